"""Reach, workspaces, ℓ(w) and rendezvous from reachability maps (the skills' Kinematics seam)."""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass

import numpy as np

from hltl.motion.human import comfort_zone, standing_posture
from hltl.motion.reach import ReachMap, load_or_build
from hltl.motion.robots import has_model
from hltl.world import geometry
from hltl.world.geometry import Context
from hltl.world.scene import Robot, Scene, Vec3

MIN_RENDEZVOUS_RADIUS = 0.05  # a hand and an object must fit in the shared region


@dataclass(frozen=True, slots=True)
class Rendezvous:
    """The inscribed sphere of two robots' shared reachable region (paper §IV-B)."""

    centre: Vec3
    radius: float


class MapKinematics:
    """Reachability from per-model maps; robots without a model keep the reach sphere.

    Implements the skill library's Kinematics protocol (reaches, can_meet, rendezvous_point,
    human_handover_point, home_point) and the context label ℓ(w).
    """

    def __init__(
        self,
        scene: Scene,
        maps: Mapping[str, ReachMap] | None = None,
        *,
        resolution: float | None = None,
    ) -> None:
        self.scene = scene
        self.maps: dict[str, ReachMap] = dict(maps or {})
        for r in scene.robots:
            if has_model(r.model) and r.model not in self.maps:
                self.maps[r.model] = load_or_build(r.model, resolution)
        self._rendezvous: dict[tuple[str, str], Rendezvous | None] = {}
        self._serve: dict[tuple[str, Vec3], Vec3 | None] = {}

    @property
    def name(self) -> str:
        """``maps``: a log checker rebuilds these from the scene (each model's cached map)."""
        return "maps"

    def map_of(self, robot: Robot) -> ReachMap | None:
        return self.maps.get(robot.model)

    # -- the Reachability/Kinematics protocol -------------------------------------------------
    def reaches(self, robot: Robot, point: Vec3) -> bool:
        m = self.map_of(robot)
        if m is None:
            return geometry.reaches(robot, point)
        return m.contains_point(np.asarray(point) - np.asarray(robot.base))

    def reaches_many(self, robot: Robot, points: np.ndarray) -> np.ndarray:
        m = self.map_of(robot)
        if m is None:
            d = np.linalg.norm(points - np.asarray(robot.base), axis=1)
            return np.asarray(d <= robot.reach + 1e-9)
        return m.contains(points - np.asarray(robot.base))

    def rendezvous(self, a: Robot, b: Robot) -> Rendezvous | None:
        """The largest sphere inside both robots' reachable regions, or None if it is too small."""
        key = (a.id, b.id) if a.id <= b.id else (b.id, a.id)
        if key not in self._rendezvous:
            self._rendezvous[key] = self._inscribed(a, b)
        return self._rendezvous[key]

    def _inscribed(self, a: Robot, b: Robot) -> Rendezvous | None:
        if a.id == b.id:
            return None
        if self.map_of(a) is None and self.map_of(b) is None:
            if not geometry.can_meet(a, b):
                return None
            c = geometry.rendezvous_point(a, b)
            d = geometry.distance(a.base, b.base)
            return Rendezvous(c, (a.reach + b.reach - d) / 2.0)
        from scipy.ndimage import distance_transform_edt

        res = min(m.resolution for m in (self.map_of(a), self.map_of(b)) if m is not None) / 2
        lo, hi = self._box(a), self._box(b)
        lo, hi = np.maximum(lo[0], hi[0]), np.minimum(lo[1], hi[1])
        if np.any(hi - lo < 2 * res):
            return None
        axes = [np.arange(lo[i], hi[i] + res, res) for i in range(3)]
        grid = np.stack(np.meshgrid(*axes, indexing="ij"), axis=-1).reshape(-1, 3)
        inside = self.reaches_many(a, grid) & self.reaches_many(b, grid)
        if not inside.any():
            return None
        shape = tuple(len(x) for x in axes)
        # pad so that the box's own faces count as the boundary of the region
        mask = np.pad(inside.reshape(shape), 1)
        dist = distance_transform_edt(mask) * res
        k = np.unravel_index(int(np.argmax(dist)), dist.shape)
        radius = float(dist[k]) - res / 2.0
        if radius < MIN_RENDEZVOUS_RADIUS:
            return None
        c = (float(axes[0][k[0] - 1]), float(axes[1][k[1] - 1]), float(axes[2][k[2] - 1]))
        return Rendezvous(c, radius)

    def _box(self, r: Robot) -> tuple[np.ndarray, np.ndarray]:
        base = np.asarray(r.base)
        m = self.map_of(r)
        if m is None:
            return base - r.reach, base + r.reach
        lo = base + np.asarray(m.origin)
        return lo, lo + (np.asarray(m.reachable.shape) - 1) * m.resolution

    def can_meet(self, giver: Robot, receiver: Robot) -> bool:
        return self.rendezvous(giver, receiver) is not None

    def rendezvous_point(self, giver: Robot, receiver: Robot) -> Vec3:
        rv = self.rendezvous(giver, receiver)
        return geometry.rendezvous_point(giver, receiver) if rv is None else rv.centre

    def serving_point(self, robot: Robot, human_position: Vec3) -> Vec3 | None:
        """A comfort-zone point of a person (facing the robot) that the robot reaches, if any.

        The point nearest the robot's base is preferred: the arm is least stretched there.
        """
        key = (robot.id, human_position)
        if key not in self._serve:
            self._serve[key] = self._serving_point(robot, human_position)
        return self._serve[key]

    def _serving_point(self, robot: Robot, human_position: Vec3) -> Vec3 | None:
        if self.map_of(robot) is None:
            if geometry.human_in_workspace(robot, human_position, self.scene.human_reach):
                return geometry.human_handover_point(robot, human_position)
            return None
        posture = standing_posture(human_position, robot.base)
        zone = np.array(comfort_zone(posture))
        ok = self.reaches_many(robot, zone)
        if not ok.any():
            return None
        pts = zone[ok]
        best = pts[int(np.argmin(np.linalg.norm(pts - np.asarray(robot.base), axis=1)))]
        return (float(best[0]), float(best[1]), float(best[2]))

    def human_handover_point(self, robot: Robot, human_position: Vec3) -> Vec3:
        p = self.serving_point(robot, human_position)
        return geometry.human_handover_point(robot, human_position) if p is None else p

    def home_point(self, robot: Robot) -> Vec3:
        return geometry.home_point(robot)

    # -- ℓ(w) ------------------------------------------------------------------------------------
    def serves(self, robot: Robot, human_position: Vec3) -> bool:
        return self.serving_point(robot, human_position) is not None

    def context_label(
        self, scene: Scene, humans: Mapping[str, Vec3] | Iterable[tuple[str, Vec3]]
    ) -> Context:
        """ℓ(w) from the maps: the robots that reach some comfort-zone point of each person."""
        items = humans.items() if isinstance(humans, Mapping) else humans
        served = []
        for hid, pos in sorted(items):
            robots = frozenset(r.id for r in scene.robots if self.serves(r, pos))
            served.append((hid, robots))
        return Context(tuple(served))
