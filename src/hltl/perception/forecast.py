"""The goal-directed forecast on a fixed time grid: stopping places, velocity fit, forecast."""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np
import numpy.typing as npt

from hltl.world.scene import Scene

F64 = npt.NDArray[np.float64]

# The resampling grid the goal-directed fit and the GRU work on: 0.1 s steps, 8 observed
# samples (0.7 s of history), 20 forecast samples (2 s).
DT = 0.1
T_OBS = 8
T_PRED = 20
FIT_SAMPLES = 5  # the velocity fit covers the last 0.4 s, like the CV baseline's window
MIN_SPEED = 0.15  # m/s below which a person is taken to stand still
GOAL_CONE = math.radians(30.0)  # a stopping place must lie within this angle of the heading
GOAL_MIN_LATERAL = 0.25  # ... or this close (m) to the heading line


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
