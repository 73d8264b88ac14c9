"""The grounder's rules of session 52, engineer 12r (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _names
from hltl.grounding._rewrites44r import _agrees44r
from hltl.grounding._rewrites46r import _P46R, _person46r
from hltl.grounding._rewrites51r import _BACK51R, _CUE51R, _one_task51r
from hltl.grounding.lexicon import Lexicon
from hltl.grounding.tree import Node

# -- 12c's fuzz: wrong readings of session 51 ---------------------------------------------------

# "…, I mean the black one, my bad. Sam gets the notepad too.": the speaker owning the mistake
# just corrected, at the end of the correction's sentence
_MEANT_MINE52R = re.compiled(
    r"(?P<fix>\bi mean(?:t)?\b[^.!?;]*?)\s*,\s*(?:oops\s*,?\s*)?(?:my bad|my mistake|my fault|"
    r"my error)\s*(?=[.!;]|$)",
    _F,
)


def _meant_mine52r(text: str, lexicon: Lexicon) -> str:
    """Session 52 (12r): "<request>, I mean <the fix>, my bad." owns the mistake the 'I mean'
    has just corrected: the closer taken off. Session 42's `_owned_mistake42r` had read it as
    owning the request and taken a next sentence for the correction ("…, I mean the black one,
    my bad. Sam gets the notepad too." read notebook>B only: 12c's fuzz)."""
    low = text.lower()
    if "i mean" not in low or "my " not in low:
        return text
    return _MEANT_MINE52R.sub(lambda m: m["fix"], text)


# "Whichever of the chips and the apple, Person A is happy with one, Person B too."
_TOO_AFTER52R = re.compiled(
    rf"(?:^|[,;.]\s*)(?P<p>{_P46R}|she|he)(?:'s| is| isn't| is not| was| wasn't| would be|'d be|"
    r"'ll be| will be| doesn't| does not| don't| can| could| will| would| likes| loves| wants| "
    rf"needs)\b[^,;.]*[,;]\s*(?:and\s+)?(?P<q>{_P46R})\s+(?:too|as well|also)\s*(?=[.!;]|$)",
    _F,
)


def _too_after52r(text: str, lexicon: Lexicon) -> None:
    """Session 52 (12r): a remark of one person then ", Q too" ("Whichever of the chips and the
    apple, Person A is happy with one, Person B too") says the same of Q: who gets the thing is
    not said (the grammar had dropped the remark and read "…, Person B" as the one who gets it:
    12c's fuzz): refused."""
    low = text.lower()
    if " too" not in low and "as well" not in low and " also" not in low:
        return
    for m in _TOO_AFTER52R.finditer(text):
        qid = _person46r(m["q"], lexicon)
        if qid is None:
            continue
        said = m["p"].lower() in ("she", "he")
        pid = None if said else _person46r(m["p"], lexicon)
        if pid == qid or (pid is None and not said):
            continue
        raise GroundingError(
            f"{m.group(0).strip(' ,;.')!r} says the same of {m['q']}: who gets it is not said; "
            "name the person who gets each thing"
        )


# -- blind50: corrections ------------------------------------------------------------------------

# "…, no, hold your horses, they were Bob's.", "…, no, tell you what, straight into P's hand.": a
# filler between the correction's cue and what it says
_FILLER52R = re.compiled(
    rf"(?P<cue>,\s*{_CUE51R})(?:hold your horses|steady on|tell you what|hang fire|wait a sec|"
    r"one sec|half a sec|come to think of it|thinking about it|on second thoughts?)\s*,\s*",
    _F,
)
# "…, no, they were Bob's": whose the things were, said in the past
_WERE_HIS52R = re.compiled(
    rf"(?P<cue>,\s*{_CUE51R})(?P<it>they|it)(?: were| was) (?P<p>{_P46R})'s"
    r"(?P<end>(?:\s+actually)?\s*[.!]?)$",
    _F,
)


def _filler_fix52r(text: str, lexicon: Lexicon) -> str:
    """Session 52 (12r): a filler after a correction's cue ("…, no, hold your horses, …", "…, no,
    tell you what, …", "…, wait, steady on, …") is taken off, and "they were (it was) P's" after
    the cue is "they're (it's) P's": the correction as sessions 19-51 read it. Taken only when
    the head is one task and the result one task of the same kind or a delivery."""
    low = text.lower()
    if "," not in low or not _BACK51R.search(text):
        return text
    out = _FILLER52R.sub(lambda m: m["cue"].rstrip() + " ", text.strip())
    m = _WERE_HIS52R.search(out)
    if m is not None and _person46r(m["p"], lexicon) is not None:
        now = "they're" if m["it"].lower() == "they" else "it's"
        out = f"{out[: m.start()]}{m['cue']}{now} {m['p']}'s{m['end']}"
    if out == text.strip():
        return text
    back = _BACK51R.search(out)
    head = out[: back.start() if back is not None else 0].rstrip(" ,;")
    if _one_task51r(f"{head}.", lexicon) is None and not _VAGUE52R.match(head):
        return text
    return out


# "Stick the bottle down somewhere": a placing that names no place
_VAGUE52R = re.compiled(
    r"^(?:just )?(?:put|stick|pop|set|leave|plonk|drop) (?P<x>the [a-z]+(?: [a-z]+)?) (?:down )?"
    r"(?:somewhere|anywhere|wherever)(?: (?:you like|handy|safe|for now))?$",
    _F,
)
# … corrected to a person: "…, no, (straight) into Person A's hand(s)" / "…, no, to Person A"
_VAGUE_TO52R = re.compiled(
    rf"^(?P<head>[^,;]+?)\s*,\s*(?P<cue>{_CUE51R})(?:(?:straight|right) )?(?:(?:into|in) "
    rf"(?P<p>{_P46R})'s hands?|to (?P<q>{_P46R}))(?P<end>\s*[.!]?)$",
    _F,
)


def _vague_to52r(text: str, lexicon: Lexicon) -> str:
    """Session 52 (12r): a placing that names no place ("Stick the bottle down somewhere"), then a
    correction to a person ("…, no, straight into Person A's hand", "…, no, to Bob") is "Give
    <the person> <the thing>": the correction says where it goes."""
    low = text.lower()
    if "," not in low or (
        "somewhere" not in low and "anywhere" not in low and "wherever" not in low
    ):
        return text
    m = _VAGUE_TO52R.match(text.strip())
    if m is None or not _BACK51R.search(m["cue"]):
        return text
    v = _VAGUE52R.match(m["head"].strip())
    who = m["p"] or m["q"]
    if v is None or _person46r(who, lexicon) is None:
        return text
    out = f"Give {who} {v['x']}{m['end'] or '.'}"
    got = _one_task51r(out, lexicon)
    return out if got is not None and got[0] == "deliver" else text


# "…, no, he said apple, not chips.": what the person said, and not the first thing
_SAID_FIX52R = re.compiled(
    rf"^(?P<head>[^,;]+?)\s*,\s*(?P<cue>{_CUE51R})(?P<w>she|he|{_P46R}) (?:said|says|asked for|"
    r"wants|wanted|meant) (?P<x>(?:the )?[a-z]+(?: [a-z]+)?)\s*,\s*not (?P<y>(?:the )?[a-z]+"
    r"(?: [a-z]+)?)(?P<end>\s*[.!]?)$",
    _F,
)


def _said_fix52r(text: str, lexicon: Lexicon) -> str:
    """Session 52 (12r): a handover, a correction cue, then "he said X, not Y" (the person the
    handover is for; Y the thing first said) is "<handover>, no, the X": the thing corrected."""
    if " not " not in text.lower() or "," not in text:
        return text
    m = _SAID_FIX52R.match(text.strip())
    if m is None or not _BACK51R.search(m["cue"]):
        return text
    first = _one_task51r(f"{m['head']}.", lexicon)
    if first is None or first[0] != "deliver":
        return text
    w = m["w"].lower()
    if w in ("she", "he"):
        if not _agrees44r(first[2], w, lexicon):
            return text
    elif _person46r(m["w"], lexicon) != first[2]:
        return text
    x = m["x"] if m["x"].lower().startswith("the ") else f"the {m['x']}"
    y = {r.id for it in _names(m["y"], lexicon) for r in it.refs}
    if y != {first[1]}:
        return text
    out = f"{m['head']}, no, {x}{m['end'] or '.'}"
    got = _one_task51r(out, lexicon)
    if got is None or got[0] != "deliver" or got[2] != first[2] or got[1] == first[1]:
        return text
    return out


# "Give Person A the, um, the bottle I meant to say."
_MEANT_TO_SAY52R = re.compiled(
    r"\s+(?:i meant to say|i mean to say|is what i meant|i meant)(?P<end>\s*[.!]?)$",
    _F,
)


def _meant_to_say52r(text: str, lexicon: Lexicon) -> str:
    """Session 52 (12r): a request closed by "I meant to say" after its one thing ("Give P the,
    um, the bottle I meant to say") is the request: the speaker naming the thing she meant.
    Taken only when the text names one object (with two it corrects one: session 19's rule)."""
    if "meant" not in text.lower() and "mean to" not in text.lower():
        return text
    m = _MEANT_TO_SAY52R.search(text.strip())
    if m is None:
        return text
    head = text.strip()[: m.start()]
    objs = {r.id for it in _names(head, lexicon) for r in it.refs if r.kind == "object"}
    if len(objs) != 1 or not re.search(r"\bthe [a-z]+(?: [a-z]+)?$", head, _F):
        return text
    out = f"{head}{m['end'] or '.'}"
    return out if _one_task51r(out, lexicon) is not None else text


# "…, no, hang on, Priya wants it left out on the desk."
_LEFT_OUT52R = re.compiled(r"\b(?P<it>it|them) left out (?P<on>on|in)\b", _F)


def _left_out52r(text: str, lexicon: Lexicon) -> str:
    """Session 52 (12r): "P wants it left out on the desk" after a correction cue is "P wants it
    left on the desk" (session 51's `_kept_on51r` reads it as the place corrected)."""
    if "left out" not in text.lower() or not _BACK51R.search(text):
        return text
    return _LEFT_OUT52R.sub(lambda m: f"{m['it']} left {m['on']}", text)


# "…, actually no, lock it away in the locker for the night."
_AWAY_IN52R = re.compiled(
    rf"^(?P<head>[^,;]+?)\s*,\s*(?P<cue>{_CUE51R})(?:lock|put|stick|pop|stash|tuck|shut|keep|"
    r"pack) (?:it|them)(?: away)? (?P<prep>in|into|on|onto|inside) (?P<s>the [a-z]+)(?: for the "
    r"night| overnight| for now| for later| for safekeeping| for the weekend)?(?P<end>\s*[.!]?)$",
    _F,
)


def _away_in52r(text: str, lexicon: Lexicon) -> str:
    """Session 52 (12r): a placing, a correction cue, then "lock it away in the locker (for the
    night)" is "<placing>, no, in the locker": the same thing placed there (how long it stays
    there is no other task)."""
    low = text.lower()
    if " it " not in low and " them " not in low:
        return text
    m = _AWAY_IN52R.match(text.strip())
    if m is None or not _BACK51R.search(m["cue"]):
        return text
    first = _one_task51r(f"{m['head']}.", lexicon)
    if first is None or first[0] != "place":
        return text
    prep = "on" if m["prep"].lower() in ("on", "onto") else "in"
    out = f"{m['head']}, no, {prep} {m['s']}{m['end'] or '.'}"
    got = _one_task51r(out, lexicon)
    if got is None or got[:2] != first[:2] or got == first:
        return text
    return out


# "…, oh hang on, I've muddled my names, Carol's the one who asked."
_WHO_ASKED52R = re.compiled(
    rf"(?P<p>{_P46R})(?:'s| is) the one (?P<who>who|that) (?P<did>asked|ordered|was asking|'s been "
    r"asking|has been asking|wanted|was after)(?P<end>\s*[.!]?)$",
    _F,
)
# the speaker owning a mix-up of names before the fix
_MUDDLED52R = re.compiled(
    rf"(?P<cue>,\s*{_CUE51R})(?:i've|i have|i) (?:muddled|mixed up|got muddled|got mixed up|"
    r"confused|mixed) (?:my|the) names(?: (?:up|again|there))?\s*,\s*",
    _F,
)


def _who_asked52r(text: str, lexicon: Lexicon) -> str:
    """Session 52 (12r): a correction closed by "P's the one who asked" (no 'for it') is "…, P's
    the one who asked for it" (session 51's `_the_one_is51r`), and "I've muddled my names"
    between the cue and the fix is taken off."""
    low = text.lower()
    if "the one" not in low or not _BACK51R.search(text):
        return text
    out = _MUDDLED52R.sub(lambda m: m["cue"].rstrip() + " ", text.strip())
    m = _WHO_ASKED52R.search(out)
    if m is not None and _person46r(m["p"], lexicon) is not None:
        out = f"{out[: m.start('who')]}{m['who']} asked for it{m['end']}"
    return text if out == text.strip() else out


# the normaliser's first rewrites (wired into normalise._STEPS19, before the session-51 ones)
_STEPS52R_FIRST: tuple[Callable[[str, Lexicon], str], ...] = ()
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-51 ones)
_STEPS52R: tuple[Callable[[str, Lexicon], str], ...] = (
    _meant_mine52r,
    _filler_fix52r,
    _vague_to52r,
    _said_fix52r,
    _meant_to_say52r,
    _left_out52r,
    _away_in52r,
    _who_asked52r,
)
# refusals asked of the text before it is read (offline._parse, after the session-51 ones)
REFUSE52R: tuple[Callable[[str, Lexicon], None], ...] = (_too_after52r,)
# checks of the whole instruction's reading (offline.parse_instruction, after the session-51 ones)
CHECK52R: tuple[Callable[[str, Node, Lexicon], None], ...] = ()
