"""The grounder's rules of session 48, engineer 12s (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _ids, _names, _only_person, _reading
from hltl.grounding._rewrites42r import _WHO42R
from hltl.grounding._rewrites44l import held_beside44l
from hltl.grounding._rewrites44s import _agrees44s
from hltl.grounding.lexicon import Lexicon, _one_edit, unaccented
from hltl.grounding.tree import Node, tasks

# -- session 48 (12s): a word with an accent (the lead's decision, session 48) -------------------
#
# "Not the red mug, the blue one, to Alice, she's off to her bodhrán lesson and likes that one.":
# a word with an accent that names nothing in the scene ('bodhrán', 'pétanque', 'café') is read as
# the same word without its accents would be ('bodhran'); the text had been refused as not English.
# Never a typo of a scene word: a word whose unaccented form names something of the scene, or is
# one edit from a word of a scene name ('bottlé', 'blüe'), stays refused (it may be the name
# mistyped or a foreign word alike), unless it is a word of a scene name that has the accent itself
# (a scene's 'Zoë': the lexicon reads its name as written or without the accent). A word in
# letters with no unaccented English form ('Алисе') stays refused.
_WORD48S = re.compile(r"[^\W\d_]+")


def _named_word48s(word: str, lexicon: Lexicon) -> bool:
    """Whether ``word`` (lower case, unaccented) is, or is one edit from, a word of a scene name
    (or a name the lexicon corrects it to)."""
    if lexicon.misspelt(word) is not None or lexicon.misspelt_keyword(word) is not None:
        return True
    return any(w == word or _one_edit(word, w) for w in lexicon.name_words())


def _accented_names48s(lexicon: Lexicon) -> frozenset[str]:
    """The unaccented words of the scene's names that have an accent ('zoe' of 'Zoë')."""
    sc = lexicon.scene
    names = [
        *(n for o in sc.objects for n in (o.id, o.category, *o.aliases)),
        *(n for h in sc.humans for n in (h.name, *h.aliases)),
        *(n for s in sc.surfaces for n in s.aliases),
    ]
    return frozenset(
        w.lower() for n in names if not n.isascii() for w in _WORD48S.findall(unaccented(n))
    )


def _accents48s(text: str, lexicon: Lexicon) -> str:
    """Session 48 (12s): each word with an accent read without it (above), when none of them
    could be a scene word mistyped."""
    if text.isascii():
        return text
    own = _accented_names48s(lexicon)
    out = text
    for word in dict.fromkeys(w for w in _WORD48S.findall(text) if not w.isascii()):
        plain = unaccented(word)
        if not plain.isascii() or not plain.isalpha():
            return text
        if plain.lower() not in own and _named_word48s(plain.lower(), lexicon):
            return text
        out = re.sub(rf"(?<![^\W\d_]){re.escape(word)}(?![^\W\d_])", plain, out)
    return out


# -- session 48 (12s): negation and exclusion (blind46's) ----------------------------------------
#
# "The bottle's not for me, it's for Person A.": a thing said not to be for the speaker, then the
# person it is for ('it's / they're for P'): "Give X to P." (the speaker is no person of the scene,
# so nothing is taken from anyone). The thing named whole, one person after; 'it's P's' (whose it
# is, not where it goes) is not read.
_NOT_FOR_ME48S = re.compile(
    r"^(?P<x>(?:the|that|this|those|these) [a-z]+(?: [a-z]+){0,2}?)(?:'s|'re| is| are)?"
    r"(?: not| n't|n't| never)(?: meant)? for (?:me|us)(?: at all)?\s*[,;:.]\s*"
    r"(?:it's|it is|they're|they are|that's|that is) (?:meant )?for (?P<p>[a-z]+(?: [a-z]+)?)"
    r"(?:,? (?:please|thanks|ta|cheers))?\s*[.!]?$",
    _F,
)


def _not_for_me48s(text: str, lexicon: Lexicon) -> str:
    """Session 48 (12s): "X's not for me, it's for P" read as "Give X to P." (above)."""
    if " for " not in text or not re.search(r"\bfor (?:me|us)\b", text, _F):
        return text
    m = _NOT_FOR_ME48S.match(text.strip())
    if m is None or not _only_person(m["p"], lexicon):
        return text
    x = re.sub(r"^(?:that|this|those|these) ", "the ", m["x"], flags=_F)
    named = _names(x, lexicon)
    if len(named) != 1 or any(r.kind != "object" for r in named[0].refs):
        return text
    if x.lower().removeprefix("the ").strip() != named[0].text.lower():
        return text  # the thing named whole
    out = f"Give {x} to {m['p']}."
    return out if _reading(out, lexicon) is not None else text


# "Omar needs neither cup, just the bowl.": 'neither X' of the two things X names, then what is
# wanted instead ('just / only Y'): read as the want of Y alone, X (exactly two objects) left out;
# Y names none of them.
_NEITHER48S = re.compile(
    r"\bneither (?P<x>(?:of )?(?:the |those |these )?(?:[a-z]+ ){0,2}?[a-z]+)\s*[,;]\s*"
    r"(?P<just>just|only|simply|but) (?P<y>(?:the |a |an )?[a-z]+(?: [a-z]+){0,2}?)"
    r"(?=\s*[,.;!?]|\s*$)",
    _F,
)


def _neither48s(text: str, lexicon: Lexicon) -> str:
    """Session 48 (12s): "P needs neither X, just / only Y" read as "P needs just Y" (above)."""
    if "neither" not in text.lower():
        return text
    m = _NEITHER48S.search(text)
    if m is None:
        return text
    x = _ids(m["x"], lexicon, "object")
    y = _ids(m["y"], lexicon, "object")
    if len(x) != 2 or not y or x & y or _ids(m["x"], lexicon) != x:
        return text
    out = f"{text[: m.start()]}just {m['y']}{text[m.end() :]}"
    node = _reading(out, lexicon)
    if node is None or any(t.obj in x for t in tasks(node)):
        return text
    return out


# "Everything but the apple to Person A, she can't stand apples and she's off to french
# skipping.": a closing remark that the person the request names dislikes a thing ('can't stand',
# 'can't abide', 'hates' …) which that person does not get there: it changes nothing of who gets
# what (session 39's rule for 'gone off X', 'sick of X'), and is taken off; a second remark after
# 'and' is left to the older rules. The pronoun fits the one person the request names; the thing
# is of the scene, and named again nowhere else.
_DISLIKE48S = re.compile(
    r"(?P<sep>\s*[,;]\s*|\s+[-–—]\s+)(?:and |as |cos |because )?(?P<pro>he|she)"
    r"(?: (?:can't|cannot|can not|can n't|won't|will not) (?:stand|abide|bear|stomach)|"
    r" (?:hates|loathes|detests|dislikes)|'s (?:allergic to|not keen on)| (?:is|'s) not keen on"
    r"| isn't keen on| is allergic to) (?P<x>(?:the |any )?[a-z]+)"
    r"(?P<rest>\s+and\s+(?:he|she)\b[^,;:.!?]*)?(?P<end>\s*[.!]?)\s*$",
    _F,
)


def _dislike48s(text: str, lexicon: Lexicon) -> str:
    """Session 48 (12s): a closing remark of a dislike of a thing the person does not get taken
    off (above)."""
    low = text.lower()
    if not any(
        w in low
        for w in (
            "stand",
            "abide",
            "bear",
            "stomach",
            "hate",
            "loathe",
            "detest",
            "dislike",
            "allergic",
            "keen",
        )
    ):
        return text
    m = _DISLIKE48S.search(text)
    if m is None:
        return text
    before = text[: m.start()]
    people = _ids(before, lexicon, "human")
    x = _ids(m["x"], lexicon, "object")
    if len(people) != 1 or not x or _ids(m["x"], lexicon) != x:
        return text
    who = next(it.text for it in _names(before, lexicon) if it.refs[0].kind == "human")
    if not _agrees44s(who, m["pro"], lexicon) or _ids(m["rest"] or "", lexicon):
        return text
    rest = m["rest"] or ""
    out = f"{before}{m['sep'].rstrip()} {rest.strip().removeprefix('and ')}" if rest else before
    out = out.rstrip() + (m["end"].strip() or ".")
    node = _reading(out, lexicon)
    if node is None or any(t.obj in x for t in tasks(node)):
        return text
    return out


# "The cup for Person A. The chips for Person B. The bottle and the apple can stay put.": 'X can /
# should / will stay put (where it is, there, as they are)' said as 'X stays put' (sessions 16, 28
# and 30's rules take off what stays where it is): where the whole then reads and gives or puts
# none of X.
_CAN_STAY48S = re.compile(
    r"(?P<x>(?:^|(?<=[.;,]))\s*(?:and )?(?:the |that |those )?[a-z]+(?: [a-z]+)?"
    r"(?: and (?:the |that )?[a-z]+(?: [a-z]+)?)?) (?:can|should|will|may|could|ought to|"
    r"is to|are to|'s to) (?:just |both |all )?stay(?P<rest> put| where (?:it is|they are)| "
    r"there| as (?:it is|they are))?(?=\s*(?:[.;,!]|$))",
    _F,
)


def _can_stay48s(text: str, lexicon: Lexicon) -> str:
    """Session 48 (12s): 'X can stay put' said as 'X stays put' (above)."""
    if "stay" not in text.lower():
        return text
    m = _CAN_STAY48S.search(text)
    if m is None:
        return text
    x = _ids(m["x"], lexicon, "object")
    if not x or _ids(m["x"], lexicon) != x:
        return text
    verb = "stay" if " and " in m["x"].lower() else "stays"
    out = f"{text[: m.start()]}{m['x']} {verb}{m['rest'] or ' put'}{text[m.end() :]}"
    node = _reading(out, lexicon)
    if node is None or any(t.obj in x for t in tasks(node)):
        return text
    return out


# -- session 48 (12s): what a person holds, said with their trade after the name -----------------
#
# 12c's asides fuzz (blind46 #163 with an aside): "person a the juggler already has the cup,
# cheers, we're all set" read `cup>A`: the trade after the name ('the juggler', no commas) hid
# 'already' from session 44's `held_beside44l`, which refuses "person a already has the cup, …"
# (it says what the person holds). Asked again with the trade taken out ('person a already has the
# cup, …'): the trade is 'the' and one or two words that name nothing of the scene but the person.
# A check of the reading (the trade rules take 'the juggler' and 'already' off first).
_APPOSED48S = re.compile(
    rf"(?P<who>{_WHO42R})\s+the (?P<ap>[a-z]+(?: (?!already\b|still\b)[a-z]+)?)"
    r"(?=\s+(?:already|still|has|'s got|"
    r"is holding|'s holding)\b)",
    _F,
)


def _held_apposed48s(text: str, _node: Node, lexicon: Lexicon) -> None:
    """Session 48 (12s): session 44's refusal of what a person holds, asked of the instruction as
    said (the trade rules take 'the juggler' and 'already' off before the refusals are asked)
    with the trade after the name taken out (above)."""
    low = text.lower()
    if " the " not in low or not any(w in low for w in ("has", "got", "holding")):
        return
    for m in _APPOSED48S.finditer(text):
        if not _only_person(m["who"], lexicon):
            continue
        named = _ids(m["ap"], lexicon)
        if named and named != _ids(m["who"], lexicon, "human"):
            continue
        held_beside44l(f"{text[: m.end('who')]}{text[m.end() :]}", lexicon)


# the normaliser's first rewrites (wired into normalise._STEPS19, before the session-47 ones)
_STEPS48S_FIRST: tuple[Callable[[str, Lexicon], str], ...] = (_accents48s,)
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-47 ones)
_STEPS48S: tuple[Callable[[str, Lexicon], str], ...] = (
    _not_for_me48s,
    _neither48s,
    _dislike48s,
    _can_stay48s,
)
# refusals asked of the text before it is read (offline._parse, after the session-47 ones)
REFUSE48S: tuple[Callable[[str, Lexicon], None], ...] = ()
# checks of the whole instruction's reading (offline.parse_instruction, after the session-47 ones)
CHECK48S: tuple[Callable[[str, Node, Lexicon], None], ...] = (_held_apposed48s,)
