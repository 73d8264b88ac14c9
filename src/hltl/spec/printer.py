"""Formulas back to text that ``parse_formula`` reads as the same tree; their atoms."""

from __future__ import annotations

from hltl.spec.syntax import (
    Always,
    And,
    Atom,
    Binary,
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
    Unary,
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


def to_string(f: Formula) -> str:
    """The formula as text with the fewest parentheses that keep it unambiguous.

    ``parse_formula(to_string(f)) == f`` for every formula: ``&``, ``|`` and ``<->`` group to the
    left, ``->``, ``U`` and ``R`` to the right, so ``(a & b) & c`` prints as ``a & b & c`` but
    ``a & (b & c)`` keeps its parentheses.
    """
    if isinstance(f, Atom):
        return str(f)
    if isinstance(f, TrueF):
        return "true"
    if isinstance(f, FalseF):
        return "false"
    if isinstance(f, Unary):
        inner = to_string(f.operand)
        if _strength(f.operand) < _ATOMIC:
            inner = f"({inner})"
        return _UNARY[type(f)] + inner
    if isinstance(f, Binary):
        symbol, strength, assoc = _BINARY[type(f)]
        left, right = to_string(f.left), to_string(f.right)
        ls, rs = _strength(f.left), _strength(f.right)
        if ls < strength or (ls == strength and assoc == "right"):
            left = f"({left})"
        if rs < strength or (rs == strength and assoc == "left"):
            right = f"({right})"
        return f"{left} {symbol} {right}"
    raise TypeError(f"not a formula: {f!r}")


def atoms(f: Formula) -> frozenset[Atom]:
    """Every atom of the formula: predicate atoms and bare names alike."""
    if isinstance(f, Atom):
        return frozenset({f})
    if isinstance(f, TrueF | FalseF):
        return frozenset()
    if isinstance(f, Unary):
        return atoms(f.operand)
    if isinstance(f, Binary):
        return atoms(f.left) | atoms(f.right)
    raise TypeError(f"not a formula: {f!r}")


def atoms_in_order(f: Formula) -> tuple[Atom, ...]:
    """The atoms in order of first occurrence, reading the printed formula left to right."""
    seen: dict[Atom, None] = {}
    stack: list[Formula] = [f]
    while stack:
        g = stack.pop()
        if isinstance(g, Atom):
            seen.setdefault(g, None)
        elif isinstance(g, Unary):
            stack.append(g.operand)
        elif isinstance(g, Binary):
            stack.append(g.right)
            stack.append(g.left)
    return tuple(seen)
