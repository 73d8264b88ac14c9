"""The normaliser's rewrites of session 39, engineer 12s (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.grounding.lexicon import Lexicon

_STEPS39S: tuple[Callable[[str, Lexicon], str], ...] = ()
# (first: before every other rewrite, as _STEPS38S_FIRST)
_STEPS39S_FIRST: tuple[Callable[[str, Lexicon], str], ...] = ()
