"""Session-55 phrasings of issue 12 (engineer 12): session 54's open wrong reading, then blind53's
politeness and fillers, wants and needs, pronouns and ellipsis and lower case, each as a family
(docs/grounding.md, "Session 55 (engineer 12)"). Each rule with sentences in other words and
scenes, and near sentences that must stay as they are."""

from __future__ import annotations

import pytest

from hltl.grounding import _rewrites55, offline
from hltl.world.scene import Scene, load_scene
from tests.grounding.helpers import (
    CELL,
    CLASSROOM,
    KITCHEN,
    NURSERY,
    ROOT,
    WARD,
    WORKSHOP,
    assert_reads,
    assert_refused,
)

# the example scenes blind53 uses
DUO, ONE, F41, F42, T12, T21, FIG1, L44, SQ, L24, TWO = (
    load_scene(ROOT / f"examples/scenes/{n}.yaml")
    for n in (
        *("2-2", "1-1", "4-1", "4-2", "1-2", "2-1", "fig1", "4-4-line", "4-4-square", "2-4-line"),
        "two_arms",
    )
)

# -- wrong readings of main (12c's fuzz, session 54) ---

# a want of the placed thing run on after the placement, no punctuation between
# (_placed_wanted55): read on main as the placement and a handover of the same thing
PLACED_WANTED = [
    ("lemon on the plate rack no sorry the worktop chef wants it for the fish", KITCHEN),
    ("lemon on the worktop chef wants it for the fish", KITCHEN),
    ("salt on the rack lena needs it", KITCHEN),
    ("tongs on the rack mr novak wants them", KITCHEN),
    ("lemon on the worktop then chef wants it", KITCHEN),
    ("lemon on the worktop chef's been asking for it", KITCHEN),
    ("apple on the shelf bob wants it", CELL),
    ("magazine on the locker mrs khan wants it", WARD),
    ("torch in the locker kofi needs it", WORKSHOP),
    ("globe on the desk zoe's been asking for it", CLASSROOM),
    ("teddy on the mat lily wants it", NURSERY),
]


@pytest.mark.parametrize(("text", "scene"), PLACED_WANTED)
def test_placed_wanted_refused(text: str, scene: Scene) -> None:
    assert_refused(text, scene)


def test_placed_wanted_read_without_the_check(monkeypatch: pytest.MonkeyPatch) -> None:
    """Without the check each is read as the placement and a handover (main's wrong reading)."""
    kept = tuple(c for c in offline._CHECKS if c is not _rewrites55._placed_wanted55)
    monkeypatch.setattr(offline, "_CHECKS", kept)
    for text, scene in PLACED_WANTED:
        got = offline.parse_instruction(text, scene)
        kinds = {t.kind for t in offline.tasks(got)}
        assert kinds == {"place", "deliver"}, text


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        # the handover is said in words, or the want is of another thing: read as before
        (
            "lemon on the worktop then give it to chef he wants it",
            "lemon@counter ; lemon>A",
            KITCHEN,
        ),
        ("apple on the shelf and give bob the crisps he wants them", "apple@shelf & chips>B", CELL),
        ("give bob the apple he wants it", "apple>B", CELL),
        ("lemon on the plate rack no sorry the worktop", "lemon@counter", KITCHEN),
    ],
)
def test_placed_wanted_near_read(text: str, want: str, scene: Scene) -> None:
    assert_reads(text, want, scene)
