"""The grounder's rules of session 46, engineer 12s (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _names, _reading
from hltl.grounding._rewrites42s import _NEGATED42S
from hltl.grounding._rewrites45s import _CORRECTS45S, _NOT_BEFORE45S, _same45s
from hltl.grounding.lexicon import VERBS, Lexicon
from hltl.grounding.tree import Group, Node, tasks

# -- session 46 (12s): order words in a text with no marks (12c's `texted` fuzz) ------------------
#
# The contract (session 46): without stops or commas an order word ('then', 'after', 'first')
# orders only what its own clause says; where it could order more, refuse. Session 45's `texted`
# family (the corpus entries without their stops and commas) found the grammar ordering more (or
# less) than the entries' marks gave it; each check below refuses one way of it.

# an order word that orders what follows it
_THEN46S = (
    r"(?:then|next|afterwards|after that|after this|later|finally|lastly)"
    r"(?!'s|\u2019s| is\b| was\b| has\b)"  # not "after that's done": a clause of its own
)


def _sequenced46s(node: Node) -> bool:
    """Whether ``node`` orders anything (a sequence anywhere in it)."""
    return isinstance(node, Group) and (
        node.op == "seq" or any(_sequenced46s(c) for c in node.children)
    )


# "Bottle to Bob Crisps to Alice Then I'm off to warm up my voice", "the globe goes on the shelf
# and the scissors on the desk and then we're sorted for the inspector": the order word orders
# only the speaker's remark after it (the entries, with their stops, read the tasks together);
# the remark was taken off and the 'then' left behind ordered the tasks before it. Refused where
# every order word of the text orders a clause naming nothing of the scene and the reading orders
# something.
_REMARK_THEN46S = re.compile(rf"\b(?P<w>(?:and )?{_THEN46S})\b(?P<clause>[^,.;:!?]*)", _F)
_POINTS46S = re.compile(
    r"\b(?:it|its|them|they|him|his|her|hers|he|she|one|ones|both|all|each|rest|other|others|"
    r"there|same)\b",
    _F,
)
_ORDERS46S = re.compile(
    r"\b(?:first|firstly|then|next|after|afterwards|before|once|when|whenever|while|until|till|"
    r"second|secondly|third|thirdly|last|lastly|finally|later|order|start|begin|followed|prior|"
    r"soon|straight|meanwhile|subsequently|initially)\b",
    _F,
)


def order_of_remark46s(text: str, node: Node, lexicon: Lexicon) -> None:
    """Session 46 (12s): refused where the only order words order a remark (above)."""
    if not _sequenced46s(node) or not re.search(rf"\b{_THEN46S}\b", text, _F):
        return
    rest, said = text, []
    for m in _REMARK_THEN46S.finditer(text):
        clause = m["clause"].strip()
        if not clause or _names(clause, lexicon) or _POINTS46S.search(clause):
            return  # it orders something of the scene (or something after it)
        said.append((m["w"], clause))
        rest = rest.replace(m.group(0), " ", 1)
    if said and not _ORDERS46S.search(rest):
        word, clause = said[0]
        raise GroundingError(
            f"{word!r} orders only {clause!r}, which names nothing of the scene, yet the tasks "
            "before it would be done in order: say whether they are (a stop or a comma)"
        )


# "First give Person A the bottle then Person B the chips and also Person A the cup and the
# apple", "put the bib on the high chair and then give her the sippy cup oh and Grandad wants the
# teddy": after 'then' (no mark between) a clause added by 'and also' / 'oh and' / 'plus' or by
# 'and <a person> wants …' may be ordered with the 'then' clause or said beside the whole (the
# entries' commas and stops said beside it): refused where the reading orders anything.
_THEN_STRETCH46S = re.compile(rf"\b{_THEN46S}\b(?P<stretch>[^,.;:!?]+)", _F)
_ADDED46S = re.compile(r"\s(?P<add>and also|also|oh and|and oh|plus|and)\s", _F)
_WANTS46S = re.compile(
    r"^(?:'s|s|is|has|wants|needs|gets|would|could|can|should|will|'d|'ll|fancies|asked)\b", _F
)


def _added46s(stretch: str, lexicon: Lexicon) -> str | None:
    """The word adding a clause of its own in ``stretch`` (what follows 'then'), if any."""
    for m in _ADDED46S.finditer(stretch):
        before, rest = stretch[: m.start()].strip(), stretch[m.end() :]
        named = _names(rest, lexicon)
        if not before or not named:
            continue
        if m["add"].lower() != "and":
            return m["add"]
        # only 'and <a person> wants / gets / is …': a clause of its own, not the 'then'
        # clause's verb said again ("then give the cup to bob and the bottle to carol")
        first = named[0]
        if (
            rest.lower().startswith(first.text.lower())
            and all(r.kind == "human" for r in first.refs)
            and _WANTS46S.match(rest[len(first.text) :].lstrip())
        ):
            return f"and {first.text}"
    return None


def then_more46s(text: str, node: Node, lexicon: Lexicon) -> None:
    """Session 46 (12s): refused where what 'then' orders could take in a clause added after it
    (above)."""
    if not _sequenced46s(node) or not re.search(rf"\b{_THEN46S}\b", text, _F):
        return
    for m in _THEN_STRETCH46S.finditer(text):
        added = _added46s(m["stretch"], lexicon)
        if added is not None:
            raise GroundingError(
                f"'then' could order what {added!r} adds after it or only what comes before: "
                "put a stop or a comma"
            )


# "Tom and Mia one box each the third goes on the belt": 'the third' is the third box; as an
# order word ('third', like 'second', is 'then' to the lexer, and 'the' a filler) it made the
# handovers a step before the placement. Refused where 'the second / third' is followed by a verb,
# a preposition or nothing (not "on the second floor": a noun after it), and no name of the scene.
_THE_NTH46S = re.compile(
    r"\bthe (?P<n>second|secondly|third|thirdly)\b(?=\s*(?:$|[,.;:!?]|(?:one |ones )?(?:goes|go|"
    r"gets|is|'s|can|could|should|will|needs|wants|belongs|stays|sits|to|for|on|onto|in|into)\b))"
    r"(?P<after>.*)$",
    _F,
)


def the_ordinal46s(text: str, lexicon: Lexicon) -> None:
    """Session 46 (12s): 'the third' (above) refused."""
    m = _THE_NTH46S.search(text)
    if m is None:
        return
    after = m["after"].strip()
    named = _names(after, lexicon) if after else []
    if named and after.lower().startswith(named[0].text.lower()):
        return  # "the second cup": a name after it (the grammar's to read or refuse)
    raise GroundingError(
        f"'the {m['n']}' is a thing counted, not an order: name it (which one goes where)"
    )


# "bottle first to alice after chips to bob" (the entry: "Bottle first. To Alice. After, chips to
# Bob."): with no stops 'after chips' read the chips before the bottle that 'first' put first.
# Refused where 'first' and then, with no mark between, 'after <a thing of the scene>' are said.
_FIRST_AFTER46S = re.compile(
    r"\bfirst\b[^,.;:!?]*?\bafter\s+(?:the\s+|a\s+|an\s+)?(?P<rest>[^,.;:!?]+)", _F
)


def first_after46s(text: str, lexicon: Lexicon) -> None:
    """Session 46 (12s): 'first' and 'after <thing>' ordering two ways (above) refused."""
    if "first" not in text.lower():
        return
    for m in _FIRST_AFTER46S.finditer(text):
        named = _names(m["rest"], lexicon)
        if (
            named
            and m["rest"].lower().startswith(named[0].text.lower())
            and all(r.kind == "object" for r in named[0].refs)
        ):
            raise GroundingError(
                f"'first' and 'after {named[0].text}' could order the tasks two ways: put a stop "
                "or a comma ('After that, …' or 'after the …')"
            )


# "Chips first to Person A Bottle next Same person Person A the clarinettist" (the entry: "Chips
# first, to Person A. Bottle next. Same person, …"): 'first' and 'next' both said, the reading
# orders nothing. Refused where 'first' and another order word are said and two tasks or more are
# read with no order.
_FIRST46S = re.compile(r"\b(?:first|firstly)\b", _F)
_LATER46S = re.compile(
    r"\b(?:then|next|second|secondly|afterwards|after that|lastly|finally|last)\b", _F
)


def order_dropped46s(text: str, node: Node, lexicon: Lexicon) -> None:
    """Session 46 (12s): an order said and not read (above) refused."""
    if _sequenced46s(node) or not _FIRST46S.search(text) or not _LATER46S.search(text):
        return
    if len(set(tasks(node))) > 1:
        raise GroundingError(
            "'first' and a later order word are said, but the tasks would be done in no order: "
            "put a stop or a comma between them"
        )


# "clear the drill and the screws onto the bench when theyre down kofi gets the torch" (the entry:
# "… onto the bench. When they're down, Kofi gets the torch."): with no stops the 'when' clause
# between two requests could close the first (its time) or open the second (its order), and the
# grammar took it as the first one's and put the torch before the drill. Refused where 'when' /
# 'once' / 'as soon as' / 'after' / 'before' follows a request with no mark or joining word
# between, its clause says 'they' / 'it' / 'he' / 'she' / 'that' of what came before, and a person
# of the scene then wants or gets something, and the reading orders anything.
_SUB_BETWEEN46S = re.compile(
    r"\s(?P<sub>when|whenever|once|as soon as|after|before)\s+(?P<pron>they|theyre|they're|"
    r"they've|it|its|it's|he|hes|he's|she|shes|she's|that|thats|that's|this)\b"
    r"(?P<rest>[^,.;:!?]+)",
    _F,
)
_JOINING46S = frozenset({"and", "then", "so", "but", "or", "plus", "also"})


def sub_between46s(text: str, node: Node, lexicon: Lexicon) -> None:
    """Session 46 (12s): a time clause between two requests with no marks (above) refused."""
    if not _sequenced46s(node):
        return
    for m in _SUB_BETWEEN46S.finditer(text):
        before = text[: m.start()].split()
        if not before or before[-1].lower() in _JOINING46S or before[-1][-1] in ",.;:!?":
            continue
        if m["sub"].lower() in ("after", "before") and m["pron"].lower() in ("that", "this", "it"):
            continue  # 'after that', 'before it': an order word, not a clause
        rest = m["rest"]
        named = _names(rest, lexicon)
        if not named or not _names(" ".join(before), lexicon):
            continue
        first = named[0]
        at = rest.lower().find(first.text.lower())
        if (
            at > 1
            and all(r.kind == "human" for r in first.refs)
            and _WANTS46S.match(rest[at + len(first.text) :].lstrip())
        ):
            raise GroundingError(
                f"'{m['sub']} {m['pron']}{rest[:at].rstrip()}' could say when the request "
                f"before it is done or when {first.text}'s is: put a stop or a comma"
            )


# -- session 46 (12s): run-ons, a text with no marks (blind44's lower case) -----------------------
#
# "crisps up on the shelf ta the pipe fitter keeps nicking them": a courtesy word inside a text
# with no marks, then a remark naming nothing of the scene: the comma after the courtesy put in
# (the older remark rules then take the remark off), when what comes before reads alone, the
# remark negates and corrects nothing, and the whole then reads as the request alone does. A
# pronoun's clause after it ("tape for tom please hes at bay four") is left to sessions 38 and
# 39's rules (12).
_COURTESY_MID46S = re.compile(
    r"(?<=[a-z]) (?P<c>thx|thanks|ta|cheers|pls|plz|please|ty)"
    r" (?!(?:he|she|it|they|hes|shes|its|theyre|he's|she's|it's|they're|i|im|i'm|you|we|were|"
    r"we're|weve|we've)\b)"
    r"(?=[a-z])",
    _F,
)


def _courtesy_mid46s(text: str, lexicon: Lexicon) -> str:
    """Session 46 (12s): the comma above put in (see there)."""
    if re.search(r"[,;:.!?]", text):
        return text
    for m in _COURTESY_MID46S.finditer(text):
        before, after = text[: m.start()], text[m.end() :]
        if _names(after, lexicon) or _NEGATED42S.search(after) or _CORRECTS45S.search(after):
            continue
        alone = _reading(before, lexicon)
        if alone is None:
            continue
        out = f"{before} {m['c']}, {after}"
        if _same45s(_reading(out, lexicon), alone):
            return out
    return text


# "tin of screws on the workbench kofi wants to count them": a request, then with no mark what a
# person of the scene wants or is going to do with it (a verb that is no task of the cell): the
# comma put in, when what comes before reads alone, the clause names no one and nothing else and
# negates and corrects nothing, and the whole then reads as the request alone does.
_PERSON_TO46S = re.compile(
    r"^(?:'s|s)? (?:wants|needs|has|has got|is going|'s going|is gonna|'s gonna|would like|"
    r"wanted|is hoping|'s hoping|plans) to (?P<verb>[a-z]+)\b(?P<rest>[^,;:.!?]*)$",
    _F,
)


def _person_to46s(text: str, lexicon: Lexicon) -> str:
    """Session 46 (12s): the comma above put in (see there)."""
    if " to " not in text or re.search(r"[,;:.!?]", text):
        return text
    low = text.lower()
    for it in _names(text, lexicon):
        if not all(r.kind == "human" for r in it.refs):
            continue
        at = low.find(" " + it.text.lower() + " ")
        if at < 0:
            at = low.find(" " + it.text.lower() + "'")
        if at <= 0:
            continue
        before, after = text[:at], text[at + 1 + len(it.text) :]
        m = _PERSON_TO46S.match(after)
        if m is None or m["verb"].lower() in VERBS:
            continue
        if _names(m["rest"], lexicon) or _NEGATED42S.search(after) or _CORRECTS45S.search(after):
            continue
        words = before.split()
        if not words or words[-1].lower() in _NOT_BEFORE45S or words[-1].lower() in VERBS:
            continue
        alone = _reading(before, lexicon)
        if alone is None:
            continue
        out = f"{before}, {text[at + 1 :]}"
        if _same45s(_reading(out, lexicon), alone):
            return out
    return text


# the normaliser's first rewrites (wired into normalise._STEPS19, before the session-45 ones)
_STEPS46S_FIRST: tuple[Callable[[str, Lexicon], str], ...] = (
    _courtesy_mid46s,
    _person_to46s,
)
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-45 ones)
_STEPS46S: tuple[Callable[[str, Lexicon], str], ...] = ()
# refusals asked of the text before it is read (offline._parse, after the session-45 ones)
REFUSE46S: tuple[Callable[[str, Lexicon], None], ...] = (the_ordinal46s, first_after46s)
# checks of the whole instruction's reading (offline.parse_instruction, after the session-45 ones)
CHECK46S: tuple[Callable[[str, Node, Lexicon], None], ...] = (
    order_of_remark46s,
    then_more46s,
    order_dropped46s,
    sub_between46s,
)
