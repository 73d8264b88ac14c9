"""The grounder's rules of session 49, engineer 12r (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _ids, _reading
from hltl.grounding._rewrites42s import _remark_only42s
from hltl.grounding._rewrites44r import _agrees44r, _read_or44r
from hltl.grounding._rewrites46r import _P46R, _person46r
from hltl.grounding._rewrites47r import _thing47r
from hltl.grounding._rewrites48r import _choice_for48r
from hltl.grounding.lexicon import Lexicon
from hltl.grounding.tree import Node, tasks

# -- blind47: corrections -------------------------------------------------------------------------

# a thing said with 'the' (its second word no preposition: "the cup to his club")
_THING49R = (
    r"the [a-z]+(?: (?!(?:to|for|at|from|with|in|on|into|onto|home|so|and|or|out|up)\b)[a-z]+)?"
)
# the words of a cue that take the request back, each one of these ('hmm' or 'oh' alone do not)
_CUE49R = (
    r"(?:(?:oh|ah|er|erm|um|hmm|no|sorry|actually|wait|hang on|hold on|scratch that|strike that|"
    r"my mistake|my bad|whoops|oops)\s*,?\s*)+"
)
_BACK49R = re.compiled(
    r"\b(?:no|sorry|wait|hang on|hold on|scratch that|strike that|my mistake|my bad|whoops|oops)\b",
    _F,
)
# a second thought or a muddle owned between the cue and the person it corrects to
_RETHINK49R = (
    r"(?:thinking about it|come to think of it|now i think about it|on second thoughts?|"
    r"i'm muddling them(?: up)?|i'm mixing them up|i've got them mixed up|i've mixed them up|"
    r"i've muddled them(?: up)?|i'm getting them muddled(?: up)?)"
)

# "The cup is for Person A, scratch that, it's Person B who's playing twister and needs it.",
# "Person B for the bottle, hmm, no, thinking about it, it was Person A who asked.", "Marco asked
# for the salt shaker, didn't he, no, sorry, I'm muddling them, it was Lena.", "Kofi needs the
# hammer, sorry, it's Jess who needs it, Kofi's on the brickie's job."
_CLEFT49R = re.compiled(
    r"^(?P<head>[^,;]+?)(?:\s*,\s*(?:didn't|did|doesn't|does|wasn't|isn't|hasn't) "
    rf"(?:he|she|they))?\s*,\s*(?P<cue>{_CUE49R})(?:{_RETHINK49R}\s*,\s*)?"
    rf"it(?:'s| is| was) (?P<q>{_P46R})(?: who(?P<vp>(?:'s| is| was)? [^,.;!?]+?))?"
    r"(?:\s*,\s*(?P<why>[^,.;!?]+?))?(?P<end>\s*[.!]?)$",
    _F,
)
# "Person B for the bottle, no, Person A." (the grammar read two recipients)
_FOR_FIRST49R = re.compiled(
    rf"^(?P<head>{_P46R} for the [a-z]+(?: [a-z]+)?)\s*,\s*(?P<cue>{_CUE49R})(?P<q>{_P46R})"
    r"(?P<end>\s*[.!]?)$",
    _F,
)
# what the person corrected to did: asked, or wants it (after doing something)
_CLEFT_VP49R = re.compiled(
    r"(?:(?:'s| is| was) (?P<act>[a-z' ]+?) and)? (?:needs|wants|needed|wanted|asked for|"
    r"would like|'d like|is after|was after) (?:it|them)|(?: had)? asked(?: first| earlier| for "
    r"(?:it|them))?",
    _F,
)
# why the first person does not get it: "Kofi's on the brickie's job"
_CLEFT_WHY49R = re.compiled(
    rf"(?:(?:as|since|because|cos) )?(?P<w>{_P46R}|he|she)(?:'s| is| was| has|'s got) "
    r"(?P<rest>[a-z' ]+)",
    _F,
)


def _targets49r(node: Node | None) -> set[str] | None:
    """The one person every task of a reading hands its thing to ({pid}), or None."""
    if node is None:
        return None
    got = list(tasks(node))
    if not got or any(t.kind != "deliver" for t in got):
        return None
    return {t.target for t in got}


def _heads49r(head: str) -> tuple[str, ...]:
    """``head`` and, when it is 'P for the X', 'the X for P' (what the grammar's correction
    reads: "Person B for the bottle, no, Person A" was read as two recipients)."""
    m = re.fullmatch(rf"(?P<p>{_P46R}) for (?P<x>the [a-z]+(?: [a-z]+)?)", head.strip(), _F)
    return (head,) if m is None else (f"{m['x']} for {m['p']}", head)


def _cleft49r(text: str, lexicon: Lexicon) -> str:
    """Session 49 (12r): a request for one person, a cue, then "it's Q who needs it" / "it was
    Q who asked" (after a second thought or a muddle owned, "thinking about it", "I'm muddling
    them"; after a tag "didn't he"), closed perhaps by why the first person does not need it
    (naming that person or Q and nothing else of the scene): the request to Q. Read only when
    the request reads as handing things to one person and the rewrite hands the same to Q."""
    low = text.lower()
    if "it's " not in low and "it was " not in low and "it is " not in low and " for " not in low:
        return text
    m = _CLEFT49R.match(text.strip()) or _FOR_FIRST49R.match(text.strip())
    if m is None or not _BACK49R.search(m["cue"]):
        return text
    q = _person46r(m["q"], lexicon)
    if q is None:
        return text
    said = m.groupdict()
    if said.get("vp") is not None:
        vp = _CLEFT_VP49R.fullmatch(m["vp"])
        if vp is None or (vp["act"] and not _remark_only42s(vp["act"], lexicon)):
            return text
    for head in _heads49r(m["head"]):
        first = _reading(f"{head}.", lexicon)
        was = _targets49r(first)
        if first is None or was is None or len(was) != 1 or q in was:
            continue
        if said.get("why") is not None and not _why_fits49r(m["why"], {*was, q}, lexicon):
            return text
        out = f"{head}, no, {m['q']}{m['end'] or '.'}"
        if " ".join(out.split()) == " ".join(text.split()):
            continue  # the text itself (its plain form): asked again it would ask again
        node = _reading(out, lexicon)
        same = node is not None and {t.obj for t in tasks(node)} == {t.obj for t in tasks(first)}
        if _targets49r(node) == {q} and same:
            return out
    return text


def _why_fits49r(why: str, people: set[str], lexicon: Lexicon) -> bool:
    """Whether a closing ``why`` says something of one of ``people`` (a name or a pronoun that
    fits one) and names nothing else of the scene."""
    m = _CLEFT_WHY49R.fullmatch(why.strip())
    if m is None or not _remark_only42s(m["rest"], lexicon):
        return False
    if m["w"].lower() in ("he", "she"):
        return any(_agrees44r(p, m["w"], lexicon) for p in people)
    return _person46r(m["w"], lexicon) in people


# "Up on the shelf with the crisps, oh, actually, no, Bob's just said he'd like them."
_SAYS_WANTS49R = re.compiled(
    rf"^(?P<head>[^,;]+?)\s*,\s*(?P<cue>{_CUE49R})(?P<p>{_P46R})(?:'s| has)? (?:just |now )?"
    r"(?:said|told (?:me|us)|mentioned|shouted|called out) (?:that )?(?P<pro>he|she)(?:'d like|"
    r" would like| wants| needs|'d love| would love) (?P<it>it|them)(?: after all)?"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _says_wants49r(text: str, lexicon: Lexicon) -> str:
    """Session 49 (12r): one thing said (a placing, or a hand-over), a cue, then "P's just said
    he'd like them": P gets that thing (the pronoun P)."""
    low = text.lower()
    if " said " not in low and " told " not in low and "mentioned" not in low:
        return text
    m = _SAYS_WANTS49R.match(text.strip())
    if m is None or not _BACK49R.search(m["cue"]):
        return text
    pid = _person46r(m["p"], lexicon)
    if pid is None or not _agrees44r(pid, m["pro"], lexicon) or _ids(m["head"], lexicon, "human"):
        return text
    objs = _ids(m["head"], lexicon, "object")
    if len(objs) != 1:
        return text
    thing = _thing47r(next(iter(objs)), lexicon)
    if thing is None:
        return text
    out = f"Give {m['p']} {thing}{m['end'] or '.'}"
    node = _reading(out, lexicon)
    if _targets49r(node) != {pid}:
        return text
    return out


# "Take Mr Lee the blue blanket, hold on, not that, the grey one."
_NOT_THAT49R = re.compiled(
    rf"(?P<cue>,\s*{_CUE49R})not that\s*,\s*(?=the [a-z]+(?: [a-z]+)?(?: one)?\s*[.!]?$)", _F
)


def _not_that49r(text: str, lexicon: Lexicon) -> str:
    """Session 49 (12r): "…, hold on, not that, the grey one" is "…, hold on, not that one,
    the grey one" (what the grammar reads)."""
    if "not that," not in text.lower() and "not that ," not in text.lower():
        return text
    m = _NOT_THAT49R.search(text)
    if m is None or not _BACK49R.search(m["cue"]):
        return text
    out = f"{text[: m.start()]}{m['cue']}not that one, {text[m.end() :]}"
    return _read_or44r(out, text, lexicon)


# -- blind47: choices left to one person ----------------------------------------------------------


def _one49r(kind: str) -> str:
    """A kind's plural said as one ('mugs' -> 'mug', 'boxes' -> 'box')."""
    low = kind.lower()
    if re.search(r"(?:x|s|sh|ch)es$", low):
        return kind[:-2]
    return kind[:-1] if low.endswith("s") and not low.endswith("ss") else kind


# "Bob isn't fussy about mugs, red or blue, just give him one."
_FUSSY_ABOUT49R = re.compiled(
    rf"^(?P<p>{_P46R})(?: isn't| is not|'s not| ain't| doesn't mind| does not mind) "
    r"(?:fussy |fussed |bothered |picky |choosy )?(?:about|over|with|which) (?P<k>[a-z]+)"
    r"\s*,\s*(?P<x>[a-z]+) or "
    r"(?P<y>[a-z]+)\s*,\s*(?:(?:so |just )?(?:give|hand|pass|bring) (?P<pro>him|her) (?:one|either|"
    r"either one|any|any one|whichever)(?: of them)?)(?P<end>\s*[.!]?)$",
    _F,
)


def _fussy_about49r(text: str, lexicon: Lexicon) -> str:
    """Session 49 (12r): "P isn't fussy about mugs, red or blue, just give him one" is "Give P a
    mug, red or blue" (a choice left to P; the pronoun P)."""
    low = text.lower()
    if " or " not in low or (" one" not in low and "either" not in low and " any" not in low):
        return text
    m = _FUSSY_ABOUT49R.match(text.strip())
    if m is None:
        return text
    pid = _person46r(m["p"], lexicon)
    if pid is None or not _agrees44r(pid, m["pro"], lexicon):
        return text
    head = f"Give {m['p']} a {_one49r(m['k'])}, {m['x']} or {m['y']}"
    return _choice_for48r(head, "", m["end"], text, lexicon)


# "Whatever Person A likes out of the apple and the cup."
_WHATEVER_OF49R = re.compiled(
    rf"^(?:whatever|whichever|anything|any one) (?P<p>{_P46R}) (?:likes|wants|fancies|prefers|"
    r"would like|'d like|picks|chooses)(?: best)?,? (?:out of|of|from|between) (?P<x>the [a-z]+"
    r"(?: [a-z]+)?) (?:and|or) (?P<y>the [a-z]+(?: [a-z]+)?)(?P<end>\s*[.!]?)$",
    _F,
)


def _whatever_of49r(text: str, lexicon: Lexicon) -> str:
    """Session 49 (12r): "Whatever P likes out of the apple and the cup" (whichever … of …,
    from …) is "P can have the apple or the cup"."""
    low = text.lower()
    if not low.startswith(("whatever", "whichever", "anything", "any one")):
        return text
    m = _WHATEVER_OF49R.match(text.strip())
    if m is None or _person46r(m["p"], lexicon) is None:
        return text
    return _choice_for48r(f"{m['p']} can have {m['x']} or {m['y']}", "", m["end"], text, lexicon)


# "Person A says she'll take the bottle or the chips, she honestly couldn't care which."
_CARE_WHICH49R = re.compiled(
    r"\s*,\s*(?:and |but )?(?P<pro>she|he)(?: honestly| really| genuinely| truly)? "
    r"(?:couldn't|could not|wouldn't|would not) care(?: less)? "
    r"(?:which|either way|which "
    r"one)(?: (?:she|he) gets)?(?P<end>\s*[.!]?)$",
    _F,
)


def _care_which49r(text: str, lexicon: Lexicon) -> str:
    """Session 49 (12r): a choice for one person closed by "she honestly couldn't care which"
    ("he couldn't care less which") is the choice (the pronoun that person); a closing
    doubt ("I can't remember which") stays the older rules' refusal."""
    if "care" not in text.lower():  # "doesn't mind / care which" are session 35's and 45's
        return text
    m = _CARE_WHICH49R.search(text.strip())
    if m is None:
        return text
    head = text.strip()[: m.start()]
    node = _reading(f"{head}.", lexicon)
    was = _targets49r(node)
    if was is None or len(was) != 1 or not _agrees44r(next(iter(was)), m["pro"], lexicon):
        return text
    return _choice_for48r(head, "", m["end"], text, lexicon)


# "Person B can take whichever of the two he prefers."
_OF_THE_TWO49R = re.compiled(
    rf"^(?P<p>{_P46R})(?:'ll| will| can| may| could) (?:take|have|pick|choose|grab|go for) "
    r"(?:whichever|either|any|the one) of the (?:two|pair)(?: (?P<k>[a-z]+))?(?: (?:that )?(?P<pro>"
    r"she|he) (?:prefers|likes|wants|fancies|likes best|would like|'d like))?(?P<end>\s*[.!]?)$",
    _F,
)


def _of_the_two49r(text: str, lexicon: Lexicon) -> str:
    """Session 49 (12r): "P can take whichever of the two (Ks) he prefers" is a choice of the
    scene's two things (of that kind), when it has exactly two."""
    if " of the two" not in text.lower() and " of the pair" not in text.lower():
        return text
    m = _OF_THE_TWO49R.match(text.strip())
    if m is None:
        return text
    pid = _person46r(m["p"], lexicon)
    if pid is None or (m["pro"] and not _agrees44r(pid, m["pro"], lexicon)):
        return text
    ids = _ids(f"the {m['k']}", lexicon, "object") if m["k"] else _all_objects49r(lexicon)
    objs = [o.id for o in lexicon.scene.objects if o.id in ids]
    if len(objs) != 2:
        return text
    said = [_thing47r(o, lexicon) for o in objs]
    if None in said:
        return text
    return _choice_for48r(f"{m['p']} can have {said[0]} or {said[1]}", "", m["end"], text, lexicon)


def _all_objects49r(lexicon: Lexicon) -> set[str]:
    """Every object of the scene."""
    return {o.id for o in lexicon.scene.objects}


# "Alice is taking both the bottle and the crisps to her snakes and ladders night, so give them
# both to her."
_BOTH_TAKING49R = re.compiled(
    rf"^(?P<p>{_P46R})(?:'s| is)? (?:taking|bringing|after|wanting|needing|wants|needs|asked for|"
    rf"has asked for|'s asked for) both (?P<x>{_THING49R}) and (?P<y>{_THING49R})"
    r"(?P<why>[^,;.!?]*?)\s*,\s*so (?:give|hand|pass|take|bring) (?:them|the two|"
    r"both)(?: both)?(?: over)? to (?P<to>her|him|[a-z][a-z ]*?)(?P<end>\s*[.!]?)$",
    _F,
)


def _both_taking49r(text: str, lexicon: Lexicon) -> str:
    """Session 49 (12r): "P is taking both the X and the Y (to …), so give them both to her" is
    "Give P the X and the Y" (the pronoun P; the words after the things naming nothing else of
    the scene)."""
    if "both" not in text.lower() or "so " not in text.lower():
        return text
    m = _BOTH_TAKING49R.match(text.strip())
    if m is None:
        return text
    pid = _person46r(m["p"], lexicon)
    if pid is None:
        return text
    to = m["to"].lower()
    if (to in ("her", "him") and not _agrees44r(pid, to, lexicon)) or (
        to not in ("her", "him") and _person46r(m["to"], lexicon) != pid
    ):
        return text
    why = re.sub(r"\b(?:her|his)\b", "", m["why"], flags=_F)
    if why.strip() and not _remark_only42s(why, lexicon):
        return text
    out = f"Give {m['p']} {m['x']} and {m['y']}{m['end'] or '.'}"
    node = _reading(out, lexicon)
    if _targets49r(node) != {pid} or node is None or len(list(tasks(node))) != 2:
        return text
    return out


# "Something for both of them, please: Person A's to get the cup and the apple is for Person B."
_SOMETHING_FOR49R = re.compiled(
    r"^(?:something|a little something|one thing|a thing|a treat) (?:for|each for) (?:both|each|"
    r"all|the two|the pair) of them(?:\s*,\s*please)?\s*:\s*(?P<rest>.+)$",
    _F,
)


def _something_for49r(text: str, lexicon: Lexicon) -> str:
    """Session 49 (12r): "Something for both of them, please: <who gets what>" is what follows
    the colon, when it hands something to every person of the scene (and only hands things
    over); otherwise ('both of them' when one is left out) it stays refused."""
    if ":" not in text or "of them" not in text.lower():
        return text
    m = _SOMETHING_FOR49R.match(text.strip())
    if m is None:
        return text
    out = m["rest"]
    out = out[:1].upper() + out[1:]
    node = _reading(out, lexicon)
    got = _targets49r(node)
    if got is None or got != {h.id for h in lexicon.scene.humans}:
        return text
    return out


# "Each of the girls gets a block, the red for Lily and the green for Ava."
_EACH_OF_THE49R = re.compiled(
    r"^each of the (?:two )?(?P<who>girls|boys|lads|ladies|gents|men|women)(?: gets| is getting|"
    r" has| can have| wants| needs) (?:a|one) (?P<k>[a-z]+)\s*[,:]\s*(?P<rest>.+?)"
    r"(?P<end>\s*[.!]?)$",
    _F,
)
_SEX49R = {
    "girls": "she",
    "ladies": "she",
    "women": "she",
    "boys": "he",
    "lads": "he",
    "gents": "he",
}


def _each_of_the49r(text: str, lexicon: Lexicon) -> str:
    """Session 49 (12r): "Each of the girls gets a block, the red for Lily and the green for
    Ava" is the hand-out after the comma (each bare colour given the kind), when it hands one
    thing of that kind to every person of the scene the group word fits ('girls': everyone
    said to be female) and to no one else."""
    if not text.lower().startswith("each of the"):
        return text
    m = _EACH_OF_THE49R.match(text.strip())
    if m is None or m["who"].lower() == "men":
        return text
    pro = _SEX49R.get(m["who"].lower(), "he")
    group = {
        h.id
        for h in lexicon.scene.humans
        if _agrees44r(h.id, pro, lexicon) and not _agrees44r(h.id, _OTHER49R[pro], lexicon)
    }
    kind = m["k"]
    rest = re.sub(
        rf"\bthe (?P<a>[a-z]+)(?! {kind}\b)(?= (?:for|to)\b)",
        rf"the \g<a> {kind}",
        m["rest"],
        flags=_F,
    )
    out = f"{rest[:1].upper()}{rest[1:]}{m['end'] or '.'}"
    node = _reading(out, lexicon)
    got = _targets49r(node)
    if node is None or got != group or len(group) < 2:
        return text
    done = list(tasks(node))
    if len(done) != len(group):
        return text
    if not {t.obj for t in done} <= _ids(f"the {kind}", lexicon, "object"):
        return text
    return out


_OTHER49R = {"she": "he", "he": "she"}


# -- blind47: counts said of the scene ------------------------------------------------------------

# 'just the one bottle', 'a single bottle', 'only one bottle'
_ONE_X49R = (
    r"(?:(?:just |only )?(?:the )?one|(?:just |only )?a single|the single|the only|one single) "
    r"(?P<x>[a-z]+(?: [a-z]+)?)"
)
_AROUND49R = r"(?: (?:here|there|in the room|on hand|about|around|going|left|to hand|in here))?"


def _the_one49r(x: str, lexicon: Lexicon) -> str | None:
    """A phrase naming the scene's one X ('bottle' -> 'the bottle'), when the scene has exactly
    one thing ``x`` names (and it is an object), else None."""
    objs = _ids(f"the {x}", lexicon, "object")
    if len(objs) != 1 or _ids(f"the {x}", lexicon) != objs:
        return None
    kind = next(o.category for o in lexicon.scene.objects if o.id in objs)
    if sum(o.category == kind for o in lexicon.scene.objects) != 1:
        return None
    return _thing47r(next(iter(objs)), lexicon)


def _it_is49r(rest: str, thing: str, oid: str, lexicon: Lexicon) -> str | None:
    """``rest`` with its first 'it' the thing (a request that reads as handing over or placing
    that thing alone), else None."""
    if re.search(r"\bit\b", rest, _F) is None:
        return None
    out = re.sub(r"\bit\b", thing, rest, count=1, flags=_F)
    out = f"{out[:1].upper()}{out[1:]}"
    node = _reading(out, lexicon)
    if node is None or {t.obj for t in tasks(node)} != {oid}:
        return None
    return out


# "Seeing as there's just the one bottle, let Person B have it.", "Since there's a single cup, give
# it to Bob."
_SEEING_AS_ONE49R = re.compiled(
    rf"^(?:seeing as|seeing that|since|as|because|given that|what with) there(?:'s| is) {_ONE_X49R}"
    rf"{_AROUND49R}\s*,\s*(?:so )?(?P<rest>.+)$",
    _F,
)


def _seeing_as_one49r(text: str, lexicon: Lexicon) -> str:
    """Session 49 (12r): "Seeing as there's just the one bottle, let P have it": when the scene
    has exactly one, the request after the comma with 'it' that thing; otherwise refused."""
    low = text.lower()
    if "there" not in low or ("one" not in low and "single" not in low and "only" not in low):
        return text
    m = _SEEING_AS_ONE49R.match(text.strip())
    if m is None:
        return text
    thing = _the_one49r(m["x"], lexicon)
    if thing is None:
        return text
    out = _it_is49r(m["rest"], thing, next(iter(_ids(thing, lexicon))), lexicon)
    return text if out is None else out


# "With just the one bottle in the room and Person A the only one here, hand it over to her."
_WITH_ONE49R = re.compiled(
    rf"^with {_ONE_X49R}{_AROUND49R} and (?P<p>{_P46R}) the only (?:one|person|body|soul)"
    rf"{_AROUND49R}\s*,\s*(?:so )?(?P<rest>.+)$",
    _F,
)


def _with_one49r(text: str, lexicon: Lexicon) -> str:
    """Session 49 (12r): "With just the one bottle in the room and P the only one here, hand it
    over to her": when the scene has exactly one such thing and P is its only person, the
    request with 'it' the thing and 'her' / 'him' P."""
    if not text.lower().startswith("with ") or "only" not in text.lower():
        return text
    m = _WITH_ONE49R.match(text.strip())
    if m is None:
        return text
    pid = _person46r(m["p"], lexicon)
    thing = _the_one49r(m["x"], lexicon)
    if pid is None or thing is None or len(lexicon.scene.humans) != 1:
        return text
    rest = m["rest"]
    pro = re.search(r"\b(?:her|him)\b", rest, _F)
    if pro is not None:
        if not _agrees44r(pid, pro[0], lexicon):
            return text
        rest = f"{rest[: pro.start()]}{m['p']}{rest[pro.end() :]}"
    out = _it_is49r(rest, thing, next(iter(_ids(thing, lexicon))), lexicon)
    return text if out is None else out


# "There's a single bottle on hand, and Bob's the one to get it."
_ONE_TO_GET49R = re.compiled(
    r"^there(?:'s| is) (?:(?:just |only )?a single|one single|the single) (?P<x>[a-z]+(?: [a-z]+)?)"
    rf"{_AROUND49R}\s*,?\s*(?:and|so) (?P<p>{_P46R})(?:'s| is) the "
    r"(?:one|person) (?:to get|to have|to take|who gets|getting|who should get|who should have) "
    r"it(?P<end>\s*[.!]?)$",
    _F,
)

# "Person A only asked for a single bottle, so that's what she gets."
_ASKED_ONE49R = re.compiled(
    rf"^(?P<p>{_P46R}) (?:only |just )?(?:asked for|asked me for|wanted|wants|needs|needed) "
    r"(?:(?:just |only )?(?:the )?one|(?:just |only )?a single|one single) (?P<x>[a-z]+"
    r"(?: [a-z]+)?)\s*,\s*so (?:that's (?:what|all) (?P<pro>she|he) (?:gets|should get|'ll get|"
    r"will get|can have)|give (?P<pro2>her|him) (?:that|just that|the one))(?P<end>\s*[.!]?)$",
    _F,
)


def _one_to_get49r(text: str, lexicon: Lexicon) -> str:
    """Session 49 (12r): "There's a single bottle on hand, and Bob's the one to get it" and "P
    only asked for a single bottle, so that's what she gets" are "Give P the bottle" when the
    scene has exactly one (the pronoun P); otherwise refused."""
    low = text.lower()
    if "one" not in low and "single" not in low:
        return text
    m = _ONE_TO_GET49R.match(text.strip()) or _ASKED_ONE49R.match(text.strip())
    if m is None:
        return text
    pid = _person46r(m["p"], lexicon)
    thing = _the_one49r(m["x"], lexicon)
    if pid is None or thing is None:
        return text
    pro = m.groupdict().get("pro") or m.groupdict().get("pro2")
    if pro and not _agrees44r(pid, pro, lexicon):
        return text
    out = f"Give {m['p']} {thing}{m['end'] or '.'}"
    return out if _targets49r(_reading(out, lexicon)) == {pid} else text


# "The bottle, to Person A, since it's the only thing there is."
_ONLY_THING49R = re.compiled(
    r"\s*,\s*(?:since|as|seeing as|because|cos|being as) (?:it's|it is|that's|that is) the only "
    r"(?P<x>thing|object|one|[a-z]+)(?: (?:there is|there|here|in the room|we have|we've got|going|"
    r"around|about|left))?(?P<end>\s*[.!]?)$",
    _F,
)


def _only_thing49r(text: str, lexicon: Lexicon) -> str:
    """Session 49 (12r): a hand-over closed by "since it's the only thing there is" (or "the
    only bottle here"): true of the scene (one thing in it, or one of that kind), taken off."""
    if "only" not in text.lower():
        return text
    m = _ONLY_THING49R.search(text.strip())
    if m is None:
        return text
    head = text.strip()[: m.start()]
    node = _reading(f"{head}.", lexicon)
    if node is None:
        return text
    objs = {t.obj for t in tasks(node)}
    x = m["x"].lower()
    whole = _all_objects49r(lexicon) if x in ("thing", "object", "one") else None
    if whole is None:
        thing = _the_one49r(m["x"], lexicon)
        whole = set() if thing is None else _ids(thing, lexicon, "object")
    if len(objs) != 1 or objs != whole:
        return text
    return f"{head}{m['end'] or '.'}"


# -- blind47: pairs -------------------------------------------------------------------------------

# "Marco's flipping the fish and needs the pair of tongs.", "Give Zoe the pair of scissors."
_PAIR_OF49R = re.compiled(r"\b(?:the|a|that|this|one|your) pair of (?P<x>[a-z]+(?: [a-z]+)?)\b", _F)


def _pair_of49r(text: str, lexicon: Lexicon) -> str:
    """Session 49 (12r): "the pair of tongs" ("a pair of scissors") is the one thing whose name
    is that plural ('tongs', 'scissors'): "the tongs" (a kind with two things, "a pair of
    books", is left to the count rules)."""
    if "pair of" not in text.lower():
        return text
    out = text
    for m in reversed(list(_PAIR_OF49R.finditer(text))):
        x = m["x"]
        for said in (x, x.split()[0]):
            objs = _ids(f"the {said}", lexicon, "object")
            if (
                len(objs) == 1
                and said.lower().endswith("s")
                and _ids(f"the {said}", lexicon) == objs
            ):
                after = m.start() + len(m[0]) - len(x) + len(said)
                out = f"{out[: m.start()]}the {said}{out[after:]}"
                break
    return _read_or44r(out, text, lexicon)


# "Shelf for the pair of them, the bottle and the crisps, before leapfrog starts."
_SURFACE_FOR49R = re.compiled(
    r"^(?P<s>[a-z]+(?: [a-z]+)?) for (?:(?:the pair|both|the two|the lot) of them\s*,\s*)?"
    r"(?P<list>(?:the )?[a-z]+(?: [a-z]+)? and (?:the )?[a-z]+(?: [a-z]+)?)(?P<tail>\s*,\s*"
    r"[^,;.!?]+)?(?P<end>\s*[.!]?)$",
    _F,
)


def _surface_for49r(text: str, lexicon: Lexicon) -> str:
    """Session 49 (12r): "Shelf for the pair of them, the bottle and the crisps, (before …)" (a
    surface first, then what goes on it) is "The bottle and the crisps on the shelf, …"; the
    words after 'for' name objects only ('Shelf for Bob' is no placing)."""
    if " for " not in text.lower():
        return text
    m = _SURFACE_FOR49R.match(text.strip())
    if m is None:
        return text
    place = _ids(f"the {m['s']}", lexicon)
    things = _ids(m["list"], lexicon)
    if len(place) != 1 or _ids(f"the {m['s']}", lexicon, "surface") != place:
        return text
    if len(things) != 2 or _ids(m["list"], lexicon, "object") != things:
        return text
    out = (
        f"{m['list'][:1].upper()}{m['list'][1:]} on the {m['s']}{m['tail'] or ''}{m['end'] or '.'}"
    )
    node = _reading(out, lexicon)
    if node is None or {(t.kind, t.obj, t.target) for t in tasks(node)} != {
        ("place", o, next(iter(place))) for o in things
    }:
        return text
    return out


# "Person A gets both of the things there are, the whole pair."
_BOTH_THERE_ARE49R = re.compiled(
    r"\bboth (?:of )?(?:the )?things (?:there are|here|in the room|we've got|we have|going)"
    r"(?:\s*,\s*(?:the whole pair|the pair of them|both of them|the two of them))?(?=\s*[.!]?$)",
    _F,
)


def _both_there_are49r(text: str, lexicon: Lexicon) -> str:
    """Session 49 (12r): "P gets both of the things there are(, the whole pair)" is "P gets both
    things" when the scene has exactly two."""
    if "both" not in text.lower() or len(lexicon.scene.objects) != 2:
        return text
    m = _BOTH_THERE_ARE49R.search(text)
    if m is None:
        return text
    return _read_or44r(f"{text[: m.start()]}both things{text[m.end() :]}", text, lexicon)


# "For the sign language lesson Mrs Ortiz wants a pair of books out, so set the two books down on
# the desk."
_WANTS_OUT49R = re.compiled(
    rf"^(?:for (?P<why>[^,;]+?),? )?(?P<p>{_P46R}) (?:wants|needs|would like|'d like|has asked for|"
    r"asked for) (?P<what>(?:a pair of|the pair of|the two|two|both(?: the)?|the) [a-z]+(?: "
    r"[a-z]+)?) (?:out|ready|handy|to hand|laid out|set out|out ready|got out)\s*,\s*so "
    r"(?P<rest>.+)$",
    _F,
)


def _wants_out49r(text: str, lexicon: Lexicon) -> str:
    """Session 49 (12r): "(For the … lesson) P wants a pair of books out, so set the two books
    down on the desk": the request after 'so', when it places (or hands over) exactly the things
    the want names, as many as it counts."""
    low = text.lower()
    if " out" not in low and "ready" not in low and "hand" not in low:
        return text
    m = _WANTS_OUT49R.match(text.strip())
    if m is None or _person46r(m["p"], lexicon) is None:
        return text
    if m["why"] is not None and not _remark_only42s(m["why"], lexicon):
        return text
    what = re.sub(
        r"^(?:a pair of|the pair of|the two|two|both(?: the)?|the) ", "", m["what"], flags=_F
    )
    objs = _ids(f"the {what}", lexicon, "object")
    counted = (
        1
        if m["what"].lower().startswith("the ")
        and not m["what"].lower().startswith(("the two", "the pair"))
        else 2
    )
    if len(objs) != counted:
        return text
    out = f"{m['rest'][:1].upper()}{m['rest'][1:]}"
    node = _reading(out, lexicon)
    if node is None or {t.obj for t in tasks(node)} != objs:
        return text
    return out


# "Teddy to Lily, no, to whoever else asked for it at teatime, I can't think who."
_WHOEVER_ELSE49R = re.compiled(
    rf"^(?P<head>[^,;]+?)\s*,\s*(?P<cue>{_CUE49R})(?:to |for )?whoever(?: else)? (?:asked for|"
    r"wanted|wants|needs|needed|was after|is after) (?:it|them)[^,;.!?]*?\s*,\s*(?:but )?i "
    r"(?:can't|cannot|can not|couldn't|don't|do not) (?:think|remember|recall|say|know)(?: who)?"
    r"\s*[.!]?$",
    _F,
)


def whoever_else49r(text: str, lexicon: Lexicon) -> None:
    """Session 49 (12r): "Teddy to Lily, no, to whoever else asked for it at teatime, I can't
    think who": the thing goes to someone the speaker cannot name: refused naming the scene's
    other people (those the request did not name)."""
    if "whoever" not in text.lower():
        return
    m = _WHOEVER_ELSE49R.match(text.strip())
    if m is None or not _BACK49R.search(m["cue"]):
        return
    said = _ids(m["head"], lexicon, "human")
    others = [h.name for h in lexicon.scene.humans if h.id not in said]
    if not others:
        return
    raise GroundingError(
        f"'whoever else asked for it' is someone the speaker cannot name: it could be "
        f"{' or '.join(others)}; say who"
    )


# -- 12c's chains (session 49): a second correction closed by 'then'; a settled choice changed -----

# "Give Bob the apple, no, Carol, um, the cup then."
_THEN_AGAIN49R = re.compiled(
    rf"(?P<head>,\s*{_CUE49R}(?:to |for )?[a-z][a-z ]*?\s*,\s*"
    r"(?:(?:um|er|erm|hmm|uh|well)\s*,?\s*)*(?:the [a-z]+(?: [a-z]+)?|[a-z]+)) then"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def then_again49r(text: str, _lexicon: Lexicon) -> None:
    """Session 49 (12r; 12c's chains): "…, no, Carol, um, the cup then": a name said alone
    after the correction's name, closed by 'then', had read as one more step (apple>C ; cup>C);
    'then' there is 'in that case' (the cup instead of the apple) or the order (the cup after
    it): refused naming both."""
    if not text.rstrip(" .!").lower().endswith(" then"):
        return
    m = _THEN_AGAIN49R.search(text)
    if m is None or not _BACK49R.search(m["head"]):
        return
    said = m["head"].split(",")[-1].strip()
    raise GroundingError(
        f"{said!r} closed by 'then' after the correction could replace what it corrects (in "
        "that case) or come after it (then): say the whole request again"
    )


# "Lemon for Marco, or Lena, so Lena, or no, Marco."
_SETTLED_AGAIN49R = re.compiled(
    r"\bor\b[^.;!?]*?,\s*so (?P<x>[a-z][a-z ]*?)\s*,\s*(?:or|no|actually|wait|hang on|hold on|"
    r"sorry|well)\b",
    _F,
)


def settled_again49r(text: str, _lexicon: Lexicon) -> None:
    """Session 49 (12r; 12c's chains): a choice said with 'or', settled with 'so X', then
    changed again ("…, or Lena, so Lena, or no, Marco") had read as a choice of all three:
    refused (which one is meant is for the speaker to say once)."""
    if ", so " not in text.lower():
        return
    m = _SETTLED_AGAIN49R.search(text)
    if m is not None:
        raise GroundingError(
            f"'so {m['x']}' settles the choice and what follows changes it again: say which one"
        )


# the normaliser's first rewrites (wired into normalise._STEPS19, before the session-48 ones)
_STEPS49R_FIRST: tuple[Callable[[str, Lexicon], str], ...] = ()
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-48 ones)
_STEPS49R: tuple[Callable[[str, Lexicon], str], ...] = (
    _cleft49r,
    _says_wants49r,
    _not_that49r,
    _fussy_about49r,
    _whatever_of49r,
    _care_which49r,
    _of_the_two49r,
    _both_taking49r,
    _something_for49r,
    _each_of_the49r,
    _seeing_as_one49r,
    _with_one49r,
    _one_to_get49r,
    _only_thing49r,
    _pair_of49r,
    _surface_for49r,
    _both_there_are49r,
    _wants_out49r,
)
# refusals asked of the text before it is read (offline._parse, after the session-48 ones)
REFUSE49R: tuple[Callable[[str, Lexicon], None], ...] = (
    then_again49r,
    settled_again49r,
    whoever_else49r,
)
# checks of the whole instruction's reading (offline.parse_instruction, after the session-48 ones)
CHECK49R: tuple[Callable[[str, Node, Lexicon], None], ...] = ()
