"""d(s, a) from motion plans: each skill instance lasts as long as its timed trajectories."""

from __future__ import annotations

import math
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
from hltl.skills.cost import (
    DEFAULT_SPEED,
    INFEASIBLE,
    AnalyticCostModel,
    Joints,
    executed_duration,
)
from hltl.skills.library import Action, Transition
from hltl.world.scene import Scene, Vec3

Config = Joints
# a hand this close to where the last dispatched plan left the tool is that arm's (m)
AT_TOLERANCE = 0.01
KEY_DIGITS = 3  # hand positions are compared to the millimetre when reusing a motion plan


class MotionInfeasibleError(HltlError, ValueError):
    """A skill instance the reachability maps allow has no motion plan (IK, collisions)."""


@dataclass(slots=True)
class MotionCostModel:
    """The planner's cost model from real motion plans (``hltl plan --motion``).

    Durations depend on the arms' joints (a :class:`~hltl.skills.cost.ChainedCostModel`): the
    planner searches from where the arms are (:meth:`arm_state`) and through where each motion
    leaves them (:meth:`timed`), so its durations are the ones the executor dispatches. Where
    an arm is: where the plan this episode dispatched last (:meth:`motion_plan`) left it, while
    its hand is still there (the transition's point, or the tool's reported position within
    ``AT_TOLERANCE``); otherwise (a fresh episode, an arm that was halted or moved) a
    position-only IK nearest the arm's home pose turns the hand point into a configuration.
    :meth:`duration` times an instance from where the arms are now (the executor's and the
    simulator's question); the driver plays the dispatched plan as given.

    Plans are cached by action, start configurations and end hands; that cache may outlive an
    episode (it is a function of its key), the dispatch state may not: the executor works on
    :meth:`for_episode`, a copy without it. :func:`~hltl.motion.planning.plan_action` plans
    each instance. ``lower_bound`` is the instance's dwell time (closing, opening or
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
    # position-only IK nearest home per (robot, hand point): a function of its key, shared
    configs: dict[tuple[str, Vec3], Config] = field(default_factory=dict)
    # this episode only: robot → where the last dispatched plan leaves the arm (the
    # transition's hand point, the tool's real position, the joints)
    _at: dict[str, tuple[Vec3, Vec3, Config]] = field(init=False, default_factory=dict)
    _fallback: AnalyticCostModel = field(init=False)

    def for_episode(self) -> MotionCostModel:
        """A copy that chains plans from scratch (the arms at rest), sharing the plan cache."""
        return MotionCostModel(self.cell, self.humans, self.candidates, self.plans, self.configs)

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
        """The instance's duration from the hands, the arms where they are now."""
        return self.timed(action, transition, hands, {})[0]

    def arm_state(self, robot: str, hand: Vec3) -> Config | None:
        """The joints of ``robot``'s arm now, its hand at ``hand`` (see the class docstring)."""
        if robot not in self.cell.arms:
            return None
        return self._start(robot, _round(hand))

    def timed(
        self,
        action: Action,
        transition: Transition,
        hands: Mapping[str, Vec3],
        joints: Mapping[str, Config],
    ) -> tuple[float, Mapping[str, Config]]:
        """Duration from the hands, each arm in ``joints`` from its joints there (the others
        from where they are now), and the joints the motion leaves the arms in."""
        if any(rid not in self.cell.arms for rid in action.robots):
            return self._fallback.duration(action, transition, hands), {}
        motion = self.motion(action, transition, hands, joints)
        if motion.plan is None:
            return INFEASIBLE, {}
        return executed_duration(self, action, transition, motion.plan.duration), dict(motion.final)

    def motion_plan(
        self, action: Action, transition: Transition, hands: Mapping[str, Vec3]
    ) -> MotionPlan | None:
        """The joint trajectories of an instance from where the arms are (the executor passes
        them to the driver). The executor calls this as it dispatches: the arms are then where
        this plan leaves them."""
        if any(rid not in self.cell.arms for rid in action.robots):
            return None
        motion = self.motion(action, transition, hands)
        if motion.plan is not None:
            ends = dict(transition.hands)
            for rid, q in motion.final:
                if rid in ends:
                    tool, _ = self.cell.arm(rid).fk(q)
                    self._at[rid] = (_round(ends[rid]), _round(_vec(tool)), q)
        return motion.plan

    def motion(
        self,
        action: Action,
        transition: Transition,
        hands: Mapping[str, Vec3],
        joints: Mapping[str, Config] | None = None,
    ) -> SkillMotion:
        """The (cached) motion plan of an instance from the given start hands, each arm from
        its ``joints`` when given, else from where it is now (see the class docstring)."""
        q = {
            rid: joints[rid]
            if joints is not None and rid in joints
            else self._start(
                rid, _round(hands.get(rid, self.cell.kinematics.scene.robot(rid).base))
            )
            for rid in action.robots
        }
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
        key = (action, (*((rid, _key(qr)) for rid, qr in q.items()), *ends))
        motion = self.plans.get(key)
        if motion is None:
            where = None
            if action.skill == "pick":
                where = transition.hands[0][1]
            motion = plan_action(
                self.cell, action, q, where=where, human_at=human_at, k=self.candidates
            )
            self.plans[key] = motion
        return motion

    def _start(self, rid: str, point: Vec3) -> Config:
        """The arm's configuration when its hand is at ``point`` (see the class docstring)."""
        at = self._at.get(rid)
        # the executor's world says where the hand is either by the transition's point or, once
        # the arm reports, by the tool's real position
        if at is not None and (point == at[0] or math.dist(point, at[1]) < AT_TOLERANCE):
            return at[2]
        q = self.configs.get((rid, point))
        if q is None:
            q = self.configs[(rid, point)] = self._config(rid, point)
        return q

    def _config(self, rid: str, point: Vec3) -> Config:
        arm = self.cell.arm(rid)
        home_pos, _ = arm.fk(arm.home)
        if np.linalg.norm(home_pos - np.asarray(point)) < 1e-3:
            return tuple(float(v) for v in arm.home)
        res = arm.ik(point, None, arm.home, prefer=arm.home)
        if res.q is None:
            # a hand pose from the sphere geometry the arm cannot take: start from home
            return tuple(float(v) for v in arm.home)
        return res.q


def _vec(p: Any) -> Vec3:
    return (float(p[0]), float(p[1]), float(p[2]))


def _key(q: Config) -> Config:
    """Joints as a cache key: plans from configurations a micro-radian apart are one."""
    return tuple(round(float(v), 6) for v in q)


def _round(p: Vec3) -> Vec3:
    return (round(p[0], KEY_DIGITS), round(p[1], KEY_DIGITS), round(p[2], KEY_DIGITS))


def motion_models(scene: Scene) -> tuple[MapKinematics, MotionCostModel]:
    """Kinematics from the reachability maps and durations from motion plans, for a scene.

    Robots without a registered model keep their reach sphere, and their instances take the
    analytic model's time (hand travel over speed plus the dwell).
    """
    kin = MapKinematics(scene)
    return kin, MotionCostModel(Cell(scene, kin))
