"""Exact ray-cast RGB-D frames of upright cylinders on a floor, with segmentation."""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from hltl.perception.frames import Camera, Frame, Segment

F64 = npt.NDArray[np.float64]


@dataclass(frozen=True, slots=True)
class Solid:
    """An upright cylinder standing at ``base`` (x, y, z of its bottom centre)."""

    kind: str  # a segment kind: object, human, robot, surface, other
    id: str
    base: tuple[float, float, float]
    radius: float
    height: float
    color: tuple[int, int, int]

    @property
    def center(self) -> tuple[float, float, float]:
        return (self.base[0], self.base[1], self.base[2] + self.height / 2.0)


def look_at(
    eye: Sequence[float], target: Sequence[float], up: Sequence[float] = (0.0, 0.0, 1.0)
) -> tuple[tuple[float, ...], ...]:
    """camera_to_world of an OpenCV camera at ``eye`` looking at ``target``."""
    e, t, u = (np.asarray(x, dtype=float) for x in (eye, target, up))
    z = t - e
    z /= np.linalg.norm(z)
    x = np.cross(z, u)
    if np.linalg.norm(x) < 1e-9:
        x = np.cross(z, [0.0, 1.0, 0.0])
    x /= np.linalg.norm(x)
    y = np.cross(z, x)
    m = np.eye(4)
    m[:3, 0], m[:3, 1], m[:3, 2], m[:3, 3] = x, y, z, e
    return tuple(tuple(float(v) for v in row) for row in m)


def make_camera(
    eye: Sequence[float],
    target: Sequence[float],
    solids: Sequence[Solid] = (),
    width: int = 160,
    height: int = 120,
    fov_deg: float = 69.0,
) -> Camera:
    """A camera with segment ids 1… for ``solids`` in order (0 is background/floor)."""
    f = (width / 2.0) / math.tan(math.radians(fov_deg) / 2.0)
    segments = {k + 1: Segment(s.kind, s.id) for k, s in enumerate(solids)}
    return Camera(
        "synthetic", width, height, f, f, width / 2.0, height / 2.0, look_at(eye, target), segments
    )


def render(
    camera: Camera,
    solids: Sequence[Solid],
    t: float = 0.0,
    index: int = 0,
    floor_color: tuple[int, int, int] = (150, 150, 150),
) -> Frame:
    """Ray-cast one frame; segment ids follow ``solids``' order from 1."""
    h, w = camera.height, camera.width
    v, u = np.mgrid[0:h, 0:w].astype(float)
    d_cam = np.stack([(u - camera.cx) / camera.fx, (v - camera.cy) / camera.fy, np.ones_like(u)])
    pose = camera.pose
    d = np.einsum("ij,jhw->ihw", pose[:3, :3], d_cam)  # world direction per unit camera depth
    o = pose[:3, 3]
    best = np.full((h, w), np.inf)
    seg = np.zeros((h, w), dtype=np.int32)
    # floor z = 0
    with np.errstate(divide="ignore", invalid="ignore"):
        tf = -o[2] / d[2]
    best = np.where((tf > 0) & np.isfinite(tf), tf, best)
    for k, s in enumerate(solids, start=1):
        ox, oy = o[0] - s.base[0], o[1] - s.base[1]
        a = d[0] ** 2 + d[1] ** 2
        b = 2 * (ox * d[0] + oy * d[1])
        c = ox * ox + oy * oy - s.radius**2
        disc = b * b - 4 * a * c
        ok = (disc >= 0) & (a > 1e-12)
        with np.errstate(invalid="ignore", divide="ignore"):
            t_side = (-b - np.sqrt(np.where(ok, disc, 0.0))) / (2 * a)
        z = o[2] + t_side * d[2]
        side = ok & (t_side > 0) & (z >= s.base[2]) & (z <= s.base[2] + s.height)
        top_z = s.base[2] + s.height
        with np.errstate(divide="ignore", invalid="ignore"):  # rays parallel to the top
            t_top = (top_z - o[2]) / d[2]
            px = o[0] + t_top * d[0] - s.base[0]
            py = o[1] + t_top * d[1] - s.base[1]
            top = (t_top > 0) & np.isfinite(t_top) & (px * px + py * py <= s.radius**2)
        hit = np.where(side, t_side, np.inf)
        hit = np.minimum(hit, np.where(top, t_top, np.inf))
        nearer = hit < best
        best = np.where(nearer, hit, best)
        seg = np.where(nearer, k, seg)
    depth = np.where(np.isfinite(best), best, 0.0).astype(np.float32)
    colors = np.array([floor_color, *(s.color for s in solids)], dtype=np.uint8)
    rgb = colors[seg]
    # a little shading by depth so colour clusters are not perfectly flat
    shade = np.clip(1.1 - 0.1 * depth, 0.6, 1.0)[..., None]
    rgb = np.clip(rgb * shade, 0, 255).astype(np.uint8)
    return Frame(index, t, rgb, depth, seg)
