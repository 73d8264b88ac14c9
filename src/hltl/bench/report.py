"""Statistics and tables of the evaluation: Wilson and bootstrap intervals, Table II and III."""

from __future__ import annotations

import math
import random
import statistics
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from hltl.bench.pmp import PmpLatency
from hltl.bench.suite import TrialResult, Variant, solved_by_all
from hltl.errors import BackendUnavailableError
from hltl.execution.latency import LatencyModel
from hltl.sim.dynamic import config_of

Z95 = 1.959963984540054

# Table II of the paper: success rate (%), time cost (s), tokens per query; Ours and SMART-LLM-R.
PAPER_TABLE_II: dict[str, tuple[float, float, float, float, float, float]] = {
    "1-1": (100, 100, 1.0, 1.0, 261, 2690),
    "2-1": (100, 99, 2.1, 2.1, 470, 3252),
    "4-1": (100, 96, 4.4, 4.4, 885, 4493),
    "1-2": (100, 100, 2.1, 2.1, 264, 3611),
    "2-2": (100, 68, 2.2, 2.8, 473, 4386),
    "4-2": (97, 41, 4.5, 6.7, 896, 6595),
    "1-4-line": (100, 79, 4.4, 4.4, 374, 4616),
    "2-4-line": (99, 39, 9.5, 9.5, 607, 4907),
    "4-4-line": (93, 19, 19.4, 19.3, 1259, 7385),
    "1-4-square": (100, 94, 2.1, 2.1, 264, 4243),
    "2-4-square": (100, 40, 2.3, 2.7, 471, 5598),
    "4-4-square": (95, 22, 4.7, 7.9, 902, 7587),
}
# Table III: H-IDLE, R-IDLE, C-ACT, F-DEL as (mean, std) in %.
PAPER_TABLE_III: dict[str, tuple[tuple[float, float], ...]] = {
    "full": ((67.1, 17.2), (38.8, 10.1), (64.9, 11.9), (-4.5, 8.6)),
    "no-pp": ((70.8, 16.7), (45.4, 11.3), (63.5, 15.0), (-4.4, 7.9)),
    "no-pmp": ((68.6, 17.9), (42.7, 11.9), (60.8, 14.0), (-4.2, 8.6)),
}
METHOD_LABELS = {"hltl": "hltl", "greedy": "Greedy-R", "smart-llm": "SMART-LLM-R"}
VARIANT_LABELS = {
    "full": "full",
    "no-pp": "w/o P.P.",
    "no-pmp": "w/o P.M.P. (serial candidates)",
    "goal": "full, goal-directed predictor",
    "antic-goal": "+ anticipation (goal-directed)",
    "antic-gru": "+ anticipation (GRU)",
}


def wilson(k: int, n: int, z: float = Z95) -> tuple[float, float]:
    """Wilson score interval for ``k`` successes in ``n`` trials, as fractions in [0, 1].

    Raises:
        ValueError: ``n < 1`` or ``k`` outside [0, n].
    """
    if n < 1 or not 0 <= k <= n:
        raise ValueError(f"need 0 <= k <= n and n >= 1, got k={k}, n={n}")
    p = k / n
    denom = 1.0 + z * z / n
    centre = (p + z * z / (2 * n)) / denom
    half = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / denom
    return max(0.0, centre - half), min(1.0, centre + half)


def bootstrap_ci(
    values: Sequence[float], *, seed: int = 0, resamples: int = 2000, level: float = 0.95
) -> tuple[float, float]:
    """Percentile bootstrap interval of the mean (seeded, so reports are reproducible).

    Raises:
        ValueError: no values.
    """
    if not values:
        raise ValueError("bootstrap_ci needs at least one value")
    if len(values) == 1:
        return values[0], values[0]
    rng = random.Random(seed)
    n = len(values)
    means = sorted(statistics.fmean(rng.choices(values, k=n)) for _ in range(resamples))
    lo = means[math.floor((1 - level) / 2 * (resamples - 1))]
    hi = means[math.ceil((1 + level) / 2 * (resamples - 1))]
    return lo, hi


@dataclass(frozen=True, slots=True)
class Cell:
    """One method on one configuration."""

    method: str
    config: str
    status: str  # "ok", "not_run", "error" (some trials crashed), "none"
    n: int = 0
    successes: int = 0
    rate_ci: tuple[float, float] | None = None
    time_mean: float | None = None
    time_ci: tuple[float, float] | None = None
    tokens_mean: float | None = None
    tokens_ci: tuple[float, float] | None = None
    est_tokens_mean: float | None = None
    errors: int = 0
    note: str = ""

    @property
    def rate(self) -> float | None:
        return self.successes / self.n if self.n else None


def _seed_of(*parts: str) -> int:
    return random.Random("/".join(parts)).randrange(2**31)


def summarise(results: Iterable[TrialResult], *, seed: int = 0) -> dict[tuple[str, str], Cell]:
    """Per (method, configuration): success rate with its Wilson interval, mean time cost over
    successful trials and mean tokens per query, each with a seeded bootstrap interval."""
    groups: dict[tuple[str, str], list[TrialResult]] = {}
    for r in results:
        groups.setdefault((r.method, r.config), []).append(r)
    out: dict[tuple[str, str], Cell] = {}
    for (method, config), rs in groups.items():
        ran = [r for r in rs if r.status in ("ok", "error")]
        if not ran:
            out[(method, config)] = Cell(method, config, "not_run", note=rs[0].reason)
            continue
        k = sum(1 for r in ran if r.status == "ok" and r.success)
        times = [r.time_cost for r in ran if r.success and r.time_cost is not None]
        tpq = [r.tokens_per_query for r in ran if r.tokens_per_query is not None]
        est = [r.est_tokens_per_query for r in ran if r.est_tokens_per_query is not None]
        s = _seed_of(str(seed), method, config)
        out[(method, config)] = Cell(
            method,
            config,
            "ok" if all(r.status == "ok" for r in ran) else "error",
            n=len(ran),
            successes=k,
            rate_ci=wilson(k, len(ran)),
            time_mean=statistics.fmean(times) if times else None,
            time_ci=bootstrap_ci(times, seed=s) if times else None,
            tokens_mean=statistics.fmean(tpq) if tpq else None,
            tokens_ci=bootstrap_ci(tpq, seed=s + 1) if tpq else None,
            est_tokens_mean=statistics.fmean(est) if est else None,
            errors=sum(1 for r in ran if r.status == "error"),
        )
    return out


def _rate(c: Cell | None) -> str:
    if c is None or c.status == "not_run":
        return "not run"
    assert c.rate_ci is not None and c.rate is not None
    lo, hi = c.rate_ci
    return f"{100 * c.rate:.0f} [{100 * lo:.0f}, {100 * hi:.0f}]"


def _mean(m: float | None, ci: tuple[float, float] | None, fmt: str, c: Cell | None) -> str:
    if c is None or c.status == "not_run":
        return "not run"
    if m is None or ci is None:
        return "–"
    return f"{m:{fmt}} [{ci[0]:{fmt}}, {ci[1]:{fmt}}]"


def _paper(v: float, fmt: str) -> str:
    return f"{v:{fmt}}"


def format_table_ii(
    cells: Mapping[tuple[str, str], Cell], configs: Sequence[str], methods: Sequence[str]
) -> str:
    """Table II's layout: one row per configuration, grouped by robot count; for each metric
    our methods, then the paper's Ours and SMART-LLM-R as reference columns (italic)."""
    labels = [METHOD_LABELS.get(m, m) for m in methods]
    head = ["Tasks–Robots"]
    for metric in ("SR %", "Time s", "Tokens/query"):
        head += [f"{metric} {lab}" for lab in labels]
        if metric == "Tokens/query" and "hltl" in methods:
            head.append("Tokens/query hltl (o200k est.)")
        head += [f"{metric} *paper Ours*", f"{metric} *paper SMART-LLM-R*"]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" + "---:|" * (len(head) - 1)]
    previous_robots = None
    for config in configs:
        robots = config.split("-")[1]
        if previous_robots is not None and robots != previous_robots:
            lines.append("| " + " | ".join([""] * len(head)) + " |")
        previous_robots = robots
        paper = PAPER_TABLE_II.get(config)
        row = [config]
        row += [_rate(cells.get((m, config))) for m in methods]
        row += (
            [f"*{_paper(paper[0], '.0f')}*", f"*{_paper(paper[1], '.0f')}*"] if paper else ["", ""]
        )
        for m in methods:
            c = cells.get((m, config))
            row.append(_mean(c.time_mean if c else None, c.time_ci if c else None, ".2f", c))
        row += [f"*{paper[2]:.1f}*", f"*{paper[3]:.1f}*"] if paper else ["", ""]
        for m in methods:
            c = cells.get((m, config))
            row.append(_mean(c.tokens_mean if c else None, c.tokens_ci if c else None, ".0f", c))
        if "hltl" in methods:
            c = cells.get(("hltl", config))
            est = c.est_tokens_mean if c is not None else None
            row.append("–" if est is None else f"{est:.0f}")
        row += [f"*{paper[4]:.0f}*", f"*{paper[5]:.0f}*"] if paper else ["", ""]
        lines.append("| " + " | ".join(row) + " |")
    return "\n".join(lines)


# the paper's four columns; then the added forms (docs/metrics.md): F-DEL as a time union,
# human-robot concurrency, H-IDLE with walking counted as active
_FLUENCY = ("h_idle", "r_idle", "c_act", "f_del")
_FLUENCY_ADDED = ("f_del_union", "c_act_hr", "h_idle_walk_active")


def fluency(results: Iterable[TrialResult]) -> dict[str, dict[str, tuple[float, float, int]]]:
    """Per variant, (mean, std, n) of H-IDLE, R-IDLE, C-ACT and F-DEL over all trials that
    have the metric (an episode without a recipient has no H-IDLE)."""
    by: dict[str, dict[str, list[float]]] = {}
    for r in results:
        if r.status != "ok":
            continue
        d = by.setdefault(r.variant, {k: [] for k in (*_FLUENCY, *_FLUENCY_ADDED)})
        for key in d:
            v = getattr(r, key)
            if v is not None:
                d[key].append(float(v))
    out: dict[str, dict[str, tuple[float, float, int]]] = {}
    for variant, d in by.items():
        out[variant] = {
            k: (
                statistics.fmean(v) if v else math.nan,
                statistics.stdev(v) if len(v) > 1 else 0.0,
                len(v),
            )
            for k, v in d.items()
        }
    return out


def format_table_iii(
    stats: Mapping[str, Mapping[str, tuple[float, float, int]]],
    extra: Mapping[str, Mapping[str, float]] | None = None,
) -> str:
    """Table III's layout (mean ± std, %), the paper's rows beside ours; ``extra`` adds columns
    per variant (e.g. time cost, takeovers)."""
    extra_keys = list(dict.fromkeys(k for v in (extra or {}).values() for k in v))
    head = [
        "Variant",
        "H-IDLE ↓ (%)",
        "R-IDLE ↓ (%)",
        "C-ACT ≥2 ↑ (%)",
        "F-DEL Σ ↓ (%)",
        "F-DEL ∪ ↓ (%)",
        "C-ACT H–R ↑ (%)",
        "H-IDLE walk=active ↓ (%)",
        *extra_keys,
    ]
    lines = ["| " + " | ".join(head) + " |", "|---|" + "---:|" * (len(head) - 1)]
    for variant in VARIANT_LABELS:
        if variant in stats:
            s = stats[variant]
            row = [f"hltl {VARIANT_LABELS[variant]}"]
            cells = [s.get(k) for k in (*_FLUENCY, *_FLUENCY_ADDED)]
            row += ["–" if not c or c[2] == 0 else f"{c[0]:.1f} ± {c[1]:.1f}" for c in cells]
            row += [f"{(extra or {}).get(variant, {}).get(k, math.nan):.3g}" for k in extra_keys]
            lines.append("| " + " | ".join(row) + " |")
    for variant, vals in PAPER_TABLE_III.items():
        row = [f"*paper {VARIANT_LABELS[variant].split(' (', 1)[0]}*"]
        row += [f"*{m:.1f} ± {sd:.1f}*" for m, sd in vals]
        row += [""] * (len(_FLUENCY_ADDED) + len(extra_keys))
        lines.append("| " + " | ".join(row) + " |")
    return "\n".join(lines)


def _group(r: TrialResult) -> str:
    robots = config_of(r.config)[1]
    if robots == 1:
        return "1 robot"
    return "multi-robot, T2 walk" if r.extra.get("walk") == "t2" else "multi-robot, random walk"


def format_ablation_groups(results: Iterable[TrialResult], variants: Sequence[Variant]) -> str:
    """The ablation split by cell (one robot; several robots with a random or a T2-style
    walk), then per configuration: trials, success, time over the trials every variant solved
    (paired), H-IDLE and R-IDLE, anticipatory dispatches. Prediction cannot help a one-robot
    cell (nobody else can serve a person who moves), so the split shows where it can."""
    ok = [r for r in results if r.status == "ok"]
    names = [v.name for v in variants]
    common = solved_by_all(ok, variants)

    def cells(rs: list[TrialResult]) -> list[str]:
        paired = [r.time_cost for r in rs if (r.config, r.index) in common and r.time_cost]
        h = [r.h_idle for r in rs if r.h_idle is not None]
        ri = [r.r_idle for r in rs if r.r_idle is not None]
        ant = [float(r.extra.get("anticipations", 0)) for r in rs]

        def f(v: list[float], fmt: str) -> str:
            return format(statistics.fmean(v), fmt) if v else "–"

        return [
            str(len(rs)),
            f"{100.0 * sum(r.success for r in rs) / max(1, len(rs)):.0f}",
            f(paired, ".2f"),
            f(h, ".1f"),
            f(ri, ".1f"),
            f(ant, ".2f"),
        ]

    head = (
        "| {} | variant | trials | success % | time paired s | H-IDLE % | R-IDLE % "
        "| anticip./trial |"
    )
    sep = "|---|---|---:|---:|---:|---:|---:|---:|"
    out = ["By cell:", "", head.format("cells"), sep]
    groups = ("1 robot", "multi-robot, random walk", "multi-robot, T2 walk")
    for g in groups:
        for v in names:
            rs = [r for r in ok if r.variant == v and _group(r) == g]
            if rs:
                label = VARIANT_LABELS.get(v, v)
                out.append("| " + " | ".join([g, label, *cells(rs)]) + " |")
    out += ["", "By configuration:", "", head.format("config"), sep]
    for c in dict.fromkeys(r.config for r in ok):
        for v in names:
            rs = [r for r in ok if r.variant == v and r.config == c]
            if rs:
                out.append("| " + " | ".join([c, VARIANT_LABELS.get(v, v), *cells(rs)]) + " |")
    return "\n".join(out)


def failure_modes(results: Iterable[TrialResult]) -> dict[str, dict[str, int]]:
    """Per method over all its trials that ran: trials, caught kinematic violations, caught
    shared-object conflicts, refused stale steps, violations the simulator saw (physics), and
    invariant problems found in the logs."""
    out: dict[str, dict[str, int]] = {}
    for r in results:
        if r.method not in METHOD_LABELS:
            continue
        d = out.setdefault(
            r.method,
            {
                "trials": 0,
                "ran": 0,
                "kinematic": 0,
                "conflict": 0,
                "stale": 0,
                "physical": 0,
                "invariants": 0,
                "errors": 0,
            },
        )
        d["trials"] += 1
        if r.status == "not_run":
            continue
        d["ran"] += 1
        d["errors"] += r.status == "error"
        d["kinematic"] += r.kinematic
        d["conflict"] += r.conflicts
        d["stale"] += r.stale
        d["physical"] += max(0, r.violations - r.kinematic - r.conflicts)
        d["invariants"] += r.invariant_problems
    return out


def format_failure_modes(modes: Mapping[str, Mapping[str, int]], notes: Mapping[str, str]) -> str:
    head = [
        "method",
        "trials run",
        "kinematic violations caught",
        "shared-object conflicts caught",
        "stale steps refused (world changed)",
        "violations in the simulator",
        "invariant problems in logs",
        "crashed trials",
    ]
    lines = ["| " + " | ".join(head) + " |", "|---|" + "---:|" * (len(head) - 1)]
    for method, d in modes.items():
        label = METHOD_LABELS.get(method, method)
        if d["ran"] == 0:
            lines.append(f"| {label} | not run: {notes.get(method, '')} |" + " |" * 6)
            continue
        lines.append(
            f"| {label} | {d['ran']} | {d['kinematic']} | {d['conflict']} | {d['stale']} | "
            f"{d['physical']} | {d['invariants']} | {d['errors']} |"
        )
    return "\n".join(lines)


def format_flat(rows: Sequence[Mapping[str, Any]]) -> str:
    """Flat LTLf beside the hierarchy (rows from :meth:`FlatComparison.to_dict`)."""
    head = [
        "tasks",
        "hier. automata",
        "hier. states / edges",
        "hier. MONA s",
        "hier. plan s",
        "flat props",
        "flat states / edges",
        "flat MONA s",
        "flat plan s",
        "makespan h / f",
    ]
    lines = ["| " + " | ".join(head) + " |", "|" + "---:|" * len(head)]
    for r in rows:
        h, f = r["hier"], r["flat"]

        def num(v: Any, fmt: str) -> str:
            return "–" if v is None else f"{v:{fmt}}"

        if f["status"] == "ok":
            fcols = [
                str(f["props"]),
                f"{f['states']} / {f['edges']}",
                num(f["compile_s"], ".2f"),
                num(f["plan_s"], ".3f")
                + ("" if f["plan_status"] == "solved" else f" ({f['plan_status']})"),
            ]
        else:
            fcols = ["–", f"failed: {f['status']}", "–", "–"]
        lines.append(
            "| "
            + " | ".join(
                [
                    str(r["tasks"]),
                    str(h["nodes"]),
                    f"{h['states']} / {h['edges']}",
                    num(h["compile_s"], ".3f"),
                    num(h["plan_s"], ".3f"),
                    *fcols,
                    f"{num(h['makespan'], '.1f')} / {num(f.get('makespan'), '.1f')}",
                ]
            )
            + " |"
        )
    return "\n".join(lines)


def format_fd(results: Iterable[TrialResult], configs: Sequence[str]) -> str:
    """Fast Downward beside hltl per configuration (medians over the trials)."""
    by: dict[str, list[TrialResult]] = {}
    for r in results:
        if r.method == "fd" and r.status == "ok":
            by.setdefault(r.config, []).append(r)
    head = [
        "config",
        "trials",
        "FD solved",
        "FD plan s (median)",
        "FD cost = total robot time s",
        "hltl plan s (median)",
        "hltl makespan s",
        "hltl total robot time s",
    ]
    lines = ["| " + " | ".join(head) + " |", "|---|" + "---:|" * (len(head) - 1)]

    def med(values: list[float | None]) -> str:
        xs = [x for x in values if x is not None]
        return "–" if not xs else f"{statistics.median(xs):.3f}"

    for c in configs:
        rs = by.get(c, [])
        if not rs:
            continue
        fd = [r.extra["fd"] for r in rs]
        ours = [r.extra["hltl"] for r in rs]
        solved = [x for x in fd if x["status"] == "solved"]
        lines.append(
            f"| {c} | {len(rs)} | {len(solved)} | {med([x['seconds'] for x in fd])} | "
            f"{med([x['cost'] for x in solved])} | {med([x['seconds'] for x in ours])} | "
            f"{med([x['makespan'] for x in ours if x['makespan'] is not None])} | "
            f"{med([x['work'] for x in ours])} |"
        )
    return "\n".join(lines)


def plot_suite(
    cells: Mapping[tuple[str, str], Cell],
    configs: Sequence[str],
    methods: Sequence[str],
    directory: Path,
) -> list[Path]:
    """``suite_success.png`` and ``suite_time.png`` (bars with 95 % intervals, paper markers).

    Raises:
        BackendUnavailableError: matplotlib is missing (the ``viz`` extra).
    """
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        raise BackendUnavailableError("plots need matplotlib: pip install 'hltl[viz]'") from None
    directory.mkdir(parents=True, exist_ok=True)
    ran = [m for m in methods if any(cells.get((m, c), Cell(m, c, "none")).n for c in configs)]
    width = 0.8 / max(1, len(ran) + 1)
    xs = list(range(len(configs)))
    written = []
    getters: list[tuple[str, str, Callable[[Cell], tuple[float, float, float] | None], int]] = [
        ("suite_success.png", "success rate (%)", _rate_bar, 0),
        ("suite_time.png", "time cost of successful trials (s)", _time_bar, 2),
    ]
    for name, ylabel, get, paper_col in getters:
        fig, ax = plt.subplots(figsize=(11, 4))
        for k, m in enumerate(ran):
            vals, lo, hi = [], [], []
            for c in configs:
                cell = cells.get((m, c))
                v = get(cell) if cell is not None else None
                vals.append(math.nan if v is None else v[0])
                lo.append(0.0 if v is None else v[0] - v[1])
                hi.append(0.0 if v is None else v[2] - v[0])
            ax.bar(
                [x + k * width for x in xs],
                vals,
                width,
                yerr=[lo, hi],
                capsize=2,
                label=METHOD_LABELS.get(m, m),
            )
        paper = [PAPER_TABLE_II[c][paper_col] if c in PAPER_TABLE_II else math.nan for c in configs]
        ax.scatter(
            [x + len(ran) * width for x in xs],
            paper,
            marker="x",
            color="black",
            label="paper Ours",
            zorder=3,
        )
        ax.set_xticks([x + width * len(ran) / 2 for x in xs])
        ax.set_xticklabels(configs, rotation=30, ha="right")
        ax.set_ylabel(ylabel)
        ax.legend(fontsize=8)
        fig.tight_layout()
        path = directory / name
        fig.savefig(path, dpi=110)
        plt.close(fig)
        written.append(path)
    return written


def _rate_bar(c: Cell) -> tuple[float, float, float] | None:
    if c.rate is None or c.rate_ci is None:
        return None
    return 100 * c.rate, 100 * c.rate_ci[0], 100 * c.rate_ci[1]


def _time_bar(c: Cell) -> tuple[float, float, float] | None:
    if c.time_mean is None or c.time_ci is None:
        return None
    return c.time_mean, c.time_ci[0], c.time_ci[1]


def plot_flat(rows: Sequence[Mapping[str, Any]], path: Path) -> Path:
    """``suite_flat.png``: automaton states and planning time against the number of tasks."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (a1, a2) = plt.subplots(1, 2, figsize=(10, 3.6))
    n = [r["tasks"] for r in rows]
    for side, label in (("hier", "hltl (hierarchical)"), ("flat", "flat LTLf")):
        states = [r[side]["states"] if r[side]["status"] == "ok" else math.nan for r in rows]
        secs = [
            (r[side]["compile_s"] or 0) + (r[side]["plan_s"] or 0)
            if r[side]["status"] == "ok"
            else math.nan
            for r in rows
        ]
        a1.plot(n, states, marker="o", label=label)
        a2.plot(n, secs, marker="o", label=label)
    for ax, yl in ((a1, "automaton states (sum)"), (a2, "MONA + planning (s)")):
        ax.set_yscale("log")
        ax.set_xlabel("deliveries")
        ax.set_ylabel(yl)
        ax.legend(fontsize=8)
    fig.tight_layout()
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def suite_section(
    *,
    command: str,
    machine: str,
    wall_s: float,
    loop_cpu_s: float,
    n_loop_trials: int,
    table: str,
    modes: str,
    results: Sequence[TrialResult],
    configs: Sequence[str],
    sweep_rows: Sequence[Mapping[str, Any]],
    sweep_s: float,
    figures: Sequence[str],
    trials: int,
) -> str:
    """The Markdown body of docs/benchmarks.md's ``suite`` section."""
    parts = [
        f"Command: `{command}`  ",
        f"Machine: {machine}. Wall time {wall_s:.0f} s for {n_loop_trials} closed-loop trials "
        f"and the planning-only runs ({loop_cpu_s:.0f} s of worker time in the closed-loop "
        f"trials); the flat-LTLf growth sweep took {sweep_s:.0f} s more.",
    ]
    if trials < 100 and n_loop_trials:
        per = wall_s / trials
        parts.append(
            f"Estimated for `--trials 100` with the same methods: about {per * 100 / 60:.0f} min "
            f"(scaled linearly from this run; not measured)."
        )
    parts += [
        "",
        "Protocol, methods and metrics: [evaluation.md](evaluation.md). Seeds: trial *i* of "
        "every configuration has seed `100000·S + i` for suite seed *S*; the scenario "
        "generator, the events and the episode draw from it. Cells: value [95 % interval]; "
        "success rate with the Wilson interval, time cost (successful trials, seconds from the "
        "start to the last goal, including the injected task) and tokens per query with "
        "seeded percentile-bootstrap intervals. Italic columns are the paper's Table II, for "
        "reference. Whether its times include injected tasks is ambiguous (§V-A says its "
        "simulator injects new tasks during execution; Table II and its text name only the "
        "base tasks), so its times are not directly comparable with ours, which do.",
        "",
        "### Table II analogue",
        "",
        table,
        "",
        "### Failure modes caught by the shared checks (§V-D)",
        "",
        modes,
    ]
    fd = [r for r in results if r.method == "fd"]
    if fd:
        if all(r.status == "not_run" for r in fd):
            parts += ["", f"Fast Downward: not run ({fd[0].reason})."]
        else:
            parts += [
                "",
                "### Fast Downward (classical, sequential) beside hltl on the same instances",
                "",
                "Whole task of each trial (base deliveries and the GOAL delivery) from the "
                "initial world; FD `seq-opt` minimises the total robot time, hltl the makespan.",
                "",
                format_fd(results, configs),
            ]
    flat = [r for r in results if r.method == "flat" and r.status == "ok"]
    if flat:
        rows = []
        for c in configs:
            for r in flat:
                if r.config == c:
                    rows.append({**r.extra, "tasks": f"{c}#{r.index}"})
        parts += [
            "",
            "### Flat LTLf beside the hierarchical monitors",
            "",
            "Per configuration (whole task with the GOAL delivery):",
            "",
            format_flat(rows),
        ]
    if sweep_rows:
        parts += [
            "",
            "Growth: unordered deliveries on a 2×2 square, one automaton for everything versus "
            "hltl's monitors (at most four children per node), the flat side in a child "
            "process killed at the limit:",
            "",
            format_flat(sweep_rows),
        ]
    if figures:
        parts += ["", " ".join(f"![{f}](figures/{f})" for f in figures)]
    return "\n".join(parts)


def _pmp_text(pmp: PmpLatency | None) -> str:
    """How the ablation charged motion planning (docs/benchmarks.md's variants paragraph)."""
    if pmp is None:
        return (
            "the motion layer's candidate planning of each robot-to-robot handover in the new "
            "plan's first step, run there and then on the arms' models (Elfin-3, xArm6) from "
            "where the believed world has their hands, 8 candidate goal sets on a pool of 2 "
            "processes, one after the other w/o P.M.P., and charged as measured (wall clock; "
            "*motion ms/trial*); a request repeated from the same arm configurations reuses its "
            "plan"
        )
    return (
        "the motion layer's measured candidate planning of each robot-to-robot handover in "
        f"the new plan's first step — {pmp.parallel_s * 1e3:.0f} ms on {pmp.workers} "
        f"processes, {pmp.serial_s * 1e3:.0f} ms serially (w/o P.M.P.) for {pmp.candidates} "
        f"candidates (measured at load {pmp.load:.1f} by {pmp.source})"
    )


def ablation_section(
    *,
    command: str,
    machine: str,
    wall_s: float,
    table: str,
    n: int,
    configs: Sequence[str],
    trials: int,
    variants: Sequence[Variant],
    latency: LatencyModel | None,
    plan_latency: float | None,
    pmp: PmpLatency | None,
    groups: str = "",
) -> str:
    """The Markdown body of docs/benchmarks.md's ``ablation`` section."""
    if latency is None:
        charged = (
            f"every planner call costs a constant {plan_latency or 0.0:g} s of simulated time "
            "(assumed, not measured)"
        )
    else:
        charged = (
            f"computation is charged where it occurs from the measured latency model "
            f"({latency.describe()}; measured by {latency.source}): disruption replans in "
            "full, routine post-step replans only beyond the step they overlap, a predicted "
            "plan only for what remains of its background computation"
        )
    return "\n".join(
        [
            f"Command: `{command}`  ",
            f"Machine: {machine}. Wall time {wall_s:.0f} s for {n} episodes "
            f"({trials} trials × {len(configs)} configurations × {len(variants)} variants, the "
            "suite's trials with H-MOVE and GOAL).",
            "",
            f"Variants (see [evaluation.md](evaluation.md#ablations)): {charged}. *full*: "
            "predictive planning on (constant-velocity forecasts); *w/o P.P.*: prediction off; "
            "*w/o P.M.P.*: prediction on, candidate goal sets planned serially; every variant "
            f"charges, with a planner call, {_pmp_text(pmp)}; *goal-directed predictor*: "
            "full with the goal-directed forecasts; "
            "*+ anticipation*: anticipatory execution with the goal-directed or the learned "
            "(GRU) predictor. Fluency metrics over all trials (mean ± std, %), the paper's rows "
            "in italic; *time paired* averages the trials every variant solved.",
            "",
            table,
            *(["", groups] if groups else []),
        ]
    )
