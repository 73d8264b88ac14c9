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
# The same with the two said the other way round ("Give Tom the lot, the boxes."), with a dash
# for the comma, and with 'everything' for 'the whole lot' (12c's probes of the family).
_LOT49L = r"(?:the whole lot|the lot|everything)(?: of them)?"
_AFTER_THINGS49L = re.compiled(
    rf"(?:,|\s+[-–—])\s*(?P<lot>{_LOT49L})(?=\s*(?:[,.;!?]|$|\s[-–—]))", _F
)
_BEFORE_THINGS49L = re.compiled(
    rf"\b(?P<lot>{_LOT49L})(?:,|\s+[-–—])\s*(?P<np>(?:the|all the|all|both|both the|those|these) "
    r"[^,.;:!?\-–—]+?)(?=\s*(?:[,.;:!?]|$|\s[-–—]))",
    _F,
)


def _kind_of(named: set[str], said: str, lexicon: Lexicon) -> bool:
    """Whether ``named`` is every object of one kind (two or more), said by the kind's plural in
    ``said`` ("the three boxes")."""
    kinds = {o.category for o in lexicon.scene.objects if o.id in named}
    if len(named) < 2 or len(kinds) != 1:
        return False
    (kind,) = kinds
    every = {o.id for o in lexicon.scene.objects if o.category == kind}
    return named == every and re.search(rf"\b{re.escape(kind)}(?:s|es)\b", said, _F) is not None


def _lot_said(text: str, m: re.Match[str], lexicon: Lexicon) -> tuple[set[str], bool]:
    """The objects the sentence names before ``m`` (', the whole lot'), and whether they are
    every object of one kind, said by the kind's plural."""
    before = re.split(r"[.!?;]\s", text[: m.start()])[-1]
    named = _ids(before, lexicon, "object")
    return named, _kind_of(named, before, lexicon)


def kind_lot49l(text: str, lexicon: Lexicon) -> str:
    """Session 49 (lead): "the three boxes, the whole lot" / "the lot, the boxes" (a kind's plural
    naming every object of that kind, and 'the whole lot', 'the lot' or 'everything' in
    apposition) is those objects, not everything in the scene: the apposition is taken off
    before the text is read."""
    low = text.lower()
    if "lot" not in low and "everything" not in low:
        return text
    for m in reversed(list(_AFTER_THINGS49L.finditer(text))):
        if _lot_said(text, m, lexicon)[1]:
            text = text[: m.start()] + text[m.end() :]
    for m in reversed(list(_BEFORE_THINGS49L.finditer(text))):
        if _kind_of(_ids(m["np"], lexicon, "object"), m["np"], lexicon):
            text = text[: m.start()] + m["np"] + text[m.end() :]
    return text


def _lot_after_things49l(text: str, lexicon: Lexicon) -> None:
    """Session 49 (lead): ', the whole lot' (or 'everything') right after a request that names
    some of the scene's objects ("Give Tom the gloves and the tape, the whole lot.") says those
    again or adds everything else, and so does 'the lot, the gloves and the tape': refused naming
    both (when what was named is everything, the two readings are one; a kind's plural is read
    by `kind_lot49l`)."""
    low = text.lower()
    if "lot" not in low and "everything" not in low:
        return
    every = {o.id for o in lexicon.scene.objects}
    found = [(m["lot"], *_lot_said(text, m, lexicon)) for m in _AFTER_THINGS49L.finditer(text)]
    found += [
        (m["lot"], named, _kind_of(named, m["np"], lexicon))
        for m in _BEFORE_THINGS49L.finditer(text)
        for named in [_ids(m["np"], lexicon, "object")]
    ]
    for lot, named, kind in found:
        if kind or not named or named == every:
            continue
        raise GroundingError(
            f"{lot!r} with {', '.join(sorted(named))} could say those again or add "
            f"everything else ({', '.join(sorted(every - named))}): say which"
        )


# -- a choice, then the speaker has forgotten which -------------------------------------------
#
# blind47: "Kofi wanted one of the spanners for the stonecarver's job, the small or the large,
# it's gone clean out of my head." read `spanner_small>A | spanner_large>A`: the closing 'it's
# gone out of my head' was taken off as a reason (`_reasons21`), and the choice left was the
# robot's. The person wanted one of them; which, the speaker has forgotten (session 39 refuses
# the same doubt said with 'which'). Any reading that leaves a choice is refused, naming it.
# The remark in the words people use for it (12c's probes: "I've clean forgotten", "my mind's
# gone blank", "it's completely gone", "I didn't catch it", "I'd have to ask him", "memory's
# shot"), closing the text or not ("…, it's gone clean out of my head, sorry."), with or without
# stops ("… the salt or the lemon its gone clean out of my head").
_CLOSE49L = r"(?=\s*(?:[,.;!?]|$|\bwhich\b|\bsorry\b|\bnow\b|\bexactly\b|\boffhand\b))"
_FORGOT49L = re.compiled(
    r"\b(?:"
    r"it(?:'s|s| has| is)? (?:(?:clean|right|completely|totally|just) )?(?:gone|went) "
    r"(?:(?:clean|right|completely|totally) )?(?:out (?:of )?my (?:head|mind)|from me|from my head)"
    rf"|it(?:'s|s| has| is) (?:(?:clean|completely|totally|just) )?gone{_CLOSE49L}"
    r"|it(?:'s|s| has)? (?:slipped my mind|escaped me)"
    r"|my mind(?:'s| has| is)? (?:gone )?(?:a )?blank"
    r"|I'm blanking|I am blanking|I've blanked|I blanked"
    rf"|I(?:'ve| have)? (?:clean |completely |totally )?forgotten{_CLOSE49L}"
    rf"|I forg[eo]t{_CLOSE49L}"
    r"|I (?:can't|cannot|can not|don't|do not|couldn't|could not) (?:for the life of me )?"
    rf"(?:remember|recall|say){_CLOSE49L}"
    r"|I (?:didn't|did not) catch (?:it|which)|I wasn't listening|I was not listening"
    r"|I (?:didn't|did not|never) (?:write|wrote) it down|I'd have to ask (?:him|her|them)"
    r"|(?:my )?memory(?:'s| is) (?:shot|gone)"
    rf"|(?:I'm |I am )?not sure{_CLOSE49L}|no idea{_CLOSE49L}|dunno"
    r")",
    _F,
)
_FORGOT_WORDS49L = (
    "gone",
    "went",
    "mind",
    "blank",
    "forg",
    "remember",
    "recall",
    "say",
    "catch",
    "listening",
    "write",
    "wrote",
    "ask",
    "memory",
    "sure",
    "idea",
    "dunno",
    "escaped",
)


def forgot49l(text: str) -> bool:
    """Session 49 (lead): the speaker says they have forgotten ("…, the small or the large, it's
    gone clean out of my head"), in one of the wordings listed above. A reading with a choice in
    it, of such a text, is a choice the person made and the speaker lost, not one left to the
    robot: session 50's `_forgot_choice50l` refuses it, naming the options (one check for both
    sessions' wordings, so the reading is walked once)."""
    low = text.lower()
    return any(w in low for w in _FORGOT_WORDS49L) and _FORGOT49L.search(text) is not None


def choice_forgotten49l(
    node: Node, lexicon: Lexicon, why: str = "the speaker has forgotten which was asked for"
) -> None:
    """A reading with a choice in it, of a text in which the speaker says they have forgotten:
    refused (``why``), naming the options (none: nothing to say)."""
    groups = [node]
    while groups:
        g = groups.pop()
        if not isinstance(g, Group):
            continue
        if g.op == "or":
            offered = sorted({_said41r(t, lexicon) for t in tasks(g)})
            raise GroundingError(f"{why}: {' or '.join(offered)}: say which")
        groups.extend(g.children)


# refusals asked of the text before it is read (offline._parse, after the session-48 ones)
REFUSE49L: tuple[Callable[[str, Lexicon], None], ...] = (_lot_after_things49l,)
# checks of the whole instruction's reading (offline.parse_instruction, after the session-48 ones)
CHECK49L: tuple[Callable[[str, Node, Lexicon], None], ...] = ()
