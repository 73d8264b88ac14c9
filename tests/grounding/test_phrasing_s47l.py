"""Phrasings the session-47 lead rules read (docs/grounding.md, Session 47 (lead))."""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from hltl.grounding import _rewrites47l
from hltl.world.scene import Scene, load_scene
from tests.grounding.helpers import (
    KITCHEN,
    LAB,
    ROOT,
    WARD,
    WORKSHOP,
    assert_reads,
    assert_refused,
)

FOUR_ONE = load_scene(ROOT / "examples/scenes/4-1.yaml")  # bottle, chips, cup, apple; A, B

# -- "X, I thought, but it was Y he wanted": the thought is taken back (blind45's one wrong reading
# kept the salt wanted)


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        (
            "Marco's shouting for salt, I thought, but it was lemon he wanted, so give Marco the "
            "lemon.",
            "lemon>A",
            KITCHEN,
        ),
        ("Marco wants the salt, I thought, but it was the lemon he wanted.", "lemon>A", KITCHEN),
        (
            "Marco wants the salt, or so I thought, but it was the lemon he wanted.",
            "lemon>A",
            KITCHEN,
        ),
        ("Dana wanted the spoon, I thought, but it was the bowl she wanted.", "bowl>A", LAB),
        ("Give Omar the bowl, I thought, but it was Dana who asked for it.", "bowl>A", LAB),
    ],
)
def test_a_thought_taken_back_is_not_read(text: str, want: str, scene: Scene) -> None:
    assert_reads(text, want, scene)


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        # no 'but': the hedge says nothing against the request
        ("Marco's shouting for salt, I thought.", "salt>A", KITCHEN),
        ("Dana wants the spoon, I thought.", "spoon>A", LAB),
        # where the thing is, not a correction (12c's probes: read `salt@rack`)
        ("Marco wants the salt, I thought, but it's on the rack.", "salt>A", KITCHEN),
        # 12c's `thoughts` fuzz family, `where` form (read `pills@trolley`, `thermometer@bedside`)
        (
            "Ruth needs the tablets for the morning round, I thought, but it's on the cart now.",
            "pills>A",
            WARD,
        ),
        (
            "nurse ruth is shouting for the thermometer, quick as u can, I think, but it's on the "
            "bedside table.",
            "thermometer>A",
            WARD,
        ),
    ],
)
def test_a_hedge_alone_keeps_the_request(text: str, want: str, scene: Scene) -> None:
    assert_reads(text, want, scene)


@pytest.mark.parametrize(
    "text",
    [
        "Give Marco the salt, I thought, but it was lemon.",
        # a correction that adds or orders does not say whether the salt stays (12c's probes)
        "Give Marco the salt, I thought, but it's the lemon he needs first.",
        "Marco wants the salt, I thought, but it's the lemon he wants too.",
        "Marco wants the salt, I reckoned, but it was the lemon he wanted as well.",
        "Marco wants the salt, I thought, but it's the lemon he wants and the salt for Lena.",
        # the present 'I think' is a hedge, not a thought taken back: refused as before
        "Give Marco the salt, I think, but it's Lena who needs the lemon first.",
        "Marco wants the salt, I think, but it's the lemon he wants too.",
    ],
)
def test_a_taken_back_thought_it_cannot_read_is_refused(text: str) -> None:
    assert_refused(text, KITCHEN)


@given(
    verb=st.sampled_from(["thought", "reckoned", "figured", "assumed", "believed"]),
    tail=st.sampled_from(["it was", "it's", "it is"]),
)
def test_the_rewrite_says_no(verb: str, tail: str) -> None:
    text = f"Marco wants the salt, I {verb}, but {tail} the lemon."
    assert _rewrites47l.thought_but47l(text) == f"Marco wants the salt, no, {tail} the lemon."
    plain = f"Marco wants the salt, I {verb}."
    assert _rewrites47l.thought_but47l(plain) == plain
    where = f"Marco wants the salt, I {verb}, but {tail} on the rack."
    assert _rewrites47l.thought_but47l(where) == where
    hedge = f"Marco wants the salt, I think, but {tail} the lemon."
    assert _rewrites47l.thought_but47l(hedge) == hedge


# -- 'no, it's the lemon he wants too / first / and …': a correction that adds or orders, refused
# (12c's probes: the older correction rules read the lemon alone)


@pytest.mark.parametrize(
    ("text", "scene"),
    [
        ("Marco wants the salt, no, it's the lemon he wants too.", KITCHEN),
        ("Marco wants the salt, no, it's the lemon he wants and the salt for Lena.", KITCHEN),
        ("Give Marco the salt, no, it's the lemon he needs first.", KITCHEN),
        ("Dana wants the spoon, sorry, it's the bowl she wants as well.", LAB),
        ("Give Omar the bowl, no, it was the spoon he asked for next.", LAB),
    ],
)
def test_a_correction_that_adds_or_orders_is_refused(text: str, scene: Scene) -> None:
    assert_refused(text, scene)


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        ("Knife to Lena, no, it's the tongs she wanted after service.", "tongs>B", KITCHEN),
        ("Dana wants the spoon, no, it's the bowl she wants.", "bowl>A", LAB),
    ],
)
def test_a_plain_correction_still_reads(text: str, want: str, scene: Scene) -> None:
    assert_reads(text, want, scene)


# -- "… on the workbench and then Kofi, I mean Jess gets the hammer": the repair takes back the
# name, not the placing before it (12c's repairs fuzz on blind45: read `hammer>B`)


@pytest.mark.parametrize(
    "text",
    [
        "Put the screws on the workbench and then Kofi, I mean Jess gets the hammer.",
        "Screws go on the workbench and after that Kofi, I mean Jess gets the hammer.",
        "Put the screws on the workbench and then Kofi, sorry, Jess wants the hammer.",
    ],
)
def test_a_subject_repaired_after_a_join_keeps_the_clause_before(text: str) -> None:
    assert_reads(text, "screws@bench ; hammer>B", WORKSHOP)


def test_a_subject_repaired_after_and_alone_reads_as_before() -> None:
    # after 'and' alone the rule above does not act (session 32: "Alice gets a mug and Carol,
    # sorry, Bob gets the other one" stays refused); a placing then a person reads as it did
    assert_reads(
        "Put the screws on the workbench and Kofi, I mean Jess gets the hammer.",
        "screws@bench & hammer>B",
        WORKSHOP,
    )


# -- "she'll be after the cup": a want, not the order word 'after' (engineer 12 found `cup>A ;
# apple>A` on main)


@pytest.mark.parametrize(
    ("text", "want"),
    [
        ("Person A would like the apple; she'll be after the cup too.", "apple>A & cup>A"),
        ("Person A would like the apple; she'll be after the cup.", "apple>A & cup>A"),
        ("Person A would like the apple, then she'll be after the cup.", "apple>A ; cup>A"),
        ("Person B'll be after the chips.", "chips>B"),
    ],
)
def test_a_person_who_will_be_after_a_thing_wants_it(text: str, want: str) -> None:
    assert_reads(text, want, FOUR_ONE)


def test_a_thing_that_will_be_after_another_is_not_a_want() -> None:
    assert_refused("The bottle will be after the chips.", FOUR_ONE)


@given(
    who=st.sampled_from(["she", "he", "Person B"]),
    aux=st.sampled_from(["'ll", " will", " would", "'d", " might", " may"]),
)
def test_the_grammar_reads_be_after_as_want(who: str, aux: str) -> None:
    # session 48 (lead): the grammar's `_is_after` reads it (session 47 rewrote the text first)
    person = "Person B" if who != "she" else "Person A"
    thing = "chips" if who != "she" else "cup"
    first = "Person A would like the apple" if who == "she" else "Person B would like the apple"
    text = f"{first}; {who}{aux} be after the {thing}."
    assert_reads(text, f"apple>{person[-1]} & {thing}>{person[-1]}", FOUR_ONE)
    assert_refused(f"The bottle{aux} be after the {thing}.", FOUR_ONE)
