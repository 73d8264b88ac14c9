"""The grounder's rules of session 41, engineer 12r (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _ids, _only_person, _reading
from hltl.grounding._normalise3 import _handovers33t, _whole_name
from hltl.grounding._normalise4 import _objects34r, _persons34r
from hltl.grounding._rewrites40r import _NAME40R, _capital40r
from hltl.grounding.lexicon import (
    KIND_CATEGORIES,
    PRONOUN_SEX,
    Lexicon,
    first_name_sex36s,
    person_name,
    said_sex35s,
)
from hltl.grounding.tree import Group, Node, Task, has_choice, normalise, tasks

# an object's name as these rules take it (checked against the scene after the match)
_THING41R = r"the [a-z]+(?: (?!(?:that|who|which|person|mr|mrs|ms|miss|dr)\b)[a-z]+)?"


# -- negation and exclusion ------------------------------------------------------------------------

# the exclusion words the grammar reads ('except') said another way, after a whole
_ALL41R = (
    r"(?P<all>\b(?:everything|the (?:whole )?lot|all (?:the|of the) [a-z]+|all of (?:it|them)|"
    r"every (?:last|single) (?:thing|item|bit|one of them|one)|each and every (?:thing|item|one)|"
    r"every (?:thing|item|one of them)))"
)
_EXCLUDING41R = (
    rf"{_ALL41R}(?P<x>\s+(?:(?:bar|but|except|save|besides|minus|barring|excluding|apart from|"
    r"other than|aside from)\b|(?P<new>excepting|not counting|leaving out|not including|with the "
    r"exception of|save for|bar for)\b))"
)


def _everything_but41r(text: str, _lexicon: Lexicon) -> str:
    """Session 41 (12r): a whole said with an intensifier ("every last thing", "every single
    item", "each and every thing") before the objects it leaves out is "everything", and the
    leaving out said as "excepting", "not counting", "leaving out", "not including", "with the
    exception of", "save for" is "except": "Every last thing bar the mugs goes to Alice" is
    "Everything bar the mugs goes to Alice" (what is left out then checked by the grammar)."""
    low = text.lower()
    if "every" not in low and "all" not in low and "lot" not in low:
        return text

    def said(m: re.Match[str]) -> str:
        whole = m["all"]
        if re.match(r"every|each", whole, _F):
            whole = "Everything" if whole[:1].isupper() else "everything"
        return whole + (" except" if m["new"] else m["x"])

    return re.sub(_EXCLUDING41R, said, text, flags=_F)


# "Not the bottle, mind, it's the crisps that Bob's after"; "Never mind about the chips; it's the
# bottle Person A wants"
_NOT_ITS41R = (
    rf"^(?:not|never mind(?: about)?|forget(?: about)?|leave|skip|scrap) (?P<x>{_THING41R})"
    r"(?:,? (?:mind|mind you|though))?\s*[,;:]\s*(?:but )?(?:it's|it is) "
    rf"(?P<y>{_THING41R}) (?:that )?(?P<p>{_NAME40R})(?:'s| is|'s been| has been)? "
    r"(?:after|wants|needs|asked for|has asked for|'s asked for|wanted|is wanting|fancies|"
    r"is after|'s after)(?P<rest>(?:\s+[^,;.!?]+?)?)(?P<end>\s*[.!]?)$"
)


def _not_its41r(text: str, lexicon: Lexicon) -> str:
    """Session 41 (12r): what is not wanted said first ("Not X", "Never mind (about) X", "Forget
    (about) X", "Leave X") then what is, as a cleft ("it's Y (that) P's after / wants / needs /
    asked for") is "P wants Y, not X": X and Y two objects named whole, P one person; what
    follows the verb (a purpose, a remark) is kept after it."""
    m = re.match(_NOT_ITS41R, text.strip(), _F)
    if m is None or not _objects34r(lexicon, m["x"], m["y"]):
        return text
    if not _only_person(m["p"], lexicon):
        return text
    return f"{m['p']} wants {m['y']}{m['rest']}, not {m['x']}{m['end'] or '.'}"


# "Never mind about the chips;" (what a cleft after it then names instead)
_LEFT_OUT_ONLY41R = (
    rf"^\s*(?:not|never mind(?: about)?|forget(?: about)?|skip) {_THING41R}(?:,? (?:mind|mind you|"
    r"though))?\s*[;.]\s*$"
)


def left_out_only41r(said: str) -> bool:
    """Session 41 (12r): whether ``said`` (what comes before a cleft: "Never mind about the
    chips;") only leaves an object out, so that the cleft after it ("it's the bottle P wants")
    says what is wanted instead, not something added to or correcting a request (session 31's
    refusal, offline._parse, asks this first; `_not_its41r` reads the two together)."""
    return re.match(_LEFT_OUT_ONLY41R, said, _F) is not None


# "Hand the cup to Person A, forget about the apple for her."
_FORGET_AFTER41R = (
    r"\s*[,;]\s*(?:and |but |just )?(?:forget|never mind|skip|leave out|"
    rf"don't bother with|no need for)(?: about)? (?P<x>{_THING41R})(?P<forwho> (?:for|from) "
    r"(?:her|him|them))?(?P<end>\s*[.!]?)$"
)


def _forget_after41r(text: str, lexicon: Lexicon) -> str:
    """Session 41 (12r): a request then ", forget (about) X (for her)" (never mind, skip, leave
    out, don't bother with, no need for X) is the request then ", not X" (session 25's leaving
    out, checked by the grammar, 'for her' kept for the grammar's pronoun checks): X an object
    named whole that the request names nowhere, nor 'it' / 'them'."""
    low = text.lower()
    if not any(w in low for w in ("forget", "never mind", "skip", "leave out", "bother", "need")):
        return text
    m = re.search(_FORGET_AFTER41R, text, _F)
    if m is None or not _whole_name(m["x"], lexicon, "object"):
        return text
    head = text[: m.start()]
    if re.search(r"[.!?]", head):
        return text  # a sentence of its own after the request: changing it, or a task
    named = _ids(head, lexicon, "object")
    if not named or named & _ids(m["x"], lexicon, "object"):
        return text
    if re.search(r"\b(?:it|them|that|those|this|these)\b", head, _F):
        return text
    said = f"{head}, not {m['x']}{m['forwho'] or ''}{m['end'] or '.'}"
    return said if _reading(said, lexicon) is not None else text


# "Mr Lee's to have the grey blanket; the blue one's not for him."
_NOT_FOR_AFTER41R = (
    r"\s*[,;]\s*(?:but |and )?(?P<x>the [a-z]+(?: [a-z]+)?)(?:'s| is)(?: not|n't) (?:for|meant for)"
    r" (?P<who>her|him)(?P<end>\s*[.!]?)$"
)


def _not_for_after41r(text: str, lexicon: Lexicon) -> str:
    """Session 41 (12r): a request then "; X's not for him (her)" (X isn't for her) is the
    request then ", not X" (the grammar's leaving out, 'the blue one' read against the objects
    the request names): X another object than the request's, the pronoun kept for the grammar
    ("…, not the blue one for him"), and the reading the request's alone."""
    if " for " not in text:
        return text
    m = re.search(_NOT_FOR_AFTER41R, text, _F)
    if m is None:
        return text
    head = text[: m.start()]
    said = f"{head}, not {m['x']} for {m['who']}{m['end'] or '.'}"
    before, after = _reading(head, lexicon), _reading(said, lexicon)
    if before is None or after is None or normalise(before) != normalise(after):
        return text
    return said


# "Nothing to wait for, the bottle can go to Person A straight off."
_NO_WAIT41R = (
    r"^(?:there's |there is )?(?:nothing to wait (?:for|on)|no (?:call|reason) to wait"
    r"(?: (?:for anyone|for anything|around|about))?|no waiting(?: around)?|no (?:rush|hurry)"
    r"(?: either way)?|no point waiting(?: around)?)\s*[,;:]\s*(?=[a-z])"
)
# "…, straight off."
_STRAIGHT_OFF41R = r",? (?:straight|right) off(?P<end>\s*[.!]?)$"


def _no_wait41r(text: str, _lexicon: Lexicon) -> str:
    """Session 41 (12r): an opener saying nothing holds the request up ("Nothing to wait for",
    "No reason to wait", "No rush", "No point waiting") is dropped before the request (as
    session 40's "No need to ask" and session 37's "No need to wait"), and "straight off" /
    "right off" closing it is "straight away" (when, not where)."""
    out = text
    m = re.match(_NO_WAIT41R, out, _F)
    if m is not None:
        out = _capital40r(out[m.end() :])
    if " off" in out:
        out = re.sub(_STRAIGHT_OFF41R, lambda k: f" straight away{k['end']}", out, flags=_F)
    return out


# "Whatever's left that isn't the bottle goes to Person A."
_LEFT_THAT_ISNT41R = (
    r"\b(?P<w>whatever|anything|everything)(?:'s| is)? (?:left|remaining|over|left over) "
    r"(?:that|which)(?: isn't| is not|'s not)(?= the )"
)


def _left_that_isnt41r(text: str, _lexicon: Lexicon) -> str:
    """Session 41 (12r): "whatever's left that isn't X" (anything remaining that's not X) is
    "whatever isn't X" ("anything that isn't X"; session 30's reading: every object but X):
    'left' says no more than the leaving out does."""
    low = text.lower()
    if "left" not in low and "remain" not in low and "over" not in low:
        return text

    def said(m: re.Match[str]) -> str:
        return f"{m['w']} isn't" if m["w"].lower() == "whatever" else f"{m['w']} that isn't"

    return re.sub(_LEFT_THAT_ISNT41R, said, text, flags=_F)


# "Tom doesn't need the scanner, give him the tape instead."
_NOT_NEEDED_INSTEAD41R = (
    rf"^(?P<p>{_NAME40R}) (?:doesn't|does not|won't|will not) (?:need|want) (?P<x>{_THING41R})"
    rf"(?: (?:today|now|any ?more))?\s*[,;]\s*(?P<rest>.+?) instead(?P<end>\s*[.!]?)$"
)
# "Keep the wipes away from Lily and give her the teddy instead."
_KEEP_AWAY41R = (
    rf"^(?:please )?(?:keep|hold) (?P<x>{_THING41R}) (?:away from|back from|out of reach of) "
    rf"(?P<p>{_NAME40R})\s*(?:,|and|, and)\s*(?P<rest>.+?)(?: instead)?(?P<end>\s*[.!]?)$"
)


def _instead_of_unwanted41r(text: str, lexicon: Lexicon) -> str:
    """Session 41 (12r): what one person is not to have, then the request "instead": "P doesn't
    need (want) X, give her Y instead", "Keep X away from P and give her Y instead" are "P
    doesn't want X, give her Y" (session 39's reading: what is not wanted dropped beside a
    request that names neither it nor 'it'): the 'instead' puts Y in X's place, nothing
    running is changed."""
    low = text.lower()
    if "instead" not in low and "away from" not in low and "reach of" not in low:
        return text
    m = re.match(_NOT_NEEDED_INSTEAD41R, text.strip(), _F) or re.match(
        _KEEP_AWAY41R, text.strip(), _F
    )
    if m is None or not _only_person(m["p"], lexicon):
        return text
    if not _whole_name(m["x"], lexicon, "object"):
        return text
    named = _ids(m["rest"], lexicon, "object")
    if not named or named & _ids(m["x"], lexicon, "object"):
        return text
    if re.search(r"\b(?:it|them|that|those|this|these)\b", m["rest"], _F):
        return text
    return f"{m['p']} doesn't want {m['x']}, {m['rest']}{m['end'] or '.'}"


# -- choice and distribution idioms ----------------------------------------------------------------

# "…, I'll let you pick.", "…, take your pick.", "…, grab whichever is handy."
_LEFT_TO_YOU41R = (
    r"\s*[,;]\s*(?:and |so |just )?(?:(?:i'll|i will|i'd|we'll|we will) let you (?:pick|choose|"
    r"decide)(?: which(?: one)?| who)?|(?:you|just) pick(?: one| which)?|take your pick|"
    r"(?:grab|take|pick|use|bring) whichever(?: one)?(?: is|'s) (?:handy|closest|nearest|easiest|"
    r"to hand|nearer|quickest)|as you (?:like|please|see fit)|however you like|i'm easy|"
    r"i don't mind which(?: one)?|either will do|any will do|any ?(?:one)?'ll do|either'll do)"
    r"(?P<end>\s*[.!]?)$"
)


def _left_to_you41r(text: str, lexicon: Lexicon) -> str:
    """Session 41 (12r): a choice left to the robot said as a closer of another shape ("I'll let
    you pick", "take your pick", "you pick", "grab whichever is handy", "as you like", "I'm easy",
    "I don't mind which") is ", your call" when the request offers a choice (read as that choice;
    a request without one is left, and refused)."""
    low = text.lower()
    if not any(
        w in low
        for w in (
            "pick",
            "let you",
            "whichever",
            "as you",
            "however",
            "easy",
            "mind which",
            "will do",
            "'ll do",
        )
    ):
        return text
    m = re.search(_LEFT_TO_YOU41R, text, _F)
    if m is None or not text[: m.start()].strip():
        return text
    out = f"{text[: m.start()]}, your call{m['end'] or '.'}"
    node = _reading(out, lexicon)
    return out if node is not None and has_choice(node) else text


# "Grandad or Ava, whichever's free, can take the teddy."
_WHICHEVER_FREE41R = (
    rf"^(?P<p>{_NAME40R}) or (?P<q>{_NAME40R})\s*,\s*(?:whichever|whoever|either)(?: of them| of "
    r"the two)?(?:'s| is) (?:free|free first|around|about|available|closest|nearest|handy|"
    r"quicker|less busy)\s*,\s*(?=(?:can|could|should|will|'ll|may|might) )"
)


def _whichever_free41r(text: str, lexicon: Lexicon) -> str:
    """Session 41 (12r): a choice of two people with an aside saying the robot may pick ("P or
    Q, whichever's free, can take X", whoever is around, either of them is available) is "P or
    Q can take X": the aside adds nothing to the choice the 'or' makes."""
    if " or " not in text:
        return text
    m = re.match(_WHICHEVER_FREE41R, text, _F)
    if m is None or not _persons34r(lexicon, m["p"], m["q"]):
        return text
    return f"{m['p']} or {m['q']} {text[m.end() :]}"


# "Stick a box on the conveyor, the small or the medium, your call."
_A_KIND_SAID41R = (
    r"\b(?:a|an|one) (?P<kind>[a-z]+)\b(?P<mid>(?:(?!\b(?:not|but|except|bar|apart|other|save|"
    r"besides|without|no|never)\b)[^,;])*?)\s*,\s*(?:either )?the (?P<a>[a-z]+)"
    r"(?: one)? or the (?P<b>[a-z]+)(?: one)?(?=\s*(?:[,;.!]|$))"
)


def _a_kind_said41r(text: str, lexicon: Lexicon) -> str:
    """Session 41 (12r): "a box …, the small or the medium (one)" says which boxes the choice
    is between: "the small box or the medium box …" (each an object of the scene named whole,
    of the kind said, two apart), when that reads; 'one' of another kind, a word naming none, or
    a rewrite that does not read ("The belt needs one box on it, …": the older rules') is left."""
    if " or the " not in text:
        return text
    m = re.search(_A_KIND_SAID41R, text, _F)
    if m is None:
        return text
    kind = m["kind"].lower()
    a, b = (f"the {m[k].lower()} {kind}" for k in ("a", "b"))
    if not _objects34r(lexicon, a, b):
        return text
    ids = _ids(a, lexicon, "object") | _ids(b, lexicon, "object")
    if not ids <= _ids(f"the {kind}", lexicon, "object") | _ids(f"the {kind}s", lexicon, "object"):
        return text
    out = f"{text[: m.start()]}{a} or {b}{m['mid']}{text[m.end() :]}"
    return out if _reading(out, lexicon) is not None else text


# "Person B isn't fussy between the chips and the bottle, bring whichever's closest."
_FUSSY_BETWEEN41R = (
    rf"^(?P<p>{_NAME40R})(?:'s| is)(?: not|n't) (?:fussy|picky|choosy|bothered|particular) "
    rf"(?:between|about|over) (?P<x>{_THING41R}) (?:and|or) (?P<y>{_THING41R})\s*[,;]\s*(?:so )?"
    r"(?P<v>bring|give|hand|pass|take|fetch)(?: (?:him|her|them))? (?P<w>whichever(?: one)?(?:'s| "
    r"is) (?:closest|nearest|handy|easiest|nearer|to hand)|whichever(?: one)?|either(?: one)?)"
    r"(?P<end>\s*[.!]?)$"
)


def _fussy_between41r(text: str, lexicon: Lexicon) -> str:
    """Session 41 (12r): "P isn't fussy between X and Y, bring whichever's closest" (picky,
    bothered about X or Y; bring him either) is "Bring P X or Y, whichever's closest": the
    choice between the two objects left to the robot."""
    if "between" not in text and "about" not in text and "over" not in text:
        return text
    m = re.match(_FUSSY_BETWEEN41R, text.strip(), _F)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    if not _objects34r(lexicon, m["x"], m["y"]):
        return text
    w = "whichever" if m["w"].lower().startswith("either") else m["w"]
    return f"{_capital40r(m['v'])} {m['p']} {m['x']} or {m['y']}, {w}{m['end'] or '.'}"


# "Sam can take whatever pen he likes so long as it isn't the red one."
_SO_LONG_AS41R = (
    rf"^(?P<head>{_NAME40R} (?:can|could|may|might) (?:take|have|grab|pick)) (?:whatever|whichever"
    r"|any) (?P<kind>[a-z]+) (?:he|she|they) (?:likes?|wants?|fancies|fancy|prefers?)\s*,?\s*"
    r"(?:so long as|as long as|provided|providing|just|only)(?: that)? (?:it(?:'s not| isn't| is "
    r"not)|not) (?P<x>the [a-z]+(?: one)?)(?P<end>\s*(?:[,;.!]|$))"
)


def _so_long_as41r(text: str, lexicon: Lexicon) -> str:
    """Session 41 (12r): "P can take whatever pen he likes so long as it isn't the red one"
    (whichever, any X she wants, as long as / provided it's not Y, just not Y) is "P can take any
    pen but the red one" (session 30's choice with one left out, checked by the grammar)."""
    if "long as" not in text and "provid" not in text and " not " not in text.lower():
        return text
    m = re.match(_SO_LONG_AS41R, text, _F)
    if m is None:
        return text
    return f"{m['head']} any {m['kind']} but {m['x']}{m['end']}{text[m.end() :]}"


# "Give one of them the crisps, Alice or Bob"
_ONE_OF_THEM_GETS41R = (
    r"^(?P<v>give|hand|pass|bring|take) one of (?:them|the two|the two of them|you two) "
    rf"(?P<x>{_THING41R})\s*,\s*(?:either )?(?P<p>{_NAME40R}) or (?P<q>{_NAME40R})"
    r"(?=\s*(?:[.!]|$|,\s*(?:your call|your choice|up to you|whichever|i'll let you pick|you pick|"
    r"take your pick)\b))"
)


def _one_of_them_gets41r(text: str, lexicon: Lexicon) -> str:
    """Session 41 (12r): "Give one of them X, P or Q" (the one said after) is "Give X to P or
    Q": a choice of the two people named."""
    if "one of" not in text.lower():
        return text
    m = re.match(_ONE_OF_THEM_GETS41R, text, _F)
    if m is None or not _persons34r(lexicon, m["p"], m["q"]):
        return text
    if not _whole_name(m["x"], lexicon, "object"):
        return text
    return f"{m['v']} {m['x']} to {m['p']} or {m['q']}{text[m.end() :]}"


# a distribution announced, then spelled out: "A drink apiece for the crumhorn duo: …", "Share
# them out, one apiece: …", "Split the four things down the middle: …", "Each student gets a
# book: …"
_SHARED_OUT41R = (
    r"^(?:(?P<a>(?:a|an|one) [a-z]+ (?:apiece|each)(?: for (?:the|both|all)[a-z' ]*|"
    rf" for (?P<p1>{_NAME40R}) and (?P<p2>{_NAME40R}))?)|"
    r"(?P<b>(?:share|split|divide|dish|deal|hand|parcel) (?:out |up )?(?:them|these|those|the lot|"
    r"it|(?:the|all|these) (?:(?P<n>two|three|four|five|six) )?(?:things|items|bits|lot)|the "
    r"(?P<kinds>[a-z]+s))(?: out| up)?(?: between (?:them|the two(?: of them)?|both(?: of them)?|"
    rf"the pair|(?P<p3>{_NAME40R}) and (?P<p4>{_NAME40R}))| down the middle| evenly| fairly)?"
    r"(?:\s*,\s*(?:one|a thing|one thing) (?:apiece|each))?)|"
    r"(?P<d>the (?P<kinds2>[a-z]+s) (?:are|is) to be (?:shared|split|divided)(?: out| up)?"
    r"(?: between (?:them|the two|both))?)|"
    r"(?P<c>(?:each|every) (?P<role>[a-z]+) (?:gets|has|takes|is getting|is having) (?:a|an|one) "
    r"[a-z]+))\s*:\s*(?P<rest>\S.*)$"
)


def _shared_out41r(text: str, lexicon: Lexicon) -> str:
    """Session 41 (12r): a distribution announced, then spelled out after a colon ("A drink
    apiece for the duo: cup to A, bottle to B", "Share them out, one apiece: …", "Split the
    four things down the middle: …", "Each student gets a book: …") is the list, when the list
    reads as hand-overs that fit what was announced: 'apiece' / 'each' every person listed
    once and one object each; 'each <role>' every person the role names, and only them; a
    split down the middle as many objects to each; a count, that many objects; "the mugs" (are to
    be shared) every mug, and only them; "between P and Q", "for P and Q" those two people.
    "One mug each for P and Q: …", "Share the mugs between P and Q: …", "The mugs are to be
    shared: …" say the same."""
    if ":" not in text:
        return text
    m = re.match(_SHARED_OUT41R, text.strip(), _F)
    if m is None:
        return text
    rest = _capital40r(m["rest"])
    said = _handovers33t(rest, lexicon)
    if said is None or len(said) < 2:
        return text
    people = [t.target for t in said]
    objects = [t.obj for t in said]
    if len(set(objects)) != len(objects) or len(set(people)) < 2:
        return text
    head = m[0].lower()
    if ("apiece" in head or "each" in head) and len(set(people)) != len(people):
        return text
    if m["role"] is not None:
        role = _ids(f"the {m['role']}", lexicon, "human") or _ids(
            f"the {m['role']}s", lexicon, "human"
        )
        if len(role) < 2 or set(people) != role or len(set(people)) != len(people):
            return text
    if "middle" in head or "evenly" in head or "fairly" in head:
        counts = {p: people.count(p) for p in people}
        if len(set(counts.values())) != 1:
            return text
    if m["n"] is not None and len(objects) != _COUNT41R[m["n"].lower()]:
        return text
    named = [(m["p1"], m["p2"]), (m["p3"], m["p4"])]
    for p, q in named:
        if p is not None and (
            not _persons34r(lexicon, p, q) or set(people) != _ids(f"{p} and {q}", lexicon, "human")
        ):
            return text
    kinds = m["kinds"] or m["kinds2"]
    if kinds is not None:
        ids = _ids(f"the {kinds}", lexicon, "object")
        if len(ids) < 2 or set(objects) != ids:
            return text
    return rest


_COUNT41R = {"two": 2, "three": 3, "four": 4, "five": 5, "six": 6}


# -- counts ----------------------------------------------------------------------------------------

# "The pair of them to Person B, …", "The both of the plates …", "The trio of pens …"
_PAIR_OF41R = (
    r"\bthe (?:(?P<two>pair|couple) of them|(?P<both>both) of (?:them|the (?P<ks>[a-z]+s))|"
    r"(?P<three>trio) of (?:them|(?:the )?(?P<ks3>[a-z]+s)))\b(?!\s+one each)"
)


def _pair_of41r(text: str, lexicon: Lexicon) -> str:
    """Session 41 (12r): a count said as a collective noun, "the pair (couple) of them", "the
    both of them / of the plates", "the trio of them / of pens", is "both of them", "both of the
    plates", "all three of them", "the three pens" (the count then checked against the scene by
    the grammar: 'both' two, 'the three pens' three pens; "the pair of cups, the green and the
    white" is session 37's, "the two of them" the grammar's)."""
    low = text.lower()
    if " of " not in low or not any(w in low for w in ("pair", "both", "couple", "trio")):
        return text

    def said(m: re.Match[str]) -> str:
        out = count(m)
        return _capital40r(out) if m[0][:1].isupper() else out

    def count(m: re.Match[str]) -> str:
        if m["two"] is not None:
            return "both of them"
        if m["both"] is not None:
            return f"both of the {m['ks']}" if m["ks"] else "both of them"
        return f"the three {m['ks3']}" if m["ks3"] else "all three of them"

    return re.sub(_PAIR_OF41R, said, text, flags=_F)


# "The pair of them to Person B, bottle and chips."
_PAIR_LISTED41R = (
    r"^the (?:(?P<two>pair|both|two|couple)|(?P<three>trio|three)) of them (?P<to>to|for) "
    rf"(?P<p>{_NAME40R})\s*,\s*(?P<list>(?:the )?[a-z]+(?: [a-z]+)?(?:(?:,| and|, and) (?:the )?"
    r"[a-z]+(?: [a-z]+)?)+)(?P<end>\s*[.!]?)$"
)


def _pair_listed41r(text: str, lexicon: Lexicon) -> str:
    """Session 41 (12r): "The pair of them to P, X and Y" (the both, the two of them; "the trio
    of them to P, X, Y and Z") is "X and Y to P": the objects listed after, as many as the
    collective noun counts, each named whole, one person."""
    if " of them " not in text:
        return text
    m = re.match(_PAIR_LISTED41R, text.strip(), _F)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    items = [w.strip() for w in re.split(r",\s*(?:and\s+)?|\s+and\s+", m["list"]) if w.strip()]
    if len(items) != (2 if m["two"] else 3):
        return text
    if not _objects34r(
        lexicon, *(w if w.lower().startswith("the ") else f"the {w}" for w in items)
    ):
        return text
    return f"{_capital40r(m['list'])} {m['to']} {m['p']}{m['end'] or '.'}"


# "Person A's taking all four of them."
_ALL_N_OF_THEM41R = (
    r"\b(?P<v>taking|takes|take|gets|get|getting|having|has|have|gets to have|can have) all "
    r"(?P<n>two|three|four|five|six) of (?:them|these|those)\b"
)


def _all_n_of_them41r(text: str, lexicon: Lexicon) -> str:
    """Session 41 (12r): "P's taking (gets, can have) all four of them" is "… all four things"
    (what the grammar checks against the scene's objects: refused where the scene has another
    count), 'them' after a verb of getting the objects."""
    if "all " not in text.lower():
        return text

    def said(m: re.Match[str]) -> str:
        # "P's taking all four": P gets them (the grammar reads 'P's getting all four things')
        v = "getting" if m["v"].lower() == "taking" else m["v"]
        return f"{v} all {m['n']} things"

    return re.sub(_ALL_N_OF_THEM41R, said, text, flags=_F)


# "Up on the shelf with the pair of them, the bottle and the crisps."
_ONTO_WITH41R = (
    r"^(?:(?:up|down|back|over|out) )?(?P<prep>on|onto|in|into|on top of|inside) (?P<s>the "
    r"[a-z]+(?: [a-z]+)?) with (?:(?:both of them|all of them|the lot|them all|all three of them)"
    r"\s*,\s*)?(?P<list>the [a-z]+(?: [a-z]+)?(?:(?:,| and|, and) the [a-z]+(?: [a-z]+)?)+)"
    r"(?P<end>\s*(?:[,;.!]|$))"
)


def _onto_with41r(text: str, lexicon: Lexicon) -> str:
    """Session 41 (12r): "(Up) on the shelf with the bottle and the crisps" (into the box with
    X, Y and Z; 'with the pair of them, X and Y') is "Put the bottle and the crisps on the shelf"
    (as "Onto the shelf with the bottle" reads): S a surface named whole."""
    if " with " not in text:
        return text
    m = re.match(_ONTO_WITH41R, text.strip(), _F)
    if m is None or not _whole_name(m["s"], lexicon, "surface"):
        return text
    return f"Put {m['list']} {m['prep']} {m['s']}{m['end']}{text.strip()[m.end() :]}"


# "…, it's the only one anyway."
_ONLY_ONE_ANYWAY41R = (
    r"\b(?P<h>(?:it's|it is|that's|that is) the only one(?: (?:left|there is|we have))?),? "
    r"(?:anyway|anyhow|in any case|after all)(?=\s*(?:[,;.!]|$))"
)


def _only_one_anyway41r(text: str, _lexicon: Lexicon) -> str:
    """Session 41 (12r): ", it's the only one anyway" (anyhow, in any case, after all) is ",
    it's the only one" (what the grammar checks against the scene)."""
    if "only one" not in text.lower():
        return text
    return re.sub(_ONLY_ONE_ANYWAY41R, lambda m: m["h"], text, flags=_F)


# "One bottle and one person in the room, so Person A gets it."
_ONE_AND_ONE41R = (
    r"^(?:there's |there is |with |we've got |we have )?(?:(?:just|only) )?(?:one|a single) "
    r"(?P<x>[a-z]+) and (?:(?:just|only) )?(?:one|a single) (?:person|human|recipient)"
    r"(?: (?:in the room|here|about|around|in here))?\s*,\s*(?:so |and )(?P<rest>\S.*)$"
)


def _one_and_one41r(text: str, lexicon: Lexicon) -> str:
    """Session 41 (12r): "One bottle and one person in the room, so <request>" is the request,
    when the scene has that: one object of that name and one person (a count the scene does
    not bear out is left, and refused)."""
    low = text.lower()
    if "one " not in low and "single" not in low:
        return text
    m = re.match(_ONE_AND_ONE41R, text.strip(), _F)
    if m is None or len(lexicon.scene.humans) != 1:
        return text
    if len(_ids(f"the {m['x']}", lexicon, "object")) != 1:
        return text
    return _capital40r(re.sub(r"\bit\b", f"the {m['x']}", m["rest"], count=1, flags=_F))


# ", plain and simple."
_PLAIN_SIMPLE41R = (
    r"\s*,\s*(?:plain and simple|simple as that|pure and simple|nice and simple|and that's that|"
    r"and that's all)(?P<end>\s*[.!]?)$"
)


def _plain_simple41r(text: str, _lexicon: Lexicon) -> str:
    """Session 41 (12r): a closer saying the request is all there is ("plain and simple", "pure
    and simple", "simple as that", "and that's that") is dropped."""
    if "simple" not in text.lower() and "that's" not in text.lower():
        return text
    return re.sub(_PLAIN_SIMPLE41R, lambda m: m["end"], text, flags=_F)


# -- corrections -----------------------------------------------------------------------------------

# a correction said with a run of cue words: ", oh no, hang about, ", ", oh scratch that, ", ",
# no, correction, ", ", oh, silly me, "
_CUE_WORD41R = (
    r"(?:oh|ah|no|nope|wait|hang on|hang about|hold on|hold up|scratch that|strike that|silly me|"
    r"daft me|my mistake|my bad|what am i saying|correction|sorry|i tell a lie)"
)
_STRONG_CUE41R = (
    r"\b(?:no|nope|wait|hang on|hang about|hold on|hold up|scratch that|strike that|silly me|"
    r"daft me|my mistake|my bad|what am i saying|correction|i tell a lie)\b"
)
_CUE_RUN41R = rf"\s*[,;]\s*(?P<run>{_CUE_WORD41R}(?:[\s,]+{_CUE_WORD41R})*)\s*[,;]?\s+(?=[a-z])"
# what a single cue the earlier rules read already is said as
_ONE_CUE41R = r"(?:no,?\s*(?:wait|hang on|hold on|sorry|correction|my mistake))"
# cues the older rules do not read (or read only alone): enough alone in a run ("oh wait")
_NEW_CUE41R = r"\b(?:scratch that|strike that|silly me|daft me|my bad)\b|^(?:oh|ah),?\s*wait$"


def _cue_run41r(text: str, lexicon: Lexicon) -> str:
    """Session 41 (12r): a correction said with a run of cue words ("oh no, hang about",
    "oh scratch that", "no, correction", "oh, silly me", "oh wait") is ", no, " (the cue the
    grammar's corrections read): a run of two cues ('no', 'wait', 'hang on / about',
    'correction' …; not "no wait", "no, hang on", which the older rules read), or one the older
    rules do not read ('scratch that', 'silly me', 'my bad', "oh wait"); a rewrite that does not
    read, or reads as the request before it did (a correction naming what was said), is left."""
    m = re.search(_CUE_RUN41R, text, _F)
    if m is None or m.start() == 0:
        return text
    run = m["run"]
    strong = re.findall(_STRONG_CUE41R, run, _F)
    # a new cue alone ("scratch that, …") is session 39's; said after 'oh' / 'no' it is ours
    new = re.search(_NEW_CUE41R, run, _F) is not None and (
        re.match(r"(?:oh|ah|no)\b", run, _F) is not None
    )
    if not new and (len(strong) < 2 or re.fullmatch(_ONE_CUE41R, run.strip(" ,"), _F)):
        return text
    out = f"{text[: m.start()]}, no, {text[m.end() :]}"
    after = _reading(out, lexicon)
    if after is None or after == _reading(text[: m.start()], lexicon):
        return text  # a correction naming what the request said is no correction
    return out


# "…, no, straight to Alice."
_STRAIGHT_TO41R = (
    r"(?P<cue>,\s*no,\s*)(?:straight|directly|right|just) (?=(?:to|over to|across to) )"
)


def _straight_to41r(text: str, _lexicon: Lexicon) -> str:
    """Session 41 (12r): a correction "…, no, straight to P" (directly to, right over to) is
    "…, no, to P": the adverb says how, the correction where ('up on the shelf' before it is
    'on the shelf', the place the correction replaces)."""
    if "no," not in text.lower():
        return text
    m = re.search(_STRAIGHT_TO41R, text, _F)
    if m is None:
        return text
    head = re.sub(
        r"\b(?:up|down|back) (?=(?:on|onto|on top of|in|into) the )",
        "",
        text[: m.start()],
        flags=_F,
    )
    return f"{head}{m['cue']}{text[m.end() :]}"


# "…, no, Mrs Khan's the one they're prescribed for."
_THE_ONE_FOR41R = (
    r"(?P<cue>,\s*no,?\s*(?:(?:hang|hold) on|wait)?,\s*)"
    rf"(?:(?:(?<=on, )|(?<=wait, ))it(?:'s| is) (?P<own>{_NAME40R})'s|(?P<q>{_NAME40R})(?:'s| is) "
    r"the one (?:(?:it's|it is|they're|they are|"
    r"that's|that is) (?:for|meant for|prescribed for|intended for|ordered for|needed for)|(?:who|"
    r"that) (?:gets|wants|needs|asked for|ordered|is getting) (?:it|them)))(?P<end>\s*(?:[,;.!]|$))"
)


def _the_one_for41r(text: str, lexicon: Lexicon) -> str:
    """Session 41 (12r): a correction naming the right person as "Q's the one they're (it's)
    for / prescribed for", "Q's the one who gets it", "it's Q's" is "…, no, Q" (the grammar's
    correction of the person): Q one person of the scene."""
    if " one " not in text and "'s" not in text:
        return text
    m = re.search(_THE_ONE_FOR41R, text, _F)
    q = None if m is None else m["q"] or m["own"]
    if m is None or q is None or not _only_person(q, lexicon):
        return text
    return f"{text[: m.start()]}{m['cue']}{q}{m['end']}{text[m.end() :]}"


# "Person A gets chips, no, she gets the bottle."
_PRONOUN_AGAIN41R = (
    r"(?P<cue>,\s*no,\s*(?:correction,\s*)?)(?P<pro>she|he|they)(?: (?:gets|wants|needs|takes|"
    r"should get|can have)|"
    r"(?:'s| is) (?:getting|having|after|to have)|'ll have|'d like) "
    rf"(?P<x>{_THING41R})(?: instead)?(?P<end>\s*(?:[,;.!]|$))"
)


def _pronoun_again41r(text: str, lexicon: Lexicon) -> str:
    """Session 41 (12r): a correction that says the same person again as a pronoun, "P gets the
    chips, no, she gets (wants, is having) the bottle (instead)", is "…, no, the bottle" (the
    grammar's correction of the object), when the request before it gives one person something
    and the pronoun may be that person (a title, a word of kin or a first name of the other
    sex rules it out)."""
    if "no," not in text.lower():
        return text
    m = re.search(_PRONOUN_AGAIN41R, text, _F)
    if m is None or not _whole_name(m["x"], lexicon, "object"):
        return text
    node = _reading(text[: m.start()], lexicon)
    if node is None:
        return text
    people = {t.target for t in tasks(node) if t.kind == "deliver"}
    if len(people) != 1:
        return text
    (pid,) = people
    pro = m["pro"].lower()
    if pro != "they":
        sex = said_sex35s(pid, lexicon) or first_name_sex36s(pid, lexicon)
        if sex is not None and sex != PRONOUN_SEX[pro]:
            return text
    return f"{text[: m.start()]}, no, {m['x']}{m['end']}{text[m.end() :]}"


# "Person A gets chips, no, the bottle; the chips are Person B's."
_CORRECTED_THEN41R = (
    rf"^(?P<head>[^;]+?,\s*no,\s*(?P<y>{_THING41R}))(?P<sep>\s*;\s*)(?P<rest>\S[^;]*)$"
)


def _corrected_then41r(text: str, lexicon: Lexicon) -> str:
    """Session 41 (12r): a request with its object corrected, then another clause after a
    semicolon ("P gets the chips, no, the bottle; the chips are Q's") is the corrected request
    then that clause ("P gets the bottle; the chips are Q's"): the correction read alone first (one
    hand-over), and the whole then read."""
    if "no," not in text.lower() or ";" not in text:
        return text
    m = re.match(_CORRECTED_THEN41R, text.strip(), _F)
    if m is None:
        return text
    node = _reading(m["head"], lexicon)
    if not isinstance(node, Task) or node.kind != "deliver":
        return text
    name = person_name(node.target, lexicon).split(" (")[0]
    out = f"{name} gets {m['y']}{m['sep']}{m['rest']}"
    return out if _reading(out, lexicon) is not None else text


# "Bottle for Person A; sorry, I said that already, just the once."
_SAID_ALREADY41R = (
    r"\s*[;.,]\s*(?:sorry|oops|ah)?,?\s*(?:i(?:'ve| have)?|i think i(?:'ve| have)?) "
    r"(?:said|told you|asked(?: for)?|mentioned) (?:that|this|it) (?:already|before|earlier)"
    r"(?:\s*,\s*(?:just|only) (?:the )?once| (?:just|only) (?:the )?once)?(?P<end>\s*[.!]?)$"
)


def _said_already41r(text: str, _lexicon: Lexicon) -> str:
    """Session 41 (12r): a request then "sorry, I said that already (, just the once)" says the
    request is not a second one: the remark is dropped (one request, done once)."""
    if "already" not in text and "before" not in text and "earlier" not in text:
        return text
    m = re.search(_SAID_ALREADY41R, text, _F)
    if m is None or not text[: m.start()].strip():
        return text
    return f"{text[: m.start()]}{m['end'] or '.'}"


# -- closers, durations, words of place and count --------------------------------------------------

# "…, just those, nothing more for him."
_JUST_THOSE41R = (
    r"\s*,\s*(?:(?:just|only) (?:those|that|them|these|this)(?:\s*,\s*|\s+and\s+)?)?"
    r"(?:nothing (?:more|else)(?: for (?:him|her|them))?|no more|that's (?:it|all))?"
    r"(?P<end>\s*[.!]?)$"
)
# a cue before the closer makes it a correction ("The pens to Sam, sorry, just the one")
_CUE_BEFORE41R = (
    r"\b(?:sorry|no|oh|actually|wait|hang on|hold on|correction|i mean|rather)\s*,?\s*$"
)


def _just_those41r(text: str, lexicon: Lexicon) -> str:
    """Session 41 (12r): a request then "just those (that)", "nothing more (else) for him",
    "that's all" says the request is all there is: dropped when the request before it reads
    alone and gives its objects to one person ("him" / "her" then that person by the grammar's
    reading of the request, which the closer only repeats); after a cue ('sorry', 'no') it
    corrects the request, and is left."""
    low = text.lower()
    if "just" not in low and "only" not in low and "nothing" not in low and "that's" not in low:
        return text
    m = re.search(_JUST_THOSE41R, text, _F)
    if m is None or m.start() == m.end() - len(m["end"] or ""):
        return text
    head = text[: m.start()]
    if re.search(_CUE_BEFORE41R, head, _F):
        return text
    node = _reading(head, lexicon)
    if node is None or has_choice(node):
        return text
    if len({t.target for t in tasks(node)}) != 1:
        return text
    return f"{head}{m['end'] or '.'}"


# "…, and last of all Tom gets the tape."; "Zoe's been asking for the scissors all lesson."
_OF_ALL41R = r"\b(?P<w>first|last|next) of all\b"
_ALL_TIME41R = (
    r"(?P<want>\b(?:asking for|asked for|after|wanting|waiting for|on about|going on about|"
    r"begging for|pestering me for|nagging for) (?:the )?[a-z]+(?: [a-z]+)?)\s+all (?:lesson|"
    r"morning|day|afternoon|evening|night|week|session|shift|class|term|break|lunch|lunchtime|"
    r"match|game|meeting)(?: long)?(?=\s*(?:[,;.!]|$))"
)


def _of_all41r(text: str, lexicon: Lexicon) -> str:
    """Session 41 (12r): 'all' that counts nothing: "last (first, next) of all" is "last", and
    "all lesson (morning, day …)" after what someone has been asking for (after, waiting for)
    says how long, not which objects: dropped from a single clause where what is left reads
    (else left for the older rules)."""
    if "all" not in text.lower():
        return text
    out = re.sub(_OF_ALL41R, lambda m: m["w"], text, flags=_F)
    if "," in out or ";" in out:
        return out  # a remark around it is the older rules' to take off, 'all day' with it
    cut = re.sub(_ALL_TIME41R, lambda m: m["want"], out, flags=_F)
    if cut != out and _reading(cut, lexicon) is None:
        return out
    return cut


# "The both of the plates out on the counter"
_OUT_ON41R = (
    r"^(?P<what>(?:the|both|all|these|those) [^,;.!?]*?) out (?P<prep>on|onto|on to) "
    r"(?P<s>the [a-z]+)(?P<s2> [a-z]+)?\b"
)

# "… leave the bowl out on the tray …"
_LEAVE_OUT_ON41R = (
    r"\b(?P<head>leave (?:the [a-z]+(?: [a-z]+)?|it|them)) out (?:on|onto|on to) "
    r"(?P<s>the [a-z]+)\b"
)


def _out_on41r(text: str, lexicon: Lexicon) -> str:
    """Session 41 (12r): a verbless placing "The X out on the counter" (out onto S) is "The X on
    the counter": 'out' says the thing is set out, the surface where (S a surface named whole),
    and "leave X out on S" is "leave X on S"; after another verb ("wants X left out on", "laying X
    out on") it is the verb's, and left."""
    if " out " not in text:
        return text

    leave = re.search(_LEAVE_OUT_ON41R, text, _F)
    if leave is not None and _whole_name(leave["s"], lexicon, "surface"):
        return f"{text[: leave.start()]}{leave['head']} on {leave['s']}{text[leave.end() :]}"
    m = re.match(_OUT_ON41R, text, _F)
    if m is None or re.search(
        r"\b(?:put|set|lay|laid|laying|left|leave|leaving|get)\b", m["what"], _F
    ):
        return text
    if m["s2"] and _whole_name(m["s"] + m["s2"], lexicon, "surface"):
        return f"{m['what']} on {m['s']}{m['s2']}{text[m.end() :]}"
    if _whole_name(m["s"], lexicon, "surface"):
        return f"{m['what']} on {m['s']}{m['s2'] or ''}{text[m.end() :]}"
    return text


# "There's only the one bottle going"
_ONE_GOING41R = (
    r"\b(?P<h>(?:only|just) (?:the )?one [a-z]+) (?:going spare|going|spare|about|around|"
    r"available|to go round|to go around|on offer)\b"
)


def _one_going41r(text: str, _lexicon: Lexicon) -> str:
    """Session 41 (12r): "only the one X going (spare, about, to go round)" is "only the one X"
    (the count then checked against the scene by the grammar)."""
    if "one" not in text.lower():
        return text
    return re.sub(_ONE_GOING41R, lambda m: m["h"], text, flags=_F)


# "… and let her cuddle the teddy"
_LET_USE41R = (
    r"\blet (?P<p>her|him|them|[A-Z][\w]*(?: [A-Z][\w]*)?) (?:cuddle|hug|hold|play with|have a go "
    r"(?:with|on)|borrow|use|keep) (?=the )"
)


def _let_use41r(text: str, _lexicon: Lexicon) -> str:
    """Session 41 (12r): "let P cuddle (hug, hold, play with, borrow, use, keep) X" is "let P have
    X": letting someone hold or use a thing is handing it to them (the grammar reads "let P have
    X")."""
    if "let " not in text.lower():
        return text
    return re.sub(_LET_USE41R, lambda m: f"let {m['p']} have ", text, flags=_F)


# "Carol's not picky: a mug for her, …"
_NOT_PICKY41R = (
    rf"^(?P<p>{_NAME40R})(?:'s| is)(?: not|n't) (?:picky|fussy|choosy|bothered|particular)"
    r"\s*:\s*(?=\S)"
)


def _not_picky41r(text: str, lexicon: Lexicon) -> str:
    """Session 41 (12r): "P's not picky (fussy, bothered):" opening a request that offers P a
    choice is that request (the choice says as much), its first 'her' / 'him' P (when P may be
    so called): P one person, the request read with a choice."""
    if "not" not in text.lower() and "n't" not in text:
        return text
    m = re.match(_NOT_PICKY41R, text, _F)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    rest = text[m.end() :]
    (pid,) = _ids(m["p"], lexicon, "human")
    pro = re.search(r"\b(?:her|him)\b", rest, _F)
    if pro is not None:
        sex = said_sex35s(pid, lexicon) or first_name_sex36s(pid, lexicon)
        if sex is not None and sex != PRONOUN_SEX[pro[0].lower()]:
            return text
        rest = f"{rest[: pro.start()]}{m['p']}{rest[pro.end() :]}"
    rest = _capital40r(rest)
    node = _reading(rest, lexicon)
    return rest if node is not None and has_choice(node) else text


# -- turning a thing down, said another way -------------------------------------------------------

# "Alice can do without the crisps, …", "No crisps for Alice, …"
_TURNS_DOWN41R = (
    rf"(?:^|(?<=[.;!?]\s))(?:(?P<p>{_NAME40R})(?: can do without| can manage without| could do "
    r"without|(?:'s| is) passing on| passes on|(?:'ll| will) pass on| can't stand| cannot stand|"
    r" has no use for|(?:'s| has) got no use for| has no need (?:of|for)| doesn't fancy| does not "
    r"fancy| doesn't care for| does not care for|(?: isn't| is not|'s not) keen on|(?:'s| has) "
    r"turned down| turned down) (?P<x>(?:the )?[a-z]+(?: [a-z]+)?)|no (?P<y>(?:the )?[a-z]+"
    rf"(?: [a-z]+)?) for (?P<q>{_NAME40R}))\s*[,;]\s*(?=[a-z])"
)


def _turns_down41r(text: str, lexicon: Lexicon) -> str:
    """Session 41 (12r): a person turning a thing down said as an idiom ("P can do without X",
    "P's passing on X", "P can't stand X", "P has no use for X", "P doesn't fancy (care for) X",
    "P isn't keen on X", "P's turned down X", "No X for P"), followed by another clause, is "P
    doesn't want the X, …", read as before (session 39's `_not_wanted39r`: dropped beside a
    request that names neither it nor 'it', else refused as a negation)."""
    low = text.lower()
    if not any(
        w in low
        for w in (
            "without",
            "passing",
            "pass",
            "stand",
            "no use",
            "no need",
            "fancy",
            "care for",
            "keen",
            "turned down",
            "no ",
        )
    ):
        return text

    def said(m: re.Match[str]) -> str:
        who = m["p"] or m["q"]
        what = m["x"] or m["y"]
        the = what if what.lower().startswith("the ") else f"the {what}"
        if not _only_person(who, lexicon) or not _whole_name(the, lexicon, "object"):
            return m[0]
        return f"{who} doesn't want {the}, "

    return re.sub(_TURNS_DOWN41R, said, text, flags=_F)


# "Rather than the crisps, give Alice the apple."; "… in place of the crisps"
_RATHER_THAN_FIRST41R = r"^(?:rather than|in place of) (?=the [a-z]+(?: [a-z]+)?\s*,)"
_IN_PLACE_OF41R = r"\bin place of (?=the )"


def _rather_than_first41r(text: str, _lexicon: Lexicon) -> str:
    """Session 41 (12r): "Rather than X, <request>" (in place of X) opening a request is "Instead
    of X, <request>", and "… in place of X" inside one is "… instead of X" (the grammar's
    leaving out)."""
    low = text.lower()
    if "rather than" not in low and "in place of" not in low:
        return text
    out = re.sub(_RATHER_THAN_FIRST41R, "Instead of ", text, flags=_F)
    return re.sub(_IN_PLACE_OF41R, "instead of ", out, flags=_F)


# "Give Carol a mug of your choosing."; "one or other of the mugs"
_OF_YOUR_CHOOSING41R = (
    r"\b(?P<a>an?|one) (?P<k>[a-z]+) of your (?:choosing|choice)(?P<end>\s*[.!]?)$"
)
_ONE_OR_OTHER41R = r"\bone or (?:the )?other of (?=the )"


def _of_your_choosing41r(text: str, _lexicon: Lexicon) -> str:
    """Session 41 (12r): "a mug of your choosing (choice)" closing a request is "a mug, your
    call", and "one or other of the mugs" is "one of the mugs" (the choice then the grammar's)."""
    low = text.lower()
    if "of your" not in low and "or other" not in low and "or the other" not in low:
        return text
    out = re.sub(
        _OF_YOUR_CHOOSING41R, lambda m: f"{m['a']} {m['k']}, your call{m['end']}", text, flags=_F
    )
    return re.sub(_ONE_OR_OTHER41R, "one of ", out, flags=_F)


# "…, let me start again, give the crisps to Bob."
_START_AGAIN41R = (
    r"^(?P<head>.+?)\s*[,;.:!-]\s*(?:(?:sorry|oh|no|ok|okay|right),?\s*)*(?:let me|i'll|i will|"
    r"let's) (?:start (?:again|over)|begin again|say (?:that|it) again|rephrase(?: that)?|"
    r"try (?:that|this) again)\s*[,;.:!-]\s*(?P<rest>\S.*)$"
)


def _start_again41r(text: str, lexicon: Lexicon) -> str:
    """Session 41 (12r): a request the speaker then restarts ("…, let me start again (start
    over, say that again, rephrase), <request>") is the request after it, when that reads
    alone (a 'them' there pointing back is refused)."""
    low = text.lower()
    if "again" not in low and "over" not in low and "rephrase" not in low:
        return text
    m = re.match(_START_AGAIN41R, text.strip(), _F)
    if m is None:
        return text
    rest = _capital40r(m["rest"])
    return rest if _reading(rest, lexicon) is not None else text


# -- refusals that name the readings -------------------------------------------------------------

# "Give the bottle to Person A, no, hang on, the other one, or was it? Not sure now."
_DOUBTED_CORRECTION41R = (
    r",\s*(?:no|wait|hang on|hold on|sorry|actually|correction)\b[^?]*?(?P<doubt>\bor was it\b\??|"
    r"\bnot (?:so )?sure(?: now| any ?more)?\b|\bi(?:'m| am) not sure\b|\bi can't remember\b|"
    r"\bdon't quote me\b|\bor is it\b\??)"
)


def doubted_correction41r(text: str, lexicon: Lexicon) -> None:
    """Session 41 (12r): a correction the speaker then doubts ("…, no, hang on, the other one, or
    was it? Not sure now") leaves open whether the request stands as first said or as
    corrected: refused, naming each person of the scene and each object the text names."""
    low = text.lower()
    if (
        "or was it" not in low
        and "sure" not in low
        and "remember" not in low
        and "quote" not in low
        and "or is it" not in low
    ):
        return
    m = re.search(_DOUBTED_CORRECTION41R, text, _F)
    if m is None:
        return
    people = " or ".join(person_name(h.id, lexicon) for h in lexicon.scene.humans)
    things = sorted(_ids(text, lexicon, "object"))
    raise GroundingError(
        f"{m['doubt']!r} doubts the correction before it: the request could stand as first said "
        f"or as corrected; who gets it could be {people}"
        + (f" ({', '.join(things)})" if things else "")
        + ": say the whole request again"
    )


# "Person A wants one of the drinks, she said which but I forget."
_WHICH_FORGOTTEN41R = (
    r"\bone of the (?P<kinds>[a-z]+s)\b[^.;!?]*?\b(?P<said>(?:(?:she|he|they|[a-z]+) "
    r"(?:said|told me|mentioned|did say)(?: which(?: one)?)?,? but i (?:forget|forgot|"
    r"can't remember|don't remember|can't recall|didn't catch it)|i (?:forget|forgot|"
    r"can't remember|don't remember|can't recall) which(?: one)?))"
)


def which_forgotten41r(text: str, lexicon: Lexicon) -> None:
    """Session 41 (12r): "P wants one of the drinks, she said which but I forget" (I can't
    remember which) names a choice the speaker cannot make: refused, naming each object of
    that kind the scene has (not read as a choice left to the robot)."""
    low = text.lower()
    if "one of the" not in low or (
        "forg" not in low and "remember" not in low and "recall" not in low and "catch" not in low
    ):
        return
    m = re.search(_WHICH_FORGOTTEN41R, text, _F)
    if m is None:
        return
    kinds = m["kinds"].lower()
    ids = sorted(_ids(f"the {kinds}", lexicon, "object"))
    if kinds in KIND_CATEGORIES:
        ids = sorted(o.id for o in lexicon.scene.objects if o.category in KIND_CATEGORIES[kinds])
    if len(ids) < 2:
        return
    raise GroundingError(
        f"{m['said']!r}: which of the {m['kinds']} is meant is not said; it could be "
        + " or ".join(ids)
        + ": name the one"
    )


# -- checks of the whole reading -------------------------------------------------------------------


def _choice_twice41r(text: str, node: Node, lexicon: Lexicon) -> None:
    """Session 41 (12r): a choice that offers some tasks twice and, once, a task of an object
    the text does not name ("Put a box on the conveyor, the small one or the medium one": every
    box, then the small one and the medium one again, the large one among them, never said) is
    not what was said: refused, naming the tasks it offers (a choice whose every option is said,
    "Whichever, the bottle or the chips, to P", read with one option twice, stays read)."""
    groups = [node]
    while groups:
        g = groups.pop()
        if not isinstance(g, Group):
            continue
        groups.extend(g.children)
        if g.op != "or":
            continue
        seen = [normalise(c) for c in g.children]
        once = [c for c in seen if seen.count(c) == 1]
        if len(once) == len(seen):
            continue
        unsaid = [t for c in once for t in tasks(c) if not _named_alone41r(t.obj, text, lexicon)]
        if not unsaid:
            continue
        offered = sorted({_said41r(t, lexicon) for t in tasks(g)})
        raise GroundingError(
            "the choice offers "
            + " or ".join(offered)
            + ", and "
            + " and ".join(sorted({t.obj for t in unsaid}))
            + " is not said: name each option once, e.g. 'the small box or the medium box'"
        )


def _named_alone41r(oid: str, text: str, lexicon: Lexicon) -> bool:
    """Whether ``text`` names object ``oid`` by a name of its own: its id, an alias, or its
    kind when no other object of the scene is of that kind."""
    low = f" {' '.join(re.findall(r'[a-z_]+', text.lower()))} "
    obj = next(o for o in lexicon.scene.objects if o.id == oid)
    kinds = [o.category for o in lexicon.scene.objects]
    names = [oid, *obj.aliases] + ([obj.category] if kinds.count(obj.category) == 1 else [])
    return any(f" {n.lower()} " in low or f" {n.lower()}s " in low for n in names)


def _said41r(task: Task, lexicon: Lexicon) -> str:
    if task.kind == "deliver":
        return f"the {task.obj} to {person_name(task.target, lexicon)}"
    return f"the {task.obj} on the {task.target}"


# "…, Mrs Khan's the one (they're for)."
_THE_ONE41R = rf"(?:^|[,;.:!?]\s*)(?:no,?\s*)?(?P<q>{_NAME40R})(?:'s| is) the one\b"


def _the_one_gets41r(text: str, node: Node, lexicon: Lexicon) -> None:
    """Session 41 (12r): a clause saying a person of the scene is "the one" ("Tablets to Mr Lee,
    Mrs Khan's the one (they're for)") names who the request is for: a reading that gives that
    person nothing is refused, naming both people (the one the request names, and the one
    said to be the one)."""
    if " one" not in text:
        return
    for m in re.finditer(_THE_ONE41R, text, _F):
        q = m["q"].strip()
        if not _only_person(q, lexicon):
            continue
        (qid,) = _ids(q, lexicon, "human")
        got = {t.target for t in tasks(node) if t.kind == "deliver"}
        if qid in got:
            continue
        others = ", ".join(person_name(p, lexicon) for p in sorted(got)) or "nobody"
        raise GroundingError(
            f"{m[0].strip(' ,;.:!?')!r} says {person_name(qid, lexicon)} is the one, but the "
            f"request gives it to {others}: say who gets it"
        )


# the normaliser's rewrites run before the session-40 ones (wired into normalise._STEPS19)
_STEPS41R_FIRST: tuple[Callable[[str, Lexicon], str], ...] = (
    _not_its41r,
    _not_picky41r,
    _cue_run41r,
    _straight_to41r,
    _the_one_for41r,
    _pronoun_again41r,
    _corrected_then41r,
    _said_already41r,
)
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-40 ones)
_STEPS41R: tuple[Callable[[str, Lexicon], str], ...] = (
    _everything_but41r,
    _forget_after41r,
    _not_for_after41r,
    _no_wait41r,
    _left_that_isnt41r,
    _instead_of_unwanted41r,
    _fussy_between41r,
    _left_to_you41r,
    _whichever_free41r,
    _a_kind_said41r,
    _so_long_as41r,
    _one_of_them_gets41r,
    _shared_out41r,
    _pair_listed41r,
    _pair_of41r,
    _all_n_of_them41r,
    _onto_with41r,
    _only_one_anyway41r,
    _one_and_one41r,
    _plain_simple41r,
    _just_those41r,
    _of_all41r,
    _out_on41r,
    _one_going41r,
    _let_use41r,
    _turns_down41r,
    _rather_than_first41r,
    _of_your_choosing41r,
    _start_again41r,
)
# refusals asked of the text before it is read (offline._parse, after the session-40 ones)
REFUSE41R: tuple[Callable[[str, Lexicon], None], ...] = (
    doubted_correction41r,
    which_forgotten41r,
)
# checks of the whole instruction's reading (offline.parse_instruction, after the session-40 ones)
CHECK41R: tuple[Callable[[str, Node, Lexicon], None], ...] = (
    _choice_twice41r,
    _the_one_gets41r,
)
