"""The grounder's rules of session 56, engineer 12 (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import (
    _F,
    _ids,
    _objects_only,
    _only_person,
    _reading,
    _surface_only,
)
from hltl.grounding._rewrites52 import _cut52
from hltl.grounding.lexicon import PRONOUN_SEX, VERBS, Lexicon, name_sexes
from hltl.grounding.tree import Node

# -- session 56 (engineer 12): the open wrong reading of session 55 (12c), then blind54's refusals
# of politeness and fillers, wants and needs, pronouns and ellipsis and lower case, each read as a
# family.

# -- wrong readings --------------------------------------------------------------------------------

# -- a want said for a later time, run on into a request ("bob wants the apple later give it him",
# "Bob needs the apple later, pass it over."; 12c): 'later' after a comma or a sentence's end is
# read as 'then' (the order of two tasks), so the want was read as a handover now. The want's time
# is the task's: refused as session 20 refuses a time that puts the task off
_WANT_LATER56 = re.compile(
    r"\b(?:wants?|needs?|wanted|needed|would like|['\u2019]d like|would love|['\u2019]d love|"
    r"could use|could do with|(?:is|['\u2019]s) after|(?:is|['\u2019]s) wanting|fancies)"
    r"(?: (?!(?:for|and|but|so|then|to|or)\b)[a-z'\u2019-]+){1,4}?"
    r" (?P<said>later(?: on)?|tomorrow|tonight|this (?:evening|afternoon)|next week|in a (?:bit|"
    r"while|minute|min|mo|sec|second|tick|jiffy)|after (?:lunch|dinner|breakfast|tea|school|"
    r"work))\b(?!\s+than\b)",
    _F,
)
_WANT_LATER_WORDS56 = (
    *("later", "tomorrow", "tonight", "this evening", "this afternoon", "next week", "in a bit"),
    *("in a while", "in a minute", "in a min", "in a mo", "in a sec", "in a tick", "in a jiffy"),
    *("after lunch", "after dinner", "after breakfast", "after tea", "after school", "after work"),
)


def _want_later56(text: str, lexicon: Lexicon) -> None:
    """Session 56: 'P wants the X later …' refused: the want's time puts the task off (above)."""
    low = text.lower()
    if not any(w in low for w in _WANT_LATER_WORDS56):
        return
    m = _WANT_LATER56.search(text)
    if m is None:
        return
    raise GroundingError(
        f"{m['said']!r} puts the task off: the cell acts now, so say the request when it is to "
        "be done"
    )


# -- politeness and fillers ------------------------------------------------------------------------

# -- 'Oh go on,' / 'Come on then,' opening the text before a courtesy ("Oh go on, if you'd be so
# kind, pop the blue mug down …"): urges, asks nothing; taken off (the courtesy frames read 'If
# you'd be so kind, …' opening the text, not after another opener)
_GO_ON56 = re.compile(
    r"^(?P<w>(?:(?:oh|ah|aw|aww|ok|okay|right|look),? )?(?:go on|come on)(?:,? then)?(?:,? "
    r"(?:love|dear|pet|mate|duck|pal))?\s*,\s*)(?=if you(?:['\u2019]d| would| could)? be "
    r"(?:so|ever so|that) (?:kind|good|sweet|lovely)\b)",
    _F,
)


def _go_on56(text: str, lexicon: Lexicon) -> str:
    """Session 56: an opening 'Oh go on,' before a courtesy taken off (above)."""
    low = text.lower()
    if "go on" not in low and "come on" not in low:
        return text
    m = _GO_ON56.search(text)
    if m is None:
        return text
    return _cut52(text, m.start("w"), m.end("w"), "", lexicon)


# -- 'If it isn't too much of a faff,' ("… too much of a bother / hassle / palaver"): said 'too
# much trouble', as the courtesy frames know it
_FAFF56 = re.compile(
    r"\b(?P<w>too much (?:of a |of an )?(?:faff|bother|hassle|palaver|pain|nuisance|chore|"
    r"imposition|drag|kerfuffle|ballache|headache|fuss)(?: for you)?)(?=\s*,)",
    _F,
)


def _faff56(text: str, lexicon: Lexicon) -> str:
    """Session 56: 'too much of a faff' said 'too much trouble' (above)."""
    if "too much" not in text.lower():
        return text
    m = _FAFF56.search(text)
    if m is None or m["w"].lower() == "too much bother":
        return text
    return _cut52(text, m.start("w"), m.end("w"), "too much trouble", lexicon)


# -- 'me again' after a greeting or an apology ("Hello, hello, sorry, me again, the bottle for
# Person B please", "Hi, it's only me again, …", "Sorry, me again, …"): who is speaking, asks
# nothing; taken off (the 'me' was taken for a person to hand to)
_AGAIN56 = re.compile(
    r"^(?P<o>(?:(?:hello|hi|hiya|hey|sorry|so sorry|morning|evening|afternoon|excuse me|oh|um|er|"
    r"erm|right|ok|okay|yes|hello again|hi again)\s*[,.!]\s*)*)(?P<w>(?:(?:it['\u2019]s|its|"
    r"it is) )?(?:only |just )?me again"
    r"(?:,? sorry)?\s*[,.!-]\s*)(?=\S)",
    _F,
)


def _again56(text: str, lexicon: Lexicon) -> str:
    """Session 56: 'me again,' at or near the start taken off (above)."""
    if "me again" not in text.lower():
        return text
    m = _AGAIN56.search(text)
    if m is None:
        return text
    return _cut52(text, m.start("w"), m.end("w"), "", lexicon)


# -- 'when it suits (you)' closing a request ("would the apple go across to Person B when it
# suits", "…, whenever it suits you"): the hearer's time, said 'when you can' (read); 'it' was
# taken for a thing of the scene
_SUITS56 = re.compile(
    r"\b(?P<w>(?:when|whenever) it(?:['\u2019]s| is)? (?:suits(?: you)?|convenient(?: for you)?))"
    r"(?=\s*[.!?]*\s*$)",
    _F,
)


def _suits56(text: str, lexicon: Lexicon) -> str:
    """Session 56: a closing 'when it suits' said 'when you can' (above)."""
    low = text.lower()
    if "suits" not in low and "convenient" not in low:
        return text
    m = _SUITS56.search(text)
    if m is None:
        return text
    return _cut52(text, m.start("w"), m.end("w"), "when you can", lexicon)


# -- 'one small favour:' after an opener and a comma ("Sukriya, and while you're at it, one small
# favour: the chips to Person A …"): session 55's _favour55 takes it off at the start only
_FAVOUR_AFTER56 = re.compile(
    r",\s*(?P<w>(?:one|a|just one)? ?(?:(?:teeny|tiny|quick|small|little|wee|cheeky|minor|"
    r"last|more) )?(?:(?:little|tiny|teeny|wee) )?favou?r(?: to ask)?(?: (?:for|of) you)?"
    r"\s*(?::|\s[-\u2013\u2014])\s*)",
    _F,
)


def _favour_after56(text: str, lexicon: Lexicon) -> str:
    """Session 56: ', one small favour:' taken off (above)."""
    low = text.lower()
    if "favour" not in low and "favor" not in low:
        return text
    m = _FAVOUR_AFTER56.search(text)
    if m is None:
        return text
    return _cut52(text, m.start("w"), m.end("w"), "", lexicon)


# -- 'over to P with it' after a want ("Tom needs the packing tape, over to the driver with it
# please", "Jess needs the torch, over to her with it"): said 'take it over to P' ('Over to P with
# the X' opening the text is session 30r's and 53s's)
_WITH_IT56 = re.compile(
    r"\b(?:wants|needs|would like|['\u2019]d like|could use|could do with|(?:is|['\u2019]s) after)"
    r" (?:the|a|an|his|her|their|some) [a-z]+(?: [a-z]+){0,2}?,\s*(?P<d>over|across|round|along)"
    r" to (?P<p>(?:the |mr |mrs |ms |dr |miss |person )?[a-z]+) with (?P<x>it|them)\b"
    # only a courtesy after it (12c: "…, over to the driver with it please, I handed it over this
    # morning." was read)
    r"(?=(?:\s*,?\s*(?:please|pls|ta|cheers|thanks|thank you))?\s*[.!]*\s*$)",
    _F,
)
_WITH_IT_WORDS56 = ("over to", "across to", "round to", "along to")


def _with_it56(text: str, lexicon: Lexicon) -> str:
    """Session 56: 'over to P with it' said 'take it over to P' (above)."""
    low = text.lower()
    if (" with it" not in low and " with them" not in low) or not any(
        w in low for w in _WITH_IT_WORDS56
    ):
        return text
    m = _WITH_IT56.search(text)
    if m is None or not (m["p"].lower() in ("him", "her") or _only_person(m["p"], lexicon)):
        return text
    put = f"take {m['x']} {m['d'].lower()} to {m['p']}"
    return _cut52(text, m.start("d"), m.end(), put, lexicon)


# -- 'Do me a kindness and …' ("… a good turn / a solid / a service"): said 'Do me a favour and'
_KINDNESS56 = re.compile(
    r"\bdo (?:me|us) a (?P<w>kindness|good turn|solid|service|kind turn|great service)"
    r"(?=,? and\b)",
    _F,
)


def _kindness56(text: str, lexicon: Lexicon) -> str:
    """Session 56: 'do me a kindness and' said 'do me a favour and' (above)."""
    if "do me a" not in text.lower() and "do us a" not in text.lower():
        return text
    m = _KINDNESS56.search(text)
    if m is None:
        return text
    return _cut52(text, m.start("w"), m.end("w"), "favour", lexicon)


# -- how pleased a person would be, closing the text ("…, Mrs Ortiz would be chuffed to bits",
# "…, Lena will be delighted", "…, he'd be over the moon"): says nothing of the task; taken off
_CHUFFED56 = re.compile(
    r",\s*(?:and |oh,? )?(?P<p>(?:[a-z]+ ){0,2}[a-z]+?)(?: would|['\u2019]d| will|['\u2019]ll)"
    r" be (?:so |ever so |really |very |just |absolutely )?(?:chuffed|delighted|thrilled|"
    r"made up|over the moon|tickled pink|tickled|stoked|ecstatic)"
    r"(?: to bits| to pieces)?\s*[.!]*\s*$",
    _F,
)
_CHUFFED_WORDS56 = (
    *("chuffed", "delighted", "thrilled", "made up", "over the moon", "tickled", "stoked"),
    "ecstatic",
)


def _chuffed56(text: str, lexicon: Lexicon) -> str:
    """Session 56: a closing ', P would be chuffed to bits' taken off (above)."""
    low = text.lower()
    if not any(w in low for w in _CHUFFED_WORDS56):
        return text
    m = _CHUFFED56.search(text)
    if m is None:
        return text
    p = m["p"].lower()
    if p not in ("he", "she", "they", "we") and not _only_person(m["p"], lexicon):
        return text
    return _cut52(text, m.start(), m.end(), "", lexicon)


# -- 'could you run them over' after one person's want ("Bob's been waiting ages for the crisps,
# could you run them over, cheers", "Lena wants the salt, would you take it across?"): over to the
# one person the want names, said 'over to P'
_RUN_OVER56 = re.compile(
    r",\s*(?:(?:so|and) )?(?:(?:could|would|can|will) you (?:please |kindly |just )?)(?:run|take|"
    r"bring|pass|carry|pop|nip|whizz|zip) (?:them|it) (?:over|across|round)(?P<w>)(?=\s*(?:[.!?]|"
    r",\s*(?:please|cheers|thanks|ta|ta very much|much appreciated)\b|$))",
    _F,
)
_RUN_WANT56 = re.compile(
    r"\b(?:wants|needs|would like|['\u2019]d like|could use|could do with|(?:is|['\u2019]s) after|"
    r"(?:has been|['\u2019]s been|is|['\u2019]s) waiting (?:ages |an age |so long )?for)\b",
    _F,
)
_RUN_OVER_WORDS56 = (" over", " across", " round")


def _run_over56(text: str, lexicon: Lexicon) -> str:
    """Session 56: "P's been waiting for the X, could you run them over" said '… over to P'
    (above)."""
    low = text.lower()
    if " you " not in low or not any(w in low for w in _RUN_OVER_WORDS56):
        return text
    m = _RUN_OVER56.search(text)
    if m is None:
        return text
    before = text[: m.start()]
    people = _ids(before, lexicon, "human")
    if len(people) != 1 or len(_RUN_WANT56.findall(before)) != 1:
        return text
    name = next(h.name for h in lexicon.scene.humans if h.id in people)
    return _cut52(text, m.start("w"), m.end("w"), f" to {name}", lexicon)


# -- why the thing is to be moved, then a request with 'it' ("…, but the stapler's cluttering
# things up, would you drop it into the box"): the thing named in the 'it', the reason taken off
_REASON_IT56 = re.compile(
    r"(?P<x>\bthe [a-z]+(?: [a-z]+)?)(?:['\u2019]s| is) (?:cluttering|getting in|in the way|"
    r"taking up|blocking|hogging|in my way|underfoot|messing up)[a-z ]{0,30}?,\s*(?P<q>(?:would|"
    r"could|can|will) you (?:please |kindly |just )?)(?P<v>drop|put|pop|stick|move|place|set|"
    r"stow|shove|stash) it\b",
    _F,
)

# what may follow the request: its place, then a courtesy at most (my probe: "…, would you drop it
# into the box, I dropped it in an hour ago." was read)
_COURTESY_END56 = re.compile(
    r"[^,.;!?]*(?:,\s*(?:please|pls|ta|cheers|thanks|thank you|ta very much|much appreciated|"
    r"cheers then|ta muchly))?\s*[.!?]*\s*$",
    _F,
)


def _reason_it56(text: str, lexicon: Lexicon) -> str:
    """Session 56: "the stapler's cluttering things up, would you drop it …" said 'would you drop
    the stapler …' (above)."""
    low = text.lower()
    if " it" not in low or not any(
        w in low for w in ("clutter", "in the way", "taking up", "blocking", "hogging", "underfoot")
    ):
        return text
    m = _REASON_IT56.search(text)
    if (
        m is None
        or not _objects_only(m["x"], lexicon)
        or not _COURTESY_END56.match(text[m.end() :])
    ):
        return text
    return _cut52(text, m.start("x"), m.end(), f"{m['q']}{m['v']} {m['x']}", lexicon)


# -- wants and needs -------------------------------------------------------------------------------

# -- 'P reckons the X would hit the spot' ("…, while Bob reckons the bottle would hit the spot",
# "Lena reckons the salt would go down a treat"): what P would like, said 'P would like the X'
_RECKONS56 = re.compile(
    r"\b(?P<p>(?:mr |mrs |ms |dr |miss |person |the )?[a-z]+) (?:reckons|thinks|"
    r"says|feels)(?: that)? (?P<x>(?:the|a|an|some) [a-z]+(?: [a-z]+){0,2}?) (?:would|['\u2019]d|"
    r"will|['\u2019]ll) (?:hit the spot|go down (?:a treat|well|nicely)|be just the "
    r"(?:thing|ticket))(?: (?:for|with) (?:him|her|them))?(?=\s*(?:[,.;!]|$))",
    _F,
)
_RECKONS_WORDS56 = ("hit the spot", "go down a treat", "go down well", "go down nicely", "just the")


def _reckons56(text: str, lexicon: Lexicon) -> str:
    """Session 56: 'P reckons the X would hit the spot' said 'P would like the X' (above)."""
    low = text.lower()
    if not any(w in low for w in _RECKONS_WORDS56):
        return text
    m = _RECKONS56.search(text)
    if m is None or not _objects_only(m["x"], lexicon):
        return text
    p = m["p"]
    if p.lower() not in ("he", "she", "they") and not _only_person(p, lexicon):
        return text
    return _cut52(text, m.start(), m.end(), f"{p} would like {m['x']}", lexicon)


# -- what the wanted thing is for, said with a pronoun ("the doctor could do with the spoon to stir
# hers", "Bob needs the knife to cut his", "Jess wants the cloth to wipe hers down"): the purpose
# names nothing of the scene; taken off (with 'her tea' it was read)
_STIR56 = re.compile(
    r"(?<=[a-z])(?P<w> to (?P<v>[a-z]+) (?:hers|his|theirs)(?: (?:up|down|out|with))?)"
    r"(?=\s*(?:[,.;!?]|$|and\b|but\b|please\b))",
    _F,
)


def _stir56(text: str, lexicon: Lexicon) -> str:
    """Session 56: a closing 'to stir hers' after the wanted thing taken off (above)."""
    low = text.lower()
    if " hers" not in low and " his" not in low and " theirs" not in low:
        return text
    m = _STIR56.search(text)
    if (
        m is None
        or m["v"].lower() in VERBS
        or _ids(text[: m.start()].split(",")[-1], lexicon) == set()
    ):
        return text
    return _cut52(text, m.start("w"), m.end("w"), "", lexicon)


# -- a meeting said by its hour ("Priya needs the notepad for her one o'clock", "… for his 3pm"):
# said 'for her meeting' (the hour was read as a time the task waits for)
_OCLOCK56 = re.compile(
    r"\bfor (?P<w>(?:her|his|their|the) (?:(?:one|two|three|four|five|six|seven|eight|nine|ten|"
    r"eleven|twelve|half (?:one|two|three|four|five|six|seven|eight|nine|ten|eleven|twelve)|\d{1,2}"
    r") ?(?:o['\u2019]?clock|o clock)|\d{1,2}(?:[:.]\d\d)? ?(?:am|pm)))"
    r"(?: (?P<m>meeting|appointment|class|lesson|call|interview|session|slot))?"
    r"(?=\s*(?:[,.;!?]|$|and\b))",
    _F,
)
_OCLOCK_WORDS56 = (
    "clock",
    "pm",
    *(f"{d}am" for d in "0123456789"),
    *(f"{d} am" for d in "0123456789"),
)

_AFTER_MEETING56 = re.compile(
    r"\b(?:after|afterwards|later|then|once|when|until|till|before)\b", _F
)


def _oclock56(text: str, lexicon: Lexicon) -> str:
    """Session 56: 'for her one o'clock' said 'for her meeting' (above)."""
    low = text.lower()
    if not any(w in low for w in _OCLOCK_WORDS56):
        return text
    m = _OCLOCK56.search(text)
    if m is None or _AFTER_MEETING56.search(text, m.end()):
        return text  # 12c: '…, bring it after that' waits on the meeting
    owner = m["w"].split()[0]
    return _cut52(text, m.start("w"), m.end(), f"{owner} {m['m'] or 'meeting'}", lexicon)


# -- 'P's lost without the X' ("Mia's lost without the barcode scanner today", "Lena would be lost
# without the tongs"): what P needs, said 'P needs the X'
_LOST_WITHOUT56 = re.compile(
    r"\b(?P<p>(?:mr |mrs |ms |dr |miss |person |the )?[a-z]+)(?:['\u2019]s| is|['\u2019]d be| would"
    r" be|['\u2019]ll be| will be|['\u2019]s been) (?:completely |totally |utterly |a bit |"
    r"rather |quite |so |just )?lost without (?P<x>(?:the|a|an|her|his|their) [a-z]+(?: "
    r"[a-z]+){0,2}?)(?=\s*(?:[,.;!]|$|today\b|now\b|at the moment\b|and\b|so\b|please\b))",
    _F,
)


def _lost_without56(text: str, lexicon: Lexicon) -> str:
    """Session 56: "P's lost without the X" said 'P needs the X' (above)."""
    if "lost without" not in text.lower():
        return text
    m = _LOST_WITHOUT56.search(text)
    if m is None or not _only_person(m["p"], lexicon) or not _objects_only(m["x"], lexicon):
        return text
    return _cut52(text, m.start(), m.end(), f"{m['p']} needs {m['x']}", lexicon)


# -- 'P's hands are raw so he wants the X' ("Tom's hands are raw so he wants the work gloves",
# "Lena's feet are killing her so she'd like …"): the he / she is the one whose hands they are,
# said 'P wants the X' (the reason dropped; not when a first name says the other sex)
_BODY56 = (
    r"hands|feet|back|head|eyes|fingers|toes|knees|legs|arms|neck|shoulders|throat|lips|nose|ears|"
    r"hand|foot|knee|leg|arm|shoulder|wrist|wrists|ankle|ankles|tummy|stomach"
)
_BODY_SO56 = re.compile(
    rf"\b(?P<p>(?:mr |mrs |ms |dr |miss |person |the )?[a-z]+)(?:['\u2019]s) (?:poor )?"
    rf"(?:{_BODY56}) (?:is|are|['\u2019]re|feel|feels)(?: [a-z'\u2019]+){{1,3}}? so "
    r"(?P<pr>he|she|they) (?P<v>wants|needs|would like|['\u2019]d like|could use|could do with|"
    r"(?:is|['\u2019]s) after)\b",
    _F,
)


def _body_so56(text: str, lexicon: Lexicon) -> str:
    """Session 56: "P's hands are raw so he wants the X" said 'P wants the X' (above)."""
    low = text.lower()
    if " so he " not in low and " so she " not in low and " so they " not in low:
        return text
    m = _BODY_SO56.search(text)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    sex = name_sexes().get(m["p"].split()[-1].lower())
    said = PRONOUN_SEX.get(m["pr"].lower())
    if sex is not None and said is not None and sex != said:
        return text
    return _cut52(text, m.start(), m.end(), f"{m['p']} {m['v']}", lexicon)


# -- a closing remark of what the person finds the food or drink ("Mr Novak is wanting the salt
# shaker, he finds the soup a bit bland", "…, she finds the tea too strong"): names nothing of the
# scene; taken off
_FINDS56 = re.compile(
    r",\s*(?:(?:as|because|since) )?(?:he|she|they) (?:finds|find|found|thinks|reckons) (?P<x>"
    r"(?:the|his|her|their|this|that) [a-z]+(?: [a-z]+)?) (?:(?:a bit|a little|rather|too|far "
    r"too|way too|very|quite|so|really|a touch) )?[a-z]+\s*[.!]*\s*$",
    _F,
)


def _finds56(text: str, lexicon: Lexicon) -> str:
    """Session 56: a closing ', he finds the soup a bit bland' taken off (above)."""
    low = text.lower()
    if "find" not in low and "found" not in low:
        return text
    m = _FINDS56.search(text)
    if m is None or _ids(m["x"], lexicon):
        return text
    return _cut52(text, m.start(), m.end(), "", lexicon)


# -- pronouns and ellipsis -------------------------------------------------------------------------

# -- 'P is the one with a craving for X' ("…, while Person B is the one with a craving for the
# apple"): said 'P has a craving for X' ('the one who wants / needs' is older rules')
_THE_ONE56 = re.compile(
    r"\b(?P<p>(?:mr |mrs |ms |dr |miss |person |the )?[a-z]+)(?: is|['\u2019]s) the one "
    r"(?:with|who has|who['\u2019]s got|who has got) (?P<a>a (?:real |bit of a |serious |"
    r"massive )?(?:craving|hankering|yen|longing|hunger|thirst)) ",
    _F,
)


def _the_one56(text: str, lexicon: Lexicon) -> str:
    """Session 56: 'P is the one with a craving for X' said 'P has a craving for X' (above)."""
    if "the one " not in text.lower():
        return text
    m = _THE_ONE56.search(text)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    return _cut52(text, m.end("p"), m.end(), f" has {m['a']} ", lexicon)


# -- a name asked, then he / she ("Person B? He's the sound mixer and he's after the bottle, so …",
# "Lena? She wants the salt"): said with the name ("Person B is the sound mixer …"), not when a
# first name says the other sex
_NAME_Q56 = re.compile(
    r"^(?P<p>(?:mr |mrs |ms |dr |miss |person )?[a-z]+)\?\s+(?P<pr>he|she)(?P<s>['\u2019]s\b)?",
    _F,
)


def _name_q56(text: str, lexicon: Lexicon) -> str:
    """Session 56: 'P? He's …' said 'P is …' (above)."""
    if "?" not in text:
        return text
    m = _NAME_Q56.search(text)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    sex = name_sexes().get(m["p"].split()[-1].lower())
    if sex is not None and sex != PRONOUN_SEX[m["pr"].lower()]:
        return text
    return _cut52(text, m.end("p"), m.end(), " is" if m["s"] else "", lexicon)


# -- who paid for it, closing the text ("The apple's meant for Person A, and so are the chips, she
# paid for them", "…, he bought it"): says nothing more of the task; taken off
_PAID56 = re.compile(
    r",\s*(?:(?:as|because|since) )?(?:he|she|they)(?:['\u2019]s| has| have|['\u2019]ve)? (?:paid "
    r"for|bought|ordered|chose|picked) (?:it|them|those|that|both)(?: (?:himself|herself|"
    r"themselves|already|earlier|this morning))?\s*[.!]*\s*$",
    _F,
)
_PAID_WORDS56 = ("paid for", "bought", "ordered", "chose", "picked")


def _paid56(text: str, lexicon: Lexicon) -> str:
    """Session 56: a closing ', she paid for them' taken off (above)."""
    low = text.lower()
    if not any(w in low for w in _PAID_WORDS56):
        return text
    m = _PAID56.search(text)
    if m is None:
        return text
    return _cut52(text, m.start(), m.end(), "", lexicon)


# -- 'P's the R; the X are his, so …' ("Person B's the puppet maker; the chips are his, so take them
# across to him", "Tom's got a long drive ahead; the gloves are his, so …"): the his is the one
# person the text names; said "The X are P's, so …" (not when a first name says the other sex)
_ARE_HIS56 = re.compile(
    r"^(?P<p>(?:mr |mrs |ms |dr |miss |person )?[a-z]+)(?P<r>(?:['\u2019]s| is) (?:the|a|an|our) "
    r"[a-z][a-z -]{0,30}?|(?:['\u2019]s got| has got| has) (?:a|an|the) [a-z][a-z -]{0,30}?)\s*"
    r"(?:[;.]|(?<=[a-z]),)\s*(?P<x>the [a-z]+(?: [a-z]+){0,2}?) (?P<b>is|are) (?P<pr>his|hers),\s*"
    r"(?=so\b)",
    _F,
)


def _are_his56(text: str, lexicon: Lexicon) -> str:
    """Session 56: "P's the R; the X are his, so …" said "The X are P's, so …" (above)."""
    low = text.lower()
    if " his," not in low and " hers," not in low:
        return text
    m = _ARE_HIS56.search(text)
    if m is None or not _only_person(m["p"], lexicon) or not _objects_only(m["x"], lexicon):
        return text
    if _ids(m["r"], lexicon, "object") or not _ids(m["r"], lexicon, "human") <= _ids(
        m["p"], lexicon
    ):
        return text  # what P is or has names no thing of the scene and no one else
    sex = name_sexes().get(m["p"].split()[-1].lower())
    if sex is not None and sex != PRONOUN_SEX[m["pr"].lower()]:
        return text
    x = m["x"][0].upper() + m["x"][1:]
    return _cut52(text, 0, m.end(), f"{x} {m['b']} {m['p']}'s, ", lexicon)


# -- 'P and Q were both …; give her …' ("Emma and Dana were both over by the sink; give her the
# sponge"): 'both' is the two people, not two things (it was asked which two objects); taken off,
# so the her is refused naming both — only where the text is refused without it too, 'both' says
# where they are and a sentence asks to hand 'him / her' something ('both on about / after the X'
# is session 51's _both_on51)
_BOTH_PEOPLE56 = re.compile(
    r"\b(?P<p>(?:mr |mrs |ms |dr |miss |person )?[a-z]+) and (?P<q>(?:mr |mrs |ms |dr |miss |"
    r"person )?[a-z]+) (?:were|are|['\u2019]re|was)(?P<w> both)(?= (?:over|by|at|in|near|next to|"
    r"round|around|here|there|sat|standing|sitting|waiting)\b)[^.;!?]*[.;!?]\s*(?:give|pass|hand|"
    r"bring|take) (?:him|her)\b",
    _F,
)


def _both_people56(text: str, lexicon: Lexicon) -> str:
    """Session 56: 'P and Q were both' said 'P and Q were' (above)."""
    if " both" not in text.lower():
        return text
    m = _BOTH_PEOPLE56.search(text)
    if m is None or not _only_person(m["p"], lexicon) or not _only_person(m["q"], lexicon):
        return text
    out = f"{text[: m.start('w')]}{text[m.end('w') :]}"
    # only the refusal's words change: where the text without 'both' reads, it is left as it is
    return out if _reading(out, lexicon) is None else text


# -- 'P has no X. Give him the red one.' ("Sam, the intern, has no pen. Give him the red one."):
# the sentence after says what to do about it, as "P has no X, give him …" (read) does
_HAS_NONE56 = re.compile(
    r"^(?P<p>(?:mr |mrs |ms |dr |miss |person )?[a-z]+(?:, (?:the|our|a|an) [a-z]+(?: [a-z]+)?,)?"
    r" (?:has|has got|['\u2019]s got) no [a-z]+(?: [a-z]+)?)(?P<w>\.\s+)(?=(?:give|pass|hand|"
    r"bring|take) (?:him|her|them) )",
    _F,
)


def _has_none56(text: str, lexicon: Lexicon) -> str:
    """Session 56: 'P has no X. Give him …' said 'P has no X, give him …' (above)."""
    if " no " not in text.lower():
        return text
    m = _HAS_NONE56.search(text)
    if m is None:
        return text
    return _cut52(text, m.start("w"), m.end("w") + 1, f", {text[m.end('w')].lower()}", lexicon)


# -- 'The X, then the Y, onto the Z' ("The small box, then the medium one, onto the belt"): each
# onto the Z in that order, said "The X onto the Z, then the Y"
_THEN_ONTO56 = re.compile(
    r"(?:^|(?<=[.!:;]\s))(?P<x>the [a-z]+(?: [a-z]+){0,2}?),\s*then (?P<y>the [a-z]+(?: [a-z]+)"
    r"{0,2}?),?\s+(?P<t>(?:onto|on to|on|into|in|over to|across to|to) (?:the )?[a-z]+(?: "
    r"[a-z]+)?)(?=\s*(?:[.!]|,\s*(?:please|ta|thanks|cheers)\b|$))",
    _F,
)


def _then_onto56(text: str, lexicon: Lexicon) -> str:
    """Session 56: 'The X, then the Y, onto the Z' said 'The X onto the Z, then the Y' (above)."""
    low = text.lower()
    if ", then " not in low:
        return text
    m = _THEN_ONTO56.search(text)
    if m is None or not _objects_only(m["x"], lexicon):
        return text
    y = m["y"]
    if not (y.lower().endswith(" one") or _objects_only(y, lexicon)):
        return text
    x = m["x"][0].upper() + m["x"][1:] if m.start() == 0 else m["x"]
    return _cut52(text, m.start(), m.end(), f"{x} {m['t']}, then {y}", lexicon)


# -- whose the thing is, said with 'there' after the thing ("That bottle there is Person A's, take
# it across to her"): the 'there' taken off and 'so' said ("That bottle is Person A's, so take it
# …" is read)
_OWNER_SO56 = re.compile(
    r"\b(?:that|this|those|these) [a-z]+(?: [a-z]+)?(?P<w> (?:there|here|over there|right there|"
    r"just there)) (?:is|are) (?P<p>(?:mr |mrs |ms |dr |miss |person )?[a-z]+)['\u2019]s,\s*"
    r"(?P<so>)(?=(?:take|give|pass|bring|carry|hand|run) (?:it|them)\b)",
    _F,
)


def _owner_so56(text: str, lexicon: Lexicon) -> str:
    """Session 56: "that X there is P's, take it to her" said "that X is P's, so take it to her"
    (above)."""
    low = text.lower()
    if "'s," not in low and "\u2019s," not in low:
        return text
    m = _OWNER_SO56.search(text)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    said = f"{text[m.end('w') : m.start('so')]}so "
    return _cut52(text, m.start("w"), m.end("so"), said, lexicon)


# -- a surface named first, then the thing it is for, all in lower case and run on into 'pls'
# ("shelf for the bottle pls somewhere the baby cant grab it", "rack for the lemon please"): said
# 'put the bottle on the shelf …'
_SURFACE_FOR56 = re.compile(
    r"^(?P<s>(?:the )?[a-z]+(?: [a-z]+)?) for (?P<x>the [a-z]+(?: [a-z]+)?) (?=(?:please|pls|plz)"
    r"\b(?!\s+or\b))",
    _F,
)


def _surface_for56(text: str, lexicon: Lexicon) -> str:
    """Session 56: 'shelf for the bottle' opening the text said 'put the bottle on the shelf'
    (above)."""
    if " for the " not in text.lower():
        return text
    m = _SURFACE_FOR56.search(text)
    if m is None or not _surface_only(m["s"], lexicon) or not _objects_only(m["x"], lexicon):
        return text
    s = m["s"].lower()
    s = s if s.startswith("the ") else f"the {s}"
    return _cut52(text, 0, m.end(), f"Put {m['x']} on {s} ", lexicon)


# -- lower case ------------------------------------------------------------------------------------

_WANT_VERB56 = (
    r"(?:wants|needs|would like|['\u2019]d like|could use|could do with|(?:is|['\u2019]s) after|"
    r"(?:is|has been|['\u2019]s been|['\u2019]s) (?:waiting|asking) for)"
)

# -- 'for signing things' ("sam wants the black pen for signing things", "… for writing stuff"):
# the purpose is the -ing, said 'for signing' (read)
_ING_THINGS56 = re.compile(
    r"\bfor [a-z]+ing(?P<w> (?:things|stuff|bits|bits and bobs|and that|and stuff|with))"
    r"(?=\s*(?:[.,;!]|$|and\b|please\b))",
    _F,
)


def _ing_things56(text: str, lexicon: Lexicon) -> str:
    """Session 56: 'for signing things' said 'for signing' (above)."""
    low = text.lower()
    if not any(
        w in low for w in ("ing things", "ing stuff", "ing bits", "ing and that", "ing with")
    ):
        return text
    m = _ING_THINGS56.search(text)
    if m is None:
        return text
    return _cut52(text, m.start("w"), m.end("w"), "", lexicon)


# -- a want with its purpose run on into another person's want without a comma ("lena needs the
# tongs for the salad and mr novak is after the salt shaker"): the comma said (read with it)
_FOR_AND56 = re.compile(
    rf"\b{_WANT_VERB56} (?:the|a|an|his|her|their|some) [a-z]+(?: [a-z]+){{0,2}}? for (?P<y>(?:the|"
    r"a|an|his|her|their|some) [a-z]+(?: [a-z]+)?)(?P<w> )and (?P<q>(?:mr |mrs |ms |dr |miss |"
    rf"person )?[a-z]+) {_WANT_VERB56}\b",
    _F,
)

_TIME_NOUN56 = re.compile(
    r"\b(?:morning|afternoon|evening|night|weekend|week|day|month|year|holiday|holidays|later|"
    r"shift)\b",
    _F,
)


def _for_and56(text: str, lexicon: Lexicon) -> str:
    """Session 56: 'needs the X for the Y and Q wants …': a comma before 'and' (above)."""
    low = text.lower()
    if " for " not in low or " and " not in low:
        return text
    m = _FOR_AND56.search(text)
    if m is None or _ids(m["y"], lexicon) or not _only_person(m["q"], lexicon):
        return text
    if _TIME_NOUN56.search(m["y"]):
        return text  # 'for the morning': when, not what for
    return _cut52(text, m.start("w"), m.end("w"), ", ", lexicon)


# -- a want's verb left out after 'and' ("person a has been waiting for the apple and person b for
# the cup so off you go"): said again ('and person b has been waiting for the cup')
_GAP56 = re.compile(
    r"\b(?P<v>(?:has been|['\u2019]s been|is|['\u2019]s) (?:waiting|asking|crying|hoping) for|"
    r"(?:is|['\u2019]s) after) (?:the|a|an|his|her|their) [a-z]+(?: [a-z]+){0,2}? and (?P<q>(?:mr "
    r"|mrs |ms |dr |miss |person )?[a-z]+) (?P<w>for )?(?=(?:the|a|an|his|her|their) )",
    _F,
)


def _gap56(text: str, lexicon: Lexicon) -> str:
    """Session 56: 'P has been waiting for the X and Q for the Y': the verb said again (above)."""
    low = text.lower()
    if " for " not in low and " after " not in low:
        return text
    m = _GAP56.search(text)
    if m is None or not _only_person(m["q"], lexicon):
        return text
    v = m["v"]
    if m["w"] is None and v.lower().endswith(" for"):
        return text
    start = m.start("w") if m["w"] else m.end()
    return _cut52(text, start, m.end(), f"{v} ", lexicon)


# -- a remark of what the person has on run on in lower case ("can person a have the bottle shes
# got handbell ringing later"): the comma said, as the grammar reads "…, she's got handbell ringing
# later" (only an -ing activity after 'got'; 'it' / 'them' after it stays as it is)
_SHES_GOT56 = re.compile(
    r"\b(?P<x>(?:the|a|an|his|her|their) [a-z]+(?: [a-z]+)?) (?P<s>shes|she['\u2019]s|hes|"
    r"he['\u2019]s|theyve|they['\u2019]ve) got (?!(?:it|them|that|those|one|some|the|a|an|his|her|"
    r"their)\b)(?:[a-z]+ ){0,2}[a-z]+ing\b",
    _F,
)


def _shes_got56(text: str, lexicon: Lexicon) -> str:
    """Session 56: '… the bottle shes got handbell ringing later': a comma after the thing
    (above)."""
    low = text.lower()
    if " got " not in low or text != low:
        return text
    m = _SHES_GOT56.search(text)
    if m is None or not _objects_only(m["x"], lexicon):
        return text
    said = {"shes": "she's", "hes": "he's", "theyve": "they've"}.get(m["s"], m["s"])
    out = f"{text[: m.end('x')]}, {said}{text[m.end('s') :]}"
    return out if _reading(out, lexicon) is not None else text


# -- what the thing is for, run on before another person's want ("jess needs the torch to see
# under there and kofi wants the screws"): session 52's _to_look52 takes it off closing the text;
# taken off before 'and Q wants' too (naming nothing of the scene)
_TO_LOOK56 = re.compile(
    r"(?P<w> (?:so as |in order )?to (?:look|peer|peek|see|check|poke about|poke around|rummage|"
    r"search|root about|root around) (?:at|behind|under|underneath|beneath|in|inside|into|round|"
    r"around|for|through|up|down|over) (?P<x>there|here|[a-z]+(?: [a-z]+){0,2}?)),? (?=and "
    rf"(?P<q>(?:mr |mrs |ms |dr |miss |person )?[a-z]+) {_WANT_VERB56}\b)",
    _F,
)


def _to_look56(text: str, lexicon: Lexicon) -> str:
    """Session 56: 'needs the torch to see under there and Q wants …': the purpose taken off
    (above)."""
    low = text.lower()
    if " to " not in low or " and " not in low:
        return text
    m = _TO_LOOK56.search(text)
    if m is None or _ids(m["x"], lexicon) or not _only_person(m["q"], lexicon):
        return text
    return _cut52(text, m.start("w"), m.end("w"), "", lexicon)


# -- why the thing is to be moved, said before the request with 'so' ("those crisps keep getting
# knocked over so stick them up on the shelf"): the reason taken off, the thing named in the 'them'
_KEEPS_SO56 = re.compile(
    r"^(?P<x>(?:those|these|the|that|this) [a-z]+(?: [a-z]+)?) (?:keeps?|kept) (?:getting|being|"
    r"falling|going|rolling|tipping) [a-z ]{0,30}? so (?P<v>stick|put|pop|place|move|set|shove|"
    r"stash|stow) (?P<p>them|it) ",
    _F,
)


def _keeps_so56(text: str, lexicon: Lexicon) -> str:
    """Session 56: 'the X keep getting knocked over so stick them …' said 'stick the X …'
    (above)."""
    low = text.lower()
    if " so " not in low or "keep" not in low:
        return text
    m = _KEEPS_SO56.search(text)
    if m is None or not _objects_only(m["x"], lexicon):
        return text
    x = "the " + m["x"].split(" ", 1)[1]
    return _cut52(text, 0, m.end(), f"{m['v']} {x} ", lexicon)


# -- 'out of harms way' with its apostrophe dropped (lower case): said "out of harm's way"
_HARMS56 = re.compile(r"\bout of (?P<w>harms) way\b", _F)


def _harms56(text: str, lexicon: Lexicon) -> str:
    """Session 56: 'out of harms way' said "out of harm's way" (above)."""
    if "harms way" not in text.lower():
        return text
    m = _HARMS56.search(text)
    if m is None:
        return text
    return f"{text[: m.start('w')]}harm's{text[m.end('w') :]}"


# the normaliser's first rewrites (wired into normalise._STEPS19, before the session-56 ones)
_STEPS56_FIRST: tuple[Callable[[str, Lexicon], str], ...] = (
    _go_on56,
    _faff56,
    _again56,
    _suits56,
    _favour_after56,
    _with_it56,
    _kindness56,
    _chuffed56,
    _run_over56,
    _reason_it56,
    _reckons56,
    _stir56,
    _oclock56,
    _lost_without56,
    _body_so56,
    _finds56,
    _the_one56,
    _name_q56,
    _paid56,
    _are_his56,
    _both_people56,
    _has_none56,
    _then_onto56,
    _owner_so56,
    _surface_for56,
    _harms56,
    _ing_things56,
    _for_and56,
    _gap56,
    _shes_got56,
    _to_look56,
    _keeps_so56,
)
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-56 ones)
_STEPS56: tuple[Callable[[str, Lexicon], str], ...] = ()
# refusals asked of the text before it is read (offline._parse, after the session-56 ones)
REFUSE56: tuple[Callable[[str, Lexicon], None], ...] = (_want_later56,)
# checks of the whole instruction's reading (offline.parse_instruction, after the session-56 ones)
CHECK56: tuple[Callable[[str, Node, Lexicon], None], ...] = ()
