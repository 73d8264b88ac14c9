"""The grounder's rules of session 42, engineer 12r (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _ids, _only, _only_person, _reading
from hltl.grounding._normalise3 import _whole_name
from hltl.grounding._rewrites40r import _capital40r
from hltl.grounding.lexicon import (
    PRONOUN_SEX,
    Lexicon,
    first_name_sex36s,
    person_name,
    said_sex35s,
)
from hltl.grounding.phrasing import starting_on
from hltl.grounding.tree import Node, has_choice, tasks

# a person's name as these rules take it (checked against the scene after the match)
_WHO42R = r"(?:person [a-z]|(?:mr|mrs|ms|miss|dr) [a-z]+|[a-z]+)"
# an object's name as these rules take it (checked against the scene after the match)
_THING42R = (
    r"(?:the|that|this|those|these) [a-z]+(?: (?!(?:at|all|today|really|then|now|either|anymore|"
    r"any|after|this|for|to|that|which|who|is|are|was|were|isn|aren)\b)[a-z]+)?"
)
# what a thing said of one already named may be: a name, or 'the <adj> one' / 'the other one'
_ONE42R = r"(?:the|that|this) (?:[a-z]+ )?one"


def _the42r(words: str) -> str:
    """``words`` with 'that' / 'this' / 'those' / 'these' said as 'the'."""
    return re.sub(r"^(?:that|this|those|these) ", "the ", words.strip(), flags=_F)


def _fits42r(pid: str, pronoun: str, lexicon: Lexicon) -> bool:
    """Whether ``pronoun`` (he / she / him / her) may be person ``pid``."""
    pro = pronoun.lower()
    if pro not in PRONOUN_SEX:
        return True
    sex = said_sex35s(pid, lexicon) or first_name_sex36s(pid, lexicon)
    return sex is None or sex == PRONOUN_SEX[pro]


def _person42r(words: str, lexicon: Lexicon) -> str | None:
    """The id of the one person ``words`` names whole, or None."""
    if not _only_person(words.strip(), lexicon):
        return None
    (pid,) = _ids(words, lexicon, "human")
    return pid


def _thing42r(words: str, of: str | None, lexicon: Lexicon) -> str | None:
    """``words`` as one whole name of one object ('the X'), or, said after object ``of`` was
    named, 'the <adj> one' as the object of that kind with that adjective, 'the other one' as
    the other object of its kind when there are two; None otherwise."""
    words = _the42r(words)
    if _whole_name(words, lexicon, "object") and len(_ids(words, lexicon, "object")) == 1:
        return words
    if of is None:
        return None
    m = re.fullmatch(r"the (?:(?P<adj>[a-z]+) )?one", words, _F)
    kind_of = [o.category for o in lexicon.scene.objects if {o.id} == _ids(of, lexicon, "object")]
    if m is None or len(kind_of) != 1:
        return None
    kind = kind_of[0]
    if m["adj"] is None or m["adj"].lower() == "other":
        (xid,) = _ids(of, lexicon, "object")
        rest = [o.id for o in lexicon.scene.objects if o.category == kind and o.id != xid]
        if m["adj"] is None or len(rest) != 1:
            return None
        names = _names42r(rest[0], lexicon)
        return f"the {names[0]}" if names else None
    said = f"the {m['adj']} {kind}"
    return said if _only(said, lexicon, "object") else None


def _names42r(oid: str, lexicon: Lexicon) -> list[str]:
    """The names of object ``oid`` that name it alone in the scene."""
    obj = next(o for o in lexicon.scene.objects if o.id == oid)
    return [a for a in (*obj.aliases, obj.id) if _only(f"the {a}", lexicon, "object")]


# -- negation and exclusion ------------------------------------------------------------------------

# a person's not wanting, or not being meant to have, a thing, said of the person
_NEG_VERB42R = (
    r"(?:(?:'s| is) not after| isn't after| is not after| (?:doesn't|does not|won't|will not|"
    r"wouldn't|would not) (?:want|need|fancy|like)|(?:'s| is) not to (?:have|get)| isn't to "
    r"(?:have|get)|(?:'s| is) not (?:having|getting)| isn't (?:having|getting)| (?:can|could) "
    r"(?:do|manage) without|(?:'s| is) not keen on| isn't keen on| has no (?:use|need) for)"
)
_INTENSE42R = (
    r"(?: at all| today| really| any more| anymore| now| after all| this time| either| thanks)?"
)
# "Bob isn't after the crisps at all", "The bottle's no good to Alice", "It was never the cup for
# Person A", "The chips aren't Person A's to have"
_NEG_HEAD42R = (
    rf"(?:(?P<p>{_WHO42R})(?: (?:says|said|reckons|tells me|told me|mentioned)(?: that)? "
    rf"(?P<pro0>he|she))?{_NEG_VERB42R} (?P<x>{_THING42R})"
    rf"|(?P<x2>{_THING42R})(?:'s| is| are|'re| was| were) (?:no|not any|not much|never any) "
    rf"(?:good|use) (?:to|for) (?P<p2>{_WHO42R})"
    rf"|(?P<x3>{_THING42R})(?: isn't| aren't| is not| are not|'s not|'re not| was never| were "
    r"never|'s never| is never| are never| wasn't| weren't)(?: meant)? (?:for "
    rf"(?P<p3>{_WHO42R})|(?P<p4>{_WHO42R})'s(?: to (?:have|keep|take))?)"
    r"|it(?: was never|'s never| is never| wasn't| isn't|'s not| is not)(?: meant to be)? "
    rf"(?P<x5>{_THING42R}) for (?P<p5>{_WHO42R}))"
    rf"{_INTENSE42R}"
)
# a reason between the two ("it's chipped", "she's brought her own"): checked to name nothing
_WHY42R = (
    r"(?:\s*[,;]\s*(?P<why>(?:it's|it is|they're|they are|she's|he's|she has|he has|it has|"
    r"they've|they have)(?: [a-z']+){1,4}))?"
)
_PRO42R = r"(?:he|she|him|her)"
# the thing the person does want, said after ("it's the bottle he wants", "the crisps then")
_WANTED42R = (
    r"(?:it(?:'s| is) (?P<y1>{T}) (?:that |which )?(?P<w1>{W}) (?:wants|needs|(?:'s|is) after|"
    r"(?:'s|is) having|'d like|would like|asked for|'s asked for|fancies|(?:'s|is) getting|should "
    r"(?:get|have)|'ll have|will have|(?:'s|is) meant to (?:get|have)|(?:'s|is) wanting)"
    r"|(?P<y2>{T})(?:'s| is) (?:what|all) (?P<w2>{W})(?:'s| is)? (?:after|having|getting|wants|"
    r"needs|wanted|asked for|'d like|would like|fancies|should get|should have)"
    r"|(?:just )?(?P<y3>{T})(?: then| instead| please)+"
    r"|(?P<w4>{W}) (?:wants|needs|'d like|would like|(?:'s|is) after|'ll have|will have|can have|"
    r"gets|(?:'s|is) getting|(?:'s|is) having|should (?:get|have)) (?P<y4>{T})(?: instead)?"
    r"|(?:give|pass|hand|bring|take|get) (?P<w5>him|her|{W}) (?P<y5>{T})(?: instead)?)"
)
# the thing going to another person instead ("they're going to Person B", "it's Noah's turn")
_ELSEWHERE42R = (
    rf"(?:(?:it's|it is|they're|they are) (?:going|headed|off|to go) to (?P<q1>{_WHO42R})"
    rf"|(?:it's|it is|they're|they are) (?:for (?P<q2>{_WHO42R})|(?P<q3>{_WHO42R})'s"
    r"(?: to have)?)"
    rf"|it(?:'s| is) (?P<q4>{_WHO42R})'s (?:turn|go)(?: today| now| this time)?"
    rf"|(?P<q5>{_WHO42R}) (?:gets|can have|is having|'s having|should (?:have|get)|'ll have|will "
    r"have|is getting|'s getting) (?:it|them)(?: instead)?)"
)
_NEG_THEN42R = (
    rf"^(?P<head>{_NEG_HEAD42R}){_WHY42R}\s*[,;:.]\s*(?:so |but |then |instead )?"
    rf"(?:{_WANTED42R.format(T=f'{_THING42R}|{_ONE42R}', W=f'{_PRO42R}|{_WHO42R}')}"
    rf"|{_ELSEWHERE42R})(?:,? (?:please|thanks|then|instead|thank you|cheers))?(?P<end>\s*[.!]?)$"
)


def negated_head42r(said: str) -> bool:
    """Session 42 (12r): whether ``said`` (what comes before a cleft: "Bob isn't after the
    crisps at all;") only says a person does not want a thing, so that the cleft after it
    ("it's the bottle he wants") says what is wanted instead (session 31's refusal of a cleft
    after a request, offline._parse, asks this; `_negated_then42r` reads the two together)."""
    # session 43 (12r): not wanting said as an idiom ("has gone off X"), and a list of things
    # not wanted ("has no use for the cup or the apple")
    # why: _rewrites43r imports this module, so it is imported where it is used
    from hltl.grounding._rewrites43r import said_as_not_wanted43r

    said = re.sub(
        r"(\bthe [a-z]+)(?:(?:,| or| and| nor) the [a-z]+)+(?=\s*[,;:.]\s*$)",
        r"\1",
        said,
        flags=_F,
    )
    said = said_as_not_wanted43r(said)
    return re.match(rf"^\s*{_NEG_HEAD42R}{_WHY42R}\s*[,;:.]\s*$", said, _F) is not None


def _negated_then42r(text: str, lexicon: Lexicon) -> str:
    """Session 42 (12r): a person's not wanting, or not being meant to have, a thing ("P isn't
    after X (at all)", "P won't want X", "P can do without X", "P's not to have X", "X's no good
    to P", "X aren't P's to have", "It was never X for P", "P says he can do without X"), then
    (after a reason that names nothing: "it's chipped") what is meant instead, is read whole:
    the thing P does want ("it's Y he wants", "Y's what she's having", "Y's all he's after", "Y
    then", "pass her the green one") is "P wants Y, not X"; the thing going to another person
    ("they're going to Q", "it's Q's turn", "Q gets it") is "Give X to Q, not P". X, Y objects
    named whole (Y 'the <adj> one' / 'the other one' of X's kind), a pronoun fitting P."""
    low = text.lower()
    if not any(w in low for w in ("not", "n't", "never", "without", " no ")):
        return text
    m = re.match(_NEG_THEN42R, text.strip(), _F)
    if m is None:
        return text
    who = next(w for w in (m["p"], m["p2"], m["p3"], m["p4"], m["p5"]) if w)
    what = next(w for w in (m["x"], m["x2"], m["x3"], m["x5"]) if w)
    pid = _person42r(who, lexicon)
    x = _thing42r(what, None, lexicon)
    if pid is None or x is None:
        return text
    if m["pro0"] and not _fits42r(pid, m["pro0"], lexicon):
        return text
    if m["why"] and _ids(m["why"], lexicon):
        return text
    end = m["end"] or "."
    q = next((w for w in (m["q1"], m["q2"], m["q3"], m["q4"], m["q5"]) if w), None)
    if q is not None:
        qid = _person42r(q, lexicon)
        if qid is None or qid == pid:
            return text
        out = f"Give {x} to {q}, not {who}{end}"
    else:
        said_y = next(w for w in (m["y1"], m["y2"], m["y3"], m["y4"], m["y5"]) if w)
        whom = next((w for w in (m["w1"], m["w2"], m["w4"], m["w5"]) if w), None)
        y = _thing42r(said_y, x, lexicon)
        if y is None or _ids(y, lexicon, "object") == _ids(x, lexicon, "object"):
            return text
        if whom is not None and whom.lower() in PRONOUN_SEX:
            if not _fits42r(pid, whom, lexicon):
                return text
        elif whom is not None and _person42r(whom, lexicon) != pid:
            return text
        out = f"{who} wants {y}, not {x}{end}"
    return out if _reading(out, lexicon) is not None else text


# "Not the red pen and not the blue; Sam gets the black one." (session 44, lead: a bare comma
# between two things is no list of things left out: "Not the apple, the cup, and it's for Alice.
# Alice wouldn't say no to the crisps." had read chips>A, the cup dropped, 12c's fuzz; "…, not …"
# and "…, nor …" are)
_NOT_LIST42R = (
    rf"^(?:not|never mind|forget(?: about)?) (?P<x>{_THING42R})(?P<more>(?:(?:\s*(?:and|or|nor|, "
    rf"and|, or|, nor)\s*(?:not )?|\s*,\s*not )(?:{_THING42R}|the [a-z]+))*)\s*[;:,.]\s*"
    r"(?P<rest>\S.*?)"
    r"(?P<end>\s*[.!]?)$"
)


def _not_list_first42r(text: str, lexicon: Lexicon) -> str:
    """Session 42 (12r): objects left out said first, one or several ("Not X and not Y; <request>",
    "Not X, nor Y: …", the second maybe said by its adjective alone: 'not the blue' after 'the
    red pen'), then a request that names none of them, is "<request>, not X or Y" (the grammar's
    leaving out, checked by it)."""
    if not re.match(r"^\s*(?:not|never mind|forget)\b", text, _F):
        return text
    m = re.match(_NOT_LIST42R, text.strip(), _F)
    if m is None:
        return text
    x = _thing42r(m["x"], None, lexicon)
    if x is None:
        return text
    if re.search(r",\s*(?!(?:and|or|nor|not)\b)\S[^,]*$", m["more"] or "", _F):
        # session 44 (12r): "Not X, Y, (oh, and Z) for P" closes on a thing after a bare comma:
        # Y in X's place (a correction), not a second thing left out
        return text
    out_of = [x]
    for said in re.findall(rf"(?:not )?((?:{_THING42R})|the [a-z]+)", m["more"] or "", _F):
        y = _thing42r(said, None, lexicon)
        if y is None:
            # 'the blue' after 'the red pen': the adjective with the first one's kind
            kinds = {o.category for o in lexicon.scene.objects if o.id in _ids(x, lexicon)}
            adj = _the42r(said).removeprefix("the ")
            y = next(
                (f"the {adj} {k}" for k in kinds if _only(f"the {adj} {k}", lexicon, "object")),
                None,
            )
        if y is None:
            return text
        out_of.append(y)
    ids = [_ids(w, lexicon, "object") for w in out_of]
    rest = m["rest"]
    if len(set().union(*ids)) != len(out_of) or set().union(*ids) & _ids(rest, lexicon):
        return text
    if re.match(r"(?:but )?it(?:'s| is) ", rest, _F):
        return text  # "Not X, it's Y P wants" is session 41's (`_not_its41r`)
    out = f"{_capital40r(rest)}, not {' or '.join(out_of)}{m['end'] or '.'}"
    return out if _reading(out, lexicon) is not None else text


# "Apart from the bottle, everything on offer goes to Person B."; "Leave the chips alone;
# anything besides them is Person A's."
_ALL_BUT_FIRST42R = (
    rf"^(?:(?:apart from|except for|other than|aside from|besides|bar|save for|excepting) "
    rf"(?P<x>{_THING42R}(?:(?:,| and) {_THING42R})*)\s*,|leave (?P<x2>{_THING42R}(?:(?:,| and) "
    rf"{_THING42R})*) (?:alone|be|out(?: of it)?|aside|where (?:it is|they are))\s*[;,.:])\s*"
    r"(?:(?:everything|anything)(?: else)?|all the rest|the rest|all the other things|all the "
    r"others)(?: (?:besides|but|except|other than) (?:it|them|that|those))?(?: (?:on offer|here|"
    r"going|left|in the room|there is|you've got|we've got))?\s*(?:(?:goes|can go|should go|is "
    rf"going) to (?P<p>{_WHO42R})|(?:is|are) (?:for )?(?P<p2>{_WHO42R})(?:'s)?|(?:for|to) "
    rf"(?P<p3>{_WHO42R}))(?P<end>\s*[.!]?)$"
)


def _all_but_first42r(text: str, lexicon: Lexicon) -> str:
    """Session 42 (12r): what is left out said first ("Apart from / Except for / Other than /
    Besides X, everything (else, on offer) goes to P", "Leave X alone (be, out of it); anything
    besides them (the rest, everything else) is P's") is "Everything except X goes to P" (the
    grammar's leaving out, which checks what is left)."""
    m = re.match(_ALL_BUT_FIRST42R, text.strip(), _F)
    if m is None:
        return text
    who = m["p"] or m["p2"] or m["p3"]
    said = m["x"] or m["x2"]
    # each a whole name of one object or of a kind ('the pens')
    things = [_the42r(w) for w in re.split(r",| and ", said) if w.strip()]
    if _person42r(who, lexicon) is None or not all(
        _whole_name(t, lexicon, "object") for t in things
    ):
        return text
    out = f"Everything except {' and '.join(things)} goes to {who}{m['end'] or '.'}"
    return out if _reading(out, lexicon) is not None else text


# "Leave everything on the bench where it is, except the big spanner, which goes in the locker."
_LEAVE_ALL_BUT42R = (
    r"^leave (?:everything|it all|all of it|the lot)(?: else)?(?: (?:on|in) (?P<s>the [a-z]+"
    r"(?: [a-z]+)?))? (?:where it is|as it is|be|alone)\s*,?\s*(?:except|but|apart from|bar|other "
    rf"than|except for|save) (?P<x>{_THING42R})\s*(?:,\s*which|;\s*(?:that|it)|:\s*(?:that|it)|,"
    r"\s*(?:that|it)) (?P<v>goes|should go|needs to go|wants to go|can go|has to go|is to go) "
    r"(?P<prep>in|on|into|onto) (?P<t>the [a-z]+(?: [a-z]+)?)(?P<end>\s*[.!]?)$"
)


def _leave_all_but42r(text: str, lexicon: Lexicon) -> str:
    """Session 42 (12r): "Leave everything (on S) where it is, except X, which goes in T" (X;
    that goes …) is "Put X in T": the one thing to move (X an object named whole, S and T
    surfaces named whole, X starting on S when S is said)."""
    m = re.match(_LEAVE_ALL_BUT42R, text.strip(), _F)
    if m is None:
        return text
    x = _thing42r(m["x"], None, lexicon)
    if x is None or not _whole_name(m["t"], lexicon, "surface"):
        return text
    if m["s"]:
        if not _whole_name(m["s"], lexicon, "surface"):
            return text
        (sid,) = _ids(m["s"], lexicon, "surface")
        if not starting_on(_ids(x, lexicon, "object"), sid, lexicon):
            return text
    out = f"Put {x} {m['prep']} {m['t']}{m['end'] or '.'}"
    return out if _reading(out, lexicon) is not None else text


# "any one of the pens that isn't already lying on the desk", "the two boxes that aren't sitting
# on the pallet"
_NOT_ON42R = (
    r"\b(?:(?:(?P<q>(?:any )?one of|(?:any|either) of|all(?: of)?|both(?: of)?) )?the (?:(?P<n>two|"
    r"three|four) )?|(?P<q3>both|all) )(?P<k>[a-z]+) (?:that|which) (?:isn't|aren't|is not|are not|"
    r"'s not|'re not) "
    r"(?:already |currently |yet |still )?(?:(?:lying|sitting|standing|resting|sat|stood|kept|"
    r"stored|left|put|placed) )?(?P<prep>on|in|at) (?P<s>the [a-z]+(?: [a-z]+)?)"
    r"(?=\s*(?:[.,;:!?]|$|goes|go|to|for|should|can|need|want))"
)
_COUNTS42R = {"two": 2, "three": 3, "four": 4, "both": 2}


def _not_on42r(text: str, lexicon: Lexicon) -> str:
    """Session 42 (12r): objects picked out by where they are not ("the boxes that aren't
    (sitting) on the pallet", "any one of the pens that isn't already lying on the desk") are the
    objects of that kind the scene does not start on that surface, named: all of them ("the small
    box and the medium box"), as many as a count says (else left for the count's refusal), or
    one of them ("the black pen or the red pen")."""
    low = text.lower()
    if "n't" not in low and " not " not in low:
        return text

    def named(m: re.Match[str]) -> str:
        kind = m["k"].lower()
        kinds = {kind, kind[:-1] if kind.endswith("s") else kind}
        if kind.endswith("es"):
            kinds.add(kind[:-2])
        of_kind = [o.id for o in lexicon.scene.objects if o.category.lower() in kinds]
        if len(of_kind) < 2 or not _whole_name(m["s"], lexicon, "surface"):
            return m[0]
        (sid,) = _ids(m["s"], lexicon, "surface")
        on = set(starting_on(set(of_kind), sid, lexicon))
        off = [o for o in of_kind if o not in on]
        names = [next(iter(_names42r(o, lexicon)), None) for o in off]
        if not off or not on or None in names:
            return m[0]
        said = [f"the {n}" for n in names if n]
        q = (m["q"] or m["q3"] or "").lower()
        if q.startswith("all"):
            return m[0]  # "All the boxes that aren't on S, stick them on" is session 27's
        one = q.startswith(("one", "any one", "any of", "either"))
        count = m["n"] or ("both" if q.startswith("both") else None)
        if count and _COUNTS42R[count.lower()] != len(off):
            return m[0]
        if not one and not count and not q and not kind.endswith("s"):
            return m[0]  # 'the X that isn't on S' is session 18's (`_negation18`)
        if one:
            return said[0] if len(said) == 1 else " or ".join(said)
        return said[0] if len(said) == 1 else f"{', '.join(said[:-1])} and {said[-1]}"

    return re.sub(_NOT_ON42R, named, text, flags=_F)


# "For Sam, the black pen or the red pen, …": a choice for a person named first
_FOR_CHOICE42R = (
    rf"^for (?P<p>{_WHO42R}),\s*(?P<x>(?:either )?{_THING42R}(?: or {_THING42R})+|(?:any )?one of "
    r"the [a-z]+s?)(?P<rest>(?:\s*,[^.!?]*)?)(?P<end>\s*[.!]?)$"
)


def _for_choice42r(text: str, lexicon: Lexicon) -> str:
    """Session 42 (12r): a person named first with 'for' then a choice of objects ("For Sam,
    the black pen or the red pen", "For Zoe, one of the books") is "<the choice> for P" (what
    follows kept), as a single object said so reads already."""
    m = re.match(_FOR_CHOICE42R, text.strip(), _F)
    if m is None or _person42r(m["p"], lexicon) is None:
        return text
    out = f"{_capital40r(m['x'])} for {m['p']}{m['rest']}{m['end'] or '.'}"
    return out if _reading(out, lexicon) is not None else text


# -- courtesy negatives: what says nothing against the request ---------------------------------

# "No bother if not, but could …"; "Don't worry if you can't, …"
_NO_BOTHER42R = (
    r"^(?:(?:it's|it is|that's) )?(?:no (?:bother|problem|worries|worry|pressure|stress|big deal)|"
    r"not to worry|don't worry|never mind|no matter) if (?:not|you can't|you cannot|you're busy|"
    r"you are busy|there's no time|it's a pain|it's a hassle|it's too much)\s*[,;.:!-]\s*"
    r"(?:but |though |otherwise |still )?(?P<rest>\S.*)$"
)
# "…, either one, really; not fussed."
_NOT_FUSSED42R = (
    r"\s*[,;.:-]\s*(?:(?:i'm|i am|we're|we are|she's|he's|they're|she is|he is|they are) )?"
    r"(?:really )?not (?:fussed|bothered|picky|fussy|particular)(?: (?:which|either way|really))?"
    r"(?P<end>\s*[.!]?)$"
)
# "… without spilling it"
_WITHOUT_SPILLING42R = (
    r",?\s*without (?:spilling|dropping|breaking|knocking over|tipping) (?:it|them|any(?: of "
    r"(?:it|them))?|a drop|anything)(?=\s*[.!?]?$)"
)
# "Person A wouldn't say no to the chips if they were going spare."
_SAY_NO42R = (
    r"\b(?P<head>(?:wouldn't|would not|won't|will not) (?:say no to|turn down|refuse|object to))"
    r" (?P<x>(?:the|that|those|some|a|an) [a-z]+(?: [a-z]+)?)(?P<if>\s*,?\s*if (?:it's|it is|"
    r"they're|they are|it was|they were|there's one|there are some|there's any|there are any) "
    r"(?:going spare|going|spare|free|left over|left|going begging|going round|on offer)|\s*,?\s*"
    r"if you're offering|\s*,?\s*if nobody else wants (?:it|them))?(?=\s*(?:[.,;!?]|$))"
)
# "…; no one else is to touch it"; "… nobody else wants them"
_NO_ONE_ELSE42R = (
    r"(?:\s*[,;.:-]\s*|\s+)(?:and |so )?(?:no ?one|no-one|nobody) else (?:(?:is to|should|may|"
    r"can|must|gets to|is allowed to|is going to) (?:touch|have|get|take|use|go near)|wants|needs|"
    r"is after|asked for|has asked for|'s asked for) (?:it|them|those|that|these)"
    r"(?P<end>\s*[.!]?)$"
)


def _courtesy42r(text: str, lexicon: Lexicon) -> str:
    """Session 42 (12r): negatives that are courtesies, not negations: "No bother (problem,
    worries) if not, but <request>" opening it (the request kept), "not fussed (bothered,
    picky)" closing a choice, "without spilling (dropping) it" closing a request, "wouldn't say
    no to (turn down) X (if they were going spare, if you're offering)" as "would like X", and
    "no one (nobody) else is to touch it / wants them" after a request that hands it to one
    person; each taken only when what is left reads (a choice for 'not fussed')."""
    low = text.lower()
    if not any(w in low for w in ("no", "not", "n't", "without")):
        return text
    out = text.strip()
    m = re.match(_NO_BOTHER42R, out, _F)
    if m is not None:
        rest = _capital40r(m["rest"])
        if _reading(rest, lexicon) is not None:
            out = rest
    m = re.search(_NOT_FUSSED42R, out, _F)
    if m is not None:
        head = out[: m.start()] + (m["end"] or ".")
        node = _reading(head, lexicon)
        if node is not None and has_choice(node):
            out = head
    out = re.sub(_WITHOUT_SPILLING42R, "", out, flags=_F)

    def would_like(m: re.Match[str]) -> str:
        if not _whole_name(m["x"], lexicon, "object"):
            return m[0]
        return f"would like {m['x']}"

    out = re.sub(_SAY_NO42R, would_like, out, flags=_F)
    m = re.search(_NO_ONE_ELSE42R, out, _F)
    if m is not None:
        head = out[: m.start()] + (m["end"] or ".")
        node = _reading(head, lexicon)
        if node is not None and len({t.target for t in tasks(node)}) == 1:
            out = head
    return out if out != text.strip() else text


# -- corrections: the speaker owning a mistake ----------------------------------------------------

# the speaker owning the mistake before the corrected request ("ignore me", "no, I got that
# wrong", "I was wrong though", "or, let me put that right", "slip of the tongue", "my memory's
# terrible"), or a correction cue ("no", "no hold on") before a corrected request said whole
_OWN42R = (
    r"(?:(?:or|oh|ah|sorry|wait|no|actually|hmm|um|erm)\s*,?\s*)*(?P<own>ignore me|ignore that|"
    r"forget what i (?:just )?said|i got that wrong|i've got that wrong|i had that wrong|i was "
    r"wrong(?: (?:though|there|about that|on that))?|i'm wrong|my mistake|my bad|my memory"
    r"(?:'s| is) (?:terrible|awful|shocking|useless|going)|slip of the tongue|let me put that "
    r"right|let me correct (?:that|myself)|let me get that right|i misspoke|i spoke too soon|"
    r"i'm getting (?:muddled|mixed up)|i've got (?:them|it) muddled|what am i saying|"
    r"i'd have said,? but "
    rf"(?:{_PRO42R}|{_WHO42R})(?:'s| has)? (?:just )?(?:shouted|called|said|told me|rung|texted|"
    r"messaged|radioed)(?: (?:down|up|over|through|across|in))?(?: that)?)"
)
_CUE42R = r"(?:(?:no|oh no|nope)\s*,?\s*(?:hold on|hang on|wait|sorry)?)"
_FIX42R = (
    rf"^(?P<head>.+?)\s*[,;.:!?-]\s*(?:{_OWN42R}|(?P<cue>{_CUE42R})|(?P<hold>(?:oh,? )?"
    r"(?:hold|hang) on))\s*[,;.:!-]?\s*(?P<fix>\S.*?)(?P<mine>\s*[,;]\s*(?:my mistake|my bad|"
    r"sorry(?: about that)?))?(?P<end>\s*[.!]?)$"
)
# what the correction says, as a cleft of the thing ("it's the apple he's meant to get")
_CLEFT_THING42R = (
    rf"^it(?:'s| is| was) (?P<y>{_THING42R}) (?:that |which )?(?P<w>{_PRO42R}|{_WHO42R})(?:'s| is| "
    r"was)? (?:meant to (?:get|have)|wants|wanted|getting|asked for|having|after|needs|needed|to "
    r"(?:have|get)|should (?:get|have)|gets)(?P<not>\s*,\s*not (?P<x>{T}))?$"
).replace("{T}", _THING42R)
# … of the person ("it's Bob who's having it")
_CLEFT_WHO42R = (
    rf"^it(?:'s| is| was) (?P<q>{_WHO42R}) (?:who|that)(?:'s| is| was)? (?:having|getting|gets|"
    r"wants|wanted|needs|asked for|after|should (?:get|have)|meant to (?:get|have)) (?:it|them)$"
)
# … of the thing for the person ("it's the bottle for him")
_CLEFT_FOR42R = rf"^it(?:'s| is| was) (?P<y>{_THING42R}) for (?P<w>{_PRO42R}|{_WHO42R})$"
# … of the place, as a person's wish ("Marco wants it on the counter by the hob")
_WANTS_IT_ON42R = (
    rf"^(?P<q>{_WHO42R}) (?:wants|needs|would like|'d like|says) (?:it|them) (?P<on>(?:on|in|onto|"
    r"into) the [a-z]+.*)$"
)
# … after a reason ("Omar says it needs washing, so the sink")
_REASON_SO42R = (
    rf"^(?:{_WHO42R} (?:says|reckons|thinks|said|tells me) )?(?:it|they) (?:needs?|wants?|has|have|"
    r"is|are|'s|'re|was|were)\b[^,;]*,\s*so (?P<frag>\S.*)$"
)
# … after a remark on the thing ("the blue's on the desk, I mean the black")
_REMARK_MEAN42R = (
    r"^(?P<why>(?:the|that) [a-z]+(?: [a-z]+)?(?:'s| is) [^,;]+),\s*(?P<frag>i mean\b.*)$"
)
# "I said bottle for Person B, didn't I?"; "Apple for Person B, I told you;"
_I_SAID42R = (
    r"^(?:i (?:said|told you|asked for)\s+)?(?P<req>.+?)(?:\s*,\s*(?:didn't i|did i not|i told "
    r"you|like i said|as i said))?$"
)


def _people42r(words: str, lexicon: Lexicon) -> set[str]:
    """The people ``words`` names."""
    return _ids(words, lexicon, "human")


def _fixed42r(fix: str, head: str, lexicon: Lexicon) -> str | None:
    """What a correction ``fix`` of request ``head`` says, as the grammar's correction takes it
    after 'no,' (a thing, 'to <person>', 'on <surface>', 'I mean …'); None when it is none of
    these forms (or a pronoun or name in it is not the head's one person)."""
    said = fix.strip()
    heads = _people42r(head, lexicon)
    m = re.match(_CLEFT_THING42R, said, _F) or re.match(_CLEFT_FOR42R, said, _F)
    if m is not None:
        y = _thing42r(m["y"], None, lexicon)
        if y is None or len(heads) != 1:
            return None
        (pid,) = heads
        w = m["w"]
        if w.lower() in PRONOUN_SEX:
            if not _fits42r(pid, w, lexicon):
                return None
        elif _person42r(w, lexicon) != pid:
            return None
        said_not = m["not"] if "not" in m.groupdict() else None
        if said_not and not _ids(m["x"], lexicon, "object") <= _ids(head, lexicon, "object"):
            return None
        return y
    m = re.match(_CLEFT_WHO42R, said, _F)
    if m is not None:
        qid = _person42r(m["q"], lexicon)
        return None if qid is None or {qid} == heads else f"to {m['q']}"
    m = re.match(_WANTS_IT_ON42R, said, _F)
    if m is not None and _person42r(m["q"], lexicon) is not None:
        # "on the counter by the hob": a landmark the scene does not hold only says where
        near = re.search(r" (?:by|next to|beside|near|under|over) the [a-z]+$", m["on"], _F)
        if near is not None and not _ids(near[0], lexicon):
            return m["on"][: near.start()]
        return m["on"]
    m = re.match(_REASON_SO42R, said, _F)
    if m is not None:
        return m["frag"]
    m = re.match(_REMARK_MEAN42R, said, _F)
    if m is not None and not _people42r(m["why"], lexicon):
        return m["frag"]
    return said


def _owned_mistake42r(text: str, lexicon: Lexicon) -> str:
    """Session 42 (12r): a request the speaker then owns as a mistake ("…; ignore me, …", "…; no, I
    got that wrong, …", "…; I was wrong though, …", "…, or, let me put that right, …", "Slip of the
    tongue, …", "…; my memory's terrible, …", 'hold on' / 'hang on' with "my mistake" after, or a
    reason then 'so'), or corrects with 'no' (hold on), and the corrected request said whole as a
    cleft ("it's the apple he's meant to get", "it's Bob who's having it", "it's the bottle for
    him", "it was the chips she asked for"), as a person's wish for the place ("Marco wants it on
    the counter"), after a reason ("Omar says it needs washing, so the sink"; "the blue's on the
    desk, I mean the black") or as it is: "<request>, no, <the correction>" (the grammar's
    correction then reads it, as it reads "…, no, the cup"). "I said <request>, didn't I?" and
    "<request>, I told you" are the request. Taken only when that reads."""
    low = text.lower()
    if not any(
        w in low
        for w in (
            "ignore",
            "wrong",
            "mistake",
            "my bad",
            "memory",
            "slip",
            "put that right",
            "correct",
            "misspoke",
            "muddled",
            "mixed up",
            "no",
            "hold on",
            "hang on",
            "what am i",
        )
    ):
        return text
    m = re.match(_FIX42R, text.strip(), _F)
    if m is None:
        return text
    if m["hold"] and not m["mine"] and not re.match(_REASON_SO42R, m["fix"], _F):
        return text  # 'hold on' alone could add to the request or correct it
    if m["cue"] and not m["own"]:
        said = _fixed42r(m["fix"], m["head"], lexicon)
        if said is None or said == m["fix"].strip():
            return text  # a plain 'no, …' is the grammar's own
    if re.search(
        r"\b(?:oh|no|hang|hold|wait|sorry|scratch|actually|correction|i mean|i meant)\b",
        m["head"],
        _F,
    ):
        return text  # a cue in the request before: the older correction rules'
    h = re.match(_I_SAID42R, m["head"].strip(), _F)
    head = _capital40r(h["req"]) if h is not None else m["head"]
    fix = _fixed42r(m["fix"], head, lexicon)
    if fix is None:
        return text
    out = f"{head}, no, {fix}{m['end'] or '.'}"
    return out if _reading(out, lexicon) is not None else text


# "Bottle for, sorry, I keep saying Person B, Person A."
_KEEP_SAYING42R = (
    r"^(?P<head>.+?)(?P<cut>\s+(?:for|to))?\s*,\s*(?:(?:sorry|no),?\s*)?i keep (?:saying|"
    r"calling (?:him|her|them)|getting (?:them|those two) (?:mixed up|muddled),? (?:it's )?)\s*"
    rf"(?P<p>{_WHO42R})"
    rf"\s*,\s*(?P<q>{_WHO42R})(?P<end>\s*[.!]?)$"
)


def _keep_saying42r(text: str, lexicon: Lexicon) -> str:
    """Session 42 (12r): "X for, sorry, I keep saying P, Q" (the request broken off to own a
    slip it keeps making: P, in the scene or not, is the wrong name) is "X for Q", and "<request
    to P>, sorry, I keep saying P, Q" is "<request>, no, Q" (P and Q two people of the scene)."""
    if "keep" not in text.lower():
        return text
    m = re.match(_KEEP_SAYING42R, text.strip(), _F)
    if m is None or m["p"].lower() == m["q"].lower():
        return text
    pid, qid = _person42r(m["p"], lexicon), _person42r(m["q"], lexicon)
    if qid is None or pid == qid:
        return text
    if m["cut"]:
        out = f"{m['head']}{m['cut']} {m['q']}{m['end'] or '.'}"
    elif pid is not None and pid in _people42r(m["head"], lexicon):
        out = f"{m['head']}, no, {m['q']}{m['end'] or '.'}"
    else:
        return text
    return out if _reading(out, lexicon) is not None else text


# "Person B wants the chips, and she wants the bottle; Person A, I mean."
_WHO_I_MEAN42R = rf"^(?P<head>.+?)\s*[;,.]\s*(?P<p>{_WHO42R}),? i mean(?P<end>\s*[.!]?)$"


def pronoun_named42r(text: str) -> bool:
    """Session 42 (12r): whether ``text`` ends "…; <a name>, I mean" after a last clause with one
    he / she / him / her (what `_pronoun_i_mean42r` reads): not a correction cut off
    (offline._cut_off asks this)."""
    m = re.match(_WHO_I_MEAN42R, text.strip(), _F)
    if m is None:
        return False
    head = m["head"]
    cut = max(head.rfind(","), head.rfind(";"), head.lower().rfind(" and "))
    last = head[cut + 1 :] if cut >= 0 else head
    return len(re.findall(r"\b(?:he|she|him|her)\b", last, _F)) == 1


def _pronoun_i_mean42r(text: str, lexicon: Lexicon) -> str:
    """Session 42 (12r): "<…, and she wants the bottle>; Person A, I mean" (a person named after
    the request with "I mean") says who the pronoun of the last clause is: that pronoun (one
    he / she / him / her there, none before it in that clause, fitting P) is P."""
    if "i mean" not in text.lower():
        return text
    m = re.match(_WHO_I_MEAN42R, text.strip(), _F)
    if m is None:
        return text
    pid = _person42r(m["p"], lexicon)
    if pid is None:
        return text
    head = m["head"]
    cut = max(head.rfind(","), head.rfind(";"), head.lower().rfind(" and "))
    last = head[cut + 1 :] if cut >= 0 else head
    pros = list(re.finditer(r"\b(?:he|she|him|her)\b", last, _F))
    if len(pros) != 1 or _people42r(last, lexicon) or not _fits42r(pid, pros[0][0], lexicon):
        return text
    start = (cut + 1 if cut >= 0 else 0) + pros[0].start()
    out = f"{head[:start]}{m['p']}{head[start + len(pros[0][0]) :]}{m['end'] or '.'}"
    return out if _reading(out, lexicon) is not None else text


# -- counts and distributions ---------------------------------------------------------------------

# "Hand over both the chips and the bottle, the two together, to Person A."
_COUNT_AGAIN42R = (
    rf"(?P<list>{_THING42R}(?:(?:,| and|, and) {_THING42R})+)\s*,\s*(?:the|both|all)(?: (?P<n>two|"
    r"three|four))?(?: of them)? (?:together|at once|in one go)\s*(?=,|$|[.!])"
)
_NUMBER42R = {"two": 2, "three": 3, "four": 4, "both": 2}


def _count_again42r(text: str, lexicon: Lexicon) -> str:
    """Session 42 (12r): a count said again after the objects it counts ("both the chips and the
    bottle, the two together, to P"; "…, all three of them, …") says nothing more: dropped when
    the objects named are that many, each named whole."""
    low = text.lower()
    if not any(w in low for w in ("two", "three", "four", "together", "at once", "in one go")):
        return text

    def again(m: re.Match[str]) -> str:
        things = [w for w in re.split(r",? and |, ", m["list"], flags=_F) if w.strip()]
        if not _objects_named42r(things, lexicon):
            return m[0]
        if m["n"] and _NUMBER42R[m["n"].lower()] != len(things):
            return m[0]
        if not m["n"] and len(things) != 2:
            return m[0]
        return m["list"]

    return re.sub(_COUNT_AGAIN42R, again, text, flags=_F)


def _objects_named42r(things: list[str], lexicon: Lexicon) -> bool:
    """Whether each of ``things`` names one object whole, each another."""
    ids = [_thing42r(t, None, lexicon) for t in things]
    if None in ids:
        return False
    got = [_ids(t, lexicon, "object") for t in ids if t]
    return len(set().union(*got)) == len(things)


# "she'll take both, the bottle and the chips"; "both items, the chips as well as the bottle"
_COUNT_THEN_LIST42R = (
    r"\b(?P<n>both|all (?:two|three|four)|the (?:two|three|four))(?: (?:items|things|bits|of "
    r"them))?"
    rf"\s*,\s*(?P<list>{_THING42R}(?:, {_THING42R})*,? (?:and|as well as|plus|along with) "
    rf"{_THING42R})(?=\s*(?:[.;!]|$))"
)
# "Person A's taking three of the things to her pyrography class: the cup, the apple and the chips."
_TAKING_LIST42R = (
    rf"^(?P<p>{_WHO42R})(?:'s| is) (?:taking|having|getting) (?P<n>both|two|three|four|all "
    r"(?:two|three|four)) of the (?:things|items|bits)(?P<mid>[^:;]*?)\s*:\s*(?P<list>"
    rf"{_THING42R}(?:, {_THING42R})*,? and {_THING42R})(?P<end>\s*[.!]?)$"
)


def _count_then_list42r(text: str, lexicon: Lexicon) -> str:
    """Session 42 (12r): a count then the objects it counts ("she'll take both, the bottle and
    the chips", "both items, the chips as well as the bottle", "all three things, …") is the
    objects ("the bottle and the chips"), when they are that many, each named whole; "P's taking
    three of the things (to her class): X, Y and Z" is "P gets X, Y and Z" (what is said of
    where P takes them naming nothing of the scene)."""
    low = text.lower()
    if not any(w in low for w in ("both", "two", "three", "four")):
        return text
    m = re.match(_TAKING_LIST42R, text.strip(), _F)
    if m is not None and _person42r(m["p"], lexicon) is not None and not _ids(m["mid"], lexicon):
        things = [w for w in re.split(r",? and |, ", m["list"], flags=_F) if w.strip()]
        n = m["n"].lower().removeprefix("all ")
        if _objects_named42r(things, lexicon) and _NUMBER42R[n] == len(things):
            out = f"{m['p']} gets {m['list']}{m['end'] or '.'}"
            if _reading(out, lexicon) is not None:
                return out

    def listed(m: re.Match[str]) -> str:
        said = re.sub(r",? (?:as well as|plus|along with) ", " and ", m["list"], flags=_F)
        things = [w for w in re.split(r",? and |, ", said, flags=_F) if w.strip()]
        n = m["n"].lower().removeprefix("all ").removeprefix("the ")
        if not _objects_named42r(things, lexicon) or _NUMBER42R[n] != len(things):
            return m[0]
        return said

    return re.sub(_COUNT_THEN_LIST42R, listed, text, flags=_F)


# "Both of the things we've got here, up onto the shelf with them"
_THINGS_HERE42R = (
    r"\b(?P<all>(?:both|all(?: (?:two|three|four))?) of the (?:things|items|bits))(?: (?:that "
    r")?(?:we've "
    r"got|we have|you've got|you have|there are)(?: here| there)?| here| on offer| "
    r"about)(?=\s*[,:])"
)
_WITH_THEM42R = r"(?P<on>\b(?:on|onto|in|into) the [a-z]+) with (?:it|them)(?=\s*(?:[,.;!]|$))"


def _things_here42r(text: str, lexicon: Lexicon) -> str:
    """Session 42 (12r): "both of the things (we've got here, on offer)" is "both of the things"
    (the grammar counts them against the scene), and "…, up onto the shelf with them" (off to
    the sink with it) is "…, up onto the shelf": where they go."""
    low = text.lower()
    if "of the" not in low and "with" not in low:
        return text
    out = re.sub(_THINGS_HERE42R, lambda m: m["all"], text, flags=_F)
    if out != text or re.match(r"^\s*(?:both|all)\b", out, _F):
        out = re.sub(_WITH_THEM42R, lambda m: m["on"], out, flags=_F)
    return out


# "a single bottle will see her through, the one you've got"
_SINGLE42R = (
    r"(?<!\bthere's )(?<!\bthere is )(?<!\bonly )(?<!\bjust )\b(?P<a>a|one) single "
    r"(?!(?:item|thing)\b)(?=[a-z]+)"
)
_THE_ONE_GOT42R = (
    r"\s*,\s*(?:just )?the one (?:you've got|you have|you've got there|you have there|there|"
    r"you're holding|in front of you)(?P<end>\s*[.!]?)$"
)


def _single42r(text: str, lexicon: Lexicon) -> str:
    """Session 42 (12r): "a single X" (one single X) is "a X", the count one, and ", the one
    you've got (there)" closing a request names again the one object of a kind the scene has
    one of: dropped then (of a kind with several, which one is not said: left)."""
    low = text.lower()
    if "single" not in low and "the one" not in low:
        return text

    def one(m: re.Match[str]) -> str:
        # "There's (only) a single X", "We've only got a single X": session 30's and 40's
        if re.search(r"\b(?:only|there's|there is|just)\b", text[: m.start()], _F):
            return m[0]
        return m["a"] + " "

    out = re.sub(_SINGLE42R, one, text, flags=_F)
    m = re.search(_THE_ONE_GOT42R, out, _F)
    if m is not None:
        named = _ids(out[: m.start()], lexicon, "object")
        cats = {o.category for o in lexicon.scene.objects if o.id in named}
        if named and all(sum(o.category == c for o in lexicon.scene.objects) == 1 for c in cats):
            out = out[: m.start()] + (m["end"] or ".")
    return out


# "Just the one bottle in the room and it's promised to Person A."
_ONLY_ONE42R = (
    r"^(?:there's |there is )?(?:just|only) the one (?P<k>[a-z]+)(?: (?:in the room|here|left|"
    r"going|"
    r"there is|we've got|we have|about|around))?\s*,?\s*(?:and|but) (?:it's|it is|that's|that "
    r"one's|"
    r"it has been|it's been) (?:promised|going|earmarked|reserved|meant|spoken for|booked|set "
    r"aside|"
    rf"saved|kept)(?: (?:to|for) (?P<p>{_WHO42R}))(?P<end>\s*[.!]?)$"
)


def _only_one42r(text: str, lexicon: Lexicon) -> str:
    """Session 42 (12r): "Just (only) the one X (in the room, here, left) and it's promised
    (earmarked, meant, going) to P" is "The X goes to P", when the scene has one X."""
    if "the one" not in text.lower():
        return text
    m = re.match(_ONLY_ONE42R, text.strip(), _F)
    if m is None or _person42r(m["p"], lexicon) is None:
        return text
    ids = _ids(f"the {m['k']}", lexicon, "object")
    if len(ids) != 1 or not _whole_name(f"the {m['k']}", lexicon, "object"):
        return text
    out = f"The {m['k']} goes to {m['p']}{m['end'] or '.'}"
    return out if _reading(out, lexicon) is not None else text


# "A blanket each for the two patients"
_ROLE_GROUP42R = (
    r"(?<!\bof )\b(?:the (?P<n>two|three|four)|both(?: of the)?|all (?P<n2>two|three|four)(?: of "
    r"the)?) "
    r"(?P<r>[a-z]+s)\b"
)


def _role_group42r(text: str, lexicon: Lexicon) -> str:
    """Session 42 (12r): people named by a role they share, in the plural, with or without a count
    ("the two patients", "both students", "the nurses"), are those people by name ("Mr Lee and
    Mrs Khan"), when the scene gives that role to two or more people, as many as the count says,
    and no object is of that kind."""

    def named(m: re.Match[str]) -> str:
        plural = m["r"].lower()
        role = plural[:-2] if plural.endswith("es") and plural[:-2] else plural[:-1]
        humans = [
            h
            for h in lexicon.scene.humans
            if any(a.lower() in (role, plural[:-1]) for a in h.aliases)
        ]
        if len(humans) < 2 or _ids(f"the {plural}", lexicon, "object"):
            return m[0]
        said = m["n"] or m["n2"] or "both"
        if _NUMBER42R[said.lower()] != len(humans):
            return m[0]
        names = []
        for h in humans:
            shared = {a for x in lexicon.scene.humans if x.id != h.id for a in x.aliases}
            name = next((a for a in (*h.aliases, h.name) if a not in shared), None)
            if name is None:
                return m[0]
            names.append(name)
        return f"{', '.join(names[:-1])} and {names[-1]}"

    out = re.sub(_ROLE_GROUP42R, named, text, flags=_F)
    # "A blanket each for Mr Lee and Mrs Khan, …" is "One blanket each for …"
    return re.sub(r"^(?:a|an) (?=[a-z]+ (?:each|apiece) for )", "One ", out, flags=_F)


# "…, whichever he likes; just take him one."; "Either of the two things will keep Person B happy,
# so bring him one."
_JUST_ONE42R = (
    r"\s*[;,]\s*(?:so |and )?(?:just )?(?:take|give|bring|pass|hand|get) (?P<pro>him|her|them) "
    r"(?:one|either|one of them|either of them|whichever)(?P<end>\s*[.!]?)$"
)
_EITHER_WILL42R = (
    r"^(?P<what>(?:either|any|one|both) of the (?:two |three |four )?[a-z]+) (?:will|would|'ll|"
    r"should|could) (?:keep (?P<p>{W}) happy|do (?:for )?(?P<p2>{W})|suit (?P<p3>{W})|please "
    r"(?P<p4>{W})|make (?P<p5>{W}) happy)"
).replace("{W}", _WHO42R)


def _just_one42r(text: str, lexicon: Lexicon) -> str:
    """Session 42 (12r): "…; just take him one" (bring her one, give them either) closing a choice
    of objects for one person says the choice again: dropped when what is before it reads as
    that choice, the pronoun fitting; "Either (any) of the things will keep P happy (do P, suit
    P)" before it is "P can have either of the things"."""
    m = re.search(_JUST_ONE42R, text, _F)
    if m is None:
        return text
    head = text[: m.start()]
    e = re.match(_EITHER_WILL42R, head.strip(), _F)
    if e is not None:
        who = next(w for w in (e["p"], e["p2"], e["p3"], e["p4"], e["p5"]) if w)
        if _person42r(who, lexicon) is None:
            return text
        head = f"{who} can have {e['what']}"
    node = _reading(head + (m["end"] or "."), lexicon)
    if node is None or not has_choice(node):
        return text
    targets = {t.target for t in tasks(node)}
    if len(targets) != 1 or not _fits42r(next(iter(targets)), m["pro"], lexicon):
        return text
    return head + (m["end"] or ".")


# "Either way, Person A gets the bottle in the end."
_EITHER_WAY42R = (
    r"^(?:either way|whatever happens|in any case|one way or (?:another|the other)|all the same|"
    r"whichever way|at any rate),\s*(?P<rest>\S.*?)(?:\s+(?:in the end|eventually|at the end of "
    r"the "
    r"day|ultimately|when all's said and done))?(?P<end>\s*[.!]?)$"
)


def _either_way42r(text: str, lexicon: Lexicon) -> str:
    """Session 42 (12r): "Either way (whatever happens, in any case), <request> (in the end,
    eventually)" is the request: what it settles is the request (taken when that reads)."""
    m = re.match(_EITHER_WAY42R, text.strip(), _F)
    if m is None:
        return text
    out = _capital40r(m["rest"]) + (m["end"] or ".")
    return out if _reading(out, lexicon) is not None else text


# "The chips go to one of them, I don't mind if it's Person A or Person B, so pick the closer."
_DONT_MIND42R = (
    r"^(?P<head>.+?) (?:to|for) (?:one of them|either of them|one of the two)\s*,\s*(?:i|we) "
    r"(?:don't|"
    rf"do not) mind (?:if it's|whether it's|which(?: it is)?,?|who,?) (?P<p>{_WHO42R}) or "
    rf"(?P<q>{_WHO42R})(?:\s*,\s*so (?:pick|choose|go for|take) the (?P<near>closer|nearer|closest|"
    r"nearest)(?: one)?)?(?P<end>\s*[.!]?)$"
)


def _dont_mind42r(text: str, lexicon: Lexicon) -> str:
    """Session 42 (12r): "X goes to one of them, I don't mind if it's P or Q (, so pick the
    closer)" is "X goes to P or Q (, whichever is closer)": the choice of two people said after
    'one of them'."""
    if "mind" not in text.lower():
        return text
    m = re.match(_DONT_MIND42R, text.strip(), _F)
    if m is None:
        return text
    pid, qid = _person42r(m["p"], lexicon), _person42r(m["q"], lexicon)
    if pid is None or qid is None or pid == qid:
        return text
    near = f", whichever is {m['near']}" if m["near"] else ""
    to = re.search(r" (to|for) (?:one of them|either of them|one of the two)", text, _F)
    prep = to[1] if to is not None else "to"
    out = f"{m['head']} {prep} {m['p']} or {m['q']}{near}{m['end'] or '.'}"
    return out if _reading(out, lexicon) is not None else text


# "…, so each of them ends up with just the one thing."
_ONE_EACH42R = (
    r"\s*,?\s*(?:so |and )?(?:each of them|each one|everyone|everybody|they each|each)(?: of "
    r"them)? "
    r"(?:ends up with|end up with|gets|get|has|have|walks away with)(?: just| only)? (?:the )?one"
    r"(?: thing| item| each)?(?P<end>\s*[.!]?)$"
)


# "Everybody gets a single item here: …"
_ONE_EACH_FIRST42R = (
    r"^(?:everybody|everyone|each person|every person) (?:gets|get|has|"
    r"have|is getting|are getting|ends up with) (?:a single|one|just one|the one|only one) (?:item|"
    r"thing)(?: each| here| apiece| this time)?\s*:\s*(?P<rest>\S.*)$"
)


def _one_each42r(text: str, lexicon: Lexicon) -> str:
    """Session 42 (12r): "…, so each of them ends up with just the one thing" (everyone gets one)
    after a request that hands each person named one object, or "Everybody gets a single item
    here: …" before it, says nothing more: dropped then."""
    m = re.search(_ONE_EACH42R, text, _F)
    first = re.match(_ONE_EACH_FIRST42R, text.strip(), _F)
    if m is None and first is None:
        return text
    if first is not None:
        head = _capital40r(first["rest"])
    elif m is not None:
        head = text[: m.start()] + (m["end"] or ".")
    node = _reading(head, lexicon)
    if node is None or has_choice(node):
        return text
    targets = [t.target for t in tasks(node)]
    if len(targets) < 2 or len(set(targets)) != len(targets):
        return text
    if first is not None and set(targets) != {h.id for h in lexicon.scene.humans}:
        return text  # 'everybody' is every person of the scene
    return head


# "Noah's gluing and Zoe's cutting, so they need the glue stick and the scissors respectively."
_RESPECTIVELY42R = (
    rf"(?P<who>(?P<p>{_WHO42R}) and (?P<q>{_WHO42R})|they|the two of them|both of them) (?P<v>need|"
    r"want|get|should get|are having|'re having|are to have|can have|are after|'re after)"
    rf" (?P<x>{_THING42R}) and (?P<y>{_THING42R}),? respectively"
)


def _respectively42r(text: str, lexicon: Lexicon) -> str:
    """Session 42 (12r): "P and Q need X and Y respectively" pairs the two lists in order: "P needs
    X and Q needs Y"; 'they' there is the two people named before it, in that order (exactly two
    named, each once)."""
    if "respectively" not in text.lower():
        return text
    m = re.search(_RESPECTIVELY42R, text, _F)
    if m is None or not _objects_named42r([m["x"], m["y"]], lexicon):
        return text
    if m["p"]:
        p, q = m["p"], m["q"]
    else:
        before = text[: m.start()]
        said = [
            w
            for w in re.findall(rf"\b{_WHO42R}\b", before, _F)
            if _person42r(w, lexicon) is not None
        ]
        ids = [_person42r(w, lexicon) for w in said]
        if len(said) != 2 or len(set(ids)) != 2:
            return text
        p, q = said
    pid, qid = _person42r(p, lexicon), _person42r(q, lexicon)
    if pid is None or qid is None or pid == qid:
        return text
    verb = {"need": "needs", "want": "wants", "get": "gets", "should get": "should get"}.get(
        m["v"].lower(), "gets"
    )
    said_out = f"{p} {verb} {m['x']} and {q} {verb} {m['y']}"
    if m["p"]:
        return text[: m.start()] + said_out + text[m.end() :]
    # 'they' pointed back: the clause that named them is the reason, the pairing the request
    start = max(text.rfind(".", 0, m.start()), text.rfind(";", 0, m.start()))
    return text[: start + 1] + (" " if start >= 0 else "") + _capital40r(said_out) + text[m.end() :]


# "Once they've got them, the red book back on the shelf."
_ONCE_GOT42R = (
    r"(?<=[.;!?])\s*once (?:(?:they|he|she)(?:'ve|'s| have| has)(?: got| been given| had)? (?:them|"
    r"it|those|that)|that's (?:done|sorted))\s*,\s*"
)


def _once_got42r(text: str, _lexicon: Lexicon) -> str:
    """Session 42 (12r): a sentence opening "Once they've got them, …" (once that's done) after a
    request is "Then …": what follows comes after it."""
    if "once" not in text.lower():
        return text
    return re.sub(_ONCE_GOT42R, " Then ", text, flags=_F)


# -- refusals that name the readings -------------------------------------------------------------

# "he told me which one, but it's gone clean out of my head"; "she pointed, but I missed which"
_WHICH_LOST42R = (
    r"\b(?P<said>(?:(?:he|she|they|[a-z]+) (?:told me|said|mentioned|showed me|pointed(?: it out| "
    r"at it| to it)?|did say|picked)(?: which(?: one| ones| of them)?)?(?: [a-z]+){0,3},? but "
    r"(?:it's gone(?: clean| right| straight| completely)? out of my head|i've lost track|i lost "
    r"track|i forget|i forgot|i've forgotten|i can't remember|i don't remember|i can't recall|i "
    r"missed (?:which|it|which one)|i didn't catch (?:which|it|which one)|i didn't see which|i "
    r"wasn't looking|it's slipped my mind|it slipped my mind|my mind's gone blank)))"
)
# "a box for Tom, the one he asked for"
_THE_ONE_ASKED42R = (
    r",\s*(?P<said>the one (?:that |which )?(?:he|she|they|[a-z]+) (?:asked for|wanted|wants|"
    r"meant|mentioned|picked|chose|likes|pointed (?:at|to)|had (?:before|earlier|yesterday)|"
    r"was using|used|was after|is after|'s after|asked about))(?=\s*(?:[.,;!?]|$))"
)
# a thing of a kind said without which ("a plate", "one of the books", "one block")
_A_KIND42R = r"\b(?:one of the|any of the|either of the|an?|one) (?P<k>[a-z]+)\b"


def _kind_said42r(text: str, lexicon: Lexicon) -> list[str]:
    """The objects of the one kind ``text`` asks one of ('a plate', 'one of the books') that the
    scene has two or more of and the text names none of whole; [] otherwise."""
    kinds: list[set[str]] = []
    for m in re.finditer(_A_KIND42R, text, _F):
        ids = _ids(f"the {m['k']}", lexicon, "object")
        if len(ids) >= 2 and ids not in kinds:
            kinds.append(ids)
    if len(kinds) != 1:
        return []
    named = [
        o.id
        for o in lexicon.scene.objects
        if o.id in kinds[0]
        and any(
            _only(f"the {a}", lexicon, "object") and re.search(rf"\bthe {re.escape(a)}\b", text, _F)
            for a in _names42r(o.id, lexicon)
        )
    ]
    return [] if named else sorted(kinds[0])


def which_lost42r(text: str, lexicon: Lexicon) -> None:
    """Session 42 (12r): a thing of a kind the speaker was told or shown but cannot say ("P needs
    a plate; he told me which one, but it's gone clean out of my head", "she pointed, but I
    missed which", "a box for Tom, the one he asked for"): which one is meant is not known, so
    the request is refused, naming each object of that kind (not read as a choice left to the
    robot)."""
    low = text.lower()
    if " but " not in low and "the one" not in low:
        return
    m = re.search(_WHICH_LOST42R, text, _F) or re.search(_THE_ONE_ASKED42R, text, _F)
    if m is None:
        return
    ids = _kind_said42r(text[: m.start()] if m.start() else text, lexicon)
    if not ids:
        return
    raise GroundingError(
        f"{m['said']!r}: which one is meant is not said; it could be {' or '.join(ids)}: name the "
        "one"
    )


# "give it to whichever of them asked first"; "for whoever it was that rang down from the office"
_WHOEVER42R = (
    r"\b(?P<said>(?:whichever|whoever) (?:of (?:them|the two|you)|one)?\s*(?:(?:it was|it is|"
    r"it's) (?:that|who) [a-z]+|(?:asked|spoke|rang|called|came|got here|arrived|shouted|phoned|"
    r"put "
    r"(?:their|a) hand up|went|wanted it|said|rang|messaged|texted|emailed|left))(?: [a-z']+){0,5})"
)


def whoever_asked42r(text: str, lexicon: Lexicon) -> None:
    """Session 42 (12r): a person picked out by what only the speaker could know ("whichever of
    them asked first", "whoever it was that rang down from the office") is not said: refused,
    naming the people the text names when two or more, else each person of the scene."""
    low = text.lower()
    if "whoever" not in low and "whichever" not in low:
        return
    m = re.search(_WHOEVER42R, text, _F)
    if m is None or re.match(
        r"(?:whichever|whoever) (?:of (?:them|the two|you) |one )?(?:is|was) (?:free|closer|"
        r"closest|nearer|nearest|around|about|handy|here|there|nearby|available)\b",
        m["said"],
        _F,
    ):
        return
    named = _people42r(text, lexicon)
    ids = sorted(named) if len(named) >= 2 else [h.id for h in lexicon.scene.humans]
    if len(ids) < 2:
        return
    people = " or ".join(person_name(pid, lexicon) for pid in ids)
    raise GroundingError(f"{m['said']!r} is not a person the scene says: it could be {people}")


# "No, to the other one, or maybe it was Mrs Ortiz."
_MAYBE_IT_WAS42R = (
    r"\b(?:no|sorry|wait|actually)\b[^.;!?]*?,\s*(?P<said>or (?:maybe|perhaps|possibly)(?: "
    rf"(?:it was|it's|it is|it should be|it were))? (?P<q>{_WHO42R}))(?=\s*[.,;!?]?\s*$)"
)


def maybe_it_was42r(text: str, lexicon: Lexicon) -> None:
    """Session 42 (12r): a correction that ends by doubting itself with another person ("No, to
    the other one, or maybe it was Mrs Ortiz") leaves who gets it open: refused, naming each
    person of the scene."""
    if "maybe" not in text.lower() and "perhaps" not in text.lower():
        return
    m = re.search(_MAYBE_IT_WAS42R, text, _F)
    if m is None or _person42r(m["q"], lexicon) is None:
        return
    people = " or ".join(person_name(h.id, lexicon) for h in lexicon.scene.humans)
    raise GroundingError(
        f"{m['said']!r} doubts the correction: who gets it could be {people}: say the whole "
        "request again"
    )


# the normaliser's rewrites run before the session-41 ones (wired into normalise._STEPS19)
_STEPS42R_FIRST: tuple[Callable[[str, Lexicon], str], ...] = ()
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-41 ones)
_STEPS42R: tuple[Callable[[str, Lexicon], str], ...] = (
    _negated_then42r,
    _not_list_first42r,
    _all_but_first42r,
    _leave_all_but42r,
    _not_on42r,
    _for_choice42r,
    _courtesy42r,
    _owned_mistake42r,
    _keep_saying42r,
    _pronoun_i_mean42r,
    _single42r,
    _count_again42r,
    _count_then_list42r,
    _things_here42r,
    _only_one42r,
    _role_group42r,
    _just_one42r,
    _either_way42r,
    _dont_mind42r,
    _one_each42r,
    _respectively42r,
    _once_got42r,
)
# refusals asked of the text before it is read (offline._parse, after the session-41 ones)
REFUSE42R: tuple[Callable[[str, Lexicon], None], ...] = (
    which_lost42r,
    whoever_asked42r,
    maybe_it_was42r,
)
# checks of the whole instruction's reading (offline.parse_instruction, after the session-41 ones)
CHECK42R: tuple[Callable[[str, Node, Lexicon], None], ...] = ()
