"""The grounder's rules of session 55, the lead (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.grounding.lexicon import Lexicon
from hltl.grounding.tree import Node

# refusals asked of the text before it is read (offline._parse, after the session-54 ones)
REFUSE55L: tuple[Callable[[str, Lexicon], None], ...] = ()
# checks of the whole instruction's reading (offline.parse_instruction, after the session-54 ones)
CHECK55L: tuple[Callable[[str, Node, Lexicon], None], ...] = ()
