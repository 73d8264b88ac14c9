"""The ticks block: ticks ahead cross the bus bit for bit, decoded one at a time; bad bytes are
one clear error."""

from __future__ import annotations

import json
import struct

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.bus.codec import Report
from hltl.bus.ticks import MAGIC, STATES, Tick, decode_answer, encode_answer, encode_ticks
from hltl.errors import BusError
from hltl.execution.drivers import ActionStatus
from hltl.skills.library import Action
from hltl.world.state import Loc, ObjectStatus, WorldState

floats = st.floats(allow_nan=False, min_value=-1e6, max_value=1e6) | st.sampled_from(
    [0.1 + 0.2, 1.0 / 3.0, -0.0, 5e-324]
)
points = st.tuples(floats, floats, floats)
names = st.text(min_size=1, max_size=6)
locs = st.builds(Loc, st.sampled_from(["rest", "held", "on", "delivered"]), st.text(max_size=4))


@st.composite
def worlds(draw: st.DrawFn, t: float) -> WorldState:
    def group(values: st.SearchStrategy) -> tuple:  # type: ignore[type-arg]
        ids = draw(st.lists(names, max_size=3, unique=True))
        return tuple((k, draw(values)) for k in ids)

    return WorldState(
        t=t,
        humans=group(points),
        objects=group(st.builds(ObjectStatus, points, locs)),
        hands=group(points),
        unavailable=frozenset(draw(st.lists(names, max_size=2))),
    )


@st.composite
def ticks(draw: st.DrawFn) -> list[Tick]:
    """A stretch: often the world only partly changes from one tick to the next."""
    out: list[Tick] = []
    for i in range(draw(st.integers(1, 6))):
        t = draw(floats)
        w = draw(worlds(t))
        keep_some: bool = draw(st.booleans())
        if out and keep_some:  # some parts as the tick before's
            before = out[-1].world
            keep = draw(st.sets(st.sampled_from(["humans", "objects", "hands", "unavailable"])))
            parts = ("humans", "objects", "hands", "unavailable")
            w = WorldState(t=t, **{k: getattr(before if k in keep else w, k) for k in parts})
        statuses = st.builds(
            ActionStatus, st.sampled_from(STATES), floats, floats, st.text(max_size=8)
        )
        u32 = st.integers(0, 2**32 - 1)
        guess = draw(st.booleans())
        starts = tuple(
            (draw(u32), draw(u32), Action("pick", (draw(names),), draw(names)))
            for _ in range(draw(st.integers(0, 2) if guess else st.just(0)))
        )
        reports = tuple(
            Report("ep", draw(u32), draw(u32), draw(statuses))
            for _ in range(draw(st.integers(0, 3)))
        )
        out.append(
            Tick(
                t=t,
                world=w,
                reports=reports,
                next=draw(st.none() | floats),
                pending=draw(st.booleans()),
                count=draw(st.integers(0, 2**32 - 1)),
                unavailable=tuple(draw(st.lists(names, max_size=2))),
                instructions=tuple(draw(st.lists(st.text(max_size=20), max_size=2))),
                records=tuple(
                    draw(st.lists(st.fixed_dictionaries({"kind": names, "t": floats}), max_size=2))
                ),
                guess=guess,
                starts=starts,
            )
        )
        del i
    return out


def _bits(x: float | None) -> bytes | None:
    return None if x is None else struct.pack("<d", x)


def assert_same_tick(got: Tick, want: Tick) -> None:
    """Equal, and every float equal bit for bit (``==`` would let -0.0 pass for 0.0)."""
    assert got == want
    assert _bits(got.t) == _bits(want.t) and _bits(got.next) == _bits(want.next)
    for (_, p), (_, q) in zip(
        got.world.humans + got.world.hands, want.world.humans + want.world.hands, strict=True
    ):
        assert [_bits(x) for x in p] == [_bits(x) for x in q]
    for (_, a), (_, b) in zip(got.world.objects, want.world.objects, strict=True):
        assert [_bits(x) for x in a.position] == [_bits(x) for x in b.position]


@settings(max_examples=80, deadline=None)
@given(ticks())
def test_ticks_cross_the_bus_bit_for_bit(stretch: list[Tick]) -> None:
    answer = {"episode": "ep", "step": 3, "next": None, "reports": 7}
    payload = encode_answer(answer, stretch)
    assert payload.startswith(MAGIC)
    d, reader = decode_answer(payload, "step answer", "ep")
    assert d == answer and reader is not None and reader.size == len(stretch)
    for want in stretch:
        assert reader.peek_time() == want.t
        assert reader.peek_guess() is want.guess  # (a guessed step's starts, not a tick)
        assert reader.peek_starts() == (want.t, want.starts)  # (without decoding the world)
        assert_same_tick(reader.take(), want)
    assert reader.peek_time() is None
    with pytest.raises(BusError, match="no tick left"):
        reader.take()


def test_an_answer_without_ticks_is_plain_json() -> None:
    payload = encode_answer({"episode": "ep", "ended": True})
    assert json.loads(payload) == {"episode": "ep", "ended": True}
    assert decode_answer(payload, "step answer") == ({"episode": "ep", "ended": True}, None)


def test_reports_take_the_requests_episode() -> None:
    w = WorldState(t=0.5, humans=(), objects=())
    rep = Report("node-ep", 1, 2, ActionStatus(STATES[1], 1.0, 0.5, "ok"))
    _, reader = decode_answer(encode_answer({}, [Tick(0.5, w, (rep,))]), "x", "mine")
    assert reader is not None
    (got,) = reader.take().reports
    assert got.episode == "mine" and got.status == rep.status


def test_an_unchanged_group_keeps_the_tick_befores_values() -> None:
    """Decoding reuses what did not change (the lazy part): the same tuple, not a new one."""
    w1 = WorldState(t=0.1, humans=(("A", (1.0, 2.0, 0.0)),), objects=(), hands=(("r1", (0, 0, 1)),))
    w2 = WorldState(t=0.2, humans=w1.humans, objects=(), hands=(("r1", (0.0, 0.5, 1.0)),))
    _, reader = decode_answer(encode_answer({}, [Tick(0.1, w1), Tick(0.2, w2)]), "x")
    assert reader is not None
    a, b = reader.take().world, reader.take().world
    assert (a, b) == (w1, w2)
    assert b.humans is a.humans and b.hands is not a.hands


@pytest.mark.parametrize(
    "cut",
    [5, 9, 12, 30, 40, -1],
)
def test_a_truncated_block_is_a_bus_error_not_a_crash(cut: int) -> None:
    w = WorldState(
        t=0.1,
        humans=(("A", (1.0, 2.0, 0.0)),),
        objects=(("cup", ObjectStatus((0.0, 0.0, 0.0), Loc("held", "r1"))),),
    )
    rep = Report("e", 1, 2, ActionStatus(STATES[0], 0.5, 0.1))
    payload = encode_answer({"step": 1}, [Tick(0.1, w, (rep,), instructions=("hi",))])
    bad = payload[:cut]
    with pytest.raises(BusError, match="malformed step answer"):
        _, reader = decode_answer(bad, "step answer")
        assert reader is not None
        reader.take()


@pytest.mark.parametrize(
    "block",
    [
        # a first tick without a layout
        struct.pack("<I", 1) + struct.pack("<ddIBB", 0.1, 0.2, 0, 0, 0),
        # its last part cut short
        encode_ticks([Tick(0.1, WorldState(t=0.1, humans=(), objects=()))])[:-2],
    ],
)
def test_malformed_blocks_are_bus_errors(block: bytes) -> None:
    head = b'{"step":1}'
    payload = MAGIC + struct.pack("<I", len(head)) + head + block
    with pytest.raises(BusError, match="malformed step answer"):
        _, reader = decode_answer(payload, "step answer")
        assert reader is not None
        reader.take()


def test_an_object_that_changes_place_where_it_lies_is_not_taken_from_the_tick_before() -> None:
    """A pick leaves the object where it was, now held: same bytes, another place."""
    cup = (0.25, -0.5, 0.05)
    w1 = WorldState(t=0.1, humans=(), objects=(("cup", ObjectStatus(cup, Loc("rest"))),))
    w2 = WorldState(t=0.2, humans=(), objects=(("cup", ObjectStatus(cup, Loc("held", "r1"))),))
    _, reader = decode_answer(encode_answer({}, [Tick(0.1, w1), Tick(0.2, w2), Tick(0.3, w2)]), "x")
    assert reader is not None
    assert [reader.take().world.objects for _ in range(3)] == [w1.objects, w2.objects, w2.objects]
