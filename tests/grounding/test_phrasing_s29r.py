"""Session-29 phrasings of issue 12 (engineer 12r): three doubtful readings on main mended (a word
saying 'no' taken off as a filler, 'one thing each' with one person named, an object said after an
exclusion), then blind27's kinds; docs/grounding.md, "Session 29 (engineer 12r)". Each rule with
the sentences it changes and near forms that must still read, or stay refused."""

from __future__ import annotations

import pytest

from hltl.world.scene import Scene
from tests.grounding.helpers import (
    CELL,
    DEPOT,
    KITCHEN,
    WARD,
    WORKSHOP,
    assert_reads,
    assert_refused,
)

# -- (1a) a word saying 'no' is the correction cue 'no', never a filler ------------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        # 'Na' had been taken off as a word the grounder does not know: both objects to Alice
        ("Give Alice the cup. Na, the apple.", "apple>A", CELL),
        ("Give Alice the cup. Nae, the apple.", "apple>A", CELL),
        ("Give Alice the cup. Nein, the apple.", "apple>A", CELL),
        # these were refused as names the scene lacks
        ("Give Alice the cup. Nah, the apple.", "apple>A", CELL),
        ("Give Alice the cup, nah, the apple.", "apple>A", CELL),
        ("Give Alice the cup, nope, the apple.", "apple>A", CELL),
        ("Give Alice the cup. Naw, Bob.", "cup>B", CELL),
        ("Give Alice the cup. Nope, give Bob the apple.", "apple>B", CELL),
        ("Ruth needs the jug. Nah, the pills.", "pills>A", WARD),
    ],
)
def test_a_word_saying_no_corrects(text: str, want: str, scene: Scene) -> None:
    assert_reads(text, want, scene)


@pytest.mark.parametrize(
    "text",
    [
        # 'no' alone after a request names nothing to change to (as "Give Alice the cup. No."):
        # 'Na.' had been taken off as a chat token, 'Nah.' / 'Nope!' as a sentence saying nothing
        "Give Alice the cup. Na.",
        "Give Alice the cup. Nah.",
        "Give Alice the cup. Nope!",
        "Give Alice the cup. Oh, nah.",
        "Na, give Alice the cup.",
    ],
)
def test_no_alone_is_refused(text: str) -> None:
    assert_refused(text, CELL)


def test_na_between_commas_names_both_readings() -> None:
    # Hindi English's tag ('…, na?', isn't it) or 'nah': which is unclear before more words
    assert_refused("Give Alice the cup, na, the apple.", CELL, match="could be 'nah'")


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        # the tag, 'na' of another language and 'nae bother' read as before
        ("Give Alice the cup, na?", "cup>A", CELL),
        ("You will give the cup to Carol, na? She is on the phone since ten.", "cup>C", CELL),
        ("Give Alice the cup. Na gode.", "cup>A", CELL),
        ("Give Alice the cup, nae bother.", "cup>A", CELL),
        ("Give Alice the cup, no worries.", "cup>A", CELL),
    ],
)
def test_near_forms_read_as_before(text: str, want: str, scene: Scene) -> None:
    assert_reads(text, want, scene)


# -- (1b) 'one thing each' before a list naming one person ---------------------------------------


@pytest.mark.parametrize(
    ("text", "scene", "match"),
    [
        # read before as the one hand-over, 'each' unheard
        ("One thing each: the tape for Mia.", DEPOT, "say what Tom gets as well"),
        ("one item each: the tape for Mia.", DEPOT, "say what Tom gets as well"),
        ("One each: the tape for Mia.", DEPOT, "say what Tom gets as well"),
        ("One apiece, the tape for Mia.", DEPOT, "leave out 'apiece'"),
        ("One thing each: the salt for Lena.", KITCHEN, "what Marco and what Mr Novak get"),
    ],
)
def test_each_with_one_person_is_refused(text: str, scene: Scene, match: str) -> None:
    assert_refused(text, scene, match=match)


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        ("One thing each: the tape for Mia and the scanner for Tom.", "tape>A & scanner>B", DEPOT),
        ("One each: the tape for Mia, the scanner for Tom.", "tape>A & scanner>B", DEPOT),
        ("One thing for Mia: the tape.", "tape>A", DEPOT),
        ("Two things for Mia: the tape and the scanner.", "tape>A & scanner>A", DEPOT),
    ],
)
def test_each_with_each_person_reads(text: str, want: str, scene: Scene) -> None:
    assert_reads(text, want, scene)


# -- (1c) an object said after an exclusion, with no 'and' -------------------------------------


@pytest.mark.parametrize(
    ("text", "match"),
    [
        # read before as the torch and the hammer
        ("Give Kofi the torch, not the drill, the hammer.", "one more thing besides 'torch'"),
        ("Give Kofi the torch, not the drill, the hammer too.", "meant in place of 'torch'"),
        ("The torch, not the drill, the hammer for Kofi.", "meant in place of 'torch'"),
        ("Give Kofi a spanner, not the small one, the hammer.", "one more thing besides"),
        # read before as the hammer alone
        ("Give Kofi everything except the drill, the hammer.", "one more left out"),
        ("Give Kofi everything but the drill, the hammer.", "one more left out"),
    ],
)
def test_an_object_after_an_exclusion_is_refused(text: str, match: str) -> None:
    assert_refused(text, WORKSHOP, match=match)


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        ("Give Kofi the torch, not the drill, and the hammer.", "torch>A & hammer>A", WORKSHOP),
        ("Give Kofi the torch and the hammer, not the drill.", "torch>A & hammer>A", WORKSHOP),
        ("Give Kofi the torch, not the drill.", "torch>A", WORKSHOP),
        ("Give Kofi the torch, not the drill, thanks.", "torch>A", WORKSHOP),
        # the one meant: one of those left, of the kind left out, or the same said again
        ("Give Kofi a spanner, not the small one, the big one.", "spanner_large>A", WORKSHOP),
        ("Give Tom a box, not the small one, the large one.", "box_large>B", DEPOT),
        ("The cup to Alice, not the chips, the cup.", "cup>A", CELL),
        # a clause of its own: a person after it, and one before
        (
            "Give Kofi the torch, not the drill, the hammer for Jess.",
            "torch>A & hammer>B",
            WORKSHOP,
        ),
        ("Give Bob the cup, not the apple, the chips for Carol.", "cup>B & chips>C", CELL),
        (
            "Give Kofi everything except the drill and the hammer.",
            "spanner_small>A & screws>A & torch>A & spanner_large>A",
            WORKSHOP,
        ),
    ],
)
def test_near_exclusions_read(text: str, want: str, scene: Scene) -> None:
    assert_reads(text, want, scene)
