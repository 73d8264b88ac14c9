"""Session-52 phrasings of issue 12 (engineer 12s): 12c's wrong readings and blind50's sentence
splits, negation and exclusion, and typos, each as a family (fresh sentences in other scenes,
each read (wrongly) or refused on main 41c5ab87 as the test says, and near sentences);
docs/grounding.md, "Session 52 (engineer 12s)"."""

from __future__ import annotations

import pytest

from hltl.grounding import _rewrites52s as r52s
from hltl.grounding import offline
from hltl.world.scene import Scene
from tests.grounding.helpers import (
    CELL,
    CLASSROOM,
    DEPOT,
    KITCHEN,
    WARD,
    PhrasingCases,
    assert_case,
    tree,
)

# -- a thing a he / she wants given to the other sex (_she_wants_other52s, a check) -----------
#
# each read on main 41c5ab87 with the thing given to the person the request hands to, whom the
# pronoun cannot mean (12c's fuzz, session 51: "Give Alice the cup, not Bob, he wants the apple."
# -> cup>A & apple>A)
SHE_WANTS = [
    ("Give Alice the cup, not Bob, he wants the apple.", CELL),
    ("Give Bob the cup, not Alice, she wants the apple.", CELL),
    ("Give Lena the salt, not Marco, he wants the knife.", KITCHEN),
    ("Give Mia the tape, not Tom, he wants the scanner.", DEPOT),
    ("Give Zoe the globe, not Noah, he wants the ruler.", CLASSROOM),
    ("Hand Marco the tongs, not Lena, she gets the lemon.", KITCHEN),
    # a reported want: 'she' is not Bob (read apple>B on main)
    ("Give Alice the cup; Bob says she wants the apple too.", CELL),
]


@pytest.mark.parametrize(("text", "scene"), SHE_WANTS)
def test_she_wants_other52s_refused(text: str, scene: Scene) -> None:
    assert_case(text, None, scene)


def test_she_wants_other52s_is_what_refuses(monkeypatch: pytest.MonkeyPatch) -> None:
    """Without the check each is read (the thing given to the one the request hands to)."""
    kept = tuple(c for c in offline._CHECKS if c is not r52s._she_wants_other52s)
    monkeypatch.setattr(offline, "_CHECKS", kept)
    for text, scene in SHE_WANTS:
        assert tree(text, scene) is not None, text


# near sentences: the pronoun may be the one who gets it, a thing left to 'it', another person
# named, a remark before a request that names its own person (blind36 #121): read as before
test_she_wants_other52s_near = PhrasingCases().test(
    ("Give Alice the cup, not Bob, he wants it.", "cup>A", CELL),
    ("Give Alice the cup, not Bob, Carol wants the apple.", "cup>A & apple>C", CELL),
    ("Not Bob, he's on a diet for the arm wrestling; the crisps go to Alice.", "chips>A", CELL),
    ("Give Bob the apple, he wants the apple.", "apple>B", CELL),
    ("Give Lena the salt, not Marco, she wants the knife too.", "salt>B & knife>B", KITCHEN),
    ("Alice wants the cup and she needs the apple.", "cup>A & apple>A", CELL),
    ("Mr Lee wants the jug, he's after the magazine too.", "jug>B & magazine>B", WARD),
)
