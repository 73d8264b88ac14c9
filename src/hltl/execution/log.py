"""The execution log (DESIGN.md §3): JSON Lines, one time-stamped event a line."""

from __future__ import annotations

import json
import math
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import MISSING, dataclass, field, fields, replace
from pathlib import Path
from typing import IO, Any, ClassVar, TypeVar, dataclass_transform

from hltl.errors import PlanFormatError
from hltl.fileio import MAX_LOG_BYTES, load_data, open_output, read_text
from hltl.spec.monitor import HierarchyMonitor, MonitorState
from hltl.spec.syntax import Atom
from hltl.world.state import Loc, ObjectStatus, WorldState

JsonObject = dict[str, Any]

_KEYS = {"from_": "from"}  # field names that are Python keywords


_T = TypeVar("_T")


@dataclass_transform(frozen_default=True, kw_only_default=True)
def record(cls: type[_T]) -> type[_T]:
    """A log record class: a frozen, slotted dataclass whose fields are given by keyword."""
    return dataclass(frozen=True, slots=True, kw_only=True)(cls)


@record
class LogRecord:
    """One line of the log: a time stamp and, per subclass, the fields of one kind of record.

    Fields are written in declaration order after ``t`` and ``type`` (the JSON Lines format is a
    contract: DESIGN.md §3); a field named in ``OPTIONAL`` is left out of the line when it is
    ``None``. Loading fills a missing field with its default; fields without one are required.
    """

    TYPE: ClassVar[str] = ""
    OPTIONAL: ClassVar[frozenset[str]] = frozenset()
    t: float

    @property
    def type(self) -> str:
        return self.TYPE

    def to_json(self) -> JsonObject:
        """The record as the JSON object of its log line."""
        out: JsonObject = {"t": self.t, "type": self.TYPE}
        for name in _field_names(type(self)):
            v = getattr(self, name)
            if v is None and name in self.OPTIONAL:
                continue
            out[_KEYS.get(name, name)] = v
        return out

    @staticmethod
    def from_json(data: Any, where: str = "<log>") -> LogRecord:
        """The record of one parsed log line.

        Raises:
            PlanFormatError: not an object, ``t`` not a finite number, an unknown ``type`` or a
                required field missing.
        """
        if not isinstance(data, dict):
            raise PlanFormatError(f"{where}: expected a JSON object, got {type(data).__name__}")
        t = data.get("t")
        if not isinstance(t, int | float) or isinstance(t, bool) or not math.isfinite(t):
            raise PlanFormatError(f"{where}: field 't' must be a finite number, got {t!r}")
        kind = data.get("type")
        cls = RECORD_CLASSES.get(kind) if isinstance(kind, str) else None
        if cls is None:
            raise PlanFormatError(
                f"{where}: unknown record type {kind!r}; "
                f"expected one of {', '.join(sorted(RECORD_TYPES))}"
            )
        if cls is Replan and "queries" in data:
            cls = PolicyReplan
        kwargs: dict[str, Any] = {"t": t}
        for f in fields(cls):
            key = _KEYS.get(f.name, f.name)
            if key in data:
                kwargs[f.name] = data[key]
            elif f.name != "t" and f.default is MISSING and f.default_factory is MISSING:
                raise PlanFormatError(f"{where}: a {kind} record needs the field {key!r}")
        return cls(**kwargs)


_FIELD_NAMES: dict[type[LogRecord], tuple[str, ...]] = {}


def _field_names(cls: type[LogRecord]) -> tuple[str, ...]:
    names = _FIELD_NAMES.get(cls)
    if names is None:
        names = _FIELD_NAMES[cls] = tuple(f.name for f in fields(cls) if f.name != "t")
    return names


@record
class EpisodeStart(LogRecord):
    """Everything needed to re-run or re-score the episode.

    ``kinematics`` names the reach the agent checked preconditions with when it is not the
    reach spheres (``maps``: the scene's arms' reachability maps); absent means spheres.
    """

    TYPE: ClassVar[str] = "episode_start"
    OPTIONAL: ClassVar[frozenset[str]] = frozenset({"kinematics"})
    scene: JsonObject = field(default_factory=dict)
    scene_source: str | None = None
    spec: JsonObject | None = None
    instruction: str | None = None
    events: list[Any] = field(default_factory=list)
    seed: int = 0
    config: JsonObject = field(default_factory=dict)
    kinematics: str | None = None


@record
class EpisodeEnd(LogRecord):
    TYPE: ClassVar[str] = "episode_end"
    success: bool
    reason: str = ""
    time_cost: float | None = None
    done: list[str] = field(default_factory=list)


@record
class Grounding(LogRecord):
    """An instruction grounded (``spec`` set) or refused (``error`` set)."""

    TYPE: ClassVar[str] = "grounding"
    OPTIONAL: ClassVar[frozenset[str]] = frozenset(
        {
            "error",
            "prompt_tokens",
            "completion_tokens",
            "latency_ms",
            "spec",
            "done",
            "update",
            "referee",
            "charged_s",
        }
    )
    text: str
    error: str | None = None
    tokens: int = 0
    prompt_tokens: int | None = None
    completion_tokens: int | None = None
    latency_ms: float | None = None
    spec: JsonObject | None = None
    done: list[str] | None = None
    update: JsonObject | None = None
    referee: bool | None = None  # the baselines' free grounding of what the referee checks
    charged_s: float | None = None  # simulated seconds grounding was charged (latency models)


@record
class Replan(LogRecord):
    """A planner call (``source`` planner) or a predicted plan taking over (``predicted``)."""

    TYPE: ClassVar[str] = "replan"
    OPTIONAL: ClassVar[frozenset[str]] = frozenset({"reason", "charged_s", "charge", "motion_s"})
    source: str = "planner"
    status: str = ""
    latency_ms: float = 0.0
    expanded: int = 0
    makespan: float | None = None
    steps: list[Any] = field(default_factory=list)
    reason: str | None = None
    world: JsonObject = field(default_factory=dict)
    charged_s: float | None = None  # simulated seconds of computation charged (latency models)
    charge: str | None = None  # how: constant, measured, model, background
    trigger: str = ""
    tokens: int = 0
    context: str = ""
    done: list[str] = field(default_factory=list)
    # measured motion planning of the first step, part of charged_s (a MotionTimer ran)
    motion_s: float | None = None


@record
class PolicyReplan(LogRecord):
    """A baseline policy's answer (a ``replan`` record with ``queries``)."""

    TYPE: ClassVar[str] = "replan"
    OPTIONAL: ClassVar[frozenset[str]] = frozenset({"script"})
    source: str
    trigger: str = ""
    status: str = ""
    latency_ms: float = 0.0
    tokens: int = 0
    queries: int = 0
    steps: list[Any] = field(default_factory=list)
    planned_feasible: list[Any] = field(default_factory=list)
    reason: str = ""
    world: JsonObject = field(default_factory=dict)
    done: list[str] = field(default_factory=list)
    script: str | None = None


@record
class Predict(LogRecord):
    TYPE: ClassVar[str] = "predict"
    basis: str = "now"
    humans: JsonObject = field(default_factory=dict)
    context: str = ""
    status: str = ""
    latency_ms: float = 0.0
    expanded: int = 0
    makespan: float | None = None


@record
class Takeover(LogRecord):
    TYPE: ClassVar[str] = "takeover"
    trigger: str = ""
    context: str = ""
    predicted_at: float | None = None
    makespan: float | None = None


@record
class Anticipate(LogRecord):
    """Anticipatory execution: the forecast world's first step dispatched because it is
    executable now (``differs``: it is not the current plan's first step)."""

    TYPE: ClassVar[str] = "anticipate"
    context: str = ""
    predicted_at: float | None = None
    actions: list[JsonObject] = field(default_factory=list)
    differs: bool = False
    humans: JsonObject = field(default_factory=dict)


@record
class Dispatch(LogRecord):
    TYPE: ClassVar[str] = "dispatch"
    step: int
    actions: list[JsonObject]
    planned: list[JsonObject] = field(default_factory=list)
    duration: float = 0.0
    world: JsonObject = field(default_factory=dict)
    done: list[str] = field(default_factory=list)


@record
class ActionRecord(LogRecord):
    """A record about one action a driver runs: its handle and the action's JSON."""

    handle: int
    action: JsonObject


class _Ends:
    """``ended``: when the action ended, per the driver's ``end`` (absent: at ``t``)."""

    __slots__ = ()
    t: float
    end: float | None

    @property
    def ended(self) -> float:
        return float(self.t if self.end is None else self.end)


@record
class ActionStart(ActionRecord):
    TYPE: ClassVar[str] = "action_start"
    robots: list[str] = field(default_factory=list)
    expected: float | None = None  # seconds the action should take


@record
class ActionDone(_Ends, ActionRecord):
    TYPE: ClassVar[str] = "action_done"
    end: float | None = None


@record
class ActionFailed(_Ends, ActionRecord):
    TYPE: ClassVar[str] = "action_failed"
    reason: str = ""
    end: float | None = None


@record
class ActionHalted(_Ends, ActionRecord):
    TYPE: ClassVar[str] = "action_halted"
    OPTIONAL: ClassVar[frozenset[str]] = frozenset({"end"})
    reason: str = ""
    end: float | None = None


ActionEnded = ActionDone | ActionFailed | ActionHalted


@record
class Halt(LogRecord):
    TYPE: ClassVar[str] = "halt"
    kind: str
    reason: str = ""
    actions: list[JsonObject] = field(default_factory=list)
    hazards: list[JsonObject] = field(default_factory=list)
    done: list[str] = field(default_factory=list)


@record
class Monitor(LogRecord):
    TYPE: ClassVar[str] = "monitor"
    step: int
    atoms: list[str] = field(default_factory=list)
    fired: list[str] = field(default_factory=list)
    done: list[str] = field(default_factory=list)
    accepted: bool = False


@record
class Wait(LogRecord):
    TYPE: ClassVar[str] = "wait"
    reason: str = ""


@record
class GiveUp(LogRecord):
    TYPE: ClassVar[str] = "give_up"
    reason: str = ""
    done: list[str] = field(default_factory=list)


@record
class HumanMove(LogRecord):
    """A person starts walking to ``to`` (through ``wander``'s points on a random walk)."""

    TYPE: ClassVar[str] = "human_move"
    OPTIONAL: ClassVar[frozenset[str]] = frozenset({"wander"})
    human: str
    from_: list[float] | None = None
    to: list[float]
    speed: float | None = None
    eta: float | None = None  # arrival (absent in old logs: until the next walk)
    wander: list[list[float]] | None = None


@record
class HumanStop(LogRecord):
    TYPE: ClassVar[str] = "human_stop"
    human: str
    position: list[float]


@record
class ObjectMove(LogRecord):
    """An object moved by someone else (``applied`` false: it was not resting, ``reason``)."""

    TYPE: ClassVar[str] = "object_move"
    OPTIONAL: ClassVar[frozenset[str]] = frozenset({"from_", "reason"})
    object: str
    from_: list[float] | None = None
    to: list[float]
    applied: bool = True
    reason: str | None = None


@record
class ObjectDrop(LogRecord):
    TYPE: ClassVar[str] = "object_drop"
    object: str
    position: list[float]
    cause: str = ""


@record
class RobotDown(LogRecord):
    TYPE: ClassVar[str] = "robot_down"
    OPTIONAL: ClassVar[frozenset[str]] = frozenset({"reason"})
    robot: str
    until: float | None = None  # None: for good (a lost bus link)
    reason: str | None = None


@record
class RobotUp(LogRecord):
    TYPE: ClassVar[str] = "robot_up"
    robot: str


@record
class InstructionGiven(LogRecord):
    TYPE: ClassVar[str] = "instruction"
    text: str


@record
class Violation(LogRecord):
    """An unsafe action: caught by the simulator while running, or by the baselines' referee
    before dispatch (``kind``, ``caught``, ``world`` set)."""

    TYPE: ClassVar[str] = "violation"
    OPTIONAL: ClassVar[frozenset[str]] = frozenset({"kind", "caught", "world"})
    handle: int | None = None
    action: JsonObject | None = None
    reason: str = ""
    kind: str | None = None
    caught: str | None = None
    world: JsonObject | None = None


@record
class Contact(LogRecord):
    """3D simulator only: a robot's collision geometry starts touching a person."""

    TYPE: ClassVar[str] = "contact"
    robot: str
    human: str
    position: list[float]
    depth: float = 0.0
    part: str = ""


@record
class Perception(LogRecord):
    TYPE: ClassVar[str] = "perception"
    latency_ms: float = 0.0
    people: JsonObject = field(default_factory=dict)
    missing: list[str] = field(default_factory=list)
    lost: list[str] = field(default_factory=list)
    ambiguous: list[str] = field(default_factory=list)


# Every record type the executor and the simulator write; readers reject anything else.
RECORD_CLASSES: dict[str, type[LogRecord]] = {
    c.TYPE: c
    for c in (
        EpisodeStart,
        EpisodeEnd,
        Grounding,
        Replan,
        Predict,
        Takeover,
        Anticipate,
        Dispatch,
        ActionStart,
        ActionDone,
        ActionFailed,
        ActionHalted,
        Halt,
        Monitor,
        Wait,
        GiveUp,
        HumanMove,
        HumanStop,
        ObjectMove,
        ObjectDrop,
        RobotDown,
        RobotUp,
        InstructionGiven,
        Violation,
        Contact,
        Perception,
    )
}
RECORD_TYPES = frozenset(RECORD_CLASSES)
REPLANS = (Replan, PolicyReplan)
HANDLED = (ActionStart, ActionDone, ActionFailed, ActionHalted, Violation)  # records with a handle

R = TypeVar("R", bound=LogRecord)


def records_of(records: Iterable[LogRecord], cls: type[R]) -> list[R]:
    """The records of one class, in order."""
    return [r for r in records if isinstance(r, cls)]


def _r(x: float) -> float:
    return round(float(x), 6)


def vec(p: Sequence[float]) -> list[float]:
    """A point as a JSON list, rounded to the micrometre."""
    return [_r(v) for v in p]


class EventLog:
    """Collects records in memory and, optionally, streams them to a JSON Lines file.

    Args:
        path: file to write (truncated when the log opens); ``None`` keeps records in memory.
        on_record: called with every record as it is emitted (live timelines).
    """

    def __init__(
        self,
        path: str | Path | None = None,
        on_record: Callable[[LogRecord], None] | None = None,
    ) -> None:
        self.records: list[LogRecord] = []
        self._on_record = on_record
        self._file: IO[str] | None = None
        if path is not None:
            self._file = open_output(path, "the log")  # closed in close()

    def emit(self, rec: R) -> R:
        """Append a record (its time rounded to the microsecond) and return it."""
        if type(rec.t) is not float or rec.t != _r(rec.t):
            rec = replace(rec, t=_r(rec.t))
        self.records.append(rec)
        if self._file is not None:
            self._file.write(json.dumps(rec.to_json(), separators=(",", ":")) + "\n")
            self._file.flush()
        if self._on_record is not None:
            self._on_record(rec)
        return rec

    def close(self) -> None:
        if self._file is not None:
            self._file.close()
            self._file = None

    def __enter__(self) -> EventLog:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()


def log_monitor_step(
    log: EventLog,
    t: float,
    step: int,
    monitor: HierarchyMonitor,
    q: MonitorState,
    symbol: frozenset[Atom],
) -> MonitorState:
    """Step the monitors on a completed step's symbol and record it; returns the new state."""
    q1 = monitor.step(q, symbol)
    log.emit(
        Monitor(
            t=t,
            step=step,
            atoms=sorted(str(a) for a in symbol),
            fired=sorted(monitor.fired(q, q1)),
            done=sorted(monitor.done(q1)),
            accepted=monitor.accepted(q1),
        )
    )
    return q1


def read_log(path: str | Path) -> list[LogRecord]:
    """Read a JSON Lines execution log.

    Raises:
        PlanFormatError: the file cannot be read, a line is not a record (a JSON object with a
            finite ``t``, a known ``type`` and that type's required fields), or the log does not
            start with ``episode_start``.
    """
    p = Path(path)
    return parse_log(read_text(p, "log", PlanFormatError, MAX_LOG_BYTES), str(p))


def parse_log(text: str, source: str = "<log>") -> list[LogRecord]:
    """The records of a log's text (see :func:`read_log`)."""
    records: list[LogRecord] = []
    for i, line in enumerate(text.splitlines(), 1):
        if not line.strip():
            continue
        data = load_data(line, f"{source}:{i}", PlanFormatError, as_json=True)
        records.append(LogRecord.from_json(data, f"{source}:{i}"))
    check_records(records, source)
    return records


def parse_records(data: Iterable[Any], source: str = "<log>") -> list[LogRecord]:
    """Records from parsed JSON objects (one per line), checked as a whole log."""
    records = [LogRecord.from_json(d, f"{source}:{i}") for i, d in enumerate(data, 1)]
    check_records(records, source)
    return records


def check_records(records: Sequence[LogRecord], source: str = "<log>") -> None:
    """A whole log: non-empty, starting with ``episode_start``, times never going back."""
    if not records:
        raise PlanFormatError(f"{source}: the log is empty")
    if not isinstance(records[0], EpisodeStart):
        raise PlanFormatError(
            f"{source}: the first record is {records[0].type!r}; expected 'episode_start'"
        )
    last = -math.inf
    for i, rec in enumerate(records, 1):
        if rec.t < last - 1e-9:
            raise PlanFormatError(
                f"{source}: record {i} ({rec.type}) at t={rec.t} is earlier than the "
                f"record before it (t={last})"
            )
        last = rec.t


# -- world states in records ---------------------------------------------------------------------


def world_to_dict(w: WorldState) -> dict[str, Any]:
    """A world state as JSON data (positions rounded to the micrometre)."""
    return {
        "t": _r(w.t),
        "humans": {h: vec(p) for h, p in w.humans},
        "objects": {o: {"position": vec(st.position), "loc": str(st.loc)} for o, st in w.objects},
        "hands": {r: vec(p) for r, p in w.hands},
        "unavailable": sorted(w.unavailable),
    }


def _loc(text: str) -> Loc:
    kind, _, ref = text.partition(":")
    if kind not in ("rest", "held", "on", "delivered"):
        raise PlanFormatError(
            f"unknown object place {text!r}; expected rest, held:, on:, delivered:"
        )
    return Loc(kind, ref)  # type: ignore[arg-type]


def _v3(p: Any, where: str) -> tuple[float, float, float]:
    if not isinstance(p, list | tuple) or len(p) != 3:
        raise PlanFormatError(f"{where}: expected a point [x, y, z], got {p!r}")
    return (float(p[0]), float(p[1]), float(p[2]))


def world_from_dict(data: Mapping[str, Any]) -> WorldState:
    """Inverse of :func:`world_to_dict`."""
    try:
        return WorldState(
            t=float(data["t"]),
            humans=tuple(sorted((h, _v3(p, h)) for h, p in data["humans"].items())),
            objects=tuple(
                sorted(
                    (o, ObjectStatus(_v3(st["position"], o), _loc(str(st["loc"]))))
                    for o, st in data["objects"].items()
                )
            ),
            hands=tuple(sorted((r, _v3(p, r)) for r, p in data.get("hands", {}).items())),
            unavailable=frozenset(str(r) for r in data.get("unavailable", ())),
        )
    except (KeyError, TypeError, AttributeError, ValueError) as exc:
        raise PlanFormatError(f"malformed world state in log: {exc!r}") from None
