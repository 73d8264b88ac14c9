"""The grounder's rules of session 42, engineer 12s (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _KEEP_WORDS, _ids, _names, _only_person, _reading
from hltl.grounding._normalise4 import _DOING37, _EVENTS37, _fit36
from hltl.grounding._rewrites41s import _ORDER41S, _WANT_SAID41S, _clause41s
from hltl.grounding.lexicon import Lexicon, person_name
from hltl.grounding.tree import Node, tasks

# -- session 42 (12s): someone else's occasion after a want ------------------------------------
#
# "Bob needs the cup after her match." had read cup>B (session 34's `_after_doing34` took 'after
# her match' off as what made him want it): 'her' is not Bob, so the match is someone else's and
# says WHEN he needs it (a time the cell cannot wait on), not why. 'after' / 'following' + his /
# her + words naming nothing of the scene, closing a clause that tells of a want of one person the
# pronoun cannot be: refused, naming whom the pronoun could be (or that it is no one of the scene).
_ELSES_AFTER42S = re.compile(
    r"\b(?:after|following) (?P<pron>his|her) (?P<what>[a-z][a-z-]*(?: [a-z][a-z-]*){0,3}?)"
    r"(?=\s*(?:[.,;:!?]|$)|\s+(?:and|so|but|please|then|thanks)\b)",
    _F,
)


def _elses_after42s(text: str, lexicon: Lexicon) -> None:
    """Session 42 (12s): 'after his / her <doing>' beside the want of a person the pronoun
    cannot be, refused (above)."""
    if " after " not in text.lower() and " following " not in text.lower():
        return
    for m in _ELSES_AFTER42S.finditer(text):
        if _names(m["what"], lexicon):
            continue
        clause = _clause41s(text[: m.start()])
        people = _ids(clause, lexicon, "human")
        if len(people) != 1 or not _WANT_SAID41S.search(clause):
            continue
        (pid,) = people
        pron = m["pron"].lower()
        if _fit36(pid, pron, lexicon):
            continue
        said = m.group(0).strip()
        who = person_name(pid, lexicon)
        others = [
            person_name(h.id, lexicon)
            for h in lexicon.scene.humans
            if h.id != pid and _fit36(h.id, pron, lexicon)
        ]
        if others:
            whose = " or ".join(f"{o}'s" for o in others)
            raise GroundingError(
                f"{pron!r} in {said!r} is not {who}: it may be {whose}, which says when {who} "
                f"wants it, not why; say when, or name whose {m['what']} it is"
            )
        raise GroundingError(
            f"{pron!r} in {said!r} is not {who}, and no one else of the scene: say whose "
            f"{m['what']} it is"
        )


# -- session 42 (12s): a remark of the person's state or doing, then 'and' + their want ------------
#
# "Mrs Khan is feeling the chill and would love the blue blanket.", "Tom's been loading vans since
# dawn and could use the gloves": what the person is or does (words naming nothing of the scene,
# no want, no negation, nothing counted, chosen or pointed back at), then 'and' + a want with the
# same subject left unsaid: the remark goes, the person kept ("Mrs Khan would love …").
_P42S = r"(?:Person [a-z]|(?:mrs|mr|ms|miss|dr) [a-z]+|[a-z]+)"
_STATE_AND42S = re.compile(
    rf"^(?P<lead>(?:(?:oh|so|well|right|ok|okay|now)\s*,?\s+)*)(?P<who>{_P42S})(?:'s|\s+(?:is|"
    r"has|was|had))\s+(?P<words>[a-z][^.;:!?,]{2,80}?),?\s+and\s+(?P<want>(?:would|'d)\s+(?:love|"
    r"like|welcome|be glad of|kill for)|wants|needs|could (?:really )?(?:use|do with|murder)|"
    r"fancies|(?:is|'s) (?:after|gasping for|dying for|desperate for|craving|asking for)|"
    r"has asked for|asked for)\b",
    _F,
)
_NEGATED42S = re.compile(r"\b(?:not|no|never|nothing|nobody|none)\b|n't\b", _F)
_NEED_STATE42S = re.compile(
    r"\b(?:hungry|thirsty|parched|starving|peckish|famished|ravenous|gasping|dry)\b", _F
)


def _remark_only42s(words: str, lexicon: Lexicon) -> bool:
    """Whether ``words`` of a remark name nothing of the scene, want nothing, negate nothing and
    count, choose or point back at nothing."""
    return not (
        _names(words, lexicon)
        or _WANT_SAID41S.search(words)
        or _NEGATED42S.search(words)
        or _KEEP_WORDS.search(re.sub(r"\b(?:his|her|their)\b", "", words, flags=_F))
    )


def _state_and42s(text: str, lexicon: Lexicon) -> str:
    """Session 42 (12s): the remark above taken off, when what is left reads."""
    if " and " not in text.lower():
        return text
    m = _STATE_AND42S.match(text)
    if m is None or not _only_person(m["who"], lexicon):
        return text
    # a need of the same person ('parched', 'starving') is what the want says: not another want
    if not _remark_only42s(_NEED_STATE42S.sub("", m["words"]), lexicon):
        return text
    (pid,) = _ids(m["who"], lexicon, "human")
    if not _fit36(pid, m["words"], lexicon):
        return text
    out = f"{m['lead']}{m['who']} {m['want']}{text[m.end() :]}"
    return out if _reading(out, lexicon) is not None else text


# -- session 42 (12s): a want said by inference ---------------------------------------------------
#
# "bob keeps pointing at the crisps so i think hed like them", "Mrs Khan keeps eyeing the
# magazine, I reckon she wants it": what the person keeps doing at a thing of the scene, then the
# speaker's inference that they would like it (he / she fitting them, 'it' / 'them' for the
# thing): the want said plainly ("Bob would like the crisps").
_INFERRED42S = re.compile(
    rf"^(?P<who>{_P42S})\s+(?:keeps|kept|has been|'s been|is|was)\s+(?:(?:pointing|gesturing|"
    r"nodding) (?:at|to|towards)|reaching (?:out )?for|eyeing(?: up)?|eying(?: up)?|looking at|"
    r"staring at|gazing at|grabbing at|glancing at|asking about|going on about|on about|"
    # session 43 (12s): asking again and again ('nagging about the cup, so let him have it')
    r"nagging (?:me |us )?(?:about|for)|pestering (?:me |us )?(?:about|for)|banging on about|"
    r"asking for|begging for|angling for|hinting at|hinting about)\s+"
    r"(?P<obj>(?:the|that|those|this|these) [^,.;:!?]+?)\s*[,;]?\s+(?:(?:and|so)\s+)?(?:(?:i|we)"
    r"\s+(?:think|reckon|guess|suppose|bet|imagine|expect|'d say|would say)\s+|i'd say\s+|"
    r"(?:pretty sure|probably|clearly|obviously|i'm guessing|im guessing)\s+)?(?:(?P<pron>he|she)"
    r"(?:'d|d| would)?\s+(?:like|love|want|wants|fancies|is after|'s after|needs)|let (?P<let>him|"
    r"her) have|(?P<can>he|she) (?:can|may|should) have)\s+(?:it|them|those|that|one)\b"
    r"(?P<tail>.*)$",
    _F,
)


def _fits42s(who: str, pronoun: str, lexicon: Lexicon) -> bool:
    """Whether ``who`` names one person of the scene whom ``pronoun`` may be."""
    if not _only_person(who, lexicon):
        return False
    (pid,) = _ids(who, lexicon, "human")
    return _fit36(pid, pronoun, lexicon)


def _inferred42s(text: str, lexicon: Lexicon) -> str:
    """Session 42 (12s): the inferred want above said plainly, when the pronoun may be the
    person, the thing is objects of the scene only, and what is left reads."""
    m = _INFERRED42S.match(text)
    if m is None or not _fits42s(m["who"], m["pron"] or m["let"] or m["can"], lexicon):
        return text
    obj = m["obj"]
    if (
        not _ids(obj, lexicon, "object")
        or _ids(obj, lexicon, "human")
        or _ids(obj, lexicon, "surface")
    ):
        return text
    tail = re.sub(r"^\s*,?\s*(?:go on|then|please|thanks|cheers)\s*", "", m["tail"], flags=_F)
    out = f"{m['who']} would like {obj}{tail}"
    return out if _reading(out, lexicon) is not None else text


# -- session 42 (12s): a closing courtesy to the robot --------------------------------------------
#
# "…, and then you can put your feet up.", "… and then take five", "…, when you're passing",
# "… and then we're all square": what the robot may do when it is done, or that the speaker is
# square, said after the request: taken off (it asks nothing of the scene). Its words name
# nothing of the scene. Not 'have a rest' (session 23: 'the rest' of the things?) nor "you're
# done for the day" (session 38's rule reads it).
_REST42S = (
    r"put your feet up|take (?:a breather|a break|five|ten|"
    r"five minutes|it easy|the weight off|a load off)|have (?:a|your) (?:break|breather|cuppa|"
    r"sit-down|sit down|lie-down|lie down|nap|brew|well-earned break)|knock off|clock off|call "
    r"it a day|(?:we're|we are) (?:all square|square|done|finished|sorted|all done|all sorted)"
    r"(?: for (?:the day|today|now))?"
)
_ROBOT_REST42S = re.compile(
    r"(?P<sep>\s*,?\s*(?:and\s+)?)(?:then\s+)?(?:you\s+can\s+|you\s+could\s+|you\s+may\s+|go\s+"
    r"and\s+|off you go and\s+)?(?P<what>" + _REST42S + r")"
    r"(?P<end>\s*[.!]*)\s*$",
    _F,
)
# Session 52 (12p): every courtesy of it spelt out, lower-cased (gate.spelt). A match ends the
# text but for spaces, full stops and '!': an ASCII text without them ends in one of these, or
# _ROBOT_REST42S (tried from every letter, ~35 us a text) finds nothing in it
_REST_ENDS42S = tuple(sorted(t.lower() for t in re.spelt(_REST42S, _F) or ()))


def _may_rest42s(text: str) -> bool:
    """False only where _ROBOT_REST42S finds nothing in ``text``."""
    low = text.lower()
    if not _REST_ENDS42S or not low.isascii():
        return True
    end = len(low)
    while end and (low[end - 1].isspace() or low[end - 1] in ".!"):
        end -= 1
    return low[:end].endswith(_REST_ENDS42S)


_PASSING42S = re.compile(
    r"(?P<sep>\s*,?\s*)(?:when|whenever|as|next time|if) you(?:'re| are) (?:passing|going past|"
    r"passing by|walking past|next passing|going by|over that way|on your way past)(?P<end>\s*"
    r"[.!]*)\s*$",
    _F,
)


def _robot_rest42s(text: str, lexicon: Lexicon) -> str:
    """Session 42 (12s): the closing courtesy above taken off, when there is a request before
    it and what is left reads."""
    for rx in (_ROBOT_REST42S, _PASSING42S):
        m = None if rx is _ROBOT_REST42S and not _may_rest42s(text) else rx.search(text)
        if m is None or m.start() == 0:
            continue
        if "then" not in m.group(0).lower() and rx is _ROBOT_REST42S and "," not in m["sep"]:
            continue
        out = text[: m.start()].rstrip(" ,") + (m["end"].strip() or "")
        if _reading(out, lexicon) is not None:
            return out
    return text


# -- session 42 (12s): what the person does meanwhile, or where their pastime was -----------------
#
# "Person B's having the chips while he watches the match": 'while' + he / she (the one person
# who gets something) + what they do (naming nothing of the scene): when they will use it, met by
# handing it now: taken off. "… after her paddle on the lake": a pastime's place (naming nothing
# of the scene) after the pastime (a doing of _DOING37: not "after a go on the coconut shy"),
# taken off, so the occasion rules see the pastime alone.
_WHILE42S = re.compile(
    r"(?P<sep>\s*,?\s+)while (?P<pron>he|she)(?:'s|\s+is|\s+[a-z]+(?:s|ed))\b(?P<words>[^.;:!?,]*?)"
    r"(?P<end>\s*[.!]*)\s*$",
    _F,
)


def _while_doing42s(text: str, lexicon: Lexicon) -> str:
    """Session 42 (12s): the 'while he / she …' above taken off, when its pronoun may be the one
    person who gets something in what is left (which reads)."""
    m = _WHILE42S.search(text)
    if m is None or m.start() == 0 or not _remark_only42s(m["words"], lexicon):
        return text
    out = text[: m.start()] + m["end"].strip()
    read = _reading(out, lexicon)
    if read is None:
        return text
    given = {t.target for t in tasks(read) if t.kind == "deliver"}
    if len(given) != 1 or not _fit36(next(iter(given)), m["pron"], lexicon):
        return text
    return out


_PASTIME_PLACE42S = re.compile(
    r"\b(?P<occ>(?:after|before|since|following) (?:his|her|their|the|a) [a-z]+(?: [a-z]+)?) "
    r"(?P<place>(?:on|at|in|round|around|down|by|along|up) (?:the|a) [a-z]+(?: [a-z]+)?)"
    r"(?=\s*(?:[.,;!?]|$))",
    _F,
)


def _pastime_place42s(text: str, lexicon: Lexicon) -> str:
    """Session 42 (12s): the pastime's place above taken off, when it names nothing of the
    scene."""
    m = _PASTIME_PLACE42S.search(text)
    if m is None or _names(m["place"], lexicon) or _names(m["occ"].split(" ", 1)[1], lexicon):
        return text
    if not re.fullmatch(_DOING37, m["occ"].split()[-1], _F):
        return text  # "after a go on the coconut shy": the place is what was done

    return text[: m.end("occ")] + text[m.end("place") :]


# -- session 42 (12s): a purpose said with 'to go with', 'to have with', 'for … to find' ---------
#
# "Give Marco the lemon to go with the fish.", "Mr Novak's asked for the lemon to go with his
# fish", "Give Bob the crisps to have with his pint": what the thing is for, after a handover or a
# want (words naming nothing of the scene; his / her fitting the one person who gets it): taken
# off. "Set the scanner down on the belt for the next shift to find", "… for the next lot to use":
# who will find or use it, after a placement: 'to find' / 'to use' … taken off (session 40's
# purpose rules decide 'for the next shift').
_GO_WITH42S = re.compile(
    r"(?P<sep>\s*,?\s+)to (?:go with|have with|eat with|drink with|dip in|finish off|finish|"
    r"go in|put in|stir|go on) (?P<det>the|a|an|his|her|their|some) (?P<words>[a-z][a-z' -]*?)"
    r"(?P<end>\s*(?:,\s*(?:please|thanks|ta|cheers))?\s*[.!]*)\s*$",
    _F,
)


def _go_with42s(text: str, lexicon: Lexicon) -> str:
    """Session 42 (12s): the purpose above taken off, when it names nothing of the scene and its
    his / her may be the one person who gets something in what is left (which reads)."""
    m = _GO_WITH42S.search(text)
    if m is None or m.start() == 0 or _names(m["words"], lexicon):
        return text
    if _KEEP_WORDS.search(m["words"]) or _NEGATED42S.search(m["words"]):
        return text
    out = text[: m.start()] + m["end"].strip()
    read = _reading(out, lexicon)
    if read is None:
        return text
    given = {t.target for t in tasks(read) if t.kind == "deliver"}
    if len(given) != 1:
        return text
    det = m["det"].lower()
    if det in ("his", "her") and not _fit36(next(iter(given)), det, lexicon):
        return text
    return out


_TO_FIND42S = re.compile(
    r"(?P<for>\bfor (?:the|a|our|my|whoever|whichever) [a-z][a-z' -]*?) to (?:find|use|collect|"
    r"pick up|grab|see|sort|deal with|have)(?: (?:it|them))?(?=\s*(?:[.,;!?]|$))",
    _F,
)


def _to_find42s(text: str, lexicon: Lexicon) -> str:
    """Session 42 (12s): 'to find' / 'to use' … after 'for <a group>' taken off, when every task
    of what is left is a placement (which reads)."""
    m = _TO_FIND42S.search(text)
    if m is None or _names(m["for"][4:], lexicon):
        return text
    out = text[: m.end("for")] + text[m.end() :]
    read = _reading(out, lexicon)
    if read is None or any(t.kind != "place" for t in tasks(read)):
        return text
    return out


# -- session 42 (12s): a placement said to hold from now on ---------------------------------------
#
# "the globe can live on the shelf from now on", "From now on the salt lives on the counter", "The
# torch belongs in the locker from now on": where a thing of the scene is to be kept is where to
# put it: "the globe goes on the shelf".
_LIVES_ON42S = re.compile(
    r"(?P<open>\bfrom now on,?\s+)?(?P<obj>(?:the|that|this) [a-z]+(?: [a-z]+){0,2}?)\s+(?:can|"
    r"should|"
    r"will|is to|'s to|is going to|has to|must)?\s*(?:live|lives|belong|belongs|stay|stays|be "
    r"kept|is kept|be stored|is stored|have a home|has a home)\s+(?P<prep>on|in|at|inside|"
    r"on top of|up on) (?P<surf>(?:the|that) [a-z][a-z ]*?)(?P<close>\s+(?:from now on|for good|"
    r"from today|permanently|for now|now))?(?=\s*(?:[.,;!?]|$|\s+(?:and|please)\b))",
    _F,
)


def _lives_on42s(text: str, lexicon: Lexicon) -> str:
    """Session 42 (12s): the standing placement above said as 'X goes on S', when X is objects
    of the scene, S one surface of it, 'from now on' (or 'for good' …) said, and what is left
    reads."""
    m = _LIVES_ON42S.search(text)
    if m is None or (m["open"] is None and m["close"] is None):
        return text
    if not _ids(m["obj"], lexicon, "object") or _ids(m["obj"], lexicon, "human"):
        return text
    if len(_ids(m["surf"], lexicon, "surface")) != 1:
        return text
    said = f"{m['obj']} goes {m['prep']} {m['surf']}"
    out = text[: m.start()] + said + text[m.end() :]
    # "… and says the globe can live …": the person's word of where it goes, joined by 'and'
    out = re.sub(r"\band says (?=" + re.escape(said) + ")", "and ", out, flags=_F)
    return out if _reading(out, lexicon) is not None else text


# -- session 42 (12s): run-ons: 'as for X, …', "X's for <a surface>", 'once it's in there' -------
#
# "as for the cup let's put that up on the shelf while we're at it": 'as for' + objects of the
# scene, then a clause whose first it / that / them is the thing: the thing said in its place.
_AS_FOR42S = re.compile(
    r"(?:^|(?<=[,;.:!?] )|(?<=\band ))as (?:for|to) (?P<x>(?:the|that|this|those|these) [a-z]+"
    r"(?: [a-z]+){0,2}?),?\s+(?P<rest>[^.;:!?]*?)\b(?P<pron>that|it|them|those|this|these)\b"
    r"(?!\s+(?:one|ones)\b)",
    _F,
)


def _as_for42s(text: str, lexicon: Lexicon) -> str:
    """Session 42 (12s): 'as for X, … it …' said as '… X …', when X is objects of the scene
    only, the words before the pronoun name no thing of it, and what is left reads."""
    if "as " not in text.lower():
        return text
    m = _AS_FOR42S.search(text)
    if m is None:
        return text
    x = m["x"]
    if not _ids(x, lexicon, "object") or _ids(x, lexicon, "human") or _ids(x, lexicon, "surface"):
        return text
    if _ids(m["rest"], lexicon, "object"):
        return text  # another thing before the pronoun: which is 'it'?
    after = text[m.end() :].split()
    if after and m["pron"].lower() not in ("it", "them") and _names(after[0], lexicon):
        return text  # "that shelf": a determiner, not the thing
    rest = m["rest"]
    out = text[: m.start()] + rest + x + text[m.end() :]
    return out if _reading(out, lexicon) is not None else text


# "The tape's for the conveyor, put it on there.": what a thing of the scene is for, a surface of
# it, is where it goes (a person there is a handover, read already); the clause after it that
# puts it there says it again.
_FOR_SURFACE42S = re.compile(
    r"(?P<obj>(?:the|that|this|those|these) [a-z]+(?: [a-z]+){0,2}?)(?:'s|'re|\s+is|\s+are)\s+"
    r"(?:for|meant for|to go on|to go in|headed for|bound for) (?P<surf>(?:the|that) [a-z]+"
    r"(?: [a-z]+)?)(?P<again>\s*,?\s*(?:so\s+)?(?:put|pop|stick|leave|set|place|lay|drop) (?:it|"
    r"them) (?:on|in|onto|into|up on|down on|over) (?:there|it|that))?(?=\s*(?:[.,;!?]|$|\s+"
    r"(?:and|please)\b))",
    _F,
)


def _for_surface42s(text: str, lexicon: Lexicon) -> str:
    """Session 42 (12s): "X's for <a surface>" said as 'X goes on <the surface>', when X is
    objects of the scene, the surface one of it, and what is left reads."""
    if " for " not in text.lower():
        return text
    m = _FOR_SURFACE42S.search(text)
    if m is None or len(_ids(m["surf"], lexicon, "surface")) != 1:
        return text
    if _ids(m["surf"], lexicon, "human") or _ids(m["surf"], lexicon, "object"):
        return text
    if not _ids(m["obj"], lexicon, "object") or _ids(m["obj"], lexicon, "human"):
        return text
    out = text[: m.start()] + f"{m['obj']} goes on {m['surf']}" + text[m.end() :]
    return out if _reading(out, lexicon) is not None else text


# "pop the notebook into the box first and once its in there priya can have the stapler", "…
# and once he's got those the bottle can head over to Person A": the task before done, then the
# next: 'then'. "the bottle can head over to Person A": a thing of the scene heading to a person
# is its going there.
_ONCE_THERE42S = re.compile(
    r"\bonce (?:(?:it's|its|it is|they're|theyre|they are|that's|thats|that is) (?:in|on|up|over|"
    r"down) there|(?P<pron>he|she)(?:'s| has|s) got (?:it|them|those|that|these|this|one|both)"
    r"(?: (?:ones|one))?"
    # session 43 (12s): 'when they're down' (after placements), 'once he's holding it', 'as
    # soon as she has it' (he / she the one given it)
    r"|(?P<placed>it's|its|it is|they're|theyre|they are) (?:down|in|on|away|in place)(?=\s*,|\s+"
    r"(?!(?:the|a|an|that|this|those|these|his|her|their|top|there|then)\b))"
    r"|(?P<holder>he|she)(?:'s| is) holding (?:it|them|that|those|both)|(?P<haver>he|she) has "
    r"(?:it|them|that|those|both))(?!\s+(?:on|in|to|for|with|from|at)\b),?",
    _F,
)
# session 43 (12s): 'when' / 'as soon as' open the same clause (as 'once' does)
_WHEN_ONCE43S = re.compile(r"\b(?:when|as soon as)(?= (?:it|its|they|theyre|he|she)\b)", _F)
_HEAD_TO42S = re.compile(
    r"(?P<x>(?:the|that|this|those|these) [a-z]+(?: [a-z]+)?) (?P<modal>can|could|should|will|"
    r"is to|'s to|are to) head (?:(?:over|across|off|on|back) )?to\b",
    _F,
)


def _holder_fits43s(before: str, pron: str | None, lexicon: Lexicon) -> bool:
    """Session 43 (12s): whether the he / she who holds it ('once he's holding it') may be the
    one person the task before hands something to (no pronoun: True)."""
    if pron is None:
        return True
    read = _reading(re.sub(r"[\s,]*(?:\band|\bthen)?\s*$", "", before, flags=_F), lexicon)
    given = {t.target for t in tasks(read) if t.kind == "deliver"} if read is not None else set()
    return len(given) == 1 and _fit36(next(iter(given)), pron, lexicon)


def _placed_before43s(before: str, lexicon: Lexicon) -> bool:
    """Session 43 (12s): whether the task before 'when it's down' reads as placements only (a
    thing handed over is nowhere to be 'down' or 'in': session 35's conditions at a place)."""
    read = _reading(re.sub(r"[\s,]*(?:\band|\bthen)?\s*$", "", before, flags=_F), lexicon)
    return read is not None and all(t.kind == "place" for t in tasks(read))


def _once_there42s(text: str, lexicon: Lexicon) -> str:
    """Session 42 (12s): 'once it's in there' / 'once he's got those' after a task said as
    'then', and a thing that 'can head over to' a person as 'can go to' them, when what is left
    reads."""
    low = text.lower()
    out = text
    if "when " in low or "as soon as " in low:
        said = _WHEN_ONCE43S.sub("once", out)
        if _ONCE_THERE42S.search(said):
            out = said
    if "once " in out.lower():
        m = _ONCE_THERE42S.search(out)
        if (
            m is not None
            and m.start() > 0
            and _names(out[: m.start()], lexicon)
            and _names(out[m.end() :], lexicon)  # a task after it ('… once it's there': which?)
            and _holder_fits43s(out[: m.start()], m["holder"] or m["haver"], lexicon)
            and (m["placed"] is None or _placed_before43s(out[: m.start()], lexicon))
            and not (  # 'then, once he has them': which waits for which? (session 7's refusal)
                (m["placed"] or m["holder"] or m["haver"])
                and re.search(r"\bthen\W*$", out[: m.start()], _F)
            )
        ):
            out = out[: m.start()] + "then" + out[m.end() :]
    if " head " in low:
        h = _HEAD_TO42S.search(out)
        if h is not None and _ids(h["x"], lexicon, "object"):
            out = out[: h.start()] + f"{h['x']} {h['modal']} go to" + out[h.end() :]
    if out == text:
        return text
    return out if _reading(out, lexicon) is not None else text


# "OK so I was thinking the chips for Person B to start with and …": the speaker's plan said as
# a thought, then what it is: the plan said ('to start with' is 'first').
_THINKING42S = re.compile(
    r"^(?P<lead>(?:(?:ok|okay|so|right|well|now|um|erm)\s*,?\s+)*)(?:i|we)(?: was| were|'m|'re|m|"
    r" am| are)? thinking,?\s+(?:that\s+|maybe\s+|perhaps\s+)*(?=(?:the|that|this|those|these) )",
    _F,
)
_TO_START42S = re.compile(r"\b(?:to start with|to begin with|for starters|to kick off)\b", _F)


def _thinking42s(text: str, lexicon: Lexicon) -> str:
    """Session 42 (12s): the speaker's thought above said as the plan, when what is left
    reads."""
    m = _THINKING42S.match(text)
    if m is None:
        return text
    out = text[m.end() :]
    out = _TO_START42S.sub("first", out)
    out = out[:1].upper() + out[1:]
    return out if _reading(out, lexicon) is not None else text


# -- session 42 (12s): remarks of the speaker, of a child, of earlier orders ----------------------
#
# "stick the bottle up on the shelf would you im trying to tidy for the bouzouki players", "I'm
# clearing up after the lunch rush, so pop the tongs on the rack": what the speaker is doing
# (words naming nothing of the scene, no want, no negation, nothing pointed back at), closing or
# opening a request: taken off.
_SPEAKER_CLOSE42S = re.compile(
    r"(?P<sep>\s*(?:,|;|\.|\bwould you\b|\bwill you\b|\bplease\b|\bta\b)?\s*)(?:i'm|im|i am|we're|"
    r"we are|i've been|ive been|we've been)\s+(?:just\s+|only\s+)?(?:trying to|having to|"
    r"going to|gonna|about to|busy|in the middle of|getting|clearing|tidying|cleaning|sorting|"
    r"setting up|packing|doing|cooking|making|working|off|heading|running|on my way|late|"
    r"swamped|snowed under)\b(?P<words>[^.;:!?,]*)(?P<end>\s*[.!]*)\s*$",
    _F,
)
_SPEAKER_OPEN42S = re.compile(
    r"^(?:i'm|im|i am|we're|we are|i've been|ive been|we've been)\s+(?:just\s+|only\s+)?"
    r"(?:trying to|having to|busy|in the middle of|clearing|tidying|cleaning|sorting|setting up|"
    r"packing|doing|cooking|making|working|getting|swamped|snowed under)\b(?P<words>[^.;:!?,]*?)"
    r"(?:,\s*so\s+|\s+so\s+|[,;]\s+)(?P<rest>\S.*)$",
    _F,
)


def _speaker_doing42s(text: str, lexicon: Lexicon) -> str:
    """Session 42 (12s): the speaker's remark above taken off, when what is left reads."""
    low = text.lower()
    if not any(
        w in low for w in ("i'm", "im ", "i am", "we're", "we are", "i've", "ive ", "we've")
    ):
        return text
    m = _SPEAKER_OPEN42S.match(text)
    if m is not None and _remark_only42s(m["words"], lexicon):
        rest = m["rest"][:1].upper() + m["rest"][1:]
        if _reading(rest, lexicon) is not None:
            return rest
    m = _SPEAKER_CLOSE42S.search(text)
    if m is not None and m.start() > 0 and _remark_only42s(m["words"], lexicon):
        out = text[: m.start()].rstrip(" ,;") + m["end"].strip()
        if _reading(out, lexicon) is not None:
            return out
    return text


# "Grandad's after the wipes, the little one's made a right mess.": a child said as 'the little
# one' (not a thing: no 'little' object) in a remark's subject after a request: 'the child' (the
# remark rules take the remark off when it asks nothing).
_LITTLE_ONE42S = re.compile(
    r"(?<=[,;] )the (?:little|wee|young|youngest|small) (?:one|un|'un)(?=(?:'s|\s+(?:is|has|was|"
    r"had))\b)",
    _F,
)


def _little_one42s(text: str, lexicon: Lexicon) -> str:
    """Session 42 (12s): 'the little one' of a remark said as 'the child', when no thing of the
    scene is so called and what is left reads."""
    m = _LITTLE_ONE42S.search(text)
    if m is None:
        return text
    out = text[: m.start()] + "the child" + text[m.end() :]
    return out if _reading(out, lexicon) is not None else text


# "orders from earlier still stand person b is having the chips …": that earlier requests still
# hold, opening new ones: asks nothing of this one (the cell acts on what is said now).
_ORDERS_STAND42S = re.compile(
    r"^(?:(?:the|my|our|those|all the|any) )?(?:orders|instructions|requests|plans|jobs) (?:from "
    r"(?:earlier|before|this morning|yesterday|last time)|i gave (?:you )?(?:earlier|before)) "
    r"(?:still )?(?:stand|apply|hold|go|count)\b,?\s*(?:[.;:]\s*)?(?:(?:and|so|but)\s+)?",
    _F,
)


def _orders_stand42s(text: str, lexicon: Lexicon) -> str:
    """Session 42 (12s): the opening remark above taken off, when what is left reads."""
    m = _ORDERS_STAND42S.match(text)
    if m is None or m.end() >= len(text):
        return text
    out = text[m.end() :]
    out = out[:1].upper() + out[1:]
    return out if _reading(out, lexicon) is not None else text


# "Sam's taking minutes for the sugar crafter's guild, hand over the notebook.": what one person is
# doing (a verb in -ing, words naming nothing else of the scene), then a handover with no one to
# hand it to: the person doing it gets it.
_DOER42S = re.compile(
    rf"^(?P<who>{_P42S})(?:'s|\s+is)\s+(?P<words>[a-z]+ing\b[^.;:!?,]*?)(?:,\s*(?:so\s+)?|;\s*|\s+"
    r"so\s+)(?P<rest>(?:(?:please|just|can you|could you)\s+)?(?:hand|pass|give|bring|take|"
    r"fetch|send)\b[^.;:!?]*?)(?P<end>\s*[.!]*)\s*$",
    _F,
)


def _doer_gets42s(text: str, lexicon: Lexicon) -> str:
    """Session 42 (12s): the handover above given to the person doing it, when it names no
    person or surface, does not read alone, and reads given to them (and only them)."""
    m = _DOER42S.match(text)
    if m is None or not _only_person(m["who"], lexicon):
        return text
    if not _remark_only42s(m["words"], lexicon):
        return text
    rest = m["rest"]
    if _ids(rest, lexicon, "human") or _ids(rest, lexicon, "surface"):
        return text
    if re.search(r"\b(?:him|her|them|me|us|you)\b", rest, _F) or _reading(rest, lexicon):
        return text
    out = f"{rest} to {m['who']}{m['end'].strip()}"
    read = _reading(out, lexicon)
    if read is None or {t.target for t in tasks(read)} != _ids(m["who"], lexicon, "human"):
        return text
    return out[:1].upper() + out[1:]


# "ruth is doing obs and needs the thermometer and mrs khan is bored so bring her the magazine":
# after a first request, another person's state (words naming nothing of the scene) then 'so' + a
# request whose one him / her fits them: their name said in its place, the state gone (as
# session 32's `_opening_state32s` does for an opening one).
_MIDDLE_STATE42S = re.compile(
    rf"(?P<sep>\s*(?:,|;|\.)?\s+(?:and\s+)?)(?P<who>{_P42S})(?:'s|\s+(?:is|has been|'s been|was|"
    r"looks|seems))\s+(?P<words>[a-z][^.;:!?,]{1,60}?),?\s+so\s+(?P<verb>(?:please\s+)?(?:bring|"
    r"give|hand|pass|take|get|fetch)) (?P<pron>him|her) (?P<rest>[^.;:!?]*)",
    _F,
)


def _middle_state42s(text: str, lexicon: Lexicon) -> str:
    """Session 42 (12s): the state above taken off and its person named in the request, when a
    request comes before it, the pronoun may be the person, and what is left reads."""
    if " so " not in text.lower():
        return text
    for m in _MIDDLE_STATE42S.finditer(text):
        if m.start() == 0 or not _fits42s(m["who"], m["pron"], lexicon):
            continue
        if not _names(text[: m.start()], lexicon) or not _remark_only42s(m["words"], lexicon):
            continue
        if _ids(m["rest"], lexicon, "human"):
            continue
        out = f"{text[: m.start()]}; {m['verb']} {m['who']} {m['rest']}{text[m.end() :]}"
        if _reading(out, lexicon) is not None:
            return out
    return text


# "ever since balalaika practice person a keeps going on about wanting the bottle": an occasion of
# the person's own doing opening a want (no comma after it): what made them want it (sessions 35
# and 37's policy, said first): taken off, when what is left reads and tells of a want.
_OPENING_OCCASION42S = re.compile(
    r"^(?:ever\s+)?(?P<prep>since|after|following)\s+(?:(?P<det>his|her|their|the|a)\s+)?"
    r"(?P<tail>[a-z].*)$",
    _F,
)


def _opening_occasion42s(text: str, lexicon: Lexicon) -> str:
    """Session 42 (12s): the opening occasion above taken off, when it is a doing (_DOING37, no
    event word) of up to three words naming nothing of the scene, what follows tells of the want
    of the one person it fits, and it reads."""
    m = _OPENING_OCCASION42S.match(text)
    if m is None:
        return text
    words = m["tail"].split(" ")
    det = (m["det"] or "").lower()
    for k in (1, 2, 3):
        if any(w.endswith(",") for w in words[:k]):
            break  # with a comma: session 37's fronted occasion (`_AFTER_HIS37`)
        what = " ".join(words[:k])
        rest = " ".join(words[k:])
        if not rest or _names(what, lexicon) or _KEEP_WORDS.search(what):
            continue
        last = what.split()[-1].lower()
        if last in _EVENTS37 or not re.fullmatch(_DOING37, last, _F):
            continue
        if not _WANT_SAID41S.search(rest) or _ORDER41S.search(rest):
            continue
        rest = rest[:1].upper() + rest[1:]
        read = _reading(rest, lexicon)
        if read is None:
            continue
        given = {t.target for t in tasks(read) if t.kind == "deliver"}
        if len(given) != 1:
            continue
        if det in ("his", "her") and not _fit36(next(iter(given)), det, lexicon):
            continue
        return rest
    return text


# the normaliser's rewrites run before the session-41 ones (wired into normalise._STEPS19)
_STEPS42S_FIRST: tuple[Callable[[str, Lexicon], str], ...] = (
    _state_and42s,
    _inferred42s,
    _robot_rest42s,
    _while_doing42s,
    _pastime_place42s,
    _go_with42s,
    _to_find42s,
    _lives_on42s,
    _as_for42s,
    _for_surface42s,
    _once_there42s,
    _thinking42s,
    _speaker_doing42s,
    _little_one42s,
    _orders_stand42s,
    _doer_gets42s,
    _middle_state42s,
    _opening_occasion42s,
)
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-41 ones)
_STEPS42S: tuple[Callable[[str, Lexicon], str], ...] = ()
# refusals asked of the text before it is read (offline._parse, after the session-41 ones)
REFUSE42S: tuple[Callable[[str, Lexicon], None], ...] = (_elses_after42s,)
# checks of the whole instruction's reading (offline.parse_instruction, after the session-41 ones)
CHECK42S: tuple[Callable[[str, Node, Lexicon], None], ...] = ()
