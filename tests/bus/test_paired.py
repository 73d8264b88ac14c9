"""Paired repeats: ABBA order, each pair's ratio, the median and its spread (no timing)."""

from __future__ import annotations

import statistics

import pytest
from hypothesis import given
from hypothesis import strategies as st

from hltl.bus.paired import (
    MIN_REPEATS,
    Pair,
    abba,
    format_ratios,
    format_spread,
    order_medians,
    paired_stats,
    quantile,
)

times = st.floats(0.01, 100.0, allow_nan=False, allow_infinity=False)


def _direct_quantile(values: list[float], q: float) -> float:
    """The inclusive quantile by its definition: rank q·(n−1) of the sorted values, between
    the two ranks around it linearly."""
    v = sorted(values)
    if len(v) == 1:
        return v[0]
    return statistics.quantiles(v, n=4, method="inclusive")[{0.25: 0, 0.5: 1, 0.75: 2}[q]]


@given(st.integers(1, 40))
def test_abba_alternates_which_side_goes_first(repeats: int) -> None:
    order = abba(repeats)
    assert len(order) == repeats and order[0] is False
    seq = "".join("BA" if b_first else "AB" for b_first in order)
    assert seq == ("ABBA" * repeats)[: 2 * repeats]
    # each side goes first in half the pairs (one more for A when the count is odd)
    assert order.count(False) - order.count(True) == repeats % 2


def test_abba_refuses_no_repeats() -> None:
    with pytest.raises(ValueError, match="at least 1, got 0"):
        abba(0)


@given(st.lists(st.tuples(times, times), min_size=1, max_size=30))
def test_the_statistics_match_a_direct_computation(walls: list[tuple[float, float]]) -> None:
    pairs = [Pair(a, b, k % 2 == 1, a) for k, (a, b) in enumerate(walls)]
    s = paired_stats(pairs)
    ratios = [(b / a - 1) * 100 for a, b in walls]
    assert s.n == len(walls) and s.pairs == tuple(pairs)
    assert s.median_ratio == pytest.approx(statistics.median(ratios))
    assert s.min_ratio == pytest.approx(min(ratios)) and s.max_ratio == pytest.approx(max(ratios))
    assert s.q1_ratio == pytest.approx(_direct_quantile(ratios, 0.25))
    assert s.q3_ratio == pytest.approx(_direct_quantile(ratios, 0.75))
    assert s.min_ratio <= s.q1_ratio <= s.median_ratio <= s.q3_ratio <= s.max_ratio
    assert s.a_median_s == statistics.median(a for a, _ in walls)
    assert s.b_median_s == statistics.median(b for _, b in walls)
    assert s.judged == (len(walls) >= MIN_REPEATS)
    assert s.a_on_core == pytest.approx(1.0)
    a_first, b_first = order_medians(s)
    assert a_first == pytest.approx(statistics.median(ratios[0::2]))
    if len(walls) > 1:
        assert b_first == pytest.approx(statistics.median(ratios[1::2]))
    else:
        assert b_first is None


@given(st.lists(st.floats(-1e6, 1e6, allow_nan=False), min_size=1, max_size=30), st.floats(0, 1))
def test_quantile_is_the_inclusive_method(values: list[float], q: float) -> None:
    v = sorted(values)
    got = quantile(v, q)
    assert v[0] - 1e-6 <= got <= v[-1] + 1e-6
    if len(v) > 1:  # against numpy's default (linear), written out
        pos = q * (len(v) - 1)
        lo, hi = int(pos), min(int(pos) + 1, len(v) - 1)
        assert got == pytest.approx(v[lo] * (1 - (pos - lo)) + v[hi] * (pos - lo), abs=1e-6)


def test_the_median_of_ratios_is_not_the_ratio_of_medians() -> None:
    # session 23's three idle reruns: +27.7, +0.5, +7.3 %
    s = paired_stats([Pair(2.04, 2.61), Pair(2.60, 2.62, True), Pair(2.57, 2.76)])
    assert [round(p.ratio, 1) for p in s.pairs] == [27.9, 0.8, 7.4]
    assert round(s.median_ratio, 1) == 7.4 and not s.judged
    assert format_ratios(s, "bus first") == "+27.9, +0.8 (bus first), +7.4"
    assert format_spread(s) == "+7.4 % (min–max +0.8 – +27.9 %; IQR +4.1 – +17.7 %)"


def test_bad_input_is_refused() -> None:
    with pytest.raises(ValueError, match="no pairs"):
        paired_stats([])
    with pytest.raises(ValueError, match=r"between 0 and 1, got 1\.5"):
        quantile([1.0], 1.5)
