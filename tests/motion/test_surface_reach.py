"""A surface is judged where an object on it is held (issue 17): place(o, s) and a pick from s
need the arm to reach the object's point, OBJECT_LIFT above the surface, not the surface's top.

The oracle is the motion layer's own placing motion (``plan_pick(..., place=True)``: side
grasps of the object standing on the surface, IK with orientation, a collision-free path),
which the skill library does not use. The T1–T6 table (0.671 m from the Elfin-3) is the case
the old judgement got wrong: its top is outside the Elfin-3's map, the placing pose is not."""

from __future__ import annotations

from typing import Any

import pytest

from hltl.motion.planning import Cell, plan_pick
from hltl.motion.workspace import MapKinematics
from hltl.skills.library import Action, Transition
from hltl.skills.semantics import ActionSemantics, apply
from hltl.world.scene import OBJECT_LIFT, Scene, scene_from_dict
from hltl.world.state import Loc, ObjectStatus, initial_world

T16_TABLE = 0.671  # the T1–T6 table's centre, (0.6, 0.3, 0), from the Elfin-3's base
FAR = 0.95  # beyond anything the Elfin-3 can do


def _scene(table_at: float, category: str) -> Scene:
    return scene_from_dict(
        {
            "units": "m",
            "robots": [{"id": "r1", "base": [0.0, 0.0, 0.0], "reach": 0.7, "model": "elfin3"}],
            "objects": [{"id": "o", "category": category, "position": [0.3, 0.2, 0.05]}],
            "surfaces": [{"id": "table", "center": [table_at, 0.0, 0.0], "size": [0.05, 0.05]}],
        },
        source=f"table at {table_at} m",
    )


def assert_placing_motion(scene: Scene, kin: MapKinematics, exists: bool) -> None:
    """The oracle: the motion layer plans (or fails to plan) the real placing motion at the
    table's centre."""
    place = Action("place", ("r1",), "o", surface="table")
    sm = plan_pick(Cell(scene, kin), place, {}, scene.surface("table").center, place=True)
    assert (sm.plan is not None) is exists, sm.reason


@pytest.mark.parametrize(
    ("table_at", "category", "reachable"),
    [(T16_TABLE, "cup", True), (T16_TABLE, "chips", True), (FAR, "cup", False)],
)
def test_place_and_pick_on_a_surface_follow_the_placing_motion(
    coarse_maps: dict[str, Any], table_at: float, category: str, reachable: bool
) -> None:
    scene = _scene(table_at, category)
    kin = MapKinematics(scene, coarse_maps)
    assert_placing_motion(scene, kin, reachable)
    sem = ActionSemantics.of(scene, kinematics=kin)
    w = initial_world(scene).with_object("o", ObjectStatus((0.3, 0.2, 0.05), Loc("held", "r1")))
    placed = sem.transition(Action("place", ("r1",), "o", surface="table"), w)
    assert isinstance(placed, Transition) is reachable, placed
    if not reachable:
        return
    assert isinstance(placed, Transition)
    (_, hand), *_ = placed.hands
    assert hand == (table_at, 0.0, OBJECT_LIFT)
    # the object lies where it was let go, and the same arm can pick it up again from there
    after = apply(w, placed)
    assert after.object_status("o") == ObjectStatus(hand, Loc("on", "table"))
    picked = sem.transition(Action("pick", ("r1",), "o"), after)
    assert isinstance(picked, Transition) and picked.pre == Loc("on", "table")


def test_the_t16_tables_top_is_outside_the_map(coarse_maps: dict[str, Any]) -> None:
    """Why the old judgement (reach at the surface's top) refused the Elfin-3 the T1–T6 table:
    the top is outside its map, the object's point on it is inside."""
    scene = _scene(T16_TABLE, "cup")
    kin = MapKinematics(scene, coarse_maps)
    r1 = scene.robot("r1")
    table = scene.surface("table")
    assert not kin.reaches(r1, table.center)
    assert kin.reaches(r1, table.object_point)
