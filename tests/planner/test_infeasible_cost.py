"""A cost model's INFEASIBLE (math.inf: no motion from these hands) removes the step from the
search, and the executor and the discrete simulator never run such an action."""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path

from hltl.execution.drivers import ActionState
from hltl.planner import PlanStatus, plan
from hltl.sim.simulator import Simulator
from hltl.skills.cost import INFEASIBLE, AnalyticCostModel
from hltl.skills.library import Action, Transition
from hltl.spec.hierarchy import load_spec
from hltl.world.scene import Scene, Vec3, load_scene

ROOT = Path(__file__).resolve().parents[2]


@dataclass(frozen=True, slots=True)
class _Without:
    """The analytic model, but ``skill`` (by ``robot``, if given) has no motion anywhere."""

    base: AnalyticCostModel
    skill: str
    robot: str | None = None

    @property
    def fixed(self) -> bool:
        return False

    def _banned(self, action: Action) -> bool:
        return action.skill == self.skill and (self.robot is None or self.robot in action.robots)

    def duration(self, action: Action, transition: Transition, hands: Mapping[str, Vec3]) -> float:
        return INFEASIBLE if self._banned(action) else self.base.duration(action, transition, hands)

    def lower_bound(self, action: Action, transition: Transition) -> float:
        return self.base.lower_bound(action, transition)


def _fig1() -> tuple[Scene, AnalyticCostModel]:
    scene = load_scene(ROOT / "examples" / "scenes" / "fig1.yaml")
    return scene, AnalyticCostModel(tuple((r.id, r.speed or 0.5) for r in scene.robots))


def test_the_planner_never_pays_for_an_infeasible_instance() -> None:
    scene, base = _fig1()
    spec = load_spec(ROOT / "examples" / "specs" / "fig1.yaml")
    ok = plan(scene, spec, cost=_Without(base, "none"))
    assert ok.status is PlanStatus.SOLVED
    # r2r has no motion: the plan does without it (it needs none here), at the same makespan
    no_r2r = plan(scene, spec, cost=_Without(base, "handover_r2r"))
    assert no_r2r.status is PlanStatus.SOLVED and no_r2r.makespan == ok.makespan
    # only r1 reaches the bottle: without its pick there is no plan, not a very long one
    none = plan(scene, spec, cost=_Without(base, "pick", "r1"))
    assert none.status is PlanStatus.INFEASIBLE and not none.steps
    assert none.makespan is None or not math.isfinite(none.makespan)


def test_the_simulator_fails_an_action_without_motion_at_once() -> None:
    scene, base = _fig1()
    sim = Simulator(scene, cost=_Without(base, "pick", "r1"))
    handle = sim.start(Action("pick", ("r1",), "bottle"), 0.0)
    status = sim.poll(handle, 0.0)
    assert status.state is ActionState.FAILED and "no motion" in status.reason
    ok = sim.start(Action("pick", ("r2",), "chips"), 0.0)
    assert sim.poll(ok, 0.0).state is ActionState.RUNNING
