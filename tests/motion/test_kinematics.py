"""IK round trips, joint limits, failure reasons; the numpy capsule distance against coal."""

from __future__ import annotations

import itertools

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.motion.collision import capsule_distance, segment_distances
from hltl.motion.kinematics import JOINT_LIMIT, OUT_OF_REACH, Arm, Capsule

ARMS = {name: Arm("r", name, (0.3, -0.2, 0.0)) for name in ("elfin3", "ur5", "panda")}
XARM6 = Arm("r", "xarm6", (0.3, -0.2, 0.0))


# A local solver with restarts: IK is not complete (hltl bench motion measures 99.3-99.7 % solved
# on random targets; the misses sit where several joints are pinned at their limits), so the
# examples are fixed (derandomized) and drawn from configurations 5 % inside the limits.
@settings(max_examples=25, deadline=None, derandomize=True)
@given(
    st.sampled_from(sorted(ARMS)),
    st.lists(st.floats(0.05, 0.95), min_size=7, max_size=7),
)
def test_ik_round_trip_respects_limits(name: str, u: list[float]) -> None:
    assert_ik_round_trip(ARMS[name], u)


# the xArm6 (hltl's URDF from UFACTORY's published kinematics) on its own examples
@settings(max_examples=25, deadline=None, derandomize=True)
@given(st.lists(st.floats(0.05, 0.95), min_size=6, max_size=6))
def test_xarm6_ik_round_trip_respects_limits(u: list[float]) -> None:
    assert_ik_round_trip(XARM6, u)


def assert_ik_round_trip(arm: Arm, u: list[float]) -> None:
    q = arm._seed_lo + np.asarray(u[: arm.nq]) * (arm._seed_hi - arm._seed_lo)
    if not arm.pose_clear(q):
        return  # not a pose the arm may take (table, self-collision)
    pos, rot = arm.fk(q)
    res = arm.ik(pos, rot, starts=12)
    assert res.ok, res
    assert res.q is not None
    qs = np.asarray(res.q)
    assert np.all(qs >= arm.lower - 1e-9) and np.all(qs <= arm.upper + 1e-9)
    p2, r2 = arm.fk(qs)
    assert np.linalg.norm(p2 - pos) <= 1e-3  # FK(IK(x)) within 1 mm
    assert np.linalg.norm(_log3(r2 @ rot.T)) <= 1e-2  # and 0.01 rad
    assert res.position_error == pytest.approx(float(np.linalg.norm(p2 - pos)), abs=1e-9)


def _log3(r: np.ndarray) -> np.ndarray:
    import pinocchio as pin

    return np.asarray(pin.log3(r))


def test_ik_reports_out_of_reach_and_joint_limits() -> None:
    arm = Arm("r", "elfin3")
    far = arm.ik((2.0, 0.0, 0.3))
    assert not far.ok and far.reason == OUT_OF_REACH
    # the upright pose is reachable, but not with the hand turned upside down at the shoulder
    # height right next to the base: every solution would cross a joint limit or the table
    res = arm.ik((0.05, 0.0, 0.05), np.diag([1.0, -1.0, -1.0]), starts=6)
    assert not res.ok
    assert res.reason in (JOINT_LIMIT, OUT_OF_REACH, "collision")


def test_prefer_returns_the_nearest_solution() -> None:
    arm = Arm("r", "ur5")
    target = np.array([0.4, 0.2, 0.3])
    a = arm.ik(target, None, arm.home, prefer=arm.home, solutions=4)
    assert a.q is not None
    b = arm.ik(target, None, arm.home)
    assert b.q is not None
    gap_a = np.max(np.abs(np.asarray(a.q) - arm.home))
    gap_b = np.max(np.abs(np.asarray(b.q) - arm.home))
    assert gap_a <= gap_b + 1e-9


@settings(max_examples=40, deadline=None)
@given(st.lists(st.floats(-1.0, 1.0), min_size=12, max_size=12), st.integers(0, 3))
def test_segment_distance_matches_coal(xs: list[float], degenerate: int) -> None:
    p = np.asarray(xs).reshape(4, 3)
    if degenerate & 1:
        p[1] = p[0]
    if degenerate & 2:
        p[3] = p[2]
    mine = segment_distances(p[0:1], p[1:2], p[2:3], p[3:4])[0, 0]
    r = 0.01
    ref = capsule_distance(
        Capsule(tuple(p[0]), tuple(p[1]), r), Capsule(tuple(p[2]), tuple(p[3]), r)
    )
    if ref > 0:  # coal reports penetration depth differently; compare where they are apart
        assert mine - 2 * r == pytest.approx(ref, abs=1e-6)
    else:
        assert mine <= 2 * r + 1e-6


def test_rrt_connect_goes_around_an_obstacle() -> None:
    from hltl.motion import paths

    arm = Arm("r", "elfin3")
    res = arm.ik((0.5, 0.0, 0.25), None, arm.home, prefer=arm.home)
    assert res.q is not None
    q0 = np.asarray(res.q)
    q1 = q0.copy()
    q1[0] += 1.5 if q0[0] < 1.5 else -1.5
    # a post where the hand passes halfway through the straight swing
    w, _ = arm.fk((q0 + q1) / 2)
    post = [Capsule((w[0], w[1], 0.0), (w[0], w[1], 0.45), 0.05, "post")]
    packed = paths.capsule_arrays(post)
    assert not paths.segment_clear(arm, q0, q1, packed)
    path = paths.plan_path(arm, q0, q1, post, timeout=5.0)
    assert path is not None and path.planner in ("via_upright", "via_home", "rrt_connect")
    rrt = paths._rrt_connect(arm, q0, q1, packed, 5.0)
    assert rrt is not None
    for found in (path, rrt):
        pts = [np.asarray(p) for p in found.waypoints]
        assert np.allclose(pts[0], q0) and np.allclose(pts[-1], q1)
        assert all(paths.segment_clear(arm, a, b, packed) for a, b in itertools.pairwise(pts))
        timed = paths.time_parametrise(arm, found.waypoints, post)
        assert timed.positions[0] == pytest.approx(tuple(q0))
        assert timed.positions[-1] == pytest.approx(tuple(q1), abs=1e-6)
        assert all(paths.config_valid(arm, np.asarray(q), packed) for q in timed.positions)
