"""The execution log (DESIGN.md §3): JSON Lines, one time-stamped event a line.

Records are plain dicts ``{"t": <seconds>, "type": <kind>, ...}`` so that a log can be written,
read back and re-scored without any hltl object; docs/execution.md lists every kind and field.
"""

from __future__ import annotations

import json
import math
from collections.abc import Callable, Iterable, Mapping, Sequence
from pathlib import Path
from typing import IO, Any

from hltl.errors import PlanFormatError
from hltl.fileio import MAX_LOG_BYTES, load_data, open_output, read_text
from hltl.spec.monitor import HierarchyMonitor, MonitorState
from hltl.spec.syntax import Atom
from hltl.world.state import Loc, ObjectStatus, WorldState

Record = dict[str, Any]

# Every record type the executor and the simulator write; readers reject anything else.
RECORD_TYPES = frozenset(
    {
        "episode_start",
        "episode_end",
        "grounding",
        "replan",
        "predict",
        "takeover",
        "anticipate",
        "dispatch",
        "action_start",
        "action_done",
        "action_failed",
        "action_halted",
        "halt",
        "monitor",
        "wait",
        "give_up",
        "human_move",
        "human_stop",
        "object_move",
        "object_drop",
        "robot_down",
        "robot_up",
        "instruction",
        "violation",
        "contact",
        "perception",
    }
)


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
        on_record: Callable[[Record], None] | None = None,
    ) -> None:
        self.records: list[Record] = []
        self._on_record = on_record
        self._file: IO[str] | None = None
        if path is not None:
            self._file = open_output(path, "the log")  # closed in close()

    def emit(self, t: float, type: str, **fields: Any) -> Record:
        """Append a record of kind ``type`` at time ``t`` and return it."""
        if type not in RECORD_TYPES:
            raise ValueError(f"unknown log record type {type!r}")
        rec: Record = {"t": _r(t), "type": type, **fields}
        self.records.append(rec)
        if self._file is not None:
            self._file.write(json.dumps(rec, separators=(",", ":")) + "\n")
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
        t,
        "monitor",
        step=step,
        atoms=sorted(str(a) for a in symbol),
        fired=sorted(monitor.fired(q, q1)),
        done=sorted(monitor.done(q1)),
        accepted=monitor.accepted(q1),
    )
    return q1


def read_log(path: str | Path) -> list[Record]:
    """Read a JSON Lines execution log.

    Raises:
        PlanFormatError: the file cannot be read, a line is not a JSON object with a finite
            ``t`` and a known ``type``, or the log does not start with ``episode_start``.
    """
    p = Path(path)
    lines = read_text(p, "log", PlanFormatError, MAX_LOG_BYTES).splitlines()
    records: list[Record] = []
    for i, line in enumerate(lines, 1):
        if not line.strip():
            continue
        rec = load_data(line, f"{p}:{i}", PlanFormatError, as_json=True)
        records.append(check_record(rec, f"{p}:{i}"))
    check_records(records, str(p))
    return records


def check_record(rec: Any, where: str) -> Record:
    """One record's shape: a mapping with a finite number ``t`` and a known ``type``."""
    if not isinstance(rec, dict):
        raise PlanFormatError(f"{where}: expected a JSON object, got {type(rec).__name__}")
    t = rec.get("t")
    if not isinstance(t, int | float) or isinstance(t, bool) or not math.isfinite(t):
        raise PlanFormatError(f"{where}: field 't' must be a finite number, got {t!r}")
    kind = rec.get("type")
    if kind not in RECORD_TYPES:
        raise PlanFormatError(
            f"{where}: unknown record type {kind!r}; "
            f"expected one of {', '.join(sorted(RECORD_TYPES))}"
        )
    return rec


def check_records(records: Sequence[Mapping[str, Any]], source: str = "<log>") -> None:
    """A whole log: non-empty, starting with ``episode_start``, times never going back."""
    if not records:
        raise PlanFormatError(f"{source}: the log is empty")
    if records[0].get("type") != "episode_start":
        raise PlanFormatError(
            f"{source}: the first record is {records[0].get('type')!r}; expected 'episode_start'"
        )
    last = -math.inf
    for i, rec in enumerate(records, 1):
        if rec["t"] < last - 1e-9:
            raise PlanFormatError(
                f"{source}: record {i} ({rec['type']}) at t={rec['t']} is earlier than the "
                f"record before it (t={last})"
            )
        last = rec["t"]


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


def records_of(records: Iterable[Mapping[str, Any]], *types: str) -> list[Mapping[str, Any]]:
    """The records of the given kinds, in order."""
    wanted = set(types)
    return [r for r in records if r.get("type") in wanted]
