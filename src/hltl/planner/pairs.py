"""Pairwise lower bound: the exact makespan of every two-object subproblem."""

from __future__ import annotations

import heapq
import math
from typing import Any

from hltl.planner.problem import Problem
from hltl.planner.relaxed import RelaxedGraph
from hltl.spec.syntax import Atom

INF = math.inf

# (object 1, object 2, number of places n, value at index place1 * n + place2)
Lookup = tuple[int, int, int, list[float]]


def pair_value(lookup: Lookup, locs: tuple[int, ...]) -> float:
    """Least makespan in which both atoms of the pair can have held, from places ``locs``."""
    o1, o2, n, flat = lookup
    return flat[locs[o1] * n + locs[o2]]


class PairBound:
    """Memoised optimal makespans of two-atom subproblems, one table per atom pair."""

    def __init__(self, problem: Problem, graph: RelaxedGraph) -> None:
        self.p = problem
        self.graph = graph
        self._flat: dict[tuple[Atom, Atom], Lookup | None] = {}

    def lookups(self, atoms: list[Atom]) -> list[Lookup]:
        """For every pair of the atoms on different objects: what :func:`pair_value` needs."""
        out: list[Lookup] = []
        for i, a in enumerate(atoms):
            for b in atoms[i + 1 :]:
                key = (a, b) if a <= b else (b, a)
                if key in self._flat:
                    lk = self._flat[key]
                else:
                    lk = self._flat[key] = self._solve(*key)
                if lk is not None:
                    out.append(lk)
        return out

    def _solve(self, a1: Atom, a2: Atom) -> Lookup | None:
        """The pair's table, read as it is used: one value per (place 1, place 2), the "has
        happened" flags set as the search sees them (a state atom that already holds is met by
        the next step, whatever it is; an event atom still needed has not happened). One
        backward Dijkstra from every state where both atoms have happened, over states
        numbered ((place 1 x n + place 2) x 4 + flags); a move of the two objects is stored
        once per pair of places and read with every pair of flags it leads from."""
        g1, g2 = self.graph.goal(a1), self.graph.goal(a2)
        if g1 is None or g2 is None or g1[0] == g2[0]:
            return None
        p = self.p
        o1, t1 = g1
        o2, t2 = g2
        n = len(p.locs)
        holder = p.code_holder
        held = [holder.get(loc) for loc in range(n)]

        def moves(o: int, atom: Atom, target: int | None) -> list[list[tuple[Any, ...]]]:
            # per place: (robots that must be free, executors, duration, place after, whether
            # the atom happens) of each instance of the object there
            return [
                [
                    (
                        i.free,
                        i.executors,
                        i.lower,
                        i.post,
                        atom in i.events if target is None else i.post == target,
                    )
                    for i in p.by_obj_pre[o][loc]
                ]
                for loc in range(n)
            ]

        moves1 = moves(o1, a1, t1)
        moves2 = moves(o2, a2, t2)
        # per pair of places after a move: (pair of places before, atom 1 happens, atom 2
        # happens, duration)
        rev: list[list[tuple[int, bool, bool, float]]] = [[] for _ in range(n * n)]
        for l1 in range(n):
            stay1 = (None, 0, 0.0, l1, l1 == t1)
            for l2 in range(n):
                busy = (held[l1], held[l2])
                opts1 = [stay1] + [m for m in moves1[l1] if not any(r in busy for r in m[0])]
                opts2 = [(None, 0, 0.0, l2, l2 == t2)]
                opts2 += [m for m in moves2[l2] if not any(r in busy for r in m[0])]
                src = l1 * n + l2
                for k1, (_, e1, d1, n1, m1) in enumerate(opts1):
                    base = n1 * n
                    for k2, (_, e2, d2, n2, m2) in enumerate(opts2):
                        if k1 == 0 and k2 == 0:
                            continue
                        if k1 and k2 and e1 & e2:
                            continue
                        rev[base + n2].append((src, m1, m2, d1 if d1 > d2 else d2))
        dist = [INF] * (4 * n * n)
        heap: list[tuple[float, int]] = []
        for pos in range(n * n):
            dist[4 * pos + 3] = 0.0
            heap.append((0.0, 4 * pos + 3))
        while heap:
            d, s = heapq.heappop(heap)
            if d > dist[s]:
                continue
            pos, flags = divmod(s, 4)
            h1, h2 = flags >> 1, flags & 1
            for src, m1, m2, w in rev[pos]:
                # the flags before: a flag set after the move was set before it or by it
                if (m1 and not h1) or (m2 and not h2):
                    continue
                nd = d + w
                for s1 in (0, 1) if m1 else (h1,):
                    for s2 in (0, 1) if m2 else (h2,):
                        prev = 4 * src + 2 * s1 + s2
                        if nd < dist[prev]:
                            dist[prev] = nd
                            heapq.heappush(heap, (nd, prev))
        flat = [
            dist[4 * (l1 * n + l2) + 2 * (l1 == t1) + (l2 == t2)]
            for l1 in range(n)
            for l2 in range(n)
        ]
        return (o1, o2, n, flat)
