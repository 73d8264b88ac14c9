"""Phrasings the session-51 lead rules refuse or read (docs/grounding.md, Session 51 (lead))."""

from __future__ import annotations

import pytest

from hltl.errors import GroundingError
from hltl.grounding import _rewrites51l, offline
from hltl.grounding.offline import parse_instruction
from hltl.world.scene import Scene
from tests.grounding.helpers import (
    CELL,
    CLASSROOM,
    DEPOT,
    KITCHEN,
    NURSERY,
    WARD,
    WORKSHOP,
    assert_reads,
)

# -- where a thing went or was, told as done (12c's fuzz: "The apple went to Alice." read apple>A)

TOLD_DONE = [
    ("The apple went to Alice.", CELL),
    ("The apple's gone to Alice and the crisps go to Carol.", CELL),
    ("The apple went on the shelf and the crisps go to Carol.", CELL),
    ("The jug went to Mr Lee, so the magazine goes to Mrs Khan.", WARD),
    ("Right so the lemon went to Marco and the salt goes to Lena and that's us.", KITCHEN),
    ("The apple was on the shelf.", CELL),
    ("The jug was on the trolley.", WARD),
    ("The lemon was on the rack, give Marco the salt.", KITCHEN),
    ("The apple ended up on the shelf.", CELL),
    ("The apple's been on the shelf all day.", CELL),
    ("The globe has already gone back to Mrs Ortiz.", CLASSROOM),
    ("The teddy landed on the mat, so the bib's for Lily.", NURSERY),
    ("You gave Alice the apple.", CELL),
    ("It went on the shelf.", CELL),
    ("They went to Bob.", CELL),
    ("You've given the hammer to Kofi, now the torch to Jess.", WORKSHOP),
    ("You've put the small box on the pallet, so the tape to Tom.", DEPOT),
]


@pytest.mark.parametrize(("text", "scene"), TOLD_DONE)
def test_told_as_done_refused(text: str, scene: Scene) -> None:
    with pytest.raises(GroundingError, match="is said as done"):
        parse_instruction(text, scene)


@pytest.mark.parametrize(("text", "scene"), TOLD_DONE)
def test_told_as_done_read_without_the_rule(
    text: str, scene: Scene, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The rule is what refuses them: without it the report is read as a request, or refused
    for another reason (never for being said as done)."""
    kept = tuple(r for r in offline._REFUSALS if r is not _rewrites51l._told_done51l)
    monkeypatch.setattr(offline, "_REFUSALS", kept)
    try:
        parse_instruction(text, scene)
    except GroundingError as refused:
        assert "is said as done" not in str(refused)


def test_most_are_read_without_the_rule(monkeypatch: pytest.MonkeyPatch) -> None:
    """Without the rule, most of these reports were read as requests (the fuzz's wrong readings).
    (The other session-51 refusals and checks are taken out too: 12's refuses a past verb of
    handing, 12r's a handover to one who has had the thing — the same reports in part.)"""
    from hltl.grounding import _rewrites51, _rewrites51r, _rewrites51s

    off = {_rewrites51l._told_done51l, *_rewrites51.REFUSE51, *_rewrites51r.REFUSE51R}
    off |= set(_rewrites51s.REFUSE51S)
    checks = {*_rewrites51.CHECK51, *_rewrites51r.CHECK51R, *_rewrites51s.CHECK51S}
    monkeypatch.setattr(offline, "_REFUSALS", tuple(r for r in offline._REFUSALS if r not in off))
    monkeypatch.setattr(offline, "_CHECKS", tuple(c for c in offline._CHECKS if c not in checks))
    read = 0
    for text, scene in TOLD_DONE:
        try:
            parse_instruction(text, scene)
        except GroundingError:
            continue
        read += 1
    assert read >= 12


@pytest.mark.parametrize(
    ("text", "scene", "spec"),
    [
        # a subordinate clause: the going is the request's own order
        ("Give Alice the bottle after the apple has gone to Carol", CELL, "apple>C ; bottle>A"),
        (
            "After the bottle's gone to Alice and the cup's gone to Bob, put the apple on the "
            "shelf",
            CELL,
            "(bottle>A & cup>B) ; apple@shelf",
        ),
        # the present and the goal said as a state
        ("The apple goes to Alice.", CELL, "apple>A"),
        ("The apple is on the shelf.", CELL, "apple@shelf"),
        ("The jug goes to Mr Lee.", WARD, "jug>B"),
        # a person as the subject
        ("Give Bob the cup, Alice was on the phone.", CELL, "cup>B"),
        # 'you' with the present
        ("You give Alice the apple.", CELL, "apple>A"),
        # 'you' asked, the verb's form that of the past
        ("Could you just put the apple on the shelf, thanks a million", CELL, "apple@shelf"),
        ("Please could you just put the lemon on the rack.", KITCHEN, "lemon@rack"),
    ],
)
def test_not_told_as_done_still_reads(text: str, scene: Scene, spec: str) -> None:
    assert_reads(text, spec, scene)
