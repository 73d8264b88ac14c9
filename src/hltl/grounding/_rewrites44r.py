"""The grounder's rules of session 44, engineer 12r (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _ids, _names, _reading
from hltl.grounding._rewrites39r import _not_wanted39r
from hltl.grounding._rewrites40r import _capital40r
from hltl.grounding._rewrites42r import _WHO42R, _fits42r, _person42r, _thing42r
from hltl.grounding.lexicon import PRONOUN_SEX, Lexicon, unnamed_sex44l
from hltl.grounding.tree import Node, has_choice, tasks


def _read_or44r(out: str, text: str, lexicon: Lexicon) -> str:
    """``out`` when it is a rewrite (not ``text`` again) the grounder reads, else ``text`` (each
    rule's last step; ``text`` itself is not read again: a rule asked of it would ask again)."""
    return out if out != text and _reading(out, lexicon) is not None else text


def _read_without44r(out: str, text: str, x: str, lexicon: Lexicon) -> str:
    """``out`` when the grounder reads it and hands none of what ``x`` names over, else
    ``text`` (the rules that leave X out)."""
    node = _reading(out, lexicon)
    if node is None or any(t.obj in _ids(x, lexicon) for t in tasks(node)):
        return text
    return out


# -- corrections -----------------------------------------------------------------------------------

# a cue that the request before is being taken back ("ooh wait", "no hang on", "correction",
# "oh hang about", "hang on, my mistake"), each word of it one of these
_CUE44R = (
    r"(?:ooh|oh|ah|er|erm|um|hmm|no|nope|wait|hang on|hold on|hang about|correction|my mistake|"
    r"sorry|whoops|oops|actually)"
)
# the words of a cue that take the request back (a bare 'oh' or 'hmm' may add to it)
_BACK44R = r"\b(?:wait|hang on|hold on|hang about|correction|my mistake|no|sorry)\b"
_REASON_FIX44R = (
    rf"^(?P<head>.+?)\s*(?P<sep>\.\.\.|…|[,;.!—])\s*(?P<cue>{_CUE44R}(?:\s*,?\s*{_CUE44R})*)\s*"
    r"[,;:—]\s*(?P<why>(?:[^,;.]+[,;]\s*){0,2}?)(?P<fix>[^,;.]+?)(?:\s*,\s*(?P<pro>hers|his) "
    r"then)?(?P<end>\s*[.!]?)$"
)
# the corrected request, said as what takes the place of the request's person, place or thing
_FIXES44R: tuple[str, ...] = (
    # "make it Person B"
    r"^make (?:it|that|them) (?:to |for )?(?P<r>.+)$",
    # "they're for Person B", "it's meant for Tom", "they're Tom's"
    rf"^(?:they're|they are|it's|it is|those are) (?:(?:meant |going )?(?:for|to) (?P<r>{_WHO42R})"
    rf"|(?P<r2>{_WHO42R})'s)$",
    # "Tom should have them", "Tom's having it"
    rf"^(?P<r>{_WHO42R}) (?:should (?:have|get)|gets|can have|(?:'s|is) (?:having|to have|getting)|"
    r"wants) (?:it|them|those|that|one)$",
    # "Ruth's doing the rounds so it's hers"
    rf"^(?P<r>{_WHO42R})(?:'s| is| has) [a-z ]+? so (?:it's|it is|they're|they are) "
    r"(?P<pro>hers|his)$",
    # "the sink's better"
    r"^(?P<r>(?:the )?[a-z]+)(?:'s| is| would be|'d be| will be) (?:better|best|a better (?:bet|"
    r"place|spot|idea))$",
    # "I must have meant the bottle"
    r"^i (?:must have |must've |should have |)meant (?P<r>.+)$",
)
_FIX_PRO44R = {"hers": "she", "his": "he"}


def _agrees44r(pid: str, pronoun: str, lexicon: Lexicon) -> bool:
    """Whether ``pronoun`` may be person ``pid``: as ``_fits42r`` has it, and, for a person the
    scene names only 'Person A' / 'Person B', not against the corpus's convention
    (``unnamed_sex44l``)."""
    pro = _FIX_PRO44R.get(pronoun.lower(), pronoun.lower())
    if not _fits42r(pid, pro, lexicon):
        return False
    human = next(h for h in lexicon.scene.humans if h.id == pid)
    if human.aliases:
        return True  # named otherwise than 'Person A': the convention is not what says the sex
    sex = unnamed_sex44l(pid, lexicon)
    return sex is None or sex == PRONOUN_SEX.get(pro, sex)


def _fix44r(fix: str, lexicon: Lexicon) -> str | None:
    """What the corrected request ``fix`` puts in the place of the request's person, place or
    thing, or None when it is said some other way."""
    for pat in _FIXES44R:
        m = re.match(pat, fix.strip(), _F)
        if m is None:
            continue
        said = next(w for w in (m.group("r"), m.groupdict().get("r2")) if w)
        pro = m.groupdict().get("pro")
        if pro is not None:
            pid = _person42r(said, lexicon)
            if pid is None or not _agrees44r(pid, pro, lexicon):
                return None
        if re.match(rf"{_ASKED44R}|(?:it|them|that|to|for|on|in)\b", said, _F):
            return None  # "I meant hand it to Ava": a request of its own, not a name
        return said
    return None


def _number_fits44r(fix: str, head: str, lexicon: Lexicon) -> bool:
    """Whether a 'they' / 'them' / 'those' of the corrected request ``fix`` may be the request's
    thing as ``head`` names it (a plural word: 'chips', 'tongs', 'gloves'), and an 'it' one said
    in the singular."""
    many = re.search(r"\b(?:they|they're|them|those)\b", fix, _F)
    one = re.search(r"\b(?:it|it's)\b", fix, _F)
    if not many and not one:
        return True
    said = [n.text.lower() for n in _names(head, lexicon) if n.refs and n.refs[0].kind == "object"]
    if len(said) != 1:
        return False
    plural = said[0].endswith("s")
    return bool(many) == plural or (bool(one) and plural)


def _reason_fix44r(text: str, lexicon: Lexicon) -> str:
    """Session 44 (12r): one request, a cue that takes it back ("ooh wait", "no hang on",
    "correction", "oh hang about", "hang on, my mistake"), maybe a reason that names nothing the
    request does not ("she's got one", "she's out on the pilot boat", "it's mucky", "no chips
    here"), then what takes the place of its person, place or thing ("make it P", "they're for P",
    "Q should have them", "Q's doing the rounds so it's hers", "the sink's better", "I must have
    meant the bottle, hers then"): "<request>, no, <that>" (the grammar's correction). Taken only
    when the request is one task (or names what the scene lacks) and that reads."""
    low = text.lower()
    if not any(
        w in low for w in ("wait", "hang ", "hold on", "correction", "mistake", "no", "sorry")
    ):
        return text
    m = re.match(_REASON_FIX44R, text.strip(), _F)
    if m is None or not re.search(_BACK44R, m["cue"], _F):
        return text
    head, why = m["head"], m["why"]
    said = _fix44r(m["fix"], lexicon)
    if said is None or re.search(r"\b(?:and|also|too|as well|plus|then|instead)\b", why, _F):
        return text
    if m["sep"] in (".", "!") and not re.search(
        r"\b(?:wait|hang on|hold on|hang about|correction|no)\b", m["cue"], _F
    ):
        return text  # "Chips to Alice. Sorry, …": a new sentence after a bare apology
    if _ids(said, lexicon) <= _ids(head, lexicon) or not _number_fits44r(m["fix"], head, lexicon):
        return text  # the same person again, or 'they' for one thing: not a correction of it
    if not _ids(said, lexicon) or _ids(why, lexicon) - _ids(head, lexicon):
        return text  # the reason names something the request does not: more than a reason
    first = _reading(head, lexicon)
    if first is not None and len(list(tasks(first))) != 1:
        return text  # several requests: which does it correct?
    if m["pro"] is not None:
        pids = _ids(f"{head} {said}", lexicon, "human")
        if len(pids) != 1 or not _agrees44r(next(iter(pids)), m["pro"], lexicon):
            return text  # "…, hers then": the request's one person
    out = f"{head}, no, {said}{m['end'] or '.'}"
    return _read_or44r(out, text, lexicon)


# "…, no, you know what, hand it to Person A"; "sorry, I misspoke there, to Person A"
_AFTER_CUE44R = (
    r"\b(?P<cue>no|sorry|actually|wait|hang on|hold on)\s*,\s*(?:you know what|on second thoughts?|"
    r"come to think of it|thinking about it|now i think about it)\s*[,;]\s*"
)


def _after_cue44r(text: str, lexicon: Lexicon) -> str:
    """Session 44 (12r): a correction cue followed by "you know what" ("on second thought",
    "come to think of it") is the cue alone, and "I misspoke there" is "I misspoke" (session 43's
    slip): "Put the bottle down, no, you know what, hand it to Person A" is "…, no, hand it to
    Person A"."""
    low = text.lower()
    if not any(w in low for w in ("know what", "second thought", "think", "misspoke there")):
        return text
    out = re.sub(_AFTER_CUE44R, r"\g<cue>, ", text.strip(), flags=_F)
    out = re.sub(r"\bi misspoke there\b", "I misspoke", out, flags=_F)
    if out == text.strip():
        return text
    return _read_or44r(out, text, lexicon)


# "Crisps on the shelf, I mean the bottle, the crisps stay out."
_STAYS_OUT44R = (
    r"\s*[,;]\s*(?:and )?(?P<x>(?:the )?[a-z]+(?: [a-z]+)?) (?:stays?|can stay|should stay|"
    r"remains?|are staying|is staying)(?: (?:out|put|where (?:it is|they are)|here|there|behind|"
    r"down|on the side))?(?P<end>\s*[.!]?)$"
)


def _stays_out44r(text: str, lexicon: Lexicon) -> str:
    """Session 44 (12r): a correction that puts one thing in another's place, then "the X stay
    out (put, where they are)" of the thing taken out: the correction (X then goes nowhere)."""
    if "stay" not in text.lower() and "remain" not in text.lower():
        return text
    m = re.search(_STAYS_OUT44R, text.strip(), _F)
    if m is None:
        return text
    head = text.strip()[: m.start()]
    x = _whole_thing44r(m["x"], lexicon)
    if x is None or not _ids(x, lexicon) & _ids(head, lexicon):
        return text  # X said before: what the correction took out
    if not re.search(r"\b(?:i mean|i meant|no|sorry|not|rather|instead|actually)\b", head, _F):
        return text
    out = f"{head}{m['end'] or '.'}"
    return _read_without44r(out, text, x, lexicon)


# -- negation and exclusion ------------------------------------------------------------------------

# a thing as these rules take it ("the bottle", "scissors", "the blue pen"), checked after
_THING44R = (
    r"(?:(?:the|that|this|those|these|any) )?[a-z]+(?: (?!(?:after|at|for|to|with|from|since|"
    r"because|as|on|in|so|and|or|but|is|are|was|were|be)\b)[a-z]+)?"
)


def _whole_thing44r(words: str, lexicon: Lexicon) -> str | None:
    """``words`` as "the <name>" when it names one object of the scene whole, or None."""
    said = re.sub(r"^(?:the|that|this|those|these|any) ", "", words.strip(), flags=_F)
    the = f"the {said}"
    ids = _ids(the, lexicon, "object")
    if len(ids) != 1 or _thing42r(the, None, lexicon) is None:
        return None
    return the


def _only_to44r(out: str, pid: str, left: set[str], lexicon: Lexicon) -> bool:
    """Whether ``out`` reads, every task of it for person ``pid`` and none of ``left``'s
    objects."""
    node = _reading(out, lexicon)
    if node is None:
        return False
    done = list(tasks(node))
    return bool(done) and all(t.target == pid and t.obj not in left for t in done)


def _pronoun_to44r(rest: str, who: str, pid: str, lexicon: Lexicon) -> str | None:
    """``rest`` with its one him / her said as ``who`` when it may be person ``pid`` (``rest``
    as it is when it has none), or None."""
    said = re.findall(_PRO44R, rest, _F)
    if not said:
        return rest
    if len(said) != 1 or not _agrees44r(pid, said[0], lexicon):
        return None
    return re.sub(r"\b(?:him|her)\b", who, rest, count=1, flags=_F)


# a he / she / him / her
_PRO44R = r"\b(?:him|her|he|she)\b"
# "No scissors for Noah, give him the ruler instead."
_NO_FOR44R = (
    rf"^no (?P<x>{_THING44R}) for (?P<p>{_WHO42R})\s*(?:,|;|\.|:|—)\s*(?:so |just )?"
    r"(?P<rest>[^,;.]+?)(?:,? instead)?(?P<end>\s*[.!]?)$"
)


def _no_for44r(text: str, lexicon: Lexicon) -> str:
    """Session 44 (12r): "No X for P, give him Y instead" (a thing P is not to have, then what
    P is to have) is "<give P Y>, not X": every task of it for P, the him / her P."""
    if not re.match(r"^\s*no\b", text, _F):
        return text
    m = re.match(_NO_FOR44R, text.strip(), _F)
    if m is None:
        return text
    x, pid = _whole_thing44r(m["x"], lexicon), _person42r(m["p"], lexicon)
    if x is None or pid is None:
        return text
    rest = _pronoun_to44r(m["rest"], m["p"], pid, lexicon)
    if rest is None:
        return text
    out = f"{_capital40r(rest)}, not {x}{m['end'] or '.'}"
    return out if _only_to44r(out, pid, _ids(x, lexicon), lexicon) else text


# "Person A, not the bloke from the tea picker tour, gets the bottle."
_NOT_ASIDE44R = (
    rf"^(?P<p>{_WHO42R})\s*,\s*(?:and )?not (?P<aside>[^,]+?)\s*,\s*(?P<vp>(?:gets|is getting|'s "
    r"getting|should (?:get|have)|has|can have|is having|'s having|wants|needs|is to have|'s to "
    r"have|is after|'s after) .+)$"
)


def _not_aside44r(text: str, lexicon: Lexicon) -> str:
    """Session 44 (12r): "P, not the bloke from the tour (not Q), gets X": the aside says who
    does not get it, and names no object or place of the scene, nor P: "P gets X"."""
    if ", not " not in text.lower() and ", and not " not in text.lower():
        return text
    m = re.match(_NOT_ASIDE44R, text.strip(), _F)
    if m is None:
        return text
    pid = _person42r(m["p"], lexicon)
    if pid is None or _ids(m["aside"], lexicon) - _ids(m["aside"], lexicon, "human"):
        return text
    if pid in _ids(m["aside"], lexicon) or re.search(r"\b(?:and|or|but)\b", m["aside"], _F):
        return text
    out = f"{m['p']} {m['vp']}"
    return out if _only_to44r(out, pid, set(), lexicon) else text


# "Person B said to leave the bottle, he's only after the crisps."
_SAID_LEAVE44R = (
    rf"^(?P<p>{_WHO42R}) (?:said|says|told me|has said|'s said) (?:to |we should |you should |"
    r"you can )?(?:leave|skip|forget(?: about)?|never mind|hold off on|not bother with) "
    rf"(?P<x>{_THING44R})(?P<rest>\s*[,;:]\s*.+)$"
)


def _said_leave44r(text: str, lexicon: Lexicon) -> str:
    """Session 44 (12r): "P said to leave (skip, forget) X, he's only after Y" is "P doesn't want
    X, …", as session 42's `_negated_then42r` reads it (Y for P, or X to another)."""
    if not re.search(r"\b(?:said|says|told me)\b", text, _F):
        return text
    m = re.match(_SAID_LEAVE44R, text.strip(), _F)
    if m is None:
        return text
    x, pid = _whole_thing44r(m["x"], lexicon), _person42r(m["p"], lexicon)
    if x is None or pid is None:
        return text
    if not all(_agrees44r(pid, w, lexicon) for w in re.findall(_PRO44R, m["rest"], _F)):
        return text  # 'he' after Lena: someone else
    rest = re.sub(
        r"^(\s*[,;:]\s*(?:he|she)(?:'s| is)) only after ", r"\1 after ", m["rest"], flags=_F
    )
    rest = re.sub(r"^(\s*[,;:]\s*(?:he|she)) (?:just|only) wants ", r"\1 wants ", rest, flags=_F)
    out = f"{m['p']} doesn't want {x}{rest}"
    return _read_or44r(out, text, lexicon)


# a request's verb (a remark before a request has none)
_ASKED44R = r"\b(?:give|hand|pass|bring|take|put|place|fetch|get|deliver|drop|stick|pop)\b"
# "…, so skip the bottle and give him the crisps."
_SKIP_AND44R = (
    r"^(?P<head>.*?)(?P<so>(?:^|,\s*|;\s*)(?:so |and )?)(?:skip|forget(?: about)?|leave out|never "
    rf"mind|don't bother with|hold off on|pass on) (?P<x>{_THING44R}) and (?:just )?"
    r"(?P<rest>(?:give|hand|pass|bring|take|get|fetch) [^,;.]+?)(?P<end>\s*[.!]?)$"
)


def _skip_and44r(text: str, lexicon: Lexicon) -> str:
    """Session 44 (12r): "(P's not thirsty, so) skip X and give him Y" is "<give him Y>, not X"
    after what was said before (which says who 'him' is, when the request does not)."""
    if not re.search(r"\b(?:skip|forget|leave out|never mind|bother|hold off|pass on)\b", text, _F):
        return text
    m = re.match(_SKIP_AND44R, text.strip(), _F)
    if m is None:
        return text
    x = _whole_thing44r(m["x"], lexicon)
    if x is None or _ids(x, lexicon) & _ids(m["rest"], lexicon):
        return text
    rest = f"{m['rest']}, not {x}{m['end'] or '.'}"
    head = m["head"].strip()
    out = f"{head}{m['so']}{rest}" if head else _capital40r(rest)
    said = _ids(head, lexicon)
    if (
        len(said) == 1
        and said <= _ids(head, lexicon, "human")
        and not re.search(_ASKED44R, head, _F)
    ):
        # "Bob's not thirsty after the unicycling club, so …": a remark about the one person
        # the request's him / her then is (and that only says why)
        (pid,) = said
        who = re.match(rf"^(?P<w>{_WHO42R}?)(?:'s|'|\s)", head, _F)
        named = _pronoun_to44r(rest, who["w"], pid, lexicon) if who else None
        if who is None or _person42r(who["w"], lexicon) != pid or named in (None, rest):
            return text
        out = _capital40r(named)
    return _read_without44r(out, text, x, lexicon)


# a remark before a request that says nothing is wanted or goes anywhere
_WANTS44R = (
    r"\b(?:wants?|needs?|gets?|would like|'d like|goes|go|give|hand|pass|bring|take|put|place|"
    r"fetch|deliver|asked|ordered|for (?:him|her)|is for|'s for|to have|have|having|has|had|and|"
    r"or|but|not|no)\b"
)
# "…, so he's to have the other blanket", "the other pens can go in the box"
_OTHER44R = r"\bthe other (?P<k>[a-z]+)\b"
_REMARK_THEN44R = r"^(?P<r>[^,;.]+?)\s*(?:[,;.]\s*(?:so |and so |which means )?|,? so )(?P<s>.+)$"


def _kind_of44r(word: str, lexicon: Lexicon) -> tuple[str, bool] | None:
    """The object category ``word`` says ('pens' -> ('pen', True)) and whether it is plural."""
    cats = {o.category for o in lexicon.scene.objects}
    low = word.lower()
    for k, many in ((low, False), (low[:-1], True), (low[:-2], True)):
        if k in cats and (not many or low[len(k) :] in ("s", "es")):
            return k, many
    return None


def _other_of44r(text: str, lexicon: Lexicon) -> str:
    """Session 44 (12r): a remark naming one thing of a kind that is not wanted or stays ("Sam's
    keeping the blue pen out for doodling", "Mr Lee says the grey one itches"), then a request for
    "the other K(s)": the other K is the scene's one K besides it, the other Ks all of them (two
    or more); the remark, which names no other thing and wants nothing, is dropped, and a him /
    her in the request is its one person."""
    if "other" not in text.lower():
        return text
    m = re.match(_REMARK_THEN44R, text.strip(), _F)
    if m is None:
        return text
    remark, rest = m["r"], m["s"]
    found = list(re.finditer(_OTHER44R, rest, _F))
    if len(found) != 1 or re.search(r"\bother\b", remark, _F) or re.search(_WANTS44R, remark, _F):
        return text
    kind = _kind_of44r(found[0]["k"], lexicon)
    if kind is None:
        return text
    cat, many = kind
    of_kind = [o.id for o in lexicon.scene.objects if o.category == cat]
    named = {
        o
        for o in of_kind
        if any(re.search(rf"\b{re.escape(w)}\b", remark, _F) for w in _names_of44r(o, lexicon)[:-1])
    }
    if _ids(remark, lexicon, "object") - set(of_kind):
        return text  # the remark names a thing of another kind
    if not named:
        # 'the grey one' said before the kind is
        adj = re.search(r"\bthe ([a-z]+) one\b", remark, _F)
        the = f"the {adj[1]} {cat}" if adj else ""
        named = _ids(the, lexicon, "object") if adj and _thing42r(the, None, lexicon) else set()
    if len(named) != 1 or not named <= set(of_kind):
        return text
    left = [o for o in of_kind if o not in named]
    if (many and len(left) < 2) or (not many and len(left) != 1):
        return text
    names = [f"the {next(iter(_names_of44r(o, lexicon)))}" for o in left]
    said = " and ".join(names)
    rest = f"{rest[: found[0].start()]}{said}{rest[found[0].end() :]}"
    people = _ids(remark, lexicon, "human")
    if len(people) > 1 or _ids(remark, lexicon, "surface"):
        return text
    if people:
        (pid,) = people
        who = next(w for w in _names_of44r(pid, lexicon) if w.lower() in remark.lower())
        named_rest = _pronoun_to44r(rest, who, pid, lexicon)
        if named_rest is None:
            return text
        rest = re.sub(r"^(?:he|she)(?:'s| is) to have\b", f"{who} gets", named_rest, flags=_F)
        rest = re.sub(r"^(?:he|she)\b", who, rest, flags=_F)
    out = _capital40r(rest)
    node = _reading(out, lexicon)
    if node is None or any(t.obj in named for t in tasks(node)):
        return text
    return out


def _names_of44r(eid: str, lexicon: Lexicon) -> list[str]:
    """The names the scene gives ``eid`` (an object's aliases first, as 'blue pen'; a person's
    name and aliases)."""
    for o in lexicon.scene.objects:
        if o.id == eid:
            return [*o.aliases, o.id.replace("_", " ")]
    for h in lexicon.scene.humans:
        if h.id == eid:
            return [h.name, *h.aliases]
    return []


# "…, so the crisps, leaving the bottle be."
_LEAVING44R = (
    r"^(?P<head>.+?)(?:,\s*|\s+)(?:and )?leaving (?P<x>{T}) (?:be|alone|where (?:it is|they are)|"
    r"untouched|aside|out)(?: for now)?(?P<end>\s*[.!]?)$"
).replace("{T}", _THING44R)


def _leaving44r(text: str, lexicon: Lexicon) -> str:
    """Session 44 (12r): a request, then "leaving X be (alone, where it is)", X not in it, is
    "<request>, not X" (the grammar's leaving out)."""
    if "leaving" not in text.lower():
        return text
    m = re.match(_LEAVING44R, text.strip(), _F)
    if m is None:
        return text
    x = _whole_thing44r(m["x"], lexicon)
    if x is None or _ids(x, lexicon) & _ids(m["head"], lexicon):
        return text
    out = f"{m['head']}, not {x}{m['end'] or '.'}"
    return _read_without44r(out, text, x, lexicon)


# "Any one thing apart from the bottle for Person B, he's off water after sheep shearing."
_ONE_THING_BUT44R = (
    r"\b(?P<any>any|just|only)? ?one (?:thing|item)(?= (?:apart from|except(?: for)?|but|besides|"
    r"other than|bar) )"
)
# a closing remark on what the person will not have ("he's off water after sheep shearing")
_OFF_REMARK44R = (
    r"\s*[,;]\s*(?P<pro>he|she)(?:'s| is) (?:off|not after|not keen on|allergic to|sick of|fed up "
    r"with|gone off|not bothered about|not fussed about) [^,;.!?]+(?P<end>[.!]?)$"
)


def _one_thing_but44r(text: str, lexicon: Lexicon) -> str:
    """Session 44 (12r): "(Any) one thing apart from (except, but) X for P" is "Any one of the
    things apart from X for P" (the choice the grammar reads), and a closing remark on what P will
    not have ("he's off water after sheep shearing"), naming nothing of the scene, the he / she P,
    is dropped."""
    if not re.search(r"\bone (?:thing|item)\b", text, _F):
        return text
    out = re.sub(_ONE_THING_BUT44R, "any one of the things", text.strip(), count=1, flags=_F)
    if out == text.strip():
        return text
    off = re.search(_OFF_REMARK44R, out, _F)
    if off is not None:
        people = _ids(out[: off.start()], lexicon, "human")
        said = _ids(out[off.start() :], lexicon)
        if len(people) != 1 or said - _ids(out[: off.start()], lexicon, "object"):
            return text  # the remark names what the request does not
        if not _agrees44r(next(iter(people)), off["pro"], lexicon):
            return text
        out = f"{out[: off.start()]}{off['end'] or '.'}"
    return _capital40r(out) if _reading(out, lexicon) is not None else text


# "The mugs can stay where they are; everything else goes on the table."
# a thing said before what is said of it ("the mugs can stay")
_SAID_THING44R = (
    r"(?:the|that|this|those|these) [a-z]+(?: (?!(?:can|should|will|must|are|is|stay|stays|remain|"
    r"remains|be|stop|stops|where)\b)[a-z]+)?"
)
_STAY_REST44R = (
    r"^(?:(?:leave|keep) (?P<x>{T}(?:(?:,| and) {T})*) (?:where (?:it is|they are)|as (?:it is|"
    r"they are)|put|be|alone)|(?P<x2>{T}(?:(?:,| and) {T})*) (?:can |should |will |must |are to |"
    r"is to )?(?:stay|stays|remain|remains|be left|stop|stops)(?: (?:where (?:it is|they are)|put|"
    r"as (?:it is|they are)|behind|here|there))?)\s*[;,.:]\s*(?:but |and )?(?:everything|anything|"
    r"all the rest|the rest|all the other things|the other things)(?: else)? (?P<vp>(?:goes|can go|"
    r"should go|go|is to go|gets put|moves|can move) (?:on|in|onto|into|up on|over to|across to) "
    r".+)$"
).replace("{T}", _SAID_THING44R)


def _stay_rest44r(text: str, lexicon: Lexicon) -> str:
    """Session 44 (12r): "X can stay where they are (stays put, leave X be); everything else goes
    on S" is "Everything except X goes on S" (the grammar's leaving out)."""
    if not re.search(r"\b(?:else|rest|other things)\b", text, _F):
        return text
    m = re.match(_STAY_REST44R, text.strip(), _F)
    if m is None:
        return text
    said = [w.strip() for w in re.split(r",| and ", m["x"] or m["x2"]) if w.strip()]
    if not said or not all(_ids(w, lexicon, "object") for w in said):
        return text
    if _ids(m["vp"], lexicon, "object") or _ids(m["vp"], lexicon, "human"):
        return text
    out = f"Everything except {' and '.join(w.lower() for w in said)} {m['vp']}"
    return _read_or44r(out, text, lexicon)


# "I'm fine for water thanks, it's Person A who should have the bottle."
_FINE_FOR44R = (
    r"^(?:i'm|i am|i'll be|we're|we are) (?:fine|ok|okay|alright|all right|good|sorted|set)(?: for "
    r"[a-z ]+?)?(?:,? thanks| thank you)?\s*[,;.:]\s*(?P<rest>\S.+)$"
)


def _fine_for44r(text: str, lexicon: Lexicon) -> str:
    """Session 44 (12r): the speaker saying they need nothing ("I'm fine for water thanks",
    "I'm sorted, thanks"), naming nothing of the scene, before a request: the request."""
    if not re.match(r"^\s*(?:i|we)(?:'m|'ll| am|'re| are)\b", text, _F):
        return text
    m = re.match(_FINE_FOR44R, text.strip(), _F)
    if m is None:
        return text
    said = text.strip()[: len(text.strip()) - len(m["rest"])]
    if _ids(said, lexicon) - _ids(said, lexicon, "object"):
        return text  # "I'm fine for water": a thing the speaker declines, no one and nowhere
    out = _capital40r(m["rest"])
    return _read_or44r(out, text, lexicon)


# "…; Person B had one at the tea picker stall already."
_HAD_ONE44R = (
    rf"\s*[,;.]\s*(?:and |as )?(?P<q>{_WHO42R})(?: had|'s had| has had| has already had|'s "
    r"already had| already had| got|'s got| has got) (?:one|some|his|hers|theirs|his own|her own|"
    r"one of (?:his|her) own)(?: [^,;.!?]+?)? already(?P<end>[.!]?)$"
)


def _had_one44r(text: str, lexicon: Lexicon) -> str:
    """Session 44 (12r): a request, then "Q had one (at the stall) already" of another person,
    naming nothing else of the scene: the request (why Q is not given one)."""
    if "already" not in text.lower():
        return text
    m = re.search(_HAD_ONE44R, text.strip(), _F)
    if m is None:
        return text
    qid = _person42r(m["q"], lexicon)
    head = text.strip()[: m.start()]
    said = _ids(m.group(0), lexicon)
    if qid is None or said != {qid} or qid in _ids(head, lexicon):
        return text
    out = f"{head}{m['end'] or '.'}"
    node = _reading(out, lexicon)
    if node is None or any(t.target == qid for t in tasks(node)):
        return text
    return out


# "Lily's only allowed her beaker just now, nothing else, so pass that to her."
_ONLY_ALLOWED44R = (
    rf"^(?P<p>{_WHO42R})(?:'s| is) only (?:allowed|permitted|meant to have|supposed to have)(?: to "
    r"have)? (?P<x>(?:her |his |the )?[a-z]+(?: (?!just|right|now|today|for|at)[a-z]+)?)"
    r"(?: (?:just now|right now|now|today|for now|at the moment))?(?:,? (?:and )?nothing else)?"
    r"\s*[,;]\s*so (?P<verb>pass|give|hand|bring|take) (?:that|it) (?:to|over to) "
    r"(?P<pro>him|her)(?P<end>\s*[.!]?)$"
)


def _only_allowed44r(text: str, lexicon: Lexicon) -> str:
    """Session 44 (12r): "P's only allowed (her) X (just now), nothing else, so pass that to
    her" is "Pass X to P", the her P."""
    if "only" not in text.lower():
        return text
    m = re.match(_ONLY_ALLOWED44R, text.strip(), _F)
    if m is None:
        return text
    pid = _person42r(m["p"], lexicon)
    x = _whole_thing44r(re.sub(r"^(?:her|his) ", "", m["x"], flags=_F), lexicon)
    if pid is None or x is None or not _agrees44r(pid, m["pro"], lexicon):
        return text
    if re.match(r"^(?:her|his) ", m["x"], _F) and not _agrees44r(pid, m["x"].split()[0], lexicon):
        return text
    out = f"{m['verb'].capitalize()} {x} to {m['p']}{m['end'] or '.'}"
    return _read_or44r(out, text, lexicon)


def _remark44r(words: str, lexicon: Lexicon) -> bool:
    """Whether clause ``words`` is a remark: it names nothing of the scene, asks for nothing and
    says no 'not'."""
    return not _ids(words, lexicon) and not re.search(
        rf"{_ASKED44R}|\b(?:not|no|n't|never|wants?|needs?|for (?:him|her|them))\b", words, _F
    )


# "Priya doesn't want the red pen, she's signing forms for the fete and wants the black one."
_NOT_WANT_REMARK44R = (
    rf"^(?P<head>(?P<p>{_WHO42R}) (?:doesn't|does not) want (?P<x>{_THING44R}))"
    r"(?P<rest>\s*[,;].+?)(?P<end>\s*[.!]?)$"
)


def _not_want_remark44r(text: str, lexicon: Lexicon) -> str:
    """Session 44 (12r): "P doesn't want X, <remarks that name nothing> (and|;) <what P has
    instead: 'wants the black one', 'the crisps are for her', 'take him the grey blanket', 'he's
    after the chips (after his round of …)'>" is "P doesn't want X, <that>", read by session 42's
    `_negated_then42r` (session 39's `_not_wanted39r` says 'P's not having X' so first)."""
    said = _not_wanted39r(text, lexicon)
    m = re.match(_NOT_WANT_REMARK44R, said.strip(), _F)
    if m is None:
        return text
    pid, x = _person42r(m["p"], lexicon), _whole_thing44r(m["x"], lexicon)
    if pid is None or x is None:
        return text
    parts = [w.strip() for w in re.split(r"[,;]|\band\b", m["rest"], flags=_F) if w.strip()]
    if not parts or not all(_remark44r(w, lexicon) for w in parts[:-1]):
        return text
    last = parts[-1]
    for cut in re.finditer(r"\s+(?:after|at|from|since) ", parts[-1], _F):
        if not _ids(parts[-1][cut.start() :], lexicon):
            last = parts[-1][: cut.start()]  # "… after his round of beetle drive": when
            break
    if re.match(r"^(?:wants|would like|'d like|is after|needs) ", last, _F):
        last = f"she {last}" if _agrees44r(pid, "she", lexicon) else f"he {last}"
    out = f"{m['head']}, {last}{m['end'] or '.'}"
    if " ".join(out.split()) == " ".join(said.split()):
        return text  # nothing dropped: the text as it is (and no reading of it again)
    return out if _only_to44r(out, pid, _ids(x, lexicon), lexicon) else text


# "Noah isn't allowed the scissors after what happened with the bunting, so the glue stick goes to
# him."
_NOT_ALLOWED44R = (
    rf"^(?P<p>{_WHO42R}) (?:isn't|is not|'s not) (?:allowed|permitted|meant to have|supposed to "
    rf"have)(?: to have)? (?P<x>{_THING44R})(?P<why> [^,;]+)?\s*[,;]\s*(?:so )?(?P<rest>[^,;.]+?)"
    r"(?P<end>\s*[.!]?)$"
)


def _not_allowed44r(text: str, lexicon: Lexicon) -> str:
    """Session 44 (12r): "P isn't allowed X (after what happened …), so Y goes to him (give him
    Y)" is "<that>, not X", the him / her P, every task P's."""
    if (
        "allowed" not in text.lower()
        and "meant" not in text.lower()
        and "supposed" not in text.lower()
    ):
        return text
    m = re.match(_NOT_ALLOWED44R, text.strip(), _F)
    if m is None:
        return text
    pid, x = _person42r(m["p"], lexicon), _whole_thing44r(m["x"], lexicon)
    if pid is None or x is None or (m["why"] and _ids(m["why"], lexicon)):
        return text
    rest = _pronoun_to44r(m["rest"], m["p"], pid, lexicon)
    if rest is None:
        return text
    out = f"{_capital40r(rest)}, not {x}{m['end'] or '.'}"
    return out if _only_to44r(out, pid, _ids(x, lexicon), lexicon) else text


# "Person A can have all of it bar the apple, she's gone off them since the scrumping trip."
_ALL_BAR44R = (
    rf"^(?P<p>{_WHO42R}) (?P<v>can have|gets|is having|'s having|should have) (?:all of it|the lot|"
    rf"everything|the whole lot) (?:bar|barring|save|but|except|apart from) (?P<x>{_THING44R})"
    r"(?:\s*,\s*(?P<pro>he|she)(?:'s| has) (?:gone off|gone right off|had enough of|gone "
    r"off of|gone cold on) (?:them|it|those|that)(?: [^,;.]+)?)?(?P<end>\s*[.!]?)$"
)


def _all_bar44r(text: str, lexicon: Lexicon) -> str:
    """Session 44 (12r): "P can have all of it (the lot) bar X(, she's gone off them since …)" is
    "P can have everything except X", the she P."""
    if not re.search(r"\b(?:bar|barring|save|but|except|apart)\b", text, _F):
        return text
    m = re.match(_ALL_BAR44R, text.strip(), _F)
    if m is None:
        return text
    pid, x = _person42r(m["p"], lexicon), _whole_thing44r(m["x"], lexicon)
    if pid is None or x is None or (m["pro"] and not _agrees44r(pid, m["pro"], lexicon)):
        return text
    out = f"{m['p']} {m['v']} everything except {x}{m['end'] or '.'}"
    return out if _only_to44r(out, pid, _ids(x, lexicon), lexicon) else text


# "The cup's not Person A's, it belongs to Person B, he brought it back from pond dipping."
_NOT_HERS44R = (
    rf"^(?P<x>{_THING44R})(?:'s| is|'re| are) not (?P<p>{_WHO42R})'s\s*[,;]\s*(?:it|they) "
    rf"(?:belongs? to|(?:'s|is|'re|are) for|(?:'s|is|'re|are)) (?P<q>{_WHO42R})(?:'s)?"
    r"(?:\s*[,;]\s*(?P<pro>he|she) [^,;.]+)?(?P<end>\s*[.!]?)$"
)


def _not_hers44r(text: str, lexicon: Lexicon) -> str:
    """Session 44 (12r): "X's not P's, it belongs to (it's) Q(, he brought it back from …)" is
    "Give X to Q, not P", the he Q and the remark naming nothing else."""
    if " not " not in text.lower():
        return text
    m = re.match(_NOT_HERS44R, text.strip(), _F)
    if m is None:
        return text
    pid, qid = _person42r(m["p"], lexicon), _person42r(m["q"], lexicon)
    x = _whole_thing44r(m["x"], lexicon)
    if pid is None or qid is None or pid == qid or x is None:
        return text
    tail = text.strip()[m.end("q") :]
    if m["pro"] and (not _agrees44r(qid, m["pro"], lexicon) or _ids(tail, lexicon)):
        return text
    out = f"Give {x} to {m['q']}, not {m['p']}{m['end'] or '.'}"
    return out if _only_to44r(out, qid, set(), lexicon) else text


# -- choices and distributions ---------------------------------------------------------------------

_N44R = {"one": 1, "two": 2, "three": 3, "four": 4, "five": 5, "six": 6, "both": 2, "pair": 2}


def _objects44r(lexicon: Lexicon) -> list[str]:
    """The scene's objects, each as "the <name>" (its first alias, or its id)."""
    return [f"the {_names_of44r(o.id, lexicon)[0]}" for o in lexicon.scene.objects]


# "…, either one suits her fine."
_EITHER_SUITS44R = (
    r"(?P<sep>,\s*)(?:either|any|whichever)(?: one| of them| of the two)? (?:suits|will suit|would "
    r"suit|does|will do|would do|'ll do|pleases|keeps) (?:her|him|them)(?: (?:fine|nicely|well|"
    r"just fine|happy))?(?P<end>\s*[.!]?)$"
)
# "…, red or green, no odds."
_NO_ODDS44R = (
    r"(?P<sep>,\s*)(?:(?:it )?(?:makes )?no odds|(?:it )?(?:makes|is) no (?:odds|difference)|no "
    r"matter which|(?:it )?doesn't matter(?: which)?|either's fine|"
    r"either is fine)(?P<end>\s*[.!]?)$"
)


def _either_suits44r(text: str, lexicon: Lexicon) -> str:
    """Session 44 (12r): a choice closed by "either one suits her fine" or "no odds" ("it doesn't
    matter", "either's fine") is the choice closed by "whichever"; taken only when that reads as
    a choice."""
    low = text.lower()
    if not any(
        w in low for w in ("suit", "does ", "do ", "please", "keeps", "odds", "matter", "fine")
    ):
        return text
    out = re.sub(_EITHER_SUITS44R, r"\g<sep>whichever\g<end>", text.strip(), count=1, flags=_F)
    out = re.sub(_NO_ODDS44R, r"\g<sep>whichever\g<end>", out, count=1, flags=_F)
    if out == text.strip():
        return text
    node = _reading(out, lexicon)
    return out if node is not None and has_choice(node) else text


# "Whichever of the two you grab first, get it to Alice."
_GRAB_FIRST44R = (
    r"^whichever (?:(?:one )?of (?:the|those|these) (?P<n>two|three|four|five|"
    r"six)(?: (?!you\b)(?P<k>[a-z]+))?"
    r"|one|thing) (?:you )?(?:grab|get|find|reach|pick up|lay hands on|come to|can reach)"
    r"(?: first)?\s*,\s*(?P<verb>get|give|bring|take|hand|pass|carry) (?:it|that|that one) to "
    rf"(?P<p>{_WHO42R})(?P<end>\s*[.!]?)$"
)


def _grab_first44r(text: str, lexicon: Lexicon) -> str:
    """Session 44 (12r): "Whichever of the two (things, Ks) you grab first, get it to P" is "Give
    P X or Y, whichever": the scene's objects (of kind K) when they are that many."""
    if not re.match(r"^\s*whichever\b", text, _F):
        return text
    m = re.match(_GRAB_FIRST44R, text.strip(), _F)
    if m is None or m["n"] is None or _person42r(m["p"], lexicon) is None:
        return text
    kind = (
        _kind_of44r(m["k"], lexicon)
        if m["k"] and m["k"].lower() not in ("things", "items")
        else None
    )
    if m["k"] and m["k"].lower() not in ("things", "items") and kind is None:
        return text
    objs = [
        f"the {_names_of44r(o.id, lexicon)[0]}"
        for o in lexicon.scene.objects
        if kind is None or o.category == kind[0]
    ]
    if len(objs) != _N44R[m["n"].lower()]:
        return text
    out = f"Give {m['p']} {', '.join(objs[:-1])} or {objs[-1]}, whichever{m['end'] or '.'}"
    return _read_or44r(out, text, lexicon)


# "The chips are up for grabs between Person A and Person B, so you decide who gets them."
_UP_FOR_GRABS44R = (
    rf"^(?P<x>{_THING44R})(?: is| are|'s|'re) (?:up for grabs|going spare|"
    rf"going begging) (?:between|"
    rf"for) (?P<p>{_WHO42R}) (?:and|or) (?P<q>{_WHO42R})(?:\s*,?\s*(?:so )?(?:you (?:decide|choose|"
    r"pick|can decide|can choose)|your (?:call|choice)|up to you)(?: who (?:gets|has|should have) "
    r"(?:it|them))?)?(?P<end>\s*[.!]?)$"
)


def _up_for_grabs44r(text: str, lexicon: Lexicon) -> str:
    """Session 44 (12r): "X is up for grabs between P and Q(, so you decide who gets it)" is "X
    goes to P or Q, whichever"."""
    if (
        "grabs" not in text.lower()
        and "spare" not in text.lower()
        and "begging" not in text.lower()
    ):
        return text
    m = re.match(_UP_FOR_GRABS44R, text.strip(), _F)
    if m is None:
        return text
    pid, qid = _person42r(m["p"], lexicon), _person42r(m["q"], lexicon)
    if pid is None or qid is None or pid == qid or not _ids(m["x"], lexicon, "object"):
        return text
    out = f"{_capital40r(m['x'])} go to {m['p']} or {m['q']}, whichever{m['end'] or '.'}"
    return _read_or44r(out, text, lexicon)


# "After a long day on the shuttering job Person B deserves the pair, so hand over both."
_DESERVES44R = (
    rf"^(?:after [^,]+?,? )?(?P<p>{_WHO42R}) (?:deserves|has earned|'s earned|has got to have|"
    rf"should "
    r"get) (?P<x>the pair|both(?: things| of them)?|the lot|the two(?: things)?|everything)\s*,?\s*"
    r"(?:so )?(?:hand|give|pass|bring) (?:over )?(?:both|them|the pair|the lot|them both|both of "
    r"them)(?: over)?(?: to (?:him|her))?(?P<end>\s*[.!]?)$"
)


def _deserves44r(text: str, lexicon: Lexicon) -> str:
    """Session 44 (12r): "(After a long day …) P deserves the pair (both, the lot), so hand over
    both" is "Give P <every object>", the scene's objects two for 'the pair' and 'both'."""
    if "deserve" not in text.lower() and "earned" not in text.lower():
        return text
    m = re.match(_DESERVES44R, text.strip(), _F)
    if m is None or _person42r(m["p"], lexicon) is None:
        return text
    objs = _objects44r(lexicon)
    said = m["x"].lower()
    if (said.startswith(("the pair", "both", "the two")) or "both" in text.lower()) and len(
        objs
    ) != 2:
        return text
    out = f"Give {m['p']} {', '.join(objs[:-1])} and {objs[-1]}{m['end'] or '.'}"
    return _read_or44r(out, text, lexicon)


# "Any one of them for Person A, bottle or crisps, doesn't matter."
_ANY_OF_THEM44R = (
    r"^(?:any|either)(?: one)? of (?:them|those|the two)(?: things)? (?P<to>for|to) "
    rf"(?P<p>{_WHO42R})\s*,\s*(?P<x>[a-z]+(?: [a-z]+)?) or (?P<y>[a-z]+(?: [a-z]+)?)"
    r"(?:\s*,\s*(?:(?:it )?doesn't matter(?: which)?|no matter which|either's fine|no odds|"
    r"whichever))?(?P<end>\s*[.!]?)$"
)


def _any_of_them44r(text: str, lexicon: Lexicon) -> str:
    """Session 44 (12r): "Any one of them for P, X or Y(, doesn't matter)" is "The X or the Y
    for P, whichever"."""
    if not re.match(r"^\s*(?:any|either)\b", text, _F):
        return text
    m = re.match(_ANY_OF_THEM44R, text.strip(), _F)
    if m is None or _person42r(m["p"], lexicon) is None:
        return text
    x, y = _whole_thing44r(m["x"], lexicon), _whole_thing44r(m["y"], lexicon)
    if x is None or y is None or _ids(x, lexicon) == _ids(y, lexicon):
        return text
    out = f"{_capital40r(x)} or {y} {m['to']} {m['p']}, whichever{m['end'] or '.'}"
    return _read_or44r(out, text, lexicon)


# "Either of those to Person B, he'll take what he's given, but do it now."
_EITHER_THOSE44R = (
    r"^(?:either|any|one) of (?:those|them|these|the two)(?: (?:things|two))? (?P<to>to|for) "
    rf"(?P<p>{_WHO42R})(?P<rest>(?:\s*,\s*(?:(?:but |and )?(?:do it|be quick|quick|now|sharpish|"
    r"(?:please )?do it now|right away)|(?:he|she)(?:'ll| will) (?:take|have) (?:what|whatever) "
    r"(?:he|she)(?:'s| is) given|(?:he|she)(?:'s| is)(?: not|n't) (?:fussy|bothered|fussed)))*)"
    r"(?P<end>\s*[.!]?)$"
)


def _either_those44r(text: str, lexicon: Lexicon) -> str:
    """Session 44 (12r): "Either of those to P, he'll take what he's given(, but do it now)", in a
    scene of two things, is "Either of the two things to P": what P says of the choice (the he /
    she P) and the hurry dropped."""
    if not re.match(r"^\s*(?:either|any|one) of\b", text, _F):
        return text
    m = re.match(_EITHER_THOSE44R, text.strip(), _F)
    if m is None or len(lexicon.scene.objects) != 2:
        return text
    pid = _person42r(m["p"], lexicon)
    if pid is None:
        return text
    if not all(_agrees44r(pid, w, lexicon) for w in re.findall(_PRO44R, m["rest"], _F)):
        return text
    out = f"Either of the two things {m['to']} {m['p']}{m['end'] or '.'}"
    return _read_or44r(out, text, lexicon)


# -- counts ----------------------------------------------------------------------------------------

# "There's only a lone bottle knocking about and Bob's to have it."
_LONE_GOING44R = (
    r"^there(?:'s| is) (?:only |just )?(?:a lone|a single|one|the one|a solitary|just the one|the "
    r"single) (?P<x>[a-z]+(?: (?!(?:knocking|going|about|around|left|on|here|in|to)\b)[a-z]+)?) "
    r"(?:knocking about|knocking around|going|about|around|left|on the go|here|in the room|to be "
    rf"had)\s*(?:,|;|and|, and)\s*(?P<p>{_WHO42R})(?:(?:'s| is) (?:to have it|the one to have it|"
    r"the one who gets it|having it|getting it|to get it|the one it's for|the one for it)| (?:gets|"
    r"can have|should have|should get) it)(?P<end>\s*[.!]?)$"
)


def _lone_going44r(text: str, lexicon: Lexicon) -> str:
    """Session 44 (12r): "There's only a lone (one, a single) X knocking about (going) and P's to
    have it (the one to have it)" is "The X goes to P" when the scene has one X."""
    if not re.match(r"^\s*there", text, _F):
        return text
    m = re.match(_LONE_GOING44R, text.strip(), _F)
    if m is None or _person42r(m["p"], lexicon) is None:
        return text
    x = _whole_thing44r(m["x"], lexicon)
    if x is None:
        return text
    out = f"{_capital40r(x)} goes to {m['p']}{m['end'] or '.'}"
    return _read_or44r(out, text, lexicon)


# "Out of the four, give Person B three for the ice road run: bottle, cup and apple."
_OUT_OF44R = (
    r"^(?:out of (?:the|these|those) (?P<all>two|three|four|five|six)(?: things)?\s*,\s*)?"
    rf"(?P<verb>give|hand|pass|bring|take) (?P<p>{_WHO42R}) (?P<n>two|three|four|five|six)(?: "
    r"things| items| of them| of the things)?(?: for [^:,;]+?)?\s*:\s*(?P<list>[a-z ,]+?)"
    r"(?P<end>\s*[.!]?)$"
)


def _out_of44r(text: str, lexicon: Lexicon) -> str:
    """Session 44 (12r): "(Out of the four,) give P three (for the run): X, Y and Z" is "Give P
    the X, the Y and the Z", the count the list's and the first the scene's."""
    if ":" not in text:
        return text
    m = re.match(_OUT_OF44R, text.strip(), _F)
    if m is None or _person42r(m["p"], lexicon) is None:
        return text
    if m["all"] is not None and _N44R[m["all"].lower()] != len(lexicon.scene.objects):
        return text
    said = [w.strip() for w in re.split(r",|\band\b", m["list"], flags=_F) if w.strip()]
    things = [_whole_thing44r(w, lexicon) for w in said]
    if None in things or len({t for t in things}) != _N44R[m["n"].lower()]:
        return text
    names = [t for t in things if t is not None]
    out = f"{m['verb'].capitalize()} {m['p']} {', '.join(names[:-1])} and {names[-1]}"
    out += m["end"] or "."
    return _read_or44r(out, text, lexicon)


# "Everything there is, which is two things, to Person B."
_WHICH_IS_N44R = (
    r"^(?P<all>everything(?: there is)?|all of it|the lot)\s*,\s*which (?:is|makes|comes to) "
    r"(?P<n>two|three|four|five|six)(?: things| items| in all)?\s*,\s*(?P<rest>(?:to|for|"
    r"goes to) .+)$"
)


def _which_is_n44r(text: str, lexicon: Lexicon) -> str:
    """Session 44 (12r): "Everything there is, which is two things, to P" is "Everything there
    is to P" when the scene has that many objects."""
    if "which" not in text.lower():
        return text
    m = re.match(_WHICH_IS_N44R, text.strip(), _F)
    if m is None or _N44R[m["n"].lower()] != len(lexicon.scene.objects):
        return text
    out = f"{_capital40r(m['all'])} {m['rest']}"
    return _read_or44r(out, text, lexicon)


# "A single packet of crisps is all Person A asked for before her shamisen lesson."
_IS_ALL44R = (
    r"^(?:a single|a lone|one|just one|only one|the one|a|the) (?P<x>[a-z]+(?: of [a-z]+|"
    r" [a-z]+)?) "
    rf"is all (?P<p>{_WHO42R}) (?P<v>asked for|wants|needs|is after|'s after|ordered|wanted|would "
    r"like|needed)(?: before [^,;.]+| after [^,;.]+)?(?P<end>\s*[.!]?)$"
)


def _is_all44r(text: str, lexicon: Lexicon) -> str:
    """Session 44 (12r): "A single (one) X is all P asked for (before her lesson)" is "P wants
    X" when the scene has one X."""
    if " is all " not in text.lower():
        return text
    m = re.match(_IS_ALL44R, text.strip(), _F)
    if m is None or _person42r(m["p"], lexicon) is None:
        return text
    said = re.sub(r"^(?:packet|bag|bottle|box|tin|cup|mug|bar) of ", "", m["x"], flags=_F)
    x = _whole_thing44r(said, lexicon) or _whole_thing44r(m["x"], lexicon)
    if x is None:
        return text
    out = f"{m['p']} wants {x}{m['end'] or '.'}"
    return _read_or44r(out, text, lexicon)


# -- refusals that name their readings -------------------------------------------------------------

# "The cup to Person A, no, the other thing she asked for."
_OTHER_ASKED44R = (
    r"\b(?:no|sorry|i mean|i meant|actually|wait)\s*,?\s*(?P<said>(?:the|that) other (?:thing|one|"
    r"item)(?: (?:she|he|they|you) (?:asked for|wanted|meant|ordered|said|mentioned|wants|"
    r"needs)))\b"
)


def other_asked44r(text: str, lexicon: Lexicon) -> None:
    """Session 44 (12r): a request for one thing corrected to "the other thing she asked for": the
    scene's other things are each that other thing, so the request is refused naming them."""
    if "other" not in text.lower():
        return
    m = re.search(_OTHER_ASKED44R, text, _F)
    if m is None:
        return
    named = _ids(text[: m.start()], lexicon, "object")
    if len(named) != 1:
        return
    rest = [o.id for o in lexicon.scene.objects if o.id not in named]
    if len(rest) < 2:
        return  # the one other thing: left to the grammar
    raise GroundingError(
        f"{m['said']!r}: which thing is meant is not said; it could be {', '.join(rest[:-1])} or "
        f"{rest[-1]}: name the thing"
    )


# the normaliser's rewrites run before the session-43 ones (wired into normalise._STEPS19)
_STEPS44R_FIRST: tuple[Callable[[str, Lexicon], str], ...] = (_after_cue44r,)
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-43 ones)
_STEPS44R: tuple[Callable[[str, Lexicon], str], ...] = (
    _reason_fix44r,
    _stays_out44r,
    _no_for44r,
    _not_aside44r,
    _said_leave44r,
    _skip_and44r,
    _other_of44r,
    _leaving44r,
    _one_thing_but44r,
    _stay_rest44r,
    _fine_for44r,
    _had_one44r,
    _only_allowed44r,
    _not_want_remark44r,
    _not_allowed44r,
    _all_bar44r,
    _not_hers44r,
    _either_suits44r,
    _grab_first44r,
    _up_for_grabs44r,
    _deserves44r,
    _any_of_them44r,
    _either_those44r,
    _lone_going44r,
    _out_of44r,
    _which_is_n44r,
    _is_all44r,
)
# refusals asked of the text before it is read (offline._parse, after the session-43 ones)
REFUSE44R: tuple[Callable[[str, Lexicon], None], ...] = (other_asked44r,)
# checks of the whole instruction's reading (offline.parse_instruction, after the session-43 ones)
CHECK44R: tuple[Callable[[str, Node, Lexicon], None], ...] = ()
