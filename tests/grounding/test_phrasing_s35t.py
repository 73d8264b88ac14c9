"""Session-35 phrasings of issue 12 (engineer 12t): blind19, blind23, blind18, blind17 and
causes15's refusals by kind; docs/grounding.md, "Session 35 (engineer 12t)". Each rule with the
sentences it changes and near forms that must stay refused (or read as they did)."""

from __future__ import annotations

import pytest

from hltl.grounding import normalise
from tests.grounding.helpers import CELL, CLASSROOM, KITCHEN, NURSERY, OFFICE, WARD, PhrasingCases

# the scenes of the numbered parts, as session 33 (12t) has them
from tests.grounding.test_phrasing_s33t import DUO, F41, SQ, T21, TWO

CASES = PhrasingCases()


# -- a person's state, 'and', then 'she' / 'he': the comma the same run-on has ----------------


test_state_and = CASES.test(
    (
        "so Lily's in her high chair now and she'll need her bib and the sippy cup can go to "
        "her as well thanks",
        "bib>A & beaker>A",
        NURSERY,
    ),
    ("Lily's awake and she'll need her bib", "bib>A", NURSERY),
    # negation in the state; the pronoun cannot be that person (kin word, title)
    ("Lily's not awake and she'll need her bib", None, NURSERY),
    ("Grandad's here and she'll need her bib", None, NURSERY),
    ("Mr Lee is awake and she needs the jug", None, WARD),
    # the state names an object: a want beside it, left as it was (refused)
    ("Lily's got the teddy and she wants the bib", None, NURSERY),
)


# -- 'he' / 'she' opening the clause after one person's clause: that person --------------------


test_subject_pronoun = CASES.test(
    (
        "Right, so Person A is thirsty, she needs the bottle, and Person B has been eyeing up "
        "the chips, he wants those.",
        "bottle>A & chips>B",
        SQ,
    ),
    (
        "Ruth wants the jug, and Mr Lee has been eyeing up the blue blanket, he wants that.",
        "jug>A & blanket_blue>B",
        WARD,
    ),
    # a reason after 'since' / 'because' (a typo in the name as the lexer reads it)
    (
        "the bottle is Person A's, and Perskn B gets the chips since he skipped lunch",
        "bottle>A & chips>B",
        DUO,
    ),
    (
        "Person A gets the bottle. Person B gets the chips because he skipped lunch.",
        "bottle>A & chips>B",
        DUO,
    ),
    (
        "the bottle is Person A's, and Person B gets the chips since she gave Person A the bottle",
        None,
        DUO,
    ),
    # after a full stop; another person in the clause before; a title that does not fit; a
    # person before whom the pronoun fits by title while this one's says nothing
    (
        "Person A needs the bottle, and Person B has been eyeing up the chips. He wants those.",
        None,
        SQ,
    ),
    (
        "Person A needs the bottle, and Person B is telling Person A about the chips, she "
        "wants those.",
        None,
        SQ,
    ),
    (
        "Ruth wants the jug, and Mr Lee has been eyeing up the blue blanket, she wants that.",
        None,
        WARD,
    ),
    (
        "Mr Lee wants the jug, and Ruth has been eyeing up the pills, he wants those.",
        None,
        WARD,
    ),
)


# -- a gapped passive: '… are wanted by P and the Y by Q' -------------------------------------


test_gapped_passive = CASES.test(
    ("The chips are wanted by Person A and the bottle by Person B.", "chips>A & bottle>B", T21),
    (
        "The chips are needed by Person A, and the bottle by Person B.",
        "chips>A & bottle>B",
        T21,
    ),
    # session 27's near forms (refused then, lest 'by Bob' read as where the crisps lie)
    ("The red mug is needed by Carol, and the crisps by Bob.", "mug_red>C & chips>B", CELL),
    ("The red mug is needed by Carol and the crisps by Bob.", "mug_red>C & chips>B", CELL),
    # no passive before it (session 28's both readings); one person twice; more after it
    ("Person A wants the chips and the bottle by Person B.", None, T21),
    ("The chips are wanted by Person A and the bottle by Person A.", None, T21),
    (
        "The chips are wanted by Person A and the bottle by Person B goes on the shelf.",
        None,
        T21,
    ),
)


# -- 'it's cluttering <the place it is now>' after putting it away -----------------------------


test_in_the_way = CASES.test(
    ("chuck the blue pen in the box its cluttering my desk", "pen_blue@box", OFFICE),
    ("Put the cup on the shelf, it's cluttering the counter", "cup@shelf", CELL),
    # where it goes; a person; two objects; a handing over; another object in the way
    ("Put the cup on the shelf, it's cluttering the shelf", None, CELL),
    ("chuck the blue pen in the box its cluttering Sam", None, OFFICE),
    ("chuck the blue pen and the red pen in the box its cluttering my desk", None, OFFICE),
    ("give Sam the blue pen its cluttering my desk", None, OFFICE),
    ("chuck the blue pen in the box the stapler is cluttering my desk", None, OFFICE),
)


# -- words said to someone else (closed lists) ------------------------------------------------


test_aside_else = CASES.test(
    (
        "Chef, sorry, behind you... oh, it's the robot. Could you kindly give the salt to Mr "
        "Novak? Thank you, sir.",
        "salt>C",
        KITCHEN,
    ),
    (
        "Yeah, hang on, Dave, I'm just telling the robot something. Robot, please hand Bob "
        "the bottle. Thanks. Sorry Dave, go on.",
        "bottle>B",
        TWO,
    ),
    # no realising it is the robot; an object in the call; the close to another name or
    # without the pause; a scene person paused for
    (
        "Chef, sorry, behind you... Could you kindly give the salt to Mr Novak? Thank you, sir.",
        None,
        KITCHEN,
    ),
    (
        "Chef, the salt, behind you... oh, it's the robot. Could you kindly give the lemon to "
        "Mr Novak?",
        None,
        KITCHEN,
    ),
    (
        "Yeah, hang on, Dave, I'm just telling the robot something. Robot, please hand Bob "
        "the bottle. Thanks. Sorry Sue, go on.",
        None,
        TWO,
    ),
    ("Robot, please hand Bob the bottle. Thanks. Sorry Dave, go on.", None, TWO),
    (
        "Yeah, hang on, Bob, I'm just telling the robot something. Robot, please hand Bob the "
        "bottle. Thanks. Sorry Bob, go on.",
        None,
        TWO,
    ),
)


# -- a person introduced by a name of their own: they are there -------------------------------


test_introduced = CASES.test(
    (
        "Mrs Khan is our new patient: the blue blanket for her, please",
        "blanket_blue>C",
        WARD,
    ),
    # another person's name; the pronoun the title rules out
    ("Mrs Khan is our new nurse: the blue blanket for her, please", None, WARD),
    ("Mrs Khan is our new patient: the blue blanket for him, please", None, WARD),
)


# -- 'with the Y' after the surface, Y already there --------------------------------------------

test_with_one_there = CASES.test(
    (
        "Any chance the red book could go up on the shelf with the green one?",
        "book_red@shelf",
        CLASSROOM,
    ),
    ("Put the red book on the shelf with the green book", "book_red@shelf", CLASSROOM),
    # Y not on that surface (it may ask to move Y too); the object moved itself
    ("Put the red book on the desk with the green one", None, CLASSROOM),
    ("Put the red book on the shelf with the globe", None, CLASSROOM),
    ("Put the green book on the shelf with the green one", None, CLASSROOM),
)


# -- a want of a drink, then the one object that holds it -------------------------------------

test_drink_in = CASES.test(
    (
        "Mrs Khan is due her medication, and Mr Lee wants some water, the jug please.",
        "pills>C & jug>B",
        WARD,
    ),
    ("Carol would like a brew, the blue mug please.", "mug_blue>C", CELL),
    # an object that holds no drink; two mugs; more after the object; no object at all
    ("Mr Lee wants some water, the grey blanket please.", None, WARD),
    ("Carol would like a brew, the mug please.", None, CELL),
    ("Mr Lee wants some water, the jug for Ruth please.", None, WARD),
    ("Priya wants a coffee", None, OFFICE),
)


# -- ', capisce?': a check that the request was understood ------------------------------------

test_understood = CASES.test(
    ("Pronto, the cup to Person A, capisce?", "cup>A", F41),
    ("The cup to Person A, savvy?", "cup>A", F41),
    # nothing before it; a request that does not read alone
    ("Capisce?", None, F41),
    ("The cup to the shelf, capisce?", None, F41),
)


# -- 'P can keep the X' of an object lying about: P is to have it -----------------------------

test_can_keep = CASES.test(
    (
        "Person B can keep the bottle, and the chips are for the other one, cheers.",
        "bottle>B & chips>A",
        DUO,
    ),
    ("Person B can keep the bottle.", "bottle>B", DUO),
    # a place after it; a person kept
    ("Person B can keep the bottle on the shelf.", None, DUO),
    ("Person B can keep Person A.", None, DUO),
)


def test_refused_without_these_steps(monkeypatch: pytest.MonkeyPatch) -> None:
    """Every sentence these rules read is refused with the session-35 (12t) steps taken out:
    each rule is what reads it."""
    CASES.refused_without(normalise._STEPS35T, monkeypatch)
