"""``hltl.bus.snapshot``: copies that later changes do not reach, checked against pickle."""

from __future__ import annotations

import enum
import pickle
import random
from dataclasses import dataclass, field
from typing import Any

from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.bus.snapshot import freeze, thaw


class Colour(enum.Enum):
    RED = "red"
    BLUE = "blue"


@dataclass(frozen=True, slots=True)
class Pose:
    t: float
    p: tuple[float, float, float]


@dataclass(slots=True)
class Box:
    items: list[Any] = field(default_factory=list)
    label: str = ""
    pose: Pose | None = None


class Opaque:
    """Neither a container nor a dataclass: pickled."""

    def __init__(self, v: Any) -> None:
        self.v = v

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Opaque) and other.v == self.v

    __hash__ = None  # type: ignore[assignment]


_leaves = st.one_of(
    st.integers(),
    st.floats(allow_nan=False),
    st.text(max_size=4),
    st.none(),
    st.booleans(),
    st.sampled_from(Colour),
    st.builds(Pose, st.floats(allow_nan=False), st.tuples(*[st.floats(allow_nan=False)] * 3)),
)


def _grow(children: st.SearchStrategy[Any]) -> st.SearchStrategy[Any]:
    return st.one_of(
        st.lists(children, max_size=4),
        st.dictionaries(st.text(max_size=3), children, max_size=4),
        st.tuples(children, children),
        st.builds(Box, st.lists(children, max_size=3), st.text(max_size=3)),
        st.builds(Opaque, children),
        st.integers(0, 2**32).map(random.Random),
    )


_states = st.dictionaries(st.text(max_size=4), st.recursive(_leaves, _grow, max_leaves=20))


def _canon(x: Any) -> Any:
    """``x`` as comparable values (a random generator by its state), for the oracle."""
    if isinstance(x, random.Random):
        return ("rng", x.getstate())
    if isinstance(x, Box):
        return ("box", _canon(x.items), x.label, x.pose)
    if isinstance(x, Opaque):
        return ("opaque", _canon(x.v))
    if isinstance(x, list | tuple):
        return (type(x).__name__, [_canon(v) for v in x])
    if isinstance(x, dict):
        return {k: _canon(v) for k, v in x.items()}
    return x


def _mutate(x: Any, rng: random.Random) -> None:
    """Change every mutable thing in ``x`` in place."""
    if isinstance(x, list):
        for v in x:
            _mutate(v, rng)
        x.append("added")
    elif isinstance(x, dict):
        for v in list(x.values()):
            _mutate(v, rng)
        x["added"] = 1
    elif isinstance(x, tuple):
        for v in x:
            _mutate(v, rng)
    elif isinstance(x, Box):
        _mutate(x.items, rng)
        x.label += "!"
    elif isinstance(x, Opaque):
        _mutate(x.v, rng)
        x.v = ("changed", x.v)
    elif isinstance(x, random.Random):
        x.random()


@settings(max_examples=150, deadline=None)
@given(_states, st.integers(0, 1000))
def test_a_snapshot_is_what_pickle_would_have_kept(state: dict[str, Any], seed: int) -> None:
    oracle = pickle.loads(pickle.dumps(state))  # an independent copy, made the old way
    snap = freeze(state)
    _mutate(state, random.Random(seed))
    first = thaw(snap)
    assert _canon(first) == _canon(oracle)
    _mutate(first, random.Random(seed))  # a restored state changes: the snapshot does not
    assert _canon(thaw(snap)) == _canon(oracle)


def test_frozen_values_are_shared_and_aliases_stay_one_object() -> None:
    pose = Pose(0.0, (1.0, 2.0, 3.0))
    shared = [pose, (0.5, pose)]
    box = Box(shared, "b", pose)
    rng = random.Random(3)
    state = {"a": shared, "b": box, "c": (shared, 1.0), "r": rng, "r2": rng}
    copy = thaw(freeze(state))
    assert copy["a"] is not shared and copy["a"] == shared
    assert copy["a"][0] is pose and copy["b"].pose is pose  # values: never copied
    assert copy["a"][1] is shared[1]  # a tuple of values is a value
    assert copy["b"].items is copy["a"] and copy["c"][0] is copy["a"]  # one list, as before
    assert copy["r"] is copy["r2"] and copy["r"] is not rng
    assert copy["r"].random() == rng.random()
