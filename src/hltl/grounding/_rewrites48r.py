"""The grounder's rules of session 48, engineer 12r (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _ids, _reading
from hltl.grounding._rewrites42s import _remark_only42s
from hltl.grounding._rewrites44r import _agrees44r, _read_or44r
from hltl.grounding._rewrites46r import (
    _P46R,
    _closing46r,
    _dropped46r,
    _each_pronoun46r,
    _person46r,
)
from hltl.grounding._rewrites47r import _DOUBT47R, _claimed47r
from hltl.grounding.lexicon import Lexicon, lex
from hltl.grounding.phrasing import _chained48r
from hltl.grounding.tree import Node, Task, has_choice, tasks

# -- a second correction of one of two ---------------------------------------------------------


def second_fix48r(text: str, lexicon: Lexicon) -> None:
    """Session 48 (12r; 12c's `chains` fuzz): the grammar's refusal of a second correction that
    names one thing alone where the request named two of its kind (`phrasing._chained48r`),
    asked before the text is read: a rewrite of the words around it ('no, Noah' taken for a
    stutter) had read "…, and the glue stick, no, Noah, well, the scissors actually." as the
    scissors for the glue stick."""
    low = text.lower()
    if sum(low.count(w) for w in ("no", "sorry", "actually", "mean", "rather", "wait")) < 2:
        return
    try:
        items = lex(text, lexicon)
    except GroundingError:
        return
    _chained48r(items)


# -- one of the two, which not said (blind46) ---------------------------------------------------

# "Person A asked for one of the two, I just can't remember which one she said.", "Zoe was reading
# one of the two books before break, and she wants that one back."
_ONE_OF_TWO48R = re.compiled(
    rf"\bone of the (?:two|pair)(?: (?P<k>[a-z]+s))?\b[^,;.!?]*?\s*[,;]\s*(?:and |but )?"
    rf"(?:(?P<said>(?:i |i just |i really )?[^,;.!?]*?\b(?:{_DOUBT47R})\b[^,;.!?]*?)|"
    r"(?P<that>(?:she|he|they)(?:'d like| wants| needs| would like)(?: to have)? that one"
    r"(?: back| again)?))(?=\s*[.!]?$)",
    _F,
)


def one_of_two48r(text: str, lexicon: Lexicon) -> None:
    """Session 48 (12r): "P asked for one of the two, I just can't remember which one" ("P was
    reading one of the two books …, and she wants that one back"): the two are the scene's two
    things (of that kind); which one is not said: refused naming both."""
    low = text.lower()
    if "one of the two" not in low and "one of the pair" not in low:
        return
    m = _ONE_OF_TWO48R.search(text)
    if m is None:
        return
    if m["k"]:
        ids = _ids(f"the {m['k']}", lexicon, "object")
    else:
        ids = {o.id for o in lexicon.scene.objects}
    if len(ids) != 2:
        return
    said = (m["said"] or m["that"]).strip()
    raise GroundingError(
        f"{said!r}: which one is meant is not said; it could be {' or '.join(sorted(ids))}: name "
        "the one"
    )


# -- someone else is to do it ---------------------------------------------------------------------

# "Bob will be given the apple by Alice.", "Bob's to be handed the cup by Carol."
_GIVEN_BY48R = re.compiled(
    r"\b(?:be|being|get|gets|getting)\s+(?:given|handed|passed|brought|taken|sent|fetched|"
    r"delivered|lent|tossed|thrown)\b[^.;!?]*?\s(?P<by>by\s+(?P<who>[a-z][\w ]*?))"
    r"(?=\s*(?:[,.;!?]|$))",
    _F,
)


def given_by48r(text: str, lexicon: Lexicon) -> None:
    """Session 48 (12r; the lead's decision): "Bob will be given the apple by Alice." says Alice
    is to give it, as "Alice will give Bob the apple." does (refused: the robots deliver); it had
    read as the robots' delivery. Refused naming the giver ('by' a person of the scene only:
    "… by the shelf" is where)."""
    low = text.lower()
    if " by " not in low or ("be" not in low and "get" not in low):
        return
    for m in _GIVEN_BY48R.finditer(text):
        who = _person46r(m["who"], lexicon)
        if who is None:
            continue
        raise GroundingError(
            f"{m['by']!r} says {m['who']} ({who}) is to hand it over, not the robots: say what "
            "the robots are to do"
        )


# -- a correction that could say where the thing is -----------------------------------------------

# "Marco wants the salt, no, it's on the rack.", "Put the lemon on the rack, no, the lemon's on the
# counter.", "Bob wants the apple, no, it's Carol's."
_WHERE_IT_IS48R = re.compiled(
    r"^(?P<req>[^.;!?]+?)\s*[,.;!]\s*(?:oh\s+)?(?:no|sorry|actually|wait|no wait|no sorry)\s*,?\s*"
    r"(?P<it>it|they|the [a-z]+(?: [a-z]+)?)(?:'s| is|'re| are) (?:(?:on|in|at|inside|on top of|"
    r"in the middle of) (?P<s>the [a-z]+(?: [a-z]+)?)|(?P<q>[a-z]+(?: [a-z]+)?)'s?)\s*[.!]?\s*$",
    _F,
)


_WANTED48R = re.compiled(
    r"\b(?:wants?|wanted|needs?|needed|would like|'d like|asked for|(?:is|'s) after|fancies)\b", _F
)


def where_it_is48r(text: str, lexicon: Lexicon) -> None:
    """Session 48 (12r; the lead's decisions): "Marco wants the salt, no, it's on the rack." could
    tell where the salt is (the want stands: salt>A) or correct the request to a placing
    (salt@rack); "Put the lemon on the rack, no, it's on the counter." where the lemon is or a
    new place; "Bob wants the apple, no, it's Carol's." Carol's want (apple>C) or Carol's apple
    for Bob (someone else's thing: refused since session 7; only after a want: "The chips are for
    Bob, no, they're Carol's." says for whom, session 40). Each refused naming both (they had
    read as the correction: salt@rack, lemon@counter, apple>C). 'it' may be the thing's name
    ("no, the lemon's on the counter"); the request is one task of one thing."""
    low = text.lower()
    if "it" not in low and "they" not in low and "'s" not in low:
        return
    m = _WHERE_IT_IS48R.match(text.strip())
    if m is None:
        return
    asked = _reading(m["req"], lexicon)
    if not isinstance(asked, Task):
        return
    it = m["it"].lower()
    if it not in ("it", "they") and _ids(m["it"], lexicon) != {asked.obj}:
        return
    said = m[0][len(m["req"]) :].strip(" ,.;!")
    was = f"{asked.obj}{'>' if asked.kind == 'deliver' else '@'}{asked.target}"
    if m["s"] is not None:
        place = _ids(m["s"], lexicon)
        if len(place) != 1 or _ids(m["s"], lexicon, "surface") != place:
            return
        if asked.kind == "place" and place == {asked.target}:
            return
        raise GroundingError(
            f"{said!r} after the request could say where it is ({was} as asked) or move it "
            f"there instead ({asked.obj}@{next(iter(place))}): say which"
        )
    who = _person46r(m["q"], lexicon)
    if who is None or asked.kind != "deliver" or who == asked.target:
        return
    if _WANTED48R.search(m["req"]) is None:
        return  # "The chips are for Bob, no, they're Carol's.": for whom (session 40's reading)
    raise GroundingError(
        f"{said!r} after the request could say {m['q']} wants it ({asked.obj}>{who}) or that "
        f"the {asked.obj} is {m['q']}'s ({asked.obj}>{asked.target} as asked, someone else's "
        "thing): say which"
    )


# -- choices left to one person (blind46) -------------------------------------------------------

# a closing remark after a choice handed to one person: an easy-going word ("no preference", "she's
# not fussy after the roller skating"), or one naming nothing of the scene ("running late for the
# night watchman's handover", "she just wants a swig before her lyre lesson")
_EASY48R = re.compiled(
    r"^(?:(?:she|he|they)(?:'s| is|'re| are) (?:not|n't) (?:fussy|fussed|bothered|picky|choosy)|"
    r"(?:she|he|they) (?:isn't|aren't|doesn't mind|don't mind)(?: (?:fussy|fussed|bothered|picky|"
    r"choosy))?|no preference|(?:she|he|they)(?:'s| has| have|'ve) no preference)\b",
    _F,
)
_PRONOUN48R = re.compiled(r"\b(?P<pro>she|he|her|him|his|hers)\b", _F)


# "she just wants a swig before her lyre lesson": what the thing is for, a use of it
_USE48R = re.compiled(
    r"^(?:she|he|they) (?:just |only )?(?:wants?|needs?|could do with|fancies|fancy) (?:a|some) "
    r"(?:swig|sip|drink|bite|nibble|snack|taste|go|look)\b",
    _F,
)


def _choice_for48r(
    head: str, tail: str, end: str, text: str, lexicon: Lexicon, *, choice: bool = True
) -> str:
    """``head`` (a choice handed to one person; one thing when not ``choice``) with the closing
    remarks of ``tail`` (comma parts) taken off, each easy-going, a use of the thing, or naming
    nothing of the scene, its pronouns that person; ``text`` unless that reads so."""
    out = f"{head}{end or '.'}"
    node = _reading(out, lexicon)
    if node is None or has_choice(node) != choice or any(t.kind != "deliver" for t in tasks(node)):
        return text
    people = {t.target for t in tasks(node)}
    if len(people) != 1:
        return text
    pid = next(iter(people))
    for part in (p.strip() for p in tail.split(",") if p.strip()):
        said = _USE48R.sub("", part)
        if _EASY48R.match(part) is None and not _remark_only42s(said, lexicon):
            return text
        if any(not _agrees44r(pid, m["pro"], lexicon) for m in _PRONOUN48R.finditer(part)):
            return text
    return out if out != text else text


# "Person B can take his pick of the cup or the bottle.", "Dana'll take either cup, no
# preference, …", "Sam can grab any of the pens except the red.", "Ava can pick whatever block she
# likes."
_TAKE_PICK48R = re.compiled(
    rf"^(?P<p>{_P46R})(?:'ll| will| can| may| could|'s free to| is free to) (?:take|grab|pick|"
    r"choose|pick out|help (?:him|her)self to)(?: (?:his|her|their) pick of)? (?P<what>(?:either|"
    r"any|whichever|whatever) [a-z]+(?: (?:she|he) (?:likes|wants|fancies|prefers))?|(?:any|one|"
    r"either) of the [a-z]+(?: except (?:for )?the [a-z]+)?|the [a-z]+ or the [a-z]+)"
    r"(?P<tail>(?:\s*,\s*[^,.;!?]+)*?)(?P<end>\s*[.!]?)$",
    _F,
)


def _take_pick48r(text: str, lexicon: Lexicon) -> str:
    """Session 48 (12r): "P can take his pick of the cup or the bottle" ("P'll take either cup",
    "P can grab any of the pens except the red", "P can pick whatever block she likes") is "P can
    have …" (a choice left to P), closing remarks that name nothing taken off."""
    low = text.lower()
    if not any(w in low for w in ("either", "any", "whichever", "whatever", "one of", " or ")):
        return text
    m = _TAKE_PICK48R.match(text.strip())
    if m is None:
        return text
    what = re.sub(r" (?:she|he) (?:likes|wants|fancies|prefers)$", "", m["what"], flags=_F)
    what = re.sub(r"^(?:whichever|whatever) ", "any ", what, flags=_F)
    return _choice_for48r(f"{m['p']} can have {what}", m["tail"], m["end"], text, lexicon)


# "Any bottle will do for Person A, she just wants a swig before her lyre lesson.", "Any one of
# the four will do for Person A, she's not fussy after the roller skating."
_WILL_DO48R = re.compiled(
    rf"^(?P<what>any (?:one of the [a-z]+|[a-z]+(?: [a-z]+)?)) (?:will|would|'ll) do (?:for|"
    rf"nicely for) (?P<p>{_P46R})(?P<tail>(?:\s*,\s*[^,.;!?]+)*?)(?P<end>\s*[.!]?)$",
    _F,
)


def _will_do48r(text: str, lexicon: Lexicon) -> str:
    """Session 48 (12r): "Any bottle will do for P" ("Any one of the four will do for P") is
    "Give P any bottle" (a choice when the scene has more than one; session 35's "any of the pens
    will do for him" is its own), closing remarks that name nothing taken off."""
    if "will do" not in text.lower() and "'ll do" not in text.lower():
        return text
    m = _WILL_DO48R.match(text.strip())
    if m is None or _person46r(m["p"], lexicon) is None:
        return text
    out = f"Give {m['p']} {m['what'][:1].lower()}{m['what'][1:]}"
    one = isinstance(_reading(f"{out}.", lexicon), Task)  # the scene has one: no choice
    return _choice_for48r(out, m["tail"], m["end"], text, lexicon, choice=not one)


# "Person B isn't fussed after his french skipping, the bottle or the crisps, he'll take either."
_NOT_FUSSED48R = re.compiled(
    rf"^(?P<p>{_P46R})(?: isn't| is not|'s not| ain't) (?:fussed|bothered|fussy|picky|choosy)"
    r"(?P<why>[^,;.!?]*)\s*,\s*(?P<what>(?:the [a-z]+(?: [a-z]+)?|either [a-z]+) (?:or|and) (?:the "
    r"[a-z]+(?: [a-z]+)?))\s*,\s*(?P<pro>she|he)(?:'ll| will|'d| would) (?:take|have|go for) "
    r"(?:either|either one|whichever|any)(?P<end>\s*[.!]?)$",
    _F,
)


def _not_fussed48r(text: str, lexicon: Lexicon) -> str:
    """Session 48 (12r): "P isn't fussed (after his french skipping), the bottle or the crisps,
    he'll take either" is "P can have the bottle or the crisps" (the pronoun P, the reason naming
    nothing of the scene)."""
    if "either" not in text.lower() and "whichever" not in text.lower():
        return text
    m = _NOT_FUSSED48R.match(text.strip())
    if m is None or (m["why"].strip() and not _remark_only42s(m["why"], lexicon)):
        return text
    pid = _person46r(m["p"], lexicon)
    if pid is None or not _agrees44r(pid, m["pro"], lexicon):
        return text
    what = re.sub(r"\band\b", "or", m["what"], flags=_F)
    return _choice_for48r(f"{m['p']} can have {what}", "", m["end"], text, lexicon)


# -- one thing each (blind46) --------------------------------------------------------------------

# "Each of them gets one thing on the way to the etch a sketch contest, Person A the cup and Person
# B the bottle.", "Both of them are worn out after the psaltery recital, so each gets something:
# the bottle to Person A and the chips to Person B.", "Both people need a drink: the bottle to
# Person A and the cup to Person B."
_EACH_LEAD48R = re.compiled(
    r"^(?:each of them|both of them|both people|the two of them|the pair of them)\b"
    r"(?P<mid>[^:;]*?)\b(?:gets?|needs?|wants?|(?:is|are|'s|'re) getting|(?:is|are|'s|'re) having|"
    r"could do with|deserves?) (?:one thing|something|a thing|one|an? (?P<k>[a-z]+))"
    r"(?P<why>[^:;,]*?)\s*[:;,]\s*(?P<rest>[^:;]+?)(?P<end>\s*[.!]?)$",
    _F,
)
# what a lead-in may call the things without naming a kind of the scene
_GENERIC48R = frozenset({"drink", "snack", "treat", "bite", "present", "bit", "thing"})


def _each_lead48r(text: str, lexicon: Lexicon) -> str:
    """Session 48 (12r): a lead-in saying each of them (both people) gets one thing ("Each of
    them gets one thing on the way to …", "Both of them are worn out after …, so each gets
    something", "Both people need a drink") before the handing out said whole, each person named:
    the handing out, when it hands two or more people one thing each, the lead-in names nothing
    of the scene, and a kind it says ('a plate') is the things' kind ('a drink' is no kind)."""
    low = text.lower()
    if "each" not in low and "both" not in low and "two of them" not in low and "pair" not in low:
        return text
    m = _EACH_LEAD48R.match(text.strip())
    if m is None:
        return text
    mid = re.sub(r",?\s*so (?:each|they each|both)(?: of them)?\s*$", "", m["mid"], flags=_F)
    if re.search(r"\b(?:each|both)\b", mid, _F):
        return text
    if not all(_remark_only42s(w, lexicon) for w in (mid, m["why"]) if w.strip()):
        return text
    k = (m["k"] or "").lower()
    rest = m["rest"].strip()
    for out in (f"{rest[:1].upper()}{rest[1:]}{m['end'] or '.'}", f"Give {rest}{m['end'] or '.'}"):
        node = _reading(out, lexicon)
        if node is None:
            continue
        got = list(tasks(node))
        people = [t.target for t in got]
        if has_choice(node) or any(t.kind != "deliver" for t in got):
            return text
        if len(got) < 2 or len(set(people)) != len(people):
            return text
        if set(people) != {h.id for h in lexicon.scene.humans}:
            return text  # 'each of them' / 'both' are everyone the scene holds (session 33's test)
        cats = {o.id: o.category for o in lexicon.scene.objects}
        if k and k not in _GENERIC48R and any(cats.get(t.obj) != k for t in got):
            return text
        return out
    return text


# "Marco and Lena both want a plate: white for him and blue for her."
_BOTH_WANT48R = re.compiled(
    rf"^(?P<p>{_P46R}) and (?P<q>{_P46R}) (?:both|each) (?:want|need|get|are getting|'re getting|"
    r"are having|'re having|would like|'d like) an? (?P<k>[a-z]+)\s*[:;,]\s*(?:the )?(?P<a>[a-z]+)"
    r"(?: one)? (?P<to>for|to) (?P<pa>her|him)\s*(?:,\s*(?:and )?|and )(?:the )?(?P<b>[a-z]+)"
    r"(?: one)? (?:for|to) (?P<pb>her|him)(?P<end>\s*[.!]?)$",
    _F,
)


def _both_want48r(text: str, lexicon: Lexicon) -> str:
    """Session 48 (12r): "P and Q both want a plate: white for him and blue for her" is session
    46's "P and Q each want one thing: the white plate for him, the blue plate for her", read by
    `_each_pronoun46r` (each pronoun one of the two and not the other)."""
    if "both" not in text.lower() and "each" not in text.lower():
        return text
    m = _BOTH_WANT48R.match(text.strip())
    if m is None:
        return text
    k = m["k"]
    out = (
        f"{m['p']} and {m['q']} each want one thing: the {m['a']} {k} {m['to']} {m['pa']}, "
        f"the {m['b']} {k} {m['to']} {m['pb']}{m['end'] or '.'}"
    )
    done = _each_pronoun46r(out, lexicon)
    return text if done == out else done


# "Put one of the boxes on the belt, the small or the medium, whichever's handier."
_ONE_OF_WHICH48R = re.compiled(
    r"\bone of the (?P<ks>[a-z]+s)\b(?P<mid>[^,;.!?]*?)\s*,\s*the (?P<a>[a-z]+)(?: one)? or the "
    r"(?P<b>[a-z]+)(?: one)?(?:\s*,\s*whichever(?:'s| is) (?:handier|handiest|nearer|nearest|"
    r"closer|closest|easier|easiest|quicker|to hand|nearest to hand))?(?P<end>\s*[.!]?)$",
    _F,
)


def _one_of_which48r(text: str, lexicon: Lexicon) -> str:
    """Session 48 (12r): "one of the boxes …, the small or the medium(, whichever's handier)" is
    "the small box or the medium box …": each word with the kind one thing of the scene, the two
    not the same."""
    if "one of the" not in text.lower():
        return text
    m = _ONE_OF_WHICH48R.search(text.strip())
    if m is None:
        return text
    ks = m["ks"]
    kind = ks[:-2] if ks.lower().endswith(("xes", "ches", "shes", "sses")) else ks[:-1]
    a, b = _ids(f"the {m['a']} {kind}", lexicon), _ids(f"the {m['b']} {kind}", lexicon)
    if len(a) != 1 or len(b) != 1 or a == b or _ids(f"the {m['a']} {kind}", lexicon, "object") != a:
        return text
    t = text.strip()
    out = f"{t[: m.start()]}the {m['a']} {kind} or the {m['b']} {kind}{m['mid']}{m['end'] or '.'}"
    return _read_or44r(out, text, lexicon)


# "Both cups into the sink, please, the constable left cold tea in them."
_LEFT_IN48R = re.compiled(
    r"\s*,\s*(?P<said>(?:the [a-z]+(?: [a-z]+)?|someone|somebody|[A-Z][a-z]+) (?:left|spilt|"
    r"spilled|poured|dropped|put) [^,;.!?]+? (?:in|on|inside|all over) (?:them|it))"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _left_in48r(text: str, lexicon: Lexicon) -> str:
    """Session 48 (12r): a closing reason "the constable left cold tea in them" (what someone
    left in or on the things, naming nothing of the scene) after a placing is taken off."""
    if " left " not in text.lower() and " spil" not in text.lower():
        return text
    m = _LEFT_IN48R.search(text.strip())
    if m is None:
        return text
    said = re.sub(r"\b(?:them|it)$", "", m["said"], flags=_F)
    if not _remark_only42s(said, lexicon):
        return text
    out = f"{text.strip()[: m.start()]}{m['end'] or '.'}"
    node = _reading(out, lexicon)
    if node is None or any(t.kind != "place" for t in tasks(node)):
        return text
    return out


# -- blind46: corrections -------------------------------------------------------------------------

_CUE48R = (
    r"(?:(?:oh|ah|er|um|no|sorry|actually|wait|hang on|hold on|oh no|no sorry|no wait)\s*,?\s*)+"
)

# "Bottle to Person A, sorry, I meant Person B, I've got the constable on the other line."
_ON_THE_LINE48R = re.compiled(
    r"\s*,\s*(?:(?:sorry|sorry about that)\s*,\s*)?I(?:'ve| have)(?: got)? (?P<who>(?:the|a|an|my) "
    r"[a-z]+(?: [a-z]+)?) (?:on the (?:other )?(?:line|phone)|on hold|in my ear|at the door)"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _on_the_line48r(text: str, lexicon: Lexicon) -> str:
    """Session 48 (12r): a closing "I've got the constable on the other line" (why the speaker
    slipped; naming nothing of the scene) is taken off."""
    if "i've" not in text.lower() and "i have" not in text.lower():
        return text
    said = _closing46r(_ON_THE_LINE48R, text)
    if said is None or not _remark_only42s(said[1]["who"], lexicon):
        return text
    return _dropped46r(*said, text, lexicon)


# "The chips for Person B, oh no hang on, the bottle for Person B."
_SAID_AGAIN_FOR48R = re.compiled(
    rf"^(?P<head>[^,;]+? (?:for|to) (?P<p>{_P46R}))\s*,\s*(?P<cue>{_CUE48R})"
    rf"(?P<y>the [a-z]+(?: [a-z]+)?) (?:for|to) (?P<q>{_P46R})(?P<end>\s*[.!]?)$",
    _F,
)


def _said_again_for48r(text: str, lexicon: Lexicon) -> str:
    """Session 48 (12r): "X for P, oh no hang on, the Y for P" (the same person said again) is
    "X for P, oh no hang on, the Y"."""
    low = text.lower()
    if low.count(" for ") + low.count(" to ") < 2:
        return text
    m = _SAID_AGAIN_FOR48R.match(text.strip())
    if m is None:
        return text
    p = _person46r(m["p"], lexicon)
    if p is None or _person46r(m["q"], lexicon) != p or len(_ids(m["y"], lexicon, "object")) != 1:
        return text
    out = f"{m['head']}, {m['cue'].strip().rstrip(',')}, {m['y']}{m['end'] or '.'}"
    return _read_or44r(out, text, lexicon)


# "Cup to Person A, no, actually, she'd rather the apple, she's just had a brew at …"
_RATHER48R = re.compiled(
    rf"(?P<cue>,\s*{_CUE48R})(?P<pro>she|he)(?:'d| would) (?:rather|prefer|sooner)(?: have)? "
    r"(?=(?:the|a|an) [a-z]+)",
    _F,
)


def _rather48r(text: str, lexicon: Lexicon) -> str:
    """Session 48 (12r): after a request for one person, a cue, then "she'd rather the apple" is
    the cue and "the apple" (the pronoun that person); a closing remark naming nothing of the
    scene, its pronoun that person, is taken off ("she's just had a brew at …")."""
    if "rather" not in text.lower() and "prefer" not in text.lower():
        return text
    m = _RATHER48R.search(text)
    if m is None:
        return text
    first = _reading(f"{text[: m.start()]}.", lexicon)
    if not isinstance(first, Task) or first.kind != "deliver":
        return text
    if not _agrees44r(first.target, m["pro"], lexicon):
        return text
    out = f"{text[: m.start()]}{m['cue']}{text[m.end() :]}"
    # the plain "…, no, she'd rather the apple" is session 40's (s40r); this rule reads it only
    # with a closing remark after the thing
    rest = re.match(
        r"^(?P<head>.*?,\s*the [a-z]+(?: [a-z]+)?)\s*,\s*(?P<tail>[^,]+?)(?P<end>\s*[.!]?)$",
        out,
        _F,
    )
    if rest is None or not _remark_only42s(rest["tail"], lexicon):
        return text
    if any(
        not _agrees44r(first.target, x["pro"], lexicon) for x in _PRONOUN48R.finditer(rest["tail"])
    ):
        return text
    return _read_or44r(f"{rest['head']}{rest['end'] or '.'}", text, lexicon)


# "The bottle stays put, oh, hold on, Person A's asking for it after all, so give it her."
_ASKING_AFTER_ALL48R = re.compiled(
    r"(?:'s| is) (?:asking|calling|shouting) for (?P<it>it|them) after all\b", _F
)


def _asking_after_all48r(text: str, lexicon: Lexicon) -> str:
    """Session 48 (12r): "…, hold on, P's asking for it after all, so give it her" is session
    47's "P's just asked for it, so …" (`_claimed47r` reads it)."""
    if "after all" not in text.lower():
        return text
    out = _ASKING_AFTER_ALL48R.sub(r"'s just asked for \g<it>", text, count=1)
    if out == text:
        return text
    done = _claimed47r(out, lexicon)
    return text if done == out else done


# "Tongs to Marco, no sorry, my head's all over the place, to Lena, she's plating the salads."
_SCATTERED48R = re.compiled(
    r"(?P<cue>,\s*(?:no|sorry|no sorry|oops|whoops)\s*,?\s*)(?:my head(?:'s| is) all over the "
    r"place|i'm all at sea|what am i like|my brain's a sieve|i'm in a muddle)\s*,\s*",
    _F,
)


def _scattered48r(text: str, lexicon: Lexicon) -> str:
    """Session 48 (12r): an apology for one's muddle between the cue and the correction ("no
    sorry, my head's all over the place, to Lena") is taken off; a closing remark of the person
    corrected to is then left to the older rules. ("I'm all over the place" and "silly me" are
    session 40's `_blame40r`'s: two rules must not read one sentence.)"""
    low = text.lower()
    if "place" not in low and "sea" not in low and "like" not in low and "sieve" not in low:
        return text
    return _read_or44r(_SCATTERED48R.sub(r"\g<cue>", text, count=1), text, lexicon)


# the normaliser's first rewrites (wired into normalise._STEPS19, before the session-47 ones)
_STEPS48R_FIRST: tuple[Callable[[str, Lexicon], str], ...] = ()
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-47 ones)
_STEPS48R: tuple[Callable[[str, Lexicon], str], ...] = (
    _take_pick48r,
    _will_do48r,
    _not_fussed48r,
    _each_lead48r,
    _both_want48r,
    _one_of_which48r,
    _left_in48r,
    _on_the_line48r,
    _said_again_for48r,
    _rather48r,
    _asking_after_all48r,
    _scattered48r,
)
# refusals asked of the text before it is read (offline._parse, after the session-47 ones)
REFUSE48R: tuple[Callable[[str, Lexicon], None], ...] = (
    second_fix48r,
    one_of_two48r,
    given_by48r,
    where_it_is48r,
)
# checks of the whole instruction's reading (offline.parse_instruction, after the session-47 ones)
CHECK48R: tuple[Callable[[str, Node, Lexicon], None], ...] = ()
