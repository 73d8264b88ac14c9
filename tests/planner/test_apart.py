"""Exact mode's A* process (``phase._Apart``, docs/planner.md "A* in a process of its own"):
whatever the first phase does — end normally, run out of time, raise, or leave a round open —
no process of a plan outlives it, and A* is never left paused while its answer is awaited."""

from __future__ import annotations

import os
import signal
import threading
import time
from collections.abc import Callable
from pathlib import Path

import pytest

from hltl import planner
from hltl.bench.cells import delivery_cell
from hltl.planner import PlanStatus, WorkClock, anytime, lns, phase, plan, schedule
from hltl.planner.problem import Problem
from hltl.planner.search import _Search, search
from tests.oracles.validator import check_plan

pytest.importorskip("ortools")
pytestmark = pytest.mark.skipif(
    not anytime.beside_possible() or not Path("/proc/self/stat").exists(),
    reason="needs two cores, fork and /proc",
)


def _children() -> dict[int, str]:
    """This process's children: pid -> state (R, S, T: stopped, Z: not yet reaped, ...)."""
    me = os.getpid()
    found = {}
    for entry in Path("/proc").iterdir():
        if not entry.name.isdigit():
            continue
        try:
            stat = (entry / "stat").read_text()
        except OSError:
            continue  # (ended meanwhile)
        fields = stat[stat.rindex(")") + 2 :].split()
        if int(fields[1]) == me:
            found[int(entry.name)] = fields[0]
    return found


def _until(holds: Callable[[], bool], seconds: float = 30.0) -> bool:
    """Whether ``holds()`` comes true within ``seconds`` (asked every 10 ms)."""
    end = time.monotonic() + seconds
    while not holds():
        if time.monotonic() > end:
            return False
        time.sleep(0.01)
    return True


def _phase_calls(monkeypatch: pytest.MonkeyPatch, then: Callable[[], object]) -> list[int]:
    """Let the real phase start A*'s process (``ahead``), open a round that pauses it
    (``lns.note_busy(2)``) and do ``then`` (raise, or end the phase without closing the
    round); the pids of the processes it started are returned in the list."""
    pids: list[int] = []

    def certify(
        problem: Problem,
        s: _Search,
        until: float,
        beside: object = None,
        ahead: Callable[[], None] | None = None,
        watch: object = None,
    ) -> object:
        before = set(_children())
        assert ahead is not None
        ahead()
        pids.extend(set(_children()) - before)
        lns.note_busy(schedule.WORKERS)
        # (the pause takes once the kernel has delivered the signal: not at once under load)
        assert _until(lambda: all(_children().get(pid) == "T" for pid in pids))
        return then()

    monkeypatch.setattr(phase, "certify", certify)
    return pids


def _line_6_5(monkeypatch: pytest.MonkeyPatch) -> tuple[object, object]:
    # the phase runs on cells of more than PHASE_ABOVE goals; line 6 seed 5 is quick for A*
    monkeypatch.setattr(planner, "PHASE_ABOVE", 0)
    c = delivery_cell("line", 6, 5)
    return c.scene, c.spec


def test_no_process_outlives_a_plan_the_phase_leaves_to_astar(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    scene, spec = _line_6_5(monkeypatch)
    started: list[phase._Apart] = []
    real_ahead = phase._Apart.ahead

    def ahead(self: phase._Apart) -> None:
        real_ahead(self)
        started.append(self)

    monkeypatch.setattr(phase._Apart, "ahead", ahead)
    before = set(_children())
    got = plan(scene, spec, timeout=120)
    assert got.solved and len(started) == 1 and started[0].proc is not None
    assert set(_children()) - before == set()
    assert got.stats.phase is not None and got.stats.held is not None
    assert 0.0 <= got.stats.held <= got.stats.seconds


def test_no_process_outlives_a_plan_that_times_out() -> None:
    # grid 10 x 10 seed 2: neither the phase (0.75 x 2 s) nor A* (until 1.9 s) ends in time.
    # On a clock of work that is so on any machine: the phase's CP-SAT gets no time, and A*'s
    # process stops after the same expansions (about 170; it needs tens of thousands)
    c = delivery_cell("grid", 10, 2)
    before = set(_children())
    got = plan(c.scene, c.spec, timeout=2.0, clock=WorkClock(0.01))
    assert got.status is PlanStatus.TIMEOUT
    assert got.stats.phase is not None  # (A* ran in its process beside the phase)
    assert set(_children()) - before == set()


def test_no_process_outlives_a_phase_that_raises(monkeypatch: pytest.MonkeyPatch) -> None:
    scene, spec = _line_6_5(monkeypatch)

    def boom() -> object:
        raise RuntimeError("the phase failed")

    pids = _phase_calls(monkeypatch, boom)
    before = set(_children())
    with pytest.raises(RuntimeError, match="the phase failed"):
        plan(scene, spec, timeout=120)
    assert len(pids) == 1
    assert set(_children()) - before == set()
    assert lns._busy is None  # (no later plan's rounds reach this one's process)


def test_astar_is_resumed_when_a_phase_leaves_a_round_open(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # the phase ends without closing the round that paused A*: its answer is still awaited and
    # given (a paused A* would never answer; the watchdog resumes it and the test fails)
    scene, spec = _line_6_5(monkeypatch)
    pids = _phase_calls(monkeypatch, lambda: phase.Certificate(None, None))
    rescued: list[int] = []

    def rescue() -> None:
        for pid, state in _children().items():
            if pid in pids and state == "T":
                rescued.append(pid)
                os.kill(pid, signal.SIGCONT)

    watchdog = threading.Timer(60.0, rescue)
    watchdog.start()
    try:
        got = plan(scene, spec, timeout=120)
    finally:
        watchdog.cancel()
    assert rescued == []
    expected = search(Problem(scene, spec), timeout=120)
    assert got.solved and got.makespan == pytest.approx(expected.makespan)
    assert got.stats.expanded > 0  # (A*'s answer, from its process)
    check_plan(scene, spec, got.to_dict())
    assert not set(pids) & set(_children())


def test_a_round_whose_question_raises_is_closed(monkeypatch: pytest.MonkeyPatch) -> None:
    # schedule's climb tells ``note_busy`` when a round of questions begins and ends; a question
    # that raises ends the round too (else exact mode's A* would stay paused)
    monkeypatch.setattr(planner, "PHASE_ABOVE", 0)
    c = delivery_cell("grid", 4, 1)
    problem = Problem(c.scene, c.spec)
    s = _Search(problem)
    start = problem.start()
    told: list[int] = []

    def boom(*_: object, **__: object) -> object:
        raise RuntimeError("a question failed")

    monkeypatch.setattr(schedule, "relaxed_steps", boom)
    lns.share_busy(told.append)
    try:
        with pytest.raises(RuntimeError, match="a question failed"):
            anytime.step_bound(problem, s, start, round(s.heuristic(start)), None, 1e18)
    finally:
        lns.share_busy(None)
    assert told[0] >= 1 and told[-1] == 0
