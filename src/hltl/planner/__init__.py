"""Exact search over the unified graph of joint robot states, bindings and monitor states."""

from __future__ import annotations

import time
from collections.abc import Callable, Sequence
from concurrent.futures import Future, ThreadPoolExecutor
from dataclasses import replace

from hltl.planner.anytime import Certificate, _Found, certify, plan_anytime, with_fallback_plan
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
    result: PlanResult | None = None
    if algorithm == "astar" and max_expansions is None and timeout is not None and timeout >= 2.0:
        state = _Search(problem)
        beside = _Beside(problem, t0 + timeout - reserve, on_progress)
        with ThreadPoolExecutor(max_workers=1) as pool:
            try:
                cert = certify(
                    problem,
                    state,
                    t0 + CERTIFY_SHARE * timeout,
                    lambda first: beside.start(pool, first),
                )
            except BaseException:
                beside.live.stopped = True  # (the pool waits for A* on the way out)
                raise
            result = beside.finish(cert)
        if cert.optimal is not None:
            stats = SearchStats(0, 0, time.perf_counter() - t0, "astar")
            if result is not None:
                stats = replace(result.stats, seconds=stats.seconds)
            return _solved(problem, cert.optimal, stats)
        best = cert.best
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
        self.future: Future[PlanResult] | None = None

    def start(self, pool: ThreadPoolExecutor, first: _Found | None) -> None:
        """Start A* (with the prioritized plan's makespan as ``upper``)."""
        self.live.upper = None if first is None else first[0]
        self.future = pool.submit(
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


def _solved(problem: Problem, found: _Found, stats: SearchStats) -> PlanResult:
    """A plan proved optimal as a result."""
    makespan = to_seconds(found[0])
    steps = plan_steps(problem, found[1])
    return PlanResult(PlanStatus.SOLVED, steps, makespan, stats, "", makespan)
