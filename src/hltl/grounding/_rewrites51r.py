"""The grounder's rules of session 51, engineer 12r (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _ids, _names, _reading
from hltl.grounding._rewrites41s import _WANT_SAID41S
from hltl.grounding._rewrites42s import _NEGATED42S, _remark_only42s
from hltl.grounding._rewrites44r import _agrees44r, _read_or44r
from hltl.grounding._rewrites46r import _P46R, _person46r
from hltl.grounding._rewrites47r import _thing47r
from hltl.grounding._rewrites48r import _choice_for48r
from hltl.grounding._rewrites49r import _it_is49r, _one49r, _targets49r, _the_one49r
from hltl.grounding._rewrites50r import _about50r, _choice50r
from hltl.grounding.lexicon import Lexicon
from hltl.grounding.tree import Node, has_choice, tasks

# a head said as done, or as what was ("Both blankets were on the locker", "A got the apple"):
# the rules that take a closing remark off leave it (12c's fuzz: the remark had been its refusal)
_DONE_HEAD51R = re.compiled(
    r"\b(?:was|were|went|had|got|been|gave|given|took|taken|received|brought|handed|passed|"
    r"delivered|sent|ended up)\b",
    _F,
)


# -- whose a thing is, said of it: the reading must not hand it to someone else ------------------

# "… Then the apple. That one's Person B's.", "…, it's Mr Lee's.", "…, that is the nurse's."
_OWNER51R = re.compiled(
    r"(?:^|(?<=[.,;:!?])\s*)(?:(?:and|but|oh|because|cos|as)\s+)?(?:that one|this one|that|this|"
    rf"it|those|these|they)(?:'s| is|'re| are) (?P<p>(?:the )?{_P46R})'s\s*(?=[.,;:!?]|$)",
    _F,
)


def _owner_said51r(text: str, node: Node, lexicon: Lexicon) -> None:
    """Session 51 (12r): "That one's P's" (it's P's, that's the nurse's) says whose the thing named
    just before it is: a reading that hands that thing to someone else, and not to P, has lost
    the remark (12c's fuzz: "… Then the apple. That one's Person B's. Also, the chips to Person
    B." had handed the apple to Person A): refused. Placing it is no contradiction."""
    if "'s" not in text:
        return
    for m in _OWNER51R.finditer(text):
        pid = _person46r(m["p"], lexicon)
        if pid is None:
            continue
        before = [it for it in _names(text[: m.start()], lexicon) if it.refs[0].kind == "object"]
        if not before:
            continue
        objs = {r.id for r in before[-1].refs}
        given = [t for t in tasks(node) if t.obj in objs and t.kind == "deliver"]
        if given and all(t.target != pid for t in given):
            raise GroundingError(
                f"{m.group(0).strip(' ,;.')!r} says whose the {before[-1].text} is, but it would "
                f"go to someone else: say who gets it"
            )


# -- blind49: choices left to one person -------------------------------------------------------

# a closing remark of the one person a choice (or thing) goes to, saying they deserve it or like
# every option: it asks for nothing more ("she's earned it at the improv night", "she likes them
# both", "he deserves it after the night shift")
_CLOSING51R = re.compiled(
    r"^(?P<pro>she|he)(?:'s| has)(?: (?:more than|really|well and truly))? (?:earned|deserved) "
    r"(?:it|them|one)\b|"
    r"^(?P<pro2>she|he) (?:deserves|has earned) (?:it|them|one)\b|"
    r"^(?P<pro3>she|he) (?:likes|loves|likes the look of|is fond of|'s fond of|enjoys) "
    r"(?:them both|both of them|both|either|either one|either of them|any of them|all of them|"
    r"them all)$",
    _F,
)


def _closing51r(head: str, tail: str, end: str, text: str, lexicon: Lexicon) -> str:
    """``head`` (a choice handed to one person) with the closing remarks of ``tail`` taken off:
    those of ``_CLOSING51R`` (what the rest of the remark says naming nothing of the scene, the
    pronoun that person), then the ones ``_choice50r`` takes off."""
    if _DONE_HEAD51R.search(head):
        return text
    node = _reading(f"{head}{end or '.'}", lexicon)
    people = _targets49r(node)
    if node is None or people is None or len(people) != 1 or not has_choice(node):
        return text
    pid = next(iter(people))
    rest = []
    for part in (p.strip() for p in tail.split(",") if p.strip()):
        m = _CLOSING51R.match(part)
        if m is None:
            rest.append(part)
            continue
        pro = m["pro"] or m["pro2"] or m["pro3"]
        after = re.sub(r"\b(?:his|her|their)\b", "", part[m.end() :], flags=_F)
        if not _agrees44r(pid, pro, lexicon) or (after.strip() and _names(after, lexicon)):
            return text
    return _choice50r(head, "".join(f", {p}" for p in rest), end, text, lexicon)


def _likes_both51r(text: str, lexicon: Lexicon) -> str:
    """Session 51 (12r): a choice handed to one person closed by a remark of ``_CLOSING51R``
    ("Either of the blocks to Lily, she likes them both"; "…, he's earned it after his shift"):
    the remark taken off (as ``_closing51r`` has it)."""
    low = text.lower()
    if " both" not in low and "either" not in low and "earned" not in low and "deserv" not in low:
        return text
    body = text.strip()
    end = re.search(r"\s*[.!]?$", body)
    stop = end.start() if end is not None else len(body)
    parts = body[:stop].split(",")
    for k in range(1, len(parts)):
        if _CLOSING51R.match(parts[k].strip()) is not None:
            head = ",".join(parts[:k]).strip()
            tail = "".join(f",{p}" for p in parts[k:])
            return _closing51r(head, tail, body[stop:], text, lexicon)
    return text


# "Any of the four things, Person B isn't choosy.", "Whichever of the chips and the apple, Person
# A is happy with one."
_FRONT_CHOICE51R = re.compiled(
    r"^(?P<c>(?:any|either|whichever|any one) of (?:the (?:two|three|four|five|six|seven|eight) "
    r"(?:things|of them|items)|the [a-z]+s|the [a-z]+(?: [a-z]+)? (?:and|or) the [a-z]+"
    r"(?: [a-z]+)?)|(?:any|either|whichever|any old) [a-z]+)\s*,\s*"
    rf"(?P<p>{_P46R})(?P<easy>(?:'s not| is not| isn't| ain't|'s never been| won't be| wouldn't "
    r"be)(?: too| that| at all| really)? (?:choosy|fussy|fussed|bothered|picky|particular)"
    r"(?: (?:which|about which))?|(?:'s| is|'ll be| will be|'d be| would be) (?:happy|fine|"
    r"content|glad|pleased|okay|ok) (?:with|to have|to take) (?:one|either|either one|any|any one|"
    r"whichever)(?: of them)?|(?: doesn't| does not| won't| will not) (?:mind|care)(?: which)?)"
    r"(?P<tail>(?:\s*,\s*[^,.;!?]+)*?)(?P<end>\s*[.!]?)$",
    _F,
)


def _front_choice51r(text: str, lexicon: Lexicon) -> str:
    """Session 51 (12r): a choice said first, then that the person is easy about it ("Any of the
    four things, P isn't choosy"; "Whichever of the chips and the apple, P is happy with one";
    "Either mug, Bob doesn't mind") is "Give P <the choice>" ('whichever of the X and the Y' as
    'the X or the Y'), closing remarks as ``_closing51r`` has them."""
    low = text.lower()
    if "any" not in low and "either" not in low and "whichever" not in low:
        return text
    m = _FRONT_CHOICE51R.match(text.strip())
    if m is None or _person46r(m["p"], lexicon) is None:
        return text
    c = m["c"]
    pair = re.match(
        r"^(?:whichever|either|any|any one) of (?P<x>the [a-z]+(?: [a-z]+)?) (?:and|or) "
        r"(?P<y>the [a-z]+(?: [a-z]+)?)$",
        c,
        _F,
    )
    if pair is not None:
        c = f"{pair['x']} or {pair['y']}"
    elif re.match(r"^(?:whichever|any old) [a-z]+$", c, _F):
        c = f"any {c.split()[-1]}"
    c = re.sub(r"^whichever of ", "any of ", c, flags=_F)
    head = f"Give {m['p']} {c}"
    return _closing51r(head, m["tail"], m["end"], text, lexicon)


# "Person A can take her pick of the bottle or the chips, she's earned it at the improv night."
_PICK_OF51R = re.compiled(
    rf"^(?P<p>{_P46R})(?:(?:'ll| will| can| may| could)? (?:have|take|get)| gets| has) "
    r"(?P<pro>his|her|their) "
    r"pick of (?P<what>the [a-z]+(?: [a-z]+)? or the [a-z]+(?: [a-z]+)?|the [a-z]+s|"
    r"the (?:two|three|four|five|six) (?:things|[a-z]+s))"
    r"(?P<tail>(?:\s*,\s*[^,.;!?]+)*?)(?P<end>\s*[.!]?)$",
    _F,
)


def _pick_of51r(text: str, lexicon: Lexicon) -> str:
    """Session 51 (12r): "P can take (have, gets) her pick of the X or the Y (the pens, the
    four things)" is "Give P the X or the Y" ("any of the pens"), the pronoun P's, closing
    remarks as ``_closing51r`` has them (session 48's `_take_pick48r` reads it said with 'take'
    and nothing after it that names nothing but is no easy-going word)."""
    if "pick of" not in text.lower():
        return text
    m = _PICK_OF51R.match(text.strip())
    if m is None:
        return text
    pid = _person46r(m["p"], lexicon)
    if pid is None or (m["pro"].lower() != "their" and not _agrees44r(pid, m["pro"], lexicon)):
        return text
    what = m["what"]
    if " or " not in what:
        what = f"any of {what}"
    return _closing51r(f"Give {m['p']} {what}", m["tail"], m["end"], text, lexicon)


# "Whichever bottle you like, so long as Person A gets it."
_SO_LONG_AS51R = re.compiled(
    r"^(?:whichever|whatever|any|any old) (?P<k>[a-z]+)(?: at all)? (?:you (?:like|want|fancy|"
    r"choose|prefer|please|pick|think best)|you're happy with|suits you|is handiest)\s*,\s*"
    r"(?:so long as|as long as|provided|providing|just so long as)(?: that)? "
    rf"(?P<p>{_P46R}) (?:gets|has|receives|ends up with) (?:it|one)(?P<end>\s*[.!]?)$",
    _F,
)


def _so_long_as51r(text: str, lexicon: Lexicon) -> str:
    """Session 51 (12r): "Whichever bottle you like, so long as P gets it" (the robot's pick of
    the kind, for P) is "Give P the bottle" when the scene has one, "Give P a bottle" (a choice)
    when it has more."""
    low = text.lower()
    if "long as" not in low and "provid" not in low:
        return text
    m = _SO_LONG_AS51R.match(text.strip())
    if m is None or _person46r(m["p"], lexicon) is None:
        return text
    end = m["end"] or "."
    thing = _the_one49r(m["k"], lexicon)
    if thing is not None:
        return _read_or44r(f"Give {m['p']} {thing}{end}", text, lexicon)
    kind = _ids(f"the {m['k']}", lexicon, "object")
    if len(kind) < 2 or _ids(f"the {m['k']}", lexicon) != kind:
        return text
    out = f"Give {m['p']} a {m['k']}{end}"
    node = _reading(out, lexicon)
    if node is None or not has_choice(node) or {t.obj for t in tasks(node)} != kind:
        return text
    return out


# "Any bottle going would suit Person A, …"
_WOULD_SUIT51R = re.compiled(
    r"^(?P<q>any|either|any old|whichever) (?P<k>[a-z]+)(?: (?:going|at all|about|around|you can "
    r"find|you've got|there is))? (?:would|will|'d|'ll|should) (?:suit|do for|please|satisfy|"
    rf"content) (?P<p>{_P46R})(?P<tail>(?:\s*,\s*[^,.;!?]+)*?)(?P<end>\s*[.!]?)$",
    _F,
)


def _would_suit51r(text: str, lexicon: Lexicon) -> str:
    """Session 51 (12r): "Any bottle going would suit P" ("Either mug would please Bob") is "Give
    P any bottle" ("a mug"; 'either' of a kind the scene has two of), closing remarks naming
    nothing taken off (``_choice_for48r``)."""
    low = text.lower()
    if "suit" not in low and "please" not in low and "satisf" not in low and "content" not in low:
        return text
    m = _WOULD_SUIT51R.match(text.strip())
    if m is None or _person46r(m["p"], lexicon) is None:
        return text
    kind = _ids(f"the {m['k']}", lexicon, "object")
    q = m["q"].lower()
    if not kind or _ids(f"the {m['k']}", lexicon) != kind or (q == "either" and len(kind) != 2):
        return text
    head = f"Give {m['p']} {'a' if q == 'either' else 'any'} {m['k']}"
    return _choice_for48r(head, m["tail"], m["end"], text, lexicon, choice=len(kind) > 1)


# "…, so both, the bottle and the chips, go to him please."
_BOTH_COMMA51R = re.compiled(
    r"\bboth\s*,\s*(?P<x>the [a-z]+(?: [a-z]+)?) and (?P<y>the [a-z]+(?: [a-z]+)?)\s*,\s*"
    r"(?=(?:go|are going|are to go|can go|should go|get|need) )",
    _F,
)


def _both_comma51r(text: str, lexicon: Lexicon) -> str:
    """Session 51 (12r): "both, the bottle and the chips, go to P" (the two things said between
    commas after 'both') is "both the bottle and the chips go to P", each naming one object."""
    if "both," not in text.lower() and "both ," not in text.lower():
        return text
    m = _BOTH_COMMA51R.search(text)
    if m is None:
        return text
    x, y = _ids(m["x"], lexicon, "object"), _ids(m["y"], lexicon, "object")
    if len(x) != 1 or len(y) != 1 or x == y:
        return text
    out = f"{text[: m.start()]}both {m['x']} and {m['y']} {text[m.end() :]}"
    node = _reading(out, lexicon)
    if node is None or not (x | y) <= {t.obj for t in tasks(node)}:
        return text
    return out


# "The doctor asked for one of the cups, green or white, but I've lost track of which."
_ASKED_ONE_OF51R = re.compiled(
    rf"^(?P<p>{_P46R}|the [a-z]+) (?P<v>asked for|asked me for|wants|wanted|would like|'d like|"
    r"is after|'s after|was after|requested|needs|needed) (?:one of the|either of the|one of "
    r"those) (?P<k>[a-z]+s)(?P<adj>\s*,\s*[a-z]+ or [a-z]+)?(?P<rest>(?:\s*,\s*|\s+)[^.!?]+?)?"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _asked_one_of51r(text: str, lexicon: Lexicon) -> str:
    """Session 51 (12r): "P asked for one of the cups(, green or white)" (wants, is after) is "P
    asked for a cup…" (a choice of the kind, which the grammar reads), the kind two or more
    objects of the scene; with more said after it only when that is the speaker forgetting which
    ("…, but I've lost track of which": refused naming both, session 50's `forgets50l`)."""
    if "of th" not in text.lower():
        return text
    m = _ASKED_ONE_OF51R.match(text.strip())
    if m is None or _person46r(m["p"], lexicon) is None:
        return text
    k = _one49r(m["k"])
    kind = _ids(f"the {m['k']}", lexicon, "object")
    if len(kind) < 2 or _ids(f"the {m['k']}", lexicon) != kind or _ids(f"the {k}", lexicon) != kind:
        return text
    out = f"{m['p']} {m['v']} a {k}{m['adj'] or ''}{m['rest'] or ''}{m['end'] or '.'}"
    if m["rest"]:
        return out if _forgot51r(out, lexicon) else text
    node = _reading(out, lexicon)
    if node is None or not has_choice(node) or not {t.obj for t in tasks(node)} <= kind:
        return text
    return out


def _forgot51r(out: str, lexicon: Lexicon) -> bool:
    """Whether ``out`` is refused naming the choice the speaker forgot."""
    # why: offline imports this module (its rules are offline's steps)
    from hltl.grounding.offline import parse_instruction

    try:
        parse_instruction(out, lexicon.scene, lexicon)
    except GroundingError as e:
        return "forgotten which" in str(e)
    return False


# "Sam can have one of the pens, whichever, he's an ichthyologist, not a contortionist."
_NOT_A51R = re.compiled(
    r"(?P<pre>,\s*(?P<pro>she|he)(?:'s| is) (?:a|an|the) [a-z-]+(?: [a-z-]+)?)\s*,?\s*(?:and )?not "
    r"(?:a|an|the) (?P<y>[a-z-]+(?: [a-z-]+)?)(?P<end>\s*[.!]?)$",
    _F,
)


def _not_a51r(text: str, lexicon: Lexicon) -> str:
    """Session 51 (12r): a request closed by what its one person is, then what they are not
    ("…, he's an ichthyologist, not a contortionist": a remark on who they are, naming nothing
    of the scene): the 'not a …' taken off, the rest of the remark left to the rules that read
    a closing remark."""
    if "not a" not in text.lower() and "not the" not in text.lower():
        return text
    m = _NOT_A51R.search(text.strip())
    if m is None or _names(m["y"], lexicon) or _DONE_HEAD51R.search(text.strip()[: m.start()]):
        return text
    out = f"{text.strip()[: m.start()]}{m['pre']}{m['end'] or '.'}"
    node = _reading(out, lexicon)
    got = _targets49r(node)
    if got is None or len(got) != 1 or not _agrees44r(next(iter(got)), m["pro"], lexicon):
        return text
    return out if _about50r(m["pre"], got, lexicon) else text


# -- blind49: counts said of the scene ----------------------------------------------------------

# "A lone bottle's all there is; Person A gets it."
_ALL_THERE_IS51R = re.compiled(
    r"^(?:a lone|a single|just the one|only the one|the one|one|just one|only one|a solitary) "
    r"(?P<k>[a-z]+)(?:'s| is) (?:all (?:there is|we've got|we have|there's left|that's left|"
    r"that's going|there's going)|the only one (?:there is|we've got|we have|going|left))"
    r"\s*[;,.:]\s*(?:(?:so|and)\s+)?(?P<rest>.+)$",
    _F,
)


def _all_there_is51r(text: str, lexicon: Lexicon) -> str:
    """Session 51 (12r): "A lone bottle's all there is; P gets it" ("One cup is all we've got,
    so hand it to Bob") is the request with 'it' the bottle, when the scene has exactly one."""
    if " all " not in text.lower() and " only " not in text.lower():
        return text
    m = _ALL_THERE_IS51R.match(text.strip())
    if m is None:
        return text
    thing = _the_one49r(m["k"], lexicon)
    if thing is None:
        return text
    out = _it_is49r(m["rest"], thing, next(iter(_ids(thing, lexicon))), lexicon)
    return text if out is None else out


# "The one bottle in here, for Person A, …"
_ONE_IN_HERE51R = re.compiled(
    r"\bthe (?:one|only|single|lone|sole) (?P<x>[a-z]+) (?:in here|in the room|here|on offer|"
    r"going|on hand|to hand|we've got|we have|there is|left|about|around)\b",
    _F,
)


def _one_in_here51r(text: str, lexicon: Lexicon) -> str:
    """Session 51 (12r): "the one bottle in here" ("the only cup on offer", "the single apple
    we've got") is "the bottle" when the scene has exactly one (session 50's `_lone_in50r`
    without 'one' / 'only' and these places)."""
    low = text.lower()
    if not any(w in low for w in ("one ", "only ", "single ", "lone ", "sole ")):
        return text
    m = _ONE_IN_HERE51R.search(text)
    if m is None or _DONE_HEAD51R.search(text):
        return text
    thing = _the_one49r(m["x"], lexicon)
    if thing is None:
        return text
    return _read_or44r(f"{text[: m.start()]}{thing}{text[m.end() :]}", text, lexicon)


# "Person A gets the bottle, the only one on offer."
_ONLY_ONE51R = re.compiled(
    r"\s*,\s*(?:it's |that's |it is |that is )?(?:the only one|the one and only|the last one|"
    r"the only one of them|the one)(?: (?:on offer|there is|we've got|we have|going|left|in here|"
    r"in the room|around|about|here))?(?P<end>\s*[.!]?)$",
    _F,
)


def _only_one51r(text: str, lexicon: Lexicon) -> str:
    """Session 51 (12r): a request closed by ", the only one on offer" (the only one there is,
    the one and only) of a thing the scene has exactly one of: the remark taken off."""
    if " one" not in text.lower():
        return text
    m = _ONLY_ONE51R.search(text.strip())
    if m is None or m.group(0).strip(" ,.!").lower() == "the one":
        return text
    if _DONE_HEAD51R.search(text.strip()[: m.start()]):
        return text
    # "Hand the bottle to Person A, the only one here.": said of the person named before it
    if _ids(" ".join(text.strip()[: m.start()].split()[-3:]), lexicon, "human"):
        return text
    out = f"{text.strip()[: m.start()]}{m['end'] or '.'}"
    node = _reading(out, lexicon)
    if node is None or has_choice(node):
        return text
    objs = [t.obj for t in tasks(node)]
    if len(set(objs)) != 1:
        return text
    cat = next(o.category for o in lexicon.scene.objects if o.id == objs[0])
    if sum(o.category == cat for o in lexicon.scene.objects) != 1:
        return text
    return out


# "…, and she's had it.", "…, she's had it already.", "…, and he's eaten it.", "…, I gave him the
# red.", "…, I gave it to him." (session 55): the thing a reading hands over is already had, or
# already given
# session 56 (lead; 12c's fuzz): when it was handed over ("…, I handed that over yesterday.", "…
# an hour ago", "… at nine", "… twice already"): a time said after the handing is no request
_WHEN_DONE51R = (
    r"(?:\s+(?:already|earlier|before|just now|now|yesterday|today|earlier today|this (?:morning|"
    r"afternoon|evening)|last night|at (?:lunch(?:time)?|breakfast|dinner|tea|noon|midday|"
    r"\d{1,2}(?::\d\d)?(?: ?[ap]m)?|one|two|three|four|five|six|seven|eight|nine|ten|eleven|"
    r"twelve)(?: o'clock)?|(?:an?|one|two|three|five|ten|twenty|a few|a couple of) (?:hour|minute|"
    r"min|second)s? ago|a (?:while|bit|moment|second|minute) ago|once|twice))*"
)
_THING_DONE51R = r"(?:it|them|that|those|(?:that|this) one)"
_DONE51R = re.compiled(
    r"(?:^|[,;.:!?]|\b(?:and|but|so|though)\b)\s*(?:(?:and|but|so|though|oh)\s+)?"
    rf"(?P<who>she|he|they|{_P46R})(?:'s| has|'ve| have)(?: already| just| since)? (?:had|eaten|"
    r"drunk|finished|used|taken|received|got|been given) (?:it|them|one|that|hers|his)"
    r"(?: already| now| by now| earlier| just now)?\s*(?=[,;.!?]|$)|"
    # … and handed over with no one said, or given said of the thing ("…, I've already handed it
    # over.", "…, I gave it him.", "…, it's been given to him already.": 12c's fuzz)
    # (brought, took, sent: a short time only — "I brought it in this morning" is no handing)
    r"\bi(?:'ve| have)?(?: already| just)? (?:brought|took|sent) "
    # session 56 (lead; 12c: "Give Bob the apple, I've already handed that over." read apple>B)
    rf"{_THING_DONE51R}(?: (?P<to2>him|her|them))?(?: (?:over|across|round|back))?"
    r"(?: already| earlier| just now| a minute ago| before)?\s*(?=[,;.!?]|$)"
    # … given, handed or passed, to whom and when ("…, I handed it over yesterday.")
    r"|\bi(?:'ve| have)?(?: already| just)? (?:gave|given|handed|passed) "
    rf"{_THING_DONE51R}(?: (?P<to4>him|her|them))?(?: (?:over|across|round|back))?"
    rf"(?: to (?P<to5>him|her|them|{_P46R}))?{_WHEN_DONE51R}\s*(?=[,;.!?]|$)"
    r"|\bi(?:'ve| have)?(?: already| just)? (?:gave|given|handed|passed|brought|took) "
    # session 55 (lead; 12c's fuzz: "Bob wants the apple, I gave it to him." read apple>B): the
    # thing said as 'it' / 'them' and the person after 'to'
    r"(?:(?:it|them|that|those|one|(?:that|this) one) (?:back |over |across |round )?to )?"
    rf"(?P<to>him|her|them|{_P46R})\b"
    r"|\b(?:it|they|that|those|(?:that|this) one)(?:'s| has|'ve| have|'re| are) (?:already |just )?"
    r"been (?:already |just )?"
    r"(?:given|handed|passed|brought|sent|delivered)(?: (?:over|across|round|back))?"
    rf"(?: to (?P<to3>him|her|them|{_P46R}))?{_WHEN_DONE51R}\s*(?=[,;.!?]|$)",
    _F,
)


def _done_after51r(text: str, node: Node, lexicon: Lexicon) -> None:
    """Session 51 (12r): a reading handing things to a person of a text that says that person
    has had it already (eaten it, been given it) or that the speaker gave it them ("The one bottle
    in here was for Person A, and she's had it.", "Bob asked for one of the mugs, I gave him the
    red.": 12c's fuzz; the want is over): refused ('it' / 'them' / 'one' said: "she's just eaten"
    is a meal). After a correction cue it is said of what
    the correction takes back, and left."""
    low = text.lower()
    if not any(
        w in low for w in ("had", "eaten", "drunk", "finished", "used", "taken", "got")
    ) and (
        not any(w in low for w in ("gave", "given", "handed", "passed", "brought", "took", "sent"))
    ):
        return
    got = {t.target for t in tasks(node) if t.kind == "deliver"}
    if not got:
        return
    for m in _DONE51R.finditer(text):
        if _BACK_JUST51R.search(text[: m.start()]):
            # "The red book for Noah, no, he's finished that, the green one": said of the thing
            # the correction takes back
            continue
        who = m["who"] or m["to"] or m["to2"] or m["to3"] or m["to4"] or m["to5"]
        if who is None:
            fits = True  # handed over, to no one said: the thing the reading hands
        elif who.lower() in ("she", "he", "her", "him"):
            fits = any(_agrees44r(pid, who, lexicon) for pid in got)
        elif who.lower() in ("they", "them"):
            fits = True
        else:
            fits = _person46r(who, lexicon) in got
        if fits:
            raise GroundingError(
                f"{m.group(0).strip(' ,;.')!r} says the want is over (had, or given already): "
                "it asks for nothing; leave it out to have the thing handed over"
            )


# "Both of them go to Person B, bottle and chips, he's got the marching band to feed."
_BOTH_OF_THEM51R = re.compiled(
    rf"^both of them (?P<v>go|are going|can go|are for|need to go|should go) (?P<to>to|for) "
    rf"(?P<p>{_P46R})\s*,\s*(?P<x>(?:the )?[a-z]+(?: [a-z]+)?) and (?P<y>(?:the )?[a-z]+"
    r"(?: [a-z]+)?)(?P<tail>(?:\s*,\s*[^,.;!?]+)*)(?P<end>\s*[.!]?)$",
    _F,
)


def _both_of_them51r(text: str, lexicon: Lexicon) -> str:
    """Session 51 (12r): "Both of them go to P, bottle and chips(, …)" (the two said after the
    person) is "Both the bottle and the chips go to P(, …)", each naming one object."""
    if not text.lower().startswith("both of them"):
        return text
    m = _BOTH_OF_THEM51R.match(text.strip())
    if m is None or _person46r(m["p"], lexicon) is None:
        return text
    x, y = (f"the {w}" if not w.lower().startswith("the ") else w for w in (m["x"], m["y"]))
    a, b = _ids(x, lexicon, "object"), _ids(y, lexicon, "object")
    if len(a) != 1 or len(b) != 1 or a == b or _ids(x, lexicon) != a or _ids(y, lexicon) != b:
        return text
    out = f"Both {x} and {y} {m['v']} {m['to']} {m['p']}{m['tail']}{m['end'] or '.'}"
    node = _reading(out, lexicon)
    if node is None or {t.obj for t in tasks(node)} != a | b:
        return text
    return out


# "All four things to Person B: bottle, chips, cup and apple."
_LISTED51R = re.compiled(
    r"^(?P<head>(?:all|both|the|all the) (?:two |three |four |five |six )?(?:things|items|of them) "
    rf"(?:to|for|go to|goes to|over to|are for) (?P<p>{_P46R}))\s*:\s*(?P<list>[^.;!?:]+?)"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _listed51r(text: str, lexicon: Lexicon) -> str:
    """Session 51 (12r): "All four things to P: bottle, chips, cup and apple" (the things said
    again after a colon, exactly the ones the head counts) is "All four things to P"."""
    if ":" not in text:
        return text
    m = _LISTED51R.match(text.strip())
    if m is None:
        return text
    named = _names(m["list"], lexicon)
    if not named or any(len(it.refs) != 1 or it.refs[0].kind != "object" for it in named):
        return text
    if _DONE_HEAD51R.search(m["head"]):
        return text
    out = f"{m['head']}{m['end'] or '.'}"
    node = _reading(out, lexicon)
    if node is None or {t.obj for t in tasks(node)} != {it.refs[0].id for it in named}:
        return text
    return out


# "Mr Lee and Mrs Khan can each have a blanket, the blue one for him."
_EACH_HAVE51R = re.compiled(
    rf"^(?P<p>{_P46R}) and (?P<q>{_P46R})(?: can| will| should| are to| could|'ll)? (?:each )?"
    r"(?:have|get|take|receive) (?:a|one) (?P<k>[a-z]+)(?: each| apiece)?\s*,\s*(?P<x>the [a-z]+) "
    rf"(?:one |[a-z]+ )?(?:for|to|goes to|is for) (?P<pro>him|her|{_P46R})(?P<end>\s*[.!]?)$",
    _F,
)


def _each_have51r(text: str, lexicon: Lexicon) -> str:
    """Session 51 (12r): "P and Q can each have a blanket, the blue one for him" (the scene's two
    blankets, one said for the one person the pronoun fits) is "Give P the blue blanket and Q the
    grey blanket": each gets one, the other the one left."""
    if "each" not in text.lower() and "apiece" not in text.lower():
        return text
    m = _EACH_HAVE51R.match(text.strip())
    if m is None:
        return text
    p, q = _person46r(m["p"], lexicon), _person46r(m["q"], lexicon)
    kind = _ids(f"the {m['k']}", lexicon, "object")
    if p is None or q is None or p == q or len(kind) != 2 or _ids(f"the {m['k']}", lexicon) != kind:
        return text
    said = _ids(f"{m['x']} {m['k']}", lexicon, "object")
    if len(said) != 1 or not said <= kind:
        return text
    pro = m["pro"]
    if pro.lower() in ("him", "her"):
        fits = [pid for pid in (p, q) if _agrees44r(pid, pro, lexicon)]
    else:
        fits = [pid for pid in (p, q) if _person46r(pro, lexicon) == pid]
    if len(fits) != 1:
        return text
    first, other = fits[0], q if fits[0] == p else p
    mine, rest = next(iter(said)), next(iter(kind - said))
    a, b = _thing47r(mine, lexicon), _thing47r(rest, lexicon)
    if a is None or b is None:
        return text
    name = {p: m["p"], q: m["q"]}
    out = f"Give {name[first]} {a} and {name[other]} {b}{m['end'] or '.'}"
    node = _reading(out, lexicon)
    if node is None or {(t.obj, t.target) for t in tasks(node)} != {(mine, first), (rest, other)}:
        return text
    return out


# "Person B is taking both things, bottle and chips, to the seed saving stall, so hand him the two."
_TAKING_TO51R = re.compiled(
    rf"^(?P<p>{_P46R})(?:'s| is)(?: off)? (?:taking|bringing|carrying|lugging|running) "
    r"(?P<what>[^;.!?]+?) (?:to|over to|down to|up to|across to|round to) (?P<place>the [a-z' -]+?)"
    r"\s*,\s*so (?:hand|give|pass|let) (?P<pro>him|her) (?:have )?(?P<n>the two|both|both of them|"
    r"the pair|the pair of them|them|the lot|all three|the three|all of them)(?P<end>\s*[.!]?)$",
    _F,
)


def _taking_to51r(text: str, lexicon: Lexicon) -> str:
    """Session 51 (12r): "P is taking both things, bottle and chips, to the stall, so hand him
    the two" (where P takes them naming nothing of the scene; 'the two' the count of what is
    named) is "Hand P the bottle and the chips"."""
    if " so " not in text.lower():
        return text
    m = _TAKING_TO51R.match(text.strip())
    if m is None:
        return text
    pid = _person46r(m["p"], lexicon)
    if pid is None or not _agrees44r(pid, m["pro"], lexicon) or _names(m["place"], lexicon):
        return text
    named = _names(m["what"], lexicon)
    if not named or any(r.kind != "object" for it in named for r in it.refs):
        return text
    objs = list(dict.fromkeys(r.id for it in named for r in it.refs))
    n = m["n"].lower()
    count = 2 if ("two" in n or "both" in n or "pair" in n) else 3 if "three" in n else None
    if len(objs) < 2 or (count is not None and len(objs) != count):
        return text
    things = [_thing47r(o, lexicon) for o in objs]
    if any(t is None for t in things):
        return text
    out = (
        f"Hand {m['p']} {', '.join(str(t) for t in things[:-1])} and {things[-1]}{m['end'] or '.'}"
    )
    node = _reading(out, lexicon)
    if node is None or {(t.obj, t.target) for t in tasks(node)} != {(o, pid) for o in objs}:
        return text
    return out


# "Both blankets on the locker for now, the ward's too warm for them at the minute."
_TOO_WARM51R = re.compiled(
    r"\s*,\s*(?P<who>the [a-z]+|it|it's getting|it has got|it's got)(?:'s| is| has got| has "
    r"become)? (?:too|far too|a bit too|much too|rather too|way too) [a-z]+ (?:for|to need|to "
    r"want) (?:them|it)(?: (?:at the minute|at the moment|right now|today|now|just now|this "
    r"afternoon|in here))?(?P<end>\s*[.!]?)$",
    _F,
)


def _too_warm51r(text: str, lexicon: Lexicon) -> str:
    """Session 51 (12r): placings closed by why they go there, "the ward's too warm for them (at
    the minute)" (the subject naming nothing of the scene, 'them' the things placed): the remark
    taken off."""
    if "too " not in text.lower():
        return text
    m = _TOO_WARM51R.search(text.strip())
    if m is None or _names(m["who"], lexicon):
        return text
    if _DONE_HEAD51R.search(text.strip()[: m.start()]):
        return text
    out = f"{text.strip()[: m.start()]}{m['end'] or '.'}"
    node = _reading(out, lexicon)
    if node is None or any(t.kind != "place" for t in tasks(node)):
        return text
    return out


# "So nobody sulks, Person A gets the apple and …"
_NOBODY_SULKS51R = re.compiled(
    r"^(?:so|so that|just so|to make sure|to be fair and)(?: that)? (?:nobody|no one|no-one|"
    r"neither of them|none of them)(?:'s|'ll| will| is| gets| feels)? (?:sulks?|fights?|argues?|"
    r"squabbles?|left out|jealous|feel left out|feels left out|kicks? off|complains?|moans?|"
    r"upset|gets upset|gets jealous|falls out)\s*,\s*(?P<rest>.+)$",
    _F,
)


def _nobody_sulks51r(text: str, lexicon: Lexicon) -> str:
    """Session 51 (12r): a request opened by "So nobody sulks," (so no one's left out, so
    neither of them kicks off) — why it is shared out, naming nothing — is the request (what it
    shares out must go to more than one person)."""
    low = text.lower()
    if "nobody" not in low and "no one" not in low and "no-one" not in low and "of them" not in low:
        return text
    m = _NOBODY_SULKS51R.match(text.strip())
    if m is None:
        return text
    if _DONE_HEAD51R.search(m["rest"]):
        return text
    out = f"{m['rest'][:1].upper()}{m['rest'][1:]}"
    node = _reading(out, lexicon)
    if node is None or len({t.target for t in tasks(node)}) < 2:
        return text
    return out


# "It doesn't matter which box, just the one of them on the belt for the driver's test run."
_ANY_ONE_ON51R = re.compiled(
    r"^it (?:doesn't|does not|don't|won't|will not) matter which (?P<k>[a-z]+)\s*,\s*"
    r"(?:just |only )?(?:the )?one (?:of them|of the [a-z]+) (?P<prep>on|onto|in|into) "
    r"(?P<s>the [a-z]+)(?P<why> for [^,.;!?]+)?(?P<end>\s*[.!]?)$",
    _F,
)


def _any_one_on51r(text: str, lexicon: Lexicon) -> str:
    """Session 51 (12r): "It doesn't matter which box, just the one of them on the belt (for the
    driver's test run)" is "Put a box on the belt": one of the kind, the robot's choice; the
    purpose ('for <someone>'s <thing>' naming nothing else of the scene) taken off."""
    if "matter which" not in text.lower():
        return text
    m = _ANY_ONE_ON51R.match(text.strip())
    if m is None:
        return text
    kind = _ids(f"the {m['k']}", lexicon, "object")
    if len(kind) < 2 or len(_ids(m["s"], lexicon, "surface")) != 1:
        return text
    if m["why"]:
        why = re.sub(rf"^ for (?:{_P46R}|the [a-z]+)'s\b", "", m["why"], flags=_F)
        if why == m["why"] or _names(why, lexicon) or not why.strip():
            return text
    out = f"Put a {m['k']} {m['prep']} {m['s']}{m['end'] or '.'}"
    node = _reading(out, lexicon)
    if node is None or not has_choice(node) or {t.obj for t in tasks(node)} != kind:
        return text
    return out


# "All three pens into the box, Priya's clearing the desk for the primatologist's visit."
_CLEARING51R = re.compiled(
    rf"\s*,\s*(?P<p>{_P46R})(?:'s| is)(?: just)? (?:clearing|tidying|emptying|wiping|cleaning|"
    r"clearing off|sorting out|sorting|wiping down|clearing up|tidying up) (?P<s>the [a-z]+)"
    r"(?P<why> for [^,.;!?]+)?(?P<end>\s*[.!]?)$",
    _F,
)


def _clearing51r(text: str, lexicon: Lexicon) -> str:
    """Session 51 (12r): placings closed by "P's clearing the desk (for the visit)" (a surface of
    the scene the things are not put on; why they are moved): the remark taken off."""
    low = text.lower()
    if not any(w in low for w in ("clear", "tidy", "tidying", "empty", "wip", "clean", "sort")):
        return text
    m = _CLEARING51R.search(text.strip())
    if m is None or _person46r(m["p"], lexicon) is None:
        return text
    sid = one_surface51r(m["s"], lexicon)
    if sid is None:
        return text
    if m["why"]:
        why = re.sub(r"\b(?:[a-z]+)'s\b", "", m["why"], flags=_F)
        if _names(why, lexicon) or _names(m["why"], lexicon):
            return text
    if _DONE_HEAD51R.search(text.strip()[: m.start()]):
        return text
    return placed_elsewhere51r(text, m, sid, lexicon)


def one_surface51r(words: str, lexicon: Lexicon) -> set[str] | None:
    """The surface ``words`` name, where they name one surface of the scene and nothing else."""
    sid = _ids(words, lexicon, "surface")
    return sid if len(sid) == 1 and _ids(words, lexicon) == sid else None


def placed_elsewhere51r(text: str, m: re.Match[str], sid: set[str], lexicon: Lexicon) -> str:
    """``text`` with the closing remark ``m`` taken off (its 'end' kept), where what is left reads
    as placings only, none on the remark's surface ``sid``; else ``text``."""
    out = f"{text.strip()[: m.start()]}{m['end'] or '.'}"
    node = _reading(out, lexicon)
    if node is None or any(t.kind != "place" or t.target in sid for t in tasks(node)):
        return text
    return out


# "All three pens into the box, Priya's had enough of the doodling."
_HAD_ENOUGH51R = re.compiled(
    rf"\s*,\s*(?P<p>{_P46R})(?:'s| has)(?: just| really)? (?:had enough of|had it with|got fed up "
    r"with|grown tired of|had her fill of|had his fill of) "
    r"(?P<why>(?:the|all the|all that) [a-z -]+)(?P<end>\s*[.!]?)$",
    _F,
)


def _had_enough51r(text: str, lexicon: Lexicon) -> str:
    """Session 51 (12r): placings closed by "P's had enough of the doodling" (why the things go
    away, naming nothing of the scene): the remark taken off."""
    low = text.lower()
    if not any(w in low for w in ("enough", "had it", "fed up", "tired", "fill")):
        return text
    m = _HAD_ENOUGH51R.search(text.strip())
    if m is None or _person46r(m["p"], lexicon) is None or _names(m["why"], lexicon):
        return text
    if _DONE_HEAD51R.search(text.strip()[: m.start()]):
        return text
    out = f"{text.strip()[: m.start()]}{m['end'] or '.'}"
    node = _reading(out, lexicon)
    if node is None or any(t.kind != "place" for t in tasks(node)):
        return text
    return out


# "The bottle's for Person A and for no one else, she's earned it at the fun run."
_EARNED51R = re.compiled(
    r"\s*,\s*(?P<pro>she|he)(?:'s| has)(?: more than| really| well and truly)? (?:earned|deserved) "
    r"(?:it|them)(?P<why> [^,.;!?]+)?(?P<end>\s*[.!]?)$",
    _F,
)


def _earned51r(text: str, lexicon: Lexicon) -> str:
    """Session 51 (12r): a request handing things to one person closed by "she's earned it (at
    the fun run)" (the pronoun that person, the rest naming nothing of the scene): the remark
    taken off (``_closing51r`` has it after a choice)."""
    if "earned" not in text.lower() and "deserved" not in text.lower():
        return text
    m = _EARNED51R.search(text.strip())
    if m is None or (m["why"] and _names(m["why"], lexicon)):
        return text
    head = text.strip()[: m.start()]
    if _DONE_HEAD51R.search(head):
        return text
    out = f"{head}{m['end'] or '.'}"
    got = _targets49r(_reading(out, lexicon))
    if got is None or len(got) != 1 or not _agrees44r(next(iter(got)), m["pro"], lexicon):
        return text
    return out


# "The dairymaid's left a solitary bottle on the side; take it to Person A, …"
_LEFT_A51R = re.compiled(
    r"^(?P<who>(?:the|a|our|my) [a-z]+(?: [a-z]+)?)(?:'s| has) (?:left|put out|set out|"
    r"dropped off) (?P<x>a (?:solitary |single |lone |sole )?[a-z]+)(?P<where> on the side| out| "
    r"here| for us| on the table| on the counter)?\s*;\s*(?P<rest>.+)$",
    _F,
)


def _left_a51r(text: str, lexicon: Lexicon) -> str:
    """Session 51 (12r): "The dairymaid's left a solitary bottle on the side; take it to P" (who
    left it naming nothing of the scene) is "There's a solitary bottle on the side; take it to
    P" (what the request is about, the scene's one of its kind)."""
    if "left" not in text.lower() and " out" not in text.lower():
        return text
    m = _LEFT_A51R.match(text.strip())
    if m is None or _names(m["who"], lexicon):
        return text
    where = m["where"] or ""
    if where and _names(where, lexicon):
        return text
    kind = m["x"].split()[-1]
    if _the_one49r(kind, lexicon) is None:
        return text
    return _read_or44r(f"There's {m['x']}{where}; {m['rest']}", text, lexicon)


# "Alice or Bob, whichever of the two, can have the crisps; they share everything on the tour."
_THEY_SHARE51R = re.compiled(
    r"\s*[;,]\s*(?:and\s+)?(?:(?:they|the two of them|the pair of them|those two)(?:'ll| will|"
    r" always| usually| tend to| just)? (?:share|split|swap|go halves on)|"
    r"(?P<both>they(?:'ve)? both|the two of them|both of them)(?= ))(?P<why> [^,.;!?]+)?"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _they_share51r(text: str, lexicon: Lexicon) -> str:
    """Session 51 (12r): a choice of who gets a thing closed by "they share everything (on the
    tour)" (why it does not matter which, naming nothing of the scene): the remark taken off."""
    low = text.lower()
    if not any(w in low for w in ("share", "split", "swap", "halves", "both")):
        return text
    m = _THEY_SHARE51R.search(text.strip())
    if m is None or (m["why"] and (_names(m["why"], lexicon) or _NEGATED42S.search(m["why"]))):
        return text
    if m["both"] and (
        not m["why"]
        or not _remark_only42s(m["why"], lexicon)
        or _DONE_HEAD51R.search(m["why"])
        or re.search(
            r"\b(?:some|any|hate|hates|dislike|dislikes|loathe|can't stand)\b", m["why"], _F
        )
    ):
        # "they both put in a shift": a remark; "they both want it", "they both hate them",
        # "they both had some" are none (12c's fuzz)
        return text
    if _DONE_HEAD51R.search(text.strip()[: m.start()]):
        return text
    out = f"{text.strip()[: m.start()]}{m['end'] or '.'}"
    node = _reading(out, lexicon)
    if node is None or not has_choice(node):
        return text
    got = list(tasks(node))
    if len({t.obj for t in got}) != 1 or len({t.target for t in got}) < 2:
        return text
    return out


# -- blind49: corrections ------------------------------------------------------------------------

# the words of a cue that take the request back (session 49's, each a whole word: 'no, Noah')
_CUE51R = (
    r"(?:(?:oh|ah|er|erm|um|hmm|no|sorry|actually|wait|hang on|hold on|scratch that|strike that|"
    r"my mistake|my bad|whoops|oops)\b\s*,?\s*)+"
)


def _one_task51r(text: str, lexicon: Lexicon) -> tuple[str, str, str] | None:
    """The (kind, object, target) of the one task ``text`` reads as, or None (a text said as done,
    "The chips went to Person A, …", none)."""
    if _DONE_HEAD51R.search(text):
        return None
    node = _reading(text, lexicon)
    got = [] if node is None else list(tasks(node))
    if node is None or len(got) != 1 or has_choice(node):
        return None
    return got[0].kind, got[0].obj, got[0].target


# "Bowl on the tray, no, it's got soup in, so in the sink.", "The red book for Zoe, wait, she's
# read that, the green one."
_WHY_FIX51R = re.compiled(
    rf"^(?P<head>[^,;]+?)\s*,\s*(?P<cue>{_CUE51R})(?P<why>[^,;.!?]+?)\s*,\s*(?:so\s+|then\s+)?"
    r"(?P<fix>(?:in|on|into|onto) the [a-z]+(?: [a-z]+)?|the [a-z]+ one|the [a-z]+"
    r"(?: (?!(?:actually|instead|too|also|please|then)\b)[a-z]+)?)"
    r"(?: instead)?(?P<end>\s*[.!]?)$",
    _F,
)


def _why_fix51r(text: str, lexicon: Lexicon) -> str:
    """Session 51 (12r): one task, a correction cue, why the first was wrong (naming nothing of
    the scene but the task's person; 'it' / 'that' the thing), then what it is to be instead ("…,
    no, it's got soup in, so in the sink"; "…, wait, she's read that, the green one") is "<task>,
    no, <fix>", read as the same task with the thing or the place corrected."""
    if "," not in text or not _BACK51R.search(text):
        return text
    m = _WHY_FIX51R.match(text.strip())
    if m is None:
        return text
    first = _one_task51r(m["head"], lexicon)
    if first is None:
        return text
    kind, obj, target = first
    people = {target} if kind == "deliver" else set()
    why = re.sub(r"\b(?:it|that|this|its)\b", "", m["why"], flags=_F)
    if not _about50r(why, people, lexicon) or _WANT_SAID41S.search(m["why"]):
        return text
    out = f"{m['head']}, no, {m['fix']}{m['end'] or '.'}"
    fixed = _one_task51r(out, lexicon)
    if fixed is None or fixed == first or fixed[0] != kind:
        return text
    place = m["fix"].split()[0].lower() in ("in", "on", "into", "onto")
    if (place and (kind != "place" or fixed[1] != obj)) or (not place and fixed[2] != target):
        return text
    return out


# the words of a correction cue (the one list both patterns below are built from)
_BACK_WORDS51R = (
    r"\b(?:no|sorry|wait|hang on|hold on|scratch that|strike that|my mistake|my bad|whoops|oops|"
    r"actually|i mean|i meant)"
)
_BACK51R = re.compiled(rf"{_BACK_WORDS51R}\b", _F)

# session 56 (lead; 12c's fuzz on blind54 #149: "Put the bottle, no, just give the bottle to Person
# A, that's been handed over already." read bottle>A): a correction cue right before the remark
# ("The red book for Noah, no, he's finished that, the green one"; "…, and no, not Lily, she's had
# hers.") says it of what is taken back; one said before a new request does not
_BACK_JUST51R = re.compiled(
    rf"{_BACK_WORDS51R}\s*[,;:.!?-]*\s*"
    # … or the person it takes back or gives to, said after the cue ("…, and no, not Lily, she's
    # had hers.", "Stapler to Priya, no, to Sam, Priya's got one.")
    r"(?:(?:not|to|for) [\w' ]{1,30}?\s*[,;:.!?-]*\s*)?(?:(?:and|but|so)\s+)?$",
    _F,
)

# "Stapler in the box, sorry, Priya likes it kept on the desk."
_KEPT_ON51R = re.compiled(
    rf"^(?P<head>[^,;]+?)\s*,\s*(?P<cue>{_CUE51R})(?P<p>{_P46R}) (?:likes|prefers|wants|would "
    r"like|'d like|would rather have|'d rather have|would prefer|'d prefer) (?:it|them) (?:kept|"
    r"left|to be kept|to be left|to stay|to live)?\s*(?P<prep>on|in) (?P<s>the [a-z]+(?: [a-z]+)?)"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _kept_on51r(text: str, lexicon: Lexicon) -> str:
    """Session 51 (12r): a placing, a correction cue, then where a person of the scene likes the
    thing kept ("Stapler in the box, sorry, Priya likes it kept on the desk") is "<placing>, no,
    on the desk": the same thing placed there."""
    if " it " not in text.lower() and " them " not in text.lower():
        return text
    m = _KEPT_ON51R.match(text.strip())
    if m is None or _person46r(m["p"], lexicon) is None or not _BACK51R.search(m["cue"]):
        return text
    first = _one_task51r(m["head"], lexicon)
    if first is None or first[0] != "place":
        return text
    out = f"{m['head']}, no, {m['prep']} {m['s']}{m['end'] or '.'}"
    fixed = _one_task51r(out, lexicon)
    if fixed is None or fixed[:2] != first[:2] or fixed == first:
        return text
    return out


# "Bottle to Bob, no wait, I've mixed them up again, Alice's the one."
_THE_ONE51R = re.compiled(
    rf"(?P<cue>,\s*(?:{_CUE51R})?)(?P<p>{_P46R})(?:'s| is) the one(?P<who> (?:who|that) [^,.;!?]+)?"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _the_one_is51r(text: str, lexicon: Lexicon) -> str:
    """Session 51 (12r): a correction closed by "P's the one (who wants it)" is "…, no, P": the
    person the one task goes to instead (the 'who' clause, if any, P wanting it)."""
    if "the one" not in text.lower():
        return text
    m = _THE_ONE51R.search(text.strip())
    if m is None or not _BACK51R.search(text.strip()[: m.end("cue")]):
        return text
    pid = _person46r(m["p"], lexicon)
    if pid is None:
        return text
    who = m["who"]
    if who and not _WANTS_IT51R.fullmatch(who):
        return text  # "Bob's the one who is allergic" says why not him, not that he gets it
    out = f"{text.strip()[: m.start()]}{m['cue']}{m['p']}{m['end'] or '.'}"
    fixed = _one_task51r(out, lexicon)
    if fixed is None or fixed[2] != pid:
        return text
    return out


_WANTS_IT51R = re.compiled(
    r" (?:who|that) (?:wants|asked for|needs|gets|ordered|'s getting|is getting) (?:it|them|one)",
    _F,
)

# "Give Person A the apple; actually, she's just said, make that the chips."
_SHE_SAID_MAKE51R = re.compiled(
    r"^(?P<head>[^;.]+?)\s*[;,.]\s*(?:actually|oh|oh actually|wait)\s*,\s*(?P<pro>she|he)"
    r"(?:'s| has)"
    r"(?: just| now)? (?:said|told me|asked|changed (?:her|his) mind|been on|shouted over)\s*,\s*"
    r"(?:so\s+)?(?:make (?:that|it)|change (?:that|it) to) (?P<x>the [a-z]+(?: [a-z]+)?)"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _she_said_make51r(text: str, lexicon: Lexicon) -> str:
    """Session 51 (12r): a request for one person, then "actually, she's just said, make that the
    chips" (she the person, told me, changed her mind) is "<request>, no, make that the chips"."""
    if "make" not in text.lower() and "change" not in text.lower():
        return text
    m = _SHE_SAID_MAKE51R.match(text.strip())
    if m is None:
        return text
    first = _one_task51r(m["head"], lexicon)
    if first is None or first[0] != "deliver" or not _agrees44r(first[2], m["pro"], lexicon):
        return text
    out = f"{m['head']}, no, make that {m['x']}{m['end'] or '.'}"
    fixed = _one_task51r(out, lexicon)
    if fixed is None or fixed[2] != first[2] or fixed[1] == first[1]:
        return text
    return out


# "The chips to Person A, I mean, gosh, it's the bottle she's asked for, to Person A."
_ITS_THE_ASKED51R = re.compiled(
    rf"^(?P<head>[^,;]+?)\s*,\s*(?P<cue>(?:{_CUE51R}|i mean\s*,?\s*|i meant\s*,?\s*)+)(?:(?:gosh|"
    r"golly|goodness|blimey|crikey|heavens|oh dear|dear me|good grief|silly me|duh)\s*,\s*)?"
    r"it(?:'s| is| was) (?P<x>the [a-z]+(?: [a-z]+)?) (?P<pro>she|he)(?:'s| has| had| is| was)? "
    r"(?:asked for|wants|wanted|after|needs|ordered|asked me for)"
    rf"(?:\s*,\s*(?:to|for) (?P<p>{_P46R}))?(?P<end>\s*[.!]?)$",
    _F,
)


def _its_the_asked51r(text: str, lexicon: Lexicon) -> str:
    """Session 51 (12r): a request for one person, a cue (with a 'gosh' after it), then "it's
    the bottle she's asked for(, to P)" (she that person, P said again) is "<request>, no, the
    bottle": the thing corrected."""
    low = text.lower()
    if "it's the" not in low and "it is the" not in low and "it was the" not in low:
        return text
    m = _ITS_THE_ASKED51R.match(text.strip())
    if m is None or not _BACK51R.search(m["cue"]):
        return text
    first = _one_task51r(m["head"], lexicon)
    if first is None or first[0] != "deliver" or not _agrees44r(first[2], m["pro"], lexicon):
        return text
    if m["p"] and _person46r(m["p"], lexicon) != first[2]:
        return text
    out = f"{m['head']}, no, {m['x']}{m['end'] or '.'}"
    fixed = _one_task51r(out, lexicon)
    if fixed is None or fixed[2] != first[2] or fixed[1] == first[1]:
        return text
    return out


# "The chips for Person A, oops, wrong name, I mean Person B, the one with the sabre bag."
_ONE_WITH51R = re.compiled(
    rf"^(?P<head>.+?(?P<p>{_P46R}))\s*,\s*the one (?:with|in|wearing|carrying|holding|who|that|"
    r"from|by)\b(?P<why>[^,.;!?]*)(?P<end>\s*[.!]?)$",
    _F,
)


def _one_with51r(text: str, lexicon: Lexicon) -> str:
    """Session 51 (12r): a correction to a person closed by "P, the one with the sabre bag" (who
    P is, naming nothing of the scene) is the correction without it."""
    if "the one " not in text.lower():
        return text
    m = _ONE_WITH51R.match(text.strip())
    if m is None or not _BACK51R.search(m["head"]):
        return text
    pid = _person46r(m["p"], lexicon)
    if pid is None or not _about50r(m["why"], {pid}, lexicon) or _DONE_HEAD51R.search(m["why"]):
        return text
    out = f"{m['head']}{m['end'] or '.'}"
    fixed = _one_task51r(out, lexicon)
    if fixed is None or fixed[2] != pid:
        return text
    return out


# "The bottle to Person A, yes, I've checked the rota twice, Person A."
_YES_AGAIN51R = re.compiled(
    rf"^(?P<head>.+?(?P<p>{_P46R}))\s*,\s*(?:yes|yep|yeah|aye|that's right|that's correct|"
    r"correct)\s*,\s*(?P<why>[^,.;!?]+?)\s*,\s*(?P<again>[^,.;!?]+?)(?P<end>\s*[.!]?)$",
    _F,
)


def _yes_again51r(text: str, lexicon: Lexicon) -> str:
    """Session 51 (12r): a request, then 'yes', a remark of the speaker's naming nothing of the
    scene, then the same person again ("The bottle to Person A, yes, I've checked the rota twice,
    Person A."): it says the request again, and is taken off."""
    low = text.lower()
    if not any(w in low for w in ("yes", "yep", "yeah", "aye", "right", "correct")):
        return text
    m = _YES_AGAIN51R.match(text.strip())
    if m is None:
        return text
    pid = _person46r(m["p"], lexicon)
    if pid is None or _person46r(m["again"], lexicon) != pid:
        return text
    why = m["why"]
    if _names(why, lexicon) or _NEGATED42S.search(why) or _WANT_SAID41S.search(why):
        return text
    out = f"{m['head']}{m['end'] or '.'}"
    fixed = _one_task51r(out, lexicon)
    if fixed is None or fixed[2] != pid:
        return text
    return out


# -- 12c's fuzz: a choice of people said to have (had) a thing ----------------------------------

# "Alice or Bob had the crisps.", "Alice or Bob, whichever of the two, has the crisps.", "Either
# Alice or Carol had the red mug."
_PEOPLE_HAD51R = re.compiled(
    rf"(?:^|(?<=[.;!?])\s*)(?:either |one of )?(?P<people>{_P46R}(?:\s*,\s*{_P46R})*\s*,?\s*or "
    rf"{_P46R})(?:\s*,\s*(?:whichever|either|one|whoever)(?: (?:of (?:the|them) (?:two|three|"
    r"both)|of them|one|it was|it is))?\s*,)?\s+(?P<v>had|got|has|has had|has got|'s got|'s had|"
    r"have|had got)\s+(?!to\b)(?P<x>[^,.;!?]+?)\s*(?=[.;!?,]|$)",
    _F,
)


def _people_had51r(text: str, lexicon: Lexicon) -> None:
    """Session 51 (12r): a sentence that is only a choice of people holding (having held) things
    ("Alice or Bob had the crisps", "…, whichever of the two, has the crisps") says what one of
    them holds or held: it asks for nothing, as session 32's "Alice had the crisps." (the
    grammar had read it as the robot's choice of who gets them: 12c's fuzz): refused."""
    low = text.lower()
    if " or " not in low or not any(w in low for w in ("had", "has", "got", "have", "'s")):
        return
    for m in _PEOPLE_HAD51R.finditer(text):
        who = [w.strip() for w in re.split(r"\s*,\s*|\s+or\s+", m["people"], flags=_F)]
        if any(_person46r(w, lexicon) is None for w in who if w):
            continue
        named = _names(m["x"], lexicon)
        if not named or any(r.kind != "object" for it in named for r in it.refs):
            continue
        raise GroundingError(
            f"{m.group(0).strip()!r} says what one of {m['people']} holds or had: it asks for "
            f"nothing; say who is to get {m['x'].strip()} to have it handed over"
        )


# -- 12c's fuzz: correction chains ---------------------------------------------------------------

# "The globe to Zoe, no, Noah, well, the ruler.": after a correction, a bare thing after 'well'
_WELL_AGAIN51R = re.compiled(
    r"\b(?:no|sorry|i mean|i meant|rather|wait|hang on|hold on|scratch that|oops|whoops|my "
    r"mistake)\b[^.;!?]*,\s*well\s*,?\s*(?P<x>the [a-z]+(?: (?!(?:actually|instead|too|also|"
    r"then|please)\b)[a-z]+)?)\s*[.!]?\s*$",
    _F,
)


def _well_again51r(text: str, lexicon: Lexicon) -> None:
    """Session 51 (12r): after a correction, "…, well, the ruler" with nothing after the thing
    (no 'actually', 'instead', 'too') could correct the request again or add to it (the grammar
    had added it: "The globe to Zoe, no, Noah, well, the ruler." read globe>B & ruler>B, 12c's
    fuzz): refused. With 'actually' it is the correction sessions 48-49 read."""
    if "well" not in text.lower():
        return
    m = _WELL_AGAIN51R.search(text)
    if m is None:
        return
    named = _names(m["x"], lexicon)
    if not named or any(r.kind != "object" for it in named for r in it.refs):
        return
    words = m["x"].lower().split()[1:]
    if len(words) > 1 and not any(
        " ".join(words) in {o.category.lower(), *(a.lower() for a in o.aliases)}
        for o in lexicon.scene.objects
    ):
        return  # "well, the pills actualy": a word after the thing, not a name of two words
    raise GroundingError(
        f"'well, {m['x']}' after a correction could correct it again or add to it: say "
        f"'{m['x']} instead' or '{m['x']} too'"
    )


def _instead_twice51r(text: str, node: Node, lexicon: Lexicon) -> None:
    """Session 51 (12r): a reading that does two things with one object, of a text that says
    'instead' (one replaces the other: "Small spanner in the locker, no, the torch, no, the
    workbench, well, give it to Kofi instead." had read torch@bench & torch>A, 12c's chains
    fuzz): refused."""
    if "instead" not in text.lower():
        return
    seen: set[str] = set()
    for t in tasks(node):
        if t.obj in seen:
            raise GroundingError(
                f"'instead' says one task replaces another, but the {t.obj} would be moved "
                "twice: say the whole request again"
            )
        seen.add(t.obj)


# "… Thank you very much, really, and the chips, no, Person B, well, the cup actually."
_AND_THEN_WHO51R = re.compiled(
    rf"\band (?P<x>the [a-z]+(?: [a-z]+)?)\s*,\s*{_CUE51R}(?P<p>{_P46R})\s*,\s*well\s*,?\s*"
    r"(?P<z>the [a-z]+(?: [a-z]+)?)\s+actually\b",
    _F,
)


def _and_then_who51r(text: str, lexicon: Lexicon) -> None:
    """Session 51 (12r): "<request for P>, and the X, no, Q, well, the Z actually": the
    correction to Q may be of the whole request or of 'the X' alone, and the Z may replace either
    thing (12c's chains fuzz: with a 'really,' or '— scratch that,' before it, it had read the
    first thing as Q's too): refused, as session 48 refuses it said plainly."""
    if "actually" not in text.lower() or "well" not in text.lower():
        return
    m = _AND_THEN_WHO51R.search(text)
    if m is None:
        return
    pid = _person46r(m["p"], lexicon)
    before = _ids(text[: m.start()], lexicon, "human")
    if pid is None or not before - {pid}:
        return
    raise GroundingError(
        f"{m['p']!r} after '{m['x']}' could correct who gets everything before it or only "
        f"{m['x']}, and {m['z']!r} could replace either thing: say the whole request again"
    )


# "Either Alice or Bob wants the crisps.", "Alice or Bob needed the crisps."
_WHO_WANTS51R = re.compiled(
    rf"(?:^|(?<=[.;!?])\s*)(?:either )?(?P<people>{_P46R}(?:\s*,\s*{_P46R})*\s*,?\s*or {_P46R})"
    r"(?:\s*,\s*(?:i think|i reckon|i'm not sure which|not sure which)\s*,)?\s+(?P<v>wants|needs|"
    r"wanted|needed|asked for|is after|was after|would like|'d like|asked me for|is asking for|"
    r"was asking for)\b",
    _F,
)


def _who_wants51r(text: str, node: Node, lexicon: Lexicon) -> None:
    """Session 51 (12r): "Either Alice or Bob wants the crisps" says one of them wants it, but
    not which (the speaker does not know: not a choice left to the robot, which "Alice or Bob can
    have the crisps" is): a reading that hands it to one of them is refused naming them (12c's
    fuzz)."""
    if " or " not in text.lower() or not has_choice(node):
        return
    m = _WHO_WANTS51R.search(text)
    if m is None:
        return
    who = [w for w in re.split(r"\s*,\s*|\s+or\s+", m["people"], flags=_F) if w.strip()]
    pids = [_person46r(w, lexicon) for w in who]
    if any(p is None for p in pids) or len(set(pids)) < 2:
        return
    got = {t.target for t in tasks(node) if t.kind == "deliver"}
    if not got <= set(pids) or len(got) < 2:
        return
    names = " or ".join(
        f"{h.name}" + (f" ({', '.join(h.aliases)})" if h.aliases else "")
        for pid in pids
        for h in lexicon.scene.humans
        if h.id == pid
    )
    raise GroundingError(
        f"'{m['people']} {m['v']}' does not say which of them: it could mean {names}; name the "
        "person"
    )


# "Alice take everything except crisps lah, no, Bob, well, put it on the shelf instead."
_EXCEPT51R = re.compiled(
    r"\b(?:except(?: for)?|apart from|other than|excluding|bar|save for|but not|besides)\s+"
    r"(?P<x>(?:the |that |those |her |his )?[a-z]+(?: [a-z]+)?)",
    _F,
)


def _excluded_back51r(text: str, node: Node, lexicon: Lexicon) -> None:
    """Session 51 (12r): a reading that moves a thing the text leaves out ("everything except
    crisps") where the rest goes, when nothing after the exclusion names that thing again (12c's
    chains fuzz: with a 'lah' after it, a correction had lost the 'except' and put the crisps on
    the shelf too): refused."""
    low = text.lower()
    if not any(
        w in low
        for w in (
            "except",
            "apart",
            "other than",
            "excluding",
            "bar ",
            "save",
            "but not",
            "besides",
        )
    ):
        return
    got = list(tasks(node))
    for m in _EXCEPT51R.finditer(text):
        left = {r.id for it in _names(m["x"], lexicon) for r in it.refs if r.kind == "object"}
        # an excluded thing going where the rest goes ("…, apart from the apple, which Person B
        # gets" sends it elsewhere, as said)
        rest = {t.target for t in got if t.obj not in left}
        back = {t.obj for t in got if t.obj in left and t.target in rest}
        if not back or back & _ids(text[m.end() :], lexicon, "object"):
            continue
        raise GroundingError(
            f"'{m.group(0)}' leaves out what the reading would move: say the whole request again"
        )


# "Give Person A the chips, sorry, not the apple, the cup."
_NOT_SAID51R = re.compiled(
    r"\b(?:sorry|no|oops|whoops|wait|i mean|i meant)\s*,\s*not (?P<x>(?:the )?[a-z]+(?: [a-z]+)?)"
    r"\s*,",
    _F,
)


def _not_said51r(text: str, lexicon: Lexicon) -> None:
    """Session 51 (12r): a correction "sorry, not the apple, the cup" that takes back a thing the
    request never said takes back nothing said: refused (session 34's refusal had held only by
    session 19's cue search reading 'no' + 't' of 'not', which the word end of 44131cb9 mends)."""
    if "not " not in text.lower():
        return
    for m in _NOT_SAID51R.finditer(text):
        said = _ids(m["x"], lexicon, "object")
        if said and not said & _ids(text[: m.start()], lexicon, "object"):
            raise GroundingError(
                f"'not {m['x']}' takes back nothing the request said: say the whole request again"
            )


# the normaliser's first rewrites (wired into normalise._STEPS19, before the session-50 ones)
_STEPS51R_FIRST: tuple[Callable[[str, Lexicon], str], ...] = ()
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-50 ones)
_STEPS51R: tuple[Callable[[str, Lexicon], str], ...] = (
    _front_choice51r,
    _likes_both51r,
    _not_a51r,
    _pick_of51r,
    _so_long_as51r,
    _would_suit51r,
    _both_comma51r,
    _asked_one_of51r,
    _all_there_is51r,
    _one_in_here51r,
    _only_one51r,
    _both_of_them51r,
    _listed51r,
    _each_have51r,
    _taking_to51r,
    _too_warm51r,
    _nobody_sulks51r,
    _any_one_on51r,
    _clearing51r,
    _had_enough51r,
    _earned51r,
    _left_a51r,
    _they_share51r,
    _why_fix51r,
    _kept_on51r,
    _the_one_is51r,
    _she_said_make51r,
    _its_the_asked51r,
    _one_with51r,
    _yes_again51r,
)
# refusals asked of the text before it is read (offline._parse, after the session-50 ones)
REFUSE51R: tuple[Callable[[str, Lexicon], None], ...] = (
    _people_had51r,
    _well_again51r,
    _and_then_who51r,
    _not_said51r,
)
# checks of the whole instruction's reading (offline.parse_instruction, after the session-50 ones)
CHECK51R: tuple[Callable[[str, Node, Lexicon], None], ...] = (
    _owner_said51r,
    _instead_twice51r,
    _done_after51r,
    _who_wants51r,
    _excluded_back51r,
)
