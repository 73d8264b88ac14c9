"""H-LTLf monitors: one DFA per node, one-shot firing, events propagated bottom-up in one step."""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from collections.abc import Set as AbstractSet
from typing import TypeAlias

from hltl.spec.automata import DFA, AutomatonCache, default_cache
from hltl.spec.hierarchy import HSpec
from hltl.spec.printer import atoms
from hltl.spec.syntax import Atom

# One int per node in ``HierarchyMonitor.nodes`` order: the node's DFA state, or DONE once the
# node has fired. Plain tuples hash fast and are what the planner keeps in every search node.
MonitorState: TypeAlias = tuple[int, ...]

DONE = -1


class HierarchyMonitor:
    """Runs the monitors of every node of an H-LTLf spec on the symbols of a plan (docs/model.md).

    A step reads the set of predicate atoms true in that step. Each leaf steps its DFA on its own
    atoms; then, deepest nodes first, each composite steps its DFA on the set of its children
    that fired in this same step (as atoms ``Atom(child)``) plus any predicate atoms it mentions.
    A node *fires* in the first step after which its DFA is in an accepting state (even if its
    initial state is accepting: it still needs one step); it is then done and never steps or
    fires again. The spec is accepted when the root has fired.

    Attributes:
        spec: the specification.
        nodes: node names in state order (``spec.formulas`` order: root first, breadth-first).
        dfas: each node's DFA.
        leaf_atoms: each leaf's predicate atoms.
        initial: the state before any step.
    """

    def __init__(self, spec: HSpec, cache: AutomatonCache | None = None) -> None:
        cache = default_cache() if cache is None else cache
        self.spec = spec
        self.nodes: tuple[str, ...] = spec.names
        self.dfas: dict[str, DFA] = {name: cache.to_dfa(f) for name, f in spec.formulas}
        self.leaf_atoms: dict[str, frozenset[Atom]] = {
            name: frozenset(a for a in atoms(spec.formula(name)) if a.is_predicate)
            for name in spec.leaves
        }
        self.initial: MonitorState = tuple(self.dfas[n].initial for n in self.nodes)
        self._root = self.nodes.index(spec.root)
        index = {n: i for i, n in enumerate(self.nodes)}

        # atom -> ((node index, bit), ...): one dict lookup per true atom builds every node's mask
        bits: dict[Atom, list[tuple[int, int]]] = {}
        for i, name in enumerate(self.nodes):
            for b, a in enumerate(self.dfas[name].props):
                if a.is_predicate:
                    bits.setdefault(a, []).append((i, 1 << b))
        self._atom_bits: dict[Atom, tuple[tuple[int, int], ...]] = {
            a: tuple(v) for a, v in bits.items()
        }
        self.atoms: frozenset[Atom] = frozenset(self._atom_bits)

        # per node, deepest first: (index, shift, table, accepting flags, parent index, bit the
        # node sets in its parent's mask when it fires)
        plan: list[tuple[int, int, Sequence[int], AbstractSet[int], int, int]] = []
        for name in reversed(self.nodes):
            dfa = self.dfas[name]
            parent = spec.parent.get(name)
            if parent is None:
                p_index, p_bit = -1, 0
            else:
                p_index = index[parent]
                p_bit = 1 << self.dfas[parent].props.index(Atom(name))
            plan.append((index[name], len(dfa.props), dfa.table, dfa.accepting, p_index, p_bit))
        self._plan = tuple(plan)

    # -- stepping ------------------------------------------------------------------------------

    def masks(self, true_atoms: Iterable[Atom]) -> list[int]:
        """Per node (``nodes`` order), the bits of the predicate atoms in ``true_atoms``.

        With ``step_masks`` this splits ``step`` so that a caller can build masks once per
        symbol (or combine masks of independent events with ``|``) and step many states.
        """
        masks = [0] * len(self.nodes)
        get = self._atom_bits.get
        for a in true_atoms:
            for i, bit in get(a, ()):
                masks[i] |= bit
        return masks

    def step_masks(self, q: MonitorState, masks: Sequence[int]) -> MonitorState:
        """``step`` on precomputed atom masks (see ``masks``); ``masks`` is not modified."""
        cur = list(masks)
        new = list(q)
        for i, shift, table, accepting, p_index, p_bit in self._plan:
            s = q[i]
            if s == DONE:
                continue
            t = table[(s << shift) | cur[i]]
            if t in accepting:
                new[i] = DONE
                if p_index >= 0:
                    cur[p_index] |= p_bit
            else:
                new[i] = t
        return tuple(new)

    def step(self, q: MonitorState, true_atoms: Iterable[Atom]) -> MonitorState:
        """The monitor state after one step in which exactly ``true_atoms`` hold.

        Args:
            q: the state before the step.
            true_atoms: the step's symbol: event atoms of its skills plus the state atoms after
                it. Atoms that no formula mentions are ignored.
        """
        return self.step_masks(q, self.masks(true_atoms))

    def run(self, trace: Iterable[Iterable[Atom]], q: MonitorState | None = None) -> MonitorState:
        """The state after reading ``trace`` from ``q`` (default: ``initial``)."""
        state = self.initial if q is None else q
        for symbol in trace:
            state = self.step(state, symbol)
        return state

    # -- reading states ------------------------------------------------------------------------

    def accepted(self, q: MonitorState) -> bool:
        """Whether the root has fired: the task is complete."""
        return q[self._root] == DONE

    def done(self, q: MonitorState) -> frozenset[str]:
        """Names of the nodes that have fired."""
        return frozenset(n for n, s in zip(self.nodes, q, strict=True) if s == DONE)

    def fired(self, q_before: MonitorState, q_after: MonitorState) -> frozenset[str]:
        """Names of the nodes that fired in the step from ``q_before`` to ``q_after``."""
        return frozenset(
            n
            for n, a, b in zip(self.nodes, q_before, q_after, strict=True)
            if a != DONE and b == DONE
        )

    def state_of(self, q: MonitorState, name: str) -> int | None:
        """The DFA state of node ``name`` in ``q``, or None once it has fired."""
        s = q[self.nodes.index(name)]
        return None if s == DONE else s


def carry_over(
    old_spec: HSpec,
    old_state: MonitorState,
    new_spec: HSpec,
    cache: AutomatonCache | None = None,
) -> MonitorState:
    """The monitor state of ``new_spec`` that continues ``old_state`` of ``old_spec``.

    A formula with the same name and text keeps its state; if one of its children became done
    through the update (a group whose open child was cancelled), it steps once on those children.
    A new or edited formula starts from its initial state and replays its done children one step
    each, in the order they appear in its text (the order of the grounding conventions: a
    sequence lists its children in the order they must complete). Done formulas stay done.
    """
    old_m = HierarchyMonitor(old_spec, cache)
    new_m = HierarchyMonitor(new_spec, cache)
    old_texts = dict(old_spec.formulas)
    done_old = old_m.done(old_state)
    done_new: set[str] = set()
    states: dict[str, int] = {}
    for name in reversed(new_m.nodes):  # breadth-first reversed: children before parents
        dfa = new_m.dfas[name]
        kids = new_spec.children[name]
        same = old_texts.get(name) == new_spec.formula(name)
        if name in done_old:
            states[name] = DONE
            done_new.add(name)
            continue
        if same:
            s = old_m.state_of(old_state, name)
            assert s is not None
            newly = [k for k in kids if k in done_new and k not in done_old]
            steps: list[list[str]] = [newly] if newly else []
        else:
            s = dfa.initial
            steps = [[k] for k in kids if k in done_new]
        for symbol in steps:
            s = dfa.step(s, [Atom(k) for k in symbol])
            if dfa.is_accepting(s):
                s = DONE
                break
        states[name] = s
        if s == DONE:
            done_new.add(name)
    return tuple(states[n] for n in new_m.nodes)
