"""The grounder's rules of session 47, the lead (docs/grounding.md)."""

from __future__ import annotations

from hltl.errors import GroundingError
from hltl.fileio import quote
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F

# the thing or person a correction 'it was …' names (not where a thing is: 'it's on the rack')
_NAMED47L = (
    r"(?:it was|it's|it is|it were)\s+(?:(?:the|a|an|his|her|their)\b|(?-i:[A-Z])|"
    r"[a-z]+\s+(?:he|she|they|who|that)\b)"
)

# -- session 47 (lead): "X, I thought, but it was Y he wanted" -------------------------------------
#
# blind45's one wrong reading (12c's measurement, main 790ed0b4): "Marco's shouting for salt, I
# thought, but it was lemon he wanted, so give Marco the lemon." read `salt>A & lemon>A`. The
# speaker's remark 'I thought' was taken off with the 'but' that joined it, so the salt stayed
# wanted. A thought in the past ('I thought', 'I reckoned', 'or so I thought', …) then 'but it was'
# and a thing or a person takes back what came before it, as 'no, it was …' does: said so, and the
# correction rules read it (or refuse it when they cannot). Not the present 'I think' (a hedge, not
# a thought taken back), and not 'but it's on the rack' (where the thing is, not a correction:
# 12c's probes). A correction that adds or orders ('too', 'as well', 'first', 'then', 'and …') is
# refused: 'no, it's the lemon he wants too' does not say whether the salt stays.
_THOUGHT_BUT47L = re.compiled(
    r"\s*,\s*(?:or so )?I (?:thought|reckoned|figured|assumed|believed|had thought)"
    r"(?: so)?\s*(?:,\s*|\s+)but\s+(?:actually,?\s+)?"
    r"(?=" + _NAMED47L + ")",
    _F,
)
# 'no, it's the lemon he wants too / first / and the salt for Lena': a correction that adds or
# orders, in one clause (12c's probes: the older correction rules read the lemon alone)
_NO_ADDS47L = re.compiled(
    r",\s*(?:no|sorry|actually|wait)\s*,\s*(?=" + _NAMED47L + r")(?P<said>[^.;!?,]*?\b"
    r"(?:(?P<w>too|as well|also|first|next|then|afterwards)\s*(?=[,.;!?]|$)|(?P<a>and)\s))",
    _F,
)
# what after the correction adds to it or orders it, up to the sentence's end
_ADDS47L = re.compiled(
    r"^[^.;!?]*?\b(?P<w>too|as well|also|first|next|after|afterwards|before|then|later|and)\b",
    _F,
)


def thought_but47l(text: str) -> str:
    """Session 47: "X, I thought, but it was Y he wanted" (above) said "X, no, it was Y …";
    refused when the correction adds or orders."""
    if "but" not in text or " I " not in text:
        return text
    m = _THOUGHT_BUT47L.search(text)
    if m is None:
        return text
    added = _ADDS47L.match(text[m.end() :])
    if added is not None:
        said = text[m.start() : m.end() + added.end()].strip(" ,")
        raise GroundingError(
            f"cannot read the correction in {quote(said)}: {added['w']!r} after it could add to "
            "what it takes back or order it; say the whole request again"
        )
    return _THOUGHT_BUT47L.sub(", no, ", text)


def added_correction47l(text: str) -> None:
    """Session 47: 'no, it's the lemon he wants too / first / and the salt for Lena' refused: a
    correction that adds or orders does not say whether what it takes back stays."""
    if "," not in text or "it" not in text:
        return
    m = _NO_ADDS47L.search(text)
    if m is None:
        return
    said = quote(m["said"].strip())
    word = m["w"] or m["a"]
    raise GroundingError(
        f"cannot read the correction {said}: {word!r} in it could add to what it takes back "
        "or order it; say the whole request again"
    )
