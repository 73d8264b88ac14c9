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


# The operators below are plain subclasses of Unary and Binary, not dataclasses of their own:
# they inherit the dataclass's __init__, __eq__ (same class, same fields), __hash__, __repr__
# (by the instance's class name), frozenness, pickling and fields, and ``__slots__ = ()`` keeps
# them without a __dict__. Generating those methods for each of the 11 cost ~7 ms of every
# start-up (docs/planner.md, "Start-up").


class Not(Unary):
    __slots__ = ()


class And(Binary):
    __slots__ = ()


class Or(Binary):
    __slots__ = ()


class Implies(Binary):
    __slots__ = ()


class Equiv(Binary):
    __slots__ = ()


class Next(Unary):
    """Strong next ``X f``: there is a next step and f holds there."""

    __slots__ = ()


class WeakNext(Unary):
    """Weak next ``WX f``: if there is a next step, f holds there."""

    __slots__ = ()


class Eventually(Unary):
    __slots__ = ()


class Always(Unary):
    __slots__ = ()


class Until(Binary):
    __slots__ = ()


class Release(Binary):
    __slots__ = ()


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
