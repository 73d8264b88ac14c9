"""The grounder's rules of session 53, engineer 12s (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _ids
from hltl.grounding._rewrites52s import _other_sex52s
from hltl.grounding.lexicon import PRONOUN_SEX, Lexicon, person_name
from hltl.grounding.tree import Node, tasks

# -- session 53 (12s): a he / she after a person left out by 'not' ------------------------------
#
# "Give Alice the apple, not Carol, she wants the crisps." read `apple>A & chips>A` and "Give
# Alice the apple, not Bob, he wanted the crisps." the same (12c's fuzz, session 52): session 19's
# `_negation19` takes ', not Carol,' off when Carol is said nowhere else, and the pronoun after it
# then has only Alice to stand for. A pronoun after 'not P' / 'instead of P' / 'rather than P' that
# P may be (the scene says no other sex) may be P: when its clause names a thing of the scene, a
# reading that hands that thing to someone else, or to P while another person named may be the
# pronoun too, is refused ('she' = Carol or Alice: the robot may not pick).
_NOT_PERSON53S = re.compile(
    r"\b(?:not|instead of|rather than)(?: (?:to|for|with))? (?P<who>[^,.;:!?]+)", _F
)
_PRONOUN53S = re.compile(r"\b(?P<pro>he|she|him|her|his|hers|himself|herself)\b", _F)


def _clause53s(text: str, at: int) -> str:
    """The clause of ``text`` around index ``at`` (between stops and commas)."""
    start = max(text.rfind(c, 0, at) for c in ",.;:!?") + 1
    ends = [i for c in ",.;:!?" if (i := text.find(c, at)) != -1]
    return text[start : min(ends) if ends else len(text)]


def _not_them53s(text: str, node: Node, lexicon: Lexicon) -> None:
    """Session 53 (12s): a thing a pronoun's clause names, after 'not P', given where the pronoun
    may be P (above): refused."""
    low = text.lower()
    if "not " not in low and "instead of" not in low and "rather than" not in low:
        return
    if "he" not in low:  # every pronoun above holds 'he' or 'her'
        return
    given = [t for t in tasks(node) if t.kind == "deliver"]
    if not given:
        return
    named = _ids(text, lexicon, "human")
    for m in _NOT_PERSON53S.finditer(text):
        left = _ids(m["who"], lexicon, "human")
        if len(left) != 1:
            continue
        (q,) = left
        for p in _PRONOUN53S.finditer(text, m.start("who")):
            pro = p["pro"].lower().removesuffix("self")
            sex = PRONOUN_SEX[pro]
            if _other_sex52s(q, sex, lexicon):
                continue
            things = _ids(_clause53s(text, p.start()), lexicon, "object")
            if not things:
                continue
            may = sorted(h for h in named if not _other_sex52s(h, sex, lexicon))
            for task in given:
                if task.obj not in things or (task.target == q and may == [q]):
                    continue
                people = " or ".join(person_name(h, lexicon) for h in may)
                raise GroundingError(
                    f"{p['pro']!r} after {m.group(0).strip()!r} may be "
                    f"{people}: the reading gives {task.obj} to "
                    f"{person_name(task.target, lexicon)}; name the person"
                )


# -- session 53 (12s): a placing or handover said the other way round -----------------------------
#
# "Bob gets the crisps first. Once he has them, over to Alice goes the cup." (blind51 #60): the
# place or person before the verb and the thing after it ('over to P goes the X', 'onto the S go
# the X and the Y'). Said the usual way round ('the X goes over to P') when what comes before
# 'goes' names one person or surface and nothing else and what comes after names things only; not
# in a sentence asking ('?'), nor said as done ('went' is no 'goes').
_GOES_TO53S = re.compile(
    r"(?P<head>^|[.;:!]\s+|,\s+|\b(?:then|and then|and|next|after that|now)\s+)"
    r"(?P<dir>(?:(?:over|across|up|down|back|off|along|round|straight) )?"
    r"(?:to|onto|on to|on|into|in) )(?P<where>[^,.;:!?]+?) (?P<verb>goes|go) "
    r"(?P<what>(?:the|that|this|those|these|both) [^,.;:!?]+?)(?=\s*(?:[,.;:!]|$))",
    _F,
)


def _goes_to53s(text: str, lexicon: Lexicon) -> str:
    """Session 53 (12s): 'over to P goes the X' said 'the X goes over to P' (above)."""
    low = text.lower()
    if (
        "go th" not in low
        and "goes th" not in low
        and "go both" not in low
        and "goes both" not in low
    ):
        return text

    def turn(m: re.Match[str]) -> str:
        where, what = m["where"], m["what"]
        if (
            len(_ids(where, lexicon, "human") | _ids(where, lexicon, "surface")) != 1
            or _ids(where, lexicon, "object")
            or not _ids(what, lexicon, "object")
            or _ids(what, lexicon, "human") | _ids(what, lexicon, "surface")
        ):
            return m.group(0)
        ask = text.find("?", m.end())
        stop = min((i for c in ".!;" if (i := text.find(c, m.end())) != -1), default=len(text))
        if ask != -1 and ask < stop:
            return m.group(0)
        head = m["head"]
        said = what if head.strip() not in ("", ".", ";", ":", "!") else what[0].upper() + what[1:]
        return f"{head}{said} {m['verb']} {m['dir']}{where}"

    return _GOES_TO53S.sub(turn, text)


# the normaliser's first rewrites (wired into normalise._STEPS19, before the session-52 ones)
_STEPS53S_FIRST: tuple[Callable[[str, Lexicon], str], ...] = (_goes_to53s,)
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-52 ones)
_STEPS53S: tuple[Callable[[str, Lexicon], str], ...] = ()
# refusals asked of the text before it is read (offline._parse, after the session-52 ones)
REFUSE53S: tuple[Callable[[str, Lexicon], None], ...] = ()
# checks of the whole instruction's reading (offline.parse_instruction, after the session-52 ones)
CHECK53S: tuple[Callable[[str, Node, Lexicon], None], ...] = (_not_them53s,)
