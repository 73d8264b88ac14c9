"""The grounder's rules of session 53, engineer 12 (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _ids, _names, _only_person, _reading, _unknown_word
from hltl.grounding._rewrites40r import _claim40r
from hltl.grounding._rewrites42 import _elided_want42
from hltl.grounding._rewrites42s import _state_and42s
from hltl.grounding._rewrites44 import _agrees44
from hltl.grounding._rewrites52 import _P52, _UNSAFE52, _WANTS52, _cut52
from hltl.grounding.lexicon import Lexicon
from hltl.grounding.tree import Node, tasks

# -- session 53 (engineer 12): blind51's refusals of politeness and fillers, wants and needs,
# pronouns and ellipsis, lower case and questions, each read as a family. Every rule rewrites to
# words the grammar (or an older rule) already reads and keeps the rewrite only when it reads and
# unmasks nothing of session 52's _UNSAFE52 (a past want, a holding, said done, a time, a tag).

# -- politeness and fillers ------------------------------------------------------------------------

# -- "Whenever's convenient," ("Whenever's convenient, pal, the packing tape wants to go on the
# belt."): no hurry, said "When it's convenient," (read); and the texted 'ur' after 'whenever' /
# 'when' / 'once' ("the bottle is for person a whenever ur free no rush"), said "you're"
_WHENEVER53 = re.compile(
    r"\b(?P<w>whenever)(?:'s| is| it's| it is) (?:convenient|good|fine|okay|ok|best|easiest|"
    r"easy|handy|a good time)(?: for you)?\b",
    _F,
)
_UR53 = re.compile(
    r"\b(?:whenever|when|once|as soon as|if) (?P<ur>ur|youre|yr)(?= (?:free|ready|done|back|"
    r"finished|able|about|around|passing|not busy)\b)",
    _F,
)


def _whenever53(text: str, lexicon: Lexicon) -> str:
    """Session 53: "Whenever's convenient" read as "When it's convenient", and 'whenever ur
    free' as "whenever you're free"."""
    if "henever" not in text and " ur " not in text and "youre" not in text and " yr " not in text:
        return text
    m = _WHENEVER53.search(text)
    if m is not None:
        put = "When it's convenient" if m["w"][0] == "W" else "when it's convenient"
        return _cut52(text, m.start(), m.end(), put, lexicon)
    m = _UR53.search(text)
    if m is not None:
        return _cut52(text, m.start("ur"), m.end("ur"), "you're", lexicon)
    return text


# -- thanks ahead in another language in two or three words ("Baie dankie in advance, my friend,
# Person B would really like the chips.", "Vielen Dank in advance, …"): each word no English word
# the grounder knows (_unknown_word: no first name, no word of the scene) or a word of thanks
# (_THANKS_WORDS53), one at least unknown, before 'in advance' / 'so much' / 'again' and a
# comma, said 'Thanks in advance,' (session 46's _thanks_ahead46 reads one word)
_THANKS_TWO53 = re.compile(
    r"^(?P<w>[A-Z][a-z]+(?: [A-Za-z][a-z]+){1,2}) (?:in advance|so much|very much|ever so much|"
    r"muchly|again|a lot|a million)\s*[,:;!]\s*(?=\S)"
)
_THANKS_WORDS53 = frozenset(
    ("dank", "danke", "tack", "takk", "merci", "grazie", "gracias", "obrigado", "obrigada")
)


def _thanks_two53(text: str, lexicon: Lexicon) -> str:
    """Session 53: an opening thanks of two or three foreign words said 'Thanks in advance,'."""
    if not any(w in text for w in (" in advance", " much", " again", " a lot", " a million")):
        return text
    m = _THANKS_TWO53.match(text)
    if m is None or _names(m["w"], lexicon):
        return text
    words = m["w"].split()
    unknown = [_unknown_word(w, lexicon) for w in words]
    if not any(unknown) or not all(
        u or w.lower() in _THANKS_WORDS53 for w, u in zip(words, unknown, strict=True)
    ):
        return text
    return _cut52(text, 0, m.end(), "Thanks in advance, ", lexicon)


# -- "bit of a ramble, but" opening a request (after one word of address: "Right, bit of a ramble,
# but the bottle, Person A, whenever suits you."): the speaker's word on their own talk, taken off
_RAMBLE53 = re.compile(
    r"^(?P<lead>(?:[Rr]ight|[Ss]o|[Oo]kay|[Oo]k|[Ww]ell|[Ss]orry|[Oo]h|[Uu]m|[Ee]rm),\s*)?"
    r"(?P<cut>(?:[Aa] |[Ss]orry,? )?(?:[Bb]it of an?|[Ss]uch an?|[Ww]hat an?|[Ss]orry for the|"
    r"[Ee]xcuse the|[Pp]ardon the) (?:ramble|waffle|rant|saga|rigmarole|palaver|essay|monologue|"
    r"tangent|ramble from me|waffle from me),?\s+but\s+)"
)


def _ramble53(text: str, lexicon: Lexicon) -> str:
    """Session 53: an opening 'bit of a ramble, but' taken off."""
    if " but" not in text:
        return text
    m = _RAMBLE53.match(text)
    if m is None:
        return text
    return _cut52(text, m.start("cut"), m.end("cut"), "", lexicon)


# -- pronouns and ellipsis -------------------------------------------------------------------------

# -- "That bottle over there, …" (a thing pointed at, said first: "That bottle over there, Person A
# has her eye on it."): the pointing taken off ("That bottle, …" reads)
_OVER_THERE53 = re.compile(
    r"^(?:[Tt]hat|[Tt]his|[Tt]he|[Tt]hose|[Tt]hese) [a-z]+(?: [a-z]+)?(?P<cut> over (?:there|here|"
    r"yonder))(?=,)"
)


def _over_there53(text: str, lexicon: Lexicon) -> str:
    """Session 53: an opening 'That bottle over there,' read as 'That bottle,'."""
    if " over " not in text:
        return text
    m = _OVER_THERE53.match(text)
    if m is None:
        return text
    return _cut52(text, m.start("cut"), m.end("cut"), "", lexicon)


# -- "That bottle's cluttering up the floor, could you …" (a thing said first with what is wrong
# with where it is, a place that names nothing of the scene): said "That bottle's in the way, …"
# (read; 12c: "That apple's cluttering up the table, put it on the table." stays refused)
_CLUTTER53 = re.compile(
    r"^(?P<x>(?:[Tt]hat|[Tt]his|[Tt]he|[Tt]hose|[Tt]hese) [a-z]+(?: [a-z]+)?)(?P<cut>(?:'s| is|"
    r"'re| are) (?:cluttering|clogging|hogging|littering|blocking|messing|taking up (?:room|space)"
    r"|lying about|lying around|rolling about|rolling around|cluttering up|clogging up|hogging up|"
    r"messing up)(?: on| up)? the [a-z]+(?: [a-z]+)?)(?=,)"
)


def _clutter53(text: str, lexicon: Lexicon) -> str:
    """Session 53: "That bottle's cluttering up the floor," read as "That bottle's in the way,"."""
    if "ing " not in text:
        return text
    m = _CLUTTER53.match(text)
    if m is None or _names(m["cut"], lexicon):
        return text  # (a surface of the scene named: where it is may be where it is to go)
    verb = "'re" if m["cut"].startswith(("'re", " are")) else "'s"
    return _cut52(text, m.start("cut"), m.end("cut"), f"{verb} in the way", lexicon)


# -- "as for P, the X's hers" after another's want ("Person B has put in for the chips; as for
# Person A, the bottle's hers."): whose it is, the one named after 'as for', said "the X's P's"
# (read) when the pronoun may be that person
_AS_FOR53 = re.compile(
    r"(?<=[;,.]) (?P<cut>[Aa]s (?:for|regards|to) (?P<p>" + _P52 + r"),\s*(?P<x>(?:the|that|"
    r"this) [a-z]+(?: [a-z]+)?)(?P<v>'s| is) (?P<pron>hers|his))(?=\s*[.!]?$)"
)


def _as_for53(text: str, lexicon: Lexicon) -> str:
    """Session 53: "as for P, the X's hers" read as "the X's P's"."""
    if "s for " not in text and "s regards " not in text and "s to " not in text:
        return text
    m = _AS_FOR53.search(text)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    (pid,) = _ids(m["p"], lexicon)
    if not _agrees44(pid, m["pron"].replace("hers", "her"), lexicon):
        return text
    return _cut52(text, m.start("cut"), m.end("cut"), f"{m['x']}{m['v']} {m['p']}'s", lexicon)


# -- wants and needs -------------------------------------------------------------------------------

# -- "P has dibs on X" / "P has her eye on it" anywhere in the text ("chips are for person b and
# person a has dibs on the bottle", "That bottle, Person A has her eye on it."): a want, said
# "P wants X" (session 40's _claim40r reads a claim opening a clause after a stop)
_DIBS53 = re.compile(
    r"\b(?P<p>" + _P52 + r")(?:'s got| has got| has) (?:(?:first )?dibs on|(?P<pron>her|his|"
    r"their) (?:beady )?eyes? on)(?= (?:(?:the|that|this|those|these) [a-z]+(?: [a-z]+)?|it|them)"
    r"\s*(?:[,.;!?]|$|and\b))",
    _F,
)


def _tails53(words: str) -> list[str]:
    """``words`` and its endings, longest first ('and person a' -> 'and person a', 'person a',
    'a')."""
    parts = words.split()
    return [" ".join(parts[k:]) for k in range(len(parts))]


def _dibs53(text: str, lexicon: Lexicon) -> str:
    """Session 53: "P has dibs on X" / "P has her eye on X" read as "P wants X"."""
    if "dibs on" not in text and " on it" not in text and " on them" not in text:
        return text
    m = _DIBS53.search(text)
    if m is None:
        return text
    # a text in lower case: the name is the last word or two matched ("… and bob has dibs on")
    who = next((w for w in _tails53(m["p"]) if _only_person(w, lexicon)), None)
    if who is None:
        return text
    (pid,) = _ids(who, lexicon)
    if m["pron"] and not _agrees44(pid, m["pron"], lexicon):
        return text
    if _claim40r(text, lexicon) != text:
        return text  # (session 40's: "Sam's got dibs on the stapler.")
    return _cut52(text, m.end("p") - len(who), m.end(), f"{who} wants", lexicon)


# -- "P's throat is like sandpaper" ("Person A's throat is like sandpaper after the crossing warden
# shift, so give her the bottle."): thirst, said "P's thirsty" (read)
_THROAT53 = re.compile(
    r"\b(?P<p>" + _P52 + r")'s (?:throat|mouth)(?:'s| is) (?:like (?:sandpaper|a desert|the desert|"
    r"the sahara|the Sahara|dust|a bone|an old boot)|as dry as (?:sandpaper|a bone|dust|a desert|"
    r"the desert|the sahara|the Sahara|an old boot)|dry as (?:a bone|dust|sandpaper)|bone dry|"
    r"parched|dry)\b"
)


def _throat53(text: str, lexicon: Lexicon) -> str:
    """Session 53: "P's throat is like sandpaper" read as "P's thirsty"."""
    if "throat" not in text and "mouth" not in text:
        return text
    m = _THROAT53.search(text)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    return _cut52(text, m.start(), m.end(), f"{m['p']}'s thirsty", lexicon)


# -- "If you ask me, …" opening ("If you ask me, the thing Person A has been angling for all along
# is that bottle."): the speaker's opinion, taken off
_ASK_ME53 = re.compile(
    r"^(?P<cut>(?:[Ii]f you ask me|[Ii]f you want my opinion|[Ii]f you want my two pennies|"
    r"[Ii]n my (?:humble )?opinion|[Bb]etween you and me|[Ff]or my money),\s*)"
)


def _ask_me53(text: str, lexicon: Lexicon) -> str:
    """Session 53: an opening 'If you ask me,' taken off."""
    if not any(w in text for w in ("ask me", "opinion", "you and me", "my money", "two pennies")):
        return text
    m = _ASK_ME53.match(text)
    if m is None:
        return text
    return _cut52(text, 0, m.end(), "", lexicon)


# -- "the thing P has been angling for (all along) is X" (a want said as what it is): said "P wants
# X" (read; "The thing Person A wants is that bottle." reads)
_CLEFT53 = re.compile(
    r"^(?P<cut>[Tt]he (?:thing|one thing|one) (?P<p>" + _P52 + r") (?:has been|'s been|is|'s) "
    r"(?:angling for|after|eyeing up|eyeing|hankering after|hoping for|pining for|holding out for|"
    r"itching for|gagging for|dying for|set on|waiting for)(?: all along| all day| all morning| "
    r"all afternoon| all week)? (?:is|'s) )(?=(?:the|that|this|those|these) [a-z]+(?: [a-z]+)?"
    r"\s*[.!]?$)"
)


def _cleft53(text: str, lexicon: Lexicon) -> str:
    """Session 53: "the thing P has been angling for is X" read as "P wants X"."""
    if "thing " not in text and "one " not in text:
        return text
    m = _CLEFT53.match(text)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    return _cut52(text, 0, m.end("cut"), f"{m['p']} wants ", lexicon)


# -- questions -------------------------------------------------------------------------------------

# -- "swing by P with the X" ("Any chance you could drop the apple off with Person A and swing by
# Person B with the cup?"): going to the person with the thing, said "take the X to P" (read)
_SWING_BY53 = re.compile(
    r"\b(?:[Ss]wing|[Pp]op|[Nn]ip|[Ss]top|[Cc]all|[Dd]rop|[Hh]ead|[Rr]un|[Dd]ash|[Zz]ip|[Ww]ander|"
    r"[Ss]troll) (?:round |over |across )?(?:by|past|to|in on|round to|over to|across to) "
    rf"(?P<p>{_P52}) with (?P<x>(?:the|that|this|those|these) [a-z]+(?: [a-z]+)?)"
    r"(?=\s*(?:[,.;!?]|$))"
)


def _swing_by53(text: str, lexicon: Lexicon) -> str:
    """Session 53: 'swing by P with the X' read as 'take the X to P'."""
    if " with " not in text:
        return text
    m = _SWING_BY53.search(text)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    return _cut52(text, m.start(), m.end(), f"take {m['x']} to {m['p']}", lexicon)


# -- batch 2 ---------------------------------------------------------------------------------------

# -- "while you're about it" said "while you're at it" ("The apple, grab it and pass it along to
# Carol, and while you're about it, the red mug for her as well.", read)
_ABOUT_IT53 = re.compile(r"\b(?:while|whilst) (?:you're|you are|youre) (?P<a>about it)\b", _F)


def _about_it53(text: str, lexicon: Lexicon) -> str:
    """Session 53: "while you're about it" read as "while you're at it"."""
    if "about it" not in text:
        return text
    m = _ABOUT_IT53.search(text)
    if m is None:
        return text
    return _cut52(text, m.start("a"), m.end("a"), "at it", lexicon)


# -- "Between the two of them it's simple:" opening ("Between the two of them it's simple: the cup
# is what Person A is after, Person B the apple."): who the sharing is between, taken off ("It's
# simple: …" reads)
_BETWEEN53 = re.compile(
    r"^(?P<cut>(?:[Bb]etween|[Ww]ith|[Ff]or) (?:the (?:two|three|pair|both|lot) of them|those "
    r"two|the pair|them both|the two),?\s+)(?=(?:it's|it is) (?:simple|easy|straightforward|dead "
    r"simple|dead easy|quite simple)\s*:)"
)


def _between53(text: str, lexicon: Lexicon) -> str:
    """Session 53: an opening 'Between the two of them' before "it's simple:" taken off."""
    if not any(w in text for w in (" of them", " two", " both", " pair")):
        return text
    m = _BETWEEN53.match(text)
    if m is None:
        return text
    return _cut52(text, 0, m.end("cut"), "", lexicon)


# -- a closing 'since her shift (as a crossing warden) ended' after a want ("Person A has been
# craving the chips since her shift as a crossing warden ended."): since when, an end or start
# that is over, taken off (the want reads)
_SINCE_ENDED53 = re.compile(
    r"(?P<cut>,?\s+(?:ever )?since (?:her|his|their|the) [a-z]+(?: [a-z]+){0,5} (?:ended|finished|"
    r"began|started|stopped|wrapped up|got going))(?=\s*[.!]?$)"
)


# wants _WANTS52 does not name ("Person A has been craving the chips")
_CRAVING53 = re.compile(
    r"\b(?:craving|craves|longing for|dying for|gasping for|desperate for|hankering after|"
    r"pining for|itching for)\b",
    _F,
)


def _since_ended53(text: str, lexicon: Lexicon) -> str:
    """Session 53: a closing 'since her shift ended' after a want taken off."""
    if "since " not in text:
        return text
    m = _SINCE_ENDED53.search(text)
    if m is None or _names(m["cut"], lexicon):
        return text
    if not _WANTS52.search(text[: m.start()]) and not _CRAVING53.search(text[: m.start()]):
        return text
    return _cut52(text, m.start("cut"), m.end("cut"), "", lexicon)


# -- "P wants them there" closing a placing, run on with 'please' ("pop the tongs down on the
# worktop please lena wants them there"): why it goes there, taken off when what is left only
# places things
_WANTS_THERE53 = re.compile(
    r"(?P<cut>(?:,\s*|\s+)(?P<p>" + _P52 + r"|[a-z]+(?: [a-z])?) (?:wants|needs|would like|'d "
    r"like|likes) (?:it|them) (?:there|put there|left there)\s*[.!]?)$",
    _F,
)


def _wants_there53(text: str, lexicon: Lexicon) -> str:
    """Session 53: a closing "P wants them there" after a placing taken off."""
    if " there" not in text:
        return text
    m = _WANTS_THERE53.search(text)
    if m is None:
        return text
    who = next((w for w in _tails53(m["p"]) if _only_person(w, lexicon)), None)
    if who is None or m["p"].lower() not in (who.lower(), f"please {who.lower()}"):
        return text
    out = text[: m.start("cut")]
    if _UNSAFE52.search(out):
        return text
    read = _reading(out, lexicon)
    if read is None or any(t.kind != "place" for t in tasks(read)):
        return text
    return out


# -- "P's got a stack of X to clip together," before a request ("Priya's got a stack of rota packs
# to clip together, would you be able to bring her the stapler?"): what keeps the person busy,
# said "P's busy," (read)
_STACK_OF53 = re.compile(
    r"^(?P<p>" + _P52 + r")(?:'s got| has got| has) (?:a (?:big |huge |whole |massive )?(?:stack|"
    r"pile|heap|load|mountain|bunch|ton|pile-up|backlog|tower)|loads|piles|heaps|stacks|tons) of "
    r"[a-z]+(?: [a-z]+){0,3} to (?:[a-z]+)(?: (?:together|through|up|out|off|in|done))?(?=,\s)"
)


def _stack_of53(text: str, lexicon: Lexicon) -> str:
    """Session 53: "P's got a stack of X to clip together," read as "P's busy,"."""
    if " of " not in text:
        return text
    m = _STACK_OF53.match(text)
    if m is None or not _only_person(m["p"], lexicon) or _names(m.group()[len(m["p"]) :], lexicon):
        return text
    return _cut52(text, 0, m.end(), f"{m['p']}'s busy", lexicon)


# -- "P's packing her own lunch box this morning and would be grateful for X" (what the person is
# doing, then a want joined by 'and'): the doing taken off, said "P would be grateful for X"
_DOING_AND53 = re.compile(
    r"^(?P<p>" + _P52 + r")(?:'s| is) (?P<w>[a-z]+ing [^,.;:!?]{3,50}?) and (?=(?:would|'d|wants|"
    r"needs|could do with|is after|fancies|is hoping for)\b)"
)


def _doing_and53(text: str, lexicon: Lexicon) -> str:
    """Session 53: "P's packing her lunch box and would be grateful for X" read as "P would be
    grateful for X"."""
    if "ing " not in text or " and " not in text:
        return text
    m = _DOING_AND53.match(text)
    if m is None or not _only_person(m["p"], lexicon) or _names(m["w"], lexicon):
        return text
    if _state_and42s(text, lexicon) != text or _elided_want42(text, lexicon) != text:
        return text  # (session 42's: "Marco is sweating over the stove and would love the lemon.")
    return _cut52(text, 0, m.end(), f"{m['p']} ", lexicon)


# -- "she's after her teddy" after a clause naming her ("Lily's grizzling and reaching out her
# little arms, she's after her teddy."): her want, said "she wants her teddy" (read)
_PRON_AFTER53 = re.compile(
    r"(?<=[,;]\s)(?P<pron>[Ss]he|[Hh]e)(?:'s| is) after (?=(?:her|his) [a-z]+)"
)


def _pron_after53(text: str, lexicon: Lexicon) -> str:
    """Session 53: "…, she's after her teddy" read as "…, she wants her teddy"."""
    if "s after " not in text and " is after " not in text:
        return text
    m = _PRON_AFTER53.search(text)
    if m is None:
        return text
    return _cut52(text, m.start(), m.end(), f"{m['pron']} wants ", lexicon)


# -- refused with its readings -------------------------------------------------------------------

# -- a question of the speaker's own memory between two things ("Did Zoe ask for the glue stick or
# the red book? I can't remember."): no choice left to the robot, refused naming both readings (as
# session 39's doubt_which39 does "…, I can't remember which"; it had been refused as a question
# naming none)
_FORGOT_WHICH53 = re.compile(
    r"^(?![Dd]id you\b)(?P<q>(?:[Dd]id|[Ww]as it|[Hh]as|[Hh]ad|[Ww]as) [^?]{0,60}?"
    r"(?P<a>\b(?:the|a|an) [a-z]+(?: [a-z]+)?) or (?P<b>(?:the|a|an) [a-z]+(?: [a-z]+)?)"
    r"[^?]{0,30}\?)\s*(?:(?:[Ii]|[Hh]onestly,? I) (?:can't|cannot|can not|don't|do not|just "
    r"can't) (?:remember|recall)|I forget|I've forgotten|I'm not sure|[Nn]o idea|[Ii]t's slipped "
    r"my mind|[Dd]unno)\b"
)


def _forgot_which53(text: str, lexicon: Lexicon) -> None:
    """Session 53: 'Did P ask for X or Y? I can't remember.' refused naming both readings."""
    if "?" not in text:
        return
    m = _FORGOT_WHICH53.match(text)
    if m is None:
        return
    a, b = _ids(m["a"], lexicon, "object"), _ids(m["b"], lexicon, "object")
    if len(a) != 1 or len(b) != 1 or a == b:
        return
    (x,), (y,) = a, b
    raise GroundingError(
        f"{m['q']!r}: the speaker does not know which is meant, {m['a']} ({x}) or {m['b']} ({y}); "
        "say which"
    )


# -- a question whether someone wants a thing, closing the text after a clause about them ("Bob's
# hungry, so does he want the apple?", "Bob, does he want the apple?"; 12c's fuzz: read apple>B
# on main, while "Bob is tired. Does he want the apple?" is refused as a question): it only asks
_DOES_HE53 = re.compile(
    r"(?:^|[,;:]\s*)(?:(?:so|and|but|then)\s+)?(?P<said>(?:does|did|do|would|will) (?:he|she|"
    r"they) (?:still |really |even |actually )?(?:want|need|fancy|like|mind|wish for|care for)\b"
    r"[^?.!;]*\?)\s*$",
    _F,
)


def _does_he53(text: str, lexicon: Lexicon) -> None:
    """Session 53: refuse a closing 'so does he want the apple?' (above)."""
    if "?" not in text:
        return
    m = _DOES_HE53.search(text)
    if m is None:
        return
    raise GroundingError(
        f"{m['said']!r} asks whether it is wanted: it asks for nothing; say 'give …' to have it "
        "handed over"
    )


# the normaliser's first rewrites (wired into normalise._STEPS19, before the session-52 ones)
_STEPS53_FIRST: tuple[Callable[[str, Lexicon], str], ...] = (
    # the rewrites inside a clause first, then those of a text's opening (anchored there)
    _whenever53,
    _thanks_two53,
    _dibs53,
    _throat53,
    _as_for53,
    _swing_by53,
    _about_it53,
    _since_ended53,
    _pron_after53,
    _wants_there53,
    _ramble53,
    _ask_me53,
    _cleft53,
    _over_there53,
    _clutter53,
    _between53,
    _stack_of53,
    _doing_and53,
)
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-52 ones)
_STEPS53: tuple[Callable[[str, Lexicon], str], ...] = ()
# refusals asked of the text before it is read (offline._parse, after the session-52 ones)
REFUSE53: tuple[Callable[[str, Lexicon], None], ...] = (_forgot_which53, _does_he53)
# checks of the whole instruction's reading (offline.parse_instruction, after the session-52 ones)
CHECK53: tuple[Callable[[str, Node, Lexicon], None], ...] = ()
