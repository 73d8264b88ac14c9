"""The profile bound (docs/planner.md, "Profile bound") never exceeds the true optimum
(brute-force oracle, exact search), and sees step synchrony where the heuristic does not."""

from __future__ import annotations

import itertools
import math
import os
import time
from pathlib import Path
from typing import Any

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from hltl.bench.cells import delivery_cell
from hltl.errors import HltlError
from hltl.planner import WALL, Clock, PlanStatus, WorkClock, anytime, lns, plan, profile, schedule
from hltl.planner.problem import Problem, to_seconds, to_ticks
from hltl.planner.schedule import time_unit
from hltl.spec.hierarchy import HSpec, spec_from_dict
from hltl.world.scene import Scene, scene_from_dict
from tests.oracles.brute_force import optimal_makespan
from tests.oracles.random_instances import random_instance
from tests.planner.start import start_targets

pytest.importorskip("ortools")

# generous: under load CP-SAT may need it; running out only lowers the bound
DEADLINE_S = 60.0


def _bound(scene: Scene, spec: HSpec) -> tuple[int, float, bool] | None:
    """(profile bound in ticks, start heuristic in ticks, relaxation solved there) from the
    start of ``scene``; None outside the bound's class or without an event goal."""
    problem = Problem(scene, spec)
    if not profile.applicable(problem):
        return None
    s, node, graph, tgts = start_targets(problem)
    h0 = s.heuristic(node)
    if math.isinf(h0):
        return None
    if not tgts:
        return None
    res = profile.profile_bound(
        problem,
        graph,
        node,
        tgts,
        floor=0,
        upper=None,
        deadline=time.perf_counter() + DEADLINE_S,
    )
    return res.ticks, h0, res.solved


def _random(seed: int, robots: int = 3, objects: int = 3) -> tuple[Scene, HSpec] | None:
    scene_d, spec_d = random_instance(seed, max_robots=robots, max_objects=objects)
    try:
        return scene_from_dict(scene_d), spec_from_dict(spec_d)
    except HltlError:
        return None  # the generator's rare spec with an unreachable formula


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.integers(0, 10**6))
def test_profile_bound_never_exceeds_the_optimum(seed: int) -> None:
    inst = _random(seed)
    if inst is None:
        return
    got = _bound(*inst)
    if got is None:
        return
    ticks, _, _ = got
    optimum = optimal_makespan(*inst)
    assert optimum is not None  # a finite heuristic: the instance is feasible
    assert ticks <= to_ticks(optimum)


@pytest.mark.parametrize("seed", range(1000, 1020))
def test_profile_bound_never_exceeds_the_optimum_with_four_robots(seed: int) -> None:
    inst = _random(seed, robots=4, objects=4)
    if inst is None:
        return
    got = _bound(*inst)
    if got is None:
        return
    optimum = optimal_makespan(*inst)
    assert optimum is not None
    assert got[0] <= to_ticks(optimum)


# instances where the start heuristic is far below the optimum (1.1 s against 2.2 s, 0.8 against
# 1.6 s: one robot must do the work of two objects one after the other, and before its first
# instance and after its last the objects need steps of their own) and the bound reaches it
@pytest.mark.parametrize("seed", [28, 66, 91])
def test_profile_bound_is_tight_where_the_heuristic_is_not(seed: int) -> None:
    inst = _random(seed)
    assert inst is not None
    got = _bound(*inst)
    assert got is not None
    ticks, h0, solved = got
    optimum = optimal_makespan(*inst)
    assert optimum is not None
    assert h0 < to_ticks(optimum)
    assert solved
    assert to_seconds(ticks) == pytest.approx(optimum)


# small delivery cells: the bound against the exact search's optimum (grid 4 seed 1 and grid 5
# seed 0: a 0.5 s pick that shares a step with a 0.6 s handover costs 0.6 s, which the start
# heuristic does not see and the duration levels do: 3.2 -> 3.3 s and 5.3 -> 5.4 s, both optimal)
@pytest.mark.parametrize(
    ("layout", "n", "seed", "above_start"),
    [
        ("grid", 4, 1, True),
        ("grid", 5, 0, True),
        ("grid", 6, 2, True),
        ("random", 4, 0, True),
        ("random", 5, 0, False),
        ("line", 4, 3, True),
        ("line", 6, 0, False),
    ],
)
def test_profile_bound_on_small_cells(layout: str, n: int, seed: int, above_start: bool) -> None:
    c = delivery_cell(layout, n, seed)
    got = _bound(c.scene, c.spec)
    assert got is not None
    ticks, h0, solved = got
    assert solved  # else the machine is too slow for DEADLINE_S
    exact = plan(c.scene, c.spec, timeout=DEADLINE_S)
    assert exact.status is PlanStatus.SOLVED and exact.makespan is not None
    assert ticks <= to_ticks(exact.makespan)
    assert (ticks > h0) is above_start


def test_a_level_the_relaxation_rules_out_has_no_plan() -> None:
    # grid 4 seed 1: "no" at 3.2 s (every plan is longer), "yes" at 3.3 s (the optimum, whose
    # plan is a relaxed solution); a level is asked at a whole number of time units
    c = delivery_cell("grid", 4, 1)
    problem = Problem(c.scene, c.spec)
    _, node, graph, tgts = start_targets(problem)
    deadline = time.perf_counter() + DEADLINE_S
    assert profile.feasible(problem, graph, node, tgts, to_ticks(3.2), deadline) is False
    assert profile.feasible(problem, graph, node, tgts, to_ticks(3.3), deadline) is True
    exact = plan(c.scene, c.spec, timeout=DEADLINE_S)
    assert exact.makespan == pytest.approx(3.3)


@pytest.mark.parametrize(
    ("layout", "n", "seed"), [("grid", 4, 1), ("grid", 5, 0), ("random", 4, 0)]
)
def test_presolve_changes_how_fast_not_what_a_level_answers(layout: str, n: int, seed: int) -> None:
    # the questions are asked without CP-SAT's presolve (session 16: the hard "no"s near the
    # bound take 2-7 times less CPU): a solver setting, so at the bound and one unit below it
    # the answers are those with presolve, and "no" below, "yes" at the relaxation's optimum
    c = delivery_cell(layout, n, seed)
    problem = Problem(c.scene, c.spec)
    _, node, graph, tgts = start_targets(problem)
    got = _bound(c.scene, c.spec)
    assert got is not None and got[2]  # solved: "yes" at got[0], "no" one unit below
    unit = time_unit(problem)
    for level, expected in ((got[0] - unit, False), (got[0], True)):
        for presolve in (False, True):
            deadline = time.perf_counter() + DEADLINE_S
            answer = profile.feasible(
                problem, graph, node, tgts, level, deadline, presolve=presolve
            )
            assert answer is expected, (level, presolve)


def test_cells_without_fixed_durations_are_outside_the_class() -> None:
    # analytic durations depend on hand poses: a step's length is not one of a few levels
    scene_d, spec_d = random_instance(3)
    del scene_d["durations"]
    problem = Problem(scene_from_dict(scene_d), spec_from_dict(spec_d))
    assert not profile.applicable(problem)


# the anytime runs below: a 4 s budget on a clock that advances 0.02 s at each reading (a
# round of the walk, a repair move, a pair: docs/planner.md, "The clock"), so each phase ends
# after the same work on a fast machine and a loaded one. CP-SAT and HiGHS keep wall time:
# ``wall_seconds`` is what the profile bound gets (0: nothing, it proves no more than its floor)
BUDGET_S = 4.0
STEP_S = 0.02


def test_anytime_gives_its_last_share_to_the_profile_bound(monkeypatch: pytest.MonkeyPatch) -> None:
    # a 17-goal grid cell (more goals than the step bound takes, no pair above the start bound),
    # on one core: the walk stops at 70 % of the budget, then the profile bound runs once, from
    # the bound known so far up to the best plan, and the bound reported is at least what it
    # proved. (Given time, CP-SAT's climb here takes 10-20 s under load: it gets none, and
    # proves its floor)
    clock = WorkClock(STEP_S)
    calls: list[tuple[int, int | None, int, float]] = []
    real = profile.profile_bound
    walks: list[float] = []
    real_more = anytime._more

    def spy(*args: object, **kwargs: object) -> profile.ProfileBound:
        at = clock.t  # (where on the run's clock it is asked)
        got = real(*args, **kwargs)  # type: ignore[arg-type]
        floor, upper = kwargs["floor"], kwargs["upper"]
        assert isinstance(floor, int) and (upper is None or isinstance(upper, int))
        calls.append((floor, upper, got.ticks, at))
        return got

    def more(problem: Problem, s: object, until: float, **kwargs: Any) -> object:
        walks.append(until)
        return real_more(problem, s, until, **kwargs)  # type: ignore[arg-type]

    monkeypatch.setattr(profile, "profile_bound", spy)
    monkeypatch.setattr(anytime, "_more", more)
    # a share of 4 s long enough for the profile bound (10 s budgets give it 1 s), on one core
    # (on two it runs beside the walk: the next tests)
    monkeypatch.setattr(anytime, "PROFILE_SHARE", 0.3)
    monkeypatch.setattr(schedule, "WORKERS", 1)
    c = delivery_cell("grid", 17, 0)
    res = plan(c.scene, c.spec, anytime=True, timeout=BUDGET_S, clock=clock)
    assert res.status is PlanStatus.SOLVED and res.makespan is not None
    assert walks == [pytest.approx(0.7 * BUDGET_S)]  # (the run starts at 0 on this clock)
    assert len(calls) == 1
    floor, upper, ticks, at = calls[0]
    assert walks[0] <= at < BUDGET_S  # (after the walk's share, before the deadline)
    assert upper is not None and floor <= ticks <= upper
    assert res.lower_bound is not None
    assert to_ticks(res.lower_bound) >= ticks


def test_a_ten_second_budget_gives_the_profile_bound_its_share() -> None:
    # 1.0 - 0.9 is 0.09999999999999998: compared as floats, 10 s budgets gave the profile bound
    # nothing, and the benchmark's 10 s runs never asked it (sessions 12-13)
    assert anytime.PROFILE_SHARE * 10.0 < anytime.PROFILE_MIN_SECONDS  # the trap is real
    assert anytime._profile_fits(10.0)
    assert anytime._profile_fits(30.0)
    assert not anytime._profile_fits(9.0)
    assert not anytime._profile_fits(1.0)


def test_building_the_model_stops_at_the_deadline(monkeypatch: pytest.MonkeyPatch) -> None:
    # building a 32-goal model takes 0.3-0.5 s of CPU: past the deadline it is not built (the
    # 10 s anytime runs' last question ran over the budget by that much)
    c = delivery_cell("grid", 4, 1)
    problem = Problem(c.scene, c.spec)
    _, node, graph, tgts = start_targets(problem)
    rows: list[object] = []
    real = profile._robot_rows
    monkeypatch.setattr(profile, "_robot_rows", lambda *a: rows.append(a) or real(*a))
    level = to_ticks(3.3)
    assert profile.feasible(problem, graph, node, tgts, level, time.perf_counter() - 1) is None
    assert rows == []
    answer = profile.feasible(problem, graph, node, tgts, level, time.perf_counter() + DEADLINE_S)
    assert answer is True and rows  # (the spy is wired: with time left the rows are built)


def test_cells_beyond_the_step_bound_skip_importing_cp_sat(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # 17 goals: the step bound does not apply, so it must not pay CP-SAT's import (0.5-1.5 s),
    # which a 32-robot line (that never uses CP-SAT) would take from its plans
    def no_import() -> bool:
        raise AssertionError("CP-SAT asked for")

    monkeypatch.setattr(lns, "available", no_import)
    c = delivery_cell("grid", 17, 0)
    problem = Problem(c.scene, c.spec)
    s, node, _, tgts = start_targets(problem)
    assert len(tgts) > anytime.SCHEDULE_UP_TO
    floor = round(s.heuristic(node))
    assert anytime.step_bound(problem, s, node, floor, None, time.perf_counter() + 5) == (
        floor,
        None,
    )


def test_each_level_proved_is_told_as_it_is_proved() -> None:
    # the process beside the walk sends these, so that stopping it loses nothing proved: they
    # rise, and the last is the bound (grid 4 x 4 seed 1: 3.3 s, the exact optimum)
    c = delivery_cell("grid", 4, 1)
    problem = Problem(c.scene, c.spec)
    _, node, graph, tgts = start_targets(problem)
    told: list[int] = []
    got = profile.profile_bound(
        problem,
        graph,
        node,
        tgts,
        floor=to_ticks(3.0),
        upper=None,
        deadline=time.perf_counter() + DEADLINE_S,
        on_proven=told.append,
    )
    assert got.ticks == to_ticks(3.3)
    assert told and told == sorted(told) and told[-1] == got.ticks


def test_the_climb_skips_at_most_max_stride_levels(monkeypatch: pytest.MonkeyPatch) -> None:
    # from a floor of 0 the climb gallops up to grid 4 x 4 seed 1's 3.3 s: the strides double
    # to MAX_STRIDE and no further (a relaxed solution far up is dear without presolve), and
    # the bound is the same as one level at a time would give
    c = delivery_cell("grid", 4, 1)
    problem = Problem(c.scene, c.spec)
    _, node, graph, tgts = start_targets(problem)
    asked: list[int] = []
    real = profile.feasible

    def spy(*args: Any, **kwargs: Any) -> bool | None:
        asked.append(args[4])
        return real(*args, **kwargs)

    monkeypatch.setattr(profile, "feasible", spy)
    got = profile.profile_bound(
        problem, graph, node, tgts, floor=0, upper=None, deadline=time.perf_counter() + DEADLINE_S
    )
    assert got.ticks == to_ticks(3.3) and got.solved
    unit = time_unit(problem)
    steps = [(b - a) // unit for a, b in itertools.pairwise(asked) if b > a]
    assert steps[:3] == [2, 4, 4]  # (from 0: "no"s far below the bound)
    assert max(steps) == profile.MAX_STRIDE


def _beside(floor: float, deadline: float, clock: Clock = WALL) -> anytime._ProfileBeside:
    c = delivery_cell("grid", 4, 1)
    problem = Problem(c.scene, c.spec)
    s, node, _, _ = start_targets(problem)
    return anytime._ProfileBeside(
        problem, s, node, to_ticks(floor), to_ticks(4.0), deadline, clock=clock
    )


@pytest.mark.skipif(not anytime.beside_possible(), reason="one core, or no fork")
def test_the_bound_beside_the_walk_is_what_the_bound_proves() -> None:
    # its bound final, the process waits for the walk's plans until its deadline (none come
    # here): on the wall clock that was the whole 60 s; on a clock of 0.1 s a reading (one
    # look for news, then 0.02 s of sleep) a deadline of 1 s is ten looks. The bound itself,
    # and the wait for the process, get up to 60 s of wall time
    beside = _beside(3.0, 1.0, WorkClock(0.1, wall_seconds=DEADLINE_S))
    assert beside.finish(wanted=True) == to_ticks(3.3)
    assert not beside.proc.is_alive()


@pytest.mark.skipif(not anytime.beside_possible(), reason="one core, or no fork")
def test_the_bound_beside_the_walk_is_not_waited_for_past_its_deadline(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # whatever keeps its process past the deadline (here a slow "is CP-SAT there", copied into
    # the process; in runs under load CP-SAT's import or a question's solve): the run takes
    # what was proved (here nothing: the floor) and stops the process
    monkeypatch.setattr(lns, "available", lambda: time.sleep(DEADLINE_S) or True)
    beside = _beside(3.0, time.perf_counter())
    assert beside.finish(wanted=True) == to_ticks(3.0)
    assert not beside.proc.is_alive()
    # not wanted (the plan meets the bound): stopped at once, whatever it was doing
    beside = _beside(3.0, time.perf_counter() + DEADLINE_S)
    assert beside.finish(wanted=False) >= to_ticks(3.0)
    assert not beside.proc.is_alive()


@pytest.mark.parametrize("workers", [1, 2])
def test_on_two_cores_the_bound_runs_beside_the_walk(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path, workers: int
) -> None:
    # two cores: the profile bound runs in a process of its own until the deadline, and the walk
    # keeps going until the deadline too; one core: the walk stops for the bound's last share
    if workers == 2 and not anytime.beside_possible():
        pytest.skip("one core, or no fork")
    # (one core: the bound gets no time, this is about when it runs; two cores: the run waits
    # for the bound's process to end, which it does by its own copy of the clock, so that it
    # has told where it runs whatever the machine's load)
    clock = WorkClock(STEP_S, wall_seconds=DEADLINE_S if workers == 2 else 0.0)
    where = tmp_path / "bound"
    seen: dict[str, float] = {}
    real_bound, real_more = profile.profile_bound, anytime._more

    def bound(*args: object, **kwargs: object) -> profile.ProfileBound:
        # (from the bound's process, on its copy of the clock: where the run was at its start)
        where.write_text(f"{os.getpid()} {clock.t!r}")
        return real_bound(*args, **kwargs)  # type: ignore[arg-type]

    def more(problem: Problem, s: object, until: float, **kwargs: float) -> object:
        seen["until"] = until
        return real_more(problem, s, until, **kwargs)  # type: ignore[arg-type]

    monkeypatch.setattr(profile, "profile_bound", bound)
    monkeypatch.setattr(anytime, "_more", more)
    monkeypatch.setattr(schedule, "WORKERS", workers)
    monkeypatch.setattr(anytime, "PROFILE_SHARE", 0.3)  # a share of 1.2 s at a 4 s budget
    # CP-SAT imported here already, so the forked process has it too: under load its own
    # import could outlast this 4 s run, and the bound would (rightly) never be asked
    assert lns.available()
    c = delivery_cell("grid", 17, 0)
    res = plan(c.scene, c.spec, anytime=True, timeout=BUDGET_S, clock=clock)
    assert res.status is PlanStatus.SOLVED and res.lower_bound is not None
    pid, at = where.read_text().split()
    assert (int(pid) == os.getpid()) is (workers == 1)
    if workers == 2:
        # the walk to the deadline, the bound from before the walk's start
        assert seen["until"] == BUDGET_S and float(at) < 0.45 * BUDGET_S
    else:
        # the walk to 70 %, the bound after it
        assert seen["until"] == pytest.approx(0.7 * BUDGET_S)
        assert seen["until"] <= float(at) < BUDGET_S


@pytest.mark.skipif(not anytime.beside_possible(), reason="one core, or no fork")
@pytest.mark.parametrize(("layout", "kept"), [("grid", True), ("line", False)])
def test_the_bound_beside_starts_before_the_pairs_and_stops_if_a_pair_beats_it(
    monkeypatch: pytest.MonkeyPatch, layout: str, kept: bool
) -> None:
    # on two cores the profile bound's process starts before the pair bounds (0.8-0.9 s of a
    # 32-goal grid or random cell's 10 s run), and is stopped when a pair beats the start
    # bound (a line: the pairs are the bound there), keeping what it proved; on a grid, where
    # no pair does, it runs on beside the walk
    started: list[anytime._ProfileBeside] = []
    real_beside, real_pairs, real_more = (
        anytime._ProfileBeside,
        anytime._pairs_at_start,
        anytime._more,
    )
    seen: dict[str, Any] = {}

    class Spy(real_beside):  # type: ignore[valid-type,misc]
        def __init__(self, *args: Any, **kwargs: Any) -> None:
            super().__init__(*args, **kwargs)
            started.append(self)

    def pairs(*args: Any, **kwargs: Any) -> float:
        seen["started before the pairs"] = len(started)
        got = real_pairs(*args, **kwargs)
        seen["pair above the start bound"] = got > args[4]
        return got

    def more(*args: Any, **kwargs: Any) -> object:
        # (closed: stopped and read for good)
        seen["bound running beside the walk"] = not started[0].conn.closed
        return real_more(*args, **kwargs)

    monkeypatch.setattr(anytime, "_ProfileBeside", Spy)
    monkeypatch.setattr(anytime, "_pairs_at_start", pairs)
    monkeypatch.setattr(anytime, "_more", more)
    monkeypatch.setattr(schedule, "WORKERS", 2)
    monkeypatch.setattr(anytime, "PROFILE_SHARE", 0.3)  # (a share long enough at 4 s)
    assert lns.available()  # (imported here: the forked process has it at once)
    c = delivery_cell(layout, 17, 0)
    res = plan(c.scene, c.spec, anytime=True, timeout=BUDGET_S, clock=WorkClock(STEP_S))
    assert res.status is PlanStatus.SOLVED and res.lower_bound is not None
    assert seen["started before the pairs"] == 1
    assert seen["pair above the start bound"] is not kept
    assert seen["bound running beside the walk"] is kept
    assert not started[0].proc.is_alive()


def _lp(scene: Scene, spec: HSpec, level: float) -> tuple[int | None, float]:
    """(the LP bound at ``level`` s in ticks, the start heuristic in ticks)."""
    problem = Problem(scene, spec)
    s, node, graph, tgts = start_targets(problem)
    deadline = time.perf_counter() + DEADLINE_S
    got = profile.lp_bound(problem, graph, node, tgts, to_ticks(level), deadline)
    return got, s.heuristic(node)


@pytest.mark.skipif(not profile.lp_available(), reason="no scipy")
@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.integers(0, 10**6))
def test_the_lp_and_mip_bounds_never_exceed_the_optimum(seed: int) -> None:
    # asked at the optimum (as the anytime run asks it at a plan's makespan): every plan that
    # long satisfies the integer model's rows, hence the LP's; so HiGHS's dual bound on the
    # model kept integral (the MIP), like its least makespan, is at most the optimum too, and
    # the LP's bound is at most the MIP's
    inst = _random(seed)
    if inst is None or not profile.applicable(Problem(*inst)):
        return
    optimum = optimal_makespan(*inst)
    if optimum is None:
        return
    got, _ = _lp(*inst, optimum)
    assert got is None or got <= to_ticks(optimum)
    if got is None:
        return  # (no target: nothing to ask)
    linear = _linear(*inst, optimum)
    deadline = time.perf_counter() + DEADLINE_S
    mip = linear.solve(deadline, integral=True)
    assert mip is not None and got <= mip[0] <= to_ticks(optimum)


@pytest.mark.skipif(not profile.lp_available(), reason="no scipy")
@pytest.mark.parametrize("seed", [28, 66, 91])
def test_the_lp_bound_reaches_the_optimum_where_the_heuristic_is_half_of_it(seed: int) -> None:
    inst = _random(seed)
    assert inst is not None
    optimum = optimal_makespan(*inst)
    assert optimum is not None
    got, h0 = _lp(*inst, optimum)
    assert got == to_ticks(optimum) and 2 * h0 == got  # (e.g. 1.1 s -> 2.2 s)


def _climb(problem: Problem, upper: float, told: list[int], **how: bool) -> profile.ProfileBound:
    """The profile bound from the start heuristic up, a plan of ``upper`` s known (as the
    bound's process beside the walk asks it), each bound proved appended to ``told``."""
    s, node, graph, tgts = start_targets(problem)
    return profile.profile_bound(
        problem,
        graph,
        node,
        tgts,
        floor=round(s.heuristic(node)),
        upper=to_ticks(upper),
        deadline=time.perf_counter() + DEADLINE_S,
        on_proven=told.append,
        **how,
    )


@pytest.mark.skipif(not profile.lp_available(), reason="no scipy")
def test_the_climb_starts_from_the_lp_bound() -> None:
    # grid 5 seed 0: start bound 5.3 s, the LP at the optimum 5.4 s says 5.4 s, so the climb
    # has nothing left to ask; without the LP it asks CP-SAT
    c = delivery_cell("grid", 5, 0)
    problem = Problem(c.scene, c.spec)
    asked = {}
    for lp in (True, False):
        told: list[int] = []
        res = _climb(problem, 5.4, told, lp=lp)
        assert res.ticks == to_ticks(5.4) and told == [to_ticks(5.4)]
        asked[lp] = res.questions
    assert asked == {True: 0, False: 1}


def _linear(scene: Scene, spec: HSpec, level: float) -> Any:
    """The profile model at ``level`` s from the start, as rows for HiGHS (``profile._Linear``)."""
    problem = Problem(scene, spec)
    _, node, graph, tgts = start_targets(problem)
    deadline = time.perf_counter() + DEADLINE_S
    linear = profile._linear(problem, graph, node, tgts, to_ticks(level), deadline)
    assert linear is not None
    return linear


@pytest.mark.skipif(not profile.lp_available(), reason="no scipy")
def test_the_mip_bound_sees_what_the_lp_does_not() -> None:
    # generator seed 299: optimum 2.8 s, start heuristic 1.4 s; the LP's fractional routes and
    # counts give 2.1 s, the model kept integral is solved at 2.8 s (the optimum)
    inst = _random(299)
    assert inst is not None
    linear = _linear(*inst, 2.8)
    deadline = time.perf_counter() + DEADLINE_S
    assert linear.solve(deadline, integral=False) == (to_ticks(2.1), False)
    assert linear.solve(deadline, integral=True) == (to_ticks(2.8), True)


@pytest.mark.skipif(not profile.lp_available(), reason="no scipy")
def test_the_climb_starts_from_the_mip_bound() -> None:
    # seed 299 again, as the bound's process beside the walk asks it (a plan of 2.8 s known):
    # LP 2.1 s, then the MIP's 2.8 s, which meets the plan: CP-SAT is asked nothing. With the
    # LP alone the climb asks CP-SAT from 2.1 s up. (Before the MIP, HiGHS's "no solution at
    # this level" may tell a level or two more on the way: ``profile.FITS_QUESTIONS``.)
    inst = _random(299)
    assert inst is not None
    asked = {}
    for mip in (True, False):
        told: list[int] = []
        res = _climb(Problem(*inst), 2.8, told, lp=True, mip=mip)
        assert res.ticks == to_ticks(2.8)
        assert told[0] == to_ticks(2.1) and told[-1] == to_ticks(2.8)
        assert told == sorted(set(told))
        asked[mip] = res.questions
    assert asked[True] == 0 and asked[False] > 0


def _mip_at(layout: str, n: int, seed: int, level: float) -> Any:
    """The profile model at ``level`` s from the start of a delivery cell, as rows for HiGHS."""
    c = delivery_cell(layout, n, seed)
    problem = Problem(c.scene, c.spec)
    _, node, graph, tgts = start_targets(problem)
    linear = profile._linear(
        problem, graph, node, tgts, to_ticks(level), time.perf_counter() + DEADLINE_S
    )
    assert linear is not None
    return linear


@pytest.mark.skipif(not profile.lp_available(), reason="no scipy")
def test_the_mip_tells_its_bound_as_highs_raises_it() -> None:
    # grid 10 x 10 seed 2 at 10.0 s: HiGHS's dual bound rises from 6.0 to 6.3 s while it runs
    # (6.3 s is the model's least makespan); each rise is told then, before the answer, which
    # is the same as scipy's milp gives at the end
    linear = _mip_at("grid", 10, 2, 10.0)
    deadline = time.perf_counter() + DEADLINE_S
    told: list[int] = []
    got = linear.solve(deadline, integral=True, on_bound=told.append)
    assert got == linear.solve(deadline, integral=True) == (to_ticks(6.3), True)
    assert told and told == sorted(set(told)) and told[-1] <= got[0]
    assert told[0] < got[0]  # (told while HiGHS still ran: a rise it went on from)


@pytest.mark.skipif(not profile.lp_available(), reason="no scipy")
def test_without_highs_own_interface_the_mip_answers_at_the_end(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # scipy's HiGHS interface is private: where it is not there, milp answers the same, told
    # nothing on the way (profile_bound tells the answer itself)
    from scipy.optimize._highspy import _core

    linear = _mip_at("grid", 10, 2, 10.0)
    monkeypatch.delattr(_core, "cb")  # (its callbacks; milp itself does not use them)
    told: list[int] = []
    got = linear.solve(time.perf_counter() + DEADLINE_S, integral=True, on_bound=told.append)
    assert got == (to_ticks(6.3), True) and told == []
