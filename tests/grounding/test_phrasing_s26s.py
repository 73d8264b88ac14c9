"""Session-26 phrasings of issue 12 (engineer 12s): choices, free splits, exclusivity said around
a request — each rule with the near forms it must read and the near forms it must refuse
(docs/grounding.md, "Session 26 (engineer 12s)")."""

from __future__ import annotations

import pytest

from hltl.world.scene import Scene, load_scene
from tests.grounding.helpers import CELL, DEPOT, KITCHEN, ROOT, assert_reads, assert_refused

FOUR = load_scene(ROOT / "examples/scenes/4-2.yaml")  # bottle, chips, cup, apple; Person A, B

# -- who gets which left free after a split ('each', 'apiece', 'one … the other') -------------


@pytest.mark.parametrize(
    ("text", "want"),
    [
        (
            "Alice and Bob, a mug each, any way round.",
            "(mug_red>A & mug_blue>B) | (mug_blue>A & mug_red>B)",
        ),
        (
            "Alice and Bob, a mug each, either way round you like.",
            "(mug_red>A & mug_blue>B) | (mug_blue>A & mug_red>B)",
        ),
        (
            "Give one mug to Alice and the other to Carol, any which way.",
            "(mug_red>A & mug_blue>C) | (mug_blue>A & mug_red>C)",
        ),
        (
            "Alice and Bob, one each, the cup and the apple, I don't mind who gets what.",
            "(cup>A & apple>B) | (apple>A & cup>B)",
        ),
        (
            "Give Alice and Bob one thing each, the cup and the apple, any way round.",
            "(cup>A & apple>B) | (apple>A & cup>B)",
        ),
        (
            "Alice and Bob are to have one mug apiece, red or blue, makes no odds who gets which.",
            "(mug_red>A & mug_blue>B) | (mug_blue>A & mug_red>B)",
        ),
        (
            "Alice and Bob, a mug each, red or blue.",
            "(mug_red>A & mug_blue>B) | (mug_blue>A & mug_red>B)",
        ),
    ],
)
def test_a_free_split_reads_as_the_choice(text: str, want: str) -> None:
    assert_reads(text, want, CELL)


@pytest.mark.parametrize(
    "text",
    [
        # two objects listed with 'and' and no word that any way will do: the order said could
        # be meant (engineer 12's call, session 26)
        "Alice and Bob can have one each, the cup and the apple.",
        # the objects listed are not two different objects, or not two
        "Alice and Bob, one each, the cup and the cup.",
        "Alice and Carol, one each, the cup and the apple and the chips.",
        # a surface is not a person who gets one
        "Alice and the shelf, one each, the cup and the apple.",
        # 'red or green' does not name two mugs; 'thing' names no kind to tell apart
        "Alice and Bob are to have one mug apiece, red or green.",
        "Alice and Bob are to have one thing apiece, red or blue.",
    ],
)
def test_a_split_not_said_as_one_is_refused(text: str) -> None:
    assert_refused(text, CELL)


def test_plates_apiece_by_colour_in_the_kitchen() -> None:
    assert_reads(
        "Lena and Mr Novak are to have one plate apiece, white or blue.",
        "(plate_white>B & plate_blue>C) | (plate_blue>B & plate_white>C)",
        KITCHEN,
    )


# -- indifference after a choice ('she does not care', "he's not fussed which") ---------------


@pytest.mark.parametrize(
    ("text", "want"),
    [
        # (session 34: 'he' for Bob; 'she' after a man's first name is someone else, refused)
        ("Give one of the cup or the apple to Bob, any, he does not care.", "cup>B | apple>B"),
        ("Give Bob the cup or the apple, he's not fussed which.", "cup>B | apple>B"),
        ("Give Bob the cup or the apple, it's all the same to him.", "cup>B | apple>B"),
        ("Give Bob the cup or the apple, makes no odds.", "cup>B | apple>B"),
    ],
)
def test_indifference_after_a_choice_reads(text: str, want: str) -> None:
    assert_reads(text, want, CELL)


@pytest.mark.parametrize(
    "text",
    [
        # no choice before it: the remark is not about which one, so it is not taken off
        "Give Bob the cup, he's not fussed which.",
        "Give Bob the cup and the apple, he does not care.",
    ],
)
def test_indifference_without_a_choice_is_refused(text: str) -> None:
    assert_refused(text, CELL)


# -- 'one of them' with the people named beside it -----------------------------------------------


@pytest.mark.parametrize(
    ("text", "want"),
    [
        ("Give the cup to one of them, Alice or Bob, it doesn't matter which.", "cup>A | cup>B"),
        ("Alice or Bob, whoever, give one of them the cup.", "cup>A | cup>B"),
    ],
)
def test_one_of_them_named_reads(text: str, want: str) -> None:
    assert_reads(text, want, CELL)


@pytest.mark.parametrize(
    "text",
    [
        "Give the cup to one of them, Alice or the apple.",  # an object is not one of 'them'
        "Give the cup to one of them.",  # nobody named
        "Alice or the apple, whoever, give one of them the cup.",
        # the grammar reads 'Give the cup and the apple to Alice or Bob' as '(cup>A & apple>A)
        # | apple>B': not a choice between the two people, so not taken
        "Give the cup and the apple to one of them, Alice or Bob.",
    ],
)
def test_one_of_them_not_named_is_refused(text: str) -> None:
    assert_refused(text, CELL)


# -- a choice opener, then its objects listed with 'or' ------------------------------------------


@pytest.mark.parametrize(
    ("text", "want"),
    [
        ("One of the two, the cup or the apple, to Bob.", "cup>B | apple>B"),
        ("Any of the fruit to Bob, the apple or the chips.", "apple>B | chips>B"),
        ("Either thing will do for Bob, cup or apple.", "cup>B | apple>B"),
    ],
)
def test_a_choice_listed_after_its_opener_reads(text: str, want: str) -> None:
    assert_reads(text, want, CELL)


@pytest.mark.parametrize(
    "text",
    [
        "One of the three, the cup or the apple, to Bob.",  # 'the three' does not count two
        "Either thing will do for Bob, cup and apple.",  # 'and' lists no choice
        "Any of them, the cup or Carol, to Bob.",  # a person is no object to choose
    ],
)
def test_a_choice_not_listed_as_one_is_refused(text: str) -> None:
    assert_refused(text, CELL)


# -- 'and nobody else' beside one person -------------------------------------------------------


@pytest.mark.parametrize(
    ("text", "want"),
    [
        ("Alice, and nobody else mind, gets the cup.", "cup>A"),
        ("Alice, and nobody else, gets the cup and the apple.", "cup>A & apple>A"),
        ("Give the cup to Alice and no one else.", "cup>A"),
        ("Not to anyone else, just Alice: the cup.", "cup>A"),
        ("Give the cup to Alice, nobody else is here.", "cup>A"),
    ],
)
def test_nobody_else_beside_one_person_reads(text: str, want: str) -> None:
    assert_reads(text, want, CELL)


@pytest.mark.parametrize(
    "text",
    [
        "Give the cup to Alice and Bob, nobody else.",  # two people: not one alone
        "Give the cup to Alice and the apple to Bob, and nobody else.",
        "Nobody else gets the cup.",  # nobody named
        "Give Carol the cup, and nobody else the apple.",  # 'nobody else' gets something
        "Put the cup on the shelf and nobody else.",  # no person at all
    ],
)
def test_nobody_else_otherwise_is_refused(text: str) -> None:
    assert_refused(text, CELL)


# -- exclusions said another way ----------------------------------------------------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        (
            "Everything on there bar the bottle goes to Bob.",
            "cup>B & chips>B & apple>B & mug_red>B & mug_blue>B",
            CELL,
        ),
        (
            "Everything you've got there except the bottle goes to Bob.",
            "cup>B & chips>B & apple>B & mug_red>B & mug_blue>B",
            CELL,
        ),
        (
            "Clear the lot onto the shelf except for the two mugs.",
            "cup@shelf & bottle@shelf & chips@shelf & apple@shelf",
            CELL,
        ),
        ("Bob gets everything that isn't a mug.", "cup>B & bottle>B & chips>B & apple>B", CELL),
        ("Tom gets everything that isn't a box.", "scanner>B & tape>B & gloves>B", DEPOT),
        (
            "Everything except the cup goes to Bob, the cup stays.",
            "bottle>B & chips>B & apple>B & mug_red>B & mug_blue>B",
            CELL,
        ),
        ("The bottle to Alice, but not the chips, leave those.", "bottle>A", CELL),
        (
            "Person A gets three of the four, the cup, the apple and the chips, and the bottle "
            "stays put.",
            "cup>A & apple>A & chips>A",
            FOUR,
        ),
    ],
)
def test_an_exclusion_said_another_way_reads(text: str, want: str, scene: Scene) -> None:
    assert_reads(text, want, scene)


@pytest.mark.parametrize(
    ("text", "scene"),
    [
        ("Bob gets everything that isn't a spoon.", CELL),  # no spoon here
        ("Tom gets everything that isn't a boxes.", DEPOT),
        # the apple is not left out: it stays AND goes with everything (was read on main)
        ("Everything except the cup goes to Bob, the apple stays.", CELL),
        ("Give Alice the bottle, leave those.", CELL),  # nothing left out before 'those'
        # the count is not the list's, or 'the four' is not the scene's objects
        ("Person A gets two of the four, the cup, the apple and the chips.", FOUR),
        ("Person A gets three of the five, the cup, the apple and the chips.", FOUR),
    ],
)
def test_an_exclusion_not_said_as_one_is_refused(text: str, scene: Scene) -> None:
    assert_refused(text, scene)


# -- the words telling every object of the chosen kind apart, said after the choice -------------


@pytest.mark.parametrize(
    ("text", "want"),
    [
        (
            "Give Alice one of the mugs, red or blue, it's all the same to her.",
            "mug_red>A | mug_blue>A",
        ),
        (
            "Give Alice one of the mugs, red or blue, and the apple to Bob.",
            "(mug_red>A | mug_blue>A) & apple>B",
        ),
    ],
)
def test_a_choice_told_apart_again_reads(text: str, want: str) -> None:
    assert_reads(text, want, CELL)


@pytest.mark.parametrize(
    "text",
    [
        "Give Alice one of the mugs, red or green.",  # no green mug
        "Give Alice one of the mugs, red or red.",  # one mug twice
        "Give Alice the cup, red or blue.",  # no choice of a kind before it
    ],
)
def test_a_choice_not_told_apart_is_refused(text: str) -> None:
    assert_refused(text, CELL)
