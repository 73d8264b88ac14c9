"""Payloads: hltl's JSON records round-trip exactly; ROS 2 types are real CDR (checked against
the byte layout of the OMG CDR standard, written out by hand with struct)."""

from __future__ import annotations

import math
import struct

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.bus.codec import (
    Command,
    JointStateMsg,
    Report,
    StampedPose,
    WireTrajectory,
    decode_joint_state,
    decode_pose,
    decode_trajectory,
    encode_joint_state,
    encode_pose,
    encode_trajectory,
    world_from_wire,
    world_to_wire,
)
from hltl.bus.keys import Keys, robot_of
from hltl.bus.session import DEFAULT_ENDPOINT, BusConfig, parse_bus
from hltl.errors import BusError
from hltl.execution.drivers import ActionState, ActionStatus
from hltl.skills.library import Action
from hltl.world.state import Loc, ObjectStatus, WorldState

floats = st.floats(allow_nan=False, allow_infinity=False, min_value=-1e6, max_value=1e6)
points = st.tuples(floats, floats, floats)


@settings(max_examples=30, deadline=None)
@given(points, points, floats, st.sampled_from(["rest", "held", "on", "delivered"]))
def test_world_states_cross_the_bus_bit_for_bit(p: tuple, q: tuple, t: float, kind: str) -> None:
    w = WorldState(
        t=t,
        humans=(("A", p),),
        objects=(("bottle", ObjectStatus(q, Loc(kind, "" if kind == "rest" else "r1"))),),  # type: ignore[arg-type]
        hands=(("r1", q), ("r2", p)),
        unavailable=frozenset({"r2"}),
    )
    import json

    assert world_from_wire(json.loads(json.dumps(world_to_wire(w)))) == w


def test_a_tick_ahead_leaves_out_its_reports_episode_and_empty_reason() -> None:
    rep = Report("ep", 9, 3, ActionStatus(ActionState.RUNNING, 0.25, 1.0 / 3.0))
    compact = {k: v for k, v in rep.to_dict().items() if k not in ("episode", "reason")}
    assert Report.from_dict(compact, "ep") == rep
    assert Report.from_dict(rep.to_dict(), "other") == rep  # its own episode wins
    with pytest.raises(BusError, match="malformed action report"):
        Report.from_dict(compact)  # an episode is needed from somewhere


def test_commands_and_reports_round_trip() -> None:
    a = Action("handover_r2r", ("r2", "r1"), "chips")
    cmd = Command("ep", 7, "start", 3, a, 0.1 + 0.2, "")
    assert Command.decode(cmd.encode()) == cmd
    rep = Report("ep", 9, 3, ActionStatus(ActionState.FAILED, 0.25, 1.0 / 3.0, "pick failed"))
    assert Report.decode(rep.encode()) == rep


@pytest.mark.parametrize(
    "payload",
    [
        b"",
        b"[1]",
        b'{"op": "start"}',
        b'{"episode":"e","seq":1,"op":"jump","handle":1,"action":{},"t":0}',
    ],
)
def test_malformed_commands_are_bus_errors(payload: bytes) -> None:
    with pytest.raises(BusError, match="command"):
        Command.decode(payload)


def _cdr_string(s: str, offset: int) -> tuple[bytes, int]:
    raw = s.encode() + b"\0"
    pad = (-offset) % 4
    return b"\0" * pad + struct.pack("<I", len(raw)) + raw, offset + pad + 4 + len(raw)


def test_pose_stamped_is_standard_cdr() -> None:
    pose = StampedPose("world", 12.25, (1.0, -2.0, 0.5), (0.0, 0.0, 0.0, 1.0))
    # encapsulation header (CDR little endian), then the body aligned from its own start
    body = struct.pack("<iI", 12, 250_000_000)
    s, off = _cdr_string("world", len(body))
    body += s
    body += b"\0" * ((-off) % 8)
    body += struct.pack("<7d", 1.0, -2.0, 0.5, 0.0, 0.0, 0.0, 1.0)
    assert encode_pose(pose) == b"\x00\x01\x00\x00" + body
    assert decode_pose(encode_pose(pose)) == pose


def test_joint_trajectory_round_trip_to_the_nanosecond() -> None:
    traj = WireTrajectory(
        "r1",
        ("j1", "j2"),
        (0.0, 0.5, 1.25),
        ((0.0, 0.1), (0.2, 0.3), (0.4, -0.5)),
        ((0.0, 0.0), (0.1, 0.1), (0.0, 0.0)),
    )
    back = decode_trajectory(encode_trajectory(traj, t=3.0))
    assert back.robot == "r1" and back.joint_names == traj.joint_names
    assert back.positions == traj.positions and back.velocities == traj.velocities
    pairs = zip(back.times, traj.times, strict=True)
    assert all(math.isclose(a, b, abs_tol=1e-9) for a, b in pairs)
    no_v = WireTrajectory("r2", ("j",), (0.0, 1.0), ((0.0,), (1.0,)))
    assert decode_trajectory(encode_trajectory(no_v)).velocities is None


def test_joint_state_round_trip() -> None:
    js = JointStateMsg(2.5, ("a", "b"), (0.1, 0.2), (0.0, -1.0))
    assert decode_joint_state(encode_joint_state(js)) == js


def test_garbage_cdr_is_a_bus_error() -> None:
    with pytest.raises(BusError, match="PoseStamped"):
        decode_pose(b"\x00\x01\x00\x00\x01")


def test_key_expressions() -> None:
    k = Keys("lab")
    assert k.action("r1") == "hltl/lab/robots/r1/action"
    assert k.human_pose("A") == "hltl/lab/humans/A/pose"
    assert k.sim_step == "hltl/lab/sim/step"
    assert robot_of(k.status("r2")) == "r2"
    with pytest.raises(BusError, match="cell name"):
        Keys("a/b")
    with pytest.raises(BusError, match="robot name"):
        k.action("r*")


def test_bus_option_and_endpoints() -> None:
    assert parse_bus("zenoh") == DEFAULT_ENDPOINT
    assert parse_bus("zenoh:tcp/10.0.0.2:7447") == "tcp/10.0.0.2:7447"
    with pytest.raises(BusError, match="unknown bus"):
        parse_bus("dds")
    with pytest.raises(BusError, match="bad Zenoh endpoint"):
        parse_bus("zenoh:localhost")
    with pytest.raises(BusError, match="bad Zenoh endpoint"):
        BusConfig(listen=("127.0.0.1:7447",))
