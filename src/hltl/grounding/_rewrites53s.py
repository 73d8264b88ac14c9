"""The grounder's rules of session 53, engineer 12s (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _DONT, _F, _ids, _only_person, _sub, _tasks_of
from hltl.grounding._rewrites52s import _other_sex52s
from hltl.grounding.lexicon import PRONOUN_SEX, Lexicon, person_name, unnamed_sex44l
from hltl.grounding.tree import Node, tasks

# -- session 53 (12s): what none of the rewrites below rewrites --------------------------------
#
# 12c's probes of the batch: a rewrite that leaves a past holding or having, or a doing, beside
# its request makes a text the older rules read wrongly ("Bob's picked the apple, he's eating
# it.", "Bob put his hand up for the apple and got it.", "It's the apple for Bob, he had it
# yesterday." read apple>B, as main reads "The apple for Bob, he had it yesterday."). Every rewrite
# of this module leaves a text saying one of these as it is (refused as before).
_UNSAFE53S = re.compile(
    r"\b(?:had|got|has it|have it|eating|eaten|ate|eats|took|taken|finished|yesterday|"
    r"earlier|last night|(?:it's|it is|they're|they are) (?:his|hers|theirs|all (?:his|hers))|"
    r"(?:his|hers|theirs) now|(?:he|she|they)(?:'s| has| have|'ve) (?:got|had)|done)\b",
    _F,
)


# -- session 53 (12s): a he / she after a person left out by 'not' ------------------------------
#
# "Give Alice the apple, not Carol, she wants the crisps." read `apple>A & chips>A` and "Give
# Alice the apple, not Bob, he wanted the crisps." the same (12c's fuzz, session 52): session 19's
# `_negation19` takes ', not Carol,' off when Carol is said nowhere else, and the pronoun after it
# then has only Alice to stand for. A pronoun after 'not P' / 'instead of P' / 'rather than P' that
# P may be (the scene says no other sex) may be P: when its clause names a thing of the scene, a
# reading that hands that thing to someone else, or to P while another person named may be the
# pronoun too, is refused ('she' = Carol or Alice: the robot may not pick).
_NOT_PERSON53S = re.compile(
    r"\b(?:not|instead of|rather than)(?: (?:to|for|with))? (?P<who>[^,.;:!?]+)", _F
)
_PRONOUN53S = re.compile(r"\b(?P<pro>he|she|him|her|his|hers|himself|herself)\b", _F)


def _clause53s(text: str, at: int) -> str:
    """The clause of ``text`` around index ``at`` (between stops and commas)."""
    start = max(text.rfind(c, 0, at) for c in ",.;:!?") + 1
    ends = [i for c in ",.;:!?" if (i := text.find(c, at)) != -1]
    return text[start : min(ends) if ends else len(text)]


def _not_them53s(text: str, node: Node, lexicon: Lexicon) -> None:
    """Session 53 (12s): a thing a pronoun's clause names, after 'not P', given where the pronoun
    may be P (above): refused."""
    low = text.lower()
    if "not " not in low and "instead of" not in low and "rather than" not in low:
        return
    if "he" not in low:  # every pronoun above holds 'he' or 'her'
        return
    given = [t for t in tasks(node) if t.kind == "deliver"]
    if not given:
        return
    named = _ids(text, lexicon, "human")
    for m in _NOT_PERSON53S.finditer(text):
        left = _ids(m["who"], lexicon, "human")
        if len(left) != 1:
            continue
        (q,) = left
        for p in _PRONOUN53S.finditer(text, m.start("who")):
            pro = p["pro"].lower().removesuffix("self")
            sex = PRONOUN_SEX[pro]
            if _other_sex52s(q, sex, lexicon):
                continue
            things = _ids(_clause53s(text, p.start()), lexicon, "object")
            if not things:
                continue
            may = sorted(h for h in named if not _other_sex52s(h, sex, lexicon))
            for task in given:
                if task.obj not in things or (task.target == q and may == [q]):
                    continue
                people = " or ".join(person_name(h, lexicon) for h in may)
                raise GroundingError(
                    f"{p['pro']!r} after {m.group(0).strip()!r} may be "
                    f"{people}: the reading gives {task.obj} to "
                    f"{person_name(task.target, lexicon)}; name the person"
                )


# -- session 53 (12s): a placing or handover said the other way round -----------------------------
#
# "Bob gets the crisps first. Once he has them, over to Alice goes the cup." (blind51 #60): the
# place or person before the verb and the thing after it ('over to P goes the X', 'onto the S go
# the X and the Y'). Said the usual way round ('the X goes over to P') when what comes before
# 'goes' names one person or surface and nothing else and what comes after names things only; not
# in a sentence asking ('?'), nor said as done ('went' is no 'goes').
_GOES_TO53S = re.compile(
    r"(?P<head>^|[.;:!]\s+|,\s+|\b(?:then|and then|and|next|after that|now)\s+)"
    r"(?P<dir>(?:(?:over|across|up|down|back|off|along|round|straight) )?"
    r"(?:to|onto|on to|on|into|in) )(?P<where>[^,.;:!?]+?) (?P<verb>goes|go) "
    r"(?P<what>(?:the|that|this|those|these|both) [^,.;:!?]+?)(?=\s*(?:[,.;:!]|$))",
    _F,
)


def _goes_to53s(text: str, lexicon: Lexicon) -> str:
    """Session 53 (12s): 'over to P goes the X' said 'the X goes over to P' (above)."""
    low = text.lower()
    if (
        "go th" not in low
        and "goes th" not in low
        and "go both" not in low
        and "goes both" not in low
    ):
        return text
    if _UNSAFE53S.search(text):
        return text  # a holding, a having had, a doing: left as it is (above)

    def turn(m: re.Match[str]) -> str:
        where, what = m["where"], m["what"]
        if (
            len(_ids(where, lexicon, "human") | _ids(where, lexicon, "surface")) != 1
            or _ids(where, lexicon, "object")
            or not _ids(what, lexicon, "object")
            or _ids(what, lexicon, "human") | _ids(what, lexicon, "surface")
        ):
            return m.group(0)
        ask = text.find("?", m.end())
        stop = min((i for c in ".!;" if (i := text.find(c, m.end())) != -1), default=len(text))
        if ask != -1 and ask < stop:
            return m.group(0)
        head = m["head"]
        said = what if head.strip() not in ("", ".", ";", ":", "!") else what[0].upper() + what[1:]
        return f"{head}{said} {m['verb']} {m['dir']}{where}"

    return _GOES_TO53S.sub(turn, text)


# -- session 53 (12s): a claim said by an idiom ----------------------------------------------------
#
# "Crisps for Alice, she put her hand up for them." (blind51 #62), "The bottle goes to Person A
# and to nobody else, she put her name on it this morning." (#130), "Bob, on the other hand, has
# picked the bottle." (#62): putting one's hand up for a thing, one's name on or down for it, and
# having picked / chosen / opted for it say that one asked for it: said 'asked for' (present
# perfect 'has asked for'), which the older rules read (a claim by a he / she that fits the
# request's person; a want of the one named). Putting one's name on it is read so only after a he /
# she / they (session 40's `_claim40r`, before this step, reads 'P put his name on them' as 'P
# wants them'). Not a past perfect ('had put her name on it'), nor
# 'picked it up / out / over' (a doing, not a choosing), nor 'gone for it' (may be gone to
# fetch it).
_CLAIMED53S = re.compile(
    r"(?P<has>\b(?:has|have) |'s |'ve )?(?<!had )\b(?:put|puts) (?:her|his|their|my|our) "
    r"hands? up for\b"
    r"|(?P<pro3>\b(?:he|she|they))(?P<has3> has| have|'s|'ve)? (?:put|puts) "
    r"(?:her|his|their|my|our) names? (?:down )?(?:on|for)\b"
    r"|(?P<has2>\b(?:has|have) |'s |'ve )"
    r"(?:picked|chosen|opted for|plumped for)(?= (?:the|that|this|those|these) [a-z]+"
    r"(?: (?!up\b|out\b|off\b|over\b|back\b|down\b|away\b)[a-z]+)?\s*(?:[,.;:!]|$))",
    _F,
)


# the gate: words one of which every claim above holds
_CLAIM_WORDS53S = (
    *("hand up", "hands up", "name on", "name down", "name for", "names on", "names down"),
    *("names for", "picked", "chosen", "opted", "plumped"),
)


def _claimed53s(text: str, lexicon: Lexicon) -> str:
    """Session 53 (12s): 'put her hand up for / her name on / has picked the X' said 'asked for'
    (above)."""
    low = text.lower()
    if not any(w in low for w in _CLAIM_WORDS53S):
        return text
    if _UNSAFE53S.search(text):
        return text  # a holding, a having had, a doing: left as it is (above)

    def said(m: re.Match[str]) -> str:
        if m["pro3"]:
            return f"{m['pro3']} {'has asked for' if m['has3'] else 'asked for'}"
        has = m["has"] or m["has2"]
        if not has:
            return "asked for"
        return " has asked for" if has.startswith("'") else "has asked for"

    return _CLAIMED53S.sub(said, text)


# -- session 53 (12s): a negated 'put the X down' before its handover -----------------------------
#
# "Don't put the bottle down, give it straight to Person A." (blind51 #129): not setting the X
# down anywhere says nothing the handover after it does not (session 31's `_negated` drops a
# negated command only when the grammar reads it, and 'put the X down' names no place). The
# negated command is taken off when it names one thing and what follows, with 'it' / 'them' that
# thing, reads as handovers only, the thing among them.
_DONT_DOWN53S = re.compile(
    rf"^{_DONT}(?:put|set|leave|lay|drop|plonk|stick) (?P<x>(?:the|that|this) [a-z]+(?: [a-z]+)?|"
    r"it|them) down(?: anywhere)?\s*[,;.]\s*(?:(?:but|instead|just|rather|please),?\s+)*"
    r"(?P<rest>.+)$",
    _F,
)


def _dont_down53s(text: str, lexicon: Lexicon) -> str:
    """Session 53 (12s): "Don't put the X down, give it to P" said "Give the X to P" (above)."""
    low = text.lower()
    if "down" not in low or ("n't" not in low and "not" not in low and "never" not in low):
        return text
    if _UNSAFE53S.search(text):
        return text  # a holding, a having had, a doing: left as it is (above)
    m = _DONT_DOWN53S.match(text.strip())
    if m is None:
        return text
    things = _ids(m["x"], lexicon, "object")
    if len(things) != 1 or _ids(m["rest"], lexicon, "object"):
        return text
    rest = _sub(r"\b(?:it|them)\b", m["x"], m["rest"])
    if rest == m["rest"]:
        return text
    asked = _tasks_of(rest, lexicon)
    if not asked or any(kind != "deliver" for kind, _, _ in asked):
        return text
    if not things & {obj for _, obj, _ in asked}:
        return text
    return rest[0].upper() + rest[1:]


# -- session 53 (12s): 'much rather' ---------------------------------------------------------------
#
# "Person A has gone off the bottle, she'd much rather have the cup." (blind51 #125): 'would
# rather have' is read, 'would much / far / a lot rather' was not: the word that only weighs the
# preference is taken off.
_MUCH_RATHER53S = re.compile(
    r"(?P<v>\b(?:would|should) |'d )(?:much|far|a lot|a good deal|very much|infinitely) "
    r"(?=rather\b)",
    _F,
)


def _much_rather53s(text: str, lexicon: Lexicon) -> str:
    """Session 53 (12s): "she'd much rather have the X" said "she'd rather have the X"."""
    if "rather" not in text.lower():
        return text
    if _UNSAFE53S.search(text):
        return text  # a holding, a having had, a doing: left as it is (above)
    return _MUCH_RATHER53S.sub(lambda m: m["v"], text)


# -- session 53 (12s): 'and to nobody else' before a remark ---------------------------------------
#
# "The bottle goes to Person A and to nobody else, she put her name on it this morning." (blind51
# #130): session 33's `_nobody_else33r` takes 'and to nobody else' off only where it closes the
# text; before a comma and a remark naming no person it says what the request says too.
_NOBODY_ELSE53S = re.compile(
    r"(?:,\s*|\s+)(?:and |but )?(?:to |for )?(?:nobody|no one|no-one|noone) else(?=\s*[,;])", _F
)


def _nobody_else53s(text: str, lexicon: Lexicon) -> str:
    """Session 53 (12s): 'X to P and to nobody else, <remark>' said 'X to P, <remark>' (above)."""
    if " else" not in text.lower():
        return text
    if _UNSAFE53S.search(text):
        return text  # a holding, a having had, a doing: left as it is (above)
    m = _NOBODY_ELSE53S.search(text)
    if m is None:
        return text
    head, rest = text[: m.start()], text[m.end() :]
    if len(_ids(head, lexicon, "human")) != 1 or not _ids(head, lexicon, "object"):
        return text
    if _ids(rest, lexicon, "human"):
        return text
    return head + rest


# -- session 53 (12s): 'It's the X for P' and 'at all' after a not-wanting -------------------------
#
# "It's the cup for Person B, he doesn't want the apple at all." (blind51 #123): a sentence opening
# 'It's the X for P' (a cleft of 'the X for P', which is read) before a stop or comma is said
# 'The X for P'; and 'at all' after 'doesn't want / need the X' (it only weighs the not-wanting)
# is taken off, so that session 32's `_not_wanted32r` reads the closing remark as before. Not in
# a text that asks ('?': "It's the cup for Bob, isn't it?").
_ITS_FOR53S = re.compile(
    r"(?P<head>^|(?<=[.;!])\s+)(?:(?:so|well|right|ok|okay),? )?it(?:'s| is) "
    r"(?P<x>the [a-z]+(?: [a-z]+)?) for (?P<p>[A-Za-z][\w ]*?)(?=\s*(?:[,.;!]|$))",
    _F,
)
_AT_ALL53S = re.compile(
    r"\b(?P<said>(?:doesn't|does not|don't|do not) (?:want|need) (?:the|a|an|any) [a-z]+"
    r"(?: [a-z]+)?) at all\b",
    _F,
)


def _its_for53s(text: str, lexicon: Lexicon) -> str:
    """Session 53 (12s): "It's the X for P, …" said "The X for P, …"; 'doesn't want the X at all'
    said 'doesn't want the X' (above)."""
    low = text.lower()
    if ("at all" in low or " for " in low) and _UNSAFE53S.search(text):
        return text  # a holding, a having had, a doing: left as it is (above)
    if "at all" in low:
        text = _AT_ALL53S.sub(lambda m: m["said"], text)
    if "it" not in low or " for " not in low or "?" in text:
        return text  # asked ("It's the cup for Bob, isn't it?"): as before

    def said(m: re.Match[str]) -> str:
        objects = _ids(m["x"], lexicon, "object")
        if not objects or _ids(m["x"], lexicon, "human") or _ids(m["x"], lexicon, "surface"):
            return m.group(0)
        if not _only_person(m["p"], lexicon):
            return m.group(0)
        x = m["x"]
        return f"{m['head']}{x[0].upper()}{x[1:]} for {m['p']}"

    return _ITS_FOR53S.sub(said, text)


# -- session 53 (12s): a he / she / they who had or got a thing ----------------------------------
#
# "Give Bob the cup, he had the apple." read `cup>B & apple>B` on main b4e4e6fc ("Give Alice the
# cup, she had the apple.", "Give Bob the cup. He had the apple.", "…, he got the apple." too):
# session 32's `_state_only32s` refuses 'Bob had the apple' (a past holding asks for nothing) but
# not a pronoun that says it. A clause whose subject is he / she / they and whose verb is a past
# 'had' / 'got' of a thing of the scene, closing the clause (a time word may follow), is refused
# so ('had to', 'had better', 'had it' are not this; 'had the chips and wants them again' goes on).
_PRONOUN_HAD53S = re.compile(
    r"(?:^|[,;.:!?]\s*|\b(?:and|so|but|because|as|since|cos|though)\s+)"
    r"(?P<said>(?P<pro>he|she|they)(?: (?:already|just|only|even|also|actually))? (?:had|got) "
    r"(?P<x>(?:the|his|her|their|that|this|those|these|a|an|some) [a-z]+(?: [a-z]+)?))"
    r"(?=(?: (?:earlier|yesterday|already|before|first|this morning|last night|at lunch|today))?"
    r"\s*(?:[,.;:!?]|$))",
    _F,
)


def _pronoun_had53s(text: str, lexicon: Lexicon) -> None:
    """Session 53 (12s): '…, he had the X' (a past holding said by a pronoun) refused (above)."""
    low = text.lower()
    if " had " not in low and " got " not in low:
        return
    for m in _PRONOUN_HAD53S.finditer(text):
        if not _ids(m["x"], lexicon, "object") or _ids(m["x"], lexicon, "human"):
            continue
        raise GroundingError(
            f"{m['said']!r} says what {m['pro'].lower()} had: it asks for nothing; leave it out, "
            f"or say 'give <person> {m['x']}' to have it handed over"
        )


# -- session 53 (12s): 'it isn't P who …, it's Q' ----------------------------------------------
#
# "It isn't Person A who's having the bottle, it's Person B, give it to him." (blind51 #127),
# "Person B's not the one the chips are meant for, it's Person A who gets them." (#128): a cleft
# that denies one person the thing and names the other is said as session 42's form, "The X isn't
# for P, it's for Q, …", which the older rules read (P and Q two people, the X things of the scene;
# a 'who gets them' after Q, saying the same, taken off). Nothing may follow but the handover to Q
# said again ('give it to him', the pronoun Q's sex by the scene and not P's): no tag, no remark.
_WHO53S = r"(?:person [a-z]|(?:mr|mrs|ms|miss|dr) [a-z]+|[a-z]+)"
_X53S = r"(?:the|that|this|those|these) [a-z]+(?: [a-z]+)?"
_NOT_WHO53S = re.compile(
    rf"^(?:it(?: isn't|'s not| is not) (?P<p1>{_WHO53S}) who(?:'s| is) (?:having|getting|"
    rf"meant to (?:have|get)|to (?:have|get)) (?P<x1>{_X53S})"
    rf"|(?P<p2>{_WHO53S})(?:'s not| is not| isn't) the one (?:(?P<x2>{_X53S}) (?:is|are|'s|'re) "
    rf"(?:meant |intended )?for|who(?:'s| is) (?:having|getting|meant to (?:have|get)) "
    rf"(?P<x3>{_X53S})|who gets (?P<x4>{_X53S})))"
    rf"\s*,\s*it(?:'s| is) (?P<q>{_WHO53S})(?: (?:who|that) (?:gets|(?:'s|is) (?:having|getting)) "
    r"(?:it|them))?(?P<rest>\s*(?:[,.;!]|$).*)$",
    _F,
)

# what may follow Q: nothing, or the handover to Q said again with a him / her that can be Q only
_THEN_GIVE53S = re.compile(
    r"\s*(?:[.!]|,\s*(?:please,? )?(?:give|hand|pass|take|bring) (?:it|them) (?:over |across )?"
    r"to (?P<pro>him|her)(?:,? please)?\s*[.!]?)?\s*",
    _F,
)


def _not_who53s(text: str, lexicon: Lexicon) -> str:
    """Session 53 (12s): "It isn't P who's having the X, it's Q" said "The X isn't for P, it's for
    Q" (above)."""
    low = text.lower()
    if "who's" not in low and "who is" not in low and "the one" not in low:
        return text
    if _UNSAFE53S.search(text):
        return text  # a holding, a having had, a doing: left as it is (above)
    m = _NOT_WHO53S.match(text.strip())
    if m is None:
        return text
    p = m["p1"] or m["p2"]
    x = m["x1"] or m["x2"] or m["x3"] or m["x4"]
    q = m["q"]
    if not (_only_person(p, lexicon) and _only_person(q, lexicon)):
        return text
    if _ids(p, lexicon) == _ids(q, lexicon):
        return text
    if not _ids(x, lexicon, "object") or _ids(x, lexicon, "human") | _ids(x, lexicon, "surface"):
        return text
    then = _THEN_GIVE53S.fullmatch(m["rest"])
    if then is None:
        return text
    if then["pro"]:
        (pid,) = _ids(p, lexicon)
        (qid,) = _ids(q, lexicon)
        sex = PRONOUN_SEX[then["pro"].lower()]
        if unnamed_sex44l(qid, lexicon) != sex or unnamed_sex44l(pid, lexicon) in (sex, None):
            return text
    return f"{x[0].upper()}{x[1:]} isn't for {p}, it's for {q}{m['rest']}"


# -- session 53 (12s): where on a surface, and a closing 'that's all for the S' --------------------
#
# "The small box goes on the belt. Stick the medium box on the belt beside it. That's all for the
# belt." (blind51 #75): the grounder places on a surface, not beside a thing on it; 'on the S
# beside it' is said 'on the S' (the S a surface of the scene named before too, and two things
# named before 'it' / 'them'). A closing 'That's all / it
# / everything for the S' (or 'for P') is taken off when what comes before places things on that
# surface (hands them to that person); else it stays, refused.
_BESIDE53S = re.compile(
    r"(?P<on>\b(?:on|onto|on to) the [a-z]+(?: [a-z]+)?) (?:beside|next to|alongside|by|near) "
    r"(?:it|them)(?=\s*(?:[,.;!]|$))",
    _F,
)
_BESIDE_WORDS53S = ("beside", "next to", "alongside", " by ", " near ")
_ALL_FOR53S = re.compile(
    r"(?:\s*[.,;]\s*|\s+)(?:and |right,? |ok,? |okay,? |so,? )?that(?:'s| is) (?:it|all|everything)"
    r"(?: for now)? for (?P<w>the [a-z]+(?: [a-z]+)?|[A-Za-z][\w ]*?)(?: for now| then| today)?"
    r"(?P<end>\s*[.!]?)\s*$",
    _F,
)


def _all_for53s(text: str, lexicon: Lexicon) -> str:
    """Session 53 (12s): 'on the S beside it' said 'on the S'; a closing "That's all for the S"
    taken off (above)."""
    low = text.lower()
    if " for " not in low and not any(w in low for w in _BESIDE_WORDS53S):
        return text
    if _UNSAFE53S.search(text):
        return text  # a holding, a having had, a doing: left as it is (above)
    if any(w in low for w in _BESIDE_WORDS53S):

        def on(m: re.Match[str]) -> str:
            if len(_ids(m["on"], lexicon, "surface")) != 1 or _ids(m["on"], lexicon, "object"):
                return m.group(0)
            # 'it' stands for a thing said before, besides the one placed, and put on the same
            # surface, said before too ("Put the cup on the shelf, and the apple on the table
            # beside it.": the cup goes on the shelf, a contradiction: as before)
            before = text[: m.start()]
            if len(_ids(before, lexicon, "object")) < 2:
                return m.group(0)
            if not _ids(m["on"], lexicon, "surface") <= _ids(before, lexicon, "surface"):
                return m.group(0)
            return m["on"]

        text = _BESIDE53S.sub(on, text)
    if "that" not in low or " for " not in low:
        return text
    m = _ALL_FOR53S.search(text)
    if m is None:
        return text
    where = _ids(m["w"], lexicon, "surface") | _ids(m["w"], lexicon, "human")
    if len(where) != 1 or _ids(m["w"], lexicon, "object"):
        return text
    rest = text[: m.start()]
    asked = _tasks_of(rest, lexicon)
    if not asked or not where & {target for _, _, target in asked}:
        return text
    return rest + (m["end"].strip() or ".")


# -- session 53 (12s): exclusion said with more words ---------------------------------------------
#
# "Every single thing goes on the belt apart from the work gloves and the barcode scanner."
# (blind51 #135): 'every single thing' / 'each and every thing' / 'every last thing' said
# 'everything', which the older rules read with 'apart from'. "Apart from the mugs, which are
# staying exactly where they are, everything's going to Alice for her picnic." (#120): a 'which'
# clause after the things left out that says they stay (where they are, put) says what the
# exclusion does: taken off.
_EVERY_SINGLE53S = re.compile(r"\b(?:every single|each and every|every last) thing\b", _F)
_WHICH_STAY53S = re.compile(
    r"(?P<ex>\b(?:apart from|except(?: for)?|other than|besides|bar) (?:the|those|these) [a-z]+"
    r"(?: [a-z]+)?),\s*which (?:are|is|'re|'s|will be|can) (?:staying|stopping|remaining|stay|"
    r"stop|remain)(?: (?:exactly |right )?(?:where (?:they|it) (?:are|is)|put|there|as (?:they|it) "
    r"(?:are|is)))?\s*,",
    _F,
)


def _every_single53s(text: str, lexicon: Lexicon) -> str:
    """Session 53 (12s): 'every single thing' said 'everything'; 'apart from the X, which are
    staying where they are,' said 'apart from the X,' (above)."""
    low = text.lower()
    if "every" not in low and "which" not in low:
        return text
    if _UNSAFE53S.search(text):
        return text  # a holding, a having had, a doing: left as it is (above)
    if "every" in low and ("single" in low or "each and" in low or "last" in low):
        text = _EVERY_SINGLE53S.sub("everything", text)
    if "which" in low and ("stay" in low or "stop" in low or "remain" in low):
        text = _WHICH_STAY53S.sub(lambda m: f"{m['ex']},", text)
    return text


# -- session 53 (12s): 'everything' said as done or asked ----------------------------------------
#
# "Everything went to Alice." and "Everything's gone to Alice apart from the mugs." read every
# thing of the scene handed to Alice, and "Everything goes to Alice, apart from the mugs?" the same
# (on main b4e4e6fc): session 41's `_done41l` and the grammar's question refuse 'the apple went to
# Alice' / 'The apple goes to Alice?' by the thing named, and 'everything' names none. A sentence
# whose subject is everything (every single thing, the lot, all of it) and whose verb says it done
# ('went', 'has gone', 'was sent', 'ended up'), or that asks ('?' closing it), is refused.
_EVERYTHING53S = re.compile(
    r"(?:^|(?<=[.;!?])\s+|(?<=,)\s+(?:and |so |then |but )?)(?P<said>(?:everything|every single "
    r"thing|each and every thing|every last thing|the lot|all of it|all of them)(?:'s| has| have)?"
    r"(?P<done> (?:went|gone|been sent|been given|been taken|ended up|was sent|were sent|was "
    r"given|were given|was taken|were taken))?[^.;!?]*(?P<ask>\?)?)",
    _F,
)

_DONE_WORDS53S = ("went", "gone", "sent", "ended up", "given", "taken")


def _everything_said53s(text: str, lexicon: Lexicon) -> None:
    """Session 53 (12s): 'Everything went to P' / 'Everything goes to P?' refused (above)."""
    low = text.lower()
    if "every" not in low and "the lot" not in low and "all of" not in low:
        return
    if "?" not in text and not any(w in low for w in _DONE_WORDS53S):
        return
    for m in _EVERYTHING53S.finditer(text):
        if m["done"]:
            raise GroundingError(
                f"{m['said'].strip()!r} is said as done ({m['done'].strip()!r}), not as something "
                "to do: say the request without it, e.g. 'give Bob the chips'"
            )
        if m["ask"]:
            raise GroundingError(
                f"{m['said'].strip()!r} is a question, not a request: say what to do, e.g. "
                "'give Bob the chips' or 'put the cup on the shelf'"
            )


# -- session 53 (12s): 'over to P with the X' in a later clause ----------------------------------
#
# "Over to Pesson A with the bottle, and across to Person B with the chips." (blind51 #191, a typo
# of the name too): session 34's `_frames34t` says an opening 'Over to P with the X' as 'The X over
# to P'; a later clause of the same frame (after ', and' / ';' / ', then') is said so too (P one
# person or surface, the X things of the scene).
_TO_WITH53S = re.compile(
    r"(?P<head>[,;]\s*(?:and |then |and then )?)(?P<dir>(?:over|across|up|round|back|down) )?to "
    r"(?P<p>[^,.;:!?]+?) with (?P<x>(?:the|that|this|those|these) [a-z]+(?: [a-z]+)?)"
    r"(?=\s*(?:[,.;!]|$))",
    _F,
)


def _to_with53s(text: str, lexicon: Lexicon) -> str:
    """Session 53 (12s): ', and across to P with the X' said ', and the X across to P' (above)."""
    low = text.lower()
    if " with th" not in low:
        return text
    if _UNSAFE53S.search(text) or "?" in text:
        return text  # a holding, a having had, a doing, a question: left as it is (above)

    def said(m: re.Match[str]) -> str:
        where = _ids(m["p"], lexicon, "human") | _ids(m["p"], lexicon, "surface")
        if len(where) != 1 or _ids(m["p"], lexicon, "object"):
            return m.group(0)
        if not _ids(m["x"], lexicon, "object") or _ids(m["x"], lexicon, "human"):
            return m.group(0)
        return f"{m['head']}{m['x']} {m['dir'] or ''}to {m['p']}"

    return _TO_WITH53S.sub(said, text)


# the normaliser's first rewrites (wired into normalise._STEPS19, before the session-52 ones)
_STEPS53S_FIRST: tuple[Callable[[str, Lexicon], str], ...] = (
    _goes_to53s,
    _dont_down53s,
    _much_rather53s,
    _nobody_else53s,
    _its_for53s,
    _not_who53s,
    _all_for53s,
    _every_single53s,
    _to_with53s,
)
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-52 ones)
_STEPS53S: tuple[Callable[[str, Lexicon], str], ...] = (_claimed53s,)
# refusals asked of the text before it is read (offline._parse, after the session-52 ones)
REFUSE53S: tuple[Callable[[str, Lexicon], None], ...] = (_pronoun_had53s, _everything_said53s)
# checks of the whole instruction's reading (offline.parse_instruction, after the session-52 ones)
CHECK53S: tuple[Callable[[str, Node, Lexicon], None], ...] = (_not_them53s,)
