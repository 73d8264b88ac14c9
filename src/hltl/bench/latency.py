"""Measure the planner's and grounder's latency in the closed loop and fit the latency model."""

from __future__ import annotations

import datetime as dt
import json
import statistics
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from hltl.execution.executor import ExecutorConfig
from hltl.execution.latency import LatencyModel
from hltl.execution.log import Grounding, Predict, Replan
from hltl.grounding.offline import OfflineGrounder
from hltl.sim.dynamic import make_trial
from hltl.sim.episode import EpisodeConfig, run_episode

DEFAULT_MODEL = Path(__file__).parent / "data" / "latency_model.json"


@dataclass(frozen=True, slots=True)
class Samples:
    """Measured calls: planner (expanded nodes, seconds) and grounding seconds."""

    planner: tuple[tuple[int, float], ...]
    grounding: tuple[float, ...]


def episode_samples(config: str, index: int, seed: int = 0) -> Samples:
    """Planner and grounding calls of hltl on one suite trial (prediction on, nothing charged)."""
    trial = make_trial(config, index, seed)
    ep = run_episode(
        trial.scene,
        instruction=trial.instruction,
        events=trial.events,
        seed=trial.seed,
        config=EpisodeConfig(executor=ExecutorConfig()),
        grounder=OfflineGrounder(),
    )
    planner = tuple(
        (int(r.expanded), float(r.latency_ms) / 1000.0)
        for r in ep.records
        if (isinstance(r, Replan) and r.source == "planner") or isinstance(r, Predict)
    )
    grounding = tuple(
        float(r.latency_ms) / 1000.0
        for r in ep.records
        if isinstance(r, Grounding) and r.latency_ms is not None
    )
    return Samples(planner, grounding)


@dataclass(frozen=True, slots=True)
class Fit:
    """The fitted model and what it was fitted to."""

    model: LatencyModel
    planner_calls: int
    grounding_calls: int
    planner_ms_median: float
    planner_ms_p95: float
    planner_ms_max: float
    expanded_median: float
    r2: float
    outliers: int
    grounding_ms_median: float

    def to_dict(self, command: str, machine: str, date: str) -> dict[str, Any]:
        return {
            "model": self.model.to_dict(),
            "measurement": {
                "command": command,
                "machine": machine,
                "date": date,
                "planner_calls": self.planner_calls,
                "grounding_calls": self.grounding_calls,
                "planner_ms_median": round(self.planner_ms_median, 4),
                "planner_ms_p95": round(self.planner_ms_p95, 4),
                "planner_ms_max": round(self.planner_ms_max, 4),
                "expanded_median": self.expanded_median,
                "r2": round(self.r2, 4),
                "outliers": self.outliers,
                "grounding_ms_median": round(self.grounding_ms_median, 4),
            },
        }


def fit(samples: Sequence[Samples], source: str) -> Fit:
    """Least squares ``seconds = a + b · expanded`` (a, b clipped at 0; outliers beyond 5 MADs
    dropped, counted in ``outliers``) and the median grounding time.

    Raises:
        ValueError: no planner call was measured.
    """
    pts = [p for s in samples for p in s.planner]
    if not pts:
        raise ValueError("no planner call was measured")
    ground = [g for s in samples for g in s.grounding]
    n = np.array([p[0] for p in pts], dtype=float)
    y = np.array([p[1] for p in pts], dtype=float)
    a, b = _line(n, y)
    # calls stalled by other processes on the shared cores (or a garbage collection) are not
    # the planner's cost: drop residuals beyond 5 median absolute deviations, then refit
    resid = y - (a + b * n)
    mad = float(np.median(np.abs(resid - np.median(resid))))
    keep = np.abs(resid - np.median(resid)) <= 5.0 * max(mad, 1e-6)
    if keep.sum() >= 2:
        a, b = _line(n[keep], y[keep])
    resid = y[keep] - (a + b * n[keep])
    var = float(((y[keep] - y[keep].mean()) ** 2).sum())
    r2 = 1.0 - float((resid**2).sum()) / var if var > 0 else 1.0
    ms = sorted(float(v) * 1000.0 for v in y)
    g = statistics.median(ground) if ground else 0.0
    model = LatencyModel(
        planner_fixed_s=a,
        planner_per_node_s=b,
        grounding_s=g,
        source=source,
    )
    return Fit(
        model=model,
        planner_calls=len(pts),
        grounding_calls=len(ground),
        planner_ms_median=statistics.median(ms),
        planner_ms_p95=ms[min(len(ms) - 1, int(0.95 * len(ms)))],
        planner_ms_max=ms[-1],
        expanded_median=statistics.median(float(v) for v in n),
        r2=r2,
        outliers=int((~keep).sum()),
        grounding_ms_median=g * 1000.0,
    )


def _line(n: np.ndarray, y: np.ndarray) -> tuple[float, float]:
    """(intercept, slope) of the least-squares line, both clipped at 0."""
    if float(np.ptp(n)) > 0:
        b, a = (float(v) for v in np.polyfit(n, y, 1))
    else:
        a, b = float(y.mean()), 0.0
    return max(a, 0.0), max(b, 0.0)


def measure(
    configs: Sequence[str],
    trials: int,
    seed: int,
    *,
    command: str,
    machine: str,
    on_trial: Callable[[str, int], None] | None = None,
) -> tuple[Fit, dict[str, Any]]:
    """Run ``trials`` trials of each configuration in this process (one at a time, so calls do
    not compete with each other for the cores) and fit the model; also the JSON to store."""
    samples = []
    for c in configs:
        for i in range(trials):
            samples.append(episode_samples(c, i, seed))
            if on_trial is not None:
                on_trial(c, i)
    date = dt.datetime.now(dt.UTC).strftime("%Y-%m-%d %H:%M UTC")
    n_calls = sum(len(s.planner) for s in samples)
    source = f"`{command}`, {date}, {machine}: {n_calls} planner calls"
    result = fit(samples, source)
    return result, result.to_dict(command, machine, date)


def write_model(path: Path, data: dict[str, Any]) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(data, indent=1) + "\n", encoding="utf-8")
