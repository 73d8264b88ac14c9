"""Session 51 (12p): the gate asks every set of words a pattern's match needs (a word of each),
not only the best one. Each set is needed by every match (a run of literals, a branch whose every
alternative needs a word, a plain or atomic group, a repeat at least once; never an optional
part, a look-around or a group with flags of its own); a pattern turned away by them finds
nothing, over corpus sentences and mixes of the patterns' own words."""

from __future__ import annotations

import re
from functools import cache

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.bench.grounding import CORPUS_DIR, load_corpus
from hltl.grounding import gate
from hltl.grounding._warm_patterns import PATTERNS
from tests.grounding.helpers import ROOT


def _sets(pattern: str, flags: int) -> list[list[str]]:
    parsed = gate._parser.parse(pattern, flags)
    fold = bool(parsed.state.flags & re.IGNORECASE)
    return sorted(sorted(words) for words in gate._all_needed(parsed, fold))


@pytest.mark.parametrize(
    ("pattern", "flags", "want"),
    [
        (
            r"\bneeds? the ([a-z]+) (?:he|she)'s\b",
            re.I,
            [[" "], [" the "], ["'s"], ["he", "she"], ["need"]],
        ),
        (r"a(?:bc)?d", 0, [["a"], ["d"]]),  # an optional part needs nothing
        (r"x(?:foo|bar)*y", 0, [["x"], ["y"]]),
        (r"x(?:foo|bar)+y", 0, [["bar", "foo"], ["x"], ["y"]]),  # once at least
        (r"ab(?=cd)", 0, [["ab"]]),  # a look-ahead is not part of the match
        (r"(?i:abc)x", 0, [["x"]]),  # a group with flags of its own is not asked
        (r"(?:left|right|) hand", 0, [[" hand"]]),  # an alternative without a word
        (r"Give (\w+) the (cup|mug)", 0, [[" the "], ["Give "], ["cup", "mug"]]),
    ],
)
def test_every_set_of_words_a_match_needs(pattern: str, flags: int, want: list[list[str]]) -> None:
    assert _sets(pattern, flags) == want


def test_the_other_sets_are_asked_after_the_gate_s_own() -> None:
    pattern = r"Give (\w+) the (cup|mug) now"
    gate.forget(pattern, 0)
    assert gate._gate(pattern, 0, build=False) == (("Give ",), False)
    assert gate._ALSO[0][pattern] == ((" the ",), (" now",), ("cup", "mug"))
    assert gate.may_match(pattern, 0, "Give Bob the cup now")
    assert not gate.may_match(pattern, 0, "Give Bob the plate now")  # no cup nor mug
    assert not gate.may_match(pattern, 0, "give Bob the cup now")  # 'Give' is asked as said
    assert re.search(pattern, "Give Bob the plate now") is None
    # a set every word of the gate's own holds a word of is not asked again; nor one letter
    pattern = r"(?:the|then) (cup|mug)"
    gate.forget(pattern, re.I)
    assert gate._gate(pattern, re.I, build=False) == (("the",), True)
    assert gate._ALSO[re.I][pattern] == (("cup", "mug"),)


@cache
def _with_more() -> tuple[tuple[str, int], ...]:
    """The warm list's patterns that have sets besides the gate's own."""
    out = []
    for pattern, flags, _build in PATTERNS:
        gate.prepare(pattern, flags, build=False)
        if gate._ALSO.get(flags, {}).get(pattern):
            out.append((pattern, flags))
    return tuple(out)


@cache
def _words() -> tuple[str, ...]:
    said: set[str] = set()
    for pattern, flags in _with_more():
        own = gate._GATES[flags][pattern]
        if own is not None:
            said.update(own[0])
        for words in gate._ALSO[flags][pattern]:
            said.update(words)
    return tuple(sorted(said))


@cache
def _sentences() -> tuple[str, ...]:
    corpus = load_corpus(ROOT / CORPUS_DIR / "tuning.yaml", ROOT)
    return tuple(e.text for e in corpus.entries)


def test_many_patterns_have_more_than_one_set() -> None:
    assert len(_with_more()) > 300


@settings(max_examples=150, deadline=None)
@given(
    st.one_of(
        st.sampled_from(_sentences()),
        st.lists(st.sampled_from(_words()), min_size=1, max_size=8).map(" ".join),
        st.tuples(st.sampled_from(_sentences()), st.sampled_from(_words())).map(" ".join),
    ),
    st.integers(min_value=0, max_value=10_000),
)
def test_a_pattern_turned_away_finds_nothing(text: str, at: int) -> None:
    patterns = _with_more()
    for pattern, flags in patterns[at % len(patterns) :][:40]:
        if not gate.may_match(pattern, flags, text):
            assert re.search(pattern, text, flags) is None, (pattern, text)
