"""What happened when: a plan or an executed episode (from its log) as spans, walks and markers."""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any, Literal

from hltl.errors import PlanFormatError, SceneError
from hltl.execution import log
from hltl.execution.log import EpisodeStart, LogRecord
from hltl.planner.result import PlanResult
from hltl.skills.kinematics import REACH_SPHERES, Kinematics
from hltl.skills.library import Action
from hltl.world.geometry import meeting_pairs
from hltl.world.scene import Scene, Vec3, scene_from_dict

Outcome = Literal["planned", "done", "failed", "halted", "running"]
# Where an object is: resting at a point, held by a robot, on a surface (at a point), delivered.
ObjectPlace = tuple[str, str, Vec3]

# Replan triggers that are the loop's routine (first plan, a step ended as planned).
ROUTINE_TRIGGERS = frozenset({"initial", "progress"})


@dataclass(frozen=True, slots=True)
class ActionSpan:
    """One skill instance in time.

    Attributes:
        action: the ground action.
        start: when it began.
        end: when it ended (done, failed, halted) or the step's end for a plan.
        outcome: ``planned`` (a plan's step), ``done``, ``failed``, ``halted`` or ``running``
            (the log ends before it does).
        step: index of the step it belongs to.
        expected: the planned duration d(a) (hands move over it); ``end - start`` if unknown.
        reason: why it failed or was halted.
    """

    action: Action
    start: float
    end: float
    outcome: Outcome
    step: int
    expected: float
    reason: str = ""


@dataclass(frozen=True, slots=True)
class Marker:
    """A moment worth a vertical line: ``kind`` is one of ``halt``, ``replan``, ``no_plan``,
    ``takeover``, ``predict``, ``failure``, ``goal``, ``robot``; ``text`` says what happened."""

    t: float
    kind: str
    text: str
    detail: str = ""


@dataclass(frozen=True, slots=True)
class Segment:
    """A straight walk of a person from ``p0`` at ``t0`` to ``p1`` at ``t1``."""

    t0: float
    p0: Vec3
    t1: float
    p1: Vec3

    def at(self, t: float) -> Vec3:
        if t >= self.t1 or self.t1 <= self.t0:
            return self.p1
        a = max(0.0, (t - self.t0) / (self.t1 - self.t0))
        return _lerp(self.p0, self.p1, a)


@dataclass(frozen=True, slots=True)
class Prediction:
    """A background plan's forecast: ``human`` is predicted at ``position``, served by
    ``robots``; the planner's answer for that world was ``status``."""

    t: float
    human: str
    position: Vec3
    robots: tuple[str, ...]
    status: str


@dataclass(frozen=True, slots=True)
class StepInfo:
    """A dispatched step: when, and what it does in words."""

    t: float
    index: int
    text: str


@dataclass(frozen=True, slots=True)
class _HandMove:
    t0: float
    p0: Vec3
    t1: float
    p1: Vec3
    stop: float  # the hand freezes here (halt, failure) if earlier than t1


@dataclass(frozen=True, slots=True)
class Track:
    """A plan or an episode laid out in time.

    Attributes:
        kind: ``plan`` or ``episode``.
        scene: the cell.
        spans: the actions, in start order.
        markers: halts, disruptive replans, takeovers, background plans, failures, goals.
        walks: each person's straight walks, in time order.
        predictions: forecasts of background (predictive) plans.
        steps: dispatched steps.
        end: the makespan (plan) or the time the task was done or given up (episode).
        success: whether the episode met every goal (``None`` for a plan).
        title: a one-line description.
        note: why there is nothing to show (a plan that is not solved), else empty.
        kinematics: where hands go (default: the paper's reach spheres).
    """

    kind: Literal["plan", "episode"]
    scene: Scene
    spans: tuple[ActionSpan, ...]
    markers: tuple[Marker, ...] = ()
    walks: tuple[tuple[str, tuple[Segment, ...]], ...] = ()
    predictions: tuple[Prediction, ...] = ()
    steps: tuple[StepInfo, ...] = ()
    jumps: tuple[tuple[float, str, Vec3], ...] = ()
    end: float = 0.0
    success: bool | None = None
    title: str = ""
    note: str = ""
    kinematics: Kinematics = field(default=REACH_SPHERES, repr=False, compare=False)
    _hands: dict[str, tuple[_HandMove, ...]] = field(init=False, repr=False, compare=False)
    _places: dict[str, tuple[tuple[float, ObjectPlace], ...]] = field(
        init=False, repr=False, compare=False
    )

    def __post_init__(self) -> None:
        hands, places = _kinematics(self)
        object.__setattr__(self, "_hands", hands)
        object.__setattr__(self, "_places", places)

    # -- rows -------------------------------------------------------------------------------------
    @property
    def robots(self) -> tuple[str, ...]:
        return self.scene.robot_ids

    @property
    def humans(self) -> tuple[str, ...]:
        return self.scene.human_ids

    def human_name(self, hid: str) -> str:
        for h in self.scene.humans:
            if h.id == hid:
                return h.name
        return hid

    def rows(self) -> tuple[str, ...]:
        """Gantt rows top to bottom: robots, then people."""
        return self.robots + self.humans

    # -- where things are ------------------------------------------------------------------------
    def human_position(self, hid: str, t: float) -> Vec3:
        """Where person ``hid`` is at time ``t`` (their scene position before any walk)."""
        for h, segs in self.walks:
            if h == hid:
                for seg in reversed(segs):
                    if seg.t0 <= t + 1e-9:
                        return seg.at(t)
        return self.scene.human(hid).position

    def human_path(self, hid: str, t: float) -> list[Vec3]:
        """The path person ``hid`` has walked up to time ``t`` (corners and the point now)."""
        pts = [self.scene.human(hid).position]
        for h, segs in self.walks:
            if h != hid:
                continue
            for seg in segs:
                if seg.t0 > t + 1e-9:
                    break
                pts.append(seg.p0)
                pts.append(seg.at(t))
        return pts

    def hand_position(self, rid: str, t: float) -> Vec3:
        """Where robot ``rid``'s hand is at time ``t``: moving linearly to each action's target
        over the action's planned duration, frozen where a halt or failure stopped it."""
        pos = self.kinematics.home_point(self.scene.robot(rid))
        for mv in self._hands.get(rid, ()):
            if mv.t0 > t + 1e-9:
                break
            pos = _hand_at(mv, t)
        return pos

    def object_place(self, oid: str, t: float) -> ObjectPlace:
        """(kind, ref, point) of object ``oid`` at ``t``: ``rest``/``on`` with the point where it
        lies, ``held`` with the robot, ``delivered`` with the person (point: not meaningful)."""
        place: ObjectPlace = ("rest", "", self.scene.object(oid).position)
        for t0, p in self._places.get(oid, ()):
            if t0 > t + 1e-9:
                break
            place = p
        return place

    def object_position(self, oid: str, t: float) -> Vec3:
        kind, ref, point = self.object_place(oid, t)
        if kind == "held":
            return self.hand_position(ref, t)
        if kind == "delivered":
            x, y, _ = self.human_position(ref, t)
            return (x + 0.07, y - 0.07, 0.0)
        return point

    def step_at(self, t: float) -> StepInfo | None:
        """The last step dispatched at or before ``t``."""
        last = None
        for s in self.steps:
            if s.t <= t + 1e-9:
                last = s
        return last

    def rendezvous(self) -> list[tuple[str, str, Vec3]]:
        """Each meeting pair once, with its rendezvous point."""
        out = []
        for g, r in meeting_pairs(self.scene):
            if g < r:
                p = self.kinematics.rendezvous_point(self.scene.robot(g), self.scene.robot(r))
                out.append((g, r, p))
        return out


# -- building tracks ------------------------------------------------------------------------------


def track_from_plan(
    plan: PlanResult | Mapping[str, Any], scene: Scene, *, title: str | None = None
) -> Track:
    """A plan replayed on its scene: each action spans its step, people stand still.

    Raises:
        PlanFormatError: ``plan`` is a malformed plan dict or names ids the scene lacks.
    """
    result = plan if isinstance(plan, PlanResult) else PlanResult.from_dict(plan)
    _check_ids(result, scene)
    spans = []
    steps = []
    for i, step in enumerate(result.steps):
        for a in step.actions:
            spans.append(
                ActionSpan(a, step.start, step.start + step.duration, "planned", i, step.duration)
            )
        steps.append(StepInfo(step.start, i, _describe_step(scene, step.actions)))
    end = result.makespan if result.makespan is not None else _last_end(spans)
    status = result.status.value
    head = f"plan ({status}), makespan {end:.2f} s" if result.solved else f"plan: {status}"
    note = "" if result.solved else f"no plan ({status}): {result.reason or 'no reason given'}"
    return Track(
        kind="plan",
        scene=scene,
        spans=tuple(spans),
        steps=tuple(steps),
        end=end,
        title=head if title is None else title,
        note=note,
    )


def track_from_log(records: Sequence[LogRecord], *, title: str | None = None) -> Track:
    """An executed episode from its log records (``hltl.execution.log.read_log``).

    Raises:
        PlanFormatError: the log does not start with an ``episode_start`` that carries the scene,
            or a record lacks a field this needs.
    """
    if not records or not isinstance(records[0], EpisodeStart):
        raise PlanFormatError("not an execution log: the first record must be 'episode_start'")
    try:
        scene = scene_from_dict(records[0].scene, source="log episode_start.scene")
    except (KeyError, SceneError) as exc:
        raise PlanFormatError(
            f"the log's episode_start has no valid scene ({exc}); expected the scene as written "
            "by hltl run"
        ) from None
    try:
        return _track_from_records(scene, records, title)
    except (KeyError, TypeError, ValueError, IndexError) as exc:
        raise PlanFormatError(f"malformed log record: {exc!r}") from None


_OUTCOMES: dict[type[LogRecord], Outcome] = {
    log.ActionDone: "done",
    log.ActionFailed: "failed",
    log.ActionHalted: "halted",
}


def _track_from_records(scene: Scene, records: Sequence[LogRecord], title: str | None) -> Track:
    open_: dict[int, tuple[log.ActionStart, int]] = {}
    spans: list[ActionSpan] = []
    markers: list[Marker] = []
    walks: dict[str, list[Segment]] = {}
    predictions: list[Prediction] = []
    steps: list[StepInfo] = []
    jumps: list[tuple[float, str, Vec3]] = []
    step = -1
    end_t = float(records[-1].t)
    success: bool | None = None
    first = records[0]
    instruction = str(first.instruction or "") if isinstance(first, EpisodeStart) else ""
    last_predict_ctx = ""
    for rec in records:
        t = float(rec.t)
        if isinstance(rec, log.Dispatch):
            step = int(rec.step)
            actions = [Action.from_dict(a) for a in rec.actions]
            steps.append(StepInfo(t, step, _describe_step(scene, actions)))
        elif isinstance(rec, log.ActionStart):
            open_[int(rec.handle)] = (rec, step)
        elif isinstance(rec, log.ActionDone | log.ActionFailed | log.ActionHalted):
            found = open_.pop(int(rec.handle), None)
            if found is None:
                continue
            start, k = found
            t0 = float(start.t)
            end = rec.ended
            reason = "" if isinstance(rec, log.ActionDone) else rec.reason
            spans.append(
                ActionSpan(
                    Action.from_dict(start.action),
                    t0,
                    end,
                    _OUTCOMES[type(rec)],
                    k,
                    float(end - t0 if start.expected is None else start.expected),
                    str(reason),
                )
            )
            if isinstance(rec, log.ActionFailed):
                markers.append(Marker(t, "failure", "failed", str(reason)))
        elif isinstance(rec, log.Halt):
            markers.append(Marker(t, "halt", f"halt ({rec.kind})", str(rec.reason)))
        elif isinstance(rec, log.REPLANS):
            trigger = str(rec.trigger)
            routine = set(trigger.split("+")) <= ROUTINE_TRIGGERS
            if rec.status != "solved":
                markers.append(
                    Marker(t, "no_plan", f"no plan ({rec.status})", str(rec.reason or ""))
                )
            elif isinstance(rec, log.Replan) and rec.source == "planner" and not routine:
                markers.append(
                    Marker(
                        t,
                        "replan",
                        f"replan ({trigger.replace('halt:', 'after ')})",
                        f"new makespan {float(rec.makespan or 0.0):.2f} s",
                    )
                )
        elif isinstance(rec, log.Takeover):
            markers.append(
                Marker(
                    t,
                    "takeover",
                    "takeover",
                    f"plan predicted at t={float(rec.predicted_at or 0.0):.2f} s takes over "
                    f"({rec.context})",
                )
            )
        elif isinstance(rec, log.Predict):
            for hid, p in dict(rec.humans or {}).items():
                predictions.append(
                    Prediction(
                        t,
                        str(hid),
                        _v3(p["position"]),
                        tuple(str(r) for r in p.get("robots", ())),
                        str(rec.status),
                    )
                )
            ctx = str(rec.context)
            if rec.status == "solved" and ctx != last_predict_ctx:
                markers.append(Marker(t, "predict", "background plan", f"for {ctx}"))
            last_predict_ctx = ctx
        elif isinstance(rec, log.HumanMove):
            if rec.from_ is None or rec.speed is None:
                raise KeyError("a human_move without 'from' or 'speed'")
            points = [_v3(p) for p in rec.wander or [rec.to]]
            _walk(walks, scene, str(rec.human), t, _v3(rec.from_), points, float(rec.speed))
        elif isinstance(rec, log.ObjectMove) and rec.applied:
            jumps.append((t, str(rec.object), _v3(rec.to)))
        elif isinstance(rec, log.ObjectDrop):
            jumps.append((t, str(rec.object), _v3(rec.position)))
        elif isinstance(rec, log.InstructionGiven):
            markers.append(Marker(t, "goal", "new instruction", repr(rec.text)))
        elif isinstance(rec, log.RobotDown):
            markers.append(Marker(t, "robot", f"{rec.robot} down", ""))
        elif isinstance(rec, log.RobotUp):
            markers.append(Marker(t, "robot", f"{rec.robot} up", ""))
        elif isinstance(rec, log.Grounding) and not instruction:
            instruction = str(rec.text)
        elif isinstance(rec, log.EpisodeEnd):
            success = bool(rec.success)
            end_t = float(t if rec.time_cost is None else rec.time_cost)
    for start, k in open_.values():  # still running when the log ends
        t0 = float(start.t)
        spans.append(
            ActionSpan(
                Action.from_dict(start.action),
                t0,
                max(end_t, t0),
                "running",
                k,
                float(start.expected or 0.0),
            )
        )
    spans.sort(key=lambda s: (s.start, s.step))
    if title is None:
        verdict = "" if success is None else ("success" if success else "failed")
        head = f"episode: {instruction!r}" if instruction else "episode"
        title = f"{head} — {verdict}, {end_t:.2f} s" if verdict else head
    return Track(
        kind="episode",
        scene=scene,
        spans=tuple(spans),
        markers=tuple(markers),
        walks=tuple((h, tuple(segs)) for h, segs in walks.items()),
        predictions=tuple(predictions),
        steps=tuple(steps),
        jumps=tuple(jumps),
        end=end_t,
        success=success,
        title=title,
    )


def _walk(
    walks: dict[str, list[Segment]],
    scene: Scene,
    hid: str,
    t: float,
    start: Vec3,
    points: Sequence[Vec3],
    speed: float,
) -> None:
    """A new walk replaces the rest of the current one (as the simulator does)."""
    segs = walks.setdefault(hid, [])
    kept = [s for s in segs if s.t0 <= t + 1e-9]
    if kept and kept[-1].t1 > t:
        last = kept[-1]
        kept[-1] = Segment(last.t0, last.p0, t, last.at(t))
    p = start
    for q in points:
        d = math.dist(p[:2], q[:2])
        t1 = t + (d / speed if speed > 0 else 0.0)
        kept.append(Segment(t, p, t1, q))
        t, p = t1, q
    walks[hid] = kept


# -- hands and objects ----------------------------------------------------------------------------


def _kinematics(
    track: Track,
) -> tuple[dict[str, tuple[_HandMove, ...]], dict[str, tuple[tuple[float, ObjectPlace], ...]]]:
    """Hand motions and object places, in one pass over the actions in time order."""
    scene = track.scene
    moves: dict[str, list[_HandMove]] = {r.id: [] for r in scene.robots}
    places: dict[str, list[tuple[float, ObjectPlace]]] = {o.id: [] for o in scene.objects}
    # events in time order: object jumps, then ends, then starts at equal times
    events: list[tuple[float, int, int]] = []
    for i, (t, _, _) in enumerate(track.jumps):
        events.append((t, 0, i))
    for i, s in enumerate(track.spans):
        events.append((s.end, 1, i))
        events.append((s.start, 2, i))
    events.sort()

    def place_at(oid: str, t: float) -> ObjectPlace:
        hist = places.get(oid, [])
        return hist[-1][1] if hist else ("rest", "", scene.object(oid).position)

    def hand_at(rid: str, t: float) -> Vec3:
        hist = moves.get(rid, [])
        return _hand_at(hist[-1], t) if hist else track.kinematics.home_point(scene.robot(rid))

    for t, kind, i in events:
        if kind == 0:
            _, oid, point = track.jumps[i]
            if oid in places:
                places[oid].append((t, ("rest", "", point)))
            continue
        span = track.spans[i]
        a = span.action
        if kind == 2:
            targets = _targets(track, a, place_at(a.object, t), t)
            for rid, target in targets.items():
                if rid not in moves:
                    continue
                stop = span.end if span.outcome in ("failed", "halted") else math.inf
                p0 = hand_at(rid, t)
                moves[rid].append(_HandMove(t, p0, t + max(span.expected, 0.0), target, stop))
        elif span.outcome in ("done", "planned") and a.object in places:
            new = _after(track, a)
            if new is not None:
                places[a.object].append((t, new))
    return (
        {r: tuple(v) for r, v in moves.items()},
        {o: tuple(v) for o, v in places.items()},
    )


def _targets(track: Track, a: Action, place: ObjectPlace, t: float) -> dict[str, Vec3]:
    """Where each executor's hand goes for action ``a`` started at ``t``."""
    scene = track.scene
    try:
        if a.skill == "pick":
            return {a.robots[0]: place[2]}
        if a.skill == "place" and a.surface is not None:
            return {a.robots[0]: scene.surface(a.surface).center}
        if a.skill == "handover_r2r" and len(a.robots) == 2:
            g, r = (scene.robot(x) for x in a.robots)
            p = track.kinematics.rendezvous_point(g, r)
            return {a.robots[0]: p, a.robots[1]: p}
        if a.skill == "handover_r2h" and a.human is not None:
            robot = scene.robot(a.robots[0])
            pos = track.human_position(a.human, t)
            return {robot.id: track.kinematics.human_handover_point(robot, pos)}
    except KeyError:  # an id the scene lacks: nothing to draw
        return {}
    return {}


def _after(track: Track, a: Action) -> ObjectPlace | None:
    if a.skill == "pick":
        return ("held", a.robots[0], (0.0, 0.0, 0.0))
    if a.skill == "handover_r2r":
        return ("held", a.robots[-1], (0.0, 0.0, 0.0))
    if a.skill == "handover_r2h" and a.human is not None:
        return ("delivered", a.human, (0.0, 0.0, 0.0))
    if a.skill == "place" and a.surface is not None:
        return ("on", a.surface, track.scene.surface(a.surface).center)
    return None


def _hand_at(mv: _HandMove, t: float) -> Vec3:
    tt = min(t, mv.stop)
    if mv.t1 <= mv.t0:
        return mv.p1 if tt >= mv.t0 else mv.p0
    a = min(1.0, max(0.0, (tt - mv.t0) / (mv.t1 - mv.t0)))
    return _lerp(mv.p0, mv.p1, a)


# -- small helpers --------------------------------------------------------------------------------


def _lerp(p: Vec3, q: Vec3, a: float) -> Vec3:
    return (p[0] + a * (q[0] - p[0]), p[1] + a * (q[1] - p[1]), p[2] + a * (q[2] - p[2]))


def _v3(p: Any) -> Vec3:
    if not isinstance(p, list | tuple) or len(p) != 3:
        raise ValueError(f"expected a point [x, y, z], got {p!r}")
    return (float(p[0]), float(p[1]), float(p[2]))


def _last_end(spans: Sequence[ActionSpan]) -> float:
    return max((s.end for s in spans), default=0.0)


def _check_ids(result: PlanResult, scene: Scene) -> None:
    for step in result.steps:
        for a in step.actions:
            unknown = [r for r in a.robots if r not in scene.robot_ids]
            if a.object not in scene.object_ids:
                unknown.append(a.object)
            if a.human is not None and a.human not in scene.human_ids:
                unknown.append(a.human)
            if a.surface is not None and a.surface not in scene.surface_ids:
                unknown.append(a.surface)
            if unknown:
                raise PlanFormatError(
                    f"the plan's action {a} names {', '.join(map(repr, unknown))}, which the "
                    f"scene {scene.source} does not have; give the plan's scene"
                )


def describe_action(scene: Scene, a: Action) -> str:
    """One action in words: 'r1 hands bottle to Person A'."""
    rs = a.robots
    if a.skill == "pick":
        return f"{rs[0]} picks {a.object}"
    if a.skill == "place":
        return f"{rs[0]} places {a.object} on {a.surface}"
    if a.skill == "handover_r2r" and len(rs) == 2:
        return f"{rs[0]} hands {a.object} to {rs[1]}"
    if a.skill == "handover_r2h" and a.human is not None:
        name = a.human
        for h in scene.humans:
            if h.id == a.human:
                name = h.name
        return f"{rs[0]} hands {a.object} to {name}"
    return str(a)


def _describe_step(scene: Scene, actions: Sequence[Action]) -> str:
    return "; ".join(describe_action(scene, a) for a in actions) or "(wait)"
