"""The closed-loop baselines as agents of the one episode loop (``run_episode``)."""

from __future__ import annotations

import time
from collections.abc import Sequence
from dataclasses import dataclass, field

from hltl.bench.baselines.model import Violation, apply_step, check_step
from hltl.bench.baselines.policy import PlanContext, Policy, Script
from hltl.execution import log as elog
from hltl.execution.drivers import ActionState, Handle
from hltl.execution.executor import MAX_FAILURES
from hltl.execution.instructions import SpecUpdate
from hltl.execution.log import (
    ActionDone,
    ActionFailed,
    ActionHalted,
    ActionStart,
    Dispatch,
    EventLog,
    GiveUp,
    Grounding,
    Halt,
    LogRecord,
    PolicyReplan,
    Wait,
    log_monitor_step,
    world_to_dict,
)
from hltl.execution.tick import ExecStatus, TickTemplate
from hltl.grounding.offline import OfflineGrounder
from hltl.sim.episode import Cell, CellFactory, EpisodeConfig, run_episode
from hltl.sim.events import EventSchedule
from hltl.sim.metrics import Metrics
from hltl.sim.simulator import Simulator
from hltl.skills.kinematics import Kinematics
from hltl.skills.library import Action, Transition, step_symbol
from hltl.skills.semantics import ActionSemantics, Infeasible
from hltl.spec.hierarchy import HSpec, spec_to_dict
from hltl.spec.monitor import HierarchyMonitor, MonitorState, carry_over
from hltl.world.geometry import Context
from hltl.world.scene import Scene
from hltl.world.state import WorldState


@dataclass(frozen=True, slots=True)
class LoopConfig:
    """Parameters shared with :class:`hltl.sim.episode.EpisodeConfig` (same defaults).

    ``max_failures``: failed actions on one object in a row after which the baseline gives up,
    hltl's rule (:class:`~hltl.execution.executor.ExecutorConfig`); without it a deterministic
    policy retries an action the cell always fails until the time limit (T4#9 with
    ``--motion``: Greedy-R's hand-over of the cup failed 922 times).
    """

    tick: float = 0.05
    max_time: float = 120.0
    max_wait: float = 10.0
    max_queries: int = 8
    max_failures: int = MAX_FAILURES


@dataclass(frozen=True, slots=True)
class BaselineEpisode:
    """The outcome of one baseline episode."""

    records: tuple[LogRecord, ...]
    metrics: Metrics
    goals_met: bool
    tokens: int
    queries: int
    kinematic: int
    conflicts: int
    stale: int
    violations: tuple[str, ...] = field(default=())


@dataclass(slots=True)
class _Run:
    action: Action
    handle: Handle
    transition: Transition
    state: ActionState | None = None


class BaselineAgent(TickTemplate):
    """A baseline policy behind the episode loop's agent protocol (:class:`hltl.sim.episode.Agent`).

    The task is refereed as for hltl: the offline grounder's spec, updated for every GOAL, and
    hltl's monitors; the policy only decides the actions.
    """

    def __init__(
        self, policy: Policy, scene: Scene, sim: Cell, log: EventLog, cfg: LoopConfig
    ) -> None:
        self.policy = policy
        self.scene = scene
        self.cfg = cfg
        self.log = log
        self.semantics = ActionSemantics.of(scene)
        self.sim = sim
        self._obs: WorldState | None = None
        self.status = ExecStatus.RUNNING
        self.reason = ""
        self.spec: HSpec | None = None
        self.monitor: HierarchyMonitor | None = None
        self.q: MonitorState = ()
        self.instructions: list[str] = []
        self.script: Script | None = None
        self.planned_ok: list[bool] = []
        self.idx = 0
        self.plan_ctx: Context | None = None
        self.running: list[_Run] = []
        self.trigger: list[str] = ["initial"]
        self.steps = 0
        self.t = 0.0
        self.accepted_at: float | None = None
        self.wait_since: float | None = None
        self.tokens = self.queries = 0
        self.kinematic = self.conflicts = self.stale = 0
        self.violation_notes: list[str] = []
        # failed actions in a row per object (a success on it resets the count), as hltl's
        self.failures: dict[str, int] = {}
        self.last_failure = ""

    # -- task (the referee) ---------------------------------------------------------------------

    def assign(self, t: float, update: SpecUpdate) -> None:
        """The referee's spec for what was said (the loop grounds it with the offline grounder)."""
        self.t = max(self.t, t)
        text, spec = update.text, update.spec
        if spec is None:
            self.log.emit(Grounding(t=self.t, text=text, error=update.error, tokens=0))
            if self.spec is None:
                self.give_up(f"cannot ground the instruction: {update.error}")
            return
        monitor = HierarchyMonitor(spec)
        q = monitor.initial if self.spec is None else carry_over(self.spec, self.q, spec)
        self.spec, self.monitor, self.q = spec, monitor, q
        self.instructions.append(text)
        # the referee's grounding is free; the policy's queries are logged with its replans
        self.log.emit(
            Grounding(t=self.t, text=text, tokens=0, spec=spec_to_dict(spec), referee=True)
        )
        self.trigger.append("initial" if len(self.instructions) == 1 else "goal")
        if self.status is ExecStatus.DONE:
            self.status = ExecStatus.RUNNING
            self.reason = ""
            self.accepted_at = None

    @property
    def kinematics(self) -> Kinematics:
        """The reach the dispatch checks use (the reach spheres)."""
        return self.semantics.kinematics

    def world(self) -> WorldState:
        w = self.sim.observe(self.t) if self._obs is None else self._obs
        return w.with_unavailable(self.sim.unavailable(self.t)).with_time(self.t)

    def done_formulas(self) -> frozenset[str]:
        return frozenset() if self.monitor is None else self.monitor.done(self.q)

    # -- one tick -------------------------------------------------------------------------------

    # -- the tick's steps (TickTemplate.update runs them in order) -------------------------------

    def _sense(self, t: float, observation: WorldState | None) -> None:
        self.t = t
        self._obs = observation

    def _step_running(self) -> bool:
        return bool(self.running)

    def _step_ended(self) -> bool:
        return all(r.state is not None for r in self.running)

    def _act(self) -> None:
        for _ in range(8):
            if self.running or self.status is not ExecStatus.RUNNING or self.monitor is None:
                return
            if not self.decide():
                return

    def _poll(self) -> None:
        for run in self.running:
            if run.state is not None:
                continue
            st = self.sim.poll(run.handle, self.t)
            if not st.terminal:
                continue
            run.state = st.state
            handle, action, end = run.handle.id, run.action.to_dict(), round(st.t, 6)
            obj = run.action.object
            if st.state is ActionState.DONE:
                self.failures.pop(obj, None)
                self.log.emit(ActionDone(t=self.t, handle=handle, action=action, end=end))
            elif st.state is ActionState.FAILED:
                self.failures[obj] = self.failures.get(obj, 0) + 1
                self.last_failure = st.reason
                self.log.emit(
                    ActionFailed(t=self.t, handle=handle, action=action, reason=st.reason, end=end)
                )
            else:
                self.log.emit(
                    ActionHalted(t=self.t, handle=handle, action=action, reason=st.reason, end=end)
                )
            if st.state is ActionState.FAILED:
                self.trigger.append("failure")

    def _end_step(self) -> None:
        runs, self.running = self.running, []
        assert self.monitor is not None
        done = [r.transition for r in runs if r.state is ActionState.DONE]
        if done:
            symbol = step_symbol(done, self.world())
            self.q = log_monitor_step(self.log, self.t, self.steps, self.monitor, self.q, symbol)
            if self.monitor.accepted(self.q):
                self.accepted_at = self.t
        self.steps += 1
        stuck = sorted(o for o, n in self.failures.items() if n >= self.cfg.max_failures)
        if stuck:
            self.give_up(
                f"{self.failures[stuck[0]]} consecutive failed actions on {stuck[0]} "
                f"(last: {self.last_failure})"
            )

    def _check_safety(self) -> None:
        world = self.world()
        for run in self.running:
            if run.state is not None:
                continue
            reason = self.semantics.check(run.action, world)
            if reason is None:
                continue
            self.sim.halt(run.handle, self.t, reason)
            run.state = ActionState.HALTED
            self.log.emit(
                ActionHalted(
                    t=self.t,
                    handle=run.handle.id,
                    action=run.action.to_dict(),
                    reason=reason,
                    end=round(self.t, 6),
                )
            )
            self.log.emit(
                Halt(
                    t=self.t,
                    kind="precondition",
                    reason=reason,
                    actions=[run.action.to_dict()],
                    hazards=[],
                    done=self._done(),
                )
            )
            self.trigger.append("halt:precondition")
        if all(r.state is not None for r in self.running):
            self._end_step()

    def _done(self) -> list[str]:
        return sorted(self.done_formulas())

    # -- deciding -------------------------------------------------------------------------------

    def decide(self) -> bool:
        """One decision; True when another round may follow in the same tick."""
        assert self.monitor is not None and self.spec is not None
        if self.monitor.accepted(self.q):
            self.status = ExecStatus.DONE
            self.reason = "all goals met"
            self.trigger.clear()
            return False
        world = self.world()
        ctx = world.context(self.scene)
        script = self.script
        if (
            script is None
            or self.idx >= len(script.steps)
            or self.trigger
            or (self.policy.replan_on_context and ctx != self.plan_ctx)
        ):
            if self.trigger:
                why = "+".join(dict.fromkeys(self.trigger))
            elif script is not None and self.idx >= len(script.steps):
                why = "script_end"
            elif script is None:
                why = "world"
            else:
                why = "context"
            self.trigger.clear()
            if self.queries >= self.cfg.max_queries and self.policy.name != "greedy":
                self.give_up(f"{self.queries} LLM queries without finishing the task")
                return False
            self.replan(why, world, ctx)
            if self.status is ExecStatus.GAVE_UP:
                return False
            script = self.script
            assert script is not None
            if not script.steps:
                self.wait("the policy has no step to take")
                return False
        assert script is not None
        step = script.steps[self.idx]
        refused = check_step(step, self.scene, world)
        if refused:
            if self.planned_ok[self.idx]:
                self.stale += 1
                self.trigger.append("precondition")
            else:
                self.record_violations(refused, world)
                self.trigger.append("violation")
            self.script = None
            return True
        self.dispatch(step, world)
        self.idx += 1
        return False

    def replan(self, why: str, world: WorldState, ctx: Context) -> None:
        assert self.spec is not None and self.monitor is not None
        t0 = time.perf_counter()
        script = self.policy.plan(
            PlanContext(
                self.scene,
                world,
                self.spec,
                self.monitor,
                self.q,
                self.monitor.done(self.q),
                tuple(self.instructions),
                why,
            )
        )
        ms = (time.perf_counter() - t0) * 1000.0
        self.tokens += script.tokens
        self.queries += script.queries
        # which steps were feasible in the world the policy planned for
        ok: list[bool] = []
        w = world
        for step in script.steps:
            ok.append(not check_step(step, self.scene, w))
            w, _, _ = apply_step(step, self.scene, w)
        self.log.emit(
            PolicyReplan(
                t=self.t,
                source=self.policy.name,
                trigger=why,
                status="error" if script.error else ("solved" if script.steps else "empty"),
                latency_ms=round(ms, 3),
                tokens=script.tokens,
                queries=script.queries,
                steps=[[a.to_dict() for a in s] for s in script.steps],
                planned_feasible=ok,
                reason=script.error or "",
                world=world_to_dict(world),
                done=self._done(),
                **({"script": script.text} if script.text else {}),
            )
        )
        if script.error is not None:
            self.give_up(f"the script is not executable: {script.error}")
            return
        self.script, self.planned_ok, self.idx, self.plan_ctx = script, ok, 0, ctx
        if script.steps:
            self.wait_since = None

    def record_violations(self, refused: Sequence[Violation], world: WorldState) -> None:
        for v in refused:
            if v.kind == "kinematic":
                self.kinematic += 1
            else:
                self.conflicts += 1
            self.violation_notes.append(f"{v.kind}: {v.reason}")
            self.log.emit(
                elog.Violation(
                    t=self.t,
                    handle=None,
                    action=None if v.action is None else v.action.to_dict(),
                    reason=v.reason,
                    kind=v.kind,
                    caught="before dispatch",
                    world=world_to_dict(world),
                )
            )

    def dispatch(self, step: Sequence[Action], world: WorldState) -> None:
        self.log.emit(
            Dispatch(
                t=self.t,
                step=self.steps,
                actions=[a.to_dict() for a in step],
                planned=[a.to_dict() for a in step],
                duration=0.0,
                world=world_to_dict(world),
                done=self._done(),
            )
        )
        for a in step:
            tr = self.semantics.transition(a, world)
            assert not isinstance(tr, Infeasible)  # check_step passed
            handle = self.sim.start(a, self.t)
            self.running.append(_Run(a, handle, tr))
            self.log.emit(
                ActionStart(
                    t=self.t,
                    handle=handle.id,
                    action=a.to_dict(),
                    robots=list(a.robots),
                    expected=0.0,
                )
            )

    def wait(self, reason: str) -> None:
        if self.wait_since is None:
            self.wait_since = self.t
            self.log.emit(Wait(t=self.t, reason=reason))
        elif self.t - self.wait_since > self.cfg.max_wait:
            self.give_up(f"waited {self.cfg.max_wait:g} s without progress ({reason})")

    def give_up(self, reason: str) -> None:
        if self.status is ExecStatus.GAVE_UP:
            return
        for run in self.running:
            if run.state is None:
                self.sim.halt(run.handle, self.t, f"giving up: {reason}")
                run.state = ActionState.HALTED
                self.log.emit(
                    ActionHalted(
                        t=self.t,
                        handle=run.handle.id,
                        action=run.action.to_dict(),
                        reason=f"giving up: {reason}",
                        end=round(self.t, 6),
                    )
                )
        self.running = []
        self.status = ExecStatus.GAVE_UP
        self.reason = reason
        self.log.emit(GiveUp(t=self.t, reason=reason, done=self._done()))


def run_baseline_episode(
    policy: Policy,
    scene: Scene,
    instruction: str,
    *,
    events: EventSchedule | None = None,
    seed: int = 0,
    config: LoopConfig | None = None,
    simulator: CellFactory = Simulator,
) -> BaselineEpisode:
    """Run one closed-loop episode of ``policy`` in the simulator (see the module docstring);
    ``simulator`` makes the world (default the discrete one; the 3D one runs T1–T6)."""
    cfg = LoopConfig() if config is None else config
    agents: list[BaselineAgent] = []

    def make(sim: Cell, log: EventLog) -> BaselineAgent:
        agents.append(BaselineAgent(policy, scene, sim, log, cfg))
        return agents[-1]

    ep = run_episode(
        scene,
        instruction=instruction,
        events=events,
        seed=seed,
        config=EpisodeConfig(tick=cfg.tick, max_time=cfg.max_time),
        grounder=OfflineGrounder(),  # the referee
        agent=make,
        simulator=simulator,
        start_config={
            "method": policy.name,
            "tick": cfg.tick,
            "max_time": cfg.max_time,
            "max_wait": cfg.max_wait,
            "max_queries": cfg.max_queries,
        },
    )
    (agent,) = agents
    return BaselineEpisode(
        records=ep.records,
        metrics=ep.metrics,
        goals_met=agent.status is ExecStatus.DONE,
        tokens=agent.tokens,
        queries=agent.queries,
        kinematic=agent.kinematic,
        conflicts=agent.conflicts,
        stale=agent.stale,
        violations=tuple(agent.violation_notes),
    )
