"""The grounder's rules of session 56, the lead (docs/grounding.md): blind54's wrong reading."""

from __future__ import annotations

from collections.abc import Callable

from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F
from hltl.grounding._rewrites49l import choice_forgotten49l
from hltl.grounding._rewrites50l import _FREE50L
from hltl.grounding.lexicon import Lexicon
from hltl.grounding.tree import Node, has_choice

# -- the speaker remembers only that it was one of the options ------------------------------
#
# blind54 #99: "Jess asked for one of the tools, the torch or the hammer, it was one of those."
# read `torch>B | hammer>B`, a free choice. "It was one of those" says what was asked for was one
# thing, and the speaker no longer knows which: the want is one of the options, not either of
# them. Past tense only ("it was", "'twas"): a present "it's one or the other" after a request
# ("Give Bob the cup or the apple, it's one or the other") leaves the choice to the robot.
_ONE_OF56L = re.compiled(
    r"(?:^|[,;.:!?-]\s*|\b(?:and|but|though)\s+)(?:(?:well|anyway|i think|i know)\s*,?\s*)?"
    r"(?:it was|'twas|twas|it were)\s+(?:definitely\s+|certainly\s+|def\s+|just\s+)?"
    r"(?:one (?:of (?:those|them|these|the two|those two|them two|the pair)(?: two| ones?)?|"
    r"or the other)"
    r"|either (?:one|the one) or the other|(?:the )?one or the other)"
    r"(?:\s*,?\s*(?:anyway|at least|i think|i'm sure|for sure|i know that much))?"
    r"\s*(?=[,;.!?]|$)",
    _F,
)


def _was_one_of56l(text: str, node: Node, lexicon: Lexicon) -> None:
    """Session 56 (lead): a reading with a choice in it, of a text in which the speaker says only
    that it was one of the options ("…, the torch or the hammer, it was one of those."), is
    refused naming the options (session 49's `choice_forgotten49l`), unless the text leaves the
    choice free ("either's fine")."""
    low = text.lower()
    if "one" not in low or ("was" not in low and "were" not in low):  # ('twas holds 'was')
        return
    if not has_choice(node):
        return
    m = _ONE_OF56L.search(text)
    # the remark's own 'either' ("it was either one or the other") leaves nothing free
    if m is None or _FREE50L.search(f"{text[: m.start()]} {text[m.end() :]}") is not None:
        return
    choice_forgotten49l(
        node, lexicon, f"{m.group(0).strip(' ,;.')!r} says one was asked for, not which"
    )


# refusals asked of the text before it is read (offline._parse, after the session-55 ones)
REFUSE56L: tuple[Callable[[str, Lexicon], None], ...] = ()
# checks of the whole instruction's reading (offline.parse_instruction, after the session-55 ones)
CHECK56L: tuple[Callable[[str, Node, Lexicon], None], ...] = (_was_one_of56l,)
