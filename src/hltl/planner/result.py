"""Plan results: status, steps with bindings, makespan, search statistics; the plan JSON format."""

from __future__ import annotations

import enum
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

from hltl.errors import PlanFormatError
from hltl.skills.library import Action


class PlanStatus(enum.Enum):
    """``solved``: a plan (optimal in exact mode; within ``gap`` of optimal in anytime mode);
    ``infeasible``: proved that none exists; ``timeout``: the limit struck first (the result may
    still carry the best plan found so far and a lower bound)."""

    SOLVED = "solved"
    INFEASIBLE = "infeasible"
    TIMEOUT = "timeout"


ROLES = ("solo", "giver", "relay", "receiver")


@dataclass(frozen=True, slots=True)
class Binding:
    """η(r) = (leaf, role) for one robot during one step."""

    robot: str
    leaf: str
    role: str


@dataclass(frozen=True, slots=True)
class PlanStep:
    """One synchronous step U_t: its actions, start time, duration max d(a), and bindings η_t."""

    start: float
    duration: float
    actions: tuple[Action, ...]
    bindings: tuple[Binding, ...] = ()

    def to_dict(self) -> dict[str, Any]:
        d: dict[str, Any] = {"start": round(self.start, 6), "duration": round(self.duration, 6)}
        if self.bindings:
            d["bindings"] = {b.robot: [b.leaf, b.role] for b in self.bindings}
        d["actions"] = [a.to_dict() for a in self.actions]
        return d

    @classmethod
    def from_dict(cls, data: Mapping[str, Any]) -> PlanStep:
        try:
            bindings = tuple(
                Binding(str(r), str(v[0]), str(v[1]))
                for r, v in dict(data.get("bindings") or {}).items()
            )
            return cls(
                start=float(data["start"]),
                duration=float(data["duration"]),
                actions=tuple(Action.from_dict(a) for a in data["actions"]),
                bindings=bindings,
            )
        except (KeyError, TypeError, ValueError, IndexError) as exc:
            raise PlanFormatError(f"plan step {dict(data)!r} is malformed ({exc})") from None


@dataclass(frozen=True, slots=True)
class SearchStats:
    expanded: int = 0
    generated: int = 0
    seconds: float = 0.0
    algorithm: str = "astar"
    #: anytime mode: seconds until the first plan was found (None: none, or exact mode)
    first_plan: float | None = None
    #: exact mode, where A* ran in a process of its own beside the first phase
    #: (docs/planner.md, "A* in a process of its own"; else None): seconds until the phase
    #: ended, and seconds A*'s process was paused through the phase's rounds
    phase: float | None = None
    held: float | None = None


@dataclass(frozen=True, slots=True)
class PlanResult:
    """The outcome of planning. "No plan" is a status, not an exception."""

    status: PlanStatus
    steps: tuple[PlanStep, ...] = ()
    makespan: float | None = None
    stats: SearchStats = field(default_factory=SearchStats)
    reason: str = ""
    #: a proven lower bound on the optimal makespan (seconds); None when nothing is proved
    lower_bound: float | None = None

    @property
    def solved(self) -> bool:
        return self.status is PlanStatus.SOLVED

    @property
    def has_plan(self) -> bool:
        """Whether the result carries a plan (solved, or the best plan found before a timeout)."""
        return self.makespan is not None and self.status is not PlanStatus.INFEASIBLE

    @property
    def gap(self) -> float | None:
        """``(makespan - lower_bound) / makespan``: the plan is optimal within this fraction
        (0 when proved optimal); None without both a plan and a bound."""
        if self.makespan is None or self.lower_bound is None:
            return None
        if self.makespan <= 0.0:
            return 0.0
        return max(0.0, (self.makespan - self.lower_bound) / self.makespan)

    @property
    def actions(self) -> tuple[Action, ...]:
        return tuple(a for s in self.steps for a in s.actions)

    def to_dict(
        self, *, spec: Mapping[str, Any] | None = None, scene: str | None = None
    ) -> dict[str, Any]:
        """The plan JSON of DESIGN.md §3."""
        d: dict[str, Any] = {
            "status": self.status.value,
            "makespan": None if self.makespan is None else round(self.makespan, 6),
            "planner": {
                "algorithm": self.stats.algorithm,
                "expanded": self.stats.expanded,
                "generated": self.stats.generated,
                "seconds": round(self.stats.seconds, 6),
            },
        }
        if self.stats.first_plan is not None:
            d["planner"]["first_plan_seconds"] = round(self.stats.first_plan, 6)
        lb, gap = self.lower_bound, self.gap
        d["lower_bound"] = None if lb is None or lb == float("inf") else round(lb, 6)
        d["gap"] = None if gap is None else round(gap, 6)
        if self.reason:
            d["reason"] = self.reason
        if spec is not None:
            d["spec"] = dict(spec)
        if scene is not None:
            d["scene"] = scene
        d["steps"] = [s.to_dict() for s in self.steps]
        return d

    @classmethod
    def from_dict(cls, data: Mapping[str, Any]) -> PlanResult:
        try:
            status = PlanStatus(data["status"])
            p = dict(data.get("planner") or {})
            return cls(
                status=status,
                steps=tuple(PlanStep.from_dict(s) for s in data.get("steps", [])),
                makespan=None if data.get("makespan") is None else float(data["makespan"]),
                stats=SearchStats(
                    int(p.get("expanded", 0)),
                    int(p.get("generated", 0)),
                    float(p.get("seconds", 0.0)),
                    str(p.get("algorithm", "astar")),
                    None if p.get("first_plan_seconds") is None else float(p["first_plan_seconds"]),
                ),
                reason=str(data.get("reason", "")),
                lower_bound=None if data.get("lower_bound") is None else float(data["lower_bound"]),
            )
        except (KeyError, TypeError, ValueError) as exc:
            raise PlanFormatError(
                f"not a plan: {exc}; expected status, makespan and steps"
            ) from None
