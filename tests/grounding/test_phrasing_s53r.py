"""Session-53 phrasings of issue 12 (engineer 12r): blind51's choices, counts and corrections, and
12c's open wrong reading, each as a family (docs/grounding.md, "Session 53 (engineer 12r)"). Every
sentence that reads here was refused on main b4e4e6fc, and is refused with its rule taken out."""

from __future__ import annotations

import pytest

from hltl.bench.grounding import parse_expectation
from hltl.errors import GroundingError
from hltl.grounding import _rewrites53r
from hltl.grounding.lexicon import Lexicon
from hltl.world.scene import load_scene
from tests.grounding.helpers import (
    CELL,
    KITCHEN,
    NURSERY,
    ROOT,
    WARD,
    assert_case,
)

# the example scenes blind51 uses
DUO, ONE, T12, F41, F42, L44, L24, T21, SQ, FIG1, TWO = (
    load_scene(ROOT / f"examples/scenes/{n}.yaml")
    for n in (
        "2-2",
        "1-1",
        "1-2",
        "4-1",
        "4-2",
        "4-4-line",
        "2-4-line",
        "2-1",
        "4-4-square",
        "fig1",
        "two_arms",
    )
)

# -- 12c's fuzz: a share-out header the list does not meet ---------------------------------------

# _each_head53r (a check of the reading): "Give each of them (all three of them, everyone)
# something: <list>" gives one thing to each of two or more people (all of them, all three), no
# one twice; main read "…: the crisps for Alice, the apple for Alice." as chips>A & apple>A
EACH_HEAD = [
    ("Give each of them something: the crisps for Alice, the apple for Alice.", CELL),
    ("Hand each of them something: the crisps for Alice, the apple for Alice.", CELL),
    ("Give each of them a thing: Alice the crisps, Alice the apple.", CELL),
    ("Give each of them something: the crisps for Alice, the bottle for Alice.", FIG1),
    ("Give each of them something: the crisps for Alice.", CELL),
    ("Give each of them something: the crisps for Alice, the apple for her.", CELL),
    ("Give each of them something: the crisps and the apple for Alice, the red mug for Bob.", CELL),
    (
        "Give each of them something: the crisps for Alice, the apple for Alice, the cup for Bob.",
        CELL,
    ),
    ("Give all three of them an item: Alice the cup, Bob the apple.", CELL),
    ("Give all three of them an item: Alice the cup, Bob the apple, Bob the crisps.", CELL),
    ("Give all of them something: Alice the cup, Bob the apple.", CELL),
    ("Give everyone something: the crisps for Alice, the apple for Bob.", CELL),
    ("Give everybody something: the salt for Marco, the knife for Marco.", KITCHEN),
    ("Give each of them something: the jug for Mr Lee, the pills for Mr Lee.", WARD),
    ("Give each of them something: the wipes for Lily, the teddy for Lily.", NURSERY),
]


@pytest.mark.parametrize(("text", "scene"), EACH_HEAD)
def test_each_head_refused(text: str, scene) -> None:
    assert_case(text, None, scene)


@pytest.mark.parametrize(("text", "scene"), EACH_HEAD)
def test_each_head_check_is_what_refuses(text: str, scene) -> None:
    lexicon = Lexicon.of(scene)
    with pytest.raises(GroundingError):
        _rewrites53r._each_head53r(text, parse_expectation("chips>A & apple>A"), lexicon)


@pytest.mark.parametrize(
    ("text", "want"),
    [
        # the list meets the header: read as before
        (
            "Give each of them something: Alice the chips, Bob the cup, Carol the apple",
            "chips>A & cup>B & apple>C",
        ),
        (
            "Give each of them something: the crisps for Alice, the apple for Bob.",
            "chips>A & apple>B",
        ),
        (
            "Give all three of them an item: Alice the cup, Bob the apple, Carol the bottle",
            "cup>A & apple>B & bottle>C",
        ),
        (
            "Give everyone something: the crisps for Alice, the apple for Bob, the cup for Carol.",
            "chips>A & apple>B & cup>C",
        ),
    ],
)
def test_each_head_kept(text: str, want: str) -> None:
    assert_case(text, want, CELL)
