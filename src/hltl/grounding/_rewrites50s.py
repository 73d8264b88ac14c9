"""The grounder's rules of session 50, engineer 12s (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _ids, _names, _only_person
from hltl.grounding._normalise2 import _inert28
from hltl.grounding._normalise3 import _not_cleft30r
from hltl.grounding._rewrites41s import _ORDER41S, _WANT_SAID41S
from hltl.grounding._rewrites42r import _negated_then42r
from hltl.grounding._rewrites42s import _NEGATED42S, _remark_only42s
from hltl.grounding._rewrites43s import _NOW_OVER43S, _now_over43s
from hltl.grounding._rewrites44r import _read_or44r, _read_without44r
from hltl.grounding._rewrites44s import _agrees44s
from hltl.grounding._rewrites45r import _isnt_its45r
from hltl.grounding._rewrites50 import asked_now_over50
from hltl.grounding.lexicon import Lexicon
from hltl.grounding.tree import Node

# -- session 50 (12s): negation and exclusion (blind48's) ---------------------------------------
#
# "It isn't the bottle Alice has her heart set on after the hooky mat session, it's the crisps.",
# "It's not the ruler Noah's after for the straw plaiting, it's the scissors.": the negated cleft
# of sessions 30 and 45 (12r) with a want said another way ('has her heart set on', "'s after"
# joined to the name) and what the want is for after it; "Marco didn't ask for the tongs, it's
# the knife he's after, …": the want denied, then the cleft of the one wanted. Said "P wants the
# Y, not the X" (session 33's 'not X'), when P is one person of the scene (a he / she the
# person may be), X and Y things of it, and what the want is for names nothing of the scene.
_WANT50S = (
    r"(?P<v>'s after| is after| was after|'s wanting| wants| wanted| needs| needed| asked for|'s "
    r"asked for| has asked for|(?:'s got| has got| has) (?:his|her|their) (?:heart set|eye|eyes)"
    r" on| fancies| is keen on|'s keen on|'s craving| is craving|'s hankering after| is hankering"
    r" after| would like)"
)
_THING50S = r"(?:the|a|an) [a-z]+(?: [a-z]+)??"
_PERSON50S = r"(?:person [a-z]|(?:mr|mrs|ms|miss|dr) [a-z]+|[a-z]+)"
_FOR50S = r"(?P<mod>(?: (?:for|after|at|before|from) [a-z][a-z' -]*?)?)"
_NOT_CLEFT50S = re.compile(
    rf"^it(?: isn't| is not|'s not| wasn't| was not) (?P<x>{_THING50S}) (?:that |which )?"
    rf"(?P<p>{_PERSON50S}){_WANT50S}{_FOR50S}\s*[,;]\s*(?:it's|it is|it was|but it's) "
    rf"(?P<y>{_THING50S})(?P<rest>\s*(?:[,;.!].*)?)$",
    _F,
)
_DENIED_CLEFT50S = re.compile(
    rf"^(?P<p>{_PERSON50S}) (?:didn't|did not|doesn't|does not|hasn't|has not|never) (?:ask for|"
    rf"want|need|mean|ask after|order) (?P<x>{_THING50S})\s*[,;]\s*(?:it's|it is|it was) "
    rf"(?P<y>{_THING50S}) (?P<q>he|she|{_PERSON50S}){_WANT50S}{_FOR50S}"
    r"(?P<rest>\s*(?:[,;.!].*)?)$",
    _F,
)


def _not_cleft50s(text: str, lexicon: Lexicon) -> str:
    """Session 50 (12s): the negated clefts above said 'P wants the Y, not the X'."""
    low = text.lower()
    if "not" not in low and "n't" not in low and "never" not in low:
        return text
    m = _NOT_CLEFT50S.match(text.strip()) or _DENIED_CLEFT50S.match(text.strip())
    if m is None or not _only_person(m["p"], lexicon):
        return text
    if any(rule(text, lexicon) != text for rule in (_not_cleft30r, _isnt_its45r, _negated_then42r)):
        return text  # the older rules' forms are theirs (each one's refused_without test)
    q = m["q"].lower() if "q" in m.groupdict() else m["p"].lower()
    if q != m["p"].lower() and (q not in ("he", "she") or not _agrees44s(m["p"], q, lexicon)):
        return text
    if not _ids(m["x"], lexicon, "object") or _ids(m["x"], lexicon) != _ids(
        m["x"], lexicon, "object"
    ):
        return text
    if not _ids(m["y"], lexicon, "object") or _ids(m["y"], lexicon) != _ids(
        m["y"], lexicon, "object"
    ):
        return text
    if m["mod"] and not _remark_only42s(m["mod"], lexicon):
        return text
    for pron in re.findall(r"\b(?:his|her|their)\b", m["v"], flags=_F):
        if pron.lower() == "their" or not _agrees44s(m["p"], pron, lexicon):
            return text  # "… Bob has her heart set on": whose heart?
    out = f"{m['p']} wants {m['y']}, not {m['x']}{m['rest'] or '.'}"
    return _read_or44r(out, text, lexicon)


# -- session 50 (12s): typos and lower case (blind48's) ------------------------------------------
#
# "can person a have the bottle now her make-up artist shift is done": session 43's 'now her
# <doing>'s over' after a want (`_now_over43s`), after 'can / could / may P have X' (asking that
# the person have it) or 'P can have X' as well: the person's doing over is why they may have it.
_MAY_HAVE50S = re.compile(
    rf"^(?P<lead>\s*(?:(?:so|and|oh|right|ok|okay)[, ]+)?)(?:(?:can|could|may|might) "
    rf"(?P<p>{_PERSON50S}) have|(?P<p2>{_PERSON50S}) (?:can|could|may) have) ",
    _F,
)


def _now_over50s(text: str, lexicon: Lexicon) -> str:
    """Session 50 (12s): the 'now …'s over' of a 'can P have X' taken off as session 43's; else
    (session 51, one rule for the family) 12's closing 'now her X's over' of a request asked as
    a question (`_rewrites50.asked_now_over50`)."""
    if "now" not in text.lower():
        return text
    out = _may_have_now_over50s(text, lexicon)
    return out if out != text else asked_now_over50(text, lexicon)


def _may_have_now_over50s(text: str, lexicon: Lexicon) -> str:
    """'can / could / may P have X now her Y's over' read as P's want (`_now_over43s`)."""
    body = text.rstrip()
    ask = body.endswith("?")
    if ask:
        body = body[:-1].rstrip()
    m = _MAY_HAVE50S.match(body)
    over = _NOW_OVER43S.search(body)
    if m is None or over is None:
        return text
    who = m["p"] or m["p2"]
    if not _only_person(who, lexicon):
        return text
    wants = f"{who} wants {body[m.end() :]}"
    if _now_over43s(wants, lexicon) == wants:
        return text
    out = f"{body[: over.start()]}{'?' if ask else (over['end'] or '').strip()}"
    return _read_or44r(out, text, lexicon)


# "Could the fchips head over to Person A, she's …": a thing of the scene asked to 'head' (over)
# to a person, as 'go' (which the grammar reads: "Could the chips go over to Person A").
_HEAD_OVER50S = re.compile(
    r"^(?P<lead>\s*(?:could|can|would|will|might) (?P<x>(?:the|that|those|these) [a-z]+"
    r"(?: [a-z]+)??) )(?:head|wander|trot|toddle|travel|drift|hop|nip|pop)(?= (?:over |across |"
    r"along |round )?to\b)",
    _F,
)


def _head_over50s(text: str, lexicon: Lexicon) -> str:
    """Session 50 (12s): 'could the X head over to P' said 'could the X go over to P', when X
    names things of the scene only."""
    m = _HEAD_OVER50S.match(text)
    if m is None:
        return text
    x = _ids(m["x"], lexicon)
    if not x or _ids(m["x"], lexicon, "object") != x:
        return text
    return _read_or44r(f"{m['lead']}go{text[m.end() :]}", text, lexicon)


# "Give Carol the blue mug, not the red, she says the red one's got a funny taste.": the reason
# after 'not the X' names the X again ('the red one', 'the red'): said 'it' (what session 31's
# reasons read: "…, not the red, she says it's got a funny taste."), when the words name the one
# thing 'not' leaves out and nothing else of the scene.
_NOT_AGAIN50S = re.compile(
    r"(?P<not>,\s*not (?:the )?(?P<x>[a-z]+(?: [a-z]+)?)(?: one)?\s*,\s*(?:(?:he|she|they) "
    r"(?:says|said|reckons|thinks) |because |cos |as )?)(?P<again>the (?P<x2>[a-z]+(?: [a-z]+)?)"
    r"(?: one)?)(?=(?:'s|'ve| is| has| was| tastes| smells| looks) )",
    _F,
)


def _not_again50s(text: str, lexicon: Lexicon) -> str:
    """Session 50 (12s): the thing left out, named again in the reason after it, said 'it'."""
    if "not" not in text.lower():
        return text
    m = _NOT_AGAIN50S.search(text)
    if m is None or _ids(m["x2"], lexicon, "human"):
        return text
    if re.sub(r" one$", "", m["x"].lower()) != re.sub(r" one$", "", m["x2"].lower()):
        return text
    if _ids(text[m.end() :], lexicon):
        return text
    out = f"{text[: m.start('again')]}it{text[m.end('again') :]}"
    return _read_or44r(out, text, lexicon)


# "Person A wants no chips, no bottle, just the apple.": the things not wanted, each with 'no',
# then 'just (only) the Z': said 'P wants just the Z, not the X or the Y' (session 42's 'not the
# X or the Y'), when X, Y and Z name things of the scene and P one person.
_NO_NO_JUST50S = re.compile(
    rf"^(?P<p>{_PERSON50S})(?P<v> wants| needs|'s after| is after| would like| asked for) "
    r"(?P<nos>no [a-z]+(?: [a-z]+)?(?:(?:\s*,\s*|\s+)(?:and |or )?no [a-z]+(?: [a-z]+)?)+)\s*,\s*"
    r"(?:just|only) (?P<z>(?:the|a|an) [a-z]+(?: [a-z]+)?)(?P<end>\s*[.!]?)\s*$",
    _F,
)


def _no_no_just50s(text: str, lexicon: Lexicon) -> str:
    """Session 50 (12s): 'P wants no X, no Y, just the Z' said 'P wants just the Z, not the X or
    the Y'."""
    if "no " not in text.lower():
        return text
    m = _NO_NO_JUST50S.match(text.strip())
    if m is None or not _only_person(m["p"], lexicon):
        return text
    nos = [n.strip()[3:] for n in re.split(r"(?:\s*,\s*|\s+)(?:and |or )?(?=no )", m["nos"])]
    things = [f"the {n}" for n in nos]
    for t in (*things, m["z"]):
        if not _ids(t, lexicon) or _ids(t, lexicon) != _ids(t, lexicon, "object"):
            return text
    out = f"{m['p']}{m['v']} just {m['z']}, not {' or '.join(things)}{m['end'] or '.'}"
    return _read_or44r(out, text, lexicon)


# "Lily's thrown the red block on the floor twice, so not that one, the green block for her.": a
# reason naming one thing of the scene, then 'so not that one (that, it)' and the request: said
# "Not the X, <request>" (session 33's 'not X, Y'), when the reason names that one thing (and
# perhaps the request's person) and nothing else, negates nothing and the request reads.
_SO_NOT_THAT50S = re.compile(
    r"^(?P<reason>[^,;.!?]+?)\s*,\s*so not (?:that one|that|it|this one)\s*,\s*(?P<rest>[^;.!?]+"
    r"[.!]?)\s*$",
    _F,
)


def _so_not_that50s(text: str, lexicon: Lexicon) -> str:
    """Session 50 (12s): the reason before 'so not that one' said as 'Not the X'."""
    if "so not" not in text.lower():
        return text
    m = _SO_NOT_THAT50S.match(text.strip())
    if m is None or _NEGATED42S.search(m["reason"]):
        return text
    said = [
        w
        for w in re.findall(r"\bthe [a-z]+(?: [a-z]+)?(?![a-z])", m["reason"], flags=_F)
        if _ids(w, lexicon, "object")
    ]
    x = _ids(said[0], lexicon) if len(said) == 1 else set()
    people = _ids(m["reason"], lexicon, "human")
    others = _ids(m["reason"].replace(said[0] if said else "", " "), lexicon) - people
    if len(x) != 1 or len(people) > 1 or others:
        return text
    rest = m["rest"]
    if people and not people <= _ids(rest, lexicon, "human"):
        # "Lily's thrown the red block …, so not that one, the green block for her.": 'her' is
        # the one person the reason names, when they may be (said by name)
        who = next(it.text for it in _names(m["reason"], lexicon) if it.refs[0].kind == "human")
        pron = re.findall(r"\b(?:him|her|them)\b", rest, flags=_F)
        if len(pron) != 1 or _ids(rest, lexicon, "human") or not _agrees44s(who, pron[0], lexicon):
            return text
        rest = re.sub(r"\b(?:him|her|them)\b", who, rest, flags=_F)
    if x <= _ids(rest, lexicon):
        return text
    out = f"Not {said[0]}, {rest}"
    return _read_without44r(out, text, said[0], lexicon) if out != text else text


# "Pferson A wants the bottle for the highlining trip tomorrow.": what the thing is for, an
# occasion of two or three words, then when the occasion is ('tomorrow', 'tonight', 'later'):
# session 28's `_purpose28` takes 'for the trip tomorrow' off (two words), not three. Taken off
# the same way after a want, when its words name nothing of the scene and hold none of
# _KEEP_WORDS (`_inert28`).
_PURPOSE_WHEN50S = re.compile(
    r",?\s+for (?:the|a|an|his|her|their|my|our) (?P<what>[a-z]+(?:[ -][a-z]+){1,2}) (?:tomorrow|"
    r"tonight|later|this (?:afternoon|evening|weekend)|at the weekend|next week)(?=\s*[.!]?\s*$)",
    _F,
)


def _purpose_when50s(text: str, lexicon: Lexicon) -> str:
    """Session 50 (12s): 'for the <occasion> tomorrow' closing a want taken off (above)."""
    if "for " not in text.lower():
        return text
    m = _PURPOSE_WHEN50S.search(text)
    if m is None or not _inert28(m["what"], lexicon):
        return text
    out = f"{text[: m.start()]}{text[m.end() :]}"
    if not _WANT_SAID41S.search(out) or _ORDER41S.search(out):
        return text
    return _read_or44r(out, text, lexicon)


# "Hand the bottle to perszon A on her way to the straw plaiting, would you.": 'on her way (to
# <occasion>, out, past)' right after the person a thing goes to says when they pass, not
# another place: taken off, when the pronoun may be that person (`_agrees44s`) and the words
# name nothing of the scene.
_ON_WAY50S = re.compile(
    r"\b(?P<to>to|for) (?P<p>[a-z]+(?: [a-z]+)?) (?P<way>on (?P<pron>his|her|their) way(?: (?:to|"
    r"over to|down to|up to|off to) (?:the |a |an |his |her |their )?(?P<what>[a-z]+(?:[ -][a-z]+)"
    r"{0,2})| out| in| past| through| home| back)?)(?=\s*(?:[,.;!?]|$))",
    _F,
)


def _on_way50s(text: str, lexicon: Lexicon) -> str:
    """Session 50 (12s): 'to P on her way to X' said 'to P' (above)."""
    if " way" not in text.lower():
        return text
    m = _ON_WAY50S.search(text)
    if m is None or not _only_person(m["p"], lexicon) or m["pron"].lower() == "their":
        return text
    if not _agrees44s(m["p"], m["pron"], lexicon) or _ids(m["way"], lexicon):
        return text
    if m["what"] and not _inert28(m["what"], lexicon):
        return text
    out = f"{text[: m.start('way')].rstrip()}{text[m.end('way') :]}"
    return _read_or44r(out, text, lexicon)


# "Work glives for Tom, it's cold on the belt.": a closing remark on the weather where the person
# works ('it's cold on the belt', 'it's freezing by the locker'): the place names a surface of
# the scene, so the remark was read as a placing. Said without the place ("…, it's cold." reads as
# before), when it closes a request to a person that names no surface.
_COLD_ON50S = re.compile(
    r"(?P<cold>[,;.]\s*(?:and |cos |because )?it(?:'s| is| gets)(?: (?:so|really|very|bitter|"
    r"perishing|freezing))? (?:cold|freezing|chilly|nippy|parky|bitter|perishing|hot|boiling|"
    r"baking|roasting|warm|damp|draughty|drafty))(?P<place> (?:on|by|at|near|in|over) the "
    r"[a-z]+(?: [a-z]+)?)(?P<end>\s*[.!]?\s*)$",
    _F,
)


def _cold_on50s(text: str, lexicon: Lexicon) -> str:
    """Session 50 (12s): the place of a closing weather remark taken off (above)."""
    m = _COLD_ON50S.search(text)
    if m is None or not _ids(m["place"], lexicon, "surface"):
        return text
    before = text[: m.start()]
    if _ids(before, lexicon, "surface") or not _ids(before, lexicon, "human"):
        return text
    out = f"{before}{m['cold']}{m['end']}"
    return _read_or44r(out, text, lexicon)


# the normaliser's first rewrites (wired into normalise._STEPS19, before the session-49 ones)
_STEPS50S_FIRST: tuple[Callable[[str, Lexicon], str], ...] = ()
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-49 ones)
_STEPS50S: tuple[Callable[[str, Lexicon], str], ...] = (
    _not_cleft50s,
    _now_over50s,
    _head_over50s,
    _not_again50s,
    _no_no_just50s,
    _so_not_that50s,
    _purpose_when50s,
    _on_way50s,
    _cold_on50s,
)
# refusals asked of the text before it is read (offline._parse, after the session-49 ones)
REFUSE50S: tuple[Callable[[str, Lexicon], None], ...] = ()
# checks of the whole instruction's reading (offline.parse_instruction, after the session-49 ones)
CHECK50S: tuple[Callable[[str, Node, Lexicon], None], ...] = ()
