"""Session-34 phrasing of issue 12 (lead): wrong readings the fuzz found (docs/grounding.md,
"Session 34 (lead)").

- 12r's repairs fuzz: "Give Person B, er, I mean Person A the bottle, or no, hang on, the other
  one, you know." (2-4-line) read chips>A. After a correction, 'the other one' of an object the
  only one of its kind could as well correct the recipient; that reading was looked for only
  when one person had been said, and here two were (Person B, taken back at once, and Person A).
  The other person is now the one besides the recipient in force (the last one said), so the
  sentence is refused naming both readings, as it is without the first repair."""

from __future__ import annotations

import pytest

from hltl.world.scene import load_scene
from tests.grounding.helpers import ROOT, assert_reads, assert_refused

L24 = load_scene(ROOT / "examples/scenes/2-4-line.yaml")


@pytest.mark.parametrize(
    "text",
    [
        "Give Person B, er, I mean Person A the bottle, or no, hang on, the other one, you know.",
        "Give Person B, no, Person A the bottle, or no, the other one.",
        "Give Person B, no, Person A the bottle. No, the other one.",
        "Give Person A the bottle, or no, hang on, the other one, you know.",
        "Give Person A, sorry, Person B the chips, no, wait, the other one.",
    ],
)
def test_the_other_one_after_a_repaired_recipient_is_refused(text: str) -> None:
    assert_refused(text, L24, match="could mean")


@pytest.mark.parametrize(
    ("text", "want"),
    [
        ("Give Person B, er, I mean Person A the bottle.", "bottle>A"),
        ("Give Person B, no, Person A the bottle, or no, the chips.", "chips>A"),
        ("Give Person B, no, Person A the bottle, or no, Person B.", "bottle>B"),
    ],
)
def test_a_repair_that_names_what_it_means_still_reads(text: str, want: str) -> None:
    assert_reads(text, want, L24)
