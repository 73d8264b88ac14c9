"""2D detections (what every object backend returns) and the support planes they stand on."""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import numpy.typing as npt

from hltl.perception.frames import Camera
from hltl.perception.geometry import backproject
from hltl.world.scene import Scene

Mask = npt.NDArray[np.bool_]
MIN_PIXELS = 15  # fewer visible pixels than this: the object counts as not seen
# a cluster whose points centre this close to a registered arm's base (on the floor plan) is a
# piece of the base: the bases here are 6–8 cm in radius and nothing can stand inside them
BASE_CLEARANCE = 0.09


@dataclass(frozen=True, slots=True)
class Detection:
    """One 2D detection.

    Attributes:
        kind: ``object`` or ``human``.
        label: what the backend calls it (a scene id for ``segmentation``).
        mask: H×W boolean mask.
        score: the backend's confidence in [0, 1].
        box: (u0, v0, u1, v1) pixel box, inclusive-exclusive.
        exact: the label is the scene id of what the pixels show (the segmentation render);
            otherwise it is a category, matched to scene objects by fusion.
    """

    kind: str
    label: str
    mask: Mask
    score: float
    box: tuple[int, int, int, int]
    exact: bool = False


def box_of(mask: Mask) -> tuple[int, int, int, int]:
    v, u = np.nonzero(mask)
    return (int(u.min()), int(v.min()), int(u.max()) + 1, int(v.max()) + 1)


def support_planes(z: npt.NDArray[np.float64], share: float = 0.04) -> list[float]:
    """Heights of horizontal planes things stand on: 1 cm bins of the points' heights holding at
    least ``share`` of them (the floor, tables), each refined to its points' median."""
    if len(z) == 0:
        return []
    lo, hi = float(z.min()), float(z.max())
    bins = np.arange(lo, hi + 0.02, 0.01)
    counts, edges = np.histogram(z, bins=bins)
    out: list[float] = []
    for i in np.flatnonzero(counts >= share * len(z)):
        sel = (z >= edges[i]) & (z < edges[i + 1])
        h = float(np.median(z[sel]))
        if not out or abs(h - out[-1]) > 0.02:
            out.append(h)
    return out


def world_points(depth: npt.NDArray[np.float32], camera: Camera) -> npt.NDArray[np.float64]:
    """H×W×3 world point of every pixel (zeros where the depth has no return)."""
    valid = depth > 0
    pts = np.zeros((*depth.shape, 3))
    pts[valid] = backproject(depth, valid, camera)
    return pts


def depth_edges(depth: npt.NDArray[np.float32], edge: float) -> Mask:
    """Pixels whose left or upper neighbour is farther away than ``edge`` × their range."""
    jump = np.zeros(depth.shape, dtype=bool)
    jump[:, 1:] |= np.abs(np.diff(depth, axis=1)) > edge * depth[:, 1:]
    jump[1:, :] |= np.abs(np.diff(depth, axis=0)) > edge * depth[1:, :]
    return jump


@dataclass(frozen=True, slots=True)
class DepthView:
    """What a backend working from depth sees of a frame."""

    valid: Mask  # pixels with a depth return
    points: npt.NDArray[np.float64]  # H×W×3 world point of each pixel
    edges: Mask  # depth edges (:func:`depth_edges`)

    @property
    def z(self) -> npt.NDArray[np.float64]:
        """Each pixel's height in the world."""
        return self.points[:, :, 2]


class DepthBackend:
    """The set-up the backends that work from depth share: the scene (its registered arms and
    objects), the depth-edge threshold that splits regions, and the support planes of the last
    frame (:class:`hltl.perception.objects.ObjectBackend`'s ``planes``)."""

    def __init__(self, scene: Scene | None = None, edge: float = 0.03) -> None:
        self.scene = scene
        self.edge = edge
        self.planes: list[float] = []
        self.doubts: list[str] = []  # the last frame's regions the backend could not decide

    def view(self, frame_depth: npt.NDArray[np.float32], camera: Camera) -> DepthView:
        """The frame's depth as world points and depth edges."""
        return DepthView(
            frame_depth > 0, world_points(frame_depth, camera), depth_edges(frame_depth, self.edge)
        )


def read_weights(path: Path, what: str) -> tuple[dict[str, Any], dict[str, npt.NDArray[Any]]]:
    """(meta, arrays) of a weights file: float arrays plus a JSON ``meta`` entry, nothing
    unpickled.

    Raises:
        FileNotFoundError / ValueError: the file is missing or not ``what``.
    """
    if not path.is_file():
        raise FileNotFoundError(f"{path}: no such weights file")
    try:
        with np.load(path, allow_pickle=False) as data:
            meta = json.loads(str(data["meta"]))
            state = {k: np.asarray(data[k]) for k in data.files if k != "meta"}
    except (OSError, ValueError, KeyError) as exc:
        raise ValueError(f"{path}: not {what} ({exc})") from exc
    return meta, state
