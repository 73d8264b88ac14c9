"""Session-32 phrasings of issue 12 (engineer 12r): blind30's choices, counts, negation,
exclusions and corrections; docs/grounding.md, "Session 32 (engineer 12r)". Each rule with the
sentences it changes and near forms that must stay refused (or read as they did)."""

from __future__ import annotations

import pytest

from hltl.world.scene import Scene, load_scene
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
    assert_reads,
    assert_refused,
)


def _scene(name: str) -> Scene:
    return load_scene(ROOT / f"examples/scenes/{name}.yaml")


SQ = _scene("4-4-square")  # bottle, chips, cup, apple; A, B
L44 = _scene("4-4-line")  # bottle, chips, cup, apple; A, B
F41 = _scene("4-1")  # bottle, chips, cup, apple; A, B
F42 = _scene("4-2")  # bottle, chips, cup, apple; A, B
DUO = _scene("2-2")  # bottle, chips; A, B
L24 = _scene("2-4-line")  # bottle, chips; A, B
ONE = _scene("1-1")  # bottle; A
T12 = _scene("1-2")  # bottle; A
T21 = _scene("2-1")  # bottle, chips; A, B
TWO = _scene("two_arms")  # bottle, chips (crisps); Alice, Bob
FIG1 = _scene("fig1")  # bottle, chips (crisps); Alice, Bob; shelf


def _assert_case(text: str, want: str | None, scene: Scene) -> None:
    if want is None:
        assert_refused(text, scene)
    else:
        assert_reads(text, want, scene)


# -- 'all four of the things', 'the pair of items': everything, the scene's count ---------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        (
            "Person A's moving house, so all four of the things on the table go to her.",
            "bottle>A & chips>A & cup>A & apple>A",
            SQ,
        ),
        ("The pair of things on the table both go to Person A.", "bottle>A & chips>A", DUO),
        # a count the scene does not meet, or a place it has
        ("All three of the things on the table go to Person B.", None, SQ),
        ("The pair of items on the table both go to Person A.", None, SQ),
        ("All six of the things on the shelf go to Bob.", None, CELL),
    ],
)
def test_all_things(text: str, want: str | None, scene: Scene) -> None:
    _assert_case(text, want, scene)


# -- 'the two things to drink from, the bottle and the cup': the list counted -------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        ("Person A gets the two things to eat, the chips and the apple.", "chips>A & apple>A", F42),
        # a list longer or shorter than the count; a place the scene lacks
        ("Person A gets the two things to eat, the chips, the apple and the cup.", None, F42),
        ("Person A gets the three things to eat, the chips and the apple.", None, F42),
        ("Person A gets the two things on the shelf, the chips and the apple.", None, F42),
    ],
)
def test_apposed_list(text: str, want: str | None, scene: Scene) -> None:
    _assert_case(text, want, scene)


# -- 'the three boxes, small, medium and large,': each adjective names one ----------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        (
            "The two boxes, small and large, go on the pallet.",
            "box_small@pallet & box_large@pallet",
            DEPOT,
        ),
        (
            "The three boxes, small, medium and large, all go on the pallet.",
            "box_small@pallet & box_medium@pallet & box_large@pallet",
            DEPOT,
        ),
        (
            "Both spanners, large and small, go in the locker.",
            "spanner_small@locker & spanner_large@locker",
            WORKSHOP,
        ),
        # a count the adjectives do not meet; an adjective that names no box
        ("The two boxes, small, medium and large, go on the pallet.", None, DEPOT),
        ("The three boxes, small, tiny and large, go on the pallet.", None, DEPOT),
    ],
)
def test_apposed_adjectives(text: str, want: str | None, scene: Scene) -> None:
    _assert_case(text, want, scene)


# -- "P's taking X home (with her)": the things go to P -----------------------------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        ("Person B's taking the chips and the apple home with her.", "chips>B & apple>B", L44),
        (
            "Person B's taking three things home, namely the bottle, the apple and the cup.",
            "bottle>B & apple>B & cup>B",
            L44,
        ),
        # taking it to someone else
        ("Person B's taking the chips home to Person A.", None, L44),
    ],
)
def test_taken_home(text: str, want: str | None, scene: Scene) -> None:
    _assert_case(text, want, scene)


# -- 'one apiece out of the two', 'One each for P and Q out of X and Y' -------------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        (
            "Person A and Person B get a single item apiece out of the two, you pick.",
            "(bottle>A & chips>B) | (bottle>B & chips>A)",
            L24,
        ),
        (
            "One each for Bob and Alice out of the bottle and the crisps.",
            "(bottle>B & chips>A) | (bottle>A & chips>B)",
            FIG1,
        ),
        (
            "One book each for Noah and Zoe out of the red one and the green one.",
            "(book_red>B & book_green>C) | (book_red>C & book_green>B)",
            CLASSROOM,
        ),
        (
            "One blanket apiece for the two patients.",
            "(blanket_blue>B & blanket_grey>C) | (blanket_blue>C & blanket_grey>B)",
            WARD,
        ),
        # a count the scene does not meet; one person twice; a role three do not share
        ("Person A and Person B get a single item apiece out of the three, you pick.", None, SQ),
        ("One each for Bob and Bob out of the bottle and the crisps.", None, FIG1),
        ("One book each for Noah and Zoe out of the red one and the globe.", None, CLASSROOM),
        ("One blanket apiece for the three patients.", None, WARD),
    ],
)
def test_apiece(text: str, want: str | None, scene: Scene) -> None:
    _assert_case(text, want, scene)


# -- ', you pick', "I don't mind how" after a share-out -----------------------------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        (
            "Person A and Person B get one each, you pick.",
            "(bottle>A & chips>B) | (bottle>B & chips>A)",
            L24,
        ),
        (
            "Each of them gets one of the bottle and the chips, I don't mind how.",
            "(bottle>A & chips>B) | (bottle>B & chips>A)",
            DUO,
        ),
        # after a single request there is nothing to pick
        ("Give Person A the bottle, you pick.", None, L24),
    ],
)
def test_you_pick(text: str, want: str | None, scene: Scene) -> None:
    _assert_case(text, want, scene)


# -- 'Each of them gets one of X and Y' with no one named: the scene's two people ---------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        (
            "Each of them gets one of the bottle and the chips.",
            "(bottle>A & chips>B) | (bottle>B & chips>A)",
            DUO,
        ),
        # three people: which two?; a person named after it
        ("Each of them gets one of the spoon and the bowl.", None, LAB),
        ("Each of them gets one of the bottle and the chips, Person A first.", None, DUO),
    ],
)
def test_each_of_them(text: str, want: str | None, scene: Scene) -> None:
    _assert_case(text, want, scene)


# -- ", whichever one's clean", ", she'll chew whichever you hand her" after a choice -----------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        ("Either cup for Omar, whichever one's clean.", "cup_green>B | cup_white>B", LAB),
        (
            "Either block for Ava, she'll play with whichever you hand her.",
            "block_red>C | block_green>C",
            NURSERY,
        ),
        (
            "Carol isn't fussy: one of the mugs, doesn't matter which, as long as it's clean.",
            "mug_red>C | mug_blue>C",
            CELL,
        ),
        # no choice before it
        ("The green cup for Omar, whichever one's clean.", None, LAB),
        ("The red block for Ava, she'll play with whichever you hand her.", None, NURSERY),
        ("Carol wants one of the mugs, as long as it's clean.", None, CELL),
    ],
)
def test_choice_tail(text: str, want: str | None, scene: Scene) -> None:
    _assert_case(text, want, scene)


# -- 'P and Q both want X; give it to either one' -----------------------------------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        (
            "Person A and Person B both want the bottle; give it to either one.",
            "bottle>A | bottle>B",
            T21,
        ),
        (
            "Person A and Person B both want the bottle; give it to either one of them.",
            "bottle>A | bottle>B",
            T21,
        ),
        # one person twice
        ("Person A and Person A both want the bottle; give it to either one.", None, T21),
    ],
)
def test_both_want_either(text: str, want: str | None, scene: Scene) -> None:
    _assert_case(text, want, scene)


# -- 'Whichever you can reach first, X or Y, hand it to P' --------------------------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        (
            "Whichever you can reach first, the cup or the apple, hand it to Person A.",
            "cup>A | apple>A",
            F41,
        ),
        # the request names another object
        (
            "Whichever you can reach first, the cup or the apple, hand it to Person A and"
            " the bottle to Person B.",
            None,
            F41,
        ),
    ],
)
def test_reach_first(text: str, want: str | None, scene: Scene) -> None:
    _assert_case(text, want, scene)


# -- "…; she doesn't want the Y", "…, Q shouldn't get it" ---------------------------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        ("Give Person B the bottle; she doesn't want the cup.", "bottle>B", F41),
        ("The chips are for Person B alone, Person A shouldn't get them.", "chips>B", L24),
        # withholding what the request gives; 'she' of two people
        ("Give Person B the bottle; she doesn't want the bottle.", None, F41),
        ("The chips are for Person B, Person B shouldn't get them.", None, L24),
        ("Hand Person A and Person B the bottle; she doesn't want the cup.", None, F41),
        # not yet: more than a name after it
        ("Give Person A the chips; she doesn't want the apple yet.", None, F42),
    ],
)
def test_not_wanted(text: str, want: str | None, scene: Scene) -> None:
    _assert_case(text, want, scene)


# -- '…; the X stays put, leave it alone' -------------------------------------------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        ("The apple is for Person B; the cup stays put, leave it alone.", "apple>B", F42),
        # the request moves it
        ("The apple is for Person B; the apple stays put, leave it alone.", None, F42),
    ],
)
def test_stays_put(text: str, want: str | None, scene: Scene) -> None:
    _assert_case(text, want, scene)


# -- 'Only the X, nothing else, goes to P' ------------------------------------------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        ("Only the cup, nothing else, goes to Person B.", "cup>B", SQ),
        # which mug?
        ("Only the mug, nothing else, goes to Bob.", None, CELL),
    ],
)
def test_only_nothing_else(text: str, want: str | None, scene: Scene) -> None:
    _assert_case(text, want, scene)


# -- 'No need to set the X down first, just pass it into P's hand' ------------------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        (
            "No need to put the bottle down first, just hand it straight into Person A's hands.",
            "bottle>A",
            T12,
        ),
        # no such person
        ("No need to put the bottle down first, just hand it into Person Z's hands.", None, T12),
    ],
)
def test_no_need_first(text: str, want: str | None, scene: Scene) -> None:
    _assert_case(text, want, scene)


# -- 'P gets the X, and no, not Q' --------------------------------------------------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        ("Grandad gets the bib, and no, not Ava, she's got hers.", "bib>B", NURSERY),
        # the same person
        ("Grandad gets the bib, and no, not Grandad.", None, NURSERY),
    ],
)
def test_not_other_person(text: str, want: str | None, scene: Scene) -> None:
    _assert_case(text, want, scene)


# -- ", and there's only the one, so no mix-ups" ------------------------------------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        ("Person A wants the bottle, and there's only the one, so no mix-ups.", "bottle>A", T12),
        # two mugs
        ("Bob wants the mug, and there's only the one, so no mix-ups.", None, CELL),
    ],
)
def test_only_the_one(text: str, want: str | None, scene: Scene) -> None:
    _assert_case(text, want, scene)


# -- "Don't suppose you could …?" ---------------------------------------------------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        ("Don't suppose you could hand Person A the cup?", "cup>A", F42),
        # still a request the grammar checks
        ("Don't suppose you could hand Person C the cup?", None, F42),
    ],
)
def test_dont_suppose(text: str, want: str | None, scene: Scene) -> None:
    _assert_case(text, want, scene)


# -- "whatever's here apart from X", 'every X bar the Y one' ------------------------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        ("Bob can take whatever's here apart from the bottle.", "chips>B", TWO),
        (
            "Every box bar the small one goes on the pallet, the drivers will sort the rest.",
            "box_medium@pallet & box_large@pallet",
            DEPOT,
        ),
        # nothing excluded before 'the rest'
        ("The small box goes on the pallet, the drivers will sort the rest.", None, DEPOT),
    ],
)
def test_whatevers_here(text: str, want: str | None, scene: Scene) -> None:
    _assert_case(text, want, scene)


# -- 'the other thing, the one that isn't the X' with two objects -------------------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        ("Person A gets the other thing, the one that isn't the chips.", "bottle>A", T21),
        # four objects
        ("Person A gets the other thing, the one that isn't the chips.", None, SQ),
    ],
)
def test_other_isnt(text: str, want: str | None, scene: Scene) -> None:
    _assert_case(text, want, scene)


# -- 'a cup, any cup except the green one' ------------------------------------------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        ("Emma would like a cup, any cup except the white one.", "cup_green>C", LAB),
        # no such cup
        ("Emma would like a cup, any cup except the red one.", None, LAB),
    ],
)
def test_any_except(text: str, want: str | None, scene: Scene) -> None:
    _assert_case(text, want, scene)


# -- "P's blanket is the one that isn't grey" ---------------------------------------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        (
            "Mr Lee's blanket is the one that isn't blue, please take it to him.",
            "blanket_grey>B",
            WARD,
        ),
        # no green blanket
        ("Mr Lee's blanket is the one that isn't green, please take it to him.", None, WARD),
    ],
)
def test_isnt_adjective(text: str, want: str | None, scene: Scene) -> None:
    _assert_case(text, want, scene)


# -- 'to Person, er, Person A, the only one here' -----------------------------------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        ("Hand the bottle to Person, um, Person A, the only one here.", "bottle>A", ONE),
        # two people: not the only one
        ("Hand the bottle to Person A, the only one here.", None, T21),
    ],
)
def test_er_person(text: str, want: str | None, scene: Scene) -> None:
    _assert_case(text, want, scene)


# -- "Put the X on, oh wait, there's no shelf, just give it to P" -------------------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        (
            "Put the bottle on, oh wait, there's no table, just hand it to Person A.",
            "bottle>A",
            T12,
        ),
        # the scene has a shelf: the placement was not broken off for want of one
        ("Put the cup on, oh wait, there's no shelf, just hand it to Bob.", None, CELL),
    ],
)
def test_no_such_place(text: str, want: str | None, scene: Scene) -> None:
    _assert_case(text, want, scene)


# -- a reason about what a correction took away: "Sam's got one", 'the cup's got a crack' -------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        ("Stapler to Priya, no, to Sam, Priya's got one.", "stapler>B", OFFICE),
        ("Crisps to Alice, sorry, I mean Bob, Alice is off crisps.", "chips>B", TWO),
        ("Chips to Person A, hang on, make it Person B, A's gone on break.", "chips>B", L24),
        ("Cup for Person B, no, sorry, the apple, the cup's got a crack.", "apple>B", F42),
        ("Sponge to the tray, no, the sink, the tray's wet.", "sponge@sink", LAB),
        # someone or something the correction did not take away
        ("Stapler to Priya, no, to Sam, Kofi's got one.", None, OFFICE),
        ("Cup for Person A, no, sorry, the bottle, the apple's got a crack.", None, F42),
        ("Cup for Person A, no, sorry, the bottle, the bottle's got a crack.", None, F42),
        ("Crisps to Alice, sorry, I mean Bob, the bottle is broken.", None, TWO),
        ("Sponge to the tray, no, the sink, the sponge's wet.", None, LAB),
        # no correction before it
        ("Cup for Person B, the cup's got a crack.", None, F42),
    ],
)
def test_corrected_reason(text: str, want: str | None, scene: Scene) -> None:
    _assert_case(text, want, scene)


# -- "X to Q, no, sorry, there's only P here, to her then" --------------------------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        (
            "Bottle to Person B, no, sorry, there's only Person A here, to her then.",
            "bottle>A",
            T12,
        ),
        ("Bottle for Person C, sorry, there's only Person A here, for her then.", "bottle>A", T12),
        (
            "Bottle to Person C. Sorry, wrong room, it's only Person A here, so she gets it.",
            "bottle>A",
            T12,
        ),
        # two people; the person said is not the one here
        ("Bottle to Person C, no, sorry, there's only Person A here, to her then.", None, T21),
        ("Bottle to Person B, no, sorry, there's only Person B here, to her then.", None, T12),
        # who gets it is not the one here
        (
            "Bottle to Person B. Oops, wrong bay, it's just Person A here, so Person B gets it.",
            None,
            T12,
        ),
        (
            "Bottle to Person C. Oops, wrong bay, it's just Person A here, so Person A gets it.",
            None,
            T21,
        ),
    ],
)
def test_only_one_here(text: str, want: str | None, scene: Scene) -> None:
    _assert_case(text, want, scene)


# -- "There's only the X, and P's the only one here, so that's simple: …" -----------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        (
            "There's only the bottle, and Person A's the only one here, so that's easy: hand"
            " her it.",
            "bottle>A",
            T12,
        ),
        # two objects: not the only one
        (
            "There's only the bottle, and Person A's the only one here, so that's simple:"
            " give it to her.",
            None,
            T21,
        ),
    ],
)
def test_only_these(text: str, want: str | None, scene: Scene) -> None:
    _assert_case(text, want, scene)


# -- 'P said the blue blanket itches, so give him the other one' --------------------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        (
            "Mrs Khan says the grey blanket is too thin, so bring her the other one.",
            "blanket_blue>C",
            WARD,
        ),
        # three pens: which other?; one jug: no other
        ("Sam said the black pen is broken, so give him the other one.", None, OFFICE),
        ("Mr Lee said the jug is too heavy, so give him the other one.", None, WARD),
    ],
)
def test_other_one(text: str, want: str | None, scene: Scene) -> None:
    _assert_case(text, want, scene)


# -- 'The two cups (both) want washing, so into the sink with the pair of them' -----------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        (
            "The two cups both need rinsing, so into the sink with the pair of them.",
            "cup_green@sink & cup_white@sink",
            LAB,
        ),
        # no bin
        ("The two cups both need rinsing, so into the bin with the pair of them.", None, LAB),
    ],
)
def test_into_with_them(text: str, want: str | None, scene: Scene) -> None:
    _assert_case(text, want, scene)


# -- ', for table six' after a request to a person ----------------------------------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        ("Lena wants the salt for table two.", "salt>B", KITCHEN),
        (
            "Marco wants the pair of plates, the white one and the blue one, for table two.",
            "plate_white>A & plate_blue>A",
            KITCHEN,
        ),
        # no person to get it
        ("Put the salt on the counter for table two.", None, KITCHEN),
    ],
)
def test_for_table(text: str, want: str | None, scene: Scene) -> None:
    _assert_case(text, want, scene)


# -- '…, all except the blue one, that stays where it is' ---------------------------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        (
            "Priya gets the pens, all except the red one, that stays where it is.",
            "pen_black>A & pen_blue>A",
            OFFICE,
        ),
        (
            "Priya gets the pens, all except the red one, that stays put.",
            "pen_black>A & pen_blue>A",
            OFFICE,
        ),
        # no green pen; no exclusion before it
        ("Priya gets the pens, all except the green one, that stays where it is.", None, OFFICE),
        ("Priya gets the red pen, that stays where it is.", None, OFFICE),
    ],
)
def test_except_stays(text: str, want: str | None, scene: Scene) -> None:
    _assert_case(text, want, scene)


# -- 'Both of the cups, the green and the white, …, into the sink with the pair' ----------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        (
            "Both of the cups, the green and the white, need rinsing, so into the sink with"
            " the pair.",
            "cup_green@sink & cup_white@sink",
            LAB,
        ),
        # no red cup
        (
            "Both of the cups, the green and the red, need rinsing, so into the sink with"
            " the pair.",
            None,
            LAB,
        ),
    ],
)
def test_apposed_adjectives_with_the(text: str, want: str | None, scene: Scene) -> None:
    _assert_case(text, want, scene)


# -- 'Give them a thing each, X and Y', 'X to either of them': the scene's two people -----------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        (
            "Give them a thing each, the bottle and the chips, don't care who gets which.",
            "(bottle>A & chips>B) | (bottle>B & chips>A)",
            DUO,
        ),
        ("The crisps to either of them, whoever's nearer.", "chips>A | chips>B", FIG1),
        # a person named after it; three people
        ("Give them a thing each, the bottle and the chips, Person A first.", None, DUO),
        ("Give them a thing each, the spoon and the bowl.", None, LAB),
        ("The apple to either of them, whoever's nearer.", None, CELL),
    ],
)
def test_either_of_them(text: str, want: str | None, scene: Scene) -> None:
    _assert_case(text, want, scene)


# -- 'one of the mugs for her, red or blue, …': the choice said again ---------------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        (
            "Carol's having a coffee, so one of the mugs for her, red or blue, not bothered.",
            "mug_red>C | mug_blue>C",
            CELL,
        ),
        # no green mug
        (
            "Carol's having a coffee, so one of the mugs for her, red or green, not bothered.",
            None,
            CELL,
        ),
    ],
)
def test_choice_adjectives(text: str, want: str | None, scene: Scene) -> None:
    _assert_case(text, want, scene)


# -- a placement, then 'so P can bash them about' -----------------------------------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        (
            "The two blocks go in the high chair so Lily can bash them about.",
            "block_red@highchair & block_green@highchair",
            NURSERY,
        ),
        ("The teddy goes on the play mat so Ava can cuddle it.", "teddy@mat", NURSERY),
        # a purpose that hands it over; a handover; no such person
        ("The teddy goes on the play mat so Ava can have it.", None, NURSERY),
        ("Give Ava the teddy so Lily can cuddle it.", None, NURSERY),
        ("The teddy goes on the play mat so Bob can cuddle it.", None, NURSERY),
    ],
)
def test_so_can(text: str, want: str | None, scene: Scene) -> None:
    _assert_case(text, want, scene)


# -- 'Two students, two books: …the red one…' ---------------------------------------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        (
            "Two students, two books: Zoe takes the red one and Noah gets the green one.",
            "book_red>C & book_green>B",
            CLASSROOM,
        ),
        # a count the scene does not meet; a book it does not have
        (
            "Three students, two books: Zoe takes the red one and Noah gets the green one.",
            None,
            CLASSROOM,
        ),
        (
            "Two students, two books: Zoe takes the blue one and Noah gets the green one.",
            None,
            CLASSROOM,
        ),
    ],
)
def test_counted_header(text: str, want: str | None, scene: Scene) -> None:
    _assert_case(text, want, scene)
