"""Workspace geometry, the context label ℓ(w), world state and projection."""

from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import given
from hypothesis import strategies as st

from hltl.errors import UnknownEntityError
from hltl.world.geometry import (
    can_meet,
    context_label,
    distance,
    human_in_workspace,
    reaches,
    rendezvous_point,
)
from hltl.world.scene import Robot, load_scene
from hltl.world.state import REST, Loc, ObjectStatus, initial_world, project


def test_two_arms_context(two_arms_path: Path) -> None:
    scene = load_scene(two_arms_path)
    ctx = context_label(scene, {h.id: h.position for h in scene.humans})
    assert ctx.robots_serving("A") == frozenset({"r1"})
    assert ctx.robots_serving("B") == frozenset({"r2"})
    assert not ctx.blocked("r1", "r2")
    # Person A walks to the middle: inside both workspaces, the rendezvous is blocked
    ctx2 = context_label(scene, {"A": (0.6, 0.2, 0.0), "B": (1.9, 0.5, 0.0)})
    assert ctx2.robots_serving("A") == frozenset({"r1", "r2"})
    assert ctx2.blocked("r1", "r2") and ctx2.blocked("r2", "r1")


def test_reach_is_inclusive_and_meeting_is_strict() -> None:
    a = Robot("a", (0.0, 0.0, 0.0), 0.5)
    b = Robot("b", (1.0, 0.0, 0.0), 0.5)
    assert reaches(a, (0.5, 0.0, 0.0))
    assert not reaches(a, (0.51, 0.0, 0.0))
    assert not can_meet(a, b)  # spheres touch at one point: no room for two hands
    assert can_meet(a, Robot("c", (0.99, 0.0, 0.0), 0.5))
    assert human_in_workspace(a, (0.8, 0.0, 5.0), 0.3)  # height is ignored for people


coords = st.floats(-2.0, 2.0)
reach = st.floats(0.2, 1.5)


@given(coords, coords, reach, coords, coords, reach)
def test_rendezvous_point_is_reachable_by_both(
    x1: float, y1: float, r1: float, x2: float, y2: float, r2: float
) -> None:
    a = Robot("a", (x1, y1, 0.0), r1)
    b = Robot("b", (x2, y2, 0.0), r2)
    if not can_meet(a, b) or distance(a.base, b.base) < 1e-6:
        return
    p = rendezvous_point(a, b)
    flat = (p[0], p[1], 0.0)
    assert distance(a.base, flat) <= a.reach + 1e-9
    assert distance(b.base, flat) <= b.reach + 1e-9


def test_world_state_updates_and_projection(two_arms_path: Path) -> None:
    scene = load_scene(two_arms_path)
    w = initial_world(scene)
    assert project(w).loc("bottle") == REST
    w2 = w.with_object("bottle", ObjectStatus((0.1, 0.1, 0.3), Loc("held", "r1")))
    assert w2.holding("r1") == "bottle" and w.holding("r1") is None
    assert project(w2).loc("bottle") == Loc("held", "r1")
    w3 = w2.with_human("A", (1.0, 0.0, 0.0))
    assert w3.human_position("A") == (1.0, 0.0, 0.0)
    assert w3.context(scene) != w2.context(scene)
    with pytest.raises(UnknownEntityError, match="unknown human 'Z'"):
        w.with_human("Z", (0.0, 0.0, 0.0))
