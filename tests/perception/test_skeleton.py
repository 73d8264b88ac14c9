"""Skeletons: lifting 2D joints with depth, the far-side rule, and the MediaPipe pose worker in
its own environment (tested where ``.venv-pose`` exists)."""

from __future__ import annotations

import json
import math
import subprocess
from pathlib import Path

import numpy as np
import pytest

from hltl.errors import BackendUnavailableError
from hltl.perception.geometry import pixel_of
from hltl.perception.skeleton import (
    JOINTS,
    LIMB_RADIUS,
    PoseWorker,
    Skeleton,
    _hide_far_side,
    lift,
    pose_python,
)
from hltl.perception.synthetic import Solid, make_camera, render

ARM = Solid("human", "A", (0.0, 1.0, 0.0), 0.05, 1.5, (200, 50, 50))


def test_lift_puts_a_joint_a_limb_radius_behind_the_surface() -> None:
    cam = make_camera((0.0, -1.0, 1.0), (0.0, 1.0, 1.0), (ARM,), width=320, height=240)
    frame = render(cam, (ARM,))
    axis = np.array([0.0, 1.0, 1.0])
    u, v, _ = pixel_of(axis, cam)
    p = lift(frame.depth, cam, (u, v))
    assert p is not None
    # the surface is a radius in front of the axis; a limb's radius behind it is the axis
    assert math.dist(p, axis) == pytest.approx(abs(ARM.radius - LIMB_RADIUS), abs=0.01)
    assert lift(frame.depth, cam, (-5.0, 3.0)) is None  # outside the image
    assert lift(np.zeros_like(frame.depth), cam, (u, v)) is None  # no depth there


def _sk(**joints: tuple[float, float, float] | None) -> Skeleton:
    js = tuple((k, joints.get(k)) for k in JOINTS)
    return Skeleton(js, tuple((k, None if p is None else (0.0, 0.0)) for k, p in js))


def test_shoulders_closer_than_a_body_drop_the_far_side() -> None:
    cam = make_camera((0.0, -2.0, 1.4), (0.0, 0.0, 1.4), ())
    near, far = (0.0, 0.0, 1.4), (0.05, 0.1, 1.4)  # side view: far shoulder lifted onto the near
    out = _hide_far_side(_sk(r_shoulder=near, l_shoulder=far, l_wrist=(0.1, 0.1, 1.0)), cam)
    assert out.joint("l_shoulder") is None and out.joint("l_wrist") is None
    assert out.joint("r_shoulder") == near and out.seen == 1
    front = _sk(r_shoulder=(-0.2, 0.0, 1.4), l_shoulder=(0.2, 0.0, 1.4))  # seen from the front
    assert _hide_far_side(front, cam) == front
    assert out.to_dict()["l_shoulder"] is None


def test_a_missing_pose_environment_is_named(tmp_path: Path) -> None:
    with pytest.raises(BackendUnavailableError, match="pose environment"):
        PoseWorker(tmp_path / "no-python")


needs_pose = pytest.mark.skipif(
    not pose_python().is_file(), reason="no pose environment (.venv-pose, made by setup.sh)"
)


@needs_pose
def test_the_pose_worker_answers_and_survives_bad_requests() -> None:
    worker = Path(__file__).parents[2] / "src/hltl/perception/pose_worker.py"
    blank = np.full((64, 48, 3), 90, dtype=np.uint8).tobytes()
    stdin = b'{"w": 0}\n' + b"not json\n" + b'{"w": 48, "h": 64}\n' + blank
    out = subprocess.run(
        [str(pose_python()), str(worker)], input=stdin, capture_output=True, timeout=120
    ).stdout
    replies = [json.loads(line) for line in out.splitlines()]
    assert replies[0]["ready"] is True and replies[0]["mediapipe"] == "0.10.21"
    assert "error" in replies[1] and "error" in replies[2]
    assert replies[3] == {"landmarks": None}  # nobody on a grey card


@needs_pose
def test_skeletons_of_a_rendered_person() -> None:
    pytest.importorskip("mujoco")
    from hltl.sim3d.gl import require_renderer

    try:
        require_renderer()
    except Exception as exc:
        pytest.skip(f"no offscreen renderer: {exc}")
    from hltl.bench.perception import skeleton_bench
    from hltl.sim.scenarios import get

    row = skeleton_bench(get("fig1").scene, limit=3)  # both people seen whole at the start
    assert row.version == "0.10.21" and row.found >= 5
    seen = sum(n for n, _, _ in row.joints.values())
    assert seen >= 8
    # seen whole from the front: each joint's median within 5 cm of the simulator's
    assert all(e[0] < 0.05 for n, e, _ in row.joints.values() if n)
