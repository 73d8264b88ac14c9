"""The grounder's rules of session 44, the lead (docs/grounding.md)."""

from __future__ import annotations

from typing import NoReturn

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _objects_only, _only_person
from hltl.grounding._rewrites42r import _WHO42R
from hltl.grounding.lexicon import Lexicon

# -- session 44 (lead): what a person holds, said beside a request ---------------------------------
#
# 12c's probes on main 004b6eb8: "Mrs Khan's got her jug; give Mr Lee the magazine." read
# `jug>C & magazine>B`, and "Bob's got the cup so give Alice the apple." `cup>B & apple>A`: the
# grammar read the person's present 'has' as allotting (session 32 reads "…, Lena has the tongs"
# beside another person's part so, as the corpus means it: "Person A has the chips and the bottle
# is Person B's."). With her own thing ("her jug": she has it already) or with 'so' after it (the
# holding is the reason for the request) it says what the person holds: nothing to do, or, if the
# speaker does mean it as a share, a handover; refused naming both readings, as session 32 refuses
# the sentence alone. Asked before the first read (offline._parse), as the grammar reads it.
_HELD44L = re.compiled(
    rf"(?:^|[.;,:!?]\s*|\band\s+)(?P<who>{_WHO42R})\s*(?P<adv1>(?:already|still)\s+)?"
    r"(?P<verb>'s got|’s got|\s*has got|\s*has had|'s had|’s had|\s*has|(?:'s|’s|\s+is)\s+"
    r"(?:already\s+|still\s+)?holding)\s+(?P<adv2>(?:already|still)\s+)?"
    r"(?P<whose>his|her|their|the)\s+(?P<own>own\s+)?(?P<x>[a-z]+(?:\s+(?!(?:and|or|so|but|now|"
    r"already|still|from|there|here|with|on|in)\b)[a-z]+){0,2})\s*"
    r"(?P<tail>(?:already|still|from earlier|from before|as it is)\s*)?"
    r"(?P<after>,?\s*\bso\b|[.;,:!?]|$)",
    _F,
)
_OWN44L = frozenset({"his", "her", "their"})


def held_beside44l(text: str, lexicon: Lexicon) -> None:
    """Session 44: "P's got her X; give Q …", "P has the X so give Q …" refused naming both
    readings (above). A 'the' thing with no 'so' after it keeps session 32's reading (a share)."""
    if "has" not in text and "got" not in text and "holding" not in text:
        return
    for m in _HELD44L.finditer(text):
        if not re.search(r"[a-z]", text[: m.start("who")] + text[m.end() :], _F):
            continue  # alone it is session 32's sentence (offline._state_only32s says what it is)
        verb = " ".join(m["verb"].lower().replace("’", "'").split())
        state = bool(
            m["adv1"] or m["adv2"] or m["own"] or m["tail"] or verb.endswith(("had", "holding"))
        )
        if (
            not state
            and m["whose"].lower() not in _OWN44L
            and not m["after"].lower().endswith("so")
        ):
            continue
        who = m["who"]
        if not _only_person(who, lexicon):
            continue
        thing = " ".join(m["x"].split())
        if not _objects_only(thing, lexicon):
            continue  # exactly a scene object, said in up to three words
        said = text[m.start("who") : m.end("tail") if m["tail"] else m.end("x")].strip()
        if state:
            # session 44 (12c's `holds` fuzz family): "Bob has his own crisps already. Put the cup
            # on the shelf and then give it to Bob" had read chips>B (the remark's thing taken for
            # the 'it'), "Bob already has the crisps, so give Bob any mug" … & chips>B
            raise GroundingError(
                f"{said!r} says what {who} already holds or had: it asks for nothing; leave it "
                f"out, or say 'give {who} the {thing}' to have it handed over"
            )
        beside_request44l(said, who, f"the {thing}")


def beside_request44l(said: str, who: str, thing: str) -> NoReturn:
    """Refuse a holding said beside a request, naming both readings (also session 53's
    ``_held_request53l``)."""
    raise GroundingError(
        f"{said!r} beside a request could say what {who} already holds (nothing to do for "
        f"it) or that {who} is to get {thing}: say 'give {who} {thing}' "
        "to have it handed over, or leave it out"
    )
