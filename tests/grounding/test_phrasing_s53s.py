"""Session-53 phrasings of issue 12 (engineer 12s): 12c's wrong readings and blind51's sentence
splits, negation and exclusion, and typos, each as a family (fresh sentences in other scenes,
each read (wrongly) or refused on main b4e4e6fc as the test says, and near sentences);
docs/grounding.md, "Session 53 (engineer 12s)"."""

from __future__ import annotations

import pytest

from hltl.grounding import _rewrites53s as r53s
from hltl.grounding import offline
from hltl.world.scene import Scene
from tests.grounding.helpers import (
    CELL,
    DEPOT,
    KITCHEN,
    NURSERY,
    OFFICE,
    WARD,
    WORKSHOP,
    PhrasingCases,
    assert_case,
    tree,
)

# -- a he / she after a person left out by 'not' (_not_them53s, a check) ----------------------
#
# each read on main b4e4e6fc with the thing the pronoun's clause names given to the one the
# request hands to, though the pronoun may be (or can only be) the person left out (12c's fuzz,
# sessions 52 and 53)
NOT_THEM = [
    ("Give Alice the apple, not Bob, he wanted the crisps.", CELL),
    ("Give Alice the apple, not Carol, she wants the crisps.", CELL),
    ("Give Alice the cup, not Bob, he had the apple.", CELL),
    ("Give Alice the apple, not Bob. He wanted the crisps.", CELL),
    ("Give Alice the apple, not Carol, then give her the crisps.", CELL),
    ("Give Alice the apple, not Bob, the crisps are for him.", CELL),
    ("Give Alice the apple instead of Carol, she wants the crisps.", CELL),
    ("The apple to Alice, not Carol, she'd like the crisps.", CELL),
    ("Give Marco the salt, not Mr Novak, he wants the knife.", KITCHEN),
    ("Give Lena the salt, not Marco, he wanted the knife.", KITCHEN),
    ("Give Marco the salt, not Lena, she wanted the knife.", KITCHEN),
    ("Give Ava the teddy, not Lily, she wants the bib.", NURSERY),
    ("Give Mia the tape, not Tom, he wanted the scanner.", DEPOT),
    ("Give Priya the stapler, not Sam, he had the notepad.", OFFICE),
]


@pytest.mark.parametrize(("text", "scene"), NOT_THEM)
def test_not_them53s_refused(text: str, scene: Scene) -> None:
    assert_case(text, None, scene)


def test_not_them53s_is_what_refuses(monkeypatch: pytest.MonkeyPatch) -> None:
    """Without the check each is read (the thing given to the one the request hands to)."""
    kept = tuple(c for c in offline._CHECKS if c is not r53s._not_them53s)
    monkeypatch.setattr(offline, "_CHECKS", kept)
    for text, scene in NOT_THEM:
        assert tree(text, scene) is not None, text


# near sentences: the pronoun cannot be the person left out, its clause names no thing ('it'), a
# person is named instead of a pronoun, a remark before the request: read as before
test_not_them53s_near = PhrasingCases().test(
    ("Give Bob the cup, not Alice, he wants the apple.", "cup>B & apple>B", CELL),
    ("Give Lena the salt, not Marco, she wants the knife too.", "salt>B & knife>B", KITCHEN),
    ("Give Alice the apple, not Bob, he wanted it.", "apple>A", CELL),
    ("Give Alice the cup, not Bob, Carol wants the apple.", "cup>A & apple>C", CELL),
    ("Not Bob, he's on a diet for the arm wrestling; the crisps go to Alice.", "chips>A", CELL),
    ("Give Alice the cup, not the apple, she wants the crisps.", "cup>A & chips>A", CELL),
)


# -- a placing or handover said the other way round (_goes_to53s) -----------------------------
GOES_TO = PhrasingCases()
test_goes_to53s = GOES_TO.test(
    (
        "Bob gets the crisps first. Once he has them, over to Alice goes the cup.",
        "chips>B ; cup>A",
        CELL,
    ),
    ("Onto the belt goes the small box.", "box_small@conveyor", DEPOT),
    (
        "Over to Mia goes the tape, then onto the pallet go the gloves.",
        "tape>A ; gloves@pallet",
        DEPOT,
    ),
    (
        "First the pills to Mr Lee, then over to Mrs Khan goes the magazine.",
        "pills>B ; magazine>C",
        WARD,
    ),
    ("Across to Jess goes the torch.", "torch>B", WORKSHOP),
    ("Onto the shelf go the crisps and the apple.", "chips@shelf & apple@shelf", CELL),
)
test_goes_to53s_near = GOES_TO.test(
    # asked, said as done, a pronoun for the thing or the person: refused as before
    ("Over to Alice goes the cup?", None, CELL),
    ("Over to Alice goes the cup, doesn't it?", None, CELL),
    ("Over to Alice went the cup.", None, CELL),
    ("Over to Alice goes it.", None, CELL),
    ("To Alice goes the cup tomorrow.", None, CELL),
)


def test_goes_to53s_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    GOES_TO.refused_without((r53s._goes_to53s,), monkeypatch)
