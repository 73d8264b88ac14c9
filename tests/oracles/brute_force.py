"""Exhaustive uniform-cost search over (object locations, monitor state): the optimality oracle.

Every step is every set of applicable skill instances with disjoint robots and distinct objects,
the empty step included (cost 0); there is no heuristic and no pruning beyond a closed set. Ties
in makespan are broken by the number of actions, so returned plans carry no idle-time busywork.
Meant for tiny problems (at most about 3 robots and 3 objects) with fixed ``durations``.
"""

from __future__ import annotations

import heapq
import itertools
import math
from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass
from typing import Any

from hltl.spec.syntax import Atom
from hltl.world.scene import Scene

from .model import (
    REST,
    Hierarchy,
    Location,
    can_hand_over,
    effect,
    event_atom,
    fire_steps,
    hierarchy,
    human_inside,
    mentions,
    point_of,
    reaches,
    state_atoms,
    surface_point,
)


class SearchBudgetExceeded(RuntimeError):
    """The search expanded ``max_nodes`` nodes without settling the question."""


@dataclass(frozen=True, order=True)
class Instance:
    """A grounded skill instance; ``target`` is the human or surface, ``""`` when none."""

    skill: str
    robots: tuple[str, ...]
    object: str
    target: str = ""

    def to_json(self) -> dict[str, Any]:
        out: dict[str, Any] = {
            "skill": self.skill,
            "robots": list(self.robots),
            "object": self.object,
        }
        if self.skill == "place":
            out["surface"] = self.target
        elif self.skill == "handover_r2h":
            out["human"] = self.target
        return out


def fixed_durations(scene: Scene) -> dict[str, float]:
    fixed = scene.duration_map()
    missing = [
        s for s in ("pick", "place", "handover_r2r", "handover_r2h") if s not in (fixed or {})
    ]
    if fixed is None or missing:
        raise ValueError(f"the oracles need fixed durations for every skill; missing: {missing}")
    return fixed


def applicable(scene: Scene, locs: Sequence[Location]) -> list[Instance]:
    """Every skill instance whose precondition holds in the state ``locs`` (scene object order)."""
    held = {
        where: obj.id
        for obj, (kind, where) in zip(scene.objects, locs, strict=True)
        if kind == "held"
    }
    out: list[Instance] = []
    for obj, loc in zip(scene.objects, locs, strict=True):
        point = point_of(scene, obj.id, loc)
        if point is not None:
            out += [
                Instance("pick", (r.id,), obj.id)
                for r in scene.robots
                if r.id not in held and reaches(r, point)
            ]
        if loc[0] != "held":
            continue
        holder = scene.robot(loc[1])
        out += [
            Instance("place", (holder.id,), obj.id, s.id)
            for s in scene.surfaces
            if reaches(holder, surface_point(scene, s.id))
        ]
        out += [
            Instance("handover_r2r", (holder.id, r.id), obj.id)
            for r in scene.robots
            if r.id not in held and can_hand_over(scene, holder, r)
        ]
        out += [
            Instance("handover_r2h", (holder.id,), obj.id, u.id)
            for u in scene.humans
            if human_inside(holder, u, scene.human_reach)
        ]
    return sorted(out)


def step_sets(instances: Sequence[Instance]) -> Iterator[tuple[Instance, ...]]:
    """Every subset of ``instances`` with pairwise disjoint robots and distinct objects."""

    def grow(
        i: int, robots: frozenset[str], objects: frozenset[str]
    ) -> Iterator[tuple[Instance, ...]]:
        if i == len(instances):
            yield ()
            return
        yield from grow(i + 1, robots, objects)
        a = instances[i]
        if robots.isdisjoint(a.robots) and a.object not in objects:
            for rest in grow(i + 1, robots | set(a.robots), objects | {a.object}):
                yield (a, *rest)

    yield from grow(0, frozenset(), frozenset())


def apply_step(
    scene: Scene, locs: Sequence[Location], step: Sequence[Instance]
) -> tuple[tuple[Location, ...], frozenset[Atom]]:
    """The next state and the step's symbol (event atoms plus the state atoms after the step)."""
    index = {o.id: i for i, o in enumerate(scene.objects)}
    nxt = list(locs)
    events: set[Atom] = set()
    for a in step:
        js = a.to_json()
        nxt[index[a.object]] = effect(js)
        ev = event_atom(js)
        if ev is not None:
            events.add(ev)
    return tuple(nxt), frozenset(events) | state_atoms(scene, nxt)


def optimal_plan(
    scene: Scene, spec: Any, max_cost: float = math.inf, max_nodes: int = 200_000
) -> dict[str, Any] | None:
    """A minimum-makespan plan in DESIGN.md's JSON format; None if no plan costs <= ``max_cost``.

    Raises:
        SearchBudgetExceeded: more than ``max_nodes`` nodes were expanded.
        ValueError: the scene lacks fixed durations.
    """
    from hltl.spec.monitor import HierarchyMonitor

    fixed = fixed_durations(scene)
    monitor = HierarchyMonitor(spec)
    start: tuple[Any, ...] = (tuple(REST for _ in scene.objects), monitor.initial, False)
    best: dict[tuple[Any, ...], tuple[float, int]] = {start: (0.0, 0)}
    parent: dict[tuple[Any, ...], tuple[tuple[Any, ...], tuple[Instance, ...], float]] = {}
    closed: set[tuple[Any, ...]] = set()
    counter = itertools.count()
    heap: list[tuple[float, int, int, tuple[Any, ...]]] = [(0.0, 0, next(counter), start)]
    expanded = 0
    while heap:
        cost, n_actions, _, key = heapq.heappop(heap)
        if key in closed:
            continue
        closed.add(key)
        locs, q, started = key
        if started and monitor.accepted(q):
            return _plan_json(scene, hierarchy(spec), _path(parent, key), cost, expanded)
        expanded += 1
        if expanded > max_nodes:
            raise SearchBudgetExceeded(f"brute force expanded more than {max_nodes} nodes")
        for step in step_sets(applicable(scene, locs)):
            duration = max((fixed[a.skill] for a in step), default=0.0)
            new_cost = round(cost + duration, 9)
            if new_cost > max_cost + 1e-9:
                continue
            nlocs, symbol = apply_step(scene, locs, step)
            nkey = (nlocs, monitor.step(q, symbol), True)
            if nkey in closed:
                continue
            cand = (new_cost, n_actions + len(step))
            if nkey not in best or cand < best[nkey]:
                best[nkey] = cand
                parent[nkey] = (key, step, duration)
                heapq.heappush(heap, (cand[0], cand[1], next(counter), nkey))
    return None


def optimal_makespan(
    scene: Scene, spec: Any, max_cost: float = math.inf, max_nodes: int = 200_000
) -> float | None:
    """The minimum makespan; None when no plan costs <= ``max_cost`` (infeasible if unbounded)."""
    plan = optimal_plan(scene, spec, max_cost=max_cost, max_nodes=max_nodes)
    return None if plan is None else float(plan["makespan"])


def _path(
    parent: Mapping[tuple[Any, ...], tuple[tuple[Any, ...], tuple[Instance, ...], float]],
    key: tuple[Any, ...],
) -> list[tuple[tuple[Instance, ...], float]]:
    steps = []
    while key in parent:
        key, step, duration = parent[key]
        steps.append((step, duration))
    return steps[::-1]


def _plan_json(
    scene: Scene,
    h: Hierarchy,
    steps: Sequence[tuple[tuple[Instance, ...], float]],
    cost: float,
    expanded: int,
) -> dict[str, Any]:
    locs: tuple[Location, ...] = tuple(REST for _ in scene.objects)
    symbols = []
    for step, _ in steps:
        locs, symbol = apply_step(scene, locs, step)
        symbols.append(symbol)
    fired = fire_steps(h, symbols)
    roles = _roles([step for step, _ in steps])
    out_steps = []
    clock = 0.0
    for k, (step, duration) in enumerate(steps):
        bindings: dict[str, list[str]] = {}
        for a in step:
            leaf = next(
                (
                    leaf
                    for leaf in h.leaves
                    if _not_done(fired[leaf], k) and mentions(h.formulas[leaf], a.object)
                ),
                None,
            )
            if leaf is not None:
                for r in a.robots:
                    bindings[r] = [leaf, roles[(k, a, r)]]
        out_steps.append(
            {
                "start": round(clock, 9),
                "duration": duration,
                "bindings": bindings,
                "actions": [a.to_json() for a in step],
            }
        )
        clock += duration
    return {
        "status": "solved",
        "makespan": cost,
        "planner": {"name": "brute-force", "expanded": expanded},
        "steps": out_steps,
    }


def _not_done(fired_at: int | None, k: int) -> bool:
    return fired_at is None or fired_at >= k


def _roles(steps: Sequence[tuple[Instance, ...]]) -> dict[tuple[int, Instance, str], str]:
    """Roles of docs/model.md §Bindings, per custody segment (pick … place or hand-to-human)."""
    segments: dict[str, list[str]] = {}  # object -> holders of its current segment, in order
    members: list[tuple[int, Instance, list[str], int]] = []  # step, action, segment, position
    for k, step in enumerate(steps):
        for a in step:
            if a.skill == "pick":
                segments[a.object] = [a.robots[0]]
            elif a.skill == "handover_r2r":
                segments[a.object].append(a.robots[1])
            seg = segments[a.object]
            members.append((k, a, seg, len(seg) - 1))
            if a.skill in ("place", "handover_r2h"):
                del segments[a.object]
    roles: dict[tuple[int, Instance, str], str] = {}
    for k, a, seg, pos in members:
        if len(seg) == 1:
            roles[(k, a, a.robots[0])] = "solo"
        elif a.skill == "pick":
            roles[(k, a, a.robots[0])] = "giver"
        elif a.skill == "handover_r2r":  # robots[1] is seg[pos], robots[0] is seg[pos - 1]
            roles[(k, a, a.robots[0])] = "giver" if pos == 1 else "relay"
            roles[(k, a, a.robots[1])] = "receiver" if pos == len(seg) - 1 else "relay"
        else:
            roles[(k, a, a.robots[0])] = "receiver"
    return roles
