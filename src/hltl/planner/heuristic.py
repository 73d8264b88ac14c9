"""Admissible heuristic: the earliest time the root monitor can fire, bottom-up over the tree.

Every predicate atom gets a lower bound on when it can first hold (the relaxed object graph).
A node can fire no earlier than the cheapest run of its DFA into acceptance, where a run costs
the latest of the times its symbols need (a symbol needs all of its true propositions, and a
child's proposition is the child firing). Runs combine with ``max``, never ``+``: parallel robots
may make everything happen at once, which keeps the bound admissible, and so A* stays exact.
"""

from __future__ import annotations

import heapq
import math
from collections.abc import Callable

from hltl.planner.problem import Node, Problem
from hltl.planner.relaxed import RelaxedGraph
from hltl.spec.automata import DFA
from hltl.spec.monitor import DONE
from hltl.spec.syntax import Atom

INF = math.inf


class Heuristic:
    """h(x) for the unified graph; call it on a search node."""

    def __init__(self, problem: Problem, done: Callable[[object], frozenset[str]]) -> None:
        self.p = problem
        self.graph = RelaxedGraph(problem)
        self.done = done
        mon = problem.monitor
        names = {name for name, _ in problem.spec.formulas}
        index = {n: i for i, n in enumerate(mon.nodes)}
        self.root = problem.spec.root
        # per node, deepest first: name, index in q, DFA, and per proposition either
        # ("child", name) or ("atom", Atom)
        self.nodes: list[tuple[str, int, DFA, tuple[tuple[str, object], ...]]] = []
        for name in reversed(mon.nodes):
            dfa = mon.dfas[name]
            props = tuple(
                ("child", a.name) if (not a.args and a.name in names) else ("atom", a)
                for a in dfa.props
            )
            self.nodes.append((name, index[name], dfa, props))
        self._cache: dict[tuple[str, int, tuple[float, ...]], float] = {}

    def __call__(self, node: Node) -> float:
        locs, _, q = node
        done = self.done(q)
        h: dict[str, float] = {}
        atom_time = self.graph.atom_time
        for name, i, dfa, props in self.nodes:
            state = q[i]
            if state == DONE:
                h[name] = 0.0
                continue
            costs: list[float] = []
            for kind, ref in props:
                if kind == "child":
                    assert isinstance(ref, str)
                    costs.append(INF if ref in done else h[ref])
                else:
                    assert isinstance(ref, Atom)
                    costs.append(atom_time(ref, locs))
            h[name] = self._bottleneck(name, dfa, state, tuple(costs))
            if name == self.root:
                break
        return h[self.root]

    def _bottleneck(self, name: str, dfa: DFA, start: int, costs: tuple[float, ...]) -> float:
        key = (name, start, costs)
        hit = self._cache.get(key)
        if hit is not None:
            return hit
        k = len(costs)
        width = 1 << k
        mask_cost = [0.0] * width
        for m in range(1, width):
            low = (m & -m).bit_length() - 1
            mask_cost[m] = max(mask_cost[m & (m - 1)], costs[low])
        table = dfa.table
        accepting = dfa.accepting
        best = INF
        dist: dict[int, float] = {start: 0.0}
        heap = [(0.0, start)]
        while heap:
            v, s = heapq.heappop(heap)
            if v > dist.get(s, INF) or v >= best:
                continue
            base = s * width
            for m in range(width):
                c = mask_cost[m]
                if c < v:
                    c = v
                if c >= best:
                    continue
                y = table[base + m]
                if y in accepting:
                    best = c
                if c < dist.get(y, INF):
                    dist[y] = c
                    heapq.heappush(heap, (c, y))
        self._cache[key] = best
        return best
