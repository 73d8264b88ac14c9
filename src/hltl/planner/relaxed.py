"""Relaxed object-movement graph: earliest time each object can reach each place or event."""

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
        self._load: dict[tuple[int, int, Atom], list[float]] = {}
        self._head_tail: dict[tuple[int, int, Atom], tuple[list[float], float]] = {}
        self._dead: dict[Atom, frozenset[int]] = {}
        self._tables: dict[Atom, tuple[int, list[float]] | None] = {}

    def goal(self, atom: Atom) -> tuple[int, int | None] | None:
        """(object index, place code) for a state atom, (object index, None) for an event atom."""
        p = self.p
        name, args = atom.name, atom.args
        if name in ("delivered", "placed", "picked"):
            o = p.obj_index.get(args[0])
            return None if o is None else (o, None)
        if name == "holding":
            o, r = p.obj_index.get(args[1]), p.robot_index.get(args[0])
            return None if o is None or r is None else (o, p.held_code[r])
        if name == "at":
            o, code = p.obj_index.get(args[0]), p.loc_code.get(Loc("on", args[1]))
            return None if o is None or code is None else (o, code)
        return None

    def head_tail(self, atom: Atom, robot: int) -> tuple[list[float], float]:
        """For the atom's object and ``robot``: per place, the earliest time the robot can first
        act on it (head), and the least time the route to ``atom`` still needs after the robot
        last acts on it (tail)."""
        g = self.goal(atom)
        assert g is not None
        o, target = g
        key = (o, robot, atom)
        hit = self._head_tail.get(key)
        if hit is not None:
            return hit
        p = self.p
        n = len(p.locs)
        bit = 1 << robot
        dist = self.place_time[o]
        mine = [i for pre in range(n) for i in p.by_obj_pre[o][pre] if i.executors & bit]
        head = [min((dist[src][i.pre] for i in mine), default=INF) for src in range(n)]
        tail = INF
        for i in mine:
            if target is None:
                t = 0.0 if atom in i.events else self.event_time[o][i.post].get(atom, INF)
            else:
                t = dist[i.post][target]
            tail = min(tail, t)
        self._head_tail[key] = (head, tail)
        return head, tail

    def robot_load(self, atom: Atom, robot: int) -> list[float] | None:
        """Per place of the atom's object: the least time ``robot`` must spend acting on it on any
        route that makes ``atom`` true (0 unless every route needs that robot).

        Each action of one robot fills a step of its own lasting at least the action, so summed
        over the distinct objects a robot must handle this bounds the makespan from below.
        """
        g = self.goal(atom)
        if g is None:
            return None
        o, target = g
        key = (o, robot, atom)
        hit = self._load.get(key)
        if hit is not None:
            return hit
        p = self.p
        n = len(p.locs)
        bit = 1 << robot
        sink = n
        rev: list[list[tuple[int, float]]] = [[] for _ in range(n + 1)]
        for pre in range(n):
            for inst in p.by_obj_pre[o][pre]:
                w = inst.lower if inst.executors & bit else 0.0
                rev[inst.post].append((pre, w))
                if target is None and atom in inst.events:
                    rev[sink].append((pre, w))
        if target is not None:
            rev[sink].append((target, 0.0))
        dist = _dijkstra(rev, sink)[:n]
        self._load[key] = dist
        return dist

    def dead_instances(self, atom: Atom) -> frozenset[int]:
        """Indices of the instances after which ``atom`` can never hold: they move the atom's
        object to a place from which the atom is unreachable, without making it true on the way
        (e.g. handing the object to a person other than the one the atom names)."""
        hit = self._dead.get(atom)
        if hit is not None:
            return hit
        g = self.goal(atom)
        out: set[int] = set()
        if g is not None:
            o, target = g
            for pre in range(len(self.p.locs)):
                for inst in self.p.by_obj_pre[o][pre]:
                    if atom in inst.events:
                        continue
                    if target is None:
                        t = self.event_time[o][inst.post].get(atom, INF)
                    else:
                        t = self.place_time[o][inst.post][target]
                    if t == INF:
                        out.add(inst.index)
        res = frozenset(out)
        self._dead[atom] = res
        return res

    def atom_table(self, atom: Atom) -> tuple[int, list[float]] | None:
        """The atom's object and, per place of it, :meth:`atom_time` (``None``: no such object)."""
        hit = self._tables.get(atom, False)
        if hit is not False:
            return hit  # type: ignore[return-value]
        g = self.goal(atom)
        table: tuple[int, list[float]] | None = None
        if g is not None:
            o, target = g
            n = len(self.p.locs)
            if target is None:
                table = (o, [self.event_time[o][loc].get(atom, INF) for loc in range(n)])
            else:
                table = (o, [self.place_time[o][loc][target] for loc in range(n)])
        self._tables[atom] = table
        return table

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
