"""Session-32 phrasings of issue 12 (engineer 12r): blind30's choices, counts, negation,
exclusions and corrections; docs/grounding.md, "Session 32 (engineer 12r)". Each rule with the
sentences it changes and near forms that must stay refused (or read as they did)."""

from __future__ import annotations

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
    PhrasingCases,
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


CASES = PhrasingCases()


# -- 'all four of the things', 'the pair of items': everything, the scene's count ---------------


test_all_things = CASES.test(
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
)


# -- 'the two things to drink from, the bottle and the cup': the list counted -------------------


test_apposed_list = CASES.test(
    ("Person A gets the two things to eat, the chips and the apple.", "chips>A & apple>A", F42),
    # a list longer or shorter than the count; a place the scene lacks
    ("Person A gets the two things to eat, the chips, the apple and the cup.", None, F42),
    ("Person A gets the three things to eat, the chips and the apple.", None, F42),
    ("Person A gets the two things on the shelf, the chips and the apple.", None, F42),
)


# -- 'the three boxes, small, medium and large,': each adjective names one ----------------------


test_apposed_adjectives = CASES.test(
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
)


# -- "P's taking X home (with her)": the things go to P -----------------------------------------


test_taken_home = CASES.test(
    ("Person B's taking the chips and the apple home with her.", "chips>B & apple>B", L44),
    (
        "Person B's taking three things home, namely the bottle, the apple and the cup.",
        "bottle>B & apple>B & cup>B",
        L44,
    ),
    # taking it to someone else
    ("Person B's taking the chips home to Person A.", None, L44),
)


# -- 'one apiece out of the two', 'One each for P and Q out of X and Y' -------------------------


test_apiece = CASES.test(
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
)


# -- ', you pick', "I don't mind how" after a share-out -----------------------------------------


test_you_pick = CASES.test(
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
)


# -- 'Each of them gets one of X and Y' with no one named: the scene's two people ---------------


test_each_of_them = CASES.test(
    (
        "Each of them gets one of the bottle and the chips.",
        "(bottle>A & chips>B) | (bottle>B & chips>A)",
        DUO,
    ),
    # three people: which two?; a person named after it
    ("Each of them gets one of the spoon and the bowl.", None, LAB),
    ("Each of them gets one of the bottle and the chips, Person A first.", None, DUO),
)


# -- ", whichever one's clean", ", she'll chew whichever you hand her" after a choice -----------


test_choice_tail = CASES.test(
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
)


# -- 'P and Q both want X; give it to either one' -----------------------------------------------


test_both_want_either = CASES.test(
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
)


# -- 'Whichever you can reach first, X or Y, hand it to P' --------------------------------------


test_reach_first = CASES.test(
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
)


# -- "…; she doesn't want the Y", "…, Q shouldn't get it" ---------------------------------------


test_not_wanted = CASES.test(
    ("Give Person B the bottle; she doesn't want the cup.", "bottle>B", F41),
    ("The chips are for Person B alone, Person A shouldn't get them.", "chips>B", L24),
    # withholding what the request gives; 'she' of two people
    ("Give Person B the bottle; she doesn't want the bottle.", None, F41),
    ("The chips are for Person B, Person B shouldn't get them.", None, L24),
    ("Hand Person A and Person B the bottle; she doesn't want the cup.", None, F41),
    # not yet: more than a name after it
    ("Give Person A the chips; she doesn't want the apple yet.", None, F42),
)


# -- '…; the X stays put, leave it alone' -------------------------------------------------------


test_stays_put = CASES.test(
    ("The apple is for Person B; the cup stays put, leave it alone.", "apple>B", F42),
    # the request moves it
    ("The apple is for Person B; the apple stays put, leave it alone.", None, F42),
)


# -- 'Only the X, nothing else, goes to P' ------------------------------------------------------


test_only_nothing_else = CASES.test(
    ("Only the cup, nothing else, goes to Person B.", "cup>B", SQ),
    # which mug?
    ("Only the mug, nothing else, goes to Bob.", None, CELL),
)


# -- 'No need to set the X down first, just pass it into P's hand' ------------------------------


test_no_need_first = CASES.test(
    (
        "No need to put the bottle down first, just hand it straight into Person A's hands.",
        "bottle>A",
        T12,
    ),
    # no such person
    ("No need to put the bottle down first, just hand it into Person Z's hands.", None, T12),
)


# -- 'P gets the X, and no, not Q' --------------------------------------------------------------


test_not_other_person = CASES.test(
    ("Grandad gets the bib, and no, not Ava, she's got hers.", "bib>B", NURSERY),
    # the same person
    ("Grandad gets the bib, and no, not Grandad.", None, NURSERY),
)


# -- ", and there's only the one, so no mix-ups" ------------------------------------------------


test_only_the_one = CASES.test(
    ("Person A wants the bottle, and there's only the one, so no mix-ups.", "bottle>A", T12),
    # two mugs
    ("Bob wants the mug, and there's only the one, so no mix-ups.", None, CELL),
)


# -- "Don't suppose you could …?" ---------------------------------------------------------------


test_dont_suppose = CASES.test(
    ("Don't suppose you could hand Person A the cup?", "cup>A", F42),
    # still a request the grammar checks
    ("Don't suppose you could hand Person C the cup?", None, F42),
)


# -- "whatever's here apart from X", 'every X bar the Y one' ------------------------------------


test_whatevers_here = CASES.test(
    ("Bob can take whatever's here apart from the bottle.", "chips>B", TWO),
    (
        "Every box bar the small one goes on the pallet, the drivers will sort the rest.",
        "box_medium@pallet & box_large@pallet",
        DEPOT,
    ),
    # nothing excluded before 'the rest'
    ("The small box goes on the pallet, the drivers will sort the rest.", None, DEPOT),
)


# -- 'the other thing, the one that isn't the X' with two objects -------------------------------


test_other_isnt = CASES.test(
    ("Person A gets the other thing, the one that isn't the chips.", "bottle>A", T21),
    # four objects
    ("Person A gets the other thing, the one that isn't the chips.", None, SQ),
)


# -- 'a cup, any cup except the green one' ------------------------------------------------------


test_any_except = CASES.test(
    ("Emma would like a cup, any cup except the white one.", "cup_green>C", LAB),
    # no such cup
    ("Emma would like a cup, any cup except the red one.", None, LAB),
)


# -- "P's blanket is the one that isn't grey" ---------------------------------------------------


test_isnt_adjective = CASES.test(
    (
        "Mr Lee's blanket is the one that isn't blue, please take it to him.",
        "blanket_grey>B",
        WARD,
    ),
    # no green blanket
    ("Mr Lee's blanket is the one that isn't green, please take it to him.", None, WARD),
)


# -- 'to Person, er, Person A, the only one here' -----------------------------------------------


test_er_person = CASES.test(
    ("Hand the bottle to Person, um, Person A, the only one here.", "bottle>A", ONE),
    # two people: not the only one
    ("Hand the bottle to Person A, the only one here.", None, T21),
)


# -- "Put the X on, oh wait, there's no shelf, just give it to P" -------------------------------


test_no_such_place = CASES.test(
    (
        "Put the bottle on, oh wait, there's no table, just hand it to Person A.",
        "bottle>A",
        T12,
    ),
    # the scene has a shelf: the placement was not broken off for want of one
    ("Put the cup on, oh wait, there's no shelf, just hand it to Bob.", None, CELL),
)


# -- a reason about what a correction took away: "Sam's got one", 'the cup's got a crack' -------


test_corrected_reason = CASES.test(
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
)


# -- "X to Q, no, sorry, there's only P here, to her then" --------------------------------------


test_only_one_here = CASES.test(
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
)


# -- "There's only the X, and P's the only one here, so that's simple: …" -----------------------


test_only_these = CASES.test(
    (
        "There's only the bottle, and Person A's the only one here, so that's easy: hand her it.",
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
)


# -- 'P said the blue blanket itches, so give him the other one' --------------------------------


test_other_one = CASES.test(
    (
        "Mrs Khan says the grey blanket is too thin, so bring her the other one.",
        "blanket_blue>C",
        WARD,
    ),
    # three pens: which other?; one jug: no other
    ("Sam said the black pen is broken, so give him the other one.", None, OFFICE),
    ("Mr Lee said the jug is too heavy, so give him the other one.", None, WARD),
)


# -- 'The two cups (both) want washing, so into the sink with the pair of them' -----------------


test_into_with_them = CASES.test(
    (
        "The two cups both need rinsing, so into the sink with the pair of them.",
        "cup_green@sink & cup_white@sink",
        LAB,
    ),
    # no bin
    ("The two cups both need rinsing, so into the bin with the pair of them.", None, LAB),
)


# -- ', for table six' after a request to a person ----------------------------------------------


test_for_table = CASES.test(
    ("Lena wants the salt for table two.", "salt>B", KITCHEN),
    (
        "Marco wants the pair of plates, the white one and the blue one, for table two.",
        "plate_white>A & plate_blue>A",
        KITCHEN,
    ),
    # no person to get it
    ("Put the salt on the counter for table two.", None, KITCHEN),
)


# -- '…, all except the blue one, that stays where it is' ---------------------------------------


test_except_stays = CASES.test(
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
)


# -- 'Both of the cups, the green and the white, …, into the sink with the pair' ----------------


test_apposed_adjectives_with_the = CASES.test(
    (
        "Both of the cups, the green and the white, need rinsing, so into the sink with the pair.",
        "cup_green@sink & cup_white@sink",
        LAB,
    ),
    # no red cup
    (
        "Both of the cups, the green and the red, need rinsing, so into the sink with the pair.",
        None,
        LAB,
    ),
)


# -- 'Give them a thing each, X and Y', 'X to either of them': the scene's two people -----------


test_either_of_them = CASES.test(
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
)


# -- 'one of the mugs for her, red or blue, …': the choice said again ---------------------------


test_choice_adjectives = CASES.test(
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
)


# -- a placement, then 'so P can bash them about' -----------------------------------------------


test_so_can = CASES.test(
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
)


# -- 'Two students, two books: …the red one…' ---------------------------------------------------


test_counted_header = CASES.test(
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
)
