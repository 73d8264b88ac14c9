"""From masks and depth to 3D: back-projection to world point clouds and a vertical-cylinder fit."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from hltl.perception.frames import Camera

F64 = npt.NDArray[np.float64]
Mask = npt.NDArray[np.bool_]


def backproject(depth: npt.NDArray[np.float32], mask: Mask, camera: Camera) -> F64:
    """World points (n, 3) of the pixels of ``mask`` that have a depth return.

    OpenCV pinhole model: pixel (u, v) at depth z is ((u − cx)·z/fx, (v − cy)·z/fy, z) in the
    optical frame, then ``camera_to_world``.
    """
    v, u = np.nonzero(mask & (depth > 0))
    z = depth[v, u].astype(float)
    pts = np.stack([(u - camera.cx) * z / camera.fx, (v - camera.cy) * z / camera.fy, z], axis=1)
    pose = camera.pose
    return np.asarray(pts @ pose[:3, :3].T + pose[:3, 3], dtype=float)


def pixel_of(point: F64, camera: Camera) -> tuple[float, float, float]:
    """(u, v, depth) of a world point in the image (depth ≤ 0: behind the camera)."""
    pose = camera.pose
    p = pose[:3, :3].T @ (np.asarray(point, dtype=float) - pose[:3, 3])
    if p[2] <= 1e-9:
        return (math.nan, math.nan, float(p[2]))
    return (
        float(camera.fx * p[0] / p[2] + camera.cx),
        float(camera.fy * p[1] / p[2] + camera.cy),
        float(p[2]),
    )


def cylinder_outline(
    center: tuple[float, float, float], radius: float, height: float, camera: Camera
) -> F64 | None:
    """The image outline (k × 2 pixel coordinates u, v, counter-clockwise) of an upright
    cylinder: the convex hull of its two rims' projections (a convex solid projects to the hull
    of its outline), unclipped by the image's border. None when any of it is behind the camera."""
    ang = np.linspace(0.0, 2.0 * math.pi, 96, endpoint=False)
    ring = np.stack([np.cos(ang), np.sin(ang)], axis=1) * radius + np.asarray(center[:2])
    rims = np.concatenate(
        [
            np.column_stack([ring, np.full(len(ring), center[2] + dz)])
            for dz in (-height / 2, height / 2)
        ]
    )
    pose = camera.pose
    cam = (rims - pose[:3, 3]) @ pose[:3, :3]
    if float(cam[:, 2].min()) <= 1e-6:
        return None
    uv = np.stack(
        [
            camera.fx * cam[:, 0] / cam[:, 2] + camera.cx,
            camera.fy * cam[:, 1] / cam[:, 2] + camera.cy,
        ],
        axis=1,
    )
    return convex_hull(uv)


def convex_hull(pts: F64) -> F64:
    """The convex hull (k × 2, counter-clockwise) of 2D points, by Andrew's monotone chain
    (no scipy: its import alone cost a frame 0.3 s)."""
    order = np.lexsort((pts[:, 1], pts[:, 0]))
    p = [(float(q[0]), float(q[1])) for q in pts[order]]

    def half(seq: list[tuple[float, float]]) -> list[tuple[float, float]]:
        out: list[tuple[float, float]] = []
        for q in seq:
            while (
                len(out) >= 2
                and (
                    (out[-1][0] - out[-2][0]) * (q[1] - out[-2][1])
                    - (out[-1][1] - out[-2][1]) * (q[0] - out[-2][0])
                )
                <= 0
            ):
                out.pop()
            out.append(q)
        return out

    lower, upper = half(p), half(p[::-1])
    return np.asarray(lower[:-1] + upper[:-1], dtype=float)


def polygon_area(poly: F64) -> float:
    """Area of a simple polygon (k × 2 vertices in order), by the shoelace formula."""
    x, y = poly[:, 0], poly[:, 1]
    return float(abs(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1))) / 2.0)


def cylinder_silhouette(
    center: tuple[float, float, float], radius: float, height: float, camera: Camera
) -> Mask:
    """The pixels (height × width) an upright cylinder covers in ``camera``'s image when
    nothing hides it (:func:`cylinder_outline`; a pixel is inside when its centre is). All False
    when any of it is behind the camera."""
    out = np.zeros((camera.height, camera.width), dtype=bool)
    hull = cylinder_outline(center, radius, height, camera)
    if hull is None:
        return out
    lo = np.maximum(np.floor(hull.min(axis=0)).astype(int), 0)
    hi = np.minimum(np.ceil(hull.max(axis=0)).astype(int), [camera.width - 1, camera.height - 1])
    if np.any(hi < lo):
        return out
    u, v = np.meshgrid(np.arange(lo[0], hi[0] + 1), np.arange(lo[1], hi[1] + 1))
    inside = np.ones(u.shape, dtype=bool)
    for a, b in zip(hull, np.roll(hull, -1, axis=0), strict=True):
        inside &= (b[0] - a[0]) * (v - a[1]) - (b[1] - a[1]) * (u - a[0]) >= 0
    out[lo[1] : hi[1] + 1, lo[0] : hi[0] + 1] = inside
    return out


@dataclass(frozen=True, slots=True)
class Cylinder:
    """An upright cylinder: ``center`` is the axis point at mid-height (world frame)."""

    center: tuple[float, float, float]
    radius: float
    height: float
    axis: tuple[float, float, float] = (0.0, 0.0, 1.0)
    points: int = 0

    def to_dict(self) -> dict[str, object]:
        return {
            "center": [round(v, 4) for v in self.center],
            "radius": round(self.radius, 4),
            "height": round(self.height, 4),
            "axis": list(self.axis),
            "points": self.points,
        }


def _circle(xy: F64) -> tuple[F64, float] | None:
    """Least-squares (Kåsa) circle through 2D points; None when they are (nearly) collinear."""
    if len(xy) < 3:
        return None
    mean = xy.mean(axis=0)
    d = xy - mean
    a = np.column_stack([2 * d, np.ones(len(d))])
    b = (d * d).sum(axis=1)
    sol, *_ = np.linalg.lstsq(a, b, rcond=None)
    c = sol[:2]
    r2 = float(sol[2] + c @ c)
    if not math.isfinite(r2) or r2 <= 0:
        return None
    return c + mean, math.sqrt(r2)


def _circle_of_radius(xy: F64, r: float, start: F64) -> F64:
    """Centre of the circle of radius ``r`` nearest (least squares) to the points, by
    Gauss-Newton from ``start`` (the side of the arc it begins on is the side it ends on)."""
    c = np.asarray(start, dtype=float).copy()
    for _ in range(20):
        d = xy - c
        n = np.maximum(np.linalg.norm(d, axis=1), 1e-9)
        res = n - r
        jac = -d / n[:, None]
        step, *_ = np.linalg.lstsq(jac, -res, rcond=None)
        c += step
        if float(np.linalg.norm(step)) < 1e-6:
            break
    return c


def fit_cylinder(
    points: F64,
    floor: float | None = None,
    size: tuple[float, float] | None = None,
    view: tuple[float, float] | None = None,
) -> Cylinder | None:
    """Fit an upright cylinder to the visible surface points of an object.

    The camera sees part of the side and maybe the top. The side points (below the top rim)
    fix the axis by a circle fit; when the side is seen too little (a view from above) the top
    disc's points do (their mean is the axis, their farthest the radius). The radius is
    bounded by the points' own spread so an almost straight arc cannot blow up. ``floor``, when
    known, is where the object stands: the height runs from there (the bottom is often hidden).

    ``size`` (radius, height), when the object is known: the side points fix only the axis
    (a circle of that radius, started behind the surface as seen from ``view``, the camera's
    x, y), and the height is the known one, standing on ``floor`` when that is known (else
    hanging from the visible top) — a sliver of the side or a hidden top or foot then no longer
    biases the centre. The fitted axis must lie within the known radius (+2 cm) of the
    visible points, else the free fit is kept.

    Returns None for fewer than 10 points.
    """
    if len(points) < 10:
        return None
    z = points[:, 2]
    top = float(z.max())
    bottom = float(z.min()) if floor is None else min(float(z.min()), floor)
    height = top - bottom
    xy = points[:, :2]
    spread = float(np.ptp(xy, axis=0).max())
    cap = z >= top - max(0.004, 0.03 * height)
    side = ~cap
    fit = _circle(xy[side]) if side.sum() >= 20 else None
    if fit is not None:
        c, r = fit
        # an arc seen edge-on is almost straight: trust it only up to the object's visible size
        if r > max(spread, 0.01) * 1.2:
            fit = None
    if fit is None:
        pts = xy[cap] if cap.sum() >= 10 else xy
        c = pts.mean(axis=0)
        r = float(np.linalg.norm(pts - c, axis=1).max())
    if size is not None:
        r0, h0 = size
        if side.sum() >= 10:
            sxy = xy[side]
            mean = sxy.mean(axis=0)
            away = mean - np.asarray(view, dtype=float) if view is not None else mean - c
            n = float(np.linalg.norm(away))
            start = mean + (away / n * r0 if n > 1e-9 else 0.0)
            c0 = _circle_of_radius(sxy, r0, start)
            if float(np.linalg.norm(sxy - c0, axis=1).min()) <= r0 + 0.02:
                c = c0
        r = r0
        bottom = floor if floor is not None else top - h0
        height = h0
    return Cylinder(
        (float(c[0]), float(c[1]), bottom + height / 2.0), float(r), height, points=len(points)
    )


# -- the top of an object ---------------------------------------------------------------

TOP_POINTS = 400  # at most this many points (evenly spaced in the sorted heights) are fitted
MIN_SIGMA = 2e-4  # a floor on the fitted noise (m): noise-free heights make a zero-width spike


def top_height(z: F64) -> float:
    """The height of an upright object's top surface from its points' heights ``z``, unbiased
    by depth noise.

    An object seen whole is its side — heights spread evenly from the lowest visible point up to
    the top H — and its top surface, all at H; depth noise adds N(0, σ²) to each. The high
    percentiles read high by about 1.3–2 σ (the 98th with half of the points on the top), so
    the top is instead fitted by maximum likelihood of that mixture: a share ρ of the points
    N(H, σ²), the rest uniform on [lo, H] (lo: the 1st percentile) convolved with the same
    noise; H, σ and ρ are free (Nelder–Mead from the 98th percentile). A hidden top leaves
    ρ ≈ 0 and H the top of what shows. Tested against hypothesis-generated noise
    (tests/perception/test_geometry_top.py); docs/perception.md gives the measured spread."""
    from scipy.optimize import minimize  # why: scipy costs start-up; only red objects need it
    from scipy.special import ndtr

    zs = np.sort(np.asarray(z, dtype=float))
    if len(zs) == 0:
        raise ValueError("top_height needs at least one point")
    if len(zs) > TOP_POINTS:
        zs = zs[np.linspace(0, len(zs) - 1, TOP_POINTS).astype(int)]
    lo, hi = float(np.percentile(zs, 1)), float(np.percentile(zs, 98))
    root2pi = math.sqrt(2.0 * math.pi)

    def nll(p: F64) -> float:
        h, log_s, logit_r = float(p[0]), float(p[1]), float(p[2])
        s = MIN_SIGMA + math.exp(min(log_s, 0.0))
        rho = 1.0 / (1.0 + math.exp(-max(min(logit_r, 30.0), -30.0)))
        spike = np.exp(-0.5 * ((zs - h) / s) ** 2) / (s * root2pi)
        side = np.maximum(ndtr((zs - lo) / s) - ndtr((zs - h) / s), 0.0) / max(h - lo, 1e-3)
        return -float(np.sum(np.log(rho * spike + (1.0 - rho) * side + 1e-12)))

    best: tuple[float, float] | None = None
    for s0 in (0.001, 0.004):  # a fit from a narrow and from a wide start; the likelier wins
        r = minimize(
            nll,
            np.array([hi, math.log(s0), 0.0]),
            method="Nelder-Mead",
            options={"xatol": 1e-5, "fatol": 1e-4, "maxiter": 300},
        )
        if best is None or float(r.fun) < best[0]:
            best = (float(r.fun), float(r.x[0]))
    assert best is not None
    return best[1]
