"""The normaliser's rules of sessions 10-37, part 5 of 5 (docs/grounding.md: where they live)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.grounding import gate as re
from hltl.grounding._normalise1 import (
    _F,
    _ids,
    _names,
    _names_nothing,
    _objects_only,
    _only,
    _only_person,
    _surface_only,
)
from hltl.grounding._normalise2 import (
    _ASKS29,
    _DET32,
    _asks_nothing29,
    _things31,
    _trade_words29,
)
from hltl.grounding._normalise4 import (
    _BY_LOOK37,
    _FOR_DOING37,
    _HOUR_OF37,
    _IN_NEED37,
    _P37,
    _THE_THING37,
    _WANT_FRAME37,
    _WOULD_QUITE37,
    _after_doing37,
    _fit36,
)
from hltl.grounding.lexicon import (
    PRONOUN_SEX,
    VERBS,
    Lexicon,
    name_sexes,
    title_sex,
)


def _wants_framed37(text: str, lexicon: Lexicon) -> str:
    """Session 37: the want frames above said plainly: 'after an hour of X, ' opening a want of one
    person (X naming nothing, asking nothing) taken off; 'P's the one who's in need of' / 'P's
    got to have' as 'P needs' (P one person); 'would quite fancy' as 'would fancy'; 'X are the
    thing P's been craving' as 'X are what P's been craving'; ', by the look of him' closing a
    want of one person the pronoun may be taken off; 'for unloading the pallets' closing a need of
    one person (a doing no verb of the grammar, its object naming no object or person) taken
    off."""
    m = _HOUR_OF37.match(text)
    if m is not None and _asks_nothing29(m["doing"], lexicon):
        rest = text[m.end() :]
        if _WANT_FRAME37.search(rest) and len(_ids(rest, lexicon, "human")) == 1:
            text = rest[0].upper() + rest[1:]
    m = _IN_NEED37.search(text)
    if m is not None and _only_person(m["p"], lexicon):
        text = f"{text[: m.start()]}{m['p']} needs {text[m.end() :]}"
    text = _WOULD_QUITE37.sub(lambda m: f"would {m['v']}", text)
    m = _THE_THING37.search(text)
    if m is not None and _only_person(m["p"], lexicon):
        text = f"{text[: m.start()]}{m['be']} what {m['p']}{m['v']} {m['w']}{text[m.end() :]}"
    m = _BY_LOOK37.search(text)
    if m is not None:
        before = text[: m.start()]
        people = _ids(before, lexicon, "human")
        if (
            len(people) == 1
            and _WANT_FRAME37.search(before)
            and m["pron"].lower() in ("him", "her")
            and _fit36(next(iter(people)), m["pron"], lexicon)
        ):
            text = before + m["end"].strip()
    m = _FOR_DOING37.search(text)
    if m is not None and m["v"].lower() not in VERBS:
        before = text[: m.start()]
        if (
            _asks_nothing29(m["v"], lexicon)
            and _ASKS29.search(m["what"]) is None
            and not _ids(m["what"], lexicon, "object")
            and not _ids(m["what"], lexicon, "human")
            and re.search(r"\b(?:needs|'s going to need|will need|wants)\b", before, _F)
            and len(_ids(before, lexicon, "human")) == 1
            and _ids(before, lexicon, "object")
        ):
            text = before + m["end"].strip()
    return text


# -- courtesies and the speaker's remarks
# "…, from a very tired steel fixer.": the message signed by the speaker's trade
_SIGNED37 = re.compile(
    r",\s*(?:and\s+)?from (?:a|an|the|one|your|yours truly, a) (?:(?:very|rather|pretty|really|"
    r"ever so|so|most) )?(?:(?P<adj>tired|weary|grateful|thankful|thirsty|hungry|busy|happy|"
    r"exhausted|knackered|humble|harassed|frazzled|cold|wet|worn-out|worn out|old|young|"
    r"friendly|hard-working|hardworking) )?(?P<trade>[a-z]+(?: [a-z]+)?)(?P<end>\s*[.!]?)\s*$",
    _F,
)
# a word for someone who does something ('fixer', 'shunter', 'philatelist', 'keeper')
_DOER37 = re.compile(r"(?:er|or|ist|ian|man|woman|hand|keeper|maker|smith|wright|eer|ant|ent)$", _F)
# "…, I'm a french polisher and I need the room": the speaker needs room (to work), closing
_NEED_ROOM37 = re.compile(
    r"(?P<lead>,\s*|\s+and\s+)(?:I|we) (?:need|want|could use|could do with) (?:the |some |a bit "
    r"of |a bit more |more )?(?P<what>room|space|elbow room|desk space|floor space)"
    r"(?P<end>\s*[.!?]?)\s*$",
    _F,
)
# "…, if that's not too much to ask of you": asked kindly (session 14's, with 'that' and 'of you')
_TOO_MUCH37 = re.compile(
    r",?\s*if (?:it's|it is|that's|that is|it isn't|that isn't) (?:not )?too much to ask"
    r"(?: of you| of anyone)?(?P<end>\s*[.!]?)\s*$",
    _F,
)
# "… give Person B the cup then that's all, …": the closer joined by 'then'
_THEN_ALL37 = re.compile(r"\s+(?:and )?then (?P<c>(?:that's|that is) (?:all|it|everything))\b", _F)
# "the apple's meant for Person B": the object's 'is' contracted before 'meant for'
_MEANT_FOR37 = re.compile(
    r"\b(?P<x>(?:the|that|this) [a-z]+(?: [a-z]+)?)'s (?=(?:meant|intended|supposed|reserved|"
    r"earmarked|set aside) for\b)",
    _F,
)


def _courtesies37(text: str, lexicon: Lexicon) -> str:
    """Session 37: a sign-off from the speaker's trade (_trade_words29) closing a request; 'I need
    the room' closing (the room naming nothing of the scene); 'if that's not too much to ask (of
    you)' closing; 'then that's all' as ', that's all' after a request; 'the apple's meant for'
    as 'the apple is meant for' (X objects only) — each when what is left names something."""
    out = text
    m = _SIGNED37.search(out)
    if (
        m is not None
        and _trade_words29(m["trade"], lexicon)
        and (m["adj"] or _DOER37.search(m["trade"]))
    ):
        out = out[: m.start()] + m["end"].strip()
    m = _NEED_ROOM37.search(out)
    if m is not None and _names_nothing(m["what"], lexicon):
        out = out[: m.start()] + m["end"].strip()
    m = _TOO_MUCH37.search(out)
    if m is not None:
        out = out[: m.start()] + m["end"].strip()
    m = _THEN_ALL37.search(out)
    if m is not None and _names(out[: m.start()], lexicon):
        out = f"{out[: m.start()]}, {m['c']}{out[m.end() :]}"
    m = _MEANT_FOR37.search(out)
    if m is not None and _things31(m["x"], lexicon):
        out = f"{out[: m.start()]}{m['x']} is {out[m.end() :]}"
    if out == text or not _names(out, lexicon):
        return text
    return out


# -- remarks about the person a request is for
# "…, she's a messy little thing", "…, he's a roughneck on leave": said of the one person
_SHE_IS_A37 = re.compile(
    r",\s*(?P<pron>he|she)(?:'s| is) (?:a|such a|a right|a proper|a real|an) (?P<what>(?:[a-z]+ )"
    r"{0,2}(?:thing|one|soul|mite|lamb|monkey|scamp|rascal|pickle|sweetheart|darling)|[a-z]+"
    r"(?: [a-z]+)? (?:on leave|off duty|on holiday|on his day off|on her day off|on a break|"
    r"between shifts|on nights|on earlies|on lates))(?P<end>\s*[.!]?)\s*$",
    _F,
)
# "… to Alice? She's just back from crabbing.", "She's tired from tap dancing.": a sentence of
# the one person's state after a pastime
_BACK_FROM37 = re.compile(
    r"(?<=[.!?])\s+(?P<pron>he|she)(?:'s| is) (?:just |only just |only )?(?:(?:back|home|in) from|"
    r"(?:tired|worn out|exhausted|shattered|knackered|sleepy|hungry|thirsty|sore|wet|cold|"
    r"starving|parched|done in) (?:from|after)) (?P<doing>[a-z]+(?: [a-z]+)?)\s*[.!]?\s*$",
    _F,
)
# "… over to Person A? Her airsoft game starts at four.": when the one person's doing starts
_HERS_AT37 = re.compile(
    r"(?<=[.!?])\s+(?P<pron>his|her) (?P<what>[a-z]+(?: [a-z]+)?) (?:starts|finishes|ends|"
    r"kicks off|is over|begins) at (?:one|two|three|four|five|six|seven|eight|nine|ten|eleven|"
    r"twelve|[0-9]{1,2})(?: o'clock| oclock| ?[ap]m)?\s*[.!]?\s*$",
    _F,
)
# ", they've both been down with the tunneller all day": of the people just named, closing
_BOTH_BEEN37 = re.compile(
    r",\s*they(?:'ve| have) (?:both|all) been (?P<what>[a-z]+(?: [a-z]+){0,3}?) (?:all day|all "
    r"morning|all afternoon|all night|all week|since dawn|since first thing)(?P<end>\s*[.!]?)\s*$",
    _F,
)
# "…, and that's her sorted": the closer said of the one person ('them' of the people named)
_THATS_HER37 = re.compile(
    r"(?:,\s*|\s+)and that's (?P<pron>her|him|them|everyone|everybody) (?:sorted|done|set|happy|"
    r"settled|seen to)"
    r"(?: out)?(?P<end>\s*[.!]?)\s*$",
    _F,
)


def _said_of_one37(text: str, m: re.Match[str], words: str, lexicon: Lexicon) -> str:
    """``text`` without the remark ``m`` (its words naming nothing, asking nothing: the closed
    words of the pattern taken out first) when the text before it names one person its pronoun
    may be, and something else."""
    plain = re.sub(
        r"\b(?:thing|one|on leave|off duty|on holiday|on (?:his|her) day off|on a break|between "
        r"shifts|on nights|on earlies|on lates)\b",
        "",
        words,
        flags=_F,
    ).strip()
    if plain and not _asks_nothing29(plain, lexicon):
        return text
    before = text[: m.start()]
    people = _ids(before, lexicon, "human")
    if len(people) != 1 or not _fit36(next(iter(people)), m["pron"], lexicon):
        return text
    if not _ids(before, lexicon, "object"):
        return text
    return before + (m["end"].strip() if "end" in m.groupdict() and m["end"] else "")


def _about_them37(text: str, lexicon: Lexicon) -> str:
    """Session 37: the remarks above about the person (or people) a request is for taken off:
    the pronoun may be the one person named before it (_fit36), the words name nothing and ask
    nothing; 'they've both been …' after two or more people; 'that's them sorted' after any."""
    m = _SHE_IS_A37.search(text)
    if m is not None:
        text = _said_of_one37(text, m, m["what"], lexicon)
    m = _BACK_FROM37.search(text)
    if m is not None:
        text = _said_of_one37(text, m, m["doing"], lexicon)
    m = _HERS_AT37.search(text)
    if m is not None:
        text = _said_of_one37(text, m, m["what"], lexicon)
    m = _BOTH_BEEN37.search(text)
    if (
        m is not None
        and _asks_nothing29(m["what"], lexicon)
        and len(_ids(text[: m.start()], lexicon, "human")) >= 2
    ):
        text = text[: m.start()] + m["end"].strip()
    m = _THATS_HER37.search(text)
    if m is not None:
        people = _ids(text[: m.start()], lexicon, "human")
        pron = m["pron"].lower()
        one = len(people) == 1 and _fit36(next(iter(people)), pron, lexicon)
        if (one if pron in ("her", "him") else bool(people)) and _names(text[: m.start()], lexicon):
            text = text[: m.start()] + m["end"].strip()
    return text


# -- pronouns and ellipsis
# "Person A, that's the apple for you.", "Person B, yours is the bottle.": a person called, then
# what is theirs
_YOURS37 = re.compile(
    rf"(?:^|(?<=[.!?;])\s+)(?P<p>{_P37}),\s*(?:(?:that's|that is|here's|here is|this is) "
    rf"(?P<x>{_DET32} [a-z][a-z ]*?) for you|(?:yours is|yours'll be|yours will be) "
    rf"(?P<y>{_DET32} [a-z][a-z ]*?)|(?P<z>{_DET32} [a-z][a-z ]*?)(?:'s| is) yours)"
    r"(?=\s*(?:[.!;]|$))",
    _F,
)
# "There's Person A, pass her the bottle", "Lena's run out of salt at her table, take her the
# salt": the person shown or said to lack something, then a request with a pronoun for them
_THERE_P37 = re.compile(
    rf"^(?:(?:right|ok|okay|so|look),\s*)?(?:(?:there's|there is|that's|that is) (?P<p>{_P37})"
    rf"(?: over there| there)?,|(?:see|look at) (?P<q>{_P37})(?: over there| there)?\?|(?P<r>"
    rf"{_P37})(?:'s| is) the (?P<d>[a-z]+(?: [a-z]+)??)(?P<one> one)?,)\s*(?P<req>.+)$",
    _F,
)
_RUN_OUT37 = re.compile(
    rf"^(?P<p>{_P37})(?:'s| has| is) (?:run out of|run short of|run low on|out of|short of|low "
    r"on) (?:(?:the|her|his|their|any) )?(?P<x>[a-z]+)(?: (?:at|on|by) (?:her|his|their) "
    r"(?:table|desk|station|place|end|spot|seat|bench))?,\s*(?P<req>.+)$",
    _F,
)
# "Right, there's the bottle, Person A's waiting on it, …": the object shown, then who wants it
_THERE_X37 = re.compile(
    rf"^(?:(?:right|ok|okay|so|look),\s*)?(?:there's|there is|here's|here is) (?P<x>{_DET32} "
    rf"[a-z][a-z ]*?),\s*(?P<p>{_P37})(?P<w>'s been|'s| is| has been) (?P<v>waiting on|waiting "
    r"for|after|"
    r"asking for|wanting) (?P<pron>it|them)\b",
    _F,
)
# "…, so off you go now": sends the hearer off, closing
_OFF_YOU_GO37 = re.compile(
    r",\s*(?:so |and |now )?off you go(?: now| then)?(?P<end>\s*[.!]?)\s*$", _F
)
# "…, and then it's the bottle for Person A": 'it's' before what is for whom
_THEN_ITS37 = re.compile(
    rf"\b(?P<then>then|after that|next),? (?:it's|it is) (?=(?P<x>{_DET32} [a-z][a-z ]*?) for "
    rf"(?P<p>{_P37})\s*(?:[.!;]|$))",
    _F,
)
# "Emma's only here for the afternoon as a visitor, …": who the person is here as
_HERE_AS37 = re.compile(
    rf"(?P<p>{_P37})(?P<here>(?:'s| is) (?:only |just )?(?:here|in|around|visiting)\b"
    r"[^,.;!?]*?) as (?:a|an|our|the) (?P<t>[a-z]+(?: [a-z]+)?)(?=\s*,)",
    _F,
)
# "Mrs Ortiz put in for the glue": asked for it
_PUT_IN_FOR37 = re.compile(rf"\b(?P<p>{_P37})(?: has|'s)? put in for (?=(?:the|a|an) )")


def _to_person37(req: str, p: str, lexicon: Lexicon) -> str | None:
    """``req`` with its one him/her said as ``p`` when it may be that person and ``req`` names
    no person; else None."""
    said = re.findall(r"\b(?:him|her)\b", req, _F)
    if len(said) != 1 or _ids(req, lexicon, "human"):
        return None
    pid = next(iter(_ids(p, lexicon, "human")))
    if not _fit36(pid, said[0], lexicon):
        return None
    return re.sub(r"\b(?:him|her)\b", p, req, count=1, flags=_F)


def _pronouns37(text: str, lexicon: Lexicon) -> str:
    """Session 37: 'P, that's X for you' / 'P, yours is X' as 'X for P' (P one person, X objects
    only); 'There's P, <request with her>' (or 'That's P over there,', 'See P?', "P's the tall
    one,") and 'P's run out of X, <request with her naming X>' as the request to P; "There's X,
    P's waiting on it" as "P's waiting on X"; ', so off you go now' closing after a want; 'then
    it's X for P' as 'then X for P'; 'P's here … as a visitor' without the trade; 'P put in for X'
    as 'P asked for X'."""

    def yours(m: re.Match[str]) -> str:
        x = m["x"] or m["y"] or m["z"]
        if not _only_person(m["p"], lexicon) or not _things31(x, lexicon):
            return m[0]
        lead = m[0][: len(m[0]) - len(m[0].lstrip())]
        return f"{lead}{x[0].upper()}{x[1:]} for {m['p']}"

    if "you" in text.lower():
        text = _YOURS37.sub(yours, text)
    m = _THERE_P37.match(text) or _RUN_OUT37.match(text)
    said = m.groupdict() if m is not None else {}
    p = said.get("p") or said.get("q") or said.get("r")
    if said.get("d") is not None and (
        not _asks_nothing29(said["d"], lexicon)
        if said.get("one")
        else _ids(said["d"], lexicon) != _ids(p or "", lexicon)
    ):
        p = None  # "Bob's the tall one, …" describes Bob ("the red one" may select); "Emma's the
        # visitor, …" names her again
    if m is not None and p is not None and _only_person(p, lexicon):
        x = said.get("x")
        if x is None or (_objects_only(x, lexicon) and _ids(x, lexicon) <= _ids(m["req"], lexicon)):
            req = _to_person37(m["req"], p, lexicon)
            if req is not None and _names(req, lexicon):
                text = req[0].upper() + req[1:]
    m = _THERE_X37.match(text)
    if m is not None and _only_person(m["p"], lexicon) and _things31(m["x"], lexicon):
        plural = len(_ids(m["x"], lexicon, "object")) > 1 or m["x"].lower().endswith("s")
        if (m["pron"].lower() == "them") == plural:
            text = f"{m['p']}{m['w']} {m['v']} {m['x']}{text[m.end() :]}"
    m = _OFF_YOU_GO37.search(text)
    if m is not None:
        before = text[: m.start()]
        wants = _WANT_FRAME37.search(before) or re.search(r"\bwaiting (?:on|for)\b", before, _F)
        if wants and _names(before, lexicon):
            text = before + m["end"].strip()
    m = _THEN_ITS37.search(text)
    if m is not None and _things31(m["x"], lexicon) and _only_person(m["p"], lexicon):
        text = f"{text[: m.start()]}{m['then']} {text[m.end() :]}"
    m = _HERE_AS37.search(text)
    if m is not None and _only_person(m["p"], lexicon):
        same = _ids(m["t"], lexicon) == _ids(m["p"], lexicon)
        if same or _trade_words29(m["t"], lexicon):
            text = text[: m.start()] + m["p"] + m["here"] + text[m.end() :]
    m = _PUT_IN_FOR37.search(text)
    if m is not None and _only_person(m["p"], lexicon):
        text = f"{text[: m.start()]}{m['p']} asked for {text[m.end() :]}"
    return text


# -- splits, lower case and questions
# "Cup first, onto the counter with it.": where it goes, 'with it' of the one object said before
_WITH_IT37 = re.compile(
    rf"\b(?P<to>(?:on|onto|in|into|up on|over to|to) (?P<s>the [a-z]+(?: [a-z]+)?|{_P37})) with "
    r"(?P<pron>it|them)(?=\s*(?:[.!;]|$))",
    _F,
)
# "…. And the lemon can sit on the worktop.": session 17's 'the X can sit on S' as a later
# sentence
_CAN_SIT37 = re.compile(
    rf"(?<=[.;!?])\s+(?:and |also |oh, and )?(?P<x>{_DET32} [a-z][a-z ]*?) can (?:sit|go|live|"
    r"stay) (?P<on>on|onto|in|into) (?P<s>the [a-z]+(?: [a-z]+)?)(?=\s*(?:[.!]|$))",
    _F,
)
# "crisps go up on the shelf out of bobs reach, hes had plenty": why it goes up there, of one
# person (lower case: 'bobs', 'hes')
_OUT_OF_REACH37 = re.compile(
    r"\s+out of (?P<p>[a-z]+(?: [a-z])?)(?:'s|s|') reach(?:,\s*(?P<pron>he|she)(?:'s|s| has) had "
    r"(?:plenty|enough|too many|too much|loads|his fill|her fill|his share|her share)"
    r"(?: already)?)?(?P<end>\s*[.!]?)\s*$",
    _F,
)
# "Could you do the apple for Person B before anything else, and the bottle for Person A after?":
# a list of 'X for P' asked to be done, with its order
_DO_FOR37 = re.compile(r"^(?:could|can|would|will) you (?:please )?do (?P<rest>.+?)\s*\?\s*$", _F)
_DO_ITEM37 = re.compile(
    rf"(?:and )?(?P<x>{_DET32} [a-z][a-z ]*?) for (?P<p>{_P37})(?: (?:first|after|afterwards|next|"
    r"last|then|second|after that|before anything else))?",
)
# "Could Ava have the teddy, do you think?": the hearer asked to judge, closing a question
_DO_YOU_THINK37 = re.compile(
    r",\s*(?:do you think|d'you think|do you reckon|d'you reckon)(?=\s*\?)", _F
)


def _splits37(text: str, lexicon: Lexicon) -> str:
    """Session 37: 'onto S with it' as 'onto S' (S a surface or one person, one object of the
    pronoun's number named before it in the sentence); a later sentence 'And X can sit on S' as
    'Put X on S' (X objects only, S one surface); 'out of P's reach(, he's had plenty)' closing a
    placement taken off (P one person the pronoun may be); 'could you do X for P before anything
    else, and Y for Q after?' as 'X for P first, and Y for Q after.' (every part 'X for P');
    ', do you think?' closing a question taken off."""
    m = _WITH_IT37.search(text)
    if m is not None and (_surface_only(m["s"], lexicon) or _only_person(m["s"], lexicon)):
        sent = re.split(r"[.;!?]\s+", text[: m.start()])[-1]
        clause = re.split(r",\s*", sent)[-1]  # "onto the counter": no object of its own
        objs = _ids(sent, lexicon, "object")
        if len(objs) == 1 and m["pron"].lower() == "it" and not _names(clause, lexicon):
            text = text[: m.end("to")] + text[m.end() :]
    m = _CAN_SIT37.search(text)
    if m is not None and _things31(m["x"], lexicon) and _surface_only(m["s"], lexicon):
        text = f"{text[: m.start()]} Put {m['x']} {m['on']} {m['s']}{text[m.end() :]}"
    m = _OUT_OF_REACH37.search(text)
    if m is not None and _only_person(m["p"], lexicon):
        pid = next(iter(_ids(m["p"], lexicon, "human")))
        before = text[: m.start()]
        if (m["pron"] is None or _fit36(pid, m["pron"], lexicon)) and _ids(
            before, lexicon, "surface"
        ):
            text = before + m["end"].strip()
    m = _DO_FOR37.match(text)
    if m is not None:
        rest = m["rest"].replace("before anything else", "first")
        items = re.split(r"\s*,\s*", rest)
        if all(
            (i := _DO_ITEM37.fullmatch(it)) is not None
            and _things31(i["x"], lexicon)
            and _only_person(i["p"], lexicon)
            for it in items
        ):
            text = rest[0].upper() + rest[1:] + "."
    return _DO_YOU_THINK37.sub("", text)


# "…, and the ruler is what Noah asked for, so pass it to him": the cleft of a later clause, and
# the request after 'so' about the clause just before it
_WHAT_ASKED37 = re.compile(
    rf"(?<=, and )(?P<x>{_DET32} [a-z][a-z ]*?) is what (?P<p>{_P37}) (?P<v>asked for|wanted|"
    r"wants|needs|ordered|is after)\b",
)
_SO_TO_LAST37 = re.compile(
    r"^(?P<first>.+?),\s*and (?P<last>[^,.;!?]+?),\s*so (?P<req>(?:pass|give|hand|take|bring) "
    r"(?:it|them)(?: over)? to )(?P<pron>him|her)(?P<end>\s*[.!]?)\s*$",
    _F,
)


def _is_said37(pid: str, pronoun: str, lexicon: Lexicon) -> bool:
    """Whether person ``pid`` is said to be of ``pronoun``'s sex: by a title, or by a first name
    of one sex (data/first_names_sex.txt)."""
    sex = PRONOUN_SEX[pronoun.lower()]
    human = next(h for h in lexicon.scene.humans if h.id == pid)
    firsts = {n.lower().split()[0] for n in (human.name, *human.aliases)}
    return title_sex(pid, lexicon) == sex or any(name_sexes().get(n) == sex for n in firsts)


def _so_to_last37(text: str, lexicon: Lexicon) -> str:
    """Session 37: 'X is what P asked for' after ', and ' as 'P asked for X' (P one person, X
    objects only); then ', so pass it to him' after two wants joined by 'and' is to the person of
    the last one, when that person is said to be of the pronoun's sex (_is_said37), every other
    person named is not (_fit36 rules them out), and the last want names one object."""
    m = _WHAT_ASKED37.search(text)
    if m is not None and _things31(m["x"], lexicon) and _only_person(m["p"], lexicon):
        text = f"{text[: m.start()]}{m['p']} {m['v']} {m['x']}{text[m.end() :]}"
    m = _SO_TO_LAST37.match(text)
    if m is None or not _WANT_FRAME37.search(m["last"]):
        return text
    last = _ids(m["last"], lexicon, "human")
    if len(last) != 1 or len(_ids(m["last"], lexicon, "object")) != 1:
        return text
    (q,) = last
    others = _ids(m["first"], lexicon, "human") - {q}
    if not _is_said37(q, m["pron"], lexicon) or any(_fit36(p, m["pron"], lexicon) for p in others):
        return text
    name = next(it.text for it in _names(m["last"], lexicon) if it.refs[0].kind == "human")
    return f"{m['first']}, and {m['last']}, so {m['req']}{name}{m['end'].strip()}"


_STEPS37: tuple[Callable[[str, Lexicon], str], ...] = (
    _courtesies37,
    _wants_framed37,
    _after_doing37,
    _about_them37,
    _pronouns37,
    _splits37,
    _so_to_last37,
)


# Session 36 (lead): two objects said as the subject of one verb of placing, in a question whose
# verb comes first ("… so can the packing tape and the scanner go on the pallet for now?", "could
# the X and, er, the Y go in the box"): the verb before them makes both its subject
_GO_TOGETHER36L = re.compile(
    r"\b(?:can|could|should|would|will|shall|may|might) (?P<a>the [a-z' -]+?) and,? "
    r"(?:(?:er|erm|uh|um),? )?(?P<b>the [a-z' -]+?) (?:both )?(?:go|be put|get put) (?:back )?"
    r"(?:on|onto|in|into|up on|over on) (?P<s>the [a-z' -]+?)(?=[.,;!?]|$| for | now| please)",
    _F,
)


def said_together36l(text: str, lexicon: Lexicon) -> list[tuple[str, set[str], str]]:
    """Session 36 (lead): each stretch of ``text`` that says two objects of the scene go on one
    surface of it together (above): the words, both objects' ids and the surface's id."""
    if " and" not in text:
        return []
    out: list[tuple[str, set[str], str]] = []
    for m in _GO_TOGETHER36L.finditer(text):
        if not (
            _only(m["a"], lexicon, "object")
            and _only(m["b"], lexicon, "object")
            and _only(m["s"], lexicon, "surface")
        ):
            continue
        both = _ids(m["a"], lexicon, "object") | _ids(m["b"], lexicon, "object")
        if len(both) == 2:
            out.append((m[0], both, next(iter(_ids(m["s"], lexicon, "surface")))))
    return out
