"""Distances between capsules (arm links, hands, people's bodies) with coal."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np

from hltl.errors import BackendUnavailableError
from hltl.motion.kinematics import Capsule, rotation_z_to


def _coal() -> Any:
    try:
        import coal
    except ImportError:
        raise BackendUnavailableError(
            "collision checking needs coal: install the 'motion' extra (pip install 'hltl[motion]')"
        ) from None
    return coal


def _shape(c: Capsule) -> tuple[Any, Any]:
    coal = _coal()
    a, b = np.asarray(c.a), np.asarray(c.b)
    length = float(np.linalg.norm(b - a))
    rot = rotation_z_to(b - a) if length > 1e-9 else np.eye(3)
    return coal.Capsule(c.radius, length), coal.Transform3s(rot, (a + b) / 2.0)


def capsule_distance(x: Capsule, y: Capsule) -> float:
    """Signed distance between two capsules' surfaces (negative when they overlap)."""
    coal = _coal()
    sx, tx = _shape(x)
    sy, ty = _shape(y)
    res = coal.DistanceResult()
    return float(coal.distance(sx, tx, sy, ty, coal.DistanceRequest(), res))


def _bound(c: Capsule) -> tuple[np.ndarray, float]:
    a, b = np.asarray(c.a), np.asarray(c.b)
    return (a + b) / 2.0, float(np.linalg.norm(b - a)) / 2.0 + c.radius


def min_distance(
    xs: Sequence[Capsule], ys: Sequence[Capsule], *, stop_below: float = -np.inf
) -> tuple[float, str, str]:
    """Smallest distance between any capsule of ``xs`` and any of ``ys``, with their names.

    Pairs whose bounding spheres are farther apart than the best distance so far are skipped;
    the search ends early once a pair is closer than ``stop_below``.
    """
    best, bx, by = np.inf, "", ""
    bounds_y = [_bound(y) for y in ys]
    for x in xs:
        cx, rx = _bound(x)
        for y, (cy, ry) in zip(ys, bounds_y, strict=True):
            if float(np.linalg.norm(cx - cy)) - rx - ry >= best:
                continue
            d = capsule_distance(x, y)
            if d < best:
                best, bx, by = d, x.name, y.name
                if best < stop_below:
                    return best, bx, by
    return best, bx, by


def collides(xs: Sequence[Capsule], ys: Sequence[Capsule], margin: float = 0.0) -> bool:
    """True when some capsule of ``xs`` comes within ``margin`` of some capsule of ``ys``."""
    d, _, _ = min_distance(xs, ys, stop_below=margin)
    return d < margin


def segment_distances(p0: np.ndarray, p1: np.ndarray, q0: np.ndarray, q1: np.ndarray) -> np.ndarray:
    """Distances between every segment p0[i]–p1[i] and every segment q0[j]–q1[j] (n×m).

    The closed form for the closest points of two segments (clamped line parameters), in numpy:
    path checks make thousands of these queries, and one call here replaces n·m coal calls
    with their Python overhead. Tests check it against coal's capsule distance.
    """
    d1 = (p1 - p0)[:, None, :]
    d2 = (q1 - q0)[None, :, :]
    r = p0[:, None, :] - q0[None, :, :]
    zero = np.zeros(r.shape[:2])
    a = (d1 * d1).sum(-1) + zero
    e = (d2 * d2).sum(-1) + zero
    f = (d2 * r).sum(-1)
    c = (d1 * r).sum(-1)
    b = (d1 * d2).sum(-1) + zero
    denom = a * e - b * b
    eps = 1e-12
    s_line = np.where(a > eps, np.clip(-c / np.maximum(a, eps), 0.0, 1.0), 0.0)
    s = np.where(denom > eps, np.clip((b * f - c * e) / np.maximum(denom, eps), 0.0, 1.0), 0.0)
    s = np.where(e > eps, s, s_line)  # the second segment is a point
    t = np.where(e > eps, (b * s + f) / np.maximum(e, eps), 0.0)
    # clamp t, then recompute s for the clamped t
    t_c = np.clip(t, 0.0, 1.0)
    s_hi = np.where(a > eps, np.clip((b - c) / np.maximum(a, eps), 0.0, 1.0), 0.0)
    s = np.where(t < 0.0, s_line, np.where(t > 1.0, s_hi, s))
    closest_p = p0[:, None, :] + d1 * s[..., None]
    closest_q = q0[None, :, :] + d2 * t_c[..., None]
    return np.asarray(np.linalg.norm(closest_p - closest_q, axis=-1))


def capsule_arrays(caps: Sequence[Capsule]) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Endpoints and radii of capsules as arrays, for :func:`fast_min_distance`."""
    a = np.array([c.a for c in caps], dtype=float).reshape(-1, 3)
    b = np.array([c.b for c in caps], dtype=float).reshape(-1, 3)
    r = np.array([c.radius for c in caps], dtype=float)
    return a, b, r


def fast_min_distance(
    xs: Sequence[Capsule], ys: tuple[np.ndarray, np.ndarray, np.ndarray]
) -> float:
    """Smallest surface distance between capsules ``xs`` and pre-packed capsules ``ys``."""
    if not xs or len(ys[2]) == 0:
        return float("inf")
    a, b, r = capsule_arrays(xs)
    d = segment_distances(a, b, ys[0], ys[1]) - r[:, None] - ys[2][None, :]
    return float(d.min())
