"""Session-46 phrasings of issue 12 (engineer 12): blind44's politeness and fillers, wants and
needs, pronouns and ellipsis and questions, each as a family (docs/grounding.md, "Session 46
(engineer 12)"). Each rule with sentences in other words and scenes it reads (refused on main and
with the rule taken out), and near sentences that must stay refused."""

from __future__ import annotations

import pytest

from hltl.errors import GroundingError
from hltl.grounding import _rewrites46
from hltl.grounding.offline import parse_instruction
from hltl.world.scene import Scene
from tests.grounding.helpers import (
    CELL,
    CLASSROOM,
    DEPOT,
    KITCHEN,
    LAB,
    NURSERY,
    OFFICE,
    WARD,
    WORKSHOP,
    PhrasingCases,
)

# -- thanks ahead in another language opening the request (_thanks_ahead46) ----------------------

THANKS = PhrasingCases()
test_thanks_ahead = THANKS.test(
    ("Ngiyabonga so much, could you take Mr Lee the magazine?", "magazine>B", WARD),
    ("Diolch again, pass Marco the lemon, please.", "lemon>A", KITCHEN),
    ("Khublei in advance, could the red mug go across to Carol, please?", "mug_red>C", CELL),
    # a name of the scene, a name not of it: no word of thanks
    ("Ava in advance, could Lily have the teddy?", None, NURSERY),
    ("Dave in advance, could you take her the jug?", None, WARD),
)


def test_thanks_ahead_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    THANKS.refused_without((_rewrites46._thanks_ahead46,), monkeypatch)


# -- an apology for asking again ('…, only …') or for cutting in ('pardon me for …') (_apology46) --

APOLOGY = PhrasingCases()
test_apology = APOLOGY.test(
    ("Sorry to nag, only Jess is still waiting on the drill, would you?", "drill>B", WORKSHOP),
    ("Hate to be a pest, only Tom's still after the tape.", "tape>B", DEPOT),
    ("Excuse me for butting in, could Priya have the notebook?", "notebook>A", OFFICE),
    ("Forgive me for interrupting, the lemon for Marco, please.", "lemon>A", KITCHEN),
    ("Pardon me for barging in, the bib for Grandad if you would.", "bib>B", NURSERY),
    # what is left says not to, or names no one
    ("Sorry to nag, only not the tape for Tom.", None, DEPOT),
    ("Pardon me for butting in, give her the notebook.", None, OFFICE),
)


def test_apology_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    APOLOGY.refused_without((_rewrites46._apology46,), monkeypatch)


# -- 'would give her eye teeth for' (_give_teeth46) ---------------------------------------------

TEETH = PhrasingCases()
test_give_teeth = TEETH.test(
    ("Tom would give his back teeth for the tape right now.", "tape>B", DEPOT),
    ("Priya'd give her eye teeth for that stapler.", "stapler>A", OFFICE),
    ("Marco would give a kidney for the lemon.", "lemon>A", KITCHEN),
    # a person after 'for': no want of a thing
    ("Tom would give his back teeth for Mia.", None, DEPOT),
)


def test_give_teeth_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    TEETH.refused_without((_rewrites46._give_teeth46,), monkeypatch)


# -- 'the X would do her nicely / set him right', 'P reckons X would …' (_would_suit46) -----------

SUIT = PhrasingCases()
test_would_suit = SUIT.test(
    ("Lily's grizzly, the teddy would do her nicely.", "teddy>A", NURSERY),
    ("Mr Lee's flagging, the magazine would set him right.", "magazine>B", WARD),
    ("Tom's frozen, the gloves would see him right.", "gloves>B", DEPOT),
    ("Noah reckons the ruler would sort him out.", "ruler>B", CLASSROOM),
    ("Mrs Khan reckons the jug would set her right.", "jug>C", WARD),
    # the pronoun is not the person's, or another of the scene may be meant
    ("Mr Lee reckons the jug would set her right.", None, WARD),
    ("Alice reckons the apple would set him right.", None, CELL),
)


def test_would_suit_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    SUIT.refused_without((_rewrites46._would_suit46,), monkeypatch)


# -- 'all afternoon', 'all this way' in a remark; 'seeing he's' (_all_said46) -------------------

ALL_SAID = PhrasingCases()
test_all_said = ALL_SAID.test(
    ("Zoe's shattered after gluing all morning, she needs the scissors.", "scissors>C", CLASSROOM),
    ("How about passing Kofi the drill, seeing he's come all this way?", "drill>A", WORKSHOP),
    ("Marco's starving after chopping all evening, he'd love the lemon.", "lemon>A", KITCHEN),
)


def test_all_said_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    ALL_SAID.refused_without((_rewrites46._all_said46,), monkeypatch)


# -- 'Do you reckon X could …?' (_you_reckon46) -------------------------------------------------

RECKON = PhrasingCases()
test_you_reckon = RECKON.test(
    (
        "Do you reckon the stapler could go across to Priya, seeing as her meeting's soon?",
        "stapler>A",
        OFFICE,
    ),
    ("Do you think the drill could go in the locker?", "drill@locker", WORKSHOP),
    ("D'you reckon the lemon might go on the rack?", "lemon@rack", KITCHEN),
    # what it wraps is refused too
    ("Do you think Kofi could manage without the drill?", None, WORKSHOP),
    ("Do you reckon Tom could have it?", None, DEPOT),
)


def test_you_reckon_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    RECKON.refused_without((_rewrites46._you_reckon46,), monkeypatch)


# -- 'when you're done' closing the request (_when_done46) --------------------------------------

DONE = PhrasingCases()
test_when_done = DONE.test(
    ("Could you put the drill away in the locker when you're done?", "drill@locker", WORKSHOP),
    ("Pop the tongs on the rack when you're through.", "tongs@rack", KITCHEN),
    ("Would you put the stapler on the desk when you're all done?", "stapler@desk", OFFICE),
    ("Pop the tongs on the rack when you're done with them.", None, KITCHEN),
)


def test_when_done_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    DONE.refused_without((_rewrites46._when_done46,), monkeypatch)


# -- what the thing is for, with any verb (_to_purpose46) ---------------------------------------

PURPOSE = PhrasingCases()
test_to_purpose = PURPOSE.test(
    ("Could Dana have the spoon to stir the mixture?", "spoon>A", LAB),
    ("Tom needs the tape to wrap the courier's parcels.", "tape>B", DEPOT),
    ("Can Marco have the knife to slice the bread?", "knife>A", KITCHEN),
    ("Priya needs the stapler to bind the report.", "stapler>A", OFFICE),
    # a verb of handing over, a thing of the scene after it
    ("Can Marco have the knife to give the porter?", None, KITCHEN),
    ("Tom needs the tape to wrap the scanner.", None, DEPOT),
)


def test_to_purpose_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    PURPOSE.refused_without((_rewrites46._to_purpose46,), monkeypatch)


# -- a remark naming the thing, then the request by a pronoun (_remark_it46) --------------------

REMARK_IT = PhrasingCases()
test_remark_it = REMARK_IT.test(
    (
        "The porter's elbow keeps catching the lemon; up on the rack with it, would you.",
        "lemon@rack",
        KITCHEN,
    ),
    ("Mrs Khan's tablets are due by the clock; take them over to her.", "pills>C", WARD),
    ("The tape's Tom's. Hand it across to him, thanks.", "tape>B", DEPOT),
    ("The glue was saved for Zoe after assembly; pass it to her.", "glue>C", CLASSROOM),
    (
        "Since the safety talk Jess keeps on about the drill; let her have it, for peace.",
        "drill>B",
        WORKSHOP,
    ),
    (
        "Lily was after the teddy. Bring it her, please, she's back from the swings.",
        "teddy>A",
        NURSERY,
    ),
    # a negation, another person, two things, a condition, a request in the remark
    ("The tape isn't Tom's. Hand it across to him.", None, DEPOT),
    ("The tape's Tom's. Hand it across to her.", None, DEPOT),
    ("The tape or the gloves are Tom's. Hand it to him.", None, DEPOT),
    ("If the lemon's spare; take it to Marco.", None, KITCHEN),
    ("Mr Lee's tablets are due; take them over to her.", None, WARD),
    ("The apple was set aside for Bob; run it over to Carol.", None, CELL),
)


def test_remark_it_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    REMARK_IT.refused_without((_rewrites46._remark_it46,), monkeypatch)


# -- the place first, then 'with it' (_with_it46) -----------------------------------------------

WITH_IT = PhrasingCases()
test_with_it = WITH_IT.test(
    ("Up on the rack with them, the tongs I mean.", "tongs@rack", KITCHEN),
    ("Up on the rack with it.", None, KITCHEN),
)


def test_with_it_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    WITH_IT.refused_without((_rewrites46._with_it46,), monkeypatch)


# -- ', for peace' (_for_peace46) ----------------------------------------------------------------

PEACE = PhrasingCases()
test_for_peace = PEACE.test(
    ("Give Bob the apple, for peace.", "apple>B", CELL),
    (
        "Noah keeps going on about the ruler, give it to him, for peace and quiet.",
        "ruler>B",
        CLASSROOM,
    ),
)


def test_for_peace_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    PEACE.refused_without((_rewrites46._for_peace46,), monkeypatch)


# -- 'take her medication over to her' (_own_thing46) ---------------------------------------------

OWN = PhrasingCases()
test_own_thing = OWN.test(
    ("Mrs Khan is in pain, so would you take her medication over to her?", "pills>C", WARD),
    ("Would you take his blanket over to her?", None, WARD),
)


def test_own_thing_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    OWN.refused_without((_rewrites46._own_thing46,), monkeypatch)


# -- why not the other one of the kind (_other_too46) --------------------------------------------

OTHER = PhrasingCases()
test_other_too = OTHER.test(
    ("Give Zoe the red book, the green one's a bit babyish for her.", "book_red>C", CLASSROOM),
    ("Could Priya have the blue pen, the black one's too faint?", "pen_blue>A", OFFICE),
    ("Pass Dana the white cup, the green cup is too small.", "cup_white>A", LAB),
    # the one handed, a pronoun for no one given to, another kind of thing
    ("Give Zoe the red book, the red one's too hard for her.", None, CLASSROOM),
    ("Give Zoe the red book, the green one's too hard for him.", None, CLASSROOM),
    ("Could Priya have the blue pen, the stapler's too heavy?", None, OFFICE),
)


def test_other_too_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    OTHER.refused_without((_rewrites46._other_too46,), monkeypatch)


# -- 'that one' with no thing named: refused naming each thing (_that_one46) --------------------


@pytest.mark.parametrize(
    ("text", "scene", "names"),
    [
        ("Take that one to Tom as well.", DEPOT, ("box_small", "scanner", "tape")),
        ("Give this one to Bob.", CELL, ("cup", "bottle", "apple")),
    ],
)
def test_that_one_names_things(text: str, scene: Scene, names: tuple[str, ...]) -> None:
    with pytest.raises(GroundingError) as refused:
        parse_instruction(text, scene)
    assert all(n in str(refused.value) for n in names)


# -- blind43's four left: the thing not for P, a cleft naming Q (_not_for_cleft46) ---------------

NOT_FOR = PhrasingCases()
test_not_for_cleft = NOT_FOR.test(
    (
        "The lemon's not for Marco, it's Mr Novak who's after it, he's got fish.",
        "lemon>C",
        KITCHEN,
    ),
    ("The stapler isn't for Priya, it's Sam who's asking for it.", "stapler>B", OFFICE),
    ("The tape's not for Tom, it's Mia who's after it, she's been waiting.", "tape>A", DEPOT),
    # the same person, two people, a pronoun that is not the person's
    ("The tape's not for Tom, it's Tom who needs it.", None, DEPOT),
    ("The tape's not for Tom, it's Mia or Tom who's after it.", None, DEPOT),
    ("The tape's not for Tom, it's Mia who's after it, he's been waiting.", None, DEPOT),
)


def test_not_for_cleft_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    NOT_FOR.refused_without((_rewrites46._not_for_cleft46,), monkeypatch)


# -- 'after …' in an opening remark of what the person is doing (_doing_after46) ----------------

DOING_AFTER = PhrasingCases()
test_doing_after = DOING_AFTER.test(
    (
        "Zoe's sorting books after assembly and either book will do, so give her one.",
        "book_red>C | book_green>C",
        CLASSROOM,
    ),
    # a thing or a person of the scene after 'after'
    ("Jess is sanding planks after Kofi, so pass her the hammer.", None, WORKSHOP),
)


def test_doing_after_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    DOING_AFTER.refused_without((_rewrites46._doing_after46,), monkeypatch)


# -- a craft named bare after a want (_craft46) -------------------------------------------------

CRAFT = PhrasingCases()
test_craft = CRAFT.test(
    ("Marco wants the lemon after woodwork.", "lemon>A", KITCHEN),
    ("Sam needs the stapler after calligraphy.", "stapler>B", OFFICE),
    ("Mr Lee wants the magazine after taxidermy.", "magazine>B", WARD),
    # an event says when; an order after it is put off
    ("Marco wants the lemon after surgery.", None, KITCHEN),
    ("Marco wants the lemon after work.", None, KITCHEN),
    ("Give Marco the lemon after woodwork.", None, KITCHEN),
)


def test_craft_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    CRAFT.refused_without((_rewrites46._craft46,), monkeypatch)


# -- an opening reason naming nothing, then 'so' (_so_reason46) ----------------------------------

SO_REASON = PhrasingCases()
test_so_reason = SO_REASON.test(
    (
        "The wheelwright's invoice needs stamping, so any pen at all for Sam.",
        "pen_black>B | pen_blue>B | pen_red>B",
        OFFICE,
    ),
    ("The glazier's bill wants paying, so the knife for Marco, please.", "knife>A", KITCHEN),
    # the reason names a surface of the scene
    ("The porter's trolley needs oiling, so put the jug on it.", None, WARD),
)


def test_so_reason_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    SO_REASON.refused_without((_rewrites46._so_reason46,), monkeypatch)


# -- blind42's: a purpose with a doing after its verb and the person's his / her (_to_purpose46) --

PURPOSE_DOING = PhrasingCases()
test_purpose_doing = PURPOSE_DOING.test(
    ("Noah needs a ruler to finish drawing his chess board.", "ruler>B", CLASSROOM),
    # the his is not the person's
    ("Zoe needs a ruler to finish drawing his chess board.", None, CLASSROOM),
)


def test_purpose_doing_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    PURPOSE_DOING.refused_without((_rewrites46._to_purpose46,), monkeypatch)


# -- why or where exactly, closing a placement (_placed_so46) -----------------------------------

PLACED_SO = PhrasingCases()
test_placed_so = PLACED_SO.test(
    ("Put the cup on the shelf so Bob stops knocking it over.", "cup@shelf", CELL),
    ("Put the stapler on the desk so Sam knows where it is.", "stapler@desk", OFFICE),
    ("Put the cup on the table, near where Bob keeps his tools.", "cup@table", CELL),
    ("Pop the gloves on the pallet ready for Mia's round.", "gloves@pallet", DEPOT),
    # 'so P can have it' may be a handover; a handover before it
    ("Put the cup on the shelf so Bob can have it.", None, CELL),
    ("Give Bob the cup so Alice stops nagging.", None, CELL),
)


def test_placed_so_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    PLACED_SO.refused_without((_rewrites46._placed_so46,), monkeypatch)


# -- the speaker's pick 'I'd say', a pastime named by its doing (_bare_doing46) ---------------

BARE_DOING = PhrasingCases()
test_bare_doing = BARE_DOING.test(
    (
        "Carol's gagging for something to drink after line dancing, the bottle I'd say.",
        "bottle>C",
        CELL,
    ),
    (
        "Jess is itching for something to work with after sanding, the drill I'd think.",
        "drill>B",
        WORKSHOP,
    ),
    # an order after it is put off
    ("Give Bob the apple after cleaning.", None, CELL),
)


def test_bare_doing_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    BARE_DOING.refused_without((_rewrites46._bare_doing46,), monkeypatch)
