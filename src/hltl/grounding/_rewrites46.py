"""The grounder's rules of session 46, engineer 12 (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import (
    _COMMON,
    _F,
    _KEEP_WORDS,
    _ids,
    _names,
    _objects_only,
    _only_person,
    _reading,
    _unknown_word,
)
from hltl.grounding._normalise2 import _asks_nothing29, _scene_words29
from hltl.grounding._normalise4 import _ORDER_LAST37, _owner_then37s
from hltl.grounding._rewrites38 import _pronouns38, _questions38
from hltl.grounding._rewrites38r import _who_asked38r
from hltl.grounding._rewrites39s import _remark_first39s
from hltl.grounding._rewrites41s import _occasion41s
from hltl.grounding._rewrites44 import _PRONOUNS44, _agrees44
from hltl.grounding._rewrites44r import _lone_going44r
from hltl.grounding._rewrites45 import _fits_only45, _person, _read_for, _read_for_said
from hltl.grounding._rewrites45r import _the_one45r
from hltl.grounding.lexicon import PRONOUN_SEX, VERBS, Lexicon
from hltl.grounding.tree import Node, tasks

# -- session 46 (engineer 12): blind44's refusals of politeness and fillers, wants and needs,
# pronouns and ellipsis and questions, each read as a family. Every rule rewrites to words the
# grammar (or an older rule) already reads, and keeps the rewrite only when it reads.


def _older_reads46(text: str, lexicon: Lexicon, *steps: Callable[[str, Lexicon], str]) -> bool:
    """Whether one of the older ``steps`` reads ``text``: its sentence is left to that rule
    (each sentence is read by one rule: the older tests take the older rule out and expect a
    refusal; session 47's -k set found the overlaps)."""
    for step in steps:
        out = step(text, lexicon)
        if out != text and _reading(out, lexicon) is not None:
            return True
    return False


# -- thanks ahead in another language opening the request ("Khublei in advance, could the red mug
# go across to Carol, please?", "Dziekuje so much, …"): a word no English word the grounder knows
# (no first name, no name of the scene: _unknown_word, _names) before 'in advance' / 'so much' /
# 'again' and a comma, said 'Thanks in advance,' (session 24 knows the common ones by name)
_THANKS_AHEAD46 = re.compile(
    r"^(?P<w>[A-Za-z][a-z]+) (?:in advance|so much|very much|ever so much|muchly|again|a lot|"
    r"a million)\s*[,:;!]\s*(?=\S)",
    _F,
)


def _thanks_ahead46(text: str, lexicon: Lexicon) -> str:
    """Session 46: the opening thanks above said as 'Thanks in advance,'."""
    m = _THANKS_AHEAD46.match(text)
    if m is None or not _unknown_word(m["w"], lexicon) or _names(m["w"], lexicon):
        return text
    return _read_for(f"Thanks in advance, {text[m.end() :]}", text, None, lexicon)


# -- an apology for asking again opening the request, then 'only' for 'but' ("Sorry to nag, only
# Person B is still hoping for the bottle, would you?", "Hate to be a pest, only Tom's still
# waiting on the tape."); and an apology for cutting in said with 'pardon / excuse / forgive me'
# ("Pardon me for butting in, the bottle for Person A …", "Forgive me for interrupting, …"): the
# apology taken off (the 'me' of it is the speaker, no recipient). Kept only when what is left
# reads.
_APOLOGY_ONLY46 = re.compile(
    r"^(?:(?:i'm |i am )?(?:so |very |really |terribly |awfully )?sorry|i hate|hate|forgive me|"
    r"pardon me|excuse me) (?:to|for) (?:nag|nagging|go on|going on|keep on|keeping on|harp on|"
    r"harping on|pester you|pestering you|bother you|bothering you|chase|chasing|ask again|"
    r"asking again|be a (?:pain|pest|nuisance|bore)|being a (?:pain|pest|nuisance|bore))"
    r"(?: again| about it| you)?\s*,\s*(?:only|but)\s+(?=\S)"
    r"|^(?:pardon|excuse|forgive) me(?: for (?:butting in|barging in|cutting in|jumping in|"
    r"chipping in|breaking in|interrupting|intruding|asking|the interruption|the intrusion|"
    r"bothering you|nagging))\s*,\s*(?:but\s+)?(?=\S)",
    _F,
)


def _apology46(text: str, lexicon: Lexicon) -> str:
    """Session 46: the apology above taken off."""
    m = _APOLOGY_ONLY46.match(text)
    if m is None:
        return text
    rest = text[m.end() :]
    return _read_for(rest[:1].upper() + rest[1:], text, None, lexicon)


# -- a want said by what the person would give for it ("Person A would give her eye teeth for that
# bottle right now", "Tom'd give his back teeth for the tape"): said with 'would give anything
# for', which session 42's idiom rule reads as 'wants' (the person before it, objects only after)
_GIVE_TEETH46 = re.compile(
    r"(?P<v>(?: would|'d) (?:happily |gladly )?give )(?:his|her|their|my) (?:eye teeth|back teeth|"
    r"left arm|last penny|last pound|last quid|last fiver)(?= for )|(?P<v2>(?: would|'d) "
    r"(?:happily |gladly )?give )(?:a kidney|an arm and a leg|a limb)(?= for )",
    _F,
)


def _give_teeth46(text: str, lexicon: Lexicon) -> str:
    """Session 46: the idiom above said as 'would give anything for'."""
    if " give " not in text.lower():
        return text
    m = _GIVE_TEETH46.search(text)
    if m is None:
        return text
    out = f"{text[: m.start()]}{m['v'] or m['v2']}anything{text[m.end() :]}"
    return _read_for(out, text, None, lexicon)


# -- a want said by what the thing would do for the person ("…, the chips would do her nicely",
# "the apple would set him right", "the bottle would see her right"): said 'would do her good',
# which session 42's rule reads as handing it to the one person named before it whom the pronoun
# may be. And the same said as what the person thinks ("Person B reckons the chips would set him
# right before the quickstep heats"): 'Person B wants the chips …', the pronoun the person's
# (_fits_only45: it may be P, and no one else of the scene is said to be of that sex).
_DO_GOOD46 = (
    r"(?:do (?P<p1>him|her|them) (?:nicely|fine|nicely thanks|a treat|the world)|(?:set|see|put)"
    r" (?P<p2>him|her|them) right|sort (?P<p3>him|her|them) out|(?:buck|perk|pick|cheer|fix) "
    r"(?P<p4>him|her|them) (?:up|right up)|sort (?P<p5>him|her|them) right out)"
)
_WOULD_SUIT46 = re.compile(
    rf"(?P<x>(?:the|that|this|those|these) [a-z][a-z ]*?) (?P<m>would|will|'d|'ll) "
    rf"(?:really |just |honestly |absolutely )?{_DO_GOOD46}",
    _F,
)
_RECKONS46 = re.compile(
    r"(?P<p>\b[A-Za-z][\w]*(?: [A-Z][\w]*)?) (?:reckons|thinks|says|swears|is sure|'s sure|"
    r"reckoned|thought|said|swore)(?: that)? "
    rf"(?P<x>(?:the|that|this|those|these) [a-z][a-z ]*?) (?:would|will|'d|'ll) "
    rf"(?:really |just |honestly |absolutely )?{_DO_GOOD46}",
    _F,
)


def _would_suit46(text: str, lexicon: Lexicon) -> str:
    """Session 46: the want above said 'would do her good' (or 'P wants X')."""
    low = text.lower()
    if " would " not in low and "'d " not in low and " will " not in low and "'ll " not in low:
        return text
    m = _RECKONS46.search(text)
    if m is not None and _objects_only(m["x"], lexicon):
        pid = _person(m["p"], lexicon)
        pron = next(g for g in m.groups()[2:] if g is not None)
        if pid is not None and _fits_only45(pid, pron, lexicon):
            out = f"{text[: m.start()]}{m['p']} wants {m['x']}{text[m.end() :]}"
            return _read_for(out, text, pid, lexicon)
        return text
    m = _WOULD_SUIT46.search(text)
    if m is None or not _objects_only(m["x"], lexicon):
        return text
    pron = next(g for g in m.groups()[2:] if g is not None)
    out = f"{text[: m.end('m')]} do {pron} good{text[m.end() :]}"
    return _read_for(out, text, None, lexicon)


# -- 'all' in a remark's time or way, naming nothing of the scene ("Person B's parched after cloud
# spotting all afternoon, he needs the cup", "…, seeing he's come all this way?"): how long or how
# far, not every thing of the scene: the time after a doing ('spotting all afternoon'; older
# rules read 'been out all day' and the like) taken off, the way said 'a long way' (older rules
# take the remark off then), when those words name nothing of the scene; 'seeing he's' said
# 'seeing as he's'. Kept only when the whole reads.
_ALL_TIME46 = re.compile(
    r"(?<=ing)\s+all (?:day|afternoon|morning|evening|night|week|weekend|month|year|season|summer|"
    r"winter|term|shift)(?: long)?\b(?=\s*(?:[,.;:!?]|$))"
    r"|\b(?P<way>all (?:this|that|the) way)(?: (?:here|over|in|down|up|across|round))?\b"
    r"(?=\s*(?:[,.;:!?]|$))",
    _F,
)
_SEEING46 = re.compile(
    r",\s*seeing (?=(?:he|she|they|you|i|we)(?:'s|'re|'ve|'d| is| has| was)\b)", _F
)


def _all_said46(text: str, lexicon: Lexicon) -> str:
    """Session 46: the time and way above said without 'all'."""
    if "all " not in text.lower():
        return text
    out = text
    for m in list(_ALL_TIME46.finditer(text))[::-1]:
        if _names(m[0], lexicon):
            continue
        said = "a long way" if m["way"] else ""
        out = out[: m.start()] + said + out[m.end() :]
    if out == text:
        return text
    out = _SEEING46.sub(", seeing as ", out)
    return _read_for(out, text, None, lexicon)


# -- a request asked as what the hearer thinks ("Do you reckon the cup could go across to Person
# A, seeing as …?"): said as the question it wraps ('Could the cup go across to Person A, …?'),
# kept only when that reads; "… you could …" (session 36's) and "… P could have / get X"
# (session 33's) are left to older rules
_YOU_RECKON46 = re.compile(
    r"^(?P<o>(?:(?:so|and|oh|well|erm|um),? )*)(?:do|d') ?you (?:reckon|think|suppose|imagine|"
    r"figure)(?: that)?,? (?P<x>(?!you\b)[a-z][^,;.?!]*?) (?P<m>could|can|might)\b"
    # 'P could have / get / take / use X' is session 33's (_THINK_COULD33)
    r"(?! (?:have|get|take|use)\b)",
    _F,
)


def _you_reckon46(text: str, lexicon: Lexicon) -> str:
    """Session 46: the question above said as the question it wraps."""
    m = _YOU_RECKON46.match(text)
    if m is None or not text.rstrip().endswith("?"):
        return text
    out = f"{m['o']}{m['m'].capitalize()} {m['x']}{text[m.end() :]}"
    return _read_for(out[:1].upper() + out[1:], text, None, lexicon)


# -- 'when you're done' closing the request: when the hearer is free, as 'when you're free'
# (which the grammar reads, in a question too) says ("Could you put the small spanner away in the
# locker when you're done?", "…, when you're through.")
_DONE46 = re.compile(
    r"(?P<sep>,?\s+)when you(?:'re| are) (?:done|through|all done)(?: there| with that| here)?"
    r"(?P<end>\s*[.?!]*)\s*$",
    _F,
)


def _when_done46(text: str, lexicon: Lexicon) -> str:
    """Session 46: 'when you're done' above said 'when you're free'."""
    m = _DONE46.search(text)
    if m is None:
        return text
    out = f"{text[: m.start()]}{m['sep']}when you're free{m['end']}"
    return _read_for(out, text, None, lexicon)


# -- what the thing is for, said with any verb closing a want or a handover to one person ("Could
# Dana have the spoon to stir the buffer?", "Mia needs the barcode scanner to log the scrap
# dealer's load."): taken off when its verb is no verb the grounder reads (give, put, take, …),
# its words name nothing of the scene and ask nothing (_asks_nothing29: no verb but the last
# noun, no 'all', 'it', 'not', no his / her), and the rest reads handing things to one person.
# Session 34 and 12s's session 42 know a closed list of such verbs; this is any verb, with a
# doing after it ("… to finish drawing his xiangqi board").
_TO_PURPOSE46 = re.compile(
    r"(?P<sep>\s*,?\s+)to (?P<v>[a-z]+)(?: (?P<g>[a-z]{2,}ing))? (?P<det>the|a|an|his|her|their|"
    r"some|its) "
    r"(?P<words>[a-z][a-z' -]*?)(?P<end>\s*[.!?]*)\s*$",
    _F,
)


def _to_purpose46(text: str, lexicon: Lexicon) -> str:
    """Session 46: the purpose above taken off."""
    if " to " not in text:
        return text
    m = _TO_PURPOSE46.search(text)
    if m is None or m["v"].lower() in VERBS or m["v"].lower() not in _COMMON:
        return text
    g = (m["g"] or "").lower()
    if g and {g, g[:-3], g[:-3] + "e", g[:-4]} & VERBS.keys():
        return text  # 'giving', 'putting', 'sticking': a verb the grounder reads
    # a his / her / their is asked of the person given to (_read_for_said), not of the remark
    owner = m["det"].lower() in ("his", "her", "their")
    words = f"{'the' if owner else m['det']} {m['words']}"
    # a noun after a determiner or an owner ("the scrap dealer's load") is no verb to read
    *head, noun = words.rsplit(" ", 1)
    if head and (head[0].endswith("'s") or head[0] == m["det"]) and noun.lower() in VERBS:
        words = f"{head[0]} x"
    if _KEEP_WORDS.search(m["words"]) or not _asks_nothing29(words, lexicon):
        return text
    said = m["det"] if owner else words
    return _read_for_said(text[: m.start()] + m["end"].strip(), text, said, lexicon)


# -- a remark naming the thing (and whose it is, or who is after it), then the request for it by a
# pronoun ("The ostler's boots keep catching the bottle; up on the shelf with it, would you.",
# "That apple was set aside for Person A at the swan upping; run it over to her.", "Mr Lee's
# tablets are overdue by the clock on the wall; take them over to him.", "The bottle's Person A's.
# Hand it across to her, thanks."): the request alone, the thing said for its 'it' / 'them' (of
# the thing's number) and the person for its 'him' / 'her' (who must fit, _fits_only45). The
# remark names one thing and at most one person, names no surface, says nothing of a condition,
# a choice or a negation, and reads as nothing or as what the request then reads as; the request
# names no thing itself.
_REMARK_IT46 = re.compile(r"^(?P<r>[^;.:!?]+?)\s*(?:;|:|[.!?](?=\s+[A-Z]))\s+(?P<q>\S.*)$")
_NOT_REMARK46 = re.compile(
    r"\b(?:if|unless|not|no|never|nobody|nothing|none|or|instead|except|without|rather|but|"
    r"only|whether|whoever|whichever|either|neither|another|other|else|both|all|each|every|any|"
    r"and|it|them|him|her|he|she|they|give|hand|pass|bring|take|put|get|left|leave|leaves)\b|"
    r"n't\b",
    _F,
)
# a request that takes something back or says someone has one already is no plain request
_NOT_REQUEST46 = re.compile(r"\b(?:hang on|hold on|wait|actually|got one|has one|sorry)\b", _F)


def _remark_it46(text: str, lexicon: Lexicon) -> str:
    """Session 46: the request after the remark above, its pronouns said."""
    # session 50 (12p): the text's own tests first (each returns the text, as the older
    # rules' reading does, so the order changes nothing): the older rules are run only for a
    # text this rule could read
    m = _REMARK_IT46.match(text)
    if m is None or _NOT_REMARK46.search(m["r"]) or _NOT_REQUEST46.search(m["q"]):
        return text
    if _older_reads46(text, lexicon, _owner_then37s, _pronouns38, _lone_going44r):
        return text
    named = _names(m["r"], lexicon)
    things = [it for it in named if all(r.kind == "object" for r in it.refs)]
    people = [it for it in named if all(r.kind == "human" for r in it.refs)]
    if len(things) != 1 or len(people) > 1 or len(things) + len(people) != len(named):
        return text
    if len({r.id for r in things[0].refs}) != 1 or _ids(m["q"], lexicon, "object"):
        return text
    (thing,) = things
    plural = thing.refs[0].plural or thing.text.lower().endswith("s")
    pron = "them" if plural else "it"
    q = _IT_HIM46.sub(r"\g<v> \g<x> to ", m["q"])  # 'bring it him' (below)
    q = _with_it_said46(q, lexicon) or q  # 'up on the shelf with it' (below)
    if not re.search(rf"\b{pron}\b", q, _F):
        return text
    out = re.sub(rf"\b{pron}\b", f"the {thing.text}", q, count=1, flags=_F)
    said = _PRONOUNS44.findall(out)
    pid = people[0].refs[0].id if people else None
    if said:
        if pid is None or len({PRONOUN_SEX[w.lower()] for w in said}) != 1:
            return text
        if not _fits_only45(pid, " ".join(said), lexicon):
            return text
        out = re.sub(r"\b(?:him|her)\b", people[0].text, out, count=1, flags=_F)
    read = _reading(out, lexicon)
    if read is None:
        return text
    if pid is not None and {t.target for t in tasks(read) if t.kind == "deliver"} - {pid}:
        return text
    alone = _reading(m["r"], lexicon)
    if alone is not None and set(tasks(alone)) != set(tasks(read)):
        return text
    return out


# -- the place first, then 'with it' ("Up on the shelf with it, would you.", "Onto the desk with
# the stapler, please.", "Over to Bob with the apple."): said 'put it up on the shelf' (a
# surface) or 'take the apple over to Bob' (a person)
_WITH_IT46 = re.compile(
    r"^(?P<o>(?:(?:right|so|now|ok|okay|and|then|go on)[,!]? )*)(?P<where>(?:(?:up|down|back|"
    r"over|across|round) )?(?:on|onto|on to|in|into|to) (?:the )?[A-Za-z][\w ]*?) with "
    r"(?P<x>it|them)(?P<rest>\s*(?:[,.!?].*)?)$",
    _F,
)


def _with_it_said46(text: str, lexicon: Lexicon) -> str | None:
    """``text`` ('up on the shelf with it, …') said 'put it up on the shelf, …', or None."""
    if " with " not in text.lower():
        return None
    m = _WITH_IT46.match(text)
    if m is None:
        return None
    where = m["where"]
    if _ids(where, lexicon, "surface") and not _ids(where, lexicon, "human"):
        verb = "put"
    elif _only_person(where, lexicon):
        verb = "take"
    else:
        return None
    out = f"{m['o']}{verb} {m['x']} {where}{m['rest']}"
    return out[:1].upper() + out[1:]


def _with_it46(text: str, lexicon: Lexicon) -> str:
    """Session 46: the place above said after 'put it' / 'take it' ('with the scanner' is
    session 33's `_onto_with33r`)."""
    out = _with_it_said46(text, lexicon)
    return text if out is None else _read_for(out, text, None, lexicon)


# -- 'bring it him' (the thing before the person, without 'to': "Bring it him, please."): said
# 'bring it to him'
_IT_HIM46 = re.compile(
    r"\b(?P<v>give|bring|take|hand|pass|send|fetch|get) (?P<x>it|them) (?=(?:him|her)\b)", _F
)


def _it_him46(text: str, lexicon: Lexicon) -> str:
    """Session 46: 'it him' said 'it to him'."""
    m = _IT_HIM46.search(text)
    if m is None:
        return text
    return _read_for(f"{text[: m.end('x')]} to {text[m.end('x') + 1 :]}", text, None, lexicon)


# -- ', for peace' closing the request (why: "…, let him have it, for peace."): said ', for a quiet
# life', which session 2x's remark rules take off
_FOR_PEACE46 = re.compile(
    r",\s*for (?:some |a bit of |the sake of )?peace(?: and quiet)?(?:'s sake)?(?=\s*[.!]*\s*$)",
    _F,
)


def _for_peace46(text: str, lexicon: Lexicon) -> str:
    """Session 46: ', for peace' said ', for a quiet life'."""
    if "peace" not in text.lower():
        return text
    out = _FOR_PEACE46.sub(", for a quiet life", text)
    return text if out == text else _read_for(out, text, None, lexicon)


# -- 'her X … to her' ('take her medication over to her', 'bring him his coat'): the thing of the
# one the pronoun gives it to, said 'the X' (the owner is the one given to; 'his … to her' and
# 'her … to him' name two people and stay refused, session 7's policy)
_OWN_THING46 = re.compile(
    r"\b(?P<v>give|bring|take|hand|pass|fetch|get|send|carry|run|pop) (?:(?P<pos>his|her) "
    r"(?P<x>[a-z][a-z ]*?) (?P<part>(?:(?:over|across|back|up|down|round) )?to) (?P<to>him|her)"
    r"|(?P<to2>him|her) (?P<pos2>his|her) (?P<x2>[a-z][a-z ]*?))(?=\s*(?:[,.;!?]|$))",
    _F,
)


def _own_thing46(text: str, lexicon: Lexicon) -> str:
    """Session 46: the owner's his / her above said 'the'."""
    m = _OWN_THING46.search(text)
    if m is None:
        return text
    pos, to, x = (m["pos"], m["to"], m["x"]) if m["pos"] else (m["pos2"], m["to2"], m["x2"])
    if PRONOUN_SEX[pos.lower()] != PRONOUN_SEX[to.lower()] or not _objects_only(x, lexicon):
        return text
    start = m.start("pos") if m["pos"] else m.start("pos2")
    out = f"{text[:start]}the{text[start + len(pos) :]}"
    return _read_for(out, text, None, lexicon)


# -- a closing remark of why not the other thing of the kind ("Could Mr Novak have the blue plate,
# the white one's too plain for him?", "Give Zoe the red book, the green one's a bit babyish for
# her."): taken off when it names a thing of the scene of the handed thing's kind ('the white
# one': its noun for 'one') that the rest does not hand, and its him / her may be the one person
# the rest hands to
_OTHER_TOO46 = re.compile(
    r",\s*(?P<x>the [a-z][a-z ]*?)(?:'s| is|'re| are) (?:(?:a bit |a touch |far |way |much |"
    r"rather |just )?too|a bit|a touch|a little|rather) [a-z]+(?: for (?P<p>him|her|them))?"
    r"(?P<end>\s*[.?!]*)\s*$",
    _F,
)


def _other_too46(text: str, lexicon: Lexicon) -> str:
    """Session 46: the remark above taken off."""
    low = text.lower()
    if "too " not in low and "a bit " not in low and "a touch " not in low and "rather " not in low:
        return text
    m = _OTHER_TOO46.search(text)
    if m is None:
        return text
    head = text[: m.start()]
    out = head + (m["end"].strip() or ".")
    read = _reading(out, lexicon)
    if read is None:
        return text
    handed = {t.obj for t in tasks(read)}
    x = m["x"]
    nouns = {
        it.text.split()[-1].lower()
        for it in _names(head, lexicon)
        if it.refs and all(r.kind == "object" for r in it.refs)
    }
    if len(nouns) != 1:
        return text
    (noun,) = nouns
    if x.lower().endswith(" one"):
        x = f"{x[:-4]} {noun}"
    elif x.split()[-1].lower() != noun:
        return text  # another kind of thing: not why this one rather than that
    other = _ids(x, lexicon, "object")
    if not other or other & handed or _ids(x, lexicon, "human") or _ids(x, lexicon, "surface"):
        return text
    given = {t.target for t in tasks(read) if t.kind == "deliver"}
    if m["p"] and (len(given) != 1 or not _fits_only45(next(iter(given)), m["p"], lexicon)):
        return text
    return out


# -- 'that one' / 'this one' with no thing named anywhere in the instruction ("Take that one to
# her as well."): refused naming each thing of the scene it could be (the grammar refused it for
# the pronoun, naming no thing)
_THAT_ONE46 = re.compile(r"\b(?:that|this|the other) one\b", _F)


def _that_one46(text: str, lexicon: Lexicon) -> str:
    """Session 46: 'that one' above refused naming what it could mean."""
    if " one" not in text.lower() or _THAT_ONE46.search(text) is None:
        return text
    if _ids(text, lexicon, "object") or _ids(text, lexicon, "surface"):
        return text
    said_words = _scene_words29(lexicon)
    if re.search(r"\b(?:other|neither|nor|not|no|just|only)\b", text, _F) or any(
        len(w) > 1 and w in said_words and not _ids(w, lexicon, "human")
        for w in re.findall(r"[a-z]+", text.lower())
    ):
        return text  # 'the small one … the other one': session 40's
    objs = [o.id for o in lexicon.scene.objects]
    if len(objs) < 2 or re.search(r"[.;:!?]\s+\S", text):
        return text
    said = _THAT_ONE46.search(text)[0]  # type: ignore[index]
    raise GroundingError(
        f"{said!r} names nothing said before it: it could mean " + " or ".join(objs)
    )


# -- blind43's four left (12r's notes, session 45) ------------------------------------------------

# "The bottle's not for Person A, it's Person B who's after it, he's been punting.": the thing
# not for one person, then a cleft naming the one it is for: said 'Person B is after the bottle,
# …' (the 'not' is corrected at once, by name; a he / she after it must fit that person)
_NOT_FOR_CLEFT46 = re.compile(
    r"^(?P<x>(?:the|that|this|those|these) [a-z][a-z ]*?)(?:'s not|'s no longer| is not| isn't|"
    r"'re not| are not| aren't) for (?P<p>[A-Za-z][\w]*(?: [A-Za-z][\w]*)?),\s*(?:it's|it is) "
    r"(?P<q>[A-Za-z][\w]*(?: [A-Za-z][\w]*)?) (?:who|that)(?:'s| is|'s been| has been)? "
    r"(?:after|asking for|waiting on|waiting for|wanting|wants|needs) (?P<pron>it|them)"
    r"(?P<rest>(?:\s*[,.;!].*)?)$",
    _F,
)


def _not_for_cleft46(text: str, lexicon: Lexicon) -> str:
    """Session 46: the correction above said as the want of the one named last."""
    if "not for" not in text.lower() and "n't for" not in text.lower():
        return text  # (session 50, 12p: before the older rule's reading, as in _remark_it46)
    if _older_reads46(text, lexicon, _who_asked38r):
        return text
    m = _NOT_FOR_CLEFT46.match(text)
    if m is None or not _objects_only(m["x"], lexicon):
        return text
    p, q = _person(m["p"], lexicon), _person(m["q"], lexicon)
    if p is None or q is None or p == q or not _agrees44(q, m["rest"] or "", lexicon):
        return text
    x = m["x"]
    out = f"{m['q']} is after {x[:1].lower()}{x[1:]}{m['rest'] or '.'}"
    return _read_for(out, text, q, lexicon)


# a remark of what the person is doing opening the instruction, with when ("Emma's rinsing
# brushes after lampwork and either cup will do, so take her one."): the 'after …' taken off when
# it names nothing and asks nothing (the rest must read)
_DOING_AFTER46 = re.compile(
    r"^(?P<head>[A-Z][\w]*(?: [A-Z][\w]*)?(?:'s| is) [a-z]+ing(?: [a-z]+){0,3}?) (?:after|since|"
    r"following) (?P<w>[a-z][a-z' ]*?)(?=\s*(?:,|;| and | so ))",
    _F,
)


def _doing_after46(text: str, lexicon: Lexicon) -> str:
    """Session 46: the time in the opening remark above taken off."""
    m = _DOING_AFTER46.match(text)
    if m is None or not _only_person(m["head"].split("'")[0].rsplit(" is", 1)[0], lexicon):
        return text
    if " is " in m["head"]:
        return text  # "Emma is rinsing brushes after lampwork and …" is 12r's _will_do_one45r
    if not _asks_nothing29(m["w"], lexicon) or _KEEP_WORDS.search(m["w"]):
        return text
    return _read_for(m["head"] + text[m.end() :], text, None, lexicon)


# a craft named bare after a want ("Not the crisps, Bob wants the bottle after basketry."): said
# as session 35's pastimes are ('after crochet'), which are taken off as why, not when; a closed
# list of crafts (an event, 'after surgery', 'after work', says when and stays refused)
_CRAFT46 = re.compile(
    r"\b(?P<a>after|since) (?P<w>basketry|lampwork|woodwork|metalwork|leatherwork|beadwork|"
    r"fretwork|stonework|ironwork|glasswork|marquetry|joinery|carpentry|falconry|cookery|"
    r"tapestry|upholstery|masonry|taxidermy|calligraphy|photography|pyrography|scrimshaw|"
    r"quillwork|papermaking|woodturning|glassblowing|silversmithing|blacksmithing)"
    r"(?=\s*(?:[,.;!?]|$))",
    _F,
)


def _craft46(text: str, lexicon: Lexicon) -> str:
    """Session 46: the craft above said 'crochet'."""
    m = _CRAFT46.search(text)
    if m is None or _names(m["w"], lexicon):
        return text
    return _read_for(f"{text[: m.end('a')]} crochet{text[m.end() :]}", text, None, lexicon)


# an opening reason naming nothing of the scene, then 'so' and the request ("The letter carver's
# quote needs signing, so any pen at all for Sam, black, blue or red."): the request alone (which
# must read; the reason names no thing, person or surface and says no negation or condition)
_SO_REASON46 = re.compile(r"^(?P<r>[A-Z][^,;.!?]*?),? so (?P<q>\S.*)$")


def _so_reason46(text: str, lexicon: Lexicon) -> str:
    """Session 46: the reason above taken off."""
    if " so " not in text:
        return text  # (session 50, 12p: before the older rule's reading, as in _remark_it46)
    if _older_reads46(text, lexicon, _remark_first39s):
        return text
    m = _SO_REASON46.match(text)
    if m is None or _names(m["r"], lexicon) or _NOT_REMARK46.search(m["r"]):
        return text
    q = m["q"]
    return _read_for(q[:1].upper() + q[1:], text, None, lexicon)


# -- why or where exactly, closing a placement ("Can the notebook go in the box so Priya stops
# losing it?", "Would you stick that packing tape on the pallet ready for Tom's load?", "Could
# the apple go on the counter, next to where Alice does her cross-stitch?"): taken off when the
# rest reads as placements only and the words name no thing or surface of the scene (a person
# may be named: the one the placement is for, not given anything; 'so P can have it' may mean
# a handover and stays refused)
_NAME46 = r"(?-i:[A-Z])[\w]*(?: (?-i:[A-Z])[\w]*)?"
_PLACED_SO46 = re.compile(
    rf"(?P<sep>,?\s+)(?:so (?:that )?(?P<so>{_NAME46}|he|she|they) (?:stops|doesn't|won't|"
    rf"can't|knows)\b|ready for (?P<owner>{_NAME46})'s [a-z]|(?:next to|near|by|beside) where "
    rf"(?P<near>{_NAME46}) )(?P<words>[^,;.!?]*)(?P<end>\s*[.?!]*)\s*$",
    _F,
)


def _placed_so46(text: str, lexicon: Lexicon) -> str:
    """Session 46: the closer above taken off a placement."""
    m = _PLACED_SO46.search(text)
    if m is None or m.start() == 0:
        return text  # (session 50, 12p: before the older rule's reading, as in _remark_it46)
    if _older_reads46(text, lexicon, _questions38):
        return text
    tail = text[m.start() : m.start("end")]
    if _ids(tail, lexicon, "object") or _ids(tail, lexicon, "surface"):
        return text
    who = m["so"] or m["owner"] or m["near"]
    if who.lower() not in ("he", "she", "they") and not _only_person(who, lexicon):
        return text
    out = text[: m.start()] + (m["end"].strip() or ".")
    read = _reading(out, lexicon)
    if read is None or any(t.kind != "place" for t in tasks(read)):
        return text
    return out


# -- a want closed by the speaker's pick ("Bob's dying for something to nibble on after axe
# throwing, the apple I'd say."): 'I'd say' said 'I reckon' (which the grammar reads as the pick),
# and a pastime named bare by its doing after a want ('after axe throwing') taken off as why, not
# when, when the clause it closes is no order (an order 'after cleaning' is put off) and it names
# nothing and asks nothing
_ID_SAY46 = re.compile(r"(?<=[a-z]) i'd (?:say|think|guess)(?=\s*[.!]*\s*$)", _F)
_BARE_DOING46 = re.compile(
    r"\s+(?:after|since) (?P<d>(?!(?:the|a|an|his|her|their|my|our|your)\b)(?:[a-z]+ )?"
    r"[a-z]{3,}ing)"
    r"(?=\s*(?:[,;.!?]|$))",
    _F,
)


def _bare_doing46(text: str, lexicon: Lexicon) -> str:
    """Session 46: the pick and the doing above."""
    if "'d " not in text and " after " not in text.lower() and " since " not in text.lower():
        return text  # (session 50, 12p: before the older rules' reading, as in _remark_it46)
    if _older_reads46(text, lexicon, _occasion41s, _the_one45r):
        return text
    out = _ID_SAY46.sub(" I reckon", text)
    m = _BARE_DOING46.search(out)
    if (
        m is not None
        and not _ORDER_LAST37.search(out[: m.start()])
        and _asks_nothing29(m["d"], lexicon)
        and not _KEEP_WORDS.search(m["d"])
        and not _ids(out[: m.start()], lexicon, "surface")
    ):
        out = out[: m.start()] + out[m.end() :]
    return text if out == text else _read_for(out, text, None, lexicon)


_STEPS46_FIRST: tuple[Callable[[str, Lexicon], str], ...] = (
    _thanks_ahead46,
    _apology46,
    _give_teeth46,
    _would_suit46,
    _all_said46,
    _you_reckon46,
    _when_done46,
    _to_purpose46,
    _remark_it46,
    _with_it46,
    _it_him46,
    _for_peace46,
    _own_thing46,
    _other_too46,
    _that_one46,
    _not_for_cleft46,
    _doing_after46,
    _craft46,
    _so_reason46,
    _placed_so46,
    _bare_doing46,
)
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-45 ones)
_STEPS46: tuple[Callable[[str, Lexicon], str], ...] = ()
# refusals asked of the text before it is read (offline._parse, after the session-45 ones)
REFUSE46: tuple[Callable[[str, Lexicon], None], ...] = ()
# checks of the whole instruction's reading (offline.parse_instruction, after the session-45 ones)
CHECK46: tuple[Callable[[str, Node, Lexicon], None], ...] = ()
