"""The cell-scale planner benchmark: its instances are valid and its table reads right."""

from __future__ import annotations

import pytest

from hltl.bench.cells import (
    CELL_LAYOUTS,
    FAMILIES,
    CellRow,
    _stolen,
    delivery_cell,
    format_cells,
    mixed_cell,
    run_cells,
)
from hltl.planner import PlanStatus, plan
from tests.oracles.validator import check_plan


@pytest.mark.parametrize("layout", CELL_LAYOUTS)
def test_delivery_cells_plan_and_validate(layout: str) -> None:
    cell = delivery_cell(layout, 4, 1)
    assert len(cell.scene.robots) == 4 and len(cell.scene.objects) == 4
    res = plan(cell.scene, cell.spec, timeout=60)
    assert res.status is PlanStatus.SOLVED
    check_plan(cell.scene, cell.spec, res.to_dict())


@pytest.mark.parametrize("family", FAMILIES)
def test_mixed_family_cells_plan_and_validate(family: str) -> None:
    cell = mixed_cell(family, 4, 0)
    res = plan(cell.scene, cell.spec, timeout=60)
    assert res.status is PlanStatus.SOLVED
    check_plan(cell.scene, cell.spec, res.to_dict())
    if family == "place-deliver":
        assert any(a.skill == "place" for a in res.actions)


def test_random_layouts_differ_by_seed_and_repeat_by_seed() -> None:
    a, b = delivery_cell("random", 6, 0), delivery_cell("random", 6, 1)
    assert a.scene.robots != b.scene.robots
    assert delivery_cell("random", 6, 0).scene == a.scene


def test_rows_and_table() -> None:
    cells = [delivery_cell("grid", 3, s) for s in range(2)]
    rows = run_cells(cells, exact_timeout=30, anytime_budgets=(0.2, 0.4))
    assert len(rows) == 1
    row = rows[0]
    assert row.seeds == 2 and row.exact_solved == 2 and row.gap_long == 0.0
    table = format_cells(
        [row, CellRow("deliveries", "line", 9, 9, 1, None, 0, None, None, None)], (0.2, 0.4)
    )
    assert "| deliveries | grid | 3 × 3 | 2 |" in table
    assert "| deliveries | line | 9 × 9 | 1 | – | – | – | – | – | – |" in table
    assert row.exact_cpu_median_s is not None and row.exact_cpu_median_s > 0


def test_the_exact_line_tells_waiting_from_working(monkeypatch: pytest.MonkeyPatch) -> None:
    # line 6 seed 5 with the first phase (more than PHASE_ABOVE goals): A* runs in a process
    # of its own, so the line shows that process's CPU, when the phase ended and the pause
    from hltl import planner
    from hltl.planner import anytime

    if not anytime.beside_possible():
        pytest.skip("needs two cores and fork")
    monkeypatch.setattr(planner, "PHASE_ABOVE", 0)
    c = delivery_cell("line", 6, 5)
    seen: list[str] = []
    run_cells([c], exact_timeout=120, anytime_budgets=None, on_cell=lambda _, s: seen.append(s))
    assert len(seen) == 1
    line = seen[0]
    assert line.startswith("exact solved ") and "A*'s process " in line
    assert "phase ended at " in line and "A* paused " in line
    # a cell left to A* alone (the phase does not run below PHASE_ABOVE goals) says neither
    monkeypatch.setattr(planner, "PHASE_ABOVE", 8)
    run_cells([c], exact_timeout=120, anytime_budgets=None, on_cell=lambda _, s: seen.append(s))
    assert "phase ended" not in seen[1] and "A*'s process" not in seen[1]
    if (stolen := _stolen()) is not None:  # (Linux: the steal column of /proc/stat)
        assert stolen >= 0 and "stolen by the host" in line
