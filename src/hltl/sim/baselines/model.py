"""The discrete model the closed-loop baselines plan and check against (docs/model.md).

Baselines propose ground skill instances (:class:`~hltl.skills.library.Action`); everything here
decides with the shared library: :func:`~hltl.skills.library.check_action` for Pre(s, ℓ, a),
:func:`~hltl.skills.library.ground` for Post.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Literal

from hltl.execution.safety import step_conflict
from hltl.skills.library import Action, Situation, Transition, check_action, ground, step_symbol
from hltl.spec.monitor import DONE, HierarchyMonitor, MonitorState
from hltl.spec.syntax import Atom
from hltl.world.scene import Scene
from hltl.world.state import ObjectStatus, WorldState

ViolationKind = Literal["kinematic", "conflict"]


@dataclass(frozen=True, slots=True)
class Violation:
    """An action the feasibility check refused.

    ``kinematic``: no instance of the skill exists for these robots and arguments in the
    current situation (out of reach, person outside the workspace, robots that cannot meet or
    whose rendezvous a person blocks, a robot that is down). ``conflict``: the instance exists
    but the state forbids it (the object is held by another robot or already gone, the receiver
    already holds something, two actions of one step share a robot or an object): the paper's
    shared-object conflicts.
    """

    action: Action | None
    kind: ViolationKind
    reason: str


def transition_of(action: Action, scene: Scene, world: WorldState) -> Transition | None:
    """Post(s, a) when Pre(s, ℓ, a) holds in ``world``, else None."""
    if check_action(action, scene, world) is not None:
        return None
    loc = world.object_status(action.object).loc
    for a, tr in ground(Situation.of(scene, world)):
        if a == action and tr.pre == loc:
            return tr
    return None  # pragma: no cover - check_action passed, so an instance exists


def classify(action: Action, scene: Scene, world: WorldState) -> ViolationKind:
    """Why an action fails its check: geometry (kinematic) or possession (conflict).

    Kinematic: no instance of the skill exists for these robots and arguments where the object
    is now (out of reach, outside the workspace, robots that cannot meet). Conflict: the
    geometry allows it but the object is held by another robot or gone, or a robot that must
    be free holds something.
    """
    loc = world.object_status(action.object).loc
    matches = [t for a, t in ground(Situation.of(scene, world)) if a == action]
    if not matches:
        return "kinematic"
    if any(t.pre == loc for t in matches):
        return "conflict"
    if action.skill == "pick" and loc.kind in ("rest", "on"):
        return "kinematic"  # it could pick it elsewhere, not where it lies
    return "conflict"


def check_step(actions: Sequence[Action], scene: Scene, world: WorldState) -> list[Violation]:
    """Every reason the step may not be dispatched in ``world`` (empty: it may)."""
    out: list[Violation] = []
    clash = step_conflict(actions)
    if clash is not None:
        out.append(Violation(None, "conflict", clash))
    for a in actions:
        reason = check_action(a, scene, world)
        if reason is not None:
            out.append(Violation(a, classify(a, scene, world), reason))
    return out


def apply_step(
    actions: Sequence[Action], scene: Scene, world: WorldState
) -> tuple[WorldState, frozenset[Atom], list[Action]]:
    """The world after the step's feasible actions and the step's symbol; also the actions
    that were infeasible (and so did nothing)."""
    trs: list[Transition] = []
    bad: list[Action] = []
    for a in actions:
        tr = transition_of(a, scene, world)
        if tr is None:
            bad.append(a)
        else:
            trs.append(tr)
    w = world
    for tr in trs:
        pos = tr.hands[-1][1] if tr.hands else w.object_status(tr.obj).position
        w = w.with_object(tr.obj, ObjectStatus(pos, tr.post))
        for rid, p in tr.hands:
            w = w.with_hand(rid, p)
    return w, symbol_of(trs, w), bad


symbol_of = step_symbol  # the same symbol the executor feeds its monitors


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
