"""Open-vocabulary object detection from user-supplied local weights (paper §III-A)."""

from __future__ import annotations

import importlib
import json
import os
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Protocol

import numpy as np
import numpy.typing as npt

from hltl.errors import BackendUnavailableError
from hltl.perception.detection import MIN_PIXELS, DepthBackend, Detection, Mask, box_of
from hltl.perception.detection import support_planes as find_planes
from hltl.perception.frames import Camera, Frame
from hltl.world.scene import Scene

WEIGHTS_ENV = "HLTL_OPEN_VOCAB_WEIGHTS"
SAM_ENV = "HLTL_SAM2_WEIGHTS"  # optional: SAM 2 masks from the detector's boxes
THRESHOLD = 0.25  # box score below which a detection is dropped
# the categories the 3D simulator renders: the queries without a scene
DEFAULT_QUERIES = ("bottle", "chips", "cup", "mug", "can", "apple", "box", "book")
IMAGENET_MEAN = (0.485, 0.456, 0.406)  # SAM 2's default image normalisation
IMAGENET_STD = (0.229, 0.224, 0.225)
SURFACE_DEPTH = 0.15  # m: a box's object is its pixels this far behind the nearest ones


@dataclass(frozen=True, slots=True)
class BoxHit:
    """One box of a zero-shot detector: pixel box (u0, v0, u1, v1), the query it matches."""

    box: tuple[float, float, float, float]
    query: str
    score: float


class BoxModel(Protocol):
    def boxes(self, rgb: npt.NDArray[np.uint8], queries: Sequence[str]) -> list[BoxHit]: ...


def hf_modules() -> tuple[Any, Any]:
    """``transformers`` and ``torch``, imported on first use, with the hub switched off.

    Imported by name (typed as Any): transformers' own annotations leave most of its loaders
    untyped, and the package is an optional extra.

    Raises:
        BackendUnavailableError: either is not installed.
    """
    os.environ["HF_HUB_OFFLINE"] = "1"  # before the hub's client reads it: never reach for it
    try:
        torch = importlib.import_module("torch")
        transformers = importlib.import_module("transformers")
    except ImportError as exc:
        raise BackendUnavailableError(
            "the open-vocabulary backends need transformers and torch: "
            "pip install 'hltl[openvocab]'"
        ) from exc
    transformers.logging.set_verbosity_error()  # its notes and progress bars: not ours to print
    transformers.utils.logging.disable_progress_bar()
    return transformers, torch


def weights_dir(
    path: str | Path | None = None, env: str = WEIGHTS_ENV, what: str = "detector"
) -> Path:
    """A local weights directory: ``path`` or ``$env``.

    Raises:
        BackendUnavailableError: neither names an existing directory with a ``config.json``.
    """
    raw = path if path is not None else os.environ.get(env)
    if not raw:
        raise BackendUnavailableError(
            f"the open-vocabulary backend needs local {what} weights: set {env} to a "
            f"directory holding {KINDS[what]} in the transformers format (nothing is "
            "downloaded)"
        )
    p = Path(raw)
    if not (p / "config.json").is_file():
        raise BackendUnavailableError(
            f"{env}={p}: not a transformers model directory (no config.json there)"
        )
    return p


KINDS = {
    "detector": "Grounding DINO or OWL-ViT/OWLv2",
    "SAM 2": "SAM 2 (Sam2Model)",
    "CLIP": "CLIP (or another model with get_image_features/get_text_features)",
}


def load_local(loader: Any, path: Path, what: str) -> Any:
    """``loader.from_pretrained(path)`` from local files only, its failures as one clear error.

    Raises:
        BackendUnavailableError: the directory does not hold a model ``loader`` can read.
    """
    try:
        return loader.from_pretrained(str(path), local_files_only=True)
    except (OSError, ValueError, KeyError, TypeError, AttributeError) as exc:
        raise BackendUnavailableError(
            f"{path}: cannot load {what} from it ({type(exc).__name__}: {str(exc)[:200]})"
        ) from None


class TransformersBoxModel:
    """A zero-shot detector (Grounding DINO, OWL-ViT, OWLv2) loaded from a local directory."""

    def __init__(self, path: Path, threshold: float = THRESHOLD) -> None:
        transformers, torch = hf_modules()
        self.threshold = threshold
        self.processor = load_local(transformers.AutoProcessor, path, "a detector's processor")
        self.model = load_local(
            transformers.AutoModelForZeroShotObjectDetection, path, "a zero-shot detector"
        ).eval()
        self._torch = torch
        kind = type(self.model).__name__.lower()
        self.grounding = "grounding" in kind
        # OWLv2 pads the image to a square at the bottom and right: its boxes are fractions of
        # that square's side (OWL-ViT resizes to a square: fractions of width and height)
        self.square = "owlv2" in kind

    def boxes(self, rgb: npt.NDArray[np.uint8], queries: Sequence[str]) -> list[BoxHit]:
        torch = self._torch
        h, w = rgb.shape[:2]
        if self.grounding:  # one prompt, phrases separated by dots
            inputs = self.processor(
                images=rgb, text=" . ".join(queries) + " .", return_tensors="pt"
            )
        else:
            inputs = self.processor(
                images=rgb, text=[list(queries)], return_tensors="pt", padding=True
            )
        with torch.no_grad():
            out = self.model(**inputs)
        if self.grounding:
            rows = self._grounded(out, inputs.input_ids[0], queries, w, h)
        else:
            side = (max(h, w), max(h, w)) if self.square else (h, w)
            res = self.processor.image_processor.post_process_object_detection(
                out, threshold=self.threshold, target_sizes=[side]
            )[0]
            labels = [queries[int(i)] for i in res["labels"]]
            rows = list(zip(res["boxes"].tolist(), labels, res["scores"].tolist(), strict=True))
        hits = []
        for b, lab, sc in rows:
            u0, v0 = min(max(b[0], 0.0), w), min(max(b[1], 0.0), h)
            u1, v1 = min(max(b[2], 0.0), w), min(max(b[3], 0.0), h)
            if u1 > u0 and v1 > v0:  # a box wholly outside the image (the padding) is dropped
                hits.append(BoxHit((u0, v0, u1, v1), lab, float(sc)))
        return hits

    def _grounded(
        self, out: Any, ids: Any, queries: Sequence[str], w: int, h: int
    ) -> list[tuple[list[float], str, float]]:
        """Grounding DINO's boxes, each named by the query whose tokens it scores highest (its
        post-processing names a box by every token over a threshold, joined: a phrase that
        need not be one query). The prompt's tokens between the separating dots are the
        queries' in order."""
        torch = self._torch
        dot = self.processor.tokenizer.convert_tokens_to_ids(".")
        spans: list[tuple[int, int]] = []
        start = 1  # after [CLS]
        for k, tid in enumerate(ids.tolist()):
            if tid == dot and k > start:
                spans.append((start, k))
                start = k + 1
        if len(spans) != len(queries):
            raise BackendUnavailableError(
                f"the detector's tokenizer split {len(queries)} queries into {len(spans)} "
                "phrases: cannot tell which query a box matches"
            )
        probs = torch.sigmoid(out.logits[0])  # (boxes, text tokens)
        per = torch.stack([probs[:, a:b].max(dim=-1).values for a, b in spans], dim=-1)
        score, best = per.max(dim=-1)
        cx, cy, bw, bh = out.pred_boxes[0].unbind(-1)
        corners = torch.stack(
            [(cx - bw / 2) * w, (cy - bh / 2) * h, (cx + bw / 2) * w, (cy + bh / 2) * h], dim=-1
        )
        keep = torch.nonzero(score > self.threshold).flatten().tolist()
        return [(corners[i].tolist(), queries[int(best[i])], float(score[i])) for i in keep]


class Sam2Masker:
    """SAM 2 (transformers' ``Sam2Model``) from a local directory: one mask per box prompt.

    The image is prepared as SAM 2's own processor does (resized to a square of
    ``preprocessor_config.json``'s size, default 1024, scaled to [0, 1], normalised by its mean
    and standard deviation, default ImageNet's), box corners scaled the same way; the low-
    resolution mask logits are resized back to the frame and thresholded at 0. It is done here,
    not by ``Sam2Processor``, because that processor needs torchvision, which would replace the
    CPU torch build this project pins.
    """

    def __init__(self, path: Path) -> None:
        transformers, torch = hf_modules()
        self.model = load_local(transformers.Sam2Model, path, "SAM 2").eval()
        self._torch = torch
        cfg: dict[str, Any] = {}
        pre = path / "preprocessor_config.json"
        if pre.is_file():
            cfg = json.loads(pre.read_text())
        size = cfg.get("size") or {}
        default = int(self.model.config.prompt_encoder_config.image_size)
        self.size = int(size.get("height", default)) if isinstance(size, dict) else default
        self.mean = tuple(float(v) for v in cfg.get("image_mean", IMAGENET_MEAN))
        self.std = tuple(float(v) for v in cfg.get("image_std", IMAGENET_STD))

    def masks(
        self, rgb: npt.NDArray[np.uint8], boxes: Sequence[tuple[float, float, float, float]]
    ) -> list[Mask]:
        """One H×W mask per pixel box (u0, v0, u1, v1); none for no boxes."""
        if not boxes:
            return []
        torch = self._torch
        fn = torch.nn.functional
        h, w = rgb.shape[:2]
        img = torch.from_numpy(np.ascontiguousarray(rgb[..., :3])).permute(2, 0, 1)[None].float()
        img = fn.interpolate(
            img / 255.0, size=(self.size, self.size), mode="bilinear", antialias=True
        )
        img = (img - torch.tensor(self.mean)[None, :, None, None]) / torch.tensor(self.std)[
            None, :, None, None
        ]
        scale = torch.tensor([self.size / w, self.size / h, self.size / w, self.size / h])
        prompts = torch.tensor([list(b) for b in boxes], dtype=torch.float32)[None] * scale
        with torch.no_grad():
            out = self.model(pixel_values=img, input_boxes=prompts, multimask_output=False)
        logits = out.pred_masks[0, :, 0]  # (boxes, h', w')
        full = fn.interpolate(logits[:, None], size=(h, w), mode="bilinear", align_corners=False)
        return [m[0].numpy() > 0.0 for m in full]


class MaskModel(Protocol):
    def masks(
        self, rgb: npt.NDArray[np.uint8], boxes: Sequence[tuple[float, float, float, float]]
    ) -> list[Mask]: ...


def queries_of(scene: Scene | None) -> tuple[str, ...]:
    """What to ask the detector for: the scene's categories and aliases, each once."""
    if scene is None or not scene.objects:
        return DEFAULT_QUERIES
    out: list[str] = []
    for o in scene.objects:
        for q in (o.category.lower(), *(a.lower() for a in o.aliases)):
            if q not in out:
                out.append(q)
    return tuple(out)


def label_of(scene: Scene | None, query: str) -> str:
    """The category a matched query names (an alias names its object's category)."""
    if scene is not None:
        for o in scene.objects:
            if query == o.category.lower() or query in (a.lower() for a in o.aliases):
                return o.category
    return query


class OpenVocabBackend(DepthBackend):
    """Boxes of a zero-shot detector, each cut to the object's pixels: by SAM 2 prompted with
    the box when SAM 2 weights are given (``$HLTL_SAM2_WEIGHTS``), then by depth."""

    name = "open-vocab"

    def __init__(
        self,
        scene: Scene | None = None,
        weights: str | Path | None = None,
        model: BoxModel | None = None,
        edge: float = 0.03,
        masker: MaskModel | None = None,
        sam_weights: str | Path | None = None,
    ) -> None:
        super().__init__(scene, edge)
        self.model: BoxModel = model or TransformersBoxModel(weights_dir(weights))
        if masker is None and (sam_weights is not None or os.environ.get(SAM_ENV)):
            masker = Sam2Masker(weights_dir(sam_weights, SAM_ENV, "SAM 2"))
        self.masker = masker
        self.queries = queries_of(scene)

    def detect(self, frame: Frame, camera: Camera) -> list[Detection]:
        view = self.view(frame.depth, camera)
        self.planes = find_planes(view.z[view.valid][::16], share=0.01)
        hits = self.model.boxes(frame.rgb, self.queries)
        shapes: list[Mask | None] = [None] * len(hits)
        if self.masker is not None:
            shapes = list(self.masker.masks(frame.rgb, [h.box for h in hits]))
        out: list[Detection] = []
        for hit, shape in zip(hits, shapes, strict=True):
            mask = box_mask(frame.depth, view.z, hit.box, self.planes, shape)
            if int(mask.sum()) < MIN_PIXELS:
                continue
            label = label_of(self.scene, hit.query)
            out.append(Detection("object", label, mask, hit.score, box_of(mask)))
        return out


def box_mask(
    depth: npt.NDArray[np.float32],
    z: npt.NDArray[np.float64],
    box: tuple[float, float, float, float],
    planes: Sequence[float],
    shape: Mask | None = None,
) -> Mask:
    """The object's pixels in a detector's box: those (of ``shape``, a segmenter's mask, when
    given) with a depth return, not on a support plane, and within SURFACE_DEPTH of the nearest
    5 % of them (the object is what the box is drawn around; what lies farther is behind it,
    or a mask's edge bleeding onto the background)."""
    h, w = depth.shape
    u0, v0 = max(int(box[0]), 0), max(int(box[1]), 0)
    u1, v1 = min(int(np.ceil(box[2])), w), min(int(np.ceil(box[3])), h)
    mask = np.zeros(depth.shape, dtype=bool)
    if u1 <= u0 or v1 <= v0:
        return mask
    d = depth[v0:v1, u0:u1]
    ok = d > 0
    if shape is not None:
        ok &= shape[v0:v1, u0:u1]
    for p in planes:
        ok &= np.abs(z[v0:v1, u0:u1] - p) > 0.01
    if not ok.any():
        return mask
    near = float(np.percentile(d[ok], 5))
    mask[v0:v1, u0:u1] = ok & (d <= near + SURFACE_DEPTH)
    return mask
