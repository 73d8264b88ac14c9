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
from tests.oracles.validator import check_plan

SEEDS = range(300)


@pytest.mark.parametrize("seed", SEEDS)
def test_astar_matches_exhaustive_search(seed: int) -> None:
    scene_d, spec_d = random_instance(seed)
    scene = scene_from_dict(scene_d, source=f"random-{seed}")
    spec = spec_from_dict(spec_d)
    expected = optimal_makespan(scene, spec)
    res = plan(scene, spec, timeout=120)
    if expected is None:
        assert res.status is PlanStatus.INFEASIBLE, res
        assert res.reason
        return
    assert res.status is PlanStatus.SOLVED, res.reason
    assert res.makespan is not None
    assert math.isclose(res.makespan, expected, abs_tol=1e-6), (res.makespan, expected)
    check_plan(scene, spec, res.to_dict())


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
