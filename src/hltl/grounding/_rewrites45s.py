"""The grounder's rules of session 45, engineer 12s (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _ids, _names, _only_person, _reading
from hltl.grounding._rewrites38 import _FRONTED38, _JOINS38, _inert38
from hltl.grounding._rewrites41s import _ORDER41S
from hltl.grounding._rewrites42s import _NEED_STATE42S, _NEGATED42S, _P42S, _remark_only42s
from hltl.grounding._rewrites43s import _HAS43S, _LATER43S
from hltl.grounding._rewrites44s import _SAYING44S, _agrees44s
from hltl.grounding.lexicon import VERBS, Lexicon
from hltl.grounding.tree import Node, tasks

# -- session 45 (12s): run-ons, a text with no marks ----------------------------------------------
#
# "person b gets the chips hes earned them at ferreting", "pop the spoon on the tray its been lying
# about since the lampwork demo", "salt shaker to mr novak he says the soup needs it": a request,
# then with no mark a clause whose subject is a pronoun (he / she / it / they, its 's said or
# dropped): the comma the writer left out put back (the older remark rules then read it), when
# what comes before reads by itself, the clause names nothing of the scene, negates nothing and
# corrects nothing, a he / she fits the one person named before it, an 'it' has a thing before it,
# a 'they' two people, and the whole reads exactly as the request alone.
_RUN_ON45S = re.compile(
    r"(?<=[a-z]) (?P<p>he|she|hes|shes|he's|she's|its|it's|they|theyre|they're|they've|theyve)"
    r"(?= [a-z])",
    _F,
)
_APOSTROPHE45S = {"hes": "he's", "shes": "she's", "its": "it's", "theyre": "they're"}
_CORRECTS45S = re.compile(
    r"\b(?:actually|sorry|wait|instead|rather|meant|mean|or|but|either|neither|only|except|"
    r"first|then|after|afterwards|later|next)\b",
    _F,
)
_COURTESY45S = frozenset({"please", "pls", "plz", "thx", "thanks", "ta", "cheers"})
_NOT_BEFORE45S = _JOINS38 | _SAYING44S | {"to", "for", "the", "a", "an", "with", "of", "on", "in"}


def _same45s(a: Node | None, b: Node | None) -> bool:
    """Whether two readings are both there and hand over or place the same things."""
    return a is not None and b is not None and set(tasks(a)) == set(tasks(b))


def _run_on45s(text: str, lexicon: Lexicon) -> str:
    """Session 45 (12s): the comma above put back, when the whole then reads as the request
    before the clause alone does."""
    if re.search(r"[,;:.!?]", text) or not _RUN_ON45S.search(text):
        return text
    for m in _RUN_ON45S.finditer(text):
        before, after = text[: m.start()], text[m.end() :]
        words = before.split()
        if not words or words[-1].lower() in _NOT_BEFORE45S or words[-1].lower() in VERBS:
            continue
        if words[-1].lower() in _COURTESY45S:
            continue  # "tape for tom please hes at bay four": sessions 38 and 39's (12)
        if _names(after, lexicon) or _NEGATED42S.search(after) or _CORRECTS45S.search(after):
            continue
        pron = m["p"].lower()
        if pron in ("hes", "shes", "he's", "she's") and _inert38(
            re.sub(
                r"\b(?:his|her|their|all (?:day|morning|afternoon|evening|night|week))\b|\bonly "
                r"just\b",
                " ",
                after,
                flags=_F,
            ),
            lexicon,
        ):
            continue  # "the teddy to lily shes back from her swimming lesson": session 38's
        alone = _reading(before, lexicon)
        if alone is None:
            continue
        people = _ids(before, lexicon, "human")
        if pron.startswith(("he", "she")):
            if len(people) != 1:
                continue
            who = next(it.text for it in _names(before, lexicon) if it.refs[0].kind == "human")
            if not _agrees44s(who, pron.split("'")[0].removesuffix("s"), lexicon):
                continue
        elif pron.startswith("it"):
            if not _ids(before, lexicon, "object"):
                continue
        elif len(people) < 2:
            continue
        said = _APOSTROPHE45S.get(pron, m["p"])
        out = f"{before}, {said}{after}"
        if _same45s(_reading(out, lexicon), alone):
            return out
    return text


# "Person A gets the cup, Person B gets the chips, they both want them before the mummers start":
# that the people the request gives to want what it gives them, closing it: taken off, when each
# person named gets something and what follows names nothing, negates nothing, corrects nothing.
_THEY_WANT45S = re.compile(
    r",\s*they(?:'ve| have|'re| are)? (?:both |all |each )?(?:want|need|after|asked for|wanted|"
    r"been after|waiting for|waiting on|been waiting for|been asking for|asking for) (?:them|it|"
    r"those|these|both|them both|them all)\b(?P<tail>[^.;:!?,]*)"
    r"(?P<end>[.!]?)\s*$",
    _F,
)


def _they_want45s(text: str, lexicon: Lexicon) -> str:
    """Session 45 (12s): the closing remark above taken off, when what is left reads giving
    each person it names something, two or more of them."""
    if "they" not in text.lower():
        return text
    m = _THEY_WANT45S.search(text)
    if m is None:
        return text
    tail = m["tail"]
    if _names(tail, lexicon) or _NEGATED42S.search(tail) or _CORRECTS45S.search(tail):
        return text
    out = text[: m.start()] + m["end"]
    read = _reading(out, lexicon)
    people = _ids(out, lexicon, "human")
    if read is None or len(people) < 2 or not people <= {t.target for t in tasks(read)}:
        return text
    return out


# "crisps over to Alice who's off ferreting, and that's everything": a clause about the person
# said just before it, with no comma ('who's', 'who is', 'who has'): the comma put in, when the
# clause names nothing, negates nothing, and the whole reads as the text without it does.
_WHO_REMARK45S = re.compile(
    r"(?<=[a-z]) (?P<c>who(?:'s| is| has| was|'d| had) [^.;:!?,]+)",
    _F,
)


def _who_remark45s(text: str, lexicon: Lexicon) -> str:
    """Session 45 (12s): the comma above put in (see there)."""
    if "who" not in text.lower():
        return text
    m = _WHO_REMARK45S.search(text)
    if m is None:
        return text
    before = text[: m.start()]
    last = _names(before, lexicon)
    if not last or last[-1].refs[0].kind != "human" or not before.rstrip().endswith(last[-1].text):
        return text  # 'the cup who …': not after a person
    clause = m["c"]
    if _names(clause, lexicon) or _NEGATED42S.search(clause) or _CORRECTS45S.search(clause):
        return text
    out = f"{before},{text[m.start() :]}"
    if _same45s(_reading(out, lexicon), _reading(before + text[m.end() :], lexicon)):
        return out
    return text


# -- session 45 (12s): lower case, an opening or a closing run on --------------------------------
#
# "after two hours of underwater hockey person b is gasping for that bottle": an opening 'after
# …' (or 'since …') with no comma before the clause it sets the time of: the comma put in before
# the first person of the scene, when the words before them name nothing, ask nothing and negate
# nothing, and the whole reads as the clause from the person on does alone (a want or a state of
# theirs, not an order: "after lunch give bob the cup" puts the task off and stays refused).
_AFTER_OPENING45S = re.compile(r"^(?P<head>(?:after|since|following) [^.;:!?,]+?) (?=[a-z])", _F)


def _after_opening45s(text: str, lexicon: Lexicon) -> str:
    """Session 45 (12s): the comma above put in (see there)."""
    if not re.match(r"(?:after|since|following) ", text, _F) or re.search(r"[,;:]", text):
        return text
    items = _names(text, lexicon)
    if not items or items[0].refs[0].kind != "human":
        return text
    at = re.search(rf"\b{re.escape(items[0].text)}\b", text, _F)
    if at is None:
        return text
    head, rest = text[: at.start()].rstrip(), text[at.start() :]
    if not re.fullmatch(r"(?:after|since|following) [a-z' -]+", head, _F):
        return text
    words = head.split()[1:]
    if any(w.lower() in VERBS for w in words) or _NEGATED42S.search(head):
        return text
    if not re.match(
        rf"{re.escape(items[0].text)}(?:'s|s)? (?:is|was|has|could|would|wants|needs|"
        r"'s|'d|fancies)\b",
        rest,
        _F,
    ):
        return text  # an order after the time ('after lunch give …'), or no clause of theirs
    out = f"{head}, {rest}"
    if _same45s(_reading(out, lexicon), _reading(rest, lexicon)):
        return out
    return text


# "person a could do with the bottle after her carolling thx": a courtesy word closing a text with
# no marks: the comma before it put in, when the whole then reads as the text without it does.
_CLOSER45S = re.compile(r"(?<=[a-z]) (?P<c>thx|thanks|ta|cheers|pls|plz|please|ty)\s*$", _F)


def _closer45s(text: str, lexicon: Lexicon) -> str:
    """Session 45 (12s): the comma above put in (see there)."""
    m = _CLOSER45S.search(text)
    if m is None or re.search(r"[,;:.!?]", text):
        return text
    before = text[: m.start()]
    items = _names(before, lexicon)
    last = before.lower().rfind(items[-1].text.lower()) if items else -1
    if last < 0 or not re.match(
        r"\s*(?:after|since|following) ", before[last + len(items[-1].text) :], _F
    ):
        return text  # a closer after a name of the scene: the older courtesy rules take it off
    out = f"{before}, {m['c']}"
    if _same45s(_reading(out, lexicon), _reading(before, lexicon)):
        return out
    return text


# "lilys thirsty after her nap so sippy cup to her pls", "Grandad's shattered after the fete so
# the bib to him": how one person of the scene is (words naming nothing, wanting nothing but a
# need of theirs, negating nothing, no time to come), then 'so' with no comma and what is to be
# done whose pronouns fit them: the comma put in, when the whole then reads giving them something.
_STATE_SO45S = re.compile(
    rf"^(?P<who>{_P42S})(?P<words>(?:'s| is| was| has been|'s been|(?<=s)) [^.;:!?,]{{2,80}}?) so "
    r"(?P<rest>[^.;:!?]+)",
    _F,
)


def _state_so45s(text: str, lexicon: Lexicon) -> str:
    """Session 45 (12s): the comma above put in (see there)."""
    if " so " not in text.lower():
        return text
    m = _STATE_SO45S.match(text)
    if m is None or _FRONTED38.match(text):
        return text  # 'bobs back from the allotment so …': session 38's
    who = m["who"]
    if m["words"].startswith(" ") and not re.match(r" (?:is|was|has) ", m["words"]):
        if text != text.lower() or not who.endswith("s"):
            return text
        who = who[:-1]  # 'lilys thirsty': the apostrophe dropped (session 39's `_name_s39`)
    if not _only_person(who, lexicon):
        return text
    words = re.sub(r"\b(?:his|her|their)\b", "", _NEED_STATE42S.sub("", m["words"]), flags=_F)
    if not _remark_only42s(words, lexicon) or _LATER43S.search(
        re.sub(
            r"\bafter (?:his|her|the|"
            r"a|an) \w+",
            "",
            m["words"],
        )
    ):
        return text
    rest = m["rest"]
    if _ids(rest, lexicon, "human") or _ORDER41S.match(rest) or _HAS43S.match(rest):
        return text  # 'so give him …' (session 42's), 'so the glue is hers' (session 43's)
    if re.match(r"(?:he|she|they)\b", rest, _F):
        return text  # 'so she needs …': the older state rules'
    for p in re.findall(r"\b(?:he|she|him|her|his|hers)\b", rest + m["words"], _F):
        if not _agrees44s(who, p, lexicon):
            return text
    out = f"{text[: m.start('rest') - 4]}, so {text[m.start('rest') :]}"
    read = _reading(out, lexicon)
    if read is None or not _ids(who, lexicon, "human") & {t.target for t in tasks(read)}:
        return text
    return out


# "Marco's doing the lemon posset so the lemon's his, and Lena wants the knife for the bread": a
# reason (session 43's `_so_reason43s`) whose words name a thing of the scene only as the first
# word of another thing ('lemon posset', 'banana bread', 'apple pie': a word naming nothing of the
# scene after it, no verb, no joining word), then 'so the X's his / hers' and more after a comma:
# "The lemon goes to Marco, and …" (the pronoun must fit them, X a thing of the scene).
_SO_HIS45S = re.compile(
    rf"^(?:(?:poor|dear|little|old) )?(?P<who>{_P42S})(?P<words>(?:'s|\s)[^.;:!?,]{{2,60}}?),?\s+"
    r"so\s+(?P<x>(?:the|that|this) [a-z]+(?: [a-z]+)?)(?:'s| is) (?P<p>his|hers)\b",
    _F,
)
_NOT_NOUN45S = frozenset(
    {
        "and",
        "or",
        "so",
        "to",
        "for",
        "with",
        "on",
        "in",
        "at",
        "of",
        "from",
        "is",
        "are",
        "was",
        "too",
        "again",
        "then",
        "now",
        "please",
        "there",
    }
)


def _modifiers_out45s(words: str, lexicon: Lexicon) -> str:
    """``words`` without each scene name said as the first word of another thing ('the lemon
    posset': a word after it that names nothing of the scene, is no verb and joins nothing)."""
    out = words
    for it in _names(words, lexicon):
        if it.refs[0].kind != "object":
            continue
        m = re.search(rf"\b{re.escape(it.text)} (?P<n>[a-z]+)\b", out, _F)
        if m is None:
            continue
        n = m["n"].lower()
        if n in _NOT_NOUN45S or n in VERBS or _names(n, lexicon) or n.endswith("'s"):
            continue
        out = out[: m.start()] + out[m.start() + len(it.text) + 1 :]
    return out


def _so_his45s(text: str, lexicon: Lexicon) -> str:
    """Session 45 (12s): the reason above taken off and the clause said as where the thing goes,
    when what is left reads giving the thing to the person."""
    if " so " not in text.lower():
        return text
    m = _SO_HIS45S.match(text)
    if m is None or not _only_person(m["who"], lexicon):
        return text
    words = _modifiers_out45s(re.sub(r"^(?:'s|\s)\s*", "", m["words"]), lexicon)
    if words == re.sub(r"^(?:'s|\s)\s*", "", m["words"]):
        return text  # no such name: session 43's rule reads it, or nothing does
    words = re.sub(r"\b(?:his|her)\b", "", words, flags=_F)
    if not _remark_only42s(words, lexicon) or _LATER43S.search(words):
        return text
    if not _agrees44s(m["who"], m["p"], lexicon):
        return text
    x = m["x"]
    if not _ids(x, lexicon, "object") or _ids(x, lexicon, "human") or _ids(x, lexicon, "surface"):
        return text
    said = f"{x} goes to {m['who']}"
    out = said[:1].upper() + said[1:] + text[m.end() :]
    read = _reading(out, lexicon)
    pid = next(iter(_ids(m["who"], lexicon, "human")))
    if read is None or not any(t.target == pid and t.obj in _ids(x, lexicon) for t in tasks(read)):
        return text
    return out


# -- session 45 (12s): a purpose or a remark of what the person does with the thing ---------------
#
# "The apple is for Person B to take to show jumping", "The crisps are for Bob to take home":
# 'to take (it) to / home / along …' after 'for <person>', naming nothing more, is what they do
# with it once theirs: taken off. "hand person a the cup she takes it to clavichord lessons",
# "Give Bob the crisps, he takes them to judo": the same said as a remark closing a request to one
# person, whose pronoun fits them: taken off. "… for Bob to take to Alice" (a person; a surface)
# stays refused.
_FOR_TAKE45S = re.compile(
    rf"\bfor (?P<who>{_P42S}) to take (?:it |them )?(?P<tail>(?:to|home|along|back|with (?:him|"
    r"her))\b[^.;:!?,]*)",
    _F,
)
_TAKES_IT45S = re.compile(
    r"(?:,\s*|\s+)(?P<p>he|she) (?:takes|'ll take|will take|is taking|'s taking|always takes|"
    r"usually takes) (?:it|them) (?P<tail>(?:to|along to|with (?:him|her) to)\b[^.;:!?,]*)"
    r"(?P<end>[.!]?)\s*$",
    _F,
)


def _take_to45s(text: str, lexicon: Lexicon) -> str:
    """Session 45 (12s): the purpose or remark above taken off, when what is left reads giving
    the person something."""
    if "take" not in text.lower():
        return text
    m = _FOR_TAKE45S.search(text)
    if m is not None:
        if not _only_person(m["who"], lexicon) or _names(m["tail"], lexicon):
            return text
        who, out = m["who"], text[: m.start()] + f"for {m['who']}" + text[m.end() :]
    else:
        m = _TAKES_IT45S.search(text)
        if m is None or _names(m["tail"], lexicon):
            return text
        people = [it for it in _names(text[: m.start()], lexicon) if it.refs[0].kind == "human"]
        if len({r.id for it in people for r in it.refs}) != 1:
            return text
        who = people[0].text
        if not _agrees44s(who, m["p"], lexicon):
            return text
        out = text[: m.start()] + m["end"]
    if _NEGATED42S.search(m["tail"]) or _CORRECTS45S.search(m["tail"]):
        return text
    read = _reading(out, lexicon)
    if read is None or not _ids(who, lexicon, "human") & {t.target for t in tasks(read)}:
        return text
    return out


# "The glovfes want putting on the pallet, the fuller left them on the floor": who left the thing
# where it is (someone, or a person of the scene; the place naming nothing of the scene), closing
# a request that names it: taken off, when what is left reads.
_LEFT_IT45S = re.compile(
    r"(?:,\s*|\s+)(?P<subj>(?:the|my|our|some|a|an|that) [a-z]+|someone|somebody|[a-z]+"
    r"(?: [a-z]+)?) (?:left|dumped|dropped|chucked|abandoned|put|stuck|shoved) (?P<x>it|them) "
    r"(?P<tail>(?:on|in|by|under|near|out|lying|there|behind|about|all over|down)\b[^.;:!?,]*)"
    r"(?P<end>[.!]?)\s*$",
    _F,
)


def _left_it45s(text: str, lexicon: Lexicon) -> str:
    """Session 45 (12s): the closing remark above taken off (see there)."""
    if " it " not in text.lower() and " them " not in text.lower():
        return text
    m = _LEFT_IT45S.search(text)
    if m is None:
        return text
    subj = m["subj"]
    if _names(subj, lexicon) and not _only_person(subj, lexicon):
        return text
    if subj.split()[-1].lower() in VERBS or subj.lower() in ("it", "they", "he", "she", "you"):
        return text
    tail = m["tail"]
    if _names(tail, lexicon) or _NEGATED42S.search(tail) or _CORRECTS45S.search(tail):
        return text
    out = text[: m.start()] + m["end"]
    things = _ids(out, lexicon, "object")
    if not things or (m["x"].lower() == "it" and len(things) != 1):
        return text
    read = _reading(out, lexicon)
    if read is None or not things <= {t.obj for t in tasks(read)}:
        return text
    return out


# "marcos on the grill tonight and hes shouting for the tongs": where one person is, then 'and'
# and a want of theirs said with its own he / she: the pronoun taken out ("… and is shouting for
# the tongs", which session 42's rules read), when it fits the person, the words before name
# nothing but what is theirs, and what is left reads giving them something.
_AND_PRON45S = re.compile(
    rf"^(?P<who>{_P42S})(?P<words>(?:'s| is| was|(?<=s)) [^.;:!?,]{{2,60}}?) and (?P<p>he|she)"
    r"(?:'s|s| is) (?=(?:shouting|asking|calling|yelling|begging|crying out|gasping|dying|"
    r"desperate|itching|angling) (?:for|after)\b)",
    _F,
)


def _and_pron45s(text: str, lexicon: Lexicon) -> str:
    """Session 45 (12s): the pronoun above taken out (see there)."""
    if " and " not in text.lower():
        return text
    m = _AND_PRON45S.match(text)
    if m is None:
        return text
    who = m["who"]
    if m["words"].startswith(" ") and not re.match(r" (?:is|was) ", m["words"]):
        if text != text.lower() or not who.endswith("s"):
            return text
        who = who[:-1]  # 'marcos on the grill': the apostrophe dropped
    if not _only_person(who, lexicon) or not _agrees44s(who, m["p"], lexicon):
        return text
    words = re.sub(r"\b(?:his|her|their)\b", "", m["words"], flags=_F)
    if not _remark_only42s(words, lexicon):
        return text
    said = m["words"] if not m["words"].startswith(" ") or m["who"] == who else "'s" + m["words"]
    out = f"{who}{said} and is {text[m.end() :]}"
    read = _reading(out, lexicon)
    if read is None or not _ids(who, lexicon, "human") & {t.target for t in tasks(read)}:
        return text
    return out


# "Person A's having the cup and Person B the apple and the chips go to Person B too": a clause
# said again without its verb ('and Person B the apple'), then 'and the X go to P too' where P is
# that clause's person: wherever the clause before the plural 'go' ends, the apple and the chips
# are P's, so the grammar's doubt (which objects 'go') does not matter: said "…, and the chips to
# Person B too". Another person after 'to' stays refused (the apple may go with the chips).
_GO_TOO45S = re.compile(
    rf"(?P<pre>\b(?P<p1>{_P42S}) (?P<y>(?:the|his|her) [a-z]+(?: [a-z]+)?)),? and (?P<x>(?:the|"
    rf"his|her) [a-z]+(?: [a-z]+)?) go to (?P<p2>{_P42S}) (?P<too>too|as well)(?P<end>[.!]?)\s*$",
    _F,
)


def _go_too45s(text: str, lexicon: Lexicon) -> str:
    """Session 45 (12s): the 'and the X go to P too' above said as 'and the X to P too', when
    both people are the same one of the scene and what is left reads giving them X."""
    if " go to " not in text.lower():
        return text
    m = _GO_TOO45S.search(text)
    if m is None or not _only_person(m["p1"], lexicon) or not _only_person(m["p2"], lexicon):
        return text
    pid = _ids(m["p1"], lexicon, "human")
    if pid != _ids(m["p2"], lexicon, "human"):
        return text
    x = m["x"]
    if not _ids(x, lexicon, "object") or _ids(x, lexicon, "human") or _ids(x, lexicon, "surface"):
        return text
    out = f"{text[: m.end('pre')]}, and {x} to {m['p2']} {m['too']}{m['end']}"
    read = _reading(out, lexicon)
    if read is None or not any(t.target in pid and t.obj in _ids(x, lexicon) for t in tasks(read)):
        return text
    return out


# the normaliser's rewrites run before the session-44 ones (wired into normalise._STEPS19)
_STEPS45S_FIRST: tuple[Callable[[str, Lexicon], str], ...] = (
    _run_on45s,
    _they_want45s,
    _who_remark45s,
    _after_opening45s,
    _closer45s,
    _state_so45s,
    _so_his45s,
    _take_to45s,
    _left_it45s,
    _and_pron45s,
    _go_too45s,
)
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-44 ones)
_STEPS45S: tuple[Callable[[str, Lexicon], str], ...] = ()
# refusals asked of the text before it is read (offline._parse, after the session-44 ones)
REFUSE45S: tuple[Callable[[str, Lexicon], None], ...] = ()
# checks of the whole instruction's reading (offline.parse_instruction, after the session-44 ones)
CHECK45S: tuple[Callable[[str, Node, Lexicon], None], ...] = ()
