"""The closed loop of the baselines: plan a script, check every step, dispatch, replan.

The loop mirrors :func:`hltl.sim.episode.run_episode`: the same
:class:`~hltl.sim.simulator.Simulator` (robots, people, events, physics), the same tick, the
same log records (so
:func:`~hltl.sim.metrics.compute_metrics` and :func:`~hltl.sim.invariants.check_invariants` score
it), the same referee for the task (the spec the offline grounder gives the instruction, updated
for every GOAL, with hltl's monitors). What differs is who decides the actions: a
:class:`Policy` returns a *script*, a sequence of synchronous steps.

Before every dispatch each action of the step goes through
:func:`~hltl.skills.semantics.check_action` against the latest perceived world (and the step
through the shared-robot/object check). A refused step is never dispatched. It is

* a **violation** when the step was already infeasible in the world the policy planned for
  (that world advanced by the script's own earlier steps): the policy's own error, logged as a
  ``violation`` record with its kind (``kinematic`` or ``conflict``), counting against success;
* **stale** when it was feasible when planned and the world changed since (a person walked
  away): the same situation in which hltl's executor replans, so it only triggers a replan.

Running actions are re-checked every tick like the executor's reactive safety does, and halted
when their precondition breaks.
"""

from __future__ import annotations

import time
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, Protocol

from hltl.execution.drivers import ActionState, Handle
from hltl.execution.log import EventLog, Record, log_monitor_step, world_to_dict
from hltl.sim.baselines.model import Violation, apply_step, check_step
from hltl.sim.events import EventSchedule
from hltl.sim.metrics import Metrics, compute_metrics
from hltl.sim.simulator import Simulator
from hltl.skills.library import Action, Transition, step_symbol
from hltl.skills.semantics import ActionSemantics, Infeasible, check_action
from hltl.spec.hierarchy import HSpec, spec_to_dict
from hltl.spec.monitor import HierarchyMonitor, MonitorState
from hltl.world.geometry import Context
from hltl.world.scene import Scene
from hltl.world.state import WorldState

if TYPE_CHECKING:
    from hltl.sim.suite import Trial, TrialResult


@dataclass(frozen=True, slots=True)
class PlanContext:
    """What a policy sees when asked for a script.

    Attributes:
        scene: the cell.
        world: the latest perceived world (objects' places, people, hands, robots down).
        spec: the task as the referee grounds it (for policies that read specs; the LLM
            baseline reads ``instructions`` instead).
        monitor, q: the referee's monitors and their state (what is done).
        done: names of the spec's formulas already done.
        instructions: everything said so far, in order.
        trigger: why the policy is asked (``initial``, ``goal``, ``precondition``…).
    """

    scene: Scene
    world: WorldState
    spec: HSpec
    monitor: HierarchyMonitor
    q: MonitorState
    done: frozenset[str]
    instructions: tuple[str, ...]
    trigger: str


@dataclass(frozen=True, slots=True)
class Script:
    """A policy's answer: synchronous steps, each a tuple of actions.

    Attributes:
        steps: the plan.
        tokens: LLM tokens this answer cost (prompt + completion).
        queries: LLM queries made for it.
        error: set when the answer could not be executed at all (e.g. a script that does not
            parse); the trial then fails.
        text: the LLM's raw answer, for the log.
    """

    steps: tuple[tuple[Action, ...], ...] = ()
    tokens: int = 0
    queries: int = 0
    error: str | None = None
    text: str = ""


class Policy(Protocol):
    """Decides actions for the baseline loop."""

    name: str
    #: replan when the context ℓ changes (a person moved), as hltl's executor does
    replan_on_context: bool

    def plan(self, ctx: PlanContext) -> Script: ...


@dataclass(frozen=True, slots=True)
class LoopConfig:
    """Parameters shared with :class:`hltl.sim.episode.EpisodeConfig` (same defaults)."""

    tick: float = 0.05
    max_time: float = 120.0
    max_wait: float = 10.0
    max_queries: int = 8


@dataclass(frozen=True, slots=True)
class BaselineEpisode:
    """The outcome of one baseline episode."""

    records: tuple[Record, ...]
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


class _Loop:
    def __init__(
        self,
        policy: Policy,
        scene: Scene,
        events: EventSchedule,
        seed: int,
        cfg: LoopConfig,
        log: EventLog,
    ) -> None:
        from hltl.grounding.offline import OfflineGrounder

        self.policy = policy
        self.scene = scene
        self.cfg = cfg
        self.log = log
        self.referee = OfflineGrounder()
        self.sim = Simulator(scene, events, seed=seed, log=log)
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
        self.done_flag = False
        self.gave_up: str | None = None
        self.accepted_at: float | None = None
        self.wait_since: float | None = None
        self.tokens = self.queries = 0
        self.kinematic = self.conflicts = self.stale = 0
        self.violation_notes: list[str] = []

    # -- task (the referee) ---------------------------------------------------------------------

    def instruct(self, text: str) -> None:
        from hltl.errors import GroundingError
        from hltl.grounding.update import carry_over

        try:
            g = self.referee.ground(text, self.scene, running=self.spec)
        except GroundingError as exc:
            self.log.emit(self.t, "grounding", text=text, error=str(exc), tokens=0)
            if self.spec is None:
                self.give_up(f"cannot ground the instruction: {exc}")
            return
        monitor = HierarchyMonitor(g.spec)
        q = monitor.initial if self.spec is None else carry_over(self.spec, self.q, g.spec)
        self.spec, self.monitor, self.q = g.spec, monitor, q
        self.instructions.append(text)
        # the referee's grounding is free; the policy's queries are logged with its replans
        self.log.emit(
            self.t, "grounding", text=text, tokens=0, spec=spec_to_dict(g.spec), referee=True
        )
        self.trigger.append("initial" if len(self.instructions) == 1 else "goal")
        if self.done_flag:
            self.done_flag = False
            self.accepted_at = None

    def world(self) -> WorldState:
        w = self.sim.observe(self.t)
        return w.with_unavailable(self.sim.unavailable(self.t)).with_time(self.t)

    # -- one tick -------------------------------------------------------------------------------

    def update(self) -> None:
        self.poll()
        for text in self.sim.take_instructions():
            self.instruct(text)
        if self.gave_up is not None:
            return
        if self.running:
            if all(r.state is not None for r in self.running):
                self.end_step()
            else:
                self.safety()
        for _ in range(8):
            if self.running or self.gave_up is not None or self.monitor is None:
                return
            if not self.decide():
                return

    def poll(self) -> None:
        for run in self.running:
            if run.state is not None:
                continue
            st = self.sim.poll(run.handle, self.t)
            if not st.terminal:
                continue
            run.state = st.state
            kind = {
                ActionState.DONE: "action_done",
                ActionState.FAILED: "action_failed",
                ActionState.HALTED: "action_halted",
            }[st.state]
            extra = {} if st.state is ActionState.DONE else {"reason": st.reason}
            self.log.emit(
                self.t,
                kind,
                handle=run.handle.id,
                action=run.action.to_dict(),
                end=round(st.t, 6),
                **extra,
            )
            if st.state is ActionState.FAILED:
                self.trigger.append("failure")

    def end_step(self) -> None:
        runs, self.running = self.running, []
        assert self.monitor is not None
        done = [r.transition for r in runs if r.state is ActionState.DONE]
        if done:
            symbol = step_symbol(done, self.world())
            self.q = log_monitor_step(self.log, self.t, self.steps, self.monitor, self.q, symbol)
            if self.monitor.accepted(self.q):
                self.accepted_at = self.t
        self.steps += 1

    def safety(self) -> None:
        world = self.world()
        for run in self.running:
            if run.state is not None:
                continue
            reason = check_action(run.action, self.scene, world)
            if reason is None:
                continue
            self.sim.halt(run.handle, self.t, reason)
            run.state = ActionState.HALTED
            self.log.emit(
                self.t,
                "action_halted",
                handle=run.handle.id,
                action=run.action.to_dict(),
                reason=reason,
                end=round(self.t, 6),
            )
            self.log.emit(
                self.t,
                "halt",
                kind="precondition",
                reason=reason,
                actions=[run.action.to_dict()],
                hazards=[],
                done=self._done(),
            )
            self.trigger.append("halt:precondition")
        if all(r.state is not None for r in self.running):
            self.end_step()

    def _done(self) -> list[str]:
        return sorted(self.monitor.done(self.q)) if self.monitor is not None else []

    # -- deciding -------------------------------------------------------------------------------

    def decide(self) -> bool:
        """One decision; True when another round may follow in the same tick."""
        assert self.monitor is not None and self.spec is not None
        if self.monitor.accepted(self.q):
            self.done_flag = True
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
            if self.gave_up is not None:
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
            self.t,
            "replan",
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
                self.t,
                "violation",
                handle=None,
                action=None if v.action is None else v.action.to_dict(),
                reason=v.reason,
                kind=v.kind,
                caught="before dispatch",
                world=world_to_dict(world),
            )

    def dispatch(self, step: Sequence[Action], world: WorldState) -> None:
        sem = ActionSemantics.of(self.scene)
        self.log.emit(
            self.t,
            "dispatch",
            step=self.steps,
            actions=[a.to_dict() for a in step],
            planned=[a.to_dict() for a in step],
            duration=0.0,
            world=world_to_dict(world),
            done=self._done(),
        )
        for a in step:
            tr = sem.transition(a, world)
            assert not isinstance(tr, Infeasible)  # check_step passed
            handle = self.sim.start(a, self.t)
            self.running.append(_Run(a, handle, tr))
            self.log.emit(
                self.t,
                "action_start",
                handle=handle.id,
                action=a.to_dict(),
                robots=list(a.robots),
                expected=0.0,
            )

    def wait(self, reason: str) -> None:
        if self.wait_since is None:
            self.wait_since = self.t
            self.log.emit(self.t, "wait", reason=reason)
        elif self.t - self.wait_since > self.cfg.max_wait:
            self.give_up(f"waited {self.cfg.max_wait:g} s without progress ({reason})")

    def give_up(self, reason: str) -> None:
        if self.gave_up is not None:
            return
        for run in self.running:
            if run.state is None:
                self.sim.halt(run.handle, self.t, f"giving up: {reason}")
                run.state = ActionState.HALTED
                self.log.emit(
                    self.t,
                    "action_halted",
                    handle=run.handle.id,
                    action=run.action.to_dict(),
                    reason=f"giving up: {reason}",
                    end=round(self.t, 6),
                )
        self.running = []
        self.gave_up = reason
        self.log.emit(self.t, "give_up", reason=reason, done=self._done())


def run_baseline_episode(
    policy: Policy,
    scene: Scene,
    instruction: str,
    *,
    events: EventSchedule | None = None,
    seed: int = 0,
    config: LoopConfig | None = None,
) -> BaselineEpisode:
    """Run one closed-loop episode of ``policy`` in the simulator (see the module docstring)."""
    cfg = LoopConfig() if config is None else config
    schedule = EventSchedule() if events is None else events
    log = EventLog()
    loop = _Loop(policy, scene, schedule, seed, cfg, log)
    log.emit(
        0.0,
        "episode_start",
        scene=scene.to_dict(),
        scene_source=scene.source,
        spec=None,
        instruction=instruction,
        events=schedule.to_list(),
        seed=seed,
        config={
            "method": policy.name,
            "tick": cfg.tick,
            "max_time": cfg.max_time,
            "max_wait": cfg.max_wait,
            "max_queries": cfg.max_queries,
        },
    )
    loop.instruct(instruction)
    loop.update()
    sim = loop.sim
    while True:
        if loop.gave_up is not None:
            break
        if loop.done_flag and not sim.pending_instructions():
            break
        if loop.t >= cfg.max_time - 1e-9:
            loop.give_up(f"time limit of {cfg.max_time:g} s reached")
            break
        nxt = sim.next_event_time()
        if loop.done_flag:
            t_next = min(nxt, cfg.max_time)
        else:
            t_next = min(loop.t + cfg.tick, nxt, cfg.max_time)
        sim.advance(t_next)
        loop.t = t_next
        loop.update()
    success = loop.gave_up is None and loop.done_flag
    time_cost = loop.accepted_at if success and loop.accepted_at is not None else loop.t
    log.emit(
        loop.t,
        "episode_end",
        success=success,
        reason=loop.gave_up or "all goals met",
        time_cost=round(time_cost, 6),
        done=loop._done(),
    )
    records = tuple(log.records)
    return BaselineEpisode(
        records=records,
        metrics=compute_metrics(records),
        goals_met=success,
        tokens=loop.tokens,
        queries=loop.queries,
        kinematic=loop.kinematic,
        conflicts=loop.conflicts,
        stale=loop.stale,
        violations=tuple(loop.violation_notes),
    )


def make_policy(method: str, **options: Any) -> Policy:
    """The policy of a closed-loop baseline (``greedy`` or ``smart-llm``)."""
    if method == "greedy":
        from hltl.sim.baselines.greedy import GreedyPolicy

        return GreedyPolicy()
    if method == "smart-llm":
        from hltl.sim.baselines.smart_llm import SmartLLMPolicy

        return SmartLLMPolicy(**options)
    from hltl.errors import HltlError

    raise HltlError(f"unknown baseline {method!r}; expected greedy or smart-llm")


def run_baseline_trial(
    method: str, trial: Trial, *, max_time: float = 120.0, **options: Any
) -> TrialResult:
    """Run a closed-loop baseline on a suite trial and score it like hltl."""
    from hltl.sim.invariants import check_invariants
    from hltl.sim.suite import TrialResult

    policy = make_policy(method, **options)
    ep = run_baseline_episode(
        policy,
        trial.scene,
        trial.instruction,
        events=trial.events,
        seed=trial.seed,
        config=LoopConfig(max_time=max_time),
    )
    m = ep.metrics
    problems = check_invariants(ep.records)
    return TrialResult(
        method=method,
        config=trial.config,
        index=trial.index,
        seed=trial.seed,
        status="ok",
        success=m.success and not problems,
        goals_met=ep.goals_met,
        reason=m.reason,
        time_cost=m.time_cost if ep.goals_met else None,
        tokens=ep.tokens,
        queries=ep.queries,
        replans=m.replans,
        violations=m.violations,
        kinematic=ep.kinematic,
        conflicts=ep.conflicts,
        stale=ep.stale,
        invariant_problems=len(problems),
        halts=m.halts,
        h_idle=m.h_idle,
        r_idle=m.r_idle,
        c_act=m.c_act,
        f_del=m.f_del,
        details=tuple([*ep.violations[:5], *problems[:5]]),
    )
