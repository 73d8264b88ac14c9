"""Optimality against independent oracles: exhaustive search (and CP-SAT) on random instances.

The oracles in tests/oracles are written from docs/model.md alone; they share no search code
with the planner. Every plan the planner returns is also replayed by the independent validator.
"""

from __future__ import annotations

import math

import pytest

from hltl.planner import PlanStatus, plan
from hltl.spec.hierarchy import spec_from_dict
from hltl.world.scene import scene_from_dict
from tests.oracles.brute_force import optimal_makespan
from tests.oracles.random_instances import random_instance
from tests.oracles.validator import check_against_optimum, check_plan

SEEDS = range(300)


@pytest.mark.parametrize("seed", SEEDS)
def test_astar_matches_exhaustive_search(seed: int) -> None:
    scene_d, spec_d = random_instance(seed)
    scene = scene_from_dict(scene_d, source=f"random-{seed}")
    spec = spec_from_dict(spec_d)
    expected = optimal_makespan(scene, spec)
    check_against_optimum(scene, spec, plan(scene, spec, timeout=120), expected)


@pytest.mark.parametrize("seed", range(0, 300, 5))
def test_dijkstra_matches_astar(seed: int) -> None:
    scene_d, spec_d = random_instance(seed)
    scene = scene_from_dict(scene_d)
    spec = spec_from_dict(spec_d)
    a = plan(scene, spec, algorithm="astar")
    d = plan(scene, spec, algorithm="dijkstra")
    assert a.status is d.status
    if a.solved:
        assert a.makespan == pytest.approx(d.makespan)
        check_plan(scene, spec, d.to_dict())


@pytest.mark.parametrize("seed", range(0, 300, 3))
def test_pairwise_bound_keeps_astar_exact(seed: int) -> None:
    # the pairwise bound only switches on for hard instances; force it from the first node
    from hltl.planner.problem import Problem
    from hltl.planner.search import search

    scene_d, spec_d = random_instance(seed)
    scene = scene_from_dict(scene_d)
    spec = spec_from_dict(spec_d)
    expected = optimal_makespan(scene, spec)
    res = search(Problem(scene, spec), pairs_after=0)
    if expected is None:
        assert res.status is PlanStatus.INFEASIBLE
    else:
        assert res.makespan is not None
        assert math.isclose(res.makespan, expected, abs_tol=1e-6), (res.makespan, expected)
        check_plan(scene, spec, res.to_dict())


@pytest.mark.parametrize("seed", range(2000, 2030))
def test_pairwise_bound_on_four_robot_instances(seed: int) -> None:
    from hltl.planner.problem import Problem
    from hltl.planner.search import search

    scene_d, spec_d = random_instance(seed, max_robots=4, max_objects=3)
    scene = scene_from_dict(scene_d)
    spec = spec_from_dict(spec_d)
    with_pairs = search(Problem(scene, spec), pairs_after=0)
    dijkstra = search(Problem(scene, spec), algorithm="dijkstra")
    assert with_pairs.status is dijkstra.status
    if dijkstra.solved:
        assert with_pairs.makespan == pytest.approx(dijkstra.makespan)


@pytest.mark.parametrize("seed", range(3000, 3060))
def test_pruned_search_matches_exhaustive_search_with_four_robots(seed: int) -> None:
    # dead-action pruning and the left-shift rule cut most successors on bigger cells: check them
    # where there is room for relays and idle robots
    scene_d, spec_d = random_instance(seed, max_objects=3, robots=4)
    scene = scene_from_dict(scene_d)
    spec = spec_from_dict(spec_d)
    expected = optimal_makespan(scene, spec)
    res = plan(scene, spec, timeout=120)
    if expected is None:
        assert res.status is PlanStatus.INFEASIBLE
        return
    assert res.makespan is not None
    assert math.isclose(res.makespan, expected, abs_tol=1e-6), (res.makespan, expected)
    check_plan(scene, spec, res.to_dict())


@pytest.mark.parametrize(
    ("n", "layout", "seed"),
    [
        (n, layout, seed)
        for n, layout in ((3, "line"), (3, "grid"), (4, "line"), (4, "grid"), (4, "square"))
        for seed in range(5)
    ],
)
def test_pruned_search_matches_exhaustive_search_on_catalogue_cells(
    n: int, layout: str, seed: int
) -> None:
    # generated cells: several deliveries competing for the same robots, relays, orderings
    from hltl.sim.scenarios import generate

    sc = generate(n, n, layout, seed)
    expected = optimal_makespan(sc.scene, sc.spec, max_nodes=1_000_000)
    res = plan(sc.scene, sc.spec, timeout=120)
    assert res.makespan is not None and expected is not None
    assert math.isclose(res.makespan, expected, abs_tol=1e-6), (res.makespan, expected)
    check_plan(sc.scene, sc.spec, res.to_dict())
