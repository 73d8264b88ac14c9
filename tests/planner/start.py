"""The relaxation's inputs at a problem's start node, shared by the bound tests."""

from __future__ import annotations

import pytest

from hltl.planner import schedule
from hltl.planner.problem import Node, Problem
from hltl.planner.relaxed import RelaxedGraph
from hltl.planner.schedule import Target
from hltl.planner.search import _Search


def start_targets(problem: Problem) -> tuple[_Search, Node, RelaxedGraph, list[Target]]:
    """(the search, its start node, the heuristic's relaxed graph, the schedule targets every
    accepting run from there needs) for ``problem``."""
    s = _Search(problem)
    node = problem.start()
    graph = s.heuristic.graph
    required = s.heuristic.required_atoms(node[2])
    return s, node, graph, schedule.targets(problem, graph, node, required)


def step_levels(monkeypatch: pytest.MonkeyPatch) -> list[int]:
    """The levels the step model (``schedule.relaxed_steps``) is asked at from now on, in the
    order asked (any model; two threads may ask in either order)."""
    levels: list[int] = []
    real = schedule.relaxed_steps

    def logged(*args: object, **kwargs: object) -> object:
        level = args[4]
        assert isinstance(level, int)
        levels.append(level)
        return real(*args, **kwargs)  # type: ignore[arg-type]

    monkeypatch.setattr(schedule, "relaxed_steps", logged)
    return levels
