"""People from depth alone (plan-view body columns) and cheap colour appearance features."""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np
import numpy.typing as npt

from hltl.perception.detection import support_planes
from hltl.perception.frames import Camera
from hltl.world.scene import Scene

F64 = npt.NDArray[np.float64]
Mask = npt.NDArray[np.bool_]
Box = tuple[float, float, float, float]

CELL = 0.05  # m: floor-plan grid
BAND = (1.4, 2.2)  # m above the floor: shoulders and head, above a robot arm on a table
MIN_TOP, MAX_TOP = 1.5, 2.2  # m above the floor: how tall a standing person's head is
MAX_WIDTH = 0.9  # m: the widest a person's shoulders and head span on the plan
MIN_WIDTH = 0.12  # m: narrower is a pole or a link of an arm seen end-on
ROBOT_CLEARANCE = 0.3  # m: a column this near a robot's base is the robot's raised arm
GROW = 2  # cells the head-and-shoulders region grows by to take in the rest of the body
MIN_CELL_POINTS = 3  # points a grid cell needs to count (one stray pixel is noise)


def floor_height(z: F64) -> float | None:
    """The lowest large horizontal plane among point heights: 2 cm bins, the lowest one holding
    at least 3 % of the points, refined to its points' median. None when there is none."""
    if len(z) == 0:
        return None
    lo = float(np.percentile(z, 0.5))
    bins = np.arange(lo - 0.02, float(z.max()) + 0.04, 0.02)
    counts, edges = np.histogram(z, bins=bins)
    big = np.flatnonzero(counts >= 0.03 * len(z))
    if not len(big):
        return None
    i = int(big[0])
    sel = (z >= edges[i]) & (z < edges[i + 1])
    return float(np.median(z[sel]))


class DepthPersonDetector:
    """Standing people as body-sized columns of depth points on the floor plan.

    Args:
        scene: its robots' bases are excluded (None: nothing excluded).
        step: work on every ``step``-th pixel (masks are scaled back to full resolution).
    """

    def __init__(self, scene: Scene | None = None, step: int = 2) -> None:
        self.bases = [r.base[:2] for r in scene.robots] if scene is not None else []
        self.step = step
        self.floor: float | None = None

    def detect(self, depth: npt.NDArray[np.float32], camera: Camera) -> list[tuple[Box, Mask]]:
        """(box, mask) of each person in view, nearest first."""
        from scipy import ndimage

        s = self.step
        small = depth[::s, ::s]
        valid = small > 0
        if not valid.any():
            return []
        # back-project the subsampled pixels with the full-resolution intrinsics
        v, u = np.nonzero(valid)
        zc = small[v, u].astype(float)
        cam_pts = np.stack(
            [(u * s - camera.cx) * zc / camera.fx, (v * s - camera.cy) * zc / camera.fy, zc],
            axis=1,
        )
        pose = camera.pose
        pts = cam_pts @ pose[:3, :3].T + pose[:3, 3]
        floor = floor_height(pts[:, 2])
        if floor is None:
            return []
        self.floor = floor
        height = pts[:, 2] - floor
        # table tops a person stands at are not the person (their colour would be theirs)
        flat = np.zeros(len(pts), dtype=bool)
        for plane in support_planes(pts[:, 2]):
            if plane > floor + 0.1:
                flat |= np.abs(pts[:, 2] - plane) < 0.02
        in_band = (height > BAND[0]) & (height < BAND[1])
        if in_band.sum() < MIN_CELL_POINTS:
            return []
        origin = pts[in_band, :2].min(axis=0) - 3 * CELL
        ij = np.floor((pts[:, :2] - origin) / CELL).astype(int)
        bi = ij[in_band]
        shape = (int(bi[:, 0].max()) + 4, int(bi[:, 1].max()) + 4)
        counts = np.zeros(shape, dtype=int)
        np.add.at(counts, (bi[:, 0], bi[:, 1]), 1)
        top = np.full(shape, -np.inf)
        np.maximum.at(top, (bi[:, 0], bi[:, 1]), height[in_band])
        occupied = counts >= MIN_CELL_POINTS
        # one empty cell between two parts of a body (a gap in a sparse far view) is bridged
        joined = ndimage.binary_closing(occupied, structure=np.ones((3, 3))) | occupied
        labels, _ = ndimage.label(joined, structure=np.ones((3, 3)))
        inside = (ij[:, 0] >= 0) & (ij[:, 1] >= 0) & (ij[:, 0] < shape[0]) & (ij[:, 1] < shape[1])
        out: list[tuple[float, Box, Mask]] = []
        cam = pose[:3, 3]
        for k, sl in enumerate(ndimage.find_objects(labels), start=1):
            if sl is None:
                continue
            cells = (labels[sl] == k) & occupied[sl]
            if not cells.any():
                continue
            head = float(top[sl][cells].max())
            ci, cj = np.nonzero(cells)
            xs = origin[0] + (ci + sl[0].start + 0.5) * CELL
            ys = origin[1] + (cj + sl[1].start + 0.5) * CELL
            w = max(float(np.ptp(xs)), float(np.ptp(ys))) + CELL
            if not (MIN_TOP <= head <= MAX_TOP) or not (MIN_WIDTH <= w <= MAX_WIDTH):
                continue
            weights = counts[sl][cells].astype(float)
            cx = float(np.average(xs, weights=weights))
            cy = float(np.average(ys, weights=weights))
            if any(math.hypot(cx - b[0], cy - b[1]) < ROBOT_CLEARANCE for b in self.bases):
                continue
            # the body below the shoulders: every point above the floor in the column's cells,
            # grown by GROW cells (legs and arms reach a little beyond the head and shoulders)
            region = ndimage.binary_dilation(
                labels == k, structure=np.ones((3, 3)), iterations=GROW
            )
            sel = np.zeros(len(pts), dtype=bool)
            sel[inside] = region[ij[inside, 0], ij[inside, 1]]
            sel &= (height > 0.03) & (height < head + 0.05) & ~flat
            if sel.sum() < 10:
                continue
            small_mask = np.zeros(small.shape, dtype=bool)
            small_mask[v[sel], u[sel]] = True
            mask = np.kron(small_mask, np.ones((s, s), dtype=bool))[
                : depth.shape[0], : depth.shape[1]
            ]
            mask &= depth > 0
            vv, uu = np.nonzero(mask)
            if len(vv) == 0:
                continue
            box: Box = (float(uu.min()), float(vv.min()), float(uu.max() + 1), float(vv.max() + 1))
            out.append((math.hypot(cx - cam[0], cy - cam[1]), box, mask))
        out.sort(key=lambda x: x[0])
        return [(b, m) for _, b, m in out]


def _hist(pixels: npt.NDArray[np.uint8]) -> F64:
    """An L2-normalised 8×4 hue/saturation histogram plus a 4-bin value histogram."""
    import cv2

    hsv = cv2.cvtColor(pixels.reshape(-1, 1, 3), cv2.COLOR_RGB2HSV).reshape(-1, 3)
    hs = np.histogram2d(hsv[:, 0], hsv[:, 1], bins=(8, 4), range=((0, 180), (0, 256)))[0]
    val = np.histogram(hsv[:, 2], bins=4, range=(0, 256))[0]
    vec = np.concatenate([hs.ravel(), val]).astype(float)
    n = float(np.linalg.norm(vec))
    return vec / n if n > 0 else vec


class ColorEmbedder:
    """Colour histograms of people's pixels as DeepSORT appearance features."""

    def embed(
        self, rgb: npt.NDArray[np.uint8], boxes: Sequence[Box], masks: Sequence[Mask | None] = ()
    ) -> list[F64]:
        out = []
        for k, (u0, v0, u1, v1) in enumerate(boxes):
            m = masks[k] if k < len(masks) else None
            if m is not None and m.any():
                pixels = rgb[m]
            else:
                pixels = rgb[
                    int(v0) : max(int(v1), int(v0) + 1), int(u0) : max(int(u1), int(u0) + 1)
                ]
            out.append(_hist(np.ascontiguousarray(pixels, dtype=np.uint8)))
        return out
