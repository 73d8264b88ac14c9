"""``hltl viz``: dispatch on the file's content, outputs, and errors that say what was expected."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from PIL import Image

from hltl.cli.main import main

ROOT = Path(__file__).resolve().parents[2]
SCENE = ROOT / "examples" / "scenes" / "two_arms.yaml"
SPEC = ROOT / "examples" / "specs" / "three_level.yaml"
PNG = b"\x89PNG\r\n\x1a\n"


@pytest.fixture(scope="module")
def files(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Path]:
    """A plan JSON and an execution log written by the CLI itself."""
    d = tmp_path_factory.mktemp("viz_inputs")
    plan = d / "plan.json"
    log = d / "episode.jsonl"
    scene = ["--scene", str(SCENE)]
    assert main(["plan", *scene, "--instruction", "Give Person A the chips", "-o", str(plan)]) == 0
    run = [
        "run", *scene,
        "--instruction", "Give Person A the bottle and Person B the chips",
        "--events", str(ROOT / "examples" / "events" / "demo.yaml"),
        "--log", str(log), "--json",
    ]  # fmt: skip
    assert main(run) == 0
    return {"plan": plan, "log": log}


def printed(capsys: pytest.CaptureFixture[str]) -> list[Path]:
    return [Path(line) for line in capsys.readouterr().out.splitlines() if line.strip()]


def test_plan_makes_a_gantt_chart(
    files: dict[str, Path], tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    capsys.readouterr()
    assert main(["viz", str(files["plan"]), "-o", str(tmp_path)]) == 0
    (out,) = printed(capsys)
    assert out == tmp_path / "plan_gantt.png" and out.read_bytes()[:8] == PNG


def test_plan_animation_finds_its_scene_or_takes_one(
    files: dict[str, Path], tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    capsys.readouterr()
    # the plan names its scene by the path it was planned with (absolute here)
    assert main(["viz", str(files["plan"]), "--animate", "-o", str(tmp_path), "--fps", "4"]) == 0
    outs = printed(capsys)
    assert [p.name for p in outs] == ["plan_gantt.png", "plan_anim.gif"]
    with Image.open(outs[1]) as im:
        assert im.n_frames == 9  # 1.6 s + 0.5 s at 4 frames per second, both ends
    # a plan whose scene cannot be found: give --scene
    data = json.loads(files["plan"].read_text(encoding="utf-8"))
    data["scene"] = "nowhere.yaml"
    moved = tmp_path / "moved.json"
    moved.write_text(json.dumps(data), encoding="utf-8")
    assert main(["viz", str(moved), "-o", str(tmp_path / "a.gif")]) == 1
    err = capsys.readouterr().err
    assert "'nowhere.yaml' was not found" in err and "--scene" in err
    assert main(["viz", str(moved), "--scene", str(SCENE), "-o", str(tmp_path / "a.html")]) == 0
    assert "<script" in (tmp_path / "a.html").read_text(encoding="utf-8")


def test_log_makes_a_gantt_chart_and_an_animation(
    files: dict[str, Path], tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    capsys.readouterr()
    assert main(["viz", str(files["log"]), "-o", str(tmp_path), "--max-frames", "6"]) == 0
    gantt, anim = printed(capsys)
    assert gantt.read_bytes()[:8] == PNG
    with Image.open(anim) as im:
        assert im.format == "GIF" and im.n_frames == 6
    # one picture to one file: the suffix picks it
    assert main(["viz", str(files["log"]), "-o", str(tmp_path / "g.svg")]) == 0
    assert "<svg" in (tmp_path / "g.svg").read_text(encoding="utf-8")


def test_frame_draws_one_moment(
    files: dict[str, Path], tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    capsys.readouterr()
    assert main(["viz", str(files["log"]), "--frame", "0.92", "-o", str(tmp_path)]) == 0
    (out,) = printed(capsys)
    assert out == tmp_path / "episode_frame.png" and out.read_bytes()[:8] == PNG


def test_spec_makes_its_tree_and_a_node_dfa(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(["viz", str(SPEC), "--node", "p100", "-o", str(tmp_path)]) == 0
    outs = printed(capsys)
    assert [p.name for p in outs] == ["three_level_tree.png", "three_level_p100_dfa.png"]
    assert all(p.read_bytes()[:8] == PNG for p in outs)


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["{spec}", "--format", "gif"], "a spec tree is a still picture"),
        (["{spec}", "--node", "p9"], "no formula 'p9'"),
        (["{log}", "-o", "{tmp}/one.png", "--format", "svg"], None),
        (["{spec}", "--node", "p100", "-o", "{tmp}/one.png"], "makes 2 pictures (tree, dfa)"),
        (["{log}", "--scene", "{scene}"], "--scene is for plans"),
        (["{log}", "--node", "p0"], "--node draws a node's DFA of a spec"),
        (["{log}", "-o", "{tmp}/x.txt"], "unknown picture format 'txt'"),
        (["{plan}", "--animate", "--format", "png"], "--animate writes an animation"),
        (["{tmp}/missing.json"], "cannot read"),
        (["{junk}"], "expected a plan (JSON with status and steps"),
        (["{log}", "--fps", "0"], "--fps >= 1"),
        (["{spec}", "--frame", "1"], "--frame draws a moment of a plan or log"),
        (["{log}", "--frame", "1", "--format", "gif"], "--frame draws a still picture"),
    ],
)
def test_errors_name_the_file_and_what_was_expected(
    args: list[str],
    message: str | None,
    files: dict[str, Path],
    tmp_path: Path,
    capsys: pytest.CaptureFixture[str],
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    monkeypatch.chdir(tmp_path)
    junk = tmp_path / "junk.json"
    junk.write_text('{"hello": 1}', encoding="utf-8")
    fill = {
        "spec": str(SPEC),
        "log": str(files["log"]),
        "plan": str(files["plan"]),
        "scene": str(SCENE),
        "tmp": str(tmp_path),
        "junk": str(junk),
    }
    argv = ["viz", *(a.format(**fill) for a in args)]
    code = main(argv)
    err = capsys.readouterr().err
    if message is None:  # --format wins over the suffix: an SVG in one.png
        assert code == 0 and "<svg" in (tmp_path / "one.png").read_text(encoding="utf-8")
        return
    assert code == 1 and err.startswith("error: ") and message in err, err


def test_mp4_without_ffmpeg_says_so_before_drawing(
    files: dict[str, Path],
    tmp_path: Path,
    capsys: pytest.CaptureFixture[str],
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    monkeypatch.setattr("hltl.viz.animate.shutil.which", lambda name: None)
    assert main(["viz", str(files["log"]), "--format", "mp4", "-o", str(tmp_path)]) == 1
    assert "MP4 needs ffmpeg" in capsys.readouterr().err
    assert list(tmp_path.iterdir()) == []
