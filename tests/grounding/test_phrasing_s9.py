"""Session-9 phrasings of issue 12: blind7's misses met by cause (a task said again, people named
in a refusal, ...), each as a family, with properties checked against independent oracles and
that none of them turns a refusal into a wrong reading."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.world.scene import load_scene
from tests.grounding.helpers import CELL, ROOT, assert_refused, tree
from tests.grounding.helpers import assert_reads as assert_means

WARD = load_scene(ROOT / "tests/grounding/paraphrase/scenes/ward.yaml")

# -- a task said again: two hand-overs of one object cannot be done, so refused -----------------

TASKS = [
    ("give Alice the apple", "give her the apple", "apple>A"),
    ("put the cup on the shelf", "put it on the shelf", "cup@shelf"),
    ("hand Bob the chips", "hand him the chips", "chips>B"),
    ("give Carol the bottle", "give the bottle to Carol", "bottle>C"),
]
JOINS = [" and then ", ", then ", ". Then ", " and ", ", and after that "]


@settings(max_examples=40, deadline=None)
@given(st.sampled_from(TASKS), st.sampled_from(JOINS))
def test_a_task_said_again_is_refused_not_read_once(task: tuple[str, str, str], join: str) -> None:
    first, second, want = task
    # the oracle: without 'again' a restated task is that task (one hand-over) ...
    assert_means(f"{first}{join}{second}", want)
    # ... with 'again' it asks for a second hand-over, which cannot be done: refused
    assert_refused(f"{first}{join}{second} again", match="a second time")


def test_again_alone_changes_nothing() -> None:
    assert_means("Give Alice the apple again", "apple>A")
    assert_means("Give Alice the apple and Bob the chips again", "apple>A & chips>B")
    assert_means("give Alice the apple, thanks again", "apple>A")


# -- an alias two people share: the refusal names the people -----------------------------------


@pytest.mark.parametrize(
    "text",
    ["Give the patient the magazine", "the patient needs the jug", "hand the patient a blanket"],
)
def test_a_shared_alias_names_the_people(text: str) -> None:
    assert_refused(
        text, WARD, match=r"Person B \(Mr Lee, patient\) or Person C \(Mrs Khan, patient\)"
    )


def test_a_shared_alias_among_others_is_still_refused() -> None:
    assert tree("Give Ruth the jug and the patient the magazine", WARD) is None
    assert_means("Give Mr Lee the magazine", "magazine>B", WARD)
    assert_means("Give Mrs Khan the magazine", "magazine>C", WARD)
    assert_means("Give Ruth the magazine and the jug", "magazine>A & jug>A", WARD)
    assert tree("give Alice the apple", CELL) is not None
