"""The forecaster that knows the walk generator: its library, its frame and its median."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.perception.forecast import T_OBS, T_PRED
from hltl.perception.oracle import LibraryForecaster, build_library, geometric_median
from hltl.perception.walks import generate_walks

WANDER = (0.0, 0.0, 0.0, 0.0, 1.0)


def test_a_library_window_forecasts_its_own_future_wherever_and_mirrored() -> None:
    lib = build_library(5, 2, WANDER)
    forecaster = LibraryForecaster(lib, k=1)
    walk = generate_walks(5, 2, mix=WANDER)[1]
    moving = [
        i
        for i in range(T_OBS, len(walk.true) - T_PRED)
        if np.ptp(walk.true[i - T_OBS + 1 : i + 1], axis=0).max() > 0.3
    ]
    assert moving
    a = math.radians(37.0)
    rot = np.array([[math.cos(a), -math.sin(a)], [math.sin(a), math.cos(a)]])
    shift = np.array([3.0, -1.5])
    mirror = np.array([1.0, -1.0])
    for i in moving[:: max(1, len(moving) // 5)]:
        obs = walk.observed[i - T_OBS + 1 : i + 1]
        fut = walk.true[i + 1 : i + 1 + T_PRED]
        # the same window: its own future (float32 library: 1e-5 m)
        assert np.allclose(forecaster.forecast(obs), fut, atol=1e-4)
        # turned and moved: the same window in its own frame, so the future turned and moved
        assert np.allclose(forecaster.forecast(obs @ rot.T + shift), fut @ rot.T + shift, atol=1e-4)
        # mirrored: the library's mirror image of it
        assert np.allclose(forecaster.forecast(obs * mirror), fut * mirror, atol=1e-4)
    with pytest.raises(ValueError, match="k must be"):
        LibraryForecaster(lib, k=0)


@settings(max_examples=25, deadline=None)
@given(st.integers(0, 2**31 - 1), st.integers(1, 9))
def test_the_median_minimises_the_summed_distance(seed: int, k: int) -> None:
    rng = np.random.default_rng(seed)
    pts = rng.normal(0.0, 1.0, (k, 3, 2)) * rng.uniform(0.01, 2.0)
    m = geometric_median(pts, iterations=500)

    def cost(c: np.ndarray, t: int) -> float:  # type: ignore[type-arg]
        return float(np.linalg.norm(pts[:, t] - c, axis=1).sum())

    for t in range(3):
        best = cost(m[t], t)
        # no point near it, nor any sample, does better (to 1e-4 relative: Weiszfeld's
        # iteration converges slowly when the median is a sample)
        for c in [*pts[:, t], *(m[t] + 1e-3 * rng.normal(size=(50, 2)))]:
            assert best <= cost(c, t) * (1 + 1e-4) + 1e-9
