"""Session-29 phrasings of issue 12 (engineer 12): the wrong readings the tails fuzz found on main
(an 'X first' dropped when another sentence follows, a 'before that' kept after 'last', a remark
that joined two sentences), and blind27's refusals by kind (docs/grounding.md, "Session 29
(engineer 12)")."""

from __future__ import annotations

import pytest

from hltl.world.scene import Scene
from tests.grounding.helpers import (
    CELL,
    DEPOT,
    KITCHEN,
    LAB,
    WARD,
    assert_reads,
    assert_refused,
)

# -- (a) 'X first' before another sentence ---------------------------------------------------
#
# "Give Lena the knife and the lemon, the lemon first. Also, give Mr Novak the salt shaker." had
# read knife>B & lemon>B & salt>C: the 'first' was taken only at the end of the whole instruction
# and dropped anywhere else (12c's tails fuzz, session 28).

KNIFE_LEMON = "Give Lena the knife and the lemon, the lemon first"
TAILS = [
    ". Also, give Mr Novak the salt shaker.",
    ". Give Mr Novak the salt shaker.",
    ". Mr Novak gets the salt shaker too.",
    ", and give Mr Novak the salt shaker.",
    ". And the salt shaker to Mr Novak as well.",
]


@pytest.mark.parametrize("tail", TAILS)
def test_an_order_of_one_sentence_is_kept_beside_the_next(tail: str) -> None:
    assert_reads(KNIFE_LEMON + tail, "(lemon>B ; knife>B) & salt>C", KITCHEN)


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        (KNIFE_LEMON + ".", "lemon>B ; knife>B", KITCHEN),
        (KNIFE_LEMON + ", thanks.", "lemon>B ; knife>B", KITCHEN),
        # an order word after it orders the next part after the whole sentence
        (
            KNIFE_LEMON + ". Then give Mr Novak the salt shaker.",
            "lemon>B ; knife>B ; salt>C",
            KITCHEN,
        ),
        (
            KNIFE_LEMON + ", then give Mr Novak the salt shaker.",
            "lemon>B ; knife>B ; salt>C",
            KITCHEN,
        ),
        (
            KNIFE_LEMON + ". Before that, give Mr Novak the salt shaker.",
            "salt>C ; lemon>B ; knife>B",
            KITCHEN,
        ),
        (
            "Marco would like both plates, the white one first. Also, give Mr Novak the tongs.",
            "(plate_white>A ; plate_blue>A) & tongs>C",
            KITCHEN,
        ),
        (
            "Put both cups in the sink, the green one first. Emma gets the bowl too.",
            "(cup_green@sink ; cup_white@sink) & bowl>C",
            LAB,
        ),
        (
            "Give the visitor the bowl and the spoon, bowl first. Emma gets the sponge too.",
            "(bowl>C ; spoon>C) & sponge>C",
            LAB,
        ),
        (
            "All three boxes onto the belt, the large one first. Also, give Mia the barcode "
            "scanner.",
            "(box_large@conveyor ; (box_small@conveyor & box_medium@conveyor)) & scanner>A",
            DEPOT,
        ),
        # a person first, as a sentence of its own: the tasks said before it
        (
            "Give Alice the cup and Bob the apple. Bob first, please. Alice gets the water bottle "
            "too.",
            "(apple>B ; cup>A) & bottle>A",
            CELL,
        ),
        ("Give Alice the cup and Bob the apple. Bob first, please.", "apple>B ; cup>A", CELL),
        # 'first' ending a sentence with nothing to order inside it: before the other sentences
        (
            "Give Lena the knife and the lemon first. Also, give Mr Novak the salt shaker.",
            "(knife>B & lemon>B) ; salt>C",
            KITCHEN,
        ),
        ("Give Mr Novak the salt shaker. Lena needs the knife first.", "knife>B ; salt>C", KITCHEN),
        ("Give Lena the knife and the lemon first.", "knife>B & lemon>B", KITCHEN),
    ],
)
def test_first_near_sentences_read(text: str, want: str, scene: Scene) -> None:
    assert_reads(text, want, scene)


@pytest.mark.parametrize(
    "text",
    [
        # every task of the sentence names it: first of what?
        "Give Lena the lemon, the lemon first. Also give Marco the knife.",
        "Give Lena the knife and the lemon, Lena first. Also, give Mr Novak the salt shaker.",
        # a choice cannot be put in order
        "Give Lena the knife or the lemon, the lemon first. Also, give Mr Novak the salt shaker.",
        # in the middle: before the sentences before it or after it?
        "Give Mr Novak the salt shaker. Lena needs the knife first. Marco gets the lemon.",
        # said first, and a later sentence before it
        "Lena needs the knife first. Before that, give Mr Novak the salt shaker.",
    ],
)
def test_first_near_sentences_refused(text: str) -> None:
    assert_refused(text, KITCHEN)


# -- (b) 'X last, and Y before that. Also, …' --------------------------------------------------
#
# blind4's "Give Carol the cup last, and Bob the apple and Alice the chips before that. Also, give
# Carol the water bottle." had read ((chips>A ; apple>B) & bottle>C) ; cup>C: 'last' takes off a
# 'before that' ending the instruction (it has put the rest first already), but not one ending
# its own sentence with more after it, which then ordered the chips before the apple.


@pytest.mark.parametrize(
    ("tail", "want"),
    [
        ("", "(apple>B & chips>A) ; cup>C"),
        (" Also, give Carol the water bottle.", "(apple>B & chips>A & bottle>C) ; cup>C"),
        (", thanks. Also, give Carol the water bottle.", "(apple>B & chips>A & bottle>C) ; cup>C"),
    ],
)
def test_before_that_after_last_orders_nothing_more(tail: str, want: str) -> None:
    text = "Give Carol the cup last, and Bob the apple and Alice the chips before that."
    assert_reads(text[:-1] + tail if tail.startswith(",") else text + tail, want)


# -- (c) a remark ending a sentence -----------------------------------------------------------
#
# blind26: "Mr Lee wants the thermometer. The blue blanket as well, he's freezing. And the water
# jug to Ruth as well." had given the blue blanket to Ruth: the remark "he's freezing" was taken
# off with the full stop after it, and the two sentences read as one ('the blanket and the jug to
# Ruth').


@pytest.mark.parametrize(
    ("tail", "want"),
    [
        ("", "thermometer>B & blanket_blue>B"),
        (" And the water jug to Ruth as well.", "thermometer>B & blanket_blue>B & jug>A"),
        (" Give Ruth the water jug.", "thermometer>B & blanket_blue>B & jug>A"),
    ],
)
def test_a_remark_ending_a_sentence_keeps_its_full_stop(tail: str, want: str) -> None:
    text = "Mr Lee wants the thermometer. The blue blanket as well, he's freezing." + tail
    assert_reads(text, want, WARD)


def test_a_remark_between_commas_still_goes() -> None:
    # the remark ends at a comma: no sentence is joined to another
    assert_reads("The magazine, Mrs Khan asked it, please bring to her", "magazine>C", WARD)
