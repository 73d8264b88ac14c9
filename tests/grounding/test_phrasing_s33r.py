"""Session-33 phrasings of issue 12 (engineer 12r): blind31's choices, counts, negation,
exclusions and corrections; docs/grounding.md, "Session 33 (engineer 12r)". Each rule with the
sentences it changes and near forms that must stay refused (or read as they did)."""

from __future__ import annotations

import pytest

from hltl.grounding import _rewrites52r, normalise
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
    PhrasingCases,
    assert_reads,
    assert_refused,
)

# the example scenes session 32's tests load (bottle, chips, cup, apple; people A and B; …)
from tests.grounding.test_phrasing_s32r import (
    DUO,
    F41,
    F42,
    FIG1,
    L24,
    L44,
    ONE,
    SQ,
    T12,
    T21,
    TWO,
)

CASES = PhrasingCases()


# -- a closing remark leaving the choice to the robot -------------------------------------------


test_free_choice = CASES.test(
    ("Either mug to Bob, whichever's closer to hand.", "mug_red>B | mug_blue>B", CELL),
    ("Give Bob either mug, whichever's closer to hand.", "mug_red>B | mug_blue>B", CELL),
    (
        "Any one of the cup, the bottle or the apple for Person B, the banjo player's not fussy.",
        "cup>B | bottle>B | apple>B",
        SQ,
    ),
    (
        "Person A can have either the apple or the chips, whatever's nearest.",
        "apple>A | chips>A",
        F41,
    ),
    (
        "Either spanner to Jess, whatever's nearest.",
        "spanner_small>B | spanner_large>B",
        WORKSHOP,
    ),
    (
        "Sam can have any of the pens, he's not fussed which colour.",
        "pen_black>B | pen_blue>B | pen_red>B",
        OFFICE,
    ),
    (
        "Any one of the boxes onto the belt, the supervisor isn't bothered which.",
        "box_small@conveyor | box_medium@conveyor | box_large@conveyor",
        DEPOT,
    ),
    (
        "Either plate onto the worktop, I'll plate up on whichever you pick.",
        "plate_white@counter | plate_blue@counter",
        KITCHEN,
    ),
    (
        "Each patient gets a blanket, either way round is fine.",
        "(blanket_blue>B & blanket_grey>C) | (blanket_grey>B & blanket_blue>C)",
        WARD,
    ),
    (
        "Hand Kofi a spanner, whichever's nearest your gripper.",
        "spanner_small>A | spanner_large>A",
        WORKSHOP,
    ),
    (
        "Pass Person A the cup or else the apple, depending on what's easiest to reach.",
        "cup>A | apple>A",
        SQ,
    ),
    # after one object the remark is left, refused
    ("Give Bob the red mug, whichever's closer to hand.", None, CELL),
    ("Hand Kofi the hammer, whichever's nearest your gripper.", None, WORKSHOP),
    ("Pass Person A the cup, depending on what's easiest to reach.", None, SQ),
    ("Give Sam the stapler, he's not fussed which colour.", None, OFFICE),
    ("The drill to Jess, whatever's nearest.", None, WORKSHOP),
)


# -- 'One each for P and Q, X and Y' ------------------------------------------------------------


test_one_each_listed = CASES.test(
    (
        "One each for Alice and Bob, the bottle and the crisps, you decide who gets which.",
        "(bottle>A & chips>B) | (chips>A & bottle>B)",
        FIG1,
    ),
    (
        "One each for Alice and Bob, the bottle and the crisps.",
        "(bottle>A & chips>B) | (chips>A & bottle>B)",
        FIG1,
    ),
    # one object twice; a name of two objects
    ("One each for Alice and Bob, the bottle and the bottle.", None, FIG1),
    ("One each for Alice and Bob, the cup and the mug, you decide who gets which.", None, CELL),
)


# -- "P's off to …, so he's taking X" -----------------------------------------------------------


test_so_taking = CASES.test(
    (
        "Bob's off to the cricket, so he's taking both, the bottle and the crisps.",
        "bottle>B & chips>B",
        TWO,
    ),
    ("Alice is off to work, so she's taking the bottle.", "bottle>A", TWO),
    # taking it to someone: not hers
    ("Alice is off to work, so she's taking the bottle to Bob.", None, TWO),
    (
        "Bob's off to the cricket, so he's taking both, the bottle and the crisps to Alice.",
        None,
        TWO,
    ),
)


# -- 'the two of them, X and Y,' ------------------------------------------------------------------


test_them_listed = CASES.test(
    (
        "Put the two of them, bottle and crisps, up on the shelf.",
        "bottle@shelf & chips@shelf",
        TWO,
    ),
    (
        "Put the two of them, the stapler and the notebook, in the box.",
        "stapler@box & notebook@box",
        OFFICE,
    ),
    # a count the list does not meet; a person in the list
    ("Put the three of them, the stapler and the notebook, in the box.", None, OFFICE),
    ("Put the two of them, the stapler and Sam, in the box.", None, OFFICE),
)


# -- 'every (single) item here …, all four of them' -----------------------------------------------


test_every_counted = CASES.test(
    (
        "Every single item here goes to Person B, all four of them.",
        "bottle>B & chips>B & cup>B & apple>B",
        SQ,
    ),
    (
        "Every box in the place, all three, goes up onto the belt for the evening run.",
        "box_small@conveyor & box_medium@conveyor & box_large@conveyor",
        DEPOT,
    ),
    # counts the scene does not meet
    ("Every single item here goes to Person B, all three of them.", None, SQ),
    ("Every box in the place, all two, goes onto the pallet.", None, DEPOT),
)


# -- 'the drinking things, which is the bottle plus the cup' --------------------------------------


test_which_is_list = CASES.test(
    (
        "Person A gets the drinking things, which is the bottle plus the cup, for the roadies.",
        "bottle>A & cup>A",
        L44,
    ),
    # one object twice; a name of the scene before 'which'
    ("Person A gets the drinking things, which is the bottle plus the bottle.", None, L44),
    ("Person A gets the chips, which is the bottle plus the cup.", None, L44),
)


# -- 'A thing for each of them, P on the X and Q on the Y' ----------------------------------------


test_thing_each = CASES.test(
    (
        "A thing for each of them, Person A on the chips and Person B on the bottle.",
        "chips>A & bottle>B",
        T21,
    ),
    (
        "A thing for each of them: Dana takes the spoon, Omar takes the bowl, Emma takes the "
        "banana.",
        "spoon>A & bowl>B & banana>C",
        LAB,
    ),
    # one person twice; two things for one; a person left out
    ("A thing for each of them, Person A on the chips and Person A on the bottle.", None, T21),
    (
        "A thing for each of them, Person A on the chips and Person B on the bottle and the cup.",
        None,
        SQ,
    ),
    ("A thing for each of them: Dana takes the spoon, Omar takes the bowl.", None, LAB),
    (
        "Everyone gets one thing: the cup for Alice, the apple for Bob and the crisps for Carol.",
        "cup>A & apple>B & chips>C",
        CELL,
    ),
    ("Everyone gets one thing: the cup for Alice, the apple for Bob.", None, CELL),
    (
        "Everyone gets one thing: the cup for Alice, the apple for Bob and the crisps for Bob.",
        None,
        CELL,
    ),
)


# -- 'Both cups need a rinse …, so into the sink they go, the green and the white' ---------------


test_into_they_go = CASES.test(
    (
        "Both cups need a rinse after the titration, so into the sink they go, the green and "
        "the white.",
        "cup_green@sink & cup_white@sink",
        LAB,
    ),
    (
        "Both cups need a rinse after the titration, so into the sink they go.",
        "cup_green@sink & cup_white@sink",
        LAB,
    ),
    # a cup the scene lacks; a person in the cause; a person for the place
    ("Both cups need a rinse, so into the sink they go, the green and the blue.", None, LAB),
    ("Both cups need a rinse after Emma, so into the sink they go.", None, LAB),
    ("Both cups need a rinse, so onto Emma they go.", None, LAB),
)


# -- 'Not the X, not the Y, just the Z to P'; 'Not on the floor, into P's hand, the X' -----------


test_not_these = CASES.test(
    ("Not the cup, not the apple, just the bottle to Person B.", "bottle>B", F41),
    ("Not on the floor, into Person A's hand, the bottle.", "bottle>A", ONE),
    ("Not on the floor, onto the shelf, the bottle.", "bottle@shelf", FIG1),
    # what 'not' names is asked for; the place 'not' names is the place said
    ("Not the cup, not the apple, just the cup to Person B.", None, F41),
    ("Not on the shelf, onto the shelf, the bottle.", None, FIG1),
)


# -- ', (and definitely) not for Q' ---------------------------------------------------------------


test_not_for_other = CASES.test(
    (
        "Chips for Person A, and definitely not for Person B, who's on a diet for the rugby.",
        "chips>A",
        F42,
    ),
    # the person the request names; a 'who' naming an object; no pause before 'but not'
    ("Chips for Person A, and definitely not for Person A.", None, F42),
    ("Chips for Person A, and definitely not for Person B, who wants the apple.", None, F42),
    ("Give Bob the chips but not to Carol", None, CELL),
)


def test_not_to_the_teacher_names_the_students() -> None:
    """'The globe to the student, not to the teacher' with two students: refused naming them
    (the refusal of 'The globe to the student'); 'not to Noah' picks a student, and is left."""
    for reading in ("Person B", "Person C"):
        assert_refused("The globe to the student, not to the teacher.", CLASSROOM, reading)
    assert_refused("The globe to the student, not to Noah.", CLASSROOM, "nothing and something")


# -- 'Nothing for Q today, he's fasting; …'; 'and to nobody else' ---------------------------------


test_nothing_for = CASES.test(
    ("Nothing for Person B today, he's fasting; the bottle's for Person A.", "bottle>A", DUO),
    ("The bottle goes to Person A and to nobody else.", "bottle>A", T12),
    # the person who gets nothing gets it; two people before 'nobody else'
    ("Nothing for Person B today; the bottle's for Person B.", None, DUO),
    ("The bottle goes to Person A and Person B and to nobody else.", None, SQ),
)


# -- 'Anything but X' -----------------------------------------------------------------------------


test_anything_but = CASES.test(
    ("Anything but the chips for Person B.", "bottle>B", T21),
    ("Give Person B anything but the chips.", "bottle>B", T21),
    ("Anything but the chips for Person B.", "bottle>B | cup>B | apple>B", SQ),
    ("Person B can have anything except the apple.", "bottle>B | chips>B | cup>B", SQ),
    (
        "Person A will take anything at all as long as it isn't the cup.",
        "bottle>A | chips>A | apple>A",
        F42,
    ),
    # a person after 'as long as it isn't'
    ("Person A will take anything at all as long as it isn't Person B.", None, F42),
)


# -- 'Onto S with X'; 'any one of the boxes onto the belt' (phrasing.py) -------------------------


test_onto_with = CASES.test(
    (
        "Onto the belt with any box apart from the big one, whichever you like.",
        "box_small@conveyor | box_medium@conveyor",
        DEPOT,
    ),
    ("Onto the belt with the scanner.", "scanner@conveyor", DEPOT),
    # a person moved; a person for the place
    ("Onto the belt with Tom.", None, DEPOT),
    ("Onto Tom with the scanner.", None, DEPOT),
)


def test_onto_says_where_one_goes() -> None:
    """'onto' says where a thing goes, never where it lies: 'Any one of the boxes onto the belt'
    is a placement; 'on the belt' may say which boxes, and is refused."""
    want = "box_small@conveyor | box_medium@conveyor | box_large@conveyor"
    assert_reads("Any one of the boxes onto the belt.", want, DEPOT)
    assert_refused("Any one of the boxes on the belt.", DEPOT, "which of them are meant")


# -- corrections said at length ------------------------------------------------------------------


test_correction_cue = CASES.test(
    ("Crisps to Alice, oh hang about, I got that wrong, they're Carol's.", "chips>C", CELL),
    ("The bottle's for Person B, hmm, no, my mistake, it's Person A's.", "bottle>A", L44),
    ("Bottle to Person A, oh, correction from the skipper, it's Person B.", "bottle>B", L24),
    (
        "Chips to Person B, no, wrong way round, chips to Person A and the bottle to Person B.",
        "chips>A & bottle>B",
        T21,
    ),
    ("Knife to Lena, oh no, not the knife, the tongs.", "tongs>B", KITCHEN),
    ("Crisps to Bob, ah, not Bob, Alice.", "chips>A", FIG1),
    ("Give Person B the apple and the cup, well, not the cup, just the apple.", "apple>B", F41),
    # the same person; no such person; no whole request after 'wrong way round'; 'not' naming
    # what the request did not name
    ("Crisps to Alice, oh hang about, I got that wrong, they're Alice's.", None, CELL),
    ("Crisps to Alice, oh hang about, I got that wrong, they're Dave's.", None, CELL),
    ("Chips to Person B, no, wrong way round.", None, T21),
    ("Knife to Lena, oh no, not the lemon, the tongs.", None, KITCHEN),
    ("Crisps to Bob, ah, not Alice, Carol.", None, FIG1),
    ("Crisps to Bob, ah, not Bob, the bottle.", None, FIG1),
    ("Give Person B the apple and the cup, well, not the bottle, just the apple.", None, F41),
)


# -- 'One of these to P, X or Y'; 'Of everything lying about here, …' ----------------------------


test_one_of_these = CASES.test(
    (
        "One of these to Person A, the bottle or the chips, I don't mind which.",
        "bottle>A | chips>A",
        DUO,
    ),
    ("Of everything lying about here, Person A only wants the bottle.", "bottle>A", ONE),
    # one object twice; a person in the choice; a place of the scene; two people
    ("One of these to Person A, the bottle or the bottle.", None, DUO),
    ("One of these to Person A, the bottle or Person B.", None, DUO),
    ("Of everything on the shelf, Person A only wants the bottle.", None, FIG1),
    ("Of everything lying about here, Person A and Person B want the bottle.", None, SQ),
)


# -- share-outs said another way: 'Two spanners, one to P and one to Q'; 'One thing each: X to
# one of them, Y to the other'; 'Whichever of the two people is closer can have X' -------------


test_share_outs = CASES.test(
    (
        "Two spanners, one to Kofi and one to Jess.",
        "(spanner_small>A & spanner_large>B) | (spanner_large>A & spanner_small>B)",
        WORKSHOP,
    ),
    (
        "Two cups, one to Dana and one to Omar.",
        "(cup_green>A & cup_white>B) | (cup_white>A & cup_green>B)",
        LAB,
    ),
    (
        "One thing each: the chips to one of them, the bottle to the other, you pick who gets "
        "what.",
        "(bottle>A & chips>B) | (chips>A & bottle>B)",
        DUO,
    ),
    ("Whichever of the two people is closer can have the bottle.", "bottle>A | bottle>B", T21),
    # one person twice; a count the scene does not meet; one object twice; three people
    ("Two spanners, one to Kofi and one to Kofi.", None, WORKSHOP),
    ("Two pens, one to Priya and one to Sam.", None, OFFICE),
    ("One thing each: the chips to one of them, the chips to the other.", None, DUO),
    ("Whichever of the two people is closer can have the bottle.", None, CELL),
)


# -- ', in whatever order suits you'; ", she'll need the two"; '… the white one, mind, not the
# blue' ------------------------------------------------------------------------------------------


test_said_again = CASES.test(
    (
        "Put all three boxes on the conveyor, in whatever order suits you.",
        "box_small@conveyor & box_medium@conveyor & box_large@conveyor",
        DEPOT,
    ),
    (
        "The pair of spanners to Jess, she'll need the two.",
        "spanner_small>B & spanner_large>B",
        WORKSHOP,
    ),
    ("Mr Novak wants a plate — the white one, mind, not the blue.", "plate_white>C", KITCHEN),
    # steps in order; one thing, not two; no red plate
    (
        "Put the small box on the conveyor, then the large box on the pallet, in whatever "
        "order suits you.",
        None,
        DEPOT,
    ),
    ("The hammer to Jess, she'll need the two.", None, WORKSHOP),
    ("Mr Novak wants a plate — the white one, mind, not the red.", None, KITCHEN),
)


# -- 'no, I mean the bottle, it's the bottle she's after'; '…and not the blue, he says that colour
# gives him a headache' ---------------------------------------------------------------------------


test_reasons_said_again = CASES.test(
    (
        "Give Person B the chips, no, I mean the bottle, it's the bottle she's after.",
        "bottle>B",
        DUO,
    ),
    (
        "Mr Lee's to get the grey blanket and not the blue, he says that colour gives him a "
        "headache.",
        "blanket_grey>B",
        WARD,
    ),
    # the reason names another object; another person; no 'not' before it
    ("Give Person B the chips, no, I mean the bottle, it's the chips she's after.", None, DUO),
    (
        "Mr Lee gets the grey blanket and not the blue, he says that colour suits Mrs Khan.",
        None,
        WARD,
    ),
    (
        "Mr Lee gets the grey blanket and not the blue, she says that colour gives him a headache.",
        None,
        WARD,
    ),
    ("Mr Lee gets the grey blanket, he says that colour gives him a headache.", None, WARD),
)


# -- blind19-21's exclusions and choices said another way ----------------------------------------


test_exclusions_said_another_way = CASES.test(
    (
        "Carol would like a mug. Red or blue, grab whichever one is nearer to you.",
        "mug_red>C | mug_blue>C",
        CELL,
    ),
    (
        "Either book can go on the desk, I just need one out for the lesson.",
        "book_red@desk | book_green@desk",
        CLASSROOM,
    ),
    (
        "The blanket on the trolley stays there; Mrs Khan gets the other one.",
        "blanket_blue>C",
        WARD,
    ),
    (
        "Mrs Khan wants a blanket, but leave the one on the cart where it is and give her the "
        "other.",
        "blanket_blue>C",
        WARD,
    ),
    (
        "Kofi's after whichever spanner isn't already on the workbench.",
        "spanner_small>A",
        WORKSHOP,
    ),
    ("Alice needs a mug, but the red one's got a crack, so not that one.", "mug_blue>A", CELL),
    ("Zoe can have the red book, not the one on the bookshelf.", "book_red>C", CLASSROOM),
    ("Not to Lily, she'll only chew it; give the teddy to Ava.", "teddy>C", NURSERY),
    ("Scanner to Tom. No, not Tom, Mia's the one who asked.", "scanner>A", DEPOT),
    # no green mug; one object before the remark; one jug; no blanket on the bedside table;
    # no spanner on the locker; no green mug; the red book is not on the desk; the person
    # 'not' names gets it; the person named twice
    ("Carol would like a mug. Red or green, grab whichever one is nearer to you.", None, CELL),
    ("Give Zoe the red book, I just need one out for the lesson.", None, CLASSROOM),
    ("The jug on the trolley stays there; Mrs Khan gets the other one.", None, WARD),
    (
        "The blanket on the bedside table stays there; Mrs Khan gets the other one.",
        None,
        WARD,
    ),
    ("Kofi's after whichever spanner isn't on the locker.", None, WORKSHOP),
    ("Alice needs a mug, but the green one's got a crack, so not that one.", None, CELL),
    ("Zoe can have the red book, not the one on the desk.", None, CLASSROOM),
    ("Not to Lily, she'll only chew it; give the teddy to Lily.", None, NURSERY),
    ("Scanner to Tom. No, not Tom, Tom's the one who asked.", None, DEPOT),
)


# -- more share-outs, choices and corrections of blind19-21 --------------------------------------


test_more_said_another_way = CASES.test(
    (
        "One item apiece for the two of them, mind: Person A's having the apple, Person B's "
        "having the cup.",
        "apple>A & cup>B",
        L44,
    ),
    (
        "Give the two people a single item each: Person A the bottle, Person B the apple.",
        "bottle>A & apple>B",
        F42,
    ),
    (
        "Person A and Person B both want a drink, so the bottle to one and the cup to the "
        "other, whichever way round.",
        "(bottle>A & cup>B) | (cup>A & bottle>B)",
        F41,
    ),
    (
        "Anything at all for Person A, just the one item, whatever you grab first.",
        "bottle>A | chips>A | cup>A | apple>A",
        SQ,
    ),
    (
        "Mr Novak's getting the plate that's sitting out, not the one up in the plate rack.",
        "plate_white>C",
        KITCHEN,
    ),
    ("Chips for Bob, ah, no, wrong way round, Alice is the one wanting chips.", "chips>A", TWO),
    ("Black pen to Priya, oh, she marks in red, so the red one instead.", "pen_red>A", OFFICE),
    ("The apple for Person B, I mean the bottle, leave the apple.", "bottle>B", F42),
    ("Bib to Ava, oh no, she's too big for bibs, to Lily.", "bib>A", NURSERY),
    (
        "The apple can go to either person, I'm not bothered which of them.",
        "apple>A | apple>B",
        F42,
    ),
    (
        "Dana and Omar both want a drink, so the green cup to one and the white cup to the other.",
        "(cup_green>A & cup_white>B) | (cup_white>A & cup_green>B)",
        LAB,
    ),
    # one person twice; one object twice; a person twice; three people; no knife in the
    # rack; no plate on the counter; another object wanted; the same person; no green pen;
    # another person's remark; an object 'leave' does not correct; the same person; a remark
    # naming another object; three people
    (
        "One item apiece for the two of them, mind: Person A's having the apple, Person A's "
        "having the cup.",
        None,
        SQ,
    ),
    (
        "Give the two people a single item each: Person A the bottle, Person A the apple.",
        None,
        F42,
    ),
    (
        "Person A and Person B both want a drink, so the bottle to one and the bottle to the "
        "other.",
        None,
        F41,
    ),
    ("Anything at all for Person A and Person B, just the one item.", None, SQ),
    (
        "Mr Novak's getting the knife that's sitting out, not the one up in the plate rack.",
        None,
        KITCHEN,
    ),
    (
        "Mr Novak's getting the plate that's sitting out, not the one on the counter.",
        None,
        KITCHEN,
    ),
    ("Chips for Bob, ah, no, wrong way round, Alice is the one wanting the bottle.", None, TWO),
    ("Chips for Bob, ah, no, wrong way round, Bob is the one wanting chips.", None, TWO),
    ("Black pen to Priya, oh, she marks in red, so the green one instead.", None, OFFICE),
    ("Black pen to Priya, oh, Sam marks in red, so the red one instead.", None, OFFICE),
    ("Black pen to Priya, oh, she marks in the box, so the red one instead.", None, OFFICE),
    ("The apple for Person B, I mean the bottle, leave the cup.", None, F42),
    ("The apple for Person B, I mean the bottle, leave the bottle.", None, F42),
    ("Bib to Ava, oh no, she's too big for bibs, to Ava.", None, NURSERY),
    ("Bib to Ava, oh no, she's too big for the teddy, to Lily.", None, NURSERY),
)


# -- "…, I mean to Lily, Ava's too big for teddies now": why, of the person corrected away -------


test_corrected_away = CASES.test(
    ("Teddy to Ava, oops, I mean to Lily, Ava's too big for teddies now.", "teddy>A", NURSERY),
    ("Gloves to Mia, no, Tom, Mia's done with them.", "gloves>B", DEPOT),
    # the person corrected to; another object; a person not named before; no person corrected
    ("Teddy to Ava, oops, I mean to Lily, Lily's too big for teddies now.", None, NURSERY),
    ("Teddy to Ava, oops, I mean to Lily, Ava's too big for the bib now.", None, NURSERY),
    ("Teddy to Ava, oops, I mean to Lily, Grandad's too big for teddies now.", None, NURSERY),
    ("Teddy to Ava, oops, I mean the bib, Ava's too big for teddies now.", None, NURSERY),
)


def test_refused_without_these_steps(monkeypatch: pytest.MonkeyPatch) -> None:
    """Every sentence these rules read is refused with the session-33 (12r) steps taken out
    (but 'Any one of the boxes onto the belt', phrasing.py's): each rule is what reads it."""
    # sessions 42 and 43 (12r): their rules of the same families read these too
    CASES.refused_without(
        (
            *normalise._STEPS33R,
            *normalise._STEPS42R,
            *normalise._STEPS43R_FIRST,
            *normalise._STEPS43R,
            # session 44 (12r): its rules of the same families read some of these too
            *normalise._STEPS44R_FIRST,
            *normalise._STEPS44R,
            # session 52 (12r): "Mia's the one who asked" after a correction, the same family
            _rewrites52r._who_asked52r,
        ),
        monkeypatch,
    )
