"""The normaliser's rewrites of session 39, engineer 12 (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.grounding.lexicon import Lexicon

_STEPS39: tuple[Callable[[str, Lexicon], str], ...] = ()
