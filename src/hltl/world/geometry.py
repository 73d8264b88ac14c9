"""Workspace geometry: reach, workspaces W_j, the context label ℓ(w) and robot rendezvous."""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping
from dataclasses import dataclass

from hltl.world.scene import Robot, Scene, Vec3

# Height of the hand when it meets another hand or a person (metres above the robot base plane).
HANDOVER_HEIGHT = 0.3


def distance(a: Vec3, b: Vec3) -> float:
    return math.dist(a, b)


def horizontal_distance(a: Vec3, b: Vec3) -> float:
    return math.hypot(a[0] - b[0], a[1] - b[1])


def reaches(robot: Robot, point: Vec3) -> bool:
    """True when ``point`` lies in the robot's reach sphere (its workspace W_r)."""
    return distance(robot.base, point) <= robot.reach + 1e-9


def human_in_workspace(robot: Robot, human_position: Vec3, human_reach: float) -> bool:
    """True when a person at ``human_position`` can be served by ``robot`` (DESIGN.md §4)."""
    return horizontal_distance(robot.base, human_position) <= robot.reach + human_reach + 1e-9


def can_meet(giver: Robot, receiver: Robot) -> bool:
    """True when the two reach spheres overlap, so a robot-to-robot handover is possible."""
    gap = distance(giver.base, receiver.base)
    return giver.id != receiver.id and gap < giver.reach + receiver.reach


def rendezvous_point(a: Robot, b: Robot) -> Vec3:
    """Centre of the sphere inscribed in the overlap of the two reach spheres (paper §IV-B).

    It lies on the segment between the bases, midway through the overlap, at handover height.
    """
    d = distance(a.base, b.base)
    if d == 0.0:
        x, y, z = a.base
        return (x, y, z + HANDOVER_HEIGHT)
    along = (d - b.reach + a.reach) / 2.0
    along = min(max(along, 0.0), d)
    t = along / d
    p = tuple(a.base[i] + t * (b.base[i] - a.base[i]) for i in range(3))
    return (p[0], p[1], p[2] + HANDOVER_HEIGHT)


def human_handover_point(robot: Robot, human_position: Vec3) -> Vec3:
    """Where the hand meets a person: towards them, as far as the arm goes, at handover height."""
    dh = horizontal_distance(robot.base, human_position)
    bx, by, bz = robot.base
    if dh == 0.0:
        return (bx, by, bz + HANDOVER_HEIGHT)
    t = min(dh, max(robot.reach - HANDOVER_HEIGHT, 0.0)) / dh
    return (
        bx + t * (human_position[0] - bx),
        by + t * (human_position[1] - by),
        bz + HANDOVER_HEIGHT,
    )


def home_point(robot: Robot) -> Vec3:
    """The hand's rest pose: above the base at handover height."""
    bx, by, bz = robot.base
    return (bx, by, bz + HANDOVER_HEIGHT)


@dataclass(frozen=True, slots=True)
class Context:
    """The discrete context label ℓ(w): for each human, the robots whose workspace holds them.

    Two world states with equal contexts allow exactly the same skill instances, which is what the
    predictive takeover rule compares.
    """

    served_by: tuple[tuple[str, frozenset[str]], ...]

    def robots_serving(self, human: str) -> frozenset[str]:
        for hid, robots in self.served_by:
            if hid == human:
                return robots
        return frozenset()

    def blocked(self, a: str, b: str) -> bool:
        """True when some person stands inside both robots' workspaces (rendezvous unsafe)."""
        return any(a in robots and b in robots for _, robots in self.served_by)

    def describe(self) -> str:
        parts = [f"{h}∈{{{','.join(sorted(rs))}}}" for h, rs in self.served_by]
        return " ".join(parts) or "no people"


def context_label(scene: Scene, humans: Mapping[str, Vec3] | Iterable[tuple[str, Vec3]]) -> Context:
    """ℓ(w): which robots' workspaces contain each human, given their current positions."""
    items = humans.items() if isinstance(humans, Mapping) else humans
    served = []
    for hid, pos in sorted(items):
        robots = frozenset(
            r.id for r in scene.robots if human_in_workspace(r, pos, scene.human_reach)
        )
        served.append((hid, robots))
    return Context(tuple(served))


def workspace_of(scene: Scene, point: Vec3, human_reach: float | None = None) -> tuple[str, ...]:
    """Ids of the robots whose workspace contains a person standing at ``point``."""
    hr = scene.human_reach if human_reach is None else human_reach
    return tuple(r.id for r in scene.robots if human_in_workspace(r, point, hr))


def meeting_pairs(scene: Scene) -> tuple[tuple[str, str], ...]:
    """Ordered (giver, receiver) pairs whose reach spheres overlap."""
    return tuple((g.id, r.id) for g in scene.robots for r in scene.robots if can_meet(g, r))
