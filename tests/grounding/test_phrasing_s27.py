"""Session-27 phrasings of issue 12 (engineer 12): the speaker's remarks no longer take an
exclusion or a correction said after the request with them, and blind25's refusals by kind
(docs/grounding.md, "Session 27 (engineer 12)")."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.world.scene import Scene
from tests.grounding.helpers import (
    CELL,
    CLASSROOM,
    KITCHEN,
    LAB,
    NURSERY,
    WARD,
    WORKSHOP,
    assert_reads,
    assert_refused,
    assert_same_or_refused,
    tree,
)

# -- (a) an opener about the speaker, a request that leaves out or corrects, a closing sentence --
#
# "I hope this is okay, give Alice a mug, just not the blue one. Good robot." was read as either
# mug: the speaker's remark ('I hope this is okay') let the words after the request that begin
# with 'just' / 'only' ("just not the blue one", "just the one") be taken for more about the
# speaker, and taken off. Such words now stay when they could single out or leave out an object.

# a scene, a kind it has two of, the words telling them apart, their ids, and a person
PAIRS: list[tuple[Scene, str, str, str, str, str, str, str]] = [
    (CELL, "mug", "red", "blue", "mug_red", "mug_blue", "Alice", "A"),
    (NURSERY, "block", "red", "green", "block_red", "block_green", "Ava", "C"),
    (KITCHEN, "plate", "white", "blue", "plate_white", "plate_blue", "Lena", "B"),
    (LAB, "cup", "green", "white", "cup_green", "cup_white", "Omar", "B"),
    (WARD, "blanket", "blue", "grey", "blanket_blue", "blanket_grey", "Mrs Khan", "C"),
    (CLASSROOM, "book", "red", "green", "book_red", "book_green", "Zoe", "C"),
    (WORKSHOP, "spanner", "small", "large", "spanner_small", "spanner_large", "Jess", "B"),
]
OPENERS = [
    "",
    "I hope this is okay, ",
    "I know you're busy, but ",
    "Sorry to bother you, but ",
    "I'm in a bit of a rush, ",
    "Morning! I'm only here for the day. ",
    "Oh, sorry, I've got clay up to my elbows. ",
    "Hope you're well, ",
]
CLOSERS = [
    "",
    ".",
    ". Good robot.",
    ". Have a great day.",
    ". Thanks!",
    ", cheers, you're a star.",
    ". Thank you so much, I'm only here for the day.",
]
# (request, which of the two it asks for: "x", "y", or None where it must be refused)
REQUESTS = [
    ("give {p} a {k}, just not the {x} one", "y"),
    ("give {p} a {k}, but not the {x} one", "y"),
    ("{p} wants a {k}, just not the {x} one", "y"),
    ("a {k} for {p}, just not the {x} one", "y"),
    ("give {p} a {k}, just the {x} one", "x"),
    ("give {p} a {k}, only the {x} one", "x"),
    ("give {p} a {k}, just the {x}", "x"),
    ("give {p} the {x} {k}, no wait, the {y} one", "y"),
    ("the {k}s to {p}, sorry, just the one", None),
    ("give {p} the {k}s, no, just the one", None),
    ("the {k}s to {p}, actually, only the one", None),
]


@settings(max_examples=150, deadline=None)
@given(
    st.sampled_from(PAIRS),
    st.sampled_from(OPENERS),
    st.sampled_from(REQUESTS),
    st.sampled_from(CLOSERS),
)
def test_a_speaker_remark_keeps_the_exclusion_after_the_request(
    pair: tuple[Scene, str, str, str, str, str, str, str],
    opener: str,
    request: tuple[str, str | None],
    closer: str,
) -> None:
    scene, k, x, y, xid, yid, p, pid = pair
    said, which = request
    text = opener + said.format(p=p, k=k, x=x, y=y) + closer
    text = text[0].upper() + text[1:]
    if which is None:
        got = tree(text, scene)
        assert got is None, f"{text!r} grounded; 'just the one' of two must be refused"
        return
    assert_same_or_refused(text, f"{xid if which == 'x' else yid}>{pid}", scene)


def test_the_two_fuzz_wrongs_of_session_26() -> None:
    assert_reads(
        "I hope this is okay, give Alice a mug, just not the blue one. Good robot.", "mug_red>A"
    )
    assert_refused(
        "I know you're busy, but the blocks to Ava, sorry, just the one. Have a great day.",
        NURSERY,
        match="block_green or block_red",
    )


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        # what the speaker is doing, after the request, is still a remark
        ("I'm in a rush, give Bob the cup, just popping out. Good robot.", "cup>B", CELL),
        ("I'm on my break, pass Omar the banana, only in for a minute. Thanks!", "banana>B", LAB),
        ("I'm the porter, here to fix the lift, could the jug go to Ruth? Ta.", "jug>A", WARD),
    ],
)
def test_what_the_speaker_is_doing_is_still_taken_off(text: str, want: str, scene: Scene) -> None:
    assert_reads(text, want, scene)
