"""The grounder's rules of session 44, engineer 12 (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _ids, _objects_only, _only_person
from hltl.grounding._normalise4 import _fit36
from hltl.grounding._rewrites41 import _TO_HIM42, _elided42, _person_ending41
from hltl.grounding.lexicon import PRONOUN_SEX, Lexicon, unnamed_sex44l
from hltl.grounding.tree import Node

# -- session 44 (engineer 12): blind42's refusals by kind — wants said by an idiom, pronouns and
# possessives, courtesies and question forms, lower case. Each rule a closed family checked
# against the scene; a remark, purpose or aside beside the request is 12s's kind, negation,
# counts and corrections 12r's.

# the words that may stand for what was wanted, to the end of the clause
_CLAUSE_CUT44 = r"[,;:.!?—–]| (?:and|but|so|while|after|before|since|for|because|as) "
# a person's name of one or two words
_NAME44 = r"(?P<p>[A-Za-z][\w]*(?: [A-Za-z][\w]*)?)"


# -- a want said by an idiom of longing or of going on about it ("Person B is gagging for the
# water bottle", "… has been dreaming about the chips all morning", "Person A keeps banging on
# about crisps"): said as 'wants' (the session-41 family, _rewrites41._want_idiom41, needs an
# article after it and runs after the rules that take a remark off; the older 'is gagging for' of
# _normalise1._wants runs only after every session-19 rewrite, so "P has been on the tug crew
# since dawn and is gagging for X" was never read). The person opens the clause (or is left unsaid
# after 'and' when the sentence opens with that one person and names nothing else), the words
# after the idiom name objects of the scene only; the past ('was gagging'), negation, a person or
# surface after it, and a request handing the person something after it stay as they were
_WANT_WORDS44 = re.compile(
    r"(?P<p>\b[A-Za-z][\w]*)(?P<idiom>"
    r"(?: is|'s|'s been| has been) (?:really |so |just |absolutely |properly |totally |still )?"
    r"(?:gagging|gasping|dying|desperate|crying out|itching|longing|aching) for"
    r"|(?: is|'s|'s been| has been| keeps| kept) (?:really |just |still )?(?:dreaming|daydreaming|"
    r"fantasi[sz]ing) (?:about|of)"
    # a bare noun after it (with an article, _rewrites41._want_idiom41 reads it)
    r"|(?: keeps|'s been| has been| is|'s) (?:going|banging|harping|droning|rabbiting|wittering) "
    r"on about(?: wanting| needing| having| getting)?(?= (?!(?:the|that|this|those|these|both|a|"
    r"an|some|his|her|their|wanting|needing|having|getting)\b)[a-z])"
    # blind41: 'would sell her soul for', 'put his name down for' (a him / her / them after it:
    # without one, _rewrites39._want_idioms39 reads it)
    r"|(?: would|'d) (?:happily |gladly )?sell (?:his|her|their) (?:soul|granny|grandmother) for"
    r"|(?P<name>(?: has| had|'s)? put (?:his|her|their) names? down for)"
    r")(?= (?:(?:the|that|this|those|these|both|a|an|some|his|her|their) )?[a-z])",
    _F,
)


# 'P said he …': the pronoun after what one person of the scene said, when it agrees with that
# person by a title, a word of kin, a first name or the corpus's Person A 'she' / Person B 'he'
# (lexicon.unnamed_sex44l); the grammar reads "Person B said he wants the chips" as him
_SAID44 = re.compile(
    r"(?:^|[,;:.!?—–]\s*|\b(?:and|but|so)\s+)(?P<who>[A-Za-z][\w]*(?: [A-Za-z][\w]*)?) "
    r"(?:said|says|reckons|tells me|told me|mentioned)(?: that)? $",
    _F,
)


def _agrees44(pid: str, words: str, lexicon: Lexicon) -> bool:
    """Whether every he / him / his / she / her / hers in ``words`` may be person ``pid``: no
    title, word of kin or first name rules it out (_fit36), nor, in a generic scene, the
    corpus's convention for 'Person A' / 'Person B' (lexicon.unnamed_sex44l)."""
    human = next(h for h in lexicon.scene.humans if h.id == pid)
    # the convention is for the generic scenes' people, named by the label alone (the paraphrase
    # scenes name Person A 'Kofi, foreman' too: the label says nothing of him there)
    sex = unnamed_sex44l(pid, lexicon) if not human.aliases else None
    said = {PRONOUN_SEX[w.lower()] for w in _PRONOUNS44.findall(words)}
    return _fit36(pid, words, lexicon) and (sex is None or said <= {sex})


_PRONOUNS44 = re.compile(r"\b(?:he|him|his|she|her|hers)\b", _F)


def _sayer44(head: str, pronoun: str, lexicon: Lexicon) -> str | None:
    """The one person of the scene whose words ``head`` ends on ('Person B said'), whom the
    he / she ``pronoun`` after it agrees with; None if not so."""
    m = _SAID44.search(head)
    if m is None or pronoun.lower() not in ("he", "she"):
        return None
    for n in (2, 1):
        who = " ".join(m["who"].split(" ")[-n:])
        if _only_person(who, lexicon):
            (pid,) = _ids(who, lexicon, "human")
            return who if _agrees44(pid, pronoun, lexicon) else None
    return None


def _want_words44(text: str, lexicon: Lexicon) -> str:
    """Session 44: the idioms above said as 'wants'."""
    low = text.lower()
    if not any(w in low for w in (" for ", " about ", " of ")):
        return text
    for m in list(_WANT_WORDS44.finditer(text))[::-1]:
        if m["p"].lower() == "and":
            if _elided42(text[: m.start("p")], lexicon) is None:
                continue
        elif _person_ending41(text, m.end("p"), lexicon, pronouns=True) is None and (
            _sayer44(text[: m.start("p")], m["p"], lexicon) is None
        ):
            continue
        rest = re.split(_CLAUSE_CUT44, text[m.end() :])
        if not _objects_only(rest[0], lexicon) or _ids(rest[0], lexicon) - _ids(
            rest[0], lexicon, "object"
        ):
            continue
        if m["name"] and not re.search(r"\b(?:her|him|them)\b", text[m.end() :], _F):
            continue  # "Noah's put his name down for the globe.": session 39's rule reads it
        if _TO_HIM42.search(text[m.end() :]):
            continue  # "Carol keeps dreaming about the apple, give her the cup": may be instead
        text = f"{text[: m.start('idiom')]} wants{text[m.end('idiom') :]}"
    return text


# -- a want said in a 'what P wants … is X' cleft with a time or degree inside it ("What Bob fancies
# right now is a packet of crisps", "All Mia needs at the moment is the tape", "What Sam wants
# most is the stapler"): 'P wants X' (the older clefts, _normalise1._wants and
# _rewrites42._cleft_want42, read it without the time). 'a packet / bag / tin of X' is the X when
# the scene has one; P one person of the scene, X objects of it only to the clause's end
_CLEFT44 = re.compile(
    r"(?:^|(?<=[.;!?:])\s*)(?:what|all|the (?:one |only )?thing) (?P<p>[A-Za-z][\w]*(?: [A-Za-z]"
    r"[\w]*)?) (?:really |actually |honestly )?(?P<v>fancies|wants|needs|would like|'d like|is "
    r"after|'s after|could do with|could use|craves|is craving|'s craving|is dying for|'s dying "
    r"for|is gagging for|'s gagging for) (?:right now|just now|at the moment|this minute|today|"
    r"now|most|more than anything)(?: of all)? is (?:(?P<pack>(?:a|one) (?:packet|bag|pack|tin|"
    r"box|bottle|pot) of) |(?P<art>the|a|an|some|that|this|those|these) )(?P<x>[a-z][a-z ]*?)"
    r"(?=\s*(?:[,;.!?]|$))",
    _F,
)


def _cleft_time44(text: str, lexicon: Lexicon) -> str:
    """Session 44: the cleft above said as 'P wants X'."""
    if " is " not in text.lower():
        return text
    m = _CLEFT44.search(text)
    if m is None or not _only_person(m["p"], lexicon) or not _objects_only(m["x"], lexicon):
        return text
    art = m["art"] or "the"
    if m["pack"] is not None and len(_ids(m["x"], lexicon, "object")) != 1:
        return text
    who = m["p"][:1].upper() + m["p"][1:] if m.start() == 0 else m["p"]
    return f"{text[: m.start()]}{who} wants {art} {m['x']}{text[m.end() :]}"


# -- a request asked as whether it could be done ("Would there be any chance of getting the crisps
# to Alice?", "Any chance you could pop the tape on the pallet?", "Might it be possible for Person
# A to get the chips?", "Is it at all possible to bring Mr Lee the jug?"): said 'could you …' /
# 'could P have …', which the grammar reads (session 42's _ask_forms42 does the same for 'could I
# trouble you to'). The verb one of the robots' tasks; 'for P' one person of the scene
_GERUNDS44 = {
    "getting": "get",
    "bringing": "bring",
    "taking": "take",
    "handing": "hand",
    "passing": "pass",
    "putting": "put",
    "giving": "give",
    "moving": "move",
    "popping": "pop",
    "sticking": "stick",
    "placing": "place",
    "fetching": "fetch",
    "sending": "send",
    "carrying": "carry",
}
_VERBS44 = r"get|bring|take|hand|pass|put|give|move|pop|stick|place|fetch|send|carry"
_CHANCE44 = re.compile(
    r"(?:^|(?<=[.;!?:])\s*)(?:(?:would|will|is) there (?:be )?|(?:is|was) there )?(?:any|a|some)"
    r" (?:chance|possibility|hope|way)(?: at all)? (?:of (?:you )?(?P<g>"
    + "|".join(_GERUNDS44)
    + r")|(?:that )?you (?:could|can|might|would) (?P<v>"
    + _VERBS44
    + r"))\b",
    _F,
)
_POSSIBLE44 = re.compile(
    r"(?:^|(?<=[.;!?:])\s*)(?:might|would|could|will) it be(?: at all| in any way)? "
    r"(?:possible|doable|feasible) (?:for (?P<p>[A-Za-z][\w]*(?: "
    r"[A-Za-z][\w]*)?) to (?:get|have|receive|be given)|(?:for you )?to (?P<v>"
    + _VERBS44
    + r"))\b",
    _F,
)


# "Any hope of Person A getting the chips?" (blind41): 'could P have'
_CHANCE_P44 = re.compile(
    r"(?:^|(?<=[.;!?:])\s*)(?:(?:would|will|is) there (?:be )?|(?:is|was) there )?(?:any|a|some)"
    rf" (?:chance|possibility|hope)(?: at all)? of {_NAME44} (?:getting|having|receiving)\b",
    _F,
)


def _ask_chance44(text: str, lexicon: Lexicon) -> str:
    """Session 44: the question forms above said 'could you …' / 'could P have …'."""
    low = text.lower()
    cues = ("chance", "possib", "way", "hope", "doable", "feasible")
    if not any(w in low for w in cues):
        return text
    m = _CHANCE_P44.search(text)
    if m is not None and _only_person(m["p"], lexicon):
        text = f"{text[: m.start()]}Could {m['p']} have{text[m.end() :]}"
    m = _CHANCE44.search(text)
    if m is not None:
        verb = _GERUNDS44[m["g"].lower()] if m["g"] else m["v"].lower()
        ask = (
            "Could you"
            if m.start() == 0 or text[: m.start()].rstrip()[-1:] in ".;!?:"
            else ("could you")
        )
        text = f"{text[: m.start()]}{ask} {verb}{text[m.end() :]}"
    m = _POSSIBLE44.search(text)
    if m is not None and not re.search(r"\bfor [^,;.!?]+ to\b", text[m.end() :], _F):
        # "… for Person A to have the chips, and for Person B to get the bottle?": two people's
        # parts, left to the older rules that read them
        if m["p"] is not None:
            if not _only_person(m["p"], lexicon):
                return text
            said = f"could {m['p']} have"
        else:
            said = f"could you {m['v'].lower()}"
        if m.start() == 0 or text[: m.start()].rstrip()[-1:] in ".;!?:":
            said = said[:1].upper() + said[1:]
        text = f"{text[: m.start()]}{said}{text[m.end() :]}"
    return text


# -- a proposal asked and then urged ("What if Person A had the apple and Person B the chips, why
# not do that?", "How about Bob gets the cup? Why don't you do that?"): the urging is the assent
# session 42's _proposal42 takes ('? Do that.'); said so. Without a proposal before it, nothing
# changes
_WHY_NOT44 = re.compile(
    r"(?:,|\?)\s*(?:so )?why (?:not|don't you|don't we|wouldn't you) (?:just )?(?:do that|do it|"
    r"go with that|go for that|go for it)(?: then)?\s*\?\s*$",
    _F,
)


def _why_not44(text: str, lexicon: Lexicon) -> str:
    """Session 44: 'why not do that?' after a proposal said as its assent."""
    if "why" not in text.lower():
        return text
    m = _WHY_NOT44.search(text)
    if m is None or not _ids(text[: m.start()], lexicon):
        return text
    return f"{text[: m.start()]}? Do that."


# -- courtesies around the request ("Chettirdim, friend, that's Tuvan for thanks; would you …",
# "Suksma, robot — my Balinese gran taught me that word — could you …", "With all due respect,
# machine, Person A needs the bottle, thanking you kindly."): a word of thanks or greeting glossed
# by the speaker, a deference opening the request, thanks closing it — each asks nothing and is
# taken off when its words name nothing of the scene and a request naming something follows
# (session 42's _courtesy42 takes "Tanemmirt, which is thanks in Tamazight," the same way)
_HEARER44 = r"(?:friend|robot|machine|mate|pal|buddy|love|dear|my friend|robots|folks|you)"
_THANKS44 = r"(?:thanks|thank you|cheers|hello|hi|please|sorry|good morning|greetings)"
_COURTESY44: tuple[re.Pattern[str], ...] = (
    re.compile(
        rf"^(?P<w>[A-Za-z][\w'-]*(?: [A-Za-z][\w'-]*)?),\s*(?:{_HEARER44},\s*)?(?:that's|that is|"
        r"which is|which means|it's|it is|it means)(?: (?:just|basically|how you say))? "
        rf"(?:[A-Z][a-z]+ for|(?:the )?[A-Z][a-z]+ (?:word )?for) (?:'{_THANKS44}'|{_THANKS44})"
        r"(?:,\s*(?:more or less|roughly|sort of|kind of))?\s*[.;:!—–]\s*",
        _F,
    ),
    re.compile(
        rf"^(?P<w>[A-Za-z][\w'-]*)(?:,\s*{_HEARER44})?,?\s*[—–]\s*(?P<a>[^—–]{{1,90}}?\b(?:word|"
        r"words|language|tongue|thanks|thank you)\b[^—–]{0,30}?)\s*[—–]\s*",
        _F,
    ),
    re.compile(
        rf"^(?:with (?:all )?(?:due|the greatest|great) respect|respectfully|if I may)(?:,\s*|\s+)"
        rf"(?:{_HEARER44},\s*)?(?P<w>)",
        _F,
    ),
)
_THANKING44 = re.compile(
    r",?\s*thanking you(?: (?:kindly|in advance|muchly|so much|very much))?\s*(?P<end>[.!]*)\s*$",
    _F,
)


def _courtesy44(text: str, lexicon: Lexicon) -> str:
    """Session 44: the courtesies above taken off."""
    for pattern in _COURTESY44:
        m = re.match(pattern, text)  # gated (session 53, 12p)
        if m is None or _ids(m[0], lexicon) or not _ids(text[m.end() :], lexicon):
            continue
        rest = text[m.end() :]
        text = rest[:1].upper() + rest[1:]
    m = _THANKING44.search(text)
    if m is not None and m.start() > 0 and _ids(text[: m.start()], lexicon):
        text = f"{text[: m.start()]}{m['end'] or '.'}"
    return text


# -- the thing said first, then what one person said of it ("The apple, Person A said she'd have
# it.", "That stapler, Sam says he'd take it"): 'P wants X' — the pronoun must agree with P
# (_agrees44), X objects of the scene only
_FRONTED_SAID44 = re.compile(
    r"^(?P<x>(?:the|that|this|those|these) [a-z]+(?: [a-z]+)?),\s*(?P<head>(?P<p>[A-Za-z][\w]*(?: "
    r"[A-Za-z][\w]*)?) (?:said|says|reckons|told me|mentioned)(?: that)? )(?P<pr>he|she)(?:'d| "
    r"would| will|'ll) (?:have|take|like|love|want) (?:it|them)(?P<end>\s*[.!]*)\s*$",
    _F,
)


def _fronted_said44(text: str, lexicon: Lexicon) -> str:
    """Session 44: the thing and what its person said of it (above) said as 'P wants X'."""
    if "," not in text:
        return text
    m = _FRONTED_SAID44.match(text.strip())
    if m is None or not _objects_only(m["x"], lexicon):
        return text
    who = _sayer44(m["head"], m["pr"], lexicon)
    if who is None:
        return text
    return f"{who} wants {m['x']}{m['end'].strip() or '.'}"


# -- 'it' named after the request ("Person A's waiting. Take it to her, the bottle.", "Hand it over
# to Mia, the tape"): the thing said in the place of the 'it' — when nothing of the scene was
# named before it that the 'it' could be; X objects of the scene only
_IT_NAMED44 = re.compile(
    r"(?:^|(?<=[.;!?:])\s*)(?P<v>take|give|hand|pass|bring|send|carry|get) it (?P<prep>(?:over |"
    r"across |back )?to) (?P<p>him|her|[A-Za-z][\w]*(?: [A-Za-z][\w]*)?),\s*(?P<x>(?:the|that|this)"
    r" [a-z]+(?: [a-z]+)?)(?:,? please)?(?P<end>\s*[.!]*)\s*$",
    _F,
)


def _it_named44(text: str, lexicon: Lexicon) -> str:
    """Session 44: the 'it' named after (above) said as the thing."""
    if "it " not in text.lower():
        return text
    m = _IT_NAMED44.search(text)
    if (
        m is None
        or not _objects_only(m["x"], lexicon)
        or _ids(text[: m.start()], lexicon, "object")
    ):
        return text
    if m["p"].lower() not in ("him", "her") and not _only_person(m["p"], lexicon):
        return text
    return f"{text[: m.start()]}{m['v']} {m['x']} {m['prep']} {m['p']}{m['end'].strip() or '.'}"


# -- the thing told apart by what one person did with it ("Those crisps Alice left out, stick them
# on the shelf.", "Those crisps are the ones Person B knocked off his lap during the briefing, so
# return them to him."): the description only says which thing (the scene has that one), so it is
# taken off; a him / her after it that agrees with that person (_agrees44) is that person
_DESCRIBED44 = re.compile(
    r"^(?P<x>(?:those|these|the|that|this) [a-z]+(?: [a-z]+)?)(?: (?:is|are|'re|'s) the (?:one|"
    r"ones))? (?:that |which )?(?P<p>[A-Z][\w]*(?: [A-Z][\w]*)?) (?P<v>left|left out|brought|"
    r"brought in|knocked|dropped|put down|had|bought|got|took|spilt|spilled|lost|forgot|"
    r"abandoned|was using|was eating|opened)\b(?P<d>[^,;.]*?)(?:,\s*(?:so\s+)?|\s*[;:]\s*|\s+so\s+)"
    r"(?P<rest>(?:please )?(?:stick|put|pop|place|give|hand|pass|take|bring|return|send|get) "
    r"(?:it|them)\b.*)$",
    _F,
)


def _described44(text: str, lexicon: Lexicon) -> str:
    """Session 44: the thing's description (above) taken off."""
    m = _DESCRIBED44.match(text.strip())
    if m is None or len(_ids(m["x"], lexicon, "object")) != 1 or not _objects_only(m["x"], lexicon):
        return text
    if not _only_person(m["p"], lexicon) or _ids(m["d"], lexicon):
        return text
    (pid,) = _ids(m["p"], lexicon, "human")
    if not _agrees44(pid, f"{m['d']} {m['rest']}", lexicon):
        return text
    rest = re.sub(r"\b(?:him|her)\b", m["p"], m["rest"], flags=_F)
    rest = re.sub(r"\breturn\b", "give", rest, flags=_F)
    if _ids(rest, lexicon, "human") - {pid}:
        return text
    x = m["x"][:1].upper() + m["x"][1:]
    return f"{x}, {rest}"


# -- a reason opened by 'seeing as' / 'being as' ("How about letting Person A have those crisps,
# seeing as she missed tea?", "Give Bob the apple, seeing that he's hungry"): said 'since', which
# the older rules read as a reason (_since28)
_SEEING_AS44 = re.compile(r",\s*(?:seeing as|seeing that|being as|being that)\b", _F)


def _seeing_as44(text: str, lexicon: Lexicon) -> str:
    """Session 44: 'seeing as' said 'since'."""
    if "seeing" not in text.lower() and "being" not in text.lower():
        return text
    return _SEEING_AS44.sub(", since", text)


# -- a person's state said with 'all' ("Lily's all sticky, she needs the baby wipes", "Tom is all
# wet"): 'all' there says how much, not which; taken off after one person of the scene and its
# 'is' before a state from a closed list (the grammar refuses 'all' as a count)
_ALL_STATE44 = re.compile(
    r"(?P<p>\b[A-Za-z][\w]*)(?P<be>'s| is| was| got) all (?=(?:sticky|wet|muddy|mucky|messy|"
    r"dirty|grubby|cold|shivery|sweaty|hot|flustered|tired|sleepy|grumpy|upset|excited|dusty|"
    r"soggy|damp|drenched|soaked|sandy|inky|floury|greasy|oily|smelly|teary|weepy|shaky|wobbly|"
    r"jittery|achy|stiff|sore|worn out|in a tizz|in a flap|of a dither|fingers and thumbs)\b)",
    _F,
)


def _all_state44(text: str, lexicon: Lexicon) -> str:
    """Session 44: the 'all' of a state (above) taken off."""
    if " all " not in text.lower():
        return text
    for m in list(_ALL_STATE44.finditer(text))[::-1]:
        if _person_ending41(text, m.end("p"), lexicon) is None:
            continue
        text = f"{text[: m.end('be')]} {text[m.end() :]}"
    return text


# -- where on the person the thing goes ("she could use the blue blanket over her knees", "give
# Lily the bib round her neck"): the handover said, where on them is for the person; taken off
# after an object of the scene when the text names one person, whom the pronoun agrees with
_ON_BODY44 = re.compile(
    r"(?<=[a-z]) (?:over|on|across|round|around|onto|on to|for) (?P<pr>his|her) (?:knees|lap|legs|"
    r"shoulders|feet|head|hands|neck|back|chest|bed)(?=\s*(?:[,;.!?]|$))",
    _F,
)


def _on_body44(text: str, lexicon: Lexicon) -> str:
    """Session 44: where on the person (above) taken off."""
    low = text.lower()
    if " his " not in low and " her " not in low:
        return text
    m = _ON_BODY44.search(text)
    if m is None or not _ids(re.split(_CLAUSE_CUT44, text[: m.start()])[-1], lexicon, "object"):
        return text
    people = _ids(text, lexicon, "human")
    if len(people) != 1 or not _agrees44(next(iter(people)), m["pr"], lexicon):
        return text
    return text[: m.start()] + text[m.end() :]


# -- a state of the person's body, then what they need, run on with a comma ("Tom's hands are raw
# from the ice road run, he needs the work gloves", "Mrs Khan's feet are like ice, she could use
# the blanket"): two sentences ('… run. He needs …', which the older rules read); the state names
# nothing of the scene, the pronoun agrees with the one person opening it
_BODY_STATE44 = re.compile(
    r"^(?P<p>[A-Za-z][\w]*(?: [A-Za-z][\w]*)?)'s (?:hands|feet|fingers|knees|back|eyes|lips|legs|"
    r"arms|toes|ears|nose|head|throat|shoulders|neck|cheeks) (?:are|is|were|was|'re|have been|has "
    r"been|feel|feels) (?P<w>[^,;.!?]{2,80}?),\s*(?P<pr>he|she)(?= (?:needs|wants|would like|'d "
    r"like|could use|could do with|'ll need|will need|is after|'s after)\b)",
    _F,
)


def _body_state44(text: str, lexicon: Lexicon) -> str:
    """Session 44: the comma after the state (above) said as a stop."""
    if "'s " not in text:
        return text
    m = _BODY_STATE44.match(text)
    if m is None or not _only_person(m["p"], lexicon) or _ids(m["w"], lexicon):
        return text
    (pid,) = _ids(m["p"], lexicon, "human")
    if not _agrees44(pid, m["pr"], lexicon):
        return text
    return f"{text[: m.end('w')]}. {m['pr'][:1].upper()}{m['pr'][1:]}{text[m.end() :]}"


# -- a spill, then the thing to clean it ("emma spilt her tea and wants the sponge to mop it", "Lily
# knocked over her juice and needs the wipes to clean it up"): 'P wants X' — the spill names
# nothing of the scene, the pronoun agrees with P, and what it is for ('to mop it up') is said
# of the spill
_SPILT44 = re.compile(
    r"^(?P<p>[A-Za-z][\w]*(?: [A-Za-z][\w]*)?) (?:has |'s |just )?(?:spilt|spilled|knocked over|"
    r"upset|splashed|slopped|dribbled|dropped) (?P<w>(?:his|her|their|some|a|an) [a-z]+(?: [a-z]+)?"
    r"(?: (?:everywhere|all over (?:the floor|the place|himself|herself)|on the floor))?) and "
    r"(?:wants|needs|would like|'d like|could use|could do with|is after|'s after) "
    r"(?P<x>(?:the|a|an|some) [a-z]+(?: [a-z]+)??)(?: to (?:mop|wipe|clean|dry|soak|sponge)"
    r"(?: (?:it|that|them))?(?: up)?)?(?P<end>\s*[.!]*)\s*$",
    _F,
)


def _spilt44(text: str, lexicon: Lexicon) -> str:
    """Session 44: the spill and its mop (above) said as 'P wants X'."""
    m = _SPILT44.match(text.strip())
    if m is None or not _only_person(m["p"], lexicon) or _ids(m["w"], lexicon):
        return text
    if not _objects_only(m["x"], lexicon):
        return text
    (pid,) = _ids(m["p"], lexicon, "human")
    if not _agrees44(pid, m["w"], lexicon):
        return text
    return f"{m['p']} wants {m['x']}{m['end'].strip() or '.'}"


# -- more ways of asking (blind41): "Could you spare a minute to hand Person B the apple?", "Would
# it be a pain to take Person A the cup?", "Could you make sure Person A ends up with her bottle?",
# "Much obliged if Person B ended up with the chips.", "If you'd be so good as to carry the chips
# across to Person A", "Er, sorry, hate to interrupt, but could the bottle make its way to Person
# A?", "With thanks, the drill to Kofi": said as 'could you …', 'make sure P gets', 'P should get',
# 'please …', 'go to P', and the courtesy taken off — the grammar reads the rest as before
_ASK_FORMS44: tuple[tuple[re.Pattern[str], str], ...] = (
    (
        re.compile(
            r"\b(?P<ask>could|can|would|will) you (?:just )?spare (?:a|one|half a) "
            r"(?:minute|moment|sec|second|mo|tick|jiffy)(?: or two)? to\b",
            _F,
        ),
        "{ask} you",
    ),
    (
        re.compile(
            r"\b(?:would|will) it be (?:a|too much of a|much of a|a real) (?:pain|bother|hassle|"
            r"nuisance|faff|drag|chore) (?:for you )?to\b",
            _F,
        ),
        "could you",
    ),
    (
        re.compile(
            r"\b(?P<ask>(?:could|can|would|will) you (?:please )?)(?:make sure|see to it that|"
            rf"ensure) {_NAME44} (?:ends up with|winds up with|gets hold of)\b",
            _F,
        ),
        "{ask}make sure {p} gets",
    ),
    (
        re.compile(
            r"^(?:(?:I'd|I would|we'd|we would) be )?(?:much|most|very|greatly|ever so) obliged if "
            rf"{_NAME44} (?:ended up with|could have|got|could get|had|were given|was given)\b",
            _F,
        ),
        "{p} should get",
    ),
    (re.compile(r"^if you(?:'d| would| could) be so (?:good|kind) as to\b", _F), "please"),
    (
        re.compile(
            r"^(?:(?:er|erm|um|uh|oh)\s*,?\s*)?(?:sorry\s*,?\s*)?(?:I )?(?:hate|don't mean|"
            r"don't want) to (?:interrupt|bother you|butt in|disturb you|be a pain|be a bother),?"
            r"\s*but\s+",
            _F,
        ),
        "",
    ),
    (re.compile(r"\b(?:make|find|wend) (?:its|their) way (?:over |across )?to\b", _F), "go to"),
    (
        re.compile(
            r"^(?:with (?:many |grateful |warm |all |my |our )?thanks(?: in advance)?),\s*", _F
        ),
        "",
    ),
)


def _ask_forms44(text: str, lexicon: Lexicon) -> str:
    """Session 44: the question forms and courtesies above said plainly (the person one of the
    scene's; a courtesy taken off only when what follows names something of the scene)."""
    for pattern, said in _ASK_FORMS44:
        m = re.search(pattern, text)  # gated (session 53, 12p)
        if m is None:
            continue
        groups = {k: v for k, v in m.groupdict().items() if v is not None}
        if "p" in groups and not _only_person(groups["p"], lexicon):
            continue
        if not said and not _ids(text[m.end() :], lexicon):
            continue
        out = said.format(**groups)
        if m.start() == 0 or text[: m.start()].rstrip().endswith((".", "?", "!", ":", ";")):
            out = out[:1].upper() + out[1:]
        rest = text[m.end() :]
        if not out and m.start() == 0:
            rest = rest[:1].upper() + rest[1:]
        text = text[: m.start()] + out + rest
    return text


# -- a want said by what the thing would be for the person, the person after it ("The chips would
# go down a treat with Person A.", "The jug would be just the thing for Mr Lee"): 'give P X'
# (session 42's _would_help42 reads the person said before it); the sentence alone, X objects of
# the scene only, P one person of it
_GO_DOWN44 = re.compile(
    r"^(?P<x>(?:the|that|this|those|these) [a-z][a-z ]*?) (?:would|will|'d|'ll) (?:really |just |"
    r"certainly )?(?:go down (?:a treat|well|nicely|a storm)|be (?:just )?the (?:thing|ticket)|be "
    r"(?:most |very )?welcome|make (?:his|her|their) day) (?:with|for|to) "
    rf"{_NAME44}(?P<end>\s*[.!]*)\s*$",
    _F,
)


def _go_down44(text: str, lexicon: Lexicon) -> str:
    """Session 44: the want above said as 'give P X'."""
    if " would " not in text.lower() and "'d " not in text and " will " not in text.lower():
        return text
    m = _GO_DOWN44.match(text.strip())
    if m is None or not _objects_only(m["x"], lexicon) or not _only_person(m["p"], lexicon):
        return text
    (pid,) = _ids(m["p"], lexicon, "human")
    if not _agrees44(pid, m[0], lexicon):
        return text
    return f"Give {m['p']} {m['x']}{m['end'].strip() or '.'}"


# -- 'ditto' for one more of the same ("Person B's having the chips, and ditto the apple."): 'and
# the X too' after a request naming objects; X objects of the scene only
_DITTO44 = re.compile(
    r",?\s*(?:and )?ditto (?:for )?(?P<x>(?:the|that|this|those|these) [a-z][a-z ]*?)"
    r"(?P<end>\s*[.!]*)\s*$",
    _F,
)


def _ditto44(text: str, lexicon: Lexicon) -> str:
    """Session 44: 'ditto the X' said 'and the X too'."""
    if "ditto" not in text.lower():
        return text
    m = _DITTO44.search(text)
    if m is None or not _objects_only(m["x"], lexicon) or not _ids(text[: m.start()], lexicon):
        return text
    if len(_ids(text[: m.start()], lexicon, "human")) > 1:
        return text  # "Give Bob the cup and Alice the apple, ditto the chips.": whose? (12s)
    return f"{text[: m.start()]}, and {m['x']} too{m['end'].strip() or '.'}"


# -- a time said inside a 'what P wants' cleft after the thing ("The bottle's what Bob has been
# angling for all morning."), and the thing said as 'the thing P needs' ("Honestly, the chips are
# the thing Person B needs more than anything"): the time taken off (session 42's _cleft_want42
# then reads it), the second said 'P needs X'
_CLEFT_TAIL44 = re.compile(
    r"(?P<head>(?:'s|\bis|\bare|'re) (?:just |exactly )?what [A-Za-z][\w]*(?: [A-Za-z][\w]*)? "
    r"[^,.;!?]*?)\s+(?:all (?:morning|day|afternoon|evening|week|night|shift)(?: long)?|for ages|"
    r"right now|just now|at the moment|today)(?=\s*(?:[,.;!?]|$))",
    _F,
)
_THE_THING44 = re.compile(
    r"(?:^|(?<=[.;!?:,])\s*)(?P<x>(?:the|that|this|those|these) [a-z][a-z ]*?) (?:is|are|'s|'re) "
    rf"the (?:one )?(?:thing|things) {_NAME44} (?P<v>needs|wants|would like|'d like|is after|'s "
    r"after)(?: (?:more than anything|most|above all|most of all))?(?=\s*(?:[,.;!?]|$))",
    _F,
)


def _cleft_tail44(text: str, lexicon: Lexicon) -> str:
    """Session 44: the clefts above said plainly."""
    if " what " in text.lower():
        m = _CLEFT_TAIL44.search(text)
        if m is not None:
            text = text[: m.end("head")] + text[m.end() :]
    if " thing" in text.lower():
        m = _THE_THING44.search(text)
        if m is not None and _objects_only(m["x"], lexicon) and _only_person(m["p"], lexicon):
            v = {"is after": "wants", "'s after": "wants"}.get(m["v"].lower(), m["v"])
            who = m["p"][:1].upper() + m["p"][1:] if m.start() == 0 else m["p"]
            text = f"{text[: m.start()]}{who} {v} {m['x']}{text[m.end() :]}"
    return text


# -- a want of a drink or of something to eat, the thing not named ("Alice could really do with a
# drink, she's been spinning fire poi for an hour", "Bob is dying for a bite to eat"): the lead's
# policy (session 44): the scene's ONE object of a drink kind (or food kind) is meant; two or more
# are refused naming them, none is refused saying so. Only after a want of one person of the
# scene, and never when the text names an object (then that object is what is meant, or it is a
# choice for the older rules)
_DRINK_KINDS44 = frozenset({"bottle", "jug", "cup", "mug", "beaker", "glass", "flask"})
_FOOD_KINDS44 = frozenset({"apple", "chips", "banana", "biscuit", "sandwich", "orange", "cake"})
_KIND_WANT44 = re.compile(
    r"(?P<p>\b[A-Za-z][\w]*)(?: wants| needs| could (?:really |just )?(?:do with|use|murder)| "
    r"would (?:really |just )?(?:like|love)|'d (?:really |just )?(?:like|love)|(?: is|'s)"
    r"(?: really| so| just)? (?:dying|desperate|gasping|gagging|longing|crying out) for| fancies) "
    r"(?P<k>(?P<drink>a drink|something to drink|a cold drink|a drink of water|some water)|"
    r"(?P<food>a bite to eat|a bite|something to eat|something to nibble(?: on)?|a snack|"
    r"something to snack on|a nibble|something to munch(?: on)?))"
    r"(?=\s*(?:[,.;!?—–]|$| and\b| so\b))",
    _F,
)


def _kind_want44(text: str, lexicon: Lexicon) -> str:
    """Session 44: the want of a drink or food (above) said as the one such object, or refused."""
    low = text.lower()
    if not any(w in low for w in ("drink", "water", "eat", "bite", "snack", "nibble", "munch")):
        return text
    m = _KIND_WANT44.search(text)
    if m is None or _ids(text, lexicon, "object"):
        return text
    if _person_ending41(text, m.end("p"), lexicon) is None:
        return text
    kinds = _DRINK_KINDS44 if m["drink"] else _FOOD_KINDS44
    found = [o for o in lexicon.scene.objects if o.category in kinds]
    if len(found) > 1:
        said = " or ".join(o.id for o in found)
        raise GroundingError(f"{m['k']!r} is not resolved: it could mean {said}; name the object")
    if not found:
        what = "to drink" if m["drink"] else "to eat"
        raise GroundingError(f"{m['k']!r}: the scene has nothing {what}; name the object")
    (thing,) = found
    name = (
        thing.category
        if sum(o.category == thing.category for o in lexicon.scene.objects) == 1
        else thing.id
    )
    return f"{text[: m.start('k')]}the {name}{text[m.end('k') :]}"


# the normaliser's rewrites run before the session-43 ones (wired into normalise._STEPS19)
_STEPS44_FIRST: tuple[Callable[[str, Lexicon], str], ...] = (
    _want_words44,
    _cleft_time44,
    _ask_chance44,
    _why_not44,
    _courtesy44,
    _fronted_said44,
    _it_named44,
    _described44,
    _seeing_as44,
    _all_state44,
    _on_body44,
    _body_state44,
    _spilt44,
    _ask_forms44,
    _go_down44,
    _ditto44,
    _cleft_tail44,
    _kind_want44,
)
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-43 ones)
_STEPS44: tuple[Callable[[str, Lexicon], str], ...] = ()
# refusals asked of the text before it is read (offline._parse, after the session-43 ones)
REFUSE44: tuple[Callable[[str, Lexicon], None], ...] = ()
# checks of the whole instruction's reading (offline.parse_instruction, after the session-43 ones)
CHECK44: tuple[Callable[[str, Node, Lexicon], None], ...] = ()
