"""The normaliser's rewrites of session 39, engineer 12 (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _ids, _names, _objects_only, _only_person, _reasons21
from hltl.grounding._normalise2 import _things31
from hltl.grounding._normalise4 import _WANT_FRAME37, _fit36
from hltl.grounding._rewrites38 import _JOINS38, _inert38
from hltl.grounding.lexicon import VERBS, Lexicon

# -- session 39 (engineer 12): blind37's refusals by kind in the sections of politeness, wants,
# pronouns and ellipsis, splits and run-ons, lower case, typos and questions. As session 38's:
# each rule a closed pattern checked against the scene, the rest of the sentence read by the same
# grammar; a closing remark beside the request is engineer 12s's (CONTRACTS.md).

# -- wants said by an idiom before 'a' / 'an' / 'some' and a name of the scene's objects ("Person
# A could murder an apple", "Bob could kill for some chips", "Zoe has her heart set on a ruler",
# "Noah's put his name down for the globe"): the idiom is 'wants'
_WANT_IDIOM39 = re.compile(
    r"(?:\s+could (?:really |happily |easily |just |so )?(?:murder|kill for)|(?:\s+has|'s)(?: got)?"
    r" (?:his|her|their) hearts? (?:set|fixed) on|(?:\s+has|'s)? put (?:his|her|their) names? "
    r"down for)(?= (?P<det>a|an|some|the|that|this|those|these) (?P<x>[a-z]+(?: [a-z]+)?)\b)",
    _F,
)


def _want_idioms39(text: str, lexicon: Lexicon) -> str:
    """Session 39: the want idioms above said 'wants' when one person is said before them in
    their clause and what follows them (up to a mark or 'and') is objects of the scene only
    (a drink, a bite: session 30's states, left to them), and no her / him / them after it may
    hand that person something else (as session 33's _idioms33)."""
    for m in list(_WANT_IDIOM39.finditer(text))[::-1]:
        before = re.split(r"[,.;!?]\s*|\s+(?:and|but|so)\s+", text[: m.start()])[-1]
        what = re.split(r"[,.;!?]|\s+(?:and|but|so|while|after|since)\s+", text[m.end() :])[0]
        # session 40 (12): when, said after the object ("could really murder that bottle right
        # now"), is no part of it
        what = re.sub(r"\s+(?:right now|just now|now|at the moment|this minute)\s*$", "", what)
        if not _only_person(before, lexicon) or not _things31(what, lexicon):
            continue
        if re.search(r"\b(?:her|him|them)\b", text[m.end() :], _F):
            continue  # "Bob has his heart set on the crisps, hand him the cup" (as _idioms33)
        text = text[: m.start()] + " wants" + text[m.end() :]
    return text


# "Carol's after a brew, so …", "Tom is after a snack": a want of a kind the scene has no name
# for, the person's state (session 30's 'could murder a drink' is 'is thirsty')
_AFTER_KIND39 = re.compile(
    r"(?:\s+is|'s) (?:after|wanting|on the lookout for) (?:a|an|some) (?:(?P<drink>drink|brew|"
    r"cuppa|cup of tea|coffee|cold drink|drop of something)|(?P<food>snack|bite|nibble|bite to "
    r"eat|sandwich|sarnie|butty))\b",
    _F,
)


def _after_kind39(text: str, lexicon: Lexicon) -> str:
    """Session 39: 'P is after a brew' (above) is 'P is thirsty' ('a snack': hungry), when the
    words said for it name nothing of the scene and one person is said before it."""
    for m in list(_AFTER_KIND39.finditer(text))[::-1]:
        said = m[0].split()[-1]
        if _names(said, lexicon):
            continue  # a scene with a coffee: what is wanted is named
        before = re.split(r"[,.;!?]\s*|\s+(?:and|but|so)\s+", text[: m.start()])[-1]
        if not _only_person(before, lexicon):
            continue
        pid = next(iter(_ids(before, lexicon, "human")))
        after = text[m.end() :]
        prons = re.findall(r"\b(?:he|him|she|her|they|them)\b", after, _F)
        if not any(_fit36(pid, p, lexicon) for p in prons) and pid not in _ids(after, lexicon):
            continue  # "Hello, Alice is after a drink. Give Bob the cup.": not said of her want
        state = "thirsty" if m["drink"] else "hungry"
        text = text[: m.start()] + f" is {state}" + text[m.end() :]
    return text


# "Person A needs a drink, and the bottle's the only one going": the one thing of the kind there
# is, so it is what the person needs
_ONLY_ONE39 = re.compile(
    r"^(?P<p>[A-Za-z][\w ]*?) (?:needs|wants|could do with|could use|is after|'s after|fancies) "
    r"(?:a|an|some) [a-z]+,?\s+(?:and|but|so)?\s*(?P<x>(?:the|that|this) [a-z]+(?: [a-z]+)?)"
    r"(?:'s| is) the only (?:one|thing|drink|snack|one of those|one we've got)(?: (?:going|left|"
    r"there is|we've got|we have|to hand|around|about))?(?P<end>\s*[.!]?)\s*$",
    _F,
)


def _only_one39(text: str, lexicon: Lexicon) -> str:
    """Session 39: 'P needs a <kind>, and the X's the only one going' (above) is 'P needs the X'
    (P one person, X objects of the scene only)."""
    if "only" not in text.lower():
        return text
    m = _ONLY_ONE39.match(text)
    if m is None or not _only_person(m["p"], lexicon) or not _things31(m["x"], lexicon):
        return text
    return f"{m['p']} needs {m['x']}{m['end'].strip()}"


# -- courtesy
# "Thanks, pet, could …", "Cheers, pet, and could …": thanks and a word of address opening a
# request
_THANKS_ADDRESS39 = re.compile(
    r"^(?:ta|thanks|thank you|cheers)\s*,?\s+(?:pet|petal|love|hen|duck|chuck|flower|pal|mate|"
    r"lad|lass|bonny lad|bonny lass|sunshine|dear|darling|sweetheart|me duck|my love)\s*,\s*"
    r"(?:and\s+)?(?=\S)",
    _F,
)


def _courtesy39(text: str, lexicon: Lexicon) -> str:
    """Session 39: thanks and a word of address (above) opening a request, taken off when what
    is left names something."""
    m = _THANKS_ADDRESS39.match(text)
    if m is None:
        return text
    rest = text[m.end() :]
    if not _names(rest, lexicon):
        return text
    return rest[0].upper() + rest[1:]


# -- questions: 'at all' in a question asking whether something can be done ("Is it at all
# possible to …", "Is it at all feasible to …")
_AT_ALL39 = re.compile(
    r"^(?P<q>is it|would it be|could it be|will it be) at all (?=possible\b)", _F
)


def _at_all39(text: str, _lexicon: Lexicon) -> str:
    """Session 39: 'at all' taken out of 'Is it at all possible to …' (the question is the
    same)."""
    return _AT_ALL39.sub(lambda m: f"{m['q']} ", text) if " at all " in text.lower() else text


# -- an object 'is to' go somewhere, said with "'s": "The blue mug's to go on the counter", "The
# cup's to be given to Bob"
_IS_TO39 = re.compile(r"(?P<x>\b[a-z]+)'s to (?=(?:go|be|end up|sit|stay|get)\b)", _F)


def _is_to39(text: str, lexicon: Lexicon) -> str:
    """Session 39: "X's to go …" is 'X is to go …' when X names something of the scene."""
    if "'s to " not in text.lower():
        return text
    return _IS_TO39.sub(
        lambda m: f"{m['x']} is to " if _names(m["x"], lexicon) else m[0],
        text,
    )


# -- order: 'start off with' / 'begin out with' (start with; 'kick off with' is session 35's); "so
# sort him out first" after a want of one person (serve them what they want); "Once both are
# sorted," / "once shes sorted"
_START_OFF39 = re.compile(r"^(?:start|begin) (?:off|out) (?=with\b)", _F)
_SORT_OUT39 = re.compile(
    r"^(?P<p>[A-Za-z][\w ]*?)(?:'s| is) (?:after|wanting|waiting for|waiting on) (?P<x>(?:the|"
    r"that|this) [a-z]+(?: [a-z]+)?),\s*so (?:sort (?P<p1>him|her) out|see to (?P<p2>him|her))"
    r"(?P<first> first)?(?=\s*(?:[.;!]|$))",
    _F,
)
_ONCE_SORTED39 = re.compile(
    r"\bonce (?:(?P<both>(?:both|both of them|they)(?: are|'re| have been)?|theyre)|"
    r"(?P<pron>he|she)(?:'s|s| is| has been)) (?:sorted|sorted out|seen to|served|looked after|"
    r"done|taken care of|dealt with)\b",
    _F,
)


def _order39(text: str, lexicon: Lexicon) -> str:
    """Session 39: 'Start off with' opening said 'Start with'; "P's after X, so sort him out
    (first)" said "P's after X, so give it to him (first)" (P one person the pronoun may be, X
    objects of the scene only); 'once both are sorted' / 'once she's sorted' (the task before
    done) said 'once that's done' when something is asked before it: of one person the pronoun
    may be, or of two tasks at least ('both')."""
    text = _START_OFF39.sub("Start ", text)
    m = _SORT_OUT39.match(text)
    if m is not None and _only_person(m["p"], lexicon) and _things31(m["x"], lexicon):
        pron = m["p1"] or m["p2"]
        pid = next(iter(_ids(m["p"], lexicon, "human")))
        if _fit36(pid, pron, lexicon):
            text = f"{text[: m.end('x')]}, so give it to {pron}{m['first'] or ''}{text[m.end() :]}"
    m = _ONCE_SORTED39.search(text)
    if m is not None:
        before = text[: m.start()]
        people = _ids(before, lexicon, "human")
        if not _ids(before, lexicon, "object"):
            return text
        if m["pron"] is not None:
            if len(people) != 1 or not _fit36(next(iter(people)), m["pron"], lexicon):
                return text
        elif len(_ids(before, lexicon, "object")) < 2:
            return text
        text = f"{before}once that's done{text[m.end() :]}"
    return text


# -- pronouns and ellipsis
# "As for Person A, the cup", "As for Mr Novak, he's had his eye on the lemon": the person said
# first, then what is for them
_AS_FOR39 = re.compile(
    r"(?:^|(?<=[.;!?]\s))(?P<and>and )?as (?:for|to|regards) (?P<p>[A-Za-z][\w ]*?),\s*"
    r"(?:(?P<pron>he|she)(?=(?:'s|'ll|'d| is| has| wants| needs| would| can| could| will| "
    r"should| gets)\b)|(?P<v>give|hand|pass|bring) (?P<obj>him|her)\b|"
    r"(?=(?:the|that|this|those|these) ))",
    _F,
)
# "The crisps? Alice's.", "The bottle? That's Bob's.": whose each thing is, said as an answer
_WHOSE39 = re.compile(
    r"(?P<x>(?:^|(?<=[.;!?]\s))(?:[Tt]he|[Tt]hat|[Tt]his|[Tt]hose|[Tt]hese) [a-z]+(?: [a-z]+)?)"
    r"\?\s+(?:[Tt]hat's |[Tt]hat is |[Ii]t's |[Ii]t is |[Tt]hose are |[Tt]hese are |[Tt]hey're |"
    r"[Tt]hey are )?(?P<p>[A-Z][\w ]*?)'s(?=\s*(?:[.;!,]|$))",
)
# "The bottle's Person A's, if you would": whose it is, said as a request by the courtesy after it
_WHOSE_PLEASE39 = re.compile(
    r"^(?P<x>(?:[Tt]he|[Tt]hat|[Tt]his) [a-z]+(?: [a-z]+)?)(?:'s| is) (?P<p>[A-Z][\w ]*?)'s,"
    r"\s*(?P<c>if you (?:would|could|will|please|don't mind|wouldn't mind)|please)\b",
)


def _pronouns39(text: str, lexicon: Lexicon) -> str:
    """Session 39: 'As for P, he …' said 'P …' and 'As for P, the X' said 'P, the X' (P one
    person the pronoun may be); 'The X? P's.' and 'The X? That's P's.' said 'The X to P.' (X
    objects of the scene only, P one person); "The X's P's, if you would" said 'The X to P, if
    you would' (the courtesy makes whose it is a request to hand it over)."""
    low = text.lower()
    if "as for " in low or "as to " in low or "as regards " in low:
        m = _AS_FOR39.search(text)
        if m is not None and _only_person(m["p"], lexicon):
            pid = next(iter(_ids(m["p"], lexicon, "human")))
            name = m["p"][0].upper() + m["p"][1:]
            head = text[: m.start()] + (m["and"] or "")
            said = m["pron"] or m["obj"]
            if said is None:
                text = f"{head}{name}, {text[m.end() :]}"
            elif _fit36(pid, said, lexicon):
                # session 41: 'give him' after the topic: 'give <P>'; 'he'll' kept as 'P will'
                name = f"{m['v']} {name}" if m["v"] else name
                rest = text[m.end() :]
                if m["pron"] and rest.startswith("'ll"):
                    rest = " will" + rest[3:]
                text = f"{head}{name}{rest}"
    if "?" in text:

        def answered(m: re.Match[str]) -> str:
            if _objects_only(m["x"], lexicon) and _only_person(m["p"], lexicon):
                return f"{m['x']} to {m['p']}"
            return m[0]

        text = _WHOSE39.sub(answered, text)
    m = _WHOSE_PLEASE39.match(text)
    if m is not None and _objects_only(m["x"], lexicon) and _only_person(m["p"], lexicon):
        text = f"{m['x']} to {m['p']}, {text[m.start('c') :]}"
    return text


# -- lower case: a person's name with 's' run on, its apostrophe left out ("toms after the
# gloves", "priyas back"), in a text that writes no apostrophe
_NAME_S39 = re.compile(r"\b(?P<n>[a-z]{2,})s\b(?= [a-z])")


def _name_s39(text: str, lexicon: Lexicon) -> str:
    """Session 39: "<name>s" is "<name>'s" (is, has, or whose) where the name is one person's of
    the scene and the word with 's' names nothing nor is a verb of the grammar, in a text written
    in lower case without apostrophes."""
    if "'" in text or "’" in text or text != text.lower():
        return text

    def mended(m: re.Match[str]) -> str:
        word = m[0]
        if word in VERBS or not _only_person(m["n"], lexicon):
            return word
        if word in {a.lower() for h in lexicon.scene.humans for a in (h.name, *h.aliases)}:
            return word  # session 41: a name in its own right ('waitress', not 'waitres' + s)
        if not _ids(word, lexicon) <= _ids(m["n"], lexicon, "human"):
            return word  # a name of its own ('chips'), or of someone else
        return f"{m['n']}'s"

    return _NAME_S39.sub(mended, text)


# -- an 'after' closing a want that says what the person has been doing, not when to act: 'after
# all that hay bale stacking', 'after a go on the coconut shy' (session 38 took 'after <doing>'
# and 'after the <race>')
_AFTER_ALL39 = re.compile(
    r"\s+after (?:all (?:that|this|the|those)|(?:a|another|his|her|their) (?:go|turn|spin|ride|"
    r"stint|round) (?:on|at|in) the) (?P<what>[a-z-]+(?: [a-z-]+){0,3})(?=\s*(?:[,.;!?]|$))|"
    # "Bob's dying for a drink after the raft race, …": session 38's races, after a want of a kind
    r"\s+after the (?P<race>(?:[a-z]+-)*[a-z]+(?: [a-z]+)? (?:race|relay|marathon|tournament|"
    r"contest|competition|heats|final|derby|regatta|gala|triathlon|fun run|sports day))"
    r"(?=\s*(?:[,.;!?]|$))",
    _F,
)
_WANTED39 = re.compile(
    r"\b(?:wants|needs|fancies|could use|could do with|would love|would like|is after|'s after|"
    r"could murder|asking for|asked for|been after|on about|(?:is|'s) (?:desperate|gasping|dying|"
    r"parched|gagging|thirsty|hungry|starving|famished|peckish) for|craving|(?:is|'s) (?:thirsty|"
    r"hungry|starving|parched|famished|peckish|knackered|shattered|exhausted|worn out))\b",
    _F,
)


def _after_all39(text: str, lexicon: Lexicon) -> str:
    """Session 39: 'after all that <doing>' and 'after a go on the <thing>' (above) taken off a
    want or a state of one person in the same clause (no surface in it), its words naming nothing
    and asking nothing: what tired them, said of the past ('after all that' cannot say when to
    act)."""
    if " after " not in text.lower():
        return text
    for m in _AFTER_ALL39.finditer(text):
        # what was done said as a noun ('all that hay bale stacking', 'a go on the slide'): no
        # word of it is a verb of the grammar
        what = " ".join("x" if w.lower() in VERBS else w for w in (m["what"] or m["race"]).split())
        if not _inert38(what, lexicon):
            continue
        before = re.split(r"[.;!?]\s+|,\s*", text[: m.start()])[-1]
        if len(_ids(before, lexicon, "human")) != 1 or not _WANTED39.search(before):
            continue
        if _ids(before, lexicon, "surface"):
            continue
        return text[: m.start()] + text[m.end() :]
    return text


# "… since she got in from the duck race", "… since he came back": how long the want has lasted,
# said by the person's coming in
_SINCE_CAME39 = re.compile(
    r",?\s+(?:ever )?since (?P<pron>he|she|they) (?:got|came|arrived|walked|wandered|rolled) "
    r"(?:in|back|here|home|over|round)(?: (?:from|off) (?P<what>(?:the|his|her|their|a|an) "
    r"[a-z-]+(?: [a-z-]+){0,3}))?(?=\s*(?:[,.;!?]|$))",
    _F,
)


def _since_came39(text: str, lexicon: Lexicon) -> str:
    """Session 39: 'since she got in (from X)' (above) taken off a want of one person the pronoun
    may be ('they' always), in the same clause with an object and no surface; X naming nothing
    and asking nothing."""
    if "since" not in text.lower():
        return text
    m = _SINCE_CAME39.search(text)
    if m is None or (m["what"] is not None and not _inert38(m["what"], lexicon)):
        return text
    before = re.split(r"[.;!?]\s+|,\s*", text[: m.start()])[-1]
    people = _ids(before, lexicon, "human")
    if len(people) != 1 or not _WANTED39.search(before) or not _ids(before, lexicon, "object"):
        return text
    if _ids(before, lexicon, "surface"):
        return text
    if m["pron"].lower() != "they" and not _fit36(next(iter(people)), m["pron"], lexicon):
        return text
    return text[: m.start()] + text[m.end() :]


# -- a text written without punctuation, in lower case: the marks the writer left out put back
# before a remark run on after the request (he's / she's / we're / I'm, a courtesy word before it
# or not: "salt for mr novak please hes at table six", "stick the bottle on the shelf please were
# off to the fair") and before a clause said again without its verb ("person a gets the apple for
# her lunch person b the chips"), so that the rules for remarks and gapped clauses see them
_REMARK_START39 = re.compile(
    r"(?<=[a-z])\s+(?:(?P<c>please|cheers|thanks|thx|ta)\s+)?(?P<s>(?P<pron>he|she)(?:s|'s| is| "
    r"has)|(?P<we>we're|were|we are|we've|weve|i'm|im|i am|i've|ive))\s+(?=[a-z])"
)
# a number after a word for a place that numbers its spots is a label, not a count
_LABEL39 = re.compile(
    r"\b(?:table|bed|room|seat|bay|booth|desk|gate|platform|pitch|stall|cubicle|ward|aisle) "
    r"(?:[0-9]+|one|two|three|four|five|six|seven|eight|nine|ten|eleven|twelve)\b"
)
# "… please priya is tired of hunting for it": a remark whose subject is a person of the scene
_NAMED_REMARK39 = re.compile(
    r"(?<=[a-z])\s+(?:(?:please|cheers|thanks|thx|ta)\s+)?(?P<n>[a-z]+) (?P<v>is|was|has) (?=[a-z])"
)
_GAPPED39 = re.compile(
    r"(?<=[a-z])\s+(?=(?P<rest>(?P<p>[a-z]+(?: [a-z]+)?) (?:the|his|her) [a-z]))"
)


def _run_on39(text: str, lexicon: Lexicon) -> str:
    """Session 39: in a text with no mark at all, in lower case: ', ' put before a clause said
    again without its verb after 'P gets X …' (the word before it no verb, no joining word, the
    clause a person of the scene and objects only), and before a remark (above) that closes the
    text naming nothing and asking nothing but its own pronouns, 'all day' and a numbered place
    ('table six'); a he / she remark only where the person of the clause before it may be the
    pronoun. The courtesy word before a remark goes (as session 38's _run_on38)."""
    if re.search(r"[,;:.!?]", text) or text != text.lower():
        return text
    out = text
    if re.match(r"^[a-z]+(?: [a-z]+)? (?:gets|has|can have|wants|needs) (?:the|his|her) ", out):
        for g in _GAPPED39.finditer(out):
            words = out[: g.start()].split()
            if words[-1] in _JOINS38 or words[-1] in VERBS or words[-1] in ("to", "for", "the"):
                continue
            clause = re.split(r"\s+(?:he|she)(?:s|'s| is)\s", g["rest"])[0]
            if not _only_person(g["p"], lexicon):
                continue
            named = _ids(clause, lexicon)
            if not named - _ids(g["p"], lexicon) <= _ids(clause, lexicon, "object"):
                continue
            if not _ids(out[: g.start()], lexicon, "object"):
                continue
            out = f"{out[: g.start()]}, {out[g.end() :]}"
            break
    n = _NAMED_REMARK39.search(out)
    if n is not None and _only_person(n["n"], lexicon):
        before = out[: n.start()]
        if _ids(before, lexicon, "object") and not _ids(before, lexicon, "human"):
            said = f"{before}, {n['n']} {n['v']} {out[n.end() :]}"
            plain = _it_remark39(said, lexicon)
            if plain != said:
                return plain  # "stapler back on the desk please priya is tired of hunting for it"
    m = _REMARK_START39.search(out)
    if m is not None:
        before, after = out[: m.start()], out[m.end() :]
        said = _LABEL39.sub("x", after)
        said = re.sub(
            r"\b(?:he|she|hes|shes|his|her|we|were|our|i|im|my|all (?:day|morning|afternoon|"
            r"evening|night|week))\b|\bonly just\b",
            " ",
            said,
        )
        words = before.split()
        if (
            words
            and words[-1] not in _JOINS38
            and words[-1] not in VERBS
            and _ids(before, lexicon, "object")
            and not _names(after, lexicon)
            and (not said.split() or _inert38(said, lexicon))
        ):
            # 'were' / 'we are' may be said of what was just named ("… and the crisps were
            # stale"): the speaker's only after a courtesy word
            ok = m["c"] is not None or m["s"] not in ("were", "we are")
            if m["pron"] is not None:
                people = _ids(before.split(",")[-1], lexicon, "human")
                ok = len(people) == 1 and _fit36(next(iter(people)), m["pron"], lexicon)
            if ok:
                subj = "we're" if m["s"] in ("were", "we're") else m["s"]
                after = re.sub(r"\bonly just\b", "just", after)
                # session 21's reasons (run before this) asked again of the text with its comma
                out = _reasons21(f"{before}, {subj} {after}", lexicon)
    return out


# "Bob's been stood there for ages after his pickled egg stall.": how long the person has waited,
# and after what of theirs, a sentence of its own before the request
_WAITED_AFTER39 = re.compile(
    r"^(?P<s>(?P<p>[A-Z][\w ]*?)(?:'s| has| is)(?: been)? (?:stood|standing|waiting|sat|sitting|"
    r"queuing|queueing|hanging about|hanging around)(?: there| here| about| around)?(?: for "
    r"(?:ages|a while|hours|an age|a good while|a bit))?) after (?P<pron>his|her|their) "
    r"(?P<what>[a-z-]+(?: [a-z-]+){0,3})(?=[.!]\s+\S)",
    _F,
)
# "Can P have X, do you reckon, she wants it for …?": the hearer asked to judge, between the
# question and a remark that closes it
_TAG_BETWEEN39 = re.compile(
    r",\s*(?:do you|d'you|d'ya) (?:think|reckon|suppose),\s*(?=(?:he|she|they)(?:'s| is| wants| "
    r"needs| has)\b)",
    _F,
)


def _questions39(text: str, lexicon: Lexicon) -> str:
    """Session 39: 'after his <doing>' taken off a sentence saying how long one person has waited
    (above) when the doing names nothing and asks nothing and the pronoun may be them;
    ', do you reckon,' between a question and a remark said ', ' (session 38's closing tag)."""
    m = _WAITED_AFTER39.match(text)
    if m is not None and _only_person(m["p"], lexicon) and _inert38(m["what"], lexicon):
        pid = next(iter(_ids(m["p"], lexicon, "human")))
        if m["pron"].lower() == "their" or _fit36(pid, m["pron"], lexicon):
            text = m["s"] + text[m.end() :]
    if "?" in text:
        text = _TAG_BETWEEN39.sub(", ", text)
    return text


# -- a remark that says 'it' of the one object the request names, after it in its sentence: "The
# bottle to Bob, he won it on the hook a duck", "… his magazine, he does the puzzles in it every
# afternoon; …", "Sponge in the sink please, Omar's got paint all over it": what the person did
# with it, or what is on it
_IT_REMARK39 = re.compile(
    r",\s*(?P<part>(?P<subj>he|she|[A-Za-z]+)(?:'s|s)?\b[^,;.!?]*?\b(?:in|on|over|for|at|off|"
    r"about|into|onto|from|of|won|"
    r"found|made|bought) it\b[^,;.!?]*?)(?=\s*(?:[;.!?]|$))",
    _F,
)
_WAITING39 = re.compile(r"\bwaiting (?:for|on)\b", _F)
_IT_MASK39 = re.compile(
    r"\b(?:it|he|she|his|her|all over|every (?:day|morning|afternoon|evening|night|week|time)|"
    r"'s got|has got|got|'s|has|does|did|was|is|had)\b",
    _F,
)


def _it_remark39(text: str, lexicon: Lexicon) -> str:
    """Session 39: a comma part closing a sentence (or before its ';') whose subject is he / she
    or one person of the scene and which says 'it' after a preposition ('in it', 'all over it',
    'for it') or a verb of getting ('won it', 'made it'), taken off when the sentence before it
    names exactly one object (what 'it' is), the rest of the part names nothing and asks nothing
    (a habit, 'every afternoon', and 'all over' apart) and no want is said in it; he / she must
    be able to be the one person the sentence names, and a person named as the subject is only
    taken off a request naming no person (a placement: "Priya is tired of hunting for it" after
    "Stapler back on the desk")."""
    if " it" not in text.lower():
        return text
    for m in _IT_REMARK39.finditer(text):
        part = m["part"]
        if _WANTED39.search(part) or _WANT_FRAME37.search(part) or _WAITING39.search(part):
            continue
        said = _IT_MASK39.sub(" ", part[len(m["subj"]) :])
        if said.split() and not _inert38(said, lexicon):
            continue
        sentence = re.split(r"[.;!?]\s+", text[: m.start()])[-1]
        if len(_ids(sentence, lexicon, "object")) != 1:
            continue
        people = _ids(sentence, lexicon, "human")
        subj = m["subj"].lower()
        if subj in ("he", "she"):
            if len(people) != 1 or not _fit36(next(iter(people)), subj, lexicon):
                continue
        elif people or not _only_person(m["subj"], lexicon):
            continue
        return text[: m.start()] + text[m.end() :]
    return text


# -- refusals that name their readings (checks offline.py makes before reading)
# "Person B wants the cup or the apple, I can't remember which": a choice the speaker does not
# know the answer to, not one left to the robot
_DOUBT_WHICH39 = re.compile(
    r"(?P<a>\b(?:the|a|an) [a-z]+(?: [a-z]+)?) or "
    r"(?P<b>(?:the|a|an) [a-z]+(?: (?!but\b|and\b)[a-z]+)?)"
    r"(?:,|\.|;|\s*-)?\s*(?:but |and )?(?:I (?:can't|cannot|can not|don't|do not|didn't|"
    r"couldn't) (?:remember|recall|know|say)|I forget|I've forgotten|I'm not sure|not sure|no idea|"
    r"dunno|it(?:'s| has)? slipped my mind|it's gone (?:clean |right )?out of my head)"
    r"(?: now| exactly| offhand)? which\b",
    _F,
)


def doubt_which39(text: str, lexicon: Lexicon) -> None:
    """Session 39: a choice between two objects (or people) followed by the speaker saying they
    do not know which ('I can't remember which', 'not sure which') is no choice left to the
    robot: refused naming both readings (it had been refused on 'I', naming none)."""
    if "which" not in text.lower():
        return
    m = _DOUBT_WHICH39.search(text)
    if m is None:
        return
    a, b = _ids(m["a"], lexicon), _ids(m["b"], lexicon)
    if len(a) != 1 or len(b) != 1 or a == b:
        return
    (x,), (y,) = a, b
    raise GroundingError(
        f"{m[0]!r}: the speaker does not know which is meant, {m['a']} ({x}) or {m['b']} ({y}); "
        "say which"
    )


# "Person A asked for her usual": what the person usually has, which the scene does not say
_USUAL39 = re.compile(
    r"\b(?P<whose>his|her|their|[A-Za-z]+'s) (?:usual|regular|normal)(?: one)?"
    r"(?=\s*(?:,?\s*(?:please|thanks|ta|cheers))?\s*[.!?]?\s*$)",
    _F,
)


def usual39(text: str, lexicon: Lexicon) -> None:
    """Session 39: 'P asked for her usual' (what the person usually has) in a sentence that names
    one person and no object: the scene does not say what that is, so refused naming each object
    it could be (it had been refused on 'usual', naming none)."""
    if "usual" not in text.lower() and "regular" not in text.lower():
        return
    m = _USUAL39.search(text)
    if m is None:
        return
    before = text[: m.start()]
    if len(_ids(before, lexicon, "human")) != 1 or _ids(text, lexicon, "object"):
        return
    if _ids(text, lexicon, "surface"):
        return
    objects = ", ".join(
        f"the {o.aliases[0] if o.aliases else o.id} ({o.id})" for o in lexicon.scene.objects
    )
    raise GroundingError(
        f"{m[0]!r}: the scene does not say what that is; it could be any of {objects}: name it"
    )


_STEPS39: tuple[Callable[[str, Lexicon], str], ...] = (
    # first: the marks a text written without them leaves out, for the rules after it
    _run_on39,
    _questions39,
    _name_s39,
    _courtesy39,
    _at_all39,
    _is_to39,
    _want_idioms39,
    _after_all39,
    _since_came39,
    _after_kind39,
    _only_one39,
    _order39,
    _pronouns39,
    # last: 'it' in the remark is what the (rewritten) request names
    _it_remark39,
)
