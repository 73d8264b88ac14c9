"""The fixed RGB-D camera: offscreen RGB, metric depth and segmentation, written as frame folders.

A frame folder (CONTRACTS.md) is what a recorded real camera would give: ``camera.json`` with
the intrinsics and the camera-to-world pose in the OpenCV optical convention (x right, y down,
z forward), ``rgb/NNNNNN.png``, ``depth/NNNNNN.npz`` (key ``depth``, float32 metres along the
optical axis, 0 where nothing is hit) and ``seg/NNNNNN.png`` (16-bit segment ids, 0 background).
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from hltl.errors import HltlError
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

    def __init__(self, sm: SceneModel, cam: Camera, *, geometry: str = "collision") -> None:
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

        ``camera``: an ``MjvCamera`` (e.g. an orbit view) instead of the fixed camera.
        """
        mj = self.mj
        r = self.renderer
        r.update_scene(
            data, camera=self.cam_id if camera is None else camera, scene_option=self.option
        )
        rgb = r.render().copy()
        h, w = rgb.shape[:2]
        ids = np.zeros((h, w), np.int32)
        if seg or depth:
            r.enable_segmentation_rendering()
            raw = r.render()
            r.disable_segmentation_rendering()
            objid, objtype = raw[..., 0], raw[..., 1]
            is_geom = objtype == int(mj.mjtObj.mjOBJ_GEOM)
            ids = np.where(is_geom, self.seg_lut[np.clip(objid, -1, None) + 1], 0).astype(np.int32)
            hit = objid >= 0
        dep = np.zeros((h, w), np.float32)
        if depth:
            r.enable_depth_rendering()
            dep = r.render().astype(np.float32)
            r.disable_depth_rendering()
            dep[~hit] = 0.0
        return Frame(rgb, dep, ids if seg else np.zeros((h, w), np.int32))


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

    def write(self, frame: Frame, t: float) -> None:
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
