"""Session-45 phrasings of issue 12 (engineer 12r): corrections, choices and distributions,
counts, negation and exclusion, each as a family; docs/grounding.md, "Session 45 (engineer 12r)".
Each rule with sentences of its kind in other words and scenes than blind43's, and near forms that
must stay refused."""

from __future__ import annotations

import pytest

from hltl.errors import GroundingError
from hltl.grounding import _rewrites45r, offline
from hltl.grounding.offline import parse_instruction
from hltl.world.scene import Scene, load_scene
from tests.grounding.helpers import (
    CELL,
    CLASSROOM,
    DEPOT,
    KITCHEN,
    NURSERY,
    OFFICE,
    ROOT,
    WARD,
    WORKSHOP,
    PhrasingCases,
)

# the example scenes blind43 uses (one person and one thing; two people; four things)
T11, T12, T21, T41, T42, L24, L44, FIG1 = (
    load_scene(ROOT / f"examples/scenes/{n}.yaml")
    for n in ("1-1", "1-2", "2-1", "4-1", "4-2", "2-4-line", "4-4-line", "fig1")
)

CASES = PhrasingCases()

# -- corrections -----------------------------------------------------------------------------------

test_what_he_wanted = CASES.test(
    # _what_he_wanted45r
    ("Tape to Tom, scratch that, it's the gloves he wanted after his shift.", "gloves>B", DEPOT),
    ("Knife to Lena, no, it's the tongs she wanted after service.", "tongs>B", KITCHEN),
    (
        "Crisps to Bob, scratch that, it's the bottle he wanted after his bachata class.",
        "bottle>B",
        FIG1,
    ),
    ("Salt to Marco, scratch that, it's the lemon he wanted for the fish.", "lemon>A", KITCHEN),
    ("Salt to Marco, scratch that, it's the lemon she wanted.", None, KITCHEN),
    ("Salt to Marco, it's the lemon he wanted.", None, KITCHEN),
)

test_switch_to = CASES.test(
    # _switch_to45r
    ("Jug to Mr Lee. Oh wait, he's asleep; switch it to Mrs Khan.", "jug>C", WARD),
    (
        "Bottle to Person A. Oh wait, she's out at the abattoir till late; switch it to Person B.",
        "bottle>B",
        T41,
    ),
    ("Drill to Kofi. Hang on, he's gone home; swap it over to Jess.", "drill>B", WORKSHOP),
    ("Tape to Tom. Wait, he's on the road, move it to Mia.", "tape>A", DEPOT),
    ("Tape to Tom, then move it to Mia.", None, DEPOT),
    ("Tape to Tom. Oh, he's on the road, switch it to Mia.", None, DEPOT),
)

test_belongs_with = CASES.test(
    # _belongs_with45r
    (
        "Send the chips to Person B, no, sorry, muddled them up, the chips belong with Person A.",
        "chips>A",
        L24,
    ),
    ("Screws to Kofi, no, sorry, they belong with Jess.", "screws>B", WORKSHOP),
    ("Knife to Lena, sorry, my mistake, the knife goes with Marco.", "knife>A", KITCHEN),
    ("Knife to Lena, sorry, my mistake, the tongs go with Marco.", None, KITCHEN),
    ("Knife to Lena, the knife goes with Marco.", None, KITCHEN),
)

test_better_verb = CASES.test(
    # _better_verb45r
    (
        "Put the bottle down... no, actually, better give it to Person A for her "
        "uilleann piping lesson.",
        "bottle>A",
        T11,
    ),
    ("Put the drill in the locker, no, actually, best hand it to Kofi.", "drill>A", WORKSHOP),
    ("Teddy on the mat, wait, you'd better give it to Lily.", "teddy>A", NURSERY),
)

test_right_first = CASES.test(
    # _right_first45r
    (
        "Bottle to Person A... hmm, or... no, I had it right the first time, Person A.",
        "bottle>A",
        T12,
    ),
    ("Tape to Tom... or maybe... no, I was right the first time.", "tape>B", DEPOT),
    ("Stapler to Priya, hmm, no, I had it right first time, Priya.", "stapler>A", OFFICE),
    ("Stapler to Priya, hmm, no, I had it right first time, Sam.", None, OFFICE),
    ("Stapler to Priya and the notebook to Sam, hmm, no, I had it right first time.", None, OFFICE),
)

test_its_p_doing = CASES.test(
    # _its_p_doing45r
    (
        "Give Noah the ruler, no sorry, it's Zoe drawing the corset pattern, give it to her.",
        "ruler>C",
        CLASSROOM,
    ),
    (
        "Give Marco the tongs, no sorry, it's Lena plating up tonight, hand them to her.",
        "tongs>B",
        KITCHEN,
    ),
    (
        "Pass Noah the glue stick, sorry, it's Zoe gluing the poster, give it to her.",
        "glue>C",
        CLASSROOM,
    ),
    ("Pass Jess the drill, sorry, it's Kofi fixing the bellows, give it to her.", None, WORKSHOP),
    (
        "Give Noah the ruler, no sorry, it's Noah drawing the pattern, give it to him.",
        None,
        CLASSROOM,
    ),
)

test_one_who = CASES.test(
    # _one_who45r
    (
        "Teddy for Lily, whoops, she's too small for it, Ava's the one who wants the teddy.",
        "teddy>C",
        NURSERY,
    ),
    (
        "Tongs for Marco, oops, he's too busy for them now, Lena's the one who needs the tongs.",
        "tongs>B",
        KITCHEN,
    ),
    (
        "Apple for Bob, whoops, he's too full for it now, Carol's the one who wants the apple.",
        "apple>C",
        CELL,
    ),
    (
        "Teddy for Ava, whoops, she's too big for it now, Lily's the one who wants the teddy.",
        "teddy>A",
        NURSERY,
    ),
)

# -- whichever, any of, one of, both, each ---------------------------------------------------------

test_apiece_tail = CASES.test(
    # _apiece_tail45r
    (
        "The red book's for Noah and the green book's for Zoe, one apiece.",
        "book_red>B & book_green>C",
        CLASSROOM,
    ),
    (
        "The red mug's for Alice and the blue mug's for Bob, one each.",
        "mug_red>A & mug_blue>B",
        CELL,
    ),
    (
        "Give Priya the black pen and Sam the red pen, one apiece.",
        "pen_black>A & pen_red>B",
        OFFICE,
    ),
    (
        "Red block to Lily, green block to Ava, a block each.",
        "block_red>A & block_green>C",
        NURSERY,
    ),
    (
        "The small spanner for Kofi and the large one for Jess, one apiece.",
        "spanner_small>A & spanner_large>B",
        WORKSHOP,
    ),
    ("The red book's for Noah and the green book's for Noah, one apiece.", None, CLASSROOM),
    ("The red book and the green book for Noah, one apiece.", None, CLASSROOM),
    ("Give Alice the red mug and the blue mug and Bob the cup, one each.", None, CELL),
)

test_each_for_folk = CASES.test(
    # _each_for_folk45r
    (
        "Something apiece for the two night shift folk: cup to Alice, apple to Bob.",
        "cup>A & apple>B",
        CELL,
    ),
    (
        "Something apiece for the two speleology folk: bottle to Person A, chips to Person B.",
        "bottle>A & chips>B",
        T21,
    ),
    (
        "Something each for the two bed bound patients: the jug to Mr Lee, the grey "
        "blanket to Mrs Khan.",
        "jug>B & blanket_grey>C",
        WARD,
    ),
    (
        "Something apiece for the two speleology folk: bottle to Person A, chips to Person A.",
        None,
        T21,
    ),
    ("Something apiece for the three cave diving folk: cup to Alice, apple to Bob.", None, CELL),
    (
        "Something apiece for the two cave diving folk: cup to Alice, apple to Bob, "
        "chips to Carol.",
        None,
        CELL,
    ),
)

# -- counts and plurals ----------------------------------------------------------------------------

test_whats_wanted = CASES.test(
    # _whats_wanted45r
    ("The lone teddy's what Lily wants after her nap.", "teddy>A", NURSERY),
    ("The hammer's what Kofi needs after his welding.", "hammer>A", WORKSHOP),
    ("The lemon's what Lena is after for her drinks.", "lemon>B", KITCHEN),
    ("The lone apple's what Person B wants after his ice climbing.", "apple>B", T42),
    ("The salt's what Mr Novak is after for his soup.", "salt>C", KITCHEN),
    ("The torch's what I want.", None, WORKSHOP),
    ("The book's what Zoe needs.", None, CLASSROOM),
)

test_the_one = CASES.test(
    # _the_one45r
    ("Just the single cup to Person A, she's the one brewing up after shoeing.", "cup>A", L44),
    ("Tape to Tom, he's the one loading the van after lunch.", "tape>B", DEPOT),
    ("Give Lena the tongs, she's the one who's plating up after service.", "tongs>B", KITCHEN),
    ("Give Marco the tongs, she's the one plating up.", None, KITCHEN),
    ("Tape to Tom, Mia's the one sealing the boxes.", None, DEPOT),
)

# -- negation and exclusion ------------------------------------------------------------------------

test_no_not = CASES.test(
    # _no_not45r
    ("No, not in the box, give the stapler to Sam.", "stapler>B", OFFICE),
    ("No, not on a shelf, hand the bottle straight to Person A.", "bottle>A", T11),
    ("No, not on the table, give the cup to Carol.", "cup>C", CELL),
    ("No no, not in the locker, the drill goes to Kofi.", "drill>A", WORKSHOP),
    ("No, give the cup to Carol.", None, CELL),
    ("No, not the cup.", None, CELL),
)

test_isnt_its = CASES.test(
    # _isnt_its45r
    (
        "It isn't the bottle Person A's after, it's the chips, for her saltmaker's lunch.",
        "chips>A",
        T21,
    ),
    ("It isn't the red book Noah needs, it's the green one.", "book_green>B", CLASSROOM),
    ("It wasn't the ruler Zoe asked for, it was the scissors.", "scissors>C", CLASSROOM),
    (
        "It isn't the jug Mrs Khan is after, it's the tablets, her hip's playing up.",
        "pills>C",
        WARD,
    ),
    ("It's not the knife Marco wants, it's Lena.", None, KITCHEN),
    ("It isn't the red book Noah needs, it's the blue one.", None, CLASSROOM),
    ("It's not the knife that I want, it's the tongs.", None, KITCHEN),
)

test_which_itches = CASES.test(
    # _which_itches45r
    ("Any blanket for Mr Lee except the blue, which makes him sneeze.", "blanket_grey>B", WARD),
    ("Any blanket for Mrs Khan except the grey, which makes her itch.", "blanket_blue>C", WARD),
)

test_leave_it = CASES.test(
    # _leave_it45r
    (
        "Jess is poking about under the bellows and wants the torch, so leave the hammer.",
        "torch>B",
        WORKSHOP,
    ),
    ("Tom's loading the van and needs the tape, so leave the scanner.", "tape>B", DEPOT),
    ("Give Lena the tongs and leave the knife.", "tongs>B", KITCHEN),
    ("Sam wants the stapler, so leave the stapler.", None, OFFICE),
    ("Sam wants a pen, so leave the red pen.", None, OFFICE),
)


def test_rewrites_read_them(monkeypatch: pytest.MonkeyPatch) -> None:
    """Each case that reads is read by these rules: refused without them."""
    CASES.refused_without((*_rewrites45r._STEPS45R_FIRST, *_rewrites45r._STEPS45R), monkeypatch)


# -- refusals that name their readings -----------------------------------------------------------

UNCLEAR: list[tuple[str, Scene, tuple[str, ...]]] = [
    # other_k45r: "the other <kind>" when the request names none of that kind
    (
        "Give Mr Novak the salt, sorry, I meant the other plate.",
        KITCHEN,
        ("plate_white", "plate_blue"),
    ),
    ("Hand Noah the globe, no, the other book.", CLASSROOM, ("book_red", "book_green")),
    ("Tape to Tom, sorry, I mean the other box.", DEPOT, ("box_small", "box_medium", "box_large")),
    ("Take Alice the apple, sorry, I meant the other mug.", CELL, ("mug_red", "mug_blue")),
]


@pytest.mark.parametrize(("text", "scene", "readings"), UNCLEAR)
def test_refusals_name_readings(text: str, scene: Scene, readings: tuple[str, ...]) -> None:
    with pytest.raises(GroundingError) as refused:
        parse_instruction(text, scene)
    assert all(r in str(refused.value) for r in readings), str(refused.value)


def test_refusals_are_these(monkeypatch: pytest.MonkeyPatch) -> None:
    """Without these refusals, none of those refusals names all its readings."""
    mine = set(_rewrites45r.REFUSE45R)
    monkeypatch.setattr(offline, "_REFUSALS", tuple(r for r in offline._REFUSALS if r not in mine))
    for text, scene, readings in UNCLEAR:
        try:
            parse_instruction(text, scene)
        except GroundingError as refused:
            assert not all(r in str(refused) for r in readings), text
