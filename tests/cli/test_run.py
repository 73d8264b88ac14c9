"""``hltl run`` and ``hltl score`` end to end."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from hltl.cli.main import main

ROOT = Path(__file__).resolve().parents[2]
SCENE = str(ROOT / "examples" / "scenes" / "two_arms.yaml")
EVENTS = ROOT / "examples" / "events"
KEYS = {
    "success",
    "time_cost",
    "replans",
    "tokens",
    "violations",
    "h_idle",
    "r_idle",
    "c_act",
    "f_del",
}


def test_run_json_then_score_the_log(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    log = tmp_path / "out.jsonl"
    code = main(
        [
            "run",
            "--scene", SCENE,
            "--instruction", "Give Person A the chips",
            "--events", str(EVENTS / "h_move_midhandover.yaml"),
            "--seed", "3",
            "--log", str(log),
            "--json",
        ]
    )  # fmt: skip
    assert code == 0
    metrics = json.loads(capsys.readouterr().out)
    assert set(metrics) >= KEYS and metrics["success"] is True and metrics["replans"] >= 1
    assert main(["score", str(log), "--json"]) == 0
    rescored = json.loads(capsys.readouterr().out)
    assert rescored.pop("invariant_problems") == []
    assert rescored == metrics


def test_run_prints_a_timeline(capsys: pytest.CaptureFixture[str]) -> None:
    code = main(
        ["run", "--scene", SCENE, "--instruction", "Give Person A the bottle", "--no-predict"]
    )
    out = capsys.readouterr().out
    assert code == 0
    assert "r1 picks bottle" in out and "r1 hands bottle to Person A" in out and "h_idle" in out


def test_give_up_exits_1(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    events = tmp_path / "down.yaml"
    events.write_text("events:\n  - {t: 0.0, type: robot_down, robot: r2, duration: 100}\n")
    code = main(
        ["run", "--scene", SCENE, "--instruction", "Give Person A the chips",
         "--events", str(events), "--max-time", "5", "--json"]
    )  # fmt: skip
    assert code == 1
    assert json.loads(capsys.readouterr().out)["success"] is False


def test_bad_events_file_is_an_error(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    events = tmp_path / "bad.yaml"
    events.write_text("events:\n  - {t: 1.0, type: human_move, human: Zed, to: [0, 0, 0]}\n")
    code = main(
        [
            "run",
            "--scene",
            SCENE,
            "--instruction",
            "Give Person A the chips",
            "--events",
            str(events),
        ]
    )
    err = capsys.readouterr().err
    assert code == 1
    assert "bad.yaml: events[0].human: unknown human" in err and "'Zed'" in err


def test_score_rejects_a_truncated_log(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    log = tmp_path / "t.jsonl"
    log.write_text('{"t": 0, "type": "episode_start", "scene": {}}\n')
    assert main(["score", str(log)]) == 1
    assert "no episode_end" in capsys.readouterr().err
