"""Session-25 phrasings of issue 12 (engineer 12r): one rule per kind — the speaker's remarks of
sessions 15, 22 and 24 as one rule (normalise.py `_speaker_remarks`), one list of sentence and
polite particles (`_PARTICLES`) — with today's readings pinned on every corpus-wrapper variant the
rules touch; and blind22's refusals by kind (docs/grounding.md, "Session 25, engineer 12r")."""

from __future__ import annotations

import csv
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.bench.grounding import CORPUS_DIR, load_corpus, show_tree
from hltl.grounding.lexicon import Lexicon
from hltl.grounding.normalise import _PARTICLES, _speaker_remarks
from hltl.grounding.offline import parse_instruction
from hltl.world.scene import Scene, load_scene
from tests.grounding.helpers import (
    ROOT,
    SCENES,
    assert_reads,
    assert_refused,
    assert_same_or_refused,
    plain_request,
)

TWO = load_scene(ROOT / "examples/scenes/two_arms.yaml")  # bottle, chips (crisps); Alice, Bob

# -- (a) one rule for the speaker's remarks ----------------------------------------------------


@pytest.mark.parametrize(
    ("text", "left"),
    [
        # session 22's kind: a sentence of the speaker's before the request
        (
            "I'm the farmer, my boots are filthy so I won't come in. Give Bob the crisps.",
            "Give Bob the crisps.",
        ),
        (
            "Afternoon, mind the smoke on my jacket, I've come straight from the hives. Give Bob "
            "the crisps.",
            "Give Bob the crisps.",
        ),
        (
            "Sorry, I'm the gardener, only in to see to the spider plants. Give Bob the crisps.",
            "Give Bob the crisps.",
        ),
        # session 24's kind: a stretch anywhere, pronouns allowed
        ("Give Bob the crisps, I keep losing it.", "Give Bob the crisps."),
        ("Give Bob the crisps while I sort the rota.", "Give Bob the crisps."),
        ("Oh, sorry, I've got clay up to my elbows. Give Bob the crisps.", "Give Bob the crisps."),
        # session 15's kind: a clause about the speaker, the hearer or the moment, the 'but'
        # that joins it, a call opening the text, an apology next to a remark
        (
            "I know it's hectic, but could you give Bob the crisps?",
            "could you give Bob the crisps?",
        ),
        ("Give Bob the crisps, hope you're having a great day.", "Give Bob the crisps."),
    ],
)
def test_one_rule_takes_off_each_kind_of_remark(text: str, left: str) -> None:
    assert _speaker_remarks(text, Lexicon.of(TWO)) == left


@pytest.mark.parametrize(
    "text",
    [
        "Give Bob the crisps, I need the bottle.",
        "Give Bob the crisps, I'm saving the bottle.",  # names the scene
        "Give Bob the crisps, I'm not sure which.",  # chooses, doubts
        "Give Bob the crisps, I changed my mind.",  # takes the request back
    ],
)
def test_a_remark_that_asks_changes_or_names_is_kept(text: str) -> None:
    assert _speaker_remarks(text, Lexicon.of(TWO)) == text


def test_the_speaker_as_a_recipient_stays_refused() -> None:
    # the remark goes; 'me' stays, and is no one in the scene
    assert _speaker_remarks("Give me the crisps, I'm starving.", Lexicon.of(TWO)) == (
        "Give me the crisps."
    )
    assert_refused("Give me the crisps, I'm starving.", TWO)


def test_a_remark_between_a_name_and_a_correction_is_kept() -> None:
    # taken off, it would join what is corrected to the correction
    said = "Give Bob the crisps, I always mix them up, no, Alice."
    assert _speaker_remarks(said, Lexicon.of(TWO)) == said
    # before anything is named it joins nothing: a sentence of the speaker's goes
    assert (
        _speaker_remarks("I'm the farmer. Give Bob the crisps, no, Alice.", Lexicon.of(TWO))
        == "Give Bob the crisps, no, Alice."
    )
    assert_reads("I'm the farmer. Give Bob the crisps, no, Alice.", "chips>A", TWO)


# -- (b) one particle list -----------------------------------------------------------------------


@settings(max_examples=60, deadline=None)
@given(
    st.sampled_from(SCENES),
    st.integers(0, 20),
    st.sampled_from(sorted(_PARTICLES)),
    st.sampled_from(["{r} {p}.", "{r}, {p}.", "{p}, {r}.", "{r}, {p}, thanks."]),
)
def test_a_particle_glued_or_alone_asks_nothing(
    scene: Scene, k: int, particle: str, frame: str
) -> None:
    request, want = plain_request(scene, k)
    assert_same_or_refused(frame.format(r=request, p=particle), want, scene)


@pytest.mark.parametrize("particle", ["krap", "lah", "innit", "po", "ah"])
def test_each_particle_reads_alone_and_glued(particle: str) -> None:
    assert_reads(f"Give Bob the crisps, {particle}.", "chips>B", TWO)
    assert_reads(f"Give Bob the crisps please {particle}.", "chips>B", TWO)


def test_a_particle_never_hides_a_request_or_a_correction() -> None:
    assert_refused("Krap.", TWO)
    assert_refused("Give Bob the crisps, lah, no, Alice, lah, no, I don't know.", TWO)


# -- (c) the readings of every wrapper variant the merged rules touch ----------------------------

# Each row: a corpus entry said inside tests/grounding/fuzz.py's wrappers (seed 25, every 6th entry
# of every part but blind23 and blind24) that one of the old rules (`_remarks15`,
# `_speaker_remarks22`, `_speaker_remarks24`, `_courtesy24`, a particle) or the merged rule
# changed; what it must read as ('refuse' for a near form) and what the merged grounder read. On
# main before the merge each was read the same, or refused (docs/grounding.md, "Session 25,
# engineer 12r"). A row read stays read exactly; a row refused may come to read only as it must.
PINNED = Path(__file__).parent / "fixtures" / "remarks_s25r.tsv"


def _pinned() -> list[tuple[str, str, str, str, str]]:
    with PINNED.open(newline="") as f:
        return [(r[0], r[1], r[2], r[3], r[4]) for r in csv.reader(f, delimiter="\t")]


ROWS = _pinned()
_SCENES: dict[tuple[str, str], Scene] = {}


def _scene(part: str, name: str) -> Scene:
    if (part, name) not in _SCENES:
        corpus = load_corpus(ROOT / CORPUS_DIR / f"{part}.yaml", ROOT)
        for key, scene in corpus.scenes.items():
            _SCENES[(part, key)] = scene
    return _SCENES[(part, name)]


def test_the_pinned_rows_cover_each_rule() -> None:
    assert len(ROWS) >= 300
    assert sum(1 for r in ROWS if r[3] == "refuse") >= 50  # near forms
    assert sum(1 for r in ROWS if r[4] != "refused") >= 100  # read


@pytest.mark.parametrize(
    ("part", "scene", "text", "want", "read"), ROWS, ids=[r[2][:60] for r in ROWS]
)
def test_a_pinned_variant_reads_as_before(
    part: str, scene: str, text: str, want: str, read: str
) -> None:
    if read != "refused":
        assert show_tree(parse_instruction(text, _scene(part, scene))) == read
    elif want == "refuse":
        assert_refused(text, _scene(part, scene))
    else:
        assert_same_or_refused(text, want, _scene(part, scene))
