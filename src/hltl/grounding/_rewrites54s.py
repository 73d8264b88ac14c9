"""The grounder's rules of session 54, engineer 12s (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _ids, _names, _only_person
from hltl.grounding._rewrites39r import _not_wanted39r
from hltl.grounding._rewrites44r import _read_or44r, _read_without44r
from hltl.grounding._rewrites51s import _plain51s
from hltl.grounding._rewrites53s import _UNSAFE53S, _WHO53S, _X53S, _not_who53s
from hltl.grounding.lexicon import PRONOUN_SEX, Lexicon, unnamed_sex44l
from hltl.grounding.tree import Node, Task, tasks

# -- session 54 (12s): a thing set against another, moved where the other goes ----------------
#
# "Pick up the bottle. Put it on the shelf, and the apple, not the bottle." read `bottle@shelf &
# apple@shelf` (12c, session 53): the grammar leaves 'not the bottle' out of 'the apple', which
# does not name it, and asks only whether a name said before has it ('Put the bottle on the
# shelf, and the apple, not the bottle.' is refused so) — the 'it' that stands for the bottle is
# no name. 'the Y, not the X' / 'instead of the X' / 'rather than the X' says the X does not go
# where the Y goes: a reading that moves the X there all the same, when nothing after the words
# names the X again, is refused (session 51's `_excluded_back51r` asks the same of 'except' /
# 'but not' ...).
_SET_AGAINST54S = re.compiled(
    r"(?:(?:(?:^|[,;:.!?(—–-])\s*(?:(?:and|or|but|so)\s+)?|\b(?:and|but)\s+)not|\binstead of|"
    r"\brather than|"
    r"\bin place of|\bas opposed to)\s+(?!just\b|only\b|even\b|to\b|for\b)"
    r"(?P<x>(?:the |that |those |this |these |her |his |their |my |any )?[a-z]+(?: [a-z]+)?)",
    _F,
)


_AGAINST_WORDS54S = ("not ", "instead of", "rather than", "in place of", "as opposed to")


def _against54s(text: str, lexicon: Lexicon) -> list[tuple[set[str], str, int]]:
    """The things ``text`` sets against another by 'not' / 'instead of' / 'rather than' (above),
    each with the words and where they end; a phrase saying 'other' / 'one' (which one is then
    unsure) is not among them."""
    out: list[tuple[set[str], str, int]] = []
    for m in _SET_AGAINST54S.finditer(text):
        words = m["x"].lower().split()
        if "other" in words or "one" in words or "ones" in words:
            continue
        named = _names(m["x"], lexicon)
        if not named or any(r.kind != "object" for r in named[0].refs):
            continue
        said = m.group(0).lstrip(",;:.!?(—–- ")
        out.append(({r.id for r in named[0].refs}, said, m.end()))
    return out


def _not_where54s(text: str, node: Node, lexicon: Lexicon) -> None:
    """Session 54 (12s): a thing set against another moved where the other goes (above)."""
    low = text.lower()
    if not any(w in low for w in _AGAINST_WORDS54S):
        return
    got: list[Task] = list(tasks(node))
    if len(got) < 2:
        return
    for left, said, end in _against54s(text, lexicon):
        rest = {t.target for t in got if t.obj not in left}
        back = {t.obj for t in got if t.obj in left and t.target in rest}
        if not back:
            continue
        after = {r.id for it in _names(text[end:], lexicon) for r in it.refs}
        if back & after:
            continue
        raise GroundingError(
            f"{said!r} sets the {', '.join(sorted(back))} against what goes where it is said, "
            "but the reading would move it there too: say the whole request again"
        )


# -- session 54 (12s): 'it isn't P that gets the X, it's Q' ----------------------------------
#
# "It isn't Person A that gets the chips, it's Person B." (blind52 #131): session 53's
# `_not_who53s` reads "It isn't P who's having / getting the X, it's Q" and "P's not the one the
# X is for, it's Q" (each said "The X isn't for P, it's for Q"); said with 'that' or 'who' and a
# present 'gets' / 'is getting' / 'should get' / 'is to have' …, or "It isn't P that / who the X
# is for", it is said in that rule's words and read by it (with all it asks: one person each,
# a thing of the scene, nothing after Q but the handover said again; nothing that says a
# holding or a doing).
_NOT_THAT54S = re.compiled(
    rf"^it(?: isn't|'s not| is not) (?P<p>{_WHO53S}) (?:that|who)(?:(?:(?:'s| is) "
    r"(?:getting|having|(?:meant |supposed )?to (?:get|have))| gets| should (?:get|have)) "
    rf"(?P<x>{_X53S})| (?P<x2>{_X53S}) (?:is|are|'s|'re) (?:meant |intended |supposed to be )?for)"
    r"(?P<rest>\s*,.*)$",
    _F,
)


def _not_that54s(text: str, lexicon: Lexicon) -> str:
    """Session 54 (12s): "It isn't P that gets the X, it's Q" read as session 53's form (above)."""
    low = text.lower()
    if "that" not in low and "who" not in low:
        return text
    if "isn't" not in low and "not" not in low:
        return text
    m = _NOT_THAT54S.match(text.strip())
    if m is None:
        return text
    if m["x"]:
        said = f"It isn't {m['p']} who's getting {m['x']}{m['rest']}"
    else:
        said = f"{m['p']} isn't the one {m['x2']} is for{m['rest']}"
    out = _not_who53s(said, lexicon)
    return text if out == said else out


# -- session 54 (12s): 'none of the X for P, just the Y' ----------------------------------------
#
# "None of the books for Noah, just the ruler." (blind52 #137): a left-out thing said first, as
# 'none of the X' / 'no X' / 'not the X' for a person, then 'just / only the Y' (nothing after
# it): said "Just the Y for P, not the X.", which the grammar reads (the Y and the X things of
# the scene, apart; P one person; the reading hands nothing the X names).
_NONE_FOR54S = re.compiled(
    r"^(?:none of|no|not(?: any of)?) (?P<x>(?:the |those |these |any )?[a-z]+(?: [a-z]+)?) "
    rf"(?:for|to) (?P<p>{_WHO53S})\s*[,;:]\s*(?:just|only|but) (?P<y>(?:the |that |this )?[a-z]+"
    r"(?: [a-z]+)?)(?:,? please)?(?P<end>\s*[.!]?)$",
    _F,
)


def _none_for54s(text: str, lexicon: Lexicon) -> str:
    """Session 54 (12s): "None of the X for P, just the Y" said "Just the Y for P, not the X"
    (above)."""
    low = text.lower()
    if "no" not in low or ("just" not in low and "only" not in low and "but" not in low):
        return text
    m = _NONE_FOR54S.match(text.strip())
    if m is None or not _only_person(m["p"], lexicon):
        return text
    x, y = _ids(m["x"], lexicon), _ids(m["y"], lexicon)
    if not x or not y or x & y:
        return text
    if x != _ids(m["x"], lexicon, "object") or y != _ids(m["y"], lexicon, "object"):
        return text
    thing = m["y"] if m["y"].lower().startswith(("the ", "that ", "this ")) else f"the {m['y']}"
    said = m["x"] if m["x"].lower().startswith(("the ", "those ", "these ")) else f"the {m['x']}"
    out = f"Just {thing} for {m['p']}, not {said}{m['end']}"
    if _read_without44r(out, text, m["x"], lexicon) == text:
        return text
    return _plain51s(out, text, lexicon)


# -- session 54 (12s): 'no X for P, he's gone for the Y instead' -------------------------------
#
# "No chips for Person B, he's gone for the apple instead." (blind52 #124): after a thing left
# out for a person ('no / none of the / not the X for P'), the thing that person chose or wants,
# said by a he / she that is P's sex by the scene ("he's gone for / he's after / he wants / he'd
# rather have / she's picked the Y (instead)", nothing after it): said "No X for P, just the Y.",
# which the grammar reads. A past holding or having ('he had', 'he's got', 'he took') is no
# choice: left as it is.
_NO_THEN_WANT54S = re.compiled(
    r"^(?P<head>(?:none of|no|not) (?P<x>(?:the |any )?[a-z]+(?: [a-z]+)?) (?:for|to) "
    rf"(?P<p>{_WHO53S}))\s*[,;]\s*(?P<pro>he|she)(?:'s (?:gone for|going for|after|chosen|"
    r"picked|opted for|asked for)| is (?:going for|after)| has (?:gone for|chosen|picked|opted for|"
    r"asked for)| (?:wants|prefers|fancies)|(?:'d| would) (?:like|rather have|prefer)) "
    r"(?P<y>(?:the |that |this )?[a-z]+(?: (?!instead\b|this\b|today\b)[a-z]+)?)"
    r"(?: instead| this time| today)?(?P<end>\s*[.!]?)$",
    _F,
)


def _no_then_want54s(text: str, lexicon: Lexicon) -> str:
    """Session 54 (12s): "No X for P, he's gone for the Y instead" said "No X for P, just the Y"
    (above)."""
    low = text.lower()
    if "no" not in low or "he" not in low:
        return text
    m = _NO_THEN_WANT54S.match(text.strip())
    if m is None or not _only_person(m["p"], lexicon):
        return text
    x, y = _ids(m["x"], lexicon), _ids(m["y"], lexicon)
    if not x or not y or x & y:
        return text
    if x != _ids(m["x"], lexicon, "object") or y != _ids(m["y"], lexicon, "object"):
        return text
    (pid,) = _ids(m["p"], lexicon)
    if unnamed_sex44l(pid, lexicon) != PRONOUN_SEX[m["pro"].lower()]:
        return text
    thing = m["y"] if m["y"].lower().startswith(("the ", "that ", "this ")) else f"the {m['y']}"
    out = f"{m['head']}, just {thing}{m['end']}"
    if _read_without44r(out, text, m["x"], lexicon) == text:
        return text
    return _plain51s(out, text, lexicon)


# -- session 54 (12s): 'the Y can stay, it's the X P is needing' --------------------------------
#
# "The drill can stay, it's the hammer Jess is needing." and "The green cup stays put; it's the
# white one that wants to go in the sink." (blind52 #139 #132): a thing left where it is ('the Y
# can stay / stays (put) / leave the Y'), then a cleft naming what is wanted instead ("it's the X
# (that) P needs / wants / is after", "it's the X that wants to go / goes in the S"): said "The Y
# stays put; P needs the X." / "…; the X goes in the S.", which the older rules read (the left
# thing as a note). The Y and the X things of the scene, apart; P one person; the cleft ends the
# text; nothing that says a holding or a doing (session 53's `_UNSAFE53S`).
_DET54S = r"(?:the|that|this|those|these|his|her|their)"
_Y54S = (
    rf"{_DET54S} [a-z]+(?: (?!can\b|should\b|will\b|may\b|stays?\b|is\b|are\b|alone\b|be\b|"
    r"where\b|there\b|here\b)[a-z]+)?"
)
_STAYS_CLEFT54S = re.compiled(
    rf"^(?:(?P<y>{_Y54S}) (?:(?:can|should|will|may) stay|stays|stay|"
    r"(?:is|are) staying)(?: put| where (?:it is|they are)| there| here)?|leave "
    rf"(?P<y2>{_Y54S})(?: where (?:it is|they are)| alone| be| there)?)"
    rf"\s*[,;]\s*(?:but |and )?it(?:'s| is) (?:actually |really )?(?P<x>{_DET54S} [a-z]+"
    r"(?: [a-z]+)??) (?:(?:that|which) (?:(?:wants?|needs?|has|have) to go|goes|go|"
    r"(?:'s|is|are|'re) going) "
    r"(?P<prep>in|on|onto|into|on to) (?P<s>the [a-z]+(?: [a-z]+)?)|(?:that |who )?"
    rf"(?P<p>{_WHO53S}) (?P<v>is needing|needs|wants|is wanting|is after|'s after|would like|"
    r"'d like))(?P<end>\s*[.!]?)$",
    _F,
)
_VERB54S = {
    "is needing": "needs",
    "is wanting": "wants",
    "'s after": "is after",
    "'d like": "would like",
}


def _stays_cleft54s(text: str, lexicon: Lexicon) -> str:
    """Session 54 (12s): "The Y can stay, it's the X P is needing" said "The Y stays put; P needs
    the X" (above)."""
    low = text.lower()
    if "it's" not in low and "it is" not in low:
        return text
    if "stay" not in low and "leave" not in low:
        return text
    if _UNSAFE53S.search(text):
        return text
    m = _STAYS_CLEFT54S.match(text.strip())
    if m is None:
        return text
    y, x = m["y"] or m["y2"], m["x"]
    if x.lower().endswith(" one") and " " in y:
        x = f"{x[:-4]} {y.split()[-1]}"  # "the white one" after "the green cup": the white cup
    ys, xs = _ids(y, lexicon), _ids(x, lexicon)
    if not ys or not xs or ys & xs:
        return text
    if ys != _ids(y, lexicon, "object") or xs != _ids(x, lexicon, "object"):
        return text
    if m["p"]:
        if not _only_person(m["p"], lexicon):
            return text
        v = m["v"].lower()
        said = f"{m['p']} {_VERB54S.get(v, v)} {x}"
    else:
        if _ids(m["s"], lexicon) != _ids(m["s"], lexicon, "surface") or not _ids(m["s"], lexicon):
            return text
        said = f"{x} goes {m['prep']} {m['s']}"
    out = f"{y[0].upper()}{y[1:]} stays put; {said}{m['end']}"
    if _read_without44r(out, text, y, lexicon) == text:
        return text
    return _plain51s(out, text, lexicon)


# -- session 54 (12s): 'P's not having the X today', '… and nothing else, nothing at all' --------
#
# "Person B's not having the cup today, hand him the apple instead." (blind52 #126): session 39's
# `_not_wanted39r` says "P's not having the X, …" "P doesn't want the X, …" but not with a time of
# the speaker's day after the thing ('today', 'this time', 'any more'; not 'tonight', which
# may be when the rest is for), and after
# session 41's `_instead_of_unwanted41r` has passed ('…, hand him the apple instead' stays
# refused): the time is said away (the request is for now anyway) and the rule asked first.
# "Person A wants the bottle and nothing else, nothing at all." (#130): session 43's
# `_nothing_more43r` takes a closing 'nothing else' off, not one said again ('nothing at all',
# 'not a thing', 'absolutely nothing'): the second is taken off. Both first (before the older
# rules that read what is left).
_NOT_TODAY54S = re.compiled(
    r"(?P<head>(?:'s| is) (?:not|never) (?:having|getting|allowed)|isn't (?:having|getting|"
    r"allowed)) (?P<what>the [a-z]+(?: [a-z]+)?) (?:today|this time|right now|now|any ?more)"
    r"(?=\s*[,;])",
    _F,
)
_NOTHING_AGAIN54S = re.compiled(
    r"(?P<said>\bnothing (?:else|more|besides))\s*[,;—–-]\s*(?:nothing (?:at all|whatsoever|more)|"
    r"not a (?:thing|single thing)|absolutely nothing)(?=\s*[.!]?\s*$)",
    _F,
)


def _not_today54s(text: str, lexicon: Lexicon) -> str:
    """Session 54 (12s): 'P's not having the X today, …' said without the time (above)."""
    low = text.lower()
    if "not" not in low and "n't" not in low:
        return text
    said = _NOT_TODAY54S.sub(lambda m: f"{m['head']} {m['what']}", text)
    if said == text and "instead" not in low:
        return text
    out = _not_wanted39r(said, lexicon)
    return _read_or44r(out, text, lexicon)


def _nothing_again54s(text: str, lexicon: Lexicon) -> str:
    """Session 54 (12s): '… nothing else, nothing at all' said '… nothing else' (above)."""
    if "nothing" not in text.lower():
        return text
    out = _NOTHING_AGAIN54S.sub(lambda m: m["said"], text)
    return _read_or44r(out, text, lexicon)


# -- session 54 (12s): 'up top on the shelf' -------------------------------------------------
#
# "Bottle up top on the shelf. Then the crisps go Alice's way." (blind52 #62): a word of where
# said before the surface that says it ('up top / up there / over there / down there / down
# below on the S') is the surface said twice: taken off before 'on / onto / in / into' and a
# surface of the scene ('up high on the shelf' is read so already); not after 's / is / sits …,
# which says where the thing is (12c: "The apple's up there on the shelf, give it to Bob." would
# read a placing too, as main reads "The apple's on the shelf, give it to Bob.").
_WHERE_TWICE54S = re.compiled(
    r"\b(?:right )?(?:up top|up there|over there|down there|down below|up above|down low)\s+"
    r"(?=(?:on|onto|on to|in|into|inside) (?P<s>(?:the |that )?[a-z]+(?: [a-z]+)?))",
    _F,
)


# where a thing is ('the apple's / is / sits / was up there on the shelf'): left as it is
_WHERE_IS54S = re.compiled(
    r"(?:'s|'re|\b(?:is|are|was|were|sits?|lies|lie|stands?|stays?|remains?|been))\s*$", _F
)


def _where_twice54s(text: str, lexicon: Lexicon) -> str:
    """Session 54 (12s): 'up top on the S' said 'on the S' (above)."""
    low = text.lower()
    if "up " not in low and "over there" not in low and "down " not in low:
        return text

    def one(m: re.Match[str]) -> str:
        if _WHERE_IS54S.search(text[: m.start()]):
            return m[0]  # "The apple's up there on the shelf": where it is, no placing
        named = _ids(m["s"], lexicon)
        return "" if named and named == _ids(m["s"], lexicon, "surface") else m[0]

    out = _WHERE_TWICE54S.sub(one, text)
    return _read_or44r(out, text, lexicon)


# -- session 54 (12s): 'Ava's changing Lily.' opening a request -------------------------------
#
# "Ava's changing Lily. So wipes to Ava first. Then once she's got them, bib on the high chair."
# (blind52 #78): the lexer takes an unknown word and the first name after it for one unknown name
# ('changing Lily'), so the opening remark of what one person is doing with another is refused
# ("Ava is changing the baby." and "Marco's serving Mr Novak." are read as remarks). Said "P's busy
# with Q", which the older rules read as a remark naming both (a he / she after it may be either:
# refused naming both). Only a clause opening the text, P and Q one person each, the -ing word no
# verb of a task or a want ('giving', 'wanting', 'getting' …), a request after it, and no he /
# she after it that may be Q (but 'once she's got them', the one just handed them).
_DOING_WITH54S = re.compiled(
    rf"^(?P<p>{_WHO53S})(?:'s| is) (?P<v>[a-z]+ing) (?P<q>(?:mr|mrs|ms|miss|dr) [a-z]+|[a-z]+)"
    r"(?P<sep>\s*[.;,]\s*(?:so |and |but )?)(?P<rest>\S.*)$",
    _F,
)
_PRONOUN54S = re.compiled(r"\b(he|she|him|her|his|hers)\b", _F)
_GOT_BACK54S = re.compiled(
    r"\b(?:once|when|after|as soon as) (?:he|she)(?:'s| has) got (?:them|it)\b", _F
)
_NOT_DOING54S = frozenset(
    {
        "giving", "handing", "passing", "bringing", "taking", "fetching", "putting", "placing",
        "sending", "getting", "asking", "wanting", "needing", "expecting", "waiting", "calling",
        "telling", "having", "holding", "keeping", "carrying", "grabbing", "eating", "drinking",
        "using", "missing", "bring", "seeing", "meeting", "leaving", "owing", "paying", "letting",
    }
)  # fmt: skip


def _doing_with54s(text: str, lexicon: Lexicon) -> str:
    """Session 54 (12s): "Ava's changing Lily. …" said "Ava's busy with Lily. …" (above)."""
    if "ing " not in text:
        return text
    m = _DOING_WITH54S.match(text.strip())
    if m is None or m["v"].lower() in _NOT_DOING54S:
        return text
    if not (_only_person(m["p"], lexicon) and _only_person(m["q"], lexicon)):
        return text
    if _ids(m["p"], lexicon) == _ids(m["q"], lexicon):
        return text
    (qid,) = _ids(m["q"], lexicon)
    sex = unnamed_sex44l(qid, lexicon)
    rest = _GOT_BACK54S.sub("", m["rest"])  # 'once she's got them': the one just handed them
    if any(sex in (None, PRONOUN_SEX[w.lower()]) for w in _PRONOUN54S.findall(rest)):
        return text  # a he / she after it that may be Q: left as it is
    out = f"{m['p']}'s busy with {m['q']}{m['sep']}{m['rest']}"
    return _plain51s(out, text, lexicon)


# -- session 54 (12s): 'No point hanging about, Person A's bottle to her now.' -----------------
#
# blind52 #129: an opener saying nothing holds the request up ('no point hanging about / around',
# 'no point dawdling', 'no time to lose') is dropped before the request, as session 41's
# `_no_wait41r` drops 'no point waiting (around)' (left to it); and "P's X to her / him" (the X
# that is P's, to the pronoun that is P's sex by the scene) said "the X to P".
_NO_POINT54S = re.compiled(
    r"^(?:there's |there is )?(?:no point (?:in )?(?:(?:hanging|dawdling|messing|faffing|standing|"
    r"sitting)(?: about| around)?|waiting about)|no time to (?:lose|waste))\s*[,;:]\s*(?=[a-z])",
    _F,
)
_OWN_TO_THEM54S = re.compiled(
    rf"^(?P<p>{_WHO53S})'s (?P<x>[a-z]+(?: [a-z]+)?) (?:to|for|over to|across to) "
    r"(?P<pro>her|him)\b(?P<rest>[^,;.!?]*(?:,? please)?\s*[.!]?)$",
    _F,
)


def _no_point54s(text: str, lexicon: Lexicon) -> str:
    """Session 54 (12s): 'No point hanging about, …' dropped; "P's X to her" said "The X to P"
    (above)."""
    low = text.lower()
    if "no " not in low and "'s " not in low:
        return text
    out = text.strip()
    m = _NO_POINT54S.match(out)
    if m is not None:
        out = out[m.end() :]
    own = _OWN_TO_THEM54S.match(out)
    if own is not None and _only_person(own["p"], lexicon):
        (pid,) = _ids(own["p"], lexicon)
        x = _ids(f"the {own['x']}", lexicon)
        if (
            unnamed_sex44l(pid, lexicon) == PRONOUN_SEX[own["pro"].lower()]
            and x
            and x == _ids(f"the {own['x']}", lexicon, "object")
        ):
            out = f"The {own['x']} to {own['p']}{own['rest']}"
    if out == text.strip():
        return text
    out = out[:1].upper() + out[1:]
    return _plain51s(out, text, lexicon)


def _own_to_other54s(text: str, node: Node, lexicon: Lexicon) -> None:
    """Session 54 (12s): "Grandad's teddy to her." read `teddy>B` on main 8977c130: the pronoun
    that is not P's sex by the scene handed to P all the same. A reading that hands the X to P
    there is refused."""
    if "'s " not in text:
        return
    own = _OWN_TO_THEM54S.match(text.strip())
    if own is None or not _only_person(own["p"], lexicon):
        return
    (pid,) = _ids(own["p"], lexicon)
    sex = unnamed_sex44l(pid, lexicon)
    if sex is None or sex == PRONOUN_SEX[own["pro"].lower()]:
        return
    x = _ids(f"the {own['x']}", lexicon, "object")
    if any(t.kind == "deliver" and t.obj in x and t.target == pid for t in tasks(node)):
        raise GroundingError(
            f"{own['pro']!r} cannot be {own['p']}: say who gets {own['p']}'s {own['x']}"
        )


# the normaliser's first rewrites (wired into normalise._STEPS19, before the session-53 ones)
_STEPS54S_FIRST: tuple[Callable[[str, Lexicon], str], ...] = (
    _no_then_want54s,
    _not_today54s,
    _nothing_again54s,
    _where_twice54s,
    _doing_with54s,
    _no_point54s,
)
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-53 ones)
_STEPS54S: tuple[Callable[[str, Lexicon], str], ...] = (_not_that54s, _none_for54s, _stays_cleft54s)
# refusals asked of the text before it is read (offline._parse, after the session-53 ones)
REFUSE54S: tuple[Callable[[str, Lexicon], None], ...] = ()
# checks of the whole instruction's reading (offline.parse_instruction, after the session-53 ones)
CHECK54S: tuple[Callable[[str, Node, Lexicon], None], ...] = (_not_where54s, _own_to_other54s)
