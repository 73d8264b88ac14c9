"""The fixed RGB-D camera: offscreen RGB, metric depth and segmentation, as frame folders."""

from __future__ import annotations

import json
import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from hltl.errors import HltlError
from hltl.perception.frames import joints_entry
from hltl.sim3d.gl import mujoco, require_renderer
from hltl.sim3d.model import SceneModel, camera_axes
from hltl.world.scene import Camera

GEOMETRY = ("collision", "visual")


@dataclass(frozen=True, slots=True)
class Intrinsics:
    fx: float
    fy: float
    cx: float
    cy: float


def intrinsics(cam: Camera) -> Intrinsics:
    """Pinhole intrinsics of a camera (square pixels; OpenCV pixel centres at integers)."""
    f = (cam.height / 2) / math.tan(math.radians(cam.fovy) / 2)
    return Intrinsics(f, f, (cam.width - 1) / 2, (cam.height - 1) / 2)


def camera_to_world(cam: Camera) -> np.ndarray:
    """4×4 pose of the OpenCV optical frame in the world."""
    axes = camera_axes(cam) @ np.diag([1.0, -1.0, -1.0])
    out = np.eye(4)
    out[:3, :3] = axes
    out[:3, 3] = cam.position
    return out


@dataclass(frozen=True, slots=True)
class Frame:
    rgb: np.ndarray  # H×W×3 uint8
    depth: np.ndarray  # H×W float32 metres, 0 = no return
    seg: np.ndarray  # H×W int32 segment ids, 0 = background


class CameraRenderer:
    """Renders one scene camera (or a free orbit view) offscreen.

    Args:
        geometry: ``collision`` draws robots' collision shapes (fast), ``visual`` their meshes.
    """

    def __init__(
        self, sm: SceneModel, cam: Camera, *, geometry: str = "collision", shadows: bool = False
    ) -> None:
        if geometry not in GEOMETRY:
            raise HltlError(f"geometry {geometry!r} is not one of {', '.join(GEOMETRY)}")
        require_renderer()
        mj = mujoco()
        self.mj = mj
        self.sm = sm
        self.cam = cam
        m = sm.model
        self.cam_id = int(mj.mj_name2id(m, mj.mjtObj.mjOBJ_CAMERA, f"camera:{cam.id}"))
        if self.cam_id < 0:
            raise HltlError(f"the 3D model has no camera {cam.id!r}")
        if cam.width > m.vis.global_.offwidth or cam.height > m.vis.global_.offheight:
            raise HltlError(
                f"camera {cam.id!r}: {cam.width}×{cam.height} exceeds the offscreen buffer "
                f"{m.vis.global_.offwidth}×{m.vis.global_.offheight}"
            )
        try:
            self.renderer = mj.Renderer(m, cam.height, cam.width)
        except Exception as exc:  # GL context errors come in many types
            raise HltlError(f"cannot open an offscreen OpenGL context: {exc}") from None
        self.option = mj.MjvOption()
        groups = (0, 2) if geometry == "collision" else (1, 2)
        for g in range(6):
            self.option.geomgroup[g] = 1 if g in groups else 0
            self.option.sitegroup[g] = 0
        self.seg_lut = np.concatenate([[0], sm.geom_segment]).astype(np.int32)
        # shadows (and the sky) cost more than the rest of a frame on a CPU renderer: camera
        # frames go without, the demo video with them
        self.shadows = shadows

    def close(self) -> None:
        self.renderer.close()

    def __enter__(self) -> CameraRenderer:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def render(
        self, data: Any, *, camera: Any = None, depth: bool = True, seg: bool = True
    ) -> Frame:
        """Render the model's current state (``data`` after ``mj_forward``/``mj_kinematics``).

        ``camera``: an ``MjvCamera`` (e.g. an orbit view) instead of the fixed camera. Two
        passes at most: the lit colour image, and one segmentation pass whose colour buffer
        gives the ids and whose depth buffer gives the depth (flat id colours keep the depth
        exact far away, as MuJoCo's own depth rendering does).
        """
        r = self.renderer
        r.update_scene(
            data, camera=self.cam_id if camera is None else camera, scene_option=self.option
        )
        flags = r.scene.flags
        flags[self.mj.mjtRndFlag.mjRND_SHADOW] = self.shadows
        flags[self.mj.mjtRndFlag.mjRND_SKYBOX] = self.shadows
        rgb = r.render().copy()
        h, w = rgb.shape[:2]
        if not (seg or depth):
            return Frame(rgb, np.zeros((h, w), np.float32), np.zeros((h, w), np.int32))
        ids, dep = self._seg_depth(h, w)
        return Frame(
            rgb,
            dep if depth else np.zeros((h, w), np.float32),
            ids if seg else np.zeros((h, w), np.int32),
        )

    def _seg_depth(self, h: int, w: int) -> tuple[np.ndarray, np.ndarray]:
        mj = self.mj
        r = self.renderer
        scn = r.scene
        saved = scn.flags.copy()
        try:
            scn.flags[mj.mjtRndFlag.mjRND_SEGMENT] = True
            scn.flags[mj.mjtRndFlag.mjRND_IDCOLOR] = True
            if r._gl_context:
                r._gl_context.make_current()
            colour = np.empty((h, w, 3), np.uint8)
            zbuf = np.empty((h, w), np.float32)
            mj.mjr_render(r._rect, scn, r._mjr_context)
            mj.mjr_readPixels(colour, zbuf, r._rect, r._mjr_context)
        finally:
            np.copyto(scn.flags, saved)
        colour, zbuf = np.flipud(colour), np.flipud(zbuf)
        # id colours → MuJoCo segment ids (0 = nothing) → geoms → scene segments
        segid = (
            colour[..., 0].astype(np.int64)
            + colour[..., 1].astype(np.int64) * 256
            + colour[..., 2].astype(np.int64) * 65536
        )
        lut = np.zeros(scn.ngeom + 2, np.int32)
        geom = int(mj.mjtObj.mjOBJ_GEOM)
        for g in scn.geoms[: scn.ngeom]:
            if g.segid >= 0 and g.objtype == geom:
                lut[g.segid + 1] = self.seg_lut[g.objid + 1]
        hit = segid > 0
        ids = lut[np.clip(segid, 0, len(lut) - 1)]
        # reversed-Z depth buffer → metres along the optical axis (MuJoCo's own conversion)
        m = self.sm.model
        far = np.float32(m.vis.map.zfar * m.stat.extent)
        near = np.float32(m.vis.map.znear * m.stat.extent)
        c = -(far + near) / (far - near)
        d = -(np.float32(2) * far * near) / (far - near)
        c, d = np.float32(-0.5) * c - np.float32(0.5), np.float32(-0.5) * d
        dep = (d / (zbuf.astype(np.float64) + c)).astype(np.float32)
        dep[~hit] = 0.0
        return ids, dep


@dataclass
class FrameWriter:
    """Writes frames into a frame folder; ``camera.json`` is rewritten by :meth:`close`."""

    folder: Path
    sm: SceneModel
    cam: Camera
    seg: bool = True
    frames: list[dict[str, Any]] = field(default_factory=list)

    def __post_init__(self) -> None:
        try:
            for sub in ("rgb", "depth") + (("seg",) if self.seg else ()):
                (self.folder / sub).mkdir(parents=True, exist_ok=True)
        except OSError as exc:
            raise HltlError(
                f"{self.folder}: cannot create the frame folder: {exc.strerror}"
            ) from None

    def write(
        self, frame: Frame, t: float, joints: Mapping[str, Sequence[float]] | None = None
    ) -> None:
        """Write ``frame`` taken at ``t``; ``joints`` (robot id → joint positions) go into its
        ``camera.json`` entry when given."""
        from PIL import Image

        i = len(self.frames)
        name = f"{i:06d}"
        entry: dict[str, Any] = {
            "index": i,
            "t": round(t, 6),
            "rgb": f"rgb/{name}.png",
            "depth": f"depth/{name}.npz",
        }
        Image.fromarray(frame.rgb).save(self.folder / entry["rgb"])
        np.savez_compressed(self.folder / entry["depth"], depth=frame.depth.astype(np.float32))
        if self.seg:
            entry["seg"] = f"seg/{name}.png"
            if int(frame.seg.max(initial=0)) > 65535:
                raise HltlError("more than 65535 segments do not fit a 16-bit PNG")
            Image.fromarray(frame.seg.astype(np.uint16)).save(self.folder / entry["seg"])
        if joints is not None:
            entry["joints"] = joints_entry(joints)
        self.frames.append(entry)

    def camera_json(self) -> dict[str, Any]:
        k = intrinsics(self.cam)
        out: dict[str, Any] = {
            "name": self.cam.id,
            "width": self.cam.width,
            "height": self.cam.height,
            "intrinsics": {"fx": k.fx, "fy": k.fy, "cx": k.cx, "cy": k.cy},
            "extrinsics": {
                "camera_to_world": [
                    [round(float(v), 9) for v in row] for row in camera_to_world(self.cam)
                ]
            },
            "convention": "opencv",
            "depth_units": "m",
            "frames": self.frames,
        }
        if self.seg:
            out["segments"] = self.sm.segment_table()
        return out

    def close(self) -> None:
        text = json.dumps(self.camera_json(), indent=1)
        (self.folder / "camera.json").write_text(text + "\n", encoding="utf-8")
