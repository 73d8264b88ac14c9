"""Skill durations d(s, a): fixed per-skill times, or the analytic hand-travel model."""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Protocol, runtime_checkable

from hltl.errors import SceneError
from hltl.skills.library import Action, Transition
from hltl.world.geometry import distance
from hltl.world.scene import Scene, Vec3

DEFAULT_SPEED = 0.5  # m/s, hand speed of a collaborative arm near people
# d(s, a) of an instance that cannot be executed from the given hands (a motion model found no
# motion): the planner drops such a step, the executor does not dispatch it, the simulator fails it
INFEASIBLE = math.inf
Joints = tuple[float, ...]  # an arm's joint positions


def executed_duration(
    cost: CostModel, action: Action, transition: Transition, planned_s: float
) -> float:
    """Seconds an instance lasts when executed along a motion plan of ``planned_s`` seconds:
    the plan's time, never less than the dwell (closing, opening, exchanging) no motion beats.
    One rule for the cost model, the executor's expectation and the simulator's timing."""
    return max(planned_s, cost.lower_bound(action, transition))


class CostModel(Protocol):
    """d(s, a). ``fixed`` models ignore hand poses (the planner then does not track them)."""

    @property
    def fixed(self) -> bool: ...

    def duration(self, action: Action, transition: Transition, hands: Mapping[str, Vec3]) -> float:
        """Seconds the instance takes when each executor's hand starts at ``hands[robot]``;
        :data:`INFEASIBLE` (``math.inf``) when it cannot be done from there."""
        ...

    def lower_bound(self, action: Action, transition: Transition) -> float:
        """A duration no start pose can beat (used by the planner's admissible heuristic)."""
        ...


@runtime_checkable
class ChainedCostModel(CostModel, Protocol):
    """A cost model whose durations depend on the arms' joint states, not only on where the
    hands are (the motion layer's model). The planner then searches over hand states, a hand
    point with the joints the arm has there: the start's from :meth:`arm_state` (where the arms
    really are), each successor's from where the instance's motion leaves the arm
    (:meth:`timed`). So the durations it searches with are the ones the executor dispatches,
    whose motions start where the previous ones ended (docs/motion.md, *Chaining*)."""

    def arm_state(self, robot: str, hand: Vec3) -> Joints | None:
        """The joints of ``robot``'s arm now, its hand at ``hand``; ``None`` without an arm."""
        ...

    def timed(
        self,
        action: Action,
        transition: Transition,
        hands: Mapping[str, Vec3],
        joints: Mapping[str, Joints],
    ) -> tuple[float, Mapping[str, Joints]]:
        """The instance's duration from these hands, each arm in ``joints`` starting from its
        joints there (:data:`INFEASIBLE` without a motion), and the joints its motion leaves
        each executor's arm in (robots without an arm are left out)."""
        ...


@dataclass(frozen=True, slots=True)
class FixedDurations:
    """The paper's d(a): one time per skill, from the scene's ``durations``."""

    durations: tuple[tuple[str, float], ...]

    @property
    def fixed(self) -> bool:
        return True

    def duration(self, action: Action, transition: Transition, hands: Mapping[str, Vec3]) -> float:
        return self.lower_bound(action, transition)

    def lower_bound(self, action: Action, transition: Transition) -> float:
        for skill, d in self.durations:
            if skill == action.skill:
                return d
        have = ", ".join(s for s, _ in self.durations)
        raise SceneError(
            f"durations: no time for skill {action.skill!r}; the scene gives: {have}. "
            "Add it to 'durations' or drop 'durations' to use the analytic model"
        )


@dataclass(frozen=True, slots=True)
class AnalyticCostModel:
    """Hand travel over speed plus a fixed grasp/release time (DESIGN.md §4).

    A two-robot handover lasts until the slower hand arrives, plus the exchange.
    """

    speeds: tuple[tuple[str, float], ...]
    grasp: float = 0.3
    release: float = 0.3
    exchange: float = 0.4

    @property
    def fixed(self) -> bool:
        return False

    def _const(self, skill: str) -> float:
        if skill == "pick":
            return self.grasp
        if skill == "handover_r2r":
            return self.exchange
        return self.release

    def _speed(self, rid: str) -> float:
        for k, v in self.speeds:
            if k == rid:
                return v
        return DEFAULT_SPEED

    def duration(self, action: Action, transition: Transition, hands: Mapping[str, Vec3]) -> float:
        travel = 0.0
        for rid, target in transition.hands:
            start = hands.get(rid, target)
            travel = max(travel, distance(start, target) / self._speed(rid))
        return travel + self._const(action.skill)

    def lower_bound(self, action: Action, transition: Transition) -> float:
        return self._const(action.skill)


def cost_model_for(scene: Scene) -> CostModel:
    """Fixed durations when the scene gives them, else the analytic model."""
    if scene.durations is not None:
        return FixedDurations(scene.durations)
    return AnalyticCostModel(tuple((r.id, r.speed or DEFAULT_SPEED) for r in scene.robots))
