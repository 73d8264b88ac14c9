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

from hltl.bus.codec import Command, world_to_wire
from hltl.bus.driver import BusTiming
from hltl.bus.realtime import RealtimeBusCell
from hltl.execution.belief import Belief
from hltl.execution.drivers import ActionState, ActionStatus, Handle
from hltl.execution.executor import ExactPlanner, ExecutorConfig
from hltl.execution.log import EventLog
from hltl.sim.episode import EpisodeConfig, run_episode
from hltl.sim.events import EventSchedule, load_events
from hltl.sim.simulator import PerceptionModel
from hltl.skills.library import Action, Transition
from hltl.world.scene import load_scene
from hltl.world.state import Loc
from tests.bus.helpers import Loopback

ROOT = Path(__file__).resolve().parents[2]
SCENE = load_scene(ROOT / "examples" / "scenes" / "two_arms.yaml")
EVENTS = load_events(ROOT / "examples" / "events" / "h_move_midhandover.yaml", SCENE)
# a quarter of a cell second per wall second (slower than real arms): the guard has one tick
# to act in (A stands inside both workspaces at t = 1.05, the hand-over ends at 1.10), which at
# one cell second per wall second was 50 ms of wall time for the tick to reach the executor, be
# checked there and the halt to reach the node, all in one process with the slow replan holding
# the interpreter; on the landing train's loaded machine that went by (the red trains of
# sessions 29 and 30, also rerun alone). At 0.25 it is 200 ms (docs/bus.md, "Tests and time")
FACTOR = 0.25
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


def test_the_guard_acts_only_while_the_loop_is_away_and_says_it_again(
    loopback: Loopback, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The guard's rules, tick by tick (a check that names one running action): nothing while
    the loop keeps up; a halt once it has been away for two ticks; not again for an older tick
    or within the bus timeout (the halt may be on its way); again after it (it may have been
    lost); never for an action whose report says it ended."""
    scene = SCENE
    with loopback.node(scene):
        cell = RealtimeBusCell(
            loopback._exec_session,
            scene,
            EventSchedule(),
            0,
            PerceptionModel(),
            EventLog(),
            factor=10.0,
            timing=BusTiming(timeout=0.1, retries=6),
        )
        try:
            sent: list[Command] = []
            monkeypatch.setattr(
                cell.link, "put", lambda key, data, **_: sent.append(Command.decode(data))
            )
            action = Action("pick", ("r2",), "chips")
            handle = Handle(7, action, 0.0)
            cell.guard(lambda world: [(handle, "chips out of reach")])
            world = world_to_wire(cell.observe(0.0))
            n = [0]

            def tick() -> None:
                n[0] += 1
                cell._guard_tick({"n": n[0], "observation": world})

            cell._loop_at = time.monotonic() + 3600.0  # the loop keeps up: it checks itself
            tick()
            assert sent == []
            cell._loop_at = time.monotonic() - 1.0  # away for 1 s: 200 ticks at 10x
            tick()
            assert [(c.op, c.handle, c.seq) for c in sent] == [("halt", 7, cell._seq)]
            assert "chips out of reach" in sent[0].reason and "guard" in sent[0].reason
            cell._guard_tick({"n": n[0] - 1, "observation": world})  # an older tick
            tick()  # within the timeout: the halt is on its way
            assert len(sent) == 1 and cell.stats.guarded == 1
            cell._guard_halts[7] -= 1.0  # the timeout passed, no report: said again
            tick()
            assert len(sent) == 2 and cell.stats.guarded == 1  # (one action halted)
            cell._local[7] = ActionStatus(ActionState.HALTED, 0.0, 0.0, "halted")
            cell._guard_halts[7] -= 1.0
            tick()  # it ended: nothing more
            assert len(sent) == 2
        finally:
            cell.end()
            cell.close()


def test_the_guard_checks_the_belief_with_the_observation_merged_in() -> None:
    """The guard's world is what the loop's next observation will make of its belief
    (``Belief.merged``), taking nothing in: a person's new place is in it, and an object the
    executor's own action moved stays where the belief has it even while the observation
    lags (a lagging observation must not halt anything)."""
    belief = Belief(SCENE)
    start = belief.world
    lagging = start.with_human("A", (0.3, 0.5, 0.0)).with_time(0.5)
    chips = start.object_status("chips").loc
    picked = Transition("chips", chips, Loc("held", "r2"), (), frozenset(), ())
    belief.completed(picked, 0.4)  # r2 picked the chips at 0.4; the camera still shows them
    belief.failed("bottle", 0.2)  # re-observed after a failure: the observation decides
    merged = belief.merged(lagging)
    assert merged.human_position("A") == (0.3, 0.5, 0.0)
    assert merged.object_status("chips").loc == Loc("held", "r2")
    assert belief.reobserving  # (merging took nothing in)
    assert belief.world.human_position("A") == start.human_position("A")
    belief.observe(lagging, 0.5)
    assert belief.world == merged.with_time(0.5) and not belief.reobserving
