"""Human trajectory predictors: constant velocity, goal-directed, learned GRU (paper §III-A)."""

from __future__ import annotations

from collections import deque
from collections.abc import Iterable, Sequence
from pathlib import Path
from typing import Protocol, runtime_checkable

import numpy as np

from hltl.perception.forecast import (
    DT,
    F64,
    MIN_SPEED,
    T_OBS,
    goal_forecast,
    resample,
    stop_places,
)
from hltl.perception.gru import GRUModel, load_model
from hltl.world.scene import Scene, Vec3

PREDICTORS = ("cv", "goal", "gru")


@runtime_checkable
class TrajectoryPredictor(Protocol):
    """Forecasts where each person will be."""

    def observe(self, t: float, humans: Iterable[tuple[str, Vec3]]) -> None:
        """Feed the positions observed at time ``t`` (perception time stamps, increasing)."""
        ...

    def predict(self, human: str, times: Sequence[float]) -> list[Vec3]:
        """The forecast positions of ``human`` at the absolute times ``times``."""
        ...

    def moving(self, human: str) -> bool:
        """Whether ``human`` is currently predicted to move at all."""
        ...


class _History:
    """Per-person observation history, the last ``keep`` seconds."""

    def __init__(self, keep: float) -> None:
        self.keep = keep
        self._history: dict[str, deque[tuple[float, Vec3]]] = {}

    def observe(self, t: float, humans: Iterable[tuple[str, Vec3]]) -> None:
        for hid, pos in humans:
            hist = self._history.setdefault(hid, deque())
            if hist and t <= hist[-1][0]:
                continue  # a stale or repeated observation adds nothing
            hist.append((t, pos))
            while hist and hist[0][0] < t - self.keep - 1e-9:
                hist.popleft()

    def get(self, human: str) -> deque[tuple[float, Vec3]]:
        hist = self._history.get(human)
        if not hist:
            raise KeyError(f"no observation of human {human!r} yet")
        return hist

    def __contains__(self, human: object) -> bool:
        return human in self._history


class ConstantVelocityPredictor(_History):
    """Constant-velocity forecasts from a least-squares fit over a sliding window (the baseline).

    The fit smooths perception noise: a person standing still with 1 cm noise at 20 Hz would
    otherwise look like someone walking at 0.3 m/s. Speeds below ``min_speed`` count as standing.

    Args:
        window: seconds of history the velocity is fitted on.
        min_speed: m/s below which a person is taken to stand still.
    """

    def __init__(self, window: float = 0.4, min_speed: float = MIN_SPEED) -> None:
        if window <= 0:
            raise ValueError(f"window must be positive, got {window!r}")
        super().__init__(window)
        self.window = window
        self.min_speed = min_speed

    def _fit(self, human: str) -> tuple[float, Vec3, tuple[float, float]]:
        """(time of the last sample, fitted position then, horizontal velocity)."""
        hist = self.get(human)
        t_last = hist[-1][0]
        n = len(hist)
        ts = [s[0] for s in hist]
        mean_t = sum(ts) / n
        mean = tuple(sum(s[1][i] for s in hist) / n for i in range(3))
        var = sum((x - mean_t) ** 2 for x in ts)
        if n < 3 or var <= 1e-12:
            return t_last, hist[-1][1], (0.0, 0.0)
        vx = sum((s[0] - mean_t) * (s[1][0] - mean[0]) for s in hist) / var
        vy = sum((s[0] - mean_t) * (s[1][1] - mean[1]) for s in hist) / var
        if (vx * vx + vy * vy) ** 0.5 < self.min_speed:
            return t_last, (mean[0], mean[1], mean[2]), (0.0, 0.0)
        dt = t_last - mean_t
        return t_last, (mean[0] + vx * dt, mean[1] + vy * dt, hist[-1][1][2]), (vx, vy)

    def velocity(self, human: str) -> tuple[float, float]:
        """The fitted horizontal velocity (m/s); zero for a person standing still."""
        return self._fit(human)[2]

    def moving(self, human: str) -> bool:
        return human in self and self.velocity(human) != (0.0, 0.0)

    def predict(self, human: str, times: Sequence[float]) -> list[Vec3]:
        t0, p, (vx, vy) = self._fit(human)
        return [(p[0] + vx * (t - t0), p[1] + vy * (t - t0), p[2]) for t in times]


def _interp_forecast(t0: float, grid: F64, z: float, times: Sequence[float]) -> list[Vec3]:
    """Positions at absolute ``times`` from a grid forecast starting DT after ``t0`` (the
    observed time ``t0`` itself is the first grid point's predecessor); held beyond its end."""
    ts = t0 + DT * np.arange(0, len(grid))
    out: list[Vec3] = []
    for t in times:
        x = float(np.interp(t, ts, grid[:, 0]))
        y = float(np.interp(t, ts, grid[:, 1]))
        out.append((x, y, z))
    return out


class GoalDirectedPredictor(_History):
    """Walks a moving person toward the nearest plausible stopping place ahead and stops there.

    Args:
        stops: (n, 2) stopping places (see :func:`stop_places`).
    """

    def __init__(self, stops: F64) -> None:
        super().__init__(keep=DT * (T_OBS + 1))
        self.stops = np.asarray(stops, dtype=float).reshape(-1, 2)
        self._cache: dict[str, tuple[float, F64, F64, float]] = {}

    def _grid(self, human: str) -> tuple[float, F64, F64, float]:
        """(last time, observed grid track, grid forecast including the present, z)."""
        hist = self.get(human)
        t_last = hist[-1][0]
        hit = self._cache.get(human)
        if hit is not None and hit[0] == t_last:
            return hit
        xy = np.array([p[:2] for _, p in hist], dtype=float)
        obs = resample([t for t, _ in hist], xy, t_last)
        fc = np.concatenate([obs[-1:], self._forecast(obs)], axis=0)
        out = (t_last, obs, fc, hist[-1][1][2])
        self._cache[human] = out
        return out

    def _forecast(self, obs: F64) -> F64:
        return goal_forecast(obs, self.stops)

    def moving(self, human: str) -> bool:
        if human not in self:
            return False
        _, _, fc, _ = self._grid(human)
        return float(np.hypot(*(fc[-1] - fc[0]))) > 0.05

    def predict(self, human: str, times: Sequence[float]) -> list[Vec3]:
        t_last, _, fc, z = self._grid(human)
        return _interp_forecast(t_last, fc, z, times)


class GRUPredictor(GoalDirectedPredictor):
    """The learned predictor: a GRU over the observed track that corrects the goal-directed
    forecast, given the nearest stopping places (see :mod:`hltl.perception.gru`).

    Args:
        stops: (n, 2) stopping places.
        weights: a weights file written by ``hltl perception train-predictor`` (default: the
            shipped one).
        model: an already loaded model (shared between predictors); overrides ``weights``.

    Raises:
        BackendUnavailableError: torch (extra ``predict``) is not installed.
    """

    def __init__(
        self, stops: F64, weights: str | Path | None = None, model: GRUModel | None = None
    ) -> None:
        super().__init__(stops)
        if model is None:
            model = load_model(weights)
        self.model: GRUModel = model

    def _forecast(self, obs: F64) -> F64:
        return self.model.forecast(obs, self.stops)


def make_predictor(
    name: str, scene: Scene, weights: str | Path | None = None
) -> TrajectoryPredictor:
    """The predictor called ``name`` (one of PREDICTORS) for ``scene``.

    Raises:
        ValueError: unknown name.
        BackendUnavailableError: ``gru`` without torch.
    """
    if name == "cv":
        return ConstantVelocityPredictor()
    if name == "goal":
        return GoalDirectedPredictor(stop_places(scene))
    if name == "gru":
        return GRUPredictor(stop_places(scene), weights)
    raise ValueError(f"unknown predictor {name!r}; expected one of {', '.join(PREDICTORS)}")
