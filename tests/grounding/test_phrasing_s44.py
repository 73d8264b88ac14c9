"""Session-44 phrasings of issue 12 (engineer 12): blind42's wants, pronouns and possessives,
courtesies and question forms, each as a family (docs/grounding.md, "Session 44 (engineer 12)").
Each rule with sentences in other words and scenes it reads (which fail with the rule taken out),
lower-cased or with a one-edit typo of a scene word, and near sentences that must stay refused."""

from __future__ import annotations

import pytest

from hltl.grounding import _rewrites44
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
    assert_case,
)

# two people named only 'Person A' and 'Person B' (the corpus's convention: Person A 'she', Person
# B 'he'), Alice and Bob with two arms, and one person alone
DUO = load_scene(ROOT / "examples/scenes/2-2.yaml")
TWO = load_scene(ROOT / "examples/scenes/two_arms.yaml")
ONE = load_scene(ROOT / "examples/scenes/1-1.yaml")
FIG1 = load_scene(ROOT / "examples/scenes/fig1.yaml")
F42 = load_scene(ROOT / "examples/scenes/4-2.yaml")

# -- a 'her' that is a person before a verb or what is handed (offline._SEXED widened): 12c's fuzz
# read "Bob keeps asking for the cup, so let her have it." as cup>B and "Noah wants the globe, so
# let her have it." as globe>B; the one person named is of the other sex, so someone else is meant


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        ("Bob keeps asking for the cup, so let her have it.", None, CELL),
        ("Bob keeps asking for the cup, so give her it.", None, CELL),
        ("Noah wants the globe, so let her have it.", None, CLASSROOM),
        ("Noah wants the globe, so let her take it.", None, CLASSROOM),
        ("Mr Lee is after the jug; pass her those.", None, WARD),
        ("Marco wants the tongs, let her keep them.", None, KITCHEN),
        # the pronoun agrees with the one person named: read as before
        ("Bob keeps asking for the cup, so let him have it.", "cup>B", CELL),
        ("Zoe wants the globe, so let her have it.", "globe>C", CLASSROOM),
        ("Carol keeps asking for the cup, so give her it.", "cup>C", CELL),
    ],
)
def test_her_before_a_verb_is_a_person(text: str, want: str | None, scene: object) -> None:
    assert_case(text, want, scene)  # type: ignore[arg-type]


# -- wants said by an idiom of longing or of going on about it (_want_words44) --------------------

WANTS = PhrasingCases()

test_want_words = WANTS.test(
    (
        "Person B has been on the tug crew since dawn and is gagging for the water bottle.",
        "bottle>B",
        DUO,
    ),
    ("Lena has been up since five and is dying for the lemon.", "lemon>B", KITCHEN),
    ("Person B said he's been dreaming about the chips all morning.", "chips>B", DUO),
    ("Mr Lee says he's been dreaming about the jug.", "jug>B", WARD),
    ("Priya's been daydreaming about the stapler.", "stapler>A", OFFICE),
    ("priya keeps banging on about stapler", "stapler>A", OFFICE),
    ("Person A keeps banging on about crisps, the poor thing's been log rolling.", "chips>A", DUO),
    ("Jess keeps harping on about screws.", "screws>B", WORKSHOP),
    ("Jess keeps harping on about scerws.", "screws>B", WORKSHOP),
    # the past; a person after it; a pronoun that disagrees with who said it; something else
    # handed after it (it may be instead)
    ("Sam was gagging for the red pen.", None, OFFICE),
    ("Sam's been dreaming about Priya.", None, OFFICE),
    ("Person B said she's been dreaming about the chips all morning.", None, DUO),
    ("Mr Lee says she's dying for the jug.", None, WARD),
    ("Sam keeps banging on about the stapler, give him the notebook.", None, OFFICE),
)


def test_want_words_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    WANTS.refused_without((_rewrites44._want_words44,), monkeypatch)


# -- a want in a cleft with a time or degree inside it (_cleft_time44) ----------------------------

CLEFTS = PhrasingCases()

test_cleft_time = CLEFTS.test(
    ("What Bob fancies right now is a packet of crisps.", "chips>B", FIG1),
    ("All Sam needs at the moment is the stapler.", "stapler>B", OFFICE),
    ("what mia fancies right now is the tape", "tape>A", DEPOT),
    ("What Lily fancies just now is the teddy.", "teddy>A", NURSERY),
    ("What lily fancies just now is the tedy.", "teddy>A", NURSERY),
    # a person for the thing; a packet of a kind the scene has two of
    ("What Priya fancies right now is Sam.", None, OFFICE),
    ("What Alice fancies right now is a packet of mugs.", None, CELL),
)


def test_cleft_time_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    CLEFTS.refused_without((_rewrites44._cleft_time44,), monkeypatch)


# -- a request asked as whether it could be done (_ask_chance44) ----------------------------------

CHANCE = PhrasingCases()

test_ask_chance = CHANCE.test(
    (
        "Would there be any chance of getting the crisps to Alice before she starts her mime "
        "workshop?",
        "chips>A",
        FIG1,
    ),
    ("Would there be any chance of putting the stapler in the box?", "stapler@box", OFFICE),
    ("is there any chance of moving the drill onto the workbench", "drill@bench", WORKSHOP),
    (
        "Might it be possible for Person A to get the chips, she's just in from the fish farm?",
        "chips>A",
        DUO,
    ),
    ("Might it be possible to bring Mr Lee the jug?", "jug>B", WARD),
    ("Might it be possible for Ruth to have the thermometre?", "thermometer>A", WARD),
    # no task said; a person who is not of the scene
    ("Any chance of the bottle?", None, FIG1),
    ("Would it be possible for Dave to get the jug?", None, WARD),
)


def test_ask_chance_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    CHANCE.refused_without((_rewrites44._ask_chance44,), monkeypatch)


# -- a proposal urged with 'why not do that?' (_why_not44, then session 42's _proposal42) ---------

WHY_NOT = PhrasingCases()

test_why_not = WHY_NOT.test(
    (
        "What if Person A had the apple and Person B the chips, why not do that?",
        "apple>A & chips>B",
        F42,
    ),
    ("What if Mia got the tape? Why don't you do that?", "tape>A", DEPOT),
    ("what if mrs khan had the magazine, why not just do that?", "magazine>C", WARD),
    # no proposal before it; a statement of what someone had
    ("Why not do that?", None, DEPOT),
    ("Person A had the apple, why not do that?", None, F42),
)


def test_why_not_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    WHY_NOT.refused_without((_rewrites44._why_not44,), monkeypatch)


# -- courtesies around the request (_courtesy44) ---------------------------------------------------

COURTESY = PhrasingCases()

test_courtesy = COURTESY.test(
    (
        "Chettirdim, friend, that's Tuvan for thanks; would you carry the crisps to Person A?",
        "chips>A",
        DUO,
    ),
    ("Rahmat, friend, that's Uzbek for thanks; would you give Bob the apple?", "apple>B", CELL),
    (
        "Suksma, robot — my Balinese gran taught me that word — could you bring Carol the red mug?",
        "mug_red>C",
        CELL,
    ),
    (
        "With all due respect, machine, Person A needs the bottle, thanking you kindly.",
        "bottle>A",
        ONE,
    ),
    ("With the greatest respect, the jug goes to Mr Lee, thanking you in advance.", "jug>B", WARD),
    ("Diolch — that's the Welsh word for thanks — pass Sam the red pen.", "pen_red>B", OFFICE),
    # the word glossed is a name of the scene (said to that person); no request after it
    ("Carol, robot — my gran taught me that word — could you bring her the red mug?", None, CELL),
    ("Mahalo, robot, that's Hawaiian for thank you.", None, CELL),
)


def test_courtesy_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    COURTESY.refused_without((_rewrites44._courtesy44,), monkeypatch)


# -- the thing first, then what its person said of it (_fronted_said44) --------------------------

FRONTED = PhrasingCases()

test_fronted_said = FRONTED.test(
    ("The apple, Person A said she'd have it.", "apple>A", F42),
    ("That stapler, Sam says he'd take it.", "stapler>B", OFFICE),
    ("the magazine, mrs khan said she'd have it", "magazine>C", WARD),
    # the pronoun disagrees with who said it (the convention's Person B 'he', a title)
    ("The apple, Person B said she'd have it.", None, F42),
    ("The magazine, Mr Lee said she'd love it.", None, WARD),
)


def test_fronted_said_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    FRONTED.refused_without((_rewrites44._fronted_said44,), monkeypatch)


# -- 'it' named after the request (_it_named44) ---------------------------------------------------

IT_NAMED = PhrasingCases()

test_it_named = IT_NAMED.test(
    ("Person A's waiting. Take it to her, the bottle.", "bottle>A", ONE),
    ("Hand it over to Mia, the tape.", "tape>A", DEPOT),
    ("give it to emma, the banana please", "banana>C", LAB),
    # a person not of the scene; two things after it
    ("Hand it over to Dave, the tape.", None, DEPOT),
)


def test_it_named_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    IT_NAMED.refused_without((_rewrites44._it_named44,), monkeypatch)


# -- the thing told apart by what one person did with it (_described44) ---------------------------

DESCRIBED = PhrasingCases()

test_described = DESCRIBED.test(
    ("Those crisps Alice left out, stick them on the shelf.", "chips@shelf", TWO),
    (
        "Those crisps are the ones Person B knocked off his lap during the gritter briefing, so "
        "return them to him.",
        "chips>B",
        DUO,
    ),
    ("The tape Tom dropped, give it to him.", "tape>B", DEPOT),
    ("the stapler sam left out, pop it in the box", "stapler@box", OFFICE),
    # a pronoun that disagrees with the person; another person after it; a kind the scene has two of
    ("Those crisps Alice left out, give them to him.", None, TWO),
    ("The tape Tom dropped, give it to Mia.", None, DEPOT),
    ("The pen Sam left out, put it in the box.", None, OFFICE),
)


def test_described_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    DESCRIBED.refused_without((_rewrites44._described44,), monkeypatch)
