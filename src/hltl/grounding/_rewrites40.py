"""The grounder's rules of session 40, engineer 12 (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _ids, _objects_only, _only, _only_person
from hltl.grounding._normalise4 import _fit36
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


# -- courtesy: 'P, bless her,' between a person and what is said of them ("Dana, bless her, wants
# the banana", "Grandad, bless him, could do with the wipes"); 'bless her' closing a request was
# read before (session 14's closers)
_BLESS40 = re.compile(
    r"(?P<p>\b[A-Z][\w]*(?: [A-Z][\w]*)?),\s*(?:god |bless )?bless (?P<pron>her|him|them|'em)"
    r"(?: (?:heart|cotton socks|little heart|soul))?,\s*",
)


def _bless40(text: str, lexicon: Lexicon) -> str:
    """Session 40: ', bless her,' after one person of the scene the pronoun may be, taken off."""
    if "bless" not in text.lower():
        return text
    for m in list(_BLESS40.finditer(text))[::-1]:
        who = _ids(m["p"], lexicon, "human")
        if not _only_person(m["p"], lexicon) or (
            m["pron"].lower() in ("her", "him") and not _fit36(next(iter(who)), m["pron"], lexicon)
        ):
            continue
        text = f"{text[: m.end('p')]} {text[m.end() :]}"
    return text


# -- an availability said as a condition after a want or request ("Person B would love the chips,
# if there's any going", "…, if there are some spare", "…, if there's one left"): the scene has
# the object, so it asks nothing more; taken off when it closes the instruction
_ANY_GOING40 = re.compile(
    r",?\s*(?:but )?(?:only )?if (?:there's|there is|there are|there're|there be) (?:any|some|one|"
    r"enough)(?: of (?:it|them|those|that))?(?: (?:going|left|spare|to spare|left over|about|"
    r"around|handy|free|going spare))?(?P<end>\s*[.!?]*\s*)$",
    _F,
)


def _any_going40(text: str, lexicon: Lexicon) -> str:
    """Session 40: the availability above taken off a request or want that names objects and
    one person (an 'if' of anything else stays a condition, refused)."""
    if " if " not in text.lower():
        return text
    m = _ANY_GOING40.search(text)
    if m is None:
        return text
    before = text[: m.start()]
    if not _ids(before, lexicon, "object") or len(_ids(before, lexicon, "human")) != 1:
        return text
    return before + (m["end"].strip() or ".")


# -- order: 'finish with X' / 'end with X' / 'round off with X' opening the last step ("Start
# with the apple to Person B; next the bottle to Person A; finish with the cup to Person B"):
# 'finally X' (session 19's 'to finish,' and 'start with' are read so)
_FINISH_WITH40 = re.compile(
    r"(?P<pre>(?:^|(?<=[.;!?])\s*))(?:finish|end|"
    r"finish off|finish up|round off|round things off|wind up|wrap up|close) with "
    r"(?=the |a |an |[A-Z])",
    _F,
)


def _finish_with40(text: str, _lexicon: Lexicon) -> str:
    """Session 40: 'finish with' (above) opening the last step's sentence is 'finally' (after
    'and' it is left to session 35's 'lead off with … and finish off with …')."""
    if " with " not in text.lower():
        return text
    return _FINISH_WITH40.sub(r"\g<pre>finally ", text)


# -- ellipsis: 'Same.' answering a question of the form 'The X? P.' ("The bottle? Person A. The
# chips? Same.", "The ruler? Noah. And the glue? The same."): the person of the answer before
_SAME40 = re.compile(
    r"(?P<q1>\b(?:the|a|an) [a-z][a-z ]*?\?)\s*(?P<p>[A-Z][\w]*(?: [A-Z][\w]*)?)"
    r"(?P<mid>(?:,[^.?!]*)?[.!]\s+(?:and |what about |how about )?(?:the|a|an) [a-z][a-z ]*?\?\s*)"
    r"(?P<same>(?:the )?same(?: again| here| person| one| for (?:it|that|them|those))?|ditto)"
    r"(?=\s*[.!]*\s*$)",
    _F,
)


def _same40(text: str, lexicon: Lexicon) -> str:
    """Session 40: the 'Same' above said as that one person of the scene."""
    if "same" not in text.lower() and "ditto" not in text.lower():
        return text
    m = _SAME40.search(text)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    return f"{text[: m.start('same')]}{m['p']}{text[m.end('same') :]}"


# the normaliser's rewrites (wired into normalise._STEPS19)
_STEPS40: tuple[Callable[[str, Lexicon], str], ...] = (
    _left_on40,
    _bless40,
    _any_going40,
    _finish_with40,
    _same40,
)
# refusals asked of the text before it is read (offline._parse, after the session-39 ones)
REFUSE40: tuple[Callable[[str, Lexicon], None], ...] = (posture_state40,)
# checks of the whole instruction's reading (offline.parse_instruction, after remark_said39s)
CHECK40: tuple[Callable[[str, Node, Lexicon], None], ...] = ()
