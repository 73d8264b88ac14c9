"""Real time on the bus: the node runs the cell on its own (accelerated) clock, the executor
follows the wall clock. Timings differ from run to run, so what is checked are the guarantees:
the plan completes with the monitor's verdicts of the in-process run, every dispatch reaches
the node exactly once and ends once, faults are survived, and a silent or broken node is down
(with a reason), never a hang."""

from __future__ import annotations

import threading
import time
from pathlib import Path
from typing import Any

import pytest

from hltl.bus.driver import BusCell, BusTiming
from hltl.bus.faults import FaultModel
from hltl.bus.node import CellNode
from hltl.bus.realtime import RealtimeBusCell, realtime_bus_cell
from hltl.cli.main import main
from hltl.errors import BusError
from hltl.execution.drivers import Handle
from hltl.execution.log import EventLog, LogRecord
from hltl.sim import scenarios
from hltl.sim.episode import Episode, EpisodeConfig, run_episode
from hltl.sim.events import EventSchedule, load_events
from hltl.sim.simulator import PerceptionModel, Simulator
from hltl.skills.library import Action
from hltl.world.scene import Scene, load_scene
from tests.bus.helpers import Loopback

ROOT = Path(__file__).resolve().parents[2]
EVENTS = ROOT / "examples" / "events"
TWO_ARMS = ROOT / "examples" / "scenes" / "two_arms.yaml"
FACTOR = 10.0  # ten cell seconds per wall second: an episode takes a fraction of a second
FAST = BusTiming(timeout=0.1, retries=6)


def _case(name: str) -> tuple[Scene, dict[str, Any]]:
    if name == "fig1":
        sc = scenarios.get("fig1")
        events = load_events(EVENTS / "fig1.yaml", sc.scene)
        return sc.scene, {"instruction": sc.instruction, "events": events, "seed": 3}
    scene = load_scene(TWO_ARMS)
    instruction, events = {
        # a person walks between the arms mid-hand-over: halt, replan
        "h_move": ("Give Person A the chips", "h_move_midhandover.yaml"),
        # a second request arrives while the first runs: ground, replan
        "goal": ("Give Person A the bottle", "goal.yaml"),
    }[name]
    return scene, {
        "instruction": instruction,
        "events": load_events(EVENTS / events, scene),
        "seed": 0,
    }


def _run(
    lb: Loopback, scene: Scene, *, timing: BusTiming = FAST, **kw: Any
) -> tuple[Episode, CellNode, BusCell]:
    run = lb.run(scene, realtime=FACTOR, timing=timing, **kw)
    return run.episode, run.node, run.cell


def _fired(ep: Episode) -> set[str]:
    return {f for r in ep.records if r.type == "monitor" for f in r.fired}


def _each_dispatch_once(ep: Episode, node: CellNode) -> None:
    starts = [r.handle for r in ep.records if r.type == "action_start"]
    ends = [
        r.handle for r in ep.records if r.type in ("action_done", "action_failed", "action_halted")
    ]
    assert len(starts) == len(set(starts))  # never dispatched twice
    assert sorted(ends) == sorted(starts)  # each ended once, and nothing ended unstarted
    assert all(n == 1 for n in node.stats.starts.values()), node.stats.starts
    assert sorted(node.stats.starts) == sorted(starts)  # nothing lost on the way


def _as_in_process(ep: Episode, local: Episode) -> None:
    assert ep.success, ep.metrics.reason
    assert ep.records[-1].done == local.records[-1].done
    assert _fired(ep) == _fired(local)  # the monitor's verdicts: the same formulas fired
    monitors = [r for r in ep.records if r.type == "monitor"]
    assert monitors[-1].accepted and not any(m.accepted for m in monitors[:-1])


# (Fig. 1 is not among them: run late, its last hand-over races Person A's second walk, and
# whether A leaves r1's workspace just before or just after it ends is a matter of timing.)
@pytest.mark.parametrize("case", ["h_move", "goal"])
def test_realtime_episode_completes_as_in_process(loopback: Loopback, case: str) -> None:
    scene, episode = _case(case)
    local = run_episode(scene, **episode)
    ep, node, bc = _run(loopback, scene, **episode)
    _as_in_process(ep, local)
    _each_dispatch_once(ep, node)
    # the node ran on its own clock (a step request would have been refused) and the executor
    # followed it tick by tick
    assert node.stats.steps > 0 and bc.stats.ticks > 0
    kinds = [r.type for r in ep.records]
    if case == "h_move":
        assert "human_move" in kinds
    if case == "goal":
        assert "instruction" in kinds and ep.records[-1].done != ["p0", "p100"]


EVERYTHING = FaultModel(
    loss=0.1, duplicate=0.2, reorder=0.2, delay=0.001, reply_loss=0.1, slow=0.001, seed=7
)


@pytest.mark.parametrize(
    ("node_faults", "exec_faults"),
    [
        (EVERYTHING, EVERYTHING),
        (FaultModel(loss=0.4, seed=11), None),  # ticks, reports and acknowledgements lost
        (FaultModel(delay=0.02, seed=12), FaultModel(delay=0.02, seed=13)),  # late (0.2 cell s)
    ],
    ids=["everything", "node_loss", "late"],
)
def test_realtime_survives_faults(
    loopback: Loopback, node_faults: FaultModel, exec_faults: FaultModel | None
) -> None:
    scene, episode = _case("h_move")
    local = run_episode(scene, **episode)
    ep, node, bc = _run(
        loopback, scene, node_faults=node_faults, exec_faults=exec_faults, **episode
    )
    _as_in_process(ep, local)
    _each_dispatch_once(ep, node)
    if node_faults.loss:  # the faults really happened, and were made good by asking
        assert node.link.dropped > 0
        assert bc.stats.missed + bc.stats.recoveries + bc.stats.retransmits > 0


def _all_down(ep: Episode, scene: Scene, t0: float) -> list[Any]:
    """The episode ended within bounds (never a hang), failed, and every robot went down."""
    assert time.monotonic() - t0 < 60
    assert not ep.success
    downs = [r for r in ep.records if r.type == "robot_down"]
    assert {r.robot for r in downs} == set(scene.robot_ids)
    return downs


def test_realtime_node_killed_mid_action_gives_up(loopback: Loopback) -> None:
    scene, episode = _case("fig1")

    def kill_on_first_start(rec: LogRecord) -> None:
        if rec.type == "action_start" and rec.handle == 1:
            loopback.kill_node_session()

    t0 = time.monotonic()
    ep, node, _ = _run(
        loopback,
        scene,
        on_record=kill_on_first_start,
        timing=BusTiming(timeout=0.1, retries=2, patience=0.5),
        config=EpisodeConfig(max_time=30.0),
        **episode,
    )
    downs = _all_down(ep, scene, t0)
    assert all(r.until is None and r.reason for r in downs)
    t_down = min(r.t for r in downs)
    assert not [r for r in ep.records if r.type == "action_start" and r.t > t_down]
    assert all(n == 1 for n in node.stats.starts.values())


# How long the executor may take to give up on a silent or broken cell before the test calls
# it a hang: far above what giving up needs (timeout x (retries + 1) + patience ~ 1 s, below).
HANG = 30.0


def _faulty(fault: str, release: threading.Event) -> type[Simulator]:
    """A cell that goes wrong once its first action has started (so mid-action, however long
    planning took): it "hangs" (every step blocks until the test releases it — silence that
    outlasts any timeout, rather than a pause that a slow machine could outlast) or "breaks"
    (every step fails, with a reason)."""

    class Faulty(Simulator):
        started = False

        def start(self, action: Action, t: float, *, motion: Any = None) -> Handle:
            handle = super().start(action, t, motion=motion)
            self.started = True
            return handle

        def advance(self, t: float) -> None:
            if self.started:
                if fault == "breaks":
                    raise RuntimeError("joint 3 encoder fault")
                release.wait()
            super().advance(t)

    return Faulty


@pytest.mark.parametrize(
    ("fault", "reason"),
    # a hung or broken node is silent to commands: the clock query (which names a failure) or
    # a command's acknowledgement gives up first, whichever the loop is waiting on (timing)
    [
        ("hangs", ("stopped answering", "did not acknowledge")),
        ("breaks", ("joint 3 encoder fault", "did not acknowledge")),
    ],
)
def test_a_silent_or_broken_cell_is_down_not_a_hang(
    loopback: Loopback, fault: str, reason: tuple[str, ...]
) -> None:
    # The timeouts only set how soon the executor gives up on a cell that never answers again;
    # they are wide (a loaded machine stalls a thread for tens of milliseconds, not 0.25 s), so
    # that before the fault a slow answer is not taken for a dead node.
    scene, episode = _case("fig1")
    release = threading.Event()
    timing = BusTiming(timeout=0.25, retries=1, patience=0.5)
    out: dict[str, Any] = {}
    opened: list[BusCell] = []

    def executor() -> None:
        make = realtime_bus_cell(
            loopback._exec_session, factor=FACTOR, timing=timing, opened=opened
        )
        try:
            out["episode"] = run_episode(
                scene, simulator=make, config=EpisodeConfig(max_time=30.0), **episode
            )
        except BaseException as exc:  # re-raised on the test's thread
            out["error"] = exc
        finally:
            for bc in opened:
                bc.close()

    with loopback.node(scene, factory=_faulty(fault, release)) as node:
        thread = threading.Thread(target=executor, name="executor", daemon=True)
        thread.start()
        thread.join(HANG)
        hung = thread.is_alive()
        release.set()  # (a hung cell holds the node's lock, which closing the node takes)
    assert not hung, f"the executor did not give up on a cell that {fault} within {HANG} s"
    if "error" in out:
        raise out["error"]
    ep: Episode = out["episode"]
    assert not ep.success
    downs = [r for r in ep.records if r.type == "robot_down"]
    assert {r.robot for r in downs} == set(scene.robot_ids)
    assert any(why in downs[0].reason for why in reason), downs[0].reason
    failed = [r for r in ep.records if r.type == "action_failed"]
    assert failed and all("down" in r.reason for r in failed)
    assert all(n == 1 for n in node.stats.starts.values())


def test_node_refuses_a_bad_clock_and_steps_in_real_time(loopback: Loopback) -> None:
    scene, _ = _case("fig1")
    with loopback.node(scene):

        def cell(factor: float) -> RealtimeBusCell:
            return RealtimeBusCell(
                loopback._exec_session,
                scene,
                EventSchedule(),
                0,
                PerceptionModel(),
                EventLog(),
                factor=factor,
                timing=FAST,
            )

        with pytest.raises(BusError, match=r"real-time factor must be in \(0, 1000\]"):
            cell(5000.0)
        bc = cell(FACTOR)
        try:
            with pytest.raises(BusError, match="runs in real time"):
                bc._ask(bc.keys.sim_step, {"episode": bc.episode, "step": 1, "t": 0.05})
        finally:
            bc.end()
            bc.close()
    with pytest.raises(ValueError, match="real-time factor"):
        realtime_bus_cell(loopback._exec_session, factor=0.0)


def test_run_realtime_on_the_command_line(
    loopback: Loopback, capsys: pytest.CaptureFixture[str]
) -> None:
    scene = load_scene(TWO_ARMS)
    argv = ["run", "--scene", str(TWO_ARMS), "--instruction", "Give Person A the bottle"]
    argv += ["--events", str(EVENTS / "goal.yaml"), "--json"]
    with loopback.node(scene) as node:
        code = main([*argv, "--bus", f"zenoh:{loopback.endpoint}", "--realtime", "10"])
    out = capsys.readouterr().out
    assert code == 0 and '"success": true' in out
    assert len(node.stats.starts) == 4 and node.stats.finished == 1


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        (["--realtime", "5"], "--realtime runs the cell on a node's clock: add --bus zenoh"),
        (["--bus", "zenoh", "--realtime", "0"], "--realtime: the factor must be a positive"),
    ],
)
def test_bad_realtime_options(
    capsys: pytest.CaptureFixture[str], argv: list[str], message: str
) -> None:
    base = ["run", "--scene", str(TWO_ARMS), "--instruction", "Give Person A the bottle"]
    code = main([*base, *argv])
    err = capsys.readouterr().err
    assert code == 1 and message in err and err.count("\n") == 1


def test_node_rejects_a_bad_rate(capsys: pytest.CaptureFixture[str]) -> None:
    code = main(["node", "sim", "--scene", str(TWO_ARMS), "--rate", "0"])
    err = capsys.readouterr().err
    assert code == 1 and "--rate must be a positive number" in err
