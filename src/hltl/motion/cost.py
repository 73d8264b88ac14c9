"""d(s, a) from motion plans: each skill instance lasts as long as its timed trajectories."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from hltl.errors import HltlError
from hltl.motion.planning import (
    EXCHANGE_DWELL,
    GRASP_DWELL,
    RELEASE_DWELL,
    Cell,
    SkillMotion,
    plan_action,
)
from hltl.motion.trajectory import MotionPlan
from hltl.motion.workspace import MapKinematics
from hltl.skills.cost import DEFAULT_SPEED, INFEASIBLE, AnalyticCostModel
from hltl.skills.library import Action, Transition
from hltl.world.scene import Scene, Vec3

KEY_DIGITS = 3  # hand positions are compared to the millimetre when reusing a motion plan


class MotionInfeasibleError(HltlError, ValueError):
    """A skill instance the reachability maps allow has no motion plan (IK, collisions)."""


@dataclass(slots=True)
class MotionCostModel:
    """The planner's CostModel from real motion plans (``hltl plan --motion``).

    Each executor's hand starts where ``hands`` says; a position-only IK nearest the arm's home
    pose turns it into a configuration, and :func:`~hltl.motion.planning.plan_action` plans
    the instance from there. Plans are cached by action and start hands, so the search pays for
    each distinct motion once. ``lower_bound`` is the instance's dwell time (closing, opening or
    exchanging), which no motion can beat.

    An instance with no motion plan from the given hands (the maps say reachable, but IK or
    collisions disagree) lasts ``math.inf`` (:data:`~hltl.skills.cost.INFEASIBLE`): the planner
    drops that step, the executor does not dispatch it and the discrete simulator fails it —
    never a large finite time a search would happily pay.
    """

    cell: Cell
    humans: Mapping[str, Vec3] | None = None
    candidates: int = 2
    plans: dict[tuple[Action, tuple[tuple[str, Any], ...]], SkillMotion] = field(
        default_factory=dict
    )
    _fallback: AnalyticCostModel = field(init=False)

    def __post_init__(self) -> None:
        # robots without an arm model are timed as before: hand travel over speed plus dwell
        scene = self.cell.scene
        speeds = tuple((r.id, r.speed or DEFAULT_SPEED) for r in scene.robots)
        self._fallback = AnalyticCostModel(speeds, GRASP_DWELL, RELEASE_DWELL, EXCHANGE_DWELL)

    @property
    def fixed(self) -> bool:
        return False

    def lower_bound(self, action: Action, transition: Transition) -> float:
        if action.skill == "pick":
            return GRASP_DWELL
        if action.skill == "handover_r2r":
            return EXCHANGE_DWELL
        return RELEASE_DWELL

    def duration(self, action: Action, transition: Transition, hands: Mapping[str, Vec3]) -> float:
        if any(rid not in self.cell.arms for rid in action.robots):
            return self._fallback.duration(action, transition, hands)
        motion = self.motion(action, transition, hands)
        if motion.plan is None:
            return INFEASIBLE
        return max(motion.plan.duration, self.lower_bound(action, transition))

    def motion_plan(
        self, action: Action, transition: Transition, hands: Mapping[str, Vec3]
    ) -> MotionPlan | None:
        """The joint trajectories of an instance (the executor passes them to the driver)."""
        if any(rid not in self.cell.arms for rid in action.robots):
            return None
        return self.motion(action, transition, hands).plan

    def motion(
        self, action: Action, transition: Transition, hands: Mapping[str, Vec3]
    ) -> SkillMotion:
        """The (cached) motion plan of an instance from the given start hands."""
        start = tuple(
            (rid, _round(hands.get(rid, self.cell.kinematics.scene.robot(rid).base)))
            for rid in action.robots
        )
        # where the person stands now (the transition's), not where the scene put them first
        human_at = transition.human_at
        if human_at is None and action.human is not None and self.humans is not None:
            human_at = self.humans.get(action.human)
        # where the person stands shapes a hand-over's motion, and where the hands end (a pick
        # from the table or from a surface) a pick's: both are part of the key, or the plan
        # made for one would be reused for the other
        ends = tuple((f"->{rid}", _round(p)) for rid, p in transition.hands)
        if human_at is not None:
            ends = (*ends, ("@", _round(human_at)))
        key = (action, (*start, *ends))
        if key not in self.plans:
            q = {rid: self._config(rid, p) for rid, p in start}
            where = None
            if action.skill == "pick":
                where = transition.hands[0][1]
            self.plans[key] = plan_action(
                self.cell, action, q, where=where, human_at=human_at, k=self.candidates
            )
        return self.plans[key]

    def _config(self, rid: str, point: Vec3) -> tuple[float, ...]:
        arm = self.cell.arm(rid)
        home_pos, _ = arm.fk(arm.home)
        if np.linalg.norm(home_pos - np.asarray(point)) < 1e-3:
            return tuple(float(v) for v in arm.home)
        res = arm.ik(point, None, arm.home, prefer=arm.home)
        if res.q is None:
            # a hand pose from the sphere geometry the arm cannot take: start from home
            return tuple(float(v) for v in arm.home)
        return res.q


def _round(p: Vec3) -> Vec3:
    return (round(p[0], KEY_DIGITS), round(p[1], KEY_DIGITS), round(p[2], KEY_DIGITS))


def motion_models(scene: Scene) -> tuple[MapKinematics, MotionCostModel]:
    """Kinematics from the reachability maps and durations from motion plans, for a scene.

    Robots without a registered model keep their reach sphere, and their instances take the
    analytic model's time (hand travel over speed plus the dwell).
    """
    kin = MapKinematics(scene)
    return kin, MotionCostModel(Cell(scene, kin))
