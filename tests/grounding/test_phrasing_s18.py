"""Session-18 phrasings of issue 12 (blind16's kinds, by mechanism): a speaker's own words around
the request (stammers and restarts, idioms of address, greeting, sign-off, hurry and asides, chat
tokens) change nothing, over every scene's plain requests; what could name, ask or change stays
refused; the wrong reading of 'Then:' on main; refusals that name their readings."""

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
    OFFICE,
    SCENES,
    WARD,
    WORKSHOP,
    assert_reads,
    assert_refused,
    assert_same_or_refused,
    plain_request,
)

# said before or after a request by speakers the grounder was not built for: each asks nothing
OPENERS = (
    "Kia ora, ",
    "G'day mate, ",
    "Roger that. ",
    "Ahoy there! ",
    "Ladies and gentlemen, ",
    "Mark my words, ",
    "Per my last email, ",
    "Going once, going twice, ",
    "Quick one, ",
    "Howdy partner, ",
    "lmao ok ",
    "Bruv, ",
)
CLOSERS = (
    ", over and out.",
    ", sweet as.",
    ", gg",
    " rn",
    ", no cap.",
    ", good hustle, nice work!",
    ", let's move it!",
    ", much obliged.",
    " when u get a chance",
    ". Zzz.",
    ", tysm",
    ", and bob's your uncle.",
)


@settings(max_examples=60, deadline=None)
@given(st.sampled_from(SCENES), st.integers(0, 5), st.sampled_from(OPENERS))
def test_an_opener_changes_nothing(scene: Scene, k: int, opener: str) -> None:
    text, want = plain_request(scene, k)
    assert_same_or_refused(opener + text, want, scene)


@settings(max_examples=60, deadline=None)
@given(st.sampled_from(SCENES), st.integers(0, 5), st.sampled_from(CLOSERS))
def test_a_closer_changes_nothing(scene: Scene, k: int, closer: str) -> None:
    text, want = plain_request(scene, k)
    assert_same_or_refused(text + closer, want, scene)


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        ("Kia ora mate, give Bob the apple, sweet as.", "apple>B", CELL),
        ("ok chat watch this, give Alice the cup, ez", "cup>A", CELL),
        ("C-could you g-give Carol the apple? Th-thanks.", "apple>C", CELL),
        ("Give Carol the b-, the bottle.", "bottle>C", CELL),
        ("Get the, the blue mug and take it to Bob.", "mug_blue>B", CELL),
        ("Put the stapler on the, on the desk.", "stapler@desk", OFFICE),
        ("Could you, um, give the, uh, red pen to Sam?", "pen_red>B", OFFICE),
        ("person b been wanting the cup all day tbh", "cup>B", CELL),
        ("Roger that, tower. Hand Carol the red mug, over.", "mug_red>C", CELL),
    ],
)
def test_a_speakers_own_words_are_read_through(text: str, want: str, scene: Scene) -> None:
    assert_reads(text, want, scene)


@pytest.mark.parametrize(
    ("text", "scene"),
    [
        ("r2, give Bob the cup", CELL),  # a robot said by its id
        ("ms Lee needs the jug", WARD),  # a title is no chat token
        ("Give Bob the cup, like I said, and the apple", CELL),
        ("Apple! Give Bob the cup.", CELL),  # a call that names an object
        ("Tom! Gloves to Mia!", DEPOT),  # a call that names a person
        ("Give Carol the m-, the m-", CELL),  # cut off
        ("Give Jess the sp-", WORKSHOP),
        ("Give Noah the red book, either colour", CLASSROOM),  # no choice before the tail
        ("Sam needs the black pen for Priya.", OFFICE),  # a purpose that names a person
        ("Tom wants the tape for the large box.", DEPOT),  # … or an object
        ("Marco needs the knife so Lena can have the lemon.", KITCHEN),
        ("tom wants the gloves, no gloves for him though", DEPOT),
        ("Roger that, tower, the crisps, over.", CELL),  # nothing asked
        ("Going once, going twice, sold!", CELL),
        # the full fuzz's wrong readings on main (session 18, seed 19): a correction after a name
        # said alone took back the speaker's remark with it; a count of steps counted a sign-off
        ("I'll need it back, so omar, no, Emma needs the banana.", LAB),
        ("I'll need it back, so marco, no, Lena needs the salt.", KITCHEN),
        (
            "Okay three things, drill to Kofi, torch to Jess, and that's your lot. "
            "Have a great day.",
            WORKSHOP,
        ),
        # 'all three of the pens' with no list after it (a crash of the first session-18 rewrite):
        # read since session 27 as the three pens (test_phrasing_s27r.py)
    ],
)
def test_what_could_name_ask_or_change_stays_refused(text: str, scene: Scene) -> None:
    assert_refused(text, scene)


def test_an_order_word_before_a_colon_orders() -> None:
    """'First: X. Then: Y.' was read as X and Y on main (a wrong reading)."""
    assert_reads(
        "First: the stapler to Priya. Then: the red pen to Sam. Last: the notepad in the box.",
        "stapler>A ; pen_red>B ; notebook@box",
        OFFICE,
    )
    assert_reads(
        "Give Priya the stapler. Next: give Sam the red pen.", "stapler>A ; pen_red>B", OFFICE
    )


def test_refusals_name_their_readings() -> None:
    assert_refused("Give Sam the pen that isn't on the desk.", OFFICE, match="pen_black or pen_red")
    assert_refused("Give the book that isn't on the desk to Zoe.", CLASSROOM, match="book_green")
    assert_refused(
        "The cup is for Alice, and the apple goes to the other one.",
        CELL,
        match="Person B .*Person C",
    )
    assert_reads("Give Noah the book that isn't on the shelf.", "book_red>B", CLASSROOM)
