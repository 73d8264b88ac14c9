"""Issue 18, item 1: a pick whose object is moved (still within reach) halts and replans."""

from __future__ import annotations

from pathlib import Path

from hltl.execution.log import ActionDone, Violation
from hltl.sim.episode import run_episode
from hltl.sim.events import EventSchedule, ObjectMove
from hltl.sim.metrics import compute_metrics
from hltl.world.scene import load_scene


def test_a_moved_grasp_target_halts_the_pick_and_replans(two_arms_path: Path) -> None:
    scene = load_scene(two_arms_path)
    # the repro: 0.14 m away, still inside r1's reach, while r1's pick is under way
    events = EventSchedule((ObjectMove(0.2, "bottle", (-0.3, 0.3, 0.05)),))
    ep = run_episode(scene, instruction="Give Person A the bottle", events=events)
    kinds = [r.type for r in ep.records]
    assert "violation" not in kinds
    halt = next(r for r in ep.records if r.type == "halt")
    assert halt.t == 0.2 and "grasp target changed" in halt.reason
    replan = next(r for r in ep.records if r.type == "replan" and r.t == 0.2)
    assert "halt" in replan.trigger
    assert ep.success and ep.metrics.reason == "all goals met"


def test_a_small_nudge_within_the_grasp_tolerance_does_not_halt(two_arms_path: Path) -> None:
    scene = load_scene(two_arms_path)
    events = EventSchedule((ObjectMove(0.2, "bottle", (-0.42, 0.21, 0.05)),))
    ep = run_episode(scene, instruction="Give Person A the bottle", events=events)
    assert not [r for r in ep.records if r.type in ("halt", "violation")]
    assert ep.success


def test_goals_met_with_a_violation_is_not_reported_as_all_goals_met(
    two_arms_path: Path,
) -> None:
    """The old message was 'episode failed: all goals met'."""
    scene = load_scene(two_arms_path)
    records = list(run_episode(scene, instruction="Give Person A the bottle").records)
    done = next(r for r in records if isinstance(r, ActionDone))
    violation = Violation(t=done.t, action=done.action, reason="bottle moved away from the grasp")
    records.insert(records.index(done), violation)
    m = compute_metrics(records)
    assert not m.success
    assert m.reason.startswith("1 safety violation(s) (bottle moved away from the grasp)")
