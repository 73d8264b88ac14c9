"""Step durations under the analytic model: the search's short way (hand travel over speed) and
its general way (any cost model's ``duration``) against the model's definition, replayed."""

from __future__ import annotations

import dataclasses
import random
from collections.abc import Mapping

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.planner import PlanResult, PlanStatus, plan
from hltl.planner.problem import Problem
from hltl.skills.cost import AnalyticCostModel, CostModel, cost_model_for
from hltl.skills.library import Action, Transition
from hltl.skills.semantics import ActionSemantics, Infeasible, apply_all
from hltl.spec.hierarchy import HSpec, load_spec, spec_from_dict
from hltl.world.scene import Scene, Vec3, load_scene, scene_from_dict
from hltl.world.state import initial_world
from tests.oracles.random_instances import random_instance


@dataclasses.dataclass(frozen=True, slots=True)
class _Opaque:
    """The analytic model behind the plain cost-model protocol: the planner cannot tell it is
    analytic, so it asks ``duration`` for every instance (the way a motion model is asked)."""

    inner: AnalyticCostModel

    @property
    def fixed(self) -> bool:
        return False

    def duration(self, action: Action, transition: Transition, hands: Mapping[str, Vec3]) -> float:
        return self.inner.duration(action, transition, hands)

    def lower_bound(self, action: Action, transition: Transition) -> float:
        return self.inner.lower_bound(action, transition)


def _replayed_durations(scene: Scene, cost: CostModel, res: PlanResult) -> list[float]:
    """Each step's duration by the definition: the slowest of its actions, each from the
    transition that applies where its object is now and from where the hands are now."""
    sem = ActionSemantics.of(scene, cost=cost)
    world = initial_world(scene)
    out = []
    for step in res.steps:
        longest = 0.0
        transitions = []
        for a in step.actions:
            tr = sem.transition(a, world)
            assert not isinstance(tr, Infeasible), tr.reason
            hands = {
                r: world.hand_position(r) or sem.kinematics.home_point(scene.robot(r))
                for r in a.robots
            }
            longest = max(longest, cost.duration(a, tr, hands))
            transitions.append(tr)
        out.append(longest)
        world = apply_all(world, transitions)
    return out


def _both_ways(scene: Scene, spec: HSpec) -> tuple[PlanResult, PlanResult, AnalyticCostModel]:
    cost = cost_model_for(scene)
    assert isinstance(cost, AnalyticCostModel)
    short = plan(scene, spec, timeout=60)
    general = plan(scene, spec, cost=_Opaque(cost), timeout=60)
    return short, general, cost


def _assert_agree(scene: Scene, short: PlanResult, general: PlanResult, cost: CostModel) -> None:
    assert short.status is general.status
    if short.status is not PlanStatus.SOLVED:
        return
    # both ways are one model: the same search, the same plan, step by step
    assert [s.duration for s in short.steps] == [s.duration for s in general.steps]
    assert [s.actions for s in short.steps] == [s.actions for s in general.steps]
    # rounded to whole microseconds per step in the search
    expected = _replayed_durations(scene, cost, short)
    assert [s.duration for s in short.steps] == pytest.approx(expected, abs=1e-6)


def test_fig1_pick_lasts_the_travel_to_where_the_object_rests() -> None:
    # #13's report: the general way took the bottle's pick from the shelf (the last transition
    # of that action) for its pick from where it rests: 1.77 s instead of 1.32 s
    scene = dataclasses.replace(load_scene("examples/scenes/fig1.yaml"), durations=None)
    spec = load_spec("examples/specs/fig1.yaml")
    short, general, cost = _both_ways(scene, spec)
    _assert_agree(scene, short, general, cost)
    # r1's hand from its home 0.3 m above the base to the bottle, at 0.5 m/s, plus the grasp
    bottle_travel = (0.4**2 + 0.2**2 + 0.25**2) ** 0.5 / 0.5
    assert short.steps[0].duration == pytest.approx(bottle_travel + 0.3, abs=1e-6)
    assert general.makespan == pytest.approx(3.065253, abs=1e-6)


def test_every_instance_costs_the_same_both_ways_from_the_start() -> None:
    scene = dataclasses.replace(load_scene("examples/scenes/fig1.yaml"), durations=None)
    spec = load_spec("examples/specs/fig1.yaml")
    cost = cost_model_for(scene)
    assert isinstance(cost, AnalyticCostModel)
    short = Problem(scene, spec)
    general = Problem(scene, spec, cost=_Opaque(cost))
    assert short.speeds and not general.speeds
    hands = short.start()[1]
    assert hands == general.start()[1]
    # a pick from rest and a pick from the shelf are the same action with two transitions
    actions = [i.action for i in short.instances]
    assert len(set(actions)) < len(actions)
    for a, b in zip(short.instances, general.instances, strict=True):
        assert a.action == b.action
        assert short.duration(a, hands) == general.duration(b, hands)


@settings(max_examples=40, deadline=None)
@given(st.integers(0, 10**6))
def test_short_and_general_way_agree_with_the_definition(seed: int) -> None:
    scene_d, spec_d = random_instance(seed, max_robots=3, max_objects=2)
    rng = random.Random(seed)
    del scene_d["durations"]
    for r in scene_d["robots"]:
        r["speed"] = rng.choice((0.1, 0.3, 0.5, 1.0))
    scene = scene_from_dict(scene_d, source=f"cost-paths-{seed}")
    spec = spec_from_dict(spec_d)
    short, general, cost = _both_ways(scene, spec)
    _assert_agree(scene, short, general, cost)
