"""The grounder's rules of session 53, the lead (docs/grounding.md): 12c's fuzz reports."""

from __future__ import annotations

from collections.abc import Callable
from typing import NoReturn

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _objects_only, _only_person
from hltl.grounding._rewrites42r import _WHO42R
from hltl.grounding._rewrites44l import _HELD44L, _OWN44L, beside_request44l
from hltl.grounding._rewrites51 import earlier_and_new51
from hltl.grounding.lexicon import Lexicon
from hltl.grounding.tree import Node

# -- what a person holds, said beside a request ----------------------------------------------
#
# 12c's session-52 fuzz: "Bob's got the apple; give him the crisps." read `apple>B & chips>B`, as
# did "Bob has the apple, give him the crisps as well." and "Marco has the lemon, give Lena the
# salt." (`lemon>A & salt>B`). Session 32 reads "P has the X" beside another's share as a share
# ("Person A has the chips and the bottle is Person B's.", "she has the bottle, he has the
# crisps", "Give Bob the cup, Alice has the apple."), and session 44 refuses it beside a request
# only with 'so' after it or with the person's own thing ("Bob's got the cup so give Alice the
# apple."). Beside a request said as one (a verb of handing opening its clause: "give him …",
# "could you pass …") to the same person (named again, or him / her / them), the holding is not a
# share beside another's part: it could say what the person holds (nothing to do) or allot the
# thing — refused naming both, as session 44 does. Kept: shares ("Alice has the apple and Bob has
# the crisps.", "Lena has the lemon, give Marco the tongs.": sessions 32, 36, 44), a holding as a
# condition ("Once Alice has the cup, give Bob …"). Said of one of several ("Bob's got one of the
# mugs; give him the other one.", "Bob has a mug, give him the apple.") the same; and alone
# ("Bob's got one of the mugs.") refused as session 32 refuses "Bob has the apple." alone; in the
# past ("Bob had one of the mugs.", read `mug_red>B | mug_blue>B`) refused wherever it is said, as
# session 32 refuses "Bob had the apple.".
_REQUEST53L = re.compiled(
    r"(?:^|[.;,:!?]\s*|\b(?:and|then|so|but|now)\s+)(?:(?:please|just|now|kindly|also|then|"
    r"oh|and)\s*,?\s+|(?:could|would|can|will)\s+you\s+(?:please\s+|just\s+|also\s+|kindly\s+)?)*"
    r"(?:give|hand|pass|bring|take|deliver|put|place|fetch|send|carry|move|set|drop|pop|stick|"
    r"toss|chuck|lay|get)\b",
    _F,
)
_CLAUSE_END53L = re.compiled(r"[.;!?]")


_HELD_ONE53L = re.compiled(
    rf"(?:^|[.;,:!?]\s*|\band\s+)(?P<who>{_WHO42R})\s*"
    r"(?P<verb>'s got|’s got|\s*has got|\s*had got|\s*has|\s*had)\s+"
    r"(?P<x>(?:(?:one|either|any) of (?:the|those|these)\s+|an?\s+)[a-z]+(?:\s+[a-z]+)?)\s*"
    r"(?P<after>[.;,:!?]|$)",
    _F,
)


def _to_same53l(rest: str, who: str) -> bool:
    """Whether ``rest`` holds a request said as one (a verb of handing opening its clause) whose
    clause names ``who`` again or says him / her / them."""
    request = _REQUEST53L.search(rest)
    if request is None:
        return False
    clause = _CLAUSE_END53L.split(rest[request.end() :], maxsplit=1)[0]
    return re.search(rf"\b(?:{re.escape(who)}|him|her|them)\b", clause, _F) is not None


def _held_request53l(text: str, lexicon: Lexicon) -> None:
    """Session 53 (lead): "Bob's got the apple; give him the crisps." — a holding beside a request
    to the same person — and "Bob's got one of the mugs." alone refused naming both readings."""
    if "has" not in text and "got" not in text and "had" not in text:
        return
    for m in _HELD44L.finditer(text):
        verb = " ".join(m["verb"].lower().replace("’", "'").split())
        if m["adv1"] or m["adv2"] or m["own"] or m["tail"] or verb.endswith(("had", "holding")):
            continue  # session 44's `held_beside44l` says what it is
        if m["whose"].lower() in _OWN44L or m["after"].lower().endswith("so"):
            continue  # the same
        who = m["who"]
        if not _to_same53l(text[: m.start("who")] + " , " + text[m.end("x") :], who):
            continue  # another person's part beside a share: session 32's reading
        thing = " ".join(m["x"].split())
        if not _only_person(who, lexicon) or not _objects_only(thing, lexicon):
            continue
        beside_request44l(text[m.start("who") : m.end("x")].strip(), who, f"the {thing}")
    for m in _HELD_ONE53L.finditer(text):
        who = m["who"]
        rest = text[: m.start("who")] + " , " + text[m.end("x") :]
        alone = re.search(r"[a-z]", rest, _F) is None
        past = m["verb"].strip().startswith("had")
        if not past and not alone and not _to_same53l(rest, who):
            continue  # a share beside another's ("Bob has one of the mugs, Alice the other")
        thing = " ".join(m["x"].split())
        if not _only_person(who, lexicon) or not _objects_only(thing, lexicon):
            continue
        said = text[m.start("who") : m.end("x")].strip()
        if past:
            raise GroundingError(
                f"{said!r} says what {who} had: it asks for nothing; say 'give {who} {thing}' to "
                "have it handed over"
            )
        if alone:
            raise GroundingError(
                f"{said!r} could say what {who} already holds (nothing to do) or that {who} is to "
                f"get {thing}: say 'give {who} {thing}' to have it handed over"
            )
        beside_request44l(said, who, thing)


# -- a want said over by a later one ---------------------------------------------------------
#
# 12c's session-52 fuzz: "First Bob wanted the apple, then the crisps." read `apple>B ; chips>B`
# and "The apple was for Bob, now the crisps are." `apple>B & chips>B`. Session 51's `_want_now51`
# refuses "Bob wanted the apple, now he wants the crisps." (the new want may replace the old or add
# to it); said with the second want left out ("…, now the crisps (are).", "…, (and) then the
# crisps.") after a clause opening with a word that tells a story of wants ('first', 'originally',
# 'at first'), or with 'now' after a past want or part, it is the same: refused. Kept: "Kofi asked
# for the big spanner, then the hammer." (two requests in order, blind9), "Bob wanted the apple
# first, then the crisps." (the order of two wants), "Bob wanted the apple." (a want, as read).
_PAST53L = (
    r"(?:wanted|asked for|was after|were after|had asked for|asked after|was wanting|requested|"
    r"fancied|was hoping for|needed|(?:was|were)(?: meant| going)? for)"
)
_THEN_THING53L = (
    r"(?:it(?:'s|’s| is| was)\s+)?(?:the|his|her|their|that|those|this|these|a|an|some)\s+[a-z]+"
)
_WANT_NOW53L = re.compiled(
    rf"\b{_PAST53L}\b[^.;!?]*?[,;.]\s*(?:but\s+|and\s+|though\s+|only\s+)?(?:now|these days|"
    rf"today|this time)\s*,?\s+(?:{_THEN_THING53L}|(?:please\s+|just\s+)?(?:give|hand|pass|"
    r"bring|take|get|fetch)\s+(?:him|her|them)\b)",
    _F,
)
_FIRST_THEN53L = re.compiled(
    r"(?:^|[.;!?]\s*)(?:first(?:ly)?|at first|originally|initially|to begin with|to start with|"
    rf"in the beginning)\s*,?\s+[^.;!?]*?\b{_PAST53L}\b[^.;!?]*?[,;]\s*(?:and\s+|but\s+)?(?:then|"
    rf"later|after that|afterwards)\s*,?\s+{_THEN_THING53L}",
    _F,
)
_NOW_WORDS53L = ("now", "today", "this time", "these days")
_FIRST_WORDS53L = ("first", "originally", "initially", "begin", "start with")


def _want_over53l(text: str, lexicon: Lexicon) -> None:
    """Session 53 (lead): "The apple was for Bob, now the crisps are.", "First Bob wanted the
    apple, then the crisps." — a want and a later one, the later said short — refused."""
    low = text.lower()
    if any(w in low for w in _NOW_WORDS53L):
        m = _WANT_NOW53L.search(text)
        if m is not None:
            earlier_and_new51(m.group(0))
    if any(w in low for w in _FIRST_WORDS53L):
        m = _FIRST_THEN53L.search(text)
        if m is not None:
            want_changed53l(m.group(0).lstrip(".;!? "))


def want_changed53l(said: str) -> NoReturn:
    """Refuse "First P wanted X, then Y" (also session 54's `_want_over54l`)."""
    raise GroundingError(
        f"{said!r} could tell how a want changed (only the later one stands) or ask for both in "
        "that order: say 'give … instead' or 'give …, then …'"
    )


# -- an apology opener before what would be refused ----------------------------------------
#
# 12c's fuzz of blind51 (its only wrong reading over 15,195 variants, #64's wrapper): "Sorry to
# bother you, but person B had the chips. He said they were stale." read `chips>B`, as "Sorry, but
# Bob had the apple.", "Apologies, but …", "Pardon me, but …", "I'm afraid Bob had the apple."
# Said without the opener, each is refused (session 32's `_state_only32s`: a past holding asks
# for nothing); the opener hid the sentence from the refusals (they look at the sentence as said),
# and the grammar then read what follows it. An apology or regret opening the instruction, with
# 'but' after it (or "I'm afraid …"), says nothing about what is asked: the refusals asked before
# the read are asked again of what follows it. Kept: what follows read as it reads alone ("Sorry
# to bother you, but could you give Carol the apple?": blind2).
_OPENER53L = re.compiled(
    r"^\s*(?:(?:oh|ah|um|erm|er|look|so)\s*,?\s+)*(?:(?:(?:i'm|i am|so|really|terribly)\s+)?"
    r"sorry|apologies|my apologies|pardon me|pardon the intrusion|excuse me|forgive me)\b"
    r"[^.;:!?]*?(?:,\s*|\s+)but\s*,?\s+|^\s*(?:(?:oh|ah|um|erm|er|look|so)\s*,?\s+)*(?:i'm|i am)"
    r"\s+afraid\s*,?\s+(?:that\s+)?",
    _F,
)
_OPENER_WORDS53L = ("sorry", "apolog", "pardon", "excuse", "forgive", "afraid")


def _opener_but53l(text: str, lexicon: Lexicon) -> None:
    """Session 53 (lead): "Sorry to bother you, but Bob had the crisps." — what follows an apology
    opener is asked the refusals it would be asked alone."""
    low = text.lower()
    if not any(w in low for w in _OPENER_WORDS53L):
        return
    m = _OPENER53L.match(text)
    if m is None or not re.search(r"[a-z]", text[m.end() :], _F):
        return
    # why: offline imports this module; its refusals are asked again of what follows the opener
    from hltl.grounding import offline

    offline.asked_before_read(text[m.end() :], lexicon)


# refusals asked of the text before it is read (offline._parse, after the session-52 ones)
REFUSE53L: tuple[Callable[[str, Lexicon], None], ...] = (
    _held_request53l,
    _want_over53l,
    _opener_but53l,
)
# checks of the whole instruction's reading (offline.parse_instruction, after the session-52 ones)
CHECK53L: tuple[Callable[[str, Node, Lexicon], None], ...] = ()
