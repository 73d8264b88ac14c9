"""Session-44 phrasings of issue 12 (engineer 12r): negation and exclusion, corrections, counts,
choices and distributions, each as a family; docs/grounding.md, "Session 44 (engineer 12r)". Each
rule with sentences of its kind in other words and scenes than blind42's, lower case and a typo,
and near forms that must stay refused."""

from __future__ import annotations

import pytest

from hltl.errors import GroundingError
from hltl.grounding import _rewrites44r, offline
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

# the one-person, one-object scene of blind42's "one" entries
T11 = load_scene(ROOT / "examples/scenes/1-1.yaml")
T21, T41 = (load_scene(ROOT / f"examples/scenes/{n}.yaml") for n in ("2-1", "4-1"))
TWO = load_scene(ROOT / "examples/scenes/two_arms.yaml")
SQ = load_scene(ROOT / "examples/scenes/4-4-square.yaml")

CASES = PhrasingCases()

# -- corrections -----------------------------------------------------------------------------------

test_reason_fix = CASES.test(
    # _reason_fix44r: a cue, maybe a reason, then what takes the place of the request's person,
    # place or thing
    ("Salt to Marco. Ooh wait, he's got some, make it Lena.", "salt>B", KITCHEN),
    (
        "Tongs for Lena; hang on, my mistake, she's off today, they're for Marco.",
        "tongs>A",
        KITCHEN,
    ),
    ("Tongs to Lena. No hang on, she's got her own, Marco should have them.", "tongs>A", KITCHEN),
    ("Tongs to Lena, correction, Marco's at the grill so they're his.", "tongs>A", KITCHEN),
    (
        "Put the lemon on the counter, oh hang about, it's sticky, the rack's better.",
        "lemon@rack",
        KITCHEN,
    ),
    ("Stapler to Sam, correction, Priya's filing so it's hers.", "stapler>A", OFFICE),
    ("Jug for Mr Lee. Wait, he's asleep, make it Mrs Khan.", "jug>C", WARD),
    ("salt to marco. ooh wait, he's got some, make it lena.", "salt>B", KITCHEN),
    # near forms: no cue that takes it back, two requests, a reason that names more, 'and', a
    # pronoun that is not the person
    ("Salt to Marco. Oh, he's got some, make it Lena.", None, KITCHEN),
    ("Salt to Marco and the knife to Lena. Wait, he's got some, make it Mr Novak.", None, KITCHEN),
    ("Salt to Marco. Wait, the knife's there too, make it Lena.", None, KITCHEN),
    ("Salt to Marco. Wait, he's got some, and make it Lena.", None, KITCHEN),
    ("Tongs to Lena, correction, Marco's at the grill so they're hers.", None, KITCHEN),
)


test_after_cue = CASES.test(
    # _after_cue44r: "no, you know what, …" and "sorry, I misspoke there, …"
    ("Put the drill on the bench, no, you know what, hand it to Jess.", "drill>B", WORKSHOP),
    ("The bowl should go to Omar, sorry, I misspoke there, to Emma.", "bowl>C", LAB),
    ("put the drill on the bench, no, you know what, hand it to jess", "drill>B", WORKSHOP),
    # near form: no correction before it
    ("You know what, give Omar the bowl.", None, LAB),
)

test_stays_out = CASES.test(
    # _stays_out44r: a correction, then the thing taken out "stays out"
    ("Salt on the counter, I mean the lemon, the salt stays out.", "lemon@counter", KITCHEN),
    ("Hammer in the locker, I mean the torch, the hammer stays out.", "torch@locker", WORKSHOP),
    ("hammer in the locker, i mean the torch, the hammer stays out", "torch@locker", WORKSHOP),
    # near forms: another thing stays out, or no correction
    ("Hammer in the locker, I mean the torch, the drill stays out.", None, WORKSHOP),
    ("Hammer in the locker and the torch, the hammer stays out.", None, WORKSHOP),
)

# -- negation and exclusion ------------------------------------------------------------------------

test_no_for = CASES.test(
    # _no_for44r: a thing P is not to have, then what P is to have
    ("No salt for Mr Novak, pass him the lemon instead.", "lemon>C", KITCHEN),
    ("No teddy for Lily, give her the beaker instead.", "beaker>A", NURSERY),
    ("No stapler for Sam, hand him the notebook instead.", "notebook>B", OFFICE),
    ("no salt for mr novak, pass him the lemon instead", "lemon>C", KITCHEN),
    # near forms: another person, the same thing, a pronoun that is not the person
    ("No salt for Mr Novak, pass Lena the lemon instead.", None, KITCHEN),
    ("No salt for Mr Novak, pass him the salt instead.", None, KITCHEN),
    ("No salt for Mr Novak, pass her the lemon instead.", None, KITCHEN),
)

test_not_aside = CASES.test(
    # _not_aside44r: who does not get it, said as an aside after the person who does
    ("Marco, not the new lad on the pass, gets the tongs.", "tongs>A", KITCHEN),
    ("Lena, not the chap from table six, should have the lemon.", "lemon>B", KITCHEN),
    ("Mrs Khan, not the lady in the next bed, gets the jug.", "jug>C", WARD),
    ("marco, not the new lad on the pass, gets the tongs", "tongs>A", KITCHEN),
    # near forms: the aside names a thing, or the person
    ("Marco, not the knife, gets the tongs.", None, KITCHEN),
    ("Marco, not Marco, gets the tongs.", None, KITCHEN),
)

test_said_leave = CASES.test(
    # _said_leave44r: a person saying to leave a thing, then what they are after
    ("Lena says to skip the salt, she's only after the lemon.", "lemon>B", KITCHEN),
    ("Mr Lee said to leave the jug, he's only after the magazine.", "magazine>B", WARD),
    ("Tom says to skip the tape, he's only after the gloves.", "gloves>B", DEPOT),
    ("tom says to skip the tape, he's only after the gloves", "gloves>B", DEPOT),
    # near forms: a pronoun that is not the person, a place
    ("Mr Lee said to leave the jug, she's only after the magazine.", None, WARD),
    ("Lena said to leave the salt on the counter.", None, KITCHEN),
)

test_skip_and = CASES.test(
    # _skip_and44r: "skip X and <request>", maybe after a remark about the request's person
    ("Lena's not hungry, so skip the lemon and pass her the salt.", "salt>B", KITCHEN),
    ("Mr Lee's not thirsty, so forget the jug and give him the magazine.", "magazine>B", WARD),
    ("Skip the tape and give Tom the gloves.", "gloves>B", DEPOT),
    ("mr lee's not thirsty, so forget the jug and give him the magazine", "magazine>B", WARD),
    # near forms: the thing skipped is the one given, a pronoun that is not the person, more after
    ("Lena's not hungry, so skip the lemon and pass her the lemon.", None, KITCHEN),
    ("Mr Lee's not thirsty, so forget the jug and give her the magazine.", None, WARD),
    ("Skip the lemon and pass Lena the salt, then the knife.", None, KITCHEN),
)


test_other_of = CASES.test(
    # _other_of44r: a remark naming one thing of a kind, then "the other K(s)"
    (
        "Jess is using the small spanner, the other spanner can go in the locker.",
        "spanner_large@locker",
        WORKSHOP,
    ),
    (
        "Kofi says the big one's blunt, so he's to have the other spanner.",
        "spanner_small>A",
        WORKSHOP,
    ),
    (
        "Lily keeps chewing the red block, so Ava can have the other block.",
        "block_green>C",
        NURSERY,
    ),
    (
        "Mia's keeping the small box for returns, the other boxes can go on the pallet.",
        "box_medium@pallet & box_large@pallet",
        DEPOT,
    ),
    ("lily keeps chewing the red block, so ava can have the other block", "block_green>C", NURSERY),
    # near forms: 'the other box' of two left, 'the other plates' of one left, a pronoun that is
    # not the person, a request first
    ("Mia's keeping the small box for returns, the other box can go on the pallet.", None, DEPOT),
    ("Marco's keeping the white plate back, the other plates can go on the rack.", None, KITCHEN),
    ("Mr Lee says the grey one itches, so she's to have the other blanket.", None, WARD),
)

test_leaving = CASES.test(
    # _leaving44r: a request, then "leaving X be"
    ("Give Lena the salt, leaving the lemon be.", "salt>B", KITCHEN),
    ("Put the drill in the locker, leaving the hammer alone.", "drill@locker", WORKSHOP),
    ("give lena the salt, leaving the lemon be", "salt>B", KITCHEN),
    # near form: the thing left is the one asked for
    ("Give Lena the salt, leaving the salt be.", None, KITCHEN),
)

test_one_thing_but = CASES.test(
    # _one_thing_but44r: "any one thing apart from X for P", maybe a remark on what P is off
    (
        "Any one thing apart from the tape for Tom, he's off tape after the ice road run.",
        "box_small>B | scanner>B | box_medium>B | gloves>B | box_large>B",
        DEPOT,
    ),
    (
        "any one thing apart from the tape for tom",
        "box_small>B | scanner>B | box_medium>B | gloves>B | box_large>B",
        DEPOT,
    ),
    # near forms: the remark names another thing, or its pronoun is not the person
    ("Any one thing apart from the tape for Tom, he's off scanners after the run.", None, DEPOT),
    ("Any one thing apart from the tape for Tom, she's off tape.", None, DEPOT),
)

test_stay_rest = CASES.test(
    # _stay_rest44r: what stays, then everything else somewhere
    (
        "The spanners can stay where they are; everything else goes in the locker.",
        "drill@locker & hammer@locker & screws@locker & torch@locker",
        WORKSHOP,
    ),
    (
        "Leave the drill where it is; everything else goes on the bench.",
        "spanner_small@bench & hammer@bench & screws@bench & torch@bench & spanner_large@bench",
        WORKSHOP,
    ),
    (
        "the spanners can stay where they are; everything else goes in the locker",
        "drill@locker & hammer@locker & screws@locker & torch@locker",
        WORKSHOP,
    ),
    # near forms: a person, not a place; a thing named after
    ("The spanners can stay where they are; everything else goes to Kofi.", None, WORKSHOP),
    (
        "The spanners can stay where they are; everything else goes in the locker with the drill.",
        None,
        WORKSHOP,
    ),
)

test_fine_for = CASES.test(
    # _fine_for44r: the speaker needing nothing, then the request
    ("I'm fine for water thanks, it's Person A who should have the bottle.", "bottle>A", T11),
    ("I'm fine for water, it's Person A who should have the bottle.", "bottle>A", T11),
    ("i'm fine for water thanks, it's person a who should have the bottle", "bottle>A", T11),
    # near form: 'it' then stands for nothing said
    ("I'm fine for the jug, thanks; it's Mrs Khan who should have it.", None, WARD),
)

test_had_one = CASES.test(
    # _had_one44r: a request, then another person had one already
    ("The banana goes to Emma; Omar had one at lunch already.", "banana>C", LAB),
    ("Give Dana the spoon, Emma's had one already.", "spoon>A", LAB),
    ("Give Dana the spoon; Omar's got his own already.", "spoon>A", LAB),
    ("the banana goes to emma; omar had one at lunch already", "banana>C", LAB),
    # near form: what was had is named
    ("The banana goes to Emma; Omar had the sponge already.", None, LAB),
)

test_only_allowed = CASES.test(
    # _only_allowed44r: "P's only allowed X, so pass that to her"
    ("Omar's only allowed the spoon today, nothing else, so hand that to him.", "spoon>B", LAB),
    ("Emma's only allowed her banana right now, so pass that to her.", "banana>C", LAB),
    ("omar's only allowed the spoon today, nothing else, so hand that to him", "spoon>B", LAB),
    # near form: the pronoun is not the person
    ("Mr Lee's only allowed the jug today, nothing else, so hand that to her.", None, WARD),
)


test_blind37_negation = CASES.test(
    # _not_want_remark44r: "P doesn't want X, <remark>, <what instead>"
    (
        "Lena doesn't want the salt, she's been on her feet all night and wants the lemon.",
        "lemon>B",
        KITCHEN,
    ),
    (
        "Tom doesn't want the tape, he's after the gloves after his run to the coast.",
        "gloves>B",
        DEPOT,
    ),
    (
        "lena doesn't want the salt, she's been on her feet all night and wants the lemon",
        "lemon>B",
        KITCHEN,
    ),
    ("Lena doesn't want the salt, she's been at the counter and wants the lemon.", None, KITCHEN),
    (
        "Lena doesn't want the salt, he's been on his feet all night and wants the salt.",
        None,
        KITCHEN,
    ),
    # _not_allowed44r: "P isn't allowed X (after …), so Y goes to him"
    (
        "Omar isn't allowed the banana after what happened last week, so the spoon goes to him.",
        "spoon>B",
        LAB,
    ),
    ("Zoe isn't allowed the glue after the mess, so give her the ruler.", "ruler>C", CLASSROOM),
    (
        "omar isn't allowed the banana after what happened last week, so the spoon goes to him",
        "spoon>B",
        LAB,
    ),
    ("Omar isn't allowed the banana, so the banana goes to him.", None, LAB),
    # _all_bar44r: "P can have the lot bar X(, he's gone off them)"
    (
        "Person B can have the lot bar the chips, he's gone off them since the scrumping trip.",
        "bottle>B & cup>B & apple>B",
        SQ,
    ),
    (
        "person b can have the lot bar the chips, he's gone off them since the scrumping trip",
        "bottle>B & cup>B & apple>B",
        SQ,
    ),
    (
        "Person B can have the lot bar the chips, she's gone off them since the scrumping trip.",
        None,
        SQ,
    ),
    # _not_hers44r: "X's not P's, it belongs to Q, she brought it in"
    (
        "The stapler's not Sam's, it belongs to Priya, she brought it in from home.",
        "stapler>A",
        OFFICE,
    ),
    ("The stapler's not Sam's, it belongs to Sam.", None, OFFICE),
)

# -- choices and distributions ---------------------------------------------------------------------

test_either_suits = CASES.test(
    # _either_suits44r: a choice closed by "either one suits him fine" or "no odds"
    ("Bob's parched; get him a mug, either one suits him fine.", "mug_red>B | mug_blue>B", CELL),
    ("Give Ava a block, red or green, no odds.", "block_red>C | block_green>C", NURSERY),
    ("give ava a block, red or green, no odds", "block_red>C | block_green>C", NURSERY),
    # near form: no choice to close
    ("Give Ava the teddy, no odds.", None, NURSERY),
)

test_grab_first = CASES.test(
    # _grab_first44r: "whichever of the N (Ks) you grab first, get it to P"
    (
        "Whichever of the two spanners you reach first, hand it to Jess.",
        "spanner_small>B | spanner_large>B",
        WORKSHOP,
    ),
    (
        "Whichever of the three pens you grab first, get it to Sam.",
        "pen_black>B | pen_blue>B | pen_red>B",
        OFFICE,
    ),
    ("whichever of the two you grab first, get it to alice", "bottle>A | chips>A", TWO),
    # near form: the count is not the scene's
    ("Whichever of the two pens you grab first, get it to Sam.", None, OFFICE),
)

test_up_for_grabs = CASES.test(
    # _up_for_grabs44r: "X is up for grabs between P and Q"
    (
        "The lemon is up for grabs between Marco and Lena, so you decide who gets it.",
        "lemon>A | lemon>B",
        KITCHEN,
    ),
    (
        "The magazine's going spare for Mr Lee or Mrs Khan, your call.",
        "magazine>B | magazine>C",
        WARD,
    ),
    (
        "the lemon is up for grabs between marco and lena, so you decide who gets it",
        "lemon>A | lemon>B",
        KITCHEN,
    ),
    # near form: one person twice
    ("The lemon is up for grabs between Marco and Marco.", None, KITCHEN),
)

test_deserves = CASES.test(
    # _deserves44r: "P deserves the pair, so hand over both"
    (
        "After the night shift Alice deserves the pair, so hand over both.",
        "bottle>A & chips>A",
        TWO,
    ),
    ("Bob has earned both things, so give them to him.", "bottle>B & chips>B", TWO),
    # near form: not two things in the scene
    ("After service Marco deserves the pair, so hand over both.", None, KITCHEN),
)

test_any_of_them = CASES.test(
    # _any_of_them44r and _either_those44r: "any one of them for P, X or Y", "either of those to
    # P, he's not fussy"
    ("Either of them to Alice, bottle or crisps, doesn't matter.", "bottle>A | chips>A", TWO),
    ("Either of those for Bob, he'll take whatever he's given.", "bottle>B | chips>B", TWO),
    ("Either of those to Person A, she's not fussy.", "bottle>A | chips>A", T21),
    # near forms: one thing twice, a pronoun that is not the person, more than two things
    ("Any one of them for Alice, bottle or bottle, doesn't matter.", None, TWO),
    ("Either of those for Bob, she'll take whatever she's given.", None, TWO),
    ("Either of those to Sam, he's not fussy.", None, OFFICE),
)

# -- counts ----------------------------------------------------------------------------------------

test_counts = CASES.test(
    # _lone_going44r: "there's only a lone X knocking about and P's to have it"
    ("There's only a lone lemon knocking about and Lena's to have it.", "lemon>B", KITCHEN),
    ("There's just the one knife going, and Marco's the one to have it.", "knife>A", KITCHEN),
    ("There's only a lone plate knocking about and Lena's to have it.", None, KITCHEN),
    ("There's only a lone lemon knocking about and Lena's to have the salt.", None, KITCHEN),
    # _out_of44r: "(out of the four,) give P three: X, Y and Z"
    ("Out of the four, give Person A two for the trip: chips and cup.", "chips>A & cup>A", T41),
    (
        "Give Jess three for the job: drill, hammer and torch.",
        "drill>B & hammer>B & torch>B",
        WORKSHOP,
    ),
    ("Give Jess two for the job: drill, hammer and torch.", None, WORKSHOP),
    ("Out of the three, give Person A two: chips and cup.", None, T41),
    # _which_is_n44r: "everything, which is two things, to P"
    ("Everything, which makes two things, to Alice.", "bottle>A & chips>A", TWO),
    ("Everything there is, which is two things, to Person A.", None, T41),
    # _is_all44r: "a single X is all P asked for"
    ("A single spoon is all Omar asked for before his shift.", "spoon>B", LAB),
    ("One lemon is all Lena wants.", "lemon>B", KITCHEN),
    ("A single plate is all Lena wants.", None, KITCHEN),
)


def test_rewrites_read_them(monkeypatch: pytest.MonkeyPatch) -> None:
    """Each case that reads is read by these rules: refused without them."""
    CASES.refused_without((*_rewrites44r._STEPS44R_FIRST, *_rewrites44r._STEPS44R), monkeypatch)


# -- wrong readings put right ----------------------------------------------------------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        # 12c's session-43 fuzz: _not_list_first42r took "the lemon" after a bare comma as a
        # second thing left out and read tongs>A; the lemon takes the knife's place
        ("Not the knife, the lemon, oh, and the tongs, for Marco", "lemon>A & tongs>A", KITCHEN),
        ("Not the hammer, the torch, oh, and the drill, for Kofi", "torch>A & drill>A", WORKSHOP),
        ("Not the spoon, the sponge, oh, and the banana, for Omar.", "sponge>B & banana>B", LAB),
        # a list left out, joined by 'nor' / 'and not', is still left out
        ("Not the knife, nor the lemon; the tongs for Marco.", "tongs>A", KITCHEN),
    ],
)
def test_not_then_thing(text: str, want: str, scene: object) -> None:
    assert_case(text, want, scene)  # type: ignore[arg-type]


# -- refusals that name their readings -------------------------------------------------------------

UNCLEAR: list[tuple[str, Scene, tuple[str, ...]]] = [
    # other_asked44r
    (
        "The stapler to Sam, no, the other thing he asked for.",
        OFFICE,
        ("pen_black", "notebook", "pen_blue", "pen_red"),
    ),
    (
        "Give Mrs Khan the jug, no, the other one she wanted.",
        WARD,
        ("blanket_blue", "pills", "thermometer", "blanket_grey", "magazine"),
    ),
]


@pytest.mark.parametrize(("text", "scene", "readings"), UNCLEAR)
def test_refusals_name_readings(text: str, scene: Scene, readings: tuple[str, ...]) -> None:
    with pytest.raises(GroundingError) as refused:
        parse_instruction(text, scene)
    assert all(r in str(refused.value) for r in readings), str(refused.value)


def test_refusals_are_these(monkeypatch: pytest.MonkeyPatch) -> None:
    """Without these refusals, none of those refusals names all its readings."""
    mine = set(_rewrites44r.REFUSE44R)
    monkeypatch.setattr(offline, "_REFUSALS", tuple(r for r in offline._REFUSALS if r not in mine))
    for text, scene, readings in UNCLEAR:
        try:
            parse_instruction(text, scene)
        except GroundingError as refused:
            assert not all(r in str(refused) for r in readings), text
