"""The grounder's rules of session 40, engineer 12r (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _ids, _names, _names_nothing, _only_person
from hltl.grounding._normalise3 import _whole_name
from hltl.grounding._normalise4 import _CORRECTION_CUE33R, _persons34r, _the_one36r
from hltl.grounding.lexicon import Lexicon
from hltl.grounding.tree import Node

# a person's name as these rules take it (checked against the scene after the match)
_NAME40R = r"[A-Za-z][\w ]*?"
# an object's name as these rules take it (checked against the scene after the match)
_THING40R = r"the [a-z]+(?: [a-z]+)?"


def _capital40r(text: str) -> str:
    return text[:1].upper() + text[1:]


# -- negation and exclusion ------------------------------------------------------------------------

# "The bottle's not for Person A, it's Person B's", "The glue stick isn't for Noah, Zoe's the one
# who asked", "…, Zoe wants it"
_CONTRAST40R = (
    rf"^(?P<what>{_THING40R})(?:'s| is)(?: not|n't) for (?P<p>{_NAME40R})\s*[,;]\s*(?:but )?"
    rf"(?:it(?:'s| is) (?P<q1>{_NAME40R})'s|(?P<q2>{_NAME40R})(?:'s| is) the one (?:who|that) "
    rf"(?:asked(?: for it)?|wants it|needs it|ordered it)|(?P<q3>{_NAME40R}) (?:wants|needs|"
    r"asked for|has asked for|'s asked for) it)(?P<end>\s*(?:[,.;!]|$))"
)


def _contrast40r(text: str, lexicon: Lexicon) -> str:
    """Session 40 (12r): who a thing is for said as a contrast of two people, the second as
    whose it is or as the one who asked: "X's not for P, it's Q's", "X isn't for P, Q's the one
    who asked (wants it, needs it)", "…, Q wants it" are "X isn't for P, it's for Q" (session
    29's `_not_for_but29s` reads it): X an object named whole, P and Q two people."""
    if " for " not in text:
        return text
    m = re.match(_CONTRAST40R, text, _F)
    if m is None or not _whole_name(m["what"], lexicon, "object"):
        return text
    q = m["q1"] or m["q2"] or m["q3"]
    if not _persons34r(lexicon, m["p"], q):
        return text
    return f"{m['what']} isn't for {m['p']}, it's for {q}{m['end']}{text[m.end() :]}"


# "Alice says no bottle for her; …", "Bob's gone off crisps since the bar billiards, …"
_GONE_OFF40R = (
    rf"(?:^|(?<=[.;!?]\s))(?P<p>{_NAME40R})(?:(?: says| said|'s said| has said) no (?:to )?"
    r"(?P<x>(?:the )?[a-z]+(?: [a-z]+)?)(?: for (?:her|him|them))?(?:,\s*thanks)?|(?:'s| has) "
    r"(?:gone (?:right |completely )?off(?: the idea of)?|gone cold on|had enough of|gone sick of)"
    r" (?P<y>(?:the )?[a-z]+(?: [a-z]+)?)(?: since [a-z' -]+?)?)\s*[,;]\s*(?=[a-z])"
)


def _gone_off40r(text: str, lexicon: Lexicon) -> str:
    """Session 40 (12r): a person turning a thing down said as a report or a change of taste:
    "P says no X (for her)", "P said no to X", "P's gone (right) off X (since …)", "P's gone
    cold on X", "P's had enough of X", followed by another clause, are "P doesn't want the X,
    …" (one person, an object named whole), which the grammar reads as before (session 39's
    `_not_wanted39r`): dropped beside a request that names neither it nor 'it', else refused
    as a negation."""
    low = text.lower()
    if " no " not in low and " off " not in low and " on " not in low and " of " not in low:
        return text

    def said(m: re.Match[str]) -> str:
        what = m["x"] or m["y"]
        the = what if what.lower().startswith("the ") else f"the {what}"
        if not _only_person(m["p"], lexicon) or not _whole_name(the, lexicon, "object"):
            return m[0]
        return f"{m['p']} doesn't want {the}, "

    return re.sub(_GONE_OFF40R, said, text, flags=_F)


# "No need to ask, the bottle's for Person A."
_NO_NEED40R = (
    r"^(?:no need to (?:ask|check|wait|worry|look)(?: (?:anyone|her|him|them|me|around|twice))?|"
    r"(?:don't|do not|no need to) bother asking(?: (?:her|him|them|anyone))?)\s*,\s*(?=[a-z])"
)


def _no_need40r(text: str, _lexicon: Lexicon) -> str:
    """Session 40 (12r): "No need to ask (anyone), <request>", "Don't bother asking, …" opens
    a request by saying the speaker's word is enough: the request after it is what to do."""
    m = re.match(_NO_NEED40R, text, _F)
    return text if m is None else _capital40r(text[m.end() :])


# "Leave the knife, just give Marco the tongs."
_LEAVE_FIRST40R = rf"^(?:leave|forget about|skip) (?P<x>{_THING40R})\s*,\s*(?=(?:just|only) )"


def _leave_first40r(text: str, lexicon: Lexicon) -> str:
    """Session 40 (12r): "Leave X, just <request>" (forget about, skip X) opening a request that
    names another object (nor 'it') is "Not X, just <request>" (session 34's opener): what is
    left out, then the request. "Leave X with P" and "Leave X, just give it to P" stay
    refused."""
    m = re.match(_LEAVE_FIRST40R, text, _F)
    if m is None or not _whole_name(m["x"], lexicon, "object"):
        return text
    rest = text[m.end() :]
    named = _ids(rest, lexicon, "object")
    if not named or named & _ids(m["x"], lexicon, "object"):
        return text
    if re.search(r"\b(?:it|them|that|this|one)\b", rest, _F):
        return text
    return f"Not {m['x']}, {rest}"


# "Don't put the teddy on the mat, put the bib on it."
_DONT_BUT40R = (
    rf"^(?:please )?(?:don't|do not) (?:put|place|set|stick|pop|lay) (?P<a>{_THING40R}) "
    rf"(?P<prep>on|onto|in|into|on top of) (?P<s>{_THING40R})\s*[,;]\s*(?:(?:just|instead) )?"
    rf"(?P<v>put|place|set|stick|pop|lay) (?P<b>{_THING40R}) (?:on|onto|in|into|on top of) "
    r"(?:it|there|that)(?: instead)?(?P<end>\s*[.!]?)$"
)


def _dont_but40r(text: str, lexicon: Lexicon) -> str:
    """Session 40 (12r): "Don't put X on S, put Y on it (there)" is "Put Y on S, not X" (session
    26's reading): the placing taken back and the one asked, its 'it' the surface (X and Y two
    objects named whole, S a surface named whole)."""
    m = re.match(_DONT_BUT40R, text.strip(), _F)
    if m is None:
        return text
    a, b = m["a"], m["b"]
    if not (_whole_name(a, lexicon, "object") and _whole_name(b, lexicon, "object")):
        return text
    if not _whole_name(m["s"], lexicon, "surface"):
        return text
    if _ids(a, lexicon, "object") & _ids(b, lexicon, "object"):
        return text
    return f"{_capital40r(m['v'])} {b} {m['prep']} {m['s']}, not {a}{m['end'] or '.'}"


# "Priya's pen is neither the black one nor the red one, it's the other one, …"
_NEITHER40R = (
    r"\b(?:neither|not) the (?P<a>[a-z]+) one,? (?:nor|or) the (?P<b>[a-z]+) one\s*[,;]\s*"
    r"(?:it's |it is |but |just )?the other (?:one|of them|one of them)\b"
)


def _adjectives40r(lexicon: Lexicon) -> dict[str, dict[str, str]]:
    """Each category of the scene's objects: the object each adjective names ('blue pen')."""
    out: dict[str, dict[str, str]] = {}
    for o in lexicon.scene.objects:
        for alias in o.aliases:
            words = alias.lower().split()
            if len(words) == 2 and words[1] == o.category:
                out.setdefault(o.category, {})[words[0]] = o.id
    return out


def _neither_nor40r(text: str, lexicon: Lexicon) -> str:
    """Session 40 (12r): "neither the A one nor the B one, (it's) the other one" (not the A one
    or the B one, …) is "the C one" when one kind of the scene has objects called A, B and
    exactly one more, C, and no other kind has both A and B: what is left out leaves one."""
    if "other" not in text.lower():
        return text
    m = re.search(_NEITHER40R, text, _F)
    if m is None:
        return text
    a, b = m["a"].lower(), m["b"].lower()
    fits = []
    for named in _adjectives40r(lexicon).values():
        if a in named and b in named and a != b:
            rest = {adj for adj, oid in named.items() if oid not in (named[a], named[b])}
            fits.append(rest)
    if len(fits) != 1 or len(fits[0]) != 1:
        return text
    (c,) = fits[0]
    return f"{text[: m.start()]}the {c} one{text[m.end() :]}"


# -- choice idioms ---------------------------------------------------------------------------------

# "Person B's not fussy (after his rehearsal), he'll take any one of the four."
_NOT_FUSSY40R = (
    rf"^(?P<p>{_NAME40R})(?:'s| is)(?: not|n't) (?:fussy|picky|choosy|bothered|particular)"
    r"(?P<said>(?: [a-z' -]+?)?)\s*,\s*(?:so )?(?P<pro>he|she|they)(?:'ll| will) "
    r"(?=(?:take|have) (?:any|either|whichever|one of)\b)"
)
# "One of them, doesn't matter which, should get the bottle."
_ONE_ANY40R = (
    r"\bone of (?P<who>them|the two|the pair of them|the two of them)\s*,\s*(?:it )?(?:doesn't|"
    r"does not) matter which(?: one)?\s*,\s*"
)
# "Give Person A one of the drinks, the cup or the bottle"
_ONE_OF_KIND40R = r"\bone of the (?P<kind>[a-z]+s)\s*,\s*(?P<x>the [a-z]+(?: [a-z]+)?) or the "
# "Person B's fine with either, the bottle or the chips"
_EITHER_COMMA40R = r"\b(?P<head>(?:fine|happy|ok|okay|good|alright) with either)\s*,\s*(?=the )"


def _indifferent40r(text: str, lexicon: Lexicon) -> str:
    """Session 40 (12r): a person's indifference said beside a choice the request offers adds
    nothing to it: "P's not fussy (…), he'll take any one of the four" is "P will take any one
    of the four" (the pronoun one P may be); "one of them, doesn't matter which, …" is "either
    of them …" (read in a scene of two people only); "one of the drinks, the cup or the bottle"
    is "the cup or the bottle"; "fine with either, the X or the Y" is "fine with either the X or
    the Y". Without a choice, nothing is read."""
    low = text.lower()
    out = text
    if "fuss" in low or "pick" in low or "choos" in low or "bother" in low or "partic" in low:
        m = re.match(_NOT_FUSSY40R, out, _F)
        if (
            m is not None
            and _the_one36r(m["p"], "" if m["pro"].lower() == "they" else m["pro"], lexicon)
            and _names_nothing(m["said"], lexicon)
        ):
            out = f"{m['p']} will {out[m.end() :]}"
    if "matter" in low:

        def either(m: re.Match[str]) -> str:
            return "Either of them " if m[0][0].isupper() else "either of them "

        out = re.sub(_ONE_ANY40R, either, out, flags=_F)
    if "one of the" in low:
        m = re.search(_ONE_OF_KIND40R, out, _F)
        if m is not None and _whole_name(m["x"], lexicon, "object"):
            out = f"{out[: m.start()]}{out[m.start('x') :]}"
    if "either" in low:
        out = re.sub(_EITHER_COMMA40R, r"\g<head> ", out, flags=_F)
    return out


# "The apple can go to whoever's nearest, Person A or Person B."
_WHOEVER40R = (
    rf"\bwhoever(?:'s| is) (?P<said>[a-z]+(?: [a-z]+)?)\s*,\s*(?=(?P<p>{_NAME40R}) or "
    rf"(?P<q>{_NAME40R})\s*(?:[,.;!]|$))"
)
# "Omar can take whichever cup's going, green or white."
_WHICHEVER_KIND40R = (
    r"\bwhichever (?P<kind>[a-z]+)(?:(?:'s| is) (?:going|free|spare|handy|nearest|closest|nearer|"
    r"closer|clean|around|about|there|available|to hand))?\s*,\s*(?P<a>[a-z]+) or (?P<b>[a-z]+)"
    r"(?=\s*(?:[,.;!]|$))"
)


def _whoever40r(text: str, lexicon: Lexicon) -> str:
    """Session 40 (12r): a choice named after what picks it: "to whoever's nearest, P or Q" is
    "to P or Q" (two people; what picks them names nothing in the scene); "whichever cup's
    going, green or white" is "the green cup or the white cup" (each an object named whole)."""
    low = text.lower()
    out = text
    if "whoever" in low:
        m = re.search(_WHOEVER40R, out, _F)
        if (
            m is not None
            and _persons34r(lexicon, m["p"], m["q"])
            and _names_nothing(m["said"], lexicon)
        ):
            out = f"{out[: m.start()]}{out[m.end() :]}"
    if "whichever" in low:
        m = re.search(_WHICHEVER_KIND40R, out, _F)
        if m is not None:
            a, b = f"the {m['a']} {m['kind']}", f"the {m['b']} {m['kind']}"
            if (
                _whole_name(a, lexicon, "object")
                and _whole_name(b, lexicon, "object")
                and _ids(a, lexicon) != _ids(b, lexicon)
            ):
                out = f"{out[: m.start()]}{a} or {b}{out[m.end() :]}"
    return out


# -- counts and distributions ----------------------------------------------------------------------

# "Give the pair of them one each: …"
_PAIR40R = r"\b(?:the pair of them|the two of them)\b(?=\s+one each\b)"


def _pair40r(text: str, _lexicon: Lexicon) -> str:
    """Session 40 (12r): "the pair of them one each", "the two of them one each" is "both of
    them one each" (the list after it then says who gets which)."""
    if "one each" not in text.lower():
        return text
    return re.sub(_PAIR40R, "both of them", text, flags=_F)


_NUMBER40R = {"two": 2, "three": 3, "four": 4}
# "Two things for two people: Person A's the chips, Person B's the bottle."
_COUNT_FOR40R = (
    r"^(?P<n>two|three|four) (?:things|items|bits|jobs|deliveries) for (?P<k>two|three|four) "
    r"(?:people|of them|folk)\s*:\s*(?=[a-z])"
)


def _count_for40r(text: str, lexicon: Lexicon) -> str:
    """Session 40 (12r): "Two things for two people: <list>" announces a list: taken off when
    the list names as many objects and as many people as it counts (else left, refused)."""
    m = re.match(_COUNT_FOR40R, text, _F)
    if m is None:
        return text
    rest = text[m.end() :]
    if len(_ids(rest, lexicon, "object")) != _NUMBER40R[m["n"].lower()]:
        return text
    if len(_ids(rest, lexicon, "human")) != _NUMBER40R[m["k"].lower()]:
        return text
    return _capital40r(rest)


# "Alice needs supplies: both the bottle and the crisps, please."
_NEEDS_LIST40R = (
    rf"^(?P<p>{_NAME40R}) (?P<v>needs|wants|is after|'s after) (?:some |a few |a couple of )?"
    r"(?:supplies|things|bits|stuff|bits and pieces)(?P<why> for (?:her|his|their|the) "
    r"[a-z' -]+?)?\s*:\s*(?=(?:both )?the )"
)


def _needs_list40r(text: str, lexicon: Lexicon) -> str:
    """Session 40 (12r): "P needs supplies (things, bits) (for her class): X and Y" is "P needs X
    and Y": the word before the colon, with what they are for (naming nothing in the scene),
    only announces the list (one person, the list all objects)."""
    m = re.match(_NEEDS_LIST40R, text, _F)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    if m["why"] and not _names_nothing(m["why"], lexicon):
        return text
    rest = text[m.end() :]
    if not _ids(rest, lexicon, "object") or _ids(rest, lexicon, "human"):
        return text
    return f"{m['p']} {m['v']} {rest}"


# "We've only got the one bottle, and it's Person A's", "There's a single bottle, and …"
_SCARCE40R = (
    r"^(?:we've (?:only )?got |we (?:only )?have |we've only |there's (?:only |just )?|there is "
    r"(?:only |just )?)(?:the one|a single|one|just the one|only the one|only one|just one) "
    r"(?P<x>[a-z]+(?: [a-z]+)?)\s*,?\s*(?:and|so|but)\s+(?P<rest>.+)$"
)


def _scarce40r(text: str, lexicon: Lexicon) -> str:
    """Session 40 (12r): "We've only got the one X, and it's P's" (there's a single X, and …)
    says who the one thing goes to: "it's P's" is "the X is for P", and any other clause after
    it is read with its one 'it' as the X (an object named whole, the scene's only one)."""
    m = re.match(_SCARCE40R, text.strip(), _F)
    if m is None:
        return text
    x = f"the {m['x']}"
    if not _whole_name(x, lexicon, "object") or len(_ids(x, lexicon, "object")) != 1:
        return text
    rest = m["rest"]
    if len(re.findall(r"\b(?:it|them|they|one)\b", rest, _F)) != 1 + rest.lower().count(
        "the one who"
    ):
        return text
    own = re.match(rf"it(?:'s| is) (?P<p>{_NAME40R})'s(?P<end>\s*(?:[,.;!]|$))", rest, _F)
    if own is not None:
        if not _only_person(own["p"], lexicon):
            return text
        return f"{_capital40r(x)} is for {own['p']}{own['end']}{rest[own.end() :]}"
    its = re.sub(r"\bit\b", x, rest, count=1, flags=_F)
    return text if its == rest else _capital40r(its)


# "Person A's taking both items to the repair cafe, so hand them over."
_TAKING_SO40R = (
    rf"^(?P<p>{_NAME40R})(?:'s| is) taking (?P<x>[^,]+?)(?: (?:to|over to|down to) "
    r"(?P<where>the [a-z' -]+?))?\s*,\s*so (?:hand|give|pass|bring) (?:it|them) "
    r"(?:over|to (?P<pro>him|her|them))(?=\s*(?:[,.;!]|$))"
)


def _taking_so40r(text: str, lexicon: Lexicon) -> str:
    """Session 40 (12r): "P's taking X (to <somewhere not in the scene>), so hand them over" is
    "P's getting X": the person takes the things away with them, so they are handed to the
    person (one person, whom the pronoun may be; X objects; the place names nothing in the
    scene)."""
    if "taking" not in text.lower():
        return text
    m = re.match(_TAKING_SO40R, text, _F)
    pro = (m["pro"] or "").lower() if m is not None else ""
    if m is None or not _the_one36r(m["p"], "" if pro == "them" else pro, lexicon):
        return text
    if m["where"] and not _names_nothing(m["where"], lexicon):
        return text
    if not _ids(m["x"], lexicon, "object") and not re.search(r"\b(?:items|things)\b", m["x"]):
        return text
    if _ids(m["x"], lexicon, "human"):
        return text
    return f"{m['p']}'s getting {m['x']}{text[m.end() :]}"


# -- corrections -----------------------------------------------------------------------------------

_MARK40R = r"(?:no|sorry|wait|no wait|hang on|hold on|oops|scratch that)"
# "…, no, sorry, wrong name, they're for Alice", "…, um, no, correction, it's Person B's"
_BLAME40R = (
    rf"(?P<m>(?<=,\s){_MARK40R}\s*,\s*)(?:(?:um|erm|er|uh|oh)\s*,\s*)?(?:wrong name|wrong person|"
    r"wrong one|my mistake|my bad|my fault|silly me|correction|i'm all over the place(?: today)?|"
    r"i'm (?:getting )?(?:muddled|mixed up|confused)(?: today)?|i got (?:that|it) wrong|"
    r"i misspoke)\s*,\s*(?=[a-z])"
)
_UM40R = r",\s*(?:um|erm|er|uh)\s*,\s*(?=(?:no|sorry|wait)\b)"


def _blame40r(text: str, _lexicon: Lexicon) -> str:
    """Session 40 (12r): the speaker blaming themselves inside a correction ("no, sorry, wrong
    name, …", "no, my mistake, …", "sorry, I'm all over the place, …", "no, correction, …")
    and a hesitation before its marker ("…, um, no, …") say nothing of what is corrected: taken
    off, the marker kept, so the correction reads as before. A marker opening a sentence ("….
    Sorry, my mistake, …") is left: it could correct or add (session 33); so is a cue session
    33's `_correction_cue33r` reads ("…, hmm, no, my mistake, …")."""
    if _CORRECTION_CUE33R.search(text):
        return text  # a cue said at length that session 33's `_correction_cue33r` reads
    low = text.lower()
    out = text
    if "um" in low or "er" in low or "uh" in low:
        out = re.sub(_UM40R, ", ", out, flags=_F)
    return re.sub(_BLAME40R, r"\g<m>", out, flags=_F)


# "…, no, she'd rather the cup"
_RATHER40R = r"(?P<w>'d|\bwould) rather (?=(?:the|a|an|some) [a-z]+(?: [a-z]+)?\s*(?:[,.;!]|$))"


def _rather40r(text: str, _lexicon: Lexicon) -> str:
    """Session 40 (12r): "P'd rather the cup" (would rather) is "P'd rather have the cup": a
    want, as the grammar reads it with 'have', when the thing ends the clause ("P'd rather the
    cup went to Q" is left; "or rather" stays a correction)."""
    if "rather" not in text.lower():
        return text
    return re.sub(_RATHER40R, r"\g<w> rather have ", text, flags=_F)


# "…, no wait, he asked for the blue one"
_ASKED_FOR40R = rf"(?P<m>\b{_MARK40R}\s*,\s*)(?P<p>he|she|they)(?: has|'s)? asked for (?=the )"


def _asked_for40r(text: str, _lexicon: Lexicon) -> str:
    """Session 40 (12r): a correction said as what the person asked for ("…, no wait, he asked
    for the blue one") is the correction "…, no wait, he wants the blue one"."""
    if "asked for" not in text.lower():
        return text

    def wants(m: re.Match[str]) -> str:
        verb = "want" if m["p"].lower() == "they" else "wants"
        return f"{m['m']}{m['p']} {verb} "

    return re.sub(_ASKED_FOR40R, wants, text, flags=_F)


# "…, no, my mistake, Person B put his name on them"
_CLAIM40R = (
    rf"(?:^|(?<=[,;.]\s))(?P<p>{_NAME40R})(?:'s | has | )(?:put (?:his|her|their) name on|"
    r"(?:got |called )?dibs on|bagged|claimed) "
    rf"(?P<x>them|it|{_THING40R})(?P<when> (?:at|during|after|before|earlier at) the "
    r"[a-z' -]+?)?(?=\s*(?:[,.;!]|$))"
)


def _claim40r(text: str, lexicon: Lexicon) -> str:
    """Session 40 (12r): a person's claim on a thing ("P put his name on them", "P's got dibs
    on X", "P has bagged X", "P's claimed X"), and when it was made ("… at the seed swap", naming
    nothing in the scene), is "P wants X" (one person; an object named whole, or 'it', 'them' as
    the grammar then reads them)."""
    low = text.lower()
    if "name on" not in low and "dibs" not in low and "bagged" not in low and "claim" not in low:
        return text

    def wants(m: re.Match[str]) -> str:
        if not _only_person(m["p"], lexicon):
            return m[0]
        if m["x"].lower() not in ("it", "them") and not _whole_name(m["x"], lexicon, "object"):
            return m[0]
        if m["when"] and not _names_nothing(m["when"], lexicon):
            return m[0]
        return f"{m['p']} wants {m['x']}"

    return re.sub(_CLAIM40R, wants, text, flags=_F)


# "…, no, they're Person B's"
_THEIRS40R = (
    rf"(?P<m>(?<=,\s){_MARK40R}\s*,\s*)(?P<pro>they|those|these)(?:'re| are) (?P<p>{_NAME40R})'s"
    r"(?=\s*(?:[,.;!]|$))"
)


def _theirs40r(text: str, lexicon: Lexicon) -> str:
    """Session 40 (12r): a correction saying whose the things are ("…, no, they're Person B's")
    is "…, no, they're for Person B", as "…, no, it's Person B's" reads (one person)."""
    if "'s" not in text:
        return text

    def theirs(m: re.Match[str]) -> str:
        if not _only_person(m["p"], lexicon):
            return m[0]
        return f"{m['m']}{m['pro']} are for {m['p']}"

    return re.sub(_THEIRS40R, theirs, text, flags=_F)


# the normaliser's rewrites (wired into normalise._STEPS19)
_STEPS40R: tuple[Callable[[str, Lexicon], str], ...] = (
    _blame40r,
    _theirs40r,
    _asked_for40r,
    _rather40r,
    _claim40r,
    _no_need40r,
    _contrast40r,
    _gone_off40r,
    _leave_first40r,
    _dont_but40r,
    _neither_nor40r,
    _indifferent40r,
    _whoever40r,
    _pair40r,
    _count_for40r,
    _needs_list40r,
    _scarce40r,
    _taking_so40r,
)


# -- refusals that name the readings -------------------------------------------------------------

# "One of them's after the apple, can't recall who."
_ONE_OF_THEM40R = (
    r"^(?:and |so |oh,? )?one of (?:them|the two|the pair of them|the two of them)(?:'s| is| has|"
    r" wants| needs| asked| would| could| should| will|'ll|'d)\b(?!\s*(?:,|either|whichever))"
)


def one_of_them40r(text: str, lexicon: Lexicon) -> None:
    """Session 40 (12r): "One of them's after the apple (, can't recall who)" names no one:
    refused naming each person of the scene it could mean (when the text names no person: "one
    of them, Alice or Bob" is a choice; "one of them, doesn't matter which" a choice read
    by `_indifferent40r`)."""
    if "one of" not in text.lower():
        return
    if re.match(_ONE_OF_THEM40R, text.strip(), _F) is None or _ids(text, lexicon, "human"):
        return
    people = [f"{h.id} ({h.name})" for h in lexicon.scene.humans]
    if len(people) < 2:
        return
    raise GroundingError(
        f"'one of them' names no one: it could mean {' or '.join(people)}; name the person"
    )


# "…, no, the other thing, or maybe not, I'm not sure now."
_DOUBTED40R = (
    rf"(?P<mark>\b{_MARK40R})\s*,.*?,\s*(?P<doubt>(?:or )?maybe not|or not|i'm not sure(?: now)?|"
    r"i am not sure(?: now)?|i can't remember|i don't know(?: now)?)\s*(?:[,.;!]|$)"
)


def doubted_correction40r(text: str, lexicon: Lexicon) -> None:
    """Session 40 (12r): a correction the speaker then doubts ("…, no, the other thing, or
    maybe not, I'm not sure now") leaves open what is meant: refused naming the objects it could
    mean (those named, and with 'the other' every object of the scene)."""
    low = text.lower()
    if "not" not in low and "know" not in low and "remember" not in low:
        return
    m = re.search(_DOUBTED40R, text, _F)
    if m is None:
        return
    said = [r.id for it in _names(text, lexicon) for r in it.refs if r.kind == "object"]
    if re.search(r"\bother\b", text, _F):
        said += [o.id for o in lexicon.scene.objects]
    objs = list(dict.fromkeys(said))
    if not objs:
        return
    raise GroundingError(
        f"{m['doubt']!r} doubts the correction {m['mark']!r}: it could mean "
        f"{' or '.join(objs)}; say which"
    )


# refusals asked of the text before it is read (offline._parse, after the session-39 ones)
REFUSE40R: tuple[Callable[[str, Lexicon], None], ...] = (one_of_them40r, doubted_correction40r)
# checks of the whole instruction's reading (offline.parse_instruction, after remark_said39s)
CHECK40R: tuple[Callable[[str, Node, Lexicon], None], ...] = ()
