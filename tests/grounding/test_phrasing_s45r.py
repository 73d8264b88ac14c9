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
    LAB,
    NURSERY,
    OFFICE,
    ROOT,
    WARD,
    WORKSHOP,
    PhrasingCases,
    assert_case,
)

# the example scenes blind43 uses (one person and one thing; two people; four things)
T11, T12, T21, T41, T42, L24, L44, FIG1, TWO = (
    load_scene(ROOT / f"examples/scenes/{n}.yaml")
    for n in ("1-1", "1-2", "2-1", "4-1", "4-2", "2-4-line", "4-4-line", "fig1", "two_arms")
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

test_mind_which = CASES.test(
    # _mind_which45r
    (
        "Person B's heading to the cooperage; let him take any one of the cup, the apple "
        "or the chips, he doesn't mind which.",
        "cup>B | apple>B | chips>B",
        L44,
    ),
    (
        "Let Lena take any one of the knife, the lemon or the tongs, she doesn't mind which.",
        "knife>B | lemon>B | tongs>B",
        KITCHEN,
    ),
    (
        "Tom's loading up; let him take the tape or the gloves, he doesn't mind which.",
        "tape>B | gloves>B",
        DEPOT,
    ),
    (
        "Carol's off out; let her take the cup or the apple, she doesn't care which.",
        "cup>C | apple>C",
        CELL,
    ),
    ("Give Sam the black pen and the red pen, he doesn't mind which.", None, OFFICE),
    ("Give Mrs Khan the jug or the magazine, he doesn't mind which.", None, WARD),
)

test_one_of_list = CASES.test(
    # _one_of_list45r
    (
        "Jess is off home; let her take any one of the drill, the hammer or the torch.",
        "drill>B | hammer>B | torch>B",
        WORKSHOP,
    ),
    (
        "Tom's loading up; let him take any one of the tape, the gloves or the scanner.",
        "tape>B | gloves>B | scanner>B",
        DEPOT,
    ),
    ("Bob can have one of the cup, the apple or the plate.", None, CELL),
)

test_one_of_them = CASES.test(
    # _one_of_them45r
    (
        "Your call which: the bottle or the chips, one of them goes to Person B before "
        "his dog sled run.",
        "bottle>B | chips>B",
        T42,
    ),
    ("The tape or the gloves, one of them goes to Tom.", "tape>B | gloves>B", DEPOT),
    ("The teddy or the bib, just one of them to Ava.", "teddy>C | bib>C", NURSERY),
    ("The tape or the gloves, both of them go to Tom.", None, DEPOT),
)

test_go_whichever = CASES.test(
    # _go_whichever45r
    (
        "Go whichever way round suits the arm, just get the bottle to Person A before "
        "she sets off for the coracle race.",
        "bottle>A",
        T11,
    ),
    ("Go whichever way suits you, just get the drill to Kofi.", "drill>A", WORKSHOP),
)

test_which_first = CASES.test(
    # _which_first45r
    (
        "Whichever's nearer the arm, the bottle or the crisps, goes to Alice, she's not bothered.",
        "bottle>A | chips>A",
        TWO,
    ),
    (
        "Whichever's closer, the stapler or the notebook, goes to Priya.",
        "stapler>A | notebook>A",
        OFFICE,
    ),
    (
        "Whichever is handier, the jug or the magazine, goes to Mr Lee, he won't mind.",
        "jug>B | magazine>B",
        WARD,
    ),
    ("Whichever's closer, the stapler or Sam, goes to Priya.", None, OFFICE),
)

test_wants_to_do = CASES.test(
    # _wants_to_do45r
    (
        "Lily's grizzling for a block, doesn't matter which of the two, she just wants "
        "to chew one.",
        "block_red>A | block_green>A",
        NURSERY,
    ),
    (
        "Ava wants a block, either one, she only wants to stack one.",
        "block_red>C | block_green>C",
        NURSERY,
    ),
    (
        "Bob wants a mug, doesn't matter which, he just wants to hold one.",
        "mug_red>B | mug_blue>B",
        CELL,
    ),
    ("Bob wants a mug, doesn't matter which, she just wants to hold one.", None, CELL),
)

test_will_do_one = CASES.test(
    # _will_do_one45r
    (
        "Emma is rinsing brushes after lampwork and either cup will do, so take her one.",
        "cup_green>C | cup_white>C",
        LAB,
    ),
    (
        "Carol's back from the gym and either mug will do, so hand her one.",
        "mug_red>C | mug_blue>C",
        CELL,
    ),
    (
        "Sam's signing forms and any pen will do, so give him one.",
        "pen_black>B | pen_blue>B | pen_red>B",
        OFFICE,
    ),
    ("Mrs Khan's cold and either blanket will do, so take him one.", None, WARD),
)


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        # offline._them_after_choice33s: 'one of them' after a choice is the one chosen (a bare
        # 'them' after it stays refused)
        ("The cup or the apple, one of them to Alice.", "cup>A | apple>A", CELL),
        ("The tape or the gloves, one of them goes to Tom.", "tape>B | gloves>B", DEPOT),
        ("Whichever you can reach first, the cup or the apple, hand them to Alice.", None, CELL),
    ],
)
def test_one_of_them_is_the_one(text: str, want: str | None, scene: Scene) -> None:
    assert_case(text, want, scene)


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
