"""Where a partly hidden upright cylinder of known size can stand: free-space carving."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from hltl.perception.frames import Camera
from hltl.perception.geometry import cylinder_outline, polygon_area

F64 = npt.NDArray[np.float64]
Mask = npt.NDArray[np.bool_]

DEPTH_TOL = 0.01  # m: a seen depth this close to the candidate's surface agrees with it
STEP = 0.004  # m: the grid of candidate axes (an 8 mm pass first)
FINE = 0.001  # m: the lattice on which the consistent region is refined
MAX_PIXELS = 4000  # a larger window is scored on every k-th pixel (both directions)
BATCH = 256  # candidate axes scored at once
SLACK = 0.02  # consistent: cost within max(2, SLACK × the object's pixels) of the best
INSIDE = 0.95  # this share of the object's points at least lies within the candidate (+1 cm)
POINTS = 200  # at most this many of the object's points prune the candidates
SIDE_MARGIN = 0.005  # m: points this far below the top are on the side (the arc)
NOISE = 0.001  # m: the least depth noise assumed on the arc (a render has none)
CHI2_99 = 9.21  # the chi-square 99 % quantile with two degrees of freedom (the axis x, y)


@dataclass(frozen=True, slots=True)
class Carved:
    """The axis (x, y) where the cylinder most likely stands, ``spread`` the farthest
    consistent axis from it plus half a FINE cell's diagonal (m), ``candidates`` how many axes
    (of the grid and the lattice) are consistent."""

    centre: tuple[float, float]
    spread: float
    candidates: int


def pixel_rays(camera: Camera, u: npt.NDArray[np.int64], v: npt.NDArray[np.int64]) -> F64:
    """World directions (n × 3) of the rays through pixels (u, v), scaled to unit optical depth."""
    pose = camera.pose
    rays = np.stack([(u - camera.cx) / camera.fx, (v - camera.cy) / camera.fy, np.ones(len(u))])
    return np.asarray((pose[:3, :3] @ rays).T, dtype=float)


def ray_depths(
    origin: F64, dirs: F64, centres: F64, radius: float, bottom: float, top: float
) -> F64:
    """Optical depth (the ray parameter: ``dirs`` have unit optical z) at which each ray from
    ``origin`` first meets each upright cylinder (axis at ``centres`` (m × 2), ``radius``,
    from ``bottom`` to ``top``): an m × n array, inf where it misses. The camera is outside."""
    ox, oy, oz = float(origin[0]), float(origin[1]), float(origin[2])
    dx, dy, dz = dirs[:, 0][None, :], dirs[:, 1][None, :], dirs[:, 2][None, :]
    px = ox - centres[:, 0][:, None]
    py = oy - centres[:, 1][:, None]
    a = np.maximum(dx * dx + dy * dy, 1e-12)
    b = 2.0 * (dx * px + dy * py)
    c = px * px + py * py - radius * radius
    disc = b * b - 4.0 * a * c
    root = np.sqrt(np.maximum(disc, 0.0))
    t_side = (-b - root) / (2.0 * a)
    z_side = oz + t_side * dz
    side = (disc >= 0) & (t_side > 0) & (z_side >= bottom) & (z_side <= top)
    best = np.where(side, t_side, np.inf)
    safe = np.where(np.abs(dz) > 1e-12, dz, 1e-12)
    for zc in (top, bottom):
        t = (zc - oz) / safe
        qx, qy = px + t * dx, py + t * dy
        cap = (t > 0) & (qx * qx + qy * qy <= radius * radius)
        best = np.where(cap & (t < best), t, best)
    return np.asarray(best, dtype=float)


def _costs(
    origin: F64,
    dirs: F64,
    seen: Mask,
    depth: F64,
    centres: F64,
    radius: float,
    bottom: float,
    top: float,
) -> npt.NDArray[np.int64]:
    t = ray_depths(origin, dirs, centres, radius, bottom, top)
    hit = np.isfinite(t)
    own = seen[None, :]
    d = depth[None, :]
    missed = own & ~hit  # the object's own pixel, outside the candidate
    through = ~own & hit & ((d <= 0) | (d > t + DEPTH_TOL))  # seen past where it would be
    apart = own & hit & (np.abs(d - t) > DEPTH_TOL)  # on it, at another depth
    return np.asarray((missed | through | apart).sum(axis=1), dtype=np.int64)


def carve(
    depth: npt.NDArray[np.float32],
    mask: Mask,
    points: F64,
    camera: Camera,
    radius: float,
    bottom: float,
    height: float,
    start: tuple[float, float],
) -> Carved | None:
    """The axes where an upright cylinder (``radius``, standing at ``bottom``, ``height``
    tall) agrees with the object's pixels ``mask``, its world ``points`` and the depth image
    around them. ``start`` (the caller's own fit) is kept when it is consistent. Searched on an
    8 mm grid, then on a 4 mm grid within 8 mm of the axes the camera allows (STEP); the
    consistent region is then refined on a 1 mm lattice (FINE) through ``start``, grown from
    the consistent axes until its every neighbour is scored. None when no candidate holds 95 %
    of the points within the radius (+1 cm) or the cylinder is behind the camera."""
    top = bottom + height
    # every point of the object lies in the cylinder (+1 cm): the axis is within that of the
    # points' mean, and a cheap first cut of the grid
    reach = radius + 0.01
    pts = points[:, :2]
    if len(pts) > POINTS:
        pts = pts[np.linspace(0, len(pts) - 1, POINTS).astype(int)]
    mid = pts.mean(axis=0)

    def within(c: F64) -> Mask:
        dist = np.sqrt(((c[:, None, :] - pts[None, :, :]) ** 2).sum(axis=2))
        # a few strays (a learned mask's pixels on what is behind) may lie outside
        return np.asarray(np.quantile(dist, INSIDE, axis=1) <= reach)

    def grid(step: float) -> F64:
        g = np.arange(-reach, reach + step / 2, step)
        gx, gy = np.meshgrid(g + mid[0], g + mid[1])
        c = np.column_stack([gx.ravel(), gy.ravel()])
        return np.asarray(c[within(c)], dtype=float)

    coarse = grid(2 * STEP)
    if len(coarse) == 0:
        return None
    # the pixels any candidate can cover: the outline of a cylinder holding all of them
    hull = cylinder_outline(
        (float(mid[0]), float(mid[1]), bottom + height / 2),
        radius + reach,
        height,
        camera,
    )
    if hull is None:
        return None
    h, w = depth.shape
    lo = np.maximum(np.floor(hull.min(axis=0)).astype(int) - 1, 0)
    hi = np.minimum(np.ceil(hull.max(axis=0)).astype(int) + 1, [w - 1, h - 1])
    if np.any(hi < lo):
        return None
    stride = math.ceil(math.sqrt((hi[0] - lo[0] + 1) * (hi[1] - lo[1] + 1) / MAX_PIXELS))
    us = np.arange(lo[0], hi[0] + 1, stride)
    vs = np.arange(lo[1], hi[1] + 1, stride)
    u, v = (a.ravel() for a in np.meshgrid(us, vs))
    dirs = pixel_rays(camera, u, v)
    seen = mask[v, u]
    d = depth[v, u].astype(float)
    origin = camera.pose[:3, 3]
    # only pixels a candidate can change: the object's own, and those a cylinder holding every
    # candidate covers without something nearer in front of it (never a violation otherwise)
    big = ray_depths(origin, dirs, mid[None, :], radius + reach * 1.5, bottom, top)[0]
    keep = seen | (np.isfinite(big) & ~((d > 0) & (d < big - DEPTH_TOL)))
    dirs, seen, d = dirs[keep], seen[keep], d[keep]
    side = points[points[:, 2] < top - SIDE_MARGIN, :2]

    def score(c: F64) -> tuple[npt.NDArray[np.int64], F64]:
        if len(c) > BATCH:  # a bounded working set: candidates × pixels
            parts = [score(c[k : k + BATCH]) for k in range(0, len(c), BATCH)]
            return np.concatenate([p[0] for p in parts]), np.concatenate([p[1] for p in parts])
        cost = _costs(origin, dirs, seen, d, c, radius, bottom, top)
        if len(side) < 3:  # only the top is seen: no arc to fit
            return cost, np.zeros(len(c))
        dist = np.sqrt(((c[:, None, :] - side[None, :, :]) ** 2).sum(axis=2))
        return cost, np.sqrt(((dist - radius) ** 2).mean(axis=1))

    cut = max(2, int(SLACK * int(seen.sum())))  # the violations allowed above the best's
    # a coarse pass first: the fine grid only near the coarse axes the camera allows
    c_cost = _costs(origin, dirs, seen, d, coarse, radius, bottom, top)
    seeds = coarse[c_cost <= int(c_cost.min()) + cut]
    cands = grid(STEP)
    near = np.sqrt(((cands[:, None, :] - seeds[None, :, :]) ** 2).sum(axis=2)).min(axis=1)
    cands = cands[near <= 2 * STEP]
    if len(cands) == 0:
        cands = seeds
    cost, res = score(cands)

    def consistent(cost: npt.NDArray[np.int64], res: F64) -> tuple[Mask, Mask]:
        """Free (what the camera sees allows the axis there) and consistent (... and the
        visible arc fits it: a likelihood-ratio region, 99 %, two unknowns, about the best
        fit, the depth noise taken as the best fit's own residual, at least NOISE)."""
        free = cost <= int(cost.min()) + cut
        best_res = float(res[free].min())
        sigma2 = max(best_res, NOISE) ** 2
        return free, free & (res**2 <= best_res**2 + CHI2_99 * sigma2 / max(len(side), 1))

    free, ok = consistent(cost, res)
    # the region refined on the FINE lattice through the caller's fit: seeded with the caller's
    # fit and the consistent grid axes, then grown from every consistent axis to its eight
    # neighbours until none is left unscored; the best, hence the region, is that of every axis
    # scored (grid and lattice)
    st = np.asarray(start, dtype=float)
    ring = np.asarray([(i, j) for i in (-1, 0, 1) for j in (-1, 0, 1) if i or j], dtype=np.int64)
    todo = np.unique(
        np.vstack([np.zeros((1, 2)), np.rint((cands[ok] - st) / FINE)]).astype(np.int64), axis=0
    )
    # every axis scored: the grid's, then the lattice's (``lattice``: their indices)
    axes, lattice = cands, np.zeros((0, 2), dtype=np.int64)
    scored: set[tuple[int, int]] = set()
    while len(todo):
        scored.update((int(i), int(j)) for i, j in todo)
        new = st + todo * FINE
        c, r = score(new)
        c[~within(new)] = len(dirs) + 1  # not a candidate: never free
        axes, lattice = np.vstack([axes, new]), np.vstack([lattice, todo])
        cost, res = np.concatenate([cost, c]), np.concatenate([res, r])
        free, ok = consistent(cost, res)
        grown = (lattice[ok[len(cands) :]][:, None, :] + ring).reshape(-1, 2)
        fresh = {(int(i), int(j)) for i, j in grown} - scored
        todo = np.asarray(sorted(fresh), dtype=np.int64).reshape(-1, 2)
    if ok[len(cands) + int(np.flatnonzero((lattice == 0).all(axis=1))[0])]:
        centre = st  # the caller's own fit is consistent: keep it
    else:  # the best fit of the free axes
        centre = axes[int(np.argmin(np.where(free, res, np.inf)))]
    # the farthest consistent axis, and half a lattice cell's diagonal beyond it
    spread = float(np.sqrt(((axes[ok] - centre) ** 2).sum(axis=1)).max()) + FINE * math.sqrt(0.5)
    return Carved((float(centre[0]), float(centre[1])), spread, int(ok.sum()))


def _clip(poly: F64, w: int, h: int) -> F64:
    """A convex polygon clipped to the image rectangle [-0.5, w - 0.5] × [-0.5, h - 0.5]
    (Sutherland–Hodgman)."""
    out = poly
    for axis, bound, keep_below in (
        (0, -0.5, False),
        (0, w - 0.5, True),
        (1, -0.5, False),
        (1, h - 0.5, True),
    ):
        if len(out) == 0:
            break
        pts = []
        for k in range(len(out)):
            a, b = out[k - 1], out[k]
            ina = a[axis] <= bound if keep_below else a[axis] >= bound
            inb = b[axis] <= bound if keep_below else b[axis] >= bound
            if ina != inb:
                f = (bound - a[axis]) / (b[axis] - a[axis])
                pts.append(a + f * (b - a))
            if inb:
                pts.append(b)
        out = np.asarray(pts, dtype=float).reshape(-1, 2)
    return out


def hidden_share(
    depth: npt.NDArray[np.float32],
    camera: Camera,
    centre: tuple[float, float, float],
    radius: float,
    height: float,
) -> float:
    """How much of an upright cylinder placed at ``centre`` the camera cannot see: the share of
    its silhouette outside the image (by area) plus, of the part inside, the share behind
    something nearer (a depth more than DEPTH_TOL in front of its surface). A mask that misses
    the object's rim (a learned one) does not count: the depth there is the object's own."""
    hull = cylinder_outline(centre, radius, height, camera)
    if hull is None:
        return 1.0
    h, w = depth.shape
    area = polygon_area(hull)
    inner = _clip(hull, w, h)
    if area <= 0 or len(inner) < 3:
        return 1.0
    outside = max(1.0 - polygon_area(inner) / area, 0.0)
    lo = np.maximum(np.floor(inner.min(axis=0)).astype(int), 0)
    hi = np.minimum(np.ceil(inner.max(axis=0)).astype(int), [w - 1, h - 1])
    u, v = (
        a.ravel() for a in np.meshgrid(np.arange(lo[0], hi[0] + 1), np.arange(lo[1], hi[1] + 1))
    )
    c = np.asarray([centre[:2]], dtype=float)
    bottom = centre[2] - height / 2
    origin = camera.pose[:3, 3]
    t = ray_depths(origin, pixel_rays(camera, u, v), c, radius, bottom, bottom + height)[0]
    hit = np.isfinite(t)
    if not hit.any():
        return 1.0
    d = depth[v, u].astype(float)
    front = hit & (d > 0) & (d < t - DEPTH_TOL)
    return min(outside + (1.0 - outside) * float(front.sum()) / float(hit.sum()), 1.0)
