"""Phrasings the session-56 lead changes read or refuse (docs/grounding.md, Session 56 (lead))."""

from __future__ import annotations

import pytest

from hltl.bench.grounding import show_tree
from hltl.errors import GroundingError
from hltl.grounding import _rewrites56l, offline
from hltl.grounding.offline import parse_instruction
from hltl.world.scene import Scene
from tests.grounding.helpers import (
    CELL,
    KITCHEN,
    WARD,
    WORKSHOP,
    assert_names_readings,
    assert_reads,
)

# -- the speaker remembers only that it was one of the options (blind54 #99: "Jess asked for one
# of the tools, the torch or the hammer, it was one of those." read torch>B | hammer>B, a free
# choice)

ONE_OF_THOSE = [
    (
        "Jess asked for one of the tools, the torch or the hammer, it was one of those.",
        WORKSHOP,
        ("torch", "hammer"),
    ),
    ("Jess asked for the torch or the hammer, it was one of those.", WORKSHOP, ("torch", "hammer")),
    ("Bob wanted the cup or the apple; it was definitely one of them.", CELL, ("cup", "apple")),
    ("Marco asked for the lemon or the salt, it was one of the two.", KITCHEN, ("lemon", "salt")),
    ("Mr Lee asked for the jug or the tablets. It was one of those two.", WARD, ("jug", "pills")),
]


@pytest.mark.parametrize(("text", "scene", "readings"), ONE_OF_THOSE)
def test_it_was_one_of_those_refused_naming_both(
    text: str, scene: Scene, readings: tuple[str, ...]
) -> None:
    assert_names_readings(text, scene, readings)
    with pytest.raises(GroundingError, match=r"says one was asked for, not which"):
        parse_instruction(text, scene)


def test_it_was_one_of_those_read_as_a_choice_without_the_check(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """The check is what refuses them: without it each was read as a free choice."""
    rule = _rewrites56l._was_one_of56l
    monkeypatch.setattr(offline, "_CHECKS", tuple(c for c in offline._CHECKS if c is not rule))
    for text, scene, _ in ONE_OF_THOSE:
        assert " | " in show_tree(parse_instruction(text, scene)), text


@pytest.mark.parametrize(
    ("text", "scene", "spec"),
    [
        # no choice said, or the choice left free
        ("Jess asked for the torch or the hammer, either is fine.", WORKSHOP,
         "torch>B | hammer>B"),
        ("Jess asked for the torch or the hammer, it was one of those, either is fine.", WORKSHOP,
         "torch>B | hammer>B"),
        ("Jess asked for one of the tools, the torch or the hammer.", WORKSHOP,
         "torch>B | hammer>B"),
        ("Jess asked for the torch, it was one of those days.", WORKSHOP, "torch>B"),
    ],
)  # fmt: skip
def test_choices_without_the_remark_still_read(text: str, scene: Scene, spec: str) -> None:
    assert_reads(text, spec, scene)


# -- given already, said with 'that' / 'those' (12c's fuzz, session 55: "Give Bob the apple,
# I've already handed that over." read apple>B)


@pytest.mark.parametrize(
    ("text", "scene"),
    [
        ("Give Bob the apple, I've already handed that over.", CELL),
        ("Bob wants the apple, I gave that to him.", CELL),
        ("Bob wants the crisps, I've handed those over already.", CELL),
        ("Give Bob the apple, that's already been given to him.", CELL),
        ("Mr Lee wants his jug, I brought that to him earlier.", WARD),
    ],
)
def test_given_already_with_that_refused(text: str, scene: Scene) -> None:
    with pytest.raises(GroundingError):
        parse_instruction(text, scene)


@pytest.mark.parametrize(
    ("text", "scene", "spec"),
    [
        ("Give Bob the apple, that's been washed.", CELL, "apple>B"),
        ("Bob wants the apple, I brought that in this morning.", CELL, "apple>B"),
    ],
)
def test_that_of_other_doings_still_read(text: str, scene: Scene, spec: str) -> None:
    assert_reads(text, spec, scene)
