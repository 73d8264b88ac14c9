"""The robot driver protocol: the only thing the executor knows about robots."""

from __future__ import annotations

import enum
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from typing import Protocol, Self, runtime_checkable

from hltl.motion.trajectory import MotionPlan
from hltl.skills.library import Action, Transition
from hltl.spec.hierarchy import HSpec
from hltl.spec.monitor import MonitorState
from hltl.world.scene import Vec3
from hltl.world.state import WorldState


class ActionState(enum.Enum):
    """Where a dispatched action is: still running, or how it ended."""

    RUNNING = "running"
    DONE = "done"
    FAILED = "failed"
    HALTED = "halted"


@dataclass(frozen=True, slots=True)
class Handle:
    """A driver's receipt for one started action."""

    id: int
    action: Action
    start: float


@dataclass(frozen=True, slots=True)
class ActionStatus:
    """The state of a started action.

    Attributes:
        state: running, done, failed or halted.
        progress: fraction of the motion completed, in [0, 1].
        t: for a terminal state, when it was reached; for ``RUNNING``, the time polled.
        reason: for ``FAILED`` and ``HALTED``, why.
    """

    state: ActionState
    progress: float
    t: float
    reason: str = ""

    @property
    def terminal(self) -> bool:
        return self.state is not ActionState.RUNNING


@runtime_checkable
class MotionSource(Protocol):
    """A cost model that also plans the joint trajectories of what it times (the motion layer's
    MotionCostModel); the executor hands those trajectories to the driver."""

    def motion_plan(
        self, action: Action, transition: Transition, hands: Mapping[str, Vec3]
    ) -> MotionPlan | None:
        """The motion of ``action`` from the given hand positions, or None without one; called
        as the action is dispatched (later motions of the episode start where it ends)."""
        ...

    def for_episode(self) -> Self:
        """A copy for one episode: no memory of where earlier episodes left the arms."""
        ...


@runtime_checkable
class RobotDriver(Protocol):
    """What the executor asks of the robots.

    Calls carry the executor's clock ``t`` (seconds since the episode started) so that a driver
    can time-stamp what it reports; a driver never moves time itself.
    """

    def start(self, action: Action, t: float, *, motion: MotionPlan | None = None) -> Handle:
        """Begin executing ``action`` (its robots must be available and idle); ``motion`` is
        the joint trajectories a motion layer planned for it (drivers that do not move arms
        ignore it)."""
        ...

    def poll(self, handle: Handle, t: float) -> ActionStatus:
        """How the action is doing at time ``t``: running with its progress, or how it ended."""
        ...

    def halt(self, handle: Handle, t: float, reason: str) -> None:
        """Stop the action now; its effect does not happen (the object stays where it was)."""
        ...

    def unavailable(self, t: float) -> frozenset[str]:
        """Robots that cannot take actions at time ``t`` (faults, maintenance, another job)."""
        ...


@runtime_checkable
class OwnClock(Protocol):
    """A driver whose robots run on their own clock, not the executor's (real arms, or the
    bus's real-time cell): an action may end before a halt sent for it arrives (optional).
    The executor then takes in the end as it was (a hand-over done is done), instead of
    believing the action halted."""

    def ended_first(self, handle: Handle) -> ActionStatus | None:
        """After :meth:`RobotDriver.halt`: how the action ended if it ended on its own before
        the halt reached it (done or failed), else ``None`` (halted, or not known yet)."""
        ...


# the executor's safety check for a guard (:class:`Guarded`): the running actions that must
# halt given an observation, each with the reason
SafetyCheck = Callable[[WorldState], Sequence[tuple[Handle, str]]]


@runtime_checkable
class Guarded(Protocol):
    """A driver whose robots run on their own clock and that can keep the executor's safety
    check running while the executor's loop is busy (planning, grounding) (optional). The
    executor gives it :data:`SafetyCheck` once, when it is made: a check of its running
    actions' preconditions against its belief with an observation merged in, which changes
    nothing and is safe to call from another thread. The driver calls it with each new
    observation it hears while the loop has not been back for a while, and
    halts at once what it names; the executor hears of such a halt as of any (the action's
    report says halted, with the reason) and replans. Nothing else in the executor depends
    on it."""

    def guard(self, check: SafetyCheck) -> None:
        """The executor's safety check, to run while its loop is busy."""
        ...


@dataclass(frozen=True, slots=True)
class Expected:
    """A step the executor expects to dispatch next if nothing happens: its plan's next step.

    Attributes:
        actions: the step's actions, in the order the executor will start them.
        at: when the plan expects the step to start (seconds since the episode started).
    """

    actions: tuple[Action, ...]
    at: float


@runtime_checkable
class Lookahead(Protocol):
    """A driver that can use what the executor will command next (optional, besides
    :class:`RobotDriver`): like an action server's goal queued behind the current one, or a
    trajectory controller's queued segments, except that nothing is committed.

    The executor calls :meth:`expect` right after it starts a step. A driver may run on with
    the guess (the bus's cell node simulates the next step's start when the current one ends,
    so one answer carries both); when the executor then commands something else (a halt, a
    replan, another step, a start at another time), the driver must undo the guess so that
    nothing of it shows: the executor's ``start``, ``poll`` and ``halt`` calls and their results
    are exactly what they would be without the hint. A driver that ignores hints (the in-process
    simulators) simply does not implement this.
    """

    def expect(self, steps: Sequence[Expected]) -> None:
        """The steps the executor will start next, in order, each once the step before it
        (first: the step just started) has ended with all its actions done; replaces any
        earlier hint (empty: no guess)."""
        ...


@dataclass(frozen=True, slots=True)
class Basis:
    """What the executor decides its next step from once the running step has ended with all
    its actions done (or now, with no step running): its spec and monitor state then, and
    its planner. A driver that runs ahead can plan from it on the world it simulates, as the
    executor will (:class:`Foresight`).

    Attributes:
        spec: the running specification.
        version: counts the executor's specs (a new request makes a new one).
        q: the monitor state once the running step ends as planned (now, with none running).
        planner: the executor's planner (a driver plans with it only if it knows how).
        config: the executor's configuration (its checks before a dispatch), if any.
        predictor: the executor's forecaster of people (for the intrusion check), if any.
    """

    spec: HSpec
    version: int
    q: MonitorState
    planner: object
    config: object = None
    predictor: object = None


@runtime_checkable
class Foresight(Protocol):
    """A driver that can foresee the executor's next step itself (optional, besides
    :class:`Lookahead`): after a walk or a new request the plan's next step is no longer what
    the executor dispatches, but the executor's replan is a function of the world and its
    :class:`Basis`, so a driver simulating the world ahead (the bus's cell node) can run the
    same planner there and start its first step on a guess. As with hints, nothing is
    committed and nothing in the executor depends on it.

    The executor calls :meth:`foresee` whenever its spec changes (an instruction grounded)
    and right after it starts a step (with the monitor state the step will leave).
    """

    def foresee(self, basis: Basis) -> None:
        """The executor's basis for its next decision (replaces any earlier one)."""
        ...


@dataclass(frozen=True, slots=True)
class Briefing:
    """The episode's first instruction as the executor is about to ground it with the offline
    grounder (before its first observation), with the planner and checks it will plan and
    check the first step with (as in :class:`Basis`): a driver that runs ahead can ground it
    and plan that step meanwhile, instead of after the executor's grounding
    (:class:`Briefed`).

    Attributes:
        instruction: the text, as said.
        planner: the executor's planner (a driver plans with it only if it knows how).
        config: the executor's configuration (its checks before a dispatch), if any.
        predictor: the executor's forecaster of people (for the intrusion check), if any.
    """

    instruction: str
    planner: object
    config: object = None
    predictor: object = None


@runtime_checkable
class Briefed(Protocol):
    """A driver that foresees (:class:`Foresight`) and can start on the first instruction
    before the executor has grounded it (optional). The executor calls :meth:`brief` once,
    before its first spec, when it is told the instruction is grounded with the offline
    grounder (which the driver can run too); its :class:`Basis` follows as usual. Nothing
    is committed and nothing in the executor depends on it."""

    def brief(self, briefing: Briefing) -> None:
        """The first instruction and what the first step will be planned and checked with."""
        ...
