"""A node's step queries reach its step thread through an inbox, not Zenoh's own channel
(docs/bus.md, "Where the time goes (session 26)"): a thread waiting in Zenoh's ``recv`` wakes
every 100 ms to look for signals, taking the interpreter lock from whichever thread simulates.
An idle node's step thread must not wake; a wait with a timeout ends when a query comes."""

from __future__ import annotations

import os
import threading
import time
from typing import Any

import pytest

from hltl.bus.node import _Inbox
from hltl.errors import BusError
from hltl.sim.dynamic import make_trial
from tests.bus.helpers import Loopback


class _Payload:
    def __init__(self, data: bytes) -> None:
        self.data = data

    def to_bytes(self) -> bytes:
        return self.data


class _Query:
    """A step query as the node's step thread sees it."""

    def __init__(self, data: bytes) -> None:
        self.payload = _Payload(data)


def _later(seconds: float, f: Any, *args: Any) -> threading.Thread:
    t = threading.Thread(target=lambda: (time.sleep(seconds), f(*args)), daemon=True)
    t.start()
    return t


def test_the_inbox_gives_queries_in_order_and_none_when_empty() -> None:
    box = _Inbox()
    assert box.try_recv() is None
    box.put("a")
    box.put("b")
    assert box.try_recv() == "a"
    assert box.recv() == "b"
    assert box.try_recv(0.01) is None  # (waited, none came)


def test_a_wait_ends_when_a_query_comes() -> None:
    box = _Inbox()
    _later(0.05, box.put, "q")
    assert box.try_recv(60.0) == "q"  # (not the whole minute: it came)
    _later(0.05, box.put, "r")
    assert box.recv() == "r"


def test_a_closed_inbox_says_so_to_every_look() -> None:
    box = _Inbox()
    box.put("a")
    box.close()
    assert box.recv() == "a"  # (what came before the close is still given)
    for _ in range(2):
        with pytest.raises(BusError, match="withdrawn"):
            box.recv()
        with pytest.raises(BusError, match="withdrawn"):
            box.try_recv(0.01)


def test_a_waiting_recv_ends_when_the_inbox_closes() -> None:
    box = _Inbox()
    _later(0.05, box.close)
    with pytest.raises(BusError):
        box.recv()


def _voluntary_switches(tid: int) -> int:
    with open(f"/proc/self/task/{tid}/status") as f:
        for line in f:
            if line.startswith("voluntary_ctxt_switches:"):
                return int(line.split()[1])
    raise AssertionError(f"no voluntary_ctxt_switches for thread {tid}")


@pytest.mark.skipif(not os.path.exists("/proc/self/task"), reason="needs Linux /proc")
def test_an_idle_node_step_thread_does_not_wake(loopback: Loopback) -> None:
    node = loopback.node(make_trial("1-1", 0).scene)
    try:
        tid = node._server.native_id
        assert tid is not None
        time.sleep(0.3)  # (in its wait by now)
        before = _voluntary_switches(tid)
        time.sleep(1.0)
        # Zenoh's recv wakes every 100 ms (about 10 times here)
        assert _voluntary_switches(tid) - before <= 2
    finally:
        node.close()
    assert not node._server.is_alive()


def test_the_step_thread_ends_when_the_node_session_dies(loopback: Loopback) -> None:
    node = loopback.node(make_trial("1-1", 0).scene)
    loopback.kill_node_session()  # (no close: Zenoh's drop callback closes the inbox)
    node._server.join(30.0)
    assert not node._server.is_alive()
    node.close()


def test_a_pause_returns_the_query_that_came_and_takes_in_a_basis_on_the_way(
    loopback: Loopback,
) -> None:
    node = loopback.node(make_trial("1-1", 0).scene)
    served = node._steps  # (the node's step thread waits there: this inbox is the test's)
    node._steps = _Inbox()
    try:
        step = _Query(b'{"episode": "e", "step": 1, "t": 0.0}')
        _later(0.05, node._steps.put, step)
        assert node._pause(60.0) is step
        # a new basis for an episode the node does not run is served as a query, too
        basis = _Query(b'{"episode": "e", "foresee": true}')
        node._steps.put(basis)
        assert node._pause(60.0) is basis
        assert node._pause(0.01) is None
    finally:
        served.close()
        node.close()
