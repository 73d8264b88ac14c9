"""Session 53 (12p): always-run steps that asked compiled patterns raw ask them through the gate,
and _cue_typo43r's one-edit test is kept per word — each step answers as it did, on every text:
over corpus sentences and sentences each step rewrites, with the gate and without it."""

from __future__ import annotations

from collections.abc import Callable
from functools import cache

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.bench.grounding import CORPUS_DIR, load_corpus
from hltl.errors import GroundingError
from hltl.grounding import (
    _normalise1,
    _normalise2,
    _normalise3,
    _rewrites38s,
    _rewrites39s,
    _rewrites41,
    _rewrites42,
    _rewrites43r,
    _rewrites44,
    _rewrites47,
    gate,
)
from hltl.grounding.lexicon import VERBS, WORDS, Lexicon, _one_edit
from hltl.world.scene import Scene
from tests.grounding.helpers import CELL, ROOT, WORKSHOP

_Step = Callable[[str, Lexicon], str]

# the steps whose raw pattern calls now go through the gate
_STEPS: tuple[_Step, ...] = (
    _normalise3._idioms27r,
    _normalise3._remarks28r,
    _normalise2._idioms32,
    _normalise2._idioms33,
    _normalise2._idioms34,
    _rewrites41._courtesy41,
    _rewrites42._courtesy42,
    _rewrites42._ask_forms42,
    _rewrites44._courtesy44,
    _rewrites44._ask_forms44,
    _rewrites47._asked47,
    _rewrites43r._cue_typo43r,
    _rewrites38s._about_them38s,  # _CUE_ANY38S
    _rewrites39s._remark39s,  # _CUE_ANY38S (_people39s, _closed39s)
    _normalise1._possessed,
)

# sentences each of which one of the steps rewrites (from their sessions' tests and docs)
_REWRITTEN = (
    "could you see the bottle gets to Person A?",
    "Give Alice the apple, since first light she's wanted it.",
    "Would you mind ever so much handing Bob the crisps?",
    "Could I trouble you to see that Bob gets the bottle?",
    "Is it too much bother to get Alice the apple?",
    "Give Bob the cup, no, the apple actulaly.",
    "Give Bob the cup, insted the apple.",
    "Bob keeps asking for the apple.",
    "Person B is asking where the chips have got to.",
    "The bottle would help Person A a lot.",
    "Both cups to Alice, the poor thing's shivering.",
)


@cache
def _sentences() -> tuple[tuple[str, Scene], ...]:
    out: list[tuple[str, Scene]] = []
    for part in ("tuning", "blind22", "causes15", "blind45"):
        corpus = load_corpus(ROOT / CORPUS_DIR / f"{part}.yaml", ROOT)
        out += [(e.text, corpus.scenes[e.scene]) for e in corpus.entries[::2]]
    out += [(t, CELL) for t in _REWRITTEN] + [(t, WORKSHOP) for t in _REWRITTEN]
    return tuple(out)


def _answer(step: _Step, text: str, scene: Scene) -> str:
    try:
        return step(text, Lexicon.of(scene))
    except GroundingError as refused:
        return f"refused: {refused}"


@pytest.mark.parametrize("step", _STEPS, ids=lambda s: s.__name__)
def test_the_step_answers_as_without_the_gate(step: _Step, monkeypatch: pytest.MonkeyPatch) -> None:
    gated = [_answer(step, t, s) for t, s in _sentences()]
    monkeypatch.setattr(gate, "may_match", lambda pattern, flags, text: True)  # every call raw
    raw = [_answer(step, t, s) for t, s in _sentences()]
    assert gated == raw


def test_the_steps_rewrite_some_sentences() -> None:
    """Not vacuous: the sentences above are rewritten by the steps asked."""
    changed = {
        step.__name__
        for step in _STEPS
        for text, scene in _sentences()
        if _answer(step, text, scene) != text
    }
    assert len(changed) >= 6, changed


@pytest.mark.parametrize(
    "word",
    [
        *("actulaly", "acually", "actualy", "insted", "isntead", "instaed", "actually"),
        *("instead", "factually", "actual", "magazine", "blanket", "ACTULALY", "Insted"),
        "instant",
    ],
)
def test_cue_of_typo_is_the_loop_it_keeps(word: str) -> None:
    low = word.lower()
    want = None
    if low not in _rewrites43r._NOT_CUE_TYPOS43R:
        want = next((c for c in _rewrites43r._CUE_WORDS43R if _one_edit(low, c)), None)
    assert _rewrites43r._cue_of_typo43r(low) == want


def _tidy_as_it_was(text: str) -> str:
    """_tidy19 of session 52 (every rewrite asked)."""
    out = gate.sub(r"([.!?])[.!?,;:]+", r"\1", text)
    out = gate.sub(r"\s+([,;:.!?])", r"\1", out)
    out = gate.sub(r"([,;:])\s*([,;:.!?])", r"\2", out)
    out = gate.sub(r"^[\s,;:.!]+", "", out)
    out = gate.sub(r"\s{2,}", " ", out).strip()
    return gate.sub(r"[,;:]$", "", out).strip()


@settings(max_examples=600, deadline=None)
@given(
    st.lists(
        st.sampled_from(["the", "cup", "Bob", " ", "  ", ",", ".", "!", "?", ";", ":", "\n"])
        | st.sampled_from(["\t", "\u00a0", "\u2003", "...", ", ", ". ", "a"]),
        max_size=10,
    ).map("".join)
)
def test_tidy19_answers_as_it_did(text: str) -> None:
    assert _normalise1._tidy19(text) == _tidy_as_it_was(text)


@pytest.mark.parametrize("text", [t for t, _ in _sentences()[::7]])
def test_tidy19_answers_as_it_did_on_corpus_sentences(text: str) -> None:
    assert _normalise1._tidy19(text) == _tidy_as_it_was(text)


def _heads_as_it_was(text: str, lexicon: Lexicon) -> str:
    """_heads of session 52 (the scene's names worked out for each text)."""
    scene = lexicon.scene
    names = [
        *((o.id, n) for o in scene.objects for n in (o.id, o.category, *o.aliases)),
        *((h.id, n) for h in scene.humans for n in (h.id, h.name, *h.aliases)),
        *((x.id, n) for x in scene.surfaces for n in (x.id, *x.aliases)),
    ]
    said = [(i, n.lower().replace("_", " ").split()) for i, n in names]
    people = {h.id for h in scene.humans}
    for oid, name in names:
        words = name.lower().split()
        if len(words) < 2 or name == oid or oid in people:
            continue
        head = words[-1]
        owners = {i for i, ws in said if head in ws}
        alone = any(ws == [head] for _, ws in said)
        if owners != {oid} or alone or head in WORDS or head in VERBS:
            continue
        text = gate.sub(
            rf"(?<!{gate.escape(words[-2])} )\b{gate.escape(head)}\b",
            name,
            text,
            flags=gate.IGNORECASE,
        )
    return text


def test_heads_answer_as_they_did() -> None:
    changed = 0
    said_by_head = [
        (f"Put the {name.split()[-1]} on the shelf, and the {name.split()[-1]}s too.", scene)
        for scene in {id(s): s for _, s in _sentences()}.values()
        for _, name in _normalise1._heads_of(scene)
    ]
    assert said_by_head  # some scene names a thing by more than one word
    for text, scene in [*_sentences(), *said_by_head]:
        for said in (text, text.replace("the ", "the old ")):
            want = _heads_as_it_was(said, Lexicon.of(scene))
            assert _normalise1._heads(said, Lexicon.of(scene)) == want
            changed += want != said
    assert changed > 0  # some text says a name by its head


def _objects_said_as_it_was(text: str, lexicon: Lexicon) -> str:
    """_objects_said34t of session 52 (the request read first)."""
    m = _normalise1._rx(
        r"(?<=[.!?])\s+(?:(?:sorry|i mean|that is|so|yes|yeah)\s*,?\s+)?(?P<objs>(?:the )?[a-z]+"
        r"(?:(?:,\s*| and )(?:the )?[a-z]+)*)\s*[.!]?$"
    ).search(text)
    if m is None:
        return text
    before = text[: m.start()]
    said = _normalise1._tasks_of(before, lexicon)
    objs = gate.split(r",\s*| and ", m["objs"], flags=gate.IGNORECASE)
    named: set[str] = set()
    for o in objs:
        if not _normalise1._only_kind(o, lexicon, "object"):
            return text
        named |= _normalise1._ids(o, lexicon, "object")
    if not said or named != {obj for _, obj, _ in said} or len(named) != len(objs):
        return text
    return before


_SAID_AGAIN = (
    "Give Bob the cup. Sorry, the cup.",
    "Give Alice the apple and Bob the crisps. I mean the apple and the crisps.",
    "Put the apple on the shelf. The apple.",
    "Give Bob the cup. Sorry, the apple.",
    "Give Bob the cup. The cup and the cup.",
    "Give Bob the cup. Bob.",
    "Give Bob the cup and the apple. The cup.",
    "Hand Alice the bottle. Thanks.",
)


def test_objects_said_answers_as_it_did() -> None:
    changed = 0
    texts = [*_sentences(), *((t, CELL) for t in _SAID_AGAIN)]
    for text, scene in texts:
        want = _objects_said_as_it_was(text, Lexicon.of(scene))
        assert _normalise3._objects_said34t(text, Lexicon.of(scene)) == want, text
        changed += want != text
    assert changed > 0
