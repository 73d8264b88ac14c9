"""The report writer: intervals against known values, Table II/III layout, failure modes."""

from __future__ import annotations

import statistics

import pytest

from hltl.bench.report import (
    PAPER_TABLE_II,
    bootstrap_ci,
    failure_modes,
    fluency,
    format_failure_modes,
    format_table_ii,
    format_table_iii,
    summarise,
    wilson,
)
from hltl.bench.suite import TrialResult
from hltl.sim.dynamic import config_names


@pytest.mark.parametrize(
    ("k", "n", "lo", "hi"),
    [
        (0, 10, 0.0, 0.2775),  # the textbook cases (Wilson 1927; Newcombe 1998, table I)
        (10, 10, 0.7225, 1.0),
        (5, 10, 0.2366, 0.7634),
        (81, 263, 0.2553, 0.3662),
        (1, 29, 0.0061, 0.1718),
        (29, 29, 0.8830, 1.0),
    ],
)
def test_wilson_interval_matches_published_values(k: int, n: int, lo: float, hi: float) -> None:
    got = wilson(k, n)
    assert got == pytest.approx((lo, hi), abs=6e-5)


def test_wilson_rejects_impossible_counts() -> None:
    for k, n in ((0, 0), (3, 2), (-1, 5)):
        with pytest.raises(ValueError, match="0 <= k <= n"):
            wilson(k, n)


def test_bootstrap_is_seeded_and_brackets_the_mean() -> None:
    xs = [1.0, 2.0, 2.5, 3.0, 4.5, 5.0, 7.0]
    a = bootstrap_ci(xs, seed=3)
    assert a == bootstrap_ci(xs, seed=3)
    assert a != bootstrap_ci(xs, seed=4)
    assert a[0] < statistics.fmean(xs) < a[1]
    assert a[0] >= min(xs) and a[1] <= max(xs)
    assert bootstrap_ci([2.0, 2.0, 2.0]) == (2.0, 2.0)
    with pytest.raises(ValueError):
        bootstrap_ci([])


def _r(
    method: str,
    config: str,
    i: int,
    *,
    ok: bool = True,
    t: float | None = 2.0,
    tokens: int = 0,
    queries: int = 0,
    status: str = "ok",
    **kw: object,
) -> TrialResult:
    return TrialResult(
        method,
        config,
        i,
        i,
        status,
        success=ok,
        goals_met=ok,
        time_cost=t if ok else None,
        tokens=tokens,
        queries=queries,
        **kw,
    )  # type: ignore[arg-type]


def test_summary_counts_successes_and_averages_successful_times() -> None:
    rs = [
        _r("hltl", "2-2", 0, t=2.0, tokens=600, queries=2),
        _r("hltl", "2-2", 1, t=4.0, tokens=800, queries=2),
        _r("hltl", "2-2", 2, ok=False, tokens=300, queries=1),
        _r("hltl", "2-2", 3, ok=False, status="error", reason="boom"),
        _r("smart-llm", "2-2", 0, status="not_run", reason="no LLM configured"),
    ]
    cells = summarise(rs)
    c = cells[("hltl", "2-2")]
    assert (c.n, c.successes, c.errors, c.status) == (4, 2, 1, "error")
    assert c.rate_ci == wilson(2, 4)
    assert c.time_mean == 3.0
    assert c.tokens_mean == pytest.approx((300 + 400 + 300) / 3)
    assert cells[("smart-llm", "2-2")].status == "not_run"


def test_table_ii_layout() -> None:
    configs = list(config_names())
    rs = [_r("hltl", c, i) for c in configs for i in range(3)]
    rs += [_r("smart-llm", c, 0, status="not_run", reason="x") for c in configs]
    table = format_table_ii(summarise(rs), configs, ["hltl", "greedy", "smart-llm"])
    lines = table.splitlines()
    header = [h.strip() for h in lines[0].strip("|").split("|")]
    # config, 3 metrics x (3 methods + 2 paper columns), plus the o200k estimate column
    assert len(header) == 1 + 3 * 5 + 1
    assert header[:6] == [
        "Tasks–Robots",
        "SR % hltl",
        "SR % Greedy-R",
        "SR % SMART-LLM-R",
        "SR % *paper Ours*",
        "SR % *paper SMART-LLM-R*",
    ]
    rows = [ln for ln in lines[2:] if ln.strip("| ")]
    assert [r.split("|")[1].strip() for r in rows] == configs
    assert all(len(r.strip("|").split("|")) == len(header) for r in lines[2:])
    # blank separators between robot counts, like the paper's rules: 1 | 2 | 4-line | 4-square
    assert len(lines) - 2 - len(rows) == 2
    row = next(r for r in rows if r.startswith("| 4-4-line |"))
    cells = [x.strip() for x in row.strip("|").split("|")]
    assert cells[1] == "100 [44, 100]"  # 3/3 with its Wilson interval
    assert cells[2] == "–" or cells[2] == "not run"
    assert cells[3] == "not run"
    paper = PAPER_TABLE_II["4-4-line"]
    assert cells[4:6] == [f"*{paper[0]:.0f}*", f"*{paper[1]:.0f}*"]
    assert cells[6] == "2.00 [2.00, 2.00]"
    assert "*19.4*" in cells and "*7385*" in cells


def test_table_iii_has_our_rows_beside_the_papers() -> None:
    rs = [
        _r(
            "hltl",
            "2-2",
            i,
            variant=v,
            h_idle=50.0 + i,
            r_idle=30.0,
            c_act=60.0,
            f_del=-1.0,
            f_del_union=-0.5,
            c_act_hr=20.0,
        )
        for v in ("full", "no-pp", "no-pmp")
        for i in range(3)
    ]
    stats = fluency(rs)
    assert stats["full"]["h_idle"] == (51.0, 1.0, 3)
    table = format_table_iii(stats, {"full": {"time cost s": 2.5}})
    # the paper's four columns, then F-DEL as a union, human-robot C-ACT, and H-IDLE with
    # walking counted (absent from these results: "–")
    assert (
        "| hltl full | 51.0 ± 1.0 | 30.0 ± 0.0 | 60.0 ± 0.0 | -1.0 ± 0.0 | -0.5 ± 0.0 "
        "| 20.0 ± 0.0 | – | 2.5 |" in table
    )
    assert (
        "| *paper full* | *67.1 ± 17.2* | *38.8 ± 10.1* | *64.9 ± 11.9* | *-4.5 ± 8.6* |" in table
    )
    assert table.count("\n") == 1 + 3 + 3


def test_failure_modes_count_what_the_checks_caught() -> None:
    rs = [
        _r("greedy", "2-2", 0, violations=1),
        _r("smart-llm", "2-2", 0, ok=False, kinematic=2, conflicts=1, violations=3, stale=1),
        _r("smart-llm", "2-2", 1, ok=False, status="error", reason="boom"),
        _r("hltl", "2-2", 0, invariant_problems=0),
    ]
    modes = failure_modes(rs)
    assert modes["smart-llm"] == {
        "trials": 2,
        "ran": 2,
        "kinematic": 2,
        "conflict": 1,
        "stale": 1,
        "physical": 0,
        "invariants": 0,
        "errors": 1,
    }
    assert modes["greedy"]["physical"] == 1
    text = format_failure_modes(modes, {})
    assert "| SMART-LLM-R | 2 | 2 | 1 | 1 | 0 | 0 | 1 |" in text
    not_run = failure_modes([_r("smart-llm", "1-1", 0, status="not_run", reason="no LLM")])
    assert "not run: no LLM" in format_failure_modes(not_run, {"smart-llm": "no LLM"})
