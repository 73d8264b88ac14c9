"""The grounder's rules of session 55, engineer 12r (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _ids, _reading
from hltl.grounding._normalise3 import _whole_name
from hltl.grounding._rewrites44 import _GERUNDS44, _VERBS44
from hltl.grounding._rewrites46r import _P46R, _person46r
from hltl.grounding._rewrites53r import _held53r
from hltl.grounding.lexicon import Lexicon
from hltl.grounding.phrasing import starting_on
from hltl.grounding.tree import Node, has_choice, tasks

# -- open wrong readings -------------------------------------------------------------------------

# a later time said alone between commas (or as a sentence): the request's own time ("Bob can take
# his pick of the cup or the apple, tomorrow", "…, before I go tomorrow", "…, after lunch")
_DAY55R = r"(?:monday|tuesday|wednesday|thursday|friday|saturday|sunday)"
_LATER55R = (
    r"(?:tonight|tomorrow(?: (?:morning|afternoon|evening|night|lunchtime))?|the day after "
    rf"tomorrow|later on|this (?:evening|afternoon|weekend)|next (?:week|month|{_DAY55R})|"
    rf"(?:on )?{_DAY55R}(?: (?:morning|afternoon|evening|night))?|in the (?:morning|afternoon|"
    r"evening)|after (?:lunch|dinner|breakfast|tea|school|work)|in (?:an?|one|two|three|four|"
    r"five|ten|twenty|\d+) hours?|in (?:two|three|four|five|ten|twenty|thirty|\d+) (?:minutes|"
    r"mins)|first thing (?:tomorrow(?: morning)?|in the "
    r"morning))"
)
_TIME_PART55R = re.compiled(
    r"(?:^|[,;:.!?])\s*(?P<said>(?:(?:but|and|only|just|ideally|maybe|say) )?(?:(?:before|by|"
    r"after|until|till|sometime|some time|any time|anytime|early|late) )?(?:(?:i|we) (?:go|leave|"
    r"head off|head home|get back|finish|knock off|clock off) )?"
    rf"{_LATER55R}(?: (?:please|then|at the latest|latest|or so))?)\s*(?=[,;:.!?]|$)",
    _F,
)


def _later_part55r(text: str, node: Node, lexicon: Lexicon) -> None:
    """Session 55 (12r; 12c's session-54 fuzz): a later time said alone between commas or as a
    sentence ("Bob can take his pick of the cup or the apple, tomorrow", "Any of the four things,
    Person B isn't choosy, before I go tomorrow", "…, after lunch") is the request's own time: it
    puts the task off (session 20), however the rest reads. The choice rules had taken it for a
    remark naming nothing and dropped it. A time said of someone ("Bob's off tomorrow, so …")
    is no such part."""
    low = text.lower()
    if (
        "tomorrow" not in low
        and "tonight" not in low
        and "later on" not in low
        and "this " not in low
        and "next " not in low
        and "day" not in low
        and "in the " not in low
        and "after " not in low
        and " in " not in low
        and "first thing" not in low
    ):
        return
    m = _TIME_PART55R.search(text)
    if m is None:
        return
    raise GroundingError(
        f"{m['said']!r} puts the task off: the cell acts now, so say the request when it is to "
        "be done"
    )


# "Could you give Bob the apple, or does Alice want it?": the speaker asking which, as a question
_OR_ASKED55R = re.compiled(
    r"\bor (?:does|do|did|is|are|was|were|should|would|will|can|could|shall|might|has|have|had) "
    r"[^.!?]*\?",
    _F,
)


def _or_asked55r(text: str, node: Node, lexicon: Lexicon) -> None:
    """Session 55 (12r; 12c's probe): "Give Bob the apple, or does Alice want it?" ("…, or
    should Alice have it?", "…, or does he want both?") read apple>B | apple>A: the grammar made
    the speaker's question a choice left to the robot. A choice read where 'or' opens a question
    is refused (the speaker asks which; "…, or is that a bother?" beside one request, no choice
    read, stays read)."""
    if "or " not in text.lower() or "?" not in text:
        return
    m = _OR_ASKED55R.search(text)
    if m is None or not has_choice(node):
        return
    raise GroundingError(
        f"{m.group(0)!r} asks which: the speaker has not left the choice to the robot; say who "
        "gets what"
    )


# the words a want is said with ("Mrs Ortiz wants both the books on the shelf.")
_WANT55R = re.compiled(
    r"\b(?:wants?|wanted|wanting|needs?|needed|needing|would like|'d like|would love|'d love|"
    r"is after|'s after|asked for|asking for|fancies|could use|'d prefer|would prefer)\b",
    _F,
)


# the rest of a want's clause, and a list in it followed by a place
_CLAUSE55R = re.compiled(r"[^;.!?]*", _F)
_LIST_PLACE55R = re.compiled(r"\band\b.*\b(?:on|onto|in|into)\b", _F)


def _put_where_it_is55r(text: str, node: Node, lexicon: Lexicon) -> None:
    """Session 55 (12r; 12c's session-54 fuzz): "Mrs Ortiz wants both the books on the shelf."
    (the green book lying on the shelf) read book_red>A & book_green@shelf: the want of a list
    with a place, one of the things already there, was left to the grammar (session 35's
    `_wanted_on` puts them all there only when none lies there), which handed the first over and
    put the last where it lies (or, the other way round, handed over the one lying there). A want
    read as a handing-over AND a placing on a surface one of the things starts on is refused:
    does she want them put there, or handed over, the one there among them?"""
    low = text.lower()
    if (
        "want" not in low
        and "need" not in low
        and "like" not in low
        and "love" not in low
        and "after" not in low
        and "asked" not in low
        and "asking" not in low
        and "fancies" not in low
        and "could use" not in low
        and "prefer" not in low
    ):
        return
    want = _WANT55R.search(text)
    if want is None:
        return
    done = list(tasks(node))
    given = {t.obj for t in done if t.kind == "deliver"}
    if not given:
        return
    # the handed thing lying there counts only where the want's own clause lists things and a place
    clause = _CLAUSE55R.match(text, want.end())
    listed = clause is not None and _LIST_PLACE55R.search(clause.group(0)) is not None
    for where in dict.fromkeys(t.target for t in done if t.kind == "place"):
        placed = {t.obj for t in done if t.kind == "place" and t.target == where}
        there = starting_on(placed | given if listed else placed, where, lexicon)
        if there:
            raise GroundingError(
                f"the {there[0]} already lies on the {where}: are the things wanted put there, "
                "or handed over? say 'put … on …' or 'give … to …'"
            )


# -- blind53: questions --------------------------------------------------------------------------

# "Any chance you'd give Sam the black pen, …?": 'you'd' is 'you could' (session 44's form)
_CHANCE_YOUD55R = re.compiled(
    r"(?:^|(?<=[.;!?:])\s*)(?P<head>(?:(?:would|is) there (?:be )?)?any (?:chance|hope|way)"
    rf"(?: at all)?) you'd (?P<v>{_VERBS44})\b",
    _F,
)


def _chance_youd55r(text: str, lexicon: Lexicon) -> str:
    """Session 55 (12r): "Any chance you'd give Sam the black pen?" is "Any chance you could give
    …?", which session 44's `_ask_chance44` reads ('you'd' there is 'you would', asked)."""
    if "you'd" not in text.lower():
        return text
    m = _CHANCE_YOUD55R.search(text)
    if m is None:
        return text
    return f"{text[: m.start()]}{m['head']} you could {m['v']}{text[m.end() :]}"


# "Wouldn't mind handing Person A her bottle, would you?": the 'you' of the tag left off the front
_WOULDNT_MIND55R = re.compiled(
    r"^(?P<not>wouldn't|would not) mind (?P<g>"
    + "|".join(_GERUNDS44)
    + r")\b(?P<rest>[^?]*),\s*would you\s*\?\s*$",
    _F,
)


def _wouldnt_mind55r(text: str, lexicon: Lexicon) -> str:
    """Session 55 (12r): "Wouldn't mind handing P her bottle, would you?" is "You wouldn't mind
    handing …, would you?" (the tag says who is asked; without it, "Wouldn't mind a cup" is the
    speaker's own want)."""
    if "mind" not in text.lower():
        return text
    m = _WOULDNT_MIND55R.match(text.strip())
    if m is None:
        return text
    return f"You {m['not']} mind {m['g']}{m['rest']}, would you?"


# "Could Person A get her bottle, please, when you're passing?": the hearer's chance, asked
_PASSING_ASKED55R = re.compiled(
    r"(?P<sep>\s*,?\s*)(?:when|whenever|as|next time) you(?:'re| are) (?:passing|going past|"
    r"passing by|walking past|going by|on your way past)\s*\?\s*$",
    _F,
)


def _passing_asked55r(text: str, lexicon: Lexicon) -> str:
    """Session 55 (12r): "…, when you're passing?" closing a question (session 42's
    `_robot_rest42s` takes it off a request ending in a full stop) is taken off, the question
    mark kept, when what is left reads."""
    if (
        "passing" not in text.lower()
        and "past" not in text.lower()
        and "going by" not in (text.lower())
    ):
        return text
    m = _PASSING_ASKED55R.search(text)
    if m is None or m.start() == 0:
        return text
    out = text[: m.start()].rstrip(" ,") + "?"
    return out if _reading(out, lexicon) is not None else text


# "Got a spare minute to get the bottle across to Person B?": whether the hearer has the time
_SPARE_MINUTE55R = re.compiled(
    r"^(?:(?:have|has) you (?:got )?|do you have |you got |got )(?:a|any|one) "
    r"(?:(?:spare|free|quick|little|spare little) )?(?:minute|moment|sec|second|mo|tick|jiffy)"
    rf"(?: or two)?(?: (?:spare|free))? to (?P<v>{_VERBS44})\b(?P<rest>[^?]*)\?\s*$",
    _F,
)


def _spare_minute55r(text: str, lexicon: Lexicon) -> str:
    """Session 55 (12r): "Got a spare minute to get the bottle across to P?" ("Have you got a
    moment to …?", "Do you have a sec to …?") asks for the task: "Could you get the bottle
    across to P?" (a question that only asks about the time, without a task, stays refused)."""
    low = text.lower()
    if (
        "minute" not in low
        and "moment" not in low
        and "sec" not in low
        and " mo " not in low
        and "tick" not in low
        and "jiffy" not in low
    ):
        return text
    m = _SPARE_MINUTE55R.match(text.strip())
    if m is None:
        return text
    return f"Could you {m['v']}{m['rest']}?"


# "Do you think you could fit in giving Person B the chips …?": room for the task, asked
_FIT_IN55R = re.compiled(
    r"\b(?P<ask>(?:could|can|would|will|might) you|you (?:could|can|would|might)) (?:fit in|"
    r"squeeze in|manage|find time for|find the time for) (?P<g>" + "|".join(_GERUNDS44) + r")\b",
    _F,
)


def _fit_in55r(text: str, lexicon: Lexicon) -> str:
    """Session 55 (12r): "Could you fit in (squeeze in, manage) giving P the chips?" is "Could you
    give P the chips?" (the task asked, room made for it)."""
    low = text.lower()
    if (
        "fit in" not in low
        and "squeeze in" not in low
        and "manage" not in low
        and ("time for" not in low)
    ):
        return text
    m = _FIT_IN55R.search(text)
    if m is None:
        return text
    return f"{text[: m.start()]}{m['ask']} {_GERUNDS44[m['g'].lower()]}{text[m.end() :]}"


# "Might the lemon go out to Mr Novak, for his fish?": 'out' (from the kitchen, out to the tables)
_OUT_TO55R = re.compiled(
    r"\b(?P<v>go|goes|going|gone|went|take|takes|taking|took|bring|brings|bringing|brought|send|"
    r"sends|sending|sent|carry|carries|carrying|carried)\b(?P<mid>(?: the [a-z]+(?: [a-z]+)?| it|"
    rf" them)?) out to (?P<p>{_P46R})(?=\s*(?:[,.;!?]|$))",
    _F,
)


def _out_to55r(text: str, lexicon: Lexicon) -> str:
    """Session 55 (12r): "the lemon goes (take the lemon) out to P" is "… over to P": 'out' says
    the way out (of the kitchen) and names nothing; only before one person of the scene ('out to
    the van', 'out to lunch' stay as they are)."""
    if " out to " not in text.lower():
        return text
    for m in list(_OUT_TO55R.finditer(text))[::-1]:
        if _person46r(m["p"], lexicon) is None:
            continue
        text = f"{text[: m.start()]}{m['v']}{m['mid']} over to {m['p']}{text[m.end() :]}"
    return text


# "Can the green book come down off the shelf to Mrs Ortiz?": the thing coming to the person
_COME_TO55R = re.compiled(
    r"^(?P<ask>can|could|might|may)\s+(?P<x>the [a-z]+(?: [a-z]+)?) come"
    r"(?P<way>(?: (?:over|down|across|back|along|round|up))?(?: (?:off|from) the [a-z]+"
    rf"(?: [a-z]+)?)?) to (?P<p>{_P46R})(?P<rest>(?:,? please)?\s*\?\s*)$",
    _F,
)


def _come_to55r(text: str, lexicon: Lexicon) -> str:
    """Session 55 (12r): "Can (could, might) the X come (down off the shelf) to P?" is "Can you
    bring the X (down off the shelf) to P?" (the thing asked to come to one person of the scene,
    by the hearer's hand); not 'will' / 'would' (asking what will happen) nor with more said after
    the person ("…, or should it go to Alice?": 12c's probe)."""
    if " come" not in text.lower():
        return text
    m = _COME_TO55R.match(text.strip())
    if m is None or _person46r(m["p"], lexicon) is None:
        return text
    ask = m["ask"][:1].upper() + m["ask"][1:].lower()
    return f"{ask} you bring {m['x']}{m['way']} to {m['p']}{m['rest']}"


# -- blind53: corrections -----------------------------------------------------------------------

# "…, argh, my brain, Bob I meant.", "…, no, Person A's, my error.": the speaker blaming herself
_MY_ERROR55R = re.compiled(
    r"(?<=,)(?P<sp>\s*)(?:(?:argh|ugh|gah|doh|duh|oh),?\s*)?(?:my (?:error|blunder|slip|goof)|"
    r"my (?:poor )?(?:brain|head|memory))(?=\s*(?:,|[.!]?\s*$))",
    _F,
)


def _my_error55r(text: str, lexicon: Lexicon) -> str:
    """Session 55 (12r): "my error" ("my blunder", "my slip") and, between commas, "(argh,) my
    brain" ("my head", "my memory") blame the speaker, as "my mistake" does; said after a request
    (not where the words before say what someone has or had)."""
    low = text.lower()
    if "my " not in low:
        return text
    if (
        "error" not in low
        and "blunder" not in low
        and "slip" not in low
        and "goof" not in low
        and "brain" not in low
        and "head" not in low
        and "memory" not in low
    ):
        return text
    m = _MY_ERROR55R.search(text)
    if m is None or m.start() < 2 or _held53r(text[: m.start()]):
        return text
    return f"{text[: m.start()]}{m['sp']}my mistake{text[m.end() :]}"


# "The grey blanket for Mrs Khan, not grey, I mean blue.": the colour (or size) put right
_NOT_WORD55R = re.compiled(
    r", (?P<cue>(?:no|sorry|oops|wait|hang on), )?not (?P<a>[a-z]+),\s*(?:(?:i mean|i meant|"
    r"make it|rather|it's|it was)\s*,?\s*)?(?:the )?(?P<b>[a-z]+)(?: one)?(?P<end>\s*[.!]?)$",
    _F,
)


def _not_word55r(text: str, lexicon: Lexicon) -> str:
    """Session 55 (12r): "The grey blanket for P, not grey, I mean blue" is "…, no, the blue one":
    the word put right said before a kind ('grey blanket'), and the new word with that kind one
    object of the scene ('blue blanket'); the head names that thing once."""
    if ", not " not in text.lower():
        return text
    m = _NOT_WORD55R.search(text)
    if m is None:
        return text
    head = text[: m.start()]
    said = re.findall(rf"\b{m['a']} (?P<k>[a-z]+)\b", head, _F)
    if len(said) != 1 or _held53r(head):
        return text
    kind = said[0]
    if len(_ids(f"the {m['a']} {kind}", lexicon, "object")) != 1:
        return text
    if not _whole_name(f"the {m['b']} {kind}", lexicon, "object"):
        return text
    return f"{head}, no, the {m['b']} one{m['end'] or '.'}"


# "Tray for the spoon, no, I've changed my mind, the sink.": a note said place first
_SURFACE_FOR55R = re.compiled(
    r"^(?P<s>(?:the )?[a-z]+(?: [a-z]+)?) for (?P<x>the [a-z]+(?: [a-z]+)?)(?P<rest>,\s*"
    r"(?:oh |or )?(?:no|sorry|wait|hang on|hold on|actually)\b.+)$",
    _F,
)


def _surface_for55r(text: str, lexicon: Lexicon) -> str:
    """Session 55 (12r): "Tray (belt) for the spoon, <cue> …, <the correction>" is "The spoon on
    the tray, <cue> …": the note said place first (one surface, one object, whole names) before a
    correction the older rules read (session 34's `_surface_for34r` has the correction 'to P' /
    'on S' right after 'no')."""
    low = text.lower()
    if " for the " not in low:
        return text
    m = _SURFACE_FOR55R.match(text.strip())
    if m is None or not _whole_name(m["s"], lexicon, "surface"):
        return text
    if not _whole_name(m["x"], lexicon, "object"):
        return text
    where = re.sub(r"^the ", "", m["s"], flags=_F).lower()
    return f"The {m['x'][4:]} on the {where}{m['rest']}"


# "…, oh hang on, it's the small box that goes on.": the thing put right, said as a cleft
_GOES_ON55R = re.compiled(
    r"\b(?P<it>it's|it is) (?P<x>the [a-z]+(?: [a-z]+)?) that (?P<v>goes|go) (?:on|in|up|on it|"
    r"in it|onto it|into it|on there|in there|up there)(?P<end>\s*[.!]?)$",
    _F,
)


def _goes_on55r(text: str, lexicon: Lexicon) -> str:
    """Session 55 (12r): "…, hang on, it's the small box that goes on (in, up there)" closing a
    correction is "…, it's the small box that goes there", which the older rules read (the thing
    one object of the scene)."""
    if "that go" not in text.lower():
        return text
    m = _GOES_ON55R.search(text)
    if m is None or not _whole_name(m["x"], lexicon, "object"):
        return text
    return f"{text[: m.start()]}{m['it']} {m['x']} that {m['v']} there{m['end']}"


# "The bottle goes to, um, yes, Person A, no change there.": a hesitation, then the person
_UM_YES55R = re.compiled(
    r"\b(?P<to>to|for),\s*(?:(?:um|uh|er|erm|ah),\s*)?(?:yes|yeah|yep|right),\s*"
    rf"(?P<p>{_P46R})(?P<tail>,\s*(?:no change there|no change|same as (?:ever|always|before))|)"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _um_yes55r(text: str, lexicon: Lexicon) -> str:
    """Session 55 (12r): "The bottle goes to, um, yes, P(, no change there)" is "The bottle goes
    to P": the speaker finding the name, then saying it is as it was (one person of the
    scene)."""
    low = text.lower()
    if "to," not in low and "for," not in low:
        return text
    m = _UM_YES55R.search(text)
    if m is None or _person46r(m["p"], lexicon) is None:
        return text
    return f"{text[: m.start()]}{m['to']} {m['p']}{m['end'] or '.'}"


# "Take the bottle to Person B, silly me, there's no Person B, so Person A.": no such person
_NO_SUCH55R = re.compiled(
    r"(?:,\s*(?:no|sorry|oops|whoops|oh|silly me|my mistake|wait|hang on)\b[^,]*)?"
    rf",\s*there(?:'s| is) no (?P<q>{_P46R})(?: here| in here| around)?,\s*(?:so |then |so then )?"
    rf"(?:(?:it's|make it) )?(?P<p>{_P46R})(?P<end>\s*[.!]?)$",
    _F,
)


def _no_such55r(text: str, lexicon: Lexicon) -> str:
    """Session 55 (12r): "Take the bottle to Person B, silly me, there's no Person B, so Person
    A" is "Take the bottle to Person A": the person said first is no whole name of the scene's
    ('Person B' in a scene of Person A alone), said once in the request before, and is put right
    by one person of the scene after 'so'."""
    low = text.lower()
    if "there's no " not in low and "there is no " not in low:
        return text
    m = _NO_SUCH55R.search(text)
    if m is None or _whole_name(m["q"], lexicon, "human") or m["q"].lower() == m["p"].lower():
        return text
    if _person46r(m["p"], lexicon) is None:
        return text
    head = text[: m.start()]
    said = list(re.finditer(rf"\b{re.escape(m['q'])}\b", head, _F))
    if len(said) != 1 or _held53r(head):
        return text
    at = said[0]
    return f"{head[: at.start()]}{m['p']}{head[at.end() :]}{m['end'] or '.'}"


# "Was it the wipes or the sippy cup Grandad wanted? It's gone right out of my head."
_WAS_IT55R = re.compiled(
    r"^was it (?P<x>the [a-z]+(?: [a-z]+)?) or (?P<y>the [a-z]+(?: (?!that\b)[a-z]+)?)(?: that)? "
    rf"(?P<p>{_P46R}) (?P<v>wanted|asked for|needed|was after)\s*\?\s*(?P<rest>.+)$",
    _F,
)
_FORGOT55R = re.compiled(
    r"^(?:(?:it's|it has|that's) gone (?:right |clean |completely )?out of my head|i (?:can't|"
    r"cannot|can not) (?:remember|recall)|i(?:'ve| have) forgotten|i forget|(?:i've )?no idea)"
    r"[^.!?]*[.!]?$",
    _F,
)


def _was_it55r(text: str, lexicon: Lexicon) -> str:
    """Session 55 (12r): "Was it the X or the Y P wanted? It's gone right out of my head." is
    "P wanted the X or the Y, it's gone right out of my head": the speaker has forgotten which
    (refused, naming both readings, as that sentence is); not without the forgetting remark (a
    question that only asks)."""
    if not text.lower().startswith("was it "):
        return text
    m = _WAS_IT55R.match(text.strip())
    if m is None or _FORGOT55R.match(m["rest"].strip()) is None:
        return text
    if _person46r(m["p"], lexicon) is None:
        return text
    rest = m["rest"].strip()
    return f"{m['p']} {m['v']} {m['x']} or {m['y']}, {rest[:1].lower()}{rest[1:]}"


# the normaliser's first rewrites (wired into normalise._STEPS19, before the session-54 ones)
_STEPS55R_FIRST: tuple[Callable[[str, Lexicon], str], ...] = (
    _my_error55r,
    _surface_for55r,
    _goes_on55r,
)
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-54 ones)
_STEPS55R: tuple[Callable[[str, Lexicon], str], ...] = (
    _chance_youd55r,
    _wouldnt_mind55r,
    _passing_asked55r,
    _spare_minute55r,
    _fit_in55r,
    _out_to55r,
    _come_to55r,
    _not_word55r,
    _um_yes55r,
    _no_such55r,
    _was_it55r,
)
# refusals asked of the text before it is read (offline._parse, after the session-54 ones)
REFUSE55R: tuple[Callable[[str, Lexicon], None], ...] = ()
# checks of the whole instruction's reading (offline.parse_instruction, after the session-54 ones)
CHECK55R: tuple[Callable[[str, Node, Lexicon], None], ...] = (
    _later_part55r,
    _put_where_it_is55r,
    _or_asked55r,
)
