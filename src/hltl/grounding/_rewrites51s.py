"""The grounder's rules of session 51, engineer 12s (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F
from hltl.grounding.lexicon import Lexicon
from hltl.grounding.tree import Node

# -- session 51 (12s): a request put off until someone's word (12c's deferrals fuzz) ------------
#
# "Check with the deckhand first. An hour on the bongos has left Person A gasping for the
# bottle.", "Once the site boss says so, Alice mentioned the crisps; could you take them to her."
# (blind47, 12c's session-50 fuzz) read as the handover: the first sentence (a verb the grammar
# does not know) or clause (a name it does not know) was dropped as a remark. Either waits on
# someone's later word, which the robot does not hear (blind30's time rule): a reading of a text
# that says so is refused. The kinds: consulting someone before acting ('check / clear it /
# confirm with P', 'run it by / past P', 'ask P first / before …'), a time clause that waits on
# someone's say-so ('once / when / as soon as / until … P says so / gives the word / the nod /
# okays it / signs off'), and waiting for it ('wait for P's nod', 'get the go-ahead from P
# first'). Asked of the whole reading only (a check), so a refusal with its readings keeps them.
_WHO51S = r"[a-z][a-z'-]*(?: [a-z][a-z'-]*){0,3}?"
_WORD51S = (
    r"(?:word|nod|go-ahead|go ahead|green light|all-clear|all clear|signal|ok|okay|o\.k\.|"
    r"thumbs up|thumbs-up|say-so|say so|blessing)"
)
_SAID_SO51S = re.compile(
    # consulting someone before acting
    rf"\b(?:(?:check|double-check|clear (?:it|that|this)|confirm|agree (?:it|that)|check (?:it|"
    rf"that|this))\s+with|run (?:it|that|this)\s+(?:by|past))\s+(?!you\b|yourself\b)"
    rf"(?P<who>{_WHO51S})(?=\s*(?:first|beforehand|before\b|[.,;:!?]|$|and\b|then\b))"
    rf"|\bask\s+(?!you\b|for\b|after\b|about\b|around\b)(?P<asked>{_WHO51S})\s+(?:first|"
    rf"beforehand|before (?:you|anything|doing|starting|going)|what|whether|if)\b"
    # a time clause waiting on someone's say-so
    rf"|\b(?:once|when|whenever|as soon as|soon as|after|until|till|not before|the moment|the "
    rf"minute|the second)\s+(?!you\b|i\b|we\b)(?P<sayer>{_WHO51S})\s+(?:says so|say so|said so"
    rf"|says go|says the word|has said so|gives (?:you |us |me )?(?:the |a |his |her |their )?"
    rf"{_WORD51S}|has given (?:you |us )?(?:the |a |his |her |their )?{_WORD51S}|okays|ok's|"
    rf"oks|signs (?:it |that )?off|has signed (?:it |that )?off|approves|has approved|agrees|"
    rf"nods|lets you know|tells you to|tells you it's)\b"
    # told to wait for it (or for anything: an outside event), or to get it first
    rf"|(?:^|[.!?;:,]\s*|\b(?:then|and|but|so|just|please|actually|first)\s+)(?:do |please |"
    rf"just )?(?:wait|hold off|hang on|hold on|hold fire)\s+(?:for|till|until)\s+(?!(?:a |one |"
    rf"just a )?(?:sec|secs|second|seconds|moment|mo|minute|tick|jiffy)\b)\S"
    rf"|\b(?:get|got|have|getting)\s+(?:the |a |an )?{_WORD51S}\s+from\s+(?P<giver>{_WHO51S})"
    rf"(?=\s*(?:first|beforehand|before\b|[.,;:!?]|$))"
    rf"|\b(?:get|got|getting)\s+(?!your\b|my\b)(?:{_WHO51S}'s|{_WHO51S}s') {_WORD51S}\s+"
    rf"(?:first|beforehand|before\b)",
    _F,
)


# a word one of the kinds above holds (the check's cheap test)
_CUES51S = (
    "check",
    "clear",
    "confirm",
    "agree",
    "run ",
    "ask",
    "say",
    "said",
    "give",
    "nod",
    "ok",
    "sign",
    "approv",
    "wait",
    "hold",
    "hang",
    "let",
    "tell",
    "word",
    "got",
    "get",
)


def _said_so51s(text: str, node: Node, lexicon: Lexicon) -> None:
    """Session 51 (12s): a reading of a text that waits on someone's later word (above) is
    refused."""
    del node
    low = text.lower()
    if not any(w in low for w in _CUES51S):
        return
    m = _SAID_SO51S.search(text)
    if m is None:
        return
    start = m.start() + len(m.group(0)) - len(m.group(0).lstrip(".!?;:, "))
    end = re.compile(r"[.!?;:,]|$").search(text, m.end() - 1)
    said = " ".join(text[start : end.start() if end else len(text)].split())
    raise GroundingError(
        f"{said!r} waits on someone's word or on something to happen, which the robot does not "
        "hear: say what to do now"
    )


# the normaliser's first rewrites (wired into normalise._STEPS19, before the session-50 ones)
_STEPS51S_FIRST: tuple[Callable[[str, Lexicon], str], ...] = ()
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-50 ones)
_STEPS51S: tuple[Callable[[str, Lexicon], str], ...] = ()
# refusals asked of the text before it is read (offline._parse, after the session-50 ones)
REFUSE51S: tuple[Callable[[str, Lexicon], None], ...] = ()
# checks of the whole instruction's reading (offline.parse_instruction, after the session-50 ones)
CHECK51S: tuple[Callable[[str, Node, Lexicon], None], ...] = (_said_so51s,)
