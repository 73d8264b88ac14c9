"""Trajectory prediction, workspace voting, safety hazards and the log format."""

from __future__ import annotations

import json
import random
from pathlib import Path

import pytest

from hltl.errors import PlanFormatError
from hltl.execution.log import (
    ActionDone,
    ActionFailed,
    ActionHalted,
    ActionRecord,
    ActionStart,
    EpisodeStart,
    EventLog,
    HumanMove,
    LogRecord,
    PolicyReplan,
    Wait,
    read_log,
    world_from_dict,
    world_to_dict,
)
from hltl.execution.predict import (
    ConstantVelocityPredictor,
    predict_workspace,
    predicted_world,
)
from hltl.execution.safety import intrusion_hazard, precondition_hazard, step_conflict
from hltl.skills.library import Action
from hltl.world.scene import Scene, load_scene
from hltl.world.state import Loc, ObjectStatus, initial_world


@pytest.fixture
def cell(two_arms_path: Path) -> Scene:
    return load_scene(two_arms_path)


def _walk(
    pred: ConstantVelocityPredictor,
    start: tuple[float, float],
    v: tuple[float, float],
    t1: float,
    noise: float = 0.0,
    seed: int = 0,
) -> None:
    rng = random.Random(seed)
    t = 0.0
    while t <= t1 + 1e-9:
        x = start[0] + v[0] * t + rng.gauss(0, noise)
        y = start[1] + v[1] * t + rng.gauss(0, noise)
        pred.observe(t, [("A", (x, y, 0.0))])
        t = round(t + 0.05, 9)


def test_constant_velocity_extrapolates_a_straight_walk() -> None:
    p = ConstantVelocityPredictor()
    _walk(p, (0.0, 0.0), (1.0, 0.5), 1.0)
    assert p.velocity("A") == pytest.approx((1.0, 0.5))
    ((x, y, _),) = p.predict("A", [2.0])
    assert (x, y) == pytest.approx((2.0, 1.0))
    assert p.moving("A")


def test_noise_on_a_standing_person_is_not_taken_for_walking() -> None:
    p = ConstantVelocityPredictor()
    _walk(p, (0.3, 0.2), (0.0, 0.0), 2.0, noise=0.01, seed=3)
    assert p.velocity("A") == (0.0, 0.0)
    assert not p.moving("A")
    ((x, y, _),) = p.predict("A", [5.0])
    assert (x, y) == pytest.approx((0.3, 0.2), abs=0.02)


def test_workspace_vote_follows_the_majority_over_the_horizon(cell: Scene) -> None:
    p = ConstantVelocityPredictor()
    # walking from Person A's spot towards r2 at 1.5 m/s: over 1.5 s the forecast spends most
    # samples past the middle, so the vote is a label containing r2
    _walk(p, (-0.5, 0.6), (1.5, 0.0), 0.3)
    pred = predict_workspace(cell, p, "A", 0.3, horizon=1.5, dt=0.1)
    assert pred.samples == 15 and pred.votes > 7
    assert "r2" in pred.robots
    w = predicted_world(initial_world(cell), {"A": pred})
    assert w.human_position("A") == pred.position
    assert w.context(cell).robots_serving("A") == pred.robots
    # standing still: the vote is where the person is
    q = ConstantVelocityPredictor()
    _walk(q, (-0.5, 0.6), (0.0, 0.0), 0.5)
    still = predict_workspace(cell, q, "A", 0.5, horizon=1.5, dt=0.1)
    assert still.robots == frozenset({"r1"}) and still.votes == still.samples and not still.moving


def test_step_conflicts_and_precondition_hazards(cell: Scene) -> None:
    w = initial_world(cell)
    assert (
        step_conflict([Action("pick", ("r1",), "bottle"), Action("pick", ("r2",), "chips")]) is None
    )
    assert "robot r1" in (
        step_conflict(
            [Action("pick", ("r1",), "bottle"), Action("place", ("r1",), "chips", surface="shelf")]
        )
        or ""
    )
    assert "object bottle" in (
        step_conflict([Action("pick", ("r1",), "bottle"), Action("pick", ("r2",), "bottle")]) or ""
    )
    assert precondition_hazard(Action("pick", ("r1",), "bottle"), cell, w) is None
    h = precondition_hazard(Action("pick", ("r1",), "chips"), cell, w)
    assert h is not None and h.kind == "precondition" and "out of reach" in h.reason


def test_intrusion_hazard_forecasts_a_person_entering_the_rendezvous(cell: Scene) -> None:
    w = initial_world(cell).with_object("chips", ObjectStatus((1.2, 0.0, 0.3), Loc("held", "r2")))
    r2r = Action("handover_r2r", ("r2", "r1"), "chips")
    p = ConstantVelocityPredictor()
    _walk(p, (-0.5, 0.6), (1.5, -0.1), 0.3)
    here = p.predict("A", [0.3])[0]
    w = w.with_human("A", here)
    assert precondition_hazard(r2r, cell, w) is None  # fine now ...
    h = intrusion_hazard(r2r, cell, w, p, 0.3, 0.9, 0.1)
    assert h is not None and h.kind == "intrusion" and "inside both" in h.reason  # ... not soon
    # too short an action: it is over before the person gets there
    assert intrusion_hazard(r2r, cell, w, p, 0.3, 0.35, 0.05) is None


def test_world_round_trips_through_the_log_and_bad_logs_are_named(
    cell: Scene, tmp_path: Path
) -> None:
    w = initial_world(cell).with_object("chips", ObjectStatus((1.0, 0.1, 0.3), Loc("held", "r2")))
    w = w.with_unavailable(frozenset({"r1"}))
    assert world_from_dict(world_to_dict(w)) == w
    path = tmp_path / "log.jsonl"
    with EventLog(path) as log:
        log.emit(EpisodeStart(t=0.0, scene=cell.to_dict()))
        log.emit(Wait(t=0.5, reason="x"))
    assert [r.type for r in read_log(path)] == ["episode_start", "wait"]
    path.write_text('{"t": 0, "type": "episode_start"}\n{"t": 1, "type": "teleport"}\n')
    with pytest.raises(PlanFormatError, match=r"log.jsonl:2: unknown record type 'teleport'"):
        read_log(path)
    path.write_text('{"t": 1, "type": "wait"}\n{"t": 0, "type": "episode_start"}\n')
    with pytest.raises(PlanFormatError, match="first record is 'wait'"):
        read_log(path)
    path.write_text('{"t": 0, "type": "episode_start"}\nnot json\n')
    with pytest.raises(PlanFormatError, match=r"log.jsonl:2: not valid JSON"):
        read_log(path)


def test_typed_records_rewrite_an_old_log_byte_for_byte() -> None:
    """docs/figures/demo.jsonl was written when records were dicts: the typed records load it
    and write every line back unchanged (key order included)."""
    path = Path(__file__).parents[2] / "docs" / "figures" / "demo.jsonl"
    text = path.read_text(encoding="utf-8")
    records = read_log(path)
    assert {type(r).__name__ for r in records} >= {"EpisodeStart", "Replan", "Dispatch", "Halt"}
    again = "".join(json.dumps(r.to_json(), separators=(",", ":")) + "\n" for r in records)
    assert again == text


def test_action_records_share_handle_and_action_and_keep_their_key_order() -> None:
    """The action records inherit handle/action and ``ended``; each line keeps its key order."""
    act = {"skill": "pick"}
    start = ActionStart(t=1.0, handle=3, action=act, robots=["r1"], expected=2.0)
    lines: list[tuple[ActionRecord, str]] = [
        (start, "handle action robots expected"),
        (ActionDone(t=3.0, handle=3, action=act, end=2.5), "handle action end"),
        (ActionFailed(t=3.0, handle=3, action=act, reason="x"), "handle action reason end"),
        (ActionHalted(t=3.0, handle=3, action=act, end=2.0), "handle action reason end"),
    ]
    for rec, keys in lines:
        assert isinstance(rec, ActionRecord)
        assert list(rec.to_json()) == ["t", "type", *keys.split()]
        assert LogRecord.from_json(json.loads(json.dumps(rec.to_json()))) == rec
    assert ActionDone(t=3.0, handle=1, action=act, end=2.5).ended == 2.5
    assert ActionFailed(t=3.0, handle=1, action=act).ended == 3.0


def test_optional_fields_are_left_out_and_a_missing_required_field_is_named() -> None:
    halted = ActionHalted(t=1.0, handle=3, action={"skill": "pick"}, reason="x")
    assert list(halted.to_json()) == ["t", "type", "handle", "action", "reason"]
    assert LogRecord.from_json(halted.to_json()) == halted
    move = LogRecord.from_json(
        {
            "t": 0.5,
            "type": "human_move",
            "human": "A",
            "from": [0, 0, 0],
            "to": [1, 0, 0],
            "speed": 1.0,
        }
    )
    assert isinstance(move, HumanMove) and move.from_ == [0, 0, 0] and move.wander is None
    assert "from" in move.to_json() and "from_" not in move.to_json()
    policy = LogRecord.from_json({"t": 0, "type": "replan", "source": "greedy", "queries": 1})
    assert isinstance(policy, PolicyReplan)
    with pytest.raises(PlanFormatError, match="a dispatch record needs the field 'step'"):
        LogRecord.from_json({"t": 0, "type": "dispatch", "actions": []}, "x")
