"""Session-33 phrasing of issue 12 (lead): blind31's one wrong reading (docs/grounding.md,
"Session 33 (lead)").

- "Bottle to Person A. Chips to Person B. Then whatever the deckhand tells you.": 'whatever'
  was read as the remark after a choice ("…, whichever is easier") and the rest of its clause
  dropped, so the plan left out the step the deckhand was to name. A 'whatever/whichever' clause
  that waits on someone's word (tells, says, asks, decides, …) is refused; a remark on a choice
  ("whichever is easier", "whichever she likes") still reads."""

from __future__ import annotations

import pytest

from hltl.world.scene import load_scene
from tests.grounding.helpers import CELL, ROOT, assert_reads, assert_refused

FIG = load_scene(ROOT / "examples/scenes/fig1.yaml")


@pytest.mark.parametrize(
    "text",
    [
        "Bottle to Person A. Chips to Person B. Then whatever the deckhand tells you.",
        "Bottle to Person A. Whatever the deckhand tells you.",
        "Bottle to Person A, chips to Person B, then whatever the skipper says.",
        "Give Person A the bottle. After that, whatever the foreman decides.",
        "Chips to Person B. Then whichever the boss asks for.",
    ],
)
def test_a_next_step_left_to_someone_elses_word_is_refused(text: str) -> None:
    assert_refused(text, FIG, match="waits on someone else's word")


@pytest.mark.parametrize(
    ("text", "want"),
    [
        ("The bottle or the chips to Person A, whichever is easier.", "bottle>A | chips>A"),
        ("The bottle or the chips to Person A, whichever she likes.", "bottle>A | chips>A"),
        ("Bottle to Person A. Chips to Person B.", "bottle>A & chips>B"),
    ],
)
def test_a_remark_on_a_choice_still_reads(text: str, want: str) -> None:
    assert_reads(text, want, FIG)


def test_the_cell_scene_reads_a_choice_remark_and_refuses_a_deferral() -> None:
    assert_reads("Give Bob the cup or the apple, whichever is nearer.", "cup>B | apple>B", CELL)
    assert_refused(
        "Give Bob the cup, then whatever Carol tells you.", CELL, match="someone else's word"
    )
