"""Real time on the bus: the cell runs on its own clock and the executor follows the wall clock."""

from __future__ import annotations

import contextlib
import dataclasses
import math
import time
from typing import Any

from hltl.bus.codec import Command, Report, loads, world_from_wire
from hltl.bus.driver import BusCell, bus_cell
from hltl.errors import BusError
from hltl.execution.drivers import ActionState, ActionStatus, Handle, SafetyCheck
from hltl.execution.log import LogRecord
from hltl.sim.episode import CellFactory, EpisodeConfig

# how an action ends on its own (not halted)
_ENDED = frozenset({ActionState.DONE, ActionState.FAILED})

# the guard checks the executor's running actions once the loop has not been back for this
# many ticks (a loop that keeps up is back every tick, and checks them itself)
GUARD_AFTER = 2.0


def check_factor(factor: float) -> float:
    """``factor`` if it can be a real-time factor (cell seconds per wall second)."""
    if not (math.isfinite(factor) and factor > 0):
        raise ValueError(f"real-time factor must be a positive number, got {factor!r}")
    return factor


class RealtimeBusCell(BusCell):
    """A cell served by a node that runs it in real time; the executor follows the wall clock.

    Args:
        factor: cell seconds per wall second (1: real robots; more: a simulator sped up).
        The rest as for :class:`~hltl.bus.driver.BusCell`; its ``tick`` is also the node's
        period unless the node has its own, and ``ahead`` is ignored (nothing is simulated
        ahead of a clock that runs on its own).

    Raises:
        BusError: no node serves the cell, it refuses the episode, or it cannot run it in
            real time.
    """

    _defer = False  # no step queries: every command goes to the robots at once
    _eager = True  # the node's clock starts with the reset: its answer is taken in at once

    @property
    def _reset_key(self) -> str:
        return self.keys.sim_reset  # (no step queries: the reset has a queryable of its own)

    def __init__(self, *args: Any, factor: float = 1.0, **kwargs: Any) -> None:
        self.factor = check_factor(factor)
        self.period = float(kwargs.get("tick", EpisodeConfig().tick))
        self._inbox: list[dict[str, Any]] = []
        self._n = 0  # the newest tick taken in
        self._have_records = 0  # the node's log records taken in (they are numbered)
        self._have_said = 0  # instructions taken in
        self._missing = False  # some records or instructions were skipped: ask for them
        self._reports_upto = 0
        self._t_node = 0.0  # the node's clock, as last heard
        self._heard = self._epoch = time.monotonic()
        self._gap_since: float | None = None
        # the executor's safety check, run on the ticks heard while its loop is busy; when
        # the loop was last back; the newest tick checked; the halts sent (handle: when)
        self._check: SafetyCheck | None = None
        self._loop_at = time.monotonic()
        self._guard_n = 0
        self._guard_halts: dict[int, float] = {}
        try:
            super().__init__(*args, **{**kwargs, "ahead": 0})
        except BusError:
            with contextlib.suppress(AttributeError):  # nothing was opened yet
                self.close()
            raise

    # -- the episode ---------------------------------------------------------------------------

    def _mode(self) -> dict[str, Any]:
        return {"realtime": {"factor": self.factor, "period": self.period}}

    def _subscribe(self) -> list[Any]:
        return [self.session.declare_subscriber(self.keys.sim_tick, self._on_tick)]

    def _take(self, d: dict[str, Any]) -> None:
        """The reset answer: the first world, and the node's clock (cell time 0 is now)."""
        rt = d.get("realtime")
        if not isinstance(rt, dict):
            raise BusError(
                f"the node serving {self.keys.sim_reset} does not run episodes in real time"
            )
        self._absorb(d)
        self._have_records = len(d.get("records", ()))
        self._reports_upto = int(d.get("reports", 0))
        now = time.monotonic()
        self._t_node = float(rt["t"])
        self._heard, self._epoch = now, now - self._t_node / self.factor

    def _on_tick(self, sample: Any) -> None:
        if self.faults.slow:
            time.sleep(self.faults.slow)
        try:
            d = loads(sample.payload.to_bytes(), "tick")
        except BusError:
            return
        if d.get("episode") == self.episode:
            with self._cond:
                self._inbox.append(d)
            if self._check is not None and not self._dead:
                self._guard_tick(d)

    # -- the guard -----------------------------------------------------------------------------

    def guard(self, check: SafetyCheck) -> None:
        """The executor's safety check (:class:`~hltl.execution.drivers.Guarded`): while its
        loop is busy (planning, grounding: not back for :data:`GUARD_AFTER` ticks), each new
        tick's world is checked here, on the thread that hears it, and an action it endangers
        is halted at once, without waiting for the loop (at 10×, a 60 ms replan on a loaded
        machine is 0.6 s of the cell's, in which a hand-over can end with a person in its
        way). The loop hears of the halt from the action's report, as of any."""
        self._check = check

    def _guard_tick(self, d: dict[str, Any]) -> None:
        """Run the executor's safety check on a tick heard while the loop is busy; halt what
        it names (again after ``timing.timeout`` if no report says it ended: the halt may
        have been lost)."""
        check = self._check
        now = time.monotonic()
        if check is None or now - self._loop_at < GUARD_AFTER * self.period / self.factor:
            return
        try:
            n = int(d.get("n", 0))
            world = world_from_wire(d["observation"])
        except (KeyError, TypeError, ValueError, BusError):
            return
        if n <= self._guard_n:  # (an older tick than one checked already: its world is stale)
            return
        self._guard_n = n
        for handle, reason in check(world):
            hid = handle.id
            with self._cond:
                ended = self._status_terminal(hid)
            sent = self._guard_halts.get(hid)
            if ended or (sent is not None and now - sent < self.timing.timeout):
                continue
            if sent is None:
                self.stats.guarded += 1
            self._guard_halts[hid] = now
            # (numbered as the last command: a halt starts nothing, the node halts by handle)
            cmd = Command(
                self.episode,
                self._seq,
                "halt",
                hid,
                handle.action,
                self.clock(),
                f"{reason} (halted by the guard while the executor's loop was busy)",
            )
            payload = cmd.encode()
            for r in handle.action.robots:
                self.link.put(self.keys.action(r), payload)

    # -- the clock -----------------------------------------------------------------------------

    def clock(self) -> float:
        """The cell's time now, by the wall clock."""
        return (time.monotonic() - self._epoch) * self.factor

    def pace(self, t: float) -> float:
        """Wait for the wall clock to reach cell time ``t``; the time then (later than ``t`` when
        the loop was busy past it: its ticks are skipped, not made up)."""
        wait = self._epoch + t / self.factor - time.monotonic()
        if wait > 0:
            time.sleep(wait)
        now = self.clock()
        if now - t > self.period:
            self.stats.late_ticks += 1
        return max(t, now)

    def _follow(self, t: float) -> None:
        """Take in the ticks the node published since the last call (asking for what was
        missed, or for the clock after a silence) and fetch reports that are late."""
        self._loop_at = time.monotonic()  # (the loop is back: the guard stands down)
        with self._cond:
            inbox, self._inbox = self._inbox, []
        for d in sorted(inbox, key=lambda d: int(d.get("n", 0))):
            self._tick_in(d)
        if self._missing or time.monotonic() - self._heard > self.timing.timeout:
            self._ask_clock()
        if not self._dead:
            self._late_reports()

    def _tick_in(self, d: dict[str, Any]) -> None:
        """Take in one tick (published, or the answer to a clock query): the numbered log
        records and instructions not seen yet, the reports, and — when it is the newest tick —
        the world and the clock."""
        try:
            n, t = int(d.get("n", 0)), float(d["t"])
            rf, sf = int(d["records_from"]), int(d["said_from"])
            records, said = list(d.get("records", ())), [str(s) for s in d.get("instructions", ())]
        except (KeyError, TypeError, ValueError):
            return  # not a tick: ignore it (the clock query fills what it should have said)
        if rf > self._have_records or sf > self._have_said:
            self._missing = True  # a tick in between never came
        else:
            for rec in records[self._have_records - rf :]:
                self._emit(LogRecord.from_json(rec, "the cell's log record"))
            self._have_records = max(self._have_records, rf + len(records))
            self._instructions.extend(said[self._have_said - sf :])
            self._have_said = max(self._have_said, sf + len(said))
        reports = [Report.from_dict(item) for item in d.get("status", ())]
        with self._cond:
            for rep in reports:
                if rep.episode == self.episode:
                    self._accept(rep)
        if n > self._n + 1:
            self.stats.missed += n - self._n - 1
        if n >= self._n:
            self._n = n
            if "observation" in d:
                self._obs = world_from_wire(d["observation"])
            self._clock(d)
            self._reports_upto = max(self._reports_upto, int(d.get("reports", 0)))
        now = time.monotonic()
        if t > self._t_node:
            self._t_node, self._heard = t, now
        # the tick left the node at cell time t: its wall time is at most now, so the earliest
        # such estimate of cell time 0 is the closest (the one with the shortest delay)
        self._epoch = min(self._epoch, now - t / self.factor)

    def _emit(self, rec: LogRecord) -> None:
        """Log what the cell did. It is heard after the executor logged its own records of that
        moment (and, the executor's clock trailing the node's by the bus delay, can even be
        stamped a little ahead of it), while a log never goes back in time: it is logged at its
        own time, kept between the log's last record and now (off by at most a tick and the
        bus delay)."""
        last = self.log.records[-1].t if self.log.records else 0.0
        t = min(max(rec.t, last), max(self.now, last))
        self.log.emit(rec if t == rec.t else dataclasses.replace(rec, t=t))

    def _ask_clock(self) -> None:
        """Ask the node for its clock and what was missed; down when it does not answer, or
        when its clock stood still for ``timing.patience``."""
        request = {
            "episode": self.episode,
            "records_from": self._have_records,
            "said_from": self._have_said,
        }
        try:
            d = self._ask(self.keys.sim_clock, request, robots=self.scene.robot_ids)
        except BusError as exc:
            self._lose_all(f"the cell node gave up: {exc}")
            return
        if d is None:
            self._lose_all(f"the cell node stopped answering at t={self.now:.2f}")
            return
        self._missing = False
        self._tick_in(d)
        if time.monotonic() - self._heard > self.timing.patience:
            self._lose_all(
                f"the cell's clock stood still at t={self._t_node:.2f} for "
                f"{self.timing.patience:g} s"
            )

    def _late_reports(self) -> None:
        """Reports the node says it sent and that have not come within ``timing.timeout``:
        fetched from the robots (the loop does not wait for them meanwhile)."""
        with self._cond:
            complete = self._contiguous >= self._reports_upto
        if complete:
            self._gap_since = None
            return
        now = time.monotonic()
        if self._gap_since is None:
            self._gap_since = now
        elif now - self._gap_since >= self.timing.timeout:
            self._gap_since = None
            self._recover(self._reports_upto)

    def ended_first(self, handle: Handle) -> ActionStatus | None:
        """After a halt: how the action ended if the node reports it ended on its own first
        (done or failed; :class:`~hltl.execution.drivers.OwnClock`). The node acts on a halt
        when it arrives, on its own clock: an action may end between the executor's decision
        and then (the halt confirmed by a report of its end)."""
        with self._cond:
            rep = None if handle.id in self._local else self._latest.get(handle.id)
        st = None if rep is None else rep.status
        return st if st is not None and st.state in _ENDED else None

    def next_event_time(self) -> float:
        """When the node expects something to happen next; an expected time already past means
        its report is on the way, so the loop just ticks on."""
        if self._dead:
            return math.inf
        if self._next > self.now and (math.isfinite(self._next) or not self._pending):
            return self._next
        return self.now + self.period  # (an instruction fired but not yet heard: tick on)

    def pending_instructions(self) -> bool:
        return bool(self._instructions) or self._pending


def realtime_bus_cell(session: Any, *, factor: float = 1.0, **kwargs: Any) -> CellFactory:
    """:func:`~hltl.bus.driver.bus_cell` for a node that runs the cell in real time
    (``factor`` cell seconds per wall second); ``kwargs`` as for ``bus_cell``."""
    check_factor(factor)

    def make(*args: Any, **kw: Any) -> RealtimeBusCell:
        return RealtimeBusCell(*args, factor=factor, **kw)

    return bus_cell(session, make_cell=make, **kwargs)
