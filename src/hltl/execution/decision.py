"""The executor's decision state machine: why it replans (triggers) and what it does next."""

from __future__ import annotations

import enum


class Trigger(enum.Enum):
    """Why the suffix is replanned; the values are what ``replan`` records say."""

    INITIAL = "initial"  # the first spec
    GOAL = "goal"  # a new instruction changed the spec
    WORLD = "world"  # no plan and the world changed since planning failed
    CONTEXT = "context"  # ℓ(w) differs from the plan's
    ROBOTS = "robots"  # robots went down or came back
    PRECONDITION = "precondition"  # the plan's first step is not executable
    FAILURE = "failure"  # an action failed
    HALT = "halt"  # a driver halted an action
    HALT_PRECONDITION = "halt:precondition"  # the executor halted one: its Pre broke
    HALT_INTRUSION = "halt:intrusion"  # the executor halted one: a person is forecast in
    HALT_UPDATE = "halt:update"  # the executor halted one: finishing it would leave no plan
    PROGRESS = "progress"  # a step ended


class Triggers:
    """The triggers collected since the last replan, in the order they happened."""

    def __init__(self) -> None:
        self._items: list[Trigger] = []

    def add(self, trigger: Trigger) -> None:
        if trigger not in self._items:
            self._items.append(trigger)

    def take(self) -> str:
        """All of them joined with ``+`` (as logged); the set is emptied."""
        text = "+".join(t.value for t in self._items)
        self._items.clear()
        return text

    def __bool__(self) -> bool:
        return bool(self._items)


class Phase(enum.Enum):
    """Where a decision stands; :meth:`hltl.execution.executor.Executor._decide` acts on it."""

    IDLE = "idle"  # a step is executing, there is no task, or the episode ended
    ACCEPTED = "accepted"  # every goal is met
    BUSY = "busy"  # a critical-path planner call is still being paid for (plan latency)
    REOBSERVING = "reobserving"  # waiting for an observation taken after a failure
    BLOCKED = "blocked"  # no plan exists and nothing changed since the planner said so
    REPLAN = "replan"  # no plan, or a trigger asks for a new one
    STALE_PLAN = "stale plan"  # the plan was made for another context or robot set
    DISPATCH = "dispatch"  # the plan's first step can go
