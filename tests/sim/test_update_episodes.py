"""Updates said while a task is pending, running or finished, in closed-loop episodes (issue 18).

An update is either refused (a ``grounding`` record with the reason) or carried out: whatever it
adds is delivered before the episode reports success. Never accepted and dropped.
"""

from __future__ import annotations

import itertools
from pathlib import Path
from typing import Any

import pytest

from hltl.sim.episode import run_episode
from hltl.sim.events import EventSchedule, Instruction
from hltl.sim.invariants import check_invariants
from hltl.world.scene import load_scene

# "Give Person A the bottle": r1 picks (0-0.5 s), hands it over (0.5-1.0 s), then it is done
TIMES = (0.2, 0.7, 1.5)
UPDATES = {
    "give Person A the chips instead": ("chips", "A"),
    "give Person B the bottle instead": ("bottle", "B"),
    "also give Person B the chips": ("chips", "B"),
    "after that give Person B the chips": ("chips", "B"),
    "cancel the bottle": None,
}


def _delivered(records: list[dict[str, Any]]) -> set[tuple[str, str]]:
    return {
        (r.action["object"], r.action["human"])
        for r in records
        if r.type == "action_done" and r.action["skill"] == "handover_r2h"
    }


@pytest.mark.parametrize(("t", "text"), list(itertools.product(TIMES, UPDATES)))
def test_an_update_is_refused_or_carried_out(two_arms_path: Path, t: float, text: str) -> None:
    two_arms = load_scene(two_arms_path)
    events = EventSchedule((Instruction(t, text),))
    ep = run_episode(two_arms, instruction="Give Person A the bottle", events=events)
    records = list(ep.records)
    grounding = [r for r in records if r.type == "grounding" and r.text == text]
    assert len(grounding) == 1
    refused = grounding[0].error is not None
    delivered = _delivered(records)
    if refused:
        assert grounding[0].error
    elif UPDATES[text] is not None:
        # accepted, even while the action it undoes is under way: carried out
        assert ep.success, (t, text, ep.metrics.reason)
        assert UPDATES[text] in delivered, (t, text, delivered)
    if t > 1.0 and text != "also give Person B the chips" and "after that" not in text:
        # the bottle was handed over already: replacing or cancelling it is refused
        assert refused, (t, text)


def test_an_update_halts_the_running_action_it_undoes(two_arms_path: Path) -> None:
    # r1 hands the bottle to A (0.5-1.0 s) when B is asked for instead: finishing the hand-over
    # would leave no plan (A would hold it), so it is halted, the bottle stays in r1's hand and
    # goes to B; it used to end in "no plan" after 10 s of waiting
    two_arms = load_scene(two_arms_path)
    text = "give Person B the bottle instead"
    ep = run_episode(
        two_arms,
        instruction="Give Person A the bottle",
        events=EventSchedule((Instruction(0.7, text),)),
    )
    records = list(ep.records)
    (halt,) = [r for r in records if r.type == "halt"]
    assert (halt.t, halt.kind) == (0.7, "update")
    assert halt.actions == [
        {"skill": "handover_r2h", "robots": ["r1"], "object": "bottle", "human": "A"}
    ]
    assert ep.success and _delivered(records) == {("bottle", "B")}
    assert ep.metrics.violations == 0
    assert check_invariants(records) == []


def test_an_update_halts_nothing_that_still_leaves_a_plan(two_arms_path: Path) -> None:
    # "also" adds a task: the running hand-over to A is still wanted and runs on
    two_arms = load_scene(two_arms_path)
    ep = run_episode(
        two_arms,
        instruction="Give Person A the bottle",
        events=EventSchedule((Instruction(0.7, "also give Person B the chips"),)),
    )
    records = list(ep.records)
    assert not [r for r in records if r.type in ("halt", "action_halted")]
    assert ep.success and _delivered(records) == {("bottle", "A"), ("chips", "B")}
