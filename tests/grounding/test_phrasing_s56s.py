"""Session-56 phrasings of issue 12 (engineer 12s): 12c's open wrong readings (where a thing is,
beside a request for another thing; ', not P, the Y') and blind54's sentence splits, negation and
exclusion, each as a family (fresh sentences in other scenes, each read (wrongly) or refused on
main 085b81dc as the test says, and near sentences); docs/grounding.md, "Session 56 (engineer
12s)"."""

from __future__ import annotations

import pytest

from hltl.grounding import _rewrites56s as r56s
from hltl.grounding import offline
from hltl.world.scene import Scene, load_scene
from tests.grounding.helpers import (
    CELL,
    CLASSROOM,
    KITCHEN,
    LAB,
    NURSERY,
    OFFICE,
    ROOT,
    WARD,
    WORKSHOP,
    PhrasingCases,
    assert_case,
    tree,
)

TWO, T21, DUO, L44, F41, L24, T12 = (
    load_scene(ROOT / f"examples/scenes/{n}.yaml")
    for n in ("two_arms", "2-1", "2-2", "4-4-line", "4-1", "2-4-line", "1-2")
)

# -- where a thing is, beside a request for another thing (_where_is56s, a check) --------------
#
# each read on main 085b81dc as a placing AND the other request (12c, session 55: "The apple's on
# the shelf, give Bob the cup." -> apple@shelf & cup>B)
WHERE_IS = [
    ("The apple's on the shelf, give Bob the cup.", CELL),
    ("The apple is on the table, the cup goes to Bob.", CELL),
    ("The apple is still on the shelf, so give Bob the cup.", CELL),
    ("Give Bob the cup, the apple's on the shelf.", CELL),
    ("The lemon's on the counter, give Lena the knife.", KITCHEN),
    ("Give Marco the tongs, the salt's on the rack.", KITCHEN),
    ("The knife is still on the worktop, so pass Mr Novak the lemon.", KITCHEN),
    ("The jug's on the bedside table, give Mrs Khan the pills.", WARD),
    ("Give Mr Lee the magazine, the thermometer is on the trolley.", WARD),
    ("The drill's on the bench, pass Jess the torch.", WORKSHOP),
    ("The stapler's in the box, give Sam the red pen.", OFFICE),
    ("The teddy's on the mat, so give Lily the bib.", NURSERY),
]


@pytest.mark.parametrize(("text", "scene"), WHERE_IS)
def test_where_is56s_refused(text: str, scene: Scene) -> None:
    assert_case(text, None, scene)


def test_where_is56s_is_what_refuses(monkeypatch: pytest.MonkeyPatch) -> None:
    """Without the check each is read (placed there, and the other request)."""
    kept = tuple(c for c in offline._CHECKS if c is not r56s._where_is56s)
    monkeypatch.setattr(offline, "_CHECKS", kept)
    for text, scene in WHERE_IS:
        assert tree(text, scene) is not None, text


# near sentences: the state alone, two states, an order ('once', 'then'), a placing said verbless
# or with its verb: read as before
test_where_is56s_near = PhrasingCases().test(
    ("The apple is on the shelf.", "apple@shelf", CELL),
    ("The apple's on the shelf and the cup's on the table.", "apple@shelf & cup@table", CELL),
    ("The apple is on the shelf, then give Bob the cup.", "apple@shelf ; cup>B", CELL),
    ("Once the apple is on the shelf, give Bob the cup.", "apple@shelf ; cup>B", CELL),
    ("The apple on the shelf, the cup to Bob.", "apple@shelf & cup>B", CELL),
    ("Put the apple on the shelf and give Bob the cup.", "apple@shelf & cup>B", CELL),
    (
        "Once the lemon's on the counter, give the knife to Lena.",
        "lemon@counter ; knife>B",
        KITCHEN,
    ),
)

# -- ', not P, the Y' closing a request (_not_p_then56s, a refusal before the read) -------------
#
# each read on main 085b81dc as both things to the request's person (12c, session 55: "Give Bob
# the red mug, not Alice, the blue." -> mug_red>B & mug_blue>B)
NOT_P_THEN = [
    ("Give Bob the red mug, not Alice, the blue.", CELL),
    ("Give Bob the red mug, not Alice, and the blue.", CELL),
    ("Give Marco the knife, not Lena, the tongs.", KITCHEN),
    ("Hand Mr Novak the white plate, not Lena, the blue one.", KITCHEN),
    ("Take Mrs Khan the blue blanket, not Mr Lee, the grey one.", WARD),
    ("Hand Kofi the hammer, not Jess, the screws.", WORKSHOP),
    ("Give Priya the black pen, not Sam, the blue.", OFFICE),
    ("Give Lily the red block, not Ava, the green one.", NURSERY),
]


@pytest.mark.parametrize(("text", "scene"), NOT_P_THEN)
def test_not_p_then56s_refused(text: str, scene: Scene) -> None:
    assert_case(text, None, scene)


def test_not_p_then56s_is_what_refuses(monkeypatch: pytest.MonkeyPatch) -> None:
    """Without the refusal each is read (both things to the request's person)."""
    kept = tuple(c for c in offline._REFUSALS if c is not r56s._not_p_then56s)
    monkeypatch.setattr(offline, "_REFUSALS", kept)
    for text, scene in NOT_P_THEN:
        assert tree(text, scene) is not None, text


# near sentences: the person left out at the end, a thing left out, a correction of the person
test_not_p_then56s_near = PhrasingCases().test(
    ("Give Bob the red mug, not Alice.", "mug_red>B", CELL),
    ("Give Bob the red mug, not the blue.", "mug_red>B", CELL),
    ("Crisps to Bob, ah, not Bob, Alice.", "chips>A", CELL),
    ("Give Zoe the ruler. Wait, not Zoe, Noah.", "ruler>B", CLASSROOM),
    ("Give Bob, not Alice, the red mug.", "mug_red>B", CELL),
)

# -- 'P's (gone) off the X, give her the Y' (_off_the56s) ---------------------------------------
#
# blind54 #127 #136 and fresh ones in other scenes, each refused on main 085b81dc
OFF_THE = PhrasingCases()
test_off_the56s = OFF_THE.test(
    ("Person A's off the chips this week, just give her the bottle.", "bottle>A", DUO),
    (
        "Lena's gone off the white plate for some reason, bring her the blue one instead.",
        "plate_blue>B",
        KITCHEN,
    ),
    ("Bob's off the apple, so give him the cup.", "cup>B", CELL),
    ("Alice is off the red mug today, hand her the blue one.", "mug_blue>A", CELL),
    ("Mrs Khan's off the magazine at the moment, take her the jug.", "jug>C", WARD),
    (
        "Jess is off the big spanner today, just hand her the small one.",
        "spanner_small>B",
        WORKSHOP,
    ),
    ("Sam's off the red pen, give him the black one.", "pen_black>B", OFFICE),
    ("Lily's gone off the teddy lately, give her the red block.", "block_red>A", NURSERY),
)


def test_off_the56s_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    OFF_THE.refused_without((r56s._off_the56s,), monkeypatch)


# near sentences: 'off to', the thing itself asked for, a holding, a question, a remark closing a
# request: read as before, or refused
test_off_the56s_near = PhrasingCases().test(
    ("Lily's off to nap, give her the teddy.", "teddy>A", NURSERY),
    ("Bob's off the apple, give him the apple.", None, CELL),
    ("Bob's off the apple, he had the cup.", None, CELL),
    ("Bob's off the apple.", None, CELL),
    ("Alice is off the chips, she has the bottle.", None, CELL),
    ("Crisps to Alice, sorry, I mean Bob, Alice is off crisps.", "chips>B", CELL),
)

# -- 'The X's not for P, it's for Q, take it to him.' (_not_for_take56s) ----------------------
#
# blind54 #121 and fresh ones in other scenes, each refused on main 085b81dc ('him' could be P)
NOT_FOR_TAKE = PhrasingCases()
test_not_for_take56s = NOT_FOR_TAKE.test(
    ("The bottle's not for Alice, it's for Bob, take it to him.", "bottle>B", TWO),
    ("The apple's not for Alice, it's for Bob, take it to him.", "apple>B", CELL),
    ("The lemon's not for Marco, it's for Mr Novak, take it to him.", "lemon>C", KITCHEN),
    ("The lemon's not for Lena, it's for Marco, so pass it to him.", "lemon>A", KITCHEN),
    ("The spoon's not for Emma, it's for Omar, hand it to him.", "spoon>B", LAB),
    ("The globe's not for Noah, it's for Zoe, take it to her.", "globe>C", CLASSROOM),
)


def test_not_for_take56s_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    NOT_FOR_TAKE.refused_without((r56s._not_for_take56s,), monkeypatch)


# near sentences: the pronoun not of Q's sex (it may be P), stays refused
test_not_for_take56s_near = PhrasingCases().test(
    ("The bottle's not for Bob, it's for Alice, take it to him.", None, TWO),
    ("The globe's not for Noah, it's for Zoe, take it to him.", None, CLASSROOM),
)

# -- '…, and no, she doesn't want anything else.' (_nothing_else56s) ---------------------------
#
# blind54 #130 and fresh ones in other scenes, each refused on main 085b81dc (negation)
NOTHING_ELSE = PhrasingCases()
test_nothing_else56s = NOTHING_ELSE.test(
    ("Person A wants the bottle, and no, she doesn't want anything else.", "bottle>A", T12),
    ("Bob wants the apple, and no, he doesn't want anything else.", "apple>B", CELL),
    ("Give Carol the cup, she doesn't need anything else.", "cup>C", CELL),
    ("Mr Lee needs the jug, and no, he doesn't need anything else thanks.", "jug>B", WARD),
    ("Jess wants the torch, and no, she doesn't want anything else.", "torch>B", WORKSHOP),
    ("Give Sam the stapler, he doesn't need anything else.", "stapler>B", OFFICE),
)


def test_nothing_else56s_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    NOTHING_ELSE.refused_without((r56s._nothing_else56s,), monkeypatch)


# near sentences: a past want, a pronoun of the other sex, two people before it: stay refused
test_nothing_else56s_near = PhrasingCases().test(
    ("Bob wanted the apple, and no, he doesn't want anything else.", None, CELL),
    ("Bob wants the apple, and no, she doesn't want anything else.", None, CELL),
    ("Bob wants the apple and Carol the cup, he doesn't want anything else.", None, CELL),
    ("Bob had the apple, he doesn't want anything else.", None, CELL),
    # 12c (on b28068d5): a holding before it
    ("Alice has the bottle, and no, she doesn't want anything else.", None, CELL),
    ("Alice's got the bottle, she doesn't need anything else.", None, CELL),
)

# -- 'Give the chips to anyone but Person A.' (_anyone_but56s) ----------------------------------
#
# blind54 #128 and fresh ones in other scenes of two people, each refused on main 085b81dc
ANYONE_BUT = PhrasingCases()
test_anyone_but56s = ANYONE_BUT.test(
    ("Give the chips to anyone but Person A.", "chips>B", L24),
    ("Give anyone but Person B the bottle.", "bottle>A", L24),
    ("The chips go to anybody except Person A.", "chips>B", DUO),
    ("Hand the stapler to anyone but Sam.", "stapler>A", OFFICE),
    ("Pass someone other than Priya the red pen.", "pen_red>B", OFFICE),
    ("Take the torch to anybody apart from Kofi, please.", "torch>B", WORKSHOP),
)


def test_anyone_but56s_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    ANYONE_BUT.refused_without((r56s._anyone_but56s,), monkeypatch)


# near sentences: three people, a negation of the request, a question, done: stay refused
test_anyone_but56s_near = PhrasingCases().test(
    ("Give the apple to anyone but Bob.", None, CELL),
    ("Don't give the chips to anyone but Person A.", None, L24),
    ("Did you give the chips to anyone but Person A?", None, L24),
    ("The chips went to anyone but Person A.", None, L24),
)

# -- a person left out, then a request for others (_left_out56s) --------------------------------
#
# blind54 #124 #131 and fresh ones in other scenes, each refused on main 085b81dc
LEFT_OUT = PhrasingCases()
test_left_out56s = LEFT_OUT.test(
    (
        "Leave Person B out this time round; both the bottle and the chips are headed to Person A.",
        "bottle>A & chips>A",
        T21,
    ),
    (
        "The bottle goes to Person B, and don't let Person A talk you into it being hers.",
        "bottle>B",
        L44,
    ),
    ("Leave Carol out this time; give Bob the apple and Alice the cup.", "apple>B & cup>A", CELL),
    ("Give Bob the cup, and don't let Alice talk you into giving it to her.", "cup>B", CELL),
    ("Leave Marco out for now, the lemon and the salt go to Lena.", "lemon>B & salt>B", KITCHEN),
    ("The tongs go to Lena, and don't let Marco sweet-talk you into it.", "tongs>B", KITCHEN),
    (
        "Count Mr Lee out today: the jug and the magazine are for Mrs Khan.",
        "jug>C & magazine>C",
        WARD,
    ),
    ("Give Jess the torch, but don't let Kofi persuade you otherwise.", "torch>B", WORKSHOP),
)


def test_left_out56s_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    LEFT_OUT.refused_without((r56s._left_out56s,), monkeypatch)


# near sentences: the person left out is the one the request hands to, a request that hands
# nothing: stay refused
test_left_out56s_near = PhrasingCases().test(
    ("Leave Person A out; both the bottle and the chips are headed to Person A.", None, T21),
    ("Give Person B the cup, and don't let Person B talk you out of it.", None, L44),
    ("Leave Bob out this time; Alice had the apple.", None, CELL),
    ("Leave Bob out; Alice has the apple.", None, CELL),
    ("Leave Bob out; Alice's got the apple.", None, CELL),
    # a past want after it: left as it was
    ("Leave Lena out; the knife was for Marco.", None, KITCHEN),
    ("Leave Lena out this time; Marco wanted the knife.", None, KITCHEN),
)

# -- '…, but leave the X alone, she's got her own.' (_leave_alone56s) --------------------------
#
# blind54 #139 and fresh ones in other scenes, each refused on main 085b81dc
LEAVE_ALONE = PhrasingCases()
test_leave_alone56s = LEAVE_ALONE.test(
    (
        "Jess could use the screws, but leave the hammer alone, she's got her own.",
        "screws>B",
        WORKSHOP,
    ),
    ("Bob wants the apple, but leave the cup alone, he's got his own.", "apple>B", CELL),
    ("Mr Lee needs the jug, but leave the magazine be, he's got his own.", "jug>B", WARD),
    ("Give Lily the teddy, and leave the bib alone, she's got her own.", "teddy>A", NURSERY),
)


def test_leave_alone56s_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    LEAVE_ALONE.refused_without((r56s._leave_alone56s,), monkeypatch)


# near sentences: 'she's got them / one' (the request may be done), a past want, the thing asked
# for left alone: stay refused
test_leave_alone56s_near = PhrasingCases().test(
    ("Jess could use the screws, but leave the hammer alone, she's got them.", None, WORKSHOP),
    ("Jess could use the screws, but leave the hammer alone, she's got one.", None, WORKSHOP),
    ("Bob wanted the apple, but leave the cup alone, he's got his own.", None, CELL),
    ("Give Bob the cup, but leave the cup alone.", None, CELL),
)

# -- 'The X holds no interest for P, it's the Y he's been eyeing, so …' (_no_interest56s) -------
#
# blind54 #125 and fresh ones in other scenes, each refused on main 085b81dc (negation)
NO_INTEREST = PhrasingCases()
test_no_interest56s = NO_INTEREST.test(
    (
        "The cup holds no interest for Person B, it's the apple he's been eyeing, so give him "
        "that.",
        "apple>B",
        F41,
    ),
    ("The cup holds no interest for Person B, give him the apple.", "apple>B", F41),
    ("Bob has no interest in the apple, it's the cup he's been eyeing.", "cup>B", CELL),
    ("Mr Novak has no interest in the lemon, pass him the salt.", "salt>C", KITCHEN),
    (
        "The magazine holds no interest for Mr Lee, it's the jug he's been eyeing, so bring him "
        "that.",
        "jug>B",
        WARD,
    ),
)


def test_no_interest56s_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    NO_INTEREST.refused_without((r56s._no_interest56s,), monkeypatch)


# near sentences: the thing itself to another person, a holding, a done request: stay refused
test_no_interest56s_near = PhrasingCases().test(
    ("Bob isn't interested in the apple, give it to Alice.", None, CELL),
    ("Bob isn't interested in the apple, he has the cup.", None, CELL),
    (
        "The apple holds no interest for Bob, it's the cup he's been eyeing, I gave it him.",
        None,
        CELL,
    ),
    ("Bob's off the apple, so give him the cup, I gave it him.", None, CELL),
    ("Leave Carol out; give Bob the apple, I handed it over already.", None, CELL),
)

# -- a thing handed to the person said to be off it (_was_off56s, a check) ----------------------
#
# each read on main 085b81dc as handing the thing too (12s's probe: "Bob was off the apple, so
# give him the cup." -> apple>B & cup>B)
WAS_OFF = [
    ("Bob was off the apple, so give him the cup.", CELL),
    ("Bob's been off the apple, give him the cup.", CELL),
    ("Alice was off the crisps, so hand her the apple.", CELL),
    ("Mr Novak was off the lemon, pass him the salt.", KITCHEN),
    ("Jess was off the torch, give her the drill.", WORKSHOP),
]


@pytest.mark.parametrize(("text", "scene"), WAS_OFF)
def test_was_off56s_refused(text: str, scene: Scene) -> None:
    assert_case(text, None, scene)


def test_was_off56s_is_what_refuses(monkeypatch: pytest.MonkeyPatch) -> None:
    """Without the check each is read (the thing handed over too)."""
    kept = tuple(c for c in offline._CHECKS if c is not r56s._was_off56s)
    monkeypatch.setattr(offline, "_CHECKS", kept)
    for text, scene in WAS_OFF:
        assert tree(text, scene) is not None, text
