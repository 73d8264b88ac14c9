"""The grounder's rules of session 54, engineer 12r (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _ids, _reading
from hltl.grounding._rewrites44r import _agrees44r
from hltl.grounding._rewrites46r import _CLEAR_BOTH46R, _P46R, _person46r
from hltl.grounding._rewrites51r import _CUE51R, _one_task51r
from hltl.grounding._rewrites53r import _held53r
from hltl.grounding.lexicon import Lexicon
from hltl.grounding.phrasing import starting_on
from hltl.grounding.tree import Node, tasks


def _says54r(text: str, *words: str) -> bool:
    """Whether ``text`` (lower-cased) holds one of ``words``: a rule's cheap word test."""
    low = text.lower()
    return any(w in low for w in words)


# "Person A has asked for it": a present want, not a holding
_HAS_ASKED54R = re.compiled(r"\b(?:has|'s) (?:asked|requested|been asking) for\b", _F)


def _held54r(words: str) -> bool:
    """_held53r, but "P has asked for …" (has requested, has been asking for) is a want said now,
    not what someone has."""
    return _held53r(_HAS_ASKED54R.sub(" asks for", words))


# -- blind52: corrections ------------------------------------------------------------------------

# "…, ah no, hang fire, …", "…, scrub that, make it the apple": a cue said in other words
_CUE_IDIOM54R = re.compiled(
    r"(?<=,)(?P<sp>\s*)(?:(?P<wait>hang fire|hold fire|hold your horses)|(?P<scratch>scrub that|"
    r"rub that out|cross that out|cross that off|wipe that))(?=\s*,)",
    _F,
)


def _cue_idiom54r(text: str, lexicon: Lexicon) -> str:
    """Session 54 (12r): "hang fire" / "hold fire" is the cue "hang on", "scrub that" / "cross
    that out" is "scratch that", said between commas after a request (a cue the older rules read
    by its usual words); not where the words before say what someone has or had."""
    low = text.lower()
    if (
        "fire" not in low
        and "rub that" not in low
        and "cross that" not in low
        and ("wipe that" not in low and "horses" not in low)
    ):
        return text
    m = _CUE_IDIOM54R.search(text)
    if m is None or _held53r(text[: m.start()]):
        return text
    said = "hang on" if m["wait"] else "scratch that"
    return f"{text[: m.start()]}{m['sp']}{said}{text[m.end() :]}"


# "Tape for Mia, ah, not her, Tom's the one taping up.": the person put right, with why
_WHO_NOW54R = re.compiled(
    rf"^(?P<head>[^,;]+?)\s*,\s*(?P<cue>{_CUE51R})?(?P<not>(?:not (?P<pro>her|him),?\s*))?"
    r"(?P<own>(?:i've|i have|i'd|i) got (?:them|those|that|it|the two) (?:mixed up|muddled|wrong|"
    r"the wrong way round),?\s*|got that wrong,?\s*|wrong person,?\s*)?"
    rf"(?:(?P<p0>{_P46R}),?\s*i mean,?\s*)?(?P<p>{_P46R})(?:'s| is) (?P<why>(?P<one>the "
    r"(?P<adj>[a-z]+) one|the one (?:who's |who is |that's )?(?P<ing>[a-z]+ing)(?: [a-z]+)?)|"
    r"(?P<ing2>[a-z]+ing)(?: (?:the |some )?[a-z]+)?)(?P<end>\s*[.!]?)$",
    _F,
)
# why it is Q, said of Q: wanting it ("the thirsty one") or doing what needs it ("the one taping
# up"); any other word may say why NOT Q ("Bob's the allergic one", "the full one": 12c's probe)
_WANTING54R = frozenset(
    [
        "thirsty",
        "hungry",
        "peckish",
        "starving",
        "famished",
        "parched",
        "cold",
        "chilly",
        "freezing",
    ]
)
_DOING54R = frozenset(
    [
        "asking",
        "waiting",
        "taping",
        "working",
        "writing",
        "cooking",
        "baking",
        "reading",
        "drinking",
        "eating",
        "stirring",
        "using",
        "doing",
        "needing",
        "wanting",
        "marking",
        "measuring",
        "cutting",
        "cleaning",
        "signing",
        "filing",
        "studying",
        "painting",
        "fixing",
        "building",
        "serving",
        "plating",
        "packing",
        "feeding",
        "wiping",
        "drawing",
        "sewing",
        "gluing",
    ]
)


def _who_now54r(text: str, lexicon: Lexicon) -> str:
    """Session 54 (12r): one handover, a correction cue (or "not her", fitting the request's
    person), then "Q's the thirsty one" / "Q's the one taping up" (or, after "I've got them mixed
    up" / "got that wrong" / "Q, I mean,", "Q's doing the geography": why it is Q, naming nothing
    of the scene) is "…, no, it's Q": read only as the same thing handed to another person than
    the request's."""
    low = text.lower()
    if (
        " one" not in low
        and "wrong" not in low
        and "mixed" not in low
        and ("muddled" not in low and "i mean" not in low)
    ):
        return text
    m = _WHO_NOW54R.match(text.strip())
    if m is None or _held53r(m["head"]) or _held53r(m["why"]) or _ids(m["why"], lexicon):
        return text
    if not (m["cue"] or m["not"]) or not (m["one"] or m["own"] or m["p0"]):
        return text  # "…, no, Bob's leaving": why Bob, or why not him?
    if m["adj"] is not None and m["adj"].lower() not in _WANTING54R:
        return text
    if (m["ing"] or m["ing2"] or "doing").lower() not in _DOING54R:
        return text
    p = _person46r(m["p"], lexicon)
    if p is None or (m["p0"] is not None and _person46r(m["p0"], lexicon) != p):
        return text
    first = _one_task51r(f"{m['head']}.", lexicon)
    if first is None or first[0] != "deliver" or first[2] == p:
        return text
    if m["pro"] is not None and not _agrees44r(first[2], m["pro"], lexicon):
        return text
    out = f"{m['head']}, no, it's {m['p']}{m['end'] or '.'}"
    return out if _one_task51r(out, lexicon) == ("deliver", first[1], p) else text


# "Take the bottle to Person B, or no, wrong thing, it was chips he fancied."
_HE_FANCIED54R = re.compiled(
    r"^(?P<head>[^,;]+?)\s*,\s*(?:or\s+)?(?P<cue>" + _CUE51R + r")(?:wrong thing,?\s*)?"
    r"it(?:'s| is| was) (?P<x>(?:the )?[a-z]+(?: [a-z]+)?) (?P<pro>he|she) (?:fancied|fancies|"
    r"wanted|wants|meant|asked for|was after|is after|needed|needs|would like|'d like|was "
    r"wanting|is wanting)(?P<end>\s*[.!]?)$",
    _F,
)


def _he_fancied54r(text: str, lexicon: Lexicon) -> str:
    """Session 54 (12r): one handover, a correction cue, then "it was (the) X he fancied"
    (wanted, meant, asked for) is "…, no, the X": read only where 'he' / 'she' can be the
    request's person alone and X is one thing other than the request's."""
    low = text.lower()
    if "it's" not in low and "it is" not in low and "it was" not in low:
        return text
    m = _HE_FANCIED54R.match(text.strip())
    if m is None or _held53r(m["head"]):
        return text
    x = _ids(m["x"], lexicon, "object")
    first = _one_task51r(f"{m['head']}.", lexicon)
    if first is None or first[0] != "deliver" or len(x) != 1 or x != _ids(m["x"], lexicon):
        return text
    if first[1] in x or not _agrees44r(first[2], m["pro"], lexicon):
        return text
    thing = m["x"] if m["x"].lower().startswith("the ") else f"the {m['x']}"
    out = f"{m['head']}, no, {thing}{m['end'] or '.'}"
    return out if _one_task51r(out, lexicon) == ("deliver", next(iter(x)), first[2]) else text


# "Marco wants the salt, hang on, no, he said lemon, take him that."
_HE_SAID54R = re.compiled(
    r"(?<=,)(?P<sp>\s*)(?:he|she) (?:said|says|told me|meant|asked for|wanted)\s+"
    r"(?=(?:the )?[a-z]+(?: [a-z]+)?\s*(?:,\s*(?:take|give|hand|bring|pass) (?:him|her) (?:that|"
    r"those|it|them|one)\b|[.!]?\s*$))",
    _F,
)


def _he_said54r(text: str, lexicon: Lexicon) -> str:
    """Session 54 (12r): after a correction cue, "he said X" (she told me, he meant) names what
    the request's person asked for instead: "…, no, X" (read only as the same person given one
    other thing, and 'he' / 'she' the request's person as the older rules read it)."""
    low = text.lower()
    if (
        "he said" not in low
        and "he says" not in low
        and "he told" not in low
        and ("he meant" not in low and "he asked" not in low and "he wanted" not in low)
    ):
        return text
    m = _HE_SAID54R.search(text)
    if m is None:
        return text
    pro = text[m.end("sp") :].split()[0]
    head = text[: m.start() - 1]
    cue = re.compiled(rf",\s*(?:{_CUE51R})$", _F).search(head + ",")
    if cue is None:
        return text
    first = _one_task51r(f"{head[: cue.start()]}.", lexicon)
    if first is None or first[0] != "deliver" or _held53r(head[: cue.start()]):
        return text
    if not _agrees44r(first[2], pro, lexicon):
        return text
    out = f"{text[: m.start()]}{m['sp']}{text[m.end() :]}"
    got = _one_task51r(out, lexicon)
    return out if got is not None and got[2] == first[2] and got[1] != first[1] else text


# -- blind52: whichever, either, both, each ------------------------------------------------------

# "Each of them is owed something: …": the share-out header said as what each is owed
_OWED54R = re.compiled(
    r"^(?P<who>\s*(?:each of them|each of you|each one|everyone|everybody|both of them|they each|"
    r"the two of them|all three of them))(?: (?:is|are) (?:owed|due)| (?:deserves?|has earned|"
    r"have earned|'s earned|'ve earned))(?P<what> (?:something|one thing|a thing|one))\s*:",
    _F,
)


def _owed54r(text: str, lexicon: Lexicon) -> str:
    """Session 54 (12r): "Each of them is owed (is due, deserves) something: <list>" is "Each of
    them gets something: <list>", the header whose list the older rules check (everyone once)."""
    low = text.lower()
    if ":" not in low or (
        "owed" not in low and "due" not in low and "earned" not in low and ("deserve" not in low)
    ):
        return text
    m = _OWED54R.match(text)
    if m is None:
        return text
    verb = " get" if m["who"].strip().lower() in ("they each",) else " gets"
    if m["who"].strip().lower() in ("both of them", "the two of them", "all three of them"):
        verb = " get"
    return f"{m['who']}{verb}{m['what']}:{text[m.end() :]}"


# "the bottle's Bob's to have": whose it is, said with 'to have' / 'to keep'
_TO_HAVE54R = re.compiled(
    rf"(?<=\S)(?:'s| is| are) (?P<p>{_P46R})(?:'s|') to (?:have|keep|take home|hang on to)"
    r"(?=\s*(?:,|;|\band\b|[.!]?\s*$))",
    _F,
)


def _to_have54r(text: str, lexicon: Lexicon) -> str:
    """Session 54 (12r): "the bottle's Bob's to have (to keep)" after a thing is "the bottle's
    for Bob" (whose it is to be): the owner one person of the scene; not where the words before
    say what someone has or had."""
    low = text.lower()
    if (
        " to have" not in low
        and " to keep" not in low
        and " to take home" not in low
        and (" to hang on" not in low)
    ):
        return text
    m = _TO_HAVE54R.search(text)
    if m is None or _person46r(m["p"], lexicon) is None or _held53r(text[: m.start()]):
        return text
    verb = text[m.start() : m.start("p")]
    return f"{text[: m.start()]}{verb}for {m['p']}{text[m.end() :]}"


# "… so both the bottle and the crisps go in his direction.": toward a person
_DIRECTION54R = re.compiled(
    rf"\b(?P<verb>go|goes|head|heads|send|sent|pass|take|bring)\b(?P<what>[^,;.!?]*?) in "
    rf"(?P<whose>his|her|(?P<p>{_P46R})(?:'s|'))(?: general)? direction\b",
    _F,
)


def _direction54r(text: str, lexicon: Lexicon) -> str:
    """Session 54 (12r): "X go(es) in his (Bob's) direction" (head, send … in …) is "X go(es) to
    him (Bob)": a pronoun left for the older rules to resolve, a name one person of the scene."""
    if "direction" not in text.lower():
        return text
    m = _DIRECTION54R.search(text)
    if m is None or _held53r(text[: m.start()]):
        return text
    whose = m["whose"].lower()
    if m["p"] is not None:
        if _person46r(m["p"], lexicon) is None:
            return text
        who = m["p"]
    else:
        who = "him" if whose == "his" else "her"
    return f"{text[: m.start()]}{m['verb']}{m['what']} to {who}{text[m.end() :]}"


# "Both items go to Person B, bottle and chips alike, for the match.": 'alike' after a list
_ALIKE54R = re.compiled(
    r"(?P<list>\b(?:the )?[a-z]+(?: [a-z]+)?(?:,? (?:and|as well as|plus) (?:the )?[a-z]+"
    r"(?: [a-z]+)?)+) alike\b",
    _F,
)


def _alike54r(text: str, lexicon: Lexicon) -> str:
    """Session 54 (12r): "X and Y alike" is "X and Y" when X and Y name things of the scene
    (only things): 'alike' says the same goes for each."""
    if " alike" not in text.lower():
        return text
    m = _ALIKE54R.search(text)
    if m is None or _held53r(text) or _CLEAR_BOTH46R.match(text.strip()):
        return text
    names = re.compiled(r",? (?:and|as well as|plus) ", _F).split(m["list"])
    if any(len(_ids(n, lexicon, "object")) != 1 or _ids(n, lexicon, "human") for n in names):
        return text
    return f"{text[: m.start()]}{m['list']}{text[m.end() :]}"


# "However you fancy doing it, …": how the robot goes about it, naming nothing of the scene
_HOWEVER54R = re.compiled(
    r"^\s*(?:however|any way|anyway|whichever way|whatever way) (?:you|u) (?:fancy|like|want|wish|"
    r"prefer|choose|see fit|think best|please)(?: (?:doing it|to do it|to go about it|to manage "
    r"it|going about it))?\s*,\s*",
    _F,
)


def _however54r(text: str, lexicon: Lexicon) -> str:
    """Session 54 (12r): an opener "However you fancy doing it, …" (any way you like, whichever
    way you prefer) says the robot may go about the request as it likes: the request (the opener
    names nothing of the scene; what follows must read on its own)."""
    low = text.lower()
    if "way" not in low and "however" not in low:
        return text
    m = _HOWEVER54R.match(text)
    if m is None:
        return text
    rest = text[m.end() :]
    return rest[:1].upper() + rest[1:] if rest else text


# "…, whoever's nearer to you at the time.": when the robot chooses
_AT_THE_TIME54R = re.compiled(
    r"(?P<keep>\b(?:whoever|whichever)(?:'s| is) (?:nearer|nearest|closer|closest|handier|"
    r"handiest|free|freer)(?: to you| to hand)?) (?:at the time|at that point|at that moment|at "
    r"the moment|then)(?=\s*[.!]?\s*$)",
    _F,
)


def _at_the_time54r(text: str, lexicon: Lexicon) -> str:
    """Session 54 (12r): "…, whoever's nearer to you at the time" is "…, whoever's nearer to
    you": when the robot makes the choice it leaves to the robot, not a time the task waits
    for."""
    low = text.lower()
    if " at th" not in low and " then" not in low:
        return text
    m = _AT_THE_TIME54R.search(text)
    if m is None:
        return text
    return f"{text[: m.start()]}{m['keep']}{text[m.end() :]}"


# -- blind52: counts -----------------------------------------------------------------------------

# "That lone bottle there, …": 'lone' / 'solitary' of the scene's one thing of its kind
_LONE54R = re.compiled(
    r"\b(?P<that>that|this) (?P<w>lone|solitary|single|sole|one and only) (?P<x>[a-z]+)\b", _F
)


def _lone54r(text: str, lexicon: Lexicon) -> str:
    """Session 54 (12r): "that lone (solitary) bottle" is "that bottle" when the scene holds one
    thing of that name (a lone mug of two, left); "a lone bottle" / "the lone bottle" are the
    older rules' (sessions 30-47 read them as they are)."""
    low = text.lower()
    if "lone" not in low and "solitary" not in low and "sole " not in low:
        return text
    m = _LONE54R.search(text)
    if m is None or m["w"].lower() in ("single", "one and only") or _held54r(text):
        return text
    x = _ids(m["x"], lexicon)
    if len(x) != 1 or _ids(m["x"], lexicon, "object") != x:
        return text
    return f"{text[: m.start()]}{m['that']} {m['x']}{text[m.end() :]}"


# "Both spanners, big and small, are wanted by Kofi.": a want said in the passive
_WANTED_BY54R = re.compiled(
    rf"^(?P<x>[^,;.!?]+?(?:,[^,;.!?]+,)?) (?:are|is) (?:wanted|needed|requested|asked for) by "
    rf"(?P<p>{_P46R})(?P<end>\s*[.!]?)$",
    _F,
)


def _wanted_by54r(text: str, lexicon: Lexicon) -> str:
    """Session 54 (12r): "X (and Y) are wanted (needed, asked for) by P" is "P wants X (and Y)"
    (the whole instruction; the things only things of the scene, P one person)."""
    low = text.lower()
    if (
        "wanted by" not in low
        and "needed by" not in low
        and "requested by" not in low
        and ("asked for by" not in low)
    ):
        return text
    m = _WANTED_BY54R.match(text.strip())
    if m is None or _person46r(m["p"], lexicon) is None:
        return text
    x = m["x"].strip()
    if not _ids(x, lexicon, "object") or _ids(x, lexicon, "human") or _held53r(x):
        return text
    return f"{m['p']} wants {x[:1].lower() + x[1:]}{m['end'] or '.'}"


# "Every box we've got, all three, onto the belt for the last run."
_WE_HAVE54R = re.compiled(
    r"\b(?P<all>every|each|all (?:the|of the)) (?P<x>[a-z]+) (?:we've got|we have|we've|we got|"
    r"there is|there are)\b",
    _F,
)
_FOR_RUN54R = re.compiled(
    r"\s+for the (?:last|final|first|next|early|late|morning|evening|afternoon|big) (?:run|trip|"
    r"load|round|delivery|collection|pickup|pick-up|batch|shipment)(?=\s*[.!]?\s*$)",
    _F,
)


def _we_have54r(text: str, lexicon: Lexicon) -> str:
    """Session 54 (12r): "every box we've got (there is)" is "every box" (the speaker's 'we':
    the scene's things of that kind), and after it "… onto the belt for the last run" (the next
    trip, the final load) is what the placing is for, said as a closer: taken off."""
    low = text.lower()
    if "we" not in low and "there is" not in low and "there are" not in low:
        return text
    m = _WE_HAVE54R.search(text)
    if m is None or not _ids(m["x"], lexicon, "object") or _ids(m["x"], lexicon, "human"):
        return text
    if _held53r(text[: m.start()] + text[m.end() :]):
        return text
    out = f"{text[: m.start()]}{m['all']} {m['x']}{text[m.end() :]}"
    run = _FOR_RUN54R.search(out)
    if run is not None:
        out = f"{out[: run.start()]}{out[run.end() :]}"
    return out


# "Both items go to Sam, the stapler and the notepad.": 'both items' read as every thing
_BOTH_THINGS54R = re.compiled(
    r"\bboth (?:of )?(?:the |these |those |them |my |your |our )?(?:items|things|objects|bits)\b",
    _F,
)


def _both_things54r(text: str, node: Node, lexicon: Lexicon) -> None:
    """Session 54 (12r): "both items" (things, objects) names two things; where the scene holds
    more, a reading handing over or placing a thing the text never names took 'items' for every
    thing of the scene ("Both items go to Sam, the stapler and the notepad." read all five pens
    and things to Sam): refused."""
    if "both" not in text.lower():
        return
    m = _BOTH_THINGS54R.search(text)
    if m is None or len(lexicon.scene.objects) <= 2:
        return
    named = _ids(f"{text[: m.start()]} , {text[m.end() :]}", lexicon, "object")
    unnamed = sorted({t.obj for t in tasks(node)} - named)
    if unnamed:
        raise GroundingError(
            f"{m.group(0)!r} names two things, but the scene has {len(lexicon.scene.objects)} "
            f"and the reading would take {', '.join(unnamed)} too, never named: name the two"
        )


# -- blind52: the robot's choice said of the person -----------------------------------------------

# "Carol says either mug will do her, …": 'do her' is 'suit her'
_DO_HER54R = re.compiled(
    r"\bsays (?:either|any|whichever)\b[^,;.!?]*? will do (?:for )?(?P<pro>her|him)"
    r"(?: (?:fine|nicely|just fine|very well|perfectly))?(?=\s*(?:,|[.!]?\s*$))",
    _F,
)


def _one_before54r(words: str, lexicon: Lexicon) -> str | None:
    """The one person ``words`` name (and no other), or None."""
    who = _ids(words, lexicon, "human")
    return next(iter(who)) if len(who) == 1 else None


def _do_her54r(text: str, lexicon: Lexicon) -> str:
    """Session 54 (12r): "P says either mug will do her (fine)" (session 38's "will do for her")
    is "P says either mug will do": 'her' / 'him' must fit the one person named before it (the
    choice is P's, as "P says either mug will do" reads; "any of the pens will do for him" without
    'says' is session 35's)."""
    if "will do" not in text.lower():
        return text
    m = _DO_HER54R.search(text)
    if m is None or _held54r(text[: m.start()]):
        return text
    p = _one_before54r(text[: m.start()], lexicon)
    if p is None or not _agrees44r(p, m["pro"], lexicon):
        return text
    said = text[m.start() : m.start("pro")]
    said = said[: said.lower().rindex(" will do") + len(" will do")]
    return f"{text[: m.start()]}{said}{text[m.end() :]}"


# "Mr Novak isn't fussy about plates, white or blue, either's fine by him."
_FUSSY_ABOUT54R = re.compiled(
    rf"^(?P<p>{_P46R})(?:'s not|'s n't| is not| isn't) (?:fussy|fussed|picky|particular|"
    r"bothered) about "
    r"(?:the |his |her )?(?P<xs>[a-z]+s)\b(?P<rest>\s*,[^;.!?]*?)(?:,? (?:either's|either is|"
    r"either one's|either one is|both are|each is) (?:fine|ok|okay|good|alright|grand)(?: (?:by|"
    r"with|for) (?P<pro>him|her))?)(?P<end>\s*[.!]?)$",
    _F,
)


def _fussy_about54r(text: str, lexicon: Lexicon) -> str:
    """Session 54 (12r): "P isn't fussy (fussed, picky) about plates, white or blue, either's
    fine (by him)" is "P can have either of the plates, white or blue, either's fine": the things
    one kind of the scene, 'him' / 'her' fitting P."""
    low = text.lower()
    if " about " not in low or "either" not in low:
        return text
    m = _FUSSY_ABOUT54R.match(text.strip())
    if m is None or _held54r(m["rest"]):
        return text
    p = _person46r(m["p"], lexicon)
    xs = _ids(m["xs"], lexicon, "object")
    if p is None or len(xs) < 2 or _ids(m["xs"], lexicon, "human"):
        return text
    if m["pro"] is not None and not _agrees44r(p, m["pro"], lexicon):
        return text
    return f"{m['p']} can have either of the {m['xs']}{m['rest']}, either's fine{m['end'] or '.'}"


# "Mrs Khan won't mind which blanket she gets, so take her whichever's closest."
_MIND_WHICH54R = re.compiled(
    rf"^(?P<p>{_P46R}) (?:won't|will not|doesn't|does not|wouldn't|would not) (?:mind|care) which "
    r"(?P<x>[a-z]+) (?P<pro>she|he) (?:gets|has|takes|ends up with), so (?P<v>take|give|bring|hand|"
    r"pass) (?P<pro2>her|him) whichever(?: one)?(?:'s| is) (?P<q>closest|nearest|nearer|closer|"
    r"handiest|handier|easiest|easier|to hand)(?P<end>\s*[.!]?)$",
    _F,
)


def _mind_which54r(text: str, lexicon: Lexicon) -> str:
    """Session 54 (12r): "P won't mind which blanket she gets, so take her whichever's closest" is
    "Take P whichever blanket is closest" (the pronouns fitting P; the kind two or more things of
    the scene)."""
    if " which " not in text.lower():
        return text
    m = _MIND_WHICH54R.match(text.strip())
    if m is None:
        return text
    p = _person46r(m["p"], lexicon)
    if p is None or len(_ids(m["x"], lexicon, "object")) < 2 or _ids(m["x"], lexicon, "human"):
        return text
    if not _agrees44r(p, m["pro"], lexicon) or not _agrees44r(p, m["pro2"], lexicon):
        return text
    verb = m["v"][:1].upper() + m["v"][1:].lower()
    return f"{verb} {m['p']} whichever {m['x']} is {m['q']}{m['end'] or '.'}"


# "Either person can have the chips, Person A or Person B, you choose."
_EITHER_PERSON54R = re.compiled(
    rf"^(?:either person|either of them|either one(?: of them)?|either of the two|one or the other)"
    rf" (?P<v>can have|gets|can take|may have|could have) (?P<x>[^,;.!?]+?),\s*(?P<pq>{_P46R} or "
    rf"{_P46R})(?P<rest>\s*,[^;.!?]*)?(?P<end>\s*[.!]?)$",
    _F,
)


def _either_person54r(text: str, lexicon: Lexicon) -> str:
    """Session 54 (12r): "Either person (either of them) can have the chips, P or Q, (you
    choose)" is "P or Q can have the chips, …": P and Q two people of the scene, the thing only
    things."""
    if "either" not in text.lower() and "one or the other" not in text.lower():
        return text
    m = _EITHER_PERSON54R.match(text.strip())
    if m is None or _held54r(m["rest"] or ""):
        return text
    who = _ids(m["pq"], lexicon, "human")
    if len(who) != 2 or _ids(m["pq"], lexicon) != who or not _ids(m["x"], lexicon, "object"):
        return text
    if _ids(m["x"], lexicon, "human"):
        return text
    return f"{m['pq']} {m['v']} {m['x']}{m['rest'] or ''}{m['end'] or '.'}"


# "Bottle to Person A, I mean, yes, to her, sorry, I'm rambling.": the request said again
_YES_TO_HER54R = re.compiled(
    rf"^(?P<head>[^,;]+?)\s*,\s*(?:i mean|i meant|that is),?\s*(?:yes|yeah|yep|right|aye),?\s*"
    rf"(?:to|for) (?P<who>her|him|{_P46R})(?P<rest>\s*,[^;]*|\s*[.!]?)$",
    _F,
)


def _yes_to_her54r(text: str, lexicon: Lexicon) -> str:
    """Session 54 (12r): "X to P, I mean, yes, to her, …" says the request's person again (a
    'yes' confirming, not a correction): "X to P, …" — 'her' / 'him' fitting P, or P named again,
    and the request one handover."""
    if (
        "yes" not in text.lower()
        and "yeah" not in text.lower()
        and "yep" not in text.lower()
        and ("right" not in text.lower() and "aye" not in text.lower())
    ):
        return text
    m = _YES_TO_HER54R.match(text.strip())
    if m is None or _held54r(m["head"]):
        return text
    first = _one_task51r(f"{m['head']}.", lexicon)
    if first is None or first[0] != "deliver":
        return text
    who = m["who"].lower()
    if who in ("her", "him"):
        if not _agrees44r(first[2], who, lexicon):
            return text
    elif _person46r(m["who"], lexicon) != first[2]:
        return text
    return f"{m['head']}{m['rest']}"


# -- blind52: counts said of the one thing -------------------------------------------------------

# "There's just the one bottle going, so Person A gets that, no fuss."
_ONE_GOING54R = re.compiled(
    rf"^there(?:'s| is) (?:just |only )?the one (?P<x>[a-z]+) (?:going|left|spare|going spare|"
    rf"about|around|here),?\s*so (?P<p>{_P46R}) (?:gets|can have|has) (?:that|it|that one)"
    r"(?P<rest>\s*,[^;.!?]*)?(?P<end>\s*[.!]?)$",
    _F,
)


def _one_going54r(text: str, lexicon: Lexicon) -> str:
    """Session 54 (12r): "There's just the one bottle going (left, spare), so P gets that" is
    "There's just the one bottle, so P gets it" when the scene holds one bottle (then session
    35's `_the_one35r` reading)."""
    if "the one" not in text.lower():
        return text
    m = _ONE_GOING54R.match(text.strip())
    if m is None or _held54r(m["rest"] or "") or _person46r(m["p"], lexicon) is None:
        return text
    x = _ids(m["x"], lexicon)
    if len(x) != 1 or _ids(m["x"], lexicon, "object") != x:
        return text
    return f"There's just the one {m['x']}, so {m['p']} gets it{m['rest'] or ''}{m['end'] or '.'}"


# "…; mind, there's only the one, so don't go looking for more."
_NO_MORE54R = re.compiled(
    r"(?P<keep>(?:there(?:'s| is)|it's|that's) (?:only|just) (?:the )?one(?: of them)?),?\s*so "
    r"(?:don't|do not|no need to|there's no need to) (?:go )?(?:looking|look|hunting|hunt|search|"
    r"searching) (?:for|round for|around for) (?:more|another(?: one)?|a second(?: one)?|others|"
    r"any more)(?=\s*[.!]?\s*$)",
    _F,
)


def _no_more54r(text: str, lexicon: Lexicon) -> str:
    """Session 54 (12r): "…; there's only the one, so don't go looking for more" closes with why
    there is one: "…; there's only the one" (the older rules' reading of that count)."""
    low = text.lower()
    if "look" not in low and "hunt" not in low and "search" not in low:
        return text
    m = _NO_MORE54R.search(text)
    if m is None:
        return text
    return f"{text[: m.start()]}{m['keep']}{text[m.end() :]}"


# "A single bottle is all Person A's asking for, nothing on top."
_ALL_ASKING54R = re.compiled(
    r"^(?P<x>(?:a|one|the) (?:single |one )?(?P<n>[a-z]+(?: [a-z]+)?)) is all "
    rf"(?P<p>{_P46R})(?:'s| is) "
    r"(?P<v>asking for|after|wanting|requesting)(?:,\s*nothing (?:on top|more|else|extra|besides))?"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _all_asking54r(text: str, lexicon: Lexicon) -> str:
    """Session 54 (12r): "A single bottle is all P's asking for (, nothing on top)" is "P's
    asking for a single bottle": the thing one of the scene, P one person."""
    if " is all " not in text.lower():
        return text
    m = _ALL_ASKING54R.match(text.strip())
    if m is None or _person46r(m["p"], lexicon) is None:
        return text
    x = _ids(m["n"], lexicon)
    if len(x) != 1 or _ids(m["n"], lexicon, "object") != x:
        return text
    thing = m["x"][:1].lower() + m["x"][1:]
    return f"{m['p']}'s {m['v']} {thing}{m['end'] or '.'}"


# "The bottle and the crisps, the pair, up onto the shelf …"
_THE_PAIR54R = re.compiled(
    r"^(?P<list>(?:the )?[a-z]+(?: [a-z]+)? and (?:the )?[a-z]+(?: [a-z]+)?),\s*(?:the pair|the "
    r"pair of them|the two|the two of them|the both of them|the twosome),",
    _F,
)


def _the_pair54r(text: str, lexicon: Lexicon) -> str:
    """Session 54 (12r): "X and Y, the pair (the two of them), …" opening the request is "X and Y,
    both of them, …" when X and Y are two things of the scene."""
    if (
        "the pair" not in text.lower()
        and "the two" not in text.lower()
        and ("the both" not in text.lower() and "twosome" not in text.lower())
    ):
        return text
    m = _THE_PAIR54R.match(text.strip())
    if m is None:
        return text
    x, y = (_ids(n, lexicon) for n in re.compiled(r" and ", _F).split(m["list"]))
    if len(x) != 1 or len(y) != 1 or x == y or _ids(m["list"], lexicon, "human"):
        return text
    return f"{m['list']}, both of them,{text.strip()[m.end() :]}"


# "Stapler in the box, oh wait, better on the desk where Priya can reach it."
_WHERE_REACH54R = re.compiled(
    rf"(?P<s>\b(?:on|in|onto|into) the [a-z]+(?: [a-z]+)?) where (?!(?:i|we|you)\b)"
    rf"(?:{_P46R}|she|he|they) can "
    r"(?:reach|get at|get to|grab|see) (?:it|them)(?=\s*[.!]?\s*$)",
    _F,
)


def _where_reach54r(text: str, lexicon: Lexicon) -> str:
    """Session 54 (12r): "… on the desk where Priya can reach it" ending the request is "… on the
    desk": why there, the surface one of the scene (a scene of one desk: the words pick no other),
    the person named one of the scene."""
    if " where " not in text.lower():
        return text
    m = _WHERE_REACH54R.search(text)
    if m is None or _held54r(text[: m.start()]):
        return text
    if len(_ids(m["s"], lexicon, "surface")) != 1 or _ids(m["s"], lexicon, "object"):
        return text
    said = text[m.end("s") : m.end()]
    who = _ids(said, lexicon, "human")
    if _ids(said, lexicon) != who or len(who) > 1:
        return text
    return f"{text[: m.end('s')]}{text[m.end() :]}"


# -- blind52: wants said with what the person is doing -------------------------------------------

# "Mrs Ortiz is marking at her desk and wants both the books, …": where P is, then the want
_AT_HER54R = re.compiled(
    rf"^(?P<p>{_P46R}) (?P<is>is|'s) (?P<v>[a-z]+ing) at (?P<pos>her|his|their) "
    r"(?P<s>[a-z]+(?: [a-z]+)?) (?P<and>and (?:wants|needs|would like|'d like|is after|is asking "
    r"for)\b)",
    _F,
)


def _at_her54r(text: str, lexicon: Lexicon) -> str:
    """Session 54 (12r): "P is marking at her desk and wants X" is "P is marking and wants X":
    where P is doing something (her desk, his table: P's own place) is not where X goes; P one
    person of the scene, the want said now."""
    if not _says54r(text, " at her ", " at his ", " at their "):
        return text
    m = _AT_HER54R.match(text.strip())
    p = None if m is None else _person46r(m["p"], lexicon)
    if m is None or p is None or _held54r(m["v"]):
        return text
    pro = {"his": "him", "her": "her"}.get(m["pos"].lower())
    if pro is not None and not _agrees44r(p, pro, lexicon):
        return text
    if _ids(m["s"], lexicon, "object") or _ids(m["s"], lexicon, "human"):
        return text
    rest = text.strip()[m.end() :]
    if _ids(rest, lexicon, "surface"):
        return text  # "… and wants both the books on the shelf": which books, or where?
    return f"{m['p']} {m['is']} {m['v']} {m['and']}{rest}"


# "Both of the blocks onto the high chair, please, Lily likes to bang them together at lunch."
_LIKES_TO54R = re.compiled(
    rf",\s*(?P<p>{_P46R}|she|he|they) (?:likes|loves|enjoys|like|love|enjoy) to (?P<v>[a-z]+) "
    r"(?:them|it)(?P<tail>(?: [a-z]+){0,4})(?P<end>\s*[.!]?)$",
    _F,
)


def _likes_to54r(text: str, lexicon: Lexicon) -> str:
    """Session 54 (12r): a placing or handover, then ", Lily likes to bang them together (at
    lunch)" — why, naming nothing of the scene but the person (what P likes to do with them, a
    habit, not a time the task waits for): taken off."""
    if not _says54r(text, "like to", "likes to", "love to", "loves to", "enjoy"):
        return text
    m = _LIKES_TO54R.search(text)
    if m is None or _held54r(text):
        return text
    said = f"{m['v']} {m['tail']}"
    if _ids(said, lexicon) or _DEFER54R.search(m["tail"]):
        return text
    if m["p"].lower() not in ("she", "he", "they") and _person46r(m["p"], lexicon) is None:
        return text
    head = text[: m.start()]
    node = _reading(f"{head}.", lexicon)
    if node is None:
        return text
    return f"{head}{m['end'] or '.'}"


# a time the task would wait for (a remark ending on one is left to the older rules)
_DEFER54R = re.compiled(
    r"\b(?:later|tomorrow|tonight|soon|after|before|when|once|until|till|next|this (?:evening|"
    r"afternoon|morning))\b",
    _F,
)


# "Every last one of the four things, Person B's having the lot for his picnic."
_HAVING_LOT54R = re.compiled(
    r"^(?P<all>every (?:last |single )?one of the (?:[a-z]+ )?(?:things|items)|all (?:of )?the "
    rf"(?:[a-z]+ )?(?:things|items)),\s*(?P<p>{_P46R})(?:'s| is) (?:having|taking|getting) (?:the "
    r"lot|them all|all of them|everything)(?: for (?:his|her|their) [a-z]+)?(?P<end>\s*[.!]?)$",
    _F,
)


def _having_lot54r(text: str, lexicon: Lexicon) -> str:
    """Session 54 (12r): "Every (last) one of the four things, P's having the lot (for his
    picnic)" is "Every one of the four things for P" (the count checked as the older rules check
    it)."""
    if not _says54r(text, "the lot", "them all", "all of them", "everything"):
        return text
    m = _HAVING_LOT54R.match(text.strip())
    if m is None or _person46r(m["p"], lexicon) is None:
        return text
    said = re.compiled(r"\b(?:last|single) ", _F).sub("", m["all"], count=1)
    return f"{said} for {m['p']}{m['end'] or '.'}"


# "Only one thing wanted by Person B today, and that's the chips."
_ONLY_ONE54R = re.compiled(
    rf"^only (?:one|the one|a single) thing (?:wanted|needed|asked for) by (?P<p>{_P46R})"
    r"(?: today| now| this time| at the moment)?,?\s*(?:and )?(?:that's|that is|it's|it is) "
    r"(?P<x>the [a-z]+(?: [a-z]+)?)(?P<end>\s*[.!]?)$",
    _F,
)


def _only_one54r(text: str, lexicon: Lexicon) -> str:
    """Session 54 (12r): "Only one thing wanted by P (today), and that's the X" is "Just the X for
    P" (P one person, X one thing of the scene; 'today' the speaker's context, read as now)."""
    if not _says54r(text, "only one thing", "only the one thing", "only a single thing"):
        return text
    m = _ONLY_ONE54R.match(text.strip())
    if m is None or _person46r(m["p"], lexicon) is None:
        return text
    x = _ids(m["x"], lexicon)
    if len(x) != 1 or _ids(m["x"], lexicon, "object") != x:
        return text
    return f"Just {m['x']} for {m['p']}{m['end'] or '.'}"


# "The small box and the medium one, the pair of them, stacked on the pallet (with the big one)."
_STACKED54R = re.compiled(
    r"^(?P<things>[^,;.!?]+?)\s*,?\s*(?:(?:the pair of them|the pair|both of them|the two of "
    r"them),\s*(?:set|put) |(?:the pair of them|the pair|both of them|the two of them),\s*)?"
    r"(?:(?:stacked|piled|stood|placed) )?(?:up )?on (?P<s>the [a-z]+(?: [a-z]+)?)"
    r"(?: (?:with|next to|beside|alongside) (?P<x>the [a-z]+(?: [a-z]+)?))?(?P<end>\s*[.!]?)$",
    _F,
)


def _stacked54r(text: str, lexicon: Lexicon) -> str:
    """Session 54 (12r): "X and Y, the pair of them, stacked (set) on the pallet" is "Stack X and
    Y on the pallet" (things only, one surface); "… with the big one" only when the big one
    already stands on that surface in the scene (beside it, not a third thing to move: session
    35's `_with_one_there35t` takes it off first)."""
    if not _says54r(text, "stacked", "piled", "stood", "placed", "the pair", "of them,"):
        return text
    m = _STACKED54R.match(text.strip())
    if m is None or _held54r(m["things"]) or m["things"].lower().startswith(("stack", "pile")):
        return text
    things, surface = _ids(m["things"], lexicon), _ids(m["s"], lexicon, "surface")
    if not things or _ids(m["things"], lexicon, "object") != things or len(surface) != 1:
        return text
    if _ids(m["s"], lexicon) != surface:
        return text
    if m["x"] is not None:
        x = _ids(m["x"], lexicon, "object")
        if m["x"].lower().endswith(" one"):
            kinds = {o.category for o in lexicon.scene.objects if o.id in things}
            word = m["x"][: -len(" one")]
            x = {i for c in kinds for i in _ids(f"{word} {c}", lexicon, "object")}
        if len(x) != 1 or x & things or not starting_on(x, next(iter(surface)), lexicon):
            return text
    head = m["things"].strip()
    out = f"Stack {head[:1].lower() + head[1:]} on {m['s']}{m['end'] or '.'}"
    node = _reading(out, lexicon)
    got = [] if node is None else list(tasks(node))
    if not got or any(t.kind != "place" or t.target not in surface for t in got):
        return text
    return out


# the normaliser's first rewrites (wired into normalise._STEPS19, before the session-53 ones)
_STEPS54R_FIRST: tuple[Callable[[str, Lexicon], str], ...] = (_cue_idiom54r, _to_have54r)
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-53 ones)
_STEPS54R: tuple[Callable[[str, Lexicon], str], ...] = (
    _who_now54r,
    _he_fancied54r,
    _he_said54r,
    _owed54r,
    _direction54r,
    _alike54r,
    _however54r,
    _at_the_time54r,
    _lone54r,
    _wanted_by54r,
    _we_have54r,
    _do_her54r,
    _fussy_about54r,
    _mind_which54r,
    _either_person54r,
    _yes_to_her54r,
    _one_going54r,
    _no_more54r,
    _all_asking54r,
    _the_pair54r,
    _where_reach54r,
    _stacked54r,
    _at_her54r,
    _likes_to54r,
    _having_lot54r,
    _only_one54r,
)
# refusals asked of the text before it is read (offline._parse, after the session-53 ones)
REFUSE54R: tuple[Callable[[str, Lexicon], None], ...] = ()
# checks of the whole instruction's reading (offline.parse_instruction, after the session-53 ones)
CHECK54R: tuple[Callable[[str, Node, Lexicon], None], ...] = (_both_things54r,)
