"""Skill library J: pick, place, handover_r2r, handover_r2h; Pre, Post, events and durations."""

from __future__ import annotations

from abc import ABC, abstractmethod
from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any, ClassVar

from hltl.errors import PlanFormatError
from hltl.skills.kinematics import REACH_SPHERES, Kinematics
from hltl.spec.syntax import Atom
from hltl.world.geometry import Context
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
    each executor's hand ends up; ``human_at``, for a hand-over to a person, where they stand
    (a motion model plans the arm towards them there)."""

    obj: str
    pre: Loc
    post: Loc
    free: tuple[str, ...]
    events: frozenset[Atom]
    hands: tuple[tuple[str, Vec3], ...]
    human_at: Vec3 | None = None


@dataclass(frozen=True, slots=True)
class Situation:
    """What grounding depends on: the scene, where objects rest now, ℓ(w), available robots."""

    scene: Scene
    rest: tuple[tuple[str, Vec3], ...]
    context: Context
    available: tuple[Robot, ...]
    objects: tuple[str, ...] = field(default=())
    humans: tuple[tuple[str, Vec3], ...] = field(default=())  # where people stand now
    kinematics: Kinematics = field(default=REACH_SPHERES)

    @classmethod
    def of(
        cls,
        scene: Scene,
        world: WorldState | None = None,
        kinematics: Kinematics = REACH_SPHERES,
    ) -> Situation:
        w = initial_world(scene) if world is None else world
        rest = tuple((oid, st.position) for oid, st in w.objects)
        return cls(
            scene=scene,
            rest=rest,
            context=kinematics.context_label(scene, w.humans),
            available=tuple(r for r in scene.robots if r.id not in w.unavailable),
            objects=tuple(oid for oid, _ in w.objects),
            humans=w.humans,
            kinematics=kinematics,
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
    """A skill of the library. Subclasses set ``name`` and ground their instances.

    ``instances`` lists every ground instance of a situation (the planner's graph);
    ``candidates`` gives the transitions of one action (the executor's and simulator's question).
    A new skill needs only ``instances``; the default ``candidates`` filters them.
    """

    name: ClassVar[str]
    #: number of robots executing one instance
    arity: ClassVar[int] = 1

    @abstractmethod
    def instances(self, sit: Situation) -> Iterator[tuple[Action, Transition]]:
        """All ground instances whose situation-dependent preconditions hold in ``sit``."""

    def candidates(self, action: Action, sit: Situation) -> Iterator[Transition]:
        """The transitions of ``action`` in ``sit`` (one per place the object may start from)."""
        return (t for a, t in self.instances(sit) if a == action)


def _paired(
    skill: Skill, actions: Iterator[Action], sit: Situation
) -> Iterator[tuple[Action, Transition]]:
    for action in actions:
        for tr in skill.candidates(action, sit):
            yield action, tr


def _robots(
    skill: Skill, action: Action, sit: Situation, *, human: bool = False, surface: bool = False
) -> tuple[Robot, ...] | None:
    """The action's robots when the action has the skill's shape (name, arity, a known object,
    a human or surface argument exactly when the skill takes one) and all its robots are
    available; else None."""
    if (
        action.skill != skill.name
        or len(action.robots) != skill.arity
        or action.object not in sit.objects
        or (action.human is not None) != human
        or (action.surface is not None) != surface
    ):
        return None
    avail = {r.id: r for r in sit.available}
    found = tuple(avail[r] for r in action.robots if r in avail)
    return found if len(found) == skill.arity else None


class Pick(Skill):
    """pick(o) by r: r free, o resting or on a surface within r's reach → r holds o."""

    name = "pick"

    def instances(self, sit: Situation) -> Iterator[tuple[Action, Transition]]:
        acts = (Action("pick", (r.id,), o) for o in sit.objects for r in sit.available)
        return _paired(self, acts, sit)

    def candidates(self, action: Action, sit: Situation) -> Iterator[Transition]:
        robots = _robots(self, action, sit)
        if robots is None:
            return
        (r,) = robots
        oid = action.object
        sources: list[tuple[Loc, Vec3]] = [(REST, sit.rest_position(oid))]
        sources += [(Loc("on", s.id), s.object_point) for s in sit.scene.surfaces]
        for loc, point in sources:
            if sit.kinematics.reaches(r, point):
                yield Transition(
                    oid,
                    loc,
                    Loc("held", r.id),
                    (r.id,),
                    frozenset({Atom("picked", (oid,))}),
                    ((r.id, point),),
                )


class Place(Skill):
    """place(o, s) by r: r holds o, s within r's reach → o on s, r free."""

    name = "place"

    def instances(self, sit: Situation) -> Iterator[tuple[Action, Transition]]:
        acts = (
            Action("place", (r.id,), o, surface=s.id)
            for o in sit.objects
            for r in sit.available
            for s in sit.scene.surfaces
        )
        return _paired(self, acts, sit)

    def candidates(self, action: Action, sit: Situation) -> Iterator[Transition]:
        robots = _robots(self, action, sit, surface=True)
        surface = next((s for s in sit.scene.surfaces if s.id == action.surface), None)
        if robots is None or surface is None:
            return
        (r,) = robots
        point = surface.object_point  # where the held object is let go, not the surface's top
        if sit.kinematics.reaches(r, point):
            yield Transition(
                action.object,
                Loc("held", r.id),
                Loc("on", surface.id),
                (),
                frozenset({Atom("placed", (action.object, surface.id))}),
                ((r.id, point),),
            )


class HandoverR2R(Skill):
    """handover_r2r(o; g, r): g holds o, r free, robots can meet, nobody inside both
    workspaces → r holds o, g free."""

    name = "handover_r2r"
    arity = 2

    def instances(self, sit: Situation) -> Iterator[tuple[Action, Transition]]:
        acts = (
            Action("handover_r2r", (g.id, r.id), o)
            for g in sit.available
            for r in sit.available
            for o in sit.objects
        )
        return _paired(self, acts, sit)

    def candidates(self, action: Action, sit: Situation) -> Iterator[Transition]:
        robots = _robots(self, action, sit)
        if robots is None:
            return
        g, r = robots
        if not sit.kinematics.can_meet(g, r) or sit.context.blocked(g.id, r.id):
            return
        point = sit.kinematics.rendezvous_point(g, r)
        yield Transition(
            action.object,
            Loc("held", g.id),
            Loc("held", r.id),
            (r.id,),
            frozenset(),
            ((g.id, point), (r.id, point)),
        )


class HandoverR2H(Skill):
    """handover_r2h(o, u) by r: r holds o, u inside r's workspace under ℓ → delivered(o, u)."""

    name = "handover_r2h"

    def instances(self, sit: Situation) -> Iterator[tuple[Action, Transition]]:
        acts = (
            Action("handover_r2h", (r.id,), o, human=h)
            for h, _ in sit.context.served_by
            for r in sit.available
            for o in sit.objects
        )
        return _paired(self, acts, sit)

    def candidates(self, action: Action, sit: Situation) -> Iterator[Transition]:
        robots = _robots(self, action, sit, human=True)
        if robots is None or action.human is None:
            return
        (r,) = robots
        if r.id not in sit.context.robots_serving(action.human):
            return
        at = sit.human_position(action.human)
        point = sit.kinematics.human_handover_point(r, at)
        yield Transition(
            action.object,
            Loc("held", r.id),
            Loc("delivered", action.human),
            (),
            frozenset({Atom("delivered", (action.object, action.human))}),
            ((r.id, point),),
            human_at=at,
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
