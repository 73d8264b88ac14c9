"""The grounder's rules of session 54, engineer 12 (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _ids, _names, _only_person
from hltl.grounding._rewrites43s import _placed_aside43s
from hltl.grounding._rewrites44 import _agrees44
from hltl.grounding._rewrites52 import _cut52
from hltl.grounding.lexicon import Lexicon
from hltl.grounding.tree import Node

# -- session 54 (engineer 12): the open wrong readings of session 53 (12c's fuzz), then blind52's
# refusals of politeness and fillers, wants and needs, pronouns and ellipsis, lower case and
# questions, each read as a family.

# -- wrong readings --------------------------------------------------------------------------------

# -- a request said to have been made on an earlier day ("Bob asked for the apple yesterday.",
# "Alice asked for the cup last night, poor thing."): session 19's words took the time off as how
# long ago he asked (read apple>B), while "Bob wanted / needed the apple yesterday." are refused: a
# want of another day may be over. Refused, unless what follows points back at it and asks for it
# now ('…, so take it to him.', '… and he still wants it.': main's reading stands)
_DAYS_AGO54 = re.compile(
    r"\b(?P<said>(?:asked|was asking|were asking|requested|begged)(?: (?:me|you|us))? for "
    r"[^.;!?,]*? (?:yesterday|last night|last week|the other day|(?:two|three|four|five|a few|"
    r"several|\d+) days ago|a week ago|over the weekend|at the weekend)(?: (?:morning|afternoon|"
    r"evening))?)(?=\s*(?:[.,;!?]|$)|\s+(?:and|but|so)\b)",
    _F,
)
# what, after the time, points back at the thing asked for ('it', 'them', 'still' …)
_BACK54 = re.compile(r"\b(?:it|them|that|those|this|one|ones|still|again|now)\b", _F)
_DAYS54 = ("yesterday", "last night", "last week", "other day", "days ago", "week ago", "weekend")


def _days_ago54(text: str, lexicon: Lexicon) -> None:
    """Session 54: 'P asked for X yesterday' refused unless the rest asks for it again (above)."""
    low = text.lower()
    if not any(w in low for w in _DAYS54):
        return
    m = _DAYS_AGO54.search(text)
    if m is None or _BACK54.search(text, m.end()):
        return
    raise GroundingError(
        f"{m['said']!r} says what was asked for on another day: the want may be over; say 'give "
        "…' to have it handed over now"
    )


# the words beside the names of things in a list of them ('the apple and his crisps')
_LIST_WORDS54 = frozenset(
    (
        "the",
        "a",
        "an",
        "his",
        "her",
        "their",
        "its",
        "my",
        "our",
        "your",
        "some",
        "and",
        "both",
        "two",
        "three",
        "those",
        "these",
        "that",
        "this",
        "one",
        "of",
        ",",
    )
)


def _things_only54(words: str, lexicon: Lexicon) -> bool:
    """Whether ``words`` names objects of the scene and says nothing else ('the apple and the
    crisps', 'a mug'; not 'her eye on the red mug')."""
    names = _names(words, lexicon)
    if not names or any(r.kind != "object" for it in names for r in it.refs):
        return False
    rest = words.lower()
    for it in names:
        rest = rest.replace(it.text.lower(), " ", 1)
    return all(w in _LIST_WORDS54 for w in rest.replace(",", " , ").split())


# -- a past holding with a reason or time after it ("Bob had the apple since his match ended.",
# "Lena had the tongs because she was cooking.", "Bob got the apple because he was hungry.", "Bob
# had the apple first."): the grammar read the clause as a handover (apple>B), while "Bob had the
# apple." alone is refused as what was (session 32's _state_only32s, a sentence of a person and
# the objects only). Refused the same: a person, 'had' / 'has had' / "'s had" / 'got', objects
# only, then 'since' / 'because' / 'as' / 'first' / 'when' …
_HAD_WHY54 = re.compile(
    r"(?:^|[.;!?,]\s*)(?:(?:and|but|so|well|oh),?\s+)?(?P<said>(?P<p>[^.;!?,]+?)(?:\s+(?:had|"
    r"has had|got)|'s had)\s+(?P<x>(?!to\b)[^.;!?,]+?))\s+(?:ever since|since|because|'cause|cause|"
    r"cos|coz|as|when|first|after|till|until|once)\b",
    _F,
)
_WHY54 = (
    " since",
    "because",
    "cause",
    " cos",
    " coz",
    " as ",
    " when",
    " first",
    " after",
    " till",
    " until",
    " once",
)


def _had_why54(text: str, lexicon: Lexicon) -> None:
    """Session 54: a past holding with a reason or time after it refused (above)."""
    low = text.lower()
    if ("had " not in low and "got " not in low) or not any(w in low for w in _WHY54):
        return
    for m in _HAD_WHY54.finditer(text):
        if not _things_only54(m["x"], lexicon) or not _only_person(m["p"], lexicon):
            continue
        raise GroundingError(
            f"{m['said']!r} says what {m['p']} had: it asks for nothing; say 'give {m['p']} "
            f"{m['x']}' to have it handed over"
        )


# -- a request followed by a question whether it was done ("Bob wants the apple, did you bring
# it?", "The apple's for Bob, did you give it to him?", "Give Bob the apple, did you?"): main read
# the request alone (apple>B); 'Did you bring it?' as a sentence of its own is refused as a
# question. It asks whether it was done: refused
_DID_YOU54 = re.compile(
    r"[,;:]\s*(?:and\s+|so\s+|but\s+)?(?P<said>(?:did|have|had) you(?: already| ever| actually| "
    r"even)?(?: (?:bring|brought|give|given|gave|take|taken|took|hand|handed|pass|passed|put|fetch|"
    r"fetched|get|got|send|sent|drop|dropped|deliver|delivered|move|moved)(?: (?:it|them|that|"
    r"those|this|these|him|her|one)\b[^.;!?]*)?)?(?:\s+(?:yet|already))?)\s*(?:\?|[.!]?\s*$)",
    _F,
)


def _did_you54(text: str, lexicon: Lexicon) -> None:
    """Session 54: a closing 'did you bring it?' after a request refused (above)."""
    low = text.lower()
    if "did you" not in low and "have you" not in low and "had you" not in low:
        return
    m = _DID_YOU54.search(text)
    if m is None:
        return
    raise GroundingError(
        f"{m['said']!r} asks whether it was done: it asks for nothing; say 'give …' to have it "
        "handed over"
    )


# -- a closing past-perfect want of a pronoun after a request ("Give Bob the cup, he had asked for
# the apple.", "…, he'd wanted the apple.", "…, he had to have the apple."; 12s's find, 12c): main
# read the want as a second handover (cup>B & apple>B), while 'Bob had asked for the apple.' alone
# is refused (session 52's _had_wanted52): a want that may be over, refused
_HAD_ASKED54 = re.compile(
    r"[,;]\s*(?:and |but |since |as |because |cos )?(?P<said>(?:he|she|they)(?: had|'d) "
    r"(?:(?:asked|begged) for|wanted|needed|requested|been (?:after|asking for|wanting|needing|"
    r"waiting for)|(?:had )?to have|had (?:his|her|their) eye on|set (?:his|her|their) heart on)"
    r"\b[^,.;!?]*)",
    _F,
)


def _had_asked54(text: str, lexicon: Lexicon) -> None:
    """Session 54: a closing "…, he'd wanted the apple." after a request refused (above)."""
    low = text.lower()
    if " had " not in low and "'d " not in low:
        return
    m = _HAD_ASKED54.search(text)
    if m is None or not _ids(m["said"], lexicon, "object"):
        return
    if re.search(r"\b(?:still|now|so give|so hand|so pass|again)\b", text[m.end() :], _F):
        return  # the rest says the want holds (session 52's convention)
    raise GroundingError(
        f"{m['said']!r} says what was wanted before: it may be over; say 'give …' for what is "
        "wanted now"
    )


# -- a question whether someone could have taken a thing ("Could Bob have taken the apple?", "Is
# it possible Bob could have taken the apple?"; 12c): main read 'Could Bob have taken the apple?'
# as apple>B ('could have got / had / eaten' were refused): a question about what was, refused
_COULD_HAVE54 = re.compile(
    r"\b(?P<said>(?:could|might|may|would|should|must|can) (?P<p>[^,.;!?]+?) (?:have|'ve) "
    r"(?:taken|took|grabbed|nicked|pinched|swiped|picked up|snatched|borrowed|used|moved|got|"
    r"gotten|had|eaten)\b[^.;!?]*)\?",
    _F,
)


def _could_have54(text: str, lexicon: Lexicon) -> None:
    """Session 54: 'Could P have taken X?' refused (above)."""
    low = text.lower()
    if "?" not in low or (" have " not in low and "'ve " not in low):
        return
    m = _COULD_HAVE54.search(text)
    if m is None or not _person_ends54(m["p"], lexicon) or not _ids(m["said"], lexicon, "object"):
        return
    raise GroundingError(
        f"{m['said']!r} asks about what was done: it asks for nothing; say 'give …' to have it "
        "handed over"
    )


# -- politeness and fillers ------------------------------------------------------------------------

# -- "…, would be grand" ("Um, if it's not too much bother, the bottle up on the shelf would be
# grand."): praise of the request said in other words than session 19's list (great, lovely,
# brilliant …), said 'would be great' (read)
_GRAND_WORDS54 = (
    *("grand", "smashing", "champion", "marvel", "splendid", "cracking", "magic", "brill"),
    *("terrific", "tremendous", "business", "just the job", "spot on", "dandy"),
)
_GRAND54 = re.compile(
    r"\b(?P<w>(?:would|'d|will) be (?:grand|smashing|champion|marvellous|marvelous|splendid|"
    r"cracking|magic|brill|terrific|tremendous|the business|just the job|spot on|dandy))\b",
    _F,
)


def _grand54(text: str, lexicon: Lexicon) -> str:
    """Session 54: 'would be grand' (and the like) said 'would be great'."""
    low = text.lower()
    if not any(w in low for w in _GRAND_WORDS54):
        return text
    m = _GRAND54.search(text)
    if m is None:
        return text
    return _cut52(text, m.start("w"), m.end("w"), "would be great", lexicon)


# -- a Thai thanks or greeting with its polite particle spelled otherwise than session 24's list
# ("Kop khun ka, the chips are for Person A, …", "Sawasdee krab, …"): the particle said as the
# list spells it ('kha', 'krap'), so session 24's _courtesy24 takes the stretch off
_THAI54 = re.compile(
    r"\b(?:k(?:h)?o[pb] khun(?: mak)?|sawas(?:dee|di)|sawatdee) (?P<p>ka|kah|krab|khrab|khrap|"
    r"kub|khub|kap|khap|krub)\b",
    _F,
)


def _thai54(text: str, lexicon: Lexicon) -> str:
    """Session 54: a Thai polite particle after thanks or a greeting spelled as session 24's."""
    if "khun" not in text.lower() and "sawa" not in text.lower():
        return text
    m = _THAI54.search(text)
    if m is None:
        return text
    put = "kha" if m["p"].lower().startswith("ka") else "krap"
    return _cut52(text, m.start("p"), m.end("p"), put, lexicon)


# -- wants and needs -------------------------------------------------------------------------------

# -- 'P has a craving for X' with X said without 'the' ("Person A has a craving for chips, the
# poor thing.", "Bob's got a real hankering for crisps."): said 'P wants X' (read; the grammar and
# sessions 34, 42 and 51 read 'has a (real) craving for the X')
_CRAVING54 = re.compile(
    r"(?P<w>(?:'s| has)(?: got)? (?:a |an )(?:real |big |massive |serious |huge |proper |bit of a "
    r"|slight |little |sudden )?(?:craving|hankering|yen|longing|hunger|thirst|fancy) for)"
    r"(?= (?!(?:the|a|an|his|her|their|my|your|our|its|that|this|those|these|some|any|one|"
    r"two)\b)[a-z])",
    _F,
)
_CRAVING_WORDS54 = (
    "craving",
    "hankering",
    " yen ",
    "longing",
    "hunger",
    "thirst",
    "fancy",
    "heart",
)
# "P's got his heart set on X" beside another clause ("Person B's got his heart set on the apple,
# and the bottle would suit Person A nicely."): said 'P wants X', so what the other clause needs
# is not held back by the holding "'s got" (_UNSAFE52); main reads the clause alone
_HEART54 = re.compile(r"(?P<w>(?:'s| has) got (?:his|her|their) heart set on)(?= )", _F)


def _craving54(text: str, lexicon: Lexicon) -> str:
    """Session 54: 'P has a craving for X' (no 'the') and "P's got his heart set on X" said 'P
    wants X'."""
    low = text.lower()
    if not any(w in low for w in _CRAVING_WORDS54):
        return text
    m = _CRAVING54.search(text) or _HEART54.search(text)
    if m is None or not _person_ends54(text[: m.start()], lexicon):
        return text
    return _cut52(text, m.start("w"), m.end("w"), " wants", lexicon)


def _person_ends54(said: str, lexicon: Lexicon) -> bool:
    """Whether the last one to three words of ``said`` (after its last stop or comma) name one
    person of the scene and nothing else, however cased ('Person A', 'mrs khan', 'Bob')."""
    words = re.split(r"[,.;:!?]", said)[-1].split()
    return any(len(words) >= k and _only_person(" ".join(words[-k:]), lexicon) for k in (3, 2, 1))


# -- 'the X would suit P (nicely)' ("…, and the bottle would suit Person A nicely."): what would
# suit the person is what they are to get, said 'the X for P' (read)
_SUIT54 = re.compile(
    r"(?P<x>\b(?:the|that|this|a|an) [^,.;!?]+?) would (?:suit|do) (?P<p>[^,.;!?]+?)"
    r"(?: (?:nicely|fine|just fine|perfectly|well|down to the ground|a treat|to a tee|to a t))?"
    r"(?=\s*(?:[.,;!?]|$))",
    _F,
)


def _suit54(text: str, lexicon: Lexicon) -> str:
    """Session 54: 'the X would suit P (nicely)' said 'the X for P'."""
    low = text.lower()
    if "would suit" not in low and "would do" not in low:
        return text
    m = _SUIT54.search(text)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    objects = _ids(m["x"], lexicon, "object")
    if not objects or objects != _ids(m["x"], lexicon):
        return text
    return _cut52(text, m.start(), m.end(), f"{m['x']} for {m['p']}", lexicon)


# -- 'so over it goes' / 'so over they go' after a want or an allotment ("What Person A's after is
# the chips, so over they go.", "person a … needs that bottle so over it goes"): the speaker's
# word to do it, taken off (what is left reads as the request)
_OVER_WORDS54 = ("it goes", "they go", "that goes", "those go", "these go", "this goes", "one goes")
_OVER_GOES54 = re.compile(
    r",?\s*(?:so|and|then)? ?(?:over|off|across) (?:it|they|that|those|these|this|"
    r"that one) (?:goes|go)\b(?: then)?(?=\s*(?:[.!]|$))",
    _F,
)


def _over_goes54(text: str, lexicon: Lexicon) -> str:
    """Session 54: a closing 'so over it goes' taken off."""
    low = text.lower()
    if not any(w in low for w in _OVER_WORDS54):
        return text
    m = _OVER_GOES54.search(text)
    if m is None or m.start() == 0:
        return text
    return _cut52(text, m.start(), m.end(), "", lexicon)


# -- pronouns and ellipsis -------------------------------------------------------------------------

# -- 'the Xs are for P, (could you) hand them over' ("Kop khun ka, the chips are for Person A,
# could you hand them over?"): the allotment said, then the word to do it with 'them' for the
# things; taken off when the things are plural (sessions before read '…, hand it over' for one)
_THEM_OVER54 = re.compile(
    r"^(?P<head>.*\b(?:are|'re) (?:for|going to|meant for) [^,.;!?]+?)\s*,\s*"
    r"(?:(?:so|and|then)\s+)?(?:(?:could|can|would|will) you (?:please |just )?|please |just )?"
    r"(?:hand|pass|bring|take|pop|send|give) them (?:over|across|round)(?: to (?:him|her|them))?"
    r"(?: please)?\s*"
    r"(?P<end>[.!?]?)\s*$",
    _F,
)


def _them_over54(text: str, lexicon: Lexicon) -> str:
    """Session 54: '…, could you hand them over?' after 'the Xs are for P' taken off."""
    low = text.lower()
    if "them over" not in low and "them across" not in low and "them round" not in low:
        return text
    m = _THEM_OVER54.match(text)
    if m is None:
        return text
    return _cut52(text, m.end("head"), len(text), ".", lexicon)


# -- 'P's got nothing to drink' ("Person A's got nothing to drink; pass her the bottle."): said
# "P's thirsty" ('to eat / to snack on': "hungry"; read as a reason); and 'with nothing to snack
# on' after what a person is doing ("Bob's loitering by the door with nothing to snack on; take him
# the apple, …"), taken off
_NOTHING_TO54 = re.compile(
    r"(?P<w>(?:'s|'ve| has| have)(?: got)? nothing (?:to|for (?:him|her|them) to) (?P<v>drink|"
    r"sip|eat|snack on|nibble(?: on)?|munch(?: on)?|chew on))\b",
    _F,
)
_WITH_NOTHING54 = re.compile(
    r"(?P<w>\s+with nothing to (?:drink|sip|eat|snack on|nibble(?: on)?|munch(?: on)?|chew on|"
    r"do))(?=\s*[,;.]|\s*$)",
    _F,
)
_LOITER54 = re.compile(r"(?:(?<='s )|(?<='re ))(?P<w>loitering|lurking|skulking)(?= )", _F)


def _nothing_to54(text: str, lexicon: Lexicon) -> str:
    """Session 54: "P's got nothing to drink" said "P's thirsty"; 'with nothing to eat' after a
    doing taken off; 'loitering' said 'hanging about'."""
    low = text.lower()
    if "nothing to" not in low and "nothing for" not in low:
        return text
    m = _NOTHING_TO54.search(text)
    before = text[: m.start()] if m is not None else ""
    if m is not None and (
        _person_ends54(before, lexicon) or before.split()[-1:] in (["he"], ["she"], ["they"])
    ):
        thirst = m["v"].lower() in ("drink", "sip")
        put = ("'s " if m["w"].startswith("'") else " is ") + ("thirsty" if thirst else "hungry")
        if m["w"].lower().startswith(("'ve", " have")):
            put = ("'re " if m["w"].startswith("'") else " are ") + put.split()[-1]
        return _cut52(text, m.start("w"), m.end("w"), put, lexicon)
    m = _WITH_NOTHING54.search(text)
    if m is None:
        return text
    out = _cut52(text, m.start("w"), m.end("w"), "", lexicon)
    if out == text:
        said = text[: m.start("w")] + text[m.end("w") :]
        k = _LOITER54.search(said)
        if k is not None:
            out = _cut52(said, k.start("w"), k.end("w"), "hanging about", lexicon)
            out = text if out == said else out
    return out


# -- a closing remark of how the person feels after some pastime ("Can Person B have the apple,
# he's starving after shot put?"): the pastime taken off when it names nothing of the scene
# (session 19's remarks read "…, he's starving" and "…, he's tired after his shift"; a pastime
# said without 'his' / 'the' may hold a verb: 'shot put')
_AFTER_DOING54 = re.compile(
    r"(?P<r>,\s*(?:he|she|they)(?:'s| is|'re| are) (?:absolutely |really |so |totally |just )?"
    r"(?:starving|famished|ravenous|hungry|peckish|thirsty|parched|gasping|knackered|exhausted|"
    r"shattered|worn out|tired|wiped out|done in|cold|freezing|boiling|roasting))(?P<w> after "
    r"(?!(?:his|her|their|the|a|an|my|our|your|its|that|this)\b)[^,.;!?]+?)(?=\s*[.!?]?\s*$)",
    _F,
)


def _after_doing54(text: str, lexicon: Lexicon) -> str:
    """Session 54: a closing "he's starving after shot put": the pastime taken off."""
    if " after " not in text.lower():
        return text
    m = _AFTER_DOING54.search(text)
    if m is None or _names(m["w"], lexicon):
        return text
    return _cut52(text, m.start("w"), m.end("w"), "", lexicon)


# -- a closing remark that the person can't get up ("Could you bring the bottle to Person A, she's
# on the phone and can't get up?"): the 'and can't get up' taken off (what is left, "…, she's on
# the phone", is a remark sessions before read)
_CANT_GET_UP54 = re.compile(
    r"(?P<r>,\s*(?:he|she|they)(?:'s| is|'re| are) [^,.;!?]+?)(?P<w> and (?:so )?(?:can't|cant|"
    r"cannot|can not|couldn't) (?:get up|move|come over|get away|get over|stand up|walk|reach|"
    r"leave|get it|fetch it))(?=\s*[.!?]?\s*$)",
    _F,
)


def _cant_get_up54(text: str, lexicon: Lexicon) -> str:
    """Session 54: a closing "…, she's on the phone and can't get up": 'and can't …' taken off."""
    low = text.lower()
    if not any(w in low for w in ("can't", "cant", "cannot", "can not", "couldn't")):
        return text
    m = _CANT_GET_UP54.search(text)
    if m is None or _names(m["w"], lexicon):
        return text
    return _cut52(text, m.start("w"), m.end("w"), "", lexicon)


# -- 'where the dog can't get them' after a placing ("crisps want to go up on the shelf where the
# dog cant get them"): why it goes there, taken off when it names nothing of the scene
_WHERE_CANT54 = re.compile(
    r"(?P<w>,?\s+where (?:the [a-z]+|[a-z]+|he|she|they|nobody|no one|no-one) (?:can't|cant|"
    r"cannot|can not|won't|wont) (?:get|reach|find|see|knock|touch|nick|grab|eat|chew|trip on|"
    r"tread on|step on)(?: (?:at|to|over|down|off))? (?:it|them)(?: (?:over|down|off))?)"
    r"(?=\s*[.!]?\s*$)",
    _F,
)


def _where_cant54(text: str, lexicon: Lexicon) -> str:
    """Session 54: a closing 'where the dog can't get them' after a placing taken off."""
    if "where " not in text.lower():
        return text
    m = _WHERE_CANT54.search(text)
    if m is None or _names(m["w"], lexicon) or _placed_aside43s(text, lexicon) != text:
        return text  # (session 43s's _placed_aside43s reads 'Pop the salt on the rack where …')
    named = _names(text[: m.start()], lexicon)
    if not named or any(r.kind != "surface" for r in named[-1].refs):
        return text  # only after a placing ("Give Lena the salt where the kids can't …")
    return _cut52(text, m.start("w"), m.end("w"), "", lexicon)


# -- lower case ------------------------------------------------------------------------------------

# -- a run-on 'asked for X a minute ago can you bring it' ("person a asked for the bottle a minute
# ago can you bring it"): how long ago said as session 19 says it ('just now'), and the request
# after it set off by a comma
_MINUTE_AGO54 = re.compile(
    r"(?P<a>\basked (?:me |you )?for [^.;!?,]*?) (?P<t>a (?:minute|min|moment|second|sec|few "
    r"minutes|couple of minutes|little while|bit) ago|just now)(?P<c>,?)(?P<q> (?:can|could|would|"
    r"will) you\b|(?= (?:please )?(?:bring|take|give|hand|pass|fetch)\b))?",
    _F,
)


def _minute_ago54(text: str, lexicon: Lexicon) -> str:
    """Session 54: 'asked for X a minute ago can you bring it' said 'asked for X just now, can
    you bring it'."""
    low = text.lower()
    if " ago" not in low and "just now" not in low:
        return text
    m = _MINUTE_AGO54.search(text)
    if m is None or (m["t"] == "just now" and (m["c"] or m["q"] is None)):
        return text
    end, rest = m.end("c"), text[m.end("c") :].strip()
    if m["q"] is None and rest and not m["c"] and rest[0] not in ".;!?":
        return text  # what runs on is no request ('… a minute ago did you bring it')
    if rest and rest[0] not in ".;!?" and not re.search(r"\b(?:it|them)\b", rest, _F):
        return text  # the request after it is for something else ('… bring him the cup')
    put = f"{m['a']} just now" + ("," if m["q"] is not None or m["c"] else "")
    return _cut52(text, m.start(), end, put, lexicon)


# -- 'and after he's had it' between two handovers ("person b is first in line for the cup and
# after hes had it the apple can go to person a"): the order said, as ', then' (read)
_AFTER_HAD54 = re.compile(
    r"(?<!\band)(?<!\band,)(?P<w>,?\s+(?:and )?(?:after|once|when) (?:he|she|they)(?:'s|s| has|"
    r"'ve| have) (?:had|finished with|finished|done with|used) (?:it|them|that|those|his|hers)"
    r"\s*,?)\s+(?=the |his |her |their )",
    _F,
)


def _after_had54(text: str, lexicon: Lexicon) -> str:
    """Session 54: "and after he's had it" between two handovers said ', then'."""
    low = text.lower()
    if not any(w in low for w in ("had ", "finished", "done with", "used ")):
        return text
    m = _AFTER_HAD54.search(text)
    if m is None or m.start() == 0:
        return text
    people = [it for it in _names(text[: m.start()], lexicon) if it.refs[0].kind == "human"]
    if not people or len({r.id for r in people[-1].refs}) != 1:
        return text
    if not _agrees44(people[-1].refs[0].id, m["w"], lexicon):
        return text  # the pronoun cannot be the one named before ('Bob … after she's had it')
    return _cut52(text, m.start("w"), m.end("w"), ", then", lexicon)


# -- questions -------------------------------------------------------------------------------------

# -- a request asked as a question with 'she's the only one without a drink' before its question
# mark ("What about the cup going to Person A, she's the only one without a drink?"): the question
# mark said as a stop, so session 30's _only_one_who30r takes the remark off (it reads it before a
# stop only)
_ONLY_ONE54 = re.compile(
    r"^(?:what about|how about|could|can|would|will)\b.*,\s*(?:she|he|they)(?:'s| is|'re| are) the "
    r"only (?:one|ones|person|people)\b[^,.;!?]*(?P<q>\?)\s*$",
    _F,
)


def _only_one54(text: str, lexicon: Lexicon) -> str:
    """Session 54: a closing "she's the only one without a drink?" after a request: '?' as '.'."""
    low = text.lower()
    if "?" not in low or not any(w in low for w in ("only one", "only person", "only people")):
        return text
    m = _ONLY_ONE54.match(text)
    if m is None:
        return text
    return _cut52(text, m.start("q"), m.end("q"), ".", lexicon)


# -- "Would you mind running the X over to P?" ("Would you mind running the bottle over to Person B
# while he's on his break?"): said 'mind taking' (read; sessions 28 and 32 read 'run the X over /
# up / down to P')
_RUN54 = re.compile(
    r"\bmind (?P<v>running)(?= (?:the|this|that|these|those|her|his|their|a|an|"
    r"some|it|them)\b[^.;!?,]*? (?:over|across|round|up|down|back|along) to\b)",
    _F,
)


def _run54(text: str, lexicon: Lexicon) -> str:
    """Session 54: 'mind running the X over to P' said 'mind taking …'."""
    if "running" not in text.lower():
        return text
    m = _RUN54.search(text)
    if m is None:
        return text
    return _cut52(text, m.start("v"), m.end("v"), "taking", lexicon)


# -- 'as you go by' ("Any chance you could drop the chips off with Person A as you go by?"): when
# the hearer passes, not a time the task waits for, taken off (read; session 42s reads "when
# you're going past")
_GO_BY54 = re.compile(
    r",?\s*\b(?:as|when) you (?:go|pass|walk|come|head|wander) (?:by|past)(?: (?:there|here))?\b"
    r"|,?\s*\bas you(?:'re| are) (?:going|passing|walking|coming|heading) (?:by|past)\b",
    _F,
)


def _go_by54(text: str, lexicon: Lexicon) -> str:
    """Session 54: 'as you go by' taken off."""
    low = text.lower()
    if "as you" not in low and "when you" not in low:
        return text
    m = _GO_BY54.search(text)
    if m is None:
        return text
    return _cut52(text, m.start(), m.end(), "", lexicon)


# -- 'Is it possible (that) P could have / get X?' ("Is it possible Person A could get her bottle
# off you now?"): a request, said 'Could P have / get X?' (read)
_POSSIBLE54 = re.compile(
    r"^(?P<q>(?:is|would) it (?:be )?(?:possible|ok|okay|alright|all right)(?: that)? )(?P<p>[^,"
    r".;!?]+?) (?:could|can|might) (?=(?:have|get|borrow|take) (?:the|a|an|his|her|their|its|my|"
    r"our|your|some|one|any|that|this|those|these|it|them|both|either)\b)",
    _F,
)


def _possible54(text: str, lexicon: Lexicon) -> str:
    """Session 54: 'Is it possible P could get X?' said 'Could P get X?'."""
    low = text.lower()
    if not any(w in low for w in ("possible", " ok ", " okay ", "alright", "all right")):
        return text
    m = _POSSIBLE54.match(text)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    return _cut52(text, 0, m.end(), f"Could {m['p']} ", lexicon)


# -- 'for story time' after a placing ("Could the teddy go down on the play mat for story time?"):
# what it is for, naming nothing of the scene, taken off (read)
_FOR_TIME54 = re.compile(
    r"\s+for (?!(?:the |a |one |this |that |some |any |each |every )?(?:first|last|next|long|"
    r"short|some|little|while|time|now|later|tomorrow|today|tonight|being)\b)(?P<w>(?:[a-z]+[ -]"
    r"){1,2})time\b(?=\s*(?:[.,;!?]|$))",
    _F,
)


def _for_time54(text: str, lexicon: Lexicon) -> str:
    """Session 54: a closing 'for story time' taken off."""
    if " time" not in text.lower():
        return text
    m = _FOR_TIME54.search(text)
    if m is None or _names(m["w"], lexicon):
        return text
    return _cut52(text, m.start(), m.end(), "", lexicon)


# -- 'before it gets knocked (over)' ("Would you be a dear and put the bottle up on the shelf
# before it gets knocked?"): why to do it, taken off (read)
_BEFORE_GETS54 = re.compile(
    r",?\s*\bbefore (?:it|they|that|those|someone|somebody|anyone|anybody) (?:gets?|get) "
    r"(?:[a-z]+ed|broken|stolen|eaten|trodden|spilt|lost|nicked|bitten|taken|sat)(?: (?:over|on|"
    r"off|down|in|up|into|onto|under))?\b(?: by (?:someone|somebody|anyone|the [a-z]+))?",
    _F,
)


def _before_gets54(text: str, lexicon: Lexicon) -> str:
    """Session 54: a closing 'before it gets knocked' taken off."""
    low = text.lower()
    if not any(f"before {w}" in low for w in ("it", "they", "that", "those", "some", "any")):
        return text
    m = _BEFORE_GETS54.search(text)
    if m is None or _names(m.group(0), lexicon):
        return text
    return _cut52(text, m.start(), m.end(), "", lexicon)


# the normaliser's first rewrites (wired into normalise._STEPS19, before the session-53 ones)
_STEPS54_FIRST: tuple[Callable[[str, Lexicon], str], ...] = (
    _grand54,
    _thai54,
    _craving54,
    _suit54,
    _over_goes54,
    _run54,
    _go_by54,
    _for_time54,
    _before_gets54,
    _possible54,
    _them_over54,
    _nothing_to54,
    _only_one54,
    _after_doing54,
    _cant_get_up54,
    _where_cant54,
    _minute_ago54,
    _after_had54,
)
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-53 ones)
_STEPS54: tuple[Callable[[str, Lexicon], str], ...] = ()
# refusals asked of the text before it is read (offline._parse, after the session-53 ones)
REFUSE54: tuple[Callable[[str, Lexicon], None], ...] = (
    _days_ago54,
    _had_why54,
    _did_you54,
    _had_asked54,
    _could_have54,
)
# checks of the whole instruction's reading (offline.parse_instruction, after the session-53 ones)
CHECK54: tuple[Callable[[str, Node, Lexicon], None], ...] = ()
