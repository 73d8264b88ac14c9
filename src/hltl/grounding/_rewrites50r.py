"""The grounder's rules of session 50, engineer 12r (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _ids, _reading
from hltl.grounding._rewrites42s import _remark_only42s
from hltl.grounding._rewrites44r import _agrees44r, _read_or44r
from hltl.grounding._rewrites46r import _P46R, _person46r
from hltl.grounding._rewrites48r import _choice_for48r
from hltl.grounding._rewrites49r import _THING49R, _it_is49r, _one49r, _targets49r, _the_one49r
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
)
# refusals asked of the text before it is read (offline._parse, after the session-49 ones)
REFUSE50R: tuple[Callable[[str, Lexicon], None], ...] = ()
# checks of the whole instruction's reading (offline.parse_instruction, after the session-49 ones)
CHECK50R: tuple[Callable[[str, Node, Lexicon], None], ...] = ()
