"""``hltl bench perception``: trajectory prediction, object localisation and people tracking."""

from __future__ import annotations

import functools
import math
import random
import statistics
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from hltl.execution.log import Perception
from hltl.grounding.offline import OfflineGrounder
from hltl.perception.detection import MIN_PIXELS, Detection
from hltl.perception.evaluate import HORIZONS, Score, score
from hltl.perception.forecast import DT, F64, stop_places
from hltl.perception.frames import Frame
from hltl.perception.geometry import cylinder_outline, polygon_area
from hltl.perception.objects import localize, make_backend
from hltl.perception.observe import Perceiver, match_objects
from hltl.perception.predict import ConstantVelocityPredictor, GoalDirectedPredictor, GRUPredictor
from hltl.perception.walks import generate_walks
from hltl.sim.dynamic import MIN_SPACING, WALK_SPEED, _spots, make_trial
from hltl.sim.episode import run_episode
from hltl.sim.events import EventSchedule, HumanMove
from hltl.sim.scenarios import catalogue
from hltl.sim.simulator import Simulator
from hltl.sim3d.camera import CameraRenderer
from hltl.sim3d.dataset import Sample, frame_camera, object_centres, render_samples
from hltl.sim3d.driver import MujocoSimulator
from hltl.sim3d.model import compile_scene, object_look
from hltl.sim3d.perceived import CameraSimulator
from hltl.sim3d.stage import Stage
from hltl.world.scene import Camera, Scene

# Held-out test sets: (name, leg mix over walks.KINDS = sim, smooth, turn, hesitate, wander).
TEST_SETS: tuple[tuple[str, tuple[float, ...]], ...] = (
    ("mixed", (0.3, 0.3, 0.15, 0.15, 0.1)),
    ("simulator walks", (1.0, 0.0, 0.0, 0.0, 0.0)),
    ("stops & turns", (0.0, 0.0, 1.0, 1.0, 0.0)),
    ("wandering", (0.0, 0.0, 0.0, 0.0, 1.0)),
)
Walks = list[tuple[F64, F64, F64]]


def _three(model: Any, data: Walks, stride: int) -> list[Score]:
    def gru(stops: F64) -> GRUPredictor:
        return GRUPredictor(stops, model=model)

    return [
        score("cv", lambda s: ConstantVelocityPredictor(), data, stride),
        score("goal", GoalDirectedPredictor, data, stride),
        score("gru", gru, data, stride),
    ]


def evaluate_predictors(
    seed: int, walks: int, model: Any, stride: int = 2
) -> list[tuple[str, list[Score]]]:
    """Scores of cv, goal and gru (the loaded ``model``) on each held-out synthetic test set."""
    out = []
    for k, (name, mix) in enumerate(TEST_SETS):
        ws = generate_walks(seed + k, walks, mix=mix)
        out.append((name, _three(model, [(w.observed, w.true, w.stops) for w in ws], stride)))
    return out


def suite_walks(seed: int = 0, legs: int = 3, noise: float = 0.01) -> Walks:
    """Every person of every catalogue cell walks ``legs`` times (1 m/s, the simulator's H-MOVE)
    to a random free spot of the suite beside a robot, standing 1–2 s in between."""
    rng = random.Random(seed)
    out: Walks = []
    for sc in catalogue():
        scene = sc.scene
        spots = _spots(scene)
        for h in scene.humans:
            t, here = 1.0, h.position
            moves = []
            for _ in range(legs):
                free = [
                    p
                    for p in spots
                    if math.dist(p[:2], here[:2]) > 0.5
                    and all(
                        math.dist(p[:2], o.position[:2]) >= MIN_SPACING
                        for o in scene.humans
                        if o.id != h.id
                    )
                ]
                if not free:
                    break
                dest = rng.choice(free)
                moves.append(HumanMove(round(t, 3), h.id, dest, WALK_SPEED))
                t += math.dist(here[:2], dest[:2]) / WALK_SPEED + rng.uniform(1.0, 2.0)
                here = dest
            if not moves:
                continue
            sim = Simulator(scene, EventSchedule(timed=tuple(moves)), seed=seed)
            n = int((t + 1.0) / DT)
            true = np.zeros((n, 2))
            for i in range(n):
                sim.advance(i * DT)
                true[i] = sim.human_position(h.id)[:2]
            nrng = np.random.default_rng(rng.randrange(2**32))
            out.append((true + nrng.normal(0.0, noise, true.shape), true, stop_places(scene)))
    return out


# -- renders ---------------------------------------------------------------------------------


def _cameras(scene: Scene) -> tuple[Camera, ...]:
    """Three poses around the cell: front, front-left from higher up, and the right side."""
    xs = [r.base[0] for r in scene.robots] + [o.position[0] for o in scene.objects]
    ys = [r.base[1] for r in scene.robots] + [o.position[1] for o in scene.objects]
    cx, cy = (min(xs) + max(xs)) / 2, (min(ys) + max(ys)) / 2
    span = max(max(xs) - min(xs), max(ys) - min(ys), 1.0)
    d = 1.2 + span
    look = (cx, cy, 0.0)
    return (
        Camera("front", (cx, cy - d, 1.1), look),
        Camera("high", (cx - 0.6 * d, cy - 0.6 * d, 1.8), look),
        Camera("side", (cx + d, cy - 0.3, 0.9), look),
    )


@dataclass(frozen=True, slots=True)
class SeenObject:
    """One object a clutter frame shows (at least MIN_PIXELS pixels in the segmentation) and
    what a backend made of it: ``visible`` is its shown pixels over the area of its whole
    unhidden silhouette (:func:`cylinder_outline`, image border included), ``error`` the
    estimate minus the true centre (m) when it was found, ``detected`` the pixels behind that
    estimate."""

    frame: int
    object: str
    category: str
    pixels: int
    visible: float
    error: tuple[float, float, float] | None = None
    detected: int = 0

    @property
    def distance(self) -> float:
        return math.nan if self.error is None else math.hypot(*self.error)


@dataclass(frozen=True, slots=True)
class ObjectRow:
    backend: str
    frames: int
    visible: int  # objects the segmentation shows with >= MIN_PIXELS pixels
    found: int  # of those, localised and matched to the right id
    errors: tuple[float, ...]  # 3D centroid errors (m) of the found ones
    ms: tuple[float, ...]  # per-frame time (detect + localise)
    cpu: tuple[float, ...] = ()  # per-frame CPU time of this process (all threads)
    # per category: (category, visible, found, named as another category)
    categories: tuple[tuple[str, int, int, int], ...] = ()
    seen: tuple[SeenObject, ...] = ()  # clutter: every object shown, found or not


def object_bench(
    scenes: Sequence[Scene], progress: Callable[[str], None] | None = None
) -> list[ObjectRow]:
    """Centroid error, recall and time of both object backends on renders of ``scenes``, each
    with and without the categories' known sizes in the cylinder fit."""

    # (row name, backend, fit with the categories' known sizes)
    runs = (
        ("segmentation", "segmentation", True),
        ("segmentation, free fit", "segmentation", False),
        ("depth-clusters", "depth-clusters", True),
        ("depth-clusters, free fit", "depth-clusters", False),
        ("learned", "learned", True),
    )
    acc: dict[str, dict[str, list[float]]] = {
        b: {"errors": [], "ms": [], "cpu": [], "visible": [], "found": []} for b, _, _ in runs
    }
    frames = 0
    for scene in scenes:
        cams = _cameras(scene)
        scene = replace(scene, cameras=cams)
        stage = Stage(compile_scene(scene))
        truth = object_centres(stage)
        for cam in cams:
            with CameraRenderer(stage.sm, cam, geometry="visual") as r:
                f = r.render(stage.data)
            fcam = frame_camera(cam, stage.sm.segment_table())
            frame = Frame(frames, 0.0, f.rgb, f.depth, f.seg, stage.joints())
            frames += 1
            visible = {
                s.id
                for sid, s in fcam.segments.items()
                if s.kind == "object" and int((f.seg == sid).sum()) >= MIN_PIXELS
            }
            for name, kind, priors in runs:
                a = acc[name]
                backend = make_backend(kind, scene)
                t0, c0 = time.perf_counter(), time.process_time()
                dets = backend.detect(frame, fcam)
                located = localize(frame, fcam, dets, backend.planes, scene, priors)
                a["ms"].append((time.perf_counter() - t0) * 1000.0)
                a["cpu"].append((time.process_time() - c0) * 1000.0)
                obs, _, _ = match_objects(scene, located)
                a["visible"].append(len(visible))
                found = [o for o in obs if o.id in visible]
                a["found"].append(len(found))
                a["errors"] += [math.dist(o.position, truth[o.id]) for o in found if o.id]
            if progress:
                progress(f"objects: {frames} frames")
    return [
        ObjectRow(
            b,
            frames,
            int(sum(a["visible"])),
            int(sum(a["found"])),
            tuple(a["errors"]),
            tuple(a["ms"]),
            tuple(a["cpu"]),
        )
        for b, a in acc.items()
    ]


def _named(s: Sample, dets: Sequence[Detection], sid: int) -> str | None:
    """What a backend calls segment ``sid``'s object: the category (or ``person``) of the
    detection covering most of it (at least 30 % of the smaller of the two), None if none."""
    assert s.frame.seg is not None
    shown = s.frame.seg == sid
    size = int(shown.sum())
    best, name = 0, None
    for d in dets:
        overlap = int((d.mask & shown).sum())
        if overlap > best and overlap >= 0.3 * min(size, int(d.mask.sum())):
            best, name = overlap, d.label
    if name is not None and name in s.scene.object_ids:  # exact labels are scene ids
        name = s.scene.object(name).category.lower()
    return name


def clutter_bench(
    scenes: Sequence[Scene],
    seed: int = 1000,
    layouts: int = 2,
    views: int = 3,
    progress: Callable[[str], None] | None = None,
) -> list[ObjectRow]:
    """The backends (known sizes) on cluttered layouts of ``scenes`` as the learned backend's
    training renders are made (:mod:`hltl.sim3d.dataset`: 3–8 objects of every rendered
    category, random cameras, lights, arm poses, people), from cells it was not trained on;
    recall and naming per category."""
    samples = render_samples(scenes, seed=seed, layouts=layouts, views=views)
    shares = [_visible_shares(s) for s in samples]
    rows = []
    for name in ("segmentation", "depth-clusters", "learned"):
        errors: list[float] = []
        ms: list[float] = []
        cpu: list[float] = []
        per: dict[str, list[int]] = {}  # category → [visible, found, named otherwise]
        seen: list[SeenObject] = []
        for s, share in zip(samples, shares, strict=True):
            assert s.frame.seg is not None
            shown = {
                seg.id: sid
                for sid, seg in s.camera.segments.items()
                if seg.kind == "object" and int((s.frame.seg == sid).sum()) >= MIN_PIXELS
            }
            backend = make_backend(name, s.scene)
            t0, c0 = time.perf_counter(), time.process_time()
            dets = backend.detect(s.frame, s.camera)
            located = localize(s.frame, s.camera, dets, backend.planes, s.scene)
            ms.append((time.perf_counter() - t0) * 1000.0)
            cpu.append((time.process_time() - c0) * 1000.0)
            obs, _, _ = match_objects(s.scene, located)
            hits = {o.id: o for o in obs if o.id in shown}
            errors += [math.dist(o.position, s.centres[oid]) for oid, o in hits.items() if oid]
            for oid, sid in shown.items():
                category = s.scene.object(oid).category.lower()
                tally = per.setdefault(category, [0, 0, 0])
                tally[0] += 1
                tally[1] += oid in hits
                called = _named(s, dets, sid)
                tally[2] += called is not None and called != category
                pixels, visible = share[oid]
                o = hits.get(oid)
                error = None if o is None else tuple(np.subtract(o.position, s.centres[oid]))
                seen.append(
                    SeenObject(
                        s.frame.index,
                        oid,
                        category,
                        pixels,
                        visible,
                        None if error is None else (error[0], error[1], error[2]),
                        0 if o is None else o.pixels,
                    )
                )
        rows.append(
            ObjectRow(
                name,
                len(samples),
                sum(t[0] for t in per.values()),
                sum(t[1] for t in per.values()),
                tuple(errors),
                tuple(ms),
                tuple(cpu),
                tuple((c, t[0], t[1], t[2]) for c, t in sorted(per.items())),
                tuple(seen),
            )
        )
        if progress:
            progress(f"clutter: {name}")
    return rows


def _visible_shares(s: Sample) -> dict[str, tuple[int, float]]:
    """Object id → (pixels shown, share of its whole silhouette shown) of a clutter sample's
    objects that show at least MIN_PIXELS pixels."""
    assert s.frame.seg is not None
    out = {}
    for sid, seg in s.camera.segments.items():
        if seg.kind != "object":
            continue
        n = int((s.frame.seg == sid).sum())
        if n < MIN_PIXELS:
            continue
        radius, height, _ = object_look(s.scene.object(seg.id))
        hull = cylinder_outline(s.centres[seg.id], radius, height, s.camera)
        area = polygon_area(hull) if hull is not None else 0.0
        out[seg.id] = (n, min(n / area, 1.0) if area > 0 else math.nan)
    return out


# the centroid targets (m): every object a backend reports is held to them
TARGETS = {"segmentation": 0.01, "depth-clusters": 0.03, "learned": 0.03}


def format_outliers(rows: Sequence[ObjectRow]) -> str:
    """Every found clutter object whose centroid error exceeds its backend's target, worst
    first, with what the frame showed of it."""
    lines = [
        "| backend (target) | frame | object | shown px (share of silhouette) | found from px "
        "| error (cm) | error x, y, z (cm) |",
        "|---|---|---|---|---|---|---|",
    ]
    for row in rows:
        target = TARGETS.get(row.backend, 0.03)
        out = sorted(
            (o for o in row.seen if o.error is not None and o.distance > target),
            key=lambda o: -o.distance,
        )
        for o in out:
            assert o.error is not None
            ex, ey, ez = (100.0 * v for v in o.error)
            lines.append(
                f"| {row.backend} ({100 * target:.0f} cm) | {o.frame} | {o.object} {o.category} "
                f"| {o.pixels} ({100 * o.visible:.0f} %) | {o.detected} "
                f"| {100 * o.distance:.2f} | {ex:+.1f}, {ey:+.1f}, {ez:+.1f} |"
            )
        found = sum(o.error is not None for o in row.seen)
        lines.append(
            f"| {row.backend} ({100 * target:.0f} cm) | all | {len(out)} of {found} found over "
            f"the target ({len(row.seen)} shown) | | | | |"
        )
    return "\n".join(lines)


def format_categories(row: ObjectRow) -> str:
    """Recall and naming of one backend per category."""
    lines = [
        "| category | visible | found (right id) | named as another category |",
        "|---|---|---|---|",
    ]
    for c, visible, found, other in row.categories:
        lines.append(
            f"| {c} | {visible} | {found} ({100.0 * found / max(visible, 1):.0f} %) | {other} |"
        )
    return "\n".join(lines)


@dataclass(frozen=True, slots=True)
class PeopleRow:
    detector: str
    person_frames: int  # frames × people visible (segmentation mask >= 2000 px)
    detected: int  # of those, a track tied to the right person within 0.3 m
    errors: tuple[float, ...]  # floor-position errors (m) of the detected ones
    switches: int  # times a person's track id changed
    wrong: int  # tracked observations tied to the wrong person
    false: int  # tracked observations near nobody
    ms: tuple[float, ...]  # wall time per frame
    cpu: tuple[float, ...] = ()  # CPU time per frame (all of this process's threads)
    yolo_ages: tuple[float, ...] = ()  # fused: age (s) of each YOLO run's boxes when used
    stale: int = 0  # fused, asynchronous: YOLO runs dropped as too old


JointTruth = dict[str, dict[str, tuple[float, float, float]]]


def _crossing(
    scene: Scene, frames: int, limit: int | None = None
) -> tuple[Scene, Any, dict[str, int], list[Any], list[JointTruth]]:
    """Two people crossing in front of the robots, rendered: (scene, camera, segment id of each
    person, [(frame, floor truth)], the true shoulders, elbows and wrists per frame). ``limit``
    renders only the first frames of the ``frames``-frame crossing."""

    a, b = scene.humans[:2]
    cam = _cameras(scene)[0]
    scene = replace(scene, cameras=(cam,))
    stage = Stage(compile_scene(scene))
    fcam = frame_camera(cam, stage.sm.segment_table())
    seg_of = {s.id: sid for sid, s in fcam.segments.items() if s.kind == "human"}
    rendered = []
    joints: list[JointTruth] = []
    pa, pb = np.array(a.position[:2]), np.array(b.position[:2])
    off = np.array([0.0, 0.25])  # the two walk on lines 0.5 m apart, so they pass, not collide
    with CameraRenderer(stage.sm, cam, geometry="collision") as r:
        for k in range(frames if limit is None else min(limit, frames)):
            s = k / (frames - 1)
            qa = pa + s * (pb - pa) + off * math.sin(math.pi * s)
            qb = pb + s * (pa - pb) - off * math.sin(math.pi * s)
            yaw_a = math.atan2(*(pb - pa)[::-1])
            stage.set_human(a.id, (qa[0], qa[1], 0.0), yaw_a, stride=float(np.linalg.norm(qa - pa)))
            stage.set_human(
                b.id, (qb[0], qb[1], 0.0), yaw_a + math.pi, stride=float(np.linalg.norm(qb - pb))
            )
            stage.forward()
            f = r.render(stage.data)
            truth = {a.id: (float(qa[0]), float(qa[1])), b.id: (float(qb[0]), float(qb[1]))}
            rendered.append((Frame(k, 0.1 * k, f.rgb, f.depth, f.seg, stage.joints()), truth))
            joints.append({h.id: _true_joints(stage, h.id) for h in (a, b)})
    return scene, fcam, seg_of, rendered, joints


def _true_joints(stage: Any, hid: str) -> dict[str, tuple[float, float, float]]:
    """Shoulder (upper arm's origin), elbow (forearm's origin) and wrist (end of the forearm,
    0.23 m down it) of a simulated person, both sides."""
    mj, m, d = stage.mj, stage.model, stage.data
    out = {}
    for side in ("l", "r"):
        up = int(mj.mj_name2id(m, mj.mjtObj.mjOBJ_BODY, f"human:{hid}/{side}_upper_arm"))
        fore = int(mj.mj_name2id(m, mj.mjtObj.mjOBJ_BODY, f"human:{hid}/{side}_forearm"))
        wrist = d.xpos[fore] + d.xmat[fore].reshape(3, 3) @ np.array([0.0, 0.0, -0.23])
        for name, p in (("shoulder", d.xpos[up]), ("elbow", d.xpos[fore]), ("wrist", wrist)):
            out[f"{side}_{name}"] = (float(p[0]), float(p[1]), float(p[2]))
    return out


def people_bench(
    scene: Scene,
    detectors: Sequence[str] = (
        "segmentation",
        "depth",
        "depth, unfiltered",
        "fused",
        "fused, inline",
        "yolo",
    ),
    frames: int = 40,
    progress: Callable[[str], None] | None = None,
) -> list[PeopleRow]:
    """Two people cross in front of the robots (each walks to where the other stood, 1 m/s
    pace), rendered at 10 Hz with walking poses; every detector tracks them inside the whole
    perception stage (its time per frame includes the objects). ``<detector>, unfiltered``:
    without the temporal filter of positions; ``fused`` runs YOLO on its worker thread with
    the frames replayed at their own pace (10 Hz, as a camera delivers them: how old YOLO's
    boxes are when used depends on it), ``fused, inline`` runs it inside every 10th frame."""
    scene, fcam, seg_of, rendered, _ = _crossing(scene, frames)
    rows = []
    for det in detectors:
        name, _, option = det.partition(", ")
        # the whole perception stage per frame: objects (segmentation, known sizes) and people
        perceiver = Perceiver(
            scene,
            fcam,
            "segmentation",
            name,
            smooth=option != "unfiltered",
            yolo_async=option != "inline",
        )
        tracker = perceiver.tracker
        paced = tracker is not None and tracker.async_yolo is not None
        start = time.perf_counter()
        person_frames = detected = wrong = false = switches = 0
        errors: list[float] = []
        ms: list[float] = []
        cpu: list[float] = []
        last_track: dict[str, str] = {}
        for frame, truth in rendered:
            if paced:  # the frame arrives at its time, not as soon as the last one is done
                time.sleep(max(0.0, start + frame.t - time.perf_counter()))
            t0, c0 = time.perf_counter(), time.process_time()
            obs = perceiver.process(frame).people
            ms.append((time.perf_counter() - t0) * 1000.0)
            cpu.append((time.process_time() - c0) * 1000.0)
            assert frame.seg is not None
            visible = {h for h in truth if int((frame.seg == seg_of[h]).sum()) >= 2000}
            person_frames += len(visible)
            for o in obs:
                near = min(truth, key=lambda h: math.dist(o.position[:2], truth[h]))
                d = math.dist(o.position[:2], truth[near])
                if d > 0.3:
                    false += 1
                    continue
                if o.person != near:
                    wrong += 1
                    continue
                if near in visible:
                    detected += 1
                errors.append(d)
                if near in last_track and last_track[near] != o.track:
                    switches += 1
                last_track[near] = o.track
        rows.append(
            PeopleRow(
                det,
                person_frames,
                detected,
                tuple(errors),
                switches,
                wrong,
                false,
                tuple(ms),
                tuple(cpu),
                tuple(tracker.yolo_ages) if tracker is not None else (),
                tracker.stale if tracker is not None else 0,
            )
        )
        perceiver.close()
        if progress:
            progress(f"people: {det}")
    return rows


# -- report ----------------------------------------------------------------------------------


def _q(xs: Sequence[float], q: float) -> float:
    if not xs:
        return math.nan
    s = sorted(xs)
    return s[min(len(s) - 1, int(q * len(s)))]


def format_prediction(results: Sequence[tuple[str, Sequence[Score]]]) -> str:
    head = "| test set | predictor | samples | " + " | ".join(
        f"ADE@{h:g}s | FDE@{h:g}s" for h in HORIZONS
    )
    lines = [head + " | vs CV (ADE@1s / ADE@2s) |", "|" + "---|" * (4 + 2 * len(HORIZONS))]
    for name, scores in results:
        cv = scores[0]
        for s in scores:
            cells = " | ".join(f"{a:.3f} | {f:.3f}" for a, f in zip(s.ade, s.fde, strict=True))
            gain = " / ".join(
                f"{100 * (1 - a / c):+.0f} %" for a, c in zip(s.ade, cv.ade, strict=True)
            )
            lines.append(f"| {name} | {s.predictor} | {s.samples} | {cells} | {gain} |")
    return "\n".join(lines)


def format_objects(rows: Sequence[ObjectRow]) -> str:
    lines = [
        "| backend | frames | objects visible | found "
        "| centroid error median / p95 / max (cm) | ms per frame: wall median / max, CPU median |",
        "|---|---|---|---|---|---|",
    ]
    for r in rows:
        e = [100 * x for x in r.errors]
        lines.append(
            f"| {r.backend} | {r.frames} | {r.visible} | {r.found} | "
            f"{_q(e, 0.5):.2f} / {_q(e, 0.95):.2f} / {max(e, default=math.nan):.2f} | "
            f"{statistics.median(r.ms):.0f} / {max(r.ms):.0f}, "
            f"{statistics.median(r.cpu) if r.cpu else math.nan:.0f} |"
        )
    return "\n".join(lines)


def format_people(rows: Sequence[PeopleRow]) -> str:
    lines = [
        "| detector | person-frames visible | detected & tied right "
        "| position error median / p95 (cm) | identity switches | wrong identity | false tracks "
        "| ms per frame (objects + people): wall median / p95 / max, CPU median |",
        "|---|---|---|---|---|---|---|---|",
    ]
    notes = []
    for r in rows:
        e = [100 * x for x in r.errors]
        rate = 100.0 * r.detected / max(r.person_frames, 1)
        lines.append(
            f"| {r.detector} | {r.person_frames} | {r.detected} ({rate:.0f} %) | "
            f"{_q(e, 0.5):.1f} / {_q(e, 0.95):.1f} | {r.switches} | {r.wrong} | {r.false} | "
            f"{statistics.median(r.ms):.0f} / {_q(r.ms, 0.95):.0f} / {max(r.ms):.0f}, "
            f"{statistics.median(r.cpu) if r.cpu else math.nan:.0f} |"
        )
        if r.yolo_ages:
            notes.append(
                f"{r.detector}: {len(r.yolo_ages)} YOLO runs used, their boxes "
                f"{1000 * min(r.yolo_ages):.0f}–{1000 * max(r.yolo_ages):.0f} ms old "
                f"(median {1000 * statistics.median(r.yolo_ages):.0f}); {r.stale} dropped as "
                "older than 1 s"
            )
    return "\n".join(lines + (["", *notes] if notes else []))


Stats = tuple[float, float, float]


@dataclass(frozen=True, slots=True)
class SkeletonRow:
    person_frames: int  # people tracked by the depth detector, over the frames
    found: int  # of those, the pose model found a body in the crop
    # joint → (seen, error median/p95/max, the same to the nearer of its left/right truths)
    joints: dict[str, tuple[int, Stats, Stats]]
    ms: tuple[float, ...]  # per frame, the whole stage with skeletons
    version: str


def skeleton_bench(scene: Scene, frames: int = 40, limit: int | None = None) -> SkeletonRow:
    """MediaPipe skeletons of the crossing people (depth detector tracks them): how often the
    pose model finds each tracked person and each joint, and its 3D error against the
    simulator's joints (the person the track is tied to); ``limit``: the first frames only."""
    scene, fcam, _, rendered, truth = _crossing(scene, frames, limit)
    perceiver = Perceiver(scene, fcam, "segmentation", "depth", skeleton=True)
    assert perceiver.tracker is not None and perceiver.tracker.pose is not None
    version = perceiver.tracker.pose.version
    tracked = found = 0
    errs: dict[str, list[float]] = {}
    either: dict[str, list[float]] = {}  # to the nearer of the person's left and right joint
    seen: dict[str, int] = {}
    ms: list[float] = []
    try:
        for (frame, _), joints in zip(rendered, truth, strict=True):
            t0 = time.perf_counter()
            obs = perceiver.process(frame)
            ms.append((time.perf_counter() - t0) * 1000.0)
            for p in obs.people:
                if p.person is None:
                    continue
                tracked += 1
                if p.skeleton is None:
                    continue
                found += 1
                for name, q in p.skeleton.joints:
                    if q is not None:
                        true = joints[p.person]
                        other = ("r" if name[0] == "l" else "l") + name[1:]
                        seen[name] = seen.get(name, 0) + 1
                        errs.setdefault(name, []).append(math.dist(q, true[name]))
                        either.setdefault(name, []).append(
                            min(math.dist(q, true[name]), math.dist(q, true[other]))
                        )
    finally:
        perceiver.close()

    def stats(xs: list[float]) -> tuple[float, float, float]:
        return (_q(xs, 0.5), _q(xs, 0.95), max(xs, default=math.nan))

    table = {
        name: (seen.get(name, 0), stats(errs.get(name, [])), stats(either.get(name, [])))
        for name in ("l_shoulder", "r_shoulder", "l_elbow", "r_elbow", "l_wrist", "r_wrist")
    }
    return SkeletonRow(tracked, found, table, tuple(ms), version)


def format_skeleton(row: SkeletonRow) -> str:
    lines = [
        f"MediaPipe {row.version} (pose worker in .venv-pose), people tracked by the depth "
        f"detector: {row.person_frames} person-frames, the pose model found a body in "
        f"{row.found} ({100.0 * row.found / max(row.person_frames, 1):.0f} %); whole stage with "
        f"skeletons {statistics.median(row.ms):.0f} ms per frame median, "
        f"{_q(row.ms, 0.95):.0f} p95.",
        "",
        "| joint | seen (of person-frames with a body) | 3D error median / p95 / max (cm) "
        "| same, to the nearer side's joint (cm) |",
        "|---|---|---|---|",
    ]
    for name, (n, e, a) in row.joints.items():
        lines.append(
            f"| {name} | {n} | {100 * e[0]:.1f} / {100 * e[1]:.1f} / {100 * e[2]:.1f} "
            f"| {100 * a[0]:.1f} / {100 * a[1]:.1f} / {100 * a[2]:.1f} |"
        )
    return "\n".join(lines)


@dataclass(frozen=True, slots=True)
class LoopRow:
    """One suite trial run in the 3D simulator: ground-truth vs camera perception."""

    config: str
    index: int
    truth_success: bool
    camera_success: bool
    truth_time: float
    camera_time: float
    frames: int
    lost_frames: int  # frames in which some scene person had no live track
    # the camera loop again without the temporal filters (None: not run)
    unfiltered_success: bool | None = None
    unfiltered_time: float | None = None
    # the camera loop again with the learned object backend (None: not run)
    learned_success: bool | None = None
    learned_time: float | None = None
    learned_missing: float | None = None  # scene objects not seen, per frame (mean)


def loop_bench(
    configs: Sequence[str],
    trials: int,
    progress: Callable[[str], None] | None = None,
    people: str = "depth",
    unfiltered: bool = False,
    learned: bool = True,
) -> list[LoopRow]:
    """Suite trials (H-MOVE and GOAL events) in the 3D simulator, observed from the ground
    truth and through the camera (segmentation object backend with known sizes, ``people``
    person detector); with ``unfiltered`` also through the camera without temporal filters,
    with ``learned`` also through the camera with the learned object backend."""

    rows = []
    for config in configs:
        for index in range(trials):
            trial = make_trial(config, index)
            model = compile_scene(trial.scene)
            made: list[CameraSimulator] = []

            def camera(
                *a: Any,
                _m: Any = model,
                _made: list[Any] = made,
                _s: bool = True,
                _b: str = "segmentation",
                **k: Any,
            ) -> Any:
                sim = CameraSimulator(
                    *a, timing="cost", model=_m, people=people, smooth=_s, backend=_b, **k
                )
                _made.append(sim)
                return sim

            kw: dict[str, Any] = {
                "instruction": trial.instruction,
                "events": trial.events,
                "seed": trial.seed,
                "grounder": OfflineGrounder(),
            }
            truth = run_episode(
                trial.scene,
                simulator=lambda *a, _m=model, **k: MujocoSimulator(
                    *a, timing="cost", model=_m, **k
                ),
                **kw,
            )
            cam = run_episode(trial.scene, simulator=camera, **kw)
            frames = [r for r in cam.records if isinstance(r, Perception)]
            raw = (
                run_episode(trial.scene, simulator=functools.partial(camera, _s=False), **kw)
                if unfiltered
                else None
            )
            net = (
                run_episode(trial.scene, simulator=functools.partial(camera, _b="learned"), **kw)
                if learned
                else None
            )
            net_frames = [r for r in net.records if isinstance(r, Perception)] if net else []
            for sim in made:
                sim.close()
            rows.append(
                LoopRow(
                    config,
                    index,
                    truth.success,
                    cam.success,
                    truth.metrics.time_cost,
                    cam.metrics.time_cost,
                    len(frames),
                    sum(1 for r in frames if r.lost),
                    None if raw is None else raw.success,
                    None if raw is None else raw.metrics.time_cost,
                    None if net is None else net.success,
                    None if net is None else net.metrics.time_cost,
                    statistics.fmean(len(r.missing) for r in net_frames) if net_frames else None,
                )
            )
            if progress:
                progress(f"loop: {config} #{index}")
    return rows


def format_loop(rows: Sequence[LoopRow]) -> str:
    def yes(b: bool | None) -> str:
        return "-" if b is None else "yes" if b else "no"

    def sec(x: float | None) -> str:
        return "-" if x is None else f"{x:.2f}"

    lines = [
        "| trial | success truth / camera / camera unfiltered / camera learned | time cost truth "
        "/ camera / camera unfiltered / camera learned (s) | frames | frames with someone "
        "untracked | objects unseen per frame, learned |",
        "|---|---|---|---|---|---|",
    ]
    for r in rows:
        lines.append(
            f"| {r.config} #{r.index} | {yes(r.truth_success)} / {yes(r.camera_success)} / "
            f"{yes(r.unfiltered_success)} / {yes(r.learned_success)} | {r.truth_time:.2f} / "
            f"{r.camera_time:.2f} / {sec(r.unfiltered_time)} / {sec(r.learned_time)} "
            f"| {r.frames} | {r.lost_frames} | {sec(r.learned_missing)} |"
        )
    n = len(rows)
    if n:

        def rate(xs: Sequence[bool | None]) -> str:
            ran = [x for x in xs if x is not None]
            return f"{100.0 * sum(bool(x) for x in ran) / len(ran):.0f} %" if ran else "-"

        cells = " / ".join(
            rate(xs)
            for xs in (
                [r.truth_success for r in rows],
                [r.camera_success for r in rows],
                [r.unfiltered_success for r in rows],
                [r.learned_success for r in rows],
            )
        )
        lines.append(f"| **all {n}** | {cells} | | | | |")
    return "\n".join(lines)
