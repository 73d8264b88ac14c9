"""Session-45 phrasings of issue 12 (engineer 12): blind43's politeness and fillers, wants and
needs, pronouns and ellipsis and questions, each as a family (docs/grounding.md, "Session 45
(engineer 12)"). Each rule with sentences in other words and scenes it reads (which are refused
with the rule taken out), near sentences that must stay refused, and the refusals that now name
their readings."""

from __future__ import annotations

import pytest

from hltl.errors import GroundingError
from hltl.grounding import _rewrites45
from hltl.grounding.lexicon import Lexicon
from hltl.grounding.offline import parse_instruction
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
    assert_case,
)

# two people named only 'Person A' and 'Person B' (the corpus's convention: Person A 'she', Person
# B 'he')
SQ = load_scene(ROOT / "examples/scenes/4-4-square.yaml")

# -- a word of thanks in another language opening a question (_thanks_word45) -------------------

THANKS = PhrasingCases()
test_thanks_word = THANKS.test(
    ("Dankie, robot, could you take Mrs Khan the water jug?", "jug>C", WARD),
    (
        "Yakoke, robot, when you get a sec could you hand Tom the gloves? He's off to the "
        "weighbridge.",
        "gloves>B",
        DEPOT,
    ),
    (
        "Seremein, erm, could Priya have the notebook? She's got a board meeting.",
        "notebook>A",
        OFFICE,
    ),
    # a name not of the scene, a typo of one of the scene's names: not a word of thanks
    ("Dave, robot, could you take her the water jug?", None, WARD),
    ("Emmma, robot, could you hand her the spoon?", None, LAB),
)


def test_thanks_word_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    THANKS.refused_without((_rewrites45._thanks_word45,), monkeypatch)


# -- a remark closing the request that ends on a time (_remark_time45) -------------------------

REMARK_TIME = PhrasingCases()
test_remark_time = REMARK_TIME.test(
    ("Could Grandad have the teddy? He's off to the allotment after this.", "teddy>B", NURSERY),
    ("Could Mrs Khan have the magazine? She's off to x-ray later.", "magazine>C", WARD),
    ("Could Tom have the gloves? He's off to the weighbridge after this.", "gloves>B", DEPOT),
    # the remark's pronoun cannot be the person given to
    ("Pass Mr Lee the jug, she's got physio later.", None, WARD),
)


def test_remark_time_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    REMARK_TIME.refused_without((_rewrites45._remark_time45,), monkeypatch)


# -- ', now (that) she's …' (_now_she45) --------------------------------------------------------

NOW_SHE = PhrasingCases()
test_now_she = NOW_SHE.test(
    ("Could you give Zoe the ruler, now she's back from the library?", "ruler>C", CLASSROOM),
    ("Could you give Carol the cup, now she's done with choir practice?", "cup>C", CELL),
    ("Pass Mr Lee the jug, now she's back from physio.", None, WARD),
)


def test_now_she_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    NOW_SHE.refused_without((_rewrites45._now_she45,), monkeypatch)


# -- someone not of the scene left the thing about, then a request for 'it' (_left_about45) ------

LEFT = PhrasingCases()
test_left_about = LEFT.test(
    (
        "Um, the porter left the tongs lying about, could you pop them on the rack?",
        "tongs@rack",
        KITCHEN,
    ),
    (
        "The cleaner left the stapler lying around, could you put it on the desk?",
        "stapler@desk",
        OFFICE,
    ),
    # the pronoun is not of the thing's number
    ("The porter left the tongs lying about, could you put it on the rack?", None, KITCHEN),
)


def test_left_about_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    LEFT.refused_without((_rewrites45._left_about45,), monkeypatch)


# -- 'what with his …' (_what_with45) -----------------------------------------------------------

WHAT_WITH = PhrasingCases()
test_what_with = WHAT_WITH.test(
    ("Sam's been after the stapler all morning, what with his filing.", "stapler>B", OFFICE),
    ("What with his cough, Mr Lee could use the water jug.", "jug>B", WARD),
    ("Jess needs the torch, what with her night shift.", "torch>B", WORKSHOP),
    # a pronoun for a thing; a her that cannot be Mr Lee
    ("Sam's been after the stapler all morning, what with it being Monday.", None, OFFICE),
    ("Mr Lee could use the jug, what with her cough.", None, WARD),
)


def test_what_with_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    WHAT_WITH.refused_without((_rewrites45._what_with45,), monkeypatch)


# -- what someone not of the scene did to the person's things (_they_did45) ----------------------

THEY_DID = PhrasingCases()
test_they_did = THEY_DID.test(
    ("Mr Lee could use the jug, the porter drank all his water.", "jug>B", WARD),
    ("Person A's desperate for the chips, the tinker ate all her sandwiches.", "chips>A", SQ),
    # the doer is a person of the scene ('driver' is Tom); a her that cannot be Mr Lee
    ("Mia could use the gloves, the forklift driver borrowed her pair.", None, DEPOT),
    ("Mr Lee could use the jug, the porter drank all her water.", None, WARD),
)


def test_they_did_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    THEY_DID.refused_without((_rewrites45._they_did45,), monkeypatch)


# -- 'all over' a surface, 'coming apart' (_all_over45) ---------------------------------------

ALL_OVER = PhrasingCases()
test_all_over = ALL_OVER.test(
    ("There's mud all over the bench from Omar's boots, so he needs the sponge.", "sponge>B", LAB),
    ("Sam's folder is falling apart, he needs the stapler to fix it.", "stapler>B", OFFICE),
    ("Lily's tower keeps coming apart, she needs the red block.", "block_red>A", NURSERY),
)


def test_all_over_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    ALL_OVER.refused_without((_rewrites45._all_over45,), monkeypatch)


def test_apart_from_still_leaves_out() -> None:
    assert_case(
        "Zoe wants everything apart from the ruler.",
        "book_red>C & scissors>C & glue>C & book_green>C & globe>C",
        CLASSROOM,
    )


# -- 'before the X visits him' (_before_him45) --------------------------------------------------

BEFORE_HIM = PhrasingCases()
test_before_him = BEFORE_HIM.test(
    ("Tom needs the gloves before the inspector checks him.", "gloves>B", DEPOT),
    ("Mr Lee needs the jug before the physio sees him.", "jug>B", WARD),
    ("Noah needs the ruler before the examiner tests him.", "ruler>B", CLASSROOM),
    # 'him' cannot be Mrs Khan
    ("Mrs Khan needs the jug before the chaplain visits him.", None, WARD),
)


def test_before_him_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    BEFORE_HIM.refused_without((_rewrites45._before_him45,), monkeypatch)


# -- 'by trade' (_by_trade45) -------------------------------------------------------------------

BY_TRADE = PhrasingCases()
test_by_trade = BY_TRADE.test(
    ("Sam wants the stapler, he's a bookbinder by trade and loves it.", "stapler>B", OFFICE),
    ("Tom wants the gloves, he's a roofer by trade and needs them.", "gloves>B", DEPOT),
    ("Mr Lee wants the jug, she's a nurse by trade.", None, WARD),
)


def test_by_trade_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    BY_TRADE.refused_without((_rewrites45._by_trade45,), monkeypatch)


# -- what the person lacks, then a request handing it to them (_lacking45) -----------------------

LACKING = PhrasingCases()
test_lacking = LACKING.test(
    ("Jess hasn't had the torch yet, could you bring it to her?", "torch>B", WORKSHOP),
    ("Mr Lee's run out of tablets, could you bring him some?", "pills>B", WARD),
    ("Tom's lost his gloves again, give them to him.", "gloves>B", DEPOT),
    # the pronoun cannot be the person who lacks it
    ("Mrs Khan's run out of tablets, could you bring him some?", None, WARD),
    ("Person B hasn't had the cup yet, could you bring it to her?", None, SQ),
)


def test_lacking_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    LACKING.refused_without((_rewrites45._lacking45,), monkeypatch)


# -- 'X? P, please' (_thing_q45) ----------------------------------------------------------------

THING_Q = PhrasingCases()
test_thing_q = THING_Q.test(
    ("The torch? Jess, please.", "torch>B", WORKSHOP),
    ("The stapler? Sam, thanks, he's on the filing.", "stapler>B", OFFICE),
    ("The jug? Mr Lee, please, she's thirsty.", None, WARD),
)


def test_thing_q_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    THING_Q.refused_without((_rewrites45._thing_q45,), monkeypatch)


# -- 'she's back from X and wants it' (_back_and45) ---------------------------------------------

BACK_AND = PhrasingCases()
test_back_and = BACK_AND.test(
    (
        "The gloves are for Tom, he's in from the yard and wants them, take them over to him.",
        "gloves>B",
        DEPOT,
    ),
    ("The jug's for Mr Lee, he's back from physio and needs it.", "jug>B", WARD),
    ("The gloves are for Tom, she's in from the yard and wants them.", None, DEPOT),
)


def test_back_and_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    BACK_AND.refused_without((_rewrites45._back_and45,), monkeypatch)


# -- a pronoun, then ', the X I mean' (_i_mean45) ---------------------------------------------

I_MEAN = PhrasingCases()
test_i_mean = I_MEAN.test(
    ("Give them to Kofi, the screws I mean.", "screws>A", WORKSHOP),
    ("Tom wants them, the gloves I mean.", "gloves>B", DEPOT),
    # not of the pronoun's number; two things for one pronoun
    ("Priya wants them, the notebook I mean.", None, OFFICE),
    ("Priya wants it, the stapler and the notebook I mean.", None, OFFICE),
)


def test_i_mean_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    I_MEAN.refused_without((_rewrites45._i_mean45,), monkeypatch)


# -- 'Find the X;' before what is said of it (_find_first45) ------------------------------------

FIND = PhrasingCases()
test_find_first = FIND.test(
    (
        "Find the torch; Jess has been asking for it since the stocktake, give it to her.",
        "torch>B",
        WORKSHOP,
    ),
    (
        "Find the stapler; Priya has been asking for it since the audit, give it to her.",
        "stapler>A",
        OFFICE,
    ),
)


def test_find_first_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    FIND.refused_without((_rewrites45._find_first45,), monkeypatch)


# -- 'has had his eye on X since …' (_eye_on45) ---------------------------------------------------

EYE_ON = PhrasingCases()
test_eye_on = EYE_ON.test(
    (
        "Kofi's had his eye on the screws since the auction, so those go to him.",
        "screws>A",
        WORKSHOP,
    ),
    ("Tom's had his eye on the gloves since the pantomime, so those go to him.", "gloves>B", DEPOT),
)


def test_eye_on_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    EYE_ON.refused_without((_rewrites45._eye_on45,), monkeypatch)


# -- refusals that name their readings (_same_as45, _it_unnamed45) ------------------------------


@pytest.mark.parametrize(
    ("text", "scene", "readings"),
    [
        ("Priya's after the same pen as yesterday.", OFFICE, ("pen_black", "pen_blue", "pen_red")),
        ("Mrs Khan wants the same blanket as last night.", WARD, ("blanket_blue", "blanket_grey")),
        (
            "Kofi's still waiting on it after the match, can you run it over to him?",
            WORKSHOP,
            ("drill", "hammer", "screws", "torch"),
        ),
        (
            "Sam's still waiting on it after the audit, can you take it to him?",
            OFFICE,
            ("notebook", "stapler", "pen_red"),
        ),
    ],
)
def test_refused_naming_the_readings(text: str, scene: Scene, readings: tuple[str, ...]) -> None:
    with pytest.raises(GroundingError) as err:
        parse_instruction(text, scene)
    assert all(r in str(err.value) for r in readings), str(err.value)


@pytest.mark.parametrize(
    ("text", "scene"),
    [
        # one stapler: not ours to name; a thing named besides
        ("Sam's after the same stapler as yesterday.", OFFICE),
        ("Carol's still waiting on a drink, can you take it over to her?", CELL),
    ],
)
def test_refusals_left_to_the_other_rules(text: str, scene: Scene) -> None:
    assert _rewrites45._same_as45(text, Lexicon.of(scene)) == text
    assert _rewrites45._it_unnamed45(text, Lexicon.of(scene)) == text
