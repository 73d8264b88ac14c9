"""Planner benchmark at cell scale: layouts, mixed specs, exact and anytime figures, start-up."""

from __future__ import annotations

import math
import os
import random
import resource
import statistics
import subprocess
import sys
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

from hltl.planner import PlanResult, PlanStatus, plan
from hltl.sim.scenarios import DURATIONS, SPACING, delivery_chain, generate
from hltl.spec.hierarchy import HSpec, spec_from_dict
from hltl.world.scene import Scene, scene_from_dict

CELL_LAYOUTS = ("line", "grid", "random")
FAMILIES = ("ordered", "either", "place-deliver")
GROUP = 4  # children per composite, as the scenario generator does


@dataclass(frozen=True, slots=True)
class Cell:
    """One benchmark instance."""

    name: str
    layout: str
    family: str
    robots: int
    tasks: int
    seed: int
    scene: Scene
    spec: HSpec


@dataclass(frozen=True, slots=True)
class CellRow:
    """Figures for one (family, layout, size) over its seeds."""

    family: str
    layout: str
    robots: int
    tasks: int
    seeds: int
    exact_median_s: float | None  # None: not run
    exact_solved: int
    first_plan_median_s: float | None
    gap_short: float | None  # median gap after the short anytime budget
    gap_long: float | None
    # median process (CPU) time of the exact runs: the machine is shared, and wall time counts
    # the other jobs' turns too
    exact_cpu_median_s: float | None = None


def _group(children: Sequence[str], join: Callable[[Sequence[str]], str]) -> dict[str, str]:
    """A root over ``children`` with at most GROUP per composite (deeper levels as needed)."""
    formulas: dict[str, str] = {}
    level = list(children)
    k = 0
    while len(level) > GROUP:
        nxt = []
        for i in range(0, len(level), GROUP):
            k += 1
            formulas[f"g{k}"] = join(level[i : i + GROUP])
            nxt.append(f"g{k}")
        level = nxt
    formulas["p0"] = join(level)
    return formulas


def _and(children: Sequence[str]) -> str:
    return " & ".join(f"F {c}" for c in children)


def delivery_spec(deliveries: Sequence[tuple[str, str]]) -> dict[str, Any]:
    leaves = {f"p{100 * (i + 1)}": f"F delivered({o}, {u})" for i, (o, u) in enumerate(deliveries)}
    return {"root": "p0", "formulas": {**_group(list(leaves), _and), **leaves}}


def random_scene(n: int, tasks: int, seed: int) -> tuple[dict[str, Any], list[tuple[str, str]]]:
    """Robots scattered at random, each near one already placed (so the handover graph is
    connected), people at the outer robots, objects near random robots; every delivery is
    checked to have a chain of robots from the object to the person."""
    rng = random.Random(f"hltl-random-cell/{n}/{tasks}/{seed}")
    bases: list[tuple[float, float]] = [(0.0, 0.0)]
    while len(bases) < n:
        ax, ay = rng.choice(bases)
        angle = rng.uniform(0, 2 * math.pi)
        d = rng.uniform(0.85, 1.05) * SPACING
        x, y = ax + d * math.cos(angle), ay + d * math.sin(angle)
        if all(math.dist((x, y), b) > 0.75 * SPACING for b in bases):
            bases.append((round(x, 3), round(y, 3)))
    robots = [
        {"id": f"r{i + 1}", "base": [x, y, 0.0], "reach": 0.65, "model": "elfin3"}
        for i, (x, y) in enumerate(bases)
    ]
    cx = sum(x for x, _ in bases) / n
    cy = sum(y for _, y in bases) / n
    outer = sorted(range(n), key=lambda i: -math.dist(bases[i], (cx, cy)))
    n_humans = max(2, min(n // 2, 8))
    humans: list[dict[str, Any]] = []
    for k in range(n_humans):
        x, y = bases[outer[k % n]]
        dx, dy = x - cx, y - cy
        norm = math.hypot(dx, dy) or 1.0
        hx, hy = x + 0.8 * dx / norm, y + 0.8 * dy / norm
        letter = "ABCDEFGHIJKLMNOPQRSTUVWXYZ"[k]
        position = [round(hx, 3), round(hy, 3), 0.0]
        humans.append({"id": letter, "name": f"Person {letter}", "position": position})
    draft: dict[str, Any] = {
        "units": "m",
        "robots": robots,
        "humans": humans,
        "durations": dict(DURATIONS),
    }
    objects: list[dict[str, Any]] = []
    deliveries: list[tuple[str, str]] = []
    for t in range(tasks):
        human = str(humans[t % len(humans)]["id"])
        oid = f"o{t + 1}"
        for _ in range(200):
            bx, by = rng.choice(bases)
            a, r = rng.uniform(0, 2 * math.pi), rng.uniform(0.1, 0.25)
            cand = {
                "id": oid,
                "category": "box",
                "position": [round(bx + r * math.cos(a), 3), round(by + r * math.sin(a), 3), 0.05],
            }
            scene = scene_from_dict({**draft, "objects": [*objects, cand]})
            if delivery_chain(scene, oid, human) is not None:
                break
        else:  # pragma: no cover - the robots are connected and every person is served
            raise RuntimeError(f"random cell {n}/{seed}: {oid} cannot reach {human}")
        objects.append(cand)
        deliveries.append((oid, human))
    return {**draft, "objects": objects}, deliveries


def delivery_cell(layout: str, n: int, seed: int) -> Cell:
    """An n-robot, n-delivery cell of ``layout``."""
    if layout == "random":
        scene_d, deliveries = random_scene(n, n, seed)
        scene = scene_from_dict(scene_d, source=f"random {n}x{n} seed {seed}")
        spec = spec_from_dict(delivery_spec(deliveries))
    else:
        sc = generate(n, n, layout, seed, ordered=False)
        scene, spec = sc.scene, sc.spec
    return Cell(f"{n}x{n}-{layout}", layout, "deliveries", n, n, seed, scene, spec)


def mixed_cell(family: str, n: int, seed: int) -> Cell:
    """A grid cell whose spec is ordered pairs, either/or pairs, or place-then-deliver pairs."""
    sc = generate(n, n, "grid", seed, ordered=False)
    scene = sc.scene
    deliveries = [
        (f.split("(")[1].split(",")[0], f.split(",")[1].strip(" )"))
        for name, f in sc.spec_dict["formulas"].items()
        if "delivered" in f
    ]
    leaves = {f"p{100 * (i + 1)}": f"F delivered({o}, {u})" for i, (o, u) in enumerate(deliveries)}
    names = list(leaves)
    pairs = [names[i : i + 2] for i in range(0, len(names), 2)]
    if family == "either":
        parts = [f"(F {p[0]} | F {p[1]})" if len(p) > 1 else f"F {p[0]}" for p in pairs]
    if family == "place-deliver":
        # the first object of each pair goes to the shelf of its nearest robot, then the second
        # is delivered: "put o1 on the shelf, then give o2 to A"
        data = scene.to_dict()
        shelves = []
        for i, p in enumerate(pairs):
            obj = scene.object(deliveries[names.index(p[0])][0])
            base = min(scene.robots, key=lambda r: math.dist(r.base, obj.position)).base
            shelves.append(
                {"id": f"s{i + 1}", "center": [base[0], base[1] + 0.35, 0.0], "size": [0.2, 0.2]}
            )
            leaves[p[0]] = f"F placed({obj.id}, s{i + 1})"
        data["surfaces"] = shelves
        scene = scene_from_dict(data, source=f"place-deliver {n}x{n} seed {seed}")
    if family != "either":  # "first A, then B" per pair
        parts = [f"F ({p[0]} & F {p[1]})" if len(p) > 1 else f"F {p[0]}" for p in pairs]
    formulas = _group_parts(parts)
    spec = spec_from_dict({"root": "p0", "formulas": {**formulas, **leaves}})
    return Cell(f"{n}x{n}-{family}", "grid", family, n, n, seed, scene, spec)


def _group_parts(parts: Sequence[str]) -> dict[str, str]:
    """Conjunction of formula parts, at most GROUP per composite."""
    if len(parts) <= GROUP:
        return {"p0": " & ".join(parts)}
    formulas: dict[str, str] = {}
    children = []
    for i in range(0, len(parts), GROUP):
        name = f"g{len(formulas) + 1}"
        formulas[name] = " & ".join(parts[i : i + GROUP])
        children.append(name)
    formulas["p0"] = " & ".join(f"F {c}" for c in children)
    return formulas


def _cpu_with_children() -> float:
    """This process's CPU time and its ended children's (exact mode's A* process, user +
    system): what a plan costs on a shared machine."""
    kids = resource.getrusage(resource.RUSAGE_CHILDREN)
    return time.process_time() + kids.ru_utime + kids.ru_stime


def _children_cpu() -> float:
    """The CPU time (user + system) of this process's ended children."""
    kids = resource.getrusage(resource.RUSAGE_CHILDREN)
    return kids.ru_utime + kids.ru_stime


def _stolen() -> float | None:
    """Seconds of CPU the host has taken from this (virtual) machine since it booted, summed
    over its CPUs (``steal`` in /proc/stat; None where there is none)."""
    try:
        with open("/proc/stat") as f:
            fields = f.readline().split()
        return int(fields[8]) / os.sysconf("SC_CLK_TCK")
    except (OSError, IndexError, ValueError):
        return None


def _exact_line(res: PlanResult, cpu: float, kids: float, stolen: float | None) -> str:
    """One exact run as the benchmark shows it: status, wall and CPU time and, where A* ran in
    a process of its own beside the first phase, that process's CPU, when the phase ended and
    how long A* was paused, and the CPU time the host took from the machine meanwhile (what
    tells a run that waited from one that worked)."""
    line = f"exact {res.status.value} {res.stats.seconds:.2f} s ({cpu:.2f} s CPU"
    if res.stats.phase is not None:
        line += f", A*'s process {kids:.2f} s; phase ended at {res.stats.phase:.2f} s"
    if res.stats.held is not None:
        line += f", A* paused {res.stats.held:.2f} s"
    if stolen is not None:
        line += f"; {stolen:.2f} s stolen by the host"
    return line + ")"


def run_cells(
    cells: Sequence[Cell],
    *,
    exact_timeout: float | None,
    anytime_budgets: tuple[float, float] | None,
    on_cell: Callable[[Cell, str], None] | None = None,
) -> list[CellRow]:
    """Exact and/or anytime figures per (family, layout, size), medians over seeds."""
    groups: dict[tuple[str, str, int, int], list[Cell]] = {}
    for c in cells:
        groups.setdefault((c.family, c.layout, c.robots, c.tasks), []).append(c)
    rows = []
    for (family, layout, robots, tasks), group in groups.items():
        exact: list[float] = []
        exact_cpu: list[float] = []
        solved = 0
        first: list[float] = []
        short: list[float] = []
        long: list[float] = []
        for c in group:
            if exact_timeout is not None:
                cpu0, kids0, stolen0 = _cpu_with_children(), _children_cpu(), _stolen()
                res = plan(c.scene, c.spec, timeout=exact_timeout)
                exact_cpu.append(_cpu_with_children() - cpu0)
                exact.append(res.stats.seconds)
                solved += res.status is PlanStatus.SOLVED
                if on_cell is not None:
                    stolen = _stolen()
                    if stolen is not None and stolen0 is not None:
                        stolen -= stolen0
                    kids = _children_cpu() - kids0
                    on_cell(c, _exact_line(res, exact_cpu[-1], kids, stolen))
            if anytime_budgets is not None:
                for budget, out in zip(anytime_budgets, (short, long), strict=True):
                    res = plan(c.scene, c.spec, anytime=True, timeout=budget)
                    if res.stats.first_plan is not None and out is short:
                        first.append(res.stats.first_plan)
                    out.append(math.inf if res.gap is None else res.gap)
                    if on_cell is not None:
                        on_cell(c, f"anytime {budget:g} s: gap {res.gap}")
        rows.append(
            CellRow(
                family,
                layout,
                robots,
                tasks,
                len(group),
                statistics.median(exact) if exact else None,
                solved,
                statistics.median(first) if first else None,
                statistics.median(short) if short else None,
                statistics.median(long) if long else None,
                statistics.median(exact_cpu) if exact_cpu else None,
            )
        )
    return rows


def format_cells(rows: Sequence[CellRow], budgets: tuple[float, float]) -> str:
    a, b = budgets
    lines = [
        f"| spec | layout | robots × tasks | seeds | exact median s | exact median CPU s | "
        f"exact solved | "
        f"first plan s | gap after {a:g} s | gap after {b:g} s |",
        "|---|---|---|---:|---:|---:|---:|---:|---:|---:|",
    ]

    def pct(v: float | None) -> str:
        if v is None:
            return "–"
        return "none" if math.isinf(v) else f"{100 * v:.1f} %"

    for r in rows:
        ex = "–" if r.exact_median_s is None else f"{r.exact_median_s:.2f}"
        cpu = "–" if r.exact_cpu_median_s is None else f"{r.exact_cpu_median_s:.2f}"
        solved = "–" if r.exact_median_s is None else f"{r.exact_solved}/{r.seeds}"
        fp = "–" if r.first_plan_median_s is None else f"{r.first_plan_median_s:.3f}"
        lines.append(
            f"| {r.family} | {r.layout} | {r.robots} × {r.tasks} | {r.seeds} | {ex} | {cpu} | "
            f"{solved} | "
            f"{fp} | {pct(r.gap_short)} | {pct(r.gap_long)} |"
        )
    return "\n".join(lines)


def startup_times(argv: Sequence[str], runs: int = 5) -> tuple[float, float]:
    """Median wall time and median CPU time (user + system) of ``hltl ARGV`` in a fresh
    interpreter: the wall time is what a user waits, the CPU time what it costs on a busy
    machine.

    Measured as an installed command starts: with Python's bytecode cache written (one untimed
    run first, and ``PYTHONDONTWRITEBYTECODE`` taken out of the environment). With that variable
    set, as on the development machine, every start compiles each imported module from source
    again (0.1 s of the Fig. 1 ``hltl plan``), which no user's installation does."""
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    command = [sys.executable, "-m", "hltl.cli.main", *argv]
    subprocess.run(command, capture_output=True, check=False, env=env)
    walls, cpus = [], []
    for _ in range(runs):
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        t0 = time.perf_counter()
        subprocess.run(command, capture_output=True, check=False, env=env)
        walls.append(time.perf_counter() - t0)
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpus.append(after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime)
    return statistics.median(walls), statistics.median(cpus)
