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
    # A registry of backends (STYLE.md, logaut): `hltl plan --spec` and the executor load no
    # parser and no LLM client.
    if name == "offline":
        # why: only the grounder asked for is imported
        from hltl.grounding.offline import OfflineGrounder

        return OfflineGrounder(**options)
    if name == "llm":
        # why: only the grounder asked for is imported (the llm extra's backend)
        from hltl.grounding.llm import LLMGrounder

        return LLMGrounder(**options)
    if name == "local":
        # why: only the grounder asked for is imported (the local extra's backend)
        from hltl.grounding.local import LocalGrounder

        return LocalGrounder(**options)
    raise GroundingError(f"unknown grounder {name!r}; expected one of {', '.join(GROUNDERS)}")
