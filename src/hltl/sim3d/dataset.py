"""Labelled renders for the learned object segmenter: randomised cells, cameras, lights and arms."""

from __future__ import annotations

import math
import random
from collections.abc import Callable, Sequence
from dataclasses import dataclass, replace
from pathlib import Path

import numpy as np

from hltl.perception.frames import Camera as FrameCamera
from hltl.perception.frames import Frame, camera_from_dict
from hltl.perception.learned import CLASSES, TrainResult, downsample_labels, inputs, train
from hltl.sim.scenarios import get
from hltl.sim3d.camera import CameraRenderer, camera_to_world, intrinsics
from hltl.sim3d.model import _quat_from_axes, camera_axes, compile_scene
from hltl.sim3d.stage import Stage
from hltl.world.scene import Camera, Human, Scene, SceneObject, Surface

OBJECT_CATEGORIES = CLASSES[2:]
# catalogue cells the segmenter is trained on; the object benchmark's cells (fig1, 2-2, 4-2,
# 4-4-line, 4-4-square) are held out
ROBOT_MODELS = ("ur5", "panda", "elfin3", "xarm6")  # xarm6 is drawn as the primitive arm
TRAIN_CELLS = ("1-1", "2-1", "4-1", "1-2", "1-4-line", "2-4-line", "1-4-square", "2-4-square")


@dataclass(frozen=True, slots=True)
class Sample:
    """One labelled render: the frame, its camera, per-pixel class indices (H×W uint8), the
    cluttered scene it shows and each object's true centre."""

    frame: Frame
    camera: FrameCamera
    labels: np.ndarray
    scene: Scene
    centres: dict[str, tuple[float, float, float]]


def object_centres(stage: Stage) -> dict[str, tuple[float, float, float]]:
    """Centre of each object's cylinder as posed in ``stage``."""
    mj, m, d = stage.mj, stage.model, stage.data
    out = {}
    for o in stage.scene.objects:
        bid = int(mj.mj_name2id(m, mj.mjtObj.mjOBJ_BODY, f"object:{o.id}"))
        g = next(g for g in range(m.ngeom) if int(m.geom_bodyid[g]) == bid)
        p = d.geom_xpos[g]
        out[o.id] = (float(p[0]), float(p[1]), float(p[2]))
    return out


def _clutter(scene: Scene, rng: random.Random) -> Scene:
    """The cell with 3–8 random objects within reach of its arms and its people moved."""
    bases = [r.base for r in scene.robots]
    objects: list[SceneObject] = []
    for _ in range(200):
        if len(objects) >= rng.randint(3, 8):
            break
        b = rng.choice(bases)
        ang, dist = rng.uniform(0, 2 * math.pi), rng.uniform(0.2, 0.6)
        p = (b[0] + dist * math.cos(ang), b[1] + dist * math.sin(ang), 0.05)
        if any(math.dist(p[:2], q[:2]) < 0.15 for q in bases):
            continue
        if any(math.dist(p[:2], o.position[:2]) < 0.11 for o in objects):
            continue
        cat = rng.choice(OBJECT_CATEGORIES)
        objects.append(SceneObject(f"o{len(objects)}", cat, p))
    humans = tuple(Human(h.id, h.name, _person_spot(scene, objects, rng)) for h in scene.humans)
    # any arm model the simulator renders (the cells mix them), and sometimes a mat
    robots = tuple(replace(r, model=rng.choice(ROBOT_MODELS)) for r in scene.robots)
    surfaces: tuple[Surface, ...] = ()
    if rng.random() < 0.5:
        b = rng.choice(bases)
        side = rng.uniform(0.2, 0.4)
        spot = (b[0] + rng.uniform(-0.5, 0.5), b[1] + rng.uniform(-0.5, 0.5), 0.0)
        surfaces = (Surface("mat", spot, (side, side * rng.uniform(0.7, 1.3))),)
    return replace(
        scene,
        robots=robots,
        objects=tuple(objects),
        humans=humans,
        surfaces=surfaces,
        cameras=(),
    )


def _person_spot(
    scene: Scene, objects: Sequence[SceneObject], rng: random.Random
) -> tuple[float, float, float]:
    bases = [r.base for r in scene.robots]
    for _ in range(100):
        b = rng.choice(bases)
        ang, dist = rng.uniform(0, 2 * math.pi), rng.uniform(0.7, 1.3)
        p = (b[0] + dist * math.cos(ang), b[1] + dist * math.sin(ang), 0.0)
        near = [q[:2] for q in bases] + [o.position[:2] for o in objects]
        if all(math.dist(p[:2], q) > 0.55 for q in near):
            return p
    return (bases[0][0], bases[0][1] - 1.2, 0.0)


def _random_camera(scene: Scene, rng: random.Random, name: str) -> Camera:
    pts = [r.base for r in scene.robots] + [o.position for o in scene.objects]
    xs, ys = [p[0] for p in pts], [p[1] for p in pts]
    cx, cy = (min(xs) + max(xs)) / 2, (min(ys) + max(ys)) / 2
    span = max(max(xs) - min(xs), max(ys) - min(ys), 1.0)
    az = rng.uniform(0, 2 * math.pi)
    d = rng.uniform(0.9, 1.5) + span * rng.uniform(0.6, 1.1)
    pos = (cx + d * math.cos(az), cy + d * math.sin(az), rng.uniform(0.5, 2.0))
    look = (cx + rng.uniform(-0.3, 0.3), cy + rng.uniform(-0.3, 0.3), rng.uniform(-0.3, 0.1))
    return Camera(name, pos, look, fovy=rng.uniform(38.0, 50.0))


def frame_camera(cam: Camera, segments: dict[str, dict[str, str]]) -> FrameCamera:
    """The perception camera (intrinsics, pose, segments) of a scene camera."""
    k = intrinsics(cam)
    return camera_from_dict(
        {
            "name": cam.id,
            "width": cam.width,
            "height": cam.height,
            "intrinsics": {"fx": k.fx, "fy": k.fy, "cx": k.cx, "cy": k.cy},
            "extrinsics": {"camera_to_world": camera_to_world(cam).tolist()},
            "segments": segments,
        },
        f"camera {cam.id}",
    )


def class_labels(seg: np.ndarray, camera: FrameCamera, scene: Scene) -> np.ndarray:
    """Per-pixel class indices of a segmentation render."""
    category = {o.id: o.category.lower() for o in scene.objects}
    lut = np.zeros(int(seg.max()) + 1, np.uint8)
    for sid, s in camera.segments.items():
        if sid >= len(lut):
            continue
        if s.kind == "human":
            lut[sid] = CLASSES.index("person")
        elif s.kind == "object" and category.get(s.id) in CLASSES:
            lut[sid] = CLASSES.index(category[s.id])
    out: np.ndarray = lut[seg]
    return out


def render_samples(
    scenes: Sequence[Scene],
    *,
    seed: int,
    layouts: int,
    views: int,
    progress: Callable[[int, int], None] | None = None,
) -> list[Sample]:
    """``layouts`` cluttered versions of each scene, ``views`` random views of each."""
    rng = random.Random(seed)
    out: list[Sample] = []
    total = len(scenes) * layouts * views
    for scene in scenes:
        for _ in range(layouts):
            sc = _clutter(scene, rng)
            probe = Camera("train", (0.0, -3.0, 1.5), (0.0, 0.0, 0.0))
            sc = replace(sc, cameras=(probe,))
            sm = compile_scene(sc, cache=False)
            stage = Stage(sm)
            m = sm.model
            mj = stage.mj
            cid = int(mj.mj_name2id(m, mj.mjtObj.mjOBJ_CAMERA, "camera:train"))
            segments = sm.segment_table()
            geometry = rng.choice(("visual", "collision"))
            with CameraRenderer(sm, probe, geometry=geometry) as r:
                for _ in range(views):
                    cam = _random_camera(sc, rng, "train")
                    m.cam_pos[cid] = cam.position
                    m.cam_quat[cid] = _quat_from_axes(camera_axes(cam))
                    m.cam_fovy[cid] = cam.fovy
                    _pose(stage, sc, rng)
                    m.vis.headlight.ambient[:] = [rng.uniform(0.15, 0.5)] * 3
                    m.vis.headlight.diffuse[:] = [rng.uniform(0.2, 0.6)] * 3
                    if m.nlight:
                        m.light_diffuse[0] = [rng.uniform(0.3, 0.9)] * 3
                        m.light_pos[0] = (rng.uniform(-2, 2), rng.uniform(-2, 2), 3.0)
                    stage.forward()
                    f = r.render(stage.data)
                    fcam = frame_camera(cam, segments)
                    frame = Frame(len(out), 0.0, f.rgb, f.depth, f.seg, stage.joints())
                    labels = class_labels(f.seg, fcam, sc)
                    out.append(Sample(frame, fcam, labels, sc, object_centres(stage)))
                    if progress:
                        progress(len(out), total)
    return out


def _pose(stage: Stage, scene: Scene, rng: random.Random) -> None:
    """Random arm poses near home, people standing or walking, facing anywhere."""
    for rid, q in stage.home.items():
        rig = stage.sm.robots[rid]
        q2 = [
            min(max(v + rng.uniform(-0.6, 0.6), lo), hi)
            for v, lo, hi in zip(q, rig.lower, rig.upper, strict=True)
        ]
        stage.set_robot(rid, q2)
    for h in scene.humans:
        p = h.position
        jitter = (p[0] + rng.uniform(-0.2, 0.2), p[1] + rng.uniform(-0.2, 0.2), 0.0)
        stride = None if rng.random() < 0.4 else rng.uniform(0.0, 1.3)
        stage.set_human(
            h.id,
            jitter,
            rng.uniform(-math.pi, math.pi),
            stride=stride,
            reach=rng.random() if rng.random() < 0.3 else 0.0,
        )


def train_detector(
    out: str | Path,
    *,
    seed: int = 0,
    layouts: int = 6,
    views: int = 8,
    epochs: int = 30,
    command: str = "",
    progress: Callable[[str, float], None] | None = None,
) -> TrainResult:
    """Render the training set from :data:`TRAIN_CELLS` and train the segmenter on it."""
    scenes = [get(name).scene for name in TRAIN_CELLS]

    def rendered(k: int, n: int) -> None:
        if progress:
            progress("rendering", k / n)

    samples = render_samples(scenes, seed=seed, layouts=layouts, views=views, progress=rendered)
    pairs = [(inputs(s.frame, s.camera), downsample_labels(s.labels)) for s in samples]
    return train(pairs, out, seed=seed, epochs=epochs, command=command, progress=progress)
