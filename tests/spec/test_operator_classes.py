"""The operator base classes: every unary/binary operator is one, and passes use them."""

from __future__ import annotations

import typing

from hltl.spec.automata import substitute_atoms
from hltl.spec.parser import parse_formula
from hltl.spec.printer import atoms, to_string
from hltl.spec.syntax import BINARY, UNARY, And, Atom, Binary, Formula, Or, Unary


def test_the_class_lists_are_exactly_the_subclasses() -> None:
    members = set(typing.get_args(Formula))
    assert set(UNARY) == {c for c in members if issubclass(c, Unary)}
    assert set(BINARY) == {c for c in members if issubclass(c, Binary)}
    assert Unary not in members and Binary not in members


def test_same_operands_different_operators_are_different_formulas() -> None:
    a, b = Atom("a"), Atom("b")
    assert And(a, b) != Or(a, b) and len({And(a, b), Or(a, b), And(a, b)}) == 2


def test_passes_over_the_base_classes_keep_each_operator() -> None:
    f = parse_formula("!(a U X b) -> G (F c & WX (d R e)) <-> a")
    assert parse_formula(to_string(f)) == f
    assert {str(x) for x in atoms(f)} == set("abcde")
    renamed = substitute_atoms(f, lambda x: Atom(x.name.upper()))
    assert to_string(renamed) == to_string(f).translate(str.maketrans("abcde", "ABCDE"))
