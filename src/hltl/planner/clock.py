"""The planner's clock: wall time in production, a clock of work in tests."""

from __future__ import annotations

import time
from typing import Final, Protocol


class Clock(Protocol):
    """What the planner asks of a clock."""

    def now(self) -> float:
        """Seconds on this clock (only differences mean anything)."""
        ...

    def wall(self, until: float) -> float:
        """The ``time.perf_counter()`` instant that stands for ``until`` (on this clock) where
        something keeps wall time: CP-SAT's and HiGHS's time limits, waits for another
        process."""
        ...


class WallClock:
    """``time.perf_counter``: the planner's clock outside tests."""

    # (the built-in itself, not a method around it: A* reads it at every expansion)
    now = staticmethod(time.perf_counter)

    def wall(self, until: float) -> float:
        return until


WALL: Final = WallClock()


class WorkClock:
    """A clock that advances by ``step`` seconds at each reading, and only then. The planner
    reads its clock once per unit of work where it checks a budget (an A* expansion and every
    ``search.CHECK_EVERY`` successors, a round of the walk over priority orders, a repair
    move, a pair bound, a priority order tried), so on this clock a run's phases and shares
    end after the same work whatever the machine's speed and load.

    What keeps wall time (CP-SAT, HiGHS, a wait for another process: ``wall``) gets
    ``wall_seconds`` of real time each time it is given a deadline this clock has not
    reached yet, and none once it has: 0 (the default) gives the solvers no time, so they
    prove nothing, on any machine; a long one (e.g. 60 s) lets them finish their work, and
    lets the anytime run wait for the bound's process until it ends, which it does by its
    own copy of this clock.

    A forked process (the profile bound beside the walk, A* apart from exact mode's first
    phase) takes a copy of the clock as it stands at the fork, and it runs on from there
    with that process's work: both processes share the epoch and the deadlines, and each
    stops at the deadline after the same work it would do alone. Threads that share one
    ``WorkClock`` advance it together."""

    def __init__(self, step: float = 0.01, *, wall_seconds: float = 0.0, start: float = 0.0):
        if step <= 0:
            raise ValueError(f"a work clock must advance: step {step!r}")
        self.step = step
        self.wall_seconds = wall_seconds
        self.start = start
        self.readings = 0

    @property
    def t(self) -> float:
        """The time the next reading gives (readings are counted: no rounding drifts)."""
        return self.start + self.readings * self.step

    def now(self) -> float:
        t = self.t
        self.readings += 1
        return t

    def wall(self, until: float) -> float:
        # (not a reading: handing a deadline over is no work)
        left = self.wall_seconds if self.t < until else 0.0
        return time.perf_counter() + left
