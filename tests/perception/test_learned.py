"""The learned object backend: shipped weights on a held-out render, training, labels."""

from __future__ import annotations

import json
import math
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from hltl.perception.frames import Frame
from hltl.perception.learned import (
    CHANNELS,
    CLASSES,
    SHIPPED,
    LearnedBackend,
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
from hltl.sim3d.model import compile_scene
from hltl.sim3d.stage import Stage
from hltl.world.scene import Camera

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
