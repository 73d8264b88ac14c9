"""Object detection backends behind one interface, and language-free 3D localisation."""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, replace
from typing import Protocol

import numpy as np
import numpy.typing as npt

from hltl.errors import PerceptionError
from hltl.perception.carve import carve, hidden_share
from hltl.perception.detection import (
    BASE_CLEARANCE,
    MIN_PIXELS,
    DepthBackend,
    Detection,
    Mask,
    box_of,
    support_planes,
)
from hltl.perception.frames import Camera, Frame
from hltl.perception.geometry import Cylinder, backproject, fit_cylinder
from hltl.perception.learned import SIZES, LearnedBackend
from hltl.world.scene import Scene

# an object of known size with more than this share of its silhouette hidden (behind something
# nearer, or outside the image) is placed by carving (hltl.perception.carve)
PARTLY = 0.1
# a partly hidden object whose axis the frame leaves more uncertain than this (m) is not reported
MAX_SPREAD = 0.01


class ObjectBackend(Protocol):
    """Turns a frame into detections; ``planes`` are the support heights it found in the last
    frame (empty when it does not look for them), ``doubts`` what it saw there but could not
    decide (reported by the observation as ambiguous, never guessed)."""

    name: str
    planes: list[float]
    doubts: list[str]

    def detect(self, frame: Frame, camera: Camera) -> list[Detection]: ...


class SegmentationBackend:
    """Masks straight from the segmentation render (exact in 2D)."""

    name = "segmentation"

    def __init__(self, scene: Scene | None = None) -> None:
        self.scene = scene
        self.planes: list[float] = []
        self.doubts: list[str] = []

    def detect(self, frame: Frame, camera: Camera) -> list[Detection]:
        if frame.seg is None:
            raise PerceptionError(
                f"frame {frame.index}: the segmentation backend needs seg/ images; this source "
                "has none (use --backend depth-clusters)"
            )
        # support heights (tables, floor) from every 4th pixel: an object whose foot is hidden
        # still stands on the plane just below what is seen of it
        sub = np.zeros(frame.depth.shape, dtype=bool)
        sub[::4, ::4] = True
        pts = backproject(frame.depth, sub, camera)
        self.planes = support_planes(pts[:, 2]) if len(pts) else []
        out: list[Detection] = []
        ids, counts = np.unique(frame.seg, return_counts=True)
        for sid, n in zip(ids.tolist(), counts.tolist(), strict=True):
            seg = camera.segments.get(int(sid))
            if seg is None or seg.kind not in ("object", "human") or n < MIN_PIXELS:
                continue
            mask = frame.seg == sid
            out.append(Detection(seg.kind, seg.id, mask, 1.0, box_of(mask), exact=True))
        return out


class DepthClusterBackend(DepthBackend):
    """Objects and people from depth alone: remove the support plane, split at depth edges."""

    name = "depth-clusters"

    def __init__(
        self, scene: Scene | None = None, edge: float = 0.03, colour: float = 24.0
    ) -> None:
        super().__init__(scene, edge)
        self.colour = colour

    def detect(self, frame: Frame, camera: Camera) -> list[Detection]:
        from scipy import ndimage

        depth = frame.depth
        view = self.view(depth, camera)
        valid, pts, z = view.valid, view.points, view.z
        planes = support_planes(z[valid])
        off_plane = valid & (z > 0.015)
        for h in planes:
            off_plane &= np.abs(z - h) > 0.015
        # split at depth edges: neighbours farther apart than ``edge`` (relative to range)
        above = off_plane & ~view.edges
        self.planes = planes
        colour_edge = np.zeros(depth.shape, dtype=bool)
        if self.colour > 0:
            rgb = frame.rgb.astype(np.int16)
            colour_edge[:, 1:] = np.abs(np.diff(rgb, axis=1)).max(axis=2) > self.colour
            colour_edge[1:, :] |= np.abs(np.diff(rgb, axis=0)).max(axis=2) > self.colour
        labels, n = ndimage.label(above)
        sizes = np.bincount(labels.ravel(), minlength=n + 1)
        out: list[Detection] = []
        for k, sl in enumerate(ndimage.find_objects(labels), start=1):
            if sl is None or sizes[k] < MIN_PIXELS:
                continue
            local = labels[sl] == k  # work inside the region's box: thousands of tiny regions
            p = pts[sl][local]
            span = np.ptp(p, axis=0)
            if span[2] > 0.7 and max(span[0], span[1]) < 0.9:  # person-tall, person-wide
                out.append(self._detection("human", "person", sl, local, labels.shape))
            elif _object_sized(span):
                if label := self._nearest(p):
                    out.append(self._detection("object", label, sl, local, labels.shape))
            elif self.colour > 0:
                # a region too big for an object may be one standing against an arm's base or
                # a person at the same depth: split it at colour edges (shading across one
                # surface changes slowly) and keep the object-sized parts standing on a plane
                parts, _ = ndimage.label(local & ~colour_edge[sl])
                for j, psl in enumerate(ndimage.find_objects(parts), start=1):
                    if psl is None:
                        continue
                    part = np.zeros(local.shape, dtype=bool)
                    part[psl] = parts[psl] == j
                    if int(part.sum()) < MIN_PIXELS:
                        continue
                    q = pts[sl][part]
                    zmin = float(q[:, 2].min())
                    standing = any(-0.01 <= zmin - h <= 0.03 for h in planes)
                    label = self._nearest(q) if standing else ""
                    if label and _object_sized(np.ptp(q, axis=0)):
                        out.append(self._detection("object", label, sl, part, labels.shape))
        return out

    @staticmethod
    def _detection(
        kind: str, label: str, sl: tuple[slice, ...], local: Mask, shape: tuple[int, ...]
    ) -> Detection:
        mask = np.zeros(shape, dtype=bool)
        mask[sl] = local
        score = float(min(1.0, local.sum() / 200.0))
        return Detection(kind, label, mask, score, box_of(mask))

    def _nearest(self, points: npt.NDArray[np.float64]) -> str:
        """The category of the registered object this cluster is near: within 0.3 m on the
        floor plan, with the registered (grasp) height inside the cluster's height range
        give or take 10 cm — a person's legs below the table are near an object on the plan,
        not in height — and no larger than the category's known cylinder (+3 cm)."""
        if self.scene is None or not self.scene.objects:
            return "object"
        c = points.mean(axis=0)
        if any(
            math.hypot(r.base[0] - c[0], r.base[1] - c[1]) < BASE_CLEARANCE
            for r in self.scene.robots
        ):
            return ""  # a piece of an arm's base (nothing stands there): not an object
        lo, hi = float(points[:, 2].min()) - 0.1, float(points[:, 2].max()) + 0.1
        span = np.ptp(points, axis=0)
        best, label = 0.3, "object"
        for o in self.scene.objects:
            d = float(np.hypot(o.position[0] - c[0], o.position[1] - c[1]))
            if d >= best or not lo <= o.position[2] <= hi:
                continue
            size = size_prior(None, o.category)
            # bigger than the object can be: a link of an arm or a hand near it, not the object
            if size is not None and (
                max(span[0], span[1]) > 2 * size[0] + 0.03 or span[2] > size[1] + 0.03
            ):
                continue
            best, label = d, o.category
        return label


def _object_sized(span: npt.NDArray[np.float64]) -> bool:
    return bool(span[0] < 0.3 and span[1] < 0.3 and span[2] < 0.4)


def _open_vocab(scene: Scene | None) -> ObjectBackend:
    """Grounding DINO / OWL-ViT from the local weights ``$HLTL_OPEN_VOCAB_WEIGHTS`` names
    (imported here: it needs transformers, an optional extra)."""
    from hltl.perception.openvocab import OpenVocabBackend  # why: an optional extra's backend

    return OpenVocabBackend(scene)


BACKENDS: dict[str, Callable[[Scene | None], ObjectBackend]] = {
    "segmentation": SegmentationBackend,
    "depth-clusters": DepthClusterBackend,
    "learned": LearnedBackend,
    "open-vocab": _open_vocab,
}


def make_backend(name: str, scene: Scene | None = None) -> ObjectBackend:
    """The object backend called ``name``.

    Raises:
        ValueError: unknown name.
    """
    try:
        factory = BACKENDS[name]
    except KeyError:
        raise ValueError(
            f"unknown object backend {name!r}; expected one of {', '.join(BACKENDS)}"
        ) from None
    return factory(scene)


@dataclass(frozen=True, slots=True)
class Located:
    """A detection placed in 3D."""

    detection: Detection
    cylinder: Cylinder
    pixels: int
    spread: float = 0.0  # a partly hidden object: how far its axis may be from the estimate (m)


def size_prior(scene: Scene | None, label: str) -> tuple[float, float] | None:
    """(radius, height) of the object a label names, when its category has a known cylinder
    (:data:`hltl.perception.learned.SIZES`: the motion layer's grasp model where it has one,
    else the size the 3D simulator renders the category at): a scene id names its object's
    category, any other label is taken as a category. None when unknown."""

    category = label
    if scene is not None:
        for o in scene.objects:
            if o.id == label:
                category = o.category
                break
    return SIZES.get(category.lower())


def localize(
    frame: Frame,
    camera: Camera,
    detections: Sequence[Detection],
    planes: Sequence[float] = (),
    scene: Scene | None = None,
    priors: bool = True,
    max_spread: float | None = MAX_SPREAD,
) -> list[Located]:
    """Back-project each object detection and fit its cylinder (people are skipped here).
    ``planes`` are support heights: an object stands on the highest one just below its lowest
    visible point (a backend that cut the plane off also cut the object's foot). With
    ``priors``, a detection whose label names a known category (:func:`size_prior`) is fitted
    with that radius and height."""
    out: list[Located] = []
    view = (float(camera.pose[0, 3]), float(camera.pose[1, 3]))
    for det in detections:
        if det.kind != "object":
            continue
        pts = backproject(frame.depth, det.mask, camera)
        floor = None
        if len(pts):
            zmin = float(pts[:, 2].min())
            # a foot hidden behind something in front is a few cm, not the floor a table away
            below = [h for h in planes if zmin - 0.15 <= h <= zmin + 0.005]
            floor = max(below) if below else None
        size = size_prior(scene, det.label) if priors else None
        cyl = fit_cylinder(pts, floor, size, view)
        if cyl is None:
            continue
        spread = 0.0
        if size is not None and hidden_share(frame.depth, camera, cyl.center, *size) > PARTLY:
            # partly hidden: the axis from what is seen and what is seen past it
            seen = det.mask & (frame.depth > 0)
            bottom = cyl.center[2] - size[1] / 2
            c = carve(frame.depth, seen, pts, camera, size[0], bottom, size[1], cyl.center[:2])
            if c is None:
                spread = math.inf
            else:
                cyl = replace(cyl, center=(*c.centre, cyl.center[2]))
                spread = c.spread
        if max_spread is None or spread <= max_spread:
            out.append(Located(det, cyl, len(pts), spread))
    return out
