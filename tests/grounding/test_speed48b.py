"""Session 48 (12b): twelve more phrasing passes run only where what they need is said:
_drop_onto ('drop'), _let ('let'), _both_people ('both'), _asked_for ('ask_for'), _questions ('?',
a wh-word or a question verb), _after_all ('after', 'once'), _one_each_of ('one'), _swaps ('swap'),
_so_after_remark ('so') and _there ('there') by their words (`phrasing._said`), and _telegraphic
(a sentence that ends before the last item) and _preambles (a comma and a word the grammar does
not know) by a test of the whole item list (`phrasing._when`). Each gate was read off its pass:
the pass changes nothing and refuses nothing without what its gate asks. As in test_speed47b: each
gate lets through a sentence its pass changes, and on random item sequences the gates close only
where the pass itself changes nothing."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.grounding import phrasing
from hltl.grounding.lexicon import Item
from tests.grounding.test_speed47b import closed_means_unchanged, gates_of, lets_through, pool_of

# each newly gated pass, with a sentence (of the cell scene) it changes or refuses at its place in
# refine, or as lexed
_CHANGED = [
    ("_drop_onto", "Drop the cup on the shelf"),
    ("_telegraphic", "Alice. Cup. Please."),
    ("_let", "Let Carol have the cup"),
    ("_both_people", "Give both Alice and Bob the chips"),
    ("_preambles", "Sorry to bother you, but could you give Carol the apple?"),
    ("_asked_for", "Carol asked for the bottle"),
    ("_questions", "Is the apple on the shelf?"),
    ("_after_all", "Give Alice the cup and the apple, and after both, give Bob the chips"),
    ("_one_each_of", "Give Alice and Bob the cup and the apple, one each"),
    ("_swaps", "Give Carol the chips and Bob the apple; no, swap them"),
    ("_so_after_remark", "Bob's hungry so give him the chips"),
    ("_there", "Put the apple on the shelf and the cup there too"),
]
_NEW = {name for name, _text in _CHANGED}
_GATES = gates_of(_NEW)
_POOL = pool_of(_CHANGED)


def test_the_new_passes_are_gated() -> None:
    assert set(_GATES) == _NEW
    gated = [s for s in phrasing._PASSES if hasattr(s, "__wrapped__")]
    said = [s for s in gated if "needs" in s.__dict__]
    when = [s for s in gated if "opens" in s.__dict__]
    # 66 gated, 57 of them by _said and 4 by _when after session 48's gates (lower bounds: other
    # engineers' passes may come gated)
    assert len(gated) >= 66 and len(said) >= 57 and len(when) >= 4


@pytest.mark.parametrize(("name", "text"), _CHANGED)
def test_each_gate_lets_through_a_sentence_its_pass_changes(name: str, text: str) -> None:
    lets_through(_GATES, name, text)


@settings(max_examples=600, deadline=None)
@given(st.lists(st.sampled_from(_POOL), max_size=14), st.sampled_from(sorted(_NEW)))
def test_where_a_gate_is_closed_the_pass_changes_nothing(items: list[Item], name: str) -> None:
    closed_means_unchanged(_GATES, items, name)
