"""Session 52 (12p): always-asked regular expressions run only where they can match — the same
answers on every text, over corpus sentences and mixes of the words the shortcuts ask."""

from __future__ import annotations

import re
from functools import cache
from typing import Any

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.bench.grounding import CORPUS_DIR, load_corpus
from hltl.errors import GroundingError
from hltl.grounding import (
    _normalise2,
    _normalise3,
    _rewrites41l,
    _rewrites42s,
    _rewrites51l,
    gate,
    offline,
)
from hltl.grounding.lexicon import Lexicon
from hltl.world.scene import Scene
from tests.grounding.helpers import CELL, ROOT, WORKSHOP


@cache
def _sentences() -> tuple[str, ...]:
    out: list[str] = []
    for part in ("tuning", "blind22", "blind45", "blind50"):
        corpus = load_corpus(ROOT / CORPUS_DIR / f"{part}.yaml", ROOT)
        out += [e.text for e in corpus.entries]
    return tuple(out)


# -- gate.first_words ------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("pattern", "want"),
    [
        (r"ab|cd", {"ab": {"ab"}, "cd": {"cd"}}),
        (r"sag ?ol|hi", {"sag": {"sag ol"}, "sagol": {"sagol"}, "hi": {"hi"}}),
        (
            r"as-?salaamu? alaikum",
            {"as": {"as-salaam alaikum", "as-salaamu alaikum"}}
            | {"assalaam": {"assalaam alaikum"}, "assalaamu": {"assalaamu alaikum"}},
        ),
        (r"(?:didi )?madloba", {"didi": {"didi madloba"}, "madloba": {"madloba"}}),
        (r"Merci(?: beaucoup)?", {"merci": {"Merci", "Merci beaucoup"}}),
    ],
)
def test_first_words_spell_out_every_text(pattern: str, want: dict[str, set[str]]) -> None:
    assert gate.first_words(pattern, re.I) == want


@pytest.mark.parametrize(
    "pattern",
    [
        r"ab+",  # a repeat without end: not spelt out
        r"a[bc]",  # a class
        r"(?:x)?",  # the empty text
        r" hi",  # begins with a letter that is not a word letter
        r"(?=a)ab",  # a look-around
        "stra\u017fe",  # 'ſ' folds onto 's'
        "\u212aelvin",  # the Kelvin sign folds onto 'k'
        r"(?:a|b|c|d)(?:a|b|c|d)(?:a|b|c|d)",  # more texts than the limit (here 16)
    ],
)
def test_first_words_none_where_not_spelt_out(pattern: str) -> None:
    assert gate.first_words(pattern, re.I, limit=16) is None


def test_the_courtesies_are_spelt_out() -> None:
    by = _normalise2._BY_FIRST24
    assert by is not None and len(by) > 200
    assert {"one", "as", "merci", "o"} <= by.keys()


@cache
def _courtesy_words() -> tuple[str, ...]:
    by = _normalise2._BY_FIRST24 or {}
    return tuple(sorted({t for texts in by.values() for t in texts}))


_SEP = st.sampled_from(["", " ", "-", "'", ",", ".", "x", "_", "1", " one "])


@settings(max_examples=400, deadline=None)
@given(
    st.one_of(
        st.sampled_from(_sentences()),
        st.tuples(
            st.sampled_from(_sentences()),
            _SEP,
            st.sampled_from(_courtesy_words()).map(lambda w: w.upper() if len(w) % 3 else w),
            _SEP,
            st.sampled_from(_courtesy_words()),
        ).map(lambda t: "".join(t)),
        st.lists(st.sampled_from(_courtesy_words()), min_size=1, max_size=4).map(" ".join),
    )
)
def test_courtesy_found_as_the_whole_list_finds_it(text: str) -> None:
    want = _normalise2._COURTESY_WORD24.search(text) is not None
    assert _normalise2._courtesy_word24(text) is want, text


def test_courtesy_shortcut_sees_the_corpus_courtesies() -> None:
    found = [t for t in _sentences() if _normalise2._COURTESY_WORD24.search(t)]
    assert len(found) > 20
    assert all(_normalise2._courtesy_word24(t) for t in found)
    assert not any(_normalise2._courtesy_word24(t) for t in _sentences() if t not in found)


# -- _told_done51l: the patterns' words ------------------------------------------------------

_MIX = (
    *_rewrites51l._WENT_WORDS51L,
    *_rewrites51l._GAVE_WORDS51L,
    "you",
    "You've",
    "the apple",
    "Alice",
    "to",
    "on the shelf",
    "'s",
    "has",
    "up",
)


@settings(max_examples=400, deadline=None)
@given(
    st.one_of(
        st.sampled_from(_sentences()),
        st.lists(st.sampled_from(_MIX), min_size=2, max_size=7).map(" ".join),
        st.tuples(st.sampled_from(_sentences()), st.sampled_from(_MIX)).map(" ".join),
    )
)
def test_a_pattern_whose_words_are_missing_finds_nothing(text: str) -> None:
    low = text.lower()
    if not low.isascii():
        return
    if not any(w in low for w in _rewrites51l._WENT_WORDS51L):
        assert _rewrites51l._WENT51L.search(text) is None, text
    if not any(w in low for w in _rewrites51l._GAVE_WORDS51L):
        assert _rewrites51l._YOU_GAVE51L.search(text) is None, text


# (the reports themselves stay refused: tests/grounding/test_phrasing_s51l.py)


# -- a lazy subject's pattern asked by its tail first ------------------------------------------

_TAILED = (
    (_rewrites41l._DONE41L, _rewrites41l._DONE_SAID41L),
    (_rewrites51l._WENT51L, _rewrites51l._WENT_SAID51L),
    (_rewrites51l._YOU_GAVE51L, _rewrites51l._GAVE_SAID51L),
)


def test_the_tail_is_the_pattern_without_its_subject() -> None:
    for full, tail in _TAILED:
        assert full.pattern == r"(?P<subject>[^,.;:!?]*?)" + tail.pattern
        assert full.flags == tail.flags


@settings(max_examples=400, deadline=None)
@given(
    st.one_of(
        st.sampled_from(_sentences()),
        st.lists(
            st.sampled_from((*_MIX, "been", "handed", ",", "Bob")), min_size=2, max_size=8
        ).map(" ".join),
        st.tuples(st.sampled_from(_sentences()), st.sampled_from(_MIX)).map(" ".join),
    )
)
def test_where_the_tail_finds_nothing_the_pattern_finds_nothing(text: str) -> None:
    for full, tail in _TAILED:
        if tail.search(text) is None:
            assert not list(full.finditer(text)), (full.pattern[:40], text)


def test_the_tail_finds_the_corpus_reports() -> None:
    found = [t for t in _sentences() if _rewrites51l._WENT51L.search(t)]
    assert found
    assert all(_rewrites51l._WENT_SAID51L.search(t) for t in found)


# -- _robot_rest42s: the closing rest said at the text's end ------------------------------------


def test_spelt_spells_out_every_text() -> None:
    assert gate.spelt(r"take (?:five|ten)(?: now)?", re.I) == {
        "take five",
        "take ten",
        "take five now",
        "take ten now",
    }
    assert gate.spelt(r"take \w+") is None


def test_every_rest_ends_in_a_letter() -> None:
    ends = _rewrites42s._REST_ENDS42S
    assert len(ends) > 50
    assert all(t[-1].isalpha() and t == t.lower() for t in ends)


@settings(max_examples=400, deadline=None)
@given(
    st.one_of(
        st.sampled_from(_sentences()),
        st.tuples(
            st.sampled_from(_sentences()).map(lambda t: t.rstrip(".!?")),
            st.sampled_from([", ", " and ", ", then you can ", " ", ","]),
            st.sampled_from(_rewrites42s._REST_ENDS42S).map(
                lambda w: w.upper() if len(w) % 2 else w
            ),
            st.sampled_from(["", ".", "!", " . ", "!!", "?", " x", "s", "\t"]),
        ).map(lambda t: "".join(t)),
    )
)
def test_a_rest_the_check_turns_away_is_not_there(text: str) -> None:
    if _rewrites42s._ROBOT_REST42S.search(text) is not None:
        assert _rewrites42s._may_rest42s(text), text


# -- _inert_stretches: what is left read first -------------------------------------------------


def _reads(text: str, scene: Scene) -> bool:
    try:
        offline.parse_instruction(text, scene, Lexicon.of(scene), normalise=False)
    except GroundingError:
        return False
    return True


@pytest.mark.parametrize(
    ("text", "scene"),
    [
        ("Give Bob the apple, cheers.", CELL),  # the text reads as it is
        ("Give Bob the apple, lovely, cheers mate.", CELL),
        ("cheers, the apple to Bob, ta very much", CELL),
        ("Right, well, bob the apple", CELL),  # neither reads
        ("Thanks, the torch, Jess, cheers.", WORKSHOP),
    ],
)
def test_the_text_is_read_only_where_what_is_left_reads(
    text: str, scene: Scene, monkeypatch: pytest.MonkeyPatch
) -> None:
    read: list[str] = []
    real = offline.parse_instruction

    def counted(said: str, *args: Any, **kwargs: Any) -> Any:
        read.append(said)
        return real(said, *args, **kwargs)

    monkeypatch.setattr(offline, "parse_instruction", counted)
    got = _normalise3._inert_stretches(text, Lexicon.of(scene))
    monkeypatch.undo()
    if not read:
        assert got == text  # nothing inert, or all of it
        return
    out = read[0]
    assert out != text
    if not _reads(out, scene):
        assert read == [out] and got == text
    else:
        assert read == [out, text]
        assert got == (text if _reads(text, scene) else out)
