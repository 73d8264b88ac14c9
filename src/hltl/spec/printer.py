"""Formulas back to text that ``parse_formula`` reads as the same tree; their atoms."""

from __future__ import annotations

from functools import singledispatch

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

# Binding strength and associativity, as in the grammar of hltl.spec.parser.
_ATOMIC = 6
_BINARY: dict[type, tuple[str, int, str]] = {
    Equiv: ("<->", 1, "left"),
    Implies: ("->", 2, "right"),
    Or: ("|", 3, "left"),
    And: ("&", 4, "left"),
    Until: ("U", 5, "right"),
    Release: ("R", 5, "right"),
}
_UNARY: dict[type, str] = {Not: "!", Next: "X ", WeakNext: "WX ", Eventually: "F ", Always: "G "}


def _strength(f: Formula) -> int:
    entry = _BINARY.get(type(f))
    return entry[1] if entry is not None else _ATOMIC


@singledispatch
def to_string(f: Formula) -> str:
    """The formula as text with the fewest parentheses that keep it unambiguous.

    ``parse_formula(to_string(f)) == f`` for every formula: ``&``, ``|`` and ``<->`` group to the
    left, ``->``, ``U`` and ``R`` to the right, so ``(a & b) & c`` prints as ``a & b & c`` but
    ``a & (b & c)`` keeps its parentheses.
    """
    raise TypeError(f"not a formula: {f!r}")


@to_string.register
def _(f: Atom) -> str:
    return str(f)


@to_string.register
def _(f: TrueF) -> str:
    return "true"


@to_string.register
def _(f: FalseF) -> str:
    return "false"


def _unary(f: Not | Next | WeakNext | Eventually | Always) -> str:
    inner = to_string(f.operand)
    if _strength(f.operand) < _ATOMIC:
        inner = f"({inner})"
    return _UNARY[type(f)] + inner


def _binary(f: And | Or | Implies | Equiv | Until | Release) -> str:
    symbol, strength, assoc = _BINARY[type(f)]
    left, right = to_string(f.left), to_string(f.right)
    ls, rs = _strength(f.left), _strength(f.right)
    if ls < strength or (ls == strength and assoc == "right"):
        left = f"({left})"
    if rs < strength or (rs == strength and assoc == "left"):
        right = f"({right})"
    return f"{left} {symbol} {right}"


for _unary_cls in (Not, Next, WeakNext, Eventually, Always):
    to_string.register(_unary_cls, _unary)
for _binary_cls in (And, Or, Implies, Equiv, Until, Release):
    to_string.register(_binary_cls, _binary)


@singledispatch
def atoms(f: Formula) -> frozenset[Atom]:
    """Every atom of the formula: predicate atoms and bare names alike."""
    raise TypeError(f"not a formula: {f!r}")


@atoms.register
def _(f: Atom) -> frozenset[Atom]:
    return frozenset({f})


@atoms.register(TrueF)
@atoms.register(FalseF)
def _(f: Formula) -> frozenset[Atom]:
    return frozenset()


def _unary_atoms(f: Not | Next | WeakNext | Eventually | Always) -> frozenset[Atom]:
    return atoms(f.operand)


def _binary_atoms(f: And | Or | Implies | Equiv | Until | Release) -> frozenset[Atom]:
    return atoms(f.left) | atoms(f.right)


for _unary_cls in (Not, Next, WeakNext, Eventually, Always):
    atoms.register(_unary_cls, _unary_atoms)
for _binary_cls in (And, Or, Implies, Equiv, Until, Release):
    atoms.register(_binary_cls, _binary_atoms)


def atoms_in_order(f: Formula) -> tuple[Atom, ...]:
    """The atoms in order of first occurrence, reading the printed formula left to right."""
    seen: dict[Atom, None] = {}
    stack: list[Formula] = [f]
    while stack:
        g = stack.pop()
        if isinstance(g, Atom):
            seen.setdefault(g, None)
        elif isinstance(g, Not | Next | WeakNext | Eventually | Always):
            stack.append(g.operand)
        elif isinstance(g, And | Or | Implies | Equiv | Until | Release):
            stack.append(g.right)
            stack.append(g.left)
    return tuple(seen)
