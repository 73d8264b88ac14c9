"""Reachability maps: IK sampled on a grid around an arm's base, cached on disk by model hash."""

from __future__ import annotations

import itertools
import math
import os
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from hltl.errors import SceneError
from hltl.motion.kinematics import Arm, FloatArray
from hltl.motion.robots import load_model, model_hash

# Bumped when the way a map is built changes, so stale cache files are not read.
MAP_FORMAT_VERSION = 3  # 2: profile boundary refined; 3: every map's boundary refined (3D too)
# Cells on the reachable region's boundary (corners that disagree) are sampled again REFINE
# times finer: the interpolated boundary of the coarse grid cuts corners where the region is
# ragged (the table and the self-collision tests make it so). On the 2-D profile of a revolving
# arm the boundary cells' neighbours are refined too (GROW), so a boundary that bends between
# coarse points is followed; on a 3-D grid that would triple the IK solves for little gain.
REFINE = 3
GROW = {2: True, 3: False}  # grid dimension -> refine the boundary cells' neighbours too
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
    above the mounting plane, no self-collision) finds a configuration for it. Between grid
    points the occupancy is interpolated (multilinearly) and thresholded at one half, so the
    boundary falls between a reachable and an unreachable point instead of snapping to cells.

    The sampled grid is either the 3-D grid itself or, for an arm whose first joint turns a
    full revolution, a (radius, height) profile revolved about the base's axis. Either way its
    boundary cells carry a REFINE-times finer sub-grid that answers inside them.

    Attributes:
        model: the registry name of the arm.
        digest: the model hash the map was built for.
        origin: base-frame coordinates of grid point (0, 0, 0).
        resolution: spacing of the grid (m).
        reachable: boolean occupancy, indexed [ix, iy, iz].
        profile: the (radius, height) occupancy of a revolving arm, else ``None``.
        profile_origin_z, profile_resolution: height of profile row 0 and the profile spacing.
        fine_cells: refined cells of the sampled grid (m×d, d = 2 for a profile, 3 for the
            grid): the cell between points ``c`` and ``c + 1`` on every axis.
        fine: their occupancy on a (REFINE + 1)^d sub-grid whose corners are the coarse points.
    """

    model: str
    digest: str
    origin: tuple[float, float, float]
    resolution: float
    reachable: np.ndarray
    profile: np.ndarray | None = None
    profile_origin_z: float = 0.0
    profile_resolution: float = 0.0
    fine_cells: np.ndarray | None = None
    fine: np.ndarray | None = None

    def occupancy(self, points: FloatArray) -> FloatArray:
        """Interpolated occupancy (0…1) at base-frame ``points`` (n×3); 0 outside the grid."""
        pts = np.atleast_2d(np.asarray(points, dtype=float))
        if self.profile is not None:
            grid = self.profile
            g = np.empty((len(pts), 2))
            g[:, 0] = np.hypot(pts[:, 0], pts[:, 1]) / self.profile_resolution
            g[:, 1] = (pts[:, 2] - self.profile_origin_z) / self.profile_resolution
        else:
            grid = self.reachable
            g = (pts - np.asarray(self.origin)) / self.resolution
        occ = _multilinear(grid, g)
        if self.fine is not None and self.fine_cells is not None and len(self.fine):
            _refined(occ, g, grid.shape, self.fine_cells, self.fine)
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


# The 2^d corner offsets of a d-dimensional cell (2^d × d), for profiles (2) and grids (3).
_CORNERS = {d: np.array(list(itertools.product((0, 1), repeat=d)), dtype=int) for d in (2, 3)}


def _lerp(
    table: np.ndarray, lead: tuple[np.ndarray, ...], i0: np.ndarray, f: FloatArray
) -> FloatArray:
    """Multilinear interpolation in the cells whose lower corners are ``i0`` (n×d) at the
    fractions ``f`` (n×d) of ``table[*lead, corner indices]`` (boolean)."""
    c = _CORNERS[f.shape[1]]
    idx = i0[:, None, :] + c[None, :, :]  # n × 2^d × d
    values = table[(*lead, *(idx[:, :, j] for j in range(idx.shape[2])))]
    weights = np.where(c[None, :, :] == 1, f[:, None, :], 1.0 - f[:, None, :]).prod(axis=2)
    return np.asarray((values * weights).sum(axis=1), dtype=float)


def _multilinear(grid: np.ndarray, g: FloatArray) -> FloatArray:
    """Multilinear interpolation of the boolean d-dimensional ``grid`` at fractional indices
    ``g`` (n×d); 0 outside."""
    i0 = np.floor(g).astype(int)
    inside = ((i0 >= 0) & (i0 + 1 < np.asarray(grid.shape))).all(axis=1)
    out = np.zeros(len(g))
    if inside.any():
        i0 = i0[inside]
        out[inside] = _lerp(grid, (), i0, g[inside] - i0)
    return out


def _refined(
    occ: FloatArray,
    g: FloatArray,
    shape: tuple[int, ...],
    cells: np.ndarray,
    fine: np.ndarray,
) -> None:
    """Replace ``occ`` (in place) inside refined cells by their fine sub-grid's multilinear
    interpolation; ``g`` (n×d) are fractional indices of the sampled grid of ``shape``."""
    cell_shape = tuple(s - 1 for s in shape)
    i = np.floor(g).astype(int)
    inside = ((i >= 0) & (i < np.asarray(cell_shape))).all(axis=1)
    if not inside.any():
        return
    # cells come from argwhere: sorted in C order, so their flat indices are sorted too
    keys = np.ravel_multi_index(tuple(cells.T), cell_shape)
    query = np.ravel_multi_index(tuple(i[inside].T), cell_shape)
    pos = np.minimum(np.searchsorted(keys, query), len(keys) - 1)
    hit = keys[pos] == query
    sel = np.flatnonzero(inside)[hit]
    if not len(sel):
        return
    n = fine.shape[1] - 1
    f = (g[sel] - i[sel]) * n
    a = np.minimum(np.floor(f).astype(int), n - 1)
    occ[sel] = _lerp(fine, (pos[hit][:, None],), a, f - a)


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
    point within their span. Random configurations seed the IK starts near each point. Either
    sampled grid then has its boundary cells refined (:func:`_refine`).
    """
    if arm.base.any():
        arm = Arm(arm.robot, arm.spec.name)  # maps live in the base frame
    lo, shape = _grid(arm, resolution)
    origin = (float(lo[0]), float(lo[1]), float(lo[2]))
    digest = model_hash(arm.spec.name)
    if arm.lower[0] <= -np.pi + 0.02 and arm.upper[0] >= np.pi - 0.02:
        h = resolution / 2.0
        z_lo = float(lo[2])
        r_max = float(np.hypot(arm.shoulder_offset[0], arm.shoulder_offset[1]) + arm.max_extent)
        n_r = len(np.arange(0.0, r_max + 2 * h, h))
        n_z = len(np.arange(z_lo, z_lo + (shape[2] - 1) * resolution + 2 * h, h))

        def on_profile(g: FloatArray) -> FloatArray:
            return np.stack([g[:, 0] * h, np.zeros(len(g)), z_lo + g[:, 1] * h], axis=1)

        prof, cells, fine = _sample(arm, (n_r, n_z), on_profile, h, seed, ik_starts)
        flat = ReachMap(
            arm.spec.name,
            digest,
            origin,
            resolution,
            np.zeros(shape, bool),
            prof,
            z_lo,
            h,
            cells,
            fine,
        )
        idx = np.array(list(np.ndindex(*shape)))
        reach = flat.contains(lo + idx * resolution).reshape(shape)
        return ReachMap(
            arm.spec.name, digest, origin, resolution, reach, prof, z_lo, h, cells, fine
        )

    def on_grid(g: FloatArray) -> FloatArray:
        return np.asarray(lo + g * resolution, dtype=float)

    reach, cells, fine = _sample(arm, shape, on_grid, resolution, seed, ik_starts)
    return ReachMap(arm.spec.name, digest, origin, resolution, reach, fine_cells=cells, fine=fine)


def _sample(
    arm: Arm,
    shape: tuple[int, ...],
    at: Callable[[FloatArray], FloatArray],
    spacing: float,
    seed: int,
    ik_starts: int,
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """IK on every point of a grid of ``shape`` (``at`` maps fractional grid indices to
    base-frame points), then on the boundary cells' sub-grids: (grid, cells, fine)."""
    idx = np.array(list(np.ndindex(*shape)), dtype=float)
    grid = _ik_grid(arm, at(idx), spacing, seed, ik_starts).reshape(shape)
    cells, fine = _refine(arm, grid, at, spacing, seed + 1, ik_starts)
    return grid, cells, fine


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


def _refine(
    arm: Arm,
    grid: np.ndarray,
    at: Callable[[FloatArray], FloatArray],
    spacing: float,
    seed: int,
    ik_starts: int,
) -> tuple[np.ndarray, np.ndarray]:
    """IK on a REFINE-times finer sub-grid of every boundary cell of the d-dimensional ``grid``.

    A boundary cell has corners that disagree; with ``GROW[d]`` its 3^d − 1 neighbours are
    refined too. Returns the cells (m×d, sorted) and their sub-grids (m × (REFINE+1)^d); a
    sub-grid's corners are the coarse points, and neighbouring cells share their faces' points
    (each solved once).
    """
    n, d = REFINE, grid.ndim
    corners = sum(
        (grid[tuple(slice(c, s - 1 + c) for c, s in zip(off, grid.shape, strict=True))]).astype(
            np.int8
        )
        for off in _CORNERS[d]
    )
    mixed = (corners > 0) & (corners < 2**d)
    grown = mixed.copy()
    if GROW[d]:
        for axis in range(d):
            before = grown.copy()
            lead = [slice(None)] * d
            lag = [slice(None)] * d
            lead[axis], lag[axis] = slice(1, None), slice(None, -1)
            grown[tuple(lead)] |= before[tuple(lag)]
            grown[tuple(lag)] |= before[tuple(lead)]
    cells = np.argwhere(grown)
    if not len(cells):
        return np.zeros((0, d), dtype=int), np.zeros((0, *([n + 1] * d)), dtype=bool)
    sub = np.array(list(np.ndindex(*([n + 1] * d))), dtype=int)  # (n+1)^d × d, C order
    keys = (cells[:, None, :] * n + sub[None, :, :]).reshape(-1, d)
    uniq, inverse = np.unique(keys, axis=0, return_inverse=True)
    on_coarse = (uniq % n == 0).all(axis=1)
    values = np.zeros(len(uniq), dtype=bool)
    values[on_coarse] = grid[tuple((uniq[on_coarse] // n).T)]
    todo = uniq[~on_coarse]
    values[~on_coarse] = _ik_grid(arm, at(todo / n), spacing / n, seed, ik_starts)
    fine = values[inverse.ravel()].reshape(len(cells), *([n + 1] * d))
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
            fine = f["fine"].astype(bool)
            return ReachMap(
                model,
                str(f["digest"]),
                (float(f["origin"][0]), float(f["origin"][1]), float(f["origin"][2])),
                float(f["resolution"]),
                f["reachable"].astype(bool),
                prof,
                float(f["profile_meta"][0]),
                float(f["profile_meta"][1]),
                f["fine_cells"] if len(fine) else None,
                fine if len(fine) else None,
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
