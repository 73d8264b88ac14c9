"""The receding-horizon executor (paper §III-D): plan, dispatch the first step, monitor, replan."""

from __future__ import annotations

import itertools
import math
import time
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Protocol

from hltl.execution.background import PlansAhead, after_running, background_forecast
from hltl.execution.belief import Belief
from hltl.execution.decision import Phase, Trigger, Triggers
from hltl.execution.drivers import (
    ActionState,
    ActionStatus,
    Basis,
    Briefed,
    Briefing,
    Expected,
    Foresight,
    Guarded,
    Handle,
    Lookahead,
    MotionSource,
    OwnClock,
    RobotDriver,
)
from hltl.execution.instructions import SpecUpdate
from hltl.execution.latency import LatencyModel, MotionTimer, planner_charge, takeover_charge
from hltl.execution.log import (
    ActionDone,
    ActionFailed,
    ActionHalted,
    ActionStart,
    Anticipate,
    Dispatch,
    EventLog,
    GiveUp,
    Halt,
    Predict,
    Replan,
    Takeover,
    Wait,
    log_monitor_step,
    world_to_dict,
)
from hltl.execution.predict import (
    ConstantVelocityPredictor,
    TrajectoryPredictor,
    WorkspacePrediction,
    predicted_world,
)
from hltl.execution.predicted import PlanKey, Predicted, PredictedPlans, plan_key, same_plan
from hltl.execution.safety import (
    Hazard,
    grasp_hazard,
    hand_speed,
    intrusion_hazard,
    precondition_hazard,
    step_conflict,
)
from hltl.execution.tick import ExecStatus as ExecStatus  # its historical home
from hltl.execution.tick import TickTemplate
from hltl.fileio import quote
from hltl.planner import PlanResult, PlanStatus, PlanStep, plan
from hltl.skills.cost import CostModel, executed_duration
from hltl.skills.kinematics import Kinematics
from hltl.skills.library import Action, Transition, step_symbol
from hltl.skills.semantics import ActionSemantics, Infeasible, apply
from hltl.spec.hierarchy import HSpec
from hltl.spec.monitor import HierarchyMonitor, MonitorState, carry_over
from hltl.spec.syntax import Atom
from hltl.world.geometry import Context, human_in_workspace
from hltl.world.scene import Scene, Vec3
from hltl.world.state import WorldState


class Planner(Protocol):
    """What the executor asks of a planner: an optimal suffix from (Proj(w_t), q_t)."""

    def __call__(
        self,
        scene: Scene,
        spec: HSpec,
        *,
        world: WorldState,
        monitor: HierarchyMonitor,
        q0: MonitorState,
    ) -> PlanResult: ...


@dataclass(frozen=True, slots=True)
class ExactPlanner:
    """The exact planner of :mod:`hltl.planner` behind the :class:`Planner` protocol."""

    algorithm: str = "astar"
    timeout: float = 60.0
    kinematics: Kinematics | None = None
    cost: CostModel | None = None

    def __call__(
        self,
        scene: Scene,
        spec: HSpec,
        *,
        world: WorldState,
        monitor: HierarchyMonitor,
        q0: MonitorState,
    ) -> PlanResult:
        return plan(
            scene,
            spec,
            world=world,
            monitor=monitor,
            q0=q0,
            algorithm=self.algorithm,
            timeout=self.timeout,
            kinematics=self.kinematics,
            cost=self.cost,
        )


# Failed actions in a row on one object before the executor gives up (see ExecutorConfig).
MAX_FAILURES = 10


@dataclass(frozen=True, slots=True)
class ExecutorConfig:
    """Knobs of the receding-horizon loop.

    Attributes:
        predict: run predictive planning and takeover (the paper's P.P.; ``--no-predict`` off).
        intrusion: halt on intrusion risk (needs a trajectory predictor).
        horizon: T_pred, seconds of forecast for ŵs and for intrusion risk.
        predict_dt: spacing of forecast samples.
        intrusion_speed: hand speed (m/s) from which a motion counts as fast, i.e. subject to
            the intrusion check; 0 checks every motion.
        max_failures: failed actions on one object in a row (no success on it in between)
            after which the executor gives up. A failed action leaves a plan (the object stays
            or drops where an arm can reach it), so this is the only give-up that is not "no
            plan": it separates a broken skill from bad luck. At 10, chance failures at the
            soak's highest rate (30 % per action, independent) end an object's task with
            probability 0.3**10 = 6e-6 (at 50 %: 1e-3), while a skill that always fails is
            given up on after 10 tries.
        max_wait: seconds the executor waits for the world to change (people to come back,
            robots to return, an intrusion risk to pass) before giving up.
        plan_latency: a constant: simulated seconds every planner call costs before the next
            dispatch (a takeover costs none); 0 models instant planning. Ignored when
            ``latency`` is given.
        latency: charge computation where it occurs, measured per call or from a fitted model
            (:mod:`hltl.execution.latency`); None uses ``plan_latency``.
        r2r_motion_s: simulated seconds of motion planning charged with a planner call for
            each robot-to-robot handover in the new plan's first step (its candidate goal sets
            planned in parallel or serially; :mod:`hltl.execution.latency`). Added to the
            constant or to the latency model's charge, under the same critical/pipelined rules.
        max_predicted: predicted plans kept for takeover.
        anticipate: anticipatory execution: when a confident forecast changes the context,
            dispatch the first step of the plan for the forecast world if every action of it is
            executable now (e.g. relay the object toward the arm that will serve the person).
        anticipate_votes: the share of forecast samples that must agree on a person's
            predicted workspace for the forecast to count as confident.
    """

    predict: bool = True
    intrusion: bool = True
    horizon: float = 1.5
    predict_dt: float = 0.1
    intrusion_speed: float = 0.0
    max_failures: int = MAX_FAILURES
    max_wait: float = 10.0
    plan_latency: float = 0.0
    latency: LatencyModel | None = None
    r2r_motion_s: float = 0.0
    max_predicted: int = 16
    anticipate: bool = False
    anticipate_votes: float = 0.6

    def __post_init__(self) -> None:
        for name in ("horizon", "predict_dt"):
            if getattr(self, name) <= 0:
                raise ValueError(f"{name} must be positive, got {getattr(self, name)!r}")
        for name in ("intrusion_speed", "max_wait", "plan_latency", "r2r_motion_s"):
            if getattr(self, name) < 0:
                raise ValueError(f"{name} must be >= 0, got {getattr(self, name)!r}")
        if self.max_failures < 1:
            raise ValueError(f"max_failures must be >= 1, got {self.max_failures!r}")
        if not 0.0 <= self.anticipate_votes <= 1.0:
            raise ValueError(f"anticipate_votes must be in [0, 1], got {self.anticipate_votes!r}")


def check_step(
    actions: Sequence[Action],
    scene: Scene,
    world: WorldState,
    semantics: ActionSemantics,
    predictor: TrajectoryPredictor | None,
    config: ExecutorConfig,
    t: float,
) -> tuple[list[_Timed], list[Hazard], list[Hazard]]:
    """A step's actions that can go now in ``world`` at time ``t`` (each timed once), those
    an intrusion forecast by ``predictor`` holds back (``None``: no intrusion check), and
    those that cannot run now: a failed precondition, or no motion from where the hands are
    (the cost model's INFEASIBLE), which must never be dispatched. The executor's check
    before each dispatch, also run by a driver that foresees it."""
    ok: list[_Timed] = []
    risky: list[Hazard] = []
    blocked: list[Hazard] = []
    hands = dict(world.hands)
    cost = semantics.cost
    for a in actions:
        h = precondition_hazard(a, scene, world, semantics=semantics)
        if h is not None:
            blocked.append(h)
            continue
        tr = semantics.transition(a, world)
        if isinstance(tr, Infeasible):
            raise LookupError(tr.reason)
        timed = _Timed(a, tr, cost.duration(a, tr, hands))
        if not math.isfinite(timed.duration):
            blocked.append(
                Hazard(a, "precondition", f"{a}: no motion plan from where the hands are")
            )
            continue
        h = None
        if (
            predictor is not None
            and hand_speed(tr, hands, timed.duration) >= config.intrusion_speed
        ):
            h = intrusion_hazard(
                a,
                scene,
                world,
                predictor,
                t,
                t + timed.duration,
                config.predict_dt,
                semantics=semantics,
            )
        if h is not None:
            risky.append(h)
        else:
            ok.append(timed)
    return ok, risky, blocked


# an infeasible world: context, robots down, spec version, people standing still
_BlockedKey = tuple[Context, frozenset[str], int, tuple[tuple[str, Vec3], ...]]


@dataclass(frozen=True, slots=True)
class _Timed:
    """An action checked for dispatch: its transition in the world as it is now and its
    duration d(s, a) from where the hands are (computed once, for the checks and the start)."""

    action: Action
    transition: Transition
    duration: float


@dataclass(slots=True)
class _Running:
    action: Action
    handle: Handle
    transition: Transition
    expected: float
    start: float
    fast: bool
    progress: float = 0.0
    status: ActionStatus | None = None
    aimed_at: Vec3 | None = None  # a pick's object position at dispatch: its grasp target


class Executor(TickTemplate):
    """Receding-horizon execution of an H-LTLf spec with reactive safety and predictive takeover.

    Args:
        scene: the cell.
        spec: the specification to execute; ``None`` to wait for a first :meth:`instruct`.
        driver: the robots.
        log: where events go (a fresh in-memory log by default).
        planner: the suffix planner (default: the exact A* planner).
        predictor: forecasts people (default: constant velocity).
        config: loop parameters.
        cost: the duration model used to time actions (default: the scene's).
        kinematics: reach and poses of the skills (default: the paper's reach spheres).
        motion: plans the motions of a new plan's first step and measures it; its seconds are
            charged with the planner call instead of ``config.r2r_motion_s`` per hand-over.
    """

    def __init__(
        self,
        scene: Scene,
        spec: HSpec | None,
        driver: RobotDriver,
        *,
        log: EventLog | None = None,
        planner: Planner | None = None,
        predictor: TrajectoryPredictor | None = None,
        config: ExecutorConfig | None = None,
        cost: CostModel | None = None,
        kinematics: Kinematics | None = None,
        motion: MotionTimer | None = None,
    ) -> None:
        self.scene = scene
        self.motion = motion
        self.driver = driver
        # a driver that takes hints is told the plan's next steps at each dispatch (checked
        # once: isinstance against a Protocol is slow)
        self._expect = driver.expect if isinstance(driver, Lookahead) else None
        # one that foresees the next step is told the spec and monitor state it follows from
        self._foresee = driver.foresee if isinstance(driver, Foresight) else None
        # one that plans ahead may have made the background plans (problem by problem)
        self._given = driver.planned if isinstance(driver, PlansAhead) else None
        self.log = EventLog() if log is None else log
        if isinstance(cost, MotionSource):
            # motions chain through where this episode's plans leave the arms, and only this
            # episode's (an executor runs one episode; its cost model may serve several)
            cost = cost.for_episode()
        self.planner: Planner = (
            ExactPlanner(kinematics=kinematics, cost=cost) if planner is None else planner
        )
        self.config = ExecutorConfig() if config is None else config
        self.predictor: TrajectoryPredictor | None = (
            ConstantVelocityPredictor() if predictor is None else predictor
        )
        self.semantics = ActionSemantics.of(scene, cost=cost, kinematics=kinematics)
        self.cost = self.semantics.cost
        self.spec: HSpec | None = None
        self.monitor: HierarchyMonitor | None = None
        self.q: MonitorState = ()
        self.belief = Belief(scene)
        self.t = 0.0
        self.status = ExecStatus.RUNNING
        self.reason = ""
        self.accepted_at: float | None = None
        self.trace: list[frozenset[Atom]] = []

        self._spec_version = 0
        self._plan: PlanResult | None = None
        self._plan_ctx: Context | None = None
        self._plan_unavailable: frozenset[str] = frozenset()
        self._blocked: _BlockedKey | None = None
        self._running: list[_Running] = []
        self._steps = 0
        self._trigger = Triggers()
        self._failures: dict[str, int] = {}
        self._last_failure = ""
        self._busy_until = 0.0
        self._step_started: float | None = None
        self.charged = 0.0  # simulated seconds of computation on the critical path so far
        self._waiting: str | None = None
        self._wait_since: float | None = None
        self._pending_tokens = 0
        self._plan_fresh = False
        self._predicted = PredictedPlans(self.config.max_predicted)
        self.predictions: dict[str, WorkspacePrediction] = {}
        if spec is not None:
            self._set_spec(spec, None)
            self._trigger.add(Trigger.INITIAL)
            self._tell_basis()
        if isinstance(driver, Guarded):  # (its robots run on while the loop plans)
            driver.guard(self._guard_check)

    # -- public ----------------------------------------------------------------------------------

    @property
    def world(self) -> WorldState:
        """The believed world w_t."""
        return self.belief.world

    @property
    def finished(self) -> bool:
        return self.status is not ExecStatus.RUNNING

    @property
    def busy(self) -> bool:
        """Whether a step is executing."""
        return bool(self._running)

    @property
    def running_actions(self) -> tuple[Action, ...]:
        return tuple(r.action for r in self._running if r.status is None)

    def brief(self, instruction: str) -> None:
        """The episode's first instruction, about to be grounded with the offline grounder
        (``run_episode`` says so before it grounds): a driver that foresees and takes
        briefings (:class:`~hltl.execution.drivers.Briefed`) is told it, with the planner and
        checks the first step will be planned and checked with, so it can ground and plan
        that step meanwhile. Nothing here depends on it."""
        if self._foresee is None or self.spec is not None or not isinstance(self.driver, Briefed):
            return
        self.driver.brief(
            Briefing(instruction, self.planner, self.config, self._check_forecaster())
        )

    def assign(self, t: float, update: SpecUpdate) -> None:
        """A grounded instruction: the running spec with it merged in (paper GOAL event).

        The monitor state of the running spec carries over by formula name
        (:func:`hltl.spec.monitor.carry_over`); the suffix is replanned at the next decision.
        A first instruction that could not be grounded ends the episode; a later one is logged
        and ignored, the running task going on.
        """
        self.t = max(self.t, t)
        charge = self._charge_grounding(update)
        if update.spec is None:
            self.log.emit(update.record(self.t, frozenset(), charge))
            if self.spec is None:
                self._give_up(f"cannot ground the instruction: {update.error}")
            return
        old = self.spec
        self._set_spec(update.spec, old)
        self.log.emit(update.record(self.t, self.done_formulas(), charge))
        self._pending_tokens += update.tokens
        self._trigger.add(Trigger.INITIAL if old is None else Trigger.GOAL)
        if old is not None:
            self._halt_undone(update.text)
        if self.status is ExecStatus.DONE:
            self.status = ExecStatus.RUNNING
            self.reason = ""
        self._tell_basis()

    # -- the tick's steps (TickTemplate.update runs them in order) -------------------------------

    def _sense(self, t: float, observation: WorldState | None) -> None:
        if t < self.t - 1e-9:
            raise ValueError(f"time went back from {self.t} to {t}")
        self.t = t
        if observation is not None:
            self._observe(observation)
        self._refresh_availability()

    def _step_running(self) -> bool:
        return bool(self._running)

    def _step_ended(self) -> bool:
        return all(r.status is not None for r in self._running)

    def _act(self) -> None:
        self._background()
        self._decide()

    # -- computation time ------------------------------------------------------------------------

    def _charge(self, seconds: float) -> None:
        """Nothing is dispatched for ``seconds`` more: the computation is on the critical path."""
        if seconds > 0:
            self._busy_until = max(self._busy_until, self.t) + seconds
            self.charged += seconds

    def _charge_grounding(self, update: SpecUpdate) -> float | None:
        """Seconds charged for grounding ``update`` (None: no latency model, nothing logged)."""
        model = self.config.latency
        if model is None:
            return None
        cost = model.grounding(update.latency_ms / 1000.0)
        self._charge(cost)
        return round(cost, 6)

    @property
    def kinematics(self) -> Kinematics:
        """The reach and poses the plans and the precondition checks use."""
        return self.semantics.kinematics

    def give_up(self, reason: str) -> None:
        """Stop the episode from outside (e.g. a time limit): halt everything, log why."""
        if self.status is not ExecStatus.GAVE_UP:
            self._give_up(reason)

    # -- belief ----------------------------------------------------------------------------------

    def _observe(self, obs: WorldState) -> None:
        if self.belief.observe(obs, self.t) and self.predictor is not None:
            self.predictor.observe(obs.t, obs.humans)

    def _refresh_availability(self) -> None:
        self.belief.set_unavailable(frozenset(self.driver.unavailable(self.t)))

    def done_formulas(self) -> frozenset[str]:
        """Names of the spec's formulas done so far."""
        return frozenset() if self.monitor is None else self.monitor.done(self.q)

    def _set_spec(self, spec: HSpec, old: HSpec | None) -> None:
        monitor = HierarchyMonitor(spec)
        if old is None or self.monitor is None:
            q = monitor.initial
        else:
            q = carry_over(old, self.q, spec)
        self.spec, self.monitor, self.q = spec, monitor, q
        self._spec_version += 1
        self._predicted.clear()
        self._plan = None
        self._blocked = None

    # -- acting ----------------------------------------------------------------------------------

    def _poll(self) -> None:
        for run in self._running:
            if run.status is not None:
                continue
            st = self.driver.poll(run.handle, self.t)
            run.progress = st.progress
            if not st.terminal:
                continue
            run.status = st
            a = run.action
            handle, action, end = run.handle.id, a.to_dict(), round(st.t, 6)
            if st.state is ActionState.DONE:
                self._apply(run.transition, st.t)
                self._failures.pop(a.object, None)
                self.log.emit(ActionDone(t=self.t, handle=handle, action=action, end=end))
                continue
            ended = ActionFailed if st.state is ActionState.FAILED else ActionHalted
            self.log.emit(ended(t=self.t, handle=handle, action=action, reason=st.reason, end=end))
            if st.state is ActionState.FAILED:
                self.belief.failed(a.object, st.t)
                self._failures[a.object] = self._failures.get(a.object, 0) + 1
                self._last_failure = st.reason
                self._trigger.add(Trigger.FAILURE)
            else:
                self.belief.touched(a.object, st.t)
                self._trigger.add(Trigger.HALT)

    def _apply(self, tr: Transition, t: float) -> None:
        self.belief.completed(tr, t)

    def _transition(self, action: Action, world: WorldState) -> Transition:
        tr = self.semantics.transition(action, world)
        if isinstance(tr, Infeasible):
            raise LookupError(tr.reason)
        return tr

    def _end_step(self) -> None:
        runs, self._running = self._running, []
        done = [r for r in runs if r.status is not None and r.status.state is ActionState.DONE]
        assert self.monitor is not None
        if done or not runs:
            symbol = step_symbol([r.transition for r in done], self.world)
            self.q = log_monitor_step(self.log, self.t, self._steps, self.monitor, self.q, symbol)
            self.trace.append(symbol)
            if self.monitor.accepted(self.q):
                self.accepted_at = self.t
        self._steps += 1
        if not self._trigger:
            self._trigger.add(Trigger.PROGRESS)
        stuck = sorted(o for o, n in self._failures.items() if n >= self.config.max_failures)
        if stuck:
            self._give_up(
                f"{self._failures[stuck[0]]} consecutive failed actions on {stuck[0]} "
                f"(last: {self._last_failure})"
            )

    def _check_safety(self) -> None:
        hazards: list[Hazard] = []
        for run in self._running:
            if run.status is not None:
                continue
            h = precondition_hazard(run.action, self.scene, self.world, semantics=self.semantics)
            if h is None and run.aimed_at is not None:
                h = grasp_hazard(run.action, run.aimed_at, self.world)
            if h is None and self._intrusion_on() and run.fast:
                until = self.t + max(0.0, 1.0 - run.progress) * run.expected
                assert self.predictor is not None
                h = intrusion_hazard(
                    run.action,
                    self.scene,
                    self.world,
                    self.predictor,
                    self.t,
                    until,
                    self.config.predict_dt,
                    semantics=self.semantics,
                )
            if h is not None:
                hazards.append(h)
        if not hazards:
            return
        # Halt only the endangered actions: the others' preconditions still hold, so they run
        # on and the step ends (and the suffix is replanned) when they finish.
        first = hazards[0]
        endangered = {h.action: h for h in hazards}
        live = [r for r in self._running if r.status is None and r.action in endangered]
        halted = [run for run in live if self._halt_run(run, endangered[run.action].reason)]
        self.log.emit(
            Halt(
                t=self.t,
                kind=first.kind,
                reason=first.reason,
                actions=[r.action.to_dict() for r in halted],
                hazards=[
                    {"action": h.action.to_dict(), "kind": h.kind, "reason": h.reason}
                    for h in hazards
                ],
                done=sorted(self.done_formulas()),
            )
        )
        self._trigger.add(Trigger(f"halt:{first.kind}"))
        if all(r.status is not None for r in self._running):
            self._end_step()

    def _guard_check(self, observation: WorldState) -> list[tuple[Handle, str]]:
        """The running actions whose precondition breaks (or whose grasp target moved) in the
        belief with ``observation`` merged in, for a driver's guard
        (:class:`~hltl.execution.drivers.Guarded`), called on another thread while the loop is
        busy: the reactive part of :meth:`_check_safety`, which changes nothing and reads
        the loop's state only by reference (the running actions, the belief); the intrusion
        forecast needs the forecaster, the loop's own. The belief, not the observation alone:
        what the executor's own actions did is in it before perception shows it."""
        world = self.belief.merged(observation)
        out = []
        for run in tuple(self._running):
            if run.status is not None:
                continue
            h = precondition_hazard(run.action, self.scene, world, semantics=self.semantics)
            if h is None and run.aimed_at is not None:
                h = grasp_hazard(run.action, run.aimed_at, world)
            if h is not None:
                out.append((run.handle, h.reason))
        return out

    def _halt_undone(self, text: str) -> None:
        """After an update, halt the fewest running actions whose completion would leave no plan.

        "Give B the bottle instead" said while r1 hands the bottle to A: once A holds it no robot
        can take it back, so finishing the hand-over makes the new spec unsatisfiable. A halted
        action changes no object (its effect happens only at its end: a halted pick leaves the
        object resting, a halted hand-over leaves it in the giver's hand), so the world stays
        consistent and the suffix is replanned from it. When finishing every running action
        still leaves a plan, or halting does not help either, nothing is halted.
        """
        live = [r for r in self._running if r.status is None]
        if not live or self._plan_exists_after(live, ()):
            return
        for k in range(1, len(live) + 1):
            for halted in itertools.combinations(live, k):
                if self._plan_exists_after(live, halted):
                    why = f"the update {quote(text)} undoes it: finishing it would leave no plan"
                    self._halt_runs(list(halted), why)
                    return

    def _plan_exists_after(self, live: Sequence[_Running], halted: Sequence[_Running]) -> bool:
        """Whether the spec has a plan once the running step ends with ``halted`` halted."""
        assert self.spec is not None and self.monitor is not None
        w = self.world
        finishing = [r for r in live if r not in halted]
        for run in finishing:
            w = apply(w, run.transition)
        done = [
            r.transition
            for r in self._running
            if (r.status is None and r not in halted)
            or (r.status is not None and r.status.state is ActionState.DONE)
        ]
        q = self.monitor.step(self.q, step_symbol(done, w)) if done else self.q
        if self.monitor.accepted(q):
            return True
        result = self.planner(self.scene, self.spec, world=w, monitor=self.monitor, q0=q)
        return result.status is PlanStatus.SOLVED

    def _halt_run(self, run: _Running, reason: str) -> bool:
        """Halt ``run``; False when it ended on its own before the halt reached its robots (a
        driver on its own clock, :class:`~hltl.execution.drivers.OwnClock`): it is then left
        to the next poll, which takes its end in as reported (a hand-over done is done)."""
        self.driver.halt(run.handle, self.t, reason)
        if isinstance(self.driver, OwnClock) and self.driver.ended_first(run.handle) is not None:
            return False
        run.status = ActionStatus(ActionState.HALTED, run.progress, self.t, reason)
        self.belief.touched(run.action.object, self.t)
        self.log.emit(
            ActionHalted(t=self.t, handle=run.handle.id, action=run.action.to_dict(), reason=reason)
        )
        return True

    def _halt_runs(self, runs: Sequence[_Running], reason: str) -> None:
        halted = [run for run in runs if self._halt_run(run, reason)]
        self.log.emit(
            Halt(
                t=self.t,
                kind="update",
                reason=reason,
                actions=[r.action.to_dict() for r in halted],
                hazards=[],
                done=sorted(self.done_formulas()),
            )
        )
        self._trigger.add(Trigger.HALT_UPDATE)

    def _intrusion_on(self) -> bool:
        return self.config.intrusion and self.predictor is not None

    def _dispatch(
        self, timed: Sequence[_Timed], step: PlanStep, following: Sequence[PlanStep] = ()
    ) -> None:
        """Start ``timed`` (checked by :meth:`_check_step`) as the plan's first step; a driver
        that takes hints is told ``following``, the plan's steps after it."""
        actions = [t.action for t in timed]
        conflict = step_conflict(actions)
        if conflict is not None:  # the planner never does this; refuse rather than collide
            self._give_up(f"the plan's step is not executable: {conflict}")
            return
        world = self.world
        self.log.emit(
            Dispatch(
                t=self.t,
                step=self._steps,
                actions=[a.to_dict() for a in actions],
                planned=[a.to_dict() for a in step.actions],
                duration=round(step.duration, 6),
                world=world_to_dict(world),
                done=sorted(self.done_formulas()),
            )
        )
        hands = dict(world.hands)
        for a, tr, expected in ((t.action, t.transition, t.duration) for t in timed):
            motion = (
                self.cost.motion_plan(a, tr, hands) if isinstance(self.cost, MotionSource) else None
            )
            if motion is None:
                handle = self.driver.start(a, self.t)
            else:  # the driver executes the trajectories the motion layer planned and timed,
                # from where the arms really are (which may differ from the hands' points)
                handle = self.driver.start(a, self.t, motion=motion)
                expected = executed_duration(self.cost, a, tr, motion.duration)
            fast = hand_speed(tr, hands, expected) >= self.config.intrusion_speed
            self.belief.touched(a.object, self.t)
            aimed = self.world.object_status(a.object).position if a.skill == "pick" else None
            self._running.append(_Running(a, handle, tr, expected, self.t, fast, aimed_at=aimed))
            self.log.emit(
                ActionStart(
                    t=self.t,
                    handle=handle.id,
                    action=a.to_dict(),
                    robots=list(a.robots),
                    expected=round(expected, 6),
                )
            )
        if self._expect is not None and self._running:
            self._hint(step, following)
        if self._foresee is not None and self._running:
            self._tell_basis()
        self._plan = None  # the suffix is replanned when this step ends
        self._step_started = self.t
        self._waiting = None
        self._wait_since = None
        if not self._running:
            self._end_step()

    def _hint(self, step: PlanStep, following: Sequence[PlanStep]) -> None:
        """Tell the driver what the plan dispatches next if nothing happens (a guess it may run
        on with; :class:`~hltl.execution.drivers.Lookahead`): nothing here depends on it."""
        assert self._expect is not None
        at = self.t + step.duration
        expected = []
        for s in following:
            expected.append(Expected(tuple(s.actions), round(at, 6)))
            at += s.duration
        self._expect(expected)

    def _tell_basis(self) -> None:
        """Tell a driver that foresees the next step what the executor will decide it from
        (:class:`~hltl.execution.drivers.Foresight`): nothing here depends on it."""
        if self._foresee is None or self.spec is None or self.monitor is None:
            return
        after = self._after_running()
        q = self.q if after is None else after[1]
        self._foresee(
            Basis(
                self.spec,
                self._spec_version,
                q,
                self.planner,
                self.config,
                self._check_forecaster(),
            )
        )

    def _check_forecaster(self) -> object:
        """The forecaster of people a driver needs to run the executor's intrusion check (None
        when that check is off): sent in a briefing and a basis."""
        return self.predictor if self._intrusion_on() else None

    # -- deciding --------------------------------------------------------------------------------

    def _phase(self) -> Phase:
        if self._running or self.status is not ExecStatus.RUNNING or self.monitor is None:
            return Phase.IDLE
        if self.monitor.accepted(self.q):
            return Phase.ACCEPTED
        if self.t < self._busy_until - 1e-12:
            return Phase.BUSY
        if self.belief.reobserving:
            return Phase.REOBSERVING
        ctx = self.semantics.context(self.world)
        down = self.world.unavailable
        if self._plan is None or self._trigger:
            unchanged = self._blocked == self._blocked_key(ctx)
            if self._plan is None and not self._trigger and unchanged:
                return Phase.BLOCKED
            return Phase.REPLAN
        if ctx != self._plan_ctx or down != self._plan_unavailable:
            return Phase.STALE_PLAN
        return Phase.DISPATCH

    def _decide(self) -> None:
        self._plan_fresh = False
        for _ in range(16):  # empty steps and re-plans settle in a few rounds
            phase = self._phase()
            if phase in (Phase.IDLE, Phase.BUSY):
                return
            if phase is Phase.ACCEPTED:
                self.status = ExecStatus.DONE
                self.reason = "all goals met"
                self._trigger.take()
                return
            if phase is Phase.REOBSERVING:
                # only an observation taken in after the failure says where the object ended
                # up (one from the same tick was read before the failure was known)
                self._wait("re-observing after a failed action")
                return
            if phase is Phase.BLOCKED:
                if not self._anticipate():
                    self._wait_or_give_up()
                return
            if self._anticipate():
                return
            ctx = self.semantics.context(self.world)
            if phase is Phase.STALE_PLAN:
                self._trigger.add(Trigger.CONTEXT if ctx != self._plan_ctx else Trigger.ROBOTS)
                continue
            if phase is Phase.REPLAN:
                if self._plan is None and not self._trigger:
                    self._trigger.add(Trigger.WORLD)
                if not self._replan(self._trigger.take(), ctx):
                    return
                if self.t < self._busy_until - 1e-12:
                    return
            if not self._dispatch_first():
                return

    def _dispatch_first(self) -> bool:
        """Dispatch what can go of the plan's first step; True when the decision goes on."""
        assert self._plan is not None
        if not self._plan.steps:
            self._give_up("the planner returned an empty plan for an unfinished task")
            return False
        step = self._plan.steps[0]
        ok, risky, blocked = self._check_step(step)
        if blocked:
            # the plan is stale (e.g. a predicted plan made for where a person was forecast to
            # stand, whose hand-over has no motion from where they are): plan afresh
            if self._plan_fresh:
                self._give_up(f"the planner's first step is not executable: {blocked[0].reason}")
                return False
            self._plan = None
            self._trigger.add(Trigger.PRECONDITION)
            return True
        if risky and not ok:
            self._wait(f"intrusion risk to {risky[0].action}")
            self._wait_or_give_up(check_only=True)
            return False
        self._dispatch(ok, step, self._plan.steps[1:])
        return not self._running

    def _check_step(self, step: PlanStep) -> tuple[list[_Timed], list[Hazard], list[Hazard]]:
        """The step's actions that can go now (each timed once), those an intrusion forecast
        holds back, and those that cannot run now (:func:`check_step`)."""
        predictor = self.predictor if self._intrusion_on() else None
        return check_step(
            step.actions, self.scene, self.world, self.semantics, predictor, self.config, self.t
        )

    def _wait(self, reason: str) -> None:
        if self._wait_since is None:
            self._wait_since = self.t
        if reason != self._waiting:
            self._waiting = reason
            self.log.emit(Wait(t=self.t, reason=reason))

    def _wait_or_give_up(self, check_only: bool = False) -> None:
        if not check_only:
            self._wait(self._waiting or "waiting for the world to change")
        if self._wait_since is not None and self.t - self._wait_since > self.config.max_wait:
            self._give_up(f"waited {self.config.max_wait:g} s without progress ({self._waiting})")

    def _key(self, ctx: Context, world: WorldState, q: MonitorState) -> PlanKey:
        return plan_key(ctx, world, q, self._spec_version)

    def _replan(self, trigger: str, ctx: Context) -> bool:
        """Plan the suffix from (Proj(w_t), q_t); a matching predicted plan takes over instead."""
        assert self.spec is not None and self.monitor is not None
        t0 = time.perf_counter()
        key = self._key(ctx, self.world, self.q)
        # a predicted plan is used once: were it kept, a later return to the same discrete
        # start (a place, then a pick of the same object) would take it over again
        pred = self._predicted.pop(key) if self.config.predict else None
        done = sorted(self.done_formulas())
        if pred is not None and self._plan is not None and same_plan(pred.result, self._plan):
            # a takeover must change the plan in hand: this one already is the predicted plan,
            # so it stays, now for the new context; nothing is taken over or replanned
            self._adopt(self._plan, ctx)
            return True
        if pred is not None and pred.result.solved and self._check_step(pred.result.steps[0])[2]:
            # made for where people were forecast to stand, its first step cannot start from
            # where they are (with motion-timed costs: no motion to the person's real place)
            pred = None
        if pred is not None and pred.result.solved:
            ms = (time.perf_counter() - t0) * 1000.0
            model = self.config.latency
            motion_s = self._motion_charge(pred.result)
            charge = (
                0.0
                if model is None
                else takeover_charge(
                    model,
                    pred.result.stats.expanded,
                    pred.wall_s,
                    self.t - pred.at,
                    motion_s,
                )
            )
            self.log.emit(
                Takeover(
                    t=self.t,
                    trigger=trigger,
                    context=ctx.describe(),
                    predicted_at=round(pred.at, 6),
                    makespan=pred.result.makespan,
                )
            )
            self.log.emit(
                Replan(
                    t=self.t,
                    source="predicted",
                    status=pred.result.status.value,
                    latency_ms=round(ms, 3),
                    expanded=0,
                    makespan=pred.result.makespan,
                    steps=[s.to_dict() for s in pred.result.steps],
                    world=world_to_dict(self.world),
                    charged_s=round(charge, 6),
                    charge="background",
                    trigger=trigger,
                    tokens=self._pending_tokens,
                    context=ctx.describe(),
                    done=done,
                    motion_s=self._motion_logged(motion_s),
                )
            )
            self._pending_tokens = 0
            self._charge(charge)
            self._adopt(pred.result, ctx)
            return True
        result = self.planner(
            self.scene, self.spec, world=self.world, monitor=self.monitor, q0=self.q
        )
        ms = (time.perf_counter() - t0) * 1000.0
        motion_s = self._motion_charge(result)
        charge, basis = self._planner_charge(trigger, result.stats.expanded, ms / 1000.0, motion_s)
        self.log.emit(
            Replan(
                t=self.t,
                source="planner",
                status=result.status.value,
                latency_ms=round(ms, 3),
                expanded=result.stats.expanded,
                makespan=result.makespan,
                steps=[s.to_dict() for s in result.steps],
                reason=result.reason,
                world=world_to_dict(self.world),
                charged_s=round(charge, 6),
                charge=basis,
                trigger=trigger,
                tokens=self._pending_tokens,
                context=ctx.describe(),
                done=done,
                motion_s=self._motion_logged(motion_s),
            )
        )
        self._pending_tokens = 0
        self._charge(charge)
        if result.status is PlanStatus.SOLVED:
            self._adopt(result, ctx)
            self._plan_fresh = True
            return True
        self._plan = None
        if result.status is PlanStatus.TIMEOUT:
            self._give_up(f"planner timeout: {result.reason}")
            return False
        # infeasible now; people may come back, robots may return: wait for a change
        self._blocked = self._blocked_key(ctx)
        self._wait(f"no plan in the current world: {result.reason}")
        self._wait_or_give_up(check_only=True)
        return False

    def _blocked_key(self, ctx: Context) -> _BlockedKey:
        """What an infeasible world is remembered by: a new plan is sought when it changes.
        With durations from motion plans a hand-over to a person depends on where they stand,
        not only on whose workspace holds them: then people who stand still count too (to
        the centimetre; a walking person counts once they stop, not at every step)."""
        still: tuple[tuple[str, Vec3], ...] = ()
        if not self.cost.fixed:
            still = tuple(
                (h, (round(p[0], 2), round(p[1], 2), round(p[2], 2)))
                for h, p in self.world.humans
                if self.predictor is None or not self.predictor.moving(h)
            )
        return (ctx, self.world.unavailable, self._spec_version, still)

    def _planner_charge(
        self, trigger: str, expanded: int, wall_s: float, motion_s: float = 0.0
    ) -> tuple[float, str]:
        model = self.config.latency
        if model is None:
            return self.config.plan_latency + motion_s, "constant"
        since = None if self._step_started is None else self.t - self._step_started
        return planner_charge(model, trigger, expanded, wall_s, since, motion_s)

    def _motion_charge(self, result: PlanResult) -> float:
        """Motion planning a plan needs before dispatch: its first step's, planned now and
        measured by the motion timer when there is one; else ExecutorConfig.r2r_motion_s per
        robot-to-robot handover in it."""
        if not result.steps:
            return 0.0
        if self.motion is not None:
            return self.motion(self.world, result.steps[0].actions)
        if not self.config.r2r_motion_s:
            return 0.0
        n = sum(a.skill == "handover_r2r" for a in result.steps[0].actions)
        return n * self.config.r2r_motion_s

    def _motion_logged(self, motion_s: float) -> float | None:
        """The measured motion planning a replan record carries (None without a timer)."""
        return None if self.motion is None else round(motion_s, 6)

    def _adopt(self, result: PlanResult, ctx: Context) -> None:
        self._plan = result
        self._plan_ctx = ctx
        self._plan_unavailable = self.world.unavailable
        self._blocked = None
        self._waiting = None
        self._wait_since = None

    # -- predictive planning ---------------------------------------------------------------------

    def _background(self) -> None:
        """Plan for the forecast world while the current step executes (computed now, stored).

        The plan is computed synchronously at the tick where the forecast changes the context,
        and kept until the observed context matches (takeover) or the start state moves on. In
        simulated time this is exactly a background thread that finishes before it is needed,
        without making episodes depend on thread scheduling; its wall-clock cost is logged as
        ``predict`` latency, off the critical path.
        """
        if self.spec is None or self.status is not ExecStatus.RUNNING:
            return
        fc = background_forecast(
            self.scene,
            self.semantics,
            self.predictor,
            self.config,
            self.world,
            self.t,
            self.monitor,
            self.q,
            self._spec_version,
            self._after_running,
        )
        if fc is None:
            return
        assert self.monitor is not None  # (else no forecast)
        self.predictions = fc.predictions
        for p in fc.problems:
            if p.key in self._predicted:
                continue
            given = None if self._given is None else self._given(self._spec_version, p)
            if given is None:
                t0 = time.perf_counter()
                result = self.planner(
                    self.scene, self.spec, world=p.world, monitor=self.monitor, q0=p.q
                )
                wall_s = time.perf_counter() - t0
            else:  # made by the driver, for exactly this problem
                result, wall_s = given.result, given.wall_s
            assert fc.context is not None
            self._predicted.put(p.key, Predicted(result, self.t, fc.context, wall_s))
            self.log.emit(
                Predict(
                    t=self.t,
                    basis=p.basis,
                    humans={h: w.to_dict() for h, w in fc.moving.items()},
                    context=fc.context.describe(),
                    status=result.status.value,
                    latency_ms=round(wall_s * 1000.0, 3),
                    expanded=result.stats.expanded,
                    makespan=result.makespan,
                )
            )

    def _anticipate(self) -> bool:
        """Anticipatory execution: dispatch the forecast world's first step if it can go now.

        Only when every moving person's forecast is confident, the forecast changes the
        context, a plan for the forecast world from the present state exists (computed in the
        background), and every action of its first step is executable in the world as it is
        now (precondition and intrusion checks): the part of the predicted plan valid in both
        contexts. True when the decision is taken (dispatched, or waiting for the background
        plan's computation to finish).
        """
        if not (self.config.anticipate and self.config.predict) or self.monitor is None:
            return False
        moving = {h: p for h, p in self.predictions.items() if p.moving}
        if not moving or any(
            p.votes < self.config.anticipate_votes * p.samples for p in moving.values()
        ):
            return False
        wp = predicted_world(self.world, moving)
        ctx_pred = self.semantics.context(wp)
        if ctx_pred == self.semantics.context(self.world):
            return False
        if self._plan is not None and self._survives_forecast(self._plan, moving):
            return False  # the plan in hand finishes its hand-overs before people leave
        pred = self._predicted.get(self._key(ctx_pred, wp, self.q))
        if pred is None or not pred.result.solved or not pred.result.steps:
            return False
        step = pred.result.steps[0]
        ok, risky, blocked = self._check_step(step)
        if risky or blocked:
            return False
        model = self.config.latency
        if model is not None:
            remaining = takeover_charge(
                model,
                pred.result.stats.expanded,
                pred.wall_s,
                self.t - pred.at,
                self._motion_charge(pred.result),
            )
            if remaining > 0:  # the background computation is still running
                self._charge(remaining)
                return True
        current = self._plan.steps[0].actions if self._plan and self._plan.steps else None
        self.log.emit(
            Anticipate(
                t=self.t,
                context=ctx_pred.describe(),
                predicted_at=round(pred.at, 6),
                actions=[a.to_dict() for a in step.actions],
                differs=current is None or tuple(current) != tuple(step.actions),
                humans={h: p.to_dict() for h, p in moving.items()},
            )
        )
        self._dispatch(ok, step, pred.result.steps[1:])
        return True

    def _survives_forecast(self, plan: PlanResult, moving: Mapping[str, object]) -> bool:
        """Whether, by the forecast, every hand-over of ``plan`` to a moving person still
        finds them in the giver's workspace when it ends (steps taken back to back from now)."""
        assert self.predictor is not None
        t = self.t
        for step in plan.steps:
            t += step.duration
            for a in step.actions:
                h = a.human
                if a.skill != "handover_r2h" or h is None or h not in moving:
                    continue
                (p,) = self.predictor.predict(h, [t])
                robot = self.scene.robot(a.robots[0])
                if not human_in_workspace(robot, p, self.scene.human_reach):
                    return False
        return True

    def _after_running(self) -> tuple[WorldState, MonitorState] | None:
        """The expected world and monitor state once the running step completes as planned."""
        if not self._running or self.monitor is None:
            return None
        runs = [
            (r.transition, r.status is None)
            for r in self._running
            if r.status is None or r.status.state is ActionState.DONE
        ]
        return after_running(self.monitor, self.q, self.world, runs)

    # -- ending ----------------------------------------------------------------------------------

    def _give_up(self, reason: str) -> None:
        for run in self._running:
            if run.status is None:
                self.driver.halt(run.handle, self.t, f"giving up: {reason}")
                run.status = ActionStatus(ActionState.HALTED, run.progress, self.t, reason)
                self.log.emit(
                    ActionHalted(
                        t=self.t,
                        handle=run.handle.id,
                        action=run.action.to_dict(),
                        reason=f"giving up: {reason}",
                    )
                )
        self._running = []
        self.status = ExecStatus.GAVE_UP
        self.reason = reason
        self.log.emit(GiveUp(t=self.t, reason=reason, done=sorted(self.done_formulas())))
