"""``hltl ground``: tree output, JSON, updates, rejected instructions and exit codes."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
import yaml

from hltl.cli.main import main

ROOT = Path(__file__).parents[2]
TWO = str(ROOT / "examples" / "scenes" / "two_arms.yaml")
CELL = str(ROOT / "examples" / "scenes" / "grounding_cell.yaml")


def test_prints_the_spec_tree_and_tokens(capsys: pytest.CaptureFixture[str]) -> None:
    text = "give A the bottle, then put the chips on the shelf"
    assert main(["ground", "--scene", TWO, "--instruction", text]) == 0
    out, err = capsys.readouterr()
    assert err == ""
    lines = out.splitlines()
    assert lines[0].split() == ["p0", "F", "(p100", "&", "F", "p200)"]
    assert "p100  F delivered(bottle, A)" in lines[1]
    assert "p200  F placed(chips, shelf)" in lines[2]
    assert "entities: bottle, A (Person A), chips, shelf" in out
    assert "tokens: 0 prompt + 0 completion" in out


def test_json_is_exactly_one_object(capsys: pytest.CaptureFixture[str]) -> None:
    text = "Give Person A the bottle and Person B the chips"
    assert main(["ground", "--scene", TWO, "--instruction", text, "--json"]) == 0
    out = capsys.readouterr().out
    assert out.count("\n") == 1
    assert json.loads(out) == {
        "spec": {
            "root": "p0",
            "formulas": {
                "p0": "F p100 & F p200",
                "p100": "F delivered(bottle, A)",
                "p200": "F delivered(chips, B)",
            },
        },
        "entities": ["bottle", "A", "chips", "B"],
        "tokens": {"prompt": 0, "completion": 0},
    }


def test_rejected_instruction_exits_1_with_the_reason(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["ground", "--scene", TWO, "--instruction", "give A the cup", "--json"]) == 1
    out, err = capsys.readouterr()
    assert out == ""
    assert err == "error: no object called 'cup' in the scene; objects: bottle, chips\n"


def test_update_of_a_running_spec(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    running = tmp_path / "running.yaml"
    assert (
        main(
            [
                "ground",
                "--scene",
                CELL,
                "--instruction",
                "give A the cup and B the chips",
                "-o",
                str(running),
            ]
        )
        == 0
    )
    capsys.readouterr()
    assert yaml.safe_load(running.read_text())["formulas"]["p200"] == "F delivered(chips, B)"
    args = ["ground", "--scene", CELL, "--running", str(running), "--json"]
    assert main([*args, "--instruction", "Also give Carol the apple"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["spec"]["root"] == "p0_1"
    assert data["spec"]["formulas"]["p0_1"] == "F p0 & F p300"
    assert data["update"]["kind"] == "add" and data["entities"] == ["apple", "C"]
    assert main([*args, "--instruction", "cancel the chips"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["spec"]["formulas"] == {"p0": "F p100", "p100": "F delivered(cup, A)"}
    assert data["update"]["removed"] == ["p200"]


def test_usage_errors_exit_2(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["ground", "--scene", TWO]) == 2
    assert main(["ground", "--scene", TWO, "--instruction", "x", "--grounder", "gpt"]) == 2
    capsys.readouterr()


def test_llm_grounder_without_an_endpoint_fails_cleanly(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    pytest.importorskip("openai")
    for var in ("HLTL_LLM_BASE_URL", "HLTL_LLM_API_KEY", "OPENAI_API_KEY", "HLTL_LLM_CONFIG"):
        monkeypatch.delenv(var, raising=False)
    monkeypatch.setenv("HOME", str(tmp_path))
    code = main(
        ["ground", "--scene", TWO, "--instruction", "give A the bottle", "--grounder", "llm"]
    )
    assert code == 1
    assert "no API key for OpenAI" in capsys.readouterr().err


def test_local_grounder_without_llama_cpp_names_the_extra(
    capsys: pytest.CaptureFixture[str],
) -> None:
    import importlib.util

    if importlib.util.find_spec("llama_cpp") is not None:
        pytest.skip("llama-cpp-python is installed")
    args = ["ground", "--scene", TWO, "--instruction", "give A the bottle", "--grounder", "local"]
    assert main(args) == 1
    assert "pip install 'hltl[local]'" in capsys.readouterr().err
