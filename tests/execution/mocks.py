"""Mocks for driving the executor without the simulator: a timed driver and a recording planner."""

from __future__ import annotations

from dataclasses import dataclass, field

from hltl.execution.drivers import ActionState, ActionStatus, Handle
from hltl.motion.trajectory import MotionPlan
from hltl.planner import PlanResult, plan
from hltl.skills.library import Action
from hltl.spec.hierarchy import HSpec
from hltl.spec.monitor import HierarchyMonitor, MonitorState
from hltl.world.geometry import Context
from hltl.world.scene import Scene
from hltl.world.state import WorldState


@dataclass
class MockDriver:
    """Every action takes ``duration`` seconds; ``fail`` lists skills that always fail."""

    duration: float = 0.5
    fail: frozenset[str] = frozenset()
    down: frozenset[str] = frozenset()
    started: list[tuple[float, Action]] = field(default_factory=list)
    halted: list[tuple[float, Action, str]] = field(default_factory=list)
    _halted_ids: dict[int, float] = field(default_factory=dict)
    _next: int = 1

    def start(self, action: Action, t: float, *, motion: MotionPlan | None = None) -> Handle:
        self.started.append((t, action))
        h = Handle(self._next, action, t)
        self._next += 1
        return h

    def poll(self, handle: Handle, t: float) -> ActionStatus:
        if handle.id in self._halted_ids:
            return ActionStatus(ActionState.HALTED, 0.5, self._halted_ids[handle.id], "halted")
        end = handle.start + self.duration
        if t + 1e-9 < end:
            return ActionStatus(ActionState.RUNNING, (t - handle.start) / self.duration, t)
        if handle.action.skill in self.fail:
            return ActionStatus(ActionState.FAILED, 1.0, end, f"{handle.action.skill} failed")
        return ActionStatus(ActionState.DONE, 1.0, end)

    def halt(self, handle: Handle, t: float, reason: str) -> None:
        self.halted.append((t, handle.action, reason))
        self._halted_ids[handle.id] = t

    def unavailable(self, t: float) -> frozenset[str]:
        return self.down


@dataclass
class RecordingPlanner:
    """The exact planner, recording the context and monitor state of every call; or, with
    ``canned``, always answering that result."""

    canned: PlanResult | None = None
    calls: list[tuple[Context, MonitorState]] = field(default_factory=list)

    def __call__(
        self,
        scene: Scene,
        spec: HSpec,
        *,
        world: WorldState,
        monitor: HierarchyMonitor,
        q0: MonitorState,
    ) -> PlanResult:
        self.calls.append((world.context(scene), q0))
        if self.canned is not None:
            return self.canned
        return plan(scene, spec, world=world, monitor=monitor, q0=q0)
