"""The grounder's rules of session 40, engineer 12s (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _KEEP_WORDS, _ids, _names, _only_person, _reading
from hltl.grounding._normalise4 import _fit36
from hltl.grounding._rewrites39s import _END39S, _plain39s, _subject39s
from hltl.grounding.lexicon import Lexicon, person_name
from hltl.grounding.tree import Node, tasks

# -- session 40 (engineer 12s): a purpose 'for <an event, a pastime, an outing>' ----------------
#
# "Person B wants the chips for the bar billiards league", "Can Person B have the cup and the
# apple for his model boat outing?", "The banana on the tray for the moth trap volunteers",
# "needs the chips for the drive to pinochle night": 'for' + a determiner or his / her + up to
# four words (and a place or a goal after 'to', 'at', 'in', 'on', 'with', 'from'), closing a
# clause right after a name of the scene (an object, a person or a surface: the request's own
# words), naming nothing of the scene (nor a typo of a name) and holding no word that counts,
# chooses or points back (_KEEP_WORDS; a number inside a word joined by hyphens, 'five-a-side',
# is the event's name), no length of time ('for a bit', 'for the time being': a loan) and no
# word of the request's own: what the thing is for, taken off when what is left reads. Session
# 12's and 28's purpose rules took one or two words; the time that defers ('for after lunch') is
# left to the time rules, and 'for later', 'for tonight', 'for the morning' read as before
# (sessions 14 and 37: met by handing it now). 'for' + a person of the scene stays a recipient;
# 'for' + a group or a trade not in the scene with no recipient or place of the request's own
# ("Take the chips for the bell ringers") does not read without it: left refused ("no person
# called 'bell ringers'"). A his / her of the purpose must fit someone who gets something
# (_owner40s refuses "Give Bob the red mug for her pottery evening": is it hers?).
_PURPOSE40S = re.compile(
    r"(?P<sep>,?\s+)for (?P<det>the|a|an|his|her|their|our|my) (?P<what>[a-z][a-z'-]*"
    r"(?: [a-z][a-z'-]*){0,3}?(?: (?:to|at|in|on|with|from) (?:the |a |an |his |her |their |"
    r"our )?[a-z][a-z'-]*(?: [a-z][a-z'-]*){0,2})?)(?=\s*(?:[.,;:!?]|$|(?<=\s)(?:please|thanks|"
    r"cheers)\b))",
    _F,
)
# words a purpose may not hold: a length of time (a loan), the request's own closers and times
_NOT_PURPOSE40S = re.compile(
    r"\b(?:bit|minute|minutes|mins?|second|seconds|secs?|moment|while|tick|jiffy|hour|hours|"
    r"time|being|now|good|keeps|change|please|thanks|cheers|too|instead|later|tonight|today|"
    r"tomorrow|sake|favour|favor|reason|use|benefit|lend|loan|borrow|back|keep|keeping)\b",
    _F,
)
# the possessive of a purpose (checked against who gets something)
_OWNER40S = re.compile(r"\bfor (?P<det>his|her) (?P<what>[a-z][a-z' -]*)", _F)


def _after_name40s(before: str, lexicon: Lexicon) -> bool:
    """Whether ``before`` ends with a name of the scene (its last word, or 'Person A'), a 'please'
    or 'thanks' after it aside ("… to Bob then" does not)."""
    words = re.findall(r"[a-z0-9][a-z0-9'-]*", before.lower())
    while words and words[-1] in ("please", "thanks", "cheers", "ta"):
        words.pop()
    if not words:
        return False
    if len(words[-1]) == 1 and len(words) >= 2:
        return bool(_names(" ".join(words[-2:]), lexicon))
    return bool(_names(words[-1], lexicon))


def _purpose_words40s(what: str, lexicon: Lexicon) -> bool:
    """Whether ``what`` (a purpose's words after its determiner) is one to take off (above)."""
    plain = re.sub(r"\b[a-z]+(?:-[a-z]+)+\b", "x", what, flags=_F)  # 'five-a-side': one word
    # (a name said with an 's' and no apostrophe: 'the teachers paper props')
    bare = re.sub(r"(?<=[a-z])'?s\b", "", what, flags=_F)
    return (
        not _names(what, lexicon)
        and not _names(bare, lexicon)
        and not _KEEP_WORDS.search(plain)
        and not _NOT_PURPOSE40S.search(what)
    )


def _purpose40s(text: str, lexicon: Lexicon) -> str:
    """Session 40 (12s): a purpose 'for <an event>' after a name of the request taken off
    (above), when what is left reads and its his / her fits someone who gets something."""
    if "for " not in text.lower():
        return text
    owners: list[str] = []

    def cut(m: re.Match[str]) -> str:
        if not _after_name40s(text[: m.start()], lexicon) or not _purpose_words40s(
            m["what"], lexicon
        ):
            return m.group(0)
        if m["det"].lower() in ("his", "her"):
            owners.append(m["det"].lower())
        return ""

    out = _PURPOSE40S.sub(cut, text)
    if out == text:
        return text
    read = _reading(out, lexicon)
    if read is None:
        return text
    given = {t.target for t in tasks(read) if t.kind == "deliver"}
    if given and any(not any(_fit36(p, w, lexicon) for p in given) for w in owners):
        return text  # _owner40s: whose is it?
    return out


def _owner40s(text: str, node: Node, lexicon: Lexicon) -> None:
    """Session 40 (12s): "Give Bob the red mug for her pottery evening": a his / her of a purpose
    (above) that fits no one who gets something in the reading is someone else's: the purpose
    may say who it is for (a slip of the name?): refused naming the people it may be."""
    if "for h" not in text.lower():
        return
    given = {t.target for t in tasks(node) if t.kind == "deliver"}
    if not given:
        return
    for m in _OWNER40S.finditer(text):
        words = m["what"].split()
        if not words or not _purpose_words40s(" ".join(words[:4]), lexicon):
            continue
        det = m["det"]
        if any(_fit36(p, det, lexicon) for p in given):
            continue
        others = [
            person_name(h.id, lexicon)
            for h in lexicon.scene.humans
            if h.id not in given and _fit36(h.id, det, lexicon)
        ]
        got = ", ".join(person_name(p, lexicon) for p in sorted(given))
        may = f": it may mean {' or '.join(others)}" if others else ""
        raise GroundingError(
            f"{det!r} in 'for {det} {' '.join(words[:4])}' cannot be {got}, who gets it{may}; "
            "say whose it is and who gets what"
        )


# -- session 40 (12s): the remark that asks nothing, widened (blind38) ---------------------------
#
# Said without punctuation, a remark of he / she / we / they in the middle of a request ("Give
# Ruth the thermometer she's doing the rounds and Mrs Khan the magazine") or closing it ("… the
# crisps they're both off to the angler's meeting after"): right after a name of the request,
# set off by commas (and its 'after' at the very end is 'afterwards'), so the rules of remarks
# said with commas read it (or refuse it) as they would; in the middle only before 'and' + a
# person of the scene + what they get (a request's next piece). He / she must fit the one person
# named before it, and say what session 39's rule takes off of a person (no time, going or being
# done) or that they want what they get (_THEIR_WANT40S); a remark naming something of the scene or
# saying 'not' is left. A text with any comma, colon, semicolon or dash is left as it is.
_RUN_ON40S = re.compile(
    r"(?<=[a-z]) (?P<said>(?:he|she)'s|(?:we|they)'(?:re|ve)|(?:he|she) (?:is|was|has)) ", _F
)
_NOT40S = re.compile(r"\b(?:not|never|no|nobody|nothing|none)\b|n't\b", _F)
_AND_NEXT40S = re.compile(r" and (?=(?P<who>[a-z]+(?: [a-z]+)?) (?:the|a|an|some|his|her) )", _F)


def _run_on40s(text: str, lexicon: Lexicon) -> str:
    """Session 40 (12s): a remark said without punctuation set off by commas (above)."""
    if re.search(r"[,;:—–]|\s-\s", text):
        return text
    m = _RUN_ON40S.search(text)
    if m is None or not _after_name40s(text[: m.start()], lexicon):
        return text
    before, said = text[: m.start()], text[m.start() + 1 :]
    if _NOT40S.search(said):
        return text  # "… hes not back from his darts match": left to be refused
    pron = re.match(r"(he|she)\b", said, _F)
    if pron is not None:
        # he / she: the one person named before it, whom it fits ("crisps for bob please shes
        # back from her darts match" is someone else: left to be refused)
        named = _ids(before, lexicon, "human")
        if len(named) != 1 or not _fit36(next(iter(named)), pron[1], lexicon):
            return text
        # … saying nothing of a time, a going or being done ("… hes back at six") but what they
        # want of what they get ("… shes been on about it all morning")
        end = _AND_NEXT40S.search(said)
        remark = said[: end.start()] if end is not None else said
        found = _subject39s(remark, lexicon)
        if not _THEIR_WANT40S.search(f", {remark}") and (
            found is None or not _plain39s("pron", found[2], next(iter(named)), lexicon)
        ):
            return text
    for n in _AND_NEXT40S.finditer(said):
        if _only_person(n["who"], lexicon) and _names(said[n.end() :], lexicon):
            if _names(said[: n.start()], lexicon):
                return text  # a remark naming something of the scene ("she's got the apple")
            rest = said[n.start() :].lstrip()
            return f"{before}, {said[: n.start()]}, {rest}"
    if _names(said, lexicon):
        return text
    said = re.sub(r"\s+after\s*([.!?]?)\s*$", r" afterwards\1", said, flags=_F)
    return f"{before}, {said}"


# A closing remark of the one person who gets everything that they want what they get ("…, she's
# been on about it all morning", "…. She asked first.", "…, he's earned them after the boccia",
# "…, Bob's been asking for it all week"): it changes nothing. The person is he / she (who must
# fit the one person the reading gives to) or a name of that person; 'it' / 'them' is what they
# get; a time gone by or 'first' may follow. Taken off when the request reads alone and gives only
# to that person.
_THEIR_WANT40S = re.compile(
    r"(?P<sep>\s*[,;]\s*|(?<=[.!?])\s+|\s+[—–-]\s+)(?:(?:and|as|because|cos|'cause)\s+)?"
    r"(?P<who>[a-z]+(?: [a-z]+)?)(?:(?:'s| has| had) been (?:on about|going on about|asking "
    r"(?:for|about)|after|nagging (?:me )?(?:for|about)|waiting (?:for|on)|dreaming of|looking "
    r"forward to|eyeing(?: up)?) (?:it|them)|(?:'s| has| had) earned (?:it|them)| earned (?:it|"
    r"them)| deserves (?:it|them)| keeps (?:asking for|going on about) (?:it|them)| asked(?: for "
    r"(?:it|them))? first| was (?:here |there )?first)(?P<tail>(?: (?:all (?:morning|day|"
    r"afternoon|evening|week)(?: long)?|for ages|for weeks|since (?:the |her |his |a )?[a-z]+"
    r"(?: [a-z]+){0,2}|after (?:the|her|his|a|an) [a-z]+(?: [a-z]+){0,3}|today|again|already|"
    r"twice|first))*)\s*[.!]?\s*$",
    _F,
)


def _their_want40s(text: str, lexicon: Lexicon) -> str:
    """Session 40 (12s): a remark that the one who gets everything wants it, taken off (above)."""
    m = _THEIR_WANT40S.search(text)
    if m is None:
        return text
    before = text[: m.start()].rstrip()
    if not _names(before, lexicon) or (m["tail"] and _names(m["tail"], lexicon)):
        return text
    out = before if before[-1:] in (".", "!", "?") else before + "."
    read = _reading(out, lexicon)
    if read is None:
        return text
    given = {t.target for t in tasks(read) if t.kind == "deliver"}
    if len(given) != 1 or any(t.kind != "deliver" for t in tasks(read)):
        return text
    who = m["who"].lower()
    (pid,) = given
    if who in ("he", "she"):
        if not _fit36(pid, who, lexicon) or len(_ids(before, lexicon, "human")) != 1:
            return text
    elif _ids(m["who"], lexicon, "human") != {pid} or not _only_person(m["who"], lexicon):
        return text
    return out


# A closing remark about things not of the scene (a thing or a trade as its subject, or we) that
# says a surface of the scene is in use ("…, the organ builder's borrowing the bench", "…, we're
# clearing the counter") or that something is after what the request moves ("…, the wasps are
# after them", only of what the request puts somewhere: of what it hands over, a want?): the
# remark says why, and changes nothing when the request puts or gives nothing on that surface.
# The surface taken as said only after a verb of using it or before a state of being in use; then
# the remark must be one session 39's rule would take off (_plain39s).
_IN_USE40S = (
    r"(?:(?:borrowing|using|clearing|cleaning|wiping(?: down)?|tidying|sorting out|painting|"
    r"varnishing|fixing|mending|sanding|hogging|needing|setting up|laying) (?:the|our|my) "
    r"(?P<used>[a-z]+(?: [a-z]+)?)|(?:the|our|my) (?P<busy>[a-z]+(?: [a-z]+)?)(?:'s| is) "
    r"(?:in use|wet|sticky|full|taken|busy|being (?:cleaned|cleared|wiped|used|painted|fixed)))"
)
_AFTER_THEM40S = re.compile(
    r"\b(?:after|at|all over|going for|nibbling|pecking at|eyeing(?: up)?) (?:it|them)\b", _F
)


def _things_aside40s(text: str, lexicon: Lexicon) -> str:
    """Session 40 (12s): a remark about a surface in use or something after the request's
    things, taken off (above)."""
    m = _END39S.search(text)
    if m is None:
        return text
    said = m["said"]
    found = _subject39s(said, lexicon)
    if found is None or found[0] not in ("thing", "we"):
        return text
    kind, _, rest = found
    before = text[: m.start("sep")].rstrip()
    if not _names(before, lexicon):
        return text
    surfaces: set[str] = set()

    def used(u: re.Match[str]) -> str:
        name = u["used"] or u["busy"]
        ids = _ids(name, lexicon)
        if ids and _ids(name, lexicon, "surface") != ids:
            return u.group(0)
        surfaces.update(ids)
        return u.group(0).replace(name, "place")

    plain = re.sub(_IN_USE40S, used, rest, flags=_F)
    after = _AFTER_THEM40S.sub("around", plain) if kind == "thing" else plain
    if after == rest or not _plain39s(kind, after, "-", lexicon):
        return text
    out = before if before[-1:] in (".", "!", "?") else before + "."
    read = _reading(out, lexicon)
    if read is None or any(t.target in surfaces for t in tasks(read)):
        return text
    if after != plain and any(t.kind == "deliver" for t in tasks(read)):
        return text  # something after what is handed over (a want?): only of what is put away
    return out


# An opening remark passing on a person's thanks ("Kofi sends his thanks in advance: could you
# pass him the power drill, please?"): a courtesy of the one person whom the request's him / her
# then means (the request names no one else, and the pronoun fits them): their name said there.
_THANKS40S = re.compile(
    r"^(?P<who>[a-z]+(?: [a-z]+)?) (?:sends|says|passes on|gives) (?:(?:his|her|their) )?"
    r"(?:thanks|cheers|thank you|love|regards|best wishes)(?: in advance)?\s*[:;,.!-]+\s*"
    r"(?P<req>\S.*)$",
    _F,
)


def _thanks40s(text: str, lexicon: Lexicon) -> str:
    """Session 40 (12s): an opening remark passing on thanks, its person said in the request
    (above)."""
    m = _THANKS40S.match(text)
    if m is None or not _only_person(m["who"], lexicon) or _ids(m["req"], lexicon, "human"):
        return text
    (pid,) = _ids(m["who"], lexicon, "human")
    said = re.findall(r"\b(?:he|him|his|she|her|hers|they|them|their)\b", m["req"], _F)
    if len(said) != 1 or said[0].lower() not in ("him", "her") or not _fit36(pid, said[0], lexicon):
        return text
    out = re.sub(r"\b(?:him|her)\b", m["who"], m["req"], count=1, flags=_F)
    return out if _reading(out, lexicon) is not None else text


# An opening remark joined by 'and' to the person's want ("Person B's been flying his drone all
# morning and asked for the chips, so hand him them"): the remark (one session 39's rule would
# take off of a person) taken off, the want kept.
_BEEN_AND40S = re.compile(
    r"^(?P<who>[a-z]+(?: [a-z]+)?)(?P<been>(?:'s| has) been [^,;:.!?]+?) and (?P<want>asked for|"
    r"wants|needs|is after|fancies|could do with|would like) ",
    _F,
)


def _been_and40s(text: str, lexicon: Lexicon) -> str:
    """Session 40 (12s): an opening remark before a want, taken off (above)."""
    m = _BEEN_AND40S.match(text)
    if m is None or not _only_person(m["who"], lexicon):
        return text
    (pid,) = _ids(m["who"], lexicon, "human")
    if not _plain39s("person", m["been"], pid, lexicon):
        return text
    out = f"{m['who']} {m['want']} {text[m.end() :]}"
    return out if _reading(out, lexicon) is not None else text


# the normaliser's rewrites (wired into normalise._STEPS19)
_STEPS40S: tuple[Callable[[str, Lexicon], str], ...] = (
    _purpose40s,
    _their_want40s,
    _things_aside40s,
)
# (first: before every other rewrite, as _STEPS39S_FIRST)
_STEPS40S_FIRST: tuple[Callable[[str, Lexicon], str], ...] = (
    _run_on40s,
    _thanks40s,
    _been_and40s,
)
# refusals asked of the text before it is read (offline._parse, after the session-39 ones)
REFUSE40S: tuple[Callable[[str, Lexicon], None], ...] = ()
# checks of the whole instruction's reading (offline.parse_instruction, after remark_said39s)
CHECK40S: tuple[Callable[[str, Node, Lexicon], None], ...] = (_owner40s,)
