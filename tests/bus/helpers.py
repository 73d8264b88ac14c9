"""Helpers for bus tests: a node session and an executor session on a loopback port."""

from __future__ import annotations

import time
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from functools import partial
from typing import Any

import pytest

from hltl.bus.driver import BusCell, BusTiming, _listeners_of, bus_cell
from hltl.bus.faults import FaultModel
from hltl.bus.keys import robot_of
from hltl.bus.node import CellNode
from hltl.bus.realtime import realtime_bus_cell
from hltl.bus.session import BusConfig, open_session
from hltl.execution.drivers import Expected
from hltl.execution.foresee import foresee_steps as _foresee_steps
from hltl.execution.log import LogRecord
from hltl.sim.episode import Episode, run_episode
from hltl.skills.library import Action
from hltl.world.scene import Scene


def without_wall_clock(x: Any) -> Any:
    """A record or metrics dict without wall-clock measurements (``*_ms`` fields): the only
    fields that legitimately differ between two runs of the same episode."""
    if isinstance(x, LogRecord):
        return without_wall_clock(x.to_json())
    if isinstance(x, Mapping):
        return {k: without_wall_clock(v) for k, v in x.items() if not str(k).endswith("_ms")}
    if isinstance(x, list | tuple):
        return [without_wall_clock(v) for v in x]
    return x


@dataclass
class BusRun:
    episode: Episode
    node: CellNode
    cell: BusCell


# how long a test waits for its node to take the episode's end (at once, unless loaded)
END_WAIT = 10.0
# the executor's query timeout in the runs of a test that counts (see patient_foresight)
PATIENT_TIMEOUT = 30.0
# how long a test waits for the executor's session to know a new node (at once, unless loaded)
ROUTE_WAIT = 30.0


class Loopback:
    """A node session and an executor session on one loopback endpoint."""

    # (set by patient_foresight: runs given no timing wait PATIENT_TIMEOUT for an answer)
    patient = False

    def __init__(self, endpoint: str) -> None:
        self.endpoint = endpoint
        self._node_session = open_session(BusConfig(listen=(endpoint,)))
        self._exec_session = open_session(BusConfig(connect=(endpoint,)))
        # the executor's report and liveliness subscriptions (declared once per session, with
        # its first cell otherwise): declared now, so that reach() waits for the node to know them
        _listeners_of(self._exec_session)

    def run(
        self,
        scene: Scene,
        *,
        node_faults: FaultModel | None = None,
        exec_faults: FaultModel | None = None,
        timing: BusTiming | None = None,
        on_record: Callable[[LogRecord], None] | None = None,
        cell: str = "default",
        factory: Any = None,
        ahead: int = 64,
        stream: bool | None = None,
        guess: bool = True,
        foresee: bool = True,
        background: bool = False,
        first: bool = False,
        realtime: float | None = None,
        node: CellNode | None = None,
        **episode: Any,
    ) -> BusRun:
        """One episode over the bus (``realtime``: the node runs it on its own clock, that
        many times faster than real time), served by a node of its own or by ``node`` (from
        :meth:`node`, left open)."""
        opened: list[BusCell] = []
        served = {} if factory is None else {"factory": factory}
        make: Any = (
            partial(bus_cell, foresee=foresee, background=background, first=first)
            if realtime is None
            else partial(realtime_bus_cell, factor=realtime)
        )
        if timing is None and self.patient:
            timing = BusTiming(timeout=PATIENT_TIMEOUT)
        own = node is None
        if node is None:
            node = self.node(scene, cell=cell, faults=node_faults, **served)
        try:
            ep = run_episode(
                scene,
                simulator=make(
                    self._exec_session,
                    cell=cell,
                    timing=timing,
                    faults=exec_faults,
                    opened=opened,
                    ahead=ahead,
                    stream=stream,
                    guess=guess,
                ),
                on_record=on_record,
                **episode,
            )
            (bc,) = opened
            bc.end()
            bc.close()
            if own and not bc._dead:
                # the end commits the guessed starts the executor took (the node counts them
                # then): a loaded node may take it after the executor stopped waiting for the
                # answer, and closing it first would lose the count, not a start
                node.finished.wait(END_WAIT)
        finally:
            if own:
                node.close()
        return BusRun(ep, node, bc)

    def node(self, scene: Scene, **kw: Any) -> CellNode:
        """A cell node on the node's session (close it when done), once the executor's session
        knows it (:meth:`reach`)."""
        node = CellNode(self._node_session, scene, **kw)
        try:
            self.reach(node)
        except BaseException:
            node.close()
            raise
        return node

    def reach(self, node: CellNode) -> None:
        """Wait (up to ``ROUTE_WAIT``) until the executor's session knows what ``node``
        declared (its queryables: a query goes to it; its command subscribers: a command
        reaches it; its robots' liveliness tokens) and the node's session knows the executor's
        report subscription (a report reaches the executor). The declarations cross the
        loopback link on Zenoh's threads; on a loaded machine the executor's reset, sent as its
        cell is built, went before them and matched nothing: lost at once, it was sent again,
        and the briefing or first basis sent right after it reached the node first, which held
        it ``RESET_WAIT`` for a reset queued behind it and then refused it (no episode): the
        first step was asked about, not foreseen, and every test that counts foresight failed
        (the red trains of session 29; since session 31 the node parks such a request until
        its reset is answered, tests/bus/test_reset_order.py). A node is up before its
        executor starts (``hltl node sim`` is started first; the executor retries a reset
        nobody answers), so the tests wait for that here rather than count what a node
        starting mid-reset does."""
        k, session = node.keys, self._exec_session
        entities = [session.declare_querier(key) for key in (k.sim_step, k.sim_reset)]
        entities += [session.declare_publisher(k.action(r)) for r in node.scene.robot_ids]
        # (and the other way: the node's reports reach the executor's subscription)
        entities += [
            self._node_session.declare_publisher(k.status(r)) for r in node.scene.robot_ids
        ]
        robots = set(node.scene.robot_ids)
        deadline = time.monotonic() + ROUTE_WAIT
        try:
            while True:
                matched = all(e.matching_status.matching for e in entities)
                if matched and robots <= _tokens(session, k.all_alive):
                    return
                if time.monotonic() > deadline:
                    raise AssertionError(
                        f"the executor's session did not know the node of cell {k.cell!r} "
                        f"within {ROUTE_WAIT:g} s"
                    )
                time.sleep(0.001)
        finally:
            for e in entities:
                e.undeclare()

    def kill_node_session(self) -> None:
        """The node's process dies: its session goes away without a word."""
        self._node_session.close()

    def close(self) -> None:
        for s in (self._exec_session, self._node_session):
            if not s.is_closed():
                s.close()


def _tokens(session: Any, key: str) -> set[str]:
    """The robots whose liveliness token under ``key`` the session sees held."""
    replies = session.liveliness().get(key, timeout=1.0)
    return {robot_of(str(r.ok.key_expr)) for r in replies if r.ok is not None}


_expect = BusCell.expect


def _wrong(self: BusCell, steps: Sequence[Expected]) -> None:
    """A hint that is always wrong: every action twice (the second start fails at once on the
    node, its robot busy), so the executor's commands never match it."""
    _expect(self, [Expected(s.actions + s.actions, s.at) for s in steps])


def patient_foresight(monkeypatch: pytest.MonkeyPatch) -> None:
    """Lift every wall-clock limit that changes what a run over the bus counts: the node's
    planner takes its time when it foresees a step (the default gives up after 50 ms, which a
    loaded machine may take), the node waits for a new spec's basis after an instruction
    (``FORESEE_WAIT``, else it guesses from the hint), and the executor waits for the node's
    stretches (a query's replies end at its timeout, 1 s by default: a node slowed 100 ms a
    tick outlasted it in 4-2 #0 and the executor asked 9 times, guesses missed; the
    context-change test's red trains of session 20 and 21). A test that counts queries,
    commands, guesses or cuts calls this first."""
    monkeypatch.setattr("hltl.bus.node.FORESEE_TIMEOUT", 60.0)
    monkeypatch.setattr("hltl.bus.node.FORESEE_WAIT", 30.0)
    monkeypatch.setattr(Loopback, "patient", True)


def guesses_in_the_answer(monkeypatch: pytest.MonkeyPatch) -> None:
    """Make nodes send guessed steps in the answer itself, not as further replies: every guess
    the node makes is then made before the executor can answer it (streamed, an executor that
    knows a guess wrong may ask before the node has made it, on a fast machine always)."""
    monkeypatch.setattr("hltl.bus.node.GUESS_STREAM", False)


def _wrong_steps(*args: Any, **kwargs: Any) -> tuple[tuple[Action, ...], ...]:
    """The node's foresight, always wrong: every action of the plan's steps twice (as
    :func:`_wrong`)."""
    return tuple(s + s for s in _foresee_steps(*args, **kwargs))


def wrong_foresight(monkeypatch: pytest.MonkeyPatch) -> None:
    """Make every step a node foresees itself wrong (:func:`_wrong_steps`)."""
    monkeypatch.setattr("hltl.bus.node.foresee_steps", _wrong_steps)


def same_as_local(local: Episode, run: BusRun) -> None:
    """The same log and metrics as in-process, and every action started once by the node."""
    assert without_wall_clock(list(run.episode.records)) == without_wall_clock(list(local.records))
    assert without_wall_clock(run.episode.metrics.to_dict()) == without_wall_clock(
        local.metrics.to_dict()
    )
    starts = [r.handle for r in local.records if r.type == "action_start"]
    assert run.node.stats.starts == dict.fromkeys(starts, 1)


def wrong_hints(monkeypatch: pytest.MonkeyPatch) -> None:
    """Make every guess wrong: each hint the executor gives a bus cell (:func:`_wrong`) and
    each step a node foresees itself (:func:`wrong_foresight`)."""
    monkeypatch.setattr(BusCell, "expect", _wrong)
    wrong_foresight(monkeypatch)
