"""The skill library: grounding, Pre under the latest world, durations."""

from __future__ import annotations

from pathlib import Path

import pytest

from hltl.errors import SceneError
from hltl.skills.cost import AnalyticCostModel, FixedDurations, cost_model_for
from hltl.skills.library import Action, Situation, ground
from hltl.skills.semantics import check_action
from hltl.world.scene import load_scene
from hltl.world.state import Loc, ObjectStatus, initial_world


def _actions(path: Path) -> set[Action]:
    """Instances applicable in the initial state (objects resting where the scene put them)."""
    scene = load_scene(path)
    return {a for a, t in ground(Situation.of(scene)) if t.pre.kind != "on"}


def test_grounding_respects_reach_and_workspaces(two_arms_path: Path) -> None:
    acts = _actions(two_arms_path)
    assert Action("pick", ("r1",), "bottle") in acts
    assert Action("pick", ("r2",), "bottle") not in acts  # 1.6 m from r2's base
    # ... but r2 reaches the shelf, so it could pick the bottle from there
    scene = load_scene(two_arms_path)
    from_shelf = [
        t for a, t in ground(Situation.of(scene)) if a == Action("pick", ("r2",), "bottle")
    ]
    assert [t.pre for t in from_shelf] == [Loc("on", "shelf")]
    assert Action("pick", ("r2",), "chips") in acts
    assert Action("handover_r2h", ("r1",), "bottle", human="A") in acts
    assert Action("handover_r2h", ("r1",), "bottle", human="B") not in acts
    assert Action("handover_r2r", ("r1", "r2"), "bottle") in acts
    assert Action("place", ("r1",), "bottle", surface="shelf") in acts


def test_check_action_reports_why(two_arms_path: Path) -> None:
    scene = load_scene(two_arms_path)
    w = initial_world(scene)
    assert check_action(Action("pick", ("r1",), "bottle"), scene, w) is None
    held = w.with_object("bottle", ObjectStatus((0.0, 0.0, 0.3), Loc("held", "r1")))
    r2r = Action("handover_r2r", ("r1", "r2"), "bottle")
    assert check_action(r2r, scene, held) is None
    # Person A steps between the arms: the rendezvous is blocked
    moved = held.with_human("A", (0.6, 0.1, 0.0))
    reason = check_action(r2r, scene, moved)
    assert reason is not None and "both r1's and r2's workspaces" in reason
    reason = check_action(Action("handover_r2h", ("r1",), "bottle", human="B"), scene, held)
    assert reason is not None and "not inside r1's workspace" in reason
    reason = check_action(Action("pick", ("r1",), "chips"), scene, w)
    assert reason is not None and "out of reach" in reason
    busy = held.with_unavailable(frozenset({"r2"}))
    reason = check_action(r2r, scene, busy)
    assert reason is not None and "unavailable" in reason


def test_fixed_and_analytic_durations(two_arms_path: Path) -> None:
    scene = load_scene(two_arms_path)
    fixed = cost_model_for(scene)
    assert isinstance(fixed, FixedDurations) and fixed.fixed
    sit = Situation.of(scene)
    inst = {a: t for a, t in ground(sit)}
    pick = Action("pick", ("r1",), "bottle")
    assert fixed.duration(pick, inst[pick], {}) == 0.5
    analytic = AnalyticCostModel((("r1", 0.5),), grasp=0.3)
    target = inst[pick].hands[0][1]
    assert analytic.duration(pick, inst[pick], {"r1": target}) == pytest.approx(0.3)
    start = (target[0] + 0.5, target[1], target[2])
    assert analytic.duration(pick, inst[pick], {"r1": start}) == pytest.approx(1.3)
    assert analytic.lower_bound(pick, inst[pick]) == pytest.approx(0.3)


def test_missing_fixed_duration_is_a_clear_error(two_arms_path: Path) -> None:
    scene = load_scene(two_arms_path)
    model = FixedDurations((("pick", 0.5),))
    sit = Situation.of(scene)
    a, t = next((a, t) for a, t in ground(sit) if a.skill == "place")
    with pytest.raises(SceneError, match="no time for skill 'place'"):
        model.duration(a, t, {})


def test_person_handover_targets_where_the_person_is_now(two_arms_path: Path) -> None:
    scene = load_scene(two_arms_path)
    w = initial_world(scene).with_human("A", (-0.2, 0.9, 0.0))
    sit = Situation.of(scene, w)
    (t,) = [t for a, t in ground(sit) if a == Action("handover_r2h", ("r1",), "bottle", human="A")]
    (_, point) = t.hands[0]
    # the hand reaches out towards A's current position (up and slightly left of r1's base)
    assert point[1] > 0.3 and point[0] < 0.0
