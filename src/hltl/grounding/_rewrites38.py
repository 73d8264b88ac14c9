"""The normaliser's rewrites of session 38 (engineer 12): blind36's politeness,
wants, pronouns, splits, lower case, typos and questions.

Each rewrite takes the text and the scene's lexicon and returns the text rewritten, or the text
unchanged when it does not apply; normalise.py runs them in `_STEPS19`'s order.
"""

from __future__ import annotations

from collections.abc import Callable

from hltl.grounding.lexicon import Lexicon

_STEPS38: tuple[Callable[[str, Lexicon], str], ...] = ()
