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

from hltl.world.scene import Scene, load_scene
from tests.grounding.helpers import (
    CELL,
    CLASSROOM,
    DEPOT,
    KITCHEN,
    LAB,
    OFFICE,
    assert_reads,
    assert_refused,
)

EXAMPLES = Path(__file__).resolve().parents[2] / "examples/scenes"
ONE, SQUARE, LINE, L24 = (
    load_scene(EXAMPLES / f"{n}.yaml") for n in ("1-1", "4-4-square", "4-4-line", "2-4-line")
)

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
        "The plate that's not on the rack goes to Mr Novak.",
    ],
)
def test_the_plate_off_the_rack_is_read_without_a_time(text: str) -> None:
    assert_reads(text, "plate_white>C", KITCHEN)


def test_the_object_said_again_after_the_surface() -> None:
    # blind20 (12r's rewrite leaves "the book that isn't on the bookshelf give it to Zoe")
    assert_reads(
        "The book that's lying about, not the one up on the bookshelf, is Zoe's, give it her.",
        "book_red>C",
        CLASSROOM,
    )


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
            # session 36 (12s): the others named leave out whom a first name says is of the
            # other sex (Carol): only Bob
            r"cannot mean Alice \(a woman's name\); it could mean Person B \(Bob\); name",
        ),
        ("Alice is off to work, so give him the bottle", "cannot mean Alice"),
        ("Give Bob the cup, she's thirsty", r"cannot mean Bob \(a man's name\)"),
        ("Alice and Carol are out, so he is having the bottle", "is not resolved"),
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
        # the repair wins (Priya is Person A)
        ("The stapler is for Sam, er, I mean Priya.", "stapler>A"),
        ("The stapler is for Priya, er, I mean Sam.", "stapler>B"),
    ],
)
def test_a_repair_in_a_statement_wins(text: str, want: str) -> None:
    assert_reads(text, want, OFFICE)


# Session 36 (lead): asked as a question, a repair leaves it a question, as "The stapler is for
# Priya?" is (session 32's "…, sorry, Priya?"); a filler before the repair had let "…, er, I mean
# Priya?" read, and 12c's repairs fuzz found "…, uh, no, Priya?" read the same way
@pytest.mark.parametrize(
    "text",
    ["The stapler is for Sam, er, I mean Priya?", "The stapler is for Priya, er, I mean Sam?"],
)
def test_a_repair_in_a_question_is_no_request(text: str) -> None:
    assert_refused(text, OFFICE, match="is a question")


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


# -- blind21/22: a correction's cue said with the slip, 'not X', or thinking aloud --------------


@pytest.mark.parametrize(
    "text",
    [
        # blind22 (normalise.py _RESTATE20: 'no, (my) mistake' before the request said again)
        "Sorry, sorry, bottle go to Person B... no, mistake, krap, it is for Person A.",
        "Bottle to Person B, no, my mistake, it is for Person A.",
        "Bottle to Person B, no, mistake, it is for Person A.",
    ],
)
def test_no_mistake_before_the_request_again(text: str) -> None:
    assert_reads(text, "bottle>A", LINE)


@pytest.mark.parametrize(
    "text",
    [
        # nothing after the cue, or no cue before 'mistake', or what follows names no person
        "Bottle to Person B, no, mistake.",
        "Bottle to Person B, mistake, it is for Person A.",
        "Bottle to Person B, no, mistake, it is for the chips.",
    ],
)
def test_mistake_without_a_correction_stays_refused(text: str) -> None:
    assert_refused(text, LINE)


@pytest.mark.parametrize(
    ("text", "want"),
    [
        # blind22 (_correction_cue33r: 'sorry, not X, Y' as 'no, not X, Y'; _corrections19: the
        # word of address after 'my mistake' said with 'my' and no comma)
        ("Give Person A the chips, sorry, not chips, the cup, my mistake my friend.", "cup>A"),
        ("Give Person A the chips, sorry, not the chips, the cup.", "cup>A"),
        ("Give Person A the chips, sorry, not Person A, Person B.", "chips>B"),
        ("Give Person A the chips, no, the cup, my mistake my friend.", "cup>A"),
        ("Give Person A the chips, no, the cup, my mistake, my friend.", "cup>A"),
    ],
)
def test_sorry_not_x_corrects(text: str, want: str) -> None:
    assert_reads(text, want, SQUARE)


def test_sorry_not_what_was_not_asked_stays_refused() -> None:
    # 'not the apple' takes back nothing the request said
    assert_refused("Give Person A the chips, sorry, not the apple, the cup.", SQUARE)


@pytest.mark.parametrize(
    "text",
    [
        # blind22 (_SAID14: thinking aloud before a correction's cue)
        "Person A gets the chips, hang on, let me check my list, no, Person B gets the chips.",
        "Person A gets the chips, hang on, let me think, no, Person B gets the chips.",
    ],
)
def test_thinking_aloud_before_a_correction(text: str) -> None:
    assert_reads(text, "chips>B", L24)


@pytest.mark.parametrize(
    "text",
    [
        "Person A gets the chips, let me check my list.",
        "Person A gets the chips, let me check my list, Person B gets the chips.",
    ],
)
def test_let_me_check_without_a_cue_stays_refused(text: str) -> None:
    assert_refused(text, L24)


# -- blind22: a remark said without its 'is' (normalise.py _zero_copula34s) ---------------------

F41 = load_scene(EXAMPLES / "4-1.yaml")


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        ("Person B want the apple lah, she hungry already since morning.", "apple>B", F41),
        ("Person B want the apple, she hungry.", "apple>B", F41),
        ("Give Alice the apple, she hungry, give Bob the cup.", "apple>A & cup>B", CELL),
    ],
)
def test_a_state_without_is_is_a_remark(text: str, want: str, scene: Scene) -> None:
    assert_reads(text, want, scene)


@pytest.mark.parametrize(
    ("text", "scene"),
    [
        # a state that names something of the scene is no remark; nor a role said after 'she'
        ("Person B want the apple, she hungry for the chips.", F41),
        ("Person B want the apple, she the hungry one.", F41),
        # the pronoun no person named may be (_named_other_sex34s)
        ("Give Alice the apple, he hungry.", CELL),
    ],
)
def test_a_state_without_is_that_says_more_stays_refused(text: str, scene: Scene) -> None:
    assert_refused(text, scene)


# -- blind22: 'the one at the sink' says where a person is (normalise.py _where_they_are) -------


@pytest.mark.parametrize(
    "text",
    [
        "Omar's the one at the sink, so the sponge, give it to him, he'll know what to do.",
        "Omar's the one at the sink, so give him the sponge.",
        "Omar's the one standing at the sink, so give him the sponge.",
    ],
)
def test_the_one_at_a_surface_is_where_they_are(text: str) -> None:
    assert_reads(text, "sponge>B", LAB)


@pytest.mark.parametrize(
    "text",
    [
        # the request points at a place: the surface may be it
        "Omar's the one at the sink, so put the sponge there.",
        # the remark names an object
        "Omar's the one with the sponge, so give him the bowl.",
    ],
)
def test_the_one_with_a_place_or_object_said_stays_refused(text: str) -> None:
    assert_refused(text, LAB)


# -- blind21: 'nothing else will do for her' closing the request (normalise.py _closers19) -----

FIG1 = load_scene(EXAMPLES / "fig1.yaml")


@pytest.mark.parametrize(
    "text",
    [
        "What Alice wants is the crisps, honestly nothing else will do for her.",
        "Alice wants the crisps, nothing else will do for her.",
        "Give Alice the crisps, nothing else will do for her.",
        "Alice wants the crisps, nothing more for her.",
    ],
)
def test_nothing_else_for_her_closes(text: str) -> None:
    assert_reads(text, "chips>A", FIG1)


def test_nothing_else_for_a_name_stays_refused() -> None:
    # a name is not said again: it may be another person's request
    assert_refused("Alice wants the crisps, nothing else will do for Bob.", FIG1)


# -- blind22: 'she said apple' said again after the correction (normalise.py _said_object34s) ---


@pytest.mark.parametrize(
    "text",
    [
        "Give Alice the cup, no wait, the apple, she said apple, I'm sure of it.",
        "Give Alice the cup, no wait, the apple, she said apple.",
        "Give Alice the apple, she said apple.",
    ],
)
def test_she_said_the_object_again(text: str) -> None:
    assert_reads(text, "apple>A", CELL)


@pytest.mark.parametrize(
    "text",
    [
        # what she said is the object the correction took back
        "Give Alice the cup, no wait, the apple, she said the cup.",
        # 'he' cannot be Alice (_named_other_sex34s)
        "Give Alice the cup, no wait, the apple, he said apple.",
    ],
)
def test_she_said_another_object_stays_refused(text: str) -> None:
    assert_refused(text, CELL)


# -- blind21: 'straight to P', and the object said alone with 'first' (normalise.py _straight34s,
# _over_to30) -----------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("text", "want"),
    [
        (
            "Apple first. Straight to Alice. After that, cup, up on the shelf, and we're square.",
            "apple>A ; cup@shelf",
        ),
        ("Take the apple straight to Alice.", "apple>A"),
        ("Apple straight to Alice.", "apple>A"),
        ("Put the cup straight onto the shelf.", "cup@shelf"),
        ("Give Alice the apple straight away.", "apple>A"),
        ("Apple first. To Alice.", "apple>A"),
        ("Apple first. To Alice. Then the cup to Bob.", "apple>A ; cup>B"),
        # blind18
        ("Bottle first. To Alice. After, chips to Bob.", "bottle>A ; chips>B"),
        ("The apple. Straight to Alice.", "apple>A"),
    ],
)
def test_straight_to_and_an_object_first(text: str, want: str) -> None:
    assert_reads(text, want, CELL)


@pytest.mark.parametrize(
    "text",
    [
        # no object before where it goes
        "Straight to Alice.",
        "Bob. To Alice.",
    ],
)
def test_where_without_an_object_stays_refused(text: str) -> None:
    assert_refused(text, CELL)


# -- a task the correction took back, asked for again (offline.py _asked_again34s) ------------


@pytest.mark.parametrize(
    "text",
    [
        # was apple>A & cup>A: the want after the correction gives the cup back
        "Give Alice the cup, no wait, the apple, she asked for the cup.",
        "Give Alice the cup, no, the apple, she wants the cup.",
        "Give Alice the cup, no, the apple, then give Alice the cup.",
    ],
)
def test_a_task_taken_back_asked_again_is_refused(text: str) -> None:
    assert_refused(text, CELL, match="the correction takes the cup back from Person A")


@pytest.mark.parametrize(
    ("text", "want"),
    [
        ("Give Alice the cup, no, the apple.", "apple>A"),
        ("Give Alice the cup, no, to Bob.", "cup>B"),
        # the cup to someone else, and a want with no correction before it
        ("Give Alice the cup, no, the apple, and give Bob the cup.", "apple>A & cup>B"),
        ("Give Alice the apple, she asked for the cup.", "apple>A & cup>A"),
        # the correction taken back in turn (causes10); 'no X for him' is no correction (blind16)
        ("Give Alice the cup. Sorry, I mean the apple. No, actually the cup was right.", "cup>A"),
        ("Bob wants the crisps, no bottle for him tho", "chips>B"),
        # a closing 'sorry.' is no correction (the lead's session-34 rule reads what follows)
        ("Give Alice the cup, sorry. Give Alice the apple.", "cup>A & apple>A"),
    ],
)
def test_a_correction_and_another_task_read(text: str, want: str) -> None:
    assert_reads(text, want, CELL)


# -- blind21: a deadline about the object, met by doing it now (normalise.py _when) ------------

TWO = load_scene(EXAMPLES / "two_arms.yaml")


@pytest.mark.parametrize(
    "text",
    [
        "Pop the cjips up on the shelf before the kids find them.",
        "Pop the chips up on the shelf before the kids eat them.",
        "Put the chips on the shelf before they find them.",
    ],
)
def test_a_deadline_about_the_object(text: str) -> None:
    assert_reads(text, "chips@shelf", TWO)


@pytest.mark.parametrize(
    ("text", "match"),
    [
        # a later time puts it off; a task verb may be one more task
        ("Put the chips on the shelf before the kids find them tomorrow.", "tomorrow"),
        ("Put the chips on the shelf before Bob takes them.", None),
    ],
)
def test_a_deadline_with_a_time_or_a_task_stays_refused(text: str, match: str | None) -> None:
    assert_refused(text, TWO, match=match)


# -- blind21: 'a snack, the chips' (normalise.py _kind_before34s) -------------------------------

F42 = load_scene(EXAMPLES / "4-2.yaml")


@pytest.mark.parametrize(
    ("text", "want"),
    [
        ("Person B wants a snack, the xhips please.", "chips>B"),
        ("Person B wants a drink, the bottle please.", "bottle>B"),
    ],
)
def test_a_kind_then_the_object(text: str, want: str) -> None:
    assert_reads(text, want, F42)


@pytest.mark.parametrize(
    "text",
    [
        # no object after the kind, or a person after it
        "Person B wants a snack.",
        "Person B wants a snack, Person A the chips.",
    ],
)
def test_a_kind_alone_stays_refused(text: str) -> None:
    assert_refused(text, F42)


# -- blind21: an apology's excuse opening the text (normalise.py _sorry_excuse34s) -------------

DUO = load_scene(EXAMPLES / "2-2.yaml")


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        ("Sorry, cold hands, give Person A the applw.", "apple>A", LINE),
        ("sorry typing one handed, chips to person b", "chips>B", DUO),
    ],
)
def test_an_apology_s_excuse_goes_with_it(text: str, want: str, scene: Scene) -> None:
    assert_reads(text, want, scene)


@pytest.mark.parametrize(
    ("text", "scene"),
    [
        # nothing after the excuse; an object, a pointing word, a request, a count in it
        ("Sorry, cold hands.", LINE),
        ("Sorry, the apple, give Person A the cup.", LINE),
        ("Sorry, wrong one, give Person A the cup.", LINE),
        ("Sorry, hand it over, give Person A the cup.", LINE),
        ("sorry, one more, chips to person b", DUO),
    ],
)
def test_an_apology_with_more_stays_refused(text: str, scene: Scene) -> None:
    assert_refused(text, scene)


@pytest.mark.parametrize(
    "text",
    [
        # the tests of sessions 5, 10, 11, 21, 26 and 28 that said 'her' / 'she' of Bob now say
        # 'him' / 'he' (a name then said no sex); said as before, it is refused
        "Bob is hungry, give her the chips",
        "Give one of the cup or the apple to Bob, any, she does not care.",
        "Give Bob the bottle, seeing as she's steaming felt.",
        "Chips to Alice and the cup to Carol, given that he's tired.",
    ],
)
def test_the_old_tests_pronouns_are_refused(text: str) -> None:
    assert_refused(text, CELL, match="cannot mean")
