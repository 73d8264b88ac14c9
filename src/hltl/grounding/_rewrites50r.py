"""The grounder's rules of session 50, engineer 12r (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _ids, _reading
from hltl.grounding._rewrites42s import _NEED_STATE42S, _remark_only42s
from hltl.grounding._rewrites44r import _agrees44r, _read_or44r
from hltl.grounding._rewrites46r import _P46R, _person46r
from hltl.grounding._rewrites48r import _choice_for48r
from hltl.grounding._rewrites49r import (
    _BACK49R,
    _CUE49R,
    _THING49R,
    _it_is49r,
    _one49r,
    _targets49r,
    _the_one49r,
)
from hltl.grounding.lexicon import Lexicon
from hltl.grounding.tree import Node, has_choice, tasks

# -- blind48: choices left to one person ----------------------------------------------------------

# a closing word that leaves the choice to the person ("just one of them", "either one", "whatever's
# handiest"): it says the choice again, and is taken off
_EITHER50R = re.compiled(
    r"^(?:(?:just|only|any) )?(?:one|either|either one|any one) (?:of them|of the two|will do)$|"
    r"^(?:just )?(?:one or the other|either one|either will do|any will do)$|"
    r"^(?:whatever|whichever)(?:'s| is) (?:handiest|nearest|closest|easiest|quickest|to hand|"
    r"nearest to hand|easiest to reach|easiest to get at)$|"
    r"^(?:she|he|they)(?:'ll| will) (?:not|never) be (?:fussy|fussed|bothered|picky|choosy)$|"
    r"^(?:she|he|they) (?:won't|wouldn't|will not|would not) (?:be )?(?:fussy|fussed|bothered|"
    r"picky|choosy|mind)$",
    _F,
)


def _choice50r(head: str, tail: str, end: str, text: str, lexicon: Lexicon) -> str:
    """``head`` (a choice handed to one person) with the closing remarks of ``tail`` taken off:
    those that say the choice again ("just one of them", "she won't be fussy", "whatever's
    handiest") and, as ``_choice_for48r`` has them, the easy-going ones naming nothing."""
    parts = [p.strip() for p in tail.split(",") if p.strip()]
    node = _reading(f"{head}{end or '.'}", lexicon)
    people = _targets49r(node)
    if node is None or people is None or len(people) != 1 or not has_choice(node):
        return text
    pid = next(iter(people))
    for part in parts:
        pro = re.match(r"(?P<pro>she|he)\b", part, _F)
        if _EITHER50R.match(part) is not None and (
            pro is None or _agrees44r(pid, pro["pro"], lexicon)
        ):
            continue
        rest = ", ".join(p for p in parts if _EITHER50R.match(p) is None)
        return _choice_for48r(head, rest, end, text, lexicon)
    return _choice_for48r(head, "", end, text, lexicon)


# "… so either mug will do for her, red or blue", "Any of the four will do for Person A"
_WILL_DO50R = re.compiled(
    rf"\bso (?P<q>either|any|any old|whichever) (?P<k>[a-z]+)(?: at all)?(?: will|'ll| would|'d|"
    rf" should) do(?: (?:fine|nicely|just fine))? for (?P<p>her|him|{_P46R})\b",
    _F,
)
_ANY_OF_N50R = re.compiled(
    r"^(?:any|either|any one|whichever) of the (?P<n>two|three|four|five|six|seven|eight) "
    r"(?:things )?(?:will do|'ll do|would do|is fine|are fine|'d do|does) for "
    rf"(?P<p>{_P46R})(?P<tail>(?:\s*,\s*[^,.;!?]+)*?)(?P<end>\s*[.!]?)$",
    _F,
)


def _will_do_for50r(text: str, lexicon: Lexicon) -> str:
    """Session 50 (12r): "…, so either mug will do for her" ("so any pen (at all) will do for
    Sam") is "so give her a mug" ("so give Sam any pen"; said alone, it is session 21's),
    'either' when the scene has two of the kind; "Any of the four will do for P, whatever's
    handiest" is "P can have any of the four things" (the grammar checks the count)."""
    if " do " not in text.lower() and " do," not in text.lower():
        return text
    m = _ANY_OF_N50R.match(text.strip())
    if m is not None:
        if _person46r(m["p"], lexicon) is None:
            return text
        head = f"{m['p']} can have any of the {m['n']} things"
        return _choice50r(head, m["tail"], m["end"], text, lexicon)
    m = _WILL_DO50R.search(text)
    if m is None:
        return text
    kind = _ids(f"the {m['k']}", lexicon, "object")
    q = m["q"].lower()
    if (
        len(kind) < 2
        or (q == "either" and len(kind) != 2)
        or _ids(f"the {m['k']}", lexicon) != kind
    ):
        return text
    said = f"so give {m['p']} {'any' if q.startswith('any') else 'a'}"
    out = f"{text[: m.start()]}{said} {m['k']}{text[m.end() :]}"
    node = _reading(out, lexicon)
    if node is None or not has_choice(node) or not {t.obj for t in tasks(node)} <= kind:
        return text
    return out


# "Person B's not bothered which, bottle or chips, just one of them.", "Kofi isn't fussed which
# spanner, the big or the small."
_NOT_BOTHERED50R = re.compiled(
    rf"^(?P<p>{_P46R})(?:'s not| is not| isn't| ain't)(?: really| too| that| at all)? "
    r"(?:bothered|fussed|fussy|picky|choosy|particular) (?:about |over |as to )?which"
    r"(?: (?P<k>[a-z]+))?\s*,\s*(?P<x>(?:the )?[a-z]+(?: one)?) or (?P<y>(?:the )?[a-z]+(?: one)?)"
    r"(?P<tail>(?:\s*,\s*[^,.;!?]+)*?)(?P<end>\s*[.!]?)$",
    _F,
)


def _the50r(x: str) -> str:
    """``x`` said with 'the'."""
    return x if x.lower().startswith("the ") else f"the {x}"


def _not_bothered_which50r(text: str, lexicon: Lexicon) -> str:
    """Session 50 (12r): "P's not bothered which, bottle or chips(, just one of them)" ("P isn't
    fussed which spanner, the big or the small") is "Give P the bottle or the chips" ("Give P a
    spanner, the big or the small"): a choice left to P."""
    if "which" not in text.lower() or " or " not in text.lower():
        return text
    m = _NOT_BOTHERED50R.match(text.strip())
    if m is None or _person46r(m["p"], lexicon) is None:
        return text
    if m["k"]:
        head = f"Give {m['p']} a {m['k']}, {m['x']} or {m['y']}"
    else:
        head = f"Give {m['p']} {_the50r(m['x'])} or {_the50r(m['y'])}"
    return _choice50r(head, m["tail"], m["end"], text, lexicon)


# "Lily'll play with whichever block, red or green."
_PLAY_WITH50R = re.compiled(
    rf"^(?P<p>{_P46R})(?:'ll| will| can| could|'d| would)(?: happily| gladly| quite happily)? "
    r"(?:play with|make do with|settle for|go for|get on with|manage with) (?P<q>whichever|either|"
    r"any|any old) (?P<k>[a-z]+)(?P<or>\s*,\s*(?:the )?[a-z]+ or (?:the )?[a-z]+)?"
    r"(?P<tail>(?:\s*,\s*[^,.;!?]+)*?)(?P<end>\s*[.!]?)$",
    _F,
)


def _play_with50r(text: str, lexicon: Lexicon) -> str:
    """Session 50 (12r): "P'll play with whichever block(, red or green)" ("make do with",
    "settle for") is "Give P a block(, red or green)": a choice left to P."""
    low = text.lower()
    if "whichever" not in low and "either" not in low and "any" not in low:
        return text
    m = _PLAY_WITH50R.match(text.strip())
    if m is None or _person46r(m["p"], lexicon) is None:
        return text
    q = "any" if m["q"].lower().startswith("any") else "a"
    head = f"Give {m['p']} {q} {m['k']}{m['or'] or ''}"
    return _choice50r(head, m["tail"], m["end"], text, lexicon)


# -- blind48: the person said by a role first, a request said as what someone says -----------------

# "For the make-up artist, that's Person A, one of the cup or the apple, she can pick."
_FOR_ROLE50R = re.compiled(
    r"^for (?P<role>the [a-z' -]+?)\s*,\s*(?:that's|that is|i\.e\.|namely|i mean|meaning) "
    rf"(?P<p>{_P46R})\s*,\s*(?P<what>[^,;:]+?)(?P<tail>(?:\s*,\s*[^,.;!?]+)*?)(?P<end>\s*[.!]?)$",
    _F,
)


def _for_role50r(text: str, lexicon: Lexicon) -> str:
    """Session 50 (12r): "For the make-up artist, that's P, <what>(, …)" is "<what> for P(, …)":
    the role (naming no one else of the scene) said again as the person."""
    if not text.lower().startswith("for the "):
        return text
    m = _FOR_ROLE50R.match(text.strip())
    if m is None:
        return text
    pid = _person46r(m["p"], lexicon)
    if pid is None:
        return text
    if not _remark_only42s(m["role"], lexicon) and _person46r(m["role"], lexicon) != pid:
        return text
    what = m["what"]
    out = f"{what[:1].upper()}{what[1:]} for {m['p']}{m['tail']}{m['end'] or '.'}"
    node = _reading(out, lexicon)
    if _targets49r(node) != {pid}:
        return text
    return out


# "Person B says both the apple and the cup, he's off to the gem cutting."
_SAYS_BOTH50R = re.compiled(
    rf"^(?P<p>{_P46R}) (?:says|said|reckons|tells me|told me|'s saying|is saying)(?: (?:it's|"
    rf"it is))? both (?P<x>{_THING49R}) and (?P<y>{_THING49R})(?P<rest>(?:\s*,\s*[^,;.!?]+)?"
    r"\s*[.!]?)$",
    _F,
)


def _says_both50r(text: str, lexicon: Lexicon) -> str:
    """Session 50 (12r): "P says both the apple and the cup(, …)" (what P says is the things P
    asks for) is "P wants both the apple and the cup(, …)"."""
    if "both" not in text.lower():
        return text
    m = _SAYS_BOTH50R.match(text.strip())
    if m is None:
        return text
    pid = _person46r(m["p"], lexicon)
    if pid is None:
        return text
    out = f"{m['p']} wants both {m['x']} and {m['y']}{m['rest'] or '.'}"
    node = _reading(out, lexicon)
    if _targets49r(node) != {pid} or node is None or len(list(tasks(node))) != 2:
        return text
    return out


# "both the small and the medium box go to Tom"
_BOTH_THE_AND50R = re.compiled(
    r"\bboth (?:of )?the (?P<a>[a-z]+) and the (?P<b>[a-z]+) (?P<k>[a-z]+)\b", _F
)


def _both_the_and50r(text: str, lexicon: Lexicon) -> str:
    """Session 50 (12r): "both the small and the medium box(es)" is "both the small box and the
    medium box", when each names one object of that kind."""
    if "both" not in text.lower():
        return text
    m = _BOTH_THE_AND50R.search(text)
    if m is None:
        return text
    k = _one49r(m["k"])
    kind = _ids(f"the {k}", lexicon, "object")
    a = _ids(f"the {m['a']} {k}", lexicon, "object")
    b = _ids(f"the {m['b']} {k}", lexicon, "object")
    if len(kind) < 2 or len(a) != 1 or len(b) != 1 or a == b or not (a | b) <= kind:
        return text
    out = f"{text[: m.start()]}both the {m['a']} {k} and the {m['b']} {k}{text[m.end() :]}"
    node = _reading(out, lexicon)
    if node is None or {t.obj for t in tasks(node)} != a | b:
        return text
    return out


# "Whichever bottle you can lay a hand on, Person A's to get it, …"
_LAY_HANDS50R = re.compiled(
    r"^(?:whichever|whatever) (?P<k>[a-z]+) you can (?:lay (?:a hand|your hands?|hands) on|"
    r"find|get hold of|get your hands? on|put (?:a hand|your hands?) on|reach|grab|"
    r"lay hold of)\s*,\s*(?P<rest>.+)$",
    _F,
)


def _lay_hands50r(text: str, lexicon: Lexicon) -> str:
    """Session 50 (12r): "Whichever bottle you can lay a hand on, P's to get it" is the request
    with 'it' the bottle when the scene has one (a choice of them when it has more); "Any bottle
    you can lay hands on, give it to P" is session 34's."""
    if " you can " not in text.lower():
        return text
    m = _LAY_HANDS50R.match(text.strip())
    if m is None:
        return text
    thing = _the_one49r(m["k"], lexicon)
    if thing is not None:
        out = _it_is49r(m["rest"], thing, next(iter(_ids(thing, lexicon))), lexicon)
        return text if out is None else out
    kind = _ids(f"the {m['k']}", lexicon, "object")
    if len(kind) < 2 or re.search(r"\bit\b", m["rest"], _F) is None:
        return text
    out = re.sub(r"\bit\b", f"a {m['k']}", m["rest"], count=1, flags=_F)
    out = f"{out[:1].upper()}{out[1:]}"
    node = _reading(out, lexicon)
    if node is None or not has_choice(node) or {t.obj for t in tasks(node)} != kind:
        return text
    return out


# -- blind48: a closing remark about the person the request names, said by a role ---------------

# "…, the intern isn't choosy", "…, the visitor's brought a friend along", "…, the guest wants
# it squeezed over his fish"
_ROLE_SAYS50R = re.compiled(
    r"^(?P<head>.+?)\s*,\s*(?P<who>the [a-z]+(?:[ -][a-z]+)?)(?P<pred>(?:'s|'d|'ll| is| was| has|"
    r" had| isn't| wasn't| won't| wouldn't| doesn't| didn't| ain't| [a-z]+s)\b[^,;.!?]*)"
    r"(?P<end>\s*[.!]?)$",
    _F,
)
_EASY50R = re.compiled(
    r"^(?:'s not|'s not that| is not| isn't| ain't| won't be| wouldn't be| will not be)(?: too| "
    r"that| at all| really)? (?:choosy|fussy|fussed|bothered|picky|particular)$|"
    r"^(?: doesn't| won't| does not| will not) (?:mind|care)(?: which)?$",
    _F,
)
_WANTS_IT50R = re.compiled(
    r"^(?: wants| needs|'d like| would like| is after|'s after| asked for) (?:it|them)\b"
    r"(?P<rest>.*)$",
    _F,
)


def _role_says50r(text: str, lexicon: Lexicon) -> str:
    """Session 50 (12r): a request handing things to one person closed by a remark about that
    person said by a role of theirs ("Any pen (at all) for Sam, the intern isn't choosy", "Both
    cups go to Emma, the visitor's brought a friend along", "…, I mean Mr Novak, the guest wants
    it squeezed over his fish"): the remark (easy-going, that person wanting 'it', or naming
    nothing of the scene) taken off."""
    if ", the " not in text.lower():
        return text
    m = _ROLE_SAYS50R.match(text.strip())
    if m is None:
        return text
    head = re.sub(r"\b(?P<a>any (?:old )?[a-z]+) at all\b", r"\g<a>", m["head"], flags=_F)
    for who, pred in _split_role50r(m["who"], m["pred"]):
        pid = _person46r(who, lexicon)
        if pid is None:
            continue
        want = _WANTS_IT50R.match(pred)
        said = want["rest"] if want is not None else pred
        said = re.sub(r"\b(?:his|her|hers|him|he|she)\b", "", said, flags=_F)
        if _EASY50R.match(pred) is None and said.strip() and not _remark_only42s(said, lexicon):
            return text
        out = f"{head}{m['end'] or '.'}"
        node = _reading(out, lexicon)
        if _targets49r(node) != {pid} or any(
            not _agrees44r(pid, p, lexicon)
            for p in re.findall(r"\b(?:his|her|he|she|him)\b", pred, _F)
        ):
            return text
        return out
    return text


def _split_role50r(who: str, pred: str) -> list[tuple[str, str]]:
    """The ways of saying "the make-up artist's …": the role as said, or its first word alone
    (the second word then the predicate's)."""
    words = who.split()
    out = [(who, pred)]
    if len(words) == 3:
        out.append((" ".join(words[:2]), f" {words[2]}{pred}"))
    return out


# "Person B asked for one of the bottle and the chips, and I've lost track of which."
_ONE_OF_AND50R = re.compiled(
    rf"\b(?P<v>asked for|asked me for|wanted|wants|was after|is after|needs|needed) (?:one|either) "
    rf"of (?P<x>{_THING49R}) and (?P<y>{_THING49R})\b",
    _F,
)


def _one_of_and50r(text: str, lexicon: Lexicon) -> str:
    """Session 50 (12r): "P asked for one of the bottle and the chips" is "P asked for the
    bottle or the chips" (each an object of the scene): a choice (refused when the speaker has
    lost which; "Give P one of …" is session 31's)."""
    if " of the " not in text.lower() or " and " not in text.lower():
        return text
    m = _ONE_OF_AND50R.search(text)
    if m is None:
        return text
    x = _ids(m["x"], lexicon)
    y = _ids(m["y"], lexicon)
    if (
        len(x) != 1
        or len(y) != 1
        or x == y
        or not (x | y) <= _ids(f"{m['x']} {m['y']}", lexicon, "object")
    ):
        return text
    out = f"{text[: m.start()]}{m['v']} {m['x']} or {m['y']}{text[m.end() :]}"
    return _read_or44r(out, text, lexicon)


# -- blind48: counts said of the scene ------------------------------------------------------------

# "There's only the one bottle at the twitching hide, and Person A's to have it.", "There's just
# the one packet of crisps, and Alice has called dibs on it."
_ONE_THERE50R = re.compiled(
    r"^there(?:'s| is) (?:just |only )?(?:the one|a single|one single|the single) "
    r"(?P<x>[a-z]+(?: of [a-z]+| [a-z]+)?)(?P<at> (?:at|in|on|up at|down at|over at|out at) "
    r"the [a-z' -]+?)?\s*,?\s*(?:and|so) "
    rf"(?P<p>{_P46R})(?P<v>(?:'s| is| has) (?:to have|to get|the one to have|the one to get)|"
    r"(?:'s| has) (?:called|got|put in|bagged|claimed|bagsied)(?: dibs on| first dibs on)?) it"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _one_there50r(text: str, lexicon: Lexicon) -> str:
    """Session 50 (12r): "There's only the one bottle at the twitching hide, and P's to have it"
    ("…the one packet of crisps, and P has called dibs on it") is "Give P the bottle" when the
    scene has exactly one (a place naming nothing of the scene; the plain "There's only the one
    bottle, and P's to have it" is session 40's)."""
    if not text.lower().startswith("there"):
        return text
    m = _ONE_THERE50R.match(text.strip())
    if m is None:
        return text
    plain = m["at"] is None and " of " not in m["x"] and "dibs" not in m["v"].lower()
    if plain and re.search(r"(?:called|got|put in|bagged|claimed|bagsied)", m["v"], _F) is None:
        return text
    if m["at"] is not None and not _remark_only42s(m["at"], lexicon):
        return text
    pid = _person46r(m["p"], lexicon)
    thing = _the_one49r(m["x"], lexicon)
    if pid is None or thing is None:
        return text
    out = f"Give {m['p']} {thing}{m['end'] or '.'}"
    return out if _targets49r(_reading(out, lexicon)) == {pid} else text


# "The lone bottle in the room goes to Person A, …"
_LONE_IN50R = re.compiled(
    r"\bthe (?:lone|sole|one and only|single) (?P<x>[a-z]+) (?:in the room|in here|on hand|"
    r"to hand|going|around|about|we have|we've got)\b",
    _F,
)


def _lone_in50r(text: str, lexicon: Lexicon) -> str:
    """Session 50 (12r): "the lone bottle in the room" ("the sole cup going") is "the bottle"
    when the scene has exactly one."""
    low = text.lower()
    if "lone" not in low and "sole" not in low and "single" not in low and "only" not in low:
        return text
    m = _LONE_IN50R.search(text)
    if m is None:
        return text
    thing = _the_one49r(m["x"], lexicon)
    if thing is None:
        return text
    return _read_or44r(f"{text[: m.start()]}{thing}{text[m.end() :]}", text, lexicon)


# "The three boxes, onto the belt with the lot of them, …"
_LOT_OF_THEM50R = re.compiled(
    r"^(?P<what>the (?:two|three|four|five|six) [a-z]+|both [a-z]+|all the [a-z]+|all [a-z]+)"
    r"\s*,\s*(?P<prep>onto|on to|on|into|in) (?P<s>the [a-z]+(?: [a-z]+)?) with (?:the lot|all|"
    r"the whole lot|both|the pair) of (?:them|'em)(?P<rest>.*)$",
    _F,
)


def _lot_of_them50r(text: str, lexicon: Lexicon) -> str:
    """Session 50 (12r): "The three boxes, onto the belt with the lot of them(, …)" is "The
    three boxes onto the belt(, …)": 'the lot of them' says the things named before again."""
    if "of them" not in text.lower() and "of 'em" not in text.lower():
        return text
    m = _LOT_OF_THEM50R.match(text.strip())
    if m is None:
        return text
    if len(_ids(m["s"], lexicon, "surface")) != 1 or _ids(m["s"], lexicon) != _ids(
        m["s"], lexicon, "surface"
    ):
        return text
    out = f"{m['what']} {m['prep']} {m['s']}{m['rest']}"
    node = _reading(out, lexicon)
    objs = _ids(m["what"], lexicon, "object")
    if node is None or not objs or {t.obj for t in tasks(node)} != objs:
        return text
    return out


# "The pair of spanners wants locking away in the locker before …"
_PAIR_WANTS50R = re.compiled(
    r"^(?P<what>the pair of [a-z]+|the two [a-z]+|both (?:the )?[a-z]+|the [a-z]+(?: [a-z]+)?) "
    r"(?:wants|want|needs|need) (?:locking away|locking up|putting away|putting|tidying away|"
    r"stowing|stowing away|storing|storing away|packing away|popping) (?P<prep>in|into|on|onto|"
    r"inside) (?P<s>the [a-z]+)(?P<rest>.*)$",
    _F,
)


def _pair_wants50r(text: str, lexicon: Lexicon) -> str:
    """Session 50 (12r): "The pair of spanners wants locking away in the locker(, …)" is "Put
    the two spanners in the locker(, …)" ('the pair of Ks' when the scene has exactly two; "the
    X needs putting away on the shelf" likewise)."""
    if " want" not in text.lower() and " need" not in text.lower():
        return text
    m = _PAIR_WANTS50R.match(text.strip())
    if m is None:
        return text
    what = m["what"]
    pair = re.match(r"the pair of (?P<k>[a-z]+)$", what, _F)
    if pair is not None:
        if len(_ids(f"the {_one49r(pair['k'])}", lexicon, "object")) != 2:
            return text
        what = f"the two {pair['k']}"
    objs = _ids(what, lexicon, "object")
    if not objs or _ids(what, lexicon) != objs:
        return text
    out = f"Put {what} {m['prep']} {m['s']}{m['rest']}"
    node = _reading(out, lexicon)
    if (
        node is None
        or {t.obj for t in tasks(node)} != objs
        or any(t.kind != "place" for t in tasks(node))
    ):
        return text
    return out


# -- blind48: corrections -------------------------------------------------------------------------


def _about50r(words: str, people: set[str], lexicon: Lexicon) -> bool:
    """Whether ``words`` (a remark) name nothing of the scene but ``people`` (by a name, or a
    pronoun that may be one of them), and want, negate, count and choose nothing."""
    said = words
    if not _ids(words, lexicon) <= people:
        return False
    for h in lexicon.scene.humans:
        if h.id in people:
            for name in sorted((h.name, *h.aliases), key=len, reverse=True):
                said = re.sub(rf"\b{re.escape(name)}\b(?:'s)?", "", said, flags=_F)
    pros = re.findall(r"\b(?:she|he|her|him|his|hers)\b", said, _F)
    if any(not any(_agrees44r(p, x, lexicon) for p in people) for x in pros):
        return False
    said = re.sub(r"\b(?:she|he|her|him|his|hers)\b", "", said, flags=_F)
    return not said.strip() or _remark_only42s(said, lexicon)


# "The bottle to Alice, no, hold on, she said crisps at the bill sticker's meeting, so the
# crisps.", "Chips to Person A, no, my mistake, she asked for the bottle on her way to the fife
# band."
_SAID_WHY50R = re.compiled(
    r"(?P<lead>,\s*(?P<pro>she|he) (?:said|asked for|asked me for|wanted|was after) )"
    r"(?P<y>(?:the )?[a-z]+(?: [a-z]+)?)(?P<why> (?:at|on|during|before|after|in|for|from) "
    r"[^,;.!?]+?)?(?:\s*,\s*so (?P<again>(?:the )?[a-z]+(?: [a-z]+)?))?(?P<end>\s*[.!]?)$",
    _F,
)


def _said_why50r(text: str, lexicon: Lexicon) -> str:
    """Session 50 (12r): a correction said as what the person said or asked for, with when or
    where ("…, no, hold on, she said crisps at the bill sticker's meeting(, so the crisps)",
    "…, no, my mistake, she asked for the bottle on her way to the fife band"): the when or
    where (naming nothing of the scene but that person) and the 'so' that says the thing again
    taken off, a bare thing said with 'the' ("she said the crisps", as session 40 reads it)."""
    if " said " not in text.lower() and " asked " not in text.lower() and "wanted" not in text:
        return text
    m = _SAID_WHY50R.search(text)
    if m is None or not _BACK49R.search(text[: m.start()]) or text.count(",") < 2:
        return text
    if m["why"] is None and m["again"] is None and m["y"].lower().startswith("the "):
        return text
    y = _ids(_the50r(m["y"]), lexicon, "object")
    if len(y) != 1 or _ids(_the50r(m["y"]), lexicon) != y:
        return text
    if m["again"] is not None and _ids(_the50r(m["again"]), lexicon) != y:
        return text
    first = _reading(f"{text[: m.start()].split(',')[0]}.", lexicon)
    was = _targets49r(first)
    if was is None or len(was) != 1 or not _agrees44r(next(iter(was)), m["pro"], lexicon):
        return text
    if m["why"] is not None and not _about50r(m["why"], was, lexicon):
        return text
    out = f"{text[: m.start()]}{m['lead']}{_the50r(m['y'])}{m['end'] or '.'}"
    node = _reading(out, lexicon)
    if _targets49r(node) != was or node is None or {t.obj for t in tasks(node)} != y:
        return text
    return out


# "Bottle to Person A, no, hang on, it's Person B who's back from the gorge walking thirsty, so to
# him.", "Bib to Ava, no, silly me, Ava's a big girl now, so to Lily, she's having her mash."
_SO_TO50R = re.compiled(
    rf"^(?P<head>[^,;]+?)\s*,\s*(?P<cue>{_CUE49R}(?:(?:silly me|my mistake|my bad)\s*,\s*)?)"
    r"(?P<mid>[^,;]+?)\s*,\s*so (?:to |for )?(?P<q>her|him|[a-z][a-z ]*?)"
    r"(?:\s*,\s*(?P<why>[^,;.!?]+?))?(?P<end>\s*[.!]?)$",
    _F,
)
_CLEFT_MID50R = re.compiled(rf"^it(?:'s| is| was) (?P<q>{_P46R}) who(?:'s| is| was| has) ", _F)


def _so_to50r(text: str, lexicon: Lexicon) -> str:
    """Session 50 (12r): a request to one person, a cue, why the first person does not get it
    (or "it's Q who's back from …"), then "so to Q(, she's having her mash)" is "<request>, no,
    Q": each remark naming nothing of the scene but those two, the pronouns fitting."""
    if ", so " not in text.lower():
        return text
    m = _SO_TO50R.match(text.strip())
    if m is None or not _BACK49R.search(m["cue"]):
        return text
    first = _reading(f"{m['head']}.", lexicon)
    was = _targets49r(first)
    if first is None or was is None or len(was) != 1:
        return text
    cleft = _CLEFT_MID50R.match(m["mid"])
    said = cleft["q"] if cleft is not None else m["q"]
    q = _person46r(said, lexicon)
    if q is None or q in was:
        return text
    if m["q"].lower() in ("her", "him") and (cleft is None or not _agrees44r(q, m["q"], lexicon)):
        return text
    if cleft is None and _person46r(m["q"], lexicon) != q:
        return text
    # "it's Q who's back from the gorge walking thirsty": Q's need is what the correction says
    mid = _NEED_STATE42S.sub("", m["mid"][cleft.end() :]) if cleft is not None else m["mid"]
    if not _about50r(mid, {*was, q}, lexicon):
        return text
    if m["why"] is not None and not _about50r(m["why"], {q}, lexicon):
        return text
    out = f"{m['head']}, no, {said}{m['end'] or '.'}"
    node = _reading(out, lexicon)
    if _targets49r(node) != {q} or node is None:
        return text
    if {t.obj for t in tasks(node)} != {t.obj for t in tasks(first)}:
        return text
    return out


# "Gloves to Mia, no, the packing tape instead, the billposter already lent Mia a pair."
_INSTEAD_WHY50R = re.compiled(
    rf"^(?P<head>[^,;]+?\s*,\s*(?:{_CUE49R})(?P<y>the [a-z]+(?: [a-z]+)?) instead)\s*,\s*"
    r"(?P<why>[^,;.!?]+?)(?P<end>\s*[.!]?)$",
    _F,
)


def _instead_why50r(text: str, lexicon: Lexicon) -> str:
    """Session 50 (12r): "X to P, no, the Y instead, <why>" with why naming nothing of the scene
    but P: the why taken off (the correction reads as before)."""
    if "instead" not in text.lower():
        return text
    m = _INSTEAD_WHY50R.match(text.strip())
    if m is None or not _BACK49R.search(m["head"]):
        return text
    out = f"{m['head']}{m['end'] or '.'}"
    node = _reading(out, lexicon)
    got = _targets49r(node)
    if got is None or len(got) != 1 or not _about50r(m["why"], got, lexicon):
        return text
    return out


# "Torch on the bench, no, in the locker, where it lives between spelunking trips."
_WHERE_IT_LIVES50R = re.compiled(
    r"\s*,\s*where (?:it|they)(?: lives?| belongs?| goes| go| usually (?:lives?|goes|go)| "
    r"always (?:lives?|goes|go)|(?:'s| is| are) (?:kept|stored|usually kept))(?P<why> [^,;.!?]+?)?"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _where_it_lives50r(text: str, lexicon: Lexicon) -> str:
    """Session 50 (12r): a placing closed by "where it lives (between spelunking trips)" (where
    it belongs, is kept): the clause says the place again and is taken off."""
    if "where " not in text.lower():
        return text
    m = _WHERE_IT_LIVES50R.search(text.strip())
    if m is None or (m["why"] is not None and not _remark_only42s(m["why"], lexicon)):
        return text
    out = f"{text.strip()[: m.start()]}{m['end'] or '.'}"
    node = _reading(out, lexicon)
    if node is None or any(t.kind != "place" for t in tasks(node)):
        return text
    return out


# the normaliser's first rewrites (wired into normalise._STEPS19, before the session-49 ones)
_STEPS50R_FIRST: tuple[Callable[[str, Lexicon], str], ...] = ()
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-49 ones)
_STEPS50R: tuple[Callable[[str, Lexicon], str], ...] = (
    _will_do_for50r,
    _not_bothered_which50r,
    _play_with50r,
    _for_role50r,
    _says_both50r,
    _both_the_and50r,
    _lay_hands50r,
    _role_says50r,
    _one_of_and50r,
    _one_there50r,
    _lone_in50r,
    _lot_of_them50r,
    _pair_wants50r,
    _said_why50r,
    _so_to50r,
    _instead_why50r,
    _where_it_lives50r,
)
# refusals asked of the text before it is read (offline._parse, after the session-49 ones)
REFUSE50R: tuple[Callable[[str, Lexicon], None], ...] = ()
# checks of the whole instruction's reading (offline.parse_instruction, after the session-49 ones)
CHECK50R: tuple[Callable[[str, Node, Lexicon], None], ...] = ()
