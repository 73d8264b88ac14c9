"""Table and branch safety: picks stay above the table (checked with coal), IK keeps its branch."""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest

from hltl.motion.kinematics import TABLE_TOLERANCE, Arm, Capsule
from hltl.motion.paths import SAMPLE_DT, segment_clear, time_parametrise, trajectory_clear
from hltl.motion.planning import plan_action
from hltl.skills.library import Action

coal = pytest.importorskip("coal")


def _table_depth(arm: Arm, q: Any) -> float:
    """How far (m) the arm's link capsules reach below the table top, by coal against a box.

    The oracle is independent of the planner's own closed-form test: a 4 × 4 × 0.5 m box whose
    top face is the scene's z = 0, and coal's capsule–box distance.
    """
    from hltl.motion.collision import _shape

    box = coal.Box(4.0, 4.0, 0.5)
    at = coal.Transform3s(np.eye(3), np.array([0.0, 0.0, -0.25]))
    worst = np.inf
    for c in arm.capsules(q)[1:]:  # the base capsule stands on the table
        shape, tf = _shape(c)
        d = coal.distance(shape, tf, box, at, coal.DistanceRequest(), coal.DistanceResult())
        worst = min(worst, float(d))
    return worst


@pytest.mark.parametrize(("robot", "obj"), [("r1", "bottle"), ("r2", "chips")])
def test_fig1_pick_stays_above_the_table(fig1_cell: Any, robot: str, obj: str) -> None:
    arm = fig1_cell.arms[robot]
    motion = plan_action(fig1_cell, Action("pick", (robot,), obj))
    assert motion.plan is not None, motion.reason
    traj = motion.plan.trajectory(robot)
    assert traj is not None
    depths = [_table_depth(arm, q) for q in traj.positions]
    assert min(depths) >= -TABLE_TOLERANCE - 1e-6
    # consecutive samples are one velocity-limited step apart: no jump to another IK branch
    steps = np.abs(np.diff(np.asarray(traj.positions), axis=0))
    assert np.all(steps <= arm.max_velocity * SAMPLE_DT * 1.05)
    # FK round trip: at the grasp the tool is at the object's grasp point
    t_grasp = next(t for t, k, _ in motion.plan.events if k == "grasp")
    tool, _ = arm.fk(traj.sample(t_grasp))
    centre = np.asarray(fig1_cell.scene.object(obj).position)
    assert float(np.linalg.norm((tool - centre)[:2])) < 0.08  # a side grasp at the object's side
    # the Elfin-3's pick used to swing through another branch (12.7 s): now one short reach
    assert motion.plan.duration < 7.0


def test_segment_through_the_table_is_rejected(fig1_cell: Any) -> None:
    # the retreat the planner once produced: the grasp and the retreat pose on two IK branches,
    # joined by a straight joint-space segment that swings under the table
    arm = fig1_cell.arms["r1"]
    grasp = np.array([3.08, -0.53, 2.33, -2.37, 1.37, 2.95])
    retreat = np.array([-2.78, -0.46, 2.53, 1.18, -1.51, -0.13])
    assert arm.pose_clear(grasp) and arm.pose_clear(retreat)
    empty = (np.zeros((0, 3)), np.zeros((0, 3)), np.zeros(0))
    assert not segment_clear(arm, grasp, retreat, empty)
    timed = time_parametrise(arm, [grasp, retreat])
    assert not trajectory_clear(arm, timed)
    assert min(_table_depth(arm, q) for q in timed.positions) < -0.1  # coal agrees


def test_ik_line_keeps_the_branch(fig1_cell: Any) -> None:
    arm = fig1_cell.arms["r1"]
    q0 = np.array([-0.06, 0.53, -2.33, -2.37, -1.37, -0.19])
    p0, r0 = arm.fk(q0)
    offset = np.array([0.069, -0.073, 0.0])
    line = arm.ik_line(q0, offset)
    assert line is not None and len(line) >= 10
    p1, r1 = arm.fk(line[-1])
    assert np.linalg.norm(p1 - (p0 + offset)) < 1e-3
    assert np.linalg.norm(r1 - r0) < 2e-2
    assert float(np.abs(np.diff(np.asarray(line), axis=0)).max()) <= 0.15


def test_elbow_up_prefers_the_upper_branch() -> None:
    arm = Arm("r", "ur5")
    target = np.array([0.35, 0.0, 0.6])
    # solutions from random starts: both elbow branches occur, and elbow_up agrees with the
    # geometry (the elbow above or below the shoulder-wrist line at its foot point)
    rng = np.random.default_rng(0)
    kinds = set()
    for _ in range(30):
        q, ep, _, _ = arm._dls(
            target, None, rng.uniform(arm._seed_lo, arm._seed_hi), 1e-3, 1e-2, 150, True
        )
        if ep > 1e-3 or not arm.above_table(q):
            continue
        pts = arm.joint_positions(q)
        shoulder, elbow, wrist = pts[1], pts[2], pts[-2]
        s = float(
            np.dot(elbow - shoulder, wrist - shoulder) / np.dot(wrist - shoulder, wrist - shoulder)
        )
        foot = shoulder + (wrist - shoulder) * s
        assert arm.elbow_up(q) == bool(elbow[2] >= foot[2])
        kinds.add(arm.elbow_up(q))
    assert kinds == {True, False}
    res = arm.ik(target, None, arm.home, prefer=arm.home, solutions=4, starts=16)
    assert res.q is not None and arm.elbow_up(res.q)


def test_capsule_table_clearance_matches_geometry() -> None:
    arm = Arm("r", "elfin3", (0.0, 0.0, 0.0))
    q = arm.neutral()  # upright: the lowest link capsule is the first, at the shoulder height
    caps: list[Capsule] = arm.capsules(q)[1:]
    expect = min(min(c.a[2], c.b[2]) - c.radius for c in caps)
    assert arm.table_clearance(q) == pytest.approx(expect)
    assert arm.table_clearance(q) == pytest.approx(_table_depth(arm, q), abs=1e-6)
