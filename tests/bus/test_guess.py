"""The executor's hint: the node starts its plan's next step on a guess; nothing of it shows."""

from __future__ import annotations

import threading
import time
from pathlib import Path
from typing import Any

import pytest

from hltl.bus.codec import Report
from hltl.bus.keys import Keys
from hltl.execution.log import LogRecord
from hltl.sim import scenarios
from hltl.sim.dynamic import make_trial
from hltl.sim.episode import run_episode
from hltl.sim.events import load_events
from hltl.world.scene import Scene
from tests.bus.helpers import (
    Loopback,
    guesses_in_the_answer,
    patient_foresight,
    same_as_local,
    wrong_hints,
)

# the node's guessed steps as further replies (as deployed), and in the answer itself, where
# the node makes every guess before the executor can answer it (so wrong ones surely happen)
MODES = pytest.mark.parametrize("inline", [False, True], ids=["streamed", "in-the-answer"])

EVENTS = Path(__file__).resolve().parents[2] / "examples" / "events"


def _fig1() -> tuple[Scene, dict[str, Any]]:
    sc = scenarios.get("fig1")
    events = load_events(EVENTS / "fig1.yaml", sc.scene)
    return sc.scene, {"instruction": sc.instruction, "events": events, "seed": 3}


@MODES
def test_fig1_a_step_held_back_undoes_the_guess(
    loopback: Loopback, monkeypatch: pytest.MonkeyPatch, inline: bool
) -> None:
    """Fig. 1: when the picks end, the plan's next step is both hand-overs (the hint), but
    Person A walks and the executor holds r1's back (intrusion risk) and starts r2's alone.
    With hints only (no basis: the node cannot make the executor's check) the node's guess is
    undone; with the basis the node holds r1's back too and its guess holds. The log is the
    in-process one either way."""
    patient_foresight(monkeypatch)
    if inline:
        guesses_in_the_answer(monkeypatch)
    scene, kw = _fig1()
    local = run_episode(scene, **kw)
    hinted = loopback.run(scene, foresee=False, **kw)
    same_as_local(local, hinted)
    assert hinted.node.stats.guesses_kept == 0
    if inline:
        assert hinted.node.stats.guessed > 0 and hinted.node.stats.undone > 0
    run = loopback.run(scene, **kw)
    same_as_local(local, run)
    if inline:
        assert run.node.stats.checked > 0 and run.node.stats.guesses_kept > 0


def test_guessed_steps_save_round_trips(
    loopback: Loopback, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A catalogue cell whose plan holds (4-1 #0): the node starts each next step on the
    executor's hint, the executor takes it without a query, and the log is the in-process
    one, as without hints. The node's planner takes its time: one that gave up (its 50 ms
    under load) made queries a foreseen step would have saved (6 against 12 without hints,
    with FORESEE_TIMEOUT 1e-6)."""
    patient_foresight(monkeypatch)
    trial = make_trial("4-1", 0)
    kw = {"instruction": trial.instruction, "events": trial.events, "seed": trial.seed}
    local = run_episode(trial.scene, **kw)
    on = loopback.run(trial.scene, **kw)
    off = loopback.run(trial.scene, guess=False, **kw)
    same_as_local(local, on)
    same_as_local(local, off)
    assert on.node.stats.guesses_kept > 0
    assert on.cell.stats.guessed > 0 and on.cell.stats.guessed_ahead > 0
    assert off.node.stats.guessed == off.cell.stats.guessed == 0
    # a step whose guess was kept needs no query for its commands (a stretch still ends at
    # its span: then a plain step query)
    # (retransmissions aside: a loaded machine may stall an answer past the timeout)
    sent = [r.cell.stats.queries - r.cell.stats.retransmits for r in (on, off)]
    assert sent[0] * 2 < sent[1]
    assert on.cell.stats.streamed == 0  # (guessed steps come as further replies, not a stream)


@MODES
@pytest.mark.parametrize(("config", "index"), [("4-4-square", 0), ("2-4-line", 1)])
def test_catalogue_cells_with_right_and_wrong_guesses(
    loopback: Loopback, monkeypatch: pytest.MonkeyPatch, config: str, index: int, inline: bool
) -> None:
    """Catalogue cells with walks and new requests: the plan changes mid-episode (the executor
    replans), so with hints only some guesses are wrong (undone at the node) and some right
    (kept): the same log either way (with foresight too: tests/bus/test_foresee.py)."""
    if inline:
        guesses_in_the_answer(monkeypatch)
    trial = make_trial(config, index)
    kw = {"instruction": trial.instruction, "events": trial.events, "seed": trial.seed}
    local = run_episode(trial.scene, **kw)
    run = loopback.run(trial.scene, foresee=False, **kw)
    same_as_local(local, run)
    stats = run.node.stats
    assert stats.guesses_kept > 0  # (the executor waits for a guess its commands match)
    if inline:
        assert stats.guesses_kept < stats.guessed and stats.undone > 0  # some undone


@MODES
def test_a_wrong_guess_never_shows(
    loopback: Loopback, monkeypatch: pytest.MonkeyPatch, inline: bool
) -> None:
    """Every guess wrong (hinted or foreseen): the node starts them (a start that fails at
    once among them) and undoes them; the log is the in-process one, no guessed start is
    counted, and observers of the robots' reports hear only outcomes the log has."""
    scene, kw = _fig1()
    local = run_episode(scene, **kw)
    wrong_hints(monkeypatch)
    if inline:
        guesses_in_the_answer(monkeypatch)
    heard: list[Report] = []
    lock = threading.Lock()

    def on_status(sample: Any) -> None:
        rep = Report.decode(sample.payload.to_bytes())
        with lock:
            heard.append(rep)

    def outcomes(episode: str) -> set[tuple[int, str, float]]:
        with lock:
            return {
                (r.handle, r.status.state.value, round(r.status.t, 6))
                for r in heard
                if r.status.terminal and r.episode == episode
            }

    sub = loopback._exec_session.declare_subscriber(Keys("default").all_status, on_status)
    try:
        run = loopback.run(scene, **kw)
        ends = {
            (r.handle, kind, r.end)
            for r in run.episode.records
            for kind in [_ended(r)]
            if kind is not None
        }
        # (the reports published before the episode's end may still be in flight)
        deadline = time.monotonic() + 5.0
        while not ends <= outcomes(run.cell.episode) and time.monotonic() < deadline:
            time.sleep(0.05)
        time.sleep(0.1)  # (and anything a guess would have published, after them)
    finally:
        sub.undeclare()
    same_as_local(local, run)
    stats = run.node.stats
    assert stats.guesses_kept == 0 and run.cell.stats.guessed == 0
    if inline:
        assert stats.guessed > 0 and stats.undone > 0
    # the executor knew each hinted guess wrong from its own commands: it never waited for
    # one (only for the steps the node planned itself, which it cannot know)
    assert run.cell.stats.awaited_hinted == 0
    assert outcomes(run.cell.episode) == ends


def _ended(rec: LogRecord) -> str | None:
    return {"action_done": "done", "action_failed": "failed", "action_halted": "halted"}.get(
        rec.type
    )
