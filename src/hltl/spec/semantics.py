"""LTLf truth on finite non-empty traces by direct recursion: the oracle for the automata."""

from __future__ import annotations

from collections.abc import Sequence
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

Trace = Sequence[frozenset[Atom]]


def evaluate(f: Formula, trace: Trace, i: int = 0) -> bool:
    """Whether ``f`` holds at position ``i`` of a finite, non-empty trace.

    Each trace element is the set of atoms true at that step. ``X f`` is false at the last
    position (there is no next one), ``WX f`` true there; ``F``, ``G``, ``U`` and ``R`` range over
    the positions ``i .. len(trace) - 1``.

    Raises:
        ValueError: the trace is empty or ``i`` is not one of its positions.
    """
    if not trace:
        raise ValueError("LTLf is evaluated on non-empty traces; got an empty trace")
    if not 0 <= i < len(trace):
        raise ValueError(f"position {i} is outside the trace of length {len(trace)}")
    return _holds(f, trace, i)


@singledispatch
def _holds(f: Formula, trace: Trace, i: int) -> bool:
    raise TypeError(f"not a formula: {f!r}")


@_holds.register
def _(f: Atom, trace: Trace, i: int) -> bool:
    return f in trace[i]


@_holds.register
def _(f: TrueF, trace: Trace, i: int) -> bool:
    return True


@_holds.register
def _(f: FalseF, trace: Trace, i: int) -> bool:
    return False


@_holds.register
def _(f: Not, trace: Trace, i: int) -> bool:
    return not _holds(f.operand, trace, i)


@_holds.register
def _(f: And, trace: Trace, i: int) -> bool:
    return _holds(f.left, trace, i) and _holds(f.right, trace, i)


@_holds.register
def _(f: Or, trace: Trace, i: int) -> bool:
    return _holds(f.left, trace, i) or _holds(f.right, trace, i)


@_holds.register
def _(f: Implies, trace: Trace, i: int) -> bool:
    return not _holds(f.left, trace, i) or _holds(f.right, trace, i)


@_holds.register
def _(f: Equiv, trace: Trace, i: int) -> bool:
    return _holds(f.left, trace, i) == _holds(f.right, trace, i)


@_holds.register
def _(f: Next, trace: Trace, i: int) -> bool:
    return i + 1 < len(trace) and _holds(f.operand, trace, i + 1)


@_holds.register
def _(f: WeakNext, trace: Trace, i: int) -> bool:
    return i + 1 >= len(trace) or _holds(f.operand, trace, i + 1)


@_holds.register
def _(f: Eventually, trace: Trace, i: int) -> bool:
    return any(_holds(f.operand, trace, j) for j in range(i, len(trace)))


@_holds.register
def _(f: Always, trace: Trace, i: int) -> bool:
    return all(_holds(f.operand, trace, j) for j in range(i, len(trace)))


@_holds.register
def _(f: Until, trace: Trace, i: int) -> bool:
    # some j >= i where right holds, with left holding at every k in [i, j)
    for j in range(i, len(trace)):
        if _holds(f.right, trace, j):
            return True
        if not _holds(f.left, trace, j):
            return False
    return False


@_holds.register
def _(f: Release, trace: Trace, i: int) -> bool:
    # right holds at every j >= i up to and including the first j where left holds
    for j in range(i, len(trace)):
        if not _holds(f.right, trace, j):
            return False
        if _holds(f.left, trace, j):
            return True
    return True
