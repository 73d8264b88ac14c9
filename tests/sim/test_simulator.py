"""The simulator: people's motion, perception, the driver protocol, failures and violations."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from hltl.execution.drivers import ActionState, RobotDriver
from hltl.execution.log import EventLog
from hltl.sim.events import events_from_dict
from hltl.sim.simulator import PerceptionModel, Simulator
from hltl.skills.library import Action
from hltl.world.scene import Scene, load_scene
from hltl.world.state import Loc

PICK = Action("pick", ("r1",), "bottle")


@pytest.fixture
def cell(two_arms_path: Path) -> Scene:
    return load_scene(two_arms_path)


def _sim(cell: Scene, events: list[dict[str, object]], **kw: object) -> Simulator:
    return Simulator(cell, events_from_dict({"events": events}, cell), log=EventLog(), **kw)  # type: ignore[arg-type]


def test_is_a_robot_driver(cell: Scene) -> None:
    assert isinstance(Simulator(cell), RobotDriver)


def test_people_walk_at_their_speed_and_stop_at_the_target(cell: Scene) -> None:
    sim = _sim(
        cell, [{"t": 1.0, "type": "human_move", "human": "A", "to": [0.5, 0.6, 0.0], "speed": 0.5}]
    )
    sim.advance(1.0)
    assert sim.human_position("A") == pytest.approx((-0.5, 0.6, 0.0))
    sim.advance(2.0)
    assert sim.human_position("A") == pytest.approx((0.0, 0.6, 0.0))
    assert sim.next_event_time() == pytest.approx(3.0)  # the arrival
    sim.advance(5.0)
    assert sim.human_position("A") == pytest.approx((0.5, 0.6, 0.0))
    assert sim.human_position("A", 2.0) == pytest.approx((0.0, 0.6, 0.0))  # the past stays known
    kinds = [(r.type, r.t) for r in sim.log.records]
    assert kinds == [("human_move", 1.0), ("human_stop", 3.0)]


def test_random_walks_are_seeded_and_stay_in_the_cell(cell: Scene) -> None:
    ev = [{"t": 0.0, "type": "human_wander", "human": "B", "duration": 6.0, "speed": 1.0}]
    a, b, c = _sim(cell, ev, seed=1), _sim(cell, ev, seed=1), _sim(cell, ev, seed=2)
    for s in (a, b, c):
        s.advance(6.0)
    assert a.human_position("B") == b.human_position("B") != c.human_position("B")
    x, y, _ = a.human_position("B")
    assert -1.5 <= x <= 2.7 and -1.5 <= y <= 1.5


def test_perception_lags_and_is_noisy_but_reproducible(cell: Scene) -> None:
    ev = [{"t": 0.0, "type": "human_move", "human": "A", "to": [1.5, 0.6, 0.0], "speed": 1.0}]
    late = _sim(cell, ev, perception=PerceptionModel(latency=0.2))
    late.advance(1.0)
    obs = late.observe(1.0)
    assert obs.t == pytest.approx(0.8)
    assert obs.human_position("A") == pytest.approx((0.3, 0.6, 0.0))
    noisy = [_sim(cell, [], seed=s, perception=PerceptionModel(noise=0.01)) for s in (7, 7, 8)]
    seen = [s.observe(0.0).human_position("B") for s in noisy]
    assert seen[0] == seen[1] != seen[2]
    assert math.dist(seen[0], (1.9, 0.5, 0.0)) < 0.06


def test_actions_take_their_duration_and_change_the_world(cell: Scene) -> None:
    sim = _sim(cell, [])
    h = sim.start(PICK, 0.0)
    assert sim.next_event_time() == pytest.approx(0.5)
    sim.advance(0.25)
    st = sim.poll(h, 0.25)
    assert st.state is ActionState.RUNNING and st.progress == pytest.approx(0.5)
    sim.advance(0.5)
    st = sim.poll(h, 0.5)
    assert st.state is ActionState.DONE and st.t == pytest.approx(0.5)
    assert sim.object_status("bottle").loc == Loc("held", "r1")
    busy = sim.start(Action("pick", ("r2",), "chips"), 0.5)
    again = sim.start(Action("place", ("r2",), "chips", surface="shelf"), 0.5)
    assert sim.poll(busy, 0.5).state is ActionState.RUNNING
    assert sim.poll(again, 0.5).state is ActionState.FAILED  # r2 is busy


def test_halt_stops_without_effect(cell: Scene) -> None:
    sim = _sim(cell, [])
    h = sim.start(PICK, 0.0)
    sim.advance(0.2)
    sim.halt(h, 0.2, "test")
    sim.advance(1.0)
    st = sim.poll(h, 1.0)
    assert st.state is ActionState.HALTED and st.reason == "test"
    assert sim.object_status("bottle").loc == Loc("rest")


@pytest.mark.parametrize("outcome", ["stay", "drop"])
def test_injected_failures(cell: Scene, outcome: str) -> None:
    sim = _sim(
        cell,
        [
            {
                "type": "skill_failure",
                "skill": "handover_r2h",
                "probability": 1.0,
                "outcome": outcome,
            }
        ],
    )
    sim.start(PICK, 0.0)
    sim.advance(0.5)
    h = sim.start(Action("handover_r2h", ("r1",), "bottle", human="A"), 0.5)
    sim.advance(1.0)
    st = sim.poll(h, 1.0)
    assert st.state is ActionState.FAILED
    bottle = sim.object_status("bottle")
    if outcome == "stay":
        assert bottle.loc == Loc("held", "r1")
    else:
        assert bottle.loc == Loc("rest") and "dropped" in st.reason
        assert bottle.position[2] == pytest.approx(0.05)  # the object's original height
        assert math.dist(bottle.position, cell.robot("r1").base) <= 0.7  # r1 can pick it again
        assert [r.type for r in sim.log.records] == ["object_drop"]


def test_robot_down_fails_its_action_and_comes_back(cell: Scene) -> None:
    sim = _sim(cell, [{"t": 0.2, "type": "robot_down", "robot": "r1", "duration": 1.0}])
    h = sim.start(PICK, 0.0)
    sim.advance(0.3)
    st = sim.poll(h, 0.3)
    assert st.state is ActionState.FAILED and "went down" in st.reason
    assert sim.unavailable(0.3) == frozenset({"r1"})
    sim.advance(1.5)
    assert sim.unavailable(1.5) == frozenset()
    assert [r.type for r in sim.log.records] == ["robot_down", "robot_up"]


def test_handover_to_a_person_who_left_fails_and_is_a_violation(cell: Scene) -> None:
    sim = _sim(
        cell, [{"t": 0.6, "type": "human_move", "human": "A", "to": [-1.5, 0.6, 0.0], "speed": 3.0}]
    )
    sim.start(PICK, 0.0)
    sim.advance(0.5)
    h = sim.start(Action("handover_r2h", ("r1",), "bottle", human="A"), 0.5)
    sim.advance(1.0)
    st = sim.poll(h, 1.0)
    assert st.state is ActionState.FAILED and "precondition false at completion" in st.reason
    assert sim.object_status("bottle").loc == Loc("held", "r1")
    violations = [r for r in sim.log.records if r.type == "violation"]
    assert len(violations) == 1 and "not inside r1's workspace" in violations[0].reason


def test_object_moved_during_a_grasp_makes_it_fail(cell: Scene) -> None:
    sim = _sim(
        cell, [{"t": 0.2, "type": "object_move", "object": "bottle", "to": [-0.3, 0.3, 0.05]}]
    )
    h = sim.start(PICK, 0.0)
    sim.advance(0.5)
    st = sim.poll(h, 0.5)
    assert st.state is ActionState.FAILED and "moved away from the grasp" in st.reason
    assert sim.object_status("bottle").position == pytest.approx((-0.3, 0.3, 0.05))
