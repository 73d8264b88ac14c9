"""The grounder's rules of session 42, the lead (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, people_named
from hltl.grounding.lexicon import Lexicon, person_name
from hltl.grounding.tree import Node, tasks

# -- session 42 (lead): a list after a person handed to, its last 'for' another person ---------
#
# 12c's `turns` fuzz: "Give Grandad the bib and the red block for Lily's tower." read
# `bib>B & block_red>A`: the last object of the list went to Lily ('for Lily's tower' is 'for
# Lily' since session 28), the first to Grandad. "Give Grandad the red block for Lily." is
# refused (two people in one clause); with a list before the 'for', 'for P' may say whom the
# last one is for (handed to P) or what the whole list is for (all handed to the person named
# after the verb). Refused naming both, unless a comma parts the list ("Give Grandad the bib, and
# the red block for Lily": a clause of its own).
_NAME42L = r"[a-z]\w*(?: [a-z]\w*)?"
# an object's name: a determiner and one to three words, none a verb or a filler (not a clause:
# "… and the chips are meant for Person B", "… and do the same with the blue plate for Lena")
_WORD42L = (
    r"(?!(?:is|are|was|were|be|been|being|meant|goes|go|going|gets|get|please|do|does|did|and|"
    r"for|to|with)\b)[a-z]+"
)
_THING42L = (
    rf"(?:the|a|an|some|his|her|their|those|these|that|this)\s(?:{_WORD42L}\s){{0,2}}{_WORD42L}"
)
_DATIVE_LIST42L = re.compiled(
    rf"(?:\b(?:give|hand|pass|bring|take|get|fetch|send|lend|offer|grab)\s+(?P<first>{_NAME42L})"
    rf"|\b(?P<owner>{_NAME42L})\s+(?:(?:can|could|may|might|should|will|would)\s+)?"
    r"(?:have|get|gets|take|takes|want|wants|need|needs|like|'d like|’d like|is getting|'s "
    r"getting|’s getting))\s+"
    rf"(?P<things>{_THING42L}\s+and\s+{_THING42L})\s+for\s+(?P<second>{_NAME42L})"
    r"(?P<whose>(?:'s|’s)\s+[a-z]+(?: [a-z]+)?)?\s*(?=[,;:.!?]|$|\bplease\b)",
    _F,
)


def _dative_list42l(text: str, node: Node, lexicon: Lexicon) -> None:
    """Session 42 (lead): 'give P the X and the Y for Q' (Q another person of the scene) read as
    the X to P and the Y to Q — or every one to P, for Q — is refused naming both readings."""
    if " and " not in text or " for " not in text:
        return
    for m in _DATIVE_LIST42L.finditer(text):
        first = people_named(m["first"] or m["owner"], lexicon)
        second = people_named(m["second"], lexicon)
        if len(first) != 1 or len(second) != 1 or first == second:
            continue
        ((p,), (q,)) = (first, second)
        to_p = sorted(t.obj for t in tasks(node) if t.kind == "deliver" and t.target == p)
        to_q = sorted(t.obj for t in tasks(node) if t.kind == "deliver" and t.target == q)
        if not to_p or not to_q:
            continue
        raise GroundingError(
            f"'for {m['second']}{m['whose'] or ''}' after {m['things']!r}: either the "
            f"{' and the '.join(to_q)} for {person_name(q, lexicon)} and the rest to "
            f"{person_name(p, lexicon)}, or all of them to {person_name(p, lexicon)} "
            f"({' and '.join(to_p + to_q)}); say which, e.g. with a comma before 'and'"
        )


# refusals asked of the text before it is read (offline._parse, after the session-41 ones)
REFUSE42L: tuple[Callable[[str, Lexicon], None], ...] = ()
# checks of the whole instruction's reading (offline.parse_instruction, after the session-41 ones)
CHECK42L: tuple[Callable[[str, Node, Lexicon], None], ...] = (_dative_list42l,)
