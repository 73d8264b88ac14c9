"""Session-47 phrasings of issue 12 (engineer 12): blind45's politeness and fillers, wants and
needs and questions, each as a family (docs/grounding.md, "Session 47 (engineer 12)"). Each rule
with sentences in other words and scenes it reads (refused on main and with the rule taken out),
and near sentences that must stay refused."""

from __future__ import annotations

import pytest

from hltl.grounding import _rewrites47
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

# the example scenes blind45 uses
L24, T11, T12 = (load_scene(ROOT / f"examples/scenes/{n}.yaml") for n in ("2-4-line", "1-1", "1-2"))

# -- a courtesy on the hearer being free ('if you're not run off your feet') (_not_busy47) ---------

NOT_BUSY = PhrasingCases()
test_not_busy = NOT_BUSY.test(
    (
        "Go on then, if you're not run off your feet, let Person A have the bottle, bless you.",
        "bottle>A",
        T12,
    ),
    ("If you're not too busy, could Mr Lee have the jug?", "jug>B", WARD),
    ("Pass Marco the lemon if you're free.", "lemon>A", KITCHEN),
    ("The drill to Jess, if you're not snowed under.", "drill>B", WORKSHOP),
    (
        "If you're not rushed off your feet right now, the bib on the high chair.",
        "bib@highchair",
        NURSERY,
    ),
    ("If you're not busy, give him the stapler.", None, OFFICE),
    ("If Tom's not too busy, give him the tape.", None, DEPOT),
)


def test_not_busy_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    NOT_BUSY.refused_without((_rewrites47._not_busy47,), monkeypatch)


# -- a word of thanks glossed ('jullay, which is Ladakhi for thank you') (_gloss47) ----------------

GLOSS = PhrasingCases()
test_gloss = GLOSS.test(
    (
        "Ruth says jullay, which is Ladakhi for thank you, and asks nicely that the magazine be "
        "put on the locker.",
        "magazine@bedside",
        WARD,
    ),
    (
        "Kammagar, Yapese for thank you, and the flashlight to Kofi if you'd be so good.",
        "torch>A",
        WORKSHOP,
    ),
    ("Mahalo, Hawaiian for thanks, and the tape to Mia.", "tape>A", DEPOT),
    ("Dank je, which is Dutch for thanks, and the stapler for Priya.", "stapler>A", OFFICE),
    ("Kammagar, Kofi for thank you, and the flashlight to Jess.", None, WORKSHOP),
)


def test_gloss_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    GLOSS.refused_without((_rewrites47._gloss47,), monkeypatch)


# -- 'P says thanks and asks nicely that …' (_says_asks47) -----------------------------------------

SAYS_ASKS = PhrasingCases()
test_says_asks = SAYS_ASKS.test(
    (
        "Mrs Khan says thanks and asks politely that the jug be put on the trolley.",
        "jug@trolley",
        WARD,
    ),
    (
        "Priya says cheers and asks nicely that the stapler be put in the box.",
        "stapler@box",
        OFFICE,
    ),
    ("Ruth says no and asks nicely that the magazine be put on the locker.", None, WARD),
    ("Dave says thanks and asks nicely that the magazine be put on the locker.", None, WARD),
)


def test_says_asks_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    SAYS_ASKS.refused_without((_rewrites47._says_asks47,), monkeypatch)


# -- an occasion owned by a person ('before Lily's nap', 'for Priya's …') (_owned_occasion47) ------

OWNED_OCCASION = PhrasingCases()
test_owned_occasion = OWNED_OCCASION.test(
    (
        "Pretty please with a cherry on top, sit the teddy bear on the high chair before Lily's "
        "nap.",
        "teddy@highchair",
        NURSERY,
    ),
    ("Put the bib on the high chair ahead of Grandad's snooze.", "bib@highchair", NURSERY),
    ("Put the stapler in the box before Sam's filing session.", "stapler@box", OFFICE),
    ("Would you put the red pen on the desk for Priya's paper marbling?", "pen_red@desk", OFFICE),
    ("Would you pop the notebook in the box for Sam's filing?", "notebook@box", OFFICE),
    ("Could you give Sam the stapler for Priya's paper marbling?", None, OFFICE),
    ("Put the bib on the high chair before Lily's teddy.", None, NURSERY),
)


def test_owned_occasion_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    OWNED_OCCASION.refused_without((_rewrites47._owned_occasion47,), monkeypatch)


# -- wants and needs in other words ('in sore need of', 'keen to get hold of') (_want_said47) ------

WANT_SAID = PhrasingCases()
test_want_said = WANT_SAID.test(
    (
        "Person A's in sore need of the bottle, the escapologist's act left her wrung out.",
        "bottle>A",
        T11,
    ),
    ("Mrs Khan is in desperate need of the pills.", "pills>C", WARD),
    (
        "Noah is keen to get hold of the ruler, he's drawing up a yahtzee score sheet.",
        "ruler>B",
        CLASSROOM,
    ),
    ("Zoe would love to get her hands on the scissors.", "scissors>C", CLASSROOM),
    ("Tom's itching to get his hands on the scanner.", "scanner>B", DEPOT),
    ("Tom's itching to get his hands on Mia.", None, DEPOT),
)


def test_want_said_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    WANT_SAID.refused_without((_rewrites47._want_said47,), monkeypatch)


# -- a time of work named by its trade ('after a long shift as a pinsetter') (_as_trade47) ---------

AS_TRADE = PhrasingCases()
test_as_trade = AS_TRADE.test(
    ("Bob's hankering for the crisps after a long shift as a pinsetter.", "chips>B", CELL),
    ("Lena wants the tongs after a long shift as a barista.", "tongs>B", KITCHEN),
    ("Jess needs the torch after a long shift as a lamplighter.", "torch>B", WORKSHOP),
    ("Jess needs the torch after a long shift as the foreman.", None, WORKSHOP),
)


def test_as_trade_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    AS_TRADE.refused_without((_rewrites47._as_trade47,), monkeypatch)


# -- what a doing is for ('for loading the basketmaker's order onto his van') (_for_doing47) -------

FOR_DOING = PhrasingCases()
test_for_doing = FOR_DOING.test(
    (
        "Tom requires the work gloves for loading the basketmaker's order onto his van.",
        "gloves>B",
        DEPOT,
    ),
    (
        "Sam needs the stapler for binding the rector's notices into his folder.",
        "stapler>B",
        OFFICE,
    ),
    ("Mia needs the scanner for checking the tape.", None, DEPOT),
    ("Tom needs the gloves for putting the tape on the belt.", None, DEPOT),
)


def test_for_doing_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    FOR_DOING.refused_without((_rewrites47._for_doing47,), monkeypatch)


# -- 'all' before how one is ('she's all mucky', 'the kefir's all finished') (_all_how47) ----------

ALL_HOW = PhrasingCases()
test_all_how = ALL_HOW.test(
    ("Lily's wanting her bib, she's all mucky from making loom bands with Ava.", "bib>A", NURSERY),
    ("Could you pop the bowl into the sink now the kefir's all finished?", "bowl@sink", LAB),
    ("Could the spoon go in the sink now the custard's all eaten?", "spoon@sink", LAB),
    ("Lily wants the beaker, she's all thirsty from dancing with Grandad.", "beaker>A", NURSERY),
    ("Give Grandad the wipes, they're all Lily's.", None, NURSERY),
)


def test_all_how_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    ALL_HOW.refused_without((_rewrites47._all_how47,), monkeypatch)


# -- a closing remark's 'with P' ('she's mucky from painting with Grandad') (_with_other_read47) ---

WITH_OTHER_READ = PhrasingCases()
test_with_other_read = WITH_OTHER_READ.test(
    ("Lily wants the wipes, she's mucky from painting with Grandad.", "wipes>A", NURSERY),
    ("Grandad wants the wipes, he's sticky from baking with Ava.", "wipes>B", NURSERY),
    ("Give Lily the bib, he's been playing with Ava.", None, NURSERY),
)


def test_with_other_read_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    WITH_OTHER_READ.refused_without((_rewrites47._with_other_read47,), monkeypatch)


# -- requests in other question forms ('Is there any chance of …', 'be given') (_asked47) ---------

ASKED = PhrasingCases()
test_asked = ASKED.test(
    (
        "Is there any chance of the blue mug landing on the counter before the precentor's "
        "rehearsal?",
        "mug_blue@table",
        CELL,
    ),
    ("Is there any chance of the spanner ending up in the locker?", None, WORKSHOP),
    (
        "Would it be a hardship to get Person B the bottle while he rests from the step dancing?",
        "bottle>B",
        L24,
    ),
    ("Might Person A be given the bottle now she's back from the contra dancing?", "bottle>A", T11),
    (
        "Jullay in advance; is it possible for Person A to receive the bottle before her celesta "
        "solo?",
        "bottle>A",
        T12,
    ),
    (
        "Might the ruler find a home on the bookshelf before the scrapbook club?",
        "ruler@shelf",
        CLASSROOM,
    ),
    ("Could the teddy find its way onto the play mat?", "teddy@mat", NURSERY),
    ("Is it possible for her to receive the bib?", None, NURSERY),
    ("Could Mr Lee be handed the magazine while he rests from his physio?", "magazine>B", WARD),
    ("Would it be an imposition to pass Marco the lemon?", "lemon>A", KITCHEN),
    ("Could Mr Lee be handed the magazine while she rests?", None, WARD),
)


def test_asked_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    ASKED.refused_without((_rewrites47._asked47,), monkeypatch)


# -- 'so she can …' naming another person; 'the big sister, Ava,' (_so_can47) ----------------------

SO_CAN = PhrasingCases()
test_so_can = SO_CAN.test(
    ("Can the big sister, Ava, be handed the bib so she can feed Lily?", "bib>C", NURSERY),
    ("Give Tom the scanner so he can check Mia's parcels.", "scanner>B", DEPOT),
    ("Could Ava have the wipes so she can clean Lily up?", "wipes>C", NURSERY),
    ("Give Ava the bib so he can feed Lily.", None, NURSERY),
    ("Give Ava the bib so she can give Lily the teddy.", None, NURSERY),
    ("Can the grandpa, Ava, be handed the bib so she can feed Lily?", None, NURSERY),
)


def test_so_can_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    SO_CAN.refused_without((_rewrites47._so_can47,), monkeypatch)
