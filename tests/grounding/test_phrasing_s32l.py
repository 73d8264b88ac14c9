"""Session-32 phrasing of issue 12 (lead): wrong readings 12c's 'repairs' fuzz found on main
(docs/grounding.md, "Session 32 (lead)").

- "Give Bob the water bottle, er, the cup": the lexer drops 'er' as a filler, so the two names
  were read as a list (bottle>B & cup>B). A bare hesitation between two names of one kind, with
  no list around them, is a self-repair, as 'sorry' is there (hltl.grounding.repairs); a title
  said again ("Mr, er, Mr Novak", "Person, um, Person B") is said once.
- "Give Bob the chips or the bottle, no, give it to Carol": the correction's 'it' stood for every
  object of the clause taken back (chips>C & bottle>C). 'it' after several objects, and any
  pronoun after a choice, is unclear: refused, naming the objects.
- "Not urgent: the apple and, um, the cup to Bob": 'Not urgent: the apple and' was taken as a
  thing left out, so the apple was lost. What is left out never runs across a colon.
- "Tom needs the packing tape and the medium box loaded onto the pallet": the grammar read 'needs
  the tape' and 'the box loaded onto the pallet'; the participle is said of the whole list."""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from hltl.bench.grounding import show_tree
from hltl.world.scene import load_scene
from tests.grounding.helpers import (
    CELL,
    DEPOT,
    OFFICE,
    ROOT,
    assert_reads,
    assert_refused,
    name_of,
    paraphrase_scene,
    tree,
)

FIG = load_scene(ROOT / "examples/scenes/fig1.yaml")

_FILLERS = ("er", "um", "uh", "erm")
_ONE_OF_A_KIND = ("cup", "bottle", "chips", "apple")


@given(
    st.sampled_from(_ONE_OF_A_KIND),
    st.sampled_from(_ONE_OF_A_KIND),
    st.sampled_from(_FILLERS),
    st.sampled_from(("A", "B", "C")),
)
def test_a_hesitation_between_two_objects_repairs_the_first(
    said: str, meant: str, filler: str, who: str
) -> None:
    person = name_of(CELL, who)
    text = f"Give {person} the {name_of(CELL, said)}, {filler}, the {name_of(CELL, meant)}"
    assert_reads(text, f"{meant}>{who}", CELL)


@pytest.mark.parametrize(
    ("text", "want"),
    [
        ("Give Bob the water bottle, er, the cup", "cup>B"),
        ("Give Alice, um, Bob a mug", "mug_red>B | mug_blue>B"),
        ("Put the cup on the table, er, the shelf", "cup@shelf"),
        ("Either mug for Person, er, Person B", "mug_red>B | mug_blue>B"),
        ("Give the cup to Mr, um, Mr Bob", "cup>B"),
        ("Hand the cup, um, the apple to Bob, no, to Carol", "apple>C"),
        ("Give Alice the cup. Then, give Bob the water bottle, er, the chips.", "cup>A ; chips>B"),
    ],
)
def test_a_repair_by_hesitation_keeps_the_name_said_last(text: str, want: str) -> None:
    assert_reads(text, want, CELL)


@pytest.mark.parametrize(
    ("text", "want"),
    [
        # a list goes on around the two names: the hesitation may be a pause inside it
        ("Give Bob the cup, er, the chips and the apple", "cup>B & chips>B & apple>B"),
        ("Give Bob the apple, the cup, um, the chips", "apple>B & cup>B & chips>B"),
        ("Give Alice, er, Bob or Carol the cup", "cup>A | cup>B | cup>C"),
        # a list word or a choice of its own after the hesitation
        ("Give Bob the cup, um, and the apple", "cup>B & apple>B"),
        ("Give Bob the cup, um, or the apple", "cup>B | apple>B"),
        ("Give Bob the cup and, um, the apple", "cup>B & apple>B"),
        ("Give Bob the cup or, er, the apple", "cup>B | apple>B"),
        # names of two kinds: nothing repaired
        ("Give Alice the cup, er, Bob the apple", "cup>A & apple>B"),
        ("Give Bob the cup, er, Alice, the apple", "cup>B & apple>A"),
        # the same name again, and a hesitation before no name
        ("Give Bob the cup, um, the cup", "cup>B"),
        ("Give Bob the cup, er, please", "cup>B"),
    ],
)
def test_a_hesitation_inside_a_list_or_between_kinds_repairs_nothing(text: str, want: str) -> None:
    assert_reads(text, want, CELL)


@pytest.mark.parametrize(
    "text",
    [
        "Give Bob the chips or the bottle, no, give it to Carol",
        "Put the chips and the bottle on the shelf, no, give it to Bob",
        "Put the chips or the bottle on the shelf, no, give them to Bob",
        "Put the chips or the bottle on the shelf. No, give it to Bob.",
        "Put the crisps, um, or the bottle, not sure which, on the shelf, no, give it to Bob",
    ],
)
def test_a_pronoun_after_a_correction_of_several_objects_is_unclear(text: str) -> None:
    assert_refused(text, CELL, match="could mean any of")
    got = tree(text, CELL)
    assert got is None


@pytest.mark.parametrize(
    ("text", "want"),
    [
        ("Give Bob the chips, no, give it to Carol", "chips>C"),
        ("Put the chips and the bottle on the shelf, no, give them to Bob", "chips>B & bottle>B"),
        ("Not urgent: the apple and, the cup to Bob", "apple>B & cup>B"),
        ("Not urgent: the apple and, um, the cup to Bob", "apple>B & cup>B"),
        ("Not the apple, give Bob the cup", "cup>B"),
    ],
)
def test_one_object_or_them_after_a_correction_and_a_heading_read(text: str, want: str) -> None:
    assert_reads(text, want, CELL)


def test_the_readings_of_a_repair_never_hold_the_name_taken_back() -> None:
    got = tree("Bob should get the water bottle, um, the apple", CELL)
    assert got is not None and "bottle" not in show_tree(got)


@pytest.mark.parametrize(
    ("text", "want"),
    [
        (
            "Tom needs the packing tape and the medium box loaded onto the pallet",
            "tape@pallet & box_medium@pallet",
        ),
        (
            "Tom needs the packing tape and, um, the medium box loaded onto the pallet",
            "tape@pallet & box_medium@pallet",
        ),
        ("Tom needs the medium box loaded onto the pallet", "box_medium@pallet"),
        (
            "Mia wants the gloves and the packing tape put on the pallet",
            "gloves@pallet & tape@pallet",
        ),
    ],
)
def test_a_participle_after_a_wanted_list_places_the_whole_list(text: str, want: str) -> None:
    assert_reads(text, want, DEPOT)


def test_a_statement_asked_after_a_repair_is_still_a_question() -> None:
    # the commas around a repair word end no clause: still 'The stapler is for Priya?'
    assert_refused("The stapler is for Sam, er, Priya?", OFFICE, match="is a question")
    assert_refused("The stapler is for Sam, no, Priya?", OFFICE, match="is a question")
    assert_reads("The stapler is for Sam, no, Priya", "stapler>A", OFFICE)
    # a request said with a question mark stays a request
    assert_reads("Give the stapler to Sam, sorry, Priya?", "stapler>A", OFFICE)


@pytest.mark.parametrize("repair", ["sorry", "er", "no, sorry", "I mean"])
def test_a_repair_after_both_to_a_person_names_whom_both_go_to(repair: str) -> None:
    text = f"the chips first then the bottle both to Person A, {repair}, person b"
    assert_reads(text, "chips>B ; bottle>B", FIG)
    assert_reads("the chips first then the bottle both to Person A", "chips>A ; bottle>A", FIG)


def test_the_other_one_after_a_repaired_person_is_not_read_alone() -> None:
    # 'the other one' points back into the clause the repair takes back: refused (as 'Alice
    # gets the cup and Carol, sorry, Bob gets the apple' is), never mug>B alone
    assert_refused(
        "Alice gets a mug and Carol, sorry, Bob gets the other one",
        CELL,
        match="could take back the whole clause",
    )
    # session 33 (lead): a subject repaired at once after a comma, before its verb, takes back
    # the name only (hltl.grounding.repairs.subject_repairs33l): Bob gets the other mug
    assert_reads(
        "Alice wants a mug, Carol, I mean Bob wants the other one",
        "(mug_red>A & mug_blue>B) | (mug_blue>A & mug_red>B)",
        CELL,
    )
    assert_reads(
        "Alice gets a mug and Bob gets the other one",
        "(mug_red>A & mug_blue>B) | (mug_blue>A & mug_red>B)",
        CELL,
    )


def test_no_other_way_round_after_a_repair_leaves_one_person() -> None:
    for text in (
        "Give Bob, uh, no, Alice the cup and the apple, or the other way round",
        "Give Bob, er, Alice the cup and the apple, or the other way round",
    ):
        assert_refused(text, CELL, match="swaps")
    assert_reads(
        "Give Alice the cup and Carol the apple, or the other way round",
        "(cup>A & apple>C) | (apple>A & cup>C)",
        CELL,
    )


def test_a_name_after_a_closing_sorry_is_what_it_repairs_to() -> None:
    kitchen = paraphrase_scene("kitchen")
    # 'Marco' after 'sorry' is the repair, not a word of address dropped with the apology
    assert_reads("The tongs to Lena. Correction: to Mr Novak, sorry, Marco.", "tongs>A", kitchen)
    assert_reads("The tongs to Lena. Correction: to Mr Novak, sorry, folks.", "tongs>C", kitchen)
    assert_reads("The tongs to Lena, no, to Mr Novak, my mistake, folks.", "tongs>C", kitchen)


def test_a_repaired_person_before_a_choice_of_people_gets_no_share() -> None:
    classroom = paraphrase_scene("classroom")
    text = "Either of the students can have the globe, Mrs Ortiz, sorry, Noah or Zoe"
    got = tree(text, classroom)
    assert got is None or show_tree(got) in ("globe>B | globe>C", "globe>C | globe>B")
    assert_reads(
        "Either of the students can have the globe, Noah or Zoe", "globe>B | globe>C", classroom
    )


@pytest.mark.parametrize(
    ("scene", "text", "want"),
    [
        (
            "ward",
            "Mrs Khan wants the medication, I mean the magazine and the jug placed on the bedside "
            "table",
            "magazine@bedside & jug@bedside",
        ),
        (
            "lab",
            "Dana needs the banana, sorry, the spoon, the bowl and the sponge put in the sink",
            "spoon@sink & bowl@sink & sponge@sink",
        ),
    ],
)
def test_a_repair_before_a_wanted_list_with_a_participle_places_the_list(
    scene: str, text: str, want: str
) -> None:
    assert_reads(text, want, paraphrase_scene(scene))


def test_a_repair_before_a_list_taken_to_a_person() -> None:
    text = "Bob would like the water bottle, er, I mean the cup and the apple taken to Carol"
    assert_reads(text, "cup>C & apple>C", CELL)
