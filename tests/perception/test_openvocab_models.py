"""The open-vocabulary path on tiny random-weight models loaded from local directories (OWLv2
boxes, SAM 2 masks, CLIP selection): the plumbing from a rendered frame to 3D and to a pick,
checked against transformers called directly and against geometry; never accuracy (no real
weights exist here: docs/perception.md)."""

from __future__ import annotations

import json
import math
from pathlib import Path
from types import SimpleNamespace
from typing import Any

import numpy as np
import numpy.typing as npt
import pytest
import yaml

from hltl.cli.main import main
from hltl.errors import BackendUnavailableError
from hltl.perception.clipselect import APPEARANCE, clip_embedder, crop_box, select_visual
from hltl.perception.detection import MIN_PIXELS
from hltl.perception.frames import write_frames
from hltl.perception.geometry import Cylinder
from hltl.perception.objects import localize, make_backend
from hltl.perception.openvocab import (
    IMAGENET_MEAN,
    IMAGENET_STD,
    SAM_ENV,
    WEIGHTS_ENV,
    OpenVocabBackend,
    Sam2Masker,
    TransformersBoxModel,
    box_mask,
    label_of,
)
from hltl.perception.synthetic import make_camera, render
from tests.perception.test_openvocab import SCENE, SOLIDS
from tests.perception.tiny_hf import (
    SAM_SIDE,
    save_clip,
    save_grounding_dino,
    save_owlv2,
    save_sam2,
    torch,
    transformers,
)


@pytest.fixture(scope="module")
def weights(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Path]:
    root = tmp_path_factory.mktemp("weights")
    return {
        "owl": save_owlv2(root / "owlv2"),
        "sam": save_sam2(root / "sam2"),
        "clip": save_clip(root / "clip"),
        "dino": save_grounding_dino(root / "grounding-dino"),
    }


def _in_box(shape: tuple[int, ...], box: tuple[float, float, float, float]) -> npt.NDArray[Any]:
    out = np.zeros(shape[:2], dtype=bool)
    out[int(box[1]) : math.ceil(box[3]), int(box[0]) : math.ceil(box[2])] = True
    return out


def test_owlv2_boxes_and_sam2_masks_run_from_a_rendered_frame_to_3d(
    weights: dict[str, Path], monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv(WEIGHTS_ENV, str(weights["owl"]))
    monkeypatch.setenv(SAM_ENV, str(weights["sam"]))
    # close up, so that the random masks overlap the objects
    cam = make_camera((0.55, -0.45, 0.5), (0.55, 0.12, 0.08), SOLIDS, width=320, height=240)
    frame = render(cam, SOLIDS)
    backend = make_backend("open-vocab", SCENE)
    assert isinstance(backend, OpenVocabBackend) and isinstance(backend.masker, Sam2Masker)
    backend.model.threshold = -1.0  # random weights score boxes anywhere in [0, 1]: keep all
    hits = backend.model.boxes(frame.rgb, backend.queries)
    shapes = backend.masker.masks(frame.rgb, [h.box for h in hits])
    assert hits and len(shapes) == len(hits)
    # the tiny OWLv2's grid boxes in the 320 × 320 square the 320 × 240 frame is padded to
    # (at the bottom): 80 px boxes centred on the patches' lower right corners, clipped to the
    # frame; the bottom row lies wholly in the padding and is dropped
    grid = sorted(
        (80.0 * j + 40, 80.0 * i + 40, min(80.0 * j + 120, 320), min(80.0 * i + 120, 240))
        for i in range(3)
        for j in range(4)
    )
    np.testing.assert_allclose(sorted(h.box for h in hits), grid, atol=0.05)
    for hit, shape in zip(hits, shapes, strict=True):
        assert hit.query in backend.queries
        assert shape.shape == frame.depth.shape and shape.dtype == np.bool_
    dets = backend.detect(frame, cam)
    assert dets  # fixed seeds: the same tiny models every run
    planes = backend.planes
    from_sam = 0
    for d in dets:
        assert d.kind == "object" and d.mask.sum() >= MIN_PIXELS
        assert not (d.mask & (frame.depth <= 0)).any()
        # every mask lies in a box of its label and in SAM 2's mask for that box
        owners = [
            i
            for i, h in enumerate(hits)
            if label_of(SCENE, h.query) == d.label
            and not (d.mask & ~(shapes[i] & _in_box(d.mask.shape, h.box))).any()
        ]
        assert owners
        depth_only = box_mask(
            frame.depth, backend.view(frame.depth, cam).z, hits[owners[0]].box, planes
        )
        from_sam += int(not np.array_equal(d.mask, depth_only))
    assert from_sam > 0  # SAM 2's masks, not the depth cut alone, shaped the detections
    for loc in localize(frame, cam, dets, planes, SCENE):
        assert all(math.isfinite(v) for v in loc.cylinder.center) and loc.pixels >= MIN_PIXELS


class BoxLogits:
    """Stands in for ``Sam2Model``: mask logits +1 inside each prompt box, -1 outside, at SAM 2's
    low resolution (a quarter of its input side)."""

    def __init__(self) -> None:
        self.calls: list[tuple[Any, Any, bool]] = []

    def __call__(self, pixel_values: Any, input_boxes: Any, multimask_output: bool) -> Any:
        self.calls.append((pixel_values, input_boxes, multimask_output))
        side = SAM_SIDE // 4
        out = -torch.ones(1, input_boxes.shape[1], 1, side, side)
        for i, (u0, v0, u1, v1) in enumerate(input_boxes[0].tolist()):
            out[0, i, 0, round(v0 / 4) : round(v1 / 4), round(u0 / 4) : round(u1 / 4)] = 1.0
        return SimpleNamespace(pred_masks=out)


def test_sam2_gets_its_input_and_box_prompts_scaled_and_its_masks_come_back_to_the_frame(
    weights: dict[str, Path],
) -> None:
    masker = Sam2Masker(weights["sam"])
    assert masker.size == SAM_SIDE  # no preprocessor_config.json: the model's prompt side
    fake = BoxLogits()
    masker.model = fake
    rgb = np.empty((120, 160, 3), dtype=np.uint8)
    rgb[:] = (200, 100, 50)
    boxes = [(20.0, 30.0, 80.0, 90.0), (100.0, 8.0, 152.0, 60.0)]
    masks = masker.masks(rgb, boxes)
    ((pixels, prompts, multimask),) = fake.calls
    assert tuple(pixels.shape) == (1, 3, SAM_SIDE, SAM_SIDE) and multimask is False
    colour = (np.array([200, 100, 50]) / 255.0 - IMAGENET_MEAN) / IMAGENET_STD
    np.testing.assert_allclose(pixels[0, :, 64, 64].numpy(), colour, atol=1e-5)
    sx, sy = SAM_SIDE / 160, SAM_SIDE / 120
    np.testing.assert_allclose(
        prompts[0].numpy(), [[b[0] * sx, b[1] * sy, b[2] * sx, b[3] * sy] for b in boxes], rtol=1e-6
    )
    for mask, box in zip(masks, boxes, strict=True):
        truth = _in_box(mask.shape, box)
        assert mask.shape == (120, 160)
        assert (mask & truth).sum() / (mask | truth).sum() > 0.9
    assert masker.masks(rgb, []) == [] and len(fake.calls) == 1


def _unit(v: Any) -> npt.NDArray[np.float64]:
    a = np.asarray(v.pooler_output if hasattr(v, "pooler_output") else v, dtype=float)
    return a / np.linalg.norm(a, axis=1, keepdims=True)


def test_clip_selection_picks_the_crop_whose_embedding_is_closest_to_the_words(
    weights: dict[str, Path],
) -> None:
    rng = np.random.default_rng(3)
    crops = [
        ("red", np.full((30, 20, 3), (220, 30, 30), np.uint8)),
        ("green", np.full((40, 25, 3), (30, 200, 60), np.uint8)),
        ("noise", rng.integers(0, 256, (24, 24, 3), dtype=np.uint8)),
    ]
    # the oracle: transformers' CLIP called directly on the same crops and words
    model = transformers.CLIPModel.from_pretrained(weights["clip"], local_files_only=True).eval()
    proc = transformers.CLIPProcessor.from_pretrained(weights["clip"], local_files_only=True)
    with torch.no_grad():
        img = _unit(
            model.get_image_features(**proc(images=[c for _, c in crops], return_tensors="pt"))
        )
        txt = _unit(model.get_text_features(**proc(text=["a red cup"], return_tensors="pt")))
    sims = img @ txt[0]
    order = np.argsort(-sims)
    emb = clip_embedder(weights["clip"])
    sel = select_visual("a red cup", crops, emb, threshold=-1.0)
    assert sel.key == crops[order[0]][0] and sel.runner_up == crops[order[1]][0]
    assert sel.word == APPEARANCE and sel.similarity == pytest.approx(sims[order[0]], abs=1e-5)
    none = select_visual("a red cup", crops, emb, threshold=float(sims.max()) + 0.01)
    assert none.key is None and "nothing in view matches 'a red cup'" in none.describe()
    twins = select_visual("a red cup", [("a", crops[0][1]), ("b", crops[0][1].copy())], emb, -1.0)
    assert twins.ambiguous and twins.similarity == pytest.approx(twins.runner_up_similarity)
    assert select_visual("a red cup", [], emb).key is None


def _folder(tmp_path: Path) -> tuple[Path, Path]:
    cam = make_camera((0.5, -1.4, 1.2), (0.5, 0.3, 0.0), SOLIDS, width=160, height=120)
    root = write_frames(tmp_path / "frames", cam, [render(cam, SOLIDS)])
    scene = tmp_path / "scene.yaml"
    scene.write_text(
        yaml.safe_dump(
            {
                "robots": [{"id": "r1", "base": [0, 0, 0], "reach": 0.7}],
                "objects": [
                    {"id": o.id, "category": o.category, "position": list(o.position)}
                    for o in SCENE.objects
                ],
            }
        )
    )
    return root, scene


def test_perceive_selects_by_appearance_with_clip_weights(
    weights: dict[str, Path], tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    root, scene = _folder(tmp_path)
    args = ["perceive", str(root), "--scene", str(scene), "--people", "none", "--json"]
    assert main([*args, "--select", "green bottle", "--clip", str(weights["clip"])]) == 0
    out = json.loads(capsys.readouterr().out)
    sel, objects = out["select"], out["frames"][-1]["objects"]
    assert sel["by"] == "clip" and {o["id"] for o in objects} == {"bottle", "chips"}
    # every object's crop is in the image, and the pick is one of them or an honest "nothing"
    cam = make_camera((0.5, -1.4, 1.2), (0.5, 0.3, 0.0), SOLIDS, width=160, height=120)
    for s in SOLIDS:
        assert crop_box(Cylinder(s.center, s.radius, s.height), cam) is not None
    assert sel["id"] in ("bottle", "chips") or "nothing in view matches" in sel["message"]


def test_bad_weight_directories_are_one_clear_error(
    weights: dict[str, Path],
    tmp_path: Path,
    capsys: pytest.CaptureFixture[str],
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    root, scene = _folder(tmp_path)
    args = ["perceive", str(root), "--scene", str(scene), "--people", "none", "--select", "cup"]
    for clip in (tmp_path / "missing", weights["sam"]):  # nothing there; a model that is no CLIP
        assert main([*args, "--clip", str(clip)]) == 1
        err = capsys.readouterr().err.strip().splitlines()
        assert len(err) == 1 and err[0].startswith("error:"), err
    monkeypatch.setenv(WEIGHTS_ENV, str(weights["clip"]))  # CLIP is no detector
    with pytest.raises(BackendUnavailableError, match="cannot load"):
        make_backend("open-vocab", SCENE)
    monkeypatch.setenv(WEIGHTS_ENV, str(weights["owl"]))
    monkeypatch.setenv(SAM_ENV, str(tmp_path))
    with pytest.raises(BackendUnavailableError, match=SAM_ENV):
        make_backend("open-vocab", SCENE)


def test_grounding_dino_boxes_are_named_by_the_query_whose_token_scores_highest(
    weights: dict[str, Path],
) -> None:
    model = TransformersBoxModel(weights["dino"], threshold=-1.0)  # keep every box
    assert model.grounding
    queries = ("bottle", "chips", "crisps")
    rgb = render(make_camera((0.5, -1.4, 1.2), (0.5, 0.3, 0.0), SOLIDS, 160, 120), SOLIDS).rgb
    hits = model.boxes(rgb, queries)
    # the oracle: the model and transformers' own post-processing called directly
    proc = model.processor
    inputs = proc(images=rgb, text="bottle . chips . crisps .", return_tensors="pt")
    with torch.no_grad():
        out = model.model(**inputs)
    ref = proc.post_process_grounded_object_detection(
        out, inputs.input_ids, threshold=0.0, text_threshold=0.0, target_sizes=[(120, 160)]
    )[0]
    assert len(hits) <= len(ref["boxes"]) == 20
    clipped = [
        (
            min(max(b[0], 0), 160),
            min(max(b[1], 0), 120),
            min(max(b[2], 0), 160),
            min(max(b[3], 0), 120),
        )
        for b in ref["boxes"].tolist()
    ]
    kept = [b for b in clipped if b[2] > b[0] and b[3] > b[1]]
    np.testing.assert_allclose(sorted(h.box for h in hits), sorted(kept), atol=1e-3)
    tokens = proc.tokenizer.convert_ids_to_tokens(inputs.input_ids[0].tolist())
    at = [tokens.index(q) for q in queries]  # one token per query in the tiny vocabulary
    probs = torch.sigmoid(out.logits[0])[:, at]
    for hit in hits:
        i = next(k for k, b in enumerate(clipped) if np.allclose(b, hit.box, atol=1e-3))
        assert hit.query == queries[int(probs[i].argmax())]
        assert hit.score == pytest.approx(float(probs[i].max()), abs=1e-5)
