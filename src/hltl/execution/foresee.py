"""The executor's next steps foreseen from its basis, on a world a driver simulates ahead."""

from __future__ import annotations

from collections.abc import Sequence

from hltl.execution.drivers import Basis
from hltl.planner import PlanStatus
from hltl.skills.library import Action, step_symbol
from hltl.skills.semantics import ActionSemantics, Infeasible, apply
from hltl.spec.monitor import HierarchyMonitor, MonitorState
from hltl.world.scene import Scene
from hltl.world.state import WorldState


def foresee_steps(
    scene: Scene, basis: Basis, monitor: HierarchyMonitor, world: WorldState
) -> tuple[tuple[Action, ...], ...]:
    """The steps the executor's replan dispatches from ``world`` (its basis's spec and monitor
    state, its planner): the plan's steps' actions, in order; empty when the spec is accepted
    there or the planner finds no plan. A guess only: the executor may take over a plan it
    predicted, or hold an action back."""
    if monitor.accepted(basis.q):
        return ()
    planner = basis.planner
    if not callable(planner):
        return ()
    result = planner(scene, basis.spec, world=world, monitor=monitor, q0=basis.q)
    if result.status is not PlanStatus.SOLVED:
        return ()
    return tuple(tuple(s.actions) for s in result.steps)


def after_step(
    semantics: ActionSemantics,
    monitor: HierarchyMonitor,
    q: MonitorState,
    world: WorldState,
    actions: Sequence[Action],
) -> MonitorState | None:
    """The monitor state after ``actions``, started together in ``world``, all end as planned
    (as the executor steps its monitor at a step's end); ``None`` when one cannot run there."""
    transitions = []
    w = world
    for a in actions:
        tr = semantics.transition(a, world)
        if isinstance(tr, Infeasible):
            return None
        transitions.append(tr)
    for tr in transitions:
        w = apply(w, tr)
    return monitor.step(q, step_symbol(transitions, w))
