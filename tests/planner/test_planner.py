"""The exact planner on hand-made cells whose optimal makespans are worked out by hand."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

from hltl.errors import UnknownEntityError
from hltl.planner import PlanStatus, plan
from hltl.skills.library import Action
from hltl.spec.hierarchy import HSpec, spec_from_dict
from hltl.spec.monitor import HierarchyMonitor
from hltl.spec.syntax import Atom
from hltl.world.scene import Scene, load_scene, scene_from_dict
from hltl.world.state import Loc, ObjectStatus, initial_world

FIG1 = {
    "root": "p0",
    "formulas": {
        "p0": "F p100 & F p200",
        "p100": "F delivered(bottle, A)",
        "p200": "F delivered(chips, B)",
    },
}


def _spec(formulas: dict[str, str], root: str = "p0") -> HSpec:
    return spec_from_dict({"root": root, "formulas": formulas})


def _one(leaf: str) -> HSpec:
    return _spec({"p0": "F p100", "p100": leaf})


@pytest.fixture
def cell(two_arms_path: Path) -> Scene:
    return load_scene(two_arms_path)


@pytest.mark.parametrize("algorithm", ["astar", "dijkstra"])
def test_fig1_parallel_deliveries(cell: Scene, algorithm: str) -> None:
    # both arms pick at once (0.5 s), then both hand over at once (0.5 s)
    res = plan(cell, spec_from_dict(FIG1), algorithm=algorithm)
    assert res.status is PlanStatus.SOLVED
    assert res.makespan == pytest.approx(1.0)
    assert [len(s.actions) for s in res.steps] == [2, 2]
    assert res.steps[1].start == pytest.approx(0.5)
    roles = {(b.robot, b.leaf, b.role) for s in res.steps for b in s.bindings}
    assert roles == {("r1", "p100", "solo"), ("r2", "p200", "solo")}


@pytest.mark.parametrize("algorithm", ["astar", "dijkstra"])
def test_far_object_needs_robot_to_robot_handover(cell: Scene, algorithm: str) -> None:
    # chips is only reachable by r2, Person A only by r1: pick 0.5 + r2r 0.6 + r2h 0.5
    res = plan(cell, _one("F delivered(chips, A)"), algorithm=algorithm)
    assert res.makespan == pytest.approx(1.6)
    assert [a.skill for a in res.actions] == ["pick", "handover_r2r", "handover_r2h"]
    assert res.steps[1].actions[0] == Action("handover_r2r", ("r2", "r1"), "chips")
    roles = [sorted((b.robot, b.role) for b in s.bindings) for s in res.steps]
    assert roles == [[("r2", "giver")], [("r1", "receiver"), ("r2", "giver")], [("r1", "receiver")]]


def test_person_between_the_arms_forces_place_and_regrasp(cell: Scene) -> None:
    # Person C stands inside both workspaces: no arm-to-arm exchange next to a person, so the
    # chips go over the shelf: pick 0.5, place 0.5, pick 0.5, hand over 0.5
    data = cell.to_dict()
    data["humans"].append({"id": "C", "name": "Person C", "position": [0.6, -0.4, 0.0]})
    scene = scene_from_dict(data)
    res = plan(scene, _one("F delivered(chips, A)"))
    assert res.makespan == pytest.approx(2.0)
    assert [a.skill for a in res.actions] == ["pick", "place", "pick", "handover_r2h"]
    assert all(a.skill != "handover_r2r" for a in res.actions)


def test_ordering_is_non_strict(cell: Scene) -> None:
    ordered = _spec(
        {
            "p0": "F (p100 & F p200)",
            "p100": "F delivered(bottle, A)",
            "p200": "F delivered(chips, B)",
        }
    )
    res = plan(cell, ordered)
    assert res.makespan == pytest.approx(1.0)  # both may complete in the same step


def test_strict_order_costs_a_step(cell: Scene) -> None:
    strict = _spec(
        {
            "p0": "F (p100 & X F p200)",
            "p100": "F delivered(bottle, A)",
            "p200": "F delivered(chips, B)",
        }
    )
    res = plan(cell, strict)
    # bottle: pick, hand (1.0); the chips handover must come in a later step: +0.5
    assert res.makespan == pytest.approx(1.5)


def test_alternative_takes_the_cheaper_branch(cell: Scene) -> None:
    either = _spec(
        {
            "p0": "F p100 | F p200",
            "p100": "F delivered(chips, A)",
            "p200": "F delivered(bottle, A)",
        }
    )
    res = plan(cell, either)
    assert res.makespan == pytest.approx(1.0)
    assert {a.object for a in res.actions} == {"bottle"}


def test_placement_and_state_atoms(cell: Scene) -> None:
    res = plan(cell, _one("F at(chips, shelf)"))
    assert res.makespan == pytest.approx(1.0)
    assert res.actions[-1] == Action("place", ("r2",), "chips", surface="shelf")


def test_out_of_reach_is_infeasible_with_a_reason(cell: Scene) -> None:
    data = cell.to_dict()
    data["objects"].append({"id": "cup", "category": "cup", "position": [5.0, 5.0, 0.0]})
    scene = scene_from_dict(data)
    res = plan(scene, _one("F delivered(cup, A)"))
    assert res.status is PlanStatus.INFEASIBLE
    assert "cup" in res.reason and "out of reach of every available robot" in res.reason
    assert res.stats.expanded == 0  # proved by the heuristic before any search


def test_person_outside_every_workspace(cell: Scene) -> None:
    data = cell.to_dict()
    data["humans"][1]["position"] = [4.0, 0.0, 0.0]
    res = plan(scene_from_dict(data), spec_from_dict(FIG1))
    assert res.status is PlanStatus.INFEASIBLE
    assert (
        "Person B (B)" in res.reason and "outside every available robot's workspace" in res.reason
    )


def test_object_needed_twice_is_infeasible(cell: Scene) -> None:
    twice = _spec(
        {
            "p0": "F p100 & F p200",
            "p100": "F delivered(bottle, A)",
            "p200": "F delivered(bottle, B)",
        }
    )
    res = plan(cell, twice)
    assert res.status is PlanStatus.INFEASIBLE
    assert "p0" in res.reason


def test_unknown_entity_in_spec(cell: Scene) -> None:
    with pytest.raises(UnknownEntityError, match=r"unknown object 'cup'.*bottle, chips"):
        plan(cell, _one("F delivered(cup, A)"))


def test_replanning_from_a_mid_episode_state(cell: Scene) -> None:
    # r1 already holds the bottle and the bottle leaf is done: only the chips remain
    spec = spec_from_dict(FIG1)
    mon = HierarchyMonitor(spec)
    q = mon.step(mon.initial, frozenset({Atom("delivered", ("bottle", "A"))}))
    assert mon.done(q) >= {"p100"}
    world = initial_world(cell).with_object(
        "chips", ObjectStatus((1.5, -0.3, 0.3), Loc("held", "r2"))
    )
    res = plan(cell, spec, world=world, monitor=mon, q0=q)
    assert res.makespan == pytest.approx(0.5)
    assert res.actions == (Action("handover_r2h", ("r2",), "chips", human="B"),)


def test_unavailable_robot_is_never_used(cell: Scene) -> None:
    world = initial_world(cell).with_unavailable(frozenset({"r2"}))
    res = plan(cell, spec_from_dict(FIG1), world=world)
    assert res.status is PlanStatus.INFEASIBLE
    res = plan(cell, _one("F delivered(bottle, A)"), world=world)
    assert res.solved and all("r2" not in a.robots for a in res.actions)


def test_plan_json_round_trip(cell: Scene) -> None:
    from hltl.planner.result import PlanResult

    res = plan(cell, spec_from_dict(FIG1))
    data: dict[str, Any] = res.to_dict(spec=FIG1, scene="two_arms.yaml")
    assert data["status"] == "solved" and data["scene"] == "two_arms.yaml"
    assert data["steps"][0]["bindings"]["r1"] == ["p100", "solo"]
    back = PlanResult.from_dict(data)
    assert back.steps == res.steps and back.makespan == res.makespan


def test_analytic_durations_track_the_hand(cell: Scene) -> None:
    data = cell.to_dict()
    del data["durations"]
    scene = scene_from_dict(data)
    res = plan(scene, spec_from_dict(FIG1))
    assert res.solved
    # every step lasts at least the grasp/release time and the total is the sum of the steps
    assert all(s.duration >= 0.3 for s in res.steps)
    assert res.makespan == pytest.approx(sum(s.duration for s in res.steps))
    dijkstra = plan(scene, spec_from_dict(FIG1), algorithm="dijkstra")
    assert dijkstra.makespan == pytest.approx(res.makespan)


def test_deadlock_is_explained_by_the_current_situation(cell: Scene) -> None:
    # r1 holds the bottle, r2 the chips, no shelf, and Person A now stands where only r2 serves
    # them: the bottle must reach A through r2, whose hand is full, and the chips may not go to
    # B first. The cup's delivery is already done and must not be blamed.
    data = cell.to_dict()
    data["surfaces"] = []
    data["objects"].append({"id": "cup", "category": "cup", "position": [1.4, 0.3, 0.05]})
    scene = scene_from_dict(data)
    spec = _spec(
        {
            "p0": "F p1 & F p300",
            "p1": "F (p100 & F p200)",
            "p100": "F delivered(bottle, A)",
            "p200": "F delivered(chips, B)",
            "p300": "F delivered(cup, B)",
        }
    )
    mon = HierarchyMonitor(spec)
    q = mon.step(mon.initial, frozenset({Atom("delivered", ("cup", "B"))}))
    world = (
        initial_world(scene)
        .with_human("A", (1.6, 0.6, 0.0))
        .with_object("bottle", ObjectStatus((0.3, 0.0, 0.3), Loc("held", "r1")))
        .with_object("chips", ObjectStatus((1.4, 0.0, 0.3), Loc("held", "r2")))
        .with_object("cup", ObjectStatus((1.9, 0.5, 1.0), Loc("delivered", "B")))
    )
    res = plan(scene, spec, world=world, monitor=mon, q0=q)
    assert res.status is PlanStatus.INFEASIBLE
    assert "r1 holds bottle; r2 holds chips; A served by r2; B served by r2" in res.reason
    assert "cup" not in res.reason
