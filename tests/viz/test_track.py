"""Tracks: what happened when, and where hands, people and objects are, from plans and logs."""

from __future__ import annotations

import math

import pytest

from hltl.errors import PlanFormatError
from hltl.execution.log import EpisodeStart, LogRecord
from hltl.planner import PlanResult
from hltl.viz.track import track_from_log, track_from_plan
from hltl.world.geometry import human_handover_point, rendezvous_point
from hltl.world.scene import Scene


def close(p: tuple[float, ...], q: tuple[float, ...], tol: float = 1e-9) -> bool:
    return all(abs(a - b) <= tol for a, b in zip(p, q, strict=True))


def test_plan_spans_are_the_steps(paper_plan: PlanResult, scene: Scene) -> None:
    track = track_from_plan(paper_plan, scene)
    expected = sorted(
        (s.start, s.start + s.duration, a.skill, a.object)
        for s in paper_plan.steps
        for a in s.actions
    )
    got = sorted((s.start, s.end, s.action.skill, s.action.object) for s in track.spans)
    assert got == expected
    assert track.end == paper_plan.makespan and track.kind == "plan"
    assert all(s.outcome == "planned" for s in track.spans)


def test_plan_from_its_json_equals_plan_from_the_result(
    chips_plan: PlanResult, scene: Scene
) -> None:
    a = track_from_plan(chips_plan, scene)
    b = track_from_plan(chips_plan.to_dict(), scene)
    assert a.spans == b.spans and a.end == b.end


def test_hands_and_objects_follow_the_chips_plan(chips_plan: PlanResult, scene: Scene) -> None:
    track = track_from_plan(chips_plan, scene)
    pick, r2r, r2h = track.spans
    assert (pick.action.skill, r2r.action.skill, r2h.action.skill) == (
        "pick",
        "handover_r2r",
        "handover_r2h",
    )
    chips = scene.object("chips").position
    # r2's hand reaches the chips as the pick ends; the chips stay where they lie until then
    assert close(track.hand_position("r2", pick.end), chips)
    assert track.object_place("chips", pick.end - 1e-6)[0] == "rest"
    assert track.object_place("chips", pick.end)[:2] == ("held", "r2")
    # both hands meet at the rendezvous; halfway there the chips are in r2's moving hand
    meet = rendezvous_point(scene.robot("r2"), scene.robot("r1"))
    assert close(track.hand_position("r1", r2r.end), meet)
    assert close(track.hand_position("r2", r2r.end), meet)
    mid = (r2r.start + r2r.end) / 2
    assert close(track.object_position("chips", mid), track.hand_position("r2", mid))
    assert track.object_place("chips", r2r.end)[:2] == ("held", "r1")
    # r1 hands them to A: its hand goes towards A, and then A has them
    target = human_handover_point(scene.robot("r1"), scene.human("A").position)
    assert close(track.hand_position("r1", r2h.end), target)
    assert track.object_place("chips", r2h.end)[:2] == ("delivered", "A")
    ax, ay, _ = scene.human("A").position
    ox, oy, _ = track.object_position("chips", r2h.end + 1.0)
    assert math.hypot(ox - ax, oy - ay) < 0.15


def test_log_track_of_the_demo(demo_records: tuple[LogRecord, ...]) -> None:
    track = track_from_log(demo_records)
    assert track.kind == "episode" and track.success is True
    end = next(r for r in demo_records if r.type == "episode_end")
    assert track.end == end.time_cost
    # one span per action_start, ending where its done/failed/halted record says
    starts = {r.handle: r for r in demo_records if r.type == "action_start"}
    ends = {
        r.handle: r
        for r in demo_records
        if r.type in ("action_done", "action_failed", "action_halted")
    }
    assert len(track.spans) == len(starts)
    for span in track.spans:
        handle = next(
            h
            for h, r in starts.items()
            if r.t == span.start and r.action["robots"] == list(span.action.robots)
        )
        assert span.end == ends[handle].ended
    outcomes = sorted(s.outcome for s in track.spans)
    assert outcomes.count("halted") == 1 and outcomes.count("done") == len(outcomes) - 1
    kinds = [m.kind for m in track.markers]
    assert "halt" in kinds and "takeover" in kinds and "predict" in kinds
    halt = next(r for r in demo_records if r.type == "halt")
    assert any(
        m.kind == "halt" and m.t == halt.t and m.detail == halt.reason for m in track.markers
    )


def test_people_walk_as_the_log_says(demo_records: tuple[LogRecord, ...]) -> None:
    track = track_from_log(demo_records)
    moves = [r for r in demo_records if r.type == "human_move"]
    first, second = moves
    # on the first walk, A is speed * elapsed along the straight line
    p0, p1 = first.from_, first.to
    d = math.dist(p0[:2], p1[:2])
    t = first.t + 0.3
    frac = first.speed * 0.3 / d
    expected = tuple(p0[i] + frac * (p1[i] - p0[i]) for i in range(3))
    assert close(track.human_position("A", t), expected, 1e-6)
    # the second walk starts where A was when it began and ends at its target
    assert close(track.human_position("A", second.t), tuple(second.from_), 1e-5)
    assert close(track.human_position("A", track.end + 5.0), tuple(second.to))
    assert close(track.human_position("B", 1.0), (1.9, 0.5, 0.0))


def test_a_failed_action_leaves_the_object_and_freezes_the_hand(
    down_records: tuple[LogRecord, ...], scene: Scene
) -> None:
    track = track_from_log(down_records)
    failed = [s for s in track.spans if s.outcome == "failed"]
    assert [(s.action.skill, s.action.robots) for s in failed] == [("pick", ("r1",))]
    f = failed[0]
    assert track.object_place("bottle", f.end + 0.01)[0] == "rest"
    frozen = track.hand_position("r1", f.end)
    assert close(track.hand_position("r1", f.end + 0.5), frozen)
    assert not close(frozen, scene.object("bottle").position)  # stopped on the way
    assert {m.kind for m in track.markers} >= {"failure", "robot", "no_plan", "replan"}


def test_bad_inputs_are_rejected_with_what_was_expected(scene: Scene) -> None:
    with pytest.raises(PlanFormatError, match="episode_start"):
        track_from_log([])
    with pytest.raises(PlanFormatError, match="scene"):
        track_from_log([EpisodeStart(t=0.0, scene={})])
    bad = {
        "status": "solved",
        "makespan": 0.5,
        "steps": [
            {
                "start": 0.0,
                "duration": 0.5,
                "actions": [{"skill": "pick", "robots": ["r1"], "object": "cup"}],
            }
        ],
    }
    with pytest.raises(PlanFormatError, match="'cup'"):
        track_from_plan(bad, scene)
    with pytest.raises(PlanFormatError, match="expected status"):
        track_from_plan({"steps": []}, scene)
