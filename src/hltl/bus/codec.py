"""Payloads on the bus: JSON for hltl's own records, ROS 2 message types (CDR) where one exists."""

from __future__ import annotations

import hashlib
import importlib
import json
import math
from collections.abc import Iterator, Mapping, Sequence
from contextlib import contextmanager
from dataclasses import dataclass
from functools import cache
from typing import Any, Literal, Protocol

from hltl.errors import BackendUnavailableError, BusError, HltlError
from hltl.execution.drivers import ActionState, ActionStatus
from hltl.planner.result import Binding, PlanResult, PlanStatus, PlanStep, SearchStats
from hltl.skills.library import Action
from hltl.spec.monitor import DONE
from hltl.world.scene import Vec3
from hltl.world.state import Loc, ObjectStatus, WorldState

Op = Literal["start", "halt"]


def dumps(data: Any) -> bytes:
    return json.dumps(data, separators=(",", ":"), allow_nan=False).encode()


def loads(payload: bytes, what: str) -> dict[str, Any]:
    """A JSON object from a payload, or :class:`BusError` naming ``what`` was expected."""
    try:
        data = json.loads(payload)
    except (ValueError, UnicodeDecodeError) as exc:
        raise BusError(f"malformed {what} on the bus: {exc}; payload {payload[:60]!r}") from None
    if not isinstance(data, dict):
        raise BusError(f"malformed {what} on the bus: expected a JSON object, got {data!r:.60}")
    return data


@dataclass(frozen=True, slots=True)
class Command:
    """Executor → robot: start or halt one action.

    ``seq`` numbers the executor's commands (a retransmission keeps its number); ``handle`` is
    the action's id, chosen by the executor, so a robot node starts each handle at most once.
    """

    episode: str
    seq: int
    op: Op
    handle: int
    action: Action
    t: float
    reason: str = ""
    motion: tuple[str, ...] = ()  # robots whose joint trajectories were sent for this start

    def to_dict(self) -> dict[str, Any]:
        d: dict[str, Any] = {
            "episode": self.episode,
            "seq": self.seq,
            "op": self.op,
            "handle": self.handle,
            "action": self.action.to_dict(),
            "t": self.t,
            "reason": self.reason,
        }
        if self.motion:
            d["motion"] = list(self.motion)
        return d

    def encode(self) -> bytes:
        return dumps(self.to_dict())

    @classmethod
    def from_dict(cls, d: Mapping[str, Any]) -> Command:
        try:
            op = d["op"]
            if op not in ("start", "halt"):
                raise ValueError(f"op {op!r} is not start or halt")
            return cls(
                str(d["episode"]),
                int(d["seq"]),
                op,
                int(d["handle"]),
                Action.from_dict(d["action"]),
                float(d["t"]),
                str(d.get("reason", "")),
                tuple(str(r) for r in d.get("motion", ())),
            )
        except (KeyError, TypeError, ValueError, HltlError) as exc:
            raise BusError(f"malformed command on the bus: {exc}") from None

    @classmethod
    def decode(cls, payload: bytes) -> Command:
        return cls.from_dict(loads(payload, "command"))


@dataclass(frozen=True, slots=True)
class Report:
    """Robot → executor: how one action is doing. ``seq`` numbers the node's reports."""

    episode: str
    seq: int
    handle: int
    status: ActionStatus

    def to_dict(self) -> dict[str, Any]:
        s = self.status
        return {
            "episode": self.episode,
            "seq": self.seq,
            "handle": self.handle,
            "state": s.state.value,
            "progress": s.progress,
            "t": s.t,
            "reason": s.reason,
        }

    def encode(self) -> bytes:
        return dumps(self.to_dict())

    @classmethod
    def from_dict(cls, d: Mapping[str, Any], episode: str | None = None) -> Report:
        """A report from its JSON form; one that leaves out its episode (a tick ahead: it is
        the request's) and an empty reason is of ``episode``."""
        try:
            state, reason = ActionState(d["state"]), str(d.get("reason", ""))
            status = ActionStatus(state, float(d["progress"]), float(d["t"]), reason)
            ep = d["episode"] if episode is None or "episode" in d else episode
            return cls(str(ep), int(d["seq"]), int(d["handle"]), status)
        except (KeyError, TypeError, ValueError) as exc:
            raise BusError(f"malformed action report on the bus: {exc}") from None

    @classmethod
    def decode(cls, payload: bytes) -> Report:
        return cls.from_dict(loads(payload, "action report"))


# -- the executor's basis (foresight) ---------------------------------------------------------


def _int(x: Any, what: str, least: int = 0) -> int:
    if isinstance(x, bool) or not isinstance(x, int) or x < least:
        raise ValueError(f"{what} must be an integer >= {least}, got {x!r:.40}")
    return x


def _number(x: Any, what: str, positive: bool = False) -> float:
    if isinstance(x, bool) or not isinstance(x, int | float):
        raise ValueError(f"{what} must be a number, got {x!r:.40}")
    v = float(x)
    if not math.isfinite(v) or v < 0 or (positive and v == 0):
        raise ValueError(
            f"{what} must be a finite {'positive' if positive else 'non-negative'} "
            f"number, got {x!r:.40}"
        )
    return v


@dataclass(frozen=True, slots=True)
class WireCheck:
    """The executor's check before a dispatch as a basis carries it: its configuration's
    intrusion speed and forecast spacing, and its constant-velocity forecaster's window and
    least speed (``None``: no intrusion check)."""

    intrusion_speed: float
    predict_dt: float
    forecast: tuple[float, float] | None = None
    # the forecast's horizon when the executor plans for forecast worlds (None: it does not,
    # or an executor from before session 23)
    horizon: float | None = None


@dataclass(frozen=True, slots=True)
class WireBasis:
    """The executor's :class:`~hltl.execution.drivers.Basis` as it travels to the node (a step
    request's ``"ahead": {"basis": …}``): its spec's version and monitor state, the exact
    planner's algorithm and time limit, its check, and the spec itself (JSON, as
    :func:`hltl.spec.hierarchy.spec_to_dict` writes it) the first time a version goes, ``None``
    after that (the node keeps it by version).

    Attributes:
        version: counts the executor's specs (1 for the first).
        q: the monitor state, one automaton state per formula of the spec (``DONE``, -1, for
            one done).
        algorithm: the exact planner's search algorithm.
        timeout: its time limit, seconds.
        check: the executor's check before a dispatch (``None``: the node does not check).
        spec: the spec's JSON form, or ``None``: the one the node has for ``version``.
    """

    version: int
    q: tuple[int, ...]
    algorithm: str
    timeout: float
    check: WireCheck | None = None
    spec: Mapping[str, Any] | None = None

    def to_dict(self, with_spec: bool = True) -> dict[str, Any]:
        d: dict[str, Any] = {
            "version": self.version,
            "q": list(self.q),
            "planner": {"algorithm": self.algorithm, "timeout": self.timeout},
        }
        if self.check is not None:
            d["check"] = _check_to(self.check)
        if with_spec and self.spec is not None:
            d["spec"] = self.spec
        return d

    @classmethod
    def from_dict(cls, d: Any) -> WireBasis:
        """Inverse of :meth:`to_dict`, every field checked.

        Raises:
            BusError: the payload is not a basis (one line saying what is wrong).
        """
        with _malformed("basis"):
            if not isinstance(d, Mapping):
                raise ValueError(f"expected a JSON object, got {d!r:.40}")
            q = d["q"]
            if not isinstance(q, list) or not q:
                raise ValueError(f"q must be a non-empty list of monitor states, got {q!r:.40}")
            algorithm, timeout = _planner_from(d["planner"])
            spec = d.get("spec")
            if spec is not None and not isinstance(spec, Mapping):
                raise ValueError(f"spec must be an object, got {spec!r:.40}")
            return cls(
                _int(d["version"], "version", 1),
                tuple(_int(x, "a monitor state", DONE) for x in q),
                algorithm,
                timeout,
                _check_from(d.get("check")),
                spec,
            )


@dataclass(frozen=True, slots=True)
class WireBriefing:
    """The executor's :class:`~hltl.execution.drivers.Briefing` as it travels to the node (a
    first-step request's ``"ahead": {"brief": …}``): the episode's first instruction, which
    the executor grounds with the offline grounder, and the exact planner and check it will
    plan and check the first step with (as in :class:`WireBasis`)."""

    instruction: str
    algorithm: str
    timeout: float
    check: WireCheck | None = None

    def to_dict(self) -> dict[str, Any]:
        return {
            "instruction": self.instruction,
            "grounder": "offline",
            "planner": {"algorithm": self.algorithm, "timeout": self.timeout},
            "check": _check_to(self.check),
        }

    @classmethod
    def from_dict(cls, d: Any) -> WireBriefing:
        """Inverse of :meth:`to_dict`, every field checked.

        Raises:
            BusError: the payload is not a briefing (one line saying what is wrong).
        """
        with _malformed("briefing"):
            if not isinstance(d, Mapping):
                raise ValueError(f"expected a JSON object, got {d!r:.40}")
            text, grounder = d["instruction"], d["grounder"]
            if not isinstance(text, str):
                raise ValueError(f"instruction must be a string, got {text!r:.40}")
            if grounder != "offline":
                raise ValueError(f"grounder must be 'offline', got {grounder!r:.40}")
            algorithm, timeout = _planner_from(d["planner"])
            return cls(text, algorithm, timeout, _check_from(d.get("check")))


@dataclass(frozen=True, slots=True)
class WirePlan:
    """One of the executor's background plans as the node made it (an answer's or reply's
    ``"plans"``): the problem's digest (:func:`hltl.execution.background.problem_digest`),
    the wall-clock seconds it took the node, and the planner's result, its floats exact
    (steps' starts and durations, makespan, bound) so the executor's decisions on it are its
    own plan's. A plan that does not parse is dropped by the executor (it plans itself).

    Attributes:
        digest: the problem planned.
        wall_s: the node's wall-clock seconds for it.
        result: what the planner returned (its stats carry only the nodes expanded and
            generated).
    """

    digest: str
    wall_s: float
    result: PlanResult

    def to_dict(self) -> dict[str, Any]:
        r = self.result
        return {
            "id": self.digest,
            "wall": self.wall_s,
            "status": r.status.value,
            "steps": [
                {
                    "start": st.start,
                    "duration": st.duration,
                    "actions": [a.to_dict() for a in st.actions],
                    "bindings": [[b.robot, b.leaf, b.role] for b in st.bindings],
                }
                for st in r.steps
            ],
            "makespan": r.makespan,
            "expanded": r.stats.expanded,
            "generated": r.stats.generated,
            "reason": r.reason,
            "bound": r.lower_bound,
        }

    @classmethod
    def from_dict(cls, d: Any) -> WirePlan:
        """Inverse of :meth:`to_dict`, every field checked.

        Raises:
            BusError: the payload is not a plan (one line saying what is wrong).
        """
        with _malformed("background plan"):
            if not isinstance(d, Mapping):
                raise ValueError(f"expected a JSON object, got {d!r:.40}")
            digest, reason = d["id"], d["reason"]
            if not isinstance(digest, str) or not isinstance(reason, str):
                raise ValueError(f"id and reason must be strings, got {digest!r:.40}")
            try:
                steps = tuple(
                    PlanStep(
                        float(st["start"]),
                        float(st["duration"]),
                        tuple(Action.from_dict(a) for a in st["actions"]),
                        tuple(Binding(str(b[0]), str(b[1]), str(b[2])) for b in st["bindings"]),
                    )
                    for st in d["steps"]
                )
            except (TypeError, IndexError, HltlError) as exc:
                raise ValueError(f"its steps: {exc}") from None
            makespan, bound = d["makespan"], d["bound"]
            result = PlanResult(
                PlanStatus(d["status"]),
                steps,
                None if makespan is None else _number(makespan, "makespan"),
                SearchStats(
                    expanded=_int(d["expanded"], "expanded"),
                    generated=_int(d["generated"], "generated"),
                ),
                reason,
                None if bound is None else _number(bound, "bound"),
            )
            return cls(digest, _number(d["wall"], "wall"), result)


def spec_digest(spec: Mapping[str, Any]) -> str:
    """A spec's name in a background plan's digest: its JSON form (as
    :func:`hltl.spec.hierarchy.spec_to_dict` writes it), keys sorted, hashed; the same on
    the node and the executor's side for the same spec."""
    text = json.dumps(spec, sort_keys=True, separators=(",", ":"))
    return hashlib.blake2b(text.encode("utf-8"), digest_size=16).hexdigest()


@contextmanager
def _malformed(what: str) -> Iterator[None]:
    """A missing key or a bad value read inside is one :class:`BusError` line naming ``what``."""
    try:
        yield
    except KeyError as exc:
        raise BusError(f"malformed {what} on the bus: {exc.args[0]!r} missing") from None
    except ValueError as exc:
        raise BusError(f"malformed {what} on the bus: {exc}") from None


def _planner_from(p: Any) -> tuple[str, float]:
    if not isinstance(p, Mapping):
        raise ValueError(f"planner must be an object, got {p!r:.40}")
    algorithm = p["algorithm"]
    if not isinstance(algorithm, str) or not algorithm:
        raise ValueError(f"planner algorithm must be a name, got {algorithm!r:.40}")
    return algorithm, _number(p["timeout"], "planner timeout", positive=True)


def _check_to(c: WireCheck | None) -> dict[str, Any] | None:
    if c is None:
        return None
    f = c.forecast
    d: dict[str, Any] = {
        "intrusion_speed": c.intrusion_speed,
        "predict_dt": c.predict_dt,
        "forecast": None if f is None else {"window": f[0], "min_speed": f[1]},
    }
    if c.horizon is not None:
        d["horizon"] = c.horizon
    return d


def _check_from(c: Any) -> WireCheck | None:
    if c is None:
        return None
    if not isinstance(c, Mapping):
        raise ValueError(f"check must be an object, got {c!r:.40}")
    f = c.get("forecast")
    if f is not None and not isinstance(f, Mapping):
        raise ValueError(f"forecast must be an object, got {f!r:.40}")
    return WireCheck(
        _number(c["intrusion_speed"], "intrusion_speed"),
        _number(c["predict_dt"], "predict_dt", positive=True),
        None
        if f is None
        else (
            _number(f["window"], "forecast window", positive=True),
            _number(f["min_speed"], "forecast min_speed"),
        ),
        None if c.get("horizon") is None else _number(c["horizon"], "horizon", positive=True),
    )


# -- world states, exact -------------------------------------------------------------------


def world_to_wire(w: WorldState) -> dict[str, Any]:
    """A world state as JSON data, floats unrounded."""
    return {
        "t": w.t,
        "humans": [[h, list(p)] for h, p in w.humans],
        "objects": [[o, list(st.position), st.loc.kind, st.loc.ref] for o, st in w.objects],
        "hands": [[r, list(p)] for r, p in w.hands],
        "unavailable": sorted(w.unavailable),
    }


def _v3(p: Sequence[Any]) -> Vec3:
    if len(p) != 3:
        raise ValueError(f"expected a point [x, y, z], got {p!r:.60}")
    return (float(p[0]), float(p[1]), float(p[2]))


def world_from_wire(d: Mapping[str, Any]) -> WorldState:
    """Inverse of :func:`world_to_wire`."""
    try:
        return WorldState(
            t=float(d["t"]),
            humans=_humans(d["humans"]),
            objects=_objects(d["objects"]),
            hands=_hands(d["hands"]),
            unavailable=frozenset(str(r) for r in d["unavailable"]),
        )
    except (KeyError, TypeError, ValueError) as exc:
        raise BusError(f"malformed world state on the bus: {exc}") from None


def _humans(items: Any) -> tuple[tuple[str, Vec3], ...]:
    return tuple((str(h), _v3(p)) for h, p in items)


def _objects(items: Any) -> tuple[tuple[str, ObjectStatus], ...]:
    return tuple((str(o), ObjectStatus(_v3(p), Loc(kind, str(ref)))) for o, p, kind, ref in items)


def _hands(items: Any) -> tuple[tuple[str, Vec3], ...]:
    return tuple((str(r), _v3(p)) for r, p in items)


def finite_or_none(x: float) -> float | None:
    """JSON has no infinity: ``None`` stands for "never"."""
    return x if math.isfinite(x) else None


# -- ROS 2 message types (CDR) ---------------------------------------------------------------------


class TrajectoryLike(Protocol):
    """What :class:`hltl.motion.trajectory.JointTrajectory` offers (CONTRACTS.md)."""

    @property
    def robot(self) -> str: ...
    @property
    def joint_names(self) -> tuple[str, ...]: ...
    @property
    def times(self) -> tuple[float, ...]: ...
    @property
    def positions(self) -> tuple[tuple[float, ...], ...]: ...
    @property
    def velocities(self) -> tuple[tuple[float, ...], ...] | None: ...


@dataclass(frozen=True, slots=True)
class WireTrajectory:
    """A joint trajectory as it arrives from the bus (the fields of ``JointTrajectory``)."""

    robot: str
    joint_names: tuple[str, ...]
    times: tuple[float, ...]
    positions: tuple[tuple[float, ...], ...]
    velocities: tuple[tuple[float, ...], ...] | None = None


@dataclass(frozen=True, slots=True)
class StampedPose:
    """A ``geometry_msgs/msg/PoseStamped``: a position (and unit quaternion x, y, z, w)."""

    frame_id: str
    t: float
    position: Vec3
    orientation: tuple[float, float, float, float] = (0.0, 0.0, 0.0, 1.0)


@dataclass(frozen=True, slots=True)
class JointStateMsg:
    """A ``sensor_msgs/msg/JointState``."""

    t: float
    names: tuple[str, ...]
    positions: tuple[float, ...]
    velocities: tuple[float, ...] = ()


JOINT_TRAJECTORY = "trajectory_msgs/msg/JointTrajectory"
POSE_STAMPED = "geometry_msgs/msg/PoseStamped"
JOINT_STATE = "sensor_msgs/msg/JointState"


@cache
def typestore() -> Any:
    """rosbags' ROS 2 Humble type store (message definitions shipped with rosbags)."""
    try:
        typesys = importlib.import_module("rosbags.typesys")
    except ImportError:
        raise BackendUnavailableError(
            "ROS 2 message types need rosbags; install the 'bus' extra (pip install 'hltl[bus]')"
        ) from None
    return typesys.get_typestore(typesys.Stores.ROS2_HUMBLE)


def _np() -> Any:
    return importlib.import_module("numpy")


def _stamp(t: float) -> Any:
    ts = typestore()
    sec = math.floor(t)
    return ts.types["builtin_interfaces/msg/Time"](
        sec=int(sec), nanosec=min(999_999_999, round((t - sec) * 1e9))
    )


def _seconds(stamp: Any) -> float:
    return float(stamp.sec) + float(stamp.nanosec) * 1e-9


def _header(frame_id: str, t: float) -> Any:
    return typestore().types["std_msgs/msg/Header"](stamp=_stamp(t), frame_id=frame_id)


def _deserialize(payload: bytes, msgtype: str) -> Any:
    try:
        return typestore().deserialize_cdr(payload, msgtype)
    except Exception as exc:  # rosbags raises plain exceptions of several kinds on bad bytes
        raise BusError(f"malformed {msgtype} on the bus: {exc}") from None


def encode_trajectory(traj: TrajectoryLike, t: float = 0.0) -> bytes:
    """A joint trajectory as CDR ``trajectory_msgs/msg/JointTrajectory``; ``frame_id`` carries
    the robot id and the header stamp the action's start ``t``."""
    ts = typestore()
    np = _np()
    point = ts.types["trajectory_msgs/msg/JointTrajectoryPoint"]
    duration = ts.types["builtin_interfaces/msg/Duration"]
    empty = np.array([], dtype=np.float64)
    points = []
    for i, (ti, q) in enumerate(zip(traj.times, traj.positions, strict=True)):
        sec = math.floor(ti)
        v = traj.velocities[i] if traj.velocities is not None else None
        points.append(
            point(
                positions=np.array(q, dtype=np.float64),
                velocities=empty if v is None else np.array(v, dtype=np.float64),
                accelerations=empty,
                effort=empty,
                time_from_start=duration(
                    sec=int(sec), nanosec=min(999_999_999, round((ti - sec) * 1e9))
                ),
            )
        )
    msg = ts.types[JOINT_TRAJECTORY](
        header=_header(traj.robot, t), joint_names=list(traj.joint_names), points=points
    )
    return bytes(ts.serialize_cdr(msg, JOINT_TRAJECTORY))


def decode_trajectory(payload: bytes) -> WireTrajectory:
    """Inverse of :func:`encode_trajectory` (times to the nanosecond)."""
    msg = _deserialize(payload, JOINT_TRAJECTORY)
    times = tuple(_seconds(p.time_from_start) for p in msg.points)
    positions = tuple(tuple(float(x) for x in p.positions) for p in msg.points)
    has_v = bool(msg.points) and all(len(p.velocities) for p in msg.points)
    velocities = tuple(tuple(float(x) for x in p.velocities) for p in msg.points) if has_v else None
    return WireTrajectory(
        str(msg.header.frame_id), tuple(msg.joint_names), times, positions, velocities
    )


def encode_pose(pose: StampedPose) -> bytes:
    ts = typestore()
    g = ts.types
    x, y, z = pose.position
    qx, qy, qz, qw = pose.orientation
    msg = g[POSE_STAMPED](
        header=_header(pose.frame_id, pose.t),
        pose=g["geometry_msgs/msg/Pose"](
            position=g["geometry_msgs/msg/Point"](x=x, y=y, z=z),
            orientation=g["geometry_msgs/msg/Quaternion"](x=qx, y=qy, z=qz, w=qw),
        ),
    )
    return bytes(ts.serialize_cdr(msg, POSE_STAMPED))


def decode_pose(payload: bytes) -> StampedPose:
    msg = _deserialize(payload, POSE_STAMPED)
    p, q = msg.pose.position, msg.pose.orientation
    return StampedPose(
        str(msg.header.frame_id),
        _seconds(msg.header.stamp),
        (float(p.x), float(p.y), float(p.z)),
        (float(q.x), float(q.y), float(q.z), float(q.w)),
    )


def encode_joint_state(js: JointStateMsg) -> bytes:
    ts = typestore()
    np = _np()
    msg = ts.types[JOINT_STATE](
        header=_header("", js.t),
        name=list(js.names),
        position=np.array(js.positions, dtype=np.float64),
        velocity=np.array(js.velocities, dtype=np.float64),
        effort=np.array([], dtype=np.float64),
    )
    return bytes(ts.serialize_cdr(msg, JOINT_STATE))


def decode_joint_state(payload: bytes) -> JointStateMsg:
    msg = _deserialize(payload, JOINT_STATE)
    return JointStateMsg(
        _seconds(msg.header.stamp),
        tuple(msg.name),
        tuple(float(x) for x in msg.position),
        tuple(float(x) for x in msg.velocity),
    )
