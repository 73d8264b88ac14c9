"""The normaliser's rules of sessions 10-37, part 2 of 5 (docs/grounding.md: where they live)."""

from __future__ import annotations

import functools
import unicodedata
from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import (
    _APOLOGY19,
    _BOTHER19,
    _BOTHERING,
    _COUNTS,
    _CUE19,
    _F,
    _KEEP_WORDS,
    _NOT_HELD31S,
    _NOT_REASON31S,
    _NUMBER18,
    _NUMBERS15,
    _PARTICLES,
    _REASON28,
    _REASON_HELD21,
    _VERB_NEXT19,
    _adjectives,
    _base,
    _drop,
    _each_of_one29r,
    _ends_object,
    _fits,
    _ids,
    _kind_of,
    _names,
    _names_nothing,
    _objects_listed,
    _objects_only,
    _only,
    _only_kind,
    _only_person,
    _opens_request,
    _reading,
    _remark_clause,
    _rx,
    _said,
    _said_any,
    _sub,
    _surface_only,
    _tasks_of,
    _the_person,
)
from hltl.grounding.lexicon import (
    PRONOUN_SEX,
    VERBS,
    Lexicon,
    first_names,
    lex,
)
from hltl.grounding.phrasing import starting_on
from hltl.grounding.tree import (
    Group,
    Task,
    tasks,
)


def _reasons28(text: str, lexicon: Lexicon) -> str:
    """Session 28: a reason said after the request that session 21's rule does not take (above),
    taken off under the same conditions."""
    for m in reversed(list(_REASON28.finditer(text))):
        clause = m.group(1)
        said = (
            clause
            if m.group(2) is None
            else clause[: m.start(2) - m.start(1)] + clause[m.end(2) - m.start(1) :]
        )
        said = re.sub(r"^(?:seeing|given|now) that\s+", "", said, flags=_F)  # no 'that' of its own
        before = text[: m.start()]
        words = re.findall(r"[A-Za-z']+", said)
        if (
            # a word joined by a hyphen is one word ('mid-take' is no 'take')
            _REASON_HELD21.search(re.sub(r"\w+(?:-\w+)+", "x", said))
            or any(w[0].isupper() and w != "I" and not w.startswith("I'") for w in words[1:])
            or not _names_nothing(clause, lexicon)
            or not _names(re.split(r"[.!?]\s", before)[-1], lexicon)
        ):
            continue
        text = before + text[m.end() :]
    return text


# What an object is for, said after the request with more words than session 12's rule
# (_purpose) takes: a possessive ('for the actuary's tally') or a place after it ('for his break in
# the signal box'), or 'ready for' ('…, and the medium one as well, ready for the cashier's
# count'). Taken off when it names nothing in the scene and holds no word that counts, chooses or
# points back (_KEEP_WORDS), at the end of a clause; never right after 'is' / ''s' (what the
# clause says of its subject).
_PURPOSE28 = re.compile(
    r"(?<!'s)(?<! is)(?<! are)(?<!'re)(?<! was)(?<! were),?\s+(?:ready )?for "
    r"(?:the|a|an|this|that|some|his|her|their|my|our) ([a-z]+(?:[ -][a-z]+)?(?:'s [a-z]+)?"
    r"(?: (?:in|on|at|from|of|by) (?:the|a|an|his|her|their|my|our) [a-z]+(?: [a-z]+)?)?)"
    r"(?=\s*(?:[.,;!?]|$|\bplease\b|\bthanks\b))",
    _F,
)


def _inert28(words: str, lexicon: Lexicon) -> bool:
    """Whether ``words`` names nothing in the scene and holds no word that counts, chooses or
    points back (_KEEP_WORDS): what session 28's rules take off."""
    return _names_nothing(words, lexicon) and not _KEEP_WORDS.search(words)


def _purpose28(text: str, lexicon: Lexicon) -> str:
    """Session 28: what an object is for, with a possessive or a place after it, or 'ready for'
    (above), taken off."""
    if "for " not in text.lower():
        return text
    return _PURPOSE28.sub(lambda m: "" if _inert28(m.group(1), lexicon) else m.group(0), text)


# 'both' floating after a list of two objects ('the scissors and the ruler both on the desk',
# 'apple and cup both over to person b'): it says the two named are the two, nothing more
_BOTH_AFTER28 = re.compile(
    r"\b((?:the )?([a-z]+(?: [a-z]+)?) and (?:the )?([a-z]+(?: [a-z]+)?)) both "
    r"(?=(?:go |goes |over |across |back |up |down )?(?:to|on|onto|in|into|for)\b)",
    _F,
)


def _both_after28(text: str, lexicon: Lexicon) -> str:
    """Session 28: 'X and Y both to / on …' is 'X and Y to / on …' (X and Y each one name of
    an object, two different objects)."""
    if " both " not in text.lower():
        return text

    def drop(m: re.Match[str]) -> str:
        one, two = m.group(2), m.group(3)
        if not (_only_kind(one, lexicon, "object") and _only_kind(two, lexicon, "object")):
            return m.group(0)
        a, b = _ids(one, lexicon, "object"), _ids(two, lexicon, "object")
        if len(a) != 1 or len(b) != 1 or a == b:
            return m.group(0)
        return f"{m.group(1)} "

    return _BOTH_AFTER28.sub(drop, text)


# "Hammer to Kofi. And the drill, same again.": the objects said alone, then 'same again' (the
# task before, with these objects): 'And the drill too.'
_SAME_AGAIN28 = re.compile(
    r"(^|[.!;]\s+)((?:and |then )?(?:the )?[a-z]+(?: [a-z]+)?),?\s+(?:the )?same again"
    r"(?:,? please)?(?=\s*(?:[.!]|$))",
    _F,
)


def _same_again28(text: str, lexicon: Lexicon) -> str:
    """Session 28: '<objects>, same again' opening its sentence, after a sentence before it, is
    '<objects> too' (the objects one name of an object)."""
    if "same again" not in text.lower():
        return text

    def too(m: re.Match[str]) -> str:
        what = re.sub(r"^(?:and|then) ", "", m.group(2), flags=_F)
        if not m.group(1) or not _only_kind(what, lexicon, "object"):
            return m.group(0)
        return f"{m.group(1)}{m.group(2)} too"

    return _SAME_AGAIN28.sub(too, text)


# An object said to want or need to go somewhere ('The small box wants to sit on the pallet',
# 'the banana wants to go on the tray'): the object put there. Not 'stay' (it is not to move).
_OBJECT_WANTS28 = re.compile(
    r"\b((?:the )?[a-z]+(?: [a-z]+)?) (?:wants|needs|want|need) to (?:go|sit|be|live)"
    r"(?: back)? (on|onto|in|into) ",
    _F,
)


def _object_wants28(text: str, lexicon: Lexicon) -> str:
    """Session 28: '<object> wants / needs to go / sit / be on S' is 'put <object> on S' (the
    object one name of objects)."""
    if not _rx(r"\b(?:wants?|needs?) to (?:go|sit|be|live)\b").search(text):
        return text

    def put(m: re.Match[str]) -> str:
        if not _only_kind(m.group(1), lexicon, "object"):
            return m.group(0)
        return f"put {m.group(1)} {m.group(2)} "

    return _OBJECT_WANTS28.sub(put, text)


# A tag closing a question that asks only whether the request is all right: Hindi English
# '…, na?' (isn't it; never 'na' before more words, where it may be 'nah', a correction), and
# '…, or is that a pain / too much trouble / a problem / a hassle / asking too much?'
_TAG28 = re.compile(
    r",\s*(?:na|or is (?:that|it|this) (?:a (?:pain|problem|hassle|bother|nuisance)|"
    r"(?:too much|asking too much|too much trouble|too much hassle|too much bother)))\s*\?",
    _F,
)


def _tag28(text: str, lexicon: Lexicon) -> str:
    """Session 28: the tags above taken off, the question mark kept (what it asks is the
    request)."""
    return _TAG28.sub("?", text) if "," in text and "?" in text else text


# Who the speaker or a person is, said beside the request (session 28, blind26): the speaker's
# self-introduction as a stretch of its own ('Excuse me, sorry, the mycologist here, would you
# …': '(it's / this is) the <role> here'), a role before the person it names ('The fletcher,
# Person B, is asking for …': the person), and where a person is, said between commas after
# the name ('Person A, up at the rope walk, wants …'). Each taken off when it names nothing in
# the scene (a role or place of the scene is never taken off).
_HERE28 = re.compile(
    r"(^|[,.!?]\s*)(?:it's |this is )?(?:the|your) ([a-z]+(?: [a-z]+)?) here\s*[,.!]\s*", _F
)
_ROLE_FIRST28 = re.compile(r"^(?:the|our|my|your) ([a-z]+(?: [a-z]+)?),\s+([^,]+?),\s+", _F)
_WHERE_AFTER28 = re.compile(
    r"^([^,]+?),\s+((?:up|down|over|out|back|round)?\s*(?:at|in|on|by|near|from) "
    r"(?:the|a|an|his|her|their|my|our) [a-z]+(?: [a-z]+){0,2}),\s+(?=[a-z])",
    _F,
)


def _who_where28(text: str, lexicon: Lexicon) -> str:
    """Session 28: the speaker's self-introduction, a role said before its person, and where a
    person is said after the name (above), taken off."""
    if " here" in text.lower():

        def intro(m: re.Match[str]) -> str:
            return m.group(1) if _inert28(m.group(2), lexicon) else m.group(0)

        text = _HERE28.sub(intro, text)
    m = _ROLE_FIRST28.match(text)
    if m is not None and _inert28(m.group(1), lexicon) and _only_person(m.group(2), lexicon):
        text = f"{m.group(2)} {text[m.end() :]}"
    m = _WHERE_AFTER28.match(text)
    if m is not None and _only_person(m.group(1), lexicon) and _names_nothing(m.group(2), lexicon):
        text = f"{m.group(1)} {text[m.end() :]}"
    return text


# "A lemon for Mr Novak's fish": an object for a person's thing (their fish, tea, break) is for
# that person (the thing naming nothing in the scene, the person one of the scene)
_FOR_WHOSE28 = re.compile(
    r"\bfor ([A-Za-z][\w ]*?)'s ([a-z]+(?: [a-z]+)?)(?=\s*(?:[.,;!?]|$|\bplease\b))", _F
)


def _for_whose28(text: str, lexicon: Lexicon) -> str:
    """Session 28: 'X for P's <thing>' is 'X for P' (above); not where a surface is named (a
    placement's 'for' says what it is for)."""
    if "'s " not in text or _ids(text, lexicon, "surface"):
        return text

    def whose(m: re.Match[str]) -> str:
        if not _only_person(m.group(1), lexicon) or not _inert28(m.group(2), lexicon):
            return m.group(0)
        return f"for {m.group(1)}"

    return _FOR_WHOSE28.sub(whose, text)


# Session 29 (engineer 12, blind27): a person described by a trade the scene does not know,
# said right after the name ('Carol the crofter wants …', 'alice the juggler gets …', 'for
# Person A, the joiner.', 'Person B, the acrobat, is welcome …'). The description is taken off
# when the name is one person of the scene (not right after a verb: 'Give Alice the red' gives),
# the words are one or two the lexer does not know, name nothing in the scene (nor a typo of a
# name) and are no word of a scene name ('red' of 'red mug'), no modifier (_NOT_TRADE29) and no
# word that counts, chooses or points back; and what follows is a comma, the end of a sentence,
# or (with no comma before: '…, the house is paying' is a clause) a verb of wanting, having or
# being.
_TRADE29 = re.compile(
    r"(?P<comma>,)?\s+the (?P<trade>[a-z]+(?: [a-z]+)??)"
    r"(?P<after>\s*,|(?=\s*(?:[.;:!?]|$))|(?= (?:wants|needs|gets|is|was|has|had|would|should|"
    r"could|can|will|might|may|fancies|likes|asked|asks|says|'s|'d)\b))",
    _F,
)
_NOT_TRADE29 = frozenset(
    {
        "red", "blue", "green", "white", "black", "grey", "gray", "yellow", "brown", "pink",
        "orange", "purple", "big", "small", "large", "little", "medium", "tall", "short", "long",
        "new", "old", "clean", "dirty", "full", "empty", "lot", "usual", "whole", "left", "right",
        "top", "bottom", "middle", "near", "far", "nearest", "nearer", "closest", "closer",
        "other", "rest", "same", "latter", "former", "most", "least", "best", "worst",
    }
)  # fmt: skip


# Session 29 (engineer 12, blind27): a remark or context that asks nothing, said as a sentence
# of its own, before a colon, or as a comma part opening or closing a sentence ("…, job done,
# back to my embroidery.", "Sorry, typing this from the cave entrance.", "Our dairy farmers are
# parched and peckish: …", "For the ghillie's picnic, …"). Taken off only when it names nothing
# in the scene (nor a typo of a name), holds no verb the grammar knows, no word that counts,
# chooses, points back, negates, corrects, orders or says a time (_ASKS29), and is no question;
# and what is left names something. 'this' of the message itself ('typing this') is no pointer.
_ASKS29 = re.compile(
    r"\b(?:no|nope|nah|not|never|none|nothing|nobody|wrong|mistake|typo|meant|mean|means|"
    r"rather|instead|actually|scratch|cancel|forget|ignore|undo|wait|hold|hang|stop|skip|drop|"
    r"change|swap|switch|kidding|joking|other|others|another|else|same|again|too|also|well|"
    r"both|each|every|all|any|either|neither|only|just|whichever|whatever|first|last|next|then|"
    r"after|before|once|when|whenever|while|until|till|if|unless|later|now|soon|today|tonight|"
    r"tomorrow|yesterday|morning|afternoon|evening|lunch|dinner|breakfast|week|hours?|minutes?|"
    r"mins?|secs?|seconds?|moment|asap|it|its|them|they|their|theirs|him|her|hers|his|he|she|"
    r"that|those|these|this|there|here|one|ones|[0-9]+|two|three|four|five|six|seven|eight|"
    r"nine|ten|half|dozen|pair|couple|lot|rest|everything|anything|something|someone|everyone|"
    r"anyone|you|me|us|we|i|please|instead|except|without|but|bar|or|nor|sorry|oops|whoops|"
    r"apologies|correction|corrected|bad|silly|firstly|secondly|thirdly|finally|lastly|"
    r"initially|subsequently|afterwards?|meanwhile|between|during|likewise|similarly|ditto|"
    r"same|order|reverse|round|around|way|whoever|whomever|depending|depends|unless)\b|n't\b|[?]",
    _F,
)
_THIS_MESSAGE29 = re.compile(r"\b(?:typing|writing|sending|texting|saying) this\b", _F)


def _first_name30s(words: str) -> bool:
    """Session 30 (12s): whether ``words`` is a first name said alone ('Dave'): before a colon it
    says who gets what follows ("Give Bob the cup. Dave: apple." had read the apple as Bob's), no
    heading to take off."""
    said = words.strip().split()
    return len(said) == 1 and said[0][:1].isupper() and said[0].lower() in first_names()


# a statement: a clause with 'be' or 'done' ('the proofs are done', 'job done'); not a name said
# alone ('The chips' where the scene has none is refused, not taken off)
_STATEMENT29 = re.compile(r"\b(?:is|are|was|were|am|been|being|done)\b|'s\b|'re\b|'m\b", _F)


# "Sorry, typing this from the cave entrance.": an apology for how the message is sent
_TYPING_FROM29 = re.compile(
    r"(?:sorry|apologies),? (?:i'm |i am )?(?:typing|writing|texting|sending) this "
    r"((?:from|on|in|with|at) [a-z' ]+)",
    _F,
)


@functools.lru_cache(maxsize=64)
def _scene_words29(lexicon: Lexicon) -> frozenset[str]:
    """Every word of the scene's ids, names, categories and aliases ('red' of 'red mug'; once per
    lexicon, session 46, 12p: it was built again for every remark read)."""
    scene = lexicon.scene
    names = [
        *(n for o in scene.objects for n in (o.id, o.category, *o.aliases)),
        *(n for h in scene.humans for n in (h.id, h.name, *h.aliases)),
        *(n for f in scene.surfaces for n in (f.id, *f.aliases)),
    ]
    return frozenset(w.lower() for n in names for w in n.replace("_", " ").split())


def _negated_reason31s(text: str, lexicon: Lexicon) -> str:
    """Session 31 (12s): a negated reason closing the request's sentence is taken off (above)."""
    for m in reversed(list(_NOT_REASON31S.finditer(text))):
        said = m.group("said")
        words = re.findall(r"[A-Za-z']+", said)
        before = text[: m.start()]
        # 'this morning', 'that week': a time, not a thing pointed at
        when = re.sub(
            r"\b(?:this|that) (?:morning|afternoon|evening|week|year)\b", "", said, flags=_F
        )
        scene_words = _scene_words29(lexicon)
        if (
            _NOT_HELD31S.search(when)
            or any(w[0].isupper() and w != "I" for w in words[1:])
            # a word of a scene name ('blue' of 'blue mug': "…, he can't stand blue")
            or any(len(w) > 2 and w.lower() in scene_words for w in words)
            or not _names_nothing(said, lexicon)
            or not _names(re.split(r"[.!?]\s", before)[-1], lexicon)
        ):
            continue
        text = before + text[m.end() :]
    return text


def _trade_words29(words: str, lexicon: Lexicon) -> bool:
    """Whether ``words`` could only describe a person (above): unknown to the lexer, naming
    nothing in the scene, no word of a scene name, no modifier."""
    try:
        items = lex(words, lexicon)
    except GroundingError:
        return False
    said = _scene_words29(lexicon)
    return (
        all(it.kind == "unknown" for it in items)
        and _inert28(words, lexicon)
        and not any(w in said or w in _NOT_TRADE29 for w in words.lower().split())
        # "crisps for alice the baker tomorrow": a time is said (or another word that asks,
        # _ASKS29), which a trade is not (lead)
        and _ASKS29.search(words) is None
    )


def trades29(text: str, lexicon: Lexicon) -> str:
    """Session 29: a trade said after a person's name (above) taken off; before the instruction
    is first read (offline._parse), as the apostrophes are mended: it only describes."""
    if " the " not in text.lower():
        return text
    for m in reversed(list(_TRADE29.finditer(text))):
        before = text[: m.start()]
        words = before.split()
        who = next(
            (
                n
                for n in (3, 2, 1)
                if len(words) >= n
                and re.fullmatch(r"[A-Za-z]+", words[-1])
                and _only_person(" ".join(words[-n:]), lexicon)
            ),
            0,
        )
        rest = text[m.end() :].lstrip()
        if m.group("comma") and rest[:1].isalpha() and not m.group("after"):
            continue  # "…, the house is paying": a clause of its own, not a description
        if not who or not _trade_words29(m.group("trade"), lexicon):
            continue
        ahead = words[-who - 1].lower().strip(",.;:!?") if len(words) > who else ""
        if ahead in VERBS or ahead in ("the", "a", "an"):
            continue  # "Give Alice the red": the person gets what follows
        if (m.group("after") or "").strip() != ",":
            text = before + text[m.end() :]  # "Carol the crofter wants", "…, the joiner."
        elif m.group("comma"):
            text = f"{before} {text[m.end() :].lstrip()}"  # ", the acrobat," goes whole
        else:
            text = before + text[m.start("after") :]  # "alice the juggler, …": the comma stays
    return text


# Session 29 (blind27): a request reported from someone ('sam says put the stapler in the box',
# 'The bottle is wanted by Person B, says the coxswain.'): the request is what is asked. The
# report opening the instruction is taken off when it is one person of the scene and what they
# say has no word for the speaker or a person pronoun ('Mia says she wants …', 'Sam says give me
# …' are left); one closing a sentence (', says the coxswain', ', the coxswain says') when its
# words name nothing.
_SAYS_OPEN29 = re.compile(r"^([A-Za-z]+(?: [A-Za-z]+)?) says,? (?:that )?(?=\w)", _F)
_SAYS_CLOSE29 = re.compile(
    r",\s*(?:says ([a-z' ]+?)|((?:the |our |my |a )?[a-z' ]+?) says)\s*(?=[.!;]|$)", _F
)
_SPEAKER_OR_PRONOUN29 = re.compile(
    r"\b(?:i|me|my|mine|we|us|our|he|she|him|her|his|they|them)\b", _F
)


def _says29(text: str, lexicon: Lexicon) -> str:
    """Session 29: the report of a request taken off (above)."""
    if "says" not in text.lower():
        return text
    m = _SAYS_OPEN29.match(text)
    if (
        m is not None
        and _only_person(m.group(1), lexicon)
        and not _SPEAKER_OR_PRONOUN29.search(text[m.end() :])
    ):
        text = text[m.end() :]

    def close(c: re.Match[str]) -> str:
        who = c.group(1) or c.group(2) or ""
        return "" if _inert28(who, lexicon) else c.group(0)

    return _SAYS_CLOSE29.sub(close, text)


# Session 29 (blind27): 'P is after X' is 'P wants X' (a scene person and a scene object), and
# 'P needs X while Q wants Y' sets two wants side by side: 'while' before a person and a verb of
# wanting, after a clause that names an object, is 'and'.
_IS_AFTER29 = re.compile(
    r"\b([A-Za-z]+(?: [A-Za-z]+)?) (?:is|'s) (?:after|angling for) (?=the )", _F
)
_WHILE29 = re.compile(
    r"(?<=\w) while ([A-Za-z]+(?: [A-Za-z]+)?) (?=(?:wants|needs|gets|would like|fancies)\b)", _F
)


def _while29(text: str, lexicon: Lexicon) -> str:
    """Session 29: 'is after' and 'while' between two wants (above)."""
    if " after " in text.lower():

        def wants(m: re.Match[str]) -> str:
            words = m.group(1).split()
            for n in (len(words), 1):
                if _only_person(" ".join(words[-n:]), lexicon):
                    return " ".join([*words[:-n], *words[-n:], "wants "])
            return m.group(0)

        text = _IS_AFTER29.sub(wants, text)
    if " while " not in text.lower():
        return text

    def side(m: re.Match[str]) -> str:
        before = re.split(r"[.!?;:]\s", text[: m.start()])[-1]
        if _only_person(m.group(1), lexicon) and _ids(before, lexicon, "object"):
            return f" and {m.group(1)} "
        return m.group(0)

    return _WHILE29.sub(side, text)


# Session 29 (blind27): "See the bottle? Person A the gamekeeper wants it.": a question that
# points at one object of the scene, opening the instruction, says what the rest is about: 'The
# bottle.' (the rest must still say who gets it)
_SEE_THE29 = re.compile(r"^(?:(?:do |can )?you )?see (the|that|this) ([a-z][a-z ]*?)\?\s*", _F)


def _see_the29(text: str, lexicon: Lexicon) -> str:
    """Session 29: 'See the X?' opening the instruction as 'The X.' (above)."""
    m = _SEE_THE29.match(text)
    if (
        m is None
        or len(_ids(m.group(2), lexicon, "object")) != 1
        or not _only(m.group(2), lexicon, "object")
    ):
        return text
    return f"The {m.group(2)}. {text[m.end() :]}"


# Session 29 (blind27): "the pawnbroker's parcel, the small box, should go on the conveyor": an
# object first described by words the scene does not know, then named between commas, opening a
# sentence whose verb follows: the name alone ('a list "the spanner, the cup, and …"' has no verb
# after it and is left)
_DESCRIBED29 = re.compile(
    r"(^|[.!?;]\s+)(?:the|a|an|my|our|your|his|her|their) ([a-z' -]+?), (the [a-z -]+?),\s+"
    r"(?=(?:should|must|needs?|goes|go|is|has|can|could|wants?|belongs)\b)",
    _F,
)


def _described29(text: str, lexicon: Lexicon) -> str:
    """Session 29: an object described, then named (above), is the name."""
    if text.count(",") < 2:
        return text

    def named(m: re.Match[str]) -> str:
        if (
            _trade_words29(m.group(2).replace("'s", ""), lexicon)
            and len(_ids(m.group(3), lexicon, "object")) == 1
            and _only(m.group(3), lexicon, "object")
        ):
            return f"{m.group(1)}{m.group(3)} "
        return m.group(0)

    return _DESCRIBED29.sub(named, text)


# Session 29 (blind27): 'that same person' ('…, the bottle to that same person as well') is the
# one person named before it; with none or several named it is left (and refused)
_SAME_PERSON29 = re.compile(
    r"\b(?:that|the) (?:very )?same (?:person|one|guy|lady|woman|man)\b", _F
)


def _same_person29(text: str, lexicon: Lexicon) -> str:
    """Session 29: 'that same person' named (above)."""
    if "same" not in text.lower():
        return text
    m = _SAME_PERSON29.search(text)
    if m is None:
        return text
    before = _ids(text[: m.start()], lexicon, "human")
    if len(before) != 1:
        return text
    pid = next(iter(before))
    name = next(h.name for h in lexicon.scene.humans if h.id == pid)
    return text[: m.start()] + name + text[m.end() :]


# -- session 30 (engineer 12): blind28's kinds (politeness, wants, pronouns and ellipsis, splits,
# lower case, questions); docs/grounding.md, "Session 30 (engineer 12)" ---------------------------

# words that join, order, choose or repeat tasks: a 'next' closing an instruction that holds one of
# them may order its own tasks ('Give Bob the cup and Alice the apple next')
_JOINS30 = re.compile(
    r"\b(?:and|or|plus|then|first|last|after|before|once|when|until|till|both|each|every|all|"
    r"either|also|too|again|instead|rather|except|not|no|but)\b|n't\b",
    _F,
)
_NEXT30 = re.compile(r"^(?P<body>[^.;!?]+?),?\s+next(?P<tail>\s*(?:,[^.;!?]*)?[.!?]?)\s*$", _F)


def _next30(text: str, lexicon: Lexicon) -> str:
    """Session 30: 'The flashlight to Jess next(, if you'd be so kind).' — a closing 'next' of an
    instruction of one task (one object, one person or surface, one sentence, no word that joins or
    orders tasks) is 'Next, …' said last: after what the cell is doing, which the grammar reads as
    now (an update reads it as 'then': update.py); with two tasks it may order them, and is left."""
    if "next" not in text.lower():
        return text
    m = _NEXT30.match(text.strip())
    if m is None or _JOINS30.search(m["body"]) or _names(m["tail"], lexicon):
        return text
    objects = _ids(m["body"], lexicon, "object")
    if len(objects) != 1 or len(_ids(m["body"], lexicon) - objects) != 1:
        return text
    return m["body"] + m["tail"]


def _by_any_chance30(text: str, _lexicon: Lexicon) -> str:
    """Session 30: 'by any chance' in a question ("Could you stow the crisps up on the shelf, by any
    chance?", "Could you by any chance …?") softens the asking, as 'please' does."""
    if "chance" not in text.lower():
        return text
    text = _sub(r",?\s*by any chance\s*(?=\?)", "", text)
    return _sub(r"\b(you),?\s+by any chance,?\s+(?=[a-z])(?=[^.!]*\?)", r"\1 ", text)


def _dyou30(text: str, _lexicon: Lexicon) -> str:
    """Session 30: "D'you mind …", "d'ya mind …": 'do you', said short."""
    return _sub(r"\bd'(?:you|ya|ye)\b", "do you", text) if "d'" in text.lower() else text


# "Would it be OK if Person B took the bottle off you?": the robot letting P take X is P having X
_LET_TAKE30 = re.compile(
    r"\b(?:would it be|will it be|is it|would that be) (?:ok|okay|all right|alright|fine) (?:with "
    r"you )?if (?P<who>[A-Za-z]+(?: [A-Za-z]+)?) (?:took|takes|had|has|got|gets) "
    r"(?P<what>(?:the|that|this|those|these) [a-z][a-z ]*?)(?: (?:off|from) you)?\s*(?=\?)",
    _F,
)


def _let_take30(text: str, lexicon: Lexicon) -> str:
    """Session 30: asking leave for P to take X (above) is 'could P have X?' when P is one person
    and X objects of the scene only."""
    if " if " not in text.lower():
        return text

    def have(m: re.Match[str]) -> str:
        if _only_person(m["who"], lexicon) and _objects_only(m["what"], lexicon):
            return f"could {m['who']} have {m['what']}"
        return m[0]

    return _LET_TAKE30.sub(have, text)


# 'run' said as carrying, where _run_to28s does not look: after 'so' ("…, so run it over to him"),
# and as '-ing' after 'of' / 'about' ("Any chance of running the chips across to Person B …?")
_RUN30 = re.compile(
    r"(?P<lead>\b(?:so|of|about) )run(?P<ing>ning)? (?P<what>it|them|(?:the|that|this|those|"
    r"these) [a-z][a-z ]*?)(?P<dir>(?: (?:up|down|over|across|round|along))?) to "
    r"(?P<where>[A-Za-z]+(?: [A-Za-z]+)?)\b",
    _F,
)


# "How about the chips going over to Person B?": a suggestion that objects go to someone
_HOW_ABOUT30 = re.compile(
    r"\b(?:how|what) about (?P<what>(?:the|that|this|those|these) [a-z][a-z ]*?) (?:going|heading|"
    r"getting taken|being taken|being brought) (?P<dir>(?:(?:over|across|round|along) )?)"
    r"(?=(?:to|on|onto|into|in) )",
    _F,
)


def _how_about30(text: str, lexicon: Lexicon) -> str:
    """Session 30: 'how about X going (over) to P' (above) is 'X (over) to P' when X is objects of
    the scene only."""
    if "about" not in text.lower():
        return text
    return _HOW_ABOUT30.sub(
        lambda m: f"{m['what']} {m['dir']}" if _objects_only(m["what"], lexicon) else m[0], text
    )


# 'then' said twice over: "…, then after it the chips", "… then Person A gets the apple after that
# is done": one order, said before and after the task
_THEN_AFTER_IT30 = re.compile(r"\bthen,? after (?:it|that),?\s+(?=[a-z])", _F)
_THEN_AFTER_THAT30 = re.compile(
    r"(\bthen\b[^.;!?,]*?)\s+after (?:that|it)(?: is| has been|'s)?(?: done| finished| over)?"
    r"(?=\s*(?:[.!?]|$))",
    _F,
)


def _then_after30(text: str, _lexicon: Lexicon) -> str:
    """Session 30: 'then' and 'after it / after that (is done)' around one task (above) are one
    'then'."""
    if "after" not in text.lower() or "then" not in text.lower():
        return text
    return _THEN_AFTER_THAT30.sub(r"\1", _THEN_AFTER_IT30.sub("then ", text))


# The speaker saying who they are, as a comma part before the request ("Hi there, it's the
# distiller from next door, er, …", "Sorry, the microbiologist again, could Omar have …"): 'it's /
# this is the <trade> (again / here) (from <a place>)' or 'the <trade> again / here'; the trade one
# or two words the lexer does not know that name nothing (_trade_words29), the place naming nothing
_INTRODUCED30 = re.compile(
    r"(?:^|(?<=,))\s*(?:(?P<its>it's|it is|this is) )?(?:the|your) "
    r"(?P<who>[a-z]+(?: (?!again\b|here\b|speaking\b|from\b)[a-z]+)?)"
    r"(?P<again> again| here| speaking)?(?: from (?P<place>next door|upstairs|downstairs|"
    r"down the (?:hall|corridor|road)|across the (?:hall|corridor|road)|the [a-z]+(?: [a-z]+)?))?"
    r"\s*,\s*",
    _F,
)


def _introduced30(text: str, lexicon: Lexicon) -> str:
    """Session 30: the speaker's introduction (above) taken off, in the first sentence only, when
    it is said with 'it's' / 'this is' or with 'again' / 'here', and something is named after it."""
    first = re.split(r"[.!?;]\s", text, maxsplit=1)[0]
    for m in _INTRODUCED30.finditer(first):
        place = m["place"] or ""
        if not (m["its"] or m["again"]) or not _trade_words29(m["who"], lexicon):
            continue
        if place and (_names(place, lexicon) or _KEEP_WORDS.search(place.replace("next door", ""))):
            continue
        rest = text[m.end() :]
        if _names(rest, lexicon):
            return f"{text[: m.start()]}{' ' if m.start() else ''}{rest}".strip()
    return text


# wants said by an idiom: a closed list (docs/grounding.md, "Session 30 (engineer 12)"); each is
# rewritten as the plain state or want it says, which the grammar reads as before
_IDIOMS30: tuple[tuple[str, str], ...] = (
    # "Person A could murder a drink, so the bottle, please.": thirsty
    (r"\bcould (?:murder|kill for|really murder) an? (?:drink|cuppa|brew|coffee|tea|pint|"
     r"cold one)\b", "is thirsty"),
    # "… could murder a sandwich": hungry
    (r"\bcould (?:murder|kill for|really murder) an? (?:sandwich|snack|bite|biscuit|butty|"
     r"sarnie)\b|\bcould eat a horse\b", "is hungry"),
    # "Person A has had her eye on that bottle": she wants it
    (r"(?:\s+has|'s) (?:had |got )?(?:her|his|their) eyes? on\b", " wants"),
    # "Lily's grizzling for her teddy", "Lily's been crying for her teddy" (s55): she wants it
    (r"(?:\s+is|'s|\s+has been|'s been) (?:grizzling|crying|crying out|pining|gasping|begging) "
     r"for\b", " wants"),
)  # fmt: skip


def _idioms30(text: str, _lexicon: Lexicon) -> str:
    """Session 30: the idioms above, said plainly."""
    for pattern, plain in _IDIOMS30:
        text = _sub(pattern, plain, text)
    return text


# "… ever since the bell-ringing practice finished": how long the want has lasted, in the past
_EVER_SINCE30 = re.compile(r"\s+ever since (?P<when>[^,.;!?]+?)(?=\s*(?:[,.;!?]|$))", _F)


def _ever_since30(text: str, lexicon: Lexicon) -> str:
    """Session 30: an 'ever since …' (above) naming nothing of the scene and holding no word that
    counts, chooses or points back, taken off: it says since when, never when to act."""
    if "ever since" not in text.lower():
        return text
    return _EVER_SINCE30.sub(lambda m: "" if _inert28(m["when"], lexicon) else m[0], text)


# "Lily wants her teddy bear; she won't nap till she's got it.": why the want presses, said after
# it: the wanting person will not do something until they have it (a reason; it asks nothing more)
_TILL_GOT30 = re.compile(
    r"\s*[;,.]\s*(?:and |so )?(?P<p1>he|she|they) (?:won't|will not|can't|cannot|wo n't) "
    r"(?P<what>[a-z]+(?: [a-z]+){0,2}) (?:till|until) (?P<p2>he|she|they)(?:'s| has|'ve| have) "
    r"(?:got|had) (?:it|them|one)\s*(?P<end>[.!]?)\s*$",
    _F,
)


def _till_got30(text: str, lexicon: Lexicon) -> str:
    """Session 30: the reason above taken off when one person is named before it, whom both
    pronouns may be, and its words name nothing of the scene."""
    if "till" not in text.lower() and "until" not in text.lower():
        return text
    m = _TILL_GOT30.search(text)
    if m is None or m["p1"].lower() != m["p2"].lower() or not _names_nothing(m["what"], lexicon):
        return text
    people = _ids(text[: m.start()], lexicon, "human")
    sexes = {
        PRONOUN_SEX[w.lower()] for w in re.findall(r"\b(?:he|him|his|she|her|hers)\b", text, _F)
    }
    if len(people) != 1 or len(sexes) > 1 or not _fits(next(iter(people)), text, lexicon):
        return text
    return text[: m.start()] + (m["end"] or ".")


# "Person A's thirsty and wants the bottle": a state said before the want, joined by 'and'
_STATE_AND30 = re.compile(
    r"(?:^|(?<=[.;!?])\s+)(?P<who>[A-Za-z]+(?: [A-Za-z]+)?)(?:'s| is) (?:very |really |so |a bit "
    r")?(?P<state>[a-z]+) and (?=(?:wants|needs|would like|'d like|is after|could use)\b)",
    _F,
)


def _state_and30(text: str, lexicon: Lexicon) -> str:
    """Session 30: the state (above) taken off when P is one person and the state one word the
    lexer does not know naming nothing (_trade_words29): 'P wants X'."""
    if " and " not in text.lower():
        return text

    def wants(m: re.Match[str]) -> str:
        start = m.start("who")
        lead = m[0][: start - m.start()]
        if _only_person(m["who"], lexicon) and _trade_words29(m["state"], lexicon):
            return f"{lead}{m['who']} "
        return m[0]

    return _STATE_AND30.sub(wants, text)


# "Person B needs something to eat, the chips'll do.": the want, then what will meet it
_WILL_DO30 = re.compile(
    r"(?P<who>[A-Za-z]+(?: [A-Za-z]+)?) (?P<verb>needs|wants|would like|could use|could do with) "
    r"(?:something|anything|a bite|a drink|a snack)(?: to (?:eat|drink|nibble|munch on))?,\s*(?:so "
    r")?(?P<what>the [a-z][a-z ]*?)(?:'ll| will| would| should|'d) do\b",
    _F,
)


def _will_do30(text: str, lexicon: Lexicon) -> str:
    """Session 30: 'P needs something (to eat), the X'll do' (above) is 'P needs the X', when P is
    one person and the X objects of the scene only."""
    if " do" not in text.lower():
        return text
    return _WILL_DO30.sub(
        lambda m: (
            f"{m['who']} {m['verb']} {m['what']}"
            if _only_person(m["who"], lexicon) and _objects_only(m["what"], lexicon)
            else m[0]
        ),
        text,
    )


# "Priya wants her notepad left out on the desk", "… would like the globe set out on the desk":
# an object wanted on a surface, 'out' saying only that it is to be seen there; 'her' / 'his'
# before it the wanting person's own (the scene knows no owners)
_SET_OUT30 = re.compile(
    r"\b(?P<who>[A-Za-z]+(?: [A-Za-z]+)?) (?P<verb>wants|needs|would like|'d like) "
    r"(?:(?P<own>her|his|their) |the )(?P<what>[a-z][a-z ]*?) (?:left|set|laid|put) out "
    r"(?P<on>on|onto|on to) ",
    _F,
)


def _set_out30(text: str, lexicon: Lexicon) -> str:
    """Session 30: 'P wants (her) X left / set / laid out on S' (above) is 'P wants the X put on
    S', when P is one person (whom 'her' / 'his' may be) and X objects of the scene only."""
    if " out " not in text.lower():
        return text

    def put(m: re.Match[str]) -> str:
        if not (_only_person(m["who"], lexicon) and _objects_only(m["what"], lexicon)):
            return m[0]
        if m["own"] and not _fits(next(iter(_ids(m["who"], lexicon))), m["own"], lexicon):
            return m[0]
        return f"{m['who']} {m['verb']} the {m['what']} put {m['on']} "

    return _SET_OUT30.sub(put, text)


# "The bottle. Over to Person A.": the object said as a sentence, where it goes as the next one
_OVER_TO30 = re.compile(
    # session 34 (12s): the object without 'the', and with 'first' ("Apple first. To Alice.")
    r"(?:^|(?<=[.!?;])\s+)(?P<what>(?:the )?[a-z][a-z ]*?)(?P<first> first)?\.\s+"
    r"(?P<dir>(?:over|across|round|along|"
    r"up|down|back) )?to (?P<where>[A-Za-z]+(?: [A-Za-z]+)?)\s*(?=[.!?]|$)",
    _F,
)


def _over_to30(text: str, lexicon: Lexicon) -> str:
    """Session 30: the two sentences above are one ('The bottle over to Person A.') when the first
    is objects of the scene alone and the second one person or surface."""
    if "to " not in text.lower():
        return text

    def joined(m: re.Match[str]) -> str:
        where = m["where"]
        if _objects_only(m["what"], lexicon) and (
            _only(where, lexicon, "human") or _only(where, lexicon, "surface")
        ):
            lead = m[0][: m.start("what") - m.start()]
            first = m["first"] or ""
            return f"{lead}{m['what']}{first} {(m['dir'] or '').lower()}to {where}"
        return m[0]

    return _OVER_TO30.sub(joined, text)


# "grab the bottle take it to Person A": two requests run on, the second taking up the first's
# object with 'it'
_RUN_ON_IT30 = re.compile(
    r"\b(?P<first>(?:grab|get|fetch|pick up|collect) (?P<what>(?:the|that|this) [a-z][a-z ]*?)) "
    r"(?=(?:and )?(?:take|bring|give|hand|carry|pass|run) it\b)",
    _F,
)


def _run_on_it30(text: str, lexicon: Lexicon) -> str:
    """Session 30: the run-on above joined with 'and', when the first object is one object of the
    scene (so that 'it' is that object)."""
    if " it " not in text.lower():
        return text
    return _RUN_ON_IT30.sub(
        lambda m: (
            f"{m['first']} and "
            if len(_ids(m["what"], lexicon, "object")) == 1
            and _only_kind(m["what"], lexicon, "object")
            and not m[0].endswith("and ")
            else m[0]
        ),
        text,
    )


# "mr novak at table four wants the salt": where the person sits, a numbered place after a name
_AT_TABLE30 = re.compile(
    r"\b(?P<who>[A-Za-z]+(?: [A-Za-z]+)?) (?:at|on|in) (?:table|bed|seat|bay|booth|desk|station|"
    r"pitch|stall|room|cubicle) (?:number |no\.? )?(?:[0-9]+|one|two|three|four|five|six|seven|"
    r"eight|nine|ten|eleven|twelve)\b"
    r"(?=\s+(?:wants|needs|would like|'d like|is after|gets|asked)\b)",
    _F,
)


def _at_table30(text: str, lexicon: Lexicon) -> str:
    """Session 30: a numbered place said after a person's name before their want (above) taken
    off when the name is one scene person and the place names nothing of the scene."""
    if " at " not in text.lower() and " in " not in text.lower() and " on " not in text.lower():
        return text

    def who(m: re.Match[str]) -> str:
        place = m[0][len(m["who"]) :]
        if _only_person(m["who"], lexicon) and _names_nothing(place, lexicon):
            return m["who"]
        return m[0]

    return _AT_TABLE30.sub(who, text)


# "all of it's for person a, that's the bottle and the chips": 'all' said, then what it is
_ALL_LISTED30 = re.compile(
    r"(?P<all>\b(?:all of it|all of them|everything|the lot|the whole lot|all of that)\b"
    # 'all' itself, not a kind of it ('Everything sweet goes …' is _described_list27's)
    r"(?='s|\s+(?:is|are|goes|go|to|for|on|onto|in|into|over|across)\b|\s*[,.;!?]|\s*$)"
    r"[^.;!?]*?)"
    r",\s*(?:that's|that is|which is|which are|i\.e\.|meaning|namely)(?: just| only)? "
    r"(?P<list>[^.;!?,]+?(?:,[^.;!?,]+?)*)\s*(?=[.;!?]|$)",
    _F,
)


def _all_listed30(text: str, lexicon: Lexicon) -> str:
    """Session 30: what 'all' is, said after it (above), taken off when the list names the
    scene's objects, each and only those (a list of fewer is a contradiction: left, and refused)."""
    m = _ALL_LISTED30.search(text)
    if m is None:
        return text
    named = _names(m["list"], lexicon)
    every = {o.id for o in lexicon.scene.objects}
    if (
        not named
        or any(len(it.refs) != 1 or it.refs[0].kind != "object" for it in named)
        or {it.refs[0].id for it in named} != every
        # each item one name of one object, nothing else ('…, before I go tomorrow' is no item)
        or not all(
            len(_ids(item, lexicon)) == 1 and _only_kind(item, lexicon, "object")
            for item in re.split(r"\s*,\s*(?:and\s+)?|\s+and\s+", m["list"].strip(), flags=_F)
        )
    ):
        return text
    return text[: m.start()] + m["all"] + text[m.end() :]


# "It's the chips that Person B wants, not the bottle.": the object put first in a cleft
_CLEFT30 = re.compile(
    r"(?:^|(?<=[.;!?])\s+)it(?:'s| is) (?P<what>(?:the|that|this) [a-z][a-z ]*?) (?:that|which) "
    r"(?P<who>[A-Za-z]+(?: [A-Za-z]+)?) (?P<verb>wants|needs|is after|would like|'d like|asked "
    r"for|has asked for)(?=\s*(?:[,.;!?]|$))",
    _F,
)


def _cleft30(text: str, lexicon: Lexicon) -> str:
    """Session 30: the cleft above said plainly ('Person B wants the chips, not the bottle.') when
    P is one person and X objects of the scene only."""
    if "it" not in text.lower():
        return text

    def plain(m: re.Match[str]) -> str:
        if not (_only_person(m["who"], lexicon) and _objects_only(m["what"], lexicon)):
            return m[0]
        lead = m[0][: m[0].lower().index("it")]
        return f"{lead}{m['who']} {m['verb']} {m['what']}"

    return _CLEFT30.sub(plain, text)


# "The milkman's crates need sealing.", "The two stagehands need feeding: …": a state said with
# 'need(s)' and a verb in '-ing', of something or someone the scene does not name; it asks the cell
# nothing. Taken off as a sentence of its own or a heading before a colon when its subject names
# nothing and asks nothing (_asks_nothing29); a count before the subject ('the two stagehands')
# only when as many people of the scene are named after the colon.
_NEEDS_DOING30 = re.compile(
    r"(?P<subject>(?:the|our|my|his|her|their|a|an|these|those) (?:(?P<count>two|three|four|both) "
    r")?[a-z' -]+?) (?:need|needs|want|wants) (?P<doing>[a-z]+ing)(?: (?:badly|urgently|again))?",
    _F,
)


# "…, while the chips go across to Person A": 'while' between two tasks sets them side by side
_WHILE_GO30 = re.compile(
    r",\s*while (?P<what>(?:the|that|this|those|these) [a-z][a-z ]*?) (?P<verb>go|goes) "
    r"(?P<dir>(?:(?:over|across|round|along|up|down) )?)to (?P<where>[A-Za-z]+(?: [A-Za-z]+)?)"
    r"(?=\s*(?:[.!?;]|$))",
    _F,
)


def _while_go30(text: str, lexicon: Lexicon) -> str:
    """Session 30: the 'while' above is 'and', when a task is said before it and the X are
    objects of the scene only and P one person or surface (as _while29 for two wants)."""
    if "while" not in text.lower():
        return text

    def side(m: re.Match[str]) -> str:
        before = re.split(r"[.!?;:]\s", text[: m.start()])[-1]
        if (
            _ids(before, lexicon, "object")
            and _objects_only(m["what"], lexicon)
            and (_only(m["where"], lexicon, "human") or _only(m["where"], lexicon, "surface"))
        ):
            what = m["what"][:1].upper() + m["what"][1:]  # a sentence of its own: 'go' is plain
            return f". {what} {m['verb']} {m['dir']}to {m['where']}"
        return m[0]

    return _WHILE_GO30.sub(side, text)


# "The clown's Person B and he's getting the bottle": who the trade is, then a pronoun for them
_WHO_IS30 = re.compile(
    r"(?:^|(?<=[.!?;]\s))(?:the|our|my|your) (?P<trade>[a-z]+(?: [a-z]+)?)(?:'s| is) "
    r"(?P<who>[A-Za-z]+(?: [A-Za-z]+)?),? and (?P<pronoun>he|she|they)\b",
    _F,
)


def _who_is30(text: str, lexicon: Lexicon) -> str:
    """Session 30: the trade said to be P (above), then a pronoun for P, is P: when the trade is
    words the lexer does not know naming nothing (_trade_words29), P one person, and the pronoun
    may be P."""
    if " and " not in text.lower():
        return text

    def named(m: re.Match[str]) -> str:
        if (
            _trade_words29(m["trade"], lexicon)
            and _only_person(m["who"], lexicon)
            and _fits(next(iter(_ids(m["who"], lexicon))), m["pronoun"], lexicon)
        ):
            return m["who"]
        return m[0]

    return _WHO_IS30.sub(named, text)


# "…, and the bottle, well, him again, Person B.": a pronoun, then the name it stands for
_NAMED_AFTER30 = re.compile(
    r"\b(?P<pronoun>him|her|them)(?: again| too| as well)?, (?P<who>[A-Za-z]+(?: [A-Za-z]+)?)"
    r"(?=\s*(?:[.!?;]|$))",
    _F,
)


def _named_after30(text: str, lexicon: Lexicon) -> str:
    """Session 30: the pronoun and its name (above) are the name, when the name is one person,
    the one person named before it, whom the pronoun may be."""
    if not _rx(r"\b(?:him|her|them)\b").search(text):
        return text

    def name(m: re.Match[str]) -> str:
        before = _ids(text[: m.start()], lexicon, "human")
        who = _ids(m["who"], lexicon, "human")
        if (
            _only_person(m["who"], lexicon)
            and before == who
            and _fits(next(iter(who)), m["pronoun"], lexicon)
        ):
            return m["who"]
        return m[0]

    return _NAMED_AFTER30.sub(name, text)


# "Bottle: Person A. Cup: Person B. And the chips, also Person A.": a note said with 'and' after
# notes of the same form ('<object>: <person>.')
_NOTE30 = re.compile(r"(?P<what>[a-z][a-z ]*?):\s*(?P<who>[A-Za-z]+(?: [A-Za-z]+)?)", _F)
_NOTE_AND30 = re.compile(
    r"(?:and|also|plus) (?:the )?(?P<what>[a-z][a-z ]*?),? (?:also |too,? )?"
    r"(?P<who>[A-Za-z]+(?: [A-Za-z]+)?)(?: too| as well)?",
    _F,
)


def _note_and30(text: str, lexicon: Lexicon) -> str:
    """Session 30: the note with 'and' (above) said as the notes before it are, when each note
    is one object and one person of the scene."""
    if ":" not in text:
        return text
    parts = re.split(r"(\s*[.!]+\s*)", text.strip())
    sents, seps = parts[0::2], [*parts[1::2], ""]

    def note(what: str, who: str) -> bool:
        return len(_ids(what, lexicon, "object")) == 1 and (
            _only_kind(what, lexicon, "object") and _only_person(who, lexicon)
        )

    seen = False
    out: list[str] = []
    for sent, sep in zip(sents, seps, strict=True):
        plain = _NOTE30.fullmatch(sent.strip())
        if plain is not None and note(plain["what"], plain["who"]):
            seen = True
        said = _NOTE_AND30.fullmatch(sent.strip())
        if seen and plain is None and said is not None and note(said["what"], said["who"]):
            sent = f"{said['what'][:1].upper()}{said['what'][1:]}: {said['who']}"
        out.append(sent + sep)
    return "".join(out).strip()


# "…, and once that's done Bob can take his crisps": 'P can take / have X' in a later clause
_CAN_TAKE30 = re.compile(
    r"(?:(?<=[,;] )|(?<=\bthen )|(?<=\bdone )|(?<=\bdone, ))"
    r"(?!(?:then|and|so)\b)(?P<who>[A-Za-z]+(?: [A-Za-z]+)?) can (?:take|have) "
    r"(?:(?P<own>his|her|their) |(?=the ))(?P<what>[a-z][a-z ]*?)(?=\s*(?:[.!?;]|$))",
    _F,
)


def _can_take30(text: str, lexicon: Lexicon) -> str:
    """Session 30: 'P can take / have X' after a comma, 'then' or 'once that's done' (above) is
    'P gets X' (as it reads alone), when P is one person (whom 'his' / 'her' may be) and X objects
    of the scene only."""
    if " can " not in text.lower():
        return text

    def gets(m: re.Match[str]) -> str:
        what = m["what"]
        if not (_only_person(m["who"], lexicon) and _objects_only(what, lexicon)):
            return m[0]
        if m["own"] and not _fits(next(iter(_ids(m["who"], lexicon))), m["own"], lexicon):
            return m[0]
        return f"{m['who']} gets {'the ' if m['own'] else ''}{what}"

    return _CAN_TAKE30.sub(gets, text)


# "person b is thirsty after the dive so she wants the bottle": a state and its cause, then 'so'
_STATE_AFTER30 = re.compile(
    r"\b(?P<state>(?:is|'s|are|'re) [a-z]+) after (?P<cause>(?:the|a|an|his|her|their|my|our) "
    r"[a-z' -]+?)(?=,? so\b)",
    _F,
)


# "Could the bowl go in the sink? The botanist's soil is caked on it.": a statement after the
# request about its one object ('it'), naming nothing else: why it is asked
_STATEMENT_IT30 = re.compile(r"\b(?:is|are|was|were|'s|'re)\b", _F)


def _mind30(text: str, _lexicon: Lexicon) -> str:
    """Session 30: "Mind popping the packing tape on the pallet?": 'Would you mind …?' said short
    (a question; 'Mind the step' is a warning, and no '-ing' follows it)."""
    return _sub(r"^mind (?=[a-z]+ing\b[^.!?]*\?)", "Would you mind ", text)


# "Can you carry the bottle down the line to Person A?": the way it is carried, then where to
_PATH30 = re.compile(
    r"(?P<before>\b(?:the|that|this|it|them)\b[^,.;!?]*?) (?P<dir>down|along|up|across|through|"
    r"round|around) the (?P<path>[a-z]+(?: [a-z]+)?) (?=to )",
    _F,
)


def _path30(text: str, lexicon: Lexicon) -> str:
    """Session 30: the way (above) taken off, its direction kept ('carry the bottle down to
    Person A'), when it names nothing of the scene and holds no word that counts, chooses or
    points back (_inert28), and an object or 'it' / 'them' is said before it."""
    if " the " not in text.lower():
        return text

    def way(m: re.Match[str]) -> str:
        said = m["before"]
        if not (_ids(said, lexicon, "object") or re.search(r"\b(?:it|them)\b", said, _F)):
            return m[0]
        if not _inert28(m["path"], lexicon):
            return m[0]
        direction = {"through": "over", "around": "round"}.get(m["dir"].lower(), m["dir"])
        return f"{said} {direction} "

    return _PATH30.sub(way, text)


# "… onto the shelf so the ventriloquist's dummy can't get at them?": what the request is for,
# with a subject the scene does not name (session 19's purpose rule takes it with a pronoun)
_SO_THAT30 = re.compile(
    r",?\s+so (?:that )?(?P<said>(?:the|a|an|his|her|their|my|our|your) [a-z' -]+? (?:can't|"
    r"cannot|won't|can|could|will|'ll|doesn't|don't|isn't) [a-z' ]{2,40}?)(?=\s*(?:[.;!?]|$))",
    _F,
)


def _so_that30(text: str, lexicon: Lexicon) -> str:
    """Session 30: the purpose above taken off when it names nothing of the scene (nor a typo of
    a name) and something is named before it."""
    if " so " not in text.lower():
        return text
    m = _SO_THAT30.search(text)
    if (
        m is None
        or not _names_nothing(m["said"], lexicon)
        or not _names(text[: m.start()], lexicon)
    ):
        return text
    return text[: m.start()] + text[m.end() :]


# "Omar's got spore prints drying, so he needs the spoon …": what a person has going on, said as the
# reason for a request after 'so'
_HAS_GOING30 = re.compile(
    r"(?:^|(?<=[.;!?]\s))(?P<who>[A-Za-z]+(?: [A-Za-z]+)?)(?:'s| has) got (?P<what>(?:some |his |"
    r"her |their |a |an |the )?[a-z][a-z' -]*?) (?P<doing>[a-z]+ing)(?=,? so\b)",
    _F,
)


# -- session 31 (engineer 12): blind29's kinds (politeness, wants, pronouns and ellipsis, splits,
# lower case, questions); docs/grounding.md, "Session 31 (engineer 12)" ---------------------------


def _things31(words: str, lexicon: Lexicon) -> bool:
    """Whether ``words`` (a phrase the session-31 patterns take lazily up to a mark) is objects of
    the scene only, said as names alone: no verb of the grammar and no word that asks
    (_ASKS29) among them ('the cup wants the apple' is no list of objects)."""
    tokens = re.findall(r"[a-z']+", words.lower())
    return (
        _objects_only(words, lexicon)
        and not any(t in VERBS for t in tokens)
        and not _ASKS29.search(" ".join(tokens[1:]))  # past its determiner ('that bottle')
    )


# A courtesy of another language said with what it is ("Rahmat, as we say in Uzbek!", "Jerejef, as
# we say in Wolof.", "…, as my gran would say in Gaelic"): one to three words, then 'as <someone>
# (would) say in <a capitalised language or place>', a sentence or comma part of its own; or that
# alone as a sentence, its courtesy taken off before (_courtesy24: "Salamat, as we say in …!")
_AS_WE_SAY31 = re.compile(
    r"(?P<lead>^|(?<=[.!?])\s+|,\s*)(?:(?P<word>[A-Za-z][\w'’-]*(?: [\w'’-]+){0,2}),\s*)?[Aa]s "
    r"(?:we|I|they|you|people|folk|my [a-z]+|our [a-z]+) (?:would |'d |always |often |like to )?"
    r"say (?:it )?(?:in|back in|over in|up in|down in) (?P<lang>[A-Z][a-z]+(?: [A-Z][a-z]+)?)"
    r"(?P<end>\s*(?:[.!?:;]|$))"
)


# an interjection opening a question, before 'could / would / can / will you' ("Ooh, would you put
# the bib on the high chair?"): a sound of the speaker, never a word of the request
_INTERJECTED31 = re.compile(
    r"^(?:oh|ooh|ah|aah|aw|ooh la la|oh dear|well|hmm|um|erm|er|uh)\s*,\s*(?=(?:could|would|can|"
    r"will|might|may) (?:you|someone|somebody|one of you)\b)",
    _F,
)


def _interjected31(text: str, _lexicon: Lexicon) -> str:
    """Session 31: the interjection above taken off."""
    return _INTERJECTED31.sub("", text)


# a trade said before a person's name, with the speaker's or a person's word, in a later clause
# ("…, while her coach, Person B, is owed the chips"): it only describes the person (as trades29's
# 'the <trade>' after the name)
_TRADE_BEFORE31 = re.compile(
    r"(?P<lead>(?<=[;]\s)|(?<=,\s)|(?<=\bwhile\s)|(?<=\band\s))(?:our|my|your|her|his|their|the) "
    r"(?P<trade>[a-z]+(?: [a-z]+)?),\s+(?P<p>[A-Z][a-z]+(?: [A-Z][a-z]*)?),\s+",
    _F,
)


def _trades31(text: str, lexicon: Lexicon) -> str:
    """Session 31: the trade above taken off, the person's name kept, when the name is one person
    of the scene and the trade words could only describe a person (_trade_words29)."""
    if "," not in text:
        return text

    def named(m: re.Match[str]) -> str:
        if _only_person(m["p"], lexicon) and _trade_words29(m["trade"], lexicon):
            return f"{m['p']} "
        return m[0]

    return _TRADE_BEFORE31.sub(named, text)


# wants said by an idiom: a closed list (docs/grounding.md, "Session 31 (engineer 12)"), each said
# plainly as a want the grammar reads ('should get')
_IDIOMS31: tuple[tuple[str, str], ...] = (
    # "Person A is owed the bottle": it is due to her
    (r"(?:\s+is|'s) (?:still )?owed\b(?= (?:the|that|this|those|these|her|his|their)\b)",
     " should get"),
    # "Person A has earned the bottle": she has a right to it now
    (r"(?:\s+has|'s) (?:really |more than |well and truly )?earned\b(?= (?:the|that|this|those|"
     r"these|her|his|their)\b)", " should get"),
    # "Bob has been eyeing the crisps": he wants them
    (r"(?:\s+has|'s|\s+is) (?:been )?eyeing(?: up)?\b(?= (?:the|that|this|those|these)\b)",
     " wants"),
)  # fmt: skip


def _idioms31(text: str, _lexicon: Lexicon) -> str:
    """Session 31: the idioms above, said plainly."""
    for pattern, plain in _IDIOMS31:
        text = _sub(pattern, plain, text)
    return text


# what the wanted object is for, said as 'to <verb>' after it ("Person B would love the chips to
# nibble", "… a cup to pour into"): a purpose, never where it goes
_TO_DO31 = re.compile(
    r"(?P<before>\b(?:would (?:love|like)|'d (?:love|like)|wants?|needs?|could use|could do with|"
    r"fancies|fancy) [^,.;!?]*?)\s+to (?P<verb>[a-z]+)(?P<prep> (?:into|in|on|with|from|over))?"
    r"(?=\s*(?:[,.;!?]|$|\band\b))",
    _F,
)


# a want said as a cleft: "The chips are what Person B is hoping for", "for Person B it's the apple
# she's craving"; the wanting said with a verb of wanting (closed: _WANTING31)
_WANTING31 = (
    r"(?:wants|needs|is after|'s after|is hoping for|'s hoping for|is wanting|'s wanting|"
    r"is craving|'s craving|craves|fancies|is longing for|'s longing for|would like|'d like|"
    r"has asked for|asked for|is waiting for|'s waiting for)"
)
_WHAT_WANTS31 = re.compile(
    rf"(?:^|(?<=[,;.!?]\s))(?P<x>(?:the|that|this|those|these) [a-z][a-z ]*?) (?:is|are|'s|'re) "
    rf"(?:just |exactly )?what (?P<p>[A-Z][a-z]+(?: [A-Z][a-z]*)?) (?:really )?{_WANTING31}"
    r"(?=\s*(?:[,.;!?]|$))",
    _F,
)
_FOR_ITS31 = re.compile(
    r"(?:^|(?<=[,;.!?]\s))for (?P<p>[A-Z][a-z]+(?: [A-Z][a-z]*)?),? it(?:'s| is) "
    r"(?P<x>(?:the|that|this|those|these) [a-z][a-z ]*?) (?:that )?(?P<pron>she|he|they)"
    r"(?:'s|'re| is| are) (?:really )?(?:craving|after|wanting|hoping for|longing for|"
    r"waiting for)"
    r"(?=\s*(?:[,.;!?]|$))",
    _F,
)


def _cleft_wants31(text: str, lexicon: Lexicon) -> str:
    """Session 31: the clefts above are 'P wants X', when P is one person of the scene, X objects
    of the scene only, and the pronoun (in the second) may be that person."""
    if " what " not in text.lower() and "for " not in text.lower():
        return text

    def wants(m: re.Match[str]) -> str:
        if not (_only_person(m["p"], lexicon) and _things31(m["x"], lexicon)):
            return m[0]
        if "pron" in m.groupdict() and not _the_person(m["p"], m["pron"], lexicon):
            return m[0]
        return f"{m['p']} wants {m['x']}"

    return _FOR_ITS31.sub(wants, _WHAT_WANTS31.sub(wants, text))


# the speaker saying whose word the request is, closing it: "…, she tells me.", "…, he told me",
# "…, or so I'm told": who said it, never who gets anything
_TOLD_ME31 = re.compile(
    r",\s*(?:or so )?(?:(?:she|he|they) (?:tells|told|has told|'s told|tell|have told|'ve told) "
    r"me|I'm told|I am told|I've been told|I was told)(?:\s+(?:so|earlier|just now))?"
    r"(?P<end>\s*[.!]?\s*)$",
    _F,
)


def _told_me31(text: str, lexicon: Lexicon) -> str:
    """Session 31: the closing part above taken off when what is left names a person of the
    scene (who told the speaker does not change what is asked)."""
    m = _TOLD_ME31.search(text)
    if m is None or not _ids(text[: m.start()], lexicon, "human"):
        return text
    return text[: m.start()] + m["end"].strip()


# "…, and the stapler along with it": 'along with it / them' after a second object is 'too'
_ALONG_WITH31 = re.compile(
    r"(?P<x>\b(?:the|that|this|those|these) [a-z][a-z ]*?) along with (?:it|them)"
    r"(?=\s*(?:[,.;!?]|$))",
    _F,
)


def _along_with31(text: str, lexicon: Lexicon) -> str:
    """Session 31: 'X along with it / them' (above) is 'X too', when X is objects of the scene only
    and an object is named before it (what 'it' stands for: the grammar keeps the first task's
    person for 'too')."""
    if "along with" not in text.lower():
        return text

    def too(m: re.Match[str]) -> str:
        before = text[: m.start()]
        if not _things31(m["x"], lexicon) or not _ids(before, lexicon, "object"):
            return m[0]
        return f"{m['x']} too"

    return _ALONG_WITH31.sub(too, text)


# "…, and she'll take the bottle (too)": a person saying what they will take is their want
_WILL_TAKE31 = re.compile(
    r"\b(?P<pron>she|he|they)(?:'ll| will) (?:happily |gladly )?take (?P<x>(?:the|that|this|those|"
    r"these) [a-z][a-z ]*?)(?P<too>,? (?:too|as well|also))?(?=\s*(?:[.;!?]|$))",
    _F,
)


def _will_take31(text: str, lexicon: Lexicon) -> str:
    """Session 31: 'she'll take X' (above) is 'she wants X', when X is objects of the scene only
    (nothing said of where it goes) and one person is named before it whom the pronoun may be."""
    if "take" not in text.lower():
        return text

    def wants(m: re.Match[str]) -> str:
        people = _ids(text[: m.start()], lexicon, "human")
        if len(people) != 1 or not _things31(m["x"], lexicon):
            return m[0]
        pid = next(iter(people))
        name = next(h.name for h in lexicon.scene.humans if h.id == pid)
        if not _the_person(name, m["pron"], lexicon):
            return m[0]
        return f"{m['pron']} wants {m['x']}{m['too'] or ''}"

    return _WILL_TAKE31.sub(wants, text)


# a task said as the person 'with' the object, no verb ("…, and after her, Person B with the
# chips", "person b first with the chips, then …"): the object to that person
_WITH_OBJECT31 = re.compile(
    r"(?P<lead>^|(?<=[,;.!?]\s)|(?<=\band\s)|(?<=\bthen\s))(?P<p>[A-Za-z]+(?: [A-Za-z])?)"
    r"(?P<when> first| next| last)?,? with (?P<x>(?:the|that|this|those|these) [a-z][a-z ]*?)"
    r"(?=\s*(?:[,.;!?]|$|\bthen\b))",
    _F,
)


def _with_object31(text: str, lexicon: Lexicon) -> str:
    """Session 31: 'P (first) with X' (above) is 'X to P (first)', when P is one person of the
    scene, said alone (no verb before it in its clause), and X objects of the scene only."""
    if " with " not in text.lower():
        return text

    def to(m: re.Match[str]) -> str:
        if not (_only_person(m["p"], lexicon) and _things31(m["x"], lexicon)):
            return m[0]
        return f"{m['x']} to {m['p']}{m['when'] or ''}"

    return _WITH_OBJECT31.sub(to, text)


# "Could Person A get the chips, with the bottle going to Person B?": a second task said as what
# goes with the first
_WITH_GOING31 = re.compile(
    r",\s*with (?P<x>(?:the|that|this|those|these) [a-z][a-z ]*?) (?:going|heading|off) "
    r"(?P<dir>(?:over |across |up |down )?)(?P<to>to|on|onto|in|into) "
    r"(?P<where>(?:the )?[A-Za-z]+(?: [A-Za-z]+)?)(?=\s*(?:[.!?]|$))",
    _F,
)


def _with_going31(text: str, lexicon: Lexicon) -> str:
    """Session 31: ', with X going to P' (above) is ', and X to P', when X is objects of the
    scene only and P one person or surface."""
    if " with " not in text.lower():
        return text

    def also(m: re.Match[str]) -> str:
        where = m["where"]
        if not _things31(m["x"], lexicon) or not (
            _only_person(where, lexicon) or _surface_only(where, lexicon)
        ):
            return m[0]
        return f", and {m['x']} {m['to']} {where}"

    return _WITH_GOING31.sub(also, text)


# "…, if you can manage both.": the speaker allowing that it is much to ask, closing the request
_IF_MANAGE31 = re.compile(
    r",\s*if you (?:can|could) (?:manage|handle|carry) (?P<what>both|it|that|them|all that|the two)"
    r"(?: (?:of them|at once|together))?(?P<end>\s*[.!]?)\s*$",
    _F,
)


def _if_manage31(text: str, lexicon: Lexicon) -> str:
    """Session 31: the closing part above taken off ('both' and 'the two' only when the request
    names exactly two objects, which it then counts)."""
    m = _IF_MANAGE31.search(text)
    if m is None:
        return text
    rest = text[: m.start()]
    if m["what"].lower() in ("both", "the two") and len(_ids(rest, lexicon, "object")) != 2:
        return text
    return rest + m["end"].strip()


# the speaker closing a run-on: "… that's it that's all from the tobacconist", "… and right that's
# the orienteers fed": it says the request is over (and who sends it), never asks
_RUN_ON_CLOSE31 = re.compile(
    r"(?:\s*,)?\s+(?:and )?(?:(?:right|okay|ok|so)\s*,?\s+)?(?:that's (?:it|all|everything)"
    r"(?:,? that's (?:it|all|everything))*(?: from (?:the|your) (?P<trade>[a-z]+(?: [a-z]+)?))?|"
    r"that's (?:the|our|my|them|the two of them|both of them) ?(?P<who>[a-z]*) "
    r"(?:fed|sorted|done|happy|set|watered|looked after))(?P<end>\s*[.!]?)\s*$",
    _F,
)


def _run_on_close31(text: str, lexicon: Lexicon) -> str:
    """Session 31: the closing above taken off when the trade (if said) could only describe a
    person (_trade_words29), the people fed are named by no scene word, and a request is left."""
    m = _RUN_ON_CLOSE31.search(text)
    if m is None:
        return text
    if m["trade"] and not _trade_words29(m["trade"], lexicon):
        return text
    if m["who"] and not _names_nothing(m["who"], lexicon):
        return text
    rest = text[: m.start()]
    return rest + m["end"].strip() if _names(rest, lexicon) else text


# "bring it her", "give it him": British speech for 'bring it to her'
_IT_HER31 = re.compile(
    r"\b(?P<v>bring|give|hand|pass|take|fetch|send) (?P<x>it|them) (?P<p>her|him|them)\b"
    r"(?=\s*(?:[,.;!?]|$))",
    _F,
)


def _it_her31(text: str, _lexicon: Lexicon) -> str:
    """Session 31: 'bring it her' (above) is 'bring it to her' (the pronouns left to the
    grammar, which refuses them when it cannot tell whom or what they mean)."""
    return _IT_HER31.sub(lambda m: f"{m['v']} {m['x']} to {m['p']}", text)


# "…, and the moment you've done that the bottle to Person A": as soon as the first is done
_THE_MOMENT31 = re.compile(
    r"\b(?:the moment|the minute|the second|as soon as) (?:you've|you have|you're|you are) "
    r"(?:done|finished|through with) (?:that|it|this)(?: one)?,?\s+(?=[a-z])",
    _F,
)


def _the_moment31(text: str, _lexicon: Lexicon) -> str:
    """Session 31: 'the moment you've done that' (above) is 'once that's done,' (which the grammar
    orders after what was said before it)."""
    return _THE_MOMENT31.sub("once that's done, ", text)


# "Any chance the chips could make their way over to Person A?": the objects going there
_MAKE_WAY31 = re.compile(
    r"(?P<x>\b(?:the|that|this|those|these) [a-z][a-z ]*?) (?P<modal>(?:could|can|would|might|"
    r"will|should) )?make (?:their|its) way (?P<dir>(?:over |across |up |down |round )?)to\b",
    _F,
)


def _make_way31(text: str, lexicon: Lexicon) -> str:
    """Session 31: 'X make their way to' (above) is 'X go to', when X is objects of the scene only
    ('their' then is said of them, never of a person)."""
    if "way" not in text.lower():
        return text

    def go(m: re.Match[str]) -> str:
        if not _things31(m["x"], lexicon):
            return m[0]
        return f"{m['x']} {m['modal'] or ''}go {m['dir']}to"

    return _MAKE_WAY31.sub(go, text)


# where an object is picked up from, said before a second task for 'it' ("Grab the apple off the
# side and give it to Carol", "Could the blue plate come off the rack and go on the worktop?")
_OFF_THE31 = re.compile(
    r"\b(?P<v>grab|take|get|pick up|lift) (?P<x>(?:the|that|this) [a-z][a-z ]*?) (?:off|from) "
    r"(?:the|that|this) (?P<from>[a-z]+(?: [a-z]+)?) and (?=(?:give|hand|pass|bring|take|put|"
    r"place|set|pop|drop|stand) it\b)",
    _F,
)
_COME_OFF31 = re.compile(
    r"(?P<x>\b(?:the|that|this) [a-z][a-z ]*?) (?P<modal>(?:could|can|would|might|will|should) )?"
    r"come (?:off|down from|out of|from) (?:the|that|this) (?P<from>[a-z]+(?: [a-z]+)?) and go "
    r"(?=(?:on|onto|in|into|to|over to|across to) )",
    _F,
)


# 'while' between two wants after a comma ("Person A should get the bottle, while Person B should
# get the chips"): _while29 reads it without the comma
_WHILE31 = re.compile(
    r"(?<=\w),\s+while (?P<p>[A-Za-z]+(?: [A-Za-z]+)?) "
    r"(?=(?:wants|needs|gets|would like|fancies|should get|should have)\b)",
    _F,
)


def _while31(text: str, lexicon: Lexicon) -> str:
    """Session 31: ', while P <wants>' is ', and P <wants>' when P is one person of the scene and
    the clause before it names an object (two wants side by side)."""
    if " while " not in text.lower():
        return text

    def side(m: re.Match[str]) -> str:
        before = re.split(r"[.!?;:]\s", text[: m.start()])[-1]
        if _only_person(m["p"], lexicon) and _ids(before, lexicon, "object"):
            return f", and {m['p']} "
        return m[0]

    return _WHILE31.sub(side, text)


# an object wanted 'up on' / 'down on' a surface ("Alice would like the bottle up on the shelf"):
# the direction is said of the surface, 'on' it
_UP_ON31 = re.compile(
    r"(?P<x>\b(?:the|that|this|those|these) [a-z][a-z ]*?) (?:up|down|back|over) "
    r"(?P<on>on|onto|in|into|on top of) (?P<s>(?:the )?[a-z]+(?: [a-z]+)?)\b",
    _F,
)


def _up_on31(text: str, lexicon: Lexicon) -> str:
    """Session 31: 'X up on S' (above) is 'X on S' when X is objects of the scene only and S one
    surface (what it is put on)."""
    if " on" not in text.lower() and " in" not in text.lower():
        return text

    def on(m: re.Match[str]) -> str:
        if not _things31(m["x"], lexicon):
            return m[0]
        words = m["s"].split()
        for k in range(len(words), 0, -1):  # 'the shelf and': the surface is 'the shelf'
            if _surface_only(" ".join(words[:k]), lexicon):
                return f"{m['x']} {m['on']} {m['s']}"
        return m[0]

    return _UP_ON31.sub(on, text)


# why a place is chosen, said of it after a comma ("…, where nobody will knock it over"): a closed
# list of the harms a high or safe place keeps off (docs/grounding.md)
_SAFE_WHERE31 = re.compile(
    r",\s*(?:where|so) (?:nobody|no one|no-one|the kids|the children|little hands|the dog|the cat) "
    r"(?:will|can|'ll|could|won't|can't)\s+(?:knock|reach|get at|get to|grab|spill|break|touch)"
    r"(?: (?:it|them))?(?: (?:over|down|off))?(?P<end>\s*[.!]?)\s*$|"
    # "…, the maltster wants them out of reach": who asks wanting them kept safe there
    r",\s*(?:(?:the|our|my) (?P<trade>[a-z]+)|she|he|they|I|we) (?:wants?|likes?|would like|"
    r"'d like|needs?) (?:it|them) (?:kept )?(?:out of reach|out of the way|up high|"
    r"somewhere safe|safe)"
    r"(?P<end2>\s*[.!]?)\s*$",
    _F,
)


def _safe_where31(text: str, lexicon: Lexicon) -> str:
    """Session 31: the reasons above taken off after a request that names one surface and an
    object (they then say why there, never anything more), the trade (if said) one that could
    only describe a person (_trade_words29)."""
    m = _SAFE_WHERE31.search(text)
    if m is None or (m["trade"] and not _trade_words29(m["trade"], lexicon)):
        return text
    rest = text[: m.start()]
    if len(_ids(rest, lexicon, "surface")) != 1 or not _ids(rest, lexicon, "object"):
        return text
    return rest + (m["end"] or m["end2"] or "").strip()


# "What Bob really needs right now, after his shift at the chandler's, is the crisps.": a cleft
# want with why, said between commas, naming what happened before (the want is now)
_WHAT_NEEDS31 = re.compile(
    r"^what (?P<p>[A-Za-z]+(?: [A-Za-z]+)??) (?:really |most )?(?P<v>needs|wants|would like)"
    r"(?: (?:right now|now|most))?,\s*(?P<why>(?:after|since) (?:his|her|their|a|the) [^,]+?),\s*"
    r"is (?P<x>(?:the|that|this|those|these) [a-z][a-z ]*?)(?P<end>\s*[.!]?)\s*$",
    _F,
)


def _what_needs31(text: str, lexicon: Lexicon) -> str:
    """Session 31: the cleft above is 'P needs X', when P is one person of the scene, X objects of
    the scene only and what happened names nothing and holds no word that asks (_ASKS29) past its
    first two words."""
    m = _WHAT_NEEDS31.match(text.strip())
    if m is None:
        return text
    why = m["why"].split(" ", 2)
    # past its determiner a noun ('his shift' is no request to shift anything): no word that asks
    if len(why) < 3 or _ASKS29.search(why[2]) or not _names_nothing(m["why"], lexicon):
        return text
    if not (_only_person(m["p"], lexicon) and _things31(m["x"], lexicon)):
        return text
    return f"{m['p']} {m['v']} {m['x']}{m['end']}"


# "After the regatta Person A is dry as a bone and needs …": what happened before the state the
# person is in now (a present 'is' right after the person): it says why, never when to act
_AFTER_STATE31 = re.compile(
    r"^(?:after|since) (?P<what>(?:the|his|her|their|a|an) [a-z][a-z' ]*?),?\s+"
    r"(?=(?P<p>[A-Za-z]+(?: [A-Za-z]+)?)(?:'s| is) )",
    _F,
)


_TO_COME31 = frozenset({"to", "going", "due", "about", "off", "away", "out", "back", "set", "yet"})


# "carol is thirsty so the water bottle to her": a state, then 'so' and what it calls for, said
# without the comma the grammar needs between them
_STATE_SO31 = re.compile(
    r"^(?P<p>[A-Za-z]+(?: [A-Za-z]+)?) (?P<be>is|'s) (?P<how>(?:really |very |so |a bit |dead )?"
    r"[a-z]+) so (?=[a-z])",
    _F,
)


# an owned surface said with a pronoun ("… set down on her desk"): the one person named before
_HER_SURFACE31 = re.compile(
    r"\b(?P<on>on|onto|in|into|on top of) (?P<pron>her|his|their) (?P<s>[a-z]+(?: [a-z]+)?)\b", _F
)


def _her_surface31(text: str, lexicon: Lexicon) -> str:
    """Session 31: 'on her desk' is 'on the desk' when the desk is one surface of the scene and
    one person is named before it, whom the pronoun may be (as _owned_surface29s with a name)."""
    if not _rx(r"\b(?:her|his|their) ").search(text):
        return text

    def the(m: re.Match[str]) -> str:
        words = m["s"].split()
        for n in (len(words), 1):
            s = " ".join(words[:n])
            if _surface_only(s, lexicon):
                people = _ids(text[: m.start()], lexicon, "human")
                if len(people) != 1:
                    return m[0]
                pid = next(iter(people))
                name = next(h.name for h in lexicon.scene.humans if h.id == pid)
                if not _the_person(name, m["pron"], lexicon):
                    return m[0]
                rest = " ".join(words[n:])
                return f"{m['on']} the {s}{' ' + rest if rest else ''}"
        return m[0]

    return _HER_SURFACE31.sub(the, text)


# what a placement is for, said as one bare word ("… on the desk for geography"): after a surface
_FOR_BARE31 = re.compile(
    r"(?P<s>\b(?:on|onto|in|into|on top of) (?:the )?[a-z]+(?: [a-z]+)?) for (?P<w>[a-z]+)"
    r"(?P<end>\s*[.!]?)\s*$",
    _F,
)


# "Serve Person A first, give her the bottle, …": who is served first, then what she is given
_SERVE_FIRST31 = re.compile(
    r"^(?:serve|see to|start with|begin with) (?P<p>[A-Za-z]+(?: [A-Za-z]+)?) first,\s*"
    r"(?P<v>give|hand|pass|bring) (?P<pron>her|him|them) (?=(?:the|that|this|those|these) )",
    _F,
)


def _serve_first31(text: str, lexicon: Lexicon) -> str:
    """Session 31: 'Serve P first, give her X' is 'First give P X', when P is one person of the
    scene whom the pronoun may be."""
    m = _SERVE_FIRST31.match(text.strip())
    if m is None or not _the_person(m["p"], m["pron"], lexicon):
        return text
    return f"First {m['v'].lower()} {m['p']} {text.strip()[m.end() :]}"


# "Cup first, over to Person B.": the object, its order, then where it goes, a sentence of its own
_FIRST_OVER31 = re.compile(
    r"(?:^|(?<=[.;!?]\s))(?P<x>(?:the |that |this )?[A-Za-z][a-z]*(?: [a-z]+)?) first,\s*"
    r"(?P<dir>(?:over|across|up|down|round) )?(?P<to>to|on|onto|in|into) "
    r"(?P<where>(?:the )?[A-Za-z]+(?: [A-Za-z]+)?)(?P<end>\s*[.!;])",
    _F,
)


def _first_over31(text: str, lexicon: Lexicon) -> str:
    """Session 31: 'X first, over to P.' is 'X to P first.', when X is one object of the scene
    (said as its name alone) and P one person or surface."""
    if "first" not in text.lower():
        return text

    def ordered(m: re.Match[str]) -> str:
        x, where = m["x"], m["where"]
        if not (_only(x, lexicon, "object") and _things31(x if " " in x else f"the {x}", lexicon)):
            return m[0]
        if not (_only_person(where, lexicon) or _surface_only(where, lexicon)):
            return m[0]
        return f"{x} {m['to']} {where} first{m['end']}"

    return _FIRST_OVER31.sub(ordered, text)


# who wants what was just asked, said after it by their trade ("Both items to Bob, the archer wants
# them."): the one person the request names, described
_TRADE_WANTS31 = re.compile(
    r",\s*(?:the|our|my|your) (?P<trade>[a-z]+(?: [a-z]+)?) (?:wants|needs|has asked for|asked "
    r"for|would like|is after) (?:it|them|those|that|both)(?P<end>\s*[.!]?)\s*$",
    _F,
)


def _trade_wants31(text: str, lexicon: Lexicon) -> str:
    """Session 31: the closing part above taken off when the request before it names one person
    and objects, and the trade words could only describe a person (_trade_words29)."""
    m = _TRADE_WANTS31.search(text)
    if m is None or not _trade_words29(m["trade"], lexicon):
        return text
    rest = text[: m.start()]
    if len(_ids(rest, lexicon, "human")) != 1 or not _ids(rest, lexicon, "object"):
        return text
    return rest + m["end"].strip()


# a trade said with 'a' / 'an' between commas after a person's name ("Person A, a dyer, wants …")
_A_TRADE31 = re.compile(
    r"(?P<p>\b[A-Za-z][a-z]*(?: [A-Za-z][a-z]*)?),\s+(?:a|an) (?P<trade>[a-z]+(?: [a-z]+)?),\s+",
    _F,
)


def trades31(text: str, lexicon: Lexicon) -> str:
    """Session 31: the trade above taken off, as trades29 takes off 'the <trade>' (and with it,
    before the instruction is first read: the rewrites read 'Person A wants a drink and will take
    …' only with the trade gone), when the name is one person of the scene and the trade words
    could only describe a person."""
    if ", a" not in text.lower():
        return text

    def named(m: re.Match[str]) -> str:
        if _only_person(m["p"], lexicon) and _trade_words29(m["trade"], lexicon):
            return f"{m['p']} "
        return m[0]

    return _A_TRADE31.sub(named, text)


# where or when a person works, said after their trade ("Person A is the forester on the night
# shift; …"): it describes the person, as the trade does
_TRADE_ON31 = re.compile(
    r"(?P<head>\b(?P<p>[A-Za-z][a-z]*(?: [A-Za-z][a-z]*)?) (?:is|'s) (?:the|our|a|an) "
    r"(?P<trade>[a-z]+)) (?P<pp>(?:on|from|at|in|of) (?:the|a|an|our) [a-z]+(?: [a-z]+){0,2})"
    r"(?=\s*[;,.])",
    _F,
)


def _trade_on31(text: str, lexicon: Lexicon) -> str:
    """Session 31: the description above taken off when P is one person of the scene, the trade
    could only describe a person and the description names nothing and holds no word that asks
    (_ASKS29) past its determiner."""
    if " is " not in text.lower() and "'s " not in text.lower():
        return text

    def said(m: re.Match[str]) -> str:
        pp = m["pp"].split(" ", 2)[-1]
        if (
            _only_person(m["p"], lexicon)
            and _trade_words29(m["trade"], lexicon)
            and _names_nothing(m["pp"], lexicon)
            and not _ASKS29.search(pp)  # past its determiner a noun: 'the night shift'
        ):
            return m["head"]
        return m[0]

    return _TRADE_ON31.sub(said, text)


# what a person's state is like, said with 'like a …' ("Mrs Khan is shivering like a diver out of
# the sea"): a comparison, asking nothing
_LIKE_A31 = re.compile(
    r"(?P<head>\b(?P<p>[A-Za-z][a-z]*(?: [A-Za-z][a-z]*)?) (?:is|'s) [a-z]+(?: (?:a|an|the|her|"
    r"his|their) [a-z]+)?) like (?P<what>(?:a|an|the) [a-z' ]+?)(?=\s*[;,.])",
    _F,
)


# one task said over two sentences: the person, then what they get ("Person B first. The bottle,
# that is.", "Then over to Person A. Chips for her.")
_PERSON_THEN_WHAT31 = re.compile(
    r"(?:^|(?<=[.!?]\s))(?P<p>[A-Za-z]+(?: [A-Za-z]+)?) (?P<when>first|next|last)\.\s+"
    r"(?P<x>(?:the |that |this )?[A-Za-z][a-z]*(?: [a-z]+)?),? that is(?P<end>\s*[.!])",
    _F,
)
_TO_THEN_WHAT31 = re.compile(
    r"(?:^|(?<=[.!?]\s))(?P<then>(?:and )?then,? |next,? )?(?P<dir>(?:over|across|up|down|round) )?"
    r"to (?P<p>[A-Za-z]+(?: [A-Za-z]+)?)\.\s+(?P<x>(?:the |that |this )?[A-Za-z][a-z]*(?: [a-z]+)?)"
    r" for (?P<pron>her|him|them)(?P<end>\s*[.!])",
    _F,
)


def _one_task_two_sentences31(text: str, lexicon: Lexicon) -> str:
    """Session 31: the two sentences above are one task, 'The bottle to Person B first.', 'Then
    chips to Person A.', when P is one person of the scene, X one object said by its name alone,
    and the pronoun one P may be (the second sentence names no one, so 'her' is the person the
    sentence before it names)."""
    if "." not in text:
        return text

    def first(m: re.Match[str]) -> str:
        x = m["x"] if " " in m["x"] else f"the {m['x']}"
        if not (_only_person(m["p"], lexicon) and _only(x, lexicon, "object")):
            return m[0]
        if not _things31(x, lexicon):
            return m[0]
        return f"{m['x']} to {m['p']} {m['when']}{m['end']}"

    def then(m: re.Match[str]) -> str:
        x = m["x"] if " " in m["x"] else f"the {m['x']}"
        if not (_the_person(m["p"], m["pron"], lexicon) and _only(x, lexicon, "object")):
            return m[0]
        if not _things31(x, lexicon):
            return m[0]
        return f"{m['then'] or ''}{m['x']} to {m['p']}{m['end']}"

    return _TO_THEN_WHAT31.sub(then, _PERSON_THEN_WHAT31.sub(first, text))


# who a person is, said between commas right after their name ("… give Alice, our bassoonist, the
# chips", "hand Bob, a regular here, the crisps", "Omar, the new intern, …"): it only describes
_APPOSITION31 = re.compile(
    r"(?P<p>\b(?:(?:person|mr|mrs|ms|miss|dr|nurse|chef) )?[A-Za-z]+),\s+(?P<det>our|my|your|a|an|"
    r"the) (?P<desc>[a-z]+(?: [a-z]+)??)(?: (?:here|round here|from next door))?,\s+(?=\S)",
    _F,
)


def _apposition31(text: str, lexicon: Lexicon) -> str:
    """Session 31: the description above taken off, the name kept (the text as said without it),
    when the name is one person of the scene and the description's words name nothing, hold no
    word of a scene name, no verb of the grammar and no word that asks (_ASKS29); after 'the' only
    words that could only describe a person (_trade_words29: 'Give Alice, the red, …' is left).
    Without it the comma kept after the name read 'give Alice, the chips' as two tasks, and gave
    Alice the object before them too (12c's frames fuzz, on main 7931fa8)."""
    if "," not in text:
        return text
    said = _scene_words29(lexicon)

    def named(m: re.Match[str]) -> str:
        desc = m["desc"]
        words = desc.lower().split()
        if not _only_person(m["p"], lexicon) or not _names_nothing(desc, lexicon):
            return m[0]
        if any(w in said or w in VERBS for w in words) or _ASKS29.search(desc):
            return m[0]
        if m["det"].lower() == "the" and not _trade_words29(desc, lexicon):
            return m[0]
        return f"{m['p']} "

    return _APPOSITION31.sub(named, text)


# -- session 32 (engineer 12): blind30's kinds (politeness, wants, pronouns and ellipsis, splits,
# lower case, typos, questions); docs/grounding.md, "Session 32 (engineer 12)" -----------------

_DET32 = r"(?:the|that|this|those|these)"
_PERSON32 = r"[A-Z][a-z]+(?: [A-Z][a-z]*)?"


def _people_before32(text: str, lexicon: Lexicon) -> set[str]:
    """The people named in the sentence of ``text`` that ends where ``text`` ends."""
    return _ids(re.split(r"[.!?]\s", text)[-1], lexicon, "human")


# The speaker's own words said as a comma part or sentence of their own (a closed list): what the
# speaker remembers ('before I forget'), that the hearer may choose when ('whenever suits you'),
# sending the hearer off ('Off you go.'), and asking whether it is much to ask ('could you manage
# that?', 'if you can manage it'). Each names nothing and changes nothing asked.
_PARTS32 = re.compile(
    r"(?:(?:oh,? )?and )?(?:before I forget|while I think of it|while I remember|"
    r"(?:now|come to) think of it)|"
    r"(?:just )?(?:whenever|when) (?:it )?suits(?: you)?|"
    r"(?:whenever|when) you get a (?:chance|moment|minute|sec|second)|in your own (?:good )?time|"
    r"(?:off|away|on) you go|"
    r"(?:could|can|would) you manage (?:that|it)|if you (?:can|could) manage (?:it|that)",
    _F,
)


# The speaker closing a request with what follows it, in a run-on without a comma: "… then it's
# tea break", and who told the speaker ("Sam wants the red pen he told me so this morning and …")
_BREAK32 = re.compile(
    r",?\s+(?:and )?then it's (?:tea|coffee|lunch|dinner|home|my|our)(?: break| time)?"
    r"(?P<end>\s*[.!]?)\s*$",
    _F,
)
_TOLD_SO32 = re.compile(
    r"\s+(?P<pron>he|she|they) (?:told|tells|has told|'s told) me so(?: this morning| earlier| "
    r"yesterday| last night| just now)?(?=\s+and\b|\s*[,.;!]|\s*$)",
    _F,
)


def _run_on_said32(text: str, lexicon: Lexicon) -> str:
    """Session 32: the closing break (above) taken off after a request; 'he told me so' taken off
    when the one person named before it in its sentence may be the pronoun."""
    m = _BREAK32.search(text)
    if m is not None and _names(text[: m.start()], lexicon):
        text = text[: m.start()] + m["end"].strip()

    def told(m: re.Match[str]) -> str:
        people = _people_before32(text[: m.start()], lexicon)
        if len(people) != 1 or not _fits(next(iter(people)), m["pron"], lexicon):
            return m[0]
        return ""

    return _TOLD_SO32.sub(told, text) if " so" in text else text


# ", the percussionist reckons": whose opinion the request is, by their trade, closing it
_RECKONS32 = re.compile(
    r",\s*(?:the|our|my) (?P<trade>[a-z]+) (?:reckons|thinks|reckoned|thought|tells me|told me)"
    r"(?P<end>\s*[.!]?)\s*$",
    _F,
)


def _trade_closing_dropped(rx: re.Pattern[str], text: str, lexicon: Lexicon) -> str:
    """``text`` without the closing part ``rx`` finds (its groups 'trade' and 'end'), when the
    trade could only describe a person and what is left names a person; else ``text``."""
    m = rx.search(text)
    if m is None or not _trade_words29(m["trade"], lexicon):
        return text
    rest = text[: m.start()]
    return rest + m["end"].strip() if _ids(rest, lexicon, "human") else text


def _reckons32(text: str, lexicon: Lexicon) -> str:
    """Session 32: the closing part above taken off when the trade could only describe a person
    (_trade_words29) and what is left names a person."""
    return _trade_closing_dropped(_RECKONS32, text, lexicon)


# a courtesy said with its language in the third person or with where it is said ("Meur ras, as
# my gran says in Cornish.", "Dhanyavad, as we say at home in Pune."): said as _as_we_say31 reads
_SAYS_IN32 = re.compile(
    r"\b(?P<who>as (?:my|our) [a-z]+|as (?:he|she)) says (?=(?:it )?(?:in|back in|over in|up in|"
    r"down in) [A-Z])"
)
_AT_HOME32 = re.compile(
    r"\b(?P<said>as (?:we|I|they|you|my [a-z]+|our [a-z]+) (?:would |'d |always |often )?say) "
    r"(?:at home|back home|where I'm from|where we're from) in (?=[A-Z])"
)


def _says_in32(text: str, _lexicon: Lexicon) -> str:
    """Session 32: 'as my gran says in' is 'as my gran would say in'; 'as we say at home in' is
    'as we say in' (_as_we_say31 then takes the courtesy off, or leaves it)."""
    if " say" not in text:
        return text
    text = _SAYS_IN32.sub(lambda m: f"{m['who']} would say ", text)
    return _AT_HOME32.sub(lambda m: f"{m['said']} in ", text)


# wants said by an idiom: a closed list (docs/grounding.md, "Session 32 (engineer 12)"), each
# said plainly as a want the grammar reads
_IDIOMS32: tuple[tuple[str, str], ...] = (
    # "Person B has her heart set on the bottle"
    (rf"(?:\s+has|'s) (?:got )?(?:her|his|their) hearts? set on\b(?= {_DET32}\b)", " wants"),
    # "Person B keeps asking for the bottle", "… has been asking for"
    (rf"\s+(?:keeps|kept) (?:on )?asking (?:for|after)\b(?= {_DET32}\b)", " wants"),
    (rf"(?:\s+has|'s) been asking (?:for|after)\b(?= {_DET32}\b)", " wants"),
    # "Person A has a fancy for the chips", "… has taken a fancy to"
    (rf"(?:\s+has|'s) (?:got |taken )?a (?:real )?fancy (?:for|to)\b(?= {_DET32}\b)", " wants"),
)  # fmt: skip


def _idioms32(text: str, _lexicon: Lexicon) -> str:
    """Session 32: the idioms above, said plainly — not where a pronoun after it may hand that
    person something else ("Carol keeps asking for the apple, give her the cup": the cup
    instead, or both? causes9 refuses it)."""
    for pattern, plain in _IDIOMS32:
        m = re.search(_rx(pattern), text)  # gated (session 53, 12p)
        if m is not None and not re.search(r"\b(?:her|him|them)\b", text[m.end() :], _F):
            text = text[: m.start()] + plain + text[m.end() :]
    return text


# "Person B is asking where the chips have got to": she wants them
_WHERE_GOT32 = re.compile(
    rf"(?:\s+is|'s) (?:asking|wondering) where (?P<x>{_DET32} [a-z][a-z ]*?) "
    r"(?:has|have|'s|'ve) (?:got|gone) to\b",
    _F,
)
# "Person A wants her bottle back from you": who has it now is the robot
_BACK_FROM32 = re.compile(
    r"\b(?P<want>wants?|needs?|would like|'d like) (?P<x>(?:her|his|their|the) [a-z][a-z ]*?) "
    r"back from (?:you|the robots?|the arms?)\b",
    _F,
)


def _asked_after32(text: str, lexicon: Lexicon) -> str:
    """Session 32: 'P is asking where X have got to' is 'P wants X'; 'wants her X back from you'
    is 'wants her X back' — X objects of the scene only."""
    if " where " in text.lower():
        text = _WHERE_GOT32.sub(
            lambda m: f" wants {m['x']}" if _things31(m["x"], lexicon) else m[0], text
        )
    if "back from" in text.lower():
        text = _BACK_FROM32.sub(
            lambda m: f"{m['want']} {m['x']} back" if _things31(m["x"], lexicon) else m[0], text
        )
    return text


# a want said as a cleft with what the person needs most: "… and what he needs most is the
# crisps", "The one thing Person A needs at the moment is that bottle."
_NEEDS_MOST32 = re.compile(
    rf"(?:^|(?<=[,;.!?]\s)|(?<=\band\s))(?:what|the (?:one|only|main) thing) "
    rf"(?P<p>{_PERSON32}|he|she|they) (?:most |really )?(?P<v>needs|need|wants|want) "
    r"(?:most(?: of all)?|more than anything)?\s*(?:(?:at the moment|right now|just now)\s*)?"
    rf"is (?P<x>{_DET32} [a-z][a-z ]*?)(?=\s*(?:[,.;!?]|$))",
    _F,
)


def _needs_most32(text: str, lexicon: Lexicon) -> str:
    """Session 32: the clefts above are 'P needs X', when P is one person of the scene (or a
    pronoun, left to the grammar) and X objects of the scene only."""
    if " is " not in text:
        return text

    def needs(m: re.Match[str]) -> str:
        p = m["p"]
        pronoun = p.lower() in ("he", "she", "they")
        if not _things31(m["x"], lexicon) or not (pronoun or _only_person(p, lexicon)):
            return m[0]
        return f"{p} {m['v']} {m['x']}"

    return _NEEDS_MOST32.sub(needs, text)


# the cleft of _cleft_wants31 said in the perfect: "… what Person A's been craving"
_BEEN_WANTING32 = re.compile(
    rf"(?<=\bwhat )(?P<p>{_PERSON32})(?:'s| has) been (?=(?:craving|wanting|hoping for|"
    r"longing for|after|waiting for)\b)",
    _F,
)


def _been_wanting32(text: str, lexicon: Lexicon) -> str:
    """Session 32: 'what P's been craving' is 'what P is craving' (P one person)."""
    if " been " not in text:
        return text
    return _BEEN_WANTING32.sub(
        lambda m: f"{m['p']} is " if _only_person(m["p"], lexicon) else m[0], text
    )


# "They each want something: the chips are what …, the bottle is what …": a header saying that
# what follows is each person's want
_EACH_WANTS32 = re.compile(
    r"^(?:they|the two of them|both of them|the pair of them|these two|those two) "
    r"(?:each |both )?(?:want|need|would like|are after|have asked for) (?:something|a thing|"
    r"one thing)(?: each)?\s*:\s*",
    _F,
)


def _each_wants32(text: str, lexicon: Lexicon) -> str:
    """Session 32: the header above taken off when what follows it names two people or more."""
    m = _EACH_WANTS32.match(text)
    if m is None or len(_ids(text[m.end() :], lexicon, "human")) < 2:
        return text
    return text[m.end() :]


# A deadline before something that happens to nobody and nothing of the scene ("… before he heads
# off on his round", "… before the caddies raid them", "… before the accordion lesson"): doing the
# task now meets it, so it asks nothing of the task (a 'before' that names a person or object of
# the scene orders tasks, and a time word, 'before lunch', is left, as earlier sessions leave
# times)
_BEFORE32 = re.compile(
    r",?\s+before (?P<what>(?:(?P<pron>he|she|they) |(?:the|our|my|some) [a-z]+s? )?"
    r"[a-z][a-z' ]*?)(?P<end>\s*[.!?]?)\s*$",
    _F,
)
_BACK_POINTERS32 = re.compile(r"\b(?:he|she|they|his|her|their|it|them)\b", _F)


# what happened that made the want, closing it: "Person A would love the bottle, the lumberjacks
# drank all the water" (people of no scene name used up what the request names)
_STORY32 = re.compile(
    r",\s*(?P<who>(?:the|our|my|some) [a-z]+) (?:drank|ate|finished|used|emptied|nicked|pinched|"
    r"polished off|ran out of) (?:all |up |off )?(?:of )?(?P<what>(?:the|our|my|their) [a-z]+)"
    r"(?P<end>\s*[.!]?)\s*$",
    _F,
)


# Possession said for a handover. "The drill is Jess's" alone is a statement (refused); it asks
# for the handover only where the instruction frames it as one: with 'to take / to have' ("The
# bottle's Bob's to take out on the trawler"), with 'too / as well' after a handover ("…; once she
# has it, the chips are hers as well"), before 'give them over' ("the chips are person b's, give
# them over"), in a list beside another task said as where a thing goes ("The drill is Jess's,
# the torch goes in the locker, …"), or as a telegram of two sentences, the things then whose
# ("The chips. Person B's.")
_TO_TAKE32 = re.compile(
    rf"(?P<x>\b{_DET32} [a-z][a-z ]*?)(?:'s| is| are) (?P<p>{_PERSON32})'s to (?:take|have|keep)"
    r"(?P<tail>(?: (?:out|home|away|along))?(?: (?:on|to|for|at|with) [a-z' ]+?)?)"
    r"(?=\s*(?:[,.;!?]|$))",
    _F,
)
_HERS_TOO32 = re.compile(
    rf"(?P<x>\b{_DET32} [a-z][a-z ]*?) (?P<be>is|are|'s|'re) (?P<pos>hers|his|theirs) "
    r"(?P<too>as well|too|also)\b",
    _F,
)
_OWNED_GIVE32 = re.compile(
    rf"^(?P<x>{_DET32} [a-z][a-z ]*?) (?:is|are|'s|'re) (?P<p>{_PERSON32})'s,\s*"
    r"(?P<v>give|hand|pass|bring|take) (?:it|them)(?: over| across| along)?"
    r"(?P<rest>(?:,? please)?\s*[.!]?)\s*$",
    _F,
)
_OWNED_PART32 = re.compile(
    rf"^(?P<x>{_DET32} [a-z][a-z ]*?) (?:is|are|'s|'re) (?P<p>{_PERSON32})'s$", _F
)
_GOES_PART32 = re.compile(
    rf"^(?:and )?(?:{_DET32} [a-z][a-z ]*? (?:goes|go) (?:to|in|into|on|onto|over to) "
    rf"(?:the )?[a-z][a-z ]*|{_PERSON32} (?:can have|gets|is having|'s having|will have|"
    rf"should have|takes) {_DET32} [a-z][a-z ]*)$",
    _F,
)
_TELEGRAM32 = re.compile(
    rf"(?:^|(?<=[.!?]\s))(?P<x>{_DET32} [a-z][a-z ]*?)\.\s+(?P<p>{_PERSON32})'s\.(?=\s|$)", _F
)
_POSSESSIVE32 = {"hers": "her", "his": "him", "theirs": "them"}


def _owned_listed32(text: str, lexicon: Lexicon) -> str:
    """Session 32: in one sentence of comma parts, 'X is P's' beside a part saying where another
    thing goes ('the torch goes in the locker') or who gets it ('Person A can have the chips')
    is 'X is for P'."""
    parts = re.split(r"(\s*[,;]\s*)", text.strip().rstrip("."))
    if len(parts) < 3 or re.search(r"[.!?]", text.strip()[:-1]):
        return text
    chunks = parts[0::2]
    if not any(_GOES_PART32.match(c) for c in chunks):
        return text
    out = []
    for c in chunks:
        m = _OWNED_PART32.match(c)
        if m and _things31(m["x"], lexicon) and _only_person(m["p"], lexicon):
            c = f"{m['x']} is for {m['p']}"
        out.append(c)
    if out == chunks:
        return text
    said = "".join(x for pair in zip(out, [*parts[1::2], ""], strict=True) for x in pair)
    return said + ("." if text.strip().endswith(".") else "")


# "Bottle next. Same person, Person A, the clarinettist.": the person of the task before,
# said again in a sentence of its own (the named person must be the one named before)
_SAME_PERSON32 = re.compile(
    r"(?P<before>(?:^|(?<=[.!?]\s))[^.!?]+?)\.\s+Same (?:person|one|recipient)"
    rf"(?:,\s*(?P<p>{_PERSON32}))?(?:,\s*(?:the|our|a) (?P<trade>[a-z]+(?: [a-z]+)?))?"
    r"\s*(?P<end>[.!]|$)",
    _F,
)


def _same_person32(text: str, lexicon: Lexicon) -> str:
    """Session 32: 'X next. Same person, P(, the <trade>).' is 'X next, same person.' when the
    sentence before names objects only, P is the one person named before it, and the trade
    could only describe a person."""
    if "same" not in text.lower():
        return text

    def same(m: re.Match[str]) -> str:
        before = m["before"]
        if not _objects_only(before, lexicon):
            return m[0]
        if m["trade"] and not _trade_words29(m["trade"], lexicon):
            return m[0]
        if m["p"]:
            earlier = _ids(text[: m.start()], lexicon, "human")
            if not _only_person(m["p"], lexicon) or earlier != _ids(m["p"], lexicon, "human"):
                return m[0]
        return f"{before}, same person{m['end']}"

    return _SAME_PERSON32.sub(same, text)


# "… when you clear up": the hearer's own tidying, when the task is done as part of it (no
# outside event is waited on)
_CLEAR_UP32 = re.compile(
    r",?\s+(?:when|while|as) you(?:'re| are)? (?:clear|tidy|clearing|tidying) (?:up|away)"
    r"(?P<end>\s*[.!]?)\s*$",
    _F,
)


def _clear_up32(text: str, lexicon: Lexicon) -> str:
    """Session 32: the closing part above taken off when what is left names something."""
    m = _CLEAR_UP32.search(text)
    if m is None or not _names(text[: m.start()], lexicon):
        return text
    return text[: m.start()] + m["end"].strip()


# "… , can you hand them over?": the request said as a question after a want
_HAND_OVER32 = re.compile(
    r",\s*(?:can|could|would|will) you (?P<v>hand|pass|give|bring) (?P<o>it|them) over\s*\?\s*$",
    _F,
)


def _hand_over32(text: str, _lexicon: Lexicon) -> str:
    """Session 32: ', can you hand them over?' is ', hand them over.' (the grammar reads it after
    a want, as it reads that)."""
    return _HAND_OVER32.sub(lambda m: f", {m['v']} {m['o']} over.", text)


# verbs of placing the grammar reads through earlier rewrites, not in VERBS ('drop it in the sink')
_PLACING32 = frozenset({"drop", "pop", "stick", "set", "stand", "sit"})
# "The sponge is dripping, pop it in the sink": the state of the object said first, then the
# request for 'it'
_STATE_IT32 = re.compile(
    rf"^(?P<x>{_DET32} [a-z][a-z ]*?) (?:is|'s) (?:all |a bit |really |very |still |soaking )?"
    r"(?P<state>[a-z]+)\s*,\s*(?:so\s+)?(?P<v>[a-z]+) it\b",
    _F,
)


# "Put the magazine on the locker for Mr Lee to read after his nap": who it is put there for,
# and what they will do with it, after a placement
_FOR_TO_DO32 = re.compile(
    r"(?P<place>\b(?:on|in|onto|into) (?:the )?[a-z]+(?: [a-z]+)?) for "
    rf"(?P<p>{_PERSON32}) to (?P<v>[a-z]+)(?P<tail>(?: (?:after|before) (?:his|her|their) "
    r"[a-z]+)?)(?=\s*(?:[,.;!?]|$))",
    _F,
)


# questions that ask for a task another way: "Any chance the blue mug could find its way over to
# Alice?" (as 'make its way', _make_way31), "Don't suppose you could pass …?", "Be good if Person
# A could get the bottle off you", "Shall we say the chips go to Person A and …?"
_FIND_WAY32 = re.compile(r"\bfind (?P<pos>its|their) way\b", _F)
_SUPPOSE32 = re.compile(
    r"(?:^|(?<=[.!?]\s))(?:I )?(?:don't|do not) suppose (?:you could|you'd|you would)\b", _F
)
_BE_GOOD32 = re.compile(
    r"^(?:(?:it|that)(?:'d| would) |would )?be (?:good|great|nice|lovely|handy|grand|brilliant|"
    rf"ace) if (?P<p>{_PERSON32}) (?:could|can|would) (?P<v>get|have|take) "
    r"(?P<rest>[^,?!.]+?)\s*(?P<end>[?.!]?)\s*$",
    _F,
)
_SHALL_WE_SAY32 = re.compile(r"^(?:shall|should) we say,? (?:that )?(?P<rest>[^?]+)\?\s*$", _F)


def _asked_as32(text: str, lexicon: Lexicon) -> str:
    """Session 32: the questions above said as the grammar reads them: 'make its way';
    'Could you'; 'Could P get X?' (P one person of the scene); the proposal after 'shall we say'
    as said (no word of a question left in it)."""
    text = _FIND_WAY32.sub(lambda m: f"make {m['pos']} way", text)
    text = _SUPPOSE32.sub("Could you", text)
    m = _BE_GOOD32.match(text)
    if m is not None and _only_person(m["p"], lexicon):
        text = f"Could {m['p']} {m['v']} {m['rest']}?"
    m = _SHALL_WE_SAY32.match(text)
    if m is not None and not re.search(
        r"\b(?:who|what|which|whether|where|how|or|not|either)\b|n't", m["rest"], _F
    ):
        text = f"{m['rest']}."
    return text


# "add the small box to the pallet": a placement, where the place is a surface
_ADD_TO32 = re.compile(
    rf"\badd (?P<x>{_DET32} [a-z][a-z ]*?) to (?P<s>(?:the )?[a-z]+(?: [a-z]+)?)"
    r"(?=\s*(?:[,.;!?]|$))",
    _F,
)


def _add_to32(text: str, lexicon: Lexicon) -> str:
    """Session 32: 'add X to S' is 'put X on S' when X is objects of the scene only and S one
    surface ('add the apple to Bob's plate', a person, is left)."""
    if "add " not in text.lower():
        return text

    def put(m: re.Match[str]) -> str:
        if not (_things31(m["x"], lexicon) and _surface_only(m["s"], lexicon)):
            return m[0]
        return f"put {m['x']} on {m['s']}"

    return _ADD_TO32.sub(put, text)


# "… on the rack next to the blue one": where on the surface, beside an object standing on it
_NEXT_TO32 = re.compile(
    r"(?P<on>\b(?:on|onto) (?P<s>(?:the )?[a-z]+(?: [a-z]+)?)) (?:next to|beside|alongside) "
    r"(?P<y>the [a-z]+(?: [a-z]+)?)(?=\s*(?:[,.;!?]|$))",
    _F,
)


def _beside_object32(words: str, before: str, lexicon: Lexicon) -> str | None:
    """The one object ``words`` names ('the blue plate', or 'the blue one' after a placed
    object of that kind), else None."""
    ids = _ids(words, lexicon)
    if ids:
        return next(iter(ids)) if len(ids) == 1 and _objects_only(words, lexicon) else None
    m = re.fullmatch(r"the ([a-z]+) one", words.strip(), _F)
    placed = _ids(before, lexicon, "object")
    if m is None or len(placed) != 1:
        return None
    kind = next(o.category for o in lexicon.scene.objects if o.id in placed)
    said = f"{m[1].lower()} {kind}"
    found = [
        o.id
        for o in lexicon.scene.objects
        if o.category == kind and o.id not in placed and said in (a.lower() for a in o.aliases)
    ]
    return found[0] if len(found) == 1 else None


def _beside_on32(text: str, lexicon: Lexicon) -> str:
    """Session 32: 'on S next to Y' is 'on S' when S is one surface of the scene and Y one
    object standing on it (by the scene's positions; 'the blue one' is the one object of the
    placed object's kind with that word in its name): the grammar places on a surface, not on a
    spot of it, and next to Y is on it."""
    if "next to" not in text and "beside" not in text and "alongside" not in text:
        return text

    def on(m: re.Match[str]) -> str:
        surface = next((f for f in lexicon.scene.surfaces if _ids(m["s"], lexicon) == {f.id}), None)
        if surface is None or not _surface_only(m["s"], lexicon):
            return m[0]
        oid = _beside_object32(m["y"], text[: m.start()], lexicon)
        obj = next((o for o in lexicon.scene.objects if o.id == oid), None)
        if obj is None:
            return m[0]
        dx = abs(obj.position[0] - surface.center[0])
        dy = abs(obj.position[1] - surface.center[1])
        if dx > surface.size[0] / 2 or dy > surface.size[1] / 2:
            return m[0]
        return m["on"]

    return _NEXT_TO32.sub(on, text)


# what the wanted object is for, said as 'to <verb> <his / her …> <noun>' after it ("Omar needs
# the spoon to stir his samples", "Zoe wants the scissors to cut out her rock diagrams"): a
# purpose (as _to_do31's 'to <verb>'), never where it goes
_TO_DO_WITH32 = re.compile(
    r"(?P<before>\b(?:would (?:love|like)|'d (?:love|like)|wants?|needs?|could use|could do with|"
    r"has asked for|asked for) [^,.;!?]*?)\s+to (?P<verb>[a-z]+)(?: (?:out|up|off|through))? "
    r"(?P<what>(?:his|her|their|some|a|an) [a-z]+(?: [a-z]+){0,2})(?=\s*(?:[,.;!?]|$))",
    _F,
)


# a reason said as the state of a place or a thing of no scene name, closing a request: "…, the
# ward's too warm"
_TOO_WARM32 = re.compile(
    r",\s*(?:(?:the|it's|it is) )?(?P<what>[a-z]+)(?:'s| is| are|'re) (?:too|so|really|very|ever "
    r"so|a bit|far too|way too) (?P<state>[a-z]+)(?P<end>\s*[.!]?)\s*$",
    _F,
)


# a past time after a want said in the perfect ("Bob has been eyeing the crisps since lunch"):
# how long the want has lasted, never when the task is to be done
_SINCE32 = re.compile(
    r"(?P<before>\b(?:has|have|'s|'ve) been [a-z]+ing [^,.;!?]*?) since (?:lunch|breakfast|"
    r"dinner|tea|this morning|dawn|yesterday|last night|earlier|first thing|the morning)\b",
    _F,
)


def _since32(text: str, lexicon: Lexicon) -> str:
    """Session 32: the time above taken off when what comes before it ends with an object of the
    scene."""
    if "since" not in text:
        return text
    return _SINCE32.sub(lambda m: m["before"] if _ends_object(m["before"], lexicon) else m[0], text)


# where a person is back from ("Aluce is back from the dive, hand her the bottle"): a remark
_BACK_FROM_PLACE32 = re.compile(
    rf"^(?P<p>{_PERSON32}) (?:is|'s) (?:just )?back from (?:the|his|her|their) [a-z]+"
    r"(?= *[,;.])",
    _F,
)


# who left an object where, then the request for 'it' ("Somebody left the sponge on the side;
# drop it in the sink", "The forester left the bottle out; put it on the shelf")
_LEFT_IT32 = re.compile(
    rf"^(?P<who>somebody|someone|(?:the|our|my) [a-z]+) left (?P<x>{_DET32} [a-z][a-z ]*?) "
    r"(?P<where>out|about|lying around|on the side|over there|here|there)\s*[;,]\s*(?:so\s+)?"
    r"(?P<v>[a-z]+) it\b",
    _F,
)


def _left_it32(text: str, lexicon: Lexicon) -> str:
    """Session 32: 'Somebody left X out; <verb> it …' is '<verb> X …', when who left it names
    nothing (nobody, or a trade), X is one object of the scene and the verb one of the
    grammar's."""
    m = _LEFT_IT32.match(text)
    if m is None or m["v"].lower() not in (*VERBS, *_PLACING32):
        return text
    who = m["who"].lower()
    if who not in ("somebody", "someone") and not _trade_words29(who.split(" ", 1)[1], lexicon):
        return text
    if not _things31(m["x"], lexicon) or len(_ids(m["x"], lexicon)) != 1:
        return text
    return f"{m['v']} {m['x']}{text[m.end() :]}"


# "P is the acupuncturist and she'd like her bottle": who the person is, then what they want
_IS_THE_AND32 = re.compile(
    rf"^(?P<p>{_PERSON32}) is the (?P<trade>[a-z]+) and (?P<pron>she|he|they)"
    r"(?P<want>'d like|'d love| would like| wants| needs| is after)\b",
    _F,
)


def _is_the_and32(text: str, lexicon: Lexicon) -> str:
    """Session 32: 'P is the <trade> and she'd like' is 'P would like', when P is one person of
    the scene, the trade could only describe a person, and the pronoun may be P."""
    m = _IS_THE_AND32.match(text)
    if m is None or not _the_person(m["p"], m["pron"], lexicon):
        return text
    if not _trade_words29(m["trade"], lexicon):
        return text
    want = m["want"].strip()
    want = {"'d like": "would like", "'d love": "would love"}.get(want, want)
    return f"{m['p']} {want}{text[m.end() :]}"


# where a person is, after their name at the end of a request ("… down to Person A at the far
# end?"): said of no scene name, it only says where to find them
_AT_THE_END32 = re.compile(
    rf"(?<=\bto )(?P<p>{_PERSON32}) (?:at|by|near) the (?P<far>far |other |back |front )?"
    r"(?P<place>[a-z]+)"
    r"(?P<end>\s*[.!?]?)\s*$",
    _F,
)
# "Could you run the chips down to …", "Can you manage the chips to …": verbs of carrying
_RUN_DOWN32 = re.compile(
    rf"\b(?:run|nip|pop|whizz|zip) (?P<x>{_DET32} [a-z][a-z ]*?) (?:down|over|up|across|along) "
    r"to\b",
    _F,
)
_MANAGE32 = re.compile(r"^(?P<ask>can|could) you manage (?=[a-z])", _F)


# "person b needs the apple and the cup over his way": to the person who wants them
_HIS_WAY32 = re.compile(
    r"(?P<before>\b(?:wants?|needs?|would like|'d like) [^,.;!?]*?) over (?P<pos>his|her|their) "
    r"way\b",
    _F,
)


def _his_way32(text: str, lexicon: Lexicon) -> str:
    """Session 32: 'over his way' (above) taken off after the wanted objects, when one person is
    named before it whom the pronoun may be."""
    if " way" not in text:
        return text

    def dropped(m: re.Match[str]) -> str:
        people = _people_before32(text[: m.start()] + m["before"], lexicon)
        if not _ends_object(m["before"], lexicon) or len(people) != 1:
            return m[0]
        return m["before"] if _fits(next(iter(people)), m["pos"], lexicon) else m[0]

    return _HIS_WAY32.sub(dropped, text)


# -- session 33 (engineer 12): blind31's kinds (politeness, wants, pronouns and ellipsis, splits,
# lower case, typos, questions); docs/grounding.md, "Session 33 (engineer 12)" -----------------

# The speaker's own words said as a comma part or sentence of their own (a closed list): what the
# request is not ('nothing fancy today'), giving in ('go on then'), that it is all there is
# ('Simple as that'), thanks ahead ('Cheers in advance'), what the
# speaker has just remembered ('oh yes'), and that neither task is pressing ('no rush on either of
# them'). Each names nothing and changes nothing asked.
_PARTS33 = re.compile(
    r"(?:hello there|hello|hi),? nothing (?:fancy|special)(?: today| this time)?|"
    r"(?:just )?(?:a )?quick one(?: before (?:the|my|our|his|her) [a-z]+(?: [a-z]+)?)?|"
    r"nothing (?:fancy|special)(?: today| this time)?|"
    r"(?:ah|oh|well),? go on(?:,)? then|go on(?:,)? then|"
    r"(?:it's |that's |it is |that is )?(?:as )?(?:simple|easy) as that|"
    r"(?:cheers|ta|thank you|thanks|many thanks) in advance|"
    r"(?:and,? )?(?:oh|ah),? yes|"
    r"(?:there's )?no (?:rush|hurry)(?: at all)? (?:on|with|for) (?:either|any|both|each|all|"
    r"none)(?: one)?(?: of them| of the two| of those)?|"
    r"(?:there's )?no (?:rush|hurry)(?: at all)? (?:on|with|for) (?:them|it)",
    _F,
)


# "The bottle, Person A, there you go, all yours.": handing it over, said to the person just
# addressed
_ALL_YOURS33 = re.compile(
    r",\s*(?P<p>[A-Z][A-Za-z ]*?),\s*(?:(?:there|here) you (?:go|are),\s*)?(?:it's |that's )?"
    r"all yours(?P<end>\s*[.!]?)\s*$"
)


def _all_yours33(text: str, lexicon: Lexicon) -> str:
    """Session 33: 'all yours' (and 'there you go' before it) taken off when the comma part
    before it is one person of the scene alone, the one addressed ("The cup to Bob, the apple,
    all yours": whose? left)."""
    if "all yours" not in text:
        return text
    m = _ALL_YOURS33.search(text)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    return f"{text[: m.start()]}, {m['p']}{m['end'].strip()}"


# wants said by an idiom: a closed list (docs/grounding.md, "Session 33 (engineer 12)"), each
# said plainly as a want the grammar reads, before a determiner
_IDIOMS33: tuple[tuple[str, str], ...] = (
    # "Person B could murder the chips" (would dearly like to eat or drink)
    (rf"\s+could (?:really |happily |easily |just |so )?murder\b(?= {_DET32}\b)", " wants"),
    # "Person A's asking after the chips", "… is asking after" (of a thing, not a person)
    (rf"(?:\s+is|'s|\s+was) asking after\b(?= {_DET32}\b)", " wants"),
)  # fmt: skip


def _idioms33(text: str, lexicon: Lexicon) -> str:
    """Session 33: the idioms above, said plainly, when what follows them up to a mark is objects
    of the scene only ('asking after Mr Lee' asks how he is), and not where a pronoun after it
    may hand that person something else (as _idioms32)."""
    for pattern, plain in _IDIOMS33:
        m = re.search(_rx(pattern), text)  # gated (session 53, 12p)
        if m is None:
            continue
        what = re.split(r"[,.;!?]|\s+(?:and|but|so|while)\s+", text[m.end() :], maxsplit=1)[0]
        if not _things31(what, lexicon) or re.search(r"\b(?:her|him|them)\b", text[m.end() :], _F):
            continue
        text = text[: m.start()] + plain + text[m.end() :]
    return text


# "the bottle would help person a a lot": what would help a person is what they need
_WOULD_HELP33 = re.compile(
    r"^(?P<x>(?:the|that|this|those|these) [^,.;!?]+?) would (?:really |so |certainly )?help "
    r"(?P<p>[^,.;!?]+?)(?: (?:a lot|loads|no end|a great deal|enormously|massively|out))?"
    r"(?=\s*(?:[,.;!?]|$))",
    _F,
)


def _would_help33(text: str, lexicon: Lexicon) -> str:
    """Session 33: 'X would help P (a lot)' opening the instruction is 'P needs X', when X is
    objects of the scene only and P one person."""
    if " help " not in text:
        return text
    m = _WOULD_HELP33.match(text)
    if m is None or not _things31(m["x"], lexicon) or not _only_person(m["p"], lexicon):
        return text
    return f"{m['p']} needs {m['x']}{text[m.end() :]}"


# "Person A needs the bottle more than anyone": how much, not who else
_MORE_THAN33 = re.compile(
    r"(?P<want>\b(?:needs?|wants?|deserves?) (?:the|that|this|those|these) [^,.;!?]+?) "
    r"more than (?:anyone|anybody|any of (?:them|us))(?: else)?(?=\s*(?:[,.;!?]|$))",
    _F,
)


def _more_than33(text: str, lexicon: Lexicon) -> str:
    """Session 33: 'more than anyone (else)' taken off after a want or need of objects only."""
    if " more than " not in text:
        return text

    def dropped(m: re.Match[str]) -> str:
        what = m["want"].split(" ", 1)[1]
        return m["want"] if _things31(what, lexicon) else m[0]

    return _MORE_THAN33.sub(dropped, text)


# ", according to the roadie": whose word the request is, by their trade, closing it
_ACCORDING33 = re.compile(
    r",\s*(?:apparently,?\s*)?according to (?:the|our|my) (?P<trade>[a-z]+)(?P<end>\s*[.!]?)\s*$",
    _F,
)


def _according33(text: str, lexicon: Lexicon) -> str:
    """Session 33: the closing part above taken off when the trade could only describe a person
    (_trade_words29) and what is left names a person (as _reckons32)."""
    if "according" not in text:
        return text
    return _trade_closing_dropped(_ACCORDING33, text, lexicon)


# "for her geography lesson this afternoon": the time is when the lesson is, and doing the task
# now meets it (the time said of an event of a closed list, after 'for' and a possessive)
_EVENT_TIME33 = re.compile(
    r"(?P<event>\bfor (?:her|his|their|the|our|my) (?:[a-z]+ ){0,2}?(?:lesson|class|lecture|"
    r"meeting|appointment|shift|talk|game|match|practice|rehearsal|exam|test|session|gig|show|"
    r"concert|break|round|visit|presentation|seminar|tutorial|training))"
    r" (?:this (?:morning|afternoon|evening)|tonight|later(?: on| today)?|today)"
    r"(?=\s*(?:[,.;!?]|$))",
    _F,
)


def _event_time33(text: str, lexicon: Lexicon) -> str:
    """Session 33: the time above taken off after the event it dates, when the words of 'for …'
    name nothing of the scene."""
    if "for " not in text.lower():
        return text
    return _EVENT_TIME33.sub(
        lambda m: m["event"] if _names_nothing(m["event"], lexicon) else m[0], text
    )


# A closing remark of what made the request (a closed list of kinds, each naming nothing):
# something has broken ("the radiator by her bed's packed in"), a child has made a mess ("the
# little one's got jam absolutely everywhere"), someone of a trade has told the person named to
# cut down ("the osteopath's told him to cut down"), or is coming to use a surface ("the
# optometrist is coming to use the desk")
_BROKEN33 = re.compile(
    r",\s*(?P<said>(?:the|her|his|their|our|my) [a-z][a-z ]*?(?:'s| is| has)"
    r" (?:packed (?:in|up)|broken(?: down)?|conked out|given up|stopped working|on the blink|"
    r"playing up|gone (?:off|cold|wrong)|bust|busted|leaking))(?P<end>\s*[.!]?)\s*$",
    _F,
)
_MESS33 = re.compile(
    r",\s*(?P<said>the (?:little|wee|young) (?:one|ones|'uns?)(?:'s| has| have|'ve) "
    r"(?:got |gotten )?[a-z][a-z ]*?(?:everywhere|all over (?:the place|himself|herself|"
    r"themselves|it)))"
    r"(?P<end>\s*[.!]?)\s*$",
    _F,
)
_TOLD_TO33 = re.compile(
    r",\s*(?P<said>(?:the|her|his|their|our|my) (?P<trade>[a-z]+)(?:'s| has) (?:told|asked|advised)"
    r" (?P<pron>him|her|them) to (?:cut down|cut back|go easy|lay off(?: it)?|take it easy|rest|"
    r"slow down|eat more|drink more|keep warm|keep it up))(?P<end>\s*[.!]?)\s*$",
    _F,
)
_COMING_TO_USE33 = re.compile(
    r",\s*(?P<said>(?:the|our|my) (?P<trade>[a-z]+) (?:is|'s) coming(?: in| over| round| by)? "
    r"(?:to use|for) (?P<s>the [a-z]+(?: [a-z]+)?))(?P<end>\s*[.!]?)\s*$",
    _F,
)


def _closing_cause33(text: str, lexicon: Lexicon) -> str:
    """Session 33: a closing remark above taken off when the request before it names something;
    a broken thing or a mess names nothing and asks nothing but the pronouns ('her bed');
    the trade could only describe a person (_trade_words29), 'him'/'her' may be the one person
    named before it; the surface someone comes to use is one the request puts nothing on."""
    if "," not in text:
        return text
    for rx in (_BROKEN33, _MESS33):
        m = rx.search(text)
        if m is not None and _names_nothing(m["said"], lexicon):
            words = re.sub(
                r"\b(?:her|his|their|our|my|little|wee|young|one|ones|all over)\b", "", m["said"]
            )
            if not _ASKS29.search(words) and _names(text[: m.start()], lexicon):
                return text[: m.start()] + m["end"].strip()
    m = _TOLD_TO33.search(text)
    if m is not None and _trade_words29(m["trade"], lexicon):
        people = _people_before32(text[: m.start()], lexicon)
        if len(people) == 1 and _fits(next(iter(people)), m["pron"], lexicon):
            return text[: m.start()] + m["end"].strip()
    m = _COMING_TO_USE33.search(text)
    if m is not None and _trade_words29(m["trade"], lexicon) and _surface_only(m["s"], lexicon):
        before = text[: m.start()]
        if not _ids(m["s"], lexicon) & _ids(before, lexicon, "surface") and _names(before, lexicon):
            return before + m["end"].strip()
    return text


# "Person A has earned the cyips after hauling the nets in": in the perfect, what the person did
# to earn it is done
_EARNED_AFTER33 = re.compile(
    r"(?P<v>(?:\s+has|'s) (?:earned|deserved)) (?P<x>(?:the|that|this|those|these) [^,.;!?]+?) "
    r"(?P<after>after (?:all )?(?:that |those |the |her |his |their )?[a-z]+ing\b[^,.;!?]*)"
    r"(?=\s*(?:[,.;!?]|$))",
    _F,
)


def _earned_after33(text: str, lexicon: Lexicon) -> str:
    """Session 33: 'after …ing …' taken off after 'has earned X', when X is objects only and
    the after-part names nothing and asks nothing."""
    if " after " not in text:
        return text

    def dropped(m: re.Match[str]) -> str:
        words = m["after"].split(" ", 1)[1]
        if not _things31(m["x"], lexicon) or not _names_nothing(words, lexicon):
            return m[0]
        return f"{m['v']} {m['x']}" if not re.search(r"\b(?:it|them)\b", words, _F) else m[0]

    return _EARNED_AFTER33.sub(dropped, text)


# "Person A first, that's the bottle; next up Person B, that's the chips": each person, then
# 'that's' what they get, in order (the first said with 'first', the next with 'next (up)' or
# 'then')
_WHO_THATS33 = re.compile(
    r"(?:^|(?<=[;.]\s))(?P<order>(?:[Nn]ext(?: up)?|[Tt]hen|[Aa]fter that|[Aa]nd then),?\s+)?"
    r"(?P<p>[A-Z][^,;.!?]*?)(?P<first> first)?,\s*that's "
    r"(?P<x>(?:the|that|this|those|these) [^,;.!?]+?)"
    r"(?=\s*(?:[,;.!?]|$))",
)


def _who_thats33(text: str, lexicon: Lexicon) -> str:
    """Session 33: each part above is 'X to P' ('the X to P first', 'next the X to P'), when
    there are two or more, the first said with 'first' and every other with its order word, each
    P one person and each X objects only."""
    if "that's" not in text:
        return text
    found = list(_WHO_THATS33.finditer(text))
    if len(found) < 2 or found[0]["first"] is None or found[0]["order"] is not None:
        return text
    if any(m["order"] is None or m["first"] is not None for m in found[1:]):
        return text
    if not all(_only_person(m["p"], lexicon) and _things31(m["x"], lexicon) for m in found):
        return text
    out, at = [], 0
    for m in found:
        order = "next " if m["order"] else ""
        said = f"{order}{m['x']} to {m['p']}{' first' if m['first'] else ''}"
        out += [text[at : m.start()], said[:1].upper() + said[1:] if m.start() == 0 else said]
        at = m.end()
    return "".join([*out, text[at:]])


# "There's a bottle over there, yeah? Person A wants it.": the thing pointed out, then who wants
# 'it'
_THERE_IT33 = re.compile(
    r"^there(?:'s| is) (?:a|an|the|that) (?P<x>[a-z][a-z ]*?)(?: (?:over )?(?:there|here))?"
    r"(?:,? (?:yeah|right|see|look))?\s*[?.,!]\s*(?P<p>[A-Z][^,.;!?]*?) (?P<v>wants|needs|"
    r"would like|'d like) it(?P<end>\s*[.!]?)\s*$",
    _F,
)


def _there_it33(text: str, lexicon: Lexicon) -> str:
    """Session 33: the text above is 'P wants the X', when X is one kind of object of the scene
    and P one person (the grammar then reads 'the X', or says which ones it could be)."""
    if not text.lower().startswith("there"):
        return text
    m = _THERE_IT33.match(text)
    if m is None or not _things31(f"the {m['x']}", lexicon) or not _only_person(m["p"], lexicon):
        return text
    return f"{m['p']} {m['v']} the {m['x']}{m['end'].strip()}"


# "That's Kofi's drill, take it over to him": whose it is, then the handover of 'it' to that
# person
_WHOSE_TAKE33 = re.compile(
    r"^that(?:'s| is) (?P<p>[A-Z][a-zA-Z ]*?)'s (?P<x>[a-z][a-z ]*?),\s*(?P<v>take|bring|give|"
    r"hand|pass|run) it (?P<over>(?:over |back |across )?)to (?P<pron>him|her|them)\b",
    _F,
)


def _whose_take33(text: str, lexicon: Lexicon) -> str:
    """Session 33: the opening above is '<verb> the X <over> to P', when P is one person whom the
    pronoun may be and 'the X' objects of the scene only."""
    if not text.lower().startswith("that"):
        return text
    m = _WHOSE_TAKE33.match(text)
    if m is None or not _things31(f"the {m['x']}", lexicon):
        return text
    if not _the_person(m["p"], m["pron"], lexicon):
        return text
    return f"{m['v'].capitalize()} the {m['x']} {m['over']}to {m['p']}{text[m.end() :]}"


# "Bob wants his crisps on the shelf": the person's own things, and where he wants them
_OWN_ON33 = re.compile(
    r"(?P<p>\b[A-Z][^,.;!?]*?) (?P<v>wants|would like|'d like|needs) (?P<pos>his|her|their) "
    r"(?P<x>[a-z][a-z ]*?) (?P<on>on|onto|in|into|on to) (?P<s>the [a-z]+(?: [a-z]+)?)\b",
)


def _own_on33(text: str, lexicon: Lexicon) -> str:
    """Session 33: 'P wants his X on the S' is 'P wants the X on the S', when P is one person the
    pronoun may be, 'the X' objects only and 'the S' a surface."""
    if " on" not in text and " in" not in text:
        return text
    m = _OWN_ON33.search(text)
    if m is None or not _things31(f"the {m['x']}", lexicon) or not _surface_only(m["s"], lexicon):
        return text
    if not _the_person(m["p"], m["pos"], lexicon):
        return text
    said = f"{m['p']} {m['v']} the {m['x']} {m['on']} {m['s']}"
    return text[: m.start()] + said + text[m.end() :]


def _name_typo33(text: str, lexicon: Lexicon) -> str:
    """Session 33: a slip in the second word of an object's name of two words ("Baby wpies" for
    'baby wipes'), when the slip names that object alone (``Lexicon.misspelt``): the name as
    said, not its first word as a name of its own ('baby': Lily in the nursery)."""
    for o in lexicon.scene.objects:
        for alias in o.aliases:
            words = alias.lower().split()
            if len(words) != 2:
                continue
            for m in _rx(rf"\b{re.escape(words[0])} (?P<w>[a-z]{{4,}})\b").finditer(text):
                typed = m["w"].lower()
                refs = lexicon.misspelt(typed) if typed != words[1] else None
                if refs and {r.id for r in refs} == {o.id}:
                    return text[: m.start("w")] + words[1] + text[m.end("w") :]
    return text


# "Do you think Person A could have the cup …?": the question asks what 'Could Person A have
# the cup …?' asks
_THINK_COULD33 = re.compile(
    r"(?:^|(?<=[.!?]\s))(?:(?:do|don't) you|d'you|d'ya) (?:think|reckon|suppose) (?:that )?"
    r"(?P<p>[A-Z][^,.;!?]*?) (?P<m>could|can|might) (?=(?:have|get|take|use)\b)",
    _F,
)
# "Is it okay if the globe goes up on the bookshelf …?": 'Could the globe go up on …?'
_OKAY_IF33 = re.compile(
    r"^is it (?:okay|ok|alright|all right|fine) if (?P<x>(?:the|that|this|those|these) "
    r"[^,.;!?]+?) (?P<v>goes|go|went)\b",
    _F,
)


def _asked_as33(text: str, lexicon: Lexicon) -> str:
    """Session 33: the questions above said as 'Could …?', when P is one person and X objects of
    the scene only, and the text is a question."""
    if not text.rstrip().endswith("?"):
        return text
    m = _THINK_COULD33.search(text)
    if m is not None and _only_person(m["p"], lexicon):
        text = text[: m.start()] + f"Could {m['p']} " + text[m.end() :]
    m = _OKAY_IF33.match(text)
    if m is not None and _things31(m["x"], lexicon):
        text = f"Could {m['x']} go{text[m.end() :]}"
    return text


# "… on the counter by the kettle": where on the surface, by a thing the scene does not have
_BY_LANDMARK33 = re.compile(
    r"(?P<on>\b(?:on|onto|on to) (?:the|that) [a-z]+(?: [a-z]+)?) (?:by|next to|beside|near) "
    r"(?P<by>the [a-z]+)(?=\s*(?:[,.;!?]|$))",
    _F,
)


# nouns that say a time ('by the weekend' is a deadline, not a spot)
_WHEN33 = frozenset(
    {
        *("weekend", "end", "noon", "midday", "midnight", "close", "deadline", "time", "night"),
        *("day", "evening", "morning", "afternoon", "break", "shift", "bell", "whistle"),
    }
)


# the clause of the placement opens with its verb (a participle after a want list, "Ruth wants
# the thermometer and the tablets put on the cart by the bed", is left: session 10 refuses it)
_PLACING33 = re.compile(
    r"^(?:(?:please|kindly|would you mind|could you|can you|would you|will you)\s+)*(?:put|place|"
    r"set|pop|stand|lay|leave|move|putting|placing|setting|popping|standing|laying|leaving|"
    r"moving)\b",
    _F,
)


def _by_landmark33(text: str, lexicon: Lexicon) -> str:
    """Session 33: 'by the X' taken off after 'on the S', when S is a surface of the scene, X
    names nothing (no word of a scene name, nothing that asks) and the clause opens with a verb
    of placing: a spot on that surface the scene cannot tell."""
    if not re.search(r" (?:by|next to|beside|near) ", text):
        return text

    def dropped(m: re.Match[str]) -> str:
        said = _scene_words29(lexicon)
        by = m["by"].split()[-1].lower()
        clause = re.split(r"[,.;:!?]\s*", text[: m.start()])[-1]
        if not _PLACING33.match(clause) or by in _WHEN33 or by in said:
            return m[0]
        if not _surface_only(m["on"].split(" ", 1)[1], lexicon):
            return m[0]
        return m["on"] if _names_nothing(m["by"], lexicon) and not _ASKS29.search(by) else m[0]

    return _BY_LANDMARK33.sub(dropped, text)


# "It's Person B who ordered the cup": the person put first in a cleft, with a verb of wanting
_CLEFT_WHO33 = re.compile(
    r"(?:^|(?<=[.;!?])\s+)it(?:'s| is| was) (?P<who>[A-Za-z]+(?: [A-Za-z]+)?) who "
    r"(?P<verb>ordered|asked for|requested|wanted|wants|needs|needed)"
    rf"(?= {_DET32}\b)",
    _F,
)


def _cleft_who33(text: str, lexicon: Lexicon) -> str:
    """Session 33: the cleft above said plainly ('Person B ordered the cup'), when P is one
    person and what follows up to a mark is objects of the scene only."""
    if " who " not in text:
        return text

    def plain(m: re.Match[str]) -> str:
        what = re.split(r"[,.;!?]|\s+(?:and|but|so)\s+", text[m.end() :], maxsplit=1)[0]
        if not _only_person(m["who"], lexicon) or not _things31(what, lexicon):
            return m[0]
        lead = m[0][: m[0].lower().index("it")]
        return f"{lead}{m['who']} {m['verb']}"

    return _CLEFT_WHO33.sub(plain, text)


# "person b's been on about the bottle again hand it over": the want said by an idiom, then the
# handover of 'it' run on
_ON_ABOUT33 = re.compile(
    rf"(?:\s+has|'s) been (?:going )?on about\b(?= {_DET32}\b)",
    _F,
)
_WANT_RUN_ON33 = re.compile(
    r"\b(?P<first>(?:wants|needs) (?P<what>(?:the|that|this) [a-z][a-z ]*?)) "
    r"(?=(?:hand|give|pass|bring|take) it(?: over)?\s*$)",
    _F,
)


def _on_about33(text: str, lexicon: Lexicon) -> str:
    """Session 33: 'P's been on about X (again)' is 'P wants X' (X objects only, no pronoun after
    that may hand P something else); a closing 'hand it over' run on after a want of one object
    is joined with a comma ('it' is that object)."""
    m = _ON_ABOUT33.search(text)
    if m is not None:
        what = re.split(r"[,.;!?]|\s+(?:again|and|but|so)\b", text[m.end() :], maxsplit=1)[0]
        if _things31(what, lexicon) and not re.search(r"\b(?:her|him|them)\b", text, _F):
            # 'again' of going on about it, not of the handover
            after = text[m.end() :]
            if after[len(what) :].lower().startswith(" again"):
                after = what + after[len(what) + len(" again") :]
            text = text[: m.start()] + " wants" + after
    if " it" not in text:
        return text
    return _WANT_RUN_ON33.sub(
        lambda m: (
            f"{m['first']}, "
            if len(_ids(m["what"], lexicon, "object")) == 1
            and _only_kind(m["what"], lexicon, "object")
            else m[0]
        ),
        text,
    )


# "The machinist says Person A should have …": the request reported from someone of a trade
_TRADE_SAYS33 = re.compile(r"^(?:the|our|my) (?P<trade>[a-z]+) says,? (?:that )?(?=[A-Z])", _F)


def _trade_says33(text: str, lexicon: Lexicon) -> str:
    """Session 33: the opening report above taken off (as _says29 takes off a person's), when the
    trade could only describe a person and what follows has no word for the speaker and no person
    pronoun ('both of them' counts the objects)."""
    if " says" not in text:
        return text
    m = _TRADE_SAYS33.match(text)
    if m is None or not _trade_words29(m["trade"], lexicon):
        return text
    rest = text[m.end() :]
    counted = re.sub(r"\b(?:both|all|either|each) of them\b", "", rest, flags=_F)
    return text if _SPEAKER_OR_PRONOUN29.search(counted) else rest


# ", the millwright's lent us them": where the things came from, said by the speaker
_LENT33 = re.compile(
    r",\s*(?:the|our|my) (?P<trade>[a-z]+)(?:'s| has| had)? lent (?:us|me) (?:them|it)"
    r"(?: (?:for the day|for now|this morning|today))?(?P<end>\s*[.!]?)\s*$",
    _F,
)


def _lent33(text: str, lexicon: Lexicon) -> str:
    """Session 33: the closing part above taken off when the trade could only describe a person
    and what is left names a person."""
    if " lent " not in text:
        return text
    return _trade_closing_dropped(_LENT33, text, lexicon)


# "… for me please my hands are all plaster": the speaker's hands, why they ask, run on at the end
_MY_HANDS33 = re.compile(
    r"(?:,\s*|\s+)(?:as |because |cos |since )?my hands are (?:all |both |a bit |too |full of |"
    r"covered in |(?:all )?covered in )?(?P<what>[a-z]+(?: [a-z]+)?)(?P<end>\s*[.!]?)\s*$",
    _F,
)


# "start off with crisps for alice and after that …": what is first, said with 'start with'
_START_WITH33 = re.compile(
    r"^(?:start|begin)(?: off| out)? with (?P<task>[^,.;!?]+?)"
    r"(?= (?:and )?(?:after that|then|next)\b)",
    _F,
)


def _start_with33(text: str, lexicon: Lexicon) -> str:
    """Session 33: 'start with X for P and after that …' is 'X for P first and after that …',
    when the task is objects and one person joined by 'for' or 'to'."""
    if not text.lower().startswith(("start", "begin")):
        return text
    m = _START_WITH33.match(text)
    if m is None:
        return text
    what, to, who = (
        m["task"].partition(" for ") if " for " in m["task"] else m["task"].partition(" to ")
    )
    if not to or not _things31(what, lexicon) or not _only_person(who, lexicon):
        return text
    return f"{m['task']} first{text[m.end() :]}"


# "Person B needs the chips to keep him going": what the thing is for, of that person
_KEEP_GOING33 = re.compile(
    r"(?P<want>\b(?:needs?|wants?) (?:the|that|this|those|these) [^,.;!?]+?) to (?:keep (?P<a>him|"
    r"her|them) going|tide (?P<b>him|her|them) over)(?=\s*(?:[,.;!?]|$))",
    _F,
)


def _keep_going33(text: str, lexicon: Lexicon) -> str:
    """Session 33: the purpose above taken off after a want of objects only, when the one person
    named before it in its sentence may be the pronoun."""
    if " to " not in text:
        return text

    def dropped(m: re.Match[str]) -> str:
        people = _people_before32(text[: m.start()], lexicon)
        pron = m["a"] or m["b"]
        what = m["want"].split(" ", 1)[1]
        if len(people) != 1 or not _fits(next(iter(people)), pron, lexicon):
            return m[0]
        return m["want"] if _things31(what, lexicon) else m[0]

    return _KEEP_GOING33.sub(dropped, text)


# "…, and the chips, well, those are Person A's, so give them to Person A": whose the things are,
# then the handover to that same person
_THOSE_ARE33 = re.compile(
    r"\b(?P<x>(?:the|that|this|those|these) [a-z][a-z ]*?),\s*(?:well,\s*)?(?:those|they|that|"
    r"it)(?:'s| are| is) (?P<p>[A-Z][A-Za-z ]*?)'s,\s*so (?:give|hand|pass|take) (?:them|it) "
    r"(?:over )?to (?P<q>[A-Z][A-Za-z ]*?)(?P<end>\s*[.!]?)\s*$"
)


def _those_are33(text: str, lexicon: Lexicon) -> str:
    """Session 33: the closing part above is 'X to P', when X is objects only and the owner and
    the one handed them are the same one person (the handover says it; 'them' is X)."""
    if "'s, so " not in text:
        return text
    m = _THOSE_ARE33.search(text)
    if m is None or not _things31(m["x"], lexicon) or not _only_person(m["p"], lexicon):
        return text
    if _ids(m["p"], lexicon) != _ids(m["q"], lexicon):
        return text
    return f"{text[: m.start()]}{m['x']} to {m['q']}{m['end']}"


# -- session 34 (engineer 12): blind32's kinds (politeness, wants, pronouns and ellipsis, splits,
# lower case, typos, questions); docs/grounding.md, "Session 34 (engineer 12)" -----------------

# The speaker's own words said as a comma part or sentence of their own (a closed list, as
# _PARTS33): a wish for the hearer ('hope the night shift was kind to you', 'hope you're well'),
# that it is not pressing ('no rush at all'), how pressing ('kind of urgently'), an exclamation
# ('Dear me'). Each names nothing and changes nothing asked.
_PARTS34 = re.compile(
    r"(?:i )?hope (?:the|your) (?:[a-z]+ ){0,2}[a-z]+ (?:was|is|has been|'s been) (?:kind|good|"
    r"easy|gentle) (?:to|on) you|(?:i )?hope you(?:'re| are) (?:well|keeping well|doing well)|"
    r"(?:there's )?no (?:rush|hurry)(?: at all| whatsoever)|"
    r"(?:kind of|sort of|kinda|quite|rather|fairly|pretty|a bit) urgently|"
    r"(?:oh )?dear me",
    _F,
)


# thanks closing the request, said from the speaker and someone of a trade ("…, and thanks from
# the potman and me."): the speaker is no recipient, the trade no person of the scene
_THANKS_FROM34 = re.compile(
    r",\s*(?:and\s+)?(?:thanks|thank you|cheers|many thanks)(?: very much| a lot)? from "
    r"(?:(?:the|our|my) (?P<trade>[a-z]+) and (?:me|us)|(?:me|us) and (?:the|our|my) "
    r"(?P<trade2>[a-z]+))(?P<end>\s*[.!]?)\s*$",
    _F,
)


def _thanks_from34(text: str, lexicon: Lexicon) -> str:
    """Session 34: the closing thanks above taken off when the trade could only describe a
    person (_trade_words29) and what is left names something."""
    m = _THANKS_FROM34.search(text)
    if m is None or not _trade_words29(m["trade"] or m["trade2"], lexicon):
        return text
    rest = text[: m.start()]
    return rest + m["end"].strip() if _names(rest, lexicon) else text


# a courtesy (of _COURTESY24, or English thanks) said with whose word it was ("…, and ke a leboga,
# as my Setswana nan used to say."): the courtesy and the saying go together
_AS_USED_TO34 = re.compile(
    r",\s*(?P<court>[^,.;!?]+?),\s*as (?:my|our) (?:[A-Z][a-z]+ )?[a-z]+ (?:used to|would|"
    r"always|often) say(?P<end>\s*[.!]?)\s*$"
)
_THANKS34 = re.compile(
    r"(?:and\s+)?(?:thanks|thank you|cheers|ta|many thanks)(?: very much| a lot| so much)?", _F
)


# wants said by an idiom: a closed list (docs/grounding.md, "Session 34 (engineer 12)"), each
# said plainly as a want the grammar reads, before a determiner (as _IDIOMS33)
_IDIOMS34: tuple[tuple[str, str], ...] = (
    # "Person A is gasping for that bottle" (thirsty for it)
    (rf"(?:\s+is|'s|\s+was) (?:absolutely |just |really )?gasping for\b(?= {_DET32}\b)", " wants"),
    # "Person A has a craving for the chips", "… has got a craving for"
    (rf"(?:\s+has|'s)(?: got)? (?:a|such a|a real|a big) craving for\b(?= {_DET32}\b)", " wants"),
    # "The chips are wanted over by Person B": wanted (over) where Person B is
    (r"\s+(?P<be>is|are) wanted over by\b(?= [A-Z])", r" \g<be> wanted by"),
    # "the chips are meant for Person B": who they are for
    (r"\s+(?P<be>is|are) (?:meant|intended) for\b(?= [A-Z])", r" \g<be> for"),
)  # fmt: skip


def _idioms34(text: str, lexicon: Lexicon) -> str:
    """Session 34: the idioms above, said plainly: a want's object up to a mark must be objects
    of the scene only, and no pronoun after it may hand that person something else (as
    _idioms33); 'wanted over by' and 'meant for' need one person of the scene after them, the
    object before them (its sentence's start) objects only."""
    for pattern, plain in _IDIOMS34:
        m = re.search(_rx(pattern), text)  # gated (session 53, 12p)
        if m is None:
            continue
        if plain == " wants":
            what = re.split(
                r"[,.;!?]|\s+(?:and|but|so|while|after)\s+", text[m.end() :], maxsplit=1
            )[0]
            if not _things31(what, lexicon) or re.search(
                r"\b(?:her|him|them)\b", text[m.end() :], _F
            ):
                continue
        else:
            who = re.split(r"[,.;!?]|\s+(?:and|but|so)\s+", text[m.end() :], maxsplit=1)[0]
            what = re.split(r"[,.;!?]|\s+(?:and|but|so)\s+", text[: m.start()])[-1]
            if not _only_person(who, lexicon) or not _things31(what, lexicon):
                continue
        text = text[: m.start()] + m.expand(plain) + text[m.end() :]
    return text


# "What I'd like is the apple going over to Person B.": the want said as a pseudo-cleft, its focus
# the object and where it goes ("I'd like the apple going over to Person B" reads)
_WHAT_LIKE34 = re.compile(
    rf"^what (?P<who>i'd|i would|we'd|we would) (?P<v>like|love|want) is (?={_DET32}\b)", _F
)


def _what_like34(text: str, lexicon: Lexicon) -> str:
    """Session 34: the pseudo-cleft above said plainly, when its focus up to 'going' is objects
    of the scene only and a person or surface follows (the grammar reads the rest)."""
    m = _WHAT_LIKE34.match(text)
    if m is None:
        return text
    focus = re.split(r"\s+(?:going|to go|sent|taken|brought|put|delivered)\b", text[m.end() :])
    if len(focus) < 2 or not _things31(focus[0], lexicon):
        return text
    return f"{m['who']} {m['v']} {text[m.end() :]}"


# "… if it's going spare": whether the thing is free for the taking, which the scene's own
# thing is (the request is for it): a closed list of such conditions, after a want of one object
_SPARE34 = re.compile(
    r"\s+if (?:it's|it is|they're|they are) (?:going spare|going begging|spare|not being used|"
    r"not needed)(?P<end>\s*[.!]?)\s*$",
    _F,
)
_WANTS_ONE34 = re.compile(
    r"\b(?:would love|would like|wants|needs|fancies|could use|would welcome) "
    rf"(?P<x>{_DET32} [a-z][a-z ]*?)$",
    _F,
)


def _if_spare34(text: str, lexicon: Lexicon) -> str:
    """Session 34: the condition above taken off when it closes a sentence whose want's object
    (its last words) is one object of the scene (or several, for 'they')."""
    m = _SPARE34.search(text)
    if m is None:
        return text
    w = _WANTS_ONE34.search(text[: m.start()])
    if w is None or not _things31(w["x"], lexicon):
        return text
    one = len(_ids(w["x"], lexicon, "object")) == 1 and not w["x"].lower().startswith("those")
    if one != bool(re.match(r"\s+if it", m[0], _F)):
        return text
    return text[: m.start()] + m["end"].strip()


# "Person A fancies the apple after her walk.": what made the person want it, said after the
# want of a closed list of doings (not an order: no task is said after it)
_AFTER_DOING34 = re.compile(
    r"\b(?P<want>(?:wants|needs|fancies|could use|would love|would like|is after|'s after) "
    rf"(?P<x>{_DET32} [a-z][a-z ]*?)) after (?:the|her|his|their|a|that) "
    r"(?:long |big |hard |early )?"
    r"(?:jog|walk|run|swim|hike|ride|workout|shift|match|game|climb|cycle|dance|practice|"
    r"rehearsal|training|session|drive|trek)(?P<end>\s*[.!]?)\s*$",
    _F,
)


def _after_doing34(text: str, lexicon: Lexicon) -> str:
    """Session 34: 'after the jog' taken off after a want of objects only, closing the
    instruction."""
    if " after " not in text:
        return text
    m = _AFTER_DOING34.search(text)
    if m is None or not _things31(m["x"], lexicon):
        return text
    return text[: m.start()] + m["want"] + m["end"].strip()


# "The landlady tells me Mr Novak wants …": the request reported from someone of a trade (as
# _trade_says33's 'says')
_TRADE_TELLS34 = re.compile(
    r"^(?:the|our|my) (?P<trade>[a-z]+) (?:tells|told|has told|'s told) (?:me|us),? (?:that )?"
    r"(?=[A-Z])",
    _F,
)
# "According to the hedgelayer, …": whose word the request is, opening it (_according33 takes
# it off closing)
_ACCORDING_OPEN34 = re.compile(r"^according to (?:the|our|my) (?P<trade>[a-z]+),\s*(?=[A-Z])", _F)


def _trade_tells34(text: str, lexicon: Lexicon) -> str:
    """Session 34: the opening report above taken off when the trade could only describe a
    person and what follows has no word for the speaker and no person pronoun (as
    _trade_says33)."""
    for rx in (_TRADE_TELLS34, _ACCORDING_OPEN34):
        m = rx.match(text)
        if m is None or not _trade_words29(m["trade"], lexicon):
            continue
        rest = text[m.end() :]
        counted = re.sub(r"\b(?:both|all|either|each) of them\b", "", rest, flags=_F)
        if not _SPEAKER_OR_PRONOUN29.search(counted):
            return rest
    return text


# "For his fractions worksheet Noah is going to need the ruler.": what the person needs it for,
# fronted, its pronoun the person named right after it
_FOR_HIS34 = re.compile(
    r"^[Ff]or (?P<pron>his|her|their) (?P<what>[a-z]+(?: [a-z]+){0,2}),? (?P<p>[A-Z][a-z]+"
    r"(?: [A-Z][a-z]*)?) (?=(?:is going to need|is gonna need|will need|needs|wants|is after|"
    r"would like)\b)"
)


# "As for the crisps, Alice can have them; …": the object said first as the topic, then the clause
# that says who gets it, pointing back with a pronoun
_AS_FOR34 = re.compile(
    r"(?:^|(?<=[.;!?])\s+)as (?:for|regards|to) (?P<x>(?:the|that|this|those|these) [^,.;!?]+?),"
    r"\s*(?P<rest>[^.;!?]*)",
    _F,
)


def _as_for34(text: str, lexicon: Lexicon) -> str:
    """Session 34: 'As for X, …' is 'X, …' (a topic the grammar reads: "The crisps, Alice can
    have them"), when X is objects of the scene only and the clause after it says 'them' (X more
    than one thing) or 'it' (one)."""
    m = _AS_FOR34.search(text)
    if m is None or not _things31(m["x"], lexicon):
        return text
    many = len(_ids(m["x"], lexicon, "object")) > 1 or m["x"].lower().endswith("s")
    pron = r"\bthem\b" if many else r"\bit\b"
    if not re.search(pron, m["rest"], _F):
        return text
    lead = re.sub(r"as (?:for|regards|to) $", "", text[: m.start("x")], flags=_F)
    return f"{lead}{text[m.start('x') :]}"


# "Person B can take the chips off your hands": P has them (the hearer is rid of them)
_OFF_HANDS34 = re.compile(
    rf"\b(?P<v>can|could|will|may) take (?P<x>{_DET32} [a-z][a-z ]*?) off (?:your|our|my) hands\b",
    _F,
)
# "Person B was the one who asked for the chips": the want said as 'the one who'
_THE_ONE_WHO34 = re.compile(
    r"(?P<p>\b[A-Z][a-z]+(?: [A-Z][a-z]*)?) (?:was|is|'s) the one (?:who|that) "
    r"(?P<v>asked for|ordered|requested|wanted|wants|needs|needed)(?= (?P<x>(?:the|that|this|"
    r"those|these) [a-z][a-z ]*?)(?:[,.;!?]|\s+(?:and|so|but)\b|$))"
)
# "… so trot them over to her": carrying, said by a verb of going quickly with a thing (as
# _carried32's 'run X down to'), its object a pronoun or objects of the scene
_TROT34 = re.compile(
    rf"\b(?:trot|scoot|nip|zip|run|whizz) (?P<x>it|them|{_DET32} [a-z][a-z ]*?) "
    r"(?:over|down|up|across|along|round) to\b",
    _F,
)


def _handover_frames34(text: str, lexicon: Lexicon) -> str:
    """Session 34: 'P can take X off your hands' is 'P can have X'; 'P was the one who asked for
    X' is 'P asked for X' (P one person, X objects only up to a mark); 'trot X over to' is 'take
    X over to' (X 'it', 'them' or objects only)."""
    if " hands" in text:
        text = _OFF_HANDS34.sub(
            lambda m: f"{m['v']} have {m['x']}" if _things31(m["x"], lexicon) else m[0], text
        )
    if " the one " in text:
        text = _THE_ONE_WHO34.sub(
            lambda m: (
                f"{m['p']} {m['v']}"
                if _only_person(m["p"], lexicon) and _things31(m["x"], lexicon)
                else m[0]
            ),
            text,
        )
    return _TROT34.sub(
        lambda m: (
            f"take {m['x']} over to"
            if m["x"].lower() in ("it", "them") or _things31(m["x"], lexicon)
            else m[0]
        ),
        text,
    )


# "Can you see the bottle on your left? Person A has asked for it, take it over.": a question that
# points the hearer at one object, then a sentence that says 'it' of it
_SEE_THE34 = re.compile(
    rf"^(?:can|do) you see (?P<x>{_DET32} [a-z][a-z ]*?)(?: (?:on|to) your (?:left|right)| over "
    r"there| there| in front of you| behind you| next to you)?\?\s+(?P<rest>[^.?!]+[.!]?)\s*$",
    _F,
)


def _see_the34(text: str, lexicon: Lexicon) -> str:
    """Session 34: the pointing question above taken off and the first 'it' of the sentence
    after it said as the object, when it is one object of the scene (by its words alone) and
    that sentence names no other object."""
    if "see " not in text.lower():
        return text
    m = _SEE_THE34.match(text)
    if m is None or not _things31(m["x"], lexicon):
        return text
    if len(_ids(m["x"], lexicon, "object")) != 1 or _ids(m["rest"], lexicon, "object"):
        return text
    if not re.search(r"\bit\b", m["rest"]):
        return text
    return re.sub(r"\bit\b", m["x"].lower(), m["rest"], count=1)


# "Person A's been on about it since the saxophone lesson": since when the person has wanted it
_SINCE_WANTED34 = re.compile(
    r"(?P<want>(?:'s|\s+has) been (?:going on|on|banging on|asking|going) (?:about|for|on about) "
    r"(?:it|them)) since (?:the|her|his|their|this|that) (?:[a-z]+ ){0,2}(?:lesson|class|"
    r"morning|meeting|match|game|break|lunch|practice|rehearsal|session|shift|walk|visit)"
    r"(?=\s*[,.;!?]|\s*$)",
    _F,
)


def _since_wanted34(text: str, lexicon: Lexicon) -> str:
    """Session 34: 'since the <event>' taken off after 'been on about it' when its words name
    nothing of the scene."""
    if " since " not in text:
        return text
    return _SINCE_WANTED34.sub(
        lambda m: m["want"] if _names_nothing(m[0][len(m["want"]) :], lexicon) else m[0], text
    )


# "The tongs are what Lena's been waiting on, so over to her with them.": the want said as a
# pseudo-cleft with the object first, then the handover said without its verb
_WHAT_WAITING34 = re.compile(
    r"^(?P<x>(?:[Tt]he|[Tt]hat|[Tt]his|[Tt]hose|[Tt]hese) [a-z][a-z ]*?) (?:is|are|'s) "
    r"(?:just )?what "
    r"(?P<p>[A-Z][a-z]+(?: [A-Z][a-z]*)?)(?P<v>(?:'s| has) been (?:waiting (?:on|for)|after|"
    r"asking for|wanting)|(?:'s| is) (?:waiting (?:on|for)|after)| wants| needs| asked for)"
    r"(?=\s*[,.;!?]|\s+(?:and|so)\b|\s*$)",
)
_OVER_WITH34 = re.compile(
    r"\b(?P<so>so |and )?over to (?P<who>her|him|them) with (?P<x>it|them)(?=\s*[.!]?\s*$)", _F
)


def _what_waiting34(text: str, lexicon: Lexicon) -> str:
    """Session 34: 'X are what P's been waiting on' is 'P wants X' (X objects only, P one
    person); then 'over to her with them' closing it is 'take them over to her'."""
    m = _WHAT_WAITING34.match(text)
    if m is not None and _things31(m["x"], lexicon) and _only_person(m["p"], lexicon):
        text = f"{m['p']} wants {m['x']}{text[m.end() :]}"
    return _OVER_WITH34.sub(lambda m: f"{m['so'] or ''}take {m['x']} over to {m['who']}", text)


# "I've been on the trumpet all morning and I'm whacked so could you …": the speaker's remarks run
# on before the request, joined by 'and' and closed by 'so'
_RUN_ON_REMARKS34 = re.compile(
    r"^(?P<said>(?:i|i'm|i've|i am|i have|we|we're|we've)\b[^,.;:!?]*?)\s+so\s+"
    r"(?=(?:could|can|would|will) you\b|please\b)",
    _F,
)
_ALL_DAY34 = re.compile(r"\b(?:all|the whole) (?:day|morning|afternoon|evening|night|week)\b", _F)


def _run_on_remarks34(text: str, lexicon: Lexicon) -> str:
    """Session 34: the run-on remarks above taken off when each of the clauses 'and' joins is a
    remark about the speaker (_remark_clause; how long, 'all morning', said of it), and what is
    left names something."""
    m = _RUN_ON_REMARKS34.match(text)
    if m is None:
        return text
    clauses = re.split(r"\s+and\s+", m["said"], flags=_F)
    if not all(_remark_clause(_ALL_DAY34.sub("", c), lexicon) for c in clauses):
        return text
    rest = text[m.end() :]
    return rest if _names(rest, lexicon) else text


# "Torch to Jess she's under the van and …": where the person just named is, run on after the
# name (a remark: it names nothing and asks nothing)
_WHERE_SHE_IS34 = re.compile(
    r"(?P<p>\b[A-Z][a-z]+(?: [A-Z][a-z]*)?),? (?P<pron>she|he)(?:'s| is) (?:under|in|at|by|behind|"
    r"up|out in|round|on) the (?P<place>[a-z]+(?: [a-z]+)?)(?=\s+and\b|\s*[,.;!?]|\s*$)"
)


# ", from the stableman": whose request it is, by their trade, closing it
_FROM_TRADE34 = re.compile(r",\s*from (?:the|our|my) (?P<trade>[a-z]+)(?P<end>\s*[.!]?)\s*$", _F)


def _from_trade34(text: str, lexicon: Lexicon) -> str:
    """Session 34: the closing part above taken off when the trade could only describe a person
    and what is left names a person (as _according33)."""
    if "from " not in text:
        return text
    return _trade_closing_dropped(_FROM_TRADE34, text, lexicon)


# "person a has the chips coming": the person is to get them; "… is owed the bottle from earlier":
# since when it is owed
_HAS_COMING34 = re.compile(
    rf"\b(?:has|'s got|has got) (?P<x>{_DET32} [a-z][a-z ]*?) coming(?: (?:to (?:her|him|them)|"
    r"her way|his way|their way))?(?=\s*[,.;!?]|\s+and\b|\s*$)",
    _F,
)
_OWED_FROM34 = re.compile(
    rf"\b(?P<owed>(?:is|'s) owed (?P<x>{_DET32} [a-z][a-z ]*?)) from (?:earlier|before|"
    r"yesterday|last time|this morning)(?=\s*[,.;!?]|\s*$)",
    _F,
)


def _has_coming34(text: str, lexicon: Lexicon) -> str:
    """Session 34: 'has X coming' is 'gets X', and 'from earlier' after 'is owed X' is taken off
    (X objects only)."""
    if " coming" in text:
        text = _HAS_COMING34.sub(
            lambda m: f"gets {m['x']}" if _things31(m["x"], lexicon) else m[0], text
        )
    if " owed " in text:
        text = _OWED_FROM34.sub(lambda m: m["owed"] if _things31(m["x"], lexicon) else m[0], text)
    return text


# "Erson A has been at the bandstand all day and could use the bottle": where the person has been
# (naming nothing), said before the want it explains
_BEEN_AT34 = re.compile(
    r"(?P<p>\b[A-Za-z][a-z]*(?: [A-Za-z][a-z]*)?) (?:has|'s) been (?P<where>(?:at|in|on|out in|"
    r"up at|down at|out at|over at) the [a-z]+(?: [a-z]+)?) (?:all day|all morning|"
    r"all afternoon|for hours|since dawn) and "
    r"(?=(?:could use|needs|wants|would love|would like|could do with)\b)",
)


# "Sam's asked for the stapler to do the handouts.": what the person wants it for, closing the
# want (a doing of a closed list, on something the scene does not name)
_TO_DO34 = re.compile(
    rf"\b(?P<want>(?:asked for|wants|needs|is after|'s after|would like) (?P<x>{_DET32} "
    r"[a-z][a-z ]*?)) to (?:do|finish|mark|sort|fix|write|staple|make) (?:the|her|his|their|"
    r"some) (?P<what>[a-z]+(?: [a-z]+)?)(?P<end>\s*[.!]?)\s*$",
    _F,
)


# "Mind if Person A grabs the chips off you?": asking leave for P to take X is asking that P get X
_MIND_IF34 = re.compile(
    r"^(?:do you |would you )?mind if (?P<p>[A-Z][a-z]+(?: [A-Z][a-z]*)?) (?P<v>grabs|takes|has|"
    rf"borrows|gets|nabs) (?P<x>{_DET32} [a-z][a-z ]*?)(?P<off> off you)?\s*\?\s*$",
    _F,
)


def _mind_if34(text: str, lexicon: Lexicon) -> str:
    """Session 34: the question above is 'Can P have X?' (P one person, X objects only), the
    whole instruction."""
    m = _MIND_IF34.match(text)
    if m is None or not _only_person(m["p"], lexicon) or not _things31(m["x"], lexicon):
        return text
    return f"Can {m['p']} have {m['x']}?"


# "Could you see your way to getting the chips to Person A?": whether the hearer can manage it
_SEE_WAY34 = re.compile(
    r"^(?P<ask>(?:could|can|would) you) (?:possibly )?see your way(?: clear)? to "
    r"(?P<v>[a-z]+)ing\b",
    _F,
)
# "What about giving Person B the bottle, would that work?": the hearer asked whether it suits
_WOULD_WORK34 = re.compile(
    r"^(?P<q>(?:what|how) about [a-z]+ing\b[^,.;!?]*?),\s*(?:would|does|will|is) that (?:work|do|"
    r"be (?:okay|ok|alright|all right|possible|fine)|suit you)\s*\?\s*$",
    _F,
)
# "Can you hand Person A the bottle, then?": 'then' closing a question that is the whole request
# ('in that case'), no order
_THEN_ASKED34 = re.compile(r"^(?P<q>(?:can|could|would|will) you [^,.;!?]+?),\s*then\s*\?\s*$", _F)


def _questions34(text: str, lexicon: Lexicon) -> str:
    """Session 34: 'see your way to -ing' is the verb itself; ', would that work?' after 'what
    about -ing …' is taken off; ', then?' closing a one-sentence question is taken off (each when
    the words left name something)."""
    m = _SEE_WAY34.match(text)
    if m is not None:
        said = f"{m['ask']} {_base(m['v'])}{text[m.end() :]}"
        if _names(said, lexicon):
            text = said
    m = _WOULD_WORK34.match(text)
    if m is not None and _names(m["q"], lexicon):
        text = f"{m['q']}?"
    m = _THEN_ASKED34.match(text)
    if m is not None and _names(m["q"], lexicon):
        text = f"{m['q']}?"
    return text


# A remark closing the instruction as a comma part ("Give Person A the bottle, hope the night shift
# was kind to you."): the same test as a sentence of its own (_inert_sentence: it names nothing,
# no word of it could name, count, choose, negate, order, delay, condition, correct, point back or
# hand over, it is shaped as no request; the lead's note, session 34: one test for the kind, not a
# pattern per remark), opening as session 16's remarks about the hearer or the moment do
# (_REMARK_SUBJECT: 'hope', 'you', 'your', 'have a'; a comma part without its own subject may say
# how or when the request is to be done: ", at your discretion", ", in a bit"), and no word that
# takes the request back, leaves it to the hearer, says when or how fast, which end of the order,
# or the speaker
_TRAILING_HELD34 = re.compile(
    r"\b(?:kidding|joking|thoughts?|second|typo|nope|nah|asap|now|soon|today|yesterday|week|"
    r"hours?|minutes?|mins?|moment|order|reverse|round|around|depend\w*|quick(?:ly)?|fast|"
    r"slow(?:ly)?|urgent(?:ly)?|end|start|beginning|finish|please|yet|still|sure|maybe|perhaps|"
    r"think|guess|unsure|doubt|mine|me|us|we|our|my|i|discretion|choice|call|decide\w*|"
    r"decision|option\w*|prefer\w*|fit|suits?|up|bit|while|shortly|eventually|sometime|later|"
    r"leisure|weekend|morning|afternoon|evening|noon|midday|midnight|clock|tonight|monday|"
    r"tuesday|wednesday|thursday|friday|saturday|sunday)\b",
    _F,
)
_TRAILING34 = re.compile(r",\s*(?P<said>[^,;:.!?]+?)(?P<end>\s*[.!]?)\s*$")


# "the wee box" (Scots and Irish English: small), "the little teddy": a size said by a word the
# scene's names do not use. Read as the scene's own size word when the scene names an object
# '<size> <noun>' of that size class (depot: 'small box'), or taken off when the noun names one
# object alone and no object of it is named by size (a description, not a choice)
_SIZE_WORD34 = re.compile(
    r"\b(?P<det>the|that|this|your|her|his|their) (?P<size>wee|little|tiny|teeny|small|big|huge|"
    r"massive|large) (?P<noun>[a-z]+)\b",
    _F,
)
_SIZE_CLASS34 = {
    **dict.fromkeys(("wee", "little", "tiny", "teeny", "small"), ("small", "little")),
    **dict.fromkeys(("big", "huge", "massive", "large"), ("large", "big")),
}


def _size_words34(text: str, lexicon: Lexicon) -> str:
    """Session 34: the size words above (a closed list), as said there."""
    if not _SIZE_WORD34.search(text):
        return text
    aliases = {a.lower() for o in lexicon.scene.objects for a in (o.id, *o.aliases)}

    def plain(m: re.Match[str]) -> str:
        noun, size = m["noun"].lower(), m["size"].lower()
        if noun in ("one", "ones", "uns", "un") or f"{size} {noun}" in aliases:
            return m[0]
        sized = [w for w in _SIZE_CLASS34[size] if f"{w} {noun}" in aliases]
        if sized:
            return f"{m['det']} {sized[0]} {m['noun']}"
        others = {w for ws in _SIZE_CLASS34.values() for w in ws}
        if any(f"{w} {noun}" in aliases for w in others):
            return m[0]  # the noun's objects are named by another size: which one is meant?
        ids = _ids(f"the {noun}", lexicon)
        if len(ids) != 1 or not _only_kind(f"the {noun}", lexicon, "object"):
            return m[0]
        return f"{m['det']} {m['noun']}"

    return _SIZE_WORD34.sub(plain, text)


# "… so hand it over, and the cup to Person A.": the handover of 'it' closed by 'over', then a
# clause of its own with its recipient (the grammar had read 'it' and the cup both to Person A)
_OVER_AND34 = re.compile(
    r"\b(?P<first>(?:hand|give|pass|take|bring) (?:it|them) over),\s+and (?P<x>(?:the|that|this) "
    r"[a-z][a-z ]*?) (?P<to>to (?P<p>[A-Z][A-Za-z ]*?))(?P<end>\s*[.!]?)\s*$"
)


def _over_and34(text: str, lexicon: Lexicon) -> str:
    """Session 34: the closing clause above said as a sentence of its own, when X is objects only
    and P one person."""
    if " over, and " not in text:
        return text
    m = _OVER_AND34.search(text)
    if m is None or not _things31(m["x"], lexicon) or not _only_person(m["p"], lexicon):
        return text
    said = m["x"][0].upper() + m["x"][1:]
    return f"{text[: m.start()]}{m['first']}. {said} {m['to']}{m['end'] or '.'}"


# "Ava, the two blocks give her, please.": the person addressed first, then the objects and the
# verb last with its pronoun (as session 27's '<person> <objects> give')
_VERB_LAST34 = re.compile(
    r"(?:^|(?<=[.!?]\s))(?P<p>[A-Z][a-z]+(?: [A-Z][a-z]*)?),\s*"
    r"(?P<x>(?:the|a|an|that|this|those|these|both|both the) [a-z][a-z -]*?) "
    r"(?P<v>give|hand|pass|bring) (?P<pron>her|him|them)"
    r"(?=\s*(?:[,.;!?]|$))"
)


def _verb_last34(text: str, lexicon: Lexicon) -> str:
    """Session 34: the clause above in the English order ('give P X'), when P is one person the
    pronoun may be (by title) and X objects only."""
    if not re.search(r" (?:give|hand|pass|bring) (?:her|him|them)\b", text):
        return text

    def plain(m: re.Match[str]) -> str:
        if not _only_person(m["p"], lexicon) or not _objects_only(m["x"], lexicon):
            return m[0]
        if not _fits(next(iter(_ids(m["p"], lexicon))), m["pron"], lexicon):
            return m[0]
        return f"{m['v'].capitalize()} {m['p']} {m['x']}"

    return _VERB_LAST34.sub(plain, text)


# "Could Person A have the cup first and, when she's done with it, the bottle?": the next thing
# when the person has finished with the first, said as 'after that'
_DONE_WITH34 = re.compile(
    r",\s*(?:when|once) (?P<pron>she|he|they)(?:'s| is| has|'re| are| have)(?: all)? "
    r"(?:done|finished)(?: with (?:it|them|that|those))?,\s*(?=(?:the|that|this|those|these)\b)",
    _F,
)


def _done_with34(text: str, lexicon: Lexicon) -> str:
    """Session 34: the clause above is ', after that, ' when the sentence before it names one
    person, the one the pronoun may be."""
    if " done" not in text and " finished" not in text:
        return text
    m = _DONE_WITH34.search(text)
    if m is None:
        return text
    people = _people_before32(text[: m.start()], lexicon)
    if len(people) != 1 or not _fits(next(iter(people)), m["pron"], lexicon):
        return text
    return f"{text[: m.start()]}, after that, {text[m.end() :]}"


# "…, and Emma needs the green cup, so do that too.": the hearer told to do what the want says,
# closing a clause that says a want of objects for one person
_DO_THAT34 = re.compile(
    r"\b(?P<want>(?:wants|needs|would like|asked for|is after|'s after) (?P<x>(?:the|that|this|"
    r"those|these) [a-z][a-z ]*?)),\s*so do (?:that|this|it|those)(?: too| as well| for (?:her|"
    r"him|them))?(?P<end>\s*[.!]?)\s*$",
    _F,
)


def _do_that34(text: str, lexicon: Lexicon) -> str:
    """Session 34: ', so do that (too)' taken off after a want of objects only."""
    if "so do " not in text:
        return text
    m = _DO_THAT34.search(text)
    if m is None or not _things31(m["x"], lexicon):
        return text
    return text[: m.start()] + m["want"] + m["end"].strip()


# "…, and Bob, for my next trick, wants the crisps.": the speaker's aside between a person and
# their want (a closed list, each naming nothing and asking nothing)
_MID_ASIDE34 = re.compile(
    r"(?P<p>\b[A-Z][a-z]+(?: [A-Z][a-z]*)?),\s*(?:for my next trick|as it happens|as luck would "
    r"have it|of all people|funnily enough|believe it or not),\s*(?=(?:wants|needs|would like|"
    r"is after|'s after|asked for|gets)\b)"
)


def _mid_aside34(text: str, lexicon: Lexicon) -> str:
    """Session 34: the aside above taken off when P is one person of the scene."""
    if "," not in text:
        return text
    return _MID_ASIDE34.sub(lambda m: f"{m['p']} " if _only_person(m["p"], lexicon) else m[0], text)


# -- session 35 (engineer 12): blind33's kinds (politeness, wants, pronouns and ellipsis, splits,
# lower case, typos, questions) and the clefts family's; docs/grounding.md, "Session 35 (engineer
# 12)" -----------------------------------------------------------------------------------------

# "… and after it the apple for person a": 'after it' before the next object is 'after that' (the
# task before it); before a determiner only, so 'put the cup after it' is no sequence
_AFTER_IT35 = re.compile(rf"\b(?P<and>,?\s*and) after it,?(?= {_DET32}\b)", _F)


def _after_it35(text: str, lexicon: Lexicon) -> str:
    """Session 35: 'and after it the X' is 'and after that the X' when what follows up to a mark
    or 'for'/'to' is objects of the scene only and something is named before it."""
    if "after it" not in text.lower():
        return text

    def plain(m: re.Match[str]) -> str:
        what = re.split(r"[,.;!?]|\s+(?:and|for|to|on|onto|in|into)\s+", text[m.end() :])[0]
        if not _things31(what, lexicon) or not _names(text[: m.start()], lexicon):
            return m[0]
        return f"{m['and']} after that"

    return _AFTER_IT35.sub(plain, text)


# a want said by a negated idiom: a closed list (docs/grounding.md, "Session 35 (engineer 12)"),
# with the subject's own pronoun: "Lily won't settle without her teddy" (she wants it: the negation
# is of settling, not of the handover)
_WANT_IDIOMS35 = re.compile(
    r"(?P<p>\b[A-Za-z][a-z]*(?: [A-Za-z][a-z]*)?) (?:won't|will not|can't|cannot|wouldn't) "
    r"(?:settle|sleep|go down|nod off|calm down|stop crying|cope)(?: down)? without "
    r"(?P<pron>her|his|their) "
    rf"(?P<x>{_DET32} [a-z][a-z ]*?|[a-z]+)(?=\s*(?:[,.;!?]|$)|\s+(?:and|but|so|after)\b)",
    _F,
)


def _want_idioms35(text: str, lexicon: Lexicon) -> str:
    """Session 35: the idiom above is 'P wants X' when P is one person whom the pronoun may be
    and X (said with or without its determiner: 'without her teddy' is 'the teddy') objects of the
    scene only."""
    if " without " not in text:
        return text

    def plain(m: re.Match[str]) -> str:
        pron = m["pron"]
        what = m["x"] if re.match(rf"{_DET32}\b", m["x"], _F) else f"the {m['x']}"
        if not _only_person(m["p"], lexicon) or not _things31(what, lexicon):
            return m[0]
        if pron.lower() != "their" and not _fits(next(iter(_ids(m["p"], lexicon))), pron, lexicon):
            return m[0]
        return f"{m['p']} wants {what}"

    return _WANT_IDIOMS35.sub(plain, text)


# "… wants the bottle after a day's angling", "… could do with the cup after her crochet": what
# made the person want it (a pastime of a closed list, said as hers or as 'a day's'; "after the
# meeting" says when, and is not taken off), closing the instruction after a want of objects only
_AFTER_PASTIME35 = re.compile(
    r"\b(?P<want>(?:wants|needs|fancies|could use|could do with|would love|would like|is after|"
    rf"'s after) (?P<x>{_DET32}(?: (?!and\b|but\b|so\b)[a-z]+)+?)) after (?:(?P<pron>her|his|"
    r"their)|a (?:long |hard |busy )?day's) (?P<doing>angling|fishing|knitting|crochet|sewing|"
    r"quilting|swimming|running|cycling|climbing|rowing|sailing|skating|skiing|surfing|riding|"
    r"dancing|singing|walking|jogging|hiking|boxing|bowling|baking|painting|gardening|"
    r"gymnastics|aerobics|pilates|yoga|karate|judo|chess|bingo|cribbage|darts|golf|tennis|"
    r"football|netball|cricket|rugby|hockey|squash|badminton|choir|ballet|embroidery|needlework|"
    r"patchwork|pottery|origami)(?P<end>\s*[.!]?)\s*$",
    _F,
)


# "Chips are needed over at Person A's end, and once they're there, …": the want said of the object,
# with the person's end of the room (a closed list of such places), and the next task when the
# objects have got there (that end: as session 11's 'there', the one place named before it)
_NEEDED_AT35 = re.compile(
    r"(?:^|(?<=[.;!?])\s+)(?P<x>(?:the |those |these )?[a-z][a-z ]*?) (?:is|are) (?:needed|wanted) "
    r"(?:over )?(?:at|by|on) (?P<p>[A-Za-z][a-z]*(?: [A-Za-z][a-z]*)?)'s (?:end|side|place|desk|"
    r"table|spot|corner|station|bench)\b",
    _F,
)
_ONCE_THERE35 = re.compile(
    r",?\s*and once (?:they're|they are|it's|it is|that's|that is) there,\s*", _F
)


def _needed_at35(text: str, lexicon: Lexicon) -> str:
    """Session 35: the want above is 'P wants X' when X (its determiner added if not said) is
    objects of the scene only and P one person; ', and once they're there, ' right after it is ',
    and after that, '."""
    if "'s " not in text or ("needed" not in text and "wanted" not in text):
        return text
    m = _NEEDED_AT35.search(text)
    if m is None:
        return text
    what = m["x"] if re.match(rf"{_DET32}\b", m["x"], _F) else f"the {m['x']}"
    if not _things31(what, lexicon) or not _only_person(m["p"], lexicon):
        return text
    then = _ONCE_THERE35.match(text, m.end())
    said = f"{m['p']} wants {what[0].lower()}{what[1:]}"
    if then is None:
        return f"{text[: m.start('x')]}{said}{text[m.end() :]}"
    return f"{text[: m.start('x')]}{said}, and after that, {text[then.end() :]}"


# "Person B fancies the chips, if you'd sort that.": the hearer asked to see to it, closing (a
# closed list: said of the request itself, no condition of the world)
_IF_SORT35 = re.compile(
    r",\s*if you(?:'d| would| could| can| will)(?: kindly| please)? (?:sort|see to|handle|arrange|"
    r"do|organise|organize|deal with) (?:that|it|this)(?: out)?(?: for (?:me|us))?"
    r"(?P<end>\s*[.!]?)\s*$",
    _F,
)


def _if_sort35(text: str, lexicon: Lexicon) -> str:
    """Session 35: the closing part above taken off when what is left names a person or a
    surface (something to see to)."""
    if " if " not in text:
        return text
    m = _IF_SORT35.search(text)
    if m is None:
        return text
    rest = text[: m.start()]
    if not _ids(rest, lexicon, "human") | _ids(rest, lexicon, "surface"):
        return text
    return rest + m["end"].strip()


# "I'd like the scanner sat on the belt": where the speaker wants the object, said with how it is
# to stand there (a closed list of such participles)
_SAT_ON35 = re.compile(
    r"\b(?P<want>(?:i|we)(?:'d| would) (?:like|love|prefer|want)) "
    rf"(?P<x>{_DET32} [a-z][a-z ]*?) (?:sat|sitting|stood|standing|placed|put|parked|set) "
    r"(?P<on>on|in|onto|into|on top of) (?=the\b)",
    _F,
)


def _sat_on35(text: str, lexicon: Lexicon) -> str:
    """Session 35: the participle above taken off ('I'd like the scanner on the belt') when X is
    objects of the scene only and what follows up to a mark is one surface."""
    if "'d " not in text and " would " not in text:
        return text

    def plain(m: re.Match[str]) -> str:
        where = re.split(r"[,.;!?]|\s+(?:and|but|so)\s+", text[m.end() :], maxsplit=1)[0]
        if not _things31(m["x"], lexicon) or not _surface_only(where, lexicon):
            return m[0]
        return f"{m['want']} {m['x']} {m['on']} "

    return _SAT_ON35.sub(plain, text)


# "The bottle's headed for Person B": where the object is bound, said of it (a closed list)
_HEADED_FOR35 = re.compile(
    rf"(?P<x>\b{_DET32} [a-z][a-z ]*?)(?P<be>'s|'re| is| are) (?:headed|heading|bound|destined|"
    r"earmarked) (?:for|to) (?=[A-Za-z])",
    _F,
)


def _headed_for35(text: str, lexicon: Lexicon) -> str:
    """Session 35: 'X is headed for P' is 'X is for P' when X is objects of the scene only and
    what follows up to a mark is one person."""
    if not re.search(r"head|bound|destined|earmarked", text):
        return text

    def plain(m: re.Match[str]) -> str:
        who = re.split(r"[,.;!?]|\s+(?:and|but|so|who)\s+", text[m.end() :], maxsplit=1)[0]
        if not _things31(m["x"], lexicon) or not _only_person(who, lexicon):
            return m[0]
        return f"{m['x']}{m['be']} for "

    return _HEADED_FOR35.sub(plain, text)


# "It was Person B who asked after the chips": the cleft of _cleft_who33 with verbs of asking for
# or being after something; "It's Bob that the apple is for": the person put first, what is for
# them after 'that'
_CLEFT_AFTER35 = re.compile(
    r"(?:^|(?<=[.;!?])\s+)it(?:'s| is| was) (?P<who>[A-Za-z]+(?: [A-Za-z]+)?) (?:who|that)"
    r"(?: asked after| was after| is after|'s after| has asked after| had asked for)"
    rf"(?= {_DET32}\b)",
    _F,
)
_CLEFT_FOR35 = re.compile(
    r"(?:^|(?<=[.;!?])\s+)it(?:'s| is| was) (?P<who>[A-Za-z]+(?: [A-Za-z]+)?) (?:that|who) "
    rf"(?P<x>{_DET32} [a-z][a-z ]*?) (?P<be>is|are|was|were) (?:for|meant for|intended for)"
    r"(?=\s*(?:[,.;!?]|$))",
    _F,
)


def _clefts35(text: str, lexicon: Lexicon) -> str:
    """Session 35: the clefts above said plainly ('Person B asked for the chips', 'The apple is
    for Bob'), when the focus is one person of the scene and what it is after (up to a mark) or
    what is for them objects of the scene only."""
    if "it" not in text.lower():
        return text

    def asked(m: re.Match[str]) -> str:
        what = re.split(r"[,.;!?]|\s+(?:and|but|so)\s+", text[m.end() :], maxsplit=1)[0]
        if not _only_person(m["who"], lexicon) or not _things31(what, lexicon):
            return m[0]
        lead = m[0][: m[0].lower().index("it")]
        return f"{lead}{m['who']} asked for"

    def meant(m: re.Match[str]) -> str:
        if not _only_person(m["who"], lexicon) or not _things31(m["x"], lexicon):
            return m[0]
        lead = m[0][: m[0].lower().index("it")]
        x = m["x"]
        return f"{lead}{x[0].upper()}{x[1:]} {m['be']} for {m['who']}"

    return _CLEFT_FOR35.sub(meant, _CLEFT_AFTER35.sub(asked, text))


# "The shelf is where the cup goes.": the place put first in a pseudo-cleft
_WHERE_GOES35 = re.compile(
    r"(?:^|(?<=[.;!?])\s+)(?P<s>(?:the|that|this) [a-z][a-z ]*?) is where "
    rf"(?P<x>{_DET32} [a-z][a-z ]*?) (?P<v>goes|go|belongs|belong|lives|live|should go|"
    r"should be|needs to go|need to go)(?=\s*(?:[,.;!?]|$))",
    _F,
)


def _where_goes35(text: str, lexicon: Lexicon) -> str:
    """Session 35: 'S is where X goes' is 'X goes on S' when S is one surface of the scene and X
    objects only."""
    if " where " not in text:
        return text

    def plain(m: re.Match[str]) -> str:
        if not _surface_only(m["s"], lexicon) or not _things31(m["x"], lexicon):
            return m[0]
        x = m["x"]
        lead = m[0][: m.start("s") - m.start()]
        return f"{lead}{x[0].upper()}{x[1:]} goes on {m['s'].lower()}"

    return _WHERE_GOES35.sub(plain, text)


# "…, and the scanner can go along with them.": a second object to go where the first went (the
# pronoun is the first clause's objects, which have one recipient or place)
_ALONG_WITH35 = re.compile(
    rf",?\s*and (?P<x>{_DET32} [a-z][a-z ]*?) (?:can|could|should|will|may|might as well|is to) "
    r"go (?:along )?with (?P<pron>them|it)(?: too| as well)?(?P<end>\s*[.!]?)\s*$",
    _F,
)


def _along_with35(text: str, lexicon: Lexicon) -> str:
    """Session 35: the clause above is ', and X too' when X is objects of the scene only and the
    one clause before it (no other mark) names objects that the pronoun may be ('it' one object,
    'them' several or one said in the plural) and one person or surface."""
    if " with " not in text:
        return text
    m = _ALONG_WITH35.search(text)
    if m is None or not _things31(m["x"], lexicon):
        return text
    before = text[: m.start()]
    if re.search(r"[.;:!?]", before):
        return text
    objs = _ids(before, lexicon, "object")
    if len(_ids(before, lexicon, "human") | _ids(before, lexicon, "surface")) != 1 or not objs:
        return text
    words = [it.text for it in _names(before, lexicon) if it.refs[0].kind == "object"]
    plural = len(objs) > 1 or any(w.lower().endswith("s") for w in words)
    if (m["pron"].lower() == "them") != plural:
        return text
    return f"{before}, and {m['x']} too{m['end'].strip()}"


# "The teddy's fallen on the floor, put it on the play mat.": a state of the object (a closed list
# of where things lie that no request says), then the request of 'it'
_STATE_IT35 = re.compile(
    r"^(?P<x>(?:the|that|this|those|these) [a-z][a-z ]*?)(?:'s|'re| is| are|'ve| has| have) "
    r"(?:(?:fallen|dropped|rolled|tipped|slipped|been knocked|got knocked)(?: over| down| off)?"
    r"(?: (?:on|onto) the (?:floor|ground|carpet|rug))?|in (?:the|my|our|your) way|"
    r"(?:on|all over) the (?:floor|ground|carpet|rug)|under (?:my|our|your) feet)"
    r",\s*(?:so\s+)?(?P<v>put|set|pop|place|stick|move|pick|lift|give|hand|take|bring|pass)"
    r"(?P<up> up)? (?P<pron>it|them)\b",
    _F,
)


def _state_it35(text: str, lexicon: Lexicon) -> str:
    """Session 35: the state above taken off and its object said for the pronoun ('put the teddy
    on the play mat'), when X is objects of the scene only and the pronoun fits their number."""
    m = _STATE_IT35.match(text)
    if m is None or not _things31(m["x"], lexicon):
        return text
    one = len(_ids(m["x"], lexicon, "object")) == 1
    if (m["pron"].lower() == "it") != (one and not m["x"].lower().startswith(("those", "these"))):
        return text
    return f"{m['v'].capitalize()}{m['up'] or ''} {m['x'].lower()}{text[m.end() :]}"


# "Then up on the shelf with the red mug.": the placement said with the place first and the object
# after 'with' (as _what_waiting34's 'over to her with it')
_ON_WITH35 = re.compile(
    r"(?:(?<=[.;!?] )|(?<=, ))(?P<then>(?:then|and then|next|after that),? )?(?:up |down |over )?"
    r"(?P<on>on|onto|in|into|on top of) (?P<s>the [a-z][a-z ]*?) with "
    rf"(?P<x>{_DET32} [a-z][a-z ]*?)(?P<end>\s*(?:[,.;!?]|$))",
    _F,
)


def _on_with35(text: str, lexicon: Lexicon) -> str:
    """Session 35: the placement above said plainly ('Then put the red mug on the shelf') when S
    is one surface of the scene and X objects only, after a sentence mark, a comma or 'then' (an
    instruction opening with it is _onto_with33r's)."""
    if " with " not in text:
        return text

    def plain(m: re.Match[str]) -> str:
        if not _surface_only(m["s"], lexicon) or not _things31(m["x"], lexicon):
            return m[0]
        then = m["then"] or ""
        opens = not then and text[: m.start()].rstrip()[-1:] in ".;!?"
        verb = "Put" if opens else "put"
        return f"{then}{verb} {m['x']} {m['on']} {m['s']}{m['end']}"

    return _ON_WITH35.sub(plain, text)


# "The bottle. For Person A.": telegraph, the object and its recipient as sentences of their own
_TELEGRAPH35 = re.compile(
    rf"^(?P<x>{_DET32} [a-z][a-z ]*?)\.\s+(?P<for>for|to) (?P<p>[A-Z][A-Za-z]*(?: [A-Z][a-z]*)?)"
    r"\.(?=\s|$)",
    _F,
)


def _telegraph35(text: str, lexicon: Lexicon) -> str:
    """Session 35: the two sentences above are one ('The bottle for Person A.') when X is objects
    of the scene only and P one person."""
    m = _TELEGRAPH35.match(text)
    if m is None or not _things31(m["x"], lexicon) or not _only_person(m["p"], lexicon):
        return text
    return f"{m['x']} {m['for'].lower()} {m['p']}.{text[m.end() :]}"


# "… and then the warehouseman can lock up.": what someone of a trade does after the tasks (a
# closed list of doings that end a day's work), closing the instruction; no task of the cell
_THEN_TRADE35 = re.compile(
    r",?\s+and then (?:the|our|my) (?P<trade>[a-z]+) (?:can|will|could|is going to|'ll) "
    r"(?:lock up|close up|shut up shop|knock off|clock off|go home|head home|get off home|"
    r"pack up|finish up|call it a day)(?P<end>\s*[.!]?)\s*$",
    _F,
)


def _then_trade35(text: str, lexicon: Lexicon) -> str:
    """Session 35: the closing clause above taken off when the trade could only describe a person
    (_trade_words29) and what is left names something."""
    if "then " not in text:
        return text
    m = _THEN_TRADE35.search(text)
    if m is None or not _trade_words29(m["trade"], lexicon):
        return text
    rest = text[: m.start()]
    return rest + m["end"].strip() if _names(rest, lexicon) else text


# "Torch to Jess, she's under the bench, then …": where the person just named is (as
# _where_she_is34), at a surface of the scene: a person under, behind or by a surface is where
# she is, not where something goes
_BY_SURFACE35 = re.compile(
    r"(?P<p>\b[A-Z][a-z]+(?: [A-Z][a-z]*)?),? (?P<pron>she|he)(?:'s| is) (?:under|behind|beside|"
    r"by|next to|near|underneath|round the back of) (?P<s>the [a-z]+(?: [a-z]+)?)"
    r"(?=\s*,|\s+and\b|\s*[.;!?]|\s*$)"
)


def _by_surface35(text: str, lexicon: Lexicon) -> str:
    """Session 35: the remark above taken off when P is one person the pronoun may be and S one
    surface of the scene (a place the scene lacks is _where_she_is34's)."""
    if "'s " not in text and " is " not in text:
        return text

    def dropped(m: re.Match[str]) -> str:
        if not _only_person(m["p"], lexicon) or not _surface_only(m["s"], lexicon):
            return m[0]
        return m["p"] if _fits(next(iter(_ids(m["p"], lexicon))), m["pron"], lexicon) else m[0]

    return _BY_SURFACE35.sub(dropped, text)


# "the apple's meant for person b so take it over", "person a is after her bottle can you get it
# to her": a want run on into the request to carry it out, with no mark between
_WANT_RUN_ON35 = re.compile(
    r"^(?P<want>(?P<x>(?:the|that|this) [a-z]+(?: [a-z]+)?)(?:'s| is) (?:meant |intended )?for "
    r"(?P<p>person [a-z]|[a-z]+)|(?P<q>person [a-z]|[a-z]+) (?:is after|'s after|wants|needs) "
    r"(?P<y>(?:the|her|his|their) [a-z]+(?: [a-z]+)?)) (?P<then>so|can you|could you|would you)\b",
    _F,
)


def _want_run_on35(text: str, lexicon: Lexicon) -> str:
    """Session 35: a mark put after the want ('…, so take it over', '…. can you get it to her')
    when its object is objects of the scene only ('her bottle' as 'the bottle'), its person one
    person, and the request after it says 'it' or 'them' (in its own sentence: session 36, the
    lead — "Marco needs the knife so Lena can have the lemon. It's for the bake sale." had taken
    the next sentence's 'It' and read the lemon as a handover to Lena)."""
    m = _WANT_RUN_ON35.match(text)
    if m is None or not re.search(r"\b(?:it|them)\b", re.split(r"[.;!?]", text[m.end() :])[0], _F):
        return text
    x = m["x"] or re.sub(r"^(?:her|his|their)\b", "the", m["y"], flags=_F)
    if not _things31(x, lexicon) or not _only_person(m["p"] or m["q"], lexicon):
        return text
    mark = ", " if m["then"].lower() == "so" else ". "
    want = re.sub(r" (?:meant|intended) for ", " for ", m["want"], flags=_F)  # as _idioms34
    return f"{want}{mark}{m['then']}{text[m.end() :]}"


# "wipes to grandad, lily needs changing": a closing remark of the person's care (a closed list),
# which asks the cell nothing
_CARE35 = re.compile(
    r",\s*(?P<p>[A-Za-z][a-z]*(?: [A-Za-z][a-z]*)?) (?:needs|wants|is due|'s due|is ready for|"
    r"'s ready for) (?:changing|a change|feeding|a feed|winding|burping|a nap|a sleep|a wash|"
    r"a bath|settling|his nap|her nap|his bath|her bath)(?P<end>\s*[.!]?)\s*$",
    _F,
)


def _care35(text: str, lexicon: Lexicon) -> str:
    """Session 35: the remark above taken off when P is one person of the scene and what is left,
    one sentence, names a person or surface."""
    if "," not in text:
        return text
    m = _CARE35.search(text)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    rest = text[: m.start()]
    if re.search(r"[.;:!?]", rest) or not _ids(rest, lexicon, "human") | _ids(
        rest, lexicon, "surface"
    ):
        return text
    return rest + m["end"].strip()


# "Person B's having the apple and the cup with her draughts game.": what the person will be
# doing when she has them (a closed list of meals and pastimes), closing the instruction
_WITH_HER35 = re.compile(
    r"\b(?P<want>(?P<p>[A-Za-z][a-z]*(?: [A-Za-z][a-z]*)?)(?:'s| is) having (?P<x>(?:the|that|"
    r"this|those|these) [a-z][a-z ]*?)) with (?P<pron>her|his|their) (?:[a-z]+ )?(?:game|match|"
    r"tea|lunch|dinner|breakfast|supper|snack|elevenses|crossword|sudoku|puzzle|jigsaw|knitting|"
    r"book|film|show|programme)(?P<end>\s*[.!]?)\s*$",
    _F,
)


def _with_her35(text: str, lexicon: Lexicon) -> str:
    """Session 35: 'with her <game>' above taken off when P is one person the pronoun may be and
    X objects of the scene only."""
    if " having " not in text:
        return text
    m = _WITH_HER35.search(text)
    if m is None or not _only_person(m["p"], lexicon) or not _things31(m["x"], lexicon):
        return text
    if m["pron"].lower() != "their" and not _fits(
        next(iter(_ids(m["p"], lexicon))), m["pron"], lexicon
    ):
        return text
    return text[: m.start()] + m["want"] + m["end"].strip()


# "Kick off with the chips for Person A, and follow up with the bottle for Person B.": the order
# said with a closed list of openers and followers
_KICK_OFF35 = re.compile(
    r"^(?:kick off|lead off|open|get going|get started) with (?P<task>[^,.;!?]+?)"
    r"(?P<sep>,?\s+(?:and )?)(?:follow (?:up|on|that up|it up)|finish (?:off|up)|round (?:off|it "
    r"off)) with (?P<next>[^,.;!?]+?)(?P<end>\s*[.!]?)\s*$",
    _F,
)


def _kick_off35(text: str, lexicon: Lexicon) -> str:
    """Session 35: the instruction above is 'X for P first, and after that Y for Q' when each
    task is objects and one person joined by 'for' or 'to'."""
    m = _KICK_OFF35.match(text)
    if m is None:
        return text
    for task in (m["task"], m["next"]):
        what, to, who = task.partition(" for ") if " for " in task else task.partition(" to ")
        if not to or not _things31(what, lexicon) or not _only_person(who, lexicon):
            return text
    return f"{m['task']} first, and after that {m['next']}{m['end'] or '.'}"


# "Would the shelf be a better home for the crisps? Pop them up there, ta.": the place asked about,
# then the placement of 'them' 'there'
_BETTER_HOME35 = re.compile(
    r"^(?:would|wouldn't|might|could) (?P<s>the [a-z][a-z ]*?) (?:be|make) a (?:better|good|nice|"
    r"decent|safer|tidier) (?:home|place|spot|resting place) for (?P<x>(?:the|that|this|those|"
    r"these) [a-z][a-z ]*?)\s*\?\s+(?:so\s+)?(?:pop|put|stick|place|set|pop|move) (?P<pron>it|them)"
    r"(?: up| down| over)? there\b",
    _F,
)


def _better_home35(text: str, lexicon: Lexicon) -> str:
    """Session 35: the question and the placement above are 'Put X on S' when S is one surface of
    the scene, X objects only and the pronoun fits their number."""
    m = _BETTER_HOME35.match(text)
    if m is None or not _surface_only(m["s"], lexicon) or not _things31(m["x"], lexicon):
        return text
    plural = len(_ids(m["x"], lexicon, "object")) > 1 or m["x"].lower().endswith("s")
    if (m["pron"].lower() == "them") != plural:
        return text
    return f"Put {m['x']} on {m['s']}{text[m.end() :]}"


# "is it alright to send her off with the cup and the chips?": leave asked to give her them
_SEND_OFF35 = re.compile(
    r"\bis it (?:alright|all right|ok|okay|fine) (?:to|if (?:i|we|you)) send (?P<p>her|him|them|"
    r"[A-Z][a-z]+(?: [A-Z][a-z]*)?) (?:off|away|home) with "
    rf"(?P<x>{_DET32} [a-z][a-z ]*?)(?P<end>\s*\?)\s*$",
    _F,
)
# "How about letting Person A have the chips, what do you say?": the hearer asked whether it suits
_WHAT_SAY35 = re.compile(
    r",\s*(?:what do you say|what d'you say|what say you|what do you reckon|what d'you reckon|"
    r"how does that sound|sound good|sound ok|sound okay)\s*\?\s*$",
    _F,
)


def _questions35(text: str, lexicon: Lexicon) -> str:
    """Session 35: 'is it alright to send her off with X?' is 'can you give her X?' (X objects
    only, her one person of the sentence before or named); ', what do you say?' closing a
    'how about'/'what about' question is taken off."""
    m = _SEND_OFF35.search(text)
    if m is not None and _things31(m["x"], lexicon):
        who = m["p"]
        if who.lower() in ("her", "him", "them"):
            people = _ids(text[: m.start()], lexicon, "human")
            ok = len(people) == 1 and _fits(next(iter(people)), who, lexicon)
        else:
            ok = _only_person(who, lexicon)
        if ok:
            text = f"{text[: m.start()]}can you give {who} {m['x']}?"
    m = _WHAT_SAY35.search(text)
    if m is not None and re.match(r"^(?:how|what) about\b", text, _F):
        text = text[: m.start()] + "?"
    return text


# "Emma's just a visitor, but can she have the banana?": who the person is (a word for a role), then
# the request of her by pronoun
_JUST_A35 = re.compile(
    r"^(?P<p>[A-Z][a-z]+(?: [A-Z][a-z]*)?)(?:'s| is) (?:just|only|merely) an? (?P<role>[a-z]+),?"
    r"\s+but (?P<ask>can|could|may) (?P<pron>she|he) (?P<rest>have|get|take) ",
    _F,
)
# "Would you pop the red pen into the box, Priya's having a tidy-up?": what a person is doing, of a
# closed list, closing the request
_HAVING_A35 = re.compile(
    r",\s*(?P<p>[A-Z][a-z]+(?: [A-Z][a-z]*)?)(?:'s| is) having a (?:tidy-up|tidy up|tidy|"
    r"clear-out|clear out|sort-out|sort out|break|nap|lie-down|lie down|rest|day off)"
    r"(?P<end>\s*[.!?]?)\s*$",
    _F,
)
# "Can Jess take the hammer and the screws?": the whole question, of a person and objects only
_CAN_P_TAKE35 = re.compile(
    r"^(?P<ask>can|could|may) (?P<p>[A-Z][a-z]+(?: [A-Z][a-z]*)?) take "
    rf"(?P<x>{_DET32} [a-z][a-z ]*?)\s*\?\s*$",
    _F,
)


def _role35(m: re.Match[str], lexicon: Lexicon) -> bool:
    """Whether ``m``'s role could only describe a person (_trade_words29) or is a name of its
    person P alone ('Emma's just a visitor' where the scene calls Emma the visitor), and its
    pronoun may be P."""
    who = _ids(m["p"], lexicon, "human")
    if not (_trade_words29(m["role"], lexicon) or _ids(m["role"], lexicon) == who):
        return False
    return _fits(next(iter(who)), m["pron"], lexicon)


def _who_she_is35(text: str, lexicon: Lexicon) -> str:
    """Session 35: 'P's just a <role>, but can she have X?' is 'Can P have X?' (P one person the
    pronoun may be, the role a word that could only describe a person); ', P's having a tidy-up'
    closing a request is taken off (P one person); 'Can P take X?' alone is 'Can P have X?' (X
    objects only: no place or other person is said, so P is to get them)."""
    m = _JUST_A35.match(text)
    if m is not None and _only_person(m["p"], lexicon) and _role35(m, lexicon):
        text = f"{m['ask'].capitalize()} {m['p']} {m['rest']} {text[m.end() :]}"
    m = _HAVING_A35.search(text)
    if m is not None and _only_person(m["p"], lexicon):
        rest = text[: m.start()]
        if not re.search(r"[.;:!?]", rest) and _names(rest, lexicon):
            text = rest + m["end"].strip()
    m = _CAN_P_TAKE35.match(text)
    if m is not None and _only_person(m["p"], lexicon) and _things31(m["x"], lexicon):
        text = f"{m['ask'].capitalize()} {m['p']} have {m['x']}?"
    return text


# "… and Person B on the bottle so get those sorted and then you can have a rest": the hearer told
# to see to the wants just said (as _do_that34's 'so do that too'), with a rest offered after it
_GET_SORTED35 = re.compile(
    r",?\s+so (?:get|have) (?P<pron>those|them|these|that|it) (?:sorted|sorted out|seen to|done)"
    r"(?: for (?:me|us|them))?(?:,? and then you can have a (?:rest|break|breather|sit down|"
    r"cuppa))?(?P<end>\s*[.!]?)\s*$",
    _F,
)
_WANTED35 = re.compile(
    r"\b(?:wants|needs|is after|'s after|is waiting on|is waiting for|would like|could use)\b", _F
)


def _get_sorted35(text: str, lexicon: Lexicon) -> str:
    """Session 35: the closing part above taken off when what is left, one sentence, says a want
    (and names no surface: nothing is placed) and the pronoun fits the number of its objects."""
    if "so " not in text:
        return text
    m = _GET_SORTED35.search(text)
    if m is None:
        return text
    rest = text[: m.start()]
    if re.search(r"[.;:!?]", rest) or not _WANTED35.search(rest) or _ids(rest, lexicon, "surface"):
        return text
    objs = _ids(rest, lexicon, "object")
    if not objs or (len(objs) > 1) != (m["pron"].lower() in ("those", "them", "these")):
        return text
    return rest + m["end"].strip()


# "Quick one, just circling back: can we action getting the stapler over to Priya?": office speech,
# 'action' before the doing
_ACTION_DOING35 = re.compile(r"\b(?P<ask>can|could) (?:we|you) action (?P<v>[a-z]+)ing\b", _F)


def _office35(text: str, lexicon: Lexicon) -> str:
    """Session 35: 'can we action getting X …' is 'can you get X …' when the words after it name
    something."""
    m = _ACTION_DOING35.search(text)
    if m is None or not _names(text[m.end() :], lexicon):
        return text
    return f"{text[: m.start()]}{m['ask']} you {_base(m['v'])}{text[m.end() :]}"


# "Mr Lee hasn't had his pills, take them over, …": what the person has not yet had (his own, a
# closed list of such negated states), then the handover of it with no recipient said
_NOT_HAD35 = re.compile(
    r"^(?P<p>[A-Z][a-z]+(?: [A-Z][a-z]*)?) (?:hasn't|has not|hasn't yet|has not yet) (?:had|got|"
    r"been given|received) (?P<pron>his|her|their) (?P<x>[a-z]+(?: [a-z]+)?),\s*"
    r"(?P<v>take|bring|carry|pop) (?P<it>them|it) over\b",
    _F,
)


def _not_had35(text: str, lexicon: Lexicon) -> str:
    """Session 35: the two clauses above are 'Take X over to P' when P is one person the pronoun
    may be, X objects of the scene only, and 'it'/'them' fits their number (the negation is of the
    state, which the handover ends: no task is negated)."""
    m = _NOT_HAD35.match(text)
    if m is None or not _only_person(m["p"], lexicon) or not _things31(f"the {m['x']}", lexicon):
        return text
    if m["pron"].lower() != "their" and not _fits(
        next(iter(_ids(m["p"], lexicon))), m["pron"], lexicon
    ):
        return text
    plural = len(_ids(m["x"], lexicon, "object")) > 1 or m["x"].lower().endswith("s")
    if (m["it"].lower() == "them") != plural:
        return text
    return f"{m['v'].capitalize()} the {m['x']} over to {m['p']}{text[m.end() :]}"


# "Very good of you, really, …", "That's kind of you, …": a courtesy opening the instruction
_GOOD_OF_YOU36 = re.compile(
    r"^(?:(?:that's|that is|it's|it is|how|so|very|really|ever so|too) )*(?:kind|good|nice|"
    r"sweet|decent|lovely|thoughtful|generous) of you(?:,\s*(?:really|truly|honestly))?\s*[,.!]\s*",
    _F,
)
# "Quick favour before my flamenco lesson: …": a favour asked for, before the speaker's own
# doing (a closed list of what the speaker goes to), opening the instruction before a colon
_FAVOUR36 = re.compile(
    r"^(?:a |one )?(?:quick|small|little|tiny|wee) favou?r(?: to ask)?(?: (?:before|ahead of) my "
    r"(?:(?P<act>[a-z]+(?: [a-z]+)?) )?(?:lesson|class|practice|rehearsal|session|shift|"
    r"appointment|"
    r"match|game|run|swim|walk|meeting))?\s*:\s*",
    _F,
)
# "…, and thanks a million from the whole ballet class.": thanks from a group the scene lacks
_THANKS_GROUP36 = re.compile(
    r",\s*(?:and\s+)?(?:thanks|thank you|cheers|many thanks)(?: a million| a bunch| a lot| very "
    r"much| so much| loads)? from (?:the whole|all the|all of the|everyone in the|everyone at the|"
    r"the) (?P<what>[a-z]+ )?(?:class|club|team|group|crew|choir|band|troupe|squad|gang|lot|"
    r"staff|family)(?P<end>\s*[.!]?)\s*$",
    _F,
)
# "Much obliged if you'd get the bottle to Person A": a request said as the speaker's thanks
_OBLIGED36 = re.compile(
    r"^(?:much obliged|most obliged|(?:I'd|I would|I'll|I will|we'd|we would) be (?:much |most |"
    r"very |ever so )?obliged) if you(?:'d| would| could)(?: kindly)? (?=[a-z])",
    _F,
)


# "Do you think you could manage the bottle over to Person A?": 'could you manage' (_carried32)
_THINK_MANAGE36 = re.compile(
    r"^(?:do you think|d'you think|do you reckon|you think|I wonder if|I wonder whether) you "
    r"(?P<ask>could|can) manage (?=[a-z])",
    _F,
)
# "laying the small spanner out on the workbench": 'out' of laying out, before the surface
_LAID_OUT36 = re.compile(
    rf"\b(?P<v>lay|laying|set|setting|spread|spreading|put|putting) (?P<x>{_DET32} [a-z][a-z ]*?)"
    r" out (?P<on>on|onto|upon|across) (?P<s>the [a-z]+(?: [a-z]+)?)(?=\s*(?:[,.;!?]|$))",
    _F,
)
# "Is there any chance of the bottle for Person B?": asks for the object to go to the person
_ANY_CHANCE36 = re.compile(
    rf"^(?:is there )?any chance of (?P<x>{_DET32} [a-z][a-z ]*?) (?:for|going to|going over to|"
    r"over to|to) (?P<p>[A-Z][a-z]+(?: [A-Z][a-z]*)?)(?=\s*[,?])",
    _F,
)


def _asked36(text: str, lexicon: Lexicon) -> str:
    """Session 36: the question frames above said plainly: 'could you manage' after 'do you
    think', 'lay X out on S' as 'lay X on S' (X objects only, S one surface), 'is there any chance
    of X for P' as 'X for P' (X objects only, P one person)."""
    m = _THINK_MANAGE36.match(text)
    if m is not None:
        text = f"{m['ask'].capitalize()} you manage {text[m.end() :]}"
    if " out " in text:
        text = _LAID_OUT36.sub(
            lambda m: (
                f"{m['v']} {m['x']} {m['on']} {m['s']}"
                if _things31(m["x"], lexicon) and _surface_only(m["s"], lexicon)
                else m[0]
            ),
            text,
        )
    m = _ANY_CHANCE36.match(text)
    if m is not None and _things31(m["x"], lexicon) and _only_person(m["p"], lexicon):
        x = m["x"]
        text = f"{x[0].upper()}{x[1:]} for {m['p']}{text[m.end() :]}"
    return text


# "Would you put the banana on the tray so nobody sits on it?": why it goes there, said of
# others (a closed list of what someone might do to it where it lies)
_SO_NOBODY36 = re.compile(
    r"(?:,\s*|\s+)so (?:that )?(?:nobody|no one|no-one) (?:sits|steps|treads|stands|trips|kneels|"
    r"leans|sits down|knocks|falls) (?:on|over|in|onto) (?P<pron>it|them)(?P<end>\s*[.!?]?)\s*$",
    _F,
)
# "… in the plate rack with the others": the place already holds others of the object's kind
_WITH_OTHERS36 = re.compile(
    r"(?P<place>\b(?:on|onto|in|into) (?P<s>the [a-z]+(?: [a-z]+)?)) with the (?:others|other "
    r"ones)(?P<end>\s*[.!?]?)\s*$",
    _F,
)


def _why_placed36(text: str, lexicon: Lexicon) -> str:
    """Session 36: after a placement of one object, 'so nobody sits on it' (the pronoun of the
    object's number) taken off; 'on S with the others' is 'on S' when S holds another object of
    the placed object's category where the scene starts."""
    m = _SO_NOBODY36.search(text)
    if m is not None:
        objs = _ids(text[: m.start()], lexicon, "object")
        if (
            len(objs) == 1
            and m["pron"].lower() == "it"
            and _ids(text[: m.start()], lexicon, "surface")
        ):
            text = text[: m.start()] + m["end"].strip()
    m = _WITH_OTHERS36.search(text)
    if m is None or not _surface_only(m["s"], lexicon):
        return text
    objs = _ids(text[: m.start()], lexicon, "object")
    if len(objs) != 1:
        return text
    (x,) = objs
    cat = next(o.category for o in lexicon.scene.objects if o.id == x)
    same = {o.id for o in lexicon.scene.objects if o.category == cat and o.id != x}
    s = next(iter(_ids(m["s"], lexicon, "surface")))
    if not same or not starting_on(same, s, lexicon) or starting_on({x}, s, lexicon):
        return text
    return text[: m.end("place")] + m["end"].strip()


# closing remarks of a closed list, naming nothing and asking nothing: "…, rough poker night",
# "…, its porridge oclock", "… thx hes the one back from surfing"
_ROUGH_NIGHT36 = re.compile(
    r"(?:rough|long|hard|tough|busy|late|heavy|mad|crazy|rotten) (?P<what>[a-z]+ )?"
    r"(?:night|day|shift|week|weekend)",
    _F,
)
_OCLOCK36 = re.compile(r"(?:it's|its|it is) (?P<what>[a-z]+) (?:o'clock|oclock|o clock|time)", _F)
_BACK_FROM36 = re.compile(
    r"(?P<lead>\s+(?:(?:thx|thanks|ta|cheers),?\s+)?|,\s*)(?P<pron>he|she)(?:'s|s| is) the one "
    r"(?:just )?(?:back from|home from|in from|off to|back off) (?P<what>[a-z]+(?: [a-z]+)?)"
    r"(?P<end>\s*[.!]?)\s*$",
    _F,
)


# "snack time so its apple for person a and chips for person b": the time of day named by what
# it is time for, then 'so it's' before the request
_TIME_SO36 = re.compile(r"^(?P<what>[a-z]+) (?:time|o'clock|oclock),? so (?:it's|its|it is) ", _F)
# "tom needs the scanner for the last van of the day": what the object is needed for, closing
_FOR_THE_LAST36 = re.compile(
    r"\s+for the (?:first|last|next|early|late|morning|afternoon|evening|night) (?P<n>[a-z]+)"
    r"(?: of the (?:day|night|week|shift|morning|afternoon|evening))?(?P<end>\s*[.!]?)\s*$",
    _F,
)
_TIME_NOUNS36 = frozenset(
    {
        "day", "night", "week", "month", "year", "hour", "minute", "time", "moment", "while",
        "bit", "morning", "afternoon", "evening", "weekend", "shift", "round", "go", "turn",
    }
)  # fmt: skip


# "The bottle's been asked for by Person B, who runs …, and …": the want said in the passive
_ASKED_BY36 = re.compile(
    rf"^(?P<x>{_DET32} [a-z][a-z ]*?)(?:'s| has|'ve| have) been (?:asked for|requested|ordered|"
    r"bagged|claimed|put aside) by (?P<p>[A-Z][a-z]+(?: [A-Z][a-z]*)?)(?P<aside>,\s*who [^,]+,)?",
    _F,
)
# "The sink is where the green cup ought to be": 'should be' (_where_goes35)
_WHERE_OUGHT36 = re.compile(
    rf"\bis where (?P<x>{_DET32} [a-z][a-z ]*?) (?:ought to|has to|must|wants to) (?P<v>be|go)\b",
    _F,
)
# "…, the aquarist left it out", "The coalman left the crisps out, so …": someone of a trade
# left the object out (where it should not be)
_LEFT_OUT36 = re.compile(
    r"(?P<lead>,\s*)(?:the|our|my) (?P<trade>[a-z]+) (?:left|got|took|has left|'s left) "
    r"(?P<pron>it|them) out(?P<end>\s*[.!]?)\s*$",
    _F,
)
_LEFT_X_OUT36 = re.compile(
    rf"^(?:the|our|my) (?P<trade>[a-z]+) (?:left|got|took|has left|'s left) (?P<x>{_DET32} "
    r"[a-z][a-z ]*?) out,\s*so (?P<req>.+)$",
    _F,
)


def _plural36(x: str, lexicon: Lexicon) -> bool:
    return len(_ids(x, lexicon, "object")) > 1 or x.lower().endswith("s")


def _wants_said36(text: str, lexicon: Lexicon) -> str:
    """Session 36: 'X has been asked for by P' is 'P wants X' (X objects only, P one person);
    'S is where X ought to be' is 'should be'; a closing '…, the <trade> left it out' taken off
    (the trade could only describe a person, the pronoun of the objects' number); 'The <trade>
    left X out, so <request>' is the request, its first pronoun of X's number said as X."""
    m = _ASKED_BY36.match(text)
    if m is not None and _things31(m["x"], lexicon) and _only_person(m["p"], lexicon):
        x = m["x"][0].lower() + m["x"][1:]
        text = f"{m['p']}{m['aside'] or ''} wants {x}{text[m.end() :]}"
    text = _WHERE_OUGHT36.sub(
        lambda m: f"is where {m['x']} should {m['v']}" if _things31(m["x"], lexicon) else m[0], text
    )
    m = _LEFT_OUT36.search(text)
    if m is not None and _trade_words29(m["trade"], lexicon):
        objs = _ids(text[: m.start()], lexicon, "object")
        if objs and (m["pron"].lower() == "them" or len(objs) == 1):
            text = text[: m.start()] + m["end"].strip()
    m = _LEFT_X_OUT36.match(text)
    if m is not None and _trade_words29(m["trade"], lexicon) and _things31(m["x"], lexicon):
        pron = "them" if _plural36(m["x"], lexicon) else "it"
        req = re.sub(rf"\b{pron}\b", m["x"].lower(), m["req"], count=1, flags=_F)
        if req != m["req"]:
            text = req[0].upper() + req[1:]
    return text


# "Person A could use the chips to keep her going at the bonsai show": why the person wants it
_KEEP_GOING36 = re.compile(
    r"\s+to keep (?P<pron>her|him|them) going(?: (?:at|through|during|till|until|for|on) "
    r"(?P<what>(?:the|her|his|their) [a-z]+(?: [a-z]+)?))?(?=\s*(?:[,.;!?]|$))",
    _F,
)
_SUBJECT36 = re.compile(
    r"(?:^|[,;.]\s*(?:and\s+)?|\band\s+)(?P<p>[A-Z][a-z]+(?: [A-Z][a-z]*)?) (?:could use|could do "
    r"with|needs|wants|would like|would love|'d like|'d love|is after|'s after) [^,;.]*$"
)


# "Person B's to have the apple, and he'll want the cup with it.": a second object for the one
# person before, said by a pronoun that may be them
_WANT_WITH36 = re.compile(
    rf",?\s*and (?P<pron>he|she)(?:'ll| will) (?:want|need|have|be wanting) (?P<x>{_DET32} "
    r"[a-z][a-z ]*?)(?: with (?:it|them)| too| as well)(?P<end>\s*[.!]?)\s*$",
    _F,
)


# a remark about a person run on with no mark before a comma or a new clause (as
# _run_on_remark26 at the end): "Person A wants the bottle she's been at kickboxing, and …",
# "Person B gets the bottle he's been waiting ages Person A gets the chips …"
_RUN_ON_MID36 = re.compile(
    r"(?<![,.;:!?])\s+(?P<r>(?:he|she)(?:'s| has) been [a-z' ]+?)"
    r"(?=\s*[,;]|\s+(?:Person [A-Z]|[A-Z][a-z]+) (?:gets|wants|needs|is having|'s having|has)\b)",
)

# what a person's been doing that is a want ("she's been craving", "he's been after")
_WANTING36 = re.compile(
    r"\b(?:crav\w*|dying|gasping|desperate|asking|after|on about|wanting|needing|hoping|keen|"
    r"itching|begging|waiting (?:for|on)|angling|eyeing|hankering|pining|longing)\b",
    _F,
)


# "…; give them those when you've got a hand free", "… and Alice wants the crisps give them
# those": the wants said before, asked for again by pronouns
_GIVE_THEM_THOSE36 = re.compile(
    r"(?:\s*[;,.]\s*|\s+)(?:so |then |just |now )?(?:give|hand|bring|take) (?:them|'em) "
    r"(?:those|these|them|what they want|their things)(?: (?:when you(?:'ve| have) got a "
    r"(?:hand|minute|moment|sec|second) (?:free|spare)|when you get a (?:chance|minute|moment)|"
    r"when you can|when you're free))?(?P<end>\s*[.!]?)\s*$",
    _F,
)
_WANTS36 = re.compile(
    r"\b(?:wants|needs|gets|is having|'s having|would like|fancies|is after|'s after)\b", _F
)


def _give_them_those36(text: str, lexicon: Lexicon) -> str:
    """Session 36: 'give them those' closing a sentence of wants of two or more people (every
    clause a want: a verb of wanting, no other verb of the grammar) taken off."""
    if "them" not in text and "'em" not in text:
        return text
    m = _GIVE_THEM_THOSE36.search(text)
    if m is None:
        return text
    before = text[: m.start()]
    if len(_ids(before, lexicon, "human")) < 2 or not _WANTS36.search(before):
        return text
    rest = _WANTS36.sub(" ", re.sub(r"\b(?:and|the)\b", " ", before, flags=_F))
    if any(w in VERBS for w in re.findall(r"[a-z]+", rest.lower())) or _KEEP_WORDS.search(rest):
        return text
    return before + m["end"].strip()


# "Marco's lost his tongs, get them to him, would you.", "The scissors are Noah's, so bring them
# over to him.": whose the object is, then the request by pronouns
_LOST_HIS36 = re.compile(
    r"^(?P<p>[A-Z][a-z]+(?: [A-Z][a-z]*)?)(?:'s| has) (?:lost|forgotten|mislaid|misplaced|dropped|"
    r"left) (?P<pos>his|her|their) (?P<x>[a-z][a-z ]*?),\s*(?:so\s+)?(?P<req>.+)$",
)
_ARE_WHOSE36 = re.compile(
    rf"^(?P<x>{_DET32} [a-z][a-z ]*?) (?:are|is|'s|belongs? to) (?P<p>[A-Z][a-z]+(?: [A-Z][a-z]*)?)"
    r"(?:'s)?,\s*so (?P<req>.+)$",
    _F,
)


# "…: the bottle to her first, then the chips, also hers.": the last object's person said again
# when every step before goes to that one person
_ALSO_HERS36 = re.compile(
    r",\s*(?:also|again|likewise) (?P<pron>hers|his|theirs)(?P<end>\s*[.!]?)\s*$", _F
)


# "Grey blanket. Mr Lee. His feet are like ice.": how the person is (a closed list of a body's
# state), a sentence of its own after the request to that person
_BODY36 = re.compile(
    r"(?:^|(?<=[.!?])\s+|,\s*)(?P<pron>His|Her|his|her) (?:feet|hands|toes|fingers|nose|ears|"
    r"hands and feet|feet and hands) (?:are|is|'re) (?:like ice|like blocks of ice|freezing|"
    r"frozen|icy|cold|perishing|numb)(?P<end>\s*[.!]?)\s*$",
)


# "Apple to Person A. Cup to Person B. Chips stay put.": an object the request does not name
# stays where it is (a sentence of its own, after the request)
_STAY_PUT36 = re.compile(
    rf"(?:^|(?<=[.!?])\s+)(?P<x>(?:{_DET32} )?[A-Za-z][a-z]*(?: [a-z]+)?) (?:stays?|remains?) "
    r"(?:put|where (?:it is|they are))(?P<end>\s*[.!]?)\s*$",
)


def _stay_put36(text: str, lexicon: Lexicon) -> str:
    """Session 36: 'X stays put.' closing, after a request that names objects, people or
    surfaces but not X, taken off (X objects only): leaving X is what the request does."""
    if "stay" not in text and "remain" not in text:
        return text
    m = _STAY_PUT36.search(text)
    if m is None or m.start() == 0:
        return text
    x = (
        m["x"]
        if m["x"].lower().split()[0] in ("the", "that", "this", "those", "these")
        else (f"the {m['x'].lower()}")
    )
    if not _things31(x, lexicon):
        return text
    before = text[: m.start()]
    if _ids(x, lexicon) & _ids(before, lexicon) or not _names(before, lexicon):
        return text
    if _KEEP_WORDS.search(re.sub(r"\b(?:and|the)\b", " ", before, flags=_F)):
        return text  # 'everything', 'the rest', 'it': the request may take X in
    return before.rstrip()


# "the bottles going to person b": the apostrophe of "bottle's" (is) dropped, where the scene
# has one bottle (a plural then names nothing) and no verb follows the plural
_DROPPED_IS36 = re.compile(
    r"\b(?P<det>the|that|this) (?P<x>[a-z]+)s (?=(?:going|headed|meant|gone|off|for|over|due)\b)",
    _F,
)


def _dropped_is36(text: str, lexicon: Lexicon) -> str:
    """Session 36: 'the Xs going to …' is "the X's going to …" in a text written without
    apostrophes, when 'the X' names exactly one object of the scene and 'Xs' is only its name
    said plural (no name of its own)."""
    if "s " not in text or "'" in text or "’" in text:
        return text  # a text that writes its apostrophes means the plural it says

    def mended(m: re.Match[str]) -> str:
        one, many = _names(f"the {m['x']}", lexicon), _names(f"the {m['x']}s", lexicon)
        if len(one) != 1 or len(many) != 1 or len(one[0].refs) != 1 or len(many[0].refs) != 1:
            return m[0]
        (a,), (b,) = one[0].refs, many[0].refs
        if a.kind != "object" or a.id != b.id or a.plural or not b.plural:
            return m[0]  # "the chips": a name said plural, no dropped mark
        return f"{m['det']} {m['x']}'s "

    return _DROPPED_IS36.sub(mended, text)


# "…, and likewise the bottle to Person B": 'likewise' before a clause said without its verb
_LIKEWISE36 = re.compile(rf"\band likewise (?={_DET32} )", _F)
# "Bob's thirsty he wants the bottle …": the person's state run on into their want, said again
# by a pronoun that may be them (a closed list of states)
_STATE_WANTS36 = re.compile(
    r"^(?P<p>[A-Z][a-z]+(?: [A-Z][a-z]*)?)(?:'s| is) (?:thirsty|hungry|starving|peckish|parched|"
    r"famished|cold|freezing|tired|shattered) (?P<pron>he|she) (?P<v>wants|needs|would like|"
    r"fancies)\b",
    _F,
)


# "…, the bosun likes things stowed", "…, the coastguard will eat later": what someone of a
# trade likes or will do, closing (a closed list, naming nothing of the scene)
_TRADE_REMARK36 = re.compile(
    r",\s*(?:the|our|my) (?P<trade>[a-z]+) (?:(?:likes|prefers|likes to have|likes to keep) "
    r"(?:things|everything|it all|stuff) (?:stowed|tidy|neat|put away|shipshape|in order|just so|"
    r"squared away|off the floor)|(?:will|'ll|is going to) (?:eat|snack|have a snack|have lunch|"
    r"have tea|have supper) (?:later|in a bit|afterwards))(?P<end>\s*[.!]?)\s*$",
    _F,
)
# "…, kendo finishes at six": when someone's activity ends, closing
_FINISHES_AT36 = re.compile(
    r",\s*(?P<what>[a-z]+) (?:finishes|ends|starts|kicks off|is over) at (?:one|two|three|four|"
    r"five|six|seven|eight|nine|ten|eleven|twelve|[0-9]{1,2})(?: o'clock| oclock| ?[ap]m)?"
    r"(?P<end>\s*[.!]?)\s*$",
    _F,
)
# "…, and Person B, the park keeper": a trade of two words whose first is a verb of the
# grammar said as a noun (after 'the'), the second a doer's word
_TRADE_COMPOUND36 = re.compile(
    r"(?P<p>\b(?:Person [A-Z]|[A-Z][a-z]+(?: [A-Z][a-z]+)?)),\s*the (?P<w1>[a-z]+) "
    r"(?P<w2>[a-z]+(?:er|or|ist|man|woman|keeper|hand|maker))(?=\s*(?:[,.;!?]|$))"
)
# "alice first with the bottle and after that …": who goes first, and with what
_FIRST_WITH36 = re.compile(
    rf"^(?P<p>(?:person [a-z]|[a-z]+)) first with (?P<x>{_DET32} [a-z][a-z ]*?)"
    r"(?= and (?:after that|then)\b|,? then\b)",
    _F,
)


def _trade_said36(text: str, lexicon: Lexicon) -> str:
    """Session 36: the closing remarks above taken off (the trade could only describe a person,
    _trade_words29; the activity names nothing and asks nothing) when what is left names
    something; 'P, the park keeper' is 'P' (P one person, the second word a trade); 'P first
    with X and after that …' is 'P gets X first and after that …' (P one person, X objects)."""
    m = _TRADE_REMARK36.search(text)
    if m is not None and _trade_words29(m["trade"], lexicon) and _names(text[: m.start()], lexicon):
        text = text[: m.start()] + m["end"].strip()
    m = _FINISHES_AT36.search(text)
    if m is not None and _trade_words29(m["what"], lexicon) and _names(text[: m.start()], lexicon):
        text = text[: m.start()] + m["end"].strip()
    m = _TRADE_COMPOUND36.search(text)
    if (
        m is not None
        and _only_person(m["p"], lexicon)
        and m["w1"].lower() in VERBS
        and _trade_words29(m["w2"], lexicon)
    ):
        text = text[: m.end("p")] + text[m.end() :]
    m = _FIRST_WITH36.match(text)
    if m is not None and _only_person(m["p"], lexicon) and _things31(m["x"], lexicon):
        text = f"{m['p']} gets {m['x']} first{text[m.end() :]}"
    return text


# "If everyone could just wait a moment, our robot here is going to place the globe on the
# desk.": the request announced to the room (the wait asked of everyone else, opening)
_ANNOUNCED36 = re.compile(
    r"^(?:(?:if )?(?:everyone|everybody|you all|all of you) (?:could|can|would) (?:just )?(?:wait|"
    r"hold on|bear with (?:me|us)) (?:a|one) (?:moment|minute|second|sec|tick|mo),\s*)?"
    r"(?:our|the|this|my) robot(?: here| friend)? (?:is going to|'s going to|is about to|will|"
    r"'ll) (?=(?:give|hand|pass|bring|take|deliver|put|place|set|pop|move)\b)",
    _F,
)


def _announced36(text: str, lexicon: Lexicon) -> str:
    """Session 36: 'our robot (here) is going to <verb> …' (after a wait asked of everyone) is the
    request '<verb> …' (a verb of the grammar's hand-overs and placements)."""
    if "robot" not in text.lower():
        return text
    m = _ANNOUNCED36.match(text)
    if m is None:
        return text
    rest = text[m.end() :]
    return rest[0].upper() + rest[1:]


# before every other rewrite: whether the text writes apostrophes is asked of the words as said
_STEPS36_FIRST: tuple[Callable[[str, Lexicon], str], ...] = (_dropped_is36,)


# "If you'd be so good as to take the jug to Mrs Khan, that'd be grand.": a request said as a
# condition of the speaker's pleasure (asks the same as 'Would you be so good as to …?')
_IF_SO_GOOD28 = re.compile(
    r"^if you(?:'d| would)(?: be so (?:good|kind) as to| not mind| kindly)\s+(.+?),\s*"
    r"(?:that|it)(?:'d| would) be (?:grand|great|lovely|brilliant|wonderful|perfect|ace|super|"
    r"smashing|fab|fabulous|fantastic|marvellous|much appreciated|appreciated|ideal)\s*([.!]?)$",
    _F,
)


def _if_so_good28(text: str, lexicon: Lexicon) -> str:
    """Session 28: 'If you'd be so good as to X, that'd be grand' is 'X' (above), in the last
    sentence of the instruction (what came before, a greeting, kept)."""
    if not text.lower().startswith("if ") and ". if " not in text.lower():
        return text
    head, sep, last = text.rpartition(". ")
    m = _IF_SO_GOOD28.match(last)
    if m is None:
        return text
    verb = m.group(1)
    if "not mind" in m.group(0).lower():
        verb = re.sub(r"^(\w+?)ing\b", lambda v: _base(v.group(1)), verb, flags=_F)
    return f"{head}{sep}{verb}{m.group(2)}"


# "A leemon for Mr Novak": 'a' / 'an' opening the instruction before a typo of a kind the
# scene has ('leemon': lemon) — the kind spelt right, so the note reads as 'A lemon for …' does
# (_a_kind_for; the capital 'A' is otherwise Person A where the scene has one)
_A_TYPO28 = re.compile(r"^(a|an) ([a-z]{4,})(?= (?:for|to) )", _F)


def _a_typo28(text: str, lexicon: Lexicon) -> str:
    """Session 28: the kind above spelt right (one object category within one edit)."""
    m = _A_TYPO28.match(text)
    if m is None or _kind_of(m.group(2), lexicon) is not None:
        return text
    refs = lexicon.misspelt(m.group(2).lower())
    objs = {o.id: o.category for o in lexicon.scene.objects}
    kinds = {objs.get(r.id) for r in refs or ()}
    if not refs or None in kinds or len(kinds) != 1:
        return text
    return f"{m.group(1)} {kinds.pop()}{text[m.end() :]}"


# Idioms of handing over (session 28, blind26): 'put X in / into P's hand(s)' is 'give X to P';
# 'X could / can make it (over) to P' is 'X could go to P'; a header 'Both / all of the <people>
# want something:' before a list of who gets what is 'Both of them want something:' (the people
# naming nothing in the scene); and 'them' given something ('Give them the chips') after one
# person alone is named before it is that person (the singular 'they': "Person B's got nothing
# yet. Give them the chips and the bottle.").
_HANDS28 = re.compile(
    r"\b(put|place|pop|drop|stick) (.+?) (?:in|into) ([A-Za-z][\w ]*?)'s (?:hands?|palms?)\b", _F
)
_MAKE_IT28 = re.compile(r"\b(could|can|would|will) make it (?:over |across )?to\b", _F)
_SOMETHING28 = re.compile(
    r"^(both|all|each) of the ([a-z]+(?: [a-z]+)?) (wants?|needs?) something\s*:", _F
)
_OUT_OF_WAY28 = re.compile(
    r",\s*(?:(?:as|because|since|cos)\s+)?([A-Za-z][\w ]*?) (?:needs|wants|'d like|would like) "
    r"(?:it|them|those|that) out of the way(?= *[.!]?$)",
    _F,
)
_GIVE_THEM28 = re.compile(r"\b(give|hand|pass|bring|fetch|get) them (?=(?:the|a|an|both) )", _F)


def _handed28(text: str, lexicon: Lexicon) -> str:
    """Session 28: the idioms of handing over above; and a reason 'P needs / wants it / them out
    of the way' closing a request that moves something (P one person, or he / she / they)."""
    low = text.lower()
    if "out of the way" in low:
        m = _OUT_OF_WAY28.search(text)
        if m is not None and (
            m.group(1).lower() in ("he", "she", "they") or _only_person(m.group(1), lexicon)
        ):
            before = text[: m.start()]
            if _ids(before, lexicon, "object"):
                text = before + text[m.end() :]
    if " hand" in low or " palm" in low:

        def hands(m: re.Match[str]) -> str:
            if not _only_person(m.group(3), lexicon) or _ids(m.group(2), lexicon, "human"):
                return m.group(0)
            return f"give {m.group(2)} to {m.group(3)}"

        text = _HANDS28.sub(hands, text)
    if "make it" in low:
        text = _MAKE_IT28.sub(r"\1 go to", text)
    m = _SOMETHING28.match(text)
    if m is not None and _names_nothing(m.group(2), lexicon):
        text = f"{m.group(1)} of them {m.group(3)} something:{text[m.end() :]}"
    m = _GIVE_THEM28.search(text)
    if m is not None and not _rx(r"\b(?:both|each|every|all|everyone|everybody)\b").search(text):
        said = [it for it in _names(text[: m.start()], lexicon) if it.refs[0].kind == "human"]
        who = {r.id for it in said for r in it.refs}
        if len(who) == 1 and all(len(it.refs) == 1 for it in said):
            text = f"{text[: m.start()]}{m.group(1)} {said[-1].text} {text[m.end() :]}"
    return text


# 'since <a past time>' in a remark of how long someone has been at something ("she's been on
# the lathe since seven", "he is driving the fork truck since morning"): said of the past, never
# when the request is to be done; taken off when its clause has 'been' or an '-ing' verb before it
_SINCE28 = re.compile(
    r"\b((?:been|[a-z]{2,}ing)\b[^,.;!?]*?) since (?:(?:one|two|three|four|five|six|seven|eight|"
    r"nine|ten|eleven|twelve|\d{1,2}(?:[:.]\d\d)?)(?: ?(?:o'clock|am|pm|thirty))?|dawn|"
    r"(?:this |early )?morning|lunch(?:time)?|breakfast|yesterday|last (?:night|week)|"
    r"(?:mon|tues|wednes|thurs|fri|satur|sun)day|first thing|the crack of dawn)(?=\s*[,.;!?]|$)",
    _F,
)


def _since28(text: str, lexicon: Lexicon) -> str:
    """Session 28: 'since <a past time>' in a remark of how long (above), taken off."""
    if "since " not in text.lower():
        return text
    return _SINCE28.sub(
        lambda m: m.group(1) if _names_nothing(m.group(1), lexicon) else m.group(0), text
    )


# 'X and Y stay put / stay where they are / stay there': nothing to do with them (as session
# 16's 'X stays' for one object, _notes), unless another clause names them or counts every object
_STAY28 = re.compile(
    r"(?:^|(?<=[.;,])\s*)(?:and )?((?:the )?[a-z]+(?: [a-z]+)? and (?:the )?[a-z]+(?: [a-z]+)?) "
    r"(?:both )?stay(?: put| where they are| there| as they are)\s*(?=[.;,]|$)",
    _F,
)


def _stay28(text: str, lexicon: Lexicon) -> str:
    """Session 28: two objects said to stay (above) taken off."""
    if "stay" not in text.lower():
        return text
    m = _STAY28.search(text)
    if m is None:
        return text
    one, two = re.split(r" and ", m.group(1), maxsplit=1, flags=_F)
    if not (_only_kind(one, lexicon, "object") and _only_kind(two, lexicon, "object")):
        return text
    others = text[: m.start()] + text[m.end() :]
    if _ids(m.group(1), lexicon) & _ids(others, lexicon) or _rx(
        r"\b(?:everything|anything|all|the lot|the rest|every)\b"
    ).search(others):
        return text
    out = others.strip(" ,;")
    return out if _names(out, lexicon) else text


# -- session 25 (engineer 12r): blind22's kinds ----------------------------------------------------

# What a person wants or needs to do, said after the request as its reason ("Will you take the
# drill to Kofi, please, he wants to hang a mirror?", "Both plates onto the counter, Marco wants to
# plate up the goulash."): a clause closing its sentence whose subject is a person of the scene
# (or he / she / they) and whose verb is 'wants / needs / has / is going / is about' + 'to' + a
# verb that is neither one of the grammar's tasks nor of having or using, naming nothing else in
# the scene and holding no word that points back, counts, chooses, negates or orders. It says what
# the person will do themself, which asks the robots for nothing: taken off, when the request
# before it names something. ("…, he wants to keep it", "…, she needs to have the cup", "…, Bob
# wants to give it back" are not.)
_DOING25 = re.compile(
    r"\s*[,;]\s*(?:(?:and|as|because|cos|since)\s+)?((?:he|she|they|[A-Z][a-z]*(?: [A-Z][a-z]*)?)"
    r"(?:'s| is| are|'re)? (?:wants|want|needs|need|has|have|going|about) to ([a-z]+)\b"
    r"[^,.;!?]*?)\s*(?=[.!?]|$)",
)
_DOING_HELD25 = re.compile(
    r"\b(?:it|them|that|this|those|these|one|ones|other|another|rest|each|both|all|every|either|"
    r"or|and|then|first|before|after|until|once|when|if|not|no|never|nothing|instead|too|also|"
    r"me|us|you|him|her|his|their|my|your|our|mine|yours|same|again|back)\b|n't\b|\d",
    _F,
)
_DOING_VERBS25 = frozenset(
    {
        *("give", "hand", "pass", "bring", "take", "put", "place", "get", "have", "keep", "hold"),
        *("use", "fetch", "grab", "move", "send", "carry", "deliver", "leave", "drop", "pop"),
        *("set", "receive", "borrow", "eat", "drink", "try", "see", "check", "open", "be", "go"),
        *("come", "wait", "stop", "cancel", "swap", "change", "choose", "pick", "share", "say"),
        *("ask",),
    }
)


def _doing25(text: str, lexicon: Lexicon) -> str:
    """Session 25: what a person wants or needs to do, said as the request's reason, taken off
    (above)."""
    if not _rx(r"\b(?:wants?|needs?|has|have|going|about) to\b").search(text):
        return text
    for m in reversed(list(_DOING25.finditer(text))):
        clause, verb = m.group(1), m.group(2).lower()
        subject = clause[: clause.lower().index(" to ")].rsplit(" ", 1)[0]
        subject = re.sub(r"(?:'s|'re| is| are)$", "", subject, flags=_F)
        who = _names(subject, lexicon)
        person = subject.lower() in ("he", "she", "they") or (
            len(who) == 1
            and all(r.kind == "human" for r in who[0].refs)
            and who[0].text.lower() == subject.lower()
        )
        rest = clause[len(subject) :]
        before = text[: m.start()]
        if (
            not person
            or verb in _DOING_VERBS25
            # session 40 (12): the posture verbs the lexicon took in then ('he wants to hang a
            # mirror') are taken off as before, naming nothing of the scene
            or (verb in VERBS and VERBS[verb] not in ("stand", "hang", "sit"))
            or _DOING_HELD25.search(rest)
            or not _names_nothing(rest, lexicon)
            or not _names(re.split(r"[.!?]\s", before)[-1], lexicon)
        ):
            continue
        text = before + text[m.end() :]
    return text


# -- session 24: blind22's kinds -----------------------------------------------------------------

# Greetings, thanks, blessings and polite particles of other languages that speakers of English
# as a second language (or of a faith) open and close requests with. The list is by KIND, one
# line per kind, each word a courtesy in its language that asks for nothing; a stretch between
# punctuation marks made only of them (with an address such as 'my friend', 'sir', 'boss') is
# taken off when what is left names something. docs/grounding.md, "Session 24", lists them.
_COURTESY24 = (
    # greetings
    r"habari(?: yako| gani)?|jambo|hujambo|sawasdee|sawatdee|sawasdi|dobryi den|dobryy den|"
    r"dobry den|dobriy den|pryvit|vitayu|selamat (?:pagi|petang|siang|malam|datang)|apa khabar|"
    r"merhaba|yassou|yassas|geia sou|xin chao|kumusta|kamusta|magandang (?:umaga|hapon|gabi)|"
    r"namaste|namaskar|salaam|salam|as-?salaamu? alaikum|shalom|hola|bonjour|ciao|konnichiwa|"
    r"ni hao|kia ora|sawubona|ahoj|"
    # thanks
    r"asante(?: sana)?|khop khun(?: mak)?|khob khun(?: mak)?|kop khun|diakuiu|dyakuyu|diakuyu|"
    r"spasibo|terima kasih|salamat|tesekkurler|efharisto|efcharisto|cam on|dhanyavaad|"
    r"dhanyavad|shukriya|shukran|gracias|merci(?: beaucoup)?|grazie(?: mille)?|danke(?: schon)?|"
    r"arigato(?: gozaimasu)?|xie xie|obrigado|obrigada|dziekuje|diolch|toda|kiitos|"
    # session 25: Persian, Indonesian, Hungarian thanks and greetings, Indonesian 'that's all'
    # and 'as you like' and its address 'Mas', Jamaican blessings ('please' and 'sorry' of
    # other languages are read as those words: _translated25)
    r"mamnoon|mamnun|khahesh mikonam|terima kasih banyak|makasih|köszönöm|koszonom|"
    r"köszi|koszi|jó napot(?: kívánok)?|jo napot(?: kivanok)?|szia|permisi|sudah|terserah|"
    r"mas|mbak|bless up|big up|respect|one love|"
    # session 26: Czech, Romanian, Tamil and Ghanaian greetings, thanks and the address 'chale'
    # (friend), with and without their letters' marks ('please' in them: _translated25)
    r"dobrý den|dobry den|děkuji|dekuji|děkuju|dekuju|bună ziua|buna ziua|bună|mulțumesc|"
    r"mulţumesc|multumesc|mersi(?: mult)?|vanakkam|vanakam|nandri|nanri|chale|medaase|akwaaba|"
    # session 27: Georgian, Lithuanian, Amharic and Sinhala greetings, thanks and the Georgian
    # address 'genatsvale' (dear), with and without their letters' marks; then those of other
    # languages no part had yet (Latvian, Estonian, Armenian, Azerbaijani, Serbian and Croatian,
    # Polish, Russian, Bulgarian, Scandinavian, Dutch, Korean, Burmese, Nepali, Bengali, Punjabi,
    # Hausa, Igbo, Zulu, Xhosa, Hawaiian, Hebrew, Arabic, Turkish, Portuguese, Spanish)
    r"gamarjoba(?:t)?|(?:didi )?madloba|genatsvale|nakhvamdis|"
    r"labas(?: rytas| vakaras)?|laba diena|ačiū(?: labai)?|aciu(?: labai)?|"
    r"tena yistilign|tena yistiligne|tena yistilgn|selam(?: new)?|"
    r"(?:betam )?(?:ameseginalehu|amesegnalehu|ameseginalew)|"
    r"ayubowan|(?:bohoma )?(?:sthuthi|sthuthiy|stuthi|isthuthi|istuti)|"
    r"labdien|paldies|sveiki|tere|aitäh|aitah|tänan|tanan|barev(?: dzez)?|shnorhakalutyun|"
    r"sağ ?ol|sag ?ol|çox sağ ?ol|chox sag ?ol|hvala(?: lijepa| puno| vam)?|zdravo|dobar dan|"
    r"dzień dobry|dzien dobry|cześć|czesc|dziękuję|privet|zdravstvuyte|blagodaryu|blagodarya|"
    r"tack(?: så mycket| sa mycket)?|takk|tusen takk|mange tak|hej|hei|dank je(?: wel)?|"
    r"dank u(?: wel)?|bedankt|goedemorgen|goedemiddag|annyeonghaseyo|annyeong|kamsahamnida|"
    r"gamsahamnida|gomawo|mingalaba|mingalarba|dhanyabad|dhonnobad|nomoskar|sat sri akal|"
    r"sannu|na gode|daalu|ndewo|ngiyabonga|siyabonga|enkosi|mahalo(?: nui)?|aloha|toda raba|"
    r"marhaba|ahlan(?: wa sahlan)?|teşekkür ederim|tesekkur ederim|olá|bom dia|"
    r"buenos (?:días|dias)|buenas tardes|muchas gracias|"
    # session 28 (blind26): Yoruba greetings and thanks ('E kaaro', 'e se gan'), Finnish 'Moi',
    # 'Kiitti' and 'Ole hyvä' (here you are / please, said alone), Albanian thanks
    r"e kaaro|e kaasan|e kaale|e ku aaro|e ku irole|e se(?: gan| o)?|o se(?: gan| o)?|"
    r"ole hyvä|ole hyva|moi|kiitti|faleminderit|"
    # session 32 (blind30): Galician, Cornish, Chichewa, Haitian Creole, Tongan, Quechua and
    # Tok Pisin thanks
    r"grazas|moitas grazas|meur ras|zikomo(?: kwambiri)?|mesi(?: anpil)?|malo aupito|mālō aupito|"
    r"sulpayki|añay|anay|tenkyu(?: tru)?|"
    # session 33 (blind31): Dzongkha and Sikkimese, Bemba and Hmong thanks
    r"kadrinchey(?: la)?|kadrin chhe(?: la)?|natotela(?: sana)?|ua tsaug(?: ntau)?|"
    # session 34 (blind32): Setswana thanks
    r"ke a leboga|kea leboga|kealeboga|"
    # session 29 (blind27): Basque, Catalan and Slovak thanks, with and without their letters'
    # marks, and the English blessing 'bless you' ('please' in them: _translated25)
    r"eskerrik asko|mila esker|milesker|gràcies|gracies|moltes gràcies|moltes gracies|"
    r"ďakujem(?: pekne)?|dakujem(?: pekne)?|vďaka|vdaka|bless you|"
    # blessings and pace
    r"amen(?: to that)?|inshallah|mashallah|pole pole|"
    # polite and sentence particles said alone (_PARTICLES)
    + "|".join(sorted(_PARTICLES, key=lambda w: (-len(w), w)))
)


def _courtesy_please33(text: str, lexicon: Lexicon) -> str:
    """Session 33: a courtesy or address of the session-24 list opening the instruction before
    'please' without a comma ("chale pls the chips to person a") taken off, as with one."""
    m = _rx(rf"^(?:{_COURTESY24})\s+(?=(?:pls|please|plz)\b)").match(text)
    if m is None or not _names_nothing(m[0], lexicon):
        return text
    return text[m.end() :]


_COURTESY_WORD24 = re.compile(rf"\b(?:{_COURTESY24})\b", _F)
_COURTESY_STRETCH24 = re.compile(
    rf"(?:and\s+)?(?:{_COURTESY24})"
    rf"(?:\s+(?:{_COURTESY24}|my friend|friend|sir|madam|boss|everyone|all|in advance))*",
    _F,
)


def _unmarked27(words: str) -> str:
    """``words`` as typed without their letters' marks ('Ačiū' → 'Aciu'; a letter with no
    unmarked form becomes 'x'): the lexer reads English letters only, and would read 'Ačiū' as
    'A', 'č', 'iū' — a scene's 'A' (session 27)."""
    if words.isascii():
        return words
    plain = "".join(c for c in unicodedata.normalize("NFKD", words) if not unicodedata.combining(c))
    return "".join(c if c.isascii() or not c.isalpha() else "x" for c in plain)


def _asks_nothing29(words: str, lexicon: Lexicon) -> bool:
    """Whether ``words`` is a remark that asks nothing (above): no word of a scene name either
    ('the red or the blue' names the mugs by their colour)."""
    plain = _THIS_MESSAGE29.sub("x", words).strip()
    tokens = re.findall(r"[a-z']+", plain.lower())
    said = _scene_words29(lexicon)
    return (
        bool(tokens)
        and not _ASKS29.search(plain)
        and not any(t in VERBS or t.split("'")[0] in VERBS or t in said for t in tokens)
        and _names_nothing(_unmarked27(words), lexicon)
    )


def _remark29(words: str, lexicon: Lexicon, opener: str) -> bool:
    """Whether ``words`` is a remark to take off: a statement that asks nothing, or a part
    opening with ``opener`` ('for the ghillie's picnic' before the request, 'back to my
    embroidery' after it) that asks nothing; never a part joined with 'and', 'plus', 'with'."""
    low = words.strip().lower()
    opens = bool(opener) and low.startswith(opener)
    if not opens and not _STATEMENT29.search(words):
        return False  # what the last line asks, asked first (session 46, 12p: it is cheap)
    rest = low[len(opener) :] if opens else low
    if (
        re.match(r"(?:and|or|plus|with|also|then)\b", low)
        or re.search(r"\bfor\b", rest)  # 'the jug is for the chef': whom it is for
        or not _asks_nothing29(words, lexicon)
    ):
        return False
    return opens or bool(_STATEMENT29.search(words))


def _typing_from29(sent: str, lexicon: Lexicon) -> bool:
    """Whether ``sent`` is such an apology (above) naming nothing of the scene."""
    m = _TYPING_FROM29.fullmatch(sent.strip())
    return m is not None and _asks_nothing29(m.group(1), lexicon)


def _remarks29(text: str, lexicon: Lexicon) -> str:
    """Session 29: remarks that ask nothing (above) taken off: whole sentences and parts before a
    colon, and comma parts opening or closing a sentence."""
    parts = re.split(r"(\s*[.!?;:]+\s*)", text.strip())
    sents, seps = parts[0::2], [*parts[1::2], ""]
    out: list[tuple[str, str]] = []
    for sent, sep in zip(sents, seps, strict=True):
        if "?" in sep or not sent.strip():
            out.append((sent, sep))
            continue
        if _remark29(sent, lexicon, "") or _typing_from29(sent, lexicon):
            continue
        if (
            sep.strip().startswith(":")
            and _asks_nothing29(sent, lexicon)
            and not _first_name30s(sent)
        ):
            continue  # "Quick list from the botanist: …": a heading
        pieces = re.split(r"\s*,\s*", sent)
        while len(pieces) > 1 and _remark29(pieces[-1], lexicon, "back to "):
            pieces.pop()
        while len(pieces) > 1 and _remark29(pieces[0], lexicon, "for "):
            pieces.pop(0)
        out.append((", ".join(pieces), sep))
    said = "".join(a + b for a, b in out).strip()
    if said == text.strip() or not _names(said, lexicon):
        return text
    return said


def _for_opener30(text: str, lexicon: Lexicon) -> str:
    """Session 30: "For the geography lesson Mrs Ortiz would like …": what the request is for,
    opening the instruction without a comma before the person who wants it; taken off as
    _remarks29 takes off 'For the ghillie's picnic, …' (the words name nothing and ask nothing,
    _asks_nothing29) when a scene person's name follows it and what is left names something."""
    m = re.match(
        r"^for ((?:the|a|an|our|my|your|this|today's|tomorrow's) [a-z' -]+)$",
        text.split(",")[0].split(".")[0],
        _F,
    )
    if m is None:
        return text
    words = m.group(1).split()
    for n in range(2, min(len(words), 6)):
        head, rest = " ".join(words[:n]), " ".join(words[n:])
        said = _names(rest, lexicon)
        if not said or not _asks_nothing29(head, lexicon):
            continue
        first = said[0]
        if first.refs[0].kind != "human" or not rest.lower().startswith(first.text.lower()):
            continue
        return text[len("for ") + len(head) :].lstrip()
    return text


def _needs_doing30(text: str, lexicon: Lexicon) -> str:
    """Session 30: the state above taken off."""
    if "need" not in text.lower() and "want" not in text.lower():
        return text
    parts = re.split(r"(\s*[.!?;:]+\s*)", text.strip())
    sents, seps = parts[0::2], [*parts[1::2], ""]
    out: list[str] = []
    for k, (sent, sep) in enumerate(zip(sents, seps, strict=True)):
        m = _NEEDS_DOING30.fullmatch(sent.strip())
        if m is None or "?" in sep:
            out.append(sent + sep)
            continue
        subject = m["subject"]
        if m["count"]:
            after = "".join(a + b for a, b in zip(sents[k + 1 :], seps[k + 1 :], strict=True))
            people = _ids(after, lexicon, "human")
            if not sep.strip().startswith(":") or len(people) != _NUMBERS15[m["count"].lower()]:
                out.append(sent + sep)
                continue
            subject = subject.replace(f" {m['count']} ", " ", 1)
        if m["doing"].lower() in VERBS or not _asks_nothing29(f"{subject} {m['doing']}", lexicon):
            out.append(sent + sep)
            continue
    said = "".join(out).strip()
    if said == text.strip() or not _names(said, lexicon):
        return text
    return said


def _state_after30(text: str, lexicon: Lexicon) -> str:
    """Session 30: the cause (above) taken off when it names nothing and asks nothing
    (_asks_nothing29): it says why, never when to act."""
    if " after " not in text.lower() or " so " not in text.lower():
        return text
    return _STATE_AFTER30.sub(
        lambda m: m["state"] if _asks_nothing29(m["cause"], lexicon) else m[0], text
    )


def _remark_it30(text: str, lexicon: Lexicon) -> str:
    """Session 30: the closing statement above taken off, when the sentences before it name one
    object of the scene (which 'it' is) and the statement, 'it' aside, names nothing and asks
    nothing (_asks_nothing29)."""
    m = re.search(r"(?<=[.!?])\s+(?P<said>[^.!?]+)[.!]?\s*$", text)
    if m is None or not re.search(r"\bit\b", m["said"], _F):
        return text
    said = m["said"]
    before = text[: m.start()]
    if (
        _STATEMENT_IT30.search(said) is None
        or len(_ids(before, lexicon, "object")) != 1
        or not _asks_nothing29(re.sub(r"\bit\b", "", said, flags=_F), lexicon)
    ):
        return text
    return before.strip()


def _has_going30(text: str, lexicon: Lexicon) -> str:
    """Session 30: the reason above is said as 'P is busy' (a remark the grammar's remark rule
    reads, its person standing in for the request's pronouns), when P is one person and what they
    have going names nothing and asks nothing (_asks_nothing29)."""
    if " got " not in text.lower():
        return text

    def busy(m: re.Match[str]) -> str:
        if _only_person(m["who"], lexicon) and _asks_nothing29(
            f"{m['what']} {m['doing']}", lexicon
        ):
            return f"{m['who']} is busy"
        return m[0]

    return _HAS_GOING30.sub(busy, text)


def _as_we_say31(text: str, lexicon: Lexicon) -> str:
    """Session 31: a courtesy said with its language (above) taken off when its words and the
    language name nothing of the scene and hold no word that asks (_asks_nothing29), and what is
    left names something. A question mark after it is kept (it closes the request)."""
    if " say " not in text.lower():
        return text

    def dropped(m: re.Match[str]) -> str:
        if m["word"] is None and (m["lead"].strip() == "," or m["end"].strip() not in ".!"):
            return m[0]  # without its words: only a sentence of its own ('Salamat' taken off)
        if not (
            (m["word"] is None or _asks_nothing29(m["word"], lexicon))
            and _names_nothing(m["lang"], lexicon)
        ):
            return m[0]
        end = m["end"].strip()
        if m["lead"].strip() == ",":
            return end if end in ("?", ".", "!") else ""
        return " " if m["lead"] else ""

    said = _AS_WE_SAY31.sub(dropped, text).strip()
    return said if said != text.strip() and _names(said, lexicon) else text


def _to_do31(text: str, lexicon: Lexicon) -> str:
    """Session 31: the purpose above taken off when what comes before it ends with an object of
    the scene (the want's object), and its verb is no verb of the grammar, names nothing and asks
    nothing (_asks_nothing29: no pronoun, count or time)."""
    if " to " not in text.lower():
        return text

    def dropped(m: re.Match[str]) -> str:
        verb = m["verb"]
        if (
            verb.lower() in VERBS
            or not _asks_nothing29(verb, lexicon)
            or not _ends_object(m["before"], lexicon)
        ):
            return m[0]
        return m["before"]

    return _TO_DO31.sub(dropped, text)


def _off_the31(text: str, lexicon: Lexicon) -> str:
    """Session 31: where the object is taken from (above) taken off, when the object is one object
    of the scene and where it is taken from names nothing of the scene or one surface ('the side',
    'the rack'): the second task says where it goes."""
    if " off " not in text.lower() and " from " not in text.lower() and " out " not in text.lower():
        return text

    def source(where: str) -> bool:
        return (_names_nothing(where, lexicon) and _asks_nothing29(where, lexicon)) or (
            _surface_only(where, lexicon)
        )

    def picked(m: re.Match[str]) -> str:
        if not _only(m["x"], lexicon, "object") or not source(m["from"]):
            return m[0]
        return f"pick up {m['x']} and "

    def moved(m: re.Match[str]) -> str:
        if not _only(m["x"], lexicon, "object") or not source(m["from"]):
            return m[0]
        return f"{m['x']} {m['modal'] or ''}go "

    return _COME_OFF31.sub(moved, _OFF_THE31.sub(picked, text))


def _after_state31(text: str, lexicon: Lexicon) -> str:
    """Session 31: the opening above taken off when P is one person of the scene, what happened
    names nothing and asks nothing (_asks_nothing29 past its determiner), and the state holds now
    (one word, then 'and', a comma or 'so')."""
    m = _AFTER_STATE31.match(text.strip())
    if m is None:
        return text
    what = m["what"].split(" ", 1)[1]
    if not (_asks_nothing29(what, lexicon) and _names_nothing(m["what"], lexicon)):
        return text
    words = m["p"].split()
    if not any(_only_person(" ".join(words[:n]), lexicon) for n in (len(words), 1)):
        return text
    rest = text.strip()[m.end() :]
    # the state is one that holds now ('is dry as a bone and …', 'is shattered, so …'): never one
    # to come ('is going to need', 'is getting', 'is to get', 'is due'), which the time puts off
    state = _rx(r"^[A-Za-z]+(?: [A-Za-z]+)?(?:'s| is) ([a-z]+)\b[^,;.]*?(?: and\b|,| so\b)").match(
        rest
    )
    if state is None:
        return text
    word = state.group(1).lower()
    if word.endswith("ing") or word in VERBS or word in _TO_COME31:
        return text
    return rest[:1].upper() + rest[1:]


def _state_so31(text: str, lexicon: Lexicon) -> str:
    """Session 31: the comma put in (above) when P is one person of the scene and the state one
    word that names nothing and asks nothing."""
    m = _STATE_SO31.match(text.strip())
    if m is None or not _only_person(m["p"], lexicon):
        return text
    how = m["how"].split()[-1]
    if how.lower() in VERBS or not _asks_nothing29(how, lexicon):
        return text
    return f"{m['p']} {m['be']} {m['how']}, so {text.strip()[m.end() :]}"


def _for_bare31(text: str, lexicon: Lexicon) -> str:
    """Session 31: the purpose above taken off when what comes before 'for' ends with one surface
    of the scene and the word names nothing, asks nothing and is no verb of the grammar."""
    m = _FOR_BARE31.search(text)
    if m is None:
        return text
    tail = m["s"].split(" ", 1)[1]
    w = m["w"]
    if not _surface_only(tail, lexicon) or w.lower() in VERBS or not _asks_nothing29(w, lexicon):
        return text
    return text[: m.start()] + m["s"] + m["end"].strip()


def _like_a31(text: str, lexicon: Lexicon) -> str:
    """Session 31: the comparison above taken off when P is one person of the scene, and the
    comparison and what the person is doing name nothing and ask nothing."""
    if " like " not in text.lower():
        return text

    def plain(m: re.Match[str]) -> str:
        doing = m["head"][len(m["p"]) :]
        what = m["what"].split(" ", 1)[1]
        if (
            _only_person(m["p"], lexicon)
            and _names_nothing(doing, lexicon)
            and _names_nothing(m["what"], lexicon)
            and _asks_nothing29(what, lexicon)
            and not any(w in VERBS for w in doing.lower().split()[1:2])
        ):
            return m["head"]
        return m[0]

    return _LIKE_A31.sub(plain, text)


_STEPS31: tuple[Callable[[str, Lexicon], str], ...] = (
    _as_we_say31,
    _interjected31,
    _trades31,
    _idioms31,
    _to_do31,
    _cleft_wants31,
    _told_me31,
    _along_with31,
    _will_take31,
    _with_object31,
    _with_going31,
    _if_manage31,
    _run_on_close31,
    _it_her31,
    _the_moment31,
    _make_way31,
    _off_the31,
    _while31,
    _up_on31,
    _safe_where31,
    _what_needs31,
    _after_state31,
    _state_so31,
    _her_surface31,
    _for_bare31,
    _serve_first31,
    _first_over31,
    _trade_wants31,
    _trade_on31,
    _like_a31,
    _one_task_two_sentences31,
    _apposition31,
)


def _before_deadline32(text: str, lexicon: Lexicon) -> str:
    """Session 32: the closing 'before …' above taken off when its words name nothing, hold no
    verb of the grammar and no word that asks (_asks_nothing29) but the pronouns, and each
    pronoun may stand for what the request names ('he' for the one person, 'them' for its
    objects)."""
    if "before" not in text.lower():
        return text
    m = _BEFORE32.search(text)
    if m is None:
        return text
    rest = text[: m.start()]
    what = m["what"]
    # a noun after 'his / her / their' is a noun ('on his round': his route, not an order)
    plain = _BACK_POINTERS32.sub("", re.sub(r"\b(?:his|her|their) [a-z]+", "", what, flags=_F))
    if not plain.split() or not _asks_nothing29(plain, lexicon):
        return text
    people = _people_before32(rest, lexicon)
    if m["pron"] and (len(people) != 1 or not _fits(next(iter(people)), what, lexicon)):
        return text
    if re.search(r"\b(?:it|them)\b", what, _F) and not _ids(rest, lexicon, "object"):
        return text
    return rest + m["end"].strip() if _names(rest, lexicon) else text


def _story32(text: str, lexicon: Lexicon) -> str:
    """Session 32: the closing story above taken off when who did it names nothing and asks
    nothing, and what they used up names nothing or only objects the request names."""
    m = _STORY32.search(text)
    if m is None:
        return text
    rest = text[: m.start()]
    if not _asks_nothing29(m["who"].split(" ", 1)[1], lexicon):
        return text
    used = _ids(m["what"], lexicon)
    if used and (
        not used <= _ids(rest, lexicon, "object") or not _objects_only(m["what"], lexicon)
    ):
        return text
    return rest + m["end"].strip() if _names(rest, lexicon) else text


def _possession32(text: str, lexicon: Lexicon) -> str:
    """Session 32: the possessions above said as handovers ('X is for P', 'give X to P', 'X to
    P'), each when X is objects of the scene only and P one person of the scene (what the
    'to take' part adds names nothing and asks nothing)."""
    if "'s" not in text and " hers " not in text and " his " not in text:
        return text

    def to_take(m: re.Match[str]) -> str:
        tail = m["tail"].strip()
        if not (_things31(m["x"], lexicon) and _only_person(m["p"], lexicon)):
            return m[0]
        if tail and not _asks_nothing29(tail, lexicon):
            return m[0]
        return f"{m['x']} is for {m['p']}"

    def too(m: re.Match[str]) -> str:
        if not _things31(m["x"], lexicon) or not _ids(text[: m.start()], lexicon, "human"):
            return m[0]
        return f"{m['x']} {m['be']} for {_POSSESSIVE32[m['pos'].lower()]} {m['too']}"

    def give(m: re.Match[str]) -> str:
        if not (_things31(m["x"], lexicon) and _only_person(m["p"], lexicon)):
            return m[0]
        return f"{m['v']} {m['x']} to {m['p']}{m['rest']}"

    def telegram(m: re.Match[str]) -> str:
        if not (_things31(m["x"], lexicon) and _only_person(m["p"], lexicon)):
            return m[0]
        return f"{m['x']} to {m['p']}."

    text = _TO_TAKE32.sub(to_take, text)
    text = _HERS_TOO32.sub(too, text)
    text = _OWNED_GIVE32.sub(give, text)
    text = _TELEGRAM32.sub(telegram, text)
    return _owned_listed32(text, lexicon)


def _state_it32(text: str, lexicon: Lexicon) -> str:
    """Session 32: 'X is <state>, <verb> it …' is '<verb> X …', when X is one object of the
    scene, the state one word naming nothing and asking nothing, and the verb one of the
    grammar's."""
    m = _STATE_IT32.match(text)
    if m is None or m["v"].lower() not in (*VERBS, *_PLACING32):
        return text
    if not _things31(m["x"], lexicon) or len(_ids(m["x"], lexicon)) != 1:
        return text
    if not _asks_nothing29(m["state"], lexicon):
        return text
    return f"{m['v']} {m['x']}{text[m.end() :]}"


def _for_to_do32(text: str, lexicon: Lexicon) -> str:
    """Session 32: 'on S for P to <verb> (after his <noun>)' is 'on S', when S is one surface of
    the scene, P one person, the verb no verb of the grammar and asking nothing, and the tail
    naming nothing (the placement is asked; what P will do with it is not)."""
    if " for " not in text:
        return text

    def placed(m: re.Match[str]) -> str:
        where = re.sub(r"^(?:on|in|onto|into) ", "", m["place"], flags=_F)
        if not (_surface_only(where, lexicon) and _only_person(m["p"], lexicon)):
            return m[0]
        if m["v"].lower() in VERBS or not _asks_nothing29(m["v"], lexicon):
            return m[0]
        if m["tail"] and not _names_nothing(m["tail"], lexicon):
            return m[0]
        return m["place"]

    return _FOR_TO_DO32.sub(placed, text)


def _to_do_with32(text: str, lexicon: Lexicon) -> str:
    """Session 32: the purpose above taken off when what comes before it ends with an object of
    the scene, the verb is no verb of the grammar, and its words name nothing and ask nothing
    (but the possessive)."""
    if " to " not in text:
        return text

    def dropped(m: re.Match[str]) -> str:
        words = re.sub(r"^(?:his|her|their|some|a|an) ", "", m["what"], flags=_F)
        if m["verb"].lower() in VERBS or not _ends_object(m["before"], lexicon):
            return m[0]
        if not _asks_nothing29(f"{m['verb']} {words}", lexicon):
            return m[0]
        return m["before"]

    return _TO_DO_WITH32.sub(dropped, text)


def _too_warm32(text: str, lexicon: Lexicon) -> str:
    """Session 32: the closing state above taken off when its words name nothing and ask nothing
    and what is left names a person."""
    m = _TOO_WARM32.search(text)
    if m is None or not _asks_nothing29(f"{m['what']} {m['state']}", lexicon):
        return text
    rest = text[: m.start()]
    return rest + m["end"].strip() if _ids(rest, lexicon, "human") else text


def _back_from_place32(text: str, lexicon: Lexicon) -> str:
    """Session 32: 'P is back from the <noun>' is 'P is back' when P is one person of the scene
    and the noun names nothing and asks nothing."""
    m = _BACK_FROM_PLACE32.match(text)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    said = m[0].split(" back from ", 1)[1]
    if not _asks_nothing29(said.split(" ", 1)[1], lexicon):
        return text
    return f"{m['p']} is back{text[m.end() :]}"


def _carried32(text: str, lexicon: Lexicon) -> str:
    """Session 32: a person's place after their name taken off (one person of the scene, the
    place naming nothing and asking nothing); 'run X down to' is 'take X to', 'can you manage X
    to P' is 'X to P?' (X objects of the scene only)."""
    m = _AT_THE_END32.search(text)
    # 'at the end' alone may say when (last: session 26); 'at the far end' says where
    ends = m is not None and m["place"].lower() in ("end", "start", "beginning") and not m["far"]
    if (
        m is not None
        and not ends
        and _only_person(m["p"], lexicon)
        and _asks_nothing29(m["place"], lexicon)
    ):
        text = text[: m.start()] + m["p"] + m["end"].strip()
    text = _RUN_DOWN32.sub(
        lambda m: f"take {m['x']} to" if _things31(m["x"], lexicon) else m[0], text
    )
    m2 = _MANAGE32.match(text)
    if m2 is not None and _ids(text[m2.end() :].split(" to ", 1)[0], lexicon, "object"):
        head = text[m2.end() :].split(" to ", 1)[0]
        if _things31(head, lexicon):
            text = text[m2.end() :]
    return text


def _my_hands33(text: str, lexicon: Lexicon) -> str:
    """Session 33: the closing part above taken off when what the hands are names nothing and
    asks nothing, and what is left names something."""
    if "my hands" not in text.lower():
        return text
    m = _MY_HANDS33.search(text)
    if (
        m is None
        or not _asks_nothing29(m["what"], lexicon)
        or not _names(text[: m.start()], lexicon)
    ):
        return text
    return text[: m.start()] + m["end"].strip()


def _as_used_to34(text: str, lexicon: Lexicon) -> str:
    """Session 34: a closing courtesy and the saying above taken off, when the courtesy is one of
    the courtesy list (or English thanks) naming nothing and what is left names something."""
    if " say" not in text:
        return text
    m = _AS_USED_TO34.search(text)
    if m is None:
        return text
    court = m["court"].strip()
    if not (_courtesy_stretch24(court) or _THANKS34.fullmatch(court)):
        return text
    if not _names_nothing(_unmarked27(court), lexicon) or not _names(text[: m.start()], lexicon):
        return text
    return text[: m.start()] + m["end"].strip()


def _for_his34(text: str, lexicon: Lexicon) -> str:
    """Session 34: the fronted purpose above taken off when its words name nothing and ask
    nothing but the pronoun, P is one person of the scene and the pronoun may be P."""
    m = _FOR_HIS34.match(text)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    if not _asks_nothing29(m["what"], lexicon) or not _names_nothing(m["what"], lexicon):
        return text
    if not _fits(next(iter(_ids(m["p"], lexicon))), m["pron"], lexicon):
        return text
    return text[m.start("p") :]


def _where_she_is34(text: str, lexicon: Lexicon) -> str:
    """Session 34: the remark above taken off when P is one person of the scene the pronoun may
    be, and the place names nothing and asks nothing."""
    if "'s " not in text and " is " not in text:
        return text

    def dropped(m: re.Match[str]) -> str:
        if not _only_person(m["p"], lexicon) or not _asks_nothing29(m["place"], lexicon):
            return m[0]
        if not _names_nothing(m["place"], lexicon):
            return m[0]
        return m["p"] if _fits(next(iter(_ids(m["p"], lexicon))), m["pron"], lexicon) else m[0]

    return _WHERE_SHE_IS34.sub(dropped, text)


def _been_at34(text: str, lexicon: Lexicon) -> str:
    """Session 34: the clause above taken off (the person is the want's subject) when the place
    names nothing and asks nothing; P is left for the grammar to read (a name with a slip)."""
    if " been " not in text:
        return text
    m = _BEEN_AT34.search(text)
    if m is None or not _names_nothing(m["where"], lexicon):
        return text
    if not _asks_nothing29(m["where"].split(" the ", 1)[1], lexicon):
        return text
    return f"{text[: m.start()]}{m['p']} {text[m.end() :]}"


def _to_do34(text: str, lexicon: Lexicon) -> str:
    """Session 34: the purpose above taken off when X is objects only and its words name
    nothing and ask nothing."""
    if " to " not in text:
        return text
    m = _TO_DO34.search(text)
    if m is None or not _things31(m["x"], lexicon):
        return text
    if not _names_nothing(m["what"], lexicon) or not _asks_nothing29(m["what"], lexicon):
        return text
    return text[: m.start()] + m["want"] + m["end"].strip()


def _after_pastime35(text: str, lexicon: Lexicon) -> str:
    """Session 35: 'after <pastime>' above taken off when X is objects only, the doing names
    nothing and asks nothing, and a pronoun there may be the want's subject (the person just
    before the want)."""
    if " after " not in text:
        return text
    m = _AFTER_PASTIME35.search(text)
    if m is None or not _things31(m["x"], lexicon):
        return text
    if not _names_nothing(m["doing"], lexicon) or not _asks_nothing29(m["doing"], lexicon):
        return text
    if m["pron"] and m["pron"].lower() != "their":
        before = re.split(r"[,.;:!?]|\s+(?:and|but|so)\s+", text[: m.start()])[-1]
        people = _ids(before, lexicon, "human")
        if len(people) != 1 or not _fits(next(iter(people)), m["pron"], lexicon):
            return text
    return text[: m.start()] + m["want"] + m["end"].strip()


_STEPS35: tuple[Callable[[str, Lexicon], str], ...] = (
    _after_it35,
    _want_idioms35,
    _after_pastime35,
    _needed_at35,
    _if_sort35,
    _sat_on35,
    _headed_for35,
    _clefts35,
    _where_goes35,
    _along_with35,
    _state_it35,
    _on_with35,
    _telegraph35,
    _then_trade35,
    _by_surface35,
    _want_run_on35,
    _care35,
    _with_her35,
    _kick_off35,
    _better_home35,
    _questions35,
    _who_she_is35,
    _get_sorted35,
    _office35,
    _not_had35,
)


def _courtesies36(text: str, lexicon: Lexicon) -> str:
    """Session 36: the courtesies above taken off (the favour's doing and the group naming
    nothing and asking nothing), when what is left names something."""
    out = text
    m = _GOOD_OF_YOU36.match(out)
    if m is not None:
        out = out[m.end() :]
    m = _FAVOUR36.match(out)
    if m is not None and (m["act"] is None or _asks_nothing29(m["act"], lexicon)):
        out = out[m.end() :]
    m = _THANKS_GROUP36.search(out)
    if m is not None and (m["what"] is None or _asks_nothing29(m["what"], lexicon)):
        out = out[: m.start()] + m["end"].strip()
    m = _OBLIGED36.match(out)
    if m is not None:
        out = out[m.end() :]
    if out == text or not _names(out, lexicon):
        return text
    return out[0].upper() + out[1:]


def _time_for36(text: str, lexicon: Lexicon) -> str:
    """Session 36: 'X time so it's …' opening (X naming nothing and asking nothing) taken off,
    and 'for the last van (of the day)' closing a want or need of one person (the noun no time
    and naming nothing) taken off."""
    m = _TIME_SO36.match(text)
    if m is not None and _asks_nothing29(m["what"], lexicon) and _names(text[m.end() :], lexicon):
        text = text[m.end() :]
    m = _FOR_THE_LAST36.search(text)
    if m is None or m["n"].lower() in _TIME_NOUNS36 or not _asks_nothing29(m["n"], lexicon):
        return text
    before = text[: m.start()]
    if not re.search(r"\b(?:needs|wants|is after|'s after|could use|could do with)\b", before, _F):
        return text
    if len(_ids(before, lexicon, "human")) != 1:
        return text
    return before + m["end"].strip()


def _stretches_dropped(text: str, drops: Callable[[str], bool], lexicon: Lexicon) -> str:
    """``text`` without each stretch between commas, colons and sentence ends that ``drops``
    (a comma left before a sentence end goes with it: "…, asante." → "…."), when what is left
    names something; else ``text``."""
    parts = re.split(r"(\s*[,;:.!?]+\s*)", text.strip())
    chunks, seps = parts[0::2], [*parts[1::2], ""]
    drop = [drops(c) for c in chunks]
    if not any(drop):
        return text
    out: list[str] = []
    for c, sep, d in zip(chunks, seps, drop, strict=True):
        if d:
            if out and sep.strip()[:1] in (".", "!", "?") and out[-1].strip()[:1] in (",", ";"):
                out[-1] = sep
            continue
        out.extend((c, sep))
    said = "".join(out).strip(" ,;:")
    return said if _names(said, lexicon) else text


def _speaker_parts32(text: str, lexicon: Lexicon) -> str:
    """Session 32: a comma part or sentence that is wholly one of the closed list above taken
    off, when it names nothing and what is left names something."""
    if not _PARTS32.search(text):
        return text
    return _stretches_dropped(  # "…, could you manage that?" → "…?"
        text,
        lambda c: bool(_PARTS32.fullmatch(c.strip())) and _names_nothing(c, lexicon),
        lexicon,
    )


_STEPS32: tuple[Callable[[str, Lexicon], str], ...] = (
    _speaker_parts32,
    _run_on_said32,
    _reckons32,
    _says_in32,
    _idioms32,
    _asked_after32,
    _needs_most32,
    _been_wanting32,
    _each_wants32,
    _before_deadline32,
    _story32,
    _possession32,
    _same_person32,
    _clear_up32,
    _hand_over32,
    _state_it32,
    _for_to_do32,
    _asked_as32,
    _add_to32,
    _beside_on32,
    _to_do_with32,
    _too_warm32,
    _since32,
    _back_from_place32,
    _left_it32,
    _is_the_and32,
    _carried32,
    _his_way32,
)


def _speaker_parts33(text: str, lexicon: Lexicon) -> str:
    """Session 33: a comma part or sentence that is wholly one of the closed list above taken
    off, when it names nothing and what is left names a person or surface (whom or where the
    request is for)."""
    if not _PARTS33.search(text):
        return text
    said = _stretches_dropped(
        text,
        lambda c: bool(_PARTS33.fullmatch(c.strip())) and _names_nothing(c, lexicon),
        lexicon,
    )
    if said == text or not _ids(said, lexicon, "human") | _ids(said, lexicon, "surface"):
        return text
    # "And, the apple": the 'and' kept before what followed the part taken off
    return re.sub(r"\b(And|and),\s+(?=the\b)", r"\1 ", said)


_STEPS33: tuple[Callable[[str, Lexicon], str], ...] = (
    _speaker_parts33,
    _all_yours33,
    _idioms33,
    _would_help33,
    _more_than33,
    _according33,
    _event_time33,
    _closing_cause33,
    _earned_after33,
    _who_thats33,
    _there_it33,
    _whose_take33,
    _own_on33,
    _name_typo33,
    _asked_as33,
    _by_landmark33,
    _cleft_who33,
    _on_about33,
    _trade_says33,
    _lent33,
    _my_hands33,
    _start_with33,
    _keep_going33,
    _courtesy_please33,
    _those_are33,
)


def _speaker_parts34(text: str, lexicon: Lexicon) -> str:
    """Session 34: a comma part or sentence that is wholly one of the closed list above taken
    off, when it names nothing and what is left names something."""
    if not _PARTS34.search(text):
        return text
    return _stretches_dropped(
        text,
        lambda c: bool(_PARTS34.fullmatch(c.strip())) and _names_nothing(c, lexicon),
        lexicon,
    )


# Session 52 (12p): the courtesies by their first word (gate.first_words). _COURTESY_WORD24 (the
# list between word edges) finds one in an ASCII text only where a word of the text is the first
# word of one of them: only those are looked for (the text's words found in one pass), where the
# list's ~300 alternatives tried at every letter cost ~0.1 ms a text
_BY_FIRST24 = re.first_words(_COURTESY24, _F)
_WORD_RUN = re.compile(r"\w+")


def _courtesy_word24(text: str) -> bool:
    """Whether _COURTESY_WORD24 finds a courtesy in ``text``."""
    low = text.lower()
    if _BY_FIRST24 is None or not low.isascii():
        return _COURTESY_WORD24.search(text) is not None
    firsts = _BY_FIRST24.keys() & _WORD_RUN.findall(low)
    return bool(firsts) and _courtesies24(frozenset(firsts)).search(text) is not None


def _courtesy_stretch24(said: str) -> bool:
    """Whether _COURTESY_STRETCH24 matches the whole of ``said`` (session 54, 12p): an ASCII text
    it matches begins with 'and' or with a courtesy's first word (_BY_FIRST24: each courtesy
    begins with a word letter and is followed by a space or the end), so only there is the
    pattern asked."""
    if _BY_FIRST24 is not None and said.isascii():
        first = _WORD_RUN.match(said)
        if first is None:
            return False
        word = first[0].lower()
        if word != "and" and word not in _BY_FIRST24:
            return False
    return _COURTESY_STRETCH24.fullmatch(said) is not None


@functools.lru_cache(maxsize=512)
def _courtesies24(firsts: frozenset[str]) -> re.Pattern[str]:
    """_COURTESY_WORD24 with only the courtesies whose first word is one of ``firsts``."""
    by = _BY_FIRST24 or {}
    said = sorted({t for f in firsts for t in by[f]}, key=lambda t: (-len(t), t))
    return re.compile(rf"\b(?:{'|'.join(map(re.escape, said))})\b", _F)


def _courtesy24(text: str, lexicon: Lexicon) -> str:
    """Session 24: stretches of greetings, thanks, blessings and polite particles of other
    languages ("Sawasdee krap.", "…, asante.", "Habari, …", "Amen to that.", "Diakuiu, thank you
    very much.") taken off (above)."""
    if not _courtesy_word24(text):
        return text
    # session 29: a colon ends a stretch too ('Eskerrik asko in advance: the cup to …')
    return _stretches_dropped(
        text,
        lambda c: _courtesy_stretch24(c.strip()) and _names_nothing(_unmarked27(c), lexicon),
        lexicon,
    )


# words of other languages that English says with one word, read as that word inside a clause:
# 'please' (Indonesian 'tolong', 'bisa tolong' = could you please; Persian 'lotfan'; German
# 'bitte'; Spanish 'por favor') and 'sorry' (Persian 'bebakhshid', Indonesian 'maaf'); and a
# title of respect before a scene person's name (Indonesian 'Bu' / 'Ibu', 'Pak' / 'Bapak', 'Mas',
# 'Mbak'). Session 27: 'please' of Lithuanian (prašau, prašom), Georgian (gtkhovt), Amharic
# (ebakih, ebakish, ebakachihu), Sinhala (karunakarala), Latvian (lūdzu), Estonian (palun),
# Polish (proszę), Serbian and Croatian (molim), Dutch (alstublieft, alsjeblieft), Turkish
# (lütfen), Russian (pozhaluysta), Greek (parakalo), Swahili (tafadhali), Hindi (kripya), French
# (s'il vous plaît), Italian (per favore), Japanese (onegaishimasu) — never where the scene
# names someone or something by that word (_translated25)
_PLEASE25 = re.compile(
    r"\b(?:bisa tolong|tolong|lotfan|bitte|por favor|prosím|prosim|vă rog|va rog|"
    r"prašau|prasau|prašom|prasom|gtkhovt|ebakih|ebakish|ebakachihu|karunakarala|lūdzu|ludzu|"
    r"palun|proszę|prosze|molim|alstublieft|alsjeblieft|lütfen|lutfen|pozhaluysta|pozhaluista|"
    r"parakalo|tafadhali|kripya|s'il vous pla[iî]t|sil vous plait|per favore|onegaishimasu|"
    r"si us plau|mesedez)(?!\w)",
    _F,
)
_SORRY25 = re.compile(r"\b(?:bebakhshid|bebakhshin|bebakhsheed|maaf)\b", _F)
# Jamaican English / Patois words for English function words ('di bottle' = the bottle, 'fi Bob'
# = for Bob, 'mek Person A get' = let Person A get, 'mi mean' = I mean, 'it nuh matter' = it
# doesn't matter; 'nuh' closing a clause asks 'won't you', as 'eh' does)
_PATOIS25 = {
    "di": "the",
    "dat": "that",
    "dis": "this",
    "fi mi": "for me",
    "fi": "for",
    "jus": "just",
    "mek": "let",
    "pon": "on",
    "wid": "with",
    "mi mean": "I mean",
    "nuh matter": "doesn't matter",
}
_PATOIS_WORD25 = re.compile(
    r"\b(?:di|dat|dis|fi mi|fi|jus|mek|pon|wid|mi mean|nuh matter)\b(?=[\s',.;!?]|$)|"
    r"\s*\bnuh\b(?=\s*[,.;!?])",
    _F,
)
_HONORIFIC25 = re.compile(r"\b(?:[Bb]u|[Ii]bu|[Pp]ak|[Bb]apak|[Mm]as|[Mm]bak)\s+(?=[A-Z])")


# an address of respect said right after a person's name ('to Alice ma'am', 'Bob sir': Indian,
# Tamil and Ghanaian English) before a mark or the end (session 26)
_ADDRESS_AFTER26 = re.compile(r"\s+(?:ma'am|ma’am|maam|madam|sir)(?=\s*[,.;!?]|$)", _F)


def _address_after26r(text: str, lexicon: Lexicon) -> str:
    """Session 26: 'ma'am' / 'madam' / 'sir' right after a person's name of the scene ("Please give
    the crisps to Alice ma'am") is said of that person, as 'Mrs' before it would be: taken off.
    After anything else ('the bottle, sir', 'Madam Curie ma'am' not in the scene) it is left."""
    if not _ADDRESS_AFTER26.search(text):
        return text

    def after_person(m: re.Match[str]) -> str:
        words = m.string[: m.start()].split()[-3:]
        said = _names(" ".join(words), lexicon)
        named = (
            bool(said)
            and m.string[: m.start()].lower().endswith(said[-1].text.lower())
            and all(r.kind == "human" for r in said[-1].refs)
        )
        return "" if named else m[0]

    return _ADDRESS_AFTER26.sub(after_person, text)


def _opens_with_person(rest: str, lexicon: Lexicon) -> bool:
    """Whether ``rest`` starts with the name of a person of the scene."""
    said = _names(" ".join(rest.split()[:2]), lexicon)
    return (
        bool(said)
        and rest.lower().startswith(said[0].text.lower())
        and all(r.kind == "human" for r in said[0].refs)
    )


def _translated25(text: str, lexicon: Lexicon) -> str:
    """Session 25: 'please' and 'sorry' said in another language are 'please' and 'sorry'
    ("Permisi, tolong the bottle for Person A", "…, ah no, bebakhshid, the apple"), Patois
    function words are their English ones ("Not di bottle, jus di crisps fi Bob"), and a title
    of respect of another language before a person's name of the scene is taken off ("Stapler
    to Bu Priya, then the notepad to Mas Sam"), as 'Mr' would be when the scene does not say
    it. (Session 54, 12p: the three word lists asked through the gate, which turns a text away
    that holds none of their words; the titles' pattern asked raw, its words too short to.)"""
    if re.search(_PLEASE25, text):
        text = _PLEASE25.sub(lambda m: m[0] if _names(m[0], lexicon) else "please", text)
    if re.search(_SORRY25, text):
        text = _SORRY25.sub("sorry", text)
    if re.search(_PATOIS_WORD25, text):
        text = _PATOIS_WORD25.sub(lambda m: _PATOIS25.get(m[0].lower(), ""), text)
    if not _HONORIFIC25.search(text):
        return text
    return _HONORIFIC25.sub(
        lambda m: "" if _opens_with_person(m.string[m.end() :], lexicon) else m[0], text
    )


# Session 25: closing stretches that ask for nothing (a house rule, a croupier's 'no more bets',
# 'then we'll see', something else that 'can wait', a warning to 'mind' something not in the
# scene), after the request, each after a comma at the end of the instruction
_CLOSER25 = re.compile(
    r"\s*,\s*(?:and\s+)?((?:house rules|no more bets(?: please)?|(?:and )?then we'll see|"
    r"(?:the|my|your|his|her|their|our) [a-z' ]+? can wait|mind the [a-z' ]+?))\s*([.!]?)\s*$",
    _F,
)


def _closers25(text: str, lexicon: Lexicon) -> str:
    """Session 25: a closing stretch of _CLOSER25 that names nothing in the scene ("…, house
    rules.", "…, no more bets", "…, then we'll see.", "…, the strings can wait", "…, mind the
    pane on the floor") is taken off; one that names something ("…, the apple can wait") is
    left, and refused."""
    for _ in range(2):
        m = _CLOSER25.search(text)
        if m is None or m.start() == 0 or not _names_nothing(m.group(1), lexicon):
            return text
        text = text[: m.start()] + m.group(2)
    return text


# -- session 26 (engineer 12): blind24's refusals by kind ------------------------------------------


def _one_name(words: str, lexicon: Lexicon, kind: str) -> str | None:
    """The id ``words`` names when they are, whole, one name of one ``kind`` of the scene ('the
    bottle', 'Bob', 'the loading bay' is None where no surface is called that)."""
    names = _names(words, lexicon)
    if len(names) != 1 or {r.kind for r in names[0].refs} != {kind}:
        return None
    ids = {r.id for r in names[0].refs}
    said = re.sub(r"^(?:the|a|an|my|our|your)\s+", "", words.strip(), flags=_F).lower()
    if len(ids) != 1 or said != names[0].text.lower():
        return None
    return next(iter(ids))


def _restated26(text: str, lexicon: Lexicon) -> str:
    """'the (one / single / only) X we've got / we have / you've got': the X (a clause saying
    that it is there picks nothing out; with several X the name stays unclear and is refused
    naming each)."""

    def restated(m: re.Match[str]) -> str:
        names = _names(m.group(2), lexicon)
        if len(names) != 1 or any(r.kind != "object" for r in names[0].refs):
            return m.group(0)
        if m.group(2).lower() != names[0].text.lower():
            return m.group(0)
        return f"{m.group(1)} {m.group(2)}"

    return _sub(
        r"\b(the)(?: (?:one|single|only))? ([a-z][a-z ]*?) (?:that |which )?"
        r"(?:we(?:'ve| have)(?: got)?|you(?:'ve| have) got)(?: here| there)?(?=\s*(?:[,.;!?]|$))",
        restated,
        text,
    )


def _brought26(text: str, lexicon: Lexicon) -> str:
    """'P wants the X brought over (from your side)': P wants the X — a participle of bringing
    with no place of its own says how, not where; a 'from' naming nothing in the scene says
    where it comes from. 'brought over from Alice' (a person) or 'brought to the shelf' are
    left."""

    def brought(m: re.Match[str]) -> str:
        source = m.group(3) or ""
        if source and (
            not _names_nothing(source, lexicon)
            or re.search(r"\b(?:him|her|them|me|us|it|his|hers)\b", source, _F)
        ):
            return m.group(0)
        if _one_name(m.group(2), lexicon, "object") is None and m.group(2).lower() not in (
            "it",
            "them",
        ):
            names = _names(m.group(2), lexicon)
            if len(names) != 1 or any(r.kind != "object" for r in names[0].refs):
                return m.group(0)
        return f"{m.group(1)} {m.group(2)}"

    return _sub(
        r"\b(wants?|needs?|would like|'d like|is after) (the [a-z ]+?|it|them) "
        r"(?:(?:brought|fetched)(?: over| across| round| along)?|"
        r"(?:sent|passed)(?: over| across| round| along))"
        r"(?: from ((?:the |your |my |our |over )?[a-z' ]+?))?(?=\s*(?:[,.;!?]|$|\band\b))",
        brought,
        text,
    )


# words of time after 'at the / in the / by the': when a task is done, not where a person is
_WHEN26 = (
    r"\b(?:end|start|beginning|moment|same time|last|first|time|minute|second|break|lunch|"
    r"weekend|night|morning|evening|afternoon|day|meeting|interval|half|match|finish|close|"
    r"latest|earliest|mo|sec|rush|shift|round|hour|week|month|next|tomorrow|tonight|later|"
    r"soon|dinner|breakfast|tea|service|game)s?\b"
)


def _located26(text: str, lexicon: Lexicon) -> str:
    """'… to Bob on the loading bay', 'go over to Carol at the till': where the person is, when
    it names nothing in the scene, is taken off (to Bob); a place of the scene after the person
    ('to Bob on the shelf') could be where the object goes, so it is left, and refused."""

    def located(m: re.Match[str]) -> str:
        if _one_name(m.group(2), lexicon, "human") is None:
            return m.group(0)
        if not _names_nothing(m.group(3), lexicon) or re.search(
            r"\b(?:him|her|them|me|us|it|his|my|your|their)\b", m.group(3), _F
        ):
            return m.group(0)
        if re.search(_WHEN26, m.group(3), _F):
            return m.group(0)  # "… to Bob at the end": when, not where (an order)
        return f"{m.group(1)} {m.group(2)}"

    return _sub(
        r"\b(to) ((?:person |mr |mrs |ms |miss |dr )?[a-z]+) "
        r"((?:on|at|in|by|over by|down at|up at|out at|out on) the [a-z][a-z' -]*?)"
        r"(?=\s*(?:[,.;!?]|$|\band\b|\bthen\b))",
        located,
        text,
    )


def _same_place26(text: str, lexicon: Lexicon) -> str:
    """'…, then the thermometer, same place': the one surface named before it (with the
    preposition said there); with none, or more than one, before it, it is left, and refused."""
    m = re.search(
        r",?\s*\b(?:in |on |at |onto |into )?(?:the )?same place\b(?=\s*(?:[,.;!?]|$))", text, _F
    )
    if m is None:
        return text
    before = text[: m.start()]
    places = [it for it in _names(before, lexicon) if it.refs[0].kind == "surface"]
    if len({r.id for it in places for r in it.refs}) != 1 or len(places[-1].refs) != 1:
        return text
    last = places[-1].text
    prep = re.findall(rf"\b(on|onto|in|into|at)\s+(?:the\s+)?{re.escape(last)}\b", before, _F)
    return f"{before} {prep[-1] if prep else 'on'} the {last}{text[m.end() :]}"


def _counted26(text: str, lexicon: Lexicon) -> str:
    """'put them both in the box', 'take them all to Bob': 'both' (said to be two, and checked) /
    'them' — before a place or a person, so 'them' is the objects, not the people."""
    out = _sub(r"\bthem both(?= (?:in|on|into|onto|to|over|across|back|up)\b)", "both", text)
    return _sub(r"\bthem all(?= (?:in|on|into|onto|to|over|across|back|up)\b)", "them", out)


def _subject_comma26(text: str, lexicon: Lexicon) -> str:
    """'the three boxes, go on the belt' (what is left of 'All three of the boxes, small, medium
    and large, go on the belt' when the list naming them is taken off): the subject and its verb
    'go', with no comma between."""
    return _sub(
        r"^(the (?:two|three|four|five|six) [a-z]+),\s*(go|goes)\b"
        r"(?= (?:on|onto|in|into|to|over)\b)",
        r"\1 \2",
        text,
    )


def _phrasal26(text: str, lexicon: Lexicon) -> str:
    """Phrasal verbs of handing over: 'sort X out for P' (get X for P), 'sort P out with X'
    (give P X); ', but keep X away from him / her' after a request naming one person (', but not
    X': that person does not get it)."""
    out = _sub(r"\bsort (the [a-z ]+?|it|them) out for\b", r"get \1 for", text)

    def sort_with(m: re.Match[str]) -> str:
        if m.group(2).lower() not in ("him", "her", "them") and (
            _one_name(m.group(2), lexicon, "human") is None
        ):
            return m.group(0)
        return f"{m.group(1)}give {m.group(2)}"

    out = _sub(r"(^|\s)sort ([a-z]+(?: [a-z]+)?) out with\b", sort_with, out)
    if len(_ids(out, lexicon, "human")) != 1:
        return out  # 'away from her' is the one person the request names, or unclear
    return _sub(
        r",\s*but keep (the [a-z ]+?|it|them) away from (?:him|her|them)(?=\s*(?:[,.;!?]|$))",
        r", but not \1",
        out,
    )


def _this_time26(text: str, lexicon: Lexicon) -> str:
    """'… gets the scissors this time (round)': which time it is asks for nothing more; 'this
    time tomorrow' (a time to wait for) is left, and refused."""
    return _sub(r"\s+this time(?: round| around)?(?=\s*(?:[,.;!?]|$))", "", text)


def _questions26(text: str, lexicon: Lexicon) -> str:
    """'Could you let P have X?' (could P have X?); 'Is it okay for X to go in S?' (can X go in
    S?), 'Is it okay for P to have X?' (can P have X?)."""

    def let(m: re.Match[str]) -> str:
        who = m.group(2)
        if who.lower() not in ("him", "her") and _one_name(who, lexicon, "human") is None:
            return m.group(0)
        return f"{m.group(1)} {who} have"

    out = _sub(
        r"\b(could|can|would|will) you (?:please |just |kindly )?let "
        r"((?:person |mr |mrs |ms |miss |dr )?[a-z]+) have\b",
        let,
        text,
    )
    return _sub(
        r"^(?:so |and )?is it (?:ok|okay|alright|all right|fine) for (.+?) to (go|have|get)\b",
        r"can \1 \2",
        out,
    )


def _rather26(text: str, lexicon: Lexicon) -> str:
    """'she'd rather have the chips', 'Bob would prefer the cup': she wants the chips (a want, read
    as wants are); 'would rather not' is left."""
    return _sub(
        r"\b(he|she|they|[a-z]+)(?:'d| would) (?:rather have|prefer to have|prefer)\b(?! not)",
        r"\1 wants",
        text,
    )


def _apology26(text: str, lexicon: Lexicon) -> str:
    """'Ever so sorry, but …' opening a request: 'So sorry, but …' (an apology before anything
    is said corrects nothing)."""
    return _sub(r"^(?:ever so|terribly|awfully|really|very) sorry\b", "so sorry", text)


def _made_it26(text: str, lexicon: Lexicon) -> str:
    """'…, no wait, he's already had his, make it the cup instead': a remark about a person
    between the cue and 'make it / make that', naming nothing in the scene, says why; the
    correction is 'make it …'."""

    def made(m: re.Match[str]) -> str:
        if not _names_nothing(m.group(2), lexicon):
            return m.group(0)
        return f"{m.group(1)}, {m.group(3)}"

    return _sub(
        r"(,\s*(?:no wait|no|wait|sorry|actually|oh no|hang on))\s*,\s*"
        r"((?:he|she|they)(?:'s|'ve| has| have| is| are)(?: already| just)? [a-z' ]+?)\s*,\s*"
        r"(make (?:it|that)\b)",
        made,
        text,
    )


def _choices26(text: str, lexicon: Lexicon) -> str:
    """Choices said another way: 'any way round' / 'any which way' (either way round); 'The pair
    of them, bottle and chips, …' / 'Both of them, …' (both, …); 'both drinks, the cup and the
    bottle' (the cup and the bottle). (A choice opener before its list, 'One of the two, the cup
    or the bottle, …', 'Either thing will do for P, X or Y', is _choice_listed26s.)"""
    out = _sub(
        r"\bany (?:which )?way(?: round| around)?(?=\s*(?:[,.;!?]|$))", "either way round", text
    )

    def described(m: re.Match[str]) -> str:
        if not _names_nothing(m.group(1), lexicon):
            return m.group(0)  # 'both cups, …' names them: read as said
        if len(_objects_listed(m.group(2), lexicon)) != 2 or _ids(m.group(2), lexicon, "human"):
            return m.group(0)
        return m.group(2)

    # "give her both drinks, the cup and the bottle": a description the scene does not name,
    # then the two objects it describes
    out = _sub(
        r"\bboth ([a-z]+s),\s*((?:the )?[a-z]+ and (?:the )?[a-z]+)(?=\s*(?:[,.;!?]|$))",
        described,
        out,
    )

    def both(m: re.Match[str]) -> str:
        if len(_objects_listed(m.group(1), lexicon)) != 2 or _ids(m.group(1), lexicon, "human"):
            return m.group(0)
        return f"Both, {m.group(1)}"

    return _sub(
        r"^(?:the pair of them|both of them|the two of them),\s*"
        r"((?:the )?[a-z]+ and (?:the )?[a-z]+)(?=\s*,)",
        both,
        out,
    )


def _let_go26(text: str, lexicon: Lexicon) -> str:
    """'…, but not the chips, leave those': leaving what was just left out says it again; ',
    it's the last one' / 'it's the only one' after a request: a remark about the object asked
    for, asking nothing more."""
    out = _sub(
        r"(\bnot (?:the [a-z ]+?|those|that|them|it))\s*,\s*leave (?:those|them|that|it|that one)"
        r"(?: be| alone| there| where (?:they are|it is))?(?=\s*(?:[,.;!?]|$))",
        r"\1",
        text,
    )
    return _sub(
        r",\s*(?:it's|it is|that's|that is) the (?:last|only) one(?: left)?\s*([.!]?)\s*$",
        r"\1",
        out,
    )


# what a remark run on without a comma may not hold: it could ask, point back, negate or order
_RUN_ON_HELD26 = re.compile(
    r"\b(?:not|n't|no|never|it|them|him|her|his|me|my|i|you|instead|first|then|later|after|before|"
    r"wants?|needs?|give|hand|bring|take|put|place|have|get|gets|one|other|both|all|each|too|also|"
    r"only|just|either|or|and|but|if|when|once|two|three|four|five|six|several|there|here)\b",
    _F,
)
# a word before 'he's' / 'she's' that joins what follows to the request as a clause of it
_JOINS26 = (
    r"\b(?:after|before|once|when|whenever|until|till|if|unless|as|because|cos|since|so|and|but|"
    r"or|while|whilst|that|which|who|where|then|than|though|although|in case)\s*$"
)


def _run_on_mid36(text: str, lexicon: Lexicon) -> str:
    """Session 36: a remark "he's been …" / "she's been …" run on after an object, ending at a
    comma or before a new clause of a person's want, taken off when it names nothing and holds
    no word that could ask, point back, negate or order (_RUN_ON_HELD26) or want (_WANTING36),
    and no word joins it to what is before (_JOINS26); a new clause after it starts a
    sentence."""
    if " been " not in text:
        return text

    def dropped(m: re.Match[str]) -> str:
        said = re.sub(r"^(?:he|she)(?:'s| has) been", "", m["r"].lower())
        before = text[: m.start()]
        if (
            not _names_nothing(m["r"], lexicon)
            or _RUN_ON_HELD26.search(said)
            or _WANTING36.search(said)
            or re.search(_JOINS26, before, _F)
            or not _ids(before.rsplit(",", 1)[-1], lexicon, "object")
        ):
            return m[0]
        after = text[m.end() :]
        return "" if after.lstrip()[:1] in (",", ";") else "."

    return _RUN_ON_MID36.sub(dropped, text)


def _run_on_remark26(text: str, lexicon: Lexicon) -> str:
    """A remark about a person run on after a request with no mark ("give the bottle to bob would
    you ta mate he's round the back", "chuck the bottle over to person a she's gasping thx"): from
    'he's' / 'she's' / 'they're' to the end, naming nothing in the scene and holding no word that
    could ask, point back, negate or order (_RUN_ON_HELD26), it is taken off when what is left
    names something."""
    m = re.search(
        r"(?<![,.;:!?])\s+((?:he|she|they)(?:'s|'re| is| are| has| have|'ve) [a-z' ]+?)\s*([.!]?)$",
        text,
        _F,
    )
    if m is None or not _names_nothing(m.group(1), lexicon):
        return text
    said = re.sub(r"^(?:he|she|they)(?:'s|'re|'ve)?", "", m.group(1).lower())
    if _RUN_ON_HELD26.search(said) or not _names(text[: m.start()], lexicon):
        return text
    if re.search(_JOINS26, text[: m.start()], _F):
        return text  # "… after they're there": a clause joined to the request, not a remark
    return text[: m.start()] + m.group(2)


def _headed26(text: str, lexicon: Lexicon) -> str:
    """'Both of them want feeding: chips for Person A, bottle for Person B': a header saying that
    the people named after it want something, before the colon, asks nothing by itself (taken off
    when what follows names two people); 'Clear the lot onto the shelf' (put it all there)."""
    m = re.match(
        r"^(?:both of them|they both|the two of them|both) (?:want|need)s? [a-z]+ing\s*:\s*",
        text,
        _F,
    )
    if m is not None and len(_ids(text[m.end() :], lexicon, "human")) == 2:
        text = text[m.end() :]
    return _sub(
        r"^clear (the lot|everything|it all|all of it|all the things) (onto|into|on|in)\b",
        r"put \1 \2",
        text,
    )


def _corrected_first26(text: str, lexicon: Lexicon) -> str:
    """'The chips, no, the bottle, (silly me,) to Person A': the one object named (or a word
    naming nothing of the scene), corrected before its recipient is said — the bottle to Person
    A."""

    def first(m: re.Match[str]) -> str:
        said = _names(m.group(1), lexicon)
        if said and _one_name(m.group(1), lexicon, "object") is None:
            return m.group(0)  # what is corrected is an object, or nothing of the scene
        if _one_name(m.group(2), lexicon, "object") is None:
            return m.group(0)
        return f"{m.group(2)} "

    return _sub(
        r"^(the [a-z]+),\s*(?:no|sorry|no wait|i mean|no,\s*sorry),\s*(the [a-z]+),\s*"
        r"(?:(?:silly me|my mistake|my bad|my fault|sorry),\s*)?(?=(?:to|for) )",
        first,
        text,
    )


def _while26(text: str, lexicon: Lexicon) -> str:
    """A closing 'while it's quiet' / 'while you're there' / 'while you're at it': when to do it,
    now, asks for nothing more (taken off when it names nothing in the scene)."""
    m = re.search(
        r"(?:,\s*|\s+)while (?:it's|it is|you're|you are|we're|we are) ([a-z' ]+?)\s*([.!?]?)$",
        text,
        _F,
    )
    if m is None or m.start() == 0 or not _names_nothing(m.group(1), lexicon):
        return text
    if re.search(r"\b(?:not|n't|him|her|them|me|later|tomorrow|done|finished)\b", m.group(1), _F):
        return text
    return text[: m.start()] + m.group(2)


# -- the speaker's remarks: one rule (session 22's and session 24's, merged in session 25) ---------
#
# The speaker talking about themself asks nothing, wherever it is said ("I'm the farmer, my boots
# are filthy so I won't come in.", "Then I'm off to warm up my voice.", "…, I keep losing it",
# "Would you mind taking the blue mug over to Carol while I sort the rota?", "I'm the vicar, here to
# bless the new wing."). A stretch is the text between punctuation marks, or from a joining word
# before 'I' / 'my' to the next mark. It is a remark, taken off, when
# - its subject is the speaker ('I', 'I'm', 'my back's', 'my new boots are', "it's my day off",
#   "that's me"), after joining words ('and', 'so', 'then', 'while', 'because', 'look', …); or,
#   right after such a stretch in its sentence, it says what the speaker is doing or why they are
#   here ('just dropping the new frames round', 'only in to water the spider plants', 'here to
#   bless the new wing'), warns of the speaker's own things ('mind the smoke on my jacket') or is
#   a sentence that asks nothing by itself (_inert_sentence);
# - it names nothing in the scene (nor by a typo);
# - it holds no word that asks for something (a verb of the grammar's tasks or of wanting, 'for
#   me', 'to me', 'have it'), chooses, orders, corrects, doubts or puts off (_SPEAKER_HELD).
#   Pronouns are allowed ("I keep losing it", "I misheard her", "I could see him shaking"): with
#   no verb of giving or wanting, a clause of the speaker's cannot ask for what the pronoun names;
# - no correction cue follows it, unless nothing has been named before it: taken off between what
#   the speaker corrects and the correction, it would join the two ("… to Zoe, sorry, Noah, I
#   always mix the two of them up, correction, the globe");
# and what is left names something. What opens its sentence goes with it when that asks nothing
# either: interjections, greetings and apologies ('Oh, sorry, …', 'Sorry to bother you, …',
# 'Afternoon, …'), a warning about the speaker's own things. 'I' or 'me' as a recipient stays, and
# is refused ("give me the cup", "I need the cup", "I'd like it", "then I'll have it").
_SPEAKER_OPEN = re.compile(
    r"^(?:(?:and|so|then|while|whilst|as|because|cos|since|but|oh|well|now|look)\s+)*"
    r"(?:(?:after that|afterwards|after this),?\s+)?"  # session 29 (12s): _speaker_plan29s
    r"(?:i(?:'m|'ve|'ll|'d)?|my (?:[a-z]+ ){1,2}(?:is|are|was|were|has|have|keeps?)|"
    r"my (?:[a-z]+ )?[a-z]+'s|it's (?:my|only me|just me)|that's me|"
    # session 29 (12s): "(I've) only just come off the gallops": the speaker's 'I've' left out
    r"(?:only |just ){1,2}(?:come|got|been|arrived|finished)(?= (?:off|in|back|from|out|up)\b))\b",
    _F,
)
# what may follow such a stretch in its sentence, still about the speaker
_SPEAKER_MORE = re.compile(r"^(?:just|only|still|here (?:to|for)|back|off)\b", _F)
# what such a following stretch may not hold: 'just not the blue one', 'only the one', 'just the
# red' after the request single out or leave out what it asks for (session 27: the speaker's
# opener had let "…, give Alice a mug, just not the blue one. Good robot." lose its exclusion)
_SPEAKER_MORE_HELD = re.compile(
    r"\b(?:not|no|never|none|nothing|nobody|neither|nor|without|except|but|one|ones|two|three|"
    r"both|all|any|either|whichever|other|another|else)\b|n't\b",
    _F,
)
# a warning about the speaker's own things
_MIND_MINE = re.compile(r"^mind (?:the|my) [a-z ]+\bmy [a-z]+$", _F)
_SPEAKER_HELD = re.compile(
    r"\b(?:give|gives|hand|pass|bring|take|put|place|set|get|send|move|fetch|grab|drop|pop|"
    r"carry|deliver|leave|keep(?! [a-z]+ing\b)|want|wants|wanted|needs?(?! to\b)|needed|like|love|"
    r"fancy|prefer|"
    r"have (?:it|them|that|this|those|these|one|both|all)|for me|to me|me the|me that|me it|"
    r"which|whichever|who|whoever|whom|whose|either|or|neither|nor|instead|rather|actually|"
    r"first|next|last|before|after|once|when|until|till|unless|if|later|tomorrow|wrong|mean|"
    r"meant|mistake|change|changed|swap|cancel|scratch|forget|forgot|remember|know|sure|"
    r"track|ignore|wait|hang|hold|other|others|another|else|same|rest|each|every|too|also|"
    r"as well|only one)\b|\d",
    _F,
)
# Session 28 (12s): a time or a place of the speaker's own said with 'next' / 'last' / 'first' /
# 'till' ("I've got four minutes till my next run", "I'm off to the next job", "I've been on since
# seven last night", "from the unit next door", "since first light") orders nothing the request
# asks: such a phrase is not a held word of the stretch. Its noun must not be a word that could
# stand for an object ('the next one', 'the last thing', 'the next item'); the stretch must still
# name nothing in the scene.
_SPEAKER_TIMES = re.compile(
    r"\b(?:(?:till|until|before|after|since|for|to) )?(?:the|my|our|his|her|their|this) "
    r"(?:next|last) (?!(?:ones?|things?|items?|bits?|lot|rest|others?|person|people)\b)"
    r"[a-z]+\b|\b(?:since )?(?:last|next) (?:night|week|month|year|door)\b|"
    r"\b(?:since )?first (?:light|thing)\b",
    _F,
)


# Session 29 (12s): the speaker's own next act, said with a verb of the grammar ("then I can get
# the tape measure out", "and I'll give you a trim after", "then I'll get the next patient
# through", "I'm only here to take bloods", "and after that I'm back to re-covering this
# armchair"): the speaker is the verb's subject (or 'here to' says why they came), so the verb
# asks the robots for nothing. The words after the verb up to the stretch's end must name nothing
# in the scene (the stretch's rule) and hold no pronoun or count that could stand for what the
# request names ('I'll take it', 'I can get the other one', 'I'll give him both'), and no 'me'
# ('I'll get me the cup' asks); an 'after' / 'afterwards' / 'later' closing it orders only the
# speaker's act. "after that" / "afterwards" opening such a stretch is when the speaker does it.
_SPEAKER_DOES29S = re.compile(
    r"\b(?:i(?:'ll|'d| will| would| can| could| must| shall|'m going to| am going to)?|"
    r"(?:here|in|over|round) to) (?:just |then |quickly )?(?:give|get|take|bring|fetch|grab|put|"
    r"move|carry|send|set|keep|leave|drop|pop|pass|hand)\b"
    r"(?P<what>(?: (?!(?:it|them|that|this|those|these|one|ones|both|all|each|either|other|"
    r"another|else|rest|me|him|her|us|first|next|last)\b)[a-z'-]+)+?)"
    r"(?: (?:after|afterwards|later))?$",
    _F,
)
_SPEAKER_AFTER29S = re.compile(
    r"^(?:(?:and|so|then) )?(?:after that|afterwards|after this),? (?=i\b|i'm\b|i'll\b)", _F
)


# 'every' / 'each' before a word that is no name of the scene ("I've got gold leaf stuck to every
# finger"): counts the speaker's own things, not the scene's (the stretch must still name
# nothing); 'every one', 'each of them', 'every thing' are left held
_SPEAKER_EVERY29S = re.compile(
    r"\b(?:every|each) (?!(?:ones?|things?|items?|bits?|of|the|them|those|these|it|person|"
    r"people|body|way)\b)[a-z]+\b",
    _F,
)
# 'not … a thing' ("I can't touch a thing", "I didn't say a thing"): nothing, no object
_NOT_A_THING29S = re.compile(r"(?:n't|\bnot) (?:[a-z]+ )?a (?:single )?thing\b", _F)


def _speaker_plan29s(piece: str) -> str:
    """``piece`` (a stretch of the speaker's) without the speaker's own next act said with a verb
    of the grammar, and without 'after that' opening it (the rule above), nor 'every <word of no
    name>'; as it was otherwise."""
    piece = _SPEAKER_EVERY29S.sub("", _SPEAKER_AFTER29S.sub("", piece.strip()))
    m = _SPEAKER_DOES29S.search(piece)
    if m is None or not _SPEAKER_OPEN.match(piece):
        return piece
    return piece[: m.start()]


def _held_but_times(piece: str) -> bool:
    """Whether ``piece`` holds a word of _SPEAKER_HELD outside the speaker's own times and places
    (_SPEAKER_TIMES) and the speaker's own next act (_speaker_plan29s)."""
    return bool(
        _SPEAKER_HELD.search(_speaker_plan29s(" ".join(_SPEAKER_TIMES.sub(" ", piece).split())))
    )


# what may open the sentence of such a stretch, taken off with it
_SPEAKER_OPENER = re.compile(
    r"(?:oh|ah|um|uh|er|erm|well|right|hi|hello|hiya|hey|sorry|so sorry|oh sorry|morning|"
    r"afternoon|evening|good (?:morning|afternoon|evening)|hi there|hello there|"
    rf"(?:so )?sorry {_BOTHERING})",
    _F,
)
_SPEAKER_CUE = re.compile(
    r"\b(?:no(?! (?:trouble|bother|rush|hurry|problem|worries|fuss))|nope|sorry|correction|"
    r"actually|wait|hang on|hold on|i mean|rather|scratch|oops|whoops|make that|instead|not)\b",
    _F,
)


# a remark needs one of these words (its subject, or a call's '!')
_REMARK_OPEN = re.compile(
    r"\b(?:i|i'm|i've|i'll|i'd|im|ive|my|me|we|we're|we've|you|you're|you've|your|hope|hoping|"
    r"have a|force of|old|chef|kitchen|workshop)\b|!",
    _F,
)
# where a stretch ends: a punctuation mark (a full stop before a space or the end), a dash
_REMARK_MARKS = re.compile(
    r"(\s*(?:[,;:!?—–]|\.\.\.|\.(?=\s|$))(?:\s*(?:[,;:!?—–]|\.\.\.|\.(?=\s|$)))*\s*|\s+-\s+)"
)
_REMARK_JOINS = (",", ";", ":", "—", "–", "-")
_STOPS = (".", "!", "?", "...")


def _speaker_more_held(piece: str, lexicon: Lexicon) -> bool:
    """Whether ``piece``, said after the speaker's stretch ('just …', 'only …'), could single out
    or leave out an object: a negation, a count or a choice ('one', 'both', 'other'), or a word
    telling the scene's objects apart ('red', 'big')."""
    if _SPEAKER_MORE_HELD.search(piece):
        return True
    adjectives = _adjectives(lexicon)
    return any(w in adjectives for w in re.findall(r"[a-z]+", piece.lower()))


# asides that ask nothing, after or inside the request
_ASIDES22: tuple[tuple[str, str], ...] = (
    # "…, since you're there", "and since you're going over there, …": the hearer is passing
    (
        r"\s*,?\s*(?:and )?since you're (?:there|here|at it|passing|up|going (?:over )?(?:there|"
        r"that way))\s*(?=[,.!]|$)",
        "",
    ),
    # "…, that's all she needs": nothing more for her
    (r"\s*,\s*that's all (?:he|she|they) (?:needs?|wants?)(?=\s*[.!]?\s*$)", ""),
    # "…, go on", "…, go on then": urging
    (r"\s*,\s*go on(?:,? then)?(?=\s*[.!]?\s*$)", ""),
    # session 27: "…, he told me so himself", "…, she said so": who said it is so, at the end;
    # session 29 (12s): "…, he told me before", "…, they told me while I was mopping" (when, and
    # what the speaker was doing then)
    (
        r"\s*,\s*(?:he|she|they) (?:told me so|said so|told me|said as much)"
        r"(?: (?:himself|herself|themselves|earlier|before|just now|this morning|yesterday))?"
        r"(?:,? (?:while|when|as) i was [a-z]+ing(?: (?:up|out|round|about))?)?(?=\s*[.!]?\s*$)",
        "",
    ),
)
# want frames said another way (rewritten whatever they name)
_FRAMES22: tuple[tuple[str, str], ...] = (
    # "What Carol's after is the crisps": what Carol is after is
    (r"\b(what [a-z]+(?: [a-z]+)?)'s after is\b", r"\1 is after is"),
    # "is shouting for", "is calling for", "is waiting for": wants
    (
        r"\s*(?:\bis|'s|\bare|'re|\bhas been|'s been) (?:shouting|calling|yelling|screaming|"
        r"begging|clamou?ring|pleading|waiting|wanting) for\b",
        " wants",
    ),
    (r"\s*(?:\bis|'s|\bare|'re) wanting\b", " wants"),
    # session 26: "Person A's been waiting on it" (waiting for it)
    (r"\s*(?:\bis|'s|\bare|'re|\bhas been|'s been|\bhave been|'ve been) waiting on\b", " wants"),
    # session 35 (12s): "Person A has been waiting ages for those chips" (how long, as _words
    # reads it)
    (
        r"\s*(?:\bis|'s|\bare|'re|\bhas been|'s been|\bhave been|'ve been) (?:still )?waiting "
        r"(?:ages|forever|a while|so long|for ages) for\b",
        " wants",
    ),
)
# a purpose after the object: 'for marking up his draft', 'for her collage of the solar system'
_PURPOSE22 = re.compile(
    r"\s+for (?:(?:his|her|their|my|our) [a-z]+(?: of (?:the |a |an |his |her |their )?[a-z]+"
    r"(?: [a-z]+)?)?|[a-z]+ing(?: [a-z]+){0,4})(?=\s*(?:[.!;]|,\s*(?:please|thanks|ta)\b|$))",
    _F,
)
# 'the one she was looking at earlier' after an object there is one of
_THE_ONE22 = re.compile(
    r"(\bthe ([a-z]+(?: [a-z]+)?)),\s*the one (?:that )?(?:she|he|they|i|we|you)(?:'s|'d| was| "
    r"is| were| had| has)? [a-z ]+?(?=\s*[.!]?\s*$)",
    _F,
)
_PURPOSE_HELD22 = re.compile(
    r"\b(?:them|those|these|it|one|ones|other|another|rest|each|both|all|every|either|or|and|"
    r"then|first|not|no|never|instead|too|also|me|us)\b|n't\b",
    _F,
)


def _asides22(text: str, lexicon: Lexicon) -> str:
    """Session 22: asides that ask nothing ("since you're there", "that's all she needs", "go
    on", "after that walk" after being desperate for something), want frames ('is shouting
    for', 'is wanting', "What Carol's after is"), a purpose after the object ('for marking up
    his draft', 'for her collage of the solar system'), and a description that picks the one
    object there is ('the apple, the one she was looking at earlier'). Taken off only where
    they name nothing in the scene and hold no word that counts, chooses, points back or
    negates."""
    out = text
    for pattern, repl in _ASIDES22:
        out = _drop(pattern, out, lexicon, repl)
    for pattern, repl in _FRAMES22:
        out = _sub(pattern, repl, out)
    # "is gasping for X after that walk": why they want it, a time past
    out = _sub(
        r"\b((?:gasping|dying|desperate|starving|parched|thirsty|famished|hungry)\b[^.!?,;]*?)(\s+"
        r"after (?:that|all that|her|his|their) [a-z]+)(?=\s*[.!]?\s*$)",
        lambda m: m.group(1) if _names_nothing(m.group(2), lexicon) else m.group(0),
        out,
    )

    def purpose(m: re.Match[str]) -> str:
        said = m.group(0)
        before = _names(out[: m.start()].rsplit(",", 1)[-1], lexicon)
        if (
            not before
            or not all(r.kind == "object" for r in before[-1].refs)
            or _PURPOSE_HELD22.search(said)
            or not _names_nothing(said, lexicon)
        ):
            return said
        return ""

    out = _PURPOSE22.sub(purpose, out)

    def the_one(m: re.Match[str]) -> str:
        said = m.group(0)[len(m.group(1)) :]
        if _only(m.group(1), lexicon, "object") and (
            not _PURPOSE_HELD22.search(said.replace("the one", ""))
            and _names_nothing(said, lexicon)
        ):
            return m.group(1)
        return m.group(0)

    out = _THE_ONE22.sub(the_one, out)
    return " ".join(out.split()) or text


def _one_person22(text: str, lexicon: Lexicon) -> str:
    """Session 22: a name and a role of the same one person said together ('emma the visitor',
    'nurse ruth', 'the technician Omar') read as the name alone."""

    def same(m: re.Match[str]) -> str:
        first, second = m.group(1), m.group(2)
        a, b = _ids(first, lexicon, "human"), _ids(second, lexicon, "human")
        if (
            len(a) == 1
            and a == b
            and _only(first, lexicon, "human")
            and _only(second.removeprefix("the "), lexicon, "human")
        ):
            return first if m.group(0).lower().startswith(first.lower()) else second
        return m.group(0)

    if not _said_any(text, (" the ", "nurse ", "doctor ", "chef ", "mr ", "mrs ")):
        return text
    out = _sub(r"\b([a-z]+) (the [a-z]+)\b", same, text)
    return _sub(r"\b((?:nurse|doctor|dr|chef|teacher|officer)) ([a-z]+)\b", same, out)


# "Don't touch the crisps, they're fine where they are.": an object left where it is
_LEFT_ALONE22 = re.compile(
    r"^(?:please )?(?:(?:don't|do not|never) (?:touch|move|bother with)|leave) (the [a-z ]+?)"
    r"(?: alone| where (?:it is|they are)| be)?(?:,\s*(?:it's|they're|it is|they are) (?:fine|ok|"
    r"okay|good) (?:where (?:it is|they are)|as (?:it is|they are)))?\s*[.!]$",
    _F,
)
_POINTS_BACK22 = re.compile(r"\b(?:it|them|those|these|that|everything|all|rest|other)\b", _F)


def _negation22(text: str, lexicon: Lexicon) -> str:
    """Session 22: exclusions that say nothing more than the request ('the white plate, not the
    blue', where the blue plate is another plate; 'whichever cup isn't the green one', of two
    cups), an object said to be left alone in a sentence of its own ("Don't touch the crisps,
    they're fine where they are.") when no other sentence names it, and a person said to get
    nothing with a reason ("Person A's had her lot, so nothing for her; …", 'Never mind Alice
    for now, …'), for _nothing_for20 to take off when they are named nowhere else."""
    out = text

    def not_other(m: re.Match[str]) -> str:
        kept = f"the {m.group(1)} {m.group(2)}"
        other = _ids(f"the {m.group(4)} {m.group(2)}", lexicon, "object")
        # session 51 (12s): the other is a K too ("…, and the salt shaker, not the lemon" named
        # the lemon by 'lemon' alone, and the 'not' was lost: 12c's chains fuzz)
        kinds = _ids(f"the {m.group(2)}", lexicon, "object")
        if (
            _only(kept, lexicon, "object")
            and len(other) == 1
            and other != _ids(kept, lexicon)
            and other | _ids(kept, lexicon) <= kinds
        ):
            # "The red mug, not the blue, goes to Alice": the subject keeps no comma
            before = out[: m.start()].lower().rstrip()
            subject = before == "the" or before.endswith((". the", "! the", "; the"))
            return f"{m.group(1)} {m.group(2)}{'' if subject else m.group(5)}"
        return m.group(0)

    # "the white plate, not the blue (one | plate)": the blue plate is another plate
    out = _sub(
        r"(?<=\bthe )([a-z]+) ([a-z]+)(\s*,\s*not the ([a-z]+)(?: one| \2)?)(\s*,|(?=\s*[.!;]|$))",
        not_other,
        out,
    )

    def whichever(m: re.Match[str]) -> str:
        cat = m.group(1)
        both = _ids(f"the {cat}s", lexicon, "object") | _ids(f"the {cat}", lexicon, "object")
        not_it = _ids(f"the {m.group(2)} {cat}", lexicon, "object")
        if len(both) == 2 and len(not_it) == 1 and not_it < both:
            (left,) = both - not_it
            return f"the {_said(left, lexicon)}"
        return m.group(0)

    # "Whichever cup isn't the green one", "the cup that isn't the green one" (of two cups)
    out = _sub(
        r"\b(?:whichever|the) ([a-z]+) (?:that )?(?:isn't|is not) the ([a-z]+)(?: one)?\b"
        r"(?! (?:on|in|at|by|near))",
        whichever,
        out,
    )
    # "Don't touch the crisps, they're fine where they are. Bob gets the bottle."
    parts = re.split(r"(?<=[.!])\s+", out.strip())
    if len(parts) > 1:
        keep = []
        for n, part in enumerate(parts):
            said = _LEFT_ALONE22.match(part)
            rest = " ".join(parts[:n] + parts[n + 1 :])
            if (
                said is not None
                and _only(said.group(1), lexicon, "object")
                and not (
                    _ids(said.group(1), lexicon, "object") & _ids(rest, lexicon, "object")
                    or _POINTS_BACK22.search(rest)
                )
            ):
                continue
            keep.append(part)
        if keep and len(keep) < len(parts):
            out = " ".join(keep)
    # "Person A's had her lot, so nothing for her": nothing for Person A
    out = _sub(
        r"(?:^|(?<=[.;!?] ))([A-Z][\w ]*?)(?:'s| has| is)(?: had| done| finished| sorted)?"
        r" (?:her|his|their) (?:lot|share|fill|turn|bit)\s*,\s*so nothing (?:for|to) "
        r"(?:her|him|them)\b",
        lambda m: f"nothing for {m.group(1)}" if _only_person(m.group(1), lexicon) else m.group(0),
        out,
    )
    # "Never mind Alice for now, …": not Alice
    return _sub(
        r"(?:^|(?<=[.;!?] ))never mind ([A-Z][\w ]*?)(?: for (?:now|the moment|today))?,\s*"
        r"(?=(?-i:[a-z]|[A-Z]))",
        lambda m: (
            f"nothing for {m.group(1)}. " if _only_person(m.group(1), lexicon) else m.group(0)
        ),
        out,
    )


def _repairs_to32l(word: str | None, lexicon: Lexicon) -> bool:
    """Session 32 (lead): whether the word after a closing 'sorry' ('…, no, to Mr Novak, sorry,
    Marco.') names someone or something of the scene: then 'sorry' repairs to it, and it is not
    a word of address to drop with the apology ('…, my mistake, folks'), as it had been (the tongs
    went to Mr Novak: 12c's repairs fuzz)."""
    return word is not None and not _names_nothing(word, lexicon)


def cue_closes_sentence(after: str) -> bool:
    """Whether the words after a correction cue ('sorry', 'no', 'my mistake', …) open with a full
    stop or '!': the cue then closes its sentence ('Bob gets the chips, sorry. Carol needs …'),
    an apology for or an answer to what came before, and corrects nothing after it (review of
    session 34: ``_corrections19``'s bare apology before a sentence with a request of its own;
    offline ``_asked_again34s`` keeps its narrower test, a comma after the cue, which this
    excludes too: a wider one there would change readings)."""
    return re.match(r"\s*[.!]", after) is not None


# a bare apology ('…, sorry. '), not 'no, sorry' or 'sorry, I mean': closing its sentence when
# cue_closes_sentence says so of what follows it
_CLOSING_SORRY34L = re.compile(r"\s*,\s*(?:(?:oh|ah|eh),? )?(?:sorry|so sorry|apologies)", _F)


def _names_verb34l(after: str) -> bool:
    """Whether the sentence ``after`` opens with a request of its own: a verb of the grammar's
    tasks or a request's opening (``_opens_request``), or a subject and a verb after it
    (``_VERB_NEXT19``: 'Carol needs …', 'What Carol needs is …')."""
    first = re.split(r"[.!?;]", after)[0]
    words = re.findall(r"[a-z]+", first.lower())
    return bool(words) and (
        words[0] in VERBS or _opens_request(first) or any(_VERB_NEXT19.match(w) for w in words[1:4])
    )


# a cue closing a correction, said of it ('…, no, the apple, my mistake'): one list for the
# three places _corrections19 takes it off
_CLOSING_CUE = r"(?:my (?:mistake|bad)|sorry|apologies|whoops|oops)"


def _corrections19(text: str, lexicon: Lexicon) -> str:
    out = _sub(r"(?:^|(?<=[.!?]))\s*(?:sorry|so sorry|apologies)\s*[.!]+\s*", " ", text).strip()
    out = _sub(r"^(?:sorry|so sorry|apologies)\s*,\s*(?=[a-z])", "", out).strip()
    out = _sub(r",\s*(?:sorry|so sorry|apologies)\s*([.!]?)$", r"\1", out).strip()
    # a cue after the correction ('…, my mistake, folks'): said of what came before it
    out = _sub(
        # session 34 (12s): the word of address with 'my' and no comma ('my mistake my friend')
        rf"(,\s*no,[^,]+?),\s*{_CLOSING_CUE}"
        r"(?:,\s*([a-z]+)|,?\s+my\s+([a-z]+))?"
        r"\s*([.!]?)$",
        lambda m: (
            m.group(0)
            if _repairs_to32l(m.group(2) or m.group(3), lexicon)
            else m.group(1) + m.group(4)
        ),
        out,
    )
    # session 37 (lead): the same cue closing the repair's sentence, another sentence after it
    # ("Give Person B the bottle, er, no, the apple, my mistake. Person B's going to need the
    # chips."): said of the repair before it, not a correction of everything before the next
    # sentence (12c's fuzz: it had dropped the apple)
    out = _sub(
        rf"(,\s*no,[^,.!?;]+?),\s*{_CLOSING_CUE}\s*([.!])"
        r"(?=\s+\S)",
        r"\1\2",
        out,
    )
    m = _rx(rf"(\s*[,.;:!—–-]\s*){_CUE19}\b\s*[,.:;!—–-]?\s*(?=[a-z])").search(out)
    if m is not None and m.start() > 0:
        before, after = out[: m.start()], out[m.end() :]
        if _APOLOGY19.search(before) or _rx(_BOTHER19).match(after):
            # "Excuse me, sorry, I'm covering today", "sorry to bother": an apology for the
            # interruption, not a correction of what was said before it
            return text
        sorry = _CLOSING_SORRY34L.match(m.group(0))
        closes = sorry is not None and cue_closes_sentence(m.group(0)[sorry.end() :])
        if closes and _names_verb34l(after):
            # session 34 (lead): "Bob gets the chips, sorry. What Carol needs is the bottle.": a
            # bare apology closing its sentence, and a sentence after it that asks for something
            # by its own verb, is an apology, as the grammar reads "…, sorry. Carol needs the
            # bottle." (12's fuzz: taken for a correction, the chips were dropped)
            return text
        if re.search(r"\b(?:and|then|and then|but)\s*$", before, _F):
            # "… and then, sorry, the chips to Person A": a pause after a conjunction
            return f"{before} {after}"
        after = _sub(r"^(?:no|sorry|i misspeak|i meant?)\b,?\s*", "", after)  # (29s: 'I meant')
        if _VERB_NEXT19.match(after) and _only_person(re.split(r"[,.;]", before)[-1], lexicon):
            # "Alice, sorry, wants the crisps": a pause before the verb, not a correction
            return f"{before} {after}"
        last = re.split(r"[.!?;]", before.strip(" .!?"))[-1]
        steps = sum(1 for w in re.findall(r"[a-z]+", last.lower()) if w in VERBS)
        if steps > 1 or re.search(r"\bthen\b", last, _F):
            # "Give Bob the cup, then give Alice the apple. Scratch that, …": which part?
            return text
        if _names(before, lexicon) and _names(after, lexicon):
            same = _rx(r"\s+((?:to|for) [A-Z][\w ]*?)\s*([.!]?)$").search(after)
            if same and before.rstrip(" .!").lower().endswith(same.group(1).lower()):
                # "The hammer for Jess, no, the drill for Jess": the same person said again
                after = after[: same.start()] + same.group(2)
            instead = _rx(r"^(give|hand|pass) ([A-Z][\w ]*?)(?: instead)?\s*([.!]?)$").match(after)
            said = _ids(before, lexicon, "object")
            if instead and _only_person(instead.group(2), lexicon) and len(said) == 1:
                # "Put bottle on shelf, no, give Alice instead": the same object
                obj = _said(next(iter(said)), lexicon)
                after = f"{instead.group(1)} {instead.group(2)} the {obj} instead{instead.group(3)}"
            out = f"{before}, no, {after}"
            out = _sub(
                rf",\s*{_CLOSING_CUE}(?:,\s*([a-z]+))?"
                r"\s*([.!]?)$",
                lambda m: m.group(0) if _repairs_to32l(m.group(1), lexicon) else m.group(2),
                out,
            )
            same = _rx(r"(?<=, no, )(.+?)\s+((?:to|for) [A-Z][\w ]*?)\s*([.!]?)$").search(out)
            if same and out[: same.start()].rstrip(" ,no").lower().endswith(same.group(2).lower()):
                out = out[: same.start()] + same.group(1) + same.group(3)
    return out if out else text


def _one_of_a_kind_before(before: str, said: set[str], lexicon: Lexicon) -> str | None:
    """The words in the last sentence of ``before`` that ask for one object of a kind the scene
    has several of ('a mug', 'one mug', 'any mug'), when those objects are all that ``said``
    names: a count after them ('both of them') contradicts it. None if there are none."""
    last = re.split(r"[.!?;]", before)[-1]
    for m in re.finditer(r"\b(?:a|an|one|any|either)\s+([a-z]+)\b", last, _F):
        kind = _kind_of(m.group(1), lexicon)
        if kind is None or m.group(1).lower() != kind:
            continue
        ids = {o.id for o in lexicon.scene.objects if o.category.lower() == kind}
        if len(ids) > 1 and said <= ids:
            return m.group(0)
    return None


def _narrowed_to_one(text: str, lexicon: Lexicon) -> str:
    """'the Xs, sorry, just the one' (the X: which one is not said, so the refusal names its
    readings); session 28: 'only the one' as 'just the one', and after 'both Xs' ("Both mugs to
    Alice, no, just the one"). Also the last of the earlier sessions' steps (``_STEPS``), after
    their closers are taken off ("…, sorry, only the one, cheers")."""

    def just_one(m: re.Match[str]) -> str:
        noun = m.group(2)
        # 'boxes' is 'box' (session 27: 'boxe' named nothing, so the plural was kept and read as
        # every box)
        cut = (noun[:-1], noun[:-2]) if noun.endswith("s") else ()
        single = next((w for w in cut if _ids(w, lexicon, "object")), noun)
        if single == noun or len(_ids(single, lexicon, "object")) < 2:
            return m.group(0)
        return f"{m.group(1)}the {single}{m.group(3)}{m.group(4)}"

    def listed_one(m: re.Match[str]) -> str:
        if len(_ids(m.group(2), lexicon, "object")) < 2:
            return m.group(0)
        return f"{m.group(1)}the {m.group(2)}{m.group(3)}{m.group(4)}"

    narrowed = (
        r",\s*(?:sorry|no|i mean),?\s*(?:just|only) (?:the )?one(?: and that's (?:it|all))?"
        r"\s*([.!]?)$"
    )
    text = _sub(r"^(.*?\b)(?:the|both) ([a-z]+)((?: [^,]*?)?)" + narrowed, just_one, text)
    # "the red mug and the blue mug to Bob, no, just the one" (the earlier steps' 'both mugs')
    return _sub(
        r"^(.*?\b)the [a-z]+ ([a-z]+)(?: and the [a-z]+ \2)+((?: [^,]*?)?)" + narrowed,
        listed_one,
        text,
    )


def _counts19(text: str, lexicon: Lexicon) -> str:
    """Counts and choices said another way: ', all of them' / ', both of them' / ', the two of
    them' / ', every one of them' after the objects they count (the count checked against what
    is named before); 'both of the Xs' (both Xs); 'any X at all' (any X); 'a single X' (one X);
    'a X, either one,' (one X); choice tails after a choice ("doesn't matter which", 'no
    preference', 'at your discretion'); 'the N things that aren't X or Y' (… X and Y); 'the Xs,
    sorry, just the one' (the X: which one is not said, so its readings are named)."""
    out = text

    def counted(m: re.Match[str]) -> str:
        before = out[: m.start()]
        said = _ids(re.split(r"[.!?;]", before)[-1], lexicon, "object")
        word = m.group(1).lower()
        need = {"both": 2, "the two": 2, "the pair": 2, "the three": 3, "the four": 4}.get(word)
        need = 3 if word == "all three" else need
        if not said or (need is not None and len(said) != need) or len(said) < 2:
            return m.group(0)
        one = _one_of_a_kind_before(before, set(said), lexicon)
        if one is not None:  # "a mug, both of them": one mug, or both?
            raise GroundingError(
                f"'{one}' and '{m.group(1)} of them': one or more than one? name them; "
                f"{lexicon.listing('object')}"
            )
        return "" if m.group(2) == "," else m.group(2)

    out = _sub(
        r",\s*(all|both|the two|the pair|the three|the four|every one|each one|all three) of "
        r"them\b"
        r"\s*(,|(?=[.!?]|$))",
        counted,
        out,
    )
    head = _rx(
        r"^(?:(.+?) each (?:take|get|have|receive)s? one(?: thing| item)?|one (?:each|apiece))"
        r"(?:,\s*(?:aye|yes|ok|okay))?\s*[:,]\s*"
    ).match(out)
    if head is not None:
        rest = out[head.end() :]
        people = _ids(rest, lexicon, "human")
        said = _ids(head.group(1) or "", lexicon, "human")
        numbered = re.search(r"\b(both|two|three|four|five)\b", head.group(1) or "", _F)
        many = {"both": 2}.get(numbered.group(1).lower(), 0) if numbered else 0
        many = many or (_NUMBER18.get(numbered.group(1).lower(), 0) if numbered else 0)
        who = said == people if said else (many == len(people) if head.group(1) else True)
        words = re.sub(r"\bperson [ab]\b", "", (head.group(1) or "").lower())
        for it in _names(head.group(1) or "", lexicon):
            words = words.replace(it.text.lower(), " ")
        # only names and words that count them: "I'm not sure, Tom and Mia each …" keeps its
        # opener, and is refused
        who = who and set(re.findall(r"[a-z']+", words)) <= {
            *("and", "the", "both", "two", "three", "four", "of", "them", "people", "all"),
        }
        tasks_said = len(re.findall(r"\b(?:to|for)\b", rest))
        if who and len(_ids(rest, lexicon, "object")) == len(people) == tasks_said:
            if head.group(1) is None:
                _each_of_one29r(out[: head.end()].strip(" :,"), people, lexicon)
            out = rest  # "P and Q each take one: X for P, Y for Q"
    out = _sub(r"\bboth of the (?=(?:[a-z]+ )?[a-z]+s\b)", "both ", out)
    out = _sub(r"\ball of the (?=[a-z]+s\b)", "all the ", out)
    out = _sub(r"\b(any|whichever|either) ([a-z]+) at all\b", r"\1 \2", out)
    out = _sub(r"\ba single (?=[a-z]+\b)", "one ", out)
    out = _sub(r"\bany single one of\b", "any one of", out)  # "any single one of the four things"
    out = _sub(r"\b(?:a|an) ([a-z]+),\s*(?:either|any) one\s*,?", r"one \1", out)
    out = _sub(
        r"\bwhichever ([a-z]+) you (?:like|want|fancy|choose|prefer|please)\b", r"one \1", out
    )
    chose = re.search(r"\b(?:one|any|either|whichever|each)\b", out, _F)
    if chose:
        out = _sub(
            r",\s*(?:(?:it )?doesn't matter which(?: one)?|no preference|at your discretion|"
            r"your (?:choice|call|pick)|dealer's choice|any (?:one )?will do|up to you)\s*"
            r"(?=[,.!?]|$)",
            "",
            out,
        )
    out = _sub(
        r"\b((?:things?|items?|ones?) that (?:aren't|are not|isn't|is not) the [a-z ]+?) or "
        r"(the [a-z ]+?)\b(?=[.!?,]|$)",
        r"\1 and \2",
        out,
    )

    def rest_of(m: re.Match[str]) -> str:
        n = _NUMBER18.get(m.group(1).lower())
        left = _ids(m.group(2), lexicon, "object")
        if n is None or not left or len(lexicon.scene.objects) - len(left) != n:
            return m.group(0)
        return f"everything except {m.group(2)}"

    out = _sub(
        r"\bthe (two|three|four|five) (?:things|items|objects) that (?:aren't|are not) "
        r"(the [a-z ]+?(?: and the [a-z ]+?)*)(?=[.!?,]|$)",
        rest_of,
        out,
    )

    return _narrowed_to_one(out, lexicon)


def _nothing_for20(text: str, lexicon: Lexicon) -> str:
    """Session 20: a person said to get nothing ('…, and nothing for P', "Don't give anything to
    P; …") is no recipient: the words are taken off when P is named nowhere else and the rest
    names one person and no group ('each', 'both', 'everyone' …, where leaving P out would change
    who is meant); an object said not to be the one ('Not the X, only the Y to P') likewise when
    the X is named nowhere else."""

    def drop(m: re.Match[str], words: str, kind: str) -> str:
        if not (_only_person(words, lexicon) if kind == "human" else _only(words, lexicon, kind)):
            return m.group(0)
        rest = text[: m.start()] + " " + text[m.end() :]
        if _ids(words, lexicon, kind) & _ids(rest, lexicon, kind):
            return m.group(0)
        if kind == "human" and len(_ids(rest, lexicon, "human")) != 1:
            return m.group(0)
        if re.search(r"\b(?:each|both|all|every|everyone|everybody|them|they|other)\b", rest, _F):
            return m.group(0)
        return m.group("keep") or ""

    out = _sub(
        r"(?P<keep>)\s*,?\s*(?:and|but)?\s*nothing (?:at all )?(?:for|to) (?P<who>[A-Z][\w ]*?)"
        r"(?=\s*[.;!?]|$)",
        lambda m: drop(m, m.group("who"), "human"),
        text,
    )
    out = _sub(
        r"(?:^|(?<=[.;!?])\s*)(?P<keep>)(?:please )?(?:don't|do not) (?:give|hand|send) "
        r"(?:anything|any of (?:it|them)) to (?P<who>[A-Z][\w ]*?)\s*[;,.]\s*",
        lambda m: drop(m, m.group("who"), "human"),
        out,
    )
    # session 21: "Not Person A, Person B should get the cup.": the person said not to be the
    # one, when named nowhere else
    out = _sub(
        r"(?:^|(?<=[.;!?])\s*)(?P<keep>)not (?P<who>[A-Z][\w ]*?),\s*(?:mind,?\s*)?"
        r"(?=(?-i:[A-Z]))(?!give|hand|pass|bring|put)",  # a name ('Not Bob, give …' stays)
        lambda m: drop(m, m.group("who"), "human"),
        out,
    )
    return _sub(
        r"(?:^|(?<=[.;!?])\s*)(?P<keep>)not (?P<what>the [a-z ]+?),\s*(?:only|just|(?:no,\s*)?"
        r"it's) ",
        lambda m: drop(m, m.group("what"), "object"),
        out,
    )


def _negation19(text: str, lexicon: Lexicon) -> str:
    """Exclusion said another way: 'save the X' after what it is taken from (except the X);
    'except X' with no article; 'that's not' / 'that is not' (that isn't); 'the X that isn't
    <colour or size>' (the one X that is not: named when one is left, else its readings);
    'P, not Q,' and ', not Q' for a person Q said nowhere else (Q is no recipient: taken off)."""
    out = _sub(r"\bthat(?:'s| is) not\b", "that isn't", text)
    out = _sub(r"(?<=[a-z,]) save (?=the |for the )", " except ", out)
    out = _sub(
        r"\bexcept (?!the\b|for\b|a\b|an\b|that\b)([a-z]+)\b",
        lambda m: f"except the {m.group(1)}" if _ids(m.group(1), lexicon, "object") else m.group(0),
        out,
    )

    def not_adj(m: re.Match[str]) -> str:
        noun, adj = m.group(1), m.group(2).lower()
        ids = _ids(noun, lexicon, "object")
        if len(ids) < 2:
            return m.group(0)
        objs = [o for o in lexicon.scene.objects if o.id in ids]
        marked = [o for o in objs if adj in " ".join([o.id, *o.aliases]).lower().replace("_", " ")]
        rest = [o for o in objs if o not in marked]
        if not marked or len(rest) != 1:
            return m.group(0)
        return f"the {rest[0].aliases[0] if rest[0].aliases else rest[0].id.replace('_', ' ')}"

    out = _sub(
        r"\bthe ([a-z]+) that isn't (?:the )?([a-z]+)(?: one)?\b(?! (?:on|in|at|by|near))",
        not_adj,
        out,
    )

    def not_person(m: re.Match[str]) -> str:
        other = m.group(1)
        if not _only_person(other, lexicon):
            return m.group(0)
        rest = out[: m.start()] + out[m.end() :]
        if _ids(other, lexicon, "human") & _ids(rest, lexicon, "human"):
            return m.group(0)
        if len(_ids(rest, lexicon, "human")) != 1 or re.search(
            r"\b(?:each|both|all|every|everyone|them|they)\b", rest, _F
        ):
            return m.group(0)
        return " " if m.group(2) == "," else m.group(2)

    out = _sub(r",\s*not ([A-Z][\w ]*?)\s*(,|(?=[.!?]|$))", not_person, out)
    return _nothing_for20(out, lexicon)


def _header_count20(text: str, lexicon: Lexicon) -> str:
    """Session 20: 'Two things. Knife to Marco. Lemon to Lena.': a count of tasks said as a
    header is taken off when the rest reads as exactly that many tasks (otherwise it stays,
    and the count is read, or refused, as before)."""
    m = re.match(
        r"^(one|two|three|four|five|six|[1-6]) (?:things?|jobs?|tasks?|requests?|deliveries)"
        r"(?: for you| to do| please)?\s*[.:!]\s*(.+)$",
        text,
        _F,
    )
    if m is None:
        return text
    word = m.group(1).lower()
    count = int(word) if word.isdigit() else _COUNTS[word]
    done = _tasks_of(m.group(2), lexicon)
    return m.group(2) if done is not None and len(done) == count else text


_OBJECT_CASE19 = {"his": "him", "her": "her", "their": "them"}


def _telegraph19(text: str, lexicon: Lexicon) -> str:
    """Requests said as bare names: 'Spoon. Doctor.' (the spoon to the doctor), 'Bib.
    Highchair.' (the bib on the highchair); 'The Y also same.' / 'Y, same.' after a sentence
    (the Y too); 'send X P's way' / 'send it his way' (to P, to him)."""
    out = _sub(
        r"\b(send|pass|pop|get) (it|them|the [a-z ]+?) ([A-Z][\w ]*?)'s way\b", r"\1 \2 to \3", text
    )
    out = _sub(
        r"\b(send|pass|pop|get) (it|them|the [a-z ]+?) (his|her|their) way\b",
        lambda m: f"{m.group(1)} {m.group(2)} to {_OBJECT_CASE19[m.group(3).lower()]}",
        out,
    )
    out = _sub(
        r"(?<=[.!?] )((?:the )?[a-z ]+?)(?:,)? (?:also |too )?same\s*([.!]?)$",
        lambda m: (
            f"{m.group(1)} too{m.group(2)}" if _objects_only(m.group(1), lexicon) else m.group(0)
        ),
        out,
    )
    out = _sub(
        r"(,\s*(?:no,\s*)?to [A-Z][\w ]*?),\s*the (?:[a-z]+ ){0,2}[a-z]+\s*([.!]?)$",
        lambda m: (
            m.group(1) + m.group(2)
            if _names_nothing(m.group(0)[len(m.group(1)) :], lexicon)
            else m.group(0)
        ),
        out,
    )
    sentences = re.split(r"(?<=[.!?])\s+", out.strip())
    if len(sentences) < 2:
        return out
    first = sentences[0].rstrip(".!?").strip()
    rest = " ".join(sentences[1:])
    if _only_person(first, lexicon) and _ids(first, lexicon) <= _ids(rest, lexicon, "human"):
        return rest  # "Howzit, Jess. Please pass the torch to Jess.": said to her first
    res: list[str] = []
    k = 0
    while k < len(sentences):
        s = sentences[k].rstrip(".!?").strip()
        nxt = sentences[k + 1].rstrip(".!?").strip() if k + 1 < len(sentences) else ""
        to = _rx(r"^(?:and )?(to|on|onto|in) (.+)$").match(nxt) if nxt else None
        if (
            to
            and _only(s, lexicon, "object")
            and (_only_person(to.group(2), lexicon) or _surface_only(to.group(2), lexicon))
        ):
            res.append(f"{s} {to.group(1)} {to.group(2)}.")  # 'The cup. To Alice.'
            k += 2
            continue
        person = bool(nxt) and _only_person(nxt, lexicon)
        if nxt and _only(s, lexicon, "object") and (person or _surface_only(nxt, lexicon)):
            obj = s if s.lower().startswith("the ") else f"the {s}"
            where = f"to {nxt}" if person else f"on the {nxt.removeprefix('the ')}"
            res.append(f"{obj} {where}.")
            k += 2
            continue
        res.append(sentences[k])
        k += 1
    return " ".join(res)


# the rewrites of _archaic19_words, in order (session 56, 12p: a module tuple, so that the step
# guard reads their words: the loop over a tuple written in the function was not read)
_ARCHAIC19_WORDS: tuple[tuple[str, str], ...] = (
    (r"\bwouldst thou\b", "would you"),
    (r"\bwilt thou\b", "will you"),
    (r"\bcanst thou\b", "can you"),
    (r"\b(?:thou|thee|ye)\b", "you"),
    (r"\bwouldst\b", "would"),
    (r"\bwilt\b(?! (?:flower|leaf))", "will"),
    (r"\bdoth (?:desire|want|crave|wish for)\b", "wants"),
    (r"\b(?:craveth|desireth|wanteth)\b", "wants"),
    (r"\bhath\b", "has"),
    (r"\bshall be (given|handed|passed|brought|placed|put|taken)\b", r"should be \1"),
    (r"\bshall (have|get|receive)\b", r"gets"),
    (r"\b(?:thereafter|thereupon)\b", "then"),
    (r"\bunto\b", "to"),  # before 'to the same': "unto the same" is 'to the same person'
    (
        r"\bto the (?:very )?same(?: (?:player|person|one|fellow|chap|lady|gentleman|guy))?\b",
        "to the same person",
    ),
    (r"\bprithee\b", "please"),
    (r"\bnay\b", "no"),
    (r"(?<!teddy )\bbear (?=the |it\b|them\b)", "bring "),
    (r"\b(?:supply|furnish|provide|equip|present) ([A-Z][\w ]*?) with\b", r"give \1"),
    (
        r"^(?:please )?(?:make sure|ensure|see to it that|see that) (.+?) (?:reaches|gets to|"
        r"arrives (?:at|with)|ends up with) ",
        r"\1 goes to ",
    ),
    (
        r"^(?:could|can|would|will) you (?:please )?see that (.+?) "
        r"(?:reach|reaches|get to|gets to) ",
        r"\1 goes to ",
    ),
    (
        r"\b(?:see to it that|make sure that|make sure) ([A-Z][\w ]*?) (?:receives|gets) ",
        r"give \1 ",
    ),
    (r"(?<!the )\brest (it|them|the [a-z ]+?) (on|onto|in|into|upon|atop)\b", r"put \1 \2"),
    (r"\btake delivery of\b", "receive"),
)


def _archaic19_words(text: str) -> str:
    """Older English said as today's: thou/thee/ye (you), wouldst/wilt/doth/hath (would, will,
    does, has), unto (to), prithee (please), 'bear the X' (bring), nay (no), craveth/desireth
    (wants); 'supply / furnish / provide / equip P with X' (give P X); 'make sure X reaches P'
    (X goes to P); 'rest it on S' / 'lift X and rest it on S' (put)."""
    out = text
    for a, b in _ARCHAIC19_WORDS:
        out = _sub(a, b, out)
    return out


def _archaic19(text: str, _lexicon: Lexicon) -> str:
    out = _archaic19_words(text)
    out = _sub(
        r"\b(?:through|along|across|round|around|aloft)\s+(?=(?:to|on|onto|into)\b)", "", out
    )
    if out != text and text.rstrip().endswith("?"):
        # "Could you see that the chips reach Person A?": a request once the frame is off
        out = _sub(r"^(the [a-z ]+ goes to [A-Z][\w ]*?)\s*\?$", r"\1.", out)
    out = _sub(
        r"^((?:either )?(?:the )?[a-z ]+ or (?:the )?[a-z ]+) should be (?:given|handed|passed|"
        r"brought|sent) to\b",
        r"\1 goes to",
        out,
    )
    return out


# -- session 26 (engineer 12s): choices, splits, exclusivity and exclusions said around a request --
#
# Each rewrite below is taken only when the grammar (no rewrites) reads what it leaves as the
# kind of request its words say: a free split or a choice must read as an 'or', one person alone
# as tasks for that one person; anything else is left as it was (and refused as before).


def _a_choice26s(text: str, lexicon: Lexicon) -> bool:
    """Whether the grammar reads ``text`` as one choice: an 'or' of single tasks, or an 'or'
    whose alternatives hand over the same objects to the same people (who gets which is free).
    An 'or' mixing both ('Give Alice or Bob the cup and the apple' is read 'cup>A | (cup>B &
    apple>B)' by the grammar) is not such a choice."""
    node = _reading(text, lexicon, normalise=False)
    if not isinstance(node, Group) or node.op != "or":
        return False
    if all(isinstance(c, Task) for c in node.children):
        return True
    said = {
        (frozenset(t.obj for t in tasks(c)), frozenset(t.target for t in tasks(c)))
        for c in node.children
    }
    return len(said) == 1


# who gets which said to be free ("any way round", "I don't mind who gets what")
_FREE_SPLIT26S = (
    r"(?:any|either) (?:which )?way(?: round| around)?(?: you (?:like|want|fancy|please))?|"
    r"(?:i )?(?:don't|do not) mind who gets (?:what|which)(?: one)?|"
    r"(?:it )?makes no odds who gets (?:what|which)(?: [a-z]+)?|"
    r"(?:it )?(?:doesn't|does not) matter who gets (?:what|which)(?: [a-z]+)?"
)
# the chooser's indifference after a choice ("she's not fussed which", "she does not care")
_INDIFFERENT26S = (
    r"any|(?:(?:she|he|they|i|we)(?:'s|'re|'m| is| are| am) )?not (?:fussed|bothered)(?: which)?|"
    r"(?:she|he|they|i|we) (?:doesn't|don't|does not|do not) (?:care|mind)(?: which)?|"
    r"(?:it )?(?:doesn't|does not) bother (?:me|her|him|them|us)(?: which)?|"
    r"(?:(?:it's|it is) )?all (?:the )?same (?:to|for) (?:me|her|him|them|us)|"
    r"(?:it )?makes no odds(?: which)?"
)


def _kinds_named26s(text: str, lexicon: Lexicon) -> str:
    """'Give Emma one of the cups, green or white, …', 'Any pen to Sam, black or blue or red, …':
    the words after a choice of a kind ('one / either / any of the Xs', 'any X') that tell apart
    every object of that kind, joined by 'or', say the choice again: taken off. Each word must
    name one object of the kind, all different, and together every object of it ('green or blue'
    with no blue cup, or 'green' alone of three, is left, and refused)."""
    m = _rx(r",\s*([a-z]+(?:(?:,| or)\s*[a-z]+)*,? or [a-z]+)\s*(?=,|[.!?]?\s*$)").search(text)
    if m is None:
        return text
    words = [w for w in re.split(r"\s*,\s*|\s+or\s+", m.group(1), flags=_F) if w]
    for chose in _rx(r"\b(?:one|either|any) (?:of (?:the|those) )?([a-z]+)\b").finditer(
        text[: m.start()]
    ):
        said = chose.group(1).lower()
        for kind in {said, said.removesuffix("s"), said.removesuffix("es")}:
            of_kind = {o.id for o in lexicon.scene.objects if o.category == kind}
            if len(of_kind) != len(words) or len(of_kind) < 2:
                continue
            named = [_ids(f"the {w} {kind}", lexicon, "object") for w in words]
            if all(len(n) == 1 for n in named) and set().union(*named) == of_kind:
                return text[: m.start()] + text[m.end() :]
    return text
