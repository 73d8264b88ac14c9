"""Self-collision of one arm: its URDF collision geometry, the link pairs that can touch, coal."""

from __future__ import annotations

import functools
import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from hltl.errors import BackendUnavailableError
from hltl.motion.robots import OWN_URDFS, arm_spec, load_model

# Smallest allowed distance (m) between two links of one arm that can touch. Small: the UR5's
# forearm and wrist-2 meshes pass within 5 mm of each other in ordinary wrist motions.
SELF_MARGIN = 0.002
# A pair closer than SELF_MARGIN in at least this fraction of random configurations touches by
# design (two housings sharing a joint point, e.g. the Elfin-3's upper arm and forearm at the
# elbow): it is not a collision the arm can avoid, so it is not checked.
ALWAYS_TOUCHING = 0.95
PAIR_SAMPLES = 200  # random configurations the always-touching pairs are computed from
PAIR_SEED = 2024


@dataclass(frozen=True, slots=True)
class LinkPair:
    """Two collision bodies of one arm (the URDF's collision element names)."""

    first: str
    second: str


@dataclass(frozen=True, slots=True, eq=False)
class CollisionGeometry:
    """An arm's collision bodies and which pairs of them are checked.

    Attributes:
        model: the registry name of the arm.
        geometry: a Pinocchio GeometryModel whose meshes are replaced by their convex hulls (the
            broad phase, distances in C++), with the checked pairs as its collision pairs.
        meshes: per body, the original triangle mesh (coal BVH) or ``None`` for a primitive.
        names: per body, its name.
        checked: the pairs that are tested.
        adjacent: pairs left out because both bodies move with one joint or with two joints of
            which one is the other's parent.
        always: pairs left out because they touch in nearly every configuration (ALWAYS_TOUCHING).
    """

    model: str
    geometry: Any
    meshes: tuple[Any | None, ...]
    names: tuple[str, ...]
    checked: tuple[LinkPair, ...]
    adjacent: tuple[LinkPair, ...]
    always: tuple[LinkPair, ...]


def _pin_coal() -> tuple[Any, Any]:
    try:
        import coal
        import pinocchio as pin
    except ImportError:
        raise BackendUnavailableError(
            "self-collision checking needs Pinocchio and coal: install the 'motion' extra"
        ) from None
    return pin, coal


def raw_geometry(name: str) -> Any:
    """The arm's collision GeometryModel as its description ships it (meshes as meshes), for
    the joints of :func:`~hltl.motion.robots.load_model`.

    Elfin-3 and xArm6: hltl's URDF primitives. UR5: example-robot-data's meshes plus a cylinder
    for the hand hltl adds beyond ``tool0``. Panda: example-robot-data's meshes, reduced with
    the fingers locked open exactly as the kinematic model is.
    """
    pin, coal = _pin_coal()
    spec = arm_spec(name)
    if name in OWN_URDFS:
        path = str(OWN_URDFS[name])
        model = pin.buildModelFromUrdf(path)
        return pin.buildGeomFromUrdf(model, path, pin.GeometryType.COLLISION)
    import example_robot_data as erd

    robot = erd.load(name)
    geom = robot.collision_model
    if name == "panda":
        model = robot.model
        locked = [model.getJointId(n) for n in ("panda_finger_joint1", "panda_finger_joint2")]
        q_ref = pin.neutral(model)
        q_ref[-2:] = 0.04
        _, geom = pin.buildReducedModel(model, geom, locked, q_ref)
    if name == "ur5":
        # hltl's hand: a cylinder from the flange (tool0) to the tool point, along tool0's z
        model = load_model(name)
        f = model.frames[model.getFrameId("tool0")]
        centre = pin.SE3(np.eye(3), np.array([0.0, 0.0, spec.hand_length / 2.0]))
        geom.addGeometryObject(
            pin.GeometryObject(
                "hltl_hand_0",
                f.parentJoint,
                f.placement * centre,
                coal.Cylinder(spec.hand_radius, spec.hand_length),
            )
        )
    return geom


def _pair(geom: Any, i: int, j: int) -> LinkPair:
    return LinkPair(str(geom.geometryObjects[i].name), str(geom.geometryObjects[j].name))


@functools.cache
def collision_geometry(name: str) -> CollisionGeometry:
    """The checked collision bodies and pairs of a registered arm (built once per process).

    Every pair of bodies is a candidate except pairs on one joint or on a joint and its parent
    (their housings overlap at the joint by construction); of the rest, pairs closer than
    SELF_MARGIN in ALWAYS_TOUCHING of PAIR_SAMPLES random configurations are dropped too.
    """
    pin, coal = _pin_coal()
    model = load_model(name)
    geom = raw_geometry(name)
    objs = list(geom.geometryObjects)
    meshes: list[Any | None] = []
    for o in objs:
        if isinstance(o.geometry, coal.BVHModelBase):
            meshes.append(o.geometry)
            # coal's own convexHull (qhull); a mesh's "convex representation" keeps its
            # non-convex vertex graph and GJK then overestimates distances
            verts = [np.asarray(v, dtype=float) for v in np.asarray(o.geometry.vertices())]
            o.geometry = coal.Convex.convexHull(verts, False, "")
        else:
            meshes.append(None)
    parents = list(model.parents)
    # example-robot-data's models come with pairs of their own (from an SRDF): start from none
    geom.removeAllCollisionPairs()
    adjacent: list[LinkPair] = []
    for i in range(len(objs)):
        for j in range(i + 1, len(objs)):
            a, b = objs[i].parentJoint, objs[j].parentJoint
            if a == b or parents[a] == b or parents[b] == a:
                adjacent.append(_pair(geom, i, j))
            else:
                geom.addCollisionPair(pin.CollisionPair(i, j))
    names = tuple(str(o.name) for o in objs)
    cg = CollisionGeometry(name, geom, tuple(meshes), names, (), tuple(adjacent), ())
    # which candidate pairs touch in (nearly) every configuration?
    probe = SelfCollision(cg, model)
    rng = np.random.default_rng(PAIR_SEED)
    lo = np.maximum(model.lowerPositionLimit, -np.pi)
    hi = np.minimum(model.upperPositionLimit, np.pi)
    touching = np.zeros(len(geom.collisionPairs))
    for _ in range(PAIR_SAMPLES):
        touching += probe.pair_touching(rng.uniform(lo, hi))
    always = [k for k in range(len(touching)) if touching[k] >= ALWAYS_TOUCHING * PAIR_SAMPLES]
    pairs = list(geom.collisionPairs)
    always_pairs = tuple(_pair(geom, pairs[k].first, pairs[k].second) for k in always)
    for k in reversed(always):
        geom.removeCollisionPair(pairs[k])
    checked = tuple(_pair(geom, cp.first, cp.second) for cp in geom.collisionPairs)
    return CollisionGeometry(
        name, geom, tuple(meshes), names, checked, tuple(adjacent), always_pairs
    )


class SelfCollision:
    """Distances between the checked link pairs of one arm at a configuration.

    Broad phase: Pinocchio computes every checked pair's distance on the convex hulls (a lower
    bound of the meshes' distance). Narrow phase: a pair whose hulls come closer than the margin
    and that involves a mesh is measured again on the meshes with coal. Holds its own Pinocchio
    data, like :class:`~hltl.motion.kinematics.Arm`: not for sharing between threads.
    """

    def __init__(self, geometry: CollisionGeometry, model: Any) -> None:
        pin, coal = _pin_coal()
        self._pin, self._coal = pin, coal
        self.geometry = geometry
        self.model = model
        self.data = model.createData()
        self.gdata = pin.GeometryData(geometry.geometry)
        self._pairs = [(cp.first, cp.second) for cp in geometry.geometry.collisionPairs]
        self._request = coal.DistanceRequest()

    def _bodies(self, k: int) -> tuple[Any, Any, Any, Any]:
        """The exact shapes (meshes where there are) of pair ``k`` and their placements."""
        coal = self._coal
        i, j = self._pairs[k]
        objs = self.geometry.geometry.geometryObjects
        mi, mj = self.geometry.meshes[i], self.geometry.meshes[j]
        ti, tj = self.gdata.oMg[i], self.gdata.oMg[j]
        return (
            mi if mi is not None else objs[i].geometry,
            coal.Transform3s(ti.rotation, ti.translation),
            mj if mj is not None else objs[j].geometry,
            coal.Transform3s(tj.rotation, tj.translation),
        )

    def _place(self, q: Any) -> int:
        """Broad phase: every checked pair's distance on the convex hulls (Pinocchio, C++);
        returns the index of the closest pair."""
        pin = self._pin
        pin.updateGeometryPlacements(
            self.model, self.data, self.geometry.geometry, self.gdata, np.asarray(q, dtype=float)
        )
        return int(pin.computeDistances(self.geometry.geometry, self.gdata))

    def _hulls(self, q: Any) -> list[float]:
        self._place(q)
        return [float(r.min_distance) for r in self.gdata.distanceResults]

    def _has_mesh(self, k: int) -> bool:
        i, j = self._pairs[k]
        return self.geometry.meshes[i] is not None or self.geometry.meshes[j] is not None

    def pair_distances(self, q: Any, margin: float = SELF_MARGIN) -> np.ndarray:
        """Distance (m) of every checked pair at ``q``; below ``margin`` exact on the meshes
        (negative: penetration depth; two intersecting meshes report 0)."""
        out = np.array(self._hulls(q))
        for k in np.flatnonzero(out < margin):
            if self._has_mesh(int(k)):
                out[k] = self._coal.distance(
                    *self._bodies(int(k)), self._request, self._coal.DistanceResult()
                )
        return out

    def pair_touching(self, q: Any, margin: float = SELF_MARGIN) -> np.ndarray:
        """Which checked pairs come closer than ``margin`` at ``q``: hull distances, then, for
        pairs with a mesh whose hulls are that close, coal's collision test on the meshes with
        ``margin`` as its security margin (cheaper than a mesh distance)."""
        hull = np.array(self._hulls(q))
        out = hull < margin
        for k in np.flatnonzero(out):
            if self._has_mesh(int(k)):
                out[k] = self._mesh_touch(int(k), margin)
        return out

    def _mesh_touch(self, k: int, margin: float) -> bool:
        coal = self._coal
        req = coal.CollisionRequest()
        req.security_margin = margin
        return bool(coal.collide(*self._bodies(k), req, coal.CollisionResult()) > 0)

    def distance(self, q: Any) -> tuple[float, LinkPair | None]:
        """The closest checked pair at ``q`` and its exact distance (inf for an arm with no
        pairs); for reports: :meth:`clear` is the fast test."""
        d = self.pair_distances(q, math.inf)
        if len(d) == 0:
            return float("inf"), None
        k = int(np.argmin(d))
        return float(d[k]), self.geometry.checked[k]

    def clearance_of(self, q: Any, bodies: Sequence[str]) -> float:
        """Exact distance from ``bodies`` to every body they are checked against."""
        d = self.pair_distances(q, math.inf)
        on = [(p.first in bodies) != (p.second in bodies) for p in self.geometry.checked]
        return float(np.min(d[on])) if any(on) else math.inf

    def clear(self, q: Any, margin: float = SELF_MARGIN) -> bool:
        """True when every checked pair is at least ``margin`` apart at ``q``."""
        if not self._pairs:
            return True
        results = self.gdata.distanceResults
        if results[self._place(q)].min_distance >= margin:
            return True  # the closest hulls are apart: so is everything (the common case)
        for k, r in enumerate(results):
            if r.min_distance < margin and (not self._has_mesh(k) or self._mesh_touch(k, margin)):
                return False
        return True
