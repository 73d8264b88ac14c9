"""Conflict repair (``planner/repair.py``): plans in fewer steps, every one valid."""

from __future__ import annotations

import math
import random
import time
from typing import Any

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.bench.cells import delivery_cell
from hltl.planner import PlanResult, PlanStatus, WorkClock, anytime, repair
from hltl.planner.anytime import _more, _orders, _OrderWalk, _Router, _squeezed, goals
from hltl.planner.problem import Problem, to_seconds
from hltl.planner.search import _Search, plan_steps
from hltl.spec.hierarchy import spec_from_dict
from hltl.world.scene import scene_from_dict
from tests.oracles.random_instances import random_instance
from tests.oracles.validator import check_plan


def _first(layout: str, n: int, seed: int) -> tuple[Problem, _Router, dict[int, repair.Path]]:
    """A cell, its router and the first prioritized plan's paths (steps counted from 0)."""
    c = delivery_cell(layout, n, seed)
    problem = Problem(c.scene, c.spec)
    s = _Search(problem)
    node = problem.start()
    gls = goals(s, node)
    assert gls
    router = _Router(s, node, gls)
    assert router.route_all(_orders(s, node, gls, seed=0)()) is not None
    return problem, router, repair.ranked({gi: rt[0] for gi, rt in router.routes.items()})


def _recount(rep: repair.Repair) -> tuple[int, int, list[int]]:
    """Clashes, weighted clashes and the goals in a clash, counted again from the routes."""
    count: dict[tuple[int, int], int] = {}
    for _, cells, _ in rep.routes.values():
        for t, used in cells:
            for r in range(len(rep.p.robots)):
                if used >> r & 1:
                    count[(t, r)] = count.get((t, r), 0) + 1
    clashes = sum(n - 1 for n in count.values())
    weighted = sum((n - 1) * rep.weight[t][r] for (t, r), n in count.items())
    clashing = [
        gi
        for gi, (_, cells, _) in rep.routes.items()
        if any(used >> r & 1 and count[(t, r)] > 1 for t, used in cells for r in range(32))
    ]
    return clashes, weighted, clashing


def _use_costs(rep: repair.Repair) -> list[list[int]]:
    """What one more use of each robot in each step costs, from the table's counts and
    weights (and a 0 past the last robot)."""
    return [
        [repair.CLASH * w if n else 0 for n, w in zip(row, weights, strict=True)] + [0]
        for row, weights in zip(rep.count, rep.weight, strict=True)
    ]


@pytest.mark.parametrize(
    ("layout", "n", "seed", "fewer"),
    [("grid", 8, 2, 5), ("random", 12, 0, 2), ("line", 8, 2, 1), ("grid", 17, 1, 3)],
)
def test_repair_squeezes_the_first_plan_into_fewer_steps_and_every_plan_is_valid(
    layout: str, n: int, seed: int, fewer: int
) -> None:
    # from the first prioritized plan (grid 8 x 8 seed 2: 16 steps, 9.2 s), a few hundred
    # moves take out steps one at a time; each plan without clashes passes the validator,
    # and the clash counts (and the goals in a clash) kept move by move are the ones counted
    # from the routes, as are what one more use of each robot costs
    c = delivery_cell(layout, n, seed)
    problem, router, paths = _first(layout, n, seed)
    rep = repair.Repair(
        problem, problem.start()[0], [g.obj for g in router.goals], router.fires, router.alive, 0
    )
    start_steps = repair.length(paths)
    assert rep.squeeze(paths, start_steps - 1)
    found = []
    for move in range(400):
        if rep.clashes:
            rep.step()
            if n <= 12 or move % 20 == 0:
                assert _recount(rep) == (rep.clashes, rep.weighted, rep._clashing())
                assert rep.rcost == _use_costs(rep)
            continue
        steps = rep.steps()
        plan_ = router.replay(steps)
        assert plan_ is not None and len(steps) < start_steps
        res = PlanResult(PlanStatus.SOLVED, plan_steps(problem, plan_[1]), to_seconds(plan_[0]))
        check_plan(c.scene, c.spec, res.to_dict())
        found.append(len(steps))
        if start_steps - len(steps) >= fewer:
            break
        paths = rep.paths()
        if not rep.squeeze(paths, repair.length(paths) - 1):
            break
    assert found and found == sorted(found, reverse=True)
    assert start_steps - found[-1] >= fewer


def _brute(rep: repair.Repair, gi: int) -> int | None:
    """Every sequence of waits and instances of goal ``gi`` whose atom happens inside the
    horizon: the least cost (clashes at their weights, then robot-steps), or None."""
    p = rep.p
    obj = rep._obj(gi)
    best: int | None = None

    def go(loc: int, t: int, cost: int) -> None:
        nonlocal best
        if t >= rep.T:
            return
        h = p.code_holder.get(loc)
        hb = 0 if h is None else 1 << h
        for inst in p.by_obj_pre[obj][loc]:
            used = inst.executors | hb
            c = cost + used.bit_count()
            c += repair.CLASH * sum(
                rep.weight[t][r] for r in range(32) if (used & rep.occ[t]) >> r & 1
            )
            if inst.index in rep.fires[gi]:
                best = c if best is None else min(best, c)
            else:
                go(inst.post, t + 1, c)
        wait = 0 if h is None else 1 + (repair.CLASH * rep.weight[t][h] if hb & rep.occ[t] else 0)
        go(loc, t + 1, cost + wait)

    go(rep.start[obj], 0, 0)
    return best


def _cost(rep: repair.Repair, cells: list[tuple[int, int]]) -> int:
    out = 0
    for t, used in cells:
        out += used.bit_count()
        out += repair.CLASH * sum(
            rep.weight[t][r] for r in range(32) if (used & rep.occ[t]) >> r & 1
        )
    return out


@settings(max_examples=40, deadline=None)
@given(st.integers(0, 10**6), st.integers(0, 10**6), st.integers(2, 5))
def test_each_route_has_the_fewest_weighted_clashes_then_robot_steps(
    seed: int, table_seed: int, horizon: int
) -> None:
    # the router of the repair against a random table of other routes (each robot and step
    # used 0-2 times, weights 1-3): the least cost of every sequence of waits and instances
    scene_d, spec_d = random_instance(seed)
    problem = Problem(scene_from_dict(scene_d), spec_from_dict(spec_d))
    s = _Search(problem)
    gls = goals(s, problem.start())
    if not gls or not repair.applicable(
        problem, [g.atom.name for g in gls], [g.after for g in gls]
    ):
        return
    router = _Router(s, problem.start(), gls)
    rep = repair.Repair(
        problem, problem.start()[0], [g.obj for g in gls], router.fires, router.alive, 0
    )
    rep.routes = {}
    rep._reset(horizon)
    rng = random.Random(table_seed)
    for t in range(horizon):
        for r in range(len(problem.robots)):
            rep.count[t][r] = rng.choice((0, 0, 1, 2))
            rep.weight[t][r] = rng.choice((1, 1, 2, 3))
            if rep.count[t][r]:
                rep.occ[t] |= 1 << r
                rep.rcost[t][r] = repair.CLASH * rep.weight[t][r]
    # (and the same routes when each instance's robots are summed from its mask, the form of
    # instances of more than two robots)
    masks = [
        [
            (hb, hr, [[(*a[:5], -1, a[4].executors | max(hb, 0)) for a in out] for out in by_left])
            for hb, hr, by_left in per
        ]
        for per in rep.arcs
    ]
    for gi in range(len(gls)):
        found = rep.route(gi)
        want = _brute(rep, gi)
        kept, rep.arcs = rep.arcs, masks
        assert rep.route(gi) == found
        rep.arcs = kept
        if found is None:
            assert want is None
            continue
        path, cells, end = found
        here = rep.start[rep._obj(gi)]
        last = -1
        for t, inst in path:  # a route: each instance where the last left its object
            assert inst.pre == here and last < t < horizon
            here, last = inst.post, t
        assert end == last and path[-1][1].index in rep.fires[gi]
        assert _cost(rep, cells) == want


def test_big_cells_squeeze_the_walks_plan_after_its_share(monkeypatch: pytest.MonkeyPatch) -> None:
    # beyond CP_UP_TO goals (no joint re-plan), when asked, the walk stops after
    # REPAIR_WALK_SHARE of the time and the repair squeezes its best plan; the plan returned
    # is valid and no longer. The share is 0 (session 23): the repair squeezes the walk's first
    # plan before any round of the walk. (The deadlines only bound how long each run takes:
    # the walk's first plan is made before any is read, the share 0 is over at once, and a
    # squeeze cut short by load returns None or a plan no longer, so nothing asserted here
    # depends on the machine's speed.)
    events: list[str] = []
    real_step = _OrderWalk.step
    real_squeezed = anytime._squeezed
    got: list[object] = []

    def squeezed(*args: object, **kwargs: object) -> object:
        events.append("repair")
        out = real_squeezed(*args, **kwargs)  # type: ignore[arg-type]
        got.append(out)
        return out

    monkeypatch.setattr(anytime, "_squeezed", squeezed)
    monkeypatch.setattr(_OrderWalk, "step", lambda self: events.append("walk") or real_step(self))
    c = delivery_cell("grid", 17, 2)
    problem = Problem(c.scene, c.spec)
    # (budgets on a clock of work: 50 and 150 rounds or moves, on any machine)
    assert _more(problem, _Search(problem), 0.5, clock=WorkClock(0.01)) is not None
    assert "repair" not in events  # (only when asked: not on lines, not at 1 s)
    events.clear()
    found = _more(problem, _Search(problem), 1.5, squeeze=True, clock=WorkClock(0.01))
    assert found is not None
    assert events[0] == "repair"
    assert got[0] is None or found[0] <= got[0][0]  # type: ignore[index]
    res = PlanResult(PlanStatus.SOLVED, plan_steps(problem, found[1]), to_seconds(found[0]))
    check_plan(c.scene, c.spec, res.to_dict())
    # with rounds (exact mode's roof: a plan independent of the machine) no repair
    events.clear()
    more = _more(problem, _Search(problem), time.perf_counter() + 5, rounds=3, squeeze=True)
    assert more is not None
    assert "repair" not in events


# the repair's budget in the tests: moves, not seconds (grid 8 x 8 seed 2 squeezes its first
# plan four times in the first 50; a few hundred moves take 0.1 s at quiet)
MOVES = 400


def _spy(monkeypatch: pytest.MonkeyPatch, name: str) -> list[int]:
    """How often ``repair.Repair.<name>`` is called (with the horizon, for ``squeeze``)."""
    calls: list[int] = []
    real = getattr(repair.Repair, name)

    def spy(self: repair.Repair, *args: Any) -> Any:
        calls.append(args[-1] if args else 0)
        return real(self, *args)

    monkeypatch.setattr(repair.Repair, name, spy)
    return calls


def test_squeezed_stops_at_a_plan_that_meets_the_bound(monkeypatch: pytest.MonkeyPatch) -> None:
    # a plan no longer than a lower bound is optimal: the repair returns the first plan it
    # finds at or below ``enough`` instead of squeezing it again; without a bound it goes on
    # squeezing each plan it finds (a budget in moves, not wall time: the same on any machine)
    calls = _spy(monkeypatch, "squeeze")
    _, router, _ = _first("grid", 8, 2)
    found = _squeezed(router, dict(router.routes), math.inf, enough=10**12, moves=MOVES)
    assert found is not None and len(calls) == 1
    calls.clear()
    again = _squeezed(router, dict(router.routes), math.inf, moves=MOVES)
    assert again is not None and again[0] < found[0] and len(calls) > 1


def test_squeezed_makes_at_most_its_moves(monkeypatch: pytest.MonkeyPatch) -> None:
    # ``moves`` ends the repair, not the clock (here a safety net of ten minutes): the plan
    # does not depend on the machine's speed
    steps = _spy(monkeypatch, "step")
    _, router, _ = _first("grid", 8, 2)
    few = _squeezed(router, dict(router.routes), time.perf_counter() + 600.0, moves=25)
    assert few is not None and 0 < len(steps) <= 25
    steps.clear()
    assert _squeezed(router, dict(router.routes), time.perf_counter() + 600.0, moves=25) == few
    assert 0 < len(steps) <= 25


def test_a_level_starts_again_from_its_plan_after_restart_moves(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # squeezed far below what the cell allows (grid 8 x 8 seed 2: 16 steps, the optimum 11),
    # the clashes stay: after RESTART moves the repair starts again from the plan it squeezed
    # (the goals done before the horizon on their old routes, the weights afresh), then after
    # twice as many; a squeeze of another plan starts the count again
    monkeypatch.setattr(repair, "RESTART", 25)
    monkeypatch.setattr(repair, "STUCK", 3)  # (weights raised within the moves)
    problem, router, paths = _first("grid", 8, 2)
    rep = repair.Repair(
        problem, problem.start()[0], [g.obj for g in router.goals], router.fires, router.alive, 0
    )
    T = 7
    assert rep.squeeze(paths, T)
    kept = {gi: path for gi, path in paths.items() if path[-1][0] < T}
    assert kept and len(kept) < len(paths)
    for restarts, moves in ((1, 25), (2, 50)):
        for _ in range(moves):
            assert rep.clashes
            rep.step()
        assert rep.moves == moves and rep.restarts == restarts - 1
        assert any(w > 1 for row in rep.weight for w in row)  # (breakout raised some)
        rep.step()
        assert rep.moves == 0 and rep.restarts == restarts
        assert all(w == 1 for row in rep.weight for w in row)
        assert all(rep.routes[gi][0] == path for gi, path in kept.items())
        assert _recount(rep) == (rep.clashes, rep.weighted, rep._clashing())
        assert rep.rcost == _use_costs(rep)
    assert rep.squeeze(dict(paths), T)
    assert rep.moves == 0 and rep.restarts == 0
