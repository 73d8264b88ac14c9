"""Foresight: the node plans the executor's next step itself after a walk; nothing of it shows."""

from __future__ import annotations

from itertools import combinations
from typing import Any

import pytest

from hltl.bus import node as node_module
from hltl.bus.codec import WireBriefing
from hltl.bus.driver import BusCell
from hltl.errors import GroundingError
from hltl.grounding import make_grounder
from hltl.sim.dynamic import make_trial
from hltl.sim.episode import run_episode
from hltl.spec.hierarchy import spec_from_dict
from tests.bus.helpers import (
    BusRun,
    Loopback,
    guesses_in_the_answer,
    patient_foresight,
    same_as_local,
    wrong_foresight,
)

# the node's guessed steps as further replies (as deployed), and in the answer itself, where
# the node makes every guess before the executor can answer it (so the counts are certain)
MODES = pytest.mark.parametrize("inline", [False, True], ids=["streamed", "in-the-answer"])


def _both(loopback: Loopback, config: str, index: int, **kw: Any) -> BusRun:
    """A catalogue trial over the bus, checked against the in-process run."""
    trial = make_trial(config, index)
    ep = {"instruction": trial.instruction, "events": trial.events, "seed": trial.seed}
    local = run_episode(trial.scene, **ep)
    run = loopback.run(trial.scene, **ep, **kw)
    same_as_local(local, run)
    assert run.node.stats.malformed == 0  # (every basis and briefing the node could read)
    return run


@MODES
@pytest.mark.parametrize(("config", "index"), [("4-2", 1), ("4-4-square", 0)])
def test_the_node_foresees_replans_after_walks(
    loopback: Loopback, monkeypatch: pytest.MonkeyPatch, config: str, index: int, inline: bool
) -> None:
    """Catalogue cells where people walk between workspaces, so the plan's next step (the
    hint) is stale when a step ends: the node plans the executor's next step itself from its
    basis on the world it simulated, the executor takes it without a query, and the log is the
    in-process one."""
    patient_foresight(monkeypatch)
    if inline:
        guesses_in_the_answer(monkeypatch)
    run = _both(loopback, config, index)
    if inline:
        stats = run.node.stats
        assert 0 < stats.foreseen_kept <= stats.foreseen
        assert stats.foreseen_kept <= stats.guesses_kept


@MODES
@pytest.mark.parametrize(("config", "index"), [("4-2", 1), ("4-4-square", 0)])
def test_a_wrong_foresight_never_shows(
    loopback: Loopback, monkeypatch: pytest.MonkeyPatch, config: str, index: int, inline: bool
) -> None:
    """Every step the node foresees is wrong (each action twice: the second start fails at
    once): it is undone, no start of it is counted, and the log is the in-process one."""
    patient_foresight(monkeypatch)
    if inline:
        guesses_in_the_answer(monkeypatch)
    wrong_foresight(monkeypatch)
    run = _both(loopback, config, index)
    stats = run.node.stats
    assert stats.foreseen_kept == 0
    if inline:
        assert stats.foreseen > 0 and stats.undone > 0


def test_no_foresight_without_the_basis(loopback: Loopback) -> None:
    """With hints off the executor sends no basis either: the node guesses nothing."""
    run = _both(loopback, "4-2", 1, guess=False)
    assert run.node.stats.guessed == run.node.stats.foreseen == 0


@MODES
@pytest.mark.parametrize("held_on", [True, False], ids=["held-on", "dropped"])
def test_a_step_held_back_past_its_stretch_is_held_on(
    loopback: Loopback, monkeypatch: pytest.MonkeyPatch, inline: bool, held_on: bool
) -> None:
    """1-1 #0: the executor holds its hand-over to A back while A walks (an intrusion risk)
    longer than the node's stretch lasts, and starts it once A has stopped, at a time off the
    tick grid. The node held the step in that stretch; the next one (the executor's plain
    step query while it waits) holds it on, so the start is the node's guess and costs no
    query. Dropped (as before session 18), the start is a guess missed: its commands go in a
    query. The log is the in-process one either way. (A stretch that has used up its span
    while the node holds a step runs on into the next since session 20, where it holds the
    step anyway: here every stretch ends at its span, as before.)"""
    patient_foresight(monkeypatch)
    monkeypatch.setattr(node_module.CellNode, "_spans_on", staticmethod(lambda ep, s: False))
    if inline:
        guesses_in_the_answer(monkeypatch)
    if not held_on:
        monkeypatch.setattr(node_module.CellNode, "_still_held", lambda self, ep, s: None)
    run = _both(loopback, "1-1", 0, first=True)  # (the first step's commands in no query)
    late = [
        r
        for r in run.episode.records
        if r.type == "action_start"
        and r.action["skill"] == "handover_r2h"
        and abs(round(r.t / 0.05) * 0.05 - r.t) > 1e-6
    ]
    assert late  # (the hand-over started at A's stop, off the tick grid)
    assert (run.cell.stats.commands == 0) is held_on  # (commands in a query: a guess missed)


def test_a_step_held_back_past_its_span_is_held_in_the_stretch(
    loopback: Loopback, monkeypatch: pytest.MonkeyPatch
) -> None:
    """1-1 #0 as above, the next stretch not taking the held step over (``_still_held``
    dropped): the stretch that holds the step runs on past its span (session 20), so the
    start at A's stop is still the node's guess, with no query of its commands; the log is
    the in-process one."""
    patient_foresight(monkeypatch)
    monkeypatch.setattr(node_module.CellNode, "_still_held", lambda self, ep, s: None)
    run = _both(loopback, "1-1", 0, first=True)  # (the first step's commands in no query)
    assert run.node.stats.spans > 0
    assert run.cell.stats.commands == 0


@MODES
def test_the_first_step_is_foreseen(
    loopback: Loopback, monkeypatch: pytest.MonkeyPatch, inline: bool
) -> None:
    """The executor sends its first basis as soon as it has grounded the instruction; the node
    plans the first step on the first world and starts it on a guess, and the executor's first
    commands are taken from there, without a query (the executor waits for that answer
    whenever it asked for it, so this holds however the two are scheduled)."""
    patient_foresight(monkeypatch)
    if inline:
        guesses_in_the_answer(monkeypatch)
    run = _both(loopback, "4-1", 0, first=True)
    first = next(r for r in run.episode.records if r.type == "dispatch")
    assert run.node.stats.foreseen_kept >= 1
    assert run.cell.stats.guessed >= len(first.actions)
    # the node grounded the instruction itself from the executor's briefing, and the
    # executor's first spec was the one it grounded
    assert run.node.stats.briefed == 1 and run.node.stats.respecs == 0


@MODES
@pytest.mark.parametrize("grounder", [None, "offline"], ids=["briefed", "own-grounder"])
def test_the_first_step_is_asked_about_without_first(
    loopback: Loopback, monkeypatch: pytest.MonkeyPatch, inline: bool, grounder: str | None
) -> None:
    """With ``first=False`` (the default since the end of session 28) the node plans no first
    step: the briefing (or, with a grounder of the executor's own, the first basis) goes at once
    and is only taken in, the executor's first commands go in a query, every action is started
    once, and the log is the in-process one. With ``first`` the node plans a step on the first
    world (the spy sees it)."""
    patient_foresight(monkeypatch)
    if inline:
        guesses_in_the_answer(monkeypatch)
    planned_at: list[float] = []
    real = node_module.CellNode._foreseen

    def foreseen(self: Any, s: Any, world: Any) -> Any:
        planned_at.append(s.t)
        return real(self, s, world)

    monkeypatch.setattr(node_module.CellNode, "_foreseen", foreseen)
    kw = {} if grounder is None else {"grounder": make_grounder(grounder)}
    for first in (False, True):
        planned_at.clear()
        run = _both(loopback, "4-1", 0, first=first, **kw)
        dispatch = next(r for r in run.episode.records if r.type == "dispatch")
        assert (0.0 in planned_at) is first
        if not first:  # (with it, the first commands go in no query; later ones may)
            assert run.cell.stats.commands >= len(dispatch.actions)
        assert set(run.node.stats.starts.values()) == {1}
        assert run.node.stats.respecs == 0
        if first:  # (without it nothing waits for the briefing: it may come after the commands)
            assert run.node.stats.briefed == (grounder is None)
        else:
            assert run.node.stats.briefed <= (grounder is None)
        assert run.node.stats.specs >= 1  # (the first spec, taken in before the first step)


def test_no_briefing_without_the_offline_grounder(
    loopback: Loopback, monkeypatch: pytest.MonkeyPatch
) -> None:
    """An episode given its spec, or grounded with a grounder of its own, sends no briefing:
    the first step is foreseen from the executor's first basis (``first``), as before."""
    patient_foresight(monkeypatch)
    trial = make_trial("4-1", 0)
    ep = {"instruction": trial.instruction, "events": trial.events, "seed": trial.seed}
    local = run_episode(trial.scene, **ep)
    run = loopback.run(trial.scene, **ep, grounder=make_grounder("offline"), first=True)
    same_as_local(local, run)
    assert run.node.stats.briefed == 0 and run.node.stats.foreseen_kept >= 1
    spec = next(r for r in local.records if r.type == "grounding").spec
    given = {"spec": spec_from_dict(spec), "events": trial.events, "seed": trial.seed}
    local = run_episode(trial.scene, **given)
    run = loopback.run(trial.scene, **given, first=True)
    same_as_local(local, run)
    assert run.node.stats.briefed == 0 and run.node.stats.foreseen_kept >= 1


@pytest.mark.parametrize("first", [True, False], ids=["first-foreseen", "first-asked"])
def test_a_wrong_briefing_never_shows(
    loopback: Loopback, monkeypatch: pytest.MonkeyPatch, first: bool
) -> None:
    """The node grounds the briefing to another spec than the executor's (here: another
    trial's instruction): its first guess, if it makes one (``first``), is wrong and undone,
    the executor's own basis replaces the node's spec, and the log is the in-process one."""
    patient_foresight(monkeypatch)
    guesses_in_the_answer(monkeypatch)
    other = make_trial("4-2", 1).instruction
    real = node_module.ground_instruction
    monkeypatch.setattr(node_module, "ground_instruction", lambda g, _text, *a: real(g, other, *a))
    run = _both(loopback, "4-1", 0, first=first)
    if first:
        assert run.node.stats.briefed == 1 and run.node.stats.respecs == 1
    else:  # (nothing waits for the briefing: one the node takes up after the first commands
        # is dropped, as the executor's own basis has come)
        assert run.node.stats.respecs == run.node.stats.briefed


def test_a_malformed_briefing_is_dropped(
    loopback: Loopback, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A briefing the node cannot read is counted and dropped; the episode goes on (its first
    commands asked about), the log the in-process one."""
    monkeypatch.setattr(WireBriefing, "to_dict", lambda self: {"instruction": 3})
    trial = make_trial("4-1", 0)
    ep = {"instruction": trial.instruction, "events": trial.events, "seed": trial.seed}
    local = run_episode(trial.scene, **ep)
    run = loopback.run(trial.scene, **ep)
    same_as_local(local, run)
    assert run.node.stats.malformed == 1 and run.node.stats.briefed == 0


@MODES
@pytest.mark.parametrize(("config", "index"), [("2-2", 0), ("4-4-line", 1)])
def test_a_new_request_sends_its_basis(
    loopback: Loopback, monkeypatch: pytest.MonkeyPatch, config: str, index: int, inline: bool
) -> None:
    """A second request mid-episode: the executor sends the new spec's basis at once, the node
    takes it in (streamed, it waits for it before it foresees the step after the one the
    request came in; whether it comes in time is a matter of timing), and the log is the
    in-process one."""
    patient_foresight(monkeypatch)
    if inline:
        guesses_in_the_answer(monkeypatch)
    run = _both(loopback, config, index)
    specs = [r for r in run.episode.records if r.type == "grounding" and r.spec is not None]
    assert len(specs) == 2
    assert run.node.stats.specs == len(specs)
    # the node grounded the request itself as it simulated it (the executor briefed it: the
    # offline grounder), the same spec the executor grounded later
    assert run.node.stats.respecs == 0
    if inline:  # (once in each context it simulated the request's tick in: see below)
        assert run.node.stats.grounded >= 1


def test_a_request_simulated_again_is_grounded_once(
    loopback: Loopback, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The node simulates a request's tick ahead (grounding it), the executor uses none of
    those ticks (here: it drops the node's foresight of its first step, as when the answer
    comes too late on a loaded machine), and the node simulates the tick again: it never
    grounds the same instructions against the same spec and formulas done twice (the first
    grounding is kept), its spec is the executor's, and the log is the in-process one."""
    patient_foresight(monkeypatch)
    guesses_in_the_answer(monkeypatch)
    monkeypatch.setattr(BusCell, "_take_first", lambda self: setattr(self, "_first", None))
    contexts: list[tuple[tuple[str, ...], Any, frozenset[str]]] = []
    real = node_module.ground_all

    def ground_all(g: Any, texts: list[str], scene: Any, spec: Any, done: Any = ()) -> Any:
        contexts.append((tuple(texts), spec, frozenset(done)))
        return real(g, texts, scene, spec, done)

    monkeypatch.setattr(node_module, "ground_all", ground_all)
    run = _both(loopback, "4-4-line", 1, first=True)
    assert run.node.stats.undone > 0  # (the first stretch, the request's tick in it)
    assert contexts and run.node.stats.grounded == len(contexts)
    assert all(
        a[0] != b[0] or a[1] is not b[1] or a[2] != b[2] for a, b in combinations(contexts, 2)
    )
    assert run.node.stats.respecs == 0


@MODES
def test_a_request_grounded_wrong_ahead_never_shows(
    loopback: Loopback, monkeypatch: pytest.MonkeyPatch, inline: bool
) -> None:
    """The node grounds a second request to another spec than the executor will (here: it
    hears another sentence): its guesses after it are wrong and undone, the executor's spec
    replaces the node's, and the log is the in-process one."""
    patient_foresight(monkeypatch)
    if inline:
        guesses_in_the_answer(monkeypatch)
    real = node_module.ground_all
    other = ["Also give Person B the cup."]
    monkeypatch.setattr(node_module, "ground_all", lambda g, _texts, *a: real(g, other, *a))
    run = _both(loopback, "2-2", 0)
    if inline:
        assert run.node.stats.grounded == 1 and run.node.stats.respecs == 1


class _FirstOnly:
    """The offline grounder for the episode's first instruction; every later one fails."""

    def __init__(self) -> None:
        self.inner, self.calls = make_grounder("offline"), 0

    def ground(self, instruction: str, scene: Any, running: Any = None) -> Any:
        self.calls += 1
        if self.calls > 1:
            raise GroundingError("not understood (a test's grounder)")
        return self.inner.ground(instruction, scene, running)


def test_no_wait_for_a_basis_that_is_not_coming(
    loopback: Loopback, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A second request the executor cannot ground makes no new spec, so no basis follows the
    step it came in, which the node waits for before it foresees the next one: the executor,
    told so (``"awaits"``), does not wait for that step but asks (counted: the node cannot
    have answered, it waits), and the node's wait ends with the question, not its time limit
    (made 30 s here). The log is the in-process one."""
    patient_foresight(monkeypatch)
    monkeypatch.setattr(node_module, "FORESEE_WAIT", 30.0)
    trial = make_trial("2-2", 0)
    ep = {"instruction": trial.instruction, "events": trial.events, "seed": trial.seed}
    local = run_episode(trial.scene, grounder=_FirstOnly(), **ep)
    failed = [r for r in local.records if r.type == "grounding" and r.spec is None]
    assert len(failed) == 1
    run = loopback.run(trial.scene, grounder=_FirstOnly(), first=True, **ep)
    same_as_local(local, run)
    assert run.node.stats.waited_out == 0 and run.cell.stats.unawaited == 1


def test_a_context_change_while_the_executor_waits_is_foreseen(
    loopback: Loopback, monkeypatch: pytest.MonkeyPatch
) -> None:
    """4-2 #0: the executor's hand-over is held back (an intrusion risk), then it finds no
    plan in the world A walks into and waits; when A walks on, it takes over the plan it
    predicted for that context and starts it. The node, nothing running, plans the next step
    itself at that context change (and simulates on where it finds no plan, as the executor
    waits): the start is its guess, with no query of its commands. Simulating on there (as
    before session 20), the start was a guess missed; the log is the in-process one either
    way."""
    patient_foresight(monkeypatch)  # (what is counted must not depend on the machine's load)
    run = _both(loopback, "4-2", 0, first=True)  # (the first step's commands in no query)
    assert [r.trigger for r in run.episode.records if r.type == "takeover"]
    assert run.cell.stats.commands == 0
    monkeypatch.setattr(node_module.CellNode, "_replans_idle", lambda self, s, w, steady: False)
    before = _both(loopback, "4-2", 0, first=True)
    assert before.cell.stats.commands > 0
