"""The per-tick sequence every agent of the episode loop follows (the executor, the baselines)."""

from __future__ import annotations

import abc
import enum
from collections.abc import Iterable

from hltl.execution.instructions import SpecUpdate
from hltl.world.state import WorldState


class ExecStatus(enum.Enum):
    RUNNING = "running"
    DONE = "done"
    GAVE_UP = "gave_up"


class TickTemplate(abc.ABC):
    """``update`` runs one tick in a fixed order; an agent fills in the steps.

    1. take the time and what perception sees; 2. collect the actions that ended; 3. take the
    instructions given since the last tick (grounded), in order; 4. stop if the agent gave up;
    5. if a step is running, end it when all its actions ended, else check it is still safe;
    6. unless that made the agent give up, act (decide, plan, dispatch).

    The template lives here rather than in ``hltl.sim.episode`` (which drives agents) because
    the executor sits below ``sim`` in the layer order.
    """

    status: ExecStatus

    def update(
        self,
        t: float,
        observation: WorldState | None = None,
        updates: Iterable[SpecUpdate] = (),
    ) -> None:
        """One tick of the loop at time ``t``.

        Args:
            t: the time now (seconds since the start of the episode; never decreasing).
            observation: the latest perceived world (its ``t`` is when it was sensed).
            updates: instructions given since the last tick, grounded.
        """
        self._sense(t, observation)
        self._poll()
        for upd in updates:
            self.assign(t, upd)
        if self._gave_up():
            return
        if self._step_running():
            if self._step_ended():
                self._end_step()
            else:
                self._check_safety()
        if self._gave_up():  # ending the step or a hazard can make the agent give up
            return
        self._act()

    def _gave_up(self) -> bool:
        return self.status is ExecStatus.GAVE_UP

    @abc.abstractmethod
    def _sense(self, t: float, observation: WorldState | None) -> None: ...

    @abc.abstractmethod
    def _poll(self) -> None: ...

    @abc.abstractmethod
    def assign(self, t: float, update: SpecUpdate) -> None: ...

    @abc.abstractmethod
    def _step_running(self) -> bool: ...

    @abc.abstractmethod
    def _step_ended(self) -> bool: ...

    @abc.abstractmethod
    def _end_step(self) -> None: ...

    @abc.abstractmethod
    def _check_safety(self) -> None: ...

    @abc.abstractmethod
    def _act(self) -> None: ...
