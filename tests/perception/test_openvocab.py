"""The open-vocabulary backend: user-supplied local weights only (never downloaded), a clear
error without them, and its boxes cut to objects by depth and localised like any backend's."""

from __future__ import annotations

import importlib.util
import math
import os
import sys
from collections.abc import Sequence
from pathlib import Path

import numpy as np
import numpy.typing as npt
import pytest

from hltl.cli.main import main
from hltl.errors import BackendUnavailableError
from hltl.perception.frames import write_frames
from hltl.perception.objects import localize, make_backend
from hltl.perception.observe import match_objects
from hltl.perception.openvocab import (
    WEIGHTS_ENV,
    BoxHit,
    OpenVocabBackend,
    TransformersBoxModel,
    queries_of,
    weights_dir,
)
from hltl.perception.synthetic import Solid, make_camera, render
from hltl.world.scene import Robot, Scene, SceneObject

BOTTLE = Solid("object", "bottle", (0.3, 0.2, 0.0), 0.035, 0.22, (30, 140, 80))
CHIPS = Solid("object", "chips", (0.8, 0.05, 0.0), 0.05, 0.18, (240, 190, 30))
SOLIDS = (BOTTLE, CHIPS)
SCENE = Scene(
    robots=(Robot("r1", (0.0, 0.0, 0.0), 0.7),),
    objects=(
        SceneObject("bottle", "bottle", (0.3, 0.2, 0.05)),
        SceneObject("chips", "chips", (0.8, 0.05, 0.05), ("crisps",)),
    ),
)


class BoxesFromSegmentation:
    """A stand-in detector: the box of each solid's pixels (grown 4 px), named by a query."""

    def __init__(self, seg: npt.NDArray[np.int32], names: dict[int, str]) -> None:
        self.seg, self.names = seg, names
        self.asked: list[tuple[str, ...]] = []

    def boxes(self, rgb: npt.NDArray[np.uint8], queries: Sequence[str]) -> list[BoxHit]:
        self.asked.append(tuple(queries))
        out = []
        for sid, name in self.names.items():
            v, u = np.nonzero(self.seg == sid)
            box = (u.min() - 4.0, v.min() - 4.0, u.max() + 5.0, v.max() + 5.0)
            out.append(BoxHit(box, name, 0.8))
        return out


def test_without_weights_the_backend_says_what_is_missing(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    monkeypatch.delenv(WEIGHTS_ENV, raising=False)
    with pytest.raises(BackendUnavailableError, match=WEIGHTS_ENV):
        make_backend("open-vocab", SCENE)
    monkeypatch.setenv(WEIGHTS_ENV, str(tmp_path))
    with pytest.raises(BackendUnavailableError, match=r"no config\.json"):
        weights_dir()
    (tmp_path / "config.json").write_text("{}")
    assert weights_dir() == tmp_path
    monkeypatch.setitem(sys.modules, "transformers", None)  # as if not installed
    with pytest.raises(BackendUnavailableError, match="openvocab"):
        TransformersBoxModel(tmp_path)


def test_perceive_with_the_open_vocabulary_backend_and_no_weights_is_one_error_line(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    monkeypatch.delenv(WEIGHTS_ENV, raising=False)
    cam = make_camera((0.5, -1.4, 1.2), (0.5, 0.3, 0.0), SOLIDS)
    d = write_frames(tmp_path / "f", cam, [render(cam, SOLIDS)])
    assert main(["perceive", str(d), "--backend", "open-vocab", "--people", "none"]) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("error:") and WEIGHTS_ENV in err[0]


def test_boxes_are_cut_to_the_object_by_depth_and_localised_within_a_centimetre() -> None:
    cam = make_camera((0.5, -1.4, 1.2), (0.5, 0.3, 0.0), SOLIDS, width=320, height=240)
    frame = render(cam, SOLIDS)
    assert frame.seg is not None
    fake = BoxesFromSegmentation(frame.seg, {1: "bottle", 2: "crisps"})  # an alias
    backend = OpenVocabBackend(SCENE, model=fake)
    assert fake.asked == [] and backend.queries == queries_of(SCENE) == (
        "bottle",
        "chips",
        "crisps",
    )
    dets = backend.detect(frame, cam)
    assert [d.label for d in dets] == ["bottle", "chips"]
    for d, sid in zip(dets, (1, 2), strict=True):
        truth = frame.seg == sid
        # the box holds floor pixels too: the depth cut keeps the object's, nothing else
        assert (d.mask & ~truth).sum() == 0 and (d.mask & truth).sum() >= 0.9 * truth.sum()
    located = localize(frame, cam, dets, backend.planes, SCENE)
    obs, unmatched, ambiguous = match_objects(SCENE, located)
    assert unmatched == [] and ambiguous == []
    truth3 = {"bottle": BOTTLE.center, "chips": CHIPS.center}
    for o in obs:
        assert o.id is not None and math.dist(o.position, truth3[o.id]) < 0.01


@pytest.mark.skipif(
    not os.environ.get(WEIGHTS_ENV) or importlib.util.find_spec("transformers") is None,
    reason=f"needs transformers and local zero-shot detector weights in ${WEIGHTS_ENV}",
)
def test_real_weights_find_a_rendered_object() -> None:  # pragma: no cover - weights only
    cam = make_camera((0.5, -1.4, 1.2), (0.5, 0.3, 0.0), SOLIDS, width=640, height=480)
    frame = render(cam, SOLIDS)
    backend = make_backend("open-vocab", SCENE)
    dets = backend.detect(frame, cam)
    assert all(d.kind == "object" and d.label in ("bottle", "chips") for d in dets)
