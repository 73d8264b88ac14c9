"""The 3D simulator seen through its camera: observations from rendered RGB-D frames."""

from __future__ import annotations

from typing import Any

from hltl.execution.log import Perception
from hltl.perception.frames import Camera as FrameCamera
from hltl.perception.frames import Frame, camera_from_dict
from hltl.perception.observe import Observation, Perceiver, fuse
from hltl.sim3d.camera import CameraRenderer, camera_to_world, intrinsics
from hltl.sim3d.driver import MujocoSimulator
from hltl.sim3d.record import pick_camera
from hltl.world.state import ObjectStatus, WorldState, initial_world


class CameraSimulator(MujocoSimulator):
    """:class:`MujocoSimulator` whose :meth:`observe` is camera perception.

    Args:
        backend: object backend (a name of ``hltl.perception.objects.BACKENDS``).
        people: person detector (``depth`` by default: it needs no segmentation render;
            ``segmentation``, ``fused`` or ``yolo``).
        camera: scene camera id (default: the first).
        smooth: filter people's and objects' positions over frames (``hltl.perception.filtering``).
        (the rest as :class:`MujocoSimulator`)
    """

    def __init__(
        self,
        *args: Any,
        backend: str = "segmentation",
        people: str = "depth",
        camera: str | None = None,
        smooth: bool = True,
        **kwargs: Any,
    ) -> None:
        super().__init__(*args, **kwargs)
        cam = pick_camera(self, camera)
        self._renderer = CameraRenderer(self.stage.sm, cam, geometry="collision")
        k = intrinsics(cam)
        spec = {
            "name": cam.id,
            "width": cam.width,
            "height": cam.height,
            "intrinsics": {"fx": k.fx, "fy": k.fy, "cx": k.cx, "cy": k.cy},
            "extrinsics": {"camera_to_world": camera_to_world(cam).tolist()},
            "segments": self.stage.sm.segment_table(),
        }
        self.camera: FrameCamera = camera_from_dict(spec, f"camera {cam.id}")
        self.perceiver = Perceiver(self.scene, self.camera, backend, people, smooth=smooth)
        self.period = 1.0 / cam.rate
        self._next_frame = 0.0
        self._belief: WorldState = initial_world(self.scene)
        self.observations: list[Observation] = []
        self._index = 0

    def close(self) -> None:
        self._renderer.close()

    def _frame(self, t: float) -> Observation:
        self._sync()
        f = self._renderer.render(self.stage.data)
        frame = Frame(self._index, t, f.rgb, f.depth, f.seg, self.stage.joints())
        self._index += 1
        return self.perceiver.process(frame)

    def observe(self, t: float | None = None) -> WorldState:
        truth = super().observe(t)
        now = self.now if t is None else t
        belief = self._belief
        # the robot knows what it holds and where it put things: take those from its senses
        for oid, st in truth.objects:
            if st.loc != belief.object_status(oid).loc:
                belief = belief.with_object(oid, st)
        if now + 1e-9 >= self._next_frame:
            obs = self._frame(now)
            self.observations.append(obs)
            seen = fuse(belief, obs)
            # an object a running action of ours handles is the robot's business: the camera
            # sees it rise in the gripper during a pick, which is not the object moving away
            for oid, _ in truth.objects:
                if self._running_on(oid):
                    seen = seen.with_object(oid, belief.object_status(oid))
            belief = seen
            self.log.emit(
                Perception(
                    t=now,
                    latency_ms=round(obs.latency * 1000.0, 1),
                    people={p.person or f"track {p.track}": list(p.position) for p in obs.people},
                    missing=list(obs.missing),
                    lost=list(obs.lost),
                    ambiguous=list(obs.ambiguous),
                )
            )
            self._next_frame = now + self.period
        self._belief = belief.with_time(truth.t)
        objects = tuple(
            (oid, self._belief.object_status(oid) if st.loc.kind in ("rest", "on") else st)
            for oid, st in truth.objects
        )
        return WorldState(
            t=truth.t,
            humans=self._belief.humans,
            objects=tuple((o, ObjectStatus(s.position, s.loc)) for o, s in objects),
            hands=truth.hands,
            unavailable=truth.unavailable,
        )
