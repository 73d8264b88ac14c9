"""The normaliser's rules of sessions 10-37, part 3 of 5 (docs/grounding.md: where they live)."""

from __future__ import annotations

import itertools
from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import (
    _ADDRESS,
    _ADDRESS19,
    _CLOSING_WORDS,
    _COMMON,
    _COUNTS,
    _CUE19,
    _DO_VERBS,
    _F,
    _HESITATION,
    _INERT_WORDS,
    _INTERJECTION19,
    _KEEP_WORDS,
    _LATER24,
    _LY_HELD19,
    _MANNER,
    _NUMBER18,
    _NUMBERS15,
    _OPEN,
    _P,
    _PARTICIPLES,
    _POINTING,
    _REMARK_HELD,
    _REMARK_SUBJECT,
    _SENTENCE_HELD,
    _STRETCH,
    _THANKED,
    _X,
    _adjectives,
    _asks30s,
    _drop,
    _fits,
    _held_word,
    _idiom_stretch,
    _ids,
    _kinds,
    _name,
    _names,
    _names_nothing,
    _near_verb,
    _objects_listed,
    _objects_only,
    _one,
    _only,
    _only_kind,
    _only_person,
    _reading,
    _rx,
    _said,
    _scene_words,
    _singular,
    _sub,
    _surface_only,
    _tasks_of,
    _word_idiom,
    _word_idiom_may,
)
from hltl.grounding._normalise2 import (
    _ASKS29,
    _FREE_SPLIT26S,
    _INDIFFERENT26S,
    _MIND_MINE,
    _NOT_A_THING29S,
    _PERSON32,
    _RUN30,
    _SPEAKER_HELD,
    _SPEAKER_MORE,
    _SPEAKER_OPEN,
    _SPEAKER_OPENER,
    _SPEAKER_TIMES,
    _TRAILING34,
    _TRAILING_HELD34,
    _a_choice26s,
    _after_doing34,
    _as_for34,
    _asks_nothing29,
    _been_at34,
    _do_that34,
    _done_with34,
    _for_his34,
    _from_trade34,
    _handover_frames34,
    _has_coming34,
    _held_but_times,
    _idioms34,
    _if_spare34,
    _inert28,
    _mid_aside34,
    _mind_if34,
    _one_name,
    _opens_with_person,
    _over_and34,
    _questions34,
    _run_on_remarks34,
    _see_the34,
    _since_wanted34,
    _size_words34,
    _speaker_more_held,
    _speaker_parts34,
    _thanks_from34,
    _to_do34,
    _trade_tells34,
    _verb_last34,
    _what_like34,
    _what_waiting34,
    _where_she_is34,
)
from hltl.grounding.lexicon import (
    KIND_CATEGORIES,
    TITLES,
    VERBS,
    Lexicon,
    first_names,
)
from hltl.grounding.phrasing import starting_on
from hltl.grounding.tree import (
    Group,
    Node,
    Task,
    tasks,
)


def _free_split26s(text: str, lexicon: Lexicon) -> str:
    """'Emma and Omar, a cup each, any way round', 'Give one block to Ava and the other to Lily,
    any which way', '…, one each, …, I don't mind who gets what'; 'one of apple or chips to
    Person B, any, she does not care': a closing remark that who gets which, or which one, is
    free is taken off when what is left already reads as that choice (an 'or'). After a split
    said in full ('Alice the bottle and Bob the chips, any way round') it is kept, and refused."""
    m = _rx(rf"(?:\s*,\s*(?:{_FREE_SPLIT26S}|{_INDIFFERENT26S}))+\s*([.!]?)\s*$").search(text)
    if m is None or m.start() == 0:
        return text
    rest = text[: m.start()] + m.group(1)
    return rest if _a_choice26s(rest, lexicon) else text


_PERSON26 = r"((?:person |mr |mrs |ms |miss |dr )?[a-z]+)"
# who gets which said to be free, after two objects listed with 'and'
_ANY_WAY26 = (
    r"(?:either way round|either way around|any way round|any which way|whichever way(?: round)?|"
    r"(?:i|we) don't mind who gets (?:what|which)|(?:it )?doesn't matter who gets (?:what|which))"
)


def _one_kind_each26s(text: str, lexicon: Lexicon) -> str | None:
    """'P and Q … one K each, X or Y': the choice said plainly, or None."""
    m = _rx(
        r"^(?:give |let )?(.+?) and (.+?)(?:,| can have| could have| get| are to have| have|"
        r" are having)? (?:one|a|an) ([a-z]+) (?:each|apiece),\s*([a-z]+) or ([a-z]+)"
        rf"(?:\s*,\s*(?:{_FREE_SPLIT26S}|{_INDIFFERENT26S}))*\s*([.!]?)$"
    ).match(text.strip())
    if m is None:
        return None
    first, second = m.group(1), m.group(2)
    if len(_ids(first, lexicon, "human")) != 1 or len(_ids(second, lexicon, "human")) != 1:
        return None
    kind = m.group(3)
    a, b = f"the {m.group(4)} {kind}", f"the {m.group(5)} {kind}"
    if len(_ids(a, lexicon, "object")) != 1 or len(_ids(b, lexicon, "object")) != 1:
        return None
    if _ids(a, lexicon, "object") == _ids(b, lexicon, "object"):
        return None
    return f"Give {a} and {b} to {first} and {second}, one each{m.group(6)}"


def _one_listed_each26s(text: str, lexicon: Lexicon) -> str | None:
    """'P and Q, one (thing) each, the X and the Y, any way round': the choice said plainly, or
    None."""
    m = _rx(
        rf"^(?:give )?{_PERSON26} and {_PERSON26},?\s*(?:can have |get |each get )?"
        r"(?:one|one thing|one item|a thing|an item) (?:each|apiece),\s*"
        r"((?:the )?[a-z]+) and ((?:the )?[a-z]+),\s*" + _ANY_WAY26 + r"(?: you like)?\s*([.!]?)$"
    ).match(text)
    if m is None:
        return None
    p, q, x, y = m.group(1), m.group(2), m.group(3), m.group(4)
    who = (_one_name(p, lexicon, "human"), _one_name(q, lexicon, "human"))
    if None in who or who[0] == who[1]:
        return None
    if len(_objects_listed(f"{x} and {y}", lexicon)) != 2:
        return None
    x, y = (w if w.lower().startswith("the ") else f"the {w}" for w in (x, y))
    return f"Give {p} {x} and {q} {y}, or the other way round{m.group(5)}"


def _one_each26s(text: str, lexicon: Lexicon) -> str:
    """Two people, one object each, who gets which free (one rule, session 27, for session 26's
    two): 'Lena and Mr Novak are to have one plate apiece, white or blue', 'Alice and Bob, a mug
    each, red or blue, any way round' (one object of a kind each, the two told apart by the words
    after it joined by 'or': 'Give the X and the Y to P and Q, one each'); 'P and Q, one (thing)
    each, the X and the Y, any way round' / '…, I don't mind who gets what' (two objects listed
    with 'and': 'Give P the X and Q the Y, or the other way round'; without a word saying any way
    will do, 'one each' could be in the order said, so it is left). Read only when the grammar
    reads the result as that choice (_a_choice26s)."""
    out = _one_kind_each26s(text, lexicon) or _one_listed_each26s(text, lexicon)
    return out if out is not None and _a_choice26s(out, lexicon) else text


def _one_of_them26s(text: str, lexicon: Lexicon) -> str:
    """'Give the bottle to one of them, Person A or Person B': 'one of them' is the people named
    after it; 'Lena or Marco, whoever, give one of them the tongs': the people named before it;
    'Give one of Lena or Marco the tongs': the people named after 'one of'. Read only when the
    people are named and what is left reads as a choice between them (one rule, session 27, for
    session 26's two)."""

    def people(who: str) -> bool:
        return bool(_ids(who, lexicon)) and _ids(who, lexicon) == _ids(who, lexicon, "human")

    out = text
    m = _rx(r"\bone of them,\s*([^,.!?]+? or [^,.!?]+?)(?=\s*(?:[,.!?]|$))").search(out)
    if m is not None and people(m.group(1)):
        out = out[: m.start()] + m.group(1) + out[m.end() :]
    m = _rx(
        r"^([^,]+? or [^,]+?),\s*(?:whoever|whichever|either)(?: of them| one)?,\s*"
        r"(give|hand|pass|take|bring) one of them\b"
    ).match(out)
    if m is not None and people(m.group(1)):
        out = f"{m.group(2)} {m.group(1)}{out[m.end() :]}"
    m = _rx(rf"^(give|hand|pass) one of ({_PERSON26} or {_PERSON26}) (?=the\b)").match(out)
    if m is not None and people(m.group(2)):
        out = f"{m.group(1)} {m.group(2)} {out[m.end() :]}"
    if out == text:
        return text
    return out if _a_choice26s(out, lexicon) else text


_LISTED26S = r"(?:the )?[a-z][a-z ]*?"


def _choice_listed26s(text: str, lexicon: Lexicon) -> str:
    """'One of the two, the cup or the bottle, to Person B', 'Any of the food to Person B, the
    apple or the chips', 'Either thing will do for Person B, bottle or chips', 'One thing for
    Person B, bottle or chips': a choice opener whose objects are listed with 'or' is read as
    that list ('the two' must count the list); 'the cup or the bottle will do for Person B' (…
    for Person B). Read only when what is left reads as a choice (one rule, session 27, for
    session 26's two)."""
    opener = (
        r"(?:one|any|either) of (?:the|them|those)(?: (two|three|four|[a-z]+))?|"
        r"(?:either|any|one)(?: thing| one| item)?"
    )
    listed = rf"({_LISTED26S}(?: or {_LISTED26S})+)"
    m = _rx(rf"^({opener}),\s*{listed},\s*((?:to|for|on|onto|in|into) .+)$").match(text.strip())
    if m is not None:
        count, items, rest = m.group(2), m.group(3), m.group(4)
    else:
        m = _rx(
            rf"^({opener})(?: (?:will|would) do)? ((?:to|for) [^,]+?),\s*{listed}\s*([.!]?)$"
        ).match(text.strip())
        if m is None:
            out = _sub(r"^((?:the )?[a-z]+ or (?:the )?[a-z]+) will do for\b", r"\1 for", text)
            return out if out != text and _a_choice26s(out, lexicon) else text
        count, items, rest = m.group(2), m.group(4), m.group(3) + m.group(5)
    parts = re.split(r"\s+or\s+", items, flags=_F)
    named = [_ids(p, lexicon, "object") for p in parts]
    if any(len(n) != 1 for n in named) or len({next(iter(n)) for n in named}) != len(parts):
        return text
    need = _NUMBER18.get((count or "").lower())
    if need is not None and need != len(parts):
        return text
    out = f"{items[0].upper()}{items[1:]} {rest}"
    return out if _a_choice26s(out, lexicon) else text


def _nobody_else26s(text: str, lexicon: Lexicon) -> str:
    """'Person A, and nobody else mind, gets the bottle', 'Not to anyone else, just Person A: the
    bottle', '…, nobody else is here', '… to Alice and no one else': that no one else gets it
    says nothing more when every task goes to one person: taken off then."""
    nobody = r"(?:nobody|no one|no-one|not anyone|not to anyone|no other person)"
    out = _sub(rf"^{nobody} else,\s*(?=(?:just|only)\b)", "", text)
    out = _sub(rf",\s*(?:and |but )?{nobody} else(?: mind)?\s*,\s*", " ", out)
    out = _sub(
        rf",?\s*(?:and |but )?{nobody} else(?: mind| is here| is around| at all)?\s*(?=[.!?]|$)",
        "",
        out,
    )
    if out == text:
        return text
    node = _reading(out, lexicon, normalise=False)
    if node is None or len({t.target for t in tasks(node)}) != 1:
        return text
    if not {t.target for t in tasks(node)} <= _ids(text, lexicon, "human"):
        return text
    return out


_EXCEPT26S = r"(?:except(?: for)?|bar|but(?: not)?|apart from|other than|not)"


def _everything26s(text: str, lexicon: Lexicon) -> str:
    """Exclusions said another way: 'everything on there / you've got there / in front of you'
    (everything), 'Clear the lot onto the shelf except …' (put everything onto it), 'everything
    that isn't a box' (everything except the boxes: the plural must name every object of that
    kind), 'three of the four, the cup, the apple and the chips' (the list: the count must be the
    list's, the four the scene's objects), and the left-out object said again after its exclusion
    ('…, the cup stays', '… but not the chips, leave those'). Read only when what is left reads
    and hands over or places no object the words leave out."""
    out = _sub(
        r"\beverything (?:on there|over there|there|here|you(?:'ve| have) got(?: there| here)?|"
        r"you have(?: there| here)?|in front of you)\b",
        "everything",
        text,
    )
    out = _sub(
        r"^clear (?:the lot|everything|it all) (onto|on to|into|in|on)\b(?=.*\b"
        + _EXCEPT26S
        + r"\b)",
        r"Put everything \1",
        out,
    )

    def kind_left(m: re.Match[str]) -> str:
        kind = m.group(1).lower()
        of_kind = {o.id for o in lexicon.scene.objects if o.category == kind}
        plural = kind + ("es" if kind.endswith(("s", "x", "ch", "sh")) else "s")
        if not of_kind or _ids(f"the {plural}", lexicon, "object") != of_kind:
            return m.group(0)
        return f"everything except the {plural}"

    out = _sub(
        r"\beverything (?:that|which) (?:isn't|is not|'s not|ain't) an? ([a-z]+)\b", kind_left, out
    )

    def counted(m: re.Match[str]) -> str:
        n, of = _NUMBER18.get(m.group(1).lower()), _NUMBER18.get(m.group(2).lower())
        listed = m.group(3)
        said = _ids(listed, lexicon, "object")
        if n is None or of != len(lexicon.scene.objects) or len(said) != n:
            return m.group(0)
        if len(re.findall(r",|\band\b", listed)) != n - 1:
            return m.group(0)  # each object its own item
        return listed

    out = _sub(
        r"\b(two|three|four|five) of the (two|three|four|five|six),\s*((?:the )?[a-z ]+?"
        r"(?:,\s*(?:the )?[a-z ]+?)*,? and (?:the )?[a-z ]+?)(?=\s*(?:[,.!?]|$))",
        counted,
        out,
    )

    def left_out(before: str) -> set[str]:
        found: set[str] = set()
        for e in _rx(rf"\b{_EXCEPT26S} ((?:the )?[a-z ]+?)(?=\s*(?:[,.!?]|$|\bgoes?\b))").finditer(
            before
        ):
            found |= _ids(e.group(1), lexicon, "object")
        return found

    def said_again(m: re.Match[str]) -> str:
        left = _ids(m.group(1), lexicon, "object")
        return "" if left and left <= left_out(out[: m.start()]) else m.group(0)

    out = _sub(
        r",\s*(?:and )?(the [a-z ]+?) (?:stays?|can stay|remains?)"
        r"(?: put| here| there| where it is| behind)?(?=\s*(?:[,.!?]|$))",
        said_again,
        out,
    )
    out = _sub(
        r"(\bnot (?:the )?[a-z ]+?),\s*leave (?:those|them|that|it|these)(?: be| there| alone)?"
        r"(?=\s*(?:[,.!?]|$))",
        r"\1",
        out,
    )
    if out == text:
        return text
    node = _reading(out, lexicon, normalise=False)
    if node is not None and {t.obj for t in tasks(node)} & left_out(out):
        return text  # an object the words leave out would be handed over or placed
    return out


# session 27 (12r): idioms whose words the grammar reads as something else: 'for once' ending a
# stretch is no condition ('once') and names no one ('for'): "her hands are free for once";
# 'since first light / first thing' is a time past, no order ('first')
_IDIOMS27R = (
    (re.compile(r"\s+for once\b(?=\s*(?:[,.;!?]|$))", _F), ""),
    (re.compile(r"\bsince first (?:light|thing)\b", _F), "since dawn"),
    # "could you see the bottle gets to Person A?": see that it does, make sure ('gets to' after
    # the object; 'see the cup on the shelf' may be looking at it, and stays)
    (
        re.compile(
            r"\b((?:could|can|will|would) you|you (?:could|can|will|would)|please) see (?:to it )?"
            r"(?:that )?(?=(?:the|a|an|this|that|these|those|it|they|both|all)\b[^,.;!?]*? "
            r"(?:gets|get) (?:over |across |back )?to\b)",
            _F,
        ),
        r"\1 make sure ",
    ),
)


def _idioms27r(text: str, lexicon: Lexicon) -> str:
    for pattern, repl in _IDIOMS27R:
        text = re.sub(pattern, repl, text)  # gated (session 53, 12p)
    return text


def _both_for27r(text: str, lexicon: Lexicon) -> str:
    """Session 27 (12r): 'the cup and the apple, both for Bob' is both to Bob (one person);
    'bottle first then the apple, both for person b' is each to that person, in that order (two
    objects, then one person or, with 'on', one surface)."""
    if "both" not in text.lower():
        return text

    def ordered(m: re.Match[str]) -> str:
        first, second, prep, target = m.group(1, 2, 3, 4)
        if m["new"]:
            # session 32 (lead): "…, both to Person A, sorry, person b": the repair names whom
            # both go to (it had been applied to the second only, after the split: 12c's
            # repairs fuzz)
            target = m["new"]
        things = all(_only_kind(x, lexicon, "object") for x in (first, second))
        to = prep.lower() in ("to", "for")
        if not things or not (
            _only_person(target, lexicon) if to else _only(target, lexicon, "surface")
        ):
            return m.group(0)
        prep = "to" if to else prep
        return f"{first} {prep} {target}, then {second} {prep} {target}"

    text = _sub(
        r"^((?:the )?[\w ]+?)(?: first)?,? then (the [\w ]+?),? both (to|for|on|onto) "
        r"([\w ]+?)(?:\s*,\s*(?:(?:no|sorry|i mean|actually|oops)\s*,?\s*)+(?P<new>[\w ]+?))?"
        r"(?=\s*(?:[.!,]|$))",
        ordered,
        text,
    )

    def for_person(m: re.Match[str]) -> str:
        return f", both to {m.group(1)}" if _only_person(m.group(1), lexicon) else m.group(0)

    return _sub(r",\s*both for ([\w ]+?)(?=\s*(?:[.!?,]|$))", for_person, text)


_INCLUDED27R = re.compile(
    r",\s*(?:(?:and )?(?:the )?([\w ]+?) included|including (?:the )?([\w ]+?))(?=\s*(?:[.!]|$))",
    _F,
)


# a predicate simile in a remark: "her throat's (as) dry as dust", "he's as tired as a dog"
_SIMILE27R = re.compile(
    r"\b('s|is|are|was|were|feels|looks|seems) (?:as )?([a-z]+) as (?:a |an )?([a-z]+)\b"
    r"(?=\s*(?:[,.;!?]|$))",
    _F,
)
# 'as … as' that measures or compares what is asked ('as soon as', 'as close as you can', 'same
# as Bob'): never a simile
_NOT_SIMILE27R = frozenset(
    {
        *("well", "soon", "long", "much", "many", "far", "near", "close", "quick", "quickly"),
        *("fast", "same", "possible", "usual", "ever", "always", "before", "agreed", "planned"),
        *("requested", "asked", "said", "you", "i", "he", "she", "it", "they", "we", "me"),
        *("him", "her", "them", "us", "one", "ones", "this", "that", "these", "those", "yesterday"),
    }
)
# "Doesn't matter to me if it's Person A or Person B that ends up with the chips"
_EITHER_PERSON27R = re.compile(
    rf"^(?:(?:it )?(?:doesn't|does not|won't|will not) matter(?: to me| to us)?(?: at all)?|"
    rf"(?:i|we) (?:don't|do not) mind) (?:if|whether) it's {_P} or {_P} (?:that|who) "
    rf"(?:ends up with|gets|has|takes|receives) "
    rf"{_X}(\s*[.!]|$)",
    _F,
)


# "Noah or Zoe, whichever student's free, give them the globe"
_WHICHEVER_FREE27R = re.compile(
    rf"^{_P} or {_P},\s*(?:whichever|whoever)( [a-z]+(?: of them)?)?(?:'s| is) (?:free|nearer|"
    rf"closer|nearest|closest|available|less busy)\s*,\s*(give|hand|pass|bring|take) them "
    rf"{_X}(\s*[.!]|$)",
    _F,
)


def _whichever_free27r(m: re.Match[str], lexicon: Lexicon) -> str | None:
    """'P or Q, whichever <noun> is free, give them X': 'give X to P or Q, whichever is free'
    (two different people; the noun, if any, 'one' / 'person' / 'of them' or a name both share;
    X one name of objects), what follows kept; else None."""
    first, second, noun, verb, things, end = m.groups()
    one, two = _ids(first, lexicon, "human"), _ids(second, lexicon, "human")
    if not (_only_person(first, lexicon) and _only_person(second, lexicon)) or one == two:
        return None
    word = (noun or "").strip().lower().removesuffix(" of them").strip()
    if word and word not in ("one", "person") and not one | two <= _ids(word, lexicon, "human"):
        return None
    if not _only_kind(things, lexicon, "object"):
        return None
    # what follows the request is kept ("…, give them the globe. Oh, don't bother." is taken
    # back: session 28, a wrong reading of the take-back fuzz when it was dropped)
    return f"{verb} {things} to {first} or {second}, whichever is free{end}{m.string[m.end() :]}"


# "Can you get the medium box stacked on the pallet?": the causative 'get X done'
_GOT_DONE27R = (
    r"\bget ((?:the |both |all the |all of the )[\w ]+?) (stacked|put|placed|set|stored|moved|"
    r"taken|brought|sent|delivered|handed|passed|given) (?=(?:over |across |back )?(?:on|onto|in|"
    r"into|to)\b)"
)


def _got_done27r(m: re.Match[str], lexicon: Lexicon) -> str:
    """'get X stacked on S' is 'stack X on S', 'get X taken to P' 'take X to P' (X one name of
    objects, or 'both / all the' them)."""
    things = re.sub(r"^(?:both|all the|all of the) ", "the ", m.group(1), flags=_F)
    if not _only_kind(things, lexicon, "object"):
        return m.group(0)
    verb = {"stacked": "stack", "set": "set", "stored": "store"}.get(m.group(2).lower())
    return f"{verb or _PARTICIPLES[m.group(2).lower()]} {m.group(1)} "


# "Every box that isn't already on the pallet, put it on." / "Put every box that isn't on the
# pallet on the conveyor."
_NOT_ON27R = re.compile(
    r"^(?:(?:put|stick|pop|place|move|set) )?(?:every|each|all the|all of the|the) ([a-z]+) that "
    r"(?:isn't|aren't|is not|are not) (?:already |yet )?(?:on|in) (?:the )?([a-z ]+?)(?:,\s*"
    r"(?:put|stick|pop|place|move|set) (?:it|them)(?: (?:on|onto|in|into)(?: (?:the )?([a-z ]+?))?"
    r")?| (?:on|onto|in|into) (?:the )?([a-z ]+?))\s*([.!]?)$",
    _F,
)


def _not_on27r(m: re.Match[str], lexicon: Lexicon) -> str | None:
    """'every X that isn't (already) on S, put it on (S2)' / 'put every X that isn't on S on S2':
    the Xs of the scene that do not start on S, each put on S2 (S when none is said); None when
    the kind or a surface is not one name, or no X is left."""
    noun, where, then, onto, end = m.groups()
    kinds = {noun.lower(), _singular(noun.lower())}
    of_kind = {o.id for o in lexicon.scene.objects if o.category.lower() in kinds}
    surface = _ids(where, lexicon, "surface")
    target = _ids(then or onto or where, lexicon, "surface")
    if not of_kind or len(surface) != 1 or len(target) != 1:
        return None
    if not (_only(where, lexicon, "surface") and _only(then or onto or where, lexicon, "surface")):
        return None
    on = set(starting_on(of_kind, next(iter(surface)), lexicon))
    left = [f"the {_said(o.id, lexicon)}" for o in lexicon.scene.objects if o.id in of_kind - on]
    if not left:
        return None
    things = left[0] if len(left) == 1 else f"{', '.join(left[:-1])} and {left[-1]}"
    surface_name = (then or onto or where).strip()
    return f"put {things} on the {surface_name.removeprefix('the ')}{end}"


def _all_for27r(text: str, lexicon: Lexicon) -> str:
    """'Teddy to Lily. Then the bib. Then the sippy cup, all for Lily.': 'all for / to P' closing
    the instruction gives every object named to P; taken only when no other person and no
    surface is named, two objects at least are, and what is left with 'for P' reads as each of
    them handed to P."""
    m = re.search(r",\s*all (?:of them |of it )?(?:for|to) ([\w ]+?)\s*([.!]?)$", text, _F)
    if m is None or not _only_person(m.group(1), lexicon):
        return text
    who = _ids(m.group(1), lexicon, "human")
    said = _names(text, lexicon)
    if any(
        r.kind == "surface" or (r.kind == "human" and r.id not in who)
        for it in said
        for r in it.refs
    ):
        return text
    objs = _ids(text, lexicon, "object")
    if len(objs) < 2:
        return text
    out = f"{text[: m.start()]}, for {m.group(1)}{m.group(2)}"
    moved = _tasks_of(out, lexicon)
    if moved is None or moved != {("deliver", o, next(iter(who))) for o in objs}:
        return text
    return out


def _alongside27r(text: str, lexicon: Lexicon) -> str:
    """'Small box onto the pallet, and the medium one alongside it': next to what was put on the
    one surface named before, so on that surface (no person named anywhere: 'next to it' after
    a hand-over says no place)."""
    m = re.search(r"\b(?:alongside|next to|beside) (?:it|them)(?=\s*(?:[,.;!?]|$))", text, _F)
    if m is None or _ids(text, lexicon, "human"):
        return text
    before = text[: m.start()]
    said = [it for it in _names(before, lexicon) if it.refs[0].kind == "surface"]
    if len({r.id for it in said for r in it.refs}) != 1:
        return text
    if not re.search(rf"\b(?:on|onto|in|into) (?:the )?{re.escape(said[-1].text)}\b", before, _F):
        return text
    return f"{before}on the {said[-1].text}{text[m.end() :]}"


def _said_aside27r(text: str, lexicon: Lexicon) -> str:
    """Session 27 (12r), what is said around a request that asks for nothing more:

    - a predicate simile ('her throat's dry as dust', 'he's as tired as a dog'): the comparison
      is taken off ("her throat's dry"), the noun compared to naming nothing in the scene and
      neither word one that measures or compares ('as soon as', 'as close as you can', 'same as
      Bob');
    - the speaker's indifference between two people: "Doesn't matter to me if it's P or Q that
      ends up with X", "I don't mind whether it's P or Q who gets X" is 'X to P or Q' (two
      people, X objects only; what follows kept, session 28);
    - 'X, them / it too' right after 'and' or a sentence's start says X again: 'X too' (X one
      name of objects);
    - 'and Y alongside / next to / beside it' after a placement on one surface (_alongside27r);
    - 'P or Q, whichever <noun> is free, give them X' (_whichever_free27r);
    - the causative 'get X stacked on S' (_got_done27r);
    - a deadline 'before the driver's / she's / he gets back': acting now meets it (someone
      coming back, never an object);
    - 'X, then Y, all for P' (_all_for27r);
    - 'every X that isn't (already) on S, put it on' (_not_on27r): the Xs not starting on S."""
    low = text.lower()
    if " as " in low:

        def simile(m: re.Match[str]) -> str:
            adj, noun = m.group(2).lower(), m.group(3).lower()
            if adj in _NOT_SIMILE27R or noun in _NOT_SIMILE27R:
                return m.group(0)
            if lexicon.lookup(noun) is not None or not _names_nothing(m.group(0), lexicon):
                return m.group(0)
            return f"{m.group(1)} {m.group(2)}"

        text = _SIMILE27R.sub(simile, text)
    if "matter" in low or "mind" in low:
        m = _EITHER_PERSON27R.match(text)
        if (
            m is not None
            and _only_person(m.group(1), lexicon)
            and _only_person(m.group(2), lexicon)
            and _ids(m.group(1), lexicon) != _ids(m.group(2), lexicon)
            and _only_kind(m.group(3), lexicon, "object")
        ):
            text = f"{m.group(3)} to {m.group(1)} or {m.group(2)}{m.group(4)}{text[m.end() :]}"
    if "whichever" in low or "whoever" in low:
        m = _WHICHEVER_FREE27R.match(text)
        if m is not None:
            text = _whichever_free27r(m, lexicon) or text
    if "that is" in low or "that are" in low or "that isn't" in low or "that aren't" in low:
        m = _NOT_ON27R.match(text)
        if m is not None:
            text = _not_on27r(m, lexicon) or text
    if " back" in low and "before" in low:

        def deadline(m: re.Match[str]) -> str:
            said = _ids(m.group(1), lexicon)
            if said - _ids(m.group(1), lexicon, "human"):
                return m.group(0)  # "before the cup's back": an object, a task of its own
            return ""

        text = _sub(
            r"\s+before (?:the |my |our |his |her |their )?([\w]+(?: [\w]+)?)(?:'s| is| are|'re|"
            r" gets| get| comes| come) back(?=\s*(?:[.!?,]|$))",
            deadline,
            text,
        )
    if "all " in low:
        text = _all_for27r(text, lexicon)
    if re.search(r"\b(?:get|got)\b", low):
        text = _sub(_GOT_DONE27R, lambda m: _got_done27r(m, lexicon), text)
    if re.search(r"\b(?:alongside|next to|beside)\b", low):
        text = _alongside27r(text, lexicon)
    if " too" in low or " as well" in low:

        def again(m: re.Match[str]) -> str:
            if not _only_kind(m.group(2), lexicon, "object"):
                return m.group(0)
            return f"{m.group(1)}{m.group(2)} {m.group(3)}"

        text = _sub(
            r"(^|(?<=[.!?])\s+|\band )((?:the )?[\w ]+?),\s*(?:them|it) (too|as well)\b",
            again,
            text,
        )
    return text


def _all_of27r(text: str, lexicon: Lexicon) -> str:
    """Session 27 (12r): 'all three of the boxes' is 'the three boxes' (the count still checked
    against the scene). Last of the rewrites: 'All three of the pens, black, blue and red, …' is
    read by session 19's counts first."""
    return _sub(
        r"\ball (two|three|four|five|six|seven|eight|nine|ten|\d+) of the\b", r"the \1", text
    )


def _included27r(text: str, lexicon: Lexicon) -> str:
    """Session 27 (12r): '…, the big one included' / '…, including the big box' says again that
    an object the request moves is among them: taken off only when what is left, read alone,
    already moves exactly that object (one object, by name or as 'the <word> one' of a kind the
    request moves); 'all three of the boxes' before it is 'the three boxes'."""
    m = _INCLUDED27R.search(text) if "includ" in text.lower() else None
    if m is None:
        return text
    text = _all_of27r(text, lexicon)
    m = _INCLUDED27R.search(text)
    if m is None:
        return text
    rest = text[: m.start()] + text[m.end() :]
    moved = _tasks_of(rest, lexicon)
    if not moved:
        return text
    objs = {obj for _, obj, _ in moved}
    said = (m.group(1) or m.group(2)).strip()
    if said.lower().endswith(" one"):
        kinds = {o.category for o in lexicon.scene.objects if o.id in objs}
        word = said[: -len(" one")]
        named = {i for c in kinds for i in _ids(f"{word} {c}", lexicon, "object")}
    elif _only_kind(said, lexicon, "object"):
        named = _ids(said, lexicon, "object")
    else:
        return text
    return rest if len(named) == 1 and named <= objs else text


def _that_there27r(text: str, lexicon: Lexicon) -> str:
    """Session 27 (12r): 'That bottle there, Person A needs it …': a sentence opening on 'that /
    this X there / here' and a comma points at X; 'there' names no place (one object only)."""

    def pointed(m: re.Match[str]) -> str:
        if not _only_kind(m.group(3), lexicon, "object"):
            return m.group(0)
        return f"{m.group(1)}{m.group(2)} {m.group(3)},"

    return _sub(
        r"(^|(?<=[.!?])\s+)(that|this) ([\w ]+?) (?:right )?(?:there|here)\s*,",
        pointed,
        text,
    )


# -- session 28 (engineer 12r): blind26's choices, counts, exclusions and corrections ------------


# a statement of why, said between a correction's cue and the corrected words ("…, no wait, Bob's
# got one, to Alice", "…, scratch that, she's fasting, chips to Person B", "…, sorry, my head's in
# the ropewalk, I mean the counter"): a subject, a form of 'be' / 'have', and words of no request
_CUE_REASON28R = re.compile(rf"(?<=,)\s*(?:{_CUE19})\s*,\s*(?P<why>[^,.;:!?]+?)\s*,\s*(?=\S)", _F)
_STATEMENT28R = re.compile(
    r"(?:he|she|they|it|there|i|we|(?:my|his|her|their|our|the) [a-z]+|[a-z]+(?: [a-z]+)?)"
    r"(?:'s|'re|'m|'ve| is| are| was| were| has| have| had| am)(?: [a-z']+)+",
    _F,
)
# what a reason may not hold: it could ask, negate, add, choose, order or point at a person after
_NOT_REASON28R = re.compile(
    r"\b(?:not|no|never|n't|too|also|instead|either|or|then|first|before|after|once|when|if|"
    r"give|hand|pass|bring|take|put|place|wants?|needs?|would|could|should|will|can)\b|n't\b",
    _F,
)
_PRONOUN28R = re.compile(r"\b(?:he|she|him|her|they|them|his|their)\b", _F)


# "it's Person A", "that was Bob": who it is, said after a correction's cue (_cue_reason28r)
_IT_IS_WHO31 = re.compile(r"(?:it|that)(?:'s| is| was) ", _F)
# "Bob's the thirsty one", "Lena is the one": who it is, said of a person (session 54, 12r)
_THE_ONE_WHO54R = re.compile(r".+?(?:'s| is) the (?:[a-z]+ )?one\b", _F)


# a 'reason' that says where the thing goes ("it's meant to go on the shelf", "it belongs in the
# locker", "that lives on the rack"): a correction to a place, not a reason (session 43, lead)
_PLACED_WHY43L = re.compile(
    r"\b(?:(?:meant|supposed|has|needs|ought|got) to (?:go|be|live|sit|stay)|should (?:go|be|"
    r"live|sit|stay)|goes|belongs|lives|sits|stays|go|belong)\b(?: back)?(?: up| down| away)?"
    r"\s+(?:on|in|onto|into|on top of|under)\b",
    _F,
)


def _cue_reason28r(text: str, lexicon: Lexicon) -> str:
    """Session 28 (12r): a reason stated between a correction's cue and the corrected words
    ("Give the bottle to Bob, no wait, Bob's got one, to Alice") says why, and is taken off, so
    the cue corrects as it does without it. Only a statement (a subject, then 'is' / 'has' / …),
    naming no object of the scene, holding no word that asks, negates, adds, chooses or orders;
    never when the corrected words hold a pronoun the reason could have given its person ("…,
    no, sorry, there's only Person A here, to her then" stays refused)."""
    m = _CUE_REASON28R.search(text)
    if m is None:
        return text
    why, after = m.group("why"), text[m.end() :]
    if not _STATEMENT28R.fullmatch(why) or _NOT_REASON28R.search(why):
        return text
    if _ids(why, lexicon, "object") or _PRONOUN28R.search(after):
        return text
    if _PLACED_WHY43L.search(why) and _ids(why, lexicon, "surface"):
        return text  # where the thing goes, not a reason (session 43, as _cue_reason29r)
    said_who = _IT_IS_WHO31.match(why) or _THE_ONE_WHO54R.match(why)
    if (re.search(r"\bfor\b", why, _F) or said_who) and _ids(why, lexicon, "human"):
        # "…. Sorry, my mistake, it's for Tom, no wait, the gloves": whom it is for is the
        # correction itself, no reason (session 30, engineer 12: the wrappers fuzz had read the
        # gloves to the person before); so is "…, whoops, it's Person A, no wait, the chips"
        # (session 31, engineer 12: the wrappers fuzz on blind29 had read the chips to Person B);
        # so is "…, no wait, Bob's the thirsty one, scratch that, the apple" (session 54, 12r:
        # 12c's wrappers fuzz had read the apple to Alice)
        return text
    return text[: m.start("why")] + after


# "Torch to Kofi, not Kofi, Jess": the name just said, said again after 'not', then another
_NOT_THAT28R = re.compile(
    r"(?P<said>\b[\w ]+?)\s*,\s*not (?:to |on |the )?(?P<x>[\w ]+?)\s*,\s*(?=(?:to |on |the )?"
    r"(?P<y>[\w ]+?)\s*(?:[,.!?]|$))",
    _F,
)


def _not_that28r(text: str, lexicon: Lexicon) -> str:
    """Session 28 (12r): ', not X, Y' right after X was named ("Torch to Kofi, not Kofi, Jess")
    takes X back and says Y instead: the grammar's ', no, Y'. X must name exactly what the words
    before it end on (the same one entity), Y one entity of the same kind, another one; else it
    is left ('…, not Kofi, the drill' is no such correction, and stays refused)."""
    if "not " not in text.lower():
        return text

    def corrected(m: re.Match[str]) -> str:
        said, x, y = m.group("said"), m.group("x"), m.group("y")
        ends, xn, yn = _names(said, lexicon), _names(x, lexicon), _names(y, lexicon)
        if not ends or len(xn) != 1 or len(yn) != 1:
            return m.group(0)
        if not all(
            re.fullmatch(rf"(?:the )?{re.escape(n[0].text)}", w.strip(), _F)
            for n, w in ((xn, x), (yn, y))
        ):
            return m.group(0)  # "…, not Kofi, Jess too": more than the name
        last, xs, ys = _ids(ends[-1].text, lexicon), _ids(x, lexicon), _ids(y, lexicon)
        if len(xs) != 1 or xs != last or len(ys) != 1 or ys == xs:
            return m.group(0)
        kind = {r.kind for it in _names(x, lexicon) for r in it.refs}
        if kind != {r.kind for it in _names(y, lexicon) for r in it.refs}:
            return m.group(0)
        if not said.lower().rstrip().endswith(ends[-1].text.lower()):
            return m.group(0)
        return f"{said}, no, "

    return _NOT_THAT28R.sub(corrected, text, count=1)


# "Person A gets whatever isn't the chips", "Everything that isn't the apple …"
_WHATEVER_NOT28R = re.compile(
    r"\b(?:whatever|everything (?:that|which)|anything (?:that|which)|all that) (?:isn't|is not|"
    r"'s not|ain't) ((?:the )?[a-z]+(?: [a-z]+)??(?:(?:,| and| or) (?:the )?[a-z]+(?: [a-z]+)??)*?)"
    r"(?=\s*(?:[,.;!?]|$|\b(?:goes|go|to|for|on|onto|in|into)\b))",
    _F,
)


def _whatever_not28r(text: str, lexicon: Lexicon) -> str:
    """Session 28 (12r): 'whatever / everything that / anything that isn't X' is everything
    except X, when X names objects of the scene and nothing else (each of its items an object by
    name: 'whatever isn't the chips'); a kind ('everything that isn't a box') is session 26's
    (_everything26s), a place or a person ('whatever isn't on the shelf') is left."""
    if "whatever" not in text.lower() and "that is" not in text.lower() and "n't" not in text:
        return text

    def others(m: re.Match[str]) -> str:
        items = re.split(r",|\band\b|\bor\b", m.group(1), flags=_F)
        if not all(_only_kind(i.strip(), lexicon, "object") for i in items if i.strip()):
            return m.group(0)
        return f"everything except {m.group(1)}"

    return _WHATEVER_NOT28R.sub(others, text)


# "Apart from the cups and the bowl, all of it goes onto the tray": the exclusion said first
_FRONTED_EXCEPT28R = re.compile(
    r"^(?P<open>(?:except(?: for)?|apart from|other than|bar|but for|aside from) "
    r"(?P<x>[^,.;:!?]+?))\s*,\s*(?P<rest>[^.;:!?]+)(?P<end>[.;:!?]*\s*)$",
    _F,
)
_EVERY28R = re.compile(
    r"\b(?:everything(?: else)?|all of it|all of them|all the rest|the lot|all the stuff|"
    r"all the things)\b",
    _F,
)


def _fronted_except28r(text: str, lexicon: Lexicon) -> str:
    """Session 28 (12r): 'Apart from / Except (for) / Other than / Bar X, <clause>' whose clause
    holds one word for everything ('everything', 'all of it', 'the lot', …) is that clause with
    'except X' after the word: "Apart from the cups and the bowl, all of it goes onto the tray".
    X must name objects only; a clause with no such word, or two, is left (refused as before:
    the exclusion leaves out from nothing)."""
    m = _FRONTED_EXCEPT28R.match(text)
    if m is None:
        return text
    x, rest = m.group("x"), m.group("rest")
    items = re.split(r",|\band\b", x, flags=_F)
    if not all(_only_kind(i.strip(), lexicon, "object") for i in items if i.strip()):
        return text
    every = list(_EVERY28R.finditer(rest))
    if len(every) != 1:
        return text
    e = every[0]
    out = f"{rest[: e.end()]} except {x}{rest[e.end() :]}"
    return out[:1].upper() + out[1:] + m.group("end")


# "…, all three bits, …" after the objects: how many they are, said again
_COUNT_AGAIN28R = re.compile(
    r"\s*,\s*(?:that's |that is |so )?all (?P<n>two|three|four|five|six) (?:bits|things|items|"
    r"pieces|objects|of them|of those)\s*,\s*",
    _F,
)


def _count_again28r(text: str, lexicon: Lexicon) -> str:
    """Session 28 (12r): '…, all three bits, …' between the objects and where they go says how
    many they are again ("Everything that isn't the apple, all three bits, over to Person B"):
    taken off when what is left reads and moves exactly that many objects; another count is left
    (refused: the speaker counts other objects than the words name)."""
    m = _COUNT_AGAIN28R.search(text) if "all " in text.lower() else None
    if m is None:
        return text
    rest = f"{text[: m.start()]} {text[m.end() :]}"
    moved = _tasks_of(rest, lexicon)
    if not moved or len({obj for _, obj, _ in moved}) != _NUMBER18[m.group("n").lower()]:
        return text
    return rest


# "… over to Person B for the actuary's tally": what it is for, someone else's
_PURPOSE_OF28R = re.compile(
    r"(?<!\bready)\s+for (?:the|a|an) (?P<who>[a-z]+)'s (?P<what>[a-z]+(?: [a-z]+)?)"
    r"(?=\s*(?:[.,;!?]|$))",
    _F,
)


def _purpose_of28r(text: str, lexicon: Lexicon) -> str:
    """Session 28 (12r): 'for the actuary's tally' closing a clause is what the task is for, as
    session 10's 'for the meeting' (_purpose), with a possessor: taken off when neither word names
    anything in the scene nor counts, chooses or points back ('for the patient's lunch' with a
    patient in the scene, or 'for the other one's tea', stays)."""
    if "'s " not in text:
        return text
    return _PURPOSE_OF28R.sub(
        lambda m: (
            ""
            if _names_nothing(f"{m.group('who')} {m.group('what')}", lexicon)
            and not _KEEP_WORDS.search(f"{m.group('who')} {m.group('what')}")
            else m.group(0)
        ),
        text,
    )


# "All of it to Person A, apart from the apple, which Person B gets.": where the left-out one goes
_WHICH_GETS28R = re.compile(
    r"(?P<ex>\b(?:apart from|except(?: for)?|but not|other than|bar) (?P<x>(?:the )?[a-z]+"
    r"(?: [a-z]+)?)),\s*(?:which|that) (?P<p>[\w ]+?) (?:gets|can have|is to get|will get|'ll get|"
    r"should get|can take|has)(?=\s*(?:[.!;]|$))",
    _F,
)


def _which_gets28r(text: str, lexicon: Lexicon) -> str:
    """Session 28 (12r): '…, apart from X, which P gets' says where the object left out goes:
    '…, apart from X, and X to P' (X one name of objects, P one person of the scene; the
    exclusion itself still has to leave X out of what goes before)."""
    if "which" not in text.lower() and "that" not in text.lower():
        return text

    def goes(m: re.Match[str]) -> str:
        x, who = m.group("x"), m.group("p")
        if not _only_kind(x, lexicon, "object") or not _only_person(who, lexicon):
            return m.group(0)
        return f"{m.group('ex')}, and {x} to {who}"

    return _WHICH_GETS28R.sub(goes, text)


# "…, whoever's nearest", "…, whichever's easier": how the choice just said is to be made
_WHO_CHOOSES28R = re.compile(
    r"\s*,\s*(?P<w>whoever|whichever)(?:'s| is) (?:nearer|closer|nearest|closest|free|handier|"
    r"handiest|quicker|quickest|easier|easiest|easiest to reach|nearer to you|closer to you|"
    r"nearest to you|closest to you|to hand|"
    # session 33 (12s): "… closer to your hand" before more words (blind22; "whichever's closer
    # to hand" closing the text is 12r's _FREE_CHOICE33R)
    r"(?:nearer|closer|nearest|closest) to your hand)(?=\s*(?:[,.!?]|$))",
    _F,
)


# "Person A will take whichever's easier, chips or apple": said before the choice it makes
_WHICH_FIRST28R = re.compile(
    r"\b(?P<w>whichever)(?:'s| is) (?:nearer|closer|nearest|closest|handier|handiest|quicker|"
    r"quickest|easier|easiest|easiest to reach|to hand)\s*,\s*(?=(?:the )?[a-z]+ or (?:the )?[a-z]+"
    r"\b)",
    _F,
)


def _one_choice28r(node: Node | None, who: bool) -> bool:
    """Whether ``node`` is one choice: an 'or' of single tasks, each another person (``who``) or
    another object (else) for the one object or person they share."""
    if not isinstance(node, Group) or node.op != "or":
        return False
    if not all(isinstance(c, Task) for c in node.children):
        return False
    objs = {t.obj for t in tasks(node)}
    targets = {t.target for t in tasks(node)}
    n = len(node.children)
    return (len(objs), len(targets)) == ((1, n) if who else (n, 1))


def _who_chooses28r(text: str, lexicon: Lexicon) -> str:
    """Session 28 (12r): '…, whoever's nearest' after a choice of people for one object ("Either
    Person A or Person B can have the bottle, whoever's nearest"), '…, whichever's easier' after a
    choice of objects for one person, wherever it stands: how the robots choose, taken off when
    what is left reads as exactly such a choice ('whoever' after 'Give Bob the cup' or after a
    choice of objects, 'whichever' after a choice of people: left, and refused)."""
    m = _WHO_CHOOSES28R.search(text) if "ever" in text.lower() else None
    if m is None:
        m = _WHICH_FIRST28R.search(text) if "whichever" in text.lower() else None
        if m is None:
            return text
    out = text[: m.start()] + text[m.end() :]
    who = m.group("w").lower() == "whoever"
    return out if _one_choice28r(_reading(out, lexicon), who) else text


# "…, they're both shattered from the usher shift", "They're both notaries on a break, so …"
_BOTH_REMARK28R = re.compile(
    r"(?:(?<=^)|\s*[,.;]\s*)they(?:'re| are) both (?P<said>[a-z][a-z' -]*?)(?:\s*,\s*so\b\s*|"
    r"(?=\s*(?:[,.;!?]|$)))",
    _F,
)


def _both_remark28r(text: str, lexicon: Lexicon) -> str:
    """Session 28 (12r): "they're both <state>" said of the people a request names ("Either
    Person A or Person B can have the bottle, they're both shattered from the usher shift",
    "They're both notaries on a break, so …") is a remark, taken off as session 10's remarks
    are: only when its words name nothing in the scene and hold no word that counts, chooses,
    negates, orders or points back, and the rest names two people at least."""
    if "both" not in text.lower():
        return text
    m = _BOTH_REMARK28R.search(text)
    if m is None or not _names_nothing(m.group("said"), lexicon):
        return text
    if _KEEP_WORDS.search(m.group("said")):
        return text
    rest = (
        text[: m.start()]
        + ("." if m.start() > 0 and "so" not in m.group(0) else "")
        + " "
        + text[m.end() :]
    ).strip()
    rest = re.sub(r"^[,.;\s]+", "", rest)
    if len(_ids(rest, lexicon, "human")) < 2:
        return text
    return rest[:1].upper() + rest[1:]


# a header saying each person gets one thing, before the list that says which
_EACH_ONE28R = re.compile(
    r"^(?:(?:so|now|right),? )?(?:(?:hand|give|share|dish) out )?(?:one (?:thing|item)|a thing) "
    r"(?:each|apiece)\s*[:,-]\s*|^both of (?:them|you) (?:need|want|get|are after) (?:something|"
    r"a thing|one thing)(?: each)?\s*,\s*so\s+",
    _F,
)


def _either_title28r(text: str, lexicon: Lexicon) -> str:
    """Session 28 (12r): 'either student' / 'either of the students', where exactly two people of
    the scene are called 'student' and the text names no other person, is 'Noah or Zoe' ("The
    scissors can go to either student, whoever's closest"); 'any one of the plates to / for …' is
    'one of the plates …' (one, any)."""
    low = text.lower()
    if "any one of the" in low:
        # only before a recipient: "Any one of the pens in the box" may say where they are
        text = _sub(r"\bany one of the ([a-z]+) (?=(?:to|for) )", r"one of the \1 ", text)
    if "either" not in low:
        return text

    def two(m: re.Match[str]) -> str:
        word = m.group(1).lower()
        people = [h for h in lexicon.scene.humans if word in (a.lower() for a in h.aliases)]
        if len(people) != 2:
            return m.group(0)
        if _ids(m.string[: m.start()] + m.string[m.end() :], lexicon, "human"):
            return m.group(0)  # "Either of the patients …, Mr Lee or Ruth": who is said apart
        return " or ".join(_name(h.id, lexicon) for h in people)

    return _sub(r"\beither (?:one of the |of the )?([a-z]+?)s?\b(?!')", two, text)


# "… put them in Person A's hands", "the bottle goes straight into Person A's hand": to that person
_IN_HAND28R = re.compile(
    r"\b(?:(?:straight|right) )?(?:in|into|in to) ([A-Za-z][\w ]*?)'s (?:own )?hands?\b", _F
)
_PUT_VERB28R = re.compile(
    r"\b(?:put|puts|place|places|pop|pops|stick|sticks|set|sets|drop|drops)\b(?=[^,.;!?]*$)", _F
)


def _in_hand28r(text: str, lexicon: Lexicon) -> str:
    """Session 28 (12r): '(straight) in / into P's hand(s)' is 'to P' (P one person of the
    scene); a verb of putting before it in its clause ('put them in Person A's hands') becomes
    'hand', since the object goes to the person, on no surface."""
    if "hand" not in text.lower():
        return text

    def to(m: re.Match[str]) -> str:
        if not _only_person(m.group(1), lexicon):
            return m.group(0)
        return f"to {m.group(1)}"

    out, start = [], 0
    for m in _IN_HAND28R.finditer(text):
        said = to(m)
        if said == m.group(0):
            continue
        before = text[start : m.start()]
        out.append(_PUT_VERB28R.sub("hand", before) + said)
        start = m.end()
    return "".join(out) + text[start:] if out else text


def _the_one_for28r(text: str, lexicon: Lexicon) -> str:
    """Session 28 (12r): "P's the one for X", 'P is the one getting X' is 'P gets X', as session
    27's "P's the one who wants X" (P one person, X one name of objects; a question, a negation
    or two people stay as they were)."""
    if "the one" not in text.lower():
        return text

    def gets(m: re.Match[str]) -> str:
        who, what = m.group(2), m.group(3)
        if not _only_person(who, lexicon) or not _only_kind(what, lexicon, "object"):
            return m.group(0)
        return f"{m.group(1)}{who} gets {what}"

    return _sub(
        rf"{_OPEN}{_P}(?:'s| is) the (?:one|person) (?:for|getting|receiving|to get) "
        r"((?:the |a |an )?[\w ]+?)(?=\s*(?:[,.;!?]|$))",
        gets,
        text,
    )


# 'Not P, …' / 'Not P ah, …' / "Not P, she's had one; …" opening: P is not the one
_NOT_PERSON28R = re.compile(
    r"^not (?P<p>[A-Za-z][\w ]*?)(?: ah| mind| though)?\s*[,;:.]\s*(?:(?P<why>(?:she|he|they)"
    r"(?:'s|'ve|'re| has| have| is| are| was) [^,;.!?]+?)\s*[,;.]\s*)?(?P<rest>\S.*)$",
    _F,
)
# a command opening what follows 'Not P,': 'Not P' may be said to the hearer (session 12)
_COMMAND28R = re.compile(
    r"(?:please |just |and |so )*(?:give|hand|pass|bring|take|put|place|send|get|fetch|deliver|"
    r"carry|move|pop|stick|chuck|leave|set)\b",
    _F,
)
# "No need to put it anywhere, just …", "Don't put it down anywhere, just …"
_NOWHERE28R = re.compile(
    r"^(?:no need to|(?:you )?(?:don't|do not|needn't|need not)(?: need to)?) (?:put|place|set) "
    r"(?:it|that) (?:down )?anywhere\s*[,;:.]\s*(?P<rest>\S.*)$",
    _F,
)
# "Not on the floor, mind, …": a place the scene has no surface for
_NOT_ON28R = re.compile(
    r"^not (?:on|onto|in|into) (?:the |a )?(?P<where>[a-z]+(?: [a-z]+)?)(?:,? mind)?\s*[,;:.]\s*"
    r"(?P<rest>\S.*)$",
    _F,
)


def _not_first28r(text: str, lexicon: Lexicon) -> str:
    """Session 28 (12r): what is not to be done, said first, then the request:
    - 'Not P, …' (or 'Not P ah, …', "Not P, she's had one; …"): P gets nothing, and the request
      after it, a statement (not a command: 'Not Bob, give Alice the cup' may be said to the
      hearer), gives one other person everything ("Not Person A, she's had one; it's Person B
      that gets the cup");
    - 'No need to put it anywhere, just …' / "Don't put it down anywhere, …": nowhere in
      particular, so the request after it places nothing;
    - 'Not on the floor, mind, …': a place the scene has no surface for, and the request after
      it places nothing there.
    Each is taken off only when the request after it reads by itself and keeps what was said
    first (a request that gives P something, or places something, stays refused); a reason after
    'Not P' must be a statement naming no object, with no word that negates, adds or asks."""
    low = text.lower()
    if not low.startswith(("not ", "no need", "don't", "do not", "you don't", "needn't")):
        return text
    m = _NOT_PERSON28R.match(text)
    if m is not None and _only_person(m.group("p"), lexicon):
        why = m.group("why")
        if why is not None and (_NOT_REASON28R.search(why) or _ids(why, lexicon, "object")):
            return text
        rest = m.group("rest")
        if _COMMAND28R.match(rest):
            return text  # "Not Bob, give Alice the cup": said to the hearer? (session 12)
        said = _tasks_of(rest, lexicon)
        targets = {t for _, _, t in said or ()}
        if len(targets) == 1 and not targets & _ids(m.group("p"), lexicon):
            return rest[:1].upper() + rest[1:]
        return text  # "Not Alice, Carol and Bob get a mug each": 'not' which? (session 21)
    for rx in (_NOWHERE28R, _NOT_ON28R):
        m = rx.match(text)
        if m is None:
            continue
        if rx is _NOT_ON28R and not _names_nothing(m.group("where"), lexicon):
            return text
        rest = m.group("rest")
        said = _tasks_of(rest, lexicon)
        if said and all(kind == "deliver" for kind, _, _ in said):
            return rest[:1].upper() + rest[1:]
    return text


# remarks said around a request that the session's earlier remark rules do not take: "…, the poor
# thing's shivering", "…, they need a rinse", "…, the notary wants blue ink", "The auditor's gone,
# so …"
_REMARKS28R = (
    re.compile(
        r"\s*,\s*(?:and )?the poor (?:thing|dear|love|soul|lamb|mite|lad|lass)(?:'s| is| has) "
        r"(?P<said>[a-z][a-z' ]*?)(?=\s*[.!]?\s*$)",
        _F,
    ),
    re.compile(
        r"\s*,\s*(?:and )?(?P<who>they|it|the [a-z]+)(?:'s| is)? (?:needs?|wants?|could "
        r"(?:do with|use)) (?P<said>(?:a |an |some )?[a-z][a-z' ]*?)(?=\s*[.!]?\s*$)",
        _F,
    ),
    re.compile(
        r"^(?P<who>(?:the|my|our) [a-z]+)(?:'s| is| has) (?P<said>gone|left|arrived|finished|off|"
        r"here|done)(?: (?:now|home|for the day|already))?,? so\s+",
        _F,
    ),
)


def _remarks28r(text: str, lexicon: Lexicon) -> str:
    """Session 28 (12r): a remark after the request about its person ("Both blankets to Mrs
    Khan, the poor thing's shivering"), about its objects or someone not in the scene wanting
    something the scene does not have ("The two cups in the sink, they need a rinse", "…, the
    notary wants blue ink"), or before it, 'The auditor's gone, so …': taken off when its words
    (and its subject) name nothing in the scene and hold no word that counts, chooses, negates,
    orders or points back; the request must read without it."""
    out = text
    for rx in _REMARKS28R:
        m = re.search(rx, out)  # gated (session 53, 12p)
        if m is None:
            continue
        said = m.group("said")
        who = m.groupdict().get("who") or ""
        if who.lower() not in ("they", "it") and not _names_nothing(who or "x", lexicon):
            continue
        if not _names_nothing(said, lexicon) or _KEEP_WORDS.search(said):
            continue
        rest = out[: m.start()] + out[m.end() :]
        if _tasks_of(rest, lexicon):
            out = rest[:1].upper() + rest[1:]
    return out


# "The single packet of crisps to Person B": what holds the one object, and 'single' for 'only'
_PACKET28R = re.compile(
    r"\b(?:(?P<det>the|a|an|one|that|this) )?(?:(?:single|one|only) )?(?P<box>packet|bag|pack|tin|"
    r"carton|punnet|jar|box) of (?:the )?(?P<x>[a-z]+(?: [a-z]+)?)\b",
    _F,
)


def _single28r(text: str, lexicon: Lexicon) -> str:
    """Session 28 (12r): 'the single X' is 'the only X' (the X, when the scene has one: session
    19's rule checks it); 'a / the (single) packet / bag / tin of X' is 'the X' when X names one
    object of the scene and the holder's word names nothing there (a box of a scene with boxes,
    or 'tin of screws' said as the scene says it, is left as it is)."""
    low = text.lower()
    if "single" in low:
        text = _sub(r"\bthe single (?=[a-z])", "the only ", text)
    if " of " not in low:
        return text

    def held(m: re.Match[str]) -> str:
        x = m.group("x")
        if lexicon.lookup(f"{m.group('box')} of {x}".lower()) is not None:
            return m.group(0)
        if _ids(m.group("box"), lexicon):
            return m.group(0)
        for n in (2, 1):
            said = " ".join(x.split()[:n])
            one = len(_ids(said, lexicon, "object")) == 1
            if len(x.split()) >= n and one and _only_kind(said, lexicon, "object"):
                return f"the {said}{x[len(said) :]}"
        return m.group(0)

    return _PACKET28R.sub(held, text)


# -- session 27 (engineer 12s): other languages' orders; a description and the list it is ------


# where a placement's surface keeps the object, said after the surface ("… up on the shelf, out
# of the dog's reach", "… on the shelf out of reach and …"): why, not where
_OUT_OF_REACH27 = re.compile(
    r"(?:\s*,\s*|\s+)(?:well |safely |right )?out of (?:reach(?: of (?:the |a |an |his |her |"
    r"their |our |my |your )?[a-z]+)?|harm's way|(?:the |his |her |their |our |my |your )?"
    r"(?:[a-z]+(?:'s|s'|') )?(?:reach|way))(?=\s*(?:[,.;!?]|$|and\b|then\b))",
    _F,
)


def _out_of_reach27(text: str, lexicon: Lexicon) -> str:
    """Session 27: 'out of (the dog's) reach' / 'out of the way' right after a surface of the
    scene ("Pop the crisps up on the shelf, out of the dog's reach") says why the object goes
    there: taken off when it names nothing. After anything else ("Put the crisps out of reach",
    "the bottle, out of the way") it is left, and refused: it would be the only place said."""
    if "out of" not in text.lower():
        return text

    def cut(m: re.Match[str]) -> str:
        before = m.string[: m.start()]
        words = " ".join(re.split(r"[.;!?,]\s", before)[-1].split()[-3:])
        said = _names(words, lexicon)
        on_surface = (
            bool(said)
            and before.lower().endswith(said[-1].text.lower())
            and all(r.kind == "surface" for r in said[-1].refs)
        )
        return "" if on_surface and _names_nothing(m[0], lexicon) else m[0]

    return _OUT_OF_REACH27.sub(cut, text)


# The verb said last (Amharic, Turkish, Japanese, Korean, Hindi word order): "Person B the chips
# give", "the chips on the shelf put"; and 'to' + a pronoun before the object ("you give to him
# the bottle"). Each clause is read in the English order only when its words are exactly a person
# (or a surface after on/onto/in), the objects, and a verb of the grammar's tasks: nothing else.
_LAST_VERB27 = r"(give|hand|pass|bring|deliver|put|place|set|leave)"
_OBJECT_NP27 = r"(?:the|a|an|that|this|those|these|both|both the|my|his|her|their) [a-z][a-z -]*?"


def _verb_last27(text: str, lexicon: Lexicon) -> str:
    """Session 27: a clause (between marks, after an optional 'please' / 'you') whose verb comes
    last: '<person> <objects> give' → 'give <person> <objects>'; '<objects> on <surface> put'
    → 'put <objects> on <surface>'; and 'give to him/her/them <objects>' → 'give him/her/them
    <objects>'. The person must be one of the scene's, whole; the objects must name objects and
    nothing else; a word left over leaves the clause as it is."""
    low = text.lower()
    if not re.search(rf"\b{_LAST_VERB27}\b", low):
        return text
    out = _sub(
        rf"\b(give|hand|pass|bring) to (him|her|them) ({_OBJECT_NP27})(?=\s*(?:[,.;!?]|$))",
        lambda m: f"{m[1]} {m[2]} {m[3]}" if _objects_only(m[3], lexicon) else m[0],
        text,
    )

    def person_first(m: re.Match[str]) -> str:
        who, what, verb = m["who"], m["what"], m["verb"]
        if verb.lower() in ("put", "place", "set", "leave"):
            return m[0]
        if (
            not _opens_with_person(who, lexicon)
            or _names(who, lexicon)[0].text.lower() != who.lower()
        ):
            return m[0]
        if not _objects_only(what, lexicon) or len(_names(who, lexicon)) != 1:
            return m[0]
        return f"{m['lead']}{verb} {who} {what}"

    out = _sub(
        r"(?P<lead>(?:^|(?<=[.;!?,])\s*)(?:please,?\s+)?(?:you\s+)?)(?P<who>(?:person [a-z]|"
        r"(?:mr|mrs|ms|miss|dr) [a-z]+|[a-z]+)) (?P<what>" + _OBJECT_NP27 + r") "
        r"(?P<verb>give|hand|pass|bring)(?=\s*(?:please\s*)?(?:[,.;!?]|$))",
        person_first,
        out,
    )

    def placed_first(m: re.Match[str]) -> str:
        what, where = m["what"], m["where"]
        if not _objects_only(what, lexicon) or not _surface_only(where, lexicon):
            return m[0]
        return f"{m['lead']}{m['verb']} {what} {m['prep']} {where}"

    return _sub(
        r"(?P<lead>(?:^|(?<=[.;!?,])\s*)(?:please,?\s+)?(?:you\s+)?)(?P<what>" + _OBJECT_NP27 + r")"
        r" (?P<prep>on|onto|on to|in|into) (?P<where>the [a-z][a-z ]*?) "
        r"(?P<verb>put|place|set|leave)(?=\s*(?:please\s*)?(?:[,.;!?]|$))",
        placed_first,
        out,
    )


def _whole_name(words: str, lexicon: Lexicon, kind: str) -> bool:
    """Whether ``words`` (an article aside, 'a' and 'an' too) are one name of the scene, whole,
    of ``kind``: :func:`_only_kind` of the words without their article."""
    return _only_kind(re.sub(r"^(?:the|a|an) ", "", words.strip(), flags=_F), lexicon, kind)


# a person's name as the session-28 (12s) rules take it: 'Person A', a title and a name, a word
_PERSON28S = r"person [a-z]|(?:mr|mrs|ms|miss|dr) [a-z]+|[a-z]+"


def _object_and_person(m: re.Match[str], lexicon: Lexicon) -> bool:
    """Whether ``m``'s 'what' is one whole name of the scene's objects and its 'who' one of its
    people."""
    return _whole_name(m["what"], lexicon, "object") and _whole_name(m["who"], lexicon, "human")


def _object_first28s(text: str, lexicon: Lexicon) -> str:
    """Session 28 (12s): a clause (between marks, after an optional 'then' / 'and then') said
    object first, '<object> give <person>' ("Apple give Person A first, then bottle give Person
    B"): 'give <person> <object>'. The object and the person must each be one name of the
    scene, whole, with nothing else in the clause but 'first' / 'next' / 'too' after it; a
    pronoun ('the bottle give her'), a count ('both give Alice'), a past form ('the bottle gave
    Bob …') or a word left over leaves the clause as it is."""

    def turned(m: re.Match[str]) -> str:
        if not _object_and_person(m, lexicon):
            return m[0]
        return f"{m['lead']}{m['verb']} {m['who']} {m['what']}{m['tail']}"

    return _sub(
        r"(?P<lead>(?:^|(?<=[.;!?,])\s*)(?:(?:and )?then,?\s+)?)(?P<what>(?:the |a |an )?"
        rf"[a-z]+(?: [a-z]+)?) (?P<verb>give|hand|pass) (?P<who>{_PERSON28S})"
        r"(?P<tail>(?: first| next| too| as well)?)(?=\s*(?:[,.;!?]|$))",
        turned,
        text,
    )


def _pair_listed28s(text: str, lexicon: Lexicon) -> str:
    """Session 28 (12s): 'the pair / both, <X> and <Y> (together / both / alike)' at the end
    ("Person A's having the pair, bottle and chips together", "Person A's to have both, bottle and
    chips alike"): the two objects listed stand for 'the pair' / 'both'.
    The list must be two names of the scene's objects, whole, and nothing else."""

    def listed(m: re.Match[str]) -> str:
        first, second = m["first"], m["second"]
        if not (_whole_name(first, lexicon, "object") and _whole_name(second, lexicon, "object")):
            return m[0]
        if _ids(first, lexicon, "object") == _ids(second, lexicon, "object"):
            return m[0]
        return f"{first} and {second}{m['end']}"

    return _sub(
        r"\b(?:the pair|both),\s*(?P<first>(?:the )?[a-z]+(?: [a-z]+)?) and "
        r"(?P<second>(?:the )?[a-z]+(?: (?!together|both|alike|as well)[a-z]+)?)"
        r"(?: (?:together|both|alike|as well))?"
        r"(?P<end>\s*[.!]?\s*)$",
        listed,
        text,
    )


def _is_to28s(text: str, lexicon: Lexicon) -> str:
    """Session 28 (12s): '<person>'s to get / have …' ("Person B's to get both"; 's before 'to' is
    'is', as a possessive cannot stand there) and '<person> is to have …' are '<person> gets …';
    'gets / has the two of them' (the objects: the person is named as the subject) is 'gets
    both'. The person must be one of the scene's, whole."""

    def gets(m: re.Match[str]) -> str:
        if not _whole_name(m["who"], lexicon, "human"):
            return m[0]
        return f"{m['who']} gets"

    out = _sub(
        rf"\b(?P<who>{_PERSON28S})(?:'s| is) to "
        r"(?:get|have|receive)\b",
        gets,
        text,
    )
    return _sub(r"\b(gets|has|receives|takes) the two of them\b", r"\1 both", out)


def _wanted_with28s(text: str, lexicon: Lexicon) -> str:
    """Session 28 (12s): '(he / she / they) wants / needs it with the <food or the like>' at the
    end of a clause ("the lemon to the chef please, he wants it with the hake"): what the object
    goes with, as 'for the hake' (_purpose), taken off when it names nothing in the scene (nor
    by a typo) and holds no word that counts, chooses or points back; 'with the salt' (an object
    of the scene) asks for it too, and stays."""
    return _sub(
        r"\b((?:he|she|they) (?:wants?|needs?|would like|'d like) (?:it|them)) with (?:the|his|"
        r"her|their|a|an|some) ([a-z]+(?:[ -][a-z]+)?)(?=\s*(?:[.;!?]|$))",
        lambda m: (
            m.group(1)
            if _names_nothing(m.group(2), lexicon) and not _KEEP_WORDS.search(m.group(2))
            else m.group(0)
        ),
        text,
    )


# -ing words that say what the person wants, not what they are busy with
_WANTING28S = frozenset(
    {
        *("asking", "waiting", "wanting", "looking", "hoping", "begging", "calling", "shouting"),
        *("dying", "gasping", "longing", "pining", "crying", "going", "getting", "having"),
        *("needing", "eyeing", "eying", "angling", "expecting", "saving", "keeping", "using"),
    }
)


def _busy_with28s(text: str, lexicon: Lexicon) -> str:
    """Session 28 (12s): '<person>'s been / is <verb>ing <a few words>,' before the request
    ("Person B's been mending sails, give him the chips"): what the person is busy with says why,
    as "Person B is busy, give him …" (read before), and is read as that when the words after
    the -ing word name nothing in the scene (nor by a typo) and hold no word that counts, chooses
    or points back, and the -ing word is no verb of the grammar and says no want ('asking',
    'waiting', 'looking', …). The person stays, for 'him' / 'her' after it."""

    def busy(m: re.Match[str]) -> str:
        ing, what = m["ing"].lower(), m["what"]
        if ing in VERBS or ing in _WANTING28S or not _whole_name(m["who"], lexicon, "human"):
            return m[0]
        if not _names_nothing(what, lexicon) or _KEEP_WORDS.search(what):
            return m[0]
        return f"{m['who']} is busy,"  # ('mending' alone is one edit from 'sending')

    return _sub(
        rf"^(?P<who>{_PERSON28S})(?P<be>'s been| has been| is| "
        r"was) (?P<ing>[a-z]+ing) (?P<what>[a-z]+(?: [a-z]+){0,2}),",
        busy,
        text,
    )


def _says_she_is28s(text: str, lexicon: Lexicon) -> str:
    """Session 28 (12s): '<person> says / said (that) she's / he's / they're <a word or two>,'
    opening the instruction ("Person A says she's peckish, the chips please"): the pronoun is
    the one who says it (the subject of the reporting verb), so it is '<person> is <words>,'. The
    words must name nothing in the scene and hold no counting or pointing word; the person must be
    one whole name."""

    def said(m: re.Match[str]) -> str:
        if not _whole_name(m["who"], lexicon, "human"):
            return m[0]
        if not _names_nothing(m["how"], lexicon) or _KEEP_WORDS.search(m["how"]):
            return m[0]
        return f"{m['who']} is {m['how']},"

    return _sub(
        rf"^(?P<who>{_PERSON28S}) (?:says|said)(?: that)? "
        r"(?:she's|she is|he's|he is|they're|they are) (?P<how>[a-z]+(?: [a-z]+)?),",
        said,
        text,
    )


def _give_both28s(text: str, lexicon: Lexicon) -> str:
    """Session 28 (12s): a last sentence 'Please (you) give both.' after two objects were each
    said to be for someone ("Person A want bottle, and Person B want chips. Please you give
    both."): doing what was said, nothing more; taken off when what comes before names exactly
    two objects and says who has each (a 'for' / 'to' or a want verb per object)."""
    m = _rx(
        r"^(?P<said>.+?[.!])\s+(?:please,?\s+)?(?:you\s+)?(?:give|do|deliver|hand over|sort out)"
        r" (?:both|them both|both of them|the two)(?:,?\s*please)?\s*[.!]?\s*$"
    ).match(text)
    if m is None:
        return text
    said = m["said"]
    wants = len(re.findall(r"\b(?:wants?|needs?|for|to|gets?)\b", said, _F))
    if len(_ids(said, lexicon, "object")) != 2 or wants < 2 or not _ids(said, lexicon, "human"):
        return text
    return said


def _dislocated28s(text: str, lexicon: Lexicon) -> str:
    """Session 28 (12s): an object said first, then a clause taking it up again with 'it' / 'that
    one' ("…, and the cup, Person A can have that one"): the pronoun is the object just said (a
    left dislocation), so '<person> can have <object>'. The object must be one whole name of the
    scene, said right after the start, a full stop or ', and'; the person one whole name."""

    def taken_up(m: re.Match[str]) -> str:
        if not _object_and_person(m, lexicon):
            return m[0]
        return f"{m['lead']}{m['who']} {m['verb']} {m['what']}"

    return _sub(
        r"(?P<lead>^|(?<=[.!?])\s+|,\s*and\s+)(?P<what>the [a-z]+(?: [a-z]+)?),\s*"
        rf"(?P<who>{_PERSON28S}) (?P<verb>can have|gets|should get|can take) "
        r"(?:it|that one|that)\b",
        taken_up,
        text,
    )


def _along_with28s(text: str, lexicon: Lexicon) -> str:
    """Session 28 (12s): ', and the <object> with it / them' closing the instruction (the object
    goes along with what was just placed or handed over: 'too'), and 'give them to <person>
    together' (how, not what: 'together' taken off). The object must be one whole name."""

    def along(m: re.Match[str]) -> str:
        if not _whole_name(m["what"], lexicon, "object"):
            return m[0]
        return f"{m['lead']}{m['what']} too{m['end']}"

    text = _sub(
        r"(?P<lead>,?\s*\band )(?P<what>the [a-z]+(?: [a-z]+)?) with (?:it|them)"
        r"(?P<end>\s*[.!]?\s*)$",
        along,
        text,
    )
    return _sub(
        r"\b((?:give|hand|pass|bring|take) (?:them|both|the two of them|both of them) (?:over )?to "
        r"(?:him|her|them|person [a-z]|[a-z]+)) together(?=\s*[.!]?\s*$)",
        r"\1",
        text,
    )


_PRONOUNS28S = frozenset({"him", "her", "them"})


def _run30(text: str, lexicon: Lexicon) -> str:
    """Session 30: 'run' carrying (above) is 'bring', on the conditions of _run_to28s: its object
    the scene's objects only or 'it' / 'them', where it goes a pronoun or one person or surface."""
    if "run" not in text.lower():
        return text

    def brought(m: re.Match[str]) -> str:
        what = m["what"]
        if what.lower() not in ("it", "them") and not _objects_only(what, lexicon):
            return m[0]
        words = m["where"].split()
        for n in (len(words), 1):
            where = " ".join(words[:n])
            if where.lower() in _PRONOUNS28S or any(
                _only(where, lexicon, kind) for kind in ("human", "surface")
            ):
                verb = "bringing" if m["ing"] else "bring"
                rest = " ".join(words[n:])
                return f"{m['lead']}{verb} {what}{m['dir']} to {where}{' ' + rest if rest else ''}"
        return m[0]

    return _RUN30.sub(brought, text)


def _run_to28s(text: str, lexicon: Lexicon) -> str:
    """Session 28 (12s): 'run <objects> (up / down / over / across) to <person or surface>' ("Will
    you run the bottle up to Person B"): carrying it there quickly, 'bring'. Only the verb said
    as a request (plain 'run', first in its clause or after 'you' / 'to' / 'please'), its object
    the scene's objects and nothing else, or 'it' / 'them' (resolved as for 'bring'): 'the foley
    session ran long', 'the tap is running', "I'll run the numbers" are no carrying."""

    def brought(m: re.Match[str]) -> str:
        said = m["what"].lower() in ("it", "them") or _objects_only(m["what"], lexicon)
        if not said or not (m["where"].lower() in _PRONOUNS28S or _names(m["where"], lexicon)):
            return m[0]
        return f"{m['lead']}bring {m['what']}{m['dir']} to {m['where']}"

    return _sub(
        r"(?P<lead>(?:^|(?<=[.;!?,])\s*|\b(?:you|to|please) ))run (?P<what>it|them|(?:the|that|"
        r"this|those|these) [a-z][a-z ]*?)(?P<dir>(?: (?:up|down|over|across|round|along))?) to "
        r"(?P<where>(?:the )?[a-z]+(?: [a-z]+)?)(?=\s*(?:[,.;!?]|$|\s(?:for|please|now)\b))",
        brought,
        text,
    )


def _matters_which28s(text: str, _lexicon: Lexicon) -> str:
    """Session 28 (12s): "I don't suppose / think it matters which (colour)" and "doesn't bother
    me which" are "it doesn't matter which (colour)", the choice tail the grammar reads (the
    speaker leaving the choice open)."""
    text = _sub(
        r"\b(?:it )?(?:doesn't|does not) bother me (?=which\b)",
        "it doesn't matter ",
        text,
    )
    return _sub(
        r"\bi (?:don't|do not) (?:suppose|think|reckon|imagine|expect) it (?:matters|'ll matter|"
        r"will matter) (?=which\b)",
        "it doesn't matter ",
        text,
    )


def _either_of_them28s(text: str, lexicon: Lexicon) -> str:
    """Session 28 (12s): 'Either of them can have / gets …' opening the instruction, in a scene
    of exactly two people, with no one named before it: 'them' are the two people (the receiving
    verb says so), so 'Either of the two people …', which the grammar reads as one or the
    other."""
    if len(lexicon.scene.humans) != 2:
        return text
    return _sub(
        r"^either of them (?=(?:can have|gets|can take|should get|should have|may have)\b)",
        "Either of the two people ",
        text,
    )


def _disturb28s(text: str, _lexicon: Lexicon) -> str:
    """Session 28 (12s): "sorry ah, disturb you a bit" (Singapore English) is "sorry to disturb
    you a bit", the apology the openers know (_BOTHERING)."""
    return _sub(
        r"\bsorry(?: (?:ah|lah|leh))?,?\s+(?=disturb(?:ing)? you\b)",
        "sorry to ",
        text,
    )


def _or_not28s(text: str, lexicon: Lexicon) -> str:
    """Session 28 (12s): a request asked with 'can … or not?' (Singapore English: "Can help me
    give Alice the crisps or not?", "the bottle, can pass to Person B or not ah?") is the request
    asked with 'can …?': 'or not' is taken off. Only after 'can' in the same sentence, at the end
    of a question: "Should Alice have the crisps or not?" asks whether, and stays a question."""
    return _sub(
        r"(\bcan\b[^.!?]*?)\s*,?\s+or not(?: (?:ah|lah|leh|one))?\s*(\?)\s*$",
        r"\1\2",
        text,
    )


# Session 28 (12s): 'finish already', 'then finish', 'and that's finished' after the last request:
# the speaker saying the list is over (asks nothing)
_FINISHED28S = (
    r",\s*(?:and |then |and then )?(?:finish|finished|finish already|all finished|that's "
    r"finished)(?: (?:already|lah|ah|now))*\s*(?=[.!]?\s*$)"
)


# 'and be quick about it', 'look sharp', 'chop chop' after the last request: urging (asks nothing)
_URGED28S = (
    r"(?:,\s*|\s+and\s+|\s*[.!]\s+)(?:be quick(?: about it)?|look sharp|chop,? chop|make it "
    r"snappy|get a move on)\s*(?=[.!]?\s*$)"
)


# 'since her shift began' after a want; "they've had sample dye in them" after a placement of
# them: when the want began, why the objects go there (each names nothing in the scene)
_SINCE28S = (
    r"\s+since (?:her|his|their|my|our|the) [a-z]+(?: [a-z]+)? (?:began|started|opened|came on)"
    r"(?=\s*[.!]?\s*$)"
)
_HAD_IN28S = (
    r",\s*(?:they've|they have|it's|it has) (?:had|got) (?:[a-z]+ ){1,3}(?:in|on) (?:them|it)"
    r"(?=\s*[.!]?\s*$)"
)


def _finished28s(text: str, lexicon: Lexicon) -> str:
    """Session 28 (12s): 'finish already' (_FINISHED28S), urging (_URGED28S), 'since her shift
    began' (_SINCE28S) and "they've had dye in them" (_HAD_IN28S) after the last request, taken
    off when they name nothing in the scene."""
    for said in (_FINISHED28S, _URGED28S, _SINCE28S, _HAD_IN28S):
        text = _drop(said, text, lexicon)
    return text


# A description of objects, then the list of the objects it describes ("The two drinks, bottle
# and cup, go to Person B", "The two things cluttering the floor, the bottle and the crisps, up
# on the shelf", "Hand over both items, chips and bottle alike, to Person B"; "Anything edible
# goes to Person B, so that's the apple and the chips"): the list is what the speaker means, and
# it stands for the description. The description must count as many objects as the list names
# ('two', 'both', 'all three'), or, said as 'anything / everything <word>', be followed by
# "so that's" / "that is" / "namely" and the list; where it names objects of the scene itself
# ('both mugs'), the list must name the same ones. The list names only objects, one per item.
_COUNT27 = {w: n for w, n in _NUMBERS15.items() if n > 1} | {"2": 2, "3": 3}  # not "one"
_DESC_HELD27 = frozenset(
    {
        *("not", "n't", "except", "but", "or", "nor", "one", "ones", "each", "other", "only"),
        *("just", "some", "either", "neither", "no", "none", "and", "then", "first", "last"),
        *("me", "him", "her", "them", "it", "us", "for", "to", "on", "onto", "into", "in"),
        *("besides", "without", "apart", "instead", "rest", "else", "more", "less", "than"),
    }
)


_PROPERTIES27 = frozenset(
    {
        *("red", "blue", "green", "white", "black", "grey", "gray", "yellow", "orange", "pink"),
        *("purple", "brown", "big", "small", "large", "medium", "little", "tall", "short"),
    }
)


def _listed_items27(words: str, lexicon: Lexicon) -> list[str] | None:
    """The object ids ``words`` lists, one per item ('bottle and cup', 'the bottle, the cup and
    the apple'), or None when an item names anything else or more or less than one object."""
    items = [w for w in re.split(r"\s*,\s*|\s+and\s+", words.strip()) if w]
    out: list[str] = []
    for item in items:
        if not re.fullmatch(r"(?:the |a |an |that |this )?[a-z][a-z -]*", item, _F):
            return None
        said = _names(item, lexicon)
        if len(said) != 1 or len(said[0].refs) != 1 or said[0].refs[0].kind != "object":
            return None
        if not item.lower().endswith(said[0].text.lower()):
            return None
        out.append(said[0].refs[0].id)
    return out if len(out) == len(set(out)) and len(out) >= 2 else None


def _describes27(desc: str, ids: list[str], lexicon: Lexicon, *, restated: bool) -> bool:
    """Whether the description ``desc`` may stand for the listed objects ``ids``."""
    words = re.findall(r"[a-z0-9']+", desc.lower())
    if not words or any(w in _DESC_HELD27 or w.endswith("n't") for w in words):
        return False
    # 'things', 'items', 'objects' name every object: the count says how many are meant
    desc = re.sub(r"\b(?:things?|items?|objects?|bits?|stuff)\b", "", desc, flags=_F)
    named = _ids(desc, lexicon)
    if named and named != set(ids):
        return False
    if named and not all(r.kind == "object" for it in _names(desc, lexicon) for r in it.refs):
        return False
    for w in words:
        # a property the description gives ('everything red', 'the two big things') must be
        # one each listed object has by its name in the scene; one the scene cannot check
        # ('edible', 'heavy') is the list's to say
        if w in _adjectives(lexicon) or w in _PROPERTIES27:
            for oid in ids:
                obj = lexicon.scene.object(oid)
                if not any(n.lower().startswith(w + " ") for n in (*obj.aliases, obj.id)):
                    return False
    counts = [_COUNT27[w] for w in words if w in _COUNT27]
    if counts:
        return len(set(counts)) == 1 and counts[0] == len(ids)
    return restated and words[0] in ("anything", "everything", "all")


_ITEM27 = r"(?:(?:the|a|an) )?[a-z]+(?: (?!alike\b|both\b|too\b)[a-z]+)?"
_LIST27 = rf"(?P<list>{_ITEM27}(?:(?:,\s*| and ){_ITEM27}){{1,4}})"


def _described_list27(text: str, lexicon: Lexicon) -> str:
    """Session 27: a description of objects followed by the list of them, the list standing for
    it (above): '<desc>, <list>(alike)?, <rest>' at the start of a sentence or after a verb of
    handing, and '<desc> <verb phrase>, so that's <list>' at the start of a sentence."""
    low = text.lower()
    if not any(w in low for w in ("two", "three", "four", "five", "six", "both", "that")):
        return text

    def apposed(m: re.Match[str]) -> str:
        ids = _listed_items27(m["list"], lexicon)
        if ids is None or not _describes27(m["desc"], ids, lexicon, restated=False):
            return m[0]
        return f"{m['lead']}{m['list']} "

    out = _sub(
        r"(?P<lead>(?:^|(?<=[.;!?])\s*)(?:(?:give|hand over|hand|pass|bring|put|stick|pop|"
        r"take) )?)(?P<desc>(?:the |all |both |all the |both the |all of the |all (?:two|three|"
        r"four|five|six) |those |these )?(?:(?:two|three|four|five|six) )?[a-z]+s\b[a-z' ]*?)"
        r",\s*" + _LIST27 + r"(?: alike| both| too)?,\s*",
        apposed,
        text,
    )

    def restated(m: re.Match[str]) -> str:
        ids = _listed_items27(m["list"], lexicon)
        if ids is None or not _describes27(m["desc"], ids, lexicon, restated=True):
            return m[0]
        verb = re.sub(r"^goes\b", "go", m["verb"], flags=_F)
        return f"{m['lead']}{m['list']} {verb}{m['end']}"

    return _sub(
        r"(?P<lead>(?:^|(?<=[.;!?])\s*))(?P<desc>(?:anything|everything|all the [a-z]+s) "
        r"[a-z]+) (?P<verb>(?:go|goes|should go|can go) (?:to|on|onto|in|into) [a-z][a-z ]*?),\s*"
        r"(?:so,? )?(?:that's|that is|those are|that means|i\.e\.,?|namely|meaning)\s+"
        + _LIST27
        + r"(?P<end>\s*(?:[,.;!?]|$))",
        restated,
        out,
    )


# -- session 29 (12s): the speaker talking about themself, by kind ---------------------------------

# The speaker owning a slip ('I make mistake', 'I made a mistake', "I've got that wrong", 'silly
# me'): after the correction that mends it, closing the text ("Apple to Person A, no,
# sorry, to Person B, I make mistake."), it says why the correction was made, and is taken off;
# between a request and what replaces it ("Give Ava the red block, oh silly me, she wants the
# green one.") it is the correction's cue, said as the grammar's ', no, '. Either way it must name
# nothing, and the correction must then read as any other (the cue's rule).
_SLIP29S = (
    r"(?:i (?:make|made|'ve made|have made) (?:a |my )?mistake|"
    r"i(?:'ve| have)? got (?:that|it) (?:wrong|mixed up|muddled)|(?:oh,? )?silly me|"
    r"i(?:'ve| have)? (?:read|heard|got|misread|misheard) (?:the|that|it|my) (?:[a-z]+ )?wrong)"
)
# a cue right before the slip: the slip is said of it ("…, nope, I've read the ticket wrong, …")
_CUE_LAST29S = re.compile(
    r"(?:,|\.\.\.|…)\s*(?:no|nope|nah|sorry|oops|whoops|oh no|no sorry)\s*$", _F
)
_SLIP_LAST29S = re.compile(rf"\s*,\s*(?:(?:sorry|oops|whoops),?\s*)?{_SLIP29S}\s*[.!]*\s*$", _F)
_SLIP_CUE29S = re.compile(rf"\s*,\s*(?:oh,?\s*)?{_SLIP29S}\s*,\s*", _F)


# "…, no, it's Person B's" closing a correction of whom a delivery goes to: the object is that
# person's, 'it's for Person B' (the person one whole name of the scene)
_CUE_NO29S = r"(?P<cue>(?:,|\.\.\.|…)\s*no,\s*)"
_ITS_HIS29S = rf"{_CUE_NO29S}it(?:'s| is| was) (?P<who>{_PERSON28S})'s\s*(?P<end>[.!]?)\s*$"


# "…, no, it was Mrs Khan who asked for it": the cleft after the cue, as session 11's "It's Carol
# who needs …" opening a text: 'Mrs Khan asked for it'
_CLEFT_AFTER_CUE29S = rf"{_CUE_NO29S}it(?:'s| is| was) (?P<who>{_PERSON28S}) (?:who|that) (?=[a-z])"


# A gapped clause with 'also' / 'too' between its person and its object ("Carol would like the
# blue mug, and Bob also the apple"): the verb is the clause's before it, and 'also' marks the
# clause as one more, as ', and Bob the apple' does; 'also' there says nothing of the object (read
# as 'the apple too', it gave the blue mug to Bob as well). The word before it must be one whole
# name of a person of the scene, after ', and' / 'and'; an object after it ('and the cup also the
# apple') or none ('and Bob also') is left.
_GAPPED29S = (
    rf"(?P<head>,?\s+and\s+)(?P<who>{_PERSON28S})\s+(?:also|too)\s+"
    r"(?=(?:the|a|an|his|her|their)\s+[a-z])"
)


def _for_person29s(
    pattern: str,
    text: str,
    lexicon: Lexicon,
    said: Callable[[re.Match[str]], str],
    what: str = "object",
) -> str:
    """``text`` with each match of ``pattern`` whose group 'who' is one whole name of a person of
    the scene said as ``said`` gives (and, where ``pattern`` has a group 'what', that is one
    whole name of one thing of kind ``what``; a he / she / his / her in the match must fit the
    person, as far as a title says); other matches as they were."""

    def one(m: re.Match[str]) -> str:
        who = m.group("who").strip()
        named = _only(who, lexicon, "human")
        if named:
            named = _fits(next(iter(_ids(who, lexicon, "human"))), m.group(0), lexicon)
        if named and "what" in m.groupdict():
            named = _only(m.group("what"), lexicon, what)
        return said(m) if named else m.group(0)

    return _sub(pattern, one, text)


def _its_persons29s(text: str, lexicon: Lexicon) -> str:
    """ "…, no, it's Person B's": "…, no, it's for Person B"; "…, no, it was Mrs Khan who asked
    for it": "…, no, Mrs Khan asked for it" (above)."""
    text = _for_person29s(
        _ITS_HIS29S, text, lexicon, lambda m: f"{m['cue']}it's for {m['who']}{m['end']}"
    )
    return _for_person29s(_CLEFT_AFTER_CUE29S, text, lexicon, lambda m: f"{m['cue']}{m['who']} ")


def _gapped_also29s(text: str, lexicon: Lexicon) -> str:
    """'…, and Bob also the apple': 'also' taken out of the gapped clause (above)."""
    return _for_person29s(_GAPPED29S, text, lexicon, lambda m: f"{m['head']}{m['who']} ")


# 'his' / 'her' / 'their' right after a person's want ("… and then Bob wants his crisps"): the
# possessive is the wanting person's (as session 11's 'once Bob has had his chips'), and says no
# more of the object than 'the' when the words after it are one whole name of one object of the
# scene; with two people named, the grammar had taken 'his' as a reference to be resolved. Two
# objects of the name ('Bob wants his mug', two mugs) or a name that is not whole stay as said.
_OWN_WANT29S = (
    rf"\b(?P<who>{_PERSON28S}) (?P<verb>wants|needs|would like|'d like|is asking for|asked for|"
    r"has asked for) (?:his|her|their) (?P<what>[a-z]+(?: [a-z]+)?)(?=\s*(?:[,.;!?]|and\b|$))"
)


def _own_want29s(text: str, lexicon: Lexicon) -> str:
    """'Bob wants his crisps': 'the crisps' (above)."""
    return _for_person29s(
        _OWN_WANT29S, text, lexicon, lambda m: f"{m['who']} {m['verb']} the {m['what']}"
    )


# After a placement, the speaker saying what they are doing with another surface, or that they
# need it ("All three pens in the box, please, I'm clearing the desk.", "…, I need the desk for
# my pattern paper.", "…, I need to do the shelves.", "Could the apple go on the table, I've got
# puppets all over the shelf?"): why the objects go where they go, asking nothing (a surface is
# never handed over). Taken off when it closes the text, its verb is one of these, the surface it
# names is not where the request puts anything, the request before it puts something on a
# surface, and what else it says names nothing in the scene.
_SURFACE_BUSY29S = re.compile(
    r"\s*,\s*(?:(?:and|so|as|because|cos|since) )?(?:"
    r"i(?:'m| am) (?:just |busy )?(?:clearing|cleaning|wiping|tidying|using|working on|doing|"
    r"dusting|sorting|painting|polishing) (?P<a>(?:the|my) [a-z]+)|"
    r"i need (?P<b>(?:the|my) [a-z]+)(?: (?:clear|free|empty))?"
    r"(?: for (?:my |the |a |an |some )?[a-z]+(?: [a-z-]+){0,2})?|"
    r"i need to (?:do|clean|wipe|clear|dust|tidy|use|sort|paint|polish) (?P<c>(?:the|my) [a-z]+)|"
    r"i(?:'ve| have) got (?:[a-z]+ ){1,2}all over (?P<d>(?:the|my) [a-z]+))"
    r"\s*[.!?]*\s*$",
    _F,
)


def _surface_busy29s(text: str, lexicon: Lexicon) -> str:
    """The speaker busy with, or needing, another surface after a placement (above): taken off."""
    m = _SURFACE_BUSY29S.search(text)
    if m is None:
        return text
    where = next(g for g in m.group("a", "b", "c", "d") if g)
    head = text[: m.start()]
    surface = _ids(where, lexicon)
    targets = _ids(head, lexicon, "surface")
    if (
        len(surface) != 1
        or _ids(where, lexicon, "surface") != surface
        or not targets
        or surface & targets
        or _ids(m.group(0).replace(where, " "), lexicon)
        or re.search(r"\b(?:me|my|i)\b", head, _F)
    ):
        return text
    return head + ("?" if m.group(0).rstrip().endswith("?") else ".")


# A surface said as a person's ('on the teacher's desk', "in Grandad's locker"): after 'on' /
# 'onto' / 'in' / 'into', the possessive says whose it is, and the surface is the one the name
# means alone; the person must be one whole name of a person of the scene (or 'the <role>' of
# one), the surface one whole name of one surface. Two surfaces of the name, or a possessor who
# is no one of the scene, are left (refused as before).
_OWNED_SURFACE29S = (
    rf"\b(?P<on>on|onto|on to|in|into|on top of) (?P<who>(?:the )?(?:{_PERSON28S}))'s "
    r"(?P<what>[a-z]+(?: [a-z]+)?)\b(?=\s*(?:[,.;!?]|$))"
)


def _owned_surface29s(text: str, lexicon: Lexicon) -> str:
    """'on the teacher's desk': 'on the desk' (above)."""
    return _for_person29s(
        _OWNED_SURFACE29S, text, lexicon, lambda m: f"{m['on']} the {m['what']}", "surface"
    )


# 'not bothered', 'not fussed', "doesn't care" leaving a choice open ("Give Carol either of the
# mugs, she's not fussed which", "…, green or white, I'm not bothered", "…, red or blue, not
# bothered", "she really doesn't care which"): said as "<who> doesn't mind", the choice tail the
# grammar reads (with 'which' / 'which of them' / 'what' after it, or alone after a choice), and
# which leaves the request as it was where nothing is open ('Give Carol the red mug, I don't
# mind'). Only as a clause of its own, between commas or closing the text.
_NOT_FUSSED29S = re.compile(
    r"(?P<lead>,\s*)(?:(?P<who>i|she|he|they)(?:'m|'s|'re| am| is| are) (?:really |honestly )?"
    r"not (?:bothered|fussed|fussy|particular)|(?P<who2>i|she|he|they) (?:really |honestly )?"
    r"(?:don't|doesn't|do not|does not) care|not (?:bothered|fussed))"
    r"(?P<tail>(?: (?:which|what)(?: (?:one|of them|of the two))?)?)(?=\s*(?:[.!,;]|$))",
    _F,
)


def _not_fussed29s(text: str, _lexicon: Lexicon) -> str:
    """'she's not fussed which': "she doesn't mind which" (above)."""

    def said(m: re.Match[str]) -> str:
        who = (m.group("who") or m.group("who2") or "i").lower()
        verb = "don't" if who in ("i", "they") else "doesn't"
        return f"{m.group('lead')}{'I' if who == 'i' else who} {verb} mind{m.group('tail')}"

    return _sub(_NOT_FUSSED29S.pattern, said, text)


# What brought a person's state on ("Person A's parched after the heat", "Bob's thirsty from the
# ride", "she's starving after the tyre change", "Person A's gasping after her run"): the cause,
# after 'after' / 'from' following a word of need or tiredness, is taken off (the state alone is
# the remark the grammar already reads: "Person A's parched, run the bottle over to her."). The
# cause must name nothing in the scene and hold no pronoun, count or verb that could say what
# happens to the scene's objects ('thirsty after that', 'hungry after she gets the chips',
# 'hungry after the apple' stay as said).
_STATE_CAUSE29S = re.compile(
    r"(?P<state>(?:'s|'re|\bis|\bare|\bwas|\bwere) (?:really |so |very |absolutely |proper |"
    r"well |just )?(?:thirsty|hungry|parched|gasping|peckish|starving|famished|ravenous|cold|"
    r"freezing|frozen|tired|knackered|shattered|exhausted|worn out|sore|sticky|filthy|soaked|"
    r"drenched|dry|boiling|roasting|sweaty|dusty)) (?P<cause>(?:after|from) [a-z' -]+?)"
    r"(?=\s*(?:[,.;!?]|$))",
    _F,
)
_CAUSE_HELD29S = re.compile(
    r"\b(?:it|them|that|this|those|these|one|ones|both|all|each|give|gives|gave|gets|got|get|"
    r"has|had|have|hand|handed|bring|brought|put|want|wants|need|needs|he|she|they|i|you|giving|"
    r"getting|handing|bringing|putting|having)\b|\d",
    _F,
)


def _state_cause29s(text: str, lexicon: Lexicon) -> str:
    """'Person A's parched after the heat': "Person A's parched" (above)."""
    return _sub(
        _STATE_CAUSE29S.pattern,
        lambda m: (
            m.group("state")
            if not _CAUSE_HELD29S.search(m.group("cause"))
            and _names_nothing(m.group("cause"), lexicon)
            else m.group(0)
        ),
        text,
    )


# A person who has asked the speaker for something ("Person A has asked me twice now for the
# chips"): the one asked is not who gets it ('ask <someone> for X': the asker wants X), so 'me'
# and how often are taken out, leaving '<person> has asked for', which the grammar reads as a
# want. The asker must be one whole name of a person of the scene, first in its clause.
_ASKED_ME29S = (
    rf"(?P<who>(?:^|(?<=[.;!?,])\s*)(?:{_PERSON28S})) (?:has asked|'s asked|asked|has been asking|"
    r"'s been asking|keeps asking) me(?: (?:twice|three times|again|already|twice now|again now|"
    r"all morning|all day|nicely))? for\b"
)


def _asked_me29s(text: str, lexicon: Lexicon) -> str:
    """'Person A has asked me twice now for the chips': 'Person A has asked for the chips'."""
    return _for_person29s(_ASKED_ME29S, text, lexicon, lambda m: f"{m['who']} has asked for")


# The kind's objects listed by their colour or size after the words that name them ("both mugs,
# red and blue, up on the shelf", "Sorry, both mugs, the red and the blue, could they …", "Load
# the three boxes onto the belt, small, medium and large.", "Hand Jess a spanner, big or small,
# …"): an apposition saying which they are. With 'and' the clause before it must name exactly the
# listed objects, by a plural of their kind ('both mugs', 'the three boxes'); with 'or', one of
# their kind ('a spanner', 'one of the mugs', 'either mug') where the listed ones are all of that
# kind. Each word must name, with the kind's name, one object of the kind, none twice. The list is
# then taken off (the plural or the choice says it already); two of three boxes after 'the three
# boxes', a choice after a plural, a list after one object named ('the red mug, red and blue'), or
# a word naming nothing are left as said (refused).
_KIND_LIST29S = (
    r"(?P<lead>,\s*)(?P<list>(?:the )?(?:{a})(?: one)?(?:(?:,\s*|\s+)(?:(?:and|or)\s+)?"
    r"(?:the )?(?:{a})(?: one)?){{1,3}})(?=\s*(?:[,.!?]|$))"
)


def _kind_adjectives29s(text: str, lexicon: Lexicon) -> str:
    """'both mugs, red and blue, …': the list taken off (above)."""
    adjectives = _adjectives(lexicon)
    if not adjectives:
        return text
    alternatives = "|".join(sorted(map(re.escape, adjectives), key=len, reverse=True))
    for m in _rx(_KIND_LIST29S.format(a=alternatives)).finditer(text):
        said = m.group("list").lower()
        joins = set(re.findall(r"\b(?:and|or)\b", said))
        words = [
            w for w in re.split(r",\s*|\s+", re.sub(r"\b(?:and|or|the|one)\b", " ", said)) if w
        ]
        if len(joins) != 1 or len(words) < 2 or any(w not in adjectives for w in words):
            continue
        head = text[: m.start()]
        start = max(head.rfind(c) for c in ".!?;:")
        clause = head[start + 1 :]
        kinds = set.intersection(*(set(adjectives[w]) for w in words))
        if len(kinds) != 1:
            continue
        kind = next(iter(kinds))
        every = {o.id for o in lexicon.scene.objects if o.category == kind}
        listed: set[str] = set()
        for w in words:
            ids = {i for i in _ids(f"the {w} {kind}", lexicon, "object") if i in every}
            if len(ids) != 1 or ids & listed:
                break
            listed |= ids
        else:
            named = _ids(clause, lexicon, "object")
            if named & every != named or not named:
                continue  # the clause names other objects too: which the list is about is unclear
            kinds_said = rf"{re.escape(kind)}(?:s|es)"
            plural = re.search(
                rf"\b(?:both|the|all|those|these|all the)(?: (?:two|three|four))? {kinds_said}\b|"
                rf"\bboth (?:of the )?{kinds_said}\b",
                clause,
                _F,
            )
            one = re.search(
                rf"\b(?:an? {kind}|one of the {kinds_said}|either {kind}|any {kind})\b", clause, _F
            )
            if (joins == {"and"} and plural and not one and named == listed) or (
                joins == {"or"} and one and not plural and listed == every
            ):
                return text[: m.start()] + text[m.end() :]
    return text


# 'wrong one' / 'wrong person' / 'wrong thing' right after a correction's cue ("Hand the chips
# to Person A, whoops, wrong one, I meant Person B.", "Chips for Person A, oops, wrong one, Person
# B."): the cue said again, taken off; without a cue before it, it is the cue (', no, '). What
# follows must be more words (a correction to read); 'wrong way round' (a swap) is not this.
_WRONG_ONE29S = re.compile(
    r"(?P<cue>,\s*(?:(?:oh |ah )?(?:no|nope|oops|whoops|sorry|oh no|ah no)\s*,?\s*)?)"
    r"wrong (?:one|person|thing|item)\s*,\s*(?=[a-z])",
    _F,
)


def _wrong_one29s(text: str, _lexicon: Lexicon) -> str:
    """'…, whoops, wrong one, I meant Person B': the cue once (above)."""
    return _sub(
        _WRONG_ONE29S.pattern,
        lambda m: m.group("cue").rstrip(" ,") + ", " if m.group("cue").strip(" ,") else ", no, ",
        text,
    )


# The speaker saying who they are with 'here' ("Alright mate, bus driver here, …", "Hiya,
# zookeeper here for the school visit, …", "Gardener here again, sorry, …"): a self-introduction
# at a sentence's start or after its opener, asking nothing; taken off when its words name
# nothing in the scene (a person of the scene saying 'Alice here' is who 'me' is, left) and hold
# no word that could ask, point or count (_REMARK_HELD: 'it here', 'the two here', 'put … here').
_HERE_I_AM29S = re.compile(
    r"(?:^|(?<=[.!?,]))\s*(?P<who>(?:[a-z]+ ){0,2}[a-z]+) here(?P<more> again| for (?:the |a |an |"
    r"your |my |our )?[a-z]+(?: [a-z]+){0,2})?\s*(?:,\s*|(?=[.!?;]|$))",
    _F,
)


def _here_i_am29s(text: str, lexicon: Lexicon) -> str:
    """'bus driver here, …': taken off (above)."""

    def said(m: re.Match[str]) -> str:
        words = f"{m['who']} {(m['more'] or '').replace(' for ', ' ').replace(' again', '')}"
        if _REMARK_HELD.search(words) or not _names_nothing(words, lexicon):
            return m.group(0)
        return " " if m.start() > 0 else ""

    out = _sub(_HERE_I_AM29S.pattern, said, text)
    return " ".join(out.split()) if out != text and _names(out, lexicon) else text


# A condition that only asks kindly ("if it's all the same to you", "if that works for you", "if
# okay with you", "only if it isn't too much trouble", "if it's no bother", "forgive me if I get
# this wrong", "if you wouldn't mind terribly"): it sets no condition on the request, and is
# taken off as a clause of its own (between commas, or a sentence's start and a comma, or
# closing a sentence). Conditions about anything else ('if Bob is there', 'if it's clean') are
# left, and refused.
_KINDLY_IF29S = re.compile(
    r"(?P<lead>(?:^|(?<=[.!?])|,)\s*)(?:(?:um|er|oh|sorry|so|but|and),?\s*)?(?:(?:only|just) )?(?:"
    r"if (?:it's|it is) all the same to you|if (?:that|this) (?:works|suits) (?:for )?you|"
    r"if (?:(?:that's|that is|it's|it is) )?(?:okay|ok|alright|all right|fine) (?:with|by|for) you|"
    r"if (?:it's|it is|that's|that is) (?:no|not (?:too much|a|any)|not) (?:trouble|bother|"
    r"problem)|if (?:it|that) (?:isn't|is not|wouldn't be|won't be) (?:too much |any |a )?"
    r"(?:trouble|bother|problem)|forgive me if i (?:get|got|have got|'ve got) (?:this|it) wrong|"
    r"if you (?:wouldn't|would not|don't|do not) mind(?: (?:terribly|awfully|too much|at all))?)"
    r"\s*(?P<end>,\s*(?:(?:but|so)\s+)?|(?=[.!?]|$))",
    _F,
)


def _kindly_if29s(text: str, lexicon: Lexicon) -> str:
    """'if it's all the same to you, …': taken off (above)."""
    out = _sub(_KINDLY_IF29S.pattern, lambda m: m["lead"] if m["end"] else "", text)
    if out == text:
        return text
    out = re.sub(r"^\s*,\s*|(?<=[.!?])\s*,\s*", " ", out).strip()
    return out if out != text and _names(out, lexicon) else text


# 'Would you mind (awfully / terribly) letting P have X?' is 'Could you let P have X?' (the
# '-ing' of the one verb 'let' the courtesy frames had not taken); and 'tidy X away into / in /
# on S' is 'put X in / on S' (putting away is placing, where S is said; without a place, left).
_MIND_LETTING29S = re.compile(
    r"\bwould you mind(?: (?:awfully|terribly|very much|at all))? letting\b", _F
)
_TIDY_AWAY29S = re.compile(
    r"\b(?:tidy|tidying|tidied) (?P<what>(?:the|that|this|those|these|both|all the) [a-z]+(?: "
    r"[a-z]+)?|it|them) away (?P<where>in|into|on|onto)\b",
    _F,
)


# thanks said as the speaker's gratitude closing the text ("…, ever so grateful", "…, much
# obliged", "I'm very grateful"): the courtesy closers' kind
_GRATEFUL29S = re.compile(
    r"\s*[,.!]\s*(?:i'm |i am |we're |we are )?(?:ever so |very |so |really |most |much |truly )?"
    r"(?:grateful|obliged|thankful|appreciated)(?: (?:to you|indeed))?\s*[.!]*\s*$",
    _F,
)


def _kindly_verbs29s(text: str, _lexicon: Lexicon) -> str:
    """'would you mind letting …', 'tidy X away into S', '…, ever so grateful' (above)."""
    text = _MIND_LETTING29S.sub("could you let", text)
    text = _GRATEFUL29S.sub(".", text)
    return _TIDY_AWAY29S.sub(lambda m: f"put {m['what']} {m['where']}", text)


# A person said, then taken up by 'he' / 'she' / 'they' as the subject of a want or a getting
# ("Bottle goes to Person A. And Person B, she gets the chips."): the pronoun repeats the person
# (session 11's "Mr Novak he want lemon" at the text's start), after 'and' / 'then' too; the
# person must be one whole name of the scene and the verb one of having or wanting.
_DISLOCATED29S = (
    rf"(?P<lead>(?:^|(?<=[.;!?])\s*|,\s*)(?:and |then |and then )?)(?P<who>{_PERSON28S}),? "
    r"(?:he|she|they) (?=(?:gets|get|wants|want|needs|need|has|have|would like|'d like|can have|"
    r"should get|should have|is getting|is having|'s getting|'s having|'ll have|will have)\b)"
)


# … and owning it: "Person B, the chips are his." is 'Person B gets the chips' (the object one
# whole name of one object of the scene)
_DISLOCATED_OWNER29S = (
    rf"(?P<lead>(?:^|(?<=[.;!?])\s*|,\s*)(?:and |then |and then )?)(?P<who>{_PERSON28S}),\s*"
    r"(?P<what>the [a-z]+(?: [a-z]+)?) (?:is|are|'s|'re) (?:his|hers|theirs)(?=\s*(?:[,.;!?]|$))"
)


def _dislocated29s(text: str, lexicon: Lexicon) -> str:
    """'And Person B, she gets the chips': 'And Person B gets the chips'; 'Person B, the chips
    are his': 'Person B gets the chips' (above)."""
    text = _for_person29s(_DISLOCATED29S, text, lexicon, lambda m: f"{m['lead']}{m['who']} ")
    return _for_person29s(
        _DISLOCATED_OWNER29S, text, lexicon, lambda m: f"{m['lead']}{m['who']} gets {m['what']}"
    )


# A correction taken back at once ("Bottle to Person A, no, wait, yes, that's right, Person A,
# carry on.", "Give Person A the bottle, no wait, yeah, that's right, the bottle.", "Person A,
# the bottle — no, yes, the bottle, that's right.", "Bottle to, no hang on, yes, Person A, it's
# only her."): 'no … yes' leaves what was said as it was, and what follows says it again. The
# words after 'yes' must be one name of the scene that the clause before the cue names already
# (the same things), or, where that clause stops at 'to' / 'for' / 'on', the name it stops before;
# what may close it: "that's right", 'carry on', 'go on', "it's only her / him". Anything else
# after 'yes' (another name, more requests) is left, and refused as before.
_NO_YES29S = re.compile(
    r"(?P<head>^[^.!?;]*?)\s*(?:,|—|–|\s-)\s*(?:no|nope)(?:,?\s*(?:wait|hang on|hold on))?\s*,?\s*"
    r"(?:yes|yeah|yep)(?:,?\s*(?:that's|that is) (?:right|it|correct))?\s*,\s*"
    r"(?P<again>[^,.!?—–]+?)(?:\s*,\s*(?:that's right|that is right|carry on|go on|it's only "
    r"(?:her|him|them)))?\s*(?P<end>[.!]?)\s*$",
    _F,
)


def _no_yes29s(text: str, lexicon: Lexicon) -> str:
    """'Bottle to Person A, no, wait, yes, that's right, Person A': 'Bottle to Person A' (above)."""
    m = _NO_YES29S.match(text)
    if m is None:
        return text
    head, again = m["head"].strip(), m["again"].strip()
    said = _ids(again, lexicon)
    whole = next((k for k in ("human", "object", "surface") if _only_kind(again, lexicon, k)), None)
    if whole is None or not said:
        return text
    if re.search(r"\b(?:to|for|on|onto)$", head, _F):
        return f"{head} {again}{m['end'] or '.'}"
    return f"{head}{m['end'] or '.'}" if said <= _ids(head, lexicon) else text


# "The chips are not for Person A, (I tell you,) they are for Person B": the object is said not
# to be one person's and then to be another's; the second says it all ('the chips are for Person
# B'). The two must be different people of the scene, each one whole name, and 'they' / 'it' must
# take up the object ("…, they are for Person B"); an aside of the speaker's between ('I tell
# you', 'mind') is let be. Without the second clause (only 'not for Person A') it stays refused.
_NOT_FOR_BUT29S = re.compile(
    rf"^(?P<what>the [a-z]+(?: [a-z]+)?) (?P<be>is|are|'s|'re)(?: not|n't) for (?P<no>{_PERSON28S})"
    r"\s*,\s*(?:(?:i tell you|mind|honestly|i'm telling you|you know)\s*,\s*)?(?:but )?"
    rf"(?:they|it)(?:'re|'s| are| is) for (?P<who>{_PERSON28S})(?P<end>\s*(?:[,.!]|$))",
    _F,
)


def _not_for_but29s(text: str, lexicon: Lexicon) -> str:
    """'The chips are not for Person A, they are for Person B': 'The chips are for Person B'."""
    m = _NOT_FOR_BUT29S.match(text)
    if m is None or not _only(m["no"], lexicon, "human") or not _only(m["who"], lexicon, "human"):
        return text
    if _ids(m["no"], lexicon) == _ids(m["who"], lexicon):
        return text
    return f"{m['what']} {m['be']} for {m['who']}{m['end']}{text[m.end() :]}"


# A want said once for two people ("Person B asked for the bottle and Person A for the chips",
# "sam's asked for the notepad and priya for the stapler"): the second person's 'for' takes the
# first's verb, as session 19's '… wants the chips, and after that Person A for the bottle'.
_ASKED_AND29S = (
    rf"(?P<first>\b(?:{_PERSON28S})(?: has|'s)? asked for (?:the |a |an )?[a-z]+(?: [a-z]+)?,? and "
    rf")(?P<who>{_PERSON28S}) for (?=(?:the|a|an) )"
)


def _asked_and29s(text: str, lexicon: Lexicon) -> str:
    """'Person B asked for the bottle and Person A for the chips': '… and Person A asked for'."""
    return _for_person29s(
        _ASKED_AND29S, text, lexicon, lambda m: f"{m['first']}{m['who']} asked for "
    )


# What a placement is for, closing the text ("Put the tape on the belt, and the gloves too, ready
# for the next shift.", "Put the globe on the desk ready for geography."): 'ready for …' says why
# the objects go there, and is taken off when the request puts something on a surface and the
# words name nothing in the scene and hold no word that could ask, point or count (the speaker's
# times aside: 'the next shift'). 'ready for Zoe', 'ready for it' are left.
_READY_FOR29S = re.compile(
    r"(?:\s*,\s*|\s+)(?:all |nice and )?ready for (?P<what>[a-z' -]+?)\s*(?P<end>[.!]?)\s*$", _F
)


def _ready_for29s(text: str, lexicon: Lexicon) -> str:
    """'…, ready for the next shift': taken off after a placement (above)."""
    m = _READY_FOR29S.search(text)
    if m is None or not _ids(text[: m.start()], lexicon, "surface"):
        return text
    what = _SPEAKER_TIMES.sub(" ", f"for {m['what']}")
    if _REMARK_HELD.search(what.replace("for ", " ", 1)) or not _names_nothing(m["what"], lexicon):
        return text
    return f"{text[: m.start()]}{m['end'] or '.'}"


# The speaker asking pardon for the state of things ("so excuse the flour on everything", "so
# forgive the mud on my boots"): an apology, asking nothing; taken off as a clause of its own when
# what is excused names nothing in the scene (nor by a typo). 'excuse the cup' (an object) is left.
_EXCUSE_THE29S = re.compile(
    r"(?P<lead>(?:^|(?<=[.!?,]))\s*)(?:(?:so|and|but|oh)\s+)?(?:please\s+)?(?:excuse|forgive|pardon|"
    r"ignore) (?:the|my|all the|this) (?P<what>[a-z]+(?: [a-z]+)?)(?: (?:on|in|all over|over) "
    r"(?P<where>everything|the floor|the place|my [a-z]+|me))?\s*(?=[.!?]|,|$)",
    _F,
)


def _excuse_the29s(text: str, lexicon: Lexicon) -> str:
    """'so excuse the flour on everything': taken off (above)."""

    def said(m: re.Match[str]) -> str:
        words = f"{m['what']} {m['where'] or ''}".replace("everything", "")
        if _REMARK_HELD.search(words) or not _names_nothing(words, lexicon):
            return m.group(0)
        return m["lead"]

    out = _sub(_EXCUSE_THE29S.pattern, said, text)
    if out == text:
        return text
    out = re.sub(r"^\s*[,.!]\s*|(?<=[.!?])\s*[,.]\s*|,\s*(?=[.!?])", " ", out).strip()
    return out if out != text.strip() and _names(out, lexicon) else text


# A sentence opening with 'Sorry' / 'Hang on' / 'Actually' could correct the sentence before it or
# add to it (the session-19 rule refuses it); said with what makes it a correction, it is one
# ("Bottle to Person B. Hang on, I misspoke, chips to Person B.", "Bob wants the cup. Sorry, my
# mistake, it's the apple he wants.", "Lemon to Mr Novak. Hang on, not the lemon, the salt.",
# "The banana for Omar. Actually, change that to Dana."): the grammar's ', no, …'. The owning of
# the slip ('my mistake', 'I misspoke', 'I misheard her', "I've got that wrong"), 'not <what was
# said>', or 'change that to' must follow the cue at once; 'not the X' must name an object the
# sentence before names. "it's the apple he wants" after it is 'the apple' (a cleft of the want).
_OPENS_A_FIX29S = re.compile(
    r"(?P<stop>[.!]\s+)(?:oh,?\s*|er,?\s*|um,?\s*)?(?:sorry|so sorry|hang on|hold on|actually|wait)"
    r"\s*,\s*(?:(?P<slip>my mistake|my bad|i misspoke|i misspeak|i misheard (?:her|him|them|you)|"
    r"i(?:'ve| have)? got (?:that|it) wrong|i said (?:that|it) wrong)\s*,\s*|"
    r"(?P<not>not (?P<said>the [a-z]+(?: [a-z]+)?)\s*,\s*)|change (?:that|it) to\s+)",
    _F,
)
_CLEFT_WANT29S = re.compile(
    r"^it(?:'s| is) (?P<what>the [a-z]+(?: [a-z]+)?) (?:he|she|they) (?:wants?|needs?|'s after|"
    r"asked for)(?P<end>\s*[.!]?\s*)$",
    _F,
)


def _opens_a_fix29s(text: str, lexicon: Lexicon) -> str:
    """'X. Hang on, I misspoke, chips to Person B.': 'X, no, chips to Person B.' (above)."""
    m = _OPENS_A_FIX29S.search(text)
    if m is None:
        return text
    head, rest = text[: m.start()], text[m.end() :]
    if m["not"] and not _ids(m["said"], lexicon, "object") <= _ids(head, lexicon, "object"):
        return text
    if m["not"] and not _ids(m["said"], lexicon, "object"):
        return text
    cleft = _CLEFT_WANT29S.match(rest)
    if cleft is not None:
        rest = f"{cleft['what']}{cleft['end']}"
    if not rest.strip(" .!") or ("change" in m.group(0).lower() and not _names(rest, lexicon)):
        return text
    to = "to " if "change" in m.group(0).lower() and not re.match(r"(?:to|for)\b", rest, _F) else ""
    return f"{head}, no, {to}{rest}"


# a correction before the slip owned at the end
_CUE_BEFORE29S = re.compile(
    rf"[,.!]\s*(?:{_CUE19}|no|nope|nah|wait|hang on|hold on|actually)\s*[,.!]", _F
)


def _slip_owned29s(text: str, lexicon: Lexicon) -> str:
    """The speaker owning a slip (above): taken off after a correction, or said as its cue."""
    last = _SLIP_LAST29S.search(text)
    if last is not None:
        head = text[: last.start()]
        if _CUE_BEFORE29S.search(head) and _names(head, lexicon):
            return head + "."
        return text
    cue = _SLIP_CUE29S.search(text)
    if (
        cue is None
        or not _names(text[: cue.start()], lexicon)
        or not text[cue.end() :].strip(" .!")
    ):
        return text
    if _CUE_LAST29S.search(text[: cue.start()]):
        return f"{text[: cue.start()]}, {text[cue.end() :]}"  # the cue said just before it
    if not _CUE_BEFORE29S.search(text[: cue.start()] + ","):  # else the cue is one already
        return f"{text[: cue.start()]}, no, {text[cue.end() :]}"
    return text


# -- session 29 (engineer 12r) -------------------------------------------------------------------

# Words that say 'no' (colloquial 'nah', 'naw', 'nope', 'nuh-uh', 'uh-uh'; Scots 'nae'; German
# 'nein', French 'non'),
# said as a stretch of their own: the correction cue 'no' ("Give Alice the cup. Nah, the apple.").
# 'na' is 'nah' only opening a sentence: after a comma it may be Hindi English's tag ('…, na?',
# isn't it; _tag28), so before more words it is refused with both readings.
_NO_WORD29R = re.compile(
    r"(?:(?<=^)|(?<=[,.!?;:]\s)|(?<=[,.!?;:]))(nah|naw|nope|nuh-uh|uh-uh|nae|nein|non)"
    r"(?=\s*[,.!?;:]|\s*$)",
    _F,
)
_NA_OPENS29R = re.compile(r"(?:(?<=^)|(?<=[.!?]\s)|(?<=[.!?]))(na)(?=\s*[,.!;:]|\s*$)", _F)
_NA_BETWEEN29R = re.compile(r",\s*na\s*,\s*(?=\S)", _F)
# a sentence that is only a word saying 'no' ("Give Alice the cup. Nah."): never inert
_NO_ALONE29R = re.compile(
    r"^\s*(?:(?:oh|ah|um|er|erm|hmm)\s*,?\s*)?(?:na|nah|naw|nope|nuh-uh|uh-uh|nae|nay|nein|non|no)"
    r"\s*[.!]*\s*$",
    _F,
)


def _inert_stretches(text: str, lexicon: Lexicon) -> str:
    """What is left when every provably inert stretch is taken off, if the grammar reads it
    (else the text as it is)."""
    if "?" in text or "(" in text:
        return text
    parts = re.split(r"(\s*(?:[,;:!—–]|\.(?=\s|$)|\s-\s)\s*)", text.strip())
    chunks, seps = parts[0::2], parts[1::2]
    if len(chunks) < 2:
        return text
    common = _COMMON

    def inert(chunk: str) -> bool:
        words = re.findall(r"[a-z']+", chunk.lower())
        if not words or re.search(r"\d", chunk) or _NO_ALONE29R.match(chunk):
            return False  # a number; 'uh-uh' (no, session 29)
        plain = [re.sub(r"'(?:s|ll|re|d|ve|m)$", "", w) for w in words]
        return (
            all(w in common or w in _INERT_WORDS for w in plain)
            and all(
                w in _INERT_WORDS or w in _CLOSING_WORDS or w in _ADDRESS or w in _MANNER
                for w in plain
            )
            and not any(_held_word(w, lexicon) for w in plain)
            and _names_nothing(chunk, lexicon)
        )

    keep = [not inert(c) if c.strip() else False for c in chunks]
    if all(keep) or not any(keep):
        return text
    out = ""
    for k, (c, on) in enumerate(zip(chunks, keep, strict=True)):
        if not on:
            continue
        if out:
            sep = seps[k - 1] if k - 1 < len(seps) else ", "
            out += sep if sep.strip() else ", "
        out += c
    out = out.strip(" ,;:—–-")
    # why: offline.py imports this module, so the grammar is imported where it is used
    from hltl.grounding.offline import parse_instruction

    # Session 52 (12p): what is left read first — the text is kept where it does not read (as
    # where the text reads as it is), so the text is read only where what is left reads (the
    # same answer: on blind22, blind45 and blind50 what is left never read, and the text's own
    # read, failing 359 times in 393, was ~0.2 ms an instruction)
    try:
        parse_instruction(out, lexicon.scene, lexicon, normalise=False)
    except GroundingError:
        return text
    try:
        parse_instruction(text, lexicon.scene, lexicon, normalise=False)
        return text  # read as it is: nothing to take off
    except GroundingError:
        return out


def _inert_sentence(sentence: str, lexicon: Lexicon) -> bool:
    if sentence.rstrip().endswith("?"):
        return False  # "Now, where was I? Oh yes, …": a question the next sentence answers
    if _NO_ALONE29R.match(sentence):
        return False  # "Give Alice the cup. Nah.": 'no' said after the request (session 29)
    plain = _THANKED.sub("thanks", sentence)
    plain = _rx(r"\bi'?m (?:only|just) [a-z]+ing\b").sub("i am", plain)
    plain = _rx(r"^(?:come|over) here\b").sub("", plain)
    # "Postdoc here.", "Night porter here!": who speaks, said as a sentence of its own
    plain = _rx(r"^((?:it's |this is )?[a-z]+(?: [a-z]+)?) here(?=\s*[.!]*$)").sub(r"\1", plain)
    return (
        bool(re.search(r"[a-z]", plain, _F))
        and not _SENTENCE_HELD.search(plain)
        and not _POINTING.search(plain)
        and not _asks30s(plain)
        and _names_nothing(plain, lexicon)
    )


def _inert_sentences(text: str, lexicon: Lexicon) -> str:
    """Every sentence of ``text`` that _inert_sentence finds inert taken off (when another is
    left)."""
    parts = re.split(r"(?<=[.!?])\s+", text.strip())
    if len(parts) < 2:
        return text
    keep = [p for p in parts if not _inert_sentence(p, lexicon)]
    if not keep or len(keep) == len(parts):
        return text
    return " ".join(keep)


def _chat_token(word: str, lexicon: Lexicon) -> bool:
    """A short token that is no English word and no first name ('gg', 'rn', 'tysm'): chat, not a
    thing asked for (an object the scene lacks has a name a dictionary holds)."""
    low = word.lower()
    return (
        low.isalpha()
        and 2 <= len(low) <= 4
        and low not in _COMMON
        and low not in _scene_words(lexicon.scene)
        and low not in TITLES
        and not _near_verb(low)
        and low not in first_names()
        and not _held_word(low, lexicon)
        and not _NO_ALONE29R.match(low)  # 'na', 'nae': 'no' (session 29)
        and _names_nothing(word, lexicon)
    )


def _word_edges18(text: str, lexicon: Lexicon) -> str:
    """Chat tokens and idioms said without punctuation at the very start or end ('lmao ok give
    person b the bottle lol tysm', '… to person a rn', '… when ur free') taken off."""
    words = text.split()
    if len(words) < 3:
        return text
    # session 55 (12p): where no stretch can be an idiom (the gate finds none of their words in
    # the words joined), only a chat token of one word is asked for
    idioms = _word_idiom_may(" ".join(words))
    start, stop = 0, len(words)
    for _ in range(4):
        moved = False
        for n in (5, 4, 3, 2, 1):
            if stop - start - n < 2 or (n > 1 and not idioms):
                continue
            tail = " ".join(words[stop - n : stop])
            bare = tail.strip(" .!?,").lower()
            if (n == 1 and _chat_token(bare, lexicon)) or (idioms and _word_idiom(tail, lexicon)):
                stop -= n
                moved = True
                break
        for n in (5, 4, 3, 2, 1):
            if stop - start - n < 2 or (n > 1 and not idioms):
                continue
            head = " ".join(words[start : start + n])
            bare = head.strip(" .!?,").lower()
            if (n == 1 and _chat_token(bare, lexicon)) or (idioms and _word_idiom(head, lexicon)):
                start += n
                moved = True
                break
        if not moved:
            break
    if (start, stop) == (0, len(words)):
        return text
    while stop - start > 2 and words[stop - 1].lower() in ("and", "so"):
        stop -= 1  # "… to bob and then we're finished": the 'and' of what was taken off
    end = words[-1][-1] if words[-1][-1] in ".!?" else ""
    return " ".join(words[start:stop]).rstrip(",;:") + end


def _edges18(text: str, lexicon: Lexicon) -> str:
    """Stretches at either edge of the request (and whole sentences) that are idioms of address,
    greeting, sign-off, hurry or an auctioneer's calls, or chat tokens only, taken off when
    something is left."""
    text = _word_edges18(text, lexicon)
    parts = _STRETCH.split(text.strip())
    chunks, seps = parts[0::2], parts[1::2]
    if len(chunks) < 2:
        return text

    def inert(chunk: str) -> bool:
        if not chunk.strip():
            return True
        if re.search(r"\d", chunk):
            return False  # 'r2, …': a robot, a number
        if _idiom_stretch(chunk, lexicon):
            return True
        words = re.findall(r"[a-z']+", chunk.lower())
        return bool(words) and all(_chat_token(w, lexicon) for w in words)

    drop = [inert(c) for c in chunks]
    if all(drop) or not any(d and c.strip() for d, c in zip(drop, chunks, strict=True)):
        return text
    # only the edges: the stretches before the first and after the last one kept, and any
    # stretch that is a whole sentence of its own
    first = drop.index(False)
    last = len(drop) - 1 - drop[::-1].index(False)
    keep_idx = []
    for k, c in enumerate(chunks):
        if not drop[k] or not c.strip():
            if c.strip():
                keep_idx.append(k)
            continue
        before = seps[k - 1] if k else "."
        after = seps[k] if k < len(seps) else "."
        whole = before.strip()[-1:] in ".!?…" and after.strip()[:1] in (".", "!", "?", "…", "")
        if first < k < last and not whole and not _idiom_stretch(c, lexicon):
            keep_idx.append(k)
    if len(keep_idx) == len([c for c in chunks if c.strip()]):
        return text
    out = chunks[keep_idx[0]]
    for prev, k in itertools.pairwise(keep_idx):
        between = seps[prev:k]
        stop = next((x.strip() for x in between if x.strip()[:1] in ".!?…"), "")
        dropped = [c for c in chunks[prev + 1 : k] if c.strip()]
        if (
            not stop
            and dropped
            and all(_HESITATION.match(c.strip()) for c in dropped)
            and not re.match(r"\s*(?:no|sorry|wait|actually|i mean|hang on)\b", chunks[k], _F)
            and re.search(r"\b(?:the|a|an|to|on|in|into|onto|my|his|her|their)\s*$", out, _F)
        ):
            out += " "  # "give the, uh, banana": the words round a hesitation are one phrase
        else:
            out += f"{stop[:1]} " if stop else (between[-1] if between[-1].strip() else ", ")
        out += chunks[k]
    tail = seps[keep_idx[-1]].strip() if keep_idx[-1] < len(seps) else ""
    return out.strip(" ,;:—–-") + (tail[:1] if tail[:1] in (".", "!", "?") else "")


def _trailing_remark34(text: str, lexicon: Lexicon) -> str:
    """Session 34: the closing comma part above taken off when it opens as a remark, is inert by
    both tests and of three words or more, and what is left, one sentence, names a person or
    surface."""
    m = _TRAILING34.search(text)
    if m is None or len(m["said"].split()) < 3:
        return text
    said = m["said"]
    if not _REMARK_SUBJECT.match(said.strip()) or _TRAILING_HELD34.search(said):
        return text
    if not _inert_sentence(said, lexicon):
        return text
    rest = text[: m.start()]
    if re.search(r"[.!?;:]", rest) or not _ids(rest, lexicon, "human") | _ids(
        rest, lexicon, "surface"
    ):
        return text
    return rest + m["end"].strip()


_STEPS34: tuple[Callable[[str, Lexicon], str], ...] = (
    _speaker_parts34,
    _trailing_remark34,
    _thanks_from34,
    _idioms34,
    _what_like34,
    _if_spare34,
    _after_doing34,
    _trade_tells34,
    _for_his34,
    _as_for34,
    _handover_frames34,
    _see_the34,
    _since_wanted34,
    _what_waiting34,
    _run_on_remarks34,
    _where_she_is34,
    _from_trade34,
    _has_coming34,
    _been_at34,
    _to_do34,
    _mind_if34,
    _questions34,
    _size_words34,
    _over_and34,
    _verb_last34,
    _done_with34,
    _do_that34,
    _mid_aside34,
)


def _speaker_stretch(
    piece: str, spoke: bool, lexicon: Lexicon, *, right_after: bool = False
) -> bool:
    """Whether ``piece`` is the speaker talking about themself (or, after such a stretch in its
    sentence, ``spoke``, what they are doing; right after one, ``right_after``, a warning about
    their own things or a sentence that asks nothing), naming nothing in the scene and asking
    nothing."""
    piece = piece.strip(" .!?")
    if (
        not piece
        or _held_but_times(piece)
        or not _names_nothing(_NOT_A_THING29S.sub(" ", piece), lexicon)
    ):
        return False
    return bool(
        _SPEAKER_OPEN.match(piece)
        or (spoke and _SPEAKER_MORE.match(piece) and not _speaker_more_held(piece, lexicon))
        or (right_after and (_MIND_MINE.match(piece) or _inert_sentence(piece, lexicon)))
    )


def _opener(piece: str, lexicon: Lexicon) -> bool:
    """Whether ``piece`` opening a remark's sentence asks nothing (an interjection, a greeting, an
    apology, a warning about the speaker's things, a sentence inert by itself)."""
    piece = piece.strip()
    if _SPEAKER_OPENER.fullmatch(piece) or _MIND_MINE.match(piece):
        return _names_nothing(piece, lexicon) and not _SPEAKER_HELD.search(piece)
    return _inert_sentence(piece, lexicon) and not _SPEAKER_HELD.search(piece)


def _no_words29r(text: str, lexicon: Lexicon) -> str:
    """Session 29 (12r): a word that says 'no', standing alone between marks, is the cue 'no',
    whose grammar (a correction, or a refusal of one that names nothing) then reads it; taken off
    as a filler it had read "Give Alice the cup. Na, the apple." as both objects. A word the scene
    names is left as it is."""
    words = _scene_words(lexicon.scene)

    def no(m: re.Match[str]) -> str:
        said = m.group(1)
        if said.lower() in words:
            return said
        return "No" if said[:1].isupper() else "no"

    out = _NA_OPENS29R.sub(no, _NO_WORD29R.sub(no, text))
    m = _NA_BETWEEN29R.search(out)
    if m is not None and "na" not in words:
        raise GroundingError(
            f"{m.group(0).strip(' ,')!r} between commas could be 'nah' (no: what follows replaces "
            "what was said before it) or a tag asking 'isn't it' (what follows is one more "
            "request): say 'no, …' or 'and …'"
        )
    return out


# a reason said after a correction's cue (as _CUE_REASON28R), with the cues that one left: plain
# 'no' and 'wait / hang on / hold on, no' after a comma or opening a sentence ("Give Person A the
# chips. Wait, no, she's fasting; the bottle instead."), the reason closed by a comma or a
# semicolon, and 'so' after it ("…, hang on, no, Alice is the thirsty one, so to Alice")
_CUE_REASON29R = re.compile(
    rf"(?:(?<=,)|(?<=[.!?]))\s*(?P<cue>{_CUE19}|(?:(?:wait|hang on|hold on),? )?no)\s*,\s*"
    r"(?P<why>[^,.;:!?]+?)\s*[,;]\s*(?P<so>so,?\s+)?(?=\S)",
    _F,
)


def _cue_reason29r(text: str, lexicon: Lexicon) -> str:
    """Session 29 (12r): a reason between a correction's cue and the corrected words is taken
    off, as _cue_reason28r's, for the cues and marks that one left. The reason may name a person
    only when the corrected words name that person again (it says why they get it: "…, no,
    Alice is the thirsty one, so to Alice"); never an object, nor words that ask, negate, add,
    choose or order, nor when the corrected words hold a pronoun it could have given a person."""
    m = _CUE_REASON29R.search(text)
    if m is None:
        return text
    why, after = m.group("why"), text[m.end() :]
    if not _STATEMENT28R.fullmatch(why) or _NOT_REASON28R.search(why):
        return text
    if _ids(why, lexicon, "object") or _PRONOUN28R.search(after):
        return text
    if _PLACED_WHY43L.search(why) and _ids(why, lexicon, "surface"):
        # session 43 (lead, 12c's fuzz): "Cup over to Bob, sorry, it's meant to go on the shelf,
        # thanks." — a 'reason' saying the thing goes on a place of the scene is the correction
        return text
    people = _ids(why, lexicon, "human")
    if people and (len(people) != 1 or people != _ids(after, lexicon, "human")):
        return text
    if m.group("so") and not people:
        return text  # '…, no, she's fasting, so …': 'so' ties what follows to her
    return text[: m.start("why")] + after


# what a correction's cue says again of itself ("no, that's wrong, …", "no, I got that wrong,
# …"), then the corrected object said in a cleft: "…, no, it's the bottle she asked for."
_CLEFT29R = re.compile(
    r"(?P<cue>,\s*no,)\s*(?:(?:that's|that is|i got that|i had that) wrong,\s*)?"
    r"(?:it's|it is|it was) (?P<said>(?:the|that) [a-z ]+?) (?:asked for|wants|wanted|needs|"
    r"needed|ordered|meant|said)\s*(?=[.!]?$)",
    _F,
)


def _cleft29r(text: str, lexicon: Lexicon) -> str:
    """Session 29 (12r): "Pass Person B the chips, no, that's wrong, it's the bottle she asked
    for." — a correction that names the object in a cleft ('it's X she asked for') is the
    grammar's '…, no, X.', when the words before name exactly one person and the cleft's subject
    is that person (a pronoun that may be hers, or her name); 'that's wrong' after the cue says
    it again."""
    m = _CLEFT29R.search(text)
    if m is None:
        return text
    before = text[: m.start()]
    people = _ids(before, lexicon, "human")
    if len(people) != 1:
        return text
    words = m.group("said").split(" ")
    for n in (1, 2):
        obj = " ".join(words[:-n])
        obj = re.sub(r" (?:that|which)$", "", obj, flags=_F)
        who = " ".join(words[-n:])
        if len(_ids(obj, lexicon, "object")) != 1 or not _only_kind(obj, lexicon, "object"):
            continue
        if who.lower() in ("she", "he", "they"):
            if not _fits(next(iter(people)), who, lexicon):
                return text
        elif _ids(who, lexicon, "human") != people or not _only_kind(who, lexicon, "human"):
            continue
        return f"{before}{m.group('cue')} {obj}{text[m.end() :]}"
    return text


# how a choice of objects for one person is to be made, said after it: "…, whichever comes to
# hand", "…; pick whichever you can reach", "…, grab whichever is nearer"
_CHOICE_TAIL29R = re.compile(
    r"\s*[,;]\s*(?:(?:just |so )?(?:pick|take|grab|choose|use) )?whichever(?: one)?(?:'s| is)? "
    r"(?:comes to hand|you can reach(?: first)?|you reach first|is nearer(?: to you)?|is closer|"
    r"is easier to reach|you can get to|you get to first)(?=\s*(?:[,.!?]|$))",
    _F,
)


def _choice_tail29r(text: str, lexicon: Lexicon) -> str:
    """Session 29 (12r): how the robots pick among objects offered to one person ('whichever
    comes to hand', 'pick whichever you can reach') is taken off when what is left reads as
    exactly one such choice (as _who_chooses28r's 'whichever's easier'); after anything else
    (one object, a choice of people) it is left, and refused."""
    m = _CHOICE_TAIL29R.search(text) if "whichever" in text.lower() else None
    if m is None:
        return text
    out = text[: m.start()] + text[m.end() :]
    return out if _one_choice28r(_reading(out, lexicon), False) else text


# "Mia only needs one of them, …": 'only' between the person and what they want
_ONLY_NEEDS29R = re.compile(
    r"^(?P<p>[A-Za-z][\w ]*?) only (?P<v>needs|wants|requires|would like|asked for)\b", _F
)
# "… one of them, the tape or the gloves": 'them' said before what it stands for
_ONE_OF_THEM29R = re.compile(
    r"\b(?:one|either) of them,\s*(?P<list>(?:the |a |an )?[a-z ]+? or (?:the |a |an )?[a-z ]+?)"
    r"(?=\s*(?:[,.;!?]|$))",
    _F,
)
# "Give Ava any one toy, the teddy or a block, …": a word for the kind, then the choice itself
_ANY_ONE29R = re.compile(
    r"\bany (?:one |single )?(?P<kind>[a-z]+),\s*(?P<list>(?:the |a |an )?[a-z ]+? or "
    r"(?:the |a |an )?[a-z ]+?)(?=\s*(?:[,.;!?]|$))",
    _F,
)


def _only_needs29r(text: str, lexicon: Lexicon) -> str:
    """Session 29 (12r): 'P only needs / wants …' is 'P needs / wants …': 'only' keeps to what
    is named, as the grammar does ('Mia only' had been read as a name)."""
    m = _ONLY_NEEDS29R.match(text)
    if m is None or not _only_person(m.group("p"), lexicon):
        return text
    return f"{m.group('p')} {m.group('v')}{text[m.end() :]}"


def _choice_said29r(text: str, lexicon: Lexicon) -> str:
    """Session 29 (12r): a choice said with a word before it that the list then says again:
    'one of them, X or Y' (with no object named before 'them') and 'any one <kind>, X or Y' (the
    kind a word for things the scene has no name for, or the kind of X and Y) are 'X or Y'. Each
    taken only where the result reads as one choice of objects for one person."""
    out = _only_needs29r(text, lexicon)
    m = _ONE_OF_THEM29R.search(out)
    if m is not None and not _ids(out[: m.start()], lexicon, "object"):
        out = out[: m.start()] + m.group("list") + out[m.end() :]
    m = _ANY_ONE29R.search(out)
    if m is not None:
        kind = _ids(m.group("kind"), lexicon, "object")
        listed = _ids(m.group("list"), lexicon, "object")
        if (not kind and _names_nothing(m.group("kind"), lexicon)) or (listed and listed <= kind):
            out = out[: m.start()] + m.group("list") + out[m.end() :]
    if out == text:
        return text
    return out if _one_choice28r(_reading(out, lexicon), False) else text


# "There's only one bottle, and Person A should have it"
_ONLY_ONE29R = re.compile(
    r"^there's (?:only |just )?(?:a single|the one|one|just the one) (?P<x>[a-z ]+?),\s*and "
    r"(?P<p>[A-Za-z][\w ]*?) (?:should have|should get|can have|gets|is to have|wants|needs) "
    r"it(?P<end>\s*[.!]?)$",
    _F,
)


def _only_one29r(text: str, lexicon: Lexicon) -> str:
    """Session 29 (12r): "There's only one X, and P should have it" is the X to P (as session
    18's "There's only one X, and it's for P"), when the scene has one X and P names one
    person."""
    m = _ONLY_ONE29R.match(text)
    if m is None or len(_ids(m.group("x"), lexicon, "object")) != 1:
        return text
    if not _only(m.group("x"), lexicon, "object") or not _only_person(m.group("p"), lexicon):
        return text
    return f"the {m.group('x')} to {m.group('p')}{m.group('end')}"


# "Something each for the two oceanographers: …", "One thing each for them: …"
_EACH_FOR29R = re.compile(
    r"^(?:something|one thing|a thing|an item|one item) (?:each|apiece) for (?:the "
    r"(?P<n>two|three) [a-z]+s|them|the (?P<m>two|three) of them|both of them)\s*:\s*"
    r"(?P<rest>\S.*)$",
    _F,
)


def _each_for29r(text: str, lexicon: Lexicon) -> str:
    """Session 29 (12r): 'Something each for the two <role>s: <list>' (the role any word; the
    people are those the list names) is the list, when it hands each of that many people (every
    person of the scene when no number is said) exactly one object; "P's to get X" in it is 'P
    is to get X'."""
    m = _EACH_FOR29R.match(text)
    if m is None:
        return text
    rest = _sub(
        r"\b(person [a-z]|[A-Z][a-z]+)'s to (get|have|receive)\b", r"\1 is to \2", m["rest"]
    )
    rest = rest[:1].upper() + rest[1:]
    node = _reading(rest, lexicon)
    if node is None or not isinstance(node, Group) or node.op != "and":
        return text
    said = list(tasks(node))
    people = [t.target for t in said]
    if any(t.kind != "deliver" for t in said) or len(set(people)) != len(people):
        return text
    n = m.group("n") or m.group("m")
    want = _COUNTS[n.lower()] if n else len(lexicon.scene.humans)
    return rest if len(people) == want else text


# "Split the two items between Person A and Person B, one apiece."
_SPLIT29R = re.compile(
    r"^(?:please )?(?:split|share|divide) (?P<x>the [a-z ]+?) between (?P<p>[A-Za-z][\w ]*?) and "
    r"(?P<q>[A-Za-z][\w ]*?),\s*one (?:apiece|each)(?P<end>\s*[.!]?)$",
    _F,
)


def _split29r(text: str, lexicon: Lexicon) -> str:
    """Session 29 (12r): 'Split X between P and Q, one apiece' is 'Give P and Q one of X each'
    (the choice of the ways to give each one), when X names exactly two objects and P and Q two
    people."""
    m = _SPLIT29R.match(text)
    if m is None or len(_ids(m.group("x"), lexicon, "object")) != 2:
        return text
    p, q = m.group("p"), m.group("q")
    if not (_only_person(p, lexicon) and _only_person(q, lexicon)):
        return text
    if _ids(p, lexicon) == _ids(q, lexicon):
        return text
    return f"Give {p} and {q} one of {m.group('x')} each{m.group('end')}"


# "One blanket for each of the two patients, whichever way round."
_EACH_OF_N29R = re.compile(
    r"\b(?P<one>one|an?) (?P<x>[a-z]+) for each of the (?P<n>two|three) (?P<role>[a-z]+)s"
    r"(?P<way>,\s*(?:whichever|either|any) way round)?(?=\s*[.!]?$)",
    _F,
)


def _each_of_n29r(text: str, lexicon: Lexicon) -> str:
    """Session 29 (12r): 'One X for each of the two <role>s' is 'one X for each <role>' when the
    scene has that many people called so; 'whichever way round' after it says the choice it
    already is."""
    m = _EACH_OF_N29R.search(text)
    if m is None:
        return text
    role = m.group("role").lower()
    people = [h for h in lexicon.scene.humans if role in (a.lower() for a in h.aliases)]
    if len(people) != _COUNTS[m.group("n").lower()]:
        return text
    return f"{text[: m.start()]}{m.group('one')} {m.group('x')} for each {role}{text[m.end() :]}"


# "None of it to Person A; …", "Nothing for Person A, …"
_NONE_FOR29R = re.compile(
    r"^(?:none of (?:it|them|that|those)|nothing|not a thing) (?:goes |is )?(?:to|for) "
    r"(?P<p>[A-Za-z][\w ]*?)\s*[;,:.]\s*(?P<rest>\S.*)$",
    _F,
)
# "Don't leave the bottle where it is; hand it to Person A."
_LEAVE_WHERE29R = re.compile(
    r"^(?:please )?(?:don't|do not) leave (?P<x>the [a-z ]+?) (?:where it is|where they are|"
    r"lying there|sitting there|there)\s*[;,:.]\s*(?P<rest>\S.*)$",
    _F,
)


def _not_first29r(text: str, lexicon: Lexicon) -> str:
    """Session 29 (12r): what is not to be done, said first (as _not_first28r): 'None of it to
    P; …' / 'Nothing for P, …' is taken off when the request after it reads by itself, hands
    things over only, and gives P nothing; "Don't leave X where it is; hand it to P" is the
    request with 'it' for X, when it moves X and nothing else."""
    m = _NONE_FOR29R.match(text)
    if m is not None and _only_person(m.group("p"), lexicon):
        rest = m.group("rest")
        said = _tasks_of(rest, lexicon)
        if (
            said
            and all(kind == "deliver" for kind, _, _ in said)
            and not {t for _, _, t in said} & _ids(m.group("p"), lexicon)
        ):
            return rest[:1].upper() + rest[1:]
        return text
    m = _LEAVE_WHERE29R.match(text)
    if m is None or len(_ids(m.group("x"), lexicon, "object")) != 1:
        return text
    rest = m.group("rest")
    if len(re.findall(r"\bit\b", rest, _F)) != 1 or _ids(rest, lexicon, "object"):
        return text
    rest = _sub(r"\bit\b", m.group("x"), rest)
    said = _tasks_of(rest, lexicon)
    if not said or {o for _, o, _ in said} != _ids(m.group("x"), lexicon, "object"):
        return text
    return rest[:1].upper() + rest[1:]


# "Apart from the bottle, give Person B whatever's there."
_WHATEVER_THERE29R = re.compile(
    r"^(?P<ex>(?:apart from|except(?: for)?|other than|besides|bar) [^,]+,\s*[^,]*?)\bwhatever"
    r"(?:'s| is) (?:there|left|going|on offer)\b",
    _F,
)
# "Person B is welcome to the lot, …"
_WELCOME29R = re.compile(r"\b(is|are) (?:more than |very )?welcome to\b", _F)


def _all_said29r(text: str, lexicon: Lexicon) -> str:
    """Session 29 (12r): words for 'everything' the earlier rules left: 'whatever's there / left'
    after an exclusion said first ("Apart from the bottle, give Person B whatever's there"), read
    by _fronted_except28r then; 'P is welcome to X' is 'P can have X'."""
    out = _WHATEVER_THERE29R.sub(lambda m: f"{m.group('ex')}everything", text)

    def welcome(m: re.Match[str]) -> str:
        before = m.string[: m.start()]
        subject = re.split(r"[,.;:!?]", before)[-1].strip()
        return "can have" if subject and _only_person(subject, lexicon) else m.group(0)

    return _WELCOME29R.sub(welcome, out) if "welcome" in out.lower() else out


# "Mia wants all the kit except the boxes: that's the scanner, the tape and the gloves."
_ALL_KIT29R = re.compile(
    r"^(?P<p>[A-Za-z][\w ]*?) (?P<v>wants|needs|gets|should get|can have) all the (?P<w>[a-z]+) "
    r"(?:except|but|apart from|bar) (?P<x>[^:,]+?)\s*[:,]\s*(?:that's|that is|i\.e\.,?|namely|"
    r"meaning)\s+(?P<list>[^.!?]+?)(?P<end>\s*[.!]?)$",
    _F,
)


def _all_kit29r(text: str, lexicon: Lexicon) -> str:
    """Session 29 (12r): 'P wants all the <word> except X: that's A, B and C' is 'P wants A, B
    and C' when the word names nothing in the scene (or everything) and the list names exactly
    the scene's objects that X leaves: the list says again what 'all … except X' is."""
    m = _ALL_KIT29R.match(text)
    if m is None or not _only_person(m.group("p"), lexicon):
        return text
    every = {o.id for o in lexicon.scene.objects}
    word = _ids(m.group("w"), lexicon, "object")
    if (word and word != every) or (not word and not _names_nothing(m.group("w"), lexicon)):
        return text
    left = every - _ids(m.group("x"), lexicon, "object")
    listed = _ids(m.group("list"), lexicon, "object")
    if not _ids(m.group("x"), lexicon, "object") or listed != left:
        return text
    return f"{m.group('p')} {m.group('v')} {m.group('list')}{m.group('end')}"


# "The chips aren't for Person A; they're Person B's, so hand them over to Person B."
_NOT_FOR29R = re.compile(
    r"^(?P<x>the [a-z ]+?) (?:aren't|are not|isn't|is not) (?:for|meant for) "
    r"(?P<p>[A-Za-z][\w ]*?)\s*[;,]\s*(?:they're|they are|it's|it is) (?P<q>[A-Za-z][\w ]*?)'s"
    r"\s*,\s*so\s+(?P<rest>\S.*)$",
    _F,
)


def _not_for29r(text: str, lexicon: Lexicon) -> str:
    """Session 29 (12r): 'X isn't for P; it's Q's, so <request>' is the request (its 'it' /
    'them' X), when P and Q are two people and the request hands X to Q and nothing else."""
    m = _NOT_FOR29R.match(text)
    if m is None or not _only(m.group("x"), lexicon, "object"):
        return text
    p, q = m.group("p"), m.group("q")
    if not (_only_person(p, lexicon) and _only_person(q, lexicon)):
        return text
    if _ids(p, lexicon) == _ids(q, lexicon):
        return text
    rest = m.group("rest")
    if _ids(rest, lexicon, "object"):
        return text
    rest = _sub(r"\b(?:it|them)\b", m.group("x"), rest)
    said = _tasks_of(rest, lexicon)
    want = {("deliver", o, t) for o in _ids(m.group("x"), lexicon) for t in _ids(q, lexicon)}
    return rest[:1].upper() + rest[1:] if said == want else text


# "I don't mind which of your arms does it, …": which robot acts, said to the robots
_WHICH_ARM29R = re.compile(
    r"^(?:i|we) (?:don't|do not) (?:mind|care) which (?:of your arms|arm|robot|of the robots|of "
    r"you|one of you)(?: (?:does it|does that|takes it|goes|handles it))?\s*[,;:.]\s*(?=\S)",
    _F,
)
# "… the bottle needs to reach Person A": where it must end up
_REACH29R = re.compile(
    r"\b(?P<x>the [a-z ]+?) (?:needs|has|have|need) to (?:reach|get to|end up with|go to) "
    r"(?P<p>[A-Za-z][\w ]*?)(?P<end>\s*[.!]?)$",
    _F,
)


def _which_arm29r(text: str, lexicon: Lexicon) -> str:
    """Session 29 (12r): the speaker not minding which robot acts ("I don't mind which of your
    arms does it, …") asks nothing, and is taken off; 'X needs to reach P' (X one object, P one
    person) is 'X goes to P'."""
    out = _WHICH_ARM29R.sub("", text)
    m = _REACH29R.search(out)
    if (
        m is not None
        and _only(m.group("x"), lexicon, "object")
        and _only_person(m.group("p"), lexicon)
    ):
        out = f"{out[: m.start()]}{m.group('x')} goes to {m.group('p')}{m.group('end')}"
    if out == text:
        return text
    return out[:1].upper() + out[1:]


# "Kofi wants the pair of spanners tidied away: both onto the locker.", "The concierge wants two
# plates for room service: both of them onto the worktop, please."
_WANTS_PUT29R = re.compile(
    r"^(?P<who>[A-Za-z][\w' ]*?) (?:wants|needs|would like) (?P<x>(?:the |both |two |the two |"
    r"the pair of |both the )[a-z ]+?)(?: (?:tidied|put|cleared|moved|packed|stowed|taken)"
    r"(?: away| up| off)?| for (?P<why>[a-z' ]+?))?\s*:\s*(?:both|both of them|the pair|them|"
    r"all|all of them|the lot) (?P<where>(?:up )?(?:onto|on|into|in) (?:the )?[a-z ]+?)"
    r"(?:,? please)?(?P<end>\s*[.!]?)$",
    _F,
)


def _wants_put29r(text: str, lexicon: Lexicon) -> str:
    """Session 29 (12r): 'P wants X tidied away: both onto S' says what to do with X after a
    colon: put X on S. P is one person of the scene or someone it does not name (who wants it
    done, not who gets it); X names exactly two objects for 'both' / 'the pair' (as many as it
    counts for 'all' / 'them'); a purpose ('for room service') names nothing; S is a surface."""
    m = _WANTS_PUT29R.match(text)
    if m is None:
        return text
    who = m.group("who")
    if not (_only_person(who, lexicon) or _names_nothing(who, lexicon)):
        return text
    if m.group("why") and not _names_nothing(m.group("why"), lexicon):
        return text
    objs = _ids(m.group("x"), lexicon, "object")
    said = m.group(0)[m.end("x") :].lower()
    if len(objs) < 2 or (("both" in said or "pair" in said) and len(objs) != 2):
        return text
    where = re.sub(r"^(?:up )?(?:onto|on|into|in) (?:the )?", "", m.group("where"), flags=_F)
    if not _surface_only(where, lexicon):
        return text
    return f"Put {m.group('x')} {m.group('where')}{m.group('end')}"


# "Three things for Person B to take to the dairy: …": where they are taken, in the header
_COUNT_FOR29R = re.compile(
    r"^(?P<head>(?:one|two|three|four|five|six) (?:things?|items?) for [A-Za-z][\w ]*?) to "
    r"(?:take|carry|bring|have|use)(?: (?:them |it )?(?:to|for|with|along|back|home|away)"
    r"(?P<why>[a-z' ]*))?\s*:",
    _F,
)


def _count_for29r(text: str, lexicon: Lexicon) -> str:
    """Session 29 (12r): 'N things for P to take to the dairy: …' is 'N things for P: …' (the
    session-10 count header) when what follows 'to take' names nothing in the scene."""
    m = _COUNT_FOR29R.match(text)
    if m is None or (m.group("why") and not _names_nothing(m.group("why"), lexicon)):
        return text
    return f"{m.group('head')}:{text[m.end() :]}"


# "It's the cup Person A wants for the dye bath, not the bottle."
_CLEFT_NOT29R = re.compile(
    r"^it(?:'s| is) (?P<said>the [a-z ]+?) (?P<v>wants|needs|asked for|would like)(?: for "
    r"(?P<why>[a-z' ]+?))?,\s*not (?P<y>the [a-z ]+?)(?P<end>\s*[.!]?)$",
    _F,
)


def _cleft_not29r(text: str, lexicon: Lexicon) -> str:
    """Session 29 (12r): "It's the X P wants (for <purpose>), not the Y" is 'P wants the X, not
    the Y' (X and Y objects, P one person, the purpose naming nothing)."""
    m = _CLEFT_NOT29R.match(text)
    if m is None or (m.group("why") and not _names_nothing(m.group("why"), lexicon)):
        return text
    words = m.group("said").split(" ")
    for n in (1, 2):
        obj, who = " ".join(words[:-n]), " ".join(words[-n:])
        if _only(obj, lexicon, "object") and _only_person(who, lexicon):
            return f"{who} {m.group('v')} {obj}, not {m.group('y')}{m.group('end')}"
    return text


# -- session 30 (12s): sizes compared ------------------------------------------------------------
#
# A scene may tell objects of one kind apart by size words in their names ('small box', 'medium
# box', 'large box'). 'the smallest box', 'the two smaller boxes', 'both of the bigger boxes',
# 'one of the smaller boxes', 'whichever box is smallest' pick them out by that order (each had
# been refused for an unknown name). Only where every object of the kind has a size word and no
# two share a rank; 'the smaller box' is one of two only, 'the smaller boxes' (no number) the two
# of three that are not the largest (or not the smallest); a number as large as the kind, or
# anything else, is left (and refused).
_SIZE_RANKS30S = {
    "tiny": 0,
    "little": 1,
    "small": 1,
    "mini": 1,
    "medium": 2,
    "middle": 2,
    "medium-sized": 2,
    "mid-sized": 2,
    "middle-sized": 2,
    "large": 3,
    "big": 3,
    "huge": 4,
}
_COMPARED30S = {
    "smaller": "less",
    "lesser": "less",
    "littler": "less",
    "bigger": "more",
    "larger": "more",
    "smallest": "least",
    "littlest": "least",
    "tiniest": "least",
    "biggest": "most",
    "largest": "most",
}


_JOINS30S = frozenset({"the", "and", "or"})


def _rank30s(oid: str, lexicon: Lexicon) -> int:
    o = next(x for x in lexicon.scene.objects if x.id == oid)
    return next(
        _SIZE_RANKS30S[w]
        for n in (o.id.replace("_", " "), *o.aliases)
        for w in n.lower().split()
        if w in _SIZE_RANKS30S
    )


def _ranked30s(category: str, lexicon: Lexicon) -> list[str] | None:
    """The objects of ``category``, smallest first, when each has one size word in its names and
    no two share a rank; else None."""
    ranks: dict[str, int] = {}
    for o in lexicon.scene.objects:
        if o.category != category:
            continue
        said = {
            _SIZE_RANKS30S[w]
            for n in (o.id.replace("_", " "), *o.aliases)
            for w in n.lower().split()
            if w in _SIZE_RANKS30S
        }
        if len(said) != 1:
            return None
        ranks[o.id] = _rank30s(o.id, lexicon)
    if len(ranks) < 2 or len(set(ranks.values())) != len(ranks):
        return None
    return sorted(ranks, key=lambda i: ranks[i])


def _kind_ranked30s(noun: str, lexicon: Lexicon) -> tuple[list[str], bool] | None:
    """The objects a kind's name ``noun`` ('box', 'boxes') names, smallest first, and whether it
    is said in the plural; None unless it names all of one category, ranked by size."""
    ids = _ids(noun, lexicon, "object")
    cats = {o.category for o in lexicon.scene.objects if o.id in ids}
    if len(cats) != 1:
        return None
    category = cats.pop()
    order = _ranked30s(category, lexicon)
    if order is None or set(order) != ids:
        return None
    return order, noun.lower() != category.lower()


# sizes said again: 'small and medium', 'the small or the medium'
_AGAIN30S = r"(?:the\s+)?[a-z-]+(?:(?:\s*,\s*|\s+(?:and|or)\s+)(?:the\s+)?[a-z-]+)+"


def _sizes_said30s(words: str) -> list[int] | None:
    """The ranks ``words`` says, sorted ('small and medium': [1, 2]); None unless each word
    other than 'the', 'and', 'or' is a size word."""
    said = [w for w in re.findall(r"[a-z-]+", words.lower()) if w not in _JOINS30S]
    if not all(w in _SIZE_RANKS30S for w in said):
        return None
    return sorted(_SIZE_RANKS30S[w] for w in said)


def _compared30s(
    m: re.Match[str],
    lexicon: Lexicon,
    chosen: list[list[int]] | None = None,
    *,
    whichever: bool = False,
) -> str:
    """What 'the two smaller boxes' (``m``) names, said by the objects' own names; ``m`` itself
    where that is not one reading."""
    kind = _kind_ranked30s(m.group("noun"), lexicon)
    if kind is None:
        return m.group(0)
    order, plural = kind
    way = _COMPARED30S[m.group("cmp").lower()]
    ranked = order if way in ("less", "least") else order[::-1]
    if whichever:
        return m.group(0) if plural else f"the {_said(ranked[0], lexicon)}"
    count_word = (m.group("count") or "").lower().split()
    count = next((_NUMBERS15[w] for w in count_word if w in _NUMBERS15), 0)
    if not plural:
        if count or m.group("one") or not m.group("the"):
            return m.group(0)
        if way in ("least", "most") or len(order) == 2:
            return f"the {_said(ranked[0], lexicon)}"  # 'the smallest box', 'the bigger box'
        return m.group(0)
    if way in ("least", "most"):
        return m.group(0)  # 'the smallest boxes'
    if not count:
        if len(order) != 3 or not (m.group("the") or m.group("one")):
            return m.group(0)
        count = 2  # 'the smaller boxes' of three: the two that are not the largest
    if count >= len(order):
        return m.group(0)
    names = [f"the {_said(i, lexicon)}" for i in ranked[:count]]
    ranks = sorted(_rank30s(i, lexicon) for i in ranked[:count])
    if m.group("again") and _sizes_said30s(m.group("again").strip(" ,")) != ranks:
        return m.group(0)  # "the two smaller boxes, small and large, …": which is meant?
    if chosen is not None and not m.group("again"):
        chosen.append(ranks)
    if m.group("one"):
        return "either " + " or ".join(names)
    return ", ".join(names[:-1]) + " and " + names[-1]


def _sizes30s(text: str, lexicon: Lexicon) -> str:
    if not re.search(r"(?:er|est)\b", text, _F) or not any(w in text.lower() for w in _COMPARED30S):
        return text
    words = "|".join(_COMPARED30S)
    before = text
    chosen: list[list[int]] = []
    text = _sub(
        rf"\b(?:(?P<count>the two|the three|two|three|both(?: of the| the)?)\s+|(?P<one>one of "
        rf"the)\s+|(?P<the>the)\s+)?(?P<cmp>{words})\s+(?P<noun>[a-z]+)\b"
        # "…, small and medium, …": the sizes said again after them
        rf"(?P<again>\s*,\s*{_AGAIN30S}\s*,)?",
        lambda m: _compared30s(m, lexicon, chosen),
        text,
    )
    for ranks in chosen:
        # "One of the smaller boxes onto the belt, the small or the medium, your pick": the sizes
        # said again later in the sentence
        for m in _rx(rf",\s*(?P<again>{_AGAIN30S})\s*(?=[,.!?;]|$)").finditer(text):
            said = _sizes_said30s(m.group("again"))
            if said is None:
                continue
            if said != ranks:
                return before  # the sizes said again are others: which is meant?
            text = text[: m.start()] + text[m.end() :]
            break
    # "Whichever box is smallest goes to Tom": the one of that size
    return _sub(
        r"\bwhichever\s+(?P<noun>[a-z]+)\s+is\s+(?:the\s+)?(?P<cmp>smallest|biggest|largest)\b",
        lambda m: _compared30s(m, lexicon, whichever=True),
        text,
    )


# -- session 30 (12s): a negated want, then what is wanted ------------------------------------
#
# "Don't give Bob the bottle; he gets the crisps.", "Alice doesn't want the crisps. The bottle's
# the one for her.", "Bob doesn't want the bottle at all, it's the crisps he's after.", "Mrs Khan
# doesn't want the grey blanket, so it's the other one for her.": the grammar reads a negated
# request and, after a comma, what is given instead ("Alice doesn't want the crisps, give her the
# bottle"); said with a full stop or a semicolon between them, with 'at all', or with what is
# wanted said as a cleft, each had been refused. Only a text opening with the negated request,
# and after a stop or a semicolon only a sentence naming an object ("Alice doesn't need the
# chips. Bob does." stays refused, session 8);
# the cleft only with a pronoun and objects of the scene; the grammar then reads (or refuses)
# the two as it reads them with a comma.
_NOT_WANTED30S = re.compile(
    r"^(?P<neg>(?:[A-Z][\w ]*? (?:doesn't|does not|won't|will not|didn't|did not) (?:want|need)|"
    r"(?:don't|do not) (?:give|hand|pass|bring|take|send|deliver)) [^.;,!?]+?)(?:\s+at all)?"
    r"\s*(?P<sep>[.;,])\s*(?P<rest>\S.*)$",
    _F,
)
_CLEFTS30S = (
    # "it's the crisps he's after" / "it's the crisps she wants"
    (
        r"^(?P<so>(?:so|but|no),?\s+)?(?:it's|it is) (?P<o>(?:the|that) [\w ]+?) (?:that |which )?"
        r"(?P<p>he|she)(?:'s| is) (?:after|wanting)\b",
        r"\g<p> wants \g<o>",
    ),
    (
        r"^(?P<so>(?:so|but|no),?\s+)?(?:it's|it is) (?P<o>(?:the|that) [\w ]+?) (?:that |which )?"
        r"(?P<p>he|she) (?:wants|needs)\b",
        r"\g<p> wants \g<o>",
    ),
    # "so it's the other one for her", "the bottle's the one for her"
    (
        r"^(?P<so>(?:so|but|no),?\s+)?(?:it's|it is) (?P<o>(?:the|that) [\w ]+?) for "
        r"(?P<p>him|her)\b",
        r"give \g<p> \g<o>",
    ),
    (
        r"^(?P<so>(?:so|but|no),?\s+)?(?P<o>the [\w ]+?)(?:'s| is) the one (?:for|meant for) "
        r"(?P<p>him|her)\b",
        r"give \g<p> \g<o>",
    ),
)


def _not_wanted30s(text: str, lexicon: Lexicon) -> str:
    if "n't" not in text and " not " not in text.lower():
        return text
    m = _NOT_WANTED30S.match(text)
    if m is None or not _ids(m.group("neg"), lexicon, "object"):
        return text
    rest = m.group("rest")
    if m.group("sep") != "," and not _ids(rest, lexicon, "object") and "other" not in rest.lower():
        return text  # "Alice doesn't need the chips. Bob does.": said alone, refused (session 8)
    for pattern, repl in _CLEFTS30S:
        c = _rx(pattern).match(rest)
        if c is None:
            continue
        said = c.group("o")
        if not (_objects_only(said, lexicon) or re.fullmatch(r"the other(?: one)?", said, _F)):
            return text
        rest = c.expand(repl) + rest[c.end() :]
        break
    out = f"{m.group('neg')}, {rest}"
    return text if " ".join(out.split()) == " ".join(text.split()) else out


# -- session 30 (12s): a suggestion said with 'what about' -----------------------------------
#
# "What about taking the bottle across to Person A, eh?" asks as "How about taking …?" does (the
# grammar's filler 'how about' before a verb): 'what about' before the -ing form of a verb of the
# grammar is said so; "How / what about letting Person A have the bottle" is 'how about giving
# Person A the bottle' (one person named between). 'What about Bob?' or 'what about the
# bottle?' (no verb) are left, and refused.
_WHAT_ABOUT30S = re.compile(
    r"\b(?:what|how) about (?:letting (?P<who>[\w ]+?) have|(?P<verb>[a-z]+ing))\b", _F
)


def _what_about30s(text: str, lexicon: Lexicon) -> str:
    if "about" not in text.lower():
        return text

    def said(m: re.Match[str]) -> str:
        if m.group("who") is not None:
            who = m.group("who")
            return f"how about giving {who}" if _only(who, lexicon, "human") else m.group(0)
        verb = m.group("verb")
        return f"how about {verb}" if verb.lower() in VERBS else m.group(0)

    return _WHAT_ABOUT30S.sub(said, text)


# -- session 30 (12s): a person said to be 'the <word> one' ----------------------------------
#
# "…, seeing as she's the thirsty one": 'the thirsty one' is the person the pronoun says, not
# an object ('one' read as an object had refused it: "no object called 'thirsty one'"). Closing
# the text after a comma, with 'he' / 'she' / 'they' and 'is', a word that tells no objects of
# the scene apart ('the red one' is left), and nothing after it, it is a reason, taken off.
_PERSON_ONE30S = re.compile(
    r",\s*(?:(?:seeing as|since|as|because|cos|'cause)\s+)?(?:he|she|they)(?:'s| is|'re| are) "
    r"the (?P<adj>[a-z]+) ones?\s*(?=[.!?]*\s*$)",
    _F,
)


def _person_one30s(text: str, lexicon: Lexicon) -> str:
    if " one" not in text.lower():
        return text
    m = _PERSON_ONE30S.search(text)
    if m is None or m.group("adj").lower() in _adjectives(lexicon) or _names(m.group(0), lexicon):
        return text
    return text[: m.start()] + text[m.end() :]


# -- session 30 (12r): blind28's choices, counts, exclusions and corrections ------------------
# Each rule below rewrites one construction into the form the grammar reads, and leaves the text
# as it was when what the construction presupposes (one person, the scene's objects, a count)
# does not hold; docs/grounding.md, "Session 30 (engineer 12r)".

# a time said in words a rule takes off ("needs a drink tomorrow", "for Tom's run tonight"): the
# rule is not taken, so what the grammar and the time rule make of the time stands
_TIME30R = re.compile(
    r"\b(?:tonight|tomorrow|later|soon|today|yesterday|morning|afternoon|evening|week|minutes?|"
    r"hours?|after|before|until|till|when|once|then|next|first|last|now)\b",
    _F,
)
_OBJECT_PRONOUN30R = {"him": "he", "her": "she", "them": "they", "me": "I", "us": "we"}
# "…, makes no odds to him", "…, it makes no difference", "…, it doesn't matter to her"
_NO_ODDS30R = re.compile(
    r"(?P<lead>,\s*)(?:(?:it|that) )?(?:(?:makes|make|'ll make|will make) (?:no|little) "
    r"(?:odds|difference)|(?:doesn't|does not|won't|will not) (?:matter|make (?:any )?difference))"
    r"(?: (?:to|for) (?P<who>him|her|them|me|us))?(?P<tail>(?: which(?: one)?)?)"
    r"(?=\s*(?:[.!,;]|$))",
    _F,
)


def _no_odds30r(text: str, _lexicon: Lexicon) -> str:
    """Session 30 (12r): 'makes no odds (to him)' and 'it doesn't matter to her', a clause of its
    own after a choice, say the chooser does not mind: "he doesn't mind" (to him) or "it doesn't
    matter" (to no one said), the tails the grammar reads, and which leave a request with nothing
    open refused as they were."""

    def said(m: re.Match[str]) -> str:
        who = m.group("who")
        if who is None:
            return f"{m.group('lead')}it doesn't matter{m.group('tail')}"
        subject = _OBJECT_PRONOUN30R[who.lower()]
        verb = "don't" if subject in ("I", "we", "they") else "doesn't"
        return f"{m.group('lead')}{subject} {verb} mind{m.group('tail')}"

    return _sub(_NO_ODDS30R.pattern, said, text)


# "… to whichever of the two of them, Person A or Person B": the people said after a word for them
_WHICHEVER_OF30R = re.compile(
    r"\b(?P<to>to|for) (?:whichever|either|any)(?: one)? of (?:the (?P<n>two|three)(?: of them)?|"
    r"them(?: both| two)?|the pair of them|the (?P<m>two|three) of you),\s*"
    r"(?P<list>(?:[A-Za-z][\w ]*?,\s*)*[A-Za-z][\w ]*? or [A-Za-z][\w ]*?)(?=\s*(?:[.!;]|$))",
    _F,
)


def _whichever_of30r(text: str, lexicon: Lexicon) -> str:
    """Session 30 (12r): 'to whichever of the two of them, P or Q' is 'to either P or Q' when the
    list names people of the scene only, one each, as many as a number said before it."""
    m = _WHICHEVER_OF30R.search(text)
    if m is None:
        return text
    names = re.split(r",\s*|\s+or\s+", m.group("list"))
    if not all(_only_person(n, lexicon) for n in names):
        return text
    if len({i for n in names for i in _ids(n, lexicon)}) != len(names):
        return text
    n = m.group("n") or m.group("m")
    if n and _COUNTS[n.lower()] != len(names):
        return text
    return f"{text[: m.start()]}{m.group('to')} either {m.group('list')}{text[m.end() :]}"


# "One of the books to each student, whichever way round."
_EACH_ROLE30R = re.compile(
    r"^(?:please,? )?(?P<what>one of the [a-z]+s|(?:one|an?) [a-z]+) (?:to|for) each "
    r"(?P<role>[a-z]+)(?:,\s*(?:whichever|either|any) way(?: round)?)?(?P<end>\s*[.!]?)$",
    _F,
)


def _each_role30r(text: str, lexicon: Lexicon) -> str:
    """Session 30 (12r): 'One of the Xs to each <role>' (with 'whichever way round' after it or
    not) is 'Give each <role> one of the Xs', when two people or more of the scene are called so;
    the grammar then reads the share, or refuses it where the objects do not match."""
    m = _EACH_ROLE30R.match(text)
    if m is None:
        return text
    role = m.group("role").lower()
    if sum(role in (a.lower() for a in h.aliases) for h in lexicon.scene.humans) < 2:
        return text
    return f"Give each {role} {m.group('what').lower()}{m.group('end')}"


# words for everything the scene has, then what they are said again to be: "the whole lot,
# which is just the bottle and the crisps", "Whatever's there goes to Person A, it's only the
# bottle anyway"
_ALL_WORDS30R = (
    r"(?:the whole lot|the lot|everything|all of it|whatever(?:'s| is) (?:there|here)|"
    r"whatever there is)"
)
_LOT_IS30R = re.compile(
    r",\s*(?:which is|which are|it's|it is|that's|that is|they're|they are|i\.e\.,?|namely) "
    r"(?:just |only |simply |all )?(?P<list>(?:the |a |an )?[a-z][a-z ,]*?)"
    r"(?: anyway| after all| really)?(?P<end>\s*[.!]?)$",
    _F,
)


def _lot_is30r(text: str, lexicon: Lexicon) -> str:
    """Session 30 (12r): a word for everything ('the whole lot', 'whatever's there'), then
    what it is said again to be (", which is just X and Y", ", it's only the X anyway"), is the
    word alone when the list, each item one name of the scene's objects, names exactly every
    object of the scene ('whatever's there' then 'everything') and what is left reads, with
    every object. A list naming fewer (or anything
    but objects) leaves the text, refused; so does 'Everything sweet …' (a kind said first)."""
    if not re.search(_ALL_WORDS30R, text, _F):
        return text
    m = _LOT_IS30R.search(text)
    if m is None or not re.search(_ALL_WORDS30R, text[: m.start()], _F):
        return text
    listed = m.group("list")
    every = {o.id for o in lexicon.scene.objects}
    items = [w for w in re.split(r"\s*,\s*(?:and\s+)?|\s+and\s+", listed.strip()) if w]
    if not all(_whole_name(w, lexicon, "object") for w in items):
        return text  # "…, the bottle and the crisps, before I go tomorrow": not a list of names
    if _ids(listed, lexicon) != every:
        return text
    out = text[: m.start()] + m.group("end")
    out = _sub(r"\bwhatever(?:'s| is) (?:there|here)|\bwhatever there is", "everything", out)
    out = out[:1].upper() + out[1:]
    said = _tasks_of(out, lexicon)
    return out if said and {o for _, o, _ in said} == every else text


def _every_last30r(text: str, lexicon: Lexicon) -> str:
    """Session 30 (12r): 'every last / single one of the four items' is 'all of the four items'
    (the grammar checks the count against the scene)."""
    return _sub(
        r"\bevery (?:last |single )?one of (?=the (?:two|three|four|five|six) [a-z]+s\b)",
        "all of ",
        text,
    )


def _pronoun_is_to30r(text: str, lexicon: Lexicon) -> str:
    """Session 30 (12r): "so she's to have the two blankets": a pronoun's 's before 'to have /
    get' is 'is' (as _is_to28s's for a name), and 'she is to have' is 'she gets'."""
    return _sub(r"\b(she|he)(?:'s| is) to (?:get|have|receive)\b", r"\1 gets", text)


def _only_not30r(text: str, lexicon: Lexicon) -> str:
    """Session 30 (12r): '…, only not the bottle' after what is given is '…, but not the
    bottle' (an exclusion the grammar reads); 'but no chips' (a bare name of the scene's objects
    after 'no') is 'but not the chips'."""
    out = _sub(r",\s*(?:only|just) not (?=the\b)", ", but not ", text)

    def bare(m: re.Match[str]) -> str:
        return f"but not the {m.group(1)}" if _whole_name(m.group(1), lexicon, "object") else m[0]

    return _sub(r"\bbut no ([a-z]+(?: [a-z]+)??)(?=\s*(?:[.!;,]|$))", bare, out)


# "Only Person A is to get the bottle, nobody else."
_ONLY_WHO30R = re.compile(
    r"^only (?P<p>[A-Za-z][\w ]*?) (?P<v>is to get|is to have|gets|should get|should have|can have)"
    r"\b",
    _F,
)


def _only_who30r(text: str, lexicon: Lexicon) -> str:
    """Session 30 (12r): 'Only P is to get X' is 'P is to get X' (the request names one
    recipient: 'only' keeps to it, as 'nobody else' after it does)."""
    m = _ONLY_WHO30R.match(text)
    if m is None or not _only_person(m.group("p"), lexicon):
        return text
    return f"{m.group('p')} {m.group('v')}{text[m.end() :]}"


def _leaving_out30r(text: str, lexicon: Lexicon) -> str:
    """Session 30 (12r): '…, leaving out the big one' closing a request is '…, except the big
    one' (only an object phrase, ending the text: 'leave it out on the desk' places it)."""

    def left(m: re.Match[str]) -> str:
        what = m.group("what")
        if what.lower().split()[-1] not in ("one", "ones") and not _objects_only(what, lexicon):
            return m[0]
        return f", except {what}{m.group('end')}"

    return _sub(
        r",\s*(?:leaving|but leave|but leaving) (?:out|aside) (?P<what>the [a-z ]+?)"
        r"(?P<end>\s*[.!]?)$",
        left,
        text,
    )


def _one_name30r(words: str, lexicon: Lexicon) -> bool:
    """Whether ``words`` (an article aside) are one name of the scene, whole, of one kind."""
    named = _names(words, lexicon)
    return len(named) == 1 and _whole_name(words, lexicon, named[0].refs[0].kind)


_NEGATED30R = re.compile(r"\b(?:not|no|never|don't|do not|doesn't|does not)\b|n't\b", _F)


def _rather_than30r(text: str, lexicon: Lexicon) -> str:
    """Session 30 (12r): 'X to P rather than Q' is 'X to P, not Q' when Q is one name of the
    scene (of a person, object or surface) and nothing before it is negated ("don't give her
    the apple rather than the crisps" stays refused): what the grammar reads as the exclusion."""

    def instead(m: re.Match[str]) -> str:
        q = m.group("q")
        if not _one_name30r(q, lexicon) or _NEGATED30R.search(m.string[: m.start()]):
            return m[0]
        return f", not {q}"

    return _sub(
        r"\s*,?\s*rather than (?P<q>(?:the )?[A-Za-z][\w ]*?)(?=\s*(?:[.!;]|$))", instead, text
    )


def _rather_after30r(text: str, lexicon: Lexicon) -> str:
    """Session 30 (12r): '…, Alice rather.' (the cue after the corrected words, closing the
    text) is '…, rather Alice.' when the words are one name of the scene."""

    def moved(m: re.Match[str]) -> str:
        said = m.group("said")
        if not _one_name30r(said, lexicon):
            return m[0]
        return f", rather {said}{m.group('end')}"

    return _sub(r",\s*(?P<said>(?:the )?[A-Za-z][\w ]*?) rather(?P<end>\s*[.!]?)$", moved, text)


def _i_mean_after30r(text: str, lexicon: Lexicon) -> str:
    """Session 30 (12r): '…, sorry, cup for Person B I mean.' (the cue after the corrected
    words) is '…, sorry, I mean cup for Person B.' when the words name something of the scene
    and no verb or cue of their own."""

    def moved(m: re.Match[str]) -> str:
        said = m.group("said")
        if not _names(said, lexicon) or re.search(r"\b(?:i|you|no|not|sorry)\b", said, _F):
            return m[0]
        return f", {m.group('cue') or ''}I mean {said}{m.group('end')}"

    return _sub(
        r",\s*(?P<cue>sorry,\s*|no,\s*)?(?P<said>[A-Za-z][\w ]*?) i mean(?P<end>\s*[.!]?)$",
        moved,
        text,
    )


# "…, I mean, the chips, sorry, long day at the dye works.": an apology after the correction
_SORRY_AFTER30R = re.compile(r",\s*sorry\s*[,;:-]\s*(?P<why>[a-z][a-z' -]*?)(?P<end>\s*[.!]?)$", _F)


# words that change what was said ('swap the people', 'the other way round'): never an apology
_CHANGES33L = re.compile(
    r"\b(?:swap|swop|switch|reverse|change|changed|other way|wrong way|round|around|instead|"
    r"mixed|mix|muddled)\b",
    _F,
)


def _sorry_after30r(text: str, lexicon: Lexicon) -> str:
    """Session 30 (12r): ', sorry, <words>' closing a text whose words name nothing of the scene
    and hold no word that counts, chooses, negates or points back is an apology (its reason),
    taken off: it corrects nothing. Only after a correction already said ('I mean', 'no,'
    'sorry,' before it), so that 'sorry' cannot be the first cue."""
    m = _SORRY_AFTER30R.search(text)
    if m is None or not _inert28(m.group("why"), lexicon) or _TIME30R.search(m.group("why")):
        return text
    if _CHANGES33L.search(m.group("why")):
        return text  # ", sorry, swap the people": a change of its own (session 33, lead)
    before = text[: m.start()]
    if not re.search(rf"(?:^|[,.;]\s*)(?:{_CUE19})\s*,", before, _F):
        return text
    return before + m.group("end")


# "The animator wants the chips sent to Person A, …": someone wants X taken to P
_WANTS_SENT30R = re.compile(
    r"^(?P<who>[A-Za-z][\w' ]*?) (?:wants|needs|would like|asked for|has asked for) "
    r"(?P<x>(?:the |both |the two |both the )[a-z ]+?) (?:sent|taken|brought|carried|run|passed)"
    r"(?P<dir>(?: over| across| back| up| down)?) to (?=\S)",
    _F,
)


def _wants_sent30r(text: str, lexicon: Lexicon) -> str:
    """Session 30 (12r): 'W wants X sent to P …' is 'Take X to P …' when W is someone the scene
    does not name (who asks, not who gets it: "The animator wants the chips sent to Person A"),
    X the scene's objects, and no pronoun follows that W could stand for ('… brought over to
    her': a person of the scene wanting it, the grammar's own reading)."""
    m = _WANTS_SENT30R.match(text)
    if m is None or not _objects_only(m.group("x"), lexicon):
        return text
    if not _inert28(m.group("who"), lexicon) or _PRONOUN28R.search(text[m.end() :]):
        return text
    return f"Take {m.group('x')}{m.group('dir')} to {text[m.end() :]}"


def _beg_pardon30r(text: str, _lexicon: Lexicon) -> str:
    """Session 30 (12r): 'beg pardon' and 'I beg your pardon' opening a correction are the cue
    'sorry'."""
    return _sub(
        r"(?:(?<=[,;.])|^)(\s*)(?:i )?beg (?:your )?pardon(?=\s*,)",
        lambda m: f"{m.group(1)}{'Sorry' if m.start() == 0 else 'sorry'}",
        text,
    )


# "Person A has waited long enough for the bottle now"
_WAITED30R = re.compile(
    r"^(?P<p>[A-Za-z][\w ]*?) (?:has|'s|have) (?:waited|been waiting)(?: (?:long enough|ages|"
    r"all day|a while))? for (?P<x>(?:the |that |this )?[a-z ]+?)(?: now| already)?"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _waited30r(text: str, lexicon: Lexicon) -> str:
    """Session 30 (12r): 'P has waited (long enough) for X (now)' is 'P is waiting for X' (what
    the grammar reads as P wanting X), P one person and X the scene's objects."""
    m = _WAITED30R.match(text)
    if m is None or not _only_person(m.group("p"), lexicon):
        return text
    if not _objects_only(m.group("x"), lexicon):
        return text
    return f"{m.group('p')} is waiting for {m.group('x')}{m.group('end')}"


# "It's not the apple Person B is after, it's the cup."
_NOT_CLEFT30R = re.compile(
    r"^it(?:'s| is) not (?P<said>the [a-z ]+?) (?:is after|wants|needs|asked for|would like|"
    r"'s after),\s*it(?:'s| is) (?P<y>the [a-z ]+?)(?P<end>\s*[.!]?)$",
    _F,
)


def _not_cleft30r(text: str, lexicon: Lexicon) -> str:
    """Session 30 (12r): "It's not the X P is after, it's the Y" is 'P wants the Y, not the X'
    (X and Y objects of the scene, P one person)."""
    m = _NOT_CLEFT30R.match(text)
    if m is None or not _objects_only(m.group("y"), lexicon):
        return text
    words = m.group("said").split(" ")
    for n in (1, 2):
        obj, who = " ".join(words[:-n]), " ".join(words[-n:])
        if _objects_only(obj, lexicon) and _only_person(who, lexicon):
            return f"{who} wants {m.group('y')}, not {obj}{m.group('end')}"
    return text


# "…, and the bottle, no, leave the bottle.": an object said, then taken back by its name
_AND_LEAVE30R = re.compile(
    r",\s*and (?P<x>(?:the )?[a-z]+(?: [a-z]+)??),\s*(?:no|oh no|wait|actually),\s*leave "
    r"(?P<y>(?:the )?[a-z]+(?: [a-z]+)??)(?: (?:be|alone|there|where it is|out))?"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _and_leave30r(text: str, lexicon: Lexicon) -> str:
    """Session 30 (12r): "The chips to Person A, and the bottle, no, leave the bottle." — an
    object added with no verb or person of its own, then taken back by the same name ('leave the
    bottle'), is said and unsaid: taken off. 'leave it' could take back the whole request (the
    grammar's refusal stands)."""
    m = _AND_LEAVE30R.search(text)
    if m is None or not _whole_name(m.group("x"), lexicon, "object"):
        return text
    if _ids(m.group("x"), lexicon) != _ids(m.group("y"), lexicon) or not _whole_name(
        m.group("y"), lexicon, "object"
    ):
        return text
    return text[: m.start()] + m.group("end")


# "Stapler into the box, oh no, leave it out on the desk instead."
_LEAVE_ON30R = re.compile(
    r"(?P<cue>\bno,\s*)(?:just )?leave (?:it|them) (?:out )?(?P<on>(?:on|onto|in|into) (?:the )?"
    r"(?P<s>[a-z]+(?: [a-z]+)??))(?P<inst> instead)?(?P<end>\s*[.!]?)$",
    _F,
)


def _leave_on30r(text: str, lexicon: Lexicon) -> str:
    """Session 30 (12r): after the cue 'no', 'leave it (out) on S (instead)' says where the object
    goes: '…, no, on S instead', the correction of a place the grammar reads (S a surface)."""
    m = _LEAVE_ON30R.search(text)
    if m is None or not _surface_only(m.group("s"), lexicon):
        return text
    return f"{text[: m.start()]}{m.group('cue')}{m.group('on')} instead{m.group('end')}"


# "The scanner to Mia. Wait, Tom, not Mia."
_NOT_AGAIN30R = re.compile(
    r"(?P<cue>(?:^|[,.;!?]\s*)(?:wait|no|sorry|hang on|hold on|oops|actually),\s*)"
    r"(?P<q>(?:the )?[A-Za-z][\w ]*?),\s*not (?P<p>(?:the )?[A-Za-z][\w ]*?)(?P<end>\s*[.!]?)$",
    _F,
)


def _not_again30r(text: str, lexicon: Lexicon) -> str:
    """Session 30 (12r): a correction '…, Tom, not Mia.' that says again what it replaces is the
    correction '…, Tom.' when Mia is named before the cue, Tom and Mia are each one name of the
    scene of the same kind, and they differ."""
    m = _NOT_AGAIN30R.search(text)
    if m is None:
        return text
    q, p = m.group("q"), m.group("p")
    if not (_one_name30r(q, lexicon) and _one_name30r(p, lexicon)):
        return text
    kinds = {r.kind for w in (q, p) for it in _names(w, lexicon) for r in it.refs}
    if len(kinds) != 1 or _ids(q, lexicon) == _ids(p, lexicon):
        return text
    if not _ids(p, lexicon) <= _ids(text[: m.start()], lexicon):
        return text
    return f"{text[: m.start('q')]}{q}{m.group('end')}"


_WANT_VERBS30R = frozenset({"wants", "needs", "would like", "'d like", "is after", "requires"})
# "Person A wants the bottle; sorry, did I say wants? Needs."
_DID_I_SAY30R = re.compile(
    r"\s*[;,.]\s*(?:sorry|oops|whoops),?\s*did i say (?P<a>[a-z' ]+?)\?\s*(?P<b>[A-Za-z' ]+?)"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _did_i_say30r(text: str, lexicon: Lexicon) -> str:
    """Session 30 (12r): "…; sorry, did I say wants? Needs." corrects a verb of wanting by
    another ('wants', 'needs', 'would like', 'is after', 'requires'): the request means the same
    either way, so the correction is taken off, when the first word is said before it."""
    m = _DID_I_SAY30R.search(text)
    if m is None:
        return text
    a, b = m.group("a").lower(), m.group("b").lower()
    if a not in _WANT_VERBS30R or b not in _WANT_VERBS30R:
        return text
    before = text[: m.start()]
    if not re.search(rf"\b{re.escape(a)}\b", before, _F):
        return text
    return before + (m.group("end") or ".")


# "We've only got a single bottle going, and Person B is having it."
_ONLY_GOT30R = re.compile(
    r"^(?:we've|we have|we) (?:only )?(?:got|have) (?:only |just )?(?:a single|one|the one|just "
    r"the one) (?P<x>[a-z]+(?: [a-z]+)??)(?: going| left| here| to spare)?,\s*and "
    r"(?P<p>[A-Za-z][\w ]*?) (?:is having|is getting|should have|should get|can have|gets|is to "
    r"have) it(?P<end>\s*[.!]?)$",
    _F,
)
# "Only one bottle and only one person here, so she gets it."
_ONLY_ONE_HERE30R = re.compile(
    r"^(?:there's )?only one (?P<x>[a-z]+(?: [a-z]+)??) and only one (?:person|human|of you|one "
    r"person)(?: here| around| about)?,\s*so (?:she|he|they) (?:gets|can have|should have|is "
    r"having) it(?P<end>\s*[.!]?)$",
    _F,
)


def _only_got30r(text: str, lexicon: Lexicon) -> str:
    """Session 30 (12r): "We've only got a single X (going), and P is having it" is 'the X to P'
    (as _only_one29r's "There's only one X, and P should have it"), the scene having one X and P
    one person; "Only one X and only one person here, so she gets it" is the X to the scene's one
    person, when it has one person and one X (and the pronoun fits her)."""
    m = _ONLY_GOT30R.match(text)
    if m is not None:
        if _only(m.group("x"), lexicon, "object") and _only_person(m.group("p"), lexicon):
            return f"The {m.group('x')} to {m.group('p')}{m.group('end')}"
        return text
    m = _ONLY_ONE_HERE30R.match(text)
    if m is None or not _only(m.group("x"), lexicon, "object"):
        return text
    if len(lexicon.scene.humans) != 1:
        return text
    pid = lexicon.scene.humans[0].id
    pronoun = re.search(r"\b(she|he|they)\b", m.group(0), _F)
    if pronoun is None or not _fits(pid, pronoun.group(1).lower(), lexicon):
        return text
    return f"The {m.group('x')} to {lexicon.scene.humans[0].name}{m.group('end')}"


def _things_here30r(text: str, lexicon: Lexicon) -> str:
    """Session 30 (12r): 'the pair of things here', 'the two items here': 'here' after a word for
    the scene's things says where they are, which the grammar knows (taken off)."""
    return _sub(
        r"\b((?:the pair of|the two|both|both the|all the|the three|the four) (?:things|items|"
        r"objects|bits)) here\b",
        r"\1",
        text,
    )


# "…; the apple stays put."
_STAYS_PUT30R = re.compile(
    r"\s*;\s*(?:and )?(?P<x>the [a-z]+(?: [a-z]+)??) (?:stays|can stay|is staying|remains) "
    r"(?:put|where it is|here|there)(?P<end>\s*[.!]?)$",
    _F,
)


def _stays_put30r(text: str, lexicon: Lexicon) -> str:
    """Session 30 (12r): '…; the apple stays put' closing a request that does nothing with the
    apple asks nothing: taken off (the count of a header before it, 'three items: …', is then
    that of its list, not of the scene with the apple)."""
    m = _STAYS_PUT30R.search(text)
    if m is None or not _whole_name(m.group("x"), lexicon, "object"):
        return text
    out = text[: m.start()] + (m.group("end") or ".")
    said = _tasks_of(out, lexicon)
    if not said or {o for _, o, _ in said} & _ids(m.group("x"), lexicon):
        return text
    return out


# "Load all three boxes onto the belt for Tom's run."
_PLACED_FOR30R = re.compile(
    r"\b(?P<on>(?:on|onto|into|in) (?:the )?[a-z]+(?: [a-z]+)??) for (?P<p>[A-Za-z][\w ]*?)'s "
    r"(?P<w>[a-z]+(?: [a-z]+)??)(?P<end>\s*[.!]?)$",
    _F,
)


def _placed_for30r(text: str, lexicon: Lexicon) -> str:
    """Session 30 (12r): a placement closed by 'for P's <thing>' (the thing naming nothing in
    the scene) says what it is for: taken off, when what is left reads as placements only."""
    m = _PLACED_FOR30R.search(text)
    if m is None or not _only_person(m.group("p"), lexicon) or not _inert28(m.group("w"), lexicon):
        return text
    if _TIME30R.search(m.group("w")):
        return text
    out = text[: m.start()] + m.group("on") + m.group("end")
    said = _tasks_of(out, lexicon)
    return out if said and all(k == "place" for k, _, _ in said) else text


def _laid_out30r(text: str, lexicon: Lexicon) -> str:
    """Session 30 (12r): 'lay out / set out X (side by side) on S' is 'lay X on S': 'out' and
    how the objects are arranged ('side by side', 'next to each other', 'in a row') say nothing
    the cell can do otherwise."""
    out = _sub(r"^((?:please )?(?:lay|set|spread)) out (?=(?:the|both|all) )", r"\1 ", text)
    if out == text:
        return text
    return _sub(r" (?:side by side|next to each other|in a row|together)(?= (?:on|onto) )", "", out)


# "The kayakers get one apiece, Person A taking the bottle and Person B the chips."
_APIECE30R = re.compile(
    r"^(?P<who>(?:the )?[a-z]+|they|the two of them|both of them) (?:get|gets|have|are getting) "
    r"one (?:thing |item )?(?:apiece|each),\s*(?P<p>[A-Za-z][\w ]*?) taking (?P<rest>\S.*)$",
    _F,
)


def _apiece30r(text: str, lexicon: Lexicon) -> str:
    """Session 30 (12r): "The kayakers get one apiece, Person A taking the bottle and Person B
    the chips" is "Person A gets the bottle and Person B the chips" when the list hands each of
    two people or more one object, and the word before (a role the scene does not name, 'they')
    names nothing."""
    m = _APIECE30R.match(text)
    if m is None or not _only_person(m.group("p"), lexicon):
        return text
    if m.group("who").lower() not in ("they", "the two of them", "both of them") and not _inert28(
        m.group("who"), lexicon
    ):
        return text
    out = f"{m.group('p')} gets {m.group('rest')}"
    node = _reading(out, lexicon)
    if not isinstance(node, Group) or node.op != "and":
        return text
    said = list(tasks(node))
    people = [t.target for t in said]
    if any(t.kind != "deliver" for t in said) or len(set(people)) != len(people) or len(said) < 2:
        return text
    return out


def _off_with30r(text: str, lexicon: Lexicon) -> str:
    """Session 30 (12r): 'pack / send P off with X' is 'give P X' (P a person of the scene or a
    pronoun, X the scene's objects)."""

    def given(m: re.Match[str]) -> str:
        who, what = m.group("p"), m.group("x")
        if not (who.lower() in ("him", "her", "them") or _only_person(who, lexicon)):
            return m[0]
        return f"{m.group('lead')}give {who} {what}" if _objects_only(what, lexicon) else m[0]

    return _sub(
        r"(?P<lead>(?:^|(?<=[,;.])\s*|\bso |\band |\bplease ))(?:pack|send|see) (?P<p>him|her|them|"
        r"[A-Z][\w]*(?: [A-Z][\w]*)?) off with (?P<x>(?:the|both|all) [a-z ,]+?)(?=\s*[.!]?$)",
        given,
        text,
    )


# "Crisps on the shelf, sorry, I meant to Person A."
_PLACE_TO30R = re.compile(
    r"^(?P<verb>(?:please )?(?:put|place|set|pop) )?(?P<x>(?:the )?[a-z]+(?: [a-z]+)??) "
    r"(?:on|onto|in|into) (?:the )?(?P<s>[a-z]+(?: [a-z]+)??),\s*(?:sorry|no|oops|whoops|my "
    r"mistake),\s*(?:i meant |i mean |no,\s*)?to (?P<p>[A-Za-z][\w ]*?)(?P<end>\s*[.!]?)$",
    _F,
)


def _place_to30r(text: str, lexicon: Lexicon) -> str:
    """Session 30 (12r): "Crisps on the shelf, sorry, I meant to Person A." — a placement whose
    place is corrected to a person ('to P' after the cue) is the object handed to P: X one name
    of the scene's objects, S a surface, P one person."""
    m = _PLACE_TO30R.match(text)
    if m is None or not _whole_name(m.group("x"), lexicon, "object"):
        return text
    if not _surface_only(m.group("s"), lexicon) or not _only_person(m.group("p"), lexicon):
        return text
    x = m.group("x")
    x = x if x.lower().startswith("the ") else f"the {x}"
    return f"Give {x} to {m.group('p')}{m.group('end')}"


# "…, doesn't matter which one, but only one."
_BUT_ONLY_ONE30R = re.compile(r",\s*(?:but )?(?:only|just) (?:the )?one(?P<end>\s*[.!]?)$", _F)


def _but_only_one30r(text: str, lexicon: Lexicon) -> str:
    """Session 30 (12r): ', but only one' closing a choice of one object among several ('put a
    box on the conveyor, doesn't matter which one, but only one') says again that one is meant:
    taken off when what is left reads as exactly one such choice."""
    m = _BUT_ONLY_ONE30R.search(text)
    if m is None:
        return text
    out = text[: m.start()] + (m.group("end") or ".")
    node = _reading(out, lexicon)
    if not isinstance(node, Group) or node.op != "or":
        return text
    if not all(isinstance(c, Task) for c in node.children):
        return text
    return out if len({t.target for t in tasks(node)}) == 1 else text


def _going_over30r(text: str, lexicon: Lexicon) -> str:
    """Session 30 (12r): 'are going over / across to P' is 'are going to P' ('over' says which
    way, as the grammar reads it after one object) when a name of the scene follows."""

    def gone(m: re.Match[str]) -> str:
        return f"{m.group(1)} to {m.group(2)}" if _names(m.group(2), lexicon) else m[0]

    return _sub(
        r"\b((?:are|is) going|go|goes) (?:over|across|round) to ((?:the )?[A-Za-z]+(?: [A-Z])?)\b",
        gone,
        text,
    )


# "Bottle on the shelf, no, there isn't one, just give it to Person A."
_NONE_THERE30R = re.compile(
    r"^(?P<x>(?:the )?[a-z]+(?: [a-z]+)??) (?:on|onto|in|into) (?:the )?[a-z]+(?: [a-z]+)??,\s*"
    r"(?:oh )?no,\s*(?:(?:there isn't one|there is not one|there's no (?:such )?[a-z]+|there is no "
    r"[a-z]+|we don't have one|we haven't got one)\s*[,;]\s*)?(?:just )?(?P<v>give|hand|pass|take|"
    r"bring) it (?P<rest>\S.*)$",
    _F,
)


def _none_there30r(text: str, lexicon: Lexicon) -> str:
    """Session 30 (12r): "Bottle on the shelf, no, there isn't one, just give it to Person A." —
    a verbless placement, then 'no' and a whole request for 'it' (with what is missing said
    between), is that request for the object: X one name of the scene's objects, and the request
    naming no other object."""
    m = _NONE_THERE30R.match(text)
    if m is None or not _whole_name(m.group("x"), lexicon, "object"):
        return text
    if _ids(m.group("rest"), lexicon, "object"):
        return text
    x = m.group("x")
    x = x if x.lower().startswith("the ") else f"the {x}"
    return f"{m.group('v').capitalize()} {x} {m.group('rest')}"


# "The crisps are Person A's; the bottle isn't."
_OWNED_NOT30R = re.compile(
    r"^(?P<x>the [a-z]+(?: [a-z]+)??) (?:is|are|'s|'re) (?P<p>[A-Za-z][\w ]*?)'s\s*[;,]\s*(?:but )?"
    r"(?P<y>the [a-z]+(?: [a-z]+)??) (?:isn't|aren't|is not|are not)(?P<end>\s*[.!]?)$",
    _F,
)


def _owned_not30r(text: str, lexicon: Lexicon) -> str:
    """Session 30 (12r): "The crisps are Person A's; the bottle isn't." — who gets what, said as
    whose things are whose, in contrast: 'X to P' (X and Y each one name of the scene's objects,
    different; P one person). Said alone, 'X is P's' may only say whose X is, and is not read."""
    m = _OWNED_NOT30R.match(text)
    if m is None or not _only_person(m.group("p"), lexicon):
        return text
    x, y = m.group("x"), m.group("y")
    if not (_whole_name(x, lexicon, "object") and _whole_name(y, lexicon, "object")):
        return text
    if _ids(x, lexicon) & _ids(y, lexicon):
        return text
    return f"{x[:1].upper()}{x[1:]} to {m.group('p')}{m.group('end')}"


# "Person B needs a drink, so the bottle to him"
_NEEDS_A30R = re.compile(
    r"^(?P<p>[A-Za-z][\w ]*?) (?:needs|wants|could use|could do with|would like|fancies) "
    r"(?:a|an|some|something) (?P<w>[a-z]+(?: [a-z]+)??)(?:,\s*so\s+(?P<so>\S.*)|\s+and (?:will|"
    r"would|'ll) (?P<v>take|have|accept|settle for) (?P<rest>\S.*))$",
    _F,
)


def _needs_a30r(text: str, lexicon: Lexicon) -> str:
    """Session 30 (12r): 'P needs a drink, so <request>' and 'P wants a drink and will take
    <objects>': what P needs said as a kind the scene does not name ('a drink', 'a snack'), then
    what to give: the request, its 'him' / 'her' P (the pronoun fitting P, and the request naming
    no other person), or 'P will take <objects>'."""
    m = _NEEDS_A30R.match(text)
    if m is None or not _only_person(m.group("p"), lexicon) or not _inert28(m.group("w"), lexicon):
        return text
    if _TIME30R.search(m.group("w")):
        return text
    p = m.group("p")
    if m.group("v"):
        rest = m.group("rest")
        if not _objects_only(re.split(r",", rest)[0], lexicon):
            return text
        return f"{p} will {m.group('v')} {rest}"
    rest = m.group("so")
    pronouns = re.findall(r"\b(him|her|them)\b", rest, _F)
    if len(pronouns) != 1 or not _fits(next(iter(_ids(p, lexicon))), pronouns[0].lower(), lexicon):
        return text
    if _ids(rest, lexicon, "human"):
        return text
    out = _sub(r"\b(?:him|her|them)\b", p, rest)
    return out[:1].upper() + out[1:]


# "Lena's carrying both plates out, so hand her the pair."
_PAIR_BACK30R = re.compile(
    r"^(?P<remark>[^,;.]*?\b(?:both|the two|the pair of) (?P<xs>[a-z]+s)\b[^,;.]*),\s*so\s+"
    r"(?P<req>[^,;.]*?\b)(?P<pair>the pair|the two|both of them|the two of them)(?P<end>\s*[.!]?)$",
    _F,
)


def _pair_back30r(text: str, lexicon: Lexicon) -> str:
    """Session 30 (12r): "Lena's carrying both plates out, so hand her the pair." — 'the pair'
    (or 'the two', 'both of them') closing a request after a remark that says 'both <Xs>' is
    those Xs, when the scene has exactly two of them."""
    m = _PAIR_BACK30R.match(text)
    if m is None or len(_ids(m.group("xs"), lexicon, "object")) != 2:
        return text
    if not _only_kind(m.group("xs"), lexicon, "object"):
        return text
    return f"{text[: m.start('pair')]}both {m.group('xs')}{m.group('end')}"


# "Sam's proofreading and just needs a pen, …", "Bob's a rower and wants the crisps, …"
_STATE_AND_WANT30R = re.compile(
    r"^(?P<p>[A-Za-z][\w ]*?)(?:'s| is| has) (?P<said>[a-z][a-z' -]*?) and (?:just |only |also )?"
    r"(?P<v>needs|wants|would like|'d like|is after|could use)\b",
    _F,
)


def _state_and_want30r(text: str, lexicon: Lexicon) -> str:
    """Session 30 (12r): 'P's <doing or being something> and (just) needs / wants …' is 'P needs
    / wants …': what P is doing, or is, joined by 'and' to what P wants, is a remark (its words
    naming nothing in the scene and holding no word that counts, chooses, negates or points
    back); P one person."""
    m = _STATE_AND_WANT30R.match(text)
    if m is None or not _only_person(m.group("p"), lexicon):
        return text
    if not _inert28(m.group("said"), lexicon):
        return text
    return f"{m.group('p')} {m.group('v')}{text[m.end() :]}"


# "Emma's a visiting palaeontologist and not fussy, so hand her either of the cups."
_AND_NOT_FUSSY30R = re.compile(
    r"^(?P<p>[A-Za-z][\w ]*?)(?:'s| is) (?P<said>[a-z][a-z' -]*?) and (?P<not>not (?:fussy|"
    r"bothered|particular|picky))(?=\s*,\s*so\b)",
    _F,
)
# "Noah and Zoe are doing a reading with the linguist; they can have a book apiece."
_THEY_AFTER30R = re.compile(
    r"^(?P<pq>[A-Za-z][\w ]*? and [A-Za-z][\w ]*?) (?:are|'re) (?P<said>[a-z][a-z' -]*?)\s*[;,]\s*"
    r"(?:so )?they (?P<rest>(?:can|could|should|will|each|both|get|have)\b.*)$",
    _F,
)


def _remark_then30r(text: str, lexicon: Lexicon) -> str:
    """Session 30 (12r): a remark about the people a request is for, said first: 'P's <a role>
    and not fussy, so …' is "P's not fussy, so …" (the remark's words naming nothing in the
    scene); 'P and Q are <doing something>; they can have …' is 'P and Q can have …' (P and Q
    two people of the scene, the remark naming nothing)."""
    m = _AND_NOT_FUSSY30R.match(text)
    if m is not None:
        if _only_person(m.group("p"), lexicon) and _inert28(m.group("said"), lexicon):
            return f"{m.group('p')}'s {m.group('not')}{text[m.end() :]}"
        return text
    m = _THEY_AFTER30R.match(text)
    if m is None or not _inert28(m.group("said"), lexicon):
        return text
    p, q = re.split(r" and ", m.group("pq"), maxsplit=1)
    if not (_only_person(p, lexicon) and _only_person(q, lexicon)):
        return text
    if _ids(p, lexicon) == _ids(q, lexicon) or _ids(m.group("rest"), lexicon, "human"):
        return text
    return f"{m.group('pq')} {m.group('rest')}"


# "Emma needs something to stir her tea; the spoon, mind, not the sponge."
_SOMETHING_TO30R = re.compile(
    r"^(?P<p>[A-Za-z][\w ]*?) (?P<v>needs|wants|would like) something"
    r"(?: to (?P<why>[a-z][a-z' ]*?))?\s*[;:]\s*(?P<rest>(?:the|a|an) \S.*)$",
    _F,
)


def _something_to30r(text: str, lexicon: Lexicon) -> str:
    """Session 30 (12r): 'P needs something to stir her tea; the spoon, (mind,) not the sponge'
    is 'P needs the spoon, …': what the thing is for (naming nothing in the scene) and then what
    it is, the first words after the mark naming the scene's objects."""
    m = _SOMETHING_TO30R.match(text)
    if m is None or not _only_person(m.group("p"), lexicon):
        return text
    if m.group("why") and (
        not _names_nothing(m.group("why"), lexicon) or _TIME30R.search(m.group("why"))
    ):
        return text
    rest = m.group("rest")
    if not _objects_only(re.split(r"[,;]", rest)[0], lexicon):
        return text
    return f"{m.group('p')} {m.group('v')} {rest}"


# "…, he's the only one who hasn't eaten.", "…, she's the only one diving."
_ONLY_ONE_WHO30R = re.compile(
    r",\s*(?P<who>she|he|they)(?:'s| is|'re| are) the only (?:one|ones|person|people)"
    r"(?P<said>(?: [a-z][a-z' -]*?)?)(?P<end>\s*[.!]?)$",
    _F,
)
_REMARK_KEEP30R = re.compile(
    r"\b(?:all|every|each|both|either|any|or|then|it|them|first|last|next|instead|except|give|"
    r"hand|take|put|bring)\b",
    _F,
)


def _only_one_who30r(text: str, lexicon: Lexicon) -> str:
    """Session 30 (12r): '…, he's the only one who hasn't eaten' closing a request says why the
    one person the request hands things to gets them: taken off, when its words name nothing in
    the scene and hold no word that chooses, counts or asks, and the pronoun fits that person;
    'and for nobody else' before it is ', nobody else'."""
    m = _ONLY_ONE_WHO30R.search(text)
    if m is None or not _names_nothing(m.group("said"), lexicon):
        return text
    if _REMARK_KEEP30R.search(m.group("said")):
        return text
    out = text[: m.start()] + (m.group("end") or ".")
    out = _sub(r"\band for (?=nobody else\b|no one else\b|no-one else\b)", ", ", out)
    said = _tasks_of(out, lexicon)
    if not said or any(k != "deliver" for k, _, _ in said):
        return text
    people = {t for _, _, t in said}
    if len(people) != 1 or not _fits(next(iter(people)), m.group("who").lower(), lexicon):
        return text
    return out


# "Emma isn't bothered which cup, either will do, …"
_WHICH_KIND30R = re.compile(
    r"^(?P<p>[A-Za-z][\w ]*?) (?:isn't|is not|'s not|doesn't mind|does not mind|doesn't care|does "
    r"not care)(?: (?:bothered|fussed|fussy|particular))? which (?P<x>[a-z]+)\s*,\s*"
    r"(?P<will>(?:either|any)(?: one)? (?:will do|is fine|'ll do))",
    _F,
)
# "Whichever thing's nearer your arm, that's the one for Person A."
_WHICHEVER_FIRST30R = re.compile(
    r"^whichever (?P<x>[a-z]+)(?:'s| is) (?P<how>nearer|closer|nearest|closest|handier|easier to "
    r"reach)(?: (?:to )?(?:your arm|the arm|you|the robot))?\s*,\s*that(?:'s| is) the one for "
    r"(?P<p>[A-Za-z][\w ]*?)(?P<end>\s*[.!]?)$",
    _F,
)


def _which_kind30r(text: str, lexicon: Lexicon) -> str:
    """Session 30 (12r): "Emma isn't bothered which cup, either will do, …" is 'Give Emma a cup,
    either will do, …' (the scene having two cups or more, P one person); "Whichever thing's
    nearer your arm, that's the one for Person A" is 'Give Person A whichever thing is nearer'
    (P one person; the grammar reads the kind, 'thing' for any object)."""
    m = _WHICH_KIND30R.match(text)
    if m is not None:
        if not _only_person(m.group("p"), lexicon):
            return text
        if len(_ids(m.group("x"), lexicon, "object")) < 2:
            return text
        if not _only_kind(m.group("x"), lexicon, "object"):
            return text
        return f"Give {m.group('p')} a {m.group('x')}, {m.group('will')}{text[m.end() :]}"
    m = _WHICHEVER_FIRST30R.match(text)
    if m is None or not _only_person(m.group("p"), lexicon):
        return text
    return f"Give {m.group('p')} whichever {m.group('x')} is nearer{m.group('end')}"


# "There's the only bottle here, sat by the arm; over to Person A with it."
_THERES_THE30R = re.compile(
    r"^there(?:'s| is) (?:the only|only the|the one|just the|the) (?P<x>[a-z]+(?: [a-z]+)??)"
    r"(?: here| there)?(?:\s*,\s*(?P<said>[a-z][a-z' ]*?))?\s*[;:]\s*(?P<rest>\S.*)$",
    _F,
)
_WITH_IT30R = re.compile(
    r"^(?P<dir>over|across|up|down|round) to (?P<p>[A-Za-z][\w ]*?) with (?P<x>it|them|the "
    r"[a-z]+(?: [a-z]+)??)(?P<end>\s*[.!]?)$",
    _F,
)


def _theres_the30r(text: str, lexicon: Lexicon) -> str:
    """Session 30 (12r): 'Over to P with it' is 'Take it over to P' (P one person); "There's the
    only bottle here, sat by the arm; <request for 'it'>" is that request for the bottle (the
    scene having one, what is said of it naming nothing else, the request naming no object and
    one 'it')."""
    m = _THERES_THE30R.match(text)
    if m is not None:
        x, rest = m.group("x"), m.group("rest")
        if not _only(x, lexicon, "object"):
            return text
        if m.group("said") and (
            not _names_nothing(m.group("said"), lexicon) or _REMARK_KEEP30R.search(m.group("said"))
        ):
            return text
        if len(re.findall(r"\bit\b", rest, _F)) != 1 or _ids(rest, lexicon, "object"):
            return text
        text = _sub(r"\bit\b", f"the {x}", rest)
        text = text[:1].upper() + text[1:]
    w = _WITH_IT30R.match(text)
    if w is None or not _only_person(w.group("p"), lexicon):
        return text
    return f"Take {w.group('x')} {w.group('dir')} to {w.group('p')}{w.group('end')}"


# "The cashier wants every box except the large one sent down the belt."
_WANTS_DOWN30R = re.compile(
    r"^(?P<who>[A-Za-z][\w' ]*?) (?:wants|needs|would like) (?P<x>(?:the|every|all|both) [a-z ]+?) "
    r"(?:sent|put|moved|run|loaded) (?:down|along|onto|on|up) (?:the )?(?P<s>[a-z]+)"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _wants_down30r(text: str, lexicon: Lexicon) -> str:
    """Session 30 (12r): 'W wants X sent down the belt' is 'Put X on the belt' (W someone the
    scene does not name, or one person of it: who asks; S a surface)."""
    m = _WANTS_DOWN30R.match(text)
    if m is None or not _surface_only(m.group("s"), lexicon):
        return text
    who = m.group("who")
    if not (_inert28(who, lexicon) or _only_person(who, lexicon)):
        return text
    return f"Put {m.group('x')} on the {m.group('s')}{m.group('end')}"


_STEPS30R: tuple[Callable[[str, Lexicon], str], ...] = (
    _no_odds30r,
    _whichever_of30r,
    _each_role30r,
    _lot_is30r,
    _every_last30r,
    _pronoun_is_to30r,
    _only_not30r,
    _only_who30r,
    _leaving_out30r,
    _rather_than30r,
    _rather_after30r,
    _i_mean_after30r,
    _sorry_after30r,
    _wants_sent30r,
    _beg_pardon30r,
    _waited30r,
    _not_cleft30r,
    _and_leave30r,
    _leave_on30r,
    _not_again30r,
    _did_i_say30r,
    _only_got30r,
    _things_here30r,
    _stays_put30r,
    _placed_for30r,
    _laid_out30r,
    _apiece30r,
    _off_with30r,
    _place_to30r,
    _but_only_one30r,
    _going_over30r,
    _none_there30r,
    _owned_not30r,
    _needs_a30r,
    _pair_back30r,
    _state_and_want30r,
    _remark_then30r,
    _something_to30r,
    _only_one_who30r,
    _which_kind30r,
    _theres_the30r,
    _wants_down30r,
)


# -- session 31 (12r): blind29's choices, counts, exclusions and corrections ------------------
# Each rule below rewrites one construction into the form the grammar reads, and leaves the text
# as it was when what the construction presupposes (one person, the scene's objects, a count)
# does not hold; docs/grounding.md, "Session 31 (engineer 12r)".

# "Either mug will do for Carol, she's not fussy.": the idiom with a clause after it
_WILL_DO_FOR31R = re.compile(
    r"^(?P<q>either|any) (?P<x>[a-z]+) (?:will do|would do|is fine|works) for "
    r"(?P<p>[A-Za-z][\w ]*?)(?=\s*,)",
    _F,
)
# "Either book will do, but it's for the student.": the person said after it
_WILL_DO_BUT31R = re.compile(
    r"^(?P<q>either|any) (?P<x>[a-z]+) (?:will do|would do|is fine|works),?\s*(?:but|and|only) "
    r"(?:it's|it is|it'll be|it will be|that's|that is) (?:for|going to) "
    r"(?P<p>[A-Za-z][\w ]*?)(?P<end>\s*[.!]?)$",
    _F,
)


def _will_do_for31r(text: str, lexicon: Lexicon) -> str:
    """Session 31 (12r): 'Either X will do for P' with a clause after it ('…, she's not fussy')
    is 'Either X for P, …' (as _speaker21's rule for the idiom alone); 'Either X will do, but
    it's for P' is 'Either X for P'. X a kind of the scene's objects, P words that name only
    people (one, or a role some share: the grammar then refuses with its readings)."""
    m = _WILL_DO_FOR31R.match(text) or _WILL_DO_BUT31R.match(text)
    if m is None or not _only_kind(m.group("x"), lexicon, "object"):
        return text
    p = m.group("p")
    named = _names(p, lexicon)
    if len(named) != 1 or not all(r.kind == "human" for r in named[0].refs):
        return text
    if not re.fullmatch(r"(?:the )?" + re.escape(named[0].text), p.strip(), _F):
        return text
    end = m.groupdict().get("end")
    rest = end if end is not None else text[m.end() :]
    return f"{m.group('q')} {m.group('x')} for {p}{rest}"


def _fine_by_me31r(text: str, _lexicon: Lexicon) -> str:
    """Session 31 (12r): "either's fine by me", "any one is fine with me" after a choice: the
    speaker saying any will do, as 'either is fine' (which the grammar reads as the choice's
    tail); 'me' there is who does not mind, not a recipient."""
    return _sub(
        r"\b(?P<q>either|any(?: one)?|whichever|both)(?:'s| is) (?P<how>fine|ok|okay|good|all "
        r"right|alright) (?:by|with) (?:me|us)(?=\s*(?:[.!,;]|$))",
        lambda m: f"{m.group('q')} is {m.group('how')}",
        text,
    )


# "Split the cup and the apple between A and B, whichever way round you like."
_SPLIT_WAY31R = re.compile(
    r"^(?P<head>(?:please )?(?:split|share|divide) the [a-z ]+? between [A-Za-z][\w ]*? and "
    r"[A-Za-z][\w ]*?),\s*(?:whichever|either|any) way(?: round| around)?(?: (?:you|u) "
    r"(?:like|want|please|prefer|fancy))?(?P<end>\s*[.!]?)$",
    _F,
)


def _split_way31r(text: str, lexicon: Lexicon) -> str:
    """Session 31 (12r): 'Split X between P and Q, whichever way round (you like)' is 'Split X
    between P and Q, one each' (_split29r's form, which checks that X names two objects and P and
    Q two people, and leaves the text otherwise)."""
    m = _SPLIT_WAY31R.match(text)
    if m is None:
        return text
    out = f"{m.group('head')}, one each{m.group('end')}"
    return out if _split29r(out, lexicon) != out else text


# "Whichever's handier, the bottle or the chips, hand it to Person A."
_WHICHEVER_FRONT31R = re.compile(
    r"^whichever(?:'s| is) (?P<how>handier|nearer|closer|easier(?: to (?:reach|grab|get))?|"
    r"nearest|closest)\s*,\s*(?P<list>(?:the |a |an )?[a-z]+(?: [a-z]+)?? or (?:the |a |an )?"
    r"[a-z]+(?: [a-z]+)??)\s*,\s*(?P<rest>[^,;:.!?]+?)(?P<end>\s*[.!]?)$",
    _F,
)


def _whichever_front31r(text: str, lexicon: Lexicon) -> str:
    """Session 31 (12r): "Whichever's handier, X or Y, hand it to P" is 'hand X or Y to P,
    whichever's handier' (the tail the grammar reads): X and Y each one object of the scene, the
    request after them naming no object and holding one 'it' for the choice."""
    m = _WHICHEVER_FRONT31R.match(text)
    if m is None:
        return text
    items = re.split(r"\s+or\s+", m.group("list"))
    if not all(_whole_name(x, lexicon, "object") and len(_ids(x, lexicon)) == 1 for x in items):
        return text
    rest = m.group("rest")
    if len(re.findall(r"\bit\b", rest, _F)) != 1 or _ids(rest, lexicon, "object"):
        return text
    if re.search(r"\b(?:them|they|one|other|each|both|not|no|don't)\b", rest, _F):
        return text
    said = _sub(r"\bit\b", m.group("list"), rest)
    return f"{said[:1].upper()}{said[1:]}, whichever's {m.group('how')}{m.group('end') or '.'}"


# "Whichever bottle's there, Person A gets it."
_WHICHEVER_THERE31R = re.compile(
    r"^whichever (?P<x>[a-z]+)(?:'s| is) (?:there|here|about|around|left)\s*,\s*"
    r"(?P<rest>[^,;:.!?]+?)(?P<end>\s*[.!]?)$",
    _F,
)


def _whichever_there31r(text: str, lexicon: Lexicon) -> str:
    """Session 31 (12r): "Whichever bottle's there, P gets it" is 'P gets the bottle' when the
    scene has one object of that kind (the words presuppose one; with two, which one is 'there'
    is not said, and the text is left, refused). The request after it names no object and holds
    one 'it'."""
    m = _WHICHEVER_THERE31R.match(text)
    if m is None or not _only(m.group("x"), lexicon, "object"):
        return text
    if not _only_kind(m.group("x"), lexicon, "object"):
        return text
    rest = m.group("rest")
    if len(re.findall(r"\bit\b", rest, _F)) != 1 or _ids(rest, lexicon, "object"):
        return text
    said = _sub(r"\bit\b", f"the {m.group('x')}", rest)
    return f"{said[:1].upper()}{said[1:]}{m.group('end')}"


def _of_their_own31r(text: str, lexicon: Lexicon) -> str:
    """Session 31 (12r): 'each of the patients … a blanket of their own' is '… a blanket': 'of
    their own' says again that each gets a different one, which 'each' already shares out. Only
    after 'each' (or 'every') in the same sentence; 'Make sure each of the Rs ends up with' is
    'Each R should get' (the role said by the scene's people)."""
    if not re.search(r"\b(?:each|every)\b", text, _F):
        return text
    out = _sub(
        r"\b(?P<x>an? [a-z]+) of (?:their|his|her|his or her) (?:very )?own\b",
        lambda m: m.group("x"),
        text,
    )
    if out == text:
        return text

    def each(m: re.Match[str]) -> str:
        role = m.group("role").lower()
        if sum(role in (a.lower() for a in h.aliases) for h in lexicon.scene.humans) < 2:
            return m[0]
        return f"Each {role} should get"

    return _sub(
        r"^(?:please )?(?:make sure|ensure|see that|see to it that) each of the (?P<role>[a-z]+)s "
        r"(?:ends up with|gets|has|receives)",
        each,
        out,
    )


def _play_with31r(text: str, lexicon: Lexicon) -> str:
    """Session 31 (12r): "Ava may play with one of the blocks, either, she's not fussy about
    colour": 'P may / can play with X' is 'P can have X' (a toy handed to P to play with; P one
    person, X the scene's objects); ', either,' after a choice says it again (taken off); 'not
    fussy about colour' is 'not fussy'."""
    m = re.match(
        r"^(?P<p>[A-Za-z][\w ]*?) (?:may|can|could|gets to|is allowed to) play with "
        r"(?P<x>(?:one of the|either of the|any of the|the|a|an|either) [a-z]+(?: [a-z]+)??)"
        r"(?=\s*(?:[,.!;]|$))",
        text,
        _F,
    )
    if m is None or not _only_person(m.group("p"), lexicon):
        return text
    if not _objects_only(m.group("x"), lexicon):
        return text
    rest = text[m.end() :]
    if re.match(r"\s*,\s*either\s*,", rest, _F) and re.match(
        r"(?:one|either|any) of\b|either\b|an?\b", m.group("x"), _F
    ):
        rest = ", " + rest.split(",", 2)[2].lstrip()
    rest = _sub(
        r"\b(not (?:fussy|fussed|bothered|particular)) (?:about|on|over) (?:the )?(?:colou?rs?|"
        r"sizes?|shapes?|which(?: one)?)\b",
        r"\1",
        rest,
    )
    return f"{m.group('p')} can have {m.group('x')}{rest}"


# "Hand over two things to Person A, namely the apple and the cup."
_NAMELY31R = re.compile(
    r"\b(?P<n>two|three|four|five|2|3|4|5) (?:things|items|objects|bits)(?P<mid>(?: [a-z][\w ]*?)?)"
    r",\s*(?:namely|that is|i\.e\.,?|to wit|specifically|viz\.?|which are) "
    r"(?P<list>(?:the |a |an )?[a-z]+(?: [a-z]+)?(?:(?:,\s*|,? and )(?:the |a |an )?[a-z]+"
    r"(?: [a-z]+)?)+)(?P<end>\s*[.!]?)$",
    _F,
)


def _namely31r(text: str, lexicon: Lexicon) -> str:
    """Session 31 (12r): 'Hand over two things to P, namely X and Y' is 'Hand over X and Y to
    P': the list says what the count counted, when it names that many objects of the scene, one
    each and different, and what stood between them names only people or surfaces."""
    m = _NAMELY31R.search(text)
    if m is None:
        return text
    items = [w for w in re.split(r"\s*,\s*(?:and\s+)?|\s+and\s+", m.group("list").strip()) if w]
    n = m.group("n").lower()
    want = int(n) if n.isdigit() else _COUNTS[n]
    if len(items) != want or not all(_whole_name(w, lexicon, "object") for w in items):
        return text
    ids = [_ids(w, lexicon, "object") for w in items]
    if any(len(i) != 1 for i in ids) or len(set().union(*ids)) != want:
        return text
    if _ids(m.group("mid"), lexicon, "object"):
        return text
    said = ", ".join(items[:-1]) + " and " + items[-1]
    return f"{text[: m.start()]}{said}{m.group('mid')}{m.group('end')}"


# "Person B wants only one item, and it's the bottle."
_ONLY_ONE_ITEM31R = re.compile(
    r"^(?P<p>[A-Za-z][\w ]*?) (?P<v>wants|needs|would like|is after|asked for|gets|should get|"
    r"can have) (?:only |just )?(?:one|a single) (?:thing|item|object),?\s*(?:and|which is) "
    r"(?:it's|it is|that's|that is|that'll be|it'll be)? ?(?P<x>(?:the |that )[a-z]+(?: [a-z]+)?)"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _only_one_item31r(text: str, lexicon: Lexicon) -> str:
    """Session 31 (12r): "P wants only one item, and it's the X" is 'P wants the X' (P one
    person, X one object of the scene: the count is the one the name meets)."""
    m = _ONLY_ONE_ITEM31R.match(text)
    if m is None or not _only_person(m.group("p"), lexicon):
        return text
    x = re.sub(r"^that ", "the ", m.group("x"), flags=_F)
    if not _whole_name(x, lexicon, "object") or len(_ids(x, lexicon)) != 1:
        return text
    return f"{m.group('p')} {m.group('v')} {x}{m.group('end')}"


def _alike31r(text: str, lexicon: Lexicon) -> str:
    """Session 31 (12r): '…, the bottle and the chips alike' closing a list of objects is the
    list ('alike' says the same of each, as 'both' before it would)."""

    def said(m: re.Match[str]) -> str:
        return m.group("list") + m.group("end") if _objects_only(m.group("list"), lexicon) else m[0]

    return _sub(
        r"(?P<list>(?:the |a |an )?[a-z]+(?: [a-z]+)?(?:(?:,\s*|,? and )(?:the |a |an )?[a-z]+"
        r"(?: [a-z]+)?)+) (?:alike|both|the pair of them)(?P<end>\s*[.!]?)$",
        said,
        text,
    )


def _solitary31r(text: str, lexicon: Lexicon) -> str:
    """Session 31 (12r): 'our solitary bottle', 'the lone cup', 'a single bottle will do for P':
    a word saying there is one is 'the X' when the scene has exactly one X (else left: 'the
    solitary mug' with two mugs is refused)."""

    def one(m: re.Match[str]) -> str:
        x = m.group("x")
        if not _only(x, lexicon, "object") or not _only_kind(x, lexicon, "object"):
            return m[0]
        return f"{m.group('lead') or ''}the {x}"

    out = _sub(
        r"(?P<lead>^|\b)(?:our|my|the|your) (?:solitary|sole|lone|one and only|single|only "
        r"remaining) (?P<x>[a-z]+)\b",
        one,
        text,
    )
    m = re.match(
        r"^(?:an?|one|a single) (?P<x>[a-z]+) (?:will do|would do|is fine|is enough) (?:for|to) "
        r"(?P<p>[A-Za-z][\w ]*?)(?=\s*(?:[,.!;]|$))",
        out,
        _F,
    )
    if (
        m is not None
        and _only(m.group("x"), lexicon, "object")
        and _only_person(m.group("p"), lexicon)
    ):
        out = f"The {m.group('x')} for {m.group('p')}{out[m.end() :]}"
    return out


def _every_one_of_them31r(text: str, lexicon: Lexicon) -> str:
    """Session 31 (12r): 'the three pens, every one of them,' (and 'all of them', 'the lot of
    them', 'each and every one') after a plural of the scene's objects says again that all are
    meant: taken off, when the plural before it names several objects."""

    def again(m: re.Match[str]) -> str:
        x = m.group("x")
        if not _objects_only(x, lexicon) or len(_ids(x, lexicon, "object")) < 2:
            return m[0]
        return f"{x}{m.group('end')}"

    return _sub(
        r"(?P<x>\bthe (?:(?:two|three|four|five) )?[a-z]+s),\s*(?:every (?:single |last )?one of "
        r"them|all of them|the lot of them|each and every one(?: of them)?|the whole lot)"
        r"(?P<end>\s*,|\s*[.!]?$)",
        again,
        text,
    )


def _gather_up31r(text: str, lexicon: Lexicon) -> str:
    """Session 31 (12r): 'Gather up X and drop them in / on S' is 'Put X in / on S' ('gather up'
    collects the objects, 'drop' sets them down: a placement; X the scene's objects, S one
    surface)."""
    m = re.match(
        r"^(?:please )?(?:gather|collect|round) up (?P<x>[^,;:.!?]+?),?\s*and (?:drop|pop|put|"
        r"place|stick|chuck) (?:them|it) (?P<on>in|into|on|onto|inside) (?P<s>(?:the )?[a-z]+"
        r"(?: [a-z]+)?)(?P<end>\s*[.!]?)$",
        text,
        _F,
    )
    if m is None or not _objects_only(m.group("x"), lexicon):
        return text
    if not _surface_only(m.group("s"), lexicon):
        return text
    return f"Put {m.group('x')} {m.group('on')} {m.group('s')}{m.group('end')}"


# "Bob wants a mug, but not the red one, he can't stand red."
_CANT_STAND31R = re.compile(
    r"(?P<keep>\bnot the (?P<a>[a-z]+) (?:one|[a-z]+)),\s*(?:(?:he|she|they|i|we)(?: just)? "
    r"(?:can't stand|cannot stand|can't abide|can't bear|hates?|dislikes?|doesn't like|don't like|"
    r"isn't keen on|aren't keen on|is not keen on|won't have|doesn't want|don't want)) "
    r"(?P<b>[a-z]+)(?: ones?| things?)?(?P<end>\s*[.!]?)$",
    _F,
)


def _cant_stand31r(text: str, lexicon: Lexicon) -> str:
    """Session 31 (12r): '…, but not the red one, he can't stand red' — a reason closing an
    exclusion, that says the excluded word again ('red' after 'not the red one'), is taken off:
    it leaves out what the exclusion already leaves out. Another word ('…, he can't stand
    blue') is left, refused."""
    m = _CANT_STAND31R.search(text)
    if m is None or m.group("a").lower() != m.group("b").lower():
        return text
    if not _names_nothing(m.group("b"), lexicon) and not _ids(m.group("keep"), lexicon):
        return text
    return text[: m.end("keep")] + (m.group("end") or ".")


# "The cup's meant for Person B; don't give it to Person A by mistake."
_BY_MISTAKE31R = re.compile(
    r"^(?P<req>[^;.!?]+?)\s*(?P<mark>[;.]|,\s*(?:but|and|so)?)\s*(?P<neg>(?:but |and |so |just )?"
    r"(?:don't|do not|never) (?:give|hand|pass|bring|take|send|put|place) )(?P<it>it|them) "
    r"(?P<to>(?:to|on|onto|in|into) [^,;.!?]+?)(?: by (?:mistake|accident)| in error)?"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _by_mistake31r(text: str, lexicon: Lexicon) -> str:
    """Session 31 (12r): "<request of X for P>; don't give it to Q (by mistake)": 'it' in the
    negated command is the request's one object, said by its name (the negated command then
    reads as the grammar's 'Don't give the X to Q' beside a request, dropped only when no task
    of it is one of the request's); 'by mistake' says why it is not wanted; "the cup's meant for
    P" is "the cup is for P". Left where the request names no object or several."""
    m = _BY_MISTAKE31R.match(text)
    if m is None:
        return text
    req = _sub(
        r"^(?P<x>(?:the |that |this )[a-z]+(?: [a-z]+)?)(?:'s| is) (?:meant|intended) for\b",
        r"\g<x> is for",
        m.group("req"),
    )
    named = [it for it in _names(req, lexicon) if it.refs[0].kind == "object"]
    if len(named) != 1 or len({r.id for r in named[0].refs}) != 1:
        return text
    if _ids(m.group("to"), lexicon, "object"):
        return text
    mark = m.group("mark").strip()
    sep = ". " if mark in (".", ";") else ", but "
    neg = m.group("neg").strip()
    neg = re.sub(r"^(?:but|and|so|just) ", "", neg, flags=_F)
    neg = neg[:1].upper() + neg[1:] if sep == ". " else neg
    return f"{req}{sep}{neg} the {named[0].text} {m.group('to')}{m.group('end') or '.'}"


# "Of the two things, Person A wants the one that isn't a bag of chips."
_ONE_THAT_ISNT31R = re.compile(
    r"^of the two(?: (?:things|items|objects))?,\s*(?P<p>[A-Za-z][\w ]*?) (?P<v>wants|needs|"
    r"gets|should get|can have|would like) the one (?:that|which)(?:'s| is)? (?:isn't|is not|"
    r"'s not|aren't|are not) (?:a (?:bag|packet|bottle|cup|box) of |the |an? )?(?P<x>[a-z]+"
    r"(?: [a-z]+)?)(?P<end>\s*[.!]?)$",
    _F,
)


def _one_that_isnt31r(text: str, lexicon: Lexicon) -> str:
    """Session 31 (12r): "Of the two things, P wants the one that isn't (a bag of) X" is 'P
    wants the Y', Y the scene's other object, when the scene has exactly two objects and X names
    one of them ('a bag of chips' the chips)."""
    m = _ONE_THAT_ISNT31R.match(text)
    if m is None or len(lexicon.scene.objects) != 2 or not _only_person(m.group("p"), lexicon):
        return text
    x = m.group("x")
    if not _whole_name(x, lexicon, "object") or len(_ids(x, lexicon)) != 1:
        return text
    other = [o.id for o in lexicon.scene.objects if o.id not in _ids(x, lexicon)]
    if len(other) != 1:
        return text
    return f"{m.group('p')} {m.group('v')} the {other[0]}{m.group('end')}"


def _not_to_semi31r(text: str, _lexicon: Lexicon) -> str:
    """Session 31 (12r): 'Not to P; the X goes to Q' is 'Not to P, …' (what _negated reads: the
    person left out, said first), the semicolon a pause as the comma is."""
    return _sub(r"^(not (?:to|for) [A-Za-z][\w ]*?)\s*;\s*(?=\S)", r"\1, ", text)


def _no_one_elses31r(text: str, lexicon: Lexicon) -> str:
    """Session 31 (12r): "That bottle is P's and no one else's, so see she gets it": 'and no one
    else's' (or 'nobody else's') after whose it is says only that P is the one (taken off); 'see
    (that) she gets it' is 'make sure she gets it'."""
    m = re.search(r"'s,? and (?:no one|no-one|nobody|not anybody|not anyone) else's\b", text, _F)
    if m is None:
        return text
    words = text[: m.start()].split(" ")
    if not any(_only_person(" ".join(words[-n:]), lexicon) for n in (1, 2, 3)):
        return text
    out = f"{text[: m.start()]}'s{text[m.end() :]}"
    return _sub(r"\bso see (?:that )?(?=(?:she|he|they) gets?\b)", "so make sure ", out)


# "No bottle for Person B today, just his chips."
_NO_X_JUST31R = re.compile(
    r"^no (?P<x>[a-z]+(?: [a-z]+)?) (?:for|to) (?P<p>[A-Za-z][\w ]*?)(?: today| this time| now)?"
    r",\s*(?:just|only) (?:his|her|their|the) (?P<y>[a-z]+(?: [a-z]+)?)(?P<end>\s*[.!]?)$",
    _F,
)


def _no_x_just31r(text: str, lexicon: Lexicon) -> str:
    """Session 31 (12r): "No X for P (today), just his Y" is 'P gets the Y, not the X' (X and Y
    objects of the scene, one each and different, P one person)."""
    m = _NO_X_JUST31R.match(text)
    if m is None or not _only_person(m.group("p"), lexicon):
        return text
    x, y = m.group("x"), m.group("y")
    if not (_whole_name(x, lexicon, "object") and _whole_name(y, lexicon, "object")):
        return text
    if len(_ids(y, lexicon)) != 1 or _ids(x, lexicon) & _ids(y, lexicon):
        return text
    return f"{m.group('p')} gets the {y}, not the {x}{m.group('end')}"


# "Leave the teddy; the bib to Lily."
_LEAVE_FIRST31R = re.compile(
    r"^(?:just )?leave (?P<x>the [a-z]+(?: [a-z]+)?)(?: (?:alone|be|where it is|where they are|"
    r"there|for now|out of it))?\s*[;:.]\s*(?P<rest>\S.*)$",
    _F,
)


def _leave_first31r(text: str, lexicon: Lexicon) -> str:
    """Session 31 (12r): "Leave the X; <request>" (a sentence or a clause of its own ending in a
    semicolon, colon or stop) says the X is not to be moved: the request alone, when it names
    neither the X nor 'it'/'them' and reads with no task of the X. 'Leave the X on S' (a
    placement) is not this form."""
    m = _LEAVE_FIRST31R.match(text)
    if m is None or not _whole_name(m.group("x"), lexicon, "object"):
        return text
    rest = m.group("rest")
    if re.search(r"\b(?:it|them|that|those|instead|too|also|as well|then)\b", rest, _F):
        return text
    if _ids(rest, lexicon, "object") & _ids(m.group("x"), lexicon):
        return text
    said = _tasks_of(rest, lexicon)
    if not said or {o for _, o, _ in said} & _ids(m.group("x"), lexicon):
        return text
    return rest[:1].upper() + rest[1:]


# what a speaker says of their own slip, between a correction's cue and the corrected words: a
# closed list ("I tell a lie", "I've got them mixed up again", "I've got that wrong")
_SLIP31R = (
    r"(?:i tell a lie|i(?:'ve| have)? got (?:them|it|that|those|this|these) (?:all )?(?:mixed up|"
    r"muddled(?: up)?|wrong|the wrong way round|back to front)(?: again)?|i(?:'ve| have)? "
    r"(?:mixed|muddled) (?:them|it|that|those) up(?: again)?|silly me|what am i saying)"
)
_SLIP_AFTER_CUE31R = re.compile(
    rf"(?P<cue>,\s*(?:{_CUE19}|no|wait|hang on|hold on|oh)\s*),\s*{_SLIP31R}\s*,\s*(?=\S)", _F
)
_SLIP_ALONE31R = re.compile(rf"(?P<lead>,\s*){_SLIP31R}\s*,\s*(?=\S)", _F)
# "Give Person A the chips, I got them mixed up.": the slip closing the text, nothing after it
_SLIP_CLOSING31R = re.compile(
    rf"[,;.!]\s*(?:(?:oh|ah|no|sorry|wait|whoops|oops)\s*,?\s*)*(?P<said>{_SLIP31R})"
    r"(?:\s*,?\s*(?:sorry|again|there))*\s*[.!]?\s*$",
    _F,
)
# "…, it's Person A.", "…, it's Zoe's turn.": the corrected person in a cleft
_ITS_WHO31R = re.compile(
    r"(?P<lead>,\s*)it(?:'s| is) (?P<p>[A-Za-z][\w ]*?)(?:'s turn| who (?:wants|wanted|needs|"
    r"needed|asked for|ordered) it)?(?P<end>\s*[.!]?)$",
    _F,
)


def _slip31r(text: str, lexicon: Lexicon) -> str:
    """Session 31 (12r): the speaker's words about their own slip ('I tell a lie', "I've got
    them mixed up again", "I've got that wrong") after a correction's cue are taken off (the cue
    corrects); without a cue before them they are the cue ('no'). Then "…, it's P" or "it's P's
    turn" closing the correction is 'P' (one person of the scene), the form the grammar reads.
    A slip said after a correction already made ("The chips, no, the bottle, silly me, to P") is
    left: it speaks of that one. A slip closing the text ("Give Person A the chips, I got them
    mixed up.") says the request is wrong and not what is right: refused (it had been taken off
    as a remark, and the request read)."""
    closing = _SLIP_CLOSING31R.search(text)
    if closing is not None:
        raise GroundingError(
            f"{closing.group('said')!r} says what was asked is wrong, but not what is right: "
            "say the whole request again"
        )
    out = _SLIP_AFTER_CUE31R.sub(lambda m: f"{m.group('cue')}, ", text)
    alone = _SLIP_ALONE31R.search(text) if out == text else None
    if alone is not None:
        if re.search(
            rf"(?:^|[,.;!?]\s*)(?:{_CUE19}|no|wait|hang on|hold on|actually)\b",
            text[: alone.start()],
            _F,
        ):
            return text  # "The chips, no, the bottle, silly me, to Person A": after a correction
        out = f"{text[: alone.start()]}{alone.group('lead')}no, {text[alone.end() :]}"
    if out == text:
        return text
    m = _ITS_WHO31R.search(out)
    if m is not None and _only_person(m.group("p"), lexicon):
        out = f"{out[: m.start()]}{m.group('lead')}{m.group('p')}{m.group('end')}"
    return out


# "The bottle to Person A. Yes, Person A, I did mean her."
_YES_MEANT31R = re.compile(
    r"(?P<lead>[.!]\s+)(?:yes|yeah|yep|yup|that's right),?\s+(?P<p>[A-Za-z][\w ]*?)"
    r"(?:,?\s*(?:i (?:did )?mean(?:t)? (?:her|him|them|it)|that's (?:right|who i meant)|"
    r"(?:she|he)'s the one))?\s*[.!]?$",
    _F,
)


def _yes_meant31r(text: str, lexicon: Lexicon) -> str:
    """Session 31 (12r): a last sentence 'Yes, P(, I did mean her)' after a request whose one
    recipient is P says the request again: taken off (the pronoun fitting P). Where the request
    gives to someone else, or to several, it is left (a correction, refused)."""
    m = _YES_MEANT31R.search(text)
    if m is None or not _only_person(m.group("p"), lexicon):
        return text
    before = text[: m.start()] + m.group("lead").strip()
    said = _tasks_of(before, lexicon)
    who = _ids(m.group("p"), lexicon)
    if not said or {t for _, _, t in said} != who:
        return text
    if not _fits(next(iter(who)), text[m.start() :], lexicon):
        return text
    return before


# "…, oh, hold on, the sink's a better home for it."; "…, no, better down on the play mat."
_BETTER_HOME31R = re.compile(
    r"(?P<cue>,\s*(?:(?:oh|ah),?\s*)?(?:hold on|hang on|wait|no|actually|on second thoughts?)"
    r"(?:,?\s*(?:no|actually))?,?\s*)(?:(?P<s>the [a-z]+(?: [a-z]+)?)(?:'s| is|'d be| would be) "
    r"(?:a |the )?better (?:home|place|spot|bet|choice)(?: for (?:it|them))?|better(?: off)?"
    r"(?: down| up)? (?P<on>on|in|onto|into) (?P<s2>the [a-z]+(?: [a-z]+)?))(?P<end>\s*[.!]?)$",
    _F,
)


def _better_home31r(text: str, lexicon: Lexicon) -> str:
    """Session 31 (12r): a correction of a placement that says the new place is better ('…, hold
    on, the sink's a better home for it', '…, no, better down on the play mat') is '…, no, on
    the S' when S is one surface of the scene and the request before places one object."""
    m = _BETTER_HOME31R.search(text)
    if m is None:
        return text
    s = m.group("s") or m.group("s2")
    if not _surface_only(s, lexicon):
        return text
    said = _tasks_of(text[: m.start()], lexicon)
    if not said or len(said) != 1 or next(iter(said))[0] != "place":
        return text
    on = m.group("on") or "on"
    return f"{text[: m.start()]}, no, {on} {s}{m.group('end') or '.'}"


def _sit_stand31r(text: str, lexicon: Lexicon) -> str:
    """Session 31 (12r): 'Sit / stand / prop / perch X on / in S' is 'Put X on / in S' (X the
    scene's objects, S one surface: where a thing is set down upright)."""

    def put(m: re.Match[str]) -> str:
        if not _objects_only(m.group("x"), lexicon) or not _surface_only(m.group("s"), lexicon):
            return m[0]
        return f"{m.group('lead')}{'P' if m.group('v')[0].isupper() else 'p'}ut {m.group('x')} "

    return _sub(
        r"(?P<lead>^|(?<=[,;.!?])\s*|\bplease )(?P<v>sit|stand|prop|perch)(?: (?:up|down))? "
        r"(?P<x>(?:the|both|all the) [a-z]+(?: [a-z]+)??) (?=(?:up |down |back )?(?:on|in|onto|"
        r"into|on top of) (?P<s>the [a-z]+(?: [a-z]+)?)\b)",
        put,
        text,
    )


# "For Person B, any one of these: the cup, the apple, the bottle."
_THESE_LISTED31R = re.compile(
    r"(?:\b(?:any|either|just) )?\bone of (?:these|those|them|the following|"
    r"the (?P<n>two|three|four)(?: of them)?)\s*:\s*(?P<list>(?:the |a |an )?[a-z]+(?: [a-z]+)?"
    r"(?:(?:,\s*|,? (?:and|or) )"
    r"(?:the |a |an )?[a-z]+(?: [a-z]+)?)+)(?P<end>\s*(?:[.!;]|$))",
    _F,
)


def _these_listed31r(text: str, lexicon: Lexicon) -> str:
    """Session 31 (12r): 'any one of these: X, Y, Z' (a chooser pointing at a list said after a
    colon) is 'X, Y or Z', when the list names objects of the scene, one each and different (as
    many as a number said with it); the grammar reads the choice."""
    m = _THESE_LISTED31R.search(text)
    if m is None:
        return text
    items = [
        w for w in re.split(r"\s*,\s*(?:and\s+|or\s+)?|\s+(?:and|or)\s+", m.group("list")) if w
    ]
    if not all(_whole_name(w, lexicon, "object") for w in items):
        return text
    ids = [_ids(w, lexicon, "object") for w in items]
    if any(len(i) != 1 for i in ids) or len(set().union(*ids)) != len(items):
        return text
    if m.group("n") and _COUNTS[m.group("n").lower()] != len(items):
        return text
    said = ", ".join(items[:-1]) + " or " + items[-1]
    return f"{text[: m.start()]}{said}{m.group('end')}{text[m.end() :]}"


def _wont_mind31r(text: str, _lexicon: Lexicon) -> str:
    """Session 31 (12r): "She won't mind." / ", he wouldn't mind" after a choice (an 'or',
    'either', 'any', 'one of', 'whichever' before it) is 'she doesn't mind' (the chooser's tail
    the grammar reads); after no choice the negation is left, and refused."""
    m = re.search(
        r"(?P<lead>(?:[.!]\s+|,\s*))(?P<who>she|he|they|i|we) (?:won't|will not|wouldn't|would "
        r"not) mind(?P<tail>(?: which(?: one)?)?)(?P<end>\s*[.!]?)$",
        text,
        _F,
    )
    if m is None or not re.search(r"\b(?:or|either|any|one of|whichever)\b", text[: m.start()], _F):
        return text
    who = m.group("who")
    verb = "don't" if who.lower() in ("i", "we", "they") else "doesn't"
    return f"{text[: m.start()]}{m.group('lead')}{who} {verb} mind{m.group('tail')}{m.group('end')}"


# "Lena doesn't want the blue plate, just the white one."
_DOESNT_WANT_JUST31R = re.compile(
    r"^(?P<p>[A-Za-z][\w ]*?) (?:doesn't|does not|don't|do not) (?:want|need) (?P<x>the [a-z]+"
    r"(?: [a-z]+)?)\s*[,;]\s*(?:just|only|but|she wants|he wants|they want) (?P<y>the [a-z]+"
    r"(?: [a-z]+)?)(?P<end>\s*[.!]?)$",
    _F,
)


def _doesnt_want_just31r(text: str, lexicon: Lexicon) -> str:
    """Session 31 (12r): "P doesn't want the X, just the Y" is 'P wants the Y, not the X' (P one
    person; the grammar checks X and Y, 'the white one' included)."""
    m = _DOESNT_WANT_JUST31R.match(text)
    if m is None or not _only_person(m.group("p"), lexicon):
        return text
    return f"{m.group('p')} wants {m.group('y')}, not {m.group('x')}{m.group('end')}"


def _meant_to_say31r(text: str, _lexicon: Lexicon) -> str:
    """Session 31 (12r): 'I meant to say', 'I should have said' in a correction are 'I meant';
    'better make it' / 'best make it' is 'make it'."""
    out = _sub(
        r"\bi (?:meant|mean|wanted) to say\b|\bi should(?: have|'ve) said\b",
        lambda m: "I meant" if m[0][0] == "I" else "i meant",
        text,
    )
    return _sub(
        r"(?<=,)(\s*)(?:(?:hmm|um|er),?\s*)?(?:better|best) (?=make (?:it|that)\b)", r"\1", out
    )


# "Tongs to Lena, hold on, it's Mr Novak who wants them."
_ITS_WHO_CUE31R = re.compile(
    rf"(?P<cue>,\s*(?:{_CUE19}|no|wait|hang on|hold on|actually)\s*,\s*)it(?:'s| is| was) "
    r"(?P<p>[A-Za-z][\w ]*?)(?:'s turn| who (?:wants|wanted|needs|needed|asked for|ordered|"
    r"is after|was after) (?:it|them|that|those)| who asked)?(?P<end>\s*[.!]?)$",
    _F,
)


def _its_who_cue31r(text: str, lexicon: Lexicon) -> str:
    """Session 31 (12r): "…, hold on, it's P who wants them", "…, wait, it's P's turn" or "…,
    no, it's P" after a request is '…, hold on, P' (the corrected person, one of the scene)."""
    m = _ITS_WHO_CUE31R.search(text)
    if m is None or not _only_person(m.group("p"), lexicon):
        return text
    return f"{text[: m.start()]}{m.group('cue')}{m.group('p')}{m.group('end') or '.'}"


# "Put the boxes on the pallet, leave the big one where it is." / "…, the big one can stay put."
_LEAVE_WHERE31R = re.compile(
    r",\s*(?:but |and )?(?:(?:just |please )?leave (?P<x>the [a-z]+(?: [a-z]+)?) (?:where it is|"
    r"where they are|alone|be|as it is|as they are|in place|untouched)|"
    r"(?P<y>the [a-z]+(?: [a-z]+)?) (?:can stay|stays|should stay|can remain|remains|is "
    r"staying) (?:where it is|put|there|behind|in place|as it is))(?P<end>\s*[.!]?)$",
    _F,
)


def _leave_where31r(text: str, lexicon: Lexicon) -> str:
    """Session 31 (12r): '…, leave the big one where it is' / 'alone', '…, the big one can stay
    where it is' closing a request is '…, except the big one' (what the grammar reads as an
    exclusion), when the words name objects only ('one' for a kind said before) and the request
    before names some object."""
    m = _LEAVE_WHERE31R.search(text)
    if m is None:
        return text
    x = m.group("x") or m.group("y")
    if x.lower().split()[-1] not in ("one", "ones") and not _objects_only(x, lexicon):
        return text
    if not _ids(text[: m.start()], lexicon, "object"):
        return text
    return f"{text[: m.start()]}, except {x}{m.group('end') or '.'}"


# "The gloves go to Tom, Mia doesn't need them." / "Tom needs the gloves; the tape isn't for him."
_NOT_FOR_THEM31R = re.compile(
    r"^(?P<req>[^;.!?]+?)\s*[,;.]\s*(?:but |and )?(?:(?P<p>[A-Za-z][\w ]*?) (?:doesn't|does not|"
    r"don't|do not) (?:need|want|get) (?P<x>it|them|the [a-z]+(?: [a-z]+)?)|(?P<y>the [a-z]+"
    r"(?: [a-z]+)?|it|they|that|those) (?:isn't|is not|aren't|are not|'s not|'re not) for "
    r"(?P<q>[A-Za-z][\w ]*?))(?P<end>\s*[.!]?)$",
    _F,
)


def _not_for_them31r(text: str, lexicon: Lexicon) -> str:
    """Session 31 (12r): a statement that someone does not need something, beside a request
    ("The gloves go to Tom, Mia doesn't need them", "Tom needs the gloves; the tape isn't for
    him"), is taken off when the request reads and none of its tasks is the one the statement
    denies ('it' / 'them' the request's objects, 'him' / 'her' its one person); else it is left,
    and refused ("Tom needs the gloves, Tom doesn't need them")."""
    m = _NOT_FOR_THEM31R.match(text)
    if m is None:
        return text
    req = m.group("req")
    said = _tasks_of(req, lexicon)
    if not said or any(k != "deliver" for k, _, _ in said):
        return text
    who_words = m.group("p") or m.group("q")
    what = m.group("x") or m.group("y")
    people = {t for _, _, t in said}
    if re.fullmatch(r"him|her|them", who_words, _F):
        if len(people) != 1 or not _fits(next(iter(people)), who_words, lexicon):
            return text
        who = set(people)
    elif _only_person(who_words, lexicon):
        who = _ids(who_words, lexicon)
    else:
        return text
    if re.fullmatch(r"it|them|they|that|those", what, _F):
        objects = {o for _, o, _ in said}
    elif _objects_only(what, lexicon):
        objects = _ids(what, lexicon, "object")
    else:
        return text
    if any(o in objects and t in who for _, o, t in said):
        return text
    return req + (m.group("end") or ".")


def _couple_of31r(text: str, _lexicon: Lexicon) -> str:
    """Session 31 (12r): 'a couple of spanners' is 'two spanners' (the grammar checks the count
    against the scene: 'two of the pens' with three pens is a choice of two)."""
    return _sub(r"\ba couple of (?:the )?(?=[a-z]+s\b)", "two ", text)


# "the small and large spanners", "the small, medium and large boxes"
_ADJECTIVES_AND31R = re.compile(
    r"\bthe (?P<adj>[a-z]+(?:,\s*[a-z]+)*,? and [a-z]+) (?P<noun>[a-z]+)s\b", _F
)


def _adjectives_and31r(text: str, lexicon: Lexicon) -> str:
    """Session 31 (12r): 'the small and large spanners' is 'the small spanner and the large
    spanner' when each adjective with the noun names one object of the scene, each a different
    one (else left: 'the red and green cups' with one red cup is refused as before)."""

    def each(m: re.Match[str]) -> str:
        adjectives = [a for a in re.split(r",\s*(?:and\s+)?|\s+and\s+", m.group("adj")) if a]
        noun = m.group("noun")
        names = [f"the {a} {noun}" for a in adjectives]
        ids = [_ids(n, lexicon, "object") for n in names]
        if any(
            len(i) != 1 or not _whole_name(n, lexicon, "object")
            for i, n in zip(ids, names, strict=True)
        ):
            return m[0]
        if len(set().union(*ids)) != len(names):
            return m[0]
        return ", ".join(names[:-1]) + " and " + names[-1]

    return _sub(_ADJECTIVES_AND31R.pattern, each, text)


# "Kofi needs the hammer, the drill and the torch, three things."
_COUNT_AFTER31R = re.compile(
    r"(?P<list>(?:the |a |an )?[a-z]+(?: [a-z]+)?(?:(?:,\s*|,? and )(?:the |a |an )?[a-z]+"
    r"(?: [a-z]+)?)+),\s*(?:that's |so )?(?P<n>two|three|four|five|six|2|3|4|5|6) (?:things|items|"
    r"objects)(?: in all| altogether| in total)?(?P<end>\s*[.!]?)$",
    _F,
)


def _count_after31r(text: str, lexicon: Lexicon) -> str:
    """Session 31 (12r): a list of objects, then ', three things' closing the text, is the list
    when it names that many different objects of the scene (else left, refused: a count the list
    does not meet)."""
    m = _COUNT_AFTER31R.search(text)
    if m is None:
        return text
    items = [w for w in re.split(r"\s*,\s*(?:and\s+)?|\s+and\s+", m.group("list").strip()) if w]
    n = m.group("n").lower()
    want = int(n) if n.isdigit() else _COUNTS[n]
    if not all(_whole_name(w, lexicon, "object") for w in items):
        return text
    ids = [_ids(w, lexicon, "object") for w in items]
    if any(len(i) != 1 for i in ids) or len(set().union(*ids)) != want or len(items) != want:
        return text
    return f"{text[: m.end('list')]}{m.group('end') or '.'}"


def _dash_header31r(text: str, _lexicon: Lexicon) -> str:
    """Session 31 (12r): 'Kofi needs 3 items - hammer, drill, torch' is '…: hammer, drill,
    torch' (a dash after a count of things opens the list, as a colon does)."""
    return _sub(
        r"\b((?:two|three|four|five|six|2|3|4|5|6) (?:things|items|objects))\s+[-\u2013\u2014]\s+"
        r"(?=[a-z])",
        r"\1: ",
        text,
    )


# "The hammer and the drill, one for Kofi and one for Jess."
_ONE_FOR_EACH31R = re.compile(
    r"^(?P<list>(?:the |a |an )?[a-z]+(?: [a-z]+)?(?:(?:,\s*|,? and )(?:the |a |an )?[a-z]+"
    r"(?: [a-z]+)?)+),\s*one (?:for|to) (?P<p>[A-Za-z][\w ]*?),? and (?:one|the other) (?:for|to) "
    r"(?P<q>[A-Za-z][\w ]*?)(?P<end>\s*[.!]?)$",
    _F,
)


def _one_for_each31r(text: str, lexicon: Lexicon) -> str:
    """Session 31 (12r): "The hammer and the drill, one for Kofi and one for Jess" is 'Give the
    hammer and the drill to Kofi and Jess, one each' when the list names two objects and the
    two people differ (the grammar reads the share, either way round)."""
    m = _ONE_FOR_EACH31R.match(text)
    if m is None:
        return text
    p, q = m.group("p"), m.group("q")
    if not (_only_person(p, lexicon) and _only_person(q, lexicon)):
        return text
    if _ids(p, lexicon) == _ids(q, lexicon):
        return text
    items = [w for w in re.split(r"\s*,\s*(?:and\s+)?|\s+and\s+", m.group("list").strip()) if w]
    if len(items) != 2 or not all(_whole_name(w, lexicon, "object") for w in items):
        return text
    ids = [_ids(w, lexicon, "object") for w in items]
    if any(len(i) != 1 for i in ids) or ids[0] == ids[1]:
        return text
    return f"Give {m.group('list')} to {p} and {q}, one each{m.group('end')}"


def _split_two31r(text: str, lexicon: Lexicon) -> str:
    """Session 31 (12r): 'Split the spanners between Kofi and Jess' with nothing after is
    session 29's 'Split … , one each' (two objects between two people: one each is the only
    split; _split29r checks both counts and leaves the text otherwise)."""
    m = re.match(
        r"^(?P<head>(?:please )?(?:split|share|divide) the [a-z ]+? between [A-Za-z][\w ]*? and "
        r"[A-Za-z][\w ]*?)(?P<end>\s*[.!]?)$",
        text,
        _F,
    )
    if m is None:
        return text
    out = f"{m.group('head')}, one each{m.group('end')}"
    return out if _split29r(out, lexicon) != out else text


# what says 'no' before a correction, from a closed list: "I'm wrong", "my apologies", "wrong
# patient", "not him"
_CUE_WORDS31R = re.compile(
    r"(?<=,)\s*(?:(?:oh|ah|hmm|sorry),?\s*)?(?:i'm wrong|i am wrong|(?:my )?apologies|wrong "
    r"(?:person|patient|one|place|spot|thing|name|item|object|guy|lady|bay|table)|not (?:him|her|"
    r"them|that one))\s*,\s*(?=\S)",
    _F,
)


def _cue_words31r(text: str, lexicon: Lexicon) -> str:
    """Session 31 (12r): words that say the request just said is wrong, between commas before
    the corrected words ("…, I'm wrong, it's Mrs Khan", "…, my apologies, Mrs Khan", "…, wrong
    patient, Mrs Khan", "…, not him, Mrs Khan"), are the cue 'no'; 'change / swap / switch that
    to / for' is 'make that'; 'oh no, it's' is 'no, it's'; "No! Mrs Khan." is "No, Mrs Khan.";
    ', Mrs Khan actually.' closing the text is ', actually Mrs Khan.' (one name of the scene); ',
    sorry about that' after a correction is taken off."""
    out = _CUE_WORDS31R.sub(" no, ", text)
    out = _sub(r"\b(?:change|swap|switch) (that|it) (?:to|for)\b", r"make \1", out)
    out = _sub(r"(?<=,)(\s*)(?:oh|ah),?\s*no,\s*(?=it(?:'s| is) )", r"\1no, ", out)
    out = _sub(r"(?<=[.!?]\s)no!\s+(?=[A-Za-z])", "No, ", out)

    def actually(m: re.Match[str]) -> str:
        said = m.group("said")
        return f", actually {said}{m.group('end')}" if _one_name30r(said, lexicon) else m[0]

    out = _sub(r",\s*(?P<said>(?:the )?[A-Za-z][\w ]*?) actually(?P<end>\s*[.!]?)$", actually, out)
    if re.search(r",\s*(?:no|sorry|i meant?|actually)\b", out[: max(0, len(out) - 20)], _F):
        out = _sub(r",\s*sorry about (?:that|this)(?=\s*[.!]?$)", "", out)
    return out


def _only_after_person31r(text: str, lexicon: Lexicon) -> str:
    """Session 31 (12r): 'Give P only the cups' is 'Give P the cups' ('only' keeps to what is
    named, as the grammar does; 'P only' had been read as a name), P one person."""

    def only(m: re.Match[str]) -> str:
        return f"{m.group(1)}{m.group(2)} " if _only_person(m.group(2), lexicon) else m[0]

    return _sub(
        r"\b((?:give|hand|pass|bring|fetch|get) )([A-Z][\w]*(?: [A-Z][\w]*)?) (?:only|just) "
        r"(?=(?:the|both|one|a|an) )",
        only,
        text,
    )


def _other_not31r(text: str, lexicon: Lexicon) -> str:
    """Session 31 (12r): 'the other cup, not the green one' is 'a cup, but not the green one'
    when the scene has exactly two cups ('the other' is then the one left); 'the non-green cup'
    is 'the cup that isn't green'."""

    def other(m: re.Match[str]) -> str:
        kind = m.group("kind")
        if len(_ids(kind, lexicon, "object")) != 2 or not _only_kind(kind, lexicon, "object"):
            return m[0]
        return f"a {kind}, but not the {m.group('adj')} one"

    out = _sub(
        r"\bthe other (?P<kind>[a-z]+),\s*not the (?P<adj>[a-z]+) (?:one|(?P=kind))\b", other, text
    )
    return _sub(
        r"\bthe non-(?P<adj>[a-z]+) (?P<kind>[a-z]+)\b", r"the \g<kind> that isn't \g<adj>", out
    )


def _adj_names_one31r(adj: str, before: str, lexicon: Lexicon) -> bool:
    """Whether ``adj`` with the kind of the one object named in ``before`` names exactly one
    object of the scene, another than that one ('red' after 'the black pen': the red pen)."""
    named = [it for it in _names(before, lexicon) if it.refs[0].kind == "object"]
    if len(named) != 1 or len({r.id for r in named[0].refs}) != 1:
        return False
    kinds = {o.category for o in lexicon.scene.objects if o.id == named[0].refs[0].id}
    for kind in kinds:
        ids = _ids(f"{adj} {kind}", lexicon, "object")
        if (
            len(ids) == 1
            and ids != {named[0].refs[0].id}
            and _whole_name(f"{adj} {kind}", lexicon, "object")
        ):
            return True
    return False


def _kind_of31r(before: str, lexicon: Lexicon) -> str:
    """The category of the one object ``before`` names ('' if not one)."""
    ids = _ids(before, lexicon, "object")
    return next((o.category for o in lexicon.scene.objects if ids == {o.id}), "")


def _bare_adjective31r(text: str, lexicon: Lexicon) -> str:
    """Session 31 (12r): a correction that says only the colour or size of the one object
    asked for ("The black pen for Priya, sorry, make that red", "…, sorry, red not black") is 'the
    red one' (the grammar's ellipsis) when the word with that object's kind names one other
    object of the scene, and the word after 'not' the object asked for (else left, refused). ("…
    - red, I mean." closes on 'I mean', which offline.py takes as a correction cut off.)"""
    m = re.search(
        r",\s*(?P<cue>(?:sorry|no|oops),?\s*)?make (?:that|it) (?P<adj>[a-z]+)(?P<end>\s*[.!]?)$",
        text,
        _F,
    )
    if m is not None and _adj_names_one31r(m.group("adj"), text[: m.start()], lexicon):
        cue = m.group("cue") or ""
        return (
            f"{text[: m.start()]}, {cue}make that the {m.group('adj')} one{m.group('end') or '.'}"
        )
    m = re.search(
        r",\s*(?P<cue>sorry|no|oops|wait),?\s*(?P<adj>[a-z]+),? not (?P<old>[a-z]+)"
        r"(?P<end>\s*[.!]?)$",
        text,
        _F,
    )
    if (
        m is not None
        and _adj_names_one31r(m.group("adj"), text[: m.start()], lexicon)
        and _ids(text[: m.start()], lexicon, "object")
        == _ids(f"{m.group('old')} {_kind_of31r(text[: m.start()], lexicon)}", lexicon, "object")
    ):
        return (
            f"{text[: m.start()]}, {m.group('cue')}, the {m.group('adj')} one, not the "
            f"{m.group('old')} one{m.group('end') or '.'}"
        )
    return text


# "Alice would be happy with the bottle or the crisps."
_HAPPY_WITH31R = re.compile(
    r"^(?P<p>[A-Za-z][\w ]*?) (?:would be|'d be|will be) (?:quite |perfectly |very )?"
    r"(?:happy|fine|glad|content|pleased) (?:with|to get|to have) (?P<x>(?:either |both )?"
    r"(?:the|a|an|one of the|any of the) [^,;:.!?]+?)(?P<end>\s*(?:[,;.!]|$))",
    _F,
)


def _happy_with31r(text: str, lexicon: Lexicon) -> str:
    """Session 31 (12r): 'P would be happy with X' / "P'd be fine with X" is 'P would like X' (P
    one person, X the scene's objects: what P takes, the grammar reading a choice or a list in
    it). 'P is happy with X' is left: it may say she has it already."""
    m = _HAPPY_WITH31R.match(text)
    if m is None or not _only_person(m.group("p"), lexicon):
        return text
    if not _objects_only(m.group("x"), lexicon):
        return text
    return f"{m.group('p')} would like {m.group('x')}{text[m.start('end') :]}"


_STEPS31R: tuple[Callable[[str, Lexicon], str], ...] = (
    _happy_with31r,
    _bare_adjective31r,
    _only_after_person31r,
    _other_not31r,
    _cue_words31r,
    _couple_of31r,
    _adjectives_and31r,
    _count_after31r,
    _dash_header31r,
    _one_for_each31r,
    _split_two31r,
    _not_for_them31r,
    _leave_where31r,
    _doesnt_want_just31r,
    _meant_to_say31r,
    _its_who_cue31r,
    _these_listed31r,
    _wont_mind31r,
    _will_do_for31r,
    _fine_by_me31r,
    _split_way31r,
    _whichever_front31r,
    _whichever_there31r,
    _of_their_own31r,
    _play_with31r,
    _namely31r,
    _only_one_item31r,
    _alike31r,
    _solitary31r,
    _every_one_of_them31r,
    _gather_up31r,
    _cant_stand31r,
    _by_mistake31r,
    _one_that_isnt31r,
    _not_to_semi31r,
    _no_one_elses31r,
    _no_x_just31r,
    _leave_first31r,
    _slip31r,
    _yes_meant31r,
    _better_home31r,
    _sit_stand31r,
)


# -- session 32 (12r): blind30's choices, counts, negation, exclusions and corrections ----------
# As session 31's: each rule rewrites one construction into the form the grammar reads, and leaves
# the text as it was when what the construction presupposes (a count the scene meets, one person,
# the object named elsewhere in the text) does not hold; docs/grounding.md, "Session 32 (engineer
# 12r)".


def _one_object32r(words: str, lexicon: Lexicon) -> bool:
    """Whether ``words`` (an article aside) are one whole name of exactly one object."""
    return _whole_name(words, lexicon, "object") and len(_ids(words, lexicon)) == 1


_COUNT_WORDS32R = r"two|three|four|five|six|2|3|4|5|6"

# "all four of the things on the table", "The pair of items on the table both", "the two things"
_ALL_THINGS32R = re.compile(
    rf"(?<!\bof )\b(?:all (?P<all>{_COUNT_WORDS32R})(?: of the)?|"
    r"(?P<pair>the pair of|both of the)) (?:things|items|objects)"
    r"(?P<loc> (?:on|at|in) the (?P<place>[a-z]+)| here| out)?"
    r"(?P<rest> (?:both|all)(?= [a-z]))?",
    _F,
)


def _all_things32r(text: str, lexicon: Lexicon) -> str:
    """Session 32 (12r): 'all four of the things (on the table)', 'the pair of items on the
    table (both)' is 'everything' when the count is the number of the scene's objects (two or
    more) and the place said with it ('on the table', in passing: where they lie) is no surface
    of the scene; a place the scene has, or a count it does not meet, leaves the text (refused)."""

    if re.search(
        r"\b(?:except|but|apart from|other than|bar|save|minus|excluding|not)\b", text, _F
    ):
        return text  # 'all four … except the cup' says two counts: left, refused

    def every(m: re.Match[str]) -> str:
        word = (m.group("all") or "two").lower()
        count = int(word) if word.isdigit() else _COUNTS[word]
        if count < 2 or count != len(lexicon.scene.objects):
            return m[0]
        place = m.group("place")
        if place is not None and _names(place, lexicon):
            return m[0]
        return "everything"

    return _sub(_ALL_THINGS32R.pattern, every, text)


# "the two things to drink from, the bottle and the cup"
_APPOSED_LIST32R = re.compile(
    rf"\bthe (?P<n>{_COUNT_WORDS32R}) (?:things|items|objects|bits)(?P<desc>(?: [a-z]+){{1,4}}?)?"
    r",\s*(?P<list>(?:the |a |an )?[a-z]+(?: [a-z]+)?(?:(?:,\s*|,? and )(?:the |a |an )?[a-z]+"
    r"(?: [a-z]+)?)+)(?P<end>\s*(?:[,;.!]|$))",
    _F,
)


def _apposed_list32r(text: str, lexicon: Lexicon) -> str:
    """Session 32 (12r): 'the two things to drink from, the bottle and the cup' is 'the bottle
    and the cup': the list after the comma says which things the count counted, when it names
    that many different objects of the scene, each whole, and the words describing them name
    nothing of the scene and no place (else left, refused: a count the list does not meet, or
    'the two things on the shelf' in a scene without a shelf)."""
    m = _APPOSED_LIST32R.search(text)
    if m is None:
        return text
    items = [w for w in re.split(r"\s*,\s*(?:and\s+)?|\s+and\s+", m.group("list").strip()) if w]
    n = m.group("n").lower()
    want = int(n) if n.isdigit() else _COUNTS[n]
    if len(items) != want or not all(_whole_name(w, lexicon, "object") for w in items):
        return text
    ids = [_ids(w, lexicon, "object") for w in items]
    if any(len(i) != 1 for i in ids) or len(set().union(*ids)) != want:
        return text
    desc = m.group("desc") or ""
    if _names(desc, lexicon) or re.search(r"\b(?:on|in|at|by|under|near) the\b", desc, _F):
        return text  # a place said of them, which the scene does not have: not checked
    said = ", ".join(items[:-1]) + " and " + items[-1]
    end = m.start("end")
    if m.start() == 0 and m.group("end").strip() == ",":
        end = m.end("end")  # the subject: the comma closes the apposition
    return f"{text[: m.start()]}{said}{text[end:]}"


# "The three boxes, small, medium and large, all go …"
_APPOSED_ADJECTIVES32R = re.compile(
    rf"\b(?:the (?P<n>{_COUNT_WORDS32R})|both(?: of the| the)?) (?P<noun>[a-z]+)s,\s*"
    r"(?P<adj>(?:the )?[a-z]+(?:,\s*(?:the )?[a-z]+)*,? and (?:the )?[a-z]+)\s*,"
    r"(?: (?:all|both)(?= [a-z]))?",
    _F,
)


def _apposed_adjectives32r(text: str, lexicon: Lexicon) -> str:
    """Session 32 (12r): 'the three boxes, small, medium and large, (all) go' is 'the small,
    medium and large boxes go' (_adjectives_and31r's form, which checks that each adjective with
    the noun names one different object), when the count is the number of adjectives ('both of
    the spanners, large and small,' two)."""

    def said(m: re.Match[str]) -> str:
        adj = _sub(r"\bthe ", "", m.group("adj"))  # 'the green and the white'
        adjectives = [a for a in re.split(r",\s*(?:and\s+)?|\s+and\s+", adj) if a]
        n = (m.group("n") or "two").lower()
        if len(adjectives) != (int(n) if n.isdigit() else _COUNTS[n]):
            return m[0]
        out = f"the {adj} {m.group('noun')}s"
        rewritten = _adjectives_and31r(out, lexicon)
        return rewritten if rewritten != out else m[0]

    return _sub(_APPOSED_ADJECTIVES32R.pattern, said, text)


# "Person A's taking the bottle and the cup home with her."
_TAKEN_HOME32R = re.compile(
    r"^(?P<p>[A-Za-z][\w ]*?)(?:'s| is) taking (?P<x>(?:the|both|all|everything)\b[^;:.!?]*?) "
    r"(?:home|away|back)(?: with (?P<pro>her|him|them))?(?P<end>\s*(?:[,;.!]|$))",
    _F,
)


def _taken_home32r(text: str, lexicon: Lexicon) -> str:
    """Session 32 (12r): "P's taking X home (with her)" is "P's having X": P takes the things
    away, so they go to P (P one person the pronoun fits, X the scene's objects only). Without
    'home' / 'away' / 'back' 'taking' is the robot's verb ('take the cup to Bob') and is left."""
    m = _TAKEN_HOME32R.match(text)
    if m is None or not _only_person(m.group("p"), lexicon):
        return text
    x = m.group("x")
    if x.lower() != "everything" and not _objects_only(x, lexicon):
        return text
    if _ids(x, lexicon, "human") or _ids(x, lexicon, "surface"):
        return text
    pid = next(iter(_ids(m.group("p"), lexicon)))
    if m.group("pro") and not _fits(pid, m.group("pro"), lexicon):
        return text
    return f"{m.group('p')}'s having {x}{text[m.start('end') :]}"


# "Person A and Person B get a single item apiece out of the two on the table"
_APIECE_OUT_OF32R = re.compile(
    r"\b(?:a single|one|just one) (?:item|thing|object) (?:apiece|each) out of the "
    rf"(?P<n>{_COUNT_WORDS32R})(?: (?:things|items|objects))?(?: (?:on|at|in) the (?P<place>[a-z]+)"
    r"| here)?(?=\s*(?:[,;.!]|$))",
    _F,
)
# "One each for Alice and Bob out of the crisps and the bottle"
_ONE_EACH_FOR32R = re.compile(
    r"^one(?: (?P<kind>[a-z]+))? (?:each|apiece) (?:for|to) (?P<p>[A-Za-z][\w ]*?) and "
    r"(?P<q>[A-Za-z][\w ]*?) "
    r"(?:out of|from) (?P<x>the [a-z ]+? and the [a-z ]+?)(?P<end>\s*(?:[,;.!]|$))",
    _F,
)
# "One blanket apiece for the two patients"
_ONE_APIECE_FOR32R = re.compile(
    rf"^(?P<one>one|an?) (?P<x>[a-z]+) (?:apiece|each) for the (?P<n>{_COUNT_WORDS32R}) "
    r"(?P<role>[a-z]+)s(?P<end>\s*(?:[,;.!]|$))",
    _F,
)


def _apiece32r(text: str, lexicon: Lexicon) -> str:
    """Session 32 (12r): the share-outs said with 'apiece' / 'each' and 'out of': 'P and Q get a
    single item apiece out of the two (on the table)' is 'P and Q get one each' when the count
    is the scene's objects and the place none of its surfaces; 'One (book) each for P and Q out
    of X and Y' is 'Give P and Q one of X and Y each' (_split29r's reading: two objects, two
    people; 'the red one' there the red book, and both books); 'One X apiece for the two Rs' is
    'One X for each of the two Rs' (_each_of_n29r checks the role's count)."""

    def one_each(m: re.Match[str]) -> str:
        n = m.group("n").lower()
        count = int(n) if n.isdigit() else _COUNTS[n]
        if count != len(lexicon.scene.objects):
            return m[0]
        place = m.group("place")
        if place is not None and _names(place, lexicon):
            return m[0]
        return "one each"

    out = _sub(_APIECE_OUT_OF32R.pattern, one_each, text)
    m = _ONE_EACH_FOR32R.match(out)
    if m is not None:
        x, kind = m.group("x"), m.group("kind")
        if kind is not None:
            if not _only_kind(kind, lexicon, "object"):
                return out
            x = _sub(r"\b(the [a-z]+) one\b", rf"\1 {kind}", x)  # 'the red one': the red book
            if not _ids(x, lexicon, "object") <= _ids(kind, lexicon, "object"):
                return out
        split = f"Split {x} between {m.group('p')} and {m.group('q')}, one each"
        if _split29r(split, lexicon) != split:
            return f"Give {m.group('p')} and {m.group('q')} one of {x} each{out[m.start('end') :]}"
    m = _ONE_APIECE_FOR32R.match(out)
    if m is not None:
        said = f"{m.group('one')} {m.group('x')} for each of the {m.group('n')} {m.group('role')}s"
        if _each_of_n29r(said, lexicon) != said:
            return f"{said}{out[m.start('end') :]}"
    return out


# what leaves the share-out to the robot, closing the text after a comma
_YOU_PICK32R = re.compile(
    r",\s*(?:you pick|you choose|your (?:pick|choice|call)|(?:i'll|i will) let you (?:choose|"
    r"pick|decide)(?: which (?:goes|one goes) where| who gets (?:which|what))?|(?:i'm|i am) not "
    r"(?:fussed|bothered|fussy) (?:who (?:ends up with|gets) (?:what|which))|(?:i )?don't mind "
    r"(?:how|which way(?: round)?|who gets (?:what|which))|(?:i )?don't care (?:how|which way"
    r"(?: round)?|who gets (?:what|which)))(?P<end>\s*[.!]?)$",
    _F,
)


def _you_pick32r(text: str, _lexicon: Lexicon) -> str:
    """Session 32 (12r): ', you pick', ", I'll let you choose which goes where", ", I'm not
    fussed who ends up with what", ", I don't mind how" closing a share-out ('one each', 'one of
    … each', 'for each of') leave the choice the share-out already is to the robot: taken off.
    After anything else (a single request) they are left, refused."""
    m = _YOU_PICK32R.search(text)
    if m is None:
        return text
    head = text[: m.start()]
    if not re.search(r"\bone each\b|\bone of\b.*\beach\b|\bfor each of\b|\beach of\b", head, _F):
        return text
    return f"{head}{m.group('end') or '.'}"


# "Each of them gets one of the bottle and the chips"
_EACH_OF_THEM32R = re.compile(
    r"^each of them (?:gets|takes|has|should get|can have) one of (?P<x>the [a-z ]+? and the "
    r"[a-z ]+?)(?P<end>\s*(?:[,;.!]|$))",
    _F,
)


def _each_of_them32r(text: str, lexicon: Lexicon) -> str:
    """Session 32 (12r): 'Each of them gets one of X and Y' opening a text that names no person
    is the scene's people, when it has two and X and Y are two objects: 'Give Person A and
    Person B one of X and Y each' (_split29r's reading). With more people (or a person named in
    the text) 'them' is not the scene's pair and the text is left, refused."""
    m = _EACH_OF_THEM32R.match(text)
    humans = lexicon.scene.humans
    if m is None or len(humans) != 2 or _ids(text, lexicon, "human"):
        return text
    p, q = (h.name or h.id for h in humans)
    split = f"Split {m.group('x')} between {p} and {q}, one each"
    if _split29r(split, lexicon) == split:
        return text
    return f"Give {p} and {q} one of {m.group('x')} each{text[m.start('end') :]}"


# ", whichever one's clean", ", she'll chew whichever you hand her", ", as long as it's clean"
_CHOICE_TAIL32R = re.compile(
    r",\s*(?:whichever(?: one)?(?:'s| is) (?P<state>clean|free|handy|handier|nearer|closer|"
    r"nearest|closest|dry|empty|spare)|(?:she|he|they)(?:'ll| will) (?:chew|use|take|have|like|"
    r"play with|enjoy|be happy with) whichever(?: one)? you (?:hand|give|bring|pass) "
    r"(?:her|him|them)|as long as it's (?:clean|dry|empty|not broken))(?P<end>\s*[.!]?)$",
    _F,
)


def _choice_tail32r(text: str, _lexicon: Lexicon) -> str:
    """Session 32 (12r): after a choice ('either cup', 'one of the mugs'), ", whichever one's
    clean", ", she'll chew whichever you hand her", ", as long as it's clean" leave which one to
    the robot: ', whichever' (the tail the grammar reads), and 'as long as …' is taken off after
    'doesn't matter which' (which says the choice again). Without a choice before it the text
    is left, refused."""
    m = _CHOICE_TAIL32R.search(text)
    if m is None:
        return text
    head = text[: m.start()]
    if not re.search(r"\b(?:either|one of the|any of the|any one of the)\b", head, _F):
        return text
    if m[0].lstrip(", ").lower().startswith("as long"):
        if not re.search(r"\b(?:doesn't|does not|don't) matter which\b", head, _F):
            return text
        return f"{head}{m.group('end') or '.'}"
    return f"{head}, whichever{m.group('end') or '.'}"


# "Person A and Person B both want the chips; give them to either one"
_BOTH_WANT_EITHER32R = re.compile(
    r"^(?P<p>[A-Za-z][\w ]*?) and (?P<q>[A-Za-z][\w ]*?) (?:both )?(?:want|need|would like|are "
    r"after)(?: both)? (?P<x>the [a-z ]+?)\s*[;,.:]\s*(?:so )?(?:just )?(?:give|hand|pass) "
    r"(?:it|them) to either(?: one)?(?: of them)?(?P<end>\s*(?:[,;.!]|$))",
    _F,
)


def _both_want_either32r(text: str, lexicon: Lexicon) -> str:
    """Session 32 (12r): 'P and Q both want X; give it / them to either (one)' is 'Give X to P
    or Q' (P and Q two people, X one object of the scene, the pronoun X again)."""
    m = _BOTH_WANT_EITHER32R.match(text)
    if m is None:
        return text
    p, q, x = m.group("p"), m.group("q"), m.group("x")
    if not (_only_person(p, lexicon) and _only_person(q, lexicon)) or _ids(p, lexicon) == _ids(
        q, lexicon
    ):
        return text
    if not _one_object32r(x, lexicon):
        return text
    return f"Give {x} to {p} or {q}{text[m.start('end') :]}"


def _reach_first32r(text: str, lexicon: Lexicon) -> str:
    """Session 32 (12r): 'Whichever (of the two) you can reach first, X or Y, hand it to P' is
    _whichever_front31r's "Whichever's nearer, X or Y, …" (the robot's choice by reach; that
    rule checks X, Y and the request)."""
    out = _sub(
        r"^whichever(?: (?:one|of the two|of them))? you can (?:reach|get to|grab) "
        r"(?:first|soonest|easiest|more easily)\s*,",
        "Whichever's nearer,",
        text,
    )
    if out == text:
        return text
    said = _whichever_front31r(out, lexicon)
    return said if said != out else text


def _request_ids32r(head: str, lexicon: Lexicon) -> tuple[set[str], set[str]] | None:
    """The objects and people a request names (None when it names none of either)."""
    objects, people = _ids(head, lexicon, "object"), _ids(head, lexicon, "human")
    return (objects, people) if objects and people else None


# "; she doesn't want the apple.", ", Person B shouldn't get it."
_NOT_WANTED32R = re.compile(
    r"\s*[;,]\s*(?:but |and )?(?P<who>[A-Za-z][\w ]*?) (?:doesn't|does not|don't|do not) "
    r"(?:want|need) (?P<x>(?:the|a|an|any) [a-z ]+?)(?P<end>\s*[.!]?)$",
    _F,
)
_SHOULDNT_GET32R = re.compile(
    r"\s*[;,]\s*(?:but |and )?(?P<who>[A-Za-z][\w ]*?) (?:shouldn't|should not|mustn't|must not|"
    r"isn't to|is not to) (?:get|have|be given) (?:it|them)(?P<end>\s*[.!]?)$",
    _F,
)


def _not_wanted32r(text: str, lexicon: Lexicon) -> str:
    """Session 32 (12r): a closing remark of what someone is not to get, said after a request
    that gives something else: 'Hand P the chips; she doesn't want the apple' (the pronoun P, the
    apple not in the request), 'The bottle is for P (alone), Q shouldn't get it' (Q another
    person than the request's). Taken off when what it withholds is nothing the request gives;
    else (the request gives it, or the person is not resolved) left, refused."""
    m = _NOT_WANTED32R.search(text)
    if m is not None:
        head = text[: m.start()]
        said = _request_ids32r(head, lexicon)
        whole = _whole_name(m.group("x"), lexicon, "object")
        x_ids = _ids(m.group("x"), lexicon, "object") if whole else set()
        who = m.group("who")
        if said is not None and len(said[1]) == 1 and x_ids and not x_ids & said[0]:
            pid = next(iter(said[1]))
            same = re.fullmatch(r"she|he|they", who, _F) and _fits(pid, who, lexicon)
            if same or (_ids(who, lexicon, "human") == said[1] and _only_person(who, lexicon)):
                return f"{head}{m.group('end') or '.'}"
    m = _SHOULDNT_GET32R.search(text)
    if m is not None:
        head = _sub(r"\b(for (?:[A-Za-z][\w ]*?)) (?:alone|only)$", r"\1", text[: m.start()])
        said = _request_ids32r(head, lexicon)
        who = m.group("who")
        if said is not None and _only_person(who, lexicon) and not _ids(who, lexicon) & said[1]:
            return f"{head}{m.group('end') or '.'}"
    return text


# "the bottle stays put, leave it alone"
_STAYS_PUT32R = re.compile(
    r"\s*[;,]\s*(?:but |and )?(?P<x>the [a-z ]+?) (?:stays|stay|is staying|can stay) "
    r"(?:put|where it is|here|there)(?:\s*,\s*(?:just )?leave it(?: alone| be| there)?)?"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _stays_put32r(text: str, lexicon: Lexicon) -> str:
    """Session 32 (12r): '…; the X stays put(, leave it alone)' after a request that does not
    name X says X is not part of it: taken off (X one object of the scene); when the request
    moves X the text is left, refused."""
    m = _STAYS_PUT32R.search(text)
    if m is None:
        return text
    head, x = text[: m.start()], m.group("x")
    if not _one_object32r(x, lexicon):
        return text
    if _request_ids32r(head, lexicon) is None or _ids(x, lexicon) & _ids(head, lexicon):
        return text
    return f"{head}{m.group('end') or '.'}"


def _only_nothing_else32r(text: str, lexicon: Lexicon) -> str:
    """Session 32 (12r): 'Only the X, nothing else, goes to P' is 'The X goes to P' (the grammar
    gives only what is named; X one object of the scene)."""

    def only(m: re.Match[str]) -> str:
        x = m.group("x")
        if not _one_object32r(x, lexicon):
            return m[0]
        return f"{x[:1].upper()}{x[1:]} "

    return _sub(
        r"^(?:only|just) (?P<x>the [a-z ]+?),\s*(?:nothing|and nothing) else,\s*(?=(?:goes|is|"
        r"should go|needs to go) (?:to|for) )",
        only,
        text,
    )


# "No need to set the bottle down first, just pass it right into Person A's hand."
_NO_NEED_FIRST32R = re.compile(
    r"^(?:there's )?no need to (?:set|put|place|leave) (?P<x>the [a-z ]+?) (?:down )?"
    r"(?:first|beforehand)\s*,\s*(?:just )?(?P<rest>(?:pass|hand|give|bring) it\b[^,;:.!?]*?)"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _no_need_first32r(text: str, lexicon: Lexicon) -> str:
    """Session 32 (12r): 'No need to set the X down first, just pass it (right) into P's hand'
    is 'pass the X to P': the step waived is no task, 'it' is X (one object of the scene), and
    'into P's hand(s)' is to P (one person)."""
    m = _NO_NEED_FIRST32R.match(text)
    if m is None:
        return text
    x = m.group("x")
    if not _one_object32r(x, lexicon):
        return text
    rest = _sub(r"\bit\b", x, m.group("rest"))
    hand = re.search(r"\b(?:right |straight )?into (?P<p>[A-Za-z][\w ]*?)'s hands?$", rest, _F)
    if hand is not None:
        if not _only_person(hand.group("p"), lexicon):
            return text
        rest = f"{rest[: hand.start()]}to {hand.group('p')}"
    return f"{rest[:1].upper()}{rest[1:]}{m.group('end') or '.'}"


def _not_other_person32r(text: str, lexicon: Lexicon) -> str:
    """Session 32 (12r): 'P gets the X, and no, not Q, she's had hers' is 'P gets the X, not Q,
    …' ('no' before 'not' says the 'not' again; _negated reads 'not Q' after a request to P).
    Only when Q is one person other than P."""

    def no(m: re.Match[str]) -> str:
        q = m.group("q")
        if not _only_person(q, lexicon) or _ids(q, lexicon) & _ids(text[: m.start()], lexicon):
            return m[0]
        return f", not {q}"

    return _sub(r",\s*(?:and )?no,\s*not (?P<q>[A-Za-z][\w ]*?)(?=\s*(?:[,.!]|$))", no, text)


# ", and there's only the one, so no mix-ups"
_ONLY_THE_ONE32R = re.compile(
    r",\s*(?:and )?there(?:'s| is) only (?:the )?one(?: of (?:it|them))?"
    r"(?:\s*,\s*so no (?:mix-?ups|confusion|mistakes))?(?P<end>\s*[.!]?)$",
    _F,
)


def _only_the_one32r(text: str, lexicon: Lexicon) -> str:
    """Session 32 (12r): ", and there's only the one(, so no mix-ups)" after a request naming
    one object says the scene has one of its kind: taken off when it has (else left, refused:
    'the cup' with two cups)."""
    m = _ONLY_THE_ONE32R.search(text)
    if m is None:
        return text
    head = text[: m.start()]
    objects = [it for it in _names(head, lexicon) if it.refs[0].kind == "object"]
    if len(objects) != 1 or len(objects[0].refs) != 1:
        return text
    kind = _kinds({objects[0].refs[0].id}, lexicon)
    if len([o for o in lexicon.scene.objects if o.category in kind]) != 1:
        return text
    return f"{head}{m.group('end') or '.'}"


def _dont_suppose32r(text: str, _lexicon: Lexicon) -> str:
    """Session 32 (12r): "(I) don't suppose you could …?" is 'Could you …?' (a request put as a
    doubt; the grammar reads the question)."""
    return _sub(r"^(?:i )?don't suppose (?:you|u) could (?=[a-z])", "Could you ", text)


def _whatevers_here32r(text: str, _lexicon: Lexicon) -> str:
    """Session 32 (12r): "whatever's here apart from X" / 'everything here bar X' is 'everything
    except X' (the grammar's exclusion, which checks X against the scene)."""
    return _sub(
        r"\b(?:whatever(?:'s| is) (?:here|there|about|around|on hand)|everything (?:here|there))"
        r"(?:,)? (?:apart from|bar|other than|but|except for|except) (?=the |a |an )",
        "everything except ",
        text,
    )


# ", the stevedores will sort the rest"
_OTHERS_REST32R = re.compile(
    r",\s*(?:the|our) [a-z]+s (?:will|can|'ll) (?:sort|deal with|handle|see to|take care of|do) "
    r"the rest(?: (?:later|themselves))?(?P<end>\s*[.!]?)$",
    _F,
)


def _others_rest32r(text: str, lexicon: Lexicon) -> str:
    """Session 32 (12r): ', the stevedores will sort the rest' after an exclusion ('every box
    bar the large one') says who sees to what is left out: not the robot's task, taken off
    when the people named are none of the scene's and the request before it excludes."""
    m = _OTHERS_REST32R.search(text)
    if m is None or _names(m[0], lexicon):
        return text
    head = text[: m.start()]
    if not re.search(r"\b(?:except|but not|apart from|other than|bar)\b", head, _F):
        return text
    return f"{head}{m.group('end') or '.'}"


def _other_isnt32r(text: str, lexicon: Lexicon) -> str:
    """Session 32 (12r): 'the other thing, the one that isn't the X' is the scene's one object
    besides X, when the scene has exactly two objects and X names one of them (else left)."""

    def other(m: re.Match[str]) -> str:
        x = m.group("x")
        if len(lexicon.scene.objects) != 2 or not _whole_name(x, lexicon, "object"):
            return m[0]
        ids = _ids(x, lexicon, "object")
        rest = [o.id for o in lexicon.scene.objects if o.id not in ids]
        return f"the {rest[0]}" if len(ids) == 1 and len(rest) == 1 else m[0]

    return _sub(
        r"\bthe other (?:thing|item|one|object),\s*the one (?:that|which) (?:isn't|is not|'s not) "
        r"(?P<x>the [a-z ]+?)(?=\s*(?:[,;.!]|$))",
        other,
        text,
    )


def _any_except32r(text: str, lexicon: Lexicon) -> str:
    """Session 32 (12r): 'a cup, any cup except the green one' is 'any cup except the green one'
    (the first 'a cup' said again by the second; one kind of the scene's objects)."""

    def said(m: re.Match[str]) -> str:
        kind = m.group("kind")
        return m.group("any") if _only_kind(kind, lexicon, "object") else m[0]

    return _sub(
        r"\ban? (?P<kind>[a-z]+),\s*(?P<any>any (?P=kind) (?:except|but|apart from|other than) )",
        said,
        text,
    )


def _isnt_adjective32r(text: str, lexicon: Lexicon) -> str:
    """Session 32 (12r): "P's X is the one that isn't grey" is "P's X is the blue one" when the
    scene has exactly two Xs and 'grey X' names one of them (the other is then said by its own
    adjective; else left, refused)."""

    def other(m: re.Match[str]) -> str:
        kind, adj = m.group("kind"), m.group("adj")
        ids = _ids(kind, lexicon, "object")
        if len(ids) != 2 or not _only_kind(kind, lexicon, "object"):
            return m[0]
        no = _ids(f"{adj} {kind}", lexicon, "object")
        if len(no) != 1 or not _whole_name(f"{adj} {kind}", lexicon, "object"):
            return m[0]
        (yes,) = ids - no
        names = [o for o in lexicon.scene.objects if o.id == yes]
        for alias in names[0].aliases if names else ():
            if alias.lower().endswith(f" {kind.lower()}") and _ids(alias, lexicon) == {yes}:
                return f"{m.group('head')}the {alias.rsplit(' ', 1)[0]} one"
        return m[0]

    return _sub(
        r"(?P<head>'s (?P<kind>[a-z]+) is )the one (?:that|which) (?:isn't|is not|'s not) "
        r"(?P<adj>[a-z]+)\b",
        other,
        text,
    )


def _er_person32r(text: str, lexicon: Lexicon) -> str:
    """Session 32 (12r): 'to Person, er, Person A' (a label begun, then said whole) is 'to
    Person A'; ', the only one here' after a person is taken off when the scene has that one
    person only."""
    out = _sub(r"\bperson,?\s*(?:er|erm|um|uh|ah),?\s*(?=person [a-z]\b)", "", text)

    def only(m: re.Match[str]) -> str:
        p = m.group("p")
        return p if len(lexicon.scene.humans) == 1 and _only_person(p, lexicon) else m[0]

    return _sub(
        r"\b(?P<p>person [a-z]|[A-Z][a-z]+),\s*the only (?:one|person) (?:here|around|about|in "
        r"the room)(?=\s*[.!]?$)",
        only,
        out,
    )


# "Put the bottle on, oh wait, there's no shelf, just give it to Person A."
_NO_SUCH_PLACE32R = re.compile(
    r"^(?:put|place|set|pop|leave) (?P<x>the [a-z ]+?) (?:on|onto|in|into)\s*,\s*(?:oh )?wait\s*,"
    r"\s*there(?:'s| is) no (?P<s>[a-z]+)(?: here)?\s*,\s*(?:so )?(?:just )?"
    r"(?P<rest>(?:give|hand|pass|bring|take) it\b[^,;:.!?]*?)(?P<end>\s*[.!]?)$",
    _F,
)


def _no_such_place32r(text: str, lexicon: Lexicon) -> str:
    """Session 32 (12r): 'Put the X on, oh wait, there's no shelf, just give it to P' is 'give
    the X to P': the placement broken off is taken back because the place does not exist (the
    scene has no surface by that word; if it has, the text is left, refused), and 'it' is X."""
    m = _NO_SUCH_PLACE32R.match(text)
    if m is None or _names(m.group("s"), lexicon):
        return text
    x = m.group("x")
    if not _one_object32r(x, lexicon):
        return text
    rest = _sub(r"\bit\b", x, m.group("rest"))
    return f"{rest[:1].upper()}{rest[1:]}{m.group('end') or '.'}"


# "The two cups both want washing, so into the sink with the pair of them."
_INTO_WITH_THEM32R = re.compile(
    r"^(?P<x>the [a-z ]+?) (?:both |all )?(?:want|need|could do with) (?:a )?[a-z]+ing\s*,\s*"
    r"(?:so )?(?P<prep>into|in|onto|on) (?P<s>the [a-z ]+?) with (?:them|the pair of them|both of "
    r"them|the lot|the two of them|the pair|the two)(?P<end>\s*[.!]?)$",
    _F,
)


def _into_with_them32r(text: str, lexicon: Lexicon) -> str:
    """Session 32 (12r): 'The two cups (both) want washing, so into the sink with the pair of
    them' is 'Put the two cups into the sink': 'into S with them' is the idiom for putting them
    there, the clause before it (the things and what they need) the reason; X the scene's
    objects only, S one surface (else left, refused)."""
    m = _INTO_WITH_THEM32R.match(text)
    if m is None or not _objects_only(m.group("x"), lexicon):
        return text
    if not _whole_name(m.group("s"), lexicon, "surface"):
        return text
    x = m.group("x")
    return f"Put {x[:1].lower()}{x[1:]} {m.group('prep')} {m.group('s')}{m.group('end') or '.'}"


def _for_table32r(text: str, lexicon: Lexicon) -> str:
    """Session 32 (12r): ', for table six' / 'for bed 4' closing a request to a person of the
    scene says what the things are for (a table the scene does not have): taken off when the
    word names nothing of the scene and the request names one person."""
    m = re.search(
        r",?\s*for (?P<place>table|bed|room|bay|seat|booth) (?:\d+|one|two|three|four|five|six|"
        r"seven|eight|nine|ten|eleven|twelve)(?P<end>\s*[.!]?)$",
        text,
        _F,
    )
    if m is None or _names(m.group("place"), lexicon):
        return text
    head = text[: m.start()]
    if len(_ids(head, lexicon, "human")) != 1 or not _ids(head, lexicon, "object"):
        return text
    return f"{head}{m.group('end') or '.'}"


# "Two students, two books: Noah takes the red one and Zoe gets the green one."
_COUNTED_HEADER32R = re.compile(
    rf"^(?P<n>{_COUNT_WORDS32R}) (?P<role>[a-z]+)s,\s*(?P<m>{_COUNT_WORDS32R}) (?P<kind>[a-z]+)s"
    r"\s*:\s*(?P<rest>\S.*)$",
    _F,
)


def _counted_header32r(text: str, lexicon: Lexicon) -> str:
    """Session 32 (12r): 'Two students, two books: Noah takes the red one and Zoe gets the
    green one' is the request after the colon, 'the red one' there the red book: the header
    counts the people by their role and the objects by their kind, and both counts must be the
    scene's (else left, refused); each 'the <adjective> one' must then name one book."""
    m = _COUNTED_HEADER32R.match(text)
    if m is None:
        return text
    n, k = m.group("n").lower(), m.group("m").lower()
    role, kind = m.group("role").lower(), m.group("kind")
    people = [h for h in lexicon.scene.humans if role in (a.lower() for a in h.aliases)]
    if len(people) != (int(n) if n.isdigit() else _COUNTS[n]):
        return text
    if not _only_kind(kind, lexicon, "object"):
        return text
    if len(_ids(kind, lexicon, "object")) != (int(k) if k.isdigit() else _COUNTS[k]):
        return text
    ok = True

    def one(o: re.Match[str]) -> str:
        nonlocal ok
        said = f"the {o.group(1)} {kind}"
        if len(_ids(said, lexicon, "object")) != 1 or not _whole_name(said, lexicon, "object"):
            ok = False
        return said

    rest = _sub(r"\bthe ([a-z]+) one\b", one, m.group("rest"))
    return f"{rest[:1].upper()}{rest[1:]}" if ok else text


# what a person corrected away has or is, closing the text: "Sam's got one", "Alice is off
# crisps", "A's gone on break"; and what is wrong with an object corrected away: "the cup's got
# a crack"
_WHY_NOT_PERSON32R = (
    r"(?:'s| has) (?:got |already got |already had |had )?(?:one|(?:his|her|their) own|his|hers|"
    r"theirs|one already|it already)(?: already)?|(?:'s| is) off (?:the )?[a-z]+|(?:'s| has) gone "
    r"(?:on (?:a )?break|home|out|off shift)|(?:'s| is) (?:on (?:a )?break|not here|off shift|busy)"
)
_WHY_NOT_OBJECT32R = (
    r"(?:'s| has) got a (?:crack|chip|hole|stain)(?: in it)?|(?:'s| is) (?:cracked|chipped|"
    r"broken|dirty|filthy|empty|wet|leaking|sticky)"
)
_WHY_NOT_SURFACE32R = (
    r"(?:'s| is) (?:wet|full|dirty|cluttered|taken|sticky|in use)"
    # session 35 (12s): what the surface is kept for ("…, no, on the counter, the rack's only for
    # plates")
    r"|(?:'s| is) (?:only|just) (?:for|meant for) [a-z]+s"
)
_WHY_NOT32R = {
    "human": _WHY_NOT_PERSON32R,
    "object": _WHY_NOT_OBJECT32R,
    "surface": _WHY_NOT_SURFACE32R,
}
_CORRECTED_REASON32R = re.compile(
    r"^(?P<head>.+?,\s*(?:no|sorry|oops|hang on|wait|i mean|make it)\b.+?),\s*(?P<who>(?:the )?"
    rf"[A-Za-z][\w ]*?)(?P<why>{'|'.join(_WHY_NOT32R.values())})(?P<end>\s*[.!]?)$",
    _F,
)


def _corrected_reason32r(text: str, lexicon: Lexicon) -> str:
    """Session 32 (12r): after a correction ('X to Q, no, to P', '…, sorry, I mean P', 'X for P,
    no, sorry, the Y'), a closing reason about what was corrected away, from a closed list for
    each kind ("Q's got one / his own", 'Q is off crisps', "Q's gone on break"; "the X's got a
    crack", 'the X is broken'; "the tray's wet"), is taken off: its subject must be one person,
    object or surface of the scene named before the cue and not after it, and the correction
    must name another of its kind (the one corrected away); anything else is left, refused."""
    m = _CORRECTED_REASON32R.match(text)
    if m is None:
        return text
    head, who = m.group("head"), m.group("who")
    kind = next((k for k in _WHY_NOT32R if _whole_name(who, lexicon, k)), "")
    if not kind or len(_ids(who, lexicon)) != 1:
        return text
    if not re.fullmatch(_WHY_NOT32R[kind], m.group("why"), _F):
        return text
    cue = list(re.finditer(r",\s*(?:no|sorry|oops|hang on|wait|i mean|make it)\b", head, _F))
    before, after = head[: cue[0].start()], head[cue[-1].end() :]
    said = _ids(who, lexicon)
    if not said <= _ids(before, lexicon) or said & _ids(after, lexicon):
        return text
    if not _ids(after, lexicon, kind):
        return text  # the correction put nothing of its kind in its place: not corrected away
    return f"{head}{m.group('end') or '.'}"


# "Bottle to Person B, no, sorry, there's only Person A here, to her then."
_ONLY_ONE_HERE32R = re.compile(
    r"^(?P<head>.+?) (?P<prep>to|for) (?P<q>[A-Za-z][\w ]*?),\s*(?:(?:no|sorry|oops|wait),\s*)+"
    r"there(?:'s| is) only (?P<p>[A-Za-z][\w ]*?) here,\s*(?:so )?(?:to|for) (?:her|him|them)"
    r"(?: then| instead)?(?P<end>\s*[.!]?)$",
    _F,
)


# "Bottle to Person B. Oops, wrong bay, it's just Person A here, so Person A gets it." ('wrong
# bay' is 'no' once _cue_words31r has run)
_ONLY_ONE_HERE_SO32R = re.compile(
    r"^(?P<head>.+?) (?P<prep>to|for) (?P<q>[A-Za-z][\w ]*?)\.\s*(?:oops|sorry|whoops),?\s*"
    r"(?:(?:wrong (?:bay|room|person|one|ward)|no),?\s*)?it(?:'s| is) (?:just|only) "
    r"(?P<p>[A-Za-z][\w ]*?) here,?\s*so (?P<p2>[A-Za-z][\w ]*?|she|he|they) "
    r"(?:gets|has|should get|can have) it"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _only_one_here32r(text: str, lexicon: Lexicon) -> str:
    """Session 32 (12r): "X to Q, no, sorry, there's only P here, to her then" and "X to Q.
    Oops, wrong bay, it's just P here, so P gets it." are 'X to P' when P is the scene's one
    person and Q no other person of it (the slip the reason explains; 'Person B' may be read as a
    typo of P), and who 'gets it' is P; else left, refused."""
    m = _ONLY_ONE_HERE32R.match(text) or _ONLY_ONE_HERE_SO32R.match(text)
    if m is None or len(lexicon.scene.humans) != 1:
        return text
    p = m.group("p")
    p2 = m.groupdict().get("p2")
    if p2 is not None and not re.fullmatch(r"she|he|they", p2, _F) and p2.lower() != p.lower():
        return text
    if not _only_person(p, lexicon) or _ids(m.group("q"), lexicon) - _ids(p, lexicon):
        return text
    if not _fits(next(iter(_ids(p, lexicon))), m[0][m.end("p") :], lexicon):
        return text
    return f"{m.group('head')} {m.group('prep')} {p}{m.group('end') or '.'}"


# "There's only the bottle, and Person A's the only one here, so that's simple: give it to her."
_ONLY_THESE32R = re.compile(
    r"^there(?:'s| is) only (?P<x>the [a-z ]+?),? and (?P<p>[A-Za-z][\w ]*?)(?:'s| is) the only "
    r"(?:one|person) here,\s*so (?:that's|it's) (?:simple|easy|straightforward)\s*[:,;]\s*"
    r"(?P<rest>\S.*)$",
    _F,
)


def _only_these32r(text: str, lexicon: Lexicon) -> str:
    """Session 32 (12r): "There's only the X, and P's the only one here, so that's simple: give
    it to her" is 'give the X to P': the scene has one object (X) and one person (P), as said, and
    the request's 'it' / 'her' are they (else left, refused)."""
    m = _ONLY_THESE32R.match(text)
    if m is None or len(lexicon.scene.objects) != 1 or len(lexicon.scene.humans) != 1:
        return text
    x, p, rest = m.group("x"), m.group("p"), m.group("rest")
    if not _whole_name(x, lexicon, "object") or not _only_person(p, lexicon):
        return text
    if _names(rest, lexicon) or not _fits(next(iter(_ids(p, lexicon))), rest, lexicon):
        return text
    rest = _sub(r"\bit\b", x, rest)
    rest = _sub(r"\b(?:her|him|them)\b", p, rest)
    return f"{rest[:1].upper()}{rest[1:]}"


# "Mr Lee said the blue blanket itches, so give him the other one."
_OTHER_ONE32R = re.compile(
    r"^(?P<p>[A-Za-z][\w ]*?) (?:said|says|thinks|reckons|told me)(?: that)? (?P<x>the [a-z ]+?) "
    r"(?:itches|is itchy|scratches|is scratchy|is too (?:small|big|heavy|cold|warm|thin)|is "
    r"(?:dirty|broken|cracked|wet)|doesn't fit)\s*,\s*so (?P<v>give|hand|bring|pass|take) "
    r"(?P<pro>him|her|them) the other one(?P<end>\s*[.!]?)$",
    _F,
)


def _other_one32r(text: str, lexicon: Lexicon) -> str:
    """Session 32 (12r): 'P said the blue blanket itches, so give him the other one' is 'give P
    the grey blanket': the complaint (from a closed list) rules out the X named, 'the other one'
    is the scene's other object of that kind when it has exactly two (said by a name of it alone),
    and the pronoun is P (one person it fits); with three of the kind, refused as before."""
    m = _OTHER_ONE32R.match(text)
    if m is None or not _only_person(m.group("p"), lexicon):
        return text
    x = m.group("x")
    ids = _ids(x, lexicon, "object")
    if len(ids) != 1 or not _whole_name(x, lexicon, "object"):
        return text
    kinds = _kinds(ids, lexicon)
    same = [o for o in lexicon.scene.objects if o.category in kinds]
    if len(same) != 2 or not _fits(
        next(iter(_ids(m.group("p"), lexicon))), m.group("pro"), lexicon
    ):
        return text
    (other,) = [o for o in same if o.id not in ids]
    name = next((a for a in other.aliases if _ids(a, lexicon) == {other.id}), "")
    if not name:
        return text
    return f"{m.group('v').capitalize()} {m.group('p')} the {name}{m.group('end') or '.'}"


# "…, all except the blue one, that stays where it is."
_EXCEPT_STAYS32R = re.compile(
    r"(?P<head>\b(?:except|apart from|other than|bar|but not) (?:for )?the [a-z ]+?)\s*,\s*"
    r"(?:that|it|which)(?: one)? (?:stays|can stay|is staying|is to stay) (?:put|where it is|here|"
    r"there)(?P<end>\s*[.!]?)$",
    _F,
)


def _except_stays32r(text: str, lexicon: Lexicon) -> str:
    """Session 32 (12r): '…, all except the blue one, that stays where it is' is '…, all except
    the blue one': the clause after the exclusion says of what it left out (one object, 'the
    blue one' after 'the pens' too) that it stays, which the exclusion already says."""
    m = _EXCEPT_STAYS32R.search(text)
    if m is None:
        return text
    excluded = m.group("head").split(" the ", 1)[1]
    said = _one(f"the {excluded}", text[: m.start()], lexicon)
    if not _one_object32r(said, lexicon):
        return text
    return f"{text[: m.end('head')]}{m.group('end') or '.'}"


def _either_of_them32r(text: str, lexicon: Lexicon) -> str:
    """Session 32 (12r): 'Give them a thing each, X and Y' and 'X to either of them' in a text
    that names no person are the scene's people when it has two: 'Give P and Q one of X and Y
    each' (_split29r's reading, two objects) and 'X to P or Q'. With more people, or a person
    named, 'them' is not the scene's pair and the text is left, refused."""
    humans = lexicon.scene.humans
    if len(humans) != 2 or _ids(text, lexicon, "human"):
        return text
    p, q = (h.name for h in humans)
    m = re.match(
        r"^(?:please )?give them (?:a thing|one thing|an item|one item|one|something) (?:each|"
        r"apiece),\s*(?P<x>the [a-z ]+? and the [a-z ]+?)(?P<end>\s*(?:[,;.!]|$))",
        text,
        _F,
    )
    if m is not None:
        split = f"Split {m.group('x')} between {p} and {q}, one each"
        if _split29r(split, lexicon) == split:
            return text
        return f"Give {p} and {q} one of {m.group('x')} each{text[m.start('end') :]}"
    return _sub(r"\b(?P<v>to|for) either of them\b", rf"\g<v> {p} or {q}", text)


def _choice_adjectives32r(text: str, lexicon: Lexicon) -> str:
    """Session 32 (12r): 'one of the mugs for him, red or blue, …' is 'one of the mugs for him,
    …': the adjectives say the choice again when each with the kind names one of its objects and
    together they name all of them (else left: 'red or green' with no green mug is refused)."""

    def again(m: re.Match[str]) -> str:
        kind = m.group("kind")
        adjectives = re.split(r",\s*(?:or\s+)?|\s+or\s+", m.group("adj"))
        names = [f"{a} {kind}" for a in adjectives]
        if not all(_one_object32r(n, lexicon) for n in names):
            return m[0]
        if set().union(*(_ids(n, lexicon) for n in names)) != _ids(kind, lexicon, "object"):
            return m[0]
        return m.group("head")

    return _sub(
        r"(?P<head>\b(?:one|either|any) of the (?P<kind>[a-z]+)s\b[^,;:.!?]*?),\s*(?:the )?"
        r"(?P<adj>[a-z]+(?:,\s*(?:the )?[a-z]+)*,? or (?:the )?[a-z]+)(?=\s*(?:[,;.!]|$))",
        again,
        text,
    )


# "Both of the blocks are to go in the high chair so Lily can bash them about."
_SO_CAN32R = re.compile(
    r"^(?P<head>[^,;:.!?]+?)\s*,?\s*so (?:that )?(?P<p>[A-Za-z][\w ]*?) can (?P<v>[a-z]+)"
    r"(?: (?:with|at|on))? (?:them|it)(?: (?:about|around|later|there|in peace))?"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


_HANDED_VERBS32R = frozenset({"keep", "use", "grab", "hold", "reach", "see", "find", "borrow"})


def _so_can32r(text: str, lexicon: Lexicon) -> str:
    """Session 32 (12r): a placement then 'so P can bash them about' (what P will do with the
    things placed) is the placement: taken off when the request names a surface and no person, P
    is one person of the scene and the verb is none of the grammar's (a purpose that hands
    something over, 'so Lily can have them', is left)."""
    m = _SO_CAN32R.match(text)
    if m is None or not _only_person(m.group("p"), lexicon):
        return text
    head = m.group("head")
    if not _ids(head, lexicon, "surface") or not _ids(head, lexicon, "object"):
        return text
    verb = m.group("v").lower()
    if _ids(head, lexicon, "human") or verb in VERBS or verb in _HANDED_VERBS32R:
        return text
    return f"{head}{m.group('end') or '.'}"


_STEPS32R: tuple[Callable[[str, Lexicon], str], ...] = (
    _apposed_list32r,
    _apposed_adjectives32r,
    _all_things32r,
    _taken_home32r,
    _apiece32r,
    _each_of_them32r,
    _either_of_them32r,
    _you_pick32r,
    _choice_tail32r,
    _both_want_either32r,
    _reach_first32r,
    _not_wanted32r,
    _stays_put32r,
    _only_nothing_else32r,
    _no_need_first32r,
    _not_other_person32r,
    _only_the_one32r,
    _dont_suppose32r,
    _whatevers_here32r,
    _others_rest32r,
    _other_isnt32r,
    _any_except32r,
    _isnt_adjective32r,
    _er_person32r,
    _no_such_place32r,
    _corrected_reason32r,
    _only_one_here32r,
    _only_these32r,
    _other_one32r,
    _into_with_them32r,
    _for_table32r,
    _counted_header32r,
    _except_stays32r,
    _choice_adjectives32r,
    _so_can32r,
)


# -- session 33 (engineer 12t): blind17, blind23, blind18, causes17 and blind15's kinds ------------

_N33T = {"two": 2, "three": 3, "four": 4}
# how much each person gets, said before the list that says what: 'one thing', 'an item',
# 'something (to drink from)', 'two things'
_AMOUNT33T = (
    r"(?:one thing|one item|a thing|an item|something|(?P<n>two|three) (?:things|items))"
    r"(?: to (?:drink|eat|read|use)(?: from| with| out of)?)?"
)
# who they are: every person of the scene ('each of them'), or so many ('both', 'the two of them')
_WHO33T = (
    r"(?:each of (?:them|you)|each of the (?P<k1>two|three|four)(?: of them)?|both (?:of them|of "
    r"you|people)|the (?P<k2>two|three|four) of them|all (?P<k3>two|three|four) of them)"
)
_EACH_HEADERS33T = (
    # "Both people get an item each: …", "Each of them gets one thing: …"
    rf"^{_WHO33T} (?:gets?|can have|receives?|should get|will get) {_AMOUNT33T}"
    r"(?: each| apiece)?\s*[:,]\s*",
    # "Something for both of them: …", "One thing apiece for the two of them: …"
    rf"^{_AMOUNT33T}(?: each| apiece)? for {_WHO33T}\s*[:,]\s*",
    # "Two things each: …"
    rf"^{_AMOUNT33T} (?:each|apiece)\s*:\s*",
)


def _handovers33t(text: str, lexicon: Lexicon) -> list[Task] | None:
    """The hand-overs ``text`` reads as, all of them asked ('and'), or None where it is refused
    or reads as anything else (a choice, an order, a placement)."""
    node = _reading(text, lexicon)
    if node is None or not isinstance(node, Group) or node.op != "and":
        return None
    said = list(tasks(node))
    return said if all(t.kind == "deliver" for t in said) else None


def _each_one28r(text: str, lexicon: Lexicon) -> str:
    """Session 28 (12r): 'Hand out one thing apiece: …', 'one thing each: …', 'Both of them need
    something, so …' before a list of hand-overs: the list says who gets what, and is read alone
    when it gives every person of the scene exactly one object (as 'each' says); a list that
    leaves someone out, gives one two, or places something is left, and refused."""
    m = _EACH_ONE28R.search(text)
    if m is None:
        return text
    rest = text[m.end() :]
    rest = rest[:1].upper() + rest[1:]
    said = _handovers33t(rest, lexicon)
    if said is None:
        return text
    people = [t.target for t in said]
    if len(set(people)) != len(people) or set(people) != {h.id for h in lexicon.scene.humans}:
        return text
    return rest


def _each_header33t(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12t): a header saying how much each person gets ('Both people get an item
    each:', 'Each of them gets one thing:', 'Something for both of them:', 'One thing apiece for
    the two of them:', 'Two things each:', 'Each of them gets something to drink from,'), then
    the list of hand-overs that says what: the list is read alone when it is a count check the
    scene passes: it hands over only, to every person of the scene (as many as 'both' / 'the two'
    say), and to each exactly as many objects as the header says. Any other list is left (and
    refused)."""
    for header in _EACH_HEADERS33T:
        m = _rx(header).match(text)
        if m is not None:
            break
    else:
        return text
    rest = text[m.end() :]
    if "," in m.group(0) and not re.match(r"(?:the |[A-Z])", rest):
        return text  # after a comma, the list itself ("…, mind: …" is session 33 (12r)'s)
    rest = rest[:1].upper() + rest[1:]

    def whose(w: re.Match[str]) -> str:
        # after the header, "the bottle's Person A's" says who gets it
        return f"{w.group(1)} to {w.group(2)}" if _only_person(w.group(2), lexicon) else w.group(0)

    rest = _sub(r"\b(the [a-z ]+?)(?:'s| is| are) ([a-z][\w ]*?)'s\b", whose, rest)
    said = _handovers33t(rest, lexicon)
    if said is None:
        return text
    humans = {h.id for h in lexicon.scene.humans}
    groups = m.groupdict()
    count = groups.get("k1") or groups.get("k2") or groups.get("k3")
    if "both" in m.group(0).lower():
        count = "two"
    if len(humans) < 2 or (count is not None and _N33T[count.lower()] != len(humans)):
        return text
    amount = _N33T[m.group("n").lower()] if m.group("n") else 1
    got = [t.target for t in said]
    if set(got) != humans or any(got.count(h) != amount for h in humans):
        return text
    return rest


# what a kind word covers, by the objects' categories (lexicon.KIND_CATEGORIES)
_KINDS33T = KIND_CATEGORIES


def _kind_choice33t(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12t): 'One of the drinks for Person A: the bottle or the cup' is 'give Person
    A the bottle or the cup' when each object listed is of a category the kind word covers
    (``_KINDS33T``; "…: the bottle or the chips" is left, and refused), as 'One of the pens for
    Priya: the red or the blue' is (``_choices17``)."""
    m = _rx(
        r"^one of the (drinks|snacks) for ([a-z][\w ]*?)\s*:\s*(the [a-z ]+?) or (the [a-z ]+?)"
        r"\s*([.!]?)$"
    ).match(text)
    if m is None or not _only_person(m.group(2), lexicon):
        return text
    kinds = _KINDS33T[m.group(1).lower()]
    for said in (m.group(3), m.group(4)):
        ids = _ids(said, lexicon, "object")
        if len(ids) != 1 or not _only(said, lexicon, "object"):
            return text
        if lexicon.scene.object(next(iter(ids))).category not in kinds:
            return text
    return f"give {m.group(2)} {m.group(3)} or {m.group(4)}{m.group(5)}"


def _each_any33t(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12t): 'Give each of them a pen, Priya and Sam, any colour' is 'Priya and Sam
    each get a pen': 'them' is the two people said after it, and 'any colour' (or size, or one)
    says again that the pen is not chosen. Only 'a/an <word>' is so said again; 'the red one'
    after the names is left."""
    m = _rx(
        r"^(?:give )?each of (?:them|you|the two) (?:gets? |can have |should get )?(an? [a-z]+),"
        r"\s*([^,]+?) and ([^,]+?),\s*any (?:colou?r|size|one|kind)\s*([.!]?)$"
    ).match(text)
    if m is None or not (_only_person(m.group(2), lexicon) and _only_person(m.group(3), lexicon)):
        return text
    return f"{m.group(2)} and {m.group(3)} each get {m.group(1)}{m.group(4)}"


def _plural33t(word: str) -> str:
    return f"{word}es" if word.endswith(("x", "ch", "sh", "s")) else f"{word}s"


def _other_two33t(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12t): 'No black pen for Priya, one of the other two will do' is 'Priya gets
    one of the pens except the black pen' when the scene has as many other objects of the black
    pen's category as the count says ('the other two'; 'either of the others' when two)."""
    m = _rx(
        r"^no (the )?([a-z][a-z ]*?) for ([a-z][\w ]*?),\s*(?:just )?(?:one of the other "
        r"(two|three|four)|either of the other (two)|either of the others) (?:will do|is fine|"
        r"'ll do|would do)\s*([.!]?)$"
    ).match(text)
    if m is None or not _only_person(m.group(3), lexicon):
        return text
    said = f"the {m.group(2)}"
    if not _only(said, lexicon, "object"):
        return text
    obj = lexicon.scene.object(next(iter(_ids(said, lexicon, "object"))))
    others = [o for o in lexicon.scene.objects if o.category == obj.category and o.id != obj.id]
    count = _N33T[(m.group(4) or m.group(5) or "two").lower()]
    if len(others) != count:
        return text
    return f"{m.group(3)} gets one of the {_plural33t(obj.category)} except {said}{m.group(6)}"


def _leave_where33t(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12t): after a request for everything ('everything', 'the lot', 'all of it'),
    '…, (just) leave the X where they are' is '…, except the X' ("Bob gets the lot, just leave
    the two mugs where they are"); 'clear everything into / onto S' (S a surface of the scene)
    is 'put everything into / onto S'. A request for named objects is left: there 'leave' may
    correct it."""
    m = _rx(
        r"^(.*\b(?:everything|the lot|all of it)\b.*?),\s*(?:and |but )?(?:just )?leave (the "
        r"[a-z ]+?) (?:where (?:it is|they are)|alone|be)\s*([.!]?)$"
    ).match(text)
    if m is None or not _ids(m.group(2), lexicon, "object"):
        return text
    if not _names(m.group(2), lexicon) or not all(
        r.kind == "object" for it in _names(m.group(2), lexicon) for r in it.refs
    ):
        return text
    head = m.group(1)
    c = _rx(r"^clear (everything|the lot|all of it) (into|onto|in|on) (the [a-z ]+?)$").match(head)
    if c is not None:
        if not _only(c.group(3), lexicon, "surface"):
            return text
        head = f"put {c.group(1)} {c.group(2)} {c.group(3)}"
    return f"{head}, except {m.group(2)}{m.group(3)}"


def _load_up33t(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12t): 'load P up with X' (P a person) is 'give P X'; 'pack / load S with X' (S
    a surface) is 'put X on S'."""

    def person(m: re.Match[str]) -> str:
        return f"give {m.group(1)} " if _only_person(m.group(1), lexicon) else m.group(0)

    text = _sub(r"\bload ([a-z][\w ]*?) up with ", person, text)

    def surface(m: re.Match[str]) -> str:
        if not _only(m.group(2), lexicon, "surface"):
            return m.group(0)
        return f"put {m.group(3)} on {m.group(2)}"

    return _sub(
        r"\b(pack|load|fill) (the [a-z ]+?) with (the lot|everything|the [a-z ]+?)(?=,|[.!]?$)",
        surface,
        text,
    )


def _wont_you33t(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12t): 'won't you' before a verb of a request ("Give Ava the teddy, won't you
    give Lily the bib too?") asks it politely: the request. Said by a subject ('you won't give')
    it negates, and is left."""
    return _sub(rf"(^|,\s*|\band\s+)won't you (?={_DO_VERBS})", r"\1", text)


def _fronted_to33t(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12t): the recipient said first, 'Unto Person A the chips' / 'To Person A the
    chips' / 'Give unto Person B …' ('give Person A the chips'; P one person of the scene, the
    objects after it), and 'whichever thou wilt / you like of the X or the Y' ('either the X or
    the Y': the robots choose)."""

    def fronted(m: re.Match[str]) -> str:
        if not _only_person(m.group(2), lexicon):
            return m.group(0)
        return f"{m.group(1)}give {m.group(2)} "

    text = _sub(
        r"(^|[.;:!]\s+)(?:give )?(?:un)?to ([a-z][\w ]*?) (?=(?:the|either|whichever|both|all) )",
        fronted,
        text,
    )
    return _sub(
        r"\bwhichever (?:thou|you) (?:wilt|will|like|want|wish|please|fancy|prefer) of (the "
        r"[a-z ]+?) or (the [a-z ]+?)(?=\s*[.!]?$)",
        r"either \1 or \2",
        text,
    )


# interjections and words of address (by kind, _INTERJECTION19 / _ADDRESS19) that may stand
# alone between commas next to a correction; those that join, point, time or may be asked for
# are not among them
_EXCLAIMS33T = (_INTERJECTION19 | _ADDRESS19) - {
    *("and", "just", "there", "please", "thanks", "thank", "you", "kindly", "quick", "slow"),
    *("slowly", "like", "hands", "fine", "right", "well", "so", "now", "ok", "okay", "yeah"),
    *("yep", "yup", "aye", "alright", "old", "me", "my", "our", "good", "young", "big"),
    *("little", "people", "easy", "steady", "careful", "smart", "o"),
    # hesitations are repair words (repairs.py, session 33's subject and object repairs)
    *("hmm", "um", "uh", "er", "erm"),
}
_FIX_CUE33T = r"(?:sorry|no|wait|oops|whoops|actually|i mean|i meant|hang on|hold on|oh no)\b"


def _is_closer33t(words: str, lexicon: Lexicon) -> bool:
    """Whether ``words`` ('…, sorry, love.') are only apology, thanks and address, naming
    nothing of the scene."""
    said = re.findall(r"[a-z']+", words.lower())
    return _names_nothing(words, lexicon) and all(
        w in _EXCLAIMS33T or w in _ADDRESS or w in ("sorry", "thanks", "please") for w in said
    )


def _exclaimed_fix33t(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12t): a correction with an interjection or a word of address beside it ("The
    hammer for Jess, eish, sorry, the drill for Jess", "…, oh no wait, on the desk, cariad,
    tidy."): the word, alone between commas just before the correction's cue or after what the
    correction names at the end, is taken off (it names nothing of the scene: a scene's 'doll'
    stays); '…, oops, Person A, I mean, sorry, love.' says 'I mean' after the name it corrects
    to: taken off there too. The correction is then read as one without them."""
    low = text.lower()
    if not any(cue in low for cue in ("sorry", "no", "wait", "oops", "mean", "actually", "hang")):
        return text

    def alone(m: re.Match[str]) -> str:
        word = m.group(2)
        if word.lower() not in _EXCLAIMS33T or not _names_nothing(word, lexicon):
            return m.group(0)
        return m.group(1)

    # before the cue: "…, eish, sorry, …"
    out = _sub(rf"(,\s*)([a-z']+)\s*,\s*(?={_FIX_CUE33T})", alone, text)
    if _rx(_FIX_CUE33T).search(out) is None:
        return text

    def at_end(m: re.Match[str]) -> str:
        word = m.group(1)
        if word.lower() not in _EXCLAIMS33T or not _names_nothing(word, lexicon):
            return m.group(0)
        return m.group(2)

    # after the correction, ending the text: "…, on the desk, cariad, tidy."
    for _ in range(3):
        was = out
        out = _sub(r"(?<=[a-z]),\s*([a-z']+)(\s*[.!]*)\s*$", at_end, out)
        if out == was:
            break
    m = _rx(rf"^(.*\b{_FIX_CUE33T},?\s+[^,]+?),\s*i mean\b(.*)$").match(out)
    if m is not None and m.group(2).strip(" ,.!") and not _is_closer33t(m.group(2), lexicon):
        return out
    return out if m is None else m.group(1) + m.group(2)


def _unknown_fixed33t(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12t): 'Forceps, sorry, I mean the spoon, to Omar.': the first word names
    nothing of the scene, and the speaker says at once ('sorry / no / oops, I mean') which object
    they mean: that object ('the spoon, to Omar.'). A first word the scene names ('The cup,
    sorry, I mean the spoon') is a correction read as before."""
    m = _rx(
        r"^(?:the )?([a-z]+),\s*(?:(?:sorry|no|oops|whoops),?\s+)+i (?:mean|meant),?\s+(the "
        r"[a-z ]+?),\s*(.+)$"
    ).match(text)
    if m is None or not _names_nothing(m.group(1), lexicon) or _KEEP_WORDS.search(m.group(1)):
        return text
    if not _only_kind(m.group(2), lexicon, "object"):
        return text
    return f"{m.group(2)}, {m.group(3)}"


# after a placement, whom it is put there for and what they will do: 'in the high chair for Lily
# to play with'
_PLACED_FOR33T = (
    r"(?P<place>\b(?:on|in|onto|into) (?:the )?[a-z]+(?: [a-z]+)?) for "
    rf"(?P<p>{_PERSON32}) to (?P<v>[a-z]+)(?: (?:with|on|in|from|at))?(?=\s*(?:[,.;!?]|$))"
)


def _placed_for33t(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12t): 'The two blocks in the high chair for Lily to play with.': after 'on /
    in S' (S one surface of the scene), 'for P to <verb> (with)' (P one person, the verb no verb
    of the grammar nor a scene name) says whom the placement is for and what they will do, as
    'for Mr Lee to read' does (``_for_to_do32``): taken off when what is left reads as
    placements only and names P nowhere else (the placement is asked; P gets nothing). A bare
    'for P' after a placement stays refused (sessions 30 and 31: 'Put the ruler on the desk for
    Noah' may ask for it to reach Noah)."""
    if " for " not in text:
        return text
    m = _rx(_PLACED_FOR33T).search(text)
    if m is None:
        return text
    where = re.sub(r"^(?:on|in|onto|into) ", "", m["place"], flags=_F)
    if not (_surface_only(where, lexicon) and _only_person(m["p"], lexicon)):
        return text
    # the verb of use may be a word of a scene name ('play' of 'play mat'), never a name itself
    if m["v"].lower() in VERBS or _ASKS29.search(m["v"]) or not _names_nothing(m["v"], lexicon):
        return text
    out = text[: m.start()] + m["place"] + text[m.end() :]
    if _ids(out, lexicon, "human"):
        return text
    said = _tasks_of(out, lexicon)
    return out if said and all(kind == "place" for kind, _, _ in said) else text


# words ending in -ing that are no verb's -ing form
_NOT_GERUNDS33T = frozenset(
    {
        *("nothing", "something", "anything", "everything", "morning", "evening", "king"),
        *("ring", "thing", "spring", "string", "wing", "sing", "bring", "during", "ceiling"),
        *("pudding", "icing", "sibling", "darling", "duckling", "sling", "swing", "sting"),
        *("building", "wedding", "clothing", "bedding", "stuffing", "filling", "timing"),
    }
)


def _purpose_ing33t(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12t): what an object is for, said with an -ing verb after it ("Person A needs
    the cup for rinsing the core samples", "Everything goes to the sink for washing"): taken
    off when the -ing word is a verb's (not 'nothing', 'evening': ``_NOT_GERUNDS33T``, no verb
    of the grammar) and neither it nor what follows it, up to the clause's end, names anything
    of the scene or asks anything (``_asks_nothing29``)."""
    if "ing" not in text:
        return text

    def purpose(m: re.Match[str]) -> str:
        verb = m.group(2).lower()
        if verb in _NOT_GERUNDS33T or len(verb) < 6 or verb[:-3] in VERBS:
            return m.group(0)
        if not _asks_nothing29(m.group(2) + m.group(3), lexicon):
            return m.group(0)
        return m.group(1)

    return _sub(
        r"\b((?:the [a-z]+|everything|it|them)(?: goes to the [a-z]+)?) for ([a-z]+ing)"
        r"((?: [a-z']+){0,4}?)(?=\s*(?:[,;.!?]|\band\b|$))",
        purpose,
        text,
    )


def _stays_on33t(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12t): '… Grey blanket stays on the cart.': an object said to stay on the
    surface it starts on (inside its footprint) is to be left where it is, as '… stays put' (read
    by the rules for that); an object that does not start there is left (staying there would be
    a move, and is refused)."""
    if "stay" not in text.lower():
        return text

    def stays(m: re.Match[str]) -> str:
        if not (_only(m["o"], lexicon, "object") and _surface_only(m["s"], lexicon)):
            return m[0]
        (obj,) = _ids(m["o"], lexicon, "object")
        (where,) = _ids(m["s"], lexicon, "surface")
        return f"{m['lead']}{m['o']} stays put" if starting_on({obj}, where, lexicon) else m[0]

    return _sub(
        r"(?P<lead>(?:^|[.;,]\s*)(?:and |but )?)(?P<o>(?:the )?[a-z]+(?: [a-z]+)?) (?:stays|can "
        r"stay|should stay) (?:on|in) (?P<s>(?:the )?[a-z]+(?: [a-z]+)?)(?=\s*(?:[.;!]|$))",
        stays,
        text,
    )


def _each_said33t(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12t): '…, and not the cup either' after a 'not' is '…, and not the cup' (one
    more left out); 'Each patient, receives one blanket, whichever colour' (a filler taken off
    between 'each <role>' and its verb) is 'Each patient receives one blanket': 'whichever
    colour / size' after 'each … one / a <noun>' says again that which one is not chosen; a
    manner word between commas after 'each <role>' ('gently', not 'only') is taken off."""
    out = _sub(
        r"(\bnot\b[^.;]*?,\s*and not (?:the )?[a-z ]+?)\s+either(?=\s*[.!]?$)",
        r"\1",
        text,
    )
    m = _rx(
        r"^(each [a-z]+)(?:,\s*([a-z]+ly)\s*)?,?\s+(receives?|gets?|should get|can have) (one|a|"
        r"an) ([a-z]+)(?:,\s*whichever (?:colou?r|size|one))?\s*([.!]?)$"
    ).match(out)
    if m is None or (m.group(2) and m.group(2).lower() in _LY_HELD19):
        return out
    return f"{m.group(1)} {m.group(3)} {m.group(4)} {m.group(5)}{m.group(6)}"


def _both_named33t(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12t): 'both mugs, (the) red and (the) blue,' names the two mugs again by what
    tells them apart: 'both mugs', when 'the red mug' and 'the blue mug' are the scene's two
    mugs (any other pair is left) and the sentence names no other object (with one, as in
    session 29's near form 'Give Alice the cup and both mugs, red and blue.', the words could be
    about it: left). 'Both mugs, could they go to Alice?' is 'could both mugs go to Alice?', and
    'easy / gently does it' (take care) is taken off between commas."""
    out = _drop(r",\s*(?:gently|easy|steady|slowly) does it(?=\s*[,.!]|$)", text, lexicon)

    def named(m: re.Match[str]) -> str:
        kind = _singular(m.group(2).lower())
        both = _ids(f"the {m.group(2)}", lexicon, "object")
        one = _ids(f"the {m.group(3)} {kind}", lexicon, "object")
        two = _ids(f"the {m.group(4)} {kind}", lexicon, "object")
        if len(both) != 2 or len(one) != 1 or len(two) != 1 or one | two != both:
            return m.group(0)
        before = re.split(r"[.;!?]", m.string[: m.start()])[-1]
        after = re.split(r"[.;!?]", m.string[m.end() :])[0]
        if _ids(before, lexicon, "object") or _ids(after, lexicon, "object"):
            return m.group(0)
        # opening the sentence, what follows is its verb ('Both spanners go …'); later, a clause
        # of its own ('Lily's to have both blocks, she wants …')
        return f"{m.group(1)}{m.group(2)}{' ' if not before.strip() else ', '}"

    out = _sub(
        r"\b(both (?:the )?)([a-z]+s),\s*(?:the )?([a-z]+) and (?:the )?([a-z]+)(?: ones)?,\s*",
        named,
        out,
    )
    return _sub(
        r"^((?:sorry|so|right|now),\s*)?(both (?:the )?[a-z]+s),?\s*(could|can|would|will) they "
        r"(go|be taken|be given) (to [a-z][\w ]*?)\s*\?",
        r"\1\3 \2 \4 \5?",
        out,
    )


def _got_them33t(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12t): 'once he's got them' / 'after she's got them' / 'once hes got them'
    (without the apostrophe) is 'once he has them' (a pronoun for the objects just named, as
    the grammar reads it), and the clause after it is set off by a comma when it is not: "tom
    wants the gloves and once hes got them mia wants the tape"."""
    if "got" not in text.lower():
        return text

    def got(m: re.Match[str]) -> str:
        have = "have" if m.group(2).lower() == "they" else "has"
        return f"{m.group(1)} {m.group(2)} {have} {m.group(3)}, "

    return _sub(
        r"\b(once|after|when) (he|she|they)(?:'s|s|'ve| has| have)? got (it|them)\b,?\s+",
        got,
        text,
    )


def _need_over33t(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12t): 'What I need is the bottle over with Person B' / '(I) need the chips
    over with person b' is 'I need the bottle taken over to Person B' (the speaker's need, said
    with where the object is to go: the person named gets it); 'like right now' is 'right
    now'."""
    out = _sub(r"\blike (?=right now\b|now\b|asap\b|straight away\b)", "", text)

    def over(m: re.Match[str]) -> str:
        if not (_only_kind(m.group(1), lexicon, "object") and _only_person(m.group(2), lexicon)):
            return m.group(0)
        return f"I need {m.group(1)} taken over to {m.group(2)}"

    return _sub(
        r"^(?:what i need is|i need|need) (the [a-z ]+?) over (?:with|to) ([a-z][\w ]*?)"
        r"(?=\s*(?:right now|now)?\s*[.!]?$)",
        over,
        out,
    )


def _telegraphed33t(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12t): words of a quick note. 'could P grab / take / get the X off you' is
    'could P have the X' (P takes it from the robot: a hand-over); 'apple n bottle' ('n' between
    two object names) is 'apple and bottle'; 'That one bottle' is 'the bottle' where the scene
    has one bottle only (with more, 'that one' points at one: left); 'P wants the X only, kindly
    do the needful' is 'P wants the X' ('only' after the one object wanted; 'do the needful',
    do what is needed, a closer)."""
    out = text

    def off(m: re.Match[str]) -> str:
        return (
            f"{m.group(1)} {m.group(2)} have " if _only_person(m.group(2), lexicon) else m.group(0)
        )

    out = _sub(
        r"\b(could|can) ([a-z][\w ]*?) (?:grab|take|get) (?=the [a-z ]+? (?:off|from) you\b)",
        off,
        out,
    )
    out = _sub(r"(\bhave the [a-z ]+?) (?:off|from) you\b", r"\1", out) if out != text else out

    def joined(m: re.Match[str]) -> str:
        if _only_kind(m.group(1), lexicon, "object") and _only_kind(m.group(2), lexicon, "object"):
            return f"{m.group(1)} and {m.group(2)}"
        return m.group(0)

    out = _sub(r"\b([a-z]+) n ([a-z]+)\b", joined, out)

    def that_one(m: re.Match[str]) -> str:
        said = f"the {m.group(2)}"
        if not _only(said, lexicon, "object"):
            return m.group(0)
        kind = lexicon.scene.object(next(iter(_ids(said, lexicon, "object")))).category
        if sum(o.category == kind for o in lexicon.scene.objects) != 1:
            return m.group(0)
        return f"{m.group(1)}{said}"

    out = _sub(r"(^|[.;]\s*)that one ([a-z]+)\b", that_one, out)
    return _sub(
        r"^([a-z][\w ]*? (?:wants|needs|is wanting) the [a-z]+) only(?:,\s*(?:kindly |please )?do "
        r"the needful)?\s*([.!]?)$",
        lambda m: m.group(1) + m.group(2) if _ids(m.group(1), lexicon, "human") else m.group(0),
        out,
    )


def _said_again33t(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12t): 'P wants the X left in / on S' is 'P wants the X put in S' ('left', the
    participle of leave, between an object and a surface; 'on the left' is no such place);
    '…, then the apple (the) same way' after a hand-over is '…, then the apple too' (the same
    hand-over); '… as well while he's at it' is '… as well'; 'Either X or Y goes to P' (or
    'shall be given to P') is 'X or Y goes to P', and 'at your discretion' after a choice is
    taken off."""
    out = _sub(
        r"\b(wants?|needs?|would like) (the [a-z ]+?) left (in|on|into|onto) "
        r"(?=the [a-z ]+?\s*(?:[,.!]|$))",
        r"\1 \2 put \3 ",
        text,
    )
    out = _sub(r"(,\s*(?:and )?then the [a-z]+) (?:the )?same way\b", r"\1 too", out)
    out = _sub(
        r"\b(too|as well|also)\s*,?\s*while (?:he|she|they|you)(?:'s|'re| is| are) at it\b",
        r"\1",
        out,
    )
    if " or " in out:
        # "…, at your discretion" after a choice: the robots choose, as the choice says
        out = _sub(r",\s*(?:at your discretion|as you see fit)(?=\s*[.!]?$)", "", out)
    return _sub(
        r"^either ((?:the )?[a-z]+ or (?:the )?[a-z]+) (?:goes|go|should go|is going|shall be "
        r"given|should be given) to\b",
        r"\1 goes to",
        out,
    )


def _owner_said33t(text: str, start: int, end: int, who: str, obj: str, lexicon: Lexicon) -> str:
    """``_whose33t``'s rewrite of "<who>'s <obj>" (``text[start:end]``), or ``text``."""
    rest = text[end:]
    if _ids(text[:start] + rest, lexicon, "human"):
        return text
    (pid,) = _ids(who, lexicon, "human")
    said = f"{text[:start]}the {obj}"
    to = _rx(r"^(.*?\b(?:to|for) )(him|her)\b").match(rest)
    if to is not None and _fits(pid, to.group(2), lexicon):
        return f"{said}{to.group(1)}{who}{rest[to.end() :]}"
    on = _rx(r"^( (?:on|in|onto|into) )(?:his|her) ([a-z]+(?: [a-z]+)?)\b").match(rest)
    if on is not None and _fits(pid, rest, lexicon) and _surface_only(on.group(2), lexicon):
        return f"{said}{on.group(1)}the {on.group(2)}{rest[on.end() :]}"
    return text


def _whose33t(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12t): an object said as a person's ('Grandad's beaker', 'Lily's bib') where
    the scene has that object once: 'bring Grandad's beaker over to him' is 'bring the beaker
    over to Grandad' (the pronoun after it fits him, and no one else is named); 'put Lily's bib
    on her high chair' is 'put the bib on the high chair' (the owner of the place, one surface of
    the scene, is the owner said before). Anything else is left."""
    if "'s " not in text:
        return text
    for m in _rx(r"\b(?:(\w+) )?(\w+)'s ([a-z]+)( [a-z]+)?\b").finditer(text):
        who = next(
            (w for w in (m.group(2), f"{m.group(1)} {m.group(2)}") if _only_person(w, lexicon)),
            None,
        )
        if who is None:
            continue
        obj = next(
            (
                o
                for o in (m.group(3) + (m.group(4) or ""), m.group(3))
                if _only(f"the {o}", lexicon, "object")
            ),
            None,
        )
        if obj is None:
            return text
        start = m.end(2) - len(who)
        end = m.start(3) + len(obj)
        return _owner_said33t(text, start, end, who, obj, lexicon)
    return text


# a pair noun ('the one pair' of tongs)
_PAIRS33T = frozenset({"tongs", "scissors", "gloves", "pliers", "tweezers", "shears", "glasses"})


def _one_said33t(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12t): a count or a choice said again after the request. '…, just the one
    pair' after a pair noun the scene has once ('Marco needs his tongs'); '…, not the green one,
    only red' where what is left is the red one alone; '…, and, honestly, that's the whole job
    today' closing a request (taken off, as 'that's all'); 'Lily wants the two blocks to bang
    together' ('to bang': what she will do with them, _USES; 'together' says it of both)."""
    out = _sub(r"\b(to [a-z]+) together(?=\s*[.!]?$)", r"\1", text)
    out = _sub(
        r"(?:,\s*and)?(?:,\s*(?:honestly|really|truly|basically))?,\s*that's (?:the whole job|all)"
        r"(?: (?:today|for today|for now))?(?=\s*[.!]?$)",
        "",
        out,
    )
    m = _rx(r"^(.*\b(?:his|her|their|the) ([a-z]+)),\s*just the one pair\s*([.!]?)$").match(out)
    if (
        m is not None
        and m.group(2).lower() in _PAIRS33T
        and _only(f"the {m.group(2)}", lexicon, "object")
    ):
        out = m.group(1) + m.group(3)
    m = _rx(r"^(.*\bnot the [a-z]+ one),\s*only (?:the )?([a-z]+)(?: one)?\s*([.!]?)$").match(out)
    if m is not None:
        said = _tasks_of(m.group(1) + m.group(3), lexicon)
        kept = {obj for _, obj, _ in said or ()}
        named = {
            o.id
            for o in lexicon.scene.objects
            if o.id in kept
            and any(
                m.group(2).lower() in a.lower().split()
                for a in (o.id.replace("_", " "), *o.aliases)
            )
        }
        if said and len(kept) == 1 and named == kept:
            out = m.group(1) + m.group(3)
    return out


# a statement about something the scene does not have, opening the instruction before a request
# ("Stock room's a mess, grab …", "Sorry, the dogs are going mad outside, could you …")
_OPENING33T = (
    r"^(?P<lead>(?:(?:sorry|oh|so|well|right|okay|ok)\s*,?\s+)*)(?P<said>(?:the |our |my )?[a-z]+"
    r"(?: [a-z]+)?(?:'s|'re| is| are) [a-z' ]+?),\s+(?P<rest>(?:(?:so|and)\s+)?(?:could|can|would|"
    r"will|please|give|hand|pass|bring|take|grab|get|pop|put|stick)\b.*)$"
)


# session 36 (12s): 'between' places the request between two steps ("Order's up so in between,
# give Bob the chips": between what?): the statement is kept, so the request is not read alone
# ('meanwhile', 'in the meantime' are while the statement's matter goes on: read as before)
_ORDER_HELD36S = frozenset({"between"})
# session 36 (lead): a word that puts the request in an order ("Order's up so last, give Carol the
# apple. Then give Bob the chips." had read the apple first: 'last' went with the statement)
_ORDER_HELD36L = frozenset({"first", "last", "lastly", "next", "finally", "then", "after"})


def _counted_close33t(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12t): a closing sentence counting the hand-overs ('Four deliveries, what a
    display!') is a count check: taken off when what comes before it reads as exactly that many
    hand-overs, all asked ('and'); an exclamation after it ('what a <word>') names nothing. A
    count the request does not meet is left (and refused)."""
    m = _rx(
        r"(?<=[.!?])\s+(one|two|three|four|five|six) (?:deliveries|delivery|hand-?overs?|drops?|"
        r"jobs?|tasks?)(?: in all| in total)?(?:,\s*what an? ([a-z]+))?\s*[.!]*\s*$"
    ).search(text)
    if m is None or (m.group(2) and not _names_nothing(m.group(2), lexicon)):
        return text
    said = _handovers33t(text[: m.start()], lexicon)
    if said is None or len(said) != _COUNTS[m.group(1).lower()]:
        return text
    return text[: m.start()]


def _objects_first33t(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12t): the objects said first, then 'give P' ("Bottle or crisps, any one also
    can, give Bob."): 'Give P <the objects>' — a choice when 'or' joins them ('any one also
    can', 'either one', 'any one' after it say the choice again), all of them with 'and'. Only
    when the objects name objects alone and P one person ('Two items, both give Alice' stays
    refused: session 28's near form, a count is not one name)."""
    m = _rx(
        r"^(?P<objs>(?:the )?[a-z]+ (?:or|and) (?:the )?[a-z]+),\s*(?:(?:any one|either one|either)"
        r"(?: also can| is fine| will do)?,\s*)?give (?P<p>[a-z][\w ]*?)(?: lah| la| leh)?"
        r"\s*(?P<end>[.!]?)$"
    ).match(text)
    if m is None:
        return text
    objs = re.split(r" (?:or|and) ", m["objs"], flags=_F)
    if _only_person(m["p"], lexicon) and all(_only_kind(o, lexicon, "object") for o in objs):
        return f"Give {m['p']} {m['objs']}{m['end']}"
    return text


def _openers33t(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12t): words that open or pace a request and ask nothing, from a closed list:
    'Right, listen.' (a call for attention: 'Right.'), 'nothing fancy,' (the request is a plain
    one), 'Quick as you like,' / ', quick as you like' (soon: the cell acts now); and a run-on
    where the speaker's own plan follows a request with no stop ("Give Person B the bottle I'm
    just going to check the hammers …": a comma before "I'm going to / I'm off to / I'll be",
    when what is before it reads alone)."""
    out = _sub(r"^((?:right|ok|okay|now|so)),?\s+listen\s*[.!,]\s*", r"\1. ", text)
    out = _sub(r"^nothing (?:fancy|special|complicated|major),\s*", "", out)
    if not _LATER24.search(out):
        # (a time said with it is left: 'Quick as you like, later.' stays refused)
        out = _sub(r"(?:(?<=[.!]\s)|^)quick as you like\s*[,.!]\s*", "", out)
        out = _sub(r",\s*quick as you like(?=\s*[,.!]|$)", "", out)
    m = _rx(
        r"^([^,.;!?]+?) (i'm (?:just )?going to|i'm off to|i'll be|i am (?:just )?going to) "
    ).match(out)
    if m is not None and _reading(m.group(1), lexicon) is not None:
        out = f"{m.group(1)}, {out[m.start(2) :]}"
    return out


def _places_said33t(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12t): where an object is, said beside the request in words that name nothing
    of the scene: 'bring her the apple from the end', 'on the tray next to the films' (taken
    off: a place the scene has, 'next to the sink', is left and refused); 'not the big one on
    the workbench' where the big one starts on the workbench (where it lies, said to pick it
    out: taken off), and 'the other spanner, not the big one' of two spanners is 'the spanner,
    not the big one'; 'the small and medium boxes, the two little ones,' (the count said again:
    taken off when it counts the objects before it); 'The chips are (meant) for P, could you take
    them over' is 'could you take the chips over to P'."""

    def place(m: re.Match[str]) -> str:
        # only right after an object or a surface of the scene ('the alple from the end')
        if not _names(m.group(1), lexicon) or _names(m.group(2), lexicon):
            return m.group(0)
        if _LATER24.search(m.group(3)) or _KEEP_WORDS.search(m.group(3)):
            return m.group(0)
        return m.group(1)

    out = _sub(
        r"\b([a-z]+)(\s+(?:from|next to|beside) the ([a-z]+(?: [a-z]+)?))(?=\s*(?:[,.!?]|$))",
        place,
        text,
    )
    m = _rx(r"\bnot the ([a-z]+) one on (the [a-z ]+?)(?=\s*[,.!]?$)").search(out)
    if m is not None and _surface_only(m.group(2), lexicon):
        (where,) = _ids(m.group(2), lexicon, "surface")
        picked = [
            o.id
            for o in lexicon.scene.objects
            if any(m.group(1).lower() in a.lower().split() for a in o.aliases)
        ]
        if len(picked) == 1 and starting_on(set(picked), where, lexicon):
            out = out[: m.start()] + f"not the {m.group(1)} one" + out[m.end() :]
    m = _rx(r"\bthe other ([a-z]+),\s*not the ([a-z]+) one\b").search(out)
    if m is not None and len(_ids(f"the {m.group(1)}s", lexicon, "object")) == 2:
        out = f"{out[: m.start()]}the {m.group(1)}, not the {m.group(2)} one{out[m.end() :]}"
    m = _rx(r"^(the [a-z]+ and [a-z]+ [a-z]+s),\s*the (two|three) [a-z]+ ones,\s*").match(out)
    if m is not None and len(_ids(m.group(1), lexicon, "object")) == _COUNTS[m.group(2).lower()]:
        out = f"{m.group(1)} {out[m.end() :]}"

    def over(m: re.Match[str]) -> str:
        if not (_only_kind(m.group(1), lexicon, "object") and _only_person(m.group(2), lexicon)):
            return m.group(0)
        return f"{m.group(3)}{m.group(4)} {m.group(1).lower()} over to {m.group(2)}"

    return _sub(
        r"^(the [a-z ]+?) (?:is|are) (?:meant |supposed to be )?for ([a-z][\w ]*?),\s*((?:could|"
        r"can|would) you |please )?(take|bring|carry) (?:it|them) over\b",
        over,
        out,
    )


def _everything_bar33t(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12t): 'Everything (left) on the pitch bar the bottle and the cup heads to
    Person A!': 'heads (over) to' is 'goes to' (before a person or a surface of the scene), 'bar'
    after 'everything' is 'except', and where everything is ('(left) on the pitch') is taken off
    when it names nothing of the scene (a surface of the scene may narrow it: left)."""
    out = _sub(
        r"\b(?:heads|is headed|is heading) (?:over |straight )?to (?=[a-z][\w ]*?\s*[.!]?$)",
        "goes to ",
        text,
    )
    m = _rx(r"^everything(?: left)?(?: (?:on|in|at) (the [a-z]+))? (?:bar|except) ").match(out)
    if m is None or (m.group(1) and not _names_nothing(m.group(1), lexicon)):
        return out if out != text and _reading(out, lexicon) is not None else text
    return f"Everything except {out[m.end() :]}"


def _formal33t(text: str, lexicon: Lexicon) -> str:
    """Session 33 (12t): formal and hesitant wrappers from a closed list: '(and) with (the
    greatest | all due) respect,' opening the request; 'no further questions' closing it (a
    closer of the courtroom: no correction); a frame begun and given up for another, 'is it okay
    if, sorry, could you …' ('could you …')."""
    out = _sub(
        r"(^|,\s*)(?:and )?with (?:the (?:greatest|utmost|deepest) |all (?:due )?)respect,\s*",
        r"\1",
        text,
    )
    out = _sub(r"(?<=[.!]\s)(thank you|thanks),\s*no further questions(?=\s*[.!]?$)", r"\1", out)
    return _sub(
        r"\b(?:is it (?:okay|ok|alright|all right)|would it be (?:okay|ok|alright|possible)) if,\s*"
        r"(?:(?:sorry|um|er|erm),\s*)*(?=(?:could|can|would|will) you\b)",
        "",
        out,
    )


# -- session 34 (12t): blind17, blind19, blind20, blind23, causes18 and causes15's kinds ---------


def _counted_those34t(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12t): a count after the demonstrative 'those' is the count with 'the': 'Those
    three things that aren't the bottle, …' is 'The three things that aren't the bottle, …'.
    Only before a plural that names objects of the scene; the count is checked as for 'the three
    things' (a count the scene does not meet is refused). 'Those two mugs want to go on …' is
    12r's `_counted_want34r` (left to it). 'Drop all three of the pens into the box' is 'Put the
    three pens into the box' ('drop' before a place is a placement; 'drop all' alone drops the
    running tasks)."""

    def the(m: re.Match[str]) -> str:
        said = f"the {m['n']} {m['kind']}"
        if not _ids(f"the {m['kind']}", lexicon, "object"):
            return m.group(0)
        return said.capitalize() if m.group(0)[:1].isupper() else said

    out = _sub(
        r"\bthose (?P<n>two|three|four|five|six) (?P<kind>[a-z]+s)\b(?! (?:want|need)s? to\b)",
        the,
        text,
    )
    m = _rx(
        r"^drop all (?P<n>two|three|four|five|six) of the (?P<kind>[a-z]+s) (?=(?:into|onto|in|on) "
        r"the [a-z]+)"
    ).match(out)
    if m is not None and _ids(f"the {m['kind']}", lexicon, "object"):
        out = f"Put the {m['n']} {m['kind']} {out[m.end() :]}"
    return out


def _objects_said34t(text: str, lexicon: Lexicon) -> str:
    """Session 34 (12t): a last sentence naming only objects ('Sorry, the bottle and the
    chips.', 'I mean the bottle and the chips.') after a request that reads: taken off when it
    names exactly the objects that request hands over or places (it says them again); any other
    objects (a correction), a person or a place in it is left and refused."""
    m = _rx(
        r"(?<=[.!?])\s+(?:(?:sorry|i mean|that is|so|yes|yeah)\s*,?\s+)?(?P<objs>(?:the )?[a-z]+"
        r"(?:(?:,\s*| and )(?:the )?[a-z]+)*)\s*[.!]?$"
    ).search(text)
    if m is None:
        return text
    before = text[: m.start()]
    objs = re.split(r",\s*| and ", m["objs"], flags=_F)
    named: set[str] = set()
    for o in objs:
        if not _only_kind(o, lexicon, "object"):
            return text
        named |= _ids(o, lexicon, "object")
    if len(named) != len(objs):
        return text
    # (session 53, 12p: the request read only where the sentence after it names objects only,
    # each once: the same answer, without a read of the request wherever it does not)
    said = _tasks_of(before, lexicon)
    if not said or named != {obj for _, obj, _ in said}:
        return text
    return before
