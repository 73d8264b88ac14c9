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
    pl.add_argument(
        "--section",
        default="planner",
        help="name of the section --write replaces (default: planner)",
    )
    pl.add_argument("--scaling-only", action="store_true", help="skip the paper configurations")
    pl.set_defaults(func=run_planner)

    su = bsub.add_parser(
        "suite",
        help="the paper's Table II with dynamics: hltl and the baselines in the closed loop",
    )
    su.add_argument("--trials", type=int, default=100, help="trials per configuration")
    su.add_argument(
        "--configs", default="", help="comma-separated configurations (default: all twelve)"
    )
    su.add_argument(
        "--methods",
        default="hltl,greedy,smart-llm,flat,fd",
        help="comma-separated: hltl, greedy, smart-llm (closed loop); flat, fd (planning only)",
    )
    su.add_argument("--jobs", type=int, default=2, help="worker processes")
    su.add_argument("--seed", type=int, default=0, help="suite seed (trial seeds derive from it)")
    su.add_argument("--max-time", type=float, default=120.0, help="simulated seconds per trial")
    su.add_argument(
        "--flat-trials", type=int, default=2, help="trials per configuration for flat LTLf"
    )
    su.add_argument(
        "--flat-sweep",
        default="1,2,4,6,8,10,12",
        help="task counts for the flat-LTLf growth sweep on a 2x2 square ('' to skip)",
    )
    su.add_argument("--flat-limit", type=float, default=60.0, help="seconds for a flat automaton")
    su.add_argument("--write", type=Path, help="update this Markdown file's suite section")
    su.add_argument("--figures", type=Path, help="write suite_*.png here (needs matplotlib)")
    su.add_argument("--json", type=Path, help="write every trial's result here")
    su.set_defaults(func=run_suite_cmd)

    ab = bsub.add_parser("ablation", help="Table III: fluency metrics of executor variants")
    ab.add_argument("--trials", type=int, default=20, help="trials per configuration")
    ab.add_argument("--configs", default="", help="comma-separated configurations (default: all)")
    ab.add_argument("--jobs", type=int, default=2, help="worker processes")
    ab.add_argument("--seed", type=int, default=0, help="suite seed")
    ab.add_argument(
        "--plan-latency",
        type=float,
        default=0.2,
        help="simulated seconds a critical-path replan costs (full and w/o P.P.)",
    )
    ab.add_argument(
        "--serial-factor",
        type=float,
        default=3.0,
        help="w/o P.M.P.: the replan latency multiplied by this (candidates computed serially)",
    )
    ab.add_argument("--write", type=Path, help="update this Markdown file's ablation section")
    ab.add_argument("--json", type=Path, help="write every trial's result here")
    ab.set_defaults(func=run_ablation_cmd)

    rp = bsub.add_parser("replan", help="closed-loop replanning latency per paper configuration")
    rp.add_argument("--seeds", type=int, default=5, help="episodes per configuration and variant")
    rp.add_argument(
        "--configs",
        default="",
        help="comma-separated names such as 4-4-line,4-4-square (default: all paper configs)",
    )
    rp.add_argument("--write", type=Path, help="update this Markdown file's replan section")
    rp.set_defaults(func=run_replan)

    gr = bsub.add_parser("grounding", help="offline grounder on the paraphrase corpus")
    gr.add_argument("--show", action="store_true", help="list every instruction not exact")
    gr.add_argument("--write", type=Path, help="update this Markdown file's grounding section")
    gr.set_defaults(func=run_grounding)


def run_planner(args: argparse.Namespace) -> int:
    from rich.console import Console
    from rich.table import Table

    from hltl.sim.bench import PlannerRow, bench_planner, format_planner_table
    from hltl.sim.scenarios import PAPER_CONFIGS, generate, scenario_name

    if args.repeats < 1 or args.seeds < 1:
        raise HltlError("--repeats and --seeds must be at least 1")
    work: list[tuple[str, Any]] = []
    for n_task, n_robot, layout in () if args.scaling_only else PAPER_CONFIGS:
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
            + (" --scaling-only" if args.scaling_only else "")
            + (f" --section {args.section}" if args.section != "planner" else "")
            + f" --write {shlex.quote(str(args.write))}"
        )
        body = (
            f"Command: `{command}`  \n"
            f"Machine: {platform.machine()}, Python {platform.python_version()}, "
            f"{_cpus()} cores. Times include compiling monitors from the automaton cache.\n\n"
            + format_planner_table(rows)
        )
        write_section(args.write, args.section, body)
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


def run_grounding(args: argparse.Namespace) -> int:
    import datetime

    from hltl.bench.grounding import (
        CORPUS_DIR,
        PARTS,
        format_scores,
        load_corpus,
        offline_tree,
        repository_root,
        score,
    )

    root = repository_root()
    scores = []
    for part in PARTS:
        result = score(load_corpus(root / CORPUS_DIR / f"{part}.yaml", root), offline_tree)
        scores.append(result)
        print(
            f"  {part}: {result.exact_pct:.1f} % exact of {result.total}, "
            f"{result.count('wrong')} wrong",
            file=sys.stderr,
        )
        for o in result.outcomes:
            if o.verdict != "exact" and (args.show or o.verdict == "wrong"):
                print(
                    f"    [{o.verdict}] {o.entry.scene}: {o.entry.text!r} -> {o.detail}",
                    file=sys.stderr,
                )
    table = format_scores(scores)
    print(table)
    if args.write is not None:
        body = (
            f"Command: `hltl bench grounding --write {shlex.quote(str(args.write))}`  \n"
            f"Date: {datetime.date.today().isoformat()}. Machine: {platform.machine()}, "
            f"Python {platform.python_version()}, "
            f"{_cpus()} cores (shared). Exact = a spec language-equivalent to the expected one, or "
            "a refusal (listing the readings when the corpus names them); wrong = a spec that "
            "differs, or a grounding where a refusal was expected. Parts: docs/grounding.md.\n\n"
            + table
        )
        write_section(args.write, "grounding", body)
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


def _progress(total: int, title: str) -> Any:
    from rich.console import Console
    from rich.progress import (
        BarColumn,
        MofNCompleteColumn,
        Progress,
        TextColumn,
        TimeElapsedColumn,
        TimeRemainingColumn,
    )

    return Progress(
        TextColumn(title),
        BarColumn(),
        MofNCompleteColumn(),
        TimeElapsedColumn(),
        TimeRemainingColumn(),
        TextColumn("{task.description}"),
        console=Console(stderr=True),
    )


def _configs(text: str) -> list[str]:
    from hltl.sim.suite import config_names, config_of

    if not text.strip():
        return list(config_names())
    names = [c.strip() for c in text.split(",") if c.strip()]
    for c in names:
        config_of(c)
    return names


def run_suite_cmd(args: argparse.Namespace) -> int:
    import json
    import time

    from hltl.sim import report
    from hltl.sim.baselines.flat import sweep
    from hltl.sim.suite import (
        METHODS,
        ONE_SHOT,
        TrialResult,
        jobs_for,
        results_to_json,
        run_suite,
    )

    if args.trials < 1 or args.jobs < 1:
        raise HltlError("--trials and --jobs must be at least 1")
    configs = _configs(args.configs)
    methods = [m.strip() for m in args.methods.split(",") if m.strip()]
    for m in methods:
        if m not in (*METHODS, *ONE_SHOT):
            raise HltlError(
                f"--methods: unknown method {m!r}; expected some of "
                f"{', '.join((*METHODS, *ONE_SHOT))}"
            )
    loop_methods = [m for m in methods if m in METHODS]
    jobs = jobs_for(configs, args.trials, loop_methods, args.seed, max_time=args.max_time)
    if "fd" in methods:
        jobs += jobs_for(configs, args.trials, ["fd"], args.seed)
    if "flat" in methods:
        jobs += jobs_for(configs, min(args.flat_trials, args.trials), ["flat"], args.seed)
    t0 = time.perf_counter()
    with _progress(len(jobs), "hltl bench suite") as progress:
        task = progress.add_task("", total=len(jobs))

        def tick(r: TrialResult) -> None:
            mark = {"ok": "ok" if r.success else "fail"}.get(r.status, r.status)
            progress.update(task, advance=1, description=f"{r.method} {r.config}#{r.index} {mark}")

        results = run_suite(jobs, workers=args.jobs, on_result=tick)
    wall = time.perf_counter() - t0
    sweep_rows: list[dict[str, Any]] = []
    sweep_s = 0.0
    if "flat" in methods and args.flat_sweep.strip():
        t1 = time.perf_counter()
        sizes = [int(x) for x in args.flat_sweep.split(",") if x.strip()]
        sweep_rows = [c.to_dict() for c in sweep(sizes, limit=args.flat_limit, seed=args.seed)]
        sweep_s = time.perf_counter() - t1

    cells = report.summarise(results, seed=args.seed)
    shown = [m for m in ("hltl", "greedy", "smart-llm") if m in loop_methods]
    table = report.format_table_ii(cells, configs, shown)
    notes = {r.method: r.reason for r in results if r.status == "not_run"}
    modes = report.format_failure_modes(report.failure_modes(results), notes)
    loop_wall = sum(r.wall_s for r in results if r.method in METHODS)
    print(table)
    print()
    print(modes)
    print(
        f"\nwall time {wall:.0f} s ({args.jobs} workers); flat sweep {sweep_s:.0f} s",
        file=sys.stderr,
    )
    if args.json is not None:
        args.json.parent.mkdir(parents=True, exist_ok=True)
        args.json.write_text(
            json.dumps(
                {
                    "command": _suite_command(args),
                    "wall_s": wall,
                    "results": results_to_json(results),
                    "flat_sweep": sweep_rows,
                },
                indent=1,
            ),
            encoding="utf-8",
        )
    figures: list[Path] = []
    if args.figures is not None:
        figures = report.plot_suite(cells, configs, shown, args.figures)
        if sweep_rows:
            figures.append(report.plot_flat(sweep_rows, args.figures / "suite_flat.png"))
    if args.write is not None:
        body = report.suite_section(
            command=_suite_command(args),
            machine=f"{platform.machine()}, Python {platform.python_version()}, {_cpus()} cores",
            wall_s=wall,
            loop_cpu_s=loop_wall,
            n_loop_trials=sum(1 for j in jobs if j.method in METHODS),
            table=table,
            modes=modes,
            results=results,
            configs=configs,
            sweep_rows=sweep_rows,
            sweep_s=sweep_s,
            figures=[f.name for f in figures],
            trials=args.trials,
        )
        write_section(args.write, "suite", body)
        print(f"wrote {args.write}", file=sys.stderr)
    return 0


def _suite_command(args: argparse.Namespace) -> str:
    parts = [
        f"hltl bench suite --trials {args.trials}",
        f"--methods {args.methods}",
        f"--jobs {args.jobs} --seed {args.seed}",
    ]
    if args.configs:
        parts.append(f"--configs {args.configs}")
    if args.max_time != 120.0:
        parts.append(f"--max-time {args.max_time:g}")
    if "flat" in args.methods:
        parts.append(
            f"--flat-trials {args.flat_trials} --flat-sweep {shlex.quote(args.flat_sweep)}"
        )
    for flag in ("write", "figures", "json"):
        v = getattr(args, flag)
        if v is not None:
            parts.append(f"--{flag} {shlex.quote(str(v))}")
    return " ".join(parts)


def run_ablation_cmd(args: argparse.Namespace) -> int:
    import json
    import statistics
    import time

    from hltl.sim import report
    from hltl.sim.suite import TrialResult, Variant, jobs_for, results_to_json, run_suite

    if args.trials < 1 or args.jobs < 1:
        raise HltlError("--trials and --jobs must be at least 1")
    if args.plan_latency < 0 or args.serial_factor < 1:
        raise HltlError("--plan-latency must be >= 0 and --serial-factor >= 1")
    configs = _configs(args.configs)
    variants = [
        Variant("full", True, args.plan_latency),
        Variant("no-pp", False, args.plan_latency),
        Variant("no-pmp", True, args.plan_latency * args.serial_factor),
    ]
    jobs = jobs_for(configs, args.trials, ["hltl"], args.seed, variants)
    t0 = time.perf_counter()
    with _progress(len(jobs), "hltl bench ablation") as progress:
        task = progress.add_task("", total=len(jobs))

        def tick(r: TrialResult) -> None:
            progress.update(task, advance=1, description=f"{r.variant} {r.config}#{r.index}")

        results = run_suite(jobs, workers=args.jobs, on_result=tick)
    wall = time.perf_counter() - t0
    stats = report.fluency(results)
    extra: dict[str, dict[str, float]] = {}
    for v in variants:
        rs = [r for r in results if r.variant == v.name and r.status == "ok"]
        times = [r.time_cost for r in rs if r.success and r.time_cost is not None]
        extra[v.name] = {
            "success %": 100.0 * sum(r.success for r in rs) / max(1, len(rs)),
            "time cost s": statistics.fmean(times) if times else float("nan"),
            "takeovers/trial": statistics.fmean(r.extra.get("takeovers", 0) for r in rs)
            if rs
            else float("nan"),
        }
    table = report.format_table_iii(stats, extra)
    print(table)
    print(f"\nwall time {wall:.0f} s ({args.jobs} workers)", file=sys.stderr)
    command = (
        f"hltl bench ablation --trials {args.trials} --jobs {args.jobs} --seed {args.seed} "
        f"--plan-latency {args.plan_latency:g} --serial-factor {args.serial_factor:g}"
        + (f" --configs {args.configs}" if args.configs else "")
        + (f" --write {shlex.quote(str(args.write))}" if args.write else "")
        + (f" --json {shlex.quote(str(args.json))}" if args.json else "")
    )
    if args.json is not None:
        args.json.parent.mkdir(parents=True, exist_ok=True)
        args.json.write_text(
            json.dumps(
                {"command": command, "wall_s": wall, "results": results_to_json(results)}, indent=1
            ),
            encoding="utf-8",
        )
    if args.write is not None:
        body = report.ablation_section(
            command=command,
            machine=f"{platform.machine()}, Python {platform.python_version()}, {_cpus()} cores",
            wall_s=wall,
            table=table,
            n=len(results),
            configs=configs,
            trials=args.trials,
            plan_latency=args.plan_latency,
            serial_factor=args.serial_factor,
        )
        write_section(args.write, "ablation", body)
        print(f"wrote {args.write}", file=sys.stderr)
    return 0
