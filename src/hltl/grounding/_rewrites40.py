"""The grounder's rules of session 40, engineer 12 (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _objects_only, _only
from hltl.grounding.lexicon import Lexicon
from hltl.grounding.tree import Node

# -- session 40 (engineer 12): blind38's refusals by kind in the sections of politeness, wants,
# pronouns and ellipsis, splits and run-ons, lower case, typos and questions, and the verbs of
# placing the lexicon lacked (stand, hang, sit, dropping; borrow: lexicon.py's VERBS). As
# session 39's: each rule a closed pattern checked against the scene, the rest of the sentence
# read by the same grammar; a closing remark or a purpose beside the request is 12s's.

# -- a thing said to stand, sit or hang somewhere ("the cup is standing on the shelf", "the mug
# hangs on the rack", "the teddy sat on the mat"): where it is, no request (the posture verbs are
# placing verbs since session 40: 'stand the cup on the shelf'); a modal ('can be stood on',
# 'should hang on') or 'to be' asks for it and is not matched
_POSTURE_STATE40 = re.compile(
    r"(?:^|[,;:.!?—–-]\s*|\b(?:and|but|so|because|since|as)\s+)(?P<x>(?:the|a|an|this|that|these|"
    r"those|my|your|his|her|their|our) (?:[a-z]+ ){0,2}?[a-z]+)(?P<be>'s|'re| is| are| was| were"
    r")?(?: (?:still|already|just|now|all|currently|usually|normally|always))? (?P<v>standing|"
    r"sitting|hanging|stands|sits|hangs|stood|sat|hung)\b",
    _F,
)


def posture_state40(text: str, lexicon: Lexicon) -> None:
    """Session 40: refuse a clause saying where objects stand, sit or hang (above): read as a
    placement it would act on a description."""
    for m in _POSTURE_STATE40.finditer(text):
        if not _objects_only(m["x"], lexicon):
            continue
        raise GroundingError(
            f"{m.group(0).lstrip(',;:.!?—–- ')!r} says where {m['x']} is: it asks for nothing; "
            f"say 'put {m['x'].lower()} on …' to have it placed"
        )


# -- 'X can be left on S' ("The red mug can be left on the counter", "the spanners should be left
# in the locker"): the passive of 'leave X on S' (a placing verb; 'left' is no verb of the
# lexicon, being also a side and what remains), asked with a modal or 'to be' at a sentence start
_LEFT_ON40 = re.compile(
    r"(?:^|(?<=[.;!?])\s+)(?P<x>(?:the|a|an|both|all|both of the|all of the) [^,;.!?]+?) "
    r"(?P<m>can|could|should|must|may|might|will|is to|are to|'s to|needs to|need to|ought to) "
    r"(?:just |simply |safely )?(?:be|get) left (?P<on>on|in|onto|into|on top of) "
    r"(?P<s>the [a-z]+(?: [a-z]+)?)(?=\s*(?:[,;.!?]|$))",
    _F,
)


def _left_on40(text: str, lexicon: Lexicon) -> str:
    """Session 40: 'X can be left on S' (above) is 'X can be put on S' when X names objects only
    and S one surface of the scene."""
    if "left" not in text.lower():
        return text
    for m in list(_LEFT_ON40.finditer(text))[::-1]:
        if not _objects_only(m["x"], lexicon) or not _only(m["s"], lexicon, "surface"):
            continue
        said = f"{m['x']} {m['m']} be put {m['on']} {m['s']}"
        text = text[: m.start("x")] + said + text[m.end() :]
    return text


# the normaliser's rewrites (wired into normalise._STEPS19)
_STEPS40: tuple[Callable[[str, Lexicon], str], ...] = (_left_on40,)
# refusals asked of the text before it is read (offline._parse, after the session-39 ones)
REFUSE40: tuple[Callable[[str, Lexicon], None], ...] = (posture_state40,)
# checks of the whole instruction's reading (offline.parse_instruction, after remark_said39s)
CHECK40: tuple[Callable[[str, Node, Lexicon], None], ...] = ()
