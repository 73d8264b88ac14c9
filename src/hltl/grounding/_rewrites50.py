"""The grounder's rules of session 50, engineer 12 (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _ids, _names, _only_person, _unknown_word
from hltl.grounding._rewrites44r import _agrees44r
from hltl.grounding._rewrites45 import _read_for
from hltl.grounding._rewrites46 import _APOLOGY_ONLY46
from hltl.grounding._rewrites48 import _GLOSS48
from hltl.grounding.lexicon import Lexicon
from hltl.grounding.tree import Node

# -- session 50 (engineer 12): blind48's refusals of politeness and fillers, wants and needs and
# questions, each read as a family. Every rule rewrites to words the grammar (or an older rule)
# already reads, and keeps the rewrite only when it reads.


def _cut50(text: str, start: int, end: int, put: str, lexicon: Lexicon) -> str:
    """``text`` with ``text[start:end]`` said as ``put`` (first letter upper-cased), when that
    reads; else ``text``."""
    out = f"{text[:start]}{put}{text[end:]}"
    return _read_for(out[:1].upper() + out[1:], text, None, lexicon)


# -- a word of thanks in another language glossed by who says it and where ("Daalu, as my mum
# says back in Lagos, and …", "Kinanaskomitin, as folk say out in Saskatchewan; …", "Gràtzias,
# as they'd put it in Cagliari: …"): the gloss taken off after the foreign word (session 48's
# _gloss48 reads 'as we say back home in Kosrae,'; session 41's 'as they say in Russian,')
_GLOSS50 = re.compile(
    r"^(?P<w>[^\W\d_]+(?: [a-z]+)?),\s*as (?:we|they|folk|people|you|my [a-z]+|our [a-z]+)"
    r"(?P<v>(?:'d| would)? (?:say|put it)| says| puts it| always says?| used to say)"
    r" (?P<pre>(?:back|out|over|up|down) )?(?:in|on) "
    r"(?P<place>[A-Z][a-z]+(?: [A-Z][a-z]+)?)\s*[,;:]\s*"
)


def _gloss50(text: str, lexicon: Lexicon) -> str:
    """Session 50: the gloss above taken off."""
    if " in " not in text and " on " not in text:
        return text
    m = _GLOSS50.match(text)
    if m is None or _names(m["place"], lexicon) or _GLOSS48.match(text):
        return text
    if not (m["pre"] or "put" in m["v"]):
        return text  # ('as they say in Russian,' is session 41's)
    if not all(_unknown_word(w, lexicon) for w in m["w"].split()):
        return text
    return _read_for(f"{m['w']}, {text[m.end() :]}", text, None, lexicon)


# -- 'only' opening the reason after an apology ("Sorry to trouble you, only Bob's parched after
# the gorge walking, so the bottle to him"): 'it's just that', taken off
_ONLY50 = re.compile(
    r"^(?:(?:I'm |I am |So |Ever so |Really )?[Ss]orry|Apologies|I hate to (?:ask|bother you|"
    r"trouble you|be a pain))[^,]{0,40}(?P<c>,\s*only )(?=(?P<p>[A-Z]\w*(?: [A-Z]\w*)?|she|he|"
    r"they)(?:'s|'re| is| are| has| have| was| were| needs| wants)\b)"
)


def _only50(text: str, lexicon: Lexicon) -> str:
    """Session 50: 'only' after an apology taken off."""
    if ", only " not in text:
        return text
    m = _ONLY50.match(text)
    if (
        m is None
        or _APOLOGY_ONLY46.match(text)
        or (m["p"][0].isupper() and not _only_person(m["p"], lexicon))
    ):
        return text
    return _read_for(f"{text[: m.start('c')]}, {text[m.end() :]}", text, None, lexicon)


# -- 'and no rush at all' between commas ("Whenever you're free, and no rush at all, Person A
# would like the chips"): said 'and no rush' (older rules read that)
_NO_RUSH50 = re.compile(r"(?<=, and )no (?P<r>rush|hurry) (?:at all|whatsoever)(?=\s*,)")


def _no_rush50(text: str, lexicon: Lexicon) -> str:
    """Session 50: 'and no rush at all' read as 'and no rush'."""
    if "and no " not in text:
        return text
    m = _NO_RUSH50.search(text)
    if m is None:
        return text
    return _cut50(text, m.start(), m.end(), f"no {m['r']}", lexicon)


# -- 'if it pleases you' / 'if it please you' ("If it pleases you, the spoon can go in the
# sink"): the courtesy 'if you please', no condition
_PLEASES50 = re.compile(r"\bif it pleases? you\b", _F)


def _pleases50(text: str, lexicon: Lexicon) -> str:
    """Session 50: 'if it pleases you' read as 'if you please'."""
    if "it pleas" not in text.lower():
        return text
    m = _PLEASES50.search(text)
    if m is None:
        return text
    return _cut50(text, m.start(), m.end(), "if you please", lexicon)


# -- 'With respect,' opening a request someone else said ("With respect, the boss says the torch
# goes to Jess, …"): a courtesy, taken off ('With respect,' before the request itself is read
# already, and session 33's _formal33t takes 'With all due respect,' off before 'the boss says')
_RESPECT50 = re.compile(
    r"^With (?:great )?respect\s*,\s*(?=(?:the [a-z]+|[A-Z]\w*(?: [A-Z]\w*)?) (?:says|said|"
    r"reckons|thinks)\b)"
)


def _respect50(text: str, lexicon: Lexicon) -> str:
    """Session 50: an opening 'With respect,' before a said request taken off."""
    if not text.startswith("With "):
        return text
    m = _RESPECT50.match(text)
    if m is None:
        return text
    return _cut50(text, 0, m.end(), "", lexicon)


# -- 'so it's out of the way (of …)' closing a placing ("Would you be able to pop the red mug down
# on the counter so it's out of the way of the sand sculpting photos?"): its reason, taken off
_OUT_OF_WAY50 = re.compile(
    r",?\s+so (?:that )?it(?:'s| is|'ll be| will be) (?:out of (?:the|his|her|their|"
    r"[A-Z]\w*(?: [A-Z]\w*)?'s) way|not in (?:the|his|her|their) way)(?: of [^,.!?]*)?"
    r"(?=\s*[.!?]?$)"
)


def _out_of_way50(text: str, lexicon: Lexicon) -> str:
    """Session 50: a closing 'so it's out of the way' taken off."""
    if " way" not in text:
        return text
    m = _OUT_OF_WAY50.search(text)
    if m is None:
        return text
    return _cut50(text, m.start(), m.end(), "", lexicon)


# -- 'as a thank you (for …)' after a request ("Could the chips go to Person A, as a thank you for
# the belly dancing display?"): said 'to say thank you' (older rules read that; what it is for
# taken off when it names nothing of the scene)
_THANK_YOU50 = re.compile(
    r",\s*as (?:a (?:little |small |big |wee )?thank[- ]you|thanks|a token of thanks)"
    r"(?P<for> for [^,;.!?]+)?(?=\s*[.!?]?$)"
)


def _thank_you50(text: str, lexicon: Lexicon) -> str:
    """Session 50: 'as a thank you' read as 'to say thank you'."""
    if "thank" not in text or " as " not in text:
        return text
    m = _THANK_YOU50.search(text)
    if m is None or (m["for"] and _names(m["for"], lexicon)):
        return text
    return _cut50(text, m.start(), m.end(), ", to say thank you", lexicon)


# -- 'P get his / her hands on the X' ("Might Person B get his hands on the bottle, …?"): P
# having the X, when the pronoun may be P
_HANDS_ON50 = re.compile(
    r"\b(?!(?:Could|Can|Might|May|Would|Will|Shall|Should) )(?P<p>[A-Z]\w*(?: [A-Z]\w*)?) get "
    r"(?P<a>his|her|their) hands on "
    r"(?=(?:the|a|an|some|that|those|these) )"
)


def _hands_on50(text: str, lexicon: Lexicon) -> str:
    """Session 50: 'P get his hands on the X' read as 'P have the X'."""
    if " hands on " not in text:
        return text
    m = _HANDS_ON50.search(text)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    pid = next(iter(_ids(m["p"], lexicon)))
    pro = {"his": "he", "her": "she", "their": "they"}[m["a"]]
    if not _agrees44r(pid, pro, lexicon):
        return text
    return _cut50(text, m.start(), m.end(), f"{m['p']} have ", lexicon)


# -- 'is there any chance of the X finding its way to P' ("Is there any chance of the apple
# finding its way to Person A, …?"): asked as 'could the X find its way to P'
_FINDING50 = re.compile(
    r"^(?:Is there |Would there be )?[Aa]ny chance of (?P<x>(?:the|that|those|these) [a-z]+"
    r"(?: [a-z]+)?) (?:finding|making) (?P<its>its|their) way "
)


def _finding50(text: str, lexicon: Lexicon) -> str:
    """Session 50: 'any chance of the X finding its way' read as 'could the X find its way'."""
    if "its way" not in text and "their way" not in text:
        return text
    m = _FINDING50.match(text)
    if m is None:
        return text
    return _cut50(text, 0, m.end(), f"Could {m['x']} find {m['its']} way ", lexicon)


# the normaliser's first rewrites (wired into normalise._STEPS19, before the session-49 ones)
_STEPS50_FIRST: tuple[Callable[[str, Lexicon], str], ...] = (
    _gloss50,
    _only50,
    _no_rush50,
    _pleases50,
    _respect50,
    _out_of_way50,
    _thank_you50,
    _hands_on50,
    _finding50,
)
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-49 ones)
_STEPS50: tuple[Callable[[str, Lexicon], str], ...] = ()
# refusals asked of the text before it is read (offline._parse, after the session-49 ones)
REFUSE50: tuple[Callable[[str, Lexicon], None], ...] = ()
# checks of the whole instruction's reading (offline.parse_instruction, after the session-49 ones)
CHECK50: tuple[Callable[[str, Node, Lexicon], None], ...] = ()
