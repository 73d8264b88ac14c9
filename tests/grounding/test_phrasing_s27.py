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
    DEPOT,
    KITCHEN,
    LAB,
    NURSERY,
    OFFICE,
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
    ("both {k}s to {p}, sorry, just the {x} one", "x"),
    ("both {k}s to {p}, sorry, just the {y} one", "y"),
    ("give {p} the {k}s, sorry, just the {y} one", "y"),
    ("the {x} {k} and the {y} {k} to {p}, sorry, the {y} one", "y"),
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


@pytest.mark.parametrize(
    ("text", "scene"),
    [
        # three of a kind: 'boxes' was not made 'box' (a plural of '-es'), so every box was read
        ("The boxes to Mia, sorry, just the one.", DEPOT),
        ("Give Tom the boxes, no, just the one.", DEPOT),
        ("The pens to Sam, I mean, just the one.", OFFICE),
    ],
)
def test_just_the_one_after_a_plural_is_refused_with_its_readings(text: str, scene: Scene) -> None:
    assert_refused(text, scene, match="ambiguous")


def test_a_correction_naming_the_last_object_again_beside_others_is_refused() -> None:
    # replaced by itself, it kept both
    assert_refused("Give Alice the cup and the apple, sorry, the apple.", match="cannot tell")
    assert_refused("The red mug and the blue mug to Bob, no, the blue one.", match="cannot tell")
    # another object named instead is read as before
    assert_reads("Give Alice the cup and the apple, sorry, the bottle.", "cup>A & bottle>A")
    assert_reads("The mugs to Carol, sorry, just the blue one.", "mug_blue>C")


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        # what replaces 'both <kinds>' takes 'both' with them
        ("Both mugs to Alice, sorry, just the blue mug.", "mug_blue>A", CELL),
        ("Both blocks to Ava, sorry, just the green one.", "block_green>C", NURSERY),
        ("Give Mrs Khan both blankets, no, the grey one.", "blanket_grey>C", WARD),
        # another object instead of the two (the rewrite 'the red mug and the blue mug' had
        # replaced the blue one alone: mug_red>A & cup>A)
        ("Both mugs to Alice, sorry, the cup.", "cup>A", CELL),
        ("Give Zoe both books, no, the globe.", "globe>C", CLASSROOM),
    ],
)
def test_a_correction_of_both_replaces_the_two(text: str, want: str, scene: Scene) -> None:
    assert_reads(text, want, scene)


def test_in_between_after_a_remark_is_not_taken_off() -> None:
    # 'in between' orders the request against another: after "I hope this is okay," the remark
    # rule took it off with the remark
    assert_refused("I hope this is okay, in between, give Bob the chips. Have a great day.")
    assert_refused("I hope this is okay, in between, hand Carol the apple. Good robot.")


# -- (b) blind25's refusals by kind -------------------------------------------------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        # the 'no?' tag of Sinhala and Indian English ('isn't it?') after a request
        ("Kindly pass the banana to Omar, no?", "banana>B", LAB),
        ("You can give Mr Lee the jug, no?", "jug>B", WARD),
        ("The tongs go to Marco, no?", "tongs>A", KITCHEN),
        # who said it is so, at the end: the request stands as said
        ("Omar wants the banana, he said so earlier.", "banana>B", LAB),
        ("Give Mrs Khan the magazine, she told me so herself.", "magazine>C", WARD),
    ],
)
def test_a_tag_or_a_report_after_a_request_asks_nothing(text: str, want: str, scene: Scene) -> None:
    assert_reads(text, want, scene)


@pytest.mark.parametrize(
    ("text", "scene"),
    [
        # without its question mark, or with a name after it, 'no' may correct or take back
        ("Kindly pass the banana to Omar, no!", LAB),
        ("Pass the banana to Omar, no? Emma.", LAB),
        ("Give Mr Lee the jug, no.", WARD),
        # 'told me to' could make the speaker the one asked for something
        ("Give Omar the banana, she told me to.", LAB),
    ],
)
def test_near_forms_that_could_ask_stay_refused(text: str, scene: Scene) -> None:
    assert_refused(text, scene)
