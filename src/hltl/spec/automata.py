"""LTLf to minimal DFA via MONA (program from ltlf2dfa); a cache keyed by formula shape."""

from __future__ import annotations

import json
import os
import re
import threading
from collections.abc import Callable, Iterable, Iterator, Mapping, Sequence
from collections.abc import Set as AbstractSet
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

from hltl.errors import AutomatonError, BackendUnavailableError
from hltl.fileio import cache_dir, sha256
from hltl.spec.printer import atoms_in_order, to_string
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

if TYPE_CHECKING:
    from concurrent.futures import Future

# The transition table has 2**len(props) columns per state; past 16 propositions it stops being
# a table one wants in memory (and MONA itself slows down near 20).
MAX_PROPS = 16
MONA_TIMEOUT = 60.0
# Positive and/or combinations of "F atom" with more atoms than this skip MONA: their automaton
# is the set of atoms seen so far (MonotoneDFA), built lazily; MONA's table would have
# 2**n states x 2**n symbols (n = 10: seconds to parse; n = 12: half a minute).
SYMBOLIC_FROM = 7
MAX_SYMBOLIC_PROPS = 30


@dataclass(frozen=True, slots=True)
class DFA:
    """A complete, minimal DFA over the symbols ``2**props``.

    ``table[(state << len(props)) | mask]`` is the successor of ``state`` on the symbol whose true
    propositions are ``{props[i] for i where bit i of mask is set}``. States are numbered
    breadth-first from ``initial == 0``; a non-accepting sink (dead state) is kept as an ordinary
    state when reachable, so ``table`` is total.
    """

    props: tuple[Atom, ...]
    initial: int
    accepting: AbstractSet[int]
    n_states: int
    table: Sequence[int]
    _bit: Mapping[Atom, int] = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        if len(self.table) != self.n_states << len(self.props):
            raise AutomatonError(
                f"DFA table has {len(self.table)} entries; expected "
                f"{self.n_states} states x {1 << len(self.props)} symbols"
            )
        object.__setattr__(self, "_bit", {a: 1 << i for i, a in enumerate(self.props)})

    @property
    def n_edges(self) -> int:
        """Number of distinct (source, target) state pairs."""
        width = 1 << len(self.props)
        return sum(len(set(self.table[s * width : (s + 1) * width])) for s in range(self.n_states))

    def mask_of(self, true_props: Iterable[Atom]) -> int:
        """The symbol of a set of true atoms; atoms outside ``props`` are ignored."""
        bit = self._bit
        mask = 0
        for a in true_props:
            mask |= bit.get(a, 0)
        return mask

    def step_mask(self, state: int, mask: int) -> int:
        """Successor of ``state`` on the symbol ``mask`` (see the class docstring)."""
        return self.table[(state << len(self.props)) | mask]

    def step(self, state: int, true_props: Iterable[Atom]) -> int:
        """Successor of ``state`` when exactly ``true_props`` (restricted to ``props``) hold."""
        return self.table[(state << len(self.props)) | self.mask_of(true_props)]

    def is_accepting(self, state: int) -> bool:
        return state in self.accepting

    def run(self, trace: Iterable[Iterable[Atom]]) -> int:
        """The state after reading the trace from the initial state."""
        q = self.initial
        for symbol in trace:
            q = self.step(q, symbol)
        return q

    def accepts(self, trace: Sequence[Iterable[Atom]]) -> bool:
        """Whether the finite, non-empty trace satisfies the formula."""
        if not trace:
            raise ValueError("LTLf is evaluated on non-empty traces; got an empty trace")
        return self.run(trace) in self.accepting

    def is_empty(self) -> bool:
        """True when no non-empty trace is accepted (the formula is unsatisfiable)."""
        width = 1 << len(self.props)
        start = self.initial * width
        frontier = list(set(self.table[start : start + width]))
        seen = set(frontier)
        while frontier:
            s = frontier.pop()
            if s in self.accepting:
                return False
            for t in set(self.table[s * width : (s + 1) * width]):
                if t not in seen:
                    seen.add(t)
                    frontier.append(t)
        return True

    def relabel(self, props: Sequence[Atom]) -> DFA:
        """The same automaton with ``props[i]`` in place of ``self.props[i]``."""
        props = tuple(props)
        if len(props) != len(self.props) or len(set(props)) != len(props):
            raise ValueError(
                f"relabel needs {len(self.props)} distinct propositions, got {len(props)}"
            )
        return DFA(props, self.initial, self.accepting, self.n_states, self.table)


# ---------------------------------------------------------------------------------------------
# positive and/or combinations of "F atom": the automaton is the set of atoms seen so far

# ("F", prop index) | ("and", a, b) | ("or", a, b)
MonoTree = tuple[object, ...]


def monotone_tree(f: Formula, props: Sequence[Atom]) -> MonoTree | None:
    """``f`` as a positive and/or tree of ``F atom`` over ``props``, or None if it is not one."""
    if isinstance(f, Eventually) and isinstance(f.operand, Atom):
        return ("F", list(props).index(f.operand)) if f.operand in props else None
    if isinstance(f, And | Or):
        a, b = monotone_tree(f.left, props), monotone_tree(f.right, props)
        if a is None or b is None:
            return None
        return ("and" if isinstance(f, And) else "or", a, b)
    return None


def _holds(t: MonoTree, seen: int) -> bool:
    if t[0] == "F":
        return bool(seen >> int(t[1]) & 1)  # type: ignore[call-overload]
    a, b = t[1], t[2]
    assert isinstance(a, tuple) and isinstance(b, tuple)
    if t[0] == "and":
        return _holds(a, seen) and _holds(b, seen)
    return _holds(a, seen) or _holds(b, seen)


class _SeenTable(Sequence[int]):
    """``table[(seen << k) | mask] == seen | mask``: reading a symbol adds its atoms."""

    __slots__ = ("_k", "_mask")

    def __init__(self, k: int) -> None:
        self._k = k
        self._mask = (1 << k) - 1

    def __len__(self) -> int:
        return 1 << (2 * self._k)

    def __getitem__(self, index: int) -> int:  # type: ignore[override]
        return (index >> self._k) | (index & self._mask)


class _Accepting(AbstractSet[int]):
    """The seen-sets that satisfy the tree (membership memoised; iteration enumerates)."""

    __slots__ = ("_k", "_memo", "_tree")

    def __init__(self, tree: MonoTree, k: int) -> None:
        self._tree = tree
        self._k = k
        self._memo: dict[int, bool] = {}

    def __contains__(self, state: object) -> bool:
        if not isinstance(state, int) or not 0 <= state < 1 << self._k:
            return False
        hit = self._memo.get(state)
        if hit is None:
            hit = _holds(self._tree, state)
            self._memo[state] = hit
        return hit

    def __iter__(self) -> Iterator[int]:
        return (s for s in range(1 << self._k) if s in self)

    def __len__(self) -> int:
        return sum(1 for _ in self)


@dataclass(frozen=True, slots=True)
class MonotoneDFA(DFA):
    """The DFA of a positive and/or combination of ``F atom``: its state is the set of atoms seen
    so far (bit i: ``props[i]``), accepting when the combination holds on that set.

    This is exact LTLf semantics for such formulas (``F a`` holds on a finite trace iff ``a``
    holds in some step) and needs neither MONA nor a table: ``table`` and ``accepting`` compute
    entries on demand. It is complete but not minimal (``n_states == 2**len(props)``).
    """

    @classmethod
    def build(cls, tree: MonoTree, props: Sequence[Atom]) -> MonotoneDFA:
        k = len(props)
        return cls(tuple(props), 0, _Accepting(tree, k), 1 << k, _SeenTable(k))

    @property
    def n_edges(self) -> int:
        # from a seen-set S every superset is one step away: sum over S of 2**(k - |S|) = 3**k
        return int(3 ** len(self.props))

    def is_empty(self) -> bool:
        # every atom can be seen in the first step: empty iff even "all seen" is rejected
        return (1 << len(self.props)) - 1 not in self.accepting

    def relabel(self, props: Sequence[Atom]) -> DFA:
        props = tuple(props)
        if len(props) != len(self.props) or len(set(props)) != len(props):
            raise ValueError(
                f"relabel needs {len(self.props)} distinct propositions, got {len(props)}"
            )
        return MonotoneDFA(props, self.initial, self.accepting, self.n_states, self.table)


# ---------------------------------------------------------------------------------------------
# canonical renaming: atoms become x0, x1, ... in order of first occurrence


def _placeholder(i: int) -> Atom:
    return Atom(f"x{i}")


def substitute_atoms(f: Formula, replace: Callable[[Atom], Formula]) -> Formula:
    """The formula with every atom ``a`` replaced by the formula ``replace(a)``."""
    if isinstance(f, Atom):
        return replace(f)
    if isinstance(f, TrueF | FalseF):
        return f
    if isinstance(f, Unary):
        return type(f)(substitute_atoms(f.operand, replace))
    if isinstance(f, Binary):
        return type(f)(substitute_atoms(f.left, replace), substitute_atoms(f.right, replace))
    raise TypeError(f"not a formula: {f!r}")


def rename_atoms(f: Formula, mapping: Mapping[Atom, Atom]) -> Formula:
    """The formula with every atom ``a`` replaced by ``mapping.get(a, a)``."""
    return substitute_atoms(f, lambda a: mapping.get(a, a))


def canonical_form(f: Formula) -> tuple[Formula, tuple[Atom, ...]]:
    """``(g, props)``: ``g`` is ``f`` with ``props[i]`` renamed to ``x{i}``.

    Two formulas that differ only in the names of their atoms (``F delivered(bottle, A)`` and
    ``F delivered(chips, B)``) have the same ``g``.
    """
    props = atoms_in_order(f)
    mapping = {a: _placeholder(i) for i, a in enumerate(props)}
    return rename_atoms(f, mapping), props


# ---------------------------------------------------------------------------------------------
# MONA


def _to_ltlf2dfa(f: Formula, mod: Any) -> Any:
    # Atoms here are the placeholders x0, x1, ...: lowercase identifiers as ltlf2dfa requires.
    if isinstance(f, Atom):
        return mod.LTLfAtomic(f.name)
    if isinstance(f, TrueF):
        return mod.LTLfTrue()
    if isinstance(f, FalseF):
        return mod.LTLfFalse()
    unary = {
        Not: mod.LTLfNot,
        Next: mod.LTLfNext,
        WeakNext: mod.LTLfWeakNext,
        Eventually: mod.LTLfEventually,
        Always: mod.LTLfAlways,
    }
    if isinstance(f, Unary):
        return unary[type(f)](_to_ltlf2dfa(f.operand, mod))
    binary = {
        And: mod.LTLfAnd,
        Or: mod.LTLfOr,
        Implies: mod.LTLfImplies,
        Equiv: mod.LTLfEquivalence,
        Until: mod.LTLfUntil,
        Release: mod.LTLfRelease,
    }
    if isinstance(f, Binary):
        return binary[type(f)]([_to_ltlf2dfa(f.left, mod), _to_ltlf2dfa(f.right, mod)])
    raise TypeError(f"not a formula: {f!r}")


def mona_program(canonical: Formula) -> str:
    """The MONA program (WS1S) for a formula over the placeholder atoms ``x0, x1, ...``."""
    try:
        from ltlf2dfa import ltlf as ltlf_mod
        from ltlf2dfa.base import MonaProgram
    except ImportError as exc:  # pragma: no cover - a core dependency
        raise BackendUnavailableError(
            "the Python package 'ltlf2dfa' is needed to compile formulas: pip install ltlf2dfa"
        ) from exc
    return str(MonaProgram(_to_ltlf2dfa(canonical, ltlf_mod)).mona_program())


def _run_mona(program: str, mona: str, timeout: float, shown: str) -> str:
    # (imported here: a warm disk cache runs no MONA, and these are ~8 ms of start-up)
    import shutil
    import subprocess
    import tempfile

    exe = shutil.which(mona)
    if exe is None:
        raise BackendUnavailableError(
            f"the MONA binary {mona!r} was not found; install the Debian package 'mona' "
            "(apt-get install mona; ./setup.sh does it)"
        )
    with tempfile.TemporaryDirectory(prefix="hltl-mona-") as tmp:
        path = Path(tmp) / "formula.mona"
        path.write_text(program, encoding="utf-8")
        try:
            proc = subprocess.run(
                [exe, "-q", "-u", "-w", str(path)],
                capture_output=True,
                text=True,
                timeout=timeout,
                check=False,
            )
        except subprocess.TimeoutExpired:
            raise AutomatonError(
                f"MONA timed out after {timeout:g} s compiling {shown!r}"
            ) from None
        except OSError as exc:
            raise AutomatonError(f"could not run MONA ({exe}): {exc}") from None
    if proc.returncode != 0:
        detail = (proc.stderr.strip() or proc.stdout.strip())[-500:]
        raise AutomatonError(
            f"MONA failed (exit {proc.returncode}) compiling {shown!r}: {detail or 'no output'}"
        )
    return proc.stdout


# MONA's output, read only where MONA ran (a warm disk cache compiles none of these at start-up)
_FREE = r"DFA for formula with free variables:([^\n]*)"
_ACCEPTING = r"Accepting states:([^\n]*)"
_STATE = r"^State (\d+): ([01X]*) -> state (\d+)\s*$"


def parse_mona_output(output: str, n_props: int) -> DFA:
    """The minimal DFA of MONA's raw state table for a formula over ``x0 .. x{n_props-1}``.

    MONA's state 0 reads a dummy first symbol (the same successor on every symbol); the DFA
    starts in that successor. ``X`` in a guard is a don't-care and is expanded; a placeholder
    that MONA dropped from its free variables is a don't-care everywhere.
    """
    free_m, acc_m = re.search(_FREE, output), re.search(_ACCEPTING, output)
    if free_m is None or acc_m is None:
        raise AutomatonError(f"unexpected MONA output (no state table): {output[-300:]!r}")
    free = free_m.group(1).split()
    bits: list[int] = []
    for name in free:
        m = re.fullmatch(r"X(\d+)", name)
        if m is None or int(m.group(1)) >= n_props:
            raise AutomatonError(f"unexpected free variable {name!r} in MONA output")
        bits.append(int(m.group(1)))
    width = 1 << n_props
    accepting = {int(s) for s in acc_m.group(1).split()}
    raw: dict[int, list[int]] = {}
    for m in re.finditer(_STATE, output, re.MULTILINE):
        src, guard, dst = int(m.group(1)), m.group(2), int(m.group(3))
        if len(guard) != len(bits):
            raise AutomatonError(f"MONA guard {guard!r} does not match variables {free}")
        row = raw.setdefault(src, [-1] * width)
        fixed = 0
        free_bits = [b for b in range(n_props) if b not in bits]
        for ch, b in zip(guard, bits, strict=True):
            if ch == "1":
                fixed |= 1 << b
            elif ch == "X":
                free_bits.append(b)
        masks = [fixed]
        for b in free_bits:
            masks += [m | 1 << b for m in masks]
        for mask in masks:
            row[mask] = dst
    if 0 not in raw or any(-1 in row for row in raw.values()):
        raise AutomatonError("MONA's state table is incomplete")
    initial = raw[0][0]
    if any(t != initial for t in raw[0]):
        raise AutomatonError("MONA's pre-initial state does not read a dummy symbol")
    return _minimise(raw, initial, accepting, n_props)


def _minimise(
    raw: Mapping[int, Sequence[int]], initial: int, accepting: set[int], n_props: int
) -> DFA:
    """Moore partition refinement on the part reachable from ``initial``; BFS numbering."""
    reach = [initial]
    seen = {initial}
    for s in reach:
        for t in raw[s]:
            if t not in seen:
                seen.add(t)
                reach.append(t)
    block = {s: int(s in accepting) for s in reach}
    n_blocks = len(set(block.values()))
    while True:
        signatures: dict[tuple[int, tuple[int, ...]], int] = {}
        new_block = {}
        for s in reach:
            sig = (block[s], tuple(block[t] for t in raw[s]))
            new_block[s] = signatures.setdefault(sig, len(signatures))
        block = new_block
        if len(signatures) == n_blocks:
            break
        n_blocks = len(signatures)
    rep: dict[int, int] = {}
    for s in reach:
        rep.setdefault(block[s], s)
    # renumber blocks breadth-first from the initial block, symbols in increasing order
    number = {block[initial]: 0}
    order = [block[initial]]
    for b in order:
        for t in raw[rep[b]]:
            if block[t] not in number:
                number[block[t]] = len(order)
                order.append(block[t])
    table: list[int] = []
    for b in order:
        table.extend(number[block[t]] for t in raw[rep[b]])
    acc = frozenset(number[b] for b in order if rep[b] in accepting)
    props = tuple(_placeholder(i) for i in range(n_props))
    return DFA(props, 0, acc, len(order), tuple(table))


def _compile_canonical(canonical: Formula, n_props: int, mona: str, timeout: float) -> DFA:
    if n_props >= SYMBOLIC_FROM:
        tree = monotone_tree(canonical, [_placeholder(i) for i in range(n_props)])
        if tree is not None:
            if n_props > MAX_SYMBOLIC_PROPS:
                raise AutomatonError(
                    f"{to_string(canonical)!r} has {n_props} atoms; at most "
                    f"{MAX_SYMBOLIC_PROPS} in one and/or combination (split it into children)"
                )
            return MonotoneDFA.build(tree, [_placeholder(i) for i in range(n_props)])
    if n_props > MAX_PROPS:
        raise AutomatonError(
            f"{to_string(canonical)!r} has {n_props} atoms; at most {MAX_PROPS} fit a DFA table "
            "(split the formula into children)"
        )
    output = _run_mona(mona_program(canonical), mona, timeout, to_string(canonical))
    return parse_mona_output(output, n_props)


def to_dfa(f: Formula, *, mona: str = "mona", timeout: float = MONA_TIMEOUT) -> DFA:
    """Compile a formula to its minimal DFA, uncached (see ``AutomatonCache`` for the cached way).

    Args:
        f: the formula; its atoms become ``props`` in order of first occurrence.
        mona: the MONA executable (name on PATH or a path).
        timeout: seconds MONA may take.

    Raises:
        BackendUnavailableError: MONA is not installed.
        AutomatonError: too many atoms, or MONA failed or timed out.
    """
    canonical, props = canonical_form(f)
    try:
        dfa = _compile_canonical(canonical, len(props), mona, timeout)
    except AutomatonError as exc:
        raise AutomatonError(str(exc).replace(to_string(canonical), to_string(f))) from None
    return dfa.relabel(props)


class AutomatonCache:
    """Thread-safe DFA cache keyed by formula shape (atoms renamed in first-occurrence order).

    ``F delivered(bottle, A)`` and ``F delivered(chips, B)`` share one MONA call; the cached DFA
    is re-labelled with each formula's atoms. Concurrent requests for the same shape wait for
    the one compilation in flight. Failed compilations are not cached. A table kept in the
    ``disk`` folder is read under the cache's lock (a small JSON file), so a warm cache makes no
    ``Future`` for it: ``concurrent.futures`` (with ``logging``, ~5 ms of `hltl plan`'s
    start-up, docs/planner.md "Start-up") is imported only when MONA has to run.
    """

    def __init__(
        self, *, mona: str = "mona", timeout: float = MONA_TIMEOUT, disk: Path | None = None
    ) -> None:
        self.mona = mona
        self.timeout = timeout
        #: a folder that keeps compiled tables across processes (None: memory only)
        self.disk = disk
        self._lock = threading.Lock()
        self._entries: dict[Formula, DFA | Future[DFA]] = {}
        self._hits = 0
        self._misses = 0

    @property
    def hits(self) -> int:
        """Requests answered from the cache (including waits on a compilation in flight)."""
        return self._hits

    @property
    def misses(self) -> int:
        """Requests that ran MONA."""
        return self._misses

    def __len__(self) -> int:
        with self._lock:
            return sum(1 for e in self._entries.values() if isinstance(e, DFA) or e.done())

    def clear(self) -> None:
        """Forget every cached DFA and reset the counts."""
        with self._lock:
            self._entries.clear()
            self._hits = self._misses = 0

    def to_dfa(self, f: Formula) -> DFA:
        """The minimal DFA of ``f`` (``props`` = its atoms in first-occurrence order).

        Raises:
            BackendUnavailableError: MONA is not installed.
            AutomatonError: too many atoms, or MONA failed or timed out.
        """
        canonical, props = canonical_form(f)
        owner: Future[DFA] | None = None  # (this request runs MONA; others wait for it)
        with self._lock:
            entry = self._entries.get(canonical)
            if entry is not None:
                self._hits += 1
            else:
                self._misses += 1
                entry = self._read(canonical, len(props))
                if entry is None:
                    from concurrent.futures import Future  # why: only when MONA runs

                    entry = owner = Future()
                self._entries[canonical] = entry
        if owner is not None:
            try:
                owner.set_result(self._compile(canonical, len(props)))
            except BaseException as exc:
                with self._lock:
                    self._entries.pop(canonical, None)
                owner.set_exception(exc)
        if isinstance(entry, DFA):
            return entry.relabel(props)
        try:
            dfa = entry.result()
        except AutomatonError as exc:
            raise AutomatonError(str(exc).replace(to_string(canonical), to_string(f))) from None
        return dfa.relabel(props)

    def _read(self, canonical: Formula, n_props: int) -> DFA | None:
        """The table the disk folder keeps for this formula (None: none, or unreadable)."""
        if self.disk is None:
            return None
        text = to_string(canonical)
        try:
            data = json.loads(_table_path(self.disk, text).read_text(encoding="utf-8"))
            if data["formula"] == text and data["format"] == DISK_FORMAT:
                return DFA(
                    tuple(_placeholder(i) for i in range(n_props)),
                    int(data["initial"]),
                    frozenset(int(x) for x in data["accepting"]),
                    int(data["n_states"]),
                    tuple(int(x) for x in data["table"]),
                )
        except (OSError, ValueError, KeyError, TypeError, AutomatonError):
            pass  # absent or unreadable: compile it
        return None

    def _compile(self, canonical: Formula, n_props: int) -> DFA:
        """MONA (``_read`` found no table), keeping the table in the disk folder if any."""
        dfa = _compile_canonical(canonical, n_props, self.mona, self.timeout)
        if self.disk is not None and not isinstance(dfa, MonotoneDFA):
            text = to_string(canonical)
            path = _table_path(self.disk, text)
            record = {
                "format": DISK_FORMAT,
                "formula": text,
                "initial": dfa.initial,
                "accepting": sorted(dfa.accepting),
                "n_states": dfa.n_states,
                "table": list(dfa.table),
            }
            try:
                self.disk.mkdir(parents=True, exist_ok=True)
                tmp = path.with_suffix(f".{os.getpid()}.{threading.get_ident()}.tmp")
                tmp.write_text(json.dumps(record), encoding="utf-8")
                os.replace(tmp, path)  # atomic: concurrent processes never read half a file
            except OSError:
                pass  # a read-only cache folder only costs the next process a MONA call
        return dfa


DISK_FORMAT = 1


def _table_path(disk: Path, text: str) -> Path:
    """Where the ``disk`` folder keeps the table of the canonical formula ``text``."""
    return disk / (sha256(f"{DISK_FORMAT}\n{text}".encode()).hexdigest() + ".json")


def disk_cache_dir() -> Path | None:
    """Where the default cache keeps tables across processes: ``$HLTL_CACHE_DIR/dfa``, else
    ``$XDG_CACHE_HOME/hltl/dfa`` or ``~/.cache/hltl/dfa``; ``HLTL_CACHE_DIR=off`` disables it."""
    return cache_dir("dfa")


_default_cache = AutomatonCache(disk=disk_cache_dir())


def default_cache() -> AutomatonCache:
    """The process-wide cache used when no cache is passed (owned by this module)."""
    return _default_cache
