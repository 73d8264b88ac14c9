"""Exact mode's first phase (docs/planner.md, "Step bound"): a plan the step bound proves optimal
is returned without A*; it must be exactly as short as plain A*'s, and valid."""

from __future__ import annotations

import math
import threading
from collections.abc import Callable
from concurrent.futures import ThreadPoolExecutor
from typing import Any

import pytest

from hltl import planner
from hltl.bench.cells import delivery_cell
from hltl.planner import PlanResult, PlanStep, WorkClock, anytime, lns, phase, plan, schedule
from hltl.planner.problem import Problem, to_ticks
from hltl.planner.search import _Search, plan_steps, search
from tests.oracles.validator import check_plan
from tests.planner.start import step_levels

pytest.importorskip("ortools")


@pytest.mark.parametrize(
    ("layout", "n", "seed"),
    [
        ("grid", 4, 1),
        ("grid", 5, 0),
        ("grid", 3, 0),
        ("grid", 3, 4),
        ("random", 4, 0),
        ("random", 4, 1),
        ("grid", 5, 4),
        ("random", 5, 0),  # A* starts beside the full model, which proves the optimum first
    ],
)
def test_certified_plans_are_optimal(
    layout: str, n: int, seed: int, monkeypatch: pytest.MonkeyPatch
) -> None:
    # the phase runs on cells of more than PHASE_ABOVE goals; let it run on small ones, where
    # plain A* is quick and exact
    monkeypatch.setattr(planner, "PHASE_ABOVE", 0)
    c = delivery_cell(layout, n, seed)
    got = plan(c.scene, c.spec, timeout=120)
    expected = search(Problem(c.scene, c.spec), timeout=120)
    assert got.solved and expected.solved
    assert got.makespan == pytest.approx(expected.makespan)
    check_plan(c.scene, c.spec, got.to_dict())


def test_a_certified_plan_skips_the_search(monkeypatch: pytest.MonkeyPatch) -> None:
    # grid 4 seed 1: the step bound is the optimum (3.3 s) and its schedule is a plan
    monkeypatch.setattr(planner, "PHASE_ABOVE", 0)
    c = delivery_cell("grid", 4, 1)
    got = plan(c.scene, c.spec, timeout=120)
    assert got.makespan == pytest.approx(3.3)
    assert got.stats.expanded == 0
    assert got.lower_bound == pytest.approx(3.3)


def test_lines_go_straight_to_astar(monkeypatch: pytest.MonkeyPatch) -> None:
    # a 10-robot line's start bound (11.7 s) is more than STEPS_UP_TO shortest steps: where A*
    # has no process of its own beside the phase (``certified``: no ``watch``), neither the
    # step bound nor CP-SAT's joint re-plan may take the phase's time from A*
    def never(*_: object, **__: object) -> None:
        raise AssertionError("called on a line")

    monkeypatch.setattr(anytime, "_jointly", never)
    monkeypatch.setattr(anytime, "step_bound", never)
    # nor need CP-SAT be imported (0.5-1.5 s in a fresh process)
    monkeypatch.setattr(lns, "available", never)
    c = delivery_cell("line", 10, 3)
    problem = Problem(c.scene, c.spec)
    assert phase.certified(problem, _Search(problem), math.inf) is None


@pytest.mark.parametrize(
    ("seed", "floor", "optimum", "lowest"), [(0, 5.4, 5.4, 54), (1, 3.3, 3.3, None)]
)
def test_the_profile_bound_is_the_step_climbs_floor(
    seed: int, floor: float, optimum: float, lowest: int | None, monkeypatch: pytest.MonkeyPatch
) -> None:
    # grid 5 seed 0: start bound 5.3 s, profile bound 5.4 s (a few cheap questions), optimum
    # 5.4 s: the step climb starts at 5.4 s, never below, and proves A*'s optimum. Grid 4 seed
    # 1: the profile bound (3.3 s) meets the prioritized plan's makespan, which is then
    # optimal without any step question
    monkeypatch.setattr(planner, "PHASE_ABOVE", 0)
    # (its 1 s may not be enough for the profile bound's questions on a loaded machine)
    monkeypatch.setattr(phase, "PROFILE_FLOOR_SECONDS", 120.0)
    c = delivery_cell("grid", 5 if seed == 0 else 4, seed)
    problem = Problem(c.scene, c.spec)
    s = _Search(problem)
    start = problem.start()
    h0 = round(s.heuristic(start))
    got = phase._profile_floor(problem, s, start, h0, None, math.inf)
    assert h0 < got == to_ticks(floor)
    levels = step_levels(monkeypatch)
    found = phase.certified(problem, _Search(problem), math.inf)
    expected = search(Problem(c.scene, c.spec), timeout=120)
    assert found is not None and expected.makespan is not None
    assert found[0] == to_ticks(expected.makespan) == to_ticks(optimum)
    assert min(levels, default=None) == lowest


@pytest.mark.parametrize(
    ("layout", "n", "seed", "level"), [("random", 5, 0, 57), ("random", 5, 1, 57)]
)
def test_the_climb_asks_sessions_whole_before_the_full_model(
    layout: str, n: int, seed: int, level: int, monkeypatch: pytest.MonkeyPatch
) -> None:
    # here the cheaper model's schedule at ``level`` is no plan, and neither sessions whole nor
    # the full model have a schedule there; one level up, sessions whole give a plan, which is
    # optimal without the full model being asked there (schedule._shave, whole_first). (Random
    # 4 seed 1 and grid 5 seed 4 were such cells until session 12's counting rows: the cheaper
    # model now proves their optimum itself.) Without the roof: the walk's plan there is
    # optimal, and the climb's first round below it proves it without the full model.
    monkeypatch.setattr(planner, "PHASE_ABOVE", 0)
    monkeypatch.setattr(phase, "ROOF_ROUNDS", 0)
    asked: list[tuple[int, bool, bool, bool]] = []  # level, holders, whole, found
    real = schedule.relaxed_steps

    def logged(*args: object, **kwargs: object) -> object:
        got = real(*args, **kwargs)  # type: ignore[arg-type]
        level_ = args[4]
        assert isinstance(level_, int)
        holders, whole = kwargs.get("holders", True), kwargs.get("whole", False)
        asked.append((level_, bool(holders), bool(whole), isinstance(got, tuple)))
        return got

    monkeypatch.setattr(schedule, "relaxed_steps", logged)
    c = delivery_cell(layout, n, seed)
    problem = Problem(c.scene, c.spec)
    found = phase.certified(problem, _Search(problem), math.inf)
    expected = search(Problem(c.scene, c.spec), timeout=120)
    assert found is not None and expected.makespan is not None
    assert found[0] == to_ticks(expected.makespan) == to_ticks((level + 1) / 10)
    # (the climbs ask two levels at once on two cores, so compare what was asked, not in
    # which order the answers came; a question stopped because another answer implies its
    # own is logged as not found)
    assert (level, False, False, True) in asked  # the cheaper model's schedule: no plan
    assert not any(h and lv < level for lv, h, _, _ in asked)  # the full model from there
    assert (level, True, True, False) in asked  # sessions whole: none
    assert (level, True, False, False) in asked  # the full model: none
    assert (level + 1, True, True, True) in asked  # sessions whole: a plan
    assert (level + 1, True, False, True) not in asked  # the full model not needed there


@pytest.mark.parametrize("roof", [True, False])
def test_the_walks_plan_is_the_climbs_roof(roof: bool, monkeypatch: pytest.MonkeyPatch) -> None:
    # random 5 seed 0: the walk's plan (5.8 s) is optimal. As the roof (levels within 20 of
    # the floor) the climb's first round asks 5.6 and 5.7 s; 5.7's schedule is no plan, nor
    # has the full model one there, so the roof is the bound and the walk's plan is returned,
    # no level from the floor (4.6 s) to 5.5 s is asked, nor any at or above 5.8 s. Without
    # the roof (ROOF_ROUNDS 0) the climb starts at the floor and ends above 5.8 s
    # (docs/planner.md, "The step model's roof")
    monkeypatch.setattr(planner, "PHASE_ABOVE", 0)
    monkeypatch.setattr(schedule, "ROOF_SPAN", 20)
    if not roof:
        monkeypatch.setattr(phase, "ROOF_ROUNDS", 0)
    levels = step_levels(monkeypatch)
    c = delivery_cell("random", 5, 0)
    problem = Problem(c.scene, c.spec)
    found = phase.certified(problem, _Search(problem), math.inf)
    expected = search(Problem(c.scene, c.spec), timeout=120)
    assert found is not None and expected.makespan is not None
    assert found[0] == to_ticks(expected.makespan) == to_ticks(5.8)
    check_plan(c.scene, c.spec, phase._solved(problem, found, expected.stats).to_dict())
    if roof:
        assert set(levels) == {56, 57}
    else:
        assert min(levels) == 46 and max(levels) >= 58


def test_sessions_whole_asked_ahead_give_the_same_bound_and_plan(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # random 5 seed 0 from 5.6 s: the cheaper model's first round asks 5.6 and 5.7 s at once;
    # held until 5.7's schedule (no plan) has come, 5.6 leaves a core free, on which sessions
    # whole at 5.7 are asked ahead (schedule._Whole); 5.6 says "no", so the full model's climb
    # starts at 5.7 and takes that answer instead of asking again. Bound and plan are the
    # ones found without asking ahead (a mutation that asks again, or takes another level's
    # answer, is caught)
    if schedule.WORKERS < 2:
        pytest.skip("needs two cores (two levels asked at once)")
    monkeypatch.setattr(planner, "PHASE_ABOVE", 0)
    c = delivery_cell("random", 5, 0)
    real = schedule.relaxed_steps
    came, ahead_asked, low_done = threading.Event(), threading.Event(), threading.Event()
    asked: list[tuple[int, bool, bool, bool]] = []  # level, holders, whole, 5.6 s still open

    def held(*args: object, **kwargs: object) -> object:
        level, holders, whole = args[4], kwargs.get("holders", True), kwargs.get("whole", False)
        assert isinstance(level, int)
        asked.append((level, bool(holders), bool(whole), not low_done.is_set()))
        if (level, whole) == (57, True):
            ahead_asked.set()
        if (level, holders) == (56, False):
            assert came.wait(120)
            ahead_asked.wait(30)  # (never set without asking ahead)
        got = real(*args, **kwargs)  # type: ignore[arg-type]
        if (level, holders) == (57, False):
            assert isinstance(got, tuple)
            came.set()
        if (level, holders) == (56, False):
            assert got is False
            low_done.set()
        return got

    def bound(ahead: bool) -> tuple[int, object]:
        problem = Problem(c.scene, c.spec)
        s = _Search(problem)
        start = problem.start()
        for event in (came, ahead_asked, low_done):
            event.clear()
        asked.clear()
        if not ahead:
            ahead_asked.set()
        with monkeypatch.context() as m:
            m.setattr(schedule, "relaxed_steps", held)
            if not ahead:
                m.setattr(schedule._Whole, "ahead", lambda *_: None)
            floor = 56 * schedule.time_unit(problem)
            return anytime.step_bound(problem, s, start, floor, None, math.inf)

    with_ahead = bound(True)
    first = list(asked)
    without = bound(False)
    assert with_ahead == without and with_ahead[0] == to_ticks(5.8)
    # sessions whole at 5.7 s asked once, ahead, while 5.6 s was open; without asking ahead,
    # asked by the full model's climb once 5.6 s had said "no"
    assert [a for a in first if a[:3] == (57, True, True)] == [(57, True, True, True)]
    assert [a for a in asked if a[:3] == (57, True, True)] == [(57, True, True, False)]


@pytest.mark.parametrize(
    ("layout", "n", "seed"),
    [("grid", 4, 1), ("grid", 5, 0), ("grid", 3, 4), ("random", 4, 0), ("line", 4, 1)],
)
def test_astar_after_an_unproved_plan_finds_the_optimum(
    layout: str, n: int, seed: int, monkeypatch: pytest.MonkeyPatch
) -> None:
    # the phase proves nothing here (no step bound, no joint re-plan), so A* runs with the
    # prioritized plan's makespan as ``upper``: it finds a shorter plan, which is optimal, or
    # proves there is none, and then that plan is optimal
    monkeypatch.setattr(planner, "PHASE_ABOVE", 0)
    # (on grid 4 seed 1 and random 4 seed 0 the profile bound meets the first plan already)
    monkeypatch.setattr(phase, "_profile_floor", lambda _p, _s, _n, floor, *_: floor)
    monkeypatch.setattr(anytime, "step_bound", lambda _p, _s, _n, floor, *_: (floor, None))
    monkeypatch.setattr(anytime, "_jointly", lambda *_, **__: None)
    c = delivery_cell(layout, n, seed)
    problem = Problem(c.scene, c.spec)
    cert = phase.certify(problem, _Search(problem), math.inf)
    assert cert.optimal is None and cert.best is not None
    got = plan(c.scene, c.spec, timeout=120)
    expected = search(Problem(c.scene, c.spec), timeout=120)
    assert got.solved and expected.solved and got.makespan is not None
    assert got.makespan == pytest.approx(expected.makespan)
    assert got.lower_bound == pytest.approx(expected.makespan)
    check_plan(c.scene, c.spec, got.to_dict())
    # the prioritized plan itself when it is optimal (A* expanded every node below it and
    # found nothing: grid 3 seed 4, line 4 seed 1), else A*'s shorter one (the others)
    if cert.best[0] == to_ticks(got.makespan):
        assert got.steps == plan_steps(problem, cert.best[1])
    else:
        assert cert.best[0] > to_ticks(got.makespan)


@pytest.mark.parametrize("proved", [True, False])
def test_a_timed_out_plan_carries_the_phases_bound(
    proved: bool, monkeypatch: pytest.MonkeyPatch
) -> None:
    # line 10 seed 0 (optimum 14.7 s, A* needs about 16 s): A* times out after about 2 s,
    # its own bound well below 14.7 s; a first phase that proved 14.7 s (as the step
    # climb's "no"s can) gives the timed-out result that bound, and says so. (On a clock of
    # work A* times out on any machine, after the same expansions: about 180)
    c = delivery_cell("line", 10, 0)
    bound = to_ticks(14.7) if proved else 0
    monkeypatch.setattr(phase, "certify", lambda *_: phase.Certificate(None, None, bound))
    got = plan(c.scene, c.spec, timeout=2.0, clock=WorkClock(0.01))
    assert got.status is planner.PlanStatus.TIMEOUT and got.lower_bound is not None
    assert got.makespan is not None and got.makespan >= 14.7 - 1e-9
    if proved:
        assert got.lower_bound == pytest.approx(14.7)
        assert "the first phase proved 14.700 s" in got.reason
    else:
        assert got.lower_bound < 14.7
        assert "first phase" not in got.reason


def test_astar_beside_the_full_model_returns_the_same_plan_whichever_ends_first(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # line 6 seed 5: the cheaper model's schedule is no plan, so A* starts beside the full
    # model's climb (phase._Beside), which proves nothing here; the phase's joint re-plan is
    # optimal, so A* finds a plan as short when it runs first, and none shorter when it runs
    # last: either way the plan returned is the phase's (a mutation check: returning A*'s
    # own plan when it is no shorter makes the two differ)
    monkeypatch.setattr(planner, "PHASE_ABOVE", 0)
    real_start, real_finish = phase._Beside.start, phase._Beside.finish
    order = {"mode": ""}
    release = threading.Event()
    started: list[str] = []

    def start(self: phase._Beside, first: object) -> None:
        started.append(order["mode"])
        if order["mode"] == "phase first":
            # A*'s pool (made here before A* makes it) has one thread: A* waits behind this
            # until the phase has ended
            self.pool = ThreadPoolExecutor(max_workers=1)
            self.pool.submit(release.wait)
        real_start(self, first)  # type: ignore[arg-type]
        if order["mode"] == "astar first":
            assert self.future is not None
            self.future.result()

    def finish(self: phase._Beside, cert: phase.Certificate) -> object:
        assert cert.optimal is None
        release.set()
        return real_finish(self, cert)

    # (the thread: without two cores or ``fork``, or with ``on_progress``: phase._Apart)
    monkeypatch.setattr(anytime, "beside_possible", lambda: False)
    monkeypatch.setattr(phase._Beside, "start", start)
    monkeypatch.setattr(phase._Beside, "finish", finish)
    steps = _line_6_5_both_ways(order, release, search)
    assert started == ["astar first", "phase first"]
    assert steps[0] == steps[1]


def _line_6_5_both_ways(
    order: dict[str, str],
    release: threading.Event | Any,
    oracle: Callable[..., PlanResult],
    cell: tuple[str, int, int] = ("line", 6, 5),
) -> list[tuple[PlanStep, ...]]:
    """Line 6 seed 5's (or ``cell``'s) plans with ``order["mode"]`` "astar first", then "phase
    first" (the patched A* waits for ``release`` in the second), each as short as ``oracle``'s,
    proved so and valid; ``oracle``'s plan last."""
    c = delivery_cell(*cell)
    expected = oracle(Problem(c.scene, c.spec), timeout=120)
    steps = []
    for mode in ("astar first", "phase first"):
        order["mode"] = mode
        release.clear()
        got = plan(c.scene, c.spec, timeout=120)
        assert got.solved and got.makespan == pytest.approx(expected.makespan)
        assert got.lower_bound == pytest.approx(expected.makespan)
        check_plan(c.scene, c.spec, got.to_dict())
        steps.append(got.steps)
    return [*steps, expected.steps]


@pytest.mark.skipif(not anytime.beside_possible(), reason="needs two cores and fork")
def test_astar_in_its_own_process_returns_the_same_plan_whichever_ends_first(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # as above with A* in a forked process from the start of the phase (phase._Apart): held
    # until the phase ends, or waited for before the phase goes on; the plan returned is the
    # phase's joint re-plan either way, and as short as plain A*'s
    import multiprocessing

    monkeypatch.setattr(planner, "PHASE_ABOVE", 0)
    ctx = multiprocessing.get_context("fork")
    release = ctx.Event()
    order = {"mode": ""}
    real_ahead, real_finish, real_search = (
        phase._Apart.ahead,
        phase._Apart.finish,
        phase.search,
    )
    apart: list[phase._Apart] = []

    def ahead(self: phase._Apart) -> None:
        apart.append(self)
        real_ahead(self)
        if order["mode"] == "astar first":
            assert self.results is not None and self.results.poll(120)  # A* has ended

    def held_search(*args: object, **kwargs: object) -> object:
        # (runs in the child, forked after this patch)
        if order["mode"] == "phase first":
            release.wait(120)
        return real_search(*args, **kwargs)  # type: ignore[arg-type]

    def finish(self: phase._Apart, cert: phase.Certificate) -> object:
        assert cert.optimal is None
        release.set()
        return real_finish(self, cert)

    monkeypatch.setattr(phase._Apart, "ahead", ahead)
    monkeypatch.setattr(phase._Apart, "finish", finish)
    monkeypatch.setattr(phase, "search", held_search)
    steps = _line_6_5_both_ways(order, release, real_search)
    assert len(apart) == 2 and all(a.proc is not None and not a.proc.is_alive() for a in apart)
    assert steps[0] == steps[1]


def test_astar_in_its_own_process_is_stopped_by_a_proof(monkeypatch: pytest.MonkeyPatch) -> None:
    # grid 4 seed 1: the step bound proves the optimum; A*'s process, started with the phase,
    # is ended, and the plan is the phase's (no expansion counted)
    if not anytime.beside_possible():
        pytest.skip("needs two cores and fork")
    monkeypatch.setattr(planner, "PHASE_ABOVE", 0)
    apart: list[phase._Apart] = []
    real_ahead = phase._Apart.ahead

    def ahead(self: phase._Apart) -> None:
        apart.append(self)
        real_ahead(self)

    monkeypatch.setattr(phase._Apart, "ahead", ahead)
    c = delivery_cell("grid", 4, 1)
    got = plan(c.scene, c.spec, timeout=120)
    assert got.makespan == pytest.approx(3.3) and got.stats.expanded == 0
    assert len(apart) == 1 and apart[0].proc is not None and not apart[0].proc.is_alive()


def test_a_cell_left_to_astar_is_proved_at_its_start_bound() -> None:
    # random 10 x 10 seed 4: the start bound (10.5 s) is above STEPS_UP_TO shortest steps, so
    # no step bound; A* alone times out on its plateau at 10.5 s (20 s runs, sessions 8-17).
    # The phase beside A* (phase._beside_astar) has CP-SAT re-plan the prioritized plan
    # (11.2 s) jointly, held at or above the start bound: 10.5 s, optimal, no expansion counted
    if not anytime.beside_possible():
        pytest.skip("needs two cores and fork")
    c = delivery_cell("random", 10, 4)
    problem = Problem(c.scene, c.spec)
    s = _Search(problem)
    h0 = round(s.heuristic(problem.start()))
    assert h0 > anytime.STEPS_UP_TO * min(i.lower for i in problem.instances)
    got = plan(c.scene, c.spec, timeout=60)
    assert got.solved and got.makespan is not None
    assert to_ticks(got.makespan) == h0 and got.lower_bound == got.makespan
    assert got.stats.expanded == 0
    check_plan(c.scene, c.spec, got.to_dict())


def _beside_astar_both_ways(
    monkeypatch: pytest.MonkeyPatch, layout: str, n: int, seed: int
) -> tuple[list[tuple[PlanStep, ...]], list[phase.AstarEnd]]:
    """Plans of a small cell by ``phase._beside_astar`` (every cell taken for one left to
    A*), with A* ended before the phase goes on, then held until the phase ends, and plain
    A*'s plan; what the phase told the watcher each time."""
    import multiprocessing

    monkeypatch.setattr(planner, "PHASE_ABOVE", 0)
    monkeypatch.setattr(anytime, "STEPS_UP_TO", 0)
    ctx = multiprocessing.get_context("fork")
    release = ctx.Event()
    order = {"mode": ""}
    real_ahead, real_watch, real_finish, real_search = (
        phase._Apart.ahead,
        phase._Apart.watch,
        phase._Apart.finish,
        phase.search,
    )
    ends: list[phase.AstarEnd] = []

    def ahead(self: phase._Apart) -> None:
        real_ahead(self)
        if order["mode"] == "astar first":
            assert self.results is not None and self.results.poll(120)  # A* has ended

    def watch(self: phase._Apart, end: phase.AstarEnd) -> bool:
        ends.append(end)
        return real_watch(self, end)

    def held_search(*args: object, **kwargs: object) -> object:
        # (runs in the child, forked after this patch)
        if order["mode"] == "phase first":
            release.wait(120)
        return real_search(*args, **kwargs)  # type: ignore[arg-type]

    def finish(self: phase._Apart, cert: phase.Certificate) -> object:
        release.set()
        return real_finish(self, cert)

    monkeypatch.setattr(phase._Apart, "ahead", ahead)
    monkeypatch.setattr(phase._Apart, "watch", watch)
    monkeypatch.setattr(phase._Apart, "finish", finish)
    monkeypatch.setattr(phase, "search", held_search)
    steps = _line_6_5_both_ways(order, release, real_search, (layout, n, seed))
    return steps, ends


@pytest.mark.skipif(not anytime.beside_possible(), reason="needs two cores and fork")
def test_a_plan_the_phase_beside_astar_proves_is_returned_whichever_ends_first(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # grid 4 seed 3: start bound 3.8 s, prioritized plan 4.5 s, optimum 3.8 s, which the joint
    # re-plan finds (another plan than A*'s). When A* ends first its plan meets the start
    # bound, so the phase goes on and proves its own: the phase's plan either way (a mutation
    # check: stopping the phase whenever A* ends returns A*'s plan when it ends first)
    steps, ends = _beside_astar_both_ways(monkeypatch, "grid", 4, 3)
    assert steps[0] == steps[1] != steps[2]
    assert len(ends) == 2 and not ends[0].stop.stopped


@pytest.mark.skipif(not anytime.beside_possible(), reason="needs two cores and fork")
def test_the_phase_beside_astar_stops_when_astar_ends_above_the_start_bound(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # line 5 seed 3: start bound 7.0 s, optimum 9.2 s: nothing the phase can prove. When A*
    # ends first the phase's joint re-plan is stopped (lines A* solves in 0.5 s do not wait
    # for CP-SAT), and the plan is A*'s either way
    steps, ends = _beside_astar_both_ways(monkeypatch, "line", 5, 3)
    assert steps[0] == steps[1] == steps[2]
    assert len(ends) == 2 and ends[0].stop.stopped
