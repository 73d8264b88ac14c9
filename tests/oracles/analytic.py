"""Exhaustive search under the analytic cost model (docs/model.md, "Analytic durations").

Same step sets as ``brute_force`` (every set of applicable instances with disjoint robots and
distinct objects, no pruning), but a step's duration depends on where each executor's hand
starts, so the state also holds every hand's point. The hand points and durations are computed
here from docs/model.md alone; nothing is imported from ``hltl.world.geometry`` or the cost model.
"""

from __future__ import annotations

import heapq
import itertools
import math
from collections.abc import Mapping
from typing import Any

from hltl.world.scene import Robot, Scene

from .brute_force import (
    Instance,
    SearchBudgetExceeded,
    applicable,
    apply_step,
    step_sets,
)
from .model import REST, Location, surface_point

HANDOVER_HEIGHT = 0.3
DEFAULT_SPEED = 0.5
CONSTANT = {"pick": 0.3, "place": 0.3, "handover_r2h": 0.3, "handover_r2r": 0.4}

Point = tuple[float, float, float]


def home(robot: Robot) -> Point:
    x, y, z = robot.base
    return (x, y, z + HANDOVER_HEIGHT)


def rendezvous(giver: Robot, receiver: Robot) -> Point:
    """Midway through the overlap of the two reach spheres, on the segment between the bases."""
    d = math.dist(giver.base, receiver.base)
    along = min(max((d - receiver.reach + giver.reach) / 2.0, 0.0), d)
    t = along / d
    x, y, z = (giver.base[i] + t * (receiver.base[i] - giver.base[i]) for i in range(3))
    return (x, y, z + HANDOVER_HEIGHT)


def toward_person(robot: Robot, person: Point) -> Point:
    """Horizontally towards the person as far as reach − handover height, at handover height."""
    bx, by, bz = robot.base
    dh = math.hypot(person[0] - bx, person[1] - by)
    if dh == 0.0:
        return (bx, by, bz + HANDOVER_HEIGHT)
    t = min(dh, max(robot.reach - HANDOVER_HEIGHT, 0.0)) / dh
    return (bx + t * (person[0] - bx), by + t * (person[1] - by), bz + HANDOVER_HEIGHT)


def hand_targets(
    scene: Scene, locs: tuple[Location, ...], a: Instance
) -> tuple[tuple[str, Point], ...]:
    """Where each executor's hand goes for instance ``a`` (read before the step)."""
    if a.skill == "pick":
        index = [o.id for o in scene.objects].index(a.object)
        kind, where = locs[index]
        point = scene.object(a.object).position if kind == "rest" else surface_point(scene, where)
        return ((a.robots[0], point),)
    if a.skill == "place":
        return ((a.robots[0], surface_point(scene, a.target)),)
    if a.skill == "handover_r2r":
        p = rendezvous(scene.robot(a.robots[0]), scene.robot(a.robots[1]))
        return ((a.robots[0], p), (a.robots[1], p))
    robot = scene.robot(a.robots[0])
    return ((robot.id, toward_person(robot, scene.human(a.target).position)),)


def duration(
    scene: Scene, hands: Mapping[str, Point], targets: tuple[tuple[str, Point], ...], skill: str
) -> float:
    """Slowest executor's travel over its speed, plus the skill's grasp/release/exchange time."""
    travel = max(
        math.dist(hands[r], p) / (scene.robot(r).speed or DEFAULT_SPEED) for r, p in targets
    )
    return travel + CONSTANT[skill]


def optimal_makespan_analytic(scene: Scene, spec: Any, max_nodes: int = 300_000) -> float | None:
    """The minimum makespan under the analytic cost model; None when no plan exists.

    Raises:
        SearchBudgetExceeded: more than ``max_nodes`` nodes were expanded.
    """
    from hltl.spec.monitor import HierarchyMonitor

    monitor = HierarchyMonitor(spec)
    robots = [r.id for r in scene.robots]
    hands0 = tuple(home(r) for r in scene.robots)
    start = (tuple(REST for _ in scene.objects), hands0, monitor.initial, False)
    best: dict[Any, float] = {start: 0.0}
    closed: set[Any] = set()
    counter = itertools.count()
    heap: list[tuple[float, int, Any]] = [(0.0, next(counter), start)]
    expanded = 0
    while heap:
        cost, _, key = heapq.heappop(heap)
        if key in closed:
            continue
        closed.add(key)
        locs, hands, q, started = key
        if started and monitor.accepted(q):
            return cost
        expanded += 1
        if expanded > max_nodes:
            raise SearchBudgetExceeded(f"analytic brute force expanded more than {max_nodes}")
        where = dict(zip(robots, hands, strict=True))
        for step in step_sets(applicable(scene, locs)):
            new_hands = dict(where)
            d = 0.0
            for a in step:
                targets = hand_targets(scene, locs, a)
                d = max(d, duration(scene, where, targets, a.skill))
                new_hands.update(targets)
            nlocs, symbol = apply_step(scene, locs, step)
            nkey = (nlocs, tuple(new_hands[r] for r in robots), monitor.step(q, symbol), True)
            new_cost = cost + d
            if nkey not in closed and new_cost < best.get(nkey, math.inf):
                best[nkey] = new_cost
                heapq.heappush(heap, (new_cost, next(counter), nkey))
    return None
