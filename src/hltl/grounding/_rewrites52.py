"""The grounder's rules of session 52, engineer 12 (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _ids, _names, _only_person
from hltl.grounding._rewrites44 import _agrees44
from hltl.grounding._rewrites45 import _read_for
from hltl.grounding._rewrites50 import _cut50
from hltl.grounding.lexicon import Lexicon
from hltl.grounding.tree import Node

# -- session 52 (engineer 12): blind50's refusals of politeness and fillers, wants and needs,
# pronouns and ellipsis, questions and lower case, each read as a family. Every rule rewrites to
# words the grammar (or an older rule) already reads, and keeps the rewrite only when it reads.

# a person's name as the corpus says them ('Bob', 'Person A', 'Mrs Khan', 'person b')
_P52 = r"(?:[Pp]erson [A-Za-z]|[A-Z]\w*(?: [A-Z]\w*)?)"


# -- politeness and fillers ------------------------------------------------------------------------

# -- 'Would you (be a star and) let P have …?' ("Would you be a star and let Person B have the
# bottle and the cup?"): a request, said 'Could you let P have …?' (session 26's _questions26
# reads 'could you let'; it read 'would you let P have' as 'would P have', a question only)
_WOULD_LET52 = re.compile(
    r"^(?P<q>(?:[Ww]ould|[Ww]ill|[Cc]ould|[Cc]an) you (?:please |kindly |just )?)(?:be (?:a |an "
    r"|such a |such an )?(?:star|angel|dear|love|darling|treasure|gem|sweetheart|pet|diamond|"
    r"sweetie|doll|lamb|duck) and (?:please |kindly |just )?)?(?=let\b)"
)


def _would_let52(text: str, lexicon: Lexicon) -> str:
    """Session 52: 'Would you (be a star and) let P have …?' read as 'Could you let P have …?'."""
    if "let " not in text:
        return text
    m = _WOULD_LET52.match(text)
    if m is None or (m["q"].lower().startswith("could") and m.end() == m.end("q")):
        return text
    return _cut50(text, 0, m.end(), "Could you ", lexicon)


# -- 'Pardon me butting in,' opening a request ("Pardon me butting in, the chips to Person A
# please"): said 'Sorry for butting in,' (read: session 20's courtesies)
_BUTTING_IN52 = re.compile(
    r"^(?:(?:[Oo]h|[Uu]m|[Ee]r|[Ss]o),? )?(?:[Pp]ardon|[Ee]xcuse|[Ff]orgive) (?:me|us)(?: for)? "
    r"(?:butting|barging|cutting|chipping|jumping|bursting|crashing|breezing) in(?= *,)"
)


def _butting_in52(text: str, lexicon: Lexicon) -> str:
    """Session 52: an opening 'Pardon me butting in' read as 'Sorry for butting in'."""
    if " in" not in text:
        return text
    m = _BUTTING_IN52.match(text)
    if m is None:
        return text
    return _cut50(text, 0, m.end(), "Sorry for butting in", lexicon)


# -- 'no rush whatsoever' / 'no hurry at all' closing a request: said 'no rush' (read)
_WHATSOEVER52 = re.compile(
    r"\bno (?:rush|hurry|panic|pressure)(?P<w> (?:whatsoever|at all|of any kind|in the slightest|"
    r"in the least|whatever))(?=\s*[.!]?$)",
    _F,
)


def _whatsoever52(text: str, lexicon: Lexicon) -> str:
    """Session 52: a closing 'no rush whatsoever' read as 'no rush'."""
    if "no " not in text:
        return text
    m = _WHATSOEVER52.search(text)
    if m is None:
        return text
    return _cut50(text, m.start("w"), m.end("w"), "", lexicon)


# -- 'just one teeny thing,' before a request ("Sorry, just one teeny thing, Person B's after the
# bottle"): said 'one little thing' (read)
_TEENY52 = re.compile(
    r"\bone (?P<a>teeny|teensy|tiny|wee|weeny|teeny[- ]weeny|teensy[- ]weensy|itsy[- ]bitsy|"
    r"itty[- ]bitty|minor|minuscule|titchy|tiddly|weeny little|tiny little|teeny little|wee "
    r"little) (?=(?:thing|favour|request|job|ask)\b)",
    _F,
)


def _teeny52(text: str, lexicon: Lexicon) -> str:
    """Session 52: 'one teeny thing' read as 'one little thing'."""
    if "one " not in text:
        return text
    m = _TEENY52.search(text)
    if m is None:
        return text
    return _cut50(text, m.start("a"), m.end("a"), "little", lexicon)


# -- 'No pressure (, mate), but' opening a want ("No pressure, mate, but Tom could do with the work
# gloves"): that it need not be hurried, taken off (read as the want alone)
_NO_PRESSURE52 = re.compile(
    r"^(?:(?:[Oo]h|[Uu]m|[Ee]r|[Ss]o|[Ll]ook|[Rr]ight),? )?[Nn]o (?:pressure|rush|hurry|stress|"
    r"worries)(?:,? (?P<voc>[a-z]+))?,? but\s+"
)
_VOCATIVES52 = frozenset(
    (
        "mate", "love", "pal", "dear", "chum", "buddy", "friend", "pet", "hun", "duck", "sweetie",
        "darling", "lad", "lass", "bud", "fella", "boss", "chief", "kiddo", "sunshine", "petal",
        "honey", "man", "dude", "bro", "cock", "flower", "treasure", "my dear", "my love",
    )
)  # fmt: skip


def _no_pressure52(text: str, lexicon: Lexicon) -> str:
    """Session 52: an opening 'No pressure (, mate), but' taken off."""
    if " but" not in text:
        return text
    m = _NO_PRESSURE52.match(text)
    if m is None or (m["voc"] and m["voc"] not in _VOCATIVES52):
        return text
    return _cut50(text, 0, m.end(), "", lexicon)


# -- "P's got his hands full" as a sentence or clause of its own after a request ("… getting the
# teddy to Lily? Grandad's got his hands full."): why the speaker asks, taken off when it names
# one person only and the pronoun may be them
_HANDS_FULL52 = re.compile(
    r"(?P<lead>(?:[.?!;]|,)\s*|\s+(?:as|since|because|cos|'cause)\s+)(?P<p>" + _P52 + r")(?:'s "
    r"got|'s| has got| has) (?P<pron>his|her|their) hands (?:full|tied)(?: (?:at the moment|"
    r"right now|just now|now|today))?(?P<end>\s*[.!]?)$"
)


def _hands_full52(text: str, lexicon: Lexicon) -> str:
    """Session 52: a closing "P's got his hands full" taken off."""
    if " hands " not in text:
        return text
    m = _HANDS_FULL52.search(text)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    (pid,) = _ids(m["p"], lexicon)
    if not _agrees44(pid, m["pron"], lexicon):
        return text
    stop = m["lead"].strip()[:1]
    out = text[: m.start()] + (stop if stop in ".?!" else m["end"])
    return _read_for(out, text, None, lexicon)


# -- wants and needs -------------------------------------------------------------------------------

# a want said before a rule's words (who wants what)
_WANTS52 = re.compile(
    r"\b(?:needs?|wants?|could do with|(?:'s|is) after|asked for|(?:'s|is) asking for|(?:'s|is|"
    r"are) waiting for|(?:has|'s got|has got) a (?:[a-z]+ )?(?:fancy|craving|hankering|yen|"
    r"thirst|hunger|longing) for|would like|'d like|would love|'d love|fancies|needed|wanted)\b",
    _F,
)


# -- ', whereas P …' joining two people's wants ("Person A has a real fancy for the apple today,
# whereas Person B could murder the chips"): said ', and P …' (read)
_WHEREAS52 = re.compile(r"(?P<w>,?\s*whereas) (?=(?P<p>" + _P52 + r")\b)")


def _whereas52(text: str, lexicon: Lexicon) -> str:
    """Session 52: ', whereas P …' after a want read as ', and P …'."""
    if "whereas" not in text:
        return text
    m = _WHEREAS52.search(text)
    if m is None or not _WANTS52.search(text[: m.start()]) or not _only_person(m["p"], lexicon):
        return text
    return _cut50(text, m.start("w"), m.end("w"), ", and", lexicon)


# -- "P's short of X" ("Lena's short of tongs and a white plate"): a want, said 'P needs X' (read;
# session 51's _short_a51 reads "P's short a glue stick")
_SHORT_OF52 = re.compile(
    r"(?P<p>" + _P52 + r")(?:'s| is| was)? (?:a (?:bit|little|tad) |rather |running |a touch "
    r")?short of (?=(?:the |a |an |some |any |her |his |their )?[a-z])"
)


def _short_of52(text: str, lexicon: Lexicon) -> str:
    """Session 52: "P's short of X" read as 'P needs X'."""
    if "short of" not in text:
        return text
    m = _SHORT_OF52.search(text)
    if m is None or " was" in m.group() or not _only_person(m["p"], lexicon):
        return text
    return _cut50(text, m.start(), m.end(), f"{m['p']} needs ", lexicon)


# -- 'P needs the X to have a look behind the bench' ("Jess needs the torch to have a look behind
# the bench"): what the person wants it for, a look at something, taken off
_TO_LOOK52 = re.compile(
    r"(?P<cut>,?\s+(?:so as |in order )?to (?:(?:have|take|get) a (?:proper |quick |good |little "
    r"|closer )?(?:look|peek|peep|squint|gander|shufti|butcher's|nosey|nose|rummage|poke "
    r"about|poke around)|look|peer|peek|see|check|poke about|poke around|rummage|search|root "
    r"about|root around)(?: (?:at|behind|under|underneath|beneath|in|inside|into|round|around|"
    r"for|through|up|down|over|at the back of|in behind) [^,.;:!?]+?)?)(?=\s*[.!]?$)"
)


def _to_look52(text: str, lexicon: Lexicon) -> str:
    """Session 52: a closing 'to have a look behind the bench' after a want taken off."""
    if " to " not in text:
        return text
    m = _TO_LOOK52.search(text)
    if m is None or not _WANTS52.search(text[: m.start()]):
        return text
    return _cut50(text, m.start("cut"), m.end("cut"), "", lexicon)


# -- pronouns and ellipsis ----------------------------------------------------------------------

# -- 'his colleague, P' ("the chips can go to his colleague, Person A"): the one named after the
# comma is who is meant; the relation taken off (the pronoun is then not asked about)
_COLLEAGUE52 = re.compile(
    r"\b(?:his|her|their) (?:(?:good|old|best|dear|new|fellow) )?(?:colleague|friend|mate|pal|"
    r"partner|neighbour|neighbor|workmate|buddy|chum|co-worker|coworker|teammate|classmate|"
    r"roommate|flatmate|sister|brother|cousin|boss|assistant|deputy|sidekick|oppo|opposite "
    r"number|other half),\s*(?P<p>" + _P52 + r")(?=\s*(?:[,.;!?]|$))"
)


def _colleague52(text: str, lexicon: Lexicon) -> str:
    """Session 52: 'his colleague, P' read as 'P'."""
    if ", " not in text:
        return text
    m = _COLLEAGUE52.search(text)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    # the one the pronoun is said of is another person, named before
    before = _ids(text[: m.start()], lexicon, "human")
    (pid,) = _ids(m["p"], lexicon)
    if not before - {pid}:
        return text
    return _cut50(text, m.start(), m.end(), m["p"], lexicon)


# -- "P's been shivering since they opened the window, so …": since when, an event that is over,
# taken off (the state and its 'so' read)
_SINCE_EVENT52 = re.compile(
    r"(?P<p>" + _P52 + r")(?:'s| has) been (?P<v>[a-z]+ing|cold|hungry|thirsty|grumpy|tired|cross|"
    r"bored|poorly|restless|sleepy|peckish|parched|freezing|starving)(?: (?:a lot|all day|all "
    r"morning|for ages))?(?P<cut> (?:ever )?since (?:they|someone|somebody|we|you|I|the [a-z]+(?: "
    r"[a-z]+)?) [a-z]+(?: [^,.;:!?]*?)?)(?=,\s*(?:so|and so|which is why)\b)"
)


def _since_event52(text: str, lexicon: Lexicon) -> str:
    """Session 52: "P's been shivering since they opened the window, so …" without 'since …'."""
    if "since " not in text:
        return text
    m = _SINCE_EVENT52.search(text)
    if m is None or not _only_person(m["p"], lexicon) or _names(m["cut"], lexicon):
        return text
    return _cut50(text, m.start("cut"), m.end("cut"), "", lexicon)


# -- lower case ------------------------------------------------------------------------------------

# -- '<pastime> starts in ten so …' opening a want ("tchoukball starts in ten so person a needs her
# bottle now"): why the want is now, taken off when it names nothing of the scene
_STARTS_IN52 = re.compile(
    r"^(?:[Hh]is |[Hh]er |[Tt]heir |[Tt]he )?(?P<w>[A-Za-z]+(?: [a-z]+)?) (?:starts|begins|kicks "
    r"off|is on) in (?:ten|five|fifteen|twenty|thirty|a few|a couple of|two|three|[0-9]+)(?: "
    r"(?:minutes|mins|min))?,? (?:so|and)\s+"
)


def _starts_in52(text: str, lexicon: Lexicon) -> str:
    """Session 52: an opening '<pastime> starts in ten so' taken off."""
    if " in " not in text:
        return text
    m = _STARTS_IN52.match(text)
    if m is None or _names(m["w"], lexicon) or not _WANTS52.search(text[m.end() :]):
        return text
    return _cut50(text, 0, m.end(), "", lexicon)


# -- questions -------------------------------------------------------------------------------------

# -- "P's asking if he can borrow the X" ("Kofi's asking if he can borrow the big spanner, would
# you take it over?"): P's want, said 'P wants to borrow the X' (read) when the pronoun may be P
_ASKING_IF52 = re.compile(
    r"^(?P<p>" + _P52 + r")(?:'s| is)? (?:asking|asked|wondering) (?:if|"
    r"whether) (?P<pron>he|she|they) (?:can|could|might|may) (?P<v>borrow|have|use|get|take) "
)


def _asking_if52(text: str, lexicon: Lexicon) -> str:
    """Session 52: "P's asking if he can borrow the X" read as 'P wants to borrow the X'."""
    if " if " not in text and "whether" not in text:
        return text
    m = _ASKING_IF52.match(text)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    (pid,) = _ids(m["p"], lexicon)
    if not _agrees44(pid, m["pron"], lexicon):
        return text
    verb = "to borrow" if m["v"] == "borrow" else "to use" if m["v"] == "use" else ""
    put = f"{m['p']} wants {verb} ".replace("  ", " ")
    return _read_for(put + text[m.end() :], text, pid, lexicon)


# -- refused (12c's fuzz) -------------------------------------------------------------------------

# -- 'Should / Must the X go to P?' ("Should the apple go on the shelf?", "Must the apple go to
# Bob?", "Should you give Bob the apple?", "Should the red mug go to Alice or Bob?"): a question
# that only asks what ought to happen, as "Should Bob get the apple?" is (refused)
_SHOULD52 = re.compile(
    r"^(?P<said>(?:Should|Must|Ought) (?:the|that|this|these|those|you|u|we|I|it|they|he|she|"
    r"one|either|both|a|an|my|his|her|their|our)\b[^?,;:.]{1,80}?)(?:,\s*(?:do you think|what do "
    r"you (?:think|reckon)|or not))?\s*\?\s*$",
    _F,
)


def _should52(text: str, lexicon: Lexicon) -> None:
    """Session 52: refuse 'Should the X go to P?' (above)."""
    if not text[:6].lower().startswith(("should", "must ", "ought ")) or "?" not in text:
        return
    m = _SHOULD52.match(text)
    if m is None:
        return
    raise GroundingError(
        f"{m['said']!r} asks what ought to happen: it asks for nothing; say 'give …' or 'put …'"
    )


# -- 'P had asked for / had wanted X.' said alone ("Bob had asked for one of the mugs.", "Alice had
# wanted the apple."): a want before some time past, which may be over; refused as session 51's
# 'had been needing' is ("Zoe had asked for the glue, but now she'd rather have the scissors."
# says what she wants now and reads)
_HAD_WANTED52 = re.compile(
    r"^(?P<said>" + _P52 + r"(?: had|'d) (?:asked for|wanted|requested|been after|been wanting|"
    r"needed|been needing|fancied)) [^,;:.!?]+[.!]?$"
)


def _had_wanted52(text: str, lexicon: Lexicon) -> None:
    """Session 52: refuse 'P had asked for X.' said alone (above)."""
    if " had " not in text and "'d " not in text:
        return
    m = _HAD_WANTED52.match(text.strip())
    if m is None or not _only_person(m["said"].rsplit(" had", 1)[0].split("'d ")[0], lexicon):
        return
    raise GroundingError(
        f"{m['said']!r} says what was wanted before: it may be over; say 'give …' for what is "
        "wanted now"
    )


# the normaliser's first rewrites (wired into normalise._STEPS19, before the session-51 ones)
_STEPS52_FIRST: tuple[Callable[[str, Lexicon], str], ...] = (
    _would_let52,
    _butting_in52,
    _whatsoever52,
    _teeny52,
    _no_pressure52,
    _hands_full52,
    _whereas52,
    _short_of52,
    _to_look52,
    _colleague52,
    _since_event52,
    _starts_in52,
    _asking_if52,
)
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-51 ones)
_STEPS52: tuple[Callable[[str, Lexicon], str], ...] = ()
# refusals asked of the text before it is read (offline._parse, after the session-51 ones)
REFUSE52: tuple[Callable[[str, Lexicon], None], ...] = (_should52, _had_wanted52)
# checks of the whole instruction's reading (offline.parse_instruction, after the session-51 ones)
CHECK52: tuple[Callable[[str, Node, Lexicon], None], ...] = ()
