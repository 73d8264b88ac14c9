"""Session-50 phrasings of issue 12 (engineer 12): blind48's politeness and fillers, wants and
needs and questions, each as a family (docs/grounding.md, "Session 50 (engineer 12)"). Each rule
with sentences in other words and scenes it reads (refused on main and with the rule taken out),
and near sentences that must stay refused."""

from __future__ import annotations

import pytest

from hltl.grounding import _rewrites50
from hltl.world.scene import load_scene
from tests.grounding.helpers import (
    CELL,
    DEPOT,
    KITCHEN,
    LAB,
    OFFICE,
    ROOT,
    WARD,
    WORKSHOP,
    PhrasingCases,
)

# the example scenes blind48 uses
DUO, T21, TWO, SQ, F42, L24 = (
    load_scene(ROOT / f"examples/scenes/{n}.yaml")
    for n in ("2-2", "2-1", "two_arms", "4-4-square", "4-2", "2-4-line")
)

# -- a foreign word of thanks glossed by who says it and where (_gloss50) --------------------------

GLOSS = PhrasingCases()
test_gloss = GLOSS.test(
    (
        "Daalu, as my mum says back in Lagos, and the apple's for Person B, if you'd be so good.",
        "apple>B",
        SQ,
    ),
    (
        "Kinanaskomitin, as folk say out in Saskatchewan; the chips to Person B would be "
        "wonderful.",
        "chips>B",
        F42,
    ),
    ("Gràtzias, as they'd put it in Cagliari: chips to Person B, ta.", "chips>B", T21),
    ("Diolch, as they'd put it in Cardiff: the lemon for Marco.", "lemon>A", KITCHEN),
    ("Asante, as folk say out in Mombasa; the stapler to Sam, please.", "stapler>B", OFFICE),
    ("Dankie, as my nan says back in Durban, the magazine for Mrs Khan.", "magazine>C", WARD),
    ("Salamat, as they'd put it in Manila, the drill for Jess.", "drill>B", WORKSHOP),
    ("Tapadh leat, as my gran says up in Bob, could Carol have the cup?", None, CELL),
    ("Hello, as my gran says up in Stornoway, could Carol have the cup?", None, CELL),
    ("Tapadh leat, as my gran says up in Stornoway.", None, CELL),
)


def test_gloss_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    GLOSS.refused_without((_rewrites50._gloss50,), monkeypatch)


# -- 'only' opening the reason after an apology (_only50) ------------------------------------------

ONLY = PhrasingCases()
test_only = ONLY.test(
    (
        "Sorry to trouble you, only Bob's parched after the gorge walking, so the bottle to "
        "him, if you please.",
        "bottle>B",
        TWO,
    ),
    ("Sorry to trouble you, only Carol's starving, could she have the apple?", "apple>C", CELL),
    ("Apologies for this, only Sam needs the stapler, would you?", "stapler>B", OFFICE),
    (
        "I hate to ask, only Marco is waiting for the lemon, could you pass it to him?",
        "lemon>A",
        KITCHEN,
    ),
    ("Sorry, only Mrs Khan wants the magazine.", "magazine>C", WARD),
    ("Sorry to trouble you, only the cup, please.", None, CELL),
    ("Sorry to trouble you, only Bob's parched, so the bottle to her.", None, CELL),
    ("Sorry to trouble you, only Dave is parched, so the cup to him.", None, CELL),
)


def test_only_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    ONLY.refused_without((_rewrites50._only50,), monkeypatch)


# -- 'and no rush at all' between commas (_no_rush50) ----------------------------------------------

NO_RUSH = PhrasingCases()
test_no_rush = NO_RUSH.test(
    (
        "Whenever you're free, and no rush at all, Person A would like the chips, ever so kindly.",
        "chips>A",
        L24,
    ),
    ("When you get a sec, and no hurry at all, could Bob have the apple?", "apple>B", CELL),
    ("Whenever suits you, and no rush whatsoever, the stapler to Sam.", "stapler>B", OFFICE),
    ("In your own time, and no rush at all, Marco would like the lemon.", "lemon>A", KITCHEN),
    ("When you get a sec, and no rush at all.", None, CELL),
    ("When you get a sec, and no rush at all, could Dave have the apple?", None, CELL),
)


def test_no_rush_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    NO_RUSH.refused_without((_rewrites50._no_rush50,), monkeypatch)


# -- 'if it pleases you' (_pleases50) --------------------------------------------------------------

PLEASES = PhrasingCases()
test_pleases = PLEASES.test(
    (
        "If it pleases you, the spoon can go in the sink, the embryologist is done with it.",
        "spoon@sink",
        LAB,
    ),
    ("If it please you, the apple to Bob.", "apple>B", CELL),
    ("The magazine for Mrs Khan, if it pleases you.", "magazine>C", WARD),
    ("If it pleases you, the small box goes on the pallet.", "box_small@pallet", DEPOT),
    ("If it pleases Bob, the apple to him.", None, CELL),
    ("If it pleases you, the apple.", None, CELL),
)


def test_pleases_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    PLEASES.refused_without((_rewrites50._pleases50,), monkeypatch)


# -- 'With respect,' opening a request someone else said (_respect50) ------------------------------

RESPECT = PhrasingCases()
test_respect = RESPECT.test(
    (
        "With respect, the boss says the torch goes to Jess, who's off spelunking at the weekend, "
        "thank you kindly.",
        "torch>B",
        WORKSHOP,
    ),
    ("With respect, the matron says the jug goes to Mr Lee.", "jug>B", WARD),
    ("With respect, Priya says the stapler goes in the box.", "stapler@box", OFFICE),
    ("With respect, the matron says the jug goes to the doctor.", None, WARD),
    ("With respect, the matron says it goes to Mr Lee.", None, WARD),
)


def test_respect_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    RESPECT.refused_without((_rewrites50._respect50,), monkeypatch)


# -- 'so it's out of the way (of …)' closing a placing (_out_of_way50) -----------------------------

OUT_OF_WAY = PhrasingCases()
test_out_of_way = OUT_OF_WAY.test(
    (
        "Would you be able to pop the red mug down on the counter so it's out of the way of the "
        "sand sculpting photos?",
        "mug_red@table",
        CELL,
    ),
    ("Could you put the bowl on the tray so it's out of the way?", "bowl@tray", LAB),
    ("Pop the stapler in the box so that it's not in the way.", "stapler@box", OFFICE),
    ("Would you set the knife on the rack so it's out of Marco's way?", "knife@rack", KITCHEN),
    ("So it's out of the way.", None, CELL),
    ("Would you be able to pop the red mug down so it's out of the way?", None, CELL),
)


def test_out_of_way_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    OUT_OF_WAY.refused_without((_rewrites50._out_of_way50,), monkeypatch)


# -- 'as a thank you (for …)' after a request (_thank_you50) ---------------------------------------

THANK_YOU = PhrasingCases()
test_thank_you = THANK_YOU.test(
    (
        "Could the chips go to Person A, as a thank you for the belly dancing display?",
        "chips>A",
        L24,
    ),
    ("Could Carol have the apple, as a thank you for the help?", "apple>C", CELL),
    ("Could the magazine go to Mrs Khan, as a little thank-you?", "magazine>C", WARD),
    ("Give Sam the stapler, as a token of thanks for the filing.", "stapler>B", OFFICE),
    ("Could Carol have the apple, as a thank you for the cup?", None, CELL),
    ("As a thank you for the help.", None, CELL),
    ("Could Dave have the apple, as a thank you for the help?", None, CELL),
)


def test_thank_you_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    THANK_YOU.refused_without((_rewrites50._thank_you50,), monkeypatch)


# -- 'P get his / her hands on the X' (_hands_on50) ------------------------------------------------

HANDS_ON = PhrasingCases()
test_hands_on = HANDS_ON.test(
    (
        "Might Person B get his hands on the bottle, he's on stage with the conjuror in a bit?",
        "bottle>B",
        DUO,
    ),
    ("Could Carol get her hands on the apple?", "apple>C", CELL),
    ("Can Marco get his hands on the lemon?", "lemon>A", KITCHEN),
    ("Might Mrs Khan get her hands on the magazine, she's bored stiff?", "magazine>C", WARD),
    ("Might Person B get her hands on the bottle?", None, DUO),
    ("Could Carol get his hands on the apple?", None, CELL),
    ("Could Dave get his hands on the apple?", None, CELL),
    ("Could Carol get her hands on it?", None, CELL),
)


def test_hands_on_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    HANDS_ON.refused_without((_rewrites50._hands_on50,), monkeypatch)


# -- 'any chance of the X finding its way to P' (_finding50) ---------------------------------------

FINDING = PhrasingCases()
test_finding = FINDING.test(
    (
        "Is there any chance of the apple finding its way to Person A, she's off on a "
        "lichenologist's field trip?",
        "apple>A",
        SQ,
    ),
    ("Any chance of the cup making its way to Bob?", "cup>B", CELL),
    ("Is there any chance of the lemon finding its way over to Marco?", "lemon>A", KITCHEN),
    (
        "Would there be any chance of the stapler finding its way into the box?",
        "stapler@box",
        OFFICE,
    ),
    ("Any chance of the gloves finding their way to Tom?", "gloves>B", DEPOT),
    ("Is there any chance of the cup finding its way?", None, CELL),
    ("Any chance of the cup making its way to Dave?", None, CELL),
    ("Is there any chance of the sofa finding its way to Bob?", None, CELL),
)


def test_finding_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    FINDING.refused_without((_rewrites50._finding50,), monkeypatch)
