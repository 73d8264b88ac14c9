"""Language-guided selection by appearance: CLIP crops vs words, local weights (paper §III-A)."""

from __future__ import annotations

import math
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import numpy as np
import numpy.typing as npt

from hltl.errors import BackendUnavailableError
from hltl.perception.frames import Camera
from hltl.perception.geometry import Cylinder, pixel_of
from hltl.perception.language import Selection
from hltl.perception.openvocab import hf_modules, load_local, weights_dir

F32 = npt.NDArray[np.float32]
Crop = npt.NDArray[np.uint8]
CLIP_ENV = "HLTL_CLIP_WEIGHTS"
# cosine of CLIP's text and image embeddings below which a crop is taken to show none of the
# words: matching pairs of CLIP ViT-B/32 usually score 0.25–0.35, unrelated ones below 0.2
# (not measured here: no CLIP weights exist on this machine)
VISUAL_THRESHOLD = 0.2
APPEARANCE = "appearance"  # Selection.word of a visual match: the crop, not a word, matched
PAD = 4  # pixels around an object's projected outline


class ClipEmbedder:
    """CLIP (or any model with ``get_image_features`` / ``get_text_features``) from a local
    directory: unit-length image and text embeddings in one space.

    Raises:
        BackendUnavailableError: transformers missing, or the directory holds no such model.
    """

    def __init__(self, path: Path) -> None:
        transformers, torch = hf_modules()
        self.processor = load_local(transformers.AutoProcessor, path, "CLIP's processor")
        self.model = load_local(transformers.AutoModel, path, "CLIP").eval()
        if not all(hasattr(self.model, f) for f in ("get_image_features", "get_text_features")):
            raise BackendUnavailableError(
                f"{path}: {type(self.model).__name__} embeds no images and texts in one space "
                "(it has no get_image_features / get_text_features)"
            )
        self._torch = torch

    def _unit(self, out: Any) -> F32:
        # transformers 5 returns the projected embeddings as an output's pooler_output
        t = out if isinstance(out, self._torch.Tensor) else out.pooler_output
        v = t.detach().float().numpy()
        return np.asarray(v / np.maximum(np.linalg.norm(v, axis=1, keepdims=True), 1e-12), "f4")

    def images(self, crops: Sequence[Crop]) -> F32:
        """(n, d) embeddings of RGB crops."""
        images = [np.ascontiguousarray(c) for c in crops]
        inputs = self.processor(images=images, return_tensors="pt")
        with self._torch.no_grad():
            return self._unit(self.model.get_image_features(pixel_values=inputs["pixel_values"]))

    def texts(self, texts: Sequence[str]) -> F32:
        """(n, d) embeddings of phrases."""
        inputs = self.processor(text=list(texts), return_tensors="pt", padding=True)
        with self._torch.no_grad():
            return self._unit(
                self.model.get_text_features(
                    input_ids=inputs["input_ids"], attention_mask=inputs["attention_mask"]
                )
            )


def clip_embedder(path: str | Path | None = None) -> ClipEmbedder:
    """The CLIP model at ``path`` or ``$HLTL_CLIP_WEIGHTS``.

    Raises:
        BackendUnavailableError: neither names a loadable model directory.
    """
    return ClipEmbedder(weights_dir(path, CLIP_ENV, "CLIP"))


def crop_box(
    cylinder: Cylinder, camera: Camera, pad: int = PAD
) -> tuple[int, int, int, int] | None:
    """The pixel box (u0, v0, u1, v1) of an object's fitted cylinder in the image, ``pad``
    pixels wider; None when it lies behind the camera or outside the image."""
    cx, cy, cz = cylinder.center
    us, vs = [], []
    for dz in (-cylinder.height / 2, cylinder.height / 2):
        for k in range(16):
            a = 2 * math.pi * k / 16
            p = (cx + cylinder.radius * math.cos(a), cy + cylinder.radius * math.sin(a), cz + dz)
            u, v, d = pixel_of(np.array(p), camera)
            if d <= 0:
                return None
            us.append(u)
            vs.append(v)
    u0, v0 = max(math.floor(min(us)) - pad, 0), max(math.floor(min(vs)) - pad, 0)
    u1 = min(math.ceil(max(us)) + pad + 1, camera.width)
    v1 = min(math.ceil(max(vs)) + pad + 1, camera.height)
    return (u0, v0, u1, v1) if u1 > u0 and v1 > v0 else None


def select_visual(
    query: str,
    crops: Sequence[tuple[str, Crop]],
    embedder: ClipEmbedder,
    threshold: float = VISUAL_THRESHOLD,
) -> Selection:
    """The candidate whose crop's CLIP embedding is most similar to the text's (cosine), with
    the runner-up; no candidate when the best is below ``threshold``."""
    if not crops:
        return Selection(query, None, 0.0, None, None, 0.0, threshold)
    sims = embedder.images([c for _, c in crops]) @ embedder.texts([query])[0]
    best: dict[str, float] = {}
    for (key, _), s in zip(crops, sims.tolist(), strict=True):
        best[key] = max(s, best.get(key, -math.inf))
    ranked = sorted(best.items(), key=lambda kv: -kv[1])
    k1, s1 = ranked[0]
    k2, s2 = ranked[1] if len(ranked) > 1 else (None, 0.0)
    if s1 < threshold:
        return Selection(query, None, s1, None, k1, s1, threshold)
    return Selection(query, k1, s1, APPEARANCE, k2, s2, threshold)
