"""Session-50 phrasings of issue 12 (engineer 12s): blind48's negation and exclusion, typos and
lower case, each as a family (fresh sentences in other scenes, each refused on issue-lead
3667287b, and near sentences that stay refused); docs/grounding.md, "Session 50 (engineer
12s)"."""

from __future__ import annotations

import pytest

from hltl.grounding import _rewrites50s as r50s
from hltl.world.scene import load_scene
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

FIG1 = load_scene(ROOT / "examples/scenes/fig1.yaml")  # Person A (Alice), Person B (Bob)
DUO = load_scene(ROOT / "examples/scenes/2-2.yaml")  # Person A, Person B
ONE = load_scene(ROOT / "examples/scenes/1-1.yaml")  # Person A alone
F41 = load_scene(ROOT / "examples/scenes/4-1.yaml")  # Person A, Person B
L24 = load_scene(ROOT / "examples/scenes/2-4-line.yaml")  # Person A, Person B
T12 = load_scene(ROOT / "examples/scenes/1-2.yaml")  # Person A alone
T21 = load_scene(ROOT / "examples/scenes/2-1.yaml")  # Person A alone

# -- the negated cleft, its want said another way ------------------------------------------------

NOT_CLEFT = PhrasingCases()
test_not_cleft50s = NOT_CLEFT.test(
    (
        "It isn't the bottle Alice has her heart set on after the hooky mat session, it's the "
        "crisps.",
        "chips>A",
        FIG1,
    ),
    (
        "It's not the ruler Noah's after for the straw plaiting, it's the scissors.",
        "scissors>B",
        CLASSROOM,
    ),
    (
        "Marco didn't ask for the tongs, it's the knife he's after, for the make-up artist's "
        "birthday cake.",
        "knife>A",
        KITCHEN,
    ),
    (
        "It isn't the apple Bob has his heart set on after the darts match, it's the crisps.",
        "chips>B",
        CELL,
    ),
    ("It's not the cup Carol's after for the pub quiz, it's the apple.", "apple>C", CELL),
    ("It wasn't the cup Carol has her eye on, it's the bottle.", "bottle>C", CELL),
    (
        "Mr Lee didn't ask for the pills, it's the magazine he's after, for the long night.",
        "magazine>B",
        WARD,
    ),
    (
        "It isn't the stapler Sam has his heart set on after the team meeting, it's the notebook.",
        "notebook>B",
        OFFICE,
    ),
    ("It isn't the bottle Person A has her heart set on, it's the chips.", "chips>A", DUO),
)
test_not_cleft50s_near = NOT_CLEFT.test(
    ("It isn't the apple Bob has her heart set on, it's the crisps.", None, CELL),
    ("It isn't the bottle Person B has her heart set on, it's the chips.", None, DUO),
    ("Bob didn't ask for the apple, it's the cup she's after.", None, CELL),
    ("Bob didn't ask for the apple, it's the cup Carol's after.", None, CELL),
    ("It isn't the apple Bob has his heart set on for Carol, it's the crisps.", None, CELL),
    ("It's not the apple Bob's after, it's Carol.", None, CELL),
)


def test_not_cleft50s_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    NOT_CLEFT.refused_without((r50s._not_cleft50s,), monkeypatch)


# -- 'can P have X now her <doing>'s over' --------------------------------------------------------

NOW_OVER = PhrasingCases()
test_now_over50s = NOW_OVER.test(
    ("can person a have the bottle now her make-up artist shift is done", "bottle>A", T12),
    ("Could Kofi have the hammer now his tea break's over?", "hammer>A", WORKSHOP),
    ("Jess can have the drill now that her lunch is finished.", "drill>B", WORKSHOP),
    ("May Kofi have the screws now his meeting is over?", "screws>A", WORKSHOP),
    ("could marco have the knife now his prep shift is over", "knife>A", KITCHEN),
)
test_now_over50s_near = NOW_OVER.test(
    ("could marco have the knife now her shift is over", None, KITCHEN),
    ("Can Kofi have the hammer now the torch is done?", None, WORKSHOP),
    ("could marco have the knife now lena's shift is over", None, KITCHEN),
)


def test_now_over50s_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    # (session 51: 12's `_rewrites50.asked_now_over50` is this rule's second way)
    NOW_OVER.refused_without((r50s._now_over50s,), monkeypatch)


# -- 'could the X head over to P' -----------------------------------------------------------------

HEAD_OVER = PhrasingCases()
test_head_over50s = HEAD_OVER.test(
    (
        "Could the fchips head over to Person A, she's the bill sticker on our street.",
        "chips>A",
        L24,
    ),
    ("Could the lemon head over to Mr Novak, he's the one with the fish.", "lemon>C", KITCHEN),
    ("Can the salt head over to Lena?", "salt>B", KITCHEN),
    ("Could the stapler wander over to Sam, he's doing the mailout.", "stapler>B", OFFICE),
    ("Would the notebook head across to Priya?", "notebook>A", OFFICE),
)
test_head_over50s_near = HEAD_OVER.test(
    ("Could Marco head over to Lena.", None, KITCHEN),
    ("Could the lemon head over to Mr Novak, she's the one with the fish.", None, KITCHEN),
)


def test_head_over50s_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    HEAD_OVER.refused_without((r50s._head_over50s,), monkeypatch)


# -- the thing left out, named again in the reason after it ---------------------------------------

NOT_AGAIN = PhrasingCases()
test_not_again50s = NOT_AGAIN.test(
    (
        "Give Carol the blue mug, not the red, she says the red one's got a funny taste.",
        "mug_blue>C",
        CELL,
    ),
    ("Give Bob the red mug, not the blue, the blue one's chipped.", "mug_red>B", CELL),
    (
        "Hand Sam the black pen, not the blue, he says the blue one's run dry.",
        "pen_black>B",
        OFFICE,
    ),
)
test_not_again50s_near = NOT_AGAIN.test(
    ("Give Bob the red mug, not the blue, the apple's chipped.", None, CELL),
    ("Give Bob the red mug, not the blue, the green one's chipped.", None, CELL),
)


def test_not_again50s_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    NOT_AGAIN.refused_without((r50s._not_again50s,), monkeypatch)


# -- 'P wants no X, no Y, just the Z' --------------------------------------------------------

NO_NO_JUST = PhrasingCases()
test_no_no_just50s = NO_NO_JUST.test(
    ("Person A wants no chips, no bottle, just the apple.", "apple>A", F41),
    ("Bob wants no apple, no cup, just the crisps.", "chips>B", CELL),
    ("Sam wants no stapler, no notebook, just the black pen.", "pen_black>B", OFFICE),
    ("Priya needs no notebook and no stapler, only the red pen.", "pen_red>A", OFFICE),
)
test_no_no_just50s_near = NO_NO_JUST.test(
    ("Bob wants no apple, no cup, just Carol.", None, CELL),
    ("No apple, no cup, just the crisps.", None, CELL),
)


def test_no_no_just50s_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    NO_NO_JUST.refused_without((r50s._no_no_just50s,), monkeypatch)


# -- a reason naming one thing, then 'so not that one, <request>' --------------------------------

SO_NOT_THAT = PhrasingCases()
test_so_not_that50s = SO_NOT_THAT.test(
    (
        "Lily's thrown the red block on the floor twice, so not that one, the green block for her.",
        "block_green>A",
        NURSERY,
    ),
    ("Bob's dropped the blue mug twice, so not that one, the red mug for him.", "mug_red>B", CELL),
    (
        "The green cup's got a crack in it, so not that one, the white cup to Emma.",
        "cup_white>C",
        LAB,
    ),
    ("Ava's chewed the teddy, so not that one, the wipes for her.", "wipes>C", NURSERY),
)
test_so_not_that50s_near = SO_NOT_THAT.test(
    ("Bob's dropped the blue mug twice, so not that one, the blue mug for him.", None, CELL),
    ("Bob's dropped the blue mug, so not that one, the red mug for her.", None, CELL),
    (
        "Lily's thrown the red block on the floor twice, so not that one, the green block for him.",
        None,
        NURSERY,
    ),
    ("Omar's left the white cup in the sink, so not that one, the green cup for him.", None, LAB),
)


def test_so_not_that50s_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    SO_NOT_THAT.refused_without((r50s._so_not_that50s,), monkeypatch)


# -- 'for the <occasion> tomorrow' closing a want -------------------------------------------------

PURPOSE_WHEN = PhrasingCases()
test_purpose_when50s = PURPOSE_WHEN.test(
    ("Pferson A wants the bottle for the highlining trip tomorrow.", "bottle>A", ONE),
    ("Person A wants the bottle for the big trip tomorrow.", "bottle>A", ONE),
    ("Marco wants the tongs for the staff barbecue tonight.", "tongs>A", KITCHEN),
    ("Mrs Khan wants the magazine for the long train home tomorrow.", "magazine>C", WARD),
)
test_purpose_when50s_near = PURPOSE_WHEN.test(
    ("Person A wants the bottle for the bottle trip tomorrow.", None, ONE),
    ("Give Person A the bottle for the hiking trip tomorrow.", None, ONE),
)


def test_purpose_when50s_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    PURPOSE_WHEN.refused_without((r50s._purpose_when50s,), monkeypatch)


# -- 'to P on her way to X' ---------------------------------------------------------------------

ON_WAY = PhrasingCases()
test_on_way50s = ON_WAY.test(
    ("Hand the bottle to perszon A on her way to the straw plaiting, would you.", "bottle>A", T12),
    ("Hand the bottle to Person A on her way out, would you.", "bottle>A", T12),
    ("Pills for Mr Lee on his way to the day room, please.", "pills>B", WARD),
    ("Salt for Mr Novak on his way back.", "salt>C", KITCHEN),
)
test_on_way50s_near = ON_WAY.test(
    ("Hand the bottle to Person A on his way out.", None, T12),
    ("Give the knife to Lena on his way out.", None, KITCHEN),
    ("Give the knife to Lena on her way to table six.", None, KITCHEN),
)


def test_on_way50s_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    ON_WAY.refused_without((r50s._on_way50s,), monkeypatch)


# -- a closing weather remark with a surface as its place --------------------------------------

COLD_ON = PhrasingCases()
test_cold_on50s = COLD_ON.test(
    ("Work glives for Tom, it's cold on the belt.", "gloves>B", DEPOT),
    ("Gloves for Tom, it's freezing by the pallet.", "gloves>B", DEPOT),
    ("Lemon for Marco, it's roasting by the counter.", "lemon>A", KITCHEN),
)
test_cold_on50s_near = COLD_ON.test(
    ("Put the gloves on the pallet, it's cold on the belt.", None, DEPOT),
)


def test_cold_on50s_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    COLD_ON.refused_without((r50s._cold_on50s,), monkeypatch)


# -- 12c's fuzz (blind47): a remark after a fronted negation made the thing a handover -------------
# On issue-lead 3667287b each read `chips>A & bottle>A`: session 49's `_fronted_not49s` took the
# negated clause only where a stop or the end closed it; a comma closes it as well.

FRONTED_NOT = PhrasingCases()
test_fronted_not_comma50s = FRONTED_NOT.test(
    (
        "Let Person A at the chips; the bottle, though, she's not allowed near, it's for the "
        "bake sale",
        "chips>A",
        T21,
    ),
    (
        "Let Person A at the chips; the bottle, though, she's not allowed near, the boiler's "
        "playing up",
        "chips>A",
        T21,
    ),
    (
        "Let Person A at the chips; the bottle, though, she's not allowed near, for the ramblers.",
        "chips>A",
        T21,
    ),
    ("Give Person A the chips; the bottle, she won't drink, it's flat.", "chips>A", T21),
)
