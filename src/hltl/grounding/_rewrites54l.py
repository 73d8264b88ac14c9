"""The grounder's rules of session 54, the lead (docs/grounding.md): 12c's fuzz reports."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _ids, _objects_only, _only_person
from hltl.grounding._rewrites42r import _WHO42R
from hltl.grounding._rewrites44l import beside_request44l
from hltl.grounding._rewrites53l import _PAST53L, _THEN_THING53L, want_changed53l
from hltl.grounding.lexicon import Lexicon
from hltl.grounding.tree import Node, tasks

# -- what a person holds, beside more for the same person ------------------------------------
#
# 12c's session-53 fuzz: session 53's `_held_request53l` refuses "Bob's got the apple; give him
# the crisps." (a holding beside a request to the same person: it could say what Bob holds, or
# allot it), but only where the request opens with a verb of handing. Said any other way the same
# sentence read `apple>B & chips>B`: "Bob has the apple; the crisps to him as well.", "…; let him
# have the crisps.", "…; he should get the crisps.", "…; the crisps are for him.", "Bob has the
# apple and the cup; give him the crisps.", "Bob has both mugs; give him the crisps.". No list of
# request forms closes, so this is asked of the reading: a present holding of definite things by
# one person ("P has / 's got / has got the X (and the Y)", "P has both Xs"), not under a
# condition ("once / when / if P has …"), whose things the reading all hands to P together with
# something the holding does not name, is refused naming both readings. Kept: shares (session 32:
# "Bob has the apple, Alice the crisps.", "Bob has the apple and the cup; give Alice the
# crisps.": P gets only what P is said to have), a holding with 'so' or of one's own (session 44),
# one of several (session 53's `_HELD_ONE53L`), what P had (session 32 refuses it).
_HELD54L = re.compiled(
    rf"(?P<head>(?:^|[.;,:!?]\s*|\b(?:and|but|so)\s+))(?P<who>{_WHO42R})\s*"
    r"(?:'s got|’s got|\s*has got|\s*has|'s already got|\s*already has|\s*has already got)\s+"
    r"(?P<x>(?:the|both(?: of)?(?: the)?|all(?: of)? the|those|these)\s+[^.;,:!?]*?)"
    r"(?=\s*(?:[.;,:!?]|$|\b(?:and|but|so|then|while|though)\s+(?!(?:the|both|his|her|their)\b)))",
    _F,
)
_CONDITION54L = re.compiled(
    r"\b(?:once|when|whenever|if|after|as soon as|until|till|before|while|unless|since)\s+$", _F
)


def _handed54l(node: Node, who: str, lexicon: Lexicon) -> set[str]:
    """The objects the reading hands ``who`` (one person of the scene, by a name)."""
    person = next(iter(_ids(who, lexicon)))
    return {t.obj for t in tasks(node) if t.kind == "deliver" and t.target == person}


def _held_and_more54l(text: str, node: Node, lexicon: Lexicon) -> None:
    """Session 54 (lead): "Bob has the apple; the crisps to him as well." — a holding read as an
    allotment beside more for the same person — refused naming both readings."""
    if "has" not in text and "got" not in text:
        return
    for m in _HELD54L.finditer(text):
        who = m["who"]
        if _CONDITION54L.search(text[: m.start("who")]) or not _only_person(who, lexicon):
            continue
        held = _ids(m["x"], lexicon, "object")
        if not held or _ids(m["x"], lexicon, "human") or _ids(m["x"], lexicon, "surface"):
            continue
        got = _handed54l(node, who, lexicon)
        if held <= got and got - held:
            said = text[m.start("who") : m.end("x")].strip()
            beside_request44l(said, who, " ".join(m["x"].split()))


# -- what a person had, read as a hand-over -----------------------------------------------------
#
# 12r's session-54 finds: "That cup there, Bob had it." read `cup>B`, "Tom had every box, all
# three." all three boxes to Tom, "Bob had the cup and the apple alike." `cup>B & apple>B`, where
# "Bob had the cup." and "Bob had the cup and the apple." are refused (session 32: what a person
# had asks for nothing). Said with a word more the sentence slipped past the refusal's forms, so
# this is asked of the reading: a reading that hands a person (named) what the words say the
# person had ('P had the X', 'P had every / all / both …', 'P had it / them'), and nothing said
# to hand it back, is refused. Kept: "Bob had the cup; give it back to him." (back, again,
# return), "Bob had to have the cup." / "had better" / "had asked for" (no thing after 'had'),
# what another person had ("Bob had the cup, give Alice the apple.").
_HAD54L = re.compiled(
    rf"(?:^|[.;,:!?]\s*|\b(?:and|but|so)\s+)(?P<who>{_WHO42R})\s+(?:already\s+|just\s+)?had\s+"
    r"(?:already\s+)?(?P<x>(?:the|every|all|both|each|his|her|their|those|these)\b[^.;:!?]*?|"
    r"(?:it|them)\b)(?=\s*(?:[.;:!?]|$|,|\b(?:and|but|so|then)\s+(?!(?:the|a|an)\b)))",
    _F,
)
_BACK54L = ("back", "again", "return")


def _had_given54l(text: str, node: Node, lexicon: Lexicon) -> None:
    """Session 54 (lead): "That cup there, Bob had it." — a reading that hands a person what the
    words say the person had — refused."""
    if "had" not in text:
        return
    low = text.lower()
    if any(w in low for w in _BACK54L):
        return
    for m in _HAD54L.finditer(text):
        who = m["who"]
        if not _only_person(who, lexicon):
            continue
        got = _handed54l(node, who, lexicon)
        x = " ".join(m["x"].split())
        held = got if x.lower() in ("it", "them") else _ids(x, lexicon, "object")
        if not held or _ids(x, lexicon, "human") or not held <= got:
            continue
        said = text[m.start("who") : m.end("x")].strip()
        raise GroundingError(
            f"{said!r} says what {who} had: it asks for nothing; say 'give {who} …' to have "
            "something handed over"
        )


# -- a want said over by a later one, the later said in full ---------------------------------
#
# 12c's session-53 fuzz: session 53's `_want_over53l` refuses "First Bob wanted the apple, then
# the crisps." (the later want said short); said in full ("…, then he wanted the crisps.", "… and
# then he wanted the crisps.") or after a full stop ("First Bob wanted the apple. Then the
# crisps.") it read `apple>B ; chips>B`: the same story of a want that changed, refused alike.
# Said with 'first' after the name ("Bob first wanted the apple, then he wanted the crisps.") the
# same. Kept: "Kofi asked for the big spanner, then the hammer." (no 'first'), "Bob wanted the apple
# first, then the crisps." (the order of two wants), a second want by another person.
_FIRST_THEN54L = re.compiled(
    r"(?:^|[.;!?]\s*)(?:(?:first(?:ly)?|at first|originally|initially|to begin with|to start with|"
    rf"in the beginning)\s*,?\s+(?P<who>{_WHO42R})|(?P<who_b>{_WHO42R})\s+(?:first|at first|"
    rf"originally|initially))\s+{_PAST53L}\s+[^.;!?]*?"
    r"(?:[,;]\s*(?:and\s+|but\s+)?|\s+(?:and|but)\s+|[.!]\s+)(?:then|later|after that|afterwards)"
    rf"\s*,?\s+(?:(?P<again>he|she|they|[a-z]+(?: [a-z]+)?)\s+{_PAST53L}\s+)?{_THEN_THING53L}",
    _F,
)
_FIRST_WORDS54L = ("first", "originally", "initially", "begin", "start with")
_PRONOUNS54L = frozenset({"he", "she", "they"})


def _want_over54l(text: str, lexicon: Lexicon) -> None:
    """Session 54 (lead): "First Bob wanted the apple, then he wanted the crisps." — a want and a
    later one by the same person, said in full — refused as session 53 refuses the short form."""
    low = text.lower()
    if not any(w in low for w in _FIRST_WORDS54L):
        return
    m = _FIRST_THEN54L.search(text)
    if m is None:
        return
    again = m["again"]
    if (
        again is not None
        and again.lower() not in _PRONOUNS54L
        and _ids(again, lexicon, "human") != _ids(m["who"] or m["who_b"], lexicon, "human")
    ):
        return  # a second want by another person
    want_changed53l(m.group(0).lstrip(".;!? "))


# -- a holding corrected ---------------------------------------------------------------------
#
# 12r's session-54 find: "Bob has the cup. No, the apple." read `apple>B` (and "Bob's got the cup.
# Sorry, the apple.", "Alice has the cup. Sorry, I mean Bob." `cup>B`), where "Bob has the apple."
# alone is refused (session 32: it could say what Bob holds, or allot it). The correction is
# applied to the holding ('the cup' → 'the apple', or 'Alice' → 'Bob') and the sentence it makes is
# asked the refusals it would be asked alone; a correction of a request ("Give Bob the cup. No,
# the apple.") makes a request, which none of them refuses.
_HELD_FIXED54L = re.compiled(
    rf"^\s*(?P<who>{_WHO42R})\s*(?P<verb>'s got|’s got|\s*has got|\s*has)\s+"
    r"(?P<x>(?:the|his|her|their) [a-z]+(?: [a-z]+)?)\s*[.,;!]\s*"
    r"(?:(?:no|sorry|oops|wait|actually|hang on|my mistake|my bad)\s*[,.!]?\s*)+"
    r"(?:i mean\s*,?\s*|rather\s*,?\s*)?(?P<y>[^.,;!?]+?)"
    r"(?:\s+(?:does|has(?: it| them)?|(?:'s|’s|\s*has) got (?:it|them)))?\s*[.!]?\s*$",
    _F,
)


def _held_corrected54l(text: str, lexicon: Lexicon) -> None:
    """Session 54 (lead): "Bob has the cup. No, the apple." — a holding corrected — asked the
    refusals the corrected holding ("Bob has the apple.") is asked alone."""
    if "has" not in text and "got" not in text:
        return
    m = _HELD_FIXED54L.match(text)
    if m is None:
        return
    verb = " ".join(m["verb"].replace("’", "'").split())
    joined = "" if verb.startswith("'") else " "
    if _only_person(m["y"], lexicon):
        fixed = f"{m['y']}{joined}{verb} {m['x']}."
    elif _objects_only(m["y"], lexicon) and not _ids(m["y"], lexicon, "human"):
        fixed = f"{m['who']}{joined}{verb} {m['y']}."
    else:
        return
    # why: offline imports this module; its refusals are asked of the corrected holding
    from hltl.grounding import offline

    offline.asked_before_read(fixed, lexicon)


# refusals asked of the text before it is read (offline._parse, after the session-53 ones)
REFUSE54L: tuple[Callable[[str, Lexicon], None], ...] = (_want_over54l, _held_corrected54l)
# checks of the whole instruction's reading (offline.parse_instruction, after the session-53 ones)
CHECK54L: tuple[Callable[[str, Node, Lexicon], None], ...] = (
    _held_and_more54l,
    _had_given54l,
)
