"""Exact search over the unified graph of joint robot states, bindings and monitor states."""

from __future__ import annotations

import contextlib
import os
import signal
import threading
import time
from collections.abc import Callable, Sequence
from dataclasses import replace
from typing import TYPE_CHECKING

from hltl.planner.anytime import (
    AstarEnd,
    Certificate,
    _Found,
    beside_possible,
    certify,
    plan_anytime,
    with_fallback_plan,
)
from hltl.planner.problem import Problem, to_seconds, to_ticks
from hltl.planner.result import Binding, PlanResult, PlanStatus, PlanStep, SearchStats
from hltl.planner.search import ALGORITHMS, Live, _Search, plan_steps, search
from hltl.skills.cost import CostModel
from hltl.skills.kinematics import Kinematics
from hltl.skills.library import DEFAULT_SKILLS, Skill
from hltl.spec.hierarchy import HSpec
from hltl.spec.monitor import HierarchyMonitor, MonitorState
from hltl.world.scene import Scene
from hltl.world.state import WorldState

if TYPE_CHECKING:
    from concurrent.futures import Future, ThreadPoolExecutor
    from multiprocessing.connection import Connection
    from multiprocessing.process import BaseProcess

# exact mode: the share of ``timeout`` (at most 1 s) kept for improving the plan that a
# timed-out search returns (prioritized routing, docs/planner.md "Anytime mode")
FALLBACK_SHARE = 0.05
# exact mode, cells of 9-16 event goals: the share of ``timeout`` the step bound may take first
# to find a plan it proves optimal (docs/planner.md, "Step bound"); A* gets the rest. Most of
# it: on the 10 x 10 grid and random cells every plan proved optimal came from this phase, and
# A* after it proved none (sessions 9-11)
CERTIFY_SHARE = 0.75

__all__ = [
    "ALGORITHMS",
    "Binding",
    "PlanResult",
    "PlanStatus",
    "PlanStep",
    "Problem",
    "SearchStats",
    "plan",
]


def plan(
    scene: Scene,
    spec: HSpec,
    *,
    world: WorldState | None = None,
    monitor: HierarchyMonitor | None = None,
    q0: MonitorState | None = None,
    algorithm: str = "astar",
    timeout: float | None = 60.0,
    max_expansions: int | None = None,
    skills: Sequence[Skill] = DEFAULT_SKILLS,
    cost: CostModel | None = None,
    kinematics: Kinematics | None = None,
    on_progress: Callable[[int, float], None] | None = None,
    anytime: bool = False,
    suboptimality: float | None = None,
) -> PlanResult:
    """Find a minimum-makespan plan for ``spec`` in ``scene``.

    Args:
        scene: the cell.
        spec: the H-LTLf specification.
        world: the current world state w_t (default: the scene's initial state).
        monitor: a compiled monitor to reuse (the executor keeps one across replans).
        q0: the monitor state to start from (default: the monitor's initial state).
        algorithm: ``"astar"`` or ``"dijkstra"``; both are exact.
        timeout: seconds before the search gives up with status ``timeout``.
        max_expansions: node budget, also ending in ``timeout``.
        skills: the skill library.
        cost: the duration model (default: the scene's fixed durations, else analytic).
        kinematics: reach and poses of the skills (default: the paper's reach spheres).
        on_progress: called now and then with (nodes expanded, current lower bound).
        anytime: return a plan fast and improve it until ``timeout`` (default 10 s), with a
            proven lower bound (``lower_bound``, ``gap``); see docs/planner.md.
        suboptimality: anytime mode stops once makespan <= suboptimality x lower bound.

    Returns:
        A :class:`PlanResult`; "no plan" is ``status == PlanStatus.INFEASIBLE`` with a reason.
        A ``timeout`` in exact mode still carries a plan (the first one prioritized routing
        finds) when there is one, with the search's lower bound.
    """
    problem = Problem(
        scene,
        spec,
        world=world,
        monitor=monitor,
        q0=q0,
        skills=skills,
        cost=cost,
        kinematics=kinematics,
    )
    if anytime or suboptimality is not None:
        return plan_anytime(
            problem,
            timeout=10.0 if timeout is None else timeout,
            suboptimality=suboptimality,
        )
    # a share of the time is kept for a better plan to return should the search time out
    reserve = 0.0 if timeout is None or timeout < 2.0 else min(1.0, FALLBACK_SHARE * timeout)
    t0 = time.perf_counter()
    state = None
    best: _Found | None = None  # a plan found before A*: A* looks only for shorter ones
    proved = 0  # a lower bound (ticks) the first phase proved on every plan
    result: PlanResult | None = None
    if algorithm == "astar" and max_expansions is None and timeout is not None and timeout >= 2.0:
        state = _Search(problem)
        deadline = t0 + timeout - reserve
        beside = _Apart(problem, state, deadline, on_progress)
        try:
            cert = certify(
                problem,
                state,
                t0 + CERTIFY_SHARE * timeout,
                beside.start,
                beside.ahead,
                beside.watch,
            )
            phase: float | None = time.perf_counter() - t0
            result = beside.finish(cert)
        finally:
            # whatever happened (an exception in the phase, or while A* is awaited), no
            # A* is left running, nor paused (``stop`` waits for A*'s thread, if it was started)
            beside.stop()
        # (where A* ran in a process beside the phase: when the phase ended, how long A* waited)
        phase, held = (None, None) if beside.proc is None else (phase, beside.held)
        if cert.optimal is not None:
            stats = SearchStats(0, 0, time.perf_counter() - t0, "astar")
            if result is not None:
                stats = replace(result.stats, seconds=stats.seconds)
            return _solved(problem, cert.optimal, replace(stats, phase=phase, held=held))
        if result is not None:
            result = replace(result, stats=replace(result.stats, phase=phase, held=held))
        best, proved = cert.best, cert.bound
    if result is None:
        result = search(
            problem,
            algorithm=algorithm,
            timeout=None if timeout is None else timeout - reserve - (time.perf_counter() - t0),
            max_expansions=max_expansions,
            on_progress=on_progress,
            upper=None if best is None else best[0],
            state=state,
        )
    if state is not None:
        result = replace(result, stats=replace(result.stats, seconds=time.perf_counter() - t0))
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
        return with_fallback_plan(problem, result, time.perf_counter() + 0.7 * reserve, best)
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
    ) -> None:
        self.problem = problem
        self.deadline = deadline
        self.on_progress = on_progress
        self.live = Live()
        # A*'s thread, made when A* starts: most exact runs (cells left to A* alone, as Fig. 1)
        # start none, and ``concurrent.futures`` (with ``logging``) is ~5 ms of `hltl plan`'s
        # start-up (docs/planner.md, "Start-up")
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
            from concurrent.futures import ThreadPoolExecutor  # why: see ``self.pool``

            self.pool = ThreadPoolExecutor(max_workers=1)
        self.future = self.pool.submit(
            search,
            self.problem,
            timeout=self.deadline - time.perf_counter(),
            on_progress=self.on_progress,
            live=self.live,
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
    ) -> None:
        self.problem = problem
        self.state = state
        self.deadline = deadline
        # A* on a thread beside the full model instead, where no process can be forked or
        # ``on_progress`` wants to be called
        self.thread = _Beside(problem, deadline, on_progress)
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
        if not (self.apart and beside_possible()):
            return
        import multiprocessing  # why: only 9-16-goal cells in exact mode need it

        from hltl.planner import lns  # why: as multiprocessing (start-up, docs/planner.md)

        ctx = multiprocessing.get_context("fork")
        self.results, result_end = ctx.Pipe(duplex=False)
        upper_end, self.uppers = ctx.Pipe(duplex=False)
        proc = ctx.Process(
            target=_apart_child,
            args=(result_end, upper_end, self.problem, self.state, self.deadline),
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
                from hltl.planner import lns  # why: as in ``ahead``

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
            from hltl.planner import lns  # why: as in ``ahead``

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
        from hltl.planner import schedule  # why: as in ``ahead``

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
    results: Connection, uppers: Connection, problem: Problem, state: _Search, deadline: float
) -> None:
    """``_Apart``'s process: A* until ``deadline``, its result sent on ``results``; a thread
    passes every smaller ``upper`` that comes on ``uppers`` to the search (``search.Live``)."""
    live = Live()

    def listen() -> None:
        try:
            while True:
                live.upper = uppers.recv()
        except (EOFError, OSError):
            return

    threading.Thread(target=listen, daemon=True).start()
    try:
        left = deadline - time.perf_counter()
        results.send(search(problem, timeout=left, state=state, live=live))
    finally:
        results.close()


def _solved(problem: Problem, found: _Found, stats: SearchStats) -> PlanResult:
    """A plan proved optimal as a result."""
    makespan = to_seconds(found[0])
    steps = plan_steps(problem, found[1])
    return PlanResult(PlanStatus.SOLVED, steps, makespan, stats, "", makespan)
