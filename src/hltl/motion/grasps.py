"""Grasps of cylindrical objects, the co-grasp filter and placements (paper §IV-A)."""

from __future__ import annotations

import functools
import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np

from hltl.motion.collision import min_distance
from hltl.motion.kinematics import Capsule, FloatArray

# Hand models (metres). A robot hand: palm capsule behind the tool point, along the approach.
ROBOT_PALM_RADIUS = 0.045
ROBOT_PALM_LENGTH = 0.10
FINGER_RADIUS = 0.012
# A human hand closing around an object: palm and fingers as one capsule wrapped around it.
HUMAN_HAND_RADIUS = 0.035
HUMAN_HAND_BREADTH = 0.09
# Two hands on one object must keep this much space between them (the paper's "too close").
CO_GRASP_GAP = 0.015

# Cylinders for object categories the examples use (radius, height); the rest get DEFAULT.
CATEGORY_CYLINDERS: dict[str, tuple[float, float]] = {
    "bottle": (0.035, 0.22),
    "cup": (0.04, 0.10),
    "can": (0.033, 0.12),
    "chips": (0.05, 0.18),
}
DEFAULT_CYLINDER = (0.035, 0.16)


@dataclass(frozen=True, slots=True)
class Cylinder:
    """An upright cylindrical object: ``radius``, ``height``; its centre is the object's point."""

    radius: float
    height: float

    @classmethod
    def for_category(cls, category: str) -> Cylinder:
        r, h = CATEGORY_CYLINDERS.get(category, DEFAULT_CYLINDER)
        return cls(r, h)

    @classmethod
    def from_points(cls, points: FloatArray) -> tuple[Cylinder, tuple[float, float, float]]:
        """Fit an upright cylinder to an object's point cloud (n×3): its centre and size.

        The axis is vertical through the mean of the points' horizontal positions, the radius
        the median horizontal distance to it, the height the cloud's vertical extent.
        """
        pts = np.asarray(points, dtype=float)
        if pts.ndim != 2 or pts.shape[1] != 3 or len(pts) < 10:
            raise ValueError(f"a point cloud needs at least 10 rows of x, y, z; got {pts.shape}")
        cx, cy = pts[:, 0].mean(), pts[:, 1].mean()
        r = float(np.median(np.hypot(pts[:, 0] - cx, pts[:, 1] - cy)))
        z0, z1 = float(pts[:, 2].min()), float(pts[:, 2].max())
        return cls(max(r, 0.01), max(z1 - z0, 0.02)), (float(cx), float(cy), (z0 + z1) / 2.0)


@dataclass(frozen=True, slots=True)
class Grasp:
    """A hand's grasp of an object, relative to the object's centre.

    ``approach`` is the unit direction the hand moves along to close on the object (the tool
    frame's z axis); ``offset`` is where the tool point sits relative to the object's centre.
    """

    kind: str  # "side" or "top"
    azimuth: float  # radians, direction from the axis to the hand (side grasps)
    height: float  # along the axis from the centre
    approach: tuple[float, float, float]
    offset: tuple[float, float, float]


def side_grasp(azimuth: float, height: float) -> Grasp:
    out = (math.cos(azimuth), math.sin(azimuth), 0.0)
    return Grasp("side", azimuth, height, (-out[0], -out[1], 0.0), (0.0, 0.0, height))


def grasp_candidates(
    cyl: Cylinder, *, n_angles: int = 12, n_heights: int = 3, top: bool = True
) -> tuple[Grasp, ...]:
    """Side grasps around the axis at several heights, and a top grasp."""
    out: list[Grasp] = []
    span = max(cyl.height / 2.0 - 0.03, 0.0)
    heights = np.linspace(-span, span, n_heights) if n_heights > 1 else np.array([0.0])
    for k in range(n_angles):
        az = 2.0 * math.pi * k / n_angles
        out.extend(side_grasp(az, float(h)) for h in heights)
    if top:
        out.append(
            Grasp("top", 0.0, cyl.height / 2.0, (0.0, 0.0, -1.0), (0.0, 0.0, cyl.height / 2.0))
        )
    return tuple(out)


def complement(g: Grasp, cyl: Cylinder) -> Grasp:
    """The receiver's grasp for a giver's grasp: the opposite side, the other end of the object."""
    if g.kind == "top":
        return side_grasp(g.azimuth + math.pi, -max(cyl.height / 2.0 - 0.03, 0.0))
    return side_grasp(g.azimuth + math.pi, -g.height)


def robot_hand(
    g: Grasp, centre: Sequence[float], cyl: Cylinder, name: str = "hand"
) -> list[Capsule]:
    """A robot hand holding the object with ``g``: the palm behind the object and the fingers
    closed around it at the grasp height."""
    c = np.asarray(centre, dtype=float)
    tool = c + np.asarray(g.offset)
    a = np.asarray(g.approach)
    start = tool - a * (cyl.radius + ROBOT_PALM_RADIUS)
    end = start - a * ROBOT_PALM_LENGTH
    side = np.cross(a, [0.0, 0.0, 1.0]) if abs(a[2]) < 0.9 else np.array([1.0, 0.0, 0.0])
    side = side / np.linalg.norm(side)
    span = cyl.radius + FINGER_RADIUS
    return [
        Capsule(_v(start), _v(end), ROBOT_PALM_RADIUS, f"{name}_palm"),
        Capsule(_v(tool - side * span), _v(tool + side * span), FINGER_RADIUS, f"{name}_fingers"),
    ]


def human_hand(g: Grasp, centre: Sequence[float], cyl: Cylinder) -> Capsule:
    """A person's hand closing around the object at ``g``'s side and height."""
    c = np.asarray(centre, dtype=float) + np.asarray(g.offset)
    out = -np.asarray(g.approach)
    side = np.array([-out[1], out[0], 0.0])
    p = c + out * (cyl.radius + HUMAN_HAND_RADIUS)
    return Capsule(
        _v(p - side * HUMAN_HAND_BREADTH / 2),
        _v(p + side * HUMAN_HAND_BREADTH / 2),
        HUMAN_HAND_RADIUS,
        "human_hand",
    )


def co_grasp_pairs(
    cyl: Cylinder,
    grasps: Sequence[Grasp],
    *,
    partner: str = "robot",
    gap: float = CO_GRASP_GAP,
) -> list[tuple[Grasp, Grasp, float]]:
    """Pairs (giver's grasp, partner's complementary grasp, clearance) that leave room for both.

    The co-grasp scene puts both hands on the object at once; pairs whose hands collide or come
    closer than ``gap`` are discarded (partner ``robot``: the other robot's hand; ``human``: a
    hand model of a person). Pairs are returned with the most clearance first.
    """
    if partner not in ("robot", "human"):
        raise ValueError(f"co-grasp partner {partner!r}: expected 'robot' or 'human'")
    return list(_co_grasp_pairs(cyl, tuple(grasps), partner, gap))


@functools.lru_cache(maxsize=64)
def _co_grasp_pairs(
    cyl: Cylinder, grasps: tuple[Grasp, ...], partner: str, gap: float
) -> tuple[tuple[Grasp, Grasp, float], ...]:
    # the filter depends on the object and grasps only (hand models in the object's frame)
    origin = (0.0, 0.0, 0.0)
    out = []
    for g in grasps:
        c = complement(g, cyl)
        mine = robot_hand(g, origin, cyl, "giver")
        if partner == "robot":
            theirs = robot_hand(c, origin, cyl, "receiver")
        else:
            theirs = [human_hand(c, origin, cyl)]
        d, _, _ = min_distance(mine, theirs)
        if d >= gap:
            out.append((g, c, d))
    out.sort(key=lambda t: -t[2])
    return tuple(out)


@dataclass(frozen=True, slots=True)
class Placement:
    """Where to put an object down on a surface and how much free space it has around it."""

    position: tuple[float, float, float]
    clearance: float


def placements(
    center: Sequence[float],
    size: tuple[float, float],
    cyl: Cylinder,
    occupied: Sequence[tuple[Sequence[float], float]],
    reachable: Callable[[FloatArray], bool],
    *,
    spacing: float = 0.05,
) -> list[Placement]:
    """Placement poses sampled on a surface, inside the robots' reach, free of other objects.

    Args:
        center, size: the surface (its top's centre and x/y extent).
        occupied: (position, radius) of objects already on or near the surface.
        reachable: tells whether every involved robot reaches a point (the intersection of
            their reachable regions).

    Returns:
        Placements whose footprint lies on the surface and clears the other objects, the
        most clearance first.
    """
    cx, cy, cz = (float(v) for v in center)
    hx, hy = size[0] / 2.0 - cyl.radius, size[1] / 2.0 - cyl.radius
    if hx < 0 or hy < 0:
        return []
    xs = np.arange(-hx, hx + 1e-9, spacing) if hx > 0 else np.array([0.0])
    ys = np.arange(-hy, hy + 1e-9, spacing) if hy > 0 else np.array([0.0])
    out = []
    z = cz + cyl.height / 2.0
    for dx in xs:
        for dy in ys:
            p = np.array([cx + dx, cy + dy, z])
            clear = min(
                (math.dist(p[:2], tuple(o)[:2]) - r - cyl.radius for o, r in occupied),
                default=math.inf,
            )
            if clear < 0.01 or not reachable(p):
                continue
            out.append(Placement(_v(p), float(clear)))
    out.sort(key=lambda pl: (-min(pl.clearance, 1.0), math.dist(pl.position[:2], (cx, cy))))
    return out


def _v(a: FloatArray) -> tuple[float, float, float]:
    return (float(a[0]), float(a[1]), float(a[2]))
