"""The grounder's rules of session 52, engineer 12r (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _ids, _names, _reading
from hltl.grounding._rewrites44r import _agrees44r
from hltl.grounding._rewrites46r import _P46R, _person46r
from hltl.grounding._rewrites51r import (
    _BACK51R,
    _CUE51R,
    _one_task51r,
    one_surface51r,
    placed_elsewhere51r,
)
from hltl.grounding.lexicon import KIND_CATEGORIES, Lexicon, person_name
from hltl.grounding.tree import Group, Node, has_choice, tasks

# -- 12c's fuzz: wrong readings of session 51 ---------------------------------------------------

# "…, I mean the black one, my bad. Sam gets the notepad too.": the speaker owning the mistake
# just corrected, at the end of the correction's sentence
_MEANT_MINE52R = re.compiled(
    r"(?P<fix>\bi mean(?:t)?\b[^.!?;]*?)\s*,\s*(?:oops\s*,?\s*)?(?:my bad|my mistake|my fault|"
    r"my error)\s*(?=[.!;]|$)",
    _F,
)


def _meant_mine52r(text: str, lexicon: Lexicon) -> str:
    """Session 52 (12r): "<request>, I mean <the fix>, my bad." owns the mistake the 'I mean'
    has just corrected: the closer taken off. Session 42's `_owned_mistake42r` had read it as
    owning the request and taken a next sentence for the correction ("…, I mean the black one,
    my bad. Sam gets the notepad too." read notebook>B only: 12c's fuzz)."""
    low = text.lower()
    if "i mean" not in low or "my " not in low:
        return text
    m = _MEANT_MINE52R.search(text)
    if m is None or re.search(r"\b(?:other|another|rest)\b", text[m.end() :], _F):
        return text  # "…, my bad. Sam gets the other one.": the one taken back, or another?
    return f"{text[: m.start()]}{m['fix']}{text[m.end() :]}"


# "Whichever of the chips and the apple, Person A is happy with one, Person B too."
_TOO_AFTER52R = re.compiled(
    rf"(?:^|[,;.]\s*)(?P<p>{_P46R}|she|he)(?:'s| is| isn't| is not| was| wasn't| would be|'d be|"
    r"'ll be| will be| doesn't| does not| don't| can| could| will| would| likes| loves| wants| "
    rf"needs)\b[^,;.]*[,;]\s*(?:and\s+)?(?P<q>{_P46R})\s+(?:too|as well|also)\s*(?=[.!;]|$)",
    _F,
)


def _too_after52r(text: str, lexicon: Lexicon) -> None:
    """Session 52 (12r): a remark of one person then ", Q too" ("Whichever of the chips and the
    apple, Person A is happy with one, Person B too") says the same of Q: who gets the thing is
    not said (the grammar had dropped the remark and read "…, Person B" as the one who gets it:
    12c's fuzz): refused."""
    low = text.lower()
    if " too" not in low and "as well" not in low and " also" not in low:
        return
    for m in _TOO_AFTER52R.finditer(text):
        qid = _person46r(m["q"], lexicon)
        if qid is None:
            continue
        said = m["p"].lower() in ("she", "he")
        pid = None if said else _person46r(m["p"], lexicon)
        if pid == qid or (pid is None and not said):
            continue
        raise GroundingError(
            f"{m.group(0).strip(' ,;.')!r} says the same of {m['q']}: who gets it is not said; "
            "name the person who gets each thing"
        )


# -- blind50: corrections ------------------------------------------------------------------------

# "…, no, hold your horses, they were Bob's.", "…, no, tell you what, straight into P's hand.": a
# filler between the correction's cue and what it says
_FILLER52R = re.compiled(
    rf"(?P<cue>,\s*{_CUE51R})(?:hold your horses|steady on|tell you what|hang fire|wait a sec|"
    r"one sec|half a sec|come to think of it|thinking about it|on second thoughts?)\s*,\s*",
    _F,
)
# "…, no, they were Bob's": whose the things were, said in the past
_WERE_HIS52R = re.compiled(
    rf"(?P<cue>,\s*{_CUE51R})(?P<it>they|it)(?: were| was) (?P<p>{_P46R})'s"
    r"(?P<end>(?:\s+actually)?\s*[.!]?)$",
    _F,
)


def _filler_fix52r(text: str, lexicon: Lexicon) -> str:
    """Session 52 (12r): a filler after a correction's cue ("…, no, hold your horses, …", "…, no,
    tell you what, …", "…, wait, steady on, …") is taken off, and "they were (it was) P's" after
    the cue is "they're (it's) P's": the correction as sessions 19-51 read it. Taken only when
    the head is one task and the result one task of the same kind or a delivery."""
    low = text.lower()
    if "," not in low or not _BACK51R.search(text):
        return text
    out = _FILLER52R.sub(lambda m: m["cue"].rstrip() + " ", text.strip())
    m = _WERE_HIS52R.search(out)
    if m is not None and _person46r(m["p"], lexicon) is not None:
        now = "they're" if m["it"].lower() == "they" else "it's"
        out = f"{out[: m.start()]}{m['cue']}{now} {m['p']}'s{m['end']}"
    if out == text.strip():
        return text
    back = _BACK51R.search(out)
    head = out[: back.start() if back is not None else 0].rstrip(" ,;")
    if _one_task51r(f"{head}.", lexicon) is None and not _VAGUE52R.match(head):
        return text
    return out


# "Stick the bottle down somewhere": a placing that names no place
_VAGUE52R = re.compiled(
    r"^(?:just )?(?:put|stick|pop|set|leave|plonk|drop) (?P<x>the [a-z]+(?: [a-z]+)?) (?:down )?"
    r"(?:somewhere|anywhere|wherever)(?: (?:you like|handy|safe|for now))?$",
    _F,
)
# … corrected to a person: "…, no, (straight) into Person A's hand(s)" / "…, no, to Person A"
_VAGUE_TO52R = re.compiled(
    rf"^(?P<head>[^,;]+?)\s*,\s*(?P<cue>{_CUE51R})(?:(?:straight|right) )?(?:(?:into|in) "
    rf"(?P<p>{_P46R})'s hands?|to (?P<q>{_P46R}))(?P<end>\s*[.!]?)$",
    _F,
)


def _vague_to52r(text: str, lexicon: Lexicon) -> str:
    """Session 52 (12r): a placing that names no place ("Stick the bottle down somewhere"), then a
    correction to a person ("…, no, straight into Person A's hand", "…, no, to Bob") is "Give
    <the person> <the thing>": the correction says where it goes."""
    low = text.lower()
    if "," not in low or (
        "somewhere" not in low and "anywhere" not in low and "wherever" not in low
    ):
        return text
    m = _VAGUE_TO52R.match(text.strip())
    if m is None or not _BACK51R.search(m["cue"]):
        return text
    v = _VAGUE52R.match(m["head"].strip())
    who = m["p"] or m["q"]
    if v is None or _person46r(who, lexicon) is None:
        return text
    out = f"Give {who} {v['x']}{m['end'] or '.'}"
    got = _one_task51r(out, lexicon)
    return out if got is not None and got[0] == "deliver" else text


# "…, no, he said apple, not chips.": what the person said, and not the first thing
_SAID_FIX52R = re.compiled(
    rf"^(?P<head>[^,;]+?)\s*,\s*(?P<cue>{_CUE51R})(?P<w>she|he|{_P46R}) (?:said|says|asked for|"
    r"wants|wanted|meant) (?P<x>(?:the )?[a-z]+(?: [a-z]+)?)\s*,\s*not (?P<y>(?:the )?[a-z]+"
    r"(?: [a-z]+)?)(?P<end>\s*[.!]?)$",
    _F,
)


def _said_fix52r(text: str, lexicon: Lexicon) -> str:
    """Session 52 (12r): a handover, a correction cue, then "he said X, not Y" (the person the
    handover is for; Y the thing first said) is "<handover>, no, the X": the thing corrected."""
    if " not " not in text.lower() or "," not in text:
        return text
    m = _SAID_FIX52R.match(text.strip())
    if m is None or not _BACK51R.search(m["cue"]):
        return text
    first = _one_task51r(f"{m['head']}.", lexicon)
    if first is None or first[0] != "deliver":
        return text
    w = m["w"].lower()
    if w in ("she", "he"):
        if not _agrees44r(first[2], w, lexicon):
            return text
    elif _person46r(m["w"], lexicon) != first[2]:
        return text
    x = m["x"] if m["x"].lower().startswith("the ") else f"the {m['x']}"
    y = {r.id for it in _names(m["y"], lexicon) for r in it.refs}
    if y != {first[1]}:
        return text
    out = f"{m['head']}, no, {x}{m['end'] or '.'}"
    got = _one_task51r(out, lexicon)
    if got is None or got[0] != "deliver" or got[2] != first[2] or got[1] == first[1]:
        return text
    return out


# "Give Person A the, um, the bottle I meant to say."
_MEANT_TO_SAY52R = re.compiled(
    r"\s+(?:i meant to say|i mean to say|is what i meant|i meant)(?P<end>\s*[.!]?)$",
    _F,
)


def _meant_to_say52r(text: str, lexicon: Lexicon) -> str:
    """Session 52 (12r): a request closed by "I meant to say" after its one thing ("Give P the,
    um, the bottle I meant to say") is the request: the speaker naming the thing she meant.
    Taken only when the text names one object (with two it corrects one: session 19's rule)."""
    if "meant" not in text.lower() and "mean to" not in text.lower():
        return text
    m = _MEANT_TO_SAY52R.search(text.strip())
    if m is None:
        return text
    head = text.strip()[: m.start()]
    objs = {r.id for it in _names(head, lexicon) for r in it.refs if r.kind == "object"}
    if len(objs) != 1 or not re.search(r"\bthe [a-z]+(?: [a-z]+)?$", head, _F):
        return text
    out = f"{head}{m['end'] or '.'}"
    return out if _one_task51r(out, lexicon) is not None else text


# "…, no, hang on, Priya wants it left out on the desk."
_LEFT_OUT52R = re.compiled(r"\b(?P<it>it|them) left out (?P<on>on|in)\b", _F)


def _left_out52r(text: str, lexicon: Lexicon) -> str:
    """Session 52 (12r): "P wants it left out on the desk" after a correction cue is "P wants it
    left on the desk" (session 51's `_kept_on51r` reads it as the place corrected)."""
    if "left out" not in text.lower() or not _BACK51R.search(text):
        return text
    return _LEFT_OUT52R.sub(lambda m: f"{m['it']} left {m['on']}", text)


# "…, actually no, lock it away in the locker for the night."
_AWAY_IN52R = re.compiled(
    rf"^(?P<head>[^,;]+?)\s*,\s*(?P<cue>{_CUE51R})(?:lock|put|stick|pop|stash|tuck|shut|keep|"
    r"pack) (?:it|them)(?: away)? (?P<prep>in|into|on|onto|inside) (?P<s>the [a-z]+)(?: for the "
    r"night| overnight| for now| for later| for safekeeping| for the weekend)?(?P<end>\s*[.!]?)$",
    _F,
)


def _away_in52r(text: str, lexicon: Lexicon) -> str:
    """Session 52 (12r): a placing, a correction cue, then "lock it away in the locker (for the
    night)" is "<placing>, no, in the locker": the same thing placed there (how long it stays
    there is no other task)."""
    low = text.lower()
    if " it " not in low and " them " not in low:
        return text
    m = _AWAY_IN52R.match(text.strip())
    if m is None or not _BACK51R.search(m["cue"]):
        return text
    first = _one_task51r(f"{m['head']}.", lexicon)
    if first is None or first[0] != "place":
        return text
    prep = "on" if m["prep"].lower() in ("on", "onto") else "in"
    out = f"{m['head']}, no, {prep} {m['s']}{m['end'] or '.'}"
    got = _one_task51r(out, lexicon)
    if got is None or got[:2] != first[:2] or got == first:
        return text
    return out


# "…, oh hang on, I've muddled my names, Carol's the one who asked."
_WHO_ASKED52R = re.compiled(
    rf"(?P<p>{_P46R})(?:'s| is) the one (?P<who>who|that) (?P<did>asked|ordered|was asking|'s been "
    r"asking|has been asking|wanted|was after)(?P<end>\s*[.!]?)$",
    _F,
)
# the speaker owning a mix-up of names before the fix
_MUDDLED52R = re.compiled(
    rf"(?P<cue>,\s*{_CUE51R})(?:i've|i have|i) (?:muddled|mixed up|got muddled|got mixed up|"
    r"confused|mixed) (?:my|the) names(?: (?:up|again|there))?\s*,\s*",
    _F,
)


def _who_asked52r(text: str, lexicon: Lexicon) -> str:
    """Session 52 (12r): a correction closed by "P's the one who asked" (no 'for it') is "…, P's
    the one who asked for it" (session 51's `_the_one_is51r`), and "I've muddled my names"
    between the cue and the fix is taken off."""
    low = text.lower()
    if "the one" not in low or not _BACK51R.search(text):
        return text
    out = _MUDDLED52R.sub(lambda m: m["cue"].rstrip() + " ", text.strip())
    m = _WHO_ASKED52R.search(out)
    if m is not None and re.search(rf"\bnot {re.escape(m['p'])}\b", out[: m.start()], _F):
        return text  # "No, not Tom, Tom's the one who asked.": who is meant?
    if m is not None and _person46r(m["p"], lexicon) is not None:
        out = f"{out[: m.start('who')]}{m['who']} asked for it{m['end']}"
    return text if out == text.strip() else out


# -- blind50: whichever, one of, each ------------------------------------------------------------

# a share-out by a role the scene's people share, with the kind: "Each student gets a book:",
# "Both patients get a blanket,", "One blanket apiece for our two patients, so …"
_EACH_KIND52R = (
    re.compiled(
        r"^(?:each|every) (?P<role>[a-z]+) (?:gets|can have|is getting|receives|is to have) "
        r"(?:a|an|one) (?P<kind>[a-z]+)(?: each| apiece)?\s*[:,;]\s*(?:so\s+)?",
        _F,
    ),
    re.compiled(
        r"^(?:each of|both|all|all of) (?:the |our |both )?(?:two |three )?(?P<role>[a-z]+)s "
        r"(?:gets?|can have|are getting|receive|are to have) (?:a|an|one) (?P<kind>[a-z]+)"
        r"(?: each| apiece)?\s*[:,;]\s*(?:so\s+)?",
        _F,
    ),
    re.compiled(
        r"^(?:one|a|an) (?P<kind>[a-z]+) (?:apiece|each) for (?:our|the|both|both of our|both the|"
        r"all|all our|all the) (?:two |three )?(?P<role>[a-z]+)s\s*[:,;]\s*(?:so\s+)?",
        _F,
    ),
)
# a list item that is a bare colour: "red to Noah", "blue goes to Mr Lee"
_BARE52R = re.compiled(
    r"(?P<pre>^|[,;]\s*(?:and\s+)?|\band\s+)(?P<c>[a-z]+)(?= (?:to|for|goes to|going to|is for|"
    r"'s for)\b)",
    _F,
)


def _each_kind52r(text: str, lexicon: Lexicon) -> str:
    """Session 52 (12r): a share-out said by a role the scene's people share and the kind ("Each
    student gets a book: red to Noah, green to Zoe"; "One blanket apiece for our two patients,
    so blue goes to Mr Lee and the grey one's for Mrs Khan") is its list, a bare colour read as
    the thing of the kind ("the red book to Noah"): read only when the list hands one thing of
    the kind to each person of the role and to no one else."""
    low = text.lower()
    if "each" not in low and "both" not in low and "apiece" not in low and "every" not in low:
        return text
    body = text.strip()
    for rx in _EACH_KIND52R:
        m = rx.match(body)
        if m is not None:
            break
    else:
        return text
    kind = m["kind"]
    role = m["role"]
    people = _ids(role, lexicon, "human")
    kinds = _ids(kind, lexicon, "object")
    if len(people) < 2 or not kinds or _ids(role, lexicon) != people:
        return text

    def bare(b: re.Match[str]) -> str:
        said = f"the {b['c']} {kind}"
        one = _ids(said, lexicon, "object")
        return f"{b['pre']}{said}" if len(one) == 1 and one <= kinds else b.group(0)

    rest = _BARE52R.sub(bare, body[m.end() :])
    rest = rest[:1].upper() + rest[1:]
    node = _reading(rest, lexicon)
    if node is None or has_choice(node):
        return text
    got = list(tasks(node))
    if any(t.kind != "deliver" or t.obj not in kinds for t in got):
        return text
    if sorted(t.target for t in got) != sorted(people):
        return text
    return rest


# "Whichever of the two things you grab first, Person B gets it."
_GRAB_FIRST52R = re.compiled(
    r"^(?:whichever|whatever) (?:(?:one )?of (?P<of>the [a-z]+(?: [a-z]+)?)|(?P<x>[a-z]+)) you "
    r"(?:grab|pick up|get to|lay (?:your )?hands on|find|reach|come across|see|spot|get hold of)"
    rf" first\s*,\s*(?P<p>{_P46R}) (?:gets|can have|should get|is to have|'s to have|has|takes)"
    r" (?:it|that one|that)(?P<end>\s*[.!]?)$",
    _F,
)


def _grab_first52r(text: str, lexicon: Lexicon) -> str:
    """Session 52 (12r): "Whichever of the two things you grab first, P gets it" (whatever X you
    lay hands on first) leaves which to the robot: "Give P one of the two things" (either X),
    read only as a choice of things for that one person."""
    if "first" not in text.lower():
        return text
    m = _GRAB_FIRST52R.match(text.strip())
    if m is None:
        return text
    pid = _person46r(m["p"], lexicon)
    if pid is None:
        return text
    what = f"one of {m['of']}" if m["of"] else f"either {m['x']}"
    out = f"Give {m['p']} {what}{m['end'] or '.'}"
    node = _reading(out, lexicon)
    if node is None or not (isinstance(node, Group) and node.op == "or"):
        return text
    got = list(tasks(node))
    if any(t.kind != "deliver" or t.target != pid for t in got) or len(got) < 2:
        return text
    return out


# "One of them gets the bottle, whichever of the two is nearer you."
_ONE_OF_THEM52R = re.compiled(
    r"^one of (?:them|the two of them|those two|the pair of them|the two) (?P<v>gets|can have|"
    r"should get|is to get|is getting|has) (?P<x>the [a-z]+(?: [a-z]+)?)\s*,\s*whichever(?: of "
    r"(?:the two|them|the pair)| one)?(?: is|'s) (?:nearer|closer|nearest|closest|handier|easier"
    r"|easiest)(?: (?:to )?(?:you|the robot))?(?P<end>\s*[.!]?)$",
    _F,
)


def _one_of_them52r(text: str, lexicon: Lexicon) -> str:
    """Session 52 (12r): "One of them gets the bottle, whichever of the two is nearer you" in a
    scene of two people is "Either of them gets the bottle": the robot's choice of who (said by
    the 'whichever … nearer you')."""
    if "whichever" not in text.lower() or len(lexicon.scene.humans) != 2:
        return text
    m = _ONE_OF_THEM52R.match(text.strip())
    if m is None:
        return text
    out = f"Either of them {m['v']} {m['x']}{m['end'] or '.'}"
    node = _reading(out, lexicon)
    if node is None or not (isinstance(node, Group) and node.op == "or"):
        return text
    got = list(tasks(node))
    if len({t.obj for t in got}) != 1 or len({t.target for t in got}) != 2:
        return text
    return out


# -- blind50: counts and plurals -----------------------------------------------------------------

# a thing said in a list ("the cup", "bottle", "the black pen"), not running into the list's word
_THING52R = r"(?:the )?[a-z]+(?: (?!(?:along|together|with|and|plus|as|or)\b)[a-z]+)?"

# "…, just the one bag mind.": the count of one said again by its packaging
_ONE_BAG52R = re.compiled(
    r"\s*,\s*(?P<only>just|only) the one (?P<n>[a-z]+)(?:\s*,?\s*mind(?: you)?)?(?P<end>\s*[.!]?)$",
    _F,
)


def _one_bag52r(text: str, lexicon: Lexicon) -> str:
    """Session 52 (12r): a handover of one thing closed by "just the one bag (, mind)" (the one
    packet, roll, dose: a word naming nothing of the scene) is "…, just the one": the count of
    one said again."""
    if "the one" not in text.lower():
        return text
    m = _ONE_BAG52R.search(text.strip())
    if m is None or _names(m["n"], lexicon) or m["n"].lower() in _COUNTS52R:
        return text  # "his knife, just the one pair": a count of its own, not a packet
    out = f"{text.strip()[: m.start()]}, {m['only']} the one{m['end'] or '.'}"
    got = _one_task51r(out, lexicon)
    return out if got is not None and got[0] == "deliver" else text


# words that count things of their own ("just the one pair"): not a packet of the one thing
_COUNTS52R = frozenset({"pair", "set", "couple", "lot", "few", "dozen", "bunch", "load", "pack"})

# "the pair of drinking things, so that's the cup plus the bottle"
_PAIR_OF52R = re.compiled(
    r"\bthe (?P<n>pair|two|couple|three)(?: of)? (?P<desc>[a-z]+) things\s*,\s*(?:so\s+)?"
    r"(?:that's|that is|that'll be|meaning|i\.e\.)\s+"
    rf"(?P<x>{_THING52R})(?:\s*,\s*(?P<y>{_THING52R}))?\s+(?:plus|and|along with|with|as well "
    rf"as)\s+(?P<z>{_THING52R})(?P<end>\s*[.!]?)$",
    _F,
)
_COUNT52R = {"pair": 2, "two": 2, "couple": 2, "three": 3}
# what the description says of the things, by their categories (a closed list: a description
# not in it, or a thing not of it, is not read)
_DESC52R = {
    **dict.fromkeys(("drinking", "drink", "drinky"), KIND_CATEGORIES["drinks"]),
    **dict.fromkeys(("eating", "snack", "snacky", "food"), KIND_CATEGORIES["snacks"]),
    "writing": frozenset({"pen", "pencil", "marker", "crayon"}),
    "cutting": frozenset({"knife", "scissors"}),
}
# a want or a holding said in the past before the count ("Bob wanted the pair of …")
_PAST52R = re.compiled(
    r"\b(?:wanted|needed|asked for|was after|were after|had|got|took|was given|received)\b", _F
)


def _pair_of52r(text: str, lexicon: Lexicon) -> str:
    """Session 52 (12r): "the pair of drinking things, so that's the cup plus the bottle" names
    the things it counts: "the cup and the bottle" (read only when the things said are as many
    as the count, each one thing of the scene)."""
    if "things" not in text.lower():
        return text
    m = _PAIR_OF52R.search(text.strip())
    if m is None:
        return text
    kinds = _DESC52R.get(m["desc"].lower())
    if kinds is None or _PAST52R.search(text.strip()[: m.start()]):
        return text
    said = [w for w in (m["x"], m["y"], m["z"]) if w]
    ids = [_ids(w, lexicon, "object") for w in said]
    if len(said) != _COUNT52R[m["n"].lower()] or any(len(i) != 1 for i in ids):
        return text
    if len(set().union(*ids)) != len(said):
        return text
    cats = {o.id: o.category for o in lexicon.scene.objects}
    if any(cats[i] not in kinds for one in ids for i in one):
        return text
    things = [w if w.lower().startswith("the ") else f"the {w}" for w in said]
    listed = (
        " and ".join(things) if len(things) == 2 else f"{things[0]}, {things[1]} and {things[2]}"
    )
    out = f"{text.strip()[: m.start()]}{listed}{m['end'] or '.'}"
    node = _reading(out, lexicon)
    if node is None or has_choice(node) or len(list(tasks(node))) != len(said):
        return text
    return out


# "P can take the both of them off you, bottle along with the chips."
_BOTH_OFF52R = re.compiled(
    rf"^(?P<p>{_P46R}) (?:can|could|will|'ll) (?:take|have) (?:the )?both of them"
    r"(?: off (?:you|your hands))?"
    rf"\s*,\s*(?P<x>{_THING52R}) (?:along with|together with|and|with|plus|as well as) "
    rf"(?P<y>{_THING52R})(?P<end>\s*[.!]?)$",
    _F,
)


def _both_off52r(text: str, lexicon: Lexicon) -> str:
    """Session 52 (12r): "P can take the both of them off you, bottle along with the chips" is
    "Give P the bottle and the chips" (the two things said after it, each one of the scene)."""
    if "both of them" not in text.lower():
        return text
    m = _BOTH_OFF52R.match(text.strip())
    if m is None:
        return text
    pid = _person46r(m["p"], lexicon)
    x, y = (_ids(w, lexicon, "object") for w in (m["x"], m["y"]))
    if pid is None or len(x) != 1 or len(y) != 1 or x == y:
        return text
    things = [w if w.lower().startswith("the ") else f"the {w}" for w in (m["x"], m["y"])]
    out = f"Give {m['p']} {things[0]} and {things[1]}{m['end'] or '.'}"
    node = _reading(out, lexicon)
    got = [] if node is None else list(tasks(node))
    if len(got) != 2 or any(t.kind != "deliver" or t.target != pid for t in got):
        return text
    return out


# "The green cup and the white cup are both dirty from the tasting, put the pair in the sink."
_BOTH_STATE52R = re.compiled(
    r"^(?P<things>(?:the )?[a-z]+(?: [a-z]+)? and (?:the )?[a-z]+(?: [a-z]+)?) are both "
    r"(?P<why>[^,;.]+?)\s*[,;]\s*(?:so\s+)?(?P<v>put|pop|stick|place|set|leave|pile) (?:the pair|"
    r"the two(?: of them)?|them(?: both)?|both(?: of them)?|the both of them|the lot)\s+(?P<where>"
    r"(?:in|on|into|onto) the [a-z]+)(?P<end>\s*[.!]?)$",
    _F,
)


def _both_state52r(text: str, lexicon: Lexicon) -> str:
    """Session 52 (12r): "X and Y are both dirty (from the tasting), put the pair in the sink"
    is "Put X and Y in the sink": the state (naming nothing else of the scene) says why."""
    if " both " not in text.lower():
        return text
    m = _BOTH_STATE52R.match(text.strip())
    if m is None:
        return text
    why = re.sub(r"\b(?:[a-z]+)'s\b", "", m["why"], flags=_F)
    if _names(why, lexicon) or _names(m["why"], lexicon) or _NOT52R.search(m["why"]):
        return text
    put = _put_pair52r(m, lexicon)
    return text if put is None else put[0]


def _put_pair52r(m: re.Match[str], lexicon: Lexicon) -> tuple[str, set[str]] | None:
    """The rewrite "Put <things> <where>" of ``m`` (groups ``things``, ``where``, ``end``) and
    the two things it places, when it reads as two placings of two things; else None. Shared by
    `_both_state52r` and session 53's `_had_lot53r`."""
    things = m["things"][:1].lower() + m["things"][1:]
    out = f"Put {things} {m['where']}{m['end'] or '.'}"
    node = _reading(out, lexicon)
    got = [] if node is None else list(tasks(node))
    if len(got) != 2 or any(t.kind != "place" for t in got) or len({t.obj for t in got}) != 2:
        return None
    return out, {t.obj for t in got}


_NOT52R = re.compiled(r"\b(?:not|n't|never|no)\b", _F)

# "…, the oenologist's tasting needs the table."
_NEEDS_THE52R = re.compiled(
    r"\s*[,;]\s*(?P<who>(?:the |our |my )?[a-z]+(?:'s)?(?: [a-z]+){0,2}) (?:needs|wants|is "
    r"using|will need|'ll need|has booked|is having) (?P<s>the [a-z]+)(?: (?:for|at) [a-z' ]+)?"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _needs_the52r(text: str, lexicon: Lexicon) -> str:
    """Session 52 (12r): placings closed by "the oenologist's tasting needs the table" (someone
    or something that is no one of the scene needing a surface the things are not put on: why
    they are moved) have the remark taken off."""
    low = text.lower()
    if not any(w in low for w in ("needs the", "wants the", "using the", "need the", "booked the")):
        return text
    m = _NEEDS_THE52R.search(text.strip())
    if m is None:
        return text
    sid = one_surface51r(m["s"], lexicon)
    if sid is None:
        return text
    who = re.sub(r"\b(?:the|our|my)\b", "", m["who"], flags=_F)
    if _names(who, lexicon) or _NOT52R.search(m["who"]):
        return text
    return placed_elsewhere51r(text, m, sid, lexicon)


# "Give each of them something to eat: …"
_GIVE_EACH52R = re.compiled(
    r"^(?:give|hand|pass|pass out|hand out|share out) (?P<who>each of them|both of them|the two of"
    r" them|each of you|them each|them both) (?P<what>one thing|something|an item|a thing)"
    r"(?P<to> to (?:eat|drink|use|read|play with))?\s*(?P<sep>[:,])\s*",
    _F,
)


def _give_each52r(text: str, lexicon: Lexicon) -> str:
    """Session 52 (12r): "Give each of them something to eat: apple for P, chips for Q" is
    session 33's share-out header "Each of them gets something to eat: …" (its count check:
    one thing to every person of the scene)."""
    if "each" not in text.lower() and "both" not in text.lower():
        return text
    m = _GIVE_EACH52R.match(text.strip())
    if m is None:
        return text
    who = m["who"].lower()
    if who in ("them each", "each of you"):
        who = "each of them"
    elif who == "them both":
        who = "both of them"
    verb = "get" if who.startswith("both") or who.startswith("the two") else "gets"
    out = f"{who[:1].upper()}{who[1:]} {verb} {m['what']}{m['to'] or ''}{m['sep']} "
    out += text.strip()[m.end() :]
    node = _reading(out, lexicon)
    got = [] if node is None else list(tasks(node))
    humans = sorted(h.id for h in lexicon.scene.humans)
    if node is None or has_choice(node) or sorted(t.target for t in got) != humans:
        return text
    return out if all(t.kind == "deliver" for t in got) else text


# -- blind50: more choices and counts ------------------------------------------------------------

# "that bottle's going to Person A in the end"
_IN_THE_END52R = re.compiled(
    rf"\b(?P<v>(?:is|'s|are|'re) going|goes|go|will go|'ll go) to (?P<p>{_P46R})"
    r"(?P<end> in the end| eventually| at the end of the day| when all's said and done)\b",
    _F,
)


def _in_the_end52r(text: str, lexicon: Lexicon) -> str:
    """Session 52 (12r): "that bottle's going to P in the end" (eventually, at the end of the day)
    says where it goes, not when: "… going to P" (read only as handovers)."""
    low = text.lower()
    if " end" not in low and "eventually" not in low and "said and done" not in low:
        return text
    m = _IN_THE_END52R.search(text)
    if m is None or _person46r(m["p"], lexicon) is None:
        return text
    out = f"{text[: m.start('end')]}{text[m.end('end') :]}"
    node = _reading(out, lexicon)
    if node is None or any(t.kind != "deliver" for t in tasks(node)):
        return text
    return out


# "Whatever bottle's knocking about, …"
_KNOCKING52R = re.compiled(
    r"^(?:whatever|whichever|any) (?P<x>[a-z]+)(?:'s| is) (?:knocking|lying|kicking|hanging|"
    r"floating|sitting) (?:about|around)(?: (?:here|in here|the place))?\s*,\s*",
    _F,
)


def _knocking52r(text: str, lexicon: Lexicon) -> str:
    """Session 52 (12r): "Whatever bottle's knocking about, let P have it" (lying around) is
    "Any bottle, let P have it": any one of the kind (read only as handovers)."""
    if "about" not in text.lower() and "around" not in text.lower():
        return text
    m = _KNOCKING52R.match(text.strip())
    if m is None or not _ids(m["x"], lexicon, "object") or _ids(m["x"], lexicon, "human"):
        return text
    out = f"Any {m['x']}, {text.strip()[m.end() :]}"
    node = _reading(out, lexicon)
    if node is None or any(t.kind != "deliver" for t in tasks(node)):
        return text
    return out


# "every one of the four things"
_EVERY_ONE52R = re.compiled(
    r"\bevery (?:single )?one of the (?P<n>two|three|four|five|six) (?P<x>[a-z]+s)\b", _F
)


def _every_one52r(text: str, lexicon: Lexicon) -> str:
    """Session 52 (12r): "every one of the four things" is "all four things" ("both" for two):
    the count check of the older rules then asks the scene."""
    if "every" not in text.lower():
        return text
    m = _EVERY_ONE52R.search(text)
    if m is None:
        return text
    n = m["n"].lower()
    said = f"both {m['x']}" if n == "two" else f"all {n} {m['x']}"
    out = f"{text[: m.start()]}{said}{text[m.end() :]}"
    return out if _reading(out, lexicon) is not None else text


# "Only the one bottle here and only Person A to give it to, so do that."
_ONLY_ONE52R = re.compiled(
    r"^(?:there's )?(?:(?:only|just) the one|(?:only|just) one|a|one|a single|a lone) "
    r"(?P<x>[a-z]+(?: (?!(?:here|in|going|about|and)\b)[a-z]+)?)(?: here| in here| going| about)?"
    rf"\s*,?\s*and (?:only|just) (?P<p>{_P46R}) to (?:give|hand|pass|take) it to"
    r"(?:\s*,?\s*so (?:do that|go on|go ahead|off you go|get to it|crack on))?(?P<end>\s*[.!]?)$",
    _F,
)


def _only_one52r(text: str, lexicon: Lexicon) -> str:
    """Session 52 (12r): "Only the one bottle here and only Person A to give it to, so do that"
    is "Give Person A the bottle" (the thing the scene's one of its kind)."""
    if " to " not in text.lower() or "it to" not in text.lower():
        return text
    m = _ONLY_ONE52R.match(text.strip())
    if m is None or _person46r(m["p"], lexicon) is None:
        return text
    if len(_ids(m["x"], lexicon, "object")) != 1 or _ids(m["x"], lexicon, "human"):
        return text
    out = f"Give {m['p']} the {m['x']}{m['end'] or '.'}"
    got = _one_task51r(out, lexicon)
    return out if got is not None and got[0] == "deliver" else text


# "There's a single cup, which is Person A's, and a single apple, which Person B can have."
_SINGLE_WHICH52R = re.compiled(
    r"(?:^there's |^there is |(?<=, )and |(?<=; )and |(?<=, )|(?<=; ))(?:a single|one|a lone|"
    r"just the one|the one) (?P<x>[a-z]+(?: [a-z]+)?), which (?:(?P<c>is|'s) (?P<p>"
    rf"{_P46R})'s|(?P<q>{_P46R}) (?P<v>can have|gets|is getting|can take|should get|'s to have|"
    r"is to have))(?=\s*(?:[,;.!]|$))",
    _F,
)


def _single_which52r(text: str, lexicon: Lexicon) -> str:
    """Session 52 (12r): "There's a single cup, which is Person A's, and a single apple, which
    Person B can have" hands each out: "the cup to Person A, and the apple to Person B" (each
    thing the scene's one; at least one clause says who gets it, not only whose it is)."""
    low = text.lower()
    if "which" not in low or ("single" not in low and "one" not in low and "lone" not in low):
        return text
    parts = []
    last = 0
    gets = False
    for m in _SINGLE_WHICH52R.finditer(text.strip()):
        who = m["p"] or m["q"]
        if _person46r(who, lexicon) is None or len(_ids(m["x"], lexicon, "object")) != 1:
            return text
        gets = gets or m["q"] is not None
        lead = "and " if m.group(0).lower().startswith("and ") else ""
        parts.append(f"{text.strip()[last : m.start()]}{lead}the {m['x']} to {who}")
        last = m.end()
    if not parts or not gets:
        return text
    out = "".join(parts) + text.strip()[last:]
    out = out[:1].upper() + out[1:]
    node = _reading(out, lexicon)
    if node is None or has_choice(node) or any(t.kind != "deliver" for t in tasks(node)):
        return text
    return out


# "Sweep the whole lot of pens, black, blue and red, into the box"
_WHOLE_LOT52R = re.compiled(r"\bthe (?:whole|entire) lot of (?P<x>[a-z]+s)\b", _F)
_SWEEP52R = re.compiled(
    r"^(?P<v>sweep|scoop|gather|bundle|tip|chuck|round up|collect) (?=(?:up )?(?:all |both |the ))",
    _F,
)


def _whole_lot52r(text: str, lexicon: Lexicon) -> str:
    """Session 52 (12r): "the whole lot of pens" is "all the pens"; a placing said with "sweep"
    (scoop, gather, bundle, tip, round up) the things "into the box" is "put": read only as
    placings."""
    low = text.lower()
    if "lot of" not in low and not _SWEEP52R.match(text.strip()):
        return text
    out = _WHOLE_LOT52R.sub(lambda m: f"all the {m['x']}", text.strip())
    v = _SWEEP52R.match(out)
    if v is not None:
        out = "Put " + re.sub(r"^up ", "", out[v.end() :], flags=_F)
    if out == text.strip():
        return text
    node = _reading(out, lexicon)
    if node is None or any(t.kind != "place" for t in tasks(node)):
        return text
    return out


# "Mia told me one of the boxes goes to Tom but I never noted down which."
_NEVER_NOTED52R = re.compiled(
    r"\bone of the (?P<x>[a-z]+s)\b[^.?!;]*?(?:,|\bbut|\band)\s*(?:i )?(?:never "
    r"(?:noted|wrote|jotted|took|caught|heard)|didn't (?:note|write|jot|catch|hear)|forgot to "
    r"(?:note|write|ask))(?: down| in)? which\b",
    _F,
)


def _never_noted52r(text: str, lexicon: Lexicon) -> None:
    """Session 52 (12r): "one of the boxes goes to Tom but I never noted down which" (didn't
    catch which) does not say which: refused, naming each thing of the kind (the speaker does
    not know; not the robot's choice)."""
    if "which" not in text.lower():
        return
    m = _NEVER_NOTED52R.search(text)
    if m is None or re.search(r"\b(?:not|except|apart|other than|or)\b", m.group(0), _F):
        return  # "one of the pens, not the blue, …", "…, white or blue, …": the older refusals'
    ids = sorted(_ids(m["x"], lexicon, "object"))
    if len(ids) < 2 or _ids(m["x"], lexicon, "human"):
        return
    raise GroundingError(
        f"{m.group(0).strip()!r}: which of the {m['x']} is meant is not said; it could be "
        f"{' or '.join(ids)}: name the one"
    )


# "Person B said he wanted the chips, or was it the cup? I was only half listening."
_OR_WAS_IT52R = re.compiled(
    r"(?P<x>(?:the |a )?[a-z]+(?: [a-z]+)?)\s*,\s*or (?:was|is) it (?P<y>(?:the |a )?[a-z]+"
    r"(?: [a-z]+)?)\s*\?(?P<rest>.*)$",
    _F,
)


def _or_was_it52r(text: str, lexicon: Lexicon) -> None:
    """Session 52 (12r): "…the chips, or was it the cup?" (the Y said as the speaker's doubt, and
    nothing after naming a thing of the scene) leaves which open: refused, naming both."""
    if "or was it" not in text.lower() and "or is it" not in text.lower():
        return
    m = _OR_WAS_IT52R.search(text.strip())
    if m is None or _names(m["rest"], lexicon):
        return
    x, y = _names(m["x"], lexicon), _names(m["y"], lexicon)
    if len(x) != 1 or len(y) != 1:
        return
    xs, ys = {r.id for r in x[0].refs}, {r.id for r in y[0].refs}
    if len(xs) != 1 or len(ys) != 1 or xs == ys:
        return
    kinds = {x[0].refs[0].kind, y[0].refs[0].kind}
    if kinds == {"human"}:
        said = " or ".join(person_name(i, lexicon) for i in (*xs, *ys))
    elif kinds == {"object"}:
        said = " or ".join(f"the {i}" for i in (*xs, *ys))
    else:
        return
    raise GroundingError(
        f"{m.group(0).strip()!r}: the speaker does not know which is meant, {said}; say which"
    )


# "…, to one of the girls, which one did he say?"
_ONE_OF_THE_GIRLS52R = re.compiled(
    r"\bone of the (?P<g>girls|women|ladies|boys|men|lads|gents)\b(?P<rest>[^.!?]*?)\s*,?\s*"
    r"(?:which (?:one|of them|of the two)? ?(?:did (?:he|she|they) say|was it|did (?:he|she|they) "
    r"mean)\s*\?|i (?:forget|can't remember|don't know|never caught) which(?: one)?\s*[.!]?)",
    _F,
)


def _one_of_the_girls52r(text: str, lexicon: Lexicon) -> None:
    """Session 52 (12r): "…, to one of the girls, which one did he say?" (one of the women, the
    boys: I forget which) does not say who: refused, naming the people of the scene 'she' (or
    'he') fits."""
    low = text.lower()
    if "one of the" not in low or "which" not in low:
        return
    m = _ONE_OF_THE_GIRLS52R.search(text)
    if m is None:
        return
    pro = "she" if m["g"].lower() in ("girls", "women", "ladies") else "he"
    who = [h.id for h in lexicon.scene.humans if _agrees44r(h.id, pro, lexicon)]
    if len(who) < 2:
        return
    said = " or ".join(person_name(i, lexicon) for i in who)
    raise GroundingError(
        f"'one of the {m['g']}' does not say which: it could mean {said}; name the person"
    )


# "…, put the pair on the shelf, Bob's done it.": the request said as done
_DONE_IT52R = re.compiled(
    rf"[,;.]\s*(?P<who>{_P46R}|she|he|they)(?:'s| has| have|'ve)(?: already| just)? (?:done|"
    r"sorted|seen to|dealt with) (?:it|them|that|those|the lot)(?: already)?\s*[.!]?\s*$",
    _F,
)


def _done_it52r(text: str, node: Node, lexicon: Lexicon) -> None:
    """Session 52 (12r): a request closed by "Bob's done it" (has sorted it, seen to them) is
    said as done: a reading of it is refused (session 44's `_done_with44s` takes "done it" off
    as "done with it", which says why things are put away; 12c's probe)."""
    low = text.lower()
    if "done" not in low and "sorted" not in low and "seen to" not in low and "dealt" not in low:
        return
    m = _DONE_IT52R.search(text)
    if m is None:
        return
    who = m["who"]
    if who.lower() not in ("she", "he", "they") and _person46r(who, lexicon) is None:
        return
    raise GroundingError(
        f"{m.group(0).strip(' ,;.')!r} says it is done already: it asks for nothing; say what "
        "is still to do"
    )


# "…, oh hang on, Carol's the one who had it." / "…, Carol's the one who asked for the cup."
_ONE_WHO52R = re.compiled(
    rf"[,;.]\s*(?:{_CUE51R})?(?P<p>{_P46R})(?:'s| is) the one (?:who|that)(?:'s| has| had)? "
    r"(?P<v>had|has|got|took|taken|asked for|wanted|wants|needs|ordered)(?: got)? (?P<x>it|them|"
    r"(?:the|a|an) [a-z]+(?: [a-z]+)?)\s*[.!]?\s*$",
    _F,
)


def _one_who52r(text: str, lexicon: Lexicon) -> None:
    """Session 52 (12r): a correction closed by "P's the one who had it" (has it, took it: P
    holds it already) or "P's the one who asked for the cup" (another thing than the request's:
    is the cup added, or does it replace the apple?) leaves what to do open: refused."""
    low = text.lower()
    if "the one" not in low or not _BACK51R.search(text):
        return
    m = _ONE_WHO52R.search(text)
    if (
        m is None
        or _person46r(m["p"], lexicon) is None
        or not _BACK51R.search(text[: m.start("p")])
    ):
        return
    v = m["v"].lower().split()[-1]
    if v in ("had", "has", "got", "took", "taken"):
        raise GroundingError(
            f"'{m['p']}'s the one who {m['v']} {m['x']}' says {m['p']} holds it already: say who "
            "is to get it"
        )
    x = m["x"].lower()
    if x in ("it", "them"):
        return
    head = {
        r.id for it in _names(text[: m.start()], lexicon) for r in it.refs if r.kind == "object"
    }
    said = _ids(m["x"], lexicon, "object")
    if said and head and not said <= head:
        raise GroundingError(
            f"'{m['p']}'s the one who {m['v']} {m['x']}' names another thing than the request: "
            "is it added, or instead? Say the whole request again"
        )


# the normaliser's first rewrites (wired into normalise._STEPS19, before the session-51 ones)
_STEPS52R_FIRST: tuple[Callable[[str, Lexicon], str], ...] = ()
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-51 ones)
_STEPS52R: tuple[Callable[[str, Lexicon], str], ...] = (
    _meant_mine52r,
    _filler_fix52r,
    _vague_to52r,
    _said_fix52r,
    _meant_to_say52r,
    _left_out52r,
    _away_in52r,
    _who_asked52r,
    _each_kind52r,
    _grab_first52r,
    _one_of_them52r,
    _one_bag52r,
    _pair_of52r,
    _both_off52r,
    _both_state52r,
    _needs_the52r,
    _give_each52r,
    _in_the_end52r,
    _knocking52r,
    _every_one52r,
    _only_one52r,
    _single_which52r,
    _whole_lot52r,
)
# refusals asked of the text before it is read (offline._parse, after the session-51 ones)
REFUSE52R: tuple[Callable[[str, Lexicon], None], ...] = (
    _too_after52r,
    _or_was_it52r,
    _one_of_the_girls52r,
    _never_noted52r,
    _one_who52r,
)
# checks of the whole instruction's reading (offline.parse_instruction, after the session-51 ones)
CHECK52R: tuple[Callable[[str, Node, Lexicon], None], ...] = (_done_it52r,)
