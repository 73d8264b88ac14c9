"""The planner on the whole scenario catalogue: oracle optima, A* == Dijkstra, valid plans.

The optima are pinned in tests/sim/test_scenarios.py, where the CP-SAT model and the exhaustive
search (both independent of the planner) establish them.
"""

from __future__ import annotations

import pytest

from hltl.planner import PlanStatus, plan
from hltl.sim.scenarios import catalogue, generate
from tests.oracles.validator import check_plan
from tests.sim.test_scenarios import OPTIMA

NAMES = [s.name for s in catalogue()]


@pytest.mark.parametrize("name", NAMES)
def test_catalogue_astar_and_dijkstra_are_optimal(name: str) -> None:
    (sc,) = [s for s in catalogue() if s.name == name]
    spec = sc.spec
    a = plan(sc.scene, spec, algorithm="astar")
    d = plan(sc.scene, spec, algorithm="dijkstra")
    assert a.status is PlanStatus.SOLVED and d.status is PlanStatus.SOLVED
    assert a.makespan == pytest.approx(OPTIMA[name])
    assert d.makespan == pytest.approx(OPTIMA[name])
    check_plan(sc.scene, spec, a.to_dict())
    check_plan(sc.scene, spec, d.to_dict())
    # A* never expands more than Dijkstra: the heuristic is doing its job
    assert a.stats.expanded <= d.stats.expanded


@pytest.mark.parametrize("seed", range(1, 6))
@pytest.mark.parametrize(("tasks", "robots", "layout"), [(4, 4, "line"), (4, 4, "square")])
def test_generated_paper_configs_agree(tasks: int, robots: int, layout: str, seed: int) -> None:
    sc = generate(tasks, robots, layout, seed)
    a = plan(sc.scene, sc.spec, algorithm="astar")
    d = plan(sc.scene, sc.spec, algorithm="dijkstra")
    assert a.solved and d.solved
    assert a.makespan == pytest.approx(d.makespan)
    check_plan(sc.scene, sc.spec, a.to_dict())


@pytest.mark.parametrize("seed", range(3))
def test_pairwise_bound_agrees_on_larger_lines(seed: int) -> None:
    from hltl.planner.problem import Problem
    from hltl.planner.search import search

    sc = generate(5, 5, "line", seed)
    with_pairs = search(Problem(sc.scene, sc.spec), pairs_after=0)
    without = search(Problem(sc.scene, sc.spec), pairs_after=10**9)
    assert with_pairs.solved and without.solved
    assert with_pairs.makespan == pytest.approx(without.makespan)
    assert with_pairs.stats.expanded <= without.stats.expanded
    check_plan(sc.scene, sc.spec, with_pairs.to_dict())
