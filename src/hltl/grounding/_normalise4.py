"""The normaliser's rules of sessions 10-37, part 4 of 5 (docs/grounding.md: where they live)."""

from __future__ import annotations

import functools
from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import (
    _COUNTS,
    _F,
    _KEEP_WORDS,
    _LATER24,
    _NUMBERS15,
    _ORDER_WORDS,
    _REASON_HELD21,
    _SENTENCE_HELD,
    _TASK_WORDS,
    _both_of31s,
    _call,
    _excluded_count,
    _fits,
    _ids,
    _names,
    _names_nothing,
    _objects_only,
    _only,
    _only_kind,
    _only_person,
    _opens_request,
    _reading,
    _remark_clause,
    _rx,
    _said_otherwise31s,
    _sub,
    _surface_only,
    _tasks_of,
    _the_person,
    _when,
    _where_it_is31s,
    _will_do31s,
    _worked_on35s,
    one_person,
)
from hltl.grounding._normalise2 import (
    _ALSO_HERS36,
    _ARE_WHOSE36,
    _BACK_FROM36,
    _BODY36,
    _COURTESY24,
    _KEEP_GOING36,
    _LIKEWISE36,
    _LOST_HIS36,
    _OCLOCK36,
    _REMARK_JOINS,
    _REMARK_MARKS,
    _REMARK_OPEN,
    _ROUGH_NIGHT36,
    _SPEAKER_CUE,
    _STATE_WANTS36,
    _STOPS,
    _SUBJECT36,
    _WANT_WITH36,
    _WANTING31,
    _announced36,
    _asked36,
    _asks_nothing29,
    _before_deadline32,
    _courtesies36,
    _give_them_those36,
    _negated_reason31s,
    _plural36,
    _run_on_mid36,
    _scene_words29,
    _stay_put36,
    _stretches_dropped,
    _things31,
    _time_for36,
    _trade_said36,
    _wants_said36,
    _why_placed36,
)
from hltl.grounding._normalise3 import (
    _N33T,
    _OPENING33T,
    _ORDER_HELD36L,
    _ORDER_HELD36S,
    _both_named33t,
    _cleft_not29r,
    _counted_close33t,
    _counted_those34t,
    _each_any33t,
    _each_header33t,
    _each_said33t,
    _everything_bar33t,
    _exclaimed_fix33t,
    _formal33t,
    _fronted_to33t,
    _got_them33t,
    _handovers33t,
    _kind_choice33t,
    _leave_where33t,
    _load_up33t,
    _need_over33t,
    _objects_first33t,
    _objects_said34t,
    _one_choice28r,
    _one_object32r,
    _one_said33t,
    _opener,
    _openers33t,
    _other_two33t,
    _placed_for33t,
    _places_said33t,
    _purpose_ing33t,
    _said_again33t,
    _speaker_stretch,
    _stays_on33t,
    _telegraphed33t,
    _unknown_fixed33t,
    _whole_name,
    _whose33t,
    _wont_you33t,
)
from hltl.grounding.lexicon import (
    KIND_CATEGORIES,
    PRONOUN_SEX,
    TITLES,
    VERBS,
    WORDS,
    Lexicon,
    name_sexes,
    said_sex35s,
    title_sex,
)
from hltl.grounding.phrasing import starting_on
from hltl.grounding.tree import (
    Group,
    Node,
    Task,
    tasks,
)

# 'P says / reckons (that) she'd love X': what P wants, said by the speaker
_REPORTED34T = (
    r"(?P<lead>^|[.!;]\s+|,\s*(?:(?:oh|and|oh and),?\s+)*)(?P<p>[a-z][\w ]*?) (?:says|said|"
    r"reckons|thinks|tells me)(?: that)? (?P<pro>he|she|they)(?P<verb>(?:'d| would) (?:love|like)|"
    r" wants| needs| fancies)\b"
)


def _reported_want34t(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12t): what a person wants, reported ('Carol says she'd love the blue mug',
    'Person B reckons she fancies the chips') is that person's want ('Carol would love the blue
    mug'): only when the words before 'says' name one person, no person is named before them, and
    the pronoun may be that person (a title says which: 'Mr Lee says she'd love …' is left)."""

    def want(m: re.Match[str]) -> str:
        if not _only_person(m["p"], lexicon) or _ids(text[: m.start()], lexicon, "human"):
            return m.group(0)
        (pid,) = _ids(m["p"], lexicon, "human")
        if m["pro"].lower() == "they" or not _fits(pid, m["pro"], lexicon):
            return m.group(0)
        verb = m["verb"].replace("'d", " would").strip()
        return f"{m['lead']}{m['p']} {verb}"

    return _sub(_REPORTED34T, want, text)


# closers said after a request without a stop: 'off you go', 'got it', 'that's all of it'
_CLOSERS34T = r"off you go|got it|that's all of it|that's it|that is all|that's the lot"


def _closers34t(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12t): closers that ask nothing, from a closed list (``_CLOSERS34T``), said
    after a request with no stop ('… the apple's going over to Person B off you go'): taken off
    when what is before them reads alone. 'Thank you, you are very kind.' is 'Thank you.'; a
    thanks of another language put right into English ('Obrigado, eh, I mean thanks.') is
    'Thanks.'; in text-speak 'when u can' is 'when you can' and 'the crisps r Alice's' is 'the
    crisps are Alice's' (only before a possessive or 'for')."""
    m = _rx(rf"^(?P<said>.*?\S)\s*,?\s+(?:{_CLOSERS34T})\s*[.!?]*$").match(text)
    if m is not None and _reading(m["said"], lexicon) is not None:
        text = m["said"]
    out = _sub(
        r"(?<=[.!]\s)(thank you|thanks|cheers),\s*(?:you are|you're) (?:very |so |too )?kind"
        r"(?=\s*[.!]?$)",
        r"\1",
        text,
    )
    out = _sub(
        rf"(?<=[.!]\s)(?:{_COURTESY24}),\s*(?:(?:eh|er|um|erm),\s*)?i mean (thanks|thank you)\b",
        r"\1",
        out,
    )
    out = _sub(r"\bwhen u can\b", "when you can", out)
    return _sub(r"(^|,\s*)(the [a-z]+) r (?=[a-z]+'s\b|for\b)", r"\1\2 are ", out)


def _frames34t(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12t): request frames of learners and of talk, from a closed list: 'I would
    like that you give …' is 'I would like you to give …'; '(do|d') you reckon you could …' is
    'could you …'; 'Over to P with the X' is 'the X over to P'; 'For P, (the) X, please give.'
    (the verb said last) is 'please give P the X'; '…, then the crisps, same place' after a
    hand-over or placement is '…, then the crisps too' (the same target: only where what is
    before it has one target, said as where it goes, 'to Bob' / 'on the shelf'; two targets, or
    'Give Ruth the jug', are left and refused, as session 26 decided)."""
    out = _sub(r"\bi would like (?:it )?that you (?=[a-z]+ )", "I would like you to ", text)
    out = _sub(
        r"\b(?:do you|d'you|d you|did you) reckon (?:that )?you (could|can)\b", r"\1 you", out
    )
    m = _rx(r"^(?:over|across) to (?P<p>[a-z][\w ]*?) with (?P<obj>the [a-z]+)\b").match(out)
    # (with a correction's cue after it, 12r's rules read it: this one stands aside)
    fix = _rx(r"\b(?:no|sorry|rather|actually|wait|i mean)\b").search(out)
    if (
        m is not None
        and not fix
        and _only_person(m["p"], lexicon)
        and _only_kind(m["obj"], lexicon, "object")
    ):
        out = f"{m['obj'].capitalize()} over to {m['p']}{out[m.end() :]}"
    m = _rx(
        r"^for (?P<p>[a-z][\w ]*?),\s*(?P<obj>(?:the )?[a-z]+),\s*(?:please )?give\s*(?P<end>[.!]?)"
    ).match(out)
    if m is not None and _only_person(m["p"], lexicon) and _only_kind(m["obj"], lexicon, "object"):
        obj = m["obj"] if m["obj"].lower().startswith("the ") else f"the {m['obj']}"
        out = f"Please give {m['p']} {obj}{m['end']}{out[m.end() :]}"

    def same(m: re.Match[str]) -> str:
        # one target before it, or 'same place' could be either; and said as where it went
        # ('to Bob', 'on the shelf'): 'Give Ruth the jug, then …, same place' names no place
        # (session 26's near forms)
        before = m.string[: m.start()].rstrip(" ,")
        said = _tasks_of(before, lexicon)
        if not said or len({target for _, _, target in said}) != 1:
            return m.group(0)
        if not _rx(r"\b(?:to|onto|into|on|in) (?:the )?[a-z]").search(before):
            return m.group(0)
        return f"{m.group(1)} too"

    return _sub(
        r"((?:(?<=[.!]\s)then|,\s*(?:and )?then) (?:the )?[a-z]+),\s*(?:the )?same (?:place|spot)"
        r"(?=\s*[.!]?$)",
        same,
        out,
    )


def _thing_cleft34t(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12t): 'the thing P has been after (all morning) is the X' is 'what P has been
    after … is the X' (the grammar's cleft): only when the words after 'the thing' name one person
    and a verb of wanting follows them ('the thing on the shelf is …' is left)."""

    def what(m: re.Match[str]) -> str:
        if not _only_person(m["p"], lexicon):
            return m.group(0)
        return f"{m['lead']}{'W' if not m['lead'] else 'w'}hat {m['p']} {m['v']}"

    return _sub(
        r"(?P<lead>^|[.!]\s+|,\s*)the thing (?P<p>[a-z][\w ]*?) (?P<v>wants|needs|has been after|"
        r"'s been after|is after|would like|has asked for|asked for)\b",
        what,
        text,
    )


def _asked_first34t(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12t): a question whether a person wants an object, then the request that hands
    'it' to 'her' ('Would Person B like the apple? Give it to her, yes?'): 'Give P the X' — only
    when the question names one person and one object, the pronouns fit them, and nothing else
    follows ('yes?', 'please' closing it)."""
    m = _rx(
        r"^(?:would|does|do) (?P<p>[a-z][\w ]*?) (?:like|want|need) (?P<obj>the [a-z]+(?: [a-z]+)?)"
        r"\?\s+(?P<verb>give|hand|pass|take) (?:it|that) (?:over )?to (?P<pro>him|her)"
        r"(?:,?\s*(?:yes|yeah|please|thanks))?\s*[.!?]?$"
    ).match(text)
    if (
        m is None
        or not _only_person(m["p"], lexicon)
        or not _only(m["obj"], lexicon, "object")
        or not _fits(next(iter(_ids(m["p"], lexicon, "human"))), m["pro"], lexicon)
    ):
        return text
    return f"{m['verb'].capitalize()} {m['p']} {m['obj']}."


def _sorted_first34t(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12t): 'Priority is P, she needs the X; …' is 'P needs the X; …' (who comes
    first, said before what they need, when the pronoun may be P and the sentence opens with it);
    'once she's sorted' (has what she needs) is 'once she's done'."""
    out = _sub(r"\bonce (he|she|they)(?:'s| is|'re| are) sorted\b", r"once \1's done", text)
    m = _rx(
        r"^(?:the )?(?:first )?priority is (?P<p>[a-z][\w ]*?),\s*(?P<pro>he|she) (?P<v>needs|"
        r"wants|would like)\b"
    ).match(out)
    if m is None or not _only_person(m["p"], lexicon):
        return out
    if not _fits(next(iter(_ids(m["p"], lexicon, "human"))), m["pro"], lexicon):
        return out
    return f"{m['p']} {m['v']}{out[m.end() :]}"


def _only_one34t(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12t): 'Only one bottle between the lot of us, so that single bottle goes to P'
    says the count of the scene: the opening is taken off when the scene has exactly one such
    object ('that single bottle' is then 'the bottle'); where it has more, left and refused."""
    m = _rx(
        r"^only (?:one|the one|a single) (?P<kind>[a-z]+) (?:between|for|among) (?:the lot of us|"
        r"all of us|us all|everyone|the lot),\s*(?:so\s+)?(?:that|the|this) (?:single |one |lone )?"
        r"(?P<again>[a-z]+)\b"
    ).match(text)
    if m is None or m["kind"].lower() != m["again"].lower():
        return text
    if not _only(f"the {m['kind']}", lexicon, "object"):
        return text
    rest = text[m.end() :]
    return f"The {m['kind']}{rest}"


def _remark_places34t(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12t): where a placement goes, said again in words that name nothing: 'on the
    bookshelf with the others' ('with the others' after a surface of the scene: where the others
    are) and 'on the desk where the class can see the dig site' (a 'where' clause at the end that
    names nothing of the scene and holds no word that would change what is asked, ``_KEEP_WORDS``);
    "Don't mind me (up the ladder)," opening a request (an idiom: pay me no attention)."""
    out = _sub(
        r"^((?:[a-z]+[!.,]\s+)?)don't mind me(?: (?:up|on|in|at|under) the [a-z]+)?,\s*",
        lambda m: m.group(1) if _names_nothing(m.group(0), lexicon) else m.group(0),
        text,
    )

    def where(m: re.Match[str]) -> str:
        if not _surface_only(m["s"], lexicon):
            return m.group(0)
        tail = m["tail"]
        if tail.lower() == "with the others":
            return m["head"]
        said = tail[len("where ") :]
        held = _KEEP_WORDS.search(said) or _LATER24.search(said)
        if (
            _names_nothing(said, lexicon)
            and not held
            and not _rx(r"\b(?:i|we|my|our)\b").search(said)
        ):
            return m["head"]
        return m.group(0)

    return _sub(
        r"(?P<head>\b(?:on|onto|in|into) (?P<s>the [a-z]+)) (?P<tail>with the others|where [a-z ]+)"
        r"(?=\s*[.!?]?$)",
        where,
        out,
    )


def _idioms34t(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12t): words that ask nothing, from closed lists: the breathing of a calm
    ('Breathe in.', 'Breathe out.', 'Breathe in... and breathe out.' as a sentence or a clause
    joined by 'and' to the request); a referee's 'Play on!' opening and ', advantage played'
    closing; text-speak 'omg' and the address 'bestie' opening, 'slay' closing; 'the wee X' is 'the
    X' ('wee': small, where the scene has one X); 'My client, Sam, requires …' ('my <word>,' before
    a name names nothing of the scene), 'Priya, the manager, …' (her own role said after her
    name), 'wishes to have' and 'requires' are 'would like' and 'needs'."""
    out = _sub(
        r"(?:^|(?<=[.!?]\s))breathe in(?:\s*(?:\.\.\.|…|,)?\s*(?:and )?breathe out)?"
        r"\s*(?:[.!]|\.\.\.|…)\s*",
        "",
        text,
    )
    out = _sub(r"(?:^|(?<=[.!?]\s))breathe in,\s*and\s+(?=[a-z])", "", out)
    out = _sub(r"(?<=[.!?])\s*breathe out\s*[.!]?$", "", out)
    out = _sub(r"^play on!\s*", "", out)
    out = _sub(r",\s*advantage played\s*([.!]?)$", r"\1", out)
    out = _sub(r"^omg\s+(?:bestie\s+)?", "", out)
    out = _sub(r",\s*slay\s*([.!]?)$", r"\1", out)

    def wee(m: re.Match[str]) -> str:
        return f"the {m.group(1)}" if _only(f"the {m.group(1)}", lexicon, "object") else m.group(0)

    out = _sub(r"\bthe wee ([a-z]+)\b", wee, out)

    def client(m: re.Match[str]) -> str:
        if _names_nothing(m.group(1), lexicon) and _only_person(m.group(2), lexicon):
            return m.group(2)
        return m.group(0)

    out = _sub(r"\bmy ([a-z]+), ([A-Z][a-z]+(?: [A-Z][a-z]+)?),(?= )", client, out)

    def role(m: re.Match[str]) -> str:
        if _only_person(m.group(1), lexicon) and _ids(m.group(1), lexicon, "human") == _ids(
            m.group(2), lexicon, "human"
        ):
            return m.group(1)
        return m.group(0)

    out = _sub(r"\b([A-Z][a-z]+), the ([a-z]+),(?= )", role, out)
    out = _sub(r"\bwishes to have\b", "would like", out)
    return _sub(r"(?<=[a-z] )requires (?=the )", "needs ", out)


def _after_those34t(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12t): 'Then the notepad to Priya after those two.' — 'after those two' (or
    'after them', 'after both') closing a 'then' sentence says the order again: taken off when
    the count agrees with the hand-overs and placements before it (a count that does not is
    left and refused)."""
    m = _rx(
        r"(?<=[.!]\s)(?P<then>then [^.!?]+?) after (?:those|these|them|both)(?: (?P<n>two|three|"
        r"four))?\s*(?P<end>[.!]?)$"
    ).search(text)
    if m is None:
        return text
    before = text[: m.start()].rstrip()
    said = _handovers33t(before, lexicon)
    want = _COUNTS[m["n"].lower()] if m["n"] else 2
    if said is None or len(said) != want:
        return text
    return f"{text[: m.start()]}{m['then']}{m['end']}"


def _left_as_was34t(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12t): after a correction that replaces an object, '…, leave the X where it
    is' naming the object replaced says the correction again ('Tape to Mia. No, hang on, the
    scanner to Mia, leave the tape where it is.'): taken off when what is before reads and does
    not move the X (an X that is still moved is left and refused)."""
    m = _rx(r",\s*(?:and )?leave (?P<obj>the [a-z]+) (?:where it is|be)\s*[.!]?$").search(text)
    if m is None or not _only(m["obj"], lexicon, "object"):
        return text
    before = text[: m.start()]
    if not _rx(r"\b(?:no|sorry|actually|wait)\b").search(before):
        return text
    (oid,) = _ids(m["obj"], lexicon, "object")
    if oid not in _ids(before, lexicon, "object"):
        return text
    said = _tasks_of(before, lexicon)
    if not said or oid in {obj for _, obj, _ in said}:
        return text
    return before + "."


def _telegraph34t(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12t): telegraphed requests. An object said as a sentence and the surface it
    goes on as the next ('That hammer. Back on the workbench.') are one ('That hammer back on the
    workbench.'; session 30's `_over_to30` joins 'The bottle. Over to Person A.'), when the first
    names objects alone and the second one surface; 'Bottle, that one is Person B's.' (the object,
    then a pronoun for it) is 'Bottle, Person B's.'; an order header 'tonight's order' ('good
    evening, tonights order chips for person b …') is taken off."""

    def joined(m: re.Match[str]) -> str:
        if _objects_only(m["what"], lexicon) and _surface_only(m["where"], lexicon):
            return f"{m['lead']}{m['what']} {m['dir'] or ''}{m['prep']} {m['where']}"
        return m.group(0)

    out = _sub(
        r"(?P<lead>(?:^|(?<=[.!?;])\s+))(?P<what>(?:the|that|this) [a-z][a-z ]*?)\.\s+"
        r"(?P<dir>(?:back|up|down) )?(?P<prep>on|onto|in|into) (?P<where>the [a-z]+(?: [a-z]+)?)"
        r"(?=\s*[.!?]|$)",
        joined,
        text,
    )

    def owned(m: re.Match[str]) -> str:
        if _objects_only(m["what"], lexicon) and _only_person(m["p"], lexicon):
            return f"{m['what']}, {m['p']}'s"
        return m.group(0)

    out = _sub(
        r"(?<![a-z] )(?P<what>\b[a-z]+(?: [a-z]+)?), (?:that one|this one|that|it) (?:is|'s) "
        r"(?P<p>[a-z][\w ]*?)'s(?=\s*[.!,]|$)",
        owned,
        out,
    )
    return _sub(
        r"(^|,\s*|(?<=[.!])\s+)(?:tonight'?s|today'?s|this evening'?s|this morning'?s) order:?\s+",
        r"\1",
        out,
    )


def _run_on_state34t(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12t): a remark on the recipient's state run on with no commas ('Give Jess the
    small spanner quick she's under the van and after that the hammer to Kofi he's waiting'): set
    off by commas (', she's under the van,') so that session 21's `_reasons21` judges it — only
    when it names nothing of the scene, right after a name or 'quick', and the whole then reads."""

    def comma(m: re.Match[str]) -> str:
        if not _names_nothing(m["state"], lexicon) or _REASON_HELD21.search(m["state"]):
            return m.group(0)
        return f"{m['before']}, {m['state']},"

    out = _sub(
        r"(?P<before>\b[a-z]+) (?P<state>(?:he|she)'s (?:under|waiting|busy|up|out|on|in)\b"
        r"[a-z ]*?)(?= and (?:after that|then)\b|\s*[.!]?$)",
        comma,
        text,
    ).rstrip(",")
    return out if out != text and _reading(out, lexicon) is not None else text


def _for_said34t(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12t): what the request is for, opening it without a determiner ('For reading
    group, lay out both books on the desk, …'): taken off as session 30's `_for_opener30` takes
    off 'For the geography lesson', when the words ask nothing and name nothing of the scene
    (`_asks_nothing29`: 'For Person B, …' is a recipient and stays) and a verb follows."""
    m = _rx(r"^for ([a-z]+(?: [a-z]+)?),\s+(?=(?:lay|put|place|set|give|hand|bring|take)\b)").match(
        text
    )
    if m is None or not _asks_nothing29(m.group(1), lexicon) or _KEEP_WORDS.search(m.group(1)):
        return text
    rest = text[m.end() :]
    return rest[:1].upper() + rest[1:]


def _reasons_said34t(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12t): reasons that ask nothing. '… because she asked earlier and she's been
    very patient' closing the request: a 'because' of a pronoun's clauses joined by 'and', taken
    off whole when it names nothing of the scene and holds no word of session 21's
    `_REASON_HELD21` ('patient' after 'been' / 'is' is the adjective, not the ward's role noun)
    and each pronoun in it may be one person named before it alone (a title says which);
    '…, his own one has died on him' (a thing of his own, so not one of the
    scene's: 'has died', 'is broken', 'has packed up', from a closed list); 'straight into
    Alice's hands' is 'to Alice'."""

    def why(m: re.Match[str]) -> str:
        # 'she's been very patient': the adjective, not the ward's role noun 'patient'
        said = _sub(r"\b(been|is|'s|was) (?:very |so |really |ever so )?patient\b", r"\1", m["why"])
        if not _names_nothing(said, lexicon) or _REASON_HELD21.search(said):
            return m.group(0)
        # each pronoun may be one person named before it alone ('Give Bob the chips and Carol
        # the apple because she's hungry': Bob or Carol, session 5's near form, stays)
        named = _ids(m.string[: m.start()], lexicon, "human")
        for pro in re.findall(r"\b(?:he|she|they|him|her)\b", said, _F):
            if len([pid for pid in named if _fits(pid, pro, lexicon)]) != 1:
                return m.group(0)
        return ""

    out = _sub(
        r" because (?P<why>(?:he|she|they)\b[^,.;!?]*?)(?=\s*[.!]?$)",
        why,
        text,
    )
    out = _sub(
        r",\s*(?:his|her|their) own one (?:has died|died|is broken|'s broken|has broken|broke|has "
        r"packed up|packed up|has given up)(?: on (?:him|her|them))?(?=\s*[.!]?$)",
        "",
        out,
    )

    def hands(m: re.Match[str]) -> str:
        return f"to {m['p']}" if _only_person(m["p"], lexicon) else m.group(0)

    return _sub(r"\b(?:straight |right )?into (?P<p>[a-z][\w ]*?)'s hands\b", hands, out)


def _target_for34t(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12t): a list of where things go said target first ('shelf for the chips, bob
    for the bottle, ta'): a clause that is a surface or a person, 'for', and one object of the
    scene is 'the chips on the shelf' / 'the bottle for Bob' — only when the words before 'for'
    name one surface or one person alone and those after it one object alone, and no
    correction's cue is said (session 34's `_surface_for34r` reads 'Shelf for the bottle, please,
    or no, better still, straight to Alice')."""

    def turned(m: re.Match[str]) -> str:
        where, obj = m["where"], m["obj"]
        if not _only_kind(obj, lexicon, "object"):
            return m.group(0)
        the = obj if obj.lower().startswith("the ") else f"the {obj}"
        if _surface_only(where, lexicon):
            place = where if where.lower().startswith("the ") else f"the {where}"
            return f"{m['lead']}{the} on {place}"
        if _only_person(where, lexicon):
            return f"{m['lead']}{the} for {where}"
        return m.group(0)

    if _rx(r"\b(?:no|rather|sorry|actually|wait|instead)\b").search(text):
        return text  # a correction's note ('Shelf for the bottle, …, or no, …'): 12r's rules
    return _sub(
        r"(?P<lead>^|,\s*)(?P<where>(?:the )?[a-z]+(?: [a-z]+)?) for (?P<obj>(?:the )?[a-z]+)"
        r"(?=\s*(?:,|[.!]?$))",
        turned,
        text,
    )


def _pirate34t(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12t): a pirate's role-play, from a closed list: 'Arr,' / ', arr' and the
    addresses 'matey', 'me hearties' are interjections; "Cap'n" before a name is a title taken
    off; "be wantin'" is 'wants'; 'old' before a name of the scene names no one else ('old
    Grandad'); 'the treasure, the teddy bear,' is 'the teddy bear,' (the role-play's word, said
    again by the object's name); 'X be P's treasure' is 'X are for P'. Only where the text holds
    one of the pirate's words ('arr', 'matey', 'hearties', "cap'n"); 'the four treasures' is 'the
    four things' wherever it is said (the count checked as for things)."""
    out = _sub(r"\bthe (two|three|four|five|six) treasures\b", r"the \1 things", text)
    if not _rx(r"\b(?:arr|matey|hearties|cap'n)\b").search(out):
        return out
    out = _sub(r"^arr,\s*", "", out)
    out = _sub(r",\s*(?:arr|matey|me hearties)(?=\s*[,.!]|$)", "", out)
    out = _sub(r"\bcap'n (?=[A-Z])", "", out)
    out = _sub(r"\bbe wantin'?(?= )", "wants", out)

    def old(m: re.Match[str]) -> str:
        return m.group(1) if _only_person(m.group(1), lexicon) else m.group(0)

    out = _sub(r"\bold ([A-Z][a-z]+)\b", old, out)

    def said(m: re.Match[str]) -> str:
        return m.group(1) if _only(m.group(1), lexicon, "object") else m.group(0)

    out = _sub(r"\bthe treasure, (the [a-z]+(?: [a-z]+)?)(?=,)", said, out)

    def owned(m: re.Match[str]) -> str:
        if _only_person(m["p"], lexicon) and _objects_only(m["what"], lexicon):
            return f"{m['what']} are for {m['p']}"
        return m.group(0)

    return _sub(r"(?P<what>\bthe [a-z ]+?) be (?P<p>[a-z][\w ]*?)'s treasure\b", owned, out)


def _reported_fix34t(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12t): a report taken back, news-style: 'We reported the cup was going to P.
    Correction: it's the apple.' is 'The cup was going to P. No, the apple.' (the report's frame
    'we reported / said / announced (that)' before what was going where, and 'Correction: it's'
    opening the next sentence before an object, the correction's cue)."""
    if "correction" not in text.lower():
        return text
    m = _rx(
        r"^we (?:reported|said|announced|stated)(?: earlier)?(?: that)? (?=the [a-z]+ (?:was|were|"
        r"is) going to )"
    ).match(text)
    if m is None:
        return text
    out = text[m.end() :]
    out = out[:1].upper() + out[1:]
    return _sub(r"(?<=[.!]\s)correction:\s*(?:it's|it is) (?=the [a-z]+\s*[.!]?$)", "No, ", out)


def _singlish34t(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12t): Singapore English from a closed list, only where one of its particles is
    said ('lah', 'leh', 'lor', 'can or not?'): the particles are taken off; 'P want' is 'P wants';
    'X is for P one' ('one' closing the clause, an emphasis) is 'X is for P'; 'P want(s) one'
    after the object said first ('The crsps, Bob want one lah') is 'P wants it'; a bare object
    opening a clause before 'is' ('Bottle is what Alice want', 'crisps is for Bob') takes 'the'.
    'Two items, both give Alice lah.' stays refused (session 28's near form: a count is not a
    name)."""
    if not _rx(r"\b(?:lah|leh|lor)\b|\bcan or not\b").search(text):
        return text
    out = _sub(r",?\s*\bcan or not\s*\?", ".", text)
    out = _sub(r"\s+\b(?:lah|leh|lor)\b(?=\s*[,.!?]|$)", "", out)

    def wants(m: re.Match[str]) -> str:
        return f"{m.group(1)} wants" if _only_person(m.group(1), lexicon) else m.group(0)

    out = _sub(r"\b([A-Z][a-z]+(?: [A-Z])?) want\b", wants, out)
    out = _sub(r"(\bfor [A-Z][a-z]+(?: [A-Z])?) one(?=\s*[,.!?]|$)", r"\1", out)
    m = _rx(r"^(?P<obj>the [a-z]+), (?P<p>[a-z][\w ]*?) wants one(?=\s*[.!]?$)").match(out)
    if m is not None and _only_person(m["p"], lexicon) and _only(m["obj"], lexicon, "object"):
        out = f"{m['obj']}, {m['p']} wants it{out[m.end() :]}"

    def the(m: re.Match[str]) -> str:
        if _only(m.group(2), lexicon, "object") and not m.group(2).lower().startswith("the "):
            return f"{m.group(1)}the {m.group(2)} is"
        return m.group(0)

    return _sub(r"(^|,\s*)([a-z]+) is\b", the, out)


def _dedication34t(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12t): a radio dedication, 'This one goes out to Lena, who'd love the tongs, and
    to Marco, who needs the knife!': the frame 'This one (song) goes out to' is taken off and each
    'P, who would love / needs X' is 'P would love / needs X' — only when every name is one person
    of the scene."""
    m = _rx(r"^this (?:one|song|next one) goes out to ").match(text)
    if m is None:
        return text
    rest = text[m.end() :]
    parts = _rx(
        r"(?:^|,\s*and to\s+)(?P<p>[A-Z][\w ]*?), who(?P<mod>'d| would)? (?P<v>love|like|needs|"
        r"wants|fancies)\b"
    )
    found = list(parts.finditer(rest))
    if not found or not all(_only_person(f["p"], lexicon) for f in found):
        return text

    def said(f: re.Match[str]) -> str:
        lead = ", and " if f.start() > 0 else ""
        verb = f"would {f['v']}" if f["mod"] else f["v"]
        return f"{lead}{f['p']} {verb}"

    return parts.sub(said, rest)


def _legal34t(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12t): legal wording from a closed list: ", hereinafter 'the item'," (a name
    given for later, naming nothing of the scene) is taken off; 'The notebook likewise.' (a
    sentence of an object and 'likewise') is 'The notebook too.'. (The name given is a kind word,
    'the item', or names nothing; "hereinafter 'the notebook'" is left and refused.)"""
    out = _sub(
        r",\s*hereinafter (?:called |referred to as )?['\"‘“](?P<name>[a-z ]+)['\"’”],",
        lambda m: (
            ""
            if _rx(r"^(?:the )?(?:item|thing|object|article)$").match(m["name"])
            or _names_nothing(m["name"], lexicon)
            else m.group(0)
        ),
        text,
    )
    return _sub(r"(?<=[.!]\s)(the [a-z]+(?: [a-z]+)?) likewise(?=\s*[.!]?$)", r"\1 too", out)


def _fronted_asked34t(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12t): the object said first, then who asked for it and the request by pronouns
    ('The chips, sorry, Person A asked for them, could they go to her?'): 'Person A asked for the
    chips, could they go to her?' — 'sorry' there replaces nothing (the clause after it points
    back to the object with 'them' / 'it'); only when the object is one of the scene's and the
    pronoun after 'to' may be the person. 'Could P have either of them? Either thing, I don't
    mind.' (the next sentence says 'them' are things) is 'Could P have either thing?', where the
    scene has two objects."""
    m = _rx(
        r"^(?P<obj>the [a-z]+), (?:sorry, )?(?P<p>[a-z][\w ]*?) asked for (?:them|it), "
        r"(?P<ask>could (?:they|it) go to (?P<pro>her|him)\?)"
    ).match(text)
    if (
        m is not None
        and _only_person(m["p"], lexicon)
        and _only(m["obj"], lexicon, "object")
        and _fits(next(iter(_ids(m["p"], lexicon, "human"))), m["pro"], lexicon)
    ):
        text = f"{m['p']} asked for {m['obj']}, {m['ask']}{text[m.end() :]}"
    if len(lexicon.scene.objects) != 2:
        return text  # 'either' counts two things: a scene of more is left and refused
    return _sub(
        r"\beither of them\?\s+either (?:thing|one)(?:,\s*(?:i don't mind|whichever|any))?"
        r"(?:,\s*sorry)?\s*[.!]?$",
        "either thing?",
        text,
    )


def _reason_for_change34t(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12t): a closing reason that names only the object the request leaves out or
    corrects away, so it changes nothing: '… but not the apple, she hates apples' (a dislike from
    a closed list, after 'not' that object) and '…, wait, sorry, the apple, I had chips on the
    brain' (the slip explained: the object replaced) — taken off when what is before it reads
    and does not move that object. 'everything you've got there' is 'everything you've got'."""
    out = _sub(r"\beverything you've got there\b", "everything you've got", text)
    m = _rx(
        r",\s*(?:(?:he|she|they) (?:hates|hate|doesn't like|don't like|can't stand|isn't keen on|"
        r"is allergic to)|i (?:had|have|'ve got|got) (?P<slip>[a-z]+) on the brain)"
        r"(?P<what>(?: [a-z]+)?)\s*[.!]?$"
    ).search(out)
    if m is None:
        return out
    named = m["slip"] or m["what"].strip()
    before = out[: m.start()]
    ids = _ids(named, lexicon, "object") if named else set()
    if len(ids) != 1 or not _names(named, lexicon) or not _objects_only(named, lexicon):
        return out
    (oid,) = ids
    cue = r"\bnot (?:the )?" if not m["slip"] else r"\b(?:sorry|wait|no)\b.*"
    if oid not in _ids(before, lexicon, "object") or not _rx(cue).search(before):
        return out
    said = _tasks_of(before, lexicon)
    if not said or oid in {obj for _, obj, _ in said}:
        return out
    return before + "."


# -- session 35 (engineer 12t): blind19, blind23, blind18, blind17 and causes15's kinds --------


@functools.lru_cache(maxsize=64)
def _person_alt35t(lexicon: Lexicon) -> str:
    """A pattern of every name or alias that names one person of the scene, longest first (once
    per lexicon, session 46, 12p: the five always-run steps that ask it built it again for each
    text, ~2 % of an instruction's CPU; it depends on the scene's names alone). Names of one
    length in alphabetical order (session 54, 12p): the set's order changed from run to run, and
    with it the pattern's text (the warm list's), never what it matches — names of one length
    that match at one place match the same letters."""
    names = {n for h in lexicon.scene.humans for n in (h.name, *h.aliases)}
    alone = [n for n in names if _only_person(n, lexicon)]
    return "|".join(re.escape(n) for n in sorted(alone, key=lambda n: (-len(n), n))) or r"(?!)"


# words for kin of one sex, in a person's names ('Grandad', 'big sister'): like a first name of
# one sex, they only rule a he / she out, never resolve one
_KIN_SEX35T = {
    **dict.fromkeys(
        (
            "grandad",
            "granddad",
            "grandpa",
            "grandfather",
            "dad",
            "daddy",
            "father",
            "uncle",
            "brother",
            "son",
            "husband",
            "boy",
            "man",
            "gentleman",
            "grandson",
            "nephew",
        ),
        "m",
    ),
    **dict.fromkeys(
        (
            "grandma",
            "granny",
            "gran",
            "nan",
            "nana",
            "nanna",
            "grandmother",
            "mum",
            "mummy",
            "mom",
            "mommy",
            "mother",
            "aunt",
            "auntie",
            "sister",
            "daughter",
            "wife",
            "girl",
            "woman",
            "lady",
            "granddaughter",
            "niece",
        ),
        "f",
    ),
}


def _may_be35t(pid: str, pronoun: str, lexicon: Lexicon) -> bool:
    """Whether he/she ``pronoun`` may be person ``pid``: neither a title, nor a first name of one
    sex (data/first_names_sex.txt), nor a word for kin of one sex in its names says otherwise
    (used here only to rule a reading out)."""
    sex = PRONOUN_SEX[pronoun.lower()]
    human = next(h for h in lexicon.scene.humans if h.id == pid)
    names = [n.lower().split() for n in (human.name, *human.aliases)]
    firsts = {n[0] for n in names if n[0].rstrip(".") not in TITLES}
    said = {name_sexes().get(n) for n in firsts} | {_KIN_SEX35T.get(w) for n in names for w in n}
    return title_sex(pid, lexicon) in (None, sex) and said - {None} <= {sex}


# -- session 36 (engineer 12): blind34's refusals by kind in the sections of politeness, wants,
# pronouns and ellipsis, splits and run-ons, lower case, typos and questions. Each rule a closed
# pattern checked against the scene; a remark is taken off only when it names nothing of the
# scene and asks nothing (_asks_nothing29, or a closed list written in the pattern).


def _fit36(pid: str, text: str, lexicon: Lexicon) -> bool:
    """Whether every he/she/him/her in ``text`` may be person ``pid``: by title (_fits), and by
    a first name or a word for kin of one sex (_may_be35t)."""
    said = re.findall(r"\b(?:he|him|his|she|her|hers)\b", text, _F)
    return _fits(pid, text, lexicon) and all(_may_be35t(pid, w, lexicon) for w in said)


def _closing_remarks36(text: str, lexicon: Lexicon) -> str:
    """Session 36: a comma part wholly one of the closed remarks above (its words naming nothing
    and asking nothing) taken off; 'he's the one back from X' closing a request to one person
    the pronoun may be, taken off."""
    low = text.lower()
    if any(w in low for w in ("night", "day", "shift", "week", "clock", "time")):

        def drops(c: str) -> bool:
            c = c.strip()
            m = _ROUGH_NIGHT36.fullmatch(c) or _OCLOCK36.fullmatch(c)
            return m is not None and (m["what"] is None or _asks_nothing29(m["what"], lexicon))

        text = _stretches_dropped(text, drops, lexicon)
    m = _BACK_FROM36.search(text)
    if m is not None and _asks_nothing29(m["what"], lexicon):
        people = _ids(text[: m.start()], lexicon, "human")
        if len(people) == 1 and _fit36(next(iter(people)), m["pron"], lexicon):
            text = text[: m.start()] + m["end"].strip()
    return text


def _keep_going36(text: str, lexicon: Lexicon) -> str:
    """Session 36: 'to keep her going (at …)' closing a want of person P taken off, when the
    pronoun may be P and the place or doing names nothing and asks nothing."""
    if "going" not in text:
        return text
    m = _KEEP_GOING36.search(text)
    if m is None or (
        m["what"] is not None and not _asks_nothing29(m["what"].split(" ", 1)[1], lexicon)
    ):
        return text
    s = _SUBJECT36.search(text[: m.start()])
    if s is None or not _only_person(s["p"], lexicon):
        return text
    if m["pron"].lower() == "them" or not _fit36(
        next(iter(_ids(s["p"], lexicon))), m["pron"], lexicon
    ):
        return text
    return text[: m.start()] + text[m.end() :]


def _want_with36(text: str, lexicon: Lexicon) -> str:
    """Session 36: ', and he'll want Y with it' after a request of one person P is ', and Y for
    P' (the pronoun may be P, Y objects only)."""
    if "'ll " not in text and " will " not in text:
        return text
    m = _WANT_WITH36.search(text)
    if m is None or not _things31(m["x"], lexicon):
        return text
    people = _ids(text[: m.start()], lexicon, "human")
    if len(people) != 1 or not _fit36(next(iter(people)), m["pron"], lexicon):
        return text
    (p,) = people
    name = next(h for h in lexicon.scene.humans if h.id == p).name
    if not _only_person(name, lexicon):
        return text
    return f"{text[: m.start()]}, and {m['x']} for {name}{m['end'].strip()}"


def _whose_then36(text: str, lexicon: Lexicon) -> str:
    """Session 36: the two statements above before a request said by pronouns: the request
    alone, its one object pronoun (of X's number) said as X and its one person pronoun (which
    may be P) as P; X objects only, P one person, no other name in the request."""
    m = _LOST_HIS36.match(text) or _ARE_WHOSE36.match(text)
    if m is None:
        return text
    x = (
        m["x"]
        if m["x"].lower().startswith(("the ", "that ", "this ", "those ", "these "))
        else (f"the {m['x']}")
    )
    if not _things31(x, lexicon) or not _only_person(m["p"], lexicon) or _names(m["req"], lexicon):
        return text
    p = next(iter(_ids(m["p"], lexicon)))
    if "pos" in m.groupdict() and not _fit36(p, m["pos"], lexicon):
        return text
    obj = "them" if _plural36(x, lexicon) else "it"
    req = m["req"]
    if len(re.findall(rf"\b{obj}\b", req, _F)) != 1:
        return text
    people = re.findall(r"\b(?:him|her)\b", req, _F)
    if len(people) != 1 or not _fit36(p, people[0], lexicon):
        return text
    req = re.sub(rf"\b{obj}\b", x.lower(), req, count=1, flags=_F)
    req = re.sub(r"\b(?:him|her)\b", m["p"], req, count=1, flags=_F)
    return req[0].upper() + req[1:]


def _also_hers36(text: str, lexicon: Lexicon) -> str:
    """Session 36: ', also hers' closing, taken off when the instruction names one person (the
    pronoun may be them) and every pronoun before is that person's."""
    m = _ALSO_HERS36.search(text)
    if m is None or m["pron"].lower() == "theirs":
        return text
    before = text[: m.start()]
    people = _ids(before, lexicon, "human")
    if len(people) != 1 or not _fit36(next(iter(people)), before + " " + m["pron"], lexicon):
        return text
    return before + m["end"].strip()


def _body_state36(text: str, lexicon: Lexicon) -> str:
    """Session 36: the closing remark above taken off after a request to one person the pronoun
    may be."""
    if (
        " feet" not in text
        and " hands" not in text
        and " toes" not in text
        and (" fingers" not in text and " nose" not in text and " ears" not in text)
    ):
        return text
    m = _BODY36.search(text)
    if m is None:
        return text
    before = text[: m.start()]
    people = _ids(before, lexicon, "human")
    if len(people) != 1 or not _fit36(next(iter(people)), m["pron"], lexicon):
        return text
    return before.rstrip(" ,") + ("." if before.rstrip()[-1:] not in ".!?" else "")


def _said_again36(text: str, lexicon: Lexicon) -> str:
    """Session 36: 'and likewise X' is 'and X'; "P's thirsty he wants X" is 'P wants X' (P one
    person the pronoun may be)."""
    if "likewise" in text.lower():
        text = _LIKEWISE36.sub("and ", text)
    m = _STATE_WANTS36.match(text)
    if (
        m is not None
        and _only_person(m["p"], lexicon)
        and _fit36(next(iter(_ids(m["p"], lexicon))), m["pron"], lexicon)
    ):
        text = f"{m['p']} {m['v']}{text[m.end() :]}"
    return text


_STEPS36: tuple[Callable[[str, Lexicon], str], ...] = (
    _courtesies36,
    _asked36,
    _why_placed36,
    _closing_remarks36,
    _time_for36,
    _wants_said36,
    _keep_going36,
    _want_with36,
    _run_on_mid36,
    _said_again36,
    _give_them_those36,
    _whose_then36,
    _also_hers36,
    _body_state36,
    _stay_put36,
    _trade_said36,
    _announced36,
)


_STATE35T = r"(?:'s|\s+is|\s+was|'s been|\s+has been)"


def _state_and35t(text: str, lexicon: Lexicon) -> str:
    """Session 35 (12t): a person's state joined by 'and' (no comma) to a clause whose subject is
    'she' / 'he' ("so Lily's in her high chair now and she'll need her bib …"): the 'and' is the
    comma the same run-on has ("Lily's in her high chair now, she'll need her bib"), read as that
    one is — only when the state is said of one person, names no object or other person, carries
    no negation or time, and the pronoun may be that person."""
    people = _person_alt35t(lexicon)
    m = _rx(
        rf"(?:^|(?<=[.!?;,])\s+)(?:(?:so|well|right|okay|ok),?\s+)*(?P<p>{people})"
        rf"(?P<state>{_STATE35T}\s+[a-z' ]+?) and (?P<pro>she|he)"
        r"(?='s\b|'ll\b|'d\b|\s+(?:is|will|would|needs|wants|has|could|can)\b)"
    ).search(text)
    if m is None or not _may_be35t(next(iter(_ids(m["p"], lexicon, "human"))), m["pro"], lexicon):
        return text
    state = m["state"]
    if (
        _ids(state, lexicon, "object")
        or _ids(state, lexicon, "human")
        or _rx(
            r"\b(?:not|n't|no|never|nobody|nothing|and|then|tonight|tomorrow|later|soon)\b"
        ).search(state.replace("n't", " n't"))
        or _opens_request(state)
    ):
        return text
    cut = m.start("pro") - len(" and ")
    return f"{text[:cut]}, {text[m.start('pro') :]}"


def _subject_pronoun35t(text: str, lexicon: Lexicon) -> str:
    """Session 35 (12t): after another person has been named, a clause of one person then a
    comma and 'he' / 'she' opening the next clause, a want or request (", and Person B has been
    eyeing up the chips, he wants those"), or 'since' / 'because' and 'he' / 'she' opening a
    reason (", and Person B gets the chips since he skipped lunch"): the pronoun goes on with
    that clause's subject, so it is that person (said by name; a remark after a comma, '…, he
    told me before', is left to the rules for remarks) — only when that clause names no other
    person and no other he/she/him/her,
    the pronoun may be that person (title, first name), and no person named before is one the
    pronoun fits by title when that person's does not say (then it is refused as before)."""
    # a name as the scene has it, or one or two words the lexer takes for one person (a typo)
    people = rf"{_person_alt35t(lexicon)}|[a-z]+ [a-z]\b|[a-z]+"
    pattern = _rx(
        rf"(?:,\s*and\s+|;\s*|[.!?]\s+)(?:so\s+)?(?P<p>{people})"
        r"(?P<clause>(?:'s|\s)[^,.;!?]+?)(?P<link>,\s+|\s+(?:since|because|cos)\s+)"
        r"(?P<pro>she|he)(?=(?:'s|'ll|'d)\b|\s+[a-z])"
        r"(?P<then>[^,.;!?]*)"
    )
    for m in pattern.finditer(text):
        before = text[: m.start()]
        pid = next(iter(_ids(m["p"], lexicon, "human"))) if _only_person(m["p"], lexicon) else ""
        sex = PRONOUN_SEX[m["pro"].lower()]
        earlier = _ids(before, lexicon, "human") - {pid}
        if (
            not pid
            or not earlier
            or (m["link"].strip() == "," and not _rx(_TASK_WORDS).search(m["then"]))
            or _ids(m["clause"], lexicon, "human")
            or _rx(r"\b(?:he|him|his|she|her|hers|they|them)\b").search(m["clause"])
            or not _may_be35t(pid, m["pro"], lexicon)
            or (
                title_sex(pid, lexicon) != sex
                and any(title_sex(q, lexicon) == sex for q in earlier)
            )
        ):
            continue
        return f"{text[: m.start('pro')]}{m['p']}{text[m.end('pro') :]}"
    return text


def _gapped_passive35t(text: str, lexicon: Lexicon) -> str:
    """Session 35 (12t): a passive of wanting, then 'and' and a second object with 'by' and a
    second person ('The chips are wanted by Person A and the bottle by Person B'): the second
    clause is the first with its verb left out (a gap), so its 'by' is the first's, whom it is
    wanted by, not where the object is — 'Person A wants the chips and Person B wants the
    bottle'. Only with two different persons, each one of the scene's, objects alone before
    each 'by', and nothing after the second person; without the passive before it ('Person A
    wants the chips, and the bottle by Person B') it stays refused with both readings."""
    people = _person_alt35t(lexicon)
    det = r"(?:the|a|an|that|this|these|those) "
    m = _rx(
        rf"(?:^|(?<=[.!?;])\s+)(?P<o1>{det}[\w '-]+?)(?:'s| is| are) (?:wanted|needed|asked for|"
        rf"requested) by (?P<p1>{people}),? and (?P<o2>{det}[\w '-]+?) by (?P<p2>{people})"
        r"(?P<end>\s*[.!]?)$"
    ).search(text)
    if m is None:
        return text
    p1, p2 = (_ids(m[k], lexicon, "human") for k in ("p1", "p2"))
    if p1 == p2 or not all(_only_kind(m[k], lexicon, "object") for k in ("o1", "o2")):
        return text
    return f"{text[: m.start()]}{m['p1']} wants {m['o1']} and {m['p2']} wants {m['o2']}{m['end']}"


def _in_the_way35t(text: str, lexicon: Lexicon) -> str:
    """Session 35 (12t): a closing reason that says only where the one object put away is now
    ('chuck the blue pen in the box its cluttering my desk', "Put the cup on the shelf, it's
    cluttering the counter"): 'it' with a verb of being in the way from a closed list and the
    place it is cluttering, a surface of the scene other than where it goes (or a place the
    scene does not name) — taken off when what is before it reads alone as placing that one
    object. After no comma, 'its' there is "it's" (texting)."""
    m = _rx(
        r"(?:,\s*|\s+)(?:it's|its|it is) (?:cluttering(?: up)?|in the way (?:on|of)|blocking|"
        r"taking up (?:space|room) on|all over) (?:the|my|our|your) (?P<s>[a-z][\w ]*?)\s*[.!]?$"
    ).search(text)
    if m is None or _ids(m["s"], lexicon, "object") or _ids(m["s"], lexicon, "human"):
        return text
    before = text[: m.start()]
    said = _tasks_of(before, lexicon)
    if not said or len(said) != 1:
        return text
    ((kind, _, target),) = said
    if kind != "place" or target in _ids(m["s"], lexicon, "surface"):
        return text
    return before + "."


def _aside_else35t(text: str, lexicon: Lexicon) -> str:
    """Session 35 (12t): words said to someone other than the robot, from closed lists, taken
    off: a kitchen call taken back on seeing the robot ("Chef, sorry, behind you... oh, it's the
    robot. Could you …": the call is to the chef, the request after it to the robot), and a pause
    to tell the robot something with its close ("Yeah, hang on, Dave, I'm just telling the robot
    something. Robot, please hand Bob the bottle. Thanks. Sorry Dave, go on."), the close only
    with the name the pause gave, which names no one and nothing of the scene. Neither may name
    an object; a request in them is left, and refused as before."""
    out = text
    m = _rx(
        r"^(?:(?P<voc>[a-z][\w ]*?),\s*)?(?:sorry,?\s*)?(?:behind(?: you)?|coming through|mind "
        r"your backs?)(?:\.\.\.|[.!,])\s*(?P<oh>oh,?\s*it's (?:just |only )?the robot[.!]\s+)"
    ).match(out)
    if m is not None and not _ids(m[0], lexicon, "object") and len(_ids(m[0], lexicon)) <= 1:
        out = m["oh"][0].upper() + out[m.start("oh") + 1 :]
    m = _rx(
        r"^(?:(?:yeah|yes|ok|okay|right),?\s*)?(?:hang on|hold on|one sec(?:ond)?|just a "
        r"sec(?:ond)?),?\s*(?P<voc>[a-z]+),?\s*i'm (?:just )?(?:telling|asking) the robot "
        r"(?:something|a thing)[.!]\s+"
    ).match(out)
    if m is None or not _names_nothing(m["voc"], lexicon) or m["voc"].lower() in WORDS:
        return out
    rest = out[m.end() :]
    close = _rx(
        rf"(?<=[.!?])\s+sorry,?\s*{re.escape(m['voc'])},?\s*(?:go on|carry on|you were "
        r"saying)[.!]?$"
    ).search(rest)
    if close is not None:
        rest = rest[: close.start()]
    return rest


def _introduced35t(text: str, lexicon: Lexicon) -> str:
    """Session 35 (12t): a person introduced by a name the scene gives that person ('Mrs Khan is
    our new patient: the blue blanket for her, please'): it says who is who and asks nothing,
    so it is read as the person being there ('Mrs Khan is here: …', which the grammar reads) —
    only when the role is one of that person's own names (shared or not: 'patient' is Mr Lee's
    too) and the person is one of the scene's; 'Mrs Khan is our new nurse' (Ruth's) is left."""
    people = _person_alt35t(lexicon)
    m = _rx(
        rf"^(?P<p>{people}) is (?:our|the|my|your|a) (?:new |latest |other )?(?P<r>[a-z][\w ]*?)"
        r"(?P<sep>\s*[:;,.]\s+)"
    ).match(text)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    (pid,) = _ids(m["p"], lexicon, "human")
    human = next(h for h in lexicon.scene.humans if h.id == pid)
    if m["r"].lower() not in {a.lower() for a in human.aliases}:
        return text
    return f"{m['p']} is here{m['sep']}{text[m.end() :]}"


def _with_one_there35t(text: str, lexicon: Lexicon) -> str:
    """Session 35 (12t): 'with the Y' after the surface an object goes to, where Y is one other
    object of the scene that starts on that surface ('Any chance the red book could go up on the
    shelf with the green one?' when the green book lies on the shelf): it says where on the
    surface, as 'next to the green one' does, and asks nothing of Y (already there) — taken off.
    'the green one' is the moved object's kind; a Y elsewhere, or not one object, stays refused
    (it may ask to move Y too)."""
    m = _rx(
        r"\b(?:on|onto|in|into) (?:the )?(?P<s>[a-z][\w ]*?) with (?P<y>the [a-z]+(?: [a-z]+)?)"
        r"(?=\s*[,.!?]|$)"
    ).search(text)
    if m is None or not _only(m["s"], lexicon, "surface"):
        return text
    moved = _ids(text[: m.start()], lexicon, "object")
    if len(moved) != 1:
        return text
    (oid,) = moved
    y = m["y"]
    if y.lower().endswith(" one"):
        kind = next(o.category for o in lexicon.scene.objects if o.id == oid)
        y = f"{y[:-4]} {kind}"
    if not _only(y, lexicon, "object"):
        return text
    (yid,) = _ids(y, lexicon, "object")
    (sid,) = _ids(m["s"], lexicon, "surface")
    if yid == oid or starting_on({yid}, sid, lexicon) != [yid]:
        return text
    return text[: m.end("s")] + text[m.end("y") :]


# what a drink is said as, and the kinds of the scene's objects that hold one
_DRINKS35T = r"(?:water|a drink|drink|juice|milk|squash|tea|coffee|a brew|a cuppa)"
_HOLDERS35T = frozenset({"jug", "bottle", "cup", "mug", "beaker", "glass", "flask"})


def _drink_in35t(text: str, lexicon: Lexicon) -> str:
    """Session 35 (12t): a want of a drink, then the one object of the scene that holds it said
    after a comma ('Mr Lee wants some water, the jug please'): the object is what is wanted —
    only for a drink from a closed list and an object whose kind holds drink (a jug, bottle,
    cup, mug, beaker, glass, flask); 'wants some water, the blanket please' and 'Priya wants a
    coffee' stay refused."""
    m = _rx(
        rf"\b(?P<want>wants|needs|would like|'d like|could do with) (?:some )?{_DRINKS35T}"
        r"(?:,\s*|\s*[-—:]\s*)(?P<x>the [a-z]+(?: (?!please\b)[a-z]+)?)"
        r"(?P<tail>(?:,?\s*please)?\s*[.!]?)$"
    ).search(text)
    if m is None or not _only(m["x"], lexicon, "object"):
        return text
    (oid,) = _ids(m["x"], lexicon, "object")
    if next(o.category for o in lexicon.scene.objects if o.id == oid) not in _HOLDERS35T:
        return text
    return f"{text[: m.start()]}{m['want']} {m['x']}{m['tail']}"


# a closing question of a speaker checking they were understood, from a closed list
_UNDERSTOOD35T = (
    r",?\s*(?:capisce|capiche|comprende|comprendez|savvy|understood|got that|you got that|"
    r"get it|follow me)\s*\?\s*$"
)


def _understood35t(text: str, lexicon: Lexicon) -> str:
    """Session 35 (12t): '…, capisce?' / ', savvy?' / ', understood?' closing a request ('Pronto,
    the cup to Person A, capisce?'): a check that the request was understood, asking nothing —
    taken off when what is before it reads alone."""
    m = _rx(_UNDERSTOOD35T).search(text)
    if m is None or m.start() == 0:
        return text
    before = text[: m.start()].rstrip(" ,")
    return before + "." if _tasks_of(before, lexicon) else text


def _can_keep35t(text: str, lexicon: Lexicon) -> str:
    """Session 35 (12t): 'P can keep the X' where the scene has X lying about (no one holds
    anything in a scene) is 'P can have the X': P is to end up with it ('Person B can keep the
    bottle, and the chips are for the other one') — only with one person of the scene, objects
    alone after 'keep', and the clause ending there."""
    people = _person_alt35t(lexicon)
    return _sub(
        rf"\b(?P<p>{people}) (?:can|may|gets to) keep (?P<x>the [a-z]+(?: [a-z]+)?)"
        r"(?=\s*(?:[,.!;]|$))",
        lambda m: (
            f"{m['p']} can have {m['x']}"
            if _only_person(m["p"], lexicon) and _only_kind(m["x"], lexicon, "object")
            else m[0]
        ),
        text,
    )


# -- session 36 (engineer 12t) ---------------------------------------------------------------

# the words after 'the next' that point back to a task or an object ('before the next one'),
# never an event of the world
_NEXT_TASK36T = frozenset(
    (
        "one",
        "ones",
        "thing",
        "things",
        "bit",
        "bits",
        "item",
        "items",
        "task",
        "tasks",
        "step",
        "steps",
        "job",
        "jobs",
        "lot",
        "person",
        "people",
        "time",
        "go",
        "turn",
        "round",
    )
)
_NEXT_EVENT36T = re.compile(
    r"(?P<lead>,?\s+before the) next (?P<noun>[a-z]+)(?P<more>(?: [a-z']+){0,3})"
    r"(?P<end>\s*[.!]?)\s*$",
    _F,
)


def _next_event36t(text: str, lexicon: Lexicon) -> str:
    """Session 36 (12t): a closing deadline 'before the next <noun> …' whose noun is an event of
    the world ("Drop the scnner on the belt before the next load comes down."): 'next' there
    orders nothing of the request, so the deadline is read as '… before the load comes down' is
    (`_when` / `_before_deadline32`: met by doing the task now) — only when the noun names nothing
    of the scene (nor a typo of it), is no word for a task or an object ('the next one', 'the next
    bit'), and the deadline without 'next' is one those rules take off; else left as it was."""
    m = _NEXT_EVENT36T.search(text)
    if m is None or m["noun"].lower() in _NEXT_TASK36T or _names(m["noun"], lexicon):
        return text
    plain = f"{text[: m.start()]}{m['lead']} {m['noun']}{m['more']}{m['end']}"
    for rule in (_when, _before_deadline32):
        out = rule(plain, lexicon)
        if out != plain and "before" not in out[m.start() :].lower():
            return out
    return text


def _sure36t(pid: str, pronoun: str, lexicon: Lexicon) -> bool:
    """Whether he/she ``pronoun`` is person ``pid`` by what the scene says of its sex: a title or
    word of kin (`said_sex35s`) or a first name of that sex (data/first_names_sex.txt)."""
    sex = PRONOUN_SEX[pronoun.lower()]
    human = next(h for h in lexicon.scene.humans if h.id == pid)
    firsts = {n.lower().split()[0] for n in (human.name, *human.aliases)}
    named = {name_sexes().get(n) for n in firsts} - {None}
    return said_sex35s(pid, lexicon) == sex or named == {sex}


def _people_in36t(text: str, lexicon: Lexicon) -> str:
    """Session 36 (12t): 'Marco and Lena are (both) in (now).' — people 'in' with no place after
    it have come in, as 'Lena's in now' says of one (`_why_said_first`): read as '… are here'.
    Only for a sentence of people named alone, joined by 'and'."""

    def here(m: re.Match[str]) -> str:
        who = re.split(r",\s*|\s+and\s+", m["who"])
        return (
            f"{m['who']} are here{m['rest']}"
            if len(who) > 1 and all(_only_person(w, lexicon) for w in who)
            else m[0]
        )

    return _sub(
        r"(?:^|(?<=[.!?]\s))(?P<who>[^,.!?;]+?) (?:are|'re) (?:both |all )?in"
        r"(?P<rest>(?: now)?(?:[.!,]|$))",
        here,
        text,
    )


def _no_trouble36t(text: str, lexicon: Lexicon) -> str:
    """Session 36 (12t): "if it's not too much trouble could the apple maybe go to Carol?" — the
    condition of courtesy said straight before a polite question (no comma between: session 19's
    `_hedges19` takes it off only before a comma or the end) asks nothing: taken off, so the
    question is read as said alone (its 'maybe' a softener there). Only 'trouble' / 'bother', and
    only before could / can / would / will / might opening the question."""
    return _sub(
        r"(?:^|(?<=[.!?,]\s))(?:but\s+)?if (?:it's|it is) (?:not|no) (?:too much |any )?"
        r"(?:trouble|bother)\s*,?\s+(?=(?:could|can|would|will|might) [a-z])",
        "",
        text,
    )


# the words before 'habit' read as 'force of habit' after an apology (a closed list)
_HABITS36T = r"chef|kitchen|workshop|old|bad"


def _habit36t(text: str, lexicon: Lexicon) -> str:
    """Session 36 (12t): "Behind! Sorry, chef habit." — '<word> habit' after an apology, closing
    its sentence, is 'force of habit' (read since session 15 as the apology for a call) for the
    words of a closed list (`_HABITS36T`, the trades and places session 15's remark openers name:
    'chef', 'kitchen', 'workshop', and 'old', 'bad'); 'salt habit', 'Lena habit', a request before
    the apology or no full stop after it are left (refused)."""

    return _sub(
        rf"\b(?P<sorry>sorry),\s+(?:an?\s+)?(?:{_HABITS36T}) habits?(?=\s*[.!])",
        lambda m: f"{m['sorry']}, force of habit",
        text,
    )


# words for the children of a group, said of the people of a shared role for children (a closed
# list both ways: 'the kids' of the classroom's two students)
_KIDS36T = r"kids|children|pupils|schoolkids|schoolchildren"
_CHILD_ROLES36T = ("student", "pupil")


def _kids36t(text: str, lexicon: Lexicon) -> str:
    """Session 36 (12t): "Each of the kids gets a book" — 'the kids' / 'the children' / 'the
    pupils' where two people or more of the scene share a role for children ('student', 'pupil')
    and no one else has it: those people, said as the role's plural ('the students', which the
    grammar reads as every one of them). Left as it was in a scene without such a role (the
    nursery's toddler and big sister are no role shared) or when a name of the scene is one of
    those words."""
    said = {a.lower() for h in lexicon.scene.humans for a in (h.name, *h.aliases)}
    if said & set(_KIDS36T.split("|")):
        return text
    for role in _CHILD_ROLES36T:
        held = [h for h in lexicon.scene.humans if role in (a.lower() for a in h.aliases)]
        if len(held) >= 2:
            return _sub(rf"\bthe (?:{_KIDS36T})\b", f"the {role}s", text)
    return text


# 'human <noun>' naming a thing or an act, never a person (a closed list)
_HUMAN_NOUN36T = re.compile(
    r"\bhuman (?=(?:pyramid|pyramids|chain|chains|tower|towers|shield|error|nature|touch|"
    r"rights|race|resources|cannonball|statue|statues)\b)",
    _F,
)


def _human_noun36t(text: str, lexicon: Lexicon) -> str:
    """Session 36 (12t): "Ava is building a tower like the acrobats' human pyramid; the two
    blocks to her." — 'human' before a noun of a closed list ('pyramid', 'chain', 'error', …) is
    an adjective, not the word for any person (`GENERIC_PEOPLE`), so it is taken off; 'a human',
    'the human' and 'human being' are left."""
    return _HUMAN_NOUN36T.sub("", text)


def _then_header36t(text: str, lexicon: Lexicon) -> str:
    """Session 36 (12t): "Bob, then Alice: chips for him, bottle for her" — a header of two people
    in order ('P, then Q:') and after it one object for each, said with him / her in that order:
    'chips to Bob, then bottle to Alice'. Only when each pronoun is its person for certain
    (`_sure36t`: a title, a word of kin or a first name of that sex) and the other person may not
    be it (`_may_be35t`); pronouns in the other order, or one either may be, are left (refused)."""
    m = _rx(
        r"^(?P<a>[^,:;.!?]+?),\s*(?:and\s+)?then\s+(?P<b>[^,:;.!?]+?)\s*:\s*(?P<x>[^,;.!?]+?) for "
        r"(?P<p>him|her),\s*(?:and\s+)?(?:then\s+)?(?P<y>[^,;.!?]+?) for (?P<q>him|her)"
        r"\s*(?P<end>[.!]?)\s*$"
    ).match(text.strip())
    if m is None or not (_only_person(m["a"], lexicon) and _only_person(m["b"], lexicon)):
        return text
    (a,) = _ids(m["a"], lexicon, "human")
    (b,) = _ids(m["b"], lexicon, "human")
    if a == b or not all(_only_kind(m[k], lexicon, "object") for k in ("x", "y")):
        return text
    p, q = m["p"].lower(), m["q"].lower()
    if not (_sure36t(a, p, lexicon) and _sure36t(b, q, lexicon)):
        return text
    if _may_be35t(b, p, lexicon) or _may_be35t(a, q, lexicon):
        return text
    return f"{m['x']} to {m['a']}, then {m['y']} to {m['b']}{m['end']}"


def _said_wanted36t(text: str, lexicon: Lexicon) -> str:
    """Session 36 (12t): "… and omar said he wanted the bowl but he can wait …" — '<P> said he /
    she wanted the X' is P's want, 'P wants the X' (the pronoun opening the clause said by P is P,
    as `_subject_pronoun35t` reads one opening the clause after P's): only when P names one person
    the pronoun is for certain (`_sure36t`: a title, a word of kin or a first name of that sex) and
    what is wanted names objects alone. ('Mr Lee said she wanted the jug' and 'Emma said he wanted
    the bowl', a name the list gives no sex, are left, refused.)"""

    def want(m: re.Match[str]) -> str:
        if not _only_person(m["p"], lexicon) or not _only_kind(m["x"], lexicon, "object"):
            return m[0]
        (pid,) = _ids(m["p"], lexicon, "human")
        if not _sure36t(pid, m["pro"], lexicon):
            return m[0]
        return f"{m['lead']}{m['p']} wants {m['x']}"

    return _sub(
        r"(?P<lead>^|\band |,\s*)(?P<p>[A-Za-z]\w*(?: [A-Za-z]\w*){0,2}) said (?P<pro>he|she) "
        r"(?:wanted|needed|"
        r"would like|'d like) (?P<x>(?:the|a|an|some|both) [a-z ]+?)(?=\s*(?:,|\bbut\b|\band\b|"
        r"[.!?]|$))",
        want,
        text,
    )


_STEPS36T: tuple[Callable[[str, Lexicon], str], ...] = (
    _next_event36t,
    _people_in36t,
    _no_trouble36t,
    _habit36t,
    _kids36t,
    _human_noun36t,
    _then_header36t,
    _said_wanted36t,
)


_STEPS35T: tuple[Callable[[str, Lexicon], str], ...] = (
    _state_and35t,
    _subject_pronoun35t,
    _gapped_passive35t,
    _in_the_way35t,
    _aside_else35t,
    _introduced35t,
    _with_one_there35t,
    _drink_in35t,
    _understood35t,
    _can_keep35t,
)


_STEPS34T: tuple[Callable[[str, Lexicon], str], ...] = (
    _counted_those34t,
    _objects_said34t,
    _reported_want34t,
    _closers34t,
    _frames34t,
    _thing_cleft34t,
    _asked_first34t,
    _sorted_first34t,
    _only_one34t,
    _remark_places34t,
    _idioms34t,
    _after_those34t,
    _left_as_was34t,
    _telegraph34t,
    _run_on_state34t,
    _for_said34t,
    _reasons_said34t,
    _target_for34t,
    _pirate34t,
    _reported_fix34t,
    _singlish34t,
    _dedication34t,
    _legal34t,
    _fronted_asked34t,
    _reason_for_change34t,
)


# A sentence of its own that only counts what the sentences before asked for: "Give Bob the cup.
# One thing, that's the lot.", "… Two things in all." It asks for nothing: it is a check (the
# grounder reads the rest and compares; offline.py). Found by 12c's 'afterthoughts' fuzz: "Hand
# Bob the bottle. Two things, that's the lot." read as both objects for Bob.
_COUNT_ONLY30 = (
    r"(?:that(?:'s| is| makes) |so )?(one|two|three|four|five|six|both|\d) (?:things?|items?)"
    r"(?: (?:in all|all told|in total|total))?"
    r"(?:,? (?:that's|that is) (?:the lot|all|it|everything)(?: (?:then|now))?)?"
)


def count_said30(text: str) -> tuple[str, int, str] | None:
    """The first sentence of ``text`` after another that only counts things ('Two things,
    that's the lot.'): ``text`` without it, the count, and the sentence; None if there is none."""
    sentences = re.split(r"(?<=[.!?])\s+", text.strip())
    for k, sentence in enumerate(sentences[1:], start=1):
        m = _rx(rf"^{_COUNT_ONLY30}\s*[.!]?$").match(sentence.strip())
        if m is not None:
            word = m.group(1).lower()
            count = int(word) if word.isdigit() else _NUMBERS15[word]
            return " ".join([*sentences[:k], *sentences[k + 1 :]]), count, sentence.strip()
    return None


# Session 35 (lead): a count said right before a kind of the scene's objects ('three plates',
# 'all 3 cups'); 'two of the …' (a part of them) is not one: its whole is counted
_COUNTED35L = re.compile(r"\b(two|three|four|five|six|[2-6])\s+([a-z]+)\b", _F)


def miscounted35l(text: str, lexicon: Lexicon) -> None:
    """Refuse ``text`` when it counts more of a kind of the scene's objects than the scene has,
    wherever it says so (12c's counts fuzz: "Lena is taking the three plates out, so she needs
    both of them" read both plates for Lena, the count in the reason clause dropped with it). A
    speaker who counts what is not there may mean something else, so the request is not read.
    Fewer is left to the grammar ('two boxes, the small and the medium' picks two of three; 'the
    two boxes, the small and the medium one' names them); words for any object ('things',
    'items') name several kinds and are counted by the grammar, not here."""
    for m in _COUNTED35L.finditer(text):
        word = m.group(1).lower()
        said = int(word) if word.isdigit() else _COUNTS[word]
        refs = [r for it in _names(m.group(2), lexicon) for r in it.refs]
        if not refs or any(r.kind != "object" for r in refs):
            continue
        ids = sorted({r.id for r in refs})
        kinds = {o.category for o in lexicon.scene.objects if o.id in ids}
        if len(kinds) == 1 and len(ids) < said:
            raise GroundingError(
                f"{m.group(0)!r}: the scene has {len(ids)} ({', '.join(ids)}) matching "
                f"{m.group(2)!r}, not {said}: name the ones meant"
            )


# Session 32 (12s): a statement closing the instruction after its request ("Could Bob have the
# crisps before we go on, he's the only tenor we've got?", "…, she's doing the X-ray rounds
# next."): who it is about, then a verb of its own
_TRAILING32S = re.compile(
    r"(?P<cut>[,.;!?]\s*(?:(?i:and|cos|because)\s+)?(?P<said>(?P<who>(?i:he|she|they|i|we|(?:his|"
    r"her|their|my|our) [a-z]+)|[A-Z][a-z]+(?: [A-Z][a-z]+)?)(?P<pred>(?:'s|'re|'m|'ve|'ll|'d|\s+"
    r"(?:is|are|am|was|were|has|have|had|will|would|says|said|asked|told|keeps|kept|does|did|can|"
    r"could|should|must|looks|seems|sounds|goes|went|came|comes))\b[^,.;!?]*)))(?P<end>[.!?]*)"
    r"\s*$"
)
# words that would make such a statement say something of the request: a negation, a choice,
# a count, a time or order, a correction, a want, a hand-over, a thing pointed at
_TRAILING_HELD32S = frozenset(
    {
        *("not", "n't", "never", "no", "nothing", "nobody", "none", "neither", "nor", "instead"),
        *("too", "also", "either", "only", "just", "rather", "prefer", "prefers", "wrong"),
        *("right", "mistake", "meant", "mean", "both", "each", "every", "all", "any", "which"),
        *("whichever", "whatever", "one", "ones", "two", "three", "four", "five", "first"),
        *("then", "after", "before", "later", "tomorrow", "tonight", "wait", "until", "till"),
        *("unless", "if", "or", "want", "wants", "wanted", "wanting", "need", "needs", "needed"),
        *("needing", "like", "likes", "love", "loves", "fancy", "fancies", "give", "gives"),
        *("hand", "pass", "bring", "take", "put", "place", "move", "send", "fetch", "get"),
        *("gets", "got", "getting", "have", "has", "had", "having", "already", "same", "other"),
        *("else", "it", "them", "those", "these", "that", "this", "mine", "yours", "hers"),
        *("his", "theirs", "ours", "allergic", "hates", "hate", "share", "keep", "keeps"),
        *("leave", "stay", "stays", "back", "again", "more", "less", "another", "for", "to"),
    }
)


# how long or since when, in such a statement ("she's been out on the water all day"); session
# 33: and 'all over the place' ("his lines are all over the place": no count)
_TRAILING_TIME32S = re.compile(
    r"\b(?:all (?:day|morning|afternoon|evening|night|week)(?: long)?|since (?:dawn|breakfast|"
    r"lunch|six|seven|eight|nine|ten|first thing|this morning)|for (?:ages|hours)|all over the "
    r"(?:place|shop)|in (?:two|five|ten|twenty|a (?:minute|mo|sec|tick|jiffy))(?: minutes)?)\b"
)


# such a statement between commas, before a request that opens on its verb
_BETWEEN32S = re.compile(
    r"(?P<cut>,\s*(?P<said>(?P<who>(?i:he|she|they|(?:his|her|their) [a-z]+)|[A-Z][a-z]+(?: [A-Z]"
    r"[a-z]+)?)(?P<pred>(?:'s|'re|\s+(?:is|are|was|were|has|have|had|will|would))\b[^,.;!?]*))"
    r"\s*,)(?=\s*(?:and\s+|so\s+|just\s+)?(?i:give|hand|pass|bring|take|put|place|pop|send|move)"
    r"\b)"
)


def _inert_statement32s(m: re.Match[str], before: str, lexicon: Lexicon) -> bool:
    """Whether the statement ``m`` matched (its 'said', 'pred') after the request ``before``
    holds none of the words that could say something of the request (_TRAILING_HELD32S: a
    negation, choice, count, time, correction, want, hand-over, or a word pointing at a thing;
    'all day', 'since seven' are its own times), no word of the scene's names but those of the
    people the request names, a he / she one of those people may be, and the request names an
    object."""
    pred = _TRAILING_TIME32S.sub(" ", m["pred"].lower())  # "all day", "since seven": when
    words = re.findall(r"[a-z]+(?:'[a-z]+)?|n't", pred)
    if not re.sub(r"^(?:'[a-z]+|\s+[a-z]+)", "", m["pred"]).strip():
        # session 33: "…; the crisps, Alice's.": a possessive that says whose the things before
        # it are (the afterthoughts fuzz: taken off, the crisps had gone to Bob), no statement
        return False
    if any(
        w in _TRAILING_HELD32S or w.split("'")[0] in _TRAILING_HELD32S or w.endswith("n't")
        for w in words
    ) or re.match(r"(?:'s|'re|\s+is|\s+are)\s+(?:up\s+)?next\b", pred):
        return False  # "…, Alice is next": next for something
    if not _ids(before, lexicon, "object"):
        return False
    request_people = _ids(before, lexicon, "human")
    said = m["said"]
    if not _ids(said, lexicon, "human") <= request_people or _ids(said, lexicon) - request_people:
        return False
    for pronoun in re.findall(r"\b(?:he|she|his|her)\b", said.lower()):
        if not any(title_sex(p, lexicon) in (None, PRONOUN_SEX[pronoun]) for p in request_people):
            return False  # "Don't take the jug to Mrs Khan, he's nil by mouth, …": who is he?
    names = _scene_words29(lexicon) - {
        w
        for p in request_people
        for h in lexicon.scene.humans
        if h.id == p
        for n in (h.id, h.name, *h.aliases)
        for w in n.lower().split()
    }
    return not any(w.split("'")[0] in names for w in words)


def _trailing_remark32s(text: str, lexicon: Lexicon) -> str:
    """Session 32 (12s): a statement after the request, closing the instruction, about the
    person it names, someone else or the speaker ("…, she's been out on the water all day?",
    "…, he's the only tenor we've got?", "…, she's doing the X-ray rounds next.", "…, his lines
    are all over the place."), is taken off when it is inert (_inert_statement32s); so is one
    between commas after a request and before another that opens on its verb ("Don't take the
    jug to Mrs Khan, she's nil by mouth, take it to Mr Lee."). Session 21's reasons and session
    29's remarks keep such a statement for the speaker's words ('we', 'me') or a word the grammar
    reads; those were refused. A he / she the request's person cannot be is checked where the
    rewrite is read (offline.py _ruled_out_dropped31s)."""
    m = _TRAILING32S.search(text)
    if m is not None and _inert_statement32s(m, text[: m.start()], lexicon):
        # session 34 (lead): a statement said as a sentence of its own leaves the request its own
        # end ('The stapler is for Priya? It's been a long morning.' stays a question: 12c's
        # asides fuzz read stapler>A, where the question alone is refused)
        own = text[m.start()] if text[m.start()] in ".!?" else ""
        return f"{text[: m.start()].rstrip()}{own or m['end'] or '.'}"
    m = _BETWEEN32S.search(text)
    if m is not None and _inert_statement32s(m, text[: m.start()], lexicon):
        return f"{text[: m.start()]},{text[m.end() :]}"
    return text


# Session 32 (12s): a statement about one person opening the instruction, then a request whose
# person is a pronoun ("Bob's had nothing since breakfast. Give him the apple, then the crisps.",
# "Person A's over there mending the nets. Take her the bottle, will you.")
# session 42 (12s): ' so' without a comma before the request too ("carols had a long shift at the
# pawn shop so give her …")
_OPENING_STATE32S = re.compile(
    r"^(?P<lead>(?:(?:oh|so|well|right|okay|ok)\s*,?\s+)*)(?:poor\s+)?(?P<who>[A-Za-z][\w]*(?: "
    r"[A-Za-z][\w]*)?)(?P<verb>'s|\s+(?:is|has|hasn't|has not|was|wasn't|isn't|is not|had|looks|"
    r"seems))\b(?P<words>[^.;!?,]*?)(?P<stop>[.;!]+\s+|,\s+(?=(?:so\s+)?(?:could|can|would|will|"
    r"please|give|hand|pass|bring|take|get|let|pop|put)\b)|\s+(?=so\s+(?:could|can|would|will|"
    r"please|give|hand|pass|bring|take|get|let|pop|put)\b))(?P<rest>\S.*)$",
    _F,
)
# words that would make the statement ask or say something of an object
_OPENING_HELD32S = frozenset(
    {
        *("give", "hand", "pass", "bring", "take", "put", "place", "send", "fetch", "get"),
        *("gets", "got", "want", "wants", "wanted", "wanting", "need", "needs", "needed"),
        *("needing", "like", "likes", "fancy", "fancies", "after", "asked", "asking", "it"),
        *("them", "that", "those", "these", "this", "one", "ones", "both", "either", "any"),
        *("which", "whichever", "whatever", "mine", "yours", "hers", "his", "theirs", "ours"),
        *("too", "also", "instead", "or", "and", "but", "if", "unless", "then", "first"),
        *("later", "tomorrow", "tonight", "wait", "until", "till", "i", "me", "my", "we", "us"),
    }
)


def _opening_scene33t(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12t): a statement opening the instruction about something the scene does not
    have ('Stock room's a mess', 'the dogs are going mad outside'), then a request: the
    statement is taken off when it names nothing of the scene (nor by a typo) and holds no word
    that would make it ask, point, choose, time or say who (``_OPENING_HELD32S``, pronouns);
    the request must read without it."""
    m = _rx(_OPENING33T).match(text)
    if m is None or not _names_nothing(m["said"], lexicon):
        return text
    words = re.findall(r"[a-z]+(?:'[a-z]+)?", m["said"].lower())
    held = _OPENING_HELD32S | {"he", "she", "they", "you", "not", "no", "never", "nothing"}
    held |= _ORDER_HELD36S | _ORDER_HELD36L
    if any(w in held or w.split("'")[0] in held or w.endswith("n't") for w in words):
        return text
    rest = m["lead"] + m["rest"]
    return rest[:1].upper() + rest[1:] if _reading(rest, lexicon) is not None else text


_STEPS33T: tuple[Callable[[str, Lexicon], str], ...] = (
    _each_header33t,
    _kind_choice33t,
    _each_any33t,
    _other_two33t,
    _leave_where33t,
    _load_up33t,
    _wont_you33t,
    _fronted_to33t,
    _exclaimed_fix33t,
    _unknown_fixed33t,
    _placed_for33t,
    _purpose_ing33t,
    _stays_on33t,
    _each_said33t,
    _both_named33t,
    _got_them33t,
    _need_over33t,
    _telegraphed33t,
    _said_again33t,
    _whose33t,
    _one_said33t,
    _opening_scene33t,
    _counted_close33t,
    _objects_first33t,
    _openers33t,
    _places_said33t,
    _everything_bar33t,
    _formal33t,
)


def _opening_state32s(text: str, lexicon: Lexicon) -> str:
    """Session 32 (12s): a statement about one person opening the instruction, before a request
    whose only person is a he / him / she / her (above), is 'P is waiting.' — who it is about
    kept, for the pronoun; what it says of them goes. Session 21's remarks drop such a statement
    only when every word of it is one the grammar does not know ('Bob's hungry.'): 'nothing',
    'since', 'from', 'there', a negation had kept it, and the pronoun had no one to mean. Only
    when the statement names nothing else in the scene and holds none of _OPENING_HELD32S (a
    want, a hand-over, a word pointing at a thing, a choice, a time, the speaker), the request
    names no person, and the person's title does not rule the pronoun out."""
    m = _OPENING_STATE32S.match(text)
    if m is None or not _only_person(m["who"], lexicon):
        return text
    pid = next(iter(_ids(m["who"], lexicon)))
    words = re.findall(r"[a-z]+(?:'[a-z]+)?", m["words"].lower())
    if any(w in _OPENING_HELD32S or w.split("'")[0] in _OPENING_HELD32S for w in words):
        return text
    if _ids(m["words"], lexicon) or _ids(m["rest"], lexicon, "human"):
        return text
    pronouns = {w.lower() for w in re.findall(r"\b(?:he|him|she|her)\b", m["rest"], _F)}
    if not pronouns or any(title_sex(pid, lexicon) not in (None, PRONOUN_SEX[p]) for p in pronouns):
        return text
    if len({PRONOUN_SEX[p] for p in pronouns}) > 1:
        return text  # 'he' and 'she': two people
    stop = ". " if m["stop"].strip() not in (",", "") else ", "  # 42s: " so" as ", so"
    return f"{m['lead']}{m['who']} is waiting{stop}{m['rest']}"


_STEPS31S: tuple[Callable[[str, Lexicon], str], ...] = (
    _will_do31s,
    _both_of31s,
    _where_it_is31s,
    _negated_reason31s,
    _said_otherwise31s,
)
_STEPS32S: tuple[Callable[[str, Lexicon], str], ...] = (_trailing_remark32s, _opening_state32s)


# Session 33 (12s): a greeting opening the instruction, with the rest of its sentence ("Morning,
# it's the dentist up from outpatients.", "Afternoon, I'm the carpenter from the unit next door,
# after a small favour.", "Hello, paramedic, just dropping off some paperwork for the manager.")
_GREETING33S = re.compile(
    r"^(?:(?:ah|oh|well|right)\s*,?\s+)?(?P<said>(?:hello|hi|hiya|hey|hullo|morning|afternoon|"
    r"evening|good (?:morning|afternoon|evening|day)|alright|all right)\b[^.!?]*[.!]+)\s+"
    r"(?P<rest>\S.*)$",
    _F,
)
# words that would make the greeting's sentence ask, point at a thing, or say when
_GREETING_HELD33S = frozenset(
    {
        *("give", "hand", "pass", "bring", "take", "put", "place", "send", "fetch", "get"),
        *("gets", "want", "wants", "wanted", "need", "needs", "needed", "like", "likes"),
        *("fancy", "fancies", "asked", "asking", "it", "them", "that", "those", "these", "this"),
        *("one", "ones", "both", "either", "any", "which", "whichever", "too", "also", "instead"),
        *("or", "if", "unless", "then", "first", "later", "tomorrow", "tonight", "wait"),
        *("until", "till", "not", "no", "don't", "never", "cancel", "please", "could", "can"),
        *("would", "will", "should", "must"),
    }
)


def _greeting_said33s(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12s): a sentence that opens on a greeting and says who the speaker is or
    why they came ("Hello, sorry, I'm the tailor, I've come to measure the manager for her
    suit. If you'd be so good, pass Priya the red pen.") asks for nothing: it goes, and the
    sentences after it are read. Only when it names no object or surface of the scene, holds
    none of _GREETING_HELD33S (a hand-over, a want, a word pointing at a thing, a choice, a
    time, a negation, a modal that could ask), names a person only in a clause of its own
    (three words or more the scene does not name, no 'after'), and nothing after it says he /
    she / him / her / they / them (who they are could hang on a name in it, or on someone it
    names whom the scene does not hold)."""
    m = _GREETING33S.match(text)
    if m is None:
        return text
    # "Morning, it's the dentist …": the speaker saying who it is, no thing pointed at
    said = re.sub(
        r"^([a-z ]+,\s*)it(?:'s| is) (?=(?:the|a|an|your|just) )", r"\1", m["said"], flags=_F
    )
    # "… I've got four minutes till my next run.": the speaker's own time
    said = re.sub(r"\b(?:till|until) (?:my|our) ", " ", said, flags=_F)
    words = re.findall(r"[a-z]+(?:'[a-z]+)?", said.lower())
    if any(w in _GREETING_HELD33S or w.split("'")[0] in _GREETING_HELD33S for w in words):
        return text
    if _ids(m["said"], lexicon, "object") or _ids(m["said"], lexicon, "surface"):
        return text
    if _ids(m["said"], lexicon, "human"):
        # a person named: only in a clause of the speaker's own ("I've come to measure the
        # manager for her suit"), not a want ('Alice is after a drink') or a terse part that may
        # allot ('for Alice', "Alice's turn", 'Alice next')
        scene = _scene_words29(lexicon)
        own = [w for w in words[1:] if len(w) > 3 and w.split("'")[0] not in scene]
        if "after" in words or len(own) < 3:
            return text
    if re.search(r"\b(?:he|him|his|she|her|hers|they|them|their)\b", m["rest"], _F):
        return text  # "Hello, I'm Carol's plumber. Hand her …": 'her' may hang on the greeting
    return m["rest"]


# Session 33 (12s): a request asked as a question whose subject is a list of objects ("Could the
# bowl and the spoon both go on the tray, please?"): the grammar reads the question with one
# object only, and the statement ('The bowl and the spoon could go …') with the list
_MODAL_FIRST33S = re.compile(
    r"^(?P<mod>could|can|would|will|might)\s+(?P<subj>(?:the )?[a-z][a-z ]*? and (?:the )?"
    r"[a-z][a-z ]*?)\s+(?P<rest>(?:both\s+)?(?:go|be put|be placed|be moved)\b.*)$",
    _F,
)


def _modal_first33s(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12s): the question above said as the statement, when its subject names
    objects of the scene only (each word of it)."""
    m = _MODAL_FIRST33S.match(text.strip())
    if m is None or not _things31(m["subj"], lexicon):
        return text
    subj = m["subj"][:1].upper() + m["subj"][1:]
    return f"{subj} {m['mod'].lower()} {m['rest']}"


# Session 33 (12s): a correction that names its person in a cleft ("Gloves to Mia, no, Tom's the
# one loading my trailer."): the person is what the correction says
_CLEFT_CORRECTED33S = re.compile(
    r"(?P<cue>,\s*(?:no|sorry|i mean|actually|wait|no wait)(?:,\s*|\s+))(?P<who>[A-Z][a-z]+(?: "
    r"[A-Z][a-z]+)?)(?:'s| is) the one(?: (?:who|that))? (?P<rest>[a-z][^,.;!?]*?)(?P<end>[.!]*)"
    r"\s*$"
)


def _cleft_corrected33s(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12s): the cleft above closing the instruction is its person alone, when that
    is one person of the scene and what the cleft says of them names nothing of the scene and
    holds none of _TRAILING_HELD32S ('Tom's the one who wants the tape' is left)."""
    m = _CLEFT_CORRECTED33S.search(text)
    if m is None or not _only_person(m["who"], lexicon) or _ids(m["rest"], lexicon):
        return text
    words = re.findall(r"[a-z]+(?:'[a-z]+)?|n't", m["rest"].lower())
    if any(w in _TRAILING_HELD32S or w.split("'")[0] in _TRAILING_HELD32S for w in words):
        return text
    return f"{text[: m.start()]}{m['cue']}{m['who']}{m['end'] or '.'}"


_STEPS33S: tuple[Callable[[str, Lexicon], str], ...] = (
    _greeting_said33s,
    _modal_first33s,
    _cleft_corrected33s,
)

# -- session 34 (12s): blind21/22's kinds -------------------------------------------------------

# A remark said without its 'is' ("Person B want the apple lah, she hungry already since
# morning."): a he / she / they right after a stop or comma, then at once a word of a person's
# state (session 29's list, `_STATE_CAUSE29S`), is said as '<pronoun> is / are <state>' (a copula
# left out, as Singapore and Malaysian English, and others, do), which the remark rules read.
_ZERO_COPULA34S = re.compile(
    r"(?P<lead>(?:^|[,.;!?])\s*)(?P<who>he|she|they)\s+(?=(?:really |so |very |also |still )?"
    r"(?:thirsty|hungry|parched|gasping|peckish|starving|famished|ravenous|cold|freezing|tired|"
    r"knackered|shattered|exhausted|sore|sticky|soaked|boiling|sweaty)\b)",
    _F,
)


def _zero_copula34s(text: str, lexicon: Lexicon) -> str:
    """', she hungry already' → ', she is hungry already' (above)."""
    return _ZERO_COPULA34S.sub(
        lambda m: f"{m['lead']}{m['who']} {'are' if m['who'].lower() == 'they' else 'is'} ", text
    )


# What a person was heard to ask for, said again after the request ("Give Alice the cup, no wait,
# the apple, she said apple, I'm sure of it."): a he / she / they after a comma, 'said', then the
# name of the one object the stretch before it names, is '<pronoun> asked for the <object>', a
# want the remark rules check against the request (it must give that object to a person the
# pronoun may be).
_SAID_OBJECT34S = re.compile(
    r"(?P<lead>,\s*)(?P<who>he|she|they) said (?:the )?(?P<what>[a-z]+(?: [a-z]+)?)"
    r"(?=\s*(?:[,.!;]|$))",
    _F,
)


def _said_object34s(text: str, lexicon: Lexicon) -> str:
    """', she said apple' → ', she asked for the apple' (above), when the object is the one the
    stretch just before it names ("…, the apple, she said apple": said again); 'she said the cup'
    after 'the apple' is left as said (refused)."""

    def said(m: re.Match[str]) -> str:
        before = text[: m.start()].rsplit(",", 1)[-1]
        what = _ids(m["what"], lexicon, "object")
        if not _only(m["what"], lexicon, "object") or what != _ids(before, lexicon, "object"):
            return m.group(0)
        return f"{m['lead']}{m['who']} asked for the {m['what']}"

    return _SAID_OBJECT34S.sub(said, text)


# 'straight' before where a thing goes ("Take the apple straight to Alice", "Apple first.
# Straight to Alice.", "… straight over to Bob", "straight onto the shelf"): how it goes (as a
# manner adverb in -ly is, session 19), not what; taken off where it names nothing of the scene.
_STRAIGHT34S = re.compile(
    r"\bstraight\s+(?=(?:(?:over|back|up|down|across) )?(?:to|onto|into|on|in|over)\b)", _F
)


def _straight34s(text: str, lexicon: Lexicon) -> str:
    """'… straight to Alice' → '… to Alice' (above)."""
    if not _names_nothing("straight", lexicon):
        return text
    return _STRAIGHT34S.sub("", text)


# A kind said before the object it is ("Person B wants a snack, the chips please.", "… a drink,
# the bottle"): 'a <word of food or drink>' that names nothing of the scene, then a comma and the
# object, is 'something' (the grammar reads "wants something to eat, the chips").
_KIND_BEFORE34S = re.compile(
    r"\b(?:a|an|some) (?P<kind>snack|drink|bite|nibble|treat|refreshment|bite to eat)\s*,\s*"
    r"(?=(?:the|that|this|those|these) )",
    _F,
)


def _kind_before34s(text: str, lexicon: Lexicon) -> str:
    """'wants a snack, the chips' → 'wants something, the chips' (above). The phrase after the
    comma must name an object of the scene (session 36, the lead: "Give Person B a snack, the
    heating's off" had become 'something' and read as any object)."""

    def kind(m: re.Match[str]) -> str:
        then = re.split(r"[,.;!?]", text[m.end() :], maxsplit=1)[0]
        if not _names_nothing(m["kind"], lexicon) or not _ids(then, lexicon, "object"):
            return m.group(0)
        return "something, "

    return _KIND_BEFORE34S.sub(kind, text)


# An apology opening the text, then its excuse ("Sorry, cold hands, give Person A the applw.",
# "sorry typing one handed, chips to person b"): the excuse, up to the next comma, of at most four
# words naming nothing of the scene, not opening on a verb of the grammar's, with no word that
# counts, negates, chooses or points (_KEEP_WORDS; 'one handed' is how the speaker types), is the
# speaker's own and goes with the apology; a request must follow it.
_SORRY_EXCUSE34S = re.compile(r"^(?P<sorry>(?:so )?sorry),?\s+(?P<why>[a-z' -]+?)\s*,\s*(?=\S)", _F)


def _sorry_excuse34s(text: str, lexicon: Lexicon) -> str:
    """'Sorry, cold hands, give …' → 'Sorry, give …' (above)."""
    m = _SORRY_EXCUSE34S.match(text)
    if m is None:
        return text
    why = m["why"]
    words = re.sub(r"\bone[- ]handed\b", "handed", why, flags=_F).split()
    if (
        len(why.split()) > 4
        or not _names_nothing(why, lexicon)
        or _KEEP_WORDS.search(" ".join(words))
        or words[0].lower() in VERBS  # "Sorry, hand it over, …": a request
        or _ORDER_WORDS.search(why)
    ):
        return text
    return f"{m['sorry']}, {text[m.end() :]}"


_STEPS34S: tuple[Callable[[str, Lexicon], str], ...] = (
    _sorry_excuse34s,
    _zero_copula34s,
    _said_object34s,
    _straight34s,
    _kind_before34s,
)

# -- session 35 (12s): blind21/22's kinds --------------------------------------------------------

# An object that has to be somewhere ("… and the medium box has to be on the pallet before he
# goes"): an obligation, as 'should be on' / 'has got to go on' (read already); said of a person
# ("Tom has to be on the pallet") it is no placement and is left.
_HAS_TO35S = re.compile(
    r"\b(?P<obj>(?:the |that |this )?[a-z]+(?: [a-z]+)?) (?:has|have) to (?P<v>be|go|sit)"
    r"(?P<back> back)? (?P<on>on|onto|in|into) ",
    _F,
)


def _has_to35s(text: str, lexicon: Lexicon) -> str:
    """'<object> has to be on S' → '<object> should be on S' (above)."""

    def should(m: re.Match[str]) -> str:
        if not _only_kind(m["obj"], lexicon, "object"):
            return m.group(0)
        return f"{m['obj']} should {m['v']}{m['back'] or ''} {m['on']} "

    return _HAS_TO35S.sub(should, text)


# a reason's subject and verb ("she's been shouting at me", "he keeps asking")
_REASON_HEAD35S = re.compile(
    r"^\s*(?:she|he|they|it)(?:'s|'re|'ve|'ll|'d| is| are| was| were| has| have| had| keeps?)\b",
    _F,
)


def _reason_head35s(head: str, out: list[str], lexicon: Lexicon) -> bool:
    """Session 35 (12s): in _speaker_remarks, the words before 'and I …' may be a reason said
    after the request ("Give Alicw the bottle, she's been shouting at me and I can't hear a
    word"): the speaker's part is taken off and the reason left for _reasons21 (which takes it
    off only when it names nothing and holds no word that could change the request), when the
    reason opens on a pronoun and a verb and the words before it name something."""
    return bool(_REASON_HEAD35S.match(head)) and bool(_names("".join(out), lexicon))


_REPHRASE42L = re.compile(r"(?:let me rephrase(?: that)?|i misspoke|i misspoke there)", _F)


def _speaker_remarks(text: str, lexicon: Lexicon) -> str:
    """The speaker's remarks (the rule above) and the session-15 clauses about the speaker, the
    hearer or the moment (_remark_clause), anywhere in the instruction, taken off when what is
    left names something; with a call of a few words opening the text ("Behind!"), an apology
    next to a remark, and the 'but' / 'so' / 'and' that joins a remark to the request."""
    if not _REMARK_OPEN.search(text):
        return text
    pieces = _REMARK_MARKS.split(text)
    out: list[str] = []
    dropped = False
    spoke = False  # the last piece read was a remark, in the same sentence
    after = False  # the last piece read was taken off
    opened = 0  # where the sentence being read starts in ``out``
    for n in range(0, len(pieces), 2):
        piece = pieces[n]
        mark = pieces[n + 1] if n + 1 < len(pieces) else ""
        if _REPHRASE42L.fullmatch(piece.strip()):
            # session 42 (lead): "Let me rephrase:" / "I misspoke:" announce a correction: kept
            # as its cue 'no' (taken off as a remark, "Take Mr Lee his jug? You're a star. Let
            # me rephrase: the medication." read as adding the medication: 12c's turns fuzz)
            piece = piece[: len(piece) - len(piece.lstrip())] + "no"
        # "… on the tray cheers, then i'll …" / "… the rota and I'll …": from a joining word
        # before the speaker to the mark
        cut = _rx(
            r"\s+(?=(?:and then|and|so|then|while|whilst|as|because|cos|since)\s+"
            r"(?:(?:after that|afterwards),?\s+)?(?:i|i'm|i've|i'll|i'd|my)\b)"
        ).search(piece)
        head, tail = (piece[: cut.start()], piece[cut.end() :]) if cut else ("", piece)
        remark = _speaker_stretch(tail, spoke, lexicon, right_after=after and not head)
        if remark and _speaker_stretch(head, False, lexicon):
            head = ""  # "my wife keeps tripping over it and I can't hear her shout": both
        clause = None if remark else _remark_clause(piece, lexicon)  # (asked once a piece)
        if not remark and (
            clause
            # "Behind!", "Mind your backs!": a call opening the text
            or (n == 0 and mark.strip() == "!" and _call(piece, lexicon))
            # "Sorry, force of habit.": the apology for a remark goes with it
            or (after and _rx(r"(?:oh |so )?sorry(?: sorry)?").fullmatch(piece.strip()))
        ):
            remark, head = True, ""
        if (
            remark
            and (not head or _names(head, lexicon) or _reason_head35s(head, out, lexicon))
            and (
                not _SPEAKER_CUE.search("".join(pieces[n + 1 :]))
                or not _names("".join(out) + head, lexicon)
                # session 15's clause holds every pointing and correcting word: it joins nothing
                or (not head and (_remark_clause(piece, lexicon) if clause is None else clause))
            )
        ):
            dropped, spoke, after = True, True, not head
            if head:
                out.append(head)
                out.append(mark)
            elif all(_opener(x, lexicon) for x in out[opened::2]):
                del out[opened:]  # "Oh, sorry, I've got clay up to my elbows." → ""
            elif out and mark.strip() in _STOPS and out[-1].strip() in _REMARK_JOINS:
                out[-1] = mark  # "…, I misheard her." → "…."
            if any(c in mark for c in ".!?"):
                opened = len(out)
            continue
        if after:
            piece = _rx(r"^(?:but|so|and)\b,?\s*").sub("", piece)  # "…, but could you …"
        spoke = spoke and not any(c in mark for c in ".!?")
        after = False
        out.append(piece)
        out.append(mark)
        if any(c in mark for c in ".!?"):
            opened = len(out)
    if not dropped:
        return text
    said = "".join(out).strip(" ,;:—–-")
    said = re.sub(r"^[,;:.!?\s]+", "", said)
    said = re.sub(r"\s*[,;:]\s*([.!?])", r"\1", said)
    return said if _names(said, lexicon) else text


# A person's state run on into the request without a mark ("bob's been on the bike all day give
# him the bottle thx"): the state, then a request opening on its verb and a pronoun.
_STATE_RUN_ON35S = re.compile(
    r"^(?P<who>[a-z]+(?: [a-z]+)?)(?P<state>(?:'s| is| was)(?: been)? [a-z' ]+?) "
    r"(?P<req>(?:give|hand|pass|bring|take|fetch) (?:him|her|them)\b[^,.;!?]*[.!]?)$",
    _F,
)


def _state_run_on35s(text: str, lexicon: Lexicon) -> str:
    """Session 35 (12s): a comma put between the state and the request above, when the state's
    subject is one person, its words name nothing else and hold no word that counts, negates,
    orders or asks (_SENTENCE_HELD, _TASK_WORDS); the remark is then read as any other."""
    m = _STATE_RUN_ON35S.match(text.strip())
    if m is None or not _only_person(m["who"], lexicon):
        return text
    # how long the state has lasted ('all day') counts nothing
    state = _rx(r"\ball (?:day|morning|afternoon|evening|night|week)\b").sub("", m["state"])
    if (
        not _names_nothing(state, lexicon)
        or _SENTENCE_HELD.search(state)
        or re.search(_TASK_WORDS, state, _F)
    ):
        return text
    return f"{m['who']}{m['state']}, {m['req']}"


# The object's use said to be over, closing the request ("…, Mrs Khan's finished with it.", "…
# now it's been used"): why it is moved, asking nothing of the person
_DONE_WITH35S = re.compile(
    r"(?:\s*,\s*(?:as |since |because )?(?P<who>[A-Za-z][\w ]*?)(?:'s| is| has| are|'re|'ve| have)"
    r" (?:finished|done)(?: with)? (?:it|them)"
    r"|,?\s+now(?: that)? (?:it|they)(?:'s| has| is|'re| are| have|'ve) been (?:used|finished|"
    r"emptied|read|done))(?=\s*[.!]?$)",
    _F,
)


def _done_with35s(text: str, lexicon: Lexicon) -> str:
    """Session 35 (12s): the closing remark above taken off, when the request before it names
    its object and its person is one person of the scene the request does not name, a he / she /
    they where the request names no one, or the speaker ("Give Mia the gloves, she's done with
    them" could take back Mia's task; "Gloves to Mia, no, Tom, Mia's done with them" is a reason
    for a correction, session 32's)."""
    m = _DONE_WITH35S.search(text)
    if m is None or m.start() == 0:
        return text
    before, who = text[: m.start()], m["who"]
    if who is not None and who.lower() not in ("i", "we"):
        if who.lower() in ("he", "she", "they"):
            if _ids(before, lexicon, "human"):
                return text
        elif not _only_person(who, lexicon) or _ids(who, lexicon) & _ids(before, lexicon):
            return text
    if not _ids(before, lexicon, "object"):
        return text
    return before + text[m.end() :]


# session 31's cleft with a he / she for its person ("Person A's gasping after the last race,
# the bottle is what she's needing."): the wanting also said as '-ing' ('is needing')
_WHAT_SHE_WANTS35S = re.compile(
    rf"(?:^|(?<=[,;.!?]\s))(?P<x>(?:the|that|this|those|these) [a-z][a-z ]*?) (?:is|are|'s|'re) "
    rf"(?:just |exactly )?what (?P<pron>she|he)\s?(?:really )?"
    rf"(?:{_WANTING31}|'s needing|is needing)(?=\s*(?:[,.;!?]|$))",
    _F,
)


def _what_she_wants35s(text: str, lexicon: Lexicon) -> str:
    """Session 35 (12s): 'X is what she wants / is needing' is 'P wants X' when P is the one
    person named before it, every he / she of the text may be P (a title, a word of kin or a
    first name of the other sex rules P out: _the_person, _named_other_sex34s), and X the scene's
    objects only."""
    m = _WHAT_SHE_WANTS35S.search(text)
    if m is None or not _things31(m["x"], lexicon):
        return text
    who = one_person(text[: m.start()], lexicon)
    if who is None or not _the_person(who, text, lexicon):
        return text
    return f"{text[: m.start()]}{who} wants {m['x']}{text[m.end() :]}"


# when a person talked about the object ("Alice was on about the crisps before the anthem,
# could you …"): when the want was said, not when to do the task (as session 34's 'since the
# lesson' after 'been on about it')
_WHEN_TALKED35S = re.compile(
    r"(?P<want>\b(?:was|were|'s been|has been|had been) (?:on|going on|banging on|asking) about "
    r"(?:(?:the|that|this|those|these) [a-z]+(?: [a-z]+)?|it|them)) "
    r"(?P<when>(?:before|during|after|at) (?:the|her|his|their|this|that) (?:[a-z]+ ){0,2}"
    r"[a-z]+)(?=\s*[,;])",
    _F,
)


def _when_talked35s(text: str, lexicon: Lexicon) -> str:
    """Session 35 (12s): the time above taken off when it names nothing of the scene and holds
    no word that counts, chooses or points back (_KEEP_WORDS), and a clause follows it."""

    def said(m: re.Match[str]) -> str:
        if not _names_nothing(m["when"], lexicon) or _KEEP_WORDS.search(m["when"]):
            return m[0]
        return m["want"]

    return _WHEN_TALKED35S.sub(said, text)


# the hearer passing by, said as an aside before the request ("Would you mind, while you're
# there, shoving the crisps up on the shelf?"): when, now, as session 26's closing one
_WHILE_THERE36S = re.compile(
    r"(?P<lead>^|,)\s*while (?:you're|you are) (?:there|over there|passing|up there)\s*,\s*", _F
)


# -- session 37 (engineer 12s): blind21 and blind22's kinds ---------------------------------------

# the person who gets it described as the only one of a role, closing the request ("Could Bob
# have the crisps, he's the only tenor we've got?"): a reason, as session 21's ('he's the best
# tenor we've got'), which holds back every 'only' (it could narrow what is given)
_ONLY_ROLE37S = re.compile(
    r"\s*,\s*(?:(?:and|cos|because|as|since)\s+)?(?:he|she|they)(?:'s|\u2019s|'re| is| are) "
    r"(?:the|our|my) only (?P<what>[a-z]+(?: [a-z]+)?)"
    r"(?: (?:we've got|we have|we've|we got|here|left|around|on shift|today|tonight))?"
    r"(?P<end>\s*[.!?]?)\s*$",
    _F,
)
# what would make 'the only …' pick or count rather than describe
_NOT_A_ROLE37S = frozenset(
    {"one", "ones", "thing", "things", "person", "people", "other", "choice", "option", "way"}
)


def _only_role37s(text: str, lexicon: Lexicon) -> str:
    """Session 37 (12s): the closing description above taken off when its words name nothing
    in the scene and are a role ('tenor', 'driver on shift'), not 'one' / 'thing' / 'person'
    (which could narrow what is given), the request before it names one person, and what is
    left reads."""
    m = _ONLY_ROLE37S.search(text)
    if m is None or set(m["what"].lower().split()) & _NOT_A_ROLE37S:
        return text
    if not _names_nothing(m["what"], lexicon):
        return text
    rest = text[: m.start()]
    if len(_ids(rest, lexicon, "human")) != 1 or not _ids(rest, lexicon, "object"):
        return text
    out = rest + m["end"].strip()
    return out if _reading(out, lexicon) is not None else text


# a need of a thing, not a person, reported from the person asked for ("Can Mr Novak have the
# salt, please, he says the soup needs it?"): why they want it
_SAYS_NEEDS37S = re.compile(
    r"\s*,\s*(?:(?:and|cos|because|as|since)\s+)?(?:he|she|they) (?:says|said|reckons|thinks) "
    r"(?:that )?(?P<thing>(?:the|his|her|their|my|our) [a-z]+(?: [a-z]+)?) "
    r"(?:needs|wants|could use|could do with|is missing|lacks) "
    r"(?:it|them|some|some more|a bit|a bit more|more)(?P<end>\s*[.!?]?)\s*$",
    _F,
)


def _says_needs37s(text: str, lexicon: Lexicon) -> str:
    """Session 37 (12s): the reported need above taken off when the thing needing it names
    nothing in the scene (the soup, not a person or an object of it), the request before it
    names one person and an object, and what is left reads (as session 31's ', the soup needs
    it' after a request)."""
    m = _SAYS_NEEDS37S.search(text)
    if m is None or not _names_nothing(m["thing"], lexicon):
        return text
    rest = text[: m.start()]
    if len(_ids(rest, lexicon, "human")) != 1 or not _ids(rest, lexicon, "object"):
        return text
    out = rest + m["end"].strip()
    return out if _reading(out, lexicon) is not None else text


# a size said with '-sized' ('the middle-sized box', 'the small-sized one'), or 'middle' / 'mid'
# for the medium one
_SIZED37S = re.compile(
    r"\b(?P<size>small|medium|large|big|little|middle|mid)(?:[- ]sized?|-size)?"
    r"(?P<noun> [a-z]+)\b",
    _F,
)


def _sized37s(text: str, lexicon: Lexicon) -> str:
    """Session 37 (12s): 'the middle-sized box' (blind21) is 'the medium box': a size word with
    '-sized' is that size, and 'middle' / 'mid' (with or without '-sized') is 'medium', when the
    scene has one object the size word and the noun after it name and the words as said name
    nothing ('in the middle of the table' is kept: 'medium of' names nothing)."""
    if not re.search(r"\b(?:middle|mid|sized?)\b|-size", text, _F):
        return text

    def sized(m: re.Match[str]) -> str:
        size = m["size"].lower()
        if size in ("middle", "mid"):
            size = "medium"
        elif m[0].lower() == f"{size}{m['noun'].lower()}":
            return m[0]  # said as it is already
        said = f"{size}{m['noun']}"
        if _only(f"the {m[0]}", lexicon, "object") or not _only(f"the {said}", lexicon, "object"):
            return m[0]
        return said

    return _SIZED37S.sub(sized, text)


# 'once' the things just placed are there ("… and the green cup on the tray and then once
# they're both there the sponge goes in the sink"): once that is done
_ONCE_THERE37S = re.compile(
    r"\bonce (?P<what>it's|it is|they're|they are)(?: (?P<both>both|all))? (?:there|in place|"
    r"on there|in there)\b(?!,)"
    r"(?= (?:the|put|place|give|hand|pass|bring|take|[a-z]+ (?:goes|go) ))",
    _F,
)


def _once_there37s(text: str, lexicon: Lexicon) -> str:
    """Session 37 (12s): 'once it's there' / 'once they're (both) there' before the next step,
    said after placing: 'once that's done' (which the grammar reads as the order), when the text
    before it names one surface (the 'there'), one object for 'it' or more for 'they', no
    person, and what is left reads."""
    m = _ONCE_THERE37S.search(text)
    if m is None:
        return text
    before = text[: m.start()]
    objects = _ids(before, lexicon, "object")
    many = m["what"].lower().startswith("they")
    if (
        len(_ids(before, lexicon, "surface")) != 1
        or _ids(before, lexicon, "human")
        or (len(objects) != 1 if not many else len(objects) < 2)
        or (m["both"] is not None and not many)
        or (m["both"] is not None and m["both"].lower() == "both" and len(objects) != 2)
    ):
        return text
    out = f"{before}once that's done{text[m.end() :]}"
    return out if _reading(out, lexicon) is not None else text


# what a person has been through, said in a want frame before 'is' ("What Bob really needs after
# three hours of the Messiah is the crisps"): why they need it, a span already past, not when
_ORDEAL37S = re.compile(
    r"\b(?P<frame>what [A-Za-z][\w ]*? (?:really |actually |most )?(?:needs|wants|could use|"
    r"could do with|would like)) after (?P<ordeal>(?:(?:a|an|one|two|three|four|five|six|seven|"
    r"eight|nine|ten|twelve|\d+|several|a few|many) (?:hours?|minutes?|days?|weeks?|months?|years?|"
    r"shifts?|laps?|miles?) of [a-z' -]+?|a (?:long|hard|busy|tough|rough) (?:day|shift|night|week|"
    r"morning|afternoon|evening|run|walk)(?: of [a-z' -]+?)?|all that)) (?=is )",
    _F,
)


def _ordeal37s(text: str, lexicon: Lexicon) -> str:
    """Session 37 (12s): the ordeal above taken off a want frame when it names nothing in the
    scene, so session 18's 'What P really needs is X' reads it; 'after the show' (which could be
    when) and 'after the crisps' (an order) are not this."""

    def past(m: re.Match[str]) -> str:
        # (the count of the span is no count of things: what it was of must hold none)
        of = m["ordeal"].split(" of ", 1)[1] if " of " in m["ordeal"] else ""
        if not _names_nothing(m["ordeal"], lexicon) or _KEEP_WORDS.search(of):
            return m[0]
        return f"{m['frame']} "

    return _ORDEAL37S.sub(past, text)


# a sentence of its own asking the hearer to see to what was just said ("… Sort them out for
# me, would you?"): 'for me' is the favour asked ('do it for me'), not the speaker getting them
_SORT_OUT37S = re.compile(
    r"(?:(?<=[.!?;]) |^)(?:(?:could|can|would|will) you |please )?sort (?:it|them|that|this|"
    r"those|these|them all|it all|that lot|everything) out(?: for (?:me|us))?"
    r"(?:,? (?:would you|will you|could you|can you|please|thanks|cheers|ta))?\s*[.!?]?\s*$",
    _F,
)


def _sort_out37s(text: str, lexicon: Lexicon) -> str:
    """Session 37 (12s): the closing sentence above taken off (session 26's `_phrasal26` had
    made 'sort them out for me' 'get them for me', the speaker's own request) when the text
    before it names a person and an object, asks nothing for the speaker ('me', 'I', 'my'), and
    what is left reads."""
    m = _SORT_OUT37S.search(text)
    if m is None or m.start() == 0:
        return text
    before = text[: m.start()].rstrip()
    if re.search(r"\b(?:me|my|mine|i|we|us|our)\b", before, _F):
        return text
    if not (_ids(before, lexicon, "human") and _ids(before, lexicon, "object")):
        return text
    return before if _reading(before, lexicon) is not None else text


# a task a person has, said as why they need the object ("Jess has forty shelf brackets to get
# up before close, so she needs the power drill."): their need
_TASK_HAD37S = re.compile(
    r"(?P<who>\b[A-Z][a-z]+(?: [A-Z][a-z]+)?) (?:has|has got|'s got|\u2019s got) "
    r"(?P<task>[a-z0-9' -]+? to [a-z]+(?: [a-z' -]+?)?)(?P<when> (?:before|by) [a-z' -]+?)?, "
    r"so (?P<pro>she|he)(?:'ll| will)? (?:needs?|wants?|could use|could do with) "
    r"(?P<x>[^,.;!?]+)",
    _F,
)


def _task_had37s(text: str, lexicon: Lexicon) -> str:
    """Session 37 (12s): the task above taken off, leaving 'P needs X', when P is one person
    the he / she may be (a title, kin word or first name of the other sex rules them out), the
    task and its deadline name nothing in the scene and hold no word that counts, chooses or
    points back but the task's own count, X names objects only, and what is left reads (a
    deadline is met by acting now)."""
    m = _TASK_HAD37S.search(text)
    if m is None or not _only_person(m["who"], lexicon) or not _objects_only(m["x"], lexicon):
        return text
    said = f"{m['task']}{m['when'] or ''}"
    if re.search(r"\b(?:tomorrow|tonight|later|next|after|when|once|until|till)\b", said, _F):
        return text  # a time the need may wait for
    if not _names_nothing(said, lexicon) or _KEEP_WORDS.search(
        re.sub(
            r"^(?:\d+|[a-z]+ty|[a-z]+teen|two|three|four|five|six|seven|eight|nine|ten) ", "", said
        )
    ):
        return text
    who = next(iter(_ids(m["who"], lexicon, "human")))
    sex = said_sex35s(who, lexicon)
    if sex is not None and PRONOUN_SEX.get(m["pro"].lower()) != sex:
        return text
    out = f"{text[: m.start()]}{m['who']} needs {m['x']}{text[m.end() :]}"
    return out if _reading(out, lexicon) is not None else text


# where a person wants the object to stay, said with a participle of lying ("The manager wants
# the stapler sitting on the desk"): on it
_SITTING37S = re.compile(
    r"\b(?P<want>wants|would like|'d like|likes|needs|prefers) (?P<x>the [a-z' -]+?) "
    r"(?:sitting|sat|standing|stood|lying|kept|resting) (?P<on>on|in|by|next to) "
    r"(?P<s>the [a-z' -]+?)(?=\s*(?:[,.;!?]|$))",
    _F,
)
# a place the object is not to go, naming nothing of the scene, after where it goes ("…, not
# hidden away in a drawer"): a contrast that changes nothing
_NOT_THERE37S = re.compile(
    r",\s*(?:and )?not (?:(?:hidden|tucked|shoved|stuck|put|left|lost|buried)(?: away)? )?"
    r"(?:in|on|under|inside|into|in with) (?:a|an|some|the) (?P<w>[a-z]+(?: [a-z]+)?)"
    r"(?P<end>\s*[.!]?)\s*$",
    _F,
)


def _sitting37s(text: str, lexicon: Lexicon) -> str:
    """Session 37 (12s): 'P wants X sitting on S' is 'P wants X on S' (a want of where it is to
    be, as 'wants X left on S' reads) when X is one object and S one surface of the scene; then a
    closing ', not (hidden away) in a drawer' (above) is taken off when it names nothing in the
    scene and the text before puts an object on a surface. What is left must read."""
    out = text
    m = _SITTING37S.search(out)
    if m is not None and _only(m["x"], lexicon, "object") and _surface_only(m["s"], lexicon):
        out = f"{out[: m.start()]}{m['want']} {m['x']} {m['on']} {m['s']}{out[m.end() :]}"
    n = _NOT_THERE37S.search(out)
    if n is not None and _names_nothing(n["w"], lexicon):
        before = out[: n.start()]
        if _ids(before, lexicon, "surface") and _ids(before, lexicon, "object"):
            out = before + n["end"].strip()
    if out == text:
        return text
    return out if _reading(out, lexicon) is not None else text


# whose the object is, then it handed to them by a pronoun ("See the blue mug? That's Bob's, give
# it to him.", "The blue mug is Bob's, give it to him."): handed to that owner
_OWNER_THEN37S = re.compile(
    r"(?P<x>\b(?:that|it|this|(?:the|that|this) [a-z' -]+?)) ?(?:'s|\u2019s| is) "
    r"(?P<who>[A-Z][a-z]+(?: [A-Z][a-z]*)?)(?:'s|\u2019s)\s*[,.;]\s*(?:so\s+)?"
    r"(?:(?P<verb>give|hand|take|pass|bring) it (?:back |over |right back )?to (?P<pro>him|her)\b"
    r"|(?P<over>take|bring|run|carry) it (?:over|across|round)(?= *(?:[,.;!?]|$)))",
    _F,
)


def _owner_then37s(text: str, lexicon: Lexicon) -> str:
    """Session 37 (12s): the owner said, then the object handed to a him / her (above): '<verb>
    it to <owner>' ('<verb> the X to <owner>' when the object was named there), when the owner
    is one person the pronoun may be (a title, kin word or first name of the other sex rules
    them out), a named object is one of the scene ('that' / 'it': the text before names one
    object, not a choice), and what is left reads ("See the blue mug? Give it to Bob." reads the
    pointing)."""
    m = _OWNER_THEN37S.search(text)
    if m is None or not _only_person(m["who"], lexicon):
        return text
    who = next(iter(_ids(m["who"], lexicon, "human")))
    sex = said_sex35s(who, lexicon)
    if m["pro"] is not None and sex is not None and PRONOUN_SEX.get(m["pro"].lower()) != sex:
        return text
    x = m["x"]
    named = " " in x.strip()
    thing = "the " + x.strip().split(" ", 1)[1] if named else "it"
    if named and not _only(thing, lexicon, "object"):
        return text
    if not named and len(_ids(text[: m.start()], lexicon, "object")) != 1:
        return text  # 'that' / 'it' points back at one object said before it, or is not this
    verb = m["verb"] or m["over"]
    out = f"{text[: m.start()]}{verb} {thing} to {m['who']}{text[m.end() :]}"
    return out if _reading(out, lexicon) is not None else text


# the speaker not knowing a person's name, closing the request ("…, I don't know the other one's
# name."): it asks nothing and names no one
_NAME_UNKNOWN37S = re.compile(
    r"\s*[,;]\s*(?:(?:and|but|as|because|cos|sorry)\s+)?i (?:don't|do not|dont|can't|cannot) "
    r"(?:know|remember|recall) (?:his|her|their|the other (?:one|person|guy|lady|man|woman)'s)"
    r" names?(?P<end>\s*[.!]?)\s*$",
    _F,
)


def _name_unknown37s(text: str, lexicon: Lexicon) -> str:
    """Session 37 (12s): the closing remark above taken off when the request before it names
    someone and what is left reads ('whoever isn't Person A' says who without the name)."""
    m = _NAME_UNKNOWN37S.search(text)
    if m is None:
        return text
    rest = text[: m.start()]
    if not _ids(rest, lexicon, "human") or not _ids(rest, lexicon, "object"):
        return text
    out = rest + m["end"].strip()
    return out if _reading(out, lexicon) is not None else text


# a small child said as 'the little one' / 'the wee one' wanting something ("The little one wants
# her teddy, …"): the one person of the scene called a child
_LITTLE_ONE37S = re.compile(
    r"\bthe (?:little|wee|youngest|smallest) one(?= (?:wants|needs|would like|'d like|is after|"
    r"'s after|could do with|could use)\b)",
    _F,
)
_CHILD_WORDS37S = frozenset({"toddler", "baby", "infant", "child", "kid", "little one", "tot"})


def _little_one37s(text: str, lexicon: Lexicon) -> str:
    """Session 37 (12s): 'the little one' above is the one person of the scene whose names say a
    small child (toddler, baby, …), when no object of the scene is named by a size ('the little
    one' could be the small box) and what is left reads."""
    m = _LITTLE_ONE37S.search(text)
    if m is None:
        return text
    if any(
        w in ("small", "little", "smallest", "mini", "tiny")
        for o in lexicon.scene.objects
        for n in (o.id.replace("_", " "), *o.aliases)
        for w in n.lower().split()
    ):
        return text
    kids = [h for h in lexicon.scene.humans if {a.lower() for a in h.aliases} & _CHILD_WORDS37S]
    if len(kids) != 1:
        return text
    name = next((a for a in (kids[0].name, *kids[0].aliases) if _only_person(a, lexicon)), None)
    if name is None:
        return text
    out = f"{text[: m.start()]}{name}{text[m.end() :]}"
    return out if _reading(out, lexicon) is not None else text


# the speaker not having heard the robot, opening the text ("Pardon? Speak up a touch, this
# hearing aid of mine keeps whistling. …"): talk about the talk, asking nothing of the scene
_PARDON37S = re.compile(
    r"^(?:(?:pardon|sorry|come again|what was that|eh|what's that|say again)\s*\?\s*)+"
    r"(?:(?:speak up|say (?:that|it) again|a bit louder|louder)(?: a (?:bit|touch|little))?"
    r"(?:,? please)?(?P<aside>,[^.!?]*)?[.!]\s*)?",
    _F,
)


def _pardon37s(text: str, lexicon: Lexicon) -> str:
    """Session 37 (12s): the opening above taken off when its words (an aside after 'speak up'
    too) name nothing in the scene, a request follows, and what is left reads."""
    m = _PARDON37S.match(text)
    if m is None or m.end() >= len(text) or not _names_nothing(m[0], lexicon):
        return text
    out = text[m.end() :].strip()
    out = out[:1].upper() + out[1:]
    return out if _reading(out, lexicon) is not None else text


# how many things a he / she ends up with, closing the request ("… and the apple goes to Person A
# as well so she's got two."): said of the one person the request gives that many
_GOT_COUNT37S = re.compile(
    r"(?:\s*,\s*|\s+)(?:so|and|which means|meaning)\s+(?P<pro>she|he)(?:'s| has| will have|'ll "
    r"have)(?: got)? (?P<n>two|three|four|both)(?: (?:of them|things|items|now))?(?P<end>\s*[.!]?)"
    r"\s*$",
    _F,
)
_COUNTS37S = {"two": 2, "both": 2, "three": 3, "four": 4}


def _got_count37s(text: str, lexicon: Lexicon) -> str:
    """Session 37 (12s): the closing count above taken off when the request before it reads
    and gives exactly one person that many objects, one the pronoun may be (a title, kin word or
    first name of the other sex rules them out): it points at them and adds nothing. No one, or
    several, with that many: left (refused)."""
    m = _GOT_COUNT37S.search(text)
    if m is None:
        return text
    rest = text[: m.start()] + m["end"].strip()
    node = _reading(rest, lexicon)
    if node is None:
        return text
    got: dict[str, set[str]] = {}
    for t in tasks(node):
        if t.kind == "deliver":
            got.setdefault(t.target, set()).add(t.obj)
    n = _COUNTS37S[m["n"].lower()]
    sex = PRONOUN_SEX.get(m["pro"].lower())
    fits = [p for p, objs in got.items() if len(objs) == n]
    if len(fits) != 1 or said_sex35s(fits[0], lexicon) not in (None, sex):
        return text
    return rest


# an occasion said as a hyphenated noun in a deadline or purpose ("… before the weigh-in", "for
# the warm-up"): its words as a plain noun phrase, as "before the race" reads
_HYPHEN_TIME37S = re.compile(
    r"\b(?P<lead>(?:before|by|for) (?:the|her|his|their|our|my) )(?P<a>[a-z]+)-(?P<b>[a-z]+)\b",
    _F,
)


def _hyphen_time37s(text: str, lexicon: Lexicon) -> str:
    """Session 37 (12s): the hyphen above taken out when the word names nothing in the scene
    and what is left reads ('the middle-sized box' is `_sized37s`'s)."""
    if "-" not in text:
        return text
    out = _HYPHEN_TIME37S.sub(
        lambda m: (
            f"{m['lead']}{m['a']} {m['b']}"
            if _names_nothing(f"{m['a']}-{m['b']}", lexicon)
            and _names_nothing(f"{m['a']} {m['b']}", lexicon)
            else m[0]
        ),
        text,
    )
    if out == text:
        return text
    return out if _reading(out, lexicon) is not None else text


# a person said to be (or have been) out on the water: afloat, a place, not the drink ('water'
# names the bottle in scenes with one): "…, she's been out on the water all day"
_ON_THE_WATER37S = re.compile(
    r"\b(?P<lead>(?:she|he|they|we|i)(?:'s|\u2019s|'ve| has| have| had|'d)? been out|(?:she|he|"
    r"they|we|i)(?:'s|\u2019s| is| was| were|'re| are|'m| am) (?:still )?out) on the "
    r"(?:water|sea|river)\b",
    _F,
)


def _on_the_water37s(text: str, lexicon: Lexicon) -> str:
    """Session 37 (12s): 'out on the water' above said as 'out afloat' (what the person has been
    doing), when what is left reads."""
    if "out on the" not in text.lower():
        return text
    out = _ON_THE_WATER37S.sub(lambda m: f"{m['lead']} afloat", text)
    if out == text:
        return text
    return out if _reading(out, lexicon) is not None else text


# a person said to have gone without a meal or sleep, closing the request ("…, and the visitor
# would like that banana, she's had no breakfast."): why, a state; session 21's reasons hold
# back every 'no' (it could say someone gets none)
_HAD_NO37S = re.compile(
    r"\s*,\s*(?:(?:and|as|because|cos|since|poor thing)\s+)?(?P<pro>she|he)(?:'s|\u2019s| has)"
    r" (?:had|eaten) (?:no|nothing for) (?:breakfast|lunch|dinner|tea|supper|brunch|food|sleep|"
    r"break|coffee)(?: (?:yet|today|all day|this morning|since [a-z]+))?(?P<end>\s*[.!?]?)\s*$",
    _F,
)


def _had_no37s(text: str, lexicon: Lexicon) -> str:
    """Session 37 (12s): the closing state above taken off when the request before it reads
    and every person it names that the he / she may be (a title, kin word or first name of the
    other sex rules them out) gets something: whoever it is, the reading is the same."""
    m = _HAD_NO37S.search(text)
    if m is None:
        return text
    rest = text[: m.start()] + m["end"].strip()
    node = _reading(rest, lexicon)
    if node is None:
        return text
    sex = PRONOUN_SEX.get(m["pro"].lower())
    named = {p for p in _ids(rest, lexicon, "human") if said_sex35s(p, lexicon) in (None, sex)}
    given = {t.target for t in tasks(node) if t.kind == "deliver"}
    if not named or not named <= given:
        return text
    return rest


# 'something to eat / drink' with one of them left out ("Give Person A something to eat, but not
# the apple, she's allergic."): the scene's snacks (drinks) but that one
_TO_EAT37S = re.compile(
    r"\bsomething (?P<what>to eat|to nibble|to snack on|to drink)\s*,?\s*(?:but |just |only )?not "
    r"(?P<x>the [a-z' -]+?)(?=\s*(?:[,.;!?]|$))",
    _F,
)


def _to_eat37s(text: str, lexicon: Lexicon) -> str:
    """Session 37 (12s): the phrase above is the one object of the kind left ('the chips'), or
    a choice of those left ('one of the cup or the bottle'), when the object left out is one of
    the scene's of that kind (KIND_CATEGORIES: snacks for eating, drinks for drinking), and what
    is left reads."""
    m = _TO_EAT37S.search(text)
    if m is None or not _only(m["x"], lexicon, "object"):
        return text
    kind = KIND_CATEGORIES["drinks" if m["what"].lower() == "to drink" else "snacks"]
    out_id = next(iter(_ids(m["x"], lexicon, "object")))
    of_kind = [o for o in lexicon.scene.objects if o.category in kind]
    if out_id not in {o.id for o in of_kind}:
        return text
    left = [o for o in of_kind if o.id != out_id]
    names = [f"the {o.aliases[0] if o.aliases else o.id.replace('_', ' ')}" for o in left]
    if not left or not all(_only(n, lexicon, "object") for n in names):
        return text
    said = names[0] if len(names) == 1 else "one of " + ", ".join(names[:-1]) + " or " + names[-1]
    out = f"{text[: m.start()]}{said}{text[m.end() :]}"
    return out if _reading(out, lexicon) is not None else text


# two people, then two objects 'for one' and 'for (the) other' ("Person A and Person B each one
# drink, bottle for one, cup for other, any way also can."): one each, either way round
_ONE_OTHER37S = re.compile(
    r"^(?P<p>[A-Za-z][\w ]*?) and (?P<q>[A-Za-z][\w ]*?)(?: (?:each|both))?(?: (?:get|have|want|"
    r"need|gets|has))?(?: one [a-z]+(?: each)?)?\s*[,:;]\s*(?P<x>(?:the )?[a-z' -]+?) for one\s*,?"
    r"\s*(?:and )?(?P<y>(?:the )?[a-z' -]+?) for (?:the )?other(?: one)?"
    r"(?:\s*,\s*(?:either way|any way|anyway|whichever way|either way round|any which way)"
    r"(?: (?:is fine|is ok|is okay|also can|can|works|will do|round))?)?\s*[.!]?\s*$",
    _F,
)


# the object fronted, then 'you <verb>' ("That bottle, you bring for her, please."): the order
# said with the object first, as 'Bring that bottle for her'
_FRONTED_YOU37S = re.compile(
    r"(?:^|(?<=[.!?] ))(?P<x>(?:that|this|the) [a-z' -]+?), you (?:can |could |please )?"
    r"(?P<verb>bring|give|take|hand|pass|carry|put) (?P<rest>(?:for|to|over to|on|in|onto|into)"
    r" [^,.;!?]+)",
    _F,
)
# a person named, then a he / she saying their state ("Person A, she is very thirsty from
# walking, …"): said of that person
_NAMED_STATE37S = re.compile(
    r"(?:^|(?<=[.!?] ))(?P<p>[A-Z][\w]*(?: [A-Z][\w]*)?), (?P<pro>she|he) (?P<be>is|was|'s)\b",
    _F,
)


def _fronted_you37s(text: str, lexicon: Lexicon) -> str:
    """Session 37 (12s): the fronted object above said as an order ('Bring that bottle for her')
    when it is one object of the scene, and a person said before a he / she of their state (above)
    as the state's subject when the pronoun may be them (a title, kin word or first name of the
    other sex rules them out); taken when what is left reads."""
    out = text
    m = _FRONTED_YOU37S.search(out)
    if m is not None and _only("the " + m["x"].split(" ", 1)[1], lexicon, "object"):
        verb = m["verb"][:1].upper() + m["verb"][1:]
        out = f"{out[: m.start()]}{verb} {m['x']} {m['rest']}{out[m.end() :]}"
    n = _NAMED_STATE37S.search(out)
    if n is not None and _only_person(n["p"], lexicon):
        who = next(iter(_ids(n["p"], lexicon, "human")))
        if said_sex35s(who, lexicon) in (None, PRONOUN_SEX.get(n["pro"].lower())):
            be = "is" if n["be"] == "'s" else n["be"]
            out = f"{out[: n.start()]}{n['p']} {be}{out[n.end() :]}"
    if out == text:
        return text
    return out if _reading(out, lexicon) is not None else text


# (first: the later rewrites look for the object's name as the scene says it)
_STEPS37S_FIRST: tuple[Callable[[str, Lexicon], str], ...] = (_sized37s,)


_STEPS35S: tuple[Callable[[str, Lexicon], str], ...] = (
    _worked_on35s,
    _when_talked35s,
    _has_to35s,
    _state_run_on35s,
    _done_with35s,
    _what_she_wants35s,
)
# -- session 33 (12r): blind31's choices, counts, negation, exclusions and corrections ----------


def _share_out33r(node: Node | None) -> bool:
    """Whether ``node`` is a share-out: an 'or' of 'and's of single tasks, each 'and' the same
    objects to the same people, another way round."""
    if not isinstance(node, Group) or node.op != "or" or len(node.children) < 2:
        return False
    ways = [c for c in node.children if isinstance(c, Group) and c.op == "and"]
    if len(ways) != len(node.children) or not all(
        isinstance(t, Task) for c in ways for t in c.children
    ):
        return False
    objs = {frozenset(t.obj for t in tasks(c)) for c in ways}
    people = {frozenset(t.target for t in tasks(c)) for c in ways}
    return len(objs) == 1 and len(people) == 1


def _objects_named33r(words: list[str], lexicon: Lexicon) -> bool:
    """Whether each of ``words`` is one whole name of one object, each another object."""
    if not all(_one_object32r(w, lexicon) for w in words):
        return False
    return len(set().union(*(_ids(w, lexicon) for w in words))) == len(words)


def _object_said33r(oid: str, lexicon: Lexicon) -> str | None:
    """A name of object ``oid`` that names it alone in the scene ('the bottle'), or None."""
    obj = next((o for o in lexicon.scene.objects if o.id == oid), None)
    if obj is None:
        return None
    for name in (*obj.aliases, obj.category):
        if _ids(f"the {name}", lexicon) == {oid}:
            return f"the {name}"
    return None


# a closing remark that leaves a choice to the robot: how it picks ("whichever's closer to hand",
# "whatever's nearest", "whichever's nearest your gripper", "depending on what's easiest to reach",
# "whichever you like"), someone not minding which ("the banjo player's not
# fussy", "he's not fussed which colour", "the supervisor isn't bothered which"), the speaker's
# use of whichever is picked ("I'll plate up on whichever you pick", "I just need one out for
# the lesson"), and, after a share-out,
# "either way round is fine", "you decide who gets which"
_FREE_CHOICE33R = re.compile(
    r",\s*(?:(?:whichever|whatever)(?: one)?(?:'s| is) (?:closer|nearer|nearest|closest|handier|"
    r"handiest)(?: to (?:hand|you)|(?: to)? (?:your|the) (?:gripper|arm|hand))?"
    r"|whichever(?: one)? you (?:like|pick|choose|prefer|fancy)"
    r"|(?:whatever|whichever)(?: one)? you (?:grab|reach|get to|can reach) first"
    r"|depending on (?:what|which|whichever)(?:'s| is) (?:easiest|nearest|closest|handiest|"
    r"quickest)(?: to (?:reach|get|grab))?"
    r"|(?P<who>(?:the [a-z]+(?: [a-z]+)?|he|she|they|i)(?:'s not|'re not|'m not| is not| isn't|"
    r" are not| aren't| am not) (?:really )?(?:fussy|fussed|bothered|particular)(?: (?:which|what)"
    r"(?: (?:colour|color|one|size|kind|of them))?)?)"
    r"|(?:i'll|i will) [a-z]+(?: [a-z]+)? (?:on|with|from|in|into) whichever(?: one)? you "
    r"(?:pick|choose|use)"
    r"|(?:i|we) (?:just |only )?need (?:the )?one(?: of them)?(?: out| there| down| up)?(?: for "
    r"(?:the |my |our )?[a-z]+)?"
    r"|(?P<share>(?:either|any) way(?: round)? (?:is|'s) (?:fine|ok|okay|good)|you (?:decide|pick|"
    r"choose) who gets (?:which|what)))"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _free_choice33r(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12r): a closing remark leaving a choice to the robot (above) says again what
    the choice before it says: taken off when what is left reads as one choice of objects (or,
    for 'either way round' and 'who gets which', as a share-out; someone not minding which, after
    a choice of people too). After one object, or a choice
    of another kind, it is left, and refused."""
    m = _FREE_CHOICE33R.search(text)
    if m is None:
        return text
    head = text[: m.start()]
    node = _reading(head, lexicon)
    if m.group("share"):
        chosen = _share_out33r(node)
    else:
        chosen = _one_choice28r(node, False) or (
            m["who"] is not None and _one_choice28r(node, True)
        )
    if not chosen:
        return text
    return f"{head}{m.group('end') or '.'}"


# "One each for Alice and Bob, the bottle and the crisps, …": the things said after the people
_ONE_EACH_LISTED33R = re.compile(
    r"^(?P<head>one (?:each|apiece) for (?P<p>[A-Za-z][\w ]*?) and (?P<q>[A-Za-z][\w ]*?)),\s*"
    r"(?P<x>(?:the )?[a-z]+(?: [a-z]+)? and (?:the )?[a-z]+(?: [a-z]+)?)(?P<end>\s*(?:[,;.!]|$))",
    _F,
)


def _one_each_listed33r(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12r): 'One each for P and Q, X and Y' is session 29's 'One each for P and Q
    out of X and Y', P and Q two people, X and Y two objects, each one named whole."""
    m = _ONE_EACH_LISTED33R.match(text)
    if m is None or not (_only_person(m["p"], lexicon) and _only_person(m["q"], lexicon)):
        return text
    if _ids(m["p"], lexicon) == _ids(m["q"], lexicon):
        return text
    if not _objects_named33r(re.split(r" and ", m["x"], maxsplit=1, flags=_F), lexicon):
        return text
    return f"{m['head']} out of {m['x']}{text[m.start('end') :]}"


# "Bob's off to the cricket, so he's taking both, the bottle and the crisps."
_SO_TAKING33R = re.compile(
    r"^(?P<lead>(?P<p>[A-Za-z][\w ]*?)(?:'s| is) [a-z][a-z' ]*?,\s*so )(?P<pro>he|she)(?:'s| is) "
    r"taking (?P<x>(?:both,?\s*)?[^,;:.!?]+?)(?P<end>\s*[.!]?)$",
    _F,
)


def _so_taking33r(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12r): "P's off to …, so he's taking X" is "…, so he's having X" (what P takes
    with him is his: session 32's "P's taking X home"): the remark before names P alone, the
    pronoun may be P, and X names the scene's objects and nothing else ('taking X to Q', 'taking
    X over', left, refused)."""
    m = _SO_TAKING33R.match(text)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    pid = next(iter(_ids(m["p"], lexicon)))
    if _ids(m["lead"], lexicon) != {pid} or not _fits(pid, m["pro"], lexicon):
        return text
    x = m["x"]
    if not _objects_only(x, lexicon) or re.search(r"\b(?:to|over|back|home|away|out)\b", x, _F):
        return text
    return f"{m['lead']}{m['pro']}'s having {x}{m['end'] or '.'}"


_NUMBERS33R = {"two": 2, "three": 3, "four": 4, "five": 5, "six": 6}

# "Put the two of them, bottle and crisps, up on the shelf": 'them' said before its list
_THEM_LISTED33R = re.compile(
    r"\bthe (?P<n>two|three|four|five|six) of them,\s*(?P<x>[a-z][a-z ]*?(?:,\s*[a-z][a-z ]*?)* "
    r"and [a-z][a-z ]*?),",
    _F,
)


def _them_listed33r(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12r): 'the two of them, X and Y,' with nothing named before it is the list:
    'them' stands for what follows, when the list names as many different objects as the count
    says, each whole (a count it does not meet, or a person in it, is left, refused)."""
    m = _THEM_LISTED33R.search(text)
    if m is None or _names(text[: m.start()], lexicon):
        return text
    parts = re.split(r",\s*(?:and\s+)?|\s+and\s+", m["x"], flags=_F)
    if not _objects_named33r(parts, lexicon) or len(parts) != _NUMBERS33R[m["n"].lower()]:
        return text
    return f"{text[: m.start()]}{m['x']}{text[m.end() :]}"


# "Every single item here goes to Person B, all four of them", "Every box in the place, all
# three, goes up onto the belt"
_EVERY_COUNTED33R = re.compile(
    r"\b(?P<every>every (?P<single>single )?(?P<kind>[a-z]+))(?P<here> here| in the place| in "
    r"the room| in sight)?(?P<mid>[^,;.!?]*?)(?P<count>,\s*all (?P<n>two|three|four|five|six)"
    r"(?: of them)?)(?:,(?=\s*[a-z]))?(?=\s*(?:[,.;!]|$|[a-z]))",
    _F,
)


def _every_counted33r(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12r): 'every (single) item (here) …, all four of them' is 'every item …' when
    the count is the number of the scene's objects (of the kind said: 'every box …, all three'
    with three boxes); 'single' and 'here' / 'in the place' go with it. A count the scene does not
    meet is left, refused."""
    m = _EVERY_COUNTED33R.search(text)
    if m is None:
        return text
    kind = m["kind"].lower()
    if kind in ("item", "thing", "object"):
        have = len(lexicon.scene.objects)
    elif _only_kind(kind, lexicon, "object"):
        have = len(_ids(kind, lexicon, "object"))
    else:
        return text
    if have != _NUMBERS33R[m["n"].lower()]:
        return text
    return f"{text[: m.start()]}every {m['kind']}{m['mid']}{text[m.end() :]}"


# "the drinking things, which is the bottle plus the cup": a description, then what it is
_WHICH_IS_LIST33R = re.compile(
    r"\bthe (?P<desc>[a-z]+ (?:things|items|bits|stuff)),\s*which (?:is|are|means) "
    r"(?P<x>(?:the )?[a-z]+(?: [a-z]+)?) (?:plus|and|with) (?P<y>(?:the )?[a-z]+(?: [a-z]+)?)"
    r"(?=\s*(?:[,;.!]|$))",
    _F,
)


def _which_is_list33r(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12r): 'the drinking things, which is the bottle plus the cup' is the list
    'the bottle and the cup': the description names nothing of the scene and the list two
    different objects, each whole."""
    m = _WHICH_IS_LIST33R.search(text)
    if m is None or _names(m["desc"].rsplit(" ", 1)[0], lexicon):
        return text
    x, y = m["x"], m["y"]
    if not _objects_named33r([x, y], lexicon):
        return text
    return f"{text[: m.start()]}{x} and {y}{text[m.end() :]}"


# "A thing for each of them, Person A on the chips and Person B on the bottle", "One thing apiece
# for them: Person A takes the cup, Person B takes the apple."
_THING_EACH33R = re.compile(
    r"^(?:(?:a|one) (?:thing|item) (?:for each of them|(?:apiece|each) for (?:them|the two of "
    r"them)|each|apiece)(?:,\s*mind)?|(?:everyone|everybody|each of them) gets? (?:one|a) (?:thing|"
    r"item)|give (?:the two people|both people|them both|both of them|each of them) (?:a single|"
    r"one|a|an) (?:item|thing) each)"
    r"\s*[,:]\s*(?P<list>[^;.!?]+?)(?P<end>\s*[.!]?)$",
    _F,
)
_ONE_SHARE33R = re.compile(
    r"^(?:(?P<p>[A-Za-z][\w ]*?)(?: (?:on|takes|gets|has|having|with|is having|is getting)|'s "
    r"(?:having|getting)) (?P<x>(?:the |a |an )?[a-z]+(?: [a-z]+)?)|(?P<x2>the [a-z]+(?: [a-z]+)?)"
    r" (?:for|to) (?P<p2>[A-Za-z][\w ]*?)|(?P<p3>[A-Za-z][\w ]*?) (?P<x3>the [a-z]+(?: [a-z]+)?))$",
    _F,
)


def _thing_each33r(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12r): 'A thing for each of them, P on the X and Q on the Y' (or 'P takes the
    X, …'; "Everyone gets one thing: the X for P, …"; 'Give the two people a single item each: P
    the X, …') is 'P gets the X and Q gets the Y': the header says each of the scene's people gets
    one thing, and the list gives every one of them ('them', no one named before) one
    different object, each whole; anything else (a person left out or twice, two things for one)
    is left, refused."""
    m = _THING_EACH33R.match(text)
    if m is None:
        return text
    shares = [_ONE_SHARE33R.match(s) for s in re.split(r",\s*(?:and\s+)?|\s+and\s+", m["list"])]
    if not all(shares):
        return text
    said = [
        (s["p"] or s["p2"] or s["p3"], s["x"] or s["x2"] or s["x3"])
        for s in shares
        if s is not None
    ]
    if not all(_only_person(p, lexicon) for p, _x in said):
        return text
    if {next(iter(_ids(p, lexicon))) for p, _x in said} != {h.id for h in lexicon.scene.humans}:
        return text
    if len(said) != len(lexicon.scene.humans):
        return text
    if not _objects_named33r([x for _p, x in said], lexicon):
        return text
    out = [f"{p} gets {x}" for p, x in said]
    joined = ", ".join(out[:-1]) + f" and {out[-1]}"
    return f"{joined}{m['end'] or '.'}"


# "Both cups need a rinse after the titration, so into the sink they go, the green and the white."
_INTO_THEY_GO33R = re.compile(
    r"^(?P<x>(?:both|the two|all (?:two|three|four)|the) [a-z]+s) (?:both |all )?(?:want|need|"
    r"could do with) (?:a )?[a-z]+(?: (?P<why>(?:after|before|from) [a-z ]+?))?\s*,\s*(?:so )?"
    r"(?P<prep>into|in|onto|on) (?P<s>the [a-z ]+?) (?:they go|with (?:them|the pair of them|both "
    r"of them|the pair|the two of them))(?:,\s*the (?P<a>[a-z]+) and the (?P<b>[a-z]+))?"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _into_they_go33r(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12r): 'Both cups need a rinse (after the titration), so into the sink they
    go(, the green and the white)' is 'Put both cups into the sink' (session 32's 'into S with
    them'): X the scene's objects only, what they need it after naming nothing of the scene, S one
    surface, and the adjectives after it (when said) naming X's objects, each once."""
    m = _INTO_THEY_GO33R.match(text)
    if m is None or not _objects_only(m["x"], lexicon):
        return text
    if not _whole_name(m["s"], lexicon, "surface"):
        return text
    if m["why"] and _names(m["why"], lexicon):
        return text
    x = m["x"]
    if m["a"]:
        kind = re.sub(r"^(?:both|the two|all \w+|the) ", "", x, flags=_F)[:-1]
        said = [_ids(f"the {adj} {kind}", lexicon, "object") for adj in (m["a"], m["b"])]
        if not all(len(s) == 1 for s in said) or said[0] | said[1] != _ids(x, lexicon):
            return text
        if said[0] == said[1]:
            return text
    return f"Put {x[:1].lower()}{x[1:]} {m['prep']} {m['s']}{m['end'] or '.'}"


# "Not the cup, not the apple, just the bottle to Person B."
_NOT_THESE33R = re.compile(
    r"^(?P<nots>(?:not (?:the |a |an )?[a-z]+(?: [a-z]+)?,\s*)+)(?P<just>(?:just|only) )?"
    r"(?P<rest>the .+)$",
    _F,
)
# "Not on the floor, into Person A's hand, the bottle."
_NOT_THERE33R = re.compile(
    r"^not (?:on|in|onto|into|under) (?:the )?(?P<place>[a-z]+(?: [a-z]+)?),\s*"
    r"(?P<where>(?:into|onto|to|in|on) [^,;.!?]+?),\s*(?P<x>the [a-z ]+?)(?P<end>\s*[.!]?)$",
    _F,
)


def _not_these33r(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12r): 'Not the X, not the Y, just the Z to P' opens with what is not asked
    for: taken off when each 'not' names one object of the scene that the rest does not name
    (the rest then reads alone); 'Not on the floor, into P's hand, the X' is 'The X into P's
    hand' when the place not meant is none the rest says."""
    m = _NOT_THESE33R.match(text)
    if m is not None:
        nots = [n for n in re.split(r",\s*", m["nots"]) if n.strip()]
        said = [re.sub(r"^not ", "", n, flags=_F) for n in nots]
        rest = m["rest"]
        if not all(_one_object32r(s, lexicon) for s in said) or not _ids(rest, lexicon, "object"):
            return text
        if set().union(*(_ids(s, lexicon) for s in said)) & _ids(rest, lexicon):
            return text
        return f"{rest[:1].upper()}{rest[1:]}"
    m = _NOT_THERE33R.match(text)
    if m is None or not _one_object32r(m["x"], lexicon):
        return text
    if _names(m["place"], lexicon) and _ids(m["place"], lexicon) & _ids(m["where"], lexicon):
        return text
    if not _ids(m["where"], lexicon) or _ids(m["where"], lexicon, "object"):
        return text
    x = m["x"]
    return f"{x[:1].upper()}{x[1:]} {m['where']}{m['end'] or '.'}"


# ", and definitely not for Person B, who's on a diet for the rugby", ", not to the teacher"
_NOT_FOR_OTHER33R = re.compile(
    r",\s*(?:and )?(?:definitely |certainly |absolutely |just )?not (?:for|to) "
    r"(?P<q>(?:the )?[A-Za-z][\w ]*?)(?:,\s*who(?:'s| is) (?P<who>[^,;.!?]+?))?(?P<end>\s*[.!]?)$",
    _F,
)


def _not_for_other33r(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12r): a closing ', (and) not for / to Q' after a request to another person
    says who does not get it (an afterthought after a pause; the tuning part's 'Give Bob the
    chips but not to Carol' stays refused): taken off when Q names people of the scene only,
    none of whom the request names (so 'to the student, not to Noah', which picks a student, is
    left), and a 'who …' about Q names nothing of the scene. What is left is read as said: 'The
    globe to the student' with two students is refused naming them."""
    m = _NOT_FOR_OTHER33R.search(text)
    if m is None:
        return text
    q = _ids(m["q"], lexicon, "human")
    if not q or _ids(m["q"], lexicon) != q or (m["who"] and _names(m["who"], lexicon)):
        return text
    head = text[: m.start()]
    said = _ids(head, lexicon, "human")
    if not said or said & q or not _ids(head, lexicon, "object"):
        return text
    return f"{head}{m['end'] or '.'}"


# "Nothing for Person B today, he's fasting; the bottle's for Person A."
_NOTHING_FOR33R = re.compile(
    r"^(?:nothing for|not to|not for) (?P<q>[A-Za-z][\w ]*?)(?: today| this time| now| for now)?"
    r"(?:,\s*(?P<pro>he|she|they)(?:'s| is|'re| are|'ll| will|'d| would) (?:only )?[a-z]+(?: "
    r"[a-z]+)?)?\s*[;.]\s*(?P<rest>.+)$",
    _F,
)


def _nothing_for33r(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12r): 'Nothing for Q (today)(, he's fasting); <request>' (or 'Not to Q, she'll
    only chew it; …') opens with who gets nothing: taken off when Q is one person of the scene
    the request does not name, the request names someone else, and the remark about Q names
    nothing and its pronoun may be Q."""
    m = _NOTHING_FOR33R.match(text)
    if m is None or not _only_person(m["q"], lexicon):
        return text
    rest = m["rest"]
    q = _ids(m["q"], lexicon)
    said = _ids(rest, lexicon, "human")
    if not said or said & q or not _ids(rest, lexicon, "object"):
        return text
    if _names(text[: m.start("rest")], lexicon) != _names(m["q"], lexicon):
        return text
    if m["pro"] and not _fits(next(iter(q)), m["pro"], lexicon):
        return text
    return f"{rest[:1].upper()}{rest[1:]}"


# "The bottle goes to Person A and to nobody else."
_NOBODY_ELSE33R = re.compile(
    r"(?:,\s*|\s+)(?:and |but )?(?:to |for )?(?:nobody|no one|no-one|noone) else(?P<end>\s*[.!]?)$",
    _F,
)


def _nobody_else33r(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12r): 'and to nobody else' closing a request to one person says what a
    request says: taken off (after a request to two people, or none, left, refused)."""
    m = _NOBODY_ELSE33R.search(text)
    if m is None:
        return text
    head = text[: m.start()]
    if len(_ids(head, lexicon, "human")) != 1 or not _ids(head, lexicon, "object"):
        return text
    return f"{head}{m['end'] or '.'}"


_ANYTHING_BUT33R = re.compile(
    r"\banything(?: at all)?,? (?:(?:but|except|apart from|other than|bar)|as long as it(?:'s not| "
    r"isn't| is not)) (?P<x>(?:the )?[a-z]+(?: [a-z]+)?)(?=\s*(?:[,;.!]|$|\s(?:for|to|goes|go|"
    r"onto|into|on|in)\b))",
    _F,
)


def _anything_but33r(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12r): 'anything but the chips', 'anything at all as long as it isn't the
    cup' is one of the scene's other objects (blind19's reading): the one object left, or 'any
    one of the A, the B or the C', each said by a name of its own (X one whole name of the
    scene's objects; where an object has no name of its own the text is left, refused)."""
    m = _ANYTHING_BUT33R.search(text)
    if m is None or not _whole_name(m["x"], lexicon, "object"):
        return text
    left = [o.id for o in lexicon.scene.objects if o.id not in _ids(m["x"], lexicon)]
    said = [_object_said33r(oid, lexicon) for oid in left]
    names = [n for n in said if n is not None]
    if not names or len(names) != len(said):
        return text
    if len(names) > 1:
        names = [f"any one of {', '.join(names[:-1])} or {names[-1]}"]
    return f"{text[: m.start()]}{names[0]}{text[m.end() :]}"


# "Onto the belt with any box apart from the big one, whichever you like."
_ONTO_WITH33R = re.compile(
    r"^(?P<prep>onto|into|on to|in to|up onto) (?P<s>the [a-z]+(?: [a-z]+)?) with "
    r"(?P<x>[^,;:.!?]+?)(?P<end>\s*(?:[,;.!]|$))",
    _F,
)


def _onto_with33r(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12r): 'Onto S with X' is 'Put X onto S' (the motion first, then what is
    moved): S one surface of the scene, X naming objects and no person or surface."""
    m = _ONTO_WITH33R.match(text)
    if m is None or not _whole_name(m["s"], lexicon, "surface"):
        return text
    x = m["x"]
    if not _ids(x, lexicon, "object") or _ids(x, lexicon, "human") or _ids(x, lexicon, "surface"):
        return text
    return f"Put {x} {m['prep'].lower()} {m['s']}{text[m.start('end') :]}"


# a correction's cue said at length: "oh hang about, I got that wrong", "hmm, no, my mistake",
# "oh, correction from the skipper", "no, wrong way round" (before the whole request again)
_CORRECTION_CUE33R = re.compile(
    r"[,.]\s*(?:(?:oh|ah|er|um),? )?(?:hang (?:about|on),? i (?:got|had) that wrong"
    r"|(?:hmm|hm|erm|um),? no,? my mistake"
    r"|(?:a )?correction from (?:the )?[a-z]+(?: [a-z]+)?"
    r"|no,? (?P<way>wrong way round|the wrong way round)"
    # session 34 (12s): 'sorry, not the chips, the cup' as 'no, not …'
    r"|(?:no|well|ah|er|um|sorry),? not (?P<x>(?:the )?[A-Za-z]+(?: [A-Za-z]+)?))"
    r"\s*,\s*(?P<fix>.+)$",
    _F,
)
# the person said again as an owner: "they're Carol's"
_THEYRE_OWNED33R = re.compile(
    r"^(?:(?:they're|they are|those are|these are) (?P<p>[A-Za-z][\w ]*?)'s|(?P<p2>[A-Za-z][\w "
    r"]*?)(?:'s| is) the one (?:who (?:asked|asked for (?:it|them)|wants (?:it|them)|needs (?:it|"
    r"them))|wanting (?P<w>it|them|(?:the )?[a-z]+)))(?P<end>\s*[.!]?)$",
    _F,
)


def _correction_cue33r(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12r): a correction's cue said at length (above) is 'no': "Crisps to Alice, oh
    hang about, I got that wrong, they're Carol's" is "Crisps to Alice, no, to Carol" (the
    owner said again a person of the scene other than the request's); "Knife to Lena, oh no, not
    the knife, the tongs" is "…, no, the tongs" (what 'not' names is the request's object, or
    its person: "Crisps to Bob, ah, not Bob, Alice"; 'well, not the cup, just the apple' too);
    'no, wrong way round' before the whole request again is 'no'. The request corrected must
    name one person; the correction is then read by the grammar's own rule."""
    m = _CORRECTION_CUE33R.search(text)
    if m is None:
        return text
    head, fix = text[: m.start()], m["fix"]
    people = _ids(head, lexicon, "human")
    if len(people) != 1 or not _ids(head, lexicon, "object"):
        return text
    if m["x"] is not None:
        # what 'not' takes back: one object or the person of the request, and the fix one of
        # its kind
        if _one_object32r(m["x"], lexicon):
            kind = "object"
        elif _ids(m["x"], lexicon) == people and _only_person(m["x"], lexicon):
            kind = "human"
        else:
            return text
        if not _ids(m["x"], lexicon) <= _ids(head, lexicon) or not _ids(fix, lexicon, kind):
            return text
    if m["way"] is not None and not (_ids(fix, lexicon, "human") and _ids(fix, lexicon, "object")):
        return text
    owned = _THEYRE_OWNED33R.match(fix)
    if owned is not None:
        p = owned["p"] or owned["p2"]
        if not _only_person(p, lexicon) or _ids(p, lexicon) == people:
            return text
        wanted = owned["w"] or "it"
        if wanted.lower() not in ("it", "them") and not (
            _ids(wanted, lexicon) and _ids(wanted, lexicon) == _ids(head, lexicon, "object")
        ):
            return text
        fix = f"to {p}{owned['end'] or '.'}"
    return f"{head}, no, {fix}"


# "One of these to Person A, the bottle or the chips, …": 'these' said before its choice
_ONE_OF_THESE33R = re.compile(
    r"^(?:just )?one of (?:these|those|them|the two) (?P<to>to|for) (?P<p>[A-Za-z][\w ]*?),\s*"
    r"(?P<x>(?:the )?[a-z]+(?: [a-z]+)?) or (?P<y>(?:the )?[a-z]+(?: [a-z]+)?)"
    r"(?P<end>\s*(?:[,;.!]|$))",
    _F,
)


def _one_of_these33r(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12r): 'One of these to P, X or Y' is 'Either X or Y to P': 'these' stands for
    the choice said after the person, two different objects of the scene, each whole; P one
    person."""
    m = _ONE_OF_THESE33R.match(text)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    x, y = m["x"], m["y"]
    if not _objects_named33r([x, y], lexicon):
        return text
    return f"Either {x} or {y} {m['to']} {m['p']}{text[m.start('end') :]}"


# "Of everything lying about here, Person A only wants the bottle."
_OF_EVERYTHING33R = re.compile(
    r"^(?:out )?of (?:everything|all the things|all the stuff|all of it|all that)(?P<mid>(?: "
    r"[a-z]+){0,4}),\s*(?P<rest>.+)$",
    _F,
)


def _of_everything33r(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12r): 'Of everything lying about here, P only wants X' opens with what X is
    picked out of, the scene's things: taken off when it names nothing of the scene and the rest
    names one person and an object (the rest is then read alone)."""
    m = _OF_EVERYTHING33R.match(text)
    if m is None or _names(m["mid"], lexicon):
        return text
    rest = m["rest"]
    if len(_ids(rest, lexicon, "human")) != 1 or not _ids(rest, lexicon, "object"):
        return text
    return f"{rest[:1].upper()}{rest[1:]}"


# "Two spanners, one to Kofi and one to Jess."
_TWO_ONE_EACH33R = re.compile(
    r"^(?:the )?two (?P<kind>[a-z]+)s,\s*one (?:to|for) (?P<p>[A-Za-z][\w ]*?),? and (?:one|the "
    r"other) (?:to|for) (?P<q>[A-Za-z][\w ]*?)(?P<end>\s*[.!]?)$",
    _F,
)


def _two_one_each33r(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12r): 'Two spanners, one to Kofi and one to Jess' is 'One spanner each for
    Kofi and Jess' (session 29's share-out): the scene has two of the kind, P and Q two people."""
    m = _TWO_ONE_EACH33R.match(text)
    if m is None or not (_only_person(m["p"], lexicon) and _only_person(m["q"], lexicon)):
        return text
    if _ids(m["p"], lexicon) == _ids(m["q"], lexicon) or not _only_kind(
        m["kind"], lexicon, "object"
    ):
        return text
    if len(_ids(m["kind"], lexicon, "object")) != 2:
        return text
    return f"One {m['kind']} each for {m['p']} and {m['q']}{m['end'] or '.'}"


# "One thing each: the chips to one of them, the bottle to the other, …"
_ONE_AND_OTHER33R = re.compile(
    r"^one (?:thing|item) each\s*[:,]\s*(?P<x>(?:the )?[a-z]+(?: [a-z]+)?) (?:to|for) one of them,"
    r"\s*(?:and )?(?P<y>(?:the )?[a-z]+(?: [a-z]+)?) (?:to|for) the other(?: one)?"
    r"(?P<end>\s*(?:[,;.!]|$))",
    _F,
)


def _one_and_other33r(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12r): 'One thing each: X to one of them, Y to the other' in a scene of two
    people, none named, is 'One each for P and Q out of X and Y' (either way round); X and Y two
    objects, each whole."""
    m = _ONE_AND_OTHER33R.match(text)
    humans = lexicon.scene.humans
    if m is None or len(humans) != 2 or _ids(text, lexicon, "human"):
        return text
    if not _objects_named33r([m["x"], m["y"]], lexicon):
        return text
    p, q = (h.name or h.id for h in humans)
    return f"One each for {p} and {q} out of {m['x']} and {m['y']}{text[m.start('end') :]}"


# "Whichever of the two people is closer can have the bottle."
_WHICHEVER_PERSON33R = re.compile(
    r"^whichever of (?:the two(?: people)?|them) is (?:closer|nearer|nearest|closest|free|handier)"
    r"(?: to you)? (?P<rest>(?:can have|gets|should get|can take) .+)$",
    _F,
)


def _whichever_person33r(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12r): 'Whichever of the two people is closer can have X' in a scene of two
    people is 'Either of the two people can have X' (a choice of people, as session 28's 'either
    of them'); with more people the text is left, refused."""
    m = _WHICHEVER_PERSON33R.match(text)
    if m is None or len(lexicon.scene.humans) != 2 or _ids(m["rest"], lexicon, "human"):
        return text
    return f"Either of the two people {m['rest']}"


# ", in whatever order suits you" after things that all go
_ANY_ORDER33R = re.compile(
    r",\s*(?:and )?in (?:whatever|any) order(?: (?:suits you|you like|you want|you fancy|is "
    r"easiest))?(?P<end>\s*[.!]?)$",
    _F,
)


def _any_order33r(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12r): ', in whatever order suits you' closing a request read as tasks in no
    order (an 'and') says what that reading is: taken off; after steps in order ('then'), or a
    choice, it is left, refused."""
    m = _ANY_ORDER33R.search(text)
    if m is None:
        return text
    head = text[: m.start()]
    node = _reading(head, lexicon)
    if not (isinstance(node, Group) and node.op == "and"):
        return text
    if not all(isinstance(c, Task) for c in node.children):
        return text
    return f"{head}{m['end'] or '.'}"


# "The pair of spanners to Jess, she'll need the two."
_NEEDS_BOTH33R = re.compile(
    r",\s*(?P<pro>she|he|they)(?:'ll| will|'s going to| is going to)? (?:need|want|use) (?:the two|"
    r"both|them both|both of them|the pair|the two of them)(?P<end>\s*[.!]?)$",
    _F,
)


def _needs_both33r(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12r): ", she'll need the two" closing a request that hands two objects to one
    person, who the pronoun may be, says why: taken off (a count other than the request's, or
    another person, is left, refused)."""
    m = _NEEDS_BOTH33R.search(text)
    if m is None:
        return text
    head = text[: m.start()]
    node = _reading(head, lexicon)
    if node is None:
        return text
    done = list(tasks(node))
    people = {t.target for t in done}
    if len(done) != 2 or len(people) != 1 or any(t.kind != "deliver" for t in done):
        return text
    if not _fits(next(iter(people)), m["pro"], lexicon):
        return text
    return f"{head}{m['end'] or '.'}"


# "Mr Novak wants a plate — the white one, mind, not the blue."
_NOT_THE_OTHER33R = re.compile(
    r"\bthe (?P<a>[a-z]+) (?P<kind>one|[a-z]+)(?P<mind>,\s*mind)?,\s*not the (?P<b>[a-z]+)"
    r"(?: one)?(?P<end>\s*[.!]?)$",
    _F,
)


def _not_the_other33r(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12r): '… the white one(, mind), not the blue' closing a text says which of two
    of a kind again: the contrast is taken off when 'the A K' and 'the B K' are each one object
    of the scene, another each (K said, or the kind of 'a K' before 'one'; 'a K — the A one'
    then says 'the A K' once)."""
    m = _NOT_THE_OTHER33R.search(text)
    if m is None:
        return text
    kind, start = m["kind"], m.start()
    if kind.lower() == "one":
        said = list(re.finditer(r"\b(?:a|an|either) (?P<k>[a-z]+)\b", text[:start], _F))
        if not said:
            return text
        kind = said[-1]["k"]
        if re.fullmatch(r"\s*[,—–-]\s*", text[said[-1].end() : start]):
            start = said[-1].start()  # 'a plate — the white one': the one said once
    this = _ids(f"the {m['a']} {kind}", lexicon, "object")
    other = _ids(f"the {m['b']} {kind}", lexicon, "object")
    if len(this) != 1 or len(other) != 1 or this == other:
        return text
    if not (this | other) <= _ids(f"the {kind}", lexicon, "object"):
        return text  # session 51 (12s): the other is a K too (as _negation22's, normalise2.py)
    return f"{text[:start]}the {m['a']} {kind}{m['end'] or '.'}"


# "…, no, I mean the bottle, it's the bottle she's after."
_ITS_THE_X33R = re.compile(
    r"\b(?:no|sorry|actually),\s*(?:i mean |i meant )?(?P<said>(?:the )?[a-z]+(?: [a-z]+)?),\s*"
    r"it's (?P<x>the [a-z]+(?: [a-z]+)?) (?:that |which )?(?:(?:she|he|they)(?:'s| is|'re| are) "
    r"after|(?:she|he|they) (?:wants?|needs?|asked for))(?P<end>\s*[.!]?)$",
    _F,
)


def _its_the_x33r(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12r): after a correction to an object ('no, I mean the bottle'), "it's the
    bottle she's after" says the correction again: taken off when it names the one object the
    correction names (another object is left, refused; _said_why's kinds for people and
    places)."""
    m = _ITS_THE_X33R.search(text)
    if m is None or not _one_object32r(m["said"], lexicon):
        return text
    if _ids(m["said"], lexicon) != _ids(m["x"], lexicon):
        return text
    return f"{text[: m.end('said')]}{m['end'] or '.'}"


# "…, and not the blue, he says that colour gives him a headache."
_EXCLUDED_REASON33R = re.compile(
    r"\bnot (?:the )?[a-z]+(?: one)?(?P<cut>,\s*(?P<pro>she|he|they) (?:says|said|reckons|thinks|"
    r"finds) (?:that (?:colour|color|one|size|kind)|it|that|those) [a-z' ]+?)(?P<end>\s*[.!]?)$",
    _F,
)


def _excluded_reason33r(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12r): a closing reason the person gives for what 'not' leaves out ("…, and
    not the blue, he says that colour gives him a headache") is taken off when it names nothing
    of the scene and the request (what is left) names one person, whom the pronoun may be."""
    m = _EXCLUDED_REASON33R.search(text)
    if m is None or _names(m["cut"].split(" ", 2)[-1], lexicon):
        return text
    head = text[: m.start("cut")]
    people = _ids(head, lexicon, "human")
    if len(people) != 1 or not _fits(next(iter(people)), m["pro"], lexicon):
        return text
    return f"{head}{m['end'] or '.'}"


# "Carol would like a mug. Red or blue, grab whichever one is nearer to you."
_CHOICE_FOLLOWS33R = re.compile(
    r"^(?P<p>[A-Za-z][\w ]*?) (?P<v>would like|wants|needs|is after|'s after) an? (?P<k>[a-z]+)\."
    r"\s*(?P<a>[a-z]+) or (?P<b>[a-z]+),\s*(?:just )?(?:grab|pick|take|choose|get|bring) "
    r"whichever(?: one)?(?:'s| is) (?:nearer|closer|nearest|closest|handier)(?: to you)?"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _choice_follows33r(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12r): 'P would like a K. A or B, grab whichever one is nearer' is 'P would
    like the A K or the B K, whichever': the second sentence says which Ks the first leaves
    open, each 'the A K' one object of the scene, another each."""
    m = _CHOICE_FOLLOWS33R.match(text)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    a, b = f"the {m['a']} {m['k']}", f"the {m['b']} {m['k']}"
    if not _objects_named33r([a, b], lexicon):
        return text
    return f"{m['p']} {m['v']} {a} or {b}, whichever{m['end'] or '.'}"


# "The blanket on the trolley stays there; Mrs Khan gets the other one." / "Mrs Khan wants a
# blanket, but leave the one on the cart where it is and give her the other."
_STAYS_OTHER33R = re.compile(
    r"^(?:the (?P<k>[a-z]+) (?:on|in) the (?P<s>[a-z]+(?: [a-z]+)?) stays (?:there|put|where it "
    r"is)\s*[;,.]\s*(?P<p>[A-Za-z][\w ]*?) gets the other(?: one)?|(?P<p2>[A-Za-z][\w ]*?) "
    r"(?:wants|needs|would like) an? (?P<k2>[a-z]+),\s*but leave the one (?:on|in) the "
    r"(?P<s2>[a-z]+(?: [a-z]+)?) (?:where it is|there|alone) and give (?:her|him|them) the "
    r"other(?: one)?)(?P<end>\s*[.!]?)$",
    _F,
)


def _stays_other33r(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12r): 'The K on the S stays there; P gets the other one' (or 'P wants a K,
    but leave the one on the S where it is and give her the other') is 'P gets the K that isn't
    on the S', when the scene has two Ks, one of them starting on S (one surface)."""
    m = _STAYS_OTHER33R.match(text)
    if m is None:
        return text
    k, s, p = m["k"] or m["k2"], m["s"] or m["s2"], m["p"] or m["p2"]
    if not _only_person(p, lexicon) or not _whole_name(s, lexicon, "surface"):
        return text
    kinds = _ids(k, lexicon, "object")
    if len(kinds) != 2 or not _only_kind(k, lexicon, "object"):
        return text
    if len(starting_on(kinds, next(iter(_ids(s, lexicon))), lexicon)) != 1:
        return text
    return f"{p} gets the {k} that isn't on the {s}{m['end'] or '.'}"


# "Kofi's after whichever spanner isn't already on the workbench."
_WHICHEVER_ISNT33R = re.compile(
    r"\bwhichever (?P<k>[a-z]+) (?:isn't|is not) (?:already |still )?(?P<what>(?:on|in) the "
    r"[a-z]+(?: [a-z]+)?|the [a-z]+ one)(?=\s*(?:[,;.!]|$))",
    _F,
)


def _whichever_isnt33r(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12r): 'whichever K isn't (already) on the S' / 'isn't the A one' is 'the K
    that isn't …' (the grammar's description), when the scene has two Ks (so one is left)."""

    def said(m: re.Match[str]) -> str:
        if len(_ids(m["k"], lexicon, "object")) != 2 or not _only_kind(m["k"], lexicon, "object"):
            return m[0]
        return f"the {m['k']} that isn't {m['what']}"

    return _sub(_WHICHEVER_ISNT33R.pattern, said, text)


# "Alice needs a mug, but the red one's got a crack, so not that one."
_BUT_FLAWED33R = re.compile(
    r",\s*but the (?P<a>[a-z]+) one(?:'s| is| has)(?: got)? (?:a crack|cracked|a chip|chipped|"
    r"broken|dirty|filthy|leaking|stained)\s*,\s*so not that one(?P<end>\s*[.!]?)$",
    _F,
)


def _but_flawed33r(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12r): "…, but the red one's got a crack, so not that one" after 'a K' is ',
    but not the red one' (the exclusion, its reason taken off), when 'the red K' is one object
    of the scene."""
    m = _BUT_FLAWED33R.search(text)
    if m is None:
        return text
    said = re.findall(r"\ban? ([a-z]+)\b", text[: m.start()], _F)
    if not said or len(_ids(f"the {m['a']} {said[-1]}", lexicon, "object")) != 1:
        return text
    return f"{text[: m.start()]}, but not the {m['a']} one{m['end'] or '.'}"


# "Zoe can have the red book, not the one on the bookshelf."
_NOT_THE_ONE_ON33R = re.compile(
    r"\bthe (?P<a>[a-z]+) (?P<k>[a-z]+),\s*not the one (?:up |down )?(?:on|in) the "
    r"(?P<s>[a-z]+(?: [a-z]+)?)(?P<end>\s*[.!]?)$",
    _F,
)


def _not_the_one_on33r(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12r): 'the red book, not the one on the bookshelf' is 'the red book' when
    the red book is one object that does not start on S and another K does."""
    m = _NOT_THE_ONE_ON33R.search(text)
    if m is None or not _whole_name(m["s"], lexicon, "surface"):
        return text
    this = _ids(f"the {m['a']} {m['k']}", lexicon, "object")
    if len(this) != 1:
        return text
    on = set(
        starting_on(_ids(m["k"], lexicon, "object"), next(iter(_ids(m["s"], lexicon))), lexicon)
    )
    if not on or on & this:
        return text
    return f"{text[: m.start()]}the {m['a']} {m['k']}{m['end'] or '.'}"


# "Person A and Person B both want a drink, so the bottle to one and the cup to the other, …"
_TO_ONE_OTHER33R = re.compile(
    r"^(?P<p>[A-Za-z][\w ]*?) and (?P<q>[A-Za-z][\w ]*?) both (?:want|need|would like) (?:an? "
    r"[a-z]+|something)\s*,\s*so (?P<x>(?:the )?[a-z]+(?: [a-z]+)?) (?:to|for) one(?: of them)? "
    r"and (?P<y>(?:the )?[a-z]+(?: [a-z]+)?) (?:to|for) the other(?: one)?(?:,\s*(?:whichever|"
    r"either|any) way(?: round)?)?(?P<end>\s*[.!]?)$",
    _F,
)


def _to_one_other33r(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12r): 'P and Q both want a drink, so X to one and Y to the other(, whichever
    way round)' is 'One each for P and Q out of X and Y' (P and Q two people, X and Y two
    objects, each whole)."""
    m = _TO_ONE_OTHER33R.match(text)
    if m is None or not (_only_person(m["p"], lexicon) and _only_person(m["q"], lexicon)):
        return text
    if _ids(m["p"], lexicon) == _ids(m["q"], lexicon):
        return text
    if not _objects_named33r([m["x"], m["y"]], lexicon):
        return text
    return f"One each for {m['p']} and {m['q']} out of {m['x']} and {m['y']}{m['end'] or '.'}"


# "Anything at all for Person A, just the one item, whatever you grab first."
_ANYTHING_AT_ALL33R = re.compile(
    r"^anything(?: at all)? for (?P<p>[A-Za-z][\w ]*?),\s*(?:just )?(?:the )?one(?: item| thing)?"
    r"(?=\s*(?:[,.!]|$))",
    _F,
)


def _anything_at_all33r(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12r): 'Anything at all for P, just the one item' is 'Any one of <every object
    of the scene> for P', each object said by a name of its own (else left, refused)."""
    m = _ANYTHING_AT_ALL33R.match(text)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    said = [_object_said33r(o.id, lexicon) for o in lexicon.scene.objects]
    names = [n for n in said if n is not None]
    if len(names) < 2 or len(names) != len(said):
        return text
    listed = f"{', '.join(names[:-1])} or {names[-1]}"
    return f"Any one of {listed} for {m['p']}{text[m.end() :]}"


# "the plate that's sitting out, not the one up in the plate rack"
_SITTING_OUT33R = re.compile(
    r"\bthe (?P<k>[a-z]+) (?:that's|that is|which is) (?:sitting|lying|left) (?:out|about|around)"
    r",\s*not the one (?:up |down )?(?:on|in) the (?P<s>[a-z]+(?: [a-z]+)?)(?P<end>,|\s*[.!]?$)",
    _F,
)


def _sitting_out33r(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12r): 'the plate that's sitting out, not the one up in the plate rack' is 'the
    plate that isn't on the rack' when the scene has two of the kind and one starts on S."""

    def said(m: re.Match[str]) -> str:
        kinds = _ids(m["k"], lexicon, "object")
        if len(kinds) != 2 or not _only_kind(m["k"], lexicon, "object"):
            return m[0]
        if not _whole_name(m["s"], lexicon, "surface"):
            return m[0]
        if len(starting_on(kinds, next(iter(_ids(m["s"], lexicon))), lexicon)) != 1:
            return m[0]
        return f"the {m['k']} that isn't on the {m['s']}{'' if m['end'] == ',' else m['end']}"

    return _sub(_SITTING_OUT33R.pattern, said, text)


# "Black pen to Priya, oh, she marks in red, so the red one instead."
_SO_INSTEAD33R = re.compile(
    r"^(?P<head>[^,;.!?]+?),\s*(?:oh|ah|hmm),\s*(?P<pro>she|he|they) (?P<why>[a-z' ]+?),\s*so "
    r"(?P<x>the [a-z]+ one|the [a-z]+ [a-z]+) instead(?P<end>\s*[.!]?)$",
    _F,
)


def _so_instead33r(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12r): "X to P, oh, she marks in red, so the red one instead" is "X to P, no,
    the red one": a remark about the request's one person (the pronoun may be P, the remark
    names nothing of the scene), then another object of X's kind."""
    m = _SO_INSTEAD33R.match(text)
    if m is None or _names(m["why"], lexicon):
        return text
    head = m["head"]
    people, objs = _ids(head, lexicon, "human"), _ids(head, lexicon, "object")
    if len(people) != 1 or len(objs) != 1 or not _fits(next(iter(people)), m["pro"], lexicon):
        return text
    return f"{head}, no, {m['x']}{m['end'] or '.'}"


# "The apple for Person B, I mean the bottle, leave the apple."
_LEAVE_CORRECTED33R = re.compile(
    r"\b(?:i mean|i meant|no|sorry),?\s+(?P<y>the [a-z]+(?: [a-z]+)?),\s*(?:and )?leave (?P<x>the "
    r"[a-z]+(?: [a-z]+)?)(?: where it is| there| alone| be)?(?P<end>\s*[.!]?)$",
    _F,
)


def _leave_corrected33r(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12r): after a correction to another object ('I mean the bottle'), 'leave the
    apple' says the correction again: taken off when the apple is one object the text names
    before the correction and the correction another."""
    m = _LEAVE_CORRECTED33R.search(text)
    if m is None or not _objects_named33r([m["x"], m["y"]], lexicon):
        return text
    if not _ids(m["x"], lexicon) <= _ids(text[: m.start()], lexicon):
        return text
    return f"{text[: m.end('y')]}{m['end'] or '.'}"


# "Bib to Ava, oh no, she's too big for bibs, to Lily."
_CUE_REMARK33R = re.compile(
    r"^(?P<head>[^,;.!?]+?),\s*(?:oh,? )?no,\s*(?P<pro>she|he|they)(?:'s| is|'re| are) "
    r"(?P<why>[a-z' ]+?),\s*(?P<fix>to [A-Za-z][\w ]*?)(?P<end>\s*[.!]?)$",
    _F,
)


def _cue_remark33r(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12r): "Bib to Ava, oh no, she's too big for bibs, to Lily" is "Bib to Ava, no,
    to Lily": a remark about the request's one person (the pronoun may be them; it names
    nothing of the scene but the request's object) before the person the correction gives it
    to, another person of the scene."""
    m = _CUE_REMARK33R.match(text)
    if m is None:
        return text
    head = m["head"]
    people = _ids(head, lexicon, "human")
    if len(people) != 1 or not _fits(next(iter(people)), m["pro"], lexicon):
        return text
    if not _ids(m["why"], lexicon) <= _ids(head, lexicon, "object"):
        return text
    q = m["fix"][3:]
    if not _only_person(q, lexicon) or _ids(q, lexicon) == people:
        return text
    return f"{head}, no, {m['fix']}{m['end'] or '.'}"


# "The apple can go to either person, …"
_EITHER_PERSON33R = re.compile(r"\b(?P<prep>to|for) either (?:person|one)\b(?! of)", _F)


def _either_person33r(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12r): 'to either person' in a scene of two people, none named elsewhere, is
    'to either of the two people' ('person' alone names each of them)."""
    m = _EITHER_PERSON33R.search(text)
    if m is None or len(lexicon.scene.humans) != 2:
        return text
    if _ids(text[: m.start()] + text[m.end() :], lexicon, "human"):
        return text
    return f"{text[: m.start()]}{m['prep']} either of the two people{text[m.end() :]}"


# "Teddy to Ava, oops, I mean to Lily, Ava's too big for teddies now."
_CORRECTED_AWAY33R = re.compile(
    r"^(?P<head>.+?\b(?:no|sorry|oops|i mean|i meant),?\s+(?:i mean\s+|i meant\s+)?(?:to )?"
    r"(?P<q>[A-Za-z][\w ]*?)),\s*(?P<p>[A-Za-z][\w ]*?)(?:'s| is) (?P<why>(?:too|not|no longer|"
    r"off|done with|finished with)\b[a-z' ]*?)(?P<end>\s*[.!]?)$",
    _F,
)


def _corrected_away33r(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12r): after a correction to another person ('I mean to Lily'), "Ava's too big
    for teddies now" says why of the person corrected away: taken off when P is one person the
    text names before the correction, the correction names another, and the remark names nothing
    of the scene but the request's objects."""
    m = _CORRECTED_AWAY33R.match(text)
    if m is None or not (_only_person(m["p"], lexicon) and _only_person(m["q"], lexicon)):
        return text
    p, q = _ids(m["p"], lexicon), _ids(m["q"], lexicon)
    cue = m.start("q")
    if p == q or not p <= _ids(text[:cue], lexicon, "human"):
        return text
    if not _ids(m["why"], lexicon) <= _ids(text[:cue], lexicon, "object"):
        return text
    return f"{m['head']}{m['end'] or '.'}"


_STEPS33R: tuple[Callable[[str, Lexicon], str], ...] = (
    _corrected_away33r,
    _to_one_other33r,
    _anything_at_all33r,
    _sitting_out33r,
    _so_instead33r,
    _leave_corrected33r,
    _cue_remark33r,
    _either_person33r,
    _choice_follows33r,
    _stays_other33r,
    _whichever_isnt33r,
    _but_flawed33r,
    _not_the_one_on33r,
    _its_the_x33r,
    _excluded_reason33r,
    _two_one_each33r,
    _one_and_other33r,
    _whichever_person33r,
    _any_order33r,
    _needs_both33r,
    _not_the_other33r,
    _one_of_these33r,
    _of_everything33r,
    _one_each_listed33r,
    _free_choice33r,
    _so_taking33r,
    _them_listed33r,
    _every_counted33r,
    _which_is_list33r,
    _thing_each33r,
    _into_they_go33r,
    _not_these33r,
    _not_for_other33r,
    _nothing_for33r,
    _nobody_else33r,
    _anything_but33r,
    _onto_with33r,
    _correction_cue33r,
)


# -- session 34 (12r): blind32's choices, counts, negation, exclusions and corrections -----------

_CUE34R = r"(?:no|sorry|actually|i mean|i meant|or rather|correction)"
_PERSON34R = r"person [a-z]|(?:mr|mrs|ms|miss|dr) [a-z]+|[a-z]+"
_THING34R = r"(?:the )?[a-z]+(?: [a-z]+)?"


def _persons34r(lexicon: Lexicon, *words: str) -> bool:
    """Whether each of ``words`` names one person, each another."""
    ids = [_ids(w, lexicon, "human") for w in words]
    return all(_only_person(w, lexicon) for w in words) and len(set().union(*ids)) == len(words)


def _one_other37s(text: str, lexicon: Lexicon) -> str:
    """Session 37 (12s): the shape above is 'Either P gets X and Q Y, or P gets Y and Q X' (the
    grammar's choice of the two pairings), when P and Q are two people, X and Y two objects of
    the scene (said by a name of one object each), and what is left reads."""
    m = _ONE_OTHER37S.match(text.strip())
    if m is None:
        return text
    p, q = m["p"].strip(), m["q"].strip()
    x, y = (w.strip() for w in (m["x"], m["y"]))
    x, y = (w if w.lower().startswith("the ") else f"the {w}" for w in (x, y))
    if not _persons34r(lexicon, p, q):
        return text
    if not (_only(x, lexicon, "object") and _only(y, lexicon, "object")):
        return text
    if _ids(x, lexicon) == _ids(y, lexicon):
        return text
    out = f"Either {p} gets {x} and {q} {y}, or {p} gets {y} and {q} {x}."
    return out if _reading(out, lexicon) is not None else text


_STEPS37S: tuple[Callable[[str, Lexicon], str], ...] = (
    _fronted_you37s,
    _one_other37s,
    _to_eat37s,
    _had_no37s,
    _on_the_water37s,
    _hyphen_time37s,
    _got_count37s,
    _pardon37s,
    _little_one37s,
    _name_unknown37s,
    _owner_then37s,
    _sitting37s,
    _task_had37s,
    _sort_out37s,
    _ordeal37s,
    _only_role37s,
    _says_needs37s,
    _once_there37s,
)


def _objects34r(lexicon: Lexicon, *words: str) -> bool:
    """Whether each of ``words`` is one whole name of one object, each another."""
    ids = [_ids(w, lexicon, "object") for w in words]
    apart = len(set().union(*ids)) == len(words)
    return apart and all(_whole_name(w, lexicon, "object") for w in words)


# "Drill to Jess, no, Kofi, final answer."
_FINAL34R = re.compile(
    rf"^(?P<head>.+?\b{_CUE34R}\b.+?),\s*(?:and )?(?:that's )?(?:my )?final answer"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _final_answer34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): 'final answer' closing a correction ("Drill to Jess, no, Kofi, final
    answer") only stresses it: taken off (not without a correction before it)."""
    m = _FINAL34R.match(text)
    return text if m is None else f"{m['head']}{m['end'] or '.'}"


# "The spoon in the sink, oh no, sorry, on the tray is better."
_BETTER34R = re.compile(
    rf"^(?P<head>.+?\b{_CUE34R},\s*)(?P<p>on|in|onto|into) the (?P<s>[a-z]+(?: [a-z]+)?) "
    r"(?:is|would be|'d be|will be) (?:better|best)(?P<end>\s*[.!]?)$",
    _F,
)


def _place_better34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): after a correction cue, 'on the tray is better' is the place the
    correction names ('…, sorry, on the tray'); S must be one surface of the scene, and a place
    the scene lacks ('…, sorry, on the floor is better') is refused (it had been dropped as a
    remark, and the place corrected away read)."""
    m = _BETTER34R.match(text)
    if m is None:
        return text
    if not _whole_name(m["s"], lexicon, "surface"):
        if _ids(m["s"], lexicon):
            return text
        raise GroundingError(
            f"no surface called {m['s']!r} in the scene; {lexicon.listing('surface')}"
        )
    return f"{m['head']}{m['p']} the {m['s']}{m['end'] or '.'}"


# "…, no, it's Person B who's meant to get it."
_MEANT34R = re.compile(
    r"\b(?P<it>it's|it is) (?P<p>[a-z][\w ]*?) who(?:'s| is) (?:meant|supposed) to "
    r"(?:get|have|receive) (?P<x>it|them|the [a-z]+(?: [a-z]+)?)\b",
    _F,
)


def _meant_to_get34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): "it's P who's meant (supposed) to get it" is "it's P who gets it" (P
    one person of the scene)."""
    m = _MEANT34R.search(text)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    return f"{text[: m.start()]}{m['it']} {m['p']} who gets {m['x']}{text[m.end() :]}"


# "…, she's been after the bottle all along."
_ALL_ALONG34R = re.compile(
    r"\b(?P<s>she|he)(?:'s| has) been after (?P<x>the [a-z]+(?: [a-z]+)?) all along\b", _F
)


def _after_all_along34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): after a correction cue ('ugh, wrong one'), "she's been after the X all
    along" is "she wants the X" (X one whole name of an object)."""
    m = _ALL_ALONG34R.search(text)
    if m is None or not _whole_name(m["x"], lexicon, "object"):
        return text
    if not re.search(rf"\b(?:{_CUE34R}|wrong one|oops)\b", text[: m.start()], _F):
        return text  # 'all along' sets the want against what was said: only after a correction
    return f"{text[: m.start()]}{m['s']} wants {m['x']}{text[m.end() :]}"


# "First I said chips, but Person A is actually after the apple, so give her that."
_FIRST_SAID34R = re.compile(
    r"^(?:at )?first,? I (?:said|asked for|put) (?P<x>(?:the )?[a-z]+(?: [a-z]+)?),?\s*but "
    r"(?P<rest>.+)$",
    _F,
)


def _first_said34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): "First I said X, but <request>" takes the speaker's earlier word back:
    the request is read alone, its 'actually' (the stress on what replaces X) with it. X must
    name something of the scene, and the request must not name it again."""
    m = _FIRST_SAID34R.match(text)
    if m is None:
        return text
    said = _ids(m["x"], lexicon)
    if not said or not _whole_name(m["x"], lexicon, "object") or said & _ids(m["rest"], lexicon):
        return text
    rest = re.sub(r"\b(?:is|'s) actually after\b", "is after", m["rest"], count=1, flags=_F)
    return rest[0].upper() + rest[1:]


# "Crisps on the shelf, actually no, give them to Bob."
_PLACED_THEN34R = re.compile(
    r"^(?P<x>(?:the )?[a-z]+(?: (?!up\b|down\b)[a-z]+)?) (?:up |down )?(?P<p>on|in|onto|into) "
    r"(?P<s>the [a-z]+"
    r"(?: [a-z]+)?)(?P<cue>,\s*(?:(?:actually|hmm|oh|er|um),?\s*)?(?:no|sorry|wait|actually|hang "
    # session 40 (12r): 'hang on' / 'hold on', and 'I meant' before the new request
    r"on|hold on)\b,?\s*(?:i meant )?(?:give|hand|pass|take|bring) (?:them|it) .+)$",
    _F,
)


def _placed_then34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): a placement said without its verb ('Crisps on the shelf') before a
    correction that says a whole new request ('actually no, give them to Bob') is 'Put the
    crisps on the shelf, …': the correction then takes the clause back, 'them' the crisps."""
    m = _PLACED_THEN34R.match(text)
    if m is None or not _whole_name(m["x"], lexicon, "object"):
        return text
    if not _whole_name(m["s"], lexicon, "surface"):
        return text
    x = m["x"] if m["x"].lower().startswith("the ") else f"the {m['x']}"
    return f"Put {x} {m['p']} {m['s']}{m['cue']}"


# "Bottle to Person B, no, Person A, there's only her here." (the scene holds Person A alone)
_ONLY_HERE34R = re.compile(
    r"^(?P<x>(?:the )?[a-z]+(?: [a-z]+)?) to (?P<q>[a-z][\w ]*?),\s*no,\s*(?P<p>[a-z][\w ]*?),"
    r"\s*(?:there's|there is) only (?P<pro>her|him) here(?P<end>\s*[.!]?)$",
    _F,
)


def _only_here34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): "X to Q, no, P, there's only her here" in a scene of one person, P,
    where Q names no one: X to P (the remark says why Q was wrong)."""
    m = _ONLY_HERE34R.match(text)
    if m is None or len(lexicon.scene.humans) != 1:
        return text
    names = {n.lower() for h in lexicon.scene.humans for n in (h.name, *h.aliases)}
    if m["q"].lower() in names or _ids(m["q"], lexicon, "object"):
        return text
    if not _the_person(m["p"], m["pro"], lexicon) or not _whole_name(m["x"], lexicon, "object"):
        return text
    return f"{m['x']} to {m['p']}{m['end'] or '.'}"


# "Whichever of Person A and Person B is closer gets the bottle."
_WHICHEVER_OF34R = re.compile(
    rf"^whichever of (?P<p>{_PERSON34R}) and (?P<q>{_PERSON34R}) (?:is|'s) (?P<adj>closer|"
    r"nearer|closest|nearest)(?P<to> to (?:you|the robot|your gripper|hand))? (?:gets|can have|"
    r"should get|takes) (?P<x>.+?)(?P<end>\s*[.!]?)$",
    _F,
)


def _whichever_of34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): "Whichever of P and Q is closer (to you) gets X" is "X to P or Q,
    whichever is closer" (the nearer one is the robot's to find: a choice; P and Q two
    people)."""
    m = _WHICHEVER_OF34R.match(text)
    if m is None or not _persons34r(lexicon, m["p"], m["q"]):
        return text
    # 'closer to you' is closer to the robot, as 'whichever is closer' says
    return f"{m['x']} to {m['p']} or {m['q']}, whichever is {m['adj']}{m['end']}"


# "…, apple or chips, pick whichever you like."
_PICK34R = re.compile(
    r"(?P<head>\bor\b.+?),\s*(?:just )?pick (?:whichever|either|any)(?: one)?(?: you (?:like|"
    r"want|fancy|prefer))?(?P<end>\s*[.!]?)$",
    _F,
)


def _pick_whichever34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): 'pick whichever you like' closing a choice ('X or Y') leaves it to the
    robot: 'whichever you like'."""
    m = _PICK34R.search(text)
    if m is None:
        return text
    return f"{text[: m.start()]}{m['head']}, whichever you like{m['end'] or '.'}"


# "Something to eat for Person A, apple or chips, …"
_SOMETHING_FOR34R = re.compile(
    rf"^something(?: to (?:eat|drink|read|nibble on|snack on|play with))? for (?P<p>{_PERSON34R})"
    rf",\s*(?:either )?(?P<x>{_THING34R}) or (?P<y>{_THING34R})(?P<rest>\s*(?:[,.!].*)?)$",
    _F,
)


def _something_for34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): "Something to eat for P, X or Y" is "X or Y for P": the objects named
    say what the something is (P one person; X and Y two objects, each whole)."""
    m = _SOMETHING_FOR34R.match(text)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    if not _objects34r(lexicon, m["x"], m["y"]):
        return text
    return f"{m['x'][0].upper()}{m['x'][1:]} or {m['y']} for {m['p']}{m['rest'] or '.'}"


# "Scissors to either of the students, Zoe or Noah, doesn't matter."
_EITHER_NAMED34R = re.compile(
    rf"\beither of the (?P<role>[a-z]+),\s*(?P<p>{_PERSON34R}) or (?P<q>{_PERSON34R})"
    r"(?=\s*[,.!]|\s*$)",
    _F,
)


def _either_named34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): "either of the students, Zoe or Noah" names the two again: "either of
    the students" (P and Q two people, and the students exactly they)."""
    m = _EITHER_NAMED34R.search(text)
    if m is None or not _persons34r(lexicon, m["p"], m["q"]):
        return text
    group = _ids(m["role"], lexicon, "human")
    if group != _ids(m["p"], lexicon) | _ids(m["q"], lexicon):
        return text
    return f"{text[: m.start()]}either of the {m['role']}{text[m.end() :]}"


# "Either patient can have the magazine, they both like the puzzles."
_BOTH_LIKE34R = re.compile(
    r"^(?P<head>either .+?),\s*(?:they|they'd) both (?:like|love|enjoy|want|read|use)\b"
    r"(?P<why>[^,;.!]*)(?P<end>\s*[.!]?)$",
    _F,
)


def _both_like34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): after a choice of two people ('Either patient can have X'), "they both
    like the puzzles" says why either will do: taken off when it names nothing of the scene but
    the request's objects."""
    m = _BOTH_LIKE34R.match(text)
    if m is None or not _ids(m["why"], lexicon) <= _ids(m["head"], lexicon, "object"):
        return text
    return f"{m['head']}{m['end'] or '.'}"


# "One for Person A, one for Person B, that's the apple and the cup; who gets which is …"
_ONE_FOR_EACH34R = re.compile(
    rf"^one for (?P<p>{_PERSON34R}),\s*(?:and )?one for (?P<q>{_PERSON34R}),\s*(?:that's|that is|"
    rf"those are|out of) (?P<x>{_THING34R}) and (?P<y>{_THING34R})(?P<tail>\s*(?:[;,.!].*)?)$",
    _F,
)


def _one_for_each34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): "One for P, one for Q, that's X and Y" is "One each for P and Q out of X
    and Y" (which goes to whom is not said: a choice); P and Q two people, X and Y two objects."""
    m = _ONE_FOR_EACH34R.match(text)
    if m is None or not _persons34r(lexicon, m["p"], m["q"]):
        return text
    if not _objects34r(lexicon, m["x"], m["y"]):
        return text
    tail = m["tail"] or "."
    if tail.lstrip().startswith(";"):
        tail = "," + tail.lstrip()[1:]
    return f"One each for {m['p']} and {m['q']} out of {m['x']} and {m['y']}{tail}"


# "Split it up so Person A ends up with the bottle and Person B ends up with the cup."
_SPLIT_SO34R = re.compile(r"^split (?:it|them|things|everything) up so(?: that)? (?P<rest>.+)$", _F)


def _split_so34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): "Split it up so <who ends up with what>" says the share-out by its
    result: the result read alone (it must name two people or more)."""
    m = _SPLIT_SO34R.match(text)
    if m is None or len(_ids(m["rest"], lexicon, "human")) < 2:
        return text
    return m["rest"][0].upper() + m["rest"][1:]


# "Any bottle you can lay hands on, give it to Person A."
_LAY_HANDS34R = re.compile(
    r"\b(?P<any>any (?:[a-z]+ )?[a-z]+) (?:that )?you can (?:lay|get|put) (?:your )?hands on\b",
    _F,
)


def _lay_hands34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): "any X you can lay hands on" is "any X" (any at all)."""
    m = _LAY_HANDS34R.search(text)
    if m is None or not _ids(m["any"], lexicon, "object"):
        return text
    return f"{text[: m.start()]}{m['any']}{text[m.end() :]}"


# "There's a lone bottle in this cell and Person A is the one to have it."
_LONE_ONE34R = re.compile(
    r"^there(?:'s| is) (?:a lone|a single|only one|just the one|just one|one) (?P<k>[a-z]+)"
    r"(?: (?:in|on) (?:this|the) (?:cell|room|table|bench|place))?(?: here)?,?\s*and "
    r"(?P<p>[a-z][\w ]*?) is the one to (?:have|get|take) it(?P<end>\s*[.!]?)$",
    _F,
)


def _lone_one34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): "There's a lone X here and P is the one to have it" is "Give P the X":
    a count, so the scene must hold exactly one X (else left, and refused)."""
    m = _LONE_ONE34R.match(text)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    if len(_ids(m["k"], lexicon, "object")) != 1 or not _whole_name(m["k"], lexicon, "object"):
        return text
    return f"Give {m['p']} the {m['k']}{m['end'] or '.'}"


# "Nobody goes without: Person A gets handed the bottle, Person B the bag of chips."
_NOBODY_WITHOUT34R = re.compile(
    r"^(?:nobody|no one|no-one) (?:goes|is going|will go|is left) without(?: anything)?\s*[:,]\s*"
    r"(?P<rest>.+)$",
    _F,
)


def _nobody_without34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): "Nobody goes without: <tasks>" is the tasks, when they name every
    person of the scene (else the heading says more than they do: left, and refused)."""
    m = _NOBODY_WITHOUT34R.match(text)
    if m is None:
        return text
    if _ids(m["rest"], lexicon, "human") != {h.id for h in lexicon.scene.humans}:
        return text
    return m["rest"][0].upper() + m["rest"][1:]


_GETS_HANDED34R = re.compile(
    rf"\b(?P<p>{_PERSON34R}) gets (?:handed|passed|given) (?=(?:the|a|an) )", _F
)


def _gets_handed34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): "P gets handed the X" is "P gets the X" (P one person)."""
    m = _GETS_HANDED34R.search(text)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    return f"{text[: m.start()]}{m['p']} gets {text[m.end() :]}"


# "Both mugs need shifting up to the shelf, the red and the blue alike."
_ALIKE34R = re.compile(
    r"^(?P<head>.*\bboth\b.+,\s*(?:the )?[a-z]+ and (?:the )?[a-z]+) alike(?P<end>\s*[.!]?)$",
    _F,
)


def _alike34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): "both …, the red and the blue alike": 'alike' only stresses the two
    listed (the list is then checked against 'both')."""
    m = _ALIKE34R.match(text)
    return text if m is None else f"{m['head']}{m['end'] or '.'}"


# "Hand everything we've got, both the items, over to Person A."
_WE_HAVE34R = re.compile(r"\b(?P<e>everything) (?:we've got|we have got|we have)\b", _F)


def _we_have34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): "everything we've got" is "everything" (the scene's objects)."""
    m = _WE_HAVE34R.search(text)
    return text if m is None else f"{text[: m.start()]}{m['e']}{text[m.end() :]}"


# "One bottle, one person: bottle to Person A."
_ONE_ONE34R = re.compile(r"^one (?P<k>[a-z]+),\s*one person\s*:\s*(?P<rest>.+)$", _F)


def _one_one34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): a heading "One bottle, one person:" counts the scene: taken off when the
    scene holds exactly one X and one person (else left, and refused)."""
    m = _ONE_ONE34R.match(text)
    if m is None or len(lexicon.scene.humans) != 1:
        return text
    if not _whole_name(m["k"], lexicon, "object"):
        return text
    kind = next(iter(_ids(m["k"], lexicon, "object")))
    cat = next(o.category for o in lexicon.scene.objects if o.id == kind)
    if sum(o.category == cat for o in lexicon.scene.objects) != 1:
        return text
    return m["rest"][0].upper() + m["rest"][1:]


# "… she needs the pair of blocks, red and green."
_PAIR_LISTED34R = re.compile(
    r"\bthe pair of (?P<k>[a-z]+s)(?=,\s*(?:the )?[a-z]+ and (?:the )?[a-z]+\s*[.!]?$)", _F
)


def _pair_listed34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): "the pair of blocks, red and green" is "both blocks, red and green"
    (the grammar checks 'both' against the scene and the list against 'both')."""
    m = _PAIR_LISTED34R.search(text)
    if m is None or not _ids(m["k"], lexicon, "object"):
        return text
    return f"{text[: m.start()]}both {m['k']}{text[m.end() :]}"


# "The locker's where the two spanners live, so in they go."
_WHERE_LIVE34R = re.compile(
    r"^the (?P<s>[a-z]+(?: [a-z]+)?)(?:'s| is) where (?P<x>the (?:two |three |four )?[a-z]+) "
    r"(?:live|belong|go|are kept|get kept),?\s*so (?P<p>in|on) (?:they|them) go(?P<end>\s*[.!]?)$",
    _F,
)


def _where_live34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): "The locker's where the spanners live, so in they go" is "Put the
    spanners in the locker" (S one surface; the objects and their count read by the grammar)."""
    m = _WHERE_LIVE34R.match(text)
    if m is None or not _whole_name(m["s"], lexicon, "surface"):
        return text
    if not _ids(m["x"], lexicon, "object"):
        return text
    return f"Put {m['x']} {m['p']} the {m['s']}{m['end'] or '.'}"


# "Carol asked for a mug, anything but the red one."
_ANYTHING_BUT34R = re.compile(
    r"\b(?P<a>an? [a-z]+),\s*anything but (?P<x>the [a-z]+ one|the [a-z]+ [a-z]+)\b", _F
)


def _anything_but34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): "a mug, anything but the red one" is "a mug, any but the red one": the
    'anything' is of the kind said before it."""
    m = _ANYTHING_BUT34R.search(text)
    if m is None or not _ids(m["a"], lexicon, "object"):
        return text
    return f"{text[: m.start()]}{m['a']}, any but {m['x']}{text[m.end() :]}"


# "Leaving the crisps aside, Bob can take what's left."
_LEAVING_ASIDE34R = re.compile(
    rf"^(?:leaving|setting|putting|keeping) (?P<x>{_THING34R}) (?:aside|to one side),\s*"
    r"(?P<p>[a-z][\w ]*?) can (?:take|have) (?:what's left|whatever's left|what is left|the rest)"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _leaving_aside34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): "Leaving X aside, P can take what's left" is "P can take everything
    except X" (X one whole object, P one person)."""
    m = _LEAVING_ASIDE34R.match(text)
    if m is None or not _only_person(m["p"], lexicon) or not _objects34r(lexicon, m["x"]):
        return text
    return f"{m['p']} can take everything except {m['x']}{m['end'] or '.'}"


# "Only Person B gets anything today, and it's the chips."
_ONLY_GETS34R = re.compile(
    r"^only (?P<p>[a-z][\w ]*?) gets anything(?: today| now| this time)?,\s*and (?:it's|it is) "
    rf"(?P<x>{_THING34R})(?P<end>\s*[.!]?)$",
    _F,
)


def _only_gets34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): "Only P gets anything, and it's the X" is "P gets the X" (P one person,
    X one whole object)."""
    m = _ONLY_GETS34R.match(text)
    if m is None or not _only_person(m["p"], lexicon) or not _objects34r(lexicon, m["x"]):
        return text
    return f"{m['p']} gets {m['x']}{m['end'] or '.'}"


# "No fuss, nothing else, just the bottle for Person A."
_NO_FUSS34R = re.compile(r"^no fuss,\s*(?P<rest>(?:nothing else,\s*)?just .+)$", _F)


def _no_fuss34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): "No fuss," before "just <request>" is a filler: taken off."""
    m = _NO_FUSS34R.match(text)
    return text if m is None else m["rest"][0].upper() + m["rest"][1:]


# "Nothing fancy, no glass, just the bottle for Person A." ('Nothing fancy,' is taken off first)
_NOTHING_FANCY34R = re.compile(
    r"^(?:nothing (?:fancy|else|more),\s*)?no (?P<n>[a-z]+(?: [a-z]+)?),\s*(?P<rest>just .+)$",
    _F,
)


def _nothing_fancy34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): "(Nothing fancy,) no glass, just X for P": the thing said not wanted is
    left out of a request that does not name it (one it names leaves the text, refused)."""
    m = _NOTHING_FANCY34R.match(text)
    if m is None or _ids(m["n"], lexicon) & _ids(m["rest"], lexicon):
        return text
    if not _ids(m["rest"], lexicon, "object") or _ids(m["n"], lexicon, "human"):
        return text
    return m["rest"][0].upper() + m["rest"][1:]


# "Person B, not Person A, is the one getting the chips."
_NOT_Q_ONE34R = re.compile(
    r"^(?P<p>[a-z][\w ]*?),\s*not (?P<q>[a-z][\w ]*?),\s*is the one (?:getting|to get|who gets|"
    r"having) (?P<rest>.+)$",
    _F,
)


def _not_q_one34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): "P, not Q, is the one getting X" is "P is the one getting X" (P and Q
    two people)."""
    m = _NOT_Q_ONE34R.match(text)
    if m is None or not _persons34r(lexicon, m["p"], m["q"]):
        return text
    return f"{m['p']} is the one getting {m['rest']}"


# "Lena wants the plate, but not the one on the plate rack."
_BUT_NOT_ON34R = re.compile(
    r"\bthe (?P<k>[a-z]+),\s*(?:but )?not the one (?P<p>on|in) the (?P<s>[a-z]+(?: [a-z]+)?)"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _but_not_on34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): "the plate, but not the one on the rack" is "the plate that is not on
    the rack" (K names several objects, S one surface; which K that leaves is the grammar's)."""
    m = _BUT_NOT_ON34R.search(text)
    if m is None or not _whole_name(m["s"], lexicon, "surface"):
        return text
    if len(_ids(m["k"], lexicon, "object")) < 2:
        return text
    return f"{text[: m.start()]}the {m['k']} that is not {m['p']} the {m['s']}{m['end'] or '.'}"


# "Zoe wants to read the book that isn't green."
_WANTS_TO_USE34R = re.compile(
    r"\b(?P<w>wants|needs|would like) to (?:read|use|borrow|eat|drink|wear|play with) "
    r"(?=the |an? )",
    _F,
)


def _wants_to_use34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): "P wants to read the book" is "P wants the book": what P does with it
    is P's (a verb of the robot's, 'wants to put …', is not one of these)."""
    m = _WANTS_TO_USE34R.search(text)
    if m is None or not _ids(text[m.end() :], lexicon, "object"):
        return text
    return f"{text[: m.start()]}{m['w']} {text[m.end() :]}"


# "Give it to Person B, the one by the window."
_ONE_BY34R = re.compile(
    r"^(?P<head>.+\bto (?P<p>[a-z][\w ]*?)),\s*the one (?:by|at|near|next to|beside) the "
    r"(?P<w>[a-z]+(?: [a-z]+)?)(?P<end>\s*[.!]?)$",
    _F,
)


def _one_by34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): after a person named once, "the one by the window" (naming nothing of
    the scene) only describes that person: taken off."""
    m = _ONE_BY34R.match(text)
    if m is None or not _only_person(m["p"], lexicon) or _ids(m["w"], lexicon):
        return text
    return f"{m['head']}{m['end'] or '.'}"


# -- session 34 (12r): the same kinds in blind19 and blind20 -------------------------------------

# "Whichever cup isn't the green one, that's Omar's, hand it to him."
_OWNER_THEN34R = re.compile(
    r"^(?P<x>.+?),\s*(?:that's|that is|is|it's|it is) (?P<p>[a-z][\w ]*?)'s,\s*"
    r"(?P<v>give|hand|pass|take) it(?: to)? (?P<pro>him|her)(?P<end>\s*[.!]?)$",
    _F,
)


def _owner_then34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): "<the object described>, that's Omar's (is Zoe's), hand it to him" is
    "<the object described>, hand it to Omar": the owner is the one person 'him' / 'her' then
    means (the description must name no person)."""
    m = _OWNER_THEN34R.match(text)
    if m is None or not _the_person(m["p"], m["pro"], lexicon):
        return text
    if _ids(m["x"], lexicon, "human") or not _ids(m["x"], lexicon, "object"):
        return text
    return f"{m['x']}, {m['v']} it to {m['p']}{m['end'] or '.'}"


# "Shelf for the bottle, please, or no, better still, straight to Alice."
_SURFACE_FOR34R = re.compile(
    r"^(?P<s>[a-z]+(?: [a-z]+)?) for (?P<x>the [a-z]+(?: [a-z]+)?),\s*(?:please,\s*)?(?:or )?"
    r"no,\s*(?:(?:better still|even better|better yet),\s*)?(?:straight |right )?"
    r"(?P<rest>(?:to|on|onto|in|into) .+)$",
    _F,
)


def _surface_for34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): a note "Shelf for the bottle" before a correction ("…, or no, better
    still, straight to Alice") is "The bottle on the shelf, no, to Alice" (S one surface, the
    object one whole name)."""
    m = _SURFACE_FOR34R.match(text)
    if m is None or not _whole_name(m["s"], lexicon, "surface"):
        return text
    if not _whole_name(m["x"], lexicon, "object"):
        return text
    return f"The {m['x'][4:]} on the {m['s'].lower()}, no, {m['rest']}"


# "Bottle on the shelf, no wait, to Alice."
_NO_WAIT_TO34R = re.compile(
    r"(?P<head>\b(?:on|in) the [a-z]+(?: [a-z]+)?),\s*no,? wait,\s*(?P<to>to [a-z])", _F
)


def _no_wait_to34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): "X on the shelf, no wait, to Alice" is "…, no, to Alice" ('no wait' the
    cue 'no', before a new recipient)."""
    m = _NO_WAIT_TO34R.search(text)
    if m is None:
        return text
    return f"{text[: m.start()]}{m['head']}, no, {m['to']}{text[m.end() :]}"


# "Sponge on the tray... actually no, sink's better, put it in the sink."
_SAID_BETTER34R = re.compile(
    r"(?P<cue>\b(?:no|sorry|actually),\s*)(?:the )?(?P<s>[a-z]+(?: [a-z]+)?)(?:'s| is| would be) "
    r"better,\s*(?P<rest>.+)$",
    _F,
)


def _said_better34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): after a correction cue, "sink's better, put it in the sink" says the
    place twice: the first saying comes off when the request after it names that surface."""
    m = _SAID_BETTER34R.search(text)
    if m is None or not _whole_name(m["s"], lexicon, "surface"):
        return text
    if not _ids(m["s"], lexicon) <= _ids(m["rest"], lexicon, "surface"):
        return text
    return f"{text[: m.start()]}{m['cue']}{m['rest']}"


# "Clear the lot into the locker, bar the drill and the hammer, I still need those."
_STILL_NEED34R = re.compile(
    r"(?P<head>\b(?:bar|except|apart from|but|other than|minus|not) [^,]+?),\s*I (?:still |'ll )?"
    r"need (?:those|them|that|it|these)(?: still| later)?(?P<end>\s*[.!]?)$",
    _F,
)


def _still_need34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): after what is left out ('bar the drill and the hammer'), "I still need
    those" says why: taken off (the speaker asks for nothing)."""
    m = _STILL_NEED34R.search(text)
    if m is None or not _ids(m["head"], lexicon, "object"):
        return text
    return f"{text[: m.start()]}{m['head']}{m['end'] or '.'}"


# "Sam's after a pen. Red's no good for forms, so one of the others."
_NO_GOOD34R = re.compile(
    r"^(?P<head>.+?\ban? (?P<k>[a-z]+))\.\s*(?:the )?(?P<a>[a-z]+)(?: one)?(?:'s| is) no good"
    r"(?: for [a-z ]+?)?,\s*so (?:one of the others|another one|a different one)(?P<end>\s*[.!]?)$",
    _F,
)


def _no_good34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): "P's after a pen. Red's no good for forms, so one of the others" is "P's
    after a pen, any but the red one" (the red pen one object of the kind)."""
    m = _NO_GOOD34R.match(text)
    if m is None or len(_ids(f"the {m['a']} {m['k']}", lexicon, "object")) != 1:
        return text
    if len(_ids(m["k"], lexicon, "object")) < 2:
        return text
    return f"{m['head']}, any but the {m['a']} one{m['end'] or '.'}"


# "Lily wants a block to chew on. Not the red one, love, the other."
_NOT_ONE_OTHER34R = re.compile(
    r"^(?P<head>.+?\ban? (?P<k>[a-z]+))(?: to [a-z]+(?: on| with)?)?\.\s*not the (?P<a>[a-z]+) "
    r"one,\s*(?:(?:love|dear|pet|mind),\s*)?the other(?: one)?(?P<end>\s*[.!]?)$",
    _F,
)


def _not_one_other34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): "P wants a block (to chew on). Not the red one, the other." is "P wants
    a block, any but the red one" when the scene holds two of the kind (with more, 'the other' is
    not one)."""
    m = _NOT_ONE_OTHER34R.match(text)
    if m is None or len(_ids(m["k"], lexicon, "object")) != 2:
        return text
    if len(_ids(f"the {m['a']} {m['k']}", lexicon, "object")) != 1:
        return text
    return f"{m['head']}, any but the {m['a']} one{m['end'] or '.'}"


# "The guest on table five, Mr Novak, gets the white plate, not the blue."
_AT_TABLE34R = re.compile(
    r"^the (?P<role>[a-z]+) (?:on|at) table (?:[a-z]+|\d+),\s*(?P<p>[a-z][\w ]*?),\s*(?P<rest>.+)$",
    _F,
)


def _at_table34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): "The guest on table five, Mr Novak, …" names one person twice: "Mr
    Novak …" (the role must be one of the person's names)."""
    m = _AT_TABLE34R.match(text)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    if not _ids(m["p"], lexicon) <= _ids(m["role"], lexicon, "human"):
        return text
    return f"{m['p']} {m['rest']}"


# "The cup and then the apple to Person B, or rather the apple first and then the cup."
_RATHER_ORDER34R = re.compile(
    rf"^(?P<x>{_THING34R}) and then (?P<y>{_THING34R}) to (?P<p>[a-z][\w ]*?),\s*or rather "
    rf"(?P<y2>{_THING34R}) first,? and then (?P<x2>{_THING34R})(?P<end>\s*[.!]?)$",
    _F,
)


def _rather_order34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): "X and then Y to P, or rather Y first and then X" says the order again
    with the same two objects: "Y to P, then X to P"."""
    m = _RATHER_ORDER34R.match(text)
    if m is None or not _only_person(m["p"], lexicon) or not _objects34r(lexicon, m["x"], m["y"]):
        return text
    if _ids(m["x"], lexicon) != _ids(m["x2"], lexicon):
        return text
    if _ids(m["y"], lexicon) != _ids(m["y2"], lexicon) or not _objects34r(lexicon, m["x2"]):
        return text
    y = m["y2"][0].upper() + m["y2"][1:]
    return f"{y} to {m['p']}, then {m['x2']} to {m['p']}{m['end'] or '.'}"


# "Cup to Person A, then the apple to Person B; no, hang on, swap the order round, apple to
# Person B first and the cup after."
_SWAP_ORDER34R = re.compile(
    r"^(?P<a>[^;,]+?),\s*then (?P<b>[^;,]+?);\s*(?:no,\s*)?(?:hang on,\s*|wait,\s*)?swap the "
    r"order(?: round| around| over)?,\s*(?P<y>[^,]+?) first,? and (?P<x>[^,]+?) after"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _swap_order34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): "A, then B; no, swap the order round, B first and A after" is "B, then
    A": the tasks said again must be the two before (their objects the same, a person they name
    the one of that task)."""
    m = _SWAP_ORDER34R.match(text)
    if m is None:
        return text
    for said, task in ((m["y"], m["b"]), (m["x"], m["a"])):
        if _ids(said, lexicon, "object") != _ids(task, lexicon, "object"):
            return text
        if not _ids(said, lexicon, "human") <= _ids(task, lexicon, "human"):
            return text
    if len(_ids(m["a"], lexicon, "object")) != 1 or len(_ids(m["b"], lexicon, "object")) != 1:
        return text
    return f"{m['b'][0].upper()}{m['b'][1:]}, then {m['a']}{m['end'] or '.'}"


# "They both want something. Bottle over to Person A please, and cup across to Person B."
_BOTH_SOMETHING34R = re.compile(
    r"^(?:they|the two of them) both (?:want|need|would like) something\.\s*(?P<rest>.+)$", _F
)


def _both_something34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): "They both want something." before tasks for both people of a scene of
    two: the heading comes off."""
    m = _BOTH_SOMETHING34R.match(text)
    people = {h.id for h in lexicon.scene.humans}
    if m is None or len(people) != 2 or _ids(m["rest"], lexicon, "human") != people:
        return text
    return m["rest"]


# "Everything that's a box goes on the conveyor, except the big one, leave that on the pallet."
_THAT_IS_A34R = re.compile(
    r"^everything that(?:'s| is) an? (?P<k>[a-z]+) (?:goes|go) (?P<p>on|onto|in|into) ", _F
)


def _that_is_a34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): "Everything that's a box goes on S" is "Every box on S"."""
    m = _THAT_IS_A34R.match(text)
    if m is None or len(_ids(m["k"], lexicon, "object")) < 2:
        return text
    return f"Every {m['k']} {m['p']} {text[m.end() :]}"


_LEAVE_THAT34R = re.compile(
    r"(?P<head>\bexcept the (?P<a>[a-z]+) one),\s*leave (?:that|it) (?:on|in) the "
    r"(?P<s>[a-z]+(?: [a-z]+)?)(?P<end>\s*[.!]?)$",
    _F,
)


def _leave_that34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): "every K …, except the big one, leave that on the pallet": the one left
    out stays where it is, said where: taken off when it starts on that surface (else left)."""
    m = _LEAVE_THAT34R.search(text)
    k = re.search(r"\bevery ([a-z]+)\b", text[: m.start()], _F) if m is not None else None
    if m is None or k is None or not _whole_name(m["s"], lexicon, "surface"):
        return text
    one = _ids(f"the {m['a']} {k.group(1)}", lexicon, "object")
    surface = next(iter(_ids(m["s"], lexicon, "surface")))
    if len(one) != 1 or set(starting_on(one, surface, lexicon)) != one:
        return text
    return f"{text[: m.start()]}{m['head']}{m['end'] or '.'}"


# "Those two mugs want to go on the counter, please." / "All three of the boxes want to go on …"
_COUNTED_WANT34R = re.compile(
    r"^(?P<d>those|the|all|both)(?P<n> two| three| four)?(?P<of> of the)? (?P<k>[a-z]+s) "
    r"(?:want|need) to (?:go|sit|be|live) (?P<p>on|onto|in|into) ",
    _F,
)


def _counted_want34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): "Those two mugs (All three of the boxes) want to go on S" is "Put the two
    mugs (all three of the boxes) on S" (session 28's '<object> wants to go on S', for a counted
    plural; the count read by the grammar)."""
    m = _COUNTED_WANT34R.match(text)
    if m is None or not _ids(m["k"], lexicon, "object"):
        return text
    d = "the" if m["d"].lower() == "those" else m["d"].lower()
    if d == "the" and m["of"]:
        return text
    return f"Put {d}{m['n'] or ''}{m['of'] or ''} {m['k']} {m['p']} {text[m.end() :]}"


# "The stapler's for Priya. Oh hang on, she's got one, give it to Sam."
_HAS_ONE34R = re.compile(
    r"(?P<cue>\b(?:hang on|no|actually|wait|sorry),\s*)(?P<pro>she|he)(?:'s| has)(?: already)? "
    r"got (?:one|it)(?: already)?,\s*(?P<rest>(?:give|hand|pass|take) it .+)$",
    _F,
)


def _has_one34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): after a correction cue, "she's got one (already)" says why the request
    before it is taken back: taken off when the text before names one person, whom the pronoun
    may be, and the request after it another."""
    m = _HAS_ONE34R.search(text)
    if m is None:
        return text
    before = _ids(text[: m.start()], lexicon, "human")
    after = _ids(m["rest"], lexicon, "human")
    if len(before) != 1 or len(after) != 1 or before == after:
        return text
    if not _fits(next(iter(before)), m["pro"], lexicon):
        return text
    return f"{text[: m.start()]}{m['cue']}{m['rest']}"


# -- session 34 (12r): the same kinds in blind24 to blind31 --------------------------------------

# "The white plate on the rack, no, the counter, we need it for service."
_NEED_IT_FOR34R = re.compile(
    rf"^(?P<head>.+\b{_CUE34R}\b.+?),\s*we (?:need|want) (?:it|that|them) (?:for|at|in) "
    r"(?P<why>[a-z ]+?)(?P<end>\s*[.!]?)$",
    _F,
)


def _need_it_for34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): after a correction, "we need it for service" says why (naming nothing
    of the scene): taken off."""
    m = _NEED_IT_FOR34R.match(text)
    if m is None or _ids(m["why"], lexicon):
        return text
    return f"{m['head']}{m['end'] or '.'}"


# "Split the two things between them, one apiece, with the bottle going to Person B and …"
_SPLIT_BETWEEN34R = re.compile(
    r"^split the (?P<n>two|three|four) (?:things|items) between (?:them|the two of them),\s*"
    r"(?:one (?:apiece|each),\s*)?with (?P<rest>.+)$",
    _F,
)


def _split_between34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): "Split the two things between them, one apiece, with X going to P and Y
    to Q" is "X to P and Y to Q" when that names as many objects as the count, each once, and
    every person of the scene (else left, refused)."""
    m = _SPLIT_BETWEEN34R.match(text)
    if m is None:
        return text
    rest = re.sub(r"\b(?:going|goes|heading) to\b", "to", m["rest"], flags=_F)
    said = [it for it in _names(rest, lexicon) if all(r.kind == "object" for r in it.refs)]
    objects = {r.id for it in said for r in it.refs}
    if len(objects) != _NUMBERS33R[m["n"].lower()] or len(said) != len(objects):
        return text
    if _ids(rest, lexicon, "human") != {h.id for h in lexicon.scene.humans}:
        return text
    return rest[0].upper() + rest[1:]


# "Not the bottle for Bob, he said so twice, he's after a packet of crisps."
_NOT_FOR_AFTER34R = re.compile(
    r"^not (?P<x>the [a-z]+) for (?P<p>[a-z][\w ]*?),\s*(?:(?P<pro1>he|she) said so(?: twice)?,"
    r"\s*)?(?P<pro>he|she)(?:'s| is) after (?:a packet of |a bag of |some |the )?(?P<y>[a-z]+)"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _not_for_after34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): "Not the bottle for Bob, he said so, he's after a packet of crisps" is
    "Not the bottle, the crisps for Bob" (the pronouns may be Bob; X and Y two objects)."""
    m = _NOT_FOR_AFTER34R.match(text)
    if m is None or not _the_person(m["p"], f"{m['pro']} {m['pro1'] or ''}", lexicon):
        return text
    if not _objects34r(lexicon, m["x"], f"the {m['y']}"):
        return text
    return f"Not {m['x']}, the {m['y']} for {m['p']}{m['end'] or '.'}"


# "Pop the bottle up on the shelf — actually, on second thoughts, straight to Alice with it."
_STRAIGHT_WITH_IT34R = re.compile(
    r"^(?P<head>.+?)\s*(?:—|–|,)\s*(?P<cue>actually|no|sorry),\s*(?:on second thoughts?,\s*)?"
    r"(?:straight |right )?to (?P<p>[a-z][\w ]*?) with it(?P<end>\s*[.!]?)$",
    _F,
)


def _straight_with_it34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): "…, actually, on second thoughts, straight to Alice with it" is "…,
    actually, give it to Alice" (P one person)."""
    m = _STRAIGHT_WITH_IT34R.match(text)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    return f"{m['head']}, {m['cue']}, give it to {m['p']}{m['end'] or '.'}"


# "Priya wants the red pen — wait, no, she said black, the black pen."
_SHE_SAID34R = re.compile(
    r"(?P<cue>\b(?:no|sorry|wait),\s*)(?:she|he|they) said (?P<a>[a-z]+),\s*"
    r"(?P<rest>the (?P=a) [a-z]+)",
    _F,
)


def _she_said34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): after a correction cue, "she said black, the black pen" says the word
    twice: the first saying comes off (the second must name one object)."""
    m = _SHE_SAID34R.search(text)
    if m is None or not _whole_name(m["rest"], lexicon, "object"):
        return text
    return f"{text[: m.start()]}{m['cue']}{m['rest']}{text[m.end() :]}"


# "The ruler goes on the desk. Sorry, the bookshelf, the desk's covered in paint."
_CORRECTED_PLACE_WHY34R = re.compile(
    r"^(?P<head>.+\b(?:no|sorry|actually),\s*(?:on |in )?the (?P<s2>[a-z]+(?: [a-z]+)?)),\s*the "
    r"(?P<s1>[a-z]+(?: [a-z]+)?)(?:'s| is) (?P<why>[a-z ]+?)(?P<end>\s*[.!]?)$",
    _F,
)


def _corrected_place_why34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): after a correction to another surface, "the desk's covered in paint"
    says why of the surface corrected away: taken off when that surface is named before the cue
    and the remark names nothing else."""
    m = _CORRECTED_PLACE_WHY34R.match(text)
    if m is None or not _whole_name(m["s1"], lexicon, "surface"):
        return text
    if not _whole_name(m["s2"], lexicon, "surface") or _ids(m["why"], lexicon):
        return text
    s1, s2 = _ids(m["s1"], lexicon), _ids(m["s2"], lexicon)
    cue = m.start("s2")
    if s1 == s2 or not s1 <= _ids(text[:cue], lexicon, "surface"):
        return text
    return f"{m['head']}{m['end'] or '.'}"


# "The two smaller boxes can join the big one on the pallet."
_JOIN_THE34R = re.compile(
    r"\b(?P<x>the (?:two |three )?[a-z]+ (?P<k>[a-z]+)) can join the (?P<a>[a-z]+) one "
    r"(?P<p>on|in) the (?P<s>[a-z]+(?: [a-z]+)?)(?P<end>\s*[.!]?)$",
    _F,
)


def _join_the34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): "the smaller boxes can join the big one on the pallet" is "… can go on
    the pallet" when the big one is one object that starts there."""
    m = _JOIN_THE34R.search(text)
    if m is None or not _whole_name(m["s"], lexicon, "surface"):
        return text
    one: set[str] = set()
    for k in (m["k"], m["k"][:-1], m["k"][:-2]):
        one = _ids(f"the {m['a']} {k}", lexicon, "object")
        if len(one) == 1:
            break
    surface = next(iter(_ids(m["s"], lexicon, "surface")))
    if len(one) != 1 or set(starting_on(one, surface, lexicon)) != one:
        return text
    return f"{text[: m.start()]}{m['x']} can go {m['p']} the {m['s']}{m['end'] or '.'}"


# "Don't bother with the bottle, she's brought a flask, just the chips to Person A."
_BROUGHT_OWN34R = re.compile(
    r"^(?P<h>don't bother with (?:the )?[a-z]+),\s*(?:she|he)(?:'s| has) (?:brought|got) "
    r"(?:a|an|her|his) (?P<w>[a-z]+)(?: with (?:her|him))?,\s*(?P<rest>just .+)$",
    _F,
)


def _brought_own34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): "Don't bother with the bottle, she's brought a flask, just …": why the
    bottle is left out (naming nothing of the scene) comes off."""
    m = _BROUGHT_OWN34R.match(text)
    if m is None or _ids(m["w"], lexicon):
        return text
    return f"{m['h']}, {m['rest']}"


# "whichever ones closer to person a, give her that"
_WHICHEVER_CLOSER34R = re.compile(
    r"^whichever (?:one's|ones|one is|is|'s) (?P<adj>closer|nearer|closest|nearest) to "
    r"(?P<p>[a-z][\w ]*?),\s*give (?P<pro>her|him) (?:that|it)(?: one)?(?P<end>\s*[.!]?)$",
    _F,
)


def _whichever_closer34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): "whichever one's closer to P, give her that" is "Give P X or Y,
    whichever is closer to her": a choice of the scene's objects (two to four, each named
    alone)."""
    m = _WHICHEVER_CLOSER34R.match(text)
    if m is None or not _the_person(m["p"], m["pro"], lexicon):
        return text
    said = [_object_said33r(o.id, lexicon) for o in lexicon.scene.objects]
    if not 2 <= len(said) <= 4 or any(s is None for s in said):
        return text
    listed = ", ".join(s for s in said[:-1] if s) + f" or {said[-1]}"
    return f"Give {m['p']} {listed}, whichever is {m['adj']} to {m['pro']}{m['end'] or '.'}"


# "Person B gets the bottle and Person A gets the chips and the apple stays where it is."
_STAYS_PUT34R = re.compile(
    r"^(?P<head>.+?)(?:,| and|;)\s*(?P<x>(?:the )?[a-z]+(?: [a-z]+)?) stays (?:where it is|put|"
    r"as it is)(?P<end>\s*[.!]?)$",
    _F,
)


def _stays_put34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): "…, and the apple stays where it is" after tasks that do not name the
    apple: nothing to do for it (one the tasks name is left, refused)."""
    m = _STAYS_PUT34R.match(text)
    if m is None or not _whole_name(m["x"], lexicon, "object"):
        return text
    if _ids(m["x"], lexicon) & _ids(m["head"], lexicon) or not _ids(m["head"], lexicon, "object"):
        return text
    return f"{m['head']}{m['end'] or '.'}"


# "It's Person B who's getting the cup, not Person A, the caddie got it wrong earlier."
_ITS_P_WHO34R = re.compile(
    r"^it(?:'s| is) (?P<p>[a-z][\w ]*?) who(?:'s| is) getting (?P<x>the [a-z]+(?: [a-z]+)?),\s*"
    r"not (?P<q>[a-z][\w ]*?)(?:,\s*(?P<why>[^,.;!?]+?))?(?P<end>\s*[.!]?)$",
    _F,
)


def _its_p_who34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): "It's P who's getting X, not Q(, the caddie got it wrong)" is "P is
    getting X, not Q" (P and Q two people; the remark naming nothing of the scene)."""
    m = _ITS_P_WHO34R.match(text)
    if m is None or not _persons34r(lexicon, m["p"], m["q"]):
        return text
    if m["why"] and _ids(m["why"], lexicon):
        return text
    return f"{m['p']} is getting {m['x']}, not {m['q']}{m['end'] or '.'}"


# "Sit the teddy in the high chair, no, better down on the play mat with her."
_BETTER_DOWN34R = re.compile(
    rf"(?P<cue>\b{_CUE34R},\s*)better (?:down |up )?(?P<p>on|in|onto|into) the "
    r"(?P<s>[a-z]+(?: [a-z]+)?)(?: with (?:her|him|them))?(?P<end>\s*[.!]?)$",
    _F,
)


def _better_down34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): after a correction cue, "better down on the play mat (with her)" is "on
    the play mat" (S one surface)."""
    m = _BETTER_DOWN34R.search(text)
    if m is None or not _whole_name(m["s"], lexicon, "surface"):
        return text
    return f"{text[: m.start()]}{m['cue']}{m['p']} the {m['s']}{m['end'] or '.'}"


# "Over to Person B with the chips, no, I mean the bottle, it's the bottle she's after."
_OVER_WITH_FIXED34R = re.compile(
    r"^over to (?P<p>[a-z][\w ]*?) with (?P<x>the [a-z]+(?: [a-z]+)?)"
    rf"(?P<rest>,\s*(?:hmm,\s*|oh,\s*)?(?:{_CUE34R})\b.+)$",
    _F,
)


def _over_with_fixed34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): "Over to P with X, no, I mean Y" is "X to P, no, I mean Y": the
    correction then replaces the object (it had left 'to P with Y', refused)."""
    m = _OVER_WITH_FIXED34R.match(text)
    if m is None or not _only_person(m["p"], lexicon) or not _objects34r(lexicon, m["x"]):
        return text
    return f"The {m['x'][4:]} to {m['p']}{m['rest']}"


# "Both of the mugs are Alice's, give her the pair."
_ARE_HERS34R = re.compile(
    r"^(?P<q>both|all (?:two|three|four)) of the (?P<k>[a-z]+) are (?P<p>[a-z][\w ]*?)'s,\s*"
    r"(?:so )?give (?P<pro>her|him) (?:the pair|both|them|the lot|all of them|the two)"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _are_hers34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): "Both of the mugs are Alice's, give her the pair" is "Give Alice both
    of the mugs" (the pronoun may be P; the count read by the grammar)."""
    m = _ARE_HERS34R.match(text)
    if m is None or not _the_person(m["p"], m["pro"], lexicon):
        return text
    if not _ids(m["k"], lexicon, "object"):
        return text
    return f"Give {m['p']} {m['q'].lower()} of the {m['k']}{m['end'] or '.'}"


# "Two things going out: Person A has the chips and the bottle is Person B's."
_GOING_OUT34R = re.compile(
    r"^(?P<n>two|three|four) things going out\s*:\s*(?P<rest>.+)$",
    _F,
)
_IS_HERS34R = re.compile(
    r"(?P<lead>^|\band |,\s*)(?P<x>the [a-z]+(?: [a-z]+)?) is (?P<p>[a-z][\w ]*?)'s(?=\s*(?:[.!,]|"
    r"\band\b|$))",
    _F,
)


def _going_out34r(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12r): a heading "Two things going out:" is "Two things:" (session 30's count,
    checked against the tasks), and in the tasks under it "the bottle is Person B's" says who it
    goes to: "Person B gets the bottle" (one person, one whole object)."""
    m = _GOING_OUT34R.match(text)
    if m is None:
        return text

    def goes(w: re.Match[str]) -> str:
        if not _only_person(w["p"], lexicon) or not _whole_name(w["x"], lexicon, "object"):
            return w.group(0)
        return f"{w['lead']}{w['p']} gets {w['x']}"

    return f"{m['n']} things: {_IS_HERS34R.sub(goes, m['rest'])}"


# -- session 35 (12r): blind33's choices, counts, negation, exclusions and corrections ----------

# "Person A's the au pair, she can take the cup or the apple": a pronoun that can take objects
_PRONOUN_TAKE35R = re.compile(
    r"(?P<lead>(?:^|[,;]\s*|\bso\s+))(?P<pro>she|he) can take (?P<what>[^,.;!?]+?)"
    r"(?=\s*(?:[,.;!?]|$))",
    _F,
)
_WHERE35R = re.compile(r"\b(?:to|for|on|onto|in|into|over|across|back|up|down|off)\b", _F)


def _pronoun_take35r(text: str, lexicon: Lexicon) -> str:
    """Session 35 (12r): "…, she can take the cup or the apple" is "she can have …" (as "P can
    take X" reads 'P gets X'): objects only after it, nothing saying to whom or where (else
    left: "she can take the cup to Person B" is refused)."""
    if " can take " not in text.lower():
        return text

    def have(m: re.Match[str]) -> str:
        what = m["what"]
        if not _objects_only(what, lexicon) or _WHERE35R.search(what):
            return m[0]
        return f"{m['lead']}{m['pro']} can have {what}"

    return _PRONOUN_TAKE35R.sub(have, text)


# "she really doesn't mind which": an intensifier inside a phrase leaving the choice
_REALLY_MIND35R = re.compile(
    r"\b(?P<who>she|he|they|i|we) (?:really|honestly|truly|genuinely) (?P<neg>doesn't|don't|"
    r"does not|do not) mind which\b",
    _F,
)


def _really_mind35r(text: str, _lexicon: Lexicon) -> str:
    """Session 35 (12r): "she really doesn't mind which" is "she doesn't mind which" (the
    choice left to the robots, as before, said with an intensifier)."""
    if "mind which" not in text.lower():
        return text
    return _REALLY_MIND35R.sub(lambda m: f"{m['who']} {m['neg']} mind which", text)


# "They're to have one thing apiece, so …", "A single thing for each of them, so …"
_APIECE35R = re.compile(
    r"^(?:(?:(?:they|both of them|the two of them)(?:'re| are) to (?:have|get) )?(?:one|a single) "
    r"thing (?:apiece|each|for each of them)|(?:they|both of them|the two of them) each (?:get|"
    r"have) (?:a|one|a single) thing)\s*,\s*(?=so\b)",
    _F,
)
# "… so the bottle finds Person A and the chips find Person B"
_FINDS35R = re.compile(
    r"(?P<x>\bthe [a-z]+(?: [a-z]+)?) finds? (?P<p>person [a-z]|[a-z]+)(?=\s*(?:[,.;!?]|\band\b|"
    r"$))",
    _F,
)


def _apiece35r(text: str, lexicon: Lexicon) -> str:
    """Session 35 (12r): a heading "They're to have one thing apiece, so", "A single thing for
    each of them, so" or "They each get a thing, so" is "One thing apiece, so" (the count checked
    against the tasks, as
    that heading is: each person named once); in the tasks after it "the bottle finds Person A"
    is "the bottle goes to Person A" (a whole object, one person)."""
    m = _APIECE35R.match(text)
    if m is None:
        return text
    rest = text[m.end() :]

    def goes(f: re.Match[str]) -> str:
        if not _whole_name(f["x"], lexicon, "object") or not _only_person(f["p"], lexicon):
            return f[0]
        return f"{f['x']} goes to {f['p']}"

    return f"One thing apiece, {_FINDS35R.sub(goes, rest)}"


# "Whichever robot's idle can fetch the bottle for Person A": the robots choose among themselves
_WHICH_ROBOT35R = re.compile(
    r"^(?:whichever|any) (?:robot|arm|one of you|of you)(?:'s| is) (?:idle|free|available|not "
    r"busy|nearest|closest|nearer|closer) (?:can|could|should|may|will) (?P<rest>.+)$",
    _F,
)


def _which_robot35r(text: str, lexicon: Lexicon) -> str:
    """Session 35 (12r): "Whichever robot's idle can fetch X for P" is "Fetch X for P": which
    robot does it is the cell's choice, so saying it leaves the request as it is."""
    m = _WHICH_ROBOT35R.match(text)
    if m is None:
        return text
    return m["rest"][:1].upper() + m["rest"][1:]


# "any of the pens will do for him": the choice, then who it is for
_WILL_DO_FOR35R = re.compile(
    r"\b(?P<x>any(?: one)? of the (?P<k>[a-z]+)) will do (?P<p>for|to) ",
    _F,
)


def _will_do_for35r(text: str, lexicon: Lexicon) -> str:
    """Session 35 (12r): "any of the pens will do for him" is "any of the pens for him" (the
    choice among the scene's objects of that kind, for the person named after it)."""
    if " will do " not in text.lower():
        return text

    def said(m: re.Match[str]) -> str:
        if not _only_kind(m["k"], lexicon, "object"):
            return m[0]
        return f"{m['x']} for "

    return _WILL_DO_FOR35R.sub(said, text)


# "whichever spanner's handy"
_HANDY35R = re.compile(r"\bwhichever (?P<k>[a-z]+)(?:'s| is) handy\b", _F)


def _handy35r(text: str, lexicon: Lexicon) -> str:
    """Session 35 (12r): "whichever spanner's handy" is "whichever spanner's to hand" (the
    robots' pick of any one of that kind, as 'whichever spanner is to hand' reads)."""
    if "handy" not in text.lower():
        return text
    return _HANDY35R.sub(
        lambda m: f"whichever {m['k']} is to hand" if _ids(m["k"], lexicon, "object") else m[0],
        text,
    )


# "There's just the one bottle here and it's meant for Person A"
_THE_ONE35R = re.compile(
    r"^there(?:'s| is) (?:just |only )?the one (?P<k>[a-z]+)(?: here)? and it(?:'s| is) "
    r"(?:meant |intended )?for (?P<p>[^,.;!?]+?)(?P<rest>\s*(?:[,.;!?].*)?)$",
    _F,
)


# "There's just the single bottle, so hand that to Person A, …"
_THE_SINGLE35R = re.compile(
    r"^there(?:'s| is) (?:just |only )?the (?:one|single|lone) (?P<k>[a-z]+)(?: here)?,\s*so "
    r"(?P<v>hand|give|pass|take|bring) (?:that|it)(?: one)? (?:over |across )?to (?P<p>[^,.;!?]+?)"
    r"(?P<rest>\s*(?:[,.;!?].*)?)$",
    _F,
)


def _the_one35r(text: str, lexicon: Lexicon) -> str:
    """Session 35 (12r): "There's just the one bottle here and it's meant for P" is "The bottle
    is for P", "There's just the single bottle, so hand that to P" is "Hand the bottle to P", when
    the scene has one bottle (the count must agree: with two it is left, and refused)."""
    m = _THE_ONE35R.match(text) or _THE_SINGLE35R.match(text)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    if len(_ids(f"the {m['k']}s", lexicon, "object")) != 1 or not _only_kind(
        m["k"], lexicon, "object"
    ):
        return text
    if m.re is _THE_SINGLE35R:
        return f"{m['v'][:1].upper()}{m['v'][1:]} the {m['k']} to {m['p']}{m['rest']}"
    return f"The {m['k']} is for {m['p']}{m['rest']}"


# ", after her gymnastics" closing a request: when, as a remark naming nothing of the scene
_AFTER_HER35R = re.compile(
    r",\s*after (?P<w>(?:her|his|their) (?:[a-z]+ )?(?:[a-z]+(?:ing|ics)|class|lesson|"
    r"practice|training|shift|session|match|game|nap|walk|swim|workout|rehearsal|appointment|"
    r"meeting|exam|lecture|visit|round))(?P<end>\s*[.!]?)$",
    _F,
)


# what the remark follows: a state of who the thing is for ("The bottle is (meant) for Person A")
_FOR_P35R = re.compile(
    r"\b(?:is|are|'s|'re) (?:meant |intended |just )?for (?:person [a-z]|[a-z]+)$", _F
)


def _after_her35r(text: str, lexicon: Lexicon) -> str:
    """Session 35 (12r): "The bottle is (meant) for P, after her gymnastics": after a comma, what
    the thing is for is when she will use it, a remark (said after a request, "Give Carol the
    apple after her walk", it is a time, and refused: session 34's near forms), taken off when it
    names an activity (a word in -ing or -ics, 'class', 'shift', 'nap', …) and nothing of the
    scene; "…, after her bottle" (an object: an order) or "…, after her pills" (a thing the scene
    lacks) is left."""
    m = _AFTER_HER35R.search(text) if "after" in text.lower() else None
    if m is None or _ids(m["w"], lexicon) or not _FOR_P35R.search(text[: m.start()]):
        return text
    if not _asks_nothing29(m["w"].split(" ", 1)[1], lexicon):  # the pronoun aside
        return text
    return f"{text[: m.start()]}{m['end'] or '.'}"


# "Those two cups are filthy, put the pair of them in the sink to soak."
_COUNTED_STATE35R = re.compile(
    r"^(?:those|these|the|both) (?P<n>two|three|four) (?P<k>[a-z]+) (?:are|'re) (?P<adj>[a-z]+)"
    r"\s*,\s*(?:so )?(?P<v>put|pop|stick|place|set|take|bring|move) (?P<them>the pair of them|"
    r"both of them|them|all (?:two|three|four) of them|the (?:two|three|four) of them) "
    r"(?P<rest>.+)$",
    _F,
)


def _counted_state35r(text: str, lexicon: Lexicon) -> str:
    """Session 35 (12r): "Those two cups are filthy, put the pair of them in the sink" is "Put the
    two cups in the sink" (the state names nothing of the scene; 'the pair' only of two, 'all
    three of them' only of three; the count read against the scene by the grammar)."""
    m = _COUNTED_STATE35R.match(text)
    if m is None or _ids(m["adj"], lexicon) or not _ids(m["k"], lexicon, "object"):
        return text
    them, n = m["them"].lower(), m["n"].lower()
    if (them == "the pair of them" or them == "both of them") and n != "two":
        return text
    if them not in ("the pair of them", "both of them", "them") and n not in them:
        return text
    return f"{m['v'][:1].upper()}{m['v'][1:]} the {n} {m['k']} {m['rest']}"


# "Gather up all three pens and drop them in the box"
_GATHER35R = re.compile(
    r"^(?:gather|collect|round|pick) up (?P<x>[^,.;!?]+?) and (?:drop|put|pop|stick|place|"
    r"pack) (?:them|it|the lot) (?P<prep>in|into|on|onto) (?P<s>the [a-z]+(?: [a-z]+)?)"
    r"(?P<rest>(?:[,.;!?].*)?)$",
    _F,
)


def _gather35r(text: str, lexicon: Lexicon) -> str:
    """Session 35 (12r): "Gather up X and drop them in S" is "Put X in S" ('drop' here the end of
    a gathering, not a request dropped; X objects only, S one surface)."""
    m = _GATHER35R.match(text)
    if m is None or not _objects_only(m["x"], lexicon):
        return text
    if not _whole_name(m["s"], lexicon, "surface"):
        return text
    return f"Put {m['x']} {m['prep']} {m['s']}{m['rest']}"


# "Load the belt with every box we've got, all three, …"
_LOAD_WITH35R = re.compile(
    r"^load (?P<s>the [a-z]+(?: [a-z]+)?) (?:up )?with (?P<x>every [a-z]+|all the [a-z]+)"
    r"(?: (?:we've got|we have|we've|there is|there are|in here))?(?:\s*,\s*all (?P<n>two|three|"
    r"four|five|six)\b)?(?P<rest>(?:[,.;!?].*)?)$",
    _F,
)
_NUMBER35R = {"two": 2, "three": 3, "four": 4, "five": 5, "six": 6}


def _load_with35r(text: str, lexicon: Lexicon) -> str:
    """Session 35 (12r): "Load the belt with every box (we've got), all three" is "Put every box
    on the belt" when the scene has that many boxes (a count that does not agree is left, and
    refused)."""
    m = _LOAD_WITH35R.match(text)
    if m is None or not _whole_name(m["s"], lexicon, "surface"):
        return text
    ids = _ids(m["x"], lexicon, "object")
    if not ids or not _objects_only(m["x"], lexicon):
        return text
    if m["n"] and len(ids) != _NUMBER35R[m["n"].lower()]:
        return text
    return f"Put {m['x']} on {m['s']}{m['rest']}"


# "Both spanners, the big one and the small one, go away in the locker."
_BOTH_NAMED35R = re.compile(
    r"^(?P<head>both (?P<k>[a-z]+)),\s*the (?P<a>[a-z]+) one and the (?P<b>[a-z]+) one,\s*"
    r"(?P<v>go|goes)(?: away)? (?P<rest>(?:in|into|on|onto) .+)$",
    _F,
)


def _both_named35r(text: str, lexicon: Lexicon) -> str:
    """Session 35 (12r): "Both spanners, the big one and the small one, go (away) in S" is "Both
    spanners go in S" when the two named are the two of that kind (else left, and refused)."""
    m = _BOTH_NAMED35R.match(text)
    if m is None:
        return text
    k = m["k"]
    every = _ids(f"the {k}", lexicon, "object")
    one = k[:-1] if k.lower().endswith("s") else k
    a = _ids(f"the {m['a']} {one}", lexicon, "object")
    b = _ids(f"the {m['b']} {one}", lexicon, "object")
    if len(every) != 2 or len(a) != 1 or len(b) != 1 or a | b != every:
        return text
    return f"{m['head']} go {m['rest']}"


# "… and leave the bottle be"
_LEAVE_BE35R = re.compile(
    r"^(?P<head>.+?)\s*(?:,\s*)?(?:and |but )?leave (?P<x>the [a-z]+(?: [a-z]+)?) (?:be|alone)"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _leave_be35r(text: str, lexicon: Lexicon) -> str:
    """Session 35 (12r): "…, and leave the bottle be (alone)" after tasks that do not name the
    bottle: nothing to do for it (as "the apple stays where it is"; one the tasks name is left,
    refused)."""
    m = _LEAVE_BE35R.match(text) if "leave" in text.lower() else None
    if m is None or not _whole_name(m["x"], lexicon, "object"):
        return text
    if _ids(m["x"], lexicon) & _ids(m["head"], lexicon) or not _ids(m["head"], lexicon, "object"):
        return text
    return f"{m['head']}{m['end'] or '.'}"


# "…, though the apple stays where it is"
_THOUGH_STAYS35R = re.compile(
    r",\s*(?:though|but|while|whereas) (?=(?:the )?[a-z]+(?: [a-z]+)? stays (?:where it is|put|"
    r"as it is)\s*[.!]?$)",
    _F,
)


def _though_stays35r(text: str, _lexicon: Lexicon) -> str:
    """Session 35 (12r): "…, though the apple stays where it is" is "…, the apple stays where it
    is" (read by _stays_put34r: nothing to do for an object the tasks do not name)."""
    if "stays" not in text.lower():
        return text
    return _THOUGH_STAYS35R.sub(", ", text)


# "she brought her own flask", "he's got wipes of his own": why the person needs no more
_OWN35R = re.compile(
    r"^(?P<head>.+?),\s*(?P<pro>she|he)(?:'s| has)? (?:brought|got|has) (?:(?:her|his) own "
    r"(?P<a>[a-z]+)|(?P<b>[a-z]+) of (?:her|his) own)(?P<end>\s*[.!]?)$",
    _F,
)


def _own35r(text: str, lexicon: Lexicon) -> str:
    """Session 35 (12r): "…, she brought her own flask" / "he's got wipes of his own" closing a
    request for one person she (he) may be: why that person needs nothing more, taken off when
    the thing is not among what the request is read to hand over (else left, and refused)."""
    m = _OWN35R.match(text) if "own" in text.lower() else None
    if m is None:
        return text
    head, what = m["head"], m["a"] or m["b"]
    people = _ids(head, lexicon, "human")
    if len(people) != 1 or not _fits(next(iter(people)), m["pro"], lexicon):
        return text
    done = _tasks_of(head, lexicon)
    if not done or _ids(what, lexicon) & {t[1] for t in done}:
        return text  # "…, she brought her own bottle" after a request that gives her the bottle
    return f"{head}{m['end'] or '.'}"


# "Person A's allergic, so the apple goes to Person B instead."
_INSTEAD35R = re.compile(
    r"^(?P<p>[^,;]+?)(?:'s| is) (?P<adj>[a-z]+),\s*so (?P<rest>.+?),? instead(?P<end>\s*[.!]?)$",
    _F,
)


def _instead35r(text: str, lexicon: Lexicon) -> str:
    """Session 35 (12r): "P's allergic, so the apple goes to Q instead": 'instead' of P, said
    just before (a state naming nothing else), not of a running task: taken off when what
    follows 'so' reads as tasks for people other than P."""
    m = _INSTEAD35R.match(text) if "instead" in text.lower() else None
    if m is None or not _only_person(m["p"], lexicon) or _ids(m["adj"], lexicon):
        return text
    out = f"{m['p']}'s {m['adj']}, so {m['rest']}{m['end'] or '.'}"
    done = _tasks_of(m["rest"], lexicon)
    p = next(iter(_ids(m["p"], lexicon)))
    if not done or any(t[0] != "deliver" or t[2] == p for t in done):
        return text
    return out


# "…, so the bottle's hers"
_HERS35R = re.compile(
    r"(?P<lead>,\s*so )(?P<x>the [a-z]+(?: [a-z]+)?)(?:'s| is) (?P<pro>hers|his)(?P<end>\s*[.!]?)$",
    _F,
)


def _hers35r(text: str, lexicon: Lexicon) -> str:
    """Session 35 (12r): "…, so the bottle's hers" is "…, so give her the bottle" (one whole
    object; who 'her' is the grammar reads as for 'give her')."""
    m = _HERS35R.search(text) if "so the" in text.lower() else None
    if m is None or not _whole_name(m["x"], lexicon, "object"):
        return text
    pro = "her" if m["pro"].lower() == "hers" else "him"
    return f"{text[: m.start()]}{m['lead']}give {pro} {m['x']}{m['end'] or '.'}"


# "Only the bottle, and only to Person A, no other jobs for now."
_ONLY_TO35R = re.compile(
    r"^(?:only|just) (?P<x>the [a-z]+(?: [a-z]+)?),\s*and (?:only|just) (?:to|for) "
    r"(?P<p>[^,.;!?]+?)(?:,\s*(?:no other jobs|nothing else|no other tasks)(?: for now)?)?"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _only_to35r(text: str, lexicon: Lexicon) -> str:
    """Session 35 (12r): "Only the bottle, and only to P(, no other jobs for now)" is "Just the
    bottle for P" (one whole object, one person; nothing else asked)."""
    m = _ONLY_TO35R.match(text)
    if m is None or not _whole_name(m["x"], lexicon, "object"):
        return text
    if not _only_person(m["p"], lexicon):
        return text
    return f"Just {m['x']} for {m['p']}{m['end'] or '.'}"


# "Apart from the two cups, load every item onto the tray."
_FRONTED_EVERY35R = re.compile(
    r"^(?P<open>(?:except(?: for)?|apart from|other than|bar|aside from) [^,.;:!?]+,\s*[^.;:!?]*?)"
    r"\bevery (?:item|thing|object|single thing)\b",
    _F,
)


def _fronted_every35r(text: str, lexicon: Lexicon) -> str:
    """Session 35 (12r): "Apart from X, load every item onto S": 'every item' is 'everything'
    (read by _fronted_except28r as "load everything except X onto S")."""
    m = _FRONTED_EVERY35R.match(text) if "every" in text.lower() else None
    if m is None:
        return text
    # "Apart from the two cups": the count checked against the scene (_excluded_count)
    return _excluded_count(f"{m['open']}everything{text[m.end() :]}", lexicon)


# "It's the bottle Alice wants, not the crisps, she's off to her knitting circle."
_CLEFT_NOT_THEN35R = re.compile(
    r"^(?P<c>it(?:'s| is) the [a-z ]+? (?:wants|needs|asked for|would like),\s*not the "
    r"[a-z ]+?),\s*(?P<rest>[^,.;!?]+?(?P<end>\s*[.!]?))$",
    _F,
)


def _cleft_not_then35r(text: str, lexicon: Lexicon) -> str:
    """Session 35 (12r): "It's the X P wants, not the Y, <remark>" is "P wants the X, not the Y,
    <remark>" (_cleft_not29r's reading of the cleft), when the remark names nothing of the scene
    (the remark rules then take it off, or it is refused)."""
    m = _CLEFT_NOT_THEN35R.match(text)
    if m is None or _ids(m["rest"], lexicon):
        return text
    said = _cleft_not29r(m["c"], lexicon)
    return text if said == m["c"] else f"{said}, {m['rest']}"


# corrections -------------------------------------------------------------------------------------

# "oops, I've gone and got it wrong, Bob's the one who ordered them"
_GOT_WRONG35R = re.compile(
    r"(?P<cue>\b(?:oops|whoops|sorry|oh|hang on|wait)),\s*i(?:'ve| have)? (?:gone and )?"
    r"(?:got|had) (?:it|that|them) wrong,\s*(?P<p>[^,.;!?]+?)(?:'s| is) the one who "
    r"(?P<v>ordered|wanted|asked for|wants|needs|needed) (?P<it>it|them)(?P<end>\s*[.!]?)$",
    _F,
)


def _got_wrong35r(text: str, lexicon: Lexicon) -> str:
    """Session 35 (12r): "…, oops, I've gone and got it wrong, Bob's the one who ordered them" is
    "…, oops, no, it's Bob who ordered them" (a correction: the person said after it is the one
    the object goes to, as that cleft reads)."""
    m = _GOT_WRONG35R.search(text) if "wrong" in text.lower() else None
    if m is None or not _only_person(m["p"], lexicon):
        return text
    return (
        f"{text[: m.start()]}{m['cue']}, no, it's {m['p']} who {m['v']} {m['it']}{m['end'] or '.'}"
    )


# "actually, no, Alice would rather have it in her hand"
_RATHER_HAVE35R = re.compile(
    r"(?P<cue>\bno),\s*(?P<p>[^,.;!?]+?) would (?:rather|prefer to) have (?P<it>it|them)"
    r"(?: in (?:her|his|their) hands?)?(?P<end>\s*[.!]?)$",
    _F,
)


def _rather_have35r(text: str, lexicon: Lexicon) -> str:
    """Session 35 (12r): after a correction cue "no, Alice would rather have it (in her hand)" is
    "no, give it to Alice" (the correction makes it a handover to her)."""
    m = (
        _RATHER_HAVE35R.search(text)
        if "rather" in text.lower() or "prefer" in text.lower()
        else None
    )
    if m is None or not _the_person(m["p"], m[0], lexicon):
        return text
    return f"{text[: m.start()]}{m['cue']}, give {m['it']} to {m['p']}{m['end'] or '.'}"


# "Hang about, no, it's Person A who's getting it."
_WHO_GETTING35R = re.compile(
    r"(?P<cue>\b(?:hang about|hang on|hold on|wait)),\s*no,\s*it(?:'s| is) (?P<p>[^,.;!?]+?) "
    r"who(?:'s| is) getting (?P<it>it|them)(?P<end>\s*[.!]?)$",
    _F,
)


def _who_getting35r(text: str, lexicon: Lexicon) -> str:
    """Session 35 (12r): "Hang about, no, it's P who's getting it" is "Hang on, no, it's P who gets
    it" (the correction's cleft, read as before)."""
    m = _WHO_GETTING35R.search(text) if "getting" in text.lower() else None
    if m is None or not _only_person(m["p"], lexicon):
        return text
    return f"{text[: m.start()]}Hang on, no, it's {m['p']} who gets {m['it']}{m['end'] or '.'}"


# "…, oh wait, I meant the bottle for her."
_MEANT_FOR35R = re.compile(
    r"(?P<said>\bi meant (?P<x>the [a-z]+(?: [a-z]+)?)) for (?P<pro>her|him)(?P<end>\s*[.!]?)$",
    _F,
)


def _meant_for35r(text: str, lexicon: Lexicon) -> str:
    """Session 35 (12r): "P's getting X, oh wait, I meant Y for her" is "…, I meant Y" when 'her'
    may be P, the one person the request names (the correction swaps the object only)."""
    m = _MEANT_FOR35R.search(text) if "meant" in text.lower() else None
    if m is None or not _whole_name(m["x"], lexicon, "object"):
        return text
    people = _ids(text[: m.start()], lexicon, "human")
    if len(people) != 1 or not _may_be35t(next(iter(people)), m["pro"], lexicon):
        return text
    return f"{text[: m.start()]}{m['said']}{m['end'] or '.'}"


# "Take the bottle over to Person B, or rather Person A, I keep mixing them up."
_RATHER_PERSON35R = re.compile(
    r"\b(?P<prep>to|for) (?P<p1>person [a-z])\s*,\s*(?:or rather|no|sorry|i mean),?\s+"
    r"(?P<p2>person [a-z]|[a-z]+)(?:\s*,\s*i (?:keep|always) (?:mixing|getting) them (?:up|"
    r"mixed up|muddled))?(?P<end>\s*[.!]?)$",
    _F,
)


def _rather_person35r(text: str, lexicon: Lexicon) -> str:
    """Session 35 (12r): "… to Person B, or rather Person A(, I keep mixing them up)" where the
    scene has no Person B: the label corrected away was a slip, and the request is "… to Person
    A" (the second one person of the scene; one the scene has is left to the grammar)."""
    m = _RATHER_PERSON35R.search(text) if "person" in text.lower() else None
    if m is None or not _only_person(m["p2"], lexicon):
        return text
    said = m["p1"].lower()
    if any(
        h.name.lower() == said or f"person {h.id.lower()}" == said for h in lexicon.scene.humans
    ):
        return text
    return f"{text[: m.start()]}{m['prep']} {m['p2']}{m['end'] or '.'}"


# "…, no, hang on, I had them the wrong way about: Person B's chips."
_WRONG_WAY35R = re.compile(
    r"(?P<cue>\bno,\s*(?:hang on|hold on|wait),)\s*i (?:had|got|put) (?:it|them|that) the wrong "
    r"way (?:about|round|around)\s*[:,;]\s*",
    _F,
)


def _wrong_way35r(text: str, _lexicon: Lexicon) -> str:
    """Session 35 (12r): "no, hang on, I had them the wrong way about: P's X" is "no, hang on,
    P's X" (what was got wrong, said before what it is)."""
    if "wrong way" not in text.lower():
        return text
    return _WRONG_WAY35R.sub(lambda m: f"{m['cue']} ", text)


# "Priya was to get the stapler, but change that, Sam's doing the filing, so him."
_CHANGE_THAT35R = re.compile(
    r"^(?P<p1>[a-z]+(?: [a-z]+)?) was (?:to get|getting|going to get|meant to get|to have) "
    r"(?P<x>the [a-z]+(?: [a-z]+)?),\s*but (?:change that|scratch that|no),\s*(?P<p2>[a-z]+"
    r"(?: [a-z]+)?)(?:'s| is) (?P<why>[^,.;!?]+?),\s*so (?P<pro>him|her)(?P<end>\s*[.!]?)$",
    _F,
)


def _change_that35r(text: str, lexicon: Lexicon) -> str:
    """Session 35 (12r): "P was to get X, but change that, Q's doing the filing, so him" is "Give X
    to Q" (P and Q two people, 'him' may be Q, the reason naming nothing of the scene)."""
    m = _CHANGE_THAT35R.match(text)
    if m is None or not _persons34r(lexicon, m["p1"], m["p2"]):
        return text
    if not _whole_name(m["x"], lexicon, "object") or _ids(m["why"], lexicon):
        return text
    if not _fits(next(iter(_ids(m["p2"], lexicon))), m["pro"], lexicon):
        return text
    return f"Give {m['x']} to {m['p2']}{m['end'] or '.'}"


# "whoops, no, it belongs to Lily, give it to her"
_BELONGS35R = re.compile(
    r"(?P<cue>\bno),\s*(?:it|they) (?:belongs?|is|are|'s) (?:to )?(?P<p>[^,.;!?]+?)(?:'s)?,\s*"
    r"(?P<v>give|hand|pass|take) (?P<it>it|them) (?:back )?to (?P<pro>her|him)(?P<end>\s*[.!]?)$",
    _F,
)


def _belongs35r(text: str, lexicon: Lexicon) -> str:
    """Session 35 (12r): after 'no', "it belongs to Lily, give it to her" is "give it to Lily"
    ('her' may be Lily, one person)."""
    m = _BELONGS35R.search(text) if "belong" in text.lower() else None
    if m is None or not _the_person(m["p"], m["pro"], lexicon):
        return text
    return f"{text[: m.start()]}{m['cue']}, {m['v']} {m['it']} to {m['p']}{m['end'] or '.'}"


# blind20's kinds -----------------------------------------------------------------------------

# "Sorry, it's gone three in the morning and I'm the only one on the floor. …"
_LATE_ALONE35R = re.compile(
    r"^(?:sorry,\s*)?(?P<said>[^.!?]+)\.\s+(?P<rest>\S.*)$",
    _F,
)
_LATE35R = re.compile(
    r"it(?:'s| is) (?:gone|past|nearly|almost|after) (?:one|two|three|four|five|six|seven|eight|"
    r"nine|ten|eleven|twelve|midnight|midday|noon|[0-9]{1,2})(?: (?:in the morning|at night|"
    r"o'clock|already))?",
    _F,
)
_ALONE35R = re.compile(
    r"(?:i'm|i am) (?:the only one|on my own|by myself|alone) (?:on|in) (?:the )?"
    r"(?P<w>[a-z]+(?: [a-z]+)?)",
    _F,
)


def _late_alone35r(text: str, lexicon: Lexicon) -> str:
    """Session 35 (12r): a first sentence that says only the time of night and that the speaker is
    alone ("Sorry, it's gone three in the morning and I'm the only one on the floor.") asks nothing
    and is taken off before the request (its place naming nothing of the scene; 'only one' there
    is the speaker, no count)."""
    m = _LATE_ALONE35R.match(text) if "it" in text.lower() else None
    if m is None:
        return text
    for part in re.split(r",\s*(?:and\s+)?|\s+and\s+", m["said"].strip(), flags=_F):
        alone = _ALONE35R.fullmatch(part)
        if alone is not None and _ids(alone["w"], lexicon):
            return text
        if alone is None and _LATE35R.fullmatch(part) is None:
            return text
    return m["rest"][:1].upper() + m["rest"][1:]


# "Person A takes the bottle off you."
_TAKES_OFF35R = re.compile(
    r"\b(?P<p>person [a-z]|[a-z]+) takes (?P<x>the [a-z]+(?: [a-z]+)?) (?:off|from) (?:you|the "
    r"robots?|the arms?)\b",
    _F,
)


def _takes_off35r(text: str, lexicon: Lexicon) -> str:
    """Session 35 (12r): "P takes the bottle off you" is "P gets the bottle" (a handover said from
    the person's side; one person, one whole object)."""
    if " takes " not in text.lower():
        return text

    def gets(m: re.Match[str]) -> str:
        if not _only_person(m["p"], lexicon) or not _whole_name(m["x"], lexicon, "object"):
            return m[0]
        return f"{m['p']} gets {m['x']}"

    return _TAKES_OFF35R.sub(gets, text)


# "…. And for Person B, the cup."
_AND_FOR35R = re.compile(r"(?<=[.!?])\s+and for (?=(?P<p>person [a-z]|[a-z]+),\s*the )", _F)


def _and_for35r(text: str, lexicon: Lexicon) -> str:
    """Session 35 (12r): a sentence opening "And for P, the X" is "For P, the X" (the 'and' joins it
    to the sentence before; P one person)."""
    if "and for" not in text.lower():
        return text
    return _AND_FOR35R.sub(lambda m: " For " if _only_person(m["p"], lexicon) else m[0], text)


# blind21's kinds -----------------------------------------------------------------------------

# "Person A gets the cup, or, ugh, my notes are smudged, the apple it says."
_IT_SAYS35R = re.compile(
    r",\s*or,\s*(?:(?:ugh|er|erm|um|hmm|oh),\s*)?(?:(?:my|the) notes? (?:are|is|'s) [a-z]+,\s*)?"
    r"(?P<x>the [a-z]+(?: [a-z]+)?) it says(?P<end>\s*[.!]?)$",
    _F,
)


def _it_says35r(text: str, lexicon: Lexicon) -> str:
    """Session 35 (12r): "…, or, ugh, my notes are smudged, the apple it says": what the notes say,
    read off after a doubt, corrects the object ("…, no, the apple"): 'it says' settles the 'or',
    which is no choice (one whole object, after one task)."""
    m = _IT_SAYS35R.search(text) if "it says" in text.lower() else None
    if m is None or not _whole_name(m["x"], lexicon, "object"):
        return text
    done = _tasks_of(text[: m.start()], lexicon)
    if done is None or len(done) != 1:
        return text  # which of several the notes correct is not said
    return f"{text[: m.start()]}, no, {m['x']}{m['end'] or '.'}"


# "For Person A, the chips. Er, hold on, she'd rather have the bottle, go with that."
_RATHER_AFTER35R = re.compile(
    r"^(?P<head>[^.!?]+)[.!]\s*(?:(?:er|erm|um|hmm|oh),?\s*)?(?:hold on|hang on|wait),\s*"
    r"(?P<pro>she|he)(?:'d| would) rather have (?P<x>the [a-z]+(?: [a-z]+)?)(?:,\s*go with "
    r"(?:that|it|that one))?(?P<end>\s*[.!]?)$",
    _F,
)


def _rather_after35r(text: str, lexicon: Lexicon) -> str:
    """Session 35 (12r): "<one handover>. Er, hold on, she'd rather have the bottle(, go with
    that)" is "<the handover>, no, the bottle": 'rather' says the object replaces the one asked
    for (a 'hold on' opening a sentence alone could also add), when 'she' may be the one person
    of the handover and the bottle is another object."""
    m = _RATHER_AFTER35R.match(text) if "rather" in text.lower() else None
    if m is None or not _whole_name(m["x"], lexicon, "object"):
        return text
    done = _tasks_of(m["head"], lexicon)
    if done is None or len(done) != 1:
        return text
    kind, obj, who = next(iter(done))
    if kind != "deliver" or obj in _ids(m["x"], lexicon) or not _fits(who, m["pro"], lexicon):
        return text
    return f"{m['head']}, no, {m['x']}{m['end'] or '.'}"


# "Lily likes both her blocks with her when she eats, so put the pair of them in the high chair."
_LIKES_BOTH35R = re.compile(
    r"^(?P<p>[a-z]+(?: [a-z]+)?) likes (?:both |the two of )?(?:her|his) (?P<k>[a-z]+s)(?: with "
    r"(?:her|him))?(?: when (?:she|he) [a-z]+)?,\s*so (?P<v>put|pop|place|set|stick) (?P<them>"
    r"the pair of them|both of them|the two of them|them) (?P<rest>(?:in|into|on|onto) .+)$",
    _F,
)


def _likes_both35r(text: str, lexicon: Lexicon) -> str:
    """Session 35 (12r): "Lily likes both her blocks (with her when she eats), so put the pair of
    them in S" is "Put both blocks in S" (why, naming one person, taken off; 'both' and 'the
    pair' read as two, checked against the scene by the grammar)."""
    m = _LIKES_BOTH35R.match(text)
    if m is None or not _only_person(m["p"], lexicon) or not _ids(m["k"], lexicon, "object"):
        return text
    return f"{m['v'][:1].upper()}{m['v'][1:]} both {m['k']} {m['rest']}"


# "Not apple. Bottle, for Person B, please."
_NOT_FIRST35R = re.compile(
    r"^not (?P<x>(?:the )?[a-z]+)\.\s*(?P<rest>[^.!?]+?)(?P<tail>\s*[.!].*)?$",
    _F,
)


def _not_first35r(text: str, lexicon: Lexicon) -> str:
    """Session 35 (12r): a first sentence "Not apple." before a request for another object is that
    request with ", not the apple" (one whole object; the request must name objects, not it)."""
    m = _NOT_FIRST35R.match(text)
    if m is None or not _whole_name(m["x"], lexicon, "object"):
        return text
    said = _ids(m["rest"], lexicon, "object")
    if not said or said & _ids(m["x"], lexicon):
        return text
    x = m["x"] if m["x"].lower().startswith("the ") else f"the {m['x']}"
    return f"{m['rest']}, not {x}{m['tail'] or '.'}"


# blind22's kinds -----------------------------------------------------------------------------

# "…, she's not fussed which, she only wants a brew."
_ONLY_WANTS35R = re.compile(
    r"(?P<head>\b(?:not fussed|not bothered|doesn't mind|don't mind|does not mind) which),\s*"
    r"(?:she|he|they) (?:only|just) wants? (?P<w>(?:a|an|some) [a-z]+(?: [a-z]+)?)"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _only_wants35r(text: str, lexicon: Lexicon) -> str:
    """Session 35 (12r): after a phrase leaving the choice ("…, she's not fussed which"), "she
    only wants a brew" says what for, naming nothing of the scene: taken off (a thing of the
    scene there is a want: left)."""
    m = _ONLY_WANTS35R.search(text) if "wants" in text.lower() else None
    if m is None or _ids(m["w"], lexicon) or not _asks_nothing29(m["w"].split(" ", 1)[1], lexicon):
        return text
    return f"{text[: m.end('head')]}{m['end'] or '.'}"


# "Give Person A the apple, there is only one only, don't worry."
_ONLY_ONE35R = re.compile(
    r"^(?P<head>[^,.;!?]+),\s*there(?:'s| is) only (?:the )?one(?: only)?(?:\s*,\s*(?:don't "
    r"worry|no worries|never mind))?(?P<end>\s*[.!]?)$",
    _F,
)


def _only_one35r(text: str, lexicon: Lexicon) -> str:
    """Session 35 (12r): "<one handover>, there is only one (only), don't worry": the count of the
    one object the request names, said again: taken off when the scene holds exactly one of its
    kind (else left, and refused)."""
    m = _ONLY_ONE35R.match(text) if "only" in text.lower() else None
    if m is None:
        return text
    done = _tasks_of(m["head"], lexicon)
    if done is None or len(done) != 1:
        return text
    obj = next(iter(done))[1]
    kind = next(o.category for o in lexicon.scene.objects if o.id == obj)
    if sum(o.category == kind for o in lexicon.scene.objects) != 1:
        return text
    return f"{m['head']}{m['end'] or '.'}"


# "…, but not the red one, that's the controller's and she's funny about it."
_NOT_THEIRS35R = re.compile(
    r"(?P<head>\bnot the [a-z]+ one),\s*(?:that's|that is|it's|it is) (?:the )?(?P<o>[a-z]+)'s"
    r"(?: and (?:she|he|they)(?:'s| is|'re| are) (?P<w>[a-z ]+?))?(?P<end>\s*[.!]?)$",
    _F,
)


def _not_theirs35r(text: str, lexicon: Lexicon) -> str:
    """Session 35 (12r): "…, but not the red one, that's the controller's (and she's funny about
    it)": why that one is left out, its owner no one of the scene and the rest naming nothing,
    taken off (an owner of the scene may be the one to get it: left)."""
    m = _NOT_THEIRS35R.search(text) if "'s" in text else None
    if m is None or _ids(m["o"], lexicon) or (m["w"] and _ids(m["w"], lexicon)):
        return text
    return f"{text[: m.end('head')]}{m['end'] or '.'}"


# "Don't give Bob the crisps, they're bad for his teeth, give him the bottle instead."
_DONT_INSTEAD35R = re.compile(
    r"^(?:don't|do not) (?P<v>give|hand|pass) (?P<p>[a-z]+(?: [a-z])?) (?P<x>the [a-z]+"
    r"(?: [a-z]+)?),\s*(?:(?P<why>[^,.;!?]+?),\s*)?(?:give|hand|pass) (?P<pro>him|her) "
    r"(?P<y>the [a-z]+(?: [a-z]+)?) instead(?P<end>\s*[.!]?)$",
    _F,
)


def _dont_instead35r(text: str, lexicon: Lexicon) -> str:
    """Session 35 (12r): "Don't give P X, <why>, give him Y instead" is "Give P Y, not X" (one
    person 'him' may be, two whole objects, the reason naming nothing of the scene)."""
    m = _DONT_INSTEAD35R.match(text) if "instead" in text.lower() else None
    if m is None or not _the_person(m["p"], m["pro"], lexicon):
        return text
    if not _objects34r(lexicon, m["x"], m["y"]) or (m["why"] and _ids(m["why"], lexicon)):
        return text
    return f"{m['v'][:1].upper()}{m['v'][1:]} {m['p']} {m['y']}, not {m['x']}{m['end'] or '.'}"


# "Give the bottle to whoever isn't Person A, I don't know the other one's name."
_WHOEVER_NOT35R = re.compile(
    r"\bto whoever (?:isn't|is not) (?P<p>person [a-z]|[a-z]+)(?=\s*(?:[,.!]|$))",
    _F,
)


def _whoever_not35r(text: str, lexicon: Lexicon) -> str:
    """Session 35 (12r): "to whoever isn't Person A" in a scene of two people is "to" the other one
    (with more people it is left, and refused; blind22's "…, I don't know the other one's name"
    stays refused: a rewrite may not take off the speaker's 'I don't know', offline.py's
    _DOUBT)."""
    m = _WHOEVER_NOT35R.search(text) if "whoever" in text.lower() else None
    people = lexicon.scene.humans
    if m is None or len(people) != 2 or not _only_person(m["p"], lexicon):
        return text
    said = next(iter(_ids(m["p"], lexicon)))
    other = next(h for h in people if h.id != said)
    return f"{text[: m.start()]}to {other.name}{text[m.end() :]}"


# "Tom can have anything but the tape and the boxes and the scanner, I'm not fussed what."
_ANYTHING_BUT35R = re.compile(
    r"^(?P<p>[a-z]+(?: [a-z])?) can have anything (?:but|except|other than) (?P<x>[^,.;!?]+?)"
    r"(?:,\s*(?:i'm|i am) not (?:fussed|bothered) (?:what|which))?(?P<end>\s*[.!]?)$",
    _F,
)


def _anything_but35r(text: str, lexicon: Lexicon) -> str:
    """Session 35 (12r): "P can have anything but X and Y (, I'm not fussed what)" is "P can have
    A or B", the scene's other objects (each named whole, every one of X and Y, two or more, a
    name of the scene's objects; one left is that one)."""
    m = _ANYTHING_BUT35R.match(text) if "anything" in text.lower() else None
    if m is None or not _only_person(m["p"], lexicon):
        return text
    items = [i.strip() for i in re.split(r",|\band\b", m["x"], flags=_F) if i.strip()]
    if len(items) < 2 or not all(_only_kind(i, lexicon, "object") for i in items):
        return text  # one thing left out is session 33's _anything_but33r
    out = {oid for i in items for oid in _ids(i, lexicon, "object")}
    said = [_object_said33r(o.id, lexicon) for o in lexicon.scene.objects if o.id not in out]
    if not said or any(x is None for x in said):
        return text
    listed = " or ".join(x for x in said if x)
    return f"{m['p']} can have {listed}{m['end'] or '.'}"


# "…, actually, on the desk is better, I keep losing it."
_KEEP_LOSING35R = re.compile(
    r"(?P<head>\b(?:no|sorry|actually)\b.*?),\s*i keep (?:losing|misplacing|forgetting|dropping)"
    r" (?:it|them)(?P<end>\s*[.!]?)$",
    _F,
)


def _keep_losing35r(text: str, _lexicon: Lexicon) -> str:
    """Session 35 (12r): after a correction, "I keep losing it" says why the speaker changed their
    mind: taken off (the correction is read as before)."""
    m = _KEEP_LOSING35R.search(text) if "keep" in text.lower() else None
    if m is None:
        return text
    return f"{text[: m.end('head')]}{m['end'] or '.'}"


# "Give Jess the spanner that isn't already sitting on the bench, she'll know why."
_ISNT_ON35R = re.compile(
    r"\bthat (?:isn't|is not) (?:already )?(?:sitting |lying |resting |left )?(?P<p>on|in) "
    r"(?P<s>the [a-z]+(?: [a-z]+)?)(?P<why>,\s*(?:she|he|they)(?:'ll| will) know why)?",
    _F,
)


def _isnt_on35r(text: str, lexicon: Lexicon) -> str:
    """Session 35 (12r): "the spanner that isn't already sitting on the bench" is "the spanner that
    is not on the bench" (session 34's reading of it), ", she'll know why" after it a remark."""
    m = (
        _ISNT_ON35R.search(text)
        if "that is" in text.lower() or "that isn't" in text.lower()
        else None
    )
    if m is None or not _whole_name(m["s"], lexicon, "surface"):
        return text
    return f"{text[: m.start()]}that is not {m['p']} {m['s']}{text[m.end() :]}"


# -- session 36 (12r): blind34's choices, counts, negation, exclusions and corrections ----------


def _the_one36r(words: str, pronoun: str, lexicon: Lexicon) -> bool:
    """Whether ``words`` name one person that he/she ``pronoun`` ('' for none) may be: by title,
    first name or a word for kin (session 35's check, used to rule a reading out)."""
    if not _only_person(words, lexicon):
        return False
    return not pronoun or _may_be35t(next(iter(_ids(words, lexicon))), pronoun, lexicon)


# "Bring Person B just one thing, the cup, the apple or the bottle": one thing, then the choice
_ONE_THING_LISTED36R = re.compile(
    r"\b(?:just |only )?(?:one|a single) (?:thing|item),\s*(?P<list>(?:the [a-z]+(?: [a-z]+)?,\s*)+"
    r"(?:the [a-z]+(?: [a-z]+)?,?\s*)?or (?:the [a-z]+(?: [a-z]+)?))(?=\s*(?:[,.;!?]|$))",
    _F,
)


def _one_thing_listed36r(text: str, lexicon: Lexicon) -> str:
    """Session 36 (12r): "one thing, the cup, the apple or the bottle" is "one of the cup, the
    apple or the bottle" (a choice among the objects listed after it, each named whole, the last
    joined by 'or'; a list joined by 'and' stays, and is refused: one thing, then several)."""
    if " or " not in text.lower():
        return text

    def one_of(m: re.Match[str]) -> str:
        said = [w for w in re.split(r",\s*|\s+or\s+", m["list"]) if w.strip()]
        if len(said) < 2 or not all(_whole_name(w, lexicon, "object") for w in said):
            return m[0]
        if len({i for w in said for i in _ids(w, lexicon)}) != len(said):
            return m[0]
        return f"one of {m['list']}"

    return _ONE_THING_LISTED36R.sub(one_of, text)


# "The apple goes to whichever of the two of them you reach first": the robots choose the person
_WHICHEVER_OF_THEM36R = re.compile(
    r"\bto whichever (?:one )?of (?P<two>the two of )?them (?:you (?:reach|get to|come to) first|"
    r"(?:is|'s) (?:nearer|nearest|closer|closest|handier))(?=\s*(?:[,.;!?]|$))",
    _F,
)


def _whichever_of_them36r(text: str, lexicon: Lexicon) -> str:
    """Session 36 (12r): "to whichever of (the two of) them you reach first / is nearer" is "to
    either of them" (the choice of person left to the robots, as 'either of them' leaves it);
    with "the two of them" only in a scene of two people."""
    if "whichever" not in text.lower():
        return text

    def either(m: re.Match[str]) -> str:
        if m["two"] and len(lexicon.scene.humans) != 2:
            return m[0]
        return "to either of them"

    return _WHICHEVER_OF_THEM36R.sub(either, text)


# "Either Person A or Person B, the bottle's for one of them, you choose."
_EITHER_THEN_ONE36R = re.compile(
    r"^either (?P<p>[a-z][\w ]*?) or (?P<q>[a-z][\w ]*?),\s*(?P<x>the [a-z]+(?: [a-z]+)?)"
    r"(?:'s| is) (?:for|going to) (?:one|either) of (?:them|the two)(?P<end>\s*(?:[,.;!?]|$))",
    _F,
)


def _either_then_one36r(text: str, lexicon: Lexicon) -> str:
    """Session 36 (12r): "Either P or Q, the X's for one of them" is "The X's for P or Q" (P and
    Q two people, the X one whole object)."""
    m = _EITHER_THEN_ONE36R.match(text)
    if m is None or not _persons34r(lexicon, m["p"], m["q"]):
        return text
    if not _whole_name(m["x"], lexicon, "object"):
        return text
    x = m["x"][:1].upper() + m["x"][1:]
    return f"{x} is for {m['p']} or {m['q']}{m['end']}{text[m.end() :]}"


# "Person B won't mind if it's the bottle or the chips, just bring him whichever's closer."
_MIND_IF36R = re.compile(
    r"^(?P<p>[a-z][\w ]*?) (?:won't|doesn't|wouldn't|will not|does not|would not) mind if "
    r"it(?:'s| is) (?P<x>the [a-z]+(?: [a-z]+)?) or (?P<y>the [a-z]+(?: [a-z]+)?),\s*(?:so )?"
    r"(?:just )?(?P<v>bring|give|take|hand) (?P<pro>him|her) whichever(?:'s| is) (?P<adj>closer|"
    r"nearer|nearest|closest|handier|easier)(?P<end>\s*[.!]?)$",
    _F,
)


def _mind_if36r(text: str, lexicon: Lexicon) -> str:
    """Session 36 (12r): "P won't mind if it's X or Y, just bring him whichever's closer" is
    "Bring P X or Y, whichever's closer" (P one person the pronoun may be; X and Y two objects,
    each whole)."""
    m = _MIND_IF36R.match(text)
    if m is None or not _the_one36r(m["p"], m["pro"], lexicon):
        return text
    if not _objects34r(lexicon, m["x"], m["y"]):
        return text
    v = m["v"][:1].upper() + m["v"][1:]
    return f"{v} {m['p']} {m['x']} or {m['y']}, whichever is {m['adj']}{m['end'] or '.'}"


# "Kofi says either spanner will do, he's not fussy."
_SAYS_WILL_DO36R = re.compile(
    r"^(?P<p>[a-z][\w ]*?) says (?P<x>(?:either|any) (?:one of the )?[a-z]+) (?:will|would) do"
    r"(?=\s*(?:[,.;!?]|$))",
    _F,
)


def _says_will_do36r(text: str, lexicon: Lexicon) -> str:
    """Session 36 (12r): "P says either spanner will do" is "Either spanner will do for P" (the
    choice is P's own, so it is for P: one person)."""
    m = _SAYS_WILL_DO36R.match(text)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    x = m["x"][:1].upper() + m["x"][1:]
    return f"{x} will do for {m['p']}{text[m.end() :]}"


# "One apiece: Person A is to have the chips and Person B the bottle"
_ONE_APIECE36R = re.compile(r"^one (?:apiece|each)\s*:\s*(?=\S)", _F)


def _one_apiece36r(text: str, _lexicon: Lexicon) -> str:
    """Session 36 (12r): a heading "One apiece:" / "One each:" before a list is "One thing
    apiece:" (session 28's heading: the list read alone only when it gives every person of the
    scene exactly one object)."""
    m = _ONE_APIECE36R.match(text)
    return text if m is None else f"One thing apiece: {text[m.end() :]}"


# "Two people, two things: the bottle's Person B's, and the chips are Person A's, hand them over."
_PEOPLE_THINGS36R = re.compile(
    r"^(?P<n>two|three|four) (?:people|persons),\s*(?P<m>two|three|four) (?:things|items)\s*:"
    r"\s*(?P<rest>.+?)(?:,\s*(?:and )?(?:hand|give|pass) (?:them|those) (?:over|out|round))?"
    r"(?P<end>\s*[.!]?)$",
    _F,
)
_WHOSE36R = re.compile(
    r"\b(?P<x>the [a-z]+(?: [a-z]+)?)(?:'s| is| are) (?P<p>[a-z][\w ]*?)'s\b", _F
)


def _people_things36r(text: str, lexicon: Lexicon) -> str:
    """Session 36 (12r): a heading "Two people, two things:" counts both: the list after it
    ("the bottle's Person B's, and the chips are Person A's", whose a thing is being who gets it;
    a closing "hand them over" asks for those hand-overs) is read alone when it hands over exactly
    that many objects to exactly that many people (else left, and refused)."""
    m = _PEOPLE_THINGS36R.match(text)
    if m is None:
        return text

    def whose(w: re.Match[str]) -> str:
        if not _only_person(w["p"], lexicon) or not _whole_name(w["x"], lexicon, "object"):
            return w[0]
        return f"{w['x']} to {w['p']}"

    rest = _WHOSE36R.sub(whose, m["rest"])
    rest = rest[:1].upper() + rest[1:] + (m["end"] or ".")
    said = _handovers33t(rest, lexicon)
    if said is None:
        return text
    people, things = _N33T[m["n"].lower()], _N33T[m["m"].lower()]
    if len({t.target for t in said}) != people or len({t.obj for t in said}) != things:
        return text
    return rest if len(said) == things else text


# "Each patient is to have a blanket, Mr Lee the blue and Mrs Khan the grey"
_EACH_ROLE36R = re.compile(
    r"^each (?P<role>[a-z]+) (?:gets|is to (?:have|get)|should (?:have|get)|can have|will get) "
    r"(?:a|one) (?P<k>[a-z]+)\s*[,:]\s*(?P<list>[a-z][\w ]*? the [a-z]+(?: one)?(?:(?:,| and|, "
    r"and) [a-z][\w ]*? the [a-z]+(?: one)?)+)(?=\s*(?:[,.;!?]|$))",
    _F,
)
_GAPPED36R = re.compile(
    r"(?:^|,\s*(?:and\s+)?|\s+and\s+)(?P<p>[a-z][\w ]*?) the (?P<adj>[a-z]+)"
    r"(?: one)?(?=,|\s+and\s|$)",
    _F,
)


def _each_role36r(text: str, lexicon: Lexicon) -> str:
    """Session 36 (12r): "Each patient is to have a blanket, Mr Lee the blue and Mrs Khan the
    grey" is "Mr Lee gets the blue blanket and Mrs Khan gets the grey blanket": every person of
    the scene the role names is named in the list, once, each with one object of the kind said
    (else left: "each patient" stays ambiguous, and refused)."""
    m = _EACH_ROLE36R.match(text)
    if m is None:
        return text
    role = m["role"].lower()
    holders = {h.id for h in lexicon.scene.humans if role in (a.lower() for a in h.aliases)}
    pairs = [(g["p"], g["adj"]) for g in _GAPPED36R.finditer(m["list"])]
    if len(holders) < 2 or len(pairs) != len(holders):
        return text
    said = " and ".join(f"{p} gets the {adj} {m['k']}" for p, adj in pairs)
    done = _handovers33t(said, lexicon)
    if done is None or sorted(t.target for t in done) != sorted(holders):
        return text
    kinds = {o.id: o.category for o in lexicon.scene.objects}
    if any(kinds.get(t.obj) != kinds.get(done[0].obj) for t in done):
        return text
    return f"{said}{text[m.end() :]}"


# "Not the bottle, the crisps, Bob's the one who's peckish."
_ONE_WHOS36R = re.compile(
    r"^(?P<head>(?:not (?:the )?[a-z]+(?: [a-z]+)?,\s*)?(?:the )?[a-z]+(?: [a-z]+)?),\s*"
    r"(?P<p>[a-z][\w ]*?)(?:'s| is) the one (?:who's|who is|that's) (?:(?:a bit|really|very|so) )?"
    r"(?:peckish|hungry|thirsty|starving|famished|parched|cold|freezing|chilly)"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _one_whos36r(text: str, lexicon: Lexicon) -> str:
    """Session 36 (12r): "(Not the bottle,) the crisps, Bob's the one who's peckish" is "(Not
    the bottle,) the crisps for Bob": an object said alone, then the one person said to be hungry,
    thirsty or cold is who it is for (the object one whole name; a clause that says to whom
    already is left)."""
    m = _ONE_WHOS36R.match(text)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    last = re.split(r",\s*", m["head"])[-1]
    if not _whole_name(last, lexicon, "object"):
        return text
    return f"{m['head']} for {m['p']}{m['end'] or '.'}"


# "The bottle isn't Person B's, it's Person A's, take it to her."
_ISNT_HERS36R = re.compile(
    r"^(?P<x>the [a-z]+(?: [a-z]+)?) (?:isn't|is not|'s not) (?P<p>[a-z][\w ]*?)'s,\s*"
    r"(?:it's|it is) (?P<q>[a-z][\w ]*?)'s(?:,\s*(?:so )?(?:take|give|bring|hand) it "
    r"(?:to|over to) (?P<pro>him|her))?(?P<end>\s*[.!]?)$",
    _F,
)


def _isnt_hers36r(text: str, lexicon: Lexicon) -> str:
    """Session 36 (12r): "The bottle isn't Person B's, it's Person A's(, take it to her)" is
    "The bottle isn't for Person B, it's for Person A": whose it is, is who gets it; the closing
    'take it to her' asks for that hand-over (its pronoun one Person A may be)."""
    m = _ISNT_HERS36R.match(text)
    if m is None or not _persons34r(lexicon, m["p"], m["q"]):
        return text
    if not _whole_name(m["x"], lexicon, "object"):
        return text
    if not _the_one36r(m["q"], m["pro"] or "", lexicon):
        return text
    return f"{m['x']} isn't for {m['p']}, it's for {m['q']}{m['end'] or '.'}"


# "No need for anything fancy, just the bottle to Person A."
_NO_NEED36R = re.compile(
    r"^no need for anything (?:fancy|special|else|more),\s*(?=(?:just|only) )", _F
)


def _no_need36r(text: str, _lexicon: Lexicon) -> str:
    """Session 36 (12r): "No need for anything fancy, just X" is "Nothing fancy, just X"
    (session 34's opener: 'just' then says the whole request)."""
    m = _NO_NEED36R.match(text)
    return text if m is None else f"Nothing fancy, {text[m.end() :]}"


# "The blue pen stays put on the desk, but the black one and the red one belong in the box."
_STAYS_BUT36R = re.compile(
    r"^(?P<x>the (?P<adj>[a-z]+) (?P<k>[a-z]+)) stays (?:put|where it is|as it is)"
    r"(?: (?:on|in) (?P<s>the [a-z]+(?: [a-z]+)?))?,\s*but (?P<rest>.+)$",
    _F,
)


def _stays_but36r(text: str, lexicon: Lexicon) -> str:
    """Session 36 (12r): "The blue pen stays put (on the desk), but the black one and the red one
    belong in the box" is "The black pen and the red pen belong in the box": nothing to do for the
    pen that stays (where it lies: a surface said must be the one it starts on), and 'the black
    one' after it is a pen (each such one a whole name; the rest must not name the pen that
    stays)."""
    m = _STAYS_BUT36R.match(text)
    if m is None or not _whole_name(m["x"], lexicon, "object"):
        return text
    x = _ids(m["x"], lexicon, "object")
    if m["s"]:
        if not _whole_name(m["s"], lexicon, "surface"):
            return text
        if not starting_on(x, next(iter(_ids(m["s"], lexicon, "surface"))), lexicon):
            return text

    def kind(o: re.Match[str]) -> str:
        said = f"the {o['adj']} {m['k']}"
        return said if _whole_name(said, lexicon, "object") else o[0]

    rest = _sub(r"\bthe (?P<adj>[a-z]+) one\b", kind, m["rest"])
    if "one" in re.findall(r"[a-z]+", rest.lower()) or _ids(rest, lexicon) & x:
        return text
    return rest[:1].upper() + rest[1:]


# "Mr Lee gets the jug but not the tablets, those are for Mrs Khan."
_BUT_NOT_THOSE36R = re.compile(
    r"^(?P<p>[a-z][\w ]*?) (?P<v>gets|is getting|has|is having) (?P<x>the [a-z]+(?: [a-z]+)?),?\s*"
    r"but not (?P<y>the [a-z]+(?: [a-z]+)?),\s*(?:those|these|they|that|this|it)(?:'re| are|'s| is)"
    r" (?:for|going to) (?P<q>[a-z][\w ]*?)(?P<end>\s*[.!]?)$",
    _F,
)


def _but_not_those36r(text: str, lexicon: Lexicon) -> str:
    """Session 36 (12r): "P gets X but not Y, those are for Q" is "P gets X and Q gets Y" (P and
    Q two people, X and Y two objects, each named whole)."""
    m = _BUT_NOT_THOSE36R.match(text)
    if m is None or not _persons34r(lexicon, m["p"], m["q"]):
        return text
    if not _objects34r(lexicon, m["x"], m["y"]):
        return text
    return f"{m['p']} gets {m['x']} and {m['q']} gets {m['y']}{m['end'] or '.'}"


# "Except for the big box, stack every other thing on the pallet", "Apart from the baby wipes,
# move the whole lot up onto the high chair"
_FRONTED_BUT36R = re.compile(
    r"^(?:except(?: for)?|apart from|other than|bar|barring|aside from) (?:the )?[a-z]+"
    r"(?: [a-z]+)?,\s*",
    _F,
)


def _fronted_rest36r(text: str, lexicon: Lexicon) -> str:
    """Session 36 (12r): after a fronted "Except for X," / "Apart from X,", "every other thing"
    is "everything else" and "the whole lot" is "everything" (session 28's fronted exception
    then reads it: all but X; a thing said that is not one of the scene's objects is left)."""
    m = _FRONTED_BUT36R.match(text)
    if m is None or not _objects_only(m[0], lexicon):
        return text
    rest = _sub(r"\bevery other (?:thing|item|object)\b", "everything else", text[m.end() :])
    rest = _sub(r"\bthe whole lot\b", "everything", rest)
    return f"{m[0]}{rest}"


# "Bob gets the chips, scratch that, Alice does, she won the bet."
_DOES_WHY36R = re.compile(
    r"^(?P<head>.+?,\s*(?:scratch that|no|sorry|actually|wait|i mean|no wait),?\s*"
    r"(?P<p>[a-z][\w ]*?) does),\s*(?P<why>(?P<pro>she|he) (?:won|lost|asked|called|got|paid|"
    r"bought|earned|came|did)\b[^,.;!?]*?)(?P<end>\s*[.!]?)$",
    _F,
)


def _does_why36r(text: str, lexicon: Lexicon) -> str:
    """Session 36 (12r): after a correction to the person ("…, scratch that, Alice does"), a
    closing reason said of that person in the past ("she won the bet") asks nothing: taken off
    (the pronoun one the person may be; the reason naming nothing of the scene and holding no word
    that could change who gets what)."""
    m = _DOES_WHY36R.match(text)
    if m is None or not _the_one36r(m["p"], m["pro"], lexicon):
        return text
    if _REASON_HELD21.search(m["why"]) or not _names_nothing(m["why"], lexicon):
        return text
    return f"{m['head']}{m['end'] or '.'}"


# "Take the bottle to, erm, what's her name, Person A, that's it."
_WHATS_NAME36R = re.compile(
    r"(?P<to>\b(?:to|for)),\s*(?:(?:erm|um|er|uh|ehm),?\s*)*what(?:'s| is) "
    r"(?P<pro>her|his|their) name,\s*(?P<p>[a-z][\w ]*?)(?:,\s*that(?:'s| is) (?:it|the one|"
    r"right))?(?P<end>\s*(?:[,.;!?]|$))",
    _F,
)


def _whats_name36r(text: str, lexicon: Lexicon) -> str:
    """Session 36 (12r): "to, erm, what's her name, Person A(, that's it)" is "to Person A": the
    speaker searching for the name, then saying it (one person, one the pronoun may be)."""
    if "name" not in text.lower():
        return text

    def named(m: re.Match[str]) -> str:
        pro = "" if m["pro"].lower() == "their" else m["pro"]
        if not _the_one36r(m["p"], pro, lexicon):
            return m[0]
        return f"{m['to']} {m['p']}{m['end']}"

    return _WHATS_NAME36R.sub(named, text)


# "Sponge in the sink, no, the tray, sorry, the sink's full."
_FULL_AFTER36R = re.compile(
    r"^(?P<head>.+?(?:in|on|into|onto) (?P<s>the [a-z]+(?: [a-z]+)?),\s*(?:no|sorry|wait|"
    r"actually),?\s*(?:(?:in|on|into|onto) )?(?P<t>the [a-z]+(?: [a-z]+)?)),\s*(?:sorry,\s*)?"
    r"(?P<again>the [a-z]+(?: [a-z]+)?)(?:'s| is) (?:full|busy|taken|in use|cluttered|occupied|"
    r"wet|dirty|a mess|covered)(?P<end>\s*[.!]?)$",
    _F,
)


def _full_after36r(text: str, lexicon: Lexicon) -> str:
    """Session 36 (12r): "Sponge in the sink, no, the tray, sorry, the sink's full" is "Sponge
    in the sink, no, the tray": why the place said first will not do (the same surface, said
    again) asks nothing once the correction names another."""
    m = _FULL_AFTER36R.match(text)
    if m is None or not _whole_name(m["s"], lexicon, "surface"):
        return text
    if not _whole_name(m["t"], lexicon, "surface"):
        return text
    again = _ids(m["again"], lexicon, "surface")
    if not _whole_name(m["again"], lexicon, "surface") or again != _ids(m["s"], lexicon):
        return text
    if again == _ids(m["t"], lexicon):
        return text
    return f"{m['head']}{m['end'] or '.'}"


# "Take Lena the lemon, no hang on, it's the salt she wants."
_ITS_X_WANTS36R = re.compile(
    r",\s*(?P<no>no|sorry|wait|actually)(?:,?\s*(?:hang on|hold on|wait))?,?\s*"
    r"it(?:'s| is) (?P<x>the [a-z]+(?: [a-z]+)?) (?:that )?(?P<pro>she|he) (?:wants|needs|"
    r"asked for|is after)(?P<end>\s*[.!]?)$",
    _F,
)


def _its_x_wants36r(text: str, lexicon: Lexicon) -> str:
    """Session 36 (12r): "Take Lena the lemon, no hang on, it's the salt she wants" is "Take
    Lena the lemon, no, the salt": the object corrected, said as what the one person named before
    wants (the pronoun one that person may be; the object one whole name)."""
    m = _ITS_X_WANTS36R.search(text)
    if m is None or not _whole_name(m["x"], lexicon, "object"):
        return text
    people = _ids(text[: m.start()], lexicon, "human")
    if len(people) != 1 or not _may_be35t(next(iter(people)), m["pro"], lexicon):
        return text
    return f"{text[: m.start()]}, no, {m['x']}{m['end'] or '.'}"


# "Just the single bottle, to Person A, that's her ration for the fell race."
_THATS_HERS36R = re.compile(
    r",\s*(?:and )?that(?:'s| is) (?P<pro>her|his) (?P<what>[a-z]+(?: [a-z]+)?(?: for the [a-z]+"
    r"(?: [a-z]+)?)?)(?P<end>\s*[.!]?)$",
    _F,
)


def _thats_hers36r(text: str, lexicon: Lexicon) -> str:
    """Session 36 (12r): a closing "that's her ration (for the fell race)" after a request to one
    person the pronoun may be says what the thing is to them: taken off (it names nothing of the
    scene and no word that could change who gets what)."""
    m = _THATS_HERS36R.search(text)
    if m is None or _REASON_HELD21.search(m["what"]) or not _names_nothing(m["what"], lexicon):
        return text
    people = _ids(text[: m.start()], lexicon, "human")
    if len(people) != 1 or not _may_be35t(next(iter(people)), m["pro"], lexicon):
        return text
    if not _ids(text[: m.start()], lexicon, "object"):
        return text
    return f"{text[: m.start()]}{m['end'] or '.'}"


# "There's a single bottle about, take it to Person A"
_THERES_ONE36R = re.compile(
    r"^there(?:'s| is) (?:a|one|a single|just the one|only the one|only one|the one) "
    r"(?P<k>[a-z]+)(?: (?:about|here|left|going|over there|on the go))?,\s*(?:so\s+)?"
    r"(?P<v>take|give|bring|hand|pass) it (?P<rest>(?:to|over to) .+)$",
    _F,
)
# "There's only the one bottle and only Person A to give it to, so off it goes to her."
_ONLY_ONE_TO36R = re.compile(
    r"^there(?:'s| is) only (?:the )?one (?P<k>[a-z]+) and only (?P<p>[a-z][\w ]*?) to "
    r"(?:give|take|hand) it to,\s*so (?:off it goes to|(?:give|take|hand) it to) (?P<pro>her|him)"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _one_of_kind36r(k: str, lexicon: Lexicon) -> str | None:
    """'the bottle' when the scene holds exactly one object of kind (or name) ``k``."""
    said = f"the {k}"
    if not _whole_name(said, lexicon, "object") or len(_ids(said, lexicon, "object")) != 1:
        return None
    return said


def _theres_one36r(text: str, lexicon: Lexicon) -> str:
    """Session 36 (12r): "There's a single bottle about, take it to P" is "Take the bottle to P",
    and "There's only the one bottle and only P to give it to, so off it goes to her" is "Give P
    the bottle": the count must agree with the scene (exactly one such object; 'only P' the one
    person of the scene, one the pronoun may be), else left, and refused."""
    m = _THERES_ONE36R.match(text)
    if m is not None:
        said = _one_of_kind36r(m["k"], lexicon)
        if said is None:
            return text
        return f"{m['v'][:1].upper()}{m['v'][1:]} {said} {m['rest']}"
    m = _ONLY_ONE_TO36R.match(text)
    if m is None or not _the_one36r(m["p"], m["pro"], lexicon):
        return text
    said = _one_of_kind36r(m["k"], lexicon)
    if said is None or len(lexicon.scene.humans) != 1:
        return text
    return f"Give {m['p']} {said}{m['end'] or '.'}"


# "Put the two mugs on the shelf, the busboy keeps knocking them over."
_THEM_REMARK36R = re.compile(
    r",\s*(?P<who>the [a-z]+) (?:keeps |kept |has been |'s been |is always |always |will only )?"
    r"(?:knock(?:ing|ed|s)? (?:them|those) (?:over|off|down)|(?:nick(?:ing|ed|s)?|"
    r"pinch(?:ing|ed|es)?|borrow(?:ing|ed|s)?|los(?:ing|t|es)|swip(?:ing|ed|es)|hid(?:ing|den|es)?|"
    r"misplac(?:ing|ed|es)) (?:them|those))(?: again)?(?: and never (?:said|asked|told anyone|"
    r"brought them back|gave them back))?(?P<end>\s*[.!]?)$",
    _F,
)


def _them_remark36r(text: str, lexicon: Lexicon) -> str:
    """Session 36 (12r): a closing remark that someone outside the scene keeps knocking over,
    nicking, borrowing or losing 'them' ("…, the busboy keeps knocking them over", "…, the
    pipefitter borrowed them and never said"), after a request that names two or more objects
    (what 'them' stands for), asks nothing: taken off (the one it is said of no one of the
    scene)."""
    m = _THEM_REMARK36R.search(text)
    if m is None or not _names_nothing(m["who"], lexicon):
        return text
    if len(_ids(text[: m.start()], lexicon, "object")) < 2:
        return text
    return f"{text[: m.start()]}{m['end'] or '.'}"


# "Both blocks up on the high chair, Lily wants to stack them."
_WANTS_TO_V36R = re.compile(
    r",\s*(?P<p>[a-z][\w ]*?) (?:wants|needs|is going|'s going|would like|'d like) to "
    r"(?:(?:stack|sort|count|line up|build with|play with|paint|colour|color|look at|tidy|check|"
    r"label|dry|clean|wash) (?:them|those|it)(?: up| out)?|(?:plate|dish|serve) up(?P<what> the "
    r"[a-z]+)?)(?P<end>\s*[.!]?)$",
    _F,
)


def _wants_to_v36r(text: str, lexicon: Lexicon) -> str:
    """Session 36 (12r): "Both blocks up on the high chair, Lily wants to stack them" (or "…,
    Marco wants to plate up the goulash"): after a request that only places objects (on a surface
    it names), what a person of the scene wants to do with them there is why: taken off (a request
    that hands anything to anyone is left, and so is a dish that names a scene object)."""
    m = _WANTS_TO_V36R.search(text)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    if m["what"] and not _names_nothing(m["what"], lexicon):
        return text  # "Marco wants to plate up the lemon": the lemon may be asked for
    head = text[: m.start()]
    done = _tasks_of(head, lexicon)
    if not done or any(kind != "place" for kind, _, _ in done):
        return text
    return f"{head}{m['end'] or '.'}"


# "…, she's frozen, the heating's off on this side."
_STATE_HERE36R = re.compile(
    r",\s*(?P<what>the [a-z]+)(?:'s| is) (?:off|out|down|broken|bust|playing up|not working|"
    r"on the blink)(?: again)?(?: (?:on|at) this (?:side|end)| in here| over here| today)?"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _state_here36r(text: str, lexicon: Lexicon) -> str:
    """Session 36 (12r): a closing state of something outside the scene ("…, the heating's off on
    this side") asks nothing: taken off when it names nothing of the scene and the request
    before it names something."""
    m = _STATE_HERE36R.search(text)
    if m is None or not _names_nothing(m["what"], lexicon):
        return text
    if not _ids(text[: m.start()], lexicon):
        return text
    return f"{text[: m.start()]}{m['end'] or '.'}"


# "The three boxes onto the belt, the whole lot's for the same van."
_SAME_VAN36R = re.compile(
    r",\s*(?:the whole lot|the lot|they|they're all|they are all|all of them|it all)(?:'s| is| "
    r"are|'re)? (?:all )?(?:for|going (?:on|in|out on)|going to) the same (?P<what>[a-z]+)"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _same_van36r(text: str, lexicon: Lexicon) -> str:
    """Session 36 (12r): "…, the whole lot's for the same van" after a request naming two or
    more objects says they go out together: taken off (the van, order or customer no one and
    nothing of the scene)."""
    m = _SAME_VAN36R.search(text)
    if m is None or not _names_nothing(m["what"], lexicon):
        return text
    if len(_ids(text[: m.start()], lexicon, "object")) < 2:
        return text
    return f"{text[: m.start()]}{m['end'] or '.'}"


# "Lily can have any one of her blocks"
_HER_ONES36R = re.compile(
    r"^(?P<p>[a-z][\w ]*?) (?P<v>can have|can take|gets|may have) (?P<any>any one|any|either|one) "
    r"of (?P<pro>her|his) (?P<k>[a-z]+s)\b",
    _F,
)


def _her_ones36r(text: str, lexicon: Lexicon) -> str:
    """Session 36 (12r): "Lily can have any one of her blocks" is "… any one of the blocks": the
    scene says nothing of whose a thing is, so 'her blocks' said of the one person who gets one
    are the scene's blocks (the pronoun one that person may be; the kind one the scene holds)."""
    m = _HER_ONES36R.match(text)
    if m is None or not _the_one36r(m["p"], m["pro"], lexicon):
        return text
    if not _ids(f"the {m['k']}", lexicon, "object"):
        return text
    return f"{m['p']} {m['v']} {m['any']} of the {m['k']}{text[m.end() :]}"


# "…, she'll only chew it."
_ONLY_CHEW36R = re.compile(
    r",\s*(?P<pro>she|he)(?:'ll| will) only (?:chew|lose|drop|break|spill|throw|break|suck) "
    r"(?:it|them)(?: anyway)?(?P<end>\s*[.!]?)$",
    _F,
)


def _only_chew36r(text: str, lexicon: Lexicon) -> str:
    """Session 36 (12r): a closing "she'll only chew it" after a request to the one person the
    pronoun may be says what will become of it: taken off."""
    m = _ONLY_CHEW36R.search(text)
    if m is None:
        return text
    people = _ids(text[: m.start()], lexicon, "human")
    if len(people) != 1 or not _may_be35t(next(iter(people)), m["pro"], lexicon):
        return text
    return f"{text[: m.start()]}{m['end'] or '.'}"


# "Person A wants the, sorry, where was I, the bottle, yes, the bottle, to Person A."
_WHERE_WAS_I36R = re.compile(
    # session 40 (12r): 'oh', 'ah' before it; "what's its name", "what's the word"
    r"\bthe,\s*(?:(?:sorry|erm|um|er|uh|oh|ah),?\s*)*(?:where was i|what's it called|what is it "
    r"called|what do you call it|what's its name|what's the word),\s*(?P<x>the [a-z]+"
    r"(?: [a-z]+)?)(?:,\s*(?:yes|yeah|that's it),\s*(?P<again>the [a-z]+"
    r"(?: [a-z]+)?))?(?=\s*(?:[,.;!?]|$))",
    _F,
)


def _where_was_i36r(text: str, lexicon: Lexicon) -> str:
    """Session 36 (12r): "the, sorry, where was I, the bottle, yes, the bottle" is "the bottle":
    the speaker lost for the word after 'the', then saying it (one whole object, said again the
    same if at all)."""
    if "the," not in text.lower():
        return text

    def said(m: re.Match[str]) -> str:
        if not _whole_name(m["x"], lexicon, "object"):
            return m[0]
        if m["again"] and _ids(m["again"], lexicon) != _ids(m["x"], lexicon):
            return m[0]
        return m["x"]

    return _WHERE_WAS_I36R.sub(said, text)


# -- session 37 (12r): blind35's choices, counts, negation, exclusions and corrections -----------

# "There's something for both of them, mind: the apple is Person A's and the cup is Person B's."
_SOMETHING_FOR37R = re.compile(
    r"^there(?:'s| is) (?:something|one thing|a thing) (?:for|going to) (?P<q>both|each|all) "
    r"(?:of )?them(?:,\s*mind)?\s*:\s*(?P<rest>\S.*)$",
    _F,
)


def _something_for37r(text: str, lexicon: Lexicon) -> str:
    """Session 37 (12r): a heading "There's something for both of them(, mind):" before a list is
    read as the list alone ("the apple is Person A's" being "the apple to Person A", as session
    36's "Two people, two things:" reads it), only when the list hands over to every person of the
    scene (two of them for 'both') and to no one else; else left, and refused."""
    m = _SOMETHING_FOR37R.match(text)
    if m is None:
        return text

    def whose(w: re.Match[str]) -> str:
        if not _only_person(w["p"], lexicon) or not _whole_name(w["x"], lexicon, "object"):
            return w[0]
        return f"{w['x']} to {w['p']}"

    rest = _WHOSE36R.sub(whose, m["rest"])
    rest = rest[:1].upper() + rest[1:]
    said = _handovers33t(rest, lexicon)
    people = {h.id for h in lexicon.scene.humans}
    if said is None or {t.target for t in said} != people:
        return text
    if m["q"].lower() == "both" and len(people) != 2:
        return text
    return rest


# "Go whichever route suits you, as long as Person A gets the bottle in the end."
_AS_LONG_AS37R = re.compile(
    r"^(?:go|do it|get it done|do it) (?:whichever|whatever|any|which ever) (?:route|way) "
    r"(?:suits you|you like|you want|you fancy|works for you|is easiest)(?: best)?,\s*"
    r"(?:as long as|so long as|just so long as|provided|provided that) (?P<rest>.+?)"
    r"(?: in the end| at the end| eventually)?(?P<end>\s*[.!]?)$",
    _F,
)


def _as_long_as37r(text: str, lexicon: Lexicon) -> str:
    """Session 37 (12r): "Go whichever route suits you, as long as Person A gets the bottle (in
    the end)" leaves the how to the robots and asks for the outcome: read as "Person A gets the
    bottle" (the clause after 'as long as' must read by itself as hand-overs or placements, no
    choice or negation in it)."""
    m = _AS_LONG_AS37R.match(text)
    if m is None or re.search(r"\b(?:not|n't|no|never|or)\b", m["rest"], _F):
        return text
    rest = m["rest"][:1].upper() + m["rest"][1:] + (m["end"] or ".")
    node = _reading(rest, lexicon)
    if node is None or (isinstance(node, Group) and node.op != "and"):
        return text
    return rest


# "Either arm can do it: the bottle to Person A."
_ANY_ARM37R = re.compile(
    r"^(?:either|any|whichever|each) (?:arm|robot|hand|one of you|of you|of your arms)"
    r" (?:can|will|could|may) do (?:it|this|that|the job)\s*[:;,.]\s*(?=\S)",
    _F,
)


def _any_arm37r(text: str, _lexicon: Lexicon) -> str:
    """Session 37 (12r): "Either arm can do it:" before a request says which robot acts, said to
    the robots (as session 29's "I don't mind which of your arms does it"): taken off."""
    out = _ANY_ARM37R.sub("", text)
    return text if out == text else out[:1].upper() + out[1:]


# "Give one of them the chips, Person A or Person B, and the other one the bottle."
_ONE_OTHER37R = re.compile(
    r"^give one of (?:them|the two(?: of them)?) (?P<x>the [a-z]+(?: [a-z]+)?),\s*"
    r"(?P<p>[a-z][\w ]*?) or (?P<q>[a-z][\w ]*?),\s*and the other(?: one)? "
    r"(?P<y>the [a-z]+(?: [a-z]+)?)(?P<end>\s*[.!]?)$",
    _F,
)


def _one_other37r(text: str, lexicon: Lexicon) -> str:
    """Session 37 (12r): "Give one of them the chips, Person A or Person B, and the other one the
    bottle" is "Give Person A the chips and Person B the bottle, or the other way round": the two
    people named, each another, two objects, each another (else left, and refused)."""
    m = _ONE_OTHER37R.match(text)
    if m is None or not _persons34r(lexicon, m["p"], m["q"]):
        return text
    if not _objects34r(lexicon, m["x"], m["y"]):
        return text
    return f"Give {m['p']} {m['x']} and {m['q']} {m['y']}, or the other way round{m['end'] or '.'}"


# "Sam's only signing for the key cutter, so any pen at all will do him."
_WILL_DO_HIM37R = re.compile(
    r"^(?P<p>[a-z][\w ]*?)(?:'s| is) (?:only|just) [a-z]+ing\b(?P<why>[^,]*),\s*so "
    r"(?P<x>any [a-z]+)(?: at all)? will do (?:for )?(?P<pro>him|her)(?P<end>\s*[.!]?)$",
    _F,
)


def _will_do_him37r(text: str, lexicon: Lexicon) -> str:
    """Session 37 (12r): "Sam's only signing (for the key cutter), so any pen at all will do him"
    is "Any pen will do for Sam": what the one person is only doing is why any one of the kind
    will do (it names nothing of the scene; the pronoun one that person may be)."""
    m = _WILL_DO_HIM37R.match(text)
    if m is None or not _the_one36r(m["p"], m["pro"], lexicon):
        return text
    if not _names_nothing(m["why"], lexicon):
        return text
    x = m["x"][:1].upper() + m["x"][1:]
    return f"{x} will do for {m['p']}{m['end'] or '.'}"


# "The belt needs one box on it, either the small or the medium, not the big one."
_NEEDS_ON_IT37R = re.compile(
    r"^(?P<s>the [a-z]+(?: [a-z]+)?) needs (?:one|a|an) (?P<k>[a-z]+) (?:on|in) it,\s*"
    r"(?P<choice>either the [a-z]+ or the [a-z]+)(?: one)?(?=\s*(?:[,.!]|$))",
    _F,
)


def _needs_on_it37r(text: str, lexicon: Lexicon) -> str:
    """Session 37 (12r): "The belt needs one box on it, either the small or the medium" is
    "Either the small or the medium box on the belt": a surface said to need one thing of a kind,
    then the choice of which (the surface one whole name; each of the two one whole object of the
    kind, each another)."""
    m = _NEEDS_ON_IT37R.match(text)
    if m is None or not _whole_name(m["s"], lexicon, "surface"):
        return text
    if not _objects34r(lexicon, *(f"{w} {m['k']}" for w in m["choice"][7:].split(" or "))):
        return text
    choice = m["choice"][:1].upper() + m["choice"][1:]
    return f"{choice} {m['k']} on the {m['s'][4:]}{text[m.end() :]}"


# "A book apiece for Noah and Zoe, I don't care who ends up with which."
_WHO_WHICH37R = re.compile(
    r"\b(?P<head>(?:apiece|each) for [a-z][\w ]*? and [a-z][\w ]*?),\s*(?:i|we) (?:don't|do not) "
    r"(?:care|mind) (?:who (?:ends up with|gets|has) which|which (?:one )?(?:goes to|gets) who)"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _who_which37r(text: str, _lexicon: Lexicon) -> str:
    """Session 37 (12r): after "a book apiece for Noah and Zoe", the speaker not caring who ends
    up with which says what 'apiece' already leaves open: taken off."""
    m = _WHO_WHICH37R.search(text)
    if m is None:
        return text
    return f"{text[: m.start()]}{m['head']}{m['end'] or '.'}"


# "Lily can have a block, she won't mind if it's the red or the green."
_WONT_MIND_IF37R = re.compile(
    r"^(?P<head>(?P<p>[a-z][\w ]*?) (?:can have|gets|is to have|should have|can take) (?:a|one) "
    r"(?P<k>[a-z]+)),\s*(?P<pro>she|he) (?:won't|will not|doesn't|does not) mind (?:if|whether) "
    r"(?:it's|it is) (?P<a>the [a-z]+)(?: one)? or (?P<b>the [a-z]+)(?: one)?"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _wont_mind_if37r(text: str, lexicon: Lexicon) -> str:
    """Session 37 (12r): "Lily can have a block, she won't mind if it's the red or the green" is
    "Lily can have a block, the red or the green": the pronoun one the person named may be, and
    each of the two a whole object of the kind, each another."""
    m = _WONT_MIND_IF37R.match(text)
    if m is None or not _the_one36r(m["p"], m["pro"], lexicon):
        return text
    if not _objects34r(lexicon, f"{m['a']} {m['k']}", f"{m['b']} {m['k']}"):
        return text
    return f"{m['head']}, {m['a']} or {m['b']}{m['end'] or '.'}"


_COUNT37R = {"two": 2, "three": 3, "four": 4, "a pair of": 2, "a couple of": 2, "both": 2}

# "Carol's got a pair of things coming, the apple and the cup, …"
_GOT_COMING37R = re.compile(
    r"^(?P<p>[a-z][\w ]*?)(?:'s| has) got (?P<n>a pair of|a couple of|two|three|four) "
    r"(?:things|items) coming,\s*(?P<list>the [a-z ,]+?)(?=\s*(?:[,.!]|$))",
    _F,
)


def _got_coming37r(text: str, lexicon: Lexicon) -> str:
    """Session 37 (12r): "Carol's got a pair of things coming, the apple and the cup" is "Carol
    gets the apple and the cup": the count said must be the number of objects the list names,
    each another, all to the one person."""
    m = _GOT_COMING37R.match(text)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    said = _handovers33t(f"{m['p']} gets {m['list']}.", lexicon)
    if said is None or len({t.obj for t in said}) != _COUNT37R[m["n"].lower()]:
        return text
    return f"{m['p']} gets {m['list']}{text[m.end() :]}"


# "Person B's taking the lot, …, to his weightlifting do."
_TO_HIS_DO37R = re.compile(
    r",\s*(?:off )?to (?P<pro>his|her) (?P<what>[a-z]+(?: [a-z]+)?) (?:do|party|bash|night|"
    r"session|class|club|practice|rehearsal|recital|match|meeting)(?P<end>\s*[.!]?)$",
    _F,
)


def _to_his_do37r(text: str, lexicon: Lexicon) -> str:
    """Session 37 (12r): a closing ", to his weightlifting do" after a request to one person the
    pronoun may be says where they are taking it, not who gets it: taken off (it names nothing of
    the scene)."""
    m = _TO_HIS_DO37R.search(text)
    if m is None or not _names_nothing(m["what"], lexicon):
        return text
    people = _ids(text[: m.start()], lexicon, "human")
    if len(people) != 1:
        return text
    pro = "he" if m["pro"].lower() == "his" else "she"
    if not _may_be35t(next(iter(people)), pro, lexicon):
        return text
    if not _ids(text[: m.start()], lexicon, "object"):
        return text
    return f"{text[: m.start()]}{m['end'] or '.'}"


# "Both the cup and the apple, that's two, are going to Person A"
_THATS_N37R = re.compile(
    r"^(?P<list>(?:both )?the [a-z ,]+?),\s*that(?:'s| is| makes) (?P<n>two|three|four|both)"
    r"(?: (?:things|items|of them))?,\s*",
    _F,
)


def _thats_n37r(text: str, lexicon: Lexicon) -> str:
    """Session 37 (12r): "Both the cup and the apple, that's two, …" counts the objects just
    listed: taken off when the count is the number of objects the list names, each another."""
    m = _THATS_N37R.match(text)
    if m is None:
        return text
    items = re.split(r",\s*(?:and\s+)?|\s+and\s+", re.sub(r"^both ", "", m["list"], flags=_F))
    if not all(_whole_name(w, lexicon, "object") for w in items):
        return text
    if not _objects34r(lexicon, *items) or len(items) != _COUNT37R[m["n"].lower()]:
        return text
    return f"{m['list']} {text[m.end() :]}"


# "Just the one item for Person A: the chips."
_THE_ONE_ITEM37R = re.compile(r"^(?:just |only )?the one (?:item|thing) for (?=[^:]+:)", _F)


def _the_one_item37r(text: str, _lexicon: Lexicon) -> str:
    """Session 37 (12r): a heading "Just the one item for P:" is "One thing for P:" (the count
    then checked against the list by the grammar, as that heading is)."""
    return _THE_ONE_ITEM37R.sub("One thing for ", text, count=1)


# "The two things here, one per person: bottle to Person A, chips to Person B."
_N_THINGS_EACH37R = re.compile(
    r"^(?:the )?(?P<n>two|three|four) (?:things|items)(?: here| there)?,\s*one (?:per person|"
    r"each|apiece|per head)\s*:\s*(?P<rest>\S.*)$",
    _F,
)


def _n_things_each37r(text: str, lexicon: Lexicon) -> str:
    """Session 37 (12r): "The two things here, one per person: …" is session 36's "One each: …"
    (every person exactly one object), when the list hands over as many objects as counted and
    the scene holds that many objects."""
    m = _N_THINGS_EACH37R.match(text)
    if m is None:
        return text
    n = _N33T[m["n"].lower()]
    said = _handovers33t(m["rest"], lexicon)
    if said is None or len(said) != n or len(lexicon.scene.objects) != n:
        return text
    return f"One thing apiece: {m['rest']}"


# "Every last thing you've got there is for Person A"
_EVERY_LAST37R = re.compile(
    r"\bevery last (?:thing|item|one of them|bit)(?: (?:you've|you have|we've|we have) got"
    r"(?: (?:there|here|about))?| (?:here|there|about))?(?=\s+(?:is|goes|should|can|needs)\b)",
    _F,
)


def _every_last37r(text: str, _lexicon: Lexicon) -> str:
    """Session 37 (12r): "every last thing (you've got there)" as a subject is "everything"."""
    return _EVERY_LAST37R.sub("everything", text)


# "…, it's the only one we've got left."
_ONLY_ONE_GOT37R = re.compile(
    r"\b(?P<head>it(?:'s| is) the (?:only|last) one) (?:we've|we have|I've|I have|you've|you have)"
    r" got( left)?(?=\s*[.!]?$)",
    _F,
)


def _only_one_got37r(text: str, _lexicon: Lexicon) -> str:
    """Session 37 (12r): ", it's the only one we've got left" is ", it's the only one left" (what
    the grammar checks against the scene)."""
    return _ONLY_ONE_GOT37R.sub(lambda m: f"{m['head']} left", text)


# "The pair of cups, the green and the white, want putting on the tray"
_PAIR_OF37R = re.compile(
    r"\bthe pair of (?P<ks>[a-z]+s)(?=,\s*the [a-z]+(?: one)? and the [a-z]+(?: one)?,)", _F
)


def _pair_of37r(text: str, lexicon: Lexicon) -> str:
    """Session 37 (12r): "the pair of cups, the green and the white, …" is "both cups, …" where
    the scene holds exactly two objects of that kind (else left), then read as session 33's "Both
    cups, the green and the white, …" is."""

    def both(m: re.Match[str]) -> str:
        ids = _ids(f"the {m['ks']}", lexicon, "object")
        if len(ids) != 2:
            return m[0]
        return f"{'B' if m[0][0].isupper() else 'b'}oth {m['ks']}"

    out = _PAIR_OF37R.sub(both, text)
    # "Both cups, the green and the white, …": session 33's reading of the two named after it
    return text if out == text else _both_named33t(out, lexicon)


# "Every box in the place, big one included, goes on the belt."
_EVERY_INCLUDED37R = re.compile(
    r"\b(?P<every>every|all the) (?P<k>[a-z]+?)(?P<pl>es|s)?(?: in the (?:place|room|building))?"
    r",\s*(?:(?:the )?(?P<a>[a-z]+) one included|including the (?P<b>[a-z]+) one),\s*",
    _F,
)


def _every_included37r(text: str, lexicon: Lexicon) -> str:
    """Session 37 (12r): "Every box in the place, big one included, goes …" is "Every box goes
    …": every one of the kind, the one said included already (it must be one object of that kind
    in the scene)."""

    def every(m: re.Match[str]) -> str:
        adj = m["a"] or m["b"]
        one = f"the {adj} {m['k']}"
        if len(_ids(one, lexicon, "object")) != 1 or not _whole_name(one, lexicon, "object"):
            return m[0]
        return f"{m['every']} {m['k']}{m['pl'] or ''} "

    return _EVERY_INCLUDED37R.sub(every, text)


# "Mrs Ortiz needs both books for her lesson on fossils"
_LESSON_ON37R = re.compile(
    r"\bfor (?P<pro>her|his|their) (?P<what>lesson|talk|class|lecture|session|presentation|"
    r"seminar|assembly) (?:on|about) (?P<topic>[a-z]+(?: [a-z]+)?)(?=\s*(?:[,.!]|$))",
    _F,
)


def _lesson_on37r(text: str, lexicon: Lexicon) -> str:
    """Session 37 (12r): "for her lesson on fossils" is "for her lesson" (the topic naming
    nothing of the scene), as the grammar reads a purpose."""

    def drop(m: re.Match[str]) -> str:
        if not _names_nothing(m["topic"], lexicon) or re.search(r"\b(?:the|a|an)\b", m["topic"]):
            return m[0]
        return f"for {m['pro']} {m['what']}"

    return _LESSON_ON37R.sub(drop, text)


# "Alice doesn't want the bottle, only the crisps, …"
_DOESNT_ONLY37R = re.compile(
    r"^(?P<p>[a-z][\w ]*?) (?:doesn't|does not) (?P<v>want|need) (?P<x>the [a-z]+(?: [a-z]+)?),"
    r"\s*(?:only|just) (?P<y>the [a-z]+(?: [a-z]+)?)(?=\s*(?:[,.!]|$))",
    _F,
)


def _doesnt_only37r(text: str, lexicon: Lexicon) -> str:
    """Session 37 (12r): "Alice doesn't want the bottle, only the crisps" is "Alice wants the
    crisps, not the bottle" (one person, two whole objects, each another)."""
    m = _DOESNT_ONLY37R.match(text)
    if m is None or not _only_person(m["p"], lexicon) or not _objects34r(lexicon, m["x"], m["y"]):
        return text
    return f"{m['p']} {m['v']}s {m['y']}, not {m['x']}{text[m.end() :]}"


# "The bottle for Bob, and nothing besides that, …"; "…, don't bother with anything more"
_NOTHING_BESIDES37R = re.compile(
    r",\s*(?:and )?(?:nothing (?:besides|beyond|on top of|apart from|other than) (?:that|it|this)|"
    r"(?:don't|do not) bother with anything (?:more|else|other))(?=\s*(?:[,.!]|$))",
    _F,
)


def _nothing_besides37r(text: str, _lexicon: Lexicon) -> str:
    """Session 37 (12r): ", and nothing besides that" and ", don't bother with anything more"
    after a request are ", nothing else" (what the grammar reads as the request alone)."""
    return _NOTHING_BESIDES37R.sub(", nothing else", text)


# "It's the cup Person B should have, the apple isn't his."
_CLEFT_ISNT37R = re.compile(
    r"^it(?:'s| is) (?P<x>the [a-z]+(?: [a-z]+)??) (?:that )?(?P<p>[a-z][\w ]*?) should "
    r"(?P<v>have|get),\s*(?P<y>the [a-z]+(?: [a-z]+)?) (?:isn't|is not|'s not) (?P<pro>his|hers)"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _cleft_isnt37r(text: str, lexicon: Lexicon) -> str:
    """Session 37 (12r): "It's the cup Person B should have, the apple isn't his" is "Person B
    should have the cup, not the apple" (one person the pronoun may be, two whole objects, each
    another)."""
    m = _CLEFT_ISNT37R.match(text)
    if m is None or not _objects34r(lexicon, m["x"], m["y"]):
        return text
    if not _the_one36r(m["p"], "he" if m["pro"].lower() == "his" else "she", lexicon):
        return text
    return f"{m['p']} should {m['v']} {m['x']}, not {m['y']}{m['end'] or '.'}"


# "No need to wait about, the bottle goes to Person A."
_NO_WAIT37R = re.compile(
    r"^no need to (?:wait|hang) (?:about|around|round)(?: for anything| for me)?\s*[,;:]\s*(?=\S)",
    _F,
)


def _no_wait37r(text: str, _lexicon: Lexicon) -> str:
    """Session 37 (12r): an opening "No need to wait about," says to start now, as the robots do:
    taken off."""
    out = _NO_WAIT37R.sub("", text)
    return text if out == text else out[:1].upper() + out[1:]


# "The chips are going to Person A, Person B's had his fill."
_HAD_FILL37R = re.compile(
    r",\s*(?P<p>[a-z][\w ]*?)(?:'s| has) had (?P<pro>his|her) fill(?P<end>\s*[.!]?)$", _F
)


def _had_fill37r(text: str, lexicon: Lexicon) -> str:
    """Session 37 (12r): a closing "P's had his fill" (P one person the pronoun may be) is "P's
    full", the state the grammar reads as a remark."""
    m = _HAD_FILL37R.search(text)
    if m is None or not _the_one36r(m["p"], "he" if m["pro"].lower() == "his" else "she", lexicon):
        return text
    return f"{text[: m.start()]}, {m['p']}'s full{m['end'] or '.'}"


# "The cups, except the green one, go in the sink."
_EXCEPT_COMMAS37R = re.compile(
    r"^(?P<ks>the [a-z]+s),\s*(?P<ex>(?:except|apart from|but not|bar) the [a-z]+ one),\s*"
    r"(?=(?:go|goes|should go|want|need|belong)\b)",
    _F,
)


def _except_commas37r(text: str, _lexicon: Lexicon) -> str:
    """Session 37 (12r): "The cups, except the green one, go …" is "The cups except the green one
    go …" (the exception said between commas)."""
    return _EXCEPT_COMMAS37R.sub(lambda m: f"{m['ks']} {m['ex']} ", text)


# "Only the chips for Person B, …"
_ONLY_FOR37R = re.compile(
    r"^only (?P<x>the [a-z]+(?: [a-z]+)?) (?P<to>for|to) (?P<p>[a-z][\w ]*?)(?=\s*(?:[,.!]|$))", _F
)


def _only_for37r(text: str, lexicon: Lexicon) -> str:
    """Session 37 (12r): an opening "Only the chips for Person B" is "Just the chips for Person
    B" (one whole object, one person)."""
    m = _ONLY_FOR37R.match(text)
    if m is None or not _whole_name(m["x"], lexicon, "object") or not _only_person(m["p"], lexicon):
        return text
    return f"Just {m['x']} {m['to']} {m['p']}{text[m.end() :]}"


# "None of the boxes, just the scanner to Mia."
_NONE_OF37R = re.compile(r"^none of (?P<x>the [a-z]+),\s*(?=(?:just|only) )", _F)


def _none_of37r(text: str, _lexicon: Lexicon) -> str:
    """Session 37 (12r): an opening "None of the boxes, just …" is "Not the boxes, just …"."""
    return _NONE_OF37R.sub(lambda m: f"Not {m['x']}, ", text)


# "Leave the drill, Kofi only wants the torch."
_LEAVE_ONLY37R = re.compile(
    r"^leave (?P<x>the [a-z]+(?: [a-z]+)??)(?: (?:be|alone|where it is))?,\s*(?:"
    r"(?P<p>[a-z][\w ]*?) (?P<o>only|just) (?P<v>wants|needs) (?P<y>the [a-z]+(?: [a-z]+)?)|"
    r"it(?:'s| is) (?P<o2>only|just) (?P<y2>the [a-z]+(?: [a-z]+)??) (?:that )?"
    r"(?P<p2>[a-z][\w ]*?) (?P<v2>wants|needs))(?=\s*(?:[,.!]|$))",
    _F,
)


def _leave_only37r(text: str, lexicon: Lexicon) -> str:
    """Session 37 (12r): "Leave the drill, Kofi only wants the torch" and "Leave the chips be,
    it's only the bottle Person A wants" are "Kofi only wants the torch, not the drill" (one
    person, two whole objects, each another)."""
    m = _LEAVE_ONLY37R.match(text)
    if m is None:
        return text
    p, o, v, y = (
        (m["p"], m["o"], m["v"], m["y"]) if m["p"] else (m["p2"], m["o2"], m["v2"], m["y2"])
    )
    if not _only_person(p, lexicon) or not _objects34r(lexicon, m["x"], y):
        return text
    return f"{p} {o.lower()} {v} {y}, not {m['x']}{text[m.end() :]}"


# -- corrections: the corrected words said again in a clause ------------------------------------

# the cues before a correction, one or more between commas
_CUE37R = (
    r"(?:(?:or |oh )?no|sorry|correction|my mistake|my bad|oh dear|oops|whoops|wait|hang on|"
    r"hold on|hang about|actually|what am i saying)"
)
_RESTATED37R = re.compile(
    rf",\s*(?P<cues>{_CUE37R}(?:,?\s*{_CUE37R})*),\s*"
    r"(?:there's no (?P<gone>[a-z][\w ]*?) here,\s*)?(?:"
    r"(?:it|that|they) should (?:be|go to|be for) (?P<p1>[a-z][\w ]*?)|"
    r"(?P<pro2>it's|it is|they're|they are) for (?P<p2>[a-z][\w ]*?)|"
    r"(?P<p3>[a-z][\w ]*?) (?:gets|should get|should have|is having|'s having) (?:it|them)|"
    r"(?P<x1>the [a-z]+(?: [a-z]+)?) (?:goes|should go|belongs) there|"
    r"it (?:goes|should go|belongs) (?:on|in|onto|into) (?P<s1>the [a-z]+(?: [a-z]+)?)|"
    r"it was (?P<x2>the [a-z]+(?: [a-z]+)?) (?P<pro>he|she) (?:asked (?:me )?for|wanted|meant)|"
    r"(?P<pro3>he|she) (?:wanted|wants|asked (?:me )?for|meant|needs|needed|was after) "
    r"(?P<x3>the [a-z]+(?: [a-z]+)?))"
    r"(?=\s*(?:[,.!]|$))",
    _F,
)


# "Chips for Person A, no, sorry, I meant to say the bottle." (a scene without chips)
_UNKNOWN_CORRECTED37R = re.compile(
    rf"^(?P<x>(?:the )?[a-z]+) (?P<to>for|to) (?P<p>[a-z][\w ]*?),\s*{_CUE37R}"
    rf"(?:,?\s*{_CUE37R})*,?\s*(?:i (?:meant|mean)(?: to say)?,?\s*)?(?P<y>the [a-z]+(?: [a-z]+)?)"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _unknown_corrected37r(text: str, lexicon: Lexicon) -> str:
    """Session 37 (12r): "Chips for Person A, no, sorry, I meant to say the bottle" in a scene
    without chips is "The bottle for Person A": the object said first names nothing of the scene
    (the grammar's corrections look for it there, and refuse), the one corrected to is one whole
    object of it, the person one person."""
    m = _UNKNOWN_CORRECTED37R.match(text)
    if m is None or not _names_nothing(m["x"], lexicon) or not _only_person(m["p"], lexicon):
        return text
    word = m["x"].lower().removeprefix("the ")
    if word in WORDS or word in VERBS or not _whole_name(m["y"], lexicon, "object"):
        return text
    y = m["y"][:1].upper() + m["y"][1:]
    return f"{y} {m['to']} {m['p']}{m['end'] or '.'}"


def _number_fits37r(pronoun: str, before: str, lexicon: Lexicon) -> bool:
    """Whether 'it' / 'they' ``pronoun`` may stand for the objects ``before`` names: 'it' for one
    object said by a name not ending in 's', 'they' for two or more or one said so ('the
    chips')."""
    said = [it.text for it in _names(before, lexicon) if it.refs[0].kind == "object"]
    plural = len(said) > 1 or (len(said) == 1 and said[0].lower().endswith("s"))
    return bool(said) and plural == pronoun.lower().startswith("they")


def _restated37r(text: str, lexicon: Lexicon) -> str:
    """Session 37 (12r): after a correction cue ("no", "oh dear, my mistake", "or no, wait",
    "No, correction", "what am I saying"), the person, object or surface corrected to said again
    in a clause ("it should be Person B", "they're for Person B", "Person A gets it", "the bib
    goes there", "it goes on the table", "it was the apple he asked me for", "she wanted the
    apple") is ", no, <it>": one request before the cue (one person for 'it was …
    he asked for' and 'she wanted …', that person one the pronoun may be; a surface before for
    'goes there', and one object for 'it goes on …'; "there's no P here" only of a person said
    before whom the scene lacks)."""
    m = _RESTATED37R.search(text)
    if m is None:
        return text
    before = text[: m.start()]
    if m["gone"] and (
        not re.search(rf"\b{re.escape(m['gone'])}\b", before, _F)
        or any(
            m["gone"].lower() in (h.name.lower(), *(a.lower() for a in h.aliases))
            for h in lexicon.scene.humans
        )
    ):
        return text
    person = m["p1"] or m["p2"] or m["p3"]
    if person is not None:
        if not _only_person(person, lexicon) or not _ids(before, lexicon, "object"):
            return text
        if m["pro2"] and not _number_fits37r(m["pro2"], before, lexicon):
            return text
        said = person
    elif m["x1"] is not None:
        if not _whole_name(m["x1"], lexicon, "object") or not _ids(before, lexicon, "surface"):
            return text
        said = m["x1"]
    elif m["s1"] is not None:
        if not _whole_name(m["s1"], lexicon, "surface") or not _ids(before, lexicon, "surface"):
            return text
        if len(_ids(before, lexicon, "object")) != 1:
            return text
        said = m["s1"]
    else:
        people = _ids(before, lexicon, "human")
        x, pro = (m["x2"], m["pro"]) if m["x2"] else (m["x3"], m["pro3"])
        if not _whole_name(x, lexicon, "object") or len(people) != 1:
            return text
        if not _may_be35t(next(iter(people)), pro, lexicon):
            return text
        said = x
    return f"{before}, no, {said}{text[m.end() :]}"


# "Give the apple to Person B, or was it Person A, yes, Person A."
_OR_WAS_IT37R = re.compile(
    r",\s*or was it (?P<a>[a-z][\w ]*?),\s*yes,\s*(?P<b>[a-z][\w ]*?)(?=\s*(?:[,.!]|$))", _F
)


def _or_was_it37r(text: str, _lexicon: Lexicon) -> str:
    """Session 37 (12r): ", or was it Person A, yes, Person A" is the speaker asking themself and
    answering: ", no, Person A" (the same words both times; else left)."""
    m = _OR_WAS_IT37R.search(text)
    if m is None or m["a"].lower() != m["b"].lower():
        return text
    return f"{text[: m.start()]}, no, {m['b']}{text[m.end() :]}"


# "A blanket each for the patients."
_EACH_FOR_ROLE37R = re.compile(
    r"^(?:a|one) (?P<k>[a-z]+) (?:each|apiece) for the (?P<role>[a-z]+?)s(?=\s*(?:[,.!]|$))", _F
)


def _each_for_role37r(text: str, lexicon: Lexicon) -> str:
    """Session 37 (12r): "A blanket each for the patients" is "Each patient gets a blanket" (two
    or more people of the scene have that role; the grammar then checks the count)."""
    m = _EACH_FOR_ROLE37R.match(text)
    if m is None:
        return text
    role = m["role"].lower()
    holders = [h for h in lexicon.scene.humans if role in (a.lower() for a in h.aliases)]
    if len(holders) < 2:
        return text
    return f"Each {role} gets a {m['k']}{text[m.end() :]}"


# "Bottle to Person A and chips to Person B, no, the other way about."
_WAY_ABOUT37R = re.compile(r"\bthe other way about\b", _F)


def _way_about37r(text: str, _lexicon: Lexicon) -> str:
    """Session 37 (12r): "the other way about" is "the other way round"."""
    return _WAY_ABOUT37R.sub("the other way round", text)


# "Noah should get the globe, hang about, I mean Zoe."
_HANG_ABOUT37R = re.compile(
    r",\s*hang about,\s*(?=(?:i mean|i meant|no|sorry|make (?:that|it))\b)", _F
)


def _hang_about37r(text: str, _lexicon: Lexicon) -> str:
    """Session 37 (12r): ", hang about," before a correction ("I mean Zoe") is ", hang on,"."""
    return _HANG_ABOUT37R.sub(", hang on, ", text)


_STEPS37R: tuple[Callable[[str, Lexicon], str], ...] = (
    _something_for37r,
    _as_long_as37r,
    _any_arm37r,
    _one_other37r,
    _will_do_him37r,
    _needs_on_it37r,
    _who_which37r,
    _wont_mind_if37r,
    _got_coming37r,
    _to_his_do37r,
    _thats_n37r,
    _the_one_item37r,
    _n_things_each37r,
    _every_last37r,
    _only_one_got37r,
    _pair_of37r,
    _every_included37r,
    _lesson_on37r,
    _doesnt_only37r,
    _nothing_besides37r,
    _cleft_isnt37r,
    _no_wait37r,
    _had_fill37r,
    _except_commas37r,
    _only_for37r,
    _none_of37r,
    _leave_only37r,
    _restated37r,
    _unknown_corrected37r,
    _or_was_it37r,
    _each_for_role37r,
    _way_about37r,
    _hang_about37r,
)


_STEPS36R: tuple[Callable[[str, Lexicon], str], ...] = (
    _one_thing_listed36r,
    _whichever_of_them36r,
    _either_then_one36r,
    _mind_if36r,
    _says_will_do36r,
    _one_apiece36r,
    _people_things36r,
    _each_role36r,
    _one_whos36r,
    _isnt_hers36r,
    _no_need36r,
    _stays_but36r,
    _but_not_those36r,
    _fronted_rest36r,
    _does_why36r,
    _whats_name36r,
    _full_after36r,
    _its_x_wants36r,
    _thats_hers36r,
    _theres_one36r,
    _them_remark36r,
    _wants_to_v36r,
    _state_here36r,
    _same_van36r,
    _her_ones36r,
    _only_chew36r,
    _where_was_i36r,
)


_STEPS35R: tuple[Callable[[str, Lexicon], str], ...] = (
    _pronoun_take35r,
    _really_mind35r,
    _apiece35r,
    _which_robot35r,
    _will_do_for35r,
    _handy35r,
    _the_one35r,
    _after_her35r,
    _counted_state35r,
    _gather35r,
    _load_with35r,
    _both_named35r,
    _leave_be35r,
    _though_stays35r,
    _own35r,
    _instead35r,
    _hers35r,
    _only_to35r,
    _fronted_every35r,
    _cleft_not_then35r,
    _got_wrong35r,
    _rather_have35r,
    _who_getting35r,
    _meant_for35r,
    _rather_person35r,
    _wrong_way35r,
    _change_that35r,
    _belongs35r,
    _late_alone35r,
    _takes_off35r,
    _and_for35r,
    _it_says35r,
    _rather_after35r,
    _likes_both35r,
    _not_first35r,
    _only_wants35r,
    _only_one35r,
    _not_theirs35r,
    _dont_instead35r,
    _whoever_not35r,
    _anything_but35r,
    _keep_losing35r,
    _isnt_on35r,
)


_STEPS34R: tuple[Callable[[str, Lexicon], str], ...] = (
    _over_with_fixed34r,
    _are_hers34r,
    _going_out34r,
    _has_one34r,
    _need_it_for34r,
    _split_between34r,
    _not_for_after34r,
    _straight_with_it34r,
    _she_said34r,
    _corrected_place_why34r,
    _join_the34r,
    _brought_own34r,
    _whichever_closer34r,
    _stays_put34r,
    _its_p_who34r,
    _better_down34r,
    _owner_then34r,
    _surface_for34r,
    _no_wait_to34r,
    _said_better34r,
    _still_need34r,
    _no_good34r,
    _not_one_other34r,
    _at_table34r,
    _rather_order34r,
    _swap_order34r,
    _both_something34r,
    _that_is_a34r,
    _leave_that34r,
    _counted_want34r,
    _final_answer34r,
    _place_better34r,
    _meant_to_get34r,
    _after_all_along34r,
    _first_said34r,
    _placed_then34r,
    _only_here34r,
    _whichever_of34r,
    _something_for34r,
    _pick_whichever34r,
    _either_named34r,
    _both_like34r,
    _one_for_each34r,
    _split_so34r,
    _lay_hands34r,
    _lone_one34r,
    _nobody_without34r,
    _gets_handed34r,
    _alike34r,
    _we_have34r,
    _one_one34r,
    _pair_listed34r,
    _where_live34r,
    _anything_but34r,
    _leaving_aside34r,
    _only_gets34r,
    _no_fuss34r,
    _nothing_fancy34r,
    _not_q_one34r,
    _but_not_on34r,
    _wants_to_use34r,
    _one_by34r,
)


# -- session 37 (engineer 12): blind35's refusals by kind in the sections of politeness, wants,
# pronouns and ellipsis, splits and run-ons, lower case, typos and questions. As session 36's:
# each rule a closed pattern checked against the scene; a remark goes only when it names nothing
# of the scene and asks nothing (_asks_nothing29, _trade_words29, or a closed list in its
# pattern), and a pronoun only where it may be the one person it is said of (_fit36).

# a person's name as the rules below take it (checked by _only_person)
_P37 = r"(?:Person [A-Z]|(?:Mrs|Mr|Ms|Miss|Dr) [A-Z][a-z]+|[A-Z][a-z]+)"
# a want or a receipt said of a person: what a reason of theirs may close
_WANT_FRAME37 = re.compile(
    r"\b(?:wants|needs|fancies|could use|could do with|would love|would like|is after|'s after|"
    r"gets|is getting|'s getting|could have|can have|is having|'s having|(?:is|are|'s|'re) for|"
    r"(?:'s|has|is|'d|had) been (?:craving|wanting|after|on about|asking for)|craving|"
    r"(?:was|is|'s) on about|(?:is|'s) (?:desperate|gasping|dying|parched|gagging) for|"
    r"asked for|crying out for)\b",  # session 40 (12): "Person B's crying out for the chips"
    _F,
)
# the speaker's doing or a pastime said as a time, not a thing done: 'after his meeting' says when
_EVENTS37 = frozenset(
    {
        "meeting", "wedding", "briefing", "morning", "evening", "hearing", "screening", "reading",
        "opening", "closing", "building", "ceiling", "thing", "something", "nothing", "anything",
        "everything", "bring", "bringing", "sing", "king", "ring", "spring", "string", "wing",
        "ending", "beginning", "starting", "landing", "booking", "check", "calling", "outing",
    }
)  # fmt: skip
# "… wants the chips after his bodyboarding", "… gets the bottle after his sumo practice", "… are
# for Person A after her padel game", "… craving since his gliding lesson", "…, after the wild
# swimming": what made the person want it, their own doing (a word in -ing, or a game, lesson,
# practice … of theirs) closing a want of one person (session 35's closed list, said generally)
_DOING37 = (
    r"(?:[a-z]+ ){0,2}?(?:[a-z]{3,}ing|(?:[a-z]+ )?(?:practice|game|lesson|class|session|match|"
    r"training|workout|club|rehearsal)|swim|run|walk|ride|jog|hike|climb|row|paddle|gig|"
    r"yoga|pilates|karate|judo|chess|darts|golf|tennis|football|netball|cricket|rugby|hockey|"
    r"squash|badminton|choir|ballet|embroidery|needlework|patchwork|pottery|origami|gymnastics|"
    r"aerobics|crochet|bingo|cribbage|kendo|crossfit|zumba|parkour|archery|fencing|physio|nap|"
    r"massage|sauna)"
)
_AFTER_DOING37 = re.compile(
    r"(?P<lead>,\s*|\s+)(?:after|(?:ever )?since|following) (?:(?P<pron>his|her|their)|the|"
    r"(?P<a>a|an) (?:(?:whole|full|long|hard|busy|good) )?(?:hour|day|morning|afternoon|evening|"
    # session 40 (12): 'a day's <doing>' ("after a day's fly fishing") as 'a day of'
    rf"week|session|shift|stint|night)(?: of| at|'s)) (?P<doing>{_DOING37})(?=\s*(?:[,.;!?]|$))",
    _F,
)
# after 'X is for P' only a doing said as one (a word in -ing, a game, a lesson …): a pastime's
# name alone there says when (test_phrasing_s35r's "The bottle is for Person A after her
# gymnastics." stays refused)
_IS_FOR37 = re.compile(r"\b(?:is|are|'s|'re) for\b", _F)
_PLAYED37 = re.compile(
    r"(?:[a-z]{3,}ing|practice|game|lesson|class|session|match|training|workout|club|rehearsal)$",
    _F,
)
# session 42 (12s): the clause just before the occasion an order ("Bob wants the cup, give it to
# him after his match"): 'after' of an order puts it off (the time rules refuse it), whatever want
# was said before
_ORDER_LAST37 = re.compile(
    r"(?:^|[.;:!?,]\s*|\s(?:and|so|then|but)\s+)(?:(?:please|kindly|just|now|so|then)[, ]+)*"
    r"(?:give|hand|pass|bring|take|deliver|put|place|set|leave|send|get|fetch|pop|stick|move|"
    r"carry|run|drop|let)\b[^.;:!?,]*$",
    _F,
)
# "After his shift, Bob needs the cup.": the same, fronted, before a want of the one person
_AFTER_HIS37 = re.compile(
    rf"^(?:after|following) (?P<pron>his|her|their) (?P<doing>{_DOING37}),\s*", _F
)


def _after_doing37(text: str, lexicon: Lexicon) -> str:
    """Session 37: 'after his <doing>' above taken off when the doing names nothing and asks
    nothing (no event word, _EVENTS37), the sentence before it is a want (_WANT_FRAME37) of one
    person, objects and no surface, and the pronoun may be that person ('the' with a word in -ing
    only); said first ('After his shift, …'), the sentence after it."""
    if not re.search(r"\b(?:after|since|following)\b", text, _F):
        return text
    m = _AFTER_HIS37.match(text)
    if m is not None and _asks_nothing29(m["doing"], lexicon):
        rest = text[m.end() :]
        sent = re.split(r"[.;!?]\s+", rest)[0]
        people = _ids(sent, lexicon, "human")
        if (
            m["doing"].split()[-1].lower() not in _EVENTS37
            and len(people) == 1
            and _WANT_FRAME37.search(sent)
            and _ids(sent, lexicon, "object")
            and not _ids(sent, lexicon, "surface")
            and (m["pron"].lower() == "their" or _fit36(next(iter(people)), m["pron"], lexicon))
        ):
            return rest[0].upper() + rest[1:]
    for m in _AFTER_DOING37.finditer(text):
        doing = m["doing"]
        last = doing.split()[-1].lower()
        if last in _EVENTS37 or not _asks_nothing29(doing, lexicon):
            continue
        if m["pron"] is None and m["a"] is None and not last.endswith("ing"):
            continue
        before = re.split(r"[.;!?]\s+", text[: m.start()])[-1]
        people = _ids(before, lexicon, "human")
        if len(people) != 1 or not _WANT_FRAME37.search(before):
            continue
        if _ORDER_LAST37.search(before):
            continue  # "…, give it to him after his match": an order put off (session 42, 12s)
        if _IS_FOR37.search(before) and not _PLAYED37.search(doing):
            continue  # "The bottle is for Person A after her gymnastics": a time (12r, s35r)
        if not _ids(before, lexicon, "object") or _ids(before, lexicon, "surface"):
            continue
        pron = (m["pron"] or "their").lower()
        if pron != "their" and not _fit36(next(iter(people)), pron, lexicon):
            continue
        return text[: m.start()] + text[m.end() :]
    return text


# "After a whole hour of crossfit, Person A is gasping for that bottle.": how long someone was at
# something, opening a want
_HOUR_OF37 = re.compile(
    r"^(?:after|following) (?:a|an|one|two|three|the) (?:(?:whole|full|long|hard|solid|entire|"
    r"busy|good) )?(?:hour|hours|day|morning|afternoon|evening|week|session|shift|stint|night) "
    r"(?:of|at) (?P<doing>[a-z]+(?: [a-z]+)?),\s*",
    _F,
)
# "Person B's the one who's in need of the bottle", "Person B is in need of the bottle",
# "Dana's got to have the spoon": a need said by a frame
_IN_NEED37 = re.compile(
    rf"\b(?P<p>{_P37})(?:(?:'s| is) the one (?:who's|who is|that's|that is) in (?:dire |real |"
    r"urgent )?need of|(?:'s| is) in (?:dire |real |urgent )?need of|(?:'s| has) (?:got to|gotta) "
    r"have| (?:wouldn't|would not) say no to|(?:'s| has) been on at (?:me|us) (?:about|for)|"
    r"(?:'s| is) on at (?:me|us) (?:about|for)| would kill for| could (?:really |just )?go for) "
    r"(?=(?:the|that|this|those|these|her|his|their) )",
    _F,  # session 41: case-blind ("person a's got to have the bottle"); P is checked as a person
)
# "Emma would quite fancy the green cup": an adverb between 'would' and the want
_WOULD_QUITE37 = re.compile(
    r"\bwould (?:quite|really|rather|so|just|very much|dearly|truly) (?P<v>fancy|like|love)\b",
    _F,
)
# "The crisps are the thing Bob's been craving": the thing = what
_THE_THING37 = re.compile(
    rf"\b(?P<be>is|are) the (?:(?:one|only|very) )?things? (?:that |which )?(?P<p>{_P37})"
    r"(?P<v>'s been|'s|has been|is|was|had been|'d been) (?P<w>craving|wanting|after|on about|"
    r"asking for|dreaming of|longing for|hankering after|going on about)\b",
)
# ", by the look of him": how the speaker can tell, closing a want of one person
_BY_LOOK37 = re.compile(
    r",\s*by the looks? of (?P<pron>him|her|them|things|it)(?P<end>\s*[.!]?)\s*$", _F
)
# "Tom needs the work gloves for unloading the pallets": what the thing is needed for, a doing
# that is no verb of the grammar, closing a need of one person
_FOR_DOING37 = re.compile(
    r"\s+for (?P<v>[a-z]{3,}ing) (?P<what>(?:the |those |these |some |a |an )?[a-z]+(?: [a-z]+)?)"
    r"(?P<end>\s*[.!]?)\s*$",
    _F,
)
