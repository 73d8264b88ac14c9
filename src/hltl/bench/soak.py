"""Fault soak: closed-loop episodes with random mixes of the five event types, checked for harm."""

from __future__ import annotations

import ctypes
import random
import signal
import threading
import time
from collections import Counter
from collections.abc import Callable, Iterable, Iterator, Sequence
from contextlib import contextmanager
from dataclasses import dataclass
from types import FrameType
from typing import Any

from hltl.bench.sweep import SweepExecutor
from hltl.execution.log import ActionDone, EpisodeStart, Grounding, LogRecord
from hltl.sim.episode import EpisodeConfig, run_episode
from hltl.sim.events import (
    EventSchedule,
    HumanMove,
    Instruction,
    ObjectMove,
    RobotDown,
    SkillFailure,
    TimedEvent,
)
from hltl.sim.scenarios import Scenario, catalogue

EVENT_TYPES = ("human_move", "object_move", "instruction", "robot_down", "skill_failure")
HANG_SECONDS = 60  # wall-clock budget of one episode (simulated time is bounded by max_time)


@dataclass(frozen=True, slots=True)
class SoakJob:
    """One episode: a scenario of the catalogue and the seed of its event mix."""

    scenario: str
    seed: int
    max_time: float = 60.0


@dataclass(frozen=True, slots=True)
class SoakResult:
    """What one episode did."""

    scenario: str
    seed: int
    events: tuple[str, ...]
    outcome: str  # "success", "failure", "crash" or "hang"
    reason: str
    violations: int
    lost: int
    duplicated: int
    wall_s: float


def random_events(scenario: Scenario, seed: int) -> EventSchedule:
    """A seeded mix of one to four events of the five types, in the scenario's cell."""
    rng = random.Random(f"hltl-soak-{scenario.name}-{seed}")
    scene = scenario.scene
    xs = [r.base[0] for r in scene.robots]
    ys = [r.base[1] for r in scene.robots]
    lo_x, hi_x, lo_y, hi_y = min(xs) - 0.8, max(xs) + 0.8, min(ys) - 0.8, max(ys) + 0.8
    timed: list[TimedEvent] = []
    failures: list[SkillFailure] = []
    for kind in rng.sample(EVENT_TYPES, rng.randint(1, 4)):
        t = round(rng.uniform(0.0, 2.5), 2)
        if kind == "human_move" and scene.humans:
            h = rng.choice(scene.humans)
            to = (round(rng.uniform(lo_x, hi_x), 2), round(rng.uniform(lo_y, hi_y), 2), 0.0)
            timed.append(HumanMove(t, h.id, to, round(rng.uniform(0.5, 1.5), 2)))
        elif kind == "object_move" and scene.objects:
            o = rng.choice(scene.objects)
            dx, dy = rng.uniform(-0.3, 0.3), rng.uniform(-0.3, 0.3)
            to = (round(o.position[0] + dx, 2), round(o.position[1] + dy, 2), o.position[2])
            timed.append(ObjectMove(t, o.id, to))
        elif kind == "instruction" and scene.objects and scene.humans:
            o, h = rng.choice(scene.objects), rng.choice(scene.humans)
            verb = rng.choice(["also give", "after that give", "cancel", "give"])
            text = (
                f"cancel the {o.category}"
                if verb == "cancel"
                else f"{verb} {h.name} the {o.category}" + (" instead" if verb == "give" else "")
            )
            timed.append(Instruction(t, text))
        elif kind == "robot_down":
            r = rng.choice(scene.robots)
            timed.append(RobotDown(t, r.id, round(rng.uniform(0.3, 2.0), 2)))
        elif kind == "skill_failure":
            skill = rng.choice(["pick", "handover_r2r", "handover_r2h"])
            drop = skill == "handover_r2h" and rng.random() < 0.5
            p = round(rng.uniform(0.05, 0.3), 2)
            failures.append(SkillFailure(skill, p, "drop" if drop else "stay"))
    timed.sort(key=lambda e: e.t)
    return EventSchedule(tuple(timed), tuple(failures), source=f"soak {scenario.name}#{seed}")


class _Hang(Exception):
    pass


@contextmanager
def alarm(seconds: int, exc: Callable[[], BaseException]) -> Iterator[None]:
    """Raise ``exc()`` in the main thread after ``seconds`` of wall clock (SIGALRM)."""

    def stop(signum: int, frame: FrameType | None) -> None:
        raise exc()

    old = signal.signal(signal.SIGALRM, stop)
    signal.alarm(seconds)
    try:
        yield
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, old)


@contextmanager
def _hang_guard(seconds: int) -> Iterator[None]:
    """Raise :class:`_Hang` in this thread after ``seconds`` of wall clock.

    The main thread (this process, local workers) uses SIGALRM. Signals reach only the main
    thread, so elsewhere (a Dask worker runs jobs in a thread) a timer raises the exception
    in this thread asynchronously; it lands at the episode's next Python bytecode.
    """
    if threading.current_thread() is threading.main_thread():
        with alarm(seconds, _Hang):
            yield
        return
    tid = threading.get_ident()
    lock = threading.Lock()
    running = [True]

    def fire() -> None:
        with lock:
            if running[0]:
                ctypes.pythonapi.PyThreadState_SetAsyncExc(
                    ctypes.c_ulong(tid), ctypes.py_object(_Hang)
                )

    timer = threading.Timer(seconds, fire)
    timer.daemon = True
    timer.start()
    try:
        yield
    finally:
        with lock:
            running[0] = False
        timer.cancel()


def run_soak_episode(job: SoakJob) -> SoakResult:
    """One soak episode; never raises (a crash or a hang is a result)."""
    scenario = next(s for s in catalogue() if s.name == job.scenario)
    events = random_events(scenario, job.seed)
    kinds = tuple(e.type for e in (*events.timed, *events.failures))
    t0 = time.perf_counter()

    try:
        with _hang_guard(HANG_SECONDS):
            ep = run_episode(
                scenario.scene,
                spec=scenario.spec,
                events=events,
                seed=job.seed,
                config=EpisodeConfig(max_time=job.max_time),
            )
    except _Hang:
        return _result(job, kinds, "hang", f"over {HANG_SECONDS} s wall clock", t0)
    except Exception as exc:  # a crash is what the soak looks for: report it, go on
        return _result(job, kinds, "crash", f"{type(exc).__name__}: {exc}", t0)
    records = list(ep.records)
    lost, duplicated = _deliveries(records, ep.success)
    m = ep.metrics
    return SoakResult(
        job.scenario,
        job.seed,
        kinds,
        "success" if ep.success else "failure",
        "" if ep.success else _reason_class(m.reason),
        m.violations,
        lost,
        duplicated,
        round(time.perf_counter() - t0, 4),
    )


def _result(
    job: SoakJob, kinds: tuple[str, ...], outcome: str, reason: str, t0: float
) -> SoakResult:
    return SoakResult(
        job.scenario, job.seed, kinds, outcome, reason, 0, 0, 0, time.perf_counter() - t0
    )


def _deliveries(records: Sequence[LogRecord], success: bool) -> tuple[int, int]:
    """(lost, duplicated): spec deliveries missing from a success; objects handed over twice."""
    handed = Counter(
        r.action["object"]
        for r in records
        if isinstance(r, ActionDone) and r.action["skill"] == "handover_r2h"
    )
    duplicated = sum(n - 1 for n in handed.values() if n > 1)
    lost = 0
    if success:
        spec = next(
            (r.spec for r in reversed(records) if isinstance(r, Grounding) and r.spec is not None),
            next(r for r in records if isinstance(r, EpisodeStart)).spec,
        )
        wanted = {
            text.split("(")[1].split(",")[0].strip()
            for text in (spec or {}).get("formulas", {}).values()
            if text.startswith("F delivered(")
        }
        # an "or" spec needs only one of its deliveries: count lost only for "and"-only specs
        if "|" not in " ".join((spec or {}).get("formulas", {}).values()):
            lost = len(wanted - set(handed))
    return lost, duplicated


def _reason_class(reason: str) -> str:
    """A failure reason without the episode's particulars (ids, times), for counting."""
    head = reason.split(":")[0]
    return head[:80]


def soak_jobs(episodes: int, seed: int = 0, max_time: float = 60.0) -> list[SoakJob]:
    """``episodes`` jobs cycling over the catalogue, with seeds derived from ``seed``."""
    names = [s.name for s in catalogue()]
    return [SoakJob(names[k % len(names)], seed * 1_000_003 + k, max_time) for k in range(episodes)]


def run_soak(
    jobs: Sequence[SoakJob],
    workers: int = 1,
    on_result: Callable[[SoakResult], None] | None = None,
    executor: SweepExecutor | None = None,
) -> list[SoakResult]:
    """Run ``jobs`` on ``executor`` (default: ``workers`` local processes; 1: here), in order."""
    return (executor or SweepExecutor()).run(run_soak_episode, jobs, workers, on_result)


def summary(results: Iterable[SoakResult]) -> dict[str, Any]:
    """Counts: outcomes, failures by reason, violations, lost and duplicated deliveries."""
    rs = list(results)
    return {
        "episodes": len(rs),
        "success": sum(r.outcome == "success" for r in rs),
        "failure": sum(r.outcome == "failure" for r in rs),
        "crash": sum(r.outcome == "crash" for r in rs),
        "hang": sum(r.outcome == "hang" for r in rs),
        "violations": sum(r.violations for r in rs),
        "lost": sum(r.lost for r in rs),
        "duplicated": sum(r.duplicated for r in rs),
        "failures_by_reason": dict(
            Counter(r.reason for r in rs if r.outcome != "success").most_common()
        ),
        "mean_wall_s": round(sum(r.wall_s for r in rs) / max(1, len(rs)), 4),
    }
