"""The grounder's rules of session 53, engineer 12r (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _ids, _reading
from hltl.grounding._rewrites44r import _agrees44r
from hltl.grounding._rewrites46r import _P46R, _person46r
from hltl.grounding._rewrites50l import forgets50l
from hltl.grounding._rewrites51r import _BACK51R, _CUE51R, _one_task51r
from hltl.grounding._rewrites52r import _put_pair52r
from hltl.grounding._rewrites52s import _HELD52S
from hltl.grounding.lexicon import Lexicon, person_name
from hltl.grounding.tree import Group, Node, Task, has_choice, tasks

# -- 12c's fuzz: a share-out header the list does not meet --------------------------------------

_COUNTS53R = {"two": 2, "three": 3, "four": 4, "five": 5, "2": 2, "3": 3, "4": 4, "5": 5}

# "Give each of them something: the crisps for Alice, the apple for Alice.": a header saying every
# person of a group gets one thing, then the list
_EACH_HEAD53R = re.compiled(
    r"^\s*(?:please,?\s+)?(?:give|hand|pass|bring|get)\s+(?P<who>each of them|them each|each of "
    r"you|them all|all of them|everyone|everybody|each person|both of them|them both|the two of "
    r"them|all (?P<n>two|three|four|five|2|3|4|5) of them|the (?P<m>two|three|four|five) of them)"
    r"\s+(?:something|some thing|one thing|a thing|an? item|one item|an object|one|one apiece|"
    r"a (?:drink|snack|treat|bite))\b[^:;.!?]*:",
    _F,
)


def _shares53r(node: Node) -> list[str] | None:
    """The person of each share of a reading that is one handover to each person, or a choice of
    things for one person ("(chips>A | apple>A) & cup>B": A, B), else None."""
    shares = node.children if isinstance(node, Group) and node.op == "and" else (node,)
    who = []
    for share in shares:
        if isinstance(share, Group) and (
            share.op != "or" or not all(isinstance(c, Task) for c in share.children)
        ):
            return None
        got = list(tasks(share))
        if any(t.kind != "deliver" for t in got) or len({t.target for t in got}) != 1:
            return None
        who.append(got[0].target)
    return who


def _each_head53r(text: str, node: Node, lexicon: Lexicon) -> None:
    """Session 53 (12r): a reading of "Give each of them (all three of them, everyone) something:
    <list>" must give one thing to each of two or more people, all three (every person of the
    scene for 'everyone', 'all of them'), no one twice and no choice: an early rewrite (session
    10's table) took the header off unchecked, so "…: the crisps for Alice, the apple for Alice."
    read chips>A & apple>A (12c's fuzz)."""
    low = text.lower()
    if ":" not in low or ("them" not in low and "every" not in low and "each" not in low):
        return
    m = _EACH_HEAD53R.match(text)
    if m is None:
        return
    who = _shares53r(node)
    want = None
    n = m["n"] or m["m"]
    if n is not None:
        want = _COUNTS53R[n.lower()]
    elif m["who"].lower() in ("both of them", "them both", "the two of them"):
        want = 2
    fits = who is not None and len(set(who)) == len(who) >= 2 and (want is None or len(who) == want)
    if (
        who is not None
        and fits
        and m["who"].lower() in ("everyone", "everybody", "all of them", "them all")
    ):
        fits = sorted(who) == sorted(h.id for h in lexicon.scene.humans)
    if not fits:
        raise GroundingError(
            f"{m.group(0).strip(' :')!r} gives one thing to each of them, but the list after it "
            "does not (someone twice, one person only, or someone left out): name who gets each "
            "thing"
        )


# -- blind51: corrections ------------------------------------------------------------------------

# the first correction cue after a request: ", oh hang on, ", ", hmm, no, "
_FIRST_CUE53R = re.compiled(rf",\s*(?P<cue>{_CUE51R})", _F)


def _head53r(text: str) -> tuple[str, str] | None:
    """The request before the first correction cue of ``text`` and what follows the cue, or
    None."""
    for m in _FIRST_CUE53R.finditer(text):
        if _BACK51R.search(m["cue"]):
            return text[: m.start()].strip(), text[m.end() :]
    return None


def _tasks53r(text: str, lexicon: Lexicon) -> list[Task] | None:
    """The tasks ``text`` reads as (no choice), or None."""
    node = _reading(text, lexicon)
    if node is None or has_choice(node):
        return None
    return list(tasks(node))


def _held53r(words: str) -> bool:
    """Whether ``words`` say what someone has, had or wanted once ("Bob has …", "Alice had …",
    "Lily's got …"; session 52's list of past holdings): a rewrite of this session's is not taken
    there (12c's variants)."""
    return _HELD52S.search(words) is not None


# "Take the bottle to Alice, oh hang on, it's Bob who wants it, not Alice."
_NOT_FIRST53R = re.compiled(
    rf"\s*,\s*(?:and )?not (?:to |for )?(?P<p>{_P46R})(?: at all| this time)?(?P<end>\s*[.!]?)$",
    _F,
)


def _not_first53r(text: str, lexicon: Lexicon) -> str:
    """Session 53 (12r): a handover to P, a correction to Q, then ", not P" (the person corrected
    away named again) is the correction alone: read only when the head hands one thing to P and
    what is left hands the same thing to another person."""
    if "not " not in text.lower():
        return text
    m = _NOT_FIRST53R.search(text)
    cut = None if m is None else _head53r(text[: m.start()])
    if m is None or cut is None:
        return text
    p = _person46r(m["p"], lexicon)
    first = None if _held53r(cut[0]) else _one_task51r(f"{cut[0]}.", lexicon)
    if p is None or first is None or first[0] != "deliver" or first[2] != p:
        return text
    out = f"{text[: m.start()]}{m['end'] or '.'}"
    got = _one_task51r(out, lexicon)
    if got is None or got[:2] != first[:2] or got[2] == p:
        return text
    return out


# "Cup to Person B, hmm, no, not the cup, make it the chips for him.": the thing corrected, its
# person said again
_FIX_FOR53R = re.compiled(
    r"(?:,\s*|\bmake it )(?P<x>(?:the|a|an) [a-z]+(?: [a-z]+)?) for (?P<p>him|her|[a-z]+"
    r"(?: [a-z]+)?)(?P<end>\s*[.!]?)$",
    _F,
)


def _fix_for53r(text: str, lexicon: Lexicon) -> str:
    """Session 53 (12r): a correction of the last handover's thing, "…, no, (make it) the chips
    for him" (for Person B), where 'him' may be that handover's person and no other person the
    request names (or the same person is named): "…, no, (make it) the chips" (the grammar's
    correction of the thing). Read only as the request with the last thing swapped."""
    if " for " not in text.lower():
        return text
    m = _FIX_FOR53R.search(text)
    cut = None if m is None else _head53r(text[: m.start("x")])
    if m is None or cut is None or _ids(m["x"], lexicon, "human") or _held53r(cut[0]):
        return text
    first = _tasks53r(f"{cut[0]}.", lexicon)
    if not first or first[-1].kind != "deliver":
        return text
    last = first[-1].target
    said = m["p"].lower()
    if said in ("him", "her"):
        others = {t.target for t in first} | _ids(cut[0], lexicon, "human")
        if not _agrees44r(last, said, lexicon) or any(
            _agrees44r(o, said, lexicon) for o in others - {last}
        ):
            return text
    elif _person46r(m["p"], lexicon) != last or len(first) < 2:
        return text  # one handover with its person named again: the older rules read it
    out = f"{text[: m.end('x')]}{m['end'] or '.'}"
    got = _tasks53r(out, lexicon)
    x = _ids(m["x"], lexicon, "object")
    if got is None or len(x) != 1 or len(got) != len(first):
        return text
    want = [*first[:-1], Task("deliver", next(iter(x)), last)]
    return out if got == want and x != {first[-1].obj} else text


# "Take Person A the bottle, sorry, I said chips before, it's the bottle.": the request said
# again after owning an earlier slip
_SAID_BEFORE53R = re.compiled(
    r"^(?P<head>[^,;]+?)\s*,\s*(?P<cue>(?:oh |ah |er |um )?(?:sorry|my mistake|my bad|oops|"
    r"whoops|apologies)\s*,?\s*)(?:i (?:said|told you|asked for|put|wrote|gave you) (?P<y>(?:the "
    r")?[a-z]+(?: [a-z]+)?) (?:before|earlier|just now|a minute ago|first|by mistake|last time)"
    r")\s*[,;]\s*(?:but )?it(?:'s| is| was) (?:definitely |really |actually )?(?P<x>(?:the )?"
    r"[a-z]+(?: [a-z]+)?)(?P<end>\s*[.!]?)$",
    _F,
)


def _said_before53r(text: str, lexicon: Lexicon) -> str:
    """Session 53 (12r): "<request for X>, sorry, I said Y before, it's (definitely) X": the
    speaker owns an earlier slip and says the request's own thing again: the request (read only
    when X names the one thing the request hands over or places, and Y another thing)."""
    low = text.lower()
    if " said " not in low and " told " not in low and " asked " not in low and "wrote" not in low:
        return text
    m = _SAID_BEFORE53R.match(text.strip())
    if m is None or _held53r(m["head"]):
        return text
    first = _one_task51r(f"{m['head']}.", lexicon)
    x, y = _ids(m["x"], lexicon), _ids(m["y"], lexicon)
    if first is None or x != {first[1]} or x & y or _ids(m["y"], lexicon, "human"):
        return text
    if _ids(m["x"], lexicon, "object") != x or len(y) > 1 or m["y"] != m["y"].lower():
        return text
    return f"{m['head']}{m['end'] or '.'}"


# "…, oh wait, my mistake, it's actually Person B.": 'actually' inside the correction
_ITS_ACTUALLY53R = re.compiled(
    r"(?P<its>\bit(?:'s| is| was)) (?:actually|really|in fact|in actual fact)\s+(?=\S)",
    _F,
)


def _its_actually53r(text: str, lexicon: Lexicon) -> str:
    """Session 53 (12r): "…, <cue>, it's actually Person B" (really, in fact) is "…, it's Person
    B": the correction as the older rules read it. Taken only after a correction cue, and read
    only as one task whose person or thing differs from the request's."""
    low = text.lower()
    if "actually" not in low and "really" not in low and "in fact" not in low:
        return text
    cut = _head53r(text)
    if cut is None or _held53r(cut[0]):
        return text
    m = _ITS_ACTUALLY53R.search(text, len(text) - len(cut[1]))
    if m is None:
        return text
    first = _one_task51r(f"{cut[0]}.", lexicon)
    out = f"{text[: m.start()]}{m['its']} {text[m.end() :]}"
    got = _one_task51r(out, lexicon)
    if first is None or got is None or got == first or got[0] != first[0]:
        return text
    if got[1] != first[1] and got[2] != first[2]:
        return text  # both the thing and its person changed: not one correction
    return out


# "…, oops, sorry, it's Lily's, she's the one who's thirsty.": why, said of the one person
_ONE_WHO_IS53R = re.compiled(
    rf"(?P<own>[,;]\s*(?:it's |it is |they're |they are )?(?P<o>{_P46R})'s\s*,\s*)"
    rf"(?P<w>\b(?:he|she|{_P46R}))(?:'s| is) the one (?:who's|who is|that's|that is) "
    r"(?P<adj>thirsty|hungry|peckish|parched|starving|famished|cold|freezing|chilly|poorly|"
    r"sleepy|tired|bored|teething|upset|grumpy)(?P<end>\s*[.!]?)$",
    _F,
)


def _one_who_is53r(text: str, lexicon: Lexicon) -> str:
    """Session 53 (12r): a request or its correction closed by "she's the one who's thirsty"
    (hungry, cold, …) is closed by "she's thirsty": why, said of a person (the older rules take
    such a remark off, the pronoun checked as for any remark)."""
    if "the one" not in text.lower():
        return text
    m = _ONE_WHO_IS53R.search(text)
    if m is None or m.start() == 0:
        return text
    o = _person46r(m["o"], lexicon)
    w = m["w"].lower()
    if o is None or (w in ("he", "she") and not _agrees44r(o, w, lexicon)):
        return text
    if w not in ("he", "she") and _person46r(m["w"], lexicon) != o:
        return text
    return f"{text[: m.end('own')]}{m['w']}'s {m['adj']}{m['end'] or '.'}"


# "…, no, actually, I've changed my mind, it's the bottle that goes up there."
_GOES_THERE53R = re.compiled(
    r"\bit(?:'s| is) (?P<x>the [a-z]+(?: [a-z]+)?) (?:that|which) (?:goes|should go|needs to go|"
    r"wants to go|belongs|has to go|is going)(?: up| down| over| back)? (?:there|on it|in it)"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _goes_there53r(text: str, lexicon: Lexicon) -> str:
    """Session 53 (12r): a placing, a correction cue, then "it's the bottle that goes (up)
    there" is "<placing>, no, the bottle": another thing on the same surface (read only so)."""
    if "there" not in text.lower() and " it" not in text.lower():
        return text
    m = _GOES_THERE53R.search(text)
    cut = None if m is None else _head53r(text[: m.start()])
    if m is None or cut is None or _held53r(cut[0]):
        return text
    first = _one_task51r(f"{cut[0]}.", lexicon)
    if first is None or first[0] != "place":
        return text
    out = f"{text[: m.start()]}{m['x']}{m['end'] or '.'}"
    got = _one_task51r(out, lexicon)
    if got is None or got[0] != "place" or got[2] != first[2] or got[1] == first[1]:
        return text
    return out


# "Torch onto the workbench, actually, rethink, lock it away in the locker instead, it walks off
# otherwise."
_RETHINK53R = re.compiled(
    r"(?P<cue>,\s*(?:actually|no|sorry|wait|hang on|hold on|oh)\b\s*,?\s*)(?:rethink|re-think|"
    r"on reflection|on second thoughts?|second thoughts?|thinking again|thinking about it|come to "
    r"think of it|scratch that|change of plan)\s*,\s*",
    _F,
)
# "…, it walks off otherwise": why the correction, naming nothing of the scene
_OTHERWISE53R = re.compiled(
    r"\s*,\s*(?:(?:it|they|that|someone|somebody|people)\b[a-z' ]*? otherwise|otherwise "
    r"[a-z' ]+)(?P<end>\s*[.!]?)$",
    _F,
)
_INSTEAD53R = re.compiled(r"\s+instead(?=\s*(?:[,.!]|$))", _F)


def _rethink53r(text: str, lexicon: Lexicon) -> str:
    """Session 53 (12r): a placing corrected by "…, actually, rethink, lock it away in the locker
    instead, it walks off otherwise": the afterthought word after the cue ("rethink", "on
    reflection", "second thoughts"), 'instead' and a closing "…, it walks off otherwise" (why,
    naming nothing of the scene) are taken off, leaving the correction the older rules read
    ("…, actually, lock it away in the locker"). Read only as the same thing placed elsewhere."""
    low = text.lower()
    if not any(w in low for w in ("think", "reflection", "second thought", "scratch that", "plan")):
        return text
    m = _RETHINK53R.search(text)
    if m is None:
        return text
    head = text[: m.start()]
    out = f"{head}{m['cue']}{text[m.end() :]}"
    why = _OTHERWISE53R.search(out)
    if why is not None:
        if (
            _ids(why.group(0), lexicon)
            or _held53r(why.group(0))
            or _WHY_HELD53R.search(why.group(0).replace("otherwise", ""))
        ):
            return text
        out = f"{out[: why.start()]}{why['end'] or '.'}"
    out = _INSTEAD53R.sub("", out)
    first = None if _held53r(head) else _one_task51r(f"{head.strip()}.", lexicon)
    got = _one_task51r(out, lexicon)
    if first is None or got is None or first[0] != "place" or got[0] != "place":
        return text
    return out if got[1] == first[1] and got[2] != first[2] else text


# -- blind51: whichever, either, any of ----------------------------------------------------------

_NEAR53R = (
    r"(?:closer|nearer|nearest|closest|handier|handiest|easier to reach|easiest to reach|to hand|"
    r"within reach|in reach|easier to get at|nearer to you|closer to you|nearest to you|closest to "
    r"you)"
)
# "Give Person A whichever of the bottle and the cup is closer."
_WHICHEVER_OF53R = re.compiled(
    r"\bwhichever of (?P<x>the [a-z]+(?: [a-z]+)?) (?:and|or) (?P<y>the [a-z]+(?: [a-z]+)?) "
    rf"(?:is|'s) (?P<q>{_NEAR53R})(?P<end>\s*[.!]?)$",
    _F,
)


def _whichever_of53r(text: str, lexicon: Lexicon) -> str:
    """Session 53 (12r): "Give P whichever of the X and the Y is closer" (handier, to hand) at the
    end of the request is "Give P the X or the Y, whichever is closer" (read so only as the
    choice of those two things, for one person or one surface)."""
    if "whichever of" not in text.lower():
        return text
    m = _WHICHEVER_OF53R.search(text)
    if m is None or _held53r(text[: m.start()]):
        return text
    x, y = _ids(m["x"], lexicon, "object"), _ids(m["y"], lexicon, "object")
    if len(x) != 1 or len(y) != 1 or x == y or _ids(m["x"] + " " + m["y"], lexicon, "human"):
        return text
    out = f"{text[: m.start()]}{m['x']} or {m['y']}, whichever is {m['q']}{m['end'] or '.'}"
    node = _reading(out, lexicon)
    got = [] if node is None else list(tasks(node))
    if node is None or not has_choice(node) or {t.obj for t in got} != x | y:
        return text
    return out if len({t.target for t in got}) == 1 and len(got) == 2 else text


# "Take Person A the bottle, either hand's fine.": how the robot holds it, not a choice of things
_EITHER_HAND53R = re.compiled(
    r"\s*,\s*(?:(?:either|any|whichever|one or (?:both|two)) hands?(?:'s| is| will do| works)?"
    r"(?: (?:fine|ok|okay|good|alright|all right|grand))?(?: by me| with me)?|with either hand|"
    r"(?:one|two)[- ]handed(?: or (?:one|two)[- ]handed)?(?:,? (?:doesn't|does not) matter)?)"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _either_hand53r(text: str, lexicon: Lexicon) -> str:
    """Session 53 (12r): a request closed by "either hand's fine" (with either hand, whichever
    hand) says how the robot may hold it: taken off where the scene has no hand among its
    things and what is left reads."""
    if "hand" not in text.lower():
        return text
    m = _EITHER_HAND53R.search(text)
    if m is None or m.start() == 0 or _ids(m.group(0), lexicon) or _held53r(text[: m.start()]):
        return text
    out = f"{text[: m.start()]}{m['end'] or '.'}"
    return out if _reading(out, lexicon) is not None else text


# "Whichever route you take round the desks, the bottle …": the way there, not the request
_ROUTE53R = re.compiled(
    r"^(?:whichever|whatever|which ?ever|however|any) (?:route|way|path) you (?:take|go|choose|"
    r"pick|fancy)(?: (?:round|around|through|across|past|over|via|between) [a-z' ]+?)?\s*,\s*"
    r"|^however you (?:get there|go|do it|manage it)\s*,\s*",
    _F,
)
# "the bottle should finish up in Person A's hands" (session 28's `_in_hand28r` leaves "finish
# up to Person A")
_FINISH_UP53R = re.compiled(
    r"\b(?P<v>should|must|needs to|has to|is to|can) (?:finish|wind|end) up (?:(?:to|with) "
    rf"(?P<p>{_P46R})|in (?P<q>{_P46R})'s (?:hands?|grasp|mitts))(?P<end>\s*[.!]?)$",
    _F,
)


def _route53r(text: str, lexicon: Lexicon) -> str:
    """Session 53 (12r): an opener "Whichever route you take (round the desks)," (whatever way
    you go, however you get there) leaves how to go there to the robot: taken off where it names
    nothing of the scene; and "X should finish up with P" (in P's hands) is "X should go to P".
    Read only as handovers or placings."""
    low = text.lower()
    if not any(w in low for w in ("route", " way ", "path", "however", " up ")):
        return text
    out = text
    m = _ROUTE53R.match(out.strip())
    if m is not None and not _ids(m.group(0), lexicon):
        rest = out.strip()[m.end() :]
        out = rest[:1].upper() + rest[1:]
    f = _FINISH_UP53R.search(out)
    who = None if f is None else f["p"] or f["q"]
    if f is not None and who is not None and _person46r(who, lexicon) is not None:
        out = f"{out[: f.start()]}{f['v']} go to {who}{f['end'] or '.'}"
    if out == text or _held53r(text):
        return text
    node = _reading(out, lexicon)
    return out if node is not None and list(tasks(node)) else text


# "either of the mugs will suit him fine", "any of the four things will do him"
_WILL_SUIT53R = re.compiled(
    r"\b(?P<which>(?:either|any|any one|one|either one) of (?:the|those|these) [a-z]+(?: [a-z]+)?)"
    r" (?:will|would|'ll|should) (?:suit|do|be (?:fine|ok|okay|good|alright) for|be fine by|"
    r"please|keep) (?P<p>him|her|them)(?: (?:fine|just fine|nicely|perfectly|well|down to the "
    r"ground))?(?P<end>\s*[.!]?)$",
    _F,
)


def _will_suit53r(text: str, lexicon: Lexicon) -> str:
    """Session 53 (12r): "either of the mugs will suit him (fine)" (will do him, be fine for
    her) is "either of the mugs for him": the choice left to the robot, the pronoun resolved by
    the grammar as for "… for him"; read only as a choice for one person."""
    low = text.lower()
    if not any(
        w in low for w in ("suit", " do ", "fine", "please", "keep", " ok", " good", "alright")
    ):
        return text
    m = _WILL_SUIT53R.search(text)
    if m is None or _held53r(text[: m.start()]):
        return text
    before = _ids(text[: m.start()], lexicon, "human")
    if m["p"].lower() != "them" and (
        len(before) != 1 or not _agrees44r(next(iter(before)), m["p"], lexicon)
    ):
        return text  # "Bob's not bothered, either of the mugs will suit her": who is she?
    if m["p"].lower() == "them":
        return text
    out = f"{text[: m.start()]}{m['which']} for {m['p']}{m['end'] or '.'}"
    node = _reading(out, lexicon)
    got = [] if node is None else list(tasks(node))
    if node is None or not has_choice(node) or len({t.target for t in got}) != 1:
        return text
    return out if all(t.kind == "deliver" for t in got) else text


# "Person B says any of the four things will do, he's honestly not fussed which one turns up."
_SAYS_ANY53R = re.compiled(
    rf"^(?P<p>{_P46R}) (?:says|said|reckons|tells me) (?P<which>(?:any|either) (?:one )?of the "
    r"[a-z]+(?: [a-z]+)?) (?:will do|would do|is fine|are fine|will be fine)\s*,\s*(?P<pro>he|she)"
    r"(?:'s| is) (?:honestly |really |genuinely |truly )?(?:not|n't) (?:fussed|bothered|fussy|"
    r"picky) (?:which|what)(?: one| ones)?(?: "
    r"(?:turns up|arrives|comes|he gets|she gets|it is|it's))?(?P<end>\s*[.!]?)$",
    _F,
)


def _says_any53r(text: str, lexicon: Lexicon) -> str:
    """Session 53 (12r): "P says any of the four things will do, he's not fussed which one turns
    up" is "Any of the four things will do for P, he's not fussed which" (the want reported as
    the older rules read "P says …"; the pronoun must fit P)."""
    low = text.lower()
    if not any(w in low for w in ("says", "said", "reckons", "tells me")):
        return text
    m = _SAYS_ANY53R.match(text.strip())
    if m is None:
        return text
    p = _person46r(m["p"], lexicon)
    if p is None or not _agrees44r(p, m["pro"], lexicon):
        return text
    w = m["which"]
    out = f"{w[:1].upper()}{w[1:]} will do for {m['p']}, {m['pro']}'s not fussed which"
    out += m["end"] or "."
    node = _reading(out, lexicon)
    got = [] if node is None else list(tasks(node))
    if node is None or not has_choice(node) or {t.target for t in got} != {p}:
        return text
    return out


# -- blind51: counts and plurals -----------------------------------------------------------------

# "Bob wants the two things on offer.": where the things are, said of all of them
_ON_OFFER53R = re.compiled(
    r"\b(?P<x>(?:the (?:two|three|four|five) |both |all (?:the )?|all (?:two|three|four|five) "
    r"(?:of the )?)?things) (?:on offer|going|available|about|around|lying about|"
    r"lying around|we've got|we have|here|there|in here|out there|up for grabs)(?P<end>\s*[.!]?)$",
    _F,
)


def _on_offer53r(text: str, lexicon: Lexicon) -> str:
    """Session 53 (12r): "Bob wants the two things on offer" (going, up for grabs, we've got)
    says where the things are: "Bob wants the two things" (the count checked by the grammar);
    read only as handovers to one person."""
    low = text.lower()
    if "thing" not in low:
        return text
    m = _ON_OFFER53R.search(text)
    if m is None or m.start() == 0 or _held53r(text[: m.start()]):
        return text
    out = f"{text[: m.end('x')]}{m['end'] or '.'}"
    node = _reading(out, lexicon)
    got = [] if node is None else list(tasks(node))
    if node is None or has_choice(node) or len(got) < 2 or len({t.target for t in got}) != 1:
        return text
    return out if all(t.kind == "deliver" for t in got) else text


# "let him have the two things he can drink out of, that's the cup plus the bottle"
_CAN_DRINK53R = re.compiled(
    r"\bthe (?P<n>pair of|two|couple of|three) things (?:he|she|they|you|one) (?:can|could) "
    r"(?P<v>drink (?:out of|from)|eat|snack on|write with|cut with)(?=\s*,)",
    _F,
)
_CAN_DESC53R = {
    "drink out of": "drinking",
    "drink from": "drinking",
    "eat": "snacky",
    "snack on": "snacky",
    "write with": "writing",
    "cut with": "cutting",
}


def _can_drink53r(text: str, lexicon: Lexicon) -> str:
    """Session 53 (12r): "the two things he can drink out of, that's the cup plus the bottle"
    (can eat, write with, cut with) is session 52's "the pair of drinking things, that's …",
    whose rule checks the things named against the description by their categories."""
    if "things" not in text.lower() or (" can" not in text.lower() and "could" not in text.lower()):
        return text
    m = _CAN_DRINK53R.search(text)
    if m is None or _held53r(text[: m.start()]):
        return text
    desc = _CAN_DESC53R[" ".join(m["v"].lower().split())]
    n = m["n"].lower().replace(" of", "")
    out = f"{text[: m.start()]}the {n} {desc} things{text[m.end() :]}"
    node = _reading(out, lexicon)
    if node is None or has_choice(node) or len(list(tasks(node))) < 2:
        return text
    return out


# "Person A's asking for a bottle, only the one, she won't need more."
_NEED_MORE53R = re.compiled(
    r"(?P<one>\b(?:only|just) (?:the )?one)\s*,\s*(?:and )?(?:he|she|they) (?:won't|will not|"
    r"doesn't|does not|don't|do not|shan't) (?:need|want|be needing|be wanting) (?:more|any more|"
    r"another|a second|two|extra|any extra)(?: than that)?(?P<end>\s*[.!]?)$",
    _F,
)


def _need_more53r(text: str, lexicon: Lexicon) -> str:
    """Session 53 (12r): "…, only the one, she won't need more" says the count again: "…, only
    the one" (read only as one handover)."""
    if "one" not in text.lower():
        return text
    m = _NEED_MORE53R.search(text)
    if m is None or _held53r(text[: m.start()]):
        return text
    out = f"{text[: m.end('one')]}{m['end'] or '.'}"
    node = _reading(out, lexicon)
    got = [] if node is None else list(tasks(node))
    return out if node is not None and len(got) == 1 and not has_choice(node) else text


# "The green cup and the white cup have had their lot, stick the pair of them in the sink."
_HAD_LOT53R = re.compiled(
    r"^(?P<things>(?:the )?[a-z]+(?: [a-z]+)? and (?:the )?[a-z]+(?: [a-z]+)?) (?:have had their "
    r"(?:lot|day|turn|use)|have been used|are (?:done|finished)(?: with)?|have done their job)"
    r"\s*[,;]\s*(?:so\s+)?(?:put|pop|stick|place|set|pile) (?:the pair(?: of them)?|the two(?: of "
    r"them)?|them(?: both)?|both(?: of them)?|the both of them)\s+(?P<where>(?:in|on|into|onto) "
    r"the [a-z]+)(?P<end>\s*[.!]?)$",
    _F,
)


def _had_lot53r(text: str, lexicon: Lexicon) -> str:
    """Session 53 (12r): "X and Y have had their lot (are done with), stick the pair of them in
    the sink" is "Put X and Y in the sink" (as session 52's "X and Y are both dirty, …"): read
    only as two placings of the two things named."""
    low = text.lower()
    if " and " not in low or not any(w in low for w in ("had their", "used", "done", "finished")):
        return text
    m = _HAD_LOT53R.match(text.strip())
    if m is None:
        return text
    put = _put_pair52r(m, lexicon)
    if put is None:
        return text
    things = m["things"][:1].lower() + m["things"][1:]
    return put[0] if _ids(things, lexicon, "object") == put[1] else text


# "The plates, both of them, want setting out on the worktop for the specials."
_BOTH_OF_THEM53R = re.compiled(
    r"^(?:the )?(?P<x>[a-z]+s)\s*,\s*(?P<n>both|all (?:two|three|four|five)|the (?:two|three|four"
    r"|five)) of them\s*,\s*(?P<rest>(?:want|need)s? (?:setting|putting|laying|popping|"
    r"sticking|moving|placing)\b.+)$",
    _F,
)


def _both_of_them53r(text: str, lexicon: Lexicon) -> str:
    """Session 53 (12r): "The plates, both of them, want setting out on …" (all three of them) is
    "Both plates want setting out on …" (the count said before the noun, where the grammar checks
    it against the scene); read only as placings of things of that kind."""
    if "of them" not in text.lower():
        return text
    m = _BOTH_OF_THEM53R.match(text.strip())
    if m is None:
        return text
    n = m["n"].lower()
    count = "Both" if n == "both" else "All " + n.split()[-1]
    out = f"{count} {m['x']} {m['rest']}"
    node = _reading(out, lexicon)
    got = [] if node is None else list(tasks(node))
    if node is None or has_choice(node) or len(got) < 2 or any(t.kind != "place" for t in got):
        return text
    return out if _ids(m["x"], lexicon, "object") == {t.obj for t in got} else text


# "Lily can have the pair of blocks, the red as well as the green."
_AS_WELL_AS53R = re.compiled(
    r"(?P<head>\b(?:the pair of|both(?: the)?|the two|both of the) (?P<k>[a-z]+)s\s*,\s*the "
    r"(?P<x>[a-z]+)(?: one)?) (?:as well as|along with|together with|plus) (?P<y>the (?P<b>[a-z]+)"
    r"(?: one)?)(?P<end>\s*[.!]?)$",
    _F,
)


def _as_well_as53r(text: str, lexicon: Lexicon) -> str:
    """Session 53 (12r): "the pair of blocks, the red as well as the green" (along with, plus)
    lists the two: "…, the red and the green" (read only as the two things of the kind)."""
    low = text.lower()
    if not any(w in low for w in ("as well as", "along with", "together with", " plus ")):
        return text
    m = _AS_WELL_AS53R.search(text)
    if m is None or _held53r(text[: m.start()]):
        return text
    x = _ids(f"the {m['x']} {m['k']}", lexicon, "object")
    y = _ids(f"the {m['b']} {m['k']}", lexicon, "object")
    if len(x) != 1 or len(y) != 1 or x == y:
        return text  # "the red as well as the red": not the two of the kind
    out = f"{text[: m.end('head')]} and {m['y']}{m['end'] or '.'}"
    node = _reading(out, lexicon)
    got = [] if node is None else list(tasks(node))
    if node is None or has_choice(node) or len(got) != 2:
        return text
    return out if {t.obj for t in got} == x | y else text


# -- blind51: share-out headers ------------------------------------------------------------------

# "One thing per person: …", "Split them up, would you: P takes the X, Q takes the Y."
_PER_PERSON53R = re.compiled(
    r"^(?:(?P<one>one (?:thing|item)|a thing|an item) per (?:person|head|customer|patient|pupil|"
    r"child|kid)|(?P<split>(?:split|share|divvy|divide|dole|portion) (?:them|these|those|the "
    r"(?:two |three )?things)(?: up| out| between them)?(?:\s*,\s*(?:would you|will you|could "
    r"you|can you|please))?))\s*:\s*(?P<rest>.+)$",
    _F,
)
# "P takes the X" in a split's list: P gets it
_TAKES53R = re.compiled(rf"(?P<p>{_P46R}) takes (?=(?:the|a|an) )", _F)


def _per_person53r(text: str, lexicon: Lexicon) -> str:
    """Session 53 (12r): a share-out header "One thing per person:" (per head) or "Split them up,
    would you:" (share them out) before a list is session 35's "One thing each:", whose count
    check asks one thing to every person named once; in a split's list "P takes the X" is "P
    gets the X". Read only as one handover to each of two or more people."""
    low = text.lower()
    if " per " not in low and ":" not in low:
        return text
    m = _PER_PERSON53R.match(text.strip())
    if m is None or _held53r(m["rest"]):
        return text
    rest = m["rest"]
    if m["split"] is not None:
        rest = _TAKES53R.sub(lambda t: f"{t['p']} gets ", rest)
    out = f"One thing each: {rest}"
    got = _tasks53r(out, lexicon)
    if got is None or len(got) < 2 or any(t.kind != "deliver" for t in got):
        return text
    who = [t.target for t in got]
    if len(set(who)) != len(who):
        return text
    if m["split"] is not None and len(got) != len(lexicon.scene.objects):
        return text  # 'them' are the scene's things: every one shared out
    return out


# "Marco and Lena each get a plate from you, the white one to Marco and the blue one to Lena,
# service starts soon."
_EACH_GET53R = re.compiled(
    rf"^(?P<p>{_P46R}) and (?P<q>{_P46R}) (?:each get|get one each|are each getting|each have) "
    r"(?:a|one) (?P<k>[a-z]+)(?: each)?(?: (?:from you|off you|from the robot))?\s*,\s*"
    r"(?P<list>[^,;]+? (?:to|for) [^,;]+? and [^,;]+? (?:to|for) [^,;.!]+?)"
    r"(?:\s*,\s*(?P<why>[a-z' ]+))?(?P<end>\s*[.!]?)$",
    _F,
)
# a closing remark that could put the task off or say something of it
_WHY_HELD53R = re.compiled(
    r"\b(?:not|n't|never|no|tomorrow|tonight|later|after|before|when|once|until|till|next|"
    r"morning|evening|afternoon|then|wait|instead|only|too|also|either|or|if|unless|first|last)\b",
    _F,
)


def _each_get53r(text: str, lexicon: Lexicon) -> str:
    """Session 53 (12r): "P and Q each get a plate (from you), the white one to P and the blue one
    to Q(, service starts soon)" is "A plate each for P and Q: …" (session 52's share-out by a
    kind), a closing remark that names nothing of the scene and no time taken off. Read only as
    one thing of that kind to each of the two."""
    if "each" not in text.lower():
        return text
    m = _EACH_GET53R.match(text.strip())
    if m is None or _held53r(m["list"] + " " + (m["why"] or "")):
        return text
    p, q = _person46r(m["p"], lexicon), _person46r(m["q"], lexicon)
    if p is None or q is None or p == q:
        return text
    if m["why"] is not None and (_ids(m["why"], lexicon) or _WHY_HELD53R.search(m["why"])):
        return text
    out = f"A {m['k']} each for {m['p']} and {m['q']}: {m['list']}{m['end'] or '.'}"
    got = _tasks53r(out, lexicon)
    kind = _ids(f"the {m['k']}", lexicon, "object")
    if got is None or len(got) != 2 or {t.target for t in got} != {p, q}:
        return text
    if any(t.kind != "deliver" or t.obj not in kind for t in got):
        return text
    return out


# -- blind51: the speaker does not know which (refused naming every reading) ---------------------

# "Mr Lee or Mrs Khan asked for the magazine, one of the two, I forget which."
_ONE_OF_TWO53R = re.compiled(
    rf"^(?P<head>(?P<p>{_P46R}) or (?P<q>{_P46R}) [^,;.]+?)\s*,\s*one of (?:the|those) two"
    r"(?P<rest>\s*[,;]\s*.+)$",
    _F,
)


def _one_of_two53r(text: str, lexicon: Lexicon) -> None:
    """Session 53 (12r): "P or Q asked for the X, one of the two, I forget which": 'one of the two'
    is one of the two people just named (not two things), and the speaker has forgotten which:
    refused, naming both (the grammar had refused it for 'one of the two' things, naming
    neither). Only with a forgetting remark after it (`forgets50l`)."""
    if "one of th" not in text.lower():
        return
    m = _ONE_OF_TWO53R.match(text.strip())
    if m is None or forgets50l(m["rest"]) is None:
        return
    p, q = _person46r(m["p"], lexicon), _person46r(m["q"], lexicon)
    if p is None or q is None or p == q:
        return
    raise GroundingError(
        f"{m['head']!r}, one of the two, and the speaker has forgotten which: it could be "
        f"{person_name(p, lexicon)} or {person_name(q, lexicon)}; name the person"
    )


# "Tom was very particular about which box he wanted, small, medium or large, and it's gone clean
# out of my head."
_PARTICULAR53R = re.compiled(
    rf"^(?P<p>{_P46R}) (?:was|is|'s) (?:very |really |quite |ever so |most )?(?:particular|"
    r"specific|"
    r"fussy|clear|picky) (?:about|on|as to) (?:which|what) (?P<k>[a-z]+) (?:he|she|they) "
    r"(?:wanted|wants|asked for|needed|needs)\s*,\s*(?P<rest>.+)$",
    _F,
)


def _particular53r(text: str, lexicon: Lexicon) -> str:
    """Session 53 (12r): "P was very particular about which box he wanted, small, medium or large,
    and it's gone clean out of my head" is "P wanted one of the boxes, …": read only with a
    forgetting remark after it (session 50's `_forgot_choice50l` then refuses the choice, naming
    each option)."""
    if "about which" not in text.lower() and "which" not in text.lower():
        return text
    m = _PARTICULAR53R.match(text.strip())
    if m is None or forgets50l(m["rest"]) is None or _person46r(m["p"], lexicon) is None:
        return text
    kind = m["k"].lower()
    if len(_ids(f"the {kind}", lexicon, "object")) < 2:
        return text
    kinds = f"{kind}es" if kind.endswith(("s", "x", "ch", "sh")) else f"{kind}s"
    return f"{m['p']} wanted one of the {kinds}, {m['rest']}"


# "Give Person A the chips, no wait, I've lost track of who asked."
_WHO_ASKED53R = re.compiled(
    r"^\s*(?:of\s+)?who(?:m)?(?:'s| is| was)?\s+(?:asked|wanted|ordered|needs|needed|wants|it's "
    r"for|it is for|it was for|they're for|they are for|they were for|gets|should get|was getting|"
    r"'s getting|is getting|it goes to|it went to|was after|is after)\b",
    _F,
)


def _lost_who53r(text: str, lexicon: Lexicon) -> None:
    """Session 53 (12r): a request the speaker then doubts, "…, I've lost track of who asked" (I
    can't remember who wanted it, I forget who it's for): who gets it is not known: refused,
    naming every person of the scene."""
    low = text.lower()
    if " who" not in low:
        return
    m = forgets50l(text)
    if m is None or _WHO_ASKED53R.match(text[m.end() :]) is None or m.start() == 0:
        return
    if re.search(r"\bother\b", text[: m.start()], _F):
        return  # a correction to 'the other patient': session 37's refusal names who fits
    people = [h.id for h in lexicon.scene.humans]
    if len(people) < 2:
        return
    said = " or ".join(person_name(i, lexicon) for i in people)
    raise GroundingError(
        f"{text[m.start() :].strip(' .!')!r}: the speaker does not know who gets it: it could be "
        f"{said}; name the person"
    )


# the normaliser's first rewrites (wired into normalise._STEPS19, before the session-52 ones)
_STEPS53R_FIRST: tuple[Callable[[str, Lexicon], str], ...] = (_one_who_is53r,)
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-52 ones)
_STEPS53R: tuple[Callable[[str, Lexicon], str], ...] = (
    _not_first53r,
    _fix_for53r,
    _said_before53r,
    _its_actually53r,
    _goes_there53r,
    _rethink53r,
    _whichever_of53r,
    _either_hand53r,
    _route53r,
    _will_suit53r,
    _says_any53r,
    _on_offer53r,
    _can_drink53r,
    _need_more53r,
    _had_lot53r,
    _both_of_them53r,
    _as_well_as53r,
    _particular53r,
    _per_person53r,
    _each_get53r,
)
# refusals asked of the text before it is read (offline._parse, after the session-52 ones)
REFUSE53R: tuple[Callable[[str, Lexicon], None], ...] = (_lost_who53r, _one_of_two53r)
# checks of the whole instruction's reading (offline.parse_instruction, after the session-52 ones)
CHECK53R: tuple[Callable[[str, Node, Lexicon], None], ...] = (_each_head53r,)
