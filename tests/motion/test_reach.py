"""Reachability maps: disk cache keyed by model hash, agreement with IK, the Kinematics seam."""

from __future__ import annotations

import os
from typing import Any

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.motion.kinematics import Arm
from hltl.motion.reach import _cache_file, load_or_build
from hltl.motion.workspace import MapKinematics
from hltl.world.scene import Scene, scene_from_dict


def test_maps_are_cached_by_model_hash(coarse_maps: dict[str, Any]) -> None:
    path = _cache_file("elfin3", 0.1)
    assert path.exists()
    assert coarse_maps["elfin3"].digest in path.name
    assert str(path).startswith(os.environ["HLTL_CACHE"])
    again = load_or_build("elfin3", 0.1)
    assert np.array_equal(again.reachable, coarse_maps["elfin3"].reachable)
    assert again.profile is not None
    assert again.fine is not None and coarse_maps["elfin3"].fine is not None
    assert len(again.fine) > 0 and np.array_equal(again.fine, coarse_maps["elfin3"].fine)


def test_map_agrees_with_ik_on_random_probes(coarse_maps: dict[str, Any]) -> None:
    arm = Arm("r", "elfin3")
    m = coarse_maps["elfin3"]
    rng = np.random.default_rng(3)
    lo = np.asarray(m.origin)
    hi = lo + (np.asarray(m.reachable.shape) - 1) * m.resolution
    probes = rng.uniform(lo, hi, (120, 3))
    pred = m.contains(probes)
    truth = np.array([arm.ik(p, None, starts=8).ok for p in probes])
    # coarse test grid (10 cm); `hltl bench motion` measures the real 3 cm maps (>= 99 %)
    assert (pred == truth).mean() >= 0.9
    assert truth.any() and not truth.all()


def test_fig1_workspaces_and_context_come_from_the_maps(
    fig1: Scene, coarse_maps: dict[str, Any]
) -> None:
    kin = MapKinematics(fig1, coarse_maps)
    r1, r2 = fig1.robots
    bottle, chips = fig1.object("bottle"), fig1.object("chips")
    assert kin.reaches(r1, bottle.position) and not kin.reaches(r2, bottle.position)
    assert kin.reaches(r2, chips.position) and not kin.reaches(r1, chips.position)
    ctx = kin.context_label(fig1, {h.id: h.position for h in fig1.humans})
    assert ctx.robots_serving("A") == frozenset({"r1"})
    assert ctx.robots_serving("B") == frozenset({"r2"})
    rv = kin.rendezvous(r1, r2)
    assert rv is not None and rv.radius > 0.1
    assert kin.reaches(r1, rv.centre) and kin.reaches(r2, rv.centre)
    # the inscribed sphere lies inside both maps: sample its surface
    rng = np.random.default_rng(0)
    d = rng.normal(size=(50, 3))
    d /= np.linalg.norm(d, axis=1, keepdims=True)
    pts = np.asarray(rv.centre) + 0.9 * rv.radius * d
    assert kin.reaches_many(r1, pts).all() and kin.reaches_many(r2, pts).all()


def test_robots_without_a_model_keep_the_sphere(coarse_maps: dict[str, Any]) -> None:
    scene = scene_from_dict(
        {
            "robots": [
                {"id": "a", "base": [0, 0, 0], "reach": 0.5, "model": "kr6"},
                {"id": "b", "base": [0.8, 0, 0], "reach": 0.5},
            ]
        }
    )
    kin = MapKinematics(scene, coarse_maps)
    a, b = scene.robots
    assert kin.map_of(a) is None
    assert kin.reaches(a, (0.45, 0.0, 0.0)) and not kin.reaches(a, (0.55, 0.0, 0.0))
    assert kin.can_meet(a, b)
    assert kin.rendezvous_point(a, b)[0] == 0.4


def test_refined_boundary_cells_answer_from_their_fine_grid() -> None:
    from hltl.motion.reach import REFINE, ReachMap

    n = REFINE
    prof = np.zeros((3, 3), dtype=bool)
    prof[0, :] = True  # reachable at radius 0, not beyond: every cell of column 0 is a boundary
    fine = np.zeros((1, n + 1, n + 1), dtype=bool)
    fine[0, :n, :] = True  # the fine grid says the boundary lies one fine step before radius h
    h = 0.1
    m = ReachMap(
        "x",
        "",
        (0.0, 0.0, 0.0),
        h,
        np.zeros((1, 1, 1), dtype=bool),
        prof,
        0.0,
        h,
        np.array([[0, 0]]),
        fine,
    )
    # inside the refined cell (0, 0): fine values; the neighbouring unrefined cell (0, 1): coarse
    step = h / n
    radius = (n - 1) * step + 0.25 * step  # a quarter fine step past the last reachable point
    assert m.occupancy(np.array([[radius, 0.0, 0.5 * h]]))[0] == pytest.approx(0.75)
    coarse = radius / h  # bilinear on the coarse profile: 1 - u
    assert m.occupancy(np.array([[radius, 0.0, 1.5 * h]]))[0] == pytest.approx(1.0 - coarse)
    # the fine grid's corners are the coarse points, so the two agree on the cell's corners
    corners = np.array([[0.0, 0.0, 0.0], [0.0, 0.0, h], [h, 0.0, 0.0]])
    assert np.allclose(m.occupancy(corners), [1.0, 1.0, 0.0])


@settings(max_examples=40, deadline=None)
@given(
    dims=st.sampled_from([2, 3]),
    cells_per_axis=st.lists(st.integers(1, 3), min_size=3, max_size=3),
    seed=st.integers(0, 2**32 - 1),
)
def test_refined_maps_interpolate_their_fine_grid(
    dims: int, cells_per_axis: list[int], seed: int
) -> None:
    """One code path for profiles (2-D) and grids (3-D): inside a refined cell the occupancy is
    the fine grid's multilinear interpolation, elsewhere the coarse grid's. Oracle: scipy's
    RegularGridInterpolator on the whole fine grid (whose every REFINE-th point is the coarse
    grid) and on the coarse grid."""
    from scipy.interpolate import RegularGridInterpolator

    from hltl.motion.reach import REFINE, ReachMap

    n, h = REFINE, 0.1
    rng = np.random.default_rng(seed)
    shape = tuple(c * n + 1 for c in cells_per_axis[:dims])
    full = rng.random(shape) < 0.5
    coarse = full[tuple(slice(None, None, n) for _ in shape)]
    every = np.argwhere(np.ones(tuple(s - 1 for s in coarse.shape), dtype=bool))
    cells = every[rng.random(len(every)) < 0.5]
    fine = np.array(
        [full[tuple(slice(c * n, c * n + n + 1) for c in cell)] for cell in cells], dtype=bool
    ).reshape(len(cells), *([n + 1] * dims))
    # fractional coarse indices inside the grid, and a few on cell faces and corners
    g = rng.uniform(0, np.array(coarse.shape) - 1, (300, dims))
    g[:20] = np.round(g[:20] * n) / n
    if dims == 3:
        m = ReachMap("x", "", (0.0, 0.0, 0.0), h, coarse, fine_cells=cells, fine=fine)
        pts = g * h
    else:
        m = ReachMap(
            "x", "", (0.0, 0.0, 0.0), h, np.zeros((1, 1, 1), bool), coarse, 0.0, h, cells, fine
        )
        pts = np.stack([g[:, 0] * h, np.zeros(len(g)), g[:, 1] * h], axis=1)
    axes_fine = [np.arange(s) / n for s in shape]
    axes_coarse = [np.arange(s, dtype=float) for s in coarse.shape]
    want_fine = RegularGridInterpolator(axes_fine, full.astype(float))(g)
    want_coarse = RegularGridInterpolator(axes_coarse, coarse.astype(float))(g)
    cell_of = np.minimum(np.floor(g).astype(int), np.array(coarse.shape) - 2)
    refined = {tuple(c) for c in cells}
    in_refined = np.array([tuple(c) in refined for c in cell_of])
    got = m.occupancy(pts)
    # on a face shared by a refined and an unrefined cell both interpolations agree only at the
    # coarse points; off the faces the cell is unambiguous
    on_face = np.any(np.abs(g - np.round(g)) < 1e-9, axis=1)
    sure = ~on_face
    assert np.allclose(got[sure & in_refined], want_fine[sure & in_refined], atol=1e-9)
    assert np.allclose(got[sure & ~in_refined], want_coarse[sure & ~in_refined], atol=1e-9)
    # outside the grid: unreachable
    assert m.occupancy(pts[:1] + 100.0)[0] == 0.0
