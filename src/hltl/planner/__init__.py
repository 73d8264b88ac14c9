"""Exact search over the unified graph of joint robot states, bindings and monitor states."""

from __future__ import annotations

import time
from collections.abc import Callable, Sequence
from dataclasses import replace

from hltl.planner.anytime import CERTIFY_SHARE, certify, plan_anytime, with_fallback_plan
from hltl.planner.problem import Instance, Node, Problem, to_seconds
from hltl.planner.result import Binding, PlanResult, PlanStatus, PlanStep, SearchStats
from hltl.planner.search import ALGORITHMS, _Search, plan_steps, search
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
    if algorithm == "astar" and max_expansions is None and timeout is not None and timeout >= 2.0:
        t0 = time.perf_counter()
        s = _Search(problem)
        pre = certify(problem, s, t0 + CERTIFY_SHARE * timeout)
        if pre is not None:
            return _exact_after(problem, s, pre, t0, t0 + timeout - reserve, on_progress)
    result = search(
        problem,
        algorithm=algorithm,
        timeout=None if timeout is None else timeout - reserve,
        max_expansions=max_expansions,
        on_progress=on_progress,
    )
    if result.status is PlanStatus.TIMEOUT:
        # the walk checks the clock between routings: leave room for the last one
        return with_fallback_plan(problem, result, time.perf_counter() + 0.7 * reserve)
    return result


def _exact_after(
    problem: Problem,
    s: _Search,
    pre: tuple[tuple[int, list[tuple[Node, tuple[Instance, ...], int]]], int],
    t0: float,
    deadline: float,
    on_progress: Callable[[int, float], None] | None,
) -> PlanResult:
    """Exact mode after ``certify`` (started at ``t0``): the plan when it meets the bound
    (proved optimal), else A* for a shorter plan until ``deadline``; when A* proves there is
    none, the plan is optimal. The stats count the time since ``t0``."""
    (ticks, chain), lb = pre
    makespan = to_seconds(ticks)
    steps = plan_steps(problem, chain)
    if ticks <= lb:
        stats = SearchStats(0, 0, time.perf_counter() - t0, "astar")
        return PlanResult(PlanStatus.SOLVED, steps, makespan, stats, "", makespan)
    res = search(
        problem,
        timeout=max(0.0, deadline - time.perf_counter()),
        upper=ticks,
        state=s,
        on_progress=on_progress,
    )
    stats = replace(res.stats, seconds=time.perf_counter() - t0)
    if res.status is PlanStatus.SOLVED:
        return replace(res, stats=stats)
    if res.status is PlanStatus.INFEASIBLE:  # nothing shorter than the plan: it is optimal
        return PlanResult(PlanStatus.SOLVED, steps, makespan, stats, "", makespan)
    bound = max(to_seconds(lb), res.lower_bound or 0.0)
    return PlanResult(
        PlanStatus.TIMEOUT,
        steps,
        makespan,
        stats,
        res.reason + f"; best plan found: {makespan:.3f} s",
        min(bound, makespan),
    )
