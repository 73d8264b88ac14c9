"""LTLf syntax tree: frozen, hashable formula nodes; passes over them live in other modules."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TypeAlias

# Predicates a leaf may use, with their arities (DESIGN.md §3).
PREDICATES: dict[str, int] = {
    "delivered": 2,  # delivered(o, u): event, o handed to human u in this step
    "placed": 2,  # placed(o, s): event, o put down on surface s in this step
    "picked": 1,  # picked(o): event, a robot picks o from where it rests
    "holding": 2,  # holding(r, o): state, r holds o after the step
    "at": 2,  # at(o, s): state, o rests on s after the step
}


@dataclass(frozen=True, slots=True, order=True)
class Atom:
    """An atomic proposition.

    A predicate atom such as ``delivered(bottle, A)`` has ``args``; a bare name such as ``p100``
    (a child formula's event in a composite) has ``args == ()``.
    """

    name: str
    args: tuple[str, ...] = ()

    @property
    def is_predicate(self) -> bool:
        return bool(self.args)

    def __str__(self) -> str:
        if not self.args:
            return self.name
        return f"{self.name}({', '.join(self.args)})"


@dataclass(frozen=True, slots=True)
class TrueF:
    """The constant true."""


@dataclass(frozen=True, slots=True)
class FalseF:
    """The constant false."""


@dataclass(frozen=True, slots=True)
class Unary:
    """An operator with one operand (never built itself: use a subclass)."""

    operand: Formula


@dataclass(frozen=True, slots=True)
class Binary:
    """An operator with two operands (never built itself: use a subclass)."""

    left: Formula
    right: Formula


@dataclass(frozen=True, slots=True)
class Not(Unary):
    pass


@dataclass(frozen=True, slots=True)
class And(Binary):
    pass


@dataclass(frozen=True, slots=True)
class Or(Binary):
    pass


@dataclass(frozen=True, slots=True)
class Implies(Binary):
    pass


@dataclass(frozen=True, slots=True)
class Equiv(Binary):
    pass


@dataclass(frozen=True, slots=True)
class Next(Unary):
    """Strong next ``X f``: there is a next step and f holds there."""


@dataclass(frozen=True, slots=True)
class WeakNext(Unary):
    """Weak next ``WX f``: if there is a next step, f holds there."""


@dataclass(frozen=True, slots=True)
class Eventually(Unary):
    pass


@dataclass(frozen=True, slots=True)
class Always(Unary):
    pass


@dataclass(frozen=True, slots=True)
class Until(Binary):
    pass


@dataclass(frozen=True, slots=True)
class Release(Binary):
    pass


Formula: TypeAlias = (
    Atom
    | TrueF
    | FalseF
    | Not
    | And
    | Or
    | Implies
    | Equiv
    | Next
    | WeakNext
    | Eventually
    | Always
    | Until
    | Release
)

UNARY: tuple[type[Unary], ...] = (Not, Next, WeakNext, Eventually, Always)
BINARY: tuple[type[Binary], ...] = (And, Or, Implies, Equiv, Until, Release)
