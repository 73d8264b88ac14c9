"""Whoever hands Zenoh a message that someone waits for and then works on at once gives its core
up for a moment (``hltl.bus.session.let_go``), so that Zenoh's sending thread, woken on that
core, sends it now rather than at the next scheduler tick (docs/bus.md, "Where the time goes
(session 19)"): the node after each answer, the executor after each request it does not wait
for at once (the reset, the foresight requests), and every put through a :class:`Link`."""

from __future__ import annotations

from typing import Any

import pytest

from hltl.bus.driver import BusCell
from hltl.bus.faults import Link
from hltl.sim.dynamic import make_trial
from hltl.sim.episode import run_episode
from tests.bus.helpers import Loopback, same_as_local


class _Query:
    """A query as the node's handlers see it: its replies are recorded."""

    key_expr = "hltl/default/sim/step"

    def __init__(self, events: list[str]) -> None:
        self.events = events

    def reply(self, key: str, payload: bytes) -> None:
        self.events.append("reply")


class _Session:
    def __init__(self, events: list[str]) -> None:
        self.events = events

    def put(self, key: str, payload: bytes, **kw: Any) -> None:
        self.events.append("put")


def _recording(monkeypatch: pytest.MonkeyPatch, module: str, events: list[str]) -> None:
    monkeypatch.setattr(f"{module}.let_go", lambda: events.append("let go"))


def test_the_node_lets_go_after_each_answer(
    loopback: Loopback, monkeypatch: pytest.MonkeyPatch
) -> None:
    events: list[str] = []
    _recording(monkeypatch, "hltl.bus.node", events)
    trial = make_trial("1-1", 0)
    node = loopback.node(trial.scene)
    try:
        assert node._reply_bytes(_Query(events), b"{}")
        assert node._reply_bytes(_Query(events), b"{}")
    finally:
        node.close()
    assert events == ["reply", "let go", "reply", "let go"]


def test_a_put_lets_go() -> None:
    events: list[str] = []
    link = Link(_Session(events))
    with pytest.MonkeyPatch.context() as mp:
        _recording(mp, "hltl.bus.faults", events)
        link.put("hltl/default/robots/r1/action", b"{}")
    link.close()
    assert events == ["put", "let go"]


def test_the_executor_lets_go_after_the_requests_it_does_not_wait_for(
    loopback: Loopback, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The reset (answered while the executor grounds its instruction), the request to foresee
    the first step (its briefing) and a new spec's basis each go with a let-go right after
    them; the episode is the in-process one."""
    events: list[str] = []
    _recording(monkeypatch, "hltl.bus.driver", events)
    query = BusCell._query

    def recorded(self: BusCell, key: str, payload: bytes, commands: bool) -> Any:
        kind = (
            "reset" if key.endswith("reset") else ("foresee" if b'"foresee"' in payload else "step")
        )
        events.append(kind)
        return query(self, key, payload, commands)

    monkeypatch.setattr(BusCell, "_query", recorded)
    trial = make_trial("2-2", 0)  # (a second request: a new spec's basis goes to the node)
    episode = {"instruction": trial.instruction, "events": trial.events, "seed": trial.seed}
    local = run_episode(trial.scene, **episode)
    run = loopback.run(trial.scene, **episode)
    same_as_local(local, run)
    unwaited = [i for i, e in enumerate(events) if e in ("reset", "foresee")]
    assert events[0] == "reset" and sum(e == "foresee" for e in events) >= 2
    assert all(events[i + 1] == "let go" for i in unwaited)
