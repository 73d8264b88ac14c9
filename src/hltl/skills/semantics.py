"""What one action means, in one place: its transition or why it is infeasible, and apply."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Literal

from hltl.skills.cost import CostModel, cost_model_for
from hltl.skills.kinematics import REACH_SPHERES, Kinematics
from hltl.skills.library import DEFAULT_SKILLS, Action, Situation, Skill, Transition, ground
from hltl.world.geometry import Context
from hltl.world.scene import Scene, Vec3
from hltl.world.state import Loc, ObjectStatus, WorldState

InfeasibleKind = Literal["kinematic", "conflict"]


@dataclass(frozen=True, slots=True)
class Infeasible:
    """Why Pre(s, ℓ, a) fails.

    ``kinematic``: no instance of the skill exists for these robots and arguments where things
    are now (out of reach, person outside the workspace, robots that cannot meet or whose
    rendezvous a person blocks, a robot that is down). ``conflict``: the instance exists but the
    state forbids it (the object is held by another robot or gone, a robot that must be free
    holds something).
    """

    action: Action
    kind: InfeasibleKind
    reason: str


@dataclass(frozen=True, slots=True)
class ActionSemantics:
    """The meaning of actions in one scene: which exist, what they do, how long they take.

    Attributes:
        scene: the cell.
        cost: d(s, a).
        skills: the skill library J.
        kinematics: reach and poses (default: the paper's reach spheres).
    """

    scene: Scene
    cost: CostModel
    skills: tuple[Skill, ...] = DEFAULT_SKILLS
    kinematics: Kinematics = REACH_SPHERES

    @classmethod
    def of(
        cls,
        scene: Scene,
        *,
        cost: CostModel | None = None,
        skills: Sequence[Skill] = DEFAULT_SKILLS,
        kinematics: Kinematics | None = None,
    ) -> ActionSemantics:
        """The semantics of ``scene`` with its own cost model unless another is given."""
        return cls(
            scene,
            cost_model_for(scene) if cost is None else cost,
            tuple(skills),
            REACH_SPHERES if kinematics is None else kinematics,
        )

    def situation(self, world: WorldState) -> Situation:
        return Situation.of(self.scene, world, self.kinematics)

    def context(self, world: WorldState) -> Context:
        """ℓ(w) by these kinematics (reachability maps when the scene's arms have models; the
        reach spheres of ``WorldState.context`` otherwise): the label the planner plans under."""
        return self.kinematics.context_label(self.scene, world.humans)

    def instances(self, world: WorldState) -> tuple[tuple[Action, Transition], ...]:
        """Every ground instance whose situation-dependent precondition holds in ``world``."""
        return ground(self.situation(world), self.skills)

    def transition(self, action: Action, world: WorldState) -> Transition | Infeasible:
        """Post(s, a) when Pre(s, ℓ, a) holds in ``world``, else the reason it does not."""
        sit = self.situation(world)
        skill = next((s for s in self.skills if s.name == action.skill), None)
        matches = [] if skill is None else list(skill.candidates(action, sit))
        if not matches:
            return Infeasible(action, "kinematic", _why_not_grounded(action, sit))
        loc = dict(world.objects)[action.object].loc
        trans = [t for t in matches if t.pre == loc]
        if not trans:
            if action.skill == "pick" and loc.kind in ("rest", "on"):
                where = _where(sit, action.object, loc)
                return Infeasible(
                    action,
                    "kinematic",
                    f"{action}: {action.object} {where} is out of reach of {action.robots[0]}",
                )
            need = " or ".join(sorted({str(t.pre) for t in matches}))
            return Infeasible(
                action, "conflict", f"{action}: {action.object} is {loc}; the skill needs it {need}"
            )
        for rid in trans[0].free:
            held = world.holding(rid)
            if held is not None:
                return Infeasible(action, "conflict", f"{action}: {rid} is not free (holds {held})")
        return trans[0]

    def check(self, action: Action, world: WorldState) -> str | None:
        """Pre(s, ℓ, a) under ``world``: ``None`` when it holds, else the reason it fails."""
        tr = self.transition(action, world)
        return tr.reason if isinstance(tr, Infeasible) else None

    def duration(self, action: Action, transition: Transition, hands: Mapping[str, Vec3]) -> float:
        """d(s, a) when each executor's hand starts at ``hands[robot]``."""
        return self.cost.duration(action, transition, hands)


def apply(world: WorldState, transition: Transition) -> WorldState:
    """The world after ``transition``: the object at its new place (in the last hand), the
    executors' hands at the poses the instance used."""
    if transition.hands:
        position = transition.hands[-1][1]
    else:
        position = world.object_status(transition.obj).position
    w = world.with_object(transition.obj, ObjectStatus(position, transition.post))
    for rid, pos in transition.hands:
        w = w.with_hand(rid, pos)
    return w


def apply_all(world: WorldState, transitions: Sequence[Transition]) -> WorldState:
    """The world after a step's transitions (they touch distinct objects and robots)."""
    for tr in transitions:
        world = apply(world, tr)
    return world


def transition(action: Action, scene: Scene, world: WorldState) -> Transition | Infeasible:
    """:meth:`ActionSemantics.transition` with the default library, kinematics and costs."""
    return ActionSemantics.of(scene).transition(action, world)


def check_action(action: Action, scene: Scene, world: WorldState) -> str | None:
    """Pre(s, ℓ, a) under the latest world: ``None`` when it holds, else the reason it fails."""
    return ActionSemantics.of(scene).check(action, world)


def _where(sit: Situation, oid: str, loc: Loc) -> str:
    if loc.kind == "on":
        return f"on {loc.ref}"
    x, y, z = sit.rest_position(oid)
    return f"at ({x:.2f}, {y:.2f}, {z:.2f})"


def _why_not_grounded(action: Action, sit: Situation) -> str:
    avail = {r.id for r in sit.available}
    down = [r for r in action.robots if r not in avail]
    if down:
        return f"{action}: robot {', '.join(down)} is unavailable"
    if action.skill == "handover_r2h" and action.human is not None:
        serving = sorted(sit.context.robots_serving(action.human))
        return (
            f"{action}: {action.human} is not inside {action.robots[0]}'s workspace "
            f"(served by: {', '.join(serving) or 'no robot'})"
        )
    if action.skill == "handover_r2r" and len(action.robots) == 2:
        g, r = action.robots
        if sit.context.blocked(g, r):
            return f"{action}: a person stands inside both {g}'s and {r}'s workspaces"
        return f"{action}: {g} and {r} cannot meet"
    return f"{action}: out of reach or not a skill of the library"
