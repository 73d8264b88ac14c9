"""The plain-form reader agrees with the full (pydantic) validator wherever it accepts a scene."""

from __future__ import annotations

import math
import subprocess
import sys
from typing import Any

from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.world import scene_schema
from hltl.world.scene import _from_models, _plain

# a valid scene (numbers as int or float, optional fields present or not), then at most one
# field replaced by a value of the wrong kind or range, or an unknown field added
_good = st.one_of(st.integers(0, 3), st.floats(0.01, 3))
BAD = [math.nan, math.inf, -1, 0, -0.0, True, False, "1.5", None, [1.0], "", 7, "x", ["a", 1]]
_bad = st.sampled_from(BAD)
_id = st.sampled_from(["r1", "r2", "cup", "A", "box", "s_1"])


def _vec(n: int) -> st.SearchStrategy[Any]:
    return st.lists(_good, min_size=n, max_size=n)


def _item(required: dict[str, Any], optional: dict[str, Any]) -> Any:
    return st.fixed_dictionaries(required, optional=optional)


_aliases = st.lists(_id, max_size=2)
_robot = _item(
    {"id": _id, "base": _vec(3), "reach": _good},
    {"model": st.sampled_from(["elfin3", "ur5"]), "speed": st.one_of(_good, st.none())},
)
_object = _item(
    {"id": _id, "position": _vec(3)},
    {"category": st.one_of(_id, st.none()), "aliases": _aliases},
)
_human = _item(
    {"id": _id, "position": _vec(3)}, {"name": st.one_of(_id, st.none()), "aliases": _aliases}
)
_surface = _item({"id": _id, "center": _vec(3), "size": _vec(2)}, {"aliases": _aliases})
_valid = _item(
    {"robots": st.lists(_robot, min_size=1, max_size=2)},
    {
        "units": st.sampled_from(["m", "cm", "mm"]),
        "objects": st.lists(_object, max_size=2),
        "humans": st.lists(_human, max_size=2),
        "surfaces": st.lists(_surface, max_size=2),
        "durations": st.one_of(
            st.none(), st.dictionaries(st.sampled_from(["pick", "place", "handover_r2h"]), _good)
        ),
        "human_reach": _good,
        "cameras": st.just([]),
    },
)


def _paths(v: Any, path: tuple[Any, ...] = ()) -> list[tuple[Any, ...]]:
    out = [path] if path else []
    if isinstance(v, dict):
        for k, x in v.items():
            out += _paths(x, (*path, k))
        out.append((*path, "bogus"))
    elif isinstance(v, list):
        for i, x in enumerate(v):
            out += _paths(x, (*path, i))
    return out


def _set(v: Any, path: tuple[Any, ...], value: Any) -> Any:
    if not path:
        return value
    head, rest = path[0], path[1:]
    if isinstance(v, dict):
        return {**v, head: _set(v.get(head), rest, value)}
    return [_set(x, rest, value) if i == head else x for i, x in enumerate(v)]


@st.composite
def _scene(draw: st.DrawFn) -> Any:
    data = draw(_valid)
    if draw(st.booleans()):
        path = draw(st.sampled_from(_paths(data)))
        data = _set(data, path, draw(_bad))
    return data


@settings(max_examples=400, deadline=None)
@given(_scene())
def test_plain_reader_agrees_with_the_validator(data: dict[str, Any]) -> None:
    raw = _plain(data)
    if raw is None:
        return  # the full validator decides
    full = _from_models(scene_schema.validate(data, "<test>"))
    # same values and same types (1 == 1.0, so compare the reprs too)
    assert raw == full
    assert repr(raw) == repr(full)


def test_loading_an_example_scene_does_not_import_pydantic() -> None:
    code = (
        "import sys\n"
        "from hltl.world.scene import load_scene\n"
        "load_scene('examples/scenes/two_arms.yaml')\n"
        "print('pydantic' in sys.modules)\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "False"


FULL = {
    "units": "cm",
    "robots": [{"id": "r1", "base": [0, 1.5, 0], "reach": 70, "model": "ur5", "speed": 0.2}],
    "objects": [{"id": "cup", "category": "mug", "position": [10, 0, 0], "aliases": ["mug"]}],
    "humans": [{"id": "A", "name": "Ann", "position": [0, 2, 0], "aliases": ["ann"]}],
    "surfaces": [{"id": "s1", "center": [1, 1, 0], "size": [2, 3.5], "aliases": ["shelf"]}],
    "durations": {"pick": 1, "place": 0.5, "handover_r2r": 0.0, "handover_r2h": 2},
    "human_reach": 25,
    "cameras": [],
}


def test_every_single_bad_field_is_left_to_the_validator() -> None:
    # exhaustive: every field of a complete scene (and an unknown one beside each) set to every
    # bad value; where the plain reader still accepts, the validator must agree exactly
    assert _plain(FULL) is not None
    for path in _paths(FULL):
        for bad in BAD:
            data = _set(FULL, path, bad)
            raw = _plain(data)
            if raw is not None:
                assert repr(raw) == repr(_from_models(scene_schema.validate(data, "<test>")))
