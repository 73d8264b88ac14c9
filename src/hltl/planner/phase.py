"""Exact mode's first phase on cells of 9-16 goals: plans proved optimal by bounds, A* beside."""

from __future__ import annotations

import contextlib
import math
import multiprocessing
import os
import signal
import threading
import time
from collections.abc import Callable
from concurrent.futures import Future, ThreadPoolExecutor
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING

from hltl.planner import anytime, lns, phase_runs, profile, schedule
from hltl.planner.anytime import _Found
from hltl.planner.clock import WALL, Clock
from hltl.planner.problem import Node, Problem, to_seconds, to_ticks
from hltl.planner.result import PlanResult, PlanStatus, SearchStats
from hltl.planner.search import Live, _Search, plan_steps, search

if TYPE_CHECKING:
    from multiprocessing.connection import Connection
    from multiprocessing.process import BaseProcess

# the share of ``timeout`` the first phase may take to find a plan it proves optimal
# (docs/planner.md, "Step bound"); A* gets the rest. Most of it: on the 10 x 10 grid and
# random cells every plan proved optimal came from this phase, and A* after it proved none
# (sessions 9-11)
CERTIFY_SHARE = 0.75
# exact mode's first phase on cells left to A* (``_beside_astar``): CP-SAT's joint re-plan
# does at most this much deterministic work (random 10 x 10 seed 4 meets its start bound after
# 0.7; line seed 4 never does, and its 15 s of CPU beside A* cost A* about 6 %)
BESIDE_WORK = 4.0
# exact mode's first phase: the profile bound (``profile.profile_bound``) raises the step
# climb's floor first, for at most this many seconds (docs/planner.md, "The profile bound as the
# climb's floor": solved in 0.05-0.7 s on the 10 x 10 cells, grid seed 4 from 4.3 to 5.7 s,
# where the step model's cheap rounds took about 3 s to get as far)
PROFILE_FLOOR_SECONDS = 1.0
# exact mode's phase improves its prioritized plan by this many rounds of the walk (an order
# and its moves, about 1 ms each on 10-goal cells) before the step climb, whose roof the plan
# is (``schedule.schedule_bound``'s ``roof``; 0: no walk and no roof, the climb of session 18)
ROOF_ROUNDS = 400


@dataclass(frozen=True, slots=True)
class Certificate:
    """What exact mode's first phase found (``certify``): a plan it proved optimal, and the
    shortest plan it knows (the same one when proved; either may be None); and the lower
    bound (ticks) it proved on every plan (0: none beyond the start bound's)."""

    optimal: _Found | None
    best: _Found | None
    bound: int = 0


def certified(problem: Problem, s: _Search, until: float) -> _Found | None:
    """The plan ``certify`` proves optimal, or None."""
    return certify(problem, s, until).optimal


def certify(
    problem: Problem,
    s: _Search,
    until: float,
    beside: Callable[[_Found | None], None] | None = None,
    ahead: Callable[[], None] | None = None,
    watch: Callable[[AstarEnd], bool] | None = None,
) -> Certificate:
    """Exact mode's first phase for cells ``planner.phase_runs`` takes (more than
    ``PHASE_ABOVE`` and at most ``PHASE_UP_TO`` event goals) of fixed positive durations,
    with CP-SAT installed, whose start bound is at most ``STEPS_UP_TO`` shortest steps: a
    prioritized plan, then the step bound at the start node until ``until`` (levels shaved one
    by one); a plan that meets the bound (the relaxation's schedule there, the first plan, or
    CP-SAT's joint re-plan of it) is optimal. Where none is proved, the shortest of those
    plans is handed back too (A* then looks only for shorter ones). ``beside`` is called
    (with the prioritized plan) when the cheaper model's schedule is no plan and the full
    model is to be asked: the caller may start A* on the second core then, and the full
    model's levels are asked one at a time. ``ahead`` is called once the phase is sure to
    run, before CP-SAT's import (the caller may start A* in a process of its own then:
    ``_Apart``).

    Cells whose start bound is above ``STEPS_UP_TO`` shortest steps (lines, some random
    cells) get no step bound; where A* runs in a process of its own (``watch`` says so),
    the phase asks, on the other core, for a plan that meets the profile bound
    (``_beside_astar``)."""
    none = Certificate(None, None)
    start = problem.start()
    heur = s.heuristic
    if not phase_runs(problem, s):
        return none
    if not schedule.steps_applicable(problem):
        return none
    h0 = heur(start)  # (A* needs it too: memoised)
    if math.isinf(h0):
        return none
    if round(h0) > anytime.STEPS_UP_TO * min(i.lower for i in problem.instances):
        # (lines: the step model proves nothing there; A* alone, or beside it on two cores)
        if ahead is None or watch is None:
            return none
        return _beside_astar(problem, s, round(h0), until, beside, ahead, watch)
    if ahead is not None:
        ahead()
    # last: importing CP-SAT takes 0.2-0.5 s even without pandas (``lns._import_cp_sat``),
    # which a cell left to A* need not pay
    if not lns.available():
        return none
    best = anytime.construct(problem, s)
    if ROOF_ROUNDS > 0 and best is not None and best[0] > h0:
        # the step climb's roof: a fixed number of rounds (the plan does not depend on the
        # machine's speed); A*'s process has the other core meanwhile
        better = anytime._more(problem, s, until, enough=h0, rounds=ROOF_ROUNDS)
        if better is not None and better[0] < best[0]:
            best = better
    floor = _profile_floor(problem, s, start, round(h0), best, until)
    if best is not None and floor >= best[0]:
        return Certificate(best, best)  # no plan is shorter
    # levels shaved one by one (no upper): certification pays where the optimum is at or just
    # above the start bound, where galloping's extra feasible questions cost most
    ticks, found = anytime.step_bound(
        problem,
        s,
        start,
        floor,
        None,
        until,
        None if beside is None else lambda: beside(best),
        None if best is None or ROOF_ROUNDS <= 0 else best[0],
    )
    if found is not None:
        return Certificate(found, found)
    if best is None:
        return Certificate(None, None, ticks)
    if ticks >= best[0]:
        return Certificate(best, best)  # no relaxed schedule is shorter
    gls = anytime.goals(s, start)
    if gls and time.perf_counter() < until and anytime._joint_possible(problem, gls):
        # the relaxation's schedule was no plan: CP-SAT re-plans every goal jointly from the
        # prioritized plan (any path, loops too), in as many steps as a plan of the bound has
        shortest = min(i.lower for i in problem.instances)
        slack = max(0, ticks // shortest - len(best[1]))
        joint = anytime._jointly(
            problem, s, anytime._Router(s, start, gls), best, until, slack=slack
        )
        if joint is not None and joint[0] <= ticks:
            return Certificate(joint, joint)
        if joint is not None and joint[0] < best[0]:
            best = joint
    return Certificate(None, best, ticks)


class AstarEnd:
    """What ``certify``'s phase beside A* (``_beside_astar``) tells whoever watches A*'s
    process (``_Apart.watch``): the floor the phase proves plans at, and how to stop
    its joint re-plan. When A* ends with no plan at or below the floor, the phase can prove
    nothing more and is stopped; when A*'s plan meets the floor the phase goes on (it may
    prove its own plan, which is then the one returned)."""

    def __init__(self, floor: int) -> None:

        self.floor = floor
        self.stop = lns.Stop()

    def hopeless(self, astar_makespan: int | None) -> bool:
        """Whether the phase can prove nothing once A* has ended with a plan of
        ``astar_makespan`` ticks (None: none shorter than its ``upper``, the prioritized plan,
        which is then optimal, and longer than the floor, or the phase would have proved it)."""
        return astar_makespan is None or astar_makespan > self.floor


def _beside_astar(
    problem: Problem,
    s: _Search,
    h0: int,
    until: float,
    beside: Callable[[_Found | None], None] | None,
    ahead: Callable[[], None],
    watch: Callable[[AstarEnd], bool],
) -> Certificate:
    """``certify`` on cells the step bound does not take (start bound ``h0`` above
    ``STEPS_UP_TO`` shortest steps): A* starts at once in a process of its own (``ahead``)
    and has a core to itself, and on the other one a prioritized plan and CP-SAT's joint
    re-plan of it, held at or above the start bound: a plan that meets the start bound is
    optimal (random 10 x 10 seed 4: 10.5 s, proved in about 1 s, where A* alone times out on
    its plateau at 10.5 s). Where none is proved, the prioritized plan is the one handed back
    (A* looks for shorter plans, and its own is returned: never the joint re-plan's, which
    may or may not be there when A* ends). ``watch`` (``_Apart.watch``) stops the
    phase when A* has ended with a plan longer than the start bound (nothing the phase could
    prove), so the plan returned is the same whichever ends first and cells A* solves
    quickly (most lines) do not wait for CP-SAT. The start bound, not the profile bound, is
    the floor: it is known before CP-SAT's import, which A* often beats on lines (line
    10 x 10 seed 3: 0.45 s), and on these cells the profile bound added nothing (random seed
    4, lines 0 and 4: the start bound)."""

    none = Certificate(None, None)
    ahead()
    end = AstarEnd(h0)
    if not watch(end):
        return none  # (no process: A* alone, at once)
    best = anytime.construct(problem, s)
    if best is None:
        return none
    if beside is not None:
        beside(best)  # (A*'s ``upper``: it looks only for shorter plans)
    if best[0] <= h0:
        return Certificate(best, best)
    # (A* may have ended before or during CP-SAT's import: then there is nothing to prove)
    if end.stop.stopped or not lns.available() or end.stop.stopped:
        return Certificate(None, best)
    start = problem.start()
    gls = anytime.goals(s, start)
    if not gls or not anytime._joint_possible(problem, gls):
        return Certificate(None, best)
    router = anytime._Router(s, start, gls)
    joint = anytime._jointly(
        problem, s, router, best, until, floor=h0, stop=end.stop, work=BESIDE_WORK
    )
    if joint is not None and joint[0] <= h0:
        return Certificate(joint, joint)
    return Certificate(None, best)


def _profile_floor(
    problem: Problem, s: _Search, start: Node, floor: int, best: _Found | None, until: float
) -> int:
    """The profile bound at the start node (``profile.profile_bound``, at most
    ``PROFILE_FLOOR_SECONDS``), or ``floor`` where it does not apply or says no more: a lower
    bound on every plan, so the step climb may start there. Its questions are cheap (no
    presolve, one at a time: A*'s process runs beside them) and it is solved long before the
    step model's hard levels, which it never reaches (docs/planner.md, "The profile bound as
    the climb's floor")."""

    if not profile.applicable(problem):
        return floor
    heur = s.heuristic
    tgts = schedule.targets(problem, heur.graph, start, heur.required_atoms(start[2]))
    if not tgts:
        return floor
    res = profile.profile_bound(
        problem,
        heur.graph,
        start,
        tgts,
        floor=floor,
        upper=None if best is None else best[0],
        deadline=min(until, time.perf_counter() + PROFILE_FLOOR_SECONDS),
    )
    return res.ticks


def plan_phased(
    problem: Problem,
    state: _Search,
    t0: float,
    timeout: float,
    reserve: float,
    on_progress: Callable[[int, float], None] | None,
    *,
    clock: Clock = WALL,
) -> PlanResult:
    """``planner.plan`` in exact mode on a cell ``planner.phase_runs`` takes: the first phase
    (``certify``) until ``CERTIFY_SHARE`` of ``timeout`` (``t0``: the run's start), A* beside
    it (``_Apart``) or after it, looking only for plans shorter than the phase's best; the
    last ``reserve`` seconds improve the plan a timed-out search returns. Times are on
    ``clock``; the phase's CP-SAT and HiGHS keep wall time (its deadline is
    ``clock.wall``'s)."""
    best: _Found | None = None  # a plan found before A*: A* looks only for shorter ones
    deadline = t0 + timeout - reserve
    beside = _Apart(problem, state, deadline, on_progress, clock=clock)
    try:
        cert = certify(
            problem,
            state,
            clock.wall(t0 + CERTIFY_SHARE * timeout),
            beside.start,
            beside.ahead,
            beside.watch,
        )
        phase: float | None = clock.now() - t0
        result = beside.finish(cert)
    finally:
        # whatever happened (an exception in the phase, or while A* is awaited), no
        # A* is left running, nor paused (``stop`` waits for A*'s thread, if it was started)
        beside.stop()
    # (where A* ran in a process beside the phase: when the phase ended, how long A* waited)
    phase, held = (None, None) if beside.proc is None else (phase, beside.held)
    if cert.optimal is not None:
        stats = SearchStats(0, 0, clock.now() - t0, "astar")
        if result is not None:
            stats = replace(result.stats, seconds=stats.seconds)
        return _solved(problem, cert.optimal, replace(stats, phase=phase, held=held))
    if result is not None:
        result = replace(result, stats=replace(result.stats, phase=phase, held=held))
    best, proved = cert.best, cert.bound
    if result is None:
        result = search(
            problem,
            timeout=timeout - reserve - (clock.now() - t0),
            on_progress=on_progress,
            upper=None if best is None else best[0],
            state=state,
            clock=clock,
        )
    result = replace(result, stats=replace(result.stats, seconds=clock.now() - t0))
    if best is not None and (
        result.status is PlanStatus.INFEASIBLE
        or (result.makespan is not None and to_ticks(result.makespan) >= best[0])
    ):
        # A* proved no plan is shorter (or, started before ``best`` was known, found one
        # as short: the same plan is returned whichever came first)
        return _solved(problem, best, result.stats)
    if result.status is PlanStatus.TIMEOUT:
        if proved and (result.lower_bound is None or to_ticks(result.lower_bound) < proved):
            # (the step climb's "no"s may have proved more than A*'s open list)
            lb = to_seconds(proved)
            reason = f"{result.reason}; the first phase proved {lb:.3f} s"
            result = replace(result, lower_bound=lb, reason=reason)
        # the walk checks the clock between routings: leave room for the last one
        return anytime.with_fallback_plan(
            problem, result, clock.now() + 0.7 * reserve, best, clock=clock
        )
    return result


class _Beside:
    """A* on a thread of its own beside exact mode's first phase, once that phase reaches the
    full model (``certify``'s ``beside``): the phase's CP-SAT questions run one at a time and
    leave the GIL while they solve, so the two share the cores. The result does not depend on
    which ends first: a plan the phase proves optimal is returned (A* is stopped, or its
    plan set aside), else A*'s, unless it is no shorter than the phase's best plan, which is
    then returned (A* is told the phase's best makespan as its ``upper`` when the phase ends,
    which changes nothing it finds below it)."""

    def __init__(
        self,
        problem: Problem,
        deadline: float,
        on_progress: Callable[[int, float], None] | None,
        *,
        clock: Clock = WALL,
    ) -> None:
        self.problem = problem
        self.deadline = deadline
        self.on_progress = on_progress
        self.clock = clock
        self.live = Live()
        # A*'s thread, made when A* starts (where it runs in a process of its own, never)
        self.pool: ThreadPoolExecutor | None = None
        self.future: Future[PlanResult] | None = None

    def stop(self) -> None:
        """Stop A* (when the phase fails, or has ended) and wait for its thread to end."""
        self.live.stopped = True
        if self.pool is not None:
            self.pool.shutdown(wait=True)

    def start(self, first: _Found | None) -> None:
        """Start A* (with the prioritized plan's makespan as ``upper``)."""
        self.live.upper = None if first is None else first[0]
        if self.pool is None:
            self.pool = ThreadPoolExecutor(max_workers=1)
        self.future = self.pool.submit(
            search,
            self.problem,
            timeout=self.deadline - self.clock.now(),
            on_progress=self.on_progress,
            live=self.live,
            clock=self.clock,
        )

    def finish(self, cert: Certificate) -> PlanResult | None:
        """A*'s result once the phase has ended with ``cert`` (None: A* was not started)."""
        if self.future is None:
            return None
        if cert.optimal is not None:
            self.live.stopped = True
        elif cert.best is not None and (self.live.upper is None or cert.best[0] < self.live.upper):
            self.live.upper = cert.best[0]
        return self.future.result()


class _Apart:
    """A* in a forked process of its own (``anytime.beside_possible``: two cores, ``fork``)
    from the moment exact mode's first phase is known to run (``certify``'s ``ahead``). It is
    paused (``SIGSTOP``, ``SIGCONT``) through each round in which the phase asks CP-SAT as
    many questions at once as there are cores (``lns.share_busy``: the cheaper model's climb
    asks two levels in a round), so it takes only the CPU the phase leaves (CP-SAT's import,
    the Python between rounds, the second core while the full model's levels are asked one
    at a time, ``certify``'s ``beside``) and all of it once the phase ends. A thread would
    take turns with the phase on Python's lock. What it returns is decided as ``_Beside``
    decides it, so the plan does not depend on which ends first: the phase's proved plan (A*
    is stopped), else A*'s, unless it is no shorter than the phase's best plan (whose
    makespan A* is sent as its ``upper``, ``search.Live``). Where no process can be forked,
    or with ``on_progress`` (called in this process), A* runs on a thread beside the full
    model (``_Beside``)."""

    def __init__(
        self,
        problem: Problem,
        state: _Search,
        deadline: float,
        on_progress: Callable[[int, float], None] | None,
        *,
        clock: Clock = WALL,
    ) -> None:
        self.problem = problem
        self.state = state
        self.deadline = deadline
        # (``deadline`` is on this clock; the process takes a copy of it as it stands)
        self.clock = clock
        # A* on a thread beside the full model instead, where no process can be forked or
        # ``on_progress`` wants to be called
        self.thread = _Beside(problem, deadline, on_progress, clock=clock)
        self.apart = on_progress is None
        self.proc: BaseProcess | None = None
        self.results: Connection | None = None  # A*'s result comes on this
        self.uppers: Connection | None = None  # smaller ``upper``s go to A* on this
        self.upper: int | None = None
        self.paused = False
        self.held = 0.0  # seconds A*'s process has been paused (its last pause began at since)
        self.since = 0.0
        # a thread that takes A*'s result as soon as it comes (``watch``), and what it took
        self.watcher: threading.Thread | None = None
        self.got: PlanResult | None = None
        self.phase_over = threading.Event()

    def ahead(self) -> None:
        """Fork the process and start A* in it."""
        if not (self.apart and anytime.beside_possible()):
            return

        ctx = multiprocessing.get_context("fork")
        self.results, result_end = ctx.Pipe(duplex=False)
        upper_end, self.uppers = ctx.Pipe(duplex=False)
        proc = ctx.Process(
            target=_apart_child,
            args=(result_end, upper_end, self.problem, self.state, self.deadline, self.clock),
            daemon=True,
        )
        proc.start()
        self.proc = proc
        lns.share_busy(self._busy)
        result_end.close()  # (the child's copies stay open: their ends are the pipes' ends)
        upper_end.close()

    def watch(self, end: AstarEnd) -> bool:
        """Take A*'s result as soon as it comes, and stop the phase's question when A* has
        ended with nothing the phase could still prove (``AstarEnd.hopeless``). False where
        no process runs."""
        if self.proc is None or self.results is None or self.watcher is not None:
            return False
        results = self.results

        def take() -> None:
            try:
                self.got = results.recv()
            except (EOFError, OSError):
                return  # (ended: ``stop``)
            got = self.got
            makespan = None
            if got.status is PlanStatus.SOLVED and got.makespan is not None:
                makespan = to_ticks(got.makespan)
            if end.hopeless(makespan):
                lns.stop_until(end.stop, self.phase_over.wait)

        self.watcher = threading.Thread(target=take, daemon=True)
        self.watcher.start()
        return True

    def start(self, first: _Found | None) -> None:
        """The prioritized plan's makespan is A*'s ``upper`` (the process runs already)."""
        if self.proc is None:
            self.thread.start(first)
        elif first is not None:
            self._tell(first[0])

    def finish(self, cert: Certificate) -> PlanResult | None:
        """A*'s result once the phase has ended with ``cert`` (None: A* was not started, was
        stopped because the phase proved a plan optimal, or its process died)."""
        if self.proc is None or self.results is None:
            return self.thread.finish(cert)
        self.phase_over.set()
        if cert.optimal is not None:
            self.stop()
            return None
        self._busy(0)
        if cert.best is not None:
            self._tell(cert.best[0])
        if self.watcher is not None:
            self.watcher.join()  # (it has A*'s result once A* has ended)
            got = self.got
        else:
            try:
                got = self.results.recv()
            except EOFError:
                got = None
        self.stop()
        return got

    def stop(self) -> None:
        """End the process (if it still runs) and close the pipes."""
        self.thread.stop()
        if self.proc is not None:  # (``ahead`` gave lns its pause hook)
            lns.share_busy(None)
        if self.paused:  # (ended while paused)
            self.paused = False
            self.held += time.perf_counter() - self.since
        self.phase_over.set()
        if self.proc is not None:
            if self.proc.is_alive():
                self.proc.kill()  # (a paused process ends too)
            self.proc.join()
        if self.watcher is not None:
            self.watcher.join()  # (the pipe's end came with the process's)
        for conn in (self.results, self.uppers):
            if conn is not None:
                conn.close()

    def _busy(self, questions: int) -> None:
        # a round of ``questions`` at once begins (0: ends): A* pauses through one that
        # takes every core

        pause = questions >= schedule.WORKERS
        if self.proc is not None and self.proc.pid is not None and pause != self.paused:
            self.paused = pause
            now = time.perf_counter()
            if pause:
                self.since = now
            else:
                self.held += now - self.since
            with contextlib.suppress(OSError):  # (A* has ended already)
                os.kill(self.proc.pid, signal.SIGSTOP if pause else signal.SIGCONT)

    def _tell(self, upper: int) -> None:
        if self.uppers is not None and (self.upper is None or upper < self.upper):
            self.upper = upper
            with contextlib.suppress(OSError):  # (A* has ended already)
                self.uppers.send(upper)


def _apart_child(
    results: Connection,
    uppers: Connection,
    problem: Problem,
    state: _Search,
    deadline: float,
    clock: Clock = WALL,
) -> None:
    """``_Apart``'s process: A* until ``deadline`` on ``clock`` (its copy), its result sent on
    ``results``; a thread passes every smaller ``upper`` that comes on ``uppers`` to the
    search (``search.Live``)."""
    live = Live()

    def listen() -> None:
        try:
            while True:
                live.upper = uppers.recv()
        except (EOFError, OSError):
            return

    threading.Thread(target=listen, daemon=True).start()
    try:
        left = deadline - clock.now()
        results.send(search(problem, timeout=left, state=state, live=live, clock=clock))
    finally:
        results.close()


def _solved(problem: Problem, found: _Found, stats: SearchStats) -> PlanResult:
    """A plan proved optimal as a result."""
    makespan = to_seconds(found[0])
    steps = plan_steps(problem, found[1])
    return PlanResult(PlanStatus.SOLVED, steps, makespan, stats, "", makespan)
