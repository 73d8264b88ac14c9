"""A stretch in parts (``hltl.bus.node.SPLIT``): an answer, and each guessed step's reply, go
once they hold the first items of their step, the rest of the step following as one further
reply. Nothing of it shows: the log is the in-process one, every action started once."""

from __future__ import annotations

from typing import Any

import pytest

from hltl.bus.driver import BusTiming
from hltl.bus.faults import FaultModel
from hltl.bus.node import SPLIT, CellNode
from hltl.sim.dynamic import make_trial
from hltl.sim.episode import run_episode
from tests.bus.helpers import BusRun, Loopback, same_as_local, wrong_hints

# a plan that holds (4-1 #0), walks that make the node plan steps itself (4-2 #1), a second
# request (2-2 #0)
CELLS = [("4-1", 0), ("4-2", 1), ("2-2", 0)]


def _run(lb: Loopback, config: str, index: int, split: int, **kw: Any) -> tuple[Any, BusRun]:
    trial = make_trial(config, index)
    episode = {"instruction": trial.instruction, "events": trial.events, "seed": trial.seed}
    local = run_episode(trial.scene, **episode)
    node = lb.node(trial.scene, faults=kw.pop("node_faults", None))
    node.split = split
    try:
        run = lb.run(trial.scene, node=node, **kw, **episode)
    finally:
        node.close()
    return local, run


def test_the_default_splits() -> None:
    assert SPLIT > 0


@pytest.mark.parametrize(("config", "index"), CELLS)
def test_parts_give_the_in_process_log(loopback: Loopback, config: str, index: int) -> None:
    """Not split, split after one item (a guessed step's starts alone, or a single tick), or
    after three: the same log; the rest of a split step comes as a further reply (counted by
    the executor, none without splitting), which the executor waits for rather than ask: no
    more queries than whole (but for a guess a busy machine makes too late: a few)."""
    local, whole = _run(loopback, config, index, 0)
    same_as_local(local, whole)
    assert whole.cell.stats.split == 0 and whole.cell.stats.guessed > 0
    for split in (1, 3):
        _, run = _run(loopback, config, index, split)
        same_as_local(local, run)
        assert run.cell.stats.split > 0 and run.cell.stats.guessed > 0
        assert run.cell.stats.queries <= whole.cell.stats.queries + 3


@pytest.mark.parametrize("split", [1, 3])
def test_wrong_guesses_in_parts_are_undone(
    loopback: Loopback, monkeypatch: pytest.MonkeyPatch, split: int
) -> None:
    """Every hint and every step the node foresees made wrong: the guesses, sent in parts,
    are undone as whole ones are; the log is the in-process one."""
    wrong_hints(monkeypatch)
    local, run = _run(loopback, "4-2", 1, split)
    same_as_local(local, run)
    assert run.cell.stats.guessed == 0


@pytest.mark.parametrize("seed", [13, 21])
def test_a_lost_part_is_asked_for(loopback: Loopback, seed: int) -> None:
    """Replies lost, among them parts of split steps: the executor asks for what it misses;
    the same log, nothing started twice or lost."""
    local, run = _run(
        loopback,
        "4-2",
        1,
        1,
        node_faults=FaultModel(reply_loss=0.25, seed=seed),
        timing=BusTiming(timeout=0.1, retries=6),
    )
    same_as_local(local, run)  # (the same log; every action started once)
    assert run.cell.stats.retransmits > 0  # (replies were lost, and asked for again)
    assert run.cell.stats.split > 0  # (steps did come in parts)


@pytest.mark.parametrize(("config", "index"), CELLS)
def test_a_stretch_runs_on_past_its_span(
    loopback: Loopback, monkeypatch: pytest.MonkeyPatch, config: str, index: int
) -> None:
    """Spans of 4 ticks (``ahead=4``): a stretch that has used up its span while an action
    runs goes on into the next, the ticks so far going at once as a part, so the executor
    waits for the next span rather than ask for it with no commands: fewer queries than with
    every such stretch ended (as before session 20), and the same log."""
    local, run = _run(loopback, config, index, SPLIT, ahead=4)
    same_as_local(local, run)
    assert run.node.stats.spans > 0
    monkeypatch.setattr(CellNode, "_spans_on", staticmethod(lambda ep, s: False))
    _, ended = _run(loopback, config, index, SPLIT, ahead=4)
    same_as_local(local, ended)
    assert ended.node.stats.spans == 0
    assert run.cell.stats.queries < ended.cell.stats.queries


def test_wrong_guesses_past_a_span_are_undone(
    loopback: Loopback, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Every guess wrong, with spans of 4 ticks run on past: what a command cuts (a span's
    save, or the stretch's) is undone as before; the log is the in-process one."""
    wrong_hints(monkeypatch)
    local, run = _run(loopback, "4-2", 1, SPLIT, ahead=4)
    same_as_local(local, run)
    assert run.node.stats.spans > 0 and run.node.stats.cuts > 0
    assert run.cell.stats.guessed == 0


@pytest.mark.parametrize(("config", "index"), [("2-2", 0), ("4-4-square", 0)])
def test_a_stream_sends_what_it_holds_before_grounding_ahead(
    loopback: Loopback, monkeypatch: pytest.MonkeyPatch, config: str, index: int
) -> None:
    """A request the node grounds ahead while it streams a stretch (milliseconds): the ticks
    it holds, not sent yet, go first as a part of their own, so the executor works on them
    meanwhile; the log is the in-process one."""
    from hltl.bus import node as N

    sent: dict[int, int] = {}  # by batch: the index after the last tick sent of it
    held: list[int] = []  # at each grounding ahead in a stream: ticks simulated, not sent
    encode, ground = N.encode_answer, N.ground_all

    def encoded(answer: dict[str, Any], ticks: Any = ()) -> bytes:
        ep = node._ep
        if "from" in answer and ep is not None and ep.batch is not None:
            sent[ep.batch.id] = max(sent.get(ep.batch.id, 0), int(answer["from"]) + len(ticks))
        return encode(answer, ticks)

    def grounded(*a: Any, **k: Any) -> Any:
        ep = node._ep
        s = None if ep is None else ep.stretch
        if s is not None and getattr(s, "early", None) is not None:
            held.append(len(s.batch.ticks) - sent.get(s.batch.id, 0))
        return ground(*a, **k)

    monkeypatch.setattr(N, "encode_answer", encoded)
    monkeypatch.setattr(N, "ground_all", grounded)
    trial = make_trial(config, index)
    episode = {"instruction": trial.instruction, "events": trial.events, "seed": trial.seed}
    local = run_episode(trial.scene, **episode)
    node = loopback.node(trial.scene)
    try:
        run = loopback.run(trial.scene, node=node, **episode)
    finally:
        node.close()
    same_as_local(local, run)
    assert held and all(n == 0 for n in held), held
