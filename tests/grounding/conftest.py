"""Grounding fixtures: scenes and a fake OpenAI client that replays recorded responses."""

from __future__ import annotations

import json
from pathlib import Path
from types import SimpleNamespace
from typing import Any

import pytest

from hltl.world.scene import Scene, load_scene

FIXTURES = Path(__file__).parent / "fixtures"
ROOT = Path(__file__).resolve().parents[2]


def recorded(name: str) -> dict[str, Any]:
    data: dict[str, Any] = json.loads((FIXTURES / name).read_text(encoding="utf-8"))
    return data


def as_object(data: Any) -> Any:
    """JSON as attribute objects, the way the openai SDK hands responses out."""
    if isinstance(data, dict):
        return SimpleNamespace(**{k: as_object(v) for k, v in data.items()})
    if isinstance(data, list):
        return [as_object(v) for v in data]
    return data


class BadRequestError(Exception):
    """Stands in for openai.BadRequestError (an HTTP 400 from the endpoint)."""

    status_code = 400


class FakeClient:
    """``client.chat.completions.create(**kwargs)`` replaying recorded responses in order.

    ``reject_formats`` lists response_format types the fake endpoint answers with HTTP 400.
    Every call's keyword arguments are kept in ``calls``.
    """

    def __init__(self, *names: str, reject_formats: tuple[str, ...] = ()) -> None:
        self.responses = [recorded(n) for n in names]
        self.reject_formats = reject_formats
        self.calls: list[dict[str, Any]] = []
        self.chat = SimpleNamespace(completions=SimpleNamespace(create=self._create))

    def _create(self, **kwargs: Any) -> Any:
        self.calls.append(kwargs)
        fmt = kwargs.get("response_format")
        if fmt is not None and fmt["type"] in self.reject_formats:
            raise BadRequestError(f"response_format {fmt['type']!r} is not supported")
        if not self.responses:
            raise AssertionError("the grounder asked more often than recorded")
        return as_object(self.responses.pop(0))


@pytest.fixture
def two_arms() -> Scene:
    return load_scene(ROOT / "examples" / "scenes" / "two_arms.yaml")


@pytest.fixture
def cell() -> Scene:
    return load_scene(ROOT / "examples" / "scenes" / "grounding_cell.yaml")
