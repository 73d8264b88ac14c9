"""Paired repeated timings: ABBA order, each pair's ratio, their median and spread."""

from __future__ import annotations

import statistics
from collections.abc import Sequence
from dataclasses import dataclass

# A wall-time target between two runs of the same work (a baseline A and a variant B) is
# judged on the median ratio of at least this many pairs: one pair's ratio spreads by ±15
# points on the shared host (docs/benchmarks.md, "Bus").
MIN_REPEATS = 5


def abba(repeats: int) -> tuple[bool, ...]:
    """For each of ``repeats`` pairs, whether the variant B runs first: A B, B A, A B, … (the
    sequence A B B A A B …), so a drift of the host's speed within the run, or a warm-up the
    first run of a pair gives the second, favours neither side."""
    if repeats < 1:
        raise ValueError(f"repeats must be at least 1, got {repeats}")
    return tuple(k % 2 == 1 for k in range(repeats))


@dataclass(frozen=True, slots=True)
class Pair:
    """One repeat: the baseline's and the variant's wall time, and which ran first."""

    a_s: float
    b_s: float
    b_first: bool = False
    a_cpu_s: float = 0.0  # the baseline's CPU time (whether it ran on a core, not waiting)

    @property
    def ratio(self) -> float:
        """How much slower the variant was, in percent of the baseline (negative: faster)."""
        return (self.b_s / self.a_s - 1) * 100 if self.a_s > 0 else 0.0


def quantile(sorted_values: Sequence[float], q: float) -> float:
    """The ``q`` quantile (0 ≤ q ≤ 1) of sorted values, interpolated linearly between the two
    nearest ranks (``statistics.quantiles``' "inclusive" method, numpy's default)."""
    if not sorted_values:
        raise ValueError("no values")
    if not 0.0 <= q <= 1.0:
        raise ValueError(f"quantile must be between 0 and 1, got {q}")
    pos = q * (len(sorted_values) - 1)
    lo = int(pos)
    hi = min(lo + 1, len(sorted_values) - 1)
    return sorted_values[lo] + (sorted_values[hi] - sorted_values[lo]) * (pos - lo)


@dataclass(frozen=True, slots=True)
class PairedStats:
    """The pairs of a repeated paired measurement and what is judged on them."""

    pairs: tuple[Pair, ...]
    median_ratio: float  # percent: the median of the pairs' ratios (not a ratio of medians)
    min_ratio: float
    max_ratio: float
    q1_ratio: float  # the interquartile range of the ratios
    q3_ratio: float
    a_median_s: float
    b_median_s: float

    @property
    def n(self) -> int:
        return len(self.pairs)

    @property
    def judged(self) -> bool:
        """Enough pairs for the median to judge a target (:data:`MIN_REPEATS`)."""
        return self.n >= MIN_REPEATS

    @property
    def a_on_core(self) -> float:
        """The baseline's CPU time over its wall time, over every pair."""
        wall = sum(p.a_s for p in self.pairs)
        return sum(p.a_cpu_s for p in self.pairs) / wall if wall > 0 else 0.0


def paired_stats(pairs: Sequence[Pair]) -> PairedStats:
    """The median ratio of ``pairs``, its spread (min–max, interquartile range) and the two
    sides' median wall times."""
    if not pairs:
        raise ValueError("no pairs")
    ratios = sorted(p.ratio for p in pairs)
    return PairedStats(
        tuple(pairs),
        statistics.median(ratios),
        ratios[0],
        ratios[-1],
        quantile(ratios, 0.25),
        quantile(ratios, 0.75),
        statistics.median(p.a_s for p in pairs),
        statistics.median(p.b_s for p in pairs),
    )


def order_medians(s: PairedStats) -> tuple[float | None, float | None]:
    """The median ratio of the pairs where the baseline ran first, and of those where the
    variant did (``None`` without such a pair): far apart, the order matters, and an odd count
    of pairs leans the overall median towards the baseline-first pairs."""
    firsts = [p.ratio for p in s.pairs if not p.b_first], [p.ratio for p in s.pairs if p.b_first]
    a, b = (statistics.median(r) if r else None for r in firsts)
    return a, b


def format_ratios(s: PairedStats, first: str = "B first") -> str:
    """Each pair's ratio in run order, marked ``(B first)`` where the variant ran first."""
    return ", ".join(f"{p.ratio:+.1f}{f' ({first})' if p.b_first else ''}" for p in s.pairs)


def format_spread(s: PairedStats) -> str:
    """``+4.7 % (min–max +0.5 – +27.7 %; IQR +3.1 – +7.3 %)``."""
    return (
        f"{s.median_ratio:+.1f} % (min–max {s.min_ratio:+.1f} – {s.max_ratio:+.1f} %; "
        f"IQR {s.q1_ratio:+.1f} – {s.q3_ratio:+.1f} %)"
    )
