"""The exact search runs with Python's cyclic garbage collector off (docs/planner.md, "The
cyclic garbage collector"), and leaves it as it found it."""

from __future__ import annotations

import gc
import sys
from collections.abc import Iterator

import pytest

from hltl.bench.cells import delivery_cell
from hltl.planner import search
from hltl.planner.problem import Problem

# (``hltl.planner.search`` is also the name of the function the package exports)
search_module = sys.modules["hltl.planner.search"]


@pytest.mark.parametrize("on_before", [True, False])
def test_the_cycle_collector_is_off_while_searching(
    on_before: bool, monkeypatch: pytest.MonkeyPatch
) -> None:
    seen: list[bool] = []
    real_steps = search_module._Search.steps

    def steps(self: object, *args: object, **kwargs: object) -> Iterator[object]:
        seen.append(gc.isenabled())
        return real_steps(self, *args, **kwargs)  # type: ignore[arg-type]

    monkeypatch.setattr(search_module._Search, "steps", steps)
    c = delivery_cell("line", 4, 1)
    was = gc.isenabled()
    try:
        if not on_before:
            gc.disable()
        got = search(Problem(c.scene, c.spec), timeout=60)
        after = gc.isenabled()
    finally:
        if was:
            gc.enable()
    assert got.solved and got.makespan == pytest.approx(4.5)
    assert seen and not any(seen)
    assert after is on_before  # (on again after, unless it was off before)
