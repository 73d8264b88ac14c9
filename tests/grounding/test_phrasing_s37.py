"""Session-37 phrasings of issue 12 (engineer 12): blind35's refusals by kind in its sections of
politeness, wants, pronouns and ellipsis, sentence splits, lower case, typos and questions
(docs/grounding.md, "Session 37 (engineer 12)"). Each rule with sentences it reads (which fail
with the rules taken out) and near sentences that must stay refused."""

from __future__ import annotations

import pytest

from hltl.grounding import normalise
from tests.grounding.helpers import (
    CELL,
    CLASSROOM,
    DEPOT,
    KITCHEN,
    LAB,
    NURSERY,
    OFFICE,
    WARD,
    PhrasingCases,
)
from tests.grounding.test_phrasing_s30r import F42
from tests.grounding.test_phrasing_s33t import DUO, F41, FIG1, L44, ONE, SQ, T12, T21, TWO
from tests.grounding.test_phrasing_s40 import POSTURE_VERBS, verbs_out

CASES = PhrasingCases()

# -- after the person's own doing: 'after his bodyboarding', 'after his sumo practice', 'since
# his gliding lesson', 'after the wild swimming', closing a want of one person -----------------

test_after_doing = CASES.test(
    ("person b wants the chips after his bodyboarding", "chips>B", L44),
    ("Person B gets the bottole after his sumo practice.", "bottle>B", L44),
    ("The chnips are for Person A after her padel game.", "chips>A", T21),
    ("Any chance Person B could have the cup after his powerlifting?", "cup>B", L44),
    (
        "Honestly, the crisps are the thing Bob's been craving since his gliding lesson.",
        "chips>B",
        FIG1,
    ),
    (
        "Alice was on about the crisps after her juggling, can you take them to her.",
        "chips>A",
        TWO,
    ),
    ("She's desperate for her bottle, Person A is, after the wild swimming.", "bottle>A", T12),
    ("Carol wants the apple after her kitesurfing.", "apple>C", CELL),
    ("Bob gets the cup after his darts practice.", "cup>B", CELL),
    ("The apple is for Carol after her rowing lesson.", "apple>C", CELL),
    ("Bob wants the cup after a long day of fencing.", "cup>B", CELL),
    ("Mr Lee's after his pills after his physio.", "pills>B", WARD),
    ("Lily's desperate for her teddy, she is, after her nap.", "teddy>A", NURSERY),
    ("Following her swim, Carol wants the apple.", "apple>C", CELL),
    ("After her run, Carol wants the apple.", "apple>C", CELL),
    # an event says when; an order, not a want; something of the scene; a pronoun that cannot be
    # the one person; two people; a surface; 'shift' may be a verb of the grammar
    ("Bob wants the cup after his meeting.", None, CELL),
    ("Bob wants the cup after the meeting.", None, CELL),
    ("Give Bob the cup after his kitesurfing.", None, CELL),
    ("Bob wants the cup after her kitesurfing.", None, CELL),
    ("Bob and Carol want the cup after their rowing.", None, CELL),
    ("Bob wants the cup on the shelf after his rowing.", None, CELL),
    ("Bob wants the cup after a long day of the apple.", None, CELL),
    ("After his meeting, Bob needs the cup.", None, CELL),
    ("After his swim, Carol wants the apple.", None, CELL),
    ("After her run, give Carol the apple.", None, CELL),
    ("After his swim, Bob and Carol need the cup.", None, CELL),
    ("After his shift, Bob needs the cup.", None, CELL),
)

# -- wants said by a frame: 'after an hour of X,', 'the one who's in need of', "'s got to have",
# 'would quite fancy', 'the thing P's been craving', 'by the look of him', 'for unloading X' ------

test_wants_framed = CASES.test(
    ("After a whole hour of crossfit, Person A is gasping for that bottle.", "bottle>A", F42),
    ("Person B's the one who's in need of the bottle, by the look of him.", "bottle>B", DUO),
    (
        "Dana's got to have the spoon for her yoghurt, and Emma would quite fancy the green cup.",
        "spoon>A & cup_green>C",
        LAB,
    ),
    ("Tom's going to need the work gloves for unloading the pallets.", "gloves>B", DEPOT),
    ("After a long hour of kickboxing, Carol is desperate for the apple.", "apple>C", CELL),
    ("Carol's the one who's in need of the apple.", "apple>C", CELL),
    ("Carol is in dire need of the cup.", "cup>C", CELL),
    ("Ruth's got to have the jug.", "jug>A", WARD),
    ("Omar would quite fancy the bowl.", "bowl>B", LAB),
    ("The apple is the thing Carol's been after.", "apple>C", CELL),
    ("Carol needs the apple, by the look of her.", "apple>C", CELL),
    ("Mia needs the gloves for unloading the pallet.", "gloves>A", DEPOT),
    ("Mia needs the gloves for sweeping the conveyor.", "gloves>A", DEPOT),
    ("Bob wouldn't say no to the cup.", "cup>B", CELL),
    ("Carol's been on at me about the apple.", "apple>C", CELL),
    ("Carol would kill for the apple.", "apple>C", CELL),
    ("Bob could really go for the cup.", "cup>B", CELL),
    # an order after the hour; two people; the thing of a surface; a pronoun that cannot be the
    # one person, or of two; a doing with a thing of the scene, or a pronoun, or a verb of the
    # grammar; two people's need
    ("After an hour of kickboxing, give Carol the apple.", None, CELL),
    ("After an hour of kickboxing, Carol and Bob want the cup.", None, CELL),
    ("After an hour of the apple, Carol wants the cup.", None, CELL),
    ("The shelf is in need of the cup.", None, CELL),
    ("Bob wouldn't say no to the shelf.", None, CELL),
    ("The shelf would kill for the cup.", None, CELL),
    ("The apple is the thing the shelf's been after.", None, CELL),
    ("Carol needs the apple, by the look of him.", None, CELL),
    ("Carol and Bob need the apple, by the look of her.", None, CELL),
    ("Give Carol the apple, by the look of her.", None, CELL),
    ("Mia needs the scanner for checking the boxes.", None, DEPOT),
    ("Mia needs the tape for wrapping them.", None, DEPOT),
    ("Tom needs the scanner for loading the pallet.", None, DEPOT),
    ("Mia needs the scanner for moving the pallet.", None, DEPOT),
    ("Mia and Tom need the tape for wrapping the parcels.", None, DEPOT),
)

# -- courtesies: a sign-off from the speaker's trade, 'I need the room', 'if that's not too much
# to ask of you', 'then that's all', "the apple's meant for" -------------------------------------

test_courtesies = CASES.test(
    (
        "The bottle for Person A, please and thank you, from a very tired steel fixer.",
        "bottle>A",
        ONE,
    ),
    (
        "Stick the bottle on the sheelf, would you, I'm a french polisher and I need the room.",
        "bottle@shelf",
        TWO,
    ),
    (
        "Would you stick the stapler in the box, I'm the philatelist and I need the room?",
        "stapler@box",
        OFFICE,
    ),
    ("Person A would like the bottle, if that's not too much to ask of you.", "bottle>A", ONE),
    (
        "Give Person A the bottle then give Person B the cup then that's all, I'm off to my shift "
        "as a shunter.",
        "bottle>A ; cup>B",
        F41,
    ),
    (
        "Sorry, sorry, I know you're busy, but the apple's meant for Person B, if that's alright.",
        "apple>B",
        SQ,
    ),
    ("Give Bob the cup, from a very tired lighthouse keeper.", "cup>B", CELL),
    ("Put the cup on the shelf, I need the room.", "cup@shelf", CELL),
    ("Bob would like the apple, if it isn't too much to ask of you.", "apple>B", CELL),
    ("Give Bob the apple then that's it.", "apple>B", CELL),
    ("The apple's intended for Bob, not Carol.", "apple>B", CELL),
    # signed by a person or thing of the scene; the speaker needs a thing of the scene; a surface
    # meant for someone
    ("Give Bob the cup, from a very tired Carol.", None, CELL),
    ("Give Bob the cup, from a tired old apple.", None, CELL),
    ("Give Bob the cup, from the shelf.", None, CELL),
    ("Give Bob the cup, from your boss.", None, CELL),
    ("Put the cup on the shelf, I need the cup.", None, CELL),
    ("The shelf's meant for Carol.", None, CELL),
)

# -- about the person a request is for: "she's a messy little thing", "he's a roughneck on leave",
# "She's just back from crabbing.", "Her airsoft game starts at four.", "they've both been …
# all day", "and that's her sorted" ---------------------------------------------------------------

test_about_them = CASES.test(
    (
        "Oh, thank you, and, um, the bib for Lily, please, she's a messy little thing.",
        "bib>A",
        NURSERY,
    ),
    ("Bob wants the crispps, he's a roughneck on leave.", "chips>B", CELL),
    ("Would you mind taking the bottle to Alice? She's just back from crabbing.", "bottle>A", FIG1),
    ("Could Ava have the teddy, do you think? She's tired from tap dancing.", "teddy>C", NURSERY),
    (
        "Mind bringing the bottle over to Person A? Her airsoft game starts at four.",
        "bottle>A",
        T12,
    ),
    (
        "Bob's to have the bottle and Alice the crisps, they've both been down with the tunneller "
        "all day.",
        "bottle>B & chips>A",
        FIG1,
    ),
    (
        "Teddy to Lily and the wipes on the high chair and that's her sorted.",
        "teddy>A & wipes@highchair",
        NURSERY,
    ),
    ("The apple for Carol, she's a sweet little thing.", "apple>C", CELL),
    ("Give Bob the cup, he's a welder on leave.", "cup>B", CELL),
    ("Give Carol the cup. She's just home from orienteering.", "cup>C", CELL),
    ("Give Carol the cup. Her pottery class starts at six.", "cup>C", CELL),
    ("The green cup for Dana and that's her happy.", "cup_green>A", LAB),
    (
        "Bob gets the cup and Carol the apple, they've both been up with the lambs all day.",
        "cup>B & apple>C",
        CELL,
    ),
    # a pronoun that cannot be the one person, or of two; a time; something of the scene; one
    # person for 'both'
    ("The apple for Carol, he's a sweet little thing.", None, CELL),
    ("The apple for Carol and the cup for Bob, she's a sweet little thing.", None, CELL),
    ("Give Bob the cup, he's a welder on leave tomorrow.", None, CELL),
    ("Give Carol the cup. He's just home from orienteering.", None, CELL),
    ("Give Carol the cup. She's just home from the shelf.", None, CELL),
    ("Give Carol and Bob the cup. She's tired from rowing.", None, CELL),
    ("Give Carol the cup. His pottery class starts at six.", None, CELL),
    ("Give Carol the cup. Her apple starts at six.", None, CELL),
    ("Bob gets the cup, they've both been busy all day.", None, CELL),
    ("The bib for Lily and the teddy for Ava and that's her sorted.", None, NURSERY),
)

# -- pronouns and ellipsis: 'P, that's X for you', 'P, yours is X', "There's P, pass her X", "P's
# run out of X, take her X", "There's X, P's waiting on it", 'then it's X for P', 'P's here as a
# visitor', 'P put in for X', ', so pass it to him' of the last want ----------------------------

test_pronouns = CASES.test(
    (
        "Person A, that's the apple for you. Person B, yours is the bottle.",
        "apple>A & bottle>B",
        F42,
    ),
    ("There's Person A, pass her the bottle, would you.", "bottle>A", ONE),
    ("Lena's run out of salt at her table, take her the salt.", "salt>B", KITCHEN),
    ("Right, there's the bottle, Person A's waiting on it, so off you go now.", "bottle>A", ONE),
    (
        "Start with Person B, he gets the chips, and then it's the bottle for Person A.",
        "chips>B ; bottle>A",
        T21,
    ),
    (
        "Emma's only here for the afternoon as a visitor, hand her the white cup.",
        "cup_white>C",
        LAB,
    ),
    (
        "Mrs Ortiz put in for the glue, and the ruler is what Noah asked for, so pass it to him.",
        "glue>A & ruler>B",
        CLASSROOM,
    ),
    ("Carol, that's the apple for you. Bob, yours is the cup.", "apple>C & cup>B", CELL),
    ("Bob, yours is the cup and the apple.", "cup>B & apple>B", CELL),
    ("There's Carol, hand her the apple.", "apple>C", CELL),
    ("That's Bob over there, the cup's for him.", "cup>B", CELL),
    ("See Carol? Give her the apple.", "apple>C", CELL),
    ("Bob's the tall one, hand him the cup.", "cup>B", CELL),
    ("Emma's the visitor, give her the banana.", "banana>C", LAB),
    ("Dana, the spoon's yours.", "spoon>A", LAB),
    ("Here's the spoon, Dana's been after it all day.", "spoon>A", LAB),
    ("Marco's run out of lemon, take him the lemon.", "lemon>A", KITCHEN),
    ("There's the apple, Carol's waiting on it.", "apple>C", CELL),
    ("Carol first, she gets the apple, and then it's the cup for Bob.", "apple>C ; cup>B", CELL),
    ("Omar's only in today as a technician, hand him the bowl.", "bowl>B", LAB),
    ("Zoe put in for the globe.", "globe>C", CLASSROOM),
    (
        "Zoe put in for the globe, and the ruler is what Noah asked for, so pass it to him.",
        "globe>C & ruler>B",
        CLASSROOM,
    ),
    (
        "Mrs Ortiz wants the glue, and Noah wants the ruler, so pass it to him.",
        "glue>A & ruler>B",
        CLASSROOM,
    ),
    # something of the scene for 'you'; a pronoun that cannot be the person; another person in
    # the request; another object than the one run out of; 'them' of one object; a surface; a
    # time; the pronoun may be two people; two objects for 'it'
    ("Bob, that's the shelf for you.", None, CELL),
    ("Bob, that's the cup for you and Carol.", None, CELL),
    ("There's Carol, hand him the apple.", None, CELL),
    ("See Carol? Give him the apple.", None, CELL),
    ("Emma's the doctor, give her the banana.", None, LAB),
    ("Dana, the sink's yours.", None, LAB),
    ("Dana, the spoon's yours and Omar's.", None, LAB),
    ("That's Bob over there, the cup's for her.", None, CELL),
    ("There's Carol, hand her the apple and Bob the cup.", None, CELL),
    ("Marco's run out of lemon, take him the knife.", None, KITCHEN),
    ("Marco's run out of lemon, take her the lemon.", None, KITCHEN),
    ("There's the apple, Carol's waiting on them.", None, CELL),
    ("There's the shelf, Carol's waiting on it.", None, CELL),
    ("Put the cup on the shelf, so off you go now.", None, CELL),
    ("Give Carol the apple, then it's the shelf for Bob.", None, CELL),
    ("Bob's only here as a welder tomorrow, hand him the cup.", None, CELL),
    ("Bob's only here as the apple, hand him the cup.", None, CELL),
    (
        "Mrs Ortiz put in for the globe, and the ruler is what Noah asked for, so pass it to her.",
        None,
        CLASSROOM,
    ),
    (
        "Noah put in for the globe, and the ruler is what Zoe asked for, so pass it to him.",
        None,
        CLASSROOM,
    ),
    (
        "Mrs Ortiz wants the glue, and Noah wants the ruler and the globe, so pass it to him.",
        None,
        CLASSROOM,
    ),
    ("Carol wants the cup, and Alice wants the apple, so give it to her.", None, CELL),
)

# -- splits and questions: 'onto S with it', a later 'And X can sit on S', 'out of P's reach',
# 'could you do X for P before anything else, and Y for Q after?', ', do you think?' --------------

test_splits = CASES.test(
    (
        "Cup first, onto the counter with it. After that, Carol gets the apple.",
        "cup@table ; apple>C",
        CELL,
    ),
    (
        "Marco's waiting on the knife. Mr Novak, the white plate. And the lemon can sit on the "
        "worktop.",
        "knife>A & plate_white>C & lemon@counter",
        KITCHEN,
    ),
    ("crisps go up on the shelf out of bobs reach, hes had plenty", "chips@shelf", TWO),
    (
        "Could you do the apple for Person B before anything else, and the bottle for Person A "
        "after?",
        "apple>B ; bottle>A",
        F42,
    ),
    ("Could Ava have the teddy, do you think? She's tired.", "teddy>C", NURSERY),
    ("Apple first, onto the shelf with it. Then Bob gets the cup.", "apple@shelf ; cup>B", CELL),
    (
        "Knife first, over to Marco with it. After that, Lena gets the lemon.",
        "knife>A ; lemon>B",
        KITCHEN,
    ),
    ("chips go up on the shelf out of bobs reach", "chips@shelf", TWO),
    ("Could you do the cup for Bob first, and the apple for Carol after?", "cup>B ; apple>C", CELL),
    # 'with it' of two objects or 'them' of one; with a thing of the scene; the lemon on a person
    # or with a time; out of reach in a hand-over; a placement among the things to do
    ("The apple and the cup onto the shelf with it.", None, CELL),
    ("Apple first, onto the shelf with them.", None, CELL),
    ("Take the cup. Put the apple on the shelf with it.", None, CELL),
    ("Give the knife to Marco with it.", None, KITCHEN),
    ("Knife first, to Marco with them.", None, KITCHEN),
    ("Cup first, onto the counter with the apple.", None, CELL),
    ("Give Marco the knife. And the lemon can sit on Lena.", None, KITCHEN),
    ("Give Marco the knife. And the lemon can sit on the worktop tomorrow.", None, KITCHEN),
    ("give bob the chips out of alices reach", None, TWO),
    ("Could you do the cup for Bob first, and the apple on the shelf after?", None, CELL),
    ("Could you do the cup for Bob before anything else, and then the dishes?", None, CELL),
)


def test_refused_without_the_rules(monkeypatch: pytest.MonkeyPatch) -> None:
    # session 40: the lexicon's posture verbs read 'the lemon can sit on the worktop' too;
    # (session 41: 12s's occasion rule reads some of them too)
    with verbs_out(*POSTURE_VERBS):
        # session 42 (12r): its rules of the same families read these too; session 43 (12s): its
        # closing remark rule reads ", he's a roughneck on leave" too
        CASES.refused_without(
            (
                *normalise._STEPS37,
                *normalise._STEPS41S_FIRST,
                *normalise._STEPS42R,
                *normalise._STEPS43S_FIRST,
            ),
            monkeypatch,
        )
