"""The grounder's rules of session 41, engineer 12s (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _KEEP_WORDS, _ids, _names, _only_person, _reading
from hltl.grounding._normalise4 import _DOING37, _EVENTS37, _fit36
from hltl.grounding._rewrites38s import _NEEDY38S
from hltl.grounding._rewrites39s import _plain39s, _shown39s, _subject39s
from hltl.grounding._rewrites40s import _purpose_words40s
from hltl.grounding.lexicon import Lexicon, person_name
from hltl.grounding.tree import Node, tasks

# -- session 41 (engineer 12s): an occasion beside a want, a need or a remark ---------------------
#
# "Person B's gasping for the bottle after bandy practice", "Person A needs the chips before her
# charades evening", "Ava's been eyeing the sippy cup since the treasure hunt", "What Person B
# really needs after the worm charming is that apple", "person a's got to have the bottle ahead
# of her boggle night": 'after', 'before', 'ahead of', 'since', 'following' or 'during' + an
# event or a pastime (a noun phrase of up to five words, with or without a determiner or his /
# her; no verb, no clock, no meal or part of the day: "after lunch", "before tonight" are left to
# the time rules) closing a clause or before 'is' of a 'what … needs … is' cleft. Said in a clause
# that tells of a want, a need or a state (a person of the scene is after it, needs it, has been
# eyeing it, is parched …), it says when or why they want it and is met by handing it now: taken
# off. 'before' and 'ahead of' of an order ("Give Alice the crisps ahead of her squash match") are
# a deadline about no task (docs, "what it is for, and by when": doing it now meets it): taken off
# too; 'after' / 'since' / 'following' / 'during' of an order ("Give her the chips after her
# charades evening") put it off or say something else: left to the time rules (refused). The words
# name nothing of the scene and hold no word that counts, chooses or points back; a his / her of
# them must fit someone who gets something in what is left; what is left must read. After a comma
# 'after' / 'following' / 'during' may say when to hand it ("Bob wants the cup, after the match"):
# left.
_OCCASION41S = re.compile(
    r"(?P<sep>,?\s+)(?P<prep>after|before|ahead of|since|following|during) (?P<det>(?:the|a|an|"
    r"his|her|their|our|my|this|that) )?(?P<what>[a-z][a-z-]*(?:'s)?(?: [a-z][a-z-]*(?:'s)?)"
    r"{0,4}?)(?=\s*(?:[.,;:!?]|$)|\s+(?:and|so|but|please|thanks|cheers|then|now)\b|\s+is\b"
    r"(?P<cleft>))",
    _F,
)
# words an occasion may not hold: a time of the day, a meal, a clock, a verb or a pronoun (a
# clause: "after he's eaten", "before the demo ends"), the request's own words
_NOT_OCCASION41S = re.compile(
    r"\b(?:lunch|lunchtime|dinner|dinnertime|tea|teatime|breakfast|brunch|supper|elevenses|"
    r"school|work|noon|midday|midnight|tonight|today|tomorrow|yesterday|monday|tuesday|"
    r"wednesday|thursday|friday|saturday|sunday|month|year|hour|hours|minute|minutes|moment|bit|"
    r"while|time|"
    r"then|now|later|soon|that|this|these|those|it|them|he|she|they|we|i|you|him|her|us|me|is|"
    r"are|was|were|be|been|has|have|had|gets|get|got|ends|starts|finishes|begins|done|over|"
    r"finished|started|ended|arrives|comes|leaves|goes|o'clock|oclock|am|pm|please|thanks|"
    r"cheers|too|also|instead|first|last|next|all|each|every|both|either|any|some)\b",
    _F,
)
# a part of the day said alone ("after the evening"); after another word it names an event ("her
# charades evening", "his boggle night")
_PART_OF_DAY41S = re.compile(r"^(?:morning|afternoon|evening|night|week|weekend|day)\b", _F)
# a clause that tells of a want, a need or a state (not an order)
_WANT_SAID41S = re.compile(
    r"\b(?:needs?|needed|wants?|wanted|wanting|would (?:like|love|kill for|be glad of)|could "
    r"(?:do with|use|murder)|fanc(?:y|ies)|(?:'s|is|was|been|are|were) after|asking for|asked "
    r"for|begging for|on about|eyeing|eying|set on|heart set on|gasping for|dying for|desperate "
    r"for|crying out for|longing for|itching for|aching for|pining for|hankering after|craving|"
    r"a must for|got to have|in want of|in need of|put in for|called (?:for )?(?:it|them)|keen "
    r"on|owed|deserves?|earned|hungry|thirsty|starving|parched|peckish|famished|ravenous)\b"
    r"(?! to (?:go|be|get|come|move|end up|head|wait|stay|have it|have them)\b)",
    _F,
)
# an order: a clause opening with a verb (after a courtesy)
_ORDER41S = re.compile(
    r"^\s*(?:(?:please|kindly|just|now|ok|okay|right|so|and|then|could you|can you|would you|"
    r"will you)[, ]+)*(?:give|hand|pass|bring|take|deliver|put|place|set|leave|send|get|fetch|"
    r"pop|stick|move|carry|run|drop|lay|stand|hang|pour)\b",
    _F,
)


def _clause41s(before: str) -> str:
    """The clause ``before`` ends with (after its last sentence end, semicolon, colon, comma, or
    'and', 'so', 'then', 'but' joining clauses)."""
    return re.split(r"[.;:!?,]\s|\s(?:and|so|then|but)\s", before)[-1]


# what made the person want it, their own doing (sessions 35 and 37: 'after his darts practice',
# 'after the wild swimming'; an event with 'the' says when: "Carol wants the cup after the
# wedding", "What Bob needs after the show is …" stay refused): a word in -ing, or a practice,
# game, lesson, solo … (_DOING37), not an event word (_EVENTS37); with 'the', 'a', 'that' only a
# word in -ing; 'since' says a time gone by (any but an event word); 'during' only of a want told
# as past ('put in for …', 'asked for …': when it was asked); of a want of one person, of objects,
# no surface
_PAST_WANT41S = re.compile(
    r"\b(?:put in for|asked for|called for|begged for|ordered|wanted|was after|were after|went "
    r"on about)\b",
    _F,
)


def _caused41s(prep: str, det: str, what: str, clause: str, lexicon: Lexicon) -> bool:
    """Whether ``what`` after ``prep`` (with determiner ``det``) closing ``clause`` is what made
    the person want it (above)."""
    last = what.split()[-1].lower()
    if last in _EVENTS37:
        return False
    if len(_ids(clause, lexicon, "human")) != 1 or _ids(clause, lexicon, "surface"):
        return False
    if not _ids(clause, lexicon, "object") and not re.match(r"\s*what\b", clause, _F):
        return False
    if prep == "since":
        return True
    if prep == "during":
        return bool(_PAST_WANT41S.search(clause))
    if det in ("his", "her", "their", ""):
        return bool(re.fullmatch(_DOING37, last, _F)) or last == "solo"
    return last.endswith("ing")


def _kept_if_owned41s(out: str, text: str, owners: list[str], lexicon: Lexicon) -> str:
    """``out`` (``text`` with an occasion or a purpose taken off) when it reads and each his / her
    said in what was taken off fits someone it hands something to; else ``text``."""
    read = _reading(out, lexicon)
    if read is None:
        return text
    given = {t.target for t in tasks(read) if t.kind == "deliver"}
    if owners and not given:
        return text
    if any(not any(_fit36(p, w, lexicon) for p in given) for w in owners):
        return text
    return out


def _occasion41s(text: str, lexicon: Lexicon) -> str:
    """Session 41 (12s): an occasion beside a want, a need or a remark, or a deadline of an
    order, taken off (above), when what is left reads and its his / her fits someone who gets
    something."""
    low = text.lower()
    if not any(
        w in low for w in ("after ", "before ", "ahead of ", "since ", "following ", "during ")
    ):
        return text
    owners: list[str] = []

    def cut(m: re.Match[str]) -> str:
        what = m["what"]
        if (
            _NOT_OCCASION41S.search(what)
            or _PART_OF_DAY41S.match(what)
            or _names(what, lexicon)
            or _names(re.sub(r"(?<=[a-z])'?s\b", "", what, flags=_F), lexicon)
            or _KEEP_WORDS.search(re.sub(r"\b[a-z]+(?:-[a-z]+)+\b", "x", what, flags=_F))
        ):
            return m.group(0)
        clause = _clause41s(text[: m.start()])
        if not _names(clause, lexicon):
            return m.group(0)
        prep = m["prep"].lower()
        if m["cleft"] is not None and not re.match(r"\s*what\b", clause, _F):
            return m.group(0)
        if "," in m["sep"] and prep not in ("before", "ahead of", "since"):
            return m.group(0)  # "Bob wants the cup, after the match": when to hand it?
        order = _ORDER41S.search(clause) is not None and not _WANT_SAID41S.search(clause)
        if order and prep not in ("before", "ahead of"):
            return m.group(0)
        if not order and not _WANT_SAID41S.search(clause) and prep not in ("before", "ahead of"):
            return m.group(0)
        det = (m["det"] or "").strip().lower()
        if prep not in ("before", "ahead of") and not _caused41s(prep, det, what, clause, lexicon):
            return m.group(0)
        if det in ("his", "her"):
            owners.append(det)
        return ""

    out = _OCCASION41S.sub(cut, text)
    if out == text:
        return text
    return _kept_if_owned41s(out, text, owners, lexicon)


# -- session 41 (12s): a purpose 'for <an event>' where session 40's rule did not look -------------
#
# "Hand the blue mug for the tea dance to Alice", "Pop the bib on the high chair for the messy
# play session", "Priya wants the stapler and the notebook for her scrivener's guild minutes":
# session 40's purpose (_purpose40s) after a name of the scene of several words ('high chair',
# 'plate rack', 'Mrs Ortiz'), with a possessive inside ("her scrivener's guild minutes", "the
# terrazzo crew's lunch"), or inside a request between its object and 'to' / 'over to' / 'on' …
# + a person or a surface of the scene. The same words as session 40's (naming nothing of the
# scene, no word that counts, chooses or points back, no length of time); taken off when what is
# left reads and a his / her of it fits someone who gets something.
_PURPOSE41S = re.compile(
    r"(?P<sep>,?\s+)for (?P<det>the|a|an|his|her|their|our|my) (?P<what>[a-z][a-z-]*(?:'s|s')?"
    r"(?: [a-z][a-z-]*(?:'s|s')?){0,4}?)(?=\s*(?:[.,;:!?]|$)|\s+(?:please|thanks|cheers)\b|"
    r"(?P<inside>\s+(?:over |across |round |up |down )?(?:to|on|onto|in|into) (?:the |a )?"
    r"(?P<target>[a-z][a-z ]*)))",
    _F,
)


def _ends_with_name41s(before: str, lexicon: Lexicon) -> bool:
    """Whether ``before`` ends with a name of the scene of one to three words ('high chair',
    'Mrs Ortiz', 'Person A') that ends at its last word (not "… Marco. It's"), a 'please' after
    it aside."""
    words = re.findall(r"[a-z0-9][a-z0-9'-]*", before.lower())
    while words and words[-1] in ("please", "thanks", "cheers", "ta"):
        words.pop()
    for k in (1, 2, 3):
        if len(words) < k:
            break
        tail = " ".join(words[-k:])
        if _names(tail, lexicon) and (k == 1 or not _names(" ".join(words[-k:-1]), lexicon)):
            return True
    return False


def _purpose41s(text: str, lexicon: Lexicon) -> str:
    """Session 41 (12s): a purpose 'for <an event>' session 40's rule does not reach, taken off
    (above)."""
    if "for " not in text.lower():
        return text
    owners: list[str] = []

    def cut(m: re.Match[str]) -> str:
        what = re.sub(r"(?:'s|s')(?=\s|$)", "", m["what"])
        # (the minutes of a meeting, after another word: 'her guild minutes')
        what = re.sub(r"(?<=[a-z] )minutes\b", "notes", what, flags=_F)
        if not _ends_with_name41s(text[: m.start()], lexicon) or not _purpose_words40s(
            what, lexicon
        ):
            return m.group(0)
        if m["inside"] is not None:
            target = m["target"]
            first = re.match(r"[a-z]+(?: [a-z]+){0,2}", target, _F)
            if first is None or not any(
                _ids(" ".join(first.group(0).split()[:k]), lexicon, kind)
                for k in (1, 2, 3)
                for kind in ("human", "surface")
            ):
                return m.group(0)
        if m["det"].lower() in ("his", "her"):
            owners.append(m["det"].lower())
        return ""

    out = _PURPOSE41S.sub(cut, text)
    if out == text:
        return text
    return _kept_if_owned41s(out, text, owners, lexicon)


# "Give Bob the cup. It's all for the ramblers.": 'all' of a closing "it's / that's / they're all
# for <a purpose>" is the things the request moves, said together (session 36 reads "It's for the
# bake sale."): said without it when the purpose names nothing of the scene and holds no word that
# counts, chooses or points back.
_ALL_FOR41S = re.compile(
    r"(?P<head>(?:^|[.!?;,]\s*)(?:it|that|this|they|these|those)(?:'s| is| are|'re) )all "
    r"(?P<rest>for (?:the|a|an|his|her|their|our) (?P<what>[a-z][a-z' -]*?))\s*(?P<end>[.!]?)\s*$",
    _F,
)


def _all_for41s(text: str, lexicon: Lexicon) -> str:
    """Session 41 (12s): "…. It's all for the ramblers." said as "…. It's for the ramblers."
    (above), when that reads."""
    m = _ALL_FOR41S.search(text)
    if m is None or m.start() == 0 or not _purpose_words40s(m["what"], lexicon):
        return text
    out = f"{text[: m.start()]}{m['head']}{m['rest']}{m['end']}"
    return out if _reading(out, lexicon) is not None else text


# -- session 41 (12s): a trade said of a person ---------------------------------------------------
#
# "first the bottle for person b the madrigal singer and after that …", "give the bottle to person
# a the clog dancer please": a trade after a person of the scene who gets something (after 'for' or
# 'to'), said without commas: 'the' + up to three words whose last is a trade or a role (a word in
# -er, -or, -ist, -ian, -man, -woman, -lady, -smith, -wright …) naming nothing of the scene, before
# the clause ends ('and', 'then', 'please', a comma or the end): who the person is, taken off.
# "she's a papermaker and needs the one only", "Person B's a reed cutter and takes anything", "he's
# a ditcher and starving", "she's a shawm player and it's the bottle she wants": a trade said of a
# person (he / she or a name) joined by 'and' to what they want or are: the trade taken off ("she
# needs …", "he's starving", "it's the bottle she wants"). Each when what is left reads.
_TRADE_WORD41S = (
    # not a word of time or order that ends like a trade (12c's fuzz: "bottle to person b the
    # crofter after" lost 'after', and with it the order)
    r"(?!(?:after|later|never|ever|over|under|rather|together|either|neither|other|another|"
    r"whether|sooner|for|nor|or|per|thereafter|hereafter|ago)\b)"
    r"[a-z]+(?:er|or|ist|ian|man|men|woman|women|lady|ladies|smith|wright|wife|maker|hand|"
    r"champion|champ|captain|chef|cook|fan|buff|nurse|lad|lass|guy|boss|rep|warden|keeper)s?"
)
_TRADE_AFTER41S = re.compile(
    r"(?P<to>\b(?:for|to) )(?P<who>[a-z]+(?: [a-z]+){0,2}?) (?P<trade>the (?:[a-z]+ ){0,2}"
    rf"{_TRADE_WORD41S})(?=\s*(?:[.,;:!?]|$)|\s+(?:and|then|please|pls|thanks|so)\b)",
    _F,
)
_TRADE_AND41S = re.compile(
    r"(?P<who>\b(?:he|she)|^[a-z]+(?: [a-z]+){0,2}?|(?<=[,;:.!?] )[a-z]+(?: [a-z]+){0,2}?)"
    r"(?:'s| is) (?:a|an|the) (?P<trade>(?:[a-z]+ ){0,2}"
    rf"{_TRADE_WORD41S}) and (?P<rest>[a-z][a-z']*)\b",
    _F,
)


def _trade41s(text: str, lexicon: Lexicon) -> str:
    """Session 41 (12s): a trade said of a person, taken off (above)."""
    out = text
    for a in list(_TRADE_AFTER41S.finditer(out))[::-1]:
        if _only_person(a["who"], lexicon) and not _names(a["trade"], lexicon):
            out = out[: a.start("trade") - 1] + out[a.end("trade") :]
    m = _TRADE_AND41S.search(out)
    if m is not None and not _names(m["trade"], lexicon):
        who = m["who"]
        if who.lower() in ("he", "she") or _only_person(who, lexicon):
            rest = m["rest"].lower()
            if rest in ("it's", "its", "that's", "there's", "so", "it", "that", "he", "she"):
                said = m["rest"]
            elif re.fullmatch(r"[a-z]{2,}[^s']s", rest) and rest not in ("is", "was", "has"):
                said = f"{who} {m['rest']}"
            else:
                said = f"{who}'s {m['rest']}"
            out = out[: m.start()] + said + out[m.end() :]
    if out == text:
        return text
    return out if _reading(out, lexicon) is not None else text


# -- session 41 (12s): a remark in the middle of a request, and a gerund after 'back from' --------
#
# "Bottle for Person A, she's back from the scavenger hunt, and the chips for Person B", "…, her
# spinet lesson ran long, and …": a remark of he / she or his / her <words> between commas before
# ', and' + the request's next piece: taken off when he / she (his / her) fits the one person
# named in the piece before it and session 39's rule would take it off of them
# (_plain39s: no time, going, being done or wanting; 'back from …' is a time gone by), the piece
# after names something of the scene, and what is left reads with that person getting something.
# "Person A's back from tobogganing, so she gets …": 'back / home / in from' + a pastime said
# with -ing and no determiner is the pastime ('from the tobogganing'), so the rules of remarks
# read it as they read 'back from the pool'.
_MIDDLE41S = re.compile(
    r",\s*(?P<said>(?:(?:he|she)(?:'s| is| has| was| had)|(?:his|her) [a-z]+)\b[^,;:.!?]*?),\s*"
    r"(?P<next>and\s+\S)",
    _F,
)
_FROM_DOING41S = re.compile(r"\b(?P<from>(?:back|home|in) from) (?P<doing>[a-z]+ing)\b", _F)


def _middle_remark41s(text: str, lexicon: Lexicon) -> str:
    """Session 41 (12s): a remark in the middle of a request taken off; a gerund pastime after
    'back from' said with 'the' (above)."""
    out = text
    for f in list(_FROM_DOING41S.finditer(out))[::-1]:
        if not _names(f["doing"], lexicon) and f["doing"].lower() not in ("nothing", "something"):
            out = f"{out[: f.start('doing')]}the {out[f.start('doing') :]}"
    m = _MIDDLE41S.search(out)
    if m is not None:
        before = out[: m.start()]
        piece = re.split(r"[.;:!?]\s", before)[-1]
        named = _ids(piece, lexicon, "human")
        found = _subject39s(m["said"], lexicon)
        if (
            len(named) == 1
            and found is not None
            and found[0] in ("pron", "poss")
            and _fit36(next(iter(named)), found[1], lexicon)
            and _plain39s(found[0], found[2], next(iter(named)), lexicon)
            and _names(out[m.start("next") :], lexicon)
        ):
            cut = f"{before}, {out[m.start('next') :]}"
            read = _reading(cut, lexicon)
            if read is not None and next(iter(named)) in {t.target for t in tasks(read)}:
                out = cut
    if out == text:
        return text
    return out if _reading(out, lexicon) is not None else text


# -- session 41 (12s): a remark of a group, a trade or a thing not in the scene --------------------
#
# "Pop the two cups in the sink, the scagliola demo's done with them", "crisps up on that shelf pls
# the piquet lot will want them": a group or a thing (no name of the scene) that is done with what
# the request puts away, or will want or use it: why it goes there, taken off when the request
# only puts things on surfaces (of what it hands over, a want of someone else: kept). "Lock both
# the spanners away in the locker now that the wainwright's gone", "…, seeing as the choir have
# left": a reason clause 'now that' / 'seeing as' / 'seeing that' closing the request whose
# subject is a thing, a group or we, that session 39's rule would take off as a remark: taken off.
# ", who's off to the dulcimer night" after a person of the scene: a relative remark closing the
# instruction, taken off when that person gets nothing in what is left (a remark of someone who
# gets nothing changes nothing: session 8), or gets something and the remark is one session 39's
# rule takes off of a person.
_THEIR_USE41S = re.compile(
    r"(?P<sep>\s*[,;]\s*|\s+(?:-|—|–)\s+|(?<=\bplease)\s+|(?<=\bpls)\s+|(?<=\bthanks)\s+)"
    r"(?P<who>(?:the|our|my) [a-z]+(?: [a-z]+){0,2}?)(?:'s|'re|'ll| is| are| has| have| will| "
    r"would)? ?(?:(?:be )?(?:done|finished|through) with|(?:be )?(?:want|need|use|wanting|"
    r"needing|using|after)|want|need) (?:it|them|those|these)(?: (?:now|later|next|soon|after|"
    r"afterwards|in a bit|tonight))?\s*[.!]?\s*$",
    _F,
)
_NOW_THAT41S = re.compile(
    r"(?P<sep>,?\s+)(?:now that|now|seeing as|seeing that) (?P<said>(?:the|our|my|we)\b[^,;:.!?]*?)"
    r"\s*(?P<end>[.!]?)\s*$",
    _F,
)
_WHO_IS41S = re.compile(
    r"(?P<sep>,\s*)who(?P<rest>(?:'s| is| was| has| had)\s[^,;:.!?]+?)\s*(?P<end>[.!]?)\s*$", _F
)


def _placed_only41s(out: str, lexicon: Lexicon) -> bool:
    """Whether ``out`` reads, every task a placement."""
    read = _reading(out, lexicon)
    return read is not None and all(t.kind != "deliver" for t in tasks(read))


def _group_remark41s(text: str, lexicon: Lexicon) -> str:
    """Session 41 (12s): a remark of a group, a trade or a thing not in the scene, or a relative
    remark of a person, taken off (above)."""
    m = _THEIR_USE41S.search(text)
    if m is not None and not _names(m["who"], lexicon) and _names(text[: m.start()], lexicon):
        out = text[: m.start()].rstrip()
        if _placed_only41s(out, lexicon):
            return out
    m = _NOW_THAT41S.search(text)
    if m is not None and _names(text[: m.start()], lexicon):
        found = _subject39s(m["said"], lexicon)
        if (
            found is not None
            and found[0] in ("thing", "we")
            and _plain39s(found[0], found[2], "-", lexicon)
        ):
            out = text[: m.start()] + m["end"]
            if _reading(out, lexicon) is not None:
                return out
    m = _WHO_IS41S.search(text)
    if m is not None:
        before = text[: m.start()]
        who = re.search(r"([a-z]+(?: [a-z]+)?)\s*$", before, _F)
        if who is None:
            return text
        name = who.group(1)
        if not _only_person(name, lexicon):
            name = name.split()[-1]
            if not _only_person(name, lexicon):
                return text
        (pid,) = _ids(name, lexicon, "human")
        rest = m["rest"]
        if _names(rest, lexicon) or re.search(
            r"\b(?:not|never|no|it|them|want|wants|need|needs)\b|n't", rest, _F
        ):
            return text
        out = before + m["end"]
        read = _reading(out, lexicon)
        if read is None:
            return text
        got = {t.target for t in tasks(read)}
        if pid in got and not _plain39s("person", rest, pid, lexicon):
            return text
        if pid not in got and _NEEDY38S.search(rest):
            return text  # "…, who's parched": a hint to give them something (session 39)
        return out
    return text


# -- session 41 (12s): 'for' + a person of the scene after a placement -----------------------------
#
# "Kindly put the globe on the bookshelf for Mrs Ortiz, thank you ever so.": a placement whose
# surface is followed by 'for' + the one person the instruction names, closing it: the thing is
# put there for them to find (what the robot does is the placement: globe@shelf). Only when every
# task of what is left is a placement and no other person is named (a handover beside it, or
# "put the cup on the shelf for Bob and the apple for Carol", may hand it over: left refused).
_PLACED_FOR41S = re.compile(
    r"(?P<sep>\s+)for (?P<who>[a-z]+(?: [a-z]+){0,2}?)(?=\s*(?:[.,;:!?]|$)|\s+(?:please|thanks|"
    r"cheers)\b)",
    _F,
)
_PLACING41S = re.compile(
    r"\b(?:put|place|set|leave|pop|stick|stand|lay|pile|stack|store|keep)\b[^,;:.!?]*\b(?:on|onto|in|"
    r"into|on top of|inside)\s+(?:the |that |this )?[a-z][a-z ]*$",
    _F,
)


def _placed_for41s(text: str, lexicon: Lexicon) -> str:
    """Session 41 (12s): 'for' + the one person named, after a placement's surface, taken off
    (above)."""
    if "for " not in text.lower():
        return text
    for m in _PLACED_FOR41S.finditer(text):
        if not _only_person(m["who"], lexicon):
            continue
        before = text[: m.start()]
        if not _PLACING41S.search(before) or not _ends_with_name41s(before, lexicon):
            continue
        tail = before.split()[-1]
        if not _ids(tail, lexicon, "surface") and not _ids(
            " ".join(before.split()[-2:]), lexicon, "surface"
        ):
            continue
        if _ids(text, lexicon, "human") != _ids(m["who"], lexicon, "human"):
            return text
        out = before + text[m.end() :]
        if _placed_only41s(out, lexicon):
            return out
    return text


# -- session 41 (12s): where the person takes it, and what they have done to a surface ---------
#
# "Can Person B take the apple and the chips off to the piquet table?", "Person A's taking the
# bottle home to the pole lathe lot": a person of the scene who takes the things (the one who gets
# them) and where they take them after, a place or a group that names nothing of the scene ('home
# to', 'off to', 'back to', 'round to' or 'to' + the / his / her …): their errand, taken off when
# what is left reads as handing the things to that person alone. "Lena's got the plate rack sorted,
# so give her the lemon": an opening remark that the person has done something to a surface of the
# scene ('got the <surface> sorted / cleared / wiped / tidied / set / laid', 'sorted / cleared …
# the <surface>'), then 'so' + a request whose one him / her fits that person: the remark taken
# off and the person's name said in its place (the lead's session-37 rule: a remark's person gets
# what follows).
_TAKES_TO41S = re.compile(
    r"(?P<who>\b[a-z]+(?: [a-z]+)?)(?:'s taking| is taking| can take| could take| will take|'ll "
    r"take| takes| to take| may take| might take| take) (?P<what>[^,;:.!?]+?) (?P<to>(?:(?:home|"
    r"off|back|away|round|over|along) )?to (?:the|his|her|their|a) (?P<where>[a-z][a-z' -]*?))"
    r"(?=\s*(?:[.,;:!?]|$))",
    _F,
)
_DONE_TO41S = re.compile(
    r"^(?P<who>[a-z]+(?: [a-z]+)?)(?:'s| has) (?:got (?P<s1>(?:the|that) [a-z]+(?: [a-z]+)?) "
    r"(?:sorted|cleared|wiped(?: down)?|tidied|cleaned|set|laid|done|ready)(?: out)?|(?:sorted|"
    r"cleared|wiped(?: down)?|tidied|cleaned|set|laid) (?P<s2>(?:the|that) [a-z]+(?: [a-z]+)?))"
    r"(?: already| now)?\s*,?\s*(?:and )?so,?\s+(?P<req>\S.*)$",
    _F,
)


def _errand41s(text: str, lexicon: Lexicon) -> str:
    """Session 41 (12s): where the person takes it, and what they have done to a surface, taken
    off (above)."""
    m = _TAKES_TO41S.search(text)
    if m is not None and _only_person(m["who"], lexicon) and not _names(m["where"], lexicon):
        (pid,) = _ids(m["who"], lexicon, "human")
        out = text[: m.start("to")].rstrip() + text[m.end("to") :]
        read = _reading(out, lexicon)
        if (
            read is not None
            and {t.target for t in tasks(read)} == {pid}
            and all(t.kind == "deliver" for t in tasks(read))
        ):
            return out
    d = _DONE_TO41S.match(text)
    if d is not None and _only_person(d["who"], lexicon):
        surface = d["s1"] or d["s2"]
        ids = _ids(surface, lexicon)
        if not ids or _ids(surface, lexicon, "surface") != ids:
            return text
        (pid,) = _ids(d["who"], lexicon, "human")
        req = d["req"]
        said = re.findall(r"\b(?:he|him|his|she|her|hers|they|them|their)\b", req, _F)
        if (
            len(said) != 1
            or said[0].lower() not in ("him", "her")
            or not _fit36(pid, said[0], lexicon)
            or _ids(req, lexicon, "human")
        ):
            return text
        out = re.sub(r"\b(?:him|her)\b", d["who"], req, count=1, flags=_F)
        out = out[:1].upper() + out[1:]
        read = _reading(out, lexicon)
        if read is not None and pid in {t.target for t in tasks(read)}:
            return out
    return text


# -- session 41 (12s): checks of the whole reading ----------------------------------------------
#
# "Tablets across to Mr Lee, oh, silly me, Mrs Khan's the one they're prescribed for.", "Give Bob
# the cup, Carol's the one.": '<a person>'s the one (…)' closing a request that gives that person
# nothing says the things may be theirs instead (a correction: the slip's cue 'oh' is a filler,
# and older rules took the rest for a remark and read the handover to Mr Lee) or is a remark:
# refused, naming both readings.
_THE_ONE41S = re.compile(
    r"(?:^|[,;.!?]\s*)(?:(?:oh|ah|well|no|sorry)\s*,?\s*)*(?P<who>[a-z]+(?: [a-z]+){0,2}?)"
    r"(?:'s| is) the (?:one|person)\b",
    _F,
)


def _the_one41s(text: str, node: Node, lexicon: Lexicon) -> None:
    """Session 41 (12s): '<a person>'s the one' of someone who gets nothing, refused (above)."""
    if "the one" not in text.lower() and "the person" not in text.lower():
        return
    given = [t for t in tasks(node) if t.kind == "deliver"]
    if not given:
        return
    for m in _THE_ONE41S.finditer(text):
        if m.start() == 0 or not _only_person(m["who"], lexicon):
            continue
        (pid,) = _ids(m["who"], lexicon, "human")
        if any(t.target == pid for t in given):
            continue
        read = _shown39s(node)
        objs = " & ".join(f"{t.obj}>{pid}" for t in given)
        raise GroundingError(
            f"{m['who']!r} is 'the one' but gets nothing in {read}: is it theirs instead ({objs}), "
            "or a remark? say who gets what"
        )


# "Give Alice the cup, she has the apple, and Bob the chips." had read the apple handed to her: a
# clause 'he / she has the <thing>' after a request that gives that person something else may say
# what they have already (a remark) or hand it over too ("Just the one item each …: she has the
# bottle, he has the crisps" hands them over: no request before it): refused naming both.
_HAS41S = re.compile(
    r"[,;]\s*(?:and\s+)?(?P<pron>he|she)\s+(?:has|already has|has already)\s+(?P<what>(?:the|his|"
    r"her)\s+[^,;.!?]+?)\s*(?=[,;.!?]|$)",
    _F,
)


_TOO41S = re.compile(r"\b(?:too|as well|also|an? (?:all|aswell))\b", _F)


def _has_it41s(text: str, node: Node, lexicon: Lexicon) -> None:
    """Session 41 (12s): 'he / she has the <thing>' after a request to them, refused (above)."""
    if " has " not in text.lower():
        return
    given = [t for t in tasks(node) if t.kind == "deliver"]
    for m in _HAS41S.finditer(text):
        objs = _ids(m["what"], lexicon, "object")
        if not objs or _ids(m["what"], lexicon) != objs or _TOO41S.search(m["what"]):
            continue
        before = text[: m.start()]
        had = [t for t in given if t.obj in objs and _fit36(t.target, m["pron"], lexicon)]
        if not had:
            continue
        pid = had[0].target
        earlier = [t for t in given if t.target == pid and t.obj not in objs]
        if not earlier or not any(_ids(before, lexicon, "object") & {t.obj} for t in earlier):
            continue
        read = _shown39s(node)
        rest = " & ".join(_shown39s(t) for t in given if t not in had) or "nothing else"
        raise GroundingError(
            f"{m.group(0).strip(' ,;')!r} may say what {person_name(pid, lexicon)} has already "
            f"({rest}) or hand it over too ({read}): say which"
        )


# the normaliser's rewrites run before the session-40 ones (wired into normalise._STEPS19)
_STEPS41S_FIRST: tuple[Callable[[str, Lexicon], str], ...] = (
    _occasion41s,
    _purpose41s,
    _all_for41s,
    _trade41s,
    _middle_remark41s,
    _group_remark41s,
    _placed_for41s,
    _errand41s,
)
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-40 ones)
_STEPS41S: tuple[Callable[[str, Lexicon], str], ...] = ()
# refusals asked of the text before it is read (offline._parse, after the session-40 ones)
REFUSE41S: tuple[Callable[[str, Lexicon], None], ...] = ()
# checks of the whole instruction's reading (offline.parse_instruction, after the session-40 ones)
CHECK41S: tuple[Callable[[str, Node, Lexicon], None], ...] = (_the_one41s, _has_it41s)
