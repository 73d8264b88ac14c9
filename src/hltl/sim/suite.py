"""The paper's simulation suite (§V-A, Table II) with dynamics, run through the closed loop.

A *trial* is one procedurally generated long-horizon task of a Table II configuration
(:func:`hltl.sim.scenarios.generate`) plus two dynamic events drawn from the trial's seed:

* **H-MOVE**: one recipient walks (1 m/s) to another free spot beside the robots while the robots
  work, so the robots serving them change;
* **GOAL**: a new delivery ("Also give Person B the can.") is said during execution; the object
  is an extra one the generator puts next to a seeded robot. Grounders take it in update mode.

Every trial is checked solvable by the exact planner before it is used: the base task from the
start, and the base task plus the new one with the mover at their destination.

:func:`run_trial` runs one method on one trial and returns a picklable :class:`TrialResult`;
:func:`run_suite` runs many in worker processes. Methods: ``hltl`` (the executor of
:mod:`hltl.execution` with the offline grounder), ``greedy`` and ``smart-llm``
(:mod:`hltl.sim.baselines`). The one-shot comparisons (flat LTLf, Fast Downward) live in
:mod:`hltl.sim.baselines.flat` and :mod:`hltl.sim.baselines.pddl`.
"""

from __future__ import annotations

import math
import random
import time
from collections.abc import Callable, Iterable, Sequence
from concurrent.futures import ProcessPoolExecutor, as_completed
from dataclasses import asdict, dataclass, field, replace
from typing import Any

from hltl.errors import HltlError
from hltl.grounding.tokens import estimate_grounding_tokens
from hltl.sim.events import EventSchedule, HumanMove, Instruction
from hltl.sim.scenarios import (
    CATEGORIES,
    OBJECT_HEIGHT,
    OBJECT_RADIUS,
    PAPER_CONFIGS,
    PERSON_OFFSET,
    Scenario,
    delivery_chain,
    generate,
    scenario_name,
)
from hltl.world.geometry import human_in_workspace
from hltl.world.scene import Scene, Vec3, scene_from_dict

METHODS = ("hltl", "greedy", "smart-llm")
ONE_SHOT = ("flat", "fd")
WALK_SPEED = 1.0  # m/s
MIN_SPACING = 0.4  # metres between two people's spots


@dataclass(frozen=True, slots=True)
class Trial:
    """One task of the suite with its dynamics.

    Attributes:
        config: the Table II configuration name, e.g. ``"2-4-line"``.
        index: trial number within the configuration.
        seed: the trial's seed (scenario, events and the episode's randomness).
        scenario: the base task; its ``scene`` already holds the extra object of the GOAL.
        goal: the GOAL delivery (object, human) and ``goal_text`` what is said.
        move: the H-MOVE (human, destination).
        events: the schedule injected into the episode (H-MOVE and GOAL).
        base_makespan: the exact planner's optimum for the base task from the start (s).
    """

    config: str
    index: int
    seed: int
    scenario: Scenario
    goal: tuple[str, str]
    goal_text: str
    move: tuple[str, Vec3]
    events: EventSchedule
    base_makespan: float

    @property
    def scene(self) -> Scene:
        return self.scenario.scene

    @property
    def instruction(self) -> str:
        return self.scenario.instruction


def trial_seed(suite_seed: int, index: int) -> int:
    """The seed of trial ``index`` (the configuration is mixed in by the generator itself)."""
    return suite_seed * 100_000 + index


def config_of(name: str) -> tuple[int, int, str]:
    """``(tasks, robots, layout)`` of a Table II configuration name.

    Raises:
        HltlError: not one of the twelve names.
    """
    for cfg in PAPER_CONFIGS:
        if scenario_name(*cfg) == name:
            return cfg
    known = ", ".join(scenario_name(*c) for c in PAPER_CONFIGS)
    raise HltlError(f"unknown configuration {name!r}; expected one of {known}")


def config_names() -> tuple[str, ...]:
    return tuple(scenario_name(*c) for c in PAPER_CONFIGS)


def make_trial(config: str, index: int, suite_seed: int = 0) -> Trial:
    """Generate trial ``index`` of ``config`` (pure function of its arguments).

    Raises:
        HltlError: no solvable variant was found in 50 draws (never seen for the paper's
            configurations; the message names the configuration and seed).
    """
    n_task, n_robot, layout = config_of(config)
    seed = trial_seed(suite_seed, index)
    rng = random.Random(f"hltl-suite/{config}/{seed}")
    for attempt in range(50):
        sc = generate(n_task, n_robot, layout, seed * 50 + attempt)
        trial = _dress(config, index, seed, sc, rng)
        if trial is not None:
            return trial
    raise HltlError(f"no solvable trial for {config} with seed {seed} after 50 draws")


def _dress(config: str, index: int, seed: int, sc: Scenario, rng: random.Random) -> Trial | None:
    """Add the GOAL object and draw the events; None when the result is not solvable."""
    from hltl.planner import PlanStatus, plan

    scene = sc.scene
    deliveries = _deliveries(sc)
    # the GOAL object: next category, next to a seeded robot, for a seeded person
    category = CATEGORIES[len(scene.objects) % len(CATEGORIES)]
    oid = category if category not in scene.object_ids else f"{category}_goal"
    human = rng.choice(scene.humans)
    holder = rng.choice(scene.robots)
    angle = rng.uniform(0.0, 2.0 * math.pi)
    radius = rng.uniform(0.5, 1.0) * OBJECT_RADIUS
    pos = [
        round(holder.base[0] + radius * math.cos(angle), 3) + 0.0,
        round(holder.base[1] + radius * math.sin(angle), 3) + 0.0,
        OBJECT_HEIGHT,
    ]
    data = scene.to_dict()
    data["objects"] = [*data["objects"], {"id": oid, "category": category, "position": pos}]
    scene = scene_from_dict(data, source=scene.source)
    goal = (oid, human.id)
    all_deliveries = [*deliveries, goal]

    # the H-MOVE: a recipient walks to a free spot that keeps every delivery possible
    recipients = sorted({u for _, u in all_deliveries})
    mover = rng.choice(recipients)
    spots = [
        p
        for p in _spots(scene)
        if all(math.dist(p[:2], h.position[:2]) >= MIN_SPACING for h in scene.humans)
    ]
    rng.shuffle(spots)
    dest: Vec3 | None = None
    moved_scene = scene
    for p in spots:
        cand = _moved(scene, mover, p)
        if all(delivery_chain(cand, o, u) is not None for o, u in all_deliveries):
            dest, moved_scene = p, cand
            break
    if dest is None or any(delivery_chain(scene, o, u) is None for o, u in all_deliveries):
        return None

    base = plan(scene, sc.spec, timeout=30.0)
    if base.status is not PlanStatus.SOLVED or base.makespan is None:
        return None
    full = _with_goal(sc, scene, goal)
    after = plan(moved_scene, full, timeout=30.0)
    if after.status is not PlanStatus.SOLVED:
        return None

    m = base.makespan
    t_move = round(rng.uniform(0.1, 0.7) * m, 3)
    t_goal = round(rng.uniform(0.2, 0.8) * m, 3)
    name = scene.human(goal[1]).name
    text = f"Also give {name} the {category}."
    events = EventSchedule(
        timed=tuple(
            sorted(
                (
                    HumanMove(t_move, mover, dest, WALK_SPEED),
                    Instruction(t_goal, text),
                ),
                key=lambda e: e.t,
            )
        ),
        source=f"suite {config} seed {seed}",
    )
    return Trial(
        config=config,
        index=index,
        seed=seed,
        scenario=replace(sc, scene=scene),
        goal=goal,
        goal_text=text,
        move=(mover, dest),
        events=events,
        base_makespan=m,
    )


def _deliveries(sc: Scenario) -> list[tuple[str, str]]:
    out = []
    spec = sc.spec
    for leaf in spec.leaves:
        from hltl.spec.printer import atoms

        for a in atoms(spec.formula(leaf)):
            if a.name == "delivered" and len(a.args) == 2:
                out.append((a.args[0], a.args[1]))
    return out


def _spots(scene: Scene) -> list[Vec3]:
    """Places a person may walk to: PERSON_OFFSET from a base in one of eight directions,
    inside exactly that robot's workspace (so nobody blocks a rendezvous)."""
    out: list[Vec3] = []
    for r in scene.robots:
        for k in range(8):
            a = k * math.pi / 4.0
            p = (
                round(r.base[0] + PERSON_OFFSET * math.cos(a), 3) + 0.0,
                round(r.base[1] + PERSON_OFFSET * math.sin(a), 3) + 0.0,
                0.0,
            )
            serving = [s for s in scene.robots if human_in_workspace(s, p, scene.human_reach)]
            if len(serving) == 1:
                out.append(p)
    return sorted(set(out))


def _moved(scene: Scene, hid: str, to: Vec3) -> Scene:
    humans = tuple(replace(h, position=to) if h.id == hid else h for h in scene.humans)
    return replace(scene, humans=humans)


def _with_goal(sc: Scenario, scene: Scene, goal: tuple[str, str]) -> Any:
    """The base spec with the GOAL delivery added as the offline grounder would merge it."""
    from hltl.grounding.offline import OfflineGrounder

    text = f"Also give {scene.human(goal[1]).name} the {scene.object(goal[0]).category}."
    return OfflineGrounder().ground(text, scene, running=sc.spec).spec


# -- results ---------------------------------------------------------------------------------------


@dataclass(frozen=True, slots=True)
class TrialResult:
    """What one method scored on one trial (plain data: it crosses process boundaries).

    ``status`` is ``ok`` (the episode ran; ``success`` says how it ended), ``not_run`` (the
    method's backend is not configured here; ``reason`` says which) or ``error`` (the method
    crashed; ``reason`` holds the exception, the trial counts as a failure).
    """

    method: str
    config: str
    index: int
    seed: int
    status: str
    success: bool = False
    goals_met: bool = False
    reason: str = ""
    time_cost: float | None = None
    tokens: int = 0
    queries: int = 0
    est_tokens: int = 0
    replans: int = 0
    violations: int = 0
    kinematic: int = 0
    conflicts: int = 0
    stale: int = 0
    invariant_problems: int = 0
    halts: int = 0
    h_idle: float | None = None
    r_idle: float | None = None
    c_act: float | None = None
    f_del: float | None = None
    wall_s: float = 0.0
    variant: str = "full"
    details: tuple[str, ...] = field(default=())
    extra: dict[str, Any] = field(default_factory=dict)

    @property
    def tokens_per_query(self) -> float | None:
        return self.tokens / self.queries if self.queries else None

    @property
    def est_tokens_per_query(self) -> float | None:
        return self.est_tokens / self.queries if self.queries else None

    def to_dict(self) -> dict[str, Any]:
        d = asdict(self)
        d["details"] = list(self.details)
        d["extra"] = dict(self.extra)
        d["tokens_per_query"] = self.tokens_per_query
        d["est_tokens_per_query"] = self.est_tokens_per_query
        return d

    @classmethod
    def from_dict(cls, data: dict[str, Any]) -> TrialResult:
        d = {k: v for k, v in data.items() if k not in ("tokens_per_query", "est_tokens_per_query")}
        d["details"] = tuple(d.get("details", ()))
        return cls(**d)


@dataclass(frozen=True, slots=True)
class Variant:
    """An executor variant for the ablation (Table III).

    Attributes:
        name: ``full``, ``no-pp`` (without predictive planning) or ``no-pmp`` (serial
            replanning computation, see docs/evaluation.md).
        predict: the executor's predictive planning and takeover.
        plan_latency: simulated seconds every critical-path planner call costs before the next
            dispatch (a predicted plan that takes over costs none).
    """

    name: str = "full"
    predict: bool = True
    plan_latency: float = 0.0


@dataclass(frozen=True, slots=True)
class TrialJob:
    """One unit of work for a worker process."""

    method: str
    config: str
    index: int
    suite_seed: int = 0
    variant: Variant = field(default_factory=Variant)
    max_time: float = 120.0


def run_trial(job: TrialJob) -> TrialResult:
    """Run one job; never raises (a crash is an ``error`` result naming the exception)."""
    t0 = time.perf_counter()
    try:
        trial = make_trial(job.config, job.index, job.suite_seed)
    except HltlError as exc:
        return TrialResult(
            job.method,
            job.config,
            job.index,
            trial_seed(job.suite_seed, job.index),
            "error",
            reason=f"trial generation failed: {exc}",
            variant=job.variant.name,
        )
    try:
        if job.method == "hltl":
            res = _run_hltl(trial, job)
        elif job.method in ("greedy", "smart-llm"):
            from hltl.sim.baselines.loop import run_baseline_trial

            res = run_baseline_trial(job.method, trial, max_time=job.max_time)
        elif job.method in ONE_SHOT:
            res = _run_one_shot(trial, job)
        else:
            raise HltlError(f"unknown method {job.method!r}; expected one of {', '.join(METHODS)}")
    except Exception as exc:  # a crash is a failed trial, reported with its cause
        res = TrialResult(
            job.method,
            job.config,
            job.index,
            trial.seed,
            "error",
            reason=f"{type(exc).__name__}: {exc}",
            variant=job.variant.name,
        )
    return replace(res, wall_s=round(time.perf_counter() - t0, 4))


def _run_hltl(trial: Trial, job: TrialJob) -> TrialResult:
    from hltl.execution.executor import ExecutorConfig
    from hltl.grounding.offline import OfflineGrounder
    from hltl.sim.episode import EpisodeConfig, run_episode
    from hltl.sim.invariants import check_invariants

    v = job.variant
    cfg = EpisodeConfig(
        max_time=job.max_time,
        executor=ExecutorConfig(predict=v.predict, plan_latency=v.plan_latency),
    )
    ep = run_episode(
        trial.scene,
        instruction=trial.instruction,
        events=trial.events,
        seed=trial.seed,
        config=cfg,
        grounder=OfflineGrounder(),
    )
    m = ep.metrics
    groundings = [r for r in ep.records if r["type"] == "grounding" and "error" not in r]
    end = [r for r in ep.records if r["type"] == "episode_end"][-1]
    problems = check_invariants(ep.records)
    est = sum(estimate_grounding_tokens(str(r["text"]), trial.scene) for r in groundings)
    return TrialResult(
        method="hltl",
        config=trial.config,
        index=trial.index,
        seed=trial.seed,
        status="ok",
        success=m.success and not problems,
        goals_met=bool(end.get("success")),
        reason=m.reason,
        time_cost=m.time_cost if end.get("success") else None,
        tokens=m.tokens,
        queries=len(groundings),
        est_tokens=est,
        replans=m.replans,
        violations=m.violations,
        invariant_problems=len(problems),
        halts=m.halts,
        h_idle=m.h_idle,
        r_idle=m.r_idle,
        c_act=m.c_act,
        f_del=m.f_del,
        variant=v.name,
        details=tuple(problems[:5]),
        extra={"takeovers": m.takeovers, "planner_calls": m.planner_calls},
    )


def full_spec(trial: Trial) -> Any:
    """The whole task of a trial: the base task and the GOAL delivery, merged as grounded."""
    return _with_goal(trial.scenario, trial.scene, trial.goal)


def _run_one_shot(trial: Trial, job: TrialJob) -> TrialResult:
    """Planning-only comparisons on the trial's whole task from the initial world."""
    spec = full_spec(trial)
    base = TrialResult(
        job.method, trial.config, trial.index, trial.seed, "ok", variant=job.variant.name
    )
    if job.method == "flat":
        from hltl.sim.baselines.flat import compare

        cmp = compare(trial.scene, spec, limit=60.0)
        return replace(base, success=cmp.flat.status == "ok", extra=cmp.to_dict())
    from hltl.planner import plan
    from hltl.sim.baselines.pddl import fd_unavailable, solve

    missing = fd_unavailable()
    if missing is not None:
        return replace(base, status="not_run", reason=missing)
    fd = solve(trial.scene, spec, timeout=60.0)
    t0 = time.perf_counter()
    ours = plan(trial.scene, spec, timeout=60.0)
    seconds = time.perf_counter() - t0
    d = trial.scene.duration_map() or {}
    work = sum(d.get(a.skill, 0.0) for s in ours.steps for a in s.actions)
    extra = {
        "fd": fd.to_dict(),
        "hltl": {
            "status": ours.status.value,
            "seconds": seconds,
            "makespan": ours.makespan,
            "work": round(work, 6),
            "actions": sum(len(s.actions) for s in ours.steps),
        },
    }
    return replace(base, success=fd.status == "solved", extra=extra)


# -- running many ----------------------------------------------------------------------------------


def jobs_for(
    configs: Sequence[str],
    trials: int,
    methods: Sequence[str],
    suite_seed: int = 0,
    variants: Sequence[Variant] = (Variant(),),
    max_time: float = 120.0,
) -> list[TrialJob]:
    """Every (method, variant, configuration, trial) job, configurations outermost."""
    return [
        TrialJob(m, c, i, suite_seed, v, max_time)
        for c in configs
        for i in range(trials)
        for m in methods
        for v in variants
    ]


def run_suite(
    jobs: Sequence[TrialJob],
    *,
    workers: int = 2,
    on_result: Callable[[TrialResult], None] | None = None,
) -> list[TrialResult]:
    """Run ``jobs`` in ``workers`` processes (1: in this process); results in job order.

    Methods whose backend is not configured are answered without starting a process.
    """
    from hltl.sim.baselines.pddl import fd_unavailable
    from hltl.sim.baselines.smart_llm import llm_unavailable

    results: list[TrialResult | None] = [None] * len(jobs)
    todo: list[int] = []
    missing = {
        "smart-llm": llm_unavailable() if any(j.method == "smart-llm" for j in jobs) else None,
        "fd": fd_unavailable(),
    }
    for k, job in enumerate(jobs):
        why = missing.get(job.method)
        if why is not None:
            res = TrialResult(
                job.method,
                job.config,
                job.index,
                trial_seed(job.suite_seed, job.index),
                "not_run",
                reason=why,
                variant=job.variant.name,
            )
            results[k] = res
            if on_result is not None:
                on_result(res)
        else:
            todo.append(k)
    if workers <= 1:
        for k in todo:
            res = run_trial(jobs[k])
            results[k] = res
            if on_result is not None:
                on_result(res)
    else:
        with ProcessPoolExecutor(max_workers=workers) as pool:
            futures = {pool.submit(run_trial, jobs[k]): k for k in todo}
            for fut in as_completed(futures):
                res = fut.result()
                results[futures[fut]] = res
                if on_result is not None:
                    on_result(res)
    return [r for r in results if r is not None]


def results_to_json(results: Iterable[TrialResult]) -> list[dict[str, Any]]:
    return [r.to_dict() for r in results]
