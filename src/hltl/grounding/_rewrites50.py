"""The grounder's rules of session 50, engineer 12 (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _ids, _names, _only_person, _reading, _unknown_word
from hltl.grounding._normalise4 import _fit36
from hltl.grounding._rewrites44r import _agrees44r
from hltl.grounding._rewrites45 import _read_for
from hltl.grounding._rewrites46 import _APOLOGY_ONLY46
from hltl.grounding._rewrites48 import _GLOSS48
from hltl.grounding.lexicon import Lexicon
from hltl.grounding.tree import Node, tasks

# -- session 50 (engineer 12): blind48's refusals of politeness and fillers, wants and needs and
# questions, each read as a family. Every rule rewrites to words the grammar (or an older rule)
# already reads, and keeps the rewrite only when it reads.


def _cut50(text: str, start: int, end: int, put: str, lexicon: Lexicon) -> str:
    """``text`` with ``text[start:end]`` said as ``put`` (first letter upper-cased), when that
    reads; else ``text``."""
    out = f"{text[:start]}{put}{text[end:]}"
    return _read_for(out[:1].upper() + out[1:], text, None, lexicon)


# -- a word of thanks in another language glossed by who says it and where ("Daalu, as my mum
# says back in Lagos, and …", "Kinanaskomitin, as folk say out in Saskatchewan; …", "Gràtzias,
# as they'd put it in Cagliari: …"): the gloss taken off after the foreign word (session 48's
# _gloss48 reads 'as we say back home in Kosrae,'; session 41's 'as they say in Russian,')
_GLOSS50 = re.compile(
    r"^(?P<w>[^\W\d_]+(?: [a-z]+)?),\s*as (?:we|they|folk|people|you|my [a-z]+|our [a-z]+)"
    r"(?P<v>(?:'d| would)? (?:say|put it)| says| puts it| always says?| used to say)"
    r" (?P<pre>(?:back|out|over|up|down) )?(?:in|on) "
    r"(?P<place>[A-Z][a-z]+(?: [A-Z][a-z]+)?)\s*[,;:]\s*"
)


def _gloss50(text: str, lexicon: Lexicon) -> str:
    """Session 50: the gloss above taken off."""
    if " in " not in text and " on " not in text:
        return text
    m = _GLOSS50.match(text)
    if m is None or _names(m["place"], lexicon) or _GLOSS48.match(text):
        return text
    if not (m["pre"] or "put" in m["v"]):
        return text  # ('as they say in Russian,' is session 41's)
    if not all(_unknown_word(w, lexicon) for w in m["w"].split()):
        return text
    return _read_for(f"{m['w']}, {text[m.end() :]}", text, None, lexicon)


# -- 'only' opening the reason after an apology ("Sorry to trouble you, only Bob's parched after
# the gorge walking, so the bottle to him"): 'it's just that', taken off
_ONLY50 = re.compile(
    r"^(?:(?:I'm |I am |So |Ever so |Really )?[Ss]orry|Apologies|I hate to (?:ask|bother you|"
    r"trouble you|be a pain))[^,]{0,40}(?P<c>,\s*only )(?=(?P<p>[A-Z]\w*(?: [A-Z]\w*)?|she|he|"
    r"they)(?:'s|'re| is| are| has| have| was| were| needs| wants)\b)"
)


def _only50(text: str, lexicon: Lexicon) -> str:
    """Session 50: 'only' after an apology taken off."""
    if ", only " not in text:
        return text
    m = _ONLY50.match(text)
    if (
        m is None
        or _APOLOGY_ONLY46.match(text)
        or (m["p"][0].isupper() and not _only_person(m["p"], lexicon))
    ):
        return text
    return _read_for(f"{text[: m.start('c')]}, {text[m.end() :]}", text, None, lexicon)


# -- 'and no rush at all' between commas ("Whenever you're free, and no rush at all, Person A
# would like the chips"): said 'and no rush' (older rules read that)
_NO_RUSH50 = re.compile(r"(?<=, and )no (?P<r>rush|hurry) (?:at all|whatsoever)(?=\s*,)")


def _no_rush50(text: str, lexicon: Lexicon) -> str:
    """Session 50: 'and no rush at all' read as 'and no rush'."""
    if "and no " not in text:
        return text
    m = _NO_RUSH50.search(text)
    if m is None:
        return text
    return _cut50(text, m.start(), m.end(), f"no {m['r']}", lexicon)


# -- 'if it pleases you' / 'if it please you' ("If it pleases you, the spoon can go in the
# sink"): the courtesy 'if you please', no condition
_PLEASES50 = re.compile(r"\bif it pleases? you\b", _F)


def _pleases50(text: str, lexicon: Lexicon) -> str:
    """Session 50: 'if it pleases you' read as 'if you please'."""
    if "it pleas" not in text.lower():
        return text
    m = _PLEASES50.search(text)
    if m is None:
        return text
    return _cut50(text, m.start(), m.end(), "if you please", lexicon)


# -- 'With respect,' opening a request someone else said ("With respect, the boss says the torch
# goes to Jess, …"): a courtesy, taken off ('With respect,' before the request itself is read
# already, and session 33's _formal33t takes 'With all due respect,' off before 'the boss says')
_RESPECT50 = re.compile(
    r"^With (?:great )?respect\s*,\s*(?=(?:the [a-z]+|[A-Z]\w*(?: [A-Z]\w*)?) (?:says|said|"
    r"reckons|thinks)\b)"
)


def _respect50(text: str, lexicon: Lexicon) -> str:
    """Session 50: an opening 'With respect,' before a said request taken off."""
    if not text.startswith("With "):
        return text
    m = _RESPECT50.match(text)
    if m is None:
        return text
    return _cut50(text, 0, m.end(), "", lexicon)


# -- 'so it's out of the way (of …)' closing a placing ("Would you be able to pop the red mug down
# on the counter so it's out of the way of the sand sculpting photos?"): its reason, taken off
_OUT_OF_WAY50 = re.compile(
    r",?\s+so (?:that )?it(?:'s| is|'ll be| will be) (?:out of (?:the|his|her|their|"
    r"[A-Z]\w*(?: [A-Z]\w*)?'s) way|not in (?:the|his|her|their) way)(?: of [^,.!?]*)?"
    r"(?=\s*[.!?]?$)"
)


def _out_of_way50(text: str, lexicon: Lexicon) -> str:
    """Session 50: a closing 'so it's out of the way' taken off."""
    if " way" not in text:
        return text
    m = _OUT_OF_WAY50.search(text)
    if m is None:
        return text
    return _cut50(text, m.start(), m.end(), "", lexicon)


# -- 'as a thank you (for …)' after a request ("Could the chips go to Person A, as a thank you for
# the belly dancing display?"): said 'to say thank you' (older rules read that; what it is for
# taken off when it names nothing of the scene)
_THANK_YOU50 = re.compile(
    r",\s*as (?:a (?:little |small |big |wee )?thank[- ]you|thanks|a token of thanks)"
    r"(?P<for> for [^,;.!?]+)?(?=\s*[.!?]?$)"
)


def _thank_you50(text: str, lexicon: Lexicon) -> str:
    """Session 50: 'as a thank you' read as 'to say thank you'."""
    if "thank" not in text or " as " not in text:
        return text
    m = _THANK_YOU50.search(text)
    if m is None or (m["for"] and _names(m["for"], lexicon)):
        return text
    return _cut50(text, m.start(), m.end(), ", to say thank you", lexicon)


# -- 'P get his / her hands on the X' ("Might Person B get his hands on the bottle, …?"): P
# having the X, when the pronoun may be P
_HANDS_ON50 = re.compile(
    r"\b(?!(?:Could|Can|Might|May|Would|Will|Shall|Should) )(?P<p>[A-Z]\w*(?: [A-Z]\w*)?) get "
    r"(?P<a>his|her|their) hands on "
    r"(?=(?:the|a|an|some|that|those|these) )"
)


def _hands_on50(text: str, lexicon: Lexicon) -> str:
    """Session 50: 'P get his hands on the X' read as 'P have the X'."""
    if " hands on " not in text:
        return text
    m = _HANDS_ON50.search(text)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    pid = next(iter(_ids(m["p"], lexicon)))
    pro = {"his": "he", "her": "she", "their": "they"}[m["a"]]
    if not _agrees44r(pid, pro, lexicon):
        return text
    return _cut50(text, m.start(), m.end(), f"{m['p']} have ", lexicon)


# -- 'is there any chance of the X finding its way to P' ("Is there any chance of the apple
# finding its way to Person A, …?"): asked as 'could the X find its way to P'
_FINDING50 = re.compile(
    r"^(?:Is there |Would there be )?[Aa]ny chance of (?P<x>(?:the|that|those|these) [a-z]+"
    r"(?: [a-z]+)?) (?:finding|making) (?P<its>its|their) way "
)


def _finding50(text: str, lexicon: Lexicon) -> str:
    """Session 50: 'any chance of the X finding its way' read as 'could the X find its way'."""
    if "its way" not in text and "their way" not in text:
        return text
    m = _FINDING50.match(text)
    if m is None:
        return text
    return _cut50(text, 0, m.end(), f"Could {m['x']} find {m['its']} way ", lexicon)


# -- 'Is it okay with you to V' ("Is it okay with you to give Person A the bottle …?"): asked as
# 'Is it okay to V' (older rules read that)
_OK_WITH_YOU50 = re.compile(r"^Is it (?:okay|ok|OK|alright|all right) (?P<w>with you )(?=to )")


def _ok_with_you50(text: str, lexicon: Lexicon) -> str:
    """Session 50: 'Is it okay with you to' read as 'Is it okay to'."""
    if " with you to " not in text:
        return text
    m = _OK_WITH_YOU50.match(text)
    if m is None:
        return text
    return _cut50(text, m.start("w"), m.end("w"), "", lexicon)


# -- 'now her X's over' closing a request asked as a question ("Is it okay with you to give Person
# A the bottle now her snowshoeing's over?"): why now, taken off when the doing names nothing of
# the scene and the pronoun may be the one person who gets something (session 43's _now_over43s
# takes it off a want; an order said bare, "Give Tom the scanner now his tea break is over.",
# stays refused: 'now' may be when)
_NOW_OVER50 = re.compile(
    r",?\s+now (?:that )?(?P<pro>her|his|their) (?P<x>[a-z]+(?: [a-z]+)?)(?:'s| is| are|'re| "
    r"has| have) (?:over|done|finished|through|ended|wrapped up)(?=\s*\?$)"
)
_ASKED50 = re.compile(r"^(?:Could|Can|Would|Will|Might|May|Is it|Would it) ")


def asked_now_over50(text: str, lexicon: Lexicon) -> str:
    """Session 50: a closing 'now her X's over' taken off a request asked as a question. Since
    session 51 not a step of its own: the second way of `_rewrites50s._now_over50s`, the one
    rule of this family (12s read it after 'can P have X')."""
    if "now " not in text or not text.endswith("?") or not _ASKED50.match(text):
        return text
    m = _NOW_OVER50.search(text)
    if m is None or _names(m["x"], lexicon):
        return text
    out = f"{text[: m.start()]}{text[m.end() :]}"
    read = _reading(out, lexicon)
    if read is None:
        return text
    given = {t.target for t in tasks(read) if t.kind == "deliver"}
    if len(given) != 1 or not _fit36(next(iter(given)), m["pro"], lexicon):
        return text
    return out


# -- 'as someone reckons he's earned them' after a request ("How about the chips for Person B, as
# the tipster reckons he's earned them?"): the reason, said as 'as he's earned them' (read)
_RECKONS50 = re.compile(
    r",\s*as (?P<who>the [a-z]+|[A-Z]\w*(?: [A-Z]\w*)?) (?:reckons|says|thinks|reckoned|said|"
    r"thought|tells me) (?=(?:he|she|they)(?:'s|'ve| has| have) (?:earned|deserved) )"
)


def _reckons50(text: str, lexicon: Lexicon) -> str:
    """Session 50: 'as someone reckons he's earned them' read as 'as he's earned them'."""
    if " as " not in text or ("earned" not in text and "deserved" not in text):
        return text
    m = _RECKONS50.search(text)
    if m is None:
        return text
    return _cut50(text, m.start(), m.end(), ", as ", lexicon)


# -- 'P's making Q's tea' closing a request ("Would you stand the sippy cup on the high chair,
# Grandad's making Lily's tea?"): why, said 'P's making the tea' (read), when the meal names
# nothing of the scene and Q is one person of it
_MAKING50 = re.compile(
    r",\s*(?:[A-Z]\w*(?: [A-Z]\w*)?|he|she|they)(?:'s| is|'re| are) (?:making|getting|cooking|"
    r"doing|fixing|warming) (?P<q>[A-Z]\w*(?: [A-Z]\w*)?'s) (?P<m>tea|dinner|lunch|breakfast|"
    r"supper|snack|meal|bath|bottle|porridge|mash)(?=\s*[.!?]?$)"
)


def _making50(text: str, lexicon: Lexicon) -> str:
    """Session 50: 'P's making Q's tea' read as 'P's making the tea'."""
    if "ing " not in text or "'s " not in text:
        return text
    m = _MAKING50.search(text)
    if m is None or _names(m["m"], lexicon) or not _only_person(m["q"][:-2], lexicon):
        return text
    return _cut50(text, m.start("q"), m.end("q"), "the", lexicon)


# -- a remark that the person's old one broke ("Bob fancies the red mug, his old one cracked at
# the pinhole camera club."): why they want it, taken off when it names nothing of the scene
# ('his own one has died on him' is session 34's)
_OLD_ONE50 = re.compile(
    r",\s*(?:and )?(?:his|her|their) (?:old|own|last|usual) (?:one|[a-z]+) (?:has |had )?"
    r"(?:cracked|broke|broken|snapped|jammed|split|leaked|went missing|gone "
    r"missing|got lost|got broken)(?P<rest>[^,;.!?]*)(?=\s*[.!]?$)"
)


def _old_one50(text: str, lexicon: Lexicon) -> str:
    """Session 50: a closing 'his old one cracked …' taken off."""
    if " old " not in text and " own " not in text and " last " not in text and "usual" not in text:
        return text
    m = _OLD_ONE50.search(text)
    if m is None or _names(m.group(0).strip(", "), lexicon):
        return text
    return _cut50(text, m.start(), m.end(), "", lexicon)


# -- 'nothing since breakfast' between commas ("Bob is famished, nothing since breakfast, he could
# murder the crisps."): why, taken off when what it names is nothing of the scene
_NOTHING_SINCE50 = re.compile(
    r",\s*(?:had |eaten |)nothing(?: to eat| to drink| at all)? since (?P<w>[^,;.!?]+)(?=\s*,)"
)


def _nothing_since50(text: str, lexicon: Lexicon) -> str:
    """Session 50: a remark 'nothing since breakfast' taken off."""
    if "nothing" not in text:
        return text
    m = _NOTHING_SINCE50.search(text)
    if m is None or _names(m["w"], lexicon):
        return text
    return _cut50(text, m.start(), m.end(), "", lexicon)


# -- 'to take her cough syrup (with)' after a want ("Person A needs the cup to take her cough
# syrup."): what it is for, said 'for her cough syrup' (read), when that names nothing of the scene
_TO_TAKE50 = re.compile(
    r"\bto take (?P<x>(?:her|his|their) [a-z]+(?: [a-z]+)?)(?: with| down)?(?=\s*[.!]?$)"
)


def _to_take50(text: str, lexicon: Lexicon) -> str:
    """Session 50: 'to take her medicine' read as 'for her medicine'."""
    if "to take " not in text:
        return text
    m = _TO_TAKE50.search(text)
    if m is None or _names(m["x"].split(" ", 1)[1], lexicon):
        return text
    return _cut50(text, m.start(), m.end(), f"for {m['x']}", lexicon)


# -- a count of hours or rounds of a pastime after 'after' ("Person B is craving the apple after
# two hours of belly dancing."): said 'after belly dancing' (session 49's _after_pastime49 reads
# that)
_SPAN50 = re.compile(
    r"\bafter (?:two|three|four|five|six|several|a few|a couple of|many|countless|endless) "
    r"(?:long |solid )?(?:hours|minutes|rounds|games|days|weeks|laps|sets|sessions|goes) of "
    # (not "three hours of all that": no doing named, and session 37's count refusal stands)
    r"(?=[a-z])(?!(?:all that|all this|that|this|it all)\b)"
)


def _span50(text: str, lexicon: Lexicon) -> str:
    """Session 50: 'after two hours of X' in a want read as 'after X'."""
    if "after " not in text:
        return text
    m = _SPAN50.search(text)
    if m is None or m.start() == 0:
        return text  # (opening the text it is session 45's and 49's)
    return _cut50(text, m.start(), m.end(), "after ", lexicon)


# -- 'After a long day (as a bookie / at the till),' opening a want ("After a long day as a
# bookie, Person A could do with the chips."): why, taken off
_LONG_DAY50 = re.compile(
    r"^After (?:a|such a) (?:long|hard|busy|tough|rough) (?:day|shift|night|week|morning)"
    r"(?: (?:as|at|on|in) [^,;]{1,40})?\s*,\s*"
)


def _long_day50(text: str, lexicon: Lexicon) -> str:
    """Session 50: an opening 'After a long day as a bookie,' taken off."""
    if not text.startswith("After "):
        return text
    m = _LONG_DAY50.match(text)
    if m is None or _names(m.group(0), lexicon):
        return text
    return _cut50(text, 0, m.end(), "", lexicon)


# -- 'it's her first week as a vet nurse' closing a want: why, taken off
_FIRST_WEEK50 = re.compile(
    r",\s*(?:it's|it is) (?:her|his|their) (?:first|second|last) (?:day|week|shift|night|month)"
    r"(?: (?:as|at|on|in|here) [^,;.!?]{0,40}| here)?(?=\s*[.!]?$)"
)


def _first_week50(text: str, lexicon: Lexicon) -> str:
    """Session 50: a closing 'it's her first week as a vet nurse' taken off."""
    if "first " not in text and "second " not in text and "last " not in text:
        return text
    m = _FIRST_WEEK50.search(text)
    if m is None or _names(m.group(0), lexicon):
        return text
    return _cut50(text, m.start(), m.end(), "", lexicon)


# -- 'the thing P's most in need of (after …) is the X' ("Between you and me, the thing Person A's
# most in need of after the rag rugging is the bottle."): said 'P needs the X'; 'Between you and
# me,' before it taken off (the speaker is no recipient)
_THING_NEED50 = re.compile(
    r"^(?:Between you and me,\s*)?[Tt]he (?:thing|one thing) (?P<p>[A-Z]\w*(?: [A-Z]\w*)?)"
    r"(?:'s| is) (?:most |really |badly |sorely )?in (?:need|want) of(?P<why> (?:after|for|since) "
    r"[^,;]+?)? is (?P<x>(?:the|a|an|some) [a-z]+(?: [a-z]+)?)(?=\s*[.!]?$)"
)


def _thing_need50(text: str, lexicon: Lexicon) -> str:
    """Session 50: 'the thing P's most in need of is the X' read as 'P needs the X'."""
    if " in need of " not in text and " in want of " not in text:
        return text
    m = _THING_NEED50.match(text)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    if m["why"] and _names(m["why"], lexicon):
        return text
    return _cut50(text, 0, m.end(), f"{m['p']} needs {m['x']}", lexicon)


# -- 'being the only one without a drink' closing a want ("Person B would appreciate the bottle,
# being the only one without a drink."): why, taken off when it names nothing of the scene
_ONLY_ONE50 = re.compile(
    r",\s*(?:what with |since )?(?:him |her )?being the only one (?:without|with no|not to have|"
    r"who hasn't (?:got|had)|that hasn't (?:got|had)) (?P<w>[^,;.!?]+)(?=\s*[.!]?$)"
)


def _only_one50(text: str, lexicon: Lexicon) -> str:
    """Session 50: a closing 'being the only one without a drink' taken off."""
    if "being the only one" not in text:
        return text
    m = _ONLY_ONE50.search(text)
    if m is None or _names(m["w"], lexicon):
        return text
    return _cut50(text, m.start(), m.end(), "", lexicon)


# -- 'P's thirsty and reaching for her X' ("Lily's thirsty and reaching for her sippy cup."): the
# state said with a want ('P's thirsty and wants her X' is read)
_REACHING50 = re.compile(
    r"\b(?P<p>[A-Z]\w*(?: [A-Z]\w*)?)(?:'s| is) (?:thirsty|hungry|peckish|parched|starving|"
    r"famished|sleepy|tired|cold|bored) and (?P<v>(?:is )?(?:reaching|grabbing|stretching|"
    r"straining|crying|asking) for) "
)


def _reaching50(text: str, lexicon: Lexicon) -> str:
    """Session 50: 'P's thirsty and reaching for her X' read as '… and wants her X'."""
    if " for " not in text or " and " not in text:
        return text
    m = _REACHING50.search(text)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    return _cut50(text, m.start("v"), m.end("v"), "wants", lexicon)


# -- 'and the X is what P's hankering for' after a request ("Person A wants the bottle, and the
# chips are what Person B's hankering for."): said 'P wants the X' (opening the text it is read
# already; session 49's _what_wants49 reads 'what P would like')
_WHAT_AFTER50 = re.compile(
    r"(?P<lead>,\s*(?:and |while |but )?|;\s*)(?P<x>the [a-z]+(?: [a-z]+)?) (?:is|'s|are) "
    r"what (?P<p>[A-Z]\w*(?: [A-Z]\w*)?)(?:(?:'s| is) (?:after|hankering for|longing for|itching "
    r"for|pining for|gasping for|angling for|asking for|hoping for)| (?:wants|needs))"
    r"(?=\s*(?:[.!?,;]|$))"
)


def _what_after50(text: str, lexicon: Lexicon) -> str:
    """Session 50: 'the X is what P's hankering for' read as 'P wants the X'."""
    if " what " not in text:
        return text
    m = _WHAT_AFTER50.search(text)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    out = f"{text[: m.start()]}{m['lead']}{m['p']} wants {m['x']}{text[m.end() :]}"
    return _read_for(out, text, None, lexicon)


# -- a question who wanted it ("Was it Mr Lee or Mrs Khan who asked for the magazine? I've
# forgotten.", "Which patient was it that wanted the blue blanket, do you remember? Take it to
# them."): the speaker does not know who; refused naming the people it could be (it was refused
# as a question, naming no one), when nothing after the question names a person
_WHO_ASKED50 = re.compile(
    r"^(?:Was it (?P<p>[A-Z]\w*(?: [A-Z]\w*)?) or (?P<q>[A-Z]\w*(?: [A-Z]\w*)?)|Which "
    r"(?P<role>[a-z]+(?: [a-z]+)?) was it) (?:who|that) (?:asked for|wanted|needed|was after|"
    r"requested|ordered|put in for|asked after|was asking for)\b[^?]*\?"
)


def _label50(pid: str, lexicon: Lexicon) -> str:
    """Person ``pid`` said with its name and its first other name ('Person B (Mr Lee)')."""
    human = next(h for h in lexicon.scene.humans if h.id == pid)
    return f"{human.name} ({human.aliases[0]})" if human.aliases else human.name


def _who_asked50(text: str, lexicon: Lexicon) -> None:
    """Session 50: the question above refused naming the people it could be."""
    if not text.startswith(("Was it ", "Which ")):
        return
    m = _WHO_ASKED50.match(text)
    if m is None or _ids(text[m.end() :], lexicon, "human"):
        return
    if m["role"]:
        pids = sorted(_ids(f"the {m['role']}", lexicon, "human"))
    elif _only_person(m["p"], lexicon) and _only_person(m["q"], lexicon):
        pids = sorted(_ids(m["p"], lexicon) | _ids(m["q"], lexicon))
    else:
        return
    if len(pids) < 2:
        return
    raise GroundingError(
        "the speaker asks who wanted it: "
        + " or ".join(_label50(pid, lexicon) for pid in pids)
        + ": say who gets it"
    )


# the normaliser's first rewrites (wired into normalise._STEPS19, before the session-49 ones)
_STEPS50_FIRST: tuple[Callable[[str, Lexicon], str], ...] = (
    _gloss50,
    _only50,
    _no_rush50,
    _pleases50,
    _respect50,
    _out_of_way50,
    _thank_you50,
    _hands_on50,
    _finding50,
    _ok_with_you50,
    _reckons50,
    _making50,
    _old_one50,
    _nothing_since50,
    _to_take50,
    _span50,
    _long_day50,
    _first_week50,
    _thing_need50,
    _only_one50,
    _reaching50,
    _what_after50,
)
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-49 ones)
_STEPS50: tuple[Callable[[str, Lexicon], str], ...] = ()
# refusals asked of the text before it is read (offline._parse, after the session-49 ones)
REFUSE50: tuple[Callable[[str, Lexicon], None], ...] = (_who_asked50,)
# checks of the whole instruction's reading (offline.parse_instruction, after the session-49 ones)
CHECK50: tuple[Callable[[str, Node, Lexicon], None], ...] = ()
