"""The bound's process on plans (docs/planner.md, "The bound's core on plans"): its bound made
final by HiGHS (``profile._Linear.fits``), then plans handed between it and the walk's process
(``anytime._Exchange``), every plan taken replayed before it counts."""

from __future__ import annotations

import multiprocessing
import time
from typing import Any

import pytest

from hltl.bench.cells import delivery_cell
from hltl.planner import (
    PlanResult,
    PlanStatus,
    WorkClock,
    anytime,
    lns,
    plan,
    profile,
    repair,
    schedule,
)
from hltl.planner.anytime import _Exchange, _Router, _Slot, _squeeze_paths, _steps_of, goals
from hltl.planner.problem import Problem, to_seconds, to_ticks
from hltl.planner.schedule import time_unit
from hltl.planner.search import _Search, plan_steps
from tests.oracles.validator import check_plan
from tests.planner.start import start_targets
from tests.planner.test_repair import _first

pytest.importorskip("ortools")
pytest.importorskip("scipy")

# generous: under load HiGHS may need it; these tests never assert on time
DEADLINE_S = 60.0


def _pair(problem: Problem) -> tuple[_Exchange, _Exchange]:
    """Two sides of an exchange, in this process (the slots are shared memory all the same)."""
    ctx = multiprocessing.get_context()
    one, two = _Slot(ctx), _Slot(ctx)
    return _Exchange(problem, one, two), _Exchange(problem, two, one)


def _paths(router: _Router, found: anytime._Found) -> dict[int, repair.Path]:
    """A delivery cell's plan as per-goal paths (each goal has an object of its own)."""
    paths: dict[int, repair.Path] = {gi: [] for gi in range(len(router.goals))}
    for t, (_, step, _) in enumerate(found[1]):
        for inst in step:
            for gi, g in enumerate(router.goals):
                if g.obj == inst.obj:
                    paths[gi].append((t, inst))
    return paths


def _steps(found: anytime._Found) -> list[list[int]]:
    return [sorted(i.index for i in step) for _, step, _ in found[1]]


def _cell(n: int, seed: int) -> tuple[Any, Problem, _Search, _Router, dict[int, repair.Path]]:
    """A grid cell, its search, router and first prioritized plan's paths."""
    problem, router, paths = _first("grid", n, seed)
    return delivery_cell("grid", n, seed), problem, router.s, router, paths


def test_fits_says_whether_the_relaxation_has_a_solution_at_a_level() -> None:
    # grid 4 x 4 seed 1: the profile relaxation's optimum is 3.3 s (the exact optimum too)
    c = delivery_cell("grid", 4, 1)
    problem = Problem(c.scene, c.spec)
    _, node, graph, tgts = start_targets(problem)
    deadline = time.perf_counter() + DEADLINE_S
    linear = profile._linear(problem, graph, node, tgts, to_ticks(4.0), deadline)
    assert linear is not None
    units = to_ticks(3.3) // time_unit(problem)
    assert linear.fits(units, deadline) is True
    assert linear.fits(units - 1, deadline) is False
    assert linear.fits(units, time.perf_counter() - 1) is None  # (no time: no answer)


@pytest.mark.parametrize(("layout", "asked"), [("grid", True), ("random", False)])
def test_the_mip_run_asks_for_a_solution_at_its_bound_only_where_handovers_are_bipartite(
    monkeypatch: pytest.MonkeyPatch, layout: str, asked: bool
) -> None:
    # grids: a relaxed solution at the LP's bound ends the run there, the bound final (solved),
    # with no MIP; random layouts (odd cycles of handovers): straight to the MIP, without the
    # LP alone first when the MIP tells its bound as it rises. Either way the bound is the
    # relaxation's optimum (the MIP solves these small cells)
    c = delivery_cell(layout, 8, 1)
    problem = Problem(c.scene, c.spec)
    assert profile._bipartite(problem) is asked
    _, node, graph, tgts = start_targets(problem)
    questions: list[int] = []
    mips: list[bool] = []
    real_fits, real_solve = profile._Linear.fits, profile._Linear.solve

    def fits(self: profile._Linear, units: int, deadline: float) -> bool | None:
        questions.append(units)
        return real_fits(self, units, deadline)

    def solve(self: profile._Linear, deadline: float, **kwargs: Any) -> Any:
        mips.append(kwargs["integral"])
        return real_solve(self, deadline, **kwargs)

    monkeypatch.setattr(profile._Linear, "fits", fits)
    monkeypatch.setattr(profile._Linear, "solve", solve)
    upper = anytime.construct(problem)
    assert upper is not None
    told: list[int] = []
    until = time.perf_counter() + DEADLINE_S
    where = (problem, graph, node, tgts)
    got = profile.profile_bound(
        *where, floor=0, upper=upper[0], deadline=until, on_proven=told.append, lp=True, mip=True
    )
    assert got.solved and told and told[-1] == got.ticks
    assert bool(questions) is asked
    if asked:
        assert questions[-1] * time_unit(problem) == got.ticks  # (the solution's level)
        assert len(questions) <= profile.FITS_QUESTIONS
    assert (True in mips) is not asked
    assert (False in mips) is (asked or not profile._streams())


def test_bipartite_handovers() -> None:
    grids = [delivery_cell("grid", 8, seed) for seed in range(3)]
    randoms = [delivery_cell("random", 8, seed) for seed in range(3)]
    assert all(profile._bipartite(Problem(c.scene, c.spec)) for c in grids)
    assert not any(profile._bipartite(Problem(c.scene, c.spec)) for c in randoms)


def test_a_plan_handed_over_is_taken_once_and_only_when_shorter() -> None:
    _, problem, _, _, paths = _cell(8, 2)
    walk, bound = _pair(problem)
    assert bound.news() is None  # (nothing yet)
    walk.offer(100, paths)
    got = bound.news()
    assert got == paths
    assert bound.news() is None  # (taken: not again)
    walk.offer(200, {})  # (longer than one already offered: not handed over)
    walk.offer(90, paths)
    bound.offer(80, paths)  # (the bound's side has a shorter one: the walk's is not news)
    assert bound.news() is None
    assert walk.news() == paths


def test_the_squeeze_takes_the_other_sides_shorter_plan_replayed(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # the bound's process squeezes the first plan; the walk's process has handed over a
    # shorter one (from a repair with another seed): it is replayed through the monitors and
    # returned (it meets ``enough``, so the squeeze stops there)
    c, problem, _, router, first = _cell(8, 2)
    # (its first shorter plan: any plan meets an ``enough`` of 10**12 ticks)
    theirs = _squeeze_paths(router, first, time.perf_counter() + DEADLINE_S, 10**12, seed=99)
    assert theirs is not None
    walk, bound = _pair(problem)
    walk.offer(theirs[0], _paths(router, theirs))
    monkeypatch.setattr(anytime, "NEWS_EVERY", 1)
    replayed: list[list[list[int]]] = []
    real = _Router.replay

    def replay(self: _Router, steps: Any) -> Any:
        replayed.append([sorted(i.index for i in step) for step in steps])
        return real(self, steps)

    monkeypatch.setattr(_Router, "replay", replay)
    found = _squeeze_paths(
        router, first, time.perf_counter() + DEADLINE_S, theirs[0], exchange=bound
    )
    assert found is not None and found[0] == theirs[0]
    assert replayed[0] == _steps(theirs) == _steps(found)
    res = PlanResult(PlanStatus.SOLVED, plan_steps(problem, found[1]), to_seconds(found[0]))
    check_plan(c.scene, c.spec, res.to_dict())


def test_the_squeeze_ignores_a_plan_handed_over_with_as_many_steps(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # the walk's side hands over a plan of as many steps as the one being squeezed (said to
    # be shorter): it is not replayed and the level's search goes on (each level is squeezed
    # once: the levels' horizons fall)
    c, problem, _, router, first = _cell(8, 2)
    walk, bound = _pair(problem)
    walk.offer(1, first)
    monkeypatch.setattr(anytime, "NEWS_EVERY", 1)
    taken: list[bool] = []
    real_news = _Exchange.news
    monkeypatch.setattr(_Exchange, "news", lambda self: taken.append(True) or real_news(self))
    replayed: list[list[list[int]]] = []
    real_replay = _Router.replay

    def replay(self: _Router, steps: Any) -> Any:
        replayed.append([sorted(i.index for i in step) for step in steps])
        return real_replay(self, steps)

    horizons: list[int] = []
    real_squeeze = repair.Repair.squeeze

    def squeeze(self: repair.Repair, routes: dict[int, repair.Path], T: int) -> bool:
        horizons.append(T)
        return real_squeeze(self, routes, T)

    monkeypatch.setattr(_Router, "replay", replay)
    monkeypatch.setattr(repair.Repair, "squeeze", squeeze)
    found = _squeeze_paths(router, first, time.perf_counter() + DEADLINE_S, 10**12, exchange=bound)
    assert taken and found is not None
    assert horizons == [repair.length(first) - 1]
    assert [sorted(i.index for i in step) for step in _steps_of(first)] not in replayed
    assert len(found[1]) < repair.length(first)
    res = PlanResult(PlanStatus.SOLVED, plan_steps(problem, found[1]), to_seconds(found[0]))
    check_plan(c.scene, c.spec, res.to_dict())


def test_a_plan_handed_over_that_is_no_plan_is_not_taken(monkeypatch: pytest.MonkeyPatch) -> None:
    # a "plan" that leaves a goal out, claimed very short: replayed, refused, and the squeeze
    # goes on with its own plans (each valid)
    c, problem, _, router, first = _cell(8, 2)
    walk, bound = _pair(problem)
    broken = dict(first)
    broken.pop(0)
    walk.offer(1, broken)
    monkeypatch.setattr(anytime, "NEWS_EVERY", 1)
    taken: list[bool] = []
    real_news = _Exchange.news
    monkeypatch.setattr(_Exchange, "news", lambda self: taken.append(True) or real_news(self))
    cost = repair.length(first)  # (stop at the first shorter plan: any is below this)
    found = _squeeze_paths(router, first, time.perf_counter() + DEADLINE_S, 10**12, exchange=bound)
    assert taken and found is not None and found[0] > 1
    assert len(found[1]) < cost
    res = PlanResult(PlanStatus.SOLVED, plan_steps(problem, found[1]), to_seconds(found[0]))
    check_plan(c.scene, c.spec, res.to_dict())


def test_the_walks_squeeze_does_not_take_the_other_sides_plans_as_they_come(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # the walk's side does not listen: its squeeze goes its own way (the bound process's
    # plans are taken at the end of the run only)
    _, problem, _, router, first = _cell(8, 2)
    ctx = multiprocessing.get_context()
    one, two = _Slot(ctx), _Slot(ctx)
    walk, bound = _Exchange(problem, one, two, listen=False), _Exchange(problem, two, one)
    bound.offer(1, first)
    monkeypatch.setattr(anytime, "NEWS_EVERY", 1)
    taken: list[bool] = []
    real_news = _Exchange.news
    monkeypatch.setattr(_Exchange, "news", lambda self: taken.append(True) or real_news(self))
    found = _squeeze_paths(router, first, time.perf_counter() + DEADLINE_S, 10**12, exchange=walk)
    assert found is not None and not taken
    assert walk.news() == first  # (there all the same, for the end)


def test_the_bound_process_waits_for_a_plan_only_until_its_deadline() -> None:
    # nothing is offered: it looks for news at each reading of its clock (0.02 s of real
    # sleep between two) and returns at the deadline, 0.2 s on a clock of 0.01 s a reading
    _, problem, s, _, _ = _cell(8, 2)
    _, bound = _pair(problem)
    clock = WorkClock(0.01)
    anytime._plans_beside(s, problem.start(), bound, 0, 0.2, clock=clock)
    assert bound.best == float("inf")  # (nothing offered, nothing taken: it just returned)
    assert clock.readings == 21  # (0.00 to 0.19 are before the deadline; 0.20 is not)


@pytest.mark.skipif(not anytime.beside_possible(), reason="one core, or no fork")
def test_the_plan_the_bound_process_squeezed_is_used(monkeypatch: pytest.MonkeyPatch) -> None:
    # a 17-goal grid at a 4 s budget on two cores: the bound's process, its bound final,
    # hands over a plan shorter than any the walk's process has (here the walk makes only its
    # first plan); the run ends with that plan, replayed, valid. On a clock of work (the
    # run's phases end after the same work on any machine) that lets the run wait for the
    # bound's process as long as it runs (60 s at most), so a loaded machine, where the
    # process starts late, hands the plan over too
    c = delivery_cell("grid", 17, 0)
    problem = Problem(c.scene, c.spec)
    s = _Search(problem)
    router = _Router(s, problem.start(), goals(s, problem.start()) or [])
    first = anytime.construct(problem, s)
    shorter = anytime._more(problem, s, time.perf_counter() + DEADLINE_S, rounds=30)
    assert first is not None and shorter is not None and shorter[0] < first[0]
    handed = _paths(router, shorter)

    def bound(*args: Any, **kwargs: Any) -> profile.ProfileBound:
        return profile.ProfileBound(kwargs["floor"], True, 0)  # (final at once)

    def plans(s: Any, start: Any, exchange: _Exchange, *_: Any, **__: Any) -> None:
        exchange.offer(shorter[0], handed)  # type: ignore[index]

    def more(problem: Problem, s: _Search, until: float, **kwargs: Any) -> Any:
        assert not kwargs["exchange"].listen  # (the walk's side of the exchange)
        return anytime.construct(problem, s)

    monkeypatch.setattr(profile, "profile_bound", bound)
    monkeypatch.setattr(anytime, "_plans_beside", plans)
    monkeypatch.setattr(anytime, "_more", more)
    monkeypatch.setattr(schedule, "WORKERS", 2)
    monkeypatch.setattr(anytime, "PROFILE_SHARE", 0.3)
    assert lns.available()  # (imported here: the forked process has it at once)
    clock = WorkClock(0.02, wall_seconds=DEADLINE_S)
    res = plan(c.scene, c.spec, anytime=True, timeout=4.0, clock=clock)
    assert res.status is PlanStatus.SOLVED and res.makespan == to_seconds(shorter[0])
    check_plan(c.scene, c.spec, res.to_dict())


@pytest.mark.parametrize("workers", [1, 2])
def test_the_walk_offers_its_plans_only_when_the_bound_runs_beside(
    monkeypatch: pytest.MonkeyPatch, workers: int
) -> None:
    # one core (or no fork): no process beside, no exchange; the walk runs as before (on a
    # clock of work: the phases end after the same work on any machine)
    if workers == 2 and not anytime.beside_possible():
        pytest.skip("one core, or no fork")
    seen: list[object] = []
    real = anytime._more

    def more(problem: Problem, s: _Search, until: float, **kwargs: Any) -> Any:
        seen.append(kwargs.get("exchange"))
        return real(problem, s, until, **kwargs)

    monkeypatch.setattr(anytime, "_more", more)
    monkeypatch.setattr(schedule, "WORKERS", workers)
    monkeypatch.setattr(anytime, "PROFILE_SHARE", 0.3)
    assert lns.available()
    c = delivery_cell("grid", 17, 0)
    res = plan(c.scene, c.spec, anytime=True, timeout=4.0, clock=WorkClock(0.02))
    assert res.status is PlanStatus.SOLVED
    assert len(seen) == 1 and (seen[0] is None) is (workers == 1)
