"""Formula generators for the spec tests: Hypothesis strategies and a seeded random builder."""

from __future__ import annotations

import random
from collections.abc import Sequence

from hypothesis import strategies as st

from hltl.spec.parser import KEYWORDS
from hltl.spec.syntax import (
    PREDICATES,
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

UNARY_OPS = (Not, Next, WeakNext, Eventually, Always)
BINARY_OPS = (And, Or, Implies, Equiv, Until, Release)

identifiers = st.from_regex(r"[A-Za-z_][A-Za-z0-9_]{0,6}", fullmatch=True)
bare_names = identifiers.filter(lambda s: s not in KEYWORDS)


@st.composite
def predicate_atoms(draw: st.DrawFn) -> Atom:
    name = draw(st.sampled_from(sorted(PREDICATES)))
    args = draw(st.lists(identifiers, min_size=PREDICATES[name], max_size=PREDICATES[name]))
    return Atom(name, tuple(args))


any_atoms = st.one_of(bare_names.map(Atom), predicate_atoms())


def formulas(
    atoms: st.SearchStrategy[Atom] = any_atoms, depth: int = 4
) -> st.SearchStrategy[Formula]:
    """Formulas of nesting depth at most ``depth`` over the given atoms."""
    leaves: st.SearchStrategy[Formula] = st.one_of(atoms, st.just(TrueF()), st.just(FalseF()))
    if depth == 0:
        return leaves
    sub = formulas(atoms, depth - 1)
    unary = st.one_of(*(st.builds(op, sub) for op in UNARY_OPS))
    binary = st.one_of(*(st.builds(op, sub, sub) for op in BINARY_OPS))
    return st.one_of(leaves, unary, binary)


def random_formula(rng: random.Random, atoms: Sequence[Atom], depth: int) -> Formula:
    """A random formula of depth at most ``depth``; constants are rare, as in real specs."""
    roll = rng.random()
    if depth == 0 or roll < 0.2:
        if rng.random() < 0.05:
            return rng.choice([TrueF(), FalseF()])
        return rng.choice(list(atoms))
    if roll < 0.55:
        return rng.choice(UNARY_OPS)(random_formula(rng, atoms, depth - 1))
    op = rng.choice(BINARY_OPS)
    return op(random_formula(rng, atoms, depth - 1), random_formula(rng, atoms, depth - 1))


def random_trace(rng: random.Random, atoms: Sequence[Atom], max_len: int) -> list[frozenset[Atom]]:
    """A random non-empty trace of at most ``max_len`` steps over ``atoms``."""
    return [
        frozenset(a for a in atoms if rng.random() < 0.5) for _ in range(rng.randint(1, max_len))
    ]
