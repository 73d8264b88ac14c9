"""Replanning latency of the closed loop per paper configuration (``hltl bench replan``)."""

from __future__ import annotations

import math
import statistics
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass

from hltl.errors import HltlError
from hltl.execution.executor import ExecutorConfig
from hltl.execution.log import REPLANS
from hltl.sim.episode import Episode, EpisodeConfig, run_episode
from hltl.sim.events import EventSchedule, HumanMove
from hltl.sim.metrics import percentile
from hltl.sim.scenarios import PAPER_CONFIGS, Scenario, generate, scenario_name

Config = tuple[int, int, str | None]  # (deliveries, robots, layout)


@dataclass(frozen=True, slots=True)
class ReplanRow:
    """Replanning figures of one configuration and variant, pooled over seeds."""

    config: str
    predict: bool
    episodes: int
    successes: int
    replans: int
    takeovers: int
    median_ms: float | None
    p95_ms: float | None
    max_ms: float | None


def crossing_walk(scenario: Scenario, start: float = 0.5, speed: float = 1.0) -> EventSchedule:
    """The first person walks to where the last person stands (or across the cell if alone)."""
    humans = scenario.scene.humans
    first = humans[0]
    if len(humans) > 1:
        target = humans[-1].position
    else:
        xs = [r.base[0] for r in scenario.scene.robots]
        target = (2 * statistics.fmean(xs) - first.position[0], first.position[1], 0.0)
    return EventSchedule((HumanMove(start, first.id, target, speed),))


def _latencies(ep: Episode) -> list[float]:
    return [
        float(r.latency_ms) for r in ep.records if isinstance(r, REPLANS) and r.trigger != "initial"
    ]


def bench_replan(
    configs: Iterable[Config],
    seeds: Sequence[int],
    *,
    variants: Sequence[bool] = (True, False),
    on_row: Callable[[ReplanRow], None] | None = None,
) -> list[ReplanRow]:
    """Median and p95 replanning latency per configuration, with and without prediction.

    Args:
        configs: (deliveries, robots, layout) triples, e.g. ``(4, 4, "square")``.
        seeds: scenario and episode seeds; one episode per seed, configuration and variant.
        variants: which ``predict`` settings to run.
        on_row: called with each row as soon as it is ready.
    """
    rows: list[ReplanRow] = []
    for n_task, n_robot, layout in configs:
        scenarios = [generate(n_task, n_robot, layout, seed) for seed in seeds]
        for predict in variants:
            lat: list[float] = []
            succ = replans = takeovers = 0
            cfg = EpisodeConfig(
                max_time=60.0, executor=ExecutorConfig(predict=predict, intrusion=predict)
            )
            for seed, sc in zip(seeds, scenarios, strict=True):
                ep = run_episode(
                    sc.scene, spec=sc.spec, events=crossing_walk(sc), seed=seed, config=cfg
                )
                lat += _latencies(ep)
                succ += int(ep.success)
                replans += ep.metrics.replans
                takeovers += ep.metrics.takeovers
            row = ReplanRow(
                config=scenarios[0].name,
                predict=predict,
                episodes=len(scenarios),
                successes=succ,
                replans=replans,
                takeovers=takeovers,
                median_ms=statistics.median(lat) if lat else None,
                p95_ms=percentile(lat, 95.0) if lat else None,
                max_ms=max(lat) if lat else None,
            )
            rows.append(row)
            if on_row is not None:
                on_row(row)
    return rows


def _fmt(x: float | None) -> str:
    return "—" if x is None or math.isnan(x) else f"{x:.2f}"


def format_rows(rows: Sequence[ReplanRow]) -> str:
    """A Markdown table of the rows (for docs/benchmarks.md)."""
    lines = [
        "| config | predict | episodes | success | replans | takeovers | median ms | p95 ms |",
        "|---|---|---|---|---|---|---|---|",
    ]
    for r in rows:
        lines.append(
            f"| {r.config} | {'yes' if r.predict else 'no'} | {r.episodes} | {r.successes} | "
            f"{r.replans} | {r.takeovers} | {_fmt(r.median_ms)} | {_fmt(r.p95_ms)} |"
        )
    return "\n".join(lines)


def replan_configs(text: str) -> list[Config]:
    """The paper configurations named in ``text`` (comma-separated; empty: all of them).

    Raises:
        HltlError: a name that is not a paper configuration.
    """
    by_name = {scenario_name(*c): c for c in PAPER_CONFIGS}
    wanted = [c.strip() for c in text.split(",") if c.strip()] or list(by_name)
    unknown = [c for c in wanted if c not in by_name]
    if unknown:
        raise HltlError(
            f"--configs: unknown configuration {unknown[0]!r}; expected one of "
            + ", ".join(by_name)
        )
    return [by_name[c] for c in wanted]


def replan_section(command: str, machine: str, table: str) -> str:
    """The docs/benchmarks.md section of a replan run."""
    return (
        f"Command: `{command}`  \n"
        f"Machine: {machine}. "
        "Latency is the planner's wall-clock time per replan on the critical path (LLM time "
        "excluded); each episode has a person walking across the cell midway.\n\n" + table
    )
