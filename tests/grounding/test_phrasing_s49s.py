"""Session-49 phrasings of issue 12 (engineer 12s): blind47's sentence splits and run-ons and its
negation and exclusion, each as a family (fresh sentences in other scenes, each refused on
issue-lead dd7390cd, and near sentences that stay refused), and a wrong reading of main refused
(a thing fronted before a negated clause about it); docs/grounding.md, "Session 49 (engineer
12s)"."""

from __future__ import annotations

import pytest

from hltl.grounding import _rewrites49s as r49s
from hltl.grounding import offline
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
    assert_reads,
    assert_refused,
)

FIG1 = load_scene(ROOT / "examples/scenes/fig1.yaml")  # Person A (Alice), Person B (Bob)
DUO = load_scene(ROOT / "examples/scenes/2-2.yaml")  # Person A, Person B
ONE = load_scene(ROOT / "examples/scenes/1-1.yaml")  # Person A alone
T12 = load_scene(ROOT / "examples/scenes/1-2.yaml")  # Person A alone
T21 = load_scene(ROOT / "examples/scenes/2-1.yaml")  # Person A alone
SQ = load_scene(ROOT / "examples/scenes/4-4-square.yaml")  # Person A, Person B

# -- 'to P on top (of that)' said 'as well' -------------------------------------------------------

ON_TOP = PhrasingCases()
test_on_top49s = ON_TOP.test(
    (
        "Person A, the apple. Person B, the cup, he's got the boxercise class after. And the "
        "bottle to Person A on top.",
        "apple>A & cup>B & bottle>A",
        SQ,
    ),
    ("Crisps to Bob, and the apple to Carol on top.", "chips>B & apple>C", CELL),
    ("Give Tom the tape. And the gloves to Tom on top of that.", "tape>B & gloves>B", DEPOT),
    ("The globe to Zoe, and the ruler to Noah on top.", "globe>C & ruler>B", CLASSROOM),
    ("Pills to Mr Lee, and the magazine for Mrs Khan on top.", "pills>B & magazine>C", WARD),
)
test_on_top49s_near = ON_TOP.test(
    ("Put the apple on the shelf and the cup on top.", None, CELL),
    ("Give the apple on top.", None, CELL),
    ("The cup to the shelf on top.", None, CELL),
)


def test_on_top49s_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    ON_TOP.refused_without((r49s._on_top49s,), monkeypatch)


# -- a closing 'don't keep her waiting' -----------------------------------------------------------

KEEP_WAITING = PhrasingCases()
test_keep_waiting49s = KEEP_WAITING.test(
    ("Give Person A the bottle, and don't keep her waiting.", "bottle>A", T12),
    ("Give Bob the apple, don't keep him hanging about.", "apple>B", CELL),
    ("Pass Sam the stapler, and don't keep him waiting.", "stapler>B", OFFICE),
    ("Give Bob the apple and Carol the cup, don't keep them waiting.", "apple>B & cup>C", CELL),
    ("Hand Mrs Khan the magazine; don't leave her waiting too long.", "magazine>C", WARD),
)
test_keep_waiting49s_near = KEEP_WAITING.test(
    ("Give Bob the apple, and don't keep her waiting.", None, CELL),
    ("Give Bob the apple, and don't keep them waiting.", None, CELL),
    ("Don't keep him waiting.", None, CELL),
)


def test_keep_waiting49s_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    KEEP_WAITING.refused_without((r49s._keep_waiting49s,), monkeypatch)


# -- 'don't go giving it to Q' ---------------------------------------------------------------------

DONT_GO = PhrasingCases()
test_dont_go49s = DONT_GO.test(
    (
        "Person B is the one who asked for the bottle, so don't go giving it to Person A.",
        "bottle>B",
        DUO,
    ),
    ("Bob wants the apple, so don't go handing it to Carol.", "apple>B", CELL),
    ("The cup's for Carol, don't go and put it on the shelf.", "cup>C", CELL),
    ("Mia asked for the tape, so don't go giving it to Tom.", "tape>A", DEPOT),
    ("Lena wants the tongs, don't go passing them to Marco.", "tongs>B", KITCHEN),
)
test_dont_go49s_near = DONT_GO.test(
    ("Don't go giving Bob the apple.", None, CELL),
    ("Bob wants the apple, so don't go giving it to Bob.", None, CELL),
)


def test_dont_go49s_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    DONT_GO.refused_without((r49s._dont_go49s,), monkeypatch)


# -- 'It's the X P's reaching for, not the Y' ----------------------------------------------------

CLEFT_REACH = PhrasingCases()
test_cleft_reach49s = CLEFT_REACH.test(
    ("It's the sippy cup Lily's reaching for, not the bib.", "beaker>A", NURSERY),
    ("It's the red mug Bob's pointing at, not the blue one.", "mug_red>B", CELL),
    ("It's the globe Zoe's pointing at, not the ruler.", "globe>C", CLASSROOM),
    ("It's the banana Emma's been reaching for, not the spoon.", "banana>C", LAB),
    ("It's the torch Kofi's reaching for, not the drill.", "torch>A", WORKSHOP),
)
test_cleft_reach49s_near = CLEFT_REACH.test(
    ("It's the red mug Bob's pointing at.", None, CELL),
    ("It's the red mug Bob's pointing at, not the red one.", None, CELL),
    ("It's the red mug the shelf's pointing at, not the blue one.", None, CELL),
)


def test_cleft_reach49s_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    CLEFT_REACH.refused_without((r49s._cleft_reach49s,), monkeypatch)


# -- 'a X that isn't A or B' --------------------------------------------------------------------

ISNT_EITHER = PhrasingCases()
test_isnt_either49s = ISNT_EITHER.test(
    ("Sam needs a pen that isn't red or blue.", "pen_black>B", OFFICE),
    ("Give Priya a pen that isn't black or blue.", "pen_red>A", OFFICE),
    ("Tom wants a box that isn't small or large.", "box_medium>B", DEPOT),
)
test_isnt_either49s_near = ISNT_EITHER.test(
    ("Give Priya a pen that isn't black or green.", None, OFFICE),
    ("Bob wants a mug that isn't red or blue.", None, CELL),
    ("Give Priya a pen that isn't black or black.", None, OFFICE),
)


def test_isnt_either49s_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    ISNT_EITHER.refused_without((r49s._isnt_either49s,), monkeypatch)


# -- 'but the X mustn't be touched (, it's got …)' -------------------------------------------------

NOT_TOUCHED = PhrasingCases()
test_not_touched49s = NOT_TOUCHED.test(
    (
        "Put the white cup in the sink, but the green cup mustn't be touched, it's got a sample "
        "in.",
        "cup_white@sink",
        LAB,
    ),
    (
        "Give Jess the drill, but the hammer isn't to be moved, it's holding the door.",
        "drill>B",
        WORKSHOP,
    ),
    ("Pass Sam the stapler, but the red pen mustn't be touched.", "stapler>B", OFFICE),
    ("Give Ava the green block, but the red block mustn't be touched.", "block_green>C", NURSERY),
    ("Give Mr Lee the jug, and the pills mustn't be touched.", "jug>B", WARD),
)
test_not_touched49s_near = NOT_TOUCHED.test(
    ("Put the white cup in the sink, but the white cup mustn't be touched.", None, LAB),
    ("The green cup mustn't be touched.", None, LAB),
    ("Teddy to Lily, but the wipes shouldn't be moved, they're for later.", None, NURSERY),
    ("Give Jess the drill, but the hammer isn't to be moved, Kofi needs it.", None, WORKSHOP),
)


def test_not_touched49s_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    NOT_TOUCHED.refused_without((r49s._not_touched49s,), monkeypatch)


# -- 'No point the X sitting about, P should have it' ---------------------------------------------

NO_POINT = PhrasingCases()
test_no_point49s = NO_POINT.test(
    ("No point the bottle sitting about, Person A should have it.", "bottle>A", ONE),
    ("No point in the apple lying around, give it to Bob.", "apple>B", CELL),
    ("No sense leaving the torch lying about, Kofi can have it.", "torch>A", WORKSHOP),
    ("No point the globe sitting there, put it on the desk.", "globe@desk", CLASSROOM),
    ("There's no point the banana going to waste, Emma should have it.", "banana>C", LAB),
)
test_no_point49s_near = NO_POINT.test(
    ("No point the apple sitting about, Bob should have the cup.", None, CELL),
    ("No point the apple sitting about, she should have it.", None, CELL),
    ("No point the apple sitting about.", None, CELL),
)


def test_no_point49s_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    NO_POINT.refused_without((r49s._no_point49s,), monkeypatch)


# -- 'P's brought his own X, so give him every other thing'; 'had enough X, whatever else' -------

OWN_OTHER = PhrasingCases()
test_own_other49s = OWN_OTHER.test(
    (
        "Person B's brought his own cup, so give him every other thing.",
        "bottle>B & chips>B & apple>B",
        SQ,
    ),
    (
        "Carol's brought her own apple, so give her everything else.",
        "cup>C & bottle>C & chips>C & mug_red>C & mug_blue>C",
        CELL,
    ),
    (
        "Kofi's brought his own hammer, so hand him all the rest.",
        "spanner_small>A & drill>A & screws>A & torch>A & spanner_large>A",
        WORKSHOP,
    ),
    (
        "Alice says she's had enough crisps for one day, but whatever else is going she'll take.",
        "bottle>A",
        FIG1,
    ),
    (
        "Person B says he's had enough chips for today, but whatever else is going he'll take.",
        "bottle>B",
        DUO,
    ),
)
test_own_other49s_near = OWN_OTHER.test(
    ("Carol's brought her own apple, so give him everything else.", None, CELL),
    (
        "Carol says she's had enough crisps for one day, but whatever else is going she'll take.",
        None,
        CELL,
    ),
    ("Carol's brought her own teapot, so give her everything else.", None, CELL),
)


def test_own_other49s_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    OWN_OTHER.refused_without((r49s._own_other49s,), monkeypatch)


# -- 'let P at X'; a thing fronted before 'she's not allowed near' --------------------------------

LET_AT = PhrasingCases()
test_let_at49s = LET_AT.test(
    ("Let Person A at the chips.", "chips>A", T21),
    ("Let Bob at the apple, he's starving.", "apple>B", CELL),
    ("Let Omar at the banana.", "banana>B", LAB),
)
test_let_at49s_near = LET_AT.test(
    ("Let Bob at the shelf.", None, CELL),
    ("Let the apple at Bob.", None, CELL),
)


def test_let_at49s_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    LET_AT.refused_without((r49s._let_at49s,), monkeypatch)


FRONTED_NOT = PhrasingCases()
test_fronted_not_read49s = FRONTED_NOT.test(
    ("Let Person A at the chips; the bottle, though, she's not allowed near.", "chips>A", T21),
    ("Give Bob the apple; as for the cup, he isn't allowed it.", "apple>B", CELL),
    ("Give Person A the chips; the bottle, she won't drink.", "chips>A", T21),
    ("Pass Kofi the torch; the drill, though, he's not allowed near.", "torch>A", WORKSHOP),
    ("Give Marco the knife; the lemon, he won't touch.", "knife>A", KITCHEN),
)
test_fronted_not_read49s_near = FRONTED_NOT.test(
    ("Give Bob the apple; the cup, though, she isn't keen on.", None, CELL),
    ("Give Bob the apple; the cup, though, he isn't keen on.", None, CELL),
)


def test_fronted_not_read49s_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    FRONTED_NOT.refused_without((r49s._fronted_not_read49s,), monkeypatch)


# -- the wrong reading: a fronted thing the person will not have read as given -------------------

FRONTED_WRONG = [
    ("Give Bob the apple; the cup, though, he isn't keen on.", CELL),
    ("Give Lily the teddy; the sippy cup, though, she's not allowed.", NURSERY),
    ("Give Ava the teddy; the red block, though, she's not allowed.", NURSERY),
]


@pytest.mark.parametrize(("text", "scene"), FRONTED_WRONG)
def test_fronted_not49s_refused(text: str, scene: Scene) -> None:
    assert_refused(text, scene, match="not a request for it")


def test_fronted_not49s_stays() -> None:
    # a negated reason after the request with no thing fronted: session 31's, as before
    assert_reads(
        "Give Person A the chips and the bottle, she hasn't eaten since six.",
        "chips>A & bottle>A",
        T21,
    )
    assert_reads("Give Person A the chips, she won't share.", "chips>A", T21)


def test_fronted_not49s_is_what_refuses(monkeypatch: pytest.MonkeyPatch) -> None:
    kept = tuple(c for c in offline._CHECKS if c is not r49s._fronted_not49s)
    monkeypatch.setattr(offline, "_CHECKS", kept)
    assert_reads(FRONTED_WRONG[0][0], "apple>B & cup>B", CELL)


# -- 'P has the X now, …' (12c's probes: a reading of what a person holds now) ------------------

HAS_NOW = [
    ("person a the juggler has the cup now, cheers, we're all set", SQ),
    ("person a has the cup now, cheers, we're all set", SQ),
    ("Bob has the cup now, thanks.", CELL),
    ("Bob has the cup now, so give Alice the apple.", CELL),
    ("Bob the porter has the cup now, ta.", CELL),
]


@pytest.mark.parametrize(("text", "scene"), HAS_NOW)
def test_has_now49s_refused(text: str, scene: Scene) -> None:
    assert_refused(text, scene, match="holds now")


def test_has_now49s_stays() -> None:
    # a share with 'and', and 'has' with no 'now': session 32's readings as before
    assert_reads("Bob has the cup now and Alice the apple.", "cup>B & apple>A", CELL)
    assert_reads("Bob has the cup, thanks.", "cup>B", CELL)
    assert_reads("Give Bob the cup now, thanks.", "cup>B", CELL)


def test_has_now49s_is_what_refuses(monkeypatch: pytest.MonkeyPatch) -> None:
    kept = tuple(c for c in offline._CHECKS if c is not r49s._has_now49s)
    monkeypatch.setattr(offline, "_CHECKS", kept)
    assert_reads(HAS_NOW[0][0], "cup>A", SQ)
    assert_reads(HAS_NOW[2][0], "cup>B", CELL)


# -- lower case: an opening 'go on' with no comma ------------------------------------------------

GO_ON = PhrasingCases()
test_go_on49s = GO_ON.test(
    ("go on hand the chips over to person a she's starving", "chips>A", DUO),
    ("go on give bob the apple", "apple>B", CELL),
    ("go on then pass alice the cup", "cup>A", CELL),
    ("come on hand kofi the torch", "torch>A", WORKSHOP),
)
test_go_on49s_near = GO_ON.test(
    ("go on the shelf", None, CELL),
    ("go on give her the apple", None, CELL),
)


def test_go_on49s_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    GO_ON.refused_without((r49s._go_on49s,), monkeypatch)


# -- 'when there's a minute' said 'when you get a minute' ----------------------------------------

THERES_MINUTE = PhrasingCases()
test_theres_minute49s = THERES_MINUTE.test(
    ("pop the bottle over to person a when there's a minute", "bottle>A", ONE),
    ("Give Bob the apple when there's a moment.", "apple>B", CELL),
    ("Pass Sam the stapler when there's a sec.", "stapler>B", OFFICE),
)
test_theres_minute49s_near = THERES_MINUTE.test(
    ("Give Bob the apple when there's a cup.", None, CELL),
    ("Give Bob the apple when there's a minute left on the clock.", None, CELL),
)


def test_theres_minute49s_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    THERES_MINUTE.refused_without((r49s._theres_minute49s,), monkeypatch)


# -- a run-on: 'P's <doing> … so <request>' with no marks ----------------------------------------

SO_RUN_ON = PhrasingCases()
test_so_run_on49s = SO_RUN_ON.test(
    ("sam's taking minutes so the notepad goes to sam", "notebook>B", OFFICE),
    (
        "person a's been eyeing the bottle so pop it over to her when there's a minute",
        "bottle>A",
        ONE,
    ),
    ("priya's filing reports so the stapler goes to priya", "stapler>A", OFFICE),
    ("kofi's been eyeing the torch so pass it to him", "torch>A", WORKSHOP),
    ("tom's packing parcels so the tape goes to tom", "tape>B", DEPOT),
    ("emma's been eyeing the banana so pop it over to her", "banana>C", LAB),
)
test_so_run_on49s_near = SO_RUN_ON.test(
    ("sam's taking minutes so the notepad goes to priya", None, OFFICE),
    ("sam's not taking minutes so the notepad goes to sam", None, OFFICE),
    ("the cup's meant for bob so take the apple over", None, CELL),
)


def test_so_run_on49s_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    SO_RUN_ON.refused_without((r49s._so_run_on49s,), monkeypatch)
