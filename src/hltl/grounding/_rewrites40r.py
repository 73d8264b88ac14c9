"""The grounder's rules of session 40, engineer 12r (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.grounding.lexicon import Lexicon
from hltl.grounding.tree import Node

# the normaliser's rewrites (wired into normalise._STEPS19)
_STEPS40R: tuple[Callable[[str, Lexicon], str], ...] = ()
# refusals asked of the text before it is read (offline._parse, after the session-39 ones)
REFUSE40R: tuple[Callable[[str, Lexicon], None], ...] = ()
# checks of the whole instruction's reading (offline.parse_instruction, after remark_said39s)
CHECK40R: tuple[Callable[[str, Node, Lexicon], None], ...] = ()
