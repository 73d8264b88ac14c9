"""Skeleton outlier rejection: bones no longer than a human's, and joints that jump relative
to the body held back until a second frame confirms them."""

from __future__ import annotations

import math

from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.perception.skeleton import (
    BONES,
    JOINT_SPEED,
    JUMP_SLACK,
    JointGate,
    Skeleton,
    drop_broken_bones,
)

Vec3 = tuple[float, float, float]
NAMES = ("l_shoulder", "r_shoulder", "l_elbow", "r_elbow", "l_wrist", "r_wrist")


def body(x: float = 1.0, y: float = 2.0, swing: float = 0.0) -> dict[str, Vec3]:
    """The simulator's person at (x, y) facing +x: shoulders 0.42 m apart at 1.41 m, upper
    arms 0.29 m and forearms 0.23 m hanging, swung forward by ``swing`` radians."""
    out: dict[str, Vec3] = {}
    for side, sy in (("l", 0.21), ("r", -0.21)):
        s = (x, y + sy, 1.41)
        e = (x + 0.29 * math.sin(swing), y + sy, 1.41 - 0.29 * math.cos(swing))
        w = (e[0] + 0.23 * math.sin(swing), y + sy, e[2] - 0.23 * math.cos(swing))
        out.update({f"{side}_shoulder": s, f"{side}_elbow": e, f"{side}_wrist": w})
    return out


def sk(joints: dict[str, Vec3 | None]) -> Skeleton:
    return Skeleton(
        tuple((k, joints.get(k)) for k in NAMES),
        tuple((k, None if joints.get(k) is None else (0.0, 0.0)) for k in NAMES),
    )


def test_a_human_skeleton_keeps_every_joint_and_stretched_bones_lose_the_outer_joint() -> None:
    j = body()
    assert drop_broken_bones(sk(dict(j)), (1.0, 2.0)) == sk(dict(j))
    bad = dict(j)
    bad["l_wrist"] = (1.0, 2.21, 0.2)  # 0.68 m below its elbow: the floor's depth
    out = drop_broken_bones(sk(bad), (1.0, 2.0))
    assert out.joint("l_wrist") is None and out.seen == 5
    assert dict(out.pixels)["l_wrist"] is None
    bad = dict(j)
    bad["r_elbow"] = (1.6, 1.79, 1.2)  # 0.64 m from its shoulder
    out = drop_broken_bones(sk(bad), (1.0, 2.0))
    assert out.joint("r_elbow") is None and out.joint("r_wrist") == j["r_wrist"]
    bad = dict(j)
    bad["r_shoulder"] = (1.0, 1.3, 1.41)  # 0.91 m from the other: not one body's
    out = drop_broken_bones(sk(bad), (1.0, 2.0))
    assert out.joint("r_shoulder") is None and out.joint("l_shoulder") == j["l_shoulder"]


def test_bone_limits_are_longer_than_the_simulated_person_s() -> None:
    j = body()
    for inner, outer, length in BONES:
        assert math.dist(j[f"l_{inner}"], j[f"l_{outer}"]) < length


@settings(max_examples=40, deadline=None)
@given(
    st.lists(st.floats(-0.6, 0.6), min_size=3, max_size=25),
    st.floats(0.0, 1.2),
)
def test_a_walker_swinging_arms_within_reach_speeds_is_never_held(
    swings: list[float], speed: float
) -> None:
    gate = JointGate()
    dt = 0.1
    prev = swings[0]
    # at most 0.5 rad per frame: the wrist (0.52 m out) moves 0.26 m, the elbow 0.15 m, within
    # their limits (JOINT_SPEED x 0.1 s); the body walks at ``speed``
    step = min(0.52 * 0.5 / (JOINT_SPEED["wrist"] * dt), 0.29 * 0.5 / (JOINT_SPEED["elbow"] * dt))
    assert step <= 1.0
    for k, s in enumerate(swings):
        prev += max(-0.5, min(0.5, s - prev))
        x = 1.0 + speed * dt * k
        out = gate.update(sk(dict(body(x, 2.0, prev))), (x, 2.0), dt * k)
        assert out.seen == 6
    assert gate.held == 0


def test_a_one_frame_left_right_mix_up_is_held_and_a_real_move_is_confirmed() -> None:
    gate = JointGate()
    for k in range(3):
        assert gate.update(sk(dict(body())), (1.0, 2.0), 0.1 * k).seen == 6
    swapped = dict(body())
    swapped["l_wrist"], swapped["r_wrist"] = swapped["r_wrist"], swapped["l_wrist"]
    out = gate.update(sk(swapped), (1.0, 2.0), 0.3)
    assert out.joint("l_wrist") is None and out.joint("r_wrist") is None and out.seen == 4
    assert gate.update(sk(dict(body())), (1.0, 2.0), 0.4).seen == 6  # back where they were
    assert gate.held == 2
    # an arm raised quickly (wrist 0.9 m up in 0.1 s) and kept there: held once, then taken
    up = dict(body())
    up["l_wrist"] = (1.0, 2.21, 1.95)
    assert gate.update(sk(up), (1.0, 2.0), 0.5).joint("l_wrist") is None
    assert gate.update(sk(up), (1.0, 2.0), 0.6).joint("l_wrist") == up["l_wrist"]
    assert JUMP_SLACK < 0.45  # a 0.42 m swap is never within the slack alone
