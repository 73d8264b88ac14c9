"""The grounder's rules of session 45, engineer 12r (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.grounding.lexicon import Lexicon
from hltl.grounding.tree import Node

# the normaliser's rewrites run before the session-44 ones (wired into normalise._STEPS19)
_STEPS45R_FIRST: tuple[Callable[[str, Lexicon], str], ...] = ()
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-44 ones)
_STEPS45R: tuple[Callable[[str, Lexicon], str], ...] = ()
# refusals asked of the text before it is read (offline._parse, after the session-44 ones)
REFUSE45R: tuple[Callable[[str, Lexicon], None], ...] = ()
# checks of the whole instruction's reading (offline.parse_instruction, after the session-44 ones)
CHECK45R: tuple[Callable[[str, Node, Lexicon], None], ...] = ()
