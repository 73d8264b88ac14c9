"""Skill library J: pick, place, handover_r2r, handover_r2h; Pre, Post, events and durations.

A skill grounds itself into instances for a :class:`Situation` (the scene, where the objects
rest, the context ℓ and the available robots). Each instance pairs an :class:`Action` (what a
plan says and a driver executes) with a :class:`Transition` (what it does to the discrete state).
The situation-dependent part of Pre (reach, workspaces, rendezvous) decides which instances exist;
the state-dependent part (the object is at ``pre``, the robots in ``free`` hold nothing) is
checked against the joint state. A new skill is one class with ``name`` and ``instances``.
"""

from __future__ import annotations

from abc import ABC, abstractmethod
from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any, ClassVar

from hltl.errors import PlanFormatError
from hltl.spec.syntax import Atom
from hltl.world.geometry import (
    Context,
    can_meet,
    context_label,
    human_handover_point,
    reaches,
    rendezvous_point,
)
from hltl.world.scene import Robot, Scene, Vec3
from hltl.world.state import REST, Loc, WorldState, initial_world


@dataclass(frozen=True, slots=True, order=True)
class Action:
    """A ground skill instance: skill name, robots in role order (giver first), its arguments."""

    skill: str
    robots: tuple[str, ...]
    object: str
    human: str | None = None
    surface: str | None = None

    def to_dict(self) -> dict[str, Any]:
        d: dict[str, Any] = {
            "skill": self.skill,
            "robots": list(self.robots),
            "object": self.object,
        }
        if self.human is not None:
            d["human"] = self.human
        if self.surface is not None:
            d["surface"] = self.surface
        return d

    @classmethod
    def from_dict(cls, data: Mapping[str, Any]) -> Action:
        try:
            return cls(
                skill=str(data["skill"]),
                robots=tuple(str(r) for r in data["robots"]),
                object=str(data["object"]),
                human=None if data.get("human") is None else str(data["human"]),
                surface=None if data.get("surface") is None else str(data["surface"]),
            )
        except (KeyError, TypeError) as exc:
            raise PlanFormatError(
                f"action {dict(data)!r} is malformed: expected skill, robots and object ({exc})"
            ) from None

    def __str__(self) -> str:
        args = [self.object] + [x for x in (self.human, self.surface) if x is not None]
        return f"{self.skill}({', '.join(args)}) by {'→'.join(self.robots)}"


@dataclass(frozen=True, slots=True)
class Transition:
    """Post(s, a) for one object: it moves from ``pre`` to ``post``; robots in ``free`` must hold
    nothing before the step; ``events`` are the atoms the step makes true; ``hands`` says where
    each executor's hand ends up."""

    obj: str
    pre: Loc
    post: Loc
    free: tuple[str, ...]
    events: frozenset[Atom]
    hands: tuple[tuple[str, Vec3], ...]


@dataclass(frozen=True, slots=True)
class Situation:
    """What grounding depends on: the scene, where objects rest now, ℓ(w), available robots."""

    scene: Scene
    rest: tuple[tuple[str, Vec3], ...]
    context: Context
    available: tuple[Robot, ...]
    objects: tuple[str, ...] = field(default=())
    humans: tuple[tuple[str, Vec3], ...] = field(default=())  # where people stand now

    @classmethod
    def of(cls, scene: Scene, world: WorldState | None = None) -> Situation:
        w = initial_world(scene) if world is None else world
        rest = tuple((oid, st.position) for oid, st in w.objects)
        return cls(
            scene=scene,
            rest=rest,
            context=context_label(scene, w.humans),
            available=tuple(r for r in scene.robots if r.id not in w.unavailable),
            objects=tuple(oid for oid, _ in w.objects),
            humans=w.humans,
        )

    def human_position(self, hid: str) -> Vec3:
        for k, v in self.humans:
            if k == hid:
                return v
        return self.scene.human(hid).position

    def rest_position(self, oid: str) -> Vec3:
        for k, v in self.rest:
            if k == oid:
                return v
        return self.scene.object(oid).position


class Skill(ABC):
    """A skill of the library. Subclasses set ``name`` and ground their instances."""

    name: ClassVar[str]
    #: number of robots executing one instance
    arity: ClassVar[int] = 1

    @abstractmethod
    def instances(self, sit: Situation) -> Iterator[tuple[Action, Transition]]:
        """All ground instances whose situation-dependent preconditions hold in ``sit``."""


class Pick(Skill):
    """pick(o) by r: r free, o resting or on a surface within r's reach → r holds o."""

    name = "pick"

    def instances(self, sit: Situation) -> Iterator[tuple[Action, Transition]]:
        for oid in sit.objects:
            sources: list[tuple[Loc, Vec3]] = [(REST, sit.rest_position(oid))]
            sources += [(Loc("on", s.id), s.center) for s in sit.scene.surfaces]
            for r in sit.available:
                for loc, point in sources:
                    if reaches(r, point):
                        yield (
                            Action("pick", (r.id,), oid),
                            Transition(
                                oid,
                                loc,
                                Loc("held", r.id),
                                (r.id,),
                                frozenset({Atom("picked", (oid,))}),
                                ((r.id, point),),
                            ),
                        )


class Place(Skill):
    """place(o, s) by r: r holds o, s within r's reach → o on s, r free."""

    name = "place"

    def instances(self, sit: Situation) -> Iterator[tuple[Action, Transition]]:
        for oid in sit.objects:
            for r in sit.available:
                for s in sit.scene.surfaces:
                    if reaches(r, s.center):
                        yield (
                            Action("place", (r.id,), oid, surface=s.id),
                            Transition(
                                oid,
                                Loc("held", r.id),
                                Loc("on", s.id),
                                (),
                                frozenset({Atom("placed", (oid, s.id))}),
                                ((r.id, s.center),),
                            ),
                        )


class HandoverR2R(Skill):
    """handover_r2r(o; g, r): g holds o, r free, spheres overlap, nobody inside both workspaces
    → r holds o, g free."""

    name = "handover_r2r"
    arity = 2

    def instances(self, sit: Situation) -> Iterator[tuple[Action, Transition]]:
        for g in sit.available:
            for r in sit.available:
                if not can_meet(g, r) or sit.context.blocked(g.id, r.id):
                    continue
                point = rendezvous_point(g, r)
                for oid in sit.objects:
                    yield (
                        Action("handover_r2r", (g.id, r.id), oid),
                        Transition(
                            oid,
                            Loc("held", g.id),
                            Loc("held", r.id),
                            (r.id,),
                            frozenset(),
                            ((g.id, point), (r.id, point)),
                        ),
                    )


class HandoverR2H(Skill):
    """handover_r2h(o, u) by r: r holds o, u inside r's workspace under ℓ → delivered(o, u)."""

    name = "handover_r2h"

    def instances(self, sit: Situation) -> Iterator[tuple[Action, Transition]]:
        for hid, robots in sit.context.served_by:
            pos = sit.human_position(hid)
            for r in sit.available:
                if r.id not in robots:
                    continue
                point = human_handover_point(r, pos)
                for oid in sit.objects:
                    yield (
                        Action("handover_r2h", (r.id,), oid, human=hid),
                        Transition(
                            oid,
                            Loc("held", r.id),
                            Loc("delivered", hid),
                            (),
                            frozenset({Atom("delivered", (oid, hid))}),
                            ((r.id, point),),
                        ),
                    )


DEFAULT_SKILLS: tuple[Skill, ...] = (Pick(), Place(), HandoverR2R(), HandoverR2H())


def ground(
    sit: Situation, skills: Sequence[Skill] = DEFAULT_SKILLS
) -> tuple[tuple[Action, Transition], ...]:
    """All ground skill instances of the library in a situation."""
    return tuple(inst for skill in skills for inst in skill.instances(sit))


def state_atoms(obj: str, loc: Loc) -> frozenset[Atom]:
    """State atoms an object's place makes true after a step (``holding``, ``at``)."""
    if loc.kind == "held":
        return frozenset({Atom("holding", (loc.ref, obj))})
    if loc.kind == "on":
        return frozenset({Atom("at", (obj, loc.ref))})
    return frozenset()


def step_symbol(transitions: Sequence[Transition], world: WorldState) -> frozenset[Atom]:
    """A step's symbol for the monitors: the events of the completed instances plus the state
    atoms of the world after the step (docs/model.md, "Monitors")."""
    atoms: set[Atom] = set()
    for tr in transitions:
        atoms |= tr.events
    for oid, st in world.objects:
        atoms |= state_atoms(oid, st.loc)
    return frozenset(atoms)


def check_action(
    action: Action,
    scene: Scene,
    world: WorldState,
    skills: Sequence[Skill] = DEFAULT_SKILLS,
) -> str | None:
    """Pre(s, ℓ, a) under the latest world: ``None`` when it holds, else the reason it fails."""
    sit = Situation.of(scene, world)
    matches = [t for a, t in ground(sit, skills) if a == action]
    if not matches:
        return _why_not_grounded(action, sit)
    status = {oid: st.loc for oid, st in world.objects}
    loc = status.get(action.object)
    trans = [t for t in matches if t.pre == loc]
    if not trans:
        if action.skill == "pick" and loc is not None and loc.kind in ("rest", "on"):
            where = _where(sit, action.object, loc)
            return f"{action}: {action.object} {where} is out of reach of {action.robots[0]}"
        need = " or ".join(sorted({str(t.pre) for t in matches}))
        return f"{action}: {action.object} is {loc}; the skill needs it {need}"
    for rid in trans[0].free:
        held = world.holding(rid)
        if held is not None:
            return f"{action}: {rid} is not free (holds {held})"
    return None


def _where(sit: Situation, oid: str, loc: Loc) -> str:
    if loc.kind == "on":
        return f"on {loc.ref}"
    x, y, z = sit.rest_position(oid)
    return f"at ({x:.2f}, {y:.2f}, {z:.2f})"


def _why_not_grounded(action: Action, sit: Situation) -> str:
    avail = {r.id for r in sit.available}
    down = [r for r in action.robots if r not in avail]
    if down:
        return f"{action}: robot {', '.join(down)} is unavailable"
    if action.skill == "handover_r2h" and action.human is not None:
        serving = sorted(sit.context.robots_serving(action.human))
        return (
            f"{action}: {action.human} is not inside {action.robots[0]}'s workspace "
            f"(served by: {', '.join(serving) or 'no robot'})"
        )
    if action.skill == "handover_r2r" and len(action.robots) == 2:
        g, r = action.robots
        if sit.context.blocked(g, r):
            return f"{action}: a person stands inside both {g}'s and {r}'s workspaces"
        return f"{action}: {g} and {r} cannot meet"
    return f"{action}: out of reach or not a skill of the library"
