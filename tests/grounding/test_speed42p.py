"""Session 42 (12p): work a cold refusal no longer does gives what the work it replaces gave."""

from __future__ import annotations

import re

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.bench.grounding import CORPUS_DIR, PARTS, load_corpus
from hltl.grounding import _normalise1, gate
from hltl.grounding.lexicon import Lexicon
from tests.grounding.helpers import ROOT


@pytest.fixture
def code_generated(monkeypatch: pytest.MonkeyPatch) -> list[str]:
    """The patterns re's code generator is run on (each compile of a parsed pattern)."""
    made: list[str] = []
    real = gate._compiler._code

    def counted(parsed: object, flags: int) -> object:
        made.append(str(parsed.state.str))  # type: ignore[attr-defined]
        return real(parsed, flags)

    monkeypatch.setattr(gate._compiler, "_code", counted)
    return made


def test_a_pattern_the_gate_turns_away_is_never_compiled(code_generated: list[str]) -> None:
    pattern = r"\bturned (?:away|back) by (\w+)\b"
    for text in ("the cup to Alice", "Give Bob the bowl, please.", "NOTHING TURNED"):
        assert gate.sub(pattern, r"\1", text, flags=re.I) == text
        assert gate.search(pattern, text, re.I) is None
        assert _normalise1._sub(pattern, r"\1", text) == text
    assert code_generated == []
    # first run: compiled once, from the parse the gate kept, and run as re runs it
    said = "It was turned away by Bob, then TURNED BACK BY Alice"
    assert gate.sub(pattern, r"\1", said, flags=re.I) == "It was Bob, then Alice"
    assert gate.findall(pattern, said, re.I) == ["Bob", "Alice"]
    assert len(code_generated) == 1


def test_a_pattern_compiled_after_other_patterns_were_gated_is_the_one_re_compiles() -> None:
    # the kept parse is not spent by gating (deriving the words) or by other patterns' compiles
    patterns = [rf"\b(?P<who>alice|bob) (?:gets|wants) (?:the )?(\w+){k}\b" for k in range(4)]
    for pattern in patterns:
        gate._GATES.pop((pattern, re.I), None)
        gate._BUILT.pop((pattern, re.I), None)
        assert not gate.may_match(pattern, re.I, "the cup to Carol")
    for pattern in reversed(patterns):
        ours, theirs = gate.compiled(pattern, re.I), re.compile(pattern, re.I)
        assert ours == theirs and ours.groupindex == theirs.groupindex
        assert (pattern, re.I) not in gate._BUILT  # handed over: the caller keeps it


_PIECES = ["the", "Cup", r"\b", r"\s+", r"(\w+)", "(?:mug|bowl)", "[a-z]", "s?", "$"]


@settings(max_examples=200, deadline=None)
@given(
    st.lists(st.sampled_from(_PIECES), min_size=1, max_size=6).map("".join),
    st.sampled_from(["", "the cup", "THE MUG s", "a bowl", "mugs cups"]),
)
def test_a_gated_sub_gives_what_re_gives_whenever_it_compiles(pattern: str, text: str) -> None:
    gate._GATES.pop((pattern, re.I), None)
    gate._BUILT.pop((pattern, re.I), None)
    for said in ("no words here", text):  # turned away (or not), then run
        try:
            want = re.sub(pattern, "<\\g<0>>", said, flags=re.I)
        except re.error:
            with pytest.raises(re.error):
                gate.sub(pattern, "<\\g<0>>", said, flags=re.I)
            continue
        assert gate.sub(pattern, "<\\g<0>>", said, flags=re.I) == want


def _scenes() -> list[Lexicon]:
    lexicons: dict[int, Lexicon] = {}
    for part in PARTS:
        if part == "blind41":
            continue
        corpus = load_corpus(ROOT / CORPUS_DIR / f"{part}.yaml", ROOT)
        for scene in corpus.scenes.values():
            lexicon = Lexicon.of(scene)
            lexicons[id(lexicon)] = lexicon
    return list(lexicons.values())


def test_the_known_words_are_built_once_per_lexicon_as_they_were_at_every_call() -> None:
    lexicons = _scenes()
    assert len(lexicons) > 20
    for lexicon in lexicons:
        kept = _normalise1._known_words(lexicon)
        assert kept is _normalise1._known_words(lexicon)  # built once
        assert kept == _normalise1._known_words.__wrapped__(lexicon)  # what a call built
    # what _plain_words answers with the kept words is what it answered
    lexicon = lexicons[0]
    names = " ".join(o.id for o in lexicon.scene.objects)
    for clause in ("the weather is lovely", f"he likes {names}", "zyzzyva qwertyuiop", ""):
        known = _normalise1._known_words.__wrapped__(lexicon)
        words = re.findall(r"[a-z]+", re.sub(r"'(?:s|ll|re|d|ve|m)\b|n't\b", " ", clause.lower()))
        assert _normalise1._plain_words(clause, lexicon) == all(w in known for w in words)
