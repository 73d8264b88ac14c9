"""People walk round the work table: the shortest walk keeping clear of a floor rectangle."""

from __future__ import annotations

import heapq
import math
from collections.abc import Sequence
from dataclasses import dataclass

from hltl.world.scene import Vec3

_EPS = 1e-9


@dataclass(frozen=True, slots=True)
class Rect:
    """An axis-aligned rectangle on the floor (x0 ≤ x1, y0 ≤ y1), metres."""

    x0: float
    x1: float
    y0: float
    y1: float

    def __post_init__(self) -> None:
        vals = (self.x0, self.x1, self.y0, self.y1)
        if not all(math.isfinite(v) for v in vals) or self.x0 > self.x1 or self.y0 > self.y1:
            raise ValueError(f"a rectangle needs finite x0 <= x1 and y0 <= y1, got {vals}")

    def grown(self, margin: float) -> Rect:
        return Rect(self.x0 - margin, self.x1 + margin, self.y0 - margin, self.y1 + margin)

    def margin(self, p: Sequence[float]) -> float:
        """The most the rectangle can grow on every side without covering ``p`` (0 inside)."""
        return max(self.x0 - p[0], p[0] - self.x1, self.y0 - p[1], p[1] - self.y1, 0.0)

    def corners(self) -> tuple[tuple[float, float], ...]:
        return ((self.x0, self.y0), (self.x1, self.y0), (self.x1, self.y1), (self.x0, self.y1))

    def crosses(self, a: Sequence[float], b: Sequence[float]) -> bool:
        """True when the segment a→b passes through the rectangle's open interior
        (Liang–Barsky clipping; running along an edge or touching a corner does not count)."""
        lo, hi = 0.0, 1.0
        dx, dy = b[0] - a[0], b[1] - a[1]
        for p, q in (
            (-dx, a[0] - self.x0),
            (dx, self.x1 - a[0]),
            (-dy, a[1] - self.y0),
            (dy, self.y1 - a[1]),
        ):
            if abs(p) < _EPS:
                if q <= _EPS:  # parallel to this edge and on or outside it
                    return False
                continue
            r = q / p
            if p < 0:
                lo = max(lo, r)
            else:
                hi = min(hi, r)
            if lo > hi:
                return False
        # inside for a stretch of positive length (not a corner graze or an edge run)
        length = math.hypot(dx, dy)
        if (hi - lo) * length <= 1e-6:
            return False
        mid = (a[0] + dx * (lo + hi) / 2, a[1] + dy * (lo + hi) / 2)
        return self.x0 + _EPS < mid[0] < self.x1 - _EPS and self.y0 + _EPS < mid[1] < self.y1 - _EPS


def route_around(table: Rect, start: Vec3, to: Vec3, clearance: float) -> list[Vec3]:
    """The points of the shortest walk from ``start`` to ``to`` (``to`` last) that keeps
    ``clearance`` from ``table``: straight when that is clear, else around the corners of the
    table grown by the clearance. The clearance shrinks to what the two ends allow (the most
    the table can grow without covering them: a person standing closer to the table than
    ``clearance`` keeps that much); an end on or against the table (within 1 mm) gets the straight
    walk, and a clearance of 0 walks along the table's edges."""
    if not math.isfinite(clearance) or clearance < 0:
        raise ValueError(f"clearance must be a finite number >= 0, got {clearance!r}")
    ends = min(table.margin(start), table.margin(to))
    if ends <= 1e-3:  # an end on or against the table: nothing to keep clear of
        return [to]
    room = min(clearance, ends)  # a small clearance still walks round, keeping that much
    keep = table.grown(room * (1.0 - 1e-6))  # the walk may run along keep's edges
    if not keep.crosses(start, to):
        return [to]
    nodes: list[tuple[float, float]] = [(start[0], start[1]), (to[0], to[1])]
    nodes += table.grown(room).corners()
    n = len(nodes)
    best = [math.inf] * n
    prev = [-1] * n
    best[0] = 0.0
    heap = [(0.0, 0)]
    while heap:
        d, i = heapq.heappop(heap)
        if d > best[i] or i == 1:
            continue
        for j in range(1, n):
            if j == i or keep.crosses(nodes[i], nodes[j]):
                continue
            nd = d + math.dist(nodes[i], nodes[j])
            if nd < best[j] - _EPS:
                best[j], prev[j] = nd, i
                heapq.heappush(heap, (nd, j))
    if not math.isfinite(best[1]):  # cannot happen around one convex rectangle
        return [to]
    path: list[Vec3] = []
    j = 1
    while j != 0:
        path.append(to if j == 1 else (nodes[j][0], nodes[j][1], to[2]))
        j = prev[j]
    path.reverse()
    return path
