"""The grounder's rules of session 47, the lead (docs/grounding.md)."""

from __future__ import annotations

from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F

# -- session 47 (lead): "X, I thought, but it was Y he wanted" -------------------------------------
#
# blind45's one wrong reading (12c's measurement, main 790ed0b4): "Marco's shouting for salt, I
# thought, but it was lemon he wanted, so give Marco the lemon." read `salt>A & lemon>A`. The
# speaker's remark 'I thought' was taken off with the 'but' that joined it, so the salt stayed
# wanted. 'I thought, but it was …' takes back what came before it, as 'no, it was …' does: said
# so, and the correction rules read it (or refuse it when they cannot).
_THOUGHT_BUT47L = re.compiled(
    r"\s*,\s*(?:or so )?I (?:thought|think|reckoned|figured|assumed|believed)"
    r"(?: so)?\s*(?:,\s*|\s+)but\s+(?:actually,?\s+|no,?\s+)?"
    r"(?=(?:it was|it's|it is|it were|turns out|it turns out|it turned out)\b)",
    _F,
)


def thought_but47l(text: str) -> str:
    """Session 47: "X, I thought, but it was Y he wanted" (above) said "X, no, it was Y …"."""
    if "but" not in text or " I " not in text:
        return text
    return _THOUGHT_BUT47L.sub(", no, ", text)
