"""A request to foresee that reaches the node before its episode's reset (docs/bus.md, "The
reset race (session 31)"): the executor sends it right after the reset, and when that reset
was lost and sent again (no queryable matched it yet: the node had just started) the copy is
queued behind the request on the node's step thread. The node parks the request, serves the
reset, then the request: the briefing is taken and the first step foreseen. Before session 31
the step thread waited there for the reset queued behind it, refused the briefing after
``RESET_WAIT`` (1 s) and the first step was asked about.

Each test puts the queries in that order itself (no sleep races the scheduler)."""

from __future__ import annotations

import threading
import time
from typing import Any

import pytest

from hltl.bus import node as node_module
from hltl.bus.codec import dumps
from hltl.bus.driver import BusCell
from hltl.bus.node import CellNode
from hltl.sim.dynamic import make_trial
from hltl.sim.episode import run_episode
from tests.bus.helpers import (
    END_WAIT,
    ROUTE_WAIT,
    BusRun,
    Loopback,
    patient_foresight,
    same_as_local,
)


def _first_planned(monkeypatch: pytest.MonkeyPatch) -> list[float]:
    """The cell times at which nodes plan a step themselves (a spy on ``_foreseen``)."""
    planned_at: list[float] = []
    real = CellNode._foreseen

    def foreseen(self: CellNode, s: Any, world: Any) -> Any:
        planned_at.append(s.t)
        return real(self, s, world)

    monkeypatch.setattr(CellNode, "_foreseen", foreseen)
    return planned_at


def _run(loopback: Loopback, **kw: Any) -> BusRun:
    """4-1 #0 over the bus with the first step foreseen, checked against the in-process run."""
    trial = make_trial("4-1", 0)
    ep = {"instruction": trial.instruction, "events": trial.events, "seed": trial.seed}
    local = run_episode(trial.scene, **ep)
    run = loopback.run(trial.scene, **ep, first=True, **kw)
    if "node" in kw:  # (a node left open: the end's count is waited for here)
        assert run.node.finished.wait(END_WAIT)
    same_as_local(local, run)
    return run


def _foreseen_first(run: BusRun, planned_at: list[float]) -> None:
    """The node took the executor's briefing, planned the first step on the first world, and
    the executor's first spec was the one it grounded."""
    assert run.node.stats.briefed == 1 and run.node.stats.respecs == 0
    assert 0.0 in planned_at
    assert run.node.stats.foreseen_kept >= 1
    assert run.node.stats.malformed == 0


def test_a_request_queued_before_its_reset_waits_for_it(
    loopback: Loopback, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The first reset reaches the node's step thread only after the request that followed
    it (as a reset sent again does): the request is parked, the reset served, then the
    request. The old wait (``_await_reset``, until session 31) fails here: it held the thread
    1 s for a reset queued behind it and refused the briefing."""
    patient_foresight(monkeypatch)
    planned_at = _first_planned(monkeypatch)
    real_put = node_module._Inbox.put
    held: list[Any] = []
    order: list[str] = []

    def put(self: Any, query: Any) -> None:
        payload = node_module._payload(query)
        reset = payload.startswith(node_module.RESET_HEAD)
        if reset and not order:  # the first reset: held until the next query is in
            held.append(query)
            order.append("reset held")
            return
        order.append("reset" if reset else "foresee" if b'"foresee"' in payload else "step")
        real_put(self, query)
        if held:
            order.append("reset")
            real_put(self, held.pop())

    monkeypatch.setattr(node_module._Inbox, "put", put)
    run = _run(loopback)
    assert order[:3] == ["reset held", "foresee", "reset"]  # (the race, reproduced)
    _foreseen_first(run, planned_at)
    assert run.node.stats.parked == 1 and run.node.stats.parked_refused == 0


def test_a_request_before_a_reset_on_its_own_queryable_is_handed_back(
    loopback: Loopback, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A reset on ``…/sim/reset`` (as lockstep executors sent it until session 20) is
    answered on another thread: taken only once the request after it has been parked, it
    hands that request back to the step thread, which serves it."""
    patient_foresight(monkeypatch)
    planned_at = _first_planned(monkeypatch)
    monkeypatch.setattr(BusCell, "_reset_key", property(lambda self: self.keys.sim_reset))
    parked = threading.Event()
    real_park, real_on_reset = CellNode._park, CellNode._on_reset

    def park(self: CellNode, query: Any) -> bool:
        out = real_park(self, query)
        if out:
            parked.set()
        return out

    def on_reset(self: CellNode, query: Any) -> None:
        # (on a thread of its own: Zenoh's, blocked, would hold back the request too)
        def later() -> None:
            parked.wait(ROUTE_WAIT)  # (never parked: the counts below say so)
            real_on_reset(self, query)

        threading.Thread(target=later, daemon=True).start()

    monkeypatch.setattr(CellNode, "_park", park)
    monkeypatch.setattr(CellNode, "_on_reset", on_reset)
    run = _run(loopback)
    _foreseen_first(run, planned_at)
    assert run.node.stats.parked == 1 and run.node.stats.parked_refused == 0


def _ghost(loopback: Loopback, node: CellNode, timeout: float) -> Any:
    """A request to foresee for an episode never reset, sent to ``node`` (its replies)."""
    request = {"episode": "ghost", "foresee": True, "t": 0.0, "ahead": {}}
    return loopback._exec_session.get(node.keys.sim_step, payload=dumps(request), timeout=timeout)


def test_a_request_whose_reset_never_comes_is_refused_after_the_wait(
    loopback: Loopback, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(node_module, "RESET_WAIT", 0.0)  # (over at once)
    node = loopback.node(make_trial("4-1", 0).scene)
    try:
        replies = list(_ghost(loopback, node, ROUTE_WAIT))
    finally:
        node.close()
    assert len(replies) == 1 and replies[0].err is not None
    assert "its reset did not come within 0 s" in replies[0].err.payload.to_bytes().decode()
    assert node.stats.parked == node.stats.parked_refused == 1


def test_a_parked_request_holds_up_no_other_episode(
    loopback: Loopback, monkeypatch: pytest.MonkeyPatch
) -> None:
    """While a request waits for a reset that is not coming, another episode is served in
    full, its first step foreseen (the old wait held the step thread for all of it)."""
    patient_foresight(monkeypatch)
    planned_at = _first_planned(monkeypatch)
    monkeypatch.setattr(node_module, "RESET_WAIT", 600.0)
    node = loopback.node(make_trial("4-1", 0).scene)
    try:
        ghost = _ghost(loopback, node, 600.0)
        # (parked once the step thread has taken it: the episode's queries come after it)
        deadline = time.monotonic() + ROUTE_WAIT
        while not node.stats.parked:
            assert time.monotonic() < deadline, "the ghost request was never parked"
            time.sleep(0.001)
        run = _run(loopback, node=node)
        _foreseen_first(run, planned_at)
        assert node.stats.parked == 1 and node.stats.parked_refused == 0
    finally:
        node.close()
    del ghost
