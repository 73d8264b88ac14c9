"""JointTrajectory and MotionPlan: validation, sampling, composition (no extras needed)."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.motion.trajectory import JointTrajectory, MotionPlan

JOINTS = ("j1", "j2")


def _traj(times: tuple[float, ...], rows: tuple[tuple[float, ...], ...]) -> JointTrajectory:
    return JointTrajectory("r1", JOINTS, times, rows)


def test_sample_interpolates_and_clamps() -> None:
    tr = _traj((0.0, 1.0, 3.0), ((0.0, 0.0), (1.0, -1.0), (1.0, 1.0)))
    assert tr.duration == 3.0
    assert tr.sample(-1.0) == (0.0, 0.0)
    assert tr.sample(0.5) == pytest.approx((0.5, -0.5))
    assert tr.sample(2.0) == pytest.approx((1.0, 0.0))
    assert tr.sample(10.0) == (1.0, 1.0)


@pytest.mark.parametrize(
    ("times", "rows", "needle"),
    [
        ((), (), "no samples"),
        ((0.1, 1.0), ((0.0, 0.0), (1.0, 1.0)), r"times\[0\]"),
        ((0.0, 0.0), ((0.0, 0.0), (1.0, 1.0)), "increase strictly"),
        ((0.0, 1.0), ((0.0, 0.0),), "rows"),
        ((0.0, 1.0), ((0.0, 0.0), (1.0,)), "finite numbers"),
        ((0.0, 1.0), ((0.0, 0.0), (1.0, float("nan"))), "finite numbers"),
    ],
)
def test_rejects_malformed(
    times: tuple[float, ...], rows: tuple[tuple[float, ...], ...], needle: str
) -> None:
    with pytest.raises(ValueError, match=needle):
        _traj(times, rows)


@settings(max_examples=40, deadline=None)
@given(
    st.lists(st.floats(0.01, 2.0), min_size=1, max_size=6),
    st.floats(0.0, 1.0),
)
def test_sample_stays_within_segment_bounds(steps: list[float], frac: float) -> None:
    times = [0.0]
    for s in steps:
        times.append(times[-1] + s)
    rows = tuple((float(i), float(-i)) for i in range(len(times)))
    tr = _traj(tuple(times), rows)
    t = frac * tr.duration
    a, b = tr.sample(t)
    assert 0.0 <= a <= len(times) - 1 + 1e-9
    assert a == pytest.approx(-b)


def test_then_and_shifted_compose() -> None:
    a = _traj((0.0, 1.0), ((0.0, 0.0), (1.0, 1.0)))
    b = _traj((0.0, 2.0), ((1.0, 1.0), (3.0, 3.0)))
    ab = a.then(b)
    assert ab.duration == 3.0
    assert ab.sample(2.0) == pytest.approx((2.0, 2.0))
    late = a.shifted(0.5)
    assert late.duration == 1.5
    assert late.sample(0.4) == (0.0, 0.0)
    with pytest.raises(ValueError, match="cannot append"):
        a.then(JointTrajectory("r2", JOINTS, (0.0, 1.0), ((0.0, 0.0), (1.0, 1.0))))


def test_motion_plan_checks_events_and_durations() -> None:
    tr = _traj((0.0, 1.0), ((0.0, 0.0), (1.0, 1.0)))
    plan = MotionPlan((tr,), ((1.0, "grasp", "r1"),), 1.2)
    assert plan.trajectory("r1") is tr
    assert plan.trajectory("r9") is None
    with pytest.raises(ValueError, match="expected one of"):
        MotionPlan((tr,), ((0.5, "wave", "r1"),), 1.2)
    with pytest.raises(ValueError, match="outside"):
        MotionPlan((tr,), ((2.0, "grasp", "r1"),), 1.2)
    with pytest.raises(ValueError, match="longer than"):
        MotionPlan((tr,), (), 0.5)


def test_trajectory_module_needs_no_extras() -> None:
    import subprocess
    import sys

    code = (
        "import sys, hltl.motion.trajectory, hltl.motion.robots\n"
        "print(','.join(m for m in ('pinocchio', 'coal', 'ompl', 'ruckig') if m in sys.modules))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == ""
