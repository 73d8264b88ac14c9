"""Human trajectory prediction and the predicted workspace (paper eq. ws_predict).

A :class:`TrajectoryPredictor` turns the positions perception reports into short-horizon
forecasts. :func:`predict_workspace` takes the majority workspace label over the horizon and
:func:`predicted_world` builds w_pred by moving each person to a representative point of it.
"""

from __future__ import annotations

from collections import Counter, deque
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from typing import Protocol, runtime_checkable

from hltl.world.geometry import workspace_of
from hltl.world.scene import Scene, Vec3
from hltl.world.state import WorldState


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


class ConstantVelocityPredictor:
    """Constant-velocity forecasts from a least-squares fit over a sliding window.

    The fit smooths perception noise: a person standing still with 1 cm noise at 20 Hz would
    otherwise look like someone walking at 0.3 m/s. Speeds below ``min_speed`` count as standing.

    Args:
        window: seconds of history the velocity is fitted on.
        min_speed: m/s below which a person is taken to stand still.
    """

    def __init__(self, window: float = 0.4, min_speed: float = 0.15) -> None:
        if window <= 0:
            raise ValueError(f"window must be positive, got {window!r}")
        self.window = window
        self.min_speed = min_speed
        self._history: dict[str, deque[tuple[float, Vec3]]] = {}

    def observe(self, t: float, humans: Iterable[tuple[str, Vec3]]) -> None:
        for hid, pos in humans:
            hist = self._history.setdefault(hid, deque())
            if hist and t <= hist[-1][0]:
                continue  # a stale or repeated observation adds nothing
            hist.append((t, pos))
            while hist and hist[0][0] < t - self.window - 1e-9:
                hist.popleft()

    def _fit(self, human: str) -> tuple[float, Vec3, tuple[float, float]]:
        """(time of the last sample, fitted position then, horizontal velocity)."""
        hist = self._history.get(human)
        if not hist:
            raise KeyError(f"no observation of human {human!r} yet")
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
        return human in self._history and self.velocity(human) != (0.0, 0.0)

    def predict(self, human: str, times: Sequence[float]) -> list[Vec3]:
        t0, p, (vx, vy) = self._fit(human)
        return [(p[0] + vx * (t - t0), p[1] + vy * (t - t0), p[2]) for t in times]


@dataclass(frozen=True, slots=True)
class WorkspacePrediction:
    """ŵs for one person: the robots whose workspaces the forecast spends most time in.

    Attributes:
        human: the person.
        robots: the predicted label (robots that could serve the person there; may be empty).
        position: a representative point: the last forecast point with that label.
        votes: forecast samples with that label, out of ``samples``.
        moving: whether the person is forecast to move at all.
    """

    human: str
    robots: frozenset[str]
    position: Vec3
    votes: int
    samples: int
    moving: bool

    def to_dict(self) -> dict[str, object]:
        return {
            "robots": sorted(self.robots),
            "position": [round(v, 6) for v in self.position],
            "votes": self.votes,
            "samples": self.samples,
        }


def horizon_times(t: float, horizon: float, dt: float) -> list[float]:
    """Sample times t+dt, t+2dt, … up to t+horizon (at least one sample)."""
    n = max(1, round(horizon / dt))
    return [t + k * horizon / n for k in range(1, n + 1)]


def predict_workspace(
    scene: Scene,
    predictor: TrajectoryPredictor,
    human: str,
    t: float,
    horizon: float,
    dt: float,
) -> WorkspacePrediction:
    """Paper eq. (ws_predict): the workspace label the forecast is in most often over the horizon.

    Workspaces overlap, so a point's "workspace" is the set of robots whose workspace holds it
    (the value ℓ assigns a person); the vote is over those labels. Ties go to the label reached
    later, which is where a walking person is heading.
    """
    times = horizon_times(t, horizon, dt)
    points = predictor.predict(human, times)
    labels = [frozenset(workspace_of(scene, p)) for p in points]
    counts = Counter(labels)
    last_index = {lab: i for i, lab in enumerate(labels)}
    best = max(counts, key=lambda lab: (counts[lab], last_index[lab]))
    return WorkspacePrediction(
        human=human,
        robots=best,
        position=points[last_index[best]],
        votes=counts[best],
        samples=len(points),
        moving=predictor.moving(human),
    )


def predicted_world(
    world: WorldState, predictions: Mapping[str, WorkspacePrediction]
) -> WorldState:
    """w_pred: ``world`` with each predicted person moved to their representative point."""
    w = world
    for hid, pred in predictions.items():
        w = w.with_human(hid, pred.position)
    return w
