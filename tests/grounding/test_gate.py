"""The normaliser's word gate (gate.py): it says a pattern cannot match only where the pattern
finds no match, over the corpus's sentences and random mixes of the words the gate looks for."""

from __future__ import annotations

import contextlib
import re
from collections.abc import Iterator

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.bench.grounding import CORPUS_DIR, load_corpus
from hltl.errors import GroundingError
from hltl.grounding import gate
from hltl.grounding.lexicon import Lexicon
from hltl.grounding.normalise import apostrophes, canonical19, order_colons
from tests.grounding.helpers import ROOT


@pytest.fixture
def checked_gate(monkeypatch: pytest.MonkeyPatch) -> Iterator[list[str]]:
    """The gate, each 'cannot match' checked against re on the same text (failures listed)."""
    wrong: list[str] = []
    real = gate.may_match

    def checked(pattern: str, flags: int, text: str) -> bool:
        says = real(pattern, flags, text)
        if not says and re.search(pattern, text, flags) is not None:
            wrong.append(f"{pattern!r} on {text!r}")
        return says

    monkeypatch.setattr(gate, "may_match", checked)
    yield wrong


@pytest.mark.parametrize("part", ["tuning", "blind20", "causes16"])
def test_the_gate_skips_no_pattern_that_matches_a_corpus_sentence(
    part: str, checked_gate: list[str]
) -> None:
    corpus = load_corpus(ROOT / CORPUS_DIR / f"{part}.yaml", ROOT)
    for entry in corpus.entries[::15]:
        text = order_colons(apostrophes(entry.text))
        with contextlib.suppress(GroundingError):
            canonical19(text, Lexicon.of(corpus.scenes[entry.scene]))
    assert checked_gate == []


@pytest.fixture(scope="module")
def patterns() -> list[tuple[str, int]]:
    """The patterns the rewrites gate on a sample of tuning sentences."""
    seen: set[tuple[str, int]] = set()
    real = gate.may_match

    def recorded(pattern: str, flags: int, text: str) -> bool:
        seen.add((pattern, flags))
        return real(pattern, flags, text)

    corpus = load_corpus(ROOT / CORPUS_DIR / "tuning.yaml", ROOT)
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(gate, "may_match", recorded)
        for entry in corpus.entries[:: len(corpus.entries) // 12]:
            with contextlib.suppress(GroundingError):
                canonical19(entry.text, Lexicon.of(corpus.scenes[entry.scene]))
    return sorted(seen)


def _mix(pattern: str, flags: int) -> st.SearchStrategy[str]:
    """A text of the words ``pattern`` needs, their halves and capitals, and other words."""
    words = sorted(gate.required(pattern, flags)[0] or {"the"})
    pieces = words + [w[: len(w) // 2] for w in words] + [w.upper() for w in words]
    pieces += ["the", "cup", "to", "Alice", ",", ".", "please", "and", "'s", "Mr", " "]
    return st.lists(st.sampled_from(pieces), max_size=12).map(" ".join)


@settings(max_examples=400, deadline=None)
@given(st.data())
def test_the_gate_skips_no_pattern_on_a_mix_of_its_words(
    patterns: list[tuple[str, int]], data: st.DataObject
) -> None:
    assert len(patterns) > 100  # the rewrites' patterns were seen
    pattern, flags = data.draw(st.sampled_from(patterns))
    text = data.draw(_mix(pattern, flags))
    gate.may_match(pattern, flags, "")  # met once: gated from now on
    if not gate.may_match(pattern, flags, text):
        assert re.search(pattern, text, flags) is None, (pattern, text)


@pytest.mark.parametrize(
    ("pattern", "flags", "words"),
    [
        (r"\bwould be grateful for\b", re.I, {"would be grateful for"}),
        (r"(?:a|b)?cup", re.I, {"cup"}),
        (r"\b(?:mug|cups?)\b", re.I, {"mug", "cup"}),
        (r"x*", 0, None),  # matches the empty text: always run
        (r"(?:the )?[\w ]+", re.I, None),
        (r"(?i)Mug|BOWL", 0, {"mug", "bowl"}),
        (r"Mr (\w+)", 0, {"Mr "}),  # case kept: 'mr ' does not match
        (r"(a)\1", 0, {"a"}),
    ],
)
def test_the_words_a_pattern_needs(pattern: str, flags: int, words: set[str] | None) -> None:
    assert gate.required(pattern, flags)[0] == (None if words is None else frozenset(words))


def test_a_pattern_is_gated_the_first_time_it_is_met() -> None:
    pattern = r"\bfirst met (\w+)\b"
    assert not gate.may_match(pattern, re.I, "the cup to Alice")  # derived when first met
    assert not gate.may_match(pattern, re.I, "the cup to Alice")
    assert gate.may_match(pattern, re.I, "FIRST MET Alice")


def test_a_pattern_is_compiled_once_from_the_parse_its_words_came_from(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    parses: list[str] = []
    real = gate._parser.parse

    def counted(pattern: str, flags: int = 0) -> object:
        parses.append(pattern)
        return real(pattern, flags)

    monkeypatch.setattr(gate._parser, "parse", counted)
    pattern = r"\bonce (?:parsed|read) for (\w+)\b"
    for text in ("the cup to Alice", "once parsed for Bob", "the bowl to Bob"):
        gate.sub(pattern, r"\1", text, flags=re.I)
        gate.search(pattern, text, re.I)
    assert gate.sub(pattern, r"\1", "ONCE READ FOR Bob", flags=re.I) == "Bob"
    assert parses == [pattern]


def test_a_compiled_pattern_is_run_as_it_is() -> None:
    compiled = re.compile(r"\b(?P<who>alice|bob) gets (?:the )?(\w+)", re.I)
    size = gate._compiled.cache_info().currsize
    for text in ("Alice gets the cup", "the cup to Alice", "BOB GETS A MUG", "ſo Bob gets it"):
        for name in ("search", "match", "fullmatch"):
            got, want = getattr(gate, name)(compiled, text), getattr(compiled, name)(text)
            assert (got and (got.span(), got.groups())) == (want and (want.span(), want.groups()))
        assert gate.findall(compiled, text) == compiled.findall(text)
        assert gate.split(compiled, text) == compiled.split(text)
        assert gate.sub(compiled, r"\g<who>", text) == compiled.sub(r"\g<who>", text)
        assert gate.sub(compiled, r"\g<who>", text) == re.sub(compiled, r"\g<who>", text)
    assert gate._compiled.cache_info().currsize == size  # never compiled again
    assert (compiled.pattern, compiled.flags) not in gate._BUILT


# pieces of patterns: literals (cased and not), classes, groups, alternations, repeats, anchors,
# look-arounds, back references, inline flags
_PIECES = st.sampled_from(
    [
        "the",
        "Cup",
        "mr ",
        r"\b",
        r"\s+",
        r"\w+",
        "[a-z]",
        "[^,.]*?",
        "(?:mug|bowl)",
        "(?P<who>alice|bob)",
        "(x)?",
        "(?=,)",
        "(?<!no )",
        "(?i:Tea)",
        "s?",
        "(?:a|an) ",
        "$",
        "^",
        "'s",
    ]
)


@settings(max_examples=300, deadline=None)
@given(
    st.lists(_PIECES, min_size=1, max_size=7).map("".join),
    st.sampled_from([0, re.I, re.I | re.M, re.S]),
)
def test_a_pattern_compiled_from_the_gates_parse_is_the_one_re_compiles(
    pattern: str, flags: int
) -> None:
    gate.forget(pattern, flags)
    gate.may_match(pattern, flags, "")  # gated: its parse kept
    try:
        theirs = re.compile(pattern, flags)
    except re.error:
        with pytest.raises(re.error):
            gate.compiled(pattern, flags)
        return
    ours = gate.compiled(pattern, flags)
    assert ours == theirs  # re's equality: the same text, flags and code
    assert (ours.groups, ours.groupindex, ours.flags) == (
        theirs.groups,
        theirs.groupindex,
        theirs.flags,
    )


def test_every_pattern_the_rewrites_gate_compiles_from_its_parse_as_re_does(
    patterns: list[tuple[str, int]],
) -> None:
    for pattern, flags in patterns:
        gate.forget(pattern, flags)
        gate.may_match(pattern, flags, "")
        assert gate.compiled(pattern, flags) == re.compile(pattern, flags), pattern


def test_a_case_kept_pattern_is_checked_with_its_case() -> None:
    gate.may_match(r"Mr (\w+)", 0, "")
    assert not gate.may_match(r"Mr (\w+)", 0, "mr novak wants the cup")
    assert gate.may_match(r"Mr (\w+)", 0, "Mr Novak wants the cup")
    assert gate.may_match(r"mr (\w+)", re.I, "MR NOVAK wants the cup")


def test_a_text_that_is_not_ascii_is_never_gated() -> None:
    # re folds the long s onto 's' in a case-blind pattern: lower() does not
    assert re.search(r"\bsugar\b", "the \u017fugar", re.I) is not None
    assert "sugar" not in "the \u017fugar".lower()
    gate.may_match(r"\bsugar\b", re.I, "")  # met once: gated from now on
    assert gate.may_match(r"\bsugar\b", re.I, "the \u017fugar to Alice")
    assert gate.sub(r"\bsugar\b", "salt", "the \u017fugar", flags=re.I) == "the salt"


def test_the_gated_functions_return_what_re_returns_for_no_match() -> None:
    text = "the cup to Alice"
    for _ in range(2):  # the second time gated
        assert gate.sub(r"\bgrateful\b", "x", text, flags=re.I) == text
        assert gate.search(r"\bgrateful\b", text, re.I) is None
        assert gate.match(r"grateful", text) is None
        assert gate.fullmatch(r"grateful", text) is None
        assert gate.findall(r"grateful", text) == []
        assert list(gate.finditer(r"grateful", text)) == []
        assert gate.split(r"grateful", text) == [text]
        assert gate.sub(r"\bcup\b", "mug", text) == "the mug to Alice"
        assert gate.split(r"\s+to\s+", text) == ["the cup", "Alice"]


def test_the_lower_case_kept_for_the_last_text_is_that_texts() -> None:
    pattern = r"\bgrateful\b"
    gate.may_match(pattern, re.I, "")  # met once: gated from now on
    loud, plain, other = "I'd be GRATEFUL for the cup", "the cup to Alice", "ſo grateful"
    for _ in range(2):  # texts alternating: each checked as itself, never as the one before
        assert gate.may_match(pattern, re.I, loud)
        assert not gate.may_match(pattern, re.I, plain)
        assert gate.may_match(pattern, re.I, other)  # not ASCII: never gated
        assert not gate.may_match(pattern, re.I, "".join(["the cup ", "to Alice"]))
        assert gate.may_match(pattern, re.I, "".join(["I'd be ", "Grateful"]))


def test_texts_lexed_are_kept_across_instructions_and_dropped_when_many(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    from hltl.grounding import lexicon as lexicon_module

    corpus = load_corpus(ROOT / CORPUS_DIR / "tuning.yaml", ROOT)
    entry = corpus.entries[0]
    lx = Lexicon.of(corpus.scenes[entry.scene])
    first = lexicon_module.lex(entry.text, lx)
    lx.forget()  # a new instruction: the lexed text is kept, and lexed the same
    assert lx.lexed(entry.text) is not None
    assert lexicon_module.lex(entry.text, lx) == first
    assert lexicon_module.lex(entry.text, lx) == list(lexicon_module._lex(entry.text, lx))
    monkeypatch.setattr(lexicon_module, "_LEXED_KEPT", 0)
    lx.forget()  # over the bound: emptied
    assert lx.lexed(entry.text) is None
    assert lexicon_module.lex(entry.text, lx) == first


def test_a_word_holding_another_the_gate_needs_is_not_looked_for_again() -> None:
    pattern = r"\b(?:ok|okay|alright)\b"
    gate.forget(pattern, re.I)
    gate.may_match(pattern, re.I, "")
    assert gate._GATES[re.I][pattern] == (("alright", "ok"), True)
    for text in ("okay for Bob", "OK for Bob", "alright for Bob", "fine for Bob"):
        assert gate.may_match(pattern, re.I, text) == (re.search(pattern, text, re.I) is not None)


def test_compiled_patterns_of_one_text_are_each_gated_with_their_own_flags() -> None:
    blind, cased = re.compile(r"\bMrs (\w+)", re.I), re.compile(r"\bMrs (\w+)")
    for text in ("mrs khan gets the jug", "Mrs Khan gets the jug", "the jug"):
        for _ in range(2):  # met, then gated
            assert bool(gate.search(blind, text)) == bool(blind.search(text))
            assert bool(gate.search(cased, text)) == bool(cased.search(text))
            assert bool(gate.search(r"\bMrs (\w+)", text)) == bool(cased.search(text))
