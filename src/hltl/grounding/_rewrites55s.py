"""The grounder's rules of session 55, engineer 12s (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import (
    _F,
    _ids,
    _names,
    _objects_only,
    _only,
    _only_person,
)
from hltl.grounding._rewrites44r import _read_without44r
from hltl.grounding._rewrites51s import _plain51s
from hltl.grounding._rewrites53s import _UNSAFE53S, _WHO53S
from hltl.grounding.lexicon import PRONOUN_SEX, Lexicon, unnamed_sex44l
from hltl.grounding.tree import Node, Task, tasks

# -- session 55 (12s): where a thing is, read as a placing beside a request for it --------------
#
# "The apple's on the shelf, give it to Bob." read `apple@shelf & apple>B` (12c, session 54): the
# grammar reads a goal said as a state ("The apple is on the shelf." is a placing, session 51),
# and the 'it' after it takes the apple. Said beside another task on the same thing, 'the X's /
# is / are (up / still / sat …) on the S' says where the thing is (where to find it), not where
# it goes: a reading that places the X there AND does something else with it is refused ('The
# apple's on the shelf, Bob wants it.' is refused so already). 'Once / after / when the X is on
# the S' (an order) is no such clause: the clause must open the text or follow a stop, a comma or
# 'and / but / so'.
_STATE55S = re.compiled(
    r"(?:(?P<stop>^|[;:.!?—–-]\s*)|,\s*|\b(?:and|but|so)\s+)(?P<x>(?:(?:the|that|this|these|those|"
    r"my|your|his|her|their|our) )?(?:[a-z]+ ){0,2}?[a-z]+)(?P<be>'s|'re| is| are|"
    r"(?=,? (?:up |down |over |back )?(?:on|in) the ))(?: (?:still|already|just|now|"
    r"currently|all|right|up|down|over|back|there|here|high|top|sat|sitting|lying|stood|standing|"
    r"out|safe|somewhere)){0,3} (?:on|in|inside|on top of|at|by|onto|into) "
    r"(?P<s>the (?:[a-z]+ ){0,2}?[a-z]+?)(?=\s*(?:[,;:.!?—–-]|$|\b(?:and|but|so|give|hand|pass|"
    r"take|bring|get)\b))",
    _F,
)
_BE55S = ("'s ", " is ", " are ", "'re ", " on the ", " in the ")
_DET55S = frozenset(
    {"the", "that", "this", "these", "those", "my", "your", "his", "her", "their", "our"}
)


def _unordered55s(node: Node) -> list[Task]:
    """The placings in ``node`` whose object another task of an ``and`` or an ``or`` with them
    moves too (no order between them)."""
    if isinstance(node, Task):
        return []
    out = [t for c in node.children for t in _unordered55s(c)]
    if node.op != "seq":
        per = [list(tasks(c)) for c in node.children]
        for i, mine in enumerate(per):
            others = {u.obj for j, theirs in enumerate(per) if j != i for u in theirs}
            out.extend(t for t in mine if t.kind == "place" and t.obj in others)
    return out


def _where_is55s(text: str, node: Node, lexicon: Lexicon) -> None:
    """Session 55 (12s): where a thing is, read as a placing beside another task on it (above)."""
    if isinstance(node, Task):
        return
    low = text.lower()
    if not any(w in low for w in _BE55S):
        return
    placed = _unordered55s(node)
    if not placed:
        return
    for m in _STATE55S.finditer(text):
        if not m["be"] and m["stop"] is None:
            continue  # '…, and the apple on the table': a placing said with the verb before
        named = _names(m["x"], lexicon)
        said = m["x"].lower().split(" ", 1)
        bare = said[1] if said[0] in _DET55S and len(said) > 1 else m["x"].lower()
        if len(named) != 1 or named[0].text.lower() != bare or not _objects_only(bare, lexicon):
            continue  # 'Once the apple', 'Bob and the apple': not one thing's name alone
        xs, ss = _ids(m["x"], lexicon), _ids(m["s"], lexicon, "surface")
        for t in placed:
            if t.obj in xs and t.target in ss:
                raise GroundingError(
                    f"{m.group(0).lstrip(',;:.!?—–- ')!r} may say where the {t.obj} is (to find "
                    "it), and the reading would place it there and do more with it (no order "
                    f"said): say 'put the {t.obj} on …, then …' to have it placed, or ask only "
                    "for the rest"
                )


# -- session 55 (12s): 'he had it yesterday' beside a handover of it to him --------------------
#
# "The apple for Bob, he had it yesterday." / "Bob's apple to him, he had it yesterday." read
# `apple>B` (12c, session 53: want refused): 'had it' of the one who gets it says he has had the
# thing already (or, of food, eaten it) — the handover may be done or no longer meant. A clause
# 'he / she / P had / 'd had / has had / 's had it / them / that' (not after 'after / once /
# when …', which orders; not 'I had it', the speaker), whose he / she may be a person the
# reading hands something to, beside that handover, is refused ('had one / some' of the kind so
# too: 12r's doubtful "Any of the four is fine for Person A, she had one earlier.").
_HAD_IT55S = re.compiled(
    r"(?:^|[,;:.!?—–-]\s*|\b(?:and|but|as|since|because|cos|'cause)\s+)(?P<p>he|she|they|"
    r"(?:mr|mrs|ms|miss|dr|person) [a-z]+|[a-z]+)(?:'s|'d| has| had)?(?: (?:already|just|only|"
    r"even|actually|definitely))? had (?:it|them|that|those|one|some)\b(?! first\b)",
    _F,
)
# "…, she's had / got / taken the blue one." (12c): a holding or a use of a thing said by its
# colour alone, of the one the reading hands a thing of that colour to
_HAD_ONE55S = re.compiled(
    r"(?:^|[,;:.!?—–-]\s*|\b(?:and|but|as|since|because|cos|'cause)\s+)(?P<p>he|she|they|"
    r"(?:mr|mrs|ms|miss|dr|person) [a-z]+|[a-z]+)(?:'s|'d| has| had)?(?: (?:already|just|only|"
    r"even|actually|definitely))? (?:had|got|taken|took|eaten|ate|used) (?:the|that|this|his|her) "
    r"(?P<adj>[a-z]+)(?: one)?(?=\s*(?:[,;:.!?]|$))",
    _F,
)


def _recipients55s(said: str, given: set[str], lexicon: Lexicon) -> set[str]:
    """The people of ``given`` a he / she / they / name ``said`` may be."""
    p = said.lower()
    if p == "they":
        return given
    if p in PRONOUN_SEX:
        return {g for g in given if unnamed_sex44l(g, lexicon) in (None, PRONOUN_SEX[p])}
    return given & _ids(said, lexicon, "human")


def _had_it55s(text: str, node: Node, lexicon: Lexicon) -> None:
    """Session 55 (12s): 'he had it yesterday' beside a handover of it to him (above)."""
    low = text.lower()
    if not any(w in low for w in _HAD55S):
        return
    handed = [t for t in tasks(node) if t.kind == "deliver"]
    given = {t.target for t in handed}
    if not given:
        return
    for m in _HAD_IT55S.finditer(text):
        if _recipients55s(m["p"], given, lexicon):
            raise GroundingError(
                f"{m.group(0).lstrip(',;:.!?—–- ')!r}: the one who gets it has had it already "
                "(or used it up), so whether it is still to be handed over is not said: say "
                "the request again"
            )
    for m in _HAD_ONE55S.finditer(text):
        adj = m["adj"].lower()
        if adj in {
            n.lower() for o in lexicon.scene.objects for n in (o.id, o.category, *o.aliases)
        }:
            continue  # "Marco's got the tongs, and …": the thing's noun, a share (lead, s55)
        may = _recipients55s(m["p"], given, lexicon)
        for t in handed:
            if t.target in may and adj in _words55s(t.obj, lexicon):
                raise GroundingError(
                    f"{m.group(0).lstrip(',;:.!?—–- ')!r}: the one who gets the {t.obj} has had "
                    "or got one like it already, so whether it is still to be handed over is not "
                    "said: say the request again"
                )


_HAD55S = ("had ", "got ", "taken ", "took ", "eaten ", "ate ", "used ")


def _words55s(oid: str, lexicon: Lexicon) -> set[str]:
    """The words of object ``oid``'s id and names (its colour among them)."""
    obj = next(o for o in lexicon.scene.objects if o.id == oid)
    names = [obj.id.replace("_", " "), *obj.aliases]
    return {w.lower() for n in names for w in n.split()}


# -- session 55 (12s): 'scrap the X for P, it's the Y she's after' ----------------------------
#
# "Scrap the chips for Person A, it's the apple she's actually after.", "Skip the chips for Person
# B, it's only the bottle he's needing.", "Forget pens for Sam, it's the stapler he's after."
# (blind53 #124 #131 #133): a thing struck off a person's request before it is given ('scrap /
# skip / forget (about) / ditch / drop / never mind the X for P'), then what that person wants
# instead ("it's (only / actually) the Y (that) he's after / needing / wants", "he's after the
# Y", "just / only the Y"), nothing after it: said "No X for P, just the Y.", which the grammar
# reads (alone 'Scrap the chips.' changes a running task and stays refused). The he / she P's
# sex by the scene; the X and the Y things of the scene, apart; P one person; nothing that says a
# holding or a doing (session 53's `_UNSAFE53S`).
_Y55S = (
    r"(?:(?:the|that|this|those|these|his|her) )?[a-z]+(?: (?!that\b|which\b|he\b|she\b)[a-z]+)?"
)
_SCRAP_FOR55S = re.compiled(
    r"^(?:(?:ok|okay|right|oh|actually|sorry|hmm|no)\s*,?\s*)*(?:scrap|skip|forget(?: about)?|"
    r"ditch|drop|never mind(?: about)?|cross off|strike off) "
    rf"(?P<x>(?:the |any |those |these |that )?[a-z]+(?: [a-z]+)?) (?:for|to) (?P<p>{_WHO53S})"
    r"\s*[,;:—–-]\s*(?:(?:it's|it is|it was) (?:only |actually |really |just )?"
    rf"(?P<y>{_Y55S}) (?:(?:that|which) )?(?P<pro>he|she)(?:(?:'s| is) (?:actually |really |only )?"
    r"(?:after|needing|wanting|on about)| (?:really |actually )?(?:wants|needs|would like)|'d like)"
    r"|(?P<pro2>he|she)(?:'s| is) (?:actually |really |only )?"
    rf"(?:after|wanting|needing) (?P<y2>{_Y55S})|(?:just|only) (?P<y3>{_Y55S}))"
    r"(?: instead)?(?:,? please)?(?P<end>\s*[.!]?)$",
    _F,
)


def _only_one55s(pid: str, sex: str, lexicon: Lexicon) -> bool:
    """Whether a he / she of ``sex`` can be person ``pid`` alone: ``pid`` that sex by the scene,
    or of no sex the scene says while everyone else is of the other."""
    mine = unnamed_sex44l(pid, lexicon)
    if mine == sex:
        return True
    others = [h.id for h in lexicon.scene.humans if h.id != pid]
    return mine is None and all(unnamed_sex44l(o, lexicon) not in (None, sex) for o in others)


def _scrap_for55s(text: str, lexicon: Lexicon) -> str:
    """Session 55 (12s): "Scrap the X for P, it's the Y she's after" said "No X for P, just the
    Y" (above)."""
    low = text.lower()
    if not any(w in low for w in _SCRAP55S):
        return text
    if _UNSAFE53S.search(text):
        return text
    m = _SCRAP_FOR55S.match(text.strip())
    if m is None or not _only_person(m["p"], lexicon):
        return text
    y = m["y"] or m["y2"] or m["y3"]
    if y.lower().endswith(" one") and " " in m["x"]:
        y = f"{y[:-4]} {m['x'].split()[-1]}"  # "the blue one" after "the red pen": the blue pen
    x, ys = _ids(m["x"], lexicon), _ids(y, lexicon)
    if not x or not ys or x & ys:
        return text
    if x != _ids(m["x"], lexicon, "object") or ys != _ids(y, lexicon, "object"):
        return text
    pro = m["pro"] or m["pro2"]
    if pro is not None:
        (pid,) = _ids(m["p"], lexicon)
        if not _only_one55s(pid, PRONOUN_SEX[pro.lower()], lexicon):
            return text
    said = m["x"].removeprefix("that ").removeprefix("any ")
    thing = (
        y if y.lower().startswith(("the ", "that ", "this ", "those ", "these ")) else f"the {y}"
    )
    out = f"No {said} for {m['p']}, just {thing}{m['end']}"
    if _read_without44r(out, text, m["x"], lexicon) == text:
        return text
    return _plain51s(out, text, lexicon)


_SCRAP55S = (
    "scrap",
    "skip",
    "forget",
    "ditch",
    "drop",
    "never mind",
    "cross off",
    "strike off",
)


# -- session 55 (12s): 'not the green cup, … the white' --------------------------------------
#
# "Emma's not having the green cup, she's having the white." (blind53 #132): the kind left out
# after a colour or size word ('the white' for the white cup) after a thing of that kind named
# whole and set aside ('not / isn't / doesn't … the green cup'): an older remark rule drops "she's
# having the white" (naming, to it, nothing) and the negation is left alone. 'the ADJ' ending a
# clause, after 'the ADJ2 N' said before it in a text that sets a thing aside, is said 'the ADJ
# N' when that names one object of the scene, not the one before ('the ADJ' alone naming nothing
# else); 'the ADJ one' so too (12c: "…, she's having the white one. Emma wants the bowl." read
# only the bowl: the clause was dropped when the next sentence is the same person's want).
_KIND_BEFORE55S = re.compiled(r"\bthe (?P<adj>[a-z]+) (?P<n>[a-z]+)\b", _F)
_BARE_ADJ55S = re.compiled(
    r"\bthe (?P<adj>[a-z]+)(?: one)?(?=\s*(?:[,;.!]|$|\b(?:please|instead|then|now|thanks)\b))",
    _F,
)
_SET_ASIDE55S = ("not ", "n't ", "instead", "rather", "no ")
_MAYBE55S = re.compiled(r"\b(?:might|may|maybe|perhaps|could|would|should|took|taken|used)\b", _F)


def _bare_adj55s(text: str, lexicon: Lexicon) -> str:
    """Session 55 (12s): 'not the green cup, … the white' said '… the white cup' (above)."""
    low = text.lower()
    if not any(w in low for w in _SET_ASIDE55S):
        return text
    if _UNSAFE53S.search(text) or _MAYBE55S.search(text):
        return text  # 12c: "…, she's had / got / taken the blue.", "…, she might have the blue."
    before = [
        (m.end(), m["adj"], m["n"], _ids(m[0], lexicon, "object"))
        for m in _KIND_BEFORE55S.finditer(text)
        if _only(m[0], lexicon, "object")
    ]
    if not before:
        return text

    def one(m: re.Match[str]) -> str:
        said = [b for b in before if b[0] <= m.start()]
        if not said:
            return m[0]
        _end, adj, n, first = said[-1]
        if adj.lower() == m["adj"].lower():
            return m[0]
        whole = f"the {m['adj']} {n}"
        if not _only(whole, lexicon, "object"):
            return m[0]
        (oid,) = _ids(whole, lexicon, "object")
        if oid in first or not _ids(f"the {m['adj']}", lexicon) <= {oid}:
            return m[0]
        return whole

    out = _BARE_ADJ55S.sub(one, text)
    return _plain51s(out, text, lexicon)


# -- session 55 (12s): '…, is he having the blue mug?' ---------------------------------------
#
# "Bob's not having the red mug, is he having the blue mug?" read `mug_blue>B` on main ceed68bd:
# the closing clause only asks whether he is (session 39's `_not_wanted39r` says the first
# clause "Bob doesn't want the red mug", and the question was read as the want). A text that
# ends, after a first clause, in a clause asking a fact of a person ('…, is / does / did / has /
# was he / she / they / P …?'; not 'could / can / might P have …?' nor 'is P able / alright /
# allowed to …?', which ask for it) is refused when read.
_ASKS_IF55S = re.compiled(
    r"[,;:.!—–-]\s*(?:and |so |or |but |then )?(?P<aux>is|isn't|are|aren't|does|doesn't|did|"
    r"didn't|has|hasn't|have|haven't|was|wasn't|were|weren't) (?P<p>he|she|they|person [a-z]|"
    r"(?:mr|mrs|ms|miss|dr) [a-z]+|[a-z]+)\b(?! (?:able|alright|all right|allowed|ok|okay|free|"
    r"fine|happy|good) to\b)[^,;:.!?]*\?\s*$",
    _F,
)


def _asks_if55s(text: str, node: Node, lexicon: Lexicon) -> None:
    """Session 55 (12s): a text ending in a question of fact about a person, read (above)."""
    if not text.rstrip().endswith("?"):
        return
    m = _ASKS_IF55S.search(text)
    if m is None:
        return
    p = m["p"].lower()
    if p not in ("he", "she", "they") and not _ids(m["p"], lexicon, "human"):
        return
    raise GroundingError(
        f"{m.group(0).lstrip(',;:.!—–- ')!r} asks whether something is so: a question that only "
        "asks is no request; say what to do"
    )


# -- session 55 (12s): 'P can't eat the X, so she gets the Y instead' --------------------------
#
# "Carol can't eat the apple, braces, so she gets the crisps instead." (blind53 #120): what a
# person cannot eat / drink / have / use, then a request for another thing: said "P doesn't want
# the X, so …", which session 39's rules read (the X named whole; a short aside after it that
# names nothing of the scene, 'braces', dropped). The reading must hand the X to no one.
_CANT_HAVE55S = re.compiled(
    rf"^(?P<p>{_WHO53S}) (?:can't|cannot|can not|mustn't|must not|isn't allowed to|is not allowed "
    r"to|isn't supposed to) (?:eat|have|drink|use|touch|manage|stomach)(?: from| out of)? "
    r"(?P<x>(?:the|that|this|those|these|any) [a-z]+(?: [a-z]+)?)"
    r"(?:\s*,\s*(?P<aside>[a-z]+(?: [a-z]+){0,2}))?(?P<rest>\s*[,;]\s*(?:so |and |but )\S.*)$",
    _F,
)


def _cant_have55s(text: str, lexicon: Lexicon) -> str:
    """Session 55 (12s): "P can't eat the X, so she gets the Y instead" said "P doesn't want the
    X, so …" (above)."""
    low = text.lower()
    if "can" not in low and "n't" not in low and "not" not in low:
        return text
    if text.rstrip().endswith("?") or _UNSAFE53S.search(text):
        return text
    m = _CANT_HAVE55S.match(text.strip())
    if m is None or not _only_person(m["p"], lexicon):
        return text
    x = _ids(m["x"], lexicon)
    if not x or x != _ids(m["x"], lexicon, "object"):
        return text
    if m["aside"] and _names(m["aside"], lexicon):
        return text
    out = f"{m['p']} doesn't want {m['x']}{m['rest']}"
    if _read_without44r(out, text, m["x"], lexicon) == text:
        return text
    return _plain51s(out, text, lexicon)


# -- session 55 (12s): "The X isn't P's to have; Q's getting it." --------------------------------
#
# blind53 #127: who a thing is not for, then who gets it ("The X isn't P's (to have) / isn't for
# P; Q's getting / having it"): said "The X isn't for P, it's for Q.", which the grammar reads.
# P and Q one person each, apart; the X named whole; nothing after.
_NOT_THEIRS55S = re.compiled(
    r"^(?P<x>(?:the|that|this) [a-z]+(?: [a-z]+)?)(?: isn't| is not|'s not) (?:(?P<p>"
    rf"{_WHO53S})'s(?: to (?:have|keep|take))?|for (?P<p2>{_WHO53S}))\s*[;,.]\s*(?:it's |it is )?"
    rf"(?P<q>{_WHO53S})(?:'s| is) (?:getting|having|(?:meant |supposed )?to (?:have|get)) "
    r"(?:it|them)(?P<end>\s*[.!]?)$",
    _F,
)


def _not_theirs55s(text: str, lexicon: Lexicon) -> str:
    """Session 55 (12s): "The X isn't P's to have; Q's getting it." said "The X isn't for P, it's
    for Q." (above)."""
    low = text.lower()
    if "not" not in low and "n't" not in low:
        return text
    m = _NOT_THEIRS55S.match(text.strip())
    if m is None:
        return text
    p = m["p"] or m["p2"]
    if not (_only_person(p, lexicon) and _only_person(m["q"], lexicon)):
        return text
    if _ids(p, lexicon) == _ids(m["q"], lexicon):
        return text
    x = _ids(m["x"], lexicon)
    if not x or x != _ids(m["x"], lexicon, "object"):
        return text
    out = f"{m['x']} isn't for {p}, it's for {m['q']}{m['end']}"
    return _plain51s(out, text, lexicon)


# -- session 55 (12s): 'No one but P gets that X' -----------------------------------------------
#
# "No one but Person A gets that bottle, so over it goes to her." (blind53 #129): 'no one /
# nobody but / except / other than P' opening the text is "Only P", which the grammar reads.
_NO_ONE_BUT55S = re.compiled(
    rf"^(?:no one|no-one|nobody) (?:but|except|other than|apart from|besides) (?P<p>{_WHO53S})"
    r"(?= (?:gets|is getting|is having|should get|can have|is to have|wants|needs)\b)",
    _F,
)


def _no_one_but55s(text: str, lexicon: Lexicon) -> str:
    """Session 55 (12s): 'No one but P gets the X' said 'Only P gets the X' (above)."""
    low = text.lower()
    if "no" not in low or ("body" not in low and "one" not in low):
        return text
    if _UNSAFE53S.search(text):
        return text
    m = _NO_ONE_BUT55S.match(text.strip())
    if m is None or not _only_person(m["p"], lexicon):
        return text
    out = f"Only {m['p']}{text.strip()[m.end() :]}"
    return _plain51s(out, text, lexicon)


# -- session 55 (12s): '…, she might have the blue.' --------------------------------------------
#
# "Carol's not having the red mug, she might have the blue." and "Alice might want the apple." read
# as handovers on main ceed68bd (12c): 'P might have / want / need / like …', 'P may want / need /
# like …' says a maybe, not a request (not after 'whether / if / any chance / hoping', which ask
# leave: "Mr Novak has asked whether he might have some salt"); a reading of such a text is
# refused.
_MIGHT55S = re.compiled(
    r"\b(?P<p>he|she|they|(?:mr|mrs|ms|miss|dr|person) [a-z]+|[a-z]+)"
    r"(?: might(?: (?:well|just|also))? (?:have|want|need|like|fancy|prefer|get|take)| may (?:want|"
    r"need|like|fancy|prefer))\b",
    _F,
)


_LEAVE55S = re.compiled(
    r"\b(?:whether|if|chance|hoping|hope|wonder|wondering|wondered)\s+(?:(?:person|mr|mrs|ms|miss|"
    r"dr)\s+)?$",
    _F,
)


def _might55s(text: str, node: Node, lexicon: Lexicon) -> None:
    """Session 55 (12s): a reading of a text saying a maybe of a person (above)."""
    low = text.lower()
    if "might " not in low and "may " not in low:
        return
    for m in _MIGHT55S.finditer(text):
        if _LEAVE55S.search(text[: m.start()]):
            continue  # 'whether he might have', 'any chance Person B might get'
        p = m["p"].lower()
        if p in ("he", "she", "they") or _ids(m["p"], lexicon, "human"):
            raise GroundingError(f"{m.group(0)!r} says a maybe, not a request: say what to do")


# -- session 55 (12s): "It's P wanting the X, not Q", '…, Q can wait her turn' ------------------
#
# "It's Mrs Khan wanting the water jug, not Mr Lee, he's fine." (blind53 #134): a cleft with an
# -ing want ('It's P wanting / needing / after the X') said "P wants / needs / is after the X",
# which the grammar reads with the rest. "Noah's the one the glue stick is for, Zoe can wait her
# turn." (#137): a closing 'Q can / will have to / must wait her / his / their turn' of another
# person said ', not Q' (the pronoun Q's sex by the scene, or unknown).
_ITS_WANTING55S = re.compiled(
    rf"^it(?:'s| is) (?P<p>{_WHO53S}) (?P<v>wanting|needing|after) (?P<x>(?:the|that|this|his|her) "
    r"[a-z]+(?: [a-z]+)?)(?P<rest>\s*(?:[,;.!]|$).*)$",
    _F,
)
_WAIT_TURN55S = re.compiled(
    rf"(?P<sep>\s*[,;]\s*)(?:and |but |so )?(?P<q>{_WHO53S}) (?:can|will (?:have to|just have to)|"
    r"must|has to|'ll have to|'ll just have to) wait (?P<pro>her|his|their) turn(?P<end>\s*[.!]?)$",
    _F,
)
_WANTING55S = {"wanting": "wants", "needing": "needs", "after": "is after"}


def _its_wanting55s(text: str, lexicon: Lexicon) -> str:
    """Session 55 (12s): "It's P wanting the X" said "P wants the X"; '…, Q can wait her turn'
    said '…, not Q' (above)."""
    low = text.lower()
    if "wait " in low and " turn" in low:
        m = _WAIT_TURN55S.search(text.rstrip())
        if m is not None and _only_person(m["q"], lexicon) and not _UNSAFE53S.search(text):
            (qid,) = _ids(m["q"], lexicon)
            pro = m["pro"].lower()
            if pro == "their" or unnamed_sex44l(qid, lexicon) in (None, PRONOUN_SEX[pro]):
                out = f"{text.rstrip()[: m.start()]}, not {m['q']}{m['end']}"
                return _plain51s(out, text, lexicon)
    if "wanting" not in low and "needing" not in low and "after" not in low:
        return text
    if text.rstrip().endswith("?") or _UNSAFE53S.search(text):
        return text
    m = _ITS_WANTING55S.match(text.strip())
    if m is None or not _only_person(m["p"], lexicon):
        return text
    x = _ids(m["x"], lexicon)
    if not x or x != _ids(m["x"], lexicon, "object"):
        return text
    out = f"{m['p']} {_WANTING55S[m['v'].lower()]} {m['x']}{m['rest']}"
    return _plain51s(out, text, lexicon)


# the normaliser's first rewrites (wired into normalise._STEPS19, before the session-54 ones)
_STEPS55S_FIRST: tuple[Callable[[str, Lexicon], str], ...] = (
    _scrap_for55s,
    _bare_adj55s,
    _cant_have55s,
    _not_theirs55s,
    _no_one_but55s,
    _its_wanting55s,
)
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-54 ones)
_STEPS55S: tuple[Callable[[str, Lexicon], str], ...] = ()
# refusals asked of the text before it is read (offline._parse, after the session-54 ones)
REFUSE55S: tuple[Callable[[str, Lexicon], None], ...] = ()
# checks of the whole instruction's reading (offline.parse_instruction, after the session-54 ones)
CHECK55S: tuple[Callable[[str, Node, Lexicon], None], ...] = (
    _where_is55s,
    _had_it55s,
    _asks_if55s,
    _might55s,
)
