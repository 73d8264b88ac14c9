"""The grounder's rules of session 41, engineer 12 (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _ids, _objects_only, _only, _only_person
from hltl.grounding._normalise4 import _fit36
from hltl.grounding.lexicon import Lexicon
from hltl.grounding.tree import Node

# -- session 41 (engineer 12): blind39's refusals by kind — a person's want said by an idiom, a
# pronoun whose one antecedent is the person just named, courtesies and question forms. Each rule
# a closed family checked against the scene; the rest of the sentence is read by the same grammar
# (a closing remark or a purpose beside the request is 12s's kind this session).

# what may stand before the person in its clause: nothing, or a word joining clauses
_CLAUSE_OPEN41 = re.compile(
    r"(?:^|[,;:.!?—–]\s*|\b(?:and|but|so|while|whereas|then|also|plus)\s+)$", _F
)


def _person_ending41(text: str, end: int, lexicon: Lexicon, pronouns: bool = False) -> str | None:
    """The person of the scene named by the one or two words ending at ``end`` ("Bob", "Person
    B", "Mrs Khan"; 'he' / 'she' when ``pronouns``), opening its clause; None if there is none."""
    words = text[:end].split(" ")
    for n in (2, 1):
        if len(words) < n:
            continue
        who = " ".join(words[-n:])
        ok = _only_person(who, lexicon) or (n == 1 and pronouns and who.lower() in ("he", "she"))
        if ok and _CLAUSE_OPEN41.search(text[: end - len(who)]):
            return who
    return None


# -- a want said by an idiom of desire, need, hunger or thirst, claim or entitlement ("Bob would be
# glad of the apple", "Priya's in want of the stapler", "Person A's set on the chips", "Noah's
# hungry for the glue", "Jess is angling for the drill", "Person A's down for the chips", "Mia has
# first call on the tape", "Tom's entitled to the scanner"): each said as 'wants', which the
# grammar reads as before. Only the present: 'was set on', 'would have been glad of' and every
# negated form ('isn't', 'not', 'no longer') do not match; idioms that cancel ('can do without',
# 'has gone off', 'is sick of', 'has had enough of') are not in the family and stay refused.
_WANT_IDIOM41 = re.compile(
    r"(?P<p>\b[A-Za-z][\w]*)(?P<idiom>"
    r"(?: would|'d) (?:really |so |very |ever so )?be (?:glad|thankful|grateful) (?:of|for)"
    r"|(?: is|'s) in (?:want|the market) (?:of|for)"
    r"|(?: is|'s|'s been| has been) (?:really |so |very |dead |quite |absolutely |just |rather |"
    r"pretty |awfully |ever so )?"
    r"(?:set on|hungry for|thirsty for|starving for|famished for|parched for|ravenous for|"
    r"yearning for|aching for|hankering (?:for|after)|hungering for|thirsting for|angling for|"
    r"holding out for|entitled to|down for|(?:first |next )?in line for|first in the queue for|"
    r"in the queue for|keen on|pining (?:for|after)|clamou?ring for|shouting for|yelling for|"
    r"hollering for|gunning for)"
    r"|(?: has|'s) set (?:his|her|their) (?:heart|sights) on"
    r"|(?: has|'s)(?: got)? (?:his|her|their) sights (?:set )?on"
    r"|(?: has|'s got|'s)(?: the)? (?:first call|first dibs|first claim|first pick|a claim) on"
    r"|(?: has|'s) (?:bagsied|bagsed)"
    # session 42: 'would give anything for', 'would jump at', 'has a yen for', 'keeps going on
    # about (wanting)', 'put in a word for' (blind40; 12c's fuzz)
    r"|(?: would|'d) (?:happily |gladly )?give (?:anything|(?:his|her|their) right arm|the "
    r"world) for"
    r"|(?: would|'d) (?:happily |gladly )?(?:jump|leap) at"
    r"|(?: has|'s got|'s) (?:a|such a|a real|a bit of a|a right) (?:yen|hankering|craving|hunger|"
    r"thirst|longing|yearning) for"
    r"|(?: keeps|'s been| has been| is|'s| kept) (?:going|banging|harping) on about"
    r"(?: wanting| needing| having| getting)?"
    r"|(?: keeps| kept) (?:asking|begging|pestering|nagging) for"
    r"|(?: put|'s put| has put|'d put| had put) in (?:a word|a request|a bid|an order) for"
    r")(?= (?:the|that|this|those|these|both|a|an|some|his|her|their) )",
    _F,
)


def _want_idiom41(text: str, lexicon: Lexicon) -> str:
    """Session 41: the idiom above after one person of the scene (or 'he' / 'she', left to the
    grammar to resolve) opening its clause, before words naming objects of the scene only (up to
    the clause's end), said as 'wants' (session 42: 'put in a word for' as 'asked for', and the
    person left unsaid after 'and' when the sentence opens with that one person and names nothing
    else before it: "Alice is parched and would kill for the bottle")."""
    for m in list(_WANT_IDIOM41.finditer(text))[::-1]:
        if m["p"].lower() == "and":
            if _elided42(text[: m.start("p")], lexicon) is None:
                continue
        elif _person_ending41(text, m.end("p"), lexicon, pronouns=True) is None:
            continue
        rest = re.split(
            r"[,;:.!?—–]| (?:and|but|so|while|after|before|since|for) ",
            text[m.end() :],
        )
        if not _objects_only(rest[0], lexicon):
            continue
        if _TO_HIM42.search(text[m.end() :]):
            # session 42: "Carol keeps asking for the apple, give her the cup" may hand her
            # something else instead (session 32's near form): left as it was
            continue
        said = " asked for" if " in " in m["idiom"] and " put" in m["idiom"] else " wants"
        text = f"{text[: m.start('idiom')]}{said}{text[m.end('idiom') :]}"
    return text


_TO_HIM42 = re.compile(r"\b(?:give|hand|pass|bring|get|take|fetch) (?:him|her|them)\b", _F)


def _elided42(head: str, lexicon: Lexicon) -> str | None:
    """Session 42: the one person of the scene who opens the sentence ending at ``head`` (the
    words before an 'and' whose subject is left unsaid), naming nothing else; None if not so."""
    sentence = re.split(r"[.;!?]\s+", head)[-1]
    if "," in sentence or _ids(sentence, lexicon, "object") or _ids(sentence, lexicon, "surface"):
        return None
    people = _ids(sentence, lexicon, "human")
    if len(people) != 1:
        return None
    for n in (2, 1):
        who = " ".join(sentence.split(" ")[:n])
        if _only_person(who, lexicon):
            return who
    return None


# -- a want of a kind answered by the thing that will do ("Person A's after something to drink out
# of, the cup will do her", "Bob wants something to eat; the apple will do him", "Noah needs
# something to measure with — the ruler will do"): the thing for the person who wants; 'the X will
# do (for) P' said alone is the same ("The apple will do Bob", "the blue pen will do for Sam")
_WILL_DO41 = re.compile(
    r"(?P<x>\b(?:the|that|this|those|these) [a-z][a-z ]*?)(?: (?:will|would|should|can|could)|'ll)"
    r"(?: (?:have to|just))? do(?: (?:for )?(?P<p>him|her|them|[A-Za-z][\w]*(?: [A-Z][\w]*)?))?"
    r"(?: (?:nicely|fine|just fine|perfectly|the trick))?(?P<end>\s*[.!]*\s*)$",
    _F,
)
_KIND_WANTED41 = re.compile(
    r"^(?P<head>.*?)(?P<want>(?P<p>\b[A-Za-z][\w]*)(?P<v>(?: is|'s) (?:after|"
    r"looking for|wanting|in need of)| (?:wants|needs|would like|'d like|could do with|could use))"
    r" (?:something|anything|summat|a thing)(?: [a-z' ]+?)?)\s*(?:[,;:—–]|\.|-)\s*$",
    _F,
)


def _will_do41(text: str, lexicon: Lexicon) -> str:
    """Session 41: 'the X will do (P)' (above) closing the instruction, X objects of the scene
    only: after '<P> is after / wants something …' it is 'give <P> the X' (the pronoun, if said,
    one P may be); alone, with P one person of the scene, 'give P the X'."""
    if " do" not in text.lower():
        return text
    m = _WILL_DO41.search(text)
    if m is None or not _objects_only(m["x"], lexicon):
        return text
    head, said = text[: m.start()], m["p"]
    k = _KIND_WANTED41.match(head)
    end = m["end"].strip() or "."
    if k is not None:
        who = _person_ending41(head, k.end("p"), lexicon)
        if who is None:
            return text
        if _ids(k["want"], lexicon, "object") or _ids(k["want"], lexicon, "surface"):
            return text
        (pid,) = _ids(who, lexicon, "human")
        if said is not None and said.lower() in ("him", "her", "them"):
            if not _fit36(pid, said, lexicon):
                return text
        elif said is not None and _ids(said, lexicon, "human") != {pid}:
            return text
        return f"{head[: k.end('p') - len(who)]}give {who} {m['x']}{end}"
    if said is None or not _only_person(said, lexicon) or head.strip(" ,;:.!?—–-"):
        return text
    return f"give {said} {m['x']}{end}"


# -- a request reported as asked for ("Chef's asked that the tongs and the knife both get left
# out on the counter", "Priya has requested that the stapler go in the box", "Marco asked for the
# knife and the tongs to be left on the counter"): the person wants the things put there ('P wants
# X put on S', which the grammar reads); X objects of the scene only, S one surface of it
_ASKED_THAT41 = re.compile(
    r"(?P<p>\b[A-Za-z][\w]*)(?:'s| has)? (?:asked|requested|asks|requests) "
    r"(?:that|for) (?P<x>(?:the|both|all|this|that|those|these) [^,;.!?]+?) (?:both |all |each |"
    r"both of them |all of them )?(?:to )?(?:be |get |)(?P<v>left|put|placed|set|stood|go|goes|got)"
    r"(?P<out> out| down| away)? (?P<prep>on|in|onto|into|on top of) (?P<s>the [a-z]+(?: [a-z]+)?)"
    r"(?=\s*(?:[,;.!?]|$| for | so | because | as ))",
    _F,
)


def _asked_that41(text: str, lexicon: Lexicon) -> str:
    """Session 41: the reported request above, P one person of the scene opening its clause."""
    if "ask" not in text.lower() and "request" not in text.lower():
        return text
    for m in list(_ASKED_THAT41.finditer(text))[::-1]:
        who = _person_ending41(text, m.end("p"), lexicon)
        if who is None:
            continue
        start = m.end("p") - len(who)
        if not _objects_only(m["x"], lexicon) or not _only(m["s"], lexicon, "surface"):
            continue
        if m["v"].lower() == "goes" and re.search(r"\b(?:and|or)\b", m["x"], _F):
            continue  # 'asked for X and Y goes on S': Y alone goes there, a clause of its own
        said = f"{who} wants {m['x']} put{m['out'] or ''} {m['prep']} {m['s']}"
        text = text[:start] + said + text[m.end() :]
    return text


# -- who said it, as an aside after the request ("Person B? The bottle, he said.", "Give Sam the
# stapler, she says, before lunch", "Mia wants the tape, they told me, for the van"): the task is
# the same whoever said it (session 27 took '…, he said so' off), so the tag is taken off when the
# pronoun may be a person named in its sentence and nothing after it names the scene ('…, she
# said, the cup' may correct, and stays)
_SAID_TAG41 = re.compile(
    r"\s*,\s*(?P<pron>he|she|they) (?:said|says|told me|tells me|reckons|reckoned|insists|insisted|"
    # session 42: who asked for it ("Chips for Person B, he asked. Bottle for Person A, she asked
    # too.")
    r"asked(?: for (?:it|them|that|those))?(?: too| as well| also| first)?)"
    r"(?P<end>\s*,\s*(?P<rest>[^.!?;]*)|(?=\s*[.!?]|\s*$))",
    _F,
)


def _said_tag41(text: str, lexicon: Lexicon) -> str:
    """Session 41: the tag above taken off (a comma after it kept)."""
    if not any(
        w in text.lower() for w in (" said", " says", " told", " reckon", " insist", " asked")
    ):
        return text
    for m in list(_SAID_TAG41.finditer(text))[::-1]:
        if m["rest"] is not None and _ids(m["rest"], lexicon):
            continue
        sentence = re.split(r"[.!;]\s", text[: m.start()])[-1]
        people = _ids(sentence, lexicon, "human")
        if not any(m["pron"].lower() == "they" or _fit36(p, m["pron"], lexicon) for p in people):
            continue
        text = text[: m.start()] + text[m.start("end") :]
    return text


# -- a want reported in the person's own words ("Person B said he'd take the chips", "Mrs Khan
# says she'll have the magazine", "Jess reckons she'd like the torch"): the pronoun is the one who
# said it (the sentence names no one else), so P wants the things; 'take X to Y' and 'on S' carry
# more than a want and are not matched (the words after the pronoun name objects only); 'they'
# may be others (session 34: "Carol says they'd love the blue mug" stays refused)
_SAID_WANT41 = re.compile(
    r"(?P<p>\b[A-Za-z][\w]*) (?:said|says|reckons|reckoned|told me|tells me|mentioned|thinks|"
    r"thought) (?:that )?(?P<pron>he|she)(?:'d| would|'ll| will) (?:really )?(?:take|have|"
    r"like|love|want|go for)(?= (?:the|that|this|those|these|both|a|an|some) )",
    _F,
)


def _said_want41(text: str, lexicon: Lexicon) -> str:
    """Session 41: the reported want above, P one person of the scene opening its clause whom the
    pronoun may be, said as 'P wants'."""
    if not any(
        w in text.lower() for w in ("said", "says", "reckon", "told", "mention", "thin", "thought")
    ):
        return text
    for m in list(_SAID_WANT41.finditer(text))[::-1]:
        who = _person_ending41(text, m.end("p"), lexicon)
        if who is None:
            continue
        (pid,) = _ids(who, lexicon, "human")
        if not _fit36(pid, m["pron"], lexicon):
            continue
        sentence = re.split(r"[.!?;]\s", text[m.end() :])[0]
        if _ids(re.split(r"[,:—–]", sentence)[0], lexicon) - _ids(sentence, lexicon, "object"):
            continue
        if not _objects_only(re.split(r"[,:—–]", sentence)[0], lexicon):
            continue
        start = m.end("p") - len(who)
        text = f"{text[:start]}{who} wants{text[m.end() :]}"
    return text


# -- a thing said to go a person's way ("The chips are going Person A's way", "the bottle goes
# Bob's way", "The torch is headed Jess's way"): it goes to that person (session 19 read 'send X
# P's way'); X objects of the scene only, P one person of it
_GOING_WAY41 = re.compile(
    r"(?P<x>\b(?:the|that|this|those|these|both) [a-z][a-z ]*?)(?: is| are|'s|'re)? (?:going|goes|"
    r"go|headed|heading|off) (?P<p>[A-Za-z][\w]*(?: [A-Za-z][\w]*)?)'s way\b",
    _F,
)


def _going_way41(text: str, lexicon: Lexicon) -> str:
    """Session 41: 'X is going P's way' (above) said as 'X goes to P'."""
    if "'s way" not in text.lower():
        return text
    for m in list(_GOING_WAY41.finditer(text))[::-1]:
        if not _objects_only(m["x"], lexicon) or not _only_person(m["p"], lexicon):
            continue
        text = f"{text[: m.start()]}{m['x']} goes to {m['p']}{text[m.end() :]}"
    return text


# -- courtesies said around the request: a foreign or old word of thanks set off with 'as my gran
# would say' ("Rakhmat, as my Bashkir gran would say, and would you …"; the bare word before a
# comma was taken off before), an apology for the fuss opening it ("Beg pardon for the fuss, …",
# "Excuse the mess, …", "Forgive the bother, …"), 'ever so much' after 'would you mind': each
# taken off when its words name nothing of the scene
_COURTESY41: tuple[tuple[re.Pattern[str], str], ...] = (
    (
        re.compile(
            r",\s*as (?:my|our|the|his|her|their|they|we|you|people|folk|one) (?P<w>[a-z' ]{0,40}?)"
            r"(?:would say|'d say|says|say|used to say|would put it|puts it|put it|likes to say)"
            r"(?: in [a-z]+)?\s*,",
            _F,
        ),
        ",",
    ),
    (
        re.compile(
            r"(?:^|(?<=[.;!?])\s*)(?:(?:i )?beg (?:your )?pardon|pardon me|excuse me|forgive me|"
            r"(?:my )?apologies|sorry|so sorry)(?P<w> for (?:the|all the|this|that|my|our) "
            r"[a-z]+(?: [a-z]+)?)\s*,\s*",
            _F,
        ),
        "",
    ),
    (
        re.compile(
            r"(?:^|(?<=[.;!?])\s*)(?:excuse|forgive|pardon) (?P<w>(?:the|all the|this|my|our) "
            r"[a-z]+(?: [a-z]+)?)\s*,\s*",
            _F,
        ),
        "",
    ),
    (
        re.compile(
            r"\b(?P<w>(?:would|do) you) mind (?:ever so|so|very|terribly|awfully) much\b", _F
        ),
        "{w} mind",
    ),
)


def _courtesy41(text: str, lexicon: Lexicon) -> str:
    """Session 41: the courtesies above taken off (their words naming nothing of the scene)."""
    for pattern, said in _COURTESY41:
        for m in list(re.finditer(pattern, text))[::-1]:  # gated (session 53, 12p)
            if _ids(m["w"], lexicon):
                continue
            text = text[: m.start()] + said.format(w=m["w"]) + text[m.end() :]
    return text


# -- permission asked in the question form ("Is Zoe alright to have the globe?", "Is Bob okay to
# take the apple?", "Is Mr Lee allowed the magazine?"): a request, as 'Can Zoe have the globe?'
# is read, when P is one person of the scene and the rest names objects of it only
_ALRIGHT_TO41 = re.compile(
    r"(?:^|(?<=[.;!?,])\s*)(?:is )?(?P<p>[A-Za-z][\w]*(?: [A-Za-z][\w]*)?) (?:alright|all right|"
    r"okay|ok|fine|ok'd|allowed|free|cleared|good) (?:to (?:have|take|get|borrow) )?"
    r"(?P<x>(?:the|that|this|those|these|both|a|an|some) [^,;.!?]+?)(?P<end>\s*\?)",
    _F,
)


def _alright_to41(text: str, lexicon: Lexicon) -> str:
    """Session 41: the question above said as 'can P have X?'."""
    if " to " not in text.lower() and "allowed" not in text.lower():
        return text
    for m in list(_ALRIGHT_TO41.finditer(text))[::-1]:
        if not _only_person(m["p"], lexicon) or not _objects_only(m["x"], lexicon):
            continue
        text = f"{text[: m.start()]}Can {m['p']} have {m['x']}{m['end']}{text[m.end() :]}"
    return text


# -- 'would you mind if P had X?' (the past of the courtesy): 'do you mind if P has X?', which is
# read as a request ('had' is otherwise what P had, refused as a condition)
_MIND_IF_HAD41 = re.compile(
    r"\b(?:would|do) you mind if (?P<p>[A-Za-z][\w]*(?: [A-Z][\w]*)?) (?:had|took|got) "
    r"(?P<x>(?:the|that|this|those|these|both) [^,;.!?]+?)(?=\s*\?)",
    _F,
)


def _mind_if_had41(text: str, lexicon: Lexicon) -> str:
    """Session 41: the question above, P one person of the scene and X objects of it only."""
    if "mind if" not in text.lower():
        return text
    for m in list(_MIND_IF_HAD41.finditer(text))[::-1]:
        if not _only_person(m["p"], lexicon) or not _objects_only(m["x"], lexicon):
            continue
        text = f"{text[: m.start()]}do you mind if {m['p']} has {m['x']}{text[m.end() :]}"
    return text


# -- 'lock X away in S' ("Lock both the spanners away in the locker", "lock the pills up in the
# bedside locker"): the robot puts them there (it cannot turn a key; 'put X away in S' is read);
# without 'away' / 'up' and a surface ('lock the locker', 'lock them away') it stays refused
_LOCK_AWAY41 = re.compile(
    r"\block (?P<x>(?:the|both|both the|both of the|all|all the|all of the|that|this|those|these) "
    r"[a-z][a-z ]*?) (?:away|up) (?P<prep>in|into|inside) (?P<s>the [a-z]+(?: (?!(?:before|after|"
    r"when|while|once|until|till|as|so|then|and|for|now|please)\b)[a-z]+)?)\b",
    _F,
)


def _lock_away41(text: str, lexicon: Lexicon) -> str:
    """Session 41: 'lock X away in S' (above), X objects of the scene only and S one surface of
    it, said as 'put X away in S'."""
    if "lock" not in text.lower():
        return text
    for m in list(_LOCK_AWAY41.finditer(text))[::-1]:
        if not _objects_only(m["x"], lexicon) or not _only(m["s"], lexicon, "surface"):
            continue
        put = "Put" if text[m.start()] == "L" else "put"
        text = f"{text[: m.start()]}{put} {m['x']} away {m['prep']} {m['s']}{text[m.end() :]}"
    return text


# -- 'sort her out' after a person's want ("the waitress is after the knife plus the tongs, sort
# her out", "Bob wants the apple, see him right", "Mr Lee needs his tablets, see to him"): asks
# that the want be met, which the want already asks; taken off when the pronoun may be the one
# person named before it
_SORT_OUT41 = re.compile(
    r"\s*[,;.!]\s*(?:(?:so|and|then|just|please|could you|can you|would you),?\s+)*(?:sort "
    r"(?P<p1>her|him|them)(?P<both1> both| all)? out|see (?P<p2>her|him|them)(?P<both2> both| all)?"
    r" right|see to (?P<p3>her|him|them)(?P<both3> both| all)?|look after (?P<p4>her|him|them)|"
    # session 42: "…; as for Tom, it's the tape he's short of. Sort them both."
    r"sort (?P<p5>them) (?P<both5>both|all)(?: out)?)(?:,? please|,? would you|,? will you)?"
    r"(?P<end>\s*[.!]*)\s*$",
    _F,
)


def _sort_out41(text: str, lexicon: Lexicon) -> str:
    """Session 41: the closing request above taken off (the want before it is read as before)."""
    if not any(w in text.lower() for w in ("sort", "see ", "look after")):
        return text
    m = _SORT_OUT41.search(text)
    if m is None:
        return text
    pron = m["p1"] or m["p2"] or m["p3"] or m["p4"] or m["p5"]
    people = _ids(text[: m.start()], lexicon, "human")
    both = m["both1"] or m["both2"] or m["both3"] or m["both5"]
    if pron.lower() == "them" and len(people) > 1:
        # session 42: 'sort them (both) out' after the wants of two people (or more, for 'all'),
        # each of whom a request names
        if both is not None and both.strip().lower() == "both" and len(people) != 2:
            return text
    elif both is not None or len(people) != 1 or not _fit36(next(iter(people)), pron, lexicon):
        return text
    if not _ids(text[: m.start()], lexicon, "object"):
        return text
    return text[: m.start()] + (m["end"].strip() or "")


# -- 'let P take X' after a want, or alone ("Ava's been eyeing the sippy cup; let her take it",
# "Let Bob take the apple"): P is let have it, as 'let P have X' is read; a place after it ('let
# him take it to the shelf') carries more and is not matched
_LET_TAKE41 = re.compile(
    r"\blet (?P<p>him|her|them|[A-Z][\w]*(?: [A-Z][\w]*)?) take (?P<x>it|them|(?:the|that|this|"
    r"those|these|both) [a-z][a-z ]*?)(?: (?:away|off|home|with (?:him|her|them)))?"
    r"(?=\s*(?:[.!,;]|$))",
    _F,
)


def _let_take41(text: str, lexicon: Lexicon) -> str:
    """Session 41: 'let P take X' (above) said as 'let P have X' (P a pronoun, or one person of
    the scene; X 'it' / 'them' or objects of it only)."""
    if "take" not in text.lower():
        return text
    for m in list(_LET_TAKE41.finditer(text))[::-1]:
        if m["p"].lower() not in ("him", "her", "them") and not _only_person(m["p"], lexicon):
            continue
        if m["x"].lower() not in ("it", "them") and not _objects_only(m["x"], lexicon):
            continue
        text = f"{text[: m.start()]}let {m['p']} have {m['x']}{text[m.end() :]}"
    return text


# -- 'can P take X off to <somewhere not in the scene>?' ("Can Person B take the apple and the
# chips off to the piquet table?", "Could Jess take the torch home?"): P is to have the things;
# where P takes them after is P's own errand. A place of the scene ('to the shelf') or a person
# ('to Bob') is a delivery of its own and is not matched
_TAKE_OFF41 = re.compile(
    r"\b(?P<ask>can|could|may|might) (?P<p>[A-Za-z][\w]*(?: [A-Z][\w]*)?) take (?P<x>(?:the|that|"
    r"this|those|these|both) [^,;.!?]+?) (?:off|away|home|back|along)(?: (?:to|with) (?P<to>(?:the|"
    r"his|her|their) [a-z' ]+?))?(?=\s*[?.!]|\s*$)",
    _F,
)


def _take_off41(text: str, lexicon: Lexicon) -> str:
    """Session 41: the question above said as 'can P take X?' (read as P having X)."""
    if "take" not in text.lower():
        return text
    for m in list(_TAKE_OFF41.finditer(text))[::-1]:
        if not _only_person(m["p"], lexicon) or not _objects_only(m["x"], lexicon):
            continue
        if m["to"] is not None and _ids(m["to"], lexicon):
            continue
        text = f"{text[: m.start()]}{m['ask']} {m['p']} take {m['x']}{text[m.end() :]}"
    return text


# -- a thing said first and taken up again by 'it' / 'them' in a want with a place ("Those work
# gloves, Mia wants them on the belt", "The apple, Bob wants it on the shelf"): the want of the
# thing there, as 'Mia wants the work gloves on the belt' is read; X objects of the scene only, P
# one person of it, S one surface
_OBJECT_FIRST41 = re.compile(
    r"(?:^|(?<=[.;!?])\s+)(?P<x>(?:the|those|these|that|this|both) [a-z][a-z ]*?),\s*"
    r"(?P<p>[A-Za-z][\w]*(?: [A-Z][\w]*)?) (?P<v>wants|needs|would like|'d like) (?:it|them) "
    r"(?P<prep>on|in|onto|into|up on|on top of) (?P<s>the [a-z]+(?: [a-z]+)?)\b",
    _F,
)


def _object_first41(text: str, lexicon: Lexicon) -> str:
    """Session 41: the want above said with the thing in its place."""
    if "," not in text:
        return text
    for m in list(_OBJECT_FIRST41.finditer(text))[::-1]:
        if not _objects_only(m["x"], lexicon) or not _only_person(m["p"], lexicon):
            continue
        if not _only(m["s"], lexicon, "surface"):
            continue
        said = f"{m['p']} {m['v']} {m['x']} {m['prep']} {m['s']}"
        text = text[: m.start("x")] + said + text[m.end() :]
    return text


# the normaliser's rewrites run before the session-40 ones (wired into normalise._STEPS19)
_STEPS41_FIRST: tuple[Callable[[str, Lexicon], str], ...] = (
    _want_idiom41,
    _will_do41,
    _asked_that41,
    _said_tag41,
    _said_want41,
    _going_way41,
    _courtesy41,
    _alright_to41,
    _mind_if_had41,
    _lock_away41,
    _sort_out41,
    _let_take41,
    _take_off41,
    _object_first41,
)
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-40 ones)
_STEPS41: tuple[Callable[[str, Lexicon], str], ...] = ()
# refusals asked of the text before it is read (offline._parse, after the session-40 ones)
REFUSE41: tuple[Callable[[str, Lexicon], None], ...] = ()
# checks of the whole instruction's reading (offline.parse_instruction, after the session-40 ones)
CHECK41: tuple[Callable[[str, Node, Lexicon], None], ...] = ()
