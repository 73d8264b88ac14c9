"""Ticks simulated ahead of the executor, as a step answer carries them: one binary block."""

from __future__ import annotations

import json
import math
import struct
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

from hltl.bus.codec import Report, dumps, loads
from hltl.errors import BusError, HltlError
from hltl.execution.drivers import ActionState, ActionStatus
from hltl.skills.library import Action
from hltl.world.scene import Vec3
from hltl.world.state import Loc, ObjectStatus, WorldState

MAGIC = b"HLT1"
PENDING, EXTRA, LAYOUT, GUESS = 1, 2, 4, 8
STATES = (ActionState.RUNNING, ActionState.DONE, ActionState.FAILED, ActionState.HALTED)
_STATE_INDEX = {s: i for i, s in enumerate(STATES)}
_U32 = struct.Struct("<I")
_HEAD = struct.Struct("<ddIBB")
_REPORT = struct.Struct("<IIBdd")
_EMPTY: dict[str, Any] = {}


@dataclass(frozen=True, slots=True)
class Tick:
    """One tick of the loop on the cell: what the executor reads from it."""

    t: float
    world: WorldState
    reports: tuple[Report, ...] = ()
    next: float | None = None  # the cell's next event time (None: never)
    pending: bool = False
    count: int = 0  # reports the node has published so far
    unavailable: tuple[str, ...] = ()  # the robots unavailable now (the cell's clock)
    instructions: tuple[str, ...] = ()
    records: tuple[dict[str, Any], ...] = ()
    # not a tick: the executor's expected next step, started by the node at ``t`` (the tick
    # before's time) on a guess; ``reports`` acknowledge its starts, the clock is after them
    guess: bool = False
    # a guessed step's starts: (command number, handle, action) each, in order
    starts: tuple[tuple[int, int, Action], ...] = ()


def encode_answer(answer: dict[str, Any], ticks: Sequence[Tick] = ()) -> bytes:
    """A step answer: JSON, followed by its ticks ahead as a binary block when there are any."""
    head = dumps(answer)
    if not ticks:
        return head
    return b"".join((MAGIC, _U32.pack(len(head)), head, encode_ticks(ticks)))


def decode_answer(
    payload: bytes, what: str, episode: str = ""
) -> tuple[dict[str, Any], TickReader | None]:
    """Inverse of :func:`encode_answer`: the answer and a reader of its ticks (``None``: none).
    Reports in the block are of ``episode``.

    Raises:
        BusError: the payload is not such an answer.
    """
    if not payload.startswith(MAGIC):
        return loads(payload, what), None
    try:
        (n,) = _U32.unpack_from(payload, 4)
        end = 8 + n
        if end > len(payload):
            raise ValueError(f"its JSON part runs past the payload ({n} bytes)")
    except (struct.error, ValueError) as exc:
        raise BusError(f"malformed {what} on the bus: {exc}") from None
    return loads(payload[8:end], what), TickReader(payload, end, episode, what)


def encode_ticks(ticks: Sequence[Tick]) -> bytes:
    """The ticks as a binary block (the module's docstring)."""
    out = [_U32.pack(len(ticks))]
    layout: tuple[tuple[str, ...], ...] | None = None
    locs: list[list[str]] | None = None
    for tick in ticks:
        w = tick.world
        ids = (
            tuple(h for h, _ in w.humans),
            tuple(o for o, _ in w.objects),
            tuple(r for r, _ in w.hands),
        )
        extra: dict[str, Any] = {}
        flags = PENDING if tick.pending else 0
        if tick.guess:
            flags |= GUESS
        if ids != layout:
            flags |= LAYOUT
            layout, locs = ids, None
        now = [[st.loc.kind, st.loc.ref] for _, st in w.objects]
        if now != locs:
            extra["loc"] = locs = now
        if w.unavailable:
            extra["seen"] = sorted(w.unavailable)
        if tick.unavailable:
            extra["unavailable"] = list(tick.unavailable)
        if tick.instructions:
            extra["instructions"] = list(tick.instructions)
        if tick.records:
            extra["records"] = list(tick.records)
        reasons = {str(i): r.status.reason for i, r in enumerate(tick.reports) if r.status.reason}
        if reasons:
            extra["reasons"] = reasons
        if tick.starts:
            extra["starts"] = [[q, h, a.to_dict()] for q, h, a in tick.starts]
        if extra:
            flags |= EXTRA
        nxt = math.nan if tick.next is None else tick.next
        out.append(_HEAD.pack(tick.t, nxt, tick.count, flags, len(tick.reports)))
        if flags & LAYOUT:
            _chunk(out, {"humans": ids[0], "objects": ids[1], "hands": ids[2]})
        xs = [c for _, p in w.humans for c in p]
        xs += [c for _, st in w.objects for c in st.position]
        xs += [c for _, p in w.hands for c in p]
        out.append(struct.pack(f"<{len(xs)}d", *xs))
        for r in tick.reports:
            s = r.status
            out.append(_REPORT.pack(r.seq, r.handle, _STATE_INDEX[s.state], s.progress, s.t))
        if flags & EXTRA:
            _chunk(out, extra)
    return b"".join(out)


def _chunk(out: list[bytes], data: dict[str, Any]) -> None:
    b = dumps(data)
    out += [_U32.pack(len(b)), b]


class TickReader:
    """The ticks of one block, decoded one at a time as they are taken (:meth:`take`)."""

    def __init__(self, payload: bytes, offset: int, episode: str, what: str = "ticks") -> None:
        self._b = payload
        self._what = what
        self._episode = episode
        try:
            (self.size,) = _U32.unpack_from(payload, offset)
        except struct.error as exc:
            raise BusError(f"malformed {what} on the bus: {exc}") from None
        self._at = offset + 4
        self.left = self.size
        self._ids: tuple[list[str], list[str], list[str]] | None = None
        self._locs: list[Loc] = []
        self._raw: tuple[bytes, bytes, bytes] = (b"", b"", b"")
        self._last: WorldState | None = None

    def peek_time(self) -> float | None:
        """The next tick's time (``None``: none left), without decoding it."""
        if not self.left:
            return None
        try:
            return float(struct.unpack_from("<d", self._b, self._at)[0])
        except struct.error as exc:
            raise BusError(f"malformed {self._what} on the bus: {exc}") from None

    def peek_guess(self) -> bool:
        """Whether the next item is a guessed step's start, not a tick (there is one left)."""
        try:
            return bool(self._b[self._at + 20] & GUESS)
        except IndexError as exc:
            raise BusError(f"malformed {self._what} on the bus: {exc}") from None

    def peek_starts(self) -> tuple[float, tuple[tuple[int, int, Action], ...]]:
        """The next item's time and, for a guessed step, its starts, without decoding its
        world or taking it (there is one left).

        Raises:
            BusError: the block is malformed.
        """
        b = self._b
        try:
            t, _, _, flags, nrep = _HEAD.unpack_from(b, self._at)
            at = self._at + _HEAD.size
            ids: Any = self._ids
            if flags & LAYOUT:
                (n,) = _U32.unpack_from(b, at)
                d = json.loads(b[at + 4 : at + 4 + n])
                ids, at = (d["humans"], d["objects"], d["hands"]), at + 4 + n
            if ids is None:
                raise ValueError("its first tick has no layout")
            at += 24 * sum(len(g) for g in ids) + _REPORT.size * nrep
            if not flags & EXTRA:
                return float(t), ()
            (n,) = _U32.unpack_from(b, at)
            extra = json.loads(b[at + 4 : at + 4 + n])
            starts = tuple(
                (int(q), int(h), Action.from_dict(a)) for q, h, a in extra.get("starts", ())
            )
        except (struct.error, ValueError, KeyError, TypeError, IndexError, HltlError) as exc:
            raise BusError(f"malformed {self._what} on the bus: {exc}") from None
        return float(t), starts

    def take(self) -> Tick:
        """Decode the next tick.

        Raises:
            BusError: the block is malformed, or no tick is left.
        """
        if not self.left:
            raise BusError(f"malformed {self._what} on the bus: no tick left in the block")
        try:
            tick = self._take()
        except (struct.error, ValueError, KeyError, TypeError, IndexError, HltlError) as exc:
            self.left = 0
            raise BusError(f"malformed {self._what} on the bus: {exc}") from None
        self.left -= 1
        return tick

    def _json(self) -> Any:
        b = self._b
        (n,) = _U32.unpack_from(b, self._at)
        start = self._at + 4
        self._at = start + n
        if self._at > len(b):
            raise ValueError(f"a JSON part runs past the block ({n} bytes)")
        return json.loads(b[start : self._at])

    def _take(self) -> Tick:
        b = self._b
        t, nxt, count, flags, nrep = _HEAD.unpack_from(b, self._at)
        self._at += _HEAD.size
        if flags & LAYOUT:
            d = self._json()
            self._ids = ids = (
                [str(h) for h in d["humans"]],
                [str(o) for o in d["objects"]],
                [str(r) for r in d["hands"]],
            )
            self._raw, self._last = (b"", b"", b""), None
        elif self._ids is None:
            raise ValueError("its first tick has no layout")
        else:
            ids = self._ids
        at = self._at
        groups = []
        for g in ids:
            end = at + 24 * len(g)
            groups.append(b[at:end])
            at = end
        if at > len(b):
            raise ValueError("its positions run past the block")
        reports = []
        for _ in range(nrep):
            reports.append(_REPORT.unpack_from(b, at))
            at += _REPORT.size
        self._at = at
        extra = self._json() if flags & EXTRA else _EMPTY
        if "loc" in extra:
            locs = [Loc(str(k), str(r)) for k, r in extra["loc"]]  # type: ignore[arg-type]
            if len(locs) != len(ids[1]):
                raise ValueError(f"{len(locs)} places for {len(ids[1])} objects")
            self._locs = locs
        elif flags & LAYOUT:
            raise ValueError("a new layout without the objects' places")
        world = self._world(t, ids, groups, "loc" in extra, frozenset(extra.get("seen", ())))
        reasons = extra.get("reasons", _EMPTY)
        ep = self._episode
        return Tick(
            t,
            world,
            tuple(
                Report(ep, seq, handle, ActionStatus(STATES[k], p, rt, reasons.get(str(i), "")))
                for i, (seq, handle, k, p, rt) in enumerate(reports)
            )
            if reports
            else (),
            None if nxt != nxt else nxt,  # (NaN: never)
            bool(flags & PENDING),
            count,
            tuple(map(str, extra["unavailable"])) if "unavailable" in extra else (),
            tuple(map(str, extra["instructions"])) if "instructions" in extra else (),
            tuple(extra["records"]) if "records" in extra else (),
            bool(flags & GUESS),
            tuple((int(q), int(h), Action.from_dict(a)) for q, h, a in extra.get("starts", ())),
        )

    def _world(
        self,
        t: float,
        ids: tuple[list[str], list[str], list[str]],
        groups: list[bytes],
        moved: bool,
        seen: frozenset[str],
    ) -> WorldState:
        """The tick's world; a group whose bytes equal the tick before's keeps its values."""
        last, raw = self._last, self._raw
        humans = (
            last.humans if last is not None and groups[0] == raw[0] else _points(ids[0], groups[0])
        )
        if last is not None and groups[1] == raw[1] and not moved:
            objects = last.objects
        else:
            objects = tuple(
                (o, ObjectStatus(p, loc))
                for (o, p), loc in zip(_points(ids[1], groups[1]), self._locs, strict=True)
            )
        hands = (
            last.hands if last is not None and groups[2] == raw[2] else _points(ids[2], groups[2])
        )
        w = WorldState(t=t, humans=humans, objects=objects, hands=hands, unavailable=seen)
        self._last, self._raw = w, (groups[0], groups[1], groups[2])
        return w


def _points(ids: list[str], raw: bytes) -> tuple[tuple[str, Vec3], ...]:
    xs = struct.unpack(f"<{3 * len(ids)}d", raw)
    return tuple((k, (xs[3 * i], xs[3 * i + 1], xs[3 * i + 2])) for i, k in enumerate(ids))
