"""A halt that comes after the action ended (real time: the robots run on their own clock).

In real time the executor decides a halt on what it has heard, and the node acts on it when it
arrives: an action may end in between (a hand-over done). The executor must then take that end
in, not believe the action halted: believing the object still in the giver's hand, it would
dispatch it again, and a real arm would act on a world that is not there (the cause of the
real-time suite's "safety violations": docs/bus.md, "Real time")."""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from hltl.bus.realtime import RealtimeBusCell
from hltl.execution.drivers import ActionState, ActionStatus, Handle, OwnClock
from hltl.execution.executor import ExecStatus, Executor, ExecutorConfig
from hltl.execution.log import EpisodeStart, EventLog
from hltl.sim.events import EventSchedule
from hltl.sim.invariants import check_invariants
from hltl.sim.simulator import PerceptionModel
from hltl.skills.library import Action
from hltl.spec.hierarchy import spec_from_dict
from hltl.world.scene import Scene, load_scene
from hltl.world.state import WorldState, initial_world
from tests.bus.helpers import Loopback
from tests.execution.mocks import MockDriver, RecordingPlanner

ROOT = Path(__file__).resolve().parents[2]
CHIPS_TO_A = {"root": "p0", "formulas": {"p0": "F p100", "p100": "F delivered(chips, A)"}}
R2_TO_R1 = Action("handover_r2r", ("r2", "r1"), "chips")


@dataclass
class _OwnClockDriver(MockDriver):
    """Robots on their own clock: an action's end is heard ``lag`` seconds after it; a halt
    that reaches an action already ended does nothing, and says how it ended."""

    lag: float = 0.1
    told: dict[int, ActionStatus] = field(default_factory=dict)

    def poll(self, handle: Handle, t: float) -> ActionStatus:
        if handle.id in self.told:
            return self.told[handle.id]
        return super().poll(handle, max(handle.start, t - self.lag))

    def halt(self, handle: Handle, t: float, reason: str) -> None:
        truth = super().poll(handle, t)
        if truth.terminal:
            self.halted.append((t, handle.action, reason))
            self.told[handle.id] = truth  # (the halt's reply: it had ended)
            return
        super().halt(handle, t, reason)

    def ended_first(self, handle: Handle) -> ActionStatus | None:
        st = self.told.get(handle.id)
        return st if st is not None and st.state is not ActionState.HALTED else None


def test_the_executor_takes_in_an_end_its_halt_came_after() -> None:
    """Person A steps between the arms just after the r2 → r1 hand-over ended (not heard yet):
    the executor halts it, the halt finds it done, and the executor takes the hand-over as done
    (logged once, done; the chips in r1's hand), then finishes the task from there."""
    scene = load_scene(ROOT / "examples" / "scenes" / "two_arms.yaml")
    driver = _OwnClockDriver(duration=0.5, lag=0.1)
    assert isinstance(driver, OwnClock)
    ex = Executor(
        scene,
        spec_from_dict(CHIPS_TO_A),
        driver,
        planner=RecordingPlanner(),
        config=ExecutorConfig(predict=False, intrusion=False),
    )
    ex.log.emit(EpisodeStart(t=0.0, scene=scene.to_dict()))
    obs = initial_world(scene)
    ex.update(0.0, obs)
    t = _run(ex, obs, 0.0, 0.75)  # the pick done (heard at 0.6), the hand-over started
    start = next(r for r in ex.log.records if r.type == "action_start" and r.handle == 2)
    assert start.action == R2_TO_R1.to_dict()
    end = start.t + 0.5
    t = _run(ex, obs, t, end)  # it ends (heard a tick and more later)
    moved = obs.with_human("A", (0.3, 0.5, 0.0))  # inside both workspaces: a hazard
    t = _run(ex, moved, t, 3.0)
    assert [a for _, a, _ in driver.halted] == [R2_TO_R1]  # the halt went out
    mine = [r for r in ex.log.records if getattr(r, "handle", None) == start.handle]
    assert [r.type for r in mine] == ["action_start", "action_done"]
    assert not [r for r in ex.log.records if r.type in ("action_failed", "action_halted")]
    # r1 (holding the chips) hands them to A, who is in its workspace now
    assert ex.status is ExecStatus.DONE
    assert check_invariants(ex.log.records) == []


def _run(ex: Executor, obs: WorldState, t: float, until: float, dt: float = 0.05) -> float:
    while t < until - 1e-9 and not ex.finished:
        t = round(t + dt, 9)
        ex.update(t, obs.with_time(t))
    return t


class _RaceCell:
    """A cell whose chips actions finish just before a halt reaches them (the halt then finds
    them done); any other action halts as asked."""

    def __init__(self, scene: Scene, events: EventSchedule, **_: Any) -> None:
        self.scene = scene
        self._n = 0
        self._status: dict[int, ActionStatus] = {}

    def start(self, action: Action, t: float, **_: Any) -> Handle:
        self._n += 1
        return Handle(self._n, action, t)

    def poll(self, handle: Handle, t: float) -> ActionStatus:
        return self._status.get(handle.id, ActionStatus(ActionState.RUNNING, 0.5, t))

    def halt(self, handle: Handle, t: float, reason: str) -> None:
        state = ActionState.DONE if handle.action.object == "chips" else ActionState.HALTED
        self._status[handle.id] = ActionStatus(state, 1.0, t, reason)

    def unavailable(self, t: float) -> frozenset[str]:
        return frozenset()

    def advance(self, t: float) -> None:
        return None

    def observe(self, t: float | None = None) -> WorldState:
        return WorldState(t=0.0 if t is None else t, humans=(), objects=())

    def next_event_time(self) -> float:
        return float("inf")

    def pending_instructions(self) -> bool:
        return False

    def take_instructions(self) -> list[str]:
        return []


def test_a_real_time_cell_says_its_halt_came_too_late(loopback: Loopback) -> None:
    """Over the bus in real time: a halt the node finds the action done at is confirmed by
    the report of its end, and the executor's cell says so (``ended_first``); a halt that
    halts says nothing."""
    scene = load_scene(ROOT / "examples" / "scenes" / "two_arms.yaml")
    with loopback.node(scene, factory=_RaceCell):
        cell = RealtimeBusCell(
            loopback._exec_session, scene, EventSchedule(), 0, PerceptionModel(), EventLog(),
            factor=10.0,
        )  # fmt: skip
        try:
            assert isinstance(cell, OwnClock)
            late = cell.start(Action("pick", ("r2",), "chips"), 0.0)
            halted = cell.start(Action("pick", ("r1",), "bottle"), 0.0)
            assert cell.poll(late, 0.0).state is ActionState.RUNNING
            cell.halt(late, 0.1, "a hazard")
            cell.halt(halted, 0.1, "a hazard")
            ended = cell.ended_first(late)
            assert ended is not None and ended.state is ActionState.DONE
            assert cell.poll(late, 0.2).state is ActionState.DONE
            assert cell.ended_first(halted) is None
            assert cell.poll(halted, 0.2).state is ActionState.HALTED
        finally:
            cell.end()
            cell.close()
