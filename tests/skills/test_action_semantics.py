"""The action-semantics API: one transition function, checked against the grounded library."""

from __future__ import annotations

import itertools
from dataclasses import dataclass, replace
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.planner import plan
from hltl.skills.kinematics import REACH_SPHERES, Kinematics, ReachSpheres
from hltl.skills.library import DEFAULT_SKILLS, Action, Situation, Skill, Transition
from hltl.skills.semantics import ActionSemantics, Infeasible, apply, check_action
from hltl.spec.hierarchy import spec_from_dict
from hltl.world.scene import Robot, Scene, Vec3, load_scene
from hltl.world.state import Loc, ObjectStatus, WorldState, initial_world
from tests.oracles.brute_force import Instance, applicable

SCENE = load_scene(Path(__file__).resolve().parents[2] / "examples" / "scenes" / "two_arms.yaml")
LOCS = [Loc("rest")] + [Loc("held", r) for r in SCENE.robot_ids]
LOCS += [Loc("on", s) for s in SCENE.surface_ids] + [Loc("delivered", h) for h in SCENE.human_ids]


@st.composite
def worlds(draw: st.DrawFn) -> WorldState:
    """Worlds of the two-arm cell: objects anywhere (at most one per hand), people moved."""
    w = initial_world(SCENE)
    holders: set[str] = set()
    for oid in SCENE.object_ids:
        loc = draw(st.sampled_from(LOCS))
        if loc.kind == "held" and loc.ref in holders:
            loc = Loc("rest")
        holders |= {loc.ref} if loc.kind == "held" else set()
        w = w.with_object(oid, ObjectStatus(w.object_status(oid).position, loc))
    for hid in SCENE.human_ids:
        x = draw(st.floats(-0.5, 2.0))
        y = draw(st.floats(-1.0, 1.0))
        w = w.with_human(hid, (x, y, 0.0))
    down = draw(st.sets(st.sampled_from(SCENE.robot_ids), max_size=1))
    return w.with_unavailable(frozenset(down))


@st.composite
def actions(draw: st.DrawFn) -> Action:
    skill = draw(st.sampled_from([*(s.name for s in DEFAULT_SKILLS), "wave"]))
    n = 2 if skill == "handover_r2r" else 1
    robots = tuple(draw(st.sampled_from((*SCENE.robot_ids, "r9"))) for _ in range(n))
    human = draw(st.sampled_from(SCENE.human_ids)) if skill == "handover_r2h" else None
    surface = draw(st.sampled_from(SCENE.surface_ids)) if skill == "place" else None
    return Action(skill, robots, draw(st.sampled_from(SCENE.object_ids)), human, surface)


def _oracle(action: Action, world: WorldState) -> Transition | None:
    """Pre and Post read off the fully grounded library (what every layer used to do)."""
    sit = Situation.of(SCENE, world)
    loc = dict(world.objects)[action.object].loc
    for skill in DEFAULT_SKILLS:
        for a, tr in skill.instances(sit):
            if a == action and tr.pre == loc:
                if any(world.holding(r) is not None for r in tr.free):
                    return None
                return tr
    return None


@settings(max_examples=150, deadline=None)
@given(actions(), worlds())
def test_transition_agrees_with_the_grounded_library(action: Action, world: WorldState) -> None:
    got = ActionSemantics.of(SCENE).transition(action, world)
    want = _oracle(action, world)
    if want is None:
        assert isinstance(got, Infeasible) and got.reason.startswith(str(action))
        assert check_action(action, SCENE, world) == got.reason
    else:
        assert got == want
        assert check_action(action, SCENE, world) is None


@settings(max_examples=60, deadline=None)
@given(actions(), worlds())
def test_skills_answer_for_one_action_as_their_instances_do(
    action: Action, world: WorldState
) -> None:
    sit = Situation.of(SCENE, world)
    for skill in DEFAULT_SKILLS:
        fast = list(skill.candidates(action, sit))
        slow = list(Skill.candidates(skill, action, sit))  # the generic filter over instances
        assert fast == slow


def test_apply_moves_the_object_and_the_hands() -> None:
    w = initial_world(SCENE)
    pick = Action("pick", ("r1",), "bottle")
    tr = ActionSemantics.of(SCENE).transition(pick, w)
    assert isinstance(tr, Transition)
    after = apply(w, tr)
    assert after.object_status("bottle").loc == Loc("held", "r1")
    assert after.hand_position("r1") == tr.hands[0][1] == after.object_status("bottle").position
    assert after.holding("r1") == "bottle"
    again = ActionSemantics.of(SCENE).transition(pick, after)
    assert isinstance(again, Infeasible) and again.kind == "conflict"


@dataclass(frozen=True, slots=True)
class _ShortArms(ReachSpheres):
    """Another reachability model: arms that reach only half as far."""

    def reaches(self, robot: Robot, point: Vec3) -> bool:
        return REACH_SPHERES.reaches(replace(robot, reach=robot.reach / 2), point)


def test_another_reachability_model_changes_what_exists(two_arms_path: Path) -> None:
    scene: Scene = load_scene(two_arms_path)
    short: Kinematics = _ShortArms()
    pick = Action("pick", ("r1",), "bottle")
    w = initial_world(scene)
    assert ActionSemantics.of(scene).check(pick, w) is None
    far = ActionSemantics.of(scene, kinematics=short).transition(pick, w)
    assert isinstance(far, Infeasible) and far.kind == "kinematic"
    spec = spec_from_dict({"root": "p0", "formulas": {"p0": "F delivered(bottle, A)"}})
    assert plan(scene, spec).solved
    assert not plan(scene, spec, kinematics=short).solved


def _all_actions() -> list[Action]:
    robots = (*SCENE.robot_ids, "r9")
    out: list[Action] = []
    for o in SCENE.object_ids:
        out += [Action(k, (r,), o) for r in robots for k in ("pick", "wave")]
        out += [Action("place", (r,), o, surface=s) for r in robots for s in SCENE.surface_ids]
        out += [Action("handover_r2r", (g, r), o) for g in robots for r in robots]
        out += [Action("handover_r2h", (r,), o, human=h) for r in robots for h in SCENE.human_ids]
    return out


@pytest.mark.parametrize("locs", list(itertools.product(LOCS, repeat=len(SCENE.objects))))
def test_feasibility_agrees_with_the_independent_oracle_model(locs: tuple[Loc, ...]) -> None:
    """tests/oracles/model.py restates the skills from the paper without hltl's library; every
    action is checked in every discrete state of the two-arm cell."""
    held = [loc.ref for loc in locs if loc.kind == "held"]
    if len(held) != len(set(held)):
        pytest.skip("one hand holds one object")
    w = initial_world(SCENE)
    for obj, loc in zip(SCENE.objects, locs, strict=True):
        w = w.with_object(obj.id, ObjectStatus(obj.position, loc))
    oracle = set(applicable(SCENE, [(loc.kind, loc.ref) for loc in locs]))
    sem = ActionSemantics.of(SCENE)
    for action in _all_actions():
        target = action.human or action.surface or ""
        feasible = Instance(action.skill, action.robots, action.object, target) in oracle
        got = sem.transition(action, w)
        assert isinstance(got, Transition) == feasible, (action, got)
