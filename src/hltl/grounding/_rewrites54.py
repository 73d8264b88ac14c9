"""The grounder's rules of session 54, engineer 12 (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _names, _only_person
from hltl.grounding.lexicon import Lexicon
from hltl.grounding.tree import Node

# -- session 54 (engineer 12): the open wrong readings of session 53 (12c's fuzz), then blind52's
# refusals of politeness and fillers, wants and needs, pronouns and ellipsis, lower case and
# questions, each read as a family.

# -- wrong readings --------------------------------------------------------------------------------

# -- a request said to have been made on an earlier day ("Bob asked for the apple yesterday.",
# "Alice asked for the cup last night, poor thing."): session 19's words took the time off as how
# long ago he asked (read apple>B), while "Bob wanted / needed the apple yesterday." are refused: a
# want of another day may be over. Refused, unless what follows points back at it and asks for it
# now ('…, so take it to him.', '… and he still wants it.': main's reading stands)
_DAYS_AGO54 = re.compile(
    r"\b(?P<said>(?:asked|was asking|were asking|requested|begged)(?: (?:me|you|us))? for "
    r"[^.;!?,]*? (?:yesterday|last night|last week|the other day|(?:two|three|four|five|a few|"
    r"several|\d+) days ago|a week ago|over the weekend|at the weekend)(?: (?:morning|afternoon|"
    r"evening))?)(?=\s*(?:[.,;!?]|$)|\s+(?:and|but|so)\b)",
    _F,
)
# what, after the time, points back at the thing asked for ('it', 'them', 'still' …)
_BACK54 = re.compile(r"\b(?:it|them|that|those|this|one|ones|still|again|now)\b", _F)
_DAYS54 = ("yesterday", "last night", "last week", "other day", "days ago", "week ago", "weekend")


def _days_ago54(text: str, lexicon: Lexicon) -> None:
    """Session 54: 'P asked for X yesterday' refused unless the rest asks for it again (above)."""
    low = text.lower()
    if not any(w in low for w in _DAYS54):
        return
    m = _DAYS_AGO54.search(text)
    if m is None or _BACK54.search(text, m.end()):
        return
    raise GroundingError(
        f"{m['said']!r} says what was asked for on another day: the want may be over; say 'give "
        "…' to have it handed over now"
    )


# the words beside the names of things in a list of them ('the apple and his crisps')
_LIST_WORDS54 = frozenset(
    (
        "the",
        "a",
        "an",
        "his",
        "her",
        "their",
        "its",
        "my",
        "our",
        "your",
        "some",
        "and",
        "both",
        "two",
        "three",
        "those",
        "these",
        "that",
        "this",
        "one",
        "of",
        ",",
    )
)


def _things_only54(words: str, lexicon: Lexicon) -> bool:
    """Whether ``words`` names objects of the scene and says nothing else ('the apple and the
    crisps', 'a mug'; not 'her eye on the red mug')."""
    names = _names(words, lexicon)
    if not names or any(r.kind != "object" for it in names for r in it.refs):
        return False
    rest = words.lower()
    for it in names:
        rest = rest.replace(it.text.lower(), " ", 1)
    return all(w in _LIST_WORDS54 for w in rest.replace(",", " , ").split())


# -- a past holding with a reason or time after it ("Bob had the apple since his match ended.",
# "Lena had the tongs because she was cooking.", "Bob got the apple because he was hungry.", "Bob
# had the apple first."): the grammar read the clause as a handover (apple>B), while "Bob had the
# apple." alone is refused as what was (session 32's _state_only32s, a sentence of a person and
# the objects only). Refused the same: a person, 'had' / 'has had' / "'s had" / 'got', objects
# only, then 'since' / 'because' / 'as' / 'first' / 'when' …
_HAD_WHY54 = re.compile(
    r"(?:^|[.;!?,]\s*)(?:(?:and|but|so|well|oh),?\s+)?(?P<said>(?P<p>[^.;!?,]+?)(?:\s+(?:had|"
    r"has had|got)|'s had)\s+(?P<x>(?!to\b)[^.;!?,]+?))\s+(?:ever since|since|because|'cause|cause|"
    r"cos|coz|as|when|first|after|till|until|once)\b",
    _F,
)
_WHY54 = (
    " since",
    "because",
    "cause",
    " cos",
    " coz",
    " as ",
    " when",
    " first",
    " after",
    " till",
    " until",
    " once",
)


def _had_why54(text: str, lexicon: Lexicon) -> None:
    """Session 54: a past holding with a reason or time after it refused (above)."""
    low = text.lower()
    if ("had " not in low and "got " not in low) or not any(w in low for w in _WHY54):
        return
    for m in _HAD_WHY54.finditer(text):
        if not _things_only54(m["x"], lexicon) or not _only_person(m["p"], lexicon):
            continue
        raise GroundingError(
            f"{m['said']!r} says what {m['p']} had: it asks for nothing; say 'give {m['p']} "
            f"{m['x']}' to have it handed over"
        )


# the normaliser's first rewrites (wired into normalise._STEPS19, before the session-53 ones)
_STEPS54_FIRST: tuple[Callable[[str, Lexicon], str], ...] = ()
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-53 ones)
_STEPS54: tuple[Callable[[str, Lexicon], str], ...] = ()
# refusals asked of the text before it is read (offline._parse, after the session-53 ones)
REFUSE54: tuple[Callable[[str, Lexicon], None], ...] = (_days_ago54, _had_why54)
# checks of the whole instruction's reading (offline.parse_instruction, after the session-53 ones)
CHECK54: tuple[Callable[[str, Node, Lexicon], None], ...] = ()
