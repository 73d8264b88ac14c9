"""Pairwise lower bound: the exact makespan of every two-object subproblem."""

from __future__ import annotations

import heapq
import math

from hltl.planner.problem import Instance, Problem
from hltl.planner.relaxed import RelaxedGraph
from hltl.spec.syntax import Atom

INF = math.inf

# a subproblem state: (place of object 1, place of object 2, atom 1 done, atom 2 done)
_State = tuple[int, int, bool, bool]
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
        self._tables: dict[tuple[Atom, Atom], dict[_State, float] | None] = {}
        self._flat: dict[tuple[Atom, Atom], Lookup] = {}

    def lookups(self, atoms: list[Atom]) -> list[Lookup]:
        """For every pair of the atoms on different objects: what :func:`pair_value` needs."""
        out: list[Lookup] = []
        for i, a in enumerate(atoms):
            for b in atoms[i + 1 :]:
                key = (a, b) if a <= b else (b, a)
                table = self._tables.get(key, False)
                if table is False:
                    table = self._solve(*key)
                    self._tables[key] = table
                if table is None:
                    continue
                assert isinstance(table, dict)
                lk = self._flat.get(key)
                if lk is None:
                    lk = self._flatten(key, table)
                    self._flat[key] = lk
                out.append(lk)
        return out

    def _flatten(self, key: tuple[Atom, Atom], table: dict[_State, float]) -> Lookup:
        """The table read as it is used: one value per (place 1, place 2), the "has happened"
        flags set as the search sees them (a state atom that already holds is met by the next
        step, whatever it is; an event atom still needed has not happened)."""
        g1, g2 = self.graph.goal(key[0]), self.graph.goal(key[1])
        assert g1 is not None and g2 is not None
        (o1, t1), (o2, t2) = g1, g2
        n = len(self.p.locs)
        flat = [table.get((l1, l2, l1 == t1, l2 == t2), INF) for l1 in range(n) for l2 in range(n)]
        return (o1, o2, n, flat)

    def _solve(self, a1: Atom, a2: Atom) -> dict[_State, float] | None:
        g1, g2 = self.graph.goal(a1), self.graph.goal(a2)
        if g1 is None or g2 is None or g1[0] == g2[0]:
            return None
        p = self.p
        o1, t1 = g1
        o2, t2 = g2
        n = len(p.locs)
        holder = p.code_holder

        def free(inst: Instance, l1: int, l2: int) -> bool:
            busy = (holder.get(l1), holder.get(l2))
            return not any(r in busy for r in inst.free)

        def met(inst: Instance | None, atom: Atom, target: int | None, loc: int) -> bool:
            if target is None:
                return inst is not None and atom in inst.events
            return loc == target

        # forward edges of the whole subproblem, stored reversed
        rev: dict[_State, list[tuple[_State, float]]] = {}
        goals: list[_State] = []
        for l1 in range(n):
            for l2 in range(n):
                opts1: list[Instance | None] = [None]
                opts1 += [i for i in p.by_obj_pre[o1][l1] if free(i, l1, l2)]
                opts2: list[Instance | None] = [None]
                opts2 += [i for i in p.by_obj_pre[o2][l2] if free(i, l1, l2)]
                for i1 in opts1:
                    for i2 in opts2:
                        if i1 is None and i2 is None:
                            continue
                        if i1 is not None and i2 is not None and i1.executors & i2.executors:
                            continue
                        cost = max(i1.lower if i1 else 0.0, i2.lower if i2 else 0.0)
                        n1 = i1.post if i1 else l1
                        n2 = i2.post if i2 else l2
                        m1 = met(i1, a1, t1, n1)
                        m2 = met(i2, a2, t2, n2)
                        for s1 in (False, True):
                            for s2 in (False, True):
                                dst = (n1, n2, s1 or m1, s2 or m2)
                                rev.setdefault(dst, []).append(((l1, l2, s1, s2), cost))
                for s1 in (False, True):
                    for s2 in (False, True):
                        if s1 and s2:
                            goals.append((l1, l2, s1, s2))
        dist: dict[_State, float] = {}
        heap: list[tuple[float, _State]] = [(0.0, g) for g in goals]
        for g in goals:
            dist[g] = 0.0
        while heap:
            d, s = heapq.heappop(heap)
            if d > dist.get(s, INF):
                continue
            for prev, w in rev.get(s, ()):
                nd = d + w
                if nd < dist.get(prev, INF):
                    dist[prev] = nd
                    heapq.heappush(heap, (nd, prev))
        return dist
