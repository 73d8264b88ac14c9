"""Human trajectory predictors: constant velocity, goal-directed and a learned GRU (paper §III-A).

Every predictor follows :class:`TrajectoryPredictor` (what the executor's workspace prediction
calls): it is fed the positions perception reports and forecasts a person's positions at given
times. :func:`make_predictor` builds one by name for a scene. The goal-directed and GRU
predictors share :func:`goal_forecast`, a pure function of an observed track and the scene's
plausible stopping places (:func:`stop_places`), so training, evaluation and the live loop use
the same numbers.
"""

from __future__ import annotations

import math
from collections import deque
from collections.abc import Iterable, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Protocol, runtime_checkable

import numpy as np
import numpy.typing as npt

from hltl.world.scene import Scene, Vec3

if TYPE_CHECKING:
    from hltl.perception.gru import GRUModel

F64 = npt.NDArray[np.float64]
PREDICTORS = ("cv", "goal", "gru")

# The resampling grid the goal-directed fit and the GRU work on: 0.1 s steps, 8 observed
# samples (0.7 s of history), 20 forecast samples (2 s).
DT = 0.1
T_OBS = 8
T_PRED = 20
FIT_SAMPLES = 5  # the velocity fit covers the last 0.4 s, like the CV baseline's window
MIN_SPEED = 0.15  # m/s below which a person is taken to stand still
GOAL_CONE = math.radians(30.0)  # a stopping place must lie within this angle of the heading
GOAL_MIN_LATERAL = 0.25  # ... or this close (m) to the heading line


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


# -- stopping places -------------------------------------------------------------------------


def stop_places(scene: Scene, directions: int = 16) -> F64:
    """Plausible places a walking person stops at, as an (n, 2) array of floor points.

    People stop where robots can serve them: a ring around each robot at the distance the
    scene's registered people stand from their nearest base (the median of those distances;
    the human reach if the scene has nobody), in ``directions`` directions, minus points inside
    another robot's ring; plus the registered positions themselves.
    """
    bases = np.array([r.base[:2] for r in scene.robots], dtype=float).reshape(-1, 2)
    people = np.array([h.position[:2] for h in scene.humans], dtype=float).reshape(-1, 2)
    if len(bases) and len(people):
        gaps = np.linalg.norm(people[:, None, :] - bases[None, :, :], axis=2).min(axis=1)
        offset = float(np.median(gaps))
    else:
        offset = max((r.reach for r in scene.robots), default=0.5) + scene.human_reach
    offset = max(offset, 0.2)
    angles = np.arange(directions) * (2.0 * math.pi / directions)
    ring = np.stack([np.cos(angles), np.sin(angles)], axis=1) * offset
    points = [people]
    for b in bases:
        cand = b + ring
        if len(bases) > 1:
            d = np.linalg.norm(cand[:, None, :] - bases[None, :, :], axis=2).min(axis=1)
            cand = cand[d >= offset * 0.9]
        points.append(cand)
    out = np.concatenate(points, axis=0) if points else np.zeros((0, 2))
    return np.unique(np.round(out, 4), axis=0)


# -- the goal-directed forecast --------------------------------------------------------------


def resample(times: Sequence[float], xy: F64, t_end: float, n: int = T_OBS) -> F64:
    """The track at ``t_end - (n-1)·DT … t_end`` by linear interpolation, clamped at its ends
    (a person seen for less than the window is taken to have stood where first seen)."""
    ts = np.asarray(times, dtype=float)
    grid = t_end - DT * np.arange(n - 1, -1, -1)
    return np.stack([np.interp(grid, ts, xy[:, 0]), np.interp(grid, ts, xy[:, 1])], axis=1)


def fit_velocity(obs: F64) -> F64:
    """Least-squares velocity (m/s) over the last FIT_SAMPLES grid samples; zero below
    MIN_SPEED."""
    pts = obs[-FIT_SAMPLES:]
    k = np.arange(len(pts), dtype=float) * DT
    kc = k - k.mean()
    var = float((kc * kc).sum())
    if var <= 0:
        return np.zeros(2)
    v = (kc[:, None] * (pts - pts.mean(axis=0))).sum(axis=0) / var
    return v if float(np.hypot(*v)) >= MIN_SPEED else np.zeros(2)


def choose_goal(p: F64, v: F64, stops: F64) -> F64 | None:
    """The nearest stopping place ahead of a person at ``p`` walking with velocity ``v``: within
    GOAL_CONE of the heading (or GOAL_MIN_LATERAL of the heading line), scored by the distance
    along the heading plus three times the distance off it; None when nothing lies ahead."""
    speed = float(np.hypot(*v))
    if speed <= 0 or len(stops) == 0:
        return None
    u = v / speed
    rel = stops - p
    along = rel @ u
    lateral = np.abs(rel[:, 0] * u[1] - rel[:, 1] * u[0])
    ok = (along > 0.05) & (lateral <= np.maximum(GOAL_MIN_LATERAL, along * math.tan(GOAL_CONE)))
    if not ok.any():
        return None
    score = np.where(ok, along + 3.0 * lateral, np.inf)
    return np.asarray(stops[int(np.argmin(score))], dtype=float)


def goal_forecast(obs: F64, stops: F64, n: int = T_PRED) -> F64:
    """Goal-directed forecast on the grid: ``n`` positions DT apart after the last of ``obs``
    (an (T, 2) track on the grid). The person keeps their fitted speed straight toward the
    nearest stopping place ahead and stops there; with nothing ahead, constant velocity; a
    person standing still stays."""
    p = obs[-1]
    v = fit_velocity(obs)
    speed = float(np.hypot(*v))
    steps = DT * np.arange(1, n + 1)
    # the fit lags half a window behind a person who speeds up: anchor at the fitted position
    k = np.arange(min(FIT_SAMPLES, len(obs)), dtype=float) * DT
    anchor = obs[-len(k) :].mean(axis=0) + v * (k[-1] - k.mean()) if speed > 0 else p
    goal = choose_goal(anchor, v, stops)
    if speed == 0:
        return np.repeat(p[None, :], n, axis=0)
    if goal is None:
        return np.asarray(anchor + steps[:, None] * v, dtype=float)
    d = goal - anchor
    dist = float(np.hypot(*d))
    travelled = np.minimum(steps * speed, dist)
    return np.asarray(anchor + travelled[:, None] * (d / max(dist, 1e-9)), dtype=float)


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
            from hltl.perception.gru import (
                load_model,  # the predict extra (GRU weights, onnxruntime), only when asked for
            )

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
