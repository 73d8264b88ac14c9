"""The README's closed-loop example shows what the README says it shows (issue 18, item 10).

tests/test_docs.py checks that every documented command exits as documented; this checks that
the ``hltl run`` tour really has the person walk into the handover region and the executor halt
and replan, reading the execution log the command writes.
"""

from __future__ import annotations

import re
import shlex
from pathlib import Path

import pytest

from hltl.cli.main import main
from hltl.execution.log import read_log

ROOT = Path(__file__).resolve().parents[1]


def _tour_command() -> list[str]:
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    lines = [ln for ln in text.splitlines() if re.match(r"^\.venv/bin/hltl run .*--events", ln)]
    assert len(lines) == 1, lines
    return shlex.split(lines[0])[1:]


def test_the_readme_run_example_halts_and_replans(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    argv = _tour_command()
    log = tmp_path / "episode.jsonl"
    argv[argv.index("--log") + 1] = str(log)
    monkeypatch.chdir(ROOT)
    assert main(argv) == 0, capsys.readouterr().err
    records = read_log(log)
    kinds = [r.type for r in records]
    assert "human_move" in kinds
    halt = next(r for r in records if r.type == "halt")
    after = [r for r in records if r.t >= halt.t]
    assert any(r.type in ("replan", "takeover") for r in after)
    assert any("halt" in r.trigger for r in after if r.type == "replan")
    assert records[-1].type == "episode_end" and records[-1].success
