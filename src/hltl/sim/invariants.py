"""Invariants every execution log must satisfy, re-checked from the log alone."""

from __future__ import annotations

from collections import Counter
from collections.abc import Mapping, Sequence
from typing import Any

from hltl.execution.log import world_from_dict
from hltl.execution.safety import step_conflict
from hltl.skills.library import Action
from hltl.skills.semantics import check_action
from hltl.world.scene import scene_from_dict

_END_TYPES = ("action_done", "action_failed", "action_halted")


def check_invariants(records: Sequence[Mapping[str, Any]]) -> list[str]:
    """Problems found in a log (empty when it is sound):

    * every dispatched action's precondition holds in the world recorded with the dispatch
      (the executor's latest world), and the actions of a dispatch share no robot or object;
    * no robot starts an action while another of its actions is running;
    * no object is delivered more than once;
    * an episode that ends in success has a monitor record that accepted.
    """
    if not records or records[0].get("type") != "episode_start":
        return ["the log does not start with episode_start"]
    scene = scene_from_dict(records[0]["scene"], source="<log scene>")
    problems: list[str] = []
    busy: dict[str, int] = {}
    delivered: Counter[str] = Counter()
    accepted = False
    for rec in records:
        kind, t = rec["type"], rec["t"]
        if kind == "dispatch":
            world = world_from_dict(rec["world"])
            actions = [Action.from_dict(a) for a in rec["actions"]]
            conflict = step_conflict(actions)
            if conflict is not None:
                problems.append(f"t={t}: dispatch shares a robot or object: {conflict}")
            for a in actions:
                reason = check_action(a, scene, world)
                if reason is not None:
                    problems.append(f"t={t}: dispatched {a} with a false precondition: {reason}")
        elif kind == "action_start":
            handle = int(rec["handle"])
            for r in rec["action"]["robots"]:
                if r in busy:
                    problems.append(
                        f"t={t}: robot {r} started action {handle} while action {busy[r]} runs"
                    )
                busy[r] = handle
        elif kind in _END_TYPES:
            handle = int(rec["handle"])
            for r in list(busy):
                if busy[r] == handle:
                    del busy[r]
            a = rec["action"]
            if kind == "action_done" and a.get("skill") == "handover_r2h":
                delivered[str(a["object"])] += 1
                if delivered[str(a["object"])] == 2:
                    problems.append(f"t={t}: {a['object']} delivered more than once")
        elif kind == "monitor" and rec.get("accepted"):
            accepted = True
        elif kind == "episode_end" and rec.get("success") and not accepted:
            problems.append(f"t={t}: the episode claims success but no monitor accepted")
    return problems
