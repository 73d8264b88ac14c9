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
    nothing else of the scene. (Session 47, the lead's decision: a place corrected away with any
    such reason, "…, sorry, the sink's broken", not only one that has no room.)"""
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
    return _dropped46r(head, m, text, lexicon)


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


# "Over to Person B with the bottle, oh, what am I saying, it's Person A who gets it, she's the
# only one here." (a scene with Person A alone)
_SLIP_LABEL46R = re.compiled(
    r"^(?P<head>[^,;.!?]+?)\s*,\s*(?:(?:oh|ah|er|um|no|nope|sorry|wait|hang on|whoops|oops|"
    r"what am i saying|what was i thinking|silly me|my mistake)\s*,?\s*)+it(?:'s| is) "
    r"(?P<p>[^,;.!?]+?) who (?:gets|wants|needs|should get|is getting|'s getting|asked for) "
    r"(?:it|them)(?:\s*,\s*(?P<pro>she|he)(?:'s| is) the only one (?:here|around|about))?"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _slip_label46r(text: str, lexicon: Lexicon) -> str:
    """Session 46 (12r): a request to a 'Person X' the scene lacks, a cue ("oh, what am I
    saying"), then "it's Person A who gets it" (", she's the only one here", when she is the
    scene's one person): the request to Person A (the label was a slip, as session 35's "or
    rather Person A, I keep mixing them up"); "Over to P with X" is "X over to P"."""
    if "who" not in text.lower() or "person" not in text.lower():
        return text
    m = _SLIP_LABEL46R.match(text.strip())
    if m is None:
        return text
    pid = _person46r(m["p"], lexicon)
    if pid is None:
        return text
    if m["pro"] is not None and not (
        len(lexicon.scene.humans) == 1 and _agrees44r(pid, m["pro"], lexicon)
    ):
        return text
    names = {h.name.lower() for h in lexicon.scene.humans}
    slips = [w for w in re.findall(r"\bperson [a-z]\b", m["head"], _F) if w.lower() not in names]
    if len(slips) != 1 or not _ids(m["head"], lexicon, "human") <= {pid}:
        return text  # ('Person B' of a scene with Person A alone is lexed as Person A)
    head = m["head"].replace(slips[0], m["p"])
    over = re.fullmatch(r"over to (?P<q>.+?) with (?P<x>the [a-z]+(?: [a-z]+)?)", head, _F)
    if over is not None:
        head = f"{over['x'][:1].upper()}{over['x'][1:]} over to {over['q']}"
    objs = _ids(m["head"], lexicon, "object")
    out = f"{head}{m['end'] or '.'}"
    node = _reading(out, lexicon)
    said = list(tasks(node)) if node is not None else []
    if len(said) != 1 or said[0].target != pid or said[0].obj not in objs:
        return text
    return out


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


def _closing46r(pattern: re.Pattern[str], text: str) -> tuple[str, re.Match[str]] | None:
    """What comes before ``pattern``'s match at the end of ``text``, and the match, or None."""
    m = pattern.search(text.strip())
    return None if m is None else (text.strip()[: m.start()], m)


def _dropped46r(head: str, m: re.Match[str], text: str, lexicon: Lexicon) -> str:
    """``head`` with the match's end (its stop), when it reads, else ``text``."""
    return _read_or44r(f"{head}{m['end'] or '.'}", text, lexicon)


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
    said = _closing46r(_JUST_THOSE46R, text)
    if said is None:
        return text
    head, m = said
    node = _reading(head, lexicon)
    if node is None:
        return text
    objs = [t.obj for t in tasks(node)]
    if len(objs) != _COUNT46R[m["n"].lower()] or len(set(objs)) != len(objs):
        return text
    if _ids(head, lexicon, "object") != set(objs):
        return text
    return _dropped46r(head, m, text, lexicon)


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
    said = _closing46r(_ONLY_ONE46R, text)
    if said is None:
        return text
    head, m = said
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
    return _dropped46r(head, m, text, lexicon)


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
    said = _closing46r(_AND_BOTH46R, text)
    if said is None:
        return text
    head, m = said
    kinds = {o.category for o in lexicon.scene.objects if o.id in _ids(head, lexicon, "object")}
    if len(kinds) != 1:
        return text
    (k,) = kinds
    a = _ids(f"the {m['a']} {k}", lexicon, "object")
    b = _ids(f"the {m['b']} {k}", lexicon, "object")
    if len(a) != 1 or len(b) != 1 or a == b:
        return text
    return _read_or44r(f"{head}{m['pair']}{m['end'] or '.'}", text, lexicon)


# -- session 46 (12r), a second batch ------------------------------------------------------------

_P46R = r"(?:Person [a-z]|(?:mrs|mr|ms|miss|dr) [a-z]+|[a-z]+)"


def _person46r(words: str, lexicon: Lexicon) -> str | None:
    """The one person ``words`` name (and nothing else), or None."""
    pids = _ids(words, lexicon)
    if len(pids) != 1 or _ids(words, lexicon, "human") != pids:
        return None
    return next(iter(pids))


def _all_to46r(out: str, text: str, pid: str, lexicon: Lexicon) -> str:
    """``out`` when it reads handing everything over to ``pid`` alone, else ``text``."""
    node = _reading(out, lexicon)
    if node is None or any(t.kind != "deliver" or t.target != pid for t in tasks(node)):
        return text
    return out


# "Person A is taking all four items to her quillwork circle.", "Alice is taking both on her munro
# bagging walk, the bottle and the crisps, so pass them to her."
_TAKING46R = re.compiled(
    rf"^(?P<p>{_P46R})(?:'s| is) taking (?P<x>[^,;.!?]+?)(?: (?:to|on|for) (?P<pro>her|his) "
    r"(?P<words>[^,;.!?]+?))?(?:\s*,\s*(?P<list>[^,;.!?]+?)\s*,\s*so (?P<v>pass|give|hand|bring|"
    r"take) them(?: over| across)? to (?P<pro2>her|him))?(?P<end>\s*[.!]?)$",
    _F,
)


def _taking46r(text: str, lexicon: Lexicon) -> str:
    """Session 46 (12r): "P is taking all four items to her quillwork circle" is "Give P all four
    items" (where she takes them names nothing of the scene), and "P is taking both (on
    her walk), the X and the Y, so pass them to her" is "Pass the X and the Y to P"; the she / he
    P, and every thing handed to P."""
    if "taking" not in text.lower():
        return text
    m = _TAKING46R.match(text.strip())
    if m is None or (m["pro"] is None and m["list"] is None):
        return text
    pid = _person46r(m["p"], lexicon)
    if pid is None:
        return text
    if m["pro"] is not None and not (
        _agrees44r(pid, m["pro"], lexicon) and _remark_only42s(m["words"], lexicon)
    ):
        return text
    end = m["end"] or "."
    if m["list"] is None:
        return _all_to46r(f"Give {m['p']} {m['x']}{end}", text, pid, lexicon)
    if not re.fullmatch(r"both|the pair|the two|all (?:three|four|five)|the lot", m["x"], _F):
        return text
    if not _agrees44r(pid, m["pro2"], lexicon) or _ids(m["list"], lexicon, "human"):
        return text
    out = f"{m['v'].capitalize()} {m['list']} to {m['p']}{end}"
    node = _reading(out, lexicon)
    n = _COUNT46R.get(m["x"].lower().split()[-1], 2)
    if node is None or len({t.obj for t in tasks(node)}) != n:
        return text
    return _all_to46r(out, text, pid, lexicon)


# "Ava's tower needs both blocks, so hand her the red and the green."
_THING_NEEDS46R = re.compiled(
    rf"^(?P<p>{_P46R})'s (?P<thing>[a-z]+(?: [a-z]+)?) (?P<v>needs|wants|could do with) "
    r"(?P<rest>[^,;.!?]+\s*,\s*so\b.*)$",
    _F,
)


def _thing_needs46r(text: str, lexicon: Lexicon) -> str:
    """Session 46 (12r): "Ava's tower needs both blocks, so hand her the red and the green" is
    "Ava needs both blocks, so …" when the thing of hers names nothing of the scene, the request
    after 'so' says her (him), and all it hands over goes to her."""
    if "'s " not in text:
        return text
    m = _THING_NEEDS46R.match(text.strip())
    if m is None or not _remark_only42s(m["thing"], lexicon):
        return text
    pid = _person46r(m["p"], lexicon)
    pro = re.search(r"\bso\b[^.;!?]*\b(?P<pro>her|him)\b", m["rest"], _F)
    if pid is None or pro is None or not _agrees44r(pid, pro["pro"], lexicon):
        return text
    return _all_to46r(f"{m['p']} {m['v']} {m['rest']}", text, pid, lexicon)


# "Mr Novak isn't fussy after his coin collecting fair, so either plate is fine for him.", "Bob's
# not particular about mugs, so your pick of the two for him."
_NOT_FUSSY46R = re.compiled(
    rf"^(?P<p>{_P46R})(?P<neg>'s not| is not| isn't) (?P<adj>fussy|particular|bothered|picky|"
    r"choosy)(?: (?:about|over|with) (?P<k>[a-z]+)| after (?P<pos>his|her) (?P<words>[^,;.!?]+?))?"
    r"\s*,\s*so (?:either (?P<k2>[a-z]+)|(?:take )?your (?:pick|choice) of the two) (?:(?:is|'s) "
    r"(?:fine|ok|okay|good|all right) |will do )?for (?P<pro>him|her)(?P<end>\s*[.!]?)$",
    _F,
)


def _not_fussy46r(text: str, lexicon: Lexicon) -> str:
    """Session 46 (12r): "P isn't fussy (about mugs, after his fair), so either plate is fine
    for him" ("your pick of the two"; 'particular', 'picky') is "P isn't fussy, so either plate for
    him": the kind said
    once of two things of the scene, the remark naming nothing of it, the he / she P."""
    if (
        "fussy" not in text.lower()
        and "particular" not in text.lower()
        and "picky" not in (text.lower())
    ):
        return text
    m = _NOT_FUSSY46R.match(text.strip())
    if m is None:
        return text
    pid = _person46r(m["p"], lexicon)
    if pid is None or not _agrees44r(pid, m["pro"], lexicon):
        return text
    if m["pos"] is not None and not (
        _agrees44r(pid, m["pos"], lexicon) and _remark_only42s(m["words"], lexicon)
    ):
        return text
    kinds = [k.lower() for k in (m["k"], m["k2"]) if k]
    if not kinds or len({k.rstrip("s") for k in kinds}) != 1:
        return text
    if len(_ids(kinds[0], lexicon, "object")) != 2 or _ids(kinds[0], lexicon, "human"):
        return text
    out = f"{m['p']} isn't fussy, so either {kinds[0].rstrip('s')} for {m['pro']}"
    return _read_or44r(f"{out}{m['end'] or '.'}", text, lexicon)


# "Priya wants a pen; black or red, up to you."
_A_K_OR46R = re.compiled(
    r"(?P<head>\b(?:wants|needs|would like|'d like|is after|asked for) an? (?P<k>[a-z]+))"
    r"\s*[;:,]\s*(?P<a>[a-z]+) or (?P<b>[a-z]+)(?=\s*(?:,\s*(?:up to you|your call|your choice|"
    r"either will do|whichever|you choose|you pick|you decide))?\s*[.!]?$)",
    _F,
)


def _a_k_or46r(text: str, lexicon: Lexicon) -> str:
    """Session 46 (12r): "P wants a pen; black or red, up to you" is "P wants a pen, the black
    or the red, …" when "the black pen" and "the red pen" are each one thing of the scene."""
    if " or " not in text.lower():
        return text
    m = _A_K_OR46R.search(text.strip())
    if m is None:
        return text
    a = _ids(f"the {m['a']} {m['k']}", lexicon, "object")
    b = _ids(f"the {m['b']} {m['k']}", lexicon, "object")
    if len(a) != 1 or len(b) != 1 or a == b:
        return text
    t = text.strip()
    out = f"{t[: m.end('head')]}, the {m['a']} or the {m['b']}{t[m.end() :]}"
    return _read_or44r(out, text, lexicon)


# "Tom can take any box except the big one, for the rag and bone man's odds and ends."
_FOR_WHOSE46R = re.compiled(
    r"\s*,\s*for (?:the|a|an|my|our|his|her) (?P<who>[a-z]+(?: [a-z]+){0,4}?)'s (?P<what>[a-z]+"
    r"(?: [a-z]+){0,3})(?P<end>\s*[.!]?)$",
    _F,
)


def _for_whose46r(text: str, lexicon: Lexicon) -> str:
    """Session 46 (12r): a closing purpose "…, for the rag and bone man's odds and ends" (an
    outsider's things, an 'and' in the words) is dropped when it names nothing of the scene and
    the request before it reads."""
    if "'s" not in text or " and " not in text.lower():
        return text
    said = _closing46r(_FOR_WHOSE46R, text)
    if said is None or " and " not in said[1][0].lower():
        return text
    head, m = said
    # 'and' inside the outsider's name and things joins no request ("rag and bone man")
    if not _remark_only42s(re.sub(r" and ", " ", f"{m['who']} {m['what']}", flags=_F), lexicon):
        return text
    return _dropped46r(head, m, text, lexicon)


# "Put the pair of books on the desk, Mrs Ortiz is reading aloud after break."
_PLACED_REMARK46R = re.compiled(
    rf"\s*,\s*(?P<p>{_P46R})(?:'s| is| will be|'ll be) (?P<words>[a-z]+ing\b[^,;.!?]*)"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


# what says a person gets, wants or holds something ("Sam's having a biscuit"), not what they do
_HAVING46R = re.compiled(
    r"(?:having|getting|taking|wanting|needing|asking|expecting|awaiting|waiting|hoping|"
    r"grabbing|borrowing|keeping|holding|using|bringing|fetching|receiving|eating|drinking)\b",
    _F,
)


def _placed_remark46r(text: str, lexicon: Lexicon) -> str:
    """Session 46 (12r): a closing remark on what a person of the scene is doing ("…, Mrs Ortiz
    is reading aloud after break") after a request that only places things is dropped: it hands
    that person nothing and names nothing else of the scene."""
    if "ing" not in text.lower():
        return text
    said = _closing46r(_PLACED_REMARK46R, text)
    if said is None or _person46r(said[1]["p"], lexicon) is None:
        return text
    head, m = said
    if _HAVING46R.match(m["words"]):
        return text  # "…, Sam's having a biscuit": a want or a handover, not a remark (session 35)
    if not _remark_only42s(re.sub(r"\b(?:his|her|their)\b", "", m["words"]), lexicon):
        return text
    node = _reading(head, lexicon)
    if node is None or any(t.kind != "place" for t in tasks(node)):
        return text
    return _dropped46r(head, m, text, lexicon)


# "Hand out a book per student, the red to Noah and the green one to Zoe, …"
_PER_HEAD46R = re.compiled(
    r"^(?:hand|give|pass|dole|share|dish) out (?:a|one) (?P<k>[a-z]+) (?:per (?:student|child|"
    r"person|head|patient|kid|pupil)|each|apiece|to each)\s*[,:]\s*the (?P<a>[a-z]+)"
    r"(?P<rest> (?:one )?to .+)$",
    _F,
)


def _per_head46r(text: str, lexicon: Lexicon) -> str:
    """Session 46 (12r): "Hand out a book per student, the red to Noah and the green one to Zoe"
    is "The red book to Noah and the green one to Zoe" when that hands each person one thing."""
    if "out" not in text.lower():
        return text
    m = _PER_HEAD46R.match(text.strip())
    if m is None or len(_ids(f"the {m['a']} {m['k']}", lexicon, "object")) != 1:
        return text
    out = f"The {m['a']} {m['k']}{m['rest']}"
    node = _reading(out, lexicon)
    said = list(tasks(node)) if node is not None else []
    if not said or any(t.kind != "deliver" for t in said):
        return text
    if len({t.target for t in said}) != len(said) or len(said) < 2:
        return text
    return out


# "One apiece for the pair of them, the bottle to Person A and the chips to Person B, like the
# milkmaid said."
_APIECE_FIRST46R = re.compiled(
    r"^(?:one|one thing|a thing|something) (?:apiece|each) for (?P<who>the pair of them|the two of"
    r" them|both of them|them both|the pair|the three of them)\s*[,:;]\s*(?P<list>[^.;!?]+?)"
    r"(?:\s*,\s*(?:like|as) (?P<said>[^,.;!?]+?) (?:said|asked|told us|told me|wanted))?"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _apiece_first46r(text: str, lexicon: Lexicon) -> str:
    """Session 46 (12r): a heading "One apiece for the pair of them, <list>" (and a closing "like
    the milkmaid said", naming nothing of the scene) is "<list>, one apiece": the list must hand
    that many people one thing each."""
    if "apiece" not in text.lower() and "each" not in text.lower():
        return text
    m = _APIECE_FIRST46R.match(text.strip())
    if m is None or (m["said"] is not None and not _remark_only42s(m["said"], lexicon)):
        return text
    out = f"{m['list'][:1].upper()}{m['list'][1:]}, one apiece{m['end'] or '.'}"
    node = _reading(out, lexicon)
    said = list(tasks(node)) if node is not None else []
    n = 3 if "three" in m["who"].lower() else 2
    if len(said) != n or len({t.target for t in said}) != n:
        return text
    return out


# "Person A will take any bottle going; as it happens there's just the one, so that one."
_JUST_THE_ONE46R = re.compiled(
    r"^(?P<head>.+?\bany (?P<k>[a-z]+))(?: going| at all| you've got| there is)?\s*[;,.]\s*"
    r"(?:(?:as it happens|as it is|mind you|though|well)\s*,?\s*)?there(?:'s| is) (?:just|only) "
    r"(?:the )?one(?: of them| here)?\s*,\s*so (?:that one|that'll do|it's that one|that)"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _just_the_one46r(text: str, lexicon: Lexicon) -> str:
    """Session 46 (12r): "P will take any bottle going; as it happens there's just the one, so
    that one" is "P will take any bottle" when the scene holds exactly one bottle."""
    if "one" not in text.lower():
        return text
    m = _JUST_THE_ONE46R.match(text.strip())
    if m is None or len(_ids(m["k"], lexicon, "object")) != 1:
        return text
    return _read_or44r(f"{m['head']}{m['end'] or '.'}", text, lexicon)


# "Pick anything of the four on offer for Person B, no odds which, he's only killing time."
_ANYTHING_OF46R = re.compiled(
    r"^(?:pick|choose|take|grab|get) (?:anything|any one|any) of the (?P<n>two|three|four|five)"
    r"(?: (?:on offer|going|there|here|we have|items|things))? for (?P<p>[^,;.!?]+?)\s*,\s*"
    r"(?:no odds which|any will do|whichever|it doesn't matter which|no matter which)"
    r"(?P<rest>.*)$",
    _F,
)


def _anything_of46r(text: str, lexicon: Lexicon) -> str:
    """Session 46 (12r): "Pick anything of the four on offer for P, no odds which, …" is "Give P
    any item, whichever, …" when the scene holds that many things."""
    if " of the " not in text.lower():
        return text
    m = _ANYTHING_OF46R.match(text.strip())
    if m is None or len(lexicon.scene.objects) != _COUNT46R[m["n"].lower()]:
        return text
    if _person46r(m["p"], lexicon) is None:
        return text
    return _read_or44r(f"Give {m['p']} any item, whichever{m['rest']}", text, lexicon)


# "Chips to Person A. Then again, she's just eaten, so swap them for the bottle."
_THEN_AGAIN46R = re.compiled(
    r"^(?P<head>[^.;!?]+?)\s*[.,;]\s*(?:then again|on second thoughts?|come to think of it)\s*,"
    r"\s*(?P<why>(?:she|he)(?:'s| is| has|'d| had| was) [^,;.!?]+?)\s*,\s*so (?:swap|change|"
    r"switch) (?:them|it|that) (?:for|to) (?P<y>the [a-z]+(?: [a-z]+)?)(?P<end>\s*[.!]?)$",
    _F,
)


def _then_again46r(text: str, lexicon: Lexicon) -> str:
    """Session 46 (12r): "<request>. Then again, she's just eaten, so swap them for the bottle"
    is "<request>, no, the bottle": the request one handover, the she / he its person, the reason
    naming nothing of the scene, the new thing not the one before."""
    if (
        "again" not in text.lower()
        and "second" not in text.lower()
        and "think" not in (text.lower())
    ):
        return text
    m = _THEN_AGAIN46R.match(text.strip())
    if m is None:
        return text
    node = _reading(m["head"], lexicon)
    said = list(tasks(node)) if node is not None else []
    if len(said) != 1 or said[0].kind != "deliver":
        return text
    pro = m["why"].split()[0].split("'")[0]
    if not _agrees44r(said[0].target, pro, lexicon):
        return text
    if not _remark_only42s(m["why"][len(pro) :], lexicon):
        return text
    y = _ids(m["y"], lexicon, "object")
    if len(y) != 1 or said[0].obj in y:
        return text
    return _read_or44r(f"{m['head']}, no, {m['y']}{m['end'] or '.'}", text, lexicon)


# "Neither goes without: Person B's having the bottle and Person A the chips before …"
_NEITHER_WITHOUT46R = re.compiled(
    r"^(?:neither|nobody|no one|none of them) (?:goes|is going|will go|gets left|is left) "
    r"without(?: anything)?\s*[:;,]\s*(?P<rest>.+)$",
    _F,
)


def _neither_without46r(text: str, lexicon: Lexicon) -> str:
    """Session 46 (12r): a heading "Neither goes without:" before a request that gives every
    person of the scene something is dropped (it says that, and nothing more)."""
    if "without" not in text.lower():
        return text
    m = _NEITHER_WITHOUT46R.match(text.strip())
    if m is None:
        return text
    out = f"{m['rest'][:1].upper()}{m['rest'][1:]}"
    node = _reading(out, lexicon)
    people = {h.id for h in lexicon.scene.humans}
    if node is None or {t.target for t in tasks(node) if t.kind == "deliver"} != people:
        return text
    return out


# -- session 46 (12r): blind42's choices and counts ------------------------------------------------

# "Person A and Person B each want one thing: her the apple, him the bottle.", "Zoe and Noah each
# need one: the scissors for her, the ruler for him."
_EACH_PRONOUN46R = re.compiled(
    rf"^(?P<p>{_P46R}) and (?P<q>{_P46R}) each (?:want|need|get|are getting|are having|'re "
    r"having) (?:one thing|one|a thing|something)\s*[:;,]\s*(?:(?P<pa>her|him) (?P<a>the [a-z]+"
    r"(?: [a-z]+)?)\s*,\s*(?:and )?(?P<pb>her|him) (?P<b>the [a-z]+(?: [a-z]+)?)|(?P<a2>the "
    r"[a-z]+(?: [a-z]+)?) (?:for|to) (?P<pa2>her|him)\s*,\s*(?:and )?(?P<b2>the [a-z]+(?: "
    r"[a-z]+)?) (?:for|to) (?P<pb2>her|him))(?P<end>\s*[.!]?)$",
    _F,
)


def _each_pronoun46r(text: str, lexicon: Lexicon) -> str:
    """Session 46 (12r): "P and Q each want one thing: her the apple, him the bottle" ("the
    scissors for her, the ruler for him") is "The apple to P and the bottle to Q" when each
    pronoun may be one of the two and not the other (names, titles or the Person A / B
    convention say so) and the two are not the same person."""
    if " each " not in text.lower():
        return text
    m = _EACH_PRONOUN46R.match(text.strip())
    if m is None:
        return text
    p, q = _person46r(m["p"], lexicon), _person46r(m["q"], lexicon)
    if p is None or q is None or p == q:
        return text
    said = m.groupdict()
    pairs = [(said["a"] or said["a2"], said["pa"] or said["pa2"])]
    pairs.append((said["b"] or said["b2"], said["pb"] or said["pb2"]))
    names = {p: m["p"], q: m["q"]}
    parts = []
    for x, pro in pairs:
        fit = [w for w in (p, q) if _agrees44r(w, pro, lexicon)]
        if len(fit) != 1 or len(_ids(x, lexicon, "object")) != 1:
            return text
        parts.append(f"{x} to {names[fit[0]]}")
    out = f"{parts[0][:1].upper()}{parts[0][1:]} and {parts[1]}{m['end'] or '.'}"
    node = _reading(out, lexicon)
    done = list(tasks(node)) if node is not None else []
    if len(done) != 2 or {t.target for t in done} != {p, q}:
        return text
    return out


# "Person A only wants a single thing off you today and it's the crisps, she's on the trapeze
# after."
_SINGLE_THING46R = re.compiled(
    rf"^(?P<p>{_P46R}) (?:only |just )?(?P<v>wants|needs) (?:a single thing|one thing|just one "
    r"thing|only one thing|the one thing)(?: off you| from you| from us)?(?: today| now| this "
    r"time)? and (?:it(?:'s| is)|that(?:'s| is)) (?P<x>the [a-z]+(?: [a-z]+)?)\b",
    _F,
)


def _single_thing46r(text: str, lexicon: Lexicon) -> str:
    """Session 46 (12r): "P only wants a single thing (off you today) and it's the crisps" is "P
    only wants the crisps" when the crisps are one thing of the scene."""
    if "thing" not in text.lower():
        return text
    m = _SINGLE_THING46R.match(text.strip())
    if m is None or len(_ids(m["x"], lexicon, "object")) != 1:
        return text
    pid = _person46r(m["p"], lexicon)
    if pid is None:
        return text
    out = f"{m['p']} only {m['v']} {m['x']}{text.strip()[m.end() :]}"
    return _all_to46r(out, text, pid, lexicon)


# "The bottle, or whatever's there, Person A isn't fussy." (a scene with the bottle alone)
_WHATEVER_THERE46R = re.compiled(
    rf"^(?P<x>the [a-z]+(?: [a-z]+)?)\s*,\s*or whatever(?:'s| is) (?:there|going|handy|to hand)"
    rf"\s*,\s*(?P<p>{_P46R})(?: isn't|'s not| is not) (?:fussy|bothered|picky|particular|choosy)"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _whatever_there46r(text: str, lexicon: Lexicon) -> str:
    """Session 46 (12r): "The bottle, or whatever's there, P isn't fussy" is "Give P the bottle"
    when the bottle is the scene's one thing ('whatever's there' is it too)."""
    if "whatever" not in text.lower():
        return text
    m = _WHATEVER_THERE46R.match(text.strip())
    if m is None or len(lexicon.scene.objects) != 1 or not _ids(m["x"], lexicon, "object"):
        return text
    pid = _person46r(m["p"], lexicon)
    if pid is None:
        return text
    return _all_to46r(f"Give {m['p']} {m['x']}{m['end'] or '.'}", text, pid, lexicon)


# "Clear both things off the floor and up onto the shelf, bottle and crisps alike, …"
_CLEAR_BOTH46R = re.compiled(
    r"^clear (?P<n>both things|both|the two things|the two|all (?:three|four) things) off the "
    r"(?:floor|ground|side)(?: and)? (?:up )?(?P<on>onto|on to|on|into|in) (?P<s>the [a-z]+"
    r"(?: [a-z]+)?)\s*,\s*(?:the )?(?P<a>[a-z]+) and (?:the )?(?P<b>[a-z]+) alike(?P<rest>.*)$",
    _F,
)


def _clear_both46r(text: str, lexicon: Lexicon) -> str:
    """Session 46 (12r): "Clear both things off the floor and up onto the shelf, bottle and
    crisps alike, …" is "Put the bottle and the crisps onto the shelf, …" when the two named are
    two things of the scene and the place one surface."""
    if "alike" not in text.lower():
        return text
    m = _CLEAR_BOTH46R.match(text.strip())
    if (
        m is None
        or len(_ids(m["s"], lexicon, "surface")) != 1
        or _ids(m["s"], lexicon) != (_ids(m["s"], lexicon, "surface"))
    ):
        return text
    a, b = _ids(m["a"], lexicon, "object"), _ids(m["b"], lexicon, "object")
    if len(a) != 1 or len(b) != 1 or a == b or "three" in m["n"] or "four" in m["n"]:
        return text
    out = f"Put the {m['a']} and the {m['b']} {m['on']} {m['s']}{m['rest']}"
    node = _reading(out, lexicon)
    if node is None or {t.obj for t in tasks(node)} != a | b:
        return text
    if any(t.kind != "place" for t in tasks(node)):
        return text
    return out


# the normaliser's first rewrites (wired into normalise._STEPS19, before the session-45 ones)
_STEPS46R_FIRST: tuple[Callable[[str, Lexicon], str], ...] = (
    _scratch_lot46r,
    _taking46r,
    _slip_label46r,
)
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-45 ones)
_STEPS46R: tuple[Callable[[str, Lexicon], str], ...] = (
    _fix_why46r,
    _one_of_hers46r,
    _just_those46r,
    _only_one46r,
    _items_there46r,
    _and_both46r,
    _thing_needs46r,
    _not_fussy46r,
    _a_k_or46r,
    _for_whose46r,
    _placed_remark46r,
    _per_head46r,
    _apiece_first46r,
    _just_the_one46r,
    _anything_of46r,
    _then_again46r,
    _neither_without46r,
    _each_pronoun46r,
    _single_thing46r,
    _whatever_there46r,
    _clear_both46r,
)
# refusals asked of the text before it is read (offline._parse, after the session-45 ones)
REFUSE46R: tuple[Callable[[str, Lexicon], None], ...] = (doubt_at46r,)
# checks of the whole instruction's reading (offline.parse_instruction, after the session-45 ones)
CHECK46R: tuple[Callable[[str, Node, Lexicon], None], ...] = ()
