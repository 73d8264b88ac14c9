"""The grounder's rules of session 43, engineer 12r (docs/grounding.md)."""

from __future__ import annotations

import functools
from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _ids, _reading
from hltl.grounding._rewrites40r import _capital40r
from hltl.grounding._rewrites42r import (
    _THING42R,
    _WHO42R,
    _fits42r,
    _kind_said42r,
    _negated_then42r,
    _person42r,
    _thing42r,
)
from hltl.grounding.lexicon import PRONOUN_SEX, Lexicon, _one_edit, person_name
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
    rf"^(?P<head>.+?)\s*(?P<sep>{_SEP43R})\s*(?P<cue>(?:{_UM43R}\s*{_SEP43R}?\s*)*{_SLIP43R}"
    rf"(?:\s*{_SEP43R}?\s*(?:{_UM43R}|{_SLIP43R}))*)\s*(?P<sep2>{_SEP43R})\s*(?P<fix>\S.*?)"
    r"(?P<end>\s*[.!]?)$"
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
    if m is None or m["sep2"] in (".", "!", "?"):
        return text  # "…, my mistake. <request>": the cue closes the sentence before it
    head = m["head"]
    if re.search(r"\b(?:no|sorry|wait|actually|scratch|hang on|hold on|i mean|rather)\b", head, _F):
        return text  # a correction in the request before: the older correction rules'
    if m["sep"] in (".", "!", "?") and re.search(r"[,;]|\b(?:then|and)\b", head, _F):
        return text  # a cue opening a sentence after several requests: which it takes back?
    fix = _slip_fix43r(m["fix"], lexicon)
    if re.search(r"\b(?:them|those|these)\b", fix, _F) and len(_ids(head, lexicon, "object")) == 1:
        return text  # 'them' after one thing
    if re.search(r"\b(?:too|as well|also|and|plus)\b", fix, _F):
        return text  # what follows may add to the request as well as correct it
    if not _ids(fix, lexicon) or re.match(r"^(?:nothing|none|never|no|not|neither)\b", fix, _F):
        # a correction that names nothing, or takes the request back ("nothing for now")
        return text
    out = f"{head}, no, {fix}{m['end'] or '.'}"
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


# "Omar will take any cup going except the green one, which he hates."
_ANY_EXCEPT43R = (
    r"^(?P<p>" + _WHO42R + r")(?: will| would| can|'ll|'d)? (?:take|have|use|make do with|do "
    r"with|be happy with) any (?:old )?(?P<k>[a-z]+)(?: going| at all| you like| you find| you've "
    r"got| about)? (?:except|but|bar|apart from|other than|save|besides) (?P<x>the [a-z]+(?: one| "
    r"[a-z]+)?)(?:\s*,\s*(?:which|as|since) (?P<w>he|she) (?:hates|can't stand|cannot stand|"
    r"dislikes|doesn't like|won't touch|loathes|had yesterday|used last)(?: it)?)?"
    r"(?P<end>\s*[.!]?)$"
)


def _any_except43r(text: str, lexicon: Lexicon) -> str:
    """Session 43 (12r): "P will take any K (going) except the A one (, which he hates)": the Ks
    of the scene but that one, for P (the one left, or a choice of those left); a pronoun after
    fitting P."""
    low = text.lower()
    if "any" not in low or not any(
        w in low for w in ("except", "but", "bar", "apart", "other", "save", "besides")
    ):
        return text
    m = re.match(_ANY_EXCEPT43R, text.strip(), _F)
    if m is None:
        return text
    pid = _person42r(m["p"], lexicon)
    kind = _of_kind43r(m["k"], lexicon)
    said = re.sub(r" one$", f" {m['k']}", m["x"], flags=_F)
    if pid is None or len(kind) < 2 or not _one_thing43r(said, lexicon):
        return text
    if m["w"] is not None and not _fits42r(pid, m["w"], lexicon):
        return text
    left_out = _ids(said, lexicon, "object")
    if not left_out <= set(kind):
        return text
    rest = [o for o in kind if o not in left_out]
    names = []
    for oid in rest:
        obj = next(o for o in lexicon.scene.objects if o.id == oid)
        name = next((a for a in (*obj.aliases, obj.id) if _one_thing43r(f"the {a}", lexicon)), None)
        if name is None:
            return text
        names.append(f"the {name}")
    out = f"Give {m['p']} {' or '.join(names)}{m['end'] or '.'}"
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


# -- counts ----------------------------------------------------------------------------------------

_NUMBER43R = {"one": 1, "two": 2, "three": 3, "four": 4, "five": 5, "six": 6, "both": 2, "pair": 2}
# a count said of things, or of requests ("a pair of requests", "two things", "all four of them")
_N43R = r"(?:one|two|three|four|five|six|both|a pair of|a couple of|the pair of)"


def _count43r(said: str) -> int | None:
    """The number ``said`` ("two", "a pair of", "both"), or None ("a couple of" is not one)."""
    word = said.lower().replace("a pair of", "pair").replace("the pair of", "pair").strip()
    return _NUMBER43R.get(word)


def _of_kind43r(kind: str, lexicon: Lexicon) -> list[str]:
    """The objects of the scene of kind ``kind`` ("bottle", "bottles")."""
    k = kind.lower()
    out = [o.id for o in lexicon.scene.objects if o.category in (k, k.rstrip("s"), k[:-2])]
    return out


# "There's only the one bottle on the go; Bob can have it."
_ONLY_THE_ONE43R = (
    r"^(?:(?:there's|there is|we've|we have|you've|you have)(?: only| just)?(?: got)? )?"
    r"(?:(?:only|just) )?(?:the )?one (?P<k>[a-z]+)(?: (?:on the go|going|here|left|about|around|"
    r"to hand|in stock|spare|we've got|we have))?\s*[;,:-]\s*(?:and |so )?(?:(?P<p1>"
    + _WHO42R
    + r") (?:can have|gets|can take|should have|is having|'s having) it|it(?:'s| is) "
    r"(?:for )?(?P<p2>"
    + _WHO42R
    + r")(?:'s)?|give it to (?P<p3>"
    + _WHO42R
    + r"))(?P<end>\s*[.!]?)$"
)


def _only_the_one43r(text: str, lexicon: Lexicon) -> str:
    """Session 43 (12r): "There's only the one X (on the go); P can have it" (just the one X, it's
    P's, give it to P): X to P, when the scene has one X (the count the speaker gives)."""
    if "one" not in text.lower():
        return text
    m = re.match(_ONLY_THE_ONE43R, text.strip(), _F)
    if m is None or len(_of_kind43r(m["k"], lexicon)) != 1:
        return text
    who = next(w for w in (m["p1"], m["p2"], m["p3"]) if w)
    if _person42r(who, lexicon) is None:
        return text
    out = f"Give {who} the {m['k']}{m['end'] or '.'}"
    return out if _reading(out, lexicon) is not None else text


# "a solitary apple", "a bottle, just one, nothing more", "One bag of chips is plenty for P"
_SOLITARY43R = r"\b(?:a|one) (?:solitary|lone|single solitary|sole|lonely) (?=[a-z])"
_JUST_ONE43R = (
    r"\b(?P<a>an?|the) (?P<k>[a-z]+)\s*,\s*(?:just|only) (?:the )?one(?:\s*,\s*(?:nothing more|"
    r"no more|nothing else|not two))?(?=\s*[.!]?\s*$)"
)
_PLENTY43R = (
    r"^(?P<n>one|a single|just one) (?:(?:bag|packet|bottle|tin|box|bar|piece|slice|jar|pot|"
    r"can|roll|pair) of )?(?P<k>[a-z]+) (?:is|'s|will be|would be) (?:plenty|enough|ample|"
    r"sufficient|quite enough|loads|all (?:she|he|they) needs?) for (?P<p>" + _WHO42R + r")"
    r"(?P<end>\s*[.!]?)$"
)


# "…, she needs the one only": the count said again of the person
_ONE_ONLY43R = (
    r"\s*,\s*(?:and )?(?P<w>he|she)(?:'s| is)? (?:only )?(?:needs|wants|asked for|'s after|is "
    r"after) (?:just |only )?(?:the |the one |a single )?one(?: only| and no more)?"
    r"(?P<end>\s*[.!]?)$"
)


def _one_said43r(text: str, lexicon: Lexicon) -> str:
    """Session 43 (12r): one thing said with a count that only stresses it: "a solitary X" (a
    lone, a sole X) as "an X"; "an X, just one, nothing more" as "an X"; "One (bag of) X is
    plenty for P" as "one X for P" (the grammar then reads the one X, or a choice of them)."""
    low = text.lower()
    if not any(w in low for w in ("solitary", "lone", "sole", "one", "single")):
        return text
    out = re.sub(_SOLITARY43R, "a ", text.strip(), flags=_F)
    out = re.sub(r"\ba (?=[aeiou])", "an ", out) if out != text.strip() else out
    out = re.sub(_JUST_ONE43R, lambda g: f"{g['a']} {g['k']}", out, flags=_F)
    only = re.search(_ONE_ONLY43R, out, _F)
    if only is not None:
        who = _ids(out[: only.start()], lexicon, "human")
        if len(who) != 1 or not _fits42r(next(iter(who)), only["w"], lexicon):
            return text
        out = f"{out[: only.start()]}{only['end']}"
    m = re.match(_PLENTY43R, out, _F)
    if m is not None and _person42r(m["p"], lexicon) is not None:
        out = f"One {m['k']} for {m['p']}{m['end'] or '.'}"
    if out == text.strip():
        return text
    return out if _reading(out, lexicon) is not None else text


# "P gets the whole lot, all four of them: bottle, chips, cup and apple."
_ALL_N_OF_THEM43R = (
    r"^(?P<head>.+?)\s*(?:,\s*)?(?P<lot>the (?:whole )?lot|everything|all of it|the pair|both)?"
    r"\s*,?\s*(?:(?:all|the|every one of the) )?(?P<n>two|three|four|five|six|pair) of (?:them|the "
    r"things|those)\s*[:,;-]\s*(?:namely |that is |meaning |i mean )?(?P<list>[a-z ,']+?)"
    r"(?P<end>\s*[.!]?)$"
)
# "P has a pair of requests, namely the bottle and the cup."; "P is owed two things, …; see he
# gets both"
_N_THINGS43R = (
    r"^(?P<p>" + _WHO42R + r") (?:has|'s got|has got|is owed|'s owed|is after|'s after|wants|is "
    r"waiting on|'s waiting on|put in) (?P<n>" + _N43R + r") (?:requests|wishes|things|items|bits)"
    r"(?: (?:on (?:her|his) list|to collect|outstanding|owing|to come))?\s*[,:;-]\s*(?:namely |"
    r"that is |which are |i\.e\. |meaning )?(?P<list>[a-z ,']+?)(?:\s*[;,.]\s*(?:so )?(?:see|make "
    r"sure|check)(?: that)? (?P<w>he|she|" + _WHO42R + r") gets (?:both|them|them both|all of "
    r"them|the lot|all (?:two|three|four) of them|both of them))?(?P<end>\s*[.!]?)$"
)
# "a full set of the spanners, meaning the small and the big"
_FULL_SET43R = (
    r"\b(?:a|the) (?:full|whole|complete) set of (?:the )?(?P<k>[a-z]+)s\s*,\s*(?:meaning|that "
    r"is|i mean|namely|so)\s+the (?P<a>[a-z]+) and the (?P<b>[a-z]+)(?: ones?)?(?=\s*[.!]?\s*$)"
)
# "Both bits on offer, the pair of them, are for P."
_BOTH_BITS43R = (
    r"^both (?:bits|things|items|objects)(?: (?:on offer|here|we've got|we have|going|on the "
    r"table|about|there))?\s*,\s*(?:the pair of them|the two of them|both of them)\s*,\s*(?P<rest>"
    r"(?:are|go|'re) (?:for|to) .+)$"
)


def _listed43r(words: str, lexicon: Lexicon) -> list[str] | None:
    """The objects of a list ``words`` said with or without 'the' ("bottle, chips, cup and
    apple"), each named whole, as "the X"; None unless each names one object."""
    said = [w.strip() for w in re.split(r",|\band\b", words, flags=_F) if w.strip()]
    out = [w if re.match(r"^(?:the|that|this) ", w, _F) else f"the {w}" for w in said]
    if not out or not all(_one_thing43r(w, lexicon) for w in out):
        return None
    ids = [i for w in out for i in _ids(w, lexicon, "object")]
    return out if len(set(ids)) == len(ids) else None


def _joined43r(things: list[str]) -> str:
    """``things`` joined as a list ("the a, the b and the c")."""
    return things[0] if len(things) == 1 else f"{', '.join(things[:-1])} and {things[-1]}"


def _all_n_of_them43r(text: str, lexicon: Lexicon) -> str | None:
    """ "P gets the whole lot, all four of them: bottle, chips, cup and apple", or None."""
    m = re.match(_ALL_N_OF_THEM43R, text, _F)
    if m is None:
        return None
    things = _listed43r(m["list"], lexicon)
    n = _count43r(m["n"])
    if things is None or n != len(things) or _ids(m["head"], lexicon, "object"):
        return None
    lot = m["lot"] and m["lot"].lower() in ("the lot", "the whole lot", "everything", "all of it")
    if lot and len(things) != len(lexicon.scene.objects):
        return None
    return f"{m['head']} {_joined43r(things)}{m['end'] or '.'}"


def _n_things43r(text: str, lexicon: Lexicon) -> str | None:
    """ "P has a pair of requests, namely X and Y", "P is owed two things, X and Y; see he gets
    both", or None."""
    m = re.match(_N_THINGS43R, text, _F)
    if m is None:
        return None
    things = _listed43r(m["list"], lexicon)
    n = _count43r(m["n"])
    pid = _person42r(m["p"], lexicon)
    if things is None or pid is None or (n is not None and n != len(things)) or len(things) < 2:
        return None
    if m["w"] is not None and not _for_whom43r(pid, m["w"], lexicon):
        return None
    return f"Give {m['p']} {_joined43r(things)}{m['end'] or '.'}"


def _full_set43r(text: str, lexicon: Lexicon) -> str | None:
    """ "a full set of the Ks, meaning the small and the big" (every K of the scene), or None."""
    m = re.search(_FULL_SET43R, text, _F)
    if m is None:
        return None
    kind = _of_kind43r(m["k"], lexicon)
    a, b = f"the {m['a']} {m['k']}", f"the {m['b']} {m['k']}"
    if not (_one_thing43r(a, lexicon) and _one_thing43r(b, lexicon)):
        return None
    ids = _ids(a, lexicon, "object") | _ids(b, lexicon, "object")
    if len(ids) != 2 or ids != set(kind):
        return None
    return f"{text[: m.start()]}{a} and {b}{text[m.end() :]}"


def _both_bits43r(text: str, lexicon: Lexicon) -> str | None:
    """ "Both bits on offer, the pair of them, are for P" (the scene holding two things), or
    None."""
    m = re.match(_BOTH_BITS43R, text, _F)
    if m is None or len(lexicon.scene.objects) != 2:
        return None
    return f"Both things {m['rest']}"


def _counted_list43r(text: str, lexicon: Lexicon) -> str:
    """Session 43 (12r): a count said with the list it counts: "P gets the whole lot, all four of
    them: bottle, chips, cup and apple" (the whole lot being every object of the scene), "P has a
    pair of requests, namely X and Y", "P is owed two things, X and Y; see he gets both", "a full
    set of the Ks, meaning the small and the big" (every K of the scene), "Both bits on offer, the
    pair of them, are for P": the list, when the count (and 'the whole lot' or 'a full set') is
    what the scene and the list say; otherwise left to be refused."""
    low = text.lower()
    if not any(w in low for w in ("of them", "pair", "things", "requests", "set of", "both")):
        return text
    for said in (_all_n_of_them43r, _n_things43r, _full_set43r, _both_bits43r):
        out = said(text.strip(), lexicon)
        if out is not None and _reading(out, lexicon) is not None:
            return out
    return text


# -- choices and distributions ---------------------------------------------------------------------

# "Alice and Bob get something apiece, her the bottle and him the crisps"; "The students get a
# book apiece, red for Noah and green for Zoe"; "Give them one thing each, the way they asked: P
# wanted X, Q the Y"
_APIECE43R = (
    r"^(?:(?P<grp>.+?) (?:get|are getting|will get|'ll get|can have|are having|have)|give "
    r"(?P<grp2>them|the two of them|the pair of them|both of them|the [a-z]+s)) (?:something|one "
    r"thing|a thing|an? (?P<k>[a-z]+)|one (?P<k2>[a-z]+)) (?:apiece|each)(?:\s*,\s*(?:the way "
    r"they asked|as they asked|like they asked|as asked|as they wanted))?\s*[,:;-]\s*(?P<rest>.+?)"
    r"(?P<end>\s*[.!]?)$"
)


def _group43r(words: str, lexicon: Lexicon) -> list[str] | None:
    """The people a group ``words`` names ("Alice and Bob", "the students", "them": everyone of
    the scene), or None."""
    w = words.strip()
    if re.fullmatch(r"them|they|the two of them|the pair of them|both of them|both", w, _F):
        everyone = [h.id for h in lexicon.scene.humans]
        two = re.search(r"\b(?:two|pair|both)\b", w, _F) is not None
        return None if two and len(everyone) != 2 else everyone
    m = re.fullmatch(r"(?:the )?(?P<r>[a-z]+)s", w, _F)
    if m is not None:
        ids = [
            h.id for h in lexicon.scene.humans if m["r"].lower() in (a.lower() for a in h.aliases)
        ]
        return ids if len(ids) >= 2 else None
    parts = [p.strip() for p in re.split(r",|\band\b", w, flags=_F) if p.strip()]
    said = [_person42r(p, lexicon) for p in parts]
    found = [i for i in said if i is not None]
    if len(found) < 2 or len(found) != len(said) or len(set(found)) != len(found):
        return None
    return found


def _share43r(
    item: str, group: list[str], kind: str | None, lexicon: Lexicon
) -> tuple[str, str] | None:
    """One share of a distribution ``item`` ("her the bottle", "red for Noah", "P wanted the X",
    "P the chips"): (person id, object named whole), the person one of ``group`` (a pronoun
    fitting exactly one of them), or None."""
    it = item.strip()
    m = (
        re.fullmatch(r"(?P<w>him|her|he|she) (?P<x>.+)", it, _F)
        or re.fullmatch(r"(?P<x>.+?) (?:for|to) (?P<w>him|her|" + _WHO42R + r")", it, _F)
        or re.fullmatch(
            r"(?P<w>" + _WHO42R + r")(?: (?:wanted|wants|asked for|gets|is having|'s having|had|"
            r"'d like|would like))? (?P<x>(?:the|a|an) .+)",
            it,
            _F,
        )
    )
    if m is None:
        return None
    w, x = m["w"], m["x"].strip()
    if w.lower() in PRONOUN_SEX:
        fit = [p for p in group if _fits42r(p, w, lexicon)]
        if len(fit) != 1:
            return None
        pid = fit[0]
    else:
        found = _person42r(w, lexicon)
        if found is None or found not in group:
            return None
        pid = found
    if not re.match(r"^(?:the|a|an) ", x, _F):
        x = f"the {x} {kind}" if kind else f"the {x}"
    x = re.sub(r"^(?:a|an) ", "the ", x, flags=_F)
    if not _one_thing43r(x, lexicon):
        if kind and _one_thing43r(f"{x} {kind}", lexicon):
            x = f"{x} {kind}"
        else:
            return None
    return pid, x


def _apiece43r(text: str, lexicon: Lexicon) -> str:
    """Session 43 (12r): a distribution said with 'apiece' or 'each' and its shares after ("Alice
    and Bob get something apiece, her the bottle and him the crisps"; "The students get a book
    apiece, red for Noah and green for Zoe"; "Give them one thing each, the way they asked: P
    wanted X, Q the Y"): each person of the group one thing, a pronoun the one person of the
    group it fits, each person once and each thing once; otherwise left to be refused."""
    low = text.lower()
    if "apiece" not in low and "each" not in low:
        return text
    m = re.match(_APIECE43R, text.strip(), _F)
    if m is None:
        return text
    group = _group43r(m["grp"] or m["grp2"], lexicon)
    if group is None:
        return text
    kind = m["k"] or m["k2"]
    items = [i for i in re.split(r"\s*(?:,|;|\band\b)\s*", m["rest"], flags=_F) if i.strip()]
    shares = [_share43r(i, group, kind, lexicon) for i in items]
    if len(shares) != len(group) or any(s is None for s in shares):
        return text
    got = [s for s in shares if s is not None]
    if {p for p, _ in got} != set(group):
        return text
    objs = [i for _, x in got for i in _ids(x, lexicon, "object")]
    if len(set(objs)) != len(objs):
        return text
    names = {h.id: h.name for h in lexicon.scene.humans}
    said = " and ".join(f"{names[p]} {x}" for p, x in got)
    out = f"Give {said}{m['end'] or '.'}"
    return out if _reading(out, lexicon) is not None else text


# "P will take whatever's going, so pick any one of … for her."
_WHATEVER_GOING43R = (
    r"^(?P<p>" + _WHO42R + r")(?: will|'ll|'s| is| would|'d)? (?:take|have|be happy with|happy "
    r"with|settle for|make do with) (?:whatever's going|whatever is going|whatever there is|"
    r"anything going|whatever you've got|whatever you have|anything at all|anything)\s*[,;:-]\s*"
    r"(?:so )?(?P<rest>(?:pick|choose|grab|take|bring|get) (?:any|either|one) .+ (?:for|to) )"
    r"(?P<w>him|her|" + _WHO42R + r")(?P<end>\s*[.!]?)$"
)
# "P isn't bothered whether it's X or Y, so one of those for him."
_NOT_BOTHERED43R = (
    r"^(?P<p>" + _WHO42R + r")(?: isn't| is not|'s not| doesn't| does not)(?: really)? "
    r"(?:bothered|fussed|fussy|particular|mind|care)(?: about)? (?:whether|if|which)(?: it's| it "
    r"is)? (?P<x>" + _THING42R + r") or (?P<y>" + _THING42R + r")\s*[,;:-]\s*(?:so )?(?:one of "
    r"(?:those|them|the two|these)|either(?: one)?|whichever|any of them) (?:for|to) (?P<w>him|her|"
    + _WHO42R
    + r")(?P<end>\s*[.!]?)$"
)


# "Person B takes anything, so any of the four things will do him."
_TAKES_ANYTHING43R = (
    r"^(?P<p>" + _WHO42R + r")(?: will| would)? (?:takes?|has|have|eats?|uses?|likes?|'ll take|'ll "
    r"have) (?:anything|whatever there is|whatever's going)(?: at all| going)?\s*[,;:-]\s*(?:so )?"
    r"(?P<any>any|either) (?:one )?of the (?P<n>two|three|four|five|six) things (?:will|would) "
    r"(?:do|suit) (?:for )?(?P<w>him|her|" + _WHO42R + r")(?P<end>\s*[.!]?)$"
)


def _for_whom43r(pid: str, w: str, lexicon: Lexicon) -> bool:
    """Whether ``w`` (a pronoun or a name said after) may be person ``pid``."""
    if w.lower() in PRONOUN_SEX:
        return _fits42r(pid, w, lexicon)
    return _person42r(w, lexicon) == pid


def _any_will_do43r(text: str, lexicon: Lexicon) -> str:
    """Session 43 (12r): a person content with any thing, then the choice left to the robot:
    "P will take whatever's going, so pick any one of X, Y or Z for her" (the pick for P); "P
    isn't bothered whether it's X or Y, so one of those for him" ("X or Y for P")."""
    low = text.lower()
    if not any(w in low for w in ("whatever", "anything", "bothered", "fussed", "fussy", "mind")):
        return text
    m = re.match(_WHATEVER_GOING43R, text.strip(), _F)
    if m is not None:
        pid = _person42r(m["p"], lexicon)
        if pid is None or not _for_whom43r(pid, m["w"], lexicon):
            return text
        out = f"{_capital40r(m['rest'])}{m['p']}{m['end'] or '.'}"
        return out if _reading(out, lexicon) is not None else text
    m = re.match(_TAKES_ANYTHING43R, text.strip(), _F)
    if m is not None:
        pid = _person42r(m["p"], lexicon)
        if pid is None or not _for_whom43r(pid, m["w"], lexicon):
            return text
        out = f"Give {m['p']} {m['any'].lower()} of the {m['n']} things{m['end'] or '.'}"
        return out if _reading(out, lexicon) is not None else text
    m = re.match(_NOT_BOTHERED43R, text.strip(), _F)
    if m is not None:
        pid = _person42r(m["p"], lexicon)
        x, y = _thing42r(m["x"], None, lexicon), _thing42r(m["y"], m["x"], lexicon)
        if pid is None or x is None or y is None or not _for_whom43r(pid, m["w"], lexicon):
            return text
        out = f"{_capital40r(x)} or {y} for {m['p']}{m['end'] or '.'}"
        return out if _reading(out, lexicon) is not None else text
    return text


# "whichever comes to hand first", "whichever's nearest", "whichever you find first"
_TO_HAND43R = (
    r"\b(?P<w>whichever|whatever)(?:'s| is| comes| you (?:find|reach|see|get to|lay hands on|can "
    r"reach|can find)| turns up| is easiest| is nearer| is nearest| is closest| is handiest)"
    r"(?: (?:to hand|to you|up|out))?(?: (?:first|soonest|quickest|fastest))?(?=\s*[.!]?\s*$)"
)


def _to_hand43r(text: str, lexicon: Lexicon) -> str:
    """Session 43 (12r): "…, whichever comes to hand first" (whichever you find first, whichever's
    nearest, whichever is handiest): the choice left to the robot, "…, whichever"."""
    if "whichever" not in text.lower() and "whatever" not in text.lower():
        return text
    m = re.search(_TO_HAND43R, text.strip(), _F)
    if m is None:
        return text
    said = text.strip()[: m.start()]
    if " or " not in said.lower() and " one" not in said.lower():
        return text
    if len(_ids(said, lexicon, "object")) < 2 and not re.search(
        r"\b(?:an?|one of the)\b", said, _F
    ):
        return text  # "Give Bob (or Carol) the cup, whichever comes to hand": no choice of things
    out = re.sub(_TO_HAND43R, r"\g<w>", text.strip(), flags=_F)
    return out if _reading(out, lexicon) is not None else text


# "If there's a bottle about, any bottle at all, Person A would like it."
_IF_THERE_IS43R = (
    r"^if (?:there's|there is|you(?:'ve| have)? got|you can find|you see|you find) (?:a|an|any) "
    r"(?P<k>[a-z]+)(?: (?:about|around|going|handy|spare|to hand|free|left|lying around|anywhere))?"
    r"(?:\s*,\s*any (?:old )?(?P<k2>[a-z]+)(?: at all| will do| whatsoever)?)?\s*,\s*"
    r"(?:(?P<p1>"
    + _WHO42R
    + r") (?:would|'d|will|'ll|could|can) (?:like|love|have|take|appreciate|"
    r"use|do with) it|(?:give|bring|pass|hand) it to (?P<p2>" + _WHO42R + r")|it(?:'s| is) for "
    r"(?P<p3>" + _WHO42R + r"))(?P<end>\s*[.!]?)$"
)


def _if_there_is43r(text: str, lexicon: Lexicon) -> str:
    """Session 43 (12r): a condition on the scene ("If there's a bottle about, any bottle at all,
    Person A would like it"), which the scene answers: with one such thing, that thing for the
    person; with several, any one of them; with none, left to be refused."""
    if not text.lower().startswith("if "):
        return text
    m = re.match(_IF_THERE_IS43R, text.strip(), _F)
    if m is None or (m["k2"] and m["k2"].lower() != m["k"].lower()):
        return text
    who = next(w for w in (m["p1"], m["p2"], m["p3"]) if w)
    if _person42r(who, lexicon) is None or not _of_kind43r(m["k"], lexicon):
        return text
    many = len(_of_kind43r(m["k"], lexicon)) > 1
    out = f"Give {who} {'any' if many else 'the'} {m['k']}{m['end'] or '.'}"
    return out if _reading(out, lexicon) is not None else text


# -- refusals that name their readings -------------------------------------------------------------

# "One of the patients asked for the magazine; can't remember which."
_WHICH_PERSON43R = (
    r"\b(?P<said>(?:one|either|one or other) of (?:the (?P<r>[a-z]+?)s|them|those two|the two of "
    r"them)\b[^;.?!]*?[;,.:-]\s*(?:but |and )?(?:i )?(?:can't|cannot|can not|couldn't|don't|do "
    r"not|forget|forgot|i've forgotten|no idea)(?: (?:remember|recall|say|tell you|think|know))? "
    r"(?:which|who)(?: one| it was| of them)?)"
)


def which_person_lost43r(text: str, lexicon: Lexicon) -> None:
    """Session 43 (12r): "One of the patients asked for X; can't remember which" (one of them,
    I forget who): who gets it is not known, so the request is refused, naming each person it
    could be (those of the scene the word names, or everyone for 'them')."""
    low = text.lower()
    if "which" not in low and "who" not in low:
        return
    m = re.search(_WHICH_PERSON43R, text, _F)
    if m is None:
        return
    if not m["r"]:
        return  # "one of them …, no idea which": session 33's refusal names everyone
    role = m["r"].lower()
    ids = [h.id for h in lexicon.scene.humans if role in (a.lower() for a in h.aliases)]
    if len(ids) < 2:
        return
    people = " or ".join(person_name(i, lexicon) for i in ids)
    raise GroundingError(
        f"{m['said']!r}: who is meant is not said; it could be {people}: name the person"
    )


# "Give Person A one of them, you know the one I mean."
_MEANT_ONE43R = (
    r"\b(?P<said>(?:you know|you'll know) (?:the one|which one|which)(?: i mean| i'm on about| i "
    r"want)?|the one (?:i mean|i'm on about|i'm thinking of)|the usual one)(?=\s*[.!?,;]?\s*$)"
)


def meant_one43r(text: str) -> bool:
    """Session 43 (12r): whether ``text`` ends on "you know the one I mean" (the usual one, the one
    I'm thinking of): a thing the speaker does not name, which `offline._cut_off` does not take
    for a correction cut off ('I mean'); `meant_one_refused43r` names what it could be."""
    return re.search(_MEANT_ONE43R, text, _F) is not None


def meant_one_refused43r(text: str, lexicon: Lexicon) -> None:
    """Session 43 (12r): one thing the speaker means but does not name ("Give P one of them, you
    know the one I mean"): refused, naming each thing it could be (those of the kind said, or
    every object of the scene for 'one of them')."""
    m = re.search(_MEANT_ONE43R, text, _F)
    if m is None:
        return
    ids = _kind_said42r(text[: m.start()], lexicon)
    if not ids and re.search(r"\b(?:one of them|one of those|either of them|one)\b", text, _F):
        named = _ids(text[: m.start()], lexicon, "object")
        ids = sorted(named) if len(named) >= 2 else [o.id for o in lexicon.scene.objects]
    if len(ids) < 2:
        return
    raise GroundingError(
        f"{m['said']!r}: which one is meant is not said; it could be {' or '.join(ids)}: name the "
        "one"
    )


# "mr lee's blanket back to him please, the one he had on"
_WHOSE_ONE43R = (
    r"\b(?:[a-z]+'s|his|her|their) (?P<k>[a-z]+)\b.*?,\s*(?P<said>the one (?:that |which )?(?:he|"
    r"she|they) (?:had on|had|was using|used|was wearing|wore|had before|had earlier|had last "
    r"night|is used to|always has|usually has|likes|came in with|brought))(?=\s*[.!?,;]?\s*$)"
)


def whose_one43r(text: str, lexicon: Lexicon) -> None:
    """Session 43 (12r): a person's thing of a kind the scene holds two or more of, said as "the
    one he had on" (was using, came in with): which one is not known to the robot, so the
    request is refused, naming each object of that kind."""
    if "the one" not in text.lower():
        return
    m = re.search(_WHOSE_ONE43R, text, _F)
    if m is None:
        return
    ids = sorted(_ids(f"the {m['k']}", lexicon, "object"))
    if len(ids) < 2 or any(
        re.search(rf"\b{re.escape(a)}\b", text, _F)
        for o in lexicon.scene.objects
        if o.id in ids
        for a in o.aliases
        if _one_thing43r(f"the {a}", lexicon)
    ):
        return
    raise GroundingError(
        f"{m['said']!r}: which {m['k']} is meant is not said; it could be {' or '.join(ids)}: "
        "name the one"
    )


# "Could you give Person B whatever he asked for yesterday? I've forgotten what it was."
_ASKED_BEFORE43R = (
    r"\b(?P<said>(?:whatever|what|the thing|the things|whichever) (?:he|she|they|[a-z]+) "
    r"(?:asked for|wanted|ordered|had|requested|put in for) (?:yesterday|earlier|before|last time|"
    r"this morning|last night|the other day|last week))\b"
)


def asked_before43r(text: str, lexicon: Lexicon) -> None:
    """Session 43 (12r): "give P whatever he asked for yesterday" (earlier, last time): what
    was asked for then is not known to the robot, so the request is refused, naming each object
    of the scene it could be."""
    low = text.lower()
    if not any(
        w in low for w in ("yesterday", "earlier", "before", "last", "morning", "other day")
    ):
        return
    m = re.search(_ASKED_BEFORE43R, text, _F)
    if m is None or _ids(text, lexicon, "object"):
        return
    ids = [o.id for o in lexicon.scene.objects]
    if len(ids) < 2:
        return
    raise GroundingError(
        f"{m['said']!r}: what was asked for then is not said; it could be {' or '.join(ids)}: "
        "name the thing"
    )


# a typo of a correction word ("actulaly", "insted"): the word
_CUE_WORDS43R = ("actually", "instead")
# words one edit from those that are words of their own
_NOT_CUE_TYPOS43R = frozenset({"factually", "actual"})


def _cue_typo43r(text: str, lexicon: Lexicon) -> str:
    """Session 43 (12r): a correction word with a one-edit typo ("the magazine actulaly",
    "insted"): the word, so that what it corrects is read as a correction (12c's session-42
    sentence once read both things)."""
    del lexicon

    def fix(m: re.Match[str]) -> str:
        word = m[0]
        cue = _cue_of_typo43r(word.lower())
        return word if cue is None else cue

    return re.sub(r"\b[a-z]{6,9}\b", fix, text, flags=_F)


@functools.lru_cache(maxsize=4096)
def _cue_of_typo43r(low: str) -> str | None:
    """The correction word one edit from ``low`` (a lower-cased word), None where there is none
    or ``low`` is a word of its own (kept per word, session 53, 12p: asked of every word of six
    to nine letters of every text)."""
    if low in _NOT_CUE_TYPOS43R:
        return None
    for cue in _CUE_WORDS43R:
        if _one_edit(low, cue):
            return cue
    return None


# the normaliser's rewrites run before the session-42 ones (wired into normalise._STEPS19)
_STEPS43R_FIRST: tuple[Callable[[str, Lexicon], str], ...] = (
    _cue_typo43r,
    _mid_sized43r,
    _slip_cue43r,
)
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
    _any_except43r,
    _only_the_one43r,
    _one_said43r,
    _counted_list43r,
    _apiece43r,
    _any_will_do43r,
    _to_hand43r,
    _if_there_is43r,
)
# refusals asked of the text before it is read (offline._parse, after the session-42 ones)
REFUSE43R: tuple[Callable[[str, Lexicon], None], ...] = (
    which_person_lost43r,
    meant_one_refused43r,
    whose_one43r,
    asked_before43r,
)
# checks of the whole instruction's reading (offline.parse_instruction, after the session-42 ones)
CHECK43R: tuple[Callable[[str, Node, Lexicon], None], ...] = ()
