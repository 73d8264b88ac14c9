"""The grounder's rules of session 53, engineer 12r (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F
from hltl.grounding.lexicon import Lexicon
from hltl.grounding.tree import Node, has_choice, tasks

# -- 12c's fuzz: a share-out header the list does not meet --------------------------------------

_COUNTS53R = {"two": 2, "three": 3, "four": 4, "five": 5, "2": 2, "3": 3, "4": 4, "5": 5}

# "Give each of them something: the crisps for Alice, the apple for Alice.": a header saying every
# person of a group gets one thing, then the list
_EACH_HEAD53R = re.compiled(
    r"^\s*(?:please,?\s+)?(?:give|hand|pass|bring|get)\s+(?P<who>each of them|them each|each of "
    r"you|them all|all of them|everyone|everybody|each person|both of them|them both|the two of "
    r"them|all (?P<n>two|three|four|five|2|3|4|5) of them|the (?P<m>two|three|four|five) of them)"
    r"\s+(?:something|some thing|one thing|a thing|an? item|one item|an object|one|one apiece|"
    r"a (?:drink|snack|treat|bite))\b[^:;.!?]*:",
    _F,
)


def _each_head53r(text: str, node: Node, lexicon: Lexicon) -> None:
    """Session 53 (12r): a reading of "Give each of them (all three of them, everyone) something:
    <list>" must give one thing to each of two or more people, all three (every person of the
    scene for 'everyone', 'all of them'), no one twice and no choice: an early rewrite (session
    10's table) took the header off unchecked, so "…: the crisps for Alice, the apple for Alice."
    read chips>A & apple>A (12c's fuzz)."""
    low = text.lower()
    if ":" not in low or ("them" not in low and "every" not in low and "each" not in low):
        return
    m = _EACH_HEAD53R.match(text)
    if m is None:
        return
    got = list(tasks(node))
    who = [t.target for t in got]
    want = None
    n = m["n"] or m["m"]
    if n is not None:
        want = _COUNTS53R[n.lower()]
    elif m["who"].lower() in ("both of them", "them both", "the two of them"):
        want = 2
    fits = (
        not has_choice(node)
        and all(t.kind == "deliver" for t in got)
        and len(set(who)) == len(who) >= 2
        and (want is None or len(who) == want)
    )
    if fits and m["who"].lower() in ("everyone", "everybody", "all of them", "them all"):
        fits = sorted(who) == sorted(h.id for h in lexicon.scene.humans)
    if not fits:
        raise GroundingError(
            f"{m.group(0).strip(' :')!r} gives one thing to each of them, but the list after it "
            "does not (someone twice, one person only, or someone left out): name who gets each "
            "thing"
        )


# the normaliser's first rewrites (wired into normalise._STEPS19, before the session-52 ones)
_STEPS53R_FIRST: tuple[Callable[[str, Lexicon], str], ...] = ()
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-52 ones)
_STEPS53R: tuple[Callable[[str, Lexicon], str], ...] = ()
# refusals asked of the text before it is read (offline._parse, after the session-52 ones)
REFUSE53R: tuple[Callable[[str, Lexicon], None], ...] = ()
# checks of the whole instruction's reading (offline.parse_instruction, after the session-52 ones)
CHECK53R: tuple[Callable[[str, Node, Lexicon], None], ...] = (_each_head53r,)
