"""Parser and printer: precedence, ltl2ba input, error positions, and the round trip."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from ltlf_strategies import formulas

from hltl.errors import SpecSyntaxError
from hltl.spec.parser import parse_formula
from hltl.spec.printer import atoms, atoms_in_order, to_string
from hltl.spec.syntax import (
    Always,
    And,
    Atom,
    Equiv,
    Eventually,
    FalseF,
    Formula,
    Implies,
    Next,
    Not,
    Or,
    Release,
    TrueF,
    Until,
    WeakNext,
)

a, b, c, d = Atom("a"), Atom("b"), Atom("c"), Atom("d")
P100, P200 = Atom("p100"), Atom("p200")


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("F p100 & F p200", And(Eventually(P100), Eventually(P200))),
        ("F (p100 & F p200)", Eventually(And(P100, Eventually(P200)))),
        ("a & b | c & d", Or(And(a, b), And(c, d))),
        ("a | b -> c", Implies(Or(a, b), c)),
        ("a -> b <-> c", Equiv(Implies(a, b), c)),
        ("a -> b -> c", Implies(a, Implies(b, c))),
        ("a <-> b <-> c", Equiv(Equiv(a, b), c)),
        ("a & b & c", And(And(a, b), c)),
        ("a U b U c", Until(a, Until(b, c))),
        ("a U b R c", Until(a, Release(b, c))),
        ("a & b U c", And(a, Until(b, c))),
        ("!a U b", Until(Not(a), b)),
        ("F a U b", Until(Eventually(a), b)),
        ("X X a", Next(Next(a))),
        ("WX a", WeakNext(a)),
        ("!!a", Not(Not(a))),
        ("G F !a", Always(Eventually(Not(a)))),
        ("F(a)", Eventually(a)),
        ("true & !false", And(TrueF(), Not(FalseF()))),
        ("Fa", Atom("Fa")),
        ("WXa", Atom("WXa")),
        ("  F\n  a ", Eventually(a)),
        ("F delivered(bottle, A)", Eventually(Atom("delivered", ("bottle", "A")))),
        ("picked(cup)", Atom("picked", ("cup",))),
        ("at(cup,shelf)", Atom("at", ("cup", "shelf"))),
        # arguments are identifiers even when they spell an operator
        ("holding(X, F)", Atom("holding", ("X", "F"))),
    ],
)
def test_parse(text: str, expected: Formula) -> None:
    assert parse_formula(text) == expected


@pytest.mark.parametrize(
    ("ltl2ba", "ours"),
    [
        ("<> p100 && <> p200", "F p100 & F p200"),
        ("[] (carry -> !publicc)", "G (carry -> !publicc)"),
        ("a || b && c", "a | b & c"),
        ("a V b", "a R b"),
        ("<>(d11 && guide U (m6 && X !guide))", "F (d11 & guide U (m6 & X !guide))"),
        (
            "<> (d5 && default && X ((carrybin U dispose) && <> default))"
            " && [](carrybin -> !publicc)",
            "F (d5 & default & X ((carrybin U dispose) & F default)) & G (carrybin -> !publicc)",
        ),
    ],
)
def test_ltl2ba_operators(ltl2ba: str, ours: str) -> None:
    assert parse_formula(ltl2ba) == parse_formula(ours)


@pytest.mark.parametrize(
    ("text", "message", "line", "column"),
    [
        ("F (a & )", "unexpected ')' at line 1, column 8 in \"F (a & )\"; expected an atom", 1, 8),
        (
            "F (a & b",
            "unexpected end of formula at line 1, column 9 in \"F (a & b\"; missing ')'",
            1,
            9,
        ),
        ("a b", "unexpected 'b' at line 1, column 3 in \"a b\"; expected a binary operator", 1, 3),
        ("a F b", "unexpected 'F' at line 1, column 3", 1, 3),
        (
            "a )",
            "unexpected ')' at line 1, column 3 in \"a )\"; this ')' has no matching '('",
            1,
            3,
        ),
        ("a $ b", "unexpected character '$' at line 1, column 3 in \"a $ b\"", 1, 3),
        ("F a &\n  & b", "unexpected '&' at line 2, column 3", 2, 3),
        ("F", 'unexpected end of formula at line 1, column 2 in "F"', 1, 2),
        (
            "picked()",
            "unexpected ')' at line 1, column 8 in \"picked()\"; expected an identifier",
            1,
            8,
        ),
        (
            "F deliver(bottle, A)",
            "unknown predicate 'deliver' at line 1, column 3 in \"F deliver(bottle, A)\"; "
            "predicates are: at, delivered, holding, picked, placed",
            1,
            3,
        ),
        (
            "F delivered(bottle)",
            "delivered() takes 2 arguments, got 1 (bottle) at line 1, column 3",
            1,
            3,
        ),
        ("picked(a, b)", "picked() takes 1 argument, got 2 (a, b) at line 1, column 1", 1, 1),
    ],
)
def test_syntax_errors_name_position_and_text(
    text: str, message: str, line: int, column: int
) -> None:
    with pytest.raises(SpecSyntaxError) as info:
        parse_formula(text)
    assert str(info.value).startswith(message)
    assert (info.value.line, info.value.column, info.value.text) == (line, column, text)


@pytest.mark.parametrize("text", ["", "   "])
def test_empty_formula_is_an_error(text: str) -> None:
    with pytest.raises(SpecSyntaxError, match="empty formula"):
        parse_formula(text)


def test_non_string_is_an_error() -> None:
    with pytest.raises(SpecSyntaxError, match="must be a string, got int"):
        parse_formula(5)  # type: ignore[arg-type]


@pytest.mark.parametrize(
    ("formula", "text"),
    [
        (And(And(a, b), c), "a & b & c"),
        (And(a, And(b, c)), "a & (b & c)"),
        (Until(a, Until(b, c)), "a U b U c"),
        (Until(Until(a, b), c), "(a U b) U c"),
        (Implies(Implies(a, b), c), "(a -> b) -> c"),
        (And(Or(a, b), c), "(a | b) & c"),
        (Or(And(a, b), c), "a & b | c"),
        (Eventually(And(P100, Eventually(P200))), "F (p100 & F p200)"),
        (Not(Eventually(a)), "!F a"),
        (Not(And(a, b)), "!(a & b)"),
        (Until(Release(a, b), c), "(a R b) U c"),
        (WeakNext(Atom("delivered", ("bottle", "A"))), "WX delivered(bottle, A)"),
        (Equiv(TrueF(), FalseF()), "true <-> false"),
    ],
)
def test_printer_uses_minimal_parentheses(formula: Formula, text: str) -> None:
    assert to_string(formula) == text
    assert parse_formula(text) == formula


@settings(max_examples=400, deadline=None)
@given(formulas(depth=5))
def test_round_trip(f: Formula) -> None:
    assert parse_formula(to_string(f)) == f


def test_atoms() -> None:
    f = parse_formula("F (picked(cup) & X p100) U (p100 | at(cup, shelf))")
    assert atoms(f) == {Atom("picked", ("cup",)), P100, Atom("at", ("cup", "shelf"))}
    assert atoms_in_order(f) == (Atom("picked", ("cup",)), P100, Atom("at", ("cup", "shelf")))
    assert atoms(parse_formula("true | !false")) == frozenset()
