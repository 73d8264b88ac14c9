"""Temporal filters of perceived positions: gated Kalman per person track, gated mean per object."""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
import numpy.typing as npt

F64 = npt.NDArray[np.float64]
Vec3 = tuple[float, float, float]
CHI2_2DOF_999 = 13.82  # 99.9 % of a 2-D Gaussian lies within this squared Mahalanobis distance


@dataclass(slots=True)
class WalkerFilter:
    """Constant-velocity Kalman filter of one walker's floor position.

    Args:
        accel: white-noise acceleration (m/s²): how fast a walker may start, stop or turn.
        noise: measurement standard deviation (m).
        resets: rejected measurements in a row after which the filter restarts there.
    """

    accel: float = 2.0
    noise: float = 0.03
    resets: int = 3
    x: F64 = field(default_factory=lambda: np.zeros(4))
    p: F64 = field(default_factory=lambda: np.eye(4))
    z: float = 0.0
    t: float | None = None
    rejected: int = 0
    gated: int = 0  # measurements not folded in, over the filter's life

    def _start(self, pos: Vec3, t: float) -> None:
        self.x = np.array([pos[0], pos[1], 0.0, 0.0])
        self.p = np.diag([self.noise**2, self.noise**2, 1.0, 1.0])
        self.z = pos[2]
        self.t = t
        self.rejected = 0

    def predict(self, t: float) -> F64:
        """Advance the state to time ``t`` (no measurement)."""
        if self.t is None:
            return self.x
        dt = max(t - self.t, 0.0)
        f = np.eye(4)
        f[0, 2] = f[1, 3] = dt
        q1 = np.array([[dt**4 / 4, dt**3 / 2], [dt**3 / 2, dt**2]]) * self.accel**2
        q = np.zeros((4, 4))
        q[np.ix_([0, 2], [0, 2])] = q1
        q[np.ix_([1, 3], [1, 3])] = q1
        self.x = f @ self.x
        self.p = f @ self.p @ f.T + q
        self.t = t
        return self.x

    def update(self, pos: Vec3, t: float) -> Vec3:
        """Fold in one measurement taken at ``t``; the filtered position."""
        if self.t is None:
            self._start(pos, t)
            return pos
        self.predict(t)
        h = np.zeros((2, 4))
        h[0, 0] = h[1, 1] = 1.0
        s = h @ self.p @ h.T + np.eye(2) * self.noise**2
        r = np.array([pos[0], pos[1]]) - h @ self.x
        if float(r @ np.linalg.solve(s, r)) > CHI2_2DOF_999:
            self.rejected += 1
            self.gated += 1
            if self.rejected >= self.resets:
                self._start(pos, t)
                return pos
            return self.position
        self.rejected = 0
        k = self.p @ h.T @ np.linalg.inv(s)
        self.x = self.x + k @ r
        self.p = (np.eye(4) - k @ h) @ self.p
        self.z += 0.3 * (pos[2] - self.z)
        return self.position

    @property
    def position(self) -> Vec3:
        return (float(self.x[0]), float(self.x[1]), float(self.z))

    @property
    def velocity(self) -> tuple[float, float]:
        return (float(self.x[2]), float(self.x[3]))


@dataclass(slots=True)
class RestingFilter:
    """Position of an object at rest, robust to single-frame mistakes.

    Args:
        gate: a measurement farther than this from the estimate (m) is held back.
        confirm: held-back measurements in a row, within ``gate`` of each other, that move the
            estimate to their mean.
        window: the estimate averages at most this many recent measurements.
    """

    gate: float = 0.03
    confirm: int = 2
    window: int = 10
    estimate: Vec3 | None = None
    count: int = 0
    pending: list[Vec3] = field(default_factory=list)
    held_back: int = 0  # measurements outside the gate, over the filter's life

    def update(self, pos: Vec3) -> Vec3:
        if self.estimate is None:
            self.estimate, self.count = pos, 1
            return pos
        if math.dist(pos, self.estimate) <= self.gate:
            self.pending.clear()
            self.count = min(self.count + 1, self.window)
            w = 1.0 / self.count
            e = self.estimate
            self.estimate = (
                e[0] + w * (pos[0] - e[0]),
                e[1] + w * (pos[1] - e[1]),
                e[2] + w * (pos[2] - e[2]),
            )
            return self.estimate
        self.held_back += 1
        if self.pending and math.dist(pos, self.pending[-1]) > self.gate:
            self.pending.clear()
        self.pending.append(pos)
        if len(self.pending) >= self.confirm:
            m = np.mean(np.array(self.pending), axis=0)
            self.estimate = (float(m[0]), float(m[1]), float(m[2]))
            self.count = len(self.pending)
            self.pending.clear()
        return self.estimate
