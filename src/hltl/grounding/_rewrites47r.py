"""The grounder's rules of session 47, engineer 12r (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _ids, _reading
from hltl.grounding._rewrites42s import _remark_only42s
from hltl.grounding._rewrites44r import _agrees44r, _read_or44r
from hltl.grounding._rewrites46r import _P46R, _each_pronoun46r, _person46r
from hltl.grounding.lexicon import KIND_CATEGORIES, Lexicon
from hltl.grounding.tree import Node, has_choice, tasks

# -- whichever, whatever, each ---------------------------------------------------------------------

# "Give Person A whichever of the apple and the chips, she won't mind."
_WHICHEVER_OF47R = re.compiled(
    r"\bwhichever (?:one )?of (?P<a>the [a-z]+(?: [a-z]+)?) (?:and|or) (?P<b>the [a-z]+"
    r"(?: [a-z]+)?)(?=\s*(?:[,;.!]|$)|\s+(?:in|on|onto|into|to|over to|up on)\s)",
    _F,
)


def _whichever_of47r(text: str, lexicon: Lexicon) -> str:
    """Session 47 (12r): "whichever of the apple and the chips" (then a stop, a comma or where it
    goes, not "… is nearer") is "one of the apple and the chips", each one thing of the
    scene."""
    if "whichever" not in text.lower():
        return text
    m = _WHICHEVER_OF47R.search(text)
    if m is None:
        return text
    a, b = _ids(m["a"], lexicon, "object"), _ids(m["b"], lexicon, "object")
    if len(a) != 1 or len(b) != 1 or a == b or _ids(m[0], lexicon, "human"):
        return text
    out = f"{text[: m.start()]}one of {m['a']} and {m['b']}{text[m.end() :]}"
    return _read_or44r(out, text, lexicon)


# "Whatever Person B chooses out of cup, bottle and apple is fine by the innkeeper, only one
# though."
_WHATEVER_CHOOSES47R = re.compiled(
    rf"^(?P<w>whatever|whichever) (?P<p>{_P46R}) (?:chooses|picks|goes for|fancies|settles on) "
    r"(?:out of|from|of|from among|among|between) (?P<list>[a-z ,]+?) (?:is|will be) (?:fine|ok|"
    r"okay|all right|good)(?P<by> (?:by|with|for) [^,;.!?]+?)?(?:\s*,\s*(?P<one>(?:but )?(?:only|"
    r"just) (?:the )?one(?: thing)?(?: though| mind| mind you)?))?(?P<end>\s*[.!]?)$",
    _F,
)


def _listed47r(words: str, lexicon: Lexicon) -> list[str] | None:
    """The things ``words`` list ("cup, bottle and apple", "the cup or the apple"), each one
    object of the scene and each once, as "the cup", …; None otherwise."""
    items = [w.strip() for w in re.split(r"\s*,\s*(?:and |or )?|\s+(?:and|or)\s+", words, flags=_F)]
    out, seen = [], set()
    for item in items:
        x = item if item.lower().startswith("the ") else f"the {item}"
        ids = _ids(x, lexicon)
        if len(ids) != 1 or _ids(x, lexicon, "object") != ids or ids & seen:
            return None
        seen |= ids
        out.append(x)
    return out if len(out) >= 2 else None


def _whatever_chooses47r(text: str, lexicon: Lexicon) -> str:
    """Session 47 (12r): "Whatever Person B chooses out of cup, bottle and apple is fine (by the
    innkeeper), only one though" is "Give Person B one of the cup, the bottle or the apple":
    'whichever' says one; 'whatever' only with "only one" (else P may take more than one)."""
    if "whatever" not in text.lower() and "whichever" not in text.lower():
        return text
    m = _WHATEVER_CHOOSES47R.match(text.strip())
    if m is None or (m["w"].lower() == "whatever" and m["one"] is None):
        return text
    pid = _person46r(m["p"], lexicon)
    listed = _listed47r(m["list"], lexicon)
    if pid is None or listed is None:
        return text
    if m["by"] is not None and not _remark_only42s(m["by"], lexicon):
        return text
    out = f"Give {m['p']} one of {', '.join(listed[:-1])} or {listed[-1]}{m['end'] or '.'}"
    node = _reading(out, lexicon)
    if node is None or not has_choice(node) or {t.target for t in tasks(node)} != {pid}:
        return text
    return out


# "Kofi's after a spanner, small or big, he'll take whatever comes first to hand.", "Emma can have
# either cup, green or white, she has no preference."
_NO_PREFERENCE47R = re.compiled(
    r"\s*[,;]\s*(?:and |so )?(?:(?P<pro>she|he)(?:'s| is| has|'s got) (?:no preference|no "
    r"favourite|happy with either(?: one)?|easy either way)|(?P<pro2>she|he)(?:'ll| will) (?:take|"
    r"have) (?:whatever|whichever)(?: one)? (?:comes|turns up|is) (?:first )?(?:to hand|first|"
    r"nearest|handiest))(?P<end>\s*[.!]?)$",
    _F,
)


def _no_preference47r(text: str, lexicon: Lexicon) -> str:
    """Session 47 (12r): a closing "she has no preference" ("he'll take whatever comes first to
    hand", "she's happy with either") after a choice handed to one person is dropped when the
    pronoun may be that person: it says again that either will do."""
    low = text.lower()
    if not any(w in low for w in ("preference", "whatever", "whichever", "either", "favourite")):
        return text
    t = text.strip()
    m = _NO_PREFERENCE47R.search(t)
    if m is None:
        return text
    head = t[: m.start()]
    node = _reading(f"{head}.", lexicon)
    if node is None or not has_choice(node) or any(x.kind != "deliver" for x in tasks(node)):
        return text
    people = {x.target for x in tasks(node)}
    if len(people) != 1 or not _agrees44r(next(iter(people)), m["pro"] or m["pro2"], lexicon):
        return text
    return f"{head}{m['end'] or '.'}"


# "Give Alice and Bob one each, the bottle to her and the crisps to him.", "Lena and Marco get a
# plate each: the white one to her, the blue one to him."
_EACH_GIVEN47R = re.compiled(
    rf"^(?:(?:give|hand|pass) )?(?P<p>{_P46R}) and (?P<q>{_P46R}) (?:(?:get|want|need|are "
    r"getting|'re getting|can have|should get|are to get|are having) )?(?:one|a thing|one thing|"
    r"an? (?P<k>[a-z]+)) each\s*[:;,]\s*(?P<a>the [a-z]+(?: [a-z]+)?) (?:to|for) (?P<pa>her|him)"
    r"\s*(?:,\s*(?:and )?|and )(?P<b>the [a-z]+(?: [a-z]+)?) (?:to|for) (?P<pb>her|him)"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _each_given47r(text: str, lexicon: Lexicon) -> str:
    """Session 47 (12r): "Give P and Q one each, the bottle to her and the crisps to him" ("P and
    Q get a plate each: the white one to her, the blue one to him": 'one' is a plate) is session
    46's "P and Q each want one thing: the bottle for her, the crisps for him", read by
    `_each_pronoun46r` (each pronoun one of the two and not the other)."""
    if " each" not in text.lower():
        return text
    m = _EACH_GIVEN47R.match(text.strip())
    if m is None:
        return text
    a, b = m["a"], m["b"]
    if m["k"] is not None:
        a = re.sub(r" one$", f" {m['k']}", a, flags=_F)
        b = re.sub(r" one$", f" {m['k']}", b, flags=_F)
    out = (
        f"{m['p']} and {m['q']} each want one thing: {a} for {m['pa']}, {b} for {m['pb']}"
        f"{m['end'] or '.'}"
    )
    done = _each_pronoun46r(out, lexicon)
    return text if done == out else done


# -- doubt: the speaker does not know which --------------------------------------------------------

# "…, and I can't for the life of me remember which.", "…, and I didn't catch which.", "…, he did
# say which one but I've gone blank."
_DOUBT47R = (
    r"(?:i (?:honestly |really |just |simply )?(?:can't|cannot|can not|don't|didn't|couldn't)"
    r"(?: for the life of me)? (?:remember|recall|know|say|catch|hear|make out)|i (?:honestly |"
    r"clean )?(?:forget|forgot)|i've (?:clean )?forgotten|i'm not sure|no idea) which(?: one)?"
    r"|(?:she|he|they) did say which(?: one)?,? but i(?:'ve| have) (?:gone blank|forgotten|lost it)"
)
_DOUBT_ONE47R = re.compiled(
    rf"\bone of (?:them\s*,\s*(?P<a>the [a-z]+(?: [a-z]+)?) or (?P<b>the [a-z]+(?: [a-z]+)?)|"
    rf"the (?P<k>[a-z]+s)(?P<more>[^,;.!?]*?)(?:\s*,\s*not (?P<x>the [a-z]+(?: one)?))?)\s*"
    rf"[,;]\s*(?:and |but )?(?P<said>{_DOUBT47R})(?=\s*[.!]?$)",
    _F,
)


def doubt_one47r(text: str, lexicon: Lexicon) -> None:
    """Session 47 (12r): "P asked for one of them, the bottle or the chips, and I can't for the
    life of me remember which" ("one of the pens earlier, not the blue, and I didn't catch
    which"; "one of the blocks, he did say which one but I've gone blank") is no choice left to
    the robot: refused naming what it could be (the things said, or the kind's things but the
    one ruled out)."""
    low = text.lower()
    if "one of" not in low or ("which" not in low and "blank" not in low):
        return
    m = _DOUBT_ONE47R.search(text)
    if m is None:
        return
    if m["a"] is not None:
        a, b = _ids(m["a"], lexicon, "object"), _ids(m["b"], lexicon, "object")
        if len(a) != 1 or len(b) != 1 or a == b:
            return
        ids = sorted(a | b)
    else:
        kinds = m["k"].lower()
        if m["more"] and not _remark_only42s(m["more"], lexicon):
            return
        cats = KIND_CATEGORIES.get(kinds)
        every = (
            {o.id for o in lexicon.scene.objects if o.category in cats}
            if cats
            else _ids(f"the {kinds}", lexicon, "object")
        )
        out: set[str] = set()
        if m["x"] is not None:
            x = re.sub(r" one$", "", m["x"], flags=_F)
            out = _ids(f"{x} {kinds.removesuffix('s')}", lexicon, "object")
            if len(out) != 1 or not out <= every:
                return
        ids = sorted(every - out)
    if len(ids) < 2:
        return
    raise GroundingError(
        f"{m['said']!r}: which one is meant is not said; it could be {' or '.join(ids)}: name the "
        "one"
    )


# the normaliser's first rewrites (wired into normalise._STEPS19, before the session-46 ones)
_STEPS47R_FIRST: tuple[Callable[[str, Lexicon], str], ...] = ()
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-46 ones)
_STEPS47R: tuple[Callable[[str, Lexicon], str], ...] = (
    _whichever_of47r,
    _whatever_chooses47r,
    _no_preference47r,
    _each_given47r,
)
# refusals asked of the text before it is read (offline._parse, after the session-46 ones)
REFUSE47R: tuple[Callable[[str, Lexicon], None], ...] = (doubt_one47r,)
# checks of the whole instruction's reading (offline.parse_instruction, after the session-46 ones)
CHECK47R: tuple[Callable[[str, Node, Lexicon], None], ...] = ()
