"""The grounder's rules of session 46, the lead (docs/grounding.md)."""

from __future__ import annotations

from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F

# -- session 46 (lead): "P wants X and Y down on the S" -------------------------------------------
#
# blind44's one wrong reading (12c's measurement, main c427b55a): "Marco wants both plates down on
# the counter for plating up." read `plate_white>A & plate_blue@counter`. The grammar reads "P wants
# X and Y on the S" as both placed, but a particle before the place ('down', 'up', 'over', 'back',
# 'across') made "Y down on the S" a clause of its own, so X went to P. With no comma or sentence
# end between the wanting and the place, the particle says nothing the place does not: it is
# dropped, and both are placed, as without it.
_PARTICLE_PLACE46L = re.compiled(
    r"\b(?P<head>(?:wants|wanted|needs|needed|would like|'d like|would love|'d love|"
    r"asked for|is after|was after)\s+(?:[^,.;:!?]*?\band\b|both\b)"
    r"[^,.;:!?]*?) "
    r"(?:down|up|over|back|across) (?P<prep>on|onto|in|into) ",
    _F,
)


def particle_place46l(text: str) -> str:
    """Session 46: "Marco wants both plates down on the counter." (above): the particle before the
    place dropped when a wanting of two things ('and', 'both') runs into it unbroken."""
    low = text.lower()
    if not any(w in low for w in (" and ", "both")) or not any(
        w in low for w in ("want", "need", "like", "after")
    ):
        return text
    return _PARTICLE_PLACE46L.sub(lambda m: f"{m['head']} {m['prep']} ", text)
