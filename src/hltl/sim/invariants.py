"""Invariants every execution log must satisfy, re-checked from the log alone."""

from __future__ import annotations

from collections import Counter
from collections.abc import Sequence

from hltl.errors import BackendUnavailableError
from hltl.execution.log import (
    ActionDone,
    ActionFailed,
    ActionHalted,
    ActionStart,
    Dispatch,
    EpisodeEnd,
    EpisodeStart,
    LogRecord,
    Monitor,
    world_from_dict,
)
from hltl.execution.safety import step_conflict
from hltl.skills.kinematics import REACH_SPHERES, Kinematics
from hltl.skills.library import Action
from hltl.skills.semantics import ActionSemantics
from hltl.world.scene import Scene, scene_from_dict


def check_invariants(
    records: Sequence[LogRecord], kinematics: Kinematics | None = None
) -> list[str]:
    """Problems found in a log (empty when it is sound):

    * every dispatched action's precondition holds in the world recorded with the dispatch
      (the executor's latest world), and the actions of a dispatch share no robot or object;
    * no robot starts an action while another of its actions is running;
    * no object is delivered more than once;
    * an episode that ends in success has a monitor record that accepted.

    Preconditions are judged with the reach the agent used: ``kinematics`` when given, else
    the one ``episode_start`` names (:func:`log_kinematics`).

    Raises:
        BackendUnavailableError: the log names reachability maps and the motion extra is not
            installed.
    """
    if not records or not isinstance(records[0], EpisodeStart):
        return ["the log does not start with episode_start"]
    scene = scene_from_dict(records[0].scene, source="<log scene>")
    if kinematics is None:
        kin = log_kinematics(records[0], scene)
        if isinstance(kin, str):
            return [kin]
    else:
        kin = kinematics
    semantics = ActionSemantics.of(scene, kinematics=kin)
    problems: list[str] = []
    busy: dict[str, int] = {}
    delivered: Counter[str] = Counter()
    accepted = False
    for rec in records:
        t = rec.t
        if isinstance(rec, Dispatch):
            world = world_from_dict(rec.world)
            actions = [Action.from_dict(a) for a in rec.actions]
            conflict = step_conflict(actions)
            if conflict is not None:
                problems.append(f"t={t}: dispatch shares a robot or object: {conflict}")
            for a in actions:
                reason = semantics.check(a, world)
                if reason is not None:
                    problems.append(f"t={t}: dispatched {a} with a false precondition: {reason}")
        elif isinstance(rec, ActionStart):
            handle = int(rec.handle)
            for r in rec.action["robots"]:
                if r in busy:
                    problems.append(
                        f"t={t}: robot {r} started action {handle} while action {busy[r]} runs"
                    )
                busy[r] = handle
        elif isinstance(rec, ActionDone | ActionFailed | ActionHalted):
            handle = int(rec.handle)
            for r in list(busy):
                if busy[r] == handle:
                    del busy[r]
            done = rec.action
            if isinstance(rec, ActionDone) and done.get("skill") == "handover_r2h":
                delivered[str(done["object"])] += 1
                if delivered[str(done["object"])] == 2:
                    problems.append(f"t={t}: {done['object']} delivered more than once")
        elif isinstance(rec, Monitor) and rec.accepted:
            accepted = True
        elif isinstance(rec, EpisodeEnd) and rec.success and not accepted:
            problems.append(f"t={t}: the episode claims success but no monitor accepted")
    return problems


def log_kinematics(start: EpisodeStart, scene: Scene) -> Kinematics | str:
    """The kinematics ``start`` names: the reach spheres (no name), or the reachability maps of
    the scene's arms (``maps``, each model's cached map as ``MapKinematics`` loads it); a
    problem (a string) for any other name.

    Raises:
        BackendUnavailableError: ``maps`` without the motion extra.
    """
    name = start.kinematics
    if name is None or name == "spheres":
        return REACH_SPHERES
    if name != "maps":
        return (
            f"episode_start names unknown kinematics {str(name)[:40]!r}; expected spheres or maps"
        )
    try:
        # why: the motion extra (numpy, the maps) is needed only for a log run with the maps
        from hltl.motion.workspace import MapKinematics
    except ImportError as exc:
        raise BackendUnavailableError(
            f"the log was run with reachability maps; checking it needs the motion extra "
            f"(pip install 'hltl[motion]'): {exc}"
        ) from exc
    return MapKinematics(scene)
