"""Session-29 phrasing of issue 12 (lead): 'a mug, either of the two' says the same choice again
(blind27's one wrong reading; docs/grounding.md, "Session 29 (lead)")."""

from __future__ import annotations

import pytest

from hltl.bench.grounding import parse_expectation, show_tree
from hltl.errors import GroundingError
from hltl.grounding.offline import parse_instruction
from hltl.world.scene import Scene, load_scene
from tests.grounding.helpers import (
    CELL,
    KITCHEN,
    OFFICE,
    ROOT,
    WARD,
    WORKSHOP,
    assert_reads,
    assert_refused,
)

# cell: mug_red and mug_blue are the two mugs; Alice is Person A, Bob Person B.


@pytest.mark.parametrize(
    "text",
    [
        "Alice is making tea for the crofters, give her a mug, either of the two, whichever.",
        "Give Alice a mug, either of the two, whichever.",
        "Give Alice a mug, either of the two.",
        "Give Alice a mug, any of the two.",
        "Give Alice a mug, one of the two.",
        "Give Alice a mug, whichever.",
    ],
)
def test_a_choice_said_again_is_one_mug(text: str) -> None:
    assert_reads(text, "mug_red>A | mug_blue>A", CELL)


def test_across_and_it_is_a_second_choice() -> None:
    # a second clause with its own recipient: one mug each, not the same choice again
    assert_reads(
        "Give Alice a mug, and either of the two to Bob.",
        "(mug_red>A & mug_blue>B) | (mug_blue>A & mug_red>B)",
        CELL,
    )


@pytest.mark.parametrize(
    "text",
    [
        # after a definite object 'either of the two' says nothing of which two
        "Give Alice the red mug, either of the two.",
        # the count is not the mugs'
        "Give Alice a mug, either of the three.",
        # two things named before: which two is unclear
        "Give Alice a mug and the cup, either of the two.",
    ],
)
def test_other_counts_stay_refused(text: str) -> None:
    assert_refused(text, CELL)


# -- 'a mug, both of them': one, or both? ------------------------------------------------------
#
# ", both of them" after the objects it counts says them again (`_counts19`); after "a mug" with
# two mugs in the scene it had been dropped as if "a mug" had named both, and the sentence read
# one mug. It contradicts the one asked for: refused, saying so.


@pytest.mark.parametrize(
    "text",
    [
        "Give Alice a mug, both of them.",
        "Give Alice one mug, both of them.",
        "A mug to Alice, both of them, please.",
    ],
)
def test_one_of_a_kind_then_both_is_refused(text: str) -> None:
    assert_refused(text, CELL, match="one or more than one")


@pytest.mark.parametrize(
    "text",
    [
        "Give Alice the mugs, both of them.",
        "Give Alice the mugs, all of them.",
        "The red mug and the blue mug to Alice, both of them.",
    ],
)
def test_both_after_both_mugs_still_reads(text: str) -> None:
    assert_reads(text, "mug_red>A & mug_blue>A", CELL)


# -- an aside between commas stays in its sentence ---------------------------------------------
#
# `_asides` dropped the words between two commas when they named nothing of the scene; split on
# commas alone, ', the juggler. After that,' was taken for one aside, and the next sentence's
# order or correction went with it (12c's asides fuzz, session 29): "Thermometer to Ruth, the
# juggler. After that, tablets to Mr Lee." read `thermometer>A & pills>B`. A sentence at a time
# now: what ends a sentence is not inside an aside.

WARD_ORDER = "Thermometer to Ruth, the juggler. After that, tablets to Mr Lee."


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        (WARD_ORDER, "thermometer>A ; pills>B", WARD),
        (
            "Hammer to Kofi, the crofter. No, hang on, the drill to Kofi, leave the hammer "
            "where it is.",
            "drill>A",
            WORKSHOP,
        ),
        (
            "The cup goes to Bob, the baker. Before that, though, give Alice the apple.",
            "apple>A ; cup>B",
            CELL,
        ),
        (
            "Last, the stapler goes to Sam, the night porter. First, though, give Priya the "
            "notebook.",
            "notebook>A ; stapler>B",
            OFFICE,
        ),
    ],
)
def test_a_sentence_end_is_not_inside_an_aside(text: str, want: str, scene: Scene) -> None:
    # never the two requests joined without their order or correction: the reading with it, or
    # a refusal (a trade at a sentence's end is read as an aside by another rule, or refused)
    try:
        got = parse_instruction(text, scene)
    except GroundingError:
        return
    assert show_tree(got) == show_tree(parse_expectation(want)), show_tree(got)


@pytest.mark.parametrize(
    ("text", "want"),
    [
        # an aside that ends inside its sentence is still dropped
        (
            "Thermometer to Ruth, the nurse, please. After that, tablets to Mr Lee.",
            "thermometer>A ; pills>B",
        ),
        (
            "Thermometer to Ruth, who is busy. After that, tablets to Mr Lee.",
            "thermometer>A ; pills>B",
        ),
        ("Thermometer to Ruth, who is busy.", "thermometer>A"),
        ("Thermometer to Ruth. After that, tablets to Mr Lee.", "thermometer>A ; pills>B"),
    ],
)
def test_asides_inside_a_sentence_still_go(text: str, want: str) -> None:
    assert_reads(text, want, WARD)


# -- a remark ends where its sentence ends ----------------------------------------------------
#
# "morning ." is one filler that takes the full stop into its words; a remark opening the
# instruction ran on past it to the next comma, and took "Not to Marco" with it (12c's asides
# fuzz, session 29): "It's been a long morning. Not to Marco, the knife goes to Marco" read
# `knife>A`, where the sentence alone contradicts itself and is refused.


def test_a_remark_does_not_take_the_next_sentence() -> None:
    assert_refused("It's been a long morning. Not to Marco, the knife goes to Marco", KITCHEN)
    assert_refused("Not to Marco, the knife goes to Marco", KITCHEN)


@pytest.mark.parametrize(
    "text",
    [
        "It's been a long morning. The knife goes to Marco",
        "Good morning. Give Marco the knife.",
        "Morning. Give Marco the knife.",
    ],
)
def test_a_remark_before_a_request_still_goes(text: str) -> None:
    assert_reads(text, "knife>A", KITCHEN)


# -- a correction's cue between commas is not an aside -----------------------------------------
#
# `_asides` takes ', our supervisor,' after a person for who that person is; it took ', my
# mistake,' so too when a closer sent the text to the rewrites ("The chips to Person A, my
# mistake, the apple. Regards." read `chips>A & apple>A`; 12c's probe on main 235a432).

LINE = load_scene(ROOT / "examples/scenes/4-4-line.yaml")


@pytest.mark.parametrize(
    "text",
    [
        "The chips to Person A, my mistake, the apple. Regards.",
        "The chips to Person A, my bad, the apple. Regards.",
        "Bit of a rush today. The chips to Person A, my mistake, the apple.",
        "The chips to Person A, my mistake, the apple.",
    ],
)
def test_my_mistake_between_commas_corrects(text: str) -> None:
    assert_reads(text, "apple>A", LINE)


def test_a_description_between_commas_still_goes() -> None:
    assert_reads("The chips to Person A, our supervisor, please. Regards.", "chips>A", LINE)


# -- a time after a name is not a trade ---------------------------------------------------------
#
# Engineer 12's `trades29` takes 'the baker' off after a name; it took 'the baker tomorrow' off
# too, and the deferring time with it ("crisps for alice the baker tomorrow" read `chips>A`;
# the lead's fuzz, seed 53, on main 9388d05).

FIG1 = load_scene(ROOT / "examples/scenes/fig1.yaml")


@pytest.mark.parametrize(
    "text", ["crisps for alice the baker tomorrow", "Crisps for Alice the baker tomorrow."]
)
def test_a_time_after_a_trade_is_not_taken_off(text: str) -> None:
    assert_refused(text, FIG1, match="puts the task off")


def test_a_trade_alone_still_goes() -> None:
    assert_reads("Crisps for Alice the baker.", "chips>A", FIG1)
