"""The grounder's rules of session 44, engineer 12s (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _ids, _names, _reading
from hltl.grounding.lexicon import Lexicon
from hltl.grounding.tree import Node, tasks

# -- session 44 (12s): a claim condition after a thing ---------------------------------------------
#
# "person b's asking for the cup, also the apple if it's going spare", "Give Zoe the glue if it's
# free", "… and the spoon if nobody else has claimed it": whether the thing can be had, which the
# task needs anyway (the lead's policy: a claim condition reads as the plain request), said straight
# after a thing of the scene (never after a surface or a person: "… on the shelf if it's free" may
# ask whether the shelf is clear). Session 14's courtesy list took 'if it's going' off and left
# 'spare' behind ("also the apple spare"), which nothing read.
_SPARE44S = re.compile(
    r",?\s+if (?:(?:it's|its|it is|they're|they are|that's|that is) (?:still )?(?:going spare|"
    r"going begging|going free|going|spare|free|available|up for grabs|not (?:being )?used|"
    r"not in use|not needed|not spoken for|not claimed|unclaimed)|there's (?:one|any|some) "
    r"(?:going )?spare|(?:nobody|no one|no-one)(?: else)?(?:'s| has| is)? (?:claimed|bagged|"
    r"nabbed|wants|needs|using|after|taken) (?:it|them|that|those))(?=\s*(?:[.!;,]|$))",
    _F,
)


def _if_spare44s(text: str, lexicon: Lexicon) -> str:
    """Session 44 (12s): the claim condition above taken off, when the last name before it is a
    thing of the scene (objects only) and what is left reads."""
    if " if " not in text.lower():
        return text
    m = _SPARE44S.search(text)
    if m is None:
        return text
    said = _names(text[: m.start()], lexicon)
    if not said or any(r.kind != "object" for r in said[-1].refs):
        return text
    out = text[: m.start()] + text[m.end() :]
    return out if _reading(out, lexicon) is not None else text


# -- session 44 (12s): 'shelve' -------------------------------------------------------------------
#
# "shelve the crisps first and when that's done bob can have the bottle", "Shelve the glue, then
# …": to shelve a thing is to put it on the shelf, when the scene has one (its one surface called
# 'shelf' or 'bookshelf'); no other place may follow ("shelve it on the desk" stays refused).
_SHELVE44S = re.compile(
    r"\b(?P<v>shelve)\s+(?P<x>it|them|(?:the|that|this|those|these|his|her|their|both) "
    r"[a-z][a-z' ]*?)(?=\s*(?:[.!;,?]|$|\s+(?:first|then|and|please|now|too|as well|after|"
    r"before|when|once|for (?:me|us)|straight away|right away|quickly)\b))",
    _F,
)


def _shelve44s(text: str, lexicon: Lexicon) -> str:
    """Session 44 (12s): 'shelve X' said as 'put X on the shelf' (above), when the scene has one
    shelf, X names things of it (or is it / them) and what is left reads."""
    if "shelve" not in text.lower():
        return text
    shelf = _ids("shelf", lexicon, "surface")
    if len(shelf) != 1:
        return text
    out = text
    for m in reversed(list(_SHELVE44S.finditer(text))):
        x = m["x"]
        if x.lower() not in ("it", "them") and (
            not _ids(x, lexicon, "object")
            or _ids(x, lexicon, "human")
            or _ids(x, lexicon, "surface")
        ):
            continue
        verb = "Put" if m["v"][0].isupper() else "put"
        out = out[: m.start()] + f"{verb} {x} on the shelf" + out[m.end() :]
    if out == text:
        return text
    read = _reading(out, lexicon)
    if read is None or not any(t.kind == "place" and t.target in shelf for t in tasks(read)):
        return text
    return out


# the normaliser's rewrites run before the session-43 ones (wired into normalise._STEPS19)
_STEPS44S_FIRST: tuple[Callable[[str, Lexicon], str], ...] = (_if_spare44s, _shelve44s)
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-43 ones)
_STEPS44S: tuple[Callable[[str, Lexicon], str], ...] = ()
# refusals asked of the text before it is read (offline._parse, after the session-43 ones)
REFUSE44S: tuple[Callable[[str, Lexicon], None], ...] = ()
# checks of the whole instruction's reading (offline.parse_instruction, after the session-43 ones)
CHECK44S: tuple[Callable[[str, Node, Lexicon], None], ...] = ()
