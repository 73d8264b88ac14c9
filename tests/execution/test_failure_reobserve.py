"""After a failed action the executor waits for a fresh observation before it replans.

Regression: an observation taken in during the same tick as the failure (read before the
failure was known) used to count as fresh, so the executor replanned on its stale belief that
the robot still held a dropped object and dispatched a handover of it.
"""

from __future__ import annotations

from pathlib import Path

from hltl.sim.episode import run_episode
from hltl.sim.events import events_from_dict
from hltl.sim.invariants import check_invariants
from hltl.world.scene import load_scene

EVENTS = {
    "events": [
        {"t": 0.2, "type": "robot_down", "robot": "r1", "duration": 1.0},
        {"type": "skill_failure", "skill": "handover_r2h", "probability": 0.5, "outcome": "drop"},
    ]
}


def test_no_dispatch_on_a_stale_belief_after_a_drop(two_arms_path: Path) -> None:
    scene = load_scene(two_arms_path)
    ep = run_episode(
        scene,
        instruction="Give Person A the bottle and Person B the chips",
        events=events_from_dict(EVENTS, scene),
        seed=6,
    )
    assert check_invariants(ep.records) == []
    drops = [r for r in ep.records if r.type == "object_drop"]
    assert drops, "the seed must produce a dropped object for this test to mean anything"
    halts = [r for r in ep.records if r.type == "halt"]
    assert not any("the skill needs it held" in str(r.reason) for r in halts)
    # after each failure the next dispatch of that object starts by picking it up again
    for i, rec in enumerate(ep.records):
        if rec.type == "action_failed" and rec.action["skill"] == "handover_r2h":
            obj = rec.action["object"]
            nxt = next(
                r
                for r in ep.records[i + 1 :]
                if r.type == "action_start" and r.action["object"] == obj
            )
            assert nxt.action["skill"] == "pick"
