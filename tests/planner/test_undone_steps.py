"""Undone steps: an instance that takes its object straight back is never generated, and the
optimum stays (docs/planner.md, "Undone steps").

With fixed durations, a step that hands an object from one robot to another (or puts it down)
followed by a step that takes it straight back, both invisible to the monitors, can lose both
instances: the rule leaves such a pair out. A monitor that sees the object's place needs the
trip, so the rule must stay off there; and a node reached several ways leaves the trip out only
when every way in made it.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from hltl.planner import PlanStatus, plan
from hltl.planner.problem import Instance, Node, Problem
from hltl.planner.search import Tag, _Search, search
from hltl.sim.scenarios import generate
from hltl.skills.cost import AnalyticCostModel
from hltl.spec.hierarchy import HSpec, spec_from_dict
from hltl.world.scene import Scene, load_scene
from tests.oracles.brute_force import optimal_makespan
from tests.oracles.validator import check_against_optimum


def _spec(**leaves: str) -> HSpec:
    root = " & ".join(f"F {name}" for name in leaves)
    return spec_from_dict({"root": "p0", "formulas": {"p0": root, **leaves}})


@pytest.fixture
def cell(two_arms_path: Path) -> Scene:
    return load_scene(two_arms_path)


def _handed_to_r2(s: _Search) -> tuple[Node, Tag, Instance]:
    """Fig. 1's bottle picked by r1 and handed to r2: the node, the handover step's tag, and
    the handover back to r1."""
    picked = [
        (child, tag)
        for U, _, child, tag, _ in s.steps(s.p.start())
        if _names(U) == {"pick(bottle) by r1"}
    ]
    assert len(picked) == 1
    node, tag = picked[0]
    given = [
        (child, tag)
        for U, _, child, tag, _ in s.steps(node, [tag])
        if _names(U) == {"handover_r2r(bottle) by r1→r2"}
    ]
    assert len(given) == 1
    back = [i for i in s.p.instances if str(i.action) == "handover_r2r(bottle) by r2→r1"]
    assert len(back) == 1
    return given[0][0], given[0][1], back[0]


def _names(U: tuple[Instance, ...]) -> set[str]:
    return {str(i.action) for i in U}


def _generated(s: _Search, node: Node, tags: list[Tag]) -> set[int]:
    return {i.index for U, *_ in s.steps(node, tags) for i in U}


def test_the_handover_back_is_not_generated_after_the_handover(cell: Scene) -> None:
    # the bottle goes to Person B, on r2's side: handed to r2 it may go back to r1 later, but
    # not in the very next step
    s = _Search(Problem(cell, _spec(p100="F delivered(bottle, B)")))
    node, tag, back = _handed_to_r2(s)
    assert s.undoes(back)
    assert back.index not in _generated(s, node, [tag])
    # the same node with no way in (a start): the handover back is an ordinary successor
    assert back.index in _generated(s, node, [])


def test_the_handover_back_stays_when_another_way_in_did_not_make_the_trip(cell: Scene) -> None:
    s = _Search(Problem(cell, _spec(p100="F delivered(bottle, B)")))
    node, tag, back = _handed_to_r2(s)
    # an equally cheap way in that took nothing from r1 (its places-left mask is empty)
    other: Tag = (tag[0], tag[1], tag[2], 0)
    assert back.index in _generated(s, node, [tag, other])
    assert back.index in _generated(s, node, [other, tag])


def test_a_monitor_that_sees_the_trip_keeps_it(cell: Scene) -> None:
    # r2 must hold the bottle once, and Person A (r1's side) gets it: r1 picks, hands it to r2,
    # which hands it straight back, and r1 hands it over: 0.5 + 0.6 + 0.6 + 0.5 s. Leaving the
    # handover back out (it is visible: holding(r2, bottle) holds before it) would cost the
    # shelf instead: 0.5 + 0.6 + 0.5 + 0.5 + 0.5 s
    spec = _spec(p100="F holding(r2, bottle)", p200="F delivered(bottle, A)")
    p = Problem(cell, spec)
    s = _Search(p)
    node, tag, back = _handed_to_r2(s)
    assert not s.undoes(back)
    assert back.index in _generated(s, node, [tag])
    res = plan(cell, spec)
    assert res.status is PlanStatus.SOLVED and res.makespan == pytest.approx(2.2)
    check_against_optimum(cell, spec, res, optimal_makespan(cell, spec))


def test_the_rule_is_off_where_durations_follow_the_hands(cell: Scene) -> None:
    cost = AnalyticCostModel(tuple((r.id, 0.5) for r in cell.robots))
    s = _Search(Problem(cell, _spec(p100="F delivered(bottle, B)"), cost=cost))
    assert not any(s.undoes(i) for i in s.p.instances)


def test_picks_places_and_handovers_take_part_deliveries_do_not(cell: Scene) -> None:
    s = _Search(Problem(cell, _spec(p100="F delivered(bottle, B)")))
    by_skill: dict[str, set[bool]] = {}
    for i in s.p.instances:
        by_skill.setdefault(i.action.skill, set()).add(s.undoes(i))
    assert by_skill["handover_r2r"] == {True}
    assert by_skill["pick"] == {True}
    assert by_skill["place"] == {True}
    assert by_skill["handover_r2h"] == {False, True}  # (only delivered(bottle, B) is seen)


@pytest.mark.parametrize(("n", "layout", "seed"), [(4, "line", 1), (4, "grid", 2), (5, "line", 0)])
def test_relay_cells_keep_the_optimum_with_fewer_nodes(
    n: int, layout: str, seed: int, monkeypatch: pytest.MonkeyPatch
) -> None:
    # relays on a line or grid: a handover back is a successor of nearly every expansion
    sc = generate(n, n, layout, seed, ordered=False)
    expected = optimal_makespan(sc.scene, sc.spec, max_nodes=1_000_000)
    res = search(Problem(sc.scene, sc.spec), timeout=None)
    check_against_optimum(sc.scene, sc.spec, res, expected)
    monkeypatch.setattr(_Search, "undoes", lambda self, inst: False)
    without = search(Problem(sc.scene, sc.spec), timeout=None)
    assert without.makespan == res.makespan
    assert res.stats.generated < without.stats.generated
