"""A person for robot-to-human handovers (paper §IV-C): body capsules and the comfort zone."""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from hltl.motion.kinematics import Capsule, FloatArray

# The arms stand on a table: scene z = 0 is the table top; people stand on the floor below it.
TABLE_HEIGHT = 0.75
DEFAULT_HEIGHT = 1.70

# Segment lengths and heights as fractions of stature (Drillis & Contini, as tabulated by
# Winter, "Biomechanics and Motor Control of Human Movement").
_SHOULDER = 0.818
_HIP = 0.530
_HEAD = 0.936
_UPPER_ARM = 0.186
_FOREARM = 0.146
_HAND = 0.108
_HALF_SHOULDERS = 0.129

# The comfort zone: elbow flexion (angle between upper arm and forearm, 90° = forearm level),
# and how far the upper arm may swing forward while staying "close to the torso".
FLEXION_DEG = (90.0, 120.0)
UPPER_ARM_FORWARD_DEG = (0.0, 20.0)


@dataclass(frozen=True, slots=True)
class Posture:
    """A person's estimated posture, in the scene frame.

    ``shoulder``/``elbow`` come from a perceived skeleton when there is one; otherwise
    :func:`standing_posture` fills them in from the person's height.
    """

    position: tuple[float, float, float]  # on the floor, as in the scene file
    facing: tuple[float, float, float]  # horizontal unit vector the person faces
    height: float
    shoulder: tuple[float, float, float]  # the handing arm's shoulder
    elbow: tuple[float, float, float] | None = None


def _unit_xy(v: Sequence[float]) -> FloatArray:
    d = np.array([v[0], v[1], 0.0])
    n = float(np.linalg.norm(d))
    return np.array([1.0, 0.0, 0.0]) if n < 1e-9 else d / n


def standing_posture(
    position: Sequence[float] | FloatArray,
    towards: Sequence[float] | FloatArray,
    height: float = DEFAULT_HEIGHT,
    *,
    right_handed: bool = True,
) -> Posture:
    """A person of ``height`` standing at ``position`` and facing ``towards`` (e.g. the robot)."""
    if not 0.5 <= height <= 2.5:
        raise ValueError(f"person height {height!r} m is implausible; expected 0.5 … 2.5 m")
    pos = np.asarray(position, dtype=float)
    fwd = _unit_xy(np.asarray(towards, dtype=float) - pos)
    right = np.array([fwd[1], -fwd[0], 0.0])
    side = right if right_handed else -right
    floor = pos[2] - TABLE_HEIGHT
    shoulder = pos + side * _HALF_SHOULDERS * height
    shoulder[2] = floor + _SHOULDER * height
    return Posture(_v3(pos), _v3(fwd), height, _v3(shoulder))


def body_capsules(p: Posture) -> list[Capsule]:
    """Legs, torso and head as capsules (the robot's hand must never pass through them)."""
    x, y, z = p.position
    floor = z - TABLE_HEIGHT
    h = p.height
    return [
        Capsule((x, y, floor + 0.05), (x, y, floor + _HIP * h), 0.13, "legs"),
        Capsule((x, y, floor + _HIP * h), (x, y, floor + (_SHOULDER - 0.03) * h), 0.16, "torso"),
        Capsule((x, y, floor + _HEAD * h), (x, y, floor + _HEAD * h), 0.11, "head"),
    ]


def comfort_zone(p: Posture, *, steps: int = 4) -> list[tuple[float, float, float]]:
    """Points where the person's hand closes comfortably around an offered object.

    The upper arm hangs close to the torso (swung forward 0–20°); the elbow flexes 90–120°
    (forearm level to raised 30°). With a perceived elbow, its position is used as is.
    """
    fwd = np.asarray(p.facing)
    up = np.array([0.0, 0.0, 1.0])
    h = p.height
    grip = (_FOREARM + 0.5 * _HAND) * h
    out = []
    swings = np.linspace(*UPPER_ARM_FORWARD_DEG, steps) if p.elbow is None else [0.0]
    for swing in swings:
        if p.elbow is None:
            s = math.radians(swing)
            elbow = np.asarray(p.shoulder) + _UPPER_ARM * h * (
                -math.cos(s) * up + math.sin(s) * fwd
            )
            arm_dir = -math.cos(s) * up + math.sin(s) * fwd
        else:
            elbow = np.asarray(p.elbow)
            arm_dir = elbow - np.asarray(p.shoulder)
            arm_dir = arm_dir / np.linalg.norm(arm_dir)
        # the forearm turns in the plane of the upper arm and the facing direction
        perp = fwd - np.dot(fwd, arm_dir) * arm_dir
        perp = perp / np.linalg.norm(perp)
        for flex in np.linspace(*FLEXION_DEG, steps):
            f = math.radians(flex)
            # flexion 0 would put the forearm along the upper arm (pointing down)
            direction = math.cos(f) * arm_dir + math.sin(f) * perp
            out.append(_v3(elbow + grip * direction))
    return out


def _v3(a: FloatArray) -> tuple[float, float, float]:
    return (float(a[0]), float(a[1]), float(a[2]))
