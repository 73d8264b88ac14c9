"""The grounder's rules of session 51, engineer 12s (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _ids, _names, _names_nothing, _only_person, _reading
from hltl.grounding._normalise2 import _WHERE_AFTER28
from hltl.grounding._normalise4 import _fit36
from hltl.grounding._rewrites39 import _name_s39
from hltl.grounding._rewrites42s import _remark_only42s
from hltl.grounding._rewrites44r import _read_without44r
from hltl.grounding.lexicon import Lexicon
from hltl.grounding.tree import Node, tasks


def _plain51s(out: str, text: str, lexicon: Lexicon) -> str:
    """``out`` (a rewrite of ``text``) as the grammar reads it: itself when it reads without the
    normaliser, else the first of the normaliser's rewrites of it that does (the rewrites before
    this rule's step are not asked again of what it returns); ``text`` when ``out`` does not read
    at all."""
    if out == text or _reading(out, lexicon) is None:
        return text
    if _reading(out, lexicon, normalise=False) is not None:
        return out
    from hltl.grounding import normalise  # why: normalise imports this module

    for again in (normalise.rewritten19, normalise.canonical, normalise.canonical19):
        plain = again(out, lexicon)
        if plain != out and _reading(plain, lexicon, normalise=False) is not None:
            return plain
    return out


# -- session 51 (12s): a request put off until someone's word (12c's deferrals fuzz) ------------
#
# "Check with the deckhand first. An hour on the bongos has left Person A gasping for the
# bottle.", "Once the site boss says so, Alice mentioned the crisps; could you take them to her."
# (blind47, 12c's session-50 fuzz) read as the handover: the first sentence (a verb the grammar
# does not know) or clause (a name it does not know) was dropped as a remark. Either waits on
# someone's later word, which the robot does not hear (blind30's time rule): a reading of a text
# that says so is refused. The kinds: consulting someone before acting ('check / clear it /
# confirm with P', 'run it by / past P', 'ask P first / before …'), a time clause that waits on
# someone's say-so ('once / when / as soon as / until … P says so / gives the word / the nod /
# okays it / signs off'), and waiting for it ('wait for P's nod', 'get the go-ahead from P
# first'). Asked of the whole reading only (a check), so a refusal with its readings keeps them.
_WHO51S = r"[a-z][a-z'-]*(?: [a-z][a-z'-]*){0,3}?"
_WORD51S = (
    r"(?:word|nod|go-ahead|go ahead|green light|all-clear|all clear|signal|ok|okay|o\.k\.|"
    r"thumbs up|thumbs-up|say-so|say so|blessing)"
)
_SAID_SO51S = re.compile(
    # consulting someone before acting
    rf"\b(?:(?:check|double-check|clear (?:it|that|this)|confirm|agree (?:it|that)|check (?:it|"
    rf"that|this))\s+with|run (?:it|that|this)\s+(?:by|past))\s+(?!you\b|yourself\b)"
    rf"(?P<who>{_WHO51S})(?=\s*(?:first|beforehand|before\b|[.,;:!?]|$|and\b|then\b))"
    rf"|\bask\s+(?!you\b|for\b|after\b|about\b|around\b)(?P<asked>{_WHO51S})\s+(?:first|"
    rf"beforehand|before (?:you|anything|doing|starting|going)|what|whether|if)\b"
    # a time clause waiting on someone's say-so
    rf"|\b(?:once|when|whenever|as soon as|soon as|after|until|till|not before|the moment|the "
    rf"minute|the second)\s+(?!you\b|i\b|we\b)(?P<sayer>{_WHO51S})\s+(?:says so|say so|said so"
    rf"|says go|says the word|has said so|gives (?:you |us |me )?(?:the |a |his |her |their )?"
    rf"{_WORD51S}|has given (?:you |us )?(?:the |a |his |her |their )?{_WORD51S}|okays|ok's|"
    rf"oks|signs (?:it |that )?off|has signed (?:it |that )?off|approves|has approved|agrees|"
    rf"nods|lets you know|tells you to|tells you it's)\b"
    # told to wait for it (or for anything: an outside event), or to get it first
    rf"|(?:^|[.!?;:,]\s*|\b(?:then|and|but|so|just|please|actually|first)\s+)(?:do |please |"
    rf"just )?(?:wait|hold off|hang on|hold on|hold fire)\s+(?:for|till|until)\s+(?!(?:a |one |"
    rf"just a )?(?:sec|secs|second|seconds|moment|mo|minute|tick|jiffy)\b)\S"
    rf"|\b(?:get|got|have|getting)\s+(?:the |a |an )?{_WORD51S}\s+from\s+(?P<giver>{_WHO51S})"
    rf"(?=\s*(?:first|beforehand|before\b|[.,;:!?]|$))"
    rf"|\b(?:get|got|getting)\s+(?!your\b|my\b)(?:{_WHO51S}'s|{_WHO51S}s') {_WORD51S}\s+"
    rf"(?:first|beforehand|before\b)"
    # opened by a preposition: 'Pending / Subject to / On / At / Upon / With(out) P's nod, …'
    rf"|\b(?:pending|subject to|on|upon|at|awaiting|after|following)\s+(?:the |a |an )?(?:"
    rf"{_WHO51S}'s |{_WHO51S}s' |my |our |his |her |their )?{_WORD51S}\b",
    _F,
)


# a time clause waiting on a person's return or their being done ("When Bob gets back the apple
# goes to him.", "As soon as Bob's done the apple goes to him.": said without the comma, 'Bob gets
# back the apple' had read as the handover; with it, it is refused as an event): the person is
# one of the scene, a he / she, or a role naming nothing of the scene ('the site boss')
_BACK51S = re.compile(
    r"\b(?:when|once|as soon as|soon as|the moment|the minute|until|till|not before)\s+"
    r"(?P<p>[a-z]+(?: [a-z]+)?)\s*(?:(?:gets|comes|'s|is|has got|has come|'s come) back|(?:'s|is|"
    r"has|'s been) (?:done|finished|free|ready|in|here|up|awake)|arrives|turns up|wakes up|gets in|"
    r"comes in|shows up|returns)\b"
    # "when she's done with it, the bottle": done with what the request hands over is an order
    r"(?! with (?:it|them|that|those|this|these|the)\b)",
    _F,
)


def _waits_on_person51s(text: str, lexicon: Lexicon) -> str | None:
    """The words of a time clause above whose person is one (or a role), else None."""
    m = _BACK51S.search(text)
    if m is None:
        return None
    p = m["p"].lower()
    if p not in ("he", "she") and not _only_person(m["p"], lexicon):
        words = p.split()
        if words[0] != "the" or len(words) != 2 or _ids(m["p"], lexicon):
            return None
    return m.group(0)


# a word one of the kinds above holds (the check's cheap test)
_CUES51S = (
    "check",
    "clear",
    "confirm",
    "agree",
    "run ",
    "ask",
    "say",
    "said",
    "give",
    "nod",
    "ok",
    "sign",
    "approv",
    "wait",
    "hold",
    "hang",
    "let",
    "tell",
    "word",
    "got",
    "get",
)


def _said_so51s(text: str, node: Node, lexicon: Lexicon) -> None:
    """Session 51 (12s): a reading of a text that waits on someone's later word (above) is
    refused."""
    del node
    low = text.lower()
    if any(
        w in low
        for w in (
            "back",
            "done",
            "finished",
            "free",
            "ready",
            "in",
            "here",
            "up",
            "awake",
            "arrives",
            "returns",
        )
    ):
        said = _waits_on_person51s(text, lexicon)
        if said is not None:
            raise GroundingError(
                f"{said!r} waits on something to happen, which the robot does not see: say what "
                "to do now, or ask when it has happened"
            )
    if not any(w in low for w in _CUES51S):
        return
    m = _SAID_SO51S.search(text)
    if m is None:
        return
    start = m.start() + len(m.group(0)) - len(m.group(0).lstrip(".!?;:, "))
    end = re.compile(r"[.!?;:,]|$").search(text, m.end() - 1)
    said = " ".join(text[start : end.start() if end else len(text)].split())
    raise GroundingError(
        f"{said!r} waits on someone's word or on something to happen, which the robot does not "
        "hear: say what to do now"
    )


# -- session 51 (12s): a later time said as a text would ('tmrw', 'tonite', 'l8r') -------------
#
# "apple for bob tmrw", "Give Bob the apple tmrw." read apple>B: the abbreviation, a word of no
# scene, was taken with the name before it and dropped. Said in full ('tomorrow', 'tonight',
# 'later on') the task is put off and refused (session 20's time rule): refused the same way.
_LATER_TEXTED51S = re.compile(
    r"\b(?:tmrw|tmw|tmr|tmrrw|tmrow|tmoro|tmorow|tmoz|tomoz|2moro|2morro|2morrow|2morow|tonite|"
    r"2nite|2night|l8r|l8er|l8ter)\b",
    _F,
)


def _later_texted51s(text: str, lexicon: Lexicon) -> None:
    """Session 51 (12s): a text's later time (above) is refused as the time in full is."""
    del lexicon
    low = text.lower()
    if not any(w in low for w in ("tm", "2m", "2n", "l8", "tonite", "tomoz")):
        return
    m = _LATER_TEXTED51S.search(text)
    if m is not None:
        raise GroundingError(
            f"{m.group(0)!r} (a later time) puts the task off: the cell acts now, so say the "
            "request when it is to be done"
        )


# -- session 51 (12s): negation and exclusion (blind49's) ----------------------------------------
#
# "Person A gets the chips, and not Person B, who's had his at the minigolf.": the person left
# out said after 'and not' / 'but not' (session 33's "…, not Person B" reads; 'and not' was asked
# to name objects): said ", not P", when P is one person of the scene and a stop, a comma or the
# end follows the name.
_AND_NOT_PERSON51S = re.compile(
    r",\s*(?:and|but) not (?P<p>(?:person|mr|mrs|ms|miss|dr|nurse) [a-z]+|[a-z]+)"
    r"(?=\s*(?:[,.;!]|$))",
    _F,
)


def _and_not_person51s(text: str, lexicon: Lexicon) -> str:
    """Session 51 (12s): ', and not P' said ', not P' (above)."""
    if " not " not in text.lower():
        return text
    m = _AND_NOT_PERSON51S.search(text)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    if _ids(m["p"], lexicon) <= _ids(text[: m.start()], lexicon, "human"):
        return text  # the person left out is the one who gets it: refused as before
    out = f"{text[: m.start()]}, not {m['p']}{text[m.end() :]}"
    return _plain51s(out, text, lexicon)


# "Forget the cup, it's only the apple Person B's after.": the cleft of the one wanted with
# 'only' (which says no more than the cleft: nothing else is wanted): said without it, as the
# older rules read "Forget the cup, it's the apple Person B's after."
_ONLY_CLEFT51S = re.compile(r"\bit(?P<be>'s| is) only (?=(?:the|a|an) [a-z])", _F)


def _only_cleft51s(text: str, lexicon: Lexicon) -> str:
    """Session 51 (12s): "it's only the X P's after" said "it's the X P's after"."""
    if "only" not in text.lower():
        return text
    out = _ONLY_CLEFT51S.sub(lambda m: f"it{m['be']} ", text)
    return _plain51s(out, text, lexicon)


# "Don't bother fetching the globe, Noah's after the ruler …": the thing not to fetch said before
# the request: said "Not the globe, <request>" (session 33's 'not X, Y'), when the thing is one
# of the scene and the request then reads without handing it over.
_DONT_BOTHER51S = re.compile(
    r"^(?:please\s+)?(?:don't|do not|no need to|you needn't|needn't) bother (?:fetching|getting|"
    r"bringing|with|taking|grabbing|moving|carrying) (?P<x>the [a-z]+(?: [a-z]+)?)\s*[,;]\s*"
    r"(?P<rest>\S.*)$",
    _F,
)


def _not_x_rest51s(m: re.Match[str] | None, text: str, lexicon: Lexicon) -> str | None:
    """The rewrite "Not <x>, <rest>" of ``m`` (a match of ``text`` with groups ``x`` and
    ``rest``) when ``x`` names one thing of the scene and nothing else and the rewrite reads
    without handing it over (session 44's `_read_without44r`); None otherwise (no match included).
    Shared by `_dont_bother51s` and session 52's `_dont_just52s`, which ask `_plain51s` and
    `_rewrites52s._plain52s` of it."""
    if m is None or len(_ids(m["x"], lexicon, "object")) != 1:
        return None
    if _ids(m["x"], lexicon) != _ids(m["x"], lexicon, "object"):
        return None
    out = f"Not {m['x']}, {m['rest']}"
    if _read_without44r(out, text, m["x"], lexicon) == text:
        return None
    return out


def _dont_bother51s(text: str, lexicon: Lexicon) -> str:
    """Session 51 (12s): "Don't bother fetching the X, <request>" said "Not the X, <request>"."""
    if "bother" not in text.lower():
        return text
    out = _not_x_rest51s(_DONT_BOTHER51S.match(text.strip()), text, lexicon)
    return text if out is None else _plain51s(out, text, lexicon)


# "Apart from the medium box, which stays put, the boxes go on the belt.": what the thing left
# out does, said of it in a relative clause ('which stays put / where it is / here'): it says no
# more than 'apart from' does: taken off.
_WHICH_STAYS51S = re.compile(
    r"(?P<ex>\b(?:apart from|except(?: for)?|bar|other than|besides|but) (?:the |that |this )?"
    r"[a-z]+(?: [a-z]+)?)\s*,\s*(?:which|that) (?:stays|is staying|can stay|will stay|should stay|"
    r"remains|stops|is stopping|can stop)(?: put| here| there| where it is| behind| alone| as it "
    r"is)?\s*(?=,)",
    _F,
)


def _which_stays51s(text: str, lexicon: Lexicon) -> str:
    """Session 51 (12s): ", which stays put" after a thing left out taken off (above)."""
    if "which" not in text.lower() and "that" not in text.lower():
        return text
    out = _WHICH_STAYS51S.sub(lambda m: m["ex"], text)
    return _plain51s(out, text, lexicon)


# "Don't hold the bottle back from Person A any longer.": not to keep a thing from a person is to
# give it to them: said "Give P the X", when P is one person and X names things of the scene.
_HOLD_BACK51S = re.compile(
    r"^(?P<lead>(?:please\s+)?)(?:don't|do not|stop|quit) (?:hold|holding|keep|keeping) "
    r"(?P<x>(?:the|that|those|this|these) [a-z]+(?: [a-z]+)?) (?:back )?from (?P<p>(?:person|mr|"
    r"mrs|ms|miss|dr|nurse) [a-z]+|[a-z]+)(?: (?:any longer|anymore|any more|now))?"
    r"(?P<end>\s*[.!]?)\s*$",
    _F,
)


def _hold_back51s(text: str, lexicon: Lexicon) -> str:
    """Session 51 (12s): "Don't hold the X back from P" said "Give P the X"."""
    if "from" not in text.lower():
        return text
    m = _HOLD_BACK51S.match(text.strip())
    if m is None or not _only_person(m["p"], lexicon):
        return text
    x = _ids(m["x"], lexicon)
    if not x or _ids(m["x"], lexicon, "object") != x:
        return text
    out = f"{m['lead']}Give {m['p']} {m['x']}{m['end'] or '.'}"
    return _plain51s(out, text, lexicon)


# "Priya'll take a pen, …": a person's 'will' run on as 'll ("Bob'll have the apple" reads; 'take'
# after it did not): said "Priya will take a pen", when the name is one person's of the scene.
_LL51S = re.compile(r"\b(?P<p>(?:person|mr|mrs|ms|miss|dr|nurse) [a-z]+|[a-z]+)'ll\b", _F)


def _ll_will51s(text: str, lexicon: Lexicon) -> str:
    """Session 51 (12s): "<person>'ll" said "<person> will"."""
    if "'ll" not in text.lower():
        return text
    if re.search(r"\b(?:either|other|whichever|one of|any)\b", text, flags=_F):
        return text  # a choice said with it is left to the older rules

    def said(m: re.Match[str]) -> str:
        return f"{m['p']} will" if _only_person(m["p"], lexicon) else m[0]

    out = _LL51S.sub(said, text)
    return _plain51s(out, text, lexicon)


# "Bob's not fussed about the bottle after the longsword class; he wants the crisps.": when the
# person stopped wanting the thing ('after / since the <occasion>') said inside the not-wanting
# clause the older rules read ("Bob's not fussed about the bottle; he wants the crisps."): taken
# off, when its words name nothing of the scene, want nothing and negate nothing.
_NOT_WANTED_WHEN51S = re.compile(
    r"(?P<head>(?:\bnot|n't|\bnever) [a-z' ]*?\b(?:about|for|on|of|with|at|near) (?:the|that|"
    r"those|this|these|any) [a-z]+(?: [a-z]+)?) (?P<mod>(?:after|since|following|from) (?:the|a|"
    r"an|his|her|their|that|this) [a-z' -]+?)(?=\s*[;,.])",
    _F,
)


def _not_wanted_when51s(text: str, lexicon: Lexicon) -> str:
    """Session 51 (12s): 'after the <occasion>' inside a not-wanting clause taken off (above)."""
    low = text.lower()
    if "not" not in low and "n't" not in low and "never" not in low:
        return text
    m = _NOT_WANTED_WHEN51S.search(text)
    if m is None or not _remark_only42s(re.sub(r"^\S+ ", "", m["mod"]), lexicon):
        return text
    if _ids(m["mod"], lexicon):
        return text
    return _plain51s(f"{text[: m.end('head')]}{text[m.end() :]}", text, lexicon)


# "Person A gets the bottle, Person B gets the chips, and the pair of them can get back to their
# warhammer game.": 'the pair of them' (session 41's 'both of them') as the subject of a closing
# remark: said 'they' ("…, and they can get back to their game" reads as the two requests).
_PAIR_CAN51S = re.compile(
    r"\b(?:the pair|both|the two|the both) of (?:them|'em)(?= (?:can|could|will|may|might|should"
    r"|'ll)\b)",
    _F,
)


def _pair_can51s(text: str, lexicon: Lexicon) -> str:
    """Session 51 (12s): 'the pair of them can …' said 'they can …' (above)."""
    if " of " not in text.lower():
        return text
    out = _PAIR_CAN51S.sub("they", text)
    node = _reading(out, lexicon) if out != text else None
    if node is None or len({t.target for t in tasks(node) if t.kind == "deliver"}) != 2:
        return text  # 'the pair of them' is the two the requests give to
    return _plain51s(out, text, lexicon)


# "Person B, being a nurseryman with simple tastes, wants …": a trade said with 'being' between
# commas after the person: said without it ("Person B, a nurseryman with simple tastes, wants …"
# reads), when the words name nothing of the scene.
_BEING_A51S = re.compile(r",\s*being (?P<a>an? [a-z][a-z' -]*?)\s*,", _F)


def _being_a51s(text: str, lexicon: Lexicon) -> str:
    """Session 51 (12s): ', being a <trade>,' said ', a <trade>,' (above)."""
    if "being" not in text.lower():
        return text
    m = _BEING_A51S.search(text)
    if m is None or _ids(m["a"], lexicon) or not _remark_only42s(m["a"], lexicon):
        return text
    return _plain51s(f"{text[: m.start()]}, {m['a']},{text[m.end() :]}", text, lexicon)


# "… wants nothing but the chips.": 'nothing but / except / other than the X' after a want: said
# 'just the X' (session 50's 'wants just the Z').
_NOTHING_BUT51S = re.compile(
    r"\b(?P<v>wants|needs|would like|'s after|is after|asked for|fancies) nothing (?:but|except|"
    r"other than|apart from|besides) (?P<x>(?:the|a|an) [a-z]+(?: [a-z]+)?)",
    _F,
)


def _nothing_but51s(text: str, lexicon: Lexicon) -> str:
    """Session 51 (12s): 'wants nothing but the X' said 'wants just the X' (above)."""
    if "nothing" not in text.lower():
        return text
    m = _NOTHING_BUT51S.search(text)
    if m is None or not re.fullmatch(r"\s*[.!]?\s*", text[m.end() :]):
        return text  # closing the text only ("…, and he's had them." is refused as before)
    x = _ids(m["x"], lexicon)
    if not x or _ids(m["x"], lexicon, "object") != x:
        return text
    out = f"{text[: m.start()]}{m['v']} just {m['x']}{text[m.end() :]}"
    return _plain51s(out, text, lexicon)


# "Not on the tray, the sponge, it'll drip; it goes in the sink.": why not there, said between
# the thing and where it goes ('it'll drip / fall / roll off'): taken off ("Not on the tray, the
# sponge; it goes in the sink." reads).
_ITLL_WHY51S = re.compile(
    r",\s*(?:it|they)(?:'ll| will) (?:drip|leak|spill|break|fall|fall off|roll|roll off|get wet|"
    r"get dirty|smash|tip over|melt|go soggy|get knocked|topple|slide off)(?: everywhere| off)?"
    r"\s*(?=[;,])",
    _F,
)


def _itll_why51s(text: str, lexicon: Lexicon) -> str:
    """Session 51 (12s): ", it'll drip" between the thing and where it goes taken off."""
    if "'ll" not in text.lower() and " will " not in text.lower():
        return text
    m = _ITLL_WHY51S.search(text)
    if m is None or not _ids(text[: m.start()], lexicon, "object"):
        return text
    return _plain51s(f"{text[: m.start()]}{text[m.end() :]}", text, lexicon)


# "Person A's allergic to apples, so give her the cup instead.": 'instead' after a reason that
# names the one thing the request replaces: said ", not the X" (which reads), when the reason
# names that one thing and at most the person, and the request then hands the X to no one.
_REASON_INSTEAD51S = re.compile(
    r"^(?P<reason>[^,;.!?]+?)\s*,?\s+so (?P<req>(?:give|hand|pass|bring|take|get) [^,;.!?]+?)"
    r"\s*,?\s*instead(?P<end>\s*[.!]?)\s*$",
    _F,
)


def _reason_instead51s(text: str, lexicon: Lexicon) -> str:
    """Session 51 (12s): 'P's allergic to Xs, so give her the Y instead' said '…, not the X'."""
    if "instead" not in text.lower():
        return text
    m = _REASON_INSTEAD51S.match(text.strip())
    if m is None:
        return text
    named = _names(m["reason"], lexicon)
    things = [it for it in named if all(r.kind == "object" for r in it.refs)]
    people = [it for it in named if all(r.kind == "human" for r in it.refs)]
    if len(things) != 1 or len(people) > 1 or len(things) + len(people) != len(named):
        return text
    x = f"the {things[0].text}"
    if _ids(m["req"], lexicon) & _ids(x, lexicon):
        return text
    out = f"{m['reason']}, so {m['req']}, not {x}{m['end'] or '.'}"
    if _read_without44r(out, text, x, lexicon) == text:
        return text
    return _plain51s(out, text, lexicon)


# "Person A wants the chips. Person B … wants the bottle. Could you sort both of those.": a last
# sentence asking the hearer to 'sort' (out) what was said: taken off, when what is before it
# reads, and 'both' / 'the two' / 'the pair' count its handovers.
_SORT_THOSE51S = re.compile(
    r"(?<=[.!?;])\s+(?:(?:could|can|would|will) you |please )?(?:just )?sort (?:out )?(?P<n>both"
    r" of |all of |the pair of |the two of |each of )?(?:those|them|these|that|it|both|the lot)"
    r"(?: out)?(?: for me)?(?:,? please)?(?:,? ta| thanks)?\s*[.?!]?\s*$",
    _F,
)


def _sort_those51s(text: str, lexicon: Lexicon) -> str:
    """Session 51 (12s): a closing "Could you sort both of those." taken off (above)."""
    if "sort" not in text.lower():
        return text
    m = _SORT_THOSE51S.search(text)
    if m is None:
        return text
    out = text[: m.start()]
    node = _reading(out, lexicon)
    if node is None:
        return text
    n = (m["n"] or "").lower()
    if (
        any(w in n or w in m[0].lower() for w in ("both", "pair", "two"))
        and len(list(tasks(node))) != 2
    ):
        return text
    return _plain51s(out, text, lexicon)


# "Person A wants the chips. Person B, back from the coarse fishing, wants the bottle.": where a
# person is (back from), said between commas after the name, in a sentence after the first:
# session 28's `_who_where28` takes it off in the first sentence only; taken off the same way in
# each later one (the person one of the scene, the words naming nothing of it).
def _where_after51s(text: str, lexicon: Lexicon) -> str:
    """Session 51 (12s): session 28's 'P, back from the X, …' in a later sentence (above)."""
    if ", " not in text or not re.search(r"[.;!?]\s+\S", text):
        return text
    parts = re.split(r"(?<=[.;!?])(\s+)", text)
    changed = False
    for k in range(2, len(parts), 2):
        m = _WHERE_AFTER28.match(parts[k])
        if m is None or not _only_person(m.group(1), lexicon):
            continue
        if not _names_nothing(m.group(2), lexicon):
            continue
        if not _fit36(next(iter(_ids(m.group(1), lexicon, "human"))), m.group(2), lexicon):
            continue  # "Zoe, back from his kayak lesson, …": whose lesson?
        parts[k] = f"{m.group(1)} {parts[k][m.end() :]}"
        changed = True
    return _plain51s("".join(parts), text, lexicon) if changed else text


# -- session 51 (12s): run-ons and lower case (blind49's) -----------------------------------------
#
# "Marco wants the knife he's doing the fish Lena wants the salt.", "Grandad wants the wipes
# Lily's made a mess with her yoghurt", "gloves to mia her hands are freezing on the dock": a
# request run on into the next clause with no stop between. A new clause starts at a he / she /
# they (with its verb), a his / her / their and a noun with its verb, or a person of the scene
# with 's, is, has, wants, needs …, after a word that ends no phrase of its own ('to', 'and',
# 'the', a verb of the grammar …). Said with a stop there, when the words before the first stop
# read by themselves as a request and the whole then reads.
_CLAUSE_VERB51S = (
    r"(?:'s|'re|'ve|'ll|'d| is| are| was| were| has| have| had| wants| needs| fancies| asked"
    r"| keeps| can't| won't| isn't| hasn't)\b"
)
_NEW_CLAUSE51S = re.compile(
    rf"(?<=[a-z0-9])\s+(?=(?:he|she|they){_CLAUSE_VERB51S}|(?:his|her|their) [a-z]+(?: [a-z]+)?"
    r" (?:is|are|was|were|has|have|keeps?|keep)\b)",
    _F,
)
_PERSON_CLAUSE51S = re.compile(
    rf"(?<=[a-z0-9])\s+(?P<p>(?:person|mr|mrs|ms|miss|dr|nurse) [a-z]+|[a-z]+){_CLAUSE_VERB51S}",
    _F,
)
# words after which a new clause cannot start: the phrase before it is not over
_OPEN51S = frozenset(
    {
        *("and", "but", "or", "so", "because", "cos", "as", "since", "that", "which", "who"),
        *("when", "if", "to", "for", "with", "from", "the", "a", "an", "not", "then", "tell"),
        *("ask", "let", "make", "says", "said", "thinks", "reckons", "know", "knows", "than"),
        *("give", "hand", "pass", "bring", "take", "put", "get", "fetch", "whether", "where"),
        *("of", "on", "in", "at", "by", "about", "what", "how", "once", "until", "after"),
        *("it's", "is", "was", "that's", "then", "now", "next"),
    }
)


# what a remark run on after a request may not say: that someone holds or had the thing, that a
# need is over, or a negation
_HELD_OR_OVER51S = re.compile(
    r"\b(?:has|have|had|got|gets|getting|fine|ok|okay|alright|better|over|no longer|not|never|"
    r"earlier|already|yesterday|anymore|any more|none|nothing|wrong|broken|sorted|back|away|gone|"
    r"out|later|tomorrow|tonight|turn|(?:done|"
    r"finished)(?! with))\b|n't\b",
    _F,
)


def _run_on51s(text: str, lexicon: Lexicon) -> str:
    """Session 51 (12s): a run-on said with its stops (above)."""
    # "… on the desk zoes done with …": session 39's name and s said with its apostrophe first
    body = _name_s39(text.rstrip(), lexicon)
    if re.search(r"[.;:!?]\s+\S", body) or "," in body:
        return text  # stops said already: not a run-on
    cuts = {m.start() for m in _NEW_CLAUSE51S.finditer(body)}
    for m in _PERSON_CLAUSE51S.finditer(body):
        if _only_person(m["p"], lexicon):
            cuts.add(m.start())
    cuts = {
        c
        for c in cuts
        if body[:c].split()[-1].lower() not in _OPEN51S and len(body[:c].split()) > 1
    }
    if not cuts:
        return text
    first = min(cuts)
    head = _reading(body[:first], lexicon)
    if head is None:
        return text  # the words before the first stop are no request of their own
    out, last = [], 0
    for c in sorted(cuts):
        out.append(body[last:c])
        last = c
    out.append(body[last:])
    # each clause after it is a request of its own, or a remark about a person it names or one
    # the requests before it give to (each he / she / his / her may be them) that says nothing
    # of holding the thing or of a need that is over ("gloves to mia she had them earlier",
    # "gloves to tom her hands are freezing": refused as before)
    given = {t.target for t in tasks(head) if t.kind == "deliver"}
    for clause in out[1:]:
        if _HELD_OR_OVER51S.search(clause):
            return text
        if _ids(clause, lexicon, "object"):
            if re.search(r"\b(?:wants?|needs?|would like|'d like) to\b", clause, flags=_F):
                return text  # "… jess wants to use the hammer": a want to do, no handover
            if not given:
                # after a placing, another's want may be why it is put there ("drill on the
                # bench jess wants (to use) the hammer"): a request of its own only after one
                # that hands something over
                return text
            node = _reading(clause, lexicon)
            if node is None:
                return text
            given |= {t.target for t in tasks(node) if t.kind == "deliver"}
            continue
        if _ids(clause, lexicon) - _ids(clause, lexicon, "human"):
            return text  # a remark naming a surface of the scene ("… hes at the pallet", s39)
        who = given | _ids(clause, lexicon, "human")
        if not any(_fit36(pid, clause, lexicon) for pid in who):
            return text
    # the rewrites before this one (a remark closing the instruction, session 38's) are asked of
    # the sentences said, as of the same words said with their stops
    return _plain51s(".".join(out), text, lexicon)


# "cup to person b who does the bat detecting and apple to person a", "Right so the apple goes to
# Alice who's been at the clay pigeon shooting and the crisps go to Carol …": a 'who' clause about
# the person a thing goes to, said without its commas, and the next request joined by 'and':
# said with its commas ("…, who does the bat detecting, and apple to person a", which the older
# rules read), when the clause names nothing of the scene and asks nothing.
_WHO_RUN_ON51S = re.compile(
    r"\b(?P<to>to|for) (?P<p>(?:person|mr|mrs|ms|miss|dr|nurse) [a-z]+|[a-z]+) "
    r"(?P<who>who(?:'s| is| does| has| was| plays| runs| works| did| teaches| drives| cooks|'ll be|"
    r" will be) [a-z' -]+?)"
    r"(?P<end> and (?=(?:the|a|an|once|then|after that|[a-z]+ (?:to|for|goes|go|gets)) )|\s*[.!]?"
    r"\s*$)",
    _F,
)


# words a clause that only describes the person does not hold
_NOT_SAID51S = re.compile(
    r"\b(?:not|no|never|if|unless|or|either|whichever|wants?|needs?|asked|after|instead|give|"
    r"hand|pass|bring|take|put|it|them|him|her|he|she|they)\b|n't\b",
    _F,
)


def _who_run_on51s(text: str, lexicon: Lexicon) -> str:
    """Session 51 (12s): a 'who' clause after the person, said with its commas (above)."""
    if " who" not in text.lower() or "," in text:
        return text
    m = _WHO_RUN_ON51S.search(text)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    if _ids(m["who"], lexicon) or _NOT_SAID51S.search(m["who"]):
        return text
    end = ", and " if m["end"].strip() == "and" else m["end"]
    out = f"{text[: m.start('who')].rstrip()}, {m['who']}{end}{text[m.end() :]}"
    return _plain51s(out, text, lexicon)


# the normaliser's first rewrites (wired into normalise._STEPS19, before the session-50 ones)
_STEPS51S_FIRST: tuple[Callable[[str, Lexicon], str], ...] = ()
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-50 ones)
_STEPS51S: tuple[Callable[[str, Lexicon], str], ...] = (
    _run_on51s,
    _who_run_on51s,
    _and_not_person51s,
    _only_cleft51s,
    _dont_bother51s,
    _which_stays51s,
    _hold_back51s,
    _ll_will51s,
    _not_wanted_when51s,
    _pair_can51s,
    _being_a51s,
    _nothing_but51s,
    _itll_why51s,
    _reason_instead51s,
    _sort_those51s,
    _where_after51s,
)
# refusals asked of the text before it is read (offline._parse, after the session-50 ones)
REFUSE51S: tuple[Callable[[str, Lexicon], None], ...] = (_later_texted51s,)
# checks of the whole instruction's reading (offline.parse_instruction, after the session-50 ones)
CHECK51S: tuple[Callable[[str, Node, Lexicon], None], ...] = (_said_so51s,)
