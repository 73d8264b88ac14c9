"""The grounder's rules of session 43, engineer 12r (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _ids, _reading
from hltl.grounding._rewrites40r import _capital40r
from hltl.grounding._rewrites42r import (
    _THING42R,
    _WHO42R,
    _fits42r,
    _negated_then42r,
    _person42r,
    _thing42r,
)
from hltl.grounding.lexicon import PRONOUN_SEX, Lexicon
from hltl.grounding.tree import Node, tasks

# the separator before or after a spoken aside ("...", ",", ";", "—")
_SEP43R = r"(?:\.\.\.|…|—|--|[,;.:!?-])"
# a thing or a list of things, named as these rules take them (checked against the scene after)
_THINGS43R = rf"{_THING42R}(?:(?:,| and| or| nor) {_THING42R})*"
# a thing named with 'of' ("the tin of screws") or as the session-42 rules name it
_OF_THING43R = rf"(?:(?:the|that|this) [a-z]+ of [a-z]+|{_THING42R})"


def _one_thing43r(words: str, lexicon: Lexicon) -> bool:
    """Whether ``words`` names one object of the scene whole."""
    return _thing42r(words, None, lexicon) is not None


def _things43r(words: str, lexicon: Lexicon) -> list[str] | None:
    """The objects of a list ``words`` ("the cup or the apple", "the cup, the apple and the
    bottle"), each named whole, or None."""
    said = [w.strip() for w in re.split(r",|\band\b|\bor\b|\bnor\b", words, flags=_F) if w.strip()]
    if not said or not all(_one_thing43r(w, lexicon) for w in said):
        return None
    return said


# -- corrections -----------------------------------------------------------------------------------

# a hesitation or cue said around an owned slip ("er", "hmm, no", "whoops", "hold on")
_UM43R = (
    r"(?:er|erm|um|uh|hmm|ah|oh|oops|whoops|oh dear|well|no|nope|wait|sorry|hold on|hang on|"
    r"actually|right|ok|okay|look)"
)
# the speaker saying the request before was wrong, said only of itself (no thing, no person)
_SLIP43R = (
    r"(?:scratch that|strike that|scrap that|forget that|rewind|back up|take that back|(?:let me )?"
    r"start (?:again|over)|change of plans?|(?:except|but|no,?) that's (?:wrong|not right|not it)|"
    r"that's (?:wrong|not right)|that is (?:wrong|not right)|i've (?:muddled|mixed up) (?:them|it|"
    r"that|those|the two)(?: up)?|i've (?:muddled|mixed) (?:them|it|that|those|the two) up|"
    r"i've got (?:them|it|that|those|the two) (?:muddled|mixed up|wrong)(?: up)?|i (?:muddled|"
    r"mixed) (?:them|it|that|those) up|my (?:bad|mistake|error)|silly "
    r"me|i'm (?:reading|looking at|reading off|reading from) the wrong (?:chart|list|note|notes|"
    r"page|sheet|order|ticket|board|form|card|label|rota|line)|i've got the wrong (?:chart|list|"
    r"note|notes|page|sheet|order|ticket|board|form|card|label|rota|line)|i (?:misread|misspoke|"
    r"misheard)(?: that| it)?)"
)
_SLIP_CUE43R = (
    rf"^(?P<head>.+?)\s*{_SEP43R}\s*(?P<cue>(?:{_UM43R}\s*{_SEP43R}?\s*)*{_SLIP43R}"
    rf"(?:\s*{_SEP43R}?\s*(?:{_UM43R}|{_SLIP43R}))*)\s*{_SEP43R}\s*(?P<fix>\S.*?)(?P<end>\s*[.!]?)$"
)
# the corrected request as the grammar's correction takes it after 'no,'
_FIX_AS43R: tuple[tuple[str, str], ...] = (
    # "he's meant to have the chips" -> "he gets the chips"
    (
        r"^(?P<w>he|she)(?:'s| is) (?:meant|supposed|due) to (?:have|get|be getting|be having) ",
        r"\g<w> gets ",
    ),
    # "it's meant to go in the locker" -> "put it in the locker"
    (
        r"^(?:it|they)(?:'s| is|'re| are) (?:meant|supposed) to (?:go|be) (?P<on>in|on|into|onto) ",
        r"put it \g<on> ",
    ),
    (r"^(?:it|they) (?:goes|go|belongs?|should go) (?P<on>in|on|into|onto) ", r"put it \g<on> "),
)
# "they're Mrs Khan's" -> "Mrs Khan"
_WHOSE_FIX43R = rf"^(?:they're|they are|it's|it is|those are|that's) (?P<q>{_WHO42R})'s$"


def _slip_fix43r(fix: str, lexicon: Lexicon) -> str:
    """A correction ``fix`` said as the grammar's correction takes it after 'no,'."""
    for pat, to in _FIX_AS43R:
        fix = re.sub(pat, to, fix, flags=_F)
    m = re.match(_WHOSE_FIX43R, fix, _F)
    if m is not None and _person42r(m["q"], lexicon) is not None:
        return m["q"]
    return fix


def _slip_cue43r(text: str, lexicon: Lexicon) -> str:
    """Session 43 (12r): a request the speaker then says was wrong in words of its own ("scratch
    that", "rewind", "change of plan", "except that's wrong", "I've muddled them", "my bad",
    "whoops, I'm reading the wrong chart", "I misspoke"), with hesitations around it ("er", "hmm,
    no", "hold on"), then the corrected request: read as "<request>, no, <correction>" (the
    grammar's correction), the correction said as it takes it ("he's meant to have X" -> "he gets
    X", "it's meant to go in L" -> "put it in L", "they're Q's" -> "Q"). Taken only when that
    reads; a cue without such words (a bare 'hold on', which may add) is not taken."""
    low = text.lower()
    if not any(
        w in low
        for w in (
            *("scratch", "strike", "scrap", "forget", "rewind", "back up", "take that", "start"),
            *("change of plan", "wrong", "muddled", "mixed", "my bad", "my mistake", "my error"),
            *("silly me", "mis", "not right", "not it"),
        )
    ):
        return text
    m = re.match(_SLIP_CUE43R, text.strip(), _F)
    if m is None:
        return text
    fix = _slip_fix43r(m["fix"], lexicon)
    if not _ids(fix, lexicon) or re.match(r"^(?:nothing|none|never|no|not|neither)\b", fix, _F):
        # a correction that names nothing, or takes the request back ("nothing for now")
        return text
    out = f"{m['head']}, no, {fix}{m['end'] or '.'}"
    return out if _reading(out, lexicon) is not None else text


# "um, did I say Emma? Dana, sorry."
_DID_I_SAY43R = (
    rf"^(?P<head>.+?)\s*{_SEP43R}\s*(?:{_UM43R}\s*{_SEP43R}?\s*)*(?:did i (?:just )?say|i said|"
    r"have i said|did i put)\s+(?P<x>[^?,;.]+?)\s*\?\s*(?:(?:no|sorry|i mean|i meant|oops|whoops)"
    r"\s*,?\s*)*(?P<y>[^?,;.!]+?)(?:\s*,?\s*(?:sorry|i mean|i meant|of course|obviously|my "
    r"mistake|my bad))?(?P<end>\s*[.!]?)$"
)
# "well, not the knife actually, the tongs"
_NOT_X_Y43R = (
    rf"^(?P<head>.+?)\s*{_SEP43R}\s*(?:(?:well|er|um|erm|oh|no|hmm|sorry|wait)\s*,?\s*)*not "
    r"(?P<x>[^,;.]+?)(?: actually| after all| really| at all)?\s*[,;]\s*(?:(?:but|i mean|i meant|"
    r"rather|actually|instead)\s*,?\s*)*(?P<y>[^,;.!]+?)(?: actually| instead| rather)?"
    r"(?P<end>\s*[.!]?)$"
)


def _named43r(words: str, lexicon: Lexicon) -> tuple[str, str] | None:
    """The kind ('human' or 'object') and id of the one person or object ``words`` names whole."""
    pid = _person42r(words, lexicon)
    if pid is not None:
        return ("human", pid)
    said = words if re.match(r"^(?:the|a|an) ", words, _F) else f"the {words}"
    if _one_thing43r(said, lexicon):
        (oid,) = _ids(said, lexicon, "object")
        return ("object", oid)
    return None


def _said_wrong43r(text: str, lexicon: Lexicon) -> str:
    """Session 43 (12r): a name the speaker takes back by asking "did I say X?" or saying "not X
    (actually), Y" after a request that names X once: the request with Y in X's place ("Emma gets
    the spoon, um, did I say Emma? Dana, sorry." -> "Dana gets the spoon."; "Lena needs the knife,
    well, not the knife actually, the tongs." -> "Lena needs the tongs."). X and Y each name one
    person, or each one object, of the scene, and differ."""
    low = text.lower()
    if "did i" not in low and "i said" not in low and "not " not in low:
        return text
    m = re.match(_DID_I_SAY43R, text.strip(), _F) or re.match(_NOT_X_Y43R, text.strip(), _F)
    if m is None:
        return text
    x, y, head = m["x"].strip(), m["y"].strip(), m["head"]
    nx, ny = _named43r(x, lexicon), _named43r(y, lexicon)
    if nx is None or ny is None or nx[0] != ny[0] or nx[1] == ny[1]:
        return text
    found = list(re.finditer(rf"\b{re.escape(x)}\b", head, _F))
    if len(found) != 1:
        return text
    f = found[0]
    if nx[0] == "object" and not re.match(r"^(?:the|a|an) ", y, _F):
        y = f"the {y}" if re.match(r"^(?:the|a|an) ", x, _F) else y
    out = f"{head[: f.start()]}{y}{head[f.end() :]}{m['end'] or '.'}"
    out = _capital40r(out.strip())
    return out if _reading(out, lexicon) is not None else text


# "Person A was down for the chips but she's changed her order to the bottle."
_CHANGED_ORDER43R = (
    rf"^(?P<p>{_WHO42R})(?: was down for| had (?:ordered|asked for|wanted|put in for|picked|"
    r"chosen)| ordered| asked for| wanted| was (?:having|getting|after|meant to get|meant to "
    rf"have))(?: originally| at first| first)? (?P<x>{_THING42R})(?: at first| originally| "
    r"first| earlier)?\s*,?\s*(?:but|only|though)\s+(?:now\s+)?(?:(?P<w>he|she)(?:'s| has) "
    r"(?:changed|switched|swapped) (?:her|his) (?:order|mind|request)(?: (?:over|round))? to|"
    r"(?P<w2>he|she)(?:'s| has) (?:switched|swapped|changed)(?: over)? to|(?P<w3>he|she)(?:'d|"
    r" would) "
    rf"(?:rather|sooner) (?:have|get)|(?P<w4>he|she) (?:wants|would like|'d like)) "
    rf"(?P<y>{_THING42R})(?: now| instead)*(?P<end>\s*[.!]?)$"
)


def _changed_order43r(text: str, lexicon: Lexicon) -> str:
    """Session 43 (12r): a person's earlier choice, then a change of it ("P was down for X but
    she's changed her order to Y", "P had asked for X, but now he'd rather have Y", "P ordered X
    but she's switched to Y"): "P wants Y, not X" (the pronoun fitting P, X and Y different)."""
    low = text.lower()
    if not any(w in low for w in ("chang", "switch", "swapp", "rather", "sooner", "now")):
        return text
    m = re.match(_CHANGED_ORDER43R, text.strip(), _F)
    if m is None:
        return text
    pid = _person42r(m["p"], lexicon)
    pro = next(w for w in (m["w"], m["w2"], m["w3"], m["w4"]) if w)
    if pid is None or not _fits42r(pid, pro, lexicon):
        return text
    x, y = _thing42r(m["x"], None, lexicon), _thing42r(m["y"], m["x"], lexicon)
    if x is None or y is None or _ids(x, lexicon, "object") == _ids(y, lexicon, "object"):
        return text
    out = f"{m['p']} wants {y}, not {x}{m['end'] or '.'}"
    return out if _reading(out, lexicon) is not None else text


# "Chips to Person B. Wait, it's the other way round: chips to Person A."
_OTHER_WAY43R = (
    rf"^(?P<head>.+?)\s*{_SEP43R}\s*(?:{_UM43R}\s*{_SEP43R}?\s*)*(?:it's|it is|it was|no,? it's) "
    r"(?:the )?other way (?:round|around|about)\s*[:;,-]\s*(?P<fix>\S.*?)(?P<end>\s*[.!]?)$"
)


def _other_way43r(text: str, lexicon: Lexicon) -> str:
    """Session 43 (12r): "<request>. Wait, it's the other way round: <request again>": the
    request said again replaces the first, when the first moves one object to one person or
    place and the one said again moves the same object elsewhere (what the other way round of one
    delivery can only be)."""
    if "other way" not in text.lower():
        return text
    m = re.match(_OTHER_WAY43R, text.strip(), _F)
    if m is None:
        return text
    first, again = _reading(m["head"], lexicon), _reading(m["fix"], lexicon)
    if first is None or again is None:
        return text
    t1, t2 = list(tasks(first)), list(tasks(again))
    if len(t1) != 1 or len(t2) != 1 or t1[0].obj != t2[0].obj or t1[0].target == t2[0].target:
        return text
    out = f"{m['head']}, no, {m['fix']}{m['end'] or '.'}"
    return out if _reading(out, lexicon) is not None else text


# a mid-sized thing said as the scene's "medium"
_MID_SIZED43R = r"\b(?:middle|mid|medium)[- ]?sized\b"


def _mid_sized43r(text: str, lexicon: Lexicon) -> str:
    """Session 43 (12r): "middle-sized", "mid-sized", "medium-sized" as "medium" where the scene
    has a medium one ("wait, I meant the middle-sized one")."""
    if "sized" not in text.lower() or not re.search(_MID_SIZED43R, text, _F):
        return text
    if not any("medium" in " ".join((o.id, *o.aliases)) for o in lexicon.scene.objects):
        return text
    return re.sub(_MID_SIZED43R, "medium", text, flags=_F)


# -- negation and exclusion ------------------------------------------------------------------------

# a person's not wanting a thing said as an idiom, as the session-42 rule says it
_NOT_WANT_IDIOM43R = (
    r"(?:\s+(?:turned|turns|has turned|'s turned) (?:her|his|their) nose up at|(?:'s| has) gone "
    r"(?:right )?off| (?:can't|cannot|can not|couldn't) (?:stand|abide|face|stomach)| "
    r"(?:doesn't|does not) (?:care for|much like|fancy)|(?:'s| is) (?:sick|tired|fed up) (?:of|"
    r"with)|(?:'s| has) had (?:enough|her fill|his fill) of| (?:won't|wouldn't|will not|would not)"
    r" (?:touch|go near|eat|drink|use)| (?:turned|turns|has turned|'s turned) down| (?:said|says|"
    r"has said|'s said) no to|(?:'s| is) (?:done|finished|through) with| (?:won't|wouldn't|will "
    r"not|would not) thank (?:you|me|us|anyone) for|(?:'s| is) not (?:bothered|fussed) about| "
    r"isn't (?:bothered|fussed) about)\b"
)
_WONT_BE43R = r" (?:won't|will not) be (?P<v>having|getting)\b"
# "Person A's had her turn with the cup" -> "The cup isn't Person A's anymore"
_HAD_TURN43R = (
    rf"^(?P<p>{_WHO42R})(?:'s| has) had (?:her|his|their) (?:turn|go|time|fill|use) (?:with|of|on) "
    rf"(?P<x>{_THING42R})"
)
# what is wanted, said as the session-42 rule takes it
_WANTED_AS43R: tuple[tuple[str, str], ...] = (
    (r"\b(?P<w>he|she)'ll (?:have|take)\b", r"\g<w> will have"),
    (
        rf"\bit(?:'s| is) (?P<y>{_THING42R}) (?:that|which) (?:goes?|is going|are going|go) to "
        r"(?P<w>him|her)\b",
        r"give \g<w> \g<y>",
    ),
    (
        rf"\bit(?:'s| is) (?P<q>{_WHO42R}) (?:who|that)(?:'s| is)? (?:gets|getting|having|has|"
        r"takes|taking) (?:it|them)(?: now| this time| instead)?",
        r"\g<q> gets it",
    ),
)


def said_as_not_wanted43r(said: str) -> str:
    """Session 43 (12r): ``said`` with a person's not wanting a thing said as an idiom ("has gone
    off X", "turned her nose up at X", "won't be having X") said as the session-42 rules say it
    ("isn't after X", "isn't having X"); session 31's refusal of a cleft after a request asks
    `_rewrites42r.negated_head42r` of it ("Omar's sick of the banana; it's the spoon he wants")."""
    said = re.sub(_NOT_WANT_IDIOM43R, " isn't after", said, flags=_F)
    return re.sub(_WONT_BE43R, r" isn't \g<v>", said, flags=_F)


def _not_idiom43r(text: str, lexicon: Lexicon) -> str:
    """Session 43 (12r): a person's not wanting a thing said as an idiom ("turned her nose up at
    X", "has gone off X", "won't thank you for X", "won't be having X", "can't stand X", "is fed up
    with X", "has had her turn with X", "has no use for X or Y"), then what is wanted instead or
    where it goes: said as the session-42 rule (_negated_then42r) takes it ("isn't after X", "won't
    want X", "isn't having X", "X isn't P's anymore"; "she'll have Y" as "she will have Y", "it's
    Y that goes to him" as "give him Y", "it's Q who gets it now" as "Q gets it", "bring him the
    grey" as "… the grey one") and read by it; a list of things not wanted ("the cup or the
    apple") must leave out what is wanted. Taken only when that rule reads it."""
    low = text.lower()
    if not any(
        w in low
        for w in (
            *("nose", "gone", "stand", "abide", "face", "stomach", "care", "like", "fancy"),
            *("sick", "tired", "fed up", "enough", "fill", "touch", "near", "eat", "drink", "use"),
            *("down", "no to", "done", "finished", "through", "thank", "won't be", "will not be"),
            *("turn", "bothered", "fussed", "no use", "no need"),
        )
    ):
        return text
    canon = said_as_not_wanted43r(text.strip())
    m = re.match(_HAD_TURN43R, canon, _F)
    if m is not None:
        canon = f"{_capital40r(m['x'])} isn't {m['p']}'s anymore{canon[m.end() :]}"
    canon = re.sub(r"(?:'s| has) no (?:use|need|time) for\b", " isn't after", canon, flags=_F)
    for pat, to in _WANTED_AS43R:
        canon = re.sub(pat, to, canon, flags=_F)
    # "bring him the grey": the adjective said alone of the thing's kind
    canon = re.sub(
        r"\b(?P<v>bring|give|pass|hand|get) (?P<w>him|her) the (?P<a>[a-z]+)(?P<end>\s*[.!]?)$",
        lambda g: (
            g[0]
            if _one_thing43r(f"the {g['a']}", lexicon)
            else (f"{g['v']} {g['w']} the {g['a']} one{g['end']}")
        ),
        canon,
        flags=_F,
    )
    # a list of things not wanted: the rule reads the first, the rest are left out too
    lst = re.search(rf"\bisn't after (?P<xs>{_THINGS43R})(?=\s*[,;:.])", canon, _F)
    rest: list[str] = []
    if lst is not None and re.search(r",|\band\b|\bor\b|\bnor\b", lst["xs"], _F):
        said = _things43r(lst["xs"], lexicon)
        if said is None:
            return text
        canon = f"{canon[: lst.start('xs')]}{said[0]}{canon[lst.end('xs') :]}"
        rest = said[1:]
    if canon == text.strip():
        return text
    out = _negated_then42r(canon, lexicon)
    node = _reading(out, lexicon)
    if node is None:
        return text
    if rest:
        # the rest of the list is left out too: what is read must be none of it
        left = {i for w in rest for i in _ids(w, lexicon, "object")}
        if any(t.obj in left for t in tasks(node)):
            return text
    return out


# "Person A never asked for the chips; Person B did, so take them to him."
_NEVER_ASKED43R = (
    rf"^(?P<p>{_WHO42R}) (?:never|didn't|did not|hasn't|has not|never once|never even) "
    r"(?:asked for|ask for|ordered|order|wanted|want|requested|request|put in for)(?: for)? "
    rf"(?P<x>{_THING42R})(?: at all| in the first place)?\s*[;,.:-]\s*(?:it was |it's |that was )?"
    rf"(?P<q>{_WHO42R}) (?:did|was the one|who did|has|was)(?:,? not (?:her|him|them))?"
    r"(?:\s*[,;]\s*so (?:take|give|bring|pass|hand|send) (?:it|them|those|that) (?:to |over to |"
    rf"across to )?(?P<w>him|her|{_WHO42R})(?: instead)?)?(?P<end>\s*[.!]?)$"
)


def _never_asked43r(text: str, lexicon: Lexicon) -> str:
    """Session 43 (12r): "P never asked for X; Q did (, so take them to him)": X goes to Q, not P
    (the pronoun after fitting Q, a name after being Q)."""
    low = text.lower()
    if "never" not in low and "n't" not in low and " not " not in low:
        return text
    m = re.match(_NEVER_ASKED43R, text.strip(), _F)
    if m is None:
        return text
    pid, qid = _person42r(m["p"], lexicon), _person42r(m["q"], lexicon)
    x = _thing42r(m["x"], None, lexicon)
    if pid is None or qid is None or pid == qid or x is None:
        return text
    w = m["w"]
    if w is not None and (
        not _fits42r(qid, w, lexicon) if w.lower() in PRONOUN_SEX else _person42r(w, lexicon) != qid
    ):
        return text
    out = f"Give {x} to {m['q']}, not {m['p']}{m['end'] or '.'}"
    return out if _reading(out, lexicon) is not None else text


# "There's no reason to hold back; …": the speaker urging the robot on, naming nothing
_NO_NEED_WAIT43R = (
    r"^(?:(?:there's|there is|there's really|there is really) no (?:reason|need|call|point|sense)|"
    r"no (?:reason|need|call|point|sense)|(?:please )?(?:don't|do not) (?:feel you need|feel you "
    r"have|need)) to (?:hold back|wait|hang about|hang around|hang back|hesitate|delay|dither|be "
    r"shy|stand on ceremony)(?: any longer| now| about it| any more)?\s*[;,.:!-]\s*(?P<rest>\S.*)$"
)


def _no_need_wait43r(text: str, lexicon: Lexicon) -> str:
    """Session 43 (12r): "There's no reason to hold back; <request>" (no need to wait, hesitate,
    hang about; don't feel you need to wait): the speaker urging the robot on, which names nothing
    and asks nothing: the request."""
    if "no " not in text.lower() and "n't" not in text.lower() and "not" not in text.lower():
        return text
    m = re.match(_NO_NEED_WAIT43R, text.strip(), _F)
    if m is None:
        return text
    out = _capital40r(m["rest"])
    return out if _reading(out, lexicon) is not None else text


# "Nothing fancy, only the bottle to Person A and not a thing besides."
_NOTHING_FANCY43R = (
    r"^(?:nothing (?:fancy|special|complicated|elaborate|much|more|else|big)(?: (?:needed|wanted|"
    r"this time|today|now))?)\s*[,;:.-]\s*(?=\S)"
)
_NOTHING_MORE43R = (
    r"\s*(?:,|;|-|—)?\s*(?:and )?(?:not a (?:thing|single thing|scrap|crumb) (?:besides|else|more)"
    r"|nothing (?:more|else|besides|extra)(?: besides)?|no more(?: than that)?|nothing more than "
    r"that|and that's your lot)(?=\s*[.!]?\s*$)"
)


def _nothing_more43r(text: str, lexicon: Lexicon) -> str:
    """Session 43 (12r): negations that only say the request is all there is ("Nothing fancy,
    …", "… and not a thing besides", "…, nothing more", "…, nothing else"): the request."""
    low = text.lower()
    if "nothing" not in low and "not a" not in low and "no more" not in low:
        return text
    out = re.sub(_NOTHING_FANCY43R, "", text.strip(), flags=_F)
    out = re.sub(_NOTHING_MORE43R, "", out, flags=_F)
    if out == text.strip():
        return text
    out = _capital40r(out)
    return out if _reading(out, lexicon) is not None else text


# "Bar the apple, the lot is Person A's to take."
_BAR_FIRST43R = (
    r"^(?:bar|barring|except for|excepting|save for|aside from|other than|but for|all but)\s+"
    rf"(?P<x>{_THINGS43R})\s*,\s*(?P<rest>(?:the (?:whole )?lot|everything(?: else)?|all the "
    r"rest|the rest|all of it|all the others|the others)\b.*)$"
)
# "Put the lot on the shelf, only leave the mugs where they are."
_ONLY_LEAVE43R = (
    r"^(?P<head>(?:put|place|move|set|take|pop|stick) (?:the (?:whole )?lot|everything|all of "
    r"it|all the things|all of them) (?:on|onto|in|into) the [a-z]+(?: [a-z]+)?)\s*[,;]\s*(?:only|"
    r"but|just|though)\s+leave (?P<x>" + _THINGS43R + r")(?: where (?:it is|they are)| alone| be| "
    r"out| off it| as (?:it is|they are))(?P<end>\s*[.!]?)$"
)


def _bar_first43r(text: str, lexicon: Lexicon) -> str:
    """Session 43 (12r): an exclusion said with 'bar' (barring, save for, other than, but for)
    before "the lot" or "everything" ("Bar the apple, the lot is Person A's to take": "Apart
    from the apple, everything is Person A's", the session-42 reading of what is left out said
    first), and everything put somewhere "only leave X where they are" (everything except X)."""
    low = text.lower()
    if "lot" not in low and "everything" not in low and "rest" not in low and "all" not in low:
        return text
    m = re.match(_BAR_FIRST43R, text.strip(), _F)
    if m is not None:
        if _things43r(m["x"], lexicon) is None:
            return text
        rest = re.sub(
            r"^(?:the (?:whole )?lot|all the rest|all of it|all the others|the others)",
            "everything",
            m["rest"],
            flags=_F,
        )
        out = f"Apart from {m['x']}, {rest}"
    else:
        m = re.match(_ONLY_LEAVE43R, text.strip(), _F)
        if m is None or not _ids(m["x"], lexicon, "object"):
            return text
        head = re.sub(
            r"\b(?:the (?:whole )?lot|all of it|all the things|all of them)\b",
            "everything",
            m["head"],
            flags=_F,
        )
        out = f"{head} except {m['x']}{m['end'] or '.'}"
    return out if _reading(out, lexicon) is not None else text


# a need said as a negation: "nothing will do but X", "can't do his etching without X"
_NOTHING_BUT43R = (
    rf"^(?P<p>{_WHO42R})(?: (?:says|said|reckons|tells me|told me))?(?: that)? nothing (?:else )?"
    r"(?:will|would|'ll|'d|is going to) (?:do|suit|work|please (?:her|him))(?: (?:her|him))? "
    rf"(?:but|except|other than|apart from|save|besides) (?P<x>{_THING42R})(?P<tail>.*)$"
)
_CANT_WITHOUT43R = (
    rf"^(?P<p>{_WHO42R}) (?:can't|cannot|can not|couldn't|won't be able to|is unable to) (?:do|"
    r"finish|start|get on with|manage|carry on with|continue|get through|begin|make|mend|fix)"
    rf"(?P<mid>(?: [a-z']+){{0,4}}?) without (?P<x>{_OF_THING43R})(?P<tail>.*)$"
)
_WITHOUT_CANT43R = (
    rf"^without (?P<x>{_OF_THING43R})\s*,?\s*(?P<p>{_WHO42R}) (?:can't|cannot|can not|couldn't|"
    r"won't be able to|is unable to) (?:do|finish|start|get on with|manage|carry on with|continue|"
    r"get "
    r"through|begin|make|mend|fix)(?P<mid>(?: [a-z']+){0,5}?)(?P<tail>\s*[.!]?)$"
)


def _need_without43r(text: str, lexicon: Lexicon) -> str:
    """Session 43 (12r): a need said by what cannot be done without the thing ("P can't do his
    etching without X", "Without X, P can't finish mending the gate") or by nothing else doing
    ("P says nothing will do but X (for her dessert round)"): "P needs X" (a pronoun in what P
    cannot do fitting P, what is done naming nothing of the scene)."""
    low = text.lower()
    if "without" not in low and "nothing" not in low:
        return text
    m = (
        re.match(_NOTHING_BUT43R, text.strip(), _F)
        or re.match(_CANT_WITHOUT43R, text.strip(), _F)
        or re.match(_WITHOUT_CANT43R, text.strip(), _F)
    )
    if m is None:
        return text
    pid = _person42r(m["p"], lexicon)
    x = _thing42r(m["x"], None, lexicon)
    if pid is None or x is None:
        return text
    mid = m.groupdict().get("mid") or ""
    if _ids(mid, lexicon) or any(
        not _fits42r(pid, pro, lexicon)
        for pro in re.findall(r"\b(?:he|she|him|her|his)\b", mid, _F)
        if pro.lower() in PRONOUN_SEX
    ):
        return text
    out = f"{m['p']} needs {x}{m['tail']}"
    if not re.search(r"[.!]\s*$", out):
        out += "."
    return out if _reading(out, lexicon) is not None else text


# the normaliser's rewrites run before the session-42 ones (wired into normalise._STEPS19)
_STEPS43R_FIRST: tuple[Callable[[str, Lexicon], str], ...] = (_mid_sized43r, _slip_cue43r)
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-42 ones)
_STEPS43R: tuple[Callable[[str, Lexicon], str], ...] = (
    _said_wrong43r,
    _changed_order43r,
    _other_way43r,
    _not_idiom43r,
    _never_asked43r,
    _no_need_wait43r,
    _nothing_more43r,
    _bar_first43r,
    _need_without43r,
)
# refusals asked of the text before it is read (offline._parse, after the session-42 ones)
REFUSE43R: tuple[Callable[[str, Lexicon], None], ...] = ()
# checks of the whole instruction's reading (offline.parse_instruction, after the session-42 ones)
CHECK43R: tuple[Callable[[str, Node, Lexicon], None], ...] = ()
