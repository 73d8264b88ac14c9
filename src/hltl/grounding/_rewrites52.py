"""The grounder's rules of session 52, engineer 12 (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _ids, _names, _only_person, _reading
from hltl.grounding._normalise5 import _STEPS37
from hltl.grounding._rewrites44 import _agrees44
from hltl.grounding._rewrites45 import _read_for
from hltl.grounding._rewrites47 import _owned_occasion47
from hltl.grounding._rewrites50 import _cut50
from hltl.grounding.lexicon import Lexicon
from hltl.grounding.tree import Node, tasks

# -- session 52 (engineer 12): blind50's refusals of politeness and fillers, wants and needs,
# pronouns and ellipsis, questions and lower case, each read as a family. Every rule rewrites to
# words the grammar (or an older rule) already reads, and keeps the rewrite only when it reads.

# a person's name as the corpus says them ('Bob', 'Person A', 'Mrs Khan', 'person b')
_P52 = r"(?:[Pp]erson [A-Za-z]|[A-Z]\w*(?: [A-Z]\w*)?)"


def _person_opening52(text: str, lexicon: Lexicon) -> str | None:
    """The words opening ``text`` (one to three, the longest) that name one person of the scene
    and nothing else, however cased ('lena', 'Mrs Khan', 'person b'); None if none do."""
    words = re.findall(r"[A-Za-z]+", text.split("'")[0])[:3]
    for k in (3, 2, 1):
        if len(words) >= k and _only_person(" ".join(words[:k]), lexicon):
            return " ".join(words[:k])
    return None


# what a rewrite of these rules may not leave in what it reads: a rule takes off words that made
# main refuse the sentence, and must not unmask a refusal's reason elsewhere in it (12c's fuzz:
# "…, he's had one", "…, Bob's done it", "…, I said no", "…, is he?", "… tomorrow", "it's in his
# bag", "let Bob keep …", a past or would-be want, a holding)
_UNSAFE52 = re.compile(
    r"\b(?:had|has had|'s had|'d had|got|gotten|has got|'s got|'ve got|kept|keep|keeps|wanted|"
    r"needed|would want|would need|were for|was for|said no|tomorrow|tonight|later|yesterday|"
    r"next week|next month|already)\b|\bhas (?:the|his|her|their|it|them|one|some)\b|"
    r"(?:'s|has|have|'ve) (?:done|sorted|seen to) (?:it|that|them)\b|\bdid (?:it|that)\b|"
    r"\b(?:in|on) (?:his|her|their) (?:bag|pocket|lap|hand)\b|"
    # session 53 (12c's fuzz): something eaten or taken, a would-be want, someone gone, and a
    # question whose subject is he / she / they ("Poor Bob, does he want the apple?")
    r"\b(?:took|ate|(?:has|'s|have|'ve|had|'d) eaten|might (?:want|need|like|fancy)|may (?:want|"
    r"need|like|fancy)|(?:'s|has|is) (?:gone|left)(?! off\b)|(?:'s|is) off now)\b|"
    r"\b(?:does|do|did|is|was|has|can|could|will|would|should)\s+(?:he|she|they)\b[^.!?]*\?|"
    r",\s*(?:is|isn't|are|aren't|can|can't|does|doesn't|did|didn't|has|hasn't|will|won't|would|"
    r"wouldn't|was|wasn't|could|couldn't|should|shall)\s+(?:he|she|they|it)\s*\?",
    _F,
)

# a time the words a rule takes off may not hold ("… to have a look at the bottle tomorrow")
_WHEN52 = re.compile(
    r"\b(?:tomorrow|tonight|later|yesterday|next (?:week|month|year|time)|this evening|on "
    r"(?:mon|tues|wednes|thurs|fri|satur|sun)day)\b",
    _F,
)


# a time a purpose taken off may not hold (12c, session 53: "Bob needs the cup to have a look at
# the bottle in an hour." had read cup>B; main refuses "Bob needs the cup in an hour.")
_WHEN_PURPOSE52 = re.compile(
    r"\b(?:in (?:an?|one|two|three|four|five|ten|fifteen|twenty|thirty|a few|a couple of|[0-9]+) "
    r"(?:minutes?|mins?|hours?|hrs?|secs?|seconds?|bit|while|tick|jiffy|moment)|in a bit|after "
    r"(?:lunch|breakfast|brekkie|dinner|tea|supper|school|work|class|the [a-z]+)|at (?:[0-9]+|"
    r"one|two|three|four|five|six|seven|eight|nine|ten|eleven|twelve|noon|midnight|half [a-z]+|"
    r"quarter [a-z]+)|this (?:morning|afternoon|evening)|first thing|soon|shortly|next "
    r"(?:period|lesson|class|week|month|year|time|shift)|by (?:[0-9]+|noon|six|five|ten|"
    r"tonight|then)|tomorrow|tonight|later|yesterday|on (?:mon|tues|wednes|thurs|fri|satur|"
    r"sun)day)\b",
    _F,
)


def _cut52(text: str, start: int, end: int, put: str, lexicon: Lexicon) -> str:
    """``text`` with ``text[start:end]`` said as ``put`` (first letter upper-cased), when that
    reads, leaves nothing of _UNSAFE52 and takes off no time (_WHEN52); else ``text``."""
    out = f"{text[:start]}{put}{text[end:]}"
    if _UNSAFE52.search(out) or _WHEN52.search(text[start:end]):
        return text
    return _cut50(text, start, end, put, lexicon)


def _read52(out: str, text: str, pid: str | None, lexicon: Lexicon) -> str:
    """``out`` when it reads (with ``pid``, handing things to that person only) and holds nothing
    of _UNSAFE52; else ``text``."""
    if _UNSAFE52.search(out):
        return text
    return _read_for(out, text, pid, lexicon)


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
    return _cut52(text, 0, m.end(), "Could you ", lexicon)


# -- 'Pardon me butting in,' opening a request ("Pardon me butting in, the chips to Person A
# please"): said 'Sorry for butting in,' (read: session 20's courtesies)
_BUTTING_IN52 = re.compile(
    r"^(?:(?:[Oo]h|[Uu]m|[Ee]r|[Ss]o),? )?(?:[Pp]ardon|[Ee]xcuse|[Ff]orgive) (?:me|us) "
    r"(?:butting|barging|cutting|chipping|jumping|bursting|crashing|breezing) in(?= *,)"
)


def _butting_in52(text: str, lexicon: Lexicon) -> str:
    """Session 52: an opening 'Pardon me butting in' read as 'Sorry for butting in'."""
    if " in" not in text:
        return text
    m = _BUTTING_IN52.match(text)
    if m is None:
        return text
    return _cut52(text, 0, m.end(), "Sorry for butting in", lexicon)


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
    return _cut52(text, m.start("w"), m.end("w"), "", lexicon)


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
    return _cut52(text, m.start("a"), m.end("a"), "little", lexicon)


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
    return _cut52(text, 0, m.end(), "", lexicon)


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
    return _read52(out, text, None, lexicon)


# -- wants and needs -------------------------------------------------------------------------------

# a want said before a rule's words (who wants what)
_WANTS52 = re.compile(
    r"\b(?:needs?|wants?|could do with|(?:'s|is) after|asked for|(?:'s|is) asking for|(?:'s|is|"
    r"are|'s been|has been|have been|been) (?:waiting for|after|waiting on)|(?:has|'s got|has "
    r"got) a (?:[a-z]+ )?(?:fancy|craving|hankering|yen|thirst|hunger|longing) for|would "
    r"(?:quite |really |so |very much )?like|'d (?:quite |really |so )?like|would love|'d "
    r"love|fancies)\b",
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
    return _cut52(text, m.start("w"), m.end("w"), ", and", lexicon)


# -- "P's short of X" ("Lena's short of tongs and a white plate"): a want, said 'P needs X' (read;
# session 51's _short_a51 reads "P's short a glue stick")
_SHORT_OF52 = re.compile(
    r"(?P<p>" + _P52 + r")(?:'s| is| was)? (?:a (?:bit|little|tad) |rather |running |a touch "
    r")?short of (?!a |an )(?=(?:the |some |any |her |his |their )?[a-z])"
)


def _short_of52(text: str, lexicon: Lexicon) -> str:
    """Session 52: "P's short of X" read as 'P needs X'."""
    if "short of" not in text:
        return text
    m = _SHORT_OF52.search(text)
    if m is None or " was" in m.group() or not _only_person(m["p"], lexicon):
        return text
    return _cut52(text, m.start(), m.end(), f"{m['p']} needs ", lexicon)


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
    if m is None or not _WANTS52.search(text[: m.start()]) or _WHEN_PURPOSE52.search(m["cut"]):
        return text
    return _cut52(text, m.start("cut"), m.end("cut"), "", lexicon)


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
    return _cut52(text, m.start(), m.end(), m["p"], lexicon)


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
    return _cut52(text, m.start("cut"), m.end("cut"), "", lexicon)


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
    return _cut52(text, 0, m.end(), "", lexicon)


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
    return _read52(put + text[m.end() :], text, pid, lexicon)


# -- batch 2 ---------------------------------------------------------------------------------------

# -- "he'll take the apple off your hands" ("Oh, and he'll take the apple off your hands as
# well."): the taking is P's want, said 'take the apple' (read)
_OFF_YOUR_HANDS52 = re.compile(
    r"\b(?P<v>take|have|relieve you of) (?P<x>(?:the|that|this|those|these) [a-z]+(?: [a-z]+)?|it|"
    r"them)(?P<cut> off (?:your|ya|yer|you're) hands)\b"
)


def _off_your_hands52(text: str, lexicon: Lexicon) -> str:
    """Session 52: 'take the X off your hands' read as 'take the X'."""
    if " hands" not in text:
        return text
    m = _OFF_YOUR_HANDS52.search(text)
    if m is None or m["v"] != "take":
        return text
    return _cut52(text, m.start("cut"), m.end("cut"), "", lexicon)


# -- 'poor (old) P' opening a want ("poor person b's been hanging about for his chips for ages"):
# the speaker's pity, taken off
_POOR52 = re.compile(r"^(?:[Pp]oor old|[Bb]less old|[Pp]oor|[Bb]less) ")


def _poor52(text: str, lexicon: Lexicon) -> str:
    """Session 52: an opening 'poor (old) P' read as 'P'."""
    if text[:4].lower() not in ("poor", "bles"):
        return text
    m = _POOR52.match(text)
    if m is None or _person_opening52(text[m.end() :], lexicon) is None:
        return text
    if not _WANTS52.search(text[m.end() :]):
        return text  # ("Poor Marco burnt his thumb, so …" is session 43's)
    return _cut52(text, 0, m.end(), "", lexicon)


# -- "P's been hanging about for his chips" ("… kicking her heels waiting for …"): waiting for
# them, said "P's been waiting for" (read)
_HANGING_ABOUT52 = re.compile(
    r"\b(?:hanging|hangin'?|hovering|loitering|lurking|kicking (?:his|her|their) heels|"
    r"twiddling (?:his|her|their) thumbs|sat|sitting|standing|stood) (?:about|around|round|on)"
    r"(?: (?:waiting|here|there))? (?=for\b)"
)


def _hanging_about52(text: str, lexicon: Lexicon) -> str:
    """Session 52: 'hanging about for' read as 'waiting for'."""
    if " for " not in text:
        return text
    m = _HANGING_ABOUT52.search(text)
    if m is None:
        return text
    return _cut52(text, m.start(), m.end(), "waiting ", lexicon)


# -- 'hunting high and low for the X' ("Kofi's been hunting high and low for the hammer all
# morning"): looking for it, said "been looking for" (read)
_HIGH_AND_LOW52 = re.compile(
    r"\b(?:hunting|searching|looking|rummaging|scouring the place|turning the place upside down|"
    r"turning everything upside down|tearing the place apart|ferreting about|ferreting around)"
    r"(?: high and low| everywhere| all over| all over the place| far and wide)? "
    r"(?P<for>(?:looking )?for)\b"
)


def _high_and_low52(text: str, lexicon: Lexicon) -> str:
    """Session 52: 'hunting high and low for' read as 'looking for'."""
    if " for " not in text:
        return text
    m = _HIGH_AND_LOW52.search(text)
    if m is None or m.group().startswith("looking for"):
        return text
    return _cut52(text, m.start(), m.end(), "looking for", lexicon)


# -- "… i've got my hands full" closing a request ("reckon you could hand person a her bottle i've
# got my hands full"): why the speaker asks, taken off
_MY_HANDS52 = re.compile(
    r"(?:[,.;:!?]\s*|\s+(?:as|since|because|cos|'cause|coz)\s+|\s+)(?:[Ii]'ve got|[Ii] have got|"
    r"[Ii] have|[Ii]'ve|[Ii]ve got|[Ii] got|[Ii]'m|[Ii]m|[Ii] am) (?:got )?(?:my hands (?:full|"
    r"tied)|(?:a bit |rather |really )?(?:busy|swamped|snowed under|up to my eyes))(?: (?:at the "
    r"moment|right now|just now|now|here|today))?(?P<end>\s*[.!]?)$"
)


def _my_hands52(text: str, lexicon: Lexicon) -> str:
    """Session 52: a closing "i've got my hands full" taken off."""
    if "hands" not in text and "busy" not in text and "snowed" not in text and "eyes" not in text:
        return text
    m = _MY_HANDS52.search(text)
    if m is None or m.start() == 0:
        return text
    return _cut52(text, m.start(), m.end(), m["end"], lexicon)


# -- 'P's asked for the X to do his silly voices' ("grandad's asked for the teddy to do his silly
# voices"): what the person wants it for, their own doing, taken off when it names nothing of the
# scene and the pronoun may be the one person named
_TO_DO_HIS52 = re.compile(
    r"(?P<cut>,?\s+(?:so as |in order )?to (?:do|play|make|practise|practice|finish|read|sing|"
    r"try|show off|work on|get on with|start|carry on with|keep up) (?P<pron>his|her|their) "
    r"[^,.;:!?]+?)(?=\s*[.!]?$)"
)


def _to_do_his52(text: str, lexicon: Lexicon) -> str:
    """Session 52: a closing 'to do his silly voices' after a want of one person taken off."""
    if " to " not in text:
        return text
    m = _TO_DO_HIS52.search(text)
    if m is None or _names(m["cut"], lexicon) or not _WANTS52.search(text[: m.start()]):
        return text
    if _WHEN_PURPOSE52.search(m["cut"]):
        return text
    people = _ids(text[: m.start()], lexicon, "human")
    if len(people) != 1 or not _agrees44(next(iter(people)), m["pron"], lexicon):
        return text
    return _cut52(text, m.start("cut"), m.end("cut"), "", lexicon)


# -- 'after her gong bath' closing a want of one person ("I reckon Person A would quite like the
# bottle after her gong bath."): a doing of theirs that session 37's list does not hold (a bath,
# a shower, a haircut …), taken off when it names nothing and the pronoun may be the one person
_AFTER_CARE52 = re.compile(
    r"(?P<cut>,?\s+(?:after|following) (?P<pron>his|her|their) (?:[a-z]+ ){0,2}?(?:bath|shower|"
    r"soak|facial|haircut|manicure|pedicure|trim|meditation|dip|sunbathe|snooze|lie-in|lie down|"
    r"lie-down|shave|blow-dry|perm|wax|scrub|steam|plunge|bathe|wash)s?)(?=\s*[.!]?$)"
)


def _after_care52(text: str, lexicon: Lexicon) -> str:
    """Session 52: a closing 'after her gong bath' after a want of one person taken off."""
    if "after" not in text and "following" not in text:
        return text
    m = _AFTER_CARE52.search(text)
    if m is None or _names(m["cut"], lexicon) or not _WANTS52.search(text[: m.start()]):
        return text
    people = _ids(text[: m.start()], lexicon, "human")
    if len(people) != 1 or not _agrees44(next(iter(people)), m["pron"], lexicon):
        return text
    return _cut52(text, m.start("cut"), m.end("cut"), "", lexicon)


# -- 'Would you leave the X ready on S (for lunchtime)?' ("Would you leave the bib ready on the
# high chair for lunchtime?"): that it be ready is what a placing does; said 'leave the X on S'
# and a meal it is ready for taken off (read: "Put the bib on the high chair for lunchtime.")
_READY_ON52 = re.compile(
    r"\b(?P<v>leave|put|set|have|get|lay|pop|place)(?P<x> (?:the|that|this|those|these) [a-z]+(?: "
    r"[a-z]+)?)(?P<ready> (?:all )?(?:ready|set out|ready and waiting|out ready|laid out))(?= "
    r"(?:on|in|onto|into|by|at) )"
)
_FOR_MEAL52 = re.compile(
    r"(?P<cut> (?:for|ready for|in time for) (?:lunch|lunchtime|dinner|dinnertime|tea|teatime|"
    r"breakfast|brekkie|supper|snack time|bedtime|bath time|nap time))(?=\s*\?\s*$)"
)


def _ready_on52(text: str, lexicon: Lexicon) -> str:
    """Session 52: 'leave the X ready on S (for lunchtime)?' read as 'leave the X on S?'."""
    if "ready" not in text and "set out" not in text and "laid out" not in text:
        return text
    m = _READY_ON52.search(text)
    if m is None:
        return text
    out = f"{text[: m.start('ready')]}{text[m.end('ready') :]}"
    meal = _FOR_MEAL52.search(out)
    if meal is not None:
        out = f"{out[: meal.start()]}{out[meal.end() :]}"
    return _read52(out, text, None, lexicon)


# -- "he's off on a bothy trip so person b wants …" (a pronoun said before the one person it may
# be): why the person wants it, taken off when it names nothing and the pronoun may be only the
# person named just after 'so'
_CATAPHOR52 = re.compile(
    r"^(?P<pron>[Hh]e|[Ss]he)(?:'s| is|s) (?:off|away|going|heading|out|just back|back) "
    r"(?P<w>[^,.;:!?]{3,60}?),? (?:so|and so) "
)


def _cataphor52(text: str, lexicon: Lexicon) -> str:
    """Session 52: an opening "he's off on a trip so P wants …" read as 'P wants …'."""
    if not text[:3].lower().startswith(("he", "she")):
        return text
    m = _CATAPHOR52.match(text)
    if m is None or _names(m["w"], lexicon):
        return text
    rest = text[m.end() :]
    who = _person_opening52(rest, lexicon)
    if who is None or not _WANTS52.search(rest) or len(_ids(rest, lexicon, "human")) != 1:
        return text
    (pid,) = _ids(who, lexicon)
    if not _agrees44(pid, m["pron"], lexicon):
        return text
    # no one else of the scene the pronoun may be
    others = [h.id for h in lexicon.scene.humans if h.id != pid]
    if any(_agrees44(o, m["pron"], lexicon) for o in others):
        return text
    return _cut52(text, 0, m.end(), "", lexicon)


# -- batch 3 ---------------------------------------------------------------------------------------

# -- 'We need the X sat on S' ("We need the small box sat on the pallet before the lorry pulls
# in."): where it is to be, said 'the X on S' (read; 'sitting' / 'standing' / 'stood' are the
# lexicon's posture verbs, session 40, and "I'd like the cup left on the shelf." stays refused)
_SAT_ON52 = re.compile(
    r"\b(?:need|needs|want|wants|'d like|would like|like|have|get|got)(?P<x> (?:the|that|this|"
    r"those|these) [a-z]+(?: [a-z]+)?)(?P<sat> (?:sat|perched|parked|plonked|placed|put|popped))"
    r"(?= (?:on|in|onto|into|by|at|inside|upon) )"
)


def _sat_on52(text: str, lexicon: Lexicon) -> str:
    """Session 52: 'need the X sat on S' read as 'need the X on S'."""
    if " on " not in text and " in " not in text and " by " not in text and " at " not in text:
        return text
    m = _SAT_ON52.search(text)
    if m is None:
        return text
    return _cut52(text, m.start("sat"), m.end("sat"), "", lexicon)


# -- 'before P's round' closing a request ("Is it possible to get the spoon onto the tray before
# Dana's round?"): by when, a doing of a person of the scene, taken off ("… before her round"
# reads)
_BEFORE_PS52 = re.compile(
    r"(?P<cut>,?\s+(?:before|ahead of|in time for) (?P<p>" + _P52 + r")'s (?P<w>[a-z]+(?: "
    r"[a-z]+)?))(?=\s*[?.!]?$)"
)


def _before_ps52(text: str, lexicon: Lexicon) -> str:
    """Session 52: a closing "before P's round" taken off."""
    if "'s " not in text:
        return text
    m = _BEFORE_PS52.search(text)
    if m is None or not _only_person(m["p"], lexicon) or _names(m["w"], lexicon):
        return text
    if _owned_occasion47(text, lexicon) != text:
        return text  # (session 47's: "… before Lily's nap")
    return _cut52(text, m.start("cut"), m.end("cut"), "", lexicon)


# -- 'when you've done that' between two requests ("start with the cup for person a and when
# you've done that the apple's for person b"): said 'when that's done' (read, in order)
_WHEN_DONE52 = re.compile(
    r"\b(?:when|once|after) (?:you've|you have|youve|you're|you are|youre) (?:done|finished|"
    r"sorted|done with|finished with|sorted out) (?:that|that one|it|this)\b"
)


def _when_done52(text: str, lexicon: Lexicon) -> str:
    """Session 52: "when you've done that" read as "when that's done"."""
    if "done" not in text and "finished" not in text and "sorted" not in text:
        return text
    m = _WHEN_DONE52.search(text)
    if m is None or not _ids(text[: m.start()], lexicon) or not _ids(text[m.end() :], lexicon):
        return text
    return _cut52(text, m.start(), m.end(), "when that's done", lexicon)


# -- 'Could you do the X for P …?' ("Could you do the bottle for Person A first, and when that's
# done, the chips for Person B?"): a handing over, said 'Could you bring the X for P …?' (read)
_DO_FOR52 = re.compile(
    r"^(?P<q>(?:[Cc]ould|[Ww]ould|[Cc]an|[Ww]ill) you (?:please |kindly |just )?)do(?= (?:the|that|"
    r"this) [a-z]+(?: [a-z]+)? for (?P<p>" + _P52 + r")\b)"
)


def _do_for52(text: str, lexicon: Lexicon) -> str:
    """Session 52: 'Could you do the X for P?' read as 'Could you bring the X for P?'."""
    if " do " not in text:
        return text
    m = _DO_FOR52.match(text)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    if any(step(text, lexicon) != text for step in _STEPS37):
        return text  # (session 37's: "… before anything else, and the bottle for P after?")
    if _ids(text[m.end() :], lexicon, "surface"):
        return text  # 'do the apple on the shelf' is not said to be a placing (s37's near)
    return _cut52(text, 0, m.end(), f"{m['q']}bring", lexicon)


# -- 'P is doing map skills next period, so …' ("Mrs Ortiz is doing map skills next period, so set
# the globe on her desk"): what the person is busy with, said 'P is busy, so' (read)
_DOING_NEXT52 = re.compile(
    r"^(?P<p>" + _P52 + r")(?:'s| is) (?P<w>(?:doing|teaching|running|taking|leading|giving|"
    r"hosting) [^,.;:!?]{3,50}?)(?P<when> (?:next period|next lesson|this afternoon|this "
    r"morning|after lunch|after break|in a bit|in a minute|shortly|soon|later|today))?,? (?=so\b)"
)


def _doing_next52(text: str, lexicon: Lexicon) -> str:
    """Session 52: "P is doing map skills next period, so" read as 'P is busy, so'."""
    if " so " not in text:
        return text
    m = _DOING_NEXT52.match(text)
    if m is None or not _only_person(m["p"], lexicon) or _names(m["w"], lexicon):
        return text
    if m["when"] and m["when"].strip() == "later":
        return text
    return _cut52(text, 0, m.end(), f"{m['p']} is busy, ", lexicon)


# -- a sentence saying someone is clearing a surface, after a placing onto another ("… could the
# stapler go in the box? Priya's clearing the desk for the cryptographer's visit."): why, taken
# off when what is left only places things, none on that surface (session 51's _clear51 reads
# 'P needs the desk clear')
_CLEARING52 = re.compile(
    r"(?<=[.?!])\s+(?P<p>" + _P52 + r"|[Ss]he|[Hh]e|[Tt]hey|We)(?:'s| is|'re| are) (?:clearing|"
    r"tidying|emptying|clearing off|clearing out|sorting out|sorting|wiping down|wiping|"
    r"cleaning|freeing up|making room on) the (?P<s>[a-z]+(?: [a-z]+)?)(?: (?:for|before|by|"
    r"ahead of) [^.!?]+)?[.!]?$"
)


def _clearing52(text: str, lexicon: Lexicon) -> str:
    """Session 52: a closing "P's clearing the desk (for …)." taken off a placing."""
    if "ing the " not in text:
        return text
    m = _CLEARING52.search(text)
    if m is None:
        return text
    if m["p"].lower() not in ("she", "he", "they", "we") and not _only_person(m["p"], lexicon):
        return text
    surfaces = _ids(f"the {m['s']}", lexicon, "surface")
    if not surfaces:
        return text
    out = text[: m.start()]
    read = None if _UNSAFE52.search(out) else _reading(out, lexicon)
    if read is None or any(t.kind != "place" or t.target in surfaces for t in tasks(read)):
        return text
    return out


# -- a sentence saying a group is in at a time, after a placing ("… would you pop the red mug up on
# the shelf? Carol's numerology lot are in at six."): why, taken off when what is left only places
# things
_LOT_IN52 = re.compile(
    r"(?<=[.?!])\s+(?:(?P<p>" + _P52 + r")'s|[Tt]he|[Oo]ur|[Mm]y|[Hh]is|[Hh]er|[Tt]heir) "
    r"(?P<w>(?:[a-z]+ ){0,2})(?:lot|crowd|group|gang|class|folk|people|bunch|party|team|"
    r"club|guests|visitors) (?:are|is|'re|'s|will be|'ll be) (?:in|coming|coming in|coming "
    r"over|here|due|due in|arriving|round|over)(?: (?:at|by|around|about) [a-z0-9:.]+(?: "
    r"(?:o'clock|sharp|ish|pm|am))?| soon| in a bit| shortly| later| tonight| this [a-z]+)?"
    r"[.!]?$"
)


def _lot_in52(text: str, lexicon: Lexicon) -> str:
    """Session 52: a closing "Carol's numerology lot are in at six." taken off a placing."""
    if "lot" not in text and " are " not in text and " is " not in text and "'re " not in text:
        return text
    m = _LOT_IN52.search(text)
    if m is None or _names(m["w"], lexicon):
        return text
    if m["p"] and not _only_person(m["p"], lexicon):
        return text
    out = text[: m.start()]
    read = None if _UNSAFE52.search(out) else _reading(out, lexicon)
    if read is None or any(t.kind != "place" for t in tasks(read)):
        return text
    return out


# -- refused (12c's fuzz) -------------------------------------------------------------------------

# -- 'Should / Must the X go to P?' ("Should the apple go on the shelf?", "Must the apple go to
# Bob?", "Should you give Bob the apple?", "Should the red mug go to Alice or Bob?"): a question
# that only asks what ought to happen, as "Should Bob get the apple?" is (refused)
_SHOULD52 = re.compile(
    r"^(?P<said>(?:Should|Must|Ought) (?:the|that|this|these|those|you|u|we|I|it|they|he|she|"
    r"one|either|both|a|an|my|his|her|their|our)\b[^?,;:.]{1,80}?)(?:,\s*(?:do you think|what do "
    r"you (?:think|reckon)|or not|or [^?,;:.]{1,40}))?\s*\?\s*$",
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


# -- 'P had asked for / had wanted X.' ("Bob had asked for one of the mugs.", "Alice had wanted the
# apple."): a want before some time past, which may be over; refused as session 51's 'had been
# needing' is, alone or beside another request ("Bob had asked for the apple; Alice wants the
# crisps." would read one want and not the other). Left to main when the rest says the want holds
# or what replaced it ('so give it to him', 'he still wants it', "but now she'd rather have …").
# 'P had been given / had got X' is a holding said as done, refused with it (read on main).
_HAD_WANTED52 = re.compile(
    r"(?:^|[,;:.!?] (?:and |but |so |then )?)(?P<said>" + _P52 + r"(?: had|'d) (?:asked for|wanted|"
    r"requested|been after|been wanting|needed|been needing|fancied|been asking for|(?P<got>been "
    r"(?:given|handed|passed|brought|sent|taken)|got(?! to\b)|gotten))) [^,;:.!?]+"
)
# what, after the past want, says it holds or was replaced: main's reading stands
_HAD_KEPT52 = re.compile(r"\b(?:it|them|still|now|rather|instead|changed)\b", _F)


def _had_wanted52(text: str, lexicon: Lexicon) -> None:
    """Session 52: refuse 'P had asked for X.' and 'P had been given X' (above)."""
    if " had " not in text and "'d " not in text:
        return
    for m in _HAD_WANTED52.finditer(text.strip()):
        if not _only_person(m["said"].rsplit(" had", 1)[0].split("'d ")[0], lexicon):
            continue
        if m["got"] is None and _HAD_KEPT52.search(text.strip()[m.end("said") :]):
            continue
        raise GroundingError(
            f"{m['said']!r} says what was wanted or had before: it may be over; say 'give …' for "
            "what is wanted now"
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
    _off_your_hands52,
    _hanging_about52,
    _poor52,
    _high_and_low52,
    _my_hands52,
    _to_do_his52,
    _after_care52,
    _ready_on52,
    _cataphor52,
    _sat_on52,
    _before_ps52,
    _when_done52,
    _do_for52,
    _doing_next52,
    _clearing52,
    _lot_in52,
)
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-51 ones)
_STEPS52: tuple[Callable[[str, Lexicon], str], ...] = ()
# refusals asked of the text before it is read (offline._parse, after the session-51 ones)
REFUSE52: tuple[Callable[[str, Lexicon], None], ...] = (_should52, _had_wanted52)
# checks of the whole instruction's reading (offline.parse_instruction, after the session-51 ones)
CHECK52: tuple[Callable[[str, Node, Lexicon], None], ...] = ()
