"""Faults on the bus: lost, delayed, duplicated, reordered messages, a slow subscriber, a node
killed mid-action. The executor ends as in-process or halts safely and gives up with a reason;
no action is ever started twice."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path
from typing import Any

import pytest

from hltl.bus import node as node_module
from hltl.bus.driver import BusTiming
from hltl.bus.faults import FaultModel
from hltl.bus.session import free_endpoint
from hltl.sim import scenarios
from hltl.sim.dynamic import make_trial
from hltl.sim.episode import EpisodeConfig, run_episode
from hltl.sim.events import load_events
from tests.bus.helpers import (
    BusRun,
    Loopback,
    guesses_in_the_answer,
    without_wall_clock,
    wrong_hints,
)

ROOT = Path(__file__).resolve().parents[2]
EVENTS = ROOT / "examples" / "events"
HLTL = (sys.executable, "-m", "hltl.cli.main")
# short waits so that recovering from a lost message costs little wall time
FAST = BusTiming(timeout=0.1, retries=6)

# (seeds whose first draws hit: the first message the node publishes is lost under "loss" and
# "everything", and its first reply under "lost_replies", so that the checks below that a fault
# really happened do not depend on chance)
FAULTS = {
    "loss": FaultModel(loss=0.25, seed=14),
    "duplicates": FaultModel(duplicate=0.5, seed=2),
    "out_of_order": FaultModel(reorder=0.5, seed=3),
    "delay": FaultModel(delay=0.003, seed=4),
    "lost_replies": FaultModel(reply_loss=0.25, seed=13),
    "slow_subscriber": FaultModel(slow=0.004, seed=6),
    "everything": FaultModel(
        loss=0.1, duplicate=0.2, reorder=0.2, delay=0.001, reply_loss=0.1, slow=0.001, seed=14
    ),
}


def _fig1() -> dict[str, Any]:
    sc = scenarios.get("fig1")
    return {
        "instruction": sc.instruction,
        "events": load_events(EVENTS / "fig1.yaml", sc.scene),
        "seed": 3,
    }


def _starts_once(run: BusRun) -> None:
    dispatched = [r.handle for r in run.episode.records if r.type == "action_start"]
    assert len(dispatched) == len(set(dispatched))
    assert all(n == 1 for n in run.node.stats.starts.values()), run.node.stats.starts
    # nothing lost either: every handle the executor started reached the node
    assert sorted(run.node.stats.starts) == sorted(dispatched)


# every fault with the stretches as the node chooses (in one answer for the discrete simulator),
# and the faults that hit replies also with the stretches streamed (a lost chunk, a query that
# ends before its last chunk)
CASES = [
    *((f, None) for f in sorted(FAULTS)),
    ("lost_replies", True),
    ("everything", True),
]


@pytest.mark.parametrize(("fault", "stream"), CASES)
def test_faulty_links_change_nothing(loopback: Loopback, fault: str, stream: bool | None) -> None:
    sc = scenarios.get("fig1")
    local = run_episode(sc.scene, **_fig1())
    faults = FAULTS[fault]
    run = loopback.run(
        sc.scene, node_faults=faults, exec_faults=faults, timing=FAST, stream=stream, **_fig1()
    )
    assert without_wall_clock(list(run.episode.records)) == without_wall_clock(list(local.records))
    _starts_once(run)
    stats, node = run.cell.stats, run.node.stats
    if fault in ("loss", "everything"):  # the fault really happened
        assert run.cell.link.dropped + run.node.link.dropped > 0
    if fault == "duplicates":  # copies both ways, and the node knew each of its own
        # (how many numbered step requests the executor sends, and so are copied, depends on
        # how many steps the node foresaw: none on a run where it foresaw them all; how many
        # reports the executor hears twice depends on time: most come in answers, and a copy
        # published as the episode ends may come after the executor has left it)
        assert run.node.link.copied > 0 and node.duplicates >= stats.step_copies
    if fault == "out_of_order":  # reports were held back for later ones to overtake
        assert run.cell.link.held + run.node.link.held > 0
    if fault == "lost_replies":
        assert stats.retransmits > 0
    assert (stats.streamed > 0) is bool(stream)
    if stream:  # a streamed stretch is never run past a step's end on a guess
        assert node.guessed == 0


# (a cell whose plan changes mid-episode; each fault with the hints and the basis as the
# executor gives them, guesses kept, and with every guess wrong, all undone)
GUESS_CASES = [(f, w) for f in ("loss", "duplicates", "lost_replies", "everything") for w in (0, 1)]


def test_a_node_slow_to_take_the_end_counts_every_start(
    loopback: Loopback, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The episode's end commits the guessed starts the executor took, and the node counts
    them then: a node that takes the end after the executor stopped waiting for its answer
    (here 0.3 s late, with a 0.1 s timeout: a loaded machine) still counts every start, since
    it is not closed before it has taken the end (it once was, and the count lost 7 starts)."""
    real = node_module.CellNode._on_step

    def slow_end(self: Any, query: Any) -> Any:
        if b'"end":true' in node_module._payload(query):  # (the episode's end)
            time.sleep(0.3)
        return real(self, query)

    monkeypatch.setattr(node_module.CellNode, "_on_step", slow_end)
    guesses_in_the_answer(monkeypatch)
    trial = make_trial("4-4-square", 0)
    kw = {"instruction": trial.instruction, "events": trial.events, "seed": trial.seed}
    run = loopback.run(trial.scene, timing=FAST, **kw)
    assert run.node.stats.guesses_kept > 0 and run.node.stats.finished == 1
    _starts_once(run)


@pytest.mark.parametrize(("fault", "wrong"), GUESS_CASES)
def test_guessed_steps_under_faults(
    loopback: Loopback, monkeypatch: pytest.MonkeyPatch, fault: str, wrong: int
) -> None:
    """Under each fault the node's guesses are kept or undone as without faults: the same log,
    every action started once, none lost (a guessed start the executor took counts once; one
    it did not take, never). The guessed steps go in the answer, so that every guess is made
    (streamed, a wrong one may be asked past before the node makes it)."""
    trial = make_trial("4-4-square", 0)
    kw = {"instruction": trial.instruction, "events": trial.events, "seed": trial.seed}
    local = run_episode(trial.scene, **kw)
    guesses_in_the_answer(monkeypatch)
    if wrong:
        wrong_hints(monkeypatch)
    faults = FAULTS[fault]
    run = loopback.run(trial.scene, node_faults=faults, exec_faults=faults, timing=FAST, **kw)
    assert without_wall_clock(list(run.episode.records)) == without_wall_clock(list(local.records))
    _starts_once(run)
    node = run.node.stats
    assert node.guessed > 0
    assert (node.guesses_kept > 0) is not wrong


def test_node_killed_mid_action_halts_and_gives_up(loopback: Loopback) -> None:
    sc = scenarios.get("fig1")

    def kill_on_first_start(rec: dict[str, Any]) -> None:
        if rec.type == "action_start" and rec.handle == 1:
            loopback.kill_node_session()

    t0 = time.monotonic()
    run = loopback.run(
        sc.scene,
        timing=FAST,
        on_record=kill_on_first_start,
        config=EpisodeConfig(max_time=30.0),
        **_fig1(),
    )
    assert time.monotonic() - t0 < 60  # bounded: never a hang
    recs = run.episode.records
    assert not run.episode.success
    downs = [r for r in recs if r.type == "robot_down"]
    assert {r.robot for r in downs} == set(sc.scene.robot_ids)
    assert all(r.until is None and r.reason for r in downs)
    failed = [r for r in recs if r.type == "action_failed"]
    assert failed and all("down" in r.reason for r in failed)
    # after the node died nothing more was dispatched
    t_down = min(r.t for r in downs)
    assert not [r for r in recs if r.type == "action_start" and r.t > t_down]
    end = recs[-1]
    assert end.type == "episode_end" and not end.success
    assert "available robot (none)" in end.reason  # gave up because no robot is left
    assert all(n == 1 for n in run.node.stats.starts.values())


def test_node_process_killed_mid_action(tmp_path: Path) -> None:
    """A real process, killed with SIGKILL while its robots are moving."""
    from hltl.bus.driver import BusCell, bus_cell
    from hltl.bus.session import BusConfig, open_session

    endpoint = free_endpoint()
    scene_file = ROOT / "examples" / "scenes" / "fig1.yaml"
    env = {**os.environ, "PYTHONPATH": str(ROOT / "src")}
    node = subprocess.Popen(
        [*HLTL, "node", "sim", "--scene", str(scene_file), "--listen", endpoint],
        env=env,
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
    )
    sc = scenarios.get("fig1")
    opened: list[BusCell] = []

    def kill_on_first_start(rec: dict[str, Any]) -> None:
        if rec.type == "action_start" and node.poll() is None:
            node.send_signal(signal.SIGKILL)
            node.wait(timeout=10)

    try:
        with open_session(BusConfig(connect=(endpoint,))) as session:
            ep = run_episode(
                sc.scene,
                on_record=kill_on_first_start,
                config=EpisodeConfig(max_time=30.0),
                simulator=bus_cell(
                    session,
                    timing=BusTiming(timeout=0.2, retries=2, connect=60.0),
                    opened=opened,
                ),
                **_fig1(),
            )
            opened[0].close()
    finally:
        node.kill()
        node.wait(timeout=10)
    assert not ep.success
    assert ep.metrics.reason
    kinds = [r.type for r in ep.records]
    assert "robot_down" in kinds and "action_failed" in kinds
    starts = [r.handle for r in ep.records if r.type == "action_start"]
    assert len(starts) == len(set(starts))


@pytest.mark.parametrize(
    ("realtime", "why"),
    [
        # lockstep: a step's commands ride its query, which the cell node never acknowledges
        (None, "is down: the simulator node did not acknowledge the step's commands"),
        # real time: each command goes to the robots at once, and each robot must acknowledge
        (10.0, "is down: robot r1 did not acknowledge"),
    ],
)
def test_a_robot_that_never_acknowledges_is_down_not_a_hang(
    loopback: Loopback, realtime: float | None, why: str
) -> None:
    """Every command is lost: the first dispatch times out, the robots are declared down, and
    the executor gives up with a reason instead of waiting forever."""
    sc = scenarios.get("fig1")
    t0 = time.monotonic()
    run = loopback.run(
        sc.scene,
        exec_faults=FaultModel(loss=0.999999, seed=0),
        timing=BusTiming(timeout=0.05, retries=1, patience=0.3),
        config=EpisodeConfig(max_time=20.0),
        realtime=realtime,
        **_fig1(),
    )
    assert time.monotonic() - t0 < 60
    assert not run.episode.success
    failed = [r for r in run.episode.records if r.type == "action_failed"]
    assert failed and why in failed[0].reason
    assert run.node.stats.starts == {}  # nothing ever reached the node: nothing ran


def test_fault_model_rejects_bad_values() -> None:
    with pytest.raises(ValueError, match="loss"):
        FaultModel(loss=1.0)
    with pytest.raises(ValueError, match="delay"):
        FaultModel(delay=-1.0)
