"""``hltl bench``: measure speed; write the figures into docs/benchmarks.md with the command."""

from __future__ import annotations

import argparse
import platform
import re
import shlex
import sys
from pathlib import Path
from typing import Any

from hltl.errors import HltlError


def register(sub: Any) -> None:
    p: argparse.ArgumentParser = sub.add_parser(
        "bench", help="benchmarks", description="Measure hltl's speed and record it."
    )
    bsub = p.add_subparsers(dest="bench", metavar="BENCH", required=True)
    pl = bsub.add_parser("planner", help="planning time over the scenario catalogue")
    pl.add_argument("--repeats", type=int, default=3, help="runs per scenario")
    pl.add_argument("--seeds", type=int, default=5, help="generated instances per configuration")
    pl.add_argument(
        "--scaling",
        default="",
        help="comma-separated RxT sizes for a scaling sweep on line layouts, e.g. 8x8,12x12",
    )
    pl.add_argument("--timeout", type=float, default=60.0, help="seconds per plan")
    pl.add_argument("--algorithm", choices=("astar", "dijkstra"), default="astar")
    pl.add_argument("--write", type=Path, help="update this Markdown file's planner section")
    pl.set_defaults(func=run_planner)

    rp = bsub.add_parser("replan", help="closed-loop replanning latency per paper configuration")
    rp.add_argument("--seeds", type=int, default=5, help="episodes per configuration and variant")
    rp.add_argument(
        "--configs",
        default="",
        help="comma-separated names such as 4-4-line,4-4-square (default: all paper configs)",
    )
    rp.add_argument("--write", type=Path, help="update this Markdown file's replan section")
    rp.set_defaults(func=run_replan)


def run_planner(args: argparse.Namespace) -> int:
    from rich.console import Console
    from rich.table import Table

    from hltl.sim.bench import PlannerRow, bench_planner, format_planner_table
    from hltl.sim.scenarios import PAPER_CONFIGS, generate, scenario_name

    if args.repeats < 1 or args.seeds < 1:
        raise HltlError("--repeats and --seeds must be at least 1")
    work: list[tuple[str, Any]] = []
    for n_task, n_robot, layout in PAPER_CONFIGS:
        name = scenario_name(n_task, n_robot, layout)
        for seed in range(args.seeds):
            work.append((name, generate(n_task, n_robot, layout, seed)))
    for size in filter(None, (s.strip() for s in args.scaling.split(","))):
        m = re.fullmatch(r"(\d+)x(\d+)", size)
        if not m:
            raise HltlError(f"--scaling: {size!r} is not ROBOTSxTASKS (e.g. 8x8)")
        r, t = int(m.group(1)), int(m.group(2))
        for seed in range(args.seeds):
            work.append((scenario_name(t, r, "line"), generate(t, r, "line", seed)))

    console = Console(stderr=True)
    table = Table(title="hltl bench planner")
    for col in (
        "config",
        "robots",
        "tasks",
        "median ms",
        "max ms",
        "expanded",
        "makespan",
        "status",
    ):
        table.add_column(col, justify="left" if col in ("config", "status") else "right")

    def show(row: PlannerRow) -> None:
        ms = "–" if row.makespan is None else f"{row.makespan:.2f}"
        console.print(
            f"  {row.config:>14}: median {row.median_ms:8.1f} ms  expanded {row.expanded:8.0f}"
            f"  makespan {ms}  {row.status}"
        )
        table.add_row(
            row.config,
            str(row.robots),
            str(row.tasks),
            f"{row.median_ms:.1f}",
            f"{row.max_ms:.1f}",
            f"{row.expanded:.0f}",
            ms,
            row.status,
        )

    rows = bench_planner(
        work, repeats=args.repeats, timeout=args.timeout, algorithm=args.algorithm, on_row=show
    )
    Console().print(table)
    if args.write is not None:
        command = (
            f"hltl bench planner --repeats {args.repeats} --seeds {args.seeds} "
            f"--algorithm {args.algorithm} --timeout {args.timeout:g}"
            + (f" --scaling {shlex.quote(args.scaling)}" if args.scaling else "")
            + f" --write {shlex.quote(str(args.write))}"
        )
        body = (
            f"Command: `{command}`  \n"
            f"Machine: {platform.machine()}, Python {platform.python_version()}, "
            f"{_cpus()} cores. Times include compiling monitors from the automaton cache.\n\n"
            + format_planner_table(rows)
        )
        write_section(args.write, "planner", body)
        print(f"wrote {args.write}", file=sys.stderr)
    return 0


def run_replan(args: argparse.Namespace) -> int:
    from rich.console import Console

    from hltl.sim.replan_bench import ReplanRow, bench_replan, format_rows
    from hltl.sim.scenarios import PAPER_CONFIGS, scenario_name

    if args.seeds < 1:
        raise HltlError("--seeds must be at least 1")
    by_name = {scenario_name(*c): c for c in PAPER_CONFIGS}
    wanted = [c.strip() for c in args.configs.split(",") if c.strip()] or list(by_name)
    unknown = [c for c in wanted if c not in by_name]
    if unknown:
        raise HltlError(
            f"--configs: unknown configuration {unknown[0]!r}; expected one of "
            + ", ".join(by_name)
        )
    console = Console(stderr=True)

    def show(row: ReplanRow) -> None:
        med = "—" if row.median_ms is None else f"{row.median_ms:.2f}"
        p95 = "—" if row.p95_ms is None else f"{row.p95_ms:.2f}"
        console.print(
            f"  {row.config:>14} predict={'yes' if row.predict else 'no ':3}  "
            f"success {row.successes}/{row.episodes}  replans {row.replans:3d}  "
            f"median {med} ms  p95 {p95} ms"
        )

    rows = bench_replan([by_name[c] for c in wanted], list(range(args.seeds)), on_row=show)
    table = format_rows(rows)
    print(table)
    if args.write is not None:
        command = (
            f"hltl bench replan --seeds {args.seeds}"
            + (f" --configs {args.configs}" if args.configs else "")
            + f" --write {shlex.quote(str(args.write))}"
        )
        body = (
            f"Command: `{command}`  \n"
            f"Machine: {platform.machine()}, Python {platform.python_version()}, {_cpus()} cores. "
            "Latency is the planner's wall-clock time per replan on the critical path (LLM time "
            "excluded); each episode has a person walking across the cell midway.\n\n" + table
        )
        write_section(args.write, "replan", body)
        print(f"wrote {args.write}", file=sys.stderr)
    return 0


def _cpus() -> int:
    import os

    return os.cpu_count() or 1


def write_section(path: Path, name: str, body: str) -> None:
    """Replace the text between ``<!-- name:begin -->`` and ``<!-- name:end -->`` (or append)."""
    begin, end = f"<!-- {name}:begin -->", f"<!-- {name}:end -->"
    text = path.read_text(encoding="utf-8") if path.exists() else "# Benchmarks\n"
    block = f"{begin}\n{body}\n{end}"
    if begin in text and end in text:
        pre, rest = text.split(begin, 1)
        _, post = rest.split(end, 1)
        text = pre + block + post
    else:
        text = text.rstrip("\n") + "\n\n" + block + "\n"
    path.write_text(text, encoding="utf-8")
