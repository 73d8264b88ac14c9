"""Scene model (DESIGN.md §3): robots, objects, humans, surfaces; loading with full validation."""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, TypeVar

from hltl.errors import SceneError, UnknownEntityError
from hltl.fileio import load_file, quote

Vec3 = tuple[float, float, float]
_T = TypeVar("_T")

DEFAULT_HUMAN_REACH = 0.3
# An object's point stands this high above what it rests on: scenes put objects on the table
# (z = 0) at z = 0.05, and a hand picks or places an object at its point (the motion layer
# grasps it there, or higher for a tall object).
OBJECT_LIFT = 0.05
# the skills of DESIGN.md §4, the keys a scene's ``durations`` may give
SKILL_NAMES = ("pick", "place", "handover_r2r", "handover_r2h")
UNIT_SCALE = {"m": 1.0, "cm": 0.01, "mm": 0.001}


@dataclass(frozen=True, slots=True)
class Robot:
    """A fixed-base arm whose workspace is the sphere of radius ``reach`` around ``base``."""

    id: str
    base: Vec3
    reach: float
    model: str = "generic"
    speed: float | None = None  # hand speed in m/s for the analytic cost model; None: model default


@dataclass(frozen=True, slots=True)
class SceneObject:
    """A graspable object resting at ``position`` at the start of the episode."""

    id: str
    category: str
    position: Vec3
    aliases: tuple[str, ...] = ()


@dataclass(frozen=True, slots=True)
class Human:
    """A person who can receive objects; ``position`` is on the floor (z is ignored for reach)."""

    id: str
    name: str
    position: Vec3
    aliases: tuple[str, ...] = ()


@dataclass(frozen=True, slots=True)
class Surface:
    """A horizontal surface objects can be placed on; ``size`` is its (x, y) extent."""

    id: str
    center: Vec3
    size: tuple[float, float]
    aliases: tuple[str, ...] = ()

    @property
    def object_point(self) -> Vec3:
        """Where an object standing at the surface's centre has its point (``OBJECT_LIFT``
        above the top, as objects on the table stand at z = 0.05): where a hand places an
        object on the surface or picks one from it, so where reach is judged."""
        x, y, z = self.center
        return (x, y, z + OBJECT_LIFT)


@dataclass(frozen=True, slots=True)
class Camera:
    """A fixed pinhole camera (the 3D simulator renders it): ``position`` looks at ``look_at``
    with the world's z axis up; square pixels, principal point at the image centre, vertical
    field of view ``fovy`` degrees; frames are taken ``rate`` times per simulated second."""

    id: str
    position: Vec3
    look_at: Vec3
    width: int = 640
    height: int = 480
    fovy: float = 42.0
    rate: float = 10.0


@dataclass(frozen=True, slots=True)
class Scene:
    """A validated scene. Lengths are in metres whatever unit the file used."""

    robots: tuple[Robot, ...]
    objects: tuple[SceneObject, ...] = ()
    humans: tuple[Human, ...] = ()
    surfaces: tuple[Surface, ...] = ()
    durations: tuple[tuple[str, float], ...] | None = None  # fixed skill durations, sorted by skill
    human_reach: float = DEFAULT_HUMAN_REACH
    cameras: tuple[Camera, ...] = ()
    source: str = field(default="<scene>", compare=False)

    # -- lookups -------------------------------------------------------------------------------
    def robot(self, rid: str) -> Robot:
        return _find(self.robots, rid, "robot", self.source)

    def object(self, oid: str) -> SceneObject:
        return _find(self.objects, oid, "object", self.source)

    def human(self, hid: str) -> Human:
        return _find(self.humans, hid, "human", self.source)

    def surface(self, sid: str) -> Surface:
        return _find(self.surfaces, sid, "surface", self.source)

    @property
    def robot_ids(self) -> tuple[str, ...]:
        return tuple(r.id for r in self.robots)

    @property
    def object_ids(self) -> tuple[str, ...]:
        return tuple(o.id for o in self.objects)

    @property
    def human_ids(self) -> tuple[str, ...]:
        return tuple(h.id for h in self.humans)

    @property
    def surface_ids(self) -> tuple[str, ...]:
        return tuple(s.id for s in self.surfaces)

    def duration_map(self) -> dict[str, float] | None:
        return None if self.durations is None else dict(self.durations)

    def to_dict(self) -> dict[str, Any]:
        """The scene in its file format (metres), so that ``scene_from_dict(s.to_dict()) == s``."""
        out: dict[str, Any] = {
            "units": "m",
            "robots": [_robot_dict(r) for r in self.robots],
            "objects": [
                _drop_empty(
                    o.id, category=o.category, position=list(o.position), aliases=list(o.aliases)
                )
                for o in self.objects
            ],
            "humans": [
                _drop_empty(h.id, name=h.name, position=list(h.position), aliases=list(h.aliases))
                for h in self.humans
            ],
            "surfaces": [
                _drop_empty(s.id, center=list(s.center), size=list(s.size), aliases=list(s.aliases))
                for s in self.surfaces
            ],
        }
        if self.durations is not None:
            out["durations"] = dict(self.durations)
        if self.human_reach != DEFAULT_HUMAN_REACH:
            out["human_reach"] = self.human_reach
        if self.cameras:
            out["cameras"] = [
                {
                    "id": c.id,
                    "position": list(c.position),
                    "look_at": list(c.look_at),
                    "width": c.width,
                    "height": c.height,
                    "fovy": c.fovy,
                    "rate": c.rate,
                }
                for c in self.cameras
            ]
        return out


def _robot_dict(r: Robot) -> dict[str, Any]:
    d: dict[str, Any] = {"id": r.id, "base": list(r.base), "reach": r.reach, "model": r.model}
    if r.speed is not None:
        d["speed"] = r.speed
    return d


def _drop_empty(id_: str, **fields: Any) -> dict[str, Any]:
    return {"id": id_, **{k: v for k, v in fields.items() if v != []}}


def _find(items: Sequence[_T], key: str, kind: str, source: str) -> _T:
    for item in items:
        if getattr(item, "id", None) == key:
            return item
    have = ", ".join(str(getattr(i, "id", i)) for i in items) or "none"
    raise UnknownEntityError(f"{source}: unknown {kind} {quote(key)}; scene has: {have}")


_ID_CHARS = set("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-")


MAX_ID_CHARS = 64  # ids appear in formulas, prompts and messages


def _check_id(value: str, where: str, source: str) -> None:
    if len(value) > MAX_ID_CHARS:
        raise SceneError(
            f"{source}: {where}: id {quote(value, 40)} is too long (at most {MAX_ID_CHARS} "
            "characters)"
        )
    if not set(value) <= _ID_CHARS or value[0].isdigit() or value[0] == "-":
        raise SceneError(
            f"{source}: {where}: id {quote(value)} is not valid; expected letters, digits, '_' "
            "or '-' starting with a letter or '_'"
        )


def scene_from_dict(data: Mapping[str, Any], source: str = "<scene>") -> Scene:
    """Validate a scene given as a mapping (the file format) and build a :class:`Scene`.

    Raises:
        SceneError: naming ``source``, the field and the offending value.
    """
    if not isinstance(data, Mapping):
        raise SceneError(f"{source}: a scene must be a mapping, got {type(data).__name__}")
    raw = _plain(data)
    if raw is None:
        # Not in the plain form: the full validator decides, and names the problem if any.
        # why: scene_schema imports pydantic, so only here: a command reading an ordinary scene
        # starts fast (docs/benchmarks.md, "Start-up")
        from hltl.world import scene_schema

        raw = _from_models(scene_schema.validate(data, source))
    k = UNIT_SCALE[raw.units]

    def v3(p: Sequence[float]) -> Vec3:
        return (p[0] * k, p[1] * k, p[2] * k)

    seen: dict[str, str] = {}
    groups: list[tuple[str, Sequence[Any]]] = [
        ("robots", raw.robots),
        ("objects", raw.objects),
        ("humans", raw.humans),
        ("surfaces", raw.surfaces),
    ]
    for kind, items in groups:
        for i, item in enumerate(items):
            where = f"{kind}[{i}].id"
            _check_id(item.id, where, source)
            if item.id in seen:
                raise SceneError(
                    f"{source}: {where}: duplicate id {quote(item.id)} "
                    f"(already used by {seen[item.id]}); ids must be unique across "
                    "robots, objects, humans and surfaces"
                )
            seen[item.id] = f"{kind}[{i}]"
    cams: dict[str, int] = {}
    for i, c in enumerate(raw.cameras):
        _check_id(c.id, f"cameras[{i}].id", source)
        if c.id in cams:
            raise SceneError(f"{source}: cameras[{i}].id: duplicate camera id {c.id!r}")
        cams[c.id] = i
        if math.dist(c.position, c.look_at) < 1e-6:
            raise SceneError(
                f"{source}: cameras[{i}]: look_at {list(c.look_at)} equals position; "
                "expected a point the camera looks towards"
            )

    return Scene(
        robots=tuple(Robot(r.id, v3(r.base), r.reach * k, r.model, r.speed) for r in raw.robots),
        objects=tuple(
            SceneObject(o.id, o.category, v3(o.position), o.aliases) for o in raw.objects
        ),
        humans=tuple(Human(h.id, h.name, v3(h.position), h.aliases) for h in raw.humans),
        surfaces=tuple(
            Surface(s.id, v3(s.center), (s.size[0] * k, s.size[1] * k), s.aliases)
            for s in raw.surfaces
        ),
        durations=raw.durations,
        human_reach=raw.human_reach * k,
        cameras=tuple(
            Camera(c.id, v3(c.position), v3(c.look_at), c.width, c.height, c.fovy, c.rate)
            for c in raw.cameras
        ),
        source=source,
    )


@dataclass(frozen=True, slots=True)
class _Raw:
    """A validated scene file before unit scaling and the id checks."""

    units: str
    robots: tuple[Robot, ...]
    objects: tuple[SceneObject, ...]
    humans: tuple[Human, ...]
    surfaces: tuple[Surface, ...]
    durations: tuple[tuple[str, float], ...] | None
    human_reach: float
    cameras: tuple[Camera, ...]


def _from_models(m: Any) -> _Raw:
    """The full validator's result (``scene_schema.SceneIn``) as a :class:`_Raw`."""
    return _Raw(
        m.units,
        tuple(Robot(r.id, tuple(r.base), r.reach, r.model, r.speed) for r in m.robots),
        tuple(
            SceneObject(o.id, o.category or o.id, tuple(o.position), tuple(o.aliases))
            for o in m.objects
        ),
        tuple(Human(h.id, h.name or h.id, tuple(h.position), tuple(h.aliases)) for h in m.humans),
        tuple(Surface(s.id, tuple(s.center), tuple(s.size), tuple(s.aliases)) for s in m.surfaces),
        None if m.durations is None else tuple(sorted(m.durations.items())),
        m.human_reach,
        tuple(
            Camera(c.id, tuple(c.position), tuple(c.look_at), c.width, c.height, c.fovy, c.rate)
            for c in m.cameras
        ),
    )


# The plain form: the keys the file format allows, ids and names as non-empty str, numbers as int
# or float (never bool), finite and in range, lists as lists; no cameras. What ``_plain`` accepts
# the full validator accepts with the same values (tests/world/test_scene.py checks it on random
# inputs); anything else, valid or not, goes to the full validator.
_TOP = frozenset(
    {"units", "robots", "objects", "humans", "surfaces", "durations", "human_reach", "cameras"}
)
_ROBOT = frozenset({"id", "base", "reach", "model", "speed"})
_OBJECT = frozenset({"id", "category", "position", "aliases"})
_HUMAN = frozenset({"id", "name", "position", "aliases"})
_SURFACE = frozenset({"id", "center", "size", "aliases"})


class _NotPlain(Exception):
    """The input is not in the plain form (it may still be valid)."""


def _num(v: object) -> float:
    if type(v) is not float and type(v) is not int:
        raise _NotPlain
    f = float(v)
    if not math.isfinite(f):
        raise _NotPlain
    return f


def _vec(v: object, n: int) -> tuple[float, ...]:
    if type(v) is not list or len(v) != n:
        raise _NotPlain
    return tuple(_num(x) for x in v)


def _name(v: object) -> str:
    if type(v) is not str or not v:
        raise _NotPlain
    return v


def _opt_name(d: dict[str, Any], key: str, default: str) -> str:
    v = d.get(key)
    return default if v is None else _name(v)


def _names(d: dict[str, Any]) -> tuple[str, ...]:
    v = d.get("aliases", [])
    if type(v) is not list or any(type(x) is not str for x in v):
        raise _NotPlain
    return tuple(v)


def _labelled(d: dict[str, Any], label: str) -> tuple[str, str, Vec3, tuple[str, ...]]:
    """An object's or a person's id, label (``category``/``name``, default the id), position
    and aliases."""
    position = _vec(d["position"], 3)
    return (_name(d["id"]), _opt_name(d, label, d["id"]), position, _names(d))  # type: ignore[return-value]


def _items(data: Mapping[str, Any], key: str, keys: frozenset[str]) -> list[dict[str, Any]]:
    v = data.get(key, [])
    if type(v) is not list or any(type(d) is not dict or not d.keys() <= keys for d in v):
        raise _NotPlain
    return v


def _plain(data: Mapping[str, Any]) -> _Raw | None:
    """The scene read directly when it is in the plain form, else ``None``."""
    try:
        if not data.keys() <= _TOP or data.get("cameras", []) != []:
            raise _NotPlain
        units = data.get("units", "m")
        if type(units) is not str or units not in UNIT_SCALE:
            raise _NotPlain
        robots = []
        for d in _items(data, "robots", _ROBOT):
            speed = d.get("speed")
            robot = Robot(
                _name(d["id"]),
                _vec(d["base"], 3),  # type: ignore[arg-type]
                _num(d["reach"]),
                _name(d.get("model", "generic")),
                None if speed is None else _num(speed),
            )
            if robot.reach <= 0 or (robot.speed is not None and robot.speed <= 0):
                raise _NotPlain
            robots.append(robot)
        if not robots:
            raise _NotPlain
        objects = tuple(
            SceneObject(*_labelled(d, "category")) for d in _items(data, "objects", _OBJECT)
        )
        humans = tuple(Human(*_labelled(d, "name")) for d in _items(data, "humans", _HUMAN))
        surfaces = tuple(
            Surface(
                _name(d["id"]),
                _vec(d["center"], 3),  # type: ignore[arg-type]
                _vec(d["size"], 2),  # type: ignore[arg-type]
                _names(d),
            )
            for d in _items(data, "surfaces", _SURFACE)
        )
        if any(min(s.size) <= 0 for s in surfaces):
            raise _NotPlain
        durations = data.get("durations")
        dur: tuple[tuple[str, float], ...] | None = None
        if durations is not None:
            if type(durations) is not dict or not durations.keys() <= set(SKILL_NAMES):
                raise _NotPlain
            dur = tuple(sorted((key, _num(v)) for key, v in durations.items()))
            if any(v < 0 for _, v in dur):
                raise _NotPlain
        human_reach = _num(data.get("human_reach", DEFAULT_HUMAN_REACH))
        if human_reach < 0:
            raise _NotPlain
    except (_NotPlain, KeyError):
        return None
    return _Raw(units, tuple(robots), objects, humans, surfaces, dur, human_reach, ())


def load_scene(path: str | Path) -> Scene:
    """Load and validate a scene from a YAML or JSON file."""
    p = Path(path)
    return scene_from_dict(load_file(p, "scene file", SceneError), source=str(p))
