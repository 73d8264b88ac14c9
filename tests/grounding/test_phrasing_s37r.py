"""Session-37 phrasings of issue 12 (engineer 12r): blind35's choices, counts, negation,
exclusions and corrections; docs/grounding.md, "Session 37 (engineer 12r)". Each rule with the
sentences it changes and near forms that must stay refused (or read as they did)."""

from __future__ import annotations

import pytest

from hltl.grounding import _rewrites53s, _rewrites54s, normalise
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
)

# the example scenes session 32's tests load (bottle, chips, cup, apple; people A and B; …)
from tests.grounding.test_phrasing_s32r import (
    DUO,
    F41,
    FIG1,
    SQ,
    T12,
    TWO,
)

CASES = PhrasingCases()


# -- choices --------------------------------------------------------------------------------------


test_choices = CASES.test(
    # "There's something for both of them(, mind): <whose each thing is>"
    (
        "There's something for both of them, mind: the chips are Person B's and the cup is "
        "Person A's.",
        "chips>B & cup>A",
        F41,
    ),
    (
        "There's something for each of them: the bottle to Alice and the crisps to Bob.",
        "bottle>A & chips>B",
        TWO,
    ),
    ("There's something for both of them: the chips are Person B's.", None, F41),
    ("There's something for both of them: the chips and the cup are Person B's.", None, F41),
    (
        "There's something for both of them: the jug is Mr Lee's and the pills are Ruth's.",
        None,
        WARD,
    ),
    (
        "There's something for both of them: the pear is Person A's and the cup is Person B's.",
        None,
        F41,
    ),
    # "Go whichever route suits you, as long as P gets X (in the end)"
    ("Go whichever way you like, as long as Bob gets the crisps in the end.", "chips>B", FIG1),
    ("Go whichever route suits you, as long as Person A gets the cup.", "cup>A", SQ),
    ("Go whichever route suits you, as long as Person A doesn't get the cup.", None, SQ),
    ("Go whichever route suits you, as long as Person A gets the cup or the apple.", None, SQ),
    ("Go whichever route suits you, as long as Person A is happy.", None, SQ),
    # "Either arm can do it: …"
    ("Either arm can do it: the cup to Person B.", "cup>B", SQ),
    ("Any robot will do it, give Bob the crisps.", "chips>B", FIG1),
    ("Either arm can do it.", None, SQ),
    ("Either arm can do it: the pear to Person B.", None, SQ),
    # "Give one of them the X, P or Q, and the other one the Y"
    (
        "Give one of them the cup, Person A or Person B, and the other one the apple.",
        "(cup>A & apple>B) | (cup>B & apple>A)",
        SQ,
    ),
    (
        "Give one of them the jug, Mr Lee or Mrs Khan, and the other the magazine.",
        "(jug>B & magazine>C) | (jug>C & magazine>B)",
        WARD,
    ),
    ("Give one of them the cup, Person A or Person A, and the other one the apple.", None, SQ),
    ("Give one of them the cup, Person A or Person B, and the other one the cup.", None, SQ),
    ("Give one of them the cup, Person A or Person B, and the other one the pear.", None, SQ),
    ("Give one of them the jug, Mr Lee or the patient, and the other the magazine.", None, WARD),
    # "P's only <doing>, so any K (at all) will do him"
    (
        "Priya's only jotting down a number, so any pen at all will do her.",
        "pen_black>A | pen_blue>A | pen_red>A",
        OFFICE,
    ),
    (
        "Kofi's just tightening a nut, so any spanner will do him.",
        "spanner_small>A | spanner_large>A",
        WORKSHOP,
    ),
    ("Mr Lee's only reading, so any blanket will do her.", None, WARD),  # 'her' not Mr Lee
    ("Sam's only signing with the stapler, so any pen will do him.", None, OFFICE),
    ("Sam's only signing, so any hammer will do him.", None, OFFICE),
    # "The S needs one K on it, either the A or the B"
    (
        "The pallet needs one box on it, either the small or the medium.",
        "box_small@pallet | box_medium@pallet",
        DEPOT,
    ),
    (
        "The belt needs a box on it, either the medium or the large, not the small one.",
        "box_medium@conveyor | box_large@conveyor",
        DEPOT,
    ),
    ("The belt needs one box on it, either the small or the tiny.", None, DEPOT),
    ("The belt needs one box on it, either the small or the small.", None, DEPOT),
    ("Tom needs one box on it, either the small or the medium.", None, DEPOT),
    # "A K apiece for P and Q, I don't care who ends up with which"
    (
        "A blanket apiece for Mr Lee and Mrs Khan, I don't care who ends up with which.",
        "(blanket_blue>B & blanket_grey>C) | (blanket_grey>B & blanket_blue>C)",
        WARD,
    ),
    (
        "A cup each for Omar and Emma, I don't mind who gets which.",
        "(cup_green>B & cup_white>C) | (cup_white>B & cup_green>C)",
        LAB,
    ),
    (
        "A book apiece for Noah and Zoe and Mrs Ortiz, I don't care who ends up with which.",
        None,
        CLASSROOM,
    ),
    ("A globe apiece for Noah and Zoe, I don't care who ends up with which.", None, CLASSROOM),
    ("A book apiece for Noah, I don't care who ends up with which.", None, CLASSROOM),
    # "A K each for the <role>s"
    (
        "A blanket each for the patients.",
        "(blanket_blue>B & blanket_grey>C) | (blanket_grey>B & blanket_blue>C)",
        WARD,
    ),
    (
        "A book apiece for the students.",
        "(book_red>B & book_green>C) | (book_green>B & book_red>C)",
        CLASSROOM,
    ),
    ("A jug each for the patients.", None, WARD),  # one jug
    ("A blanket each for the nurses.", None, WARD),  # one nurse
    ("A cup each for the visitors.", None, LAB),
    # "P can have a K, she won't mind if it's the A or the B"
    (
        "Ava can have a block, she won't mind if it's the green or the red.",
        "block_green>C | block_red>C",
        NURSERY,
    ),
    (
        "Mr Lee can have a blanket, he won't mind if it's the grey or the blue.",
        "blanket_grey>B | blanket_blue>B",
        WARD,
    ),
    ("Mr Lee can have a blanket, she won't mind if it's the grey or the blue.", None, WARD),
    ("Lily can have a block, she won't mind if it's the red or the yellow.", None, NURSERY),
    ("Lily can have a block, she won't mind if it's the red or the red.", None, NURSERY),
    ("Lily can have a block, she will mind if it's the red or the green.", None, NURSERY),
)


# -- counts ---------------------------------------------------------------------------------------


test_counts = CASES.test(
    # "P's got a pair of things coming, X and Y"
    ("Bob's got a pair of things coming, the bottle and the mug.", None, CELL),  # two mugs
    ("Alice's got a pair of things coming, the crisps and the bottle.", "chips>A & bottle>A", TWO),
    ("Dana's got two things coming, the spoon and the bowl, she's busy.", "spoon>A & bowl>A", LAB),
    ("Alice's got three things coming, the crisps and the bottle.", None, TWO),
    ("Alice's got a pair of things coming, the crisps and the crisps.", None, TWO),
    ("Alice's got a pair of things coming, the crisps and the pear.", None, TWO),
    # ", to his <event> do" after a request to the one person 'his' may be
    ("Person A's taking the cup and the apple, to her birthday do.", "cup>A & apple>A", SQ),
    ("Give Bob the crisps, to his darts night.", "chips>B", FIG1),
    ("Give Bob the crisps, to her darts night.", None, FIG1),
    ("Give Bob and Alice the crisps, to his darts night.", None, FIG1),
    ("Give Bob the crisps, to his shelf party.", None, FIG1),
    # "X and Y, that's two, …"
    ("Both the chips and the bottle, that's two, are going to Person B.", "chips>B & bottle>B", SQ),
    (
        "The cup, the apple and the chips, that's three, are going to Person A.",
        "cup>A & apple>A & chips>A",
        SQ,
    ),
    ("Both the chips and the bottle, that's three, are going to Person B.", None, SQ),
    ("The cup, the apple and the chips, that's two, are going to Person A.", None, SQ),
    ("Both the chips and the pear, that's two, are going to Person B.", None, SQ),
    # "Just the one item for P: X"
    ("Just the one item for Person B: the apple.", "apple>B", SQ),
    ("The one thing for Mia: the tape.", "tape>A", DEPOT),
    ("Just the one item for Person B: the apple and the cup.", None, SQ),
    ("Just the one item for Person B: the pear.", None, SQ),
    # "The two things (here), one per person: …"
    (
        "The two things here, one per person: chips to Person A, bottle to Person B.",
        "chips>A & bottle>B",
        DUO,
    ),
    ("Two things, one each: bottle to Alice, crisps to Bob.", "bottle>A & chips>B", TWO),
    ("The two things here, one per person: chips to Person A, bottle to Person A.", None, DUO),
    ("The three things here, one per person: chips to Person A, bottle to Person B.", None, DUO),
    ("The two things here, one per person: cup to Person A, apple to Person B.", None, SQ),
    # "every last thing (you've got there)"
    ("Every last thing you've got there is for Bob.", "bottle>B & chips>B", FIG1),
    ("Every last thing goes to Person B.", "bottle>B & chips>B", DUO),
    ("Every last thing you've got there is for Person C.", None, DUO),
    # "…, it's the only one we've got left"
    ("Give Person A the bottle, it's the only one we've got left.", "bottle>A", T12),
    ("Give Person A the cup, it's the last one we've got.", "cup>A", SQ),
    ("Give Mr Novak the plate, it's the only one we've got left.", None, KITCHEN),
    # "the pair of Ks" in a scene of two Ks
    (
        "The pair of cups, the white and the green, go in the sink.",
        "cup_white@sink & cup_green@sink",
        LAB,
    ),
    (
        "The pair of blocks, the green and the red, go on the high chair.",
        "block_green@highchair & block_red@highchair",
        NURSERY,
    ),
    ("Put the pair of pens in the box.", None, OFFICE),  # three pens
    ("The pair of cups, the white and the blue, go in the sink.", None, LAB),
    # "Every K in the place, big one included, …"
    (
        "Every spanner in the place, big one included, goes in the locker.",
        "spanner_small@locker & spanner_large@locker",
        WORKSHOP,
    ),
    (
        "All the boxes, including the small one, go on the pallet.",
        "box_small@pallet & box_medium@pallet & box_large@pallet",
        DEPOT,
    ),
    ("Every box in the place, huge one included, goes on the belt.", None, DEPOT),
    ("Every box in the place, red one included, goes on the belt.", None, DEPOT),
    # "for her lesson on fossils"
    ("Mrs Ortiz needs the globe for her lesson on volcanoes.", "globe>A", CLASSROOM),
    ("Noah needs both books for his talk about dinosaurs.", "book_red>B & book_green>B", CLASSROOM),
    ("Mrs Ortiz needs the globe for her lesson on the desk.", None, CLASSROOM),
    ("Mrs Ortiz needs the globe for her lesson on scissors.", None, CLASSROOM),
)


# -- negation and exclusions ----------------------------------------------------------------------


test_negation = CASES.test(
    # "P doesn't want X, only Y"
    ("Bob doesn't want the crisps, only the bottle, he's just had lunch.", "bottle>B", TWO),
    ("Person A doesn't need the cup, just the apple, she's full.", "apple>A", SQ),
    ("Bob doesn't want the crisps, only the crisps.", None, TWO),
    ("Bob doesn't want the crisps, only the pear.", None, TWO),
    ("Bob doesn't want the crisps.", None, TWO),
    # ", and nothing besides that"; ", don't bother with anything more"
    ("The crisps for Alice, and nothing besides that.", "chips>A", FIG1),
    ("Just the cup for Person A, don't bother with anything else.", "cup>A", SQ),
    ("Nothing besides that.", None, FIG1),
    ("Don't bother with anything more.", None, FIG1),
    # "It's X P should have, Y isn't his"
    ("It's the apple Person A should have, the cup isn't hers.", "apple>A", SQ),
    ("It's the cup Mr Lee should get, the jug isn't his.", None, WARD),  # no 'the cup' in the ward
    ("It's the jug Mr Lee should get, the magazine isn't his.", "jug>B", WARD),
    ("It's the jug Mr Lee should get, the magazine isn't hers.", None, WARD),
    ("It's the apple Person A should have, the apple isn't hers.", None, SQ),
    # "No need to wait about, …"
    ("No need to hang around, give Bob the crisps.", "chips>B", FIG1),
    ("No need to wait about, the cup goes to Person B.", "cup>B", SQ),
    ("No need to wait about.", None, SQ),
    ("No need to give Bob the crisps.", None, FIG1),
    # "…, P's had his fill"
    ("The cup is going to Person A, Person B's had his fill.", "cup>A", SQ),
    ("The crisps are going to Bob, Alice has had her fill.", "chips>B", FIG1),
    ("The crisps are going to Bob, Alice has had his fill.", None, FIG1),
    ("The crisps are going to Bob, Person Z has had his fill.", None, FIG1),
    # "The Ks, except the A one, go …"
    (
        "The boxes, except the big one, go on the belt.",
        "box_small@conveyor & box_medium@conveyor",
        DEPOT,
    ),
    ("The spanners, apart from the small one, go in the locker.", "spanner_large@locker", WORKSHOP),
    ("The cups, except the blue one, go in the sink.", None, LAB),
    # "Only X for P, …"
    ("Only the bottle for Person A, she's in a hurry.", "bottle>A", SQ),
    ("Only the pear for Person A.", None, SQ),
    ("Only the bottle for Person Z.", None, SQ),
    # "None of the Ks, just X to P"
    ("None of the spanners, just the torch to Jess.", "torch>B", WORKSHOP),
    ("None of the boxes.", None, DEPOT),
    ("None of the boxes, just the pear to Mia.", None, DEPOT),
    # "Leave X, P only wants Y"
    ("Leave the hammer, Jess only wants the drill.", "drill>B", WORKSHOP),
    ("Leave the crisps, Bob just wants the bottle.", "bottle>B", FIG1),
    ("Leave the drill alone, it's only the torch that Kofi needs.", "torch>A", WORKSHOP),
    ("Leave the drill be, it's only the torch Jess wants, she's up a ladder.", "torch>B", WORKSHOP),
    ("Leave the drill be, it's only the drill Jess wants.", None, WORKSHOP),
    ("Leave the drill be, it's only the torch Person Q wants.", None, WORKSHOP),
    ("Leave the drill, Jess only wants the drill.", None, WORKSHOP),
    ("Leave the drill, Jess only wants the pear.", None, WORKSHOP),
    ("Leave the drill.", None, WORKSHOP),
)


# -- corrections ----------------------------------------------------------------------------------


test_corrections = CASES.test(
    # after a correction cue, the person or object corrected to said again in a clause
    (
        "Alice's to have the crisps, or no, wait, it was the bottle she asked me for.",
        "bottle>A",
        FIG1,
    ),
    ("Alice's to have the crisps, or no, wait, it was the bottle he asked me for.", None, FIG1),
    ("Alice's to have the crisps, or no, wait, it was the pear she asked me for.", None, FIG1),
    ("Apple to Person B, oh dear, my mistake, it should be Person A.", "apple>A", SQ),
    ("Apple to Person B, oh dear, my mistake, it should be Person Z.", None, SQ),
    ("Apple to Person B, it should be Person A.", None, SQ),  # no cue
    ("Bottle to Person B. No, correction, they're for Person A.", None, DUO),  # 'they' a bottle
    ("Chips to Person B. No, correction, they're for Person A.", "chips>A", DUO),
    ("Chips to Alice, sorry, they're for Bob.", "chips>B", TWO),
    ("Chips to Alice. Sorry, they're for Bob.", None, TWO),  # 'Sorry' opening a sentence
    ("Give the jug to Ruth, what am I saying, there's no Ruth here, Mr Lee gets it.", None, WARD),
    (
        "Bottle to Person C, what am I saying, there's no Person C here, Person B gets it.",
        "bottle>B",
        DUO,
    ),
    (
        "Bottle to Person C, what am I saying, there's no Person D here, Person B gets it.",
        None,
        DUO,
    ),
    ("Bib on the mat, or no, the teddy goes there.", "teddy@mat", NURSERY),
    ("Bib to Lily, or no, the teddy goes there.", None, NURSERY),  # 'there' not a person
    ("Bib on the mat, or no, the pear goes there.", None, NURSERY),
    # "she wanted the Y", "it goes on the T", "it goes to Q" after a cue
    ("Give Person A the cup, no, sorry, she wanted the apple.", "apple>A", SQ),
    ("Give Mr Lee the jug, no, sorry, she wanted the magazine.", None, WARD),  # 'she' not Mr Lee
    ("Give Person A the cup and Person B the chips, no, she wanted the apple.", None, SQ),
    ("Give Person A the cup, sorry, she wants the apple too.", None, SQ),
    ("Cup on the shelf, or no, it goes on the table.", "cup@table", CELL),
    ("Cup on the shelf, or no, it goes on the floor.", None, CELL),
    ("Cup and apple on the shelf, or no, it goes on the table.", None, CELL),
    # ", or was it Q, yes, Q"
    ("Give the apple to Person B, or was it Person A, yes, Person A.", "apple>A", SQ),
    ("Give Sam the stapler, or was it the notepad, yes, the notepad.", "notebook>B", OFFICE),
    ("Give the apple to Person B, or was it Person A, yes, Person B.", None, SQ),
    ("Give Sam the stapler, or was it the pen, yes, the pen.", None, OFFICE),  # three pens
    # an object the scene lacks corrected to one it has
    ("Pear to Person A, no, sorry, I meant to say the bottle.", "bottle>A", T12),
    ("The pear for Person B, sorry, I mean the chips.", "chips>B", DUO),
    ("Pear to Person A, no, sorry, I meant to say the plum.", None, T12),
    ("Pear to Person B, no, sorry, I meant to say the bottle.", None, T12),  # no Person B
    ("Pear to Person A, I meant to say the bottle.", None, T12),  # no cue
    # "the other way about"
    ("Cup to Person A and apple to Person B, no, the other way about.", "cup>B & apple>A", SQ),
    ("The other way about.", None, SQ),
    # ", hang about, I mean Q"
    ("Mrs Ortiz should get the ruler, hang about, I mean Noah.", "ruler>B", CLASSROOM),
    ("Mrs Ortiz should get the ruler, hang about.", None, CLASSROOM),
    ("Mrs Ortiz should get the ruler, hang about, I mean Person Q.", None, CLASSROOM),
)


def test_refused_without_these_steps(monkeypatch: pytest.MonkeyPatch) -> None:
    """Every sentence these rules read is refused with the session-37 (12r) steps taken out: each
    rule is what reads it. (12s's session-40 purpose rule reads 'for her lesson on volcanoes'
    too: taken out as well.)"""
    CASES.refused_without(
        # session 42 (12r): its rules of the same families read these too
        (
            *normalise._STEPS37R,
            # session 51 (12r; at the merge): its rules of the same families read some of these too
            *normalise._STEPS51R,
            # session 53 (12s; at the merge): 'every last thing' said 'everything' reads it too
            _rewrites53s._every_single53s,
            *normalise._STEPS40S,
            *normalise._STEPS41S_FIRST,
            *normalise._STEPS42R,
            # session 43 (12r): its rules of the same families read these too
            *normalise._STEPS43R_FIRST,
            *normalise._STEPS43R,
            # session 44 (12r): its rules of the same families read some of these too
            *normalise._STEPS44R_FIRST,
            *normalise._STEPS44R,
            # session 50 (12r; lead at the merge): its 'any … at all' rule reads one of these too
            *normalise._STEPS50R_FIRST,
            *normalise._STEPS50R,
            # session 54 (12s, 12r; lead at the merge): 'the X can stay / leave … alone, it's the
            # Y', '…, no, sorry, she wanted the Y' read some of these too
            _rewrites54s._stays_cleft54s,
            *normalise._STEPS54R_FIRST,
            *normalise._STEPS54R,
        ),
        monkeypatch,
    )
