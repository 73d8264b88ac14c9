"""The grounder's rules of session 51, the lead (docs/grounding.md): 12c's fuzz reports."""

from __future__ import annotations

from collections.abc import Callable

from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _ids
from hltl.grounding._rewrites41l import _SUBORDINATE41L, said_as_done41l
from hltl.grounding.lexicon import Lexicon
from hltl.grounding.tree import Node

# -- where a thing went or was, told as done -------------------------------------------------------
#
# 12c's session-51 fuzz: "The apple went to Alice." read `apple>A`, "The apple's gone to Alice and
# the crisps go to Carol." `apple>A & chips>C`, "The apple was on the shelf." `apple@shelf`, and
# the lead's probes of the same kind: "The apple ended up on the shelf.", "The apple's been on the
# shelf all day." (`apple@shelf`), "You gave Alice the apple." (`apple>A`). The grammar reads a
# verb in any of its forms, so a past 'went' / 'gave' is read as 'go' / 'give', and 'was on' as
# the goal 'is on'. Session 41's `_done41l` refuses the same report said in the passive ("the
# chips were handed to Bob"); this is its active and stative kin: a scene object said to have
# gone, been or ended up at a person or a surface (went, 's / has / had gone, was, were, 's / has
# / had been, ended / wound up, landed), or 'you' said to have handed, placed or brought it (gave,
# handed, brought, took, sent, delivered, placed, moved, carried, fetched, returned, lent; or put,
# set, passed, dropped, left after 've / have / had / already), tells what has happened, not what
# to do: refused, as session 41's. Kept, as there: a subordinate clause ("after the apple has gone
# to Carol", "the cup that was on the table", "once it's been on the shelf"), a person as the
# subject ("Bob's gone to lunch", "she was on the phone"), the present and the future ("the apple
# goes to Alice", "is on the shelf", "has to go to Alice"), and 'you' asked ("could you just put
# the green cup on the tray": a request, whatever the verb's form).
_WENT_TAIL51L = (
    r"\s*(?P<said>\bwent|(?:\b(?:has|have|had)|(?<=\w)['’]s)\s+"
    r"(?:already\s+|just\s+|now\s+)?(?:gone|been)|\b(?:was|were)|\b(?:ended|wound)\s+up|"
    r"\blanded(?:\s+up)?)\s+(?:(?:already|just|all|straight|right|off|over|across|back|up|down|"
    r"out|away)\s+)*(?P<rest>(?:to|on|onto|in|into|at)\b[^,.;:!?]*)"
)
_WENT51L = re.compiled(r"(?P<subject>[^,.;:!?]*?)" + _WENT_TAIL51L, _F)
_GAVE_TAIL51L = (
    r"\s*(?P<said>\byou(?:['’]ve|\s+have|\s+had|['’]d)?\s+"
    r"(?:(?:already|just)\s+)*(?:gave|given|handed|brought|took|taken|sent|delivered|placed|moved|"
    r"carried|fetched|returned|lent)\b|\byou(?:['’]ve|\s+have|\s+had|['’]d)?\s+already\s+"
    r"(?:put|set|passed|dropped|left)\b|\byou(?:['’]ve|\s+have|\s+had)\s+(?:put|set|passed|"
    r"dropped|left)\b)(?P<rest>[^,.;:!?]*)"
)
_YOU_GAVE51L = re.compiled(r"(?P<subject>[^,.;:!?]*?)" + _GAVE_TAIL51L, _F)
# Session 52 (12p): the two patterns without their subject. Every match of a pattern ends in a
# match of its tail, so where the tail finds nothing the pattern finds nothing either: asked
# first, as a lazy subject tried from every letter of a clause costs ~0.1-0.4 ms a text
_WENT_SAID51L = re.compiled(_WENT_TAIL51L, _F)
_GAVE_SAID51L = re.compiled(_GAVE_TAIL51L, _F)
# things said without their names ("Both of them went to Person B, bottle and chips.", 12r's
# probe; "It went on the shelf.")
_THINGS51L = re.compiled(
    r"(?:^|\b(?:and|so|right|oh|well|but)\s+)(?:it|they|both(?: of them)?|all(?: of them)?|the lot|"
    r"those|these|each(?: of them)?|the (?:two|pair|both) of them)\s*$",
    _F,
)
# 'you' asked ("could you just put the cup on the tray"): a request, whatever the verb's form
_ASKED51L = re.compiled(
    r"\b(?:could|can|would|will|might|may|do|did|should|shall|if|please|won't|wouldn't|can't|"
    r"couldn't|mind if)\s*$",
    _F,
)
_GONE_WORDS51L = ("went", "gone", "was", "were", "been", "ended", "wound", "landed", "you")
# Session 52 (12p): the words each pattern's 'said' needs (one of them is in every match of it,
# as the text's lower case holds them where the text is ASCII): a pattern whose words the text
# lacks is not run (its lazy subject tried at every letter cost ~0.4 ms an instruction)
_WENT_WORDS51L = ("went", "gone", "was", "were", "been", "ended", "wound", "landed")
_GAVE_WORDS51L = (
    *("gave", "given", "handed", "brought", "took", "taken", "sent", "delivered", "placed"),
    *("moved", "carried", "fetched", "returned", "lent", "put", "set", "passed", "dropped"),
    "left",
)


def _told_done51l(text: str, lexicon: Lexicon) -> None:
    """Session 51 (lead): 'the apple went to Alice', 'the apple was on the shelf', 'you gave Alice
    the apple' — where a thing went or was, told as done — refused, not read as a request."""
    low = text.lower()
    if not any(w in low for w in _GONE_WORDS51L):
        return
    ascii_ = low.isascii()
    went = (not ascii_ or any(w in low for w in _WENT_WORDS51L)) and bool(
        _WENT_SAID51L.search(text)
    )
    for m in _WENT51L.finditer(text) if went else ():
        subject = m.group("subject")
        if _SUBORDINATE41L.search(subject):
            continue
        if _ids(subject, lexicon, "human"):
            continue
        if not _ids(subject, lexicon, "object") and _THINGS51L.search(subject) is None:
            continue
        rest = m.group("rest")
        if not (_ids(rest, lexicon, "human") or _ids(rest, lexicon, "surface")):
            continue
        said_as_done41l(m)
    if "you" not in low or (ascii_ and not any(w in low for w in _GAVE_WORDS51L)):
        return
    if _GAVE_SAID51L.search(text) is None:
        return
    for m in _YOU_GAVE51L.finditer(text):
        subject = m.group("subject")
        if _SUBORDINATE41L.search(subject) or _ASKED51L.search(subject):
            continue
        rest = m.group("rest")
        if not _ids(rest, lexicon, "object"):
            continue
        if not (_ids(rest, lexicon, "human") or _ids(rest, lexicon, "surface")):
            continue
        said_as_done41l(m)


# refusals asked of the text before it is read (offline._parse, before the other session-51 ones)
REFUSE51L: tuple[Callable[[str, Lexicon], None], ...] = (_told_done51l,)
# checks of the whole instruction's reading (offline.parse_instruction, before the other
# session-51 ones)
CHECK51L: tuple[Callable[[str, Node, Lexicon], None], ...] = ()
