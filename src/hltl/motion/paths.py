"""Joint-space paths (direct, or OMPL RRTConnect around obstacles) timed with ruckig."""

from __future__ import annotations

import itertools
import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from hltl.errors import BackendUnavailableError
from hltl.motion.collision import capsule_arrays, fast_min_distance
from hltl.motion.kinematics import Arm, Capsule, FloatArray, Joints
from hltl.motion.trajectory import JointTrajectory

CHECK_STEP = 0.05  # rad: largest joint change between two collision checks along a path
SAMPLE_DT = 0.04  # s between the samples of a timed trajectory
OBSTACLE_MARGIN = 0.02  # m
# Paths with more waypoints than this (RRTConnect's) are smoothed by TOPP-RA; shorter ones are
# timed rest to rest, which costs little and follows the checked segments exactly.
SMOOTH_FROM = 4
RRT_SEED = 1


@dataclass(frozen=True, slots=True)
class JointPath:
    """Waypoints from start to goal and how they were found: ``direct``, ``via_upright`` (through
    the arm's upright zero pose), ``via_home`` (through its rest pose) or ``rrt_connect``."""

    waypoints: tuple[tuple[float, ...], ...]
    planner: str


Packed = tuple[np.ndarray, np.ndarray, np.ndarray]


def config_valid(arm: Arm, q: FloatArray, obstacles: Packed) -> bool:
    """Within limits, every link clear of the table top, and clear of the obstacles (packed
    capsules)."""
    if np.any(q < arm.lower - 1e-9) or np.any(q > arm.upper + 1e-9):
        return False
    if not arm.pose_clear(q):
        return False
    if len(obstacles[2]) == 0:
        return True
    return fast_min_distance(arm.capsules(q), obstacles) >= OBSTACLE_MARGIN


def segment_clear(arm: Arm, q0: FloatArray, q1: FloatArray, obstacles: Packed) -> bool:
    """True when the straight joint-space segment q0→q1 stays valid at every check step."""
    n = max(1, math.ceil(float(np.max(np.abs(q1 - q0))) / CHECK_STEP))
    return all(config_valid(arm, q0 + (q1 - q0) * (k / n), obstacles) for k in range(n + 1))


def trajectory_clear(arm: Arm, traj: JointTrajectory, obstacles: Sequence[Capsule] = ()) -> bool:
    """Every sample of a timed trajectory is valid (:func:`config_valid`), and consecutive samples
    are at most CHECK_STEP apart or the segment between them is checked too."""
    packed = capsule_arrays(obstacles)
    rows = [np.asarray(p, dtype=float) for p in traj.positions]
    if not all(config_valid(arm, q, packed) for q in rows):
        return False
    return all(
        float(np.max(np.abs(b - a))) <= CHECK_STEP or segment_clear(arm, a, b, packed)
        for a, b in itertools.pairwise(rows)
    )


def plan_path(
    arm: Arm,
    q_start: Joints,
    q_goal: Joints,
    obstacles: Sequence[Capsule] = (),
    *,
    timeout: float = 1.0,
) -> JointPath | None:
    """A collision-free joint path: the straight segment when it is clear, else RRTConnect."""
    q0 = np.asarray(q_start, dtype=float)
    q1 = np.asarray(q_goal, dtype=float)
    packed = capsule_arrays(obstacles)
    if segment_clear(arm, q0, q1, packed):
        return JointPath((_t(q0), _t(q1)), "direct")
    # Table-top arms usually clear what blocks a straight swing (the table, their own links) by
    # passing through the upright pose or, for arms whose zero pose lies along the table (the
    # UR5's), through their folded rest pose: two straight segments are far cheaper to check
    # than a sampling-based search.
    for via, name in ((arm.neutral(), "via_upright"), (arm.home, "via_home")):
        if segment_clear(arm, q0, via, packed) and segment_clear(arm, via, q1, packed):
            return JointPath((_t(q0), _t(via), _t(q1)), name)
    return _rrt_connect(arm, q0, q1, packed, timeout)


def _ompl() -> tuple[Any, Any, Any]:
    try:
        from ompl import base as ob
        from ompl import geometric as og
        from ompl import util as ou
    except ImportError:
        raise BackendUnavailableError(
            "sampling-based planning needs OMPL: install the 'motion' extra"
        ) from None
    return ob, og, ou


def _rrt_connect(
    arm: Arm, q0: FloatArray, q1: FloatArray, obstacles: Packed, timeout: float
) -> JointPath | None:
    ob, og, ou = _ompl()
    ou.setLogLevel(ou.LOG_NONE)
    # the same query gets the same path (plans are cached and compared across runs)
    ou.RNG.setSeed(RRT_SEED)
    if not config_valid(arm, q0, obstacles) or not config_valid(arm, q1, obstacles):
        return None
    n = arm.nq
    space = ob.RealVectorStateSpace(n)
    bounds = ob.RealVectorBounds(n)
    for i in range(n):
        bounds.setLow(i, float(arm.lower[i]))
        bounds.setHigh(i, float(arm.upper[i]))
    space.setBounds(bounds)
    ss = og.SimpleSetup(space)

    def valid(state: Any) -> bool:
        return config_valid(arm, np.array([state[i] for i in range(n)]), obstacles)

    ss.setStateValidityChecker(valid)
    si = ss.getSpaceInformation()
    # check motions at about CHECK_STEP rad: the resolution is a fraction of the space's extent
    si.setStateValidityCheckingResolution(CHECK_STEP / max(space.getMaximumExtent(), 1e-9))
    start, goal = space.allocState(), space.allocState()
    for i in range(n):
        start[i] = float(q0[i])
        goal[i] = float(q1[i])
    ss.setStartAndGoalStates(start, goal)
    ss.setPlanner(og.RRTConnect(si))
    solved = ss.solve(timeout)
    if not solved or not ss.haveExactSolutionPath():
        return None
    path = ss.getSolutionPath()
    raw = [np.array([path.getState(k)[i] for i in range(n)]) for k in range(path.getStateCount())]
    return JointPath(tuple(_t(q) for q in _shortcut(arm, raw, obstacles)), "rrt_connect")


def _shortcut(arm: Arm, pts: list[FloatArray], obstacles: Packed) -> list[FloatArray]:
    """Greedy shortcutting: from each kept waypoint, jump to the farthest one in plain sight.

    (OMPL's own simplifier spends most of a second in Python validity callbacks here.)
    """
    out = [pts[0]]
    i = 0
    while i < len(pts) - 1:
        j = len(pts) - 1
        while j > i + 1 and not segment_clear(arm, pts[i], pts[j], obstacles):
            j -= 1
        out.append(pts[j])
        i = j
    return out


def time_parametrise(
    arm: Arm, waypoints: Sequence[Sequence[float]], obstacles: Sequence[Capsule] = ()
) -> JointTrajectory:
    """Time a joint path under the arm's velocity and acceleration limits.

    A path with many waypoints (from RRTConnect) is first tried as a smooth spline timed by
    TOPP-RA; the spline leaves the checked segments a little, so its samples are checked
    again and, if any collides, the path falls back to the exact rest-to-rest timing. Two-point
    paths and the fallback use ruckig: each segment a time-optimal, phase-synchronised
    (straight in joint space) motion from rest to rest.
    """
    if len(waypoints) > SMOOTH_FROM:
        smooth = _toppra(arm, waypoints)
        packed = capsule_arrays(obstacles)
        if smooth is not None and all(
            config_valid(arm, np.asarray(p), packed) for p in smooth.positions
        ):
            return smooth
    return _ruckig(arm, waypoints)


def _toppra(arm: Arm, waypoints: Sequence[Sequence[float]]) -> JointTrajectory | None:
    try:
        import toppra as ta
        import toppra.algorithm as algo
        import toppra.constraint as constraint
    except ImportError:
        raise BackendUnavailableError(
            "time parametrisation needs toppra: install the 'motion' extra"
        ) from None
    ta.setup_logging("WARNING")
    wp = np.asarray(waypoints, dtype=float)
    # spline knots spaced by joint-space distance, so fast and slow legs are not distorted
    gaps = np.maximum(np.linalg.norm(np.diff(wp, axis=0), axis=1), 1e-6)
    s = np.concatenate([[0.0], np.cumsum(gaps)])
    path = ta.SplineInterpolator(s / s[-1], wp, bc_type="clamped")
    vlim = np.stack([-arm.max_velocity, arm.max_velocity], axis=1)
    acc = np.full(arm.nq, arm.spec.max_acceleration)
    alim = np.stack([-acc, acc], axis=1)
    inst = algo.TOPPRA(
        [constraint.JointVelocityConstraint(vlim), constraint.JointAccelerationConstraint(alim)],
        path,
        parametrizer="ParametrizeConstAccel",
    )
    traj = inst.compute_trajectory()
    if traj is None:
        return None
    d = float(traj.duration)
    steps = max(1, math.ceil(d / SAMPLE_DT))
    ts = np.linspace(0.0, d, steps + 1)
    pos, vel = traj(ts), traj(ts, 1)
    vel[0] = 0.0
    vel[-1] = 0.0
    return JointTrajectory(
        arm.robot,
        arm.joint_names,
        tuple(float(t) for t in ts),
        tuple(_t(p) for p in pos),
        tuple(_t(v) for v in vel),
    )


def _ruckig(arm: Arm, waypoints: Sequence[Sequence[float]]) -> JointTrajectory:
    try:
        from ruckig import InputParameter, Result, Ruckig, Synchronization, Trajectory
    except ImportError:
        raise BackendUnavailableError(
            "time parametrisation needs ruckig: install the 'motion' extra"
        ) from None
    n = arm.nq
    times: list[float] = [0.0]
    rows: list[tuple[float, ...]] = [tuple(float(v) for v in waypoints[0])]
    vels: list[tuple[float, ...]] = [tuple(0.0 for _ in range(n))]
    for a, b in itertools.pairwise(waypoints):
        if np.allclose(a, b, atol=1e-9):
            continue
        otg = Ruckig(n)
        inp = InputParameter(n)
        inp.current_position = list(a)
        inp.target_position = list(b)
        inp.max_velocity = [float(v) for v in arm.max_velocity]
        inp.max_acceleration = [arm.spec.max_acceleration] * n
        inp.max_jerk = [10.0 * arm.spec.max_acceleration] * n
        inp.synchronization = Synchronization.Phase
        traj = Trajectory(n)
        res = otg.calculate(inp, traj)
        if res not in (Result.Working, Result.Finished):
            raise RuntimeError(f"ruckig could not time a segment of {arm.robot}'s path: {res}")
        d = float(traj.duration)
        steps = max(1, math.ceil(d / SAMPLE_DT))
        t0 = times[-1]
        for k in range(1, steps + 1):
            t = d * k / steps
            p, v, _acc = traj.at_time(t)
            times.append(t0 + t)
            rows.append(tuple(float(x) for x in p))
            vels.append(tuple(float(x) for x in v))
    return JointTrajectory(arm.robot, arm.joint_names, tuple(times), tuple(rows), tuple(vels))


def _t(q: FloatArray) -> tuple[float, ...]:
    return tuple(float(v) for v in q)
