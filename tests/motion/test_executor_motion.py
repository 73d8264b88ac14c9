"""The executor hands the motion layer's joint trajectories to the driver with each action."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from hltl.execution.drivers import ActionState, ActionStatus, Handle
from hltl.execution.executor import Executor, ExecutorConfig
from hltl.motion.cost import MotionCostModel
from hltl.motion.trajectory import MotionPlan
from hltl.skills.library import Action
from hltl.spec.hierarchy import spec_from_dict
from hltl.world.scene import Scene
from hltl.world.state import initial_world


@dataclass
class RecordingDriver:
    """Every action takes its motion plan's duration (1 s without one); records the plans."""

    started: list[tuple[Action, MotionPlan | None]] = field(default_factory=list)
    _ends: dict[int, float] = field(default_factory=dict)

    def start(self, action: Action, t: float, *, motion: MotionPlan | None = None) -> Handle:
        self.started.append((action, motion))
        h = Handle(len(self.started), action, t)
        self._ends[h.id] = t + (motion.duration if motion is not None else 1.0)
        return h

    def poll(self, handle: Handle, t: float) -> ActionStatus:
        end = self._ends[handle.id]
        if t + 1e-9 < end:
            return ActionStatus(ActionState.RUNNING, 0.5, t)
        return ActionStatus(ActionState.DONE, 1.0, end)

    def halt(self, handle: Handle, t: float, reason: str) -> None:
        self._ends[handle.id] = t

    def unavailable(self, t: float) -> frozenset[str]:
        return frozenset()


def test_dispatched_actions_carry_their_motion_plans(fig1: Scene, fig1_cell: Any) -> None:
    spec = spec_from_dict(
        {
            "root": "p0",
            "formulas": {"p0": "F p100", "p100": "F delivered(bottle, A)"},
        }
    )
    driver = RecordingDriver()
    ex = Executor(
        fig1,
        spec,
        driver,
        cost=MotionCostModel(fig1_cell),
        kinematics=fig1_cell.kinematics,
        config=ExecutorConfig(predict=False, intrusion=False),
    )
    ex.update(0.0, initial_world(fig1))
    assert driver.started, "the first step was dispatched"
    action, motion = driver.started[0]
    assert action == Action("pick", ("r1",), "bottle")
    assert motion is not None
    assert [tr.robot for tr in motion.trajectories] == ["r1"]
    assert any(kind == "grasp" for _, kind, _ in motion.events)


def test_the_forecast_workspace_comes_from_the_maps(fig1: Scene, fig1_cell: Any) -> None:
    """W_j of eq. (ws_predict) is the maps' when the arms have models: a person standing where
    r1's map reaches their comfort zone but its reach sphere does not is forecast in r1's
    workspace (by the executor too), in nobody's by the spheres."""
    from hltl.execution.predict import predict_workspace
    from hltl.perception.predict import ConstantVelocityPredictor
    from hltl.world.geometry import context_label

    kin = fig1_cell.kinematics
    spot = (-0.9, 0.6, 0.0)
    assert kin.context_label(fig1, {"A": spot}).robots_serving("A") == frozenset({"r1"})
    assert context_label(fig1, {"A": spot}).robots_serving("A") == frozenset()
    still = ConstantVelocityPredictor()
    for k in range(6):
        still.observe(0.1 * k, [("A", spot)])
    assert predict_workspace(fig1, still, "A", 0.5, 1.5, 0.1, kin).robots == {"r1"}
    assert predict_workspace(fig1, still, "A", 0.5, 1.5, 0.1).robots == frozenset()

    spec = spec_from_dict(
        {"root": "p0", "formulas": {"p0": "F p100", "p100": "F delivered(bottle, A)"}}
    )
    world = initial_world(fig1).with_human("A", spot)
    ex = Executor(fig1, spec, RecordingDriver(), kinematics=kin, config=ExecutorConfig())
    ex.update(0.0, world)
    assert ex.busy, "the pick was dispatched"
    ex.update(0.1, world)  # forecasts run while a step executes
    assert ex.predictions["A"].robots == frozenset({"r1"})
