"""``hltl perception train-predictor/eval-predictor`` and ``hltl run --predictor``."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from hltl.cli.main import main

pytest.importorskip("torch")

ROOT = Path(__file__).resolve().parents[2]
SCENE = str(ROOT / "examples" / "scenes" / "two_arms.yaml")
EVENTS = ROOT / "examples" / "events"


def test_train_then_evaluate_a_tiny_predictor(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    out = tmp_path / "w.npz"
    args = ["perception", "train-predictor", "--walks", "2", "--epochs", "1", "--out", str(out)]
    assert main(args) == 0
    assert "wrote" in capsys.readouterr().out
    assert (
        main(["perception", "eval-predictor", "--walks", "1", "--weights", str(out), "--json"]) == 0
    )
    scores = json.loads(capsys.readouterr().out)
    assert set(scores) == {"mixed", "simulator walks", "stops & turns", "wandering"}
    for rows in scores.values():
        assert [r["predictor"] for r in rows] == ["cv", "goal", "gru"]
        assert all(r["ade@1s"] <= r["ade@2s"] for r in rows)


def test_a_training_mix_is_recorded_and_the_oracle_scores_a_test_set(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    from hltl.perception.gru import load_model

    out = tmp_path / "w.npz"
    args = ["perception", "train-predictor", "--walks", "2", "--epochs", "1", "--out", str(out)]
    assert main([*args, "--mix", "0,0,0,0,1"]) == 0
    meta = load_model(out).meta
    assert meta["mix"] == [0.0, 0.0, 0.0, 0.0, 1.0] and "--mix=0,0,0,0,1" in meta["command"]
    capsys.readouterr()
    orc = ["perception", "oracle-predictor", "--walks", "1", "--library", "2", "--k", "5"]
    assert main([*orc, "--json"]) == 0
    res = json.loads(capsys.readouterr().out)
    assert res["set"] == "wandering" and res["library_windows"] > 5
    rows = res["scores"]
    assert [r["predictor"] for r in rows] == ["cv", "goal", "gru", "oracle"]
    assert rows[0]["vs_cv"] == [0.0, 0.0, 0.0, 0.0]
    for r in rows:  # the margins are the table's own numbers
        assert r["vs_cv"][2] == pytest.approx(1 - r["ade@2s"] / rows[0]["ade@2s"], abs=1e-3)
    for bad, what in (("1,2", "--mix"), ("0,0,0,0,0", "--mix"), ("a,b,c,d,e", "--mix")):
        assert main([*args, "--mix", bad]) == 1
        err = capsys.readouterr().err.strip().splitlines()
        assert len(err) == 1 and err[0].startswith(f"error: {what}")
    assert main([*orc, "--k", "100000"]) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("error: --k")


def test_bad_arguments_give_one_error_line(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(["perception", "eval-predictor", "--walks", "0"]) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("error: --walks")
    bad = tmp_path / "bad.npz"
    bad.write_text("x")
    assert main(["perception", "eval-predictor", "--weights", str(bad)]) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "not a GRU predictor weights file" in err[0]
    assert main(["perception", "train-detector", "--views", "0"]) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("error: --views")


@pytest.mark.parametrize("predictor", ["goal", "gru"])
def test_run_with_a_configured_predictor(
    predictor: str, capsys: pytest.CaptureFixture[str]
) -> None:
    code = main(
        [
            "run",
            "--scene", SCENE,
            "--instruction", "Give Person A the chips",
            "--events", str(EVENTS / "h_move_midhandover.yaml"),
            "--predictor", predictor,
            "--json",
        ]
    )  # fmt: skip
    assert code == 0
    assert json.loads(capsys.readouterr().out)["success"] is True
