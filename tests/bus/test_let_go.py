"""A message someone waits for goes at once (docs/bus.md, "Where the time goes (session 19)").
Whoever hands Zenoh such a message and then works on at once gives its core up for a moment
(``hltl.bus.session.let_go``), so that Zenoh's sending thread, woken on that core, sends it now
rather than at the next scheduler tick: the node after each answer, the executor after each
request it does not wait for at once (the reset, the foresight requests), and every put through
a :class:`Link`. The node answers the reset out of its lock, so that its step thread takes up
the request to foresee the first step meanwhile."""

from __future__ import annotations

import threading
import time
from typing import Any

import pytest

from hltl.bus.driver import BusCell
from hltl.bus.faults import Link
from hltl.bus.node import RESET_HEAD, CellNode, _payload
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
        # with an executor in the node's process, one of the two waits for the interpreter:
        # the other core is Zenoh's
        monkeypatch.setattr("hltl.bus.node.executor_here", lambda: True)
        assert node._reply_bytes(_Query(events), b"{}")
    finally:
        node.close()
    assert events == ["reply", "let go", "reply", "let go", "reply"]


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

    def recorded(self: BusCell, key: str, payload: bytes, commands: bool, **kw: Any) -> Any:
        kind = (
            "reset"
            if payload.startswith(RESET_HEAD)
            else ("foresee" if b'"foresee"' in payload else "step")
        )
        events.append(kind)
        return query(self, key, payload, commands, **kw)

    monkeypatch.setattr(BusCell, "_query", recorded)
    trial = make_trial("2-2", 0)  # (a second request: a new spec's basis goes to the node)
    episode = {"instruction": trial.instruction, "events": trial.events, "seed": trial.seed}
    local = run_episode(trial.scene, **episode)
    run = loopback.run(trial.scene, **episode)
    same_as_local(local, run)
    unwaited = [i for i, e in enumerate(events) if e in ("reset", "foresee")]
    assert events[0] == "reset" and sum(e == "foresee" for e in events) >= 2
    assert all(events[i + 1] == "let go" for i in unwaited)


def test_the_reset_is_answered_out_of_the_node_lock(
    loopback: Loopback, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The reset's answer goes out of the node's lock, so that the step thread takes up the
    request to foresee the first step (sent right after the reset) while it goes; every other
    answer, under it. The episode is the in-process one."""
    held: dict[str, list[bool]] = {"reset": [], "step": []}
    reply = CellNode._reply_bytes

    def recorded(self: CellNode, query: Any, payload: bytes, key: str | None = None) -> bool:
        kind = "reset" if _payload(query).startswith(RESET_HEAD) else "step"
        held[kind].append(self._lock._is_owned())  # type: ignore[attr-defined]
        return reply(self, query, payload, key)

    monkeypatch.setattr(CellNode, "_reply_bytes", recorded)
    trial = make_trial("1-1", 0)
    episode = {"instruction": trial.instruction, "events": trial.events, "seed": trial.seed}
    local = run_episode(trial.scene, **episode)
    run = loopback.run(trial.scene, **episode)
    same_as_local(local, run)
    assert held["reset"] == [False]
    assert held["step"] and all(held["step"])


def test_the_first_step_is_foreseen_once_the_reset_is_answered(
    loopback: Loopback, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The step thread takes up the request to foresee the first step only once the reset's
    answer has gone: that answer needs the interpreter lock, which the step thread holds for
    milliseconds while it grounds the briefing and plans, and the executor waits for it (its
    first observation). Here the reset's answer is slow to go (50 ms): the briefing is still
    grounded after it, and the episode is the in-process one."""
    events: list[str] = []
    reply, brief = CellNode._reply_bytes, CellNode._take_brief

    def replied(self: CellNode, query: Any, payload: bytes, key: str | None = None) -> bool:
        if not _payload(query).startswith(RESET_HEAD):
            return reply(self, query, payload, key)
        time.sleep(0.05)
        try:
            return reply(self, query, payload, key)
        finally:
            events.append("reset answered")

    def briefed(self: CellNode, ep: Any, d: Any) -> None:
        events.append("briefing")
        brief(self, ep, d)

    monkeypatch.setattr(CellNode, "_reply_bytes", replied)
    monkeypatch.setattr(CellNode, "_take_brief", briefed)
    trial = make_trial("1-1", 0)
    episode = {"instruction": trial.instruction, "events": trial.events, "seed": trial.seed}
    local = run_episode(trial.scene, **episode)
    run = loopback.run(trial.scene, **episode)
    same_as_local(local, run)
    assert events == ["reset answered", "briefing"]
    assert run.node.stats.briefed == 1 and run.cell.stats.guessed > 0


def test_the_node_lets_go_before_it_plans_or_grounds(
    loopback: Loopback, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A plan or a grounding ahead takes the node's thread milliseconds: it lets go first (a
    reply the executor waits for may be queued on its core). The episode is the in-process
    one."""
    from hltl.bus import node as N

    events: list[tuple[int, str]] = []  # (the thread, what it did)

    def note(what: str) -> None:
        events.append((threading.get_ident(), what))

    monkeypatch.setattr(N, "let_go", lambda: note("let go"))
    monkeypatch.setattr(N, "executor_here", lambda: False)  # (a node in a process of its own)
    plan, ground = N.foresee_steps, N.ground_all

    def planned(*a: Any, **k: Any) -> Any:
        note("plan")
        return plan(*a, **k)

    def grounded(*a: Any, **k: Any) -> Any:
        note("ground")
        return ground(*a, **k)

    reply = CellNode._reply_bytes

    def replied(self: CellNode, query: Any, payload: bytes, key: str | None = None) -> bool:
        note("reply")
        return reply(self, query, payload, key)

    monkeypatch.setattr(N, "foresee_steps", planned)
    monkeypatch.setattr(N, "ground_all", grounded)
    monkeypatch.setattr(CellNode, "_reply_bytes", replied)
    trial = make_trial("2-2", 0)  # (a second request, grounded ahead by the node)
    episode = {"instruction": trial.instruction, "events": trial.events, "seed": trial.seed}
    local = run_episode(trial.scene, **episode)
    run = loopback.run(trial.scene, **episode)
    same_as_local(local, run)
    steps = [e for t, e in events if t == run.node._server.ident]  # (the step thread's)
    long = [i for i, e in enumerate(steps) if e in ("plan", "ground")]
    # (the node plans the first step itself; it grounds the second request ahead when it
    # simulates that tick ahead, which the executor's timing decides)
    assert "plan" in steps
    # (before a plan, a let-go of its own, not the one after an answer; before a grounding
    # ahead in a stream, the ticks it holds may go first: then the let-go after that reply)
    assert all(steps[i - 1] == "let go" for i in long)
    assert all(steps[i - 2] != "reply" for i in long if steps[i] == "plan")
