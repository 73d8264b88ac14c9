"""The scene's ``cameras:`` block and ``hltl render``."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest
import yaml

from hltl.cli.main import main
from hltl.errors import SceneError
from hltl.world.scene import scene_from_dict

BASE: dict[str, Any] = {"robots": [{"id": "r1", "base": [0, 0, 0], "reach": 0.6}]}


def _with(cam: dict[str, Any]) -> dict[str, Any]:
    return {**BASE, "cameras": [cam]}


def test_camera_defaults_and_round_trip() -> None:
    s = scene_from_dict(_with({"id": "c", "position": [0, -2, 1], "look_at": [0, 0, 0]}))
    c = s.cameras[0]
    assert (c.width, c.height, c.fovy, c.rate) == (640, 480, 42.0, 10.0)
    assert scene_from_dict(s.to_dict()) == s


def test_camera_units_scale() -> None:
    s = scene_from_dict(
        {**_with({"id": "c", "position": [0, -200, 100], "look_at": [0, 0, 0]}), "units": "cm"}
    )
    assert s.cameras[0].position == (0.0, -2.0, 1.0)


@pytest.mark.parametrize(
    ("cam", "needle"),
    [
        ({"id": "c", "position": [0, 0, 1], "look_at": [0, 0, 1]}, "look_at"),
        ({"id": "c", "position": [0, -1, 1], "look_at": [0, 0, 0], "fovy": 0}, "fovy"),
        ({"id": "c", "position": [0, -1, 1], "look_at": [0, 0, 0], "width": 3}, "width"),
        ({"id": "c", "position": [0, -1, 1], "look_at": [0, 0, 0], "zoom": 2}, "zoom"),
        ({"id": "c", "position": [0, -1], "look_at": [0, 0, 0]}, "position"),
    ],
)
def test_bad_cameras_are_named(cam: dict[str, Any], needle: str) -> None:
    with pytest.raises(SceneError, match=needle):
        scene_from_dict(_with(cam), source="s.yaml")


def test_duplicate_camera_ids() -> None:
    cam = {"id": "c", "position": [0, -1, 1], "look_at": [0, 0, 0]}
    with pytest.raises(SceneError, match="duplicate camera"):
        scene_from_dict({**BASE, "cameras": [cam, cam]})


def test_render_cli(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    pytest.importorskip("mujoco")
    scene = {
        **BASE,
        "objects": [{"id": "cup", "category": "cup", "position": [0.3, 0, 0.05]}],
        "cameras": [
            {
                "id": "top",
                "position": [0, -1.5, 1.0],
                "look_at": [0, 0, 0],
                "width": 96,
                "height": 72,
            }
        ],
    }
    path = tmp_path / "s.yaml"
    path.write_text(yaml.safe_dump(scene))
    out = tmp_path / "frames"
    assert main(["render", "--scene", str(path), "-o", str(out), "--geometry", "collision"]) == 0
    meta = json.loads((out / "camera.json").read_text())
    assert meta["name"] == "top" and len(meta["frames"]) == 1
    assert (out / "rgb" / "000000.png").exists() and (out / "depth" / "000000.npz").exists()
    assert "object cup" in capsys.readouterr().out
    assert main(["render", "--scene", str(path), "-o", str(out), "--camera", "nope"]) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("error: --camera: no camera 'nope'")
