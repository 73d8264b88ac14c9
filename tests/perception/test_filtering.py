"""Temporal filters of people and objects, and left/right relabelling of skeletons."""

from __future__ import annotations

import copy
import math

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.perception.filtering import RestingFilter, WalkerFilter
from hltl.perception.skeleton import Skeleton, orient_sides


def _walk(heading: float, speed: float, n: int = 40, dt: float = 0.1) -> list[tuple[float, float]]:
    return [
        (1.0 + speed * k * dt * math.cos(heading), -0.5 + speed * k * dt * math.sin(heading))
        for k in range(n)
    ]


# derandomized: the mean-error and velocity bounds are statistical (about 1 noise draw in 1,500
# breaks the velocity one), so CI must not draw new examples on every run
@settings(max_examples=15, deadline=None, derandomize=True)
@given(st.floats(-math.pi, math.pi), st.floats(0.0, 1.5), st.integers(0, 2**31 - 1))
def test_walker_filter_beats_raw_measurements_and_ignores_one_outlier(
    heading: float, speed: float, seed: int
) -> None:
    rng = np.random.default_rng(seed)
    truth = _walk(heading, speed)
    f = WalkerFilter()
    raw_err, filt_err = [], []
    for k, (x, y) in enumerate(truth):
        m = (x + rng.normal(0, 0.03), y + rng.normal(0, 0.03), 1.0)
        if k == 30:  # one frame measures a neighbour 1 m away
            m = (x + 1.0, y, 1.0)
        if k == 30:
            # not folded in: the estimate is the filter's own prediction (a hard bound on its
            # distance to the truth fails on rare noise draws at 1.5 m/s; the old one did)
            ahead = copy.deepcopy(f).predict(0.1 * k)
            est = f.update(m, 0.1 * k)
            assert math.dist(est[:2], (float(ahead[0]), float(ahead[1]))) < 1e-9
            assert math.dist(est[:2], (x, y)) < 0.3  # folding 1 m in would move it further
            continue
        est = f.update(m, 0.1 * k)
        if k >= 10:
            raw_err.append(math.dist(m[:2], (x, y)))
            filt_err.append(math.dist(est[:2], (x, y)))
    assert f.gated >= 1
    assert float(np.mean(filt_err)) < float(np.mean(raw_err))
    assert math.dist(f.velocity, (speed * math.cos(heading), speed * math.sin(heading))) < 0.45


def test_walker_filter_restarts_where_the_person_really_is() -> None:
    f = WalkerFilter(resets=3)
    for k in range(10):
        f.update((0.0, 0.0, 1.0), 0.1 * k)
    out = [f.update((2.0, 0.0, 1.0), 1.0 + 0.1 * k) for k in range(3)]
    assert out[0][0] < 0.1 and out[1][0] < 0.1  # two frames: held back
    assert out[2] == (2.0, 0.0, 1.0)  # the third: restarted there


def test_resting_filter_averages_and_needs_two_frames_to_move() -> None:
    f = RestingFilter()
    rng = np.random.default_rng(0)
    ests = [f.update((0.5 + rng.normal(0, 0.005), 0.2, 0.05)) for _ in range(10)]
    assert abs(ests[-1][0] - 0.5) < 0.004
    assert f.update((0.9, 0.2, 0.05))[0] < 0.51  # one stray frame: held back
    assert f.update((0.5, 0.2, 0.05))[0] < 0.51
    assert f.update((0.8, 0.2, 0.05))[0] < 0.51  # moved: first frame held back
    assert f.update((0.8, 0.2, 0.05))[0] == 0.8  # second agreeing frame: moved
    assert f.held_back == 3  # every measurement outside the gate


def _skeleton(heading: float, centre: tuple[float, float]) -> Skeleton:
    left = (-math.sin(heading), math.cos(heading))
    joints = []
    for name, off in (("shoulder", 0.19), ("elbow", 0.22), ("wrist", 0.2)):
        for side, sign in (("l", 1.0), ("r", -1.0)):
            p = (centre[0] + sign * off * left[0], centre[1] + sign * off * left[1], 1.2)
            joints.append((f"{side}_{name}", p))
    return Skeleton(tuple(joints), tuple((k, (float(i), 0.0)) for i, (k, _) in enumerate(joints)))


def _swapped(sk: Skeleton) -> Skeleton:
    ren = {k: ("r" if k[0] == "l" else "l") + k[1:] for k, _ in sk.joints}
    j, p = dict(sk.joints), dict(sk.pixels)
    return Skeleton(
        tuple((k, j[ren[k]]) for k, _ in sk.joints), tuple((k, p[ren[k]]) for k, _ in sk.pixels)
    )


@settings(max_examples=25, deadline=None)
@given(st.floats(-math.pi, math.pi), st.floats(0.6, 1.5))
def test_walking_skeletons_get_their_sides_from_the_heading(heading: float, speed: float) -> None:
    centre = (0.3, -0.7)
    v = (speed * math.cos(heading), speed * math.sin(heading))
    right = _skeleton(heading, centre)
    assert orient_sides(right, centre, v) == right
    assert orient_sides(_swapped(right), centre, v) == right
    # a lone joint on the wrong side takes the other side's name
    lone = Skeleton(
        tuple((k, p if k == "r_wrist" else None) for k, p in _swapped(right).joints),
        tuple((k, None) for k, _ in right.pixels),
    )
    fixed = orient_sides(lone, centre, v)
    assert fixed.joint("l_wrist") == right.joint("l_wrist") and fixed.joint("r_wrist") is None


def test_standing_skeletons_keep_the_labelling_of_the_previous_frame() -> None:
    centre = (0.0, 0.0)
    before = _skeleton(0.4, centre)
    now = _swapped(_skeleton(0.45, centre))
    fixed = orient_sides(now, centre, (0.0, 0.05), before)
    assert fixed == _skeleton(0.45, centre)
    assert orient_sides(now, centre, None, None) == now  # nothing to go by: unchanged
