"""H-LTLf specifications: a tree of named formulas, loading, validity rules (DESIGN.md §4)."""

from __future__ import annotations

import heapq
import re
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from types import MappingProxyType
from typing import Any

from hltl.errors import SpecSyntaxError, SpecValidationError
from hltl.fileio import load_file, quote
from hltl.spec.automata import DFA, AutomatonCache, MonotoneDFA, default_cache
from hltl.spec.parser import KEYWORDS, parse_formula
from hltl.spec.printer import atoms_in_order, to_string
from hltl.spec.syntax import PREDICATES, Atom, Formula

_NAME = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")

# Above this many children the one-shot search of rule 3 (3**children symbols per DFA state)
# is skipped and only plain satisfiability is checked.
MAX_CHILDREN_CHECKED = 12


def _listing(names: Iterable[str]) -> str:
    return ", ".join(names)


def _and_list(names: list[str]) -> str:
    return names[0] if len(names) == 1 else ", ".join(names[:-1]) + " and " + names[-1]


@dataclass(frozen=True, slots=True)
class HSpec:
    """A hierarchical LTLf specification: named formulas forming a tree under ``root``.

    A composite formula refers to its children by name (``F p100 & F p200``); a leaf uses
    predicate atoms only (``F delivered(bottle, A)``). Constructing an ``HSpec`` checks the tree
    (rules 1-2 of DESIGN.md §4) and puts ``formulas`` in a canonical order: breadth-first from
    the root, children in order of first occurrence in their parent. The automaton-level checks
    (satisfiability, rule 3) are ``validate_automata``; ``spec_from_dict`` runs both.

    Attributes:
        root: name of the root formula.
        formulas: ``(name, formula)`` pairs, root first, breadth-first.
        parent: each non-root name to its parent's name.
        children: each name to its children's names (``()`` for a leaf).
        levels: names by depth; ``levels[0] == (root,)``.
        leaves: names of the formulas without children, in ``formulas`` order.
        composites: names of the formulas with children, in ``formulas`` order.
    """

    root: str
    formulas: tuple[tuple[str, Formula], ...]
    parent: Mapping[str, str] = field(init=False, repr=False, compare=False)
    children: Mapping[str, tuple[str, ...]] = field(init=False, repr=False, compare=False)
    levels: tuple[tuple[str, ...], ...] = field(init=False, repr=False, compare=False)
    leaves: tuple[str, ...] = field(init=False, repr=False, compare=False)
    composites: tuple[str, ...] = field(init=False, repr=False, compare=False)
    _by_name: Mapping[str, Formula] = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        formulas = tuple((name, f) for name, f in self.formulas)
        by_name, children = _check_tree(self.root, formulas)
        levels: list[tuple[str, ...]] = []
        layer = [self.root]
        while layer:
            levels.append(tuple(layer))
            layer = [c for name in layer for c in children[name]]
        if len(levels) > MAX_LEVELS:
            # every pass over the tree (printing, monitors) recurses once per level
            raise SpecValidationError(
                f"the hierarchy has {len(levels)} levels; at most {MAX_LEVELS} are supported"
            )
        order = [name for layer_ in levels for name in layer_]
        parent = {c: name for name in order for c in children[name]}
        object.__setattr__(self, "formulas", tuple((n, by_name[n]) for n in order))
        object.__setattr__(self, "_by_name", MappingProxyType(by_name))
        object.__setattr__(self, "children", MappingProxyType(children))
        object.__setattr__(self, "parent", MappingProxyType(parent))
        object.__setattr__(self, "levels", tuple(levels))
        object.__setattr__(self, "leaves", tuple(n for n in order if not children[n]))
        object.__setattr__(self, "composites", tuple(n for n in order if children[n]))

    def __reduce__(self) -> tuple[type[HSpec], tuple[str, tuple[tuple[str, Formula], ...]]]:
        # rebuilt from root and formulas: the derived read-only maps do not pickle
        return (HSpec, (self.root, self.formulas))

    @property
    def names(self) -> tuple[str, ...]:
        """Formula names, root first, breadth-first."""
        return tuple(name for name, _ in self.formulas)

    @property
    def depth(self) -> int:
        """Number of levels (1 for a lone root)."""
        return len(self.levels)

    def formula(self, name: str) -> Formula:
        """The formula called ``name``."""
        try:
            return self._by_name[name]
        except KeyError:
            raise KeyError(f"no formula {name!r}; formulas are: {_listing(self.names)}") from None

    def level_of(self, name: str) -> int:
        """Depth of ``name`` (0 for the root)."""
        for k, layer in enumerate(self.levels):
            if name in layer:
                return k
        raise KeyError(f"no formula {name!r}; formulas are: {_listing(self.names)}")

    def is_leaf(self, name: str) -> bool:
        return not self.children[name]


MAX_LEVELS = 64  # far beyond any task a person states; keeps recursive passes bounded
MAX_FORMULAS = 2_000
MAX_NAME_CHARS = 64


def _check_tree(
    root: str, formulas: tuple[tuple[str, Formula], ...]
) -> tuple[dict[str, Formula], dict[str, tuple[str, ...]]]:
    """Rules 1-2: names, references, one parent each, no cycle, everything under the root."""
    by_name: dict[str, Formula] = {}
    for name, f in formulas:
        if not isinstance(name, str) or not _NAME.fullmatch(name):
            raise SpecValidationError(
                f"formula name {quote(name)} is not an identifier (letters, digits, _), e.g. p100"
            )
        if name in KEYWORDS or name in PREDICATES:
            raise SpecValidationError(
                f"formula name {quote(name)} is an operator or predicate name; use e.g. p100"
            )
        if len(name) > MAX_NAME_CHARS:
            raise SpecValidationError(
                f"formula name {quote(name, 40)} is too long (at most {MAX_NAME_CHARS} characters)"
            )
        if name in by_name:
            raise SpecValidationError(f"formula {name} is defined twice")
        by_name[name] = f
    if not by_name:
        raise SpecValidationError("the specification has no formulas")
    if len(by_name) > MAX_FORMULAS:
        raise SpecValidationError(
            f"the specification has {len(by_name):,} formulas; at most {MAX_FORMULAS:,}"
        )
    listing = _listing(by_name)
    if root not in by_name:
        raise SpecValidationError(f"root {quote(root)} is not a formula; formulas are: {listing}")

    children: dict[str, tuple[str, ...]] = {}
    for name, f in by_name.items():
        bare = [a.name for a in atoms_in_order(f) if not a.is_predicate]
        kids = tuple(n for n in bare if n in by_name)
        unknown = [n for n in bare if n not in by_name]
        if unknown and not kids:
            raise SpecValidationError(
                f"{name} refers to {quote(unknown[0])}, which is not a formula; formulas are: "
                f"{listing} (leaf formulas use predicate atoms: "
                f"{_listing(f'{p}(...)' for p in sorted(PREDICATES))})"
            )
        if unknown:
            raise SpecValidationError(
                f"{name} refers to {quote(unknown[0])}, which is not a formula; formulas are: "
                f"{listing}"
            )
        if name in kids:
            raise SpecValidationError(f"{name} refers to itself; the hierarchy must be a tree")
        children[name] = kids

    parents: dict[str, list[str]] = {}
    for name, kids in children.items():
        for c in kids:
            parents.setdefault(c, []).append(name)
    if root in parents:
        raise SpecValidationError(
            f"the root {root} has no parent, but {_and_list(parents[root])} refers to it"
        )
    for c, ps in parents.items():
        if len(ps) > 1:
            raise SpecValidationError(
                f"{c} is a child of both {ps[0]} and {ps[1]}; every formula except the root "
                "must appear in exactly one parent (rule 2: the hierarchy is a tree)"
            )

    reached = {root}
    stack = [root]
    while stack:
        for c in children[stack.pop()]:
            if c not in reached:
                reached.add(c)
                stack.append(c)
    for name in by_name:
        if name in reached:
            continue
        # with one parent each and a parentless root, an unreached node is either orphaned or
        # on a cycle of its own
        chain = [name]
        while chain[-1] in parents and parents[chain[-1]][0] not in chain:
            chain.append(parents[chain[-1]][0])
        if chain[-1] in parents:
            loop = chain[chain.index(parents[chain[-1]][0]) :]
            cycle = " -> ".join([*reversed(loop), loop[-1]])
            raise SpecValidationError(f"cycle: {cycle}; the hierarchy must be a tree")
        why = (
            "no formula refers to it"
            if len(chain) == 1
            else f"its ancestor {chain[-1]} is not referred to by any formula"
        )
        raise SpecValidationError(f"{name} is not reachable from the root {root}: {why}")
    return by_name, children


# ---------------------------------------------------------------------------------------------
# automaton-level checks


def validate_automata(spec: HSpec, cache: AutomatonCache | None = None) -> dict[str, DFA]:
    """Compile every formula and check it can be met; returns the DFAs by name.

    A leaf must be satisfiable. A composite must be satisfiable by a trace of its children's
    events where each child fires at most once (one-shot monitors), and, by rule 3, by such a
    trace where no two children fire in the same step. Precisely: with step cost
    ``max(0, children firing - 1)``, a cheapest accepting one-shot trace must cost 0. A formula
    like ``F (p100 & p200)`` costs 1 and is rejected; ``F p100 & F p200`` costs 0 (children may
    still finish together at run time). Composites with more than ``MAX_CHILDREN_CHECKED``
    children get the plain satisfiability check only.

    Raises:
        SpecValidationError: a formula is unsatisfiable or breaks rule 3; the message names it.
        AutomatonError, BackendUnavailableError: compiling failed.
    """
    cache = default_cache() if cache is None else cache
    dfas: dict[str, DFA] = {}
    for name, f in spec.formulas:
        dfa = cache.to_dfa(f)
        dfas[name] = dfa
        kids = spec.children[name]
        if dfa.is_empty():
            raise SpecValidationError(f"{name}: '{to_string(f)}' is unsatisfiable")
        if not kids or len(kids) > MAX_CHILDREN_CHECKED or isinstance(dfa, MonotoneDFA):
            # an and/or of "F child" never needs two children in one step: nothing to check
            continue
        found = _cheapest_one_shot_run(dfa, kids)
        if found is None:
            raise SpecValidationError(
                f"{name}: '{to_string(f)}' cannot be satisfied when each child completes once "
                "(children are one-shot events: a child's proposition is true in one step only)"
            )
        together = next((step for step in found if len(step) > 1), None)
        if together is not None:
            raise SpecValidationError(_rule3_message(name, f, together))
    return dfas


def _rule3_message(name: str, f: Formula, together: list[str]) -> str:
    both = " & ".join(f"F {c}" for c in together)
    ordered = f"F {together[-1]}"
    for c in reversed(together[:-1]):
        ordered = f"F ({c} & {ordered})"
    return (
        f"{name}: '{to_string(f)}' requires {_and_list(together)} to complete in the same step, "
        f"which rule 3 forbids (children complete independently); write '{both}' if all must "
        f"complete, or '{ordered}' for this order"
    )


def _cheapest_one_shot_run(dfa: DFA, kids: tuple[str, ...]) -> list[list[str]] | None:
    """Children firing per step along a cheapest accepting one-shot run, or None if none.

    Dijkstra over ``(dfa state, children done)`` with distance ``(cost, steps)``; a step fires any
    subset of the children not yet done (cost: how many beyond one) and any values of the other
    atoms. The empty trace is not a run, so the search starts with one step taken.
    """
    index = {a: i for i, a in enumerate(dfa.props)}
    kid_bits = [1 << index[Atom(c)] for c in kids]
    other_masks = [0]
    for i, a in enumerate(dfa.props):
        if a.is_predicate or a.name not in kids:
            other_masks += [m | 1 << i for m in other_masks]
    shift, table = len(dfa.props), dfa.table

    Node = tuple[int, int]
    best: dict[Node, tuple[int, int]] = {}
    back: dict[Node, tuple[Node | None, int]] = {}
    heap: list[tuple[int, int, int, int]] = []

    def relax(node: Node | None, q: int, done: int, cost: int, length: int) -> None:
        fired_sets = [0]
        for i in range(len(kid_bits)):
            if not done >> i & 1:
                fired_sets += [f | 1 << i for f in fired_sets]
        for fired in fired_sets:
            dist = (cost + max(0, fired.bit_count() - 1), length + 1)
            kid_mask = sum(bit for i, bit in enumerate(kid_bits) if fired >> i & 1)
            for om in other_masks:
                nxt = (table[(q << shift) | kid_mask | om], done | fired)
                if nxt not in best or dist < best[nxt]:
                    best[nxt] = dist
                    back[nxt] = (node, fired)
                    heapq.heappush(heap, (*dist, *nxt))

    relax(None, dfa.initial, 0, 0, 0)
    while heap:
        cost, length, q, done = heapq.heappop(heap)
        if best[(q, done)] != (cost, length):
            continue
        if q in dfa.accepting:
            steps: list[list[str]] = []
            node: Node | None = (q, done)
            while node is not None:
                node, fired = back[node]
                steps.append([c for i, c in enumerate(kids) if fired >> i & 1])
            return steps[::-1]
        relax((q, done), q, done, cost, length)
    return None


# ---------------------------------------------------------------------------------------------
# loading and saving


def _parse_named(name: str, text: object, source: str) -> Formula:
    if not isinstance(text, str):
        raise SpecValidationError(
            f"{source}: formula {name} must be a string, got {type(text).__name__} {text!r}"
        )
    try:
        return parse_formula(text)
    except SpecSyntaxError as exc:
        raise SpecSyntaxError(
            f"{source}: formula {name}: {exc}", text=exc.text, line=exc.line, column=exc.column
        ) from None


def _names_of(level: Mapping[Any, Any], where: str, source: str) -> None:
    for key in level:
        if not isinstance(key, str):
            raise SpecValidationError(
                f"{source}: {where}: formula name {key!r} must be a string such as p100"
            )


def _from_design(data: Mapping[Any, Any], source: str) -> tuple[str, list[tuple[str, Formula]]]:
    unknown = [k for k in data if k not in ("root", "formulas")]
    if unknown:
        raise SpecValidationError(
            f"{source}: unknown key {quote(unknown[0])}; a spec has 'root' and 'formulas'"
        )
    if "formulas" not in data:
        raise SpecValidationError(f"{source}: missing 'formulas' (a mapping of name to formula)")
    if "root" not in data:
        raise SpecValidationError(f"{source}: missing 'root' (the name of the top formula)")
    root, formulas = data["root"], data["formulas"]
    if not isinstance(root, str):
        raise SpecValidationError(f"{source}: 'root' must be a formula name, got {root!r}")
    if not isinstance(formulas, Mapping):
        raise SpecValidationError(
            f"{source}: 'formulas' must map names to formulas, got {type(formulas).__name__}"
        )
    _names_of(formulas, "formulas", source)
    return root, [(name, _parse_named(name, text, source)) for name, text in formulas.items()]


def _from_levels(data: list[Any], source: str) -> tuple[str, list[tuple[str, Formula]]]:
    if not data:
        raise SpecValidationError(f"{source}: the list of levels is empty")
    seen: dict[str, int] = {}
    parsed: list[tuple[str, Formula]] = []
    for k, level in enumerate(data, start=1):
        if not isinstance(level, Mapping):
            raise SpecValidationError(
                f"{source}: level {k} must map names to formulas, got {type(level).__name__}"
            )
        _names_of(level, f"level {k}", source)
        for name, text in level.items():
            if name in seen:
                raise SpecValidationError(
                    f"{source}: formula {name} is defined twice (levels {seen[name]} and {k})"
                )
            seen[name] = k
            parsed.append((name, _parse_named(name, text, source)))
    if len(data[0]) != 1:
        raise SpecValidationError(
            f"{source}: the first level holds the root alone; it has {len(data[0])} formulas"
        )
    return next(iter(data[0])), parsed


def _check_levels(spec: HSpec, listed: Mapping[str, int], source: str) -> None:
    for name, level in listed.items():
        if name != spec.root and listed[spec.parent[name]] != level - 1:
            raise SpecValidationError(
                f"{source}: {name} is listed in level {level} but its parent "
                f"{spec.parent[name]} is in level {listed[spec.parent[name]]}; a formula's "
                "children belong to the next level"
            )


def spec_from_dict(
    data: Any,
    source: str = "<spec>",
    *,
    cache: AutomatonCache | None = None,
    check_automata: bool = True,
) -> HSpec:
    """Build and validate a specification from plain data (parsed YAML or JSON).

    Two layouts are accepted: DESIGN.md's ``{"root": "p0", "formulas": {"p0": ..., ...}}`` and
    Luo & Liu's list of levels ``[{"p0": ...}, {"p100": ..., "p200": ...}, ...]`` whose first
    level holds the root alone (each formula's children are listed in the next level).

    Args:
        data: the parsed file content.
        source: what to call the input in error messages (usually the file name).
        cache: where to compile the automata (``default_cache()`` if None).
        check_automata: also compile every formula and check satisfiability and rule 3.

    Raises:
        SpecSyntaxError: a formula does not parse.
        SpecValidationError: the layout is wrong or a validity rule is broken; the message
            starts with ``source`` and names the formula.
    """
    if isinstance(data, Mapping):
        root, parsed = _from_design(data, source)
        listed: dict[str, int] | None = None
    elif isinstance(data, list):
        root, parsed = _from_levels(data, source)
        listed = {name: k for k, level in enumerate(data, 1) for name in level}
    else:
        raise SpecValidationError(
            f"{source}: a spec is a mapping {{root: p0, formulas: {{p0: ..., p100: ...}}}} or a "
            f"list of levels [{{p0: ...}}, {{p100: ..., p200: ...}}]; got {type(data).__name__}"
        )
    try:
        spec = HSpec(root, tuple(parsed))
        if listed is not None:
            _check_levels(spec, listed, source)
        if check_automata:
            validate_automata(spec, cache)
    except SpecValidationError as exc:
        message = str(exc)
        if message.startswith(f"{source}: "):
            raise
        raise SpecValidationError(f"{source}: {message}") from None
    return spec


def load_spec(
    path: str | Path, *, cache: AutomatonCache | None = None, check_automata: bool = True
) -> HSpec:
    """Load and validate a specification file (``.json``, else YAML); see ``spec_from_dict``.

    Raises:
        SpecValidationError: the file is missing or unreadable, or the spec is invalid; the
            message starts with the file name.
        SpecSyntaxError: a formula does not parse.
    """
    path = Path(path)
    data = load_file(path, "spec", SpecValidationError)
    return spec_from_dict(data, str(path), cache=cache, check_automata=check_automata)


def spec_to_dict(spec: HSpec) -> dict[str, Any]:
    """The spec in DESIGN.md's layout: ``{"root": ..., "formulas": {name: text}}``."""
    return {"root": spec.root, "formulas": {name: to_string(f) for name, f in spec.formulas}}


def spec_from_formulas(root: str, formulas: Mapping[str, str | Formula]) -> HSpec:
    """Build a spec from names to formulas (text or trees), checking the tree only."""
    items = tuple(
        (name, parse_formula(f) if isinstance(f, str) else f) for name, f in formulas.items()
    )
    return HSpec(root, items)
