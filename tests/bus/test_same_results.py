"""An episode over the bus gives the same log and metrics as the in-process one."""

from __future__ import annotations

import os
import subprocess
import sys
import time
from pathlib import Path
from typing import Any

import pytest

from hltl.bus.driver import BusTiming
from hltl.bus.session import free_endpoint
from hltl.sim import scenarios
from hltl.sim.dynamic import make_trial
from hltl.sim.episode import run_episode
from hltl.sim.events import load_events
from hltl.world.scene import Scene
from tests.bus.helpers import BusRun, Loopback, patient_foresight, without_wall_clock

ROOT = Path(__file__).resolve().parents[2]
EVENTS = ROOT / "examples" / "events"
HLTL = (sys.executable, "-m", "hltl.cli.main")


def _assert_same(
    loopback: Loopback,
    scene: Scene,
    ahead: int = 64,
    stream: bool | None = None,
    guess: bool = True,
    **episode: Any,
) -> BusRun:
    local = run_episode(scene, **episode)
    remote = loopback.run(scene, ahead=ahead, stream=stream, guess=guess, **episode)
    assert without_wall_clock(list(remote.episode.records)) == without_wall_clock(
        list(local.records)
    )
    assert without_wall_clock(remote.episode.metrics.to_dict()) == without_wall_clock(
        local.metrics.to_dict()
    )
    # every action the executor started was started exactly once by the node
    starts = [r.handle for r in local.records if r.type == "action_start"]
    assert remote.node.stats.starts == dict.fromkeys(starts, 1)
    return remote


def test_fig1_episode(loopback: Loopback) -> None:
    sc = scenarios.get("fig1")
    _assert_same(
        loopback,
        sc.scene,
        instruction=sc.instruction,
        events=load_events(EVENTS / "fig1.yaml", sc.scene),
        seed=3,
    )


def test_fig1_episode_in_lockstep(loopback: Loopback) -> None:
    """Without look-ahead every tick is one query: the same log."""
    sc = scenarios.get("fig1")
    run = _assert_same(
        loopback,
        sc.scene,
        ahead=0,
        instruction=sc.instruction,
        events=load_events(EVENTS / "fig1.yaml", sc.scene),
        seed=3,
    )
    assert run.node.stats.ahead == 0
    assert run.cell.stats.queries >= run.node.stats.steps


@pytest.mark.parametrize("stream", [True, False], ids=["streamed", "one-answer"])
def test_look_ahead_is_used_and_undone_when_a_command_comes_first(
    loopback: Loopback, stream: bool, monkeypatch: pytest.MonkeyPatch
) -> None:
    """2-1 #1: the executor commands in the middle of a quiet stretch the node had simulated
    ahead; those ticks are undone and the consumed ones replayed (from a save, or from the save
    made before the commands that began the stretch, and those commands made again), and the
    log is unchanged.
    Streamed, the stretch comes as further replies after the answer's first tick, and the
    node saves the simulator every few ticks of it: a cut replays fewer than that many.
    Without the executor's hints, so that every step's commands come in a query (the node's
    save made while it waited for them is used)."""
    from hltl.bus.node import CHECKPOINT

    # the node saves while idle at once after an answer, not after its pause (a next query that
    # comes within the pause, as it may on a loaded machine, finds no save made while idle)
    monkeypatch.setattr("hltl.bus.node.PAUSE", 0.0)
    trial = make_trial("2-1", 1)
    run = _assert_same(
        loopback,
        trial.scene,
        stream=stream,
        guess=False,
        instruction=trial.instruction,
        events=trial.events,
        seed=trial.seed,
    )
    stats = run.node.stats
    assert stats.ahead > 0 and stats.undone > 0 and stats.cuts > 0
    assert run.cell.stats.queries * 3 < stats.steps  # far fewer round trips than ticks
    # stretches after commands start from the save made while the node waited (no save then)
    assert stats.based > 0
    if stream:
        assert run.cell.stats.streamed > 0
        assert stats.replayed < CHECKPOINT * stats.cuts
    else:
        assert run.cell.stats.streamed == 0


@pytest.mark.parametrize("config", ["2-2", "2-4-line", "4-4-square"])
def test_catalogue_cells_with_dynamic_events(loopback: Loopback, config: str) -> None:
    trial = make_trial(config, 0)
    run = _assert_same(
        loopback, trial.scene, instruction=trial.instruction, events=trial.events, seed=trial.seed
    )
    # left to the node, the discrete simulator's stretches (cheap ticks) go in one answer
    assert run.node.stats.ahead > 0 and run.cell.stats.streamed == 0


@pytest.mark.parametrize("events", ["res.yaml", "fail.yaml"])
def test_robot_down_and_skill_failures(loopback: Loopback, events: str) -> None:
    from hltl.world.scene import load_scene

    scene = load_scene(ROOT / "examples" / "scenes" / "two_arms.yaml")
    _assert_same(
        loopback,
        scene,
        instruction="Give Person A the bottle and Person B the chips",
        events=load_events(EVENTS / events, scene),
        seed=1,
    )


def test_two_episodes_in_a_row_on_one_node(loopback: Loopback) -> None:
    """One node serves episode after episode (as `hltl node sim` does): the second gives the
    same log, and it numbers its reports from the start again, so the executor waits for none
    of the first episode's (it used to wait out its timeout and ask the robots for them)."""
    sc = scenarios.get("fig1")
    local = run_episode(sc.scene, instruction=sc.instruction, seed=0)
    timing = BusTiming(timeout=2.0)
    with loopback.node(sc.scene) as node:
        runs = [
            loopback.run(sc.scene, node=node, timing=timing, instruction=sc.instruction, seed=0)
            for _ in range(2)
        ]
    assert node.stats.episodes == 2
    for run in runs:
        assert without_wall_clock(list(run.episode.records)) == without_wall_clock(
            list(local.records)
        )
        assert run.cell.stats.recoveries == 0


def test_node_refuses_another_scene(loopback: Loopback) -> None:
    from hltl.errors import BusError
    from hltl.world.scene import load_scene

    node_scene = scenarios.get("fig1").scene
    other = load_scene(ROOT / "examples" / "scenes" / "2-4-line.yaml")
    from hltl.bus.driver import bus_cell

    with (
        loopback.node(node_scene),
        pytest.raises(BusError, match="serves the scene"),
    ):
        run_episode(
            other,
            instruction="Give Person A the chips",
            simulator=bus_cell(loopback._exec_session, timing=BusTiming(timeout=0.5, connect=1.0)),
        )


def test_a_node_yields_to_an_executor_only_in_its_process(loopback: Loopback) -> None:
    """A streaming node yields the interpreter between ticks only while an executor drives a
    cell from the same process (``executor_here``): a cell counts from when it is built until
    it is closed, also when its node refuses it."""
    from hltl.bus.driver import BusCell
    from hltl.bus.session import open_executors
    from hltl.errors import BusError
    from hltl.execution.log import EventLog
    from hltl.sim.events import EventSchedule
    from hltl.sim.simulator import PerceptionModel
    from hltl.world.scene import load_scene

    sc = scenarios.get("fig1")
    before = open_executors()  # (another test's cell left open would count here)
    seen: list[int] = []

    class Hook:
        def on_tick(self, t: float, sim: object, executor: object) -> None:
            seen.append(open_executors())

    run = loopback.run(sc.scene, instruction=sc.instruction, seed=0, hooks=[Hook()])
    assert run.episode.success and seen and set(seen) == {before + 1}
    assert open_executors() == before  # closed
    other = load_scene(ROOT / "examples" / "scenes" / "2-4-line.yaml")
    with loopback.node(sc.scene):
        cell = BusCell(
            loopback._exec_session,
            other,
            EventSchedule(),
            0,
            PerceptionModel(),
            EventLog(),
            timing=BusTiming(timeout=0.5, connect=1.0),
        )
        assert open_executors() == before + 1  # its reset asked, the answer not yet taken in
        with pytest.raises(BusError, match="serves"):  # the refusal, when the cell is first used
            cell.observe(0.0)
    assert open_executors() == before  # refused: closed too


def test_no_node_is_an_error_not_a_hang(loopback: Loopback) -> None:
    from hltl.bus.driver import bus_cell
    from hltl.errors import BusError

    sc = scenarios.get("fig1")
    with pytest.raises(BusError, match="no simulator node answers"):
        run_episode(
            sc.scene,
            instruction=sc.instruction,
            simulator=bus_cell(
                loopback._exec_session, timing=BusTiming(timeout=0.05, retries=1, connect=0.2)
            ),
        )


def test_cli_node_in_a_subprocess_gives_the_in_process_metrics(tmp_path: Path) -> None:
    endpoint = free_endpoint()
    scene = ROOT / "examples" / "scenes" / "fig1.yaml"
    env = {**os.environ, "PYTHONPATH": str(ROOT / "src")}
    node = subprocess.Popen(
        [*HLTL, "node", "sim", "--scene", str(scene), "--listen", endpoint, "--episodes", "1"],
        env=env,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    try:
        common = ["run", "--scene", str(scene), "--events", str(EVENTS / "fig1.yaml")]
        common += ["--instruction", "Give Person A the bottle and Person B the chips"]
        common += ["--json"]
        bus = subprocess.run(
            [*HLTL, *common, "--bus", f"zenoh:{endpoint}", "--log", str(tmp_path / "bus.jsonl")],
            env=env,
            capture_output=True,
            text=True,
            timeout=120,
        )
        _, node_err = node.communicate(timeout=30)
    finally:
        node.kill()
    local = subprocess.run(
        [*HLTL, *common, "--log", str(tmp_path / "local.jsonl")],
        env=env,
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert bus.returncode == 0, bus.stderr
    assert local.returncode == 0, local.stderr
    import json

    assert without_wall_clock(json.loads(bus.stdout)) == without_wall_clock(
        json.loads(local.stdout)
    )
    from hltl.execution.log import read_log

    assert without_wall_clock(read_log(tmp_path / "bus.jsonl")) == without_wall_clock(
        read_log(tmp_path / "local.jsonl")
    )
    assert node.returncode == 0
    assert "served 1 episode" in node_err


def test_mujoco_simulator_served_as_a_node(loopback: Loopback) -> None:
    """The 3D simulator behind the node: the same log as the 3D simulator in-process."""
    pytest.importorskip("mujoco")
    import functools

    from hltl.sim3d.driver import MujocoSimulator
    from hltl.sim3d.model import compile_scene

    sc = scenarios.get("fig1")
    make = functools.partial(MujocoSimulator, timing="motion", model=compile_scene(sc.scene))
    local = run_episode(sc.scene, instruction=sc.instruction, seed=0, simulator=make)
    # a stream's further replies come within its query's timeout: a generous one, so that on a
    # loaded machine (a suite run taking 4x its time) no stretch is cut short by the clock and
    # the counts below are the look-ahead's, not the machine's (session 10 saw one fail so)
    slow_ok = BusTiming(timeout=30.0)
    remote = loopback.run(
        sc.scene, factory=make, instruction=sc.instruction, seed=0, timing=slow_ok
    )
    assert local.success
    assert without_wall_clock(list(remote.episode.records)) == without_wall_clock(
        list(local.records)
    )
    # it was run ahead (restored and replayed where a command cut a stretch), not tick by tick
    stats, cs = remote.node.stats, remote.cell.stats
    assert stats.ahead > 0 and cs.queries < cs.ticks / 2, (stats, cs)
    # left to the node, the 3D simulator's stretches (costly ticks) are streamed
    assert cs.streamed > 0, (stats, cs)


def test_mujoco_node_looks_ahead_through_a_dynamic_trial(loopback: Loopback) -> None:
    """2-1 #0 in the 3D simulator: a person walks, a second request comes; the node runs
    ahead, a command cuts a stretch (restored, replayed), and the log is the in-process one."""
    pytest.importorskip("mujoco")
    import functools

    from hltl.sim3d.driver import MujocoSimulator
    from hltl.sim3d.model import compile_scene

    trial = make_trial("2-1", 0)
    make = functools.partial(MujocoSimulator, model=compile_scene(trial.scene))
    episode = {"instruction": trial.instruction, "events": trial.events, "seed": trial.seed}
    local = run_episode(trial.scene, simulator=make, **episode)
    remote = loopback.run(trial.scene, factory=make, **episode)
    assert without_wall_clock(list(remote.episode.records)) == without_wall_clock(
        list(local.records)
    )
    assert remote.node.stats.undone > 0  # the restore-and-replay path was taken


def test_observers_receive_ros2_poses(loopback: Loopback) -> None:
    """Anyone on the bus (a viewer, a ROS 2 bridge) gets people and hands as PoseStamped."""
    import threading

    from hltl.bus.codec import decode_pose
    from hltl.bus.keys import Keys

    sc = scenarios.get("fig1")
    got: dict[str, list] = {"humans": [], "hands": []}
    lock = threading.Lock()

    def on(kind: str):  # type: ignore[no-untyped-def]
        def cb(sample) -> None:  # type: ignore[no-untyped-def]
            with lock:
                got[kind].append((str(sample.key_expr), decode_pose(sample.payload.to_bytes())))

        return cb

    keys = Keys("default")
    subs = [
        loopback._exec_session.declare_subscriber(f"{keys.root}/humans/*/pose", on("humans")),
        loopback._exec_session.declare_subscriber(f"{keys.root}/robots/*/tool_pose", on("hands")),
    ]
    # a subscriber hears what is published after its declaration has reached the publisher (the
    # node learns it through its matching listeners): wait for that, bounded, before the episode
    node = loopback.node(sc.scene)
    wanted = {keys.human_pose(h) for h in sc.scene.human_ids}
    wanted |= {keys.tool_pose(r) for r in sc.scene.robot_ids}
    deadline = time.monotonic() + 10.0
    while not wanted <= node._matched and time.monotonic() < deadline:
        time.sleep(0.01)
    try:
        run = loopback.run(sc.scene, instruction=sc.instruction, seed=0, node=node)
        # the node publishes every tick before it answers the episode's end, but delivery to the
        # subscribers is asynchronous: wait for it, bounded, before withdrawing the node
        deadline = time.monotonic() + 10.0
        while time.monotonic() < deadline:
            with lock:
                heard = {k for k, _ in got["humans"] + got["hands"]}
            if wanted <= heard:
                break
            time.sleep(0.01)
    finally:
        node.close()
    for s in subs:
        s.undeclare()
    assert run.episode.success
    assert {k for k, _ in got["humans"]} == {keys.human_pose(h) for h in sc.scene.human_ids}
    assert {k for k, _ in got["hands"]} == {keys.tool_pose(r) for r in sc.scene.robot_ids}
    assert all(p.frame_id == "world" for _, p in got["humans"] + got["hands"])


def test_a_steps_commands_ride_its_query(loopback: Loopback) -> None:
    """Lockstep: no start or halt goes out on its own (nothing on ``…/action``); each rides the
    query after its step, whose answer acknowledges it (or the node guessed it: then no query
    at all): fewer queries than commands plus peeks, and the same log."""
    import threading

    from hltl.bus.keys import Keys

    trial = make_trial("2-4-line", 0)  # hand-overs: steps with two and more actions
    heard: list[str] = []
    lock = threading.Lock()

    def on_action(sample) -> None:  # type: ignore[no-untyped-def]
        with lock:
            heard.append(str(sample.key_expr))

    sub = loopback._exec_session.declare_subscriber(Keys("default").all_actions, on_action)
    try:
        run = _assert_same(
            loopback,
            trial.scene,
            instruction=trial.instruction,
            events=trial.events,
            seed=trial.seed,
        )
    finally:
        sub.undeclare()
    assert heard == []
    dispatches = [r for r in run.episode.records if r.type == "dispatch"]
    starts = [r for r in run.episode.records if r.type == "action_start"]
    assert len(starts) > len(dispatches)  # some step started several actions at once
    # the rest were the node's guesses from the executor's hints, taken without a query
    assert run.node.stats.commands == run.cell.stats.commands
    assert run.cell.stats.commands + run.cell.stats.guessed == len(starts)


def test_closing_a_node_ends_its_step_server(loopback: Loopback) -> None:
    """Step queries are served by a thread of the node's own; closing the node withdraws their
    queryable and the thread ends (it used to keep the queryable borrowed while it waited, so
    the node could not withdraw it)."""
    with loopback.node(scenarios.get("fig1").scene) as node:
        assert node._server.is_alive()
    node._server.join(5.0)
    assert not node._server.is_alive()


def test_one_sessions_cells_share_its_subscriptions_and_hear_only_their_own(
    loopback: Loopback,
) -> None:
    """The reports and liveliness subscriptions are declared once per session, not per episode:
    two cells' episodes on one session share them, each hears only its own cell's robots, and
    a closed one nothing."""
    from hltl.bus.driver import _listeners_of

    trial = make_trial("1-1", 0)
    heard: dict[str, list[str]] = {"a": [], "b": []}
    nodes = [loopback.node(trial.scene, cell=c) for c in ("a", "b")]
    try:
        runs = [
            loopback.run(trial.scene, instruction=trial.instruction, seed=0, cell=c, node=n)
            for c, n in zip(("a", "b"), nodes, strict=True)
        ]
        session = loopback._exec_session
        shared = _listeners_of(session)
        assert _listeners_of(session) is shared  # one set per session
        cells = [r.cell for r in runs]
        assert all(c._listeners is shared for c in cells)  # (both episodes used it)

        class Sample:
            def __init__(self, key: str) -> None:
                self.key_expr = key

        for c, cell in zip(("a", "b"), cells, strict=True):
            cell._on_report = lambda s, c=c: heard[c].append(str(s.key_expr))  # type: ignore[method-assign]
        shared.add(cells[0])  # (closed after its episode: opened again to listen)
        shared.add(cells[1])
        shared._on_report(Sample("hltl/a/robots/r1/status"))
        shared._on_report(Sample("hltl/b/robots/r1/status"))
        shared.remove(cells[1])
        shared._on_report(Sample("hltl/b/robots/r1/status"))
        shared.remove(cells[0])
        assert heard == {"a": ["hltl/a/robots/r1/status"], "b": ["hltl/b/robots/r1/status"]}
        assert all(r.episode.success for r in runs)
    finally:
        for n in nodes:
            n.close()


def test_the_reset_is_answered_while_the_executor_goes_on(loopback: Loopback) -> None:
    """``BusCell()`` sends the reset and returns; the answer is taken in when the cell is first
    used (the episode grounds its instruction meanwhile). Here the node cannot answer until
    the test, after ``BusCell()`` returned, lets it build the cell."""
    import threading

    from hltl.bus.driver import BusCell
    from hltl.execution.log import EventLog
    from hltl.sim.events import EventSchedule
    from hltl.sim.simulator import PerceptionModel, Simulator

    sc = scenarios.get("fig1")
    gate = threading.Event()
    released: list[bool] = []

    def held(*args: Any, **kwargs: Any) -> Simulator:
        released.append(gate.wait(10.0))
        return Simulator(*args, **kwargs)

    with loopback.node(sc.scene, factory=held):
        cell = BusCell(
            loopback._exec_session,
            sc.scene,
            EventSchedule(),
            0,
            PerceptionModel(),
            EventLog(),
            timing=BusTiming(timeout=20.0),
        )
        gate.set()
        try:
            assert cell.observe(0.0).t == 0.0
            assert released == [True]  # the node answered only after BusCell() returned
            cell.end()
        finally:
            cell.close()


def test_an_update_that_halts_cuts_the_stretch_it_came_in(
    loopback: Loopback, monkeypatch: pytest.MonkeyPatch
) -> None:
    """An instruction does not end the node's stretch; when its update halts the hand-over it
    undoes (test_update_episodes), the ticks simulated after it are undone and the log is the
    in-process one (before, the stretch ended at the instruction: nothing was cut). Another
    instruction, which halts nothing, is taken in with its stretch: nothing cut. The node's
    planner takes its time (a step it gave up foreseeing under load, past its 50 ms, was a
    guess missed: 2 cuts in the second episode, session 20, at load 8)."""
    from hltl.sim.events import EventSchedule, Instruction
    from hltl.world.scene import load_scene

    patient_foresight(monkeypatch)
    scene = load_scene(ROOT / "examples" / "scenes" / "two_arms.yaml")
    halting = _assert_same(
        loopback,
        scene,
        instruction="Give Person A the bottle",
        events=EventSchedule((Instruction(0.7, "give Person B the bottle instead"),)),
    )
    assert [r.kind for r in halting.episode.records if r.type == "halt"] == ["update"]
    assert halting.node.stats.cuts > 0 and halting.node.stats.undone > 0
    also = _assert_same(
        loopback,
        scene,
        instruction="Give Person A the bottle",
        events=EventSchedule((Instruction(0.7, "also give Person B the chips"),)),
    )
    # the instruction came inside a stretch: taken with its ticks, nothing cut
    assert also.node.stats.cuts == 0
