"""Session-28 phrasings of issue 12 (engineer 12r): three odd readings on main mended (an object
that 'is back', 'the crisps by Bob' in a gap, a gapped clause sending objects a second place),
then blind26's kinds; docs/grounding.md, "Session 28 (engineer 12r)". Each rule with the
sentences it changes and near forms that must still read, or stay refused."""

from __future__ import annotations

import pytest

from hltl.world.scene import Scene
from tests.grounding.helpers import (
    CELL,
    CLASSROOM,
    DEPOT,
    KITCHEN,
    LAB,
    NURSERY,
    OFFICE,
    WARD,
    WORKSHOP,
    assert_reads,
    assert_refused,
)

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


# -- (2a) corrections: a reason between the cue and the corrected words; ', not X, Y' -------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        ("Chips to Alice, scratch that, she's fasting, chips to Bob.", "chips>B", CELL),
        ("Give the bottle to Bob, no wait, Bob's got one, to Alice.", "bottle>A", CELL),
        (
            "Put the apple on the shelf, sorry, my head's in the ropewalk, I mean the counter.",
            "apple@table",
            CELL,
        ),
        ("Torch to Kofi, not Kofi, Jess.", "torch>B", WORKSHOP),
        ("Torch to Kofi, not Kofi, to Jess, she's going under the van.", "torch>B", WORKSHOP),
        ("Put the torch on the bench, not the bench, the locker.", "torch@locker", WORKSHOP),
    ],
)
def test_a_reason_or_a_not_inside_a_correction_reads(text: str, want: str, scene: Scene) -> None:
    assert_reads(text, want, scene)


@pytest.mark.parametrize(
    ("text", "scene"),
    [
        # the reason gives the person a pronoun after it stands for
        ("Give the bottle to Bob, no wait, there's only Alice here, to her then.", CELL),
        # negated, naming an object, adding ('too'), or wanting: not a bare reason
        ("Give the bottle to Bob, no wait, Bob isn't thirsty, to Alice.", CELL),
        ("Give the bottle to Bob, no wait, Bob's got the cup, to Alice.", CELL),
        ("Give the bottle to Bob, no wait, Bob wants the cup, to Alice.", CELL),
        ("Put the apple on the shelf, sorry, it's too high, I mean the counter.", CELL),
        # 'not X' that is not the name just said, or more than a name after it
        ("Torch to Kofi, not Kofi, Jess too.", WORKSHOP),
        ("Torch to Kofi, not Kofi, the drill.", WORKSHOP),
    ],
)
def test_near_forms_of_a_reason_in_a_correction_stay_refused(text: str, scene: Scene) -> None:
    assert_refused(text, scene)


# -- (2b) exclusions: 'whatever isn't X', 'Apart from X, all of it …', '…, which P gets' ----------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        (
            "Bob gets whatever isn't the crisps.",
            "cup>B & bottle>B & apple>B & mug_red>B & mug_blue>B",
            CELL,
        ),
        ("Give Bob whatever isn't the mugs.", "cup>B & bottle>B & chips>B & apple>B", CELL),
        (
            "Everything that isn't the apple goes on the shelf.",
            "cup@shelf & bottle@shelf & chips@shelf & mug_red@shelf & mug_blue@shelf",
            CELL,
        ),
        (
            "Apart from the mugs, all of it goes onto the table.",
            "cup@table & bottle@table & chips@table & apple@table",
            CELL,
        ),
        (
            "Everything except the tape, all five bits, over to Tom for the cashier's tally.",
            "box_small>B & scanner>B & box_medium>B & gloves>B & box_large>B",
            DEPOT,
        ),
        (
            "Everything to Mia, apart from the tape, which Tom gets.",
            "box_small>A & scanner>A & box_medium>A & gloves>A & box_large>A & tape>B",
            DEPOT,
        ),
    ],
)
def test_exclusions_said_another_way_read(text: str, want: str, scene: Scene) -> None:
    assert_reads(text, want, scene)


@pytest.mark.parametrize(
    ("text", "scene"),
    [
        # a place, a property or a person is no object left out
        ("Bob gets whatever isn't on the shelf.", CELL),
        ("Bob gets whatever isn't red.", CELL),
        ("Bob gets whatever isn't Alice.", CELL),
        # no word for everything after the fronted exclusion, or two
        ("Apart from the mugs, the cup goes on the table.", CELL),
        ("Apart from the mugs, everything and all of it goes onto the table.", CELL),
        # a count that is not what is left; a purpose naming someone of the scene
        ("Everything except the tape, all four bits, over to Tom.", DEPOT),
        ("Give Tom the tape for the driver's tally.", DEPOT),
        # 'which' with an object or two people
        ("Everything to Mia, apart from the tape, which the scanner gets.", DEPOT),
        ("Everything to Mia, apart from the tape, which Tom and Mia get.", DEPOT),
    ],
)
def test_near_forms_of_the_exclusions_stay_refused(text: str, scene: Scene) -> None:
    assert_refused(text, scene)


# -- (2c) choices: 'whoever's nearest', 'whichever's easier', 'either student', headers ----------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        ("Either Mia or Tom can have the tape, whoever's nearest.", "tape>A | tape>B", DEPOT),
        ("Tom will take whichever's easier, tape or gloves.", "tape>B | gloves>B", DEPOT),
        ("Tom will take the tape or the gloves, whichever's easier.", "tape>B | gloves>B", DEPOT),
        (
            "Either Mia or Tom can have the tape, they're both shattered from the night shift.",
            "tape>A | tape>B",
            DEPOT,
        ),
        (
            "The scissors can go to either student, whoever's closest.",
            "scissors>B | scissors>C",
            CLASSROOM,
        ),
        ("Either student can have the globe.", "globe>B | globe>C", CLASSROOM),
        ("Any one of the plates to Lena, white or blue.", "plate_white>B | plate_blue>B", KITCHEN),
        (
            "Hand out one thing apiece: the tape goes to Mia and the gloves go to Tom.",
            "tape>A & gloves>B",
            DEPOT,
        ),
        (
            "Both of them need something, so the tape to Mia and the gloves to Tom.",
            "tape>A & gloves>B",
            DEPOT,
        ),
    ],
)
def test_choices_and_headers_said_around_a_request_read(text: str, want: str, scene: Scene) -> None:
    assert_reads(text, want, scene)


@pytest.mark.parametrize(
    ("text", "scene"),
    [
        # no choice of people before 'whoever'
        ("Give Tom the tape, whoever's nearest.", DEPOT),
        # 'either of the patients' with another person said apart
        ("Either of the patients can have the magazine, Mr Lee or Ruth", WARD),
        # 'any one of the pens' with no recipient: where they are, or where one goes?
        ("Any one of the pens in the box, please", OFFICE),
        # a header whose list gives one person two things or places one
        ("One thing each: the tape and the gloves for Mia, the scanner for Tom.", DEPOT),
        ("Both of them need something, so the tape to Mia and the gloves on the belt.", DEPOT),
    ],
)
def test_near_forms_of_the_choices_stay_refused(text: str, scene: Scene) -> None:
    assert_refused(text, scene)


# -- (2d) what is not to be done, said first; 'in P's hands'; "P's the one for X" ----------------


@pytest.mark.parametrize(
    ("text", "want"),
    [
        ("Not Alice, she's had one; it's Bob that gets the cup.", "cup>B"),
        ("Not Alice ah, Bob is the one getting the apple.", "apple>B"),
        ("Carol's the one for the apple.", "apple>C"),
        ("Don't put it down anywhere, just hand the bottle to Alice.", "bottle>A"),
        ("No need to put it anywhere, just give Alice the bottle.", "bottle>A"),
        ("Not on the floor, mind, the bottle goes straight into Alice's hand.", "bottle>A"),
        ("Put the bottle in Alice's hands, and the cup on the shelf.", "bottle>A & cup@shelf"),
    ],
)
def test_what_is_not_to_be_done_said_first_reads(text: str, want: str) -> None:
    assert_reads(text, want, CELL)


@pytest.mark.parametrize(
    "text",
    [
        # the request after it does what was said not to be done
        "Not Alice, Bob gets the cup and Alice the apple.",
        "No need to put it anywhere, just put the bottle on the shelf.",
        "Not on the floor, put the bottle on the shelf.",
        # a reason naming an object; hands that are no one's of the scene
        "Not Alice, she's got the cup; Bob gets the apple.",
        "Put the bottle in the shelf's hands.",
    ],
)
def test_near_forms_of_what_is_not_to_be_done_stay_refused(text: str) -> None:
    assert_refused(text, CELL)


# -- (2e) remarks around a request: 'the poor thing's …', 'they need a rinse', 'X's gone, so' ----


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        (
            "Both blankets to Mrs Khan, the poor thing's shivering.",
            "blanket_blue>C & blanket_grey>C",
            WARD,
        ),
        ("The two cups in the sink, they need a rinse.", "cup_green@sink & cup_white@sink", LAB),
        ("Give Omar the spoon, it needs a wash.", "spoon>B", LAB),
        ("The blue pen to Priya, the notary wants blue ink.", "pen_blue>A", OFFICE),
        (
            "The auditor's gone, so every one of the three pens back in the box.",
            "pen_black@box & pen_blue@box & pen_red@box",
            OFFICE,
        ),
    ],
)
def test_remarks_around_a_request_are_taken_off(text: str, want: str, scene: Scene) -> None:
    assert_reads(text, want, scene)


@pytest.mark.parametrize(
    ("text", "scene"),
    [
        # negated, naming a thing of the scene, or said of a person of the scene
        ("Both blankets to Mrs Khan, the poor thing's not shivering.", WARD),
        ("Both blankets to Mrs Khan, the poor thing needs the jug.", WARD),
        ("The blue pen to Priya, the manager wants blue ink.", OFFICE),
        ("Sam's gone, so the stapler to Priya.", OFFICE),
    ],
)
def test_near_forms_of_the_remarks_stay_refused(text: str, scene: Scene) -> None:
    assert_refused(text, scene)


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        ("The single packet of crisps to Bob.", "chips>B", CELL),
        ("The single apple to Bob.", "apple>B", CELL),
        ("Give Bob a tin of crisps.", "chips>B", CELL),
        ("Give Jess the tin of screws.", "screws>B", WORKSHOP),
    ],
)
def test_the_single_one_and_what_holds_it_read(text: str, want: str, scene: Scene) -> None:
    assert_reads(text, want, scene)


@pytest.mark.parametrize(
    ("text", "scene"),
    [
        ("The single mug to Bob.", CELL),  # two mugs
        ("The bag of mugs to Bob.", CELL),
        ("Give Tom the box of tape.", DEPOT),  # boxes are objects of the depot
    ],
)
def test_near_forms_of_the_single_one_stay_refused(text: str, scene: Scene) -> None:
    assert_refused(text, scene)


@pytest.mark.parametrize(
    ("text", "want"),
    [
        (
            "Grandad's clearing the floor, so both of the blocks up on the high chair.",
            "block_red@highchair & block_green@highchair",
        ),
        (
            "Grandad's clearing the floor, so both of the blocks onto the high chair.",
            "block_red@highchair & block_green@highchair",
        ),
        ("Grandad's tired, the bib back on the high chair.", "bib@highchair"),
    ],
)
def test_objects_sent_onto_a_surface_after_a_remark_read(text: str, want: str) -> None:
    assert_reads(text, want, NURSERY)


@pytest.mark.parametrize(
    "text",
    [
        # 'on' may say where they lie (for Grandad?) or where they go
        "Grandad's clearing the floor, so both of the blocks on the high chair.",
        "Grandad's tired, the bib on the high chair.",
    ],
)
def test_objects_on_a_surface_after_a_remark_stay_refused(text: str) -> None:
    assert_refused(text, NURSERY)
