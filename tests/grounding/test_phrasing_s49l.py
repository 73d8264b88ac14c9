"""Phrasings the session-49 lead rules read or refuse (docs/grounding.md, Session 49 (lead))."""

from __future__ import annotations

import pytest

from hltl.errors import GroundingError
from hltl.grounding.offline import parse_instruction
from hltl.world.scene import Scene, load_scene
from tests.grounding.helpers import (
    CELL,
    DEPOT,
    KITCHEN,
    LAB,
    OFFICE,
    ROOT,
    WARD,
    WORKSHOP,
    assert_reads,
)

SQUARE = load_scene(ROOT / "examples/scenes/4-4-square.yaml")

# -- a choice, then "it's gone clean out of my head": the speaker has forgotten which was asked
# for (blind47's wrong reading left the choice to the robot)


@pytest.mark.parametrize(
    ("text", "scene", "named"),
    [
        (
            "Kofi wanted one of the spanners for the stonecarver's job, the small or the large, "
            "it's gone clean out of my head.",
            WORKSHOP,
            ("spanner_small", "spanner_large"),
        ),
        (
            "Lena wanted one of the plates, the white or the blue, it's gone clean out of my head.",
            KITCHEN,
            ("plate_white", "plate_blue"),
        ),
        (
            "Marco asked for the salt or the lemon, it's slipped my mind.",
            KITCHEN,
            ("salt", "lemon"),
        ),
        (
            "Mrs Khan wanted one of the blankets, the blue or the grey, it's slipped my mind.",
            WARD,
            ("blanket_blue", "blanket_grey"),
        ),
        (
            "Priya wanted one of the pens, it's gone out of my head.",
            OFFICE,
            ("pen_black", "pen_blue", "pen_red"),
        ),
        (
            "Jess asked for the drill or the hammer, it's gone right out of my head.",
            WORKSHOP,
            ("drill", "hammer"),
        ),
        # the remark in other words, not last, or without stops (12c's probes)
        (
            "Kofi wanted one of the spanners, the small or the large, I've clean forgotten.",
            WORKSHOP,
            ("spanner_small", "spanner_large"),
        ),
        (
            "Jess wanted the drill or the hammer, my mind's gone blank.",
            WORKSHOP,
            ("drill", "hammer"),
        ),
        (
            "Jess wanted the torch or the hammer, I'd have to ask her.",
            WORKSHOP,
            ("torch", "hammer"),
        ),
        (
            "Kofi asked for a spanner, it's gone out of my head which size.",
            WORKSHOP,
            ("spanner_small", "spanner_large"),
        ),
        (
            "Lena wanted a plate, white or blue, it's completely gone, she's out the back.",
            KITCHEN,
            ("plate_white", "plate_blue"),
        ),
        ("Mr Novak asked for the salt or the lemon, memory's shot.", KITCHEN, ("salt", "lemon")),
        (
            "mr novak asked for the salt or the lemon its gone clean out of my head",
            KITCHEN,
            ("salt", "lemon"),
        ),
        ("Dana wanted the spoon or the bowl, I didn't catch it, sorry.", LAB, ("spoon", "bowl")),
    ],
)
def test_a_choice_the_speaker_has_forgotten_is_refused_naming_it(
    text: str, scene: Scene, named: tuple[str, ...]
) -> None:
    with pytest.raises(GroundingError) as err:
        parse_instruction(text, scene)
    message = str(err.value)
    assert "forgotten which" in message
    assert all(f"the {n} to" in message for n in named)


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        # a choice left to the robot, or a reason that is no doubt, still reads
        ("Give Jess the drill or the hammer, whichever.", "drill>B | hammer>B", WORKSHOP),
        (
            "Give Kofi either spanner, he's not fussy.",
            "spanner_small>A | spanner_large>A",
            WORKSHOP,
        ),
        ("Marco wants the salt or the lemon.", "salt>A | lemon>A", KITCHEN),
        # 'gone' of something else is no doubt about the choice
        (
            "Give Jess either spanner, it's gone cold in here.",
            "spanner_small>B | spanner_large>B",
            WORKSHOP,
        ),
    ],
)
def test_a_choice_with_no_doubt_still_reads(text: str, want: str, scene: Scene) -> None:
    assert_reads(text, want, scene)


# -- "the three boxes, the whole lot": 'the whole lot' in apposition says the kind again (blind47's
# other wrong reading added everything else in the scene)


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        (
            "Load the belt with the three boxes, the whole lot, the brickie's van is nearly here.",
            "box_small@conveyor & box_medium@conveyor & box_large@conveyor",
            DEPOT,
        ),
        (
            "Put the three boxes on the belt, the whole lot.",
            "box_small@conveyor & box_medium@conveyor & box_large@conveyor",
            DEPOT,
        ),
        (
            "Put the three boxes, the whole lot, on the belt.",
            "box_small@conveyor & box_medium@conveyor & box_large@conveyor",
            DEPOT,
        ),
        (
            "Put both plates on the counter, the whole lot.",
            "plate_white@counter & plate_blue@counter",
            KITCHEN,
        ),
        ("Sam gets the pens, the whole lot.", "pen_black>B & pen_blue>B & pen_red>B", OFFICE),
        ("Alice gets the mugs, the whole lot of them.", "mug_red>A & mug_blue>A", CELL),
        (
            "Put the boxes on the belt - the whole lot.",
            "box_small@conveyor & box_medium@conveyor & box_large@conveyor",
            DEPOT,
        ),
        (
            "Put the boxes on the belt, everything.",
            "box_small@conveyor & box_medium@conveyor & box_large@conveyor",
            DEPOT,
        ),
        # said the other way round
        ("Give Tom the lot, the boxes.", "box_small>B & box_medium>B & box_large>B", DEPOT),
        ("Ruth gets everything, both blankets.", "blanket_blue>A & blanket_grey>A", WARD),
        # a count and a list after it say what the lot is (session 43's rule)
        (
            "Person B gets the whole lot, all four of them: bottle, chips, cup and apple.",
            "bottle>B & chips>B & cup>B & apple>B",
            SQUARE,
        ),
        # 'the whole lot' alone is still everything
        (
            "Give Bob the whole lot.",
            "cup>B & bottle>B & chips>B & apple>B & mug_red>B & mug_blue>B",
            CELL,
        ),
    ],
)
def test_the_whole_lot_after_a_kind_is_that_kind(text: str, want: str, scene: Scene) -> None:
    assert_reads(text, want, scene)


@pytest.mark.parametrize(
    ("text", "scene", "named"),
    [
        ("Give Tom the gloves and the tape, the whole lot.", DEPOT, ("gloves, tape", "box_large")),
        (
            "Put the tape and the gloves on the belt, the whole lot.",
            DEPOT,
            ("gloves, tape", "scanner"),
        ),
        (
            "Give Sam the stapler and the notebook, the lot.",
            OFFICE,
            ("notebook, stapler", "pen_red"),
        ),
        ("Load the belt with the tape, the whole lot.", DEPOT, ("with tape", "gloves")),
        ("Give Tom the gloves, the tape, everything.", DEPOT, ("gloves, tape", "scanner")),
        ("Give Tom everything, the tape and the gloves.", DEPOT, ("gloves, tape", "box_small")),
    ],
)
def test_the_whole_lot_after_other_things_is_refused_naming_both(
    text: str, scene: Scene, named: tuple[str, str]
) -> None:
    with pytest.raises(GroundingError) as err:
        parse_instruction(text, scene)
    message = str(err.value)
    assert "could say those again or add everything else" in message
    assert all(n in message for n in named)
