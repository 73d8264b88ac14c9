"""Session-48 phrasings of issue 12 (engineer 12): blind46's politeness and fillers, wants and
needs, pronouns and ellipsis and questions, each as a family (docs/grounding.md, "Session 48
(engineer 12)"). Each rule with sentences in other words and scenes it reads (refused on main and
with the rule taken out), and near sentences that must stay refused."""

from __future__ import annotations

import pytest

from hltl.grounding import _rewrites48
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

# the example scenes blind46 uses
TWO, SQ, L44, F42, DUO, L24, T21, FIG1, T11 = (
    load_scene(ROOT / f"examples/scenes/{n}.yaml")
    for n in ("two_arms", "4-4-square", "4-4-line", "4-2", "2-2", "2-4-line", "2-1", "fig1", "1-1")
)

# -- 'like' as a filler between commas (_like48) ---------------------------------------------------

LIKE = PhrasingCases()
test_like = LIKE.test(
    (
        "Um, so, like, whenever you're ready, could the cup go over to Person A? Much obliged.",
        "cup>A",
        L44,
    ),
    ("Like, the bottle to Bob, yeah?", "bottle>B", CELL),
    ("So, like, could Marco have the tongs?", "tongs>A", KITCHEN),
    ("Like, give him the cup.", None, CELL),
    ("Like Bob, Alice wants the cup.", None, CELL),
)


def test_like_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    LIKE.refused_without((_rewrites48._like48,), monkeypatch)


# -- a word of thanks glossed by where it is said ('as we say back home on Kosrae') (_gloss48) -----

GLOSS = PhrasingCases()
test_gloss = GLOSS.test(
    (
        "Kulo, as we say back home on Kosrae, could you pop the red mug up on the shelf for me "
        "when you get a sec?",
        "mug_red@shelf",
        CELL,
    ),
    (
        "Meitaki, that's what my nan says in Rarotongan, and now the cup for Person B, please.",
        "cup>B",
        F42,
    ),
    ("Ka pai, as we say back home in Rotorua, the apple for Person A.", "apple>A", F42),
    (
        "Grazie, that's what we say back home in Napoli, could Sam have the stapler?",
        "stapler>B",
        OFFICE,
    ),
    ("Kulo, as we say back home on Kosrae, could you give her the cup?", None, CELL),
)


def test_gloss_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    GLOSS.refused_without((_rewrites48._gloss48,), monkeypatch)


# -- the speaker saying who they are ('Sam here, the intern, could I …') (_here48) -----------------

HERE = PhrasingCases()
test_here = HERE.test(
    (
        "Hiya, sorry, Sam here, the intern, could I possibly have the stapler when you've a "
        "minute?",
        "stapler>B",
        OFFICE,
    ),
    (
        "Morning, Mia here, be a gem and set the small box on the belt, would you?",
        "box_small@conveyor",
        DEPOT,
    ),
    ("Hello, Priya here, the manager, can I have the notebook?", "notebook>A", OFFICE),
    ("Hi, Kofi here, pass me the torch, would you?", "torch>A", WORKSHOP),
    ("Hi, Tom here, the driver, pass me the gloves, would you?", "gloves>B", DEPOT),
    (
        "Morning, Ruth here, could I have the thermometer when you've a minute?",
        "thermometer>A",
        WARD,
    ),
    # the role is another's; no one of the scene so named
    ("Hiya, Sam here, the manager, could I have the stapler?", None, OFFICE),
    ("Hiya, Bob here, could I have the stapler?", None, OFFICE),
)


def test_here_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    HERE.refused_without((_rewrites48._here48,), monkeypatch)


# -- wants in other words ('would murder', 'set his sights on', 'a craving for') (_want_said48) ----

WANT_SAID = PhrasingCases()
test_want_said = WANT_SAID.test(
    (
        "Person A fancies the apple, and Person B would murder a bag of chips.",
        "apple>A & chips>B",
        L44,
    ),
    ("Person A would murder a packet of crisps.", "chips>A", TWO),
    ("Omar would murder a banana.", "banana>B", LAB),
    ("Lena would murder that lemon.", "lemon>B", KITCHEN),
    (
        "Person B's got his eye on the chips after all that double dutch; give them him.",
        "chips>B",
        L24,
    ),
    ("Kofi's got his eye on the torch after all that sanding; hand it him.", "torch>A", WORKSHOP),
    ("Ava's got her eye on the green block after all that hopscotch.", "block_green>C", NURSERY),
    # ('could murder a brew' is session 30's thirst: no thing named; the pronoun is another's)
    ("Person B would murder her crisps.", None, TWO),
    ("Dana would murder a brew.", None, LAB),
    # an order naming another thing after it (sessions 33, 34, 42)
    ("Lena would murder that lemon, give her the knife.", None, KITCHEN),
)


def test_want_said_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    WANT_SAID.refused_without((_rewrites48._want_said48,), monkeypatch)


# -- a stretch of time at a pastime ('after an afternoon on the cowbell') (_stretch48) -------------

STRETCH = PhrasingCases()
test_stretch = STRETCH.test(
    (
        "Person B has set his sights on the chips after an afternoon on the cowbell.",
        "chips>B",
        DUO,
    ),
    (
        "Person B has set his sights on the bottle after a long evening at the bingo.",
        "bottle>B",
        TWO,
    ),
    ("Tom wants the gloves after a long morning on the forklift.", "gloves>B", DEPOT),
    ("Noah needs the ruler after a whole afternoon on the trampoline.", "ruler>B", CLASSROOM),
    # an order: 'after' says when to act
    ("Give Bob the cup after an afternoon on the swings.", None, CELL),
)


def test_stretch_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    STRETCH.refused_without((_rewrites48._stretch48,), monkeypatch)


# -- a compound with hyphens in a pastime or purpose ('after her kite-flying') (_hyphened48) -------

HYPHENED = PhrasingCases()
test_hyphened = HYPHENED.test(
    (
        "Person A's got a craving for the chips after her kite-flying, and Person B would like "
        "the bottle.",
        "chips>A & bottle>B",
        T21,
    ),
    ("Zoe needs the glue stick for her dot-to-dot collage.", "glue>C", CLASSROOM),
    ("Person A's got a craving for the crisps after her bell-ringing.", "chips>A", TWO),
    ("Mrs Ortiz wants the glue stick for her end-of-term display.", "glue>A", CLASSROOM),
    ("Zoe wants the scissors after her cat's-cradle.", None, CLASSROOM),
)


def test_hyphened_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    HYPHENED.refused_without((_rewrites48._hyphened48,), monkeypatch)


# -- a closing apposition saying what the thing will be ('a sip between tunes') (_apposed48) -------

APPOSED = PhrasingCases()
test_apposed = APPOSED.test(
    (
        "Person B needs the cup for his penny whistle practice, a sip between tunes.",
        "cup>B",
        SQ,
    ),
    ("Bob wants the apple, a snack for the bus.", "apple>B", CELL),
    ("Lily wants the beaker, a drink between naps.", "beaker>A", NURSERY),
    ("Mia needs the scanner, a quick check before the lorry comes.", "scanner>A", DEPOT),
    # an order; a person named in it
    ("Give Bob the apple, a snack for Alice.", None, CELL),
)


def test_apposed_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    APPOSED.refused_without((_rewrites48._apposed48,), monkeypatch)


# -- a purpose with a verb the grounder reads or a particle ('to hang the new shelves') ------------

PURPOSE = PhrasingCases()
test_purpose = PURPOSE.test(
    ("Jess needs the power drill to hang the new shelves.", "drill>B", WORKSHOP),
    ("Jess needs the hanmer to knock together a stand for the serpent.", "hammer>B", WORKSHOP),
    ("Jess needs the hammer to knock together a stand.", "hammer>B", WORKSHOP),
    (
        "person a wants the chips and the apple to take up to the airfix club",
        "chips>A & apple>A",
        F42,
    ),
    ("Person B wants the cup to take along to the choir.", "cup>B", F42),
    ("Bob wants the crisps to take along to the darts match.", "chips>B", CELL),
    (
        "Jess needs the pair of spanners to strip down the old mangle for the laundress.",
        "spanner_small>B & spanner_large>B",
        WORKSHOP,
    ),
    ("Kofi needs the torch to sort out the fuse box.", "torch>A", WORKSHOP),
    # a thing of the scene, a person of it, an order
    ("Jess needs the drill to hang the torch.", None, WORKSHOP),
    ("Person B wants the cup to take along to Person A.", None, F42),
    ("Give Jess the drill to hang the shelves.", None, WORKSHOP),
    ("Kofi needs the torch to hand over the keys.", None, WORKSHOP),
    ("Mia needs the tape to patch up a box for Tom.", None, DEPOT),
)


def test_purpose_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    PURPOSE.refused_without((_rewrites48._purpose48,), monkeypatch)


# -- 'for her …' inside a list of wants ('for her paper snowman and noah the ruler') ---------------

FOR_THEIRS = PhrasingCases()
test_for_theirs = FOR_THEIRS.test(
    (
        "zoe needs the scissors for her paper snowman and noah the ruler",
        "scissors>C & ruler>B",
        CLASSROOM,
    ),
    ("Marco needs the knife for his fish pie and Lena the lemon.", "knife>A & lemon>B", KITCHEN),
    (
        "Priya wants the stapler for her minutes and Sam the red pen.",
        "stapler>A & pen_red>B",
        OFFICE,
    ),
    ("Zoe needs the scissors for his paper snowman and Noah the ruler", None, CLASSROOM),
)


def test_for_theirs_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    FOR_THEIRS.refused_without((_rewrites48._for_theirs48,), monkeypatch)


# -- a question closing with 'while he …' ('… while he tunes the cittern?') (_while_asked48) -------

WHILE_ASKED = PhrasingCases()
test_while_asked = WHILE_ASKED.test(
    ("Would you mind giving Person B the bottle while he tunes the cittern?", "bottle>B", FIG1),
    ("Could you pass Marco the tongs while he plates up?", "tongs>A", KITCHEN),
    ("Would you hand Dana the spoon while she stirs the buffer?", "spoon>A", LAB),
    ("Can you give Kofi the torch while he checks the van?", "torch>A", WORKSHOP),
    ("Could you give Person A the bottle while she warms up?", "bottle>A", TWO),
    # the pronoun is another's
    ("Could you pass Marco the tongs while she plates up?", None, KITCHEN),
    ("Could you give Person A the bottle while he warms up?", None, TWO),
)


def test_while_asked_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    WHILE_ASKED.refused_without((_rewrites48._while_asked48,), monkeypatch)


# -- 'P's done with the X, could you put it …?' (_done_with48) ------------------------------------

DONE_WITH = PhrasingCases()
test_done_with = DONE_WITH.test(
    ("Marco's done with the knife, could you put it on the worktop?", "knife@counter", KITCHEN),
    ("Priya's finished with the stapler, can it go in the box?", "stapler@box", OFFICE),
    ("Omar's done with the bowl, could you put it in the sink?", "bowl@sink", LAB),
    ("Tom's through with the tape, would you pop it on the pallet?", "tape@pallet", DEPOT),
    # a handover after it
    ("Marco's done with the knife, could you give it to Lena?", None, KITCHEN),
)


def test_done_with_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    DONE_WITH.refused_without((_rewrites48._done_with48,), monkeypatch)


# -- why a thing is placed: 'Emma keeps knocking it over' (_keeps48) -------------------------------

KEEPS = PhrasingCases()
test_keeps = KEEPS.test(
    ("Can the bowl go on the tray, Emma keeps knocking it over?", "bowl@tray", LAB),
    ("Could the lemon go on the rack, Marco keeps knocking it off?", "lemon@rack", KITCHEN),
    ("Put the jug on the locker, Mr Lee keeps knocking it over.", "jug@bedside", WARD),
    # no one of the scene; a handover
    ("Put the jug on the locker, Bob keeps knocking it over.", None, WARD),
    ("Give Mr Lee the jug, Ruth keeps knocking it over.", None, WARD),
    # taking or borrowing it is a want (session 44); two things (session 36)
    ("Put the torch in the locker, Jess keeps borrowing it.", None, WORKSHOP),
)


def test_keeps_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    KEEPS.refused_without((_rewrites48._keeps48,), monkeypatch)


# -- blind45's: the person said first by a pronoun, named after ('She's …, Person A is') ---------

SHE_IS = PhrasingCases()
test_she_is = SHE_IS.test(
    ("She's asking for the bottle, Person A is, so let her have it.", "bottle>A", T11),
    ("He wants the crisps, Bob does, so give them to him.", "chips>B", CELL),
    ("He's after the crisps, Bob is, so give them to him.", "chips>B", CELL),
    ("She's after the red mug, Carol is.", "mug_red>C", CELL),
    ("She wants the lemon, Lena does, so pass it over.", "lemon>B", KITCHEN),
    # the pronoun is not theirs
    ("She's after the red mug, Bob is.", None, CELL),
    ("He's asking for the bottle, Person A is, so let him have it.", None, T11),
)


def test_she_is_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    SHE_IS.refused_without((_rewrites48._she_is48,), monkeypatch)


# -- blind45's: who a person is, asked back with a tag ('Omar's the technician, isn't he?') -------

TAG = PhrasingCases()
test_tag = TAG.test(
    ("Omar's the technician, isn't he? Take him the bowl.", "bowl>B", LAB),
    ("Ruth's the nurse, isn't she? Hand her the thermometer.", "thermometer>A", WARD),
    ("Marco's the chef, isn't he? Pass him the tongs.", "tongs>A", KITCHEN),
    # two patients
    ("Mr Lee's the patient, isn't he? Take him the jug.", None, WARD),
    # the role or the pronoun is another's
    ("Omar's the doctor, isn't he? Take him the bowl.", None, LAB),
    ("Omar's the technician, isn't she? Take her the bowl.", None, LAB),
)


def test_tag_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    TAG.refused_without((_rewrites48._tag48,), monkeypatch)
