"""Language equivalence of hierarchical specs and of flat formulas, with counterexamples."""

from __future__ import annotations

import pytest

from hltl.spec.equivalence import (
    counterexample,
    equivalent,
    equivalent_formulas,
    formula_counterexample,
)
from hltl.spec.hierarchy import HSpec, spec_from_dict
from hltl.spec.monitor import HierarchyMonitor
from hltl.spec.parser import parse_formula
from hltl.spec.semantics import evaluate
from hltl.spec.syntax import Atom

BOTTLE, CHIPS = "F delivered(bottle, A)", "F delivered(chips, B)"


def _spec(**formulas: str) -> HSpec:
    return spec_from_dict({"root": "p0", "formulas": formulas})


UNORDERED = _spec(p0="F p100 & F p200", p100=BOTTLE, p200=CHIPS)
SWAPPED = _spec(p0="F p200 & F p100", p100=BOTTLE, p200=CHIPS)
RENAMED = _spec(p0="F p7 & F p1", p1=BOTTLE, p7=CHIPS)
ORDERED = _spec(p0="F (p100 & F p200)", p100=BOTTLE, p200=CHIPS)
EITHER = _spec(p0="F p100 | F p200", p100=BOTTLE, p200=CHIPS)


def test_equivalent_specs() -> None:
    assert equivalent(UNORDERED, SWAPPED)
    assert equivalent(UNORDERED, RENAMED)
    assert counterexample(UNORDERED, UNORDERED) is None
    # the same task written flat: one leaf holding both deliveries
    flat = _spec(p0="F p100", p100="F delivered(bottle, A) & F delivered(chips, B)")
    assert equivalent(UNORDERED, flat)
    # a deeper tree for the same task
    deep = _spec(p0="F p100", p100="F p110 & F p120", p110=BOTTLE, p120=CHIPS)
    assert equivalent(UNORDERED, deep)


@pytest.mark.parametrize(("a", "b"), [(UNORDERED, ORDERED), (UNORDERED, EITHER), (ORDERED, EITHER)])
def test_non_equivalent_specs_give_a_shortest_counterexample(a: HSpec, b: HSpec) -> None:
    assert not equivalent(a, b)
    trace = counterexample(a, b)
    assert trace is not None and len(trace) >= 1
    ma, mb = HierarchyMonitor(a), HierarchyMonitor(b)
    assert ma.accepted(ma.run(trace)) != mb.accepted(mb.run(trace))
    # shortest: no proper prefix tells them apart
    for k in range(1, len(trace)):
        assert ma.accepted(ma.run(trace[:k])) == mb.accepted(mb.run(trace[:k]))


def test_ordered_versus_unordered_counterexample_is_chips_first() -> None:
    trace = counterexample(UNORDERED, ORDERED)
    bottle, chips = Atom("delivered", ("bottle", "A")), Atom("delivered", ("chips", "B"))
    assert trace is not None and len(trace) == 2
    assert chips in trace[0] and bottle not in trace[0] and bottle in trace[1]


def test_different_atoms_are_not_equivalent() -> None:
    other = _spec(p0="F p100 & F p200", p100=BOTTLE, p200="F delivered(chips, A)")
    assert not equivalent(UNORDERED, other)


@pytest.mark.parametrize(
    ("f", "g", "same"),
    [
        ("F a & F b", "F b & F a", True),
        ("!F a", "G !a", True),
        ("a U b", "b | (a & X (a U b))", True),
        ("WX a", "!X !a", True),
        ("a R b", "!(!a U !b)", True),
        ("G F a", "F G a", True),  # on finite traces both say: a at the last step
        ("X true", "true", False),
        ("F (a & F b)", "F a & F b", False),
        ("a -> b", "b -> a", False),
    ],
)
def test_equivalent_formulas(f: str, g: str, same: bool) -> None:
    pf, pg = parse_formula(f), parse_formula(g)
    assert equivalent_formulas(pf, pg) is same
    trace = formula_counterexample(pf, pg)
    assert (trace is None) is same
    if trace is not None:
        assert evaluate(pf, trace) != evaluate(pg, trace)


def test_too_many_atoms_to_compare() -> None:
    f = parse_formula(" | ".join(f"a{i}" for i in range(9)))
    g = parse_formula(" | ".join(f"b{i}" for i in range(9)))
    with pytest.raises(ValueError, match="cannot compare over 18 atoms; at most 16"):
        formula_counterexample(f, g)
