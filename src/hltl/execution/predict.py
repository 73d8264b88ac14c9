"""Human trajectory prediction and the predicted workspace (paper eq. ws_predict)."""

from __future__ import annotations

from collections import Counter
from collections.abc import Mapping
from dataclasses import dataclass

from hltl.perception.predict import ConstantVelocityPredictor, TrajectoryPredictor
from hltl.skills.kinematics import REACH_SPHERES, Kinematics
from hltl.world.scene import Scene, Vec3
from hltl.world.state import WorldState

__all__ = [
    "ConstantVelocityPredictor",
    "TrajectoryPredictor",
    "WorkspacePrediction",
    "horizon_times",
    "predict_workspace",
    "predicted_world",
]


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
    kinematics: Kinematics = REACH_SPHERES,
) -> WorkspacePrediction:
    """Paper eq. (ws_predict): the workspace label the forecast is in most often over the horizon.

    Workspaces overlap, so a point's "workspace" is the set of robots whose workspace holds it
    (the value ℓ assigns a person, by ``kinematics``: the reach spheres, or the reachability
    maps when the arms have models); the vote is over those labels. Ties go to the label
    reached later, which is where a walking person is heading.
    """
    times = horizon_times(t, horizon, dt)
    points = predictor.predict(human, times)
    labels = [kinematics.context_label(scene, ((human, p),)).robots_serving(human) for p in points]
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
