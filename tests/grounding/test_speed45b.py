"""Session 45 (12b): eleven more phrasing passes run only where an item they need is said
(phrasing._only_with, as the eight of session 44). A gate must hold of some item wherever its pass
would change the items or refuse: where no item passes it, the pass gives the items back as they
are. test_speed44b's last test compares every gated pass with the pass itself at every refine step
of four tuning parts; these tests add that the new gates do let the passes' changes through, and
that on random item sequences without a gate's item the pass itself changes nothing."""

from __future__ import annotations

import inspect
from collections.abc import Callable

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.bench.grounding import CORPUS_DIR, load_corpus
from hltl.errors import GroundingError
from hltl.grounding import phrasing
from hltl.grounding.lexicon import Item, Lexicon, lex
from hltl.world.scene import load_scene
from tests.grounding.helpers import ROOT

_NEW = {
    "_choice_restated",
    "_notes",
    "_wanted_done",
    "_wanted_on",
    "_then_inside",
    "_wished_for",
    "_superlatives",
    "_rest",
    "_any_restated",
    "_appositions",
    "_nobody",
}
_Pass = Callable[[list[Item], Lexicon], list[Item]]


def _name(step: _Pass) -> str:
    """The name of the pass a gate (and _plain) wraps."""
    inner = getattr(step, "__wrapped__", step)
    if inner.__name__ == "<lambda>":  # _plain(pass)
        inner = inspect.getclosurevars(inner).nonlocals["step"]
    return inner.__name__


def _gates() -> dict[str, tuple[_Pass, _Pass, Callable[[Item], bool]]]:
    """Each new gated pass by name: (the gated step, the pass itself, the gate)."""
    out = {}
    for step in phrasing._PASSES:
        if hasattr(step, "__wrapped__") and _name(step) in _NEW:
            needs = step.__dict__.get("needs") or inspect.getclosurevars(step).nonlocals["needs"]
            out[_name(step)] = (step, step.__wrapped__, needs)  # type: ignore[attr-defined]
    return out


_GATES = _gates()


def _run(step: _Pass, items: list[Item], lexicon: Lexicon) -> object:
    try:
        return step(list(items), lexicon)
    except GroundingError as exc:
        return f"refused: {exc}"


def test_the_eleven_passes_are_gated() -> None:
    assert set(_GATES) == _NEW


def test_each_gate_lets_its_pass_change_the_items_on_the_corpus() -> None:
    """At every refine step of three tuning parts' sentences: each new gated pass gives what the
    pass gives, and each pass does change (or refuse) some sentence there, through its gate."""
    changed: set[str] = set()
    for part in ("tuning", "blind22", "blind37"):
        corpus = load_corpus(ROOT / CORPUS_DIR / f"{part}.yaml", ROOT)
        for e in corpus.entries:
            lexicon = Lexicon.of(corpus.scenes[e.scene])
            try:
                items = lex(e.text, lexicon)
            except GroundingError:
                continue
            for step in phrasing._PASSES:
                name = _name(step)
                plain = getattr(step, "__wrapped__", step)
                got = _run(plain, items, lexicon)
                if name in _GATES:
                    assert _run(step, items, lexicon) == got, (e.text, name)
                    if got != items:
                        changed.add(name)
                if isinstance(got, str):
                    break
                items = got  # type: ignore[assignment]
    # the others change no sentence of these parts as lexed (below: sentences they change)
    assert changed >= {"_appositions", "_choice_restated", "_notes", "_nobody", "_wished_for"}


_CHANGED = [
    ("_rest", "cell", "Give Alice the chips and Bob the rest"),
    ("_rest", "cell", "Give Carol the apple and Bob everything else"),
    ("_then_inside", "cell", "Give Alice the apple. Bob should then get the chips."),
    ("_superlatives", "cell", "Give Bob the nearest mug to him"),
    ("_superlatives", "cell", "Give Bob whichever mug is nearest to him"),
    ("_wanted_on", "ward", "Ruth wants the blue blanket on the bedside table"),
    ("_wanted_done", "ward", "Ruth wants the thermometer and the tablets put on the cart"),
    ("_any_restated", "cell", "Alice needs a mug, any mug"),
    ("_any_restated", "cell", "Give Alice a mug, any of them"),
    ("_choice_restated", "cell", "Put a mug on the shelf, any mug"),
    ("_notes", "cell", "for Carol the apple, for Bob the bottle"),
    ("_wished_for", "cell", "Give Bob the chips he asked for"),
    ("_appositions", "lab", "Give Emma the cup, the green cup"),
    ("_nobody", "cell", "Carol gets nothing, Bob gets the apple"),
]
_SCENES = {
    "cell": "examples/scenes/grounding_cell.yaml",
    "ward": "tests/grounding/paraphrase/scenes/ward.yaml",
    "lab": "tests/grounding/paraphrase/scenes/lab.yaml",
}


@pytest.mark.parametrize(("name", "scene", "text"), _CHANGED)
def test_each_gate_lets_through_a_sentence_its_pass_changes(
    name: str, scene: str, text: str
) -> None:
    step, plain, _needs = _GATES[name]
    lexicon = Lexicon.of(load_scene(ROOT / _SCENES[scene]))
    items = lex(text, lexicon)
    got = _run(plain, items, lexicon)
    assert got != items
    assert _run(step, items, lexicon) == got


def _pool() -> tuple[list[Item], Lexicon]:
    """Items of sentences that say each gate's word, lexed in the cell scene."""
    lexicon = Lexicon.of(load_scene(ROOT / _SCENES["cell"]))
    texts = [
        "Give Alice the chips and Bob the rest, the red mug or either mug.",
        "Bob gets nothing, nobody gets the apple, not Carol, not anything else.",
        "Carol wants the cup and the apple put on the shelf, then give her the mug she asked for.",
        "Give Bob a mug, any mug, whichever one Alice doesn't get, the one nearest to him.",
        "Everything else to Carol, for Bob the bottle, the other two on the table.",
    ]
    pool: list[Item] = []
    for text in texts:
        for it in lex(text, lexicon):
            if it not in pool:
                pool.append(it)
    return pool, lexicon


_POOL, _CELL = _pool()


@settings(max_examples=300, deadline=None)
@given(st.lists(st.sampled_from(_POOL), max_size=14), st.sampled_from(sorted(_NEW)))
def test_without_a_gates_item_the_pass_changes_nothing(items: list[Item], name: str) -> None:
    _step, plain, needs = _GATES[name]
    if any(needs(it) for it in items):
        return
    assert _run(plain, items, _CELL) == items
