"""Scene model (DESIGN.md §3): robots, objects, humans, surfaces; loading with full validation."""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Annotated, Any, TypeVar

from pydantic import (
    BaseModel,
    BeforeValidator,
    ConfigDict,
    Field,
    ValidationError,
    field_validator,
)

from hltl.errors import SceneError, UnknownEntityError
from hltl.fileio import clip, load_file, quote

Vec3 = tuple[float, float, float]
_T = TypeVar("_T")

DEFAULT_HUMAN_REACH = 0.3
# the skills of DESIGN.md §4, the keys a scene's ``durations`` may give
SKILL_NAMES = ("pick", "place", "handover_r2r", "handover_r2h")
_UNIT_SCALE = {"m": 1.0, "cm": 0.01, "mm": 0.001}


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


# -- validation models (file format) -------------------------------------------------------------


class _Strict(BaseModel):
    model_config = ConfigDict(extra="forbid", strict=False, frozen=True)


def _not_bool(v: Any) -> Any:
    # pydantic's lax mode reads true as 1.0: a coordinate or length is never a yes/no
    if isinstance(v, bool):
        raise ValueError(f"expected a number, got {str(v).lower()}")
    return v


Num = Annotated[float, BeforeValidator(_not_bool)]


def _finite(values: Sequence[float]) -> list[float]:
    for v in values:
        if not math.isfinite(v):
            raise ValueError(f"{quote(v)} is not a finite number")
    return list(values)


class _RobotIn(_Strict):
    id: str = Field(min_length=1)
    base: tuple[Num, Num, Num]
    reach: Num = Field(gt=0)
    model: str = "generic"
    speed: Num | None = Field(default=None, gt=0)

    _v = field_validator("base")(lambda v: tuple(_finite(v)))

    @field_validator("reach", "speed")
    @classmethod
    def _finite_scalar(cls, v: float | None) -> float | None:
        if v is not None and not math.isfinite(v):
            raise ValueError(f"{quote(v)} is not a finite number")
        return v


class _ObjectIn(_Strict):
    id: str = Field(min_length=1)
    category: str | None = None
    position: tuple[Num, Num, Num]
    aliases: list[str] = []

    _v = field_validator("position")(lambda v: tuple(_finite(v)))


class _HumanIn(_Strict):
    id: str = Field(min_length=1)
    name: str | None = None
    position: tuple[Num, Num, Num]
    aliases: list[str] = []

    _v = field_validator("position")(lambda v: tuple(_finite(v)))


class _SurfaceIn(_Strict):
    id: str = Field(min_length=1)
    center: tuple[Num, Num, Num]
    size: tuple[Num, Num]
    aliases: list[str] = []

    _v = field_validator("center", "size")(lambda v: tuple(_finite(v)))

    @field_validator("size")
    @classmethod
    def _positive(cls, v: tuple[Num, Num]) -> tuple[Num, Num]:
        if min(v) <= 0:
            raise ValueError(f"sizes must be positive, got {list(v)}")
        return v


class _CameraIn(_Strict):
    id: str = Field(min_length=1)
    position: tuple[Num, Num, Num]
    look_at: tuple[Num, Num, Num]
    width: int = Field(default=640, ge=8, le=4096)
    height: int = Field(default=480, ge=8, le=4096)
    fovy: Num = Field(default=42.0, gt=1.0, lt=170.0)
    rate: Num = Field(default=10.0, gt=0.0, le=1000.0)

    _v = field_validator("position", "look_at")(lambda v: tuple(_finite(v)))


class _SceneIn(_Strict):
    units: str = "m"
    robots: list[_RobotIn] = Field(min_length=1)
    objects: list[_ObjectIn] = []
    humans: list[_HumanIn] = []
    surfaces: list[_SurfaceIn] = []
    durations: dict[str, Num] | None = None
    human_reach: Num = Field(default=DEFAULT_HUMAN_REACH, ge=0)
    cameras: list[_CameraIn] = []

    @field_validator("units")
    @classmethod
    def _units(cls, v: str) -> str:
        if v not in _UNIT_SCALE:
            raise ValueError(f"unknown unit {quote(v)}; expected one of {', '.join(_UNIT_SCALE)}")
        return v

    @field_validator("durations")
    @classmethod
    def _durations(cls, v: dict[str, float] | None) -> dict[str, float] | None:
        for k, d in (v or {}).items():
            if k not in SKILL_NAMES:
                raise ValueError(
                    f"unknown skill {quote(k)}; expected some of {', '.join(SKILL_NAMES)}"
                )
            if not math.isfinite(d) or d < 0:
                raise ValueError(
                    f"duration of {quote(k)} must be a finite number >= 0, got {quote(d)}"
                )
        return v

    @field_validator("human_reach")
    @classmethod
    def _hr(cls, v: float) -> float:
        if not math.isfinite(v):
            raise ValueError(f"{quote(v)} is not a finite number")
        return v


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
    try:
        raw = _SceneIn.model_validate(dict(data))
    except ValidationError as exc:
        raise SceneError(_format_validation(exc, source, data)) from None
    k = _UNIT_SCALE[raw.units]

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
            SceneObject(o.id, o.category or o.id, v3(o.position), tuple(o.aliases))
            for o in raw.objects
        ),
        humans=tuple(
            Human(h.id, h.name or h.id, v3(h.position), tuple(h.aliases)) for h in raw.humans
        ),
        surfaces=tuple(
            Surface(s.id, v3(s.center), (s.size[0] * k, s.size[1] * k), tuple(s.aliases))
            for s in raw.surfaces
        ),
        durations=None if raw.durations is None else tuple(sorted(raw.durations.items())),
        human_reach=raw.human_reach * k,
        cameras=tuple(
            Camera(c.id, v3(c.position), v3(c.look_at), c.width, c.height, c.fovy, c.rate)
            for c in raw.cameras
        ),
        source=source,
    )


def load_scene(path: str | Path) -> Scene:
    """Load and validate a scene from a YAML or JSON file."""
    p = Path(path)
    return scene_from_dict(load_file(p, "scene file", SceneError), source=str(p))


def _format_validation(exc: ValidationError, source: str, data: Mapping[str, Any]) -> str:
    err = exc.errors()[0]
    loc = err.get("loc", ())
    path = ""
    for part in loc:
        path += f"[{part}]" if isinstance(part, int) else (f".{part}" if path else str(part))
    value = _lookup(data, loc)
    msg = str(err.get("msg", "invalid")).removeprefix("Value error, ")
    if err.get("type") == "extra_forbidden":
        return f"{source}: {path}: unknown field (value {quote(value)}); check the spelling"
    if err.get("type") == "missing":
        return f"{source}: {path}: required field is missing"
    return f"{source}: {path}: invalid value {quote(value)}: {clip(msg)}"


def _lookup(data: Any, loc: Sequence[Any]) -> Any:
    cur = data
    for part in loc:
        try:
            cur = cur[part]
        except (KeyError, IndexError, TypeError):
            return None
    return cur
