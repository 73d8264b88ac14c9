"""Session-50 phrasings of issue 12 (engineer 12): blind48's politeness and fillers, wants and
needs and questions, each as a family (docs/grounding.md, "Session 50 (engineer 12)"). Each rule
with sentences in other words and scenes it reads (refused on main and with the rule taken out),
and near sentences that must stay refused."""

from __future__ import annotations

import pytest

from hltl.errors import GroundingError
from hltl.grounding import _rewrites50, offline
from hltl.grounding.offline import parse_instruction
from hltl.world.scene import Scene, load_scene
from tests.grounding.helpers import (
    CELL,
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

# the example scenes blind48 uses
DUO, T21, TWO, SQ, F42, L24, ONE, FIG1, F41, T12 = (
    load_scene(ROOT / f"examples/scenes/{n}.yaml")
    for n in (
        "2-2",
        "2-1",
        "two_arms",
        "4-4-square",
        "4-2",
        "2-4-line",
        "1-1",
        "fig1",
        "4-1",
        "1-2",
    )
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


# -- 'Is it okay with you to V' (_ok_with_you50) ---------------------------------------------------

OK_WITH_YOU = PhrasingCases()
test_ok_with_you = OK_WITH_YOU.test(
    (
        "Is it okay with you to give Person A the bottle now her snowshoeing's over?",
        "bottle>A",
        ONE,
    ),
    ("Is it okay with you to give Bob the apple?", "apple>B", CELL),
    ("Is it all right with you to pass Marco the lemon?", "lemon>A", KITCHEN),
    ("Is it alright with you to put the jug on the locker?", "jug@bedside", WARD),
    ("Is it okay with you to give the apple?", None, CELL),
    ("Is it okay with you to give Dave the apple?", None, CELL),
)


def test_ok_with_you_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    OK_WITH_YOU.refused_without((_rewrites50._ok_with_you50,), monkeypatch)


# -- 'now her X's over' closing a request (_now_over50) --------------------------------------------

NOW_OVER = PhrasingCases()
test_now_over = NOW_OVER.test(
    ("Could you give Carol the apple now her shift's over?", "apple>C", CELL),
    ("Would you pass Sam the stapler now his meeting is done?", "stapler>B", OFFICE),
    ("Can you give Jess the drill now her tea break's finished?", "drill>B", WORKSHOP),
    ("Could Mrs Khan have the magazine now her physio is over?", "magazine>C", WARD),
    ("Pass Sam the stapler now his meeting is done.", None, OFFICE),
    ("Could you give Carol the apple now his shift's over?", None, CELL),
    ("Could you give Carol the apple now the cup's over?", None, CELL),
    ("Could you give Dave the apple now her shift's over?", None, CELL),
)


def test_now_over_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    # (session 51: 12's way is the second way of 12s's `_now_over50s`, the family's one rule)
    from hltl.grounding import _rewrites50s

    NOW_OVER.refused_without((_rewrites50s._now_over50s,), monkeypatch)


# -- 'as someone reckons he's earned them' (_reckons50) --------------------------------------------

RECKONS = PhrasingCases()
test_reckons = RECKONS.test(
    ("How about the chips for Person B, as the tipster reckons he's earned them?", "chips>B", T21),
    ("How about the apple for Carol, as Bob says she's earned it?", "apple>C", CELL),
    ("The lemon for Marco, as the chef reckons he's earned it.", "lemon>A", KITCHEN),
    ("Could Sam have the stapler, as Priya thinks he's deserved it?", "stapler>B", OFFICE),
    ("How about the apple for Carol, as the tipster reckons?", None, CELL),
    ("How about the apple for Dave, as Bob says he's earned it?", None, CELL),
)


def test_reckons_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    RECKONS.refused_without((_rewrites50._reckons50,), monkeypatch)


# -- 'P's making Q's tea' closing a request (_making50) --------------------------------------------

MAKING = PhrasingCases()
test_making = MAKING.test(
    (
        "Would you stand the sippy cup on the high chair, Grandad's making Lily's tea?",
        "beaker@highchair",
        NURSERY,
    ),
    ("Put the knife on the rack, Lena's making Marco's dinner.", "knife@rack", KITCHEN),
    ("Put the jug on the locker, the nurse is doing Mr Lee's breakfast.", None, WARD),
)


def test_making_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    MAKING.refused_without((_rewrites50._making50,), monkeypatch)


# -- a remark that the person's old one broke (_old_one50) -----------------------------------------

OLD_ONE = PhrasingCases()
test_old_one = OLD_ONE.test(
    ("Bob fancies the red mug, his old one cracked at the pinhole camera club.", "mug_red>B", CELL),
    ("Carol wants the blue mug, her old one broke.", "mug_blue>C", CELL),
    ("Sam needs the stapler, his own one jammed this morning.", "stapler>B", OFFICE),
    ("Marco could do with the knife, his usual one went missing.", "knife>A", KITCHEN),
    ("Carol wants the blue mug, her old cup broke.", None, CELL),
    ("Dave wants the blue mug, his old one broke.", None, CELL),
)


def test_old_one_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    OLD_ONE.refused_without((_rewrites50._old_one50,), monkeypatch)


# -- 'nothing since breakfast' between commas (_nothing_since50) -----------------------------------

NOTHING_SINCE = PhrasingCases()
test_nothing_since = NOTHING_SINCE.test(
    ("Bob is famished, nothing since breakfast, he could murder the crisps.", "chips>B", FIG1),
    ("Carol's starving, nothing to eat since lunch, could she have the apple?", "apple>C", CELL),
    ("Marco is ravenous, nothing since the early shift, pass him the lemon.", "lemon>A", KITCHEN),
    (
        "Mrs Khan's hungry, had nothing since breakfast, she'd like the magazine.",
        "magazine>C",
        WARD,
    ),
    ("Carol's starving, nothing since the apple, could she have the cup?", None, CELL),
    ("Carol's starving, nothing since lunch.", None, CELL),
)


def test_nothing_since_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    NOTHING_SINCE.refused_without((_rewrites50._nothing_since50,), monkeypatch)


# -- 'to take her cough syrup' after a want (_to_take50) -------------------------------------------

TO_TAKE = PhrasingCases()
test_to_take = TO_TAKE.test(
    ("Person A needs the cup to take her cough syrup.", "cup>A", SQ),
    ("Bob needs the cup to take his tablets.", "cup>B", CELL),
    ("Bob needs the cup to take his apple.", None, CELL),
    ("Dave needs the cup to take his tablets.", None, CELL),
)


def test_to_take_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    TO_TAKE.refused_without((_rewrites50._to_take50,), monkeypatch)


# -- a count of hours or rounds of a pastime after 'after' (_span50) -------------------------------

SPAN = PhrasingCases()
test_span = SPAN.test(
    ("Person B is craving the apple after two hours of belly dancing.", "apple>B", F41),
    ("Carol is craving the apple after three rounds of squash.", "apple>C", CELL),
    ("Marco is gasping for the lemon after a couple of hours of chopping.", "lemon>A", KITCHEN),
    ("Carol is craving the apple after two hours of Bob.", None, CELL),
    ("Give Carol the apple after two hours of squash.", None, CELL),
)


def test_span_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    SPAN.refused_without((_rewrites50._span50,), monkeypatch)


# -- 'After a long day as a bookie,' opening a want (_long_day50) ----------------------------------

LONG_DAY = PhrasingCases()
test_long_day = LONG_DAY.test(
    ("After a long day as a bookie, Person A could do with the chips.", "chips>A", DUO),
    ("After a busy morning, Sam would like the stapler.", "stapler>B", OFFICE),
    ("After such a hard day on the line, Marco wants the lemon.", "lemon>A", KITCHEN),
    ("After a long day with the apple, Carol could do with the cup.", None, CELL),
    ("After a long day as a bookie, Dave could do with the chips.", None, CELL),
)


def test_long_day_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    LONG_DAY.refused_without((_rewrites50._long_day50,), monkeypatch)


# -- 'it's her first week as a vet nurse' closing a want (_first_week50) ---------------------------

FIRST_WEEK = PhrasingCases()
test_first_week = FIRST_WEEK.test(
    ("Person A would be glad of the bottle, it's her first week as a vet nurse.", "bottle>A", ONE),
    ("Carol would like the apple, it's her first day here.", "apple>C", CELL),
    ("Sam needs the stapler, it's his first week on the job.", "stapler>B", OFFICE),
    ("Carol would like the apple, it's her first week with the cup.", None, CELL),
    ("Dave would like the apple, it's his first day here.", None, CELL),
)


def test_first_week_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    FIRST_WEEK.refused_without((_rewrites50._first_week50,), monkeypatch)


# -- 'the thing P's most in need of is the X' (_thing_need50) --------------------------------------

THING_NEED = PhrasingCases()
test_thing_need = THING_NEED.test(
    (
        "Between you and me, the thing Person A's most in need of after the rag rugging is the "
        "bottle.",
        "bottle>A",
        T12,
    ),
    ("The thing Carol's most in need of is the apple.", "apple>C", CELL),
    (
        "Between you and me, the one thing Marco is sorely in need of is the lemon.",
        "lemon>A",
        KITCHEN,
    ),
    ("The thing Sam's really in need of after that meeting is the stapler.", "stapler>B", OFFICE),
    ("The thing Carol's most in need of after the cup is the apple.", None, CELL),
    ("The thing Dave's most in need of is the apple.", None, CELL),
)


def test_thing_need_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    THING_NEED.refused_without((_rewrites50._thing_need50,), monkeypatch)


# -- 'being the only one without a drink' closing a want (_only_one50) -----------------------------

ONLY_ONE = PhrasingCases()
test_only_one = ONLY_ONE.test(
    ("Person B would appreciate the bottle, being the only one without a drink.", "bottle>B", T21),
    ("Carol would like the apple, being the only one without a snack.", "apple>C", CELL),
    ("Marco needs the knife, being the only one who hasn't got a blade.", "knife>A", KITCHEN),
    (
        "Mrs Khan would appreciate the magazine, being the only one with no reading matter.",
        "magazine>C",
        WARD,
    ),
    ("Carol would like the apple, being the only one without a cup.", None, CELL),
    ("Dave would like the apple, being the only one without a snack.", None, CELL),
)


def test_only_one_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    ONLY_ONE.refused_without((_rewrites50._only_one50,), monkeypatch)


# -- 'P's thirsty and reaching for her X' (_reaching50) --------------------------------------------

REACHING = PhrasingCases()
test_reaching = REACHING.test(
    ("Lily's thirsty and reaching for her sippy cup.", "beaker>A", NURSERY),
    ("Ava's bored and reaching for the teddy.", "teddy>C", NURSERY),
    ("Carol's hungry and reaching for the apple.", "apple>C", CELL),
    ("Marco is peckish and asking for the lemon.", "lemon>A", KITCHEN),
    ("Lily's reaching for her sippy cup.", None, NURSERY),
    ("Dave's hungry and reaching for the apple.", None, CELL),
)


def test_reaching_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    REACHING.refused_without((_rewrites50._reaching50,), monkeypatch)


# -- 'and the X is what P's hankering for' after a request (_what_after50) -------------------------

WHAT_AFTER = PhrasingCases()
test_what_after = WHAT_AFTER.test(
    (
        "Person A wants the bottle, and the chips are what Person B's hankering for.",
        "bottle>A & chips>B",
        F42,
    ),
    ("Bob wants the cup, and the apple is what Carol's after.", "cup>B & apple>C", CELL),
    ("Bob wants the cup, and the apple is what Dave's after.", None, CELL),
    ("Bob wants the cup, and the sofa is what Carol's after.", None, CELL),
)


def test_what_after_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    WHAT_AFTER.refused_without((_rewrites50._what_after50,), monkeypatch)


# -- a question who wanted it, refused naming the people (_who_asked50) ----------------------------

WHO_ASKED = [
    ("Was it Mr Lee or Mrs Khan who asked for the magazine? I've forgotten.", WARD, ("B", "C")),
    (
        "Which patient was it that wanted the blue blanket, do you remember? Take it to them.",
        WARD,
        ("B", "C"),
    ),
    ("Was it Bob or Carol who wanted the apple?", CELL, ("B", "C")),
    ("Was it Tom or Mia that asked for the gloves? Can't remember.", DEPOT, ("A", "B")),
]


@pytest.mark.parametrize(("text", "scene", "pids"), WHO_ASKED)
def test_who_asked_names_the_people(text: str, scene: Scene, pids: tuple[str, ...]) -> None:
    with pytest.raises(GroundingError) as err:
        parse_instruction(text, scene)
    assert "asks who wanted it" in str(err.value)
    for pid in pids:
        assert f"Person {pid}" in str(err.value)


@pytest.mark.parametrize(
    ("text", "scene"),
    [
        ("Was it Mr Lee or Mrs Khan who asked for the magazine? Give it to Mr Lee.", WARD),
        ("Was it Bob or Dave who wanted the apple?", CELL),
        ("Which intern was it who asked for the stapler?", OFFICE),
    ],
)
def test_who_asked_near_refused_as_before(text: str, scene: Scene) -> None:
    with pytest.raises(GroundingError) as err:
        parse_instruction(text, scene)
    assert "asks who wanted it" not in str(err.value)


def test_who_asked_refused_with(monkeypatch: pytest.MonkeyPatch) -> None:
    """With the rule taken out, the questions are refused without the people named."""
    monkeypatch.setattr(
        offline,
        "_REFUSALS",
        tuple(r for r in offline._REFUSALS if r is not _rewrites50._who_asked50),
    )
    for text, scene, _pids in WHO_ASKED:
        with pytest.raises(GroundingError) as err:
            parse_instruction(text, scene)
        assert "asks who wanted it" not in str(err.value)
