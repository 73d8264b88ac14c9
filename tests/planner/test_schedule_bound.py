"""The relaxed-schedule bound never exceeds the true optimum (brute-force oracle), and is tight
where the heuristic is not."""

from __future__ import annotations

import math
import time

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from hltl.bench.cells import Cell, delivery_cell
from hltl.errors import HltlError
from hltl.planner import PlanResult, PlanStatus, SearchStats, plan, schedule
from hltl.planner.anytime import replay
from hltl.planner.problem import Node, Problem, to_seconds, to_ticks
from hltl.planner.search import _Search, plan_steps
from hltl.spec.hierarchy import spec_from_dict
from hltl.world.scene import scene_from_dict
from tests.oracles.brute_force import optimal_makespan
from tests.oracles.cpsat import cpsat_makespan
from tests.oracles.random_instances import random_instance
from tests.oracles.validator import check_plan
from tests.planner import test_symmetry as twins
from tests.planner.start import start_targets, step_levels

pytest.importorskip("ortools")

# generous: under load CP-SAT may need it; running out only lowers the bound
DEADLINE_S = 60.0


def _bound_and_optimum(
    seed: int, robots: int = 3, objects: int = 3, *, steps: bool = False
) -> tuple[int, float, float | None] | None:
    """(bound in ticks, start heuristic in ticks, oracle optimum in s); None when the instance
    is outside the bound's class or has no event goal. ``steps``: the step-indexed bound."""
    scene_d, spec_d = random_instance(seed, max_robots=robots, max_objects=objects)
    try:
        scene, spec = scene_from_dict(scene_d), spec_from_dict(spec_d)
    except HltlError:
        return None  # the generator's rare spec with an unreachable formula
    problem = Problem(scene, spec)
    if not (schedule.steps_applicable(problem) if steps else schedule.applicable(problem)):
        return None
    s = _Search(problem)
    node = problem.start()
    h0 = s.heuristic(node)
    if math.isinf(h0):
        return None
    tgts = schedule.targets(problem, s.heuristic.graph, node, s.heuristic.required_atoms(node[2]))
    if not tgts:
        return None
    res = schedule.schedule_bound(
        problem,
        s.heuristic.graph,
        node,
        tgts,
        floor=0,
        upper=None,
        deadline=time.perf_counter() + DEADLINE_S,
        steps=steps,
    )
    return res.ticks, h0, optimal_makespan(scene, spec)


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.integers(0, 10**6))
def test_bound_never_exceeds_the_optimum(seed: int) -> None:
    got = _bound_and_optimum(seed)
    if got is None:
        return
    ticks, _, optimum = got
    assert optimum is not None  # a finite heuristic: the instance is feasible
    assert ticks <= to_ticks(optimum)


@pytest.mark.parametrize("steps", [False, True])
@pytest.mark.parametrize("seed", range(1000, 1040))
def test_bound_never_exceeds_the_optimum_with_four_robots(seed: int, steps: bool) -> None:
    got = _bound_and_optimum(seed, robots=4, objects=4, steps=steps)
    if got is None:
        return
    ticks, _, optimum = got
    assert optimum is not None
    assert ticks <= to_ticks(optimum)


# instances where the start heuristic is far below the optimum (e.g. 1.1 s against 2.2 s: one
# robot must carry two objects one after the other) and the relaxed schedule sees it
@pytest.mark.parametrize("steps", [False, True])
@pytest.mark.parametrize("seed", [28, 71, 105, 259, 291])
def test_bound_is_tight_where_the_heuristic_is_not(seed: int, steps: bool) -> None:
    got = _bound_and_optimum(seed, steps=steps)
    assert got is not None
    ticks, h0, optimum = got
    assert optimum is not None
    assert h0 < to_ticks(optimum)
    assert to_seconds(ticks) == pytest.approx(optimum)


def test_cells_with_other_skills_are_outside_the_class() -> None:
    # analytic durations depend on hand poses: the relaxation's fixed intervals do not apply
    scene_d, spec_d = random_instance(3)
    del scene_d["durations"]
    problem = Problem(scene_from_dict(scene_d), spec_from_dict(spec_d))
    assert not schedule.applicable(problem)


# -- the step-indexed bound (docs/planner.md, "Step bound") --------------------------------------


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.integers(0, 10**6))
def test_step_bound_never_exceeds_the_optimum(seed: int) -> None:
    got = _bound_and_optimum(seed, steps=True)
    if got is None:
        return
    ticks, _, optimum = got
    assert optimum is not None
    assert ticks <= to_ticks(optimum)


def _cell_bounds(layout: str, n: int, seed: int) -> tuple[Problem, int, int, int]:
    """(problem, unit, interval bound, step bound) at the start of a delivery cell."""
    c = delivery_cell(layout, n, seed)
    problem = Problem(c.scene, c.spec)
    s = _Search(problem)
    node = problem.start()
    tgts = schedule.targets(problem, s.heuristic.graph, node, s.heuristic.required_atoms(node[2]))
    deadline = time.perf_counter() + DEADLINE_S
    h0 = round(s.heuristic(node))
    by = [
        schedule.schedule_bound(
            problem,
            s.heuristic.graph,
            node,
            tgts,
            floor=h0,
            upper=None,
            deadline=deadline,
            steps=steps,
        )
        for steps in (False, True)
    ]
    assert all(b.solved for b in by)  # else the machine is too slow for DEADLINE_S
    return problem, schedule.time_unit(problem), by[0].ticks, by[1].ticks


def test_step_bound_sees_that_a_step_lasts_its_longest_instance() -> None:
    # a 4-robot grid cell whose optimum (3.3 s, by the independent CP-SAT oracle) needs a 0.5 s
    # action to share a step with a 0.6 s handover: intervals of their own durations give 3.2 s
    c = delivery_cell("grid", 4, 1)
    optimum = cpsat_makespan(c.scene, c.spec, time_limit=DEADLINE_S)
    assert optimum is not None
    _, _, by_intervals, by_steps = _cell_bounds("grid", 4, 1)
    assert by_intervals < to_ticks(optimum)
    assert by_steps == to_ticks(optimum)


def test_step_bound_sees_where_a_loop_takes_the_object() -> None:
    # a 4-robot random cell whose optimum is 4.5 s (the independent CP-SAT oracle): a split
    # session that parks its object for free (no holder in between, the loop's steps as short
    # as any) let the step bound stop at 4.4 s (session 8's model). Both the full model (the
    # holder, the loop's step lengths) and, since session 12, the counting rows (the loop's
    # two instances fill steps of the robot's own, and count in its load) rule that out
    c = delivery_cell("random", 4, 1)
    optimum = cpsat_makespan(c.scene, c.spec, time_limit=DEADLINE_S)
    assert optimum is not None
    problem, unit, _, by_steps = _cell_bounds("random", 4, 1)
    assert by_steps == to_ticks(optimum)
    # one unit below it, neither model finds a schedule
    _, node, graph, tgts = start_targets(problem)
    below = by_steps // unit - 1
    deadline = time.perf_counter() + DEADLINE_S
    weak = schedule.relaxed_steps(problem, graph, node, tgts, below, deadline, holders=False)
    assert weak is False
    assert schedule.relaxed_steps(problem, graph, node, tgts, below, deadline) is False


def _at_start(
    layout: str, n: int, seed: int
) -> tuple[Cell, Problem, _Search, Node, list[schedule.Target]]:
    """A delivery cell, its problem, a search on it, the start node and the targets there."""
    c = delivery_cell(layout, n, seed)
    problem = Problem(c.scene, c.spec)
    s = _Search(problem)
    node = problem.start()
    tgts = schedule.targets(problem, s.heuristic.graph, node, s.heuristic.required_atoms(node[2]))
    return c, problem, s, node, tgts


@pytest.mark.parametrize(("layout", "n", "seed"), [("grid", 4, 1), ("grid", 5, 0), ("grid", 3, 0)])
def test_relaxed_steps_at_the_bound_are_an_optimal_plan(layout: str, n: int, seed: int) -> None:
    # where the relaxation is tight its schedule (sessions whole) is a plan: the independent
    # validator accepts it, and its makespan is the bound, so it is optimal
    c, problem, s, node, tgts = _at_start(layout, n, seed)
    graph = s.heuristic.graph
    bound = schedule.schedule_bound(
        problem,
        graph,
        node,
        tgts,
        floor=round(s.heuristic(node)),
        upper=None,
        deadline=time.perf_counter() + DEADLINE_S,
        steps=True,
    )
    level = bound.ticks // schedule.time_unit(problem)
    got = schedule.relaxed_steps(
        problem, graph, node, tgts, level, time.perf_counter() + DEADLINE_S, whole=True
    )
    assert isinstance(got, tuple)
    found = replay(s, node, got)
    assert found is not None
    assert found[0] == bound.ticks
    result = PlanResult(
        PlanStatus.SOLVED,
        plan_steps(problem, found[1]),
        to_seconds(found[0]),
        SearchStats(0, 0, 0.0, "astar"),
        "",
        to_seconds(bound.ticks),
    )
    check_plan(c.scene, c.spec, result.to_dict())
    assert result.makespan == pytest.approx(plan(c.scene, c.spec, timeout=DEADLINE_S).makespan)


# -- twins in the relaxation (docs/planner.md, "Twins in the relaxation") ------------------------


def _twin_bounds(seed: int) -> tuple[int, int, float, int] | None:
    """(step bound with the twins' order, without it, oracle optimum, twin pairs) on the
    symmetry tests' instance ``seed`` (objects cloned beside their originals); None outside
    the step bound's class."""
    scene_d, spec_d = twins.twins_instance(seed)
    scene, spec = scene_from_dict(scene_d), spec_from_dict(spec_d)
    problem = Problem(scene, spec)
    if not schedule.steps_applicable(problem):
        return None
    s, node, graph, tgts = start_targets(problem)
    h0 = s.heuristic(node)
    if math.isinf(h0):
        return None
    pairs = schedule.twin_pairs(problem, tgts, node[0])

    def bound() -> int:
        res = schedule.schedule_bound(
            problem,
            graph,
            node,
            tgts,
            floor=0,
            upper=None,
            deadline=time.perf_counter() + DEADLINE_S,
            steps=True,
        )
        assert res.solved  # else the machine is too slow for DEADLINE_S
        return res.ticks

    ordered = bound()
    real = schedule.twin_pairs
    try:
        schedule.twin_pairs = lambda *_: []
        plain = bound()
    finally:
        schedule.twin_pairs = real
    optimum = optimal_makespan(scene, spec, max_nodes=1_000_000)
    assert optimum is not None  # a finite heuristic: the instance is feasible
    return ordered, plain, optimum, len(pairs)


def test_twin_order_keeps_the_step_bound() -> None:
    # swapping two twins maps relaxed schedules onto relaxed schedules, so "the first twin's
    # atom happens no later than the second's" changes no level's answer: the bound with the
    # order equals the bound without it, and stays at most the exhaustive search's optimum
    with_pairs = 0
    for seed in range(16):
        got = _twin_bounds(seed)
        if got is None:
            continue
        ordered, plain, optimum, pairs = got
        assert ordered == plain
        assert ordered <= to_ticks(optimum)
        with_pairs += pairs > 0
    assert with_pairs >= 8  # the check is only worth something where there are twins


def test_an_order_between_objects_that_are_not_twins_can_raise_the_bound() -> None:
    # the mutation check of the test above: on a 4-robot grid cell (no twins; step bound and
    # optimum 3.3 s), making target 0's atom happen no later than target 2's leaves no relaxed
    # schedule at 3.3 s, so an order the symmetry does not allow would show up there
    c = delivery_cell("grid", 4, 0)
    problem = Problem(c.scene, c.spec)
    _, node, graph, tgts = start_targets(problem)
    assert schedule.twin_pairs(problem, tgts, node[0]) == []
    level = to_ticks(3.3) // schedule.time_unit(problem)
    deadline = time.perf_counter() + DEADLINE_S
    assert isinstance(schedule.relaxed_steps(problem, graph, node, tgts, level, deadline), tuple)
    real = schedule.twin_pairs
    try:
        schedule.twin_pairs = lambda *_: [(0, 2)]
        got = schedule.relaxed_steps(problem, graph, node, tgts, level, deadline)
    finally:
        schedule.twin_pairs = real
    assert got is False


@pytest.mark.parametrize(("layout", "n", "seed"), [("grid", 4, 1), ("grid", 3, 4), ("grid", 5, 4)])
@pytest.mark.parametrize("upper", [None, 31, 60])
def test_skipping_levels_finds_the_same_bound(
    layout: str, n: int, seed: int, upper: int | None, monkeypatch: pytest.MonkeyPatch
) -> None:
    # the climb skips up to MAX_SKIP levels while "no"s are cheap; from a floor of 0 every cell
    # here is skipped past its optimum, so the levels below the schedule found must be asked
    # again (a mutation: returning the first schedule found reports a higher bound)
    _, problem, s, node, tgts = _at_start(layout, n, seed)
    graph = s.heuristic.graph
    got: dict[float, tuple[int, bool]] = {}
    asked: dict[float, list[int]] = {}
    real = schedule.relaxed_steps
    for cheap in (0.0, math.inf):  # never skip, skip whenever it can
        monkeypatch.setattr(schedule, "CHEAP_NO", cheap)
        levels: list[int] = []

        def logged(*args: object, levels: list[int] = levels, **kwargs: object) -> object:
            level = args[4]
            assert isinstance(level, int)
            levels.append(level)
            return real(*args, **kwargs)  # type: ignore[arg-type]

        monkeypatch.setattr(schedule, "relaxed_steps", logged)
        unit = schedule.time_unit(problem)
        # the cheaper model's climb (with a plan's makespan as ``upper`` too)
        res = schedule._shave(
            problem,
            graph,
            node,
            tgts,
            0,
            None if upper is None else upper * unit,
            time.perf_counter() + DEADLINE_S,
            0,
            0,
            True,
            True,
        )
        got[cheap] = (res.ticks, res.solved)
        asked[cheap] = levels
    assert got[0.0] == got[math.inf]
    assert len(asked[math.inf]) < len(asked[0.0])
    best = got[0.0][0] // schedule.time_unit(problem)
    if upper is None or upper > best:
        assert max(asked[math.inf]) > best  # it went past the optimum and came back
    else:
        assert not got[0.0][1] or got[0.0][0] == upper * schedule.time_unit(problem)


def test_a_skipping_round_asks_levels_as_far_apart_as_the_skip(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # grid 4 seed 1 from 0, skipping whenever it can: the first round asks 0 and 1, the next
    # (a skip of 2) 3 and 5, the next (4) 9 and 13, not the levels just above the first
    # (docs/planner.md, "Rounds as far apart as the skip"); the bound is the same
    if schedule.WORKERS < 2:
        pytest.skip("needs two cores (two levels asked at once)")
    _, problem, s, node, tgts = _at_start("grid", 4, 1)
    monkeypatch.setattr(schedule, "CHEAP_NO", math.inf)
    levels = step_levels(monkeypatch)
    graph = s.heuristic.graph
    deadline = time.perf_counter() + DEADLINE_S
    res = schedule._shave(problem, graph, node, tgts, 0, None, deadline, 0, 0, True, True)
    assert res.ticks == 33 * schedule.time_unit(problem)
    assert {0, 1, 3, 5, 9, 13} <= set(levels)
    assert not {2, 4, 10, 14} & set(levels)


@pytest.mark.parametrize(("roof", "below"), [(33, False), (36, True), (42, True)])
def test_a_roof_first_asks_the_levels_just_below_it(
    roof: int, below: bool, monkeypatch: pytest.MonkeyPatch
) -> None:
    # grid 4 seed 1, whose cheaper model's optimum is 33 units, from level 25. A roof (a plan's
    # makespan) at 33: the first round asks 31 and 32, whose "no" proves it, and no level below
    # them is asked (the bound is the roof, with no schedule). At 36 and 42: 34 and 35, 40 and
    # 41 have schedules, and the climb goes on from 25 to the same bound and schedule as
    # without a roof (docs/planner.md, "The step model's roof")
    if schedule.WORKERS < 2:
        pytest.skip("needs two cores (two levels asked at once)")
    _, problem, s, node, tgts = _at_start("grid", 4, 1)
    unit = schedule.time_unit(problem)
    graph = s.heuristic.graph

    def climb(upper: int | None, descend: bool) -> tuple[schedule.ScheduleBound, list[int]]:
        monkeypatch.undo()
        levels = step_levels(monkeypatch)
        deadline = time.perf_counter() + DEADLINE_S
        res = schedule._shave(
            problem,
            graph,
            node,
            tgts,
            25,
            None if upper is None else upper * unit,
            deadline,
            0,
            0,
            True,
            True,
            descend=descend,
        )
        return res, levels

    plain, plain_levels = climb(None, False)
    assert plain.ticks == 33 * unit and plain.steps is not None
    res, levels = climb(roof, True)
    assert {roof - 2, roof - 1} <= set(levels)
    assert res.ticks == 33 * unit
    if below:
        assert res.steps == plain.steps  # (one worker, a fixed seed at a fixed level)
        assert 25 in levels
    else:
        assert res.steps is None and res.solved
        assert set(levels) == {31, 32}
        assert 25 in plain_levels  # (without a roof the climb starts at the floor)


@pytest.mark.parametrize(
    ("layout", "n", "seed"), [("grid", 4, 1), ("random", 4, 1), ("line", 4, 0)]
)
@pytest.mark.parametrize("weak", [True, False])
def test_asking_two_levels_at_once_changes_no_answer(
    layout: str, n: int, seed: int, weak: bool, monkeypatch: pytest.MonkeyPatch
) -> None:
    # the climb asks WORKERS levels at once and stops a question whose answer another one
    # implies: the bound, whether it is solved, and the schedule at the bound are those of
    # asking one level at a time (and of asking at once again)
    _, problem, s, node, tgts = _at_start(layout, n, seed)
    graph = s.heuristic.graph
    # a few levels below the start bound, so that the climbs ask several rounds
    level = max(0, round(s.heuristic(node)) // schedule.time_unit(problem) - 4)
    got: dict[tuple[int, bool, int], schedule.ScheduleBound] = {}
    for workers, run in ((1, 0), (2, 0), (2, 1)):
        monkeypatch.setattr(schedule, "WORKERS", workers)
        for whole_first in (False, True) if not weak else (False,):
            got[workers, whole_first, run] = schedule._shave(
                problem,
                graph,
                node,
                tgts,
                level,
                None,
                time.perf_counter() + DEADLINE_S,
                0,
                0,
                True,
                weak,
                whole_first,
            )
    for (_, whole_first, _), res in got.items():
        assert res == got[1, whole_first, 0]
        assert res.solved and res.steps is not None


def test_the_climb_says_how_many_questions_it_asks_at_once(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # exact mode's A* process (phase._Apart) is paused through the climb's rounds that ask
    # a level on every core: the climb tells how many a round asks (2), how many are still
    # running as its questions end, and 0 when it ends
    from hltl.planner import lns

    _, problem, s, node, tgts = _at_start("grid", 4, 1)
    level = max(0, round(s.heuristic(node)) // schedule.time_unit(problem) - 4)
    monkeypatch.setattr(schedule, "WORKERS", 2)
    seen: list[int] = []
    lns.share_busy(seen.append)
    try:
        res = schedule._shave(
            problem,
            s.heuristic.graph,
            node,
            tgts,
            level,
            None,
            time.perf_counter() + DEADLINE_S,
            0,
            0,
            True,
            True,
        )
    finally:
        lns.share_busy(None)
    assert res.solved
    assert seen[-1] == 0 and max(seen) == 2
    rounds: list[list[int]] = [[]]  # what each round told before its end
    for told in seen:
        if told:
            rounds[-1].append(told)
        else:
            rounds.append([])
    assert rounds.pop() == []
    assert len(rounds) >= 2
    # a round begins with its questions, then fewer are left
    assert all(r and r == sorted(r, reverse=True) and len(set(r)) == len(r) for r in rounds)
