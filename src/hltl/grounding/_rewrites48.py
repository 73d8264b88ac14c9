"""The grounder's rules of session 48, engineer 12 (docs/grounding.md)."""

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
from hltl.grounding._rewrites39 import _WANTED39
from hltl.grounding._rewrites42s import _remark_only42s, _while_doing42s
from hltl.grounding._rewrites44 import _agrees44
from hltl.grounding._rewrites45 import _fits_only45, _person, _read_for, _targets
from hltl.grounding._rewrites47 import _asked47
from hltl.grounding.lexicon import VERBS, Lexicon
from hltl.grounding.tree import Node, tasks

# -- session 48 (engineer 12): blind46's refusals of politeness and fillers, wants and needs,
# pronouns and ellipsis and questions, each read as a family. Every rule rewrites to words the
# grammar (or an older rule) already reads, and keeps the rewrite only when it reads.


def _placing48(out: str, text: str, lexicon: Lexicon) -> str:
    """``out`` when it reads placing things only (a remark taken off that may say why); else
    ``text``."""
    read = _reading(out, lexicon)
    if read is None or any(t.kind != "place" for t in tasks(read)):
        return text
    return out


# -- 'like' as a filler between commas ("Um, so, like, whenever you're ready, could the cup go
# over to Person A?", "Like, the bottle to Bob, yeah?"): taken off
_LIKE48 = re.compile(r"(?:^|(?<=,))\s*like\s*,\s*", _F)


def _like48(text: str, lexicon: Lexicon) -> str:
    """Session 48: the filler 'like' above taken off."""
    if "like," not in text.lower():
        return text
    out = _LIKE48.sub(" ", text).strip()
    if out == text.strip():
        return text
    out = out.replace(" ,", ",")
    return _read_for(out[:1].upper() + out[1:], text, None, lexicon)


# -- a word of thanks in another language glossed by where it is said or who says it ("Kulo, as
# we say back home on Kosrae, could you …", "Meitaki, that's what my nan says in Rarotongan, and
# now the cup …"): the gloss taken off after an opening word no English word the grounder knows
# (older rules read such a word opening a request)
_GLOSS48 = re.compile(
    r"^(?P<w>[A-Z][a-z]+(?: [a-z]+)?),\s*(?:as (?:we|they|folk|people|my [a-z]+) (?:say|would "
    r"say|used to say|like to say)(?: it)?(?P<home> back home| at home| where I'm from| over "
    r"there| up north| down south)|that's what (?:we|they|folk|people|my [a-z]+) (?:say|says|"
    r"would say|used to say|always says?)(?: it)?(?P<home2> back home| at home| where I'm from| "
    r"over there| up north| down south)?)(?: (?:in|on|at|up in|down in|out in|over in) "
    r"(?P<place>[A-Z][a-z]+(?: [A-Z][a-z]+)?))?\s*,\s*"
)


def _gloss48(text: str, lexicon: Lexicon) -> str:
    """Session 48: the gloss above taken off."""
    if " say" not in text:
        return text
    m = _GLOSS48.match(text)
    if m is None or not all(_unknown_word(w, lexicon) for w in m["w"].split()):
        return text
    # ('as they say in Russian', 'as my gran would say' alone are session 41's)
    if not m["place"] or _names(m["place"], lexicon):
        return text
    return _read_for(f"{m['w']}, {text[m.end() :]}", text, None, lexicon)


# -- the speaker saying who they are ("Hiya, sorry, Sam here, the intern, could I possibly have
# the stapler …?", "Morning, Mia here, be a gem and set the small box on the belt"): the one
# person of the scene so named (and the role after it, if any, theirs) is the speaker: the
# introduction taken off and 'I' / 'me' of the request said as that person; the reading must
# hand things to them alone, or to no one
_HERE48 = re.compile(
    r"(?P<sep>^|,\s*)(?P<p>[A-Z]\w*(?: [A-Z]\w*)?) here(?:,\s*(?:the|your|a) (?P<role>[a-z]+(?: "
    r"[a-z]+)?))?\s*,\s*"
)
_I_ME48 = re.compile(
    r"\b(?P<q>can|could|may|might|shall) I\b|\b(?P<me>me)\b(?!,)|\b(?P<my>my)\b", _F
)


def _here48(text: str, lexicon: Lexicon) -> str:
    """Session 48: the introduction above taken off, its 'I' / 'me' said as the person."""
    if " here," not in text:
        return text
    m = _HERE48.search(text)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    pid = next(iter(_ids(m["p"], lexicon)))
    human = next(h for h in lexicon.scene.humans if h.id == pid)
    if m["p"] not in (human.name, *human.aliases):
        return text  # said by a role ('Teacher here, give me the globe.' stays refused: session 29)
    if m["role"] and _ids(m["role"], lexicon) != {pid}:
        return text
    rest = text[m.end() :]
    said = _I_ME48.sub(
        lambda i: f"{i['q']} {m['p']}" if i["q"] else m["p"] if i["me"] else f"{m['p']}'s", rest
    )
    out = f"{text[: m.start()]}{', ' if m['sep'] and m.start() else ''}{said}"
    out = out[:1].upper() + out[1:]
    read = _reading(out, lexicon)
    if read is None or (said != rest and _targets(read) != {pid}):
        return text
    if said == rest and (_targets(read) - {pid}) and " I " in f" {rest} ":
        return text
    return out


# an order's verb (a text holding one is no want statement alone)
_ORDER48 = re.compile(
    r"(?:^|[,;.!?]\s*|\band\s+|\bso\s+)(?:give|hand|pass|bring|take|put|get|fetch|pop|set|stick|"
    r"run)\b",
    _F,
)


# -- wants said in other words ("Person B would murder a bag of chips", "has set his sights on
# the chips", "has his sights set on", "'s got his eye on", "has got a craving for"): said
# 'wants', when the person said before it is one of the scene whom its his / her may be; kept
# when the whole reads. ('could murder a drink' is session 30's: a thing of the scene must follow)
_WANT_SAID48 = re.compile(
    r"(?P<head>(?:'s| has| had)(?: got)? set (?P<a>his|her|their) sights on|(?:'s| has) got "
    r"(?P<c>his|her|their) eyes? on| would (?:murder|demolish|devour) (?=(?:a|an|the|some|that|"
    r"those|these) ))",
    _F,
)


def _want_said48(text: str, lexicon: Lexicon) -> str:
    """Session 48: the want above said 'wants'."""
    low = text.lower()
    if not any(w in low for w in (" sights", " eye", " would ")):
        return text
    if _ORDER48.search(text) and len(_ids(text, lexicon, "object")) > 1:
        return text  # an order naming another thing: the want may be why, or a second request
    out, pos = text, 0
    while (m := _WANT_SAID48.search(out, pos)) is not None:
        pos = m.start() + 1
        clause = re.split(r"[,;.!?]\s*|\band\s+", out[: m.start()])[-1]
        pid = _person(clause.strip(), lexicon)
        pron = m["a"] or m["c"] or ""
        if pid is None or not _agrees44(pid, pron, lexicon):
            continue
        if "would" in m[0].lower():
            thing = re.split(r"[,;.!?]|\band\b", out[m.end() :])[0]
            if not _ids(thing, lexicon, "object"):
                continue
        out = f"{out[: m.start()]} wants {out[m.end() :].lstrip()}"
    if out == text:
        return text
    return _read_for(out, text, None, lexicon)


# -- a stretch of time at a pastime after a want ("… after an afternoon on the cowbell", "after a
# long morning at the allotment"): what tired them, said as session 39's 'after a go on the …',
# which takes it off a want of one person
_STRETCH48 = re.compile(
    r"\bafter (?:a|an) (?:(?:long|whole|busy|hard|full|entire) )?(?:afternoon|morning|evening|"
    r"day|night|hour|week|shift|stint|session|spell) (?:on|at) the (?P<w>[a-z]+(?: [a-z]+)?)"
    r"(?=\s*(?:[,.;!?]|$))",
    _F,
)


def _stretch48(text: str, lexicon: Lexicon) -> str:
    """Session 48: the stretch above said 'after a go on the …'."""
    if "after a" not in text.lower():
        return text
    m = _STRETCH48.search(text)
    if m is None or _KEEP_WORDS.search(m["w"]) or not _asks_nothing29(m["w"], lexicon):
        return text
    out = f"{text[: m.start()]}after a go on the {m['w']}{text[m.end() :]}"
    return _read_for(out, text, None, lexicon)


# -- a compound with hyphens in a pastime or purpose ("after her kite-flying", "for her
# dot-to-dot collage"): said as one word, as session 38's _idle38s reads it ('three-legged'),
# when no part of it names a thing of the scene
_HYPHENED48 = re.compile(
    r"\b(?P<prep>after|for) (?P<det>(?:his|her|their|the|a|an|all that) )?"
    r"(?P<c>[a-z]+(?:-[a-z]+)+)\b"
)


def _hyphened48(text: str, lexicon: Lexicon) -> str:
    """Session 48: the compound above said as one word."""
    if "-" not in text or _ORDER48.search(text) or not _WANTED39.search(text):
        return text
    out = text
    for m in reversed(list(_HYPHENED48.finditer(text))):
        if _names(m["c"].replace("-", " "), lexicon) or _KEEP_WORDS.search(m["c"]):
            continue
        out = out[: m.start("c")] + m["c"].replace("-", "") + out[m.end("c") :]
    if out == text:
        return text
    return _read_for(out, text, None, lexicon)


# -- a closing apposition saying what the thing will be ("Person B needs the cup for his penny
# whistle practice, a sip between tunes.", "Bob wants the apple, a snack for the bus."): a noun
# and what it is for, naming nothing and asking nothing, taken off when one person is given to
_APPOSED48 = re.compile(
    r",\s*(?:just )?(?:a|an) (?P<w>[a-z]+(?: [a-z]+)? (?:between|before|after|for|during|on|at|"
    r"in|to keep (?:him|her) going (?:till|until|through)) [a-z' ]+?)\s*(?P<end>[.!]?)\s*$",
    _F,
)


def _apposed48(text: str, lexicon: Lexicon) -> str:
    """Session 48: the apposition above taken off."""
    if ", a" not in text.lower():
        return text
    m = _APPOSED48.search(text)
    if (
        m is None
        or not _WANTED39.search(text[: m.start()])
        or not _remark_only42s(m["w"], lexicon)
        or any(w in VERBS for w in re.findall(r"[a-z']+", m["w"].lower()))
    ):
        return text
    out = text[: m.start()] + (m["end"] or ".")
    read = _reading(out, lexicon)
    if read is None or len(_targets(read)) != 1 or any(t.kind != "deliver" for t in tasks(read)):
        return text
    return out


# -- a question closing with what the one given to does meanwhile ("Would you mind giving Person
# B the bottle while he tunes the cittern?"): session 42's 'while he …' (12s's
# `_while_doing42s`, which reads it in an order) asked of the question said as an order
def _while_asked48(text: str, lexicon: Lexicon) -> str:
    """Session 48: the 'while he / she …' of a question taken off."""
    if " while " not in text or not text.rstrip().endswith("?"):
        return text
    if _asked47(text, lexicon) != text:
        return text  # ('be handed … while he rests from …' is session 47's)
    asked = text.rstrip()[:-1] + "."
    out = _while_doing42s(asked, lexicon)
    if out is asked:
        return text
    return _read_for(out.rstrip(".") + "?", text, None, lexicon)


# -- a remark that a person is done with the thing, then a question on where it goes, after a
# comma ("Marco's done with the knife, could you put it on the worktop?", "Priya's finished with
# the stapler, can it go in the box?"): the comma said ';', as the grammar reads the remark
_DONE_WITH48 = re.compile(
    r"^(?P<r>[A-Z][\w ]*?(?:'s| is| has) (?:done|finished|through) with (?:the|his|her|their) "
    r"[a-z]+(?: [a-z]+)?),\s*(?=(?:could|can|would|will) (?:you|it|they|that|those)\b)"
)


def _done_with48(text: str, lexicon: Lexicon) -> str:
    """Session 48: the comma above said ';'."""
    if " with " not in text:
        return text
    m = _DONE_WITH48.match(text)
    if m is None:
        return text
    return _placing48(f"{m['r']}; {text[m.end() :]}", text, lexicon)


# -- why a thing is to be placed: a person keeps knocking it over or into it ("Can the bowl go on
# the tray, Emma keeps knocking it over?"): taken off when it names one person of the scene and
# nothing else, its verb is none the grounder reads, and the reading places things only
_KEEPS48 = re.compile(
    r"[,;]\s*(?P<p>[A-Z]\w*(?: [A-Z]\w*)?) keeps (?P<v>knocking|tipping|kicking|bumping|"
    r"dropping|spilling|elbowing|nudging) it(?P<w>(?: (?:over|off|down|flying|everywhere|about|"
    r"around|on the floor))?)\s*(?P<end>[.!?]?)\s*$"
)


def _keeps48(text: str, lexicon: Lexicon) -> str:
    """Session 48: the reason above taken off."""
    if " keeps " not in text:
        return text
    m = _KEEPS48.search(text)
    if m is None or not _only_person(m["p"], lexicon) or m["v"].lower() in VERBS:
        return text
    return _placing48(text[: m.start()] + (m["end"] or "."), text, lexicon)


# -- what a wanted thing is for, said with a verb the grounder reads or a verb and its particle
# ("Jess needs the power drill to hang the new shelves.", "Jess needs the hanmer to knock together
# a stand for the serpent.", "person a wants the chips and the apple to take up to the airfix
# club"): session 46's `_to_purpose46` leaves verbs the grounder reads and takes no particle. Taken
# off after a want or need (no order) when its words name nothing of the scene: hanging or building
# what the scene does not hold, or taking the thing to a place the scene does not hold, is no
# task of the cell; the reading hands things to one person, whom its his / her may be
_PURPOSE48 = re.compile(
    r"(?P<sep>\s*,?\s+)to (?P<v>hang|put up|[a-z]+)(?: (?P<part>up|together|down|out|off|over|"
    r"along|back|round))? "
    r"(?P<rest>(?P<to>to )?(?:the|a|an|his|her|their|some) [a-z][a-z' -]*?)(?P<end>\s*[.!]*)\s*$",
    _F,
)
_MOVING48 = frozenset({"take", "bring", "carry", "cart", "ferry", "lug", "run"})


def _purpose48(text: str, lexicon: Lexicon) -> str:
    """Session 48: the purpose above taken off."""
    if " to " not in text:
        return text
    m = _PURPOSE48.search(text)
    if m is None or (m["v"].lower() in _MOVING48) != bool(m["to"]):
        return text
    # another verb: one the grounder does not read, with its particle ('strip down', 'knock
    # together'; without one it is session 46's)
    v = m["v"].lower()
    if v not in _MOVING48 | {"hang", "put up"} and (
        not m["part"] or v in VERBS or v not in _COMMON
    ):
        return text
    before = text[: m.start()]
    if not _WANTED39.search(before) or re.search(
        r"\b(?:give|hand|pass|put|take|bring)\b", before, _F
    ):
        return text
    rest = re.sub(r"\b(?:his|her|their)\b", "the", m["rest"], flags=_F)
    if not _remark_only42s(rest, lexicon) or _ids(rest, lexicon):
        return text
    out = before + m["end"].strip()
    read = _reading(out, lexicon)
    if read is None or len(given := _targets(read)) != 1:
        return text
    if not _agrees44(next(iter(given)), m["rest"], lexicon):
        return text
    return out


# -- what a thing is for, said with his / her inside a list of wants ("zoe needs the scissors
# for her paper snowman and noah the ruler"): session 38's `_for_theirs38s` takes it off only
# closing the text; here before 'and' and the next person, when its words name nothing and its
# his / her may be the person of its clause
_FOR_THEIRS48 = re.compile(
    r"\s+for (?P<pos>his|her|their) (?P<w>[a-z][a-z'-]*(?: [a-z][a-z'-]*){0,2})(?=,?\s+and\s+"
    r"(?P<next>[A-Za-z]\w*(?: [A-Za-z]\w*)?) (?:the|a|an|his|her|their)\b)",
    _F,
)


def _for_theirs48(text: str, lexicon: Lexicon) -> str:
    """Session 48: the 'for his / her …' above taken off."""
    if " for " not in text:
        return text
    m = _FOR_THEIRS48.search(text)
    if m is None or not _only_person(m["next"], lexicon):
        return text
    clause = re.split(r"[,;.!?]\s*|\band\s+", text[: m.start()])[-1]
    pid = _person(clause.split(" ")[0], lexicon) or _person(" ".join(clause.split()[:2]), lexicon)
    if pid is None or not _agrees44(pid, m["pos"], lexicon) or not _WANTED39.search(clause):
        return text
    if not _remark_only42s(m["w"], lexicon) or _ids(m["w"], lexicon):
        return text
    return _read_for(text[: m.start()] + text[m.end() :], text, None, lexicon)


# -- a person said first by a pronoun and named after with the verb again ("She's asking for the
# bottle, Person A is, so let her have it.", "He wants the crisps, Bob does, …"): said with the
# name first, when the pronoun may be that person
_SHE_IS48 = re.compile(
    r"^(?P<pro>She|He)(?P<clause>(?:'s| is| wants| needs| has| would| fancies)[^,;.!?]*?),\s*"
    r"(?P<p>[A-Z]\w*(?: [A-Z]\w*)?) (?:is|does|has|would|do)\s*(?P<end>,|[.!]?\s*$)"
)


def _she_is48(text: str, lexicon: Lexicon) -> str:
    """Session 48: the person above said first."""
    if not text.startswith(("She", "He")):
        return text
    m = _SHE_IS48.match(text)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    pid = next(iter(_ids(m["p"], lexicon)))
    if not _fits_only45(pid, m["pro"], lexicon) or _ids(m["clause"], lexicon, "human"):
        return text
    out = f"{m['p']}{m['clause']}{m['end']}{text[m.end() :]}"
    return _read_for(out, text, None, lexicon)


# -- who a person is, asked back with a tag ("Omar's the technician, isn't he? Take him the
# bowl."): the tag taken off when the role is that person's own and the tag's he / she may be them
_TAG48 = re.compile(
    r"^(?P<r>(?P<p>[A-Z]\w*(?: [A-Z]\w*)?)(?:'s| is) (?:the|our|your) "
    r"(?P<role>[a-z]+(?: [a-z]+)?)),\s*(?:isn't|is not|ain't) (?P<pro>he|she)\?\s+"
)


def _tag48(text: str, lexicon: Lexicon) -> str:
    """Session 48: the tag above taken off."""
    if "n't " not in text and " not " not in text:
        return text
    m = _TAG48.match(text)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    pid = next(iter(_ids(m["p"], lexicon)))
    if _ids(m["role"], lexicon) != {pid} or not _fits_only45(pid, m["pro"], lexicon):
        return text
    return _read_for(f"{m['r']}. {text[m.end() :]}", text, pid, lexicon)


# the normaliser's first rewrites (wired into normalise._STEPS19, before the session-47 ones)
_STEPS48_FIRST: tuple[Callable[[str, Lexicon], str], ...] = (
    _like48,
    _gloss48,
    _here48,
    _want_said48,
    _stretch48,
    _hyphened48,
    _apposed48,
    _purpose48,
    _for_theirs48,
    _while_asked48,
    _done_with48,
    _keeps48,
    _she_is48,
    _tag48,
)
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-47 ones)
_STEPS48: tuple[Callable[[str, Lexicon], str], ...] = ()
# refusals asked of the text before it is read (offline._parse, after the session-47 ones)
REFUSE48: tuple[Callable[[str, Lexicon], None], ...] = ()
# checks of the whole instruction's reading (offline.parse_instruction, after the session-47 ones)
CHECK48: tuple[Callable[[str, Node, Lexicon], None], ...] = ()
