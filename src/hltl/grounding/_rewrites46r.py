"""The grounder's rules of session 46, engineer 12r (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _ids, _reading
from hltl.grounding._rewrites39 import doubt_which39
from hltl.grounding._rewrites42s import _remark_only42s
from hltl.grounding._rewrites44r import _CUE44R, _agrees44r, _read_or44r
from hltl.grounding.lexicon import Lexicon
from hltl.grounding.tree import Node, tasks

# -- corrections -----------------------------------------------------------------------------------

# "Run the cup over to Person B, or rather the apple, the cup's cracked.", "Bowl goes in the sink,
# correction, the tray, the sink's full of …", "…, no, sorry, the grey one, blue's too thin."
_FIX_WHY46R = re.compiled(
    rf"^(?P<head>.+?[,;]\s*(?:{_CUE44R}|or rather|rather|i mean|i meant)\b.*?)\s*,\s*"
    r"(?P<subj>(?:the |that )?[a-z]+)(?:'s|'re| is| are) (?P<why>[^,;.!?]+?)(?P<end>\s*[.!]?)$",
    _F,
)


def _fix_why46r(text: str, lexicon: Lexicon) -> str:
    """Session 46 (12r): after a correction, a closing reason said of what the correction took
    away ("…, or rather the apple, the cup's cracked"; "…, correction, the tray, the sink's full of
    the hermit's crockery"; "…, no, sorry, the grey one, blue's too thin") is dropped: its subject
    is a thing or place said before the cue and not in the corrected reading, and it names
    nothing else of the scene."""
    if "'s" not in text and " is " not in text and "'re" not in text and " are " not in text:
        return text
    m = _FIX_WHY46R.match(text.strip())
    if m is None or not _remark_only42s(m["why"], lexicon):
        return text
    head = m["head"]
    node = _reading(head, lexicon)
    if node is None:
        return text
    used = {t.obj for t in tasks(node)} | {t.target for t in tasks(node)}
    away = _ids(head, lexicon) - used - _ids(head, lexicon, "human")
    subj = m["subj"].lower().removeprefix("the ").removeprefix("that ")
    said = _ids(m["subj"], lexicon) or {
        o.id
        for o in lexicon.scene.objects
        if o.id in away and _ids(f"the {subj} {o.category}", lexicon) == {o.id}
    }
    # the subject is what was corrected away ("the mug" of two mugs: the one said before), and
    # nothing the corrected request hands over or places on
    if not said & away or said & used or said & _ids(head, lexicon, "human"):
        return text
    return _read_or44r(f"{head}{m['end'] or '.'}", text, lexicon)


# "Give Alice the crisps, no, scratch the lot of that, it's Bob who wants the bottle."
_SCRATCH_LOT46R = re.compiled(
    r"\bscratch (?:the lot of that|the lot|all (?:of )?that|all (?:of )?what i (?:just )?said|"
    r"everything i (?:just )?said)(?=\s*[,;])",
    _F,
)


def _scratch_lot46r(text: str, lexicon: Lexicon) -> str:
    """Session 46 (12r): "scratch the lot of that" ("scratch all that", "scratch everything I
    just said") after a cue that takes the request back is "scratch that"."""
    if "scratch" not in text.lower():
        return text
    m = _SCRATCH_LOT46R.search(text)
    if m is None or not re.search(rf"[,;.]\s*(?:{_CUE44R}\s*,?\s*)+$", text[: m.start()], _F):
        return text
    return _read_or44r(f"{text[: m.start()]}scratch that{text[m.end() :]}", text, lexicon)


# -- whichever, any of, one of, both, each ---------------------------------------------------------

# "Person B asked for one of the cup or the apple at the footvolley match, I can't recall which."
_DOUBT_AT46R = re.compiled(
    r"(?P<a>\b(?:the|a|an) [a-z]+(?: [a-z]+)?) or (?P<b>(?:the|a|an) [a-z]+(?: [a-z]+)?)"
    r"(?P<at> (?:at|during|after|before|in|on|over|from|for) [^,;.!?]+?)(?=\s*[,;.-]\s*(?:but |and "
    r")?(?:i (?:can't|cannot|can not|don't|do not|didn't|couldn't) (?:remember|recall|know|say)|"
    r"i forget|i've forgotten|i'm not sure|not sure|no idea|dunno)(?: now| exactly| offhand)? "
    r"which\b)",
    _F,
)


def doubt_at46r(text: str, lexicon: Lexicon) -> None:
    """Session 46 (12r): session 39's doubt ("the cup or the apple, I can't recall which")
    with a time or place said between the choice and the doubt ("… at the footvolley match, I
    can't recall which"), the words naming nothing of the scene: refused as session 39's
    `doubt_which39` refuses it, naming both things."""
    if "which" not in text.lower():
        return
    m = _DOUBT_AT46R.search(text)
    if m is None or not _remark_only42s(m["at"], lexicon):
        return
    doubt_which39(text[: m.start("at")] + text[m.end("at") :], lexicon)


# "Lily wants one of her blocks, either will do."
_ONE_OF_HERS46R = re.compiled(
    r"^(?P<p>[A-Za-z][\w ]*?) (?P<v>wants|needs|would like|'d like|is after|asked for) "
    r"(?P<one>one|either|any) of (?P<pro>her|his) (?P<k>[a-z]+s)\b",
    _F,
)


def _one_of_hers46r(text: str, lexicon: Lexicon) -> str:
    """Session 46 (12r): "Lily wants one of her blocks" is "Lily wants one of the blocks" when
    'her' may be Lily and the blocks are things of the scene (whose they are picks none out)."""
    if " of her " not in text.lower() and " of his " not in text.lower():
        return text
    m = _ONE_OF_HERS46R.match(text.strip())
    if m is None:
        return text
    pids = _ids(m["p"], lexicon, "human")
    if len(pids) != 1 or _ids(m["p"], lexicon) != pids:
        return text
    (pid,) = pids
    if not _agrees44r(pid, m["pro"], lexicon) or len(_ids(m["k"], lexicon, "object")) < 2:
        return text
    out = f"{text.strip()[: m.start('pro')]}the{text.strip()[m.end('pro') :]}"
    return _read_or44r(out, text, lexicon)


# -- counts and plurals ----------------------------------------------------------------------------

_COUNT46R = {"two": 2, "three": 3, "four": 4, "five": 5, "both": 2}

# "Person B wants the bottle and the cup, just those two."
_JUST_THOSE46R = re.compiled(
    r"\s*[,;]\s*(?:just|only)(?: the| those| these)? (?P<n>two|three|four|five)"
    r"(?: of them| things| items)?(?: only)?(?P<end>\s*[.!]?)$",
    _F,
)


def _just_those46r(text: str, lexicon: Lexicon) -> str:
    """Session 46 (12r): a closing count "…, just those two" ("only the three", "just those two
    items") after a request that hands over exactly that many things is dropped."""
    if "just" not in text.lower() and "only" not in text.lower():
        return text
    m = _JUST_THOSE46R.search(text.strip())
    if m is None:
        return text
    head = text.strip()[: m.start()]
    node = _reading(head, lexicon)
    if node is None:
        return text
    objs = [t.obj for t in tasks(node)]
    if len(objs) != _COUNT46R[m["n"].lower()] or len(set(objs)) != len(objs):
        return text
    if _ids(head, lexicon, "object") != set(objs):
        return text
    return _read_or44r(f"{head}{m['end'] or '.'}", text, lexicon)


# "Person A wants the one apple, the only one there is."
_ONLY_ONE46R = re.compiled(
    r"\s*[,;]\s*the only (?:one|[a-z]+) (?:there is|there's|we have|we've got|going|in the "
    r"place|left|around)(?P<end>\s*[.!]?)$",
    _F,
)


def _only_one46r(text: str, lexicon: Lexicon) -> str:
    """Session 46 (12r): "…the one apple, the only one there is" drops the closing "the only one
    there is" when the request names one thing and the scene holds no other of its kind."""
    if "only" not in text.lower():
        return text
    m = _ONLY_ONE46R.search(text.strip())
    if m is None:
        return text
    head = text.strip()[: m.start()]
    objs = _ids(head, lexicon, "object")
    if len(objs) != 1:
        return text
    (oid,) = objs
    cat = next(o.category for o in lexicon.scene.objects if o.id == oid)
    if sum(1 for o in lexicon.scene.objects if o.category == cat) != 1:
        return text
    word = m[0].lower().split("only ", 1)[1].split()[0]
    if word != "one" and _ids(word, lexicon, "object") != objs:
        return text
    return _read_or44r(f"{head}{m['end'] or '.'}", text, lexicon)


# "The two items there, both of them, go to Person A …"
_ITEMS_THERE46R = re.compiled(
    r"^(?P<lead>(?:the|all) (?P<n>two|three|four|five) (?:items|things|objects)) (?:there|here|"
    r"over there|you can see)(?=\s*,\s*(?:both|all(?: (?:two|three|four|five))?) of them\s*,)",
    _F,
)


def _items_there46r(text: str, lexicon: Lexicon) -> str:
    """Session 46 (12r): "The two items there, both of them, go to P" is "The two items, both of
    them, go to P" when the scene holds that many things ('there' points at all of them)."""
    if "there" not in text.lower() and "here" not in text.lower() and "see" not in text.lower():
        return text
    m = _ITEMS_THERE46R.match(text.strip())
    if m is None or len(lexicon.scene.objects) != _COUNT46R[m["n"].lower()]:
        return text
    return _read_or44r(f"{m['lead']}{text.strip()[m.end() :]}", text, lexicon)


# "For the titration Dana needs the pair of cups, green and white both."
_AND_BOTH46R = re.compiled(
    r"(?P<pair>,\s*(?:the )?(?P<a>[a-z]+)(?: one)? and (?:the )?(?P<b>[a-z]+)(?: one)?) both"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _and_both46r(text: str, lexicon: Lexicon) -> str:
    """Session 46 (12r): "…the pair of cups, green and white both" drops the closing 'both' when
    the two words before it are the two of a kind the clause names ("the green cup", "the white
    cup": the pair said again)."""
    if "both" not in text.lower():
        return text
    m = _AND_BOTH46R.search(text.strip())
    if m is None:
        return text
    head = text.strip()[: m.start()]
    kinds = {o.category for o in lexicon.scene.objects if o.id in _ids(head, lexicon, "object")}
    if len(kinds) != 1:
        return text
    (k,) = kinds
    a = _ids(f"the {m['a']} {k}", lexicon, "object")
    b = _ids(f"the {m['b']} {k}", lexicon, "object")
    if len(a) != 1 or len(b) != 1 or a == b:
        return text
    return _read_or44r(f"{head}{m['pair']}{m['end'] or '.'}", text, lexicon)


# the normaliser's first rewrites (wired into normalise._STEPS19, before the session-45 ones)
_STEPS46R_FIRST: tuple[Callable[[str, Lexicon], str], ...] = (_scratch_lot46r,)
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-45 ones)
_STEPS46R: tuple[Callable[[str, Lexicon], str], ...] = (
    _fix_why46r,
    _one_of_hers46r,
    _just_those46r,
    _only_one46r,
    _items_there46r,
    _and_both46r,
)
# refusals asked of the text before it is read (offline._parse, after the session-45 ones)
REFUSE46R: tuple[Callable[[str, Lexicon], None], ...] = (doubt_at46r,)
# checks of the whole instruction's reading (offline.parse_instruction, after the session-45 ones)
CHECK46R: tuple[Callable[[str, Node, Lexicon], None], ...] = ()
