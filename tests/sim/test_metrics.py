"""Metrics from hand-made logs whose values are worked out by hand (docs/metrics.md)."""

from __future__ import annotations

from typing import Any

import pytest

from hltl.errors import PlanFormatError
from hltl.sim.metrics import compute_metrics, concurrent_time, percentile

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
    m = compute_metrics(_log())
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


def test_violations_spoil_success_and_overlap_makes_f_del_negative() -> None:
    assert not compute_metrics(_log(violation=True)).success
    m = compute_metrics(_log(overlap=True))
    # the exchange starts 0.2 s before the grasp ends (-0.2), the r2h 0.5 s after it (+0.5)
    assert m.f_del == pytest.approx(100 * 0.3 / 4.0)


def test_helpers() -> None:
    assert percentile([5.0], 95) == 5.0
    assert percentile([1.0, 2.0, 3.0, 4.0, 5.0], 50) == 3.0
    agents = {"a": [(0.0, 2.0)], "b": [(1.0, 3.0)], "c": [(1.5, 1.8), (2.5, 4.0)]}
    assert concurrent_time(agents) == pytest.approx(1.5)  # 1-2 and 2.5-3
    assert concurrent_time(agents, at_least=3) == pytest.approx(0.3)


def test_truncated_or_malformed_logs_are_refused() -> None:
    with pytest.raises(PlanFormatError, match="no episode_end"):
        compute_metrics(_log()[:-1])
    with pytest.raises(PlanFormatError, match="empty"):
        compute_metrics([])
