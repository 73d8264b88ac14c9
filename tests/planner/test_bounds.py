"""The robot-load bound's one-machine relaxation and the commuting-events left-shift."""

from __future__ import annotations

import itertools
import math
import random

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.bench.cells import delivery_cell
from hltl.planner import plan
from hltl.planner.heuristic import _one_machine_bound
from hltl.planner.pairs import PairBound, pair_value
from hltl.planner.problem import Problem, to_seconds, to_ticks
from hltl.planner.search import _Search, search
from hltl.sim.scenarios import generate
from hltl.spec.hierarchy import spec_from_dict
from hltl.world.scene import scene_from_dict
from tests.oracles.brute_force import optimal_makespan
from tests.oracles.random_instances import random_instance
from tests.oracles.validator import check_plan

_job = st.tuples(st.integers(0, 6), st.integers(1, 4), st.integers(0, 6))


def _best_schedule(jobs: list[tuple[int, int, int]]) -> int:
    """One machine, jobs in some order, each started no earlier than its head and followed by
    its tail: the least makespan over every order (waiting never helps beyond the head)."""
    best = math.inf
    for order in itertools.permutations(jobs):
        t = 0
        end = 0
        for hd, v, tl in order:
            t = max(t, hd) + v
            end = max(end, t + tl)
        best = min(best, end)
    return int(best)


@settings(max_examples=150, deadline=None)
@given(st.lists(_job, min_size=1, max_size=5))
def test_one_machine_bound_never_exceeds_the_best_schedule(
    jobs: list[tuple[int, int, int]],
) -> None:
    bound = _one_machine_bound([(float(h), float(v), float(t)) for h, v, t in jobs])
    assert bound <= _best_schedule(jobs)
    # and it is at least the classic all-jobs bound
    assert bound >= min(h for h, _, _ in jobs) + sum(v for _, v, _ in jobs) + min(
        t for _, _, t in jobs
    )


def test_one_machine_bound_sees_a_late_subset() -> None:
    # two jobs free at once, two that only arrive at 5: the late pair alone needs 5 + 2 + 2
    jobs = [(0.0, 1.0, 0.0), (0.0, 1.0, 0.0), (5.0, 2.0, 0.0), (5.0, 2.0, 0.0)]
    assert _one_machine_bound(jobs) == 9.0


def test_events_commute_only_for_conjunctions_of_events() -> None:
    unordered = generate(3, 3, "line", 0, ordered=False)
    assert Problem(unordered.scene, unordered.spec).events_commute
    ordered = generate(3, 3, "line", 0, ordered=True)
    assert not Problem(ordered.scene, ordered.spec).events_commute


@pytest.mark.parametrize(
    ("n", "layout", "seed"),
    [
        (n, layout, seed)
        for n, layout in ((3, "grid"), (4, "line"), (4, "square"))
        for seed in range(3)
    ],
)
def test_commuting_event_cells_match_exhaustive_search(n: int, layout: str, seed: int) -> None:
    # every instance is left-shiftable here (conjunction of deliveries): check the optimum
    sc = generate(n, n, layout, seed, ordered=False)
    assert Problem(sc.scene, sc.spec).events_commute
    expected = optimal_makespan(sc.scene, sc.spec, max_nodes=1_000_000)
    res = plan(sc.scene, sc.spec, timeout=120)
    assert res.makespan is not None and expected is not None
    assert math.isclose(res.makespan, expected, abs_tol=1e-6), (res.makespan, expected)
    check_plan(sc.scene, sc.spec, res.to_dict())


@pytest.mark.parametrize("seed", range(0, 300, 10))
def test_cheap_bound_never_exceeds_the_full_one_or_the_optimum(seed: int) -> None:
    # the search orders fresh nodes by the cheap bound and pops them under the full one: both
    # must be admissible, and the cheap one no larger (else a node could be expanded too early)
    scene_d, spec_d = random_instance(seed)
    scene = scene_from_dict(scene_d)
    spec = spec_from_dict(spec_d)
    expected = optimal_makespan(scene, spec)
    s = _Search(Problem(scene, spec))
    s.heuristic.enable_pairs()
    start = s.p.start()
    nodes = [start] + [child for *_, child, _, _ in s.steps(start)]
    for node in nodes:
        cheap, full = s.heuristic.cheap(node), s.heuristic(node)
        assert cheap <= full
    if expected is not None:
        assert to_seconds(s.heuristic(start)) <= expected + 1e-9


@pytest.mark.parametrize(("layout", "seed"), [("line", 0), ("line", 3), ("grid", 1)])
def test_cheap_bound_with_the_parents_hot_parts_stays_below_the_full_one(
    layout: str, seed: int
) -> None:
    # the search passes each expanded node's ``hot`` (its two most loaded robots and its
    # largest pair) to the cheap bound of its children: on every child of a random walk that
    # bound must stay at or below the full value, computed by a heuristic of its own
    sc = generate(5, 5, layout, seed, ordered=False)
    problem = Problem(sc.scene, sc.spec)
    s, ref = _Search(problem), _Search(problem)
    s.heuristic.enable_pairs()
    ref.heuristic.enable_pairs()
    rng = random.Random(seed)
    node = problem.start()
    checked = raised = 0
    for _ in range(30):
        s.heuristic(node)
        hot = s.heuristic.hot(node)
        alive = []
        for _, _, child, _, _ in s.steps(node):
            cheap, full = s.heuristic.cheap(child, hot), ref.heuristic(child)
            assert cheap <= full
            raised += cheap > ref.heuristic._critical(child[0], child[2])
            checked += 1
            if not math.isinf(full):
                alive.append(child)
        if not alive:
            break
        node = rng.choice(alive)
    # not vacuous: the parent's parts raise the cheap bound above the critical path
    assert checked > 50 and raised > 0


@pytest.mark.parametrize(("layout", "seed"), [("grid", 0), ("line", 1), ("grid", 2)])
def test_conjunction_critical_path_equals_the_general_one(layout: str, seed: int) -> None:
    # delivery cells take the short way (largest table value over the open leaves): it must
    # give what the general bottom-up evaluation gives on every node of a random walk
    sc = generate(5, 5, layout, seed, ordered=False)
    s = _Search(Problem(sc.scene, sc.spec))
    heur = s.heuristic
    assert heur._conj is not None
    rng = random.Random(seed)
    node = s.p.start()
    checked = 0
    for _ in range(40):
        children = [child for _, _, child, _, _ in s.steps(node)]
        if not children:
            break
        for child in children[:15]:
            fast = heur._critical(child[0], child[2])
            conj, heur._conj = heur._conj, None
            try:
                general = heur._critical(child[0], child[2])
            finally:
                heur._conj = conj
            assert fast == general
            checked += 1
        node = rng.choice(children)
    assert checked > 100
    ordered = generate(3, 3, "line", 0, ordered=True)
    assert _Search(Problem(ordered.scene, ordered.spec)).heuristic._conj is None


@pytest.mark.parametrize("layout", ["line", "grid", "random"])
@pytest.mark.parametrize("seed", range(3))
def test_a_pair_table_of_a_two_delivery_cell_is_its_optimum(layout: str, seed: int) -> None:
    # with only two objects the pair's subproblem is the whole problem: the table at the start
    # is A*'s optimum (a table too weak, e.g. one that drops a flag combination, is caught)
    c = delivery_cell(layout, 2, seed)
    problem = Problem(c.scene, c.spec)
    s = _Search(problem)
    start = problem.start()
    atoms = sorted(s.heuristic.required_atoms(start[2]))
    lks = PairBound(problem, s.heuristic.graph).lookups(atoms)
    expected = search(Problem(c.scene, c.spec), algorithm="dijkstra", timeout=60)
    assert len(lks) == 1 and expected.makespan is not None
    assert pair_value(lks[0], start[0]) == to_ticks(expected.makespan)
