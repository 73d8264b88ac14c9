"""Episode hooks of the 3D simulator: camera frame folders and pose snapshots for videos."""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from hltl.errors import HltlError
from hltl.sim3d.camera import CameraRenderer, FrameWriter
from hltl.sim3d.driver import MujocoSimulator
from hltl.sim3d.model import scene_cameras
from hltl.world.scene import Camera


def pick_camera(sim: MujocoSimulator, camera: str | None) -> Camera:
    cams = scene_cameras(sim.scene)
    if camera is None:
        return cams[0]
    for c in cams:
        if c.id == camera:
            return c
    raise HltlError(
        f"camera {camera!r} is not in {sim.scene.source}; it has: {', '.join(c.id for c in cams)}"
    )


class FrameRecorder:
    """Writes the fixed camera's frames at its rate while an episode runs (a frame folder)."""

    def __init__(
        self, folder: Path, *, camera: str | None = None, geometry: str = "collision"
    ) -> None:
        self.folder = folder
        self.camera = camera
        self.geometry = geometry
        self._renderer: CameraRenderer | None = None
        self._writer: FrameWriter | None = None
        self._next = 0.0
        self._period = 0.1

    def on_tick(self, t: float, sim: Any, executor: Any) -> None:
        if not isinstance(sim, MujocoSimulator):
            raise HltlError("camera frames need the 3D simulator (--sim mujoco)")
        if self._renderer is None:
            cam = pick_camera(sim, self.camera)
            self._renderer = CameraRenderer(sim.stage.sm, cam, geometry=self.geometry)
            self._writer = FrameWriter(self.folder, sim.stage.sm, cam)
            self._period = 1.0 / cam.rate
        if t + 1e-9 < self._next:
            return
        assert self._writer is not None
        self._writer.write(self._renderer.render(sim.stage.data), t, sim.stage.joints())
        self._next = t + self._period

    @property
    def frames(self) -> int:
        return 0 if self._writer is None else len(self._writer.frames)

    def close(self) -> None:
        if self._writer is not None:
            self._writer.close()
        if self._renderer is not None:
            self._renderer.close()


@dataclass
class Snapshots:
    """The 3D pose every ``period`` simulated seconds, taken as the simulator poses its model
    (between the executor's ticks too), to be rendered after the episode."""

    period: float = 0.02
    times: list[float] = field(default_factory=list)
    qpos: list[np.ndarray] = field(default_factory=list)
    mocap_pos: list[np.ndarray] = field(default_factory=list)
    mocap_quat: list[np.ndarray] = field(default_factory=list)
    sim: MujocoSimulator | None = None

    def attach(self, sim: MujocoSimulator) -> None:
        self.sim = sim
        sim.on_pose.append(self._take)

    def _take(self, t: float) -> None:
        if self.times and t < self.times[-1] + self.period - 1e-9:
            return
        assert self.sim is not None
        d = self.sim.stage.data
        self.times.append(t)
        self.qpos.append(d.qpos.copy())
        self.mocap_pos.append(d.mocap_pos.copy())
        self.mocap_quat.append(d.mocap_quat.copy())

    def restore(self, i: int) -> None:
        """Pose the simulator's model as snapshot ``i`` (for rendering)."""
        assert self.sim is not None
        st = self.sim.stage
        st.data.qpos[:] = self.qpos[i]
        st.data.mocap_pos[:] = self.mocap_pos[i]
        st.data.mocap_quat[:] = self.mocap_quat[i]
        st.forward()
