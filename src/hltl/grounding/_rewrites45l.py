"""The grounder's rules of session 45, the lead (docs/grounding.md)."""

from __future__ import annotations

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _fits, _names
from hltl.grounding.lexicon import Lexicon

# -- session 45 (lead): "…, no, not her, the other one" -------------------------------------------
#
# blind43's one wrong reading (12c's measurement, main ec96b6cf): "Pass Emma the green cup, no, not
# her, the other one." read `cup_white>C`: session 31's cue words take "not her" for the cue 'no',
# and 'the other one' after "the green cup" was then read as the lab's other cup. 'Not him / her'
# says the person was the slip, so 'the other one' is another person: in a scene of two people the
# other one (read as "…, no, <name>"), in a scene of more refused naming each it could be.
_OTHER_PERSON45L = re.compiled(
    r",\s*(?:(?:no|sorry|oops|wait)\b,?\s*)*not (?P<pron>him|her)\b,?\s*(?:(?:I mean|I meant|"
    r"it's|it is|rather)\s+)?the other (?:one|person|guy|lady|man|woman|bloke|fella|chap)\b",
    _F,
)


def other_person45l(text: str, lexicon: Lexicon) -> str:
    """Session 45: "Give P the X, no, not him, the other one" (above): the other person of a
    two-person scene, said by name; refused naming the people it could be in a larger scene.
    Unchanged when no one is named before it or the pronoun cannot be the last person named."""
    if "other" not in text or "not" not in text:
        return text
    m = _OTHER_PERSON45L.search(text)
    if m is None:
        return text
    people = [
        r.id for it in _names(text[: m.start()], lexicon) for r in it.refs if r.kind == "human"
    ]
    if not people or not _fits(people[-1], m["pron"], lexicon):
        return text
    others = [h for h in lexicon.scene.humans if h.id != people[-1]]
    if len(others) == 1:
        return f"{text[: m.start()]}, no, {others[0].name}{text[m.end() :]}"
    said = m[0].lstrip(", ").strip()
    could = " or ".join(h.name + (f" ({h.aliases[0]})" if h.aliases else "") for h in others)
    raise GroundingError(
        f"{said!r} says the person was wrong, not who is meant: it could mean {could}; "
        "name the person"
    )
