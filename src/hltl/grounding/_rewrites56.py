"""The grounder's rules of session 56, engineer 12 (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.grounding.lexicon import Lexicon
from hltl.grounding.tree import Node

# the normaliser's first rewrites (wired into normalise._STEPS19, before the session-56 ones)
_STEPS56_FIRST: tuple[Callable[[str, Lexicon], str], ...] = ()
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-56 ones)
_STEPS56: tuple[Callable[[str, Lexicon], str], ...] = ()
# refusals asked of the text before it is read (offline._parse, after the session-56 ones)
REFUSE56: tuple[Callable[[str, Lexicon], None], ...] = ()
# checks of the whole instruction's reading (offline.parse_instruction, after the session-56 ones)
CHECK56: tuple[Callable[[str, Node, Lexicon], None], ...] = ()
