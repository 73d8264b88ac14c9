"""The normaliser's rewrites of session 39, engineer 12s (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _adjectives, _ids, _names, _only_person, _reading
from hltl.grounding._normalise4 import _fit36, _gather35r
from hltl.grounding._normalise5 import _BACK_FROM37, _BOTH_BEEN37, _HERS_AT37, _SHE_IS_A37
from hltl.grounding._rewrites38 import _LEFT_THEM38
from hltl.grounding._rewrites38s import (
    _ABOUT_VERB38S,
    _CUE_ANY38S,
    _CUED38S,
    _DETERMINED38S,
    _GONE_BY38S,
    _NEEDY38S,
    _P38S,
    _about_of38s,
)
from hltl.grounding.lexicon import VERBS, Lexicon, person_name
from hltl.grounding.tree import Node, Task, tasks

# -- session 39 (engineer 12s): a remark beside a request, by the kind of its subject -------------
#
# "…, he's got a bed push to get to", "…, her decoupage glue's drying", "…, we've the van hire
# place shutting at noon", "…, the lights have gone out in the back", "…, Mia's got a car boot
# sale to get to": a clause closing the instruction (after a comma, a semicolon, a dash or a
# sentence's end; a second one after 'and') that says something and asks nothing. Its subject is
# one of: a person of the scene by a name or a role (what _about_them38s leaves: its held words
# are fewer here), he / she (the one person the request names whom it may be, who gets something
# there), his / her <words> (the same), they (both / all) of two or more people who all get
# something, we (the speaker's side), or a thing or a place ("the lights", "the open garden lot",
# "the heating"). It is taken off when no word of it could change who gets what or when
# (_HELD39S): no name or adjective of the scene, no verb of giving, putting, wanting or needing (a
# light has / had / got; a word of VERBS used as a noun after a determiner), no negation, count,
# choice or pointing word, no correction, no speaker or hearer (but 'we' / 'our' in a remark of
# the speaker's side), no 'it' / 'them' (they could be what the request hands); no time that
# could put the request off: a time joined by 'before', 'until', 'once', 'when', 'by' anywhere;
# of a person, a time at all, a coming or going, being done, fine or away ('back at six', 'off
# home', 'in a bit') — of a thing, a place or the speaker's side, a time or a going is that of
# something else ("the van hire place shutting at noon", "the open garden lot will be here soon",
# "the lights have gone out": the request is not put off by it); gone by ('since the scrumping
# trip', 'after his pickled egg stall', 'all day') allowed; a dislike only of something the
# person does not get ('her running club's put her off crisps' beside the apple for her). A need
# ('parched') of a person who gets nothing there, or of the speaker's side, is a hint to give
# them something: kept. What is left must name something and read.

# a remark closing the instruction
_END39S = re.compile(
    r"(?P<sep>\s*[,;]\s*|\s+[—–-]\s+|(?<=[.!?])\s+)(?:(?:and|as|because|cos|'cause|oh|ah|well|"
    r"mind you),?\s+)?(?P<said>[^,;:.!?—–]+?)\s*(?P<end>[.!?]?)\s*$",
    _F,
)
# … or, in a text said without punctuation ("salt for mr novak please he's at table six"), before
# he's / she's / we're / we've / they're, or 'were' after a closer ("… please were off to …")
_RUN_ON39S = re.compile(
    r"^(?P<before>[^,;:.!?—–]+?[a-z])(?P<sep>\s+)(?P<said>(?:(?:he|she)'s|(?:we|they)'(?:re|ve)|"
    r"(?<=please )were|(?<=thanks )were|(?<=cheers )were) [^,;:.!?—–]+?)\s*$",
    _F,
)
# a second remark joined to the first by 'and'
_AND39S = re.compile(r"\s+and\s+(?=(?:he|she|we|they|his|her|their)\b)", _F)
# what the subject is
_WE39S = re.compile(r"^we(?='re|'ve|'d|\s+(?:are|were|have|had|all|both)\b)", _F)
# (session 40, 12s: or a doing gone by said without -ed: "he won the egg and spoon race")
_PRON39S = re.compile(
    r"^(?P<pron>he|she)(?='s|'d|\s+(?:is|was|has|had|[a-z]+(?:s|ed)|won|got|came|spent|did|ran|"
    r"swam|sang|rode|flew|slept|caught|drove|fought|taught|built|made|kept|sat|stood|wrote|dug|"
    r"threw|broke|felt|burnt|lost|beat|met|found|saw|heard|knew|grew|wore)\b)",
    _F,
)
_THEY39S = re.compile(
    r"^they(?P<aux>'ve|'re|\s+(?:have|are|were))?\s+(?:both|all)\b(?P<rest>.*)$", _F
)
_POSS39S = re.compile(r"^(?P<pron>his|her|their)\s+(?P<what>[a-z][a-z ]*)$", _F)
_THING39S = re.compile(r"^(?:the|our|my)\s+[a-z][a-z ]*$", _F)
# the verb after a subject of several words ('s, is, are, have, will be …, a word of a doing)
_VERB39S = re.compile(r"^(?:'re|'ve|'ll be|\s+(?:are|were|have|will be)\b)(?=\s*\S)", _F)
# 'got a car boot sale to get to', 'got the marching band to feed': what the person has to do
_TO_DO39S = re.compile(
    r"\b(?P<got>got|has|have|'ve) (?P<what>(?:a|an|the|his|her|their|our) [a-z]+(?: [a-z]+){0,3}) "
    r"to (?:get to|go to|catch|feed|run|do|finish|sort out|see to|look after|set up|pack up)\b",
    _F,
)
# a dislike: 'put her off X', 'gone off X', 'had enough of X', 'sick of X', 'fed up with X'
_DISLIKE39S = re.compile(
    r"\b(?:put (?:him|her|them) off|(?:'s|has|have|'ve) gone off|(?:'s|has|have|'ve) had enough "
    r"of|(?:sick|tired) of|fed up (?:of|with)) (?P<x>(?:the |any )?[a-z]+(?: [a-z]+)?)\s*$",
    _F,
)
# 'after' / 'since' a thing gone by (not 'he's after the X': a want)
_SINCE39S = re.compile(
    r"(?<!'s )(?<!\bis )(?<!\bwas )(?<!\bbeen )\b(?:after|since) (?:the|a|an|his|her|their|our) "
    r"[a-z]+(?: [a-z]+){0,3}$|\bsince (?:noon|midday|lunch(?:time)?|teatime|\d{1,2}(?: ?[ap]m)?|"
    r"(?:one|two|three|four|five|six|seven|eight|nine|ten|eleven|twelve)(?: o'clock)?)$",
    _F,
)
# a time word ending a thing's name ('a quiz night', 'the away day', 'her lunch club'): no time
_NAMED_TIME39S = re.compile(
    r"\b(?:a|an|the|his|her|their|our) (?!(?:next|last|same|other|one|this|that|whole|early|"
    r"late)\b)[a-z]+ (?:night|day|morning|afternoon|evening|week|weekend|lunch|dinner|tea|"
    r"breakfast|supper)(?: [a-z]+)?\b",
    _F,
)
# 'was a long one', 'has been a rough one': of the subject itself, no object picked out
_A_LONG_ONE39S = re.compile(
    r"\b(?:a|such a|another) (?:long|short|hard|busy|rough|tough|late|early|quiet|slow|mad|good|"
    r"bad|big|hectic) one\b",
    _F,
)
# 'at table six', 'in bed four': a place by its number, no time
_PLACE_NUMBER39S = re.compile(
    r"\b(?:at|on|in) (?:table|bed|room|bay|seat|desk|stall|pitch|platform|gate|cubicle) "
    r"(?:number )?(?:\d{1,3}|one|two|three|four|five|six|seven|eight|nine|ten|eleven|twelve)\b",
    _F,
)
# held of every remark: negation, counts and choices, pointing words, what is whose, the speaker
# and the hearer, corrections, a time joined to the request, wanting, needing, asking, giving
_HELD_WORDS39S = (
    r"no|not|never|nobody|none|nothing|nor|neither|without|except|but|unless|if|or|either|"
    r"one|ones|both|any|some|each|every|all|other|another|else|rest|same|pair|couple|half|few|"
    r"several|dozen|two|three|four|five|six|seven|eight|nine|ten|eleven|twelve|"
    r"own|it|its|them|as|they|theirs|hers|this|that|these|those|there|"
    r"which|what|who|whom|whose|where|why|how|me|my|mine|i|i'm|you|your|yours|"
    r"drink|drinks|snack|snacks|"
    r"actually|sorry|oops|whoops|mean|meant|mistake|scratch|wait|hang|hold|instead|rather|"
    r"wrong|right|backwards|muddled|mixed|confused|"
    r"correction|change|changed|forget|cancel|ignore|scrap|swap|switch|"
    r"before|once|when|whenever|while|until|till|by|then|next|first|last|finally|already|still|"
    r"yet|too|also|only|"
    r"want|wants|wanted|wanting|need|needs|needed|needing|like|likes|liked|love|loves|loved|"
    r"fancy|fancies|prefer|prefers|preferred|keen|dying|craving|asked|ask|asks|asking|request|"
    r"requested|ordered|could|would|should|can|must|might|may|shall|ought|get|gets|getting|"
    r"given|giving|waiting|waited|hoping|hoped|expecting|queueing|queuing|"
    r"us|our|ours|we|their"
)
_HELD_MORE39S = r"|\b(?:has|have|had|got|'s|is|was|about) to\b|n't\b|'d\b"
# … and of a person: a time at all, coming, going, being away, done or fine, a clock's number
_PERSON_HELD39S = (
    r"after|since|later|soon|shortly|tonight|tomorrow|today|now|minute|minutes|hour|hours|mins?|"
    r"secs?|second|seconds|moment|tick|jiffy|bit|o'clock|noon|midday|midnight|morning|afternoon|"
    r"evening|night|week|weekend|day|lunch|dinner|tea|breakfast|supper|monday|tuesday|wednesday|"
    r"thursday|friday|saturday|sunday|will|'ll|"
    r"off|away|out|gone|leaving|left|leave|going|goes|go|went|heading|headed|due|expected|coming|"
    r"comes|arriving|arrives|arrived|way|home|loo|toilet|bathroom|asleep|sleeping|napping|fine|"
    r"sorted|set|good|okay|ok|alright|happy|done|finished|covered|served|full|fill|plenty|enough|"
    r"over|through|free|ready|available|here|around|about"
)
_DIGITS39S = r"|\d"
# a time of a thing's or the speaker's side's own ('shutting at noon', 'here any minute')
_CLOCK39S = re.compile(
    r"\b(?:at (?:\d{1,2}(?:[:.]\d\d)?(?: ?[ap]m)?|noon|midday|one|two|three|four|five|six|seven|"
    r"eight|nine|ten|eleven|twelve)(?: o'clock)?|any (?:minute|moment|second|time)(?: now)?)\b",
    _F,
)


# words of VERBS a remark may say: light ones, and of a thing or the speaker's side, going and
# having ("the lights have gone out", "we're having a picnic"; "Sam's having a biscuit" may be a
# want of his)
_LIGHT39S = frozenset({"has", "had", "have", "got"})
_GOING39S = frozenset({"go", "goes", "going", "gone", "went", "having"})


def _held39s(kind: str) -> re.Pattern[str]:
    """What a remark whose subject is of ``kind`` may not hold (above)."""
    words = _HELD_WORDS39S
    if kind == "we":
        words = re.sub(r"\|us\|our\|ours\|we", "|us", words)
    if kind == "they":
        words = words.replace("|their", "")
    more = _HELD_MORE39S + _DIGITS39S
    if kind in ("person", "pron", "poss", "they"):
        words = f"{words}|{_PERSON_HELD39S}"
        more += r"|\bback\b(?! from)"  # 'back at six', 'back in a bit' ('back from' gone by)
    return re.compile(rf"\b(?:{words})\b{more}", _F)


_HELD39S = {k: _held39s(k) for k in ("person", "pron", "poss", "they", "we", "thing")}
_PRONOUNS39S = re.compile(r"\b(?:he|him|his|she|her|hers)\b", _F)


def _people39s(text: str, lexicon: Lexicon) -> set[str]:
    """The people ``text`` names each by a word of one person alone ('Person' of 'Person B', which
    the lexer takes for any person, is not one), after the last correction cue when one is said
    and names someone after it (the person taken back is not whom a later he / she means)."""
    cues = list(re.finditer(_CUE_ANY38S, text))  # gated (session 53, 12p)
    if cues:
        after = _people39s(text[cues[-1].end() :], lexicon)
        if after:
            return after
    return {
        it.refs[0].id
        for it in _names(text, lexicon)
        if len(it.refs) == 1 and it.refs[0].kind == "human"
    }


def _subject39s(said: str, lexicon: Lexicon) -> tuple[str, str, str] | None:
    """The kind of ``said``'s subject (person, pron, poss, they, we, thing), the words that say
    who it is (a name, a pronoun, ''), and the words after the subject; None where ``said`` is
    no clause of one of these subjects."""
    said = said.strip()
    if _WE39S.match(said):
        return "we", "", said[2:]
    m = _PRON39S.match(said)
    if m is not None:
        return "pron", m["pron"], said[m.end() :]
    m = _THEY39S.match(said)
    if m is not None:
        return "they", "", m["rest"]
    words = said.split()
    for k in range(min(5, len(words) - 1), 0, -1):
        head = " ".join(words[:k])
        subject = re.sub(r"'s$", "", head)
        rest = said[len(subject) :]
        if not (_ABOUT_VERB38S.match(rest) or _VERB39S.match(rest)):
            continue
        if _only_person(subject, lexicon):
            return "person", subject, rest
        if k >= 2 and not _names(subject, lexicon):
            # (the subject's own words are asked of as the rest's are: 'the other one')
            m = _POSS39S.match(subject)
            if m is not None:
                return "poss", m["pron"], said
            if _THING39S.match(subject):
                return "thing", "", said
    return None


def _plain39s(kind: str, rest: str, who: str | None, lexicon: Lexicon) -> bool:
    """Whether ``rest`` (a remark's words after its subject of ``kind``, about ``who``) holds
    nothing that could change who gets what or when (above)."""
    plain = _GONE_BY38S.sub(" ", rest)
    plain = _TO_DO39S.sub(lambda m: f"{m['got']} {m['what']}", plain)
    # (session 41, lead: not 'after the apple', a thing of the scene: "Carol is hankering after
    # the apple" is a want, not a time gone by)
    plain = _SINCE39S.sub(lambda m: m[0] if _names(m[0], lexicon) else " ", plain.strip())
    plain = _NAMED_TIME39S.sub(" ", plain)
    plain = _A_LONG_ONE39S.sub(" ", plain)
    plain = _PLACE_NUMBER39S.sub(" ", plain)
    if kind in ("we", "thing"):
        plain = _CLOCK39S.sub(" ", plain)
    m = _DISLIKE39S.search(plain)
    if m is not None:
        plain = plain[: m.start()]
    if _HELD39S[kind].search(plain) or _names(plain, lexicon):
        return False
    tokens = [re.sub(r"'(?:s|re|ve|m)$", "", w) for w in re.findall(r"[a-z']+", plain.lower())]
    adjectives = {w for ws in _adjectives(lexicon).values() for w in ws}
    light = _LIGHT39S | (_GOING39S if kind in ("we", "thing") else frozenset())
    for n, w in enumerate(tokens):
        if w in adjectives or (w in VERBS and w not in light and not _noun39s(tokens, n)):
            return False
    return True


def _noun39s(tokens: list[str], n: int) -> bool:
    """Whether ``tokens[n]`` ends a noun phrase: a determiner at most three words before it with
    no verb between ("a long shift", "her pop class", "the van hire place")."""
    if n > 0 and tokens[n - 1] in _DETERMINED38S:
        return True
    for k in range(n - 1, max(n - 4, -1), -1):
        if tokens[k] in ("a", "an", "the", "his", "her", "their", "our", "my"):
            return True
        if tokens[k] in VERBS or tokens[k] in ("", "is", "are", "was", "were", "be", "been"):
            return False
    return False


def _disliked39s(rest: str, lexicon: Lexicon) -> set[str]:
    """The objects of the scene a dislike closing ``rest`` names (none: an empty set)."""
    m = _DISLIKE39S.search(rest)
    return _ids(m["x"], lexicon, "object") if m is not None else set()


def _ends39s(text: str) -> re.Match[str] | None:
    """The remark closing ``text`` (_END39S), else the run-on one (_RUN_ON39S)."""
    return _END39S.search(text) or _RUN_ON39S.match(text)


def _closed39s(
    text: str,
    lexicon: Lexicon,
    about: set[str],
    needy: set[str],
    dislikes: dict[str, set[str]],
    middle: bool = False,
) -> str:
    """``text`` without the remarks closing it (above), taken off one by one from the end while
    what is left names something; the people a pronoun of them means (``about``), those said to
    need something (``needy``) and what each is said to dislike (``dislikes``) are added to
    (``middle``: a sentence with another after it, which _about_them38s does not read)."""
    out = text
    while (m := _ends39s(out)) is not None:
        before = out[: m.start("sep")].rstrip()
        parts = _AND39S.split(re.sub(r"^were\b", "we're", m["said"]))
        people = _people39s(before, lexicon)
        ok = bool(_names(before, lexicon))
        last = re.split(r"[,;:.!?—–]\s|\s-\s", before.rstrip(" .!?"))[-1]
        if _CUED38S.search(last) and not _names(last, lexicon):
            ok = False  # "Give Alice the apple, sorry, she's been waiting": what 'sorry' corrects
        cue = list(re.finditer(_CUE_ANY38S, before))  # gated (session 53, 12p)
        for said in parts if ok else ():
            found = _subject39s(said, lexicon)
            if found is None:
                ok = False
                break
            kind, head, rest = found
            said_of = {*re.findall(r"\b(?:he|him|his|she|her|hers)\b", rest.lower())}
            if kind == "person":
                if not middle and _about_of38s(said, lexicon) is not None:
                    ok = False  # _about_them38s's (closing the instruction): read there
                    break
                who = next(iter(_ids(head, lexicon, "human")))
                if _PRONOUNS39S.search(before) or (
                    cue and who in _ids(before[: cue[-1].start()], lexicon, "human")
                ):
                    ok = False  # a name beside a pronoun, or of the person taken back
                    break
                fit = [who] if all(_fit36(who, w, lexicon) for w in said_of) else []
            elif kind == "they":
                if _BOTH_BEEN37.search(f", {said}"):
                    ok = False  # session 37's
                    break
                fit = sorted(people) if len(people) >= 2 and not said_of else []
            else:
                if (
                    kind in ("pron", "poss")
                    and not middle
                    and m.re is _END39S
                    and m["sep"].strip() == ""
                ):
                    ok = False  # a he / she sentence of its own: sessions 37 and 38 (12) read it
                    break
                if kind == "pron" and any(
                    p.search(f", {said}") for p in (_SHE_IS_A37, _BACK_FROM37, _HERS_AT37)
                ):
                    ok = False  # session 37's
                    break
                if kind in ("poss", "thing") and _LEFT_THEM38.search(f", {said}"):
                    ok = False  # session 38's (12): 'her physio makes her thirsty'
                    break
                said_of |= {head.lower()} if kind in ("pron", "poss") and head != "their" else set()
                if head == "their":
                    fit = sorted(people) if len(people) >= 2 and not said_of else []
                elif said_of:
                    fit = [p for p in people if all(_fit36(p, w, lexicon) for w in said_of)]
                    fit = fit if len(fit) == 1 else []
                else:
                    fit = ["-"]
            if not fit or not _plain39s(kind, rest, fit[0], lexicon):
                ok = False
                break
            if kind in ("pron", "poss", "they") or (kind == "thing" and said_of):
                about |= set(fit)
            if _NEEDY38S.search(rest):
                if kind in ("we",) or fit == ["-"]:
                    ok = False
                    break
                needy |= set(fit)
            for p in fit:
                dislikes.setdefault(p, set()).update(_disliked39s(rest, lexicon))
        if not ok:
            break
        said_end = m.groupdict().get("end") or ""
        end = "?" if said_end == "?" and before[-1:] not in (".", "!", "?") else "."
        out = before if before[-1:] in (".", "!", "?") else before + end
    return out


# sentences (and parts after a semicolon) of an instruction, each with the space after it
_SENTENCES39S = re.compile(r"[^.!?;]+(?:[.!?;]+|$)\s*")


def _remark39s(text: str, lexicon: Lexicon) -> str:
    """Session 39 (12s): remarks closing the instruction, or a sentence of it before another
    ("…, he's got a bed push to get to. Once that's done, …", "…. The boiler's playing up again.
    …"), taken off (above); then what is left must read, each person a remark is about by a
    pronoun get something there, no one get what a remark says they dislike, and a need be said
    only of someone who gets something."""
    if _gather35r(text, lexicon) != text:
        return text  # session 35's (12r) 'gather up X and drop them in S' reads its remark
    about: set[str] = set()  # people a pronoun of a remark means: they must get something
    needy: set[str] = set()
    dislikes: dict[str, set[str]] = {}
    pieces = _SENTENCES39S.findall(text) if re.search(r"[.!?;]\s+\S", text) else [text]
    out = ""
    for k, piece in enumerate(pieces):
        said = out + piece
        if k == len(pieces) - 1:
            out = _closed39s(said, lexicon, about, needy, dislikes)
            break
        cut = _closed39s(said.rstrip(), lexicon, about, needy, dislikes, middle=True)
        out = cut + " " if cut != said.rstrip() else said
    if out == text or " ".join(out.split()) == " ".join(text.split()):
        return text
    read = _reading(out, lexicon)
    if read is None:
        return text
    got = {t.target for t in tasks(read)}
    if not (about | needy) <= got:
        return text
    for p, objs in dislikes.items():
        if any(t.target == p and t.obj in objs for t in tasks(read)):
            return text
    return out


# -- the same remarks opening the instruction ------------------------------------------------
#
# "We've the van hire place shutting at noon, so stick the boxes on the belt.", "Dana has been on
# the phone all morning. Pass the bowl to Emma.": a remark of a person of the scene by a name, of
# the speaker's side or of a thing, then the request (after a sentence's end, a semicolon, or
# 'so'; after a comma alone only of the speaker's side or a thing). Taken off under the same held
# words when the request has no pronoun for a person (the remark's person may be whom it means:
# the older rules read that) and reads alone; the remark's person, if the request names them,
# must get something there, and so must one said to need something (the lead's session-37 rule:
# "Zoe is thirsty. Books." gives Zoe the books; bare objects do not read alone, so that is left).
_FIRST39S = re.compile(
    r"^(?:(?:right|ok|okay|so|well|look),?\s+)?(?P<said>[^,;:.!?—–]+?)(?P<sep>\s*[.;!]\s+|\s*[,;]?"
    r"\s+(?:and )?so,?\s+|\s*,\s+)(?P<req>\S.*)$",
    _F,
)
_THEIRS39S = re.compile(r"\b(?:he|him|his|she|her|hers|they|them|their|theirs)\b", _F)
_BOTH_OF_THEM40S = re.compile(r"\b(?:both|each|either|the pair|the two|all) of them\b", _F)


def _remark_first39s(text: str, lexicon: Lexicon) -> str:
    """Session 39 (12s): a remark opening the instruction taken off (above)."""
    m = _FIRST39S.match(text)
    if m is None or not _names(m["req"], lexicon):
        return text
    found = _subject39s(m["said"], lexicon)
    if found is None:
        return text
    kind, head, rest = found
    req = m["req"]
    if kind in ("thing", "we"):
        # (session 40, 12s: "The tin whistle session's just finished, so both of them get a
        # drink: …": 'both of them' are the request's people, not the remark's thing)
        req = _BOTH_OF_THEM40S.sub(" ", req)
    if _THEIRS39S.search(req):
        return text
    comma = m["sep"].strip() == ","
    if kind not in ("person", "pron", "poss", "we", "thing") or head == "their":
        return text
    if comma and kind in ("person", "pron", "poss"):
        return text
    said_of = set(re.findall(r"\b(?:he|him|his|she|her|hers)\b", rest.lower()))
    if kind == "person":
        who = next(iter(_ids(head, lexicon, "human")))
        named = _people39s(m["req"], lexicon)
        if not named or who in named or not all(_fit36(who, w, lexicon) for w in said_of):
            return text  # (the lead's session-37 rule: the remark's person gets what follows)
    elif kind in ("pron", "poss"):
        # "He's got a train to catch, so give Bob the cup": the one person the request names
        fit = [
            p
            for p in _people39s(m["req"], lexicon)
            if all(_fit36(p, w, lexicon) for w in said_of | {head.lower()})
        ]
        if len(fit) != 1:
            return text
        who = fit[0]
    elif said_of:
        return text
    else:
        who = ""
    if not _plain39s(kind, rest, who, lexicon):
        return text
    if _NEEDY38S.search(rest) and not who:
        return text
    out = m["req"][:1].upper() + m["req"][1:]
    read = _reading(out, lexicon)
    if read is None:
        return text
    got = {t.target for t in tasks(read)}
    if kind in ("pron", "poss") and who not in got:
        return text
    if who and who not in got and (_NEEDY38S.search(rest) or who in _ids(out, lexicon, "human")):
        return text
    return out


# -- what a remark about a person must not be read past (offline.py calls this on the reading) ----
#
# The follow-ups of session 38: older rules took these remarks off and read the request, but each
# may change who gets what. A closing remark about the person who gets something, said again by
# their name (no correction before it), that they are leaving, away, fine or done ("Give Bob the
# cup, Bob's off home.", "Give Bob the cup, Bob's fine."): is it still to be handed over? By he /
# she the tuned parts read "…, he's off to watch the football" as the handover before they go
# (blind21); of someone who gets nothing, session 8 reads "Give Bob the cup, Carol is leaving
# soon" and session 37 "give bob the cup, alice is back at six" as said now, and "The chips are
# going to Person A, Person B's had his fill." is read (blind35): those are kept. By a name or a
# he / she that means one person: that the one who gets it is asleep ("Give Mr Lee the magazine,
# he's asleep.": no one to hand it to), or that someone who gets nothing needs something ("Give
# Alice the apple, Bob's parched.": a hint to give them something too).
_GOING39S_SAID = re.compile(
    r"(?:'s|\bis|\bwas|'re|\bare)\s+(?:just\s+|only\s+)?(?:off(?: to| home| out| now| soon| for|"
    r" in)?\s*$|off (?:to|home|out)\b|(?:away|gone (?:home|out|off)|leaving|heading (?:off|home|"
    r"out)|fine|ok|okay|alright|sorted|done|finished)\b(?! with)|out\b(?! of)|all (?:right|set|"
    r"done)\b)",
    _F,
)
_ASLEEP39S = re.compile(
    r"(?:'s|\bis)\s+(?:fast |sound |still |just )?(?:asleep|sleeping|napping|"
    r"dozing|having a nap)\b",
    _F,
)


def _shown39s(node: Node) -> str:
    """``node`` in the corpus notation ('cup>B', 'cup@shelf', '&', '|', ';')."""
    if isinstance(node, Task):
        return f"{node.obj}{'>' if node.kind == 'deliver' else '@'}{node.target}"
    shown = {"and": " & ", "or": " | ", "seq": " ; "}[node.op].join(
        _shown39s(c) for c in node.children
    )
    return f"({shown})"


def remark_said39s(text: str, node: Node, lexicon: Lexicon) -> None:
    """Session 39 (12s): refuse a reading past a closing remark about a person of the scene (above)
    that says, by the name of one who gets something, that they are leaving, away, fine or done,
    or, by a name or a he / she of one person, that the one who gets something is asleep or that
    someone who gets nothing needs something; naming what was read."""
    out = text
    got = {t.target for t in tasks(node)}
    read = _shown39s(node)
    while (m := _END39S.search(out)) is not None:
        before = out[: m.start()].rstrip()
        said = m["said"].strip()
        found = _subject39s(said, lexicon)
        if found is None or found[0] not in ("person", "pron") or not _names(before, lexicon):
            return
        kind, head, rest = found
        if _CUE_ANY38S.search(before):
            return  # a remark after a correction may say why it was made
        if kind == "pron":
            fit = [p for p in sorted(_people39s(before, lexicon)) if _fit36(p, head, lexicon)]
            if len(fit) != 1:
                return
            who = fit[0]
        else:
            who = next(iter(_ids(head, lexicon, "human")))
        name = person_name(who, lexicon)
        if kind == "person" and who in got and _GOING39S_SAID.search(rest):
            raise GroundingError(
                f"{said!r} says {name} is leaving, away, fine or done: is {read} "
                "still what is to be done? say the request without it, or who gets what"
            )
        if _ASLEEP39S.search(rest) and who in got:
            raise GroundingError(
                f"{said!r} says {name} is asleep: hand it over ({read}), or leave it by them? say "
                "where it goes"
            )
        if _NEEDY38S.search(rest) and who not in got:
            raise GroundingError(
                f"{said!r} says {name} needs something, but the request gives them nothing "
                f"({read}): is something for them too? say who gets what"
            )
        out = before


# -- session 39 (engineer 12s): blind37's corrections, by kind ------------------------------------
#
# A correction cue, then words that only say the speaker slipped, or say the correction another
# way: each read as the plain correction (the session-33 and -38 rules then read it) when its words
# name nothing else of the scene.
_CUE39S = (
    r"(?:no|nope|sorry|no sorry|oh no|actually|wait|no wait|hang on|hold on|hang about|"
    r"scratch that|correction|i mean|my mistake|oops|whoops)"
)
# "…, sorry, I keep saying Bob, …", "…, oh no, I've muddled them, …", "…, oops, my muddle, …",
# "…, oh silly me, …": the speaker's slip said after a cue (or as one)
_SLIP39S = re.compile(
    rf"(?P<lead>,\s*)(?P<cue>(?:(?:oh|ah|well)\s*,?\s*)?(?:{_CUE39S})\s*,\s*)?(?:oh\s*,?\s*)?"
    r"(?P<slip>i keep (?:saying|calling (?:him|her|them)|getting (?:them|those) (?:mixed up|"
    r"muddled(?: up)?))(?P<said>(?: [a-z]+){0,2})|i(?:'ve| have) (?:muddled|mixed) (?:them|those|"
    r"it|that)(?: up)?|i(?:'ve| have) got (?:them|those) (?:mixed up|muddled(?: up)?)|my (?:muddle|"
    r"mix-up|mix up|bad)|silly me|daft me|silly old me)\s*,\s*",
    _F,
)
# "…, hold up, …": as 'hold on'
_HOLD_UP39S = re.compile(r"(?P<lead>,\s*(?:(?:ah|oh)\s*,?\s*)?)hold up(?=\s*,)", _F)
# "…, scratch that, it should go to Person B": where it goes said again after a cue
_GOES_TO39S = re.compile(
    rf"(?P<cue>\b{_CUE39S}\s*,\s*)(?:it|they|that|that one)(?: should| ought to| needs to| has "
    r"to| have to| must| can)? go(?:es)? (?=to\s)",
    _F,
)
# "…, no, my mistake, the bowl's what he asked for": the object corrected to, said in a
# pseudo-cleft of the person's want
_WHAT_ASKED39S = re.compile(
    rf"(?P<cue>\b{_CUE39S}\s*,\s*)(?P<x>the [a-z][a-z ]*?)(?:'s| is) what (?P<who>he|she|"
    rf"{_P38S}) (?:asked for|wants|wanted|needs|needed|ordered|is after|'s after|was after)"
    r"(?P<end>\s*[.!]?)\s*$",
    _F,
)
# "…, no, Mia's the one needing it for the stock count": as '… the one who needs it'
_ONE_NEEDING39S = re.compile(
    rf"(?P<p>\b{_P38S})(?:'s| is) the one (?:needing|wanting|after|asking for) (?P<it>it|them)"
    r"(?: for (?:the|her|his|their) [a-z]+(?: [a-z]+){0,2})?(?P<end>\s*[.!]?)\s*$",
    _F,
)
# "…, oh silly me, he's not here, it's Person A who's about, so give it her": the person taken
# back not here, the one who is named
_WHO_IS_ABOUT39S = re.compile(
    rf"(?P<cue>\b{_CUE39S}\s*,\s*)(?:(?P<gone>he|she)(?:'s| is) not (?:here|about|around|in)"
    rf"(?: today)?\s*,\s*)?it(?:'s| is) (?P<p>{_P38S}) (?:who|that)(?:'s| is) (?:about|here|"
    r"around|in)(?:\s*,\s*so (?:give|hand|pass|take) (?:it|them) (?:to )?(?P<pron>her|him))?"
    r"(?P<end>\s*[.!]?)\s*$",
    _F,
)
# "Thermometer to Ruth, or no, on the locker.": a place instead of the person
_PLACE_NOT39S = re.compile(
    r"^(?P<head>[^,;.!?]+?\bto [^,;.!?]+?),\s*(?:or\s+)?(?P<cue>no|actually|sorry|no wait|"
    r"rather)\s*,\s*(?P<where>(?:on|onto|in|into) (?:the )?[a-z][a-z ]*?)(?P<end>\s*[.!]?)\s*$",
    _F,
)


def _only_before39s(said: str, before: str, lexicon: Lexicon) -> bool:
    """Whether ``said`` names nothing, or only what ``before`` names."""
    return _ids(said, lexicon) <= _ids(before, lexicon)


def _corrections39s(text: str, lexicon: Lexicon) -> str:
    """Session 39 (12s): blind37's corrections (above), each when what is left reads."""
    out = text
    m = _SLIP39S.search(out)
    if m is not None and _only_before39s(m["said"] or "", out[: m.start()], lexicon):
        cue = (m["cue"] or "").strip(" ,") or "sorry"
        out = f"{out[: m.start()]}{m['lead']}{cue}, {out[m.end() :]}"
    out = _HOLD_UP39S.sub(lambda m: f"{m['lead']}hold on", out)
    out = _GOES_TO39S.sub(lambda m: m["cue"], out)
    m = _WHAT_ASKED39S.search(out)
    if m is not None:
        people = _people39s(out[: m.start()], lexicon)
        who = m["who"]
        fits = (
            len(people) == 1 and _fit36(next(iter(people)), who, lexicon)
            if who.lower() in ("he", "she")
            else _ids(who, lexicon, "human") == people and len(people) == 1
        )
        if fits:
            out = f"{out[: m.start()]}{m['cue']}{m['x']}{m['end']}"
    m = _ONE_NEEDING39S.search(out)
    if m is not None and _only_person(m["p"], lexicon):
        out = f"{out[: m.start()]}{m['p']}'s the one who needs {m['it']}{m['end']}"
    m = _WHO_IS_ABOUT39S.search(out)
    if m is not None and _only_person(m["p"], lexicon):
        pid = next(iter(_ids(m["p"], lexicon, "human")))
        gone = _people39s(out[: m.start()], lexicon)
        if (m["pron"] is None or _fit36(pid, m["pron"], lexicon)) and (
            m["gone"] is None or not gone or any(_fit36(g, m["gone"], lexicon) for g in gone)
        ):  # ('he's not here' of a person the scene does not hold, too)
            out = f"{out[: m.start()]}{m['cue']}{m['p']}{m['end']}"
    m = _PLACE_NOT39S.match(out)
    if (
        m is not None
        and len(_ids(m["head"], lexicon, "object")) == 1
        and len(_people39s(m["head"], lexicon)) == 1
        and not _ids(m["head"], lexicon, "surface")
        and _ids(m["where"], lexicon)
        and _ids(m["where"], lexicon) <= _ids(m["where"], lexicon, "surface")
    ):
        out = f"{m['head']}, no, put it {m['where']}{m['end']}"
    if out == text:
        return text
    return out if _reading(out, lexicon) is not None else text


_STEPS39S: tuple[Callable[[str, Lexicon], str], ...] = ()
# (first: before every other rewrite, as _STEPS38S_FIRST)
_STEPS39S_FIRST: tuple[Callable[[str, Lexicon], str], ...] = (
    _remark39s,
    _remark_first39s,
    # (first: the older correction rules refuse a cue they cannot read)
    _corrections39s,
)
