"""The discrete planning model of docs/model.md, re-implemented for the oracles only.

Nothing here imports the planner, the skill library or ``hltl.world.geometry``: the oracles must
fail when those disagree with docs/model.md, so they cannot share code with them.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any

from hltl.spec.syntax import Atom, Formula
from hltl.world.scene import Human, Robot, Scene

# Distances are compared with this slack so that a point exactly at the reach radius counts as
# reachable whatever the rounding; generated instances keep well away from such boundaries.
EPS = 1e-9

SKILLS = ("pick", "place", "handover_r2r", "handover_r2h")
ROBOTS_PER_SKILL = {"pick": 1, "place": 1, "handover_r2r": 2, "handover_r2h": 1}
ROLES = frozenset({"solo", "giver", "receiver", "relay"})

# Where an object is: ("rest", "") where the scene put it, ("held", robot), ("on", surface),
# ("delivered", human).
Location = tuple[str, str]
REST: Location = ("rest", "")


# -- geometry -------------------------------------------------------------------------------------


def reaches(robot: Robot, point: Sequence[float]) -> bool:
    return math.dist(robot.base, point) <= robot.reach + EPS


def human_inside(robot: Robot, human: Human, human_reach: float) -> bool:
    dh = math.hypot(robot.base[0] - human.position[0], robot.base[1] - human.position[1])
    return dh <= robot.reach + human_reach + EPS


def can_meet(giver: Robot, receiver: Robot) -> bool:
    return giver.id != receiver.id and math.dist(giver.base, receiver.base) < (
        giver.reach + receiver.reach
    )


def rendezvous_blocked(scene: Scene, a: Robot, b: Robot) -> bool:
    return any(
        human_inside(a, h, scene.human_reach) and human_inside(b, h, scene.human_reach)
        for h in scene.humans
    )


def can_hand_over(scene: Scene, giver: Robot, receiver: Robot) -> bool:
    """Static part of handover_r2r's precondition: the pair can meet and nobody blocks them."""
    return can_meet(giver, receiver) and not rendezvous_blocked(scene, giver, receiver)


# docs/model.md: an object on a surface has its point this high above the surface's centre
SURFACE_LIFT = 0.05


def surface_point(scene: Scene, sid: str) -> tuple[float, float, float]:
    """Where a hand places an object on surface ``sid`` or picks one from it."""
    x, y, z = scene.surface(sid).center
    return (x, y, z + SURFACE_LIFT)


def point_of(scene: Scene, oid: str, loc: Location) -> tuple[float, float, float] | None:
    """The point a robot must reach to pick ``oid`` at ``loc``; None when it cannot be picked."""
    kind, where = loc
    if kind == "rest":
        return scene.object(oid).position
    if kind == "on":
        return surface_point(scene, where)
    return None


# -- state and symbols ----------------------------------------------------------------------------


def initial_locations(scene: Scene) -> tuple[Location, ...]:
    return tuple(REST for _ in scene.objects)


def state_atoms(scene: Scene, locs: Sequence[Location]) -> frozenset[Atom]:
    """``holding(r, o)`` and ``at(o, s)`` atoms of a state (objects in scene order)."""
    out: set[Atom] = set()
    for obj, (kind, where) in zip(scene.objects, locs, strict=True):
        if kind == "held":
            out.add(Atom("holding", (where, obj.id)))
        elif kind == "on":
            out.add(Atom("at", (obj.id, where)))
    return frozenset(out)


def event_atom(action: Mapping[str, Any]) -> Atom | None:
    skill = action["skill"]
    if skill == "pick":
        return Atom("picked", (action["object"],))
    if skill == "place":
        return Atom("placed", (action["object"], action["surface"]))
    if skill == "handover_r2h":
        return Atom("delivered", (action["object"], action["human"]))
    return None


def effect(action: Mapping[str, Any]) -> Location:
    """Where the action leaves its object."""
    skill, robots = action["skill"], action["robots"]
    if skill == "pick":
        return ("held", robots[0])
    if skill == "place":
        return ("on", action["surface"])
    if skill == "handover_r2r":
        return ("held", robots[1])
    return ("delivered", action["human"])


# -- the hierarchy --------------------------------------------------------------------------------


@dataclass(frozen=True)
class Hierarchy:
    """The parts of an HSpec the oracles need, read once through its public attributes."""

    root: str
    formulas: Mapping[str, Formula]
    children: Mapping[str, tuple[str, ...]]
    leaves: tuple[str, ...]

    def bottom_up(self) -> list[str]:
        """Every node after all of its children."""
        order: list[str] = []

        def visit(name: str) -> None:
            for c in self.children.get(name, ()):
                visit(c)
            order.append(name)

        visit(self.root)
        return order


def hierarchy(spec: Any) -> Hierarchy:
    """Read an ``HSpec`` (``formulas`` are ``(name, formula)`` pairs, ``children`` a mapping)."""
    formulas = dict(spec.formulas)
    children = {name: tuple(spec.children[name]) for name in formulas}
    return Hierarchy(spec.root, formulas, children, tuple(spec.leaves))


def formula_atoms(f: Formula) -> frozenset[Atom]:
    """Every atom in ``f`` (own walk over the syntax tree, so the oracle needs no printer)."""
    if isinstance(f, Atom):
        return frozenset({f})
    out: frozenset[Atom] = frozenset()
    for name in ("operand", "left", "right"):
        sub = getattr(f, name, None)
        if sub is not None:
            out |= formula_atoms(sub)
    return out


def mentions(f: Formula, oid: str) -> bool:
    return any(oid in a.args for a in formula_atoms(f))


def fired_children(names: Iterable[str]) -> frozenset[Atom]:
    return frozenset(Atom(n) for n in names)


def fire_steps(h: Hierarchy, symbols: Sequence[frozenset[Atom]]) -> dict[str, int | None]:
    """The step at which each node fires, by the direct LTLf evaluator (not the DFA monitor).

    A node fires at the first step ``i`` such that its formula holds on its own trace
    ``[0..i]``. A leaf's trace is the step symbols; a composite's trace holds, at step ``j``,
    ``Atom(child)`` for each child that fired at ``j`` (plus the step symbol, for the rare atom
    used higher up: DESIGN.md §4 rule 1).
    """
    from hltl.spec.semantics import evaluate

    n = len(symbols)
    fired: dict[str, int | None] = {}
    for name in h.bottom_up():
        kids = h.children[name]
        if kids:
            trace = [
                fired_children(c for c in kids if fired[c] == j) | symbols[j] for j in range(n)
            ]
        else:
            trace = list(symbols)
        formula = h.formulas[name]
        fired[name] = next((i for i in range(n) if evaluate(formula, trace[: i + 1])), None)
    return fired
