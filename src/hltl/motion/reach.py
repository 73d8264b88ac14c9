"""Reachability maps: IK sampled on a grid around an arm's base, cached on disk by model hash."""

from __future__ import annotations

import math
import os
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from hltl.errors import SceneError
from hltl.motion.kinematics import Arm, FloatArray
from hltl.motion.robots import load_model, model_hash

# Bumped when the way a map is built changes, so stale cache files are not read.
MAP_FORMAT_VERSION = 2  # 2: boundary cells of the revolved profile refined
# Profile cells on the reachable region's boundary (corners that disagree, and their neighbours)
# are sampled again REFINE times finer: the interpolated boundary of the coarse profile cuts
# corners where the region is ragged (the table and the self-collision tests make it so).
REFINE = 3
DEFAULT_RESOLUTION = 0.03  # metres between grid points (IK runs at half of it on the profile)
COARSE_RESOLUTION = 0.06  # for arms whose first joint does not turn fully: IK on the 3D grid
FK_SAMPLES_PER_CELL = 2.0  # random configurations per grid point, before IK fills the gaps


def cache_dir() -> Path:
    """Where maps are cached: ``$HLTL_CACHE/reach`` or ``~/.cache/hltl/reach``."""
    root = os.environ.get("HLTL_CACHE")
    base = Path(root) if root else Path.home() / ".cache" / "hltl"
    return base / "reach"


@dataclass(frozen=True, slots=True, eq=False)
class ReachMap:
    """Which tool positions an arm reaches, on a grid in the arm's base frame.

    A grid point is reachable when position IK (any hand orientation, joint limits, every link
    above the mounting plane) finds a configuration for it. Between grid points the occupancy is
    interpolated trilinearly and thresholded at one half, so the boundary falls between a
    reachable and an unreachable point instead of snapping to cells.

    Attributes:
        model: the registry name of the arm.
        digest: the model hash the map was built for.
        origin: base-frame coordinates of grid point (0, 0, 0).
        resolution: spacing of the grid (m).
        reachable: boolean occupancy, indexed [ix, iy, iz].
    """

    model: str
    digest: str
    origin: tuple[float, float, float]
    resolution: float
    reachable: np.ndarray
    profile: np.ndarray | None = None  # (radius, height) occupancy of a revolving arm
    profile_origin_z: float = 0.0
    profile_resolution: float = 0.0
    # Refined boundary cells of the profile: fine_cells[k] = (i, j) is the cell between profile
    # points (i, j) and (i + 1, j + 1); fine[k] its occupancy on a (REFINE + 1)² sub-grid.
    fine_cells: np.ndarray | None = None
    fine: np.ndarray | None = None

    def occupancy(self, points: FloatArray) -> FloatArray:
        """Interpolated occupancy (0…1) at base-frame ``points`` (n×3); 0 outside the grid."""
        pts = np.atleast_2d(np.asarray(points, dtype=float))
        if self.profile is not None:
            u = np.hypot(pts[:, 0], pts[:, 1]) / self.profile_resolution
            v = (pts[:, 2] - self.profile_origin_z) / self.profile_resolution
            occ = _bilinear(self.profile, u, v)
            if self.fine is not None and self.fine_cells is not None and len(self.fine):
                _refined(occ, u, v, self.profile.shape, self.fine_cells, self.fine)
            return occ
        g = (pts - np.asarray(self.origin)) / self.resolution
        shape = np.array(self.reachable.shape)
        i0 = np.floor(g).astype(int)
        f = g - i0
        inside = np.all((i0 >= 0) & (i0 + 1 < shape), axis=1)
        occ = np.zeros(len(pts))
        if not np.any(inside):
            return occ
        i0, f = i0[inside], f[inside]
        grid = self.reachable.astype(float)
        acc = np.zeros(len(i0))
        for dx in (0, 1):
            wx = f[:, 0] if dx else 1.0 - f[:, 0]
            for dy in (0, 1):
                wy = f[:, 1] if dy else 1.0 - f[:, 1]
                for dz in (0, 1):
                    wz = f[:, 2] if dz else 1.0 - f[:, 2]
                    acc += wx * wy * wz * grid[i0[:, 0] + dx, i0[:, 1] + dy, i0[:, 2] + dz]
        occ[inside] = acc
        return occ

    def contains(self, points: FloatArray) -> np.ndarray:
        """Boolean reachability of base-frame ``points`` (n×3)."""
        return self.occupancy(points) >= 0.5

    def contains_point(self, point: FloatArray | tuple[float, float, float]) -> bool:
        return bool(self.contains(np.asarray(point, dtype=float)[None, :])[0])

    def points(self) -> FloatArray:
        """Base-frame coordinates of every reachable grid point (n×3)."""
        idx = np.argwhere(self.reachable)
        return np.asarray(np.asarray(self.origin) + idx * self.resolution, dtype=float)

    @property
    def fraction(self) -> float:
        return float(self.reachable.mean())


def _bilinear(grid: np.ndarray, u: FloatArray, v: FloatArray) -> FloatArray:
    """Bilinear interpolation of ``grid`` at fractional indices (u, v); 0 outside."""
    out = np.zeros(len(u))
    inside = (u >= 0) & (v >= 0) & (u < grid.shape[0] - 1) & (v < grid.shape[1] - 1)
    if not np.any(inside):
        return out
    u, v = u[inside], v[inside]
    i, j = np.floor(u).astype(int), np.floor(v).astype(int)
    fu, fv = u - i, v - j
    g = grid.astype(float)
    out[inside] = (
        (1 - fu) * (1 - fv) * g[i, j]
        + fu * (1 - fv) * g[i + 1, j]
        + (1 - fu) * fv * g[i, j + 1]
        + fu * fv * g[i + 1, j + 1]
    )
    return out


def _refined(
    occ: FloatArray,
    u: FloatArray,
    v: FloatArray,
    shape: tuple[int, ...],
    cells: np.ndarray,
    fine: np.ndarray,
) -> None:
    """Replace ``occ`` (in place) inside refined profile cells by the fine sub-grid's bilinear
    interpolation; (u, v) are fractional profile indices."""
    index = np.full((shape[0] - 1, shape[1] - 1), -1, dtype=int)
    index[cells[:, 0], cells[:, 1]] = np.arange(len(cells))
    i, j = np.floor(u).astype(int), np.floor(v).astype(int)
    inside = (i >= 0) & (j >= 0) & (i < shape[0] - 1) & (j < shape[1] - 1)
    k = np.full(len(u), -1)
    k[inside] = index[i[inside], j[inside]]
    sel = np.flatnonzero(k >= 0)
    if not len(sel):
        return
    n = fine.shape[1] - 1
    fu, fv = (u[sel] - i[sel]) * n, (v[sel] - j[sel]) * n
    a, b = np.minimum(np.floor(fu).astype(int), n - 1), np.minimum(np.floor(fv).astype(int), n - 1)
    du, dv = fu - a, fv - b
    g = fine[k[sel]].astype(float)
    rows = np.arange(len(sel))
    occ[sel] = (
        (1 - du) * (1 - dv) * g[rows, a, b]
        + du * (1 - dv) * g[rows, a + 1, b]
        + (1 - du) * dv * g[rows, a, b + 1]
        + du * dv * g[rows, a + 1, b + 1]
    )


def _grid(arm: Arm, resolution: float) -> tuple[FloatArray, tuple[int, int, int]]:
    sh = arm.shoulder_offset
    r = arm.max_extent
    lo = np.array([sh[0] - r, sh[1] - r, -0.1])
    hi = np.array([sh[0] + r, sh[1] + r, sh[2] + r])
    n = np.floor((hi - lo) / resolution).astype(int) + 2
    return lo, (int(n[0]), int(n[1]), int(n[2]))


def build_map(
    arm: Arm, resolution: float = DEFAULT_RESOLUTION, *, seed: int = 0, ik_starts: int = 6
) -> ReachMap:
    """Build the map of ``arm``'s model (in its base frame) by IK over grid points.

    When the first joint turns a full revolution about the base's vertical axis, the reachable
    set is a solid of revolution: IK then runs on a half-plane (radius, height) at half the
    grid spacing and the 3D grid is filled by revolving it. Other arms get IK on every 3D grid
    point within their span. Random configurations seed the IK starts near each point.
    """
    if arm.base.any():
        arm = Arm(arm.robot, arm.spec.name)  # maps live in the base frame
    lo, shape = _grid(arm, resolution)
    origin = (float(lo[0]), float(lo[1]), float(lo[2]))
    digest = model_hash(arm.spec.name)
    if arm.lower[0] <= -np.pi + 0.02 and arm.upper[0] >= np.pi - 0.02:
        h = resolution / 2.0
        prof = _profile(
            arm, float(lo[2]), float(lo[2] + (shape[2] - 1) * resolution), h, seed, ik_starts
        )
        cells, fine = _refine_profile(arm, prof, float(lo[2]), h, seed, ik_starts)
        flat = ReachMap(
            arm.spec.name,
            digest,
            origin,
            resolution,
            np.zeros(shape, dtype=bool),
            prof,
            float(lo[2]),
            h,
            cells,
            fine,
        )
        idx = np.array(list(np.ndindex(*shape)))
        reach = flat.contains(lo + idx * resolution).reshape(shape)
        return ReachMap(
            arm.spec.name, digest, origin, resolution, reach, prof, float(lo[2]), h, cells, fine
        )
    reach = _full_grid(arm, lo, shape, resolution, seed, ik_starts)
    return ReachMap(arm.spec.name, digest, origin, resolution, reach)


def _ik_grid(
    arm: Arm, points: FloatArray, resolution: float, seed: int, ik_starts: int
) -> np.ndarray:
    """Position IK at every point within the arm's span, seeded by nearby random configurations."""
    rng = np.random.default_rng(seed)
    lo = points.min(axis=0)
    seeds: dict[tuple[int, ...], FloatArray] = {}
    for _ in range(int(FK_SAMPLES_PER_CELL * len(points))):
        q = rng.uniform(arm._seed_lo, arm._seed_hi)
        p, _r = arm.fk(q)
        key = tuple(int(v) for v in np.rint((p - lo) / resolution))
        if key not in seeds:
            seeds[key] = q
    out = np.zeros(len(points), dtype=bool)
    shoulder = arm.shoulder_offset
    for i, point in enumerate(points):
        if np.linalg.norm(point - shoulder) > arm.max_extent:
            continue
        key = tuple(int(v) for v in np.rint((point - lo) / resolution))
        out[i] = arm.ik(point, None, seeds.get(key), starts=ik_starts, seed=seed + i).ok
    return out


def _full_grid(
    arm: Arm,
    lo: FloatArray,
    shape: tuple[int, int, int],
    resolution: float,
    seed: int,
    ik_starts: int,
) -> np.ndarray:
    idx = np.array(list(np.ndindex(*shape)))
    pts = lo + idx * resolution
    return _ik_grid(arm, pts, resolution, seed, ik_starts).reshape(shape)


def _profile(arm: Arm, z_lo: float, z_hi: float, h: float, seed: int, ik_starts: int) -> np.ndarray:
    """Reachability on the half-plane (radius ≥ 0, height) of a revolving arm, spacing ``h``."""
    r_max = float(np.hypot(arm.shoulder_offset[0], arm.shoulder_offset[1]) + arm.max_extent)
    rs = np.arange(0.0, r_max + 2 * h, h)
    zs = np.arange(z_lo, z_hi + 2 * h, h)
    rr, zz = np.meshgrid(rs, zs, indexing="ij")
    pts = np.stack([rr.ravel(), np.zeros(rr.size), zz.ravel()], axis=1)
    return _ik_grid(arm, pts, h, seed, ik_starts).reshape(rr.shape)


def _refine_profile(
    arm: Arm, prof: np.ndarray, z_lo: float, h: float, seed: int, ik_starts: int
) -> tuple[np.ndarray, np.ndarray]:
    """IK on a REFINE-times finer sub-grid of every boundary cell of the profile.

    A boundary cell has corners that disagree; its eight neighbours are refined too, so a
    boundary that bends between coarse points is followed. Returns the cells (m×2) and their
    sub-grids (m × (REFINE+1) × (REFINE+1)); the sub-grid corners are the coarse points.
    """
    n = REFINE
    g = prof.astype(np.int8)
    corners = g[:-1, :-1] + g[1:, :-1] + g[:-1, 1:] + g[1:, 1:]
    mixed = (corners > 0) & (corners < 4)
    grown = mixed.copy()
    grown[1:, :] |= mixed[:-1, :]
    grown[:-1, :] |= mixed[1:, :]
    grown[:, 1:] |= grown[:, :-1].copy()
    grown[:, :-1] |= grown[:, 1:].copy()
    cells = np.argwhere(grown)
    if not len(cells):
        return np.zeros((0, 2), dtype=int), np.zeros((0, n + 1, n + 1), dtype=bool)
    # every fine point once (neighbouring cells share their edges), coarse points from prof
    sub = np.arange(n + 1)
    keys = cells[:, None, None, :] * n + np.stack(np.meshgrid(sub, sub, indexing="ij"), -1)
    flat = keys.reshape(-1, 2)
    uniq, inverse = np.unique(flat, axis=0, return_inverse=True)
    on_coarse = (uniq % n == 0).all(axis=1)
    values = np.zeros(len(uniq), dtype=bool)
    coarse = uniq[on_coarse] // n
    values[on_coarse] = prof[coarse[:, 0], coarse[:, 1]]
    todo = uniq[~on_coarse]
    pts = np.stack([todo[:, 0] * h / n, np.zeros(len(todo)), z_lo + todo[:, 1] * h / n], axis=1)
    values[~on_coarse] = _ik_grid(arm, pts, h / n, seed + 1, ik_starts)
    fine = values[inverse.ravel()].reshape(len(cells), n + 1, n + 1)
    return cells.astype(int), fine


def _cache_file(model: str, resolution: float) -> Path:
    digest = model_hash(model)
    return cache_dir() / f"{model}-{digest}-r{round(resolution * 1000)}mm-v{MAP_FORMAT_VERSION}.npz"


def default_resolution(model: str) -> float:
    """Grid spacing of a model's map: finer for arms whose map is a revolved profile (cheap).

    ``$HLTL_REACH_RESOLUTION`` (metres) overrides it, e.g. coarse maps for quick tests.
    """
    env = os.environ.get("HLTL_REACH_RESOLUTION")
    if env:
        try:
            value = float(env)
        except ValueError:
            value = math.nan
        if not 0.005 <= value <= 0.5:
            raise SceneError(
                f"HLTL_REACH_RESOLUTION={env!r}: expected a grid spacing of 0.005 … 0.5 m"
            )
        return value
    m = load_model(model)
    revolves = m.lowerPositionLimit[0] <= -np.pi + 0.02 and m.upperPositionLimit[0] >= np.pi - 0.02
    return DEFAULT_RESOLUTION if revolves else COARSE_RESOLUTION


def load_or_build(
    model: str, resolution: float | None = None, *, use_cache: bool = True
) -> ReachMap:
    """The map of a registered arm, read from the cache or built (and cached) on a miss."""
    if resolution is None:
        resolution = default_resolution(model)
    path = _cache_file(model, resolution)
    if use_cache and path.exists():
        with np.load(path) as f:
            prof = f["profile"].astype(bool) if f["profile"].ndim == 2 else None
            return ReachMap(
                model,
                str(f["digest"]),
                (float(f["origin"][0]), float(f["origin"][1]), float(f["origin"][2])),
                float(f["resolution"]),
                f["reachable"].astype(bool),
                prof,
                float(f["profile_meta"][0]),
                float(f["profile_meta"][1]),
                f["fine_cells"] if prof is not None else None,
                f["fine"].astype(bool) if prof is not None else None,
            )
    m = build_map(Arm("map", model), resolution)
    if use_cache:
        path.parent.mkdir(parents=True, exist_ok=True)
        tmp = path.with_suffix(f".{os.getpid()}.tmp.npz")
        np.savez_compressed(
            tmp,
            digest=m.digest,
            origin=np.array(m.origin),
            resolution=m.resolution,
            reachable=m.reachable,
            profile=m.profile if m.profile is not None else np.zeros(0, dtype=bool),
            profile_meta=np.array([m.profile_origin_z, m.profile_resolution]),
            fine_cells=m.fine_cells if m.fine_cells is not None else np.zeros((0, 2), dtype=int),
            fine=m.fine if m.fine is not None else np.zeros((0, 2, 2), dtype=bool),
        )
        os.replace(tmp, path)  # atomic: concurrent builders never see half a file
    return m
