"""The grounder's rules of session 45, engineer 12r (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _ids, _only_person, _reading
from hltl.grounding._rewrites44r import _BACK44R, _agrees44r, _read_or44r, _read_without44r
from hltl.grounding.lexicon import Lexicon
from hltl.grounding.tree import Group, Node, has_choice, tasks


def _one_each(node: Node | None) -> bool:
    """Whether ``node`` hands each of several people exactly one thing, and does nothing else."""
    if not isinstance(node, Group) or node.op != "and":
        return False
    said = list(tasks(node))
    people = [t.target for t in said]
    return all(t.kind == "deliver" for t in said) and len(set(people)) == len(people) > 1


# -- corrections -----------------------------------------------------------------------------------

# a cue that takes the request before back, said before the correction ("scratch that", "no,
# sorry", "whoops", "oh wait")
_TAKE_BACK45R = (
    r"\b(?:scratch that|no|nope|sorry|correction|wait|hang on|hold on|whoops|oops|my mistake|"
    r"actually|i mean|rather)\b"
)


def _one_person45r(words: str, lexicon: Lexicon) -> str | None:
    """The one person ``words`` names, or None."""
    pids = _ids(words, lexicon, "human")
    return next(iter(pids)) if len(pids) == 1 else None


# "…, scratch that, it's the bottle he wanted after his bachata class"
_WHAT_HE_WANTED45R = (
    r"\s*,\s*it(?:'s| is| was) (?P<x>(?:the|that) [a-z]+(?: [a-z]+)?) (?:that |which )?"
    r"(?P<pro>he|she) (?:wanted|wants|needs|needed|asked for|was after|is after|'s after|meant|"
    r"really wanted|really wants)\b[^,;.!?]*(?P<end>[.!]?)$"
)


def _what_he_wanted45r(text: str, lexicon: Lexicon) -> str:
    """Session 45 (12r): a correction "…, scratch that, it's the bottle he wanted (after his
    bachata class)" is "…, scratch that, the bottle" when 'he' is the request's one person (the
    correction names the thing; what follows 'wanted' is said of it)."""
    if "it" not in text.lower():
        return text
    m = re.search(_WHAT_HE_WANTED45R, text.strip(), _F)
    if m is None:
        return text
    head = text.strip()[: m.start()]
    pid = _one_person45r(head, lexicon)
    if (
        pid is None
        or not re.search(_TAKE_BACK45R, head, _F)
        or not _agrees44r(pid, m["pro"], lexicon)
    ):
        return text
    return _read_or44r(f"{head}, {m['x']}{m['end'] or '.'}", text, lexicon)


def _switch_to45r(text: str, lexicon: Lexicon) -> str:
    """Session 45 (12r): after a cue that takes the request back, "switch it to Person B" (swap,
    change, move it over to) is "make it Person B" (session 44's `_reason_fix44r` reads that)."""
    low = text.lower()
    if not any(w in low for w in ("switch", "swap", "change", "move", "shift")):
        return text
    m = re.search(
        r"\b(?:switch|swap|change|move|shift) (?P<it>it|that|them)(?: over| round)? to "
        r"(?P<p>[^,;.!?]+?)(?P<end>\s*[.!]?)$",
        text.strip(),
        _F,
    )
    if m is None or _one_person45r(m["p"], lexicon) is None or not _only_person(m["p"], lexicon):
        return text
    if not re.search(_BACK44R, text.strip()[: m.start()], _F):
        return text
    out = f"{text.strip()[: m.start()]}make {m['it']} {m['p']}{m['end'] or '.'}"
    return _read_or44r(out, text, lexicon)


def _belongs_with45r(text: str, lexicon: Lexicon) -> str:
    """Session 45 (12r): after a cue that takes the request back, "the chips belong with Person
    A" (go with, should go to) is "they're for Person A" ("it's for" of one thing), what session
    44's `_reason_fix44r` reads."""
    if not any(w in text.lower() for w in ("belong", "go with", "goes with")):
        return text
    m = re.search(
        r"\b(?P<x>the [a-z]+(?: [a-z]+)?|they|it) (?:belongs?|goes|go|should go) with "
        r"(?P<p>[^,;.!?]+?)(?P<end>\s*[.!]?)$",
        text.strip(),
        _F,
    )
    if m is None or not _only_person(m["p"], lexicon):
        return text
    head = text.strip()[: m.start()]
    if not re.search(_BACK44R, head, _F):
        return text
    x = m["x"].lower()
    if x.startswith("the ") and not _ids(m["x"], lexicon, "object") & _ids(head, lexicon):
        return text  # another thing than the request's
    many = x == "they" or (x.startswith("the ") and x.endswith("s"))
    out = f"{head}{'they are' if many else 'it is'} for {m['p']}{m['end'] or '.'}"
    return _read_or44r(out, text, lexicon)


def _better_verb45r(text: str, lexicon: Lexicon) -> str:
    """Session 45 (12r): "…, no, actually, better give it to Person A": 'better' ('best', "you'd
    better") before the corrected request's verb is dropped."""
    if "better" not in text.lower() and "best" not in text.lower():
        return text
    out = re.sub(
        r"(\b(?:no|actually|wait|sorry|hang on|correction|rather)\s*,\s*)(?:you'd |you had |"
        r"probably |)(?:better|best) (?=(?:give|hand|pass|bring|take|put|place|send|pop|set)\b)",
        r"\1",
        text,
        flags=_F,
    )
    return _read_or44r(out, text, lexicon)


# "Bottle to Person A... hmm, or... no, I had it right the first time, Person A."
_RIGHT_FIRST45R = (
    r"^(?P<head>.+?)\s*(?:\.\.\.|…|[,;.])\s*(?:(?:hmm|um|erm|er|or|or maybe|maybe)\s*"
    r"(?:\.\.\.|…|,)\s*)*no\s*,\s*(?:i had it right|i was right|i got it right|i had it|"
    r"it was right)(?: the first time| first time| before| all along)?"
    r"(?:\s*,\s*(?P<again>[^,;.!?]+?))?\s*[.!]?$"
)


def _right_first45r(text: str, lexicon: Lexicon) -> str:
    """Session 45 (12r): a request, a doubt ("hmm, or…"), then "no, I had it right the first
    time" (maybe saying its person or thing again): the request as said first, when it is one
    task and what is said again is in it."""
    if "right" not in text.lower():
        return text
    m = re.match(_RIGHT_FIRST45R, text.strip(), _F)
    if m is None:
        return text
    head = m["head"]
    if m["again"] is not None and not (
        _ids(m["again"], lexicon) and _ids(m["again"], lexicon) <= _ids(head, lexicon)
    ):
        return text
    node = _reading(head, lexicon)
    if node is None or len(list(tasks(node))) != 1 or isinstance(node, Group):
        return text
    return head if head.endswith((".", "!")) else f"{head}."


# "…, no sorry, it's Zoe drawing the corset pattern, give it to her"
_ITS_P_DOING45R = (
    r"(?P<cue>[,;.]\s*(?:no|sorry|oops|whoops|wait|hang on|correction)(?:\s*,?\s*(?:no|sorry|"
    r"actually))*\s*,\s*)it(?:'s| is) (?P<p>[^,;.!?]+?) (?:who's |who is |that's )?[a-z]+ing\b"
    r"[^,;.!?]*,\s*(?P<verb>give|hand|pass|bring|take|send) (?P<it>it|them) to (?P<pro>her|him)"
    r"(?P<end>\s*[.!]?)$"
)


def _its_p_doing45r(text: str, lexicon: Lexicon) -> str:
    """Session 45 (12r): a correction "…, no sorry, it's Zoe drawing the corset pattern, give it
    to her" is "…, no sorry, give it to Zoe", when 'her' may be that one person and no other."""
    if "it" not in text.lower():
        return text
    m = re.search(_ITS_P_DOING45R, text.strip(), _F)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    pid = _one_person45r(m["p"], lexicon)
    if pid is None or not _agrees44r(pid, m["pro"], lexicon):
        return text
    head = text.strip()[: m.start()]
    if pid in _ids(head, lexicon):
        return text  # the same person: no correction of the person
    if any(_agrees44r(q, m["pro"], lexicon) for q in _ids(head, lexicon, "human")):
        return text  # 'her' may be the person corrected away from too
    out = f"{head}{m['cue']}{m['verb']} {m['it']} to {m['p']}{m['end'] or '.'}"
    return _read_or44r(out, text, lexicon)


# "Teddy for Ava, whoops, she's too big for it now, Lily's the one who wants the teddy."
_ONE_WHO45R = (
    r"^(?P<head>[^,;.]+?)\s*[,;.]\s*(?P<cue>(?:whoops|oops|no|sorry|wait|hang on|correction|"
    r"actually)(?:\s*,?\s*(?:no|sorry|actually|wait))*)\s*,\s*(?P<why>(?:[^,;.]+[,;]\s*){0,2}?)"
    r"(?P<p>[^,;.!?]+?)(?:'s| is) the one (?:who |that )?(?:wants|needs|is after|'s after|asked "
    r"for|should have|should get|gets) (?P<x>it|them|the [a-z]+(?: [a-z]+)?)(?P<end>\s*[.!]?)$"
)


def _one_who45r(text: str, lexicon: Lexicon) -> str:
    """Session 45 (12r): a request, a cue ("whoops", "no, sorry"), maybe a reason naming nothing
    new, then "Lily's the one who wants the teddy" of the request's thing: the request to that
    person ("<request>, no, Lily")."""
    if "the one" not in text.lower():
        return text
    m = re.match(_ONE_WHO45R, text.strip(), _F)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    head = m["head"]
    things = _ids(head, lexicon, "object")
    if m["x"].lower() not in ("it", "them") and not _ids(m["x"], lexicon) <= things:
        return text
    if not things or _ids(m["why"], lexicon) - _ids(head, lexicon):
        return text
    if _ids(m["p"], lexicon) <= _ids(head, lexicon):
        return text
    node = _reading(head, lexicon)
    if node is None or isinstance(node, Group) or len(list(tasks(node))) != 1:
        return text
    return _read_or44r(f"{head}, no, {m['p']}{m['end'] or '.'}", text, lexicon)


# "Give Mr Novak the salt, sorry, I meant the other plate."
_OTHER_K45R = (
    r"\b(?:i meant|i mean|no|sorry|make (?:it|that))\s*,?\s*the other (?P<k>[a-z]+)\s*[.!]?$"
)


def other_k45r(text: str, lexicon: Lexicon) -> None:
    """Session 45 (12r): a request for one thing corrected to "I meant the other plate" when the
    request names no plate: which plate is 'the other' is not said, so the request is refused
    naming the scene's plates."""
    if "other" not in text.lower():
        return
    m = re.search(_OTHER_K45R, text.strip(), _F)
    if m is None:
        return
    k = m["k"].lower()
    kind = [o.id for o in lexicon.scene.objects if o.category in (k, k.rstrip("s"))]
    head = text.strip()[: m.start()]
    if len(kind) < 2 or _ids(head, lexicon, "object") & set(kind):
        return
    if not _ids(head, lexicon, "object"):
        return
    raise GroundingError(
        f"'the other {k}': the request names no {k} for it to be the other of; it could be "
        f"{', '.join(kind[:-1])} or {kind[-1]}: name the {k}"
    )


# -- whichever, any of, one of, both, each ---------------------------------------------------------

# "…, one apiece.", "…, one each", "…, a book each": the list before it hands each one thing
_APIECE_TAIL45R = r"\s*[,;:—-]\s*(?:one|a [a-z]+|one [a-z]+) (?:apiece|each)(?P<end>\s*[.!]?)$"


def _apiece_tail45r(text: str, lexicon: Lexicon) -> str:
    """Session 45 (12r): "the red book's for Noah and the green book's for Zoe, one apiece": the
    list, when it hands each of its people exactly one thing (what 'one apiece' says)."""
    low = text.lower()
    if "apiece" not in low and "each" not in low:
        return text
    m = re.search(_APIECE_TAIL45R, text.strip(), _F)
    if m is None:
        return text
    out = f"{text.strip()[: m.start()]}{m['end'] or '.'}"
    return out if _one_each(_reading(out, lexicon)) else text


# "Something apiece for the two speleology folk: …": the people's role said in more than one word
_FOLK45R = (
    r"^(?P<what>something|one thing|a thing|an item|one item|one) (?P<each>each|apiece) for the "
    r"(?P<n>two|three) (?:[a-z]+ ){1,2}?(?:folk|folks|people|lot|crew|ones|pair|[a-z]+s)\s*:\s*"
)


def _each_for_folk45r(text: str, lexicon: Lexicon) -> str:
    """Session 45 (12r): "Something apiece for the two speleology folk: bottle to Person A, chips
    to Person B" is "… for the two of them: …" (session 29's `_each_for29r` then asks that the list
    hands that many people one thing each)."""
    if "each" not in text.lower() and "apiece" not in text.lower():
        return text
    m = re.match(_FOLK45R, text.strip(), _F)
    if m is None:
        return text
    out = f"{m['what']} {m['each']} for the {m['n']} of them: {text.strip()[m.end() :]}"
    return out if _one_each(_reading(out, lexicon)) else text


# "…, he doesn't mind which", "…, she's not bothered which": the choice said before it
_MIND_WHICH45R = (
    r"\s*[,;]\s*(?:(?:he|she|they) (?:doesn't|does not|don't|do not) (?:mind|care) which(?: one)?|"
    r"(?:he|she|they)(?:'s| is|'re| are) not (?:bothered|fussed|fussy) which(?: one)?)"
    r"(?P<end>\s*[.!]?)$"
)


def _mind_which45r(text: str, lexicon: Lexicon) -> str:
    """Session 45 (12r): a choice closed by "he doesn't mind which" ("she's not bothered which")
    is the choice closed by "whichever", taken only when that reads as a choice of things."""
    if "which" not in text.lower():
        return text
    m = re.search(_MIND_WHICH45R, text.strip(), _F)
    if m is None:
        return text
    out = f"{text.strip()[: m.start()]}, whichever{m['end'] or '.'}"
    node = _reading(out, lexicon)
    if node is None or not has_choice(node):
        return text
    people = {t.target for t in tasks(node)}
    pro = re.search(r"\b(?:he|she)\b", m.group(0), _F)
    if pro is not None and not all(_agrees44r(p, pro.group(0), lexicon) for p in people):
        return text  # 'she' of a choice for him
    return out


# "any one of the cup, the apple or the chips": the 'or' list already says one of them
_ONE_OF_LIST45R = (
    r"\b(?:any |just |only )?one of (?P<list>(?:the [a-z]+(?: [a-z]+)?, )*the [a-z]+(?: [a-z]+)? "
    r"or the [a-z]+(?: [a-z]+)?)\b"
)


def _one_of_list45r(text: str, lexicon: Lexicon) -> str:
    """Session 45 (12r): "let him take any one of the cup, the apple or the chips" is "let him
    take the cup, the apple or the chips": each listed item one thing of the scene."""
    if "one of" not in text.lower():
        return text
    m = re.search(_ONE_OF_LIST45R, text, _F)
    if m is None:
        return text
    items = re.split(r",\s*|\s+or\s+", m["list"])
    if any(len(_ids(i, lexicon, "object")) != 1 for i in items):
        return text
    if len({next(iter(_ids(i, lexicon, "object"))) for i in items}) != len(items):
        return text
    out = f"{text[: m.start()]}{m['list']}{text[m.end() :]}"
    node = _reading(out, lexicon)
    return out if node is not None and has_choice(node) else text


def _one_of_them45r(text: str, lexicon: Lexicon) -> str:
    """Session 45 (12r): "the bottle or the chips, one of them goes to Person B" is "the bottle or
    the chips goes to Person B" (the 'or' already says one of them)."""
    if "one of" not in text.lower():
        return text
    out = re.sub(
        r"\b((?:the )?[a-z]+(?: [a-z]+)? or (?:the )?[a-z]+(?: [a-z]+)?)\s*,\s*(?:just |only )?one "
        r"of (?:them|the two|those|the pair) (?=(?:goes|go|should go|can go|is going|to)\b)",
        r"\1 ",
        text,
        flags=_F,
    )
    node = _reading(out, lexicon) if out != text else None
    return out if node is not None and has_choice(node) else text


def _go_whichever45r(text: str, lexicon: Lexicon) -> str:
    """Session 45 (12r): "Go whichever way round suits the arm, just get the bottle to Person A"
    is "Whichever way round suits the arm, …" (how the robots go about it is theirs to choose)."""
    if "way" not in text.lower():
        return text
    out = re.sub(
        r"^(?:go|do it|work it) (?=(?:whichever|any|either) way\b)", "", text.strip(), flags=_F
    )
    return _read_or44r(out[:1].upper() + out[1:], text, lexicon)


# "Whichever's nearer the arm, the bottle or the crisps, goes to Alice, …"
_WHICH_FIRST45R = (
    r"^whichever(?:'s| is) (?P<how>[^,]+?)\s*,\s*(?P<choice>[^,]+? or [^,]+?)\s*,\s*"
    r"(?P<rest>(?:goes|"
    r"go|should go|is going|can go) (?:to|on|in|into|onto) [^,.;!]+?)(?P<tail>\s*(?:[,;.!].*)?)$"
)


def _which_first45r(text: str, lexicon: Lexicon) -> str:
    """Session 45 (12r): "Whichever's nearer the arm, the bottle or the crisps, goes to Alice" is
    "The bottle or the crisps goes to Alice, whichever's nearer the arm" (said after, as read)."""
    if "whichever" not in text.lower():
        return text
    m = re.match(_WHICH_FIRST45R, text.strip(), _F)
    if m is None or _ids(m["how"], lexicon):
        return text
    choice = m["choice"][:1].upper() + m["choice"][1:]
    out = f"{choice} {m['rest']}, whichever's {m['how']}{m['tail'] or '.'}"
    node = _reading(out, lexicon)
    return out if node is not None and has_choice(node) else text


def _wants_to_do45r(text: str, lexicon: Lexicon) -> str:
    """Session 45 (12r): a closing remark "…, she just wants to chew one (it)" after a request of
    one person is dropped, the she / he that person."""
    if "wants to" not in text.lower():
        return text
    m = re.search(
        r"\s*[,;]\s*(?P<pro>she|he) (?:just |only |really )?wants to [a-z]+(?: on| with)? "
        r"(?:one|it)"
        r"(?P<end>\s*[.!]?)$",
        text.strip(),
        _F,
    )
    if m is None:
        return text
    out = f"{text.strip()[: m.start()]}{m['end'] or '.'}"
    node = _reading(out, lexicon)
    if node is None:
        return text
    people = {t.target for t in tasks(node)}
    if len(people) != 1 or not _agrees44r(next(iter(people)), m["pro"], lexicon):
        return text
    return out


def _will_do_one45r(text: str, lexicon: Lexicon) -> str:
    """Session 45 (12r): "… and either cup will do, so take her one" is "…, so take her either
    cup" (any K will do, so hand him one)."""
    if "do" not in text.lower() or "one" not in text.lower():
        return text
    out = re.sub(
        r"(?:\s*,\s*|\s+)(?:and |but )?(?P<q>either|any) (?P<k>[a-z]+)(?: at all)? "
        r"(?:will do|'ll do|"
        r"would do|is fine|works),?\s*so (?P<v>[a-z]+) (?P<pro>her|him) one\b",
        r", so \g<v> \g<pro> \g<q> \g<k>",
        text,
        flags=_F,
    )
    node = _reading(out, lexicon) if out != text else None
    return out if node is not None and has_choice(node) else text


# -- counts and plurals ----------------------------------------------------------------------------


def _whats_wanted45r(text: str, lexicon: Lexicon) -> str:
    """Session 45 (12r): "The lone apple's what Person B wants" is "The lone apple is what Person
    B wants" (the grammar's cleft), 'wants', 'needs', 'is after', 'asked for'."""
    if "'s what" not in text.lower():
        return text
    out = re.sub(
        r"^((?:the|that|this|just the|only the) [a-z]+(?: [a-z]+)?)'s what\b",
        r"\1 is what",
        text,
        flags=_F,
    )
    return _read_or44r(out, text, lexicon)


# "…, she's the one brewing up after shoeing": a remark on the person who gets it
_THE_ONE45R = r"([,;]\s*(?:she|he))(?:'s| is) the one (?:who's |who is |that's )?(?=[a-z]+ing\b)"


def _the_one45r(text: str, lexicon: Lexicon) -> str:
    """Session 45 (12r): a remark "…, she's the one brewing up after shoeing" after a request is
    "…, she's brewing up after shoeing" (read as a remark where that one is)."""
    if "the one" not in text.lower():
        return text
    return _read_or44r(re.sub(_THE_ONE45R, r"\1's ", text, flags=_F), text, lexicon)


# -- negation and exclusion ------------------------------------------------------------------------


def _no_not45r(text: str, lexicon: Lexicon) -> str:
    """Session 45 (12r): "No, not on a shelf, hand the bottle straight to Person A": a first 'no'
    (there is nothing before it that it could take back) before 'not …, <request>' is dropped."""
    if not text.lower().startswith("no"):
        return text
    out = re.sub(r"^no(?:,? no)*\s*[,!.]\s*(?=not\b)", "", text.strip(), flags=_F)
    return _read_or44r(out[:1].upper() + out[1:], text, lexicon)


# "It isn't the bottle Person A's after, it's the chips, …"
_ISNT_ITS45R = (
    r"^it (?:isn't|is not|'s not|s not|wasn't) (?P<x>(?:the|a|an) [a-z]+(?: [a-z]+)??) "
    r"(?:that |which )?(?P<p>person [a-z]|(?:mr|mrs|ms|miss|dr) [a-z]+|[a-z]+)(?P<v>'s after|"
    r"'s wanting| is after| wants| needs| asked for|'s asked for| has asked for)\s*[,;]\s*"
    r"(?:it's|it is|it was|but) (?P<y>(?:the|a|an) [a-z]+(?: [a-z]+)?)(?P<rest>\s*(?:[,;.!].*)?)$"
)


def _isnt_its45r(text: str, lexicon: Lexicon) -> str:
    """Session 45 (12r): "It isn't the X P's after, it's the Y" (wants, needs, asked for) is "Not
    the X, P's after the Y" (session 33's 'not X, Y'), when P is a person and X and Y things."""
    if "it" not in text.lower() or ("not" not in text.lower() and "n't" not in text.lower()):
        return text
    m = re.match(_ISNT_ITS45R, text.strip(), _F)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    y = m["y"]
    if y.lower().endswith(" one"):
        y = f"{y[:-4]} {m['x'].split()[-1]}"  # "it's the green one": the green <thing>
    if not _ids(m["x"], lexicon, "object") or not _ids(y, lexicon, "object"):
        return text
    out = f"Not {m['x']}, {m['p']}{m['v']} {y}{m['rest'] or '.'}"
    return _read_or44r(out, text, lexicon)


def _which_itches45r(text: str, lexicon: Lexicon) -> str:
    """Session 45 (12r): "Any blanket for Mrs Khan except the grey, which makes her itch": the
    'which' clause after the thing left out is a remark on it ("…, it makes her itch")."""
    if "which" not in text.lower():
        return text
    out = re.sub(
        r"\b((?:except|but|bar|not|apart from|other than) (?:the )?[a-z]+(?: one)?)\s*,\s*which "
        r"(?=(?:is|makes|has|gives|was|'s)\b)",
        r"\1, it ",
        text,
        flags=_F,
    )
    return _read_or44r(out, text, lexicon)


def _leave_it45r(text: str, lexicon: Lexicon) -> str:
    """Session 45 (12r): "Jess … wants the torch, so leave the hammer": the thing left is left
    alone ("…, so leave the hammer alone"), when it is not what the request hands over."""
    if "leave" not in text.lower():
        return text
    m = re.search(
        r"(?:\s*[,;]\s*(?:so |and )?|\s+(?:and|so) )leave (?P<x>the [a-z]+(?: [a-z]+)?)"
        r"(?P<end>\s*[.!]?)$",
        text.strip(),
        _F,
    )
    if m is None or len(_ids(m["x"], lexicon, "object")) != 1:
        return text
    if re.search(_TAKE_BACK45R, text.strip()[: m.start()], _F):
        return text  # "X for P, I mean Y, leave Z": which request does it go with? (session 33)
    out = f"{text.strip()[: m.start('end')]} alone{m['end'] or '.'}"
    return _read_without44r(out, text, m["x"], lexicon)


# the normaliser's rewrites run before the session-44 ones (wired into normalise._STEPS19)
_STEPS45R_FIRST: tuple[Callable[[str, Lexicon], str], ...] = (_one_of_list45r, _mind_which45r)
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-44 ones)
_STEPS45R: tuple[Callable[[str, Lexicon], str], ...] = (
    _what_he_wanted45r,
    _switch_to45r,
    _belongs_with45r,
    _better_verb45r,
    _right_first45r,
    _its_p_doing45r,
    _one_who45r,
    _apiece_tail45r,
    _each_for_folk45r,
    _one_of_them45r,
    _go_whichever45r,
    _which_first45r,
    _wants_to_do45r,
    _will_do_one45r,
    _whats_wanted45r,
    _the_one45r,
    _no_not45r,
    _isnt_its45r,
    _which_itches45r,
    _leave_it45r,
)
# refusals asked of the text before it is read (offline._parse, after the session-44 ones)
REFUSE45R: tuple[Callable[[str, Lexicon], None], ...] = (other_k45r,)
# checks of the whole instruction's reading (offline.parse_instruction, after the session-44 ones)
CHECK45R: tuple[Callable[[str, Node, Lexicon], None], ...] = ()
