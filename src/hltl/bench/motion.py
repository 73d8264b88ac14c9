"""``hltl bench motion``: IK speed and accuracy, map agreement, handover and planning times."""

from __future__ import annotations

import os
import statistics
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from hltl.bench.pmp import PmpLatency
from hltl.errors import HltlError
from hltl.motion.handover import optimise_r2r
from hltl.motion.kinematics import Arm
from hltl.motion.planning import CandidatePlanner, Cell, plan_action, r2r_candidates
from hltl.motion.reach import load_or_build
from hltl.skills.library import Action
from hltl.world.scene import load_scene

FIG1 = Path("examples/scenes/fig1.yaml")


@dataclass(frozen=True, slots=True)
class IkRow:
    model: str
    solves: int
    solved_pct: float
    median_ms: float
    p90_ms: float
    max_pos_mm: float
    max_rot_rad: float


@dataclass(frozen=True, slots=True)
class MapRow:
    model: str
    resolution: float
    probes: int
    agree_pct: float
    build_s: float


@dataclass(frozen=True, slots=True)
class TimingRow:
    what: str
    runs: int
    median_ms: float  # wall clock
    cpu_ms: float  # this process's CPU time: what the code costs on an idle core
    note: str


@dataclass(frozen=True, slots=True)
class MotionBench:
    ik: tuple[IkRow, ...]
    maps: tuple[MapRow, ...]
    timings: tuple[TimingRow, ...]


def bench_ik(model: str, n: int, seed: int = 0) -> IkRow:
    """6-D IK from the nearest stored start on targets FK'd from random valid configurations."""
    import pinocchio as pin

    arm = Arm("r", model)
    rng = np.random.default_rng(seed)
    times: list[float] = []
    pos_err: list[float] = []
    rot_err: list[float] = []
    solved = 0
    while len(times) < n:
        q = rng.uniform(arm._seed_lo, arm._seed_hi)
        if not arm.pose_clear(q):
            continue
        p, r = arm.fk(q)
        target = (float(p[0]), float(p[1]), float(p[2]))
        t0 = time.perf_counter()
        res = arm.ik(target, r)
        times.append(time.perf_counter() - t0)
        if res.q is not None:
            solved += 1
            p2, r2 = arm.fk(res.q)
            pos_err.append(float(np.linalg.norm(p2 - p)))
            rot_err.append(float(np.linalg.norm(pin.log3(r2 @ r.T))))
    return IkRow(
        model,
        n,
        100.0 * solved / n,
        1000 * statistics.median(times),
        1000 * float(np.percentile(times, 90)),
        1000 * max(pos_err, default=float("nan")),
        max(rot_err, default=float("nan")),
    )


def bench_map(model: str, probes: int, resolution: float | None, seed: int = 1) -> MapRow:
    """Agreement of a map with an 8-start position IK on probes uniform in the map's box."""
    t0 = time.perf_counter()
    m = load_or_build(model, resolution)
    build = time.perf_counter() - t0
    arm = Arm("r", model)
    rng = np.random.default_rng(seed)
    lo = np.asarray(m.origin)
    hi = lo + (np.asarray(m.reachable.shape) - 1) * m.resolution
    pts = rng.uniform(lo, hi, (probes, 3))
    pred = m.contains(pts)
    truth = np.array([arm.ik(p, None, starts=8).ok for p in pts])
    return MapRow(model, m.resolution, probes, 100.0 * float((pred == truth).mean()), build)


def _median_ms(fn: Callable[[], object], runs: int) -> tuple[float, float]:
    """Median wall-clock and CPU milliseconds of ``runs`` calls."""
    wall, cpu = [], []
    for _ in range(runs):
        t0, c0 = time.perf_counter(), time.process_time()
        fn()
        wall.append(time.perf_counter() - t0)
        cpu.append(time.process_time() - c0)
    return 1000 * statistics.median(wall), 1000 * statistics.median(cpu)


def bench_planning(runs: int, candidates: Sequence[int], workers: int) -> list[TimingRow]:
    """Fig. 1 cell: handover pose optimisation, skill motion plans, serial vs parallel P.M.P."""
    cell = Cell(load_scene(FIG1))
    r1, r2 = cell.scene.robots
    sphere = cell.kinematics.rendezvous(r1, r2)
    assert sphere is not None
    people = cell.people()
    a1, a2 = cell.arm("r1"), cell.arm("r2")
    rows = []
    seeds = iter(range(10_000))
    ms = _median_ms(lambda: optimise_r2r(a1, a2, sphere, people=people, seed=next(seeds)), runs)
    rows.append(TimingRow("R2R handover pose (sample, score, IK ×4, collisions)", runs, *ms, ""))
    handover = Action("handover_r2r", ("r1", "r2"), "bottle")
    for act, note in (
        (Action("pick", ("r1",), "bottle"), ""),
        (Action("handover_r2h", ("r1",), "bottle", human="A"), ""),
        (handover, "2 candidates, best of 2"),
    ):
        ms = _median_ms(lambda a=act: plan_action(cell, a, k=2), runs)  # type: ignore[misc]
        rows.append(TimingRow(f"skill motion plan, serial: {act}", runs, *ms, note))
    for k in candidates:
        n, ms_s, ms_p = _pmp_timings(cell, handover, k, workers, runs)
        rows.append(TimingRow(f"P.M.P. {n} candidates, serial", runs, *ms_s, "best of k"))
        if ms_p is not None:
            rows.append(
                TimingRow(
                    f"P.M.P. {n} candidates, {workers} processes",
                    runs,
                    ms_p[0],
                    ms_p[1],
                    f"wall-clock speed-up ×{ms_s[0] / ms_p[0]:.2f} (CPU: parent process only)",
                )
            )
    return rows


def _pmp_timings(
    cell: Cell, handover: Action, k: int, workers: int, runs: int
) -> tuple[int, tuple[float, float], tuple[float, float] | None]:
    """(candidates, serial (wall, CPU) ms, parallel (wall, parent CPU) ms or None) of the
    candidate planner on ``handover``'s best ``k`` candidates."""
    cands = r2r_candidates(cell, handover, {}, k=k)
    serial = CandidatePlanner(cell)
    ms_s = _median_ms(lambda: serial.plan(handover, {}, cands), runs)
    if workers < 2:
        return len(cands), ms_s, None
    with CandidatePlanner(cell, workers=workers) as pool:
        pool.warm_up()
        ms_p = _median_ms(lambda: pool.plan(handover, {}, cands), runs)
    return len(cands), ms_s, ms_p


def measure_pmp(candidates: int, workers: int, runs: int, source: str) -> PmpLatency:
    """Serial against parallel candidate planning of the Fig. 1 robot-to-robot handover: the
    latencies the Table III ablation charges (docs/evaluation.md)."""
    if workers < 2:
        raise HltlError("--workers must be at least 2 (a pool against the serial planner)")
    cell = Cell(load_scene(FIG1))
    handover = Action("handover_r2r", ("r1", "r2"), "bottle")
    n, ms_s, ms_p = _pmp_timings(cell, handover, candidates, workers, runs)
    assert ms_p is not None
    return PmpLatency(
        candidates=n,
        workers=workers,
        serial_s=round(ms_s[0] / 1000.0, 4),
        parallel_s=round(ms_p[0] / 1000.0, 4),
        serial_cpu_s=round(ms_s[1] / 1000.0, 4),
        runs=runs,
        load=round(os.getloadavg()[0], 2),
        source=source,
    )


def bench_motion(
    *,
    models: Sequence[str],
    ik_solves: int,
    map_models: Sequence[str],
    probes: int,
    runs: int,
    candidates: Sequence[int],
    workers: int,
    resolution: float | None = None,
) -> MotionBench:
    ik = tuple(bench_ik(m, ik_solves) for m in models)
    maps = tuple(bench_map(m, probes, resolution) for m in map_models)
    timings = tuple(bench_planning(runs, candidates, workers))
    return MotionBench(ik, maps, timings)


def format_motion(b: MotionBench) -> str:
    """Markdown tables of a run."""
    out = [
        "| model | 6-D IK solves | solved | median | p90 | max FK(IK) error |",
        "|---|---:|---:|---:|---:|---:|",
    ]
    for r in b.ik:
        out.append(
            f"| {r.model} | {r.solves} | {r.solved_pct:.1f} % | {r.median_ms:.2f} ms | "
            f"{r.p90_ms:.2f} ms | {r.max_pos_mm:.3f} mm / {r.max_rot_rad:.4f} rad |"
        )
    out += [
        "",
        "| map | grid | probes | agrees with IK | load or build |",
        "|---|---:|---:|---:|---:|",
    ]
    for m in b.maps:
        out.append(
            f"| {m.model} | {m.resolution * 100:.1f} cm | {m.probes} | {m.agree_pct:.1f} % | "
            f"{m.build_s:.1f} s |"
        )
    out += [
        "",
        "| Fig. 1 cell | runs | median wall | median CPU | note |",
        "|---|---:|---:|---:|---|",
    ]
    for t in b.timings:
        out.append(f"| {t.what} | {t.runs} | {t.median_ms:.1f} ms | {t.cpu_ms:.1f} ms | {t.note} |")
    return "\n".join(out)
