"""The executor's background plans for the forecast world: which problems, keyed how, made where."""

from __future__ import annotations

import hashlib
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Protocol, runtime_checkable

from hltl.execution.predict import (
    TrajectoryPredictor,
    WorkspacePrediction,
    predict_workspace,
    predicted_world,
)
from hltl.execution.predicted import PlanKey, plan_key
from hltl.planner import PlanResult
from hltl.skills.library import Transition, step_symbol
from hltl.skills.semantics import ActionSemantics, apply
from hltl.spec.monitor import HierarchyMonitor, MonitorState
from hltl.world.geometry import Context
from hltl.world.scene import Scene
from hltl.world.state import WorldState


class _Forecasting(Protocol):
    """The executor's configuration as far as the forecast reads it."""

    @property
    def predict(self) -> bool: ...

    @property
    def horizon(self) -> float: ...

    @property
    def predict_dt(self) -> float: ...


@dataclass(frozen=True, slots=True)
class Problem:
    """One background plan: the executor's planner from ``world`` (the forecast world) and
    monitor state ``q``; ``key`` is its predicted-plan key (one plan a key is kept)."""

    basis: str  # "now", or "after_step": once the running step ends as planned
    world: WorldState
    q: MonitorState
    key: PlanKey


@dataclass(frozen=True, slots=True)
class Forecast:
    """What the executor's background step forecasts at a tick: each observed person's
    predicted workspace, the moving ones, the forecast world's context (``None``: nobody
    moves) and the plans to make for it (none when the forecast keeps the context)."""

    predictions: dict[str, WorkspacePrediction]
    moving: dict[str, WorkspacePrediction]
    context: Context | None
    problems: tuple[Problem, ...]


def after_running(
    monitor: HierarchyMonitor,
    q: MonitorState,
    world: WorldState,
    runs: Sequence[tuple[Transition, bool]],
) -> tuple[WorldState, MonitorState]:
    """The world and monitor state once the running step completes as planned. ``runs``:
    the step's actions that run or ended done, in dispatch order, each with whether it still
    runs; those still running are applied to ``world``, and the monitor steps over all."""
    w = world
    for tr, running in runs:
        if running:
            w = apply(w, tr)
    return w, monitor.step(q, step_symbol([tr for tr, _ in runs], w))


def background_forecast(
    scene: Scene,
    semantics: ActionSemantics,
    predictor: TrajectoryPredictor | None,
    config: _Forecasting,
    world: WorldState,
    t: float,
    monitor: HierarchyMonitor | None,
    q: MonitorState,
    spec_version: int,
    after: Callable[[], tuple[WorldState, MonitorState] | None],
) -> Forecast | None:
    """The executor's background step at time ``t`` (``Executor._background``), as a pure
    function of its state: ``None`` when it forecasts nothing (prediction off, no
    forecaster, no spec, the spec accepted); else the forecast, with the plans to make for
    the forecast world from now (``world``, ``q``) and, when a step runs, from its end as
    planned (``after()``). The executor and a driver that simulates ahead (the bus's cell
    node) compute the same problems and keys from the same state."""
    if not config.predict or predictor is None or monitor is None or monitor.accepted(q):
        return None
    preds: dict[str, WorkspacePrediction] = {}
    for hid, _ in world.humans:
        try:
            preds[hid] = predict_workspace(
                scene, predictor, hid, t, config.horizon, config.predict_dt, semantics.kinematics
            )
        except KeyError:  # never observed yet
            continue
    moving = {h: p for h, p in preds.items() if p.moving}
    if not moving:
        return Forecast(preds, moving, None, ())
    ctx_pred = semantics.context(predicted_world(world, moving))
    if ctx_pred == semantics.context(world):
        return Forecast(preds, moving, ctx_pred, ())
    bases: list[tuple[str, WorldState, MonitorState]] = [("now", world, q)]
    later = after()
    if later is not None:
        bases.append(("after_step", *later))
    problems = []
    for basis, w, qb in bases:
        wp = predicted_world(w, moving)
        problems.append(Problem(basis, wp, qb, plan_key(ctx_pred, wp, qb, spec_version)))
    return Forecast(preds, moving, ctx_pred, tuple(problems))


def problem_digest(spec_id: str, problem: Problem) -> str:
    """The planning problem's identity, exact: the spec (``spec_id``, the same text on both
    sides for the same spec), the monitor state and the whole forecast world (floats by
    their exact ``repr``). Two problems with one digest give the same plan."""
    text = repr((spec_id, problem.q, problem.world))
    return hashlib.blake2b(text.encode("utf-8"), digest_size=16).hexdigest()


@dataclass(frozen=True, slots=True)
class Given:
    """A background plan made elsewhere for the executor (by a driver that simulates ahead)
    and the wall-clock seconds it took there."""

    result: PlanResult
    wall_s: float


@runtime_checkable
class PlansAhead(Protocol):
    """A driver that may have made the executor's background plans already (optional,
    besides :class:`~hltl.execution.drivers.Foresight`): asked for each problem the executor
    is about to plan, it gives the plan made for exactly that problem under the executor's
    spec of ``spec_version`` (the executor's planner, as told in its basis), or ``None``: the
    executor plans it itself."""

    def planned(self, spec_version: int, problem: Problem) -> Given | None: ...
