"""The realworld benchmark's two-arm cell (T1 trial 0): the motion cost model plans what the
arms execute, and a failed motion plan is INFEASIBLE, never a large finite duration."""

from __future__ import annotations

import math
from typing import Any

import pytest

from hltl.bench.realworld import make_task
from hltl.motion.cost import MotionCostModel
from hltl.motion.planning import Cell
from hltl.motion.workspace import MapKinematics, Rendezvous
from hltl.skills.library import Action, Transition
from hltl.world.scene import Robot
from hltl.world.state import Loc

# the shared region of the two arms by the default (3 cm) maps, as `hltl bench realworld
# --motion` sees it; the tests' coarse maps put its centre elsewhere
MEASURED = Rendezvous((0.4898885019295056, -0.0065, 0.32), 0.3225)


class _Measured(MapKinematics):
    def rendezvous(self, a: Robot, b: Robot) -> Rendezvous | None:
        return MEASURED


@pytest.fixture(scope="module")
def t1_cell(coarse_maps: dict[str, Any]) -> Cell:
    scene = make_task("T1", 0).scene
    return Cell(scene, _Measured(scene, coarse_maps))


def _r2r(cell: Cell) -> tuple[Action, Transition]:
    point = MEASURED.centre
    tr = Transition(
        "chips",
        Loc("held", "r2"),
        Loc("held", "r1"),
        ("r1",),
        frozenset(),
        (("r2", point), ("r1", point)),
    )
    return Action("handover_r2r", ("r2", "r1"), "chips"), tr


def test_t1_handover_after_the_pick_has_a_motion(t1_cell: Cell) -> None:
    """The T1 bug: from r2's hand at the chips and r1 at rest, the two best goal sets (both at
    the centre of the shared region) put the Elfin-3's wrist through a singularity on the
    approach line; the cost model tried only those and timed the hand-over 1000 s. Further goal
    sets are tried before a hand-over is called infeasible."""
    cost = MotionCostModel(t1_cell)
    action, tr = _r2r(t1_cell)
    chips = t1_cell.scene.object("chips").position
    hands = {"r2": chips, "r1": t1_cell.kinematics.home_point(t1_cell.scene.robot("r1"))}
    d = cost.duration(action, tr, hands)
    assert math.isfinite(d) and 1.0 < d < 15.0
    motion = cost.motion(action, tr, hands)
    assert motion.plan is not None and {t.robot for t in motion.plan.trajectories} == {"r1", "r2"}


def test_an_instance_without_motion_is_infeasible(t1_cell: Cell) -> None:
    """A hand-over to a person nobody can reach has no motion plan: math.inf, not a number the
    planner would pay."""
    cost = MotionCostModel(t1_cell)
    far = (5.0, 5.0, 0.0)
    tr = Transition(
        "chips",
        Loc("held", "r1"),
        Loc("delivered", "A"),
        (),
        frozenset(),
        (("r1", (0.4, 0.4, 0.4)),),
        human_at=far,
    )
    action = Action("handover_r2h", ("r1",), "chips", human="A")
    hands = {"r1": t1_cell.kinematics.home_point(t1_cell.scene.robot("r1"))}
    assert cost.duration(action, tr, hands) == math.inf
    assert cost.motion_plan(action, tr, hands) is None


def test_a_hand_over_to_a_person_goes_where_they_stand_now(t1_cell: Cell) -> None:
    """The transition's ``human_at`` (where the person is now), not the scene's first position:
    T2's person walks from r1's side to r2's, and r2 hands over there."""
    cost = MotionCostModel(t1_cell)
    scene = t1_cell.scene
    r2 = scene.robot("r2")
    there = (1.95, 0.5, 0.0)
    assert math.dist(scene.human("A").position, r2.base) > 1.5  # the scene has A far from r2
    point = t1_cell.kinematics.human_handover_point(r2, there)
    tr = Transition(
        "chips", Loc("held", "r2"), Loc("delivered", "A"), (), frozenset(), (("r2", point),), there
    )
    action = Action("handover_r2h", ("r2",), "chips", human="A")
    hands = {"r2": scene.object("chips").position}
    motion = cost.motion(action, tr, hands)
    assert motion.plan is not None, motion.reason
