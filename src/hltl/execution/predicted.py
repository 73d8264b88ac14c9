"""The predicted-plan cache: plans for forecast worlds, kept until one takes over."""

from __future__ import annotations

from collections import OrderedDict
from dataclasses import dataclass

from hltl.planner import PlanResult
from hltl.spec.monitor import MonitorState
from hltl.world.geometry import Context
from hltl.world.state import JointState, WorldState, project

# The discrete start of a plan: context, object places, monitor state, unavailable robots, spec.
PlanKey = tuple[Context, JointState, MonitorState, frozenset[str], int]


def plan_key(ctx: Context, world: WorldState, q: MonitorState, spec_version: int) -> PlanKey:
    """Two starts with equal keys allow exactly the same plans (the takeover rule compares them)."""
    return (ctx, project(world), q, world.unavailable, spec_version)


@dataclass(frozen=True, slots=True)
class Predicted:
    """A plan computed at time ``at`` for the forecast context ``context``, which took
    ``wall_s`` seconds of wall-clock time."""

    result: PlanResult
    at: float
    context: Context
    wall_s: float = 0.0


def same_plan(a: PlanResult, b: PlanResult) -> bool:
    """Whether two plans do the same thing: the same actions in the same steps (their
    durations may differ, when they were timed for different places of the people)."""
    return [s.actions for s in a.steps] == [s.actions for s in b.steps]


class PredictedPlans:
    """At most ``size`` predicted plans, the oldest dropped first."""

    def __init__(self, size: int) -> None:
        self.size = size
        self._plans: OrderedDict[PlanKey, Predicted] = OrderedDict()

    def get(self, key: PlanKey) -> Predicted | None:
        return self._plans.get(key)

    def __contains__(self, key: PlanKey) -> bool:
        return key in self._plans

    def put(self, key: PlanKey, plan: Predicted) -> None:
        self._plans[key] = plan
        while len(self._plans) > self.size:
            self._plans.popitem(last=False)

    def pop(self, key: PlanKey) -> Predicted | None:
        """The plan at ``key``, forgotten: a predicted plan is used once."""
        return self._plans.pop(key, None)

    def clear(self) -> None:
        self._plans.clear()
