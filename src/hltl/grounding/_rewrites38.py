"""The normaliser's rewrites of session 38, engineer 12 (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.grounding import gate as re
from hltl.grounding._normalise1 import (
    _F,
    _ids,
    _names,
    _names_nothing,
    _only_person,
    _reasons21,
    _surface_only,
)
from hltl.grounding._normalise2 import (
    _ASKS29,
    _BACK_FROM36,
    _asks_nothing29,
    _scene_words29,
    _things31,
)
from hltl.grounding._normalise4 import _EVENTS37, _P37, _WANT_FRAME37, _fit36
from hltl.grounding._normalise5 import _DOER37
from hltl.grounding.lexicon import PRONOUN_SEX, VERBS, Lexicon

# -- session 38 (engineer 12): blind36's refusals by kind in the sections of politeness, wants,
# pronouns and ellipsis, splits and run-ons, lower case, typos and questions. As session 37's:
# each rule a closed pattern checked against the scene; a remark goes only when it names nothing
# of the scene and asks nothing (_asks_nothing29), and a pronoun only where it may be the one
# person it is said of (_fit36).

# -- a text written without punctuation: a remark about the person (he's / she's …) run on after
# the request, with a courtesy before it or not ("chips for person a please shes back from her
# jenga tournament", "bottle to person b when youre free hes been out …")
_RUN_ON38 = re.compile(
    r"(?<=[a-z])\s+(?:(?P<c>please|cheers|thanks|thx|ta)\s+)?(?P<pron>he|she)"
    r"(?P<v>s|'s| is| has| was)\s+(?=[a-z])",
    _F,
)
# words after which a clause is joined to the one before, not run on
_JOINS38 = frozenset(
    {
        "when", "once", "if", "because", "cos", "as", "so", "and", "but", "that", "till", "until",
        "since", "before", "after", "while", "where", "unless", "or", "then", "whether", "what",
        "who", "which", "think", "thinks", "say", "says", "said", "know", "knows", "hope", "guess",
        "reckon", "bet", "sure", "tell", "told", "ask", "asked", "whom", "how", "why", "though",
    }
)  # fmt: skip


def _inert38(words: str, lexicon: Lexicon) -> bool:
    """Whether ``words`` asks nothing (_asks_nothing29) once its articles are taken out ('a' is
    no Person A) and a hyphened word is read as one ('three-legged' counts nothing)."""
    plain = re.sub(r"\b(?:a|an|the)\b", " ", words.replace("-", ""), flags=_F)
    return _asks_nothing29(plain, lexicon)


def _doer38(words: str, lexicon: Lexicon) -> bool:
    """Whether ``words`` (one or two words) is someone by their trade: a word for a doer last
    (_DOER37: 'caterer', 'repairer', 'lollipop man'), no word of a scene name, naming nothing and
    asking nothing (a verb of the grammar may say what they do: 'the set designer')."""
    said = words.lower().split()
    if not 1 <= len(said) <= 2 or len(said[-1]) < 3 or not _DOER37.search(said[-1]):
        return False
    if said[-1] in VERBS or any(w in _scene_words29(lexicon) for w in said):
        return False
    return _names_nothing(words, lexicon) and _ASKS29.search(words) is None


def _run_on38(text: str, lexicon: Lexicon) -> str:
    """Session 38: in a text with no comma, colon or semicolon, ', ' put before a he's / she's
    (and a courtesy word before it) run on after a request that names one person the pronoun may
    be, and closing it (naming nothing after it, and asking nothing but the person's own and 'all
    day'): what the writer left out, so that the remark rules see the remark as a part of its own
    (session 21's reasons, which run before this, asked again here). Not after a word that joins
    the clause to the one before ('when', 'that', 'so' …)."""
    if re.search(r"[,;:]", text) or _BACK_FROM36.search(text):
        return text  # "… thx hes the one back from surfing": session 36's, read as it is
    m = _RUN_ON38.search(text)
    if m is None:
        return text
    said = re.sub(
        r"\b(?:his|her|their|all (?:day|morning|afternoon|evening|night|week))\b",
        " ",
        text[m.end() :],
        flags=_F,
    )
    if _ASKS29.search(said):
        return text  # "give the bottle to bob he's not here": the remark says more than a state
    before = text[: m.start()]
    words = before.split()
    if not words or words[-1].lower() in _JOINS38 or words[-1].lower() in VERBS:
        return text
    people = _ids(before, lexicon, "human")
    if len(people) != 1 or not _ids(before, lexicon, "object") or _names(text[m.end() :], lexicon):
        return text  # what follows names more: a request run on, not a remark closing one
    if not _fit36(next(iter(people)), m["pron"], lexicon):
        return text
    # the courtesy word goes, as session 19's fillers take it off; session 21's reasons (run
    # before this) are asked again of the text with its comma
    return _reasons21(f"{before}, {m['pron']}{m['v']} {text[m.end() :]}", lexicon)


# "carols back from the glass blowers so the red mug to her and the cup to bob", "omars on a diet
# for the toe wrestling so a banana to him and …": the one person's state opening the instruction
# (where they are back from, a diet and what it is for), then 'so' and a request to them by a
# pronoun
_FRONTED38 = re.compile(
    r"^(?P<p>(?:(?:mr|mrs|ms|miss|dr|person) )?[a-z]+?)(?:'s|s| is) (?:just )?(?P<state>(?:back|"
    r"home|in|fresh) from|on (?:a|her|his) (?:diet|health kick|detox|fast|cleanse)(?: for)?|in "
    r"training for|training for|off to) (?P<what>(?:the|his|her|their|a|an) [a-z' -]+?)"
    r",?\s+so (?P<rest>\S.*)$",
    _F,
)


def _fronted38(text: str, lexicon: Lexicon) -> str:
    """Session 38: the one person's state opening the instruction (above), before 'so' and a
    request whose pronouns may all be that person and no other person it names, is 'P is
    waiting, so …' (session 32's reading of such a statement): what it says of them names
    nothing and asks nothing."""
    m = _FRONTED38.match(text)
    if m is None:
        return text
    said = m["p"]
    if not _only_person(said, lexicon):
        return text
    pid = next(iter(_ids(said, lexicon, "human")))
    if not _inert38(m["what"].split(" ", 1)[1], lexicon):
        return text
    rest = m["rest"]
    prons = re.findall(r"\b(?:he|him|she|her)\b", rest, _F)
    if not prons or not _names(rest, lexicon) or not _fit36(pid, " ".join(prons), lexicon):
        return text
    others = _ids(rest, lexicon, "human") - {pid}
    if any(_fit36(q, " ".join(prons), lexicon) for q in others):
        return text
    name = said[0].upper() + said[1:]
    return f"{name} is waiting. So {rest}"


# -- wants closed by what made the person want it: 'after rehearsing with the brass band', 'after
# speedcubing all day', 'after the three-legged race' (session 37's 'after his <doing>', said
# with a bare word in -ing or a race, a match, a tournament of the person's)
_AFTER_DOING38 = re.compile(
    r"\s+(?:after|since|following) (?:(?P<ing>[a-z]{3,}ing)(?P<with> (?:with|at|in|on|for) "
    r"(?:the|his|her|their|a|an) [a-z-]+(?: [a-z-]+){0,2})?|the (?P<race>(?:[a-z]+-)*[a-z]+"
    r"(?: [a-z]+)? (?:race|relay|marathon|tournament|contest|competition|heats|final|derby|"
    r"regatta|gala|triathlon|fun run|sports day)))(?P<long> all (?:day|morning|afternoon|evening|"
    r"night|week))?(?=\s*(?:[,.;!?]|$))",
    _F,
)
_WANT38 = re.compile(
    rf"{_WANT_FRAME37.pattern}|\b(?:could (?:murder|kill for|eat|drink)|could do with)\b", _F
)


def _after_doing38(text: str, lexicon: Lexicon) -> str:
    """Session 38: 'after <doing>' (above) taken off a want (_WANT38) of one person, objects and
    no surface, in the same clause: the doing a word in -ing that is no verb of the grammar nor
    an event (_EVENTS37), with what it was done with, or a race of the person's; its words naming
    nothing and asking nothing."""
    if not re.search(r"\b(?:after|since|following)\b", text, _F):
        return text
    for m in _AFTER_DOING38.finditer(text):
        if m["ing"] is not None:
            ing = m["ing"].lower()
            if ing in VERBS or ing in _EVENTS37 or ing.endswith("thing"):
                continue
            words = ing + (" " + m["with"].split(" ", 3)[-1] if m["with"] else "")
        else:
            words = m["race"]
        if not _inert38(words, lexicon):
            continue
        before = re.split(r"[.;!?]\s+|,\s*", text[: m.start()])[-1]
        people = _ids(before, lexicon, "human")
        if len(people) != 1 or not _WANT38.search(before):
            continue
        if not _ids(before, lexicon, "object") or _ids(before, lexicon, "surface"):
            continue
        return text[: m.start()] + text[m.end() :]
    return text


# "What Person A needs, being a sheep shearer with a dry throat, is the cup": an aside of what
# the person is, between commas
_BEING_A38 = re.compile(
    r",\s*being (?:a|an) (?P<what>[a-z]+(?: [a-z]+){0,5}),\s*(?=(?:is|are|was)\b)", _F
)


def _wants38(text: str, lexicon: Lexicon) -> str:
    """Session 38: ', being a <trade> (with …),' inside 'What P needs … is X' taken off (its
    words naming nothing and asking nothing, the sentence one person's)."""
    m = _BEING_A38.search(text)
    if m is not None and _inert38(m["what"], lexicon):
        before = text[: m.start()]
        if re.match(r"^what\b", before, _F) and len(_ids(before, lexicon, "human")) == 1:
            text = f"{before} {text[m.end() :]}"
    return text


# -- courtesies
# "…, so if you could, ta ever so": the ask said with no verb after it, closing
_SO_IF38 = re.compile(
    r",\s*so if you (?:could|would|can|don't mind|wouldn't mind|would be so kind)"
    r"(?=\s*(?:,|[.!]?\s*$))",
    _F,
)
# "On behalf of our lacemaking circle, …": on whose behalf the speaker asks, opening
_ON_BEHALF38 = re.compile(
    r"^on behalf of (?:our|the|my|all of us at the|everyone at the|us at the) "
    r"(?P<who>[a-z]+(?: [a-z]+){0,3}),\s*",
    _F,
)
# "…, the caterer wants a tidy counter": someone by their trade wanting a surface kept clear
_WANTS_TIDY38 = re.compile(
    r",\s*(?:the|our|my) (?P<who>[a-z]+(?: [a-z]+)?) (?:wants|likes|needs|prefers|expects|has "
    r"asked for|asked for) (?:a|an) (?:tidy|clear|clean|empty|neat|spotless|uncluttered|free) "
    r"(?P<what>[a-z]+)(?P<end>\s*[.!]?)\s*$",
    _F,
)


def _courtesies38(text: str, lexicon: Lexicon) -> str:
    """Session 38: ', so if you could' closing (no verb after it); 'On behalf of our <group>, '
    opening (the group naming nothing, asking nothing); ', the <trade> wants a tidy <surface>'
    closing a request (the trade _doer38, what is kept tidy no object or person) — each
    when what is left names something."""
    out = text
    m = _SO_IF38.search(out)
    if m is not None:
        out = out[: m.start()] + out[m.end() :]
    m = _ON_BEHALF38.match(out)
    if m is not None and _inert38(m["who"], lexicon):
        rest = out[m.end() :]
        out = rest[0].upper() + rest[1:]
    m = _WANTS_TIDY38.search(out)
    if (
        m is not None
        and _doer38(m["who"], lexicon)
        and not _ids(m["what"], lexicon, "object")
        and not _ids(m["what"], lexicon, "human")
    ):
        out = out[: m.start()] + m["end"].strip()
    if out == text or not _names(out, lexicon):
        return text
    return out


# -- remarks about the person a request is for: what left them tired or thirsty, what they have
# on, a promise someone made them
# "…, her theremin practice makes her thirsty", "…; the pony club tired him out": a doing of the
# person's (or 'the <club>') that left them in a state, closing
_LEFT_THEM38 = re.compile(
    r"(?:[,;]\s*|(?<=[.!])\s+)(?P<whose>his|her|their|the|all that|that) (?P<what>[a-z-]+"
    r"(?: [a-z-]+){0,2}) (?:(?:makes|made|leaves|left|gets|got|has made|has left) (?P<p1>him|her|"
    r"them) (?:so |really |very |a bit |proper )?(?:thirsty|hungry|peckish|parched|starving|"
    r"famished|tired|sleepy|sore|sweaty|achy|stiff|worn out|exhausted|shattered)|(?:tired|wore|"
    r"wears|tires|has tired|has worn|wiped|has wiped|knocked|has knocked) (?P<p2>him|her|them) "
    r"out)(?P<end>\s*[.!]?)\s*$",
    _F,
)
# "…, she's got her steel drum practice and wants a brew first": what the person has on, and a
# drink or a bite they want before it
_GOT_HER38 = re.compile(
    r",\s*(?P<pron>he|she)(?:'s| has) got (?P<whose>his|her) (?P<what>[a-z-]+(?: [a-z-]+){0,2}) "
    r"(?:practice|lesson|class|rehearsal|session|shift|match|game|training|appointment|meeting|"
    r"exam|audition)(?: (?:and|so) (?:wants|needs|would like|fancies|could do with) (?:a|an|some) "
    r"(?:brew|cuppa|drink|snack|bite|sit down|sit-down|rest|breather|sugar boost)"
    r"(?: first| beforehand| before that| before it)?)?(?P<end>\s*[.!]?)\s*$",
    _F,
)
# "…, the set designer promised him some": someone by their trade promised the person some
_PROMISED38 = re.compile(
    r",\s*(?:the|our|my) (?P<who>[a-z]+(?: [a-z]+)?) (?:promised|owes|offered|has promised|had "
    r"promised) (?P<pron>him|her|them) (?:some|one|a few|a couple)(?P<end>\s*[.!]?)\s*$",
    _F,
)


def _remarks38(text: str, lexicon: Lexicon) -> str:
    """Session 38: the remarks above taken off a request to one person their pronouns may be
    (and no other), its words naming nothing and asking nothing (the promise's maker a trade,
    _doer38), when the request names an object."""
    m = _LEFT_THEM38.search(text)
    if m is not None:
        pron = m["p1"] or m["p2"]
        if m["whose"].lower() in ("his", "her"):
            pron = f"{pron} {m['whose']}"
        text = _of_one38(text, m.start(), m["what"], pron, m["end"], lexicon)
    m = _GOT_HER38.search(text)
    if m is not None:
        text = _of_one38(text, m.start(), m["what"], f"{m['pron']} {m['whose']}", m["end"], lexicon)
    m = _PROMISED38.search(text)
    if m is not None and _doer38(m["who"], lexicon):
        text = _of_one38(text, m.start(), "", m["pron"], m["end"], lexicon)
    return text


def _of_one38(text: str, start: int, words: str, prons: str, end: str, lexicon: Lexicon) -> str:
    """``text`` without its remark from ``start`` (``words`` naming nothing, asking nothing) when
    the text before names one person, who every pronoun of ``prons`` may be ('them' always), and
    an object."""
    if words and not _inert38(words, lexicon):
        return text
    before = text[:start]
    people = _ids(before, lexicon, "human")
    if len(people) != 1 or not _ids(before, lexicon, "object"):
        return text
    said = " ".join(p for p in prons.lower().split() if p not in ("them", "their"))
    if said and not _fit36(next(iter(people)), said, lexicon):
        return text
    return before + end.strip()


# -- pronouns and ellipsis
# "Person A's asked for it twice now, the bottle, I mean, …": 'it' said first, then what it is
_IT_I_MEAN38 = re.compile(
    r"^(?P<pre>[^,]*?)\bit\b(?P<mid>[^,]*),\s*(?P<x>(?:the|that|this|her|his|their) [a-z]+"
    r"(?: [a-z]+)?),\s*I mean\b(?P<sep>,\s*|\s*[.!]?\s*$)",
    _F,
)
# "Mr Lee was asking after his magazine": a want
_ASKING_AFTER38 = re.compile(
    rf"\b(?P<p>{_P37}) (?:was|is|'s|has been|'s been|had been) (?:asking|enquiring|inquiring) "
    r"(?:after|about) (?=(?:the|his|her|their|that|this) )",
)
# "…, the one with the basket weaver on the cover": what is on the one object named just before
_ONE_WITH38 = re.compile(
    r",\s*the one with (?P<d>(?:a|an|the|some) [a-z' -]+?) on (?:the|its) (?:cover|front|back|"
    r"label|lid|side|spine|top)(?=\s*(?:[;,.!]|$))",
    _F,
)
# "Omar's done with the white cup, he's off to judge the dog show, so it can go in the sink"
_DONE_WITH38 = re.compile(
    rf"^(?P<p>{_P37})(?:'s| is| has) (?:done|finished) with (?P<x>(?:the|his|her|that|this) "
    r"[a-z]+(?: [a-z]+)?),\s*(?:(?P<pron>he|she)(?:'s| is) (?P<why>[a-z' ]+?),\s*)?so (?:it|that) "
    r"(?:can|could|should|may) (?:go|live) (?P<where>(?:back )?(?:in|on|into|onto) .+)$",
)


def _pronouns38(text: str, lexicon: Lexicon) -> str:
    """Session 38: "… it …, the bottle, I mean" as '… the bottle …' (one 'it', the words said
    objects only, the clause of one person and no object); 'P was asking after X' as 'P wants X'
    (P one person, X an object); ', the one with a … on the cover' after one object taken off
    (what is pictured naming nothing, asking nothing); "P's done with X, (he's …,) so it can go
    in S" as 'X can go in S' (the remark of a pronoun P may be, asking nothing)."""
    m = _IT_I_MEAN38.match(text)
    if (
        m is not None
        and _things31(m["x"], lexicon)
        and len(re.findall(r"\bit\b", m["pre"] + m["mid"], _F)) == 0
        and len(_ids(m["pre"] + m["mid"], lexicon, "human")) == 1
        and not _ids(m["pre"] + m["mid"], lexicon, "object")
    ):
        sep = ", " if m["sep"].strip() == "," else m["sep"]
        text = f"{m['pre']}{m['x']}{m['mid']}{sep}{text[m.end() :]}"
    m = _ASKING_AFTER38.search(text)
    if m is not None and _only_person(m["p"], lexicon):
        nxt = re.match(r"(?:the|his|her|their|that|this) [a-z]+(?: [a-z]+)?", text[m.end() :], _F)
        if nxt is not None and _ids(nxt[0], lexicon, "object"):
            text = f"{text[: m.start()]}{m['p']} wants {text[m.end() :]}"
    m = _ONE_WITH38.search(text)
    if m is not None and _inert38(m["d"].split(" ", 1)[1], lexicon):
        before = text[: m.start()]
        last = re.split(r"\s+(?:the|his|her|their|that|this)\s+", before, flags=_F)[-1]
        if len(_ids(last, lexicon, "object")) == 1 and not _ids(last, lexicon, "human"):
            text = before + text[m.end() :]
    m = _DONE_WITH38.match(text)
    if m is not None and _only_person(m["p"], lexicon) and _things31(m["x"], lexicon):
        pid = next(iter(_ids(m["p"], lexicon, "human")))
        ok = m["pron"] is None or (_fit36(pid, m["pron"], lexicon) and _inert38(m["why"], lexicon))
        if ok and _ids(m["where"], lexicon, "surface"):
            x = m["x"]
            if x.split()[0].lower() in ("his", "her"):
                x = "the " + x.split(" ", 1)[1]
            text = f"{x[0].upper()}{x[1:]} can go {m['where']}"
    return text


# -- splits and run-ons
# "…, and then you're done for the day": the robot let go, closing
_DONE_FOR38 = re.compile(
    r",\s*(?:and )?(?:then )?(?:you're|you are|youre) (?:done|finished|free|free to go)"
    r"(?: for (?:the day|today|now|the night|the week|the shift))?(?=\s*(?:,|[.!]?\s*$))",
    _F,
)
# "…, with the ruler on the desk after that": a last placement said with 'with'
_WITH_AFTER38 = re.compile(
    r",\s*with (?P<x>(?:the|that|this) [a-z]+(?: [a-z]+)?) (?P<on>on|in|onto|into) "
    r"(?P<s>the [a-z]+(?: [a-z]+)?) (?:after that|afterwards|after|last|to finish|at the end)"
    r"(?P<end>\s*[.!]?)\s*$",
    _F,
)


def _splits38(text: str, lexicon: Lexicon) -> str:
    """Session 38: ', and then you're done (for the day)' closing a request taken off (nothing
    named after it: "…, and then you're done, then give Carol the apple" stays refused); ', with X
    on S after that' closing as ', then X on S' (X objects, S a surface)."""
    m = _DONE_FOR38.search(text)
    if (
        m is not None
        and _names(text[: m.start()], lexicon)
        and not _names(text[m.end() :], lexicon)
    ):
        text = text[: m.start()] + text[m.end() :]
    m = _WITH_AFTER38.search(text)
    if (
        m is not None
        and _things31(m["x"], lexicon)
        and _surface_only(m["s"], lexicon)
        and _names(text[: m.start()], lexicon)
    ):
        text = f"{text[: m.start()]}, then {m['x']} {m['on']} {m['s']}{m['end'].strip()}"
    return text


# -- lower case
# "… like every time", "… as always": a habit of the person's, closing a want
_HABIT38 = re.compile(
    r"\s*,?\s+(?:like|as|same as) (?:every time|always|ever|usual|per usual|normal)"
    r"(?P<end>\s*[.!]?)\s*$",
    _F,
)
# "… for the set designers cardboard props": what a trade's things need it for, closing a want
_FOR_TRADES38 = re.compile(
    r"\s+for (?:the|our|my|his|her) (?P<who>[a-z]+(?: [a-z]+)?)(?:'s|s'|s) (?P<what>[a-z]+"
    r"(?: [a-z]+){0,2})(?P<end>\s*[.!]?)\s*$",
    _F,
)


def _lower38(text: str, lexicon: Lexicon) -> str:
    """Session 38: 'like every time' / 'as always' closing a want of one person taken off; 'for
    the <trade>'s <things>' closing a want of one person (the trade _doer38, its things
    naming nothing, asking nothing) taken off."""
    m = _HABIT38.search(text)
    if m is not None:
        before = text[: m.start()]
        if len(_ids(before, lexicon, "human")) == 1 and _WANT_FRAME37.search(before):
            text = before + m["end"].strip()
    m = _FOR_TRADES38.search(text)
    if m is not None and _doer38(m["who"], lexicon):
        before = text[: m.start()]
        if (
            _inert38(m["what"], lexicon)
            and len(_ids(before, lexicon, "human")) == 1
            and _ids(before, lexicon, "object")
            and _WANT_FRAME37.search(before)
        ):
            text = before + m["end"].strip()
    return text


# -- questions and what follows them
# "… ? He's just back from his theremin lesson.": session 37's sentence of the person's state,
# with a doing of theirs of up to three words
_BACK_FROM38 = re.compile(
    r"(?<=[.!?])\s+(?P<pron>he|she)(?:'s| is) (?:just |only just )?(?:back|home|in) from "
    r"(?P<whose>his|her) (?P<doing>[a-z-]+(?: [a-z-]+){0,2})\s*[.!]?\s*$",
    _F,
)
# "… ? The shoe repairer likes his tea there.", "… ? The lollipop man's van collects from
# there.": a sentence about someone by their trade (what of theirs, 'his' of them), closing
_THIRD_PARTY38 = re.compile(
    r"(?<=[.!?])\s+(?:the|our|my) (?P<words>[a-z][a-z' ]*?)\s*[.!]?\s*$",
    _F,
)
# ", ready for Lily's tea after the dog show?": what a placement is ready for, closing
_READY_FOR38 = re.compile(
    rf",\s*(?:all )?ready for (?P<p>{_P37})(?:'s|s) (?:tea|lunch|dinner|breakfast|supper|snack|"
    r"bath|nap|bedtime|feed|bottle time)(?: (?:after|before) (?:the|his|her) (?P<ev>[a-z-]+"
    r"(?: [a-z-]+)?))?(?P<end>\s*[.!?]?)\s*$",
)
# "How about Person B gets the cup and Person A the apple, seeing as she asked first?"
_HOW_ABOUT38 = re.compile(
    rf"^(?:how|How) about (?P<req>(?P<p>{_P37}) (?:gets|has|takes|can have) .+?)"
    r"(?:,\s*(?:seeing as|since|as|because) (?:he|she|they) (?:asked|got here|came|was here|"
    r"were here) first)?\s*\?\s*$",
)


def _questions38(text: str, lexicon: Lexicon) -> str:
    """Session 38: 'He's just back from his <doing>' after a request to one person the pronouns
    may be, taken off; a sentence about someone by their trade (_doer38) closing a request, taken
    off when what it says names nothing and asks nothing but 'there' (the place just named) and
    'his' / 'her' (the trade's own); ', ready for P's tea' closing a placement taken off (P one
    person); 'How about P gets X and Q the Y(, seeing as she asked first)?' as 'P gets X and Q
    the Y.' (who asked first changes nothing that is done)."""
    m = _BACK_FROM38.search(text)
    if m is not None and PRONOUN_SEX[m["pron"].lower()] == PRONOUN_SEX[m["whose"].lower()]:
        text = _of_one38(text, m.start(), m["doing"], m["pron"], "", lexicon)
    m = _THIRD_PARTY38.search(text)
    if m is not None and _names(text[: m.start()], lexicon):
        said = m["words"].split()
        for n in (2, 1):
            who = " ".join(said[:n])
            who = who[:-2] if who.endswith("'s") else who  # "the lollipop man's van"
            rest = re.sub(r"\b(?:his|her|there|here)\b", " ", " ".join(said[n:]), flags=_F)
            # what they do is said of them ('collects'), not asked of the robot
            rest = " ".join("x" if w.endswith("s") and w in VERBS else w for w in rest.split())
            if len(said) > n and _doer38(who, lexicon) and _inert38(rest, lexicon):
                text = text[: m.start()]
                break
    m = _READY_FOR38.search(text)
    if m is not None and _only_person(m["p"], lexicon):
        before = text[: m.start()]
        if _ids(before, lexicon, "surface") and (m["ev"] is None or _inert38(m["ev"], lexicon)):
            text = before + m["end"].strip()
    m = _HOW_ABOUT38.match(text)
    if m is not None and _only_person(m["p"], lexicon) and _ids(m["req"], lexicon, "object"):
        text = m["req"][0].upper() + m["req"][1:] + "."
    return text


_STEPS38: tuple[Callable[[str, Lexicon], str], ...] = (
    # first: the commas a text written without them leaves out, for the rules after it
    _run_on38,
    _courtesies38,
    _wants38,
    _after_doing38,
    _remarks38,
    _pronouns38,
    _splits38,
    _lower38,
    _questions38,
    _fronted38,
)
