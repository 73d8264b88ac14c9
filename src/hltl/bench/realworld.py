"""The paper's real-world study (§V-B, T1–T6) in the 3D simulator: two arms, six scenarios."""

from __future__ import annotations

import dataclasses
import functools
import math
import random
import statistics
import time
from collections.abc import Callable, Sequence
from concurrent.futures import ProcessPoolExecutor
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from hltl.bench.baselines.greedy import GreedyPolicy
from hltl.bench.baselines.loop import LoopConfig, run_baseline_episode
from hltl.bench.baselines.policy import Policy
from hltl.bench.baselines.smart_llm import ChatFn, SmartLLMPolicy
from hltl.errors import BackendUnavailableError, HltlError
from hltl.execution.drivers import Handle
from hltl.execution.executor import Executor
from hltl.execution.log import (
    REPLANS,
    ActionDone,
    ActionStart,
    Contact,
    EpisodeEnd,
    EventLog,
    LogRecord,
)
from hltl.grounding.offline import OfflineGrounder
from hltl.motion.cost import MotionCostModel, motion_models
from hltl.sim.episode import Agent, AgentFactory, Cell, EpisodeConfig, run_episode
from hltl.sim.events import EventSchedule, HumanMove, Instruction, TimedEvent
from hltl.sim.invariants import check_invariants
from hltl.sim3d.driver import MujocoSimulator
from hltl.sim3d.model import compile_scene
from hltl.skills.library import Action
from hltl.world.geometry import human_in_workspace
from hltl.world.scene import Scene, Vec3, scene_from_dict

TASKS = ("T1", "T2", "T3", "T4", "T5", "T6")
# §V-B, word for word
WORDING = {
    "T1": "A single user requests a distant object (Q1).",
    "T2": "A single user requests a distant object while walking into the other robot's "
    "workspace during the handover process (Q2).",
    "T3": "A single user requests a nearby object and, after a short delay, issues a new "
    "request for another distant object (Q2).",
    "T4": "Two users located in different robots' workspaces simultaneously request nearby "
    "objects; then a new request is issued to deliver an object in the shared workspace to "
    "either user (Q3).",
    "T5": "Two users located at different robots' workspaces simultaneously request distant "
    "objects that both require inter-robot collaboration (Q4).",
    "T6": "Two users located at different robots' workspaces request nearby objects while "
    "switching their positions during the task, leading to combined challenges of dynamic "
    "adaptation and multi-task coordination (Q2, Q3, Q4).",
}
METHODS3D = ("hltl", "greedy", "smart-llm")
MAX_REPLANS = 3  # the paper: trials exceeding 3 replans are failures
ROUTINE = frozenset({"initial", "progress", "script_end"})
WALK_SPEED = 1.0

# the paper's cell (examples/scenes/two_arms.yaml): r1 Elfin-3 0.7 m, r2 UR5 0.9 m, 1.2 m apart
R1, R2 = (0.0, 0.0, 0.0), (1.2, 0.0, 0.0)
SPOT = {"r1": (-0.5, 0.6), "r2": (1.9, 0.5)}  # where a person served by one robot stands
NEAR = {"r1": (-0.4, 0.2), "r2": (1.5, -0.3)}  # an object only that robot reaches
SHARED = (0.6, -0.25)  # reached by both


@dataclass(frozen=True, slots=True)
class Task3D:
    """One trial of one scenario: the cell, what is said at the start, and the events."""

    task: str
    index: int
    seed: int
    scene: Scene
    instruction: str
    events: EventSchedule


def _jit(rng: random.Random, p: tuple[float, float], r: float) -> list[float]:
    return [round(p[0] + rng.uniform(-r, r), 3), round(p[1] + rng.uniform(-r, r), 3)]


def make_task(
    task: str, index: int, seed: int = 0, timing: str = "motion", motion: bool = False
) -> Task3D:
    """Trial ``index`` of scenario ``task`` (positions jittered, timings drawn, from the seed).

    T2's walk starts during the robot-to-robot hand-over: when that is depends on the arms'
    motions, so it is found by running hltl once on the trial without the walk (in the 3D
    simulator with ``timing``) and drawn uniformly within the hand-over.

    Raises:
        HltlError: an unknown task name.
    """
    if task not in TASKS:
        raise HltlError(f"unknown task {task[:20]!r}; expected one of {', '.join(TASKS)}")
    s = seed * 100_000 + index
    rng = random.Random(f"hltl-t16/{task}/{s}")
    two = task in ("T4", "T5", "T6")
    at = {"A": _jit(rng, SPOT["r1"], 0.08)}
    if two:
        at["B"] = _jit(rng, SPOT["r2"], 0.08)
    people = [{"id": h, "name": f"Person {h}", "position": [*p, 0.0]} for h, p in at.items()]
    objects = []

    def obj(oid: str, cat: str, at: tuple[float, float]) -> None:
        objects.append({"id": oid, "category": cat, "position": [*_jit(rng, at, 0.05), 0.05]})

    events: list[TimedEvent] = []
    if task in ("T1", "T2"):
        obj("chips", "chips", NEAR["r2"])
        text = "Give Person A the chips."
        if task == "T2":  # the start is drawn below, within the hand-over
            x, y = _jit(rng, SPOT["r2"], 0.08)
            events.append(HumanMove(0.0, "A", (x, y, 0.0), WALK_SPEED))
    elif task == "T3":
        obj("bottle", "bottle", NEAR["r1"])
        obj("chips", "chips", NEAR["r2"])
        text = "Give Person A the bottle."
        events.append(Instruction(round(rng.uniform(1.0, 2.0), 3), "Also give Person A the chips."))
    elif task == "T4":
        obj("bottle", "bottle", NEAR["r1"])
        obj("chips", "chips", NEAR["r2"])
        obj("cup", "cup", SHARED)
        text = "Give Person A the bottle and Person B the chips."
        who = rng.choice(["Person A", "Person B"])
        events.append(Instruction(round(rng.uniform(0.5, 1.5), 3), f"Also give {who} the cup."))
    elif task == "T5":
        obj("bottle", "bottle", NEAR["r2"])
        obj("chips", "chips", NEAR["r1"])
        text = "Give Person A the bottle and Person B the chips."
    else:  # T6
        obj("bottle", "bottle", NEAR["r1"])
        obj("chips", "chips", NEAR["r2"])
        text = "Give Person A the bottle and Person B the chips."
        t = round(rng.uniform(0.2, 1.0), 3)
        a, b = at["A"], at["B"]
        # each walks to where the other stood (until session 8 to 0.25 m nearer the table than
        # that, which put B 0.15 m from the bottle the Elfin-3 picks: into its path). They walk
        # round the table (MujocoSimulator) and pass each other: people do not touch in the
        # model, only robots and people do
        events.append(HumanMove(t, "A", (b[0], b[1], 0.0), WALK_SPEED))
        events.append(HumanMove(t, "B", (a[0], a[1], 0.0), WALK_SPEED))
    data: dict[str, Any] = {
        "units": "m",
        "robots": [
            {"id": "r1", "base": list(R1), "reach": 0.7, "model": "elfin3"},
            {"id": "r2", "base": list(R2), "reach": 0.9, "model": "ur5"},
        ],
        "objects": objects,
        "humans": people,
        "durations": {"pick": 0.5, "place": 0.5, "handover_r2r": 0.6, "handover_r2h": 0.5},
        # the table between the arms: a robot can put an object down (T6 needs it when both
        # hold an object for the person who just left)
        "surfaces": [{"id": "table", "center": [0.6, 0.3, 0.0], "size": [0.3, 0.3]}],
    }
    scene = scene_from_dict(data, source=f"T1-T6 {task} seed {s}")
    _check(scene, task, [e.to for e in events if isinstance(e, HumanMove)])
    if task == "T2":
        start, end = _handover_window(scene, text, timing, motion)
        walk = events[0]
        assert isinstance(walk, HumanMove)
        events = [HumanMove(round(rng.uniform(start, end), 3), "A", walk.to, WALK_SPEED)]
    schedule = EventSchedule(
        timed=tuple(sorted(events, key=lambda e: e.t)), source=f"T1-T6 {task} seed {s}"
    )
    return Task3D(task, index, s, scene, text, schedule)


def _check(scene: Scene, task: str, moves: Sequence[Vec3]) -> None:
    """The variation keeps the scenario's meaning: every place a person stands or walks to is
    served by one robot only."""
    for p in [h.position for h in scene.humans] + list(moves):
        serving = [r.id for r in scene.robots if human_in_workspace(r, p, scene.human_reach)]
        if len(serving) != 1:
            raise AssertionError(f"{task}: a person at {p} is served by {serving}")


def _handover_window(
    scene: Scene, instruction: str, timing: str, motion: bool = False
) -> tuple[float, float]:
    """When hltl's robot-to-robot hand-over runs on ``scene`` with nobody moving."""
    world = _world(scene, timing, motion)
    ep = run_episode(
        scene,
        instruction=instruction,
        grounder=OfflineGrounder(),
        simulator=world.simulator,
        agent=world.agent,
        config=EpisodeConfig(max_time=60.0),
    )
    starts = {
        r.handle: r.t
        for r in ep.records
        if isinstance(r, ActionStart) and r.action["skill"] == "handover_r2r"
    }
    for r in ep.records:
        if isinstance(r, ActionDone) and r.handle in starts:
            return float(starts[r.handle]), float(r.t)
    raise HltlError(f"{scene.source}: no robot-to-robot hand-over ran ({ep.metrics.reason})")


@dataclass(frozen=True, slots=True)
class World3D:
    """How a trial runs: the 3D simulator's factory, who decides for hltl (``None``: the default
    executor), the motion cost model hltl plans with (``None`` without ``--motion``), and every
    simulator the factory made (read after the episode: which motions the arms really ran)."""

    simulator: Callable[..., MujocoSimulator]
    agent: AgentFactory | None
    cost: MotionCostModel | None
    made: list[MujocoSimulator]


def _world(scene: Scene, timing: str, motion: bool = False) -> World3D:
    """The trial's world: with ``motion`` (the motion extra), the simulator and hltl's executor
    share the motion layer — reach and workspaces from the arms' reachability maps, each action
    as long as its motion plan, the executor's trajectories played by the arms — so hltl's plans
    are optimal for the motions, not for fixed durations; without it hltl plans with the scene's
    fixed durations while the arms still take as long as their motions."""
    base = functools.partial(MujocoSimulator, timing=timing, model=compile_scene(scene))
    made: list[MujocoSimulator] = []
    agent: AgentFactory | None = None
    cost: MotionCostModel | None = None
    if motion:
        kinematics, cost = motion_models(scene)
        base = functools.partial(base, cost=cost, kinematics=kinematics)
        model = cost

        def agent(cell: Cell, log: EventLog) -> Agent:
            return Executor(scene, None, cell, log=log, cost=model, kinematics=kinematics)

    def simulator(*args: Any, **kwargs: Any) -> MujocoSimulator:
        sim = base(*args, **kwargs)
        made.append(sim)
        return sim

    return World3D(simulator, agent, cost, made)


def unplanned_motions(records: Sequence[LogRecord], world: World3D) -> list[str]:
    """Actions that ran without a checked motion plan, each with who failed to plan it.

    Two ways: hltl's executor started an action its motion cost model has no plan for (an
    infinite expected duration, ``INFEASIBLE``; the executor refuses to, so this is a guard),
    or the 3D simulator's own motion planner found none and the arms followed unchecked IK
    waypoints (``MotionInfo.source == "ik"``), so the time is not a collision-checked motion's.
    Either makes the trial's execution time meaningless: the benchmark counts such a trial as
    failed.
    """
    sim = world.made[-1] if world.made else None
    out: list[str] = []
    for r in records:
        if not isinstance(r, ActionStart):
            continue
        act = Action.from_dict(r.action)
        what = f"{act.skill}({act.object}) by {'→'.join(act.robots)} at {r.t:.2f} s"
        if r.expected is not None and not math.isfinite(r.expected):
            out.append(f"{what}: hltl's motion model has no plan")
        info = None if sim is None else sim.motion_of(Handle(r.handle, act, r.t))
        if info is not None and info.source == "ik":
            why = f" ({info.note[:60]})" if info.note else ""
            out.append(f"{what}: the simulator has no motion plan, ran IK waypoints{why}")
    return out


@dataclass(frozen=True, slots=True)
class Result3D:
    """One method on one trial."""

    task: str
    index: int
    method: str
    goals_met: bool
    success: bool
    time_cost: float | None
    replans: int
    reason: str
    wall_s: float
    unplanned: int = 0  # actions run without a checked motion plan (unplanned_motions)
    cpu_s: float = 0.0  # CPU seconds of the worker for this trial (with T2's dry run)
    contacts: int = 0  # robot–person contacts the 3D simulator logged (reported, not failed)


def contacts(records: Sequence[LogRecord]) -> int:
    """Robot–person contacts in a 3D episode's log: each time a robot's collision geometry
    starts touching a person (``contact`` records of :class:`~hltl.sim3d.driver.MujocoSimulator`).

    The benchmark reports them beside success without failing the trial: success stays the
    paper's (the task done, no precondition broken, at most 3 replans), and a contact of the
    arms' and the body's capsule models is a different, geometric measure.
    """
    return sum(1 for r in records if isinstance(r, Contact))


def _replans(records: Sequence[LogRecord]) -> int:
    """Plan regenerations: replans for anything but the first plan or a finished step."""
    return sum(
        1 for r in records if isinstance(r, REPLANS) and not set(r.trigger.split("+")) <= ROUTINE
    )


def run_task(
    task: Task3D,
    method: str,
    *,
    timing: str = "motion",
    max_time: float = 60.0,
    chat: ChatFn | None = None,
    motion: bool = False,
) -> Result3D:
    """Run ``method`` (hltl, greedy or smart-llm) on one trial in the MuJoCo simulator;
    SMART-LLM-R asks ``chat`` (default: the configured LLM endpoint). With ``motion`` hltl
    plans with the motion layer in the same simulator the baselines run in (:func:`_world`).

    Raises:
        BackendUnavailableError: MuJoCo (extra ``sim3d``) is not installed, or SMART-LLM-R has
            no LLM configured.
    """
    world = _world(task.scene, timing, motion)
    t0 = time.perf_counter()
    if method == "hltl":
        ep = run_episode(
            task.scene,
            instruction=task.instruction,
            events=task.events,
            seed=task.seed,
            config=EpisodeConfig(max_time=max_time),
            grounder=OfflineGrounder(),
            simulator=world.simulator,
            agent=world.agent,
        )
        records, m = ep.records, ep.metrics
    elif method in ("greedy", "smart-llm"):
        policy: Policy = GreedyPolicy() if method == "greedy" else SmartLLMPolicy(chat=chat)
        bep = run_baseline_episode(
            policy,
            task.scene,
            task.instruction,
            events=task.events,
            seed=task.seed,
            config=LoopConfig(max_time=max_time),
            simulator=world.simulator,
        )
        records, m = bep.records, bep.metrics
    else:
        raise HltlError(f"unknown method {method!r}; expected one of {', '.join(METHODS3D)}")
    wall = time.perf_counter() - t0
    end = [r for r in records if isinstance(r, EpisodeEnd)][-1]
    goals = bool(end.success)
    replans = _replans(records)
    problems = check_invariants(records)
    unplanned = unplanned_motions(records, world)
    # the first reason that fails the trial, in this order
    reasons = [
        *([m.reason or "failed"] if not m.success else []),
        *([f"log check: {problems[0]}"] if problems else []),
        *([f"no motion plan: {unplanned[0]}"] if unplanned else []),
        *([f"{replans} replans (> {MAX_REPLANS})"] if replans > MAX_REPLANS else []),
    ]
    ok = not reasons
    reason = reasons[0] if reasons else ""
    return Result3D(
        task.task,
        task.index,
        method,
        goals,
        ok,
        m.time_cost if goals else None,
        replans,
        reason,
        round(wall, 3),
        len(unplanned),
        contacts=contacts(records),
    )


def _run_job(job: tuple[str, int, int, str, str, bool]) -> Result3D:
    task, index, seed, method, timing, motion = job
    cpu = time.process_time()
    res = run_task(
        make_task(task, index, seed, timing, motion), method, timing=timing, motion=motion
    )
    return dataclasses.replace(res, cpu_s=round(time.process_time() - cpu, 3))


def run_all(
    trials: int,
    *,
    tasks: Sequence[str] = TASKS,
    methods: Sequence[str] = METHODS3D,
    seed: int = 0,
    jobs: int = 2,
    timing: str = "motion",
    motion: bool = False,
    on_result: Callable[[Result3D], None] | None = None,
) -> list[Result3D]:
    """Every (task, trial, method), in ``jobs`` worker processes (1: here); in job order."""
    todo = [(t, i, seed, m, timing, motion) for t in tasks for i in range(trials) for m in methods]
    out: list[Result3D] = []
    if jobs <= 1:
        for j in todo:
            out.append(_run_job(j))
            if on_result is not None:
                on_result(out[-1])
        return out
    with ProcessPoolExecutor(max_workers=jobs) as pool:
        for res in pool.map(_run_job, todo):
            out.append(res)
            if on_result is not None:
                on_result(res)
    return out


@dataclass(frozen=True, slots=True)
class Summary3D:
    """One (task, method) cell: success rate, execution time and replans (mean, std), how many
    trials ran an action without a checked motion plan (counted as failed) and in how many a
    robot touched a person (reported, not failed)."""

    task: str
    method: str
    n: int
    success: float
    time: tuple[float, float] | None
    replans: tuple[float, float]
    unplanned: int = 0
    contacts: int = 0


def _ms(v: list[float]) -> tuple[float, float]:
    return statistics.fmean(v), (statistics.stdev(v) if len(v) > 1 else 0.0)


def summarise3d(results: Sequence[Result3D]) -> list[Summary3D]:
    out = []
    for t in dict.fromkeys(r.task for r in results):
        for m in dict.fromkeys(r.method for r in results):
            rs = [r for r in results if r.task == t and r.method == m]
            if not rs:
                continue
            times = [r.time_cost for r in rs if r.success and r.time_cost is not None]
            out.append(
                Summary3D(
                    t,
                    m,
                    len(rs),
                    100.0 * sum(r.success for r in rs) / len(rs),
                    _ms(times) if times else None,
                    _ms([float(r.replans) for r in rs]),
                    sum(1 for r in rs if r.unplanned),
                    sum(1 for r in rs if r.contacts),
                )
            )
    return out


LABELS = {"hltl": "hltl", "greedy": "Greedy-R", "smart-llm": "SMART-LLM-R"}


def format_t16(rows: Sequence[Summary3D], not_run: dict[str, str] | None = None) -> str:
    """The T1–T6 table: per scenario, each method's success, execution time and replans;
    ``not_run`` names methods that could not run, with why (SMART-LLM-R without an LLM)."""
    lines = [
        "| task | method | trials | success % | execution time s (mean ± std) "
        "| replans (mean ± std) | trials without a motion plan "
        "| trials with a robot–person contact |",
        "|---|---|---:|---:|---:|---:|---:|---:|",
    ]
    for s in rows:
        time_s = "–" if s.time is None else f"{s.time[0]:.2f} ± {s.time[1]:.2f}"
        lines.append(
            f"| {s.task} | {LABELS.get(s.method, s.method)} | {s.n} | {s.success:.0f} | "
            f"{time_s} | {s.replans[0]:.2f} ± {s.replans[1]:.2f} | {s.unplanned} | {s.contacts} |"
        )
    for m, why in (not_run or {}).items():
        lines.append(f"| T1–T6 | {LABELS.get(m, m)} | – | not run: {why} | – | – | – | – |")
    return "\n".join(lines)


def _time_of(s: Summary3D | None) -> tuple[float, float]:
    return (math.nan, 0.0) if s is None or s.time is None else s.time


def _bars(values: Sequence[tuple[float, float]], top: float = math.inf) -> list[list[float]]:
    """Error bars of (mean, std) pairs: one std each way, never below 0 nor above ``top``;
    none on a mean that is off the scale (above ``top``) or missing."""
    shown = [math.isfinite(m) and m <= top for m, _ in values]
    lo = [min(sd, m) if ok else 0.0 for (m, sd), ok in zip(values, shown, strict=True)]
    hi = [min(sd, top - m) if ok else 0.0 for (m, sd), ok in zip(values, shown, strict=True)]
    return [lo, hi]


def plot_t16(rows: Sequence[Summary3D], path: Path) -> Path:
    """Fig. (exp_result)-like: execution time and replanning count per task, one bar per method."""
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        raise BackendUnavailableError("plots need matplotlib: pip install 'hltl[viz]'") from None
    tasks = list(dict.fromkeys(s.task for s in rows))
    methods = list(dict.fromkeys(s.method for s in rows))
    cell = {(s.task, s.method): s for s in rows}
    fig, axes = plt.subplots(1, 3, figsize=(12, 3.6))
    width = 0.8 / max(1, len(methods))
    colours = {"hltl": "#4477AA", "greedy": "#EE6677", "smart-llm": "#228833"}
    for k, m in enumerate(methods):
        xs = [i + (k - (len(methods) - 1) / 2) * width for i in range(len(tasks))]
        succ = [cell[t, m].success if (t, m) in cell else 0.0 for t in tasks]
        tm = [_time_of(cell.get((t, m))) for t in tasks]
        rp = [cell[t, m].replans if (t, m) in cell else (math.nan, 0.0) for t in tasks]
        c = colours.get(m, "#777777")
        label = LABELS.get(m, m)
        axes[0].bar(xs, succ, width, color=c, label=label)
        axes[1].bar(xs, [v[0] for v in tm], width, yerr=_bars(tm), color=c, capsize=2)
        # a trial that loops replans thousands of times would flatten the rest: the axis stops
        # at twice the failure threshold and an off-scale mean is written above its bar
        top = 2 * MAX_REPLANS
        shown = [min(v[0], top) for v in rp]
        axes[2].bar(xs, shown, width, yerr=_bars(rp, top), color=c, capsize=2)
        for x, v in zip(xs, rp, strict=True):
            if v[0] > top:
                axes[2].text(x, top, f"{v[0]:.0f}", ha="center", va="bottom", fontsize=7)
    axes[2].set_ylim(0, 2 * MAX_REPLANS + 1)
    for ax, title in zip(
        axes, ("Success rate (%)", "Execution time (s)", "Avg. replanning count"), strict=True
    ):
        ax.set_xticks(range(len(tasks)), tasks)
        ax.set_title(title)
        ax.grid(axis="y", alpha=0.3)
    axes[2].axhline(MAX_REPLANS, color="k", lw=0.8, ls="--")
    fig.legend(*axes[0].get_legend_handles_labels(), loc="upper right", ncol=2, fontsize=9)
    n = max((s.n for s in rows), default=0)
    fig.suptitle(
        f"T1–T6 (paper §V-B) in the 3D simulator: Elfin-3 + UR5, {n} seeded trials each",
        fontsize=10,
        x=0.4,
    )
    fig.tight_layout()
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path
