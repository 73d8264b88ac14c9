"""The grounder's rules of session 47, engineer 12 (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.grounding import gate as re
from hltl.grounding._normalise1 import (
    _COMMON,
    _F,
    _KEEP_WORDS,
    _ids,
    _names,
    _only_person,
    _reading,
    _unknown_word,
)
from hltl.grounding._normalise2 import _asks_nothing29
from hltl.grounding._rewrites45 import _read_for, _read_for_said
from hltl.grounding.lexicon import VERBS, Lexicon
from hltl.grounding.tree import Node, tasks

# -- session 47 (engineer 12): blind45's refusals of politeness and fillers, wants and needs,
# pronouns and ellipsis and questions, each read as a family. Every rule rewrites to words the
# grammar (or an older rule) already reads, and keeps the rewrite only when it reads.


# -- a condition of courtesy on the hearer being free ("Go on then, if you're not run off your
# feet, let Person A have the bottle", "…, if you're not too busy.", "If you're free, …"): the
# hearer's being busy is no state of the scene and no later event, only a courtesy, as 'if you've
# got a minute' (the lexicon's) is; taken off when what is left reads.
_NOT_BUSY47 = re.compile(
    r"(?P<sep>^|,|\s)\s*if you(?:'re| are) (?:not (?:too |that |very |terribly |awfully |so |all "
    r"that )?(?:busy|run off your feet|rushed off your feet|snowed under|swamped|flat out|"
    r"up to your (?:eyes|neck|ears)(?: in it)?|in the middle of something)|free|not busy)"
    r"(?: (?:right )?now| at the moment| just now)?\s*(?P<end>,|(?=[.!?]*\s*$))\s*",
    _F,
)


def _not_busy47(text: str, lexicon: Lexicon) -> str:
    """Session 47: the courtesy above taken off."""
    if "if you" not in text.lower():
        return text
    m = _NOT_BUSY47.search(text)
    if m is None:
        return text
    out = text[: m.start()] + (", " if m["sep"].strip() and m["end"] else "") + text[m.end() :]
    out = out.strip().lstrip(", ")
    out = out[:1].upper() + out[1:]
    return _read_for(out, text, None, lexicon)


# -- a word of thanks in another language glossed ("Ruth says jullay, which is Ladakhi for thank
# you, and asks …", "Kammagar, Yapese for thank you, and the flashlight to Kofi …"): the gloss
# (a capitalised word that names nothing of the scene, 'for thank you / thanks / please') taken
# off when what is left reads; the foreign word is read as older rules read it.
_GLOSS47 = re.compile(
    r",\s*(?:which is |which means |that's |that is |meaning |or |i\.e\. )?(?P<lang>[A-Z][a-z]+) "
    r"for (?:thank you|thanks|cheers|please)\s*(?=,)"
)


def _gloss47(text: str, lexicon: Lexicon) -> str:
    """Session 47: the gloss above taken off."""
    if " for " not in text:
        return text
    m = _GLOSS47.search(text)
    if m is None or _names(m["lang"], lexicon):
        return text
    out = text[: m.start()] + text[m.end() :]
    return _read_for(_said_asks47(out, lexicon) or out, text, None, lexicon)


# -- "Ruth says jullay(, …) and asks nicely that the magazine be put on the locker.": a person of
# the scene saying thanks (a word of thanks, or a word no English word the grounder knows) and
# asking (nicely, politely, kindly) that …: said 'Ruth asks that …', which the grammar reads
_SAYS_ASKS47 = re.compile(
    r"^(?P<p>[A-Z][\w' ]*?) says (?P<w>thanks|thank you|cheers|ta|[a-z]+),? and asks (?:(?:very |"
    r"so |ever so )?(?:nicely|politely|kindly|sweetly) )?(?=that )",
    _F,
)


def _said_asks47(text: str, lexicon: Lexicon) -> str | None:
    """``text`` with the thanks and the manner of asking above taken off, or None."""
    if " asks " not in text:
        return None
    m = _SAYS_ASKS47.match(text)
    if m is None or not _only_person(m["p"], lexicon):
        return None
    w = m["w"].lower()
    if w not in ("thanks", "thank you", "cheers", "ta") and not _unknown_word(w, lexicon):
        return None
    return f"{m['p']} asks {text[m.end() :]}"


def _says_asks47(text: str, lexicon: Lexicon) -> str:
    """Session 47: the thanks and the manner of asking above taken off."""
    out = _said_asks47(text, lexicon)
    return text if out is None else _read_for(out, text, None, lexicon)


# -- an occasion owned by a person of the scene ("… before Lily's nap", "… ahead of Grandad's
# snooze"): said 'before the nap' (the occasion rules of sessions 41 and 42 read 'before the
# nap', 'before her nap') when the occasion's words name nothing of the scene and ask nothing;
# 'for P's …' ("Would you put the red pen on the desk for Priya's paper marbling?") only in a
# reading that places things and hands nothing over
_OWNED_OCCASION47 = re.compile(
    r"\b(?P<prep>before|ahead of|for) (?P<p>[A-Z][\w]*(?: [A-Z][\w]*)?)'s (?P<what>[a-z][a-z -]*?)"
    r"(?=\s*(?:[.!?,;]|$))"
)


def _owned_occasion47(text: str, lexicon: Lexicon) -> str:
    """Session 47: the occasion above said without its owner."""
    if "'s " not in text:
        return text
    m = _OWNED_OCCASION47.search(text)
    if (
        m is None
        or not _only_person(m["p"], lexicon)
        or _KEEP_WORDS.search(m["what"])
        or not _asks_nothing29(m["what"], lexicon)
    ):
        return text
    out = f"{text[: m.start()]}{m['prep']} the {m['what']}{text[m.end() :]}"
    if m["prep"].lower() != "for":
        return _read_for(out, text, None, lexicon)
    # 'for P's …' may say whom a thing handed over is for: read only where nothing is handed
    read = _reading(out, lexicon)
    if read is None or any(t.kind != "place" for t in tasks(read)):
        return text
    return out


# -- wants and needs said in other words ("Person A's in sore need of the bottle", "Noah is keen
# to get hold of the ruler", "Tom would love to get his hands on the tape"): said 'needs' / 'wants'
# (which the grammar reads), kept only when the whole reads
_WANT_SAID47 = (
    (
        re.compile(
            # ('dire / real / urgent need of' is session 37's)
            r"(?:'s| is| are|'re) in (?:sore|desperate|great|serious|terrible|awful|bad|dreadful|"
            r"pressing) need of\b",
            _F,
        ),
        " needs",
    ),
    (
        re.compile(
            r"(?:'s| is| are|'re) (?:keen|eager|itching|dying|desperate|raring|mad keen) to "
            r"(?:get hold of|get (?:his|her|their) hands on|lay (?:his|her|their) hands on|"
            r"get (?:his|her|their) mitts on)\b",
            _F,
        ),
        " wants",
    ),
    (
        re.compile(
            r" would (?:love|like|kill|give anything) to (?:get hold of|get (?:his|her|their) "
            r"hands on|lay (?:his|her|their) hands on|get (?:his|her|their) mitts on)\b",
            _F,
        ),
        " wants",
    ),
)


def _want_said47(text: str, lexicon: Lexicon) -> str:
    """Session 47: the want or need above said 'wants' / 'needs'."""
    if " need of" not in text and " on" not in text and " of" not in text:
        return text
    out = text
    for pattern, said in _WANT_SAID47:
        out = pattern.sub(said, out, count=1)
    if out == text:
        return text
    return _read_for(out, text, None, lexicon)


# -- a time of work named by the trade worked in ("… after a long shift as a pinsetter", "…
# after her stint as a lollipop lady"): the trade (a word or two naming nothing of the scene)
# taken off, as the time alone ('after a long shift') is read as why
_AS_TRADE47 = re.compile(
    r"\b(?P<t>shift|stint|day|week|turn|spell|night|session|morning|afternoon|evening)s? as "
    r"(?:a|an|the) (?P<w>[a-z]+(?: [a-z]+)?)(?=\s*(?:[.!?,;]|$))",
    _F,
)


def _as_trade47(text: str, lexicon: Lexicon) -> str:
    """Session 47: the trade above taken off."""
    if " as " not in text:
        return text
    m = _AS_TRADE47.search(text)
    if m is None or _KEEP_WORDS.search(m["w"]) or not _asks_nothing29(m["w"], lexicon):
        return text
    out = text[: m.start()] + m["t"] + text[m.end() :]
    return _read_for(out, text, None, lexicon)


# -- what a doing is for, closing a want or a request ("Tom requires the work gloves for loading
# the basketmaker's order onto his van."): taken off (sessions 34 and 42 read a closed list of
# such doings bare: 'for loading') when its words name nothing of the scene and ask nothing, and
# its his / her may be the one person given to (_read_for_said)
_FOR_DOING47 = re.compile(
    r"(?P<head>\s*,?\s*\bfor (?P<g>[a-z]{3,}ing)) (?P<words>(?:the|a|an|his|her|their|some) "
    r"[^,;.!?]+?)(?P<end>\s*[.!?]*)\s*$",
    _F,
)


def _for_doing47(text: str, lexicon: Lexicon) -> str:
    """Session 47: the doing's object above taken off."""
    if "ing " not in text:
        return text
    m = _FOR_DOING47.search(text)
    if m is None:
        return text
    # (a doing the grounder reads, 'loading', asks nothing of a scene its words do not name)
    plain = re.sub(r"\b(?:his|her|their)\b", "the", m["words"], flags=_F)
    # a noun after a determiner or an owner ("the basketmaker's order") naming nothing of the
    # scene is no verb or request to read
    said = plain.split()
    plain = " ".join(
        "x"
        if i and re.fullmatch(r"the|a|an|[a-z]+'s", said[i - 1], _F) and not _names(w, lexicon)
        else w
        for i, w in enumerate(said)
    )
    if _KEEP_WORDS.search(plain) or not _asks_nothing29(plain, lexicon):
        return text
    out = text[: m.start()].rstrip(" ,") + m["end"].strip()
    return _read_for_said(out, text, m["words"], lexicon)


# -- 'all' before a word of how someone or something is, in a remark after the request or a
# 'now' ("…, she's all mucky from making loom bands", "now the kefir's all finished"): 'all' says
# 'wholly', no thing of the scene; taken off when the word after it names nothing (a closed list,
# or a word of how one is ending -ed / -y) and what is left reads (an opening "Tom's all sweaty,
# …" is session 44's)
_ALL_HOW47 = re.compile(
    r"(?<=\w)(?P<be>'s|'re| is| are| was| were| got| gets| looks| look) all "
    r"(?P<w>finished|done|gone|over|set|ready|in|out|alone|wet|hot|cold|ears|smiles|thumbs|"
    r"[a-z]+(?:ed|y|en))\b",
    _F,
)


def _all_how47(text: str, lexicon: Lexicon) -> str:
    """Session 47: the 'all' above taken off."""
    if " all " not in text:
        return text
    out = text
    for m in list(_ALL_HOW47.finditer(text))[::-1]:
        if _names(m["w"], lexicon) or _KEEP_WORDS.fullmatch(m["w"]):
            return text
        if not re.search(r"[,;]|\bnow\b", text[: m.start()], _F):
            return text  # "Tom's all sweaty, he needs …" opening the text is session 44's
        out = out[: m.start()] + m["be"] + " " + out[m.end("w") - len(m["w"]) :]
    if out == text:
        return text
    out = _asked_said47(_with_other47(out, lexicon) or out)
    return _read_for(out, text, None, lexicon)


# -- a closing remark on what the one given to was doing with another person of the scene
# ("Lily's wanting her bib, she's mucky from making loom bands with Ava."): 'with Ava' taken off
# (who the doing was with says why, not who gets), when the remark's he / she may be the one
# person given to and no one else of that sex (_read_for_said)
_WITH_OTHER47 = re.compile(
    r"(?P<r>,\s*(?:he|she)(?:'s| is| was| has been|'s been) [^,;.!?]+?) with "
    r"(?P<p>[A-Z][\w]*(?: [A-Z][\w]*)?)(?P<end>\s*[.!]*)\s*$"
)


def _with_other47(text: str, lexicon: Lexicon) -> str | None:
    """``text`` without the 'with P' above, or None."""
    if " with " not in text:
        return None
    m = _WITH_OTHER47.search(text)
    if m is None or not _only_person(m["p"], lexicon) or _KEEP_WORDS.search(m["r"][1:]):
        return None
    return text[: m.start()] + m["r"] + m["end"]


def _with_other_read47(text: str, lexicon: Lexicon) -> str:
    """Session 47: the remark above read without 'with P'."""
    out = _with_other47(text, lexicon)
    if out is None:
        return text
    m = _WITH_OTHER47.search(text)
    assert m is not None
    return _read_for_said(out, text, m["r"], lexicon)


# -- requests asked in other question forms, said as the forms the grammar reads: "Is there any
# chance of X landing / ending up / finding its way on Y?" ('Any chance of X going on Y?'),
# "Might the ruler find a home on the bookshelf?" ('go on'), "Might / Could P be given / handed
# X?" ('Could P have X?'), "… for P to receive X" ('to have'), "Would it be a hardship / an
# imposition to …?" ('Would it be a pain to …?'), "now the kefir's finished", "while he rests
# from the step dancing" (said as the remarks ', the kefir's finished', ', he's resting from …',
# which the grammar reads in a question too), "now she's back from …" (said with a comma); each
# kept only when the whole reads
_ON47 = r"(?=(?:on|onto|in|into|on to) (?:the|my|our|his|her) )"
_ASKED47: tuple[tuple[re.Pattern[str], str], ...] = (
    # ('is there' only with such a gerund: "Is there any chance of the cup for Bob?" is
    # session 36's)
    (
        re.compile(
            r"^(?:is there )?(?P<a>any chance of [^,;.?!]+?) (?:landing|ending up|winding up|"
            rf"finding its way|finding a (?:home|place|spot)|making its way) {_ON47}",
            _F,
        ),
        r"\g<a> going ",
    ),
    (
        re.compile(
            r"\b(?:land|end up|wind up|find its way|find a (?:home|place|spot)|make its way) "
            + _ON47,
            _F,
        ),
        "go ",
    ),
    (
        re.compile(
            r"^(?:might|could|can|may) (?P<p>[A-Z]\w*(?: [A-Z]\w*)?) be (?:given|handed|passed|"
            r"brought) (?=(?:the|a|an|some|his|her|their) )"
        ),
        r"Could \g<p> have ",
    ),
    (re.compile(r"(?<=\bto) receive\b", _F), " have"),
    (
        re.compile(
            r"^(?:would|will|is) it (?:be )?(?:a |an )?(?:hardship|imposition|chore|drag|faff|"
            r"trial|burden|big ask|lot to ask|struggle|headache) to ",
            _F,
        ),
        "Would it be a pain to ",
    ),
    (
        re.compile(
            r"\s+now (?:that )?(?P<s>the [a-z]+(?: [a-z]+)?)(?:'s| is) (?P<w>finished|done|gone|"
            r"over|empty|eaten|drunk|used up)\b",
            _F,
        ),
        r", \g<s>'s \g<w>",
    ),
    (
        re.compile(
            r"\s+while (?P<who>he|she) (?:rests|is resting|'s resting|recovers|is recovering|"
            r"'s recovering)\b",
            _F,
        ),
        r", \g<who>'s resting",
    ),
    # 'now she's back from …' in a question: said with the comma session 45 reads it with
    # (with its comma, session 45's `_now_she45` reads it)
    (re.compile(r"(?<![,;])\s+now (?=(?:he|she)(?:'s| is) back from\b)", _F), ", now "),
)


def _asked_said47(text: str) -> str:
    """``text`` with the question forms above said as the grammar's."""
    out = text
    for pattern, said in _ASKED47:
        out = re.sub(pattern, said, out, count=1)  # gated (session 53, 12p)
    return out[:1].upper() + out[1:] if out != text else text


def _asked47(text: str, lexicon: Lexicon) -> str:
    """Session 47: the question forms above said as the grammar's."""
    out = _asked_said47(text)
    if out == text:
        return text
    now = re.search(r"\bnow (?:that )?the (?P<w>[a-z]+(?: [a-z]+)?)(?:'s| is)", text, _F)
    if now is not None and _names(now["w"], lexicon):
        return text  # "Tom wants the scanner now the tape is done." is session 43's to refuse
    return _read_for(out, text, None, lexicon)


# -- what the one given to will do with the thing, naming another person of the scene ("Can the
# big sister, Ava, be handed the bib so she can feed Lily?", "Give Tom the scanner so he can
# check Mia's boxes"): the 'so he / she can …' taken off when its he / she may be the one person
# given to (_read_for_said), its verb is none the grounder reads (give, put, …) and its words,
# the person's name aside, ask nothing; an apposition 'the big sister, Ava,' (naming no one else)
# said 'Ava'
_SO_CAN47 = re.compile(
    r"\s+so (?:that )?(?P<who>he|she) (?:can|could|'ll|will) (?P<v>[a-z]+)(?P<w>(?: [^,;.!?]+)?)"
    r"(?P<end>\s*[.!?]*)\s*$",
    _F,
)
_APPOSED47 = re.compile(r"\bthe (?P<d>[a-z]+(?: [a-z]+)?), (?P<p>[A-Z]\w*(?: [A-Z]\w*)?), (?=be )")


def _so_can47(text: str, lexicon: Lexicon) -> str:
    """Session 47: the 'so she can …' above taken off."""
    if "so " not in text:
        return text
    m = _SO_CAN47.search(text)
    if m is None or m["v"].lower() in VERBS or m["v"].lower() not in _COMMON:
        return text
    words = " ".join(w for w in m["w"].split() if not _only_person(w.strip("'s"), lexicon))
    if words and (_KEEP_WORDS.search(words) or not _asks_nothing29(words, lexicon)):
        return text
    out = text[: m.start()] + m["end"].strip()
    a = _APPOSED47.search(out)
    if (
        a is not None
        and _only_person(a["p"], lexicon)
        and _ids(a["d"], lexicon) <= _ids(a["p"], lexicon)
        and (_names(a["d"], lexicon) or _asks_nothing29(a["d"], lexicon))
    ):
        out = out[: a.start()] + f"{a['p']} " + out[a.end() :]
    return _read_for_said(_asked_said47(out), text, m["who"], lexicon)


# the normaliser's first rewrites (wired into normalise._STEPS19, before the session-46 ones)
_STEPS47_FIRST: tuple[Callable[[str, Lexicon], str], ...] = (
    _not_busy47,
    _gloss47,
    _says_asks47,
    _owned_occasion47,
    _want_said47,
    _as_trade47,
    _for_doing47,
    _all_how47,
    _with_other_read47,
    _asked47,
    _so_can47,
)
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-46 ones)
_STEPS47: tuple[Callable[[str, Lexicon], str], ...] = ()
# refusals asked of the text before it is read (offline._parse, after the session-46 ones)
REFUSE47: tuple[Callable[[str, Lexicon], None], ...] = ()
# checks of the whole instruction's reading (offline.parse_instruction, after the session-46 ones)
CHECK47: tuple[Callable[[str, Node, Lexicon], None], ...] = ()
