"""The grounder's rules of session 44, engineer 12s (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _ids, _names, _only_person, _reading
from hltl.grounding._normalise4 import _fit36
from hltl.grounding._rewrites39 import doubt_which39
from hltl.grounding._rewrites41s import _ORDER41S, _WANT_SAID41S
from hltl.grounding._rewrites42s import _P42S, _fits42s, _remark_only42s
from hltl.grounding._rewrites43s import _LATER43S, _PRON43S
from hltl.grounding.lexicon import PRONOUN_SEX, Item, Lexicon, unnamed_sex44l
from hltl.grounding.tree import Group, Node, tasks

# -- session 44 (12s): a claim condition after a thing ---------------------------------------------
#
# "person b's asking for the cup, also the apple if it's going spare", "Give Zoe the glue if it's
# free", "… and the spoon if nobody else has claimed it": whether the thing can be had, which the
# task needs anyway (the lead's policy: a claim condition reads as the plain request), said straight
# after a thing of the scene (never after a surface or a person: "… on the shelf if it's free" may
# ask whether the shelf is clear). Session 14's courtesy list took 'if it's going' off and left
# 'spare' behind ("also the apple spare"), which nothing read.
_SPARE44S = re.compile(
    r",?\s+if (?:(?:it's|its|it is|they're|they are|that's|that is) (?:still )?(?:going spare|"
    r"going begging|going free|going|spare|free|available|up for grabs|not (?:being )?used|"
    r"not in use|not needed|not spoken for|not claimed|unclaimed)|there's (?:one|any|some) "
    r"(?:going )?spare|(?:nobody|no one|no-one)(?: else)?(?:'s| has| is)? (?:claimed|bagged|"
    r"nabbed|wants|needs|using|after|taken) (?:it|them|that|those))(?=\s*(?:[.!;,]|$))",
    _F,
)


def _if_spare44s(text: str, lexicon: Lexicon) -> str:
    """Session 44 (12s): the claim condition above taken off, when the last name before it is a
    thing of the scene (objects only) and what is left reads."""
    if " if " not in text.lower():
        return text
    m = _SPARE44S.search(text)
    if m is None:
        return text
    said = _names(text[: m.start()], lexicon)
    if not said or any(r.kind != "object" for r in said[-1].refs):
        return text
    # 'it' for one thing said alone: "the apple and the cup if it's going spare" (session 34's
    # refusal) names two things for it; "…, and the apple if it's going spare" (a comma before
    # 'and': a clause of its own) the last
    one = re.match(r",?\s+if (?:it|its|that)\b", m.group(0), _F) is not None
    last = text[: m.start()].lower().rsplit(said[-1].text.lower(), 1)[0]
    listed = len(said) > 1 and re.search(
        r"(?:(?<!,) (?:and|or|&)|,)\s+(?:the |that |this )?$", last, _F
    )
    if one and (listed or len({r.id for r in said[-1].refs}) != 1):
        return text
    out = text[: m.start()] + text[m.end() :]
    return out if _reading(out, lexicon) is not None else text


# -- session 44 (12s): 'shelve' -------------------------------------------------------------------
#
# "shelve the crisps first and when that's done bob can have the bottle", "Shelve the glue, then
# …", "Shelf the bottle please" (the noun said as the verb, opening a sentence): to shelve a thing
# is to put it on the shelf, when the scene has one (its one surface called 'shelf' or
# 'bookshelf'); no other place may follow ("shelve it on the desk" stays refused).
_SHELVE44S = re.compile(
    r"(?:\b(?P<v>shelve)|(?:^|(?<=[.;!?] ))(?P<v2>shelf))\s+(?P<x>it|them|(?:the|that|this|"
    r"those|these|his|her|their|both) [a-z][a-z' ]*?)(?=\s*(?:[.!;,?]|$|\s+(?:first|then|and|"
    r"please|now|too|as well|after|before|when|once|for (?:me|us)|straight away|right away|"
    r"quickly)\b))",
    _F,
)


def _shelve44s(text: str, lexicon: Lexicon) -> str:
    """Session 44 (12s): 'shelve X' said as 'put X on the shelf' (above), when the scene has one
    shelf, X names things of it (or is it / them) and what is left reads."""
    if "shel" not in text.lower():
        return text
    shelf = _ids("shelf", lexicon, "surface")
    if len(shelf) != 1:
        return text
    out = text
    for m in reversed(list(_SHELVE44S.finditer(text))):
        x = m["x"]
        if x.lower() not in ("it", "them") and (
            not _ids(x, lexicon, "object")
            or _ids(x, lexicon, "human")
            or _ids(x, lexicon, "surface")
        ):
            continue
        said = m["v"] or m["v2"]
        verb = "Put" if said[0].isupper() else "put"
        out = out[: m.start()] + f"{verb} {x} on the shelf" + out[m.end() :]
    if out == text:
        return text
    read = _reading(out, lexicon)
    if read is None or not any(t.kind == "place" and t.target in shelf for t in tasks(read)):
        return text
    return out


# -- session 44 (12s): run-ons and sequences -----------------------------------------------------
#
# "… Alice is having the crisps and after her Bob has the apple": 'after her' / 'after him' straight
# before another person of the scene, the pronoun fitting the one person named last before it (who
# gets something there), is 'after that': the next task comes once theirs is done.
_AFTER_HER44S = re.compile(
    rf"\b(?P<after>after|following|next after) (?P<pron>her|him)\s+(?=(?P<who>{_P42S})\b)",
    _F,
)


def _after_her44s(text: str, lexicon: Lexicon) -> str:
    """Session 44 (12s): 'after her <person>' said as 'after that, <person>' (above), when the
    pronoun fits the last person named before it, the one after is another of the scene, and what
    is left reads as a sequence that gives each of them something."""
    if "after h" not in text.lower() and "following h" not in text.lower():
        return text
    m = _AFTER_HER44S.search(text)
    if m is None or m.start() == 0:
        return text
    who = next(
        (w for w in (m["who"], " ".join(m["who"].split()[:2])) if _only_person(w, lexicon)),
        None,
    )
    if who is None:
        return text
    people = [it for it in _names(text[: m.start()], lexicon) if _humans44s(it)]
    if not people or len({r.id for r in people[-1].refs}) != 1:
        return text
    (before,) = {r.id for r in people[-1].refs}
    (after,) = _ids(who, lexicon, "human")
    if before == after or not _fit36(before, m["pron"], lexicon):
        return text
    out = text[: m.start()] + "after that, " + text[m.end() :]
    read = _reading(out, lexicon)
    if not isinstance(read, Group) or read.op != "seq":
        return text
    if not {before, after} <= {t.target for t in tasks(read)}:
        return text
    return out


def _humans44s(item: Item) -> bool:
    return bool(item.refs) and all(r.kind == "human" for r in item.refs)


def _only_fit44s(pid: str, pronoun: str, lexicon: Lexicon) -> bool:
    """Whether ``pronoun`` ('he', "she'd", …) may be person ``pid`` and no other person of the
    scene (by `_fit36` and the lead's `unnamed_sex44l`)."""
    word = re.sub(r"'.*$", "", pronoun).lower()

    def may(hid: str) -> bool:
        sex = _generic_sex44s(hid, lexicon)
        return _fit36(hid, word, lexicon) and (sex is None or PRONOUN_SEX.get(word, sex) == sex)

    return may(pid) and not any(may(h.id) for h in lexicon.scene.humans if h.id != pid)


def _generic_sex44s(pid: str, lexicon: Lexicon) -> str | None:
    """The lead's `unnamed_sex44l` for a person the scene calls by a generic label alone ('Person
    A' 'she', 'Person B' 'he'); None for a person with other names (Kofi is Person A of the
    workshop: the convention is not theirs, and `_fit36` reads their names)."""
    human = next(h for h in lexicon.scene.humans if h.id == pid)
    return None if human.aliases else unnamed_sex44l(pid, lexicon)


def _agrees44s(who: str, pronoun: str, lexicon: Lexicon) -> bool:
    """Whether ``pronoun`` may be the one person ``who`` names, by `_fits42s` and by what the
    scene says of their sex (session 44, the lead's `unnamed_sex44l`: a title, a word of kin, a
    first name or the corpus's convention, Person A 'she' and Person B 'he')."""
    if not _fits42s(who, pronoun, lexicon):
        return False
    (pid,) = _ids(who, lexicon, "human")
    sex = _generic_sex44s(pid, lexicon)
    return sex is None or PRONOUN_SEX.get(pronoun.lower(), sex) == sex


# "Shelf for the bottle first, and after that …", "tray for the banana first": a surface of the
# scene, 'for' a thing of it, then 'first': "<thing> goes on the <surface> first" (session 43's
# `_spot_for43s` reads "Shelf first, for the cup").
_SURFACE_FIRST44S = re.compile(
    r"(?:^|(?<=[.;!?] )|(?<=, )|(?<=\band ))(?P<s>(?:the )?[a-z]+) for (?P<x>(?:the|that|this|"
    r"those|these) [a-z]+(?: [a-z]+)?) first\b",
    _F,
)


def _surface_first44s(text: str, lexicon: Lexicon) -> str:
    """Session 44 (12s): the surface above said as where the thing goes first, when the surface
    is one of the scene, the thing objects of it only, and what is left reads."""
    if " first" not in text.lower():
        return text
    m = _SURFACE_FIRST44S.search(text)
    if m is None:
        return text
    surf = m["s"]
    if len(_ids(surf, lexicon, "surface")) != 1 or _ids(surf, lexicon, "object"):
        return text
    x = m["x"]
    if not _ids(x, lexicon, "object") or _ids(x, lexicon, "human") or _ids(x, lexicon, "surface"):
        return text
    noun = re.sub(r"^the ", "", surf, flags=_F)
    said = f"{x} goes on the {noun} first"
    if m.start() == 0:
        said = said[:1].upper() + said[1:]
    out = text[: m.start()] + said + text[m.end() :]
    return out if _reading(out, lexicon) is not None else text


# "… and after that Alice wants the crisps so give them to her": a want run on into the request
# to carry it out, inside a longer instruction (session 35's `_want_run_on35` reads it opening
# one): a comma before 'so'.
_WANT_SO44S = re.compile(
    rf"(?<=\s)(?P<who>{_P42S}) (?:is after|'s after|wants|needs|would like|'d like|fancies) "
    r"(?P<x>(?:the|her|his|their) [a-z]+(?: [a-z]+)?) (?=so (?:give|hand|pass|take|bring|get|"
    r"let)\b[^.;!?]*\b(?:it|them)\b)",
    _F,
)


def _want_so44s(text: str, lexicon: Lexicon) -> str:
    """Session 44 (12s): the comma above put in, when the person is one of the scene, the thing
    objects of it, and what is left reads giving them the thing."""
    if " so " not in text.lower():
        return text
    m = _WANT_SO44S.search(text)
    if m is None or not _only_person(m["who"], lexicon):
        return text
    x = re.sub(r"^(?:her|his|their)\b", "the", m["x"], flags=_F)
    if not _ids(x, lexicon, "object") or _ids(x, lexicon, "human"):
        return text
    clause = re.split(r"[.;!?]", text[m.end() :])[0]
    if any(
        not _agrees44s(m["who"], p, lexicon) for p in re.findall(r"\b(?:him|her)\b", clause, _F)
    ):
        return text  # "… Emma wants the banana so pass it to him": someone else
    out = text[: m.end() - 1] + ", " + text[m.end() :]
    read = _reading(out, lexicon)
    if read is None or not _ids(m["who"], lexicon, "human") & {t.target for t in tasks(read)}:
        return text
    return out


# "Spoon to the sink after.": 'after' closing a sentence that is not the first, with nothing
# after it, is 'afterwards'; "Last of all Dana's green cup goes back to her": 'lastly'.
_AFTER_END44S = re.compile(r"(?<=[a-z] )after(?=\s*(?:[.!;]|$))", _F)
_LAST_OF_ALL44S = re.compile(r"\b(?P<and>and )?last of all\b,?", _F)


def _after_end44s(text: str, lexicon: Lexicon) -> str:
    """Session 44 (12s): 'after' closing a later sentence said as 'afterwards', and 'last of all'
    as 'lastly', when what is left reads as a sequence."""
    low = text.lower()
    if "after" not in low and "last of all" not in low:
        return text
    out = _LAST_OF_ALL44S.sub(lambda m: "and lastly" if m["and"] else "lastly", text)
    out = re.sub(r"(^|(?<=[.;!?] ))lastly\b", "Lastly", out, flags=_F)
    for m in reversed(list(_AFTER_END44S.finditer(out))):
        if not re.search(r"[.;!?]\s+\S", out[: m.start()]):
            continue  # the first sentence: after what?
        out = out[: m.start()] + "afterwards" + out[m.end() :]
    if out == text:
        return text
    read = _reading(out, lexicon)
    if not isinstance(read, Group) or read.op != "seq":
        return text
    return out


# "Person A gets the bottle, Person B gets the chips, no fuss": 'no fuss' (as 'no rush') closing
# a request asks nothing.
_NO_FUSS44S = re.compile(
    r",?\s*(?:and )?no (?:fuss|bother|drama|faff|messing about)(?: (?:needed|required))?"
    r"(?P<end>\s*[.!]*)\s*$",
    _F,
)


def _no_fuss44s(text: str, lexicon: Lexicon) -> str:
    """Session 44 (12s): the closer above taken off, when it ends a request that reads."""
    if "no " not in text.lower():
        return text
    m = _NO_FUSS44S.search(text)
    if m is None or m.start() == 0:
        return text
    out = text[: m.start()] + (m["end"] or "").strip()
    return out if _reading(out, lexicon) is not None else text


# "Sam needs the red pen, Priya the notebook, just hand them over": a closing 'hand them over'
# after two or more handovers said to two or more people asks for those handovers.
_HAND_OVER44S = re.compile(
    r"[,;.]?\s*(?:so |just |then |and )*(?:hand|give|pass|dish) (?:them|those|these|both|"
    r"them both|the lot) (?:over|out|round|across)(?:,? please)?(?P<end>\s*[.!]*)\s*$",
    _F,
)


def _hand_over44s(text: str, lexicon: Lexicon) -> str:
    """Session 44 (12s): the closer above taken off, when what is left reads as handovers only,
    of two or more things to two or more people."""
    if "over" not in text.lower() and "out" not in text.lower() and "round" not in text.lower():
        return text
    m = _HAND_OVER44S.search(text)
    if m is None or m.start() == 0:
        return text
    out = text[: m.start()] + (m["end"] or "").strip()
    read = _reading(out, lexicon)
    if read is None:
        return text
    done = list(tasks(read))
    if any(t.kind != "deliver" for t in done) or len({t.target for t in done}) < 2:
        return text
    return out


# "Sam needs the red pen Priya the notebook": a want of one person, then straight on another
# person of the scene and a thing of it (the want gapped): a comma between.
_GAPPED44S = re.compile(
    rf"(?<=[a-z]) (?P<who>{_P42S}) (?P<x>(?:the|her|his|their) [a-z]+(?: [a-z]+)?)"
    r"(?=\s*(?:[,.;!]|$|\s+(?:and|just|so|then|please|too)\b))",
    _F,
)


def _gapped44s(text: str, lexicon: Lexicon) -> str:
    """Session 44 (12s): the comma above put in, when a want is said before, the word before is a
    thing of the scene, the person one of it and what is left reads giving them the thing."""
    if not _WANT_SAID41S.search(text):
        return text
    for m in _GAPPED44S.finditer(text):
        if not _only_person(m["who"], lexicon):
            continue
        before = text[: m.start()]
        if not before.split() or not _ids(before.split()[-1], lexicon, "object"):
            continue
        if not _WANT_SAID41S.search(before):
            continue
        x = re.sub(r"^(?:her|his|their)\b", "the", m["x"], flags=_F)
        if not _ids(x, lexicon, "object") or _ids(x, lexicon, "human"):
            continue
        out = before + "," + text[m.start() :]
        read = _reading(out, lexicon)
        if read is not None and _ids(m["who"], lexicon, "human") & {t.target for t in tasks(read)}:
            return out
    return text


# "Person A had a long night on ramp agent duty she'd like the bottle the chips can go to Person
# B": a remark about a person run on into their want ('she'd like', 'he wants', …) and into the
# next clause ('the chips can go to …') with no stops: a comma before each. The pronoun must fit
# the one person named before it (the older remark rules then read the commas).
_RUN_ON_PRON44S = re.compile(
    r"(?<=[a-z]) (?=(?:he|she)(?:'d like|'d love| would like| would love| wants| needs| could "
    r"use| could do with|'s after| is after)\b)",
    _F,
)
_RUN_ON_NEXT44S = re.compile(
    r"(?<=[a-z]) (?=(?:the|that|those|these) [a-z]+(?: [a-z]+)? (?:can go|goes|go|should go|is "
    r"going|are going|can have|is for|are for)\b)",
    _F,
)


_SAYING44S = frozenset(
    {
        "says",
        "said",
        "say",
        "thinks",
        "thought",
        "reckons",
        "reckoned",
        "mentioned",
        "told",
        "tells",
        "knows",
        "hopes",
        "feels",
        "believes",
        "guesses",
        "that",
        "claims",
        "swears",
    }
)


def _run_on_pronoun44s(text: str, lexicon: Lexicon) -> str:
    """Session 44 (12s): the commas above put in, when each pronoun fits the one person named
    before it, the word before the next clause is a thing of the scene, and what is left reads
    giving each person named something."""
    low = text.lower()
    if " he" not in low and " she" not in low:
        return text
    cuts: list[int] = []
    for m in _RUN_ON_PRON44S.finditer(text):
        people = [it for it in _names(text[: m.start()], lexicon) if _humans44s(it)]
        ids = {r.id for it in people for r in it.refs}
        if len(ids) != 1 or not _only_fit44s(next(iter(ids)), text[m.end() :].split()[0], lexicon):
            return text
        before = text[: m.start()].split()
        if before and before[-1].lower() in _SAYING44S:
            return text  # "Person A says she's after the bottle, …": what she says (session 28)
        want = re.match(
            r"\S+\s+(?:\S+\s+)?(?:after|like|love|use|with|wants|needs)\s+(\S+(?: \S+)?)",
            text[m.end() :],
            _F,
        )
        if want is None or not _ids(want[1], lexicon, "object"):
            return text  # "give the bottle to bob he's after it": what it wants is no thing said
        cuts.append(m.start())
    if not cuts:
        return text
    for m in _RUN_ON_NEXT44S.finditer(text, cuts[-1]):
        before = text[: m.start()].split()
        if before and _ids(before[-1], lexicon, "object"):
            cuts.append(m.start())
    out = text
    for at in sorted(cuts, reverse=True):
        out = out[:at] + "," + out[at:]
    read = _reading(out, lexicon)
    if read is None:
        return text
    named = {r.id for it in _names(text, lexicon) if _humans44s(it) for r in it.refs}
    if not named <= {t.target for t in tasks(read)}:
        return text
    return out


# "Mr Lee's finished his magazine. Mrs Khan wants it next. Take it to her.": one person done
# with a thing of the scene, then another who wants 'it' next: the thing is theirs now ("Mrs Khan
# wants the magazine.").
_DONE_NEXT44S = re.compile(
    rf"^(?P<p1>{_P42S})(?:'s| has| is) (?:finished|done|through)(?: with)? (?P<x>(?:his|her|"
    r"their|the|that) [a-z]+(?: [a-z]+)?)\s*[.;,]\s+(?P<p2>" + _P42S + r") (?P<want>wants|would "
    r"like|'d like|is after|'s after|can have|gets|needs) (?:it|that|that one) next\b",
    _F,
)


def _done_next44s(text: str, lexicon: Lexicon) -> str:
    """Session 44 (12s): the two sentences above said as the second's want of the thing, when
    both are people of the scene, the first's pronoun fits them, and what is left reads giving
    the thing to the second."""
    if "next" not in text.lower():
        return text
    m = _DONE_NEXT44S.match(text)
    if m is None or not _only_person(m["p1"], lexicon) or not _only_person(m["p2"], lexicon):
        return text
    if _ids(m["p1"], lexicon, "human") == _ids(m["p2"], lexicon, "human"):
        return text
    pron = re.match(r"(his|her|their) ", m["x"], _F)
    if pron and not _fits42s(m["p1"], pron[1], lexicon):
        return text
    x = re.sub(r"^(?:his|her|their|that)\b", "the", m["x"], flags=_F)
    if not _ids(x, lexicon, "object") or _ids(x, lexicon, "human") or _ids(x, lexicon, "surface"):
        return text
    out = f"{m['p2']} {m['want']} {x}{text[m.end() :]}"
    read = _reading(out, lexicon)
    done = list(tasks(read)) if read is not None else []
    if not done or any(t.target not in _ids(m["p2"], lexicon, "human") for t in done):
        return text
    return out


# -- session 44 (12s): remarks and asides beside a request ----------------------------------------
#
# "Alice has been stuck on an escalator callout all shift, so the bottle goes to her", "Person B's
# had a long turbine tech shift, the chips are his", "Person A did the whole steelpan set, give her
# the chips": what one person of the scene has done or been through (words naming nothing of the
# scene, wanting, negating, counting or pointing back at nothing; no time to come), then, after a
# comma (and 'so'), an order or a clause of who has what whose one pronoun fits them: their name
# said for the pronoun, the remark gone.
_OPENING44S = re.compile(
    rf"^(?:(?:poor|dear|little|old) )?(?P<who>{_P42S})(?P<words>(?:'s|\s)[^.;:!?,]{{2,80}}?)[,;]\s*"
    r"(?:and )?(?:so )?(?:be an? (?:sweetheart|dear|love|star|pal|gem|darling|angel|treasure|good "
    r"robot) and )?(?P<rest>(?:give|hand|pass|bring|take|get|fetch|let|send)\b[^.;:!?]*|"
    r"(?:the|that|this|those|these) [a-z]+(?: [a-z]+)?(?: goes to| go to| is for| are for| is| "
    r"are|'s|'re) [^.;:!?]*)(?P<end>[.!]?)\s*$",
    _F,
)
_SPELL44S = re.compile(
    r"\ball (?:day|morning|afternoon|evening|night|week|shift|session|lesson|set|match|game)"
    r"(?: long)?\b",
    _F,
)
_HER_OBJ44S = re.compile(
    r"\b(?:give|hand|pass|bring|get|fetch|let|send|to|for)\s+(?P<p>her|him)\b|\b(?P<q>his|"
    r"hers)\b|\b(?P<r>he|she)\b",
    _F,
)


def _opening_remark44s(text: str, lexicon: Lexicon) -> str:
    """Session 44 (12s): the opening remark above taken off and its person named for the one
    pronoun after it, when the pronoun fits them, nothing else names a person, and what is left
    reads giving them something."""
    m = _OPENING44S.match(text)
    if m is None or not _only_person(m["who"], lexicon):
        return text
    words = re.sub(r"^(?:'s|\s)\s*", "", m["words"])
    if len(words.split()) < 2:
        return text  # "Bob does, give him the chips" (causes8): does what? an answer to no one
    # "Zoe's got shodo practice after this, so give her …": when her practice is, not the task
    # (an order only); "Mr Novak's salad needs seasoning; …": the need of a thing of theirs
    if _ORDER41S.match(m["rest"]) and re.match(r"got ", words, _F):
        words = re.sub(
            r"\s+(?:after this|after that|later|later on|this afternoon|tonight)$",
            "",
            words,
            flags=_F,
        )
    words = re.sub(r"^([a-z]+) (?:needs|wants)\b", r"\1 lacks", words, flags=_F)
    if _LATER43S.search(words) or re.search(r"\b(?:will|'ll|going to|gonna)\b", words, _F):
        return text
    if not _remark_only42s(re.sub(r"\b(?:his|her|their)\b", "", _SPELL44S.sub("", words)), lexicon):
        return text
    rest = m["rest"]
    if _ids(rest, lexicon, "human") or len(_PRON43S.findall(rest)) != 1:
        return text
    p = _HER_OBJ44S.search(rest)
    if p is None:
        return text
    pron = p["p"] or p["q"] or p["r"]
    if not _agrees44s(m["who"], pron, lexicon):
        return text
    own = re.search(r"\b(?:his|her)\b", words, _F)
    if own and not _agrees44s(m["who"], own.group(0), lexicon):
        return text
    who = m["who"]
    said = f"{who}'s" if p["q"] else who
    at = p.start("p") if p["p"] else p.start()
    out = rest[:at] + said + rest[at + len(pron) :] + m["end"]
    out = out[:1].upper() + out[1:]
    read = _reading(out, lexicon)
    if read is None or not _ids(who, lexicon, "human") & {t.target for t in tasks(read)}:
        return text
    return out


# "our ramp agent keeps treading on the crisps, so stick them up on the shelf", "The cat keeps
# knocking the cup over, so put it on the shelf": what someone not of the scene keeps doing to
# one thing of it (the words naming no one of the scene), then 'so' and an order whose one
# it / them is that thing: the thing said for the pronoun, the remark gone.
_KEEPS_DOING44S = re.compile(
    r"^(?P<subj>(?:our|my|the|a|some|that|this|these|those) [a-z][a-z ]{0,30}?|people|someone|"
    r"somebody|everyone|everybody|folk|they) keeps? (?P<doing>[a-z]+ing\b[^.;:!?,]{0,60}?),?\s+"
    r"so\s+(?P<rest>(?:please |just |can you |could you |would you )?(?:put|stick|pop|place|set|"
    r"move|shift|leave|get|take|give|hand|pass|bring|lay|stand|hang|drop|tuck|stash)\b[^.;:!?]*)"
    r"(?P<end>[.!]?)\s*$",
    _F,
)


def _keeps_doing44s(text: str, lexicon: Lexicon) -> str:
    """Session 44 (12s): the remark above taken off and its thing said for the order's pronoun,
    when the subject names nothing of the scene, the doing names one thing of it (objects only),
    the order has one it / them fitting that thing's number, and what is left reads."""
    if "keep" not in text.lower():
        return text
    m = _KEEPS_DOING44S.match(text)
    if m is None or _names(m["subj"], lexicon):
        return text
    said = _names(m["doing"], lexicon)
    if len(said) != 1 or any(r.kind != "object" for r in said[0].refs):
        return text
    prons = re.findall(r"\b(?:it|them)\b", m["rest"], _F)
    if len(prons) != 1:
        return text
    thing = said[0].text
    plural = len({r.id for r in said[0].refs}) > 1 or thing.lower().endswith("s")
    if plural != (prons[0].lower() == "them"):
        return text
    x = re.search(
        rf"(?:(?:the|that|this|those|these|my|our|his|her|their) )?{re.escape(thing)}",
        m["doing"],
        _F,
    )
    if x is None:
        return text
    obj = re.sub(
        r"^(?:my|our|his|her|their|that|this|those|these)\b",
        "the",
        x.group(0),
        flags=_F,
    )
    if not obj.lower().startswith("the "):
        obj = f"the {obj}"
    rest = re.sub(r"\b(?:it|them)\b", obj, m["rest"], count=1, flags=_F)
    out = rest[:1].upper() + rest[1:] + m["end"]
    return out if _reading(out, lexicon) is not None else text


# "Drop the stapler into the box, people keep walking off with it", "… on the shelf, the kids
# keep knocking it over": why a thing goes where it goes, said of people not of the scene, after
# a request that places everything it names: taken off (as session 43's `_placed_aside43s`).
_KEEP_TAKING44S = re.compile(
    r"(?P<sep>\s*[,;]\s*|\s+(?:as|because|cos|since)\s+)(?P<subj>(?:people|someone|somebody|"
    r"everyone|everybody|folk|they|(?:the|our|my|those|these) [a-z]+(?: [a-z]+)?)) (?:keeps?|"
    r"always|are always|is always) [a-z]+ing\b(?P<words>[^.;:!?,]{0,40}?)(?P<end>\s*[.!]*)\s*$",
    _F,
)


def _keep_taking44s(text: str, lexicon: Lexicon) -> str:
    """Session 44 (12s): the closing reason above taken off, when it names nothing of the scene
    and what is left reads as placements only."""
    if "keep" not in text.lower() and "always" not in text.lower():
        return text
    m = _KEEP_TAKING44S.search(text)
    if m is None or m.start() == 0:
        return text
    if _names(m["subj"], lexicon) or _names(m["words"], lexicon):
        return text
    out = text[: m.start()] + (m["end"] or "").strip()
    read = _reading(out, lexicon)
    if read is None or any(t.kind != "place" for t in tasks(read)):
        return text
    return out


# "Emma skipped breakfast and asked if she could have the banana", "Tom lost his gloves and
# needs the work gloves": a past doing of the person's (a verb in -ed or a few others), then
# 'and' and their want: said with 'has' ("Emma's skipped breakfast and …"), which the older
# remark rules read (session 42's `_state_and42s`).
_PAST_AND44S = re.compile(
    rf"^(?P<who>{_P42S}) (?P<verb>[a-z]+ed|had|did|got|lost|ate|went|spent|left|forgot|broke|"
    r"tore|fell|ran|came|slept|woke|bought|made|took)(?= [^.;:!?]*?,?\s+and\s+(?:asked|wants|"
    r"needs|would|could|'d|is|'s|has))",
    _F,
)
_PARTICIPLE44S = {
    "did": "done",
    "ate": "eaten",
    "went": "been",
    "broke": "broken",
    "tore": "torn",
    "fell": "fallen",
    "ran": "run",
    "came": "come",
    "woke": "woken",
    "took": "taken",
}


def _past_and44s(text: str, lexicon: Lexicon) -> str:
    """Session 44 (12s): the past doing above said with 'has', when the person is one of the
    scene and what is left reads giving them something."""
    if " and " not in text.lower():
        return text
    m = _PAST_AND44S.match(text)
    if m is None or not _only_person(m["who"], lexicon) or m["verb"].lower() in _NOT_PAST44S:
        return text
    verb = _PARTICIPLE44S.get(m["verb"].lower(), m["verb"])
    out = f"{m['who']} has {verb}{text[m.end() :]}"
    read = _reading(out, lexicon)
    if read is None or not _ids(m["who"], lexicon, "human") & {t.target for t in tasks(read)}:
        return text
    return out


# not a want's words, and not a spill (engineer 12's session-44 `_spilt44` reads "Omar spilled his
# soup and wants the spoon")
_NOT_PAST44S = frozenset(
    {
        "need",
        "needed",
        "wanted",
        "asked",
        "red",
        "bed",
        "shed",
        "fed",
        "spilled",
        "spilt",
        "knocked",
        "splashed",
        "slopped",
        "dropped",
        "tipped",
        "upset",
    }
)


# "… and asked if she could have the banana": her asking for it ('asked for'), when she is the one
# person named before it (session 14's `_wrappers` says it so after the older rules have run).
_ASKED_IF44S = re.compile(
    r"\basked (?:if|whether) (?P<p>he|she) (?:could|can|might|may) (?:have|get|borrow|take) ",
    _F,
)


def _asked_if44s(text: str, lexicon: Lexicon) -> str:
    """Session 44 (12s): 'asked if she could have' said as 'asked for', when the pronoun fits the
    one person named before it and what is left reads giving them something."""
    if "asked" not in text.lower():
        return text
    m = _ASKED_IF44S.search(text)
    if m is None:
        return text
    people = {r.id for it in _names(text[: m.start()], lexicon) if _humans44s(it) for r in it.refs}
    if len(people) != 1 or not _fit36(next(iter(people)), m["p"], lexicon):
        return text
    out = text[: m.start()] + "asked for " + text[m.end() :]
    read = _reading(out, lexicon)
    if read is None or not people & {t.target for t in tasks(read)}:
        return text
    return out


# "Lily won't settle for her nap without the teddy", "Noah can't draw without the ruler": what
# the person cannot do without a thing of the scene is their need of it: "<person> needs <it>".
_WITHOUT44S = re.compile(
    rf"^(?P<who>{_P42S}) (?:won't|will not|can't|cannot|can not|wouldn't|would not|couldn't|"
    r"could not|never) (?P<doing>[a-z]+(?: [a-z]+){0,5}?) without (?P<x>(?:the|her|his|their) "
    r"[a-z]+(?: [a-z]+)?)(?P<end>\s*[.!]*)\s*$",
    _F,
)


def _without44s(text: str, lexicon: Lexicon) -> str:
    """Session 44 (12s): the need above said plainly, when the person is one of the scene, the
    doing names nothing of it, his / her fit the person, the thing is objects of it only, and it
    reads."""
    if "without" not in text.lower():
        return text
    m = _WITHOUT44S.match(text)
    if m is None or not _only_person(m["who"], lexicon):
        return text
    doing = m["doing"]
    if not _remark_only42s(re.sub(r"\b(?:his|her|their)\b", "", doing, flags=_F), lexicon):
        return text
    for pron in re.findall(r"\b(?:his|her)\b", f"{doing} {m['x']}", _F):
        if not _agrees44s(m["who"], pron, lexicon):
            return text
    x = re.sub(r"^(?:his|her|their)\b", "the", m["x"], flags=_F)
    if not _ids(x, lexicon, "object") or _ids(x, lexicon, "human") or _ids(x, lexicon, "surface"):
        return text
    out = f"{m['who']} needs {x}{m['end']}"
    read = _reading(out, lexicon)
    if read is None or not _ids(m["who"], lexicon, "human") & {t.target for t in tasks(read)}:
        return text
    return out


# "Sorry to be a pest, Omar's back from rug hooking club and would like the white cup": an
# apology for asking, opening the instruction, asks nothing; taken off before the other rules
# look for what opens it (session 14's courtesy list takes it off after them).
_SORRY44S = re.compile(
    r"^(?:(?:oh|so|right|hi|hello|hey|um|erm),?\s+)?(?:i'm |i am )?(?:so |really |very |terribly "
    r"|awfully |ever so )?sorry (?:to (?:be (?:a |such a )?(?:pest|pain|nuisance|bother)|bother "
    r"you|trouble you|interrupt|ask|nag|hassle you|disturb you)(?: again)?|for (?:the bother|"
    r"bothering you|interrupting|asking|the interruption))\s*[,.!;]+\s*(?:but\s+)?(?=\S)",
    _F,
)


def _opening_sorry44s(text: str, lexicon: Lexicon) -> str:
    """Session 44 (12s): the apology above taken off, when what is left reads."""
    if "sorry" not in text[:40].lower():
        return text
    m = _SORRY44S.match(text)
    if m is None:
        return text
    out = text[m.end() :]
    out = out[:1].upper() + out[1:]
    return out if _reading(out, lexicon) is not None else text


# "Right, erm, before my fibre splicer shift starts, pop the crisps up on the shelf": the time of
# the speaker's own coming doing, before which the task is to be done: done now, it is met; taken
# off (a time that puts the task off stays refused: "after my shift starts").
_BEFORE_MINE44S = re.compile(
    r"(?:^|(?<=, )|(?<=[.;!?] ))before (?:my|our|the) (?P<words>[a-z][a-z -]{1,40}?) (?:starts|"
    r"begins|kicks off|gets going|is on|opens)\s*,\s*",
    _F,
)


def _before_mine44s(text: str, lexicon: Lexicon) -> str:
    """Session 44 (12s): the time above taken off, when its words name nothing of the scene and
    what is left reads."""
    if "before" not in text.lower():
        return text
    m = _BEFORE_MINE44S.search(text)
    if m is None or not _remark_only42s(m["words"], lexicon):
        return text
    out = text[: m.start()] + text[m.end() :]
    if m.start() == 0:
        out = out[:1].upper() + out[1:]
    return out if _reading(out, lexicon) is not None else text


# "Morning Mia! Um, so, the packing tape onto the conveyor, lovely, ta.": the speaker greeting a
# person of the scene, then a request to the robots that speaks to no one and points at no one
# ('you', he / she): the greeting asks nothing; taken off.
_GREETING44S = re.compile(
    rf"^(?:good )?(?:morning|afternoon|evening|hi|hello|hey|hiya|howdy|alright|all right|cheers)"
    rf",? (?P<who>{_P42S})\s*[!.,]+\s+(?P<rest>\S.*)$",
    _F,
)


def _greeting44s(text: str, lexicon: Lexicon) -> str:
    """Session 44 (12s): the greeting above taken off (above), when what is left reads."""
    m = _GREETING44S.match(text)
    if m is None or not _only_person(m["who"], lexicon):
        return text
    rest = m["rest"]
    if re.search(r"\b(?:you|your|yours|he|she|him|her|his|hers)\b", rest, _F):
        return text
    out = rest[:1].upper() + rest[1:]
    return out if _reading(out, lexicon) is not None else text


# "Person A's after the chips; Person B, back from his rice paddy survey, the cup.": where the
# person has just come from (or is off to), said between commas after their name: taken off.
_BACK_FROM44S = re.compile(
    rf"(?P<who>{_P42S}),\s*(?:just |fresh )?(?:back from|in from|home from|fresh from|off to|"
    r"on (?:his|her) way to|straight from) (?P<pron>his|her) (?P<words>[a-z][a-z -]{1,40}?),\s*",
    _F,
)


def _back_from44s(text: str, lexicon: Lexicon) -> str:
    """Session 44 (12s): the aside above taken off, when his / her fits the person, the words
    name nothing of the scene, and what is left reads giving them something."""
    if "from" not in text.lower() and "off to" not in text.lower():
        return text
    m = _BACK_FROM44S.search(text)
    if m is None or not _only_person(m["who"], lexicon):
        return text
    if not _agrees44s(m["who"], m["pron"], lexicon) or not _remark_only42s(m["words"], lexicon):
        return text
    out = text[: m.end("who")] + ", " + text[m.end() :]
    read = _reading(out, lexicon)
    if read is None or not _ids(m["who"], lexicon, "human") & {t.target for t in tasks(read)}:
        return text
    return out


# "Kofi's cleared a space on the workbench. Put the drill there.": someone has made room on a
# surface of the scene, then a placement 'there': on that surface.
_SPACE_ON44S = re.compile(
    rf"^(?P<who>{_P42S}|i|we|someone|somebody)(?:'s|'ve| has| have) (?:cleared|made|freed up|"
    r"found|left|got) (?:a |some )?(?:space|room|spot|gap|a bit of room)(?: for (?:it|them))? "
    r"(?P<prep>on|in|at) (?P<s>(?:the|that) [a-z]+(?: [a-z]+)?)\s*[.;,]\s+(?P<rest>[^.;!?]*"
    r"\bthere\b[^.;!?]*)(?P<end>[.!]?)\s*$",
    _F,
)


def _space_on44s(text: str, lexicon: Lexicon) -> str:
    """Session 44 (12s): the two sentences above said as the placement on the surface, when the
    surface is one of the scene and what is left reads placing things there only."""
    if "there" not in text.lower():
        return text
    m = _SPACE_ON44S.match(text)
    if m is None:
        return text
    surf = _ids(m["s"], lexicon, "surface")
    if len(surf) != 1 or _ids(m["s"], lexicon, "object") or _ids(m["s"], lexicon, "human"):
        return text
    if m["who"].lower() not in ("i", "we", "someone", "somebody") and not _only_person(
        m["who"], lexicon
    ):
        return text
    noun = re.sub(r"^(?:the|that) ", "", m["s"], flags=_F)
    prep = "in" if m["prep"].lower() == "in" else "on"
    rest = re.sub(
        r"\b(?:over |up |down )?there\b",
        f"{prep} the {noun}",
        m["rest"],
        count=1,
        flags=_F,
    )
    out = rest[:1].upper() + rest[1:] + m["end"]
    read = _reading(out, lexicon)
    if read is None or any(t.kind != "place" or t.target not in surf for t in tasks(read)):
        return text
    return out


# "Grandad's reading to Lily; give him the teddy, he'll do the voices": what the one the order
# names by a pronoun will do with it (he'll / she'll + words naming nothing of the scene), the
# same pronoun as the order's: taken off, so session 43's doer rule sees the order alone.
_WILL_DO44S = re.compile(
    r"(?P<pre>\b(?P<p1>him|her)\b[^.;:!?,]*),\s*(?P<p2>he|she)(?:'ll| will) (?P<words>[a-z]"
    r"[a-z ]{1,40}?)(?P<end>\s*[.!]*)\s*$",
    _F,
)


def _will_do44s(text: str, lexicon: Lexicon) -> str:
    """Session 44 (12s): the closing remark above taken off, when its pronoun is of the order's
    pronoun's sex, its words name nothing of the scene and what is left reads."""
    if "'ll" not in text and " will " not in text.lower():
        return text
    m = _WILL_DO44S.search(text)
    if m is None or PRONOUN_SEX[m["p1"].lower()] != PRONOUN_SEX[m["p2"].lower()]:
        return text
    if not _remark_only42s(m["words"], lexicon):
        return text
    out = text[: m.end("pre")] + (m["end"] or "").strip()
    return out if _reading(out, lexicon) is not None else text


# "Those crisps? Alice has been after them, so over to her they go.": 'over to <her> they go' is
# the order to take them to her ("give them to her").
_OVER_THEY_GO44S = re.compile(
    rf"\b(?:over|across|off|up) (?:to|for) (?P<who>her|him|{_P42S}) (?P<pron>it|they|that|those|"
    r"these|the lot) go(?:es)?\b",
    _F,
)


def _over_they_go44s(text: str, lexicon: Lexicon) -> str:
    """Session 44 (12s): the order above said plainly, when what is left reads."""
    if " go" not in text.lower():
        return text
    m = _OVER_THEY_GO44S.search(text)
    if m is None or m.start() == 0:
        return text
    who = m["who"]
    if who.lower() in ("her", "him"):
        people = [it for it in _names(text[: m.start()], lexicon) if _humans44s(it)]
        ids = {r.id for r in people[-1].refs} if people else set()
        if len(ids) != 1 or not _agrees44s(people[-1].text, who, lexicon):
            return text  # "Noah's after the globe, so over to her it goes": someone else
    elif not _only_person(who, lexicon):
        return text
    them = "it" if m["pron"].lower() in ("it", "that") else "them"
    out = text[: m.start()] + f"give {them} to {who}" + text[m.end() :]
    return out if _reading(out, lexicon) is not None else text


# "Would you mind dropping the spoon in the sink? Emma's finished her tea.", "Could you hang the
# tongs on the plate rack, Marco's done with them?": that someone of the scene is done with what
# is put away, closing a request that places everything it names: why, taken off.
_DONE_WITH44S = re.compile(
    rf"(?P<sep>\s*[,;.?!]\s*|\s+(?:as|because|since|cos)\s+)(?P<who>{_P42S})(?:'s| has| is) "
    r"(?:finished|done|through)(?: with)? (?P<what>it|them|that|those|(?:his|her|their|the) "
    r"[a-z][a-z ]{0,30}?)(?P<end>\s*[.!?]*)\s*$",
    _F,
)


def _done_with44s(text: str, lexicon: Lexicon) -> str:
    """Session 44 (12s): the closing remark above taken off, when the person is one of the scene,
    his / her fit them, and what is left reads as placements only."""
    if "finished" not in text.lower() and "done" not in text.lower():
        return text
    m = _DONE_WITH44S.search(text)
    if m is None or m.start() == 0 or not _only_person(m["who"], lexicon):
        return text
    pron = re.match(r"(his|her) ", m["what"], _F)
    if pron and not _agrees44s(m["who"], pron[1], lexicon):
        return text
    words = re.sub(r"^(?:his|her|their|the) ", "", m["what"], flags=_F)
    if words.lower() not in ("it", "them", "that", "those") and _names(words, lexicon):
        return text
    end = "?" if "?" in (m["end"] or "") or m["sep"].strip() == "?" else "."
    out = text[: m.start()] + end
    read = _reading(out, lexicon)
    if read is None or any(t.kind != "place" for t in tasks(read)):
        return text
    return out


# -- session 44 (12s): the speaker did not see which ---------------------------------------------
#
# "Give Person B the one he pointed at earlier, the cup or the bottle, I didn't see which": as
# session 39's "I can't remember which" (`doubt_which39`), the speaker does not know which of two
# things is meant: refused naming both readings (it had been refused on 'I', naming none).
_UNSEEN44S = re.compile(
    r"(?<=\bI )(?:didn't|did not|couldn't|could not|can't|cannot|wasn't able to|never) (?:see|"
    r"catch|notice|spot|hear|make out|tell|quite see)(?: properly| exactly)?(?= which\b)",
    _F,
)


def unseen_which44s(text: str, lexicon: Lexicon) -> None:
    """Session 44 (12s): the doubt above asked as session 39's `doubt_which39` asks "I can't
    remember which" (its refusal names both things), the speaker's own words quoted."""
    if "which" not in text.lower():
        return
    m = _UNSEEN44S.search(text)
    if m is None:
        return
    said = text[: m.start()] + "can't remember" + text[m.end() :]
    try:
        doubt_which39(said, lexicon)
    except GroundingError as refused:
        raise GroundingError(str(refused).replace("can't remember", m.group(0), 1)) from None


# the normaliser's rewrites run before the session-43 ones (wired into normalise._STEPS19)
_STEPS44S_FIRST: tuple[Callable[[str, Lexicon], str], ...] = (
    _opening_sorry44s,
    _before_mine44s,
    _greeting44s,
    _back_from44s,
    _space_on44s,
    _will_do44s,
    _over_they_go44s,
    _done_with44s,
    _if_spare44s,
    _shelve44s,
    _after_her44s,
    _surface_first44s,
    _want_so44s,
    _after_end44s,
    _no_fuss44s,
    _hand_over44s,
    _gapped44s,
    _run_on_pronoun44s,
    _done_next44s,
    _opening_remark44s,
    _keeps_doing44s,
    _keep_taking44s,
    _asked_if44s,
    _past_and44s,
    _without44s,
)
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-43 ones)
_STEPS44S: tuple[Callable[[str, Lexicon], str], ...] = ()
# refusals asked of the text before it is read (offline._parse, after the session-43 ones)
REFUSE44S: tuple[Callable[[str, Lexicon], None], ...] = (unseen_which44s,)
# checks of the whole instruction's reading (offline.parse_instruction, after the session-43 ones)
CHECK44S: tuple[Callable[[str, Node, Lexicon], None], ...] = ()
