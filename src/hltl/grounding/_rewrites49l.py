"""The grounder's rules of session 49, the lead (docs/grounding.md): blind47's wrong readings."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _ids
from hltl.grounding._rewrites41r import _said41r
from hltl.grounding.lexicon import Lexicon
from hltl.grounding.tree import Group, Node, tasks

# -- 'the whole lot' said after named things --------------------------------------------------
#
# blind47: "Load the belt with the three boxes, the whole lot, the brickie's van is nearly here."
# read every object of the depot onto the belt: the grammar took ', the whole lot' as one more
# item, everything. Said right after things it names, 'the whole lot' says again what was just
# named ("the three boxes, the whole lot": all three of them), or adds everything else: with a
# kind's plural naming every object of that kind before it ("the boxes", "the three boxes") it is
# the kind, read so (`kind_lot49l`, run on the text before its first read, as session 45's
# `other_person45l`); after other things that are not everything in the scene it is refused,
# naming both readings.
_LOT49L = r"(?:the whole lot|the lot)(?: of them)?"
_AFTER_THINGS49L = re.compiled(rf",\s*(?P<lot>{_LOT49L})(?=\s*(?:[,.;!?]|$))", _F)


def _lot_said(text: str, m: re.Match[str], lexicon: Lexicon) -> tuple[set[str], bool]:
    """The objects the sentence names before ``m`` (', the whole lot'), and whether they are
    every object of one kind, said by the kind's plural ("the three boxes")."""
    before = re.split(r"[.!?;]\s", text[: m.start()])[-1]
    named = _ids(before, lexicon, "object")
    kinds = {o.category for o in lexicon.scene.objects if o.id in named}
    if len(named) < 2 or len(kinds) != 1:
        return named, False
    (kind,) = kinds
    every = {o.id for o in lexicon.scene.objects if o.category == kind}
    plural = re.search(rf"\b{re.escape(kind)}(?:s|es)\b", before, _F) is not None
    return named, named == every and plural


def kind_lot49l(text: str, lexicon: Lexicon) -> str:
    """Session 49 (lead): "the three boxes, the whole lot" (a kind's plural naming every object of
    that kind, then 'the whole lot' or 'the lot' in apposition) is those objects, not everything
    in the scene: the apposition is taken off before the text is read."""
    if "lot" not in text.lower():
        return text
    for m in reversed(list(_AFTER_THINGS49L.finditer(text))):
        if _lot_said(text, m, lexicon)[1]:
            text = text[: m.start()] + text[m.end() :]
    return text


def _lot_after_things49l(text: str, lexicon: Lexicon) -> None:
    """Session 49 (lead): ', the whole lot' right after a request that names some of the scene's
    objects ("Give Tom the gloves and the tape, the whole lot.") says those again or adds
    everything else: refused naming both (when what was named is everything, the two readings
    are one; a kind's plural before it is read by `kind_lot49l`)."""
    if "lot" not in text.lower():
        return
    for m in _AFTER_THINGS49L.finditer(text):
        named, kind = _lot_said(text, m, lexicon)
        every = {o.id for o in lexicon.scene.objects}
        if kind or not named or named == every:
            continue
        raise GroundingError(
            f"{m['lot']!r} after {', '.join(sorted(named))} could say those again or add "
            f"everything else ({', '.join(sorted(every - named))}): say which"
        )


# -- a choice, then the speaker has forgotten which -------------------------------------------
#
# blind47: "Kofi wanted one of the spanners for the stonecarver's job, the small or the large,
# it's gone clean out of my head." read `spanner_small>A | spanner_large>A`: the closing 'it's
# gone out of my head' was taken off as a reason (`_reasons21`), and the choice left was the
# robot's. The person wanted one of them; which, the speaker has forgotten (session 39 refuses
# the same doubt said with 'which'). Any reading that leaves a choice is refused, naming it.
_FORGOT49L = re.compiled(
    r"[,;:.!?\-–—]\s*(?:(?:but|and|though|sorry|honestly)[,\s]\s*)*"
    r"(?:it(?:'s| has| is)? (?:gone (?:clean |right |completely )?out of my head|"
    r"slipped my mind|escaped me|gone from me)|"
    r"I (?:can't|cannot|can not|don't|do not|couldn't|could not) (?:for the life of me )?"
    r"(?:remember|recall|say)|I(?:'ve| have)? forgotten|I forget|I forgot|"
    r"(?:I'm |I am )?not sure|no idea|dunno)"
    r"(?: now| exactly| offhand| which(?: one)?)?\s*[.!]?\s*$",
    _F,
)


def _forgot_choice49l(text: str, node: Node, lexicon: Lexicon) -> None:
    """Session 49 (lead): a reading with a choice in it, of a text that closes with the speaker
    saying they have forgotten ("…, the small or the large, it's gone clean out of my head"), is
    a choice the person made and the speaker lost, not one left to the robot: refused, naming the
    options."""
    low = text.lower()
    words = ("mind", "head", "forg", "remember", "recall", "sure", "idea", "dunno", "escaped")
    if not any(w in low for w in words) or _FORGOT49L.search(text) is None:
        return
    groups = [node]
    while groups:
        g = groups.pop()
        if not isinstance(g, Group):
            continue
        if g.op == "or":
            offered = sorted({_said41r(t, lexicon) for t in tasks(g)})
            raise GroundingError(
                "the speaker has forgotten which was asked for: "
                + " or ".join(offered)
                + ": say which"
            )
        groups.extend(g.children)


# refusals asked of the text before it is read (offline._parse, after the session-48 ones)
REFUSE49L: tuple[Callable[[str, Lexicon], None], ...] = (_lot_after_things49l,)
# checks of the whole instruction's reading (offline.parse_instruction, after the session-48 ones)
CHECK49L: tuple[Callable[[str, Node, Lexicon], None], ...] = (_forgot_choice49l,)
