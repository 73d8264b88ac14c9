"""The grounder's rules of session 43, the lead (docs/grounding.md)."""

from __future__ import annotations

from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _ids, _objects_only, _only_person
from hltl.grounding.lexicon import Lexicon

# -- session 43 (lead): another person's thing handed to the person the clause names -----------
#
# 12c's `said` fuzz: "Carol gets Bob's crisps." read `chips>B`: the grammar takes "'s" for 'is'
# and the last person before the object as the one it goes to, so the owner took the subject's
# place ("Carol can have Bob's crisps", "Could Carol have Bob's cup?", "Carol can borrow Bob's
# cup" the same). The clause says who gets it (the subject of a want or possession verb, or the
# person after a handing verb); the owner only says which thing: "Q's X" is said "the X", which
# the scene must still single out (two bags of crisps stay refused). The owner and the one who
# gets it must be two people of the scene; "Bob wants Bob's crisps" and pronouns are left as said.
# The grammar reads the first form without a refusal, so this runs before the first read
# (offline._parse, with the other canonical rewrites), not among the normaliser's steps.
_WHO43L = r"(?:person [a-z]|(?:mr|mrs|ms|miss|dr) [a-z]+|[a-z]+)"
_MODAL43L = r"(?:can|could|may|might|should|shall|will|would|must|'d|'ll|’d|’ll)"
_OWNED_OTHER43L = re.compiled(
    rf"(?:\b(?P<p>{_WHO43L})(?:\s+{_MODAL43L})?(?:\s+(?:also|just|really|then|now))?\s+"
    r"(?:have|get|gets|take|takes|want|wants|need|needs|like|likes|borrow|borrows|receive|"
    r"receives|'d like|’d like)"
    rf"|\b(?:give|hand|pass|bring|fetch|get|take|lend|send)\s+(?P<p2>{_WHO43L}))"
    rf"\s+(?P<q>{_WHO43L})(?:'s|’s)\s+(?P<x>[a-z]+(?:\s+[a-z]+)?)",
    _F,
)


def owned_other43l(text: str, lexicon: Lexicon) -> str:
    """Session 43: "P <gets/wants/can have …> Q's X" and "<give …> P Q's X" → "… the X" (above)."""
    if "'s" not in text and "’s" not in text:
        return text
    for m in list(_OWNED_OTHER43L.finditer(text))[::-1]:
        who = m["p"] or m["p2"]
        owner = m["q"]
        if not _only_person(who, lexicon) or not _only_person(owner, lexicon):
            continue
        if _ids(who, lexicon) == _ids(owner, lexicon):
            continue
        first = m["x"].split()[0]
        if not (_objects_only(m["x"], lexicon) or _objects_only(first, lexicon)):
            continue
        text = text[: m.start("q")] + "the " + text[m.start("x") :]
    return text
