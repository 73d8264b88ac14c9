"""Reactive safety (paper §III-D): kinematic infeasibility and intrusion risk of actions."""

from __future__ import annotations

from collections.abc import Collection, Mapping, Sequence
from dataclasses import dataclass
from typing import Literal

from hltl.execution.predict import TrajectoryPredictor, horizon_times
from hltl.skills.library import Action, Transition
from hltl.skills.semantics import ActionSemantics
from hltl.world.geometry import distance
from hltl.world.scene import Scene, Vec3
from hltl.world.state import WorldState

HazardKind = Literal["precondition", "intrusion"]

# An object farther than this from where a grasp was aimed is no longer where the fingers close
# (the simulator counts such a pick as a violation; the executor halts it before that).
GRASP_TOLERANCE = 0.05


@dataclass(frozen=True, slots=True)
class Hazard:
    """Why an action must not run (on): its precondition fails now, or is forecast to fail."""

    action: Action
    kind: HazardKind
    reason: str


def step_conflict(actions: Sequence[Action]) -> str | None:
    """Why a set of actions cannot form one step (shared robot or object), or None."""
    robots: dict[str, Action] = {}
    objects: dict[str, Action] = {}
    for a in actions:
        for r in a.robots:
            if r in robots:
                return f"{a} and {robots[r]} both need robot {r}"
            robots[r] = a
        if a.object in objects:
            return f"{a} and {objects[a.object]} both need object {a.object}"
        objects[a.object] = a
    return None


def precondition_hazard(
    action: Action,
    scene: Scene,
    world: WorldState,
    *,
    semantics: ActionSemantics | None = None,
) -> Hazard | None:
    """(i) Kinematic infeasibility: Pre(s, ℓ, a) fails under the latest world."""
    sem = ActionSemantics.of(scene) if semantics is None else semantics
    reason = sem.check(action, world)
    return None if reason is None else Hazard(action, "precondition", reason)


def grasp_hazard(action: Action, aimed_at: Vec3, world: WorldState) -> Hazard | None:
    """A dispatched pick whose object has moved from where the grasp was aimed.

    The pick's precondition (object in reach, not held) may still hold at the new place, but the
    motion under way goes to the old one: any change of the grasp target halts and replans.
    """
    now = world.object_status(action.object).position
    moved = distance(now, aimed_at)
    if moved <= GRASP_TOLERANCE:
        return None
    where = ", ".join(f"{v:.2f}" for v in now)
    return Hazard(
        action,
        "precondition",
        f"{action}: {action.object} moved {moved:.2f} m from where the grasp was aimed "
        f"(now at [{where}]); the grasp target changed",
    )


def hand_speed(transition: Transition, hands: Mapping[str, Vec3], duration: float) -> float:
    """Mean speed (m/s) of the fastest executor's hand over the action."""
    if duration <= 0:
        return 0.0
    travel = 0.0
    for rid, target in transition.hands:
        start = hands.get(rid, target)
        travel = max(travel, distance(start, target))
    return travel / duration


def intrusion_hazard(
    action: Action,
    scene: Scene,
    world: WorldState,
    predictor: TrajectoryPredictor,
    t: float,
    until: float,
    dt: float,
    humans: Collection[str] | None = None,
    *,
    semantics: ActionSemantics | None = None,
) -> Hazard | None:
    """(ii) Intrusion risk: a forecast person breaks the action's precondition before it ends.

    The people the forecast moves are placed at their forecast positions at each sample time in
    (t, until]; the first time the context changes in a way that makes Pre(a) false is reported.
    Only the context ℓ depends on people, so samples with the current context are skipped.

    Args:
        humans: people to forecast (default: those the predictor sees moving).
        semantics: the action semantics (default: the scene's with reach spheres).
    """
    if until <= t:
        return None
    movers = [
        h for h, _ in world.humans if (h in humans if humans is not None else predictor.moving(h))
    ]
    if not movers:
        return None
    times = horizon_times(t, until - t, dt)
    tracks = {h: predictor.predict(h, times) for h in movers}
    sem = ActionSemantics.of(scene) if semantics is None else semantics
    current = sem.context(world)
    for k, tau in enumerate(times):
        w = world
        for h in movers:
            w = w.with_human(h, tracks[h][k])
        if sem.context(w) == current:
            continue
        reason = sem.check(action, w)
        if reason is not None:
            return Hazard(action, "intrusion", f"{reason} (forecast for t={tau:.2f})")
    return None
