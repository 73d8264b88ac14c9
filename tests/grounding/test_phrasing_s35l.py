"""Session-35 phrasing of issue 12 (lead): wrong readings the fuzz found (docs/grounding.md,
"Session 35 (lead)").

- 12c's counts fuzz: "Everything but both mugs to Alice." (cell) read every object, the mugs
  included, and "Put everything on the worktop except the knife and both plates" (kitchen) put
  the plates there too: 'but' before 'both' was read as 'and', and 'both' after 'and' in a list
  of objects left out ended the list. 'both' before the objects left out is skipped as a
  determiner when the name after it is two objects; another number is refused.
- The same fuzz: "Dana needs the spoon, the one bowl and the sponge put in the sink" (lab) read
  spoon>A & bowl>A & sponge@sink, and "… and the cup and the one apple go to Person A too"
  (4-4-square) gave the cup to Person B: 'the one bowl' means 'the bowl', but the 'one' was
  taken off only after the passes that read a list had stopped at it.
- The same fuzz: "Lena is taking the three plates out, so she needs both of them" (kitchen, two
  plates) read both plates for Lena: the count was in a reason clause, dropped with it. A count
  said right before a kind of the scene's objects that is more than the scene has is refused
  wherever it is said; fewer is left to the grammar ("the two boxes, the small and the medium
  one" names two of three).
- 12's frames fuzz: "We need the apple, both mugs need shifting up to the shelf, the red and the
  blue alike." (cell) read the apple onto the shelf: 'both mugs' named as 'the red mug and the
  blue mug' joined the list before the comma. Opening a clause of its own (a verb after it), it
  opens a sentence now, and "We need the apple" is refused as before (the speaker).
- 12r's fuzz: "Tom wants to move the large box, can he have the gloves? Also, give Tom the
  packing tape or the barcode scanner, it's up to you which." (depot) read the large box into the
  choice: the plan's object stood for an 'it' anywhere after it, here the subject of "it's up to
  you". Only an object 'it' of the request's own sentence is the plan's object now.
- blind34's one wrong reading at its measurement: "The stapler goes to Priya, and she should get
  the notebook after it." (office) read notebook>A ; stapler>A. 'after it' closing the last
  clause was read as a condition put before everything. Its 'it' is the one object said before
  that clause and not in it, and the clause comes after that one, as with 'after that'; any
  other 'after it' there is refused."""

from __future__ import annotations

import pytest

from hltl.world.scene import Scene, load_scene
from tests.grounding.helpers import (
    CELL,
    DEPOT,
    KITCHEN,
    LAB,
    NURSERY,
    OFFICE,
    ROOT,
    assert_reads,
    assert_refused,
)

SQ = load_scene(ROOT / "examples/scenes/4-4-square.yaml")

_NO_MUGS = "cup>A & bottle>A & chips>A & apple>A"


@pytest.mark.parametrize(
    "text",
    [
        "Everything but both mugs to Alice.",
        "Give Alice everything but both mugs.",
        "Give Alice everything but both the mugs.",
        "Give Alice everything but both of the mugs.",
        "Give Alice everything except both mugs.",
        "Give Alice everything but the mugs.",
        "Give Alice everything but the two mugs.",
    ],
)
def test_both_in_what_is_left_out_is_left_out(text: str) -> None:
    assert_reads(text, _NO_MUGS, CELL)


@pytest.mark.parametrize(
    ("text", "want"),
    [
        (
            "Put everything on the worktop except the knife and both plates",
            "lemon@counter & salt@counter & tongs@counter",
        ),
        (
            "Put everything on the worktop except both plates and the knife",
            "lemon@counter & salt@counter & tongs@counter",
        ),
        ("Give Lena everything but the knife and both plates.", "lemon>B & salt>B & tongs>B"),
    ],
)
def test_both_after_and_in_what_is_left_out_is_left_out(text: str, want: str) -> None:
    assert_reads(text, want, KITCHEN)


def test_both_in_a_list_of_objects_left_out_keeps_the_rest() -> None:
    assert_reads(
        "Put everything but both mugs and the cup on the table",
        "bottle@table & chips@table & apple@table",
        CELL,
    )
    assert_reads(
        "Give Omar everything but both cups and the sponge", "spoon>B & banana>B & bowl>B", LAB
    )


@pytest.mark.parametrize(
    ("text", "scene"),
    [
        ("Give Mia everything but both boxes.", DEPOT),  # three boxes
        ("Give Mia everything except the tape and both boxes.", DEPOT),
        ("Give Alice everything but both cups.", CELL),  # one cup
    ],
)
def test_both_that_the_scene_does_not_count_is_refused(text: str, scene: Scene) -> None:
    assert_refused(text, scene, match="both")


def test_the_one_object_in_a_list_is_that_object() -> None:
    assert_reads(
        "Dana needs the spoon, the one bowl and the sponge put in the sink",
        "spoon@sink & bowl@sink & sponge@sink",
        LAB,
    )
    assert_reads(
        "The bottle goes to Person A and the chips go to Person B and the cup and the one apple "
        "go to Person A too",
        "bottle>A & chips>B & cup>A & apple>A",
        SQ,
    )


@pytest.mark.parametrize(
    "text",
    [
        "Give Alice the cup and the one mug.",  # two mugs: which?
        "The cup and the one mug go to Alice.",
        "Give Alice just the one mug.",
    ],
)
def test_the_one_of_two_stays_refused(text: str) -> None:
    assert_refused(text, CELL, match="ambiguous")


def test_the_one_and_the_other_keep_their_choice() -> None:
    assert_reads(
        "Give Alice the one mug and Bob the other.",
        "(mug_red>A & mug_blue>B) | (mug_blue>A & mug_red>B)",
        CELL,
    )


@pytest.mark.parametrize(
    ("text", "scene"),
    [
        ("Lena is taking the three plates out, so she needs both of them", KITCHEN),
        ("Lena is taking all three plates out, so she needs both of them", KITCHEN),
        ("Lena's stacking 3 plates, give her the tongs.", KITCHEN),
        ("The two cups are dirty, so give Alice the bottle.", CELL),  # one cup
    ],
)
def test_a_count_the_scene_does_not_have_is_refused_wherever_said(text: str, scene: Scene) -> None:
    assert_refused(text, scene, match="the scene has")


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        (
            "Lena is taking the two plates out, so she needs both of them",
            "plate_white>B & plate_blue>B",
            KITCHEN,
        ),
        (
            "Put all 3 boxes on the conveyor.",
            "box_small@conveyor & box_medium@conveyor & box_large@conveyor",
            DEPOT,
        ),
        ("Give Mia one of the three boxes.", "box_small>A | box_medium>A | box_large>A", DEPOT),
        ("Give Alice one of the two mugs.", "mug_red>A | mug_blue>A", CELL),
        (
            "Give Mia the two boxes, the small and the medium one.",
            "box_small>A & box_medium>A",
            DEPOT,
        ),
        ("Both mugs go to Bob.", "mug_red>B & mug_blue>B", CELL),
    ],
)
def test_a_count_the_scene_has_is_read(text: str, want: str, scene: Scene) -> None:
    assert_reads(text, want, scene)


@pytest.mark.parametrize(
    "text",
    [
        "We need the apple, both mugs need shifting up to the shelf, the red and the blue alike.",
        "We need the apple, both mugs need shifting up to the shelf.",
    ],
)
def test_both_opening_a_clause_does_not_join_the_list_before(text: str) -> None:
    assert_refused(text, CELL, match="speaker")


@pytest.mark.parametrize(
    ("text", "want"),
    [
        ("Give Alice the cup, both mugs go to Bob.", "cup>A & mug_red>B & mug_blue>B"),
        (
            "Alice gets the cup, both mugs go on the shelf.",
            "cup>A & mug_red@shelf & mug_blue@shelf",
        ),
        (
            "Give Alice the cup, both mugs and the apple.",
            "cup>A & mug_red>A & mug_blue>A & apple>A",
        ),
        ("Give Alice the apple, both mugs are for Bob.", "apple>A & mug_red>B & mug_blue>B"),
    ],
)
def test_both_after_a_comma_keeps_its_clause(text: str, want: str) -> None:
    assert_reads(text, want, CELL)


def test_a_plans_object_is_not_the_it_of_a_later_remark() -> None:
    assert_refused(
        "Tom wants to move the large box, can he have the gloves? Also, give Tom the packing "
        "tape or the barcode scanner, it's up to you which.",
        DEPOT,
    )
    assert_reads("Tom wants to move the large box, can he have it?", "box_large>B", DEPOT)
    assert_reads(
        "Ava wants to build a tower, can she have the blocks?",
        "block_red>C & block_green>C",
        NURSERY,
    )


OFFICE_STAPLER_FIRST = "stapler>A ; notebook>A"


@pytest.mark.parametrize(
    "text",
    [
        "The stapler goes to Priya, and she should get the notebook after it.",
        "Give Priya the stapler, and she should get the notebook after it.",
        "The stapler goes to Priya, and the notebook goes to her after it.",
        "Give Priya the stapler and the notebook after it.",
        "The stapler goes to Priya, and she should get the notebook after that.",
    ],
)
def test_after_it_closing_a_clause_follows_the_object_before(text: str) -> None:
    assert_reads(text, OFFICE_STAPLER_FIRST, OFFICE)


@pytest.mark.parametrize(
    "text",
    [
        "Give Priya the notebook after it.",  # nothing before it
        "Give Priya the stapler and the notebook, and Sam the black pen after it.",  # two before
    ],
)
def test_after_it_with_no_one_object_before_is_refused(text: str) -> None:
    assert_refused(text, OFFICE, match="after it")
