"""The grounder's rules of session 45, engineer 12 (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import (
    _F,
    _ids,
    _names,
    _objects_only,
    _only_person,
    _reading,
    _unknown_word,
)
from hltl.grounding._rewrites44 import _NAME44, _PRONOUNS44, _agrees44
from hltl.grounding.lexicon import PRONOUN_SEX, Lexicon, unnamed_sex44l
from hltl.grounding.tree import Node, tasks

# -- session 45 (engineer 12): blind43's refusals of politeness and fillers, wants and needs,
# pronouns and ellipsis and questions, each read as a family. Every rule rewrites to words the
# grammar (or an older rule) already reads, and keeps the rewrite only when it reads; the person
# a he / she / his / her is said of must be the one the reading hands something to.


def _targets(node: Node) -> set[str]:
    """Everyone ``node`` hands something to."""
    return {t.target for t in tasks(node) if t.kind == "deliver"}


def _read_for(out: str, text: str, pid: str | None, lexicon: Lexicon) -> str:
    """``out`` when it reads (and, with ``pid``, hands things to that person only); else
    ``text``."""
    read = _reading(out, lexicon)
    if read is None or (pid is not None and _targets(read) != {pid}):
        return text
    return out


def _read_for_said(out: str, text: str, words: str, lexicon: Lexicon) -> str:
    """``out`` when it reads handing things to one person, whom every he / she of ``words`` may
    be (_agrees44); else ``text``."""
    read = _reading(out, lexicon)
    if read is None:
        return text
    given = _targets(read)
    if len(given) != 1 or not all(_agrees44(p, words, lexicon) for p in given):
        return text
    return out


def _fits_only45(pid: str, words: str, lexicon: Lexicon) -> bool:
    """Whether every he / him / she / her of ``words`` may be person ``pid`` (_agrees44), and,
    unless the scene says ``pid`` is of that sex, no one else of the scene is said to be."""
    if not _agrees44(pid, words, lexicon):
        return False
    said = {PRONOUN_SEX[w.lower()] for w in _PRONOUNS44.findall(words)}
    if len(said) != 1 or unnamed_sex44l(pid, lexicon) in said:
        return len(said) <= 1
    return not any(
        unnamed_sex44l(h.id, lexicon) in said for h in lexicon.scene.humans if h.id != pid
    )


def _person(words: str, lexicon: Lexicon) -> str | None:
    """The id of the one person ``words`` name (by a name of one or two words), or None."""
    if not _only_person(words, lexicon):
        return None
    (pid,) = _ids(words, lexicon, "human")
    return pid


# the second word of a thing's name is not one of these
_NOT_NOUN45 = r"(?!(?:again|yet|already|now|lying|sitting|about|around|out|here|there)\b)"


# -- a word of thanks or greeting in another language opening the request ("Yakoke, robot, when
# you get a sec could you hand Bob the blue mug?", "Seremein, erm, could Emma have the banana?"):
# a word no English word the grounder knows of, no name (first names included) and no typo of a
# name of the scene, before a comma and a word to the hearer or a filler: said as 'Thanks'
# (session 19's fillers take such a word off an order, but not off a question that opens with it)
_THANKS_WORD45 = re.compile(
    r"^(?P<w>[A-Za-z][a-z]+)(?:!|,)\s+(?=(?:robot|friend|machine|mate|pal|buddy|love|dear|erm|"
    r"um|umm|er|uh|so|now|right|well|oh)\b,?\s+(?:could|can|would|will|when|please|if|pass|give|"
    r"hand|bring|take|put)\b)",
    _F,
)


def _thanks_word45(text: str, lexicon: Lexicon) -> str:
    """Session 45: the opening word above said as 'Thanks,'."""
    m = _THANKS_WORD45.match(text)
    if m is None or not _unknown_word(m["w"], lexicon) or _names(m["w"], lexicon):
        return text
    return _read_for(f"Thanks, {text[m.end() :]}", text, None, lexicon)


# -- a remark closing the request that ends on when it happens ("Could Emma have the banana?
# She's got a snowshoe trek later.", "…, ta, I'm off to the cider press after this."): the time
# belongs to the remark (the speaker's or the person's plans), not to the request; taken off, the
# older remark rules take the rest off. The remark names nothing of the scene, and what is left
# must read as the request alone does.
_REMARK_TIME45 = re.compile(
    r"(?P<sep>[.?!]\s+|,\s*|;\s*)(?P<r>(?:he|she|they|i|we)(?:'s|'m|'re| is| am| are| has| have|"
    r"'ve)? (?:just |then |also )?(?:got|off to|going to|heading to|heading off to|due at|due to|"
    r"has|have|on|at)\b[^.?!,;]*?)\s+(?:later(?: on)?|tonight|after this|after that|afterwards|"
    r"this (?:afternoon|evening|morning)|in a bit|in a while|soon)(?P<end>\s*[.?!]*)\s*$",
    _F,
)


def _remark_time45(text: str, lexicon: Lexicon) -> str:
    """Session 45: the time closing a remark (above) taken off."""
    m = _REMARK_TIME45.search(text)
    if m is None or _names(m["r"], lexicon):
        return text
    alone = _reading(text[: m.start()] + (m["end"].strip() or "."), lexicon)
    out = text[: m.end("r")] + (m["end"].strip() or ".")
    read = _reading(out, lexicon)
    if read is None or alone is None or set(tasks(read)) != set(tasks(alone)):
        return text
    return out


# -- 'now (that)' before a remark of what the person has done ("Could you give Carol the red mug,
# now she's done with taxidermy class?"): the remark alone after the comma (older rules take it
# off when its he / she fits the person given to)
_NOW_SHE45 = re.compile(r",\s*now (?:that )?(?=(?:he|she)(?:'s| is| has)\b)", _F)


def _now_she45(text: str, lexicon: Lexicon) -> str:
    """Session 45: ', now she's …' said ', she's …'."""
    if "now" not in text.lower():
        return text
    m = _NOW_SHE45.search(text)
    if m is None:
        return text
    return _read_for(f"{text[: m.start()]}, {text[m.end() :]}", text, None, lexicon)


# -- someone not of the scene left a thing of it about, then a request for 'it' ("Right, um, the
# bootmaker left the bottle lying about, could you pop it up on the shelf for me?"): the request
# with the thing said for its pronoun. The one who left it names nothing of the scene; the thing
# names objects only, and the pronoun is of its number.
_LEFT_ABOUT45 = re.compile(
    r"(?P<open>^(?:(?:right|ok|okay|so|um|erm|er|oh|well|look)[,]?\s+)*)(?:the|our|my|some|a|an) "
    r"(?P<who>[a-z]+(?: [a-z]+)?) (?:has |'s )?(?:left|dumped|forgot|forgotten) "
    rf"(?P<x>(?:the|that|those|these) [a-z]+(?: {_NOT_NOUN45}[a-z]+)?) (?:lying |sitting )?"
    r"(?:about|around)"
    r"(?: (?:again|here|there))?\s*(?:,|;|\.|,? so)\s+(?P<req>.+)$",
    _F,
)


def _left_about45(text: str, lexicon: Lexicon) -> str:
    """Session 45: the remark above taken off, its thing said for the request's pronoun."""
    if "left" not in text.lower() and "dumped" not in text.lower() and "forgot" not in text:
        return text
    m = _LEFT_ABOUT45.match(text)
    if m is None or _names(m["who"], lexicon) or not _objects_only(m["x"], lexicon):
        return text
    pron = "them" if len(_ids(m["x"], lexicon, "object")) > 1 or m["x"].endswith("s") else "it"
    req = m["req"]
    if _names(req, lexicon) and _ids(req, lexicon, "object"):
        return text  # the request names a thing itself: 'it' is not needed
    if not re.search(rf"\b{pron}\b", req, _F):
        return text
    out = re.sub(rf"\b{pron}\b", m["x"].lower(), req, count=1, flags=_F)
    return _read_for(out[:1].upper() + out[1:], text, None, lexicon)


# -- 'what with his …' closing a want or an order (a reason: "Person B has been craving an apple
# all afternoon, what with his butoh rehearsal"), or opening it ("What with her shift, Alice needs
# the bottle"): taken off when it names nothing of the scene and its his / her fits the person
# the rest hands something to.
_WHAT_WITH45 = re.compile(
    r"(?:,\s*|\s+)what with (?P<w>[^,.;!?]+?)(?P<end>\s*[.!?]*)\s*$|^what with (?P<w2>[^,;]+?),\s*",
    _F,
)


def _what_with45(text: str, lexicon: Lexicon) -> str:
    """Session 45: the reason above taken off."""
    if "what with" not in text.lower():
        return text
    m = _WHAT_WITH45.search(text)
    if m is None:
        return text
    words = m["w"] or m["w2"]
    if _names(words, lexicon) or re.search(r"\b(?:it|them|that|this|those|these|one)\b", words, _F):
        return text
    if m["w"] is not None:
        out = text[: m.start()] + (m["end"].strip() or ".")
    else:
        rest = text[m.end() :]
        out = rest[:1].upper() + rest[1:]
    return _read_for_said(out, text, words, lexicon)


# -- a remark of what someone not of the scene did to the person's things, closing the want ("Person
# A's desperate for the chips, the peat cutter ate all her sandwiches"): taken off. The doer and
# what was done to name nothing of the scene; the his / her fits the one person the rest hands
# something to.
_THEY_DID45 = re.compile(
    r"(?P<sep>,\s*|;\s*)(?:the|a|an|some|our|my) (?P<who>[a-z]+(?: [a-z]+)?) (?P<v>[a-z]+ed|ate|"
    r"took|stole|drank|broke|had|nicked|pinched|swiped|scoffed|got|ate up|ran off with|made off "
    r"with) (?:all (?:of )?|the last of |most of |up )?(?P<pos>his|her) (?P<what>[a-z]+"
    r"(?: [a-z]+)?)(?P<end>\s*[.!]*)\s*$",
    _F,
)


def _they_did45(text: str, lexicon: Lexicon) -> str:
    """Session 45: the remark above taken off."""
    m = _THEY_DID45.search(text)
    if m is None or _names(m[0], lexicon):
        return text
    out = text[: m.start()] + (m["end"].strip() or ".")
    return _read_for_said(out, text, m["pos"], lexicon)


# -- a remark of a mess 'all over' something, and things 'coming apart' ("There's clay all over the
# bench from Omar's slip cast trial, so he needs the sponge", "Noah's marbling project is coming
# apart, he needs the glue stick"): 'all' and 'apart' here neither count nor leave out; said 'on'
# and 'to bits'. What the mess is and where name nothing but a surface of the scene.
_ALL_OVER45 = re.compile(
    r"\b(?P<head>there's|there is|there are|it's|it is) (?P<stuff>[a-z]+(?: [a-z]+)?) all over "
    r"(?=(?:the|his|her|their|my) [a-z])",
    _F,
)
_APART45 = re.compile(
    r"\b(?P<v>coming|falling|come|came|fallen|fell|gone|going) apart\b(?! from)(?=\s*[,.;!?]|"
    r"\s+(?:so|and|now)\b)",
    _F,
)


def _all_over45(text: str, lexicon: Lexicon) -> str:
    """Session 45: 'all over' said 'on', 'coming apart' said 'coming to bits' (above)."""
    low = text.lower()
    if "all over" not in low and "apart" not in low:
        return text
    out = text
    m = _ALL_OVER45.search(out)
    if m is not None and not _names(m["stuff"], lexicon):
        out = f"{out[: m.start()]}{m['head']} {m['stuff']} on {out[m.end() :]}"
    m = _APART45.search(out)
    if m is not None:
        out = f"{out[: m.start()]}{m['v']} to bits{out[m.end() :]}"
    return text if out == text else _read_for(out, text, None, lexicon)


# -- a time clause closing a need whose doer, not of the scene, does something to the person
# ("Mr Lee needs his tablets before the harness maker visits him"): the 'him' taken off (the older
# rule takes a deadline that names nothing off); it must fit the one person given to
_BEFORE_HIM45 = re.compile(
    r"\b(?P<head>(?:before|until|till|ahead of when) (?:the|a|an|his|her|their) [a-z]+"
    r"(?: [a-z]+)? [a-z]+s) (?P<pr>him|her)(?P<end>\s*[.!]*)\s*$",
    _F,
)


def _before_him45(text: str, lexicon: Lexicon) -> str:
    """Session 45: the pronoun of the time clause above taken off."""
    m = _BEFORE_HIM45.search(text)
    if m is None or _names(m["head"], lexicon):
        return text
    out = text[: m.end("head")] + (m["end"].strip() or ".")
    return _read_for_said(out, text, m["pr"], lexicon)


# -- a trade said 'by trade' in a remark ("…, he's a cockler by trade and loves it"): what the
# person is; the older remark rules read "he's a cockler and loves it"
_BY_TRADE45 = re.compile(
    r"(?P<head>(?:'s|\bis|\bwas) (?:a|an) [a-z]+(?: [a-z]+)?) by (?:trade|profession|calling)\b",
    _F,
)


def _by_trade45(text: str, lexicon: Lexicon) -> str:
    """Session 45: 'by trade' taken off."""
    if " by " not in text.lower():
        return text
    m = _BY_TRADE45.search(text)
    if m is None or _names(m["head"], lexicon):
        return text
    return _read_for(text[: m.end("head")] + text[m.end() :], text, None, lexicon)


# -- what the person lacks, then a request that hands it to them ("Person B hasn't had the cup yet,
# could you bring it to him?", "Sam's lost his stapler again, bring it to him", "Tom's out of tape.
# Can you get him some?"): said 'P needs X'. The person opens the text; X names objects only; what
# follows names no one else and its he / she / him / her fits the person; the reading hands
# things to that person only.
_LACKING45 = re.compile(
    rf"^{_NAME44}(?:'s| has| is)? (?:still |just )?(?P<v>hasn't had|has not had|hasn't got|has "
    r"not got|hasn't been given|has not been given|not had|lost|'s lost|has lost|run out of|'s run "
    r"out of|ran out of|out of|is out of|'s out of|mislaid|'s mislaid|has mislaid|can't find|"
    rf"cannot find) (?P<x>(?:(?:the|his|her|their|any|some) )?[a-z]+(?: {_NOT_NOUN45}[a-z]+)?)"
    r"(?: (?:again|"
    r"yet|already|now))?(?P<sep>\s*[,;.]\s*|\s*,?\s+so\s+)(?P<rest>.+)$",
    _F,
)


def _lacking45(text: str, lexicon: Lexicon) -> str:
    """Session 45: what the person lacks (above) said as their need."""
    low = text.lower()
    if not any(w in low for w in ("had", "got", "given", "lost", "out of", "mislaid", "find")):
        return text
    m = _LACKING45.match(text)
    if m is None:
        return text
    who = m["p"]
    for lead in ("Poor ", "poor "):
        who = who.removeprefix(lead)
    pid = _person(who, lexicon)
    if pid is None or not _objects_only(m["x"], lexicon):
        return text
    rest = m["rest"]
    if _ids(rest, lexicon, "human") - {pid} or not re.search(r"\b(?:him|her|he|she)\b", rest, _F):
        return text
    # what is handed is what was lacked, said by a pronoun of its number: "Zoe hasn't got a ruler,
    # give her the glue", "Sam's run out of pens, give him the black one", "Marco's lost his
    # tongs, get it to him" stay as they were (session 12's, 13's and 36's tests)
    if _ids(rest, lexicon, "object") or re.search(r"\b(?:one|ones|other|another)\b", rest, _F):
        return text
    many = len(_ids(m["x"], lexicon, "object")) > 1 or m["x"].lower().endswith("s")
    pron = re.findall(r"\b(?:it|them|some|any)\b", rest, _F)
    if not pron or any(
        (p.lower() == "it" and many) or (p.lower() == "them" and not many) for p in pron
    ):
        return text
    if not _fits_only45(pid, rest, lexicon) or not _agrees44(pid, m["x"], lexicon):
        return text  # "Sam hasn't had the stapler yet, could you bring it to her?": Priya?
    return _read_for(f"{who} needs {m['x']}{m['sep']}{rest}", text, pid, lexicon)


# -- a thing asked by itself, then the person with a please ("The bottle? Person A, please, she's
# the stonecutter."): 'the bottle to Person A, please'
_THING_Q45 = re.compile(
    r"^(?P<x>(?:the|that|those|these) [a-z]+(?: [a-z]+)?)\?\s+(?P<p>[A-Z][\w]*(?: [A-Z][\w]*)?),"
    r"\s*(?P<please>please|thanks|ta|cheers)\b",
    _F,
)


def _thing_q45(text: str, lexicon: Lexicon) -> str:
    """Session 45: 'X? P, please' said 'X to P, please'."""
    if "?" not in text:
        return text
    m = _THING_Q45.match(text)
    if m is None or not _objects_only(m["x"], lexicon):
        return text
    pid = _person(m["p"], lexicon)
    if pid is None:
        return text
    out = f"{m['x']} to {m['p']}, {m['please']}{text[m.end() :]}"
    return _read_for(out, text, pid, lexicon)


# -- a remark of where the person has been, then their want, in one clause ("The bottle's for
# Person A, she's back from tent pegging and wants it, take it over to her."): 'she wants it'
_BACK_AND45 = re.compile(
    r"\b(?P<pr>he|she)(?:'s| is) (?:just )?(?:back|home|in) from (?P<w>[a-z]+(?: [a-z]+){0,2}) "
    r"and (?=(?:wants|needs|would like|'d like|is after|could use|could do with)\b)",
    _F,
)


def _back_and45(text: str, lexicon: Lexicon) -> str:
    """Session 45: the remark above taken off the want."""
    if "from" not in text.lower():
        return text
    m = _BACK_AND45.search(text)
    if m is None or _names(m["w"], lexicon):
        return text
    out = f"{text[: m.start()]}{m['pr']} {text[m.end() :]}"
    return _read_for_said(out, text, m["pr"], lexicon)


# -- a pronoun said before the thing it stands for, with 'I mean' ("Person B wants them, the chips
# I mean."): the thing said in its place, when nothing else of the scene's things is named before
# and the pronoun is of its number
_I_MEAN45 = re.compile(
    r"^(?P<head>[^,;.]*?\b(?P<pr>it|them)\b[^,;.]*?),\s*(?:I mean )?(?P<x>(?:the|that|those|these) "
    r"[a-z]+(?: [a-z]+)?)(?: I mean)?(?P<end>\s*[.!]*)\s*$",
    _F,
)


def _i_mean45(text: str, lexicon: Lexicon) -> str:
    """Session 45: the pronoun said as the thing named after it (above)."""
    if "mean" not in text.lower():
        return text
    m = _I_MEAN45.match(text)
    if m is None or "mean" not in m[0][m.end("head") :].lower():
        return text
    if _ids(m["head"], lexicon, "object") or not _objects_only(m["x"], lexicon):
        return text
    if len(re.findall(r"\b(?:it|them)\b", m["head"], _F)) != 1:
        return text
    many = len(_ids(m["x"], lexicon, "object")) > 1 or m["x"].lower().endswith("s")
    if (m["pr"].lower() == "them") != many:
        return text
    head = m["head"]
    out = head[: m.start("pr")] + m["x"].lower() + head[m.end("pr") :] + (m["end"].strip() or ".")
    return _read_for(out, text, None, lexicon)


# -- 'Find the X;' before what is said of it ("Find the cup; Person A's been asking for it since
# the pantomime, give it to her."): the thing said for the first 'it' after it
_FIND_FIRST45 = re.compile(
    r"^(?:please )?(?:find|grab|locate|get|fetch|dig out|track down) "
    r"(?P<x>(?:the|that|those|these) [a-z]+(?: [a-z]+)?)\s*[;:.]\s+(?P<rest>.+)$",
    _F,
)


def _find_first45(text: str, lexicon: Lexicon) -> str:
    """Session 45: the opening order to find it said in the first pronoun after it."""
    m = _FIND_FIRST45.match(text)
    if m is None or not _objects_only(m["x"], lexicon):
        return text
    rest = m["rest"]
    if _ids(rest, lexicon, "object"):
        return text
    pron = "them" if len(_ids(m["x"], lexicon, "object")) > 1 or m["x"].endswith("s") else "it"
    p = re.search(rf"\b{pron}\b", rest, _F)
    if p is None:
        return text
    out = rest[: p.start()] + m["x"].lower() + rest[p.end() :]
    return _read_for(out[:1].upper() + out[1:], text, None, lexicon)


# -- an occasion after 'has had his eye on X' ("Person B's had his eye on the chips since the
# pantomime, so those go to him"): taken off (session 30's idiom reads the rest; session 41's
# occasion rule knows no 'eye on'), when it names nothing of the scene
_EYE_ON45 = re.compile(
    r"(?P<head>(?:'s| has) had (?:his|her|their) eyes? on (?:the|that|those|these) [a-z]+"
    r"(?: [a-z]+)?) since (?:the|his|her|their|a|an) [a-z]+(?: [a-z]+)?(?=\s*(?:[,.;!?]|$))",
    _F,
)


def _eye_on45(text: str, lexicon: Lexicon) -> str:
    """Session 45: the occasion above taken off, when that reads."""
    if "eye" not in text.lower():
        return text
    m = _EYE_ON45.search(text)
    if m is None or _names(m[0][len(m["head"]) :], lexicon):
        return text
    return _read_for(text[: m.end("head")] + text[m.end() :], text, None, lexicon)


# -- refusals naming the readings --------------------------------------------------------------
#
# 'the same X as yesterday' ("Dana's after the same cup as yesterday."): the scene does not say
# which one that was; refused naming each X of the scene when it has more than one
_SAME_AS45 = re.compile(
    r"\bthe same (?P<x>[a-z]+(?: [a-z]+)?) (?:as|that \w+ had|she had|he had) (?:yesterday|before|"
    r"last time|earlier|the other day|this morning|last week|last night|then|previously)\b",
    _F,
)


def _same_as45(text: str, lexicon: Lexicon) -> str:
    """Session 45: 'the same X as yesterday' refused naming each X of the scene."""
    if "same" not in text.lower():
        return text
    m = _SAME_AS45.search(text)
    if m is None:
        return text
    kinds = _ids(f"the {m['x']}s", lexicon, "object") | _ids(f"the {m['x']}", lexicon, "object")
    if len(kinds) < 2 or _ids(m["x"], lexicon, "human") or _ids(m["x"], lexicon, "surface"):
        return text
    if _ids(text[: m.start()] + text[m.end() :], lexicon, "object"):
        return text  # a thing named besides: left to the other rules
    raise GroundingError(
        f"'the same {m['x']}' as before: which one that was is not in the scene; it could mean "
        + " or ".join(sorted(kinds))
    )


# 'it' for nothing named, with one person ("Bob's still waiting on it after canoe polo, can you run
# it over to him?"): refused naming each thing of the scene it could be (the grammar refused it
# for too many names in one clause, naming none)
_WAITING_ON_IT45 = re.compile(
    r"\b(?:waiting (?:on|for)|asking (?:for|about)|on about|after|looking for|chasing) "
    r"(?:it|them)\b",
    _F,
)
_SOME_THING45 = re.compile(
    r"\b(?:drink|food|snack|bite|something|thing|things|one|ones|stuff|what|which|whatever)\b", _F
)


def _it_unnamed45(text: str, lexicon: Lexicon) -> str:
    """Session 45: the pronoun above refused naming what it could mean."""
    if "it" not in text.lower() and "them" not in text.lower():
        return text
    if _WAITING_ON_IT45.search(text) is None or _SOME_THING45.search(text):
        return text
    if _ids(text, lexicon, "object") or _ids(text, lexicon, "surface"):
        return text
    if len(_ids(text, lexicon, "human")) != 1 or len(lexicon.scene.objects) < 2:
        return text
    objs = [o.id for o in lexicon.scene.objects]
    raise GroundingError("'it' names nothing said before it: it could mean " + " or ".join(objs))


# the normaliser's rewrites run before the session-44 ones (wired into normalise._STEPS19)
_STEPS45_FIRST: tuple[Callable[[str, Lexicon], str], ...] = (
    _thanks_word45,
    _remark_time45,
    _now_she45,
    _left_about45,
    _what_with45,
    _they_did45,
    _all_over45,
    _before_him45,
    _by_trade45,
    _lacking45,
    _thing_q45,
    _back_and45,
    _i_mean45,
    _find_first45,
    _eye_on45,
    _same_as45,
    _it_unnamed45,
)
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-44 ones)
_STEPS45: tuple[Callable[[str, Lexicon], str], ...] = ()
# refusals asked of the text before it is read (offline._parse, after the session-44 ones)
REFUSE45: tuple[Callable[[str, Lexicon], None], ...] = ()
# checks of the whole instruction's reading (offline.parse_instruction, after the session-44 ones)
CHECK45: tuple[Callable[[str, Node, Lexicon], None], ...] = ()
