"""Relaxed object-movement graph: earliest time each object can reach each place or event.

The relaxation drops the "receiver is free" preconditions and the interaction between objects,
so every time it gives is a lower bound on the real one: the basis of the admissible heuristic
and of infeasibility explanations.
"""

from __future__ import annotations

import heapq
import math

from hltl.planner.problem import Problem
from hltl.spec.syntax import Atom
from hltl.world.state import Loc

INF = math.inf


class RelaxedGraph:
    """For each object: shortest times between places and from each place to each event atom."""

    def __init__(self, problem: Problem) -> None:
        self.p = problem
        n = len(problem.locs)
        self.place_time: list[list[list[float]]] = []
        self.event_time: list[list[dict[Atom, float]]] = []
        for o in range(len(problem.objects)):
            edges: list[list[tuple[int, float]]] = [[] for _ in range(n)]
            producers: list[tuple[int, float, frozenset[Atom]]] = []
            for pre in range(n):
                for inst in problem.by_obj_pre[o][pre]:
                    edges[pre].append((inst.post, inst.lower))
                    if inst.events:
                        producers.append((pre, inst.lower, inst.events))
            dist = [_dijkstra(edges, src) for src in range(n)]
            self.place_time.append(dist)
            ev: list[dict[Atom, float]] = []
            for src in range(n):
                best: dict[Atom, float] = {}
                for pre, d, atoms in producers:
                    t = dist[src][pre] + d
                    for a in atoms:
                        if t < best.get(a, INF):
                            best[a] = t
                ev.append(best)
            self.event_time.append(ev)

    def atom_time(self, atom: Atom, locs: tuple[int, ...]) -> float:
        """Earliest time (lower bound) at which ``atom`` can be true in a step's symbol."""
        p = self.p
        name, args = atom.name, atom.args
        if name in ("delivered", "placed", "picked"):
            o = p.obj_index.get(args[0])
            if o is None:
                return INF
            return self.event_time[o][locs[o]].get(atom, INF)
        if name == "holding":
            o = p.obj_index.get(args[1])
            r = p.robot_index.get(args[0])
            if o is None or r is None:
                return INF
            return self.place_time[o][locs[o]][p.held_code[r]]
        if name == "at":
            o = p.obj_index.get(args[0])
            code = p.loc_code.get(Loc("on", args[1]))
            if o is None or code is None:
                return INF
            return self.place_time[o][locs[o]][code]
        return INF


def _dijkstra(edges: list[list[tuple[int, float]]], src: int) -> list[float]:
    dist = [INF] * len(edges)
    dist[src] = 0.0
    heap = [(0.0, src)]
    while heap:
        d, u = heapq.heappop(heap)
        if d > dist[u]:
            continue
        for v, w in edges[u]:
            nd = d + w
            if nd < dist[v]:
                dist[v] = nd
                heapq.heappush(heap, (nd, v))
    return dist
