"""The grounder's rules of session 54, engineer 12r (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _ids
from hltl.grounding._rewrites44r import _agrees44r
from hltl.grounding._rewrites46r import _P46R, _person46r
from hltl.grounding._rewrites51r import _CUE51R, _one_task51r
from hltl.grounding._rewrites53r import _held53r
from hltl.grounding.lexicon import Lexicon
from hltl.grounding.tree import Node, tasks

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
    rf"(?:(?P<p0>{_P46R}),?\s*i mean,?\s*)?(?P<p>{_P46R})(?:'s| is) (?P<why>(?P<one>the [a-z]+ one|"
    r"the one (?:who's |who is |that's )?[a-z]+ing(?: [a-z]+)?)|[a-z]+ing(?: (?:the |some )?"
    r"[a-z]+)?)(?P<end>\s*[.!]?)$",
    _F,
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
    r"(?=(?:the )?[a-z]+(?: [a-z]+)?\s*(?:,|[.!]?\s*$))",
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
    if m is None or _held53r(text):
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
_LONE54R = re.compiled(r"\b(?P<w>lone|solitary|single|sole|one and only) (?P<x>[a-z]+)\b", _F)


def _lone54r(text: str, lexicon: Lexicon) -> str:
    """Session 54 (12r): "that lone (solitary) bottle" is "that bottle" when the scene holds one
    thing of that name (a lone mug of two, left)."""
    low = text.lower()
    if "lone" not in low and "solitary" not in low and "sole " not in low:
        return text
    m = _LONE54R.search(text)
    if m is None or m["w"].lower() in ("single", "one and only") or _held54r(text):
        return text
    x = _ids(m["x"], lexicon)
    if len(x) != 1 or _ids(m["x"], lexicon, "object") != x:
        return text
    return f"{text[: m.start()]}{m['x']}{text[m.end() :]}"


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
)
# refusals asked of the text before it is read (offline._parse, after the session-53 ones)
REFUSE54R: tuple[Callable[[str, Lexicon], None], ...] = ()
# checks of the whole instruction's reading (offline.parse_instruction, after the session-53 ones)
CHECK54R: tuple[Callable[[str, Node, Lexicon], None], ...] = (_both_things54r,)
