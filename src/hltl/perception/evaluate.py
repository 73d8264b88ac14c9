"""ADE/FDE of trajectory predictors on walks, run through the live predictor classes."""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np

from hltl.perception.forecast import DT, F64, T_OBS, T_PRED
from hltl.perception.predict import TrajectoryPredictor

HORIZONS = (1.0, 2.0)
MOVING = 0.1  # metres a window must span to count


@dataclass(frozen=True, slots=True)
class Score:
    """Errors of one predictor on one test set (metres)."""

    predictor: str
    samples: int
    ade: tuple[float, ...]  # per HORIZONS
    fde: tuple[float, ...]

    def to_dict(self) -> dict[str, object]:
        out: dict[str, object] = {"predictor": self.predictor, "samples": self.samples}
        for h, a, f in zip(HORIZONS, self.ade, self.fde, strict=True):
            out[f"ade@{h:g}s"] = round(a, 4)
            out[f"fde@{h:g}s"] = round(f, 4)
        return out


def errors(
    make: Callable[[F64], TrajectoryPredictor],
    observed: F64,
    true: F64,
    stops: F64,
    stride: int = 1,
) -> F64:
    """(samples, T_PRED) forecast errors of one walk (only moving samples)."""
    pred = make(stops)
    rows: list[F64] = []
    n = len(true)
    for i in range(n):
        t = i * DT
        pred.observe(t, [("p", (float(observed[i, 0]), float(observed[i, 1]), 0.0))])
        if i + T_PRED >= n or i % stride:
            continue
        lo = max(0, i - T_OBS + 1)
        span = np.concatenate([true[lo : i + 1], true[i + 1 : i + 1 + T_PRED]])
        if float(np.ptp(span, axis=0).max()) < MOVING:
            continue
        times = [t + DT * k for k in range(1, T_PRED + 1)]
        fc = np.array([p[:2] for p in pred.predict("p", times)])
        rows.append(np.hypot(*(fc - true[i + 1 : i + 1 + T_PRED]).T))
    return np.array(rows).reshape(-1, T_PRED)


def score(
    name: str,
    make: Callable[[F64], TrajectoryPredictor],
    walks: Sequence[tuple[F64, F64, F64]],
    stride: int = 1,
) -> Score:
    """ADE/FDE at HORIZONS of predictor ``make(stops)`` over ``walks`` of (observed, true,
    stops)."""
    errs = np.concatenate([errors(make, o, t, s, stride) for o, t, s in walks], axis=0)
    ade, fde = [], []
    for h in HORIZONS:
        k = round(h / DT)
        ade.append(float(errs[:, :k].mean()) if len(errs) else float("nan"))
        fde.append(float(errs[:, k - 1].mean()) if len(errs) else float("nan"))
    return Score(name, len(errs), tuple(ade), tuple(fde))
