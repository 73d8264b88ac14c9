"""The learned object backend: shipped weights on a held-out render, training, labels."""

from __future__ import annotations

import json
import math
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

from hltl.perception.frames import Frame
from hltl.perception.learned import (
    CHANNELS,
    CLASSES,
    CONFUSED,
    SHIPPED,
    SIZES,
    LearnedBackend,
    PixelProbabilities,
    downsample_labels,
    load_segmenter,
    train,
)
from hltl.perception.objects import localize, make_backend
from hltl.perception.observe import match_objects
from hltl.sim.scenarios import get
from hltl.sim3d.camera import CameraRenderer
from hltl.sim3d.dataset import TRAIN_CELLS, frame_camera, object_centres, render_samples
from hltl.sim3d.gl import require_renderer
from hltl.sim3d.model import compile_scene, object_look
from hltl.sim3d.stage import Stage
from hltl.world.scene import Camera, SceneObject

torch = pytest.importorskip("torch")


def _renderer() -> None:
    pytest.importorskip("mujoco")
    try:
        require_renderer()
    except Exception as exc:
        pytest.skip(f"no offscreen renderer: {exc}")


def test_shipped_weights_find_the_objects_of_a_held_out_cell() -> None:
    # fig1 is not among the training cells (hltl.sim3d.dataset.TRAIN_CELLS)
    _renderer()

    assert "fig1" not in TRAIN_CELLS
    scene = get("fig1").scene
    cam = Camera("above", (0.55, -1.4, 2.2), (0.55, -0.05, 0.0))
    scene = replace(scene, cameras=(cam,))
    stage = Stage(compile_scene(scene))
    with CameraRenderer(stage.sm, cam, geometry="collision") as r:
        f = r.render(stage.data)
    fcam = frame_camera(cam, stage.sm.segment_table())
    frame = Frame(0, 0.0, f.rgb, f.depth, f.seg)
    backend = make_backend("learned", scene)
    assert isinstance(backend, LearnedBackend)
    dets = backend.detect(frame, fcam)
    located = localize(frame, fcam, dets, backend.planes, scene)
    obs, _, _ = match_objects(scene, located)
    truth = object_centres(stage)
    found = {o.id: o for o in obs if o.id}
    assert "chips" in found  # the bottle stands behind a person's arm: only its top shows
    for oid, o in found.items():
        assert math.dist(o.position, truth[oid]) < 0.03, oid
    assert all(0.0 <= d.score <= 1.0 for d in dets)


def test_the_shipped_file_records_how_it_was_trained() -> None:
    with np.load(SHIPPED) as data:
        meta = json.loads(str(data["meta"]))
    assert meta["command"].startswith("hltl perception train-detector --seed=")
    assert tuple(meta["classes"]) == CLASSES
    assert SHIPPED.stat().st_size < 500_000


def test_one_training_epoch_writes_weights_that_load(tmp_path: Path) -> None:
    rng = np.random.default_rng(0)
    samples = []
    for _ in range(3):
        x = rng.normal(size=(CHANNELS, 24, 32)).astype(np.float32)
        y = np.zeros((24, 32), np.int64)
        y[5:12, 8:14] = CLASSES.index("cup")
        samples.append((x, y))
    res = train(samples, tmp_path / "w.npz", seed=3, epochs=1, crop=16, command="test")
    assert res.images == 3 and math.isfinite(res.train_loss)
    model = load_segmenter(res.path)
    p = model.probabilities(samples[0][0])
    assert p.shape == (len(CLASSES), 24, 32)
    assert np.allclose(p.sum(axis=0), 1.0, atol=1e-4)
    assert model.meta["seed"] == 3 and model.meta["command"] == "test"


def test_bad_weights_files_are_refused(tmp_path: Path) -> None:
    bad = tmp_path / "bad.npz"
    bad.write_text("x")
    with pytest.raises(ValueError, match="not an object segmenter weights file"):
        load_segmenter(bad)
    with pytest.raises(FileNotFoundError):
        load_segmenter(tmp_path / "missing.npz")


def test_labels_of_a_render_follow_the_segmentation() -> None:
    _renderer()
    (s,) = render_samples([get("1-1").scene], seed=1, layouts=1, views=1)
    assert s.frame.seg is not None
    for sid, seg in s.camera.segments.items():
        mask = s.frame.seg == sid
        if not mask.any():
            continue
        got = set(np.unique(s.labels[mask]).tolist())
        if seg.kind == "human":
            assert got == {CLASSES.index("person")}
        elif seg.kind != "object":
            assert got == {0}
    objects = s.labels >= 2
    assert objects.any()  # the clutter is in view
    half = downsample_labels(s.labels)
    assert half.shape == (s.labels.shape[0] // 2, s.labels.shape[1] // 2)


def test_sizes_are_the_ones_the_simulator_renders() -> None:
    for category, size in SIZES.items():
        radius, height, _ = object_look(SceneObject("o", category, (0.0, 0.0, 0.05)))
        assert (radius, height) == pytest.approx(size), category
    assert set(CONFUSED) <= set(SIZES)


def _standing(category: str, plane: float, seen: float, rng: np.random.Generator) -> np.ndarray:
    """Points of a category's cylinder standing on ``plane`` as a camera above sees it: the
    near half of its side up to ``seen`` of its height, and its top disc if all of it shows."""
    r, h = SIZES[category]
    n = 300
    a = rng.uniform(-math.pi / 2, math.pi / 2, n)
    z = plane + rng.uniform(0.0, seen * h, n)
    side = np.stack([r * np.cos(a), r * np.sin(a), z], axis=1)
    if seen < 1.0:
        return side
    rho, b = r * np.sqrt(rng.uniform(0, 1, n)), rng.uniform(0, 2 * math.pi, n)
    top = np.stack([rho * np.cos(b), rho * np.sin(b), np.full(n, plane + h)], axis=1)
    return np.concatenate([side, top])


def _network(truth: int, share: float, split: float) -> PixelProbabilities:
    """A 4×4 (half-resolution) probability map over the classes giving the true red category
    ``share``, the other two the rest in the ratio ``split``."""
    prob = np.zeros((len(CLASSES), 4, 4), np.float32)
    others = [c for c in CONFUSED if CONFUSED.index(c) != truth]
    prob[CLASSES.index(CONFUSED[truth])] = share
    prob[CLASSES.index(others[0])] = (1 - share) * split
    prob[CLASSES.index(others[1])] = (1 - share) * (1 - split)
    return PixelProbabilities(prob)


@settings(max_examples=40, deadline=None)
@given(
    truth=st.integers(0, len(CONFUSED) - 1),
    plane=st.floats(-0.05, 0.3),
    share=st.floats(0.05, 1.0),
    split=st.floats(0.0, 1.0),
    # depth noise up to 5 mm: the top is fitted unbiased (geometry.top_height); the 98th
    # percentile read ~2 noise sigmas high and lost to a 15:1 network at 2.9 mm
    noise=st.floats(0.0, 0.005),
    seed=st.integers(0, 2**16),
)
# the lowest of 600 noisy points 1.3 cm under the table: the floor was taken as the plane under it
@example(truth=0, plane=0.0, share=0.25, split=0.0, noise=0.004391391253862464, seed=11025)
def test_a_red_object_seen_whole_is_named_by_its_height(
    truth: int, plane: float, share: float, split: float, noise: float, seed: int
) -> None:
    # the network may favour a wrong red category 19:1: the measured height still decides
    rng = np.random.default_rng(seed)
    backend = _backend()
    backend.planes = [plane - 0.8, plane]  # the floor and the table it stands on
    q = _standing(CONFUSED[truth], plane, 1.0, rng)
    q[:, 2] += rng.normal(0.0, noise, len(q))
    mask = np.ones((8, 8), dtype=bool)
    assert backend._name(CONFUSED, q, _network(truth, share, split), mask) == CONFUSED[truth]


@settings(max_examples=20, deadline=None)
@given(truth=st.integers(0, len(CONFUSED) - 1), split=st.floats(0.0, 1.0))
def test_a_red_object_with_its_top_hidden_is_named_by_the_network(truth: int, split: float) -> None:
    # a 4.5 cm stump is shorter than each red category: every one could be it, top hidden
    backend = _backend()
    backend.planes = [0.0]
    r = 0.035
    a = np.linspace(-1.5, 1.5, 200)
    q = np.stack([r * np.cos(a), r * np.sin(a), np.linspace(0.0, 0.045, 200)], axis=1)
    mask = np.ones((8, 8), dtype=bool)
    name = backend._name(CONFUSED, q, _network(truth, 0.6, split), mask)
    assert name == CONFUSED[truth]


_BACKEND: list[LearnedBackend] = []


def _backend() -> LearnedBackend:
    if not _BACKEND:
        _BACKEND.append(LearnedBackend())
    return _BACKEND[0]


def test_apple_can_and_mug_on_one_table_are_told_apart() -> None:
    # the three red categories side by side in a cell the network was not trained on
    _renderer()
    scene = get("fig1").scene
    x, y = 0.55, -0.25
    objects = tuple(
        SceneObject(c, c, (x + dx, y, 0.05))
        for c, dx in (("apple", -0.15), ("can", 0.0), ("mug", 0.15))
    )
    cam = Camera("near", (x, y - 0.9, 0.7), (x, y, 0.0))
    scene = replace(scene, objects=objects, cameras=(cam,))
    stage = Stage(compile_scene(scene, cache=False))
    with CameraRenderer(stage.sm, cam, geometry="visual") as r:
        f = r.render(stage.data)
    frame = Frame(0, 0.0, f.rgb, f.depth, f.seg)
    fcam = frame_camera(cam, stage.sm.segment_table())
    backend = make_backend("learned", scene)
    dets = backend.detect(frame, fcam)
    obs, _, _ = match_objects(scene, localize(frame, fcam, dets, backend.planes, scene))
    truth = object_centres(stage)
    found = {o.id: o for o in obs if o.id}
    assert set(found) == {"apple", "can", "mug"}, [(d.label, d.box) for d in dets]
    for oid, o in found.items():
        assert o.label == oid
        assert math.dist(o.position, truth[oid]) < 0.03, oid


@settings(max_examples=30, deadline=None)
@given(
    h=st.integers(2, 9),
    w=st.integers(2, 9),
    box=st.tuples(st.integers(0, 8), st.integers(0, 8), st.integers(0, 8), st.integers(0, 8)),
    seed=st.integers(0, 2**16),
)
def test_pixel_probabilities_take_the_zoomed_pass_where_it_is_far(
    h: int, w: int, box: tuple[int, int, int, int], seed: int
) -> None:
    # oracle: the full-resolution map written out pixel by pixel
    rng = np.random.default_rng(seed)
    half = rng.dirichlet(np.ones(len(CLASSES)), size=(h // 2, w // 2)).transpose(2, 0, 1)
    v0, v1 = sorted((min(box[0], h), min(box[1], h)))
    u0, u1 = sorted((min(box[2], w), min(box[3], w)))
    zoom = rng.dirichlet(np.ones(len(CLASSES)), size=(v1 - v0, u1 - u0)).transpose(2, 0, 1)
    far = rng.random((v1 - v0, u1 - u0)) < 0.5
    prob = PixelProbabilities(
        half.astype(np.float32), (v0, v1, u0, u1), zoom.astype(np.float32), far
    )
    want = np.zeros((len(CLASSES), h, w))
    want[0] = 1.0
    for v in range(h):
        for u in range(w):
            if v0 <= v < v1 and u0 <= u < u1 and far[v - v0, u - u0]:
                want[:, v, u] = zoom[:, v - v0, u - u0]
            elif v < 2 * (h // 2) and u < 2 * (w // 2):
                want[:, v, u] = half[:, v // 2, u // 2]
    red = [CLASSES.index(c) for c in CONFUSED]
    merged = want.copy()
    merged[red[0]] = want[red].sum(axis=0)
    merged[red[1:]] = 0.0
    cls, conf = prob.labels((h, w))
    assert (cls == merged.argmax(axis=0)).all()
    assert conf == pytest.approx(merged.max(axis=0), abs=1e-5)
    mask = rng.random((h, w)) < 0.5
    inside = mask & ~((np.arange(h)[:, None] >= 2 * (h // 2)) | (np.arange(w) >= 2 * (w // 2)))
    inside |= mask & _far_mask(h, w, (v0, v1, u0, u1), far)
    if inside.any():
        k = int(rng.integers(len(CLASSES)))
        assert prob.mean(k, inside) == pytest.approx(float(want[k][inside].mean()), abs=1e-5)


def _far_mask(h: int, w: int, box: tuple[int, int, int, int], far: np.ndarray) -> np.ndarray:
    out = np.zeros((h, w), dtype=bool)
    v0, v1, u0, u1 = box
    out[v0:v1, u0:u1] = far
    return out


def _cylinder_points(
    category: str, x: float, y: float, plane: float, rng: np.random.Generator
) -> np.ndarray:
    """The near half of a category's cylinder standing at (x, y) on ``plane``, and its top."""
    out: np.ndarray = _standing(category, plane, 1.0, rng) + np.array([x, y, 0.0])
    return out


def _region(*clouds: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """A one-row 'image' holding the clouds' points and the mask of all of them."""
    q = np.concatenate(clouds)
    return q[None], np.ones((1, len(q)), dtype=bool)


@settings(max_examples=30, deadline=None)
@given(
    first=st.sampled_from(CONFUSED),
    second=st.sampled_from(CONFUSED),
    angle=st.floats(0.0, 2 * math.pi),
    gap=st.floats(0.0, 0.02),
    seed=st.integers(0, 2**16),
)
def test_two_red_objects_side_by_side_in_one_region_are_two_objects(
    first: str, second: str, angle: float, gap: float, seed: int
) -> None:
    # touching in the image with no depth edge between: one region of the merged red class
    rng = np.random.default_rng(seed)
    backend = _backend()
    backend.planes = [-0.75, 0.0]
    d = SIZES[first][0] + SIZES[second][0] + gap
    a = _cylinder_points(first, 0.0, 0.0, 0.0, rng)
    b = _cylinder_points(second, d * math.cos(angle), d * math.sin(angle), 0.0, rng)
    pts, mask = _region(a, b)
    r = max(SIZES[c][0] for c in CONFUSED)
    hgt = max(SIZES[c][1] for c in CONFUSED)
    found = backend._shaped(mask, pts, r, hgt)
    assert len(found) == 2
    truth = np.arange(len(a) + len(b)) >= len(a)
    # each is mostly one of the two objects: 2-means draws the boundary between the clouds'
    # means, which sit on the visible sides, so up to ~1/6 of a touching pair's points go to
    # the other object (worst 0.83 over all pairs at 5° steps, no gap)
    for m in found:
        purity = max(float(np.mean(truth[m[0]])), float(np.mean(~truth[m[0]])))
        assert purity >= 0.75


@settings(max_examples=30, deadline=None)
@given(share=st.floats(0.02, 0.15), seed=st.integers(0, 2**16))
def test_stray_pixels_around_an_object_are_dropped_not_the_object(share: float, seed: int) -> None:
    # a few pixels of a link or a neighbour 10-25 cm off, joined to a cup's region
    rng = np.random.default_rng(seed)
    backend = _backend()
    backend.planes = [-0.75, -0.015]
    cup = _cylinder_points("cup", 0.3, 0.2, 0.0, rng)
    n = int(share * len(cup) / (1 - share)) + 1
    ang, dist = rng.uniform(0, 2 * math.pi, n), rng.uniform(0.1, 0.25, n)
    z = rng.uniform(0.0, 0.1, n)
    fringe = np.stack([0.3 + dist * np.cos(ang), 0.2 + dist * np.sin(ang), z], axis=1)
    pts, mask = _region(cup, fringe)
    found = backend._shaped(mask, pts, *SIZES["cup"])
    assert len(found) == 1
    assert (found[0][0] == (np.arange(len(cup) + n) < len(cup))).all()


def test_three_in_a_row_are_not_guessed_into_one() -> None:
    rng = np.random.default_rng(0)
    backend = _backend()
    backend.planes = [0.0]
    clouds = [_cylinder_points("can", 0.07 * i, 0.0, 0.0, rng) for i in range(3)]
    pts, mask = _region(*clouds)
    assert backend._shaped(mask, pts, *SIZES["can"]) == []
