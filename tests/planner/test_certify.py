"""Exact mode's first phase (a plan and the scheduling bound; when they meet, the plan is
optimal, else A* looks for a shorter one) keeps the exact mode exact."""

from __future__ import annotations

import math
import time

import pytest

from hltl.planner import PlanStatus, _exact_after, anytime, schedule
from hltl.planner.problem import Problem
from hltl.planner.search import _Search, search
from hltl.sim.scenarios import generate
from tests.oracles.validator import check_plan

pytest.importorskip("ortools")

CELLS = [(4, "line", 0), (4, "grid", 1), (5, "grid", 0), (5, "line", 1), (6, "grid", 2)]
# a resource limit, not a measurement: under load the first phase may prove less, and the
# answer must be exact either way
PHASE_S = 20.0


@pytest.mark.parametrize(("n", "layout", "seed"), CELLS)
def test_first_phase_then_search_is_exact(
    n: int, layout: str, seed: int, monkeypatch: pytest.MonkeyPatch
) -> None:
    sc = generate(n, n, layout, seed, ordered=False)
    optimum = search(Problem(sc.scene, sc.spec), timeout=None)
    assert optimum.status is PlanStatus.SOLVED and optimum.makespan is not None
    # small cells stand in for the 9-16-goal cells the first phase is for
    monkeypatch.setattr(anytime, "PAIRS_UP_TO", 1)
    problem = Problem(sc.scene, sc.spec)
    s = _Search(problem)
    t0 = time.perf_counter()
    pre = anytime.certify(problem, s, t0 + PHASE_S)
    assert pre is not None
    (ticks, _), lb = pre
    assert lb <= round(optimum.makespan * 1e6) <= ticks
    res = _exact_after(problem, s, pre, t0, math.inf, None)
    assert res.status is PlanStatus.SOLVED and res.makespan is not None
    assert res.makespan == pytest.approx(optimum.makespan)
    assert res.lower_bound == pytest.approx(optimum.makespan)
    check_plan(sc.scene, sc.spec, res.to_dict())


def test_the_bound_alone_proves_some_first_plans_optimal() -> None:
    proved = 0
    for n, layout, seed in CELLS:
        sc = generate(n, n, layout, seed, ordered=False)
        problem = Problem(sc.scene, sc.spec)
        s = _Search(problem)
        start = problem.start()
        h0 = round(s.heuristic(start))
        found = anytime.construct(problem, s)
        assert found is not None
        graph = s.heuristic.graph
        tgts = schedule.targets(problem, graph, start, s.heuristic.required_atoms(start[2]))
        bound = schedule.schedule_bound(
            problem, graph, start, tgts, floor=h0, upper=found[0], deadline=time.perf_counter() + 60
        )
        proved += h0 < found[0] == bound.ticks
    assert proved >= 1
