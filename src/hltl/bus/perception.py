"""Perception as a node: camera frames in, observations out (``hltl node perception``)."""

from __future__ import annotations

import threading
import time
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any

from hltl.bus.codec import StampedPose, dumps, encode_pose, loads
from hltl.bus.keys import Keys
from hltl.errors import BusError
from hltl.perception.frames import Frame
from hltl.perception.geometry import Cylinder
from hltl.perception.observe import ObjectObservation, Observation, Perceiver, fuse
from hltl.perception.people import PersonObservation
from hltl.world.state import WorldState


def observation_to_wire(obs: Observation) -> dict[str, Any]:
    """An observation as JSON data, floats unrounded (``Observation.to_dict`` is for people)."""
    return {
        "t": obs.t,
        "frame": obs.frame,
        "latency": obs.latency,
        "objects": [
            {
                "id": o.id,
                "label": o.label,
                "position": list(o.position),
                "cylinder": [
                    list(o.cylinder.center),
                    o.cylinder.radius,
                    o.cylinder.height,
                    list(o.cylinder.axis),
                    o.cylinder.points,
                ],
                "score": o.score,
                "pixels": o.pixels,
            }
            for o in obs.objects
        ],
        "people": [
            {
                "track": p.track,
                "id": p.person,
                "position": list(p.position),
                "box": list(p.box),
                "score": p.score,
            }
            for p in obs.people
        ],
        "missing": list(obs.missing),
        "unmatched": list(obs.unmatched),
        "ambiguous": list(obs.ambiguous),
        "lost": list(obs.lost),
        "notes": list(obs.notes),
    }


def _v(p: Sequence[Any], n: int = 3) -> tuple[float, ...]:
    if len(p) != n:
        raise ValueError(f"expected {n} numbers, got {p!r:.60}")
    return tuple(float(x) for x in p)


def observation_from_wire(d: Mapping[str, Any]) -> Observation:
    """Inverse of :func:`observation_to_wire`.

    Raises:
        BusError: the record is malformed (names what).
    """

    def opt(x: Any) -> str | None:
        return None if x is None else str(x)

    def strs(key: str) -> tuple[str, ...]:
        return tuple(str(s) for s in d.get(key, ()))

    try:
        objects = []
        for o in d["objects"]:
            center, radius, height, axis, points = o["cylinder"]
            cyl = Cylinder(_v(center), float(radius), float(height), _v(axis), int(points))  # type: ignore[arg-type]
            objects.append(
                ObjectObservation(
                    opt(o["id"]),
                    str(o["label"]),
                    _v(o["position"]),  # type: ignore[arg-type]
                    cyl,
                    float(o["score"]),
                    int(o["pixels"]),
                )
            )
        people = [
            PersonObservation(
                str(p["track"]),
                opt(p["id"]),
                _v(p["position"]),  # type: ignore[arg-type]
                _v(p["box"], 4),  # type: ignore[arg-type]
                float(p["score"]),
            )
            for p in d["people"]
        ]
        return Observation(
            float(d["t"]),
            int(d["frame"]),
            tuple(objects),
            tuple(people),
            float(d["latency"]),
            strs("missing"),
            strs("unmatched"),
            strs("ambiguous"),
            strs("lost"),
            strs("notes"),
        )
    except (KeyError, TypeError, ValueError) as exc:
        raise BusError(f"malformed perception record on the bus: {exc}") from None


@dataclass(slots=True)
class PerceptionStats:
    frames: int = 0
    poses: int = 0
    waited: float = 0.0  # seconds spent waiting for a subscriber


def serve_frames(
    session: Any,
    perceiver: Perceiver,
    frames: Iterable[Frame],
    *,
    cell: str = "default",
    realtime: bool = False,
    wait: float = 10.0,
    stop: threading.Event | None = None,
    on_frame: Callable[[Observation], None] | None = None,
) -> PerceptionStats:
    """Perceive each frame and publish what is seen; returns when the frames run out.

    Args:
        realtime: pace frames by their time stamps (a recording replayed as it was taken);
            otherwise as fast as perception goes.
        wait: seconds to wait for someone to subscribe to ``hltl/<cell>/perception`` before the
            first frame (frames nobody receives are lost).
    """
    keys = Keys(cell)
    stop = threading.Event() if stop is None else stop
    stats = PerceptionStats()
    pub = session.declare_publisher(keys.perception)
    poses: dict[str, Any] = {}
    try:
        t0 = time.monotonic()
        while not pub.matching_status.matching and time.monotonic() - t0 < wait:
            if stop.wait(0.01):
                return stats
        stats.waited = time.monotonic() - t0
        start: tuple[float, float] | None = None
        for frame in frames:
            if stop.is_set():
                break
            if realtime:
                now = time.monotonic()
                start = start or (now, frame.t)
                delay = start[0] + (frame.t - start[1]) - now
                if delay > 0 and stop.wait(delay):
                    break
            obs = perceiver.process(frame)
            pub.put(dumps(observation_to_wire(obs)))
            stats.frames += 1
            for p in obs.people:
                if p.person is None:
                    continue
                pp = poses.get(p.person)
                if pp is None:
                    pp = poses[p.person] = session.declare_publisher(keys.human_pose(p.person))
                if pp.matching_status.matching:
                    pp.put(encode_pose(StampedPose("world", obs.t, p.position)))
                    stats.poses += 1
            if on_frame is not None:
                on_frame(obs)
    finally:
        for p in (pub, *poses.values()):
            p.undeclare()
    return stats


class PerceptionClient:
    """The executor's side: collects a perception node's observations (in frame-time order)."""

    def __init__(self, session: Any, *, cell: str = "default") -> None:
        self.keys = Keys(cell)
        self._lock = threading.Lock()
        self._seen = threading.Condition(self._lock)
        self._obs: list[Observation] = []
        self.malformed = 0
        self._sub = session.declare_subscriber(self.keys.perception, self._on_sample)

    def _on_sample(self, sample: Any) -> None:
        try:
            obs = observation_from_wire(loads(sample.payload.to_bytes(), "perception record"))
        except BusError:
            with self._lock:
                self.malformed += 1
            return
        with self._lock:
            self._obs.append(obs)
            self._obs.sort(key=lambda o: (o.t, o.frame))
            self._seen.notify_all()

    @property
    def observations(self) -> list[Observation]:
        with self._lock:
            return list(self._obs)

    def wait_for(self, n: int, timeout: float) -> bool:
        """Wait (bounded) until ``n`` observations have arrived."""
        with self._lock:
            return self._seen.wait_for(lambda: len(self._obs) >= n, timeout)

    def latest(self, t: float | None = None) -> Observation | None:
        """The newest observation of a frame taken at or before ``t`` (any, without ``t``)."""
        with self._lock:
            for o in reversed(self._obs):
                if t is None or o.t <= t + 1e-9:
                    return o
        return None

    def fuse(self, world: WorldState) -> WorldState:
        """``world`` with the latest observation up to its time fused in (unchanged if none)."""
        obs = self.latest(world.t)
        if obs is None:
            return world

        return fuse(world, obs)

    def close(self) -> None:
        self._sub.undeclare()
