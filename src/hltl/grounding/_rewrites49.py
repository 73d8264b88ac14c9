"""The grounder's rules of session 49, engineer 12 (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _names
from hltl.grounding._rewrites45 import _read_for
from hltl.grounding.lexicon import Lexicon
from hltl.grounding.tree import Node

# -- session 49 (engineer 12): blind47's refusals of politeness and fillers, wants and needs,
# pronouns and ellipsis and questions, each read as a family. Every rule rewrites to words the
# grammar (or an older rule) already reads, and keeps the rewrite only when it reads.


def _capital49(out: str) -> str:
    """``out`` with its first letter upper-cased."""
    return out[:1].upper() + out[1:]


# -- sympathy said after the request with a word the grounder does not know ("Lily's grizzling
# for her teddy bear again, poor mite.", "…, the poor little poppet."): the courtesy list's
# ', poor thing' took such words for a name before it ran; taken off when the words name nothing
_POOR49 = re.compile(r",\s*(?:the )?poor (?:little |wee |old )?(?P<w>[a-z]+)(?=\s*(?:[.!]|$))", _F)


def _poor49(text: str, lexicon: Lexicon) -> str:
    """Session 49: the sympathy above taken off."""
    if "poor " not in text.lower():
        return text
    m = _POOR49.search(text)
    if m is None or _names(m.group(0).strip(", ").removeprefix("the "), lexicon):
        return text
    return _read_for(f"{text[: m.start()]}{text[m.end() :]}", text, None, lexicon)


# -- 'seeing' alone opening a reason ("Could the bottle go over to Person A, seeing she's asked
# twice?"): read as 'seeing as' (session 28's reasons read that)
_SEEING49 = re.compile(r",\s*seeing (?=(?:she|he|they|it|we|I)(?:'s|'ve|'d|'re| has| is| was) )")


def _seeing49(text: str, lexicon: Lexicon) -> str:
    """Session 49: 'seeing' before a pronoun and its verb read as 'seeing as'."""
    if ", seeing " not in text:
        return text
    out = _SEEING49.sub(", seeing as ", text, count=1)
    return text if out == text else _read_for(out, text, None, lexicon)


# -- 'sorting P out with the X' ("would you mind sorting him out with the bottle?"): giving P
# the X (an older rule reads 'sort P out with the X')
_SORT49 = re.compile(
    r"\bsorting (?P<p>him|her|them|[A-Z]\w*(?: [A-Z]\w*)?) out with "
    r"(?P<x>(?:the|a|an|some|his|her|their) )",
)


def _sort_out49(text: str, lexicon: Lexicon) -> str:
    """Session 49: 'sorting P out with the X' read as 'giving P the X'."""
    if "sorting " not in text:
        return text
    m = _SORT49.search(text)
    if m is None:
        return text
    out = f"{text[: m.start()]}giving {m['p']} {m['x']}{text[m.end() :]}"
    return _read_for(out, text, None, lexicon)


# -- a reason that something is in someone's way ("Would you set the bowl down on the tray, it's
# in Dana's way?"): read as 'it's in the way' (an older rule reads that), the person named
_IN_WAY49 = re.compile(
    r",\s*it(?:'s| is) (?:getting )?in (?P<p>[A-Z]\w*(?: [A-Z]\w*)?'s|his|her|their) way"
    r"(?=\s*[.!?]?$)"
)


def _in_way49(text: str, lexicon: Lexicon) -> str:
    """Session 49: '… in P's way' closing a placing read as '… in the way'."""
    if " way" not in text:
        return text
    m = _IN_WAY49.search(text)
    if m is None:
        return text
    out = f"{text[: m.start()]}, it's in the way{text[m.end() :]}"
    return _read_for(out, text, None, lexicon)


# -- 'for that' closing a request after what someone is doing ("Jess is putting up brackets,
# could you fetch Jess the power drill for that?"): the purpose said again, taken off
_FOR_THAT49 = re.compile(r" for (?:that|this|the job)(?=\s*[.!?]?$)")


def _for_that49(text: str, lexicon: Lexicon) -> str:
    """Session 49: a closing 'for that' taken off a request after a remark."""
    if " for th" not in text and " for the job" not in text:
        return text
    m = _FOR_THAT49.search(text)
    if m is None or "," not in text[: m.start()]:
        return text
    return _read_for(f"{text[: m.start()]}{text[m.end() :]}", text, None, lexicon)


# -- 'any objection to' / 'any chance of' before what to do ("Person B's hungry, any objection to
# giving him the chips?"): asked as 'would you mind'
_OBJECTION49 = re.compile(
    r"(?P<lead>^|,\s*)(?:(?:is there|would there be|have you got|got) )?any (?:objection to|"
    r"chance of) (?=(?:giving|handing|passing|bringing|taking|putting|setting|getting) )",
    _F,
)


def _objection49(text: str, lexicon: Lexicon) -> str:
    """Session 49: 'any objection to V-ing' read as 'would you mind V-ing'."""
    if "any " not in text.lower():
        return text
    m = _OBJECTION49.search(text)
    if m is None:
        return text
    ask = "would you mind " if m["lead"] else "Would you mind "
    out = f"{text[: m.start()]}{m['lead']}{ask}{text[m.end() :]}"
    return _read_for(out, text, None, lexicon)


# the normaliser's first rewrites (wired into normalise._STEPS19, before the session-48 ones)
_STEPS49_FIRST: tuple[Callable[[str, Lexicon], str], ...] = (
    _poor49,
    _seeing49,
    _sort_out49,
    _in_way49,
    _for_that49,
    _objection49,
)
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-48 ones)
_STEPS49: tuple[Callable[[str, Lexicon], str], ...] = ()
# refusals asked of the text before it is read (offline._parse, after the session-48 ones)
REFUSE49: tuple[Callable[[str, Lexicon], None], ...] = ()
# checks of the whole instruction's reading (offline.parse_instruction, after the session-48 ones)
CHECK49: tuple[Callable[[str, Node, Lexicon], None], ...] = ()
