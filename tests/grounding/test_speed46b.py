"""Session 46 (12b): twenty-three more phrasing passes run only where a lemma or a text they need
is said, and every gate that asked `_is` of each item is now two set look-ups (phrasing._said on
phrasing._present: the lemmas and texts of the items, kept while the items stay the same). A gate
must hold wherever its pass would change the items or refuse: where it does not, the pass gives
the items back as they are. test_speed44b's last test compares every gated pass with the pass
itself at every refine step of four tuning parts; these tests add that the new gates let their
passes' changes through, that on random item sequences without a gate's word the pass itself
changes nothing, and that _present gives the sets of the items it is asked about."""

from __future__ import annotations

import inspect
from collections.abc import Callable

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.errors import GroundingError
from hltl.grounding import phrasing
from hltl.grounding.lexicon import Item, Lexicon, lex
from hltl.world.scene import load_scene
from tests.grounding.helpers import ROOT

_Pass = Callable[[list[Item], Lexicon], list[Item]]

# each new gated pass, with a sentence it changes (or refuses) at its place in refine, or as lexed
_CHANGED = [
    ("_any_order", "cell", "Give Bob the chips and Alice the cup, in either order"),
    ("_closing_also", "cell", "Alice wants the apple also"),
    ("_for_me_alone", "classroom", "Give Noah the glue, and the globe for me"),
    ("_floating_all", "cell", "The cup, the bottle and the chips all go on the shelf"),
    ("_listed_subjects", "cell", "The cup, the bottle and the chips go on the shelf"),
    ("_do_whose", "cell", "Do Carol's bottle first and then Bob's chips"),
    ("_hedges", "cell", "Maybe give Carol the chips?"),
    ("_do_for", "cell", "Do the cup for Alice first"),
    ("_places_named", "cell", "Give Carol the mug nearest to Bob"),
    ("_whichever_nearer", "cell", "Bring Alice a mug, whichever one's closer to her"),
    ("_relatives", "cell", "Give Bob the mug that is red"),
    ("_never_mind", "cell", "Hand Bob the apple. Never mind, give it to Carol instead."),
    ("_i_mean_after", "cell", "Give Carol the red mug, er, the blue one I mean"),
    ("_instead_of", "cell", "Give Carol the apple instead of the cup"),
    ("_respectively", "cell", "Give Alice and Bob the cup and the apple respectively"),
    ("_said_after", "cell", "give the apple to carol she said she wants it"),
    ("_has_taken", "cell", "Once Bob has taken the cup, give Alice the apple"),
    ("_not_wanted", "cell", "Alice doesn't want the cup, she wants the apple"),
    ("_not_after", "cell", "Give Carol the chips, but don't give her the apple"),
    ("_each_nearest", "cell", "Give Alice and Bob the mug closest to them"),
    ("_ordinals", "cell", "Give Carol the apple second and Alice the cup first"),
    ("_last", "cell", "Give Alice the bottle last; first give Bob the chips"),
    ("_datives", "cell", "Alice: the cup"),
]
_NEW = {name for name, _scene, _text in _CHANGED}
_SCENES = {
    "cell": "examples/scenes/grounding_cell.yaml",
    "classroom": "tests/grounding/paraphrase/scenes/classroom.yaml",
}


def _name(step: _Pass) -> str:
    """The name of the pass a gate (and _plain) wraps."""
    inner = getattr(step, "__wrapped__", step)
    if inner.__name__ == "<lambda>":  # _plain(pass)
        inner = inspect.getclosurevars(inner).nonlocals["step"]
    return inner.__name__


def _needs(step: _Pass) -> Callable[[Item], bool]:
    """A gate as an item test: _said keeps it as ``needs``; _only_with closes over it."""
    found = step.__dict__.get("needs")
    return found if found is not None else inspect.getclosurevars(step).nonlocals["needs"]


def _gates() -> dict[str, tuple[_Pass, _Pass, Callable[[Item], bool]]]:
    """Each new gated pass by name: (the gated step, the pass itself, the gate)."""
    out = {}
    for step in phrasing._PASSES:
        if hasattr(step, "__wrapped__") and _name(step) in _NEW:
            out[_name(step)] = (step, step.__wrapped__, _needs(step))  # type: ignore[attr-defined]
    return out


_GATES = _gates()


def _run(step: _Pass, items: list[Item], lexicon: Lexicon) -> object:
    try:
        return step(list(items), lexicon)
    except GroundingError as exc:
        return f"refused: {exc}"


def test_the_new_passes_are_gated() -> None:
    assert set(_GATES) == _NEW
    # every gate of _PASSES that asked `_is` of an item (or a text) is a set look-up now
    said = [s for s in phrasing._PASSES if "needs" in getattr(s, "__dict__", {})]
    # (37 and 42 in session 46; session 47 gates more: test_speed47b)
    assert len(said) >= 37 and len([s for s in phrasing._PASSES if hasattr(s, "__wrapped__")]) >= 42


@pytest.mark.parametrize(("name", "scene", "text"), _CHANGED)
def test_each_gate_lets_through_a_sentence_its_pass_changes(
    name: str, scene: str, text: str
) -> None:
    step, plain, _gate = _GATES[name]
    lexicon = Lexicon.of(load_scene(ROOT / _SCENES[scene]))
    lexed = lex(text, lexicon)
    items = lexed
    for before in phrasing._PASSES:  # the items as refine gives them to the pass
        if before is step:
            break
        items = before(items, lexicon)
    changed = False
    for said in (items, lexed):
        got = _run(plain, said, lexicon)
        assert _run(step, said, lexicon) == got
        changed = changed or got != said
    assert changed


def _pool() -> tuple[list[Item], Lexicon]:
    """Items of sentences that say each gate's words, lexed in the cell scene."""
    lexicon = Lexicon.of(load_scene(ROOT / _SCENES["cell"]))
    pool: list[Item] = []
    for _, scene, text in _CHANGED:
        if scene != "cell":
            continue
        for it in lex(text, lexicon):
            if it not in pool:
                pool.append(it)
    return pool, lexicon


_POOL, _CELL = _pool()


@settings(max_examples=400, deadline=None)
@given(st.lists(st.sampled_from(_POOL), max_size=14), st.sampled_from(sorted(_NEW)))
def test_without_a_gates_word_the_pass_changes_nothing(items: list[Item], name: str) -> None:
    step, plain, needs = _GATES[name]
    if any(needs(it) for it in items):
        return
    assert step(items, _CELL) is items
    assert _run(plain, items, _CELL) == items


@settings(max_examples=200, deadline=None)
@given(st.lists(st.lists(st.sampled_from(_POOL), max_size=10), min_size=1, max_size=4))
def test_present_gives_the_sets_of_the_items_asked_about(runs: list[list[Item]]) -> None:
    for items in [*runs, *runs]:  # each again after the others: no stale sets
        lemmas, texts = phrasing._present(items)
        assert lemmas == {it.lemma for it in items}
        assert texts == {it.text.lower() for it in items}


@settings(max_examples=200, deadline=None)
@given(st.lists(st.sampled_from(_POOL), max_size=12))
def test_a_said_gate_opens_exactly_where_an_item_passes_needs(items: list[Item]) -> None:
    seen: list[list[Item]] = []

    def step(got: list[Item], _lexicon: Lexicon) -> list[Item]:
        seen.append(got)
        return got

    gate = phrasing._said(step, ("then", "not", ","), ("all", "i mean"))
    gate(items, _CELL)
    assert bool(seen) == any(_needs(gate)(it) for it in items)
