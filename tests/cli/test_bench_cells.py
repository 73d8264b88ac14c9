"""`hltl bench planner --cells`: choosing layouts and seeds (--layouts, --seed-list)."""

from __future__ import annotations

from typing import Any

import pytest

from hltl.cli import bench
from hltl.cli.main import main


def _cells_run(monkeypatch: pytest.MonkeyPatch, *argv: str) -> list[tuple[str, int]]:
    """The (layout, seed) of each cell `hltl bench planner ARGV` would plan, in order."""
    seen: list[tuple[str, int]] = []

    def run_cells(cells: Any, **_: Any) -> list[Any]:
        seen.extend((c.layout, c.seed) for c in cells)
        return []

    monkeypatch.setattr(bench, "run_cells", run_cells)
    monkeypatch.setattr(bench, "startup_times", lambda _argv: (0.0, 0.0))
    assert main(["bench", "planner", *argv]) == 0
    return seen


def test_every_layout_and_seed_by_default(monkeypatch: pytest.MonkeyPatch) -> None:
    seen = _cells_run(monkeypatch, "--cells", "8x8", "--seeds", "2")
    assert seen == [(layout, s) for layout in ("line", "grid", "random") for s in (0, 1)]


def test_layouts_and_seed_list_choose_the_cells(monkeypatch: pytest.MonkeyPatch) -> None:
    seen = _cells_run(
        monkeypatch,
        "--anytime-cells",
        "8x8",
        "--cells",
        "8x8",
        "--layouts",
        "random,grid",
        "--seed-list",
        "3,1,3",
    )
    # (layouts in the benchmark's order, seeds in the order given, each once)
    want = [("grid", 3), ("grid", 1), ("random", 3), ("random", 1)]
    assert seen == want + want


@pytest.mark.parametrize(
    ("option", "value", "named"),
    [
        ("--layouts", "grid,ring", "'ring'"),
        ("--seed-list", "2,x", "'x'"),
        ("--seed-list", "-1", "'-1'"),
    ],
)
def test_a_bad_choice_is_one_error_line(
    option: str, value: str, named: str, capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(["bench", "planner", "--cells", "8x8", option, value]) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith(f"error: {option}: {named}")
