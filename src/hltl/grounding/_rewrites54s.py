"""The grounder's rules of session 54, engineer 12s (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _names
from hltl.grounding.lexicon import Lexicon
from hltl.grounding.tree import Node, Task, tasks

# -- session 54 (12s): a thing set against another, moved where the other goes ----------------
#
# "Pick up the bottle. Put it on the shelf, and the apple, not the bottle." read `bottle@shelf &
# apple@shelf` (12c, session 53): the grammar leaves 'not the bottle' out of 'the apple', which
# does not name it, and asks only whether a name said before has it ('Put the bottle on the
# shelf, and the apple, not the bottle.' is refused so) — the 'it' that stands for the bottle is
# no name. 'the Y, not the X' / 'instead of the X' / 'rather than the X' says the X does not go
# where the Y goes: a reading that moves the X there all the same, when nothing after the words
# names the X again, is refused (session 51's `_excluded_back51r` asks the same of 'except' /
# 'but not' ...).
_SET_AGAINST54S = re.compiled(
    r"(?:(?:(?:^|[,;:.!?(—–-])\s*(?:(?:and|or|but|so)\s+)?|\b(?:and|but)\s+)not|\binstead of|"
    r"\brather than|"
    r"\bin place of|\bas opposed to)\s+(?!just\b|only\b|even\b|to\b|for\b)"
    r"(?P<x>(?:the |that |those |this |these |her |his |their |my |any )?[a-z]+(?: [a-z]+)?)",
    _F,
)


_AGAINST_WORDS54S = ("not ", "instead of", "rather than", "in place of", "as opposed to")


def _against54s(text: str, lexicon: Lexicon) -> list[tuple[set[str], str, int]]:
    """The things ``text`` sets against another by 'not' / 'instead of' / 'rather than' (above),
    each with the words and where they end; a phrase saying 'other' / 'one' (which one is then
    unsure) is not among them."""
    out: list[tuple[set[str], str, int]] = []
    for m in _SET_AGAINST54S.finditer(text):
        words = m["x"].lower().split()
        if "other" in words or "one" in words or "ones" in words:
            continue
        named = _names(m["x"], lexicon)
        if not named or any(r.kind != "object" for r in named[0].refs):
            continue
        said = m.group(0).lstrip(",;:.!?(—–- ")
        out.append(({r.id for r in named[0].refs}, said, m.end()))
    return out


def _not_where54s(text: str, node: Node, lexicon: Lexicon) -> None:
    """Session 54 (12s): a thing set against another moved where the other goes (above)."""
    low = text.lower()
    if not any(w in low for w in _AGAINST_WORDS54S):
        return
    got: list[Task] = list(tasks(node))
    if len(got) < 2:
        return
    for left, said, end in _against54s(text, lexicon):
        rest = {t.target for t in got if t.obj not in left}
        back = {t.obj for t in got if t.obj in left and t.target in rest}
        if not back:
            continue
        after = {r.id for it in _names(text[end:], lexicon) for r in it.refs}
        if back & after:
            continue
        raise GroundingError(
            f"{said!r} sets the {', '.join(sorted(back))} against what goes where it is said, "
            "but the reading would move it there too: say the whole request again"
        )


# the normaliser's first rewrites (wired into normalise._STEPS19, before the session-53 ones)
_STEPS54S_FIRST: tuple[Callable[[str, Lexicon], str], ...] = ()
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-53 ones)
_STEPS54S: tuple[Callable[[str, Lexicon], str], ...] = ()
# refusals asked of the text before it is read (offline._parse, after the session-53 ones)
REFUSE54S: tuple[Callable[[str, Lexicon], None], ...] = ()
# checks of the whole instruction's reading (offline.parse_instruction, after the session-53 ones)
CHECK54S: tuple[Callable[[str, Node, Lexicon], None], ...] = (_not_where54s,)
