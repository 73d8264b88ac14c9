"""`hltl plan` as a program: its objects are left to the OS at exit, its output is whole."""

from __future__ import annotations

import contextlib
import gc
import io
import json
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest

from hltl.cli.main import FREEZE_AT_EXIT, main

ARGS = ["plan", "--scene", "examples/scenes/two_arms.yaml", "--spec", "examples/specs/fig1.yaml"]


def test_main_called_with_arguments_freezes_nothing() -> None:
    # (a test, a notebook or another program calling main(argv) goes on living)
    assert "plan" in FREEZE_AT_EXIT
    before = gc.get_freeze_count()
    with contextlib.redirect_stdout(io.StringIO()):
        assert main(ARGS) == 0
    assert gc.get_freeze_count() == before


def test_the_program_writes_its_output_whole_and_exits_with_its_code(tmp_path: Path) -> None:
    out = tmp_path / "plan.json"
    code = "import sys; from hltl.cli.main import main; sys.exit(main())"
    run = subprocess.run(
        [sys.executable, "-c", code, *ARGS, "--json", "-o", str(out)],
        capture_output=True,
        text=True,
        check=False,
    )
    assert run.returncode == 0, run.stderr
    assert json.loads(run.stdout) == json.loads(out.read_text(encoding="utf-8"))
    assert json.loads(run.stdout)["makespan"] == 1.0
    bad = tmp_path / "bad.yaml"
    bad.write_text("root: t\nformulas:\n  t: F (a &\n", encoding="utf-8")
    run = subprocess.run(
        [sys.executable, "-c", code, *ARGS[:3], "--spec", str(bad)],
        capture_output=True,
        text=True,
        check=False,
    )
    assert run.returncode == 1
    assert run.stderr.startswith("error: ") and run.stderr.count("\n") == 1, run.stderr


def test_the_other_commands_are_built_only_where_help_can_list_them(
    capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    # `hltl plan ...` (or `hltl --debug plan ...`) builds no parser for the 13 other commands;
    # any other option before the command (--help: the top-level help lists them) builds them all
    import hltl.cli.main as m

    built: list[bool] = []
    real = m.build_parser

    def build(command: str | None = None, *, others: bool = True) -> Any:
        parser = real(command, others=others)
        sub = next(a for a in parser._actions if a.dest == "command")
        built.append(len(sub.choices) == len(m.COMMANDS))  # type: ignore[arg-type]
        return parser

    monkeypatch.setattr(m, "build_parser", build)
    outputs = []
    for argv in (["--help"], ["--help", "plan"], ["-h", "plan"], ["--he", "plan"]):
        assert main(argv) == 0
        outputs.append(capsys.readouterr().out)
    assert built == [True] * 4
    assert outputs[0] == outputs[1] == outputs[2] == outputs[3]
    assert all(name in outputs[0] for name in m.COMMANDS)
    for argv in (["plan", "--help"], ["--debug", "plan", "--help"]):
        assert main(argv) == 0
        outputs.append(capsys.readouterr().out)
    assert built == [True] * 4 + [False] * 2
    assert outputs[4] == outputs[5] and outputs[4].startswith("usage: hltl plan ")
    with contextlib.redirect_stdout(io.StringIO()):
        assert main(["--debug", *ARGS]) == 0
    assert built[-1] is False
