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
    elif UPDATES[text] is not None and ep.success:
        assert UPDATES[text] in delivered, (t, text, delivered)
    elif UPDATES[text] is not None:
        # accepted while the action it undoes was already under way (the bottle is in A's
        # hands at 1.0 s): the episode fails, saying that no plan exists any more
        assert "no plan" in ep.metrics.reason, ep.metrics.reason
    if t > 1.0 and text != "also give Person B the chips" and "after that" not in text:
        # the bottle was handed over already: replacing or cancelling it is refused
        assert refused, (t, text)
