"""``hltl bench planner`` runs the catalogue and records a Markdown section."""

from __future__ import annotations

from pathlib import Path

from hltl.bench.markdown import write_section
from hltl.cli.main import main


def test_bench_planner_writes_its_section(tmp_path: Path) -> None:
    out = tmp_path / "benchmarks.md"
    out.write_text("# Benchmarks\n\nintro stays\n")
    assert main(["bench", "planner", "--repeats", "1", "--seeds", "1", "--write", str(out)]) == 0
    text = out.read_text()
    assert "intro stays" in text
    assert "Command: `hltl bench planner --repeats 1 --seeds 1" in text
    for config in ("1-1", "4-2", "4-4-line", "4-4-square"):
        assert f"| {config} |" in text
    assert "| solved |" in text and "| timeout |" not in text


def test_write_section_replaces_in_place(tmp_path: Path) -> None:
    path = tmp_path / "b.md"
    write_section(path, "x", "first")
    write_section(path, "y", "other")
    write_section(path, "x", "second")
    text = path.read_text()
    assert "second" in text and "first" not in text and "other" in text
    assert text.index("second") < text.index("other")


def test_bad_scaling_argument_is_a_usage_error(capsys: object) -> None:
    assert main(["bench", "planner", "--scaling", "8by8", "--seeds", "1"]) == 1


def test_bench_replan_writes_its_section(tmp_path: Path) -> None:
    out = tmp_path / "benchmarks.md"
    args = ["bench", "replan", "--seeds", "1", "--configs", "1-2,2-4-line", "--write", str(out)]
    assert main(args) == 0
    text = out.read_text()
    assert "<!-- replan:begin -->" in text and "Command: `hltl bench replan --seeds 1" in text
    assert "| 1-2 | yes | 1 | 1 |" in text and "| 2-4-line | no | 1 | 1 |" in text


def test_bench_replan_rejects_unknown_configs() -> None:
    assert main(["bench", "replan", "--configs", "9-9"]) == 1
