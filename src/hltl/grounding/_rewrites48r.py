"""The grounder's rules of session 48, engineer 12r (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _ids, _reading
from hltl.grounding._rewrites46r import _person46r
from hltl.grounding.lexicon import Lexicon
from hltl.grounding.tree import Node, Task

# -- someone else is to do it ---------------------------------------------------------------------

# "Bob will be given the apple by Alice.", "Bob's to be handed the cup by Carol."
_GIVEN_BY48R = re.compiled(
    r"\b(?:be|being|get|gets|getting)\s+(?:given|handed|passed|brought|taken|sent|fetched|"
    r"delivered|lent|tossed|thrown)\b[^.;!?]*?\s(?P<by>by\s+(?P<who>[a-z][\w ]*?))"
    r"(?=\s*(?:[,.;!?]|$))",
    _F,
)


def given_by48r(text: str, lexicon: Lexicon) -> None:
    """Session 48 (12r; the lead's decision): "Bob will be given the apple by Alice." says Alice
    is to give it, as "Alice will give Bob the apple." does (refused: the robots deliver); it had
    read as the robots' delivery. Refused naming the giver ('by' a person of the scene only:
    "… by the shelf" is where)."""
    low = text.lower()
    if " by " not in low or ("be" not in low and "get" not in low):
        return
    for m in _GIVEN_BY48R.finditer(text):
        who = _person46r(m["who"], lexicon)
        if who is None:
            continue
        raise GroundingError(
            f"{m['by']!r} says {m['who']} ({who}) is to hand it over, not the robots: say what "
            "the robots are to do"
        )


# -- a correction that could say where the thing is -----------------------------------------------

# "Marco wants the salt, no, it's on the rack.", "Put the lemon on the rack, no, the lemon's on the
# counter.", "Bob wants the apple, no, it's Carol's."
_WHERE_IT_IS48R = re.compiled(
    r"^(?P<req>[^.;!?]+?)\s*[,.;!]\s*(?:oh\s+)?(?:no|sorry|actually|wait|no wait|no sorry)\s*,?\s*"
    r"(?P<it>it|they|the [a-z]+(?: [a-z]+)?)(?:'s| is|'re| are) (?:(?:on|in|at|inside|on top of|"
    r"in the middle of) (?P<s>the [a-z]+(?: [a-z]+)?)|(?P<q>[a-z]+(?: [a-z]+)?)'s?)\s*[.!]?\s*$",
    _F,
)


def where_it_is48r(text: str, lexicon: Lexicon) -> None:
    """Session 48 (12r; the lead's decisions): "Marco wants the salt, no, it's on the rack." could
    tell where the salt is (the want stands: salt>A) or correct the request to a placing
    (salt@rack); "Put the lemon on the rack, no, it's on the counter." where the lemon is or a
    new place; "Bob wants the apple, no, it's Carol's." Carol's want (apple>C) or Carol's apple
    for Bob (someone else's thing: refused since session 7). Each refused naming both (they had
    read as the correction: salt@rack, lemon@counter, apple>C). 'it' may be the thing's name
    ("no, the lemon's on the counter"); the request is one task of one thing."""
    low = text.lower()
    if "it" not in low and "they" not in low and "'s" not in low:
        return
    m = _WHERE_IT_IS48R.match(text.strip())
    if m is None:
        return
    asked = _reading(m["req"], lexicon)
    if not isinstance(asked, Task):
        return
    it = m["it"].lower()
    if it not in ("it", "they") and _ids(m["it"], lexicon) != {asked.obj}:
        return
    said = m[0][len(m["req"]) :].strip(" ,.;!")
    was = f"{asked.obj}{'>' if asked.kind == 'deliver' else '@'}{asked.target}"
    if m["s"] is not None:
        place = _ids(m["s"], lexicon)
        if len(place) != 1 or _ids(m["s"], lexicon, "surface") != place:
            return
        if asked.kind == "place" and place == {asked.target}:
            return
        raise GroundingError(
            f"{said!r} after the request could say where it is ({was} as asked) or move it "
            f"there instead ({asked.obj}@{next(iter(place))}): say which"
        )
    who = _person46r(m["q"], lexicon)
    if who is None or asked.kind != "deliver" or who == asked.target:
        return
    raise GroundingError(
        f"{said!r} after the request could say {m['q']} wants it ({asked.obj}>{who}) or that "
        f"the {asked.obj} is {m['q']}'s ({asked.obj}>{asked.target} as asked, someone else's "
        "thing): say which"
    )


# the normaliser's first rewrites (wired into normalise._STEPS19, before the session-47 ones)
_STEPS48R_FIRST: tuple[Callable[[str, Lexicon], str], ...] = ()
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-47 ones)
_STEPS48R: tuple[Callable[[str, Lexicon], str], ...] = ()
# refusals asked of the text before it is read (offline._parse, after the session-47 ones)
REFUSE48R: tuple[Callable[[str, Lexicon], None], ...] = (given_by48r, where_it_is48r)
# checks of the whole instruction's reading (offline.parse_instruction, after the session-47 ones)
CHECK48R: tuple[Callable[[str, Node, Lexicon], None], ...] = ()
