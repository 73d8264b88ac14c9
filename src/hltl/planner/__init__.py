"""Exact search over the unified graph of joint robot states, bindings and monitor states."""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import replace

from hltl.planner.clock import WALL, Clock, WorkClock
from hltl.planner.problem import Problem
from hltl.planner.result import Binding, PlanResult, PlanStatus, PlanStep, SearchStats
from hltl.planner.search import ALGORITHMS, _Search, search
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
# exact mode's first phase (planner/phase.py: bounds that prove a plan optimal, A* beside them)
# runs on cells of more than PHASE_ABOVE and at most PHASE_UP_TO event goals; the others are
# A*'s alone (docs/planner.md, "Step bound"). Only the phase, anytime mode and a timed-out
# search's fallback plan use lns, schedule, profile and repair: ``plan`` imports planner/phase.py
# and planner/anytime.py where those branches start, and the exact runs A* takes alone (the
# paper's cells) import neither (start-up, docs/planner.md "Start-up")
PHASE_ABOVE = 8
PHASE_UP_TO = 16

__all__ = [
    "ALGORITHMS",
    "WALL",
    "Binding",
    "Clock",
    "PlanResult",
    "PlanStatus",
    "PlanStep",
    "Problem",
    "SearchStats",
    "WorkClock",
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
    clock: Clock = WALL,
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
        clock: where ``timeout``, every phase's share of it and the seconds reported are read:
            ``time.perf_counter`` (``WALL``); tests pass a :class:`WorkClock`, which advances
            only with the planner's work (docs/planner.md, "The clock").

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
        from hltl.planner.anytime import plan_anytime  # why: start-up (see PHASE_ABOVE)

        return plan_anytime(
            problem,
            timeout=10.0 if timeout is None else timeout,
            suboptimality=suboptimality,
            clock=clock,
        )
    # a share of the time is kept for a better plan to return should the search time out
    reserve = 0.0 if timeout is None or timeout < 2.0 else min(1.0, FALLBACK_SHARE * timeout)
    t0 = clock.now()
    state = None
    if algorithm == "astar" and max_expansions is None and timeout is not None and timeout >= 2.0:
        state = _Search(problem)
        if phase_runs(problem, state):
            from hltl.planner.phase import plan_phased  # why: start-up (see PHASE_ABOVE)

            return plan_phased(problem, state, t0, timeout, reserve, on_progress, clock=clock)
    result = search(
        problem,
        algorithm=algorithm,
        timeout=None if timeout is None else timeout - reserve - (clock.now() - t0),
        max_expansions=max_expansions,
        on_progress=on_progress,
        state=state,
        clock=clock,
    )
    if state is not None:
        result = replace(result, stats=replace(result.stats, seconds=clock.now() - t0))
    if result.status is PlanStatus.TIMEOUT:
        from hltl.planner.anytime import with_fallback_plan  # why: start-up (see PHASE_ABOVE)

        # the walk checks the clock between routings: leave room for the last one
        return with_fallback_plan(problem, result, clock.now() + 0.7 * reserve, clock=clock)
    return result


def phase_runs(problem: Problem, s: _Search) -> bool:
    """Whether exact mode's first phase (``phase.certify``) runs on ``problem`` (``s``: its
    search state): more than ``PHASE_ABOVE`` and at most ``PHASE_UP_TO`` goal atoms still
    needed at the start."""
    start = problem.start()
    if problem.monitor.accepted(start[2]):
        return False
    return PHASE_ABOVE < len(s.heuristic.required_atoms(start[2])) <= PHASE_UP_TO
