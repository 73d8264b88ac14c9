"""Session-31 phrasings of issue 12 (engineer 12s): doubtful readings found on main by the lead's
probes, each now a refusal naming why — a step waited for that nothing asks, a request the words
after it call wrong, 'has' beside a want, a reason whose pronoun a title rules out. Each rule
with the near forms it must still read (docs/grounding.md, "Session 31 (engineer 12s)")."""

from __future__ import annotations

import pytest

from hltl.world.scene import Scene
from tests.grounding.helpers import (
    CELL,
    DEPOT,
    KITCHEN,
    LAB,
    NURSERY,
    OFFICE,
    WARD,
    assert_reads,
    assert_refused,
)

# -- 'after the cup is done' with no step for the cup (offline.py _unasked_done31s) --------------


@pytest.mark.parametrize(
    "text",
    [
        # was cup>A ; chips>B ; apple>A: 'is done' taken as fillers, 'after the cup' as a step
        "Bob gets the chips, then Alice gets the apple after the cup is done",
        "Give Alice the apple once the cup is done.",
        "Give Alice the apple when the cup's done.",
        "Give Alice the apple after Bob's cup is done.",
        "Give Alice the apple as soon as the cup is over.",
        "Give Alice the apple after the cup has been done.",
    ],
)
def test_a_step_waited_for_that_nothing_asks_is_refused(text: str) -> None:
    assert_refused(text, CELL, match="waits for a step this instruction does not ask for")


@pytest.mark.parametrize(
    ("text", "want"),
    [
        # the step waited for is asked in the instruction
        ("Give Bob the cup, and once the cup is done, give Alice the apple", "cup>B ; apple>A"),
        ("Give Bob the cup, and once that is done, give Alice the apple", "cup>B ; apple>A"),
        # 'after the cup' (no 'is done'): the same person's step before (session 8)
        ("Give Alice the apple after the cup", "cup>A ; apple>A"),
        ("Give Alice the apple after the cup is on the shelf", "cup@shelf ; apple>A"),
        ("Once Bob has the cup, give Alice the apple", "cup>B ; apple>A"),
    ],
)
def test_near_forms_of_a_step_waited_for_read_as_before(text: str, want: str) -> None:
    assert_reads(text, want, CELL)


# -- the words after the request say it is wrong (offline.py _said_wrong31s) ----------------------


@pytest.mark.parametrize(
    "text",
    [
        # each was read as the request before it (the remark taken off)
        "Put the apple on the shelf. It is the wrong one.",
        "Put the apple on the shelf, it's the wrong one.",
        "Give Bob the cup, that's wrong.",
        "Give Bob the cup. That's the wrong cup.",
        "Give Bob the cup. It isn't the right one.",
        "Give Bob the cup. Oh, that looks like the wrong one!",
    ],
)
def test_a_request_said_to_be_wrong_is_refused(text: str) -> None:
    assert_refused(text, CELL, match="says it is wrong")


@pytest.mark.parametrize(
    ("text", "want"),
    [
        ("Give Bob the cup, it's the right one.", "cup>B"),
        ("Give Bob the cup, he's the right one to ask.", "cup>B"),
        # a correction after 'wrong' is read as a correction (session 27)
        ("Hand the chips to Alice, whoops, wrong one, I meant Bob.", "chips>B"),
    ],
)
def test_near_forms_of_a_request_said_to_be_wrong_read_as_before(text: str, want: str) -> None:
    assert_reads(text, want, CELL)


# -- 'has' beside a want (offline.py _has_beside_want31s) ----------------------------------------


@pytest.mark.parametrize(
    "text",
    [
        # was cup>B & apple>B: 'has' read as a request
        "Bob has the cup and wants the apple.",
        "Bob has the cup, he needs the apple.",
        "Bob has the cup. He wants the apple.",
        "Bob's got the cup, and he'd like the apple.",
        "Bob wants the apple and has the cup.",
        "Bob has the cup and Bob wants the apple.",
    ],
)
def test_has_beside_a_want_is_refused_with_both_readings(text: str) -> None:
    assert_refused(text, CELL, match="could say what .* already holds .* or that .* is to get")


@pytest.mark.parametrize(
    ("text", "want"),
    [
        # no want said: 'has' allots (blind13, blind21)
        ("Bob has the cup and Alice the apple.", "cup>B & apple>A"),
        ("Is it alright if Bob has the cup?", "cup>B"),
        # a condition: 'has' is the state waited for
        ("Once Bob has the cup, Alice wants the apple", "cup>B ; apple>A"),
        ("Bob wants the cup; once he has it, give Alice the apple", "cup>B ; apple>A"),
        ("Bob wants the apple and the cup.", "apple>B & cup>B"),
        # another person's want: 'has' allots, as session 27 (12r) reads "Marco's got the tongs,
        # and what Lena wants is the salt shaker"
        ("Alice wants the apple and Bob has the cup.", "apple>A & cup>B"),
    ],
)
def test_near_forms_of_has_read_as_before(text: str, want: str) -> None:
    assert_reads(text, want, CELL)


# -- a reason whose pronoun a title rules out (offline.py _ruled_out_dropped31s) -----------------


def test_a_reason_with_a_pronoun_the_title_rules_out_is_refused_with_its_readings() -> None:
    # was jug>B: session 21's rule took the reason off, 'she' with it
    assert_refused(
        "Give Mr Lee the jug, she's thirsty.",
        WARD,
        match=r"cannot mean Person B .*could mean Person A \(Ruth.*Person C \(Mrs Khan",
    )
    assert_refused(
        "Give Mrs Khan the magazine, he's bored.", WARD, match=r"cannot mean Person C .*by title"
    )


@pytest.mark.parametrize(
    ("text", "want"),
    [
        ("Give Mr Lee the jug, he's thirsty.", "jug>B"),
        ("Give Mrs Khan the jug, she's thirsty.", "jug>C"),
        ("Give Ruth the jug, she's thirsty.", "jug>A"),  # a name alone says nothing of sex
        ("Give Mr Lee the jug, it's hot in here.", "jug>B"),
    ],
)
def test_a_reason_whose_pronoun_fits_is_taken_off_as_before(text: str, want: str) -> None:
    assert_reads(text, want, WARD)


# -- a choice said to be fine for one person (normalise.py _will_do31s) --------------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        # each was refused ('will do' / 'is fine' unread)
        ("Any of the pens will do for Sam.", "pen_black>B | pen_blue>B | pen_red>B", OFFICE),
        ("Either of the pens is fine for Sam.", "pen_black>B | pen_blue>B | pen_red>B", OFFICE),
        ("Either mug's fine for Carol.", "mug_red>C | mug_blue>C", CELL),
        ("Either mug works for Carol.", "mug_red>C | mug_blue>C", CELL),
        ("Any of the mugs to Carol is fine.", "mug_red>C | mug_blue>C", CELL),
        (
            "Lily can have one of the blocks, either colour's fine.",
            "block_red>A | block_green>A",
            NURSERY,
        ),
    ],
)
def test_a_choice_said_to_be_fine_for_one_person_is_that_choice(
    text: str, want: str, scene: Scene
) -> None:
    assert_reads(text, want, scene)


@pytest.mark.parametrize(
    "text",
    [
        "Either of the mugs is fine for Carol and Bob.",  # two people: who gets it?
        "Give Carol the red mug, either colour's fine.",  # no choice before: a contradiction
        "Either of them is fine for Carol.",  # names no object
    ],
)
def test_near_forms_of_a_choice_said_to_be_fine_are_refused(text: str) -> None:
    assert_refused(text, CELL)


# -- 'both of those' before where they go (normalise.py _both_of31s) ------------------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        # each was refused ('Both of' unread)
        (
            "Black pen to Sam. Also the notepad. Both of those to him.",
            "pen_black>B & notebook>B",
            OFFICE,
        ),
        ("Give Alice the cup and the apple. Both of those to Alice.", "cup>A & apple>A", CELL),
        ("Both of them, the bottle and the cup, go to Alice.", "bottle>A & cup>A", CELL),
        ("Both, the bottle and the cup, to Alice.", "bottle>A & cup>A", CELL),
    ],
)
def test_both_of_those_is_the_two_named(text: str, want: str, scene: Scene) -> None:
    assert_reads(text, want, scene)


@pytest.mark.parametrize(
    "text",
    [
        "Both of them, the bottle, go to Alice.",  # one named: not both
        "Both of them, Alice and Bob, go to the shelf.",  # people, not things
        "Alice and Bob. Give both of them the cup.",
        "Give Alice the cup. Both of those to Bob.",  # one object before 'both'
    ],
)
def test_near_forms_of_both_of_those_are_refused(text: str) -> None:
    assert_refused(text, CELL)


# -- where the one object named is, and the question pointing at it (normalise.py
#    _where_it_is31s) -----------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        # each was refused ('by the window': no such place in the scene)
        (
            "You see the red mug by the window? Take it across to Alice, would you.",
            "mug_red>A",
            CELL,
        ),
        ("See the notepad by the phone? Drop it in the box.", "notebook@box", OFFICE),
        ("The cup by the door, give it to Alice.", "cup>A", CELL),
        ("You see the apple next to you? Bob needs it.", "apple>B", CELL),
        ("You see the apple? Bob needs it.", "apple>B", CELL),
    ],
)
def test_where_the_one_object_named_is_tells_nothing_more(
    text: str, want: str, scene: Scene
) -> None:
    assert_reads(text, want, scene)


@pytest.mark.parametrize(
    "text",
    [
        "You see the mug by the window? Take it across to Alice.",  # two mugs: which?
        "Put the cup by the window.",  # after a verb: where to put it
        "Give Alice the cup by the window.",
        "You see the mugs by the window? Take them to Alice.",
        "The cup by Bob, give it to Alice.",  # next to Bob, or Bob's?
    ],
)
def test_near_forms_of_where_an_object_is_are_refused(text: str) -> None:
    assert_refused(text, CELL)


# -- a negated reason after the request (normalise.py _negated_reason31s) -------------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        # each was refused for the negation
        (
            "Lily wants her teddy bear, she won't settle for the hymn practice without it.",
            "teddy>A",
            NURSERY,
        ),
        (
            "Dana's desperate for the banana, she hasn't eaten since six this morning.",
            "banana>A",
            LAB,
        ),
        ("Give Bob the cup, it isn't urgent.", "cup>B", CELL),
        ("Give Bob the cup, it doesn't belong there.", "cup>B", CELL),
    ],
)
def test_a_negated_reason_after_the_request_is_taken_off(
    text: str, want: str, scene: Scene
) -> None:
    assert_reads(text, want, scene)


@pytest.mark.parametrize(
    ("text", "scene"),
    [
        ("Give Dana the banana, she doesn't like this one.", LAB),  # which one
        ("Give Dana the banana, she hasn't had that today.", LAB),
        ("Give Bob the cup, she won't mind.", CELL),
        ("Give Bob the cup, he's not having the apple.", CELL),  # names an object
        ("Give Bob the cup, it isn't his.", CELL),  # whose it is
        ("Give Bob the cup, he hasn't got one.", CELL),
        ("Give Bob a mug, it isn't the blue one.", CELL),
        ("Give Bob a mug, he can't stand blue.", CELL),  # a word of a scene name: which mug
    ],
)
def test_a_negation_that_could_change_the_request_is_not_taken_off(text: str, scene: Scene) -> None:
    assert_refused(text, scene)


# -- 'do likewise', 'straight after', '… both' (normalise.py _said_otherwise31s) ------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        # each was refused
        (
            "Haul the medium box onto the belt, then do likewise with the small one, smartly.",
            "box_medium@conveyor ; box_small@conveyor",
            DEPOT,
        ),
        (
            "Small box onto the conveyor first, please, and the medium one straight after.",
            "box_small@conveyor ; box_medium@conveyor",
            DEPOT,
        ),
        (
            "Hand the cup over to Bob and do likewise for Carol with the chips.",
            "cup>B & chips>C",
            CELL,
        ),
        ("Give Bob the cup and the apple both.", "cup>B & apple>B", CELL),
        ("Put the cup on the shelf please love.", "cup@shelf", CELL),
        ("Both plates are for Marco this morning!", "plate_white>A & plate_blue>A", KITCHEN),
        ("Give Marco the knife this morning.", "knife>A", KITCHEN),
    ],
)
def test_words_the_grammar_reads_said_another_way(text: str, want: str, scene: Scene) -> None:
    assert_reads(text, want, scene)


@pytest.mark.parametrize(
    ("text", "scene"),
    [
        ("Small box onto the conveyor, and the medium one straight after lunch.", DEPOT),  # later
        ("Give the cup to Bob and Alice both.", CELL),  # two people: 'both' counts no objects
        ("Marco had the knife this morning.", KITCHEN),  # what was, not what to do
        ("Give Marco the knife this afternoon.", KITCHEN),  # later: put off (session 20)
    ],
)
def test_near_forms_said_another_way_are_refused(text: str, scene: Scene) -> None:
    assert_refused(text, scene)
