"""Events files: loading, validation errors that name file, index, field and value."""

from __future__ import annotations

from pathlib import Path

import pytest

from hltl.errors import EventsError
from hltl.sim.events import (
    HumanMove,
    Instruction,
    ObjectMove,
    RobotDown,
    SkillFailure,
    events_from_dict,
    load_events,
)
from hltl.world.scene import Scene, load_scene

EXAMPLES = Path(__file__).resolve().parents[2] / "examples" / "events"


@pytest.fixture
def cell(two_arms_path: Path) -> Scene:
    return load_scene(two_arms_path)


def test_design_example_loads_sorted_by_time(cell: Scene) -> None:
    data = {
        "events": [
            {"t": 1.2, "type": "human_move", "human": "A", "to": [1.8, 0.4, 0.0], "speed": 1.0},
            {"t": 0.5, "type": "object_move", "object": "chips", "to": [0.2, 0.3, 0.05]},
            {"t": 2.0, "type": "instruction", "text": "Also give Person B the bottle"},
            {"t": 1.0, "type": "robot_down", "robot": "r2", "duration": 3.0},
            {"type": "skill_failure", "skill": "pick", "probability": 0.2},
        ]
    }
    ev = events_from_dict(data, cell, "e.yaml")
    assert [type(e) for e in ev.timed] == [ObjectMove, RobotDown, HumanMove, Instruction]
    assert ev.failures == (SkillFailure("pick", 0.2, "stay"),)
    assert ev.failure_of("pick") is not None and ev.failure_of("place") is None
    assert ev.instructions == (Instruction(2.0, "Also give Person B the bottle"),)
    assert events_from_dict({"events": ev.to_list()}, cell) == ev.__class__(
        ev.timed, ev.failures, "<events>"
    )


@pytest.mark.parametrize(
    ("event", "message"),
    [
        (
            {"t": 1, "type": "teleport"},
            r"e.yaml: events\[0\].type: unknown event type \(value 'teleport'\)",
        ),
        (
            {"t": 1, "type": "human_move", "human": "Z", "to": [0, 0, 0]},
            r"events\[0\].human: unknown human.*value 'Z'",
        ),
        (
            {"t": 1, "type": "object_move", "object": "cup", "to": [0, 0, 0]},
            r"events\[0\].object: unknown object.*'cup'",
        ),
        (
            {"t": 1, "type": "robot_down", "robot": "r9", "duration": 1},
            r"events\[0\].robot: unknown robot",
        ),
        (
            {"t": -1, "type": "instruction", "text": "hi"},
            r"events\[0\].t: must be >= 0 \(value -1\)",
        ),
        (
            {"t": 1, "type": "human_move", "human": "A", "to": [0, 0]},
            r"events\[0\].to: expected a point",
        ),
        (
            {"t": 1, "type": "human_move", "human": "A", "to": [0, 0, 0], "speed": 0},
            r"events\[0\].speed: must be > 0",
        ),
        (
            {"t": 1, "type": "robot_down", "robot": "r1"},
            r"events\[0\].duration: required field is missing",
        ),
        (
            {"t": 1, "type": "instruction", "text": "x", "when": 3},
            r"events\[0\].when: unknown field for instruction",
        ),
        (
            {"type": "skill_failure", "skill": "fly", "probability": 0.1},
            r"events\[0\].skill: unknown skill",
        ),
        (
            {"type": "skill_failure", "skill": "pick", "probability": 1.5},
            r"events\[0\].probability: must be <= 1",
        ),
        (
            {"type": "skill_failure", "skill": "pick", "probability": 0.1, "outcome": "explode"},
            r"events\[0\].outcome",
        ),
        (
            {"t": float("nan"), "type": "instruction", "text": "x"},
            r"events\[0\].t: expected a finite number",
        ),
    ],
)
def test_bad_events_are_rejected_up_front(
    cell: Scene, event: dict[str, object], message: str
) -> None:
    with pytest.raises(EventsError, match=message):
        events_from_dict({"events": [event]}, cell, "e.yaml")


def test_bad_files(cell: Scene, tmp_path: Path) -> None:
    with pytest.raises(EventsError, match="unknown top-level field 'event'"):
        events_from_dict({"event": []}, cell)
    p = tmp_path / "bad.yaml"
    p.write_text("events: [\n")
    with pytest.raises(EventsError, match=r"bad\.yaml: not valid YAML"):
        load_events(p, cell)
    with pytest.raises(EventsError, match="cannot read"):
        load_events(tmp_path / "missing.yaml", cell)
    dup = {"events": [{"type": "skill_failure", "skill": "pick", "probability": 0.1}] * 2}
    with pytest.raises(EventsError, match=r"events\[1\].skill: a failure model"):
        events_from_dict(dup, cell)


@pytest.mark.parametrize("path", sorted(EXAMPLES.glob("*.yaml")), ids=lambda p: p.stem)
def test_example_events_load(cell: Scene, path: Path) -> None:
    ev = load_events(path, cell)
    assert ev.timed or ev.failures
