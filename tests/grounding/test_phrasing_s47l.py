"""Phrasings the session-47 lead rules read (docs/grounding.md, Session 47 (lead))."""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from hltl.grounding import _rewrites47l
from hltl.world.scene import Scene
from tests.grounding.helpers import KITCHEN, LAB, assert_reads, assert_refused

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
        ("Give Marco the salt, I think, but it's the lemon he's after.", "lemon>A", KITCHEN),
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
    ],
)
def test_a_hedge_alone_keeps_the_request(text: str, want: str, scene: Scene) -> None:
    assert_reads(text, want, scene)


def test_a_taken_back_thought_without_a_whole_request_is_refused() -> None:
    assert_refused("Give Marco the salt, I thought, but it was lemon.", KITCHEN)


@given(
    verb=st.sampled_from(["thought", "think", "reckoned", "figured", "assumed"]),
    tail=st.sampled_from(["it was", "it's", "it turns out"]),
)
def test_the_rewrite_says_no(verb: str, tail: str) -> None:
    text = f"Marco wants the salt, I {verb}, but {tail} the lemon."
    assert _rewrites47l.thought_but47l(text) == f"Marco wants the salt, no, {tail} the lemon."
    plain = f"Marco wants the salt, I {verb}."
    assert _rewrites47l.thought_but47l(plain) == plain
