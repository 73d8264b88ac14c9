"""Greedy-R: nearest-robot allocation along the shortest handover chain, no LLM, no search."""

from __future__ import annotations

import itertools
from collections import deque
from dataclasses import dataclass

from hltl.bench.baselines.model import Liveness, apply_step
from hltl.bench.baselines.policy import PlanContext, Script
from hltl.skills.library import Action
from hltl.skills.semantics import check_action
from hltl.spec.hierarchy import HSpec
from hltl.spec.monitor import MonitorState
from hltl.spec.printer import atoms
from hltl.spec.syntax import Atom
from hltl.world.geometry import Context, can_meet, distance, reaches
from hltl.world.scene import Robot, Scene
from hltl.world.state import WorldState

MAX_STEPS = 200


@dataclass(slots=True)
class _Task:
    leaf: str
    obj: str
    actions: list[Action]
    robots: tuple[str, ...]
    pos: int = 0
    started: bool = False


def chain(
    scene: Scene, world: WorldState, context: Context, obj: str, target: tuple[str, str]
) -> tuple[str, ...] | None:
    """The shortest chain of available robots from ``obj`` (where it is now) to the target
    (``("delivered", person)`` or ``("placed", surface)``); None when there is none."""
    avail = [r for r in scene.robots if r.id not in world.unavailable]
    st = world.object_status(obj)
    if st.loc.kind == "held":
        starts = [r for r in avail if r.id == st.loc.ref]
    elif st.loc.kind in ("rest", "on"):
        point = st.position if st.loc.kind == "rest" else scene.surface(st.loc.ref).object_point
        starts = sorted(
            (r for r in avail if reaches(r, point)), key=lambda r: (distance(r.base, point), r.id)
        )
    else:
        return None
    kind, ref = target
    if kind == "delivered":
        serving = context.robots_serving(ref)
        goal = {r.id for r in avail if r.id in serving}
    else:
        goal = {r.id for r in avail if reaches(r, scene.surface(ref).object_point)}
    previous: dict[str, str | None] = {r.id: None for r in starts}
    queue: deque[Robot] = deque(starts)
    while queue:
        here = queue.popleft()
        if here.id in goal:
            out = [here.id]
            while (p := previous[out[-1]]) is not None:
                out.append(p)
            return tuple(reversed(out))
        for other in sorted(avail, key=lambda r: (distance(here.base, r.base), r.id)):
            if (
                other.id not in previous
                and can_meet(here, other)
                and not context.blocked(here.id, other.id)
            ):
                previous[other.id] = here.id
                queue.append(other)
    return None


def _depth_first_leaves(spec: HSpec) -> list[str]:
    """Leaves in the order a person reads the spec (depth first), which is the priority order."""
    out: list[str] = []

    def visit(name: str) -> None:
        kids = spec.children[name]
        if not kids:
            out.append(name)
        for k in kids:
            visit(k)

    visit(spec.root)
    return out


def _enabled(ctx: PlanContext, live: Liveness, q: MonitorState, w: WorldState, t: _Task) -> bool:
    """Whether finishing the task now keeps the task satisfiable (its predecessors are done)."""
    final = t.actions[-1]
    event = (
        Atom("delivered", (t.obj, final.human or ""))
        if final.skill == "handover_r2h"
        else Atom("placed", (t.obj, final.surface or ""))
    )
    return live.alive(ctx.monitor.step(q, {event}))


def _target(ctx: PlanContext, leaf: str) -> tuple[str, str, str] | None:
    """(object, kind, person or surface) of a delivery or placement leaf."""
    for a in sorted(atoms(ctx.spec.formula(leaf))):
        if a.name in ("delivered", "placed") and len(a.args) == 2:
            return a.args[0], a.name, a.args[1]
    return None


class GreedyPolicy:
    """Greedy-R (see the module docstring)."""

    name = "greedy"
    replan_on_context = True

    def plan(self, ctx: PlanContext) -> Script:
        scene, world = ctx.scene, ctx.world
        context = world.context(scene)
        tasks: list[_Task] = []
        for leaf in _depth_first_leaves(ctx.spec):
            if leaf in ctx.done:
                continue
            tgt = _target(ctx, leaf)
            if tgt is None:
                continue
            obj, kind, ref = tgt
            if world.object_status(obj).loc.kind == "delivered":
                continue
            robots = chain(scene, world, context, obj, (kind, ref))
            if robots is None:
                continue
            acts: list[Action] = []
            if world.object_status(obj).loc.kind != "held":
                acts.append(Action("pick", (robots[0],), obj))
            acts += [Action("handover_r2r", (g, r), obj) for g, r in itertools.pairwise(robots)]
            if kind == "delivered":
                acts.append(Action("handover_r2h", (robots[-1],), obj, human=ref))
            else:
                acts.append(Action("place", (robots[-1],), obj, surface=ref))
            tasks.append(_Task(leaf, obj, acts, robots))

        live = Liveness(ctx.monitor)
        owner: dict[str, str] = {}
        for t in tasks:  # a robot holding a task's object is that task's already
            holder = world.object_status(t.obj).loc
            if holder.kind == "held":
                owner[holder.ref] = t.leaf
                t.started = True
                for r in t.robots:
                    owner.setdefault(r, t.leaf)
        w, q = world, ctx.q
        steps: list[tuple[Action, ...]] = []
        for _ in range(MAX_STEPS):
            remaining = [t for t in tasks if t.pos < len(t.actions)]
            if not remaining:
                break
            chosen: list[tuple[_Task, Action]] = []
            used: set[str] = set()
            for t in remaining:
                if not t.started:
                    if not _enabled(ctx, live, q, w, t):
                        continue
                    if any(owner.get(r, t.leaf) != t.leaf for r in t.robots):
                        continue
                    if any(w.holding(r) not in (None, t.obj) for r in t.robots):
                        continue
                    for r in t.robots:
                        owner[r] = t.leaf
                    t.started = True
                a = t.actions[t.pos]
                if used & set(a.robots) or check_action(a, scene, w) is not None:
                    continue
                chosen.append((t, a))
                used |= set(a.robots)
            # an action that would make the task unsatisfiable (ordering) waits
            while chosen:
                w2, symbol, _ = apply_step([a for _, a in chosen], scene, w)
                q2 = ctx.monitor.step(q, symbol)
                if live.alive(q2):
                    break
                finals = [k for k, (t, _) in enumerate(chosen) if t.pos == len(t.actions) - 1]
                if not finals:
                    chosen = []
                    break
                chosen.pop(finals[-1])
            if not chosen:
                break
            for t, a in chosen:
                t.pos += 1
                if a.skill == "handover_r2r" or t.pos == len(t.actions):
                    giver = a.robots[0]
                    if owner.get(giver) == t.leaf:
                        del owner[giver]
                if t.pos == len(t.actions):
                    for r in t.robots:
                        if owner.get(r) == t.leaf:
                            del owner[r]
            steps.append(tuple(a for _, a in chosen))
            w, q = w2, q2
        return Script(tuple(steps))
