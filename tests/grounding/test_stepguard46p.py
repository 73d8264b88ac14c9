"""Session 46 (12p): stepguard reads loops — over a search's matches (``for m in P.finditer(text)``,
in ``reversed``/``list``/``[::-1]``) and over a module's tuple of patterns or (pattern,
replacement) pairs substituted in the text (``_sub``, ``_drop``). A step read so is turned away
only where it leaves the text as it is (hypothesis over corpus sentences and mixes of its words);
a loop of another shape has no guard; a module tuple changed since the list was made drops it."""

from __future__ import annotations

from collections.abc import Callable
from functools import cache

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.bench.grounding import CORPUS_DIR, load_corpus
from hltl.grounding import _normalise1, gate, stepguard
from hltl.grounding._normalise1 import _drop, _sub
from hltl.grounding._step_guards import GUARDS
from hltl.grounding.lexicon import Lexicon
from hltl.world.scene import Scene
from tests.grounding.helpers import ROOT, SCENES

_Step = Callable[[str, Lexicon], str]


def _without_loops(step: _Step) -> stepguard.Entry | None:
    """``step``'s entry as the session-45 reader read it (no loops)."""

    def refuse(self: object, stmt: object) -> frozenset[stepguard.Atom]:
        raise stepguard._Unread("loop")

    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(stepguard._Reader, "_loop", refuse)
        return stepguard.read_guard(step)


@cache
def _loop_read() -> tuple[tuple[_Step, stepguard.Guard], ...]:
    """The steps whose guard in use is read through a loop."""
    steps = stepguard.all_steps()
    rules = stepguard.guards(steps, GUARDS)
    return tuple(
        (s, r)
        for s, r in zip(steps, rules, strict=True)
        if r is not None and _without_loops(s) is None
    )


@cache
def _sentences() -> tuple[tuple[str, Scene], ...]:
    out: list[tuple[str, Scene]] = []
    for part in ("tuning", "blind42", "blind44"):
        corpus = load_corpus(ROOT / CORPUS_DIR / f"{part}.yaml", ROOT)
        out += [(e.text, corpus.scenes[e.scene]) for e in corpus.entries]
    return tuple(out)


@cache
def _pieces() -> tuple[str, ...]:
    words = sorted({w for _, (plain, folded, _) in _loop_read() for w in (*plain, *folded)})
    pieces = words + [w[: len(w) // 2] for w in words[::3]] + [w.upper() for w in words[::4]]
    pieces += ["the", "cup", "to", "Alice", "Bob", "give", ",", ".", "please", "no,", "sorry"]
    pieces += ["actually", "it", "Chips to A", "correction", "—", "’", "café", "wait", "i mean"]
    return tuple(pieces)


def _texts() -> st.SearchStrategy[tuple[str, Scene]]:
    mixed = st.tuples(
        st.lists(st.sampled_from(_pieces()), min_size=1, max_size=14).map(" ".join),
        st.sampled_from(SCENES),
    )
    return st.one_of(st.sampled_from(_sentences()), mixed)


def test_the_loop_reader_guards_steps_it_did_not() -> None:
    names = {stepguard.key(s).split(":")[1] for s, _ in _loop_read()}
    assert {"_restated20", "_wrappers", "_reasons28"} <= names
    assert len(names) >= 10


@settings(max_examples=300, deadline=None)
@given(_texts())
def test_a_step_read_through_a_loop_turned_away_leaves_the_text_as_it_is(
    said: tuple[str, Scene],
) -> None:
    text, scene = said
    text = " ".join(text.split())
    lexicon = Lexicon.of(scene)
    low, plain = text.lower(), text.isascii()
    for step, rule in _loop_read():
        if not stepguard.may_act(rule, text, low, plain):
            assert step(text, lexicon) == text, stepguard.key(step)


# -- small steps: the shapes read and those refused ----------------------------------------------

_CUE46P = gate.compile(r"\b(?:sorry|actually),?\s+", gate.IGNORECASE)
_PAIRS46P = ((r"\bkindly\b", ""), (r"\bpretty please\b", "please"))
_STRINGS46P = (r"\bmate\b", r"\bduck\b")
_WORDLESS46P = ((r"\bkindly\b", ""), (r"\d+", ""))
_COMPILED46P = ((gate.compile(r"\bkindly\b"), ""),)


def _matches_reversed(text: str, lexicon: Lexicon) -> str:
    for m in reversed(list(_CUE46P.finditer(text))):
        return text[: m.start()] + text[m.end() :]
    return text


def _findall_backwards(text: str, lexicon: Lexicon) -> str:
    for said in gate.findall(r"\bcup\b", text)[::-1]:
        text = text + said
    return text


def _pairs(text: str, lexicon: Lexicon) -> str:
    for pattern, repl in _PAIRS46P:
        text = _sub(pattern, repl, text)
    return text


def _strings_dropped(text: str, lexicon: Lexicon) -> str:
    for pattern in _STRINGS46P:
        text = _drop(pattern, text, lexicon)
    if "cup" not in text:
        return text
    return text + "!"


def _loop_then_sub(text: str, lexicon: Lexicon) -> str:
    for m in _CUE46P.finditer(text):
        text = text.replace(m[0], "")
    text = _sub(r"\bplease\b", "", text)
    return text


def _over_words(text: str, lexicon: Lexicon) -> str:
    for word in text.split():
        text = text + word
    return text


def _lowered_body(text: str, lexicon: Lexicon) -> str:
    for pattern, repl in _PAIRS46P:
        text = _sub(pattern, repl, text.lower())
    return text


def _other_pattern(text: str, lexicon: Lexicon) -> str:
    for _pattern, repl in _PAIRS46P:
        text = _sub(r"\w", repl, text)
    return text


def _with_else(text: str, lexicon: Lexicon) -> str:
    for m in _CUE46P.finditer(text):
        text = text + m[0]
    else:
        text = text + "!"
    return text


def _wordless_pair(text: str, lexicon: Lexicon) -> str:
    for pattern, repl in _WORDLESS46P:
        text = _sub(pattern, repl, text)
    return text


def _compiled_pairs(text: str, lexicon: Lexicon) -> str:
    for pattern, repl in _COMPILED46P:
        text = pattern.sub(repl, text)
    return text


def _two_statements(text: str, lexicon: Lexicon) -> str:
    for pattern, repl in _PAIRS46P:
        text = _sub(pattern, repl, text)
        text = text + "!"
    return text


@pytest.mark.parametrize(
    ("step", "want"),
    [
        (_matches_reversed, ((), ("actually", "sorry"), True)),
        (_findall_backwards, (("cup",), (), True)),
        (_pairs, ((), ("kindly", "pretty please"), True)),
        (_strings_dropped, (("cup",), ("duck", "mate"), True)),
        (_loop_then_sub, ((), ("actually", "please", "sorry"), True)),
        (_over_words, None),
        (_lowered_body, None),
        (_other_pattern, None),
        (_with_else, None),
        (_wordless_pair, None),
        (_compiled_pairs, None),
        (_two_statements, None),
    ],
)
def test_a_loop_is_read_only_where_it_does_nothing_without_its_words(
    step: _Step, want: stepguard.Guard | None
) -> None:
    entry = stepguard.read_guard(step)
    assert (entry and entry[1]) == want
    if entry is not None:
        assert stepguard.guard(step, entry) == want
        lexicon = Lexicon.of(SCENES[0])
        for text in ("Give Alice the cup", "sorry, the mug", "kindly pass it", "x", "mate"):
            if not stepguard.may_act(entry[1], text, text.lower(), text.isascii()):
                assert step(text, lexicon) == text


def test_a_module_tuple_changed_since_the_list_was_made_drops_the_guard(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    entry = stepguard.read_guard(_pairs)
    assert entry is not None and stepguard.guard(_pairs, entry) is not None
    monkeypatch.setitem(_pairs.__globals__, "_PAIRS46P", ((r"\bkindly\b", ""),))
    assert stepguard.guard(_pairs, entry) is None
    monkeypatch.setitem(_pairs.__globals__, "_PAIRS46P", (r"\bkindly\b", r"\bpretty please\b"))
    assert stepguard.guard(_pairs, entry) is None
    # the replacements are not kept: a new replacement keeps the guard (it acts only on a match)
    monkeypatch.setitem(
        _pairs.__globals__, "_PAIRS46P", ((r"\bkindly\b", "x"), (r"\bpretty please\b", "y"))
    )
    assert stepguard.guard(_pairs, entry) is not None


def test_a_real_loop_step_is_not_called_without_its_words() -> None:
    step = _normalise1._restated20
    rule = stepguard.guard(step, GUARDS[stepguard.key(step)])  # type: ignore[arg-type]
    assert rule is not None
    text = "Give Alice the cup and Bob the mug."
    assert not stepguard.may_act(rule, text, text.lower(), text.isascii())
    text = "Chips to A. Correction, chips to B."
    assert stepguard.may_act(rule, text, text.lower(), text.isascii())
