"""Session 45 (12p): the normaliser's steps indexed by the words they need (stepguard.py). A step
its guard turns away leaves the text as it is, step by step, and a pass run with the guards is the
pass run without them, over the corpus's sentences and random mixes of the guards' words; the list
is what the steps' source says now; a step edited since it was made always runs."""

from __future__ import annotations

import contextlib
import types
from collections.abc import Callable
from functools import cache

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.bench.grounding import CORPUS_DIR, load_corpus
from hltl.errors import GroundingError
from hltl.grounding import _normalise1, gate, normalise, stepguard
from hltl.grounding._normalise1 import _F, _said_any, _sub
from hltl.grounding._step_guards import GUARDS
from hltl.grounding.lexicon import Lexicon
from hltl.world.scene import Scene
from tests.grounding.helpers import ROOT, SCENES

_Step = Callable[[str, Lexicon], str]


@cache
def _sentences() -> tuple[tuple[str, Scene], ...]:
    """Sentences of three tuning parts with their scenes."""
    out: list[tuple[str, Scene]] = []
    for part in ("tuning", "blind42", "blind43"):
        corpus = load_corpus(ROOT / CORPUS_DIR / f"{part}.yaml", ROOT)
        out += [(e.text, corpus.scenes[e.scene]) for e in corpus.entries]
    return tuple(out)


@cache
def _guarded() -> tuple[tuple[_Step, stepguard.Guard], ...]:
    """Every step with a guard in use, and the guard."""
    steps = stepguard.all_steps()
    rules = stepguard.guards(steps, GUARDS)
    return tuple((s, r) for s, r in zip(steps, rules, strict=True) if r is not None)


@cache
def _pieces() -> tuple[str, ...]:
    """The guards' words, their halves and capitals, other words, marks and letters that are
    not ASCII."""
    words = sorted({w for _, (plain, folded, _) in _guarded() for w in (*plain, *folded)})
    pieces = words + [w[: len(w) // 2] for w in words[::3]] + [w.upper() for w in words[::5]]
    pieces += ["the", "cup", "to", "Alice", "Bob", "give", ",", ".", "?", "please", "and"]
    pieces += ["'s", "Mr", " ", "—", "’", "café", "no,", "sorry", "actually", "it"]
    return tuple(pieces)


def _texts() -> st.SearchStrategy[tuple[str, Scene]]:
    """A corpus sentence with its scene, or a mix of the guards' words in a scene."""
    said = st.sampled_from(_sentences())
    mixed = st.tuples(
        st.lists(st.sampled_from(_pieces()), min_size=1, max_size=14).map(" ".join),
        st.sampled_from(SCENES),
    )
    return st.one_of(said, mixed)


def test_most_steps_have_a_guard_in_use() -> None:
    assert len(_guarded()) > 500  # of some 1,200 (the rest always run)


def test_the_list_is_what_the_steps_source_says_now() -> None:
    """Each guard in use is the one read from its step's source today."""
    for step, rule in _guarded():
        entry = stepguard.read_guard(step)
        assert entry is not None and entry[1] == rule, stepguard.key(step)


@settings(max_examples=150, deadline=None)
@given(_texts())
def test_a_step_its_guard_turns_away_leaves_the_text_as_it_is(said: tuple[str, Scene]) -> None:
    text, scene = said
    text = " ".join(text.split())
    lexicon = Lexicon.of(scene)
    low, plain = text.lower(), text.isascii()
    for step, rule in _guarded():
        if stepguard.may_act(rule, text, low, plain):
            continue
        assert step(text, lexicon) == text, stepguard.key(step)


def _pass(run: Callable[[str, Lexicon], str], text: str, lexicon: Lexicon) -> str:
    lexicon.forget()
    lexicon.rewrites.clear()
    try:
        return run(text, lexicon)
    except GroundingError as refused:
        return f"refused: {refused}"


@settings(max_examples=40, deadline=None)
@given(_texts())
def test_a_pass_with_the_guards_is_the_pass_without(said: tuple[str, Scene]) -> None:
    text, scene = said
    lexicon = Lexicon.of(scene)
    with_guards = _pass(normalise.canonical19, text, lexicon)
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(_normalise1, "_guards_of", lambda steps: (None,) * len(steps))
        without = _pass(normalise.canonical19, text, lexicon)
    assert with_guards == without


def test_a_step_turned_away_is_not_called(monkeypatch: pytest.MonkeyPatch) -> None:
    step, rule = next((s, r) for s, r in _guarded() if r[1] == ("stay",))
    called: list[str] = []

    def spy(text: str, lexicon: Lexicon) -> str:
        called.append(text)
        return text

    steps = (spy, step)
    monkeypatch.setitem(_normalise1._GUARDED, id(steps), (steps, (None, rule)))
    lexicon = Lexicon.of(SCENES[0])
    _normalise1._rewritten("t45p", steps, "Give Alice the cup.", lexicon)
    assert called == ["Give Alice the cup."]


# -- the list is used only where it is what the code says ------------------------------------


def test_a_step_edited_since_the_list_was_made_always_runs() -> None:
    step, _ = _guarded()[0]
    entry = GUARDS[stepguard.key(step)]
    assert isinstance(entry, tuple)
    assert stepguard.guard(step, entry) is not None

    def edited(text: str, lexicon: Lexicon) -> str:
        return text

    edited.__module__, edited.__qualname__ = step.__module__, step.__qualname__
    assert stepguard.key(edited) == stepguard.key(step)
    assert stepguard.guard(edited, entry) is None
    assert stepguard.guards((edited,), GUARDS) == (None,)


def test_a_module_name_holding_something_else_drops_the_guard(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    step, entry = next(
        (s, e)
        for s, _ in _guarded()
        if isinstance(e := GUARDS[stepguard.key(s)], tuple)
        and any(d[1][0] == "pattern" for d in e[2])
    )
    name = next(d[0] for d in entry[2] if d[1][0] == "pattern")
    assert stepguard.guard(step, entry) is not None
    monkeypatch.setitem(step.__globals__, name, gate.compile(r"another"))
    assert stepguard.guard(step, entry) is None


def test_no_guard_where_the_gate_derives_words_otherwise() -> None:
    steps = stepguard.all_steps()
    assert stepguard.guards(steps, {**GUARDS, "derivation": "another"}) == (None,) * len(steps)


def test_a_pattern_guard_lets_a_text_that_is_not_ascii_through() -> None:
    assert stepguard.may_act(((), ("cup",), True), "Give Zoë the mug", "give zoë the mug", False)
    assert not stepguard.may_act(
        ((), ("cup",), False), "Give Zoë the mug", "give zoë the mug", False
    )
    assert not stepguard.may_act(((), ("cup",), True), "Give Bob the mug", "give bob the mug", True)


# -- reading a guard -----------------------------------------------------------------------------


def _folded(text: str, lexicon: Lexicon) -> str:
    if "stay" not in text.lower():
        return text
    return text + "!"


def _low_any(text: str, lexicon: Lexicon) -> str:
    low = text.lower()
    if not any(w in low for w in ("wait", "hang on")):
        return text
    return text + "!"


def _matched(text: str, lexicon: Lexicon) -> str:
    m = gate.match(r"\bgive (\w+)", text, _F)
    if m is None:
        return text
    return text + "!"


def _both(text: str, lexicon: Lexicon) -> str:
    if "a" not in text and not _said_any(text, ("bee",)):
        return text
    return text + "!"


def _either(text: str, lexicon: Lexicon) -> str:
    if "cup" not in text or "mug" not in text.lower():
        return text
    return text + "!"


def _subbed(text: str, lexicon: Lexicon) -> str:
    text = _sub(r"\bplease\b", "", text)
    return _sub(r"\bkindly\b", "", text)


def _wrong_way(text: str, lexicon: Lexicon) -> str:
    if "cup" in text:
        return text
    return text + "!"


def _after_other(text: str, lexicon: Lexicon) -> str:
    n = len(text)
    if "cup" not in text or n > 3:
        return text
    return text + "!"


def _none_of_a_bool(text: str, lexicon: Lexicon) -> str:
    if ("cup" in text) is None:  # never None: not a guard
        return text
    return text + "!"


def _wordless(text: str, lexicon: Lexicon) -> str:
    if not gate.search(r"\w*", text):
        return text
    return text + "!"


def _of_the_scene(text: str, lexicon: Lexicon) -> str:
    if "cup" not in lexicon.scene.name:
        return text
    return text + "!"


@pytest.mark.parametrize(
    ("step", "want"),
    [
        (_folded, ((), ("stay",), False)),
        (_low_any, ((), ("hang on", "wait"), False)),
        (_matched, ((), ("give ",), True)),
        (_both, (("a",), ("bee",), False)),
        (_either, (("cup",), (), False)),
        (_subbed, ((), ("kindly", "please"), True)),
        (_wrong_way, None),
        (_after_other, None),
        (_none_of_a_bool, None),
        (_wordless, None),
        (_of_the_scene, None),
        (lambda text, lexicon: text, None),
    ],
)
def test_a_guard_is_read_only_from_a_step_that_returns_the_text_without_its_words(
    step: _Step, want: stepguard.Guard | None
) -> None:
    entry = stepguard.read_guard(step)
    assert (entry and entry[1]) == want
    if entry is not None:  # and it is used, and turns away only what the step leaves alone
        assert stepguard.guard(step, entry) == want
        for text in ("Give Alice the cup", "wait, the mug", "Please stay", "a bee", "x"):
            if not stepguard.may_act(entry[1], text, text.lower(), text.isascii()):
                assert step(text, Lexicon.of(SCENES[0])) == text


def test_a_closure_has_no_guard() -> None:
    word = "cup"

    def inner(text: str, lexicon: Lexicon) -> str:
        if word not in text:
            return text
        return text + "!"

    assert stepguard.read_guard(inner) is None
    assert stepguard.read_guard(types.SimpleNamespace()) is None  # type: ignore[arg-type]


def test_a_fingerprint_is_the_same_for_the_same_code_and_differs_for_other_code() -> None:
    assert stepguard.fingerprint(_folded) == stepguard.fingerprint(_folded)
    assert stepguard.fingerprint(_folded) != stepguard.fingerprint(_low_any)
    with contextlib.suppress(AttributeError):
        stepguard._PRINTS.clear()
    assert stepguard.fingerprint(_folded) == stepguard.fingerprint(_folded)
