"""The discrete model the closed-loop baselines plan and check against (docs/model.md)."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from hltl.execution.safety import step_conflict
from hltl.skills.library import Action, Transition, step_symbol
from hltl.skills.semantics import ActionSemantics, Infeasible, InfeasibleKind, apply_all
from hltl.spec.monitor import DONE, HierarchyMonitor, MonitorState
from hltl.spec.syntax import Atom
from hltl.world.scene import Scene
from hltl.world.state import WorldState

ViolationKind = InfeasibleKind


@dataclass(frozen=True, slots=True)
class Violation:
    """An action the feasibility check refused (``None``: two actions of one step share a
    robot or an object, a ``conflict``); ``kind`` as in :class:`~hltl.skills.semantics.Infeasible`.
    """

    action: Action | None
    kind: ViolationKind
    reason: str


def check_step(actions: Sequence[Action], scene: Scene, world: WorldState) -> list[Violation]:
    """Every reason the step may not be dispatched in ``world`` (empty: it may)."""
    sem = ActionSemantics.of(scene)
    out: list[Violation] = []
    clash = step_conflict(actions)
    if clash is not None:
        out.append(Violation(None, "conflict", clash))
    for a in actions:
        tr = sem.transition(a, world)
        if isinstance(tr, Infeasible):
            out.append(Violation(a, tr.kind, tr.reason))
    return out


def apply_step(
    actions: Sequence[Action], scene: Scene, world: WorldState
) -> tuple[WorldState, frozenset[Atom], list[Action]]:
    """The world after the step's feasible actions and the step's symbol; also the actions
    that were infeasible (and so did nothing)."""
    sem = ActionSemantics.of(scene)
    trs: list[Transition] = []
    bad: list[Action] = []
    for a in actions:
        tr = sem.transition(a, world)
        if isinstance(tr, Infeasible):
            bad.append(a)
        else:
            trs.append(tr)
    w = apply_all(world, trs)
    return w, step_symbol(trs, w), bad


class Liveness:
    """Which monitor states can still reach acceptance (a dead state means the task is lost,
    e.g. the second of two ordered deliveries done first).

    A node is alive when its DFA can reach an accepting state on symbols in which none of its
    already-done children fires again (children are one-shot); the monitor state is alive when
    every unfinished node is.
    """

    def __init__(self, monitor: HierarchyMonitor) -> None:
        self.monitor = monitor
        self._cache: dict[tuple[str, int, int], bool] = {}
        self._child_bit: dict[str, dict[str, int]] = {
            name: {a.name: 1 << i for i, a in enumerate(dfa.props) if not a.is_predicate}
            for name, dfa in monitor.dfas.items()
        }

    def _node_alive(self, name: str, state: int, forbidden: int) -> bool:
        key = (name, state, forbidden)
        hit = self._cache.get(key)
        if hit is not None:
            return hit
        dfa = self.monitor.dfas[name]
        k = len(dfa.props)
        masks = [m for m in range(1 << k) if not m & forbidden]
        seen, stack, ok = {state}, [state], False
        while stack and not ok:
            s = stack.pop()
            for m in masks:
                t = dfa.table[(s << k) | m]
                if t in dfa.accepting:
                    ok = True
                    break
                if t not in seen:
                    seen.add(t)
                    stack.append(t)
        self._cache[key] = ok
        return ok

    def alive(self, q: MonitorState) -> bool:
        done = self.monitor.done(q)
        for name, s in zip(self.monitor.nodes, q, strict=True):
            if s == DONE:
                continue
            forbidden = 0
            for child, bit in self._child_bit[name].items():
                if child in done:
                    forbidden |= bit
            if not self._node_alive(name, s, forbidden):
                return False
        return True
