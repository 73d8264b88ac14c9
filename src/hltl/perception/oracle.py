"""A forecaster that knows the walk generator's process: how good a forecaster can be."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
import numpy.typing as npt

from hltl.perception.forecast import F64, T_OBS, T_PRED
from hltl.perception.gru import frame_of
from hltl.perception.predict import GoalDirectedPredictor
from hltl.perception.walks import MIX, generate_walks

F32 = npt.NDArray[np.float32]
MIRROR = np.array([1.0, -1.0])
LIBRARY_SEED = 70000  # the library's walks: not a test set's (1000+) nor training's (0) seed


@dataclass(frozen=True, slots=True)
class Library:
    """Windows of generated walks in their observations' frames.

    Attributes:
        obs: (n, (T_OBS - 1) * 2) observed points before the last (the last is the origin).
        fut: (n, T_PRED, 2) true future points.
    """

    obs: F32
    fut: F32


def local_window(obs: F64) -> tuple[F64, F64, F64]:
    """(origin, rotation, the observed points before the last in that frame, flattened)."""
    origin, rot = frame_of(obs)
    return origin, rot, ((obs - origin) @ rot.T)[:-1].ravel()


def build_library(seed: int, walks: int, mix: Sequence[float] = MIX) -> Library:
    """Every window (observed T_OBS samples, clamped at the walk's start, and T_PRED true future
    samples) of ``walks`` generated walks, and its mirror image."""
    obs: list[F64] = []
    fut: list[F64] = []
    for w in generate_walks(seed, walks, mix=mix):
        n = len(w.true)
        for i in range(n - T_PRED):
            idx = np.clip(np.arange(i - T_OBS + 1, i + 1), 0, None)
            origin, rot, x = local_window(w.observed[idx])
            obs.append(x)
            fut.append((w.true[i + 1 : i + 1 + T_PRED] - origin) @ rot.T)
    o = np.array(obs, dtype=np.float32).reshape(-1, (T_OBS - 1) * 2)
    f = np.array(fut, dtype=np.float32).reshape(-1, T_PRED, 2)
    mirror = np.tile(MIRROR, T_OBS - 1).astype(np.float32)
    return Library(
        np.concatenate([o, o * mirror]), np.concatenate([f, f * MIRROR.astype(np.float32)])
    )


def geometric_median(points: F64, iterations: int = 50) -> F64:
    """Per-step geometric median of ``points`` (k, T, 2) by Weiszfeld's iteration → (T, 2)."""
    m = points.mean(axis=0)
    for _ in range(iterations):
        d = np.maximum(np.linalg.norm(points - m, axis=2), 1e-9)
        w = 1.0 / d
        m = (w[..., None] * points).sum(axis=0) / w.sum(axis=0)[:, None]
    return np.asarray(m, dtype=float)


class LibraryForecaster:
    """Nearest-window forecasts from a :class:`Library` (see the module's docstring).

    Args:
        library: the windows.
        k: how many nearest windows a forecast takes the median of.
    """

    def __init__(self, library: Library, k: int = 100) -> None:
        from scipy.spatial import cKDTree

        if k < 1 or k > len(library.obs):
            raise ValueError(f"k must be 1..{len(library.obs)}, got {k}")
        self.library = library
        self.k = k
        self._tree: Any = cKDTree(library.obs)

    def forecast(self, obs: F64) -> F64:
        """(T_PRED, 2) world forecast after the observed grid track ``obs`` (T_OBS, 2)."""
        origin, rot, x = local_window(obs)
        _, idx = self._tree.query(x, k=self.k)
        near = self.library.fut[np.atleast_1d(idx)].astype(float)
        return np.asarray(geometric_median(near) @ rot + origin, dtype=float)


class OraclePredictor(GoalDirectedPredictor):
    """The live predictor interface over a :class:`LibraryForecaster` (for :mod:`evaluate`)."""

    def __init__(self, stops: F64, forecaster: LibraryForecaster) -> None:
        super().__init__(stops)
        self.forecaster = forecaster

    def _forecast(self, obs: F64) -> F64:
        return self.forecaster.forecast(obs)
