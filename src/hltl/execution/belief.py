"""The executor's belief w_t: perception merged with what its own actions did."""

from __future__ import annotations

from hltl.skills.library import Transition
from hltl.skills.semantics import apply
from hltl.world.scene import Scene
from hltl.world.state import WorldState, initial_world


class Belief:
    """The world as the executor believes it, and which objects it is unsure about."""

    def __init__(self, scene: Scene) -> None:
        self.world: WorldState = initial_world(scene)
        self._touched: dict[str, float] = {}
        self._reobserve: dict[str, float] = {}
        self._last_obs_t = -1.0

    def observe(self, obs: WorldState, t: float) -> bool:
        """Merge an observation at time ``t``; False when it is older than one already seen."""
        if obs.t < self._last_obs_t:
            return False  # out of order: an older observation adds nothing
        self._last_obs_t = obs.t
        w, seen = self._merge(obs)
        for oid in seen:
            del self._reobserve[oid]
        self.world = w.with_time(t)
        return True

    def merged(self, obs: WorldState) -> WorldState:
        """The world as it would be with ``obs`` merged in (:meth:`observe`), nothing taken
        in: read-only, so another thread may ask (the executor's guard, while its loop is
        busy)."""
        return self._merge(obs)[0]

    def _merge(self, obs: WorldState) -> tuple[WorldState, list[str]]:
        """The belief with ``obs`` merged in, and the objects re-observed after a failure."""
        w = self.world
        seen = []
        for hid, pos in obs.humans:
            w = w.with_human(hid, pos)
        for oid, st in obs.objects:
            if obs.t < self._touched.get(oid, -1.0) - 1e-12:
                continue  # sensed before our last action on it: stale
            if oid in self._reobserve:
                w = w.with_object(oid, st)  # after a failure only perception knows where it is
                seen.append(oid)
            elif w.object_status(oid).loc.kind in ("rest", "on") and st.loc.kind in ("rest", "on"):
                w = w.with_object(oid, st)  # people move resting objects (O-MOVE)
        for rid, pos in obs.hands:
            w = w.with_hand(rid, pos)
        return w, seen

    def set_unavailable(self, down: frozenset[str]) -> None:
        if down != self.world.unavailable:
            self.world = self.world.with_unavailable(down)

    def touched(self, obj: str, t: float) -> None:
        """An action on ``obj`` started or stopped at ``t``: older observations of it are stale."""
        self._touched[obj] = t

    def completed(self, transition: Transition, t: float) -> None:
        """An action ended as planned at ``t``: its effect is now part of the world."""
        self.world = apply(self.world, transition)
        self._touched[transition.obj] = t

    def failed(self, obj: str, t: float) -> None:
        """An action on ``obj`` failed at ``t``: only a later observation says where it is."""
        self._touched[obj] = t
        self._reobserve[obj] = t

    @property
    def reobserving(self) -> bool:
        """Whether some object's place waits for an observation taken after a failure."""
        return bool(self._reobserve)
