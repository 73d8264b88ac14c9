"""Instruction to H-LTLf grounding: offline semantic parser and LLM grounders."""

from __future__ import annotations

from typing import Any

from hltl.errors import GroundingError
from hltl.grounding.base import Grounder, Grounding, TokenUsage, UpdateInfo, scene_graph

GROUNDERS = ("offline", "llm", "local")

__all__ = [
    "GROUNDERS",
    "Grounder",
    "Grounding",
    "TokenUsage",
    "UpdateInfo",
    "make_grounder",
    "scene_graph",
]


def make_grounder(name: str = "offline", **options: Any) -> Grounder:
    """The grounder called ``name`` (``offline``, ``llm`` or ``local``); backends load lazily.

    Args:
        name: which grounder.
        options: passed to the grounder's constructor (e.g. ``config=`` for ``llm``).

    Raises:
        GroundingError: unknown name.
        BackendUnavailableError: the backend's optional dependency is missing (``llm``, ``local``
            say so when they are first used).
    """
    if name == "offline":
        from hltl.grounding.offline import (
            OfflineGrounder,  # only the grounder asked for is imported
        )

        return OfflineGrounder(**options)
    if name == "llm":
        from hltl.grounding.llm import LLMGrounder  # only the grounder asked for (the llm extra)

        return LLMGrounder(**options)
    if name == "local":
        from hltl.grounding.local import (
            LocalGrounder,  # only the grounder asked for (the local extra)
        )

        return LocalGrounder(**options)
    raise GroundingError(f"unknown grounder {name!r}; expected one of {', '.join(GROUNDERS)}")
