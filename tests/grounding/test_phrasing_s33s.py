"""Session-33 phrasings of issue 12 (engineer 12s): doubtful readings found on main by the lead's
probes and the fuzz — a remark that undercuts the request or its correction, 'leave' with a
place then 'it', an owner said alone, 'the other' after a taken-back 'a mug', 'them' after a
choice, a gapped possessive taken for a remark — each now the reading a careful person gives or
a refusal naming the readings. Each rule with the near forms it must leave as they were
(docs/grounding.md, "Session 33 (engineer 12s)")."""

from __future__ import annotations

import re

import pytest

from tests.grounding.helpers import (
    CELL,
    DEPOT,
    NURSERY,
    OFFICE,
    WARD,
    WORKSHOP,
    assert_reads,
    assert_refused,
)

# -- a remark that says the person who gets it does not take it (offline.py _said_against33s) ---


@pytest.mark.parametrize(
    "text",
    [
        # was chips>B: the reason contradicts the correction
        "Crisps to Alice, sorry, I mean Bob, Bob is off crisps.",
        "Crisps to Alice, sorry, I mean Bob, he is off crisps.",
        "Crisps to Alice, no, Bob, Bob's off the crisps.",
        "Give Bob the crisps, Bob is off crisps.",
        # was chips>B: a statement that asks for nothing
        "Bob is off crisps.",
    ],
)
def test_a_person_off_what_they_get_is_refused(text: str) -> None:
    assert_refused(text, CELL, match="says Person B does not take the chips")


def test_the_refusal_names_the_correction_s_other_reading() -> None:
    assert_refused(
        "Crisps to Alice, sorry, I mean Bob, Bob is off crisps.",
        CELL,
        match="to go to Person B, or to Person A",
    )


@pytest.mark.parametrize(
    ("text", "want"),
    [
        # the remark is about the person the correction takes the crisps from (blind24)
        ("Crisps to Alice, sorry, I mean Bob, Alice is off crisps.", "chips>B"),
        ("Chips to Person A, actually, make that the bottle, she's off salt.", "bottle>A"),
        # 'off' before no object is no remark about one
        ("Give Bob the crisps, he's off to the match.", "chips>B"),
    ],
)
def test_near_forms_of_off_read_as_before(text: str, want: str) -> None:
    assert_reads(text, want, CELL)


# -- a remark closing the instruction that says the person holds one already ---------------------


@pytest.mark.parametrize(
    "text",
    [
        # was cup>B
        "Give Bob the cup, he's got one already.",
        "Give Bob the cup, he has one.",
        "Give Bob the cup, because he has it already.",
        "Give Bob the cup, Bob's got one.",
    ],
)
def test_a_recipient_said_to_have_one_is_refused(text: str) -> None:
    assert_refused(text, CELL, match="says Person B already has one, yet the request gives the cup")


def test_a_corrected_recipient_said_to_have_one_is_refused_with_both_readings() -> None:
    # was stapler>B: decided refused (the remark undercuts the correction; keeping Priya would
    # be a guess as well), naming both people
    assert_refused(
        "Stapler to Priya, no, to Sam, Sam's got one.",
        OFFICE,
        match="still to go to Person B, or to Person A",
    )


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        # the remark is about the person the correction takes the object from
        ("Stapler to Priya, no, to Sam, Priya's got one.", "stapler>B", OFFICE),
        ("Give the bottle to Bob, no wait, Bob's got one, to Alice.", "bottle>A", CELL),
        # a condition, not a remark
        ("Chips for Bob, and once he has them, the bottle for Alice.", "chips>B ; bottle>A", CELL),
    ],
)
def test_near_forms_of_holding_one_read_as_before(text: str, want: str, scene: object) -> None:
    assert_reads(text, want, scene)  # type: ignore[arg-type]


# -- 'leave' with a place, then 'it' (offline.py _left_then_it32s, session 33) ------------------


@pytest.mark.parametrize(
    "text",
    [
        # was teddy@mat & teddy>A
        "Leave the teddy on the mat; give it to Lily.",
        "Leave the teddy on the mat and then give it to Lily.",
        "Leave the teddy in the high chair, give it to Ava.",
    ],
)
def test_leave_on_a_place_then_it_is_refused_with_both_readings(text: str) -> None:
    assert_refused(text, NURSERY, match="is the teddy to stay .*, or to go .* and then be moved")


@pytest.mark.parametrize(
    ("text", "want"),
    [
        ("Put the teddy on the mat; give it to Lily.", "teddy@mat & teddy>A"),
        ("Leave the teddy on the mat.", "teddy@mat"),
        ("Leave the teddy on the mat; give the bib to Lily.", "teddy@mat & bib>A"),
    ],
)
def test_near_forms_of_leave_on_read_as_before(text: str, want: str) -> None:
    assert_reads(text, want, NURSERY)


# -- an owner said alone (offline.py _owner_only33s) ---------------------------------------------


@pytest.mark.parametrize("text", ["The spanners are Jess's!", "The spanners are Jess's."])
def test_an_owner_said_alone_is_refused_with_both_readings(text: str) -> None:
    # several things: whose both are, or that both go to Jess (session 42: one thing reads)
    assert_refused(text, WORKSHOP, match="could say whose the .* (is|are) .* or that the")


@pytest.mark.parametrize(
    ("text", "want"),
    [
        # session 42 (the lead's possession policy, 2026-12-06): one scene thing said to be one
        # scene person's is a handover to the owner (three blind writers read it so; session 33
        # had refused it naming both readings)
        ("The drill is Jess's.", "drill>B"),
        ("The drill's Jess's.", "drill>B"),
        ("The drill is Jess's, please.", "drill>B"),
        # beside another part it allots (blind30)
        (
            "The drill is Jess's, the torch goes in the locker, and that's the lot.",
            "drill>B & torch@locker",
        ),
        ("The drill is for Jess.", "drill>B"),
    ],
)
def test_near_forms_of_an_owner_read_as_before(text: str, want: str) -> None:
    assert_reads(text, want, WORKSHOP)


# -- 'the other' after a taken-back 'a mug' (offline.py _other_after_repair33s) -----------------


@pytest.mark.parametrize(
    "text",
    [
        # was mug_red>B | mug_blue>B
        "Give Alice a mug, no, give Bob the other one",
        "Give Alice a mug. No, give Bob the other one.",
        "Give Alice one of the mugs, sorry, give Bob the other mug",
    ],
)
def test_the_other_after_a_taken_back_indefinite_is_refused(text: str) -> None:
    assert_refused(text, CELL, match="could mean mug_red or mug_blue")


@pytest.mark.parametrize(
    ("text", "want"),
    [
        ("Give Alice the red mug, no, give Bob the other one", "mug_blue>B"),
        (
            "Give Alice a mug and Bob the other one",
            "(mug_red>A & mug_blue>B) | (mug_blue>A & mug_red>B)",
        ),
    ],
)
def test_near_forms_of_the_other_read_as_before(text: str, want: str) -> None:
    assert_reads(text, want, CELL)


# -- 'them' after a choice (offline.py _them_after_choice33s) ------------------------------------


@pytest.mark.parametrize(
    "text",
    [
        # was cup>A & apple>A
        "Whichever you can reach first, the cup or the apple, hand them to Person A.",
        "Either the cup or the apple, give them to Bob",
        "The cup or the apple, hand them to Person A.",
    ],
)
def test_them_after_a_choice_is_refused_with_both_readings(text: str) -> None:
    assert_refused(text, CELL, match="could mean the one chosen or both")


@pytest.mark.parametrize(
    ("text", "want"),
    [
        (
            "Whichever you can reach first, the cup or the apple, hand it to Person A.",
            "cup>A | apple>A",
        ),
        ("The cup and the apple, hand them to Person A.", "cup>A & apple>A"),
    ],
)
def test_near_forms_of_them_after_a_list_read_as_before(text: str, want: str) -> None:
    assert_reads(text, want, CELL)


# -- a gapped possessive after a remark (normalise.py _inert_statement32s, session 33) -----------


@pytest.mark.parametrize(
    "text",
    [
        # was bottle>B & chips>B (the afterthoughts fuzz): ", Alice's" taken off as a statement
        "Alice is starving. The bottle's Bob's to take out on the trawler; the crisps, Alice's.",
        "The bottle's Bob's to take out on the trawler; the crisps, Alice's.",
    ],
)
def test_a_gapped_possessive_keeps_its_owner(text: str) -> None:
    assert_reads(text, "bottle>B & chips>A", CELL)


def test_a_closing_statement_is_still_taken_off() -> None:
    assert_reads("Give Bob the crisps, he's doing the rounds next door.", "chips>B", CELL)


# -- a greeting sentence that asks nothing (normalise.py _greeting_said33s) ----------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        # each was refused (blind21, blind22): the greeting's sentence says who the speaker is
        (
            "Hello, paramedic, just dropping off some paperwork for the manager. Would you mind "
            "passing Sam the notepad?",
            "notebook>B",
            OFFICE,
        ),
        (
            "Morning, it's the dentist up from outpatients. Could you set the magazine down on "
            "the bedside locker?",
            "magazine@bedside",
            WARD,
        ),
        (
            "Hello, sorry, I'm the tailor, I've come to measure the manager for her suit. Pass "
            "Priya the red pen.",
            "pen_red>A",
            OFFICE,
        ),
        ("Hiya, I'm the plumber from upstairs. Hand Bob the crisps.", "chips>B", CELL),
    ],
)
def test_a_greeting_sentence_goes(text: str, want: str, scene: object) -> None:
    assert_reads(text, want, scene)  # type: ignore[arg-type]


def test_a_greeting_sentence_with_a_want_keeps_it() -> None:
    assert_reads("Morning, Bob wants the cup. Hand Alice the crisps.", "cup>B & chips>A", CELL)


@pytest.mark.parametrize(
    "text",
    [
        # the greeting's sentence points at a thing, asks, or names an object: not taken off
        "Morning, it's for Bob. Hand Alice the crisps.",
        "Hello, don't give Bob anything. Hand Alice the crisps.",
        "Hello, I'm after the apple. Hand Alice the crisps.",
        # a person named in a terse part or a want: it may allot or ask
        "Morning, for Alice. Give Bob the cup.",
        "Morning, Alice next. Give Bob the cup.",
        "Hello, Alice is after a drink. Give Bob the cup.",
        "Hi, to Alice. Give Bob the cup.",
    ],
)
def test_a_greeting_sentence_that_says_something_is_not_dropped(text: str) -> None:
    assert_refused(text, CELL)


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        (
            "Would you be a good sort and hand Jess the torch? Much appreciated.",
            "torch>B",
            WORKSHOP,
        ),
        ("When you get a tick, could the packing tape go on the belt?", "tape@conveyor", DEPOT),
    ],
)
def test_courtesy_frames_with_a_kind_word(text: str, want: str, scene: object) -> None:
    assert_reads(text, want, scene)  # type: ignore[arg-type]


def test_a_kind_word_frame_is_not_a_name() -> None:
    assert_refused("Would you be a good hammer and hand Jess the torch?", WORKSHOP)


# -- a choice made by what is to hand; a closer; an idiom in a closing statement -----------------


@pytest.mark.parametrize(
    ("text", "want"),
    [
        # each was refused (blind21, blind22)
        ("Either mug to Bob, whichever's closer to hand.", "mug_red>B | mug_blue>B"),
        ("The cup or the apple for Bob, whichever is closer to your hand.", "cup>B | apple>B"),
        ("Give Alice the cup. The crisps, Bob. Ready when you are.", "cup>A & chips>B"),
        ("Bob desperately needs the crisps, his tea is all over the place.", "chips>B"),
    ],
)
def test_blind21_22_kinds_read(text: str, want: str) -> None:
    assert_reads(text, want, CELL)


def test_whichever_to_hand_after_one_object_is_still_refused() -> None:
    # nothing to choose from: 'closer to hand' is no choice of the robots'
    assert_refused("Hand Bob the cup, whichever's closer to hand.", CELL)


def test_all_outside_the_idiom_still_counts() -> None:
    # 'all' in a closing statement may count what is asked: the statement stays (refused)
    assert_refused("Bob desperately needs the crisps, he's eaten all the rest.", CELL)


@pytest.mark.parametrize(
    ("text", "want"),
    [
        # each was refused (blind21)
        ("Please, you help me, give the crisps to Alice.", "chips>A"),
        (
            "Alice wants the cup. Bob wants the crisps. Sort the pair of them out.",
            "cup>A & chips>B",
        ),
        ("Nothing for Alice today; the crisps go to Bob.", "chips>B"),
    ],
)
def test_more_blind21_kinds_read(text: str, want: str) -> None:
    assert_reads(text, want, CELL)


def test_nothing_for_today_still_refuses_what_it_rules_out() -> None:
    # the request after it gives the person something: not taken off (refused)
    assert_refused("Nothing for Alice today; the crisps go to Alice.", CELL)


@pytest.mark.parametrize(
    ("text", "want"),
    [
        # each was refused (blind22; blind23's crane entry reads too)
        ("Crisps. Bob. Quick as you like, he's on stage in five.", "chips>B"),
        ("Crisps to Bob, quick as you like.", "chips>B"),
        ("Crisps to Bob, he's on stage in ten minutes.", "chips>B"),
    ],
)
def test_quick_as_you_like_and_in_five(text: str, want: str) -> None:
    assert_reads(text, want, CELL)


# -- refusals that name their readings (offline.py _more_readings33s) ----------------------------


@pytest.mark.parametrize(
    ("text", "scene", "readings"),
    [
        # each was refused without its readings (blind21, blind22, blind31)
        ("Hand that over to Alice when you're ready.", CELL, "'it' could mean cup or bottle"),
        (
            "Bob spoke of the cup and the apple. Please, give it to her now.",
            CELL,
            "'it' could mean cup or apple",
        ),
        (
            "Priya came by looking for her pen. Could you take it back to her?",
            OFFICE,
            "'pen' could mean pen_black or pen_blue or pen_red",
        ),
        ("Mug to Carol. The one she likes. You know the one I mean.", CELL, "mug_blue or mug_red"),
        (
            "Put one of the mugs on the shelf, the one Bob put a sticker on.",
            CELL,
            "mug_blue or mug_red",
        ),
        (
            "One of them gets the crisps, no idea which, you'll have to ask.",
            CELL,
            "'one of them' could mean Person A (Alice) or Person B (Bob) or Person C (Carol)",
        ),
    ],
)
def test_refusals_name_their_readings(text: str, scene: object, readings: str) -> None:
    assert_refused(text, scene, match=re.escape(readings))  # type: ignore[arg-type]


def test_a_shared_role_is_named_with_its_people() -> None:
    assert_refused(
        "The patient by the window wants the jug, can you take it over?",
        WARD,
        match=re.escape("'patient' could mean Person B (Mr Lee, patient) or Person C"),
    )


@pytest.mark.parametrize(
    ("text", "want"),
    [
        # readings are only added to refusals: what reads stays read
        ("Hand the cup over to Alice when you're ready.", "cup>A"),
    ],
)
def test_readings_never_make_a_reading(text: str, want: str) -> None:
    assert_reads(text, want, CELL)


# -- a list asked as a question; a cleft naming the corrected person; 'alright' ------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        # each was refused (blind22, blind20)
        (
            "Could the cup and the apple both go on the shelf, please?",
            "cup@shelf & apple@shelf",
            CELL,
        ),
        ("Can the cup and the apple go on the shelf?", "cup@shelf & apple@shelf", CELL),
        ("Crisps to Alice, no, Bob's the one doing the dishes.", "chips>B", CELL),
        (
            "Alright mate, van driver here, I've got five minutes till my next run. Be a legend "
            "and chuck the packing tape on the belt, cheers.",
            "tape@conveyor",
            DEPOT,
        ),
    ],
)
def test_batch2_kinds_read(text: str, want: str, scene: object) -> None:
    assert_reads(text, want, scene)  # type: ignore[arg-type]


@pytest.mark.parametrize(
    "text",
    [
        # a person in the list, or a word the scene does not hold: not the statement
        "Could Bob and the cup go on the shelf?",
        # the cleft names the scene or says something of the request: left (refused)
        "Crisps to Alice, no, Bob's the one sitting by the apple.",
        "Crisps to Alice, no, Bob's the one who is allergic.",
        # 'till' not the speaker's own time
        "Alright, wait till Carol's here. Hand Bob the cup.",
    ],
)
def test_batch2_near_forms_stay_refused(text: str) -> None:
    assert_refused(text, CELL)
