"""The grounder's rules of session 43, the lead (docs/grounding.md)."""

from __future__ import annotations

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _ids, _objects_only, _only_person
from hltl.grounding._rewrites42r import _WHO42R
from hltl.grounding.lexicon import Lexicon, person_name

# -- session 43 (lead): another person's thing named beside the one who gets it -------------------
#
# 12c's `said` fuzz: "Carol gets Bob's crisps." read `chips>B`: the grammar takes "'s" for 'is'
# and the last person before the object as the one it goes to, so the owner took the subject's
# place ("Could Carol have Bob's cup?", "Carol can borrow Bob's cup", "Let Carol have Bob's apple"
# the same). Since session 7 a person's possessive names whom the thing is for ("Do Carol's bottle
# first and then Bob's chips": `bottle>C ; chips>B`) and "Give Bob Carol's bottle" is refused
# (whose it is is not who gets it); the subject's form is the same clash, so it is refused naming
# both people: the clause's person (the thing being the owner's) or the owner (their order). P and
# Q must be two people of the scene and X a scene object; "Bob wants Bob's crisps" and pronouns are
# left as said. The grammar reads the first form without a refusal, so this is asked before the
# first read (offline._parse, with the canonical rewrites), not among the normaliser's steps.
_MODAL43L = r"(?:can|could|may|might|should|shall|will|would|must|'d|'ll|’d|’ll)"
_OWNED_OTHER43L = re.compiled(
    rf"(?:\b(?P<p>{_WHO42R})(?:\s+{_MODAL43L})?(?:\s+(?:also|just|really|then|now))?\s+"
    r"(?:have|get|gets|take|takes|want|wants|need|needs|like|likes|borrow|borrows|receive|"
    r"receives|'d like|’d like)"
    rf"|\b(?:give|hand|pass|bring|fetch|get|take|lend|send)\s+(?P<p2>{_WHO42R}))"
    rf"\s+(?P<q>{_WHO42R})(?:'s|’s)\s+(?P<x>[a-z]+(?:\s+(?!(?:and|or|nor|but|to|for|with|"
    r"from|please|then|too|as|if)\b)[a-z]+){0,2})",
    _F,
)


def owned_other43l(text: str, lexicon: Lexicon) -> None:
    """Session 43: "P <gets/wants/can have …> Q's X" and "<give …> P Q's X" refused naming P and Q
    (above)."""
    if "'s" not in text and "’s" not in text:
        return
    for m in _OWNED_OTHER43L.finditer(text):
        refuse_owned43l(m["p"] or m["p2"], m["q"], m["x"], lexicon)


def refuse_owned43l(who: str, owner: str, said: str, lexicon: Lexicon) -> None:
    """Refuse "<who> … <owner>'s <said>" naming both people, when both are one person of the
    scene each, two people, and ``said`` opens with a scene object's name (one to three words:
    "cup", "red mug", "tin of screws"); else nothing."""
    if not _only_person(who, lexicon) or not _only_person(owner, lexicon):
        return
    p, q = sorted(_ids(who, lexicon)), sorted(_ids(owner, lexicon))
    if p == q:
        return
    words = said.split()
    thing = next(
        (
            " ".join(words[:n])
            for n in range(len(words), 0, -1)
            if _objects_only(" ".join(words[:n]), lexicon)
        ),
        None,
    )
    if thing is None:
        return
    raise GroundingError(
        f'"{owner}\'s {thing}" beside {who!r}: whose it is does not say who gets it; it '
        f"could go to {person_name(p[0], lexicon)} or to {person_name(q[0], lexicon)}: say "
        "who gets it"
    )
