"""The direct LTLf evaluator (the oracle of the automata tests) on hand-checked traces."""

from __future__ import annotations

import pytest

from hltl.spec.parser import parse_formula
from hltl.spec.semantics import evaluate
from hltl.spec.syntax import Atom

a, b = Atom("a"), Atom("b")
A, B, AB, NONE = frozenset({a}), frozenset({b}), frozenset({a, b}), frozenset[Atom]()


@pytest.mark.parametrize(
    ("text", "trace", "expected"),
    [
        ("a", [A], True),
        ("a", [B, A], False),
        ("X a", [A], False),  # strong next: no next position
        ("X a", [NONE, A], True),
        ("WX a", [NONE], True),  # weak next: holds at the last position
        ("WX a", [NONE, B], False),
        ("!X true", [A], True),
        ("F a", [NONE, NONE, A], True),
        ("F a", [NONE, B], False),
        ("G a", [A, AB, A], True),
        ("G a", [A, B], False),
        ("G F a", [A, NONE], False),  # finite traces: the last step must have a
        ("a U b", [A, A, B], True),
        ("a U b", [B], True),
        ("a U b", [A, A], False),  # b must come
        ("a U b", [A, NONE, B], False),
        ("a R b", [B, B], True),  # b all the way is enough on a finite trace
        ("a R b", [B, AB, NONE], True),  # a releases b (b still holds that step)
        ("a R b", [B, A], False),
        ("F (a & F b)", [A, NONE, B], True),
        ("F (a & F b)", [B, A], False),
        ("F (a & F b)", [AB], True),
        ("a -> X b", [NONE], True),
        ("a <-> b", [AB], True),
        ("a <-> b", [A], False),
        ("false | true", [NONE], True),
    ],
)
def test_evaluate(text: str, trace: list[frozenset[Atom]], expected: bool) -> None:
    assert evaluate(parse_formula(text), trace) is expected


def test_evaluate_at_a_position() -> None:
    f = parse_formula("a & X b")
    assert evaluate(f, [NONE, A, B], 1)
    assert not evaluate(f, [NONE, A, B], 0)


def test_empty_trace_and_bad_position_are_errors() -> None:
    with pytest.raises(ValueError, match="non-empty"):
        evaluate(a, [])
    with pytest.raises(ValueError, match="position 2 is outside the trace of length 2"):
        evaluate(a, [A, A], 2)
