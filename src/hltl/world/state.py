"""World state w_t (continuous, what perception or the simulator reports) and its projection."""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Literal, TypeVar

from hltl.errors import UnknownEntityError
from hltl.world.geometry import Context, context_label, home_point
from hltl.world.scene import Scene, Vec3

_V = TypeVar("_V")
LocKind = Literal["rest", "held", "on", "delivered"]


@dataclass(frozen=True, slots=True, order=True)
class Loc:
    """Discrete place of an object: resting where it lies, held by a robot, on a surface, or
    delivered to a person (``ref`` is the robot, surface or human id; empty for ``rest``)."""

    kind: LocKind
    ref: str = ""

    def __str__(self) -> str:
        return self.kind if not self.ref else f"{self.kind}:{self.ref}"


REST = Loc("rest")


@dataclass(frozen=True, slots=True)
class ObjectStatus:
    """Where an object is: its position (metres) and its discrete place."""

    position: Vec3
    loc: Loc = REST


@dataclass(frozen=True, slots=True)
class WorldState:
    """The perceived world w_t: people, objects, hands and which robots are available.

    Values are stored as sorted tuples so that world states hash and compare by content.
    """

    t: float
    humans: tuple[tuple[str, Vec3], ...]
    objects: tuple[tuple[str, ObjectStatus], ...]
    hands: tuple[tuple[str, Vec3], ...] = ()
    unavailable: frozenset[str] = frozenset()

    # -- queries ------------------------------------------------------------------------------
    def human_position(self, hid: str) -> Vec3:
        for k, v in self.humans:
            if k == hid:
                return v
        raise UnknownEntityError(f"unknown human {hid!r}; world has: {_ids(self.humans)}")

    def object_status(self, oid: str) -> ObjectStatus:
        for k, v in self.objects:
            if k == oid:
                return v
        raise UnknownEntityError(f"unknown object {oid!r}; world has: {_ids(self.objects)}")

    def hand_position(self, rid: str) -> Vec3 | None:
        for k, v in self.hands:
            if k == rid:
                return v
        return None

    def holding(self, rid: str) -> str | None:
        """The object robot ``rid`` holds, if any."""
        for oid, st in self.objects:
            if st.loc.kind == "held" and st.loc.ref == rid:
                return oid
        return None

    def context(self, scene: Scene) -> Context:
        """ℓ(w_t)."""
        return context_label(scene, self.humans)

    # -- updates (return new values) ------------------------------------------------------------
    def with_time(self, t: float) -> WorldState:
        return replace(self, t=t)

    def with_human(self, hid: str, position: Vec3) -> WorldState:
        self.human_position(hid)
        return replace(self, humans=_set(self.humans, hid, position))

    def with_object(self, oid: str, status: ObjectStatus) -> WorldState:
        self.object_status(oid)
        return replace(self, objects=_set(self.objects, oid, status))

    def with_hand(self, rid: str, position: Vec3) -> WorldState:
        return replace(self, hands=_set(self.hands, rid, position))

    def with_unavailable(self, robots: frozenset[str]) -> WorldState:
        return replace(self, unavailable=robots)


def _ids(items: tuple[tuple[str, object], ...]) -> str:
    return ", ".join(k for k, _ in items) or "none"


def _set(items: tuple[tuple[str, _V], ...], key: str, value: _V) -> tuple[tuple[str, _V], ...]:
    out = dict(items)
    out[key] = value
    return tuple(sorted(out.items()))


def initial_world(scene: Scene) -> WorldState:
    """w_0 as the scene describes it: objects resting, hands at home, everyone available."""
    return WorldState(
        t=0.0,
        humans=tuple(sorted((h.id, h.position) for h in scene.humans)),
        objects=tuple(sorted((o.id, ObjectStatus(o.position)) for o in scene.objects)),
        hands=tuple(sorted((r.id, home_point(r)) for r in scene.robots)),
    )


@dataclass(frozen=True, slots=True)
class JointState:
    """Proj(w): the discrete joint state s — each object's place (robot states follow from it:
    a robot holds the object whose place is ``held:<robot>``)."""

    objects: tuple[tuple[str, Loc], ...]

    def loc(self, oid: str) -> Loc:
        for k, v in self.objects:
            if k == oid:
                return v
        raise UnknownEntityError(f"unknown object {oid!r}; state has: {_ids(self.objects)}")


def project(world: WorldState) -> JointState:
    """Proj(w_t) → s_t."""
    return JointState(tuple((oid, st.loc) for oid, st in world.objects))
