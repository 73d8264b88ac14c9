"""The grounder's rules of session 56, engineer 12s (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _ids, _names, _objects_only, _only_person, _reading
from hltl.grounding._rewrites44r import _read_without44r
from hltl.grounding._rewrites51s import _plain51s
from hltl.grounding._rewrites53s import _UNSAFE53S, _WHO53S
from hltl.grounding._rewrites55s import _BE55S, _DET55S, _STATE55S
from hltl.grounding.lexicon import PRONOUN_SEX, Lexicon, unnamed_sex44l
from hltl.grounding.tree import Node, Task, tasks

# a holding said of someone ('Alice has the bottle', "she's got it", 'holding'): the rules that
# drop or restate a clause beside a request leave such a text as it was (12c: "Alice has the
# bottle, and no, she doesn't want anything else." was read bottle>A)
_HOLDS56S = re.compiled(
    r"\b(?:has|have|'s got|'ve got|got|hold|holds|holding|keeps|kept|had)\b", _F
)
# a thing said as given already ('I gave it him', 'handed over', 'sent'): the same rules leave a
# text holding one of these as it was (the refusals of a done request are asked of the text as
# said, not of a rule's restatement of it)
_DONE56S = re.compiled(
    r"\b(?:gave|given|handed|passed|brought|took|taken|sent|delivered|done|already|dropped)\b", _F
)


# -- session 56 (12s): where a thing is, beside a request for another thing ---------------------
#
# "The apple's on the shelf, give Bob the cup." read `apple@shelf & cup>B` (12c, session 55's
# doubtful): the grammar reads a goal said as a state ("The apple is on the shelf." is a placing,
# session 51), so a state clause beside a request placed the thing. Beside a request for another
# thing, with no order between them, 'the X's / is / are (still / up / sat …) on the S' says where
# the X is as often as where it goes ("The apple is still on the shelf, so give Bob the cup.",
# "Give Bob the cup, the apple's on the shelf."): such a reading is refused. Session 55's
# `_where_is55s` refuses it beside another task on the same X. Read as before: the state alone,
# two states ("The apple's on the shelf and the cup's on the table."), an order ('Once the X is on
# the S, …', '…, then …'), a placing said with its verb or verbless ('The apple on the shelf, the
# cup to Bob.').


def _states56s(text: str, lexicon: Lexicon) -> set[tuple[str, str]]:
    """The (object, surface) pairs of the state clauses 'the X's / is / are … on the S' in
    ``text`` (a verb 'be' said; the X one thing's name alone)."""
    out: set[tuple[str, str]] = set()
    for m in _STATE55S.finditer(text):
        if not m["be"]:
            continue  # 'The apple on the shelf, …': verbless, a placing asked for
        named = _names(m["x"], lexicon)
        said = m["x"].lower().split(" ", 1)
        bare = said[1] if said[0] in _DET55S and len(said) > 1 else m["x"].lower()
        if len(named) != 1 or named[0].text.lower() != bare or not _objects_only(bare, lexicon):
            continue
        xs, ss = _ids(m["x"], lexicon), _ids(m["s"], lexicon, "surface")
        out.update((x, s) for x in xs for s in ss)
    return out


def _beside56s(node: Node, states: set[tuple[str, str]]) -> Task | None:
    """A placing of ``states`` in ``node`` beside (an ``and`` / ``or``, no order) a task that is
    no such placing."""
    if isinstance(node, Task):
        return None
    for c in node.children:
        found = _beside56s(c, states)
        if found is not None:
            return found
    if node.op == "seq":
        return None
    per = [list(tasks(c)) for c in node.children]
    for i, mine in enumerate(per):
        said = [t for t in mine if t.kind == "place" and (t.obj, t.target) in states]
        if not said:
            continue
        for j, theirs in enumerate(per):
            if j != i and any(u.kind != "place" or (u.obj, u.target) not in states for u in theirs):
                return said[0]
    return None


def _where_is56s(text: str, node: Node, lexicon: Lexicon) -> None:
    """Session 56 (12s): where a thing is, beside a request for another thing (above)."""
    if isinstance(node, Task):
        return
    low = text.lower()
    if not any(w in low for w in _BE55S):
        return
    if not any(t.kind == "place" for t in tasks(node)):
        return
    states = _states56s(text, lexicon)
    if not states:
        return
    t = _beside56s(node, states)
    if t is not None:
        raise GroundingError(
            f"'the {t.obj} … on the {t.target}' may say where the {t.obj} is, not where it goes, "
            f"beside the rest of the request: say 'put the {t.obj} on the {t.target}' to have it "
            "placed, or ask only for the rest"
        )


# -- session 56 (12s): 'Give Bob the red mug, not Alice, the blue.' ---------------------------
#
# read `mug_red>B & mug_blue>B` (12c, session 55's doubtful): ', not P,' set against the person of
# the request, then a thing with no verb or person of its own: the thing may be P's instead ("not
# Alice — (she gets) the blue"), or the request's person's too; the robot may not pick. Refused
# when P is a person of the scene and the thing after it names objects only, closing the text
# ('please / thanks / cheers' may follow), after a request that named a thing. Read as before:
# ', not Alice.' at the end, 'not Alice, Bob' (a correction of the person), 'not the blue' (an
# object left out), 'Give Bob, not Alice, the red mug.' (the request's own thing).
_THING_WORDS56S = frozenset({"one", "other", "ones", "others"})
_NOT_P_THEN56S = re.compiled(
    r",\s*not (?:to |for )?(?P<p>(?:person [a-z]|(?:mr|mrs|ms|miss|dr) [a-z]+|[a-z]+))\s*[,;:—–-]"
    r"\s*(?:and |but |just |only )?(?P<y>(?:the|a|an|that|this|those|these|his|her) "
    r"(?:[a-z]+ ){0,2}?[a-z]+)(?:,? (?:please|thanks|cheers|ta))?\s*[.!]?\s*$",
    _F,
)


def _not_p_then56s(text: str, lexicon: Lexicon) -> None:
    """Session 56 (12s): ', not P, the Y' closing a request (above)."""
    if "not " not in text.lower():
        return
    m = _NOT_P_THEN56S.search(text)
    if (
        m is None
        or not _ids(m["p"], lexicon, "human")
        or _ids(m["p"], lexicon) - _ids(m["p"], lexicon, "human")
    ):
        return
    if not _ids(text[: m.start()], lexicon, "object"):
        return  # 'Give Bob, not Alice, the red mug.': the thing of the request itself
    y = m["y"]
    bare = y.split(" ", 1)[1].lower()
    if _names(y, lexicon):
        if not _objects_only(y, lexicon):
            return  # 'not Alice, the chef': a person or a place
    elif not set(bare.split()) <= _THING_WORDS56S | {
        w.lower()
        for o in lexicon.scene.objects
        for n in (o.id.replace("_", " "), *o.aliases)
        for w in n.split()
    }:
        return  # 'not Alice, the poor thing': no thing of the scene
    raise GroundingError(
        f"'not {m['p']}, {y}' may say {m['p']} is not to get {y} (someone else is), or that the "
        "request's person gets it too: say who gets each thing"
    )


# -- session 56 (12s): 'P's (gone) off the X, give her the Y' -----------------------------------
#
# "Person A's off the chips this week, just give her the bottle." and "Lena's gone off the white
# plate for some reason, bring her the blue one instead." (blind54 #127 #136): a person 'off' a
# thing (not wanting it now), then a request: said "P doesn't want the X, …", which session 39's
# rules read; a time or reason right after the thing ('this week', 'today', 'for some reason', 'at
# the moment', 'lately') is the speaker's context, read as now, and dropped. P one person named
# (not a pronoun: a remark closing a request, "…, she's off salt", is left as it was); the X one
# thing or kind of the scene, named whole; the reading must hand the X to no one; nothing that
# says a holding or a doing (session 53's `_UNSAFE53S`). 'off to / off for / off home' are no
# such clause.
_OFF_THE56S = re.compiled(
    rf"^(?P<p>{_WHO53S})(?:'s| is| has)(?: (?:gone|gone right|really|a bit|totally|properly))? "
    r"off (?:the |her |his |their )?(?P<x>[a-z]+(?: [a-z]+)??)(?: (?:this week|today|at the "
    r"moment|for now|lately|these days|for some reason|right now|for the moment|for a bit|for a "
    r"while))?(?P<rest>\s*[,;]\s*(?:so |and |but |just |only )?\S.*)$",
    _F,
)


def _off_the56s(text: str, lexicon: Lexicon) -> str:
    """Session 56 (12s): "P's (gone) off the X, give her the Y" said "P doesn't want the X, …"
    (above)."""
    if " off " not in text.lower():
        return text
    if _DONE56S.search(text):
        return text
    if text.rstrip().endswith("?") or _UNSAFE53S.search(text) or _HOLDS56S.search(text):
        return text
    m = _OFF_THE56S.match(text.strip())
    if m is None or not _only_person(m["p"], lexicon):
        return text
    x = _ids(m["x"], lexicon)
    named = _names(m["x"], lexicon)
    if not x or x != _ids(m["x"], lexicon, "object") or len(named) != 1:
        return text
    if named[0].text.lower() != m["x"].lower():
        return text  # 'off the teddy box': not the thing named whole
    if _PAST56S.search(m["rest"]):
        return text  # a past want after it is left as it was
    out = f"{m['p']} doesn't want the {m['x']}{m['rest']}"
    if _read_without44r(out, text, m["x"], lexicon) == text:
        return text
    return _plain51s(out, text, lexicon)


# -- session 56 (12s): 'The X's not for P, it's for Q, take it to him.' ------------------------
#
# blind54 #121: who a thing is not for, who it is for, then the request for it to 'him / her':
# the pronoun stands for Q, the person it is for (P is the one it is not for). Said "The X isn't
# for P, it's for Q.", which the grammar reads. The pronoun of Q's sex by the scene (a title, a
# word of kin, a first name, the corpus's 'Person A / B'), or Q's sex unknown and P's the other;
# 'them' for either; P and Q one person each, apart; the X one thing; nothing after but 'please'.
_NOT_FOR_TAKE56S = re.compiled(
    r"^(?P<head>(?:the|that|this) (?P<x>[a-z]+(?: [a-z]+)?)(?:'s not| is not| isn't) (?:meant |"
    rf"intended )?for (?P<p>{_WHO53S})\s*[,;]\s*(?:it's|it is) (?:meant |intended |actually |"
    rf"really )?for (?P<q>{_WHO53S}))\s*[,;]\s*(?:so |and |just )?(?:give|take|hand|pass|bring|"
    r"run|carry) it(?: (?:over|across|along|round))?(?: to)? (?P<pro>him|her|them)(?:,? please)?"
    r"(?P<end>\s*[.!]?)$",
    _F,
)


def _not_for_take56s(text: str, lexicon: Lexicon) -> str:
    """Session 56 (12s): "The X's not for P, it's for Q, take it to him." said "The X isn't for
    P, it's for Q." (above)."""
    if "for " not in text.lower():
        return text
    if _DONE56S.search(text):
        return text
    m = _NOT_FOR_TAKE56S.match(text.strip())
    if m is None or not _only_person(m["p"], lexicon) or not _only_person(m["q"], lexicon):
        return text
    (p,), (q,) = _ids(m["p"], lexicon), _ids(m["q"], lexicon)
    if p == q or len(_ids(m["x"], lexicon, "object")) != 1:
        return text
    pro = m["pro"].lower()
    if pro != "them":
        sex = PRONOUN_SEX[pro]
        said_q, said_p = unnamed_sex44l(q, lexicon), unnamed_sex44l(p, lexicon)
        if said_q != sex and not (said_q is None and said_p not in (None, sex)):
            return text
    out = f"{m['head']}{m['end'] or '.'}"
    return _plain51s(out, text, lexicon)


# -- session 56 (12s): '…, and no, she doesn't want anything else.' ----------------------------
#
# blind54 #130 "Person A wants the bottle, and no, she doesn't want anything else.": a closing
# clause that the one person of the request wants nothing more is "…, and nothing else", which
# the grammar reads. The request before it names one person, whom the he / she may be (the scene
# says no other sex) or whom it names again; nothing after but 'thanks / at all'; not after a
# past want ('Bob wanted the apple, …') or a holding ('Alice has the bottle, …', 12c; session 53's
# `_UNSAFE53S`).
_NOTHING_ELSE56S = re.compiled(
    r"^(?P<head>.+?)\s*[,;]\s*(?:and |but )?(?:no\s*,?\s*)?(?P<pro>he|she|they|"
    r"(?:person [a-z]|(?:mr|mrs|ms|miss|dr) [a-z]+|[a-z]+)) (?:doesn't|does not|don't|do not) "
    r"(?:want|need) (?:anything|owt|a thing) else(?: (?:at all|thanks|though))?(?P<end>\s*[.!]?)$",
    _F,
)

_PAST56S = re.compiled(
    r"\b(?:wanted|needed|asked|fancied|liked|was|were|did|used to|would have|'d have)\b", _F
)


def _nothing_else56s(text: str, lexicon: Lexicon) -> str:
    """Session 56 (12s): "…, and no, she doesn't want anything else." said "…, and nothing
    else." (above)."""
    if " else" not in text.lower():
        return text
    if _DONE56S.search(text):
        return text
    m = _NOTHING_ELSE56S.match(text.strip())
    if m is None:
        return text
    if _PAST56S.search(m["head"]) or _UNSAFE53S.search(m["head"]) or _HOLDS56S.search(m["head"]):
        return text  # 'Bob wanted the apple, …': a past want is left as it was
    people = _ids(m["head"], lexicon, "human")
    if len(people) != 1:
        return text
    (p,) = people
    pro = m["pro"].lower()
    if pro in PRONOUN_SEX:
        if unnamed_sex44l(p, lexicon) not in (None, PRONOUN_SEX[pro]):
            return text
    elif pro == "they" or _ids(m["pro"], lexicon) != {p}:
        return text
    out = f"{m['head']}, and nothing else{m['end']}"
    node = _reading(out, lexicon)
    if node is None or any(t.target != p for t in tasks(node)):
        return text
    return _plain51s(out, text, lexicon)


# -- session 56 (12s): 'Give the chips to anyone but Person A.' --------------------------------
#
# blind54 #128: in a scene of two people, 'to anyone / anybody / someone (else) but / except /
# other than / apart from / bar P' (closing its clause) and 'give anyone but P the X' are the
# other person (session 35's `_whoever_not35r` reads 'to whoever isn't P' so). With more people it
# is left (and refused); not after a negation of the request ("Don't give the chips to anyone but
# Person A.").
_ANYONE_BUT56S = re.compiled(
    r"\b(?:(?P<to>to )|(?P<v>give|hand|pass|bring|take) )(?:anyone|anybody|someone|somebody)"
    r"(?: else)? (?:but|except|other than|apart from|bar|besides|save) (?P<p>person [a-z]|"
    r"(?:mr|mrs|ms|miss|dr) [a-z]+|[a-z]+)(?(to)(?=\s*(?:[,;.!]|$))|"
    r"(?= (?:the|a|an|that|this|those|these) ))",
    _F,
)
_NOT_BEFORE56S = re.compiled(r"\b(?:don't|do not|never|not|mustn't|shouldn't|can't|no)\b", _F)


def _anyone_but56s(text: str, lexicon: Lexicon) -> str:
    """Session 56 (12s): 'to anyone but P' in a scene of two people is 'to' the other (above)."""
    low = text.lower()
    if "any" not in low and "some" not in low:
        return text
    if _DONE56S.search(text):
        return text
    people = lexicon.scene.humans
    if len(people) != 2:
        return text
    if _HOLDS56S.search(text) or _UNSAFE53S.search(text):
        return text
    m = _ANYONE_BUT56S.search(text)
    if m is None or not _only_person(m["p"], lexicon) or _NOT_BEFORE56S.search(text[: m.start()]):
        return text
    (said,) = _ids(m["p"], lexicon)
    other = next(h for h in people if h.id != said)
    head = "to " if m["to"] else f"{m['v']} "
    return f"{text[: m.start()]}{head}{other.name}{text[m.end() :]}"


# -- session 56 (12s): a person left out, then a request for others ----------------------------
#
# blind54 #131 "Leave Person B out this time round; both the bottle and the chips are headed to
# Person A." and #124 "The bottle goes to Person B, and don't let Person A talk you into it being
# hers.": a clause that leaves a person out ('Leave / Count P out (this time (round))', opening the
# text) or that forbids being talked round by P ("(and / but) don't let P talk / persuade / sweet-
# talk you into …", closing it) beside a request that hands P nothing: the request alone is what
# to do, and the clause is dropped. The rest must read, hand something over and give P nothing.
_LEAVE_OUT56S = re.compiled(
    rf"^(?:leave|count|keep) (?P<p>{_WHO53S}) out(?: of (?:it|this|things))?(?: (?:this time"
    r"(?: round| around)?|for now|today|for once))?\s*[;:,.—–-]\s*(?P<rest>\S.*)$",
    _F,
)
_TALKED_ROUND56S = re.compiled(
    rf"^(?P<rest>.*?\S)\s*[,;]?\s*(?:and |but )?(?:don't|do not|never) let (?P<p>{_WHO53S}) "
    r"(?:talk|persuade|sweet-talk|sweet talk|con|convince|wheedle|charm|coax) you (?:into|out of|"
    r"otherwise|round|around)\b[^,;.!?]*(?P<end>\s*[.!]?)$",
    _F,
)


def _left_out56s(text: str, lexicon: Lexicon) -> str:
    """Session 56 (12s): 'Leave P out this time; …' and '…, and don't let P talk you into …'
    dropped beside a request that hands P nothing (above)."""
    low = text.lower()
    if " out" not in low and "let " not in low:
        return text
    if _DONE56S.search(text):
        return text
    if _HOLDS56S.search(text) or _UNSAFE53S.search(text):
        return text
    m = _LEAVE_OUT56S.match(text.strip()) or _TALKED_ROUND56S.match(text.strip())
    if m is None or not _only_person(m["p"], lexicon):
        return text
    (p,) = _ids(m["p"], lexicon)
    rest = m["rest"]
    if _PAST56S.search(rest):
        return text  # "Leave Lena out; the knife was for Marco.": a past want is left as it was
    out = f"{rest[:1].upper()}{rest[1:]}" if "end" not in m.groupdict() else f"{rest}{m['end']}"
    node = _reading(out, lexicon)
    if node is None:
        return text
    given = [t for t in tasks(node) if t.kind == "deliver"]
    if not given or any(t.target == p for t in tasks(node)):
        return text
    return _plain51s(out, text, lexicon)


# -- session 56 (12s): '…, but leave the X alone, she's got her own.' --------------------------
#
# blind54 #139 "Jess could use the screws, but leave the hammer alone, she's got her own.": a
# thing to be left where it is ('leave the X alone / be / where it is'), after a request for
# other things, is "…, but not the X", which the grammar reads ("…, but not the hammer, she's got
# her own." reads). The X one thing of the scene, named whole; the rest must read without it; after
# it only "(as) she's got her own" (not 'she's got it / them / one', which may say the request is
# done); not after a past want or a holding.
_LEAVE_ALONE56S = re.compiled(
    r"^(?P<head>.+?\S)\s*[,;]\s*(?:but |and |just )?leave (?P<x>(?:the|that|this|those|these) "
    r"[a-z]+(?: [a-z]+)?) (?:alone|be|where (?:it is|they are)|where it's|where they're|out of it)"
    r"(?P<tail>\s*[,;]\s*(?:as |since |because |cos )?(?:he|she|they|[a-z]+)(?:'s| has|'ve| have)"
    r" (?:already )?got (?:his|her|their) own(?: ones?)?)?(?P<end>\s*[.!]?)$",
    _F,
)


def _leave_alone56s(text: str, lexicon: Lexicon) -> str:
    """Session 56 (12s): "…, but leave the X alone" said "…, but not the X" (above)."""
    if "leave " not in text.lower():
        return text
    if _DONE56S.search(text):
        return text
    m = _LEAVE_ALONE56S.match(text.strip())
    if m is None or _PAST56S.search(m["head"]) or _HOLDS56S.search(m["head"]):
        return text  # 'Bob wanted the apple, …': a past want, a holding: left as it was
    if _UNSAFE53S.search(m["head"]):
        return text
    x = _ids(m["x"], lexicon)
    bare = m["x"].split(" ", 1)[1]
    named = _names(bare, lexicon)
    if not x or x != _ids(m["x"], lexicon, "object") or len(named) != 1:
        return text
    if named[0].text.lower() != bare.lower():
        return text
    out = f"{m['head']}, but not {m['x']}{m['tail'] or ''}{m['end']}"
    if _read_without44r(out, text, m["x"], lexicon) == text:
        return text
    return _plain51s(out, text, lexicon)


# -- session 56 (12s): 'The X holds no interest for P, it's the Y he's been eyeing, so …' -------
#
# blind54 #125: a thing a person has no interest in ('the X holds / has no interest for P', 'P
# has no interest in / isn't interested in the X'), then a request: said "P doesn't want the X,
# …", which session 39's rules read; "it's the Y (that) he's been eyeing (up)" in the rest is
# "it's the Y he wants". P one person named; the X one thing of the scene, named whole; the
# reading hands the X to no one; no holding, no question.
_NO_INTEREST56S = re.compiled(
    r"^(?:(?P<x>(?:the|that|this) [a-z]+(?: [a-z]+)?) (?:holds|has) (?:no|zero|not the slightest|"
    rf"little) (?:interest|appeal) for (?P<p>{_WHO53S})|(?P<p2>{_WHO53S}) (?:has no interest in|"
    r"isn't interested in|is not interested in|has zero interest in) (?P<x2>(?:the|that|this) "
    r"[a-z]+(?: [a-z]+)?))(?P<rest>\s*[,;]\s*\S.*)$",
    _F,
)
_EYEING56S = re.compiled(
    r"\b(?P<head>it's (?:the|that|this) [a-z]+(?: [a-z]+)? (?:that )?(?:he|she))(?:'s| has) been "
    r"eyeing(?: up)?\b",
    _F,
)


def _no_interest56s(text: str, lexicon: Lexicon) -> str:
    """Session 56 (12s): "The X holds no interest for P, …" said "P doesn't want the X, …"
    (above)."""
    if "interest" not in text.lower():
        return text
    if _DONE56S.search(text):
        return text
    if text.rstrip().endswith("?") or _UNSAFE53S.search(text):
        return text
    m = _NO_INTEREST56S.match(text.strip())
    if m is None:
        return text
    p, x = m["p"] or m["p2"], m["x"] or m["x2"]
    if not _only_person(p, lexicon):
        return text
    bare = x.split(" ", 1)[1]
    named = _names(bare, lexicon)
    ids = _ids(x, lexicon)
    if not ids or ids != _ids(x, lexicon, "object") or len(named) != 1:
        return text
    if named[0].text.lower() != bare.lower():
        return text
    rest = _EYEING56S.sub(lambda e: f"{e['head']} wants", m["rest"])
    if _HOLDS56S.search(rest) or _PAST56S.search(rest):
        return text  # "…, he has the cup": a holding; a past want
    out = f"{p} doesn't want {x}{rest}"
    if _read_without44r(out, text, x, lexicon) == text:
        return text
    return _plain51s(out, text, lexicon)


# -- session 56 (12s): 'Bob was off the apple, so give him the cup.' ----------------------------
#
# read `apple>B & cup>B` on main 085b81dc (12s's own probe): a person 'off' a thing (now or before:
# 's / is / was / has been / had gone off the X) is not to be handed that thing: a reading that
# hands the X to that person is refused.
_WAS_OFF56S = re.compiled(
    rf"\b(?P<p>{_WHO53S})(?:'s| is| was| has been| had been|'d been|'s been| has gone| had gone|"
    r"'d gone| went)(?: (?:gone|right|really|a bit|totally|properly|completely))? off (?:the |her "
    r"|his |their )?(?P<x>[a-z]+(?: [a-z]+)?)",
    _F,
)


def _was_off56s(text: str, node: Node, lexicon: Lexicon) -> None:
    """Session 56 (12s): a thing handed to the person said to be off it (above)."""
    if " off " not in text.lower():
        return
    given = {(t.obj, t.target) for t in tasks(node) if t.kind == "deliver"}
    if not given:
        return
    for m in _WAS_OFF56S.finditer(text):
        people = _ids(m["p"], lexicon, "human")
        things = _ids(m["x"], lexicon, "object") | _ids(m["x"].split(" ")[0], lexicon, "object")
        for x, p in given:
            if p in people and x in things:
                raise GroundingError(
                    f"{m.group(0)!r} says {m['p']} is off the {x}, yet the reading hands it to "
                    f"{m['p']}: say who gets what"
                )


# the normaliser's first rewrites (wired into normalise._STEPS19, before the session-56 ones)
_STEPS56S_FIRST: tuple[Callable[[str, Lexicon], str], ...] = (
    _off_the56s,
    _not_for_take56s,
    _nothing_else56s,
    _anyone_but56s,
    _left_out56s,
    _leave_alone56s,
    _no_interest56s,
)
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-56 ones)
_STEPS56S: tuple[Callable[[str, Lexicon], str], ...] = ()
# refusals asked of the text before it is read (offline._parse, after the session-56 ones)
REFUSE56S: tuple[Callable[[str, Lexicon], None], ...] = (_not_p_then56s,)
# checks of the whole instruction's reading (offline.parse_instruction, after the session-56 ones)
CHECK56S: tuple[Callable[[str, Node, Lexicon], None], ...] = (_where_is56s, _was_off56s)
