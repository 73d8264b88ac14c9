"""The grounder's rules of session 55, engineer 12 (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _ids, _only_person
from hltl.grounding.lexicon import Lexicon, person_name
from hltl.grounding.tree import Node, tasks

# -- session 55 (engineer 12): the open wrong reading of session 54 (12c's fuzz), then blind53's
# refusals of politeness and fillers, wants and needs, pronouns and ellipsis and lower case, each
# read as a family.

# -- wrong readings --------------------------------------------------------------------------------

# -- a want of the placed thing said after the placement with no punctuation between ("lemon on the
# plate rack no sorry the worktop chef wants it for the fish", "salt on the rack lena needs it",
# "tongs on the rack mr novak wants them"; 12c's fuzz): read as the placement and a handover
# (lemon@counter & lemon>A), while "Put the lemon on the worktop, chef wants it." is refused naming
# both readings (session 38's offline._placed_wanted38l, which asks for a comma or 'and' before
# the person). The same refusal when the person's want runs on from the placement
_WANTED55 = re.compile(
    r"(?:\s|(?=['\u2019]))(?P<v>(?:wants|needs|wanted|needed|would like|['\u2019]d like|could use|"
    r"could do with|(?:has |['\u2019]s )?(?:asked|been asking|been waiting|begged) for|"
    r"(?:is|has been|['\u2019]s|['\u2019]s been) after|(?:is|['\u2019]s) (?:waiting|asking) for)"
    r" (?:it|them))\b",
    _F,
)
# the words the pattern needs (its gate): each of its verbs ends in one of them
_WANTED55_WORDS = tuple(
    f"{v} {p}"
    for v in ("wants", "needs", "wanted", "needed", "like", "use", "with", "for", "after")
    for p in ("it", "them")
)
# a verb that asks for a handover in words (session 38's _HANDOVER_SAID38L): then it is said
_HANDOVER55 = re.compile(
    r"\b(?:give|gives|hand|hands|pass|passes|bring|brings|take|takes|deliver|fetch|send|carry|"
    r"let(?!'s|\u2019s|\s+(?:me|us)\b))\b",
    _F,
)
_THEM55 = re.compile(r"\b(?:it(?!'s|\u2019s|\s+is\b|\s+was\b)|them)\b", _F)
_SENTENCE55 = re.compile(r"(?<=[.!?;])\s+")


def _who55(before: str, lexicon: Lexicon) -> set[str] | None:
    """The person the last words of ``before`` name ('… the worktop chef' -> {'A'}); None for
    he / she / they (any person); an empty set when they name no one."""
    words = before.split()
    if words and words[-1].lower() in ("he", "she", "they"):
        return None
    for n in (3, 2, 1):
        if len(words) >= n and _only_person(" ".join(words[-n:]), lexicon):
            return _ids(" ".join(words[-n:]), lexicon, "human")
    return set()


def _placed_wanted55(text: str, node: Node, lexicon: Lexicon) -> None:
    """Session 55: a want of the placed thing run on after the placement refused as session 38's
    check refuses it after a comma (above)."""
    low = text.lower()
    if not any(w in low for w in _WANTED55_WORDS):
        return
    placed = {t.obj: t.target for t in tasks(node) if t.kind == "place"}
    both = [t for t in tasks(node) if t.kind == "deliver" and t.obj in placed]
    if not both or any(
        _HANDOVER55.search(s)
        and (_THEM55.search(s) or {t.obj for t in both} & _ids(s, lexicon, "object"))
        for s in _SENTENCE55.split(text)
    ):
        return  # a verb of handing said of the placed thing: the handover is asked for
    for m in _WANTED55.finditer(text):
        who = _who55(text[: m.start()], lexicon)
        said = [t for t in both if who is None or t.target in who]
        if not said:
            continue
        t = said[0]
        put, name = f"{t.obj}@{placed[t.obj]}", person_name(t.target, lexicon)
        raise GroundingError(
            f"{m['v']!r} after putting the {t.obj} on the {placed[t.obj]}: is that why it goes "
            f"there ({put}), or is {name} to be handed it too ({put} & {t.obj}>{t.target})? say "
            "which"
        )


# the normaliser's first rewrites (wired into normalise._STEPS19, before the session-54 ones)
_STEPS55_FIRST: tuple[Callable[[str, Lexicon], str], ...] = ()
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-54 ones)
_STEPS55: tuple[Callable[[str, Lexicon], str], ...] = ()
# refusals asked of the text before it is read (offline._parse, after the session-54 ones)
REFUSE55: tuple[Callable[[str, Lexicon], None], ...] = ()
# checks of the whole instruction's reading (offline.parse_instruction, after the session-54 ones)
CHECK55: tuple[Callable[[str, Node, Lexicon], None], ...] = (_placed_wanted55,)
