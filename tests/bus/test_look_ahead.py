"""The node's look-ahead: a simulator put back by ``_saver`` replays exactly the same future."""

from __future__ import annotations

import math
from typing import Any

import pytest

from hltl.bus.bench import _InstantCell
from hltl.bus.node import _again, _call, _Episode, _saver
from hltl.errors import BusError
from hltl.execution.drivers import ActionState
from hltl.execution.log import EventLog
from hltl.sim.dynamic import make_trial
from hltl.sim.events import EventSchedule
from hltl.sim.simulator import PerceptionModel, Simulator
from hltl.sim3d.driver import MujocoSimulator
from hltl.sim3d.model import compile_scene
from hltl.skills.library import Action


def _future(sim: Simulator, log: EventLog, t: float, ticks: int) -> list[Any]:
    out: list[Any] = []
    n0 = len(log.records)
    for _ in range(ticks):
        t += 0.05
        sim.advance(t)
        out.append((t, sim.observe(t), sim.take_instructions(), sim.next_event_time()))
        out.append([sim.poll(h, t) for h in handles(sim)])
    out.append(log.records[n0:])
    return out


def handles(sim: Simulator) -> list[Any]:
    return [a.handle for a in sim._actions.values()]


def test_restored_simulator_replays_the_same_future() -> None:
    trial = make_trial("2-4-line", 1)  # people walk and wander: every random generator is used
    log = EventLog()
    sim = Simulator(
        trial.scene, trial.events, seed=5, perception=PerceptionModel(noise=0.05), log=log
    )
    robot = trial.scene.robot_ids[0]
    obj = trial.scene.objects[0].id
    sim.start(Action("pick", (robot,), obj), 0.0)
    sim.advance(0.5)
    restore = _saver(sim)
    assert restore is not None
    first = _future(sim, log, 0.5, 60)
    restore()
    again = _future(sim, log, 0.5, 60)
    assert first[:-1] == again[:-1]
    assert first[-1] == again[-1] and first[-1]  # the same log records, and there were some


def test_a_save_before_commands_and_the_commands_made_again_replay_the_same_future() -> None:
    """The node saves the cell while it waits for the executor; a stretch after the next
    query's commands is then undone with that save and the commands made again (``_again``):
    the same future as from the cell right after the commands."""
    trial = make_trial("2-4-line", 1)
    log = EventLog()
    sim = Simulator(
        trial.scene, trial.events, seed=5, perception=PerceptionModel(noise=0.05), log=log
    )
    sim.advance(0.5)
    idle = _saver(sim)  # (the node, idle)
    assert idle is not None
    ep = _Episode("e", sim, [])
    ep.calls = []
    r0, r1 = trial.scene.robot_ids[:2]
    h = _call(ep, lambda: sim.start(Action("pick", (r0,), trial.scene.objects[0].id), 0.5))
    assert h is not None
    _call(ep, lambda: sim.start(Action("pick", (r1,), trial.scene.objects[1].id), 0.5))
    _call(ep, lambda: sim.halt(h, 0.5, "a person came near"))
    assert len(ep.calls) == 3 and ep.version == 3
    first = _future(sim, log, 0.5, 60)
    _again(idle, ep.calls)()
    again = _future(sim, log, 0.5, 60)
    assert first[:-1] == again[:-1]
    assert first[-1] == again[-1] and first[-1]
    # a start that gives another handle the second time is an error, never a silent mix-up
    ep.calls[0] = (ep.calls[0][0], None)
    with pytest.raises(BusError, match="another handle"):
        _again(idle, ep.calls)()


def test_cells_that_cannot_be_saved_are_stepped_in_lockstep() -> None:
    trial = make_trial("1-1", 0)
    assert _saver(_InstantCell(trial.scene, EventSchedule())) is None


def test_restored_3d_simulator_replays_the_same_future() -> None:
    """The 3D simulator is run ahead too: its MuJoCo model is posed again after a restore, so
    the hands (read from the model), contacts and log records of the replayed ticks are the
    same."""
    pytest.importorskip("mujoco")
    trial = make_trial("2-2", 0)
    log = EventLog()
    sim = MujocoSimulator(
        trial.scene,
        trial.events,
        seed=5,
        perception=PerceptionModel(noise=0.05),
        log=log,
        model=compile_scene(trial.scene),
    )
    robot, obj = next(  # a pick that runs: the arm moves
        (r, o.id)
        for r in trial.scene.robot_ids
        for o in trial.scene.objects
        if math.dist(trial.scene.robot(r).base, o.position) < trial.scene.robot(r).reach - 0.05
    )
    h = sim.start(Action("pick", (robot,), obj), 0.0)
    sim.advance(0.3)
    assert sim.poll(h, 0.3).state is ActionState.RUNNING
    hand = sim.hand_position(robot)  # read from the posed model
    restore = _saver(sim)
    assert restore is not None
    first = _future(sim, log, 0.3, 30)
    assert sim.hand_position(robot) != hand  # the arm moved on
    restore()
    assert sim.hand_position(robot) == hand  # the model is posed as the state says again
    again = _future(sim, log, 0.3, 30)
    assert first == again
    sim.on_pose.append(lambda t: None)  # a recorder would see undone ticks: no look-ahead
    assert _saver(sim) is None
