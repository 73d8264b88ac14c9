"""Phrasings the session-43 lead rules read (docs/grounding.md, Session 43 (lead))."""

from __future__ import annotations

import pytest

from hltl.bench.grounding import show_tree
from hltl.errors import GroundingError
from hltl.grounding import _rewrites43l
from hltl.grounding.offline import parse_instruction
from tests.grounding.helpers import CELL, OFFICE, WORKSHOP, PhrasingCases

# -- another person's thing handed to the person the clause names (_rewrites43l.owned_other43l):
# 12c's `said` fuzz found "Carol gets Bob's crisps." read chips>B (the owner for the subject)

OWNED = PhrasingCases()
test_owned_other = OWNED.test(
    ("Carol gets Bob's crisps.", "chips>C", CELL),
    ("Could Carol have Bob's cup?", "cup>C", CELL),
    ("Let Carol have Bob's apple.", "apple>C", CELL),
    ("carol wants bob's crisps", "chips>C", CELL),
    ("Carol should get Bob's crisps, not the bottle.", "chips>C", CELL),
    ("Carol gets Bob's cup and Bob gets the crisps.", "cup>C & chips>B", CELL),
    ("Sam can borrow Priya's stapler.", "stapler>B", OFFICE),
    ("Priya needs Sam's notebook.", "notebook>A", OFFICE),
    ("Kofi can borrow Jess's hammer.", "hammer>A", WORKSHOP),
    ("Give Sam Priya's notebook, please.", "notebook>B", OFFICE),
    ("Priya would like Sam's notebok.", "notebook>A", OFFICE),
    # the owner's thing the scene does not single out (two mugs; three pens): refused
    ("Carol needs Bob's mug.", None, CELL),
    ("Sam wants Priya's pen.", None, OFFICE),
    # a state, not a want ('has'); a doer
    ("Carol likes Bob's cup.", None, CELL),
    ("Carol takes Bob's cup to the shelf.", None, CELL),
)
# the owner is the one who gets it: read as before
SAME = PhrasingCases()
test_owner_gets_it = SAME.test(
    ("Bob wants Bob's crisps.", "chips>B", CELL),
    ("Sam wants his notebook.", "notebook>B", OFFICE),
)


@pytest.mark.parametrize(("text", "want", "scene"), OWNED.read)
def test_owned_other_not_read_without(
    text: str, want: str, scene: object, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Without the rule each case reads otherwise (the owner for the one who gets it) or is
    refused."""
    monkeypatch.setattr(_rewrites43l, "owned_other43l", lambda t, lexicon: t)
    try:
        got = show_tree(parse_instruction(text, scene))  # type: ignore[arg-type]
    except GroundingError:
        return
    assert got != want
