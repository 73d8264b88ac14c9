"""Session-30 phrasing of issue 12 (lead): a sentence that only counts what was asked for ("Two
things, that's the lot.") is a check, never a request of that many (12c's 'afterthoughts' fuzz
read it as one; docs/grounding.md, "Session 30 (lead)")."""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from hltl.world.scene import load_scene
from tests.grounding.helpers import CELL, ROOT, assert_reads, assert_refused, assert_same_or_refused

TWO = load_scene(ROOT / "examples/scenes/2-1.yaml")  # bottle, chips; Person A, Person B
F41 = load_scene(ROOT / "examples/scenes/4-1.yaml")  # bottle, chips, cup, apple


@pytest.mark.parametrize(
    "text",
    [
        "Hey, hand Person B the bottle real quick. Two things, that's the lot.",
        "Give Person B the chips. Two things.",
        "Give Person B the chips. Both things.",
        "Give Person B the chips. That's two things in all.",
        "Give Person A the chips, no, the bottle. Two things, that's the lot.",
        "Give Person B everything except the chips. Two things, that's the lot.",
        "Give Person A the chips or the bottle. Two things, that's the lot.",
        "Give Person B the chips and the bottle. One thing, that's the lot.",
    ],
)
def test_a_count_that_is_not_what_was_asked_is_refused(text: str) -> None:
    assert_refused(text, TWO, match="counts")


@pytest.mark.parametrize(
    ("text", "want"),
    [
        (
            "Give Person B the chips and the bottle. Two things, that's the lot.",
            "chips>B & bottle>B",
        ),
        ("Give Person B the chips, sorry. One thing, that's the lot.", "chips>B"),
        ("Give Person A the bottle. One thing.", "bottle>A"),
        ("Give Person A the bottle. That's one thing in all.", "bottle>A"),
    ],
)
def test_a_count_of_what_was_named_reads_as_the_request(text: str, want: str) -> None:
    assert_reads(text, want, TWO)


def test_the_right_count_after_a_choice_or_same_is_refused() -> None:
    # (fuzz no. 6 and 7) 'the same for' makes more than was named; 'sorry' does not
    assert_reads("Give Bob the cup, sorry. One thing, that's the lot.", "cup>B", CELL)
    assert_refused(
        "Put the apple on the shelf and do the same for the cup. One thing, that's the lot.",
        CELL,
        match="counts",
    )
    assert_refused(
        "Person B wants everything but the apple. Four things, that's the lot.", F41, match="counts"
    )


def test_a_count_said_first_or_inside_a_sentence_is_not_this_rule() -> None:
    # only a sentence of its own after another: these read as before
    assert_reads("Two things for Person B: the chips and the bottle.", "chips>B & bottle>B", TWO)
    assert_reads("Two things. Give Person B the chips and the bottle.", "chips>B & bottle>B", TWO)


@given(
    st.sampled_from(["bottle", "chips"]),
    st.sampled_from(["A", "B"]),
    st.sampled_from(["One thing", "Two things", "Both things", "That's two things in all"]),
    st.sampled_from(["", ", that's the lot", ", that's all"]),
)
def test_a_count_after_one_handover_is_that_handover_or_refused(
    obj: str, who: str, count: str, tail: str
) -> None:
    text = f"Give Person {who} the {obj}. {count}{tail}."
    assert_same_or_refused(text, f"{obj}>{who}", TWO)


TWO_ARMS = load_scene(ROOT / "examples/scenes/two_arms.yaml")  # bottle, chips; Alice, Bob


@pytest.mark.parametrize(
    ("text", "want"),
    [
        # (12c's asides fuzz, causes10: the greeting 'morning.' swallowed the stop after a
        # remark, and the next sentence's person went to Bob)
        (
            "It's been a long morning. Alice gets whatever Bob doesn't: Bob gets the bottle",
            "bottle>B & chips>A",
        ),
        (
            "Bob gets the bottle. It's been a long evening. Alice gets the chips",
            "bottle>B & chips>A",
        ),
        (
            "Bob gets the bottle. It has been a long morning. Alice gets the rest",
            "bottle>B & chips>A",
        ),
        ("Morning. Give Alice the chips.", "chips>A"),
        ("Oh, morning! Give Alice the chips.", "chips>A"),
        ("Good afternoon. Give Alice the chips.", "chips>A"),
    ],
)
def test_a_greeting_word_ending_a_remark_keeps_its_stop(text: str, want: str) -> None:
    assert_reads(text, want, TWO_ARMS)
