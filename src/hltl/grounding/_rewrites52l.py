"""The grounder's rules of session 52, the lead (docs/grounding.md): 12c's fuzz reports."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _ids
from hltl.grounding._rewrites41l import _SUBORDINATE41L, said_as_done41l
from hltl.grounding.lexicon import Lexicon
from hltl.grounding.tree import Node

# -- a person said to have ended up with a thing ---------------------------------------------------
#
# 12c's session-52 fuzz: "Bob ended up with the apple." read `apple>B`, as did "Bob received the
# apple." and "Give Alice the crisps; Bob ended up with the apple." (`chips>A & apple>B`). Session
# 41's `_done41l` refuses a handing told as done in the passive ("the chips were handed to Bob"),
# session 51's `_told_done51l` a thing said to have gone to a person ("the apple went to Alice");
# this is the same report said of the person who got it: a scene person (or he / she / they)
# said to have received, ended / wound up with, come / walked / made off with, or got hold of a
# scene object tells what has happened, not what to do — refused. Kept: a subordinate clause
# ("once Bob has received the apple, …", "the cup that Alice ended up with"), the present and the
# future ("Bob receives the apple", "make sure Bob ends up with the apple": a request).
_GOT_IT52L = re.compiled(
    r"(?P<subject>[^,.;:!?]*?)\s*(?P<said>(?:\b(?:has|have|had)\s+|(?<=\w)['’](?:s|ve|d)\s+)?"
    r"(?:already\s+|just\s+|finally\s+)?(?:received|(?:ended|wound)\s+up\s+with|(?:came|walked|"
    r"made)\s+(?:away|off)\s+with|got\s+hold\s+of))\s+(?P<rest>[^,.;:!?]*)",
    _F,
)
_PERSON_PRONOUN52L = re.compiled(r"(?:^|\b(?:and|so|but|oh|well)\s+)(?:he|she|they)\s*$", _F)
_GOT_WORDS52L = ("received", " up with", " off with", " away with", " hold of")


def _got_it52l(text: str, lexicon: Lexicon) -> None:
    """Session 52 (lead): 'Bob ended up with the apple', 'Bob received the apple' — a person
    said to have got a thing, told as done — refused, not read as a request."""
    low = text.lower()
    if not any(w in low for w in _GOT_WORDS52L):
        return
    for m in _GOT_IT52L.finditer(text):
        subject = m.group("subject")
        if _SUBORDINATE41L.search(subject):
            continue
        if _ids(subject, lexicon, "object"):
            continue
        if not _ids(subject, lexicon, "human") and _PERSON_PRONOUN52L.search(subject) is None:
            continue
        if not _ids(m.group("rest"), lexicon, "object"):
            continue
        said_as_done41l(m)


# -- what a person holds, reported ---------------------------------------------------------------
#
# 12c's session-52 fuzz (135 variants of its `done` family, one form): "Alice says Bob has the
# apple." read `apple>B`, as did "Alice says Bob's got the apple.", "… Bob had the apple.", "… Bob
# got the apple." Session 29's `_says29` takes a reported request's "Alice says" off ("Sam says
# put the stapler in the box"); what is left here is a sentence of holding, which alone is refused
# (session 32's `_state_only32s`: "Bob has the apple." could say what Bob holds or allot it;
# "Bob had the apple." asks for nothing), but which the grammar reads as a hand-over once the
# report is gone. A report of who has or had a thing ('says', 'said', 'reckons', 'thinks',
# 'tells me', 'told me', 'mentioned'; by anyone: 'Alice', 'the coxswain'), opening the sentence
# or closing it ("Bob has the apple, Alice says(, so …)"), is refused as the sentence itself is.
# Kept: a reported want or need ("Alice says Bob wants the apple", "… Bob has to have the apple",
# "… Bob has asked for the apple", "… Bob has his eye on the apple": a request, as on main).
_HOLDING52L = (
    r"(?P<said>(?P<p>[A-Za-z]+(?: (?!(?:has|had|got|is|was)\b)[A-Za-z]+)?)\s*(?P<verb>['’]s\s+"
    r"got|['’]s\s+had|has\s+got|has\s+had|had\s+got|['’]d\s+got|has|had|got|['’]s\s+been\s+"
    r"given|was\s+given)\s+(?P<rest>(?:the|a|an|his|her|their|that|this|those|these|both|all|one|"
    r"some)\b[^,.;:!?]*))"
)
_SAYS_HOLDS52L = re.compiled(
    r"^\s*(?P<who>(?:(?:the|our|my|a)\s+)?[A-Za-z]+(?: [A-Za-z]+)?)\s+(?:says|said|reckons|"
    rf"thinks|tells me|told me|mentioned)\s*,?\s+(?:that\s+)?{_HOLDING52L}",
    _F,
)
# the report closing the sentence ("Bob has the apple, Alice says.")
_HOLDS_SAYS52L = re.compiled(
    rf"^\s*{_HOLDING52L}\s*,\s*(?:(?P<who>(?:(?:the|our|my|a)\s+)?[A-Za-z]+(?: [A-Za-z]+)?)\s+"
    r"(?:says|said|reckons|thinks|tells me|told me)|(?:says|said)\s+(?P<who2>(?:(?:the|our|my|a)"
    r"\s+)?[A-Za-z]+(?: [A-Za-z]+)?))\s*(?:[,.;:!]|$)",
    _F,
)
_SAYS_WORDS52L = ("says", "said", "reckons", "thinks", "tells me", "told me", "mentioned")
_PRONOUN52L = frozenset({"he", "she", "they"})
# where the thing held ends ("the apple in his bag"; "his eye | on the apple")
_HEAD_END52L = re.compiled(r"\b(?:on|for|of|to|in|at|with|about|from|over)\b", _F)


def _says_holds52l(text: str, lexicon: Lexicon) -> None:
    """Session 52 (lead): 'Alice says Bob has the apple' — who holds a thing, reported — refused
    as the sentence of holding is, not read as a hand-over."""
    low = text.lower()
    if not any(w in low for w in _SAYS_WORDS52L):
        return
    m = _SAYS_HOLDS52L.match(text) or _HOLDS_SAYS52L.match(text)
    if m is None:
        return
    p = m.group("p")
    if p.lower() not in _PRONOUN52L and not _ids(p, lexicon, "human"):
        return
    if _ids(p, lexicon, "object"):
        return
    if not _ids(_HEAD_END52L.split(m.group("rest"), maxsplit=1)[0], lexicon, "object"):
        return  # 'has his eye on the apple', 'has a craving for it': a want, not a holding
    past = m.group("verb").lower() in {"had", "got"} or "had" in m.group("verb").lower()
    whom = "the person" if p.lower() in _PRONOUN52L else p
    raise GroundingError(
        f"{m.group('said').strip()!r}, reported, says what {p} "
        f"{'had' if past else 'holds'}: it asks for nothing; say 'give {whom} …' to have it "
        "handed over"
    )


# refusals asked of the text before it is read (offline._parse, after the session-51 ones)
REFUSE52L: tuple[Callable[[str, Lexicon], None], ...] = (_got_it52l, _says_holds52l)
# checks of the whole instruction's reading (offline.parse_instruction, after the session-51 ones)
CHECK52L: tuple[Callable[[str, Node, Lexicon], None], ...] = ()
