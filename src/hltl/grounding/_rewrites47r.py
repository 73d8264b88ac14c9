"""The grounder's rules of session 47, engineer 12r (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _ids, _reading
from hltl.grounding._rewrites41r import which_forgotten41r
from hltl.grounding._rewrites42s import _remark_only42s
from hltl.grounding._rewrites43s import _placed_aside43s
from hltl.grounding._rewrites44r import _agrees44r, _read_or44r
from hltl.grounding._rewrites46r import _P46R, _each_pronoun46r, _fix_why46r, _person46r
from hltl.grounding.lexicon import KIND_CATEGORIES, Lexicon
from hltl.grounding.tree import Node, Task, has_choice, tasks

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
    out: list[str] = []
    seen: set[str] = set()
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
    r"favourite|easy either way)|(?P<pro2>she|he)(?:'ll| will) (?:take|"
    r"have) (?:whatever|whichever)(?: one)? (?:comes|turns up|is) (?:first )?(?:to hand|first|"
    r"nearest|handiest))(?P<end>\s*[.!]?)$",
    _F,
)


def _no_preference47r(text: str, lexicon: Lexicon) -> str:
    """Session 47 (12r): a closing "she has no preference" ("he'll take whatever comes first to
    hand", "she's easy either way"; session 31's "she's happy with either" is its own) after a
    choice handed to one person is dropped when the pronoun may be that person: it says again
    that either will do."""
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


# -- counts and plurals ----------------------------------------------------------------------------

# "Both of the mugs up on the shelf, please, clear of the publican's elbows."
_CLEAR_OF47R = re.compiled(r",\s*(?:well |right )?clear of (?=[^,;.!?]+[.!]?$)", _F)


def _clear_of47r(text: str, lexicon: Lexicon) -> str:
    """Session 47 (12r): a closing "clear of the publican's elbows" after a placing is session
    43's "out of reach of …" (`_placed_aside43s` takes it off: what it names must be no thing or
    surface of the scene)."""
    if "clear of" not in text.lower():
        return text
    m = _CLEAR_OF47R.search(text)
    if m is None:
        return text
    out = _placed_aside43s(f"{text[: m.start()]}, out of reach of {text[m.end() :]}", lexicon)
    if "out of reach" in out:
        return text
    node = _reading(out, lexicon)
    if node is None or any(x.kind != "place" for x in tasks(node)):
        return text
    return out


# "Both blankets to Mr Lee, he's shivering like a stable lad in January."
_STATE_LIKE47R = re.compiled(
    r"(?P<state>\b(?:she|he|they|[A-Z][a-z]+)(?:'s| is|'re| are) (?:shivering|shaking|trembling|"
    r"freezing|starving|parched|gasping|sweating|wilting|flagging|dropping|fading|drooping)) like "
    r"(?P<what>(?:a|an|the|some) [^,;.!?]+?)(?P<end>\s*[.!]?)$",
    _F,
)


def _state_like47r(text: str, lexicon: Lexicon) -> str:
    """Session 47 (12r): a closing state said with a likeness ("he's shivering like a stable
    lad in January") is the state ("he's shivering"), the likeness naming nothing of the
    scene."""
    if " like " not in text.lower():
        return text
    m = _STATE_LIKE47R.search(text.strip())
    if m is None or not _remark_only42s(m["what"], lexicon):
        return text
    return _read_or44r(f"{text.strip()[: m.end('state')]}{m['end'] or '.'}", text, lexicon)


# "Both cups in the sink, the pair of them, before the visitor looks."
_BEFORE_LOOKS47R = re.compiled(
    r"\s*,?\s*before (?P<p>(?:the )?[a-z]+(?: [a-z]+)?) (?:looks|sees|notices|spots it|spots them|"
    r"comes in|walks in|turns up|arrives|wakes up)(?P<end>\s*[.!]?)$",
    _F,
)


def _before_looks47r(text: str, lexicon: Lexicon) -> str:
    """Session 47 (12r): a closing deadline "before the visitor looks" ("before Emma comes in")
    said of one person of the scene is session 34's "before she gets back" (acting now meets
    it): taken off when the rest reads and hands that person nothing."""
    if "before" not in text.lower():
        return text
    m = _BEFORE_LOOKS47R.search(text.strip())
    if m is None:
        return text
    pid = _person46r(m["p"], lexicon)
    if pid is None:
        return text
    out = f"{text.strip()[: m.start()]}{m['end'] or '.'}"
    node = _reading(out, lexicon)
    if node is None or any(x.target == pid for x in tasks(node)):
        return text
    return out


# -- corrections -----------------------------------------------------------------------------------

# "Pop the bottle up on the shelf, or actually Bob's just shouted for it, so him instead.", "Put
# the bib on the high chair, or, wait, Grandad's holding out his hand for it, so to him.", "Crisps
# over to Bob, or, hmm, Alice called dibs on them first, so Alice.", "Person B's bottle, hold your
# horses, it turns out Person A was the thirsty one, so give it her."
_CLAIMED47R = re.compiled(
    r"^(?P<head>[^,;]+?)\s*,\s*(?:or\s*,?\s*)?(?:(?:actually|wait|hmm|hang on|hold on|no|oh|er|"
    r"um|hold your horses|sorry)\s*,?\s*)+(?:(?P<p>[A-Z][a-z]+(?: [A-Z][a-z]*)?)(?:'s| has| is)? "
    r"(?:just )?(?:shouted for|called for|asked for|called dibs on|bagsied|claimed|holding out "
    r"(?:his|her) hands? for|got (?:his|her) hand up for|put (?:his|her) hand up for) (?:it|them)"
    r"(?: first| already)?|it turns out (?P<q>[A-Z][a-z]+(?: [A-Z][a-z]*)?) (?:was|is) the "
    r"(?:thirsty|hungry|peckish|cold|tired) one)\s*,\s*so (?:(?:give it|hand it|pass it|take it|"
    r"send it)(?: to)? |to |it's |it goes to )?(?P<to>him|her|[A-Z][a-z]+(?: [A-Z][a-z]*)?)"
    r"(?: instead)?(?P<end>\s*[.!]?)$"
)


def _thing47r(oid: str, lexicon: Lexicon) -> str | None:
    """A phrase naming object ``oid`` alone ("the bottle", "the medium box"), or None."""
    obj = next(o for o in lexicon.scene.objects if o.id == oid)
    for name in (*obj.aliases, obj.category, obj.id):
        if _ids(f"the {name}", lexicon) == {oid}:
            return f"the {name}"
    return None


def _claimed47r(text: str, lexicon: Lexicon) -> str:
    """Session 47 (12r): a request with one thing, a cue, then someone's claim on it ("or
    actually Bob's just shouted for it, so him instead"; "Alice called dibs on them first, so
    Alice"; "it turns out Person A was the thirsty one, so give it her"): the thing to that
    person, when the 'him' / 'her' (or name) after 'so' is that person."""
    low = text.lower()
    if "so " not in low or (
        " for it" not in low
        and " for them" not in low
        and (" on them" not in low and " on it" not in low and "turns out" not in low)
    ):
        return text
    m = _CLAIMED47R.match(text.strip())
    if m is None:
        return text
    pid = _person46r(m["p"] or m["q"], lexicon)
    if pid is None:
        return text
    to = m["to"]
    if to.lower() in ("him", "her"):
        if not _agrees44r(pid, to, lexicon):
            return text
    elif _person46r(to, lexicon) != pid:
        return text
    objs = _ids(m["head"], lexicon, "object")
    if len(objs) != 1:
        return text
    thing = _thing47r(next(iter(objs)), lexicon)
    if thing is None:
        return text
    return _read_or44r(f"Give {m['p'] or m['q']} {thing}{m['end'] or '.'}", text, lexicon)


# "Chips to Person A, oops, there aren't any chips, the bottle then.", "Person A's cup, er, no,
# that's wrong, there isn't one, I meant her bottle, bring it along."
_NONE_THERE47R = re.compiled(
    r"^(?P<head>[^,;]+?)\s*,\s*(?:(?:oops|whoops|er|erm|um|no|sorry|oh|hang on|wait)\s*,?\s*)+"
    r"(?:that's wrong\s*,\s*)?there (?:aren't|isn't|are no|is no|'s no)(?: any)?(?: (?P<k>[a-z]+)|"
    r" one)(?: here)?\s*,\s*(?:i meant |i mean |so )?(?P<fix>(?:the|her|his) [a-z]+"
    r"(?: (?!then\b)[a-z]+)?)"
    r"(?: then)?(?:\s*,\s*(?:bring|take|fetch) (?:it|that) (?:along|over|instead))?"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _none_there47r(text: str, lexicon: Lexicon) -> str:
    """Session 47 (12r): a request for a thing the scene lacks, a cue, "there aren't any chips"
    ("there isn't one"), then another thing ("the bottle then", "I meant her bottle"): the
    request with that thing, when the thing said missing names nothing of the scene and the
    other is one thing of it."""
    if "there " not in text.lower():
        return text
    m = _NONE_THERE47R.match(text.strip())
    if m is None:
        return text
    head = m["head"]
    if m["k"] and m["k"].lower() != "one":
        word = m["k"]
    else:  # "there isn't one": the one thing the request names that the scene lacks
        said = re.findall(r"(?:^|\b(?:the|a|an|some)\s|'s\s)([a-z]+)\b", head, _F)
        unknown = [w for w in said if not _ids(w, lexicon)]
        if len(unknown) != 1:
            return text
        word = unknown[0]
    if _ids(word, lexicon) or not re.search(rf"\b{re.escape(word)}\b", head, _F):
        return text
    fix = re.sub(r"^(?:her|his) ", "the ", m["fix"], flags=_F)
    objs = _ids(fix, lexicon, "object")
    if len(objs) != 1 or _ids(fix, lexicon) != objs:
        return text
    people = _ids(head, lexicon, "human")
    out = re.sub(rf"(?:\bthe )?\b{re.escape(word)}\b", fix, head, count=1, flags=_F)
    owner = re.fullmatch(r"(?P<p>.+?)'s (?:the )?[a-z]+", out.replace(fix, "x", 1), _F)
    if owner is not None and len(people) == 1:
        out = f"Give {owner['p']} {fix}"  # "Person A's cup, …": hers to hand over
    out = f"{out[:1].upper()}{out[1:]}{m['end'] or '.'}"
    node = _reading(out, lexicon)
    if node is None or {x.obj for x in tasks(node)} != objs:
        return text
    return out


# "Omar asked for the white cup, well, I heard white, but he corrected me: it's the green cup he's
# after." (as the lead's `thought_but47l`: 'no, it's …')
_HEARD_BUT47R = re.compiled(
    r"\s*,\s*(?:well\s*,?\s*)?I (?:heard|thought I heard|caught|understood|took it as) [^,;:]+?"
    r"\s*,\s*but (?:she|he|they) (?:corrected me|put me right|set me straight)\s*[:,;]\s*"
    r"(?=it(?:'s| is| was) )",
    _F,
)


def _heard_but47r(text: str, lexicon: Lexicon) -> str:
    """Session 47 (12r): ", well, I heard white, but he corrected me: it's the green cup he's
    after" takes back what came before as ", no, it's …" does (the correction rules read it or
    refuse it)."""
    if "corrected" not in text and "put me right" not in text and "straight" not in text:
        return text
    return _read_or44r(_HEARD_BUT47R.sub(", no, ", text, count=1), text, lexicon)


# "Kofi asked for the small spanner, no, I've mixed it up, the drill's what he's after."
_MIXED_UP47R = re.compiled(
    r"(?P<cue>,\s*(?:no|sorry|oh)\s*,\s*)(?:I've (?:mixed (?:it|them|that) up|got (?:it|that) "
    r"(?:wrong|mixed up)|muddled (?:it|them|that)(?: up)?)|I got (?:it|that) wrong|my mistake|my "
    r"bad)\s*,\s*(?P<x>the [a-z]+(?: [a-z]+)?)(?:'s| is) what (?P<pro>he|she)(?:'s| is) after"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _mixed_up47r(text: str, lexicon: Lexicon) -> str:
    """Session 47 (12r): ", no, I've mixed it up, the drill's what he's after" is ", no, it's
    the drill he's after" (session 45's correction)."""
    if "what" not in text.lower():
        return text
    m = _MIXED_UP47R.search(text.strip())
    if m is None:
        return text
    out = f"{text.strip()[: m.start()]}, no, it's {m['x']} {m['pro']}'s after{m['end'] or '.'}"
    return _read_or44r(out, text, lexicon)


# "That medium box wants to go on the pallet, or rather the conveyor, the pallet's full of the
# basketmaker's stock."
_GOES_ON47R = re.compiled(
    r"^(?:that|the|this) (?P<x>[a-z]+(?: [a-z]+)?) (?:wants|needs|has|ought) to go (?P<on>on|in|"
    r"onto|into) ",
    _F,
)


def _fix_why_goes47r(text: str, lexicon: Lexicon) -> str:
    """Session 47 (12r): "That medium box wants to go on the pallet, or rather the conveyor, the
    pallet's full of …" is "Put the medium box on the pallet, …", whose closing reason session
    46's `_fix_why46r` takes off (said as it is, the reason went first, and the wanting-to-go
    that is left was then read by no later step)."""
    if "to go" not in text.lower():
        return text
    m = _GOES_ON47R.match(text.strip())
    if m is None or len(_ids(f"the {m['x']}", lexicon, "object")) != 1:
        return text
    out = f"Put the {m['x']} {m['on']} {text.strip()[m.end() :]}"
    done = _fix_why46r(out, lexicon)
    return text if done == out else done


# "Alice wants the red mug, oh hang about, she said blue, the blue mug to Alice."
_RESTATED47R = re.compiled(
    r"^(?P<head>[^,;]+?)\s*,\s*(?:(?:oh|ah|er|no|hang about|hang on|hold on|wait)\s*,?\s*)+"
    r"(?:she|he) said (?P<w>[a-z]+)\s*,\s*(?P<req>[^,;]+?)(?P<end>\s*[.!]?)$",
    _F,
)
# what says the request after the cue adds to the first (the lead's `added_correction47l`)
_ADDS47R = re.compiled(r"\b(?:too|as well|also|first|then|next|and|plus|afterwards)\b", _F)


def _restated47r(text: str, lexicon: Lexicon) -> str:
    """Session 47 (12r): a request of one thing for one person, a cue ("oh hang about"), what
    that person said ("she said blue"), then the request said again whole with another thing of
    the same kind for the same person ("the blue mug to Alice"): the request said again."""
    if "said" not in text.lower():
        return text
    m = _RESTATED47R.match(text.strip())
    if m is None or _ADDS47R.search(m["req"]):
        return text
    if not re.search(rf"\b{re.escape(m['w'])}\b", m["req"], _F):
        return text
    first, again = _reading(f"{m['head']}.", lexicon), _reading(f"{m['req']}.", lexicon)
    if not isinstance(first, Task) or not isinstance(again, Task):
        return text
    cats = {o.id: o.category for o in lexicon.scene.objects}
    if (first.kind, first.target) != (again.kind, again.target) or first.obj == again.obj:
        return text
    if cats.get(first.obj) != cats.get(again.obj):
        return text
    return f"{m['req'][:1].upper()}{m['req'][1:]}{m['end'] or '.'}"


# "The cup to Person B, I mean Person A, the one back from the celesta recital."
_ONE_BACK47R = re.compiled(
    r"\s*,\s*the one (?:who's |who is |that's )?(?:just )?(?:back from|home from|fresh from|in "
    r"from|off) (?P<what>[^,;.!?]+?)(?P<end>\s*[.!]?)$",
    _F,
)


def _one_back47r(text: str, lexicon: Lexicon) -> str:
    """Session 47 (12r): a person said last, then "the one back from the celesta recital" (who
    that is, naming nothing of the scene): taken off, when all that is left hands over to that
    person."""
    if "the one" not in text.lower():
        return text
    t = text.strip()
    m = _ONE_BACK47R.search(t)
    if m is None or not _remark_only42s(m["what"], lexicon):
        return text
    head = t[: m.start()]
    pid = _person46r(re.split(r"[,;]", head)[-1], lexicon)
    if pid is None:
        return text
    out = f"{head}{m['end'] or '.'}"
    node = _reading(out, lexicon)
    if node is None or any(x.target != pid for x in tasks(node)):
        return text
    return out


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
    try:
        which_forgotten41r(text, lexicon)
    except GroundingError:
        return  # session 41's refusal names them ("one of the boxes, I can't remember which")
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
    _clear_of47r,
    _state_like47r,
    _before_looks47r,
    _claimed47r,
    _none_there47r,
    _heard_but47r,
    _mixed_up47r,
    _fix_why_goes47r,
    _restated47r,
    _one_back47r,
)
# refusals asked of the text before it is read (offline._parse, after the session-46 ones)
REFUSE47R: tuple[Callable[[str, Lexicon], None], ...] = (doubt_one47r,)
# checks of the whole instruction's reading (offline.parse_instruction, after the session-46 ones)
CHECK47R: tuple[Callable[[str, Node, Lexicon], None], ...] = ()
