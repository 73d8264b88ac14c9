"""Session-28 phrasings of issue 12 (engineer 12r): three odd readings on main mended (an object
that 'is back', 'the crisps by Bob' in a gap, a gapped clause sending objects a second place),
then blind26's kinds; docs/grounding.md, "Session 28 (engineer 12r)". Each rule with the
sentences it changes and near forms that must still read, or stay refused."""

from __future__ import annotations

import pytest

from hltl.world.scene import Scene
from tests.grounding.helpers import CELL, DEPOT, assert_reads, assert_refused

# -- (1a) 'X is / comes / gets back', with no place after it: an outside event, never a task ------


@pytest.mark.parametrize(
    ("text", "scene"),
    [
        # each read before as the object handed over or put where the other goes
        ("Put the tape on the pallet before the small box is back.", DEPOT),
        ("Put the tape on the pallet after the small box is back.", DEPOT),
        ("Give Tom the tape before the small box is back.", DEPOT),
        ("Give Tom the tape and the small box is back.", DEPOT),
        ("Give Bob the cup once the apple is back.", CELL),
        ("Give Bob the cup once the apple's back.", CELL),
        ("Give Bob the cup after the apple's back.", CELL),
        ("Give Bob the cup once it's back.", CELL),
        ("Give Bob the cup once it gets back.", CELL),
    ],
)
def test_what_is_back_is_refused(text: str, scene: Scene) -> None:
    assert_refused(text, scene, match="is or comes back")


def test_what_is_back_where_it_belongs_is_refused() -> None:
    # main read 'the apple' handed to Bob first ("where it belongs" is taken off as said again)
    assert_refused("Give Bob the cup once the apple is back where it belongs.", CELL)


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        # 'back' with a place after it, or after a verb that moves: a filler, as before
        ("Put the small box back on the pallet.", "box_small@pallet", DEPOT),
        (
            "Put the tape on the pallet after the small box is back on the belt.",
            "box_small@conveyor ; tape@pallet",
            DEPOT,
        ),
        ("Once the apple is back on the shelf, give Bob the cup.", "apple@shelf ; cup>B", CELL),
        ("Bring the cup back to Bob.", "cup>B", CELL),
        ("Give Bob the cup back.", "cup>B", CELL),
        ("Bob wants the apple back, please.", "apple>B", CELL),
        ("Get back the cup for Bob.", "cup>B", CELL),
        # a person coming back before: acting now meets the deadline (session 27)
        ("Put the tape on the pallet before the driver's back.", "tape@pallet", DEPOT),
        ("Put the tape on the pallet before Tom is back.", "tape@pallet", DEPOT),
        ("Give Bob the cup before Alice gets back.", "cup>B", CELL),
        # said as a sentence of its own before the request: a remark, 'it' the box
        ("The small box is back. Give it to Tom.", "box_small>B", DEPOT),
    ],
)
def test_back_with_a_place_or_a_mover_still_reads(text: str, want: str, scene: Scene) -> None:
    assert_reads(text, want, scene)


# -- (1b) 'by <person>' after an object opening a clause of no verb: near, or wanted by? ---------


@pytest.mark.parametrize(
    "text",
    [
        "Carol wants the red mug, and the crisps by Bob.",
        "Carol wants the red mug and the crisps by Bob.",
        "Give Carol the red mug, and the crisps by Bob.",
        "Carol wants the red mug, then the crisps by Bob.",
    ],
)
def test_by_a_person_in_a_gap_is_refused_with_both_readings(text: str) -> None:
    assert_refused(text, CELL, match=r"next to Bob, or the crisps for Bob")


@pytest.mark.parametrize(
    ("text", "want"),
    [
        # after a verb, or with a verb or a place of its own: where the object is
        ("Give Carol the crisps by Bob.", "chips>C"),
        ("The mug by Bob goes to Carol.", "mug_blue>C"),
        # a surface, or 'next to': where the crisps lie, as before
        ("Carol wants the red mug, and the crisps by the shelf.", "mug_red>C & chips>C"),
        ("Carol wants the red mug, and the crisps next to Bob.", "mug_red>C & chips>C"),
        # the person said as the gap's recipient
        ("Carol wants the red mug, and Bob the crisps.", "mug_red>C & chips>B"),
        ("Carol wants the red mug, and the crisps for Bob.", "mug_red>C & chips>B"),
    ],
)
def test_by_after_a_verb_or_a_surface_still_reads(text: str, want: str) -> None:
    assert_reads(text, want, CELL)


# -- (1c) a gapped clause handing over what the clause before puts somewhere (or the other way) --


@pytest.mark.parametrize(
    "text",
    [
        "Put the cup and the apple on the shelf, both to Bob.",
        "Put the cup and the apple on the shelf, and both to Bob.",
        "Put the cup and the apple on the shelf. Both to Bob.",
        "Put the cup and the apple on the shelf, and the apple to Bob.",
        "Give the cup and the apple to Bob, and both on the shelf.",
    ],
)
def test_a_gap_sending_objects_a_second_place_is_refused(text: str) -> None:
    assert_refused(text, CELL, match="no verb of its own and no order")


@pytest.mark.parametrize(
    ("text", "want"),
    [
        # an order, or a verb of its own: two steps, as before
        (
            "Put the cup and the apple on the shelf, then both to Bob.",
            "(cup@shelf & apple@shelf) ; (cup>B & apple>B)",
        ),
        ("Put the cup on the shelf and give it to Bob.", "cup@shelf & cup>B"),
        # the same person or place again, other objects, a condition, a choice each
        ("Give the cup and the apple, both to Bob.", "cup>B & apple>B"),
        ("Put the cup and the apple on the shelf, both of them.", "cup@shelf & apple@shelf"),
        ("Put the cup on the shelf, and the apple to Bob.", "cup@shelf & apple>B"),
        ("Put the cup on the shelf and once it's there give Bob the apple.", "cup@shelf ; apple>B"),
        ("Give Alice and Bob a mug each.", "(mug_red>A & mug_blue>B) | (mug_blue>A & mug_red>B)"),
    ],
)
def test_a_gap_to_the_same_place_or_in_order_still_reads(text: str, want: str) -> None:
    assert_reads(text, want, CELL)
