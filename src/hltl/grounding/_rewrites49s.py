"""The grounder's rules of session 49, engineer 12s (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _ids, _names, _objects_only, _only_person, _reading
from hltl.grounding._rewrites42r import _WHO42R
from hltl.grounding._rewrites42s import _NEGATED42S
from hltl.grounding._rewrites44s import _agrees44s
from hltl.grounding._rewrites45s import _CORRECTS45S
from hltl.grounding.lexicon import Lexicon
from hltl.grounding.tree import Node, tasks


def _one_person49s(text: str, lexicon: Lexicon) -> str | None:
    """The words naming the one person ``text`` names, or None where it names none or several."""
    if len(_ids(text, lexicon, "human")) != 1:
        return None
    return next(it.text for it in _names(text, lexicon) if it.refs[0].kind == "human")


# -- session 49 (12s): sentence splits and run-ons (blind47's) -----------------------------------
#
# "Person A, the apple. Person B, the cup, he's got the boxercise class after. And the bottle to
# Person A on top.": 'on top' (of that) closing a handover to a person says 'as well' (the person
# is no surface to put a thing on): said 'as well', when the words before it name one person of
# the scene and the scene has no surface called 'top'.
_ON_TOP49S = re.compile(
    r"\b(?P<to>to|for) (?P<p>[a-z]+(?: [a-z]+)?) on top(?: of (?:that|this|it all|all that|"
    r"everything(?: else)?))?(?=\s*(?:[.!;,]|$))",
    _F,
)


def _on_top49s(text: str, lexicon: Lexicon) -> str:
    """Session 49 (12s): 'to P on top' said 'to P as well' (above)."""
    if "on top" not in text.lower() or "top" in lexicon.name_words():
        return text
    m = _ON_TOP49S.search(text)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    out = f"{text[: m.end('p')]} as well{text[m.end() :]}"
    return out if _reading(out, lexicon) is not None else text


# -- session 49 (12s): negation and exclusion (blind47's) ----------------------------------------
#
# "Give Person A the bottle, and don't keep her waiting.": a closing 'don't keep / leave her
# waiting' (hurry, asks nothing more) taken off, when the pronoun may be the one person the
# request names ('them': two or more people named) and what is left reads.
_KEEP_WAITING49S = re.compile(
    r"\s*[,;]\s*(?:and |but |so |just )?(?:please )?(?:don't|dont|do not) (?:keep|leave) "
    r"(?P<pro>her|him|them) (?:waiting|hanging(?: on| about| around)?)(?: (?:any longer|too "
    r"long|long|about|around))?(?:,? please)?(?P<end>\s*[.!]?)\s*$",
    _F,
)


def _keep_waiting49s(text: str, lexicon: Lexicon) -> str:
    """Session 49 (12s): the closing hurry above taken off (above)."""
    low = text.lower()
    if "waiting" not in low and "hanging" not in low:
        return text
    m = _KEEP_WAITING49S.search(text)
    if m is None:
        return text
    before = text[: m.start()]
    pro = m["pro"].lower()
    if pro == "them":
        if len(_ids(before, lexicon, "human")) < 2:
            return text
    else:
        who = _one_person49s(before, lexicon)
        if who is None or not _agrees44s(who, "she" if pro == "her" else "he", lexicon):
            return text
    out = before.rstrip() + (m["end"].strip() or ".")
    return out if _reading(out, lexicon) is not None else text


# "Person B is the one who asked for the bottle, so don't go giving it to Person A.": 'don't go
# giving / go and give' said 'don't give' (the older rules read a 'don't give it to P' that the
# request before does not do).
_VERB49S = {
    "giving": "give",
    "handing": "hand",
    "passing": "pass",
    "taking": "take",
    "bringing": "bring",
    "sending": "send",
    "putting": "put",
    "placing": "place",
}
_DONT_GO49S = re.compile(
    rf"\b(?P<neg>don't|dont|do not) go (?:and )?(?P<v>{'|'.join(_VERB49S)}|"
    rf"{'|'.join(_VERB49S.values())})(?=\s)",
    _F,
)


def _dont_go49s(text: str, lexicon: Lexicon) -> str:
    """Session 49 (12s): "don't go giving" said "don't give" (above)."""
    if " go " not in text.lower():
        return text
    out = _DONT_GO49S.sub(
        lambda m: f"{m['neg']} {_VERB49S.get(m['v'].lower(), m['v'].lower())}", text
    )
    if out == text:
        return text
    return out if _reading(out, lexicon) is not None else text


# "It's the sippy cup Lily's reaching for, not the bib.": a want said by what the person reaches,
# points or cries for, in the cleft 'It's the X P's reaching for, not the Y' (a thing said
# instead of another): said 'It's the X P wants, not the Y', when P is one person of the scene,
# X and Y things of it.
_CLEFT_REACH49S = re.compile(
    r"^(?P<it>it's|it is|it was) (?P<rest>(?:the|that) [a-z]+(?: [a-z]+){1,4}?)(?:'s| is| was|'s "
    r"been| has been) (?:reaching|pointing|grabbing|crying|crying out|angling|gesturing|"
    r"straining|itching) (?:for|at|towards)(?P<not>\s*,\s*(?:and |but )?not (?:the|that) "
    r"[a-z]+(?: [a-z]+){0,2}?\s*[.!]?)\s*$",
    _F,
)


def _cleft_reach49s(text: str, lexicon: Lexicon) -> str:
    """Session 49 (12s): 'It's the X P's reaching for, not the Y' said 'It's the X P wants, not
    the Y' (above)."""
    low = text.lower()
    if "not" not in low or not any(
        w in low for w in ("reach", "point", "grab", "cry", "angl", "gestur", "strain", "itch")
    ):
        return text
    m = _CLEFT_REACH49S.match(text.strip())
    if m is None:
        return text
    words = m["rest"].split()
    for k in range(len(words) - 1, 1, -1):
        x, p = " ".join(words[:k]), " ".join(words[k:])
        if not _only_person(p, lexicon):
            continue
        named = _ids(x, lexicon)
        # 'not the blue one': the one of X's kind
        y = _ids(re.sub(r"\bone\b", words[k - 1], m["not"], flags=_F), lexicon)
        if not named or not y or named & y or _ids(x, lexicon, "object") != named:
            return text
        out = f"{m['it']} {x} {p} wants{m['not']}"
        node = _reading(out, lexicon)
        if node is None or any(t.obj in y for t in tasks(node)):
            return text
        return out
    return text


# "Sam needs a pen that isn't red or blue.": 'a X that isn't A or B' where A and B are words of
# the names of two of the scene's Xs: said 'a X, but not the A one or the B one' (the older rules
# read it: the Xs left), when the scene has three or more Xs.
_ISNT_EITHER49S = re.compile(
    r"\b(?P<a>an?|any|one) (?P<x>[a-z]+) (?:that|which) (?:isn't|is not|ain't|'s not|is n't)"
    r" (?P<c1>[a-z]+),? (?:or|nor) (?P<c2>[a-z]+)(?= *(?:[.!,;]|$))",
    _F,
)


def _isnt_either49s(text: str, lexicon: Lexicon) -> str:
    """Session 49 (12s): 'a X that isn't A or B' said 'a X, but not the A one or the B one'
    (above)."""
    if "n't" not in text and " not " not in text.lower():
        return text
    m = _ISNT_EITHER49S.search(text)
    if m is None:
        return text
    kind = _ids(m["x"], lexicon, "object")
    one = _ids(f"the {m['c1']} {m['x']}", lexicon, "object")
    two = _ids(f"the {m['c2']} {m['x']}", lexicon, "object")
    if len(kind) < 3 or len(one) != 1 or len(two) != 1 or one == two or not (one | two) <= kind:
        return text
    said = f"{m['a']} {m['x']}, but not the {m['c1']} one or the {m['c2']} one"
    out = f"{text[: m.start()]}{said}{text[m.end() :]}"
    node = _reading(out, lexicon)
    if node is None or any(t.obj in one | two for t in tasks(node)):
        return text
    return out


# "Put the white cup in the sink, but the green cup mustn't be touched, it's got a sample in.":
# 'but the X mustn't / shouldn't / isn't to be touched (or moved)', with a reason after it about
# the thing ('it's got …', naming nothing of the scene): said 'but don't touch the X' (the older
# rules read it), when X is things of the scene the request before does not move.
_NOT_TOUCHED49S = re.compile(
    r"(?P<sep>\s*[,;]\s*)(?P<but>but |and |though )?(?P<x>(?:the|that|those) [a-z]+(?: [a-z]+)?)"
    r" (?:mustn't|must not|shouldn't|should not|can't|cannot|isn't to|is not to|aren't to|are "
    r"not to|mustn't ever|is never to) be (?:touched|moved|disturbed|shifted|handled)"
    r"(?: at all)?(?P<why>\s*,\s*(?:as |cos |because |since )?(?:it|they)(?:'s|'ve| has| have| is|"
    r" are|'re) [a-z' ]+)?(?P<end>\s*[.!]?)\s*$",
    _F,
)


def _not_touched49s(text: str, lexicon: Lexicon) -> str:
    """Session 49 (12s): 'but the X mustn't be touched (, it's got …)' said 'but don't touch the
    X' (above)."""
    low = text.lower()
    if " be " not in low or not any(
        w in low for w in ("touched", "moved", "disturbed", "shifted", "handled")
    ):
        return text
    m = _NOT_TOUCHED49S.search(text)
    if m is None:
        return text
    x = _ids(m["x"], lexicon)
    if not x or _ids(m["x"], lexicon, "object") != x or _names(m["why"] or "", lexicon):
        return text
    before = text[: m.start()]
    out = f"{before}{m['sep'].rstrip()} {m['but'] or 'but '}don't touch {m['x']}."
    node = _reading(out, lexicon)
    if node is None or _reading(before, lexicon) is None or any(t.obj in x for t in tasks(node)):
        return text
    return out


# "Let Person A at the chips; …": 'let P at X' (let them have it) said 'let P have X', when P is
# one person of the scene and X things of it.
_LET_AT49S = re.compile(
    r"\blet (?P<p>[a-z]+(?: [a-z]+)?) (?:get )?at (?P<x>(?:the|that|those|these|her|his|their) "
    r"[a-z]+(?: [a-z]+)?)(?=\s*(?:[.!;,]|$))",
    _F,
)


def _let_at49s(text: str, lexicon: Lexicon) -> str:
    """Session 49 (12s): 'let P at X' said 'let P have X' (above)."""
    if " at " not in text.lower() or "let" not in text.lower():
        return text
    m = _LET_AT49S.search(text)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    x = _ids(m["x"], lexicon)
    if not x or _ids(m["x"], lexicon, "object") != x:
        return text
    out = f"{text[: m.start()]}{m.group(0)[:3]} {m['p']} have {m['x']}{text[m.end() :]}"
    return out if _reading(out, lexicon) is not None else text


# "Give Person A the chips; the bottle, she won't drink.", "Give Bob the apple; the cup, though,
# he isn't keen on.": a thing said alone after the request, then a negated clause about it whose
# object is left out (it ends on a verb or a preposition with nothing after it, or on 'it'): the
# thing is the clause's object, fronted — what the person will not have. Session 31's
# `_negated_reason31s` took the clause off as a reason and the thing was read as given too
# (`chips>A & bottle>A`): a check of the reading refuses any reading that gives or puts the thing
# (`_fronted_not49s`), and 'she's not allowed near / won't touch / doesn't want …' after one
# person's request is read as 'but not the X' (`_fronted_not_read49s`, blind47).
_FRONTED_NOT49S = re.compile(
    r"(?P<lead>(?:^|[;,.:]\s*)(?:and |but |as for |as to |now )?)(?P<x>(?:the|that|this|those|"
    r"these) [a-z]+(?: [a-z]+)?)(?:\s*,\s*(?:though|tho|however|mind you|mind|mind, though))?"
    r"\s*,\s*(?P<said>(?:and |but |as )?(?P<pro>she|he|they|[A-Z][a-z]+)(?:'s| is| has| was|'re| "
    r"are)? ?(?P<neg>won't|wont|isn't|hasn't|can't|cannot|doesn't|didn't|mustn't|shouldn't|not|"
    r"never|is not|are not|aren't|does not|will not|must not)\b(?P<rest>[^,.;:!?]*?))"
    r"(?P<end>\s*(?:[.!?;,]|$))",
    _F,
)
_GAP49S = frozenset(
    [
        "near",
        "on",
        "at",
        "with",
        "for",
        "to",
        "about",
        "of",
        "from",
        "into",
        "onto",
        "by",
        "around",
        "round",
        "after",
        "without",
        "it",
        "them",
        "drink",
        "eat",
        "touch",
        "want",
        "need",
        "like",
        "use",
        "have",
        "take",
        "get",
        "share",
        "open",
        "carry",
        "hold",
        "stand",
        "manage",
        "finish",
        "fancy",
        "abide",
        "stomach",
        "bear",
        "keep",
        "allowed",
        "trust",
        "reach",
        "afford",
        "handle",
        "lift",
    ]
)


def _fronted_nots49s(text: str, lexicon: Lexicon) -> list[tuple[re.Match[str], set[str]]]:
    """Each fronted thing above with its negated clause, and the thing's ids."""
    low = text.lower()
    if "n't" not in low and " not" not in low and "never" not in low and "cannot" not in low:
        return []
    out = []
    for m in _FRONTED_NOT49S.finditer(text):
        words = m["said"].lower().split()
        if not words or words[-1] not in _GAP49S or (not m.start("lead") and not m["lead"]):
            continue
        if not text[: m.start("x")].strip(" ,;:.").strip():
            continue  # a thing said first ("The bottle, she won't drink.") is no request after
        x = _ids(m["x"], lexicon)
        if x and _ids(m["x"], lexicon, "object") == x and not _names(m["rest"], lexicon):
            out.append((m, x))
    return out


def _fronted_not49s(text: str, node: Node, lexicon: Lexicon) -> None:
    """Session 49 (12s): a reading that gives or puts a thing the text says, fronted, a person
    will not have is refused (above)."""
    for m, x in _fronted_nots49s(text, lexicon):
        if any(t.obj in x for t in tasks(node)):
            raise GroundingError(
                f"{m['x']!r} is said before {m['said'].strip()!r}: what is not to be done with "
                f"{m['x']}, not a request for it; say who gets what, e.g. '…, but not {m['x']}'"
            )


_NOT_HAVE49S = re.compile(
    r"^(?:and |but |as )?(?:she|he|they)(?:'s|'re| is| are) not allowed(?: (?:near|anywhere near|"
    r"to have|to touch|it|them|near it|near them))?$|^(?:and |but |as )?(?:she|he|they)"
    r"(?: won't| wont| will not| doesn't| does not| don't| can't| cannot| mustn't| must not|'s not|"
    r" isn't| is not|'re not| aren't)(?: be)? (?:allowed(?: it| them| near)?|having|touch|"
    r"want|need|drink|eat|keen on|have|getting|after|fussed about|bothered about|interested in)$",
    _F,
)


def _fronted_not_read49s(text: str, lexicon: Lexicon) -> str:
    """Session 49 (12s): 'X, (though,) she's not allowed near' after one person's request said
    '…, but not X' (above), when the pronoun may be that person and what is left reads."""
    found = _fronted_nots49s(text, lexicon)
    if len(found) != 1:
        return text
    m, x = found[0]
    if not _NOT_HAVE49S.match(m["said"].strip()) or m["pro"].lower() == "they":
        return text
    before = text[: m.start()]
    who = _one_person49s(before, lexicon)
    if who is None or not _agrees44s(who, m["pro"], lexicon) or _ids(before, lexicon) & x:
        return text
    out = f"{before}, but not {m['x']}{m['end'].strip() or '.'}{text[m.end() :]}"
    node = _reading(out, lexicon)
    if node is None or any(t.obj in x for t in tasks(node)):
        return text
    return out


# "No point the bottle sitting about, Person A should have it.": an opening 'no point (in) X
# sitting about / lying around' (the thing is unused) and the request about it: said as the
# request with its 'it' (or 'them') the thing, when the thing is objects of the scene, the
# request names no other and reads giving or putting it.
_NO_POINT49S = re.compile(
    r"^(?:there's |there is |it's |theres )?no (?:point|sense|use|good reason)(?: in)?"
    r" (?:(?:leaving|having|letting|keeping) )?(?P<x>(?:the|that|those|these) [a-z]+"
    r"(?: [a-z]+)?) (?:just )?(?:sitting|lying|standing|going|hanging|kicking) (?:about|around|"
    r"there|idle|unused|to waste|spare|doing nothing)(?: (?:doing nothing|unused|idle))?"
    r"\s*[,;:.]\s*(?:so )?(?P<rest>[^,;:.!?]+?)(?P<end>\s*[.!]?)\s*$",
    _F,
)


def _no_point49s(text: str, lexicon: Lexicon) -> str:
    """Session 49 (12s): the opening above taken off and the request's 'it' said as the thing
    (above)."""
    if not text.lower().startswith(("no ", "there", "it's no", "theres")):
        return text
    m = _NO_POINT49S.match(text.strip())
    if m is None:
        return text
    x = _ids(m["x"], lexicon)
    rest = m["rest"]
    pron = re.findall(r"\b(?:it|them)\b", rest, flags=_F)
    if not x or _ids(m["x"], lexicon, "object") != x or len(pron) != 1:
        return text
    if _ids(rest, lexicon, "object"):
        return text
    said = re.sub(r"\b(?:it|them)\b", m["x"], rest, flags=_F)
    out = f"{said[:1].upper()}{said[1:]}{m['end'].strip() or '.'}"
    node = _reading(out, lexicon)
    if node is None or not tasks(node) or any(t.obj not in x for t in tasks(node)):
        return text
    return out


# "Person B's brought his own cup, so give him every other thing.": a person said to have brought
# their own X, then 'give him / her every other thing (everything else, all the rest)': said
# "Give P everything but the X." (the scene's X is what they do not need), when P is one person
# of the scene the pronoun may be, and X names objects of it.
# "Alice says she's had enough crisps for one day, but whatever else is going she'll take.": a
# person who has had enough of X, and will take whatever else there is: said "Give P everything
# but the X." only where one object of the scene is left besides the Xs ('whatever else' could
# be any one of several).
_OWN_OTHER49S = re.compile(
    r"^(?P<p>[a-z]+(?: [a-z]+)?)(?:'s| has) (?:brought|got|fetched|packed|bought|made) "
    r"(?P<pro1>his|her) own (?P<x>[a-z]+(?: [a-z]+)?)\s*[,;]\s*(?:so )?(?:give|hand|pass|bring|"
    r"take) (?P<pro>him|her) (?:every other thing|everything else|all the rest|every other item|"
    r"all the other things|the rest of it|all the others)(?P<end>\s*[.!]?)\s*$"
    r"|^(?P<q>[a-z]+(?: [a-z]+)?) (?:says|said) (?P<pro2>she|he)(?:'s| has) had (?:enough|plenty|"
    r"her fill|his fill)(?: of)? (?P<y>(?:the )?[a-z]+)(?: for (?:one day|today|now|the day|the "
    r"moment|a while))?\s*,\s*but (?:whatever else is going|whatever else there is|whatever "
    r"else is left|whatever else) (?P<pro3>she|he)(?:'ll| will) (?:take|have)(?P<end2>\s*[.!]?)"
    r"\s*$",
    _F,
)


def _own_other49s(text: str, lexicon: Lexicon) -> str:
    """Session 49 (12s): the two forms above said "Give P everything but the X." (above)."""
    low = text.lower()
    if " own " not in low and "else" not in low:
        return text
    m = _OWN_OTHER49S.match(text.strip())
    if m is None:
        return text
    who, pro, thing = (m["p"], m["pro"], m["x"]) if m["p"] else (m["q"], m["pro2"], m["y"])
    if not _only_person(who, lexicon):
        return text
    if m["p"] and m["pro1"].lower()[0] != pro.lower()[0]:
        return text  # 'his own …, give her …'
    if m["q"] and m["pro2"].lower() != m["pro3"].lower():
        return text
    said = {"him": "he", "her": "she"}.get(pro.lower(), pro.lower())
    if not _agrees44s(who, said, lexicon):
        return text
    the = thing if thing.lower().startswith("the ") else f"the {thing}"
    x = _ids(the, lexicon)
    if not x or _ids(the, lexicon, "object") != x:
        return text
    if m["q"] and len({o.id for o in lexicon.scene.objects} - x) != 1:
        return text
    out = f"Give {who} everything but {the}."
    node = _reading(out, lexicon)
    if node is None or any(t.obj in x for t in tasks(node)):
        return text
    return out


# -- session 49 (12s): what a person has now, said with nothing asked after it -------------------
#
# 12c's probes (session 49, the lead's message): "person a the juggler has the cup now, cheers,
# we're all set" read `cup>A`, as "Bob has the cup now, thanks." and "Bob has the cup now, so give
# Alice the apple." (`cup>B & apple>A`) did: session 44's `held_beside44l` refuses "P already has
# the X, …" and "P has the X so …", but a 'now' after the thing took the sentence out of its
# pattern, and "Bob has the cup now." alone is refused (session 32) while the same with 'thanks'
# after it read as a handover. 'P has the X now' (the person's trade after the name or not)
# followed by a stop, a comma or 'so' says what the person holds now: a reading of it is refused.
_HAS_NOW49S = re.compile(
    rf"(?:^|[.;,:!?]\s*|\band\s+)(?P<who>{_WHO42R})(?P<ap>\s+the [a-z]+(?: [a-z]+)?)?\s*"
    r"(?P<verb>'s got|\s*has got|\s*has)\s+(?:the|his|her|their)\s+(?P<x>[a-z]+(?: [a-z]+){0,2}?)"
    r"\s+now\b(?=\s*(?:,?\s*\bso\b|[.;,:!?]|$))",
    _F,
)


def _has_now49s(text: str, node: Node, lexicon: Lexicon) -> None:
    """Session 49 (12s): a reading of 'P has the X now, …' refused (above)."""
    low = text.lower()
    if " now" not in low or ("has" not in low and "got" not in low):
        return
    for m in _HAS_NOW49S.finditer(text):
        who = m["who"]
        if not _only_person(who, lexicon) or not _objects_only(m["x"], lexicon):
            continue
        if m["ap"] and not _ids(m["ap"], lexicon) <= _ids(who, lexicon, "human"):
            continue
        said = text[m.start("who") : m.end()].strip()
        raise GroundingError(
            f"{said!r} says what {who} holds now: it asks for nothing; leave it out, or say "
            f"'give {who} the {' '.join(m['x'].split())}' to have it handed over"
        )


# -- session 49 (12s): lower case (blind47's) ----------------------------------------------------
#
# "go on hand the chips over to person a she's starving": 'go on (then)' before the request's verb
# with no comma (an urging: "Go on, give Bob the apple." reads) taken off.
_GO_ON49S = re.compile(
    r"^(?:go on|come on|go on then|come on then|go on now)\s+(?=(?:give|hand|pass|bring|take|pop|"
    r"put|get|fetch|chuck|send|drop|set|place|stick|leave)\b)",
    _F,
)


def _go_on49s(text: str, lexicon: Lexicon) -> str:
    """Session 49 (12s): an opening 'go on' with no comma taken off (above)."""
    if not text[:8].lower().startswith(("go on", "come on")):
        return text
    m = _GO_ON49S.match(text)
    if m is None:
        return text
    out = text[m.end() :]
    out = out[:1].upper() + out[1:] if text[:1].isupper() else out
    return out if _reading(out, lexicon) is not None else text


# "… so pop it over to her when there's a minute": 'when there's a minute (moment, sec)' said
# 'when you get a minute' (the older rules take that off: the hearer's time, not a condition).
_THERES_MINUTE49S = re.compile(
    r"\bwhen (?:there's|there is|theres) (?P<t>a (?:minute|moment|sec|second|mo|tick|spare "
    r"minute|spare moment)|time)(?=\s*(?:[.!,;]|$))",
    _F,
)


def _theres_minute49s(text: str, lexicon: Lexicon) -> str:
    """Session 49 (12s): 'when there's a minute' said 'when you get a minute' (above)."""
    if "there" not in text.lower():
        return text
    out = _THERES_MINUTE49S.sub(lambda m: f"when you get {m['t']}", text)
    if out == text:
        return text
    return out if _reading(out, lexicon) is not None else text


# "sam's taking minutes so the notepad goes to sam", "person a's been eyeing the bottle so pop it
# over to her …": a text with no marks that opens on what a person is doing ('P's / P is / P's been
# <verb>ing …'), then 'so' and the request: the comma before 'so' put back (the older rules read
# "P's taking minutes, so …"), when the opening names one person and nothing else but objects,
# negates and corrects nothing, and what follows 'so' names no other person.
_SO_RUN_ON49S = re.compile(
    rf"^(?P<a>(?P<p>{_WHO42R})(?:'s|'s been| is| was| has been) [a-z]+ing\b[a-z' ]*?) so "
    r"(?P<b>(?!(?:much|many|far|long|that|he|she|they|it)\b)[a-z][a-z' ]*)$",
    _F,
)


def _so_run_on49s(text: str, lexicon: Lexicon) -> str:
    """Session 49 (12s): the comma before 'so' put back (above)."""
    if " so " not in text.lower() or re.search(r"[,;:.!?]", text.rstrip(".!")):
        return text
    m = _SO_RUN_ON49S.match(text.strip())
    if m is None or not _only_person(m["p"], lexicon):
        return text
    a, b = m["a"], m["b"]
    if _NEGATED42S.search(a) or _CORRECTS45S.search(a) or _CORRECTS45S.search(b):
        return text
    people = _ids(a, lexicon, "human")
    if people != _ids(m["p"], lexicon, "human") or not _ids(b, lexicon, "human") <= people:
        return text
    out = f"{a}, so {b}"
    node = _reading(out, lexicon)
    if node is None or {t.target for t in tasks(node)} - people:
        return text
    # what is handed over is what the request names (or its 'it' / 'them', when it names none)
    said = _ids(b, lexicon, "object")
    if not said and re.search(r"\b(?:it|them)\b", b, _F):
        said = _ids(a, lexicon, "object")
    if not {t.obj for t in tasks(node)} <= said:
        return text
    return out


# the normaliser's first rewrites (wired into normalise._STEPS19, before the session-48 ones)
_STEPS49S_FIRST: tuple[Callable[[str, Lexicon], str], ...] = (
    _dont_go49s,
    _let_at49s,
    _fronted_not_read49s,
    _not_touched49s,
)
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-48 ones)
_STEPS49S: tuple[Callable[[str, Lexicon], str], ...] = (
    _on_top49s,
    _keep_waiting49s,
    _cleft_reach49s,
    _isnt_either49s,
    _no_point49s,
    _own_other49s,
    _go_on49s,
    _theres_minute49s,
    _so_run_on49s,
)
# refusals asked of the text before it is read (offline._parse, after the session-48 ones)
REFUSE49S: tuple[Callable[[str, Lexicon], None], ...] = ()
# checks of the whole instruction's reading (offline.parse_instruction, after the session-48 ones)
CHECK49S: tuple[Callable[[str, Node, Lexicon], None], ...] = (_fronted_not49s, _has_now49s)
