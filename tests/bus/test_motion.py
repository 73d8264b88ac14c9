"""``hltl run --motion`` over the bus: the executor's joint trajectories reach the node's robots
(CDR ``JointTrajectory`` on ``…/trajectory``) and the node starts each action with them."""

from __future__ import annotations

import functools
from typing import Any

import pytest

from hltl.errors import BackendUnavailableError
from hltl.motion.trajectory import MotionPlan
from hltl.sim import scenarios
from hltl.sim.episode import EpisodeConfig, run_episode
from hltl.sim.simulator import Simulator
from hltl.skills.library import Action
from tests.bus.helpers import Loopback, without_wall_clock


class _Recording(Simulator):
    """The discrete simulator, noting the motion plan each action was started with."""

    plans: list[MotionPlan | None]

    def start(self, action: Action, t: float, *, motion: MotionPlan | None = None) -> Any:
        type(self).plans.append(motion)
        return super().start(action, t, motion=motion)


def _recording(**kw: Any) -> tuple[Any, list[MotionPlan | None]]:
    cls = type("Rec", (_Recording,), {"plans": []})
    return functools.partial(cls, **kw), cls.plans


def test_motion_plans_cross_the_bus_and_the_log_is_unchanged(loopback: Loopback) -> None:
    from hltl.cli.run import _motion_options
    from hltl.motion.cost import motion_models

    sc = scenarios.get("fig1")
    try:
        kinematics, cost = motion_models(sc.scene)
    except BackendUnavailableError as exc:
        pytest.skip(str(exc))
    agent = _motion_options(sc.scene, None, EpisodeConfig(), None)["agent"]
    here, sent = _recording(cost=cost, kinematics=kinematics)
    local = run_episode(sc.scene, instruction=sc.instruction, seed=0, simulator=here, agent=agent)
    k2, c2 = motion_models(sc.scene)  # the node's own motion layer
    there, received = _recording(cost=c2, kinematics=k2)
    run = loopback.run(sc.scene, factory=there, agent=agent, instruction=sc.instruction, seed=0)
    assert local.success
    assert without_wall_clock(list(run.episode.records)) == without_wall_clock(list(local.records))
    assert sent and all(p is not None for p in sent)
    assert len(received) == len(sent)
    for a, b in zip(sent, received, strict=True):
        assert a is not None and b is not None
        assert b.events == a.events and b.duration == a.duration
        assert [t.robot for t in b.trajectories] == [t.robot for t in a.trajectories]
        for ta, tb in zip(a.trajectories, b.trajectories, strict=True):
            assert tb.joint_names == ta.joint_names and tb.positions == ta.positions
            assert tb.times == pytest.approx(ta.times, abs=1e-9)  # CDR times are nanoseconds
    assert run.node.stats.trajectories >= sum(len(p.trajectories) for p in sent if p)
