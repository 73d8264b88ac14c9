"""Simulated time the executor's own computation costs: planner, grounding and motion planning."""

from __future__ import annotations

import json
import math
from collections.abc import Sequence
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Any, Protocol, TypeVar

from hltl.errors import HltlError
from hltl.skills.library import Action
from hltl.world.state import WorldState

T = TypeVar("T")

PIPELINED = frozenset({"progress"})


class MotionTimer(Protocol):
    """Plans the motions a new plan's first step needs before it can be dispatched, and says
    how long that took: measured wall-clock seconds, charged with the planner call (e.g.
    :class:`hltl.motion.pmp.HandoverMotionTimer`, the paper's P.M.P. in the closed loop)."""

    def __call__(self, world: WorldState, actions: Sequence[Action]) -> float: ...


@dataclass(frozen=True, slots=True)
class LatencyModel:
    """How long one call takes, in seconds.

    Attributes:
        measured: charge each call's measured wall-clock time (not reproducible: it depends on
            the machine and its load); otherwise the fitted model below.
        planner_fixed_s, planner_per_node_s: planner time ≈ fixed + per_node · expanded nodes
            (least squares over measured calls).
        grounding_s: time to ground one instruction (the median of measured calls).
        scale: every charge multiplied by this (1 = as measured).
        source: the measurement the model comes from (command, date, machine, calls, fit).
    """

    measured: bool = False
    planner_fixed_s: float = 0.0
    planner_per_node_s: float = 0.0
    grounding_s: float = 0.0
    scale: float = 1.0
    source: str = ""

    def __post_init__(self) -> None:
        for name in ("planner_fixed_s", "planner_per_node_s", "grounding_s", "scale"):
            v = getattr(self, name)
            if not (isinstance(v, (int, float)) and math.isfinite(v) and v >= 0):
                raise ValueError(f"{name} must be a finite number >= 0, got {v!r}")

    def planner(self, expanded: int, wall_s: float) -> float:
        """Seconds one planner call that expanded ``expanded`` nodes costs."""
        if self.measured:
            return self.scale * wall_s
        return self.scale * (self.planner_fixed_s + self.planner_per_node_s * expanded)

    def grounding(self, wall_s: float) -> float:
        """Seconds grounding one instruction costs."""
        return self.scale * (wall_s if self.measured else self.grounding_s)

    def scaled(self, factor: float) -> LatencyModel:
        return LatencyModel(
            self.measured,
            self.planner_fixed_s,
            self.planner_per_node_s,
            self.grounding_s,
            self.scale * factor,
            self.source,
        )

    def to_dict(self) -> dict[str, Any]:
        return asdict(self)

    def describe(self) -> str:
        if self.measured:
            return "measured per call (wall clock)" + (
                f" x{self.scale:g}" if self.scale != 1 else ""
            )
        text = (
            f"planner {self.planner_fixed_s * 1e3:.3g} ms + {self.planner_per_node_s * 1e6:.3g} µs"
            f"/node, grounding {self.grounding_s * 1e3:.3g} ms"
        )
        return text + (f" x{self.scale:g}" if self.scale != 1 else "")


def planner_charge(
    model: LatencyModel,
    trigger: str,
    expanded: int,
    wall_s: float,
    since_step: float | None,
    motion_s: float = 0.0,
) -> tuple[float, str]:
    """(seconds on the critical path, why) for a planner call made for ``trigger``.

    ``since_step`` is how long ago the step that just ended was dispatched (None: no step
    ran before this call); a pipelined call is paid only beyond that. ``motion_s`` is the
    motion planning the call's plan needs before dispatch, computed with it.
    """
    cost = model.planner(expanded, wall_s) + motion_s
    parts = set(trigger.split("+")) if trigger else set()
    if parts and parts <= PIPELINED and since_step is not None:
        return max(0.0, cost - since_step), "pipelined"
    return cost, "critical"


def takeover_charge(
    model: LatencyModel, expanded: int, wall_s: float, since: float, motion_s: float = 0.0
) -> float:
    """What remains of a predicted plan's computation (and its motion planning, ``motion_s``),
    started ``since`` seconds ago."""
    return max(0.0, model.planner(expanded, wall_s) + motion_s - since)


def load_latency_model(path: str | Path) -> LatencyModel:
    """A model written by ``hltl bench latency --write-model``.

    Raises:
        HltlError: the file is missing, not JSON or not a latency model.
    """
    return load_record(path, "latency model", LatencyModel, key="model")


def load_record(path: str | Path, what: str, cls: type[T], *, key: str | None = None) -> T:
    """A frozen dataclass ``cls`` from a JSON file (its fields, or under ``key``).

    Raises:
        HltlError: the file is missing or not JSON, lacks ``key``, has unknown fields, or
            ``cls`` refuses the values; the message names ``what`` and the file.
    """
    p = Path(path)
    name = f"{what} {str(p)[:200]!r}"
    try:
        data = json.loads(p.read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError, json.JSONDecodeError) as exc:
        raise HltlError(f"{name}: cannot read it ({exc})") from exc
    if key is not None:
        data = data.get(key) if isinstance(data, dict) else None
        if not isinstance(data, dict):
            raise HltlError(f"{name}: expected an object with a {key!r} key")
    if not isinstance(data, dict):
        raise HltlError(f"{name}: expected a JSON object")
    fields: dict[str, Any] = getattr(cls, "__dataclass_fields__", {})
    unknown = sorted(set(data) - set(fields))
    if unknown:
        raise HltlError(f"{name}: unknown keys {unknown[:5]}")
    try:
        return cls(**data)
    except (TypeError, ValueError) as exc:
        raise HltlError(f"{name}: {exc}") from exc
