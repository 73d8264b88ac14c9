"""Session-46 phrasings of issue 12 (engineer 12r): corrections, choices and distributions,
counts and plurals, each as a family; docs/grounding.md, "Session 46 (engineer 12r)". Each rule
with sentences of its kind in other words and scenes than blind44's (each refused on main
c427b55a), and near forms that must stay refused."""

from __future__ import annotations

import pytest

from hltl.errors import GroundingError
from hltl.grounding import _rewrites46r, offline
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
)

# the example scenes blind44 uses
T22, SQ, FIG1 = (
    load_scene(ROOT / f"examples/scenes/{n}.yaml") for n in ("2-2", "4-4-square", "fig1")
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


def test_rewrites_read_them(monkeypatch: pytest.MonkeyPatch) -> None:
    """Each case that reads is read by these rules: refused without them."""
    CASES.refused_without((*_rewrites46r._STEPS46R_FIRST, *_rewrites46r._STEPS46R), monkeypatch)


# -- refusals that name their readings -----------------------------------------------------------

UNCLEAR: list[tuple[str, Scene, tuple[str, ...]]] = [
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
    with pytest.raises(GroundingError) as refused:
        parse_instruction(text, scene)
    assert all(r in str(refused.value) for r in readings), str(refused.value)


def test_refusals_are_these(monkeypatch: pytest.MonkeyPatch) -> None:
    """Without these refusals, none of those refusals names all its readings."""
    mine = set(_rewrites46r.REFUSE46R)
    monkeypatch.setattr(offline, "_REFUSALS", tuple(r for r in offline._REFUSALS if r not in mine))
    for text, scene, readings in UNCLEAR:
        try:
            parse_instruction(text, scene)
        except GroundingError as refused:
            assert not all(r in str(refused) for r in readings), text
