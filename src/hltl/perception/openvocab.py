"""Open-vocabulary object detection from user-supplied local weights (paper §III-A)."""

from __future__ import annotations

import importlib
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
THRESHOLD = 0.25  # box score below which a detection is dropped
# the categories the 3D simulator renders: the queries without a scene
DEFAULT_QUERIES = ("bottle", "chips", "cup", "mug", "can", "apple", "box", "book")
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
    return transformers, torch


def weights_dir(path: str | Path | None = None) -> Path:
    """The local weights directory: ``path`` or ``$HLTL_OPEN_VOCAB_WEIGHTS``.

    Raises:
        BackendUnavailableError: neither names an existing directory with a ``config.json``.
    """
    raw = path if path is not None else os.environ.get(WEIGHTS_ENV)
    if not raw:
        raise BackendUnavailableError(
            f"the open-vocabulary backend needs local detector weights: set {WEIGHTS_ENV} to a "
            "directory holding Grounding DINO or OWL-ViT in the transformers format (nothing "
            "is downloaded)"
        )
    p = Path(raw)
    if not (p / "config.json").is_file():
        raise BackendUnavailableError(
            f"{WEIGHTS_ENV}={p}: not a transformers model directory (no config.json there)"
        )
    return p


class TransformersBoxModel:
    """A zero-shot detector (Grounding DINO, OWL-ViT, OWLv2) loaded from a local directory."""

    def __init__(self, path: Path) -> None:
        transformers, torch = hf_modules()
        try:
            self.processor = transformers.AutoProcessor.from_pretrained(
                str(path), local_files_only=True
            )
            self.model = transformers.AutoModelForZeroShotObjectDetection.from_pretrained(
                str(path), local_files_only=True
            )
        except (OSError, ValueError, KeyError) as exc:
            raise BackendUnavailableError(
                f"{path}: cannot load a zero-shot detector from it ({type(exc).__name__}: "
                f"{str(exc)[:200]})"
            ) from None
        self.model.eval()
        self._torch = torch
        self.grounding = "grounding" in type(self.model).__name__.lower()

    def boxes(self, rgb: npt.NDArray[np.uint8], queries: Sequence[str]) -> list[BoxHit]:
        torch = self._torch
        h, w = rgb.shape[:2]
        if self.grounding:  # one prompt, phrases separated by dots
            text: Any = " . ".join(queries) + " ."
        else:
            text = [list(queries)]
        inputs = self.processor(images=rgb, text=text, return_tensors="pt")
        with torch.no_grad():
            out = self.model(**inputs)
        if self.grounding:
            res = self.processor.post_process_grounded_object_detection(
                out, inputs.input_ids, threshold=THRESHOLD, target_sizes=[(h, w)]
            )[0]
            labels = [str(x) for x in res.get("text_labels", res.get("labels", []))]
        else:
            res = self.processor.post_process_object_detection(
                out, threshold=THRESHOLD, target_sizes=torch.tensor([(h, w)])
            )[0]
            labels = [queries[int(i)] for i in res["labels"]]
        return [
            BoxHit(tuple(float(v) for v in b), lab, float(s))  # type: ignore[arg-type]
            for b, lab, s in zip(res["boxes"].tolist(), labels, res["scores"].tolist(), strict=True)
        ]


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
    """Boxes of a zero-shot detector, each cut to the object's pixels by depth."""

    name = "open-vocab"

    def __init__(
        self,
        scene: Scene | None = None,
        weights: str | Path | None = None,
        model: BoxModel | None = None,
        edge: float = 0.03,
    ) -> None:
        super().__init__(scene, edge)
        self.model: BoxModel = model or TransformersBoxModel(weights_dir(weights))
        self.queries = queries_of(scene)

    def detect(self, frame: Frame, camera: Camera) -> list[Detection]:
        view = self.view(frame.depth, camera)
        self.planes = find_planes(view.z[view.valid][::16], share=0.01)
        out: list[Detection] = []
        for hit in self.model.boxes(frame.rgb, self.queries):
            mask = box_mask(frame.depth, view.z, hit.box, self.planes)
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
) -> Mask:
    """The object's pixels in a detector's box: those with depth within SURFACE_DEPTH of the
    nearest 5 % of the box's depths (the object is what the box is drawn around; what lies
    farther is behind it) and not on a support plane."""
    h, w = depth.shape
    u0, v0 = max(int(box[0]), 0), max(int(box[1]), 0)
    u1, v1 = min(int(np.ceil(box[2])), w), min(int(np.ceil(box[3])), h)
    mask = np.zeros(depth.shape, dtype=bool)
    if u1 <= u0 or v1 <= v0:
        return mask
    d = depth[v0:v1, u0:u1]
    ok = d > 0
    for p in planes:
        ok &= np.abs(z[v0:v1, u0:u1] - p) > 0.01
    if not ok.any():
        return mask
    near = float(np.percentile(d[ok], 5))
    mask[v0:v1, u0:u1] = ok & (d <= near + SURFACE_DEPTH)
    return mask
