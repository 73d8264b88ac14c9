"""A discrete-event simulator of the cell in continuous (simulated) time."""

from __future__ import annotations

import math
import random
from collections.abc import Sequence
from dataclasses import dataclass, field

from hltl.execution import log as elog
from hltl.execution.drivers import ActionState, ActionStatus, Handle
from hltl.execution.log import (
    EventLog,
    HumanStop,
    InstructionGiven,
    ObjectDrop,
    RobotUp,
    Violation,
    vec,
)
from hltl.execution.safety import GRASP_TOLERANCE
from hltl.motion.trajectory import MotionPlan
from hltl.sim.events import (
    EventSchedule,
    HumanMove,
    HumanWander,
    Instruction,
    ObjectMove,
    RobotDown,
)
from hltl.skills.cost import CostModel, executed_duration
from hltl.skills.kinematics import Kinematics
from hltl.skills.library import Action, Transition
from hltl.skills.semantics import ActionSemantics, Infeasible, apply
from hltl.world.geometry import distance
from hltl.world.scene import Scene, Vec3
from hltl.world.state import REST, ObjectStatus, WorldState

_EPS = 1e-9


@dataclass(frozen=True, slots=True)
class PerceptionModel:
    """What the executor sees: the world ``latency`` seconds ago, people's and resting objects'
    horizontal positions with Gaussian noise of standard deviation ``noise`` metres. Hands are
    read from the arms' encoders: exact and current."""

    noise: float = 0.0
    latency: float = 0.0

    def __post_init__(self) -> None:
        for name in ("noise", "latency"):
            v = getattr(self, name)
            if not math.isfinite(v) or v < 0:
                raise ValueError(f"perception {name} must be a finite number >= 0, got {v!r}")


@dataclass(frozen=True, slots=True)
class _Segment:
    t0: float
    p0: Vec3
    t1: float
    p1: Vec3

    def at(self, t: float) -> Vec3:
        if t >= self.t1 or self.t1 <= self.t0:
            return self.p1
        a = max(0.0, (t - self.t0) / (self.t1 - self.t0))
        return tuple(self.p0[i] + a * (self.p1[i] - self.p0[i]) for i in range(3))  # type: ignore[return-value]


@dataclass(slots=True)
class _SimAction:
    handle: Handle
    duration: float
    end: float
    hands0: dict[str, Vec3]
    targets: dict[str, Vec3]
    grasp_at: Vec3 | None
    fails: bool
    outcome: str
    status: ActionStatus | None = None
    unsafe: str | None = None  # why its precondition was false at some instant, if it was
    violation_logged: bool = False


@dataclass(slots=True)
class _Wander:
    """A random walk in progress; its legs are drawn a chunk at a time as the clock reaches them,
    so a walk of a million seconds costs only what the episode lives through."""

    rng: random.Random
    end: float
    speed: float
    leg: float
    until: float  # legs are drawn up to here


@dataclass(slots=True)
class _Walker:
    segments: list[_Segment] = field(default_factory=list)
    arrival: float | None = None  # end of the current walk, for the ``human_stop`` record
    wander: _Wander | None = None


# legs drawn at once by a wander: one log record per chunk
_WANDER_CHUNK = 32


class Simulator:
    """The simulated cell; also the robots' driver.

    Args:
        scene: the cell.
        events: the dynamic events to inject.
        seed: seeds perception noise, skill failures and random walks.
        perception: the perception model.
        log: where world events (people, objects, robots, violations) are recorded.
        cost: the duration model (default: the scene's).
        kinematics: reach and poses of the skills (default: the paper's reach spheres).
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
        kinematics: Kinematics | None = None,
    ) -> None:
        self.scene = scene
        self.events = EventSchedule() if events is None else events
        self.seed = seed
        self.perception = PerceptionModel() if perception is None else perception
        self.log = EventLog() if log is None else log
        self.semantics = ActionSemantics.of(scene, cost=cost, kinematics=kinematics)
        self.cost = self.semantics.cost
        self.now = 0.0
        self._rng_fail = random.Random(f"hltl-fail-{seed}")
        self._rng_noise = random.Random(f"hltl-noise-{seed}")
        self._rng_walk = random.Random(f"hltl-walk-{seed}")
        self._walkers = {
            h.id: _Walker([_Segment(0.0, h.position, 0.0, h.position)]) for h in scene.humans
        }
        self._objects: dict[str, list[tuple[float, ObjectStatus]]] = {
            o.id: [(0.0, ObjectStatus(o.position))] for o in scene.objects
        }
        self._hands: dict[str, Vec3] = {
            r.id: self.semantics.kinematics.home_point(r) for r in scene.robots
        }
        self._down_until: dict[str, float] = {}
        self._busy: dict[str, int] = {}
        self._actions: dict[int, _SimAction] = {}
        self._next_id = 1
        self._next_event = 0
        self._instructions: list[str] = []
        xs = [r.base[0] for r in scene.robots]
        ys = [r.base[1] for r in scene.robots]
        m = max(r.reach for r in scene.robots) + scene.human_reach
        self._bounds = (min(xs) - m, max(xs) + m, min(ys) - m, max(ys) + m)

    # -- the true world --------------------------------------------------------------------------

    def human_position(self, hid: str, t: float | None = None) -> Vec3:
        t = self.now if t is None else t
        segs = self._walkers[hid].segments
        for seg in reversed(segs):
            if seg.t0 <= t + _EPS:
                return seg.at(t)
        return segs[0].p0

    def object_status(self, oid: str, t: float | None = None) -> ObjectStatus:
        t = self.now if t is None else t
        hist = self._objects[oid]
        for t0, st in reversed(hist):
            if t0 <= t + _EPS:
                return st
        return hist[0][1]

    def hand_position(self, rid: str, t: float | None = None) -> Vec3:
        t = self.now if t is None else t
        rid_busy = self._busy.get(rid)
        if rid_busy is not None:
            act = self._actions[rid_busy]
            if act.status is None and rid in act.targets:
                a = (
                    min(1.0, max(0.0, (t - act.handle.start) / act.duration))
                    if act.duration
                    else 1.0
                )
                p0, p1 = act.hands0[rid], act.targets[rid]
                return (
                    p0[0] + a * (p1[0] - p0[0]),
                    p0[1] + a * (p1[1] - p0[1]),
                    p0[2] + a * (p1[2] - p0[2]),
                )
        return self._hands[rid]

    def true_world(self, t: float | None = None) -> WorldState:
        """The world as it is (``t`` defaults to now; past times are exact for people and
        objects, hands are always current)."""
        t = self.now if t is None else t
        return WorldState(
            t=t,
            humans=tuple(sorted((h, self.human_position(h, t)) for h in self._walkers)),
            objects=tuple(sorted((o, self.object_status(o, t)) for o in self._objects)),
            hands=tuple(sorted((r, self.hand_position(r)) for r in self._hands)),
            unavailable=self.unavailable(t),
        )

    def observe(self, t: float | None = None) -> WorldState:
        """What perception reports at ``t``: the world at ``t - latency``, with noise."""
        t = self.now if t is None else t
        stamp = max(0.0, t - self.perception.latency)
        sigma = self.perception.noise
        rng = self._rng_noise

        def noisy(p: Vec3) -> Vec3:
            if sigma == 0.0:
                return p
            return (p[0] + rng.gauss(0.0, sigma), p[1] + rng.gauss(0.0, sigma), p[2])

        humans = tuple(sorted((h, noisy(self.human_position(h, stamp))) for h in self._walkers))
        objects = []
        for o in sorted(self._objects):
            st = self.object_status(o, stamp)
            if st.loc.kind in ("rest", "on"):
                st = ObjectStatus(noisy(st.position), st.loc)
            objects.append((o, st))
        return WorldState(
            t=stamp,
            humans=humans,
            objects=tuple(objects),
            hands=tuple(sorted((r, self.hand_position(r)) for r in self._hands)),
        )

    # -- time ------------------------------------------------------------------------------------

    def next_event_time(self) -> float:
        """When something happens next on its own (an event, an action end, a robot return, an
        arrival); ``inf`` when nothing will."""
        times = [math.inf]
        if self._next_event < len(self.events.timed):
            times.append(self.events.timed[self._next_event].t)
        times += [a.end for a in self._actions.values() if a.status is None]
        times += [u for u in self._down_until.values() if u > self.now + _EPS]
        times += [w.arrival for w in self._walkers.values() if w.arrival is not None]
        return max(self.now, min(times))

    def pending_instructions(self) -> bool:
        """Whether an instruction is still to come (the episode is not over before it)."""
        return bool(self._instructions) or any(
            isinstance(e, Instruction) for e in self.events.timed[self._next_event :]
        )

    def take_instructions(self) -> list[str]:
        """Instructions given since the last call."""
        out, self._instructions = self._instructions, []
        return out

    def advance(self, t: float) -> None:
        """Run the world forward to time ``t``, handling everything that happens on the way."""
        if t < self.now - _EPS:
            raise ValueError(f"cannot go back in time from {self.now} to {t}")
        while True:
            te = self.next_event_time()
            if te > t + _EPS:
                break
            self.now = max(self.now, te)
            self._sample_safety()
            self._fire_due()
        self.now = max(self.now, t)
        self._sample_safety()

    def _fire_due(self) -> None:
        now = self.now
        for act in sorted(self._actions.values(), key=lambda a: a.handle.id):
            if act.status is None and act.end <= now + _EPS:
                self._complete(act)
        for rid in sorted(self._down_until):
            if self._down_until[rid] <= now + _EPS:
                del self._down_until[rid]
                self.log.emit(RobotUp(t=now, robot=rid))
        while (
            self._next_event < len(self.events.timed)
            and self.events.timed[self._next_event].t <= now + _EPS
        ):
            ev = self.events.timed[self._next_event]
            self._next_event += 1
            self._inject(ev)
        for hid in sorted(self._walkers):
            w = self._walkers[hid]
            if w.arrival is not None and w.arrival <= now + _EPS:
                w.arrival = None
                if w.wander is not None:
                    self._wander_on(hid)
                else:
                    self.log.emit(
                        HumanStop(t=now, human=hid, position=vec(self.human_position(hid)))
                    )

    # -- dynamic events --------------------------------------------------------------------------

    def _inject(self, ev: HumanMove | HumanWander | ObjectMove | Instruction | RobotDown) -> None:
        now = self.now
        if isinstance(ev, HumanMove):
            start = self.human_position(ev.human)
            self._walkers[ev.human].wander = None
            points = self._route(start, ev.to)
            eta = self._walk(ev.human, points, ev.speed)
            self.log.emit(
                elog.HumanMove(
                    t=now,
                    human=ev.human,
                    from_=vec(start),
                    to=vec(ev.to),
                    speed=ev.speed,
                    eta=round(eta, 6),
                    wander=[vec(p) for p in points] if len(points) > 1 else None,
                )
            )
        elif isinstance(ev, HumanWander):
            # its own generator, seeded from the walk stream: chunks drawn later do not shift
            # the headings of other people's walks
            rng = random.Random(self._rng_walk.getrandbits(64))
            self._walkers[ev.human].wander = _Wander(rng, now + ev.duration, ev.speed, ev.leg, now)
            self._wander_on(ev.human)
        elif isinstance(ev, ObjectMove):
            st = self.object_status(ev.object)
            if st.loc.kind in ("rest", "on"):
                self._set_object(ev.object, ObjectStatus(ev.to, REST))
                self.log.emit(
                    elog.ObjectMove(
                        t=now,
                        object=ev.object,
                        from_=vec(st.position),
                        to=vec(ev.to),
                        applied=True,
                    )
                )
            else:
                self.log.emit(
                    elog.ObjectMove(
                        t=now,
                        object=ev.object,
                        to=vec(ev.to),
                        applied=False,
                        reason=f"{ev.object} is {st.loc}, not resting",
                    )
                )
        elif isinstance(ev, Instruction):
            self._instructions.append(ev.text)
            self.log.emit(InstructionGiven(t=now, text=ev.text))
        else:
            until = max(self._down_until.get(ev.robot, 0.0), now + ev.duration)
            self._down_until[ev.robot] = until
            self.log.emit(elog.RobotDown(t=now, robot=ev.robot, until=round(until, 6)))
            hid = self._busy.get(ev.robot)
            if hid is not None:
                self._fail(self._actions[hid], f"robot {ev.robot} went down", "stay")

    def _route(self, start: Vec3, to: Vec3) -> list[Vec3]:
        """The points a person walking from ``start`` to ``to`` passes through (``to`` last):
        straight here; the 3D simulator walks them around its table."""
        return [to]

    def _walk(self, hid: str, points: Sequence[Vec3], speed: float) -> float:
        """Replace the person's future motion by a walk through ``points``; returns the arrival."""
        now = self.now
        w = self._walkers[hid]
        here = self.human_position(hid)
        kept = [s for s in w.segments if s.t0 <= now + _EPS]
        last = kept[-1]
        if last.t1 > now:  # cut the walk in progress where the person is now
            kept[-1] = _Segment(last.t0, last.p0, now, here)
        t, p = now, here
        for q in points:
            d = math.dist(p[:2], q[:2])
            t1 = t + d / speed
            kept.append(_Segment(t, p, t1, (q[0], q[1], q[2])))
            t, p = t1, q
        w.segments = kept
        w.arrival = t if t > now + _EPS else None
        return t

    def _wander_on(self, hid: str) -> None:
        """Draw the next chunk of a wander's legs and walk them (logged as one ``human_move``)."""
        wander = self._walkers[hid].wander
        assert wander is not None
        start = self.human_position(hid)
        points = self._wander_points(wander, start)
        if wander.until >= wander.end - _EPS:
            self._walkers[hid].wander = None
        eta = self._walk(hid, points, wander.speed)
        self.log.emit(
            elog.HumanMove(
                t=self.now,
                human=hid,
                from_=vec(start),
                to=vec(points[-1]),
                speed=wander.speed,
                eta=round(eta, 6),
                wander=[vec(p) for p in points],
            )
        )

    def _wander_points(self, wander: _Wander, start: Vec3) -> list[Vec3]:
        x0, x1, y0, y1 = self._bounds
        p = start
        points: list[Vec3] = []
        while len(points) < _WANDER_CHUNK and (not points or wander.until < wander.end - _EPS):
            span = max(0.0, min(wander.leg, wander.end - wander.until))
            wander.until += span
            theta = wander.rng.uniform(0.0, 2 * math.pi)
            step = wander.speed * span
            x = p[0] + step * math.cos(theta)
            y = p[1] + step * math.sin(theta)
            # reflect off the cell's bounds so the person stays around the robots
            x = x0 + abs(x - x0) if x < x0 else (x1 - abs(x - x1) if x > x1 else x)
            y = y0 + abs(y - y0) if y < y0 else (y1 - abs(y - y1) if y > y1 else y)
            p = (min(max(x, x0), x1), min(max(y, y0), y1), p[2])
            points.append(p)
        return points

    def _set_object(self, oid: str, st: ObjectStatus) -> None:
        self._objects[oid].append((self.now, st))

    # -- the driver ------------------------------------------------------------------------------

    def unavailable(self, t: float | None = None) -> frozenset[str]:
        t = self.now if t is None else t
        return frozenset(r for r, u in self._down_until.items() if u > t + _EPS)

    def start(self, action: Action, t: float, *, motion: MotionPlan | None = None) -> Handle:
        # the discrete simulator times an action with its cost model, or as long as the motion
        # plan given for it (what the arms execute: the executor's motion layer chains its
        # plans through where earlier ones left the arms, which this cost model cannot know)
        handle = Handle(self._next_id, action, self.now)
        self._next_id += 1
        world = self.true_world()
        hands0 = {r: self.hand_position(r) for r in action.robots}
        busy = [r for r in action.robots if r in self._busy]
        down = [r for r in action.robots if r in self.unavailable()]
        found = self.semantics.transition(action, world)
        tr = None if isinstance(found, Infeasible) else found
        failure = self.events.failure_of(action.skill)
        fails = failure is not None and self._rng_fail.random() < failure.probability
        if tr is None:
            duration = self.cost.duration(action, _still(action, world), hands0)
        elif motion is not None:
            duration = executed_duration(self.cost, action, tr, motion.duration)
        else:
            duration = self.cost.duration(action, tr, hands0)
        # the cost model has no motion for it from these hands (INFEASIBLE): the arms cannot
        # do it, so it fails at once, as on a busy robot
        no_motion = not math.isfinite(duration)
        if no_motion:
            duration = 0.0
        act = _SimAction(
            handle=handle,
            duration=duration,
            end=self.now + duration,
            hands0=hands0,
            targets=dict(tr.hands) if tr is not None else {},
            grasp_at=world.object_status(action.object).position
            if action.skill == "pick"
            else None,
            fails=fails,
            outcome=failure.outcome if failure is not None else "stay",
        )
        self._actions[handle.id] = act
        if busy or down:
            why = "busy" if busy else "unavailable"
            act.status = ActionStatus(
                ActionState.FAILED, 0.0, self.now, f"robot {', '.join(busy or down)} is {why}"
            )
            return handle
        if no_motion:
            act.status = ActionStatus(
                ActionState.FAILED, 0.0, self.now, f"{action}: no motion from where the hands are"
            )
            return handle
        for r in action.robots:
            self._busy[r] = handle.id
        if isinstance(found, Infeasible):
            act.unsafe = found.reason
        return handle

    def poll(self, handle: Handle, t: float) -> ActionStatus:
        act = self._actions[handle.id]
        if act.status is not None:
            return act.status
        progress = 1.0 if act.duration <= 0 else min(1.0, (self.now - handle.start) / act.duration)
        return ActionStatus(ActionState.RUNNING, progress, self.now)

    def halt(self, handle: Handle, t: float, reason: str) -> None:
        act = self._actions[handle.id]
        if act.status is not None:
            return
        for r in handle.action.robots:
            self._hands[r] = self.hand_position(r)
        progress = 0.0 if act.duration <= 0 else min(1.0, (self.now - handle.start) / act.duration)
        act.status = ActionStatus(ActionState.HALTED, progress, self.now, reason)
        self._release(handle)

    def _release(self, handle: Handle) -> None:
        for r in handle.action.robots:
            if self._busy.get(r) == handle.id:
                del self._busy[r]

    def _sample_safety(self) -> None:
        """Note running actions whose precondition is false in the true world right now."""
        world: WorldState | None = None
        for act in self._actions.values():
            if act.status is not None or act.unsafe is not None:
                continue
            world = world or self.true_world()
            reason = self.semantics.check(act.handle.action, world)
            if reason is not None:
                act.unsafe = f"{reason} (at t={self.now:.2f})"

    def _complete(self, act: _SimAction) -> None:
        action = act.handle.action
        world = self.true_world()
        found = self.semantics.transition(action, world)
        reason = found.reason if isinstance(found, Infeasible) else None
        if reason is None and act.grasp_at is not None:
            now_at = world.object_status(action.object).position
            if distance(now_at, act.grasp_at) > GRASP_TOLERANCE:
                reason = f"{action}: {action.object} moved away from the grasp"
        if reason is not None:
            act.unsafe = act.unsafe or reason
            self._violation(act)
            self._fail(act, f"precondition false at completion: {reason}", "stay")
            return
        if act.unsafe is not None:
            self._violation(act)
        assert not isinstance(found, Infeasible)  # its reason was handled above
        if act.fails:
            self._fail(act, f"{action.skill} failed", act.outcome, found)
            return
        after = apply(world, found)
        self._set_object(found.obj, after.object_status(found.obj))
        for rid, _ in found.hands:
            pos = after.hand_position(rid)
            assert pos is not None  # apply moved it there
            self._hands[rid] = pos
        act.status = ActionStatus(ActionState.DONE, 1.0, self.now)
        self._release(act.handle)

    def _fail(
        self, act: _SimAction, reason: str, outcome: str, tr: Transition | None = None
    ) -> None:
        action = act.handle.action
        for r in action.robots:
            self._hands[r] = self.hand_position(r)
        if outcome == "drop":
            st = self.object_status(action.object)
            at = tr.hands[-1][1] if tr is not None and tr.hands else st.position
            z = self.scene.object(action.object).position[2]
            landed = (at[0], at[1], z)
            self._set_object(action.object, ObjectStatus(landed, REST))
            self.log.emit(
                ObjectDrop(t=self.now, object=action.object, position=vec(landed), cause=reason)
            )
            reason += "; the object dropped"
        progress = (
            0.0 if act.duration <= 0 else min(1.0, (self.now - act.handle.start) / act.duration)
        )
        act.status = ActionStatus(ActionState.FAILED, progress, self.now, reason)
        self._release(act.handle)

    def _violation(self, act: _SimAction) -> None:
        if act.violation_logged:
            return
        act.violation_logged = True
        self.log.emit(
            Violation(
                t=self.now,
                handle=act.handle.id,
                action=act.handle.action.to_dict(),
                reason=act.unsafe or "",
            )
        )


def _still(action: Action, world: WorldState) -> Transition:
    """A transition that moves nothing: times an action whose precondition fails (it will fail)."""
    loc = world.object_status(action.object).loc
    return Transition(action.object, loc, loc, (), frozenset(), ())
