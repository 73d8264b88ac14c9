"""Session-34 phrasings of issue 12 (engineer 12s): doubtful readings found on main by the lead's
probes — a time said after a surface that ended a 'that isn't on' rewrite, a task said with
'-ing' of a sentence about a person, a pronoun left to the one person of the scene once a
sentence naming someone else was taken off, a he / she that no person named may be — each now
a refusal naming what it did not understand or its readings; and readings the probes doubted
that stand (a repair in a question, 'needs the box loaded onto the pallet'). Each rule with the
near forms it must leave as they were (docs/grounding.md, "Session 34 (engineer 12s)")."""

from __future__ import annotations

from pathlib import Path

import pytest

from hltl.world.scene import load_scene
from tests.grounding.helpers import (
    CELL,
    DEPOT,
    KITCHEN,
    OFFICE,
    assert_reads,
    assert_refused,
)

ONE = load_scene(Path(__file__).resolve().parents[2] / "examples/scenes/1-1.yaml")

# -- a time after the surface of 'the X that isn't on S' (normalise.py _negation18) -----------


@pytest.mark.parametrize(
    "text",
    [
        # was plate_white>C: the surface's words ran on to the end and took the time with them
        "Mr Novak's getting the plate that's sitting out, not the one up in the plate rack, "
        "before I go tomorrow",
        "Give Mr Novak the plate that isn't on the rack before I go tomorrow",
    ],
)
def test_a_time_after_the_surface_puts_the_task_off(text: str) -> None:
    assert_refused(text, KITCHEN, match="'tomorrow' puts the task off")


@pytest.mark.parametrize(
    "text",
    [
        "Mr Novak's getting the plate that's sitting out, not the one up in the plate rack",
        "Mr Novak's getting the plate that's sitting out, not the one up in the plate rack, "
        "before I go",
        "Mr Novak's getting the plate that isn't on the plate rack.",
        "Give Mr Novak the plate that isn't on the rack before I go",
    ],
)
def test_the_plate_off_the_rack_is_read_without_a_time(text: str) -> None:
    assert_reads(text, "plate_white>C", KITCHEN)


# -- '-ing' after a sentence about a person (offline.py _doer_said34s) -------------------------


@pytest.mark.parametrize(
    "text",
    [
        # was apple>C ; chips>B: Bob gave the apple (a reason), the robots did not
        "Bob has earned the crisps after giving Carol the apple.",
        "Bob gets the crisps after giving Carol the apple.",
        "Bob can have the crisps after handing Carol the apple.",
        # was chips>B & apple>C
        "Bob has earned the crisps, having given Carol the apple.",
    ],
)
def test_what_the_person_does_is_no_task(text: str) -> None:
    assert_refused(text, CELL, match="is said of Bob")


@pytest.mark.parametrize(
    ("text", "want"),
    [
        # said to the robots: the robots give the apple first (blind2, blind5, heldout)
        ("Give Bob the crisps after giving Carol the apple.", "apple>C ; chips>B"),
        ("Put the apple on the shelf after giving Carol the cup", "cup>C ; apple@shelf"),
        ("Before giving Bob the chips, put the cup on the shelf", "cup@shelf ; chips>B"),
        # 'getting' is what the person receives
        ("Bob wants the crisps after getting the apple.", "apple>B ; chips>B"),
        # another person's task, said in full
        ("Alice gets the crisps after Bob gets the apple.", "apple>B ; chips>A"),
        ("Bob has earned the crisps.", "chips>B"),
    ],
)
def test_tasks_said_to_the_robots_stay(text: str, want: str) -> None:
    assert_reads(text, want, CELL)


# -- a name taken off with a sentence a pronoun may point at (offline.py _stranger_dropped34s) --


@pytest.mark.parametrize(
    "text",
    [
        # was bottle>A: 'her' may be Carol, whom the one-person scene does not hold
        "I'm Carol's plumber. Hand her the bottle.",
        "Carol is here. Hand her the bottle.",
    ],
)
def test_a_pronoun_after_a_stranger_names_them(text: str) -> None:
    assert_refused(text, ONE, match="it could mean 'Carol', whom the scene does not hold")


@pytest.mark.parametrize(
    "text",
    [
        "Hand her the bottle.",
        "Hi there! Hand her the bottle.",
        "I'm the plumber. Hand her the bottle.",
        "I'm Carol's plumber. Hand Person A the bottle.",
    ],
)
def test_a_pronoun_with_no_stranger_is_the_one_person(text: str) -> None:
    assert_reads(text, "bottle>A", ONE)


# -- a he / she no person named may be (offline.py _named_other_sex34s) ----------------------


@pytest.mark.parametrize(
    ("text", "match"),
    [
        # was bottle>A: Alice is a woman's name; 'he' is someone else
        (
            "Alice is off to work, so he is having the bottle",
            r"cannot mean Alice \(a woman's name\); it could mean Person B \(Bob\) or Person C",
        ),
        ("Alice is off to work, so give him the bottle", "cannot mean Alice"),
        ("Give Bob the cup, she's thirsty", r"cannot mean Bob \(a man's name\)"),
        ("Alice and Carol are out, so he is having the bottle", "cannot mean Alice or Carol"),
    ],
)
def test_a_pronoun_of_the_other_sex_is_refused(text: str, match: str) -> None:
    assert_refused(text, CELL, match=match)


@pytest.mark.parametrize(
    ("text", "want"),
    [
        ("Alice is off to work, so she is having the bottle", "bottle>A"),
        ("Give Bob the cup, he's thirsty", "cup>B"),
        # one person named may be it
        ("Give Alice the cup and Bob the bottle, he's thirsty", "cup>A & bottle>B"),
        # a role says no sex
        ("The intern needs the red pen, she's marking.", "pen_red>B"),
    ],
)
def test_a_pronoun_a_person_named_may_be_is_read(text: str, want: str) -> None:
    scene = OFFICE if "intern" in text else CELL
    assert_reads(text, want, scene)


# -- readings the probes doubted that stand ---------------------------------------------------


@pytest.mark.parametrize(
    ("text", "want"),
    [
        # the repair wins, asked as a question or not (Priya is Person A)
        ("The stapler is for Sam, er, I mean Priya?", "stapler>A"),
        ("The stapler is for Sam, er, I mean Priya.", "stapler>A"),
        ("The stapler is for Priya, er, I mean Sam?", "stapler>B"),
    ],
)
def test_a_repair_in_a_question_wins(text: str, want: str) -> None:
    assert_reads(text, want, OFFICE)


def test_a_question_without_a_repair_is_no_request() -> None:
    assert_refused("The stapler is for Sam?", OFFICE, match="is a question")


@pytest.mark.parametrize(
    ("text", "want"),
    [
        # 'needs the box loaded onto the pallet' asks for the box to be put there (need + object
        # + past participle: what is to be done to it), not for the box to go to Tom
        (
            "Tom needs the barcode scanner, oh, and the medium box loaded onto the pallet",
            "scanner>B & box_medium@pallet",
        ),
        ("Tom needs the medium box loaded onto the pallet", "box_medium@pallet"),
        # without the participle the box is Tom's
        ("Tom needs the barcode scanner, oh, and the medium box", "scanner>B & box_medium>B"),
        ("Tom needs the medium box", "box_medium>B"),
    ],
)
def test_needs_it_loaded_is_a_placement(text: str, want: str) -> None:
    assert_reads(text, want, DEPOT)
