"""The guard: in real time, the executor's safety check keeps running while its loop is busy.

A person walks between the arms while they hand the chips over (examples/events/
h_move_midhandover.yaml); the executor replans when it sees the walk, and here that replan is
made slow on purpose (the executor plans a takeover on A's forecast walk, and that plan keeps
the loop busy through the moment A breaks the hand-over's precondition and past the
hand-over's planned end). Without the
guard nothing halts the hand-over until the loop is back: it ends with the person in its way,
a safety violation. With it, the hand-over is halted on the node once the person breaks its
precondition, before it ends, and the episode goes on as in-process (the chips to A by r2).
"""

from __future__ import annotations

import time
from pathlib import Path
from typing import Any

import pytest

from hltl.bus.driver import BusTiming
from hltl.bus.realtime import RealtimeBusCell
from hltl.execution.executor import ExactPlanner, ExecutorConfig
from hltl.sim.episode import EpisodeConfig, run_episode
from hltl.sim.events import load_events
from hltl.world.scene import load_scene
from tests.bus.helpers import Loopback

ROOT = Path(__file__).resolve().parents[2]
SCENE = load_scene(ROOT / "examples" / "scenes" / "two_arms.yaml")
EVENTS = load_events(ROOT / "examples" / "events" / "h_move_midhandover.yaml", SCENE)
# one cell second per wall second (real arms' pace): a loaded machine's stalls (tens of
# milliseconds) are small against the hand-over's second and the slow replan's
FACTOR = 1.0
MARGIN = 0.3  # cell seconds the slow replan lasts past the hand-over's planned end
# the executor's own halt is the reactive one only (no halt on a forecast intrusion, which
# could come before the slow replan or not, by timing): in-process it halts the hand-over at
# t = 1.05, when A stands inside both workspaces
EPISODE: dict[str, Any] = {
    "instruction": "Give Person A the chips",
    "events": EVENTS,
    "seed": 0,
    "config": EpisodeConfig(executor=ExecutorConfig(intrusion=False)),
}


class SlowPlanner:
    """The exact planner, made slow once on purpose: the first plan while the arms hand the
    chips over with Person A on the move (the executor plans a takeover on A's forecast walk)
    keeps the loop's thread busy, computing (holding the interpreter, as a planner does),
    until ``MARGIN`` past the hand-over's planned end (by the wall clock from its start)."""

    def __init__(self) -> None:
        self.exact = ExactPlanner()
        self.handover: tuple[float, float] | None = None  # its start (wall) and expected end
        self.slowed = False

    def on_record(self, rec: Any) -> None:
        if rec.type == "action_start" and rec.action["skill"] == "handover_r2r":
            self.handover = (time.monotonic(), rec.expected)
        elif rec.type in ("action_done", "action_failed", "action_halted"):
            self.handover = None  # (nothing else runs beside it)

    def __call__(self, *args: Any, **kwargs: Any) -> Any:
        result = self.exact(*args, **kwargs)
        a = kwargs["world"].human_position("A")
        moved = abs(a[0] - SCENE.human("A").position[0]) > 1e-6
        if not self.slowed and self.handover is not None and moved:
            self.slowed = True
            w0, expected = self.handover
            end = w0 + (expected + MARGIN) / FACTOR
            while time.monotonic() < end:
                sum(range(1000))
        return result


def _run(lb: Loopback) -> Any:
    planner = SlowPlanner()
    run = lb.run(
        SCENE,
        realtime=FACTOR,
        timing=BusTiming(timeout=0.1, retries=6),
        planner=planner,
        on_record=planner.on_record,
        **EPISODE,
    )
    assert planner.slowed  # a replan while the hand-over ran was slow
    return run


def _handover(ep: Any) -> tuple[Any, Any]:
    start = next(
        r for r in ep.records if r.type == "action_start" and r.action["skill"] == "handover_r2r"
    )
    end = next(
        r
        for r in ep.records
        if r.type in ("action_done", "action_failed", "action_halted") and r.handle == start.handle
    )
    return start, end


def test_the_guard_halts_a_handover_while_the_loop_replans(loopback: Loopback) -> None:
    run = _run(loopback)
    ep = run.episode
    start, end = _handover(ep)
    assert end.type == "action_halted", [r.type for r in ep.records]
    assert "guard" in end.reason and "both" in end.reason  # A inside both workspaces
    # halted on the node before the hand-over would have ended, after A stepped in
    assert end.end < start.t + start.expected
    assert not [r for r in ep.records if r.type == "violation"]
    assert run.cell.stats.guarded == 1
    # the loop was back only after the hand-over's planned end: its own check was too late
    assert end.t >= start.t + start.expected
    local = run_episode(SCENE, **EPISODE)
    assert ep.success and ep.records[-1].done == local.records[-1].done


def test_without_the_guard_the_slow_replan_is_a_violation(
    loopback: Loopback, monkeypatch: pytest.MonkeyPatch
) -> None:
    # (the test above can fail: with the guard off, the same episode breaks safety)
    monkeypatch.setattr(RealtimeBusCell, "guard", lambda self, check: None)
    run = _run(loopback)
    ep = run.episode
    _, end = _handover(ep)
    # it ran to its end with A in its way: a violation, and it failed there
    assert end.type == "action_failed" and "precondition false at completion" in end.reason
    assert [r for r in ep.records if r.type == "violation"]
    assert run.cell.stats.guarded == 0
