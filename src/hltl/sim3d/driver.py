"""The 3D simulator: the discrete-event simulator's world, embodied in MuJoCo."""

from __future__ import annotations

import dataclasses
import itertools
import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np

from hltl.execution import log as elog
from hltl.execution.drivers import Handle
from hltl.execution.log import (
    EventLog,
    vec,
)
from hltl.motion.kinematics import Arm, rotation_z_to
from hltl.motion.planning import Cell, plan_action
from hltl.motion.robots import has_model
from hltl.motion.trajectory import JointTrajectory, MotionPlan
from hltl.sim.events import EventSchedule
from hltl.sim.route import route_around
from hltl.sim.simulator import PerceptionModel, Simulator
from hltl.sim3d.model import SceneModel, compile_scene
from hltl.sim3d.stage import DOWN, Contact, Stage
from hltl.skills.cost import CostModel
from hltl.skills.kinematics import Kinematics
from hltl.skills.library import Action
from hltl.world.scene import OBJECT_LIFT, Scene, Vec3

TIMINGS = ("motion", "cost")
# seconds the hand dwells at the target to close or open the fingers (the analytic cost model's)
_DWELL = {"pick": 0.3, "place": 0.3, "handover_r2h": 0.3, "handover_r2r": 0.4}
_EVENT = {
    "pick": "grasp",
    "place": "release",
    "handover_r2h": "release",
    "handover_r2r": "transfer",
}
_SAMPLE_DT = 0.05  # trajectory rows every 50 ms
_APPROACH = 0.08  # pick and place come down onto the target from this far above
_MEET_GAP = 0.05  # at a robot-to-robot handover each hand stops this short of the meeting point
# rad: a given motion plan whose start is farther than this from an arm's joints is replanned
START_TOLERANCE = 1e-3
# m a walking person keeps from the table's edge (a shoulder's half-width and a hand's margin)
WALK_CLEARANCE = 0.3


@dataclass(frozen=True, slots=True)
class MotionInfo:
    """What the driver made for one action (for the log and tests)."""

    plan: MotionPlan
    ik_error: float  # the worst distance between a waypoint and where IK put the hand
    source: str = "given"  # given | hltl.motion | ik (the driver's own waypoints)
    note: str = ""  # why hltl.motion's planner was not used, if it was not


class MujocoSimulator(Simulator):
    """The discrete-event simulator with arms, people and objects posed in a MuJoCo model.

    Args:
        timing: ``motion`` (an action lasts as long as its motion plan) or ``cost`` (the motion
            is stretched to the scene's cost-model duration, so timing equals the discrete
            simulator's exactly).
        model: a compiled scene (default: compiled, or loaded from the model cache).
        contact_dt: period of the robot–person contact checks, in simulated seconds.
        use_motion_layer: plan IK with hltl.motion for arms it has a model of (needs the
            ``motion`` extra); False uses MuJoCo's own IK for every arm. Those arms start at
            the motion layer's rest pose (``Arm.home``), where its motion plans start.
        kinematics: reach, workspaces and ℓ(w) (e.g. the reachability maps of ``--motion``);
            None keeps the scene's spheres.
        walk_round_table: people walk round the table (:meth:`_route`); False walks them
            straight as the discrete simulator does (with ``cost`` timing, episodes are then
            the discrete simulator's exactly).

    A motion plan given to :meth:`start` (the executor's, from its motion cost model) is played
    as it is when it starts where the arms are (within START_TOLERANCE); otherwise the instance
    is planned again here from the arms' joints, so an arm never jumps.
    """

    def __init__(
        self,
        scene: Scene,
        events: EventSchedule | None = None,
        *,
        seed: int = 0,
        perception: PerceptionModel | None = None,
        log: EventLog | None = None,
        cost: CostModel | None = None,
        timing: str = "motion",
        model: SceneModel | None = None,
        contact_dt: float = 0.02,
        use_motion_layer: bool = True,
        kinematics: Kinematics | None = None,
        walk_round_table: bool = True,
    ) -> None:
        if timing not in TIMINGS:
            raise ValueError(f"timing must be one of {', '.join(TIMINGS)}, got {timing!r}")
        if not contact_dt > 0:
            raise ValueError(f"contact_dt must be positive, got {contact_dt!r}")
        super().__init__(
            scene,
            events,
            seed=seed,
            perception=perception,
            log=log,
            cost=cost,
            kinematics=kinematics,
        )
        self.timing = timing
        self.contact_dt = contact_dt
        self.stage = Stage(model if model is not None else compile_scene(scene))
        self._table = self.stage.table_rect() if walk_round_table else None
        self._arms = _motion_arms(scene) if use_motion_layer else {}
        for rid, arm in self._arms.items():
            self.stage.rehome(rid, tuple(float(v) for v in arm.home))
        self._q: dict[str, tuple[float, ...]] = dict(self.stage.home)
        self._plans: dict[int, MotionInfo] = {}
        self._touching: set[tuple[str, str]] = set()
        self._cell: Cell | None = None
        # what the hands visibly carry: object → (robot or human, offset from the hand)
        self._carry: dict[str, tuple[str, str, np.ndarray]] = {}
        self._frozen: dict[str, Vec3] = {}  # released by a hand, not yet where the log puts it
        self._fired: dict[int, set[int]] = {}
        self.contacts: list[tuple[float, str, str]] = []
        # called with the time after every posing (every contact_dt at most): video recorders
        self.on_pose: list[Callable[[float], None]] = []
        self.synced_at = -1.0
        self._sync()

    # -- the driver --------------------------------------------------------------------------

    def start(self, action: Action, t: float, *, motion: MotionPlan | None = None) -> Handle:
        self._sync()
        handle = super().start(action, t, motion=motion)
        act = self._actions[handle.id]
        if act.status is not None:  # refused at once (robot busy or down)
            return handle
        if motion is not None and self._starts_here(motion):
            info = MotionInfo(motion, 0.0)
        else:
            info = self._plan(action, act.targets)
            if motion is not None:
                info = dataclasses.replace(
                    info, note=f"the given plan starts away from the arms; {info.note}".strip()
                )
        plan = info.plan
        self._fired[handle.id] = set()
        if self.timing == "cost" or plan.duration <= 0:
            plan = _stretch(plan, act.duration)
        else:
            act.duration = plan.duration
            act.end = self.now + plan.duration
        self._plans[handle.id] = dataclasses.replace(info, plan=plan)
        return handle

    def halt(self, handle: Handle, t: float, reason: str) -> None:
        self._sync()
        super().halt(handle, t, reason)

    def _starts_here(self, motion: MotionPlan) -> bool:
        """Every trajectory of ``motion`` starts within START_TOLERANCE of its arm's joints."""
        for tr in motion.trajectories:
            q = self._q.get(tr.robot)
            if q is None or not tr.positions:
                return False
            gap = np.max(np.abs(np.asarray(tr.positions[0]) - np.asarray(q)))
            if float(gap) > START_TOLERANCE:
                return False
        return True

    def motion_of(self, handle: Handle) -> MotionInfo | None:
        return self._plans.get(handle.id)

    # -- people ----------------------------------------------------------------------------

    def _route(self, start: Vec3, to: Vec3) -> list[Vec3]:
        """People walk around the table the arms stand on, WALK_CLEARANCE from its edge (or
        as far as where they start and stop allow), not through the arms above it."""
        if self._table is None:
            return [to]
        return route_around(self._table, start, to, WALK_CLEARANCE)

    # -- time ----------------------------------------------------------------------------------

    def advance(self, t: float) -> None:
        # in short steps, so that contacts are looked for while arms and people move
        while self.now < t - 1e-9:
            super().advance(min(t, self.now + self.contact_dt))
            self._sync()
        super().advance(t)
        self._sync()

    def hand_position(self, rid: str, t: float | None = None) -> Vec3:
        """The hand as the arm's encoders give it: forward kinematics of the current pose."""
        if (t is not None and abs(t - self.now) > 1e-9) or self.synced_at != self.now:
            return super().hand_position(rid, t)
        return self.stage.hand(rid)

    # -- posing --------------------------------------------------------------------------------

    def _running_plan(self, rid: str) -> tuple[MotionInfo, float] | None:
        hid = self._busy.get(rid)
        if hid is None:
            return None
        act = self._actions[hid]
        info = self._plans.get(hid)
        if act.status is not None or info is None:
            return None
        return info, self.now - act.handle.start

    def _sync(self) -> None:
        """Pose the MuJoCo model as the world is at ``now`` and log new contacts."""
        st = self.stage
        now = self.now
        for rid in st.sm.robots:
            run = self._running_plan(rid)
            if run is not None:
                tr = run[0].plan.trajectory(rid)
                if tr is not None:
                    self._q[rid] = tr.sample(run[1])
            st.set_robot(rid, self._q[rid])
        receiving = {}
        for act in self._actions.values():
            if act.status is None and act.handle.action.skill == "handover_r2h":
                h = act.handle.action.human
                if h is not None:
                    receiving[h] = min(1.0, (now - act.handle.start) / max(act.duration, 1e-9))
        holding = {
            st_.loc.ref
            for o in self._objects
            if (st_ := self.object_status(o)).loc.kind == "delivered"
        }
        for hid in self._walkers:
            p = self.human_position(hid)
            yaw, stride = self._walk_pose(hid, p)
            st.set_human(
                hid,
                p,
                yaw,
                reach=min(1.0, 1.5 * receiving.get(hid, 0.0)),
                hold=hid in holding,
                stride=stride,
            )
        st.forward()  # arms and people first: objects follow hands
        self._fire_motion_events()
        for oid in self._objects:
            st.set_object(oid, self._object_pose(oid))
        st.forward()
        self.synced_at = now
        self._note_contacts()
        for f in self.on_pose:
            f(now)

    def _fire_motion_events(self) -> None:
        """The running plans' grasp / transfer / release events: hands take and let go."""
        st = self.stage
        for hid, act in self._actions.items():
            info = self._plans.get(hid)
            if act.status is not None or info is None:
                continue
            done = self._fired.setdefault(hid, set())
            elapsed = self.now - act.handle.start
            action = act.handle.action
            oid = action.object
            for k, (te, kind, rid) in enumerate(info.plan.events):
                if k in done or te > elapsed + 1e-9:
                    continue
                done.add(k)
                at = np.asarray(self._object_pose(oid), float)
                if kind in ("grasp", "transfer") and rid in st.sm.robots:
                    self._carry[oid] = ("robot", rid, at - np.asarray(st.hand(rid)))
                elif kind == "release":
                    carrier = self._carry.get(oid)
                    if carrier is not None and carrier[1] != rid:
                        continue  # the giver lets go after the receiver took it
                    self._carry.pop(oid, None)
                    if action.skill == "handover_r2h" and action.human is not None:
                        self._carry[oid] = ("human", action.human, np.zeros(3))
                    else:
                        self._frozen[oid] = (float(at[0]), float(at[1]), float(at[2]))

    def _object_pose(self, oid: str) -> Vec3:
        """Where an object is drawn: on the hand that visibly holds it, where a hand let it go
        until the log moves it, else where the log says (standing on a surface it is on)."""
        st = self.stage
        s = self.object_status(oid)
        kind, who = s.loc.kind, s.loc.ref
        carrier = self._carry.get(oid)
        # the log is the truth once it says something the hands do not show (while an action
        # on the object runs, its hands are ahead of the log)
        moving = self._running_on(oid)
        if kind == "held" and (carrier is None or (carrier[1] != who and not moving)):
            self._carry[oid] = carrier = ("robot", who, np.zeros(3))
        elif kind == "delivered" and (carrier is None or (carrier[1] != who and not moving)):
            self._carry[oid] = carrier = ("human", who, np.zeros(3))
        elif kind in ("rest", "on") and carrier is not None and not self._grasping(oid):
            self._carry.pop(oid)
            carrier = None
        if carrier is not None:
            base = st.hand(carrier[1]) if carrier[0] == "robot" else st.human_hand(carrier[1])
            p = np.asarray(base) + carrier[2]
            return (float(p[0]), float(p[1]), float(p[2]))
        frozen = self._frozen.get(oid)
        if frozen is not None:
            if kind in ("rest", "on") and not self._releasing(oid):
                del self._frozen[oid]
            else:
                return frozen
        if kind == "on":  # the log puts the object's point OBJECT_LIFT above the surface
            lift = st.object_lift(oid)
            return (s.position[0], s.position[1], s.position[2] - OBJECT_LIFT + lift)
        return s.position

    def _running_on(self, oid: str) -> bool:
        return any(
            a.status is None and a.handle.action.object == oid for a in self._actions.values()
        )

    def _grasping(self, oid: str) -> bool:
        """A running pick of ``oid`` has closed its hand (the log says 'held' only at its end)."""
        return any(
            a.status is None and a.handle.action.object == oid and a.handle.action.skill == "pick"
            for a in self._actions.values()
        )

    def _releasing(self, oid: str) -> bool:
        return any(
            a.status is None and a.handle.action.object == oid and a.handle.action.skill == "place"
            for a in self._actions.values()
        )

    def _walk_pose(self, hid: str, p: Vec3) -> tuple[float, float | None]:
        """Yaw and distance walked so far (None when standing) of a person at ``now``."""
        w = self._walkers[hid]
        now = self.now
        moving = None
        walked = 0.0
        for seg in w.segments:
            if seg.t0 > now + 1e-9:
                break
            walked += math.dist(seg.p0[:2], seg.at(now)[:2])
            if seg.t0 <= now < seg.t1 and math.dist(seg.p0[:2], seg.p1[:2]) > 1e-6:
                moving = seg
        if moving is None:
            return self.stage.facing(p), None
        return math.atan2(moving.p1[1] - moving.p0[1], moving.p1[0] - moving.p0[0]), walked

    def _note_contacts(self) -> None:
        # the hand a person holds out to take an object from a robot is meant to meet it
        taking = {
            (a.handle.action.robots[0], a.handle.action.human)
            for a in self._actions.values()
            if a.status is None and a.handle.action.skill == "handover_r2h"
        }
        pairs: dict[tuple[str, str], Contact] = {}
        for c in self.stage.contacts():
            key = (c.robot, c.human)
            if key in taking and c.part == "r_forearm":
                continue
            if key not in pairs or c.depth > pairs[key].depth:
                pairs[key] = c
        for key in sorted(pairs.keys() - self._touching):
            c = pairs[key]
            self.contacts.append((self.now, c.robot, c.human))
            self.log.emit(
                elog.Contact(
                    t=self.now,
                    robot=c.robot,
                    human=c.human,
                    position=vec(c.position),
                    depth=round(c.depth, 4),
                    part=c.part,
                )
            )
        self._touching = set(pairs)

    # -- motion plans --------------------------------------------------------------------------

    def _plan(self, action: Action, targets: dict[str, Vec3]) -> MotionInfo:
        """hltl.motion's plan of the skill instance where it has models of every arm involved
        (grasps, collision-free paths, time parametrisation); else the driver's own IK plan."""
        note = ""
        if self._arms and all(r in self._arms for r in action.robots) and targets:
            try:
                if self._cell is None:
                    self._cell = Cell(self.scene)
                where = None
                if action.skill == "pick":
                    where = self.object_status(action.object).position
                human_at = None
                if action.human is not None:
                    human_at = self.human_position(action.human)
                sm = plan_action(self._cell, action, dict(self._q), where=where, human_at=human_at)
                if sm.plan is not None:
                    return MotionInfo(sm.plan, 0.0, "hltl.motion")
                note = sm.reason or "no motion"
            except ImportError as exc:
                note = f"hltl.motion unavailable: {exc}"
        info = self._ik_plan(action, targets)
        return dataclasses.replace(info, note=note)

    def _ik_plan(self, action: Action, targets: dict[str, Vec3]) -> MotionInfo:
        """Waypoints by IK from the current joints to each robot's transition target, timed by
        the joints' speed limits, with a dwell to grasp or release."""
        trajectories = []
        worst = 0.0
        arrive = 0.0
        robots = [r for r in action.robots if r in targets]
        for k, rid in enumerate(robots):
            target = np.asarray(targets[rid], float)
            approach: Sequence[float] = DOWN
            if action.skill == "handover_r2r" and len(robots) == 2:
                other = self.scene.robot(robots[1 - k]).base
                here = self.scene.robot(rid).base
                d = np.array([other[0] - here[0], other[1] - here[1], 0.0])
                d /= max(float(np.linalg.norm(d)), 1e-9)
                approach = tuple(d)
                target = target - _MEET_GAP * d
            elif action.skill == "handover_r2h" and action.human is not None:
                hp = self.human_position(action.human)
                base = self.scene.robot(rid).base
                d = np.array([hp[0] - base[0], hp[1] - base[1], 0.0])
                if float(np.linalg.norm(d)) > 1e-6:
                    approach = tuple(d / np.linalg.norm(d))
            points = [target]
            if action.skill in ("pick", "place"):
                points = [target + np.array([0.0, 0.0, _APPROACH]), target]
            qs = [self._q[rid]]
            for p in points:
                q, err = self._ik(rid, p, qs[-1], approach)
                worst = max(worst, err)
                qs.append(q)
            tr = self._time(rid, qs)
            arrive = max(arrive, tr.duration)
            trajectories.append(tr)
        dwell = _DWELL.get(action.skill, 0.3)
        duration = arrive + dwell
        events = tuple((arrive, _EVENT.get(action.skill, "grasp"), r) for r in robots[:1])
        return MotionInfo(MotionPlan(tuple(trajectories), events, duration), worst, "ik")

    def _ik(
        self, rid: str, target: np.ndarray, q0: tuple[float, ...], approach: Sequence[float]
    ) -> tuple[tuple[float, ...], float]:
        arm = self._arms.get(rid)
        if arm is not None:
            res = arm.ik(tuple(target), rotation_z_to(approach), q0, starts=4)
            if not res.ok:
                res = arm.ik(tuple(target), None, q0, starts=4)
            if res.q is not None:
                return res.q, res.position_error
        r = self.stage.solve(rid, tuple(target), q0, approach)
        return r.q, r.error

    def _time(self, rid: str, qs: list[tuple[float, ...]]) -> JointTrajectory:
        """Segments between waypoints, each a smoothstep at the joints' speed limits."""
        rig = self.stage.sm.robots[rid]
        arm = self._arms.get(rid)
        vmax = np.asarray(arm.max_velocity) if arm is not None else np.full(len(qs[0]), rig.vmax)
        times = [0.0]
        rows = [qs[0]]
        for a, b in itertools.pairwise(qs):
            qa, qb = np.asarray(a), np.asarray(b)
            # a smoothstep's peak speed is 1.5 times its mean
            seg = max(0.2, 1.5 * float(np.max(np.abs(qb - qa) / vmax)))
            n = max(2, math.ceil(seg / _SAMPLE_DT))
            t0 = times[-1]
            for i in range(1, n + 1):
                s = i / n
                blend = s * s * (3 - 2 * s)
                times.append(t0 + seg * s)
                rows.append(tuple(float(v) for v in qa + blend * (qb - qa)))
        return JointTrajectory(rid, rig.joint_names, tuple(times), tuple(rows))


def _stretch(plan: MotionPlan, duration: float) -> MotionPlan:
    """The same motion played over ``duration`` seconds."""
    if plan.duration <= 0 or duration <= 0:
        return MotionPlan(plan.trajectories, (), max(duration, 0.0)) if duration > 0 else plan
    k = duration / plan.duration
    trs = tuple(
        JointTrajectory(
            tr.robot, tr.joint_names, tuple(t * k for t in tr.times), tr.positions, None
        )
        for tr in plan.trajectories
    )
    events = tuple((t * k, kind, r) for t, kind, r in plan.events)
    return MotionPlan(trs, events, duration)


def _motion_arms(scene: Scene) -> dict[str, Arm]:
    """hltl.motion arms for the scene's robots it has models of (none without the extra)."""
    out: dict[str, Arm] = {}
    for r in scene.robots:
        if has_model(r.model) and r.model in ("elfin3", "ur5"):
            try:
                out[r.id] = Arm(r.id, r.model, r.base)
            except ImportError:
                return {}
    return out
