"""The grounder's rules of session 56, engineer 12r (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _ids, _reading
from hltl.grounding._normalise3 import _whole_name
from hltl.grounding._rewrites41r import _said41r
from hltl.grounding._rewrites42s import _remark_only42s
from hltl.grounding._rewrites46r import _P46R, _person46r
from hltl.grounding._rewrites52s import _other_sex52s
from hltl.grounding.lexicon import PRONOUN_SEX, Lexicon, unnamed_sex44l
from hltl.grounding.tree import Node, Task, has_choice, tasks


def _has(text: str, *words: str) -> bool:
    """Whether ``text`` (lower-cased) holds one of ``words``: the cheap test a rule asks first."""
    low = text.lower()
    return any(w in low for w in words)


# -- blind54: whichever / any of / one of / both / each ------------------------------------------

# "Share them out so nobody's left empty-handed: …", "Hand out both things: …", "Something for
# both of them, then: …", "A book for each child: …": a sharing-out said before a colon
_SHARE_OUT56R = re.compiled(
    r"^(?:(?:(?:share|hand|dish|pass|give|divvy|parcel) (?:them |these |those |the things |both "
    r"things |both items |the lot |everything )?(?:out|round|around|up)(?: (?:both things|both "
    r"items|the things|the lot|them|these|those))?(?: (?:so|so that) [^:;]+)?)|(?:(?:a|one) "
    r"(?:little )?(?:something|thing|treat)|something(?: nice)?) for (?P<q>both|each|the two) of "
    r"them(?:,? then)?|(?P<h>(?:a|one) [a-z]+) for each (?P<n>child|kid|person|guest|patient|one "
    r"of them|of them|worker|student|pupil))\s*:\s*(?P<rest>\S.*)$",
    _F,
)


def _share_out56r(text: str, lexicon: Lexicon) -> str:
    """Session 56 (12r): a sharing-out said before a colon ("Share them out so nobody's left
    empty-handed: …", "Hand out both things: …", "Something for both of them, then: …", "A book
    for each child: …") is "One each: …" ("A book each: …"), read by the older 'each' rules,
    which check that the list hands one thing to each of two or more people; here too the list
    must read, and hand things to two or more people and nothing else ('both of them' two,
    'each of them' every person of the scene: "Something for each of them: the cup to Alice and
    the apple to Bob." with Carol there stays refused, session 49's near form)."""
    if not _has(text, " out", " round", " up", " of them", " each "):
        return text
    m = _SHARE_OUT56R.match(text.strip())
    if m is None:
        return text
    node = _reading(m["rest"], lexicon)
    if node is None:
        return text
    done = list(tasks(node))
    got = {t.target for t in done}
    if any(t.kind != "deliver" for t in done) or len(got) < 2:
        return text
    q, n = (m["q"] or "").lower(), (m["n"] or "").lower()
    if q in ("both", "the two") and len(got) != 2:
        return text
    if (q == "each" or n.endswith("of them")) and len(got) != len(lexicon.scene.humans):
        return text  # "Something for each of them: …" naming two of three (session 49's near)
    head = f"{m['h']} each" if m["h"] else "One each"
    return f"{head}: {m['rest']}"


# "Any spare cup, white or green, to Emma": 'spare' says the robot may take any one
_ANY_SPARE56R = re.compiled(r"\b(?P<q>any|either|one of the) spare (?=[a-z])", _F)


def _any_spare56r(text: str, lexicon: Lexicon) -> str:
    """Session 56 (12r): "any (either) spare X" is "any X" (what is left is read by the older
    rules, which check the kind has more than one thing)."""
    if "spare" not in text.lower():
        return text
    return _ANY_SPARE56R.sub(lambda m: f"{m['q']} ", text)


# "One of the pens to Sam, any of the three will do."
_ANY_N_DO56R = re.compiled(
    r"^(?:one|any) of the (?P<k>[a-z]+s) (?P<to>(?:to|for) [^,]+?),\s*(?:any|either) (?:one )?of "
    r"(?:the|them|those|these) ?(?P<n>two|three|four|five)?(?: of them)? (?:will do|is fine|"
    r"would do|is good|is ok|is okay)(?P<end>\s*[.!]?)$",
    _F,
)


def _any_n_do56r(text: str, lexicon: Lexicon) -> str:
    """Session 56 (12r): "One of the Xs to P, any of the three will do" is "Any of the three Xs
    to P" (the grammar checks the count against the scene); the recipient one person."""
    if not _has(text, " do", " fine", " good", " ok"):
        return text
    m = _ANY_N_DO56R.match(text.strip())
    if m is None or _person46r(m["to"][3:].strip(), lexicon) is None:
        return text
    n = f" {m['n']}" if m["n"] else ""
    return f"Any of the{n} {m['k']} {m['to']}{m['end'] or '.'}"


# "…, whichever you lay a hand on first": the robot's pick
_LAY_HAND56R = re.compiled(
    r"\bwhichever (?:you )?(?:lay|put|get|lays|puts|gets) (?:a|your) hands? on (?:first|soonest|"
    r"quickest)(?=\s*(?:[,.!]|$))",
    _F,
)


def _lay_hand56r(text: str, lexicon: Lexicon) -> str:
    """Session 56 (12r): "…, whichever you lay (get, put) a hand on first" after a choice is
    "…, whichever comes to hand first" (read by the older rules)."""
    if "hand" not in text.lower() or "whichever" not in text.lower():
        return text
    return _LAY_HAND56R.sub("whichever comes to hand first", text)


# "Whichever of the two is closest, the chips or the bottle, take it to Person B."
_WHICHEVER_OF56R = re.compiled(
    r"^whichever (?:of (?:the|them|those|these) ?(?:two|both)?|one)(?: is|'s) (?P<how>closest|"
    r"nearest|handiest|easiest|nearer|closer|handier|easier)(?: to (?:hand|reach|you))?,\s*"
    r"(?P<x>the [a-z]+(?: [a-z]+)?) or (?P<y>the [a-z]+(?: [a-z]+)?),\s*(?:(?:take|bring|give|"
    r"hand|pass|carry|get) it (?:over |across )?to (?P<p>[^,.!]+?)|it(?:'s| is| goes) (?:to|for) "
    r"(?P<q>[^,.!]+?))(?P<end>\s*[.!]?)$",
    _F,
)


def _whichever_of56r(text: str, lexicon: Lexicon) -> str:
    """Session 56 (12r): "Whichever of the two is closest, the X or the Y, take it to P" is "The
    X or the Y to P, whichever is closest" (read by the older rules): two objects of the scene,
    one person."""
    if "whichever" not in text.lower():
        return text
    m = _WHICHEVER_OF56R.match(text.strip())
    if m is None:
        return text
    who = m["p"] or m["q"]
    if _person46r(who, lexicon) is None:
        return text
    x, y = _ids(m["x"], lexicon, "object"), _ids(m["y"], lexicon, "object")
    if len(x) != 1 or len(y) != 1 or x == y:
        return text
    if not _whole_name(m["x"], lexicon, "object") or not _whole_name(m["y"], lexicon, "object"):
        return text
    x_, y_ = m["x"][0].upper() + m["x"][1:], m["y"]
    return f"{x_} or {y_} to {who}, whichever is {m['how'].lower()}{m['end'] or '.'}"


# -- blind54: corrections -------------------------------------------------------------------------

# "…, make that the lemon for him.": the thing corrected, the person said again as a pronoun
_MAKE_THAT_FOR56R = re.compiled(
    r"(?P<head>\b(?:to|for) (?P<p>[^,;.!?]+?),\s*(?:(?:er|erm|um|uh|oh|no|sorry|wait),\s*)*no,\s*"
    r"make (?:that|it) (?P<x>the [a-z]+(?: [a-z]+)?)) (?:for|to) (?:him|her|them)"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _make_that_for56r(text: str, lexicon: Lexicon) -> str:
    """Session 56 (12r): "Salt over to Marco, er, no, make that the lemon for him." is "…, make
    that the lemon." (the older correction rules read it): one person before the correction, one
    whole object in it, the pronoun that person said again."""
    if "make " not in text.lower():
        return text
    m = _MAKE_THAT_FOR56R.search(text.strip())
    if m is None or _person46r(m["p"], lexicon) is None:
        return text
    if not _whole_name(m["x"], lexicon, "object"):
        return text
    return f"{text.strip()[: m.start()]}{m['head']}{m['end'] or '.'}"


# "The apple to Bob, no, sorry, I'm thinking of Carol, give it to her."
_THINKING_OF56R = re.compiled(
    r"(?P<cue>,\s*no,\s*(?:sorry,\s*)?)(?:i'm|i am|i was) (?:thinking of|getting mixed up with|"
    r"confusing (?:him|her) with) (?P<q>[^,.!]+?)(?:,\s*(?:so )?(?:give|take|hand|pass|bring) it "
    r"(?:over |across )?to (?P<pr>him|her|them))?(?P<end>\s*[.!]?)$",
    _F,
)


def _thinking_of56r(text: str, lexicon: Lexicon) -> str:
    """Session 56 (12r): "X to P, no, sorry, I'm thinking of Q(, give it to her)" is "X to P,
    no, sorry, Q" (the older correction rules read it): Q one person of the scene, and a him /
    her after it one Q may be (12c's probe: "…, I'm thinking of Carol, give it to him." stays
    refused)."""
    if not _has(text, "thinking of", "mixed up with", "confusing"):
        return text
    m = _THINKING_OF56R.search(text.strip())
    q = None if m is None else _person46r(m["q"], lexicon)
    if m is None or q is None:
        return text
    sex = PRONOUN_SEX.get((m["pr"] or "").lower())
    if sex is not None and unnamed_sex44l(q, lexicon) not in (None, sex):
        return text
    return f"{text.strip()[: m.start()]}{m['cue']}{m['q']}{m['end'] or '.'}"


# "…, oh no, I've said it backwards, swap those round."
_BACKWARDS56R = re.compiled(
    r",\s*(?P<cue>(?:oh )?no|oops|sorry|whoops),\s*(?:i've|i have|i) (?:said|got|put|done) "
    r"(?:it|that|them|those) (?:backwards|the wrong way round|the wrong way around|back to "
    r"front),\s*(?:swap|switch) (?:those|them|that|it|the two|the people) (?:round|around|over)"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _backwards56r(text: str, lexicon: Lexicon) -> str:
    """Session 56 (12r): "X to P, Y to Q, oh no, I've said it backwards, swap those round" is
    "…, oh no, the other way round" (session-era rules read the swap, and refuse it where the
    two requests do not swap)."""
    if "swap" not in text.lower() and "switch" not in text.lower():
        return text
    m = _BACKWARDS56R.search(text.strip())
    if m is None:
        return text
    return f"{text.strip()[: m.start()]}, {m['cue']}, the other way round{m['end'] or '.'}"


# "Teddy on the high chair, no, wait, Lily naps on the play mat, so teddy goes there instead."
_GOES_THERE56R = re.compiled(
    r"(?P<cue>,\s*(?:no|wait|actually|sorry|hang on)(?:,\s*(?:no|wait|actually|sorry|hang on))*),"
    r"\s*(?P<p>[^,;.!?]+?) (?:naps|sleeps|sits|plays|works|eats|reads|lies|likes it|keeps (?:it|"
    r"them)) (?P<on>on|in|at|by) (?P<s>the [a-z]+(?: [a-z]+)?),\s*so (?P<x>it|they|the [a-z]+|"
    r"[a-z]+) (?:goes|go|should go|can go|belongs?) there(?: instead)?(?P<end>\s*[.!]?)$",
    _F,
)


def _goes_there56r(text: str, lexicon: Lexicon) -> str:
    """Session 56 (12r): "X on S, no, wait, P naps on the T, so X goes there instead" is "X on
    S, no, wait, on the T" (the older correction rules read it): P one person, T one whole
    surface of the scene, the thing said again the one before the correction (or 'it')."""
    if "there" not in text.lower():
        return text
    m = _GOES_THERE56R.search(text.strip())
    if m is None or _person46r(m["p"], lexicon) is None:
        return text
    if not _whole_name(m["s"], lexicon, "surface"):
        return text
    head = text.strip()[: m.start()]
    said = re.sub(r"^the ", "", m["x"], flags=_F).lower()
    if said not in ("it", "they") and not head.lower().lstrip().startswith(
        (said, f"the {said}", f"put the {said}", f"put {said}")
    ):
        return text
    return f"{head}{m['cue']}, on {m['s']}{m['end'] or '.'}"


# "Drill to Kofi, wait, Jess needs it more, give it to Jess."
_NEEDS_MORE56R = re.compiled(
    r"(?P<cue>,\s*(?:no|wait|actually|sorry|hang on)(?:,\s*(?:no|wait|actually|sorry|hang on))*),"
    r"\s*(?P<p>[^,;.!?]+?) (?:needs|wants) (?:it|them) (?:more|most|first|sooner|worse),\s*"
    r"(?P<give>(?:so )?(?:give|take|hand|pass|bring) (?:it|them) (?:over |across )?to "
    r"(?P<q>[^,;.!?]+?))(?P<end>\s*[.!]?)$",
    _F,
)


def _needs_more56r(text: str, lexicon: Lexicon) -> str:
    """Session 56 (12r): "X to P, wait, Q needs it more, give it to Q" is "X to P, wait, give it
    to Q" (the older correction rules read it): the one who needs it and the one it goes to the
    same person of the scene."""
    if not _has(text, " more", " most", "first", "sooner", "worse"):
        return text
    m = _NEEDS_MORE56R.search(text.strip())
    if m is None:
        return text
    p, q = _person46r(m["p"], lexicon), _person46r(m["q"], lexicon)
    if p is None or p != q:
        return text
    return f"{text.strip()[: m.start()]}{m['cue']}, {m['give']}{m['end'] or '.'}"


# what follows 'leave the X be' when the speaker takes it back: a cue, then a request moving it
_TAKEN_BACK56R = re.compiled(
    r"^\s*,\s*(?:(?:actually|no|wait|sorry|on reflection|on second thoughts?|thinking about it|"
    r"come to think of it),\s*)+(?:run|take|bring|give|hand|pass|carry|pop|put|send|get) it\b",
    _F,
)


def kept_taken_back56r(after: str) -> bool:
    """Session 56 (12r): whether ``after`` (the words after "leave the X be / alone / where it
    is") takes the keeping back ("…, actually, on reflection, run it over to P"): session 39's
    check (offline._left_moved39l) lets such a reading through."""
    return _TAKEN_BACK56R.match(after) is not None


# -- blind54: questions ---------------------------------------------------------------------------

# "Is it alright if Person B helps himself to the chips, do you reckon, and could you take them?"
_HELPS_SELF56R = re.compiled(
    r"^(?:is it (?:alright |all right |ok |okay |fine )?if|would it be (?:alright |all right |ok |"
    rf"okay |fine )?if) (?P<p>{_P46R}) (?:helps|help) (?:himself|herself|themselves) to (?P<x>the "
    r"[a-z]+(?: [a-z]+)?)(?:,\s*(?:do you reckon|do you think|d'you reckon))?,?\s*and (?P<v>could|"
    r"can|would|will) you (?:take|bring|pass|carry|run) (?:it|them)(?: over| across)?(?: to "
    r"(?:him|her|them))?\s*\?$",
    _F,
)


def _helps_self56r(text: str, lexicon: Lexicon) -> str:
    """Session 56 (12r): "Is it alright if P helps himself to the X(, do you reckon), and could
    you take it (to him)?" is "Could you take the X to P?": one person, one whole object."""
    if "help" not in text.lower():
        return text
    m = _HELPS_SELF56R.match(text.strip())
    if m is None or _person46r(m["p"], lexicon) is None:
        return text
    if not _whole_name(m["x"], lexicon, "object"):
        return text
    return f"{m['v'].capitalize()} you take {m['x']} to {m['p']}?"


# "Can Jess borrow the small spanner, hers has gone walkabout?"
_GONE_WALKABOUT56R = re.compiled(
    r",\s*(?:(?:as|because|since|cause|'cause) )?(?:his|hers|theirs|his own|her own|their own) "
    r"(?:has|'s|is) (?:gone (?:walkabout|missing|awol|astray)|disappeared|vanished|broken|bust|"
    r"gone|lost|missing)(?P<end>\s*[?.!]?)$",
    _F,
)
_BORROW56R = re.compiled(
    rf"^(?:can|could|may|might) (?P<p>{_P46R}) (?:borrow|have|use) (?P<x>the [a-z]+(?: [a-z]+)?)"
    r"\s*$",
    _F,
)


def _gone_walkabout56r(text: str, lexicon: Lexicon) -> str:
    """Session 56 (12r): "Can P borrow the X, hers has gone walkabout?" is "Can P borrow the
    X?": the reason is about P's own one, not a thing of the scene (one person asked about, one
    whole object)."""
    low = text.lower()
    if "his" not in low and "hers" not in low and "their" not in low:
        return text
    m = _GONE_WALKABOUT56R.search(text.strip())
    if m is None:
        return text
    head = text.strip()[: m.start()]
    b = _BORROW56R.match(head)
    if b is None or _person46r(b["p"], lexicon) is None:
        return text
    if not _whole_name(b["x"], lexicon, "object"):
        return text
    return f"{head}?"


# -- blind54: counts and plurals -----------------------------------------------------------------

# "The pair of cups, green and white, …", "Kofi needs the pair of spanners, …"
_PAIR_OF56R = re.compiled(
    r"\b(?:the|that|this) pair of (?P<k>[a-z]+s)(?P<two>,\s*[a-z]+ and [a-z]+\s*,)", _F
)


def _pair_of56r(text: str, lexicon: Lexicon) -> str:
    """Session 56 (12r): "the pair of Xs, green and white," is "both Xs, green and white," where
    the scene has exactly two things of the kind (the older rules read 'both' with the two words
    said after it and check them; 'the pair of Xs' alone, or with 'the green and the white', the
    older rules read)."""
    if "pair of" not in text.lower():
        return text

    def both(m: re.Match[str]) -> str:
        if len(_ids(f"the {m['k']}", lexicon, "object")) != 2:
            return m.group(0)
        return f"both {m['k']}{m['two']}"

    return _PAIR_OF56R.sub(both, text)


# "…, so he's to have all four things, every last one."
_EVERY_LAST56R = re.compiled(
    r"(?P<all>\ball (?:(?:two|three|four|five|six) )?(?:the )?[a-z]+s|\ball of (?:them|those|"
    r"these)|\bthe lot),\s*every (?:last|single) one(?: of (?:them|those))?(?P<end>\s*[.!]?)$",
    _F,
)


def _every_last56r(text: str, lexicon: Lexicon) -> str:
    """Session 56 (12r): "…all four things, every last one" is "…all four things": the count
    said again."""
    if "every" not in text.lower():
        return text
    m = _EVERY_LAST56R.search(text.strip())
    if m is None:
        return text
    return f"{text.strip()[: m.start()]}{m['all']}{m['end'] or '.'}"


# "…, so every one of the three boxes, small, medium and large, onto the belt."
_EVERY_ONE_OF56R = re.compiled(
    r"\bevery (?:single )?one of the (?P<n>two|three|four|five|six) (?P<k>[a-z]+s)\b", _F
)


def _every_one_of56r(text: str, lexicon: Lexicon) -> str:
    """Session 56 (12r): "every one of the three Xs" is "all three Xs" (the older rules check
    the count against the scene)."""
    if "every" not in text.lower():
        return text
    return _EVERY_ONE_OF56R.sub(lambda m: f"all {m['n']} {m['k']}", text)


# "The small box and the medium one, both of them, onto the belt"
_BOTH_OF_THEM56R = re.compiled(
    r"^(?P<x>the [a-z]+(?: [a-z]+)? and the [a-z]+(?: [a-z]+)?),\s*(?:both of them|the two of "
    r"them|the pair of them|both),\s*(?P<rest>(?:up |down |over |across )?(?:on|onto|in|into|to) "
    r"\S.*)$",
    _F,
)


def _both_of_them56r(text: str, lexicon: Lexicon) -> str:
    """Session 56 (12r): "The X and the Y, both of them, onto the S" is "The X and the Y onto the
    S": the count of two said again after a list of two (the older rules read what is left)."""
    if not _has(text, "both", " two of them", "pair of them"):
        return text
    m = _BOTH_OF_THEM56R.match(text.strip())
    if m is None:
        return text
    return f"{m['x']} {m['rest']}"


# "…, so bring her both blankets, blue as well as grey."
_AS_WELL_AS56R = re.compiled(
    r"(?P<both>\bboth (?:the )?[a-z]+s),\s*(?P<a>[a-z]+) as well as (?:the )?(?P<b>[a-z]+)"
    r"(?=\s*(?:[,.!]|$))",
    _F,
)


def _as_well_as56r(text: str, lexicon: Lexicon) -> str:
    """Session 56 (12r): "both Xs, blue as well as grey" is "both Xs, blue and grey" (read by
    the older rules, which check the two words name the two things)."""
    if "as well as" not in text.lower():
        return text
    return _AS_WELL_AS56R.sub(lambda m: f"{m['both']}, {m['a']} and {m['b']}", text)


# "Only the single cup, to Person B, he just needs the one."
_ONLY_SINGLE56R = re.compiled(
    r"^(?:only|just) the (?:single|one|lone) (?P<k>[a-z]+),\s*(?P<to>(?:to|for) [^,.!]+?)"
    r"(?:,\s*(?P<pr>he|she|they) (?:just |only )?(?:needs|wants) (?:the one|just the one|one|"
    r"the single one))?(?P<end>\s*[.!]?)$",
    _F,
)


def _only_single56r(text: str, lexicon: Lexicon) -> str:
    """Session 56 (12r): "Only the single X, to P(, he just needs the one)" is "The X to P" (the
    kind one thing of the scene: else 'the X' does not read; one person)."""
    if "only" not in text.lower() and "just" not in text.lower():
        return text
    m = _ONLY_SINGLE56R.match(text.strip())
    if m is None or _person46r(m["to"][3:].strip(), lexicon) is None:
        return text
    if len(_ids(f"the {m['k']}", lexicon, "object")) != 1:
        return text
    return f"The {m['k']} {m['to']}{m['end'] or '.'}"


# "Two things are on Person A's list, the apple and the cup, and nothing beyond that."
_ON_LIST56R = re.compiled(
    r"^(?P<n>two|three|four) things (?:are|'re) on (?P<p>[^,]+?)'s list,\s*(?P<x>[^.!?;:]+? and "
    r"[^,.!?;:]+?)(?:,\s*(?:and )?nothing (?:beyond|else|more|besides)(?: than)?(?: that)?)?"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _on_list56r(text: str, lexicon: Lexicon) -> str:
    """Session 56 (12r): "Two things are on P's list, the X and the Y(, and nothing beyond
    that)" is "Two things for P, the X and the Y" (read by the older rules, which check the
    count): one person."""
    if "list" not in text.lower():
        return text
    m = _ON_LIST56R.match(text.strip())
    if m is None or _person46r(m["p"], lexicon) is None:
        return text
    return f"{m['n']} things for {m['p']}, {m['x']}{m['end'] or '.'}"


# "There's one bottle and one bag of crisps, both want to go up onto the shelf."
_BOTH_WANT_GO56R = re.compiled(
    r"^there(?:'s| is| are) (?:one|a|an) (?P<x>[a-z]+(?: of [a-z]+)?) and (?:one|a|an) "
    r"(?P<y>[a-z]+(?: of [a-z]+)?),\s*(?:and )?(?:both|the two of them|the pair of them) "
    r"(?:want|need|have|ought) to go (?P<place>(?:up |down |back )?(?:on|onto|in|into) the "
    r"[a-z]+(?: [a-z]+)?)(?P<end>\s*[.!]?)$",
    _F,
)


def _both_want_go56r(text: str, lexicon: Lexicon) -> str:
    """Session 56 (12r): "There's one X and one Y, both want to go up onto the S" is "Put the X
    and the Y up onto the S": each one thing of the scene (the older rules check it), nothing
    else said."""
    if "both" not in text.lower() and " of them" not in text.lower():
        return text
    m = _BOTH_WANT_GO56R.match(text.strip())
    if m is None:
        return text
    if len(_ids(f"the {m['x']}", lexicon, "object")) != 1:
        return text
    if len(_ids(f"the {m['y']}", lexicon, "object")) != 1:
        return text
    return f"Put the {m['x']} and the {m['y']} {m['place']}{m['end'] or '.'}"


# "Both items are Person A's, so take the pair of them to her."
_BOTH_ARE_HIS56R = re.compiled(
    r"^(?P<both>both (?:items|things|of the things|of them)) (?:are|belong to) (?P<p>[^,]+?)"
    r"(?:'s)?,\s*so (?P<v>take|bring|give|hand|pass|carry|run) (?:the pair of them|the two of "
    r"them|both of them|them both|them|both) (?:over |across |back )?to (?:him|her|them)"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _both_are_his56r(text: str, lexicon: Lexicon) -> str:
    """Session 56 (12r): "Both items are P's, so take the pair of them to her" is "Take both
    items to P" (the older rules read 'both' and check the scene holds two things)."""
    if "both" not in text.lower():
        return text
    m = _BOTH_ARE_HIS56R.match(text.strip())
    if m is None or _person46r(m["p"], lexicon) is None:
        return text
    things = "both items" if "item" in m["both"].lower() else "both things"
    return f"{m['v'].capitalize()} {things} to {m['p']}{m['end'] or '.'}"


# "…, she honestly doesn't mind which you bring."
_MIND_WHICH56R = re.compiled(
    r"(?P<head>,\s*(?:he|she|they)) (?:honestly |really |genuinely |truly )?(?P<neg>doesn't|"
    r"does not|don't|do not) mind which(?: one)?(?: (?:you (?:bring|pick|choose|grab|take|"
    r"fetch)|it is|it's))?(?P<end>\s*[.!]?)$",
    _F,
)


def _mind_which56r(text: str, lexicon: Lexicon) -> str:
    """Session 56 (12r): "…, she honestly doesn't mind which you bring" after a choice is "…,
    she doesn't mind which" (read by the older rules, which take it only after a choice)."""
    if "mind which" not in text.lower():
        return text
    m = _MIND_WHICH56R.search(text.strip())
    if m is None:
        return text
    out = f"{text.strip()[: m.start()]}{m['head']} {m['neg']} mind which{m['end'] or '.'}"
    return out if out != text.strip() else text


# -- blind54: who or which was asked, forgotten (refused naming the readings) -------------------

# "The globe to Noah, or was it Zoe who asked, I've got them mixed up."
_OR_WAS_IT56R = re.compiled(
    r"^(?P<x>[^,;.!?]+?) (?P<to>to|for) (?P<p>[^,;.!?]+?),\s*or was it (?P<q>[^,;.!?]+?) who "
    r"(?:asked|wanted it|wanted (?:them|that)|asked for (?:it|them|that))(?:,\s*|\?\s*|\.\s*)"
    r"(?:i(?:'ve| have)? got (?:them|it|that|those) (?:all )?(?:mixed up|muddled(?: up)?)|"
    r"i(?:'ve| have)? (?:mixed|muddled) (?:them|it|that|those) up|i can't (?:remember|recall)|"
    r"i(?:'ve| have)? forgotten)(?: again)?\s*[.!]?$",
    _F,
)


def _or_was_it56r(text: str, lexicon: Lexicon) -> None:
    """Session 56 (12r): "X to P, or was it Q who asked, I've got them mixed up" — the speaker
    forgot which of two people asked (P and Q two people of the scene, X one whole object):
    refused before the read, naming both readings (session 31's slip closing the text refused
    it naming neither)."""
    if "or was it" not in text.lower():
        return
    m = _OR_WAS_IT56R.match(text.strip())
    if m is None:
        return
    p, q = _person46r(m["p"], lexicon), _person46r(m["q"], lexicon)
    x = _ids(m["x"], lexicon, "object")
    if p is None or q is None or p == q or len(x) != 1:
        return
    if not _whole_name(
        re.sub(r"^(?:give|hand|pass|take|bring) ", "", m["x"], flags=_F), lexicon, "object"
    ):
        return
    obj = next(iter(x))
    said = " or ".join(_said41r(Task("deliver", obj, h), lexicon) for h in (p, q))
    raise GroundingError(f"{m.group(0)!r}: the speaker has forgotten who asked: {said}: say which")


# "…, the apple or the chips, he said which but I've clean forgot."
_SAID_WHICH56R = re.compiled(
    r"(?P<a>the [a-z]+(?: [a-z]+)?) or (?P<b>the [a-z]+(?: [a-z]+)?),\s*(?:and |but )?(?:he|she|"
    r"they) (?:did )?(?:said|say|told me|mentioned) which(?: one)?,?\s*(?:but|and) (?:i(?:'ve| "
    r"have)|i) (?:clean |completely |totally |plain )?(?:forgot|forgotten)(?: it| which)?\s*[.!]?$",
    _F,
)


def _said_which56r(text: str, lexicon: Lexicon) -> None:
    """Session 56 (12r): "…, the X or the Y, he said which but I've (clean) forgot" — a choice
    the person made and the speaker lost: refused before the read, naming both things (each of
    the scene; the grammar refused it on the speaker's 'I', naming neither)."""
    if "which" not in text.lower() or "forgot" not in text.lower():
        return
    m = _SAID_WHICH56R.search(text.strip())
    if m is None:
        return
    x, y = _ids(m["a"], lexicon, "object"), _ids(m["b"], lexicon, "object")
    if not x or not y or x & y:
        return
    a, b = ", ".join(sorted(x)), ", ".join(sorted(y))
    raise GroundingError(
        f"{m.group(0)!r}: the speaker has forgotten which was asked for, {m['a']} ({a}) or "
        f"{m['b']} ({b}); say which"
    )


# -- blind54: openers and remarks around a placing ------------------------------------------------

# "Clear the floor for the mopping, would you: the bottle and the crisps, …, up onto the shelf."
_CLEAR_FOR56R = re.compiled(
    r"^(?:clear|tidy|free up|make (?:room|space) on) (?:the|this|that) (?P<s>[a-z]+(?: [a-z]+)?)"
    r"(?: for (?:the )?[a-z]+(?: [a-z]+)?)?(?:,? (?:would|could|will|can) you)?(?:,? please)?"
    r"\s*:\s*(?P<rest>\S.*)$",
    _F,
)


def _clear_for56r(text: str, lexicon: Lexicon) -> str:
    """Session 56 (12r): "Clear the floor (for the mopping), would you: <placings>" is the
    placings: the opener says why, and names no thing of the scene; nothing is put on what is
    cleared, and what follows reads as placings only."""
    if not _has(text, "clear", "tidy", "free up", "room on", "space on"):
        return text
    m = _CLEAR_FOR56R.match(text.strip())
    if m is None or _ids(m["s"], lexicon, "object") or _ids(m["s"], lexicon, "human"):
        return text
    node = _reading(m["rest"], lexicon)
    if node is None:
        return text
    cleared = _ids(m["s"], lexicon, "surface")
    done = list(tasks(node))
    if any(t.kind != "place" or t.target in cleared for t in done):
        return text
    return m["rest"][0].upper() + m["rest"][1:]


# "…, onto the belt, Tom's waiting to tape them up."
_WAITING_TO56R = re.compiled(
    r",\s*(?P<p>[^,;.!?]+?)(?:'s| is| are|'re) (?:waiting|ready|standing by) to [a-z]+ (?:them|"
    r"it)(?: up| down| away| off| in)?(?P<end>\s*[.!]?)$",
    _F,
)


def _waiting_to56r(text: str, lexicon: Lexicon) -> str:
    """Session 56 (12r): "<placings>, Tom's waiting to tape them up" is the placings: a remark
    on what someone of the scene will do with them after, kept off when what is left reads as
    placings only (so the one waiting is no recipient)."""
    if not _has(text, "waiting to", "ready to", "standing by to"):
        return text
    m = _WAITING_TO56R.search(text.strip())
    if m is None or _person46r(m["p"], lexicon) is None:
        return text
    out = f"{text.strip()[: m.start()]}{m['end'] or '.'}"
    node = _reading(out, lexicon)
    if node is None or any(t.kind != "place" for t in tasks(node)):
        return text
    return out


# "Both of the things here, bottle and chips, belong with Person B, he's the mask maker."
_BELONG_WITH56R = re.compiled(
    r"^(?:both of the (?:things|items)(?: here)?|the (?:two|three|four) (?:things|items)"
    r"(?: here)?|all (?:the|four|three|two) (?:things|items)(?: here)?),\s*(?P<x>[^,;.!?]+? and "
    r"[^,;.!?]+?),\s*(?:belong|go|should go) (?:with|to) (?P<p>[^,;.!?]+?)"
    r"(?P<rest>,[^;]*|\s*[.!])?$",
    _F,
)


def _belong_with56r(text: str, lexicon: Lexicon) -> str:
    """Session 56 (12r): "Both of the things here, X and Y, belong with P(, he's …)" is "X and Y
    go to P(, he's …)": the list said after the count, one person; the older rules read what
    is left and check the count of things."""
    if "belong" not in text.lower() and " go " not in text.lower():
        return text
    m = _BELONG_WITH56R.match(text.strip())
    if m is None or _person46r(m["p"], lexicon) is None:
        return text
    x = m["x"][0].upper() + m["x"][1:]
    return f"{x} go to {m['p']}{m['rest'] or '.'}"


# "Priya's clearing the desk, so <placings>", "The driver's about to load, so <placings>"
_DOING_SO56R = re.compiled(
    r"^(?P<p>[^,;.!?]+?)(?:'s| is) (?:(?:about|going|getting ready|set) to [a-z]+|[a-z]+ing)"
    r"(?: (?:the|her|his|their|up|off|out) ?[a-z]*)?,\s*so (?P<rest>\S.*)$",
    _F,
)


# what says the things are moved: 'onto' / 'into', or a verb of putting ('on the S' alone may say
# where they lie)
_MOVED_TO56R = re.compiled(
    r"\b(?:onto|into|on to|in to|put|place|pop|stick|set|move|lay)\b|\bthey go\b", _F
)


def _doing_so56r(text: str, lexicon: Lexicon) -> str:
    """Session 56 (12r): "P's about to load (P's clearing the desk), so <placings>" is the
    placings: what P is doing is the reason (P one person of the scene); only where what
    follows reads alone as placings (so P is no recipient, and no pronoun looks back at P) and
    says they are moved ('onto', 'into', a verb of putting: "…, so both of the blocks on the
    high chair" may say where they lie, session 28's near form)."""
    if ", so " not in text.lower():
        return text
    m = _DOING_SO56R.match(text.strip())
    if m is None or _person46r(m["p"], lexicon) is None:
        return text
    if _MOVED_TO56R.search(m["rest"]) is None:
        return (
            text  # "Grandad's clearing the floor, so both of the blocks on the high chair." (s28r)
        )
    node = _reading(m["rest"], lexicon)
    if node is None or any(t.kind != "place" for t in tasks(node)):
        return text
    return m["rest"][0].upper() + m["rest"][1:]


# "…, all three, in the box they go."
_IN_THEY_GO56R = re.compiled(
    r",\s*(?P<prep>in|into|on|onto) (?P<s>the [a-z]+(?: [a-z]+)?) (?:they|it) go(?:es)?"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _in_they_go56r(text: str, lexicon: Lexicon) -> str:
    """Session 56 (12r): "<things>, in the box they go" is "<things> into the box": one whole
    surface of the scene, and what is left reads as placings only."""
    if "they go" not in text.lower() and "it goes" not in text.lower():
        return text
    m = _IN_THEY_GO56R.search(text.strip())
    if m is None or not _whole_name(m["s"], lexicon, "surface"):
        return text
    prep = {"in": "into", "on": "onto"}.get(m["prep"].lower(), m["prep"])
    out = f"{text.strip()[: m.start()]} {prep} {m['s']}{m['end'] or '.'}"
    node = _reading(out, lexicon)
    if node is None or any(t.kind != "place" for t in tasks(node)):
        return text
    return out


# -- 12c's open wrong reading (session 56): the speaker names which, after a choice -------------

# "Bob asked for the cup or the apple, it was the apple.", "…; I think it was the cup."
_IT_WAS56R = re.compiled(
    r"\b(?:it|that|one|which) (?:was|wasn't|was not)\b|'twas\b|\b(?:it's|it is|it isn't|it is "
    r"not|that's|that is) (?:not )?the\b",
    _F,
)
_CLAUSES56R = re.compiled(r"[^,;.!?]+", _F)


def _it_was_the56r(text: str, node: Node, lexicon: Lexicon) -> None:
    """Session 56 (12r; 12c's fuzz): "Bob asked for the cup or the apple, it was the apple."
    read cup>B | apple>B: a later clause saying which it was ("it was the apple (he wanted)", "I
    think it was the cup", "the torch it was", "it wasn't the cup") names one of the choice's
    things, and the choice rules took it for a remark. A reading with a choice, of a text with a
    clause after the choice holding 'it was' / "it's" / 'it wasn't' and naming one of the
    choice's things, is refused: the robot may not pick ('it was one of those' naming none is
    session 56's _was_one_of56l)."""
    low = text.lower()
    if " or " not in low or not _has(low, " was", "'s", " is", "'twas"):
        return
    if not has_choice(node):
        return
    offered = {t.obj for t in tasks(node)}
    cut = low.rfind(" or ")
    for m in _CLAUSES56R.finditer(text, cut):
        said = m.group(0)
        if _IT_WAS56R.search(said) is None:
            continue
        words = set(re.findall(r"[a-z]+", said.lower()))
        if _ids(said, lexicon, "object") & offered or any(
            words & set(o.lower().split("_")) for o in offered if "_" in o
        ):
            raise GroundingError(
                f"{said.strip()!r} says which was asked for, but the reading leaves the choice "
                "to the robot: say the one that goes"
            )


# -- 12c's 01:39 probe: reports read as requests ------------------------------------------------

# "Both cups, green and white, went to Emma.": a done verb after a list said with its apposition
_DONE_LIST56R = re.compiled(
    r"^(?P<said>(?P<pre>[^.;:!?]*?),\s*(?:went|were (?:given|taken|handed|brought|put|passed|"
    r"delivered|placed|sent)|got (?:given|taken|put|handed|sent)|(?:have|'ve|had|has|'s) (?:gone|"
    r"been (?:given|taken|handed|put|sent|brought)))) (?:over |across |back |up |down )?(?:to|on|"
    r"onto|in|into)\b",
    _F,
)
_ASKED_VERB56R = re.compiled(
    r"\b(?:give|hand|pass|bring|take|put|place|pop|run|carry|send|fetch|get|stick|set|move|"
    r"leave|deliver|grab)\b",
    _F,
)


def _done_list56r(text: str, lexicon: Lexicon) -> None:
    """Session 56 (12r; 12c's probe): "Both cups, green and white, went to Emma." (main:
    cup_green>C & cup_white>C; "…, were put in the sink", "…, have gone to Bob") is a report of
    what was done: the done refusals did not see past the list's apposition. Refused where
    nothing before the done verb asks for anything."""
    if not _has(text, "went", "were ", "got ", "gone", "been "):
        return
    m = _DONE_LIST56R.match(text.strip())
    if m is None or _ASKED_VERB56R.search(m["pre"]) is not None:
        return
    raise GroundingError(
        f"{m['said']!r} says what was done, not what to do: say the request, e.g. 'give Bob the "
        "cup'"
    )


# "I shared them out …: <list>", "Did you share them out: <list>?", "I've tidied up: <list>"
_DONE_COLON56R = re.compiled(
    r"^(?P<said>(?:(?:i|we)(?:'ve| have| had)? (?:already |just |now )?(?:shared|handed|dished|"
    r"divvied|parcelled|cleared|tidied|sorted|put|given|moved|done|passed|split)|(?:did|have|"
    r"has|had) (?:you|we|they|he|she) (?:already |just )?[a-z]+)\b[^:]*):",
    _F,
)


def _done_colon56r(text: str, lexicon: Lexicon) -> None:
    """Session 56 (12r; 12c's probe): "I shared them out so nobody was left empty-handed: the
    apple to Bob and the cup to Alice." (main: apple>B & cup>A), "Did you share them out: …?",
    "I've cleared the floor for the mopping: the bottle and the crisps are up on the shelf." —
    what the speaker did (or asks was done) before a colon: the list after it says how it was
    done, not what to do. Refused."""
    if ":" not in text:
        return
    m = _DONE_COLON56R.match(text.strip())
    if m is None:
        return
    raise GroundingError(
        f"{m['said']!r} says what was done (or asks it), not what to do: say the request"
    )


# "The apple to Bob, no, sorry, Carol, give it to him.": the closing him / her no recipient may be
_GIVE_IT_TO56R = re.compiled(
    r"[,;.]\s*(?:so |and )?(?:give|take|hand|pass|bring|run) (?:it|them) (?:over |across |back )?"
    r"to (?P<pr>him|her)\s*[.!]?$",
    _F,
)


_CUE56R = re.compiled(
    r"[,;.]\s*(?:no|sorry|wait|hang on|i mean|actually|make that|scratch that)\b", _F
)


def _give_it_to56r(text: str, node: Node, lexicon: Lexicon) -> None:
    """Session 56 (12r; 12c's probe): "The apple to Bob, no, sorry, Carol, give it to him." read
    apple>C: a closing "give it to him / her" said again of the one corrected to, whom the scene
    says is of the other sex (a title, a word of kin, a first name of one sex; not the corpus's
    Person A / Person B convention). After a correction only, a reading none of whose
    recipients the him / her may be is refused."""
    if "him" not in text.lower() and "her" not in text.lower():
        return
    m = _GIVE_IT_TO56R.search(text.strip())
    if m is None:
        return
    if _CUE56R.search(text[: m.start()]) is None:
        return  # no correction before it (blind20 #52: 'Person B …, take them over to her')
    sex = PRONOUN_SEX[m["pr"].lower()]
    got = {t.target for t in tasks(node) if t.kind == "deliver"}
    if not got:
        return
    if all(_other_sex52s(h, sex, lexicon) for h in got):
        raise GroundingError(
            f"{m['pr']!r} cannot be {' or '.join(sorted(got))}, who the request hands it to: "
            "name the person"
        )


# -- older parts (session-55 leftovers): counts --------------------------------------------------

# "Of the boxes, two go on the belt today: the small one and the medium one, the large stays put."
_OF_THE_N56R = re.compiled(
    r"^of the (?P<k>[a-z]+s),\s*(?P<n>two|three|four) (?:go|should go|need to go|want to go) "
    r"(?P<on>on|onto|in|into) (?P<s>the [a-z]+(?: (?!today|now|please)[a-z]+)?)(?: today| now| "
    r"please)?\s*:\s*"
    r"(?P<list>[^:;]+?)(?:,\s*the [a-z]+(?: one)? (?:stays put|stays where it is|stays|can stay"
    r"(?: put)?))?(?P<end>\s*[.!]?)$",
    _F,
)
_N56R = {"two": 2, "three": 3, "four": 4}


def _of_the_n56r(text: str, lexicon: Lexicon) -> str:
    """Session 56 (12r; blind50 #115): "Of the Xs, two go on the S: the A one and the B one(, the
    C stays put)" is "The A one and the B one on the S" where that reads as placing exactly two
    things, each an X of the scene, on the surface said (the one that stays is not placed)."""
    if "of the" not in text.lower():
        return text
    m = _OF_THE_N56R.match(text.strip())
    if m is None or not _whole_name(m["s"], lexicon, "surface"):
        return text
    on = {"on": "onto", "in": "into"}.get(m["on"].lower(), m["on"])
    k = m["k"].lower()
    one = k[:-2] if k.endswith(("xes", "shes", "ches", "sses")) else k[:-1]
    said = re.sub(r"\b(the [a-z]+) ones?\b", rf"\1 {one}", m["list"], flags=_F)
    out = f"{said[0].upper()}{said[1:]} {on} {m['s']}{m['end'] or '.'}"
    node = _reading(out, lexicon)
    kind = _ids(f"the {m['k']}", lexicon, "object")
    surface = _ids(m["s"], lexicon, "surface")
    if node is None:
        return text
    done = list(tasks(node))
    if len(done) != _N56R[m["n"].lower()] or any(
        t.kind != "place" or t.obj not in kind or t.target not in surface for t in done
    ):
        return text
    return out


# "Person A gets the bottle and Person B gets the apple and they're both off to the willow weaving"
_BOTH_OFF_TO56R = re.compiled(
    r"(?:,\s*|\s+)and (?:they're|they are) both (?:off|going|heading) (?:to|for) "
    r"(?P<what>[^,.;!?]+)(?P<end>\s*[.!]?)$",
    _F,
)


def _both_off_to56r(text: str, lexicon: Lexicon) -> str:
    """Session 56 (12r; blind48 #65): "P gets X and Q gets Y and they're both off to the willow
    weaving" is "P gets X and Q gets Y": where they are off to names nothing of the scene, and
    what is left hands things to two people."""
    if "both" not in text.lower():
        return text
    m = _BOTH_OFF_TO56R.search(text.strip())
    if m is None or not _remark_only42s(m["what"], lexicon):
        return text
    out = f"{text.strip()[: m.start()]}{m['end'] or ''}"
    node = _reading(out, lexicon)
    if node is None:
        return text
    done = list(tasks(node))
    if any(t.kind != "deliver" for t in done) or len({t.target for t in done}) != 2:
        return text
    return out


_STEPS56R_FIRST: tuple[Callable[[str, Lexicon], str], ...] = ()
_STEPS56R: tuple[Callable[[str, Lexicon], str], ...] = (
    _share_out56r,
    _any_spare56r,
    _any_n_do56r,
    _lay_hand56r,
    _whichever_of56r,
    _make_that_for56r,
    _thinking_of56r,
    _backwards56r,
    _goes_there56r,
    _needs_more56r,
    _helps_self56r,
    _gone_walkabout56r,
    _pair_of56r,
    _every_last56r,
    _both_of_them56r,
    _as_well_as56r,
    _only_single56r,
    _on_list56r,
    _both_want_go56r,
    _both_are_his56r,
    _mind_which56r,
    _clear_for56r,
    _waiting_to56r,
    _belong_with56r,
    _in_they_go56r,
    _doing_so56r,
    _of_the_n56r,
    _both_off_to56r,
)
REFUSE56R: tuple[Callable[[str, Lexicon], None], ...] = (
    _or_was_it56r,
    _said_which56r,
    _done_list56r,
    _done_colon56r,
)
CHECK56R: tuple[Callable[[str, Node, Lexicon], None], ...] = (_it_was_the56r, _give_it_to56r)
