"""The executor's state as the cell node mirrors it along the cell's path (its background plans)."""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field, replace

from hltl.execution.background import after_running
from hltl.execution.drivers import ActionState, ActionStatus, Handle
from hltl.execution.predicted import PlanKey
from hltl.skills.library import Transition, step_symbol
from hltl.skills.semantics import ActionSemantics, Infeasible, apply
from hltl.spec.hierarchy import HSpec
from hltl.spec.monitor import HierarchyMonitor, MonitorState, carry_over
from hltl.world.scene import Scene
from hltl.world.state import WorldState, initial_world

# a spec the node knows by version: the spec and its monitor (None: not known here)
SpecOf = Callable[[int], tuple[HSpec, HierarchyMonitor] | None]


@dataclass(frozen=True, slots=True)
class Mind:
    """What the executor believes and is doing after its tick at ``t`` (before it acts), as
    far as the node can tell from the cell's path: its belief (the observations merged as
    :class:`~hltl.execution.belief.Belief` merges them, its completed actions applied), its
    monitor state and spec version (0: no spec known yet), the highest handle of a step it
    has ended, the running step's transitions by handle, and the background plans' keys it
    holds. ``known`` is False once something happened that the node cannot mirror (the
    executor then plans itself: every plan the node sends is checked by its problem)."""

    t: float
    world: WorldState
    q: MonitorState = ()
    version: int = 0
    ended: int = 0
    trans: Mapping[int, Transition] = field(default_factory=dict)
    keys: frozenset[PlanKey] = frozenset()
    known: bool = True

    def runs(self, latest: Mapping[int, ActionStatus]) -> list[tuple[Transition, bool]]:
        """The running step's actions that run or ended done, in dispatch order, each with
        whether it still runs (as :func:`~hltl.execution.background.after_running` takes
        them)."""
        out = []
        for h in sorted(self.trans):
            st = latest.get(h)
            if st is None or not st.terminal:
                out.append((self.trans[h], True))
            elif st.state is ActionState.DONE:
                out.append((self.trans[h], False))
        return out

    def after(
        self, monitor: HierarchyMonitor, latest: Mapping[int, ActionStatus]
    ) -> tuple[WorldState, MonitorState] | None:
        """The world and monitor state once the running step ends as planned (None: none
        runs)."""
        if not self.trans:
            return None
        return after_running(monitor, self.q, self.world, self.runs(latest))


class Mirror:
    """Derives the executor's :class:`Mind` tick by tick (the node keeps them along the path:
    a tick simulated again replaces the ones from its time on)."""

    def __init__(self, scene: Scene, semantics: ActionSemantics) -> None:
        self.scene = scene
        self.semantics = semantics

    def first(self, obs: WorldState, unavailable: frozenset[str]) -> Mind:
        """The executor's mind after its first tick (time 0): the scene's initial world with
        the first observation merged."""
        return Mind(0.0, _merge(initial_world(self.scene), obs, 0.0, unavailable))

    def tick(
        self,
        prev: Mind,
        t: float,
        obs: WorldState,
        unavailable: frozenset[str],
        handles: Mapping[int, Handle],
        latest: Mapping[int, ActionStatus],
        ended_now: Sequence[int],
        version: int,
        spec_of: SpecOf,
    ) -> Mind:
        """The executor's mind after its tick at ``t`` (observation ``obs``, the robots the
        cell has down), from the one after its tick before: the starts made then (``handles``
        above ``prev.ended`` it has no transition for, started at ``prev.t``), the actions
        that ended at this tick (``ended_now``; ``latest``: every action's status now), the
        spec it holds now (``version``: a later one carries the monitor state over, as the
        executor's ``assign``), and the step's end when every action of it has ended."""
        if not prev.known:
            return replace(prev, t=t)
        world = _merge(prev.world, obs, t, unavailable)
        trans = dict(prev.trans)
        for h in sorted(handles):
            if h <= prev.ended or h in trans:
                continue
            hd = handles[h]
            tr = self.semantics.transition(hd.action, prev.world)
            if abs(hd.start - prev.t) > 1e-9 or isinstance(tr, Infeasible):
                return replace(prev, t=t, known=False)  # (not dispatched after that tick)
            trans[h] = tr
        for h in ended_now:
            st = latest.get(h)
            if h in trans and st is not None and st.state is ActionState.DONE:
                world = apply(world, trans[h])
            elif h in trans and st is not None and st.state is ActionState.FAILED:
                return replace(prev, t=t, known=False)  # (the executor re-observes)
        q, have, keys = prev.q, prev.version, prev.keys
        if have == 0 and version >= 1:
            got = spec_of(1)
            if got is None:
                return replace(prev, t=t, known=False)
            q, have = got[1].initial, 1
        while have < version:
            old, new = spec_of(have), spec_of(have + 1)
            if old is None or new is None:
                return replace(prev, t=t, known=False)
            q, have, keys = carry_over(old[0], q, new[0]), have + 1, frozenset()
        ended = prev.ended
        if trans and all((st := latest.get(h)) is not None and st.terminal for h in trans):
            done = [trans[h] for h in sorted(trans) if latest[h].state is ActionState.DONE]
            if done:
                got = spec_of(have)
                if got is None:
                    return replace(prev, t=t, known=False)
                q = got[1].step(q, step_symbol(done, world))
            ended, trans = max(trans), {}
        return Mind(t, world, q, have, ended, trans, keys)


def _merge(world: WorldState, obs: WorldState, t: float, unavailable: frozenset[str]) -> WorldState:
    """:meth:`Belief.observe <hltl.execution.belief.Belief.observe>`'s merge in one go
    (people and hands from ``obs``, resting objects that people moved), then the time and
    the robots down, as the executor's tick takes them in. Its other two rules never apply
    here: the cell's observations are of their tick (none older than the executor's last
    touch of an object), and after a failed action (re-observed) the mind is given up."""
    objects = dict(world.objects)
    for oid, st in obs.objects:
        cur = objects[oid]
        if cur.loc.kind in _RESTING and st.loc.kind in _RESTING:
            objects[oid] = st
    return WorldState(
        t,
        tuple(sorted({**dict(world.humans), **dict(obs.humans)}.items())),
        tuple(sorted(objects.items())),
        tuple(sorted({**dict(world.hands), **dict(obs.hands)}.items())),
        unavailable,
    )


_RESTING = ("rest", "on")


def remember(history: list[Mind], mind: Mind) -> None:
    """Keep ``mind`` as the last of ``history``: the ones of its time or later are dropped
    (the cell went back: a restore, then the same ticks again)."""
    while history and history[-1].t >= mind.t - 1e-12:
        history.pop()
    history.append(mind)


def before(history: list[Mind], t: float) -> Mind | None:
    """The latest mind of ``history`` before time ``t`` (dropping none)."""
    for m in reversed(history):
        if m.t < t - 1e-12:
            return m
    return None
