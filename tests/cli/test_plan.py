"""``hltl plan``: timeline and JSON output, exit codes 0 / 1 / 2."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from hltl.cli.main import main

SCENE = "examples/scenes/two_arms.yaml"
FIG1 = ["plan", "--scene", SCENE, "--spec", "examples/specs/fig1.yaml"]


@pytest.fixture(autouse=True)
def _at_root(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(Path(__file__).resolve().parents[2])


def test_plan_json_follows_the_plan_format(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["plan", "--scene", SCENE, "--spec", "examples/specs/fig1.yaml", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["status"] == "solved" and data["makespan"] == 1.0
    assert data["scene"] == SCENE and data["spec"]["root"] == "p0"
    assert set(data["planner"]) >= {"expanded", "seconds"}
    step = data["steps"][0]
    assert set(step) == {"start", "duration", "bindings", "actions"}
    assert {a["skill"] for a in step["actions"]} == {"pick"}


def test_plan_timeline_and_output_file(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    out = tmp_path / "plan.json"
    args = ["plan", "--scene", SCENE, "--instruction", "Give Alice the crisps", "-o", str(out)]
    assert main(args) == 0
    text = capsys.readouterr().out
    assert "makespan 1.60 s" in text and "r2 hands chips to r1" in text
    assert json.loads(out.read_text())["makespan"] == 1.6


def test_infeasible_exits_1_with_the_reason(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    scene = tmp_path / "far.yaml"
    scene.write_text(
        "robots: [{id: r1, base: [0, 0, 0], reach: 0.5}]\n"
        "objects: [{id: cup, position: [3, 0, 0]}]\n"
        "humans: [{id: A, position: [0.5, 0, 0]}]\n"
        "durations: {pick: 0.5, place: 0.5, handover_r2r: 0.6, handover_r2h: 0.5}\n"
    )
    assert main(["plan", "--scene", str(scene), "--instruction", "give A the cup"]) == 1
    err = capsys.readouterr().err
    assert err.startswith("error: infeasible: no plan satisfies p0: delivered(cup, A)")
    assert "out of reach of every available robot" in err


@pytest.mark.parametrize(
    ("argv", "code", "needle"),
    [
        (["plan", "--scene", SCENE], 2, "one of the arguments --spec --instruction"),
        (["plan", "--scene", "missing.yaml", "--spec", "x.yaml"], 1, "missing.yaml"),
        (["plan", "--scene", SCENE, "--instruction", "give A the cup"], 1, "no object called"),
        (
            ["plan", "--scene", SCENE, "--spec", "examples/specs/fig1.yaml", "--timeout", "0"],
            1,
            "--timeout: expected a finite number > 0",
        ),
        (
            [*FIG1, "--suboptimality", "0.5"],
            1,
            "--suboptimality: expected a factor of at least 1 (e.g. 1.1), got 0.5",
        ),
    ],
)
def test_usage_and_input_errors(
    argv: list[str], code: int, needle: str, capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(argv) == code
    assert needle in capsys.readouterr().err


@pytest.mark.parametrize("command", ["run", "demo"])
def test_failed_episodes_end_with_one_error_line(
    command: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    argv = [command, "--instruction", "give Z the bottle"]
    argv += ["--scene", SCENE] if command == "run" else ["--no-pictures", "--out", str(tmp_path)]
    assert main(argv) == 1
    err = [ln for ln in capsys.readouterr().err.splitlines() if ln.startswith("error:")]
    assert len(err) == 1 and "no person called 'Z'" in err[0]


def test_anytime_reports_bound_and_gap(capsys: pytest.CaptureFixture[str]) -> None:
    argv = ["plan", "--scene", SCENE, "--spec", "examples/specs/fig1.yaml", "--anytime"]
    assert main([*argv, "--timeout", "2", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["status"] == "solved" and data["makespan"] == 1.0
    assert data["lower_bound"] == 1.0 and data["gap"] == 0.0
    assert main([*argv, "--suboptimality", "1.5"]) == 0
    assert "optimal within 0.0 %" in capsys.readouterr().out
