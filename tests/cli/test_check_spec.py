"""``hltl check-spec``: output, JSON, and exit codes."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from hltl.cli.main import main

SPECS = Path(__file__).parents[2] / "examples" / "specs"


def test_valid_spec_prints_a_tree(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["check-spec", str(SPECS / "fig1.yaml")]) == 0
    out, err = capsys.readouterr()
    assert err == ""
    lines = out.splitlines()
    assert lines[0] == f"{SPECS / 'fig1.yaml'}: valid (3 formulas, depth 2)"
    assert "p0: F p100 & F p200  [4 states, 9 edges]" in lines[1]
    assert "p100: F delivered(bottle, A)  [2 states, 3 edges]" in lines[2]
    assert "p200: F delivered(chips, B)  [2 states, 3 edges]" in lines[3]
    # children are drawn under their parent
    assert lines[2].index("p100") > lines[1].index("p0")


def test_json_output(capsys: pytest.CaptureFixture[str]) -> None:
    files = [str(SPECS / "three_level.yaml"), str(SPECS / "office_2.yaml")]
    assert main(["check-spec", *files, "--json"]) == 0
    reports = json.loads(capsys.readouterr().out)
    assert [r["file"] for r in reports] == files
    three = reports[0]
    assert three["valid"] and three["root"] == "p0" and three["depth"] == 3
    by_name = {f["name"]: f for f in three["formulas"]}
    assert by_name["p100"] == {
        "name": "p100",
        "formula": "F (p110 & F p120)",
        "level": 1,
        "parent": "p0",
        "children": ["p110", "p120"],
        "leaf": False,
        "states": 3,
        "edges": 6,
    }
    assert by_name["p120"]["leaf"] and by_name["p0"]["parent"] is None
    assert len(reports[1]["formulas"]) == 4


def test_invalid_spec_exits_1_with_the_file_name(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    bad = tmp_path / "bad.yaml"
    bad.write_text(
        "root: p0\nformulas:\n  p0: 'F (p100 & p200)'\n"
        "  p100: 'F delivered(bottle, A)'\n  p200: 'F delivered(chips, B)'\n"
    )
    assert main(["check-spec", str(SPECS / "fig1.yaml"), str(bad)]) == 1
    out, err = capsys.readouterr()
    assert "fig1.yaml: valid" in out  # the good file is still reported
    assert err.startswith(f"error: {bad}: p0: 'F (p100 & p200)' requires p100 and p200")


def test_invalid_spec_in_json(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    bad = tmp_path / "bad.yaml"
    bad.write_text("root: p0\nformulas: {p0: 'F (p100 & )', p100: 'F picked(cup)'}\n")
    assert main(["check-spec", "--json", str(bad)]) == 1
    out, err = capsys.readouterr()
    (report,) = json.loads(out)
    assert report["file"] == str(bad) and report["valid"] is False
    assert report["error"].startswith(f"{bad}: formula p0: unexpected ')'")
    assert err.startswith(f"error: {bad}: formula p0: unexpected ')' at line 1, column 11")


def test_unknown_file(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    missing = tmp_path / "nope.yaml"
    assert main(["check-spec", str(missing)]) == 1
    assert capsys.readouterr().err.startswith(f"error: {missing}: cannot read spec")


def test_no_file_is_a_usage_error(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["check-spec"]) == 2
    assert "FILE" in capsys.readouterr().err
