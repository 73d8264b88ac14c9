"""The robots' own bodies in a frame (joint state → link capsules) and the learned backend's test
for pieces of people's legs; frames carry joints through frame folders."""

from __future__ import annotations

import dataclasses
import json
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.errors import PerceptionError
from hltl.perception.frames import FrameFolder, write_frames
from hltl.perception.ownbody import OwnBodies
from hltl.perception.synthetic import Solid, make_camera, render
from hltl.world.scene import Robot, Scene

TABLE = Solid("surface", "table", (0.0, 0.0, 0.0), 0.8, 0.75, (120, 90, 60))
CUP = Solid("object", "cup", (0.0, -0.2, 0.75), 0.04, 0.10, (230, 230, 230))
SOLIDS = (TABLE, CUP)


def test_frames_carry_joints_through_a_frame_folder(tmp_path: Path) -> None:
    cam = make_camera((0.0, -2.0, 1.6), (0.0, 0.0, 0.7), SOLIDS, width=64, height=48)
    q = {"r1": (0.1, -0.5, 1.25, 0.0, 0.3, -2.0)}
    frames = [
        dataclasses.replace(render(cam, SOLIDS), joints=q),
        render(cam, SOLIDS, t=0.1, index=1),
    ]
    root = write_frames(tmp_path / "f", cam, frames)
    ff = FrameFolder(root)
    assert ff.frame(0).joints == q
    assert ff.frame(1).joints is None
    data = json.loads((root / "camera.json").read_text())
    for bad in ({"r1": [0.1, "x"]}, [0.1, 0.2], {"r1": [float("nan")]}, {"r1": [True]}):
        data["frames"][0]["joints"] = bad
        (root / "camera.json").write_text(json.dumps(data))
        with pytest.raises(PerceptionError, match=r"frames\[0\]\.joints"):
            FrameFolder(root)


def _brute_share(points: np.ndarray, caps: list[tuple[np.ndarray, np.ndarray, float]]) -> float:
    """The share of points within r of some point of a densely sampled segment (an oracle
    independent of the projection formula; the sampling step bounds its error)."""
    inside = np.zeros(len(points), dtype=bool)
    for a, b, r in caps:
        s = a + np.linspace(0.0, 1.0, 2001)[:, None] * (b - a)
        d = np.linalg.norm(points[:, None, :] - s[None, :, :], axis=2).min(axis=1)
        inside |= d <= r
    return float(inside.mean())


@settings(max_examples=30, deadline=None)
@given(st.integers(0, 2**31 - 1))
def test_the_share_inside_capsules_matches_a_brute_force_oracle(seed: int) -> None:
    rng = np.random.default_rng(seed)
    caps = [(rng.uniform(-1, 1, 3), rng.uniform(-1, 1, 3), float(rng.uniform(0.05, 0.4)))]
    caps.append((caps[0][1], caps[0][1] + rng.uniform(-0.3, 0.3, 3), 0.1))
    pts = rng.uniform(-1.5, 1.5, (400, 3))
    # points within 1 mm of a capsule's surface may fall either way with the oracle's sampling
    gap = np.full(len(pts), np.inf)
    for a, b, r in caps:
        t = np.clip((pts - a) @ (b - a) / ((b - a) @ (b - a)), 0.0, 1.0)
        near = np.abs(np.linalg.norm(pts - a - t[:, None] * (b - a), axis=1) - r)
        gap = np.minimum(gap, near)
    pts = pts[gap > 1e-3]
    assert OwnBodies.share(pts, caps) == pytest.approx(_brute_share(pts, caps))
    assert OwnBodies.share(pts[:0], caps) == 0.0 and OwnBodies.share(pts, []) == 0.0


def test_an_arms_capsules_come_from_its_joints_as_the_motion_model_places_them() -> None:
    pytest.importorskip("pinocchio")
    from hltl.motion.kinematics import Arm

    base = (0.4, -0.2, 0.0)
    scene = Scene(robots=(Robot("r1", base, 0.6, model="elfin3"), Robot("r2", (1, 0, 0), 0.6)))
    arm = Arm("r1", "elfin3", base)
    rng = np.random.default_rng(3)
    bodies = OwnBodies(scene, margin=0.02)
    for _ in range(3):
        q = rng.uniform(arm.lower, arm.upper)
        caps = bodies.capsules({"r1": tuple(q), "r2": (0.0,) * 4, "ghost": (0.0,)})
        want = arm.capsules(q)  # the motion layer's own capsules, built by its Arm
        assert len(caps) == len(want)  # r2 (no motion model) and "ghost" (not in the scene): none
        for (a, b, r), c in zip(caps, want, strict=True):
            assert (
                np.allclose(a, c.a) and np.allclose(b, c.b) and r == pytest.approx(c.radius + 0.02)
            )
        # points on the hand's axis are the arm; points 0.5 m above its base's top are not
        hand = want[-1]
        on = np.linspace(hand.a, hand.b, 20)
        assert OwnBodies.share(on, caps) == 1.0
        assert OwnBodies.share(on + np.array([0.0, 0.0, 5.0]), caps) == 0.0
    with pytest.raises(PerceptionError, match=r"robot r1 \(elfin3\) has 6 joints, got 2"):
        bodies.capsules({"r1": (0.0, 0.0)})
    assert bodies.capsules(None) == [] and OwnBodies(None).capsules({"r1": tuple(q)}) == []


def test_the_simulator_reports_joints_only_of_arms_drawn_as_their_motion_model() -> None:
    pytest.importorskip("mujoco")
    pytest.importorskip("pinocchio")
    from hltl.sim.scenarios import get
    from hltl.sim3d.model import compile_scene
    from hltl.sim3d.stage import Stage

    scene = get("4-4-square").scene  # three xArm6 (drawn as the primitive arm) and an Elfin-3
    joints = Stage(compile_scene(scene)).joints()
    drawn = {r.id for r in scene.robots if r.model == "elfin3"}
    assert set(joints) == drawn and all(len(q) == 6 for q in joints.values())
    caps = OwnBodies(scene).capsules(joints)  # every reported arm is placed, none refused
    assert len(caps) == 7 * len(drawn)
