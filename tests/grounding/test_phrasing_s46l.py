"""Phrasings the session-46 lead rules read (docs/grounding.md, Session 46 (lead))."""

from __future__ import annotations

import pytest

from hltl.world.scene import Scene
from tests.grounding.helpers import KITCHEN, LAB, OFFICE, WORKSHOP, assert_reads, assert_refused

# -- "P wants X and Y down on the S": both placed, as without the particle (blind44's one wrong
# reading gave X to P and placed Y)


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        (
            "Marco wants both plates down on the counter for plating up.",
            "plate_white@counter & plate_blue@counter",
            KITCHEN,
        ),
        ("Dana wants both cups back on the tray.", "cup_green@tray & cup_white@tray", LAB),
        ("Omar needs the spoon and the bowl down in the sink.", "spoon@sink & bowl@sink", LAB),
        (
            "Emma would like the banana and the sponge over on the tray.",
            "banana@tray & sponge@tray",
            LAB,
        ),
        (
            "Sam needs the stapler and the notebook up on the desk.",
            "stapler@desk & notebook@desk",
            OFFICE,
        ),
        (
            "Kofi wants the hammer and the drill back on the workbench.",
            "hammer@bench & drill@bench",
            WORKSHOP,
        ),
    ],
)
def test_two_things_wanted_on_a_surface_are_both_placed(text: str, want: str, scene: Scene) -> None:
    assert_reads(text, want, scene)


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        # a comma or a sentence end between says the first thing is the person's
        ("Dana wants the spoon, and the bowl down in the sink.", "spoon>A & bowl@sink", LAB),
        ("Dana wants the spoon. The bowl back in the sink.", "spoon>A & bowl@sink", LAB),
        # no place after the particle: both handed to the one who wants them
        ("Kofi wants the hammer and the drill down.", "hammer>A & drill>A", WORKSHOP),
    ],
)
def test_a_break_or_no_place_keeps_the_wanting(text: str, want: str, scene: Scene) -> None:
    assert_reads(text, want, scene)


def test_both_of_three_is_still_refused() -> None:
    assert_refused("Priya wants both pens back in the box.", OFFICE)
