"""Joint trajectories and per-action motion plans (CONTRACTS.md); plain Python, no extras."""

from __future__ import annotations

import bisect
import math
from collections.abc import Sequence
from dataclasses import dataclass

EVENT_KINDS = ("grasp", "release", "transfer")


@dataclass(frozen=True, slots=True)
class JointTrajectory:
    """Positions of one robot's joints over time, from the action's start.

    ``times`` start at 0 and increase strictly; ``positions`` has one row per time (radians);
    ``velocities``, when given, one row per time (rad/s). :meth:`sample` interpolates linearly and
    clamps outside ``[0, duration]``.
    """

    robot: str
    joint_names: tuple[str, ...]
    times: tuple[float, ...]
    positions: tuple[tuple[float, ...], ...]
    velocities: tuple[tuple[float, ...], ...] | None = None

    def __post_init__(self) -> None:
        n = len(self.joint_names)
        if not self.times:
            raise ValueError(f"trajectory of {self.robot!r}: no samples; expected at least one")
        if self.times[0] != 0.0:
            raise ValueError(
                f"trajectory of {self.robot!r}: times[0] is {self.times[0]!r}; expected 0.0"
            )
        for a, b in zip(self.times, self.times[1:], strict=False):
            if not b > a:
                raise ValueError(
                    f"trajectory of {self.robot!r}: times must increase strictly, got {a!r} "
                    f"then {b!r}"
                )
        rows: list[tuple[str, Sequence[Sequence[float]]]] = [("positions", self.positions)]
        if self.velocities is not None:
            rows.append(("velocities", self.velocities))
        for what, table in rows:
            if len(table) != len(self.times):
                raise ValueError(
                    f"trajectory of {self.robot!r}: {len(table)} {what} rows for "
                    f"{len(self.times)} times"
                )
            for row in table:
                if len(row) != n or not all(math.isfinite(v) for v in row):
                    raise ValueError(
                        f"trajectory of {self.robot!r}: {what} row {tuple(row)!r} needs "
                        f"{n} finite numbers ({', '.join(self.joint_names)})"
                    )

    @property
    def duration(self) -> float:
        return self.times[-1]

    def sample(self, t: float) -> tuple[float, ...]:
        """Joint positions at ``t`` seconds (linear interpolation, clamped to the ends)."""
        if t <= 0.0:
            return self.positions[0]
        if t >= self.times[-1]:
            return self.positions[-1]
        i = bisect.bisect_right(self.times, t) - 1
        t0, t1 = self.times[i], self.times[i + 1]
        a = (t - t0) / (t1 - t0)
        p0, p1 = self.positions[i], self.positions[i + 1]
        return tuple(x + a * (y - x) for x, y in zip(p0, p1, strict=True))

    def shifted(self, offset: float) -> JointTrajectory:
        """The same motion starting ``offset`` seconds later, holding the first pose until then."""
        if offset <= 0.0:
            return self
        times = (0.0, *(t + offset for t in self.times))
        positions = (self.positions[0], *self.positions)
        vel = None
        if self.velocities is not None:
            zero = tuple(0.0 for _ in self.joint_names)
            vel = (zero, *self.velocities)
        return JointTrajectory(self.robot, self.joint_names, times, positions, vel)

    def then(self, other: JointTrajectory) -> JointTrajectory:
        """This trajectory followed by ``other`` (same robot and joints)."""
        if other.robot != self.robot or other.joint_names != self.joint_names:
            raise ValueError(
                f"cannot append trajectory of {other.robot!r} to one of {self.robot!r}"
            )
        end = self.duration
        times = self.times + tuple(end + t for t in other.times[1:])
        positions = self.positions + other.positions[1:]
        vel = None
        if self.velocities is not None and other.velocities is not None:
            vel = self.velocities + other.velocities[1:]
        return JointTrajectory(self.robot, self.joint_names, times, positions, vel)


@dataclass(frozen=True, slots=True)
class MotionPlan:
    """Everything one skill instance's robots do: one trajectory per robot and timed events.

    ``events`` are ``(time, kind, robot)`` with kind ``grasp``, ``release`` or ``transfer``.
    """

    trajectories: tuple[JointTrajectory, ...]
    events: tuple[tuple[float, str, str], ...]
    duration: float

    def __post_init__(self) -> None:
        for t, kind, robot in self.events:
            if kind not in EVENT_KINDS:
                raise ValueError(
                    f"motion event {kind!r} of {robot!r}: expected one of {EVENT_KINDS}"
                )
            if not 0.0 <= t <= self.duration + 1e-9:
                raise ValueError(
                    f"motion event {kind!r} of {robot!r} at t={t!r} lies outside "
                    f"[0, {self.duration!r}]"
                )
        for tr in self.trajectories:
            if tr.duration > self.duration + 1e-9:
                raise ValueError(
                    f"trajectory of {tr.robot!r} lasts {tr.duration:.3f} s, longer than the "
                    f"plan's {self.duration:.3f} s"
                )

    def trajectory(self, robot: str) -> JointTrajectory | None:
        for tr in self.trajectories:
            if tr.robot == robot:
                return tr
        return None
