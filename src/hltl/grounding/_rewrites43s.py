"""The grounder's rules of session 43, engineer 12s (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _ids, _names, _only_person, _reading
from hltl.grounding._normalise4 import _fit36
from hltl.grounding._rewrites41s import _ORDER41S, _WANT_SAID41S
from hltl.grounding._rewrites42s import _P42S, _fits42s, _remark_only42s
from hltl.grounding.lexicon import Lexicon
from hltl.grounding.tree import Group, Node, tasks

# -- session 43 (12s): a typo in 'Person' itself ---------------------------------------------------
#
# "Plerson B keeps nagging about the cup, so …", "Persohn A left her bottle …": one insertion,
# deletion, substitution or swap of neighbours in 'person', before the one letter that, after
# 'Person', names a person of the scene. The lexicon reads such a name already (session 32), but
# the rules that match 'Person <letter>' in their patterns (the remark and want rules) do not see
# it: said 'Person <letter>' first. Not an English word one edit away ('parson', 'prison',
# 'persons') nor a letter no one of the scene is called by.
_PERSON_TYPO43S = re.compile(r"\b(?P<word>[a-z]{5,7})\s+(?P<letter>[a-z])(?=(?:'s?)?(?![\w-]))", _F)
_NOT_PERSON43S = frozenset({"parson", "prison", "persons", "person"})


def _one_edit43s(word: str, target: str) -> bool:
    """Whether ``word`` is one insertion, deletion, substitution or swap of neighbours from
    ``target``."""
    if word == target or abs(len(word) - len(target)) > 1:
        return False
    if len(word) == len(target):
        diff = [k for k in range(len(word)) if word[k] != target[k]]
        if len(diff) == 1:
            return True
        return (
            len(diff) == 2
            and diff[1] == diff[0] + 1
            and word[diff[0]] == target[diff[1]]
            and word[diff[1]] == target[diff[0]]
        )
    short, long_ = (word, target) if len(word) < len(target) else (target, word)
    return any(long_[:k] + long_[k + 1 :] == short for k in range(len(long_)))


def _person_typo43s(text: str, lexicon: Lexicon) -> str:
    """Session 43 (12s): a one-edit typo of 'Person' before a person's letter said as 'Person'
    (above)."""
    out = text
    for m in reversed(list(_PERSON_TYPO43S.finditer(text))):
        word = m["word"].lower()
        if word in _NOT_PERSON43S or not _one_edit43s(word, "person"):
            continue
        if not _only_person(f"Person {m['letter'].upper()}", lexicon):
            continue
        cap = "Person" if m["word"][0].isupper() else "person"
        out = out[: m.start("word")] + cap + out[m.end("word") :]
    return out


# -- session 43 (12s): 'and <person> takes the X' after a request ----------------------------------
#
# "chips go across to person b and person a takes the cup", "Give Zoe the ruler, and Noah takes
# the glue": a person who 'takes' a thing with no place or person after it, in a clause after a
# request, gets it (as `_elided` reads it opening a sentence).
_AND_TAKES43S = re.compile(
    rf"(?P<sep>(?:,\s*|\s+)and\s+)(?P<who>{_P42S})\s+(?P<modal>(?:can |will |should |"
    r"may |could )?)takes?\s+(?P<obj>(?:the|that|this|those|these|his|her|their) [a-z][a-z ]*?)"
    r"(?=\s*(?:[.,;!?]|$|\s+(?:and|please|too|as well)\b))",
    _F,
)


def _and_takes43s(text: str, lexicon: Lexicon) -> str:
    """Session 43 (12s): '… and <person> takes the X' said as '… and <person> gets the X', when
    the person is one of the scene, X names objects only, and what is left reads."""
    if "take" not in text.lower():
        return text
    out = text
    for m in reversed(list(_AND_TAKES43S.finditer(text))):
        if m.start() == 0 or not _only_person(m["who"], lexicon):
            continue
        if not _ids(m["obj"], lexicon, "object") or _ids(m["obj"], lexicon, "human"):
            continue
        if _ids(m["obj"], lexicon, "surface"):
            continue
        verb = "get" if m["modal"] else "gets"
        out = out[: m.start("modal")] + f"{m['modal']}{verb} {m['obj']}" + out[m.end("obj") :]
    if out == text:
        return text
    return out if _reading(out, lexicon) is not None else text


# -- session 43 (12s): a run-on of wants with no stops ---------------------------------------------
#
# "Person A needs her apple Person B wants the bottle and Person A would like chips as well",
# "zoe wants the ruler noah needs the glue": a thing of the scene, then straight on another
# person of the scene and what they want: a comma between (each clause a want of its own).
_WANTER43S = re.compile(
    rf"(?<=[a-z]) (?P<who>{_P42S})(?:'s (?:after|having|getting)| (?:wants|needs|would like|"
    r"would love|'d like|fancies|is after|is having|gets|could use|could do with|has asked for|"
    r"asked for))\b",
    _F,
)


def _run_on_wants43s(text: str, lexicon: Lexicon) -> str:
    """Session 43 (12s): a comma put before each person (of the scene) who wants something,
    said straight after a thing of the scene with no stop, when what is left reads."""
    out = text
    for m in reversed(list(_WANTER43S.finditer(text))):
        if not _only_person(m["who"], lexicon):
            continue
        before = out[: m.start()]
        last = before.split()[-1] if before.split() else ""
        if not _ids(last, lexicon, "object"):
            continue  # the clause before ends with a thing of the scene
        if not _WANT_SAID41S.search(before) and not re.search(r"\bgets\b", before, _F):
            continue
        out = before + "," + out[m.start() :]
    if out == text:
        return text
    return out if _reading(out, lexicon) is not None else text


# -- session 43 (12s): a thing said to come before the rest --------------------------------------
#
# "Person B's bottle comes before anything else and once he's holding it …", "the chips come
# first for person a then …", "Zoe's ruler is top of the list": a thing of the scene (or a person's)
# said to come first is the task said first: "<thing> first".
_PRIORITY43S = re.compile(
    rf"(?P<x>(?:(?:the|that|this)|{_P42S}'s) [a-z]+(?: [a-z]+)?) (?:comes?|goes|go|should come|"
    r"should go|ha(?:s|ve) to come|ha(?:s|ve) to go|needs? to come|needs? to go|is|are|must come|"
    r"must go)\s+"
    r"(?:before anything else|before everything else|before all else|first of all|first|top of "
    r"the list|ahead of everything(?: else)?|ahead of anything(?: else)?)",
    _F,
)


def _priority43s(text: str, lexicon: Lexicon) -> str:
    """Session 43 (12s): a thing said to come before the rest said as '<thing> first', when it
    names objects of the scene and what is left reads as a sequence."""
    m = _PRIORITY43S.search(text)
    if m is None:
        return text
    x = m["x"]
    if not _ids(x, lexicon, "object"):
        return text
    if "'s " in x and not _only_person(x.split("'s ")[0], lexicon):
        return text
    out = text[: m.start()] + f"{x} first" + text[m.end() :]
    read = _reading(out, lexicon)
    if not isinstance(read, Group) or read.op != "seq":
        return text
    return out


# -- session 43 (12s): a thing claimed by a person, a surface said to be a thing's spot ------------
#
# "The chips are spoken for by Person B.", "the cup's been claimed by Alice", "The globe is
# earmarked by Zoe": a thing of the scene claimed by one person is theirs to get: "… is for
# <person>". Not 'taken by' (done already?) nor 'wanted by' (the want rules').
_CLAIMED43S = re.compile(
    r"(?P<x>(?:the|that|this|those|these) [a-z]+(?: [a-z]+)?)(?P<be>'s|'re| is| are| was| were)"
    r"(?: been)? (?:spoken for|claimed|bagged|reserved|booked|earmarked|called dibs on|put by|"
    rf"set aside) (?:by|for) (?P<who>{_P42S})\b",
    _F,
)


def _claimed_by43s(text: str, lexicon: Lexicon) -> str:
    """Session 43 (12s): a thing claimed by one person said as '<thing> is for <person>', when
    the thing is objects of the scene only and what is left reads."""
    m = _CLAIMED43S.search(text)
    if m is None or not _only_person(m["who"], lexicon):
        return text
    if not _ids(m["x"], lexicon, "object") or _ids(m["x"], lexicon, "human"):
        return text
    be = "are" if m["be"].strip(" '").lower() in ("re", "are", "were") else "is"
    out = text[: m.start()] + f"{m['x']} {be} for {m['who']}" + text[m.end() :]
    return out if _reading(out, lexicon) is not None else text


# "shelf's the spot for the bottle", "The box is the place for the stapler", "Shelf first, for
# the cup.": a surface of the scene said to be where a thing of it goes: "the <thing> goes on the
# <surface>" ('first' kept).
_SPOT_FOR43S = re.compile(
    r"(?:^|(?<=[.;!?] )|(?<=, )|(?<=\band ))(?P<s>(?:the |that )?[a-z]+(?: [a-z]+)?)(?:(?:'s|\s+is)"
    r"\s+(?:the|a|its|their) (?:(?:right|best|proper|usual|only) )?(?:spot|place|home|place to "
    r"go|place to put|one)|(?P<first>\s+first)?,)\s+for (?P<x>(?:the|that|this|those|these) "
    r"[a-z]+(?: [a-z]+)?)(?=\s*(?:[.,;!?]|$|\s+(?:and|then|please)\b))",
    _F,
)


def _spot_for43s(text: str, lexicon: Lexicon) -> str:
    """Session 43 (12s): the surface above said as where the thing goes, when the surface is one
    of the scene, the thing objects of it only, and what is left reads."""
    m = _SPOT_FOR43S.search(text)
    if m is None:
        return text
    surf = m["s"]
    if len(_ids(surf, lexicon, "surface")) != 1 or _ids(surf, lexicon, "object"):
        return text
    if _ids(surf, lexicon, "human"):
        return text
    if not _ids(m["x"], lexicon, "object") or _ids(m["x"], lexicon, "human"):
        return text
    noun = re.sub(r"^(?:the|that) ", "", surf, flags=_F)
    said = f"{m['x']} goes on the {noun}" + (" first" if m["first"] else "")
    if m.start() == 0:
        said = said[:1].upper() + said[1:]
    out = text[: m.start()] + said + text[m.end() :]
    return out if _reading(out, lexicon) is not None else text


# -- session 43 (12s): the speaker finding the person, a remark of the person's liking -----------
#
# "Where's Bob... ah, there. The bottle's his; …", "where's mia? oh there she is, her box goes
# on the pallet": the speaker looking for a person of the scene and finding them, opening: the
# person is whom the first he / his / she / her after it means (said in its place), the search
# taken off.
_FOUND43S = re.compile(
    rf"^(?:(?:right|ok|okay|now|so|um|erm|er|hmm)\s*,?\s+)*where(?:'s| is) (?P<who>{_P42S})"
    r"\s*(?:\.\.\.|…|\?|,|-|–|—)\s*(?:(?:ah|oh|aha|ah yes|right|ok|okay)\s*,?\s*)?(?:there (?:he|"
    r"she) is|there|over there|found (?:him|her)|here (?:he|she) (?:is|comes))\s*[.!,;…]*\s+"
    r"(?P<rest>\S.*)$",
    _F,
)


def _found_person43s(text: str, lexicon: Lexicon) -> str:
    """Session 43 (12s): the search above taken off and the person named for the first pronoun
    after it, when the pronoun may be them and what is left reads."""
    m = _FOUND43S.match(text)
    if m is None or not _only_person(m["who"], lexicon):
        return text
    rest = m["rest"]
    p = _PRON43S.search(rest)
    if p is None or not _fits42s(m["who"], p.group(0), lexicon):
        return text
    who = m["who"]
    said = f"{who}'s" if p.group(0).lower() in ("his", "hers") else who
    out = rest[: p.start()] + said + rest[p.end() :]
    out = out[:1].upper() + out[1:]
    return out if _reading(out, lexicon) is not None else text


# "… the magazine on the locker for Mr Lee he likes a read", "Lily needs her bib because she's a
# mucky pup and Ava …", "…, she loves a puzzle", "…, he's a ditcher and starving": what the person
# named just before likes or what they are ('a …', 'the …'; and a need of theirs), closing a
# request or before 'and' (with or without 'because' / 'as' / 'since'): asks nothing (words naming
# nothing of the scene, no want): taken off, when the pronoun may be that person and what is left
# reads. A need alone ("…, because she's hungry") may ask for food: left to the older rules.
_NEED43S = (
    r"(?:(?:so|really|very|absolutely|proper|just) )?(?:starving|famished|ravenous|peckish|hungry|"
    r"thirsty|parched|gasping)"
)
_LIKING43S = re.compile(
    r"(?P<sep>\s*[,;]?\s+(?:(?:because|as|since|cos|'cause)\s+)?)(?P<pron>he|she)(?:(?: (?:likes|"
    r"loves|enjoys|adores|is fond of|'s fond of|never says no to)|(?:'s| is) (?:a|an|the|such a|a "
    r"bit of a|a real|a right|a proper|a big|a great)) (?P<words>(?:(?:a|an|his|her|the|good) )?"
    rf"[a-z-]+(?: [a-z-]+){{0,2}}?)(?: and {_NEED43S})?)"
    r"(?P<end>\s*[.!]*\s*$|(?=,?\s+and\s))",
    _F,
)


def _liking_remark43s(text: str, lexicon: Lexicon) -> str:
    """Session 43 (12s): the remark above taken off (above)."""
    if " he" not in text.lower() and " she" not in text.lower():
        return text
    for m in _LIKING43S.finditer(text):
        if m.start() == 0 or not _remark_only42s(m["words"] or "", lexicon):
            continue
        before = text[: m.start()]
        people = [it for it in _names(before, lexicon) if any(r.kind == "human" for r in it.refs)]
        if not people:
            continue
        last = {r.id for r in people[-1].refs if r.kind == "human"}
        if len(last) != 1 or not _fit36(next(iter(last)), m["pron"], lexicon):
            continue
        after = text[m.end() :]
        if after.strip() and not _ids(
            " ".join(re.split(r"\s+", after.strip())[1:4]), lexicon, "human"
        ):
            continue  # '… and needs it' says more of them (session 41's trades): 'and <person> …'
        out = before + (m["end"] or "").strip() + after
        read = _reading(out, lexicon)
        if read is None:
            continue
        # the person gets something, or a thing is put somewhere for them
        if any(t.target in last or t.kind == "place" for t in tasks(read)):
            return out
    return text


# "Omar's the one the sponge is for", "Zoe is the one who gets the globe": a person of the scene
# said to be the one a thing of it is for: "<thing> is for <person>".
_ONE_FOR43S = re.compile(
    rf"(?P<who>{_P42S})(?:'s|\s+is)\s+the (?:one|person|lady|man|woman|fella|girl|boy|lad|"
    r"chap|patient|one person) (?:(?:that |who |whom )?(?P<x>(?:the|that|this|those|these) "
    r"[a-z]+(?: [a-z]+)?) (?:is|are|'s|'re) (?:for|meant for|going to|headed for)|(?:who|that) "
    r"(?:gets|wants|needs|asked for|is getting|should get) (?P<y>(?:the|that|this|those|these) "
    r"[a-z]+(?: [a-z]+)?))(?=\s*(?:[.,;!?]|$|\s+(?:and|please|thanks)\b))",
    _F,
)


def _one_for43s(text: str, lexicon: Lexicon) -> str:
    """Session 43 (12s): the cleft above said as '<thing> is for <person>', when the person is
    one of the scene, the thing objects of it only, and what is left reads."""
    m = _ONE_FOR43S.search(text)
    if m is None or not _only_person(m["who"], lexicon):
        return text
    x = m["x"] or m["y"]
    if not _ids(x, lexicon, "object") or _ids(x, lexicon, "human") or _ids(x, lexicon, "surface"):
        return text
    said = f"{x} is for {m['who']}"
    if m.start() == 0:
        said = said[:1].upper() + said[1:]
    out = text[: m.start()] + said + text[m.end() :]
    return out if _reading(out, lexicon) is not None else text


# "The thermometer to Ruth and the magazine on the locker for Mr Lee": a thing put on a surface
# of the scene 'for' a person, in a clause of its own beside a handover to someone else said with
# 'to' (session 41's `_placed_for41s` reads it alone): the placement. Not when 'for' names whom
# else a thing is for ("… on the shelf for Bob and the apple for Carol": a handover?), nor when
# the person gets something too.
_PLACED_FOR43S = re.compile(
    r"(?:(?<=[,;.] )|(?<=\band ))(?P<clause>"
    r"(?:the|that|this|those|these) [a-z]+(?: [a-z]+)? (?:on|onto|in|into|on top of|inside) (?:the|"
    rf"that) [a-z]+(?: [a-z]+)?) for (?P<who>{_P42S})(?=\s*(?:[.,;!?]|$))",
    _F,
)


def _placed_for43s(text: str, lexicon: Lexicon) -> str:
    """Session 43 (12s): 'for <person>' after the placement above taken off, when no other 'for'
    names a person, the person gets nothing, and what is left reads with the thing placed."""
    if text.lower().count(" for ") != 1:
        return text
    m = _PLACED_FOR43S.search(text)
    if m is None or not _only_person(m["who"], lexicon):
        return text
    objs = _ids(m["clause"], lexicon, "object")
    if len(objs) != 1 or len(_ids(m["clause"], lexicon, "surface")) != 1:
        return text
    if _ids(m["clause"], lexicon, "human"):
        return text
    out = text[: m.end("clause")] + text[m.end() :]
    read = _reading(out, lexicon)
    if read is None:
        return text
    (obj,) = objs
    pid = _ids(m["who"], lexicon, "human")
    if not any(t.kind == "place" and t.obj == obj for t in tasks(read)):
        return text
    if any(t.target in pid for t in tasks(read)):
        return text
    return out


# "Grandad's changing Lily; can you pass him the baby wipes?": what one person of the scene is
# doing to another (words naming no thing of it), then a request whose one pronoun may be the
# doer and not the other: the doer named in its place (the lead's session-37 rule: a remark's
# person gets what follows), the remark taken off.
_OPENING_DOER43S = re.compile(
    rf"^(?P<who>{_P42S})(?:'s|\s+is)\s+(?P<words>[a-z]+ing\b[^.;:!?,]*?)(?:\s*[;,.]\s*(?:so\s+)?|"
    r"\s+so\s+)(?P<rest>\S.*)$",
    _F,
)


def _opening_doer43s(text: str, lexicon: Lexicon) -> str:
    """Session 43 (12s): the doer above named for the pronoun, when the pronoun may be them and
    none of the other people the remark names, and what is left reads."""
    m = _OPENING_DOER43S.match(text)
    if m is None or not _only_person(m["who"], lexicon):
        return text
    words = m["words"]
    if _ids(words, lexicon, "object") or _ids(words, lexicon, "surface"):
        return text
    others = _ids(words, lexicon, "human")
    if not others:
        return text  # a remark naming no one: session 37's and 42's rules
    rest = m["rest"]
    prons = _PRON43S.findall(rest)
    if len(prons) != 1 or _ids(rest, lexicon, "human"):
        return text
    if not _fits42s(m["who"], prons[0], lexicon):
        return text
    if any(_fit36(o, prons[0], lexicon) for o in others):
        return text
    who = m["who"]
    said = f"{who}'s" if prons[0].lower() in ("his", "hers") else who
    out = _PRON43S.sub(said, rest, count=1)
    read = _reading(out, lexicon)
    if read is None or not any(t.target in _ids(who, lexicon, "human") for t in tasks(read)):
        return text
    return out


# "Bowl in the sink. Spoon in with it.", "put the cup on the shelf and the apple on with it",
# "The drill goes in the locker; the torch in with it too": a thing put 'in with' / 'on with' the
# thing just placed goes on the same surface (the one surface said before it): said so.
_IN_WITH43S = re.compile(
    r"\b(?P<prep>in|on|onto|into|up) (?:there )?(?:with|alongside|beside|next to) (?:it|them|that|"
    r"those)\b(?! (?:one|ones)\b)",
    _F,
)


def _in_with43s(text: str, lexicon: Lexicon) -> str:
    """Session 43 (12s): 'in with it' after a placement said as 'in <its surface>', when the text
    before names one surface of the scene, what it puts there is placed, and what is left
    reads."""
    m = _IN_WITH43S.search(text)
    if m is None or m.start() == 0:
        return text
    before = text[: m.start()]
    surfs = [it for it in _names(before, lexicon) if any(r.kind == "surface" for r in it.refs)]
    if len(surfs) != 1 or len({r.id for r in surfs[0].refs}) != 1:
        return text
    (sid,) = {r.id for r in surfs[0].refs}
    said = surfs[0].text
    prep = "in" if m["prep"].lower() in ("in", "into") else "on"
    out = f"{before}{prep} the {said}{text[m.end() :]}"
    read = _reading(out, lexicon)
    if read is None:
        return text
    placed = [t for t in tasks(read) if t.kind == "place"]
    if len(placed) < 2 or any(t.target != sid for t in placed):
        return text
    return out


# "Chips first. Person B's. After those, …", "The globe. Zoe's.", "Tape first. That's Tom's.": a
# thing of the scene said alone (first, or not), then, as a sentence of its own, whose it is:
# the thing to that person.
_WHOSE43S = re.compile(
    r"(?:^|(?<=[.;!?] ))(?P<x>(?:(?:the|that|this|those|these) )?[a-z]+(?: [a-z]+)?)(?P<first> "
    r"first)?\s*[.;]\s+(?:(?:that's|that is|it's|it is|they're|they are|those are|that one's)\s+)?"
    rf"(?P<who>{_P42S})'s\s*(?P<end>[.;!]|$)",
    _F,
)


def _whose_after43s(text: str, lexicon: Lexicon) -> str:
    """Session 43 (12s): the thing and whose it is above said as '<thing> to <person>', when the
    thing is objects of the scene only, the person one of it, and what is left reads."""
    m = _WHOSE43S.search(text)
    if m is None or not _only_person(m["who"], lexicon):
        return text
    x = m["x"]
    if not _ids(x, lexicon, "object") or _ids(x, lexicon, "human") or _ids(x, lexicon, "surface"):
        return text
    said = f"{x} to {m['who']}{m['first'] or ''}{m['end'] or ''}"
    out = text[: m.start()] + said + text[m.end() :]
    read = _reading(out, lexicon)
    if read is None or not any(t.target in _ids(m["who"], lexicon, "human") for t in tasks(read)):
        return text
    return out


# "Dana's after a spoon, plus the green cup to go with it", "Give Zoe the glue and the ruler to go
# with it": a second thing said to go with the first, both to one person: what it goes with is
# what she gets already (whichever 'it' is), so the purpose is taken off.
_GO_WITH_IT43S = re.compile(
    r"(?P<sep>\s*,?\s+)to (?:go with|go alongside|go along with|have with|eat with|drink with|"
    r"use with|match) (?:it|them|that|those|the first|the other)(?P<end>\s*(?:,\s*(?:please|"
    r"thanks|ta|cheers))?\s*[.!]*)\s*$",
    _F,
)


def _go_with_it43s(text: str, lexicon: Lexicon) -> str:
    """Session 43 (12s): 'to go with it' after a second thing taken off, when what is left reads
    as two or more things handed to one person only."""
    m = _GO_WITH_IT43S.search(text)
    if m is None or m.start() == 0:
        return text
    out = text[: m.start()] + m["end"].strip()
    read = _reading(out, lexicon)
    if read is None:
        return text
    done = list(tasks(read))
    if len(done) < 2 or any(t.kind != "deliver" for t in done):
        return text
    if len({t.target for t in done}) != 1:
        return text
    return out


# -- session 43 (12s): a reason per person, then 'so' + what they get ------------------------------
#
# "person b's drinking so the bottle is his", "Poor Person B skipped his dinner break, so the
# chips are his", "Omar's washing up so the sponge is his": what one person is or does (words
# naming nothing of the scene, no want, no negation, nothing counted or pointed back at), then
# 'so' + a clause whose one he / his / him / she / her may be them: their name said in its place,
# the reason gone. Only a clause that says who has what ('the bottle is his', 'she takes the
# chips'): an order ('so give him …', 'so let her have …') is session 32's and 42's state rules'.
_SO_REASON43S = re.compile(
    rf"(?:^|(?<=[,;.] )|(?<=\band ))(?:(?:poor|dear|little|old) )?(?P<who>{_P42S})"
    r"(?P<words>(?:'s|\s)[^.;:!?,]{2,60}?),?\s+so\s+(?P<clause>[^.;:!?,]+)",
    _F,
)
_PRON43S = re.compile(r"\b(?:he|she|his|her|hers|him)\b", _F)
# a clause that says who has what: 'the bottle is his', 'she takes the chips' ('so she gets …':
# session 41's middle remarks)
_HAS43S = re.compile(
    r"\s*(?:(?:the|that|this|those|these) [a-z]+(?: [a-z]+)?(?:'s|'re| is| are) (?:his|hers)\b|"
    r"(?:he|she) takes (?:the|that|this|those|these) )",
    _F,
)
_LATER43S = re.compile(
    r"\b(?:tomorrow|later|tonight|next|soon|this (?:afternoon|evening|morning)|after|before|"
    r"when|until|till)\b",
    _F,
)


def _so_reason43s(text: str, lexicon: Lexicon) -> str:
    """Session 43 (12s): each reason above taken off and its person named in the clause, when
    the clause's one pronoun may be the person and it names no other person, and what is left
    reads, giving each of them something."""
    if " so " not in text.lower():
        return text
    out = text
    named: set[str] = set()
    for _ in range(4):
        for m in _SO_REASON43S.finditer(out):
            if not _HAS43S.match(m["clause"]) or _LATER43S.search(m["words"]):
                continue  # 'so give him …', 'so she needs …': the older state rules
            if not _fits42s(m["who"], m["clause"], lexicon):
                continue
            words = re.sub(r"^(?:'s|\s)\s*", "", m["words"])
            words = re.sub(r"\b(?:his|her)\b", "", words, flags=_F)
            if not _remark_only42s(words, lexicon) or _ids(m["clause"], lexicon, "human"):
                continue
            prons = _PRON43S.findall(m["clause"])
            if len(prons) != 1:
                continue
            who = m["who"]
            said = {"his": f"{who}'s", "hers": f"{who}'s"}.get(prons[0].lower(), who)
            clause = _PRON43S.sub(said, m["clause"], count=1)
            # 'Noah takes the ruler' after a clause is 'Noah gets the ruler' (takes it: gets it)
            clause = re.sub(rf"^(\s*{re.escape(who)}) takes\b", r"\1 gets", clause, flags=_F)
            if m.start() == 0:
                clause = clause[:1].upper() + clause[1:]
            named |= _ids(who, lexicon, "human")
            out = out[: m.start()] + clause + out[m.end() :]
            break
        else:
            break
    if out == text:
        return text
    read = _reading(out, lexicon)
    if read is None or not named <= {t.target for t in tasks(read)}:
        return text
    return out


# -- session 43 (12s): where a thing is put out of someone's reach --------------------------------
#
# "Stick the bottle on the shelf where Bob's puppy can't chew it", "… on the shelf, out of sight
# of the grandkids", "… in the box out of the way", "… on the rack, away from the toddlers":
# why a thing goes where it goes (words naming no thing or surface of the scene; a person there
# is whom it is kept from): taken off after a request that places everything it names.
_OUT_OF_REACH43S = re.compile(
    r"(?P<sep>\s*,?\s*)(?:(?:where|so) (?P<who>[^.;:!?,]{1,40}?) (?:can't|cannot|can not|won't|"
    r"couldn't) (?:get at|get to|reach|chew|grab|knock|touch|nick|pinch|see|find|spill|break|"
    r"get hold of|mess with|eat) (?:it|them)|out of (?:the )?(?:sight|reach|way|harm's way)"
    r"(?: of (?P<of>[^.;:!?,]{1,40}?))?|(?:safely )?away from (?P<from>(?:the|our|my|his|her|"
    r"those) [^.;:!?,]{1,40}?))(?P<end>\s*[.!?]*)\s*$",
    _F,
)


def _placed_aside43s(text: str, lexicon: Lexicon) -> str:
    """Session 43 (12s): the reason of a placement above taken off, when its words name nothing
    of the scene and what is left reads as placements only."""
    m = _OUT_OF_REACH43S.search(text)
    if m is None or m.start() == 0:
        return text
    words = " ".join(w for w in (m["who"], m["of"], m["from"]) if w)
    # a person of the scene may be whom it is kept from ("where Bob's puppy can't chew it"):
    # they are given nothing; a thing or a surface of the scene is another task
    if words and (_ids(words, lexicon, "object") or _ids(words, lexicon, "surface")):
        return text
    out = text[: m.start()] + (m["end"] or "").strip()
    read = _reading(out, lexicon)
    if read is None or any(t.kind != "place" for t in tasks(read)):
        return text
    return out


# "Stick the bottle high up on the shelf", "pop the crisps up high on the shelf", "put the tin
# right up on top of the locker": how high on the surface is where on it: 'on'.
_HEIGHT43S = re.compile(
    r"\b(?:high up|up high|way up|right up|high|up|well up|low down|down low|right down)\s+"
    r"(?:on top of|on|onto|in|into|up on)\s+(?=(?:the|that|this) )",
    _F,
)


def _height43s(text: str, lexicon: Lexicon) -> str:
    """Session 43 (12s): a height before 'on <surface>' said as 'on', when the surface is one of
    the scene and what is left reads."""
    m = _HEIGHT43S.search(text)
    if m is None:
        return text
    rest = text[m.end() :]
    if not _ids(" ".join(rest.split()[:3]), lexicon, "surface"):
        return text
    prep = "in" if re.search(r"\bin(?:to)?\s*$", m.group(0), _F) else "on"
    out = text[: m.start()] + f"{prep} " + rest
    return out if _reading(out, lexicon) is not None else text


# -- session 43 (12s): a spell of work or time before a want --------------------------------------
#
# "After a morning on the piling rig, Bob would love the water bottle", "After a long shift at
# the quarry, Mia could murder the tea", "Following a hard day in the fields, …": a spell of time
# spent somewhere (naming nothing of the scene) before the want of one person: why they want it,
# taken off (as session 37's 'after his <doing>'). Before an order ('After a long day, put …')
# it says when: kept; without the place ("After his shift, …") it is session 37's event (when).
_SPELL43S = re.compile(
    r"^(?:after|following) (?:a|an|the|his|her|their|that) (?:(?:long|hard|busy|whole|full|"
    r"tough|rough|gruelling|hot|cold|wet|late|early|heavy|endless|solid) ){0,2}(?:morning|day|"
    r"afternoon|evening|night|week|shift|stint|spell|stretch|session|hour|hours|weekend|"
    r"fortnight|month|lesson|practice)(?P<place> (?:on|at|in|out|up|down|over|round|behind|"
    r"under) [^.;:!?,]{1,40}?),\s*(?P<rest>\S.*)$",
    _F,
)


def _after_spell43s(text: str, lexicon: Lexicon) -> str:
    """Session 43 (12s): the opening spell above taken off, when it names nothing of the scene,
    what follows tells of a want (not an order) of one person, and it reads."""
    m = _SPELL43S.match(text)
    if m is None or _names(m.group(0)[: m.start("rest")], lexicon):
        return text
    rest = m["rest"]
    if not _WANT_SAID41S.search(rest) or _ORDER41S.search(rest):
        return text
    rest = rest[:1].upper() + rest[1:]
    read = _reading(rest, lexicon)
    if read is None:
        return text
    given = {t.target for t in tasks(read) if t.kind == "deliver"}
    if len(given) != 1 or any(t.kind != "deliver" for t in tasks(read)):
        return text
    pron = re.match(r"^\w+ (his|her)\b", m.group(0), _F)
    if pron and not _fit36(next(iter(given)), pron[1], lexicon):
        return text
    return rest


# "Person A fancies the bottle now her qigong session's over", "Kofi wants the drill now that
# his tea break is done", "… now she's back from her swim": that the person's own doing is over
# (why they want it now), after their want: taken off.
_NOW_OVER43S = re.compile(
    r"(?P<sep>\s*,?\s+)now (?:that )?(?:(?P<p1>his|her) (?P<what>[a-z][a-z -]{1,40}?)(?:'s|"
    r"\s+is|\s+has)\s+(?:over|done|finished|ended|out of the way|wrapped up|been and gone)|"
    r"(?P<p2>he|she)(?:'s|\s+is|\s+has)\s+(?:back from|done with|finished|through with|"
    r"(?:got )?out of) (?:his|her) (?P<what2>[a-z][a-z -]{1,40}?))(?P<end>\s*[.!]*)\s*$",
    _F,
)


def _now_over43s(text: str, lexicon: Lexicon) -> str:
    """Session 43 (12s): 'now her <doing>'s over' after a want taken off, when the doing names
    nothing of the scene, the pronoun may be the one person who gets something, and what is left
    reads (a want, not an order: an order said now is when)."""
    m = _NOW_OVER43S.search(text)
    if m is None or m.start() == 0:
        return text
    what = m["what"] or m["what2"] or ""
    if not _remark_only42s(what, lexicon):
        return text
    out = text[: m.start()] + (m["end"] or "").strip()
    if not _WANT_SAID41S.search(out) or _ORDER41S.search(out):
        return text
    read = _reading(out, lexicon)
    if read is None:
        return text
    given = {t.target for t in tasks(read) if t.kind == "deliver"}
    if len(given) != 1 or not _fit36(next(iter(given)), m["p1"] or m["p2"], lexicon):
        return text
    return out


# the normaliser's rewrites run before every other rewrite (wired into normalise._STEPS19)
_STEPS43S_FIRST: tuple[Callable[[str, Lexicon], str], ...] = (
    _person_typo43s,
    _run_on_wants43s,
    _so_reason43s,
    _and_takes43s,
    _priority43s,
    _claimed_by43s,
    _spot_for43s,
    _found_person43s,
    _liking_remark43s,
    _one_for43s,
    _placed_for43s,
    _opening_doer43s,
    _in_with43s,
    _whose_after43s,
    _go_with_it43s,
    _placed_aside43s,
    _height43s,
    _after_spell43s,
    _now_over43s,
)
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-42 ones)
_STEPS43S: tuple[Callable[[str, Lexicon], str], ...] = ()
# refusals asked of the text before it is read (offline._parse, after the session-42 ones)
REFUSE43S: tuple[Callable[[str, Lexicon], None], ...] = ()
# checks of the whole instruction's reading (offline.parse_instruction, after the session-42 ones)
CHECK43S: tuple[Callable[[str, Node, Lexicon], None], ...] = ()
