"""Dynamic events (DESIGN.md §3): load and validate the events YAML that ``hltl run`` injects."""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Literal, TypeAlias

from hltl.errors import EventsError
from hltl.fileio import clip, load_file, quote
from hltl.grounding.base import MAX_INSTRUCTION_CHARS
from hltl.world.scene import Scene, Vec3

SKILLS = ("pick", "place", "handover_r2r", "handover_r2h")
Outcome = Literal["stay", "drop"]
DEFAULT_WALK_SPEED = 1.0  # m/s, a comfortable walking pace
# What an events file may ask for: far beyond any episode (the default time limit is 120 s), and
# small enough that no file can make the simulator hang or fill memory.
MAX_EVENTS = 10_000
MAX_SECONDS = 1e6  # times and durations (about 11.6 days)
MAX_SPEED = 10.0  # m/s; people walk at 1-2
MIN_LEG = 0.01  # s, a wander's shortest leg


@dataclass(frozen=True, slots=True)
class HumanMove:
    """H-MOVE: from time ``t`` the person walks straight to ``to`` at ``speed`` m/s."""

    t: float
    human: str
    to: Vec3
    speed: float = DEFAULT_WALK_SPEED
    type: str = "human_move"


@dataclass(frozen=True, slots=True)
class HumanWander:
    """From ``t`` for ``duration`` s the person walks in random directions at ``speed``, changing
    heading every ``leg`` s (headings drawn from the episode's seed), staying inside the cell."""

    t: float
    human: str
    duration: float
    speed: float = DEFAULT_WALK_SPEED
    leg: float = 1.0
    type: str = "human_wander"


@dataclass(frozen=True, slots=True)
class ObjectMove:
    """O-MOVE: at ``t`` a person moves the (resting) object to ``to``."""

    t: float
    object: str
    to: Vec3
    type: str = "object_move"


@dataclass(frozen=True, slots=True)
class Instruction:
    """GOAL: at ``t`` somebody says ``text`` (a new or changed instruction)."""

    t: float
    text: str
    type: str = "instruction"


@dataclass(frozen=True, slots=True)
class RobotDown:
    """RES: robot ``robot`` is unavailable from ``t`` for ``duration`` s."""

    t: float
    robot: str
    duration: float
    type: str = "robot_down"


@dataclass(frozen=True, slots=True)
class SkillFailure:
    """FAIL: every instance of ``skill`` fails with ``probability``; the object then stays where it
    was (``stay``) or drops to the table below the hand (``drop``)."""

    skill: str
    probability: float
    outcome: Outcome = "stay"
    type: str = "skill_failure"


TimedEvent: TypeAlias = HumanMove | HumanWander | ObjectMove | Instruction | RobotDown


@dataclass(frozen=True, slots=True)
class EventSchedule:
    """All events of an episode: the timed ones by time (stable), and the failure models."""

    timed: tuple[TimedEvent, ...] = ()
    failures: tuple[SkillFailure, ...] = ()
    source: str = "<events>"

    def failure_of(self, skill: str) -> SkillFailure | None:
        for f in self.failures:
            if f.skill == skill:
                return f
        return None

    @property
    def instructions(self) -> tuple[Instruction, ...]:
        return tuple(e for e in self.timed if isinstance(e, Instruction))

    def to_list(self) -> list[dict[str, Any]]:
        """The events in their file format (what ``episode_start`` records)."""
        out: list[dict[str, Any]] = []
        for e in (*self.timed, *self.failures):
            d: dict[str, Any] = {"type": e.type}
            for k in e.__slots__:
                if k == "type":
                    continue
                v = getattr(e, k)
                d[k] = list(v) if isinstance(v, tuple) else v
            out.append(d)
        return out


_FIELDS: dict[str, tuple[tuple[str, ...], tuple[str, ...]]] = {
    # type: (required fields, optional fields)
    "human_move": (("t", "human", "to"), ("speed",)),
    "human_wander": (("t", "human", "duration"), ("speed", "leg")),
    "object_move": (("t", "object", "to"), ()),
    "instruction": (("t", "text"), ()),
    "robot_down": (("t", "robot", "duration"), ()),
    "skill_failure": (("skill", "probability"), ("outcome",)),
}


class _Checker:
    def __init__(self, source: str, index: int, event: Mapping[str, Any]) -> None:
        self.source = source
        self.index = index
        self.event = event

    def fail(self, field: str, problem: str) -> EventsError:
        value = self.event.get(field)
        return EventsError(
            f"{self.source}: events[{self.index}].{field}: {problem} (value {quote(value)})"
        )

    def number(
        self, field: str, *, low: float = 0.0, strict: bool = False, high: float = MAX_SECONDS
    ) -> float:
        v = self.event[field]
        if isinstance(v, bool) or not isinstance(v, int | float) or not math.isfinite(v):
            raise self.fail(field, "expected a finite number")
        if v < low or (strict and v == low):
            raise self.fail(field, f"must be {'>' if strict else '>='} {low:g}")
        if v > high:
            raise self.fail(field, f"must be <= {high:g}")
        return float(v)

    def optional(
        self, field: str, default: float, *, low: float = 0.0, high: float = MAX_SECONDS
    ) -> float:
        if field not in self.event:
            return default
        return self.number(field, low=low, strict=low == 0.0, high=high)

    def point(self, field: str) -> Vec3:
        v = self.event[field]
        if (
            not isinstance(v, list | tuple)
            or len(v) != 3
            or not all(
                isinstance(x, int | float) and not isinstance(x, bool) and math.isfinite(x)
                for x in v
            )
        ):
            raise self.fail(field, "expected a point [x, y, z] of finite numbers")
        return (float(v[0]), float(v[1]), float(v[2]))

    def ident(self, field: str, known: Sequence[str], kind: str) -> str:
        v = self.event[field]
        if not isinstance(v, str) or v not in known:
            raise self.fail(field, f"unknown {kind}; the scene has: {', '.join(known) or 'none'}")
        return v


def events_from_dict(data: Any, scene: Scene, source: str = "<events>") -> EventSchedule:
    """Validate events given as parsed YAML/JSON against ``scene``.

    Raises:
        EventsError: naming ``source``, the event index, the field and the value.
    """
    if data is None:
        return EventSchedule(source=source)
    if not isinstance(data, Mapping):
        raise EventsError(
            f"{source}: expected a mapping with an 'events' list, got {type(data).__name__}"
        )
    extra = sorted(str(k) for k in data if k != "events")
    if extra:
        raise EventsError(f"{source}: unknown top-level field {quote(extra[0])}; expected 'events'")
    items = data.get("events") or []
    if not isinstance(items, list):
        raise EventsError(f"{source}: events: expected a list, got {type(items).__name__}")
    if len(items) > MAX_EVENTS:
        raise EventsError(f"{source}: events: {len(items):,} events; at most {MAX_EVENTS:,}")
    timed: list[TimedEvent] = []
    failures: list[SkillFailure] = []
    for i, ev in enumerate(items):
        if not isinstance(ev, Mapping):
            raise EventsError(f"{source}: events[{i}]: expected a mapping, got {quote(ev)}")
        kind = ev.get("type")
        if not isinstance(kind, str) or kind not in _FIELDS:
            raise EventsError(
                f"{source}: events[{i}].type: unknown event type (value {quote(kind)}); "
                f"expected one of {', '.join(_FIELDS)}"
            )
        required, optional = _FIELDS[kind]
        for f in required:
            if f not in ev:
                raise EventsError(f"{source}: events[{i}].{f}: required field is missing")
        for f in ev:
            if f != "type" and f not in required and f not in optional:
                raise EventsError(
                    f"{source}: events[{i}].{clip(str(f), 40)}: unknown field for {kind} "
                    f"(value {quote(ev[f])}); "
                    f"expected {', '.join(required + optional)}"
                )
        c = _Checker(source, i, ev)
        if kind == "human_move":
            timed.append(
                HumanMove(
                    c.number("t"),
                    c.ident("human", scene.human_ids, "human"),
                    c.point("to"),
                    c.optional("speed", DEFAULT_WALK_SPEED, high=MAX_SPEED),
                )
            )
        elif kind == "human_wander":
            timed.append(
                HumanWander(
                    c.number("t"),
                    c.ident("human", scene.human_ids, "human"),
                    c.number("duration", strict=True),
                    c.optional("speed", DEFAULT_WALK_SPEED, high=MAX_SPEED),
                    c.optional("leg", 1.0, low=MIN_LEG),
                )
            )
        elif kind == "object_move":
            timed.append(
                ObjectMove(
                    c.number("t"), c.ident("object", scene.object_ids, "object"), c.point("to")
                )
            )
        elif kind == "instruction":
            text = ev["text"]
            if not isinstance(text, str) or not text.strip():
                raise c.fail("text", "expected a non-empty instruction")
            if len(text) > MAX_INSTRUCTION_CHARS:
                raise c.fail(
                    "text", f"an instruction has at most {MAX_INSTRUCTION_CHARS:,} characters"
                )
            timed.append(Instruction(c.number("t"), text))
        elif kind == "robot_down":
            timed.append(
                RobotDown(
                    c.number("t"),
                    c.ident("robot", scene.robot_ids, "robot"),
                    c.number("duration", strict=True),
                )
            )
        else:
            skill = c.ident("skill", SKILLS, "skill")
            p = c.number("probability")
            if p > 1.0:
                raise c.fail("probability", "must be <= 1")
            outcome = ev.get("outcome", "stay")
            if outcome not in ("stay", "drop"):
                raise c.fail("outcome", "expected 'stay' or 'drop'")
            if any(f.skill == skill for f in failures):
                raise c.fail("skill", "a failure model for this skill is already given")
            failures.append(SkillFailure(skill, p, outcome))
    timed.sort(key=lambda e: e.t)  # stable: simultaneous events keep their file order
    return EventSchedule(tuple(timed), tuple(failures), source)


def load_events(path: str | Path, scene: Scene) -> EventSchedule:
    """Load and validate an events file (YAML, or JSON by extension)."""
    p = Path(path)
    return events_from_dict(load_file(p, "events file", EventsError), scene, str(p))
