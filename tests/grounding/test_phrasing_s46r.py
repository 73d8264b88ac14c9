"""Session-46 phrasings of issue 12 (engineer 12r): corrections, choices and distributions,
counts and plurals, each as a family; docs/grounding.md, "Session 46 (engineer 12r)". Each rule
with sentences of its kind in other words and scenes than blind44's (each refused on main
c427b55a), and near forms that must stay refused."""

from __future__ import annotations

import pytest

from hltl.grounding import _rewrites46r, _rewrites50l, _rewrites51r
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
    Unclear,
    assert_names_readings,
    assert_refusals_are,
)

# the example scenes blind44 uses
T11, T12, T22, T42, SQ, FIG1, TWO = (
    load_scene(ROOT / f"examples/scenes/{n}.yaml")
    for n in ("1-1", "1-2", "2-2", "4-2", "4-4-square", "fig1", "two_arms")
)

CASES = PhrasingCases()

# -- corrections -----------------------------------------------------------------------------------

test_fix_why = CASES.test(
    # _fix_why46r: a closing reason said of what the correction took away
    ("Take the red mug over to Carol, or rather the apple, the mug's chipped.", "apple>C", CELL),
    (
        "Spoon goes in the sink, correction, the tray, the sink's piled high with beakers.",
        "spoon@tray",
        LAB,
    ),
    ("Tom's to get the big box, no, sorry, the small one, big's too heavy.", "box_small>B", DEPOT),
    (
        "Put the tape on the belt, correction, the pallet, the belt's jammed with parcels.",
        "tape@pallet",
        DEPOT,
    ),
    (
        "Pop the teddy on the mat, correction, the high chair, the mat's soaked through.",
        "teddy@highchair",
        NURSERY,
    ),
    ("Torch to Kofi, sorry, the drill, the torch is flat.", "drill>A", WORKSHOP),
    # the reason names another thing, or what the correction keeps, or there is no correction
    ("Put the tape on the belt, no, the pallet, the gloves are torn.", None, DEPOT),
    ("Take the cup to Person B, or rather the apple, the apple's ripe.", None, SQ),
    ("Take the cup to Person B, the cup's cracked.", None, SQ),
    ("Sam's to get the blue pen, no, sorry, the black one, the notebook is full.", None, OFFICE),
)

test_scratch_lot = CASES.test(
    # _scratch_lot46r: "scratch the lot of that" after a cue is "scratch that"
    (
        "Hand Noah the ruler, no, scratch all that, it's Zoe who wants the globe.",
        "globe>C",
        CLASSROOM,
    ),
    ("Tape to Tom, sorry, scratch all of that, it's Mia who wants the gloves.", "gloves>A", DEPOT),
    ("Give Bob the crisps, no, scratch the lot, give Alice the bottle.", "bottle>A", FIG1),
    (
        "Knife to Lena, oh wait, scratch everything I just said, it's Marco who wants the lemon.",
        "lemon>A",
        KITCHEN,
    ),
    ("Give Alice the crisps and scratch the lot of that.", None, FIG1),
    ("Scratch the lot of that, it's Bob who wants the bottle.", None, FIG1),
)

# -- whichever, any of, one of, both, each ---------------------------------------------------------

test_one_of_hers = CASES.test(
    # _one_of_hers46r: "one of her blocks" of the one who wants it
    ("Emma wants one of her cups, either will do.", "cup_green>C | cup_white>C", LAB),
    ("Tom needs one of his boxes, whichever.", "box_small>B | box_medium>B | box_large>B", DEPOT),
    (
        "Kofi wants one of his spanners, either will do.",
        "spanner_small>A | spanner_large>A",
        WORKSHOP,
    ),
    (
        "Mrs Khan would like one of her blankets, either will do.",
        "blanket_blue>C | blanket_grey>C",
        WARD,
    ),
    # 'his' is not Lily; one spoon only
    ("Lily wants one of his blocks, either will do.", None, NURSERY),
    ("Emma wants one of her spoons, either will do.", None, LAB),
)

# -- counts and plurals ----------------------------------------------------------------------------

test_just_those = CASES.test(
    # _just_those46r: a closing count that the request meets
    ("Give Dana the spoon and the bowl, just those two.", "spoon>A & bowl>A", LAB),
    (
        "Marco wants the salt, the lemon and the knife, only those three.",
        "salt>A & lemon>A & knife>A",
        KITCHEN,
    ),
    ("Jess needs the hammer and the torch, just the two.", "hammer>B & torch>B", WORKSHOP),
    ("Person B wants the bottle and the cup, only those two items.", "bottle>B & cup>B", SQ),
    # the count is not the request's
    ("Give Dana the spoon and the bowl, just those three.", None, LAB),
    ("Marco wants the salt and the lemon, only those three.", None, KITCHEN),
)

test_only_one = CASES.test(
    # _only_one46r: "the only one there is" of a thing the scene holds one of
    ("Tom wants the one scanner, the only one there is.", "scanner>B", DEPOT),
    ("Hand Noah the globe, the only one we have.", "globe>B", CLASSROOM),
    ("Ruth needs the thermometer, the only one going.", "thermometer>A", WARD),
    # two cups, three pens
    ("Dana wants the cup, the only one there is.", None, LAB),
    ("Sam wants the one pen, the only one there is.", None, OFFICE),
)

test_items_there = CASES.test(
    # _items_there46r: "the two items there, both of them" of a scene holding that many
    (
        "The two things there, both of them, go to Person B for the ferry.",
        "bottle>B & chips>B",
        T22,
    ),
    (
        "The four items there, all of them, go to Person A for her stall.",
        "bottle>A & chips>A & cup>A & apple>A",
        SQ,
    ),
    ("The two items there, both of them, go to Person A.", None, SQ),
)

test_and_both = CASES.test(
    # _and_both46r: "the pair of cups, green and white both"
    ("Ava needs the pair of blocks, red and green both.", "block_red>C & block_green>C", NURSERY),
    (
        "For the night Mr Lee needs the pair of blankets, blue and grey both.",
        "blanket_blue>B & blanket_grey>B",
        WARD,
    ),
    (
        "For the party Marco wants the pair of plates, white and blue both.",
        "plate_white>A & plate_blue>A",
        KITCHEN,
    ),
    ("Emma needs the pair of cups, green and white both.", "cup_green>C & cup_white>C", LAB),
    # no blue block
    ("Hand Ava the blocks, the red and the blue both.", None, NURSERY),
)


# -- refusals that name their readings -----------------------------------------------------------

UNCLEAR: list[Unclear] = [
    # doubt_at46r: "X or Y <when, where>, I can't recall which"
    (
        "Mrs Khan asked for the jug or the magazine at breakfast, I can't remember which.",
        WARD,
        ("jug", "magazine"),
    ),
    (
        "Tom wanted the tape or the gloves during his shift, not sure which.",
        DEPOT,
        ("tape", "gloves"),
    ),
    (
        "Noah asked for the ruler or the globe in assembly, I forget which.",
        CLASSROOM,
        ("ruler", "globe"),
    ),
]


@pytest.mark.parametrize(("text", "scene", "readings"), UNCLEAR)
def test_refusals_name_readings(text: str, scene: Scene, readings: tuple[str, ...]) -> None:
    assert_names_readings(text, scene, readings)


def test_refusals_are_these(monkeypatch: pytest.MonkeyPatch) -> None:
    """Without these refusals, none of those refusals names all its readings."""
    # session 50 (lead): `forgot_which50l` names the readings of a forgotten choice too
    assert_refusals_are(
        (*_rewrites46r.REFUSE46R, _rewrites50l.forgot_which50l), UNCLEAR, monkeypatch
    )


# -- a second batch --------------------------------------------------------------------------------

test_taking = CASES.test(
    # _taking46r: "P is taking all four items to her quillwork circle"; "P is taking both (on
    # his fishing trip), the X and the Y, so pass them to him"
    (
        "Person B is taking all four things to his allotment.",
        "bottle>B & chips>B & cup>B & apple>B",
        SQ,
    ),
    (
        "Bob is taking both on his fishing trip, the cup and the apple, so pass them to him.",
        "cup>B & apple>B",
        CELL,
    ),
    (
        "Priya's taking both to her book club, the stapler and the notebook, so hand them over to "
        "her.",
        "stapler>A & notebook>A",
        OFFICE,
    ),
    # three things for 'both'; another person's place
    (
        "Bob is taking both on his fishing trip, the cup, the apple and the chips, so pass them to "
        "him.",
        None,
        CELL,
    ),
    ("Mia is taking the tape to Tom's allotment.", None, DEPOT),
)

test_thing_needs = CASES.test(
    # _thing_needs46r: "Ava's tower needs both blocks, so hand her …"
    (
        "Noah's project needs both books, so hand him the red and the green.",
        "book_red>B & book_green>B",
        CLASSROOM,
    ),
    (
        "Dana's titration needs both cups, so give her the green and the white.",
        "cup_green>A & cup_white>A",
        LAB,
    ),
    (
        "Mr Lee's bed needs both blankets, so pass him the blue and the grey.",
        "blanket_blue>B & blanket_grey>B",
        WARD,
    ),
    # the thing is one of the scene's; the pronoun is not Noah
    ("Ava's teddy needs both blocks, so hand her the red and the green.", None, NURSERY),
    ("Noah's project needs both books, so hand her the red and the green.", None, CLASSROOM),
)

test_not_fussy = CASES.test(
    # _not_fussy46r: "P isn't fussy (about K, after his fair), so either K is fine for him"
    (
        "Kofi isn't fussy about spanners, so your pick of the two for him.",
        "spanner_small>A | spanner_large>A",
        WORKSHOP,
    ),
    (
        "Mrs Khan isn't fussy after her physio, so either blanket is fine for her.",
        "blanket_blue>C | blanket_grey>C",
        WARD,
    ),
    (
        "Dana's not picky about cups, so either cup will do for her.",
        "cup_green>A | cup_white>A",
        LAB,
    ),
    (
        "Carol isn't fussy after her swim, so either mug is fine for her.",
        "mug_red>C | mug_blue>C",
        CELL,
    ),
    # 'her' is not Mr Lee; three pens are not 'the two'
    ("Mr Lee isn't fussy about blankets, so your pick of the two for her.", None, WARD),
    ("Sam isn't fussy about pens, so your pick of the two for him.", None, OFFICE),
)

test_a_k_or = CASES.test(
    # _a_k_or46r: "P wants a pen; black or red, up to you"
    ("Mr Lee wants a blanket; blue or grey, up to you.", "blanket_blue>B | blanket_grey>B", WARD),
    (
        "Kofi needs a spanner: small or large, your call.",
        "spanner_small>A | spanner_large>A",
        WORKSHOP,
    ),
    ("Lily would like a block; red or green.", "block_red>A | block_green>A", NURSERY),
    # no green pen
    ("Priya wants a pen; black or green, up to you.", None, OFFICE),
)

test_for_whose = CASES.test(
    # _for_whose46r: "…, for the rag and bone man's odds and ends"
    ("Give Mia the tape, for the bed and breakfast's parcels.", "tape>A", DEPOT),
    ("Marco wants the lemon, for the fish and chip shop's batter.", "lemon>A", KITCHEN),
    # the words name people of the scene
    ("Give Mia the tape, for the driver and supervisor's van.", None, DEPOT),
)

test_placed_remark = CASES.test(
    # _placed_remark46r: "Put X on S, P is <doing> …" after a placing
    ("Put the globe on the shelf, Noah is reading quietly after lunch.", "globe@shelf", CLASSROOM),
    (
        "Put the plates on the rack, Lena is laying up after service.",
        "plate_white@rack & plate_blue@rack",
        KITCHEN,
    ),
    ("Put the tape on the pallet, Tom is loading up after lunch.", "tape@pallet", DEPOT),
    # the remark names a thing of the scene
    ("Put the tape on the pallet, Tom is loading the gloves.", None, DEPOT),
    # a want or a handover, not a remark (session 35's near form)
    ("Put the tape on the pallet, Tom's having a biscuit.", None, DEPOT),
)

test_per_head = CASES.test(
    # _per_head46r: "Hand out a K per student, the A to P and the B one to Q"
    (
        "Hand out a blanket per patient, the blue to Mr Lee and the grey one to Mrs Khan.",
        "blanket_blue>B & blanket_grey>C",
        WARD,
    ),
    (
        "Give out a block each, the red to Lily and the green one to Ava.",
        "block_red>A & block_green>C",
        NURSERY,
    ),
    (
        "Dish out a plate apiece, the white to Marco and the blue one to Lena.",
        "plate_white>A & plate_blue>B",
        KITCHEN,
    ),
    # one person twice
    (
        "Hand out a blanket per patient, the blue to Mr Lee and the grey one to Mr Lee.",
        None,
        WARD,
    ),
)

test_apiece_first = CASES.test(
    # _apiece_first46r: "One apiece for the pair of them, <list>, like the milkmaid said"
    (
        "One each for the two of them, the tape to Mia and the gloves to Tom, as the foreman said.",
        "tape>A & gloves>B",
        DEPOT,
    ),
    (
        "Something apiece for both of them, the salt to Marco and the knife to Lena.",
        "salt>A & knife>B",
        KITCHEN,
    ),
    (
        "One apiece for the pair of them, the drill to Kofi and the torch to Jess, like the boss "
        "asked.",
        "drill>A & torch>B",
        WORKSHOP,
    ),
    # not one each; who said it is of the scene
    ("One apiece for the pair of them, the drill and the torch to Kofi.", None, WORKSHOP),
    (
        "One apiece for the pair of them, the drill to Kofi and the torch to Jess, like Jess said.",
        None,
        WORKSHOP,
    ),
)

test_just_the_one = CASES.test(
    # _just_the_one46r: "P will take any K going; there's just the one, so that one"
    (
        "Tom will take any scanner going; as it happens there's just the one, so that one.",
        "scanner>B",
        DEPOT,
    ),
    ("Noah will take any globe at all; there's only the one, so that'll do.", "globe>B", CLASSROOM),
    (
        "Ruth will have any thermometer going; mind you, there's just the one, so that one.",
        "thermometer>A",
        WARD,
    ),
    # two cups
    ("Dana will take any cup going; as it happens there's just the one, so that one.", None, LAB),
)

test_anything_of = CASES.test(
    # _anything_of46r: "Pick anything of the four on offer for P, no odds which, …"
    (
        "Pick anything of the four on offer for Person A, whichever, she's only browsing.",
        "bottle>A | chips>A | cup>A | apple>A",
        SQ,
    ),
    ("Choose any of the two for Person B, no odds which.", "bottle>B | chips>B", T22),
    (
        "Grab anything of the four for Person B, it doesn't matter which.",
        "bottle>B | chips>B | cup>B | apple>B",
        SQ,
    ),
    # four things, not three
    ("Pick anything of the three on offer for Person B, no odds which.", None, SQ),
)

test_then_again = CASES.test(
    # _then_again46r: "<request>. Then again, she's just eaten, so swap them for the bottle"
    ("Tape to Tom. Then again, he's got loads, so swap it for the gloves.", "gloves>B", DEPOT),
    (
        "Lemon to Marco. On second thoughts, he's made the sauce, so swap it for the salt.",
        "salt>A",
        KITCHEN,
    ),
    (
        "Globe to Zoe. Then again, she's done geography, so swap it for the ruler.",
        "ruler>C",
        CLASSROOM,
    ),
    # 'she' is not Tom; the same thing again
    ("Tape to Tom. Then again, she's got loads, so swap it for the gloves.", None, DEPOT),
    ("Tape to Tom. Then again, he's got loads, so swap it for the tape.", None, DEPOT),
)

test_neither_without = CASES.test(
    # _neither_without46r: "Neither goes without: <every person gets something>"
    (
        "Neither goes without: Tom's having the tape and Mia the gloves.",
        "tape>B & gloves>A",
        DEPOT,
    ),
    (
        "Neither goes without: Person A's having the bottle and Person B the chips.",
        "bottle>A & chips>B",
        T22,
    ),
    (
        "Neither goes without: Sam's having the stapler and Priya the notebook.",
        "stapler>B & notebook>A",
        OFFICE,
    ),
    (
        "Neither goes without: Kofi's having the drill and Jess the torch.",
        "drill>A & torch>B",
        WORKSHOP,
    ),
    # someone does go without
    ("Neither goes without: Tom's having the tape and the gloves.", None, DEPOT),
    ("Neither goes without: Zoe's having the ruler and Noah the globe.", None, CLASSROOM),
)


test_slip_label = CASES.test(
    # _slip_label46r: a request to a 'Person X' the scene lacks, corrected to its one person
    (
        "Over to Person C with the bottle, oh, what am I saying, it's Person A who gets it, she's "
        "the only one here.",
        "bottle>A",
        T12,
    ),
    ("Bottle to Person B, no, what am I saying, it's Person A who gets it.", "bottle>A", T11),
    ("The bottle to Person B, sorry, silly me, it's Person A who wants it.", "bottle>A", T12),
    (
        "Over to Person C with the bottle, whoops, it's Person A who needs it, she's the only one "
        "around.",
        "bottle>A",
        T11,
    ),
    # 'he' is not Person A (the convention); a two-person scene; a person the scene lacks again
    (
        "Over to Person B with the bottle, oh, what am I saying, it's Person A who gets it, he's "
        "the only one here.",
        None,
        T11,
    ),
    (
        "Over to Person C with the crisps, oh, what am I saying, it's Alice who gets them, she's "
        "the only one here.",
        None,
        FIG1,
    ),
    (
        "Over to Person B with the bottle, oh, what am I saying, it's Person C who gets it.",
        None,
        T11,
    ),
)


# -- blind42's choices and counts ------------------------------------------------------------------

test_each_pronoun = CASES.test(
    # _each_pronoun46r: "P and Q each want one thing: her the X, him the Y"
    ("Alice and Bob each want one thing: her the apple, him the cup.", "apple>A & cup>B", CELL),
    (
        "Mr Lee and Mrs Khan each need one: the jug for him, the magazine for her.",
        "jug>B & magazine>C",
        WARD,
    ),
    ("Mia and Tom each get something: him the scanner, her the tape.", "scanner>B & tape>A", DEPOT),
    (
        "Person B and Person A each want one thing: him the cup, her the apple.",
        "cup>B & apple>A",
        T42,
    ),
    # both 'her'; neither Kofi's nor Jess's sex is said
    ("Alice and Carol each want one thing: her the apple, her the cup.", None, CELL),
    ("Kofi and Jess each want one thing: him the drill, her the torch.", None, WORKSHOP),
)

test_single_thing = CASES.test(
    # _single_thing46r: "P only wants a single thing off you today and it's the X"
    (
        "Tom only wants a single thing off you today and it's the scanner, he's on the late run.",
        "scanner>B",
        DEPOT,
    ),
    ("Lena only needs one thing from you and it's the knife.", "knife>B", KITCHEN),
    (
        "Emma just wants the one thing today and that's the banana, she's skipped lunch.",
        "banana>C",
        LAB,
    ),
    # two plates
    ("Lena only needs one thing from you and it's the plate.", None, KITCHEN),
)

test_whatever_there = CASES.test(
    # _whatever_there46r: "The X, or whatever's there, P isn't fussy" of a scene holding X alone
    ("The bottle, or whatever's there, Person A isn't fussy.", "bottle>A", T11),
    ("The bottle, or whatever's handy, Person A's not bothered.", "bottle>A", T12),
    ("The bottle, or whatever's there, Person A isn't fussy.", None, T22),
)

test_clear_both = CASES.test(
    # _clear_both46r: "Clear both things off the floor and onto the S, X and Y alike"
    (
        "Clear both things off the floor and onto the shelf, bottle and crisps alike.",
        "bottle@shelf & chips@shelf",
        TWO,
    ),
    (
        "Clear both off the floor and up onto the table, apple and cup alike, cleaners are due.",
        "apple@table & cup@table",
        CELL,
    ),
    (
        "Clear both things off the floor and into the high chair, bib and teddy alike.",
        "bib@highchair & teddy@highchair",
        NURSERY,
    ),
    ("Clear both things off the floor and onto Bob, apple and cup alike.", None, CELL),
)


def test_rewrites_read_them(monkeypatch: pytest.MonkeyPatch) -> None:
    """Each case that reads is read by these rules: refused without them."""
    # session 51 (12r; at the merge): its rules of the same families read some of these too
    CASES.refused_without(
        (*_rewrites46r._STEPS46R_FIRST, *_rewrites46r._STEPS46R, *_rewrites51r._STEPS51R),
        monkeypatch,
    )
