"""The normaliser's rewrites of session 38, engineer 12s (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.grounding import gate as re
from hltl.grounding._normalise1 import (
    _F,
    _adjectives,
    _ids,
    _names,
    _names_nothing,
    _only_person,
    _reading,
)
from hltl.grounding._normalise2 import _things31
from hltl.grounding._normalise4 import _fit36
from hltl.grounding.lexicon import PRONOUN_SEX, VERBS, Lexicon
from hltl.grounding.tree import tasks

# -- session 38 (engineer 12s): a remark about a person of the scene, by kind ---------------------
#
# "…, Carol's just back from choir", "…? The intern is new on the team.", "…, Bob's a new
# starter": a clause whose subject is one person of the scene (a name or a role of theirs; a he /
# she of such a remark is left to the earlier rules, _about_them37 …) and whose words say something
# about them — a state, a pastime, where they have been — closing the instruction. It is taken
# off when what is left reads and names something of the scene, and no word of it could change
# who gets what or when (_ABOUT_HELD38S): no scene name or adjective, no verb of giving, putting,
# wanting or needing (light 'has', 'had', 'got' allowed; a word of VERBS used as a noun after a
# determiner, "a long shift", too), no negation, no count or choice, no pointing word, no
# correction, no time
# that could put the request off ('back at six', 'in a bit', 'later'; a stretch gone by, 'all
# day', 'for hours', is allowed), no leaving, being away or being done ('off home', 'gone', 'in
# the loo', 'due', 'she's fine', 'he's had enough'), no other person (him / her only of the
# subject), no speaker or hearer. A name said by the remark while the request has a pronoun for a
# person is left: the name may be whom the pronoun means ("Give her the cup, Carol's back from
# choir"). A need said of someone ("Bob's parched") is a hint to give them something: taken off
# only when they get something in what is left.

# a stretch of time gone by, and the idle words of a state, taken out before the held words
_GONE_BY38S = re.compile(
    r"\b(?:all (?:day|morning|afternoon|evening|night|week|weekend|shift)(?: long)?|since (?:dawn|"
    r"first thing|breakfast)|for (?:hours|ages|a while|days|weeks|months|years)(?: now)?|"
    r"(?:a|such a|another) (?:long|short|hard|busy|rough|tough|mad|hectic|quiet|slow) (?:day|"
    r"shift|week|night|morning|afternoon)|home from|only just|just|already(?= had\b))\b",
    _F,
)
# what a remark may not hold: negation, counts and choices, pointing words, the speaker and the
# hearer, what is whose, corrections, times and orders, wanting, needing, asking, giving
_HELD_WORDS38S = (
    r"no|not|never|nobody|none|nothing|nor|neither|without|except|but|unless|if|or|either|"
    r"one|ones|both|any|some|each|every|all|other|another|else|rest|same|pair|couple|half|few|"
    r"several|dozen|two|three|four|five|six|seven|eight|nine|ten|eleven|twelve|own|it|its|them|as|"
    r"they|their|theirs|hers|there|which|what|who|whom|whose|where|why|how|"
    r"me|my|mine|us|our|ours|we|i|i'm|you|your|yours|drink|drinks|snack|snacks|"
    r"actually|sorry|oops|whoops|mean|meant|mistake|scratch|wait|hang|hold|instead|rather|"
    r"correction|change|changed|forget|cancel|ignore|scrap|swap|switch|"
    r"before|after|once|when|whenever|while|until|till|later|soon|shortly|tonight|tomorrow|today|"
    r"now|then|next|first|last|finally|already|still|yet|again|too|also|only|minute|minutes|"
    r"hour|hours|mins?|sec|secs|second|seconds|moment|tick|jiffy|o'clock|noon|midday|midnight|"
    r"morning|afternoon|evening|night|week|weekend|day|lunch|dinner|tea|breakfast|supper|by|"
    r"monday|tuesday|wednesday|thursday|friday|saturday|sunday|"
    r"want|wants|wanted|wanting|need|needs|needed|needing|like|likes|liked|love|loves|loved|"
    r"fancy|fancies|prefer|prefers|preferred|keen|dying|craving|asked|ask|asks|asking|request|"
    r"requested|ordered|could|would|should|will|can|must|might|may|shall|ought|get|gets|getting|"
    r"given|giving|waiting|waited|hoping|hoped|expecting|queueing|queuing"
)
_HELD_MORE38S = r"|\b(?:has|have|had|got|'s|is|was|about) to\b|\bhis\s*$|n't\b|'ll\b|'d\b|\d"
_HELD38S = re.compile(rf"\b(?:{_HELD_WORDS38S})\b{_HELD_MORE38S}", _F)
# … and, said of a person beside a request, pointing at a thing, leaving, being away, arriving or
# being done
_ABOUT_HELD38S = re.compile(
    rf"\b(?:{_HELD_WORDS38S}|this|that|these|those|"
    r"off|away|out|gone|leaving|left|leave|going|goes|go|went|heading|headed|due|expected|coming|"
    r"comes|arriving|arrives|way|home|loo|toilet|bathroom|asleep|sleeping|napping|fine|sorted|set|"
    rf"good|okay|ok|alright|happy|done|finished|covered|served|full|fill|plenty|enough|over|"
    rf"through)\b"
    rf"{_HELD_MORE38S}",
    _F,
)
# a need said of someone: a hint to give them something
_NEEDY38S = re.compile(
    r"\b(?:thirsty|hungry|starving|starved|famished|peckish|parched|gasping|cold|freezing|chilly|"
    r"frozen|bored|desperate|dry|dehydrated)\b",
    _F,
)
# the verb after the subject: 's, is, was, has, had, or a word of a doing now or gone by
_ABOUT_VERB38S = re.compile(
    r"^(?:'s|\s+(?:is|was|has|had)\b|\s+(?:just |only just |always |finally )?(?!(?:as|us|yes|"
    r"plus|less|this|thus|his|hers|its|ours|yours|theirs|unless|across|towards|besides|perhaps|"
    r"always|sometimes|afterwards|needs|wants|gets|takes|likes|loves|says|asks|red)\b)(?:[a-z]{2,}"
    r"(?:s|ed)|got|came|spent|did|won|ran|swam|sang|rode|flew|slept|caught|drove|fought|taught|"
    r"built|made|kept|sat|stood|wrote|dug|threw|broke|felt|burnt)\b)(?=\s+\S)",
    _F,
)
# where the remark closes the instruction: after a comma, a semicolon, a dash or a sentence's end
_ABOUT_END38S = re.compile(
    r"(?P<sep>\s*[,;]\s*|\s+[—–-]\s+|(?<=[.!?])\s+)(?:(?:and|as|because|cos|'cause|oh|ah|well),?"
    r"\s+)?(?P<said>[^,;:.!?—–]+?)\s*[.!]?\s*$",
    _F,
)
# a correction's cue anywhere before the remark
_CUE_ANY38S = re.compile(
    r"\b(?:no|sorry|actually|wait|hang on|hold on|hang about|scratch that|i mean|i meant|"
    r"correction|rather|instead|oops|whoops|my mistake)\b",
    _F,
)
# a cue or a hesitation just before the remark: the remark may be what it corrects to
_CUED38S = re.compile(
    r"\b(?:no|nope|sorry|actually|wait|hang|hold|mean|meant|oops|whoops|er|erm|um|uh|rather|"
    r"instead|correction|scratch|or)\b",
    _F,
)
_DETERMINED38S = frozenset(
    {"a", "an", "the", "his", "her", "long", "short", "night", "late", "early", "double", "whole"}
    | {"busy", "hard", "pop", "extra"}
)


def _about_of38s(said: str, lexicon: Lexicon) -> str | None:
    """The person remark ``said`` is about, by a name or a role of theirs, or None where ``said``
    is no remark about one person of the scene that asks nothing (above)."""
    words = said.strip().split()
    for k in range(min(4, len(words)), 0, -1):
        head = " ".join(words[:k])
        subject = re.sub(r"'s$", "", head)
        rest = said.strip()[len(subject) :]
        if not _ABOUT_VERB38S.match(rest):
            continue
        if _only_person(subject, lexicon):
            who = next(iter(_ids(subject, lexicon, "human")))
            break
    else:
        return None
    plain = _GONE_BY38S.sub(" ", rest)
    if _ABOUT_HELD38S.search(plain) or not _names_nothing(rest, lexicon):
        return None
    tokens = [re.sub(r"'(?:s|re|ve|m)$", "", w) for w in re.findall(r"[a-z']+", plain.lower())]
    adjectives = {w for ws in _adjectives(lexicon).values() for w in ws}
    for n, w in enumerate(tokens):
        noun = n > 0 and tokens[n - 1] in _DETERMINED38S  # "a long shift", "her pop class"
        if w in adjectives or (w in VERBS and w not in ("has", "had", "have", "got") and not noun):
            return None
    # him / her / his only of the subject
    sexes = {PRONOUN_SEX[w] for w in re.findall(r"\b(?:he|him|his|she|her)\b", rest.lower())}
    if len(sexes) > 1:
        return None
    if sexes and not _fit36(who, "he" if sexes == {"m"} else "she", lexicon):
        return None
    return who


def _about_them38s(text: str, lexicon: Lexicon) -> str:
    """Session 38 (12s): remarks about one person of the scene closing the instruction taken off
    (above), one by one from the end, while what is left names something and reads; a need
    said only of someone who gets something there; session 53 (12s): 'Q's already had her X'
    only of someone who gets nothing there."""
    out = text
    needy: set[str] = set()
    over: set[str] = set()
    while (m := _ABOUT_END38S.search(out)) is not None:
        who = _about_of38s(m["said"], lexicon)
        before = out[: m.start()].rstrip()
        if who is None or not _names(before, lexicon):
            break
        last = re.split(r"[,;:.!?—–]\s|\s-\s", before.rstrip(" .!?"))[-1]
        if _CUED38S.search(last) and not _names(last, lexicon):
            break  # "Give Alice the apple, sorry, Carol's been waiting": what 'sorry' corrects
        if re.search(r"\b(?:he|him|his|she|her|hers|they|them|their)\b", before, _F):
            break  # "Give her the cup, Carol's back from choir": the name may be whom 'her' means
        cue = list(re.finditer(_CUE_ANY38S, before))  # gated (session 53, 12p)
        if cue and who in _ids(before[: cue[-1].start()], lexicon, "human"):
            break  # "…, scratch that, Mrs Khan does, Mr Lee won the bet": why, of whom taken back
        if _NEEDY38S.search(m["said"]):
            needy.add(who)
        if re.search(r"\balready had\b", m["said"], _F):
            over.add(who)  # session 53: what the person has already had says no more of theirs
        out = before if before[-1:] in (".", "!", "?") else before + "."
    if out == text:
        return text
    read = _reading(out, lexicon)
    if read is None or not needy <= {t.target for t in tasks(read)}:
        return text
    if over & {t.target for t in tasks(read)}:
        return text
    return out


# -- session 38 (engineer 12s): blind36's corrections, by kind ------------------------------------
#
# A correction cue, then words that say again what the correction is, or why: each is read as the
# plain correction when the words name nothing else of the scene and ask nothing (_HELD38S).
# a person said by name (as _P37 below)
_P38S = r"(?:Person [A-Z]|(?:Mrs|Mr|Ms|Miss|Dr) [A-Z][a-z]+|[A-Z][a-z]+)"
_CUE38S = (
    r"(?:no|nope|sorry|no sorry|actually|wait|no wait|hang on|hold on|hang about|scratch that|"
    r"correction|oh,? correction|i mean|my mistake)"
)
# "…, or actually, the locker would be better", "…, or wait, …": 'or' before a cue is the cue's
# ('or no' is session 37's)
_OR_CUE38S = re.compile(r",\s*or,?\s+(?P<cue>actually|wait|hang on|hold on)\s*,", _F)
# "…, wait, not the tape, …": the object taken back said again, negated
# (the cues the session-33 rules do not read this after: 'no', 'sorry', 'scratch that' … they do)
_NOT_TAKEN38S = re.compile(
    r"(?P<cue>(?<!\bno )\b(?:wait|hang on|hold on|hang about|actually)\s*,\s*)not "
    r"(?P<x>the [a-z][a-z ]*?)\s*,\s*",
    _F,
)
# "…, no sorry, Emma says on the tray", "…, she said the scanner": whose word the correction is
_SAID_SO38S = re.compile(
    rf"(?P<cue>\b{_CUE38S}\s*,\s*)(?P<who>he|she|{_P38S}) (?:said|says|reckons|told me)\s+"
    r"(?P<x>(?:(?:on|in|onto|into) )?the [a-z][a-z ]*?)(?=\s*(?:[,.!]|$))",
    _F,
)
# "…, scratch that, it's the cup she's after": the cleft of a want after a cue ('it's the X he
# wants / needs' after 'no', 'hang on' … is session 36's: here only after the cues it leaves)
_CLEFT_WANT38S = re.compile(
    rf"(?P<cue>\b{_CUE38S}\s*,\s*)it(?:'s| is) (?P<x>the [a-z][a-z ]*?) (?:(?P<p>he|she)(?:'s| is) "
    r"(?:after|wanting|asking for)|(?P<q>he|she) (?:wants|needs|asked for))(?P<end>\s*[.!]?)\s*$",
    _F,
)
_CLEFT_CUE38S = re.compile(r"\b(?:scratch that|correction|my mistake)\s*,\s*$", _F)
# "…, no, Bob, he's the one back from the kendama comp", "…, Ruth's the one taking temperatures
# on this ward, so her": the corrected person said to be the one (he / she after the name said
# alone, a name only with ', so him / her' after it), with what they are doing or have been
# doing, or where they are back from ("no, Bob's the one who is allergic" gives him nothing)
_THE_ONE38S = re.compile(
    rf"(?P<head>\b{_CUE38S}\b[^.;!?]*?),\s*(?:(?P<pron>he|she)|(?P<p>{_P38S}))(?:'s| is) the one"
    r" (?P<what>(?:(?:who|that)(?:'s| is| has) )?(?:just )?(?:(?:back|in|home) from|been|[a-z]+ing)"
    r"\b[^,.;!?]*?)(?:,\s*so (?P<so>him|her))?"
    r"(?P<end>\s*[.!]?)\s*$",
    _F,
)
# "…, actually, she's fine, it's Person B who's just finished the three-legged race": the person
# taken back needing nothing, and the person of the correction with what they have been doing
_FINE38S = re.compile(
    rf"(?P<cue>\b{_CUE38S}\s*,\s*)(?P<pron>he|she)(?:'s| is) (?:fine|ok|okay|sorted|all right|"
    r"alright|good|set)\s*,\s*(?=it(?:'s| is) )",
    _F,
)
_IT_WHO38S = re.compile(
    rf"(?P<head>\b{_CUE38S}\s*,\s*(?:[^,.;!?]+,\s*)?)it(?:'s| is) (?P<p>{_P38S}) (?:who|that)"
    r"(?:'s| is| has) (?P<what>[^,.;!?]+?)(?P<end>\s*[.!]?)\s*$",
    _F,
)
# "Person A gets the chips, no, the bottle, we're out of chips.": the reason says the object
# taken back is not to be had
_OUT_OF38S = re.compile(
    rf"(?P<old>(?:the |some |a |an )?(?P<x>[a-z]+))(?P<mid>\s*,\s*{_CUE38S}\s*,\s*)"
    r"(?P<new>(?:the|some|a|an) [a-z][a-z ]*?)\s*,\s*(?:we're|we are|we've|we have|they're|"
    r"you're|i'm)(?: all| clean| right)?(?: run)? out of (?:the |any )?(?P<y>[a-z]+)"
    r"(?P<end>\s*[.!]?)\s*$",
    _F,
)
# "Hand the bottle to, oh, what's she called, Person A, that's it, Person A.": a name searched for
# ('what's her name, …' is session 36's)
_NAME_SEARCH38S = re.compile(
    r"\b(?P<to>to|for),\s*(?:(?:oh|er|erm|um|uh|ah)\s*,?\s*)?what(?:'s| is) (?P<pron>he|she) "
    r"called(?: again)?\s*[,?]\s*(?P<p>" + _P38S + r")(?:\s*,\s*(?:that's "
    r"it|that's the one|that's right|yes|yeah)(?:\s*,\s*(?P<again>" + _P38S + r"))?)?"
    r"(?=\s*(?:[.!]|$))",
    _F,
)
# "…, er, my brain's fried from speedcubing, I mean the apple": the speaker's state said before
# the correction
_SLIP38S = re.compile(
    r",\s*(?P<er>er|erm|um|uh|oh|sorry)\s*,\s*(?:my (?:brain|head|mind|memory)(?:'s| is)|i'm|i am)"
    r" (?P<what>[^,.;!?]+?)\s*,\s*(?=(?:i mean|i meant|sorry|no)\b)",
    _F,
)


def _idle38s(words: str, lexicon: Lexicon) -> bool:
    """Whether ``words`` names nothing of the scene and holds no word of _HELD38S (a stretch gone
    by taken out first; a compound with a hyphen, 'three-legged', is one word)."""
    plain = re.sub(r"(?<=\w)-(?=\w)", "", _GONE_BY38S.sub(" ", words))
    return bool(plain.strip()) and not _HELD38S.search(plain) and _names_nothing(words, lexicon)


def _one_of38s(words: str, lexicon: Lexicon) -> str | None:
    """The person ``words`` names alone, or None."""
    return next(iter(_ids(words, lexicon, "human"))) if _only_person(words, lexicon) else None


def _corrections38s(text: str, lexicon: Lexicon) -> str:
    """Session 38 (12s): blind36's corrections by kind (above), each taken when what is left
    reads."""
    out = _OR_CUE38S.sub(lambda m: f", {m['cue']},", text)
    m = _NOT_TAKEN38S.search(out)
    if m is not None:
        x = _ids(m["x"], lexicon, "object")
        if x and x <= _ids(out[: m.start()], lexicon, "object") and _things31(m["x"], lexicon):
            out = out[: m.start()] + m["cue"] + out[m.end() :]
    m = _SAID_SO38S.search(out)
    if m is not None:
        before = out[: m.start()]
        said = _ids(m["x"], lexicon)
        surface = bool(said) and said <= _ids(m["x"], lexicon, "surface")
        who = _one_of38s(m["who"], lexicon)
        people = _ids(before, lexicon, "human")
        if m["who"].lower() in ("he", "she"):
            fit = [p for p in people if _fit36(p, m["who"], lexicon)]
            who = fit[0] if len(fit) == 1 else None
        # a delivery's object said by the person who gets it; a place said by anyone
        if (
            said
            and who is not None
            and (surface or (people == {who} and _things31(m["x"], lexicon)))
        ):
            out = out[: m.start()] + m["cue"] + m["x"] + out[m.end() :]
    m = _CLEFT_WANT38S.search(out)
    if m is not None and _things31(m["x"], lexicon) and (m["p"] or _CLEFT_CUE38S.search(m["cue"])):
        pron = m["p"] or m["q"]
        out = f"{out[: m.start()]}{m['cue']}{pron} wants {m['x']}{m['end']}"
    m = _THE_ONE38S.search(out)
    if m is not None and _idle38s(m["what"], lexicon):
        head = m["head"]
        last = _names(re.split(r",", head)[-1], lexicon)
        if m["pron"]:
            named = [it for it in last if it.refs[0].kind == "human"]
            if len(named) == 1 and len(named[0].refs) == 1:
                who = named[0].refs[0].id
                if _fit36(who, m["pron"], lexicon) and (
                    not m["so"] or _fit36(who, m["so"], lexicon)
                ):
                    out = f"{out[: m.start()]}{head}{m['end']}"
        elif (
            (who := _one_of38s(m["p"], lexicon)) is not None
            and not last
            and m["so"]
            and _fit36(who, m["so"], lexicon)
        ):
            out = f"{out[: m.start()]}{head}, {m['p']}{m['end']}"
    m = _FINE38S.search(out)
    if m is not None:
        taken = _ids(out[: m.start()], lexicon, "human")
        if len(taken) == 1 and _fit36(next(iter(taken)), m["pron"], lexicon):
            out = out[: m.start()] + m["cue"] + out[m.end() :]
    m = _IT_WHO38S.search(out)
    if m is not None and _one_of38s(m["p"], lexicon) and _idle38s(m["what"], lexicon):
        out = f"{out[: m.start()]}{m['head']}{m['p']}{m['end']}"
    m = _OUT_OF38S.search(out)
    if m is not None and m["x"].lower() == m["y"].lower() and _things31(m["new"], lexicon):
        if _ids(m["old"], lexicon):
            out = f"{out[: m.start()]}{m['old']}{m['mid']}{m['new']}{m['end']}"
        else:  # an object the scene does not hold, taken back: the new one in its place
            out = f"{out[: m.start()]}{m['new']}{m['end']}"
    m = _NAME_SEARCH38S.search(out)
    if (
        m is not None
        and (who := _one_of38s(m["p"], lexicon)) is not None
        and _fit36(who, m["pron"], lexicon)
        and (not m["again"] or _one_of38s(m["again"], lexicon) == who)
    ):
        out = f"{out[: m.start()]}{m['to']} {m['p']}{out[m.end() :]}"
    m = _SLIP38S.search(out)
    if m is not None and _idle38s(m["what"], lexicon):
        words = re.findall(r"[a-z']+", m["what"].lower())
        if not any(w in VERBS for w in words):
            out = f"{out[: m.start()]}, {m['er']}, {out[m.end() :]}"
    if out == text or _reading(out, lexicon) is None:
        return text
    return out


# "…, he's wanting the bottle for his hula hoop class", "Give Lena the lemon for her water": a
# purpose of the person's own closing the instruction, which changes nothing of who gets what
_FOR_THEIRS38S = re.compile(
    r"(?<=[a-z])\s+for (?P<pos>his|her) (?P<what>[a-z][a-z' -]*?)(?P<end>\s*[.!]?)\s*$", _F
)


# (a purpose named by its words alone; 'for her lesson on volcanoes' is an earlier rule's)
_PLACE_WORD38S = re.compile(r"\b(?:on|about|with|at|in|of|from|to|for|by|into|onto)\b", _F)


def _for_theirs38s(text: str, lexicon: Lexicon) -> str:
    """Session 38 (12s): 'for his / her <doing>' closing the instruction taken off (above) when
    its words are idle (_idle38s, no verb of VERBS), the pronoun may be a person named before it,
    and what is left names an object and reads."""
    m = _FOR_THEIRS38S.search(text)
    if m is None or not _idle38s(m["what"], lexicon) or _PLACE_WORD38S.search(m["what"]):
        return text
    if any(w in VERBS for w in re.findall(r"[a-z']+", m["what"].lower())):
        return text
    before = text[: m.start()]
    people = _ids(before, lexicon, "human")
    if not _ids(before, lexicon, "object") or not any(_fit36(p, m["pos"], lexicon) for p in people):
        return text
    out = before + (m["end"].strip() or ".")
    return out if _reading(out, lexicon) is not None else text


_STEPS38S: tuple[Callable[[str, Lexicon], str], ...] = (_corrections38s, _for_theirs38s)
# (first: a remark closing the instruction taken off, the rewrites read the request as if it were
# said alone)
_STEPS38S_FIRST: tuple[Callable[[str, Lexicon], str], ...] = (_about_them38s,)
