"""Session-54 phrasings of issue 12 (engineer 12): session 53's open wrong readings, then blind52's
politeness and fillers, wants and needs, pronouns and ellipsis, lower case and questions, each as a
family (docs/grounding.md, "Session 54 (engineer 12)"). Each rule with sentences in other words and
scenes, and near sentences that must stay as they are."""

from __future__ import annotations

import pytest

from hltl.errors import GroundingError
from hltl.grounding import _rewrites54
from hltl.grounding.lexicon import Lexicon
from hltl.world.scene import Scene, load_scene
from tests.grounding.helpers import (
    CELL,
    CLASSROOM,
    KITCHEN,
    ROOT,
    WARD,
    WORKSHOP,
    assert_reads,
    assert_refused,
)

# the example scenes blind52 uses
DUO, ONE, F41, T12, T21, FIG1, L44, SQ = (
    load_scene(ROOT / f"examples/scenes/{n}.yaml")
    for n in ("2-2", "1-1", "4-1", "1-2", "2-1", "fig1", "4-4-line", "4-4-square")
)

# -- wrong readings of main (12c's fuzz, session 53) ---

# a request said to have been made on another day (_days_ago54): read on main as a want of now
DAYS_AGO = [
    ("Bob asked for the apple yesterday.", CELL),
    ("Alice asked for the cup last night, poor thing.", CELL),
    ("bob asked for the apple yesterday", CELL),
    ("Bob was asking for the apple yesterday.", CELL),
    ("Bob asked for the apple yesterday; give Alice the crisps.", CELL),
    ("Marco asked for the lemon yesterday.", KITCHEN),
    ("Mrs Khan asked for the magazine last night.", WARD),
    ("Zoe asked for the scissors yesterday, bless her.", CLASSROOM),
]


@pytest.mark.parametrize(("text", "scene"), DAYS_AGO)
def test_days_ago_refused(text: str, scene: Scene) -> None:
    assert_refused(text, scene)
    with pytest.raises(GroundingError):
        _rewrites54._days_ago54(text, Lexicon.of(scene))


@pytest.mark.parametrize(
    ("text", "want"),
    [
        # the rest asks for it now, or the want is said to hold: main's reading stands
        ("Bob asked for the apple yesterday, so take it to him.", "apple>B"),
        ("Bob asked for the apple yesterday, and he still wants it.", "apple>B"),
        ("Bob has been asking for the apple since yesterday.", "apple>B"),
        ("Bob asked for the apple this morning.", "apple>B"),
        ("Bob asked for the apple earlier.", "apple>B"),
    ],
)
def test_days_ago_near_read(text: str, want: str) -> None:
    assert_reads(text, want, CELL)


# a past holding with a reason or time after it (_had_why54): read on main as a handover
HAD_WHY = [
    ("Bob had the apple since his match ended.", CELL),
    ("Bob's had the apple since his match ended.", CELL),
    ("Bob got the apple because he was hungry.", CELL),
    ("Bob had the apple first.", CELL),
    ("Bob had a mug since his match ended.", CELL),
    ("bob had the apple since his match ended", CELL),
    ("Bob had the apple since his match ended. Give Alice the crisps.", CELL),
    ("Marco had the knife since his shift started.", KITCHEN),
    ("Lena had the tongs because she was cooking.", KITCHEN),
    ("Marco has had the lemon since lunch.", KITCHEN),
    ("Mr Lee had the blue blanket because he was cold.", WARD),
    ("Zoe had the scissors since the lesson began.", CLASSROOM),
    ("Kofi got the power drill as he was on the shelving job.", WORKSHOP),
]


@pytest.mark.parametrize(("text", "scene"), HAD_WHY)
def test_had_why_refused(text: str, scene: Scene) -> None:
    assert_refused(text, scene)
    with pytest.raises(GroundingError):
        _rewrites54._had_why54(text, Lexicon.of(scene))


@pytest.mark.parametrize(
    ("text", "want"),
    [
        # a want, not a holding
        ("Bob wants the apple since his match ended.", "apple>B"),
        ("Bob needs the apple because he's hungry.", "apple>B"),
        ("Bob would like the apple since his match ended.", "apple>B"),
    ],
)
def test_had_why_near_read(text: str, want: str) -> None:
    assert_reads(text, want, CELL)
    _rewrites54._had_why54(text, Lexicon.of(CELL))


def test_had_why_leaves_a_want() -> None:
    # 'had his eye on X since …' is a want (session 45 reads it), not a holding
    _rewrites54._had_why54(
        "Kofi's had his eye on the screws since the auction.", Lexicon.of(WORKSHOP)
    )
    _rewrites54._had_why54("Carol has had her eye on the red mug ever since.", Lexicon.of(CELL))
