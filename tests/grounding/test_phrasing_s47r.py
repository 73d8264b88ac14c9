"""Session-47 phrasings of issue 12 (engineer 12r): choices, doubts and distributions, counts and
plurals, corrections, each as a family; docs/grounding.md, "Session 47 (engineer 12r)". Each rule
with sentences of its kind in other words and scenes than blind45's (each refused on issue-lead
4ac0c655), and near forms that must stay refused."""

from __future__ import annotations

import pytest

from hltl.grounding import _rewrites47r
from hltl.world.scene import load_scene
from tests.grounding.helpers import (
    CELL,
    CLASSROOM,
    DEPOT,
    KITCHEN,
    LAB,
    NURSERY,
    OFFICE,
    ROOT,
    WARD,
    WORKSHOP,
    PhrasingCases,
    Unclear,
    unclear_tests,
)

# the example scenes blind45 uses
T11, T21, T22, T41, T42, SQ, FIG1, TWO = (
    load_scene(ROOT / f"examples/scenes/{n}.yaml")
    for n in ("1-1", "2-1", "2-2", "4-1", "4-2", "4-4-square", "fig1", "two_arms")
)

CASES = PhrasingCases()

# -- whichever, whatever, each ---------------------------------------------------------------------

test_whichever_of = CASES.test(
    # _whichever_of47r: "whichever of the X and the Y" is "one of the X and the Y"
    ("Hand Bob whichever of the cup and the apple, he's not fussy.", "cup>B | apple>B", CELL),
    ("Pass Noah whichever of the ruler or the globe.", "ruler>B | globe>B", CLASSROOM),
    ("Put whichever of the spoon and the bowl in the sink.", "spoon@sink | bowl@sink", LAB),
    (
        "Give Mrs Khan whichever of the jug and the magazine, she won't mind.",
        "jug>C | magazine>C",
        WARD,
    ),
    # a pick by a property, a thing the scene lacks, a person among the things
    ("Give Bob whichever of the cup and the apple is nearer.", None, CELL),
    ("Give Alice whichever of the cup and the pear.", None, CELL),
    ("Give Person A whichever of the apple and Person B.", None, SQ),
)

test_whatever_chooses = CASES.test(
    # _whatever_chooses47r: "Whatever P chooses out of X, Y and Z is fine, only one though"
    (
        "Whatever Bob picks out of cup, apple and chips is fine by the landlord, only one though.",
        "cup>B | apple>B | chips>B",
        CELL,
    ),
    (
        "Whichever Zoe chooses from the ruler and the globe is fine.",
        "ruler>C | globe>C",
        CLASSROOM,
    ),
    (
        "Whatever Tom goes for out of tape, gloves and scanner is fine by the gaffer, just one "
        "mind.",
        "tape>B | gloves>B | scanner>B",
        DEPOT,
    ),
    ("Whichever Person A picks out of bottle and chips is fine.", "bottle>A | chips>A", T22),
    # 'whatever' without "only one" (P may take more), a thing the scene lacks, a remark that
    # names a person
    ("Whatever Bob picks out of cup, apple and chips is fine.", None, CELL),
    ("Whichever Zoe chooses from the ruler and the pear is fine.", None, CLASSROOM),
    ("Whichever Bob picks out of cup and apple is fine by Alice.", None, CELL),
)

test_no_preference = CASES.test(
    # _no_preference47r: "she has no preference", "he'll take whatever comes first to hand"
    (
        "Mrs Khan can have either blanket, she has no preference.",
        "blanket_blue>C | blanket_grey>C",
        WARD,
    ),
    (
        "Give Tom the small box or the medium box, he'll take whatever comes first to hand.",
        "box_small>B | box_medium>B",
        DEPOT,
    ),
    (
        "Zoe can have the red book or the green book, she has no preference.",
        "book_red>C | book_green>C",
        CLASSROOM,
    ),
    ("Give Lena either plate, she's got no preference.", "plate_white>B | plate_blue>B", KITCHEN),
    # the pronoun is not the person; no choice; a placing
    ("Give Lena either plate, he has no preference.", None, KITCHEN),
    ("Give Lena the white plate, she has no preference.", None, KITCHEN),
    ("Put either plate on the rack, she has no preference.", None, KITCHEN),
)

test_each_given = CASES.test(
    # _each_given47r: "Give P and Q one each, the X to her and the Y to him"
    (
        "Give Mrs Ortiz and Noah one each, the globe to her and the ruler to him.",
        "globe>A & ruler>B",
        CLASSROOM,
    ),
    (
        "Ruth and Mr Lee get a blanket each: the grey one to him, the blue one to her.",
        "blanket_grey>B & blanket_blue>A",
        WARD,
    ),
    (
        "Hand Ava and Grandad one each, the teddy for her and the bib for him.",
        "teddy>C & bib>B",
        NURSERY,
    ),
    (
        "Zoe and Noah get a book each, the red one to him and the green one to her.",
        "book_red>B & book_green>C",
        CLASSROOM,
    ),
    # both pronouns the same person; a pronoun either may be; one thing for both
    ("Give Mrs Ortiz and Noah one each, the globe to her and the ruler to her.", None, CLASSROOM),
    # Person A 'she', Person B 'he': the corpus's convention (as session 46's rule has it)
    (
        "Give Person A and Person B one each, the bottle to her and the chips to him.",
        "bottle>A & chips>B",
        T22,
    ),
    ("Give Person A and Person B one each, the bottle to him and the chips to him.", None, T22),
    ("Zoe and Noah get a book each, the red one to him and the red one to her.", None, CLASSROOM),
)

# -- doubt: the speaker does not know which --------------------------------------------------------

UNCLEAR: list[Unclear] = [
    (
        "Carol asked for one of them, the cup or the apple, and I can't for the life of me "
        "remember which.",
        CELL,
        ("cup", "apple"),
    ),
    (
        "Mrs Ortiz wanted one of the books after assembly, and I didn't catch which.",
        CLASSROOM,
        ("book_red", "book_green"),
    ),
    (
        "Tom asked for one of the boxes, not the large one, and I honestly forget which.",
        DEPOT,
        ("box_small", "box_medium"),
    ),
    (
        "Mr Lee wants one of the blankets, he did say which one but I've gone blank.",
        WARD,
        ("blanket_blue", "blanket_grey"),
    ),
    (
        "Priya needs one of the pens, not the red, I can't for the life of me recall which.",
        OFFICE,
        ("pen_black", "pen_blue"),
    ),
]


# each refusal names its readings; without REFUSE47R none does
test_refusals_name_readings, test_refusals_are_these = unclear_tests(
    UNCLEAR, _rewrites47r.REFUSE47R
)

test_doubt_near = CASES.test(
    # what the doubt refusal leaves alone: a choice left to the robot, a want named
    ("Carol asked for one of them, the cup or the pear, and I forget which.", None, CELL),
)

# -- corrections -----------------------------------------------------------------------------------

test_fix_why_place = CASES.test(
    # session 46's _fix_why46r, the lead's session-47 decision: a place corrected away with an
    # apology and a reason said of it ("…, sorry, the sink's broken") reads the correction
    ("Sponge in the sink, no, the tray, sorry, the sink's broken.", "sponge@tray", LAB),
    ("Spoon on the tray, no, the sink, sorry, the tray's wobbly.", "spoon@sink", LAB),
    ("Put the tape on the belt, no, the pallet, sorry, the belt's stopped.", "tape@pallet", DEPOT),
    ("Drill in the locker, no, the bench, sorry, the locker's locked.", "drill@bench", WORKSHOP),
    ("Teddy on the mat, correction, the high chair, the mat's filthy.", "teddy@highchair", NURSERY),
    # the reason names the new place, or a thing, or there is no correction
    ("Sponge in the sink, no, the tray, sorry, the tray's broken.", None, LAB),
    ("Sponge in the sink, no, the tray, sorry, the bowl's broken.", None, LAB),
    ("Sponge in the sink, sorry, the sink's broken.", None, LAB),
    ("Sponge in the sink, no, the tray, sorry, the sink's where Omar wants it.", None, LAB),
)


def test_rewrites_read_them(monkeypatch: pytest.MonkeyPatch) -> None:
    """Each case that reads is read by these rules: refused without them (session 46's
    `_fix_why46r` reads the place corrected away, the lead's decision)."""
    from hltl.grounding import _rewrites46r

    CASES.refused_without(
        (*_rewrites47r._STEPS47R_FIRST, *_rewrites47r._STEPS47R, _rewrites46r._fix_why46r),
        monkeypatch,
    )
