"""The normaliser's rewrites of session 39, engineer 12r (docs/grounding.md)."""

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
    _only_kind,
    _only_person,
    _reading,
    _said,
)
from hltl.grounding._normalise3 import _whole_name
from hltl.grounding._normalise4 import _ISNT_HERS36R, _may_be35t, _objects34r
from hltl.grounding.lexicon import Lexicon
from hltl.grounding.phrasing import starting_on
from hltl.grounding.tree import Node, Task, tasks

# -- negation and exclusion frames ----------------------------------------------------------------


def _one_of39r(words: str, rest: str, lexicon: Lexicon) -> str | None:
    """``words`` as one whole name of objects: itself when it is one, or "the <adj> one" said
    of the kind of an object ``rest`` names ("the blue one … take him the grey blanket": the blue
    blanket), when exactly one kind so named has an object of that adjective; else None."""
    words = words.strip()
    if _whole_name(words, lexicon, "object"):
        return words
    m = re.fullmatch(r"the (?P<adj>[a-z]+) one", words, _F)
    if m is None:
        return None
    named = _ids(rest, lexicon, "object")
    kinds = {o.category for o in lexicon.scene.objects if o.id in named}
    said = [f"the {m['adj']} {k}" for k in sorted(kinds)]
    fit = [w for w in said if _only(w, lexicon, "object")]
    return fit[0] if len(fit) == 1 else None


# "Priya's not having the red pen", "Noah isn't allowed the scissors", "Kofi's not after the drill"
_NOT_HAVING39R = re.compile(
    r"(?:^|(?<=[.;!?]\s))(?P<who>[A-Za-z][\w ]*?)(?:(?:'s| is) (?:not|never)| isn't) "
    r"(?:having|allowed|after|getting|to have|to get) (?P<what>the [a-z]+(?: [a-z]+)?)(?=\s*[,;])",
    _F,
)
# "The blue one's no good for Mr Lee", "the red pen is no use to Sam", "X won't do for P"
_NO_GOOD39R = re.compile(
    r"(?:^|(?<=[.;!?]\s))(?P<what>the [a-z]+(?: [a-z]+)?)(?:(?:'s| is) (?:no good|no use|not "
    r"(?:any )?good|not any use|not right|not suitable)|(?: won't| will not) do) (?:for|to) "
    r"(?P<who>[A-Za-z][\w ]*?)(?=\s*[,;])",
    _F,
)


def _not_wanted39r(text: str, lexicon: Lexicon) -> str:
    """Session 39 (12r): a person's not having something said other ways than "P doesn't want
    X": "P's not having X", "P isn't allowed X", "P's not after X", "P isn't getting X", and the
    thing first, "X's no good / no use for P", "X won't do for P", are "P doesn't want X" (one
    person, an object named whole, or "the <adj> one" of a kind the rest of the sentence names),
    which the grammar reads as before: dropped beside a request that names neither it nor 'it',
    else refused as a negation."""
    low = text.lower()
    if "not " not in low and "n't " not in low and " no " not in low:
        return text

    def having(m: re.Match[str]) -> str:
        what = _one_of39r(m["what"], text[m.end() :], lexicon)
        if what is None or not _only_person(m["who"], lexicon):
            return m[0]
        return f"{m['who']} doesn't want {what}"

    out = _NOT_HAVING39R.sub(having, text)

    def no_good(m: re.Match[str]) -> str:
        what = _one_of39r(m["what"], out[m.end() :], lexicon)
        if what is None or not _only_person(m["who"], lexicon):
            return m[0]
        return f"{m['who']} doesn't want {what}"

    return _NO_GOOD39R.sub(no_good, out)


# "The cup's not Person A's, it belongs to Person B", "The mug isn't Bob's, it's Carol's"
_OWNER39R = re.compile(
    r"^(?P<what>the [a-z]+(?: [a-z]+)?)(?:'s not| is not| isn't) (?P<p>[A-Za-z][\w ]*?)'s\s*[,;]\s*"
    r"(?:it|that)(?: belongs to (?P<q>[A-Za-z][\w ]*?)|(?:'s| is) (?P<q2>[A-Za-z][\w ]*?)'s)"
    r"(?P<end>\s*(?:[,.;!]|$))",
    _F,
)
# "It's not Person B who wants the bottle, it's Person A."
_CLEFT39R = re.compile(
    r"^it(?:'s not| is not| isn't) (?P<p>[A-Za-z][\w ]*?) (?:who|that)(?: wants| needs| asked for|"
    r" is after|'s after) (?P<what>the [a-z]+(?: [a-z]+)?),\s*it(?:'s| is) (?P<q>[A-Za-z][\w ]*?)"
    r"(?P<end>\s*(?:[,.;!]|$))",
    _F,
)


def _owner39r(text: str, lexicon: Lexicon) -> str:
    """Session 39 (12r): who a thing is for said as a contrast of two people: "X's not P's, it
    belongs to Q" / "…, it's Q's" is "X isn't for P, it's for Q" (as session 36's
    `_isnt_hers36r` reads "X isn't P's, it's Q's"; session 29's `_not_for_but29s` then reads
    it), and the cleft "It's not P who wants X, it's Q" is "P doesn't want X, Q does" (P and Q
    two people, each named whole, X an object: the contrast says who gets it; "X is Q's" said
    alone stays refused, as it may only say whose it is)."""
    if "'s" not in text and " is" not in text.lower():
        return text
    m = _OWNER39R.match(text)
    # "X isn't P's, it's Q's (, take it to her)" is session 36's (`_isnt_hers36r`)
    if m is not None and _ISNT_HERS36R.match(text) is None:
        q = m["q"] or m["q2"]
        if _whole_name(m["what"], lexicon, "object") and _two39r(m["p"], q, lexicon):
            return f"{m['what']} isn't for {m['p']}, it's for {q}{m['end']}{text[m.end() :]}"
    m = _CLEFT39R.match(text)
    if (
        m is not None
        and _whole_name(m["what"], lexicon, "object")
        and _two39r(m["p"], m["q"], lexicon)
    ):
        return f"{m['p']} doesn't want {m['what']}, {m['q']} does{m['end']}{text[m.end() :]}"
    return text


def _two39r(p: str, q: str, lexicon: Lexicon) -> bool:
    """Whether ``p`` and ``q`` each name one person, two people."""
    return (
        _only_person(p, lexicon)
        and _only_person(q, lexicon)
        and _ids(p, lexicon) != _ids(q, lexicon)
    )


# "…; leave the red one where it is", "…, and leave the stapler alone"
_LEAVE39R = re.compile(
    r"(?:\s*[,;]\s*(?:and |but |just )?|\s+and )(?:leave (?P<left>the [a-z]+(?: [a-z]+)?) "
    r"(?P<how>where (?:it is|they are)|alone|be|as (?:it|they) (?:is|are))|(?:don't|do not) "
    r"(?:touch|move) (?P<what>the [a-z]+(?: [a-z]+)?))(?P<end>\s*[.!]?)$",
    _F,
)


def _left_be39r(text: str, lexicon: Lexicon) -> str:
    """Session 39 (12r): "…; leave the red one where it is" (or alone, be; "don't touch / move
    X") after a request says what is NOT to be moved: no task, taken off, when what it names
    (an object named whole, or "the <adj> one" of a kind the request names) is another object
    than any the request names, and the request is one sentence with no correction in it; else
    left (and refused). A bare "leave X" stays refused (session 31: it may say where to leave
    it)."""
    if "leave" not in text.lower() and "touch" not in text.lower() and "move" not in text.lower():
        return text
    m = _LEAVE39R.search(text)
    if m is None or m.start() == 0:
        return text
    head = text[: m.start()]
    if m["how"] in ("be", "alone") and _whole_name(m["left"], lexicon, "object"):
        return text  # "…, and leave the bottle be": session 35's `_leave_be35r`
    if re.search(
        r"[.!?]|\b(?:no|hang on|hold on|wait|sorry|actually|i mean|instead|rather)\b", head, _F
    ):
        return text  # a correction before it: what is left may be what it takes back (session 34)
    what = _one_of39r(m["left"] or m["what"], head, lexicon)
    if what is None:
        return text
    left = _ids(what, lexicon, "object")
    named = _ids(head, lexicon, "object")
    if not named or left & named or re.search(r"\b(?:it|them|everything|all|rest)\b", head, _F):
        return text
    return f"{head}{m['end'] or '.'}"


# "Don't hang on to the bottle, give it to Person A."
_HANG_ON39R = re.compile(
    r"^(?:(?:no|so) )?(?:don't|do not|no need to) (?:hang on to|hang onto|hold on to|hold onto|"
    r"keep|hang on to|sit on) (?P<what>the [a-z]+(?: [a-z]+)?)\s*[,;]\s*(?:just )?"
    r"(?P<req>(?:give|hand|pass|bring|take|put|place|pop|stick|set) .+)$",
    _F,
)


def _hang_on39r(text: str, lexicon: Lexicon) -> str:
    """Session 39 (12r): "Don't hang on to X, give it to P" (hold on to, keep, sit on) says
    only not to keep X: the request after it, with its one 'it' read as X (an object named
    whole), is what to do."""
    m = _HANG_ON39R.match(text.strip())
    if m is None or not _whole_name(m["what"], lexicon, "object"):
        return text
    its = re.findall(r"\b(?:it|them|that|this)\b", m["req"], _F)
    if its != ["it"] and its != ["It"]:
        return text
    req = re.sub(r"\bit\b", m["what"], m["req"], count=1, flags=_F)
    return req[0].upper() + req[1:]


# -- choice idioms ---------------------------------------------------------------------------------

# "Person B can make do with the cup or the bottle", "Alice is happy with either the bottle or …"
_MAKE_DO39R = re.compile(
    r"(?:^|(?<=[.;!?,]\s))(?P<who>[A-Za-z][\w ]*?)(?: (?:can|could|will|would)|'ll|'d)? make do "
    r"with (?=the |a |an |either |any |whichever )",
    _F,
)
_HAPPY_WITH39R = re.compile(
    r"(?:^|(?<=[.;!?,]\s))(?P<who>[A-Za-z][\w ]*?)(?:'s| is|'d be| would be|'ll be| will be) "
    r"(?:quite |perfectly |just )?(?:happy|fine|content|okay|ok|all right) with "
    r"(?P<what>(?:either |any |whichever )?(?:the |a |an )?[^,;.!?]*?)(?=\s*(?:[,;.!?]|$)| "
    r"(?:after|before|while|since|as|because|for)\b)",
    _F,
)


def _make_do39r(text: str, lexicon: Lexicon) -> str:
    """Session 39 (12r): the want idioms of a choice, "P can make do with X (or Y)" and "P is
    happy / fine / content with either X or Y" (a choice said: 'either', 'any', 'whichever' or
    'or'; "Alice is happy with the bottle" alone may say she has what she wants, and stays), are
    "P can have …" (P one person, named whole)."""
    low = text.lower()
    if "make do" not in low and " with " not in low:
        return text

    def make_do(m: re.Match[str]) -> str:
        return f"{m['who']} can have " if _only_person(m["who"], lexicon) else m[0]

    out = _MAKE_DO39R.sub(make_do, text)

    def happy(m: re.Match[str]) -> str:
        if not _only_person(m["who"], lexicon):
            return m[0]
        if not re.search(r"^(?:either|any|whichever)\b|\bor\b", m["what"], _F):
            return m[0]
        return f"{m['who']} can have {m['what']}"

    return _HAPPY_WITH39R.sub(happy, out)


# ", hand her whichever", ", she'll take whichever's closest to hand"
_WHICHEVER_AGAIN39R = re.compile(
    r",\s*(?:(?:just )?(?:give|hand|pass|bring|take) (?P<obj>him|her)|(?P<subj>he|she)(?:'ll| "
    r"will| can| would|'d)? (?:take|have|want|like|go for)) (?P<rest>whichever\b[^,;.!?]*)"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _whichever_again39r(text: str, lexicon: Lexicon) -> str:
    """Session 39 (12r): a choice said again after it is offered, "P can have X or Y, hand her
    whichever" / "…, she'll take whichever's closest to hand", is "…, whichever (…)": the
    pronoun the one person the request names and may be (title, first name), a choice ('or',
    'either', 'any') before it."""
    if "whichever" not in text.lower():
        return text
    m = _WHICHEVER_AGAIN39R.search(text)
    if m is None:
        return text
    head = text[: m.start()]
    if not re.search(r"\b(?:or|either|any)\b", head, _F):
        return text
    who = _ids(head, lexicon, "human")
    pronoun = m["obj"] or m["subj"]
    if len(who) != 1 or not _may_be35t(next(iter(who)), pronoun, lexicon):
        return text
    out = f"{head}, {m['rest']}{m['end']}"
    # the choice before it must read as it is said ("P won't mind if it's X or Y, …" is read by
    # session 36's `_mind_if36r`, with its pronoun, after this rule)
    return out if _reading(out, lexicon) is not None else text


def whichever_again_says39r(text: str, node: Node, _lexicon: Lexicon) -> None:
    """Session 39 (12r): "Lena can have either plate, pass her whichever" had read as both plates
    to Lena (the grammar took 'whichever' for one more of the choice, handed over as well): a
    choice said again after it is offered gives nothing more. Where the grammar's reading hands one
    person two things together, it is refused here, so the rewrites read it as "…, whichever"
    (`_whichever_again39r`, where the pronoun may be the one person named); a reading of one thing
    ("…, just bring him whichever's closer": the bottle or the chips) stands."""
    if "whichever" not in text.lower():
        return
    m = _WHICHEVER_AGAIN39R.search(text)
    if m is None or not re.search(r"\b(?:or|either|any)\b", text[: m.start()], _F):
        return
    if _two_together39r(node):
        raise GroundingError(f"{m[0].strip(' ,')!r} says the choice again: say 'whichever' alone")


def _two_together39r(node: Node) -> bool:
    """Whether ``node`` hands one person two things together (in an 'and' or a sequence)."""
    if isinstance(node, Task):
        return False
    if node.op != "or":
        said = [t for t in tasks(node) if t.kind == "deliver"]
        for t in said:
            if any(u.target == t.target and u.obj != t.obj for u in said):
                return True
    return any(_two_together39r(child) for child in node.children)


# "The chips can go to whichever of the two you like, Person A or Person B"
_WHICHEVER_OF39R = re.compile(
    r"\bwhichever (?:of the two|of them|of those|of the pair|one)(?: (?:you|u) (?:like|want|fancy|"
    r"prefer|choose)| suits(?: you)?)?,\s*(?P<a>(?:the )?[A-Za-z][\w ]*?) or (?P<b>(?:the )?"
    r"[A-Za-z][\w ]*?)(?=\s*(?:[,;.!?]|$))",
    _F,
)


def _whichever_of39r(text: str, lexicon: Lexicon) -> str:
    """Session 39 (12r): "whichever of the two you like, A or B" (of them, one; you want, you
    fancy) is "A or B": the two it chooses between said after it, each one whole name of one
    person, or each of one object, two others."""
    if "whichever" not in text.lower():
        return text

    def two(m: re.Match[str]) -> str:
        a, b = m["a"], m["b"]
        if _two39r(a, b, lexicon) or (
            _whole_name(a, lexicon, "object")
            and _whole_name(b, lexicon, "object")
            and not _ids(a, lexicon) & _ids(b, lexicon)
        ):
            return f"{a} or {b}"
        return m[0]

    return _WHICHEVER_OF39R.sub(two, text)


# "any pen as long as it's not the one on the desk", "any plate but the one on the rack"
_ANY_BUT39R = re.compile(
    r"\bany (?P<k>[a-z]+),?\s*(?:(?:as|so) long as it(?:'s not| is not| isn't)|provided "
    r"it(?:'s not| is not| isn't)|that(?:'s not| is not| isn't)|but|except|other than|apart from) "
    r"(?P<x>the (?:one|[a-z]+)) (?P<on>on|in|at|by) (?P<s>the [a-z]+(?: [a-z]+)?)"
    r"(?=\s*(?:[,;.!?]|$))",
    _F,
)
# "as long as it's not the red one": the object left out named
_ANY_BUT_NAMED39R = re.compile(
    r"\bany (?P<k>[a-z]+),?\s*(?:(?:as|so) long as it(?:'s not| is not| isn't)|provided "
    r"it(?:'s not| is not| isn't)) (?P<x>the [a-z]+(?: [a-z]+)?)(?=\s*(?:[,;.!?]|$))",
    _F,
)


def _any_but39r(text: str, lexicon: Lexicon) -> str:
    """Session 39 (12r): a choice of any of a kind but one said by where it is or with a
    condition: "any pen as long as it's not the one on the desk" (but, except, other than, that
    isn't the one in / on S) is "any pen except the blue pen" (the one object of that kind
    standing on the surface named, said by a name of its own; none or several: left, and
    refused), and "any pen as long as it's not the red one" is "any pen except the red one"."""
    low = text.lower()
    if "any " not in low:
        return text

    def placed(m: re.Match[str]) -> str:
        k = m["k"]
        if not _only_kind(k, lexicon, "object") or not _only(m["s"], lexicon, "surface"):
            return m[0]
        if m["x"].lower() != "the one" and _ids(m["x"], lexicon, "object") != _ids(
            k, lexicon, "object"
        ):
            return m[0]
        (surface,) = _ids(m["s"], lexicon, "surface")
        there = starting_on(_ids(k, lexicon, "object"), surface, lexicon)
        if len(there) != 1:
            return m[0]
        return f"any {k} except the {_said(there[0], lexicon)}"

    out = _ANY_BUT39R.sub(placed, text)

    def named(m: re.Match[str]) -> str:
        if not _only_kind(m["k"], lexicon, "object"):
            return m[0]
        return f"any {m['k']} except {m['x']}"

    return _ANY_BUT_NAMED39R.sub(named, out)


# "Bob wants something, but not the crisps."
_SOMETHING_BUT39R = re.compile(
    r"\b(?:something|a thing|one thing)\s*,?\s*(?:but not|just not|only not|as long as it's not|"
    r"so long as it's not) (?=the [a-z]+(?: [a-z]+)?\s*(?:[,;.!?]|$))",
    _F,
)


def _something_but39r(text: str, _lexicon: Lexicon) -> str:
    """Session 39 (12r): "P wants something, but not X" is "P wants anything but X" (one thing,
    any of the scene's but X: the grammar's reading of 'anything but', a choice)."""
    if "thing" not in text.lower():
        return text
    return _SOMETHING_BUT39R.sub("anything but ", text)


# "Whichever student's nearer can have the book."
_WHICHEVER_WHO39R = re.compile(
    r"^whichever (?P<role>[a-z]+(?: [a-z]+)?)(?:'s| is) (?:nearer|closer|nearest|closest|free|"
    r"handier|quicker|about|around|nearby|free first)(?: to (?:you|hand))? (?P<v>can have|gets|"
    r"should get|can take|should have|wants)\b",
    _F,
)


def _whichever_who39r(text: str, lexicon: Lexicon) -> str:
    """Session 39 (12r): "Whichever student's nearer can have the book" (closer, free) leaves
    the choice of person to the robot, as "whichever's nearer" does of objects: "Noah or Zoe can
    have the book", the people the role names (two or more, people only), each by a name of
    their own; what they may have is then read (or refused: "the book" of two) as before."""
    m = _WHICHEVER_WHO39R.match(text.strip())
    if m is None or not _only_kind(m["role"], lexicon, "human"):
        return text
    who = sorted(_ids(m["role"], lexicon, "human"))
    if len(who) < 2:
        return text
    names = [_own_name39r(h, lexicon) for h in who]
    if None in names:
        return text
    said = ", ".join(str(n) for n in names[:-1]) + f" or {names[-1]}"
    return f"{said} {m['v']}{text.strip()[m.end() :]}"


def _own_name39r(pid: str, lexicon: Lexicon) -> str | None:
    """A name of person ``pid`` that names no one else, or None."""
    h = next(x for x in lexicon.scene.humans if x.id == pid)
    for name in (*h.aliases, h.name):
        if _only_person(name, lexicon) and _ids(name, lexicon) == {pid}:
            return name
    return None


# -- distributions and counts ----------------------------------------------------------------------

# "They each get a bite before the show: Person A the apple, Person B the chips", "One apiece for
# the pair of them: …"
_EACH_HEADER39R = re.compile(
    r"^(?:(?:they|the two of them|the pair of them|both of them|you two) (?:each |both )?"
    r"(?:get|gets|have|can have|are having) (?:one each|one apiece|(?:a|an|one) "
    r"(?P<noun>[a-z]+)(?: each)?)|one (?:each|apiece)(?: for (?:the (?:pair|two) of them|both of "
    r"them|them both|the pair|the two))?)(?P<adj>(?: (?:before|after|for|at|from) [^:,;]+?)?)"
    r"\s*:\s*(?P<list>\S.*)$",
    _F,
)


def _each_header39r(text: str, lexicon: Lexicon) -> str:
    """Session 39 (12r): a share-out said before its list, "They each get a bite (before the
    show): P the X, Q the Y", "One apiece for the pair of them: …", is "One each: P the X, Q the
    Y" (the grammar's reading of the list, one thing each): the header's noun and what follows
    it name nothing of the scene ("a bite", "a treat"); "They each get the apple: …" stays."""
    m = _EACH_HEADER39R.match(text.strip())
    if m is None:
        return text
    if m["noun"] is not None and (_names(m["noun"], lexicon) or m["noun"].lower() in _SAID39R):
        return text
    if m["adj"] and _names(m["adj"], lexicon):
        return text
    return f"One each: {m['list']}"


# words that are not things in a share-out's header ("they each get one"); "each" is its own
_SAID39R = frozenset({"other", "lot", "rest", "few", "couple", "pair"})

# "One bottle, just the one, for Person A", "One tray for Tom, only the one"
_JUST_THE_ONE39R = re.compile(
    r"^(?P<head>(?:one|a|an|a single) [a-z]+(?: [a-z]+)?)\s*,\s*(?:just|only) the one\s*"
    r"(?:,\s*|(?=[.!]?$))",
    _F,
)


def _just_the_one39r(text: str, lexicon: Lexicon) -> str:
    """Session 39 (12r): "One X, just the one, for P" (only the one) says the count of one
    again: taken off, when X names objects of the scene ("One bottle for P", as before)."""
    m = _JUST_THE_ONE39R.match(text.strip())
    if m is None:
        return text
    x = re.sub(r"^(?:one|a|an|a single) ", "", m["head"], flags=_F)
    if not _ids(x, lexicon, "object") or not _only_kind(x, lexicon, "object"):
        return text
    rest = text.strip()[m.end() :]
    return f"{m['head']} {rest}" if rest else f"{m['head']}."


# ", that's all she asked for": what the person wants, said again as all of it
_ALL_ASKED39R = re.compile(
    r",\s*that(?:'s| is) all (?P<who>he|she|they)(?: asked for| ordered| wanted| needed| requested|"
    r" is after|'s after| was after)(?P<end>\s*[.!]?)$",
    _F,
)


def _all_asked39r(text: str, lexicon: Lexicon) -> str:
    """Session 39 (12r): ", that's all she asked for" (ordered, wanted, is after) closing a
    request to one person the pronoun may be is ", that's all she wants", which the grammar reads
    as before (nothing more to do)."""
    if "all" not in text.lower():
        return text
    m = _ALL_ASKED39R.search(text)
    if m is None:
        return text
    who = _ids(text[: m.start()], lexicon, "human")
    if m["who"].lower() != "they" and (
        len(who) != 1 or not _may_be35t(next(iter(who)), m["who"], lexicon)
    ):
        return text
    return f"{text[: m.start()]}, that's all {m['who']} wants{m['end']}"


# "Alice is taking both things to the fete, so that's the bottle and the crisps to her."
_THAT_IS_TO39R = re.compile(
    r"^(?:(?P<p>[A-Za-z][\w ]*?) is (?:taking|getting|having|after|bringing) (?P<n>both|the two|"
    r"two|all three|three|all four|four) (?:things|items|bits)(?P<adj>(?: [^,;]+?)?)\s*,\s*"
    r"(?:so |and )?|(?:so |right,? |okay,? |ok,? )?)that(?:'s| is) "
    r"(?P<list>the [a-z]+(?: [a-z]+)?(?:,? (?:and )?the [a-z]+(?: [a-z]+)?)*) (?:to|for) "
    r"(?P<who>[A-Za-z][\w ]*?)(?P<end>\s*[.!]?)$",
    _F,
)
_COUNT39R = {"both": 2, "the two": 2, "two": 2, "all three": 3, "three": 3, "all four": 4}
_COUNT39R["four"] = 4


def _that_is_to39r(text: str, lexicon: Lexicon) -> str:
    """Session 39 (12r): a hand-out summed up, "(so) that's the bottle and the crisps to Alice",
    is "the bottle and the crisps to Alice" (each object named whole, one person); said after
    "P is taking both things (to …)", its pronoun P (may be: title, first name), the count the
    objects listed (both: two), and what the things are taken to names nothing of the scene."""
    if "that" not in text.lower():
        return text
    m = _THAT_IS_TO39R.match(text.strip())
    if m is None:
        return text
    said = [w for w in re.split(r",?\s+and\s+|,\s*", m["list"]) if w.strip()]
    if not _objects34r(lexicon, *said):
        return text
    who = m["who"]
    if m["p"] is not None:
        if not _only_person(m["p"], lexicon) or _COUNT39R[m["n"].lower()] != len(said):
            return text
        if m["adj"] and _names(m["adj"], lexicon):
            return text
        if who.lower() in ("her", "him"):
            pronoun = "she" if who.lower() == "her" else "he"
            if not _may_be35t(next(iter(_ids(m["p"], lexicon))), pronoun, lexicon):
                return text
            who = m["p"]
        elif _ids(who, lexicon) != _ids(m["p"], lexicon):
            return text
    if not _only_person(who, lexicon):
        return text
    return f"{m['list'][0].upper()}{m['list'][1:]} to {who}{m['end'] or '.'}"


# "…: the bottle, the cup and the apple, all to her."
_ALL_TO39R = re.compile(
    r"(?P<list>\bthe [a-z]+(?: [a-z]+)?(?:,\s*the [a-z]+(?: [a-z]+)?)*,? and the [a-z]+"
    r"(?: [a-z]+)?),\s*all (?:of them |of it |three |four |both )?(?:to|for) (?P<who>her|him)"
    r"(?P<end>\s*[.!]?)$",
    _F,
)
# "Person A's picnic (for the rally) wants three things": what is P's wants what P wants
_OWNED_WANTS39R = re.compile(
    r"^(?P<p>[A-Za-z][\w ]*?)'s (?P<noun>[a-z]+(?: [a-z]+)?)(?P<adj>(?: (?:for|at) [^:,;]+?)?) "
    r"(?P<v>wants|needs|could use|could do with) (?=[a-z]+ things\s*:)",
    _F,
)


def _all_to39r(text: str, lexicon: Lexicon) -> str:
    """Session 39 (12r): "P wants three things: A, B and C, all to her" says again who gets the
    list: ", all to her" is taken off when her is the one person the sentence names (may be:
    title, first name); and "P's picnic (for …) wants three things: …" (a thing of P's, naming
    nothing of the scene, wanting a counted list) is "P wants three things: …"."""
    if ", all " not in text.lower():
        return text
    m = _ALL_TO39R.search(text)
    if m is None:
        return text
    head = text[: m.start("list")]
    who = _ids(head, lexicon, "human")
    pronoun = "she" if m["who"].lower() == "her" else "he"
    if len(who) != 1 or not _may_be35t(next(iter(who)), pronoun, lexicon):
        return text
    out = f"{head}{m['list']}{m['end'] or '.'}"
    o = _OWNED_WANTS39R.match(out)
    if (
        o is not None
        and _only_person(o["p"], lexicon)
        and not _names(o["noun"] + o["adj"], lexicon)
    ):
        out = f"{o['p']} {o['v']} {out[o.end() :]}"
    return out


# "Stand both of the blocks up on the high chair"
_STAND39R = re.compile(
    r"^(?P<pre>(?:please |just |now )?)stand (?P<x>[^,;.!?]+?)(?: up(?:right)?)? (?P<on>on|onto|in|"
    r"into) (?P<s>the [a-z]+(?: [a-z]+)?)(?=\s*(?:[,;.!?]|$)| so\b)",
    _F,
)


def _stand39r(text: str, lexicon: Lexicon) -> str:
    """Session 39 (12r): "Stand X (up) on S", said to set things upright on a surface, is "Put X
    on S" (X naming objects only, S one surface)."""
    m = _STAND39R.match(text)
    if m is None or not _objects_only(m["x"], lexicon) or not _only(m["s"], lexicon, "surface"):
        return text
    return f"{m['pre']}Put {m['x']} {m['on']} {m['s']}{text[m.end() :]}"


_STEPS39R: tuple[Callable[[str, Lexicon], str], ...] = (
    _not_wanted39r,
    _owner39r,
    _left_be39r,
    _hang_on39r,
    _make_do39r,
    _whichever_again39r,
    _whichever_of39r,
    _each_header39r,
    _just_the_one39r,
    _all_asked39r,
    _any_but39r,
    _something_but39r,
    _that_is_to39r,
    _all_to39r,
    _stand39r,
    _whichever_who39r,
)
"""Ahead of the offline grammar: what it refuses, rewritten as plain requests and read again."""
