"""What a closed-loop baseline is: a policy that answers a planning context with a script."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Protocol

from hltl.skills.library import Action
from hltl.spec.hierarchy import HSpec
from hltl.spec.monitor import HierarchyMonitor, MonitorState
from hltl.world.scene import Scene
from hltl.world.state import WorldState


@dataclass(frozen=True, slots=True)
class PlanContext:
    """What a policy sees when asked for a script.

    Attributes:
        scene: the cell.
        world: the latest perceived world (objects' places, people, hands, robots down).
        spec: the task as the referee grounds it (for policies that read specs; the LLM
            baseline reads ``instructions`` instead).
        monitor, q: the referee's monitors and their state (what is done).
        done: names of the spec's formulas already done.
        instructions: everything said so far, in order.
        trigger: why the policy is asked (``initial``, ``goal``, ``precondition``…).
    """

    scene: Scene
    world: WorldState
    spec: HSpec
    monitor: HierarchyMonitor
    q: MonitorState
    done: frozenset[str]
    instructions: tuple[str, ...]
    trigger: str


@dataclass(frozen=True, slots=True)
class Script:
    """A policy's answer: synchronous steps, each a tuple of actions.

    Attributes:
        steps: the plan.
        tokens: LLM tokens this answer cost (prompt + completion).
        queries: LLM queries made for it.
        error: set when the answer could not be executed at all (e.g. a script that does not
            parse); the trial then fails.
        text: the LLM's raw answer, for the log.
    """

    steps: tuple[tuple[Action, ...], ...] = ()
    tokens: int = 0
    queries: int = 0
    error: str | None = None
    text: str = ""


class Policy(Protocol):
    """Decides actions for the baseline loop."""

    name: str
    #: replan when the context ℓ changes (a person moved), as hltl's executor does
    replan_on_context: bool

    def plan(self, ctx: PlanContext) -> Script: ...
