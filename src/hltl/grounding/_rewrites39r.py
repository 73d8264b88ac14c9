"""The normaliser's rewrites of session 39, engineer 12r (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.grounding.lexicon import Lexicon

_STEPS39R: tuple[Callable[[str, Lexicon], str], ...] = ()
