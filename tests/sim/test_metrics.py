"""Metrics from hand-made logs whose values are worked out by hand (docs/metrics.md)."""

from __future__ import annotations

from typing import Any

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.errors import PlanFormatError
from hltl.execution.log import parse_records
from hltl.sim.metrics import (
    compute_metrics,
    concurrent_time,
    functional_delay,
    functional_delay_union,
    overlap_time,
    percentile,
)

SCENE = {
    "robots": [
        {"id": "r1", "base": [0, 0, 0], "reach": 0.7},
        {"id": "r2", "base": [1.2, 0, 0], "reach": 0.9},
    ],
    "objects": [{"id": "x", "position": [0.2, 0, 0.05]}],
    "humans": [{"id": "A", "position": [1.5, 0.5, 0]}, {"id": "B", "position": [-0.5, 0, 0]}],
}
SPEC = {"root": "p0", "formulas": {"p0": "F p100", "p100": "F delivered(x, A)"}}


def _act(skill: str, robots: list[str], **kw: str) -> dict[str, Any]:
    return {"skill": skill, "robots": robots, "object": "x", **kw}


def _log(*, violation: bool = False, overlap: bool = False) -> list[dict[str, Any]]:
    pick, r2r = _act("pick", ["r1"]), _act("handover_r2r", ["r1", "r2"])
    r2h = _act("handover_r2h", ["r2"], human="A")
    recs: list[dict[str, Any]] = [
        {"t": 0.0, "type": "episode_start", "scene": SCENE, "spec": SPEC},
        {"t": 0.0, "type": "grounding", "text": "...", "tokens": 120, "spec": SPEC},
        {"t": 0.0, "type": "replan", "trigger": "initial", "source": "planner", "latency_ms": 10.0},
        {"t": 0.0, "type": "action_start", "handle": 1, "action": pick},
    ]
    if overlap:  # an asynchronous executor starting the exchange before the grasp ends
        recs += [
            {"t": 0.8, "type": "action_start", "handle": 2, "action": r2r},
            {"t": 1.0, "type": "action_done", "handle": 1, "action": pick},
        ]
    else:
        recs += [
            {"t": 1.0, "type": "action_done", "handle": 1, "action": pick},
            {
                "t": 1.0,
                "type": "replan",
                "trigger": "progress",
                "source": "planner",
                "latency_ms": 2.0,
            },
            {"t": 1.0, "type": "action_start", "handle": 2, "action": r2r},
        ]
    recs += [
        {"t": 2.0, "type": "action_done", "handle": 2, "action": r2r},
        {
            "t": 2.0,
            "type": "replan",
            "trigger": "halt:precondition",
            "source": "planner",
            "latency_ms": 4.0,
        },
        {"t": 2.4, "type": "takeover", "context": "A∈{r2}"},
        {
            "t": 2.4,
            "type": "replan",
            "trigger": "context",
            "source": "predicted",
            "latency_ms": 0.0,
        },
        {"t": 2.5, "type": "action_start", "handle": 3, "action": r2h},
    ]
    if violation:
        recs.append({"t": 3.0, "type": "violation", "handle": 3, "action": r2h, "reason": "r"})
    recs += [
        {"t": 3.6, "type": "action_done", "handle": 3, "action": r2h, "end": 3.5},
        {
            "t": 4.0,
            "type": "episode_end",
            "success": True,
            "reason": "all goals met",
            "time_cost": 4.0,
        },
    ]
    return recs


def test_hand_made_log() -> None:
    m = compute_metrics(parse_records(_log()))
    assert m.success and m.time_cost == 4.0 and m.violations == 0
    assert m.tokens == 120 and m.deliveries == 1 and m.takeovers == 1
    assert m.replans == 2  # the halt and the context change; initial and progress do not count
    assert m.planner_calls == 3
    # latencies after the first plan: 2, 4, 0 ms
    assert m.replan_latency_median_ms == 2.0
    assert m.replan_latency_p95_ms == pytest.approx(3.8)
    # r1 active 0-2 of 4 s, r2 1-2 and 2.5-3.5: both idle 50 %
    assert m.r_idle == pytest.approx(50.0)
    # Person A (the only recipient) receives 2.5-3.5; B takes no part and is not counted
    assert m.h_idle == pytest.approx(75.0)
    # two agents at once: 1-2 (r1, r2) and 2.5-3.5 (r2, A)
    assert m.c_act == pytest.approx(50.0)
    # hand-offs of x: pick(r1) -> r2r(r1, r2) at once, r2r -> r2h(r2) 0.5 s later: 0.5 / 4
    assert m.f_del == pytest.approx(12.5)
    # one object, so the union of its waits is the same 0.5 s
    assert m.f_del_union == pytest.approx(12.5)
    # a robot and A at once only while r2 hands x to A: 2.5-3.5
    assert m.c_act_hr == pytest.approx(25.0)
    assert m.h_idle_walk_active == pytest.approx(75.0)  # nobody walks: the same as h_idle


def test_violations_spoil_success_and_overlap_makes_f_del_negative() -> None:
    assert not compute_metrics(parse_records(_log(violation=True))).success
    m = compute_metrics(parse_records(_log(overlap=True)))
    # the exchange starts 0.2 s before the grasp ends (-0.2), the r2h 0.5 s after it (+0.5)
    assert m.f_del == pytest.approx(100 * 0.3 / 4.0)
    # one object: the union form agrees (0.5 s waiting minus 0.2 s anticipated)
    assert m.f_del_union == pytest.approx(100 * 0.3 / 4.0)


def test_helpers() -> None:
    assert percentile([5.0], 95) == 5.0
    assert percentile([1.0, 2.0, 3.0, 4.0, 5.0], 50) == 3.0
    agents = {"a": [(0.0, 2.0)], "b": [(1.0, 3.0)], "c": [(1.5, 1.8), (2.5, 4.0)]}
    assert concurrent_time(agents) == pytest.approx(1.5)  # 1-2 and 2.5-3
    assert concurrent_time(agents, at_least=3) == pytest.approx(0.3)


def test_truncated_or_malformed_logs_are_refused() -> None:
    with pytest.raises(PlanFormatError, match="no episode_end"):
        compute_metrics(parse_records(_log()[:-1]))
    with pytest.raises(PlanFormatError, match="empty"):
        compute_metrics(parse_records([]))


def _parallel_log() -> list[dict[str, Any]]:
    """Two objects waiting at once, and a recipient who walks before being served."""
    scene = {
        **SCENE,
        "robots": [*SCENE["robots"], {"id": "r3", "base": [0.6, 0.8, 0], "reach": 0.8}],
        "objects": [*SCENE["objects"], {"id": "y", "position": [0.6, 0.5, 0.05]}],
    }
    spec = {"root": "p0", "formulas": {"p0": "F delivered(x, A) & F delivered(y, A)"}}

    def act(skill: str, robots: list[str], obj: str, **kw: str) -> dict[str, Any]:
        return {"skill": skill, "robots": robots, "object": obj, **kw}

    def walk(t: float, who: str, eta: float) -> dict[str, Any]:
        return {"t": t, "type": "human_move", "human": who, "to": [1, 1, 0], "eta": eta}

    def start(t: float, h: int, a: dict[str, Any]) -> dict[str, Any]:
        return {"t": t, "type": "action_start", "handle": h, "action": a}

    def done(t: float, h: int, a: dict[str, Any]) -> dict[str, Any]:
        return {"t": t, "type": "action_done", "handle": h, "action": a}

    px, py = act("pick", ["r1"], "x"), act("pick", ["r3"], "y")
    hx = act("handover_r2h", ["r2"], "x", human="A")
    hy = act("handover_r2h", ["r1"], "y", human="A")
    return [
        {"t": 0.0, "type": "episode_start", "scene": scene, "spec": spec},
        start(0.0, 1, px),
        start(0.0, 2, py),
        walk(0.5, "A", 2.5),
        done(1.0, 1, px),
        walk(2.0, "A", 3.5),  # replaces the rest of the first walk
        done(2.0, 2, py),
        walk(2.2, "B", 3.0),  # B receives nothing: not a participant
        start(3.0, 3, hx),
        done(4.0, 3, hx),
        start(4.0, 4, hy),
        done(5.0, 4, hy),
        {"t": 10.0, "type": "episode_end", "success": True, "reason": "ok", "time_cost": 10.0},
    ]


def test_parallel_objects_walks_and_human_robot_concurrency() -> None:
    m = compute_metrics(parse_records(_parallel_log()))
    # x waits 1-3 (r1 -> r2), y waits 2-4 (r3 -> r1): summed 2 + 2 = 4 s, as a union 1-4 = 3 s
    assert m.f_del == pytest.approx(40.0)
    assert m.f_del_union == pytest.approx(30.0)
    # A is handed things over 3-5 (2 s of 10)
    assert m.h_idle == pytest.approx(80.0)
    # A walks 0.5-2 and 2-3.5; with the hand-overs A is active 0.5-5 (4.5 s)
    assert m.h_idle_walk_active == pytest.approx(55.0)
    # >= 2 agents: 0-1 (r1, r3), 3-4 (r2, A), 4-5 (r1, A) = 3 s
    assert m.c_act == pytest.approx(30.0)
    # a robot and a participant at once: 3-5
    assert m.c_act_hr == pytest.approx(20.0)
    # r1 active 2 s, r2 1 s, r3 2 s of 10
    assert m.r_idle == pytest.approx(100.0 * 25.0 / 30.0)


def test_a_walk_under_way_at_the_end_counts_until_the_end() -> None:
    recs = _parallel_log()
    recs.insert(-1, {"t": 9.0, "type": "human_move", "human": "A", "to": [0, 0, 0], "eta": 12.0})
    # active 0.5-5 and 9-10: 5.5 s of 10
    assert compute_metrics(parse_records(recs)).h_idle_walk_active == pytest.approx(45.0)


def test_old_logs_without_walk_arrival_still_score() -> None:
    recs = _parallel_log()
    for r in recs:
        if r["type"] == "human_move":
            del r["eta"]
    # each walk then lasts until the next one or the end: 0.5-10
    assert compute_metrics(parse_records(recs)).h_idle_walk_active == pytest.approx(5.0)


@st.composite
def _chains(draw: st.DrawFn) -> tuple[list[tuple[float, float, tuple[str, ...], str]], bool]:
    """Completed actions on a few objects, each object's actions in sequence (gaps >= 0),
    passed between robots; with ``serial`` the objects follow one another in time, so no two
    waits overlap."""
    serial = draw(st.booleans())
    out: list[tuple[float, float, tuple[str, ...], str]] = []
    t0 = 0.0
    for k in range(draw(st.integers(1, 4))):
        t = t0 if serial else draw(st.floats(0.0, 5.0))
        for _ in range(draw(st.integers(1, 4))):
            t += draw(st.floats(0.0, 2.0))  # the wait before this action
            dur = draw(st.floats(0.1, 2.0))
            robots = (draw(st.sampled_from(["r1", "r2", "r3"])),)
            out.append((t, t + dur, robots, f"o{k}"))
            t += dur
        t0 = t
    out.sort(key=lambda c: c[0])
    return out, serial


@settings(max_examples=60, deadline=None)
@given(_chains())
def test_union_never_exceeds_the_sum_and_equals_it_without_overlap(
    case: tuple[list[tuple[float, float, tuple[str, ...], str]], bool],
) -> None:
    completed, serial = case
    union, total = functional_delay_union(completed), functional_delay(completed)
    assert 0.0 <= union <= total + 1e-9  # every gap here is a wait (>= 0)
    if serial:
        assert union == pytest.approx(total, abs=1e-9)


_ivs = st.lists(
    st.tuples(st.integers(0, 20), st.integers(0, 20)).map(lambda p: (min(p), max(p))),
    max_size=5,
)


@settings(max_examples=60, deadline=None)
@given(_ivs, _ivs)
def test_overlap_time_matches_a_grid_count(
    a: list[tuple[int, int]], b: list[tuple[int, int]]
) -> None:
    # integer end points: each unit cell [k, k+1] is wholly inside a union or wholly outside
    def cover(ivs: list[tuple[int, int]]) -> set[int]:
        return {k for lo, hi in ivs for k in range(lo, hi)}

    fa = [(float(x), float(y)) for x, y in a]
    fb = [(float(x), float(y)) for x, y in b]
    assert overlap_time(fa, fb) == pytest.approx(len(cover(a) & cover(b)))


def test_overlapping_anticipations_count_once() -> None:
    # x and y are both taken over 1 s before their previous action ends, over the same second
    completed = [
        (0.0, 2.0, ("r1",), "x"),
        (0.0, 2.0, ("r2",), "y"),
        (1.0, 3.0, ("r3",), "x"),
        (1.0, 3.0, ("r4",), "y"),
    ]
    assert functional_delay(completed) == pytest.approx(-2.0)
    assert functional_delay_union(completed) == pytest.approx(-1.0)
