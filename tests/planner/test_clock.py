"""The planner's clock (docs/planner.md, "The clock"): production reads ``time.perf_counter``;
on a ``WorkClock`` a run's phases end after the same work whatever the machine's speed."""

from __future__ import annotations

import time
from typing import Any

import pytest

from hltl.bench.cells import delivery_cell
from hltl.planner import WALL, PlanStatus, WorkClock, anytime, plan
from hltl.planner.anytime import _Router
from hltl.planner.problem import Problem
from hltl.planner.search import search
from tests.oracles.validator import check_plan


def test_production_reads_perf_counter_and_hands_its_deadlines_over_as_they_are() -> None:
    assert WALL.now is time.perf_counter  # (the built-in itself: A* reads it every expansion)
    assert WALL.wall(12.5) == 12.5


def test_a_work_clock_advances_by_a_step_at_each_reading_and_only_then() -> None:
    clock = WorkClock(0.5, start=10.0)
    assert [clock.now(), clock.now(), clock.now()] == [10.0, 10.5, 11.0]
    assert clock.readings == 3
    # handing a deadline to what keeps wall time is no reading; it gets ``wall_seconds`` of
    # real time while the clock has not reached it, and none after
    before = time.perf_counter()
    assert before <= clock.wall(20.0) <= time.perf_counter()  # (wall_seconds 0: no time)
    patient = WorkClock(0.5, wall_seconds=60.0)
    assert patient.wall(1.0) >= before + 60.0
    assert patient.wall(0.0) <= time.perf_counter()  # (reached: none)
    assert clock.readings == 3 and patient.readings == 0
    with pytest.raises(ValueError, match="advance"):
        WorkClock(0.0)


def test_a_search_times_out_after_the_same_work_on_any_machine() -> None:
    # line 10 x 10 seed 0: A* needs about 16 s; on a work clock a 1 s budget is 100 readings,
    # one per expansion and one per 64 successors: the same expansions every time
    c = delivery_cell("line", 10, 0)
    runs = [search(Problem(c.scene, c.spec), timeout=1.0, clock=WorkClock(0.01)) for _ in "ab"]
    assert {r.status for r in runs} == {PlanStatus.TIMEOUT}
    assert runs[0].stats.expanded == runs[1].stats.expanded < 100
    assert runs[0].lower_bound == runs[1].lower_bound


def test_an_anytime_run_on_a_slow_machine_is_the_run_on_a_fast_one(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # grid 12 x 12 seed 0 for 3 s: the step bound and the joint re-plan (CP-SAT) get no time on
    # this clock, the pairs, the walk over priority orders and A*'s slice each get their share
    # in work. Every routed plan made 2 ms slower (a machine several times slower, or
    # loaded): the same plan, the same bound and the same readings. On the wall clock the
    # walk would make fewer rounds
    c = delivery_cell("grid", 12, 0)

    def run() -> tuple[Any, ...]:
        clock = WorkClock(0.01)
        res = plan(c.scene, c.spec, anytime=True, timeout=3.0, clock=clock)
        assert res.status is PlanStatus.SOLVED
        check_plan(c.scene, c.spec, res.to_dict())
        return res.makespan, res.lower_bound, res.stats.expanded, clock.readings

    fast = run()
    real = _Router.replay

    def slow(self: _Router, steps: Any) -> Any:
        time.sleep(0.002)
        return real(self, steps)

    monkeypatch.setattr(_Router, "replay", slow)
    assert run() == fast
    assert fast[3] > 300  # (the whole budget was read: no early proof of optimality)


def test_the_pairs_end_after_the_same_work(monkeypatch: pytest.MonkeyPatch) -> None:
    # a budget of readings for the pair bounds at the start node: as many pairs as readings
    # (grid 8 x 8 seed 1 has 28 pairs, and no pair beats the start bound on a grid, so the
    # trial stops the pairs after ``PAIRS_TRIAL``; with a larger trial, the clock does)
    monkeypatch.setattr(anytime, "PAIRS_TRIAL", 10**6)
    c = delivery_cell("grid", 8, 1)
    problem = Problem(c.scene, c.spec)
    s = anytime._Search(problem)
    start = problem.start()
    lb = s.heuristic(start)
    tried: list[int] = []
    real = anytime.PairBound.lookups

    def lookups(self: Any, atoms: Any) -> Any:
        tried.append(1)
        return real(self, atoms)

    monkeypatch.setattr(anytime.PairBound, "lookups", lookups)
    anytime._pairs_at_start(problem, s, start, 1.0, lb, clock=WorkClock(0.25))
    assert len(tried) == 5  # (readings 0, 0.25, ..., 1.0 are not past 1.0: each starts one)
