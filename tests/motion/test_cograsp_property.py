"""The co-grasp filter against an independent oracle: hands' surface gap by dense axis samples."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

pytest.importorskip("coal")

from hltl.motion.grasps import (
    Cylinder,
    co_grasp_pairs,
    complement,
    grasp_candidates,
    human_hand,
    robot_hand,
)
from hltl.motion.kinematics import Capsule


def _sampled_gap(xs: list[Capsule], ys: list[Capsule]) -> float:
    """Surface distance of two capsule sets by dense samples of their axes (the oracle)."""
    t = np.linspace(0.0, 1.0, 400)[:, None]
    best = math.inf
    for x in xs:
        px = np.asarray(x.a) + t * (np.asarray(x.b) - np.asarray(x.a))
        for y in ys:
            py = np.asarray(y.a) + t * (np.asarray(y.b) - np.asarray(y.a))
            d = np.linalg.norm(px[:, None, :] - py[None, :, :], axis=2).min()
            best = min(best, float(d) - x.radius - y.radius)
    return best


@settings(max_examples=30, deadline=None)
@given(
    radius=st.floats(0.02, 0.06),
    height=st.floats(0.06, 0.3),
    n_angles=st.integers(3, 12),
    n_heights=st.integers(1, 4),
    partner=st.sampled_from(["robot", "human"]),
    gap=st.floats(0.0, 0.05),
)
def test_co_grasp_filter_keeps_exactly_the_pairs_with_room(
    radius: float, height: float, n_angles: int, n_heights: int, partner: str, gap: float
) -> None:
    cyl = Cylinder(radius, height)
    grasps = grasp_candidates(cyl, n_angles=n_angles, n_heights=n_heights)
    kept = co_grasp_pairs(cyl, grasps, partner=partner, gap=gap)
    assert [d for *_, d in kept] == sorted((d for *_, d in kept), reverse=True)
    by_grasp = {g: (c, d) for g, c, d in kept}
    origin = (0.0, 0.0, 0.0)
    tol = 1e-3  # the oracle samples the axes every <= 0.5 mm
    for g in grasps:
        c = complement(g, cyl)
        mine = robot_hand(g, origin, cyl, "giver")
        theirs = (
            robot_hand(c, origin, cyl, "receiver")
            if partner == "robot"
            else [human_hand(c, origin, cyl)]
        )
        true_gap = _sampled_gap(mine, theirs)
        if g in by_grasp:
            kc, d = by_grasp[g]
            assert kc == c and abs(d - true_gap) <= tol and true_gap >= gap - tol
        else:
            assert true_gap < gap + tol  # discarded only when the hands are too close
        if g.kind == "side":  # the receiver's grasp: opposite side, mirrored height
            assert np.allclose(c.approach, -np.asarray(g.approach))
            assert c.height == pytest.approx(-g.height)
            back = complement(c, cyl)
            assert np.allclose(back.approach, g.approach) and back.height == pytest.approx(g.height)
    # a wider gap keeps a subset
    wider = {g for g, _, _ in co_grasp_pairs(cyl, grasps, partner=partner, gap=gap + 0.01)}
    assert wider <= set(by_grasp)
