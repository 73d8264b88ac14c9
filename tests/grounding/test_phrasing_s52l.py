"""Phrasings the session-52 lead rules refuse or read (docs/grounding.md, Session 52 (lead))."""

from __future__ import annotations

import pytest

from hltl.errors import GroundingError
from hltl.grounding import _rewrites52l, offline
from hltl.grounding.offline import parse_instruction
from hltl.world.scene import Scene
from tests.grounding.helpers import (
    CELL,
    CLASSROOM,
    DEPOT,
    KITCHEN,
    NURSERY,
    OFFICE,
    WARD,
    WORKSHOP,
    assert_reads,
)

# -- a person said to have got a thing (12c's fuzz: "Bob ended up with the apple." read apple>B)

GOT_IT = [
    ("Bob ended up with the apple.", CELL),
    ("Bob received the apple.", CELL),
    ("Give Alice the crisps; Bob ended up with the apple.", CELL),
    ("Bob ended up with the apple, and Alice wants the crisps.", CELL),
    ("Mr Lee ended up with the magazine.", WARD),
    ("She's ended up with the jug, so give Mr Lee the magazine.", WARD),
    ("Marco ended up with the lemon.", KITCHEN),
    ("Lena received the tongs, give Marco the salt.", KITCHEN),
    ("Kofi received the hammer.", WORKSHOP),
    ("Jess walked off with the torch.", WORKSHOP),
    ("Tom came away with the tape.", DEPOT),
    ("Sam got hold of the stapler.", OFFICE),
    ("Lily wound up with the teddy.", NURSERY),
    ("Zoe made off with the scissors.", CLASSROOM),
]

# -- who holds a thing, reported (12c's fuzz: "Alice says Bob has the apple." read apple>B) ------

SAYS_HOLDS = [
    ("Alice says Bob has the apple.", CELL),
    ("Alice says Bob's got the apple.", CELL),
    ("Alice says Bob had the apple.", CELL),
    ("Alice said Bob had got the apple.", CELL),
    ("Bob has the apple, Alice says.", CELL),
    ("Bob's got the apple, says Alice.", CELL),
    ("Bob has the apple, Alice says, so give Carol the crisps.", CELL),
    ("Alice says Bob has the apple in his bag.", CELL),
    ("The coxswain says Bob has the apple.", CELL),
    ("Ruth says Mr Lee has got the magazine.", WARD),
    ("Mr Lee has the jug, the nurse says.", WARD),
    ("Kofi says Jess had the drill.", WORKSHOP),
    ("Mia says Tom's got the small box.", DEPOT),
    ("Priya says Sam has the notepad.", OFFICE),
    ("Mrs Ortiz says Noah's got the globe.", CLASSROOM),
]


@pytest.mark.parametrize(("text", "scene"), GOT_IT)
def test_got_it_refused(text: str, scene: Scene) -> None:
    with pytest.raises(GroundingError, match="is said as done"):
        parse_instruction(text, scene)


@pytest.mark.parametrize(("text", "scene"), SAYS_HOLDS)
def test_reported_holding_refused(text: str, scene: Scene) -> None:
    with pytest.raises(GroundingError, match="reported, says what"):
        parse_instruction(text, scene)


def _read_without(
    rule: object, said: str, cases: list[tuple[str, Scene]], mp: pytest.MonkeyPatch
) -> int:
    """How many of ``cases`` read with ``rule`` out of the refusals (none refused as ``said``)."""
    mp.setattr(offline, "_REFUSALS", tuple(r for r in offline._REFUSALS if r is not rule))
    read = 0
    for text, scene in cases:
        try:
            parse_instruction(text, scene)
        except GroundingError as refused:
            assert said not in str(refused)
            continue
        read += 1
    return read


def test_got_it_read_without_the_rule(monkeypatch: pytest.MonkeyPatch) -> None:
    """The rule is what refuses them: without it most were read as hand-overs (the fuzz's wrong
    readings)."""
    assert _read_without(_rewrites52l._got_it52l, "is said as done", GOT_IT, monkeypatch) >= 7


def test_reported_holding_read_without_the_rule(monkeypatch: pytest.MonkeyPatch) -> None:
    """The rule is what refuses them: without it most were read as hand-overs."""
    rule = _rewrites52l._says_holds52l
    assert _read_without(rule, "reported, says what", SAYS_HOLDS, monkeypatch) >= 10


@pytest.mark.parametrize(
    ("text", "scene", "spec"),
    [
        # the present and a request: what is to happen
        ("Make sure Bob ends up with the apple.", CELL, "apple>B"),
        ("Bob receives the apple.", CELL, "apple>B"),
        # a reported want, need or request: a request, as before
        ("Alice says Bob wants the apple.", CELL, "apple>B"),
        ("Alice says Bob has to have the apple.", CELL, "apple>B"),
        ("Alice says Bob has asked for the apple.", CELL, "apple>B"),
        ("Alice says give Bob the apple.", CELL, "apple>B"),
        # a want said with 'has' (12c's probe: lost by the rule's first version)
        ("Alice says Bob has his eye on the apple.", CELL, "apple>B"),
        ("Alice says Bob has a craving for the apple.", CELL, "apple>B"),
        ("Bob wants the apple, Alice says.", CELL, "apple>B"),
        ("Give Carol the cup, Alice says.", CELL, "cup>C"),
        ("Priya says Sam wants the notepad.", OFFICE, "notebook>B"),
    ],
)
def test_requests_still_read(text: str, scene: Scene, spec: str) -> None:
    assert_reads(text, spec, scene)
