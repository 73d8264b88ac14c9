"""The 3D model and the RGB-D camera: frames checked against ray casting done here, by hand."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest

from hltl.world.scene import Scene, scene_from_dict

pytest.importorskip("mujoco")  # tests/conftest.py chose the offscreen backend already

from hltl.sim3d.camera import CameraRenderer, FrameWriter, camera_to_world, intrinsics
from hltl.sim3d.model import TABLE_HEIGHT, compile_scene, object_look
from hltl.sim3d.stage import Stage

W, H = 160, 120


def _scene() -> Scene:
    # the camera looks from -y at two objects in front of a primitive arm; a person stands aside
    return scene_from_dict(
        {
            "robots": [{"id": "r1", "base": [0.0, 0.4, 0.0], "reach": 0.6}],
            "objects": [
                {"id": "bottle", "category": "bottle", "position": [-0.25, 0.0, 0.05]},
                {"id": "chips", "category": "chips", "position": [0.25, 0.05, 0.05]},
            ],
            "humans": [{"id": "A", "position": [-0.9, 0.5, 0.0]}],
            "surfaces": [{"id": "mat", "center": [0.5, 0.5, 0.0], "size": [0.2, 0.2]}],
            "cameras": [
                {
                    "id": "side",
                    "position": [0.0, -1.2, 0.5],
                    "look_at": [0.0, 0.2, 0.0],
                    "width": W,
                    "height": H,
                    "fovy": 50,
                }
            ],
        },
        source="<test>",
    )


@pytest.fixture(scope="module")
def rendered(tmp_path_factory: pytest.TempPathFactory) -> tuple[Scene, Path]:
    scene = _scene()
    sm = compile_scene(scene, cache=tmp_path_factory.mktemp("cache"))
    stage = Stage(sm)
    out = tmp_path_factory.mktemp("frames")
    with CameraRenderer(sm, scene.cameras[0]) as r:
        frame = r.render(stage.data)
    w = FrameWriter(out, sm, scene.cameras[0])
    w.write(frame, 0.0)
    w.close()
    return scene, out


def _ray(meta: dict, u: float, v: float) -> tuple[np.ndarray, np.ndarray]:
    """World origin and direction (unit z in the optical frame) of pixel (u, v)."""
    k = meta["intrinsics"]
    pose = np.array(meta["extrinsics"]["camera_to_world"])
    d_cam = np.array([(u - k["cx"]) / k["fx"], (v - k["cy"]) / k["fy"], 1.0])
    return pose[:3, 3], pose[:3, :3] @ d_cam


def _project(meta: dict, p: np.ndarray) -> tuple[float, float, float]:
    k = meta["intrinsics"]
    pose = np.array(meta["extrinsics"]["camera_to_world"])
    c = pose[:3, :3].T @ (p - pose[:3, 3])
    return k["fx"] * c[0] / c[2] + k["cx"], k["fy"] * c[1] / c[2] + k["cy"], c[2]


def _cylinder_depth(o: np.ndarray, d: np.ndarray, c: np.ndarray, r: float) -> float:
    """Optical depth (the ray's z parameter) where the ray meets a vertical cylinder's side."""
    ox, oy = o[0] - c[0], o[1] - c[1]
    a = d[0] ** 2 + d[1] ** 2
    b = 2 * (ox * d[0] + oy * d[1])
    cc = ox**2 + oy**2 - r**2
    disc = b * b - 4 * a * cc
    assert disc > 0
    return float((-b - math.sqrt(disc)) / (2 * a))


def _load(out: Path) -> tuple[dict, np.ndarray, np.ndarray, np.ndarray]:
    from PIL import Image

    meta = json.loads((out / "camera.json").read_text())
    f = meta["frames"][0]
    rgb = np.asarray(Image.open(out / f["rgb"]))
    depth = np.load(out / f["depth"])["depth"]
    seg = np.asarray(Image.open(out / f["seg"])).astype(np.int64)
    return meta, rgb, depth, seg


def test_frame_folder_layout(rendered: tuple[Scene, Path]) -> None:
    scene, out = rendered
    meta, rgb, depth, seg = _load(out)
    assert (meta["width"], meta["height"], meta["convention"], meta["depth_units"]) == (
        W,
        H,
        "opencv",
        "m",
    )
    assert rgb.shape == (H, W, 3) and rgb.dtype == np.uint8
    assert depth.shape == (H, W) and depth.dtype == np.float32
    assert seg.shape == (H, W)
    kinds = {(s["kind"], s["id"]) for s in meta["segments"].values()}
    assert {("object", "bottle"), ("object", "chips"), ("robot", "r1"), ("human", "A")} <= kinds
    assert ("surface", "mat") in kinds and ("floor", "floor") in kinds
    # every segment id in the image is named, and background (0) has no depth
    assert {int(v) for v in np.unique(seg)} - {0} <= {int(k) for k in meta["segments"]}
    assert np.all(depth[seg == 0] == 0)
    assert np.all(depth[seg > 0] > 0)
    k = intrinsics(scene.cameras[0])
    assert meta["intrinsics"]["fx"] == pytest.approx(k.fx)
    assert np.allclose(meta["extrinsics"]["camera_to_world"], camera_to_world(scene.cameras[0]))


def test_objects_segmented_and_depth_exact(rendered: tuple[Scene, Path]) -> None:
    scene, out = rendered
    meta, rgb, depth, seg = _load(out)
    ids = {(s["kind"], s["id"]): int(k) for k, s in meta["segments"].items()}
    for obj in scene.objects:
        radius, height, rgba = object_look(obj)
        centre = np.array([obj.position[0], obj.position[1], height / 2])
        u, v, _ = _project(meta, centre)
        ui, vi = round(u), round(v)
        assert 0 <= ui < W and 0 <= vi < H
        sid = ids[("object", obj.id)]
        assert seg[vi, ui] == sid, obj.id
        # every pixel of the object has its colour family: segmentation and RGB agree
        mask = seg == sid
        assert mask.sum() > 20
        mean = rgb[mask].mean(axis=0) / 255
        assert np.argmax(mean) == int(np.argmax(rgba[:3])), obj.id
        # depth at the object's pixel = where that pixel's ray meets the cylinder, within 1 cm
        o, d = _ray(meta, ui, vi)
        expected = _cylinder_depth(o, d, centre, radius)
        assert abs(float(depth[vi, ui]) - expected) < 0.01, (obj.id, depth[vi, ui], expected)


def test_floor_depth_matches_plane(rendered: tuple[Scene, Path]) -> None:
    _, out = rendered
    meta, _, depth, seg = _load(out)
    floor = int(next(k for k, s in meta["segments"].items() if s["kind"] == "floor"))
    vs, us = np.nonzero(seg == floor)
    assert len(us) > 0
    for i in np.linspace(0, len(us) - 1, 7).astype(int):
        o, d = _ray(meta, float(us[i]), float(vs[i]))
        t = (-TABLE_HEIGHT - o[2]) / d[2]
        assert abs(float(depth[vs[i], us[i]]) - t) < 0.01


def test_model_cache_reloads_the_same_model(tmp_path: Path) -> None:
    scene = _scene()
    a = compile_scene(scene, cache=tmp_path)
    assert len(list(tmp_path.glob("*.mjb"))) == 1
    b = compile_scene(scene, cache=tmp_path)
    assert (a.model.nbody, a.model.ngeom, a.model.nq) == (b.model.nbody, b.model.ngeom, b.model.nq)
    assert np.array_equal(a.geom_segment, b.geom_segment)
    assert a.segments == b.segments


def test_ik_reaches_and_home_pose(rendered: tuple[Scene, Path]) -> None:
    scene, _ = rendered
    stage = Stage(compile_scene(scene, cache=False))
    base = scene.robots[0].base
    assert math.dist(stage.hand("r1"), (base[0], base[1], base[2] + 0.3)) < 1e-3
    target = (0.2, 0.2, 0.05)
    r = stage.solve("r1", target, stage.home["r1"])
    assert r.error < 1e-3
    stage.set_robot("r1", r.q)
    stage.forward()
    assert math.dist(stage.hand("r1"), target) < 1e-3


def test_fig1_robots_load(examples_dir: Path, tmp_path: Path) -> None:
    from hltl.world.scene import load_scene

    scene = load_scene(examples_dir / "scenes" / "fig1.yaml")
    stage = Stage(compile_scene(scene, cache=tmp_path))
    assert {r.model for r in stage.sm.robots.values()} == {"elfin3", "ur5"}
    assert len(stage.sm.robots["r2"].joint_names) == 6
    for rid in stage.sm.robots:
        base = scene.robot(rid).base
        assert math.dist(stage.hand(rid), (base[0], base[1], 0.3)) < 2e-3, rid
