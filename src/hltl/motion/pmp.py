"""P.M.P. in the closed loop: a new plan's hand-overs planned serially or in parallel, timed."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from hltl.motion.kinematics import Arm
from hltl.motion.planning import CandidatePlanner, Cell, SkillMotion, plan_r2r
from hltl.motion.reach import ReachMap
from hltl.motion.workspace import MapKinematics, Rendezvous
from hltl.skills.library import Action
from hltl.world.scene import Robot, Scene, Vec3
from hltl.world.state import WorldState

Config = tuple[float, ...]

# What a process builds once for every scene it times (each is a function of its key): the
# arms (their rest pose and IK start library take seconds), the maps, and each pair of arms'
# shared region.
_ARMS: dict[tuple[str, str, Vec3], Arm] = {}
_MAPS: dict[str, ReachMap] = {}
_RENDEZVOUS: dict[tuple[Any, ...], Rendezvous | None] = {}


def _robot_key(r: Robot) -> tuple[str, str, Vec3, float]:
    return (r.id, r.model, r.base, r.reach)


class _SharedKinematics(MapKinematics):
    """Map kinematics whose rendezvous spheres are kept for the whole process (keyed by both
    robots' id, model, base and reach: everything the sphere depends on)."""

    def rendezvous(self, a: Robot, b: Robot) -> Rendezvous | None:
        key = tuple(sorted((_robot_key(a), _robot_key(b))))
        if key not in _RENDEZVOUS:
            _RENDEZVOUS[key] = super().rendezvous(a, b)
        return _RENDEZVOUS[key]


def shared_cell(scene: Scene) -> Cell:
    """A cell for ``scene`` built from this process's arms, maps and rendezvous spheres."""
    kin = _SharedKinematics(scene, _MAPS)
    _MAPS.update(kin.maps)
    arms = {}
    for r in scene.robots:
        key = (r.id, r.model, r.base)
        if key in _ARMS:
            arms[r.id] = _ARMS[key]
    cell = Cell(scene, kin, arms)
    for rid, arm in cell.arms.items():
        r = scene.robot(rid)
        _ARMS[(r.id, r.model, r.base)] = arm
    return cell


@dataclass(slots=True)
class HandoverMotionTimer:
    """The executor's :class:`~hltl.execution.latency.MotionTimer` for robot-to-robot
    hand-overs: each one in a new plan's first step is planned by the motion layer
    (:func:`~hltl.motion.planning.plan_r2r`, its ``k`` best candidate goal sets), on a process
    pool of ``workers`` (the paper's P.M.P.) or serially (``workers`` < 2), and the step costs
    the measured seconds of those calls (``SkillMotion.seconds``).

    Where the arms start: each robot's hand point in the believed world turned into joints by
    a position-only IK nearest the arm's rest pose (the rest pose when the hand is there, or the
    point is out of the arm's reach), computed before the clock starts (a real arm reports its
    joints). A request repeated with the same arms' start (an unchanged first step planned
    again) reuses its motion and costs nothing, as a plan cache would. Hand-overs between arms
    hltl has no model of are not planned (they cost 0).

    The cell, its models and maps, each pair's shared region (the rendezvous sphere) and the
    pool are built at the first hand-over that needs them, outside the clock; call
    :meth:`close` (or use ``with``) to stop the pool.
    """

    scene: Scene
    workers: int = 0
    k: int = 8
    motions: list[SkillMotion] = field(default_factory=list)  # every call, in order
    _cell: Cell | None = field(default=None, init=False)
    _planner: CandidatePlanner | None = field(default=None, init=False)
    _cache: dict[tuple[Action, tuple[tuple[str, Config], ...]], SkillMotion] = field(
        default_factory=dict, init=False
    )
    _configs: dict[tuple[str, Vec3], Config] = field(default_factory=dict, init=False)

    def __enter__(self) -> HandoverMotionTimer:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def close(self) -> None:
        if self._planner is not None:
            self._planner.close()
            self._planner = None

    @property
    def parallel(self) -> bool:
        return self.workers > 1

    def __call__(self, world: WorldState, actions: Sequence[Action]) -> float:
        """Plan the hand-overs among ``actions`` from ``world``; their measured seconds."""
        total = 0.0
        for action in actions:
            if action.skill != "handover_r2r":
                continue
            cell, planner = self._ready()
            if any(rid not in cell.arms for rid in action.robots):
                continue
            q = tuple((rid, self._start(cell, rid, world)) for rid in action.robots)
            key = (action, q)
            if key in self._cache:
                continue
            # the two arms' shared region is the cell's geometry, computed once (cached by the
            # kinematics) like the maps it comes from: not part of a request's time
            giver, receiver = (self.scene.robot(rid) for rid in action.robots)
            cell.kinematics.rendezvous(giver, receiver)
            motion = plan_r2r(cell, action, dict(q), planner=planner, k=self.k)
            self._cache[key] = motion
            self.motions.append(motion)
            total += motion.seconds
        return total

    def _ready(self) -> tuple[Cell, CandidatePlanner]:
        if self._cell is None or self._planner is None:
            self._cell = shared_cell(self.scene)
            self._planner = CandidatePlanner(self._cell, workers=self.workers)
            self._planner.warm_up()
        return self._cell, self._planner

    def _start(self, cell: Cell, rid: str, world: WorldState) -> Config:
        arm = cell.arm(rid)
        hand = world.hand_position(rid)
        if hand is None:
            return tuple(float(v) for v in arm.home)
        point = (round(hand[0], 3), round(hand[1], 3), round(hand[2], 3))
        q = self._configs.get((rid, point))
        if q is None:
            home_pos, _ = arm.fk(arm.home)
            res = None
            if float(np.linalg.norm(home_pos - np.asarray(point))) >= 1e-3:
                res = arm.ik(point, None, arm.home, prefer=arm.home)
            if res is None or res.q is None:
                q = tuple(float(v) for v in arm.home)
            else:
                q = tuple(round(float(v), 9) for v in res.q)
            self._configs[(rid, point)] = q
        return q
