"""The grounder's rules of session 55, engineer 12r (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _ids, _reading
from hltl.grounding._normalise3 import _whole_name
from hltl.grounding._rewrites42s import _remark_only42s
from hltl.grounding._rewrites44 import _GERUNDS44, _VERBS44
from hltl.grounding._rewrites46r import _P46R, _person46r
from hltl.grounding._rewrites53r import _held53r
from hltl.grounding.lexicon import Lexicon, lex
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


def _list_split55r(text: str, node: Node, lexicon: Lexicon) -> None:
    """Session 55 (12r): "Bob had the cup and the apple on the shelf." (main: cup>B &
    apple@shelf), "Bob had both mugs on the shelf." — a list of things (or one plural name)
    right before 'on' / 'in' a surface, read as handing some of them over and putting the others
    there: the place said of the whole list went to its last thing only. Both readings a person
    might mean (all put there, or all handed over and the place says which) take the list whole;
    a split reading is refused."""
    low = text.lower()
    if " and " not in low and "both" not in low and "all" not in low:
        return
    if " on" not in low and " in" not in low:
        return
    done = list(tasks(node))
    given = {t.obj for t in done if t.kind == "deliver"}
    placed = {(t.obj, t.target) for t in done if t.kind == "place"}
    if not given or not placed:
        return
    try:
        items = lex(text, lexicon)
    except GroundingError:
        return
    run: set[str] = set()
    for k, it in enumerate(items):
        if it.kind == "ent" and it.refs and all(r.kind == "object" for r in it.refs):
            run |= {r.id for r in it.refs}
            continue
        if it.kind == "word" and it.lemma in ("and", "det", "both"):
            continue  # a comma ends the list ("Give Bob the cup, and the apple on the shelf.")
        if run and it.kind == "word" and it.lemma in ("on", "filler"):
            j = k
            while j < len(items) and items[j].kind == "word" and items[j].lemma == "filler":
                j += 1
            if j < len(items) and items[j].lemma == "on":
                j += 1
                while j < len(items) and items[j].kind == "word" and items[j].lemma == "det":
                    j += 1
                if j < len(items) and items[j].kind == "ent" and len(items[j].refs) == 1:
                    where = items[j].refs[0].id
                    after = items[j + 1 : j + 3]
                    if (
                        len(after) == 2
                        and low.lstrip().startswith(("give ", "hand ", "pass "))
                        and after[0].lemma == "for"
                        and after[1].kind == "ent"
                        and all(r.kind == "human" for r in after[1].refs)
                    ):
                        break  # "… the salt on the rack for Mr Novak": session 43's placed_for
                    handed = run & given
                    put = {o for o in run if (o, where) in placed}
                    if len(run) > 1 and handed and put and handed != put:
                        raise GroundingError(
                            f"the place after {' and '.join(sorted(run))} could say where all of "
                            "them go or which are meant: say 'put … on …' or who gets what"
                        )
        run = set()


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


# what may come before 'to, um, yes, P': a request or a present 'goes' / 'is for' (12c's probe:
# "The bottle went to, um, yes, Person A." is said as done)
_ASKED_TO55R = re.compiled(
    r"\b(?:goes|go|is|are|'s|give|hand|take|pass|bring|send|deliver|carry|pop|run)\b[^,.;!?]*$", _F
)
_DONE_TO55R = re.compiled(
    r"\b(?:went|gone|was|were|had|has|have|handed|given|passed|taken|brought|sent|delivered|"
    r"should|would|could|might|must)\b",
    _F,
)


def _um_yes55r(text: str, lexicon: Lexicon) -> str:
    """Session 55 (12r): "The bottle goes to, um, yes, P(, no change there)" is "The bottle goes
    to P": the speaker finding the name, then saying it is as it was (one person of the
    scene); only after a request or a present 'goes' / 'is for' (not 'went', 'has gone', 'should
    have gone', 'was handed')."""
    low = text.lower()
    if "to," not in low and "for," not in low:
        return text
    m = _UM_YES55R.search(text)
    if m is None or _person46r(m["p"], lexicon) is None:
        return text
    head = text[: m.start()]
    if _ASKED_TO55R.search(head) is None or _DONE_TO55R.search(head) is not None:
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


# -- blind53: whichever, either, both, each ------------------------------------------------------

# "Bob can have whichever mug is closer to hand.": the robot's pick of the kind
_CLOSER_TO_HAND55R = re.compiled(
    r"\bwhichever (?P<k>[a-z]+) (?:is|'s) (?:closer|closest|nearer|nearest|handier|handiest|"
    r"easier|easiest)(?: to (?:hand|reach|get at|grab|you))?(?=\s*(?:[,.!]|$))",
    _F,
)


def _closer_to_hand55r(text: str, lexicon: Lexicon) -> str:
    """Session 55 (12r): "P can have whichever mug is closer to hand (handiest, nearest to you)"
    is "P can have any mug" (the scene holding more than one of the kind): the robot picks; not
    'closer to <someone or something>' (which one is meant: the older rules measure it)."""
    if "whichever" not in text.lower():
        return text
    m = _CLOSER_TO_HAND55R.search(text)
    if m is None or len(_ids(f"the {m['k']}", lexicon, "object")) < 2:
        return text
    return f"{text[: m.start()]}any {m['k']}{text[m.end() :]}"


# "Any of the four is fine for Person A, …": the robot's pick among the scene's things
_ANY_FINE55R = re.compiled(
    r"^(?:any|either|any one|whichever) of the (?P<n>two|three|four|five|six) (?:things |items )?"
    r"(?:is|are|would be|'d be|will be|'ll be) (?:fine|ok|okay|good|grand|alright|all right) "
    rf"(?:for|by) (?P<p>{_P46R})(?P<rest>(?:\s*,[^.;!?]*)?[.!]?)\s*$",
    _F,
)


# a remark about before, after a choice ("…, she had one earlier"): doubt about the choice
_PAST55R = re.compiled(
    r"\b(?:had|has had|'s had|said|told|was|were|yesterday|earlier|before|ago|last|used to)\b",
    _F,
)


def _any_fine55r(text: str, lexicon: Lexicon) -> str:
    """Session 55 (12r): "Any of the four is fine for P(, …)" is "P can have any of the four
    things(, …)" (session 50's "Any of the four will do for P"; the grammar checks the count),
    one person of the scene."""
    if (
        " fine" not in text.lower()
        and " ok" not in text.lower()
        and "good" not in text.lower()
        and ("grand" not in text.lower() and "right" not in text.lower())
    ):
        return text
    m = _ANY_FINE55R.match(text.strip())
    if m is None or _person46r(m["p"], lexicon) is None:
        return text
    if _PAST55R.search(m["rest"]) is not None:
        return text  # "…, she had one earlier", "…, she said yesterday" (12c's probe)
    return f"{m['p']} can have any of the {m['n']} things{m['rest'] or '.'}"


# "Any of the four is fine for Person A, grab what's nearest.": the robot's pick, said again
_GRAB_NEAREST55R = re.compiled(
    r",\s*(?:just )?(?:grab|take|pick|bring|get|hand (?:her|him) over) (?:what's|whatever's|"
    r"whichever's|whatever is|whichever is|the one that's|what is) (?:nearest|closest|handiest|"
    r"easiest|nearer|closer)(?: to (?:hand|you|reach))?(?P<end>\s*[.!]?)$",
    _F,
)


def _grab_nearest55r(text: str, lexicon: Lexicon) -> str:
    """Session 55 (12r): "…, grab what's nearest (whatever's handiest)" closing a choice left to
    the robot says the choice again: taken off when what is left reads as a choice."""
    low = text.lower()
    if (
        "nearest" not in low
        and "closest" not in low
        and "handiest" not in low
        and ("easiest" not in low and "nearer" not in low and "closer" not in low)
    ):
        return text
    m = _GRAB_NEAREST55R.search(text)
    if m is None:
        return text
    out = f"{text[: m.start()]}{m['end'] or '.'}"
    node = _reading(out, lexicon)
    return out if node is not None and has_choice(node) else text


# "Person A or Person B, I'm easy, one of the two gets the bottle, your pick."
_ONE_OF_TWO55R = re.compiled(
    rf"^(?P<p>{_P46R}) or (?P<q>{_P46R}),\s*(?:(?:i'm|i am) (?:easy|not fussed|not bothered|happy "
    r"either way),\s*)?(?:one of (?:the two|them|the pair|you two|the two of "
    r"them)|either (?:one|of them)) (?:gets|has|can have|takes|is having) (?P<x>the [a-z]+"
    r"(?: [a-z]+)?)(?P<tail>,\s*(?:your (?:pick|call|choice)|you (?:choose|decide|pick)|up to "
    r"you|(?:i'm|i am) easy))?(?P<end>\s*[.!]?)$",
    _F,
)


def _one_of_two55r(text: str, lexicon: Lexicon) -> str:
    """Session 55 (12r): "P or Q, one of the two gets the X(, your pick)" is "P or Q can have the
    X(, your pick)": two people of the scene named, the thing one object; nothing after it but
    that the pick is the robot's ("…, Carol says" stays refused)."""
    if "one of" not in text.lower() and "either" not in text.lower():
        return text
    m = _ONE_OF_TWO55R.match(text.strip())
    if m is None or not _whole_name(m["x"], lexicon, "object"):
        return text
    p, q = _person46r(m["p"], lexicon), _person46r(m["q"], lexicon)
    if p is None or q is None or p == q:
        return text
    return f"{m['p']} or {m['q']} can have {m['x']}{m['tail'] or ''}{m['end'] or '.'}"


# "…, and that's the only bottle, so she's having it.": the one thing of its kind, named
_ONLY_ONE55R = re.compiled(
    r"\s+and (?:that's|that is|it's|it is) the only (?P<x>[a-z]+(?: [a-z]+)?),\s*so "
    r"(?P<pro>she|he)(?:'s| is) having it\b",
    _F,
)


def _only_one55r(text: str, lexicon: Lexicon) -> str:
    """Session 55 (12r): "P's the only soul about and that's the only bottle, so she's having
    it" is "P's the only soul about, so she's having the bottle": 'the only X' of the one X of
    the scene."""
    if "the only" not in text.lower():
        return text
    m = _ONLY_ONE55R.search(text)
    if m is None or not _whole_name(m["x"], lexicon, "object"):
        return text
    if len(_ids(f"the {m['x']}", lexicon, "object")) != 1:
        return text
    return f"{text[: m.start()]}, so {m['pro']}'s having the {m['x']}{text[m.end() :]}"


# "Marco wants every plate on the worktop, white and blue alike, …": each of the kind, named
_EVERY_ALIKE55R = re.compiled(
    r"\bevery (?P<k>[a-z]+) (?P<prep>(?:up |down )?(?:on|onto|in|into)) (?P<s>the [a-z]+(?: "
    r"[a-z]+)?),\s*(?P<a>[a-z]+) and (?P<b>[a-z]+) alike\b",
    _F,
)


def _every_alike55r(text: str, lexicon: Lexicon) -> str:
    """Session 55 (12r): "every plate on the worktop, white and blue alike" is "the white plate
    and the blue plate on the worktop": the two named are every one of the kind in the scene."""
    if "alike" not in text.lower():
        return text
    m = _EVERY_ALIKE55R.search(text)
    if m is None:
        return text
    kind = _ids(f"the {m['k']}", lexicon, "object")
    a = _ids(f"the {m['a']} {m['k']}", lexicon, "object")
    b = _ids(f"the {m['b']} {m['k']}", lexicon, "object")
    if len(kind) != 2 or len(a) != 1 or len(b) != 1 or a | b != kind:
        return text
    said = f"the {m['a']} {m['k']} and the {m['b']} {m['k']} {m['prep']} {m['s']}"
    return f"{text[: m.start()]}{said}{text[m.end() :]}"


# "A drink apiece, please: the cup's for Person A and …": each gets one, the list after the colon
_APIECE55R = re.compiled(
    r"^(?P<h>an? [a-z]+|one) (?:apiece|each)(?: for (?:the pair of them|the two of them|both of "
    r"them|them both|each of them))?(?P<remark>,\s*[^:,]+?)?(?P<please>,? please)?\s*:",
    _F,
)


def _apiece55r(text: str, lexicon: Lexicon) -> str:
    """Session 55 (12r): "A drink apiece, please: <list>" ("One apiece for the pair of them,
    they've both been up ladders: <list>") is "A drink each: <list>" (read by the older rules:
    the header says each gets one); a remark before the colon must name nothing of the scene
    ('they've both' is the pair said again)."""
    low = text.lower()
    if "apiece" not in low and "each" not in low:
        return text
    m = _APIECE55R.match(text.strip())
    if m is None or (m["remark"] is None and m["please"] is None):
        return text  # "One apiece (for the pair of them): <list>" is session 46's
    if m["remark"] is not None:
        said = re.sub(r"\b(they(?:'ve| have|'re| are)) both\b", r"\1", m["remark"], flags=_F)
        if not _remark_only42s(said.strip(" ,"), lexicon):
            return text
    return f"{m['h']} each:{text.strip()[m.end() :]}"


# -- blind53: counts and plurals -----------------------------------------------------------------

# "The red mug and its blue twin, …": the other of the kind, by its colour
_TWIN55R = re.compiled(
    r"\b(?P<a>the (?P<c1>[a-z]+) (?P<k>[a-z]+)) and its (?P<c2>[a-z]+) (?:twin|partner|mate|"
    r"sibling|brother|sister|counterpart|match|pair|cousin|friend)\b",
    _F,
)


def _twin55r(text: str, lexicon: Lexicon) -> str:
    """Session 55 (12r): "the red mug and its blue twin (partner, mate)" is "the red mug and the
    blue mug": each one object of the scene."""
    if " its " not in text.lower():
        return text
    m = _TWIN55R.search(text)
    if m is None or not _whole_name(m["a"], lexicon, "object"):
        return text
    other = f"the {m['c2']} {m['k']}"
    if not _whole_name(other, lexicon, "object"):
        return text
    return f"{text[: m.start()]}{m['a']} and {other}{text[m.end() :]}"


# "Chips, cup, apple: those three to Person B": the list counted again after a colon
_THOSE_N55R = re.compiled(
    r"^(?P<list>[^:;,]+(?:,\s*[^:;,]+)+):\s*(?:those|these|all|the|all of those) (?P<n>two|three|"
    r"four|five)(?: of them)? (?P<rest>(?:go )?(?:to|for|on|onto|in|into) [^;]+?)(?P<end>\s*[.!;]"
    r".*)?$",
    _F,
)
_N55R = {"two": 2, "three": 3, "four": 4, "five": 5}


def _those_n55r(text: str, lexicon: Lexicon) -> str:
    """Session 55 (12r): "Chips, cup, apple: those three to Person B" is "Chips, cup and apple
    to Person B": the count said after the colon that of the list (each item one object)."""
    if ":" not in text:
        return text
    m = _THOSE_N55R.match(text.strip())
    if m is None:
        return text
    items = [x.strip() for x in m["list"].split(",")]
    if len(items) != _N55R[m["n"].lower()]:
        return text
    if any(not _whole_name(x, lexicon, "object") for x in items):
        return text
    said = ", ".join(items[:-1]) + f" and {items[-1]}"
    return f"{said} {m['rest']}{m['end'] or '.'}"


# "Both items are spoken for by Person B, so hand the pair of them over."
_SPOKEN_FOR55R = re.compiled(
    rf"\b(?P<be>is|are) (?:spoken for|called for|bagged|reserved) by (?P<p>{_P46R})"
    r"(?P<so>,\s*so (?:hand|pass|give|take) (?:it|them|the pair of them|both of them|the lot) "
    r"over)(?P<end>\s*[.!]?)$",
    _F,
)


def _spoken_for55r(text: str, lexicon: Lexicon) -> str:
    """Session 55 (12r): "X are spoken for (bagged, reserved) by P, so hand them over" is "X are
    for P": only with that tail (without it session 43's `_claimed_by43s` reads it): one person
    of the scene; not where the words before say what someone has or had."""
    low = text.lower()
    if (
        "spoken for" not in low
        and "called for" not in low
        and "bagged" not in low
        and ("reserved" not in low)
    ):
        return text
    m = _SPOKEN_FOR55R.search(text)
    if m is None or _person46r(m["p"], lexicon) is None or _held53r(text[: m.start()]):
        return text
    return f"{text[: m.start()]}{m['be']} for {m['p']}{m['end'] or '.'}"


# "Both of the cups want soaking, so into the sink with them.": where they go, for why
_WANT_DOING55R = re.compiled(
    r"^(?P<x>[^,]+?) (?:want|wants|need|needs) (?:a )?[a-z]+(?:ing)?(?: (?:out|up|off|down|"
    r"through))?,\s*so (?P<prep>(?:up |down |back )?(?:on|onto|in|into)) (?P<s>the [a-z]+"
    r"(?: [a-z]+)?)(?: with (?:them|it|the pair of them|both of them|the lot))?(?: now| please)?"
    r"(?P<end>\s*[.!]?)$",
    _F,
)
_WITH_THEM55R = re.compiled(
    r"(?P<prep>(?:up |down |back |over )?(?:on|onto|in|into)) (?P<s>the [a-z]+(?: [a-z]+)?) with "
    r"(?:them|the pair of them|both of them|the two of them|the lot(?: of them)?|all of them)"
    r"(?=\s*(?:[,.!]|$))",
    _F,
)


def _with_them55r(text: str, lexicon: Lexicon) -> str:
    """Session 55 (12r): "X want soaking (need a wash), so into the sink (with them)" is "X into
    the sink"; "X and Y, up on the shelf with the pair of them" is "X and Y, up on the shelf":
    the surface one of the scene, 'with them' the things said before it."""
    low = text.lower()
    if " so " in low and (" want" in low or " need" in low):
        m = _WANT_DOING55R.match(text.strip())
        if m is not None and _whole_name(m["s"], lexicon, "surface"):
            out = f"{m['x']} {m['prep']} {m['s']}{m['end'] or '.'}"
            if _reading(out, lexicon) is not None:
                return out
    if " with " not in low:
        return text
    m2 = _WITH_THEM55R.search(text)
    if m2 is None or m2.start() == 0 or not _whole_name(m2["s"], lexicon, "surface"):
        return text
    if len(_ids(text[: m2.start()], lexicon, "object")) < 2:
        return text  # "Apple first, onto the shelf with them.": 'them' are not the things said
    out = f"{text[: m2.start()]}{m2['prep']} {m2['s']}{text[m2.end() :]}"
    return out if _reading(out, lexicon) is not None else text


# "Mr Lee's shivering, wrap him in both blankets, …": what he is wrapped in, handed to him
_WRAP_IN55R = re.compiled(
    rf"\bwrap (?P<p>him|her|{_P46R})(?: up)? in (?P<x>(?:the|both|both the|both of the|his|her) "
    r"[a-z]+(?: [a-z]+)?)",
    _F,
)


def _wrap_in55r(text: str, lexicon: Lexicon) -> str:
    """Session 55 (12r): "wrap him (up) in both blankets" is "give him both blankets": the things
    handed (the robot hands them over; one person or a pronoun the older rules resolve)."""
    if "wrap " not in text.lower():
        return text
    m = _WRAP_IN55R.search(text)
    if m is None or not _ids(m["x"], lexicon, "object"):
        return text
    if m["p"].lower() not in ("him", "her") and _person46r(m["p"], lexicon) is None:
        return text
    return f"{text[: m.start()]}give {m['p']} {m['x']}{text[m.end() :]}"


# "Lena's carrying out two plates, the white and the blue, so let her have them both."
_CARRYING55R = re.compiled(
    rf"^(?P<p>{_P46R})(?:'s| is) (?:carrying|taking|bringing|serving|running)(?: (?:out|over|up|"
    r"round|through))? (?:two|both|the two|both the) (?P<k>[a-z]+)s(?P<which>,\s*the [a-z]+ and "
    r"the [a-z]+)?,\s*so (?:let (?:her|him) have|give (?:her|him)) (?:them|those)(?: both)?"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _carrying55r(text: str, lexicon: Lexicon) -> str:
    """Session 55 (12r): "P's carrying out two plates(, the white and the blue), so let her have
    them both" is "Let P have both plates(, the white and the blue)": the two of the kind in the
    scene, for one person of it."""
    low = text.lower()
    if "so " not in low or (" have them" not in low and "give " not in low):
        return text
    m = _CARRYING55R.match(text.strip())
    if m is None or _person46r(m["p"], lexicon) is None:
        return text
    if len(_ids(f"the {m['k']}", lexicon, "object")) != 2:
        return text
    return f"Let {m['p']} have both {m['k']}s{m['which'] or ''}{m['end'] or '.'}"


# "Both spanners live in the locker, so in they go now.": where they belong, so put there
_IN_THEY_GO55R = re.compiled(
    r",\s*so (?P<prep>in|on|up|onto|into) (?:they|it) go(?:es)?(?: now| then| please)?"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _in_they_go55r(text: str, lexicon: Lexicon) -> str:
    """Session 55 (12r): "X live (belong) in the locker, so in they go (now)" is "X live in the
    locker": what is left reads as putting them there (the older rules read 'live in' so), only
    placings."""
    if "they go" not in text.lower() and "it goes" not in text.lower():
        return text
    m = _IN_THEY_GO55R.search(text)
    if m is None or m.start() == 0:
        return text
    out = f"{text[: m.start()]}{m['end'] or '.'}"
    node = _reading(out, lexicon)
    if node is None or any(t.kind != "place" for t in tasks(node)):
        return text
    return out


# "On the desk, please, go the red book and the green one, both for the reading corner."
_ON_S_GO55R = re.compiled(
    r"^(?P<prep>on|onto|in|into) (?P<s>the [a-z]+(?: [a-z]+)?),\s*(?:please,\s*)?go (?P<x>the "
    r"[a-z]+(?: [a-z]+)? and the [a-z]+(?: [a-z]+)?)(?:,\s*both for (?P<why>the [a-z]+"
    r"(?: [a-z]+)?))?(?P<end>\s*[.!]?)$",
    _F,
)


def _on_s_go55r(text: str, lexicon: Lexicon) -> str:
    """Session 55 (12r): "On the desk, (please,) go the red book and the green one(, both for the
    reading corner)" is "Put the red book and the green one on the desk": the surface one of the
    scene; what they are for, naming nothing of the scene, taken off."""
    if " go " not in text.lower():
        return text
    m = _ON_S_GO55R.match(text.strip())
    if m is None or not _whole_name(m["s"], lexicon, "surface"):
        return text
    if m["why"] is not None and _ids(m["why"], lexicon):
        return text
    return f"Put {m['x']} {m['prep'].lower()} {m['s']}{m['end'] or '.'}"


# "The bottle went to, um, Person A.": said as done, the hesitation before the name
_DONE_UM55R = re.compiled(
    r"\b(?P<said>(?:went|gone|(?:was|were) (?:given|handed|passed|taken|brought|sent|delivered))"
    r") to,\s*(?:(?:um|uh|er|erm|ah|yes|yeah|right),\s*)+",
    _F,
)


def _done_um55r(text: str, lexicon: Lexicon) -> None:
    """Session 55 (12r; 12c's probe): "The bottle went to, um, Person A." read bottle>A — the
    refusal of what is said as done ("The bottle went to Person A.") did not see past the
    hesitation: refused the same."""
    low = text.lower()
    if "went" not in low and "gone" not in low and "was " not in low and "were " not in low:
        return
    m = _DONE_UM55R.search(text)
    if m is None:
        return
    raise GroundingError(
        f"{m['said']!r} says it as done, not as something to do: say the request without it, "
        "e.g. 'give Bob the chips'"
    )


# "Bob had either mug.", "Bob could have had any mug.": what someone had, said of a choice
_HAD_CHOICE55R = re.compiled(
    r"\b(?P<said>(?:had|has had|'s had|have had|could have had|would have had|might have had|"
    r"should have had|could've had|would've had|might've had|should've had) (?:either|any|"
    r"whichever|one of|(?:his|her|their) pick))\b",
    _F,
)


def _had_choice55r(text: str, lexicon: Lexicon) -> None:
    """Session 55 (12r): "Bob had either mug." ("… could have had any mug", "… had his pick of
    the cups") read mug_red>B | mug_blue>B on main: what someone had (or might have had) is no
    request, the choice in it no choice left to the robot: refused."""
    if "had" not in text.lower():
        return
    m = _HAD_CHOICE55R.search(text)
    if m is None:
        return
    raise GroundingError(
        f"{m['said']!r} says what someone had or might have had: it asks for nothing; say "
        "'give …' to have something handed over"
    )


# "Person A wants the cup, hang on, no, not the cup, something else, I've lost it."
_SOMETHING_ELSE55R = re.compiled(
    r"\bnot (?P<x>the [a-z]+(?: [a-z]+)?),\s*(?:it's |it was )?something else,\s*(?:i've lost it|"
    r"i've forgotten(?: what)?|i forget what|i can't remember what|can't remember what|it's gone|"
    r"no idea what)\b",
    _F,
)


def _something_else55r(text: str, lexicon: Lexicon) -> None:
    """Session 55 (12r): "P wants the cup, hang on, no, not the cup, something else, I've lost
    it" leaves what P wants to the speaker's lost word: refused, naming the other things it could
    be (every object of the scene but the one put aside)."""
    if "something else" not in text.lower():
        return
    m = _SOMETHING_ELSE55R.search(text)
    if m is None:
        return
    out = _ids(m["x"], lexicon, "object")
    if len(out) != 1:
        return
    rest = [o.id for o in lexicon.scene.objects if o.id not in out]
    if not rest:
        return
    raise GroundingError(
        f"{m.group(0)!r}: the speaker has lost what is wanted instead of {m['x']}: it could be "
        f"{', '.join(rest)}; say which"
    )


# the normaliser's first rewrites (wired into normalise._STEPS19, before the session-54 ones)
_STEPS55R_FIRST: tuple[Callable[[str, Lexicon], str], ...] = (
    _my_error55r,
    _surface_for55r,
    _goes_on55r,
    _apiece55r,
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
    _closer_to_hand55r,
    _any_fine55r,
    _grab_nearest55r,
    _one_of_two55r,
    _only_one55r,
    _every_alike55r,
    _twin55r,
    _those_n55r,
    _spoken_for55r,
    _with_them55r,
    _wrap_in55r,
    _carrying55r,
    _in_they_go55r,
    _on_s_go55r,
)
# refusals asked of the text before it is read (offline._parse, after the session-54 ones)
REFUSE55R: tuple[Callable[[str, Lexicon], None], ...] = (
    _done_um55r,
    _had_choice55r,
    _something_else55r,
)
# checks of the whole instruction's reading (offline.parse_instruction, after the session-54 ones)
CHECK55R: tuple[Callable[[str, Node, Lexicon], None], ...] = (
    _later_part55r,
    _put_where_it_is55r,
    _or_asked55r,
    _list_split55r,
)
