"""The scene file format as pydantic models: the full validator, with its error messages."""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import Annotated, Any

from pydantic import (
    AfterValidator,
    BaseModel,
    BeforeValidator,
    ConfigDict,
    Field,
    ValidationError,
    field_validator,
)

from hltl.errors import SceneError
from hltl.fileio import clip, quote
from hltl.world.scene import DEFAULT_HUMAN_REACH, SKILL_NAMES, UNIT_SCALE


class Strict(BaseModel):
    model_config = ConfigDict(extra="forbid", strict=False, frozen=True)


def _not_bool(v: Any) -> Any:
    # pydantic's lax mode reads true as 1.0: a coordinate or length is never a yes/no
    if isinstance(v, bool):
        raise ValueError(f"expected a number, got {str(v).lower()}")
    return v


def _finite(v: Any) -> Any:
    for x in v if isinstance(v, tuple) else (v,):
        if x is not None and not math.isfinite(x):
            raise ValueError(f"{quote(x)} is not a finite number")
    return v


Num = Annotated[float, BeforeValidator(_not_bool)]
Finite = Annotated[Num, AfterValidator(_finite)]
Point = Annotated[tuple[Num, Num, Num], AfterValidator(_finite)]  # named whole in messages


class RobotIn(Strict):
    id: str = Field(min_length=1)
    base: Point
    reach: Finite = Field(gt=0)
    model: str = "generic"
    speed: Annotated[Num | None, AfterValidator(_finite)] = Field(default=None, gt=0)


class ObjectIn(Strict):
    id: str = Field(min_length=1)
    category: str | None = None
    position: Point
    aliases: list[str] = []


class HumanIn(Strict):
    id: str = Field(min_length=1)
    name: str | None = None
    position: Point
    aliases: list[str] = []


class SurfaceIn(Strict):
    id: str = Field(min_length=1)
    center: Point
    size: Annotated[tuple[Num, Num], AfterValidator(_finite)]
    aliases: list[str] = []

    @field_validator("size")
    @classmethod
    def _positive(cls, v: tuple[Num, Num]) -> tuple[Num, Num]:
        if min(v) <= 0:
            raise ValueError(f"sizes must be positive, got {list(v)}")
        return v


class CameraIn(Strict):
    id: str = Field(min_length=1)
    position: Point
    look_at: Point
    width: int = Field(default=640, ge=8, le=4096)
    height: int = Field(default=480, ge=8, le=4096)
    fovy: Num = Field(default=42.0, gt=1.0, lt=170.0)
    rate: Num = Field(default=10.0, gt=0.0, le=1000.0)


class SceneIn(Strict):
    units: str = "m"
    robots: list[RobotIn] = Field(min_length=1)
    objects: list[ObjectIn] = []
    humans: list[HumanIn] = []
    surfaces: list[SurfaceIn] = []
    durations: dict[str, Num] | None = None
    human_reach: Finite = Field(default=DEFAULT_HUMAN_REACH, ge=0)
    cameras: list[CameraIn] = []

    @field_validator("units")
    @classmethod
    def _units(cls, v: str) -> str:
        if v not in UNIT_SCALE:
            raise ValueError(f"unknown unit {quote(v)}; expected one of {', '.join(UNIT_SCALE)}")
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


def validate(data: Mapping[str, Any], source: str) -> SceneIn:
    """The scene validated by the models; a :class:`SceneError` naming the first problem."""
    try:
        return SceneIn.model_validate(dict(data))
    except ValidationError as exc:
        raise SceneError(_format_validation(exc, source, data)) from None


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
