"""The learned object backend: a small segmentation network trained on the project's own renders."""

from __future__ import annotations

import json
import math
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import numpy.typing as npt

from hltl.errors import BackendUnavailableError
from hltl.motion.grasps import CATEGORY_CYLINDERS
from hltl.perception.detection import (
    BASE_CLEARANCE,
    MIN_PIXELS,
    DepthBackend,
    Detection,
    Mask,
    box_of,
    read_weights,
    support_planes,
)
from hltl.perception.frames import Camera, Frame
from hltl.perception.geometry import backproject, top_height
from hltl.perception.ownbody import OWN_SHARE, OwnBodies
from hltl.world.scene import Scene

CLASSES = ("background", "person", "bottle", "chips", "cup", "mug", "can", "apple", "box", "book")
SHIPPED = Path(__file__).parent / "data" / "object_segmenter.npz"
WIDTHS = (12, 24, 48)  # channels of the three encoder stages
CHANNELS = 6  # r, g, b, depth, world height, valid
F32 = npt.NDArray[np.float32]
F64 = npt.NDArray[np.float64]
MIN_CONFIDENCE = 0.5  # pixels the network is less sure of are left out
# (radius, height) of each category's cylinder as the 3D simulator renders it (hltl.sim3d.model;
# a test keeps the two equal): what the network was trained to see. The renderer takes the
# motion layer's grasp cylinders where it has one, its own looks for the rest.
SIZES: dict[str, tuple[float, float]] = {
    **CATEGORY_CYLINDERS,
    "mug": (0.04, 0.10),
    "apple": (0.04, 0.08),
    "box": (0.06, 0.12),
    "book": (0.07, 0.04),
}
# Categories of one colour that differ only in size (the red ones: 8, 10 and 12 cm tall): the
# network confuses them (validation IoU 0.33-0.37 each), so their pixels are segmented as one
# class and each object is named by its measured height (:meth:`LearnedBackend._name`).
CONFUSED = ("apple", "mug", "can")
# the size gate of boxes and books stays loose (as before the sizes above were used): with
# their rendered sizes the gate dropped 6 more of 61 held-out boxes (3 fewer found), nothing gained
LOOSE: dict[str, tuple[float, float]] = {c: (0.15, 0.3) for c in ("box", "book")}
# a support plane holds at least this share of the frame's points: a table seen from across
# the room is ~1-3 % of them (the default cameras of the 1-, 2- and 4-arm cells; at 4 % no
# table was found there and nothing on it counted as standing)
PLANE_SHARE = 0.01
# beyond this range (m) the network also looks at full resolution (LearnedBackend._probabilities)
FAR = 2.5
ZOOM_PAD = 16  # pixels of context around the far band
SPLIT_HEIGHT = 0.03  # each of two objects split apart is at least this tall (m)
STRAY = 0.2  # at most this share of a region's pixels are dropped as strays around an object
HEIGHT_SIGMA = 0.006  # spread of a measured height about the true one when the top is seen (m)
HIDDEN_TOP = 0.01  # chance that a shorter measured height is a taller object with its top hidden
# an object region near an arm's base whose surrounding ring continues the same surface over
# this share is a piece of the base (LearnedBackend._continued; chosen on tuning clutter seed
# 5000, where 42 of 52 false detections lay on arms' bases)
CONTINUED = 0.4
NEAR_BASE = 0.25  # m: where a piece of an arm's base or first link can be taken for an object
# a table-top sized "person" standing on a table is relabelled as the object class the network
# gives at least this mean probability over it (LearnedBackend._retest_person)
RETEST_MIN = 0.1


def _torch() -> Any:
    try:
        import torch
    except ImportError:
        raise BackendUnavailableError(
            "the learned object backend needs torch: pip install 'hltl[predict]'"
        ) from None
    return torch


def inputs(frame: Frame, camera: Camera, height: F64 | None = None) -> F32:
    """The network's input (CHANNELS × H/2 × W/2): colour averaged over 2×2 pixels, the depth
    and world height of each block's top-left pixel (exact values, not mixed across an edge).
    ``height``: every pixel's world height, when the caller has it already."""
    h, w = frame.depth.shape
    h2, w2 = h // 2, w // 2
    rgb = frame.rgb[: 2 * h2, : 2 * w2].astype(np.float32) / 255.0
    rgb = rgb.reshape(h2, 2, w2, 2, 3).mean(axis=(1, 3))
    sub = np.zeros(frame.depth.shape, dtype=bool)
    sub[: 2 * h2 : 2, : 2 * w2 : 2] = True
    depth = frame.depth[: 2 * h2 : 2, : 2 * w2 : 2].astype(np.float32)
    valid = depth > 0
    if height is not None:
        z = height[: 2 * h2 : 2, : 2 * w2 : 2].astype(np.float32)
    else:
        z = np.zeros((h2, w2), np.float32)
        sub &= frame.depth > 0
        z[valid] = backproject(frame.depth, sub, camera)[:, 2]
    out = np.empty((CHANNELS, h2, w2), np.float32)
    out[:3] = rgb.transpose(2, 0, 1) - 0.5
    out[3] = np.clip(depth, 0.0, 8.0) / 4.0 - 0.5
    out[4] = np.clip(z, -1.0, 2.5)
    out[5] = valid
    return out


def zoomed_inputs(rgb: npt.NDArray[np.uint8], depth: npt.NDArray[np.float32], z: F64) -> F32:
    """The network's input at full resolution with the depth halved: what a camera at half the
    distance would see at half resolution (colour of each pixel, its depth / 2, its world
    height — heights do not change with the distance)."""
    out = np.empty((CHANNELS, *depth.shape), np.float32)
    out[:3] = rgb.astype(np.float32).transpose(2, 0, 1) / 255.0 - 0.5
    out[3] = np.clip(depth.astype(np.float32) / 2.0, 0.0, 8.0) / 4.0 - 0.5
    out[4] = np.clip(z, -1.0, 2.5)
    out[5] = depth > 0
    return out


def _build(torch: Any) -> Any:
    """Half resolution → three stages down to 1/8 (dilated at the bottom for context: an object
    is told from a robot link by what is around it) → two skip connections back up; the
    full-width layers are thin because they cost the most on a CPU."""
    nn = torch.nn
    a, b, c = WIDTHS

    def conv(i: int, o: int, stride: int = 1, dil: int = 1) -> Any:
        return nn.Sequential(
            nn.Conv2d(i, o, 3, stride=stride, padding=dil, dilation=dil), nn.ReLU(inplace=True)
        )

    class Net(nn.Module):  # type: ignore[name-defined,misc]
        def __init__(self) -> None:
            super().__init__()
            self.e1 = conv(CHANNELS, a)
            self.e2 = nn.Sequential(conv(a, b, 2), conv(b, b))
            self.e3 = nn.Sequential(conv(b, c, 2), conv(c, c, dil=2), conv(c, c, dil=4))
            self.r3 = nn.Sequential(nn.Conv2d(c, a, 1), nn.ReLU(inplace=True))
            self.d2 = conv(a + b, b)
            self.head = nn.Conv2d(b + a, len(CLASSES), 1)

        def forward(self, x: Any) -> Any:
            f = torch.nn.functional
            x1 = self.e1(x)
            x2 = self.e2(x1)
            x3 = self.r3(self.e3(x2))
            y2 = self.d2(torch.cat([f.interpolate(x3, size=x2.shape[2:]), x2], dim=1))
            return self.head(torch.cat([f.interpolate(y2, size=x1.shape[2:]), x1], dim=1))

    return Net()


class SegmenterModel:
    """Loaded weights: :meth:`probabilities` of each class per half-resolution pixel."""

    def __init__(self, state: dict[str, npt.NDArray[Any]], meta: dict[str, Any]) -> None:
        torch = _torch()
        self._torch = torch
        self.meta = meta
        self.net = _build(torch)
        self.net.load_state_dict(
            {k: torch.from_numpy(np.asarray(v, dtype=np.float32)) for k, v in state.items()}
        )
        self.net.eval()

    def probabilities(self, x: F32) -> F32:
        """(classes × h × w) softmax of one input (CHANNELS × h × w)."""
        torch = self._torch
        with torch.no_grad():
            logits = self.net(torch.from_numpy(x[None]))
            out: F32 = torch.softmax(logits, dim=1)[0].numpy()
        return out


def load_segmenter(path: str | Path | None = None) -> SegmenterModel:
    """Load weights written by :func:`train` (default: the shipped file).

    Raises:
        BackendUnavailableError: torch is missing.
        FileNotFoundError / ValueError: the file is missing or not segmenter weights.
    """
    p = SHIPPED if path is None else Path(path)
    meta, state = read_weights(p, "an object segmenter weights file")
    if tuple(meta.get("classes", ())) != CLASSES or tuple(meta.get("widths", ())) != WIDTHS:
        raise ValueError(f"{p}: weights were trained for other classes or widths")
    try:
        return SegmenterModel(state, meta)
    except RuntimeError as exc:
        raise ValueError(f"{p}: weights do not fit this model ({exc})") from exc


_MODELS: dict[Path, SegmenterModel] = {}


def _shared(path: Path) -> SegmenterModel:
    """One loaded model per weights file for the process (backends are built per frame
    source; loading costs more than a frame)."""
    if path not in _MODELS:
        _MODELS[path] = load_segmenter(path)
    return _MODELS[path]


@dataclass(frozen=True, slots=True)
class PixelProbabilities:
    """Class probabilities over a frame: ``half`` (classes × H/2 × W/2, each value covering its
    2×2 block) and, where ``box`` (v0, v1, u0, u1) says, ``zoom`` (classes × the box, full
    resolution) for the box's pixels ``far`` marks."""

    half: F32
    box: tuple[int, int, int, int] | None = None
    zoom: F32 | None = None
    far: Mask | None = None

    def _merged(self, p: F32) -> tuple[npt.NDArray[np.int64], F32]:
        """Class and confidence of each pixel of ``p``, the confused categories counted as one
        class (their summed probability decides; the class is the first of them)."""
        group = [CLASSES.index(c) for c in CONFUSED]
        merged = p.copy()
        merged[group[0]] = p[group].sum(axis=0)
        merged[group[1:]] = 0.0
        return merged.argmax(axis=0), merged.max(axis=0)

    def labels(self, shape: tuple[int, ...]) -> tuple[npt.NDArray[np.int64], F32]:
        """(class, confidence) of every pixel of a frame of ``shape``; a last odd row or column
        the half-resolution pass did not cover is background."""
        cls, conf = self._merged(self.half)
        full = np.zeros(shape[:2], dtype=np.int64)
        fconf = np.ones(shape[:2], dtype=np.float32)
        h2, w2 = cls.shape
        full[: 2 * h2, : 2 * w2] = np.repeat(np.repeat(cls, 2, 0), 2, 1)
        fconf[: 2 * h2, : 2 * w2] = np.repeat(np.repeat(conf, 2, 0), 2, 1)
        if self.box is not None and self.zoom is not None and self.far is not None:
            v0, v1, u0, u1 = self.box
            zc, zf = self._merged(self.zoom)
            full[v0:v1, u0:u1] = np.where(self.far, zc, full[v0:v1, u0:u1])
            fconf[v0:v1, u0:u1] = np.where(self.far, zf, fconf[v0:v1, u0:u1])
        return full, fconf

    def mean(self, k: int, mask: Mask) -> float:
        """Mean probability of class ``k`` over the pixels of ``mask``."""
        v, u = np.nonzero(mask)
        if len(v) == 0:
            return 0.0
        vals = self.half[k][
            np.minimum(v // 2, self.half.shape[1] - 1), np.minimum(u // 2, self.half.shape[2] - 1)
        ]
        if self.box is not None and self.zoom is not None and self.far is not None:
            v0, v1, u0, u1 = self.box
            inside = (v >= v0) & (v < v1) & (u >= u0) & (u < u1)
            vi, ui = v[inside] - v0, u[inside] - u0
            far = self.far[vi, ui]
            vals[np.flatnonzero(inside)[far]] = self.zoom[k][vi[far], ui[far]]
        return float(vals.mean())


class LearnedBackend(DepthBackend):
    """Objects (and people) from the trained segmenter; labels are categories."""

    name = "learned"

    def __init__(
        self, scene: Scene | None = None, weights: str | Path | None = None, edge: float = 0.03
    ) -> None:
        super().__init__(scene, edge)
        self.model = _shared(SHIPPED if weights is None else Path(weights))
        self._depth: npt.NDArray[np.float32] = np.zeros((0, 0), np.float32)  # the last frame's
        self.dropped = 0  # the last frame's object regions dropped as pieces of bigger surfaces
        self.bodies = OwnBodies(scene)
        self.own = 0  # the last frame's regions dropped as lying on an arm (its joint state)

    def detect(self, frame: Frame, camera: Camera) -> list[Detection]:
        from scipy import ndimage

        depth = frame.depth
        view = self.view(depth, camera)
        valid, pts, z = view.valid, view.points, view.z
        self.planes = support_planes(z[valid][::16], share=PLANE_SHARE)
        self._depth = depth
        prob = self.probabilities(frame, camera, z)
        full, fconf = prob.labels(depth.shape)
        group = [CLASSES.index(c) for c in CONFUSED]
        keep = valid & (full > 0) & (fconf >= MIN_CONFIDENCE)
        for p in self.planes:  # a table's pixels at an object's foot are not the object
            keep &= np.abs(z - p) > 0.01
        self.doubts = []
        self.dropped = 0
        self.own = 0
        arms = self.bodies.capsules(frame.joints)
        out: list[Detection] = []
        for k in np.unique(full[keep]).tolist():
            labels, _ = ndimage.label(keep & (full == k) & ~view.edges)
            # (slice, local mask) of each region big enough, worked on inside its box
            parts = [
                (sl, labels[sl] == i)
                for i, sl in enumerate(ndimage.find_objects(labels), start=1)
                if sl is not None
            ]
            parts = [(sl, m) for sl, m in parts if int(m.sum()) >= MIN_PIXELS]
            if CLASSES[k] == "person":
                for sl, m in parts:
                    mask = _full(depth.shape, sl, m)
                    if OwnBodies.share(pts[mask], arms) >= OWN_SHARE:
                        self.own += 1  # a link or the hand of an arm, placed by its joints
                        continue
                    label = self._retest_person(mask, pts, prob)
                    if label is None:  # table-top sized on a table, and no object class fits
                        continue
                    kind = "human" if label == "person" else "object"
                    score = float(fconf[mask].mean())
                    if kind == "object":
                        score = prob.mean(_class_of(label), mask)
                    out.append(Detection(kind, label, mask, score, box_of(mask)))
                continue
            cats = CONFUSED if k in group else (CLASSES[k],)
            for mask in self._objects(cats, parts, pts, depth.shape):
                if OwnBodies.share(pts[mask], arms) >= OWN_SHARE:
                    self.own += 1  # a gripper or a link's end, placed by the arm's joints
                    continue
                if (
                    self._near_base(pts[mask])
                    and self._continued(mask, depth, z, full) >= CONTINUED
                ):
                    self.dropped += 1  # a piece of an arm's base (or its first link)
                    continue
                label = cats[0] if len(cats) == 1 else self._name(cats, pts[mask], prob, mask)
                score = float(fconf[mask].mean())
                out.append(Detection("object", label, mask, score, box_of(mask)))
        return out

    def _near_base(self, q: F64) -> bool:
        """Are points ``q`` centred within :data:`NEAR_BASE` of a registered arm's base (on
        the floor plan)?"""
        if self.scene is None or len(q) == 0:
            return False
        c = q.mean(axis=0)
        return any(
            math.hypot(rb.base[0] - c[0], rb.base[1] - c[1]) < NEAR_BASE for rb in self.scene.robots
        )

    def _continued(
        self, mask: Mask, depth: npt.NDArray[np.float32], z: F64, full: npt.NDArray[np.int64]
    ) -> float:
        """The share of the ring of pixels around ``mask`` (2 pixels wide) where the surface
        goes on: a depth return within 3 % + 2 cm of the region's median depth, not on a support
        plane and not labelled an object. An object stands free — around it the view jumps to
        what is behind or in front, or meets the table it stands on — whereas a piece of an
        arm's base or of a person's leg that the network took for an object is surrounded by
        more of the same surface (docs/perception.md, "False detections")."""
        from scipy import ndimage

        sl = _grown(box_of(mask), 3, depth.shape)
        local = mask[sl]
        ring = ndimage.binary_dilation(local, iterations=2) & ~local
        if not ring.any():
            return 0.0
        here = float(np.median(depth[sl][local]))
        d, zz, lab = depth[sl][ring], z[sl][ring], full[sl][ring]
        on = (d > 0) & (np.abs(d - here) < 0.03 * here + 0.02) & (lab < 2)
        for p in self.planes:
            on &= np.abs(zz - p) >= 0.015
        return float(on.mean())

    def _retest_person(self, mask: Mask, pts: F64, prob: PixelProbabilities) -> str | None:
        """What a region the network calls ``person`` is: ``person`` unless it is table-top
        sized (no wider or taller than the largest category, +3 cm) and stands on a support
        plane above the lowest one (an object sits on a table, a person stands on the floor);
        then the object category the network gives most probability over it (at least
        :data:`RETEST_MIN`) when the region is plausible as that object; else None, and the
        region is reported in :attr:`doubts` (neither a person nor an object that fits)."""
        q = pts[mask]
        span = np.ptp(q, axis=0)
        r = max(LOOSE.get(c, SIZES[c])[0] for c in SIZES)
        hgt = max(LOOSE.get(c, SIZES[c])[1] for c in SIZES)
        if max(span[0], span[1]) > 2 * r + 0.03 or span[2] > hgt + 0.03 or len(self.planes) < 2:
            return "person"
        zmin = float(q[:, 2].min())
        below = [p for p in self.planes if p <= zmin + 0.01]
        if not below or max(below) <= self.planes[0] + 0.02 or zmin - max(below) > 0.12:
            return "person"  # on the floor, or not standing on anything
        if not (self._on_surface(mask, pts, max(below)) or self._foot_hidden(mask)):
            return "person"  # at the table's height but beyond its edge: a person behind it
        group = [CLASSES.index(c) for c in CONFUSED]
        scores: dict[str, float] = {}
        for k in range(2, len(CLASSES)):
            if k in group[1:]:
                continue
            cats = CONFUSED if k in group else (CLASSES[k],)
            scores[cats[0]] = sum(prob.mean(CLASSES.index(c), mask) for c in cats)
        for first in sorted(scores, key=lambda c: -scores[c]):
            if scores[first] < RETEST_MIN:
                break
            cats = CONFUSED if first == CONFUSED[0] else (first,)
            rc = max(LOOSE.get(c, SIZES[c])[0] for c in cats)
            hc = max(LOOSE.get(c, SIZES[c])[1] for c in cats)
            if self._plausible(q, rc, hc, mask):
                return cats[0] if len(cats) == 1 else self._name(cats, q, prob, mask)
        c = q.mean(axis=0)
        best = max(scores, key=lambda k: scores[k])
        self.doubts.append(
            f"person or object: {int(mask.sum())} px at ({c[0]:.2f}, {c[1]:.2f}, {c[2]:.2f}) "
            f"stand on the surface at z = {max(below):.2f}, too small for a person; no object "
            f"fits (closest {best}, probability {scores[best]:.2f})"
        )
        return None

    def probabilities(self, frame: Frame, camera: Camera, z: F64) -> PixelProbabilities:
        """The network's class probabilities for ``frame``: on the half-resolution frame, and
        again at full resolution with the depth halved — the view of a camera at half the
        distance — over the box of the far pixels (:data:`FAR` and beyond) in the band where
        objects stand on the support planes: a cup 4 m away is a handful of half-resolution
        pixels, too few for the network (docs/perception.md)."""
        half = self.model.probabilities(inputs(frame, camera, z))
        box = self._far_box(frame.depth, z)
        if box is None:
            return PixelProbabilities(half)
        v0, v1, u0, u1 = box
        zoom = self.model.probabilities(
            zoomed_inputs(frame.rgb[v0:v1, u0:u1], frame.depth[v0:v1, u0:u1], z[v0:v1, u0:u1])
        )
        return PixelProbabilities(half, box, zoom, frame.depth[v0:v1, u0:u1] >= FAR)

    def _far_box(self, depth: npt.NDArray[np.float32], z: F64) -> tuple[int, int, int, int] | None:
        """(v0, v1, u0, u1): the box around the far pixels where objects can stand — up to the
        tallest category above a support plane, the lowest plane (the floor) left out when there
        are others — padded by :data:`ZOOM_PAD` pixels; None when there are none."""
        planes = self.planes[1:] if len(self.planes) > 1 else self.planes
        tallest = max(hgt for _, hgt in SIZES.values())
        band = np.zeros(depth.shape, dtype=bool)
        for p in planes:
            band |= (z > p + 0.01) & (z < p + tallest + 0.03)
        band &= depth >= FAR
        rows, cols = np.flatnonzero(band.any(axis=1)), np.flatnonzero(band.any(axis=0))
        if len(rows) == 0:
            return None
        h, w = depth.shape
        return (
            max(int(rows[0]) - ZOOM_PAD, 0),
            min(int(rows[-1]) + 1 + ZOOM_PAD, h),
            max(int(cols[0]) - ZOOM_PAD, 0),
            min(int(cols[-1]) + 1 + ZOOM_PAD, w),
        )

    def _objects(
        self,
        categories: Sequence[str],
        parts: list[tuple[tuple[slice, ...], Mask]],
        pts: F64,
        shape: tuple[int, ...],
    ) -> list[Mask]:
        """One class's regions as objects: fragments of one object (split by a highlight or
        something thin in front) merged — centres closer than the category's diameter — and
        what cannot be such an object dropped: wider or taller than its cylinder (+3 cm; the
        largest of ``categories``), not standing on a support plane (its lowest point more than
        12 cm above the plane below it, or below every plane), or centred on a registered arm's
        base."""
        r = max(LOOSE.get(c, SIZES[c])[0] for c in categories)
        hgt = max(LOOSE.get(c, SIZES[c])[1] for c in categories)
        clouds = [pts[sl][m] for sl, m in parts]
        centres = [c.mean(axis=0) for c in clouds]
        group = list(range(len(parts)))

        def root(i: int) -> int:
            while group[i] != i:
                i = group[i]
            return i

        for i in range(len(parts)):
            for j in range(i):
                if math.dist(centres[i][:2], centres[j][:2]) < 2 * r + 0.02:
                    group[root(i)] = root(j)
        out: list[Mask] = []
        for g in sorted({root(i) for i in range(len(parts))}):
            members = [i for i in range(len(parts)) if root(i) == g]
            # the merged fragments if they make a plausible object, else each fragment alone
            # (a piece of an arm's base next to the object must not sink it)
            tries = [members] if len(members) == 1 else [members] + [[i] for i in members]
            for group_ in tries:
                mask = np.zeros(shape, dtype=bool)
                for i in group_:
                    mask[parts[i][0]] |= parts[i][1]
                shaped = self._shaped(mask, pts, r, hgt)
                out += shaped
                if shaped and group_ is members:
                    break
        return out

    def _name(self, categories: Sequence[str], q: F64, prob: PixelProbabilities, mask: Mask) -> str:
        """The one of ``categories`` an object is: its measured height — its top surface
        (:func:`~hltl.perception.geometry.top_height`, unbiased by depth noise) above the support
        plane under it — against each category's, weighed with the network's mean probability
        over its pixels. A top can be hidden (the height then reads low) but an object cannot
        read taller than it is, so a category shorter than the measurement by more than 2 cm is
        out, one taller keeps a small chance (HIDDEN_TOP) and the network decides between
        those."""
        # the foot from the 1st percentile: with depth noise the lowest point of a few hundred
        # lies ~3 sigmas under the plane the object stands on (1.3 cm at 4.4 mm), and that
        # plane was missed for the floor under the table
        zmin = float(np.percentile(q[:, 2], 1))
        below = [p for p in self.planes if p <= zmin + 0.01]
        tall = top_height(q[:, 2]) - (max(below) if below else zmin)

        def score(c: str) -> float:
            net = prob.mean(CLASSES.index(c), mask)
            fit = math.exp(-0.5 * ((tall - SIZES[c][1]) / HEIGHT_SIGMA) ** 2)
            if tall < SIZES[c][1]:
                fit += HIDDEN_TOP
            return math.log(net + 1e-6) + math.log(fit + 1e-12)

        return max(categories, key=score)

    def _shaped(self, mask: Mask, pts: F64, r: float, hgt: float) -> list[Mask]:
        """The objects a region of one class is: itself if it is plausible (:meth:`_plausible`);
        else, when it is too wide, two objects side by side (touching in the image with no
        depth edge between them: 2-means on the floor plan, both halves plausible and at least
        :data:`SPLIT_HEIGHT` tall); else the one object left when stray pixels around it — a
        table's fringe, the edge of a link — are dropped (those farther than its radius + 2 cm
        from the median position; at most :data:`STRAY` of the region); else none."""
        q = pts[mask]
        if self._plausible(q, r, hgt, mask):
            return [mask]
        v, u = np.nonzero(mask)
        if max(np.ptp(q[:, 0]), np.ptp(q[:, 1])) > 2 * r + 0.03 and len(q) >= 2 * MIN_PIXELS:
            side = two_means(q[:, :2])
            halves = []
            for k in (False, True):
                sub = np.zeros_like(mask)
                sub[v[side == k], u[side == k]] = True
                qk = q[side == k]
                if (
                    len(qk) >= MIN_PIXELS
                    and np.ptp(qk[:, 2]) >= SPLIT_HEIGHT
                    and self._plausible(qk, r, hgt, sub)
                ):
                    halves.append(sub)
            if len(halves) == 2:
                return halves
        near = np.hypot(*(q[:, :2] - np.median(q[:, :2], axis=0)).T) <= r + 0.02
        if near.sum() >= (1.0 - STRAY) * len(q):
            sub = np.zeros_like(mask)
            sub[v[near], u[near]] = True
            if self._plausible(q[near], r, hgt, sub):
                return [sub]
        return []

    def _plausible(self, q: F64, r: float, hgt: float, mask: Mask | None = None) -> bool:
        """Can points ``q`` be one object of radius ``r`` and height ``hgt``: no wider or
        taller (+3 cm), standing on a support plane — its lowest point at most 12 cm above it,
        or, when something nearer hides its foot (:meth:`_foot_hidden`, needs ``mask``), its
        top at most the height (+3 cm) above it — and not centred on a registered arm's base."""
        span = np.ptp(q, axis=0)
        if max(span[0], span[1]) > 2 * r + 0.03 or span[2] > hgt + 0.03:
            return False
        zmin = float(q[:, 2].min())
        below = [p for p in self.planes if p <= zmin + 0.01]
        if not below:
            return False
        if zmin - max(below) > 0.12 and not (
            mask is not None
            and float(q[:, 2].max()) - max(below) <= hgt + 0.03
            and self._foot_hidden(mask)
        ):
            return False
        c = q.mean(axis=0)
        return self.scene is None or all(
            math.hypot(rb.base[0] - c[0], rb.base[1] - c[1]) >= BASE_CLEARANCE
            for rb in self.scene.robots
        )

    def _on_surface(self, mask: Mask, pts: F64, plane: float) -> bool:
        """Does ``mask`` touch the surface at height ``plane``: in at least half of its
        columns, a point of that surface within 6 rows below its lowest pixel lies within 5 cm
        of that pixel's point (something behind a table's edge is at the table's height in the
        image, but its foot is not on the table)."""
        v, u = np.nonzero(mask)
        if len(v) == 0:
            return False
        h = mask.shape[0]
        bottom = np.full(mask.shape[1], -1)
        np.maximum.at(bottom, u, v)
        cols = np.flatnonzero(bottom >= 0)
        touch = 0
        for c in cols.tolist():
            b = int(bottom[c])
            below = pts[b + 1 : min(b + 7, h), c]
            on = below[np.abs(below[:, 2] - plane) < 0.015]
            if len(on) and float(np.min(np.linalg.norm(on - pts[b, c], axis=1))) <= 0.05:
                touch += 1
        return touch >= 0.5 * len(cols)

    def _foot_hidden(self, mask: Mask) -> bool:
        """Is the bottom of ``mask`` hidden by something nearer: in at least half of its
        columns, the pixel 3 rows below its lowest one is at least 5 cm nearer the camera."""
        depth = self._depth
        v, u = np.nonzero(mask)
        if len(v) == 0:
            return False
        bottom = np.full(depth.shape[1], -1)
        np.maximum.at(bottom, u, v)
        cols = np.flatnonzero((bottom >= 0) & (bottom + 3 < depth.shape[0]))
        if len(cols) == 0:
            return False
        here = depth[bottom[cols], cols]
        below = depth[bottom[cols] + 3, cols]
        return bool(np.mean((below > 0) & (below < here - 0.05)) >= 0.5)


def two_means(xy: F64, iterations: int = 10) -> npt.NDArray[np.bool_]:
    """Split points (n × 2) in two by 2-means, started from the two points farthest apart
    along the points' main axis; True marks the second group."""
    c = xy.mean(axis=0)
    d = xy - c
    axis = np.linalg.svd(d, full_matrices=False)[2][0]
    t = d @ axis
    a, b = xy[int(np.argmin(t))], xy[int(np.argmax(t))]
    side = np.zeros(len(xy), dtype=bool)
    for _ in range(iterations):
        side = np.sum((xy - b) ** 2, axis=1) < np.sum((xy - a) ** 2, axis=1)
        if side.all() or not side.any():
            break
        a2, b2 = xy[~side].mean(axis=0), xy[side].mean(axis=0)
        if np.allclose(a2, a) and np.allclose(b2, b):
            break
        a, b = a2, b2
    return side


def _class_of(label: str) -> int:
    """The network class a category is segmented as (the confused ones: the first of them)."""
    return CLASSES.index(CONFUSED[0] if label in CONFUSED else label)


def _grown(box: tuple[int, int, int, int], pad: int, shape: tuple[int, ...]) -> tuple[slice, slice]:
    u0, v0, u1, v1 = box
    return (
        slice(max(v0 - pad, 0), min(v1 + pad, shape[0])),
        slice(max(u0 - pad, 0), min(u1 + pad, shape[1])),
    )


def _full(shape: tuple[int, ...], sl: tuple[slice, ...], local: Mask) -> Mask:
    mask = np.zeros(shape, dtype=bool)
    mask[sl] = local
    return mask


# -- training --------------------------------------------------------------------------------


@dataclass(frozen=True, slots=True)
class TrainResult:
    path: Path
    images: int
    epochs: int
    train_loss: float
    val_iou: dict[str, float]  # per class, on the validation images
    seconds: float


def downsample_labels(labels: npt.NDArray[np.uint8]) -> npt.NDArray[np.int64]:
    """Class of each 2×2 block: its top-left pixel (the pixel whose depth the input carries)."""
    h2, w2 = labels.shape[0] // 2, labels.shape[1] // 2
    out: npt.NDArray[np.int64] = labels[: 2 * h2 : 2, : 2 * w2 : 2].astype(np.int64)
    return out


def train(
    samples: Sequence[tuple[F32, npt.NDArray[np.int64]]],
    out: str | Path,
    *,
    seed: int = 0,
    epochs: int = 30,
    crop: int = 112,
    command: str = "",
    progress: Callable[[str, float], None] | None = None,
) -> TrainResult:
    """Train on (input, half-resolution labels) pairs (10 % held out for validation) with
    random crops centred on an object pixel two times in three, horizontal flips, and
    cross-entropy weighted toward the rare object classes; write the weights to ``out``."""
    torch = _torch()
    t0 = time.perf_counter()
    torch.manual_seed(seed)
    rng = np.random.default_rng(seed)
    n = len(samples)
    order = rng.permutation(n)
    n_val = max(1, n // 10) if n > 1 else 0
    val_idx, tr_idx = order[:n_val], order[n_val:]
    if len(tr_idx) == 0:
        tr_idx = order
    net = _build(torch)
    opt = torch.optim.Adam(net.parameters(), lr=3e-3)
    steps_per_epoch = max(1, len(tr_idx) // 8)
    sched = torch.optim.lr_scheduler.OneCycleLR(
        opt, max_lr=3e-3, total_steps=epochs * steps_per_epoch
    )
    weight = torch.tensor([1.0, 2.0] + [6.0] * (len(CLASSES) - 2))
    loss_fn = torch.nn.CrossEntropyLoss(weight=weight)

    def crop_of(i: int) -> tuple[F32, npt.NDArray[np.int64]]:
        x, y = samples[i]
        h, w = y.shape
        c = min(crop, h, w)
        objs = np.argwhere(y >= 2)
        if len(objs) and rng.random() < 2 / 3:
            cv, cu = objs[rng.integers(len(objs))]
            v0 = int(np.clip(cv - c // 2 + rng.integers(-c // 4, c // 4 + 1), 0, h - c))
            u0 = int(np.clip(cu - c // 2 + rng.integers(-c // 4, c // 4 + 1), 0, w - c))
        else:
            v0, u0 = int(rng.integers(0, h - c + 1)), int(rng.integers(0, w - c + 1))
        xs, ys = x[:, v0 : v0 + c, u0 : u0 + c], y[v0 : v0 + c, u0 : u0 + c]
        if rng.random() < 0.5:
            xs, ys = xs[:, :, ::-1], ys[:, ::-1]
        # colour jitter: brightness and contrast of the RGB channels (lighting varies)
        xs = xs.copy()
        xs[:3] = (xs[:3] + 0.5) * rng.uniform(0.8, 1.2) + rng.uniform(-0.08, 0.08) - 0.5
        return xs, np.ascontiguousarray(ys)

    train_loss = math.nan
    for epoch in range(epochs):
        net.train()
        perm = rng.permutation(tr_idx)
        total, count = 0.0, 0
        for s in range(steps_per_epoch):
            batch = perm[s * 8 : s * 8 + 8]
            if len(batch) == 0:
                batch = perm[:8]
            pairs = [crop_of(int(i)) for i in batch]
            xb = torch.from_numpy(np.stack([p[0] for p in pairs]))
            yb = torch.from_numpy(np.stack([p[1] for p in pairs]))
            loss = loss_fn(net(xb), yb)
            opt.zero_grad()
            loss.backward()
            opt.step()
            sched.step()
            total += float(loss.detach()) * len(batch)
            count += len(batch)
        train_loss = total / max(count, 1)
        if progress:
            progress("training", (epoch + 1) / epochs)
    net.eval()
    inter = np.zeros(len(CLASSES))
    union = np.zeros(len(CLASSES))
    with torch.no_grad():
        for i in val_idx:
            x, y = samples[int(i)]
            pred = net(torch.from_numpy(x[None])).argmax(dim=1)[0].numpy()
            for k in range(len(CLASSES)):
                inter[k] += np.sum((pred == k) & (y == k))
                union[k] += np.sum((pred == k) | (y == k))
    val_iou = {
        CLASSES[k]: round(float(inter[k] / union[k]), 4) for k in range(len(CLASSES)) if union[k]
    }
    meta = {
        "command": command,
        "seed": seed,
        "epochs": epochs,
        "images": n,
        "crop": crop,
        "classes": list(CLASSES),
        "widths": list(WIDTHS),
        "train_loss": round(train_loss, 5),
        "val_iou": val_iou,
        "torch": str(torch.__version__),
    }
    path = Path(out)
    path.parent.mkdir(parents=True, exist_ok=True)
    # float16 storage halves the file; the network runs in float32
    state = {k: v.detach().numpy().astype(np.float16) for k, v in net.state_dict().items()}
    with path.open("wb") as fh:
        np.savez_compressed(fh, meta=np.array(json.dumps(meta)), **state)
    _MODELS.pop(path, None)
    return TrainResult(path, n, epochs, train_loss, val_iou, time.perf_counter() - t0)
