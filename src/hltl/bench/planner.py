"""Benchmarks: planner speed over the scenario catalogue and a scaling sweep."""

from __future__ import annotations

import re
import statistics
import time
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass

from hltl.errors import HltlError
from hltl.planner import PlanStatus, plan
from hltl.sim.scenarios import PAPER_CONFIGS, Scenario, generate, scenario_name


@dataclass(frozen=True, slots=True)
class PlannerRow:
    """Planning figures for one configuration (medians over repeats and seeds)."""

    config: str
    robots: int
    tasks: int
    runs: int
    median_ms: float
    max_ms: float
    expanded: float
    makespan: float | None
    status: str


def bench_planner(
    scenarios: Iterable[tuple[str, Scenario]],
    *,
    repeats: int = 3,
    timeout: float = 60.0,
    algorithm: str = "astar",
    on_row: Callable[[PlannerRow], None] | None = None,
) -> list[PlannerRow]:
    """Plan each scenario ``repeats`` times (fresh monitor cache each time) and summarise.

    ``scenarios`` yields (configuration name, Scenario); several scenarios may share a name
    (different seeds) and are pooled into one row.
    """
    groups: dict[str, list[Scenario]] = {}
    for name, sc in scenarios:
        groups.setdefault(name, []).append(sc)
    rows: list[PlannerRow] = []
    for name, scs in groups.items():
        times: list[float] = []
        expanded: list[int] = []
        makespans: list[float] = []
        statuses: set[str] = set()
        for sc in scs:
            spec = sc.spec
            for _ in range(repeats):
                t0 = time.perf_counter()
                res = plan(sc.scene, spec, algorithm=algorithm, timeout=timeout)
                times.append(time.perf_counter() - t0)
                expanded.append(res.stats.expanded)
                statuses.add(res.status.value)
                if res.status is PlanStatus.SOLVED and res.makespan is not None:
                    makespans.append(res.makespan)
        row = PlannerRow(
            config=name,
            robots=scs[0].n_robot,
            tasks=scs[0].n_task,
            runs=len(times),
            median_ms=statistics.median(times) * 1000,
            max_ms=max(times) * 1000,
            expanded=statistics.median(expanded),
            makespan=statistics.median(makespans) if makespans else None,
            status="/".join(sorted(statuses)),
        )
        rows.append(row)
        if on_row is not None:
            on_row(row)
    return rows


def format_planner_table(rows: Sequence[PlannerRow]) -> str:
    """Rows as a Markdown table."""
    lines = [
        "| config | robots | tasks | runs | median ms | max ms | expanded | makespan s | status |",
        "|---|---:|---:|---:|---:|---:|---:|---:|---|",
    ]
    for r in rows:
        ms = "–" if r.makespan is None else f"{r.makespan:.2f}"
        lines.append(
            f"| {r.config} | {r.robots} | {r.tasks} | {r.runs} | {r.median_ms:.1f} | "
            f"{r.max_ms:.1f} | {r.expanded:.0f} | {ms} | {r.status} |"
        )
    return "\n".join(lines)


def planner_work(
    seeds: int, scaling: str = "", *, scaling_only: bool = False
) -> list[tuple[str, Scenario]]:
    """The (configuration, scenario) list of ``hltl bench planner``: the paper configurations
    (unless ``scaling_only``) and line layouts of the ``scaling`` sizes (``"8x8,12x12"``),
    ``seeds`` generated instances each.

    Raises:
        HltlError: ``seeds`` below 1 or a size that is not ROBOTSxTASKS.
    """
    if seeds < 1:
        raise HltlError("--repeats and --seeds must be at least 1")
    work: list[tuple[str, Scenario]] = []
    for n_task, n_robot, layout in () if scaling_only else PAPER_CONFIGS:
        name = scenario_name(n_task, n_robot, layout)
        work += [(name, generate(n_task, n_robot, layout, seed)) for seed in range(seeds)]
    for size in filter(None, (s.strip() for s in scaling.split(","))):
        m = re.fullmatch(r"(\d+)x(\d+)", size)
        if not m:
            raise HltlError(f"--scaling: {size!r} is not ROBOTSxTASKS (e.g. 8x8)")
        r, t = int(m.group(1)), int(m.group(2))
        work += [(scenario_name(t, r, "line"), generate(t, r, "line", s)) for s in range(seeds)]
    return work


def planner_section(command: str, machine: str, rows: Sequence[PlannerRow]) -> str:
    """The docs/benchmarks.md section of a planner run."""
    return (
        f"Command: `{command}`  \n"
        f"Machine: {machine}. Times include compiling monitors from the automaton cache.\n\n"
        + format_planner_table(rows)
    )
