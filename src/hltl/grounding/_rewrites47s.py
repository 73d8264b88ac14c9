"""The grounder's rules of session 47, engineer 12s (docs/grounding.md)."""

from __future__ import annotations

import itertools
from collections.abc import Callable

from hltl.grounding import gate as re
from hltl.grounding._normalise1 import (
    _F,
    _ids,
    _names,
    _objects_only,
    _only_person,
    _reading,
)
from hltl.grounding._rewrites42s import _NEGATED42S
from hltl.grounding._rewrites44s import _agrees44s
from hltl.grounding._rewrites45s import _CORRECTS45S, _COURTESY45S, _NOT_BEFORE45S
from hltl.grounding._rewrites46s import _sequenced46s
from hltl.grounding.lexicon import VERBS, Lexicon
from hltl.grounding.tree import Node, tasks

# -- session 47 (12s): run-ons (blind45's sentence splits and run-ons) ---------------------------
#
# "Bottle to Alice crisps to Bob the costermonger's shouting about his barrow again": a request,
# then with no mark a remark whose subject is someone outside the scene ('the costermonger', 'the
# cowman's lorry'); with a stop before it the remark rules take it off ("… to Bob. The
# costermonger's shouting about his barrow again" reads), and its 'his' is the costermonger's.
# The stop put in, when the words before read alone, the remark names nothing of the scene,
# points at nothing of it (it / them / one …), wants, negates and corrects nothing, and the whole
# then reads exactly as the request alone does.
_REMARK_THE47S = re.compile(
    r"the (?P<who>(?:(?!the\b)[a-z-]+ ){0,2}(?!the\b)[a-z-]+)"
    r"(?:'s|\u2019s| is| was| are| were| has| have| keeps| keep| says| sends)\b"
    r"[^,;:.!?]*[.!]?$",
    _F,
)
_REMARK_HELD47S = re.compile(
    r"\b(?:it|its|them|they|their|one|ones|both|all|each|rest|other|others|same|this|that|these|"
    r"those|want|wants|wanted|need|needs|needed|asked|asking|after|claimed|dibs|instead|"
    r"first|then|next|later|before|once|when|until|till)\b",
    _F,
)


def _remark_the47s(text: str, lexicon: Lexicon) -> str:
    """Session 47 (12s): the stop before a run-on remark about someone outside the scene put in
    (above)."""
    if " the " not in text.lower():
        return text
    low = text.lower()
    at = low.find(" the ")
    while at >= 0:
        m = _REMARK_THE47S.match(text, at + 1)
        at = low.find(" the ", at + 1)
        if m is None:
            continue
        before, remark = text[: m.start()].rstrip(), m.group(0)
        words = before.split()
        if not words or re.search(r"[,;:.!?]$", before):
            continue
        last = words[-1].lower()
        if last in _NOT_BEFORE45S or last in VERBS:
            continue
        if len(words) >= 2 and words[-2].lower() == "to" and not _names(words[-1], lexicon):
            continue  # "Tom needs the tape to wrap the courier's parcels": the verb's object
        if last.endswith("ing") and not _names(words[-1], lexicon):
            continue  # "… the stapler for binding the rector's notices …": the doing's object
        if len(remark[len(m["who"]) + 4 :].split()) < 3:
            continue  # "the courier's parcels": a possessive, no clause
        if last in _COURTESY45S:
            continue  # "bottle to bob cheers the lads are thirsty": session 46's `_courtesy_mid46s`
        if _names(remark, lexicon) or _REMARK_HELD47S.search(remark):
            continue
        if _NEGATED42S.search(remark) or _CORRECTS45S.search(remark):
            continue
        alone = _reading(before, lexicon)
        if alone is None:
            continue
        out = f"{before}. {remark[0].upper()}{remark[1:]}"
        if _reading(out, lexicon) == alone:
            return out
    return text


# "Small box onto the belt medium box onto the pallet": two placements with no mark between,
# the second opening on its object right after the first one's surface (the grammar reads
# "bottle to alice crisps to bob", a person before the next object, but not a surface before
# it). ', ' put in, when each side reads alone and the whole then reads both sides' tasks and
# no order neither side said.
def _placed_run_on47s(text: str, lexicon: Lexicon) -> str:
    """Session 47 (12s): the comma between two placements run on put in (above)."""
    named = _names(text, lexicon)
    if len(named) < 4:
        return text
    for a, b in itertools.pairwise(named):
        if not all(r.kind == "surface" for r in a.refs):
            continue
        if not all(r.kind == "object" for r in b.refs):
            continue
        pattern = rf"\b{re.escape(a.text)}(?= (?:the )?{re.escape(b.text)}\b)"
        for m in re.finditer(pattern, text, _F):
            left, right = text[: m.end()], text[m.end() + 1 :]
            if re.search(r"[,;:.!?]\s*$", left):
                continue
            one, two = _reading(left, lexicon), _reading(right, lexicon)
            if one is None or two is None:
                continue
            both = _reading(f"{left}, {right}", lexicon)
            if both is None or _sequenced46s(both) != (_sequenced46s(one) or _sequenced46s(two)):
                continue
            if set(tasks(both)) == set(tasks(one)) | set(tasks(two)):
                return f"{left}, {right}"
    return text


# "Chips? Person A's. Bottle? Person B's.": a thing asked as a question and answered by whose it
# is — session 19's telegraph form "Chips? Person A." (the chips to Person A, which reads) with
# the answer said as the person's. The 's taken off where the question is the name of a thing of
# the scene alone (a determiner before it at most: not "Whose are the chips? Person B's.", which
# reads as it is) and the answer one person of the scene alone.
_WHOSE_ANSWER47S = re.compile(
    r"(?:^|(?<=[.!?] ))(?P<obj>[^.!?]+)\? (?P<who>[^.!?]+?)(?:'s|\u2019s)(?=\s*(?:[.!]|$))", _F
)


def _whose_answer47s(text: str, lexicon: Lexicon) -> str:
    """Session 47 (12s): 'X? P's.' said 'X? P.' (above)."""
    if "?" not in text:
        return text

    def answer(m: re.Match[str]) -> str:
        obj, who = m["obj"].strip(), m["who"].strip()
        # the thing's name alone ("Chips?", "And the bottle?"), not "Whose are the chips?"
        bare = re.sub(r"^(?:and |so |then )?(?:the |that |this |those |these )?", "", obj, flags=_F)
        named = _names(bare, lexicon)
        if (
            len(named) != 1
            or named[0].text.lower() != bare.lower()
            or not _objects_only(bare, lexicon)
            or not _only_person(who, lexicon)
        ):
            return m.group(0)
        return f"{m['obj']}? {who}"

    return re.sub(_WHOSE_ANSWER47S.pattern, answer, text, flags=_F)


# "The farm hand sends his regards and says ta.": 'hand' in a worker's name ('farm hand', 'deck
# hand', 'stage hand') is no verb; said as one word ('farmhand', which the remark rules take
# off), where the word before names nothing of the scene.
_HAND47S = re.compile(
    r"\b(?P<det>the|a|an|our|their|that|this|his|her|your|my) (?P<w>farm|deck|stage|ranch|field|"
    r"hired|dock|stable|mill|cattle|kitchen|shop|factory|chore)[ -]hand(?P<s>s?)\b",
    _F,
)


def _hand_worker47s(text: str, lexicon: Lexicon) -> str:
    """Session 47 (12s): 'the farm hand' said 'the farmhand' (above)."""
    if "hand" not in text.lower():
        return text
    return re.sub(
        _HAND47S.pattern,
        lambda m: m.group(0) if _names(m["w"], lexicon) else f"{m['det']} {m['w']}hand{m['s']}",
        text,
        flags=_F,
    )


# "The chips. Person A wants them. Nobody else has asked.": a closing 'nobody else has asked'
# (no one else claims it) says the request is the plain one (the contracts' claim conditions);
# "… Nobody else has asked for them." reads already. Taken off where the request gives things to
# one person only, and the whole then reads exactly as the request alone does.
_NOBODY_ELSE47S = re.compile(
    r"(?:^|(?<=[.!?;,]) )(?:and )?(?:nobody|no one|no-one) else(?:'s| has| have| had)?(?: even)?"
    r" (?:asked|claimed|called dibs|spoken up|put in|shouted|bagged)"
    r"(?: (?:for |on )?(?:it|them|one))?"
    r"(?: yet| so far)?\s*[.!]?$",
    _F,
)


def _nobody_else47s(text: str, lexicon: Lexicon) -> str:
    """Session 47 (12s): a closing 'nobody else has asked' taken off (above)."""
    low = text.lower()
    if " else" not in low or ("nobody" not in low and "no one" not in low and "no-one" not in low):
        return text
    m = _NOBODY_ELSE47S.search(text)
    if m is None or m.start() == 0:
        return text
    before = text[: m.start()].rstrip(" ,;")
    alone = _reading(before, lexicon)
    if alone is None or len({t.target for t in tasks(alone)}) != 1:
        return text
    if any(t.kind != "deliver" for t in tasks(alone)):
        return text
    return before


# "Sponge into the sink first. After, the bowl for Omar. Emma's fine with waiting, she's a
# visitor.": a closing remark that a person of the scene the request gives nothing will wait
# ('is fine with waiting', 'is happy to wait', 'can wait', 'doesn't mind waiting'), with or
# without who they are said after it ('she's a visitor': their role in the scene, the pronoun
# fitting them). Taken off where the request reads alone, gives that person nothing, and the
# whole then reads exactly as the request alone does.
_WAITS47S = re.compile(
    r"(?:^|(?<=[.!?;,]) )(?:and |but )?(?P<who>[A-Z][\w ]*?|he|she)"
    r"(?:(?:'s|\u2019s| is) (?:fine|happy|okay|ok|content|glad|alright|all right)"
    r" (?:with waiting|to wait|waiting)| can wait| will wait|'ll wait| doesn't mind waiting|"
    r" does not mind waiting| don't mind waiting)(?: a bit| a while| for now| till later)?"
    r"(?:,? (?P<pron>he|she)(?:'s|\u2019s| is) (?:a|an|the) (?P<role>[a-z]+))?\s*[.!]?$",
    _F,
)


def _waits47s(text: str, lexicon: Lexicon) -> str:
    """Session 47 (12s): a closing remark that someone the request leaves out will wait taken
    off (above)."""
    if "wait" not in text.lower():
        return text
    m = _WAITS47S.search(text)
    if m is None or m.start() == 0 or not _only_person(m["who"], lexicon):
        return text
    pid = next(iter(_ids(m["who"], lexicon)))
    if m["role"] is not None and (
        _ids(m["role"], lexicon, "human") != {pid} or not _agrees44s(m["who"], m["pron"], lexicon)
    ):
        return text
    before = text[: m.start()].rstrip(" ,;")
    alone = _reading(before, lexicon)
    if alone is None or any(t.target == pid for t in tasks(alone)):
        return text
    return before


# "chef marcos got the damson jam cake to slice give him the knife": lower case with no marks, a
# person's state run on into the request (session 35's `_state_run_on35s` reads "marco's got the
# cake to slice give him the knife"), said with the apostrophe of "marco's" dropped and the
# person's role before the name ('chef marco': both words name the one person). Said "marco's
# got …" where the text has no marks, the name with 's' names nothing itself, and the whole then
# reads.
_ROLE_NAME_S47S = re.compile(
    r"^(?P<role>[a-z]+ )?(?P<name>[a-z]+?)(?:s|'s|\u2019s) "
    r"(?P<rest>(?:got|been|just|gone|off)\b.+)$"
)


def _role_name_s47s(text: str, lexicon: Lexicon) -> str:
    """Session 47 (12s): "chef marcos got …" said "marco's got …" (above)."""
    if text != text.lower() or re.search(r"[,;:.!?]\s*\S", text):
        return text
    m = _ROLE_NAME_S47S.match(text)
    if m is None or not _only_person(m["name"], lexicon):
        return text
    if m["role"] is None and m["name"].endswith("'s"):
        return text
    pid = _ids(m["name"], lexicon)
    if m["role"] is not None and _ids(m["role"], lexicon) != pid:
        return text
    if _ids(m["name"] + "s", lexicon) - pid:
        return text  # "james": a name of its own
    out = f"{m['name']}'s {m['rest']}"
    if out == text:
        return text
    read = _reading(out, lexicon)
    if read is None or not pid & {t.target for t in tasks(read)}:
        return text
    return out


# -- session 47 (12s): negation and exclusion (blind45) -----------------------------------------
#
# "Jess is off power tools until the timekeeper signs the card; hammer only for now, to Jess.":
# '<a thing> only' opening a piece says just that thing ("Just the hammer for now, to Jess."
# reads): said so, where the words name one object of the scene and the whole then reads.
_ONLY_AFTER47S = re.compile(
    r"(?:^|(?<=[.;:!?,] ))(?P<the>the )?(?P<x>[a-z][a-z ]*?) only\b(?! (?:if|when|one|just))", _F
)


def _only_after47s(text: str, lexicon: Lexicon) -> str:
    """Session 47 (12s): '<thing> only' said 'just the <thing>' (above)."""
    if " only" not in text.lower():
        return text
    for m in _ONLY_AFTER47S.finditer(text):
        named = _names(m["x"], lexicon)
        if len(named) != 1 or named[0].text.lower() != m["x"].lower():
            continue
        if not all(r.kind == "object" for r in named[0].refs):
            continue
        just = "Just" if m.start() == 0 else "just"
        out = f"{text[: m.start()]}{just} the {m['x']}{text[m.end() :]}"
        if _reading(out, lexicon) is not None:
            return out
    return text


# the normaliser's first rewrites (wired into normalise._STEPS19, before the session-46 ones)
_STEPS47S_FIRST: tuple[Callable[[str, Lexicon], str], ...] = (
    _remark_the47s,
    _placed_run_on47s,
    _whose_answer47s,
    _hand_worker47s,
    _nobody_else47s,
    _waits47s,
    _role_name_s47s,
    _only_after47s,
)
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-46 ones)
_STEPS47S: tuple[Callable[[str, Lexicon], str], ...] = ()
# refusals asked of the text before it is read (offline._parse, after the session-46 ones)
REFUSE47S: tuple[Callable[[str, Lexicon], None], ...] = ()
# checks of the whole instruction's reading (offline.parse_instruction, after the session-46 ones)
CHECK47S: tuple[Callable[[str, Node, Lexicon], None], ...] = ()
