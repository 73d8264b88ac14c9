"""The normaliser's rewrites of session 38, engineer 12r (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import (
    _F,
    _drop,
    _ids,
    _names,
    _names_nothing,
    _only,
    _only_kind,
    _only_person,
    _singular,
)
from hltl.grounding._normalise4 import (
    _may_be35t,
    _objects34r,
    _persons34r,
    _sure36t,
    _the_one36r,
)
from hltl.grounding.lexicon import Lexicon

# "any old mug will do her": 'any old' is 'any' (the idiom: no age is said)
_ANY_OLD38R = re.compile(r"\b(?P<any>any) old (?P<k>[a-z]+)\b", _F)
# "… any mug will do her": a choice that will do for a person said with a bare object
_WILL_DO_PRO38R = re.compile(
    r"\b(?P<x>(?:any|either|whichever)\b[^,.;:!?]*?) will do (?P<p>him|her)"
    r"(?=\s*(?:[,.;!?]|$)| (?:before|after|while|when|since|as|because)\b)",
    _F,
)


def _any_old38r(text: str, lexicon: Lexicon) -> str:
    """Session 38 (12r): "any old mug" is "any mug" (where 'mug' names objects of the scene and
    'old' none: the idiom says any at all, no age), and "any mug / either of them / whichever you
    like will do her" is "… will do for her" (the person a choice will do said without 'for')."""
    if "any old" not in text.lower() and " will do h" not in text.lower():
        return text

    def old(m: re.Match[str]) -> str:
        k = m["k"]
        if not _only_kind(k, lexicon, "object") or _names(f"old {k}", lexicon) != _names(
            k, lexicon
        ):
            return m[0]
        return f"{m['any']} {k}"

    out = _ANY_OLD38R.sub(old, text)
    return _WILL_DO_PRO38R.sub(lambda m: f"{m['x']} will do for {m['p']}", out)


# "Give Person B something, the apple, the cup or the chips, …": what 'something' is, said after it
_SOMETHING_LISTED38R = re.compile(
    r"\b(?:something|anything|a thing)(?: nice)?(?: to (?:eat|drink|nibble))?\s*[,:]\s*"
    r"(?P<list>(?:the [a-z]+(?: [a-z]+)?,\s*)*"
    r"the [a-z]+(?: [a-z]+)?,?\s*or the [a-z]+(?: [a-z]+)?)(?=\s*(?:[,.;!?]|$))",
    _F,
)
# "…, any one of those will do (for him)": the choice said again after it is listed
_ANY_ONE_OF38R = re.compile(r"\bany one of (?=those|these|them)\b", _F)
_WILL_DO_FOR38R = re.compile(
    r"(?<=,) any of (?:those|these|them) will do(?P<for> for (?P<pro>him|her))"
    r"(?=\s*(?:[.!]|$)| (?:before|after|while|when|since|as|because)\b)",
    _F,
)


def _something_listed38r(text: str, lexicon: Lexicon) -> str:
    """Session 38 (12r): "something, the apple, the cup or the chips" (or "something to drink:
    …") is "the apple, the cup or the chips" (the list says which things the 'something' is: each
    one whole name of another object, the last joined by 'or'; else left, as before; session 35's
    `_kind_fits35s` refuses a list that 'to eat' / 'to drink' does not fit), and "any one of
    those" after such a list is "any of those", which says the choice again."""
    if "," not in text and ":" not in text:
        return text

    def listed(m: re.Match[str]) -> str:
        said = [w.strip() for w in re.split(r",\s*|\s+or\s+", m["list"]) if w.strip()]
        if len(said) < 2 or not _objects34r(lexicon, *said):
            return m[0]
        return m["list"]

    out = _SOMETHING_LISTED38R.sub(listed, text)
    if out == text and not re.search(r"\bthe [a-z]+,?\s+or the [a-z]+\b", text, _F):
        return text
    out = _ANY_ONE_OF38R.sub("any of ", out)
    m = _WILL_DO_FOR38R.search(out)
    if m is None:
        return out
    # "…, any of those will do for him": him the one person the request before it names
    who = _ids(out[: m.start()], lexicon, "human")
    if len(who) != 1 or not _may_be35t(next(iter(who)), m["pro"], lexicon):
        return out
    return out[: m.start("for")] + out[m.end("for") :]


# "whichever's nearer, the bottle or the chips, she can have": the choice put first
_WHICHEVER_FIRST38R = re.compile(
    r"\b(?P<so>so |and )?whichever(?:'s| is) (?P<adj>nearer|closer|nearest|closest|handier|"
    r"handiest|easier|easiest|quicker|quickest)(?: to (?:hand|reach|get))?,\s*"
    r"(?P<a>the [a-z]+(?: [a-z]+)?) or (?P<b>the [a-z]+(?: [a-z]+)?),\s*"
    r"(?P<who>she|he|[A-Za-z][\w ]*?) (?P<v>can have|can take|gets|should get|should have)"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _whichever_first38r(text: str, lexicon: Lexicon) -> str:
    """Session 38 (12r): "so whichever's nearer, the bottle or the chips, she can have" is "so she
    can have the bottle or the chips, whichever's nearer" (the two objects, each whole and each
    another, put before the one who may have either; 'she' is read as before, by what precedes)."""
    if "whichever" not in text.lower():
        return text
    m = _WHICHEVER_FIRST38R.search(text)
    if m is None or not _objects34r(lexicon, m["a"], m["b"]):
        return text
    who = m["who"]
    if who.lower() not in ("she", "he") and not _only_person(who, lexicon):
        return text
    return (
        f"{text[: m.start()]}{m['so'] or ''}{who} {m['v']} {m['a']} or {m['b']}, whichever's "
        f"{m['adj']}{m['end'] or '.'}"
    )


# "Any bottle you've got, to Person A.": the choice said of what there is
_YOU_HAVE38R = re.compile(
    r"\b(?P<h>(?:any|whatever|whichever) [a-z]+) (?:(?:that|which) )?(?:you(?:'ve| have)(?: got)?|"
    r"you can find|there is|there's)(?=\s*[,.;!?]|\s+(?:to|for) )",
    _F,
)


def _you_have38r(text: str, lexicon: Lexicon) -> str:
    """Session 38 (12r): "any bottle you've got" / "whatever cup there is" is "any bottle": what
    the scene holds is all there is to choose from (the kind names objects of the scene)."""
    if "you" not in text.lower() and "there" not in text.lower():
        return text

    def bare(m: re.Match[str]) -> str:
        k = m["h"].split()[1]
        return m["h"] if _only_kind(k, lexicon, "object") else m[0]

    return _YOU_HAVE38R.sub(bare, text)


# "Sam needs something to write with (for …), any of the pens will do."
_NEEDS_SOMETHING38R = re.compile(
    r"^(?P<p>[A-Za-z][\w ]*?) (?:needs|wants|could use|could do with) (?:something|a thing)"
    r"(?P<why>(?: to [a-z]+(?: [a-z]+)? (?:with|in|on))?(?: for [^,;]+?)?),\s*"
    r"(?P<x>any(?: one)? of the [a-z]+|any [a-z]+|either [a-z]+|either of the [a-z]+) will do"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _needs_something38r(text: str, lexicon: Lexicon) -> str:
    """Session 38 (12r): "Sam needs something to write with for the order, any of the pens will
    do" is "Any of the pens will do for Sam": one person's need of a thing (what it is for names
    nothing of the scene), then the choice of which."""
    if "will do" not in text.lower():
        return text
    m = _NEEDS_SOMETHING38R.match(text)
    if m is None or not _only_person(m["p"], lexicon) or not _names_nothing(m["why"], lexicon):
        return text
    x = re.sub(r"^any one of", "any of", m["x"], flags=_F)
    if not _ids(x, lexicon, "object") or _ids(x, lexicon, "human"):
        return text
    return f"{x[:1].upper()}{x[1:]} will do for {m['p']}{m['end'] or '.'}"


# "Ava or Grandad, one of them, gets the teddy."
_OR_ONE_OF38R = re.compile(
    r"^(?P<a>[A-Za-z][\w ]*?) or (?P<b>[A-Za-z][\w ]*?),\s*(?:one of (?:them|the two)|one or the "
    r"other|whichever of them|whoever),\s*",
    _F,
)


def _or_one_of38r(text: str, lexicon: Lexicon) -> str:
    """Session 38 (12r): "Ava or Grandad, one of them, gets the teddy" is "Ava or Grandad, either
    of them, gets the teddy" (read as before): 'one of them' after two people joined by 'or' says
    the choice again (each one person, each another; else left)."""
    if " or " not in text.lower():
        return text
    m = _OR_ONE_OF38R.match(text)
    if m is None or not _persons34r(lexicon, m["a"], m["b"]):
        return text
    return f"{m['a']} or {m['b']}, either of them, {text[m.end() :]}"


# "One of the patients should have the magazine(, either will do)."
_ONE_OF_ROLE38R = re.compile(r"\b(?P<one>one) of the (?P<role>[a-z]+?)(?:e?s)\b", _F)


def _one_of_role38r(text: str, lexicon: Lexicon) -> str:
    """Session 38 (12r): "one of the patients" where the scene has exactly two people called
    patient (and no object or surface of that name) is "either patient", a choice of the two;
    with one or three such people, left (refused as before)."""
    if "one of the" not in text.lower():
        return text

    def either(m: re.Match[str]) -> str:
        for role in (m["role"], m[0].split()[-1][:-1]):
            ids = _ids(f"the {role}", lexicon)
            if len(ids) == 2 and _only_kind(role, lexicon, "human"):
                return f"{'E' if m[0][0].isupper() else 'e'}ither {role}"
        return m[0]

    return _ONE_OF_ROLE38R.sub(either, text)


# "Each student gets a book, no matter which one goes to who."
_NO_MATTER38R = re.compile(
    r"^(?P<head>(?:each|every) [a-z]+ (?:gets|can have|should get|is to get|receives) "
    r"(?:a|an|one) [a-z]+(?: for [^,]+?)?|(?:a|an|one) [a-z]+ (?:each|apiece) for [^,]+?),\s*"
    r"(?:no matter|regardless of|it doesn't matter|it does not matter) "
    r"(?:which (?:one )?(?:goes to|gets) (?:who|whom|which)|who (?:gets|has|ends up with) "
    r"(?:which|what))(?P<end>\s*[.!]?)$",
    _F,
)


def _no_matter38r(text: str, _lexicon: Lexicon) -> str:
    """Session 38 (12r): after "each student gets a book" (a thing of a kind for each of several
    people), "no matter which one goes to who" says what 'each' already leaves open: taken off
    (as session 37's "I don't care who ends up with which" after 'apiece')."""
    if "matter" not in text.lower() and "regardless" not in text.lower():
        return text
    m = _NO_MATTER38R.match(text)
    return text if m is None else f"{m['head']}{m['end'] or '.'}"


# "Alice and Bob are back from the highland games: one thing each for them, …"
_THEM_NAMED38R = re.compile(
    r"^(?P<p>[A-Za-z][\w ]*?) and (?P<q>[A-Za-z][\w ]*?) (?:are|'re|were) (?P<rem>[^:;,]+?)"
    r"\s*[:;]\s*(?P<rest>[^:;]*?\b(?:for|to) )them\b(?P<tail>[^:;]*)$",
    _F,
)


def _them_named38r(text: str, lexicon: Lexicon) -> str:
    """Session 38 (12r): "Alice and Bob are back from the games: one thing each for them" is "one
    thing each for Alice and Bob": a remark about two people (naming nothing else of the scene),
    then a request for 'them' after a colon, which can only be those two."""
    if "them" not in text.lower():
        return text
    m = _THEM_NAMED38R.match(text)
    if m is None or not _persons34r(lexicon, m["p"], m["q"]):
        return text
    if not _names_nothing(m["rem"], lexicon) or re.search(
        r"\b(?:they|them|their|he|him|his|she|her)\b", m["tail"], _F
    ):
        return text
    rest = m["rest"][:1].upper() + m["rest"][1:]
    return f"{rest}{m['p']} and {m['q']}{m['tail']}"


# "All the food, the chips and the apple, to Person B.": what 'all the food' is, said after it
_ALL_THE_WORD38R = re.compile(
    r"^(?P<all>all (?:the|of the|this|that|my) (?P<w>[a-z]+)),\s*"
    r"(?P<list>(?:the [a-z]+(?: [a-z]+)?,\s*)*the [a-z]+(?: [a-z]+)?,?\s*and the [a-z]+"
    r"(?: [a-z]+)?),\s*(?P<rest>(?:to|for|on|in|into|onto) .+)$",
    _F,
)


def _all_the_word38r(text: str, lexicon: Lexicon) -> str:
    """Session 38 (12r): "All the food, the chips and the apple, to Person B" is "The chips and the
    apple to Person B": a word for things that names nothing of the scene ('food', 'kit'), then
    the list of what it is (each one whole name of another object, the last joined by 'and'); the
    word naming things of the scene is left (session 30 reads a list that says all of them)."""
    if "all" not in text.lower():
        return text
    m = _ALL_THE_WORD38R.match(text)
    if m is None or not _names_nothing(m["w"], lexicon):
        return text
    said = [w.strip() for w in re.split(r",\s*(?:and\s+)?|\s+and\s+", m["list"]) if w.strip()]
    if len(said) < 2 or not _objects34r(lexicon, *said):
        return text
    return f"{m['list'][:1].upper()}{m['list'][1:]} {m['rest']}"


# "Only the one bottle, and it's for Person A."
_ONLY_THE_ONE38R = re.compile(
    r"^(?:only|just) (?:the )?one (?P<k>[a-z]+),\s*(?:and )?(?:it's|it is|that's|that is|it goes|"
    r"that goes) (?P<to>for|to) (?P<p>[A-Za-z][\w ]*?)"
    r"(?P<tail>,\s*(?:she|he)(?:'s| is| was)\b[^;:]*?)?(?P<end>\s*[.!]?)$",
    _F,
)


def _only_the_one38r(text: str, lexicon: Lexicon) -> str:
    """Session 38 (12r): "Only the one bottle, and it's for Person A" is "The bottle for Person
    A": the count said first must be the scene's (exactly one object of that kind; else left)."""
    if "one" not in text.lower():
        return text
    m = _ONLY_THE_ONE38R.match(text)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    if not _only(m["k"], lexicon, "object"):
        return text
    return f"The {m['k']} {m['to']} {m['p']}{m['tail'] or ''}{m['end'] or '.'}"


# "…, on her shift with the crossing patrol.": the time of the speaker's context, said last
_ON_SHIFT38R = (
    r",\s*(?:on|during|for) (?:her|his|their) (?:shift|break|lunch break|tea break|rounds|round|"
    r"day off|night shift|late shift|early shift)(?: (?:with|at|on|in) [a-z' ]+)?(?=\s*[.!]?$)"
)


def _on_shift38r(text: str, lexicon: Lexicon) -> str:
    """Session 38 (12r): "…, on her shift with the crossing patrol" / "…, during his break at the
    depot" said last after a comma is when the person is busy, not a time the request waits on:
    taken off (when it names nothing of the scene), and the request read as now."""
    if " shift" not in text.lower() and " break" not in text.lower() and "round" not in text:
        return text
    return _drop(_ON_SHIFT38R, text, lexicon)


# "Put all three pens in the box so the sound tech stops walking off with them."
_SO_STOPS38R = (
    r"\s+so (?:that )?(?:the [a-z]+(?: [a-z]+)?|people|nobody|no one|everyone|they|it) "
    r"(?:stops|stop|doesn't|don't|won't|can't|cannot|can) [a-z]+\b[^,.;!?]*(?=\s*[.!]?$)"
)


def _so_stops38r(text: str, lexicon: Lexicon) -> str:
    """Session 38 (12r): a purpose said last with 'so' ("so the sound tech stops walking off with
    them", "so nobody can't find them") after a request: why it is asked, naming nothing of the
    scene ('them' is the things of the request): taken off."""
    if " so " not in text.lower():
        return text
    return _drop(_SO_STOPS38R, text, lexicon)


# "…, so both blocks, the red and the green, go to her."
_BOTH_LISTED38R = re.compile(
    r"\b(?P<c>so|and|then|but) (?P<both>both (?:the )?(?P<ks>[a-z]+s)),\s*"
    r"(?:(?:the )?(?P<a>[a-z]+) and (?:the )?(?P<b>[a-z]+)(?: ones)?,\s*)?"
    r"(?=(?:go|goes|are|should|can|get|must|will)\b)",
    _F,
)


def _both_listed38r(text: str, lexicon: Lexicon) -> str:
    """Session 38 (12r): "so both blocks, the red and the green, go to her" is "so both blocks go
    to her" when the two named are the scene's two blocks (as session 33's 'both mugs, red and
    blue', said after a conjunction: its own clause, whose verb follows)."""
    if "both" not in text.lower():
        return text

    def named(m: re.Match[str]) -> str:
        kind = _singular(m["ks"].lower())
        both = _ids(f"the {m['ks']}", lexicon, "object")
        if m["a"] is None:  # "so both blocks, go to her": session 33's rule took the two off
            return f"{m['c']} {m['both']} " if len(both) == 2 else m[0]
        one = _ids(f"the {m['a']} {kind}", lexicon, "object")
        two = _ids(f"the {m['b']} {kind}", lexicon, "object")
        if len(both) != 2 or len(one) != 1 or len(two) != 1 or one | two != both:
            return m[0]
        return f"{m['c']} {m['both']} "

    return _BOTH_LISTED38R.sub(named, text)


# "Ava wants to build a tower, so …": what the person wants to do, the reason for the request
_WANTS_TO_SO38R = re.compile(
    r"^(?P<p>[A-Za-z][\w ]*?) (?:wants|would like|'d like|is hoping|hopes) to "
    r"(?P<do>[a-z][a-z' ]*?),\s*so\s+(?P<rest>\S.*)$",
    _F,
)


def _wants_to_so38r(text: str, lexicon: Lexicon) -> str:
    """Session 38 (12r): "Ava wants to build a tower, so both blocks go to her" is "Ava is going
    to build a tower, so both blocks go to her": what one person wants to do (naming nothing of
    the scene) is the reason for what follows 'so', read as session 35's "P's <doing>, so …"."""
    if "so" not in text.lower() or " to " not in text:
        return text
    m = _WANTS_TO_SO38R.match(text)
    if m is None or not _only_person(m["p"], lexicon) or not _names_nothing(m["do"], lexicon):
        return text
    return f"{m['p']} is going to {m['do']}, so {m['rest']}"


# "The apple's Person B's, not Person A's": whose it is, against whose it is not
_NOT_WHOSE38R = re.compile(
    r"\b(?P<x>the [a-z]+(?: [a-z]+)?)(?:'s| is|'re| are) (?P<p>[A-Za-z][\w ]*?)'s,\s*not "
    r"(?P<q>[A-Za-z][\w ]*?)'s\b",
    _F,
)


def _not_whose38r(text: str, lexicon: Lexicon) -> str:
    """Session 38 (12r): "the apple's Person B's, not Person A's" is "the apple is for Person B,
    not Person A": said against another person, whose it is says who is to have it (a bare
    "the apple's Person B's" stays refused: it may only say whose it is)."""
    if "not" not in text.lower():
        return text

    def whose(m: re.Match[str]) -> str:
        if not _objects34r(lexicon, m["x"]) or not _persons34r(lexicon, m["p"], m["q"]):
            return m[0]
        verb = "are" if m[0][len(m["x"]) :].lstrip().startswith(("'re", "are")) else "is"
        return f"{m['x']} {verb} for {m['p']}, not {m['q']}"

    return _NOT_WHOSE38R.sub(whose, text)


# "Person B doesn't need the bottle any more, just the cup."
_ANY_MORE38R = re.compile(
    r"\b(?P<h>(?:doesn't|does not|don't|do not) (?:need|want) the [a-z]+(?: [a-z]+)?) "
    r"(?:any ?more|any longer|now),\s*(?P<j>just|only) (?=the )",
    _F,
)
_NO_LONGER38R = re.compile(
    r"\b(?:no longer|not any more) (?P<v>need|want)s? (?P<x>the [a-z]+(?: [a-z]+)?),\s*"
    r"(?P<j>just|only) (?=the )",
    _F,
)


def _any_more38r(text: str, lexicon: Lexicon) -> str:
    """Session 38 (12r): "P doesn't need the bottle any more, just the cup" is "P doesn't need the
    bottle, just the cup" (read as before: the cup), and "P no longer needs the bottle, just the
    cup" the same: what is no longer needed, then what is, said together (a bare "no longer needs
    the bottle" stays what changes a running task)."""
    if "just" not in text.lower() and "only" not in text.lower():
        return text
    out = _ANY_MORE38R.sub(lambda m: f"{m['h']}, {m['j']} ", text)
    return _NO_LONGER38R.sub(lambda m: f"doesn't {m['v']} {m['x']}, {m['j']} ", out)


# "Person A's had enough to drink at the party, so the chips, not the bottle."
_SO_NOT38R = re.compile(
    r"^(?P<p>[A-Za-z][\w ]*?)(?:'s| is| has|'s had| has had| was) (?P<rem>[^,;]+?),\s*so "
    r"(?P<x>the [a-z]+(?: [a-z]+)?),\s*not (?P<y>the [a-z]+(?: [a-z]+)?)(?P<end>\s*[.!]?)$",
    _F,
)


def _so_not38r(text: str, lexicon: Lexicon) -> str:
    """Session 38 (12r): "Person A's had enough to drink at the party, so the chips, not the
    bottle" is "The chips, not the bottle, to Person A": a remark about one person (naming nothing
    else of the scene), then what is for them against what is not."""
    if "not" not in text.lower():
        return text
    m = _SO_NOT38R.match(text)
    if m is None or not _only_person(m["p"], lexicon) or not _names_nothing(m["rem"], lexicon):
        return text
    if not _objects34r(lexicon, m["x"], m["y"]):
        return text
    x = m["x"][:1].upper() + m["x"][1:]
    return f"{x}, not {m['y']}, to {m['p']}{m['end'] or '.'}"


# "Never mind the chips; the bottle for Person B."
_NEVER_MIND38R = re.compile(
    r"^never mind (?:about )?(?P<x>the [a-z]+(?: [a-z]+)?)(?: for (?:now|today|the moment))?"
    r"\s*[;:,.]\s*(?P<rest>\S.*)$",
    _F,
)


def _never_mind38r(text: str, lexicon: Lexicon) -> str:
    """Session 38 (12r): "Never mind the chips; the bottle for Person B" opening an instruction is
    the request after it: 'never mind' takes an object of the scene off what is asked (as session
    22's "Never mind Alice for now, …" a person), when the rest names it nowhere (else left)."""
    if text[:5].lower() != "never":
        return text
    m = _NEVER_MIND38R.match(text)
    if m is None or not _objects34r(lexicon, m["x"]):
        return text
    if _ids(m["x"], lexicon, "object") & _ids(m["rest"], lexicon, "object"):
        return text
    if re.search(r"\b(?:it|them|that|those|they)\b", m["rest"], _F):
        return text
    return m["rest"][:1].upper() + m["rest"][1:]


# "Person A shouldn't get the chips; they're for Person B."
_SHOULDNT_GET38R = re.compile(
    r"^(?P<p>[A-Za-z][\w ]*?) (?:shouldn't|should not|isn't to|is not to|mustn't|must not) "
    r"(?:get|have|be given) (?P<x>the [a-z]+(?: [a-z]+)?)\s*[;,.]\s*(?P<pro>they're|they are|"
    r"it's|it is) (?:for|meant for) (?P<q>[A-Za-z][\w ]*?)(?P<end>\s*[.!]?)$",
    _F,
)


def _shouldnt_get38r(text: str, lexicon: Lexicon) -> str:
    """Session 38 (12r): "Person A shouldn't get the chips; they're for Person B" is "The chips
    are for Person B, not Person A": who is not to have a thing, then who is (one object, two
    people, each another)."""
    if "n't" not in text and " not " not in text:
        return text
    m = _SHOULDNT_GET38R.match(text)
    if m is None or not _objects34r(lexicon, m["x"]):
        return text
    if not _persons34r(lexicon, m["p"], m["q"]):
        return text
    x = m["x"][:1].upper() + m["x"][1:]
    verb = "are" if m["pro"].lower().startswith("they") else "is"
    return f"{x} {verb} for {m['q']}, not {m['p']}{m['end'] or '.'}"


# "The banana isn't for Omar, it's Emma who's asked for it."
_WHO_ASKED38R = re.compile(
    r"^(?P<head>the [a-z]+(?: [a-z]+)? (?:isn't|is not|aren't|are not) for [A-Za-z][\w ]*?),\s*"
    r"(?:it's|it is) (?P<q>[A-Za-z][\w ]*?) who(?:'s| has| is)? (?:asked for|wants|needs|ordered|"
    r"requested|been asking for|after|is after|wanted|asked me for) (?:it|them)"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _who_asked38r(text: str, lexicon: Lexicon) -> str:
    """Session 38 (12r): "The banana isn't for Omar, it's Emma who's asked for it" is "The banana
    isn't for Omar, it's for Emma": the cleft says whose want it is (one person of the scene)."""
    if " who" not in text.lower():
        return text
    m = _WHO_ASKED38R.match(text)
    if m is None or not _only_person(m["q"], lexicon):
        return text
    return f"{m['head']}, it's for {m['q']}{m['end'] or '.'}"


# "Priya hates the black pen, so any of the others will do her."
_HATES_OTHERS38R = re.compile(
    r"^(?P<p>[A-Za-z][\w ]*?) (?:hates|can't stand|cannot stand|doesn't like|does not like|"
    r"dislikes|won't use|will not use|isn't keen on|is not keen on) (?P<x>the [a-z]+ [a-z]+),\s*"
    r"so any (?:one )?of the others(?: will do(?: for)? (?P<pro>her|him))?(?P<end>\s*[.!]?)$",
    _F,
)


def _hates_others38r(text: str, lexicon: Lexicon) -> str:
    """Session 38 (12r): "Priya hates the black pen, so any of the others will do her" is "Any pen
    but the black one for Priya": the one thing a person will not have, then any of the others of
    its kind (two or more left; the pronoun one that person may be)."""
    if "others" not in text.lower():
        return text
    m = _HATES_OTHERS38R.match(text)
    if m is None or not _the_one36r(m["p"], m["pro"] or "", lexicon):
        return text
    if not _objects34r(lexicon, m["x"]):
        return text
    adj, kind = m["x"].split()[1:]
    every = _ids(f"the {kind}s", lexicon, "object") | _ids(f"the {kind}", lexicon, "object")
    if not _ids(m["x"], lexicon, "object") < every or len(every) < 3:
        return text
    return f"Any {kind} but the {adj} one for {m['p']}{m['end'] or '.'}"


# "Mrs Khan says the blue blanket's too thin, so not that one, the grey one for her."
_TOO_THIN38R = re.compile(
    r"^(?P<p>[A-Za-z][\w ]*?) (?:says|said|thinks|reckons|finds|found|complains|complained) "
    r"(?:that )?(?P<x>the [a-z]+ [a-z]+)(?:'s|'re| is| was| are)? "
    r"(?:too|far too|a bit too|much too) [a-z]+,\s*so not that one,\s*(?P<y>the [a-z]+ one) "
    r"(?P<to>for|to) (?P<pro>her|him)"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _too_thin38r(text: str, lexicon: Lexicon) -> str:
    """Session 38 (12r): "Mrs Khan says the blue blanket's too thin, so not that one, the grey one
    for her" is "Not the blue blanket, the grey one for Mrs Khan": what is wrong with one thing
    (said by the person, who the pronoun may be), then another of its kind for them."""
    if "not that one" not in text.lower():
        return text
    m = _TOO_THIN38R.match(text)
    if m is None or not _the_one36r(m["p"], m["pro"], lexicon):
        return text
    kind = m["x"].split()[-1]
    other = f"{m['y'][: -len('one')]}{kind}"
    if not _objects34r(lexicon, m["x"], other):
        return text
    return f"Not {m['x']}, {m['y']} {m['to']} {m['p']}{m['end'] or '.'}"


# "Leave the large box out of it; the other two boxes go on the pallet."
_LEAVE_OUT38R = re.compile(
    r"^leave (?P<x>the [a-z]+ [a-z]+) (?:out of it|out|alone|be|where it is)\s*[;,.:]\s*"
    r"the other (?:(?P<n>two|three|four) )?(?P<ks>[a-z]+s) (?P<rest>(?:go|should go|can go|are to "
    r"go|need to go|want to go|are going) .+)$",
    _F,
)
_COUNTS38R = {"two": 2, "three": 3, "four": 4}


def _leave_out38r(text: str, lexicon: Lexicon) -> str:
    """Session 38 (12r): "Leave the large box out of it; the other two boxes go on the pallet" is
    "All the boxes but the large one go on the pallet": one thing left out, then the others of its
    kind (their number, when said, the scene's less the one; else left, and refused)."""
    if text[:5].lower() != "leave":
        return text
    m = _LEAVE_OUT38R.match(text)
    if m is None or not _objects34r(lexicon, m["x"]):
        return text
    adj, kind = m["x"].split()[1:]
    every = _ids(f"the {m['ks']}", lexicon, "object")
    x = _ids(m["x"], lexicon, "object")
    if _singular(m["ks"].lower()) != kind.lower() or not x < every or len(every) < 3:
        return text
    if m["n"] and _COUNTS38R[m["n"].lower()] != len(every) - 1:
        return text
    return f"All the {m['ks']} but the {adj} one {m['rest']}"


# what each pronoun is said to have: "she's having", "he has", "she's getting"
_HAVING38R = r"(?:(?:'s| is) (?:having|getting|to have|taking)| (?:has|gets|takes))"
# "Alice and Bob each get something: she's having the chips, he's having the bottle."
_EACH_PRONOUNS38R = re.compile(
    r"^(?:(?P<p>[A-Za-z][\w ]*?) and (?P<q>[A-Za-z][\w ]*?) (?:each|both) (?:get|have|are "
    r"getting|are having) (?:something|one thing|a thing)(?: each)?|(?:just )?(?:the )?one "
    r"(?:item|thing) each for (?P<p2>[A-Za-z][\w ]*?) and (?P<q2>[A-Za-z][\w ]*?))\s*[:;,]\s*"
    rf"(?P<a>she|he){_HAVING38R} (?P<x>the [a-z]+(?: [a-z]+)?),\s*"
    rf"(?:and )?(?P<b>she|he){_HAVING38R} (?P<y>the [a-z]+(?: [a-z]+)?)(?P<end>\s*[.!]?)$",
    _F,
)


def _each_pronouns38r(text: str, lexicon: Lexicon) -> str:
    """Session 38 (12r): "Alice and Bob each get something: she's having the chips, he's having
    the bottle" is "Alice gets the chips and Bob gets the bottle" when 'she' and 'he' each can be
    only one of the two (the other ruled out by `_may_be35t`: a title, a first name of one sex, a
    word of kin) and is that one for certain or no one else in the scene may be it (session 36's
    `_named_by_sex36t`, which reads a pronoun so, one at a time); 'she' and 'she', or names that
    rule nobody out, stay refused."""
    if " each " not in text.lower() and " both " not in text.lower():
        return text
    m = _EACH_PRONOUNS38R.match(text)
    if m is None or m["a"].lower() == m["b"].lower():
        return text
    p, q = (m["p"], m["q"]) if m["p"] else (m["p2"], m["q2"])
    if not _persons34r(lexicon, p, q) or not _objects34r(lexicon, m["x"], m["y"]):
        return text
    named = {next(iter(_ids(w, lexicon, "human"))): w for w in (p, q)}
    picked: list[str] = []
    for pronoun in (m["a"], m["b"]):
        may = [pid for pid in named if _may_be35t(pid, pronoun, lexicon)]
        if len(may) != 1:
            return text
        (pid,) = may
        others = [h.id for h in lexicon.scene.humans if h.id != pid]
        if not _sure36t(pid, pronoun, lexicon) and any(
            _may_be35t(o, pronoun, lexicon) for o in others
        ):
            return text
        picked.append(named[pid])
    if picked[0] == picked[1]:
        return text
    return f"{picked[0]} gets {m['x']} and {picked[1]} gets {m['y']}{m['end'] or '.'}"


# "Either of them can have the bottle, Person A or Person B, whoever's nearer to the door."
_EITHER_NAMED38R = re.compile(
    r"^either (?:of them|one of them|one) (?P<v>can have|gets|should get|should have|can take)"
    r" (?P<x>the [a-z]+(?: [a-z]+)?),\s*(?P<p>[A-Za-z][\w ]*?) or (?P<q>[A-Za-z][\w ]*?)"
    r"(?:,\s*(?P<who>whoever|whichever)(?:'s| is) (?P<adj>nearer|closer|nearest|closest|free|"
    r"freer|handier)(?P<to> (?:to|by|at) the [a-z]+(?: [a-z]+)?)?)?(?P<end>\s*[.!]?)$",
    _F,
)


def _either_named38r(text: str, lexicon: Lexicon) -> str:
    """Session 38 (12r): "Either of them can have the bottle, Person A or Person B, whoever's
    nearer to the door" is "Person A or Person B can have the bottle, whoever's nearer": who 'them'
    are, said after the object (two people, each another; the object one whole name; where they
    are nearer to names nothing of the scene)."""
    if text[:6].lower() != "either":
        return text
    m = _EITHER_NAMED38R.match(text)
    if m is None or not _persons34r(lexicon, m["p"], m["q"]) or not _objects34r(lexicon, m["x"]):
        return text
    if m["to"] and not _names_nothing(m["to"], lexicon):
        return text
    tail = f", whoever's {m['adj']}" if m["who"] else ""
    return f"{m['p']} or {m['q']} {m['v']} {m['x']}{tail}{m['end'] or '.'}"


# Session 38 (12r): a list said after 'something' or 'all the stuff' that says what it is
_LIST_SAYS38R = re.compile(
    r"\b(?P<word>something|anything|a thing|all (?:the|of the|this|that|my) (?:stuff|things|lot)),"
    r"\s*(?P<list>(?:the [a-z]+(?: [a-z]+)?(?:,\s*|,?\s+and\s+))*the [a-z]+(?: [a-z]+)?,?\s*"
    r"(?:or|and) the [a-z]+(?: [a-z]+)?)\b",
    _F,
)


def list_says38r(text: str, lexicon: Lexicon) -> None:
    """Session 38 (12r): "Give Alice something, the cup or the apple" had read as any object or
    the cup or the apple (a choice of every object), and "All the stuff, the knife, the lemon and
    the salt, to Marco" as every object: the list after 'something' / 'all the stuff' says what it
    is. Refused here, when the list names objects of the scene and not every one of them, so the
    rewrites read the list alone (`_something_listed38r`, `_all_the_word38r`)."""
    lowered = text.lower()
    if "thing" not in lowered and "stuff" not in lowered and " lot," not in lowered:
        return
    m = _LIST_SAYS38R.search(text)
    if m is None:
        return
    listed = _ids(m["list"], lexicon, "object")
    if not listed or listed == {o.id for o in lexicon.scene.objects}:
        return
    raise GroundingError(f"{m[0]!r}: the list says what {m['word']!r} is; say {m['list']!r} alone")


# "Bob's the red one, hand him the cup."
_DESCRIBED_ONE38R = re.compile(
    r"^(?P<p>[A-Za-z][\w ]*?)(?:'s| is) the (?P<adj>[a-z]+) one\s*[,;:]\s*(?P<rest>\S.*)$", _F
)


def described_one38r(text: str, lexicon: Lexicon) -> None:
    """Session 38 (12r): "Bob's the red one, hand him the cup" where one object of the scene is
    called red ('the red mug') may say who Bob is (the one in red; then only the cup) or whose the
    red mug is ("Bob's is the red one"; then it is handed over too, as session 33 allots "The drill
    is Jess's, …" beside another part): refused naming both readings (it had read the second).
    Where no object is called by the word ('the tall one'), nothing is said of an object."""
    if " one" not in text.lower():
        return
    m = _DESCRIBED_ONE38R.match(text)
    if m is None or not _only_person(m["p"], lexicon):
        return
    adj = m["adj"].lower()
    called = [
        (o.id, a)
        for o in lexicon.scene.objects
        for a in o.aliases
        if a.lower().split()[0] == adj and len(a.split()) > 1
    ]
    if len({oid for oid, _a in called}) != 1:
        return
    (pid,) = _ids(m["p"], lexicon, "human")
    oid, alias = called[0]
    raise GroundingError(
        f"{m['p']}'s the {m['adj']} one could say who {m['p']} is (then only: {m['rest']!r}) or "
        f"that the {alias} ({oid}) is {m['p']}'s, to be handed over too ({oid}>{pid}): say "
        f"'give {m['p']} the {alias}' if it is to go, or leave the description out"
    )


_STEPS38R: tuple[Callable[[str, Lexicon], str], ...] = (
    _any_old38r,
    _something_listed38r,
    _whichever_first38r,
    _you_have38r,
    _needs_something38r,
    _one_of_role38r,
    _or_one_of38r,
    _no_matter38r,
    _them_named38r,
    _all_the_word38r,
    _only_the_one38r,
    _on_shift38r,
    _so_stops38r,
    _both_listed38r,
    _wants_to_so38r,
    _not_whose38r,
    _any_more38r,
    _so_not38r,
    _never_mind38r,
    _shouldnt_get38r,
    _who_asked38r,
    _hates_others38r,
    _too_thin38r,
    _leave_out38r,
    _each_pronouns38r,
    _either_named38r,
)
