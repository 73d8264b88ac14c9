"""Language equivalence of H-LTLf specs (monitor product) and of flat formulas (DFA product)."""

from __future__ import annotations

from collections import deque
from collections.abc import Callable, Hashable, Sequence
from typing import TypeVar

from hltl.spec.automata import AutomatonCache, default_cache
from hltl.spec.hierarchy import HSpec
from hltl.spec.monitor import HierarchyMonitor
from hltl.spec.syntax import Atom, Formula

# The product is explored over every subset of the atoms: 2**MAX_ATOMS symbols per state.
MAX_ATOMS = 16

S = TypeVar("S", bound=Hashable)


def _symbols(props: Sequence[Atom]) -> list[frozenset[Atom]]:
    if len(props) > MAX_ATOMS:
        raise ValueError(
            f"cannot compare over {len(props)} atoms; at most {MAX_ATOMS} (2**n symbols a step)"
        )
    symbols = [frozenset[Atom]()]
    for a in props:
        symbols += [s | {a} for s in symbols]
    return symbols


def _shortest_difference(
    start: S,
    symbols: Sequence[frozenset[Atom]],
    step: Callable[[S, frozenset[Atom]], S],
    differs: Callable[[S], bool],
) -> list[frozenset[Atom]] | None:
    """Breadth-first: the shortest non-empty trace after which ``differs`` holds, or None."""
    back: dict[S, tuple[S | None, frozenset[Atom]]] = {}
    queue: deque[S] = deque()
    # the empty trace is not compared: LTLf traces are non-empty, and no monitor accepts before
    # its first step
    for sym in symbols:
        nxt = step(start, sym)
        if nxt not in back:
            back[nxt] = (None, sym)
            queue.append(nxt)
    while queue:
        pair = queue.popleft()
        if differs(pair):
            trace: list[frozenset[Atom]] = []
            node: S | None = pair
            while node is not None:
                node, sym = back[node]
                trace.append(sym)
            return trace[::-1]
        for sym in symbols:
            nxt = step(pair, sym)
            if nxt not in back:
                back[nxt] = (pair, sym)
                queue.append(nxt)
    return None


def counterexample(
    a: HSpec, b: HSpec, cache: AutomatonCache | None = None
) -> list[frozenset[Atom]] | None:
    """A shortest trace that completes one spec but not the other, or None if they agree.

    "Completes" is ``HierarchyMonitor.accepted``: the root has fired (one-shot semantics,
    docs/model.md). Symbols range over every subset of the predicate atoms of both specs.

    Raises:
        ValueError: more than ``MAX_ATOMS`` atoms in total.
    """
    cache = default_cache() if cache is None else cache
    ma, mb = HierarchyMonitor(a, cache), HierarchyMonitor(b, cache)
    symbols = _symbols(sorted(ma.atoms | mb.atoms))

    def step(
        pair: tuple[tuple[int, ...], tuple[int, ...]], sym: frozenset[Atom]
    ) -> tuple[tuple[int, ...], tuple[int, ...]]:
        return ma.step(pair[0], sym), mb.step(pair[1], sym)

    def differs(pair: tuple[tuple[int, ...], tuple[int, ...]]) -> bool:
        return ma.accepted(pair[0]) != mb.accepted(pair[1])

    return _shortest_difference((ma.initial, mb.initial), symbols, step, differs)


def equivalent(a: HSpec, b: HSpec, cache: AutomatonCache | None = None) -> bool:
    """Whether two specs are completed by exactly the same traces (see ``counterexample``)."""
    return counterexample(a, b, cache) is None


def formula_counterexample(
    f: Formula, g: Formula, cache: AutomatonCache | None = None
) -> list[frozenset[Atom]] | None:
    """A shortest non-empty trace satisfying exactly one of two flat formulas, or None."""
    cache = default_cache() if cache is None else cache
    df, dg = cache.to_dfa(f), cache.to_dfa(g)
    symbols = _symbols(sorted(set(df.props) | set(dg.props)))

    def step(pair: tuple[int, int], sym: frozenset[Atom]) -> tuple[int, int]:
        return df.step(pair[0], sym), dg.step(pair[1], sym)

    def differs(pair: tuple[int, int]) -> bool:
        return (pair[0] in df.accepting) != (pair[1] in dg.accepting)

    return _shortest_difference((df.initial, dg.initial), symbols, step, differs)


def equivalent_formulas(f: Formula, g: Formula, cache: AutomatonCache | None = None) -> bool:
    """Whether two formulas hold on exactly the same finite non-empty traces."""
    return formula_counterexample(f, g, cache) is None
