"""The grounder's rules of session 55, engineer 12 (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import (
    _COMMON,
    _F,
    _KEEP_WORDS,
    _ids,
    _objects_only,
    _only_person,
    _reading,
)
from hltl.grounding._rewrites42r import _WHO42R, which_lost42r
from hltl.grounding._rewrites43l import refuse_owned43l
from hltl.grounding._rewrites52 import _UNSAFE52, _cut52
from hltl.grounding.lexicon import VERBS, Lexicon, person_name
from hltl.grounding.tree import Node, tasks

# -- session 55 (engineer 12): the open wrong reading of session 54 (12c's fuzz), then blind53's
# refusals of politeness and fillers, wants and needs, pronouns and ellipsis and lower case, each
# read as a family.

# -- wrong readings --------------------------------------------------------------------------------

# -- a want of the placed thing said after the placement with no punctuation between ("lemon on the
# plate rack no sorry the worktop chef wants it for the fish", "salt on the rack lena needs it",
# "tongs on the rack mr novak wants them"; 12c's fuzz): read as the placement and a handover
# (lemon@counter & lemon>A), while "Put the lemon on the worktop, chef wants it." is refused naming
# both readings (session 38's offline._placed_wanted38l, which asks for a comma or 'and' before
# the person). The same refusal when the person's want runs on from the placement
_WANTED55 = re.compile(
    r"(?:\s|(?=['\u2019]))(?P<v>(?:wants|needs|wanted|needed|would like|['\u2019]d like|could use|"
    r"could do with|(?:has |['\u2019]s )?(?:asked|been asking|been waiting|begged) for|"
    r"(?:is|has been|['\u2019]s|['\u2019]s been) after|(?:is|['\u2019]s) (?:waiting|asking) for)"
    r" (?:it|them))\b",
    _F,
)
# the words the pattern needs (its gate): each of its verbs ends in one of them
_WANTED55_WORDS = tuple(
    f"{v} {p}"
    for v in (
        *("wants", "needs", "wanted", "needed", "like", "use", "do with", "asked for"),
        *("asking for", "waiting for", "begged for", "after"),
    )
    for p in ("it", "them")
)
# a verb that asks for a handover in words (session 38's _HANDOVER_SAID38L): then it is said
_HANDOVER55 = re.compile(
    r"\b(?:give|gives|hand|hands|pass|passes|bring|brings|take|takes|deliver|fetch|send|carry|"
    r"let(?!'s|\u2019s|\s+(?:me|us)\b))\b",
    _F,
)
_THEM55 = re.compile(r"\b(?:it(?!'s|\u2019s|\s+is\b|\s+was\b)|them)\b", _F)
_SENTENCE55 = re.compile(r"(?<=[.!?;])\s+")


def _who55(before: str, lexicon: Lexicon) -> set[str] | None:
    """The person the last words of ``before`` name ('… the worktop chef' -> {'A'}); None for
    he / she / they (any person); an empty set when they name no one."""
    words = before.split()
    if words and words[-1].lower() in ("he", "she", "they"):
        return None
    for n in (3, 2, 1):
        if len(words) >= n and _only_person(" ".join(words[-n:]), lexicon):
            return _ids(" ".join(words[-n:]), lexicon, "human")
    return set()


def _placed_wanted55(text: str, node: Node, lexicon: Lexicon) -> None:
    """Session 55: a want of the placed thing run on after the placement refused as session 38's
    check refuses it after a comma (above)."""
    low = text.lower()
    if not any(w in low for w in _WANTED55_WORDS):
        return
    placed = {t.obj: t.target for t in tasks(node) if t.kind == "place"}
    both = [t for t in tasks(node) if t.kind == "deliver" and t.obj in placed]
    if not both or any(
        _HANDOVER55.search(s)
        and (_THEM55.search(s) or {t.obj for t in both} & _ids(s, lexicon, "object"))
        for s in _SENTENCE55.split(text)
    ):
        return  # a verb of handing said of the placed thing: the handover is asked for
    for m in _WANTED55.finditer(text):
        who = _who55(text[: m.start()], lexicon)
        said = [t for t in both if who is None or t.target in who]
        if not said:
            continue
        t = said[0]
        put, name = f"{t.obj}@{placed[t.obj]}", person_name(t.target, lexicon)
        raise GroundingError(
            f"{m['v']!r} after putting the {t.obj} on the {placed[t.obj]}: is that why it goes "
            f"there ({put}), or is {name} to be handed it too ({put} & {t.obj}>{t.target})? say "
            "which"
        )


# -- a want of another person's thing said with 'asking for' / 'crying for' / 'after' …
# ("Lily's been crying for Ava's teddy.", "Bob's asking for Alice's apple.", "Jess has been asking
# for Kofi's drill."; 12c's fuzz): read as a handover to the owner (the grammar takes the last
# person before the object), while "Bob wants Alice's apple." is refused by session 43's
# owned_other43l (whose it is does not say who gets it). Refused the same, naming both people
_WANT_FOR55 = (
    r"(?:(?:'s|\u2019s|\s+is|\s+has|\s+was|\s+keeps|\s+kept)(?:\s+(?:been|had|got))?)?\s+"
    r"(?:(?:really |so |just )?(?:[a-z]+ing|[a-z]+ed|desperate|hungry|thirsty|eager|greedy|mad|"
    r"crazy|wild|keen)(?: out)? for|after|(?:his|her|their|an|a) "
    r"(?:eye|eyes) on|(?:keen|sweet|set|dead set) on|wanting|(?:would|'d|\u2019d) (?:really )?"
    r"love|loves|fancies|fancied|could (?:really )?(?:use|do with)|craves|covets|had|got|has|"
    r"took|borrowed|nicked|pinched)"
)
_OWNED_WANT55 = re.compile(
    rf"\b(?P<p>{_WHO42R}){_WANT_FOR55}\s+(?P<q>{_WHO42R})(?:'s|\u2019s)\s+(?P<x>[a-z]+(?:\s+"
    r"(?!(?:and|or|nor|but|to|for|with|from|please|then|too|as|if)\b)[a-z]+){0,2})",
    _F,
)
_WANT_FOR_WORDS55 = (
    *("ing for", "ing out for", "ed for", "ed out for", "after", "eye on", "eyes on", "keen on"),
    *("desperate for", "hungry for", "thirsty for", "eager for", "greedy for", "mad for"),
    *("crazy for", "wild for", "keen for"),
    *("sweet on", "set on", "wanting", "love", "fancie", "use", "do with", "craves", "covets"),
    *("had ", "got ", "has ", "took ", "borrowed ", "nicked ", "pinched "),
)


def _owned_want55(text: str, lexicon: Lexicon) -> None:
    """Session 55: "P's asking for Q's X" refused naming P and Q, as session 43's owned_other43l
    refuses "P wants Q's X" (above)."""
    low = text.lower()
    if ("'s" not in low and "\u2019s" not in low) or not any(w in low for w in _WANT_FOR_WORDS55):
        return
    for m in _OWNED_WANT55.finditer(text):
        refuse_owned43l(m["p"], m["q"], m["x"], lexicon)


# -- politeness and fillers ------------------------------------------------------------------------

# -- a time filler set off by commas between the courtesy and its verb ("Would you mind, when
# you've a sec, running the crisps over to Alice?", "Could you, when you get a minute, …"): taken
# off, so session 54's 'mind running … over to' and the grammar read what is left
_SEC55 = re.compile(
    r"\b(?P<a>mind|you),\s*(?:when|whenever|once|if) you(?:'ve| have| get| got|'ve got| have "
    r"got) a (?:spare )?(?:sec|second|minute|min|mo|moment|tick|jiffy|chance)\s*,\s*",
    _F,
)
_SEC_WORDS55 = ("a sec", "a minute", "a min", "a mo", "a tick", "a jiffy", "a chance", "a spare")


def _sec55(text: str, lexicon: Lexicon) -> str:
    """Session 55: ', when you've a sec,' between 'would you mind' / 'could you' and the verb
    taken off (above)."""
    low = text.lower()
    if not any(w in low for w in _SEC_WORDS55):
        return text
    m = _SEC55.search(text)
    if m is None:
        return text
    return _cut52(text, m.end("a"), m.end(), " ", lexicon)


# -- 'pretty please with <anything> on (top)' ("Pretty please with sprinkles on, hand Person B the
# cup"): said 'pretty please' (the courtesy frames know only sugar, a cherry, cherries, bells)
_PRETTY55 = re.compile(
    r"\bpretty please(?P<w>,? with (?!(?:sugar|a cherry|cherries|bells) on\b)(?:a |some |extra |"
    r"the )?(?:[a-z]+ ){0,2}[a-z]+ on"
    r"(?: top| it)?)\b",
    _F,
)


def _pretty55(text: str, lexicon: Lexicon) -> str:
    """Session 55: 'pretty please with sprinkles on' said 'pretty please' (above)."""
    if "pretty please" not in text.lower():
        return text
    m = _PRETTY55.search(text)
    if m is None:
        return text
    return _cut52(text, m.start("w"), m.end("w"), "", lexicon)


# -- a small favour asked for at the start ("Teeny favour, Dana would like the green cup", "Quick
# favour: …", "Morning! Tiny favour to ask, …"): taken off ('Teeny favour:' was read, the comma
# made the words a name)
_FAVOUR55 = re.compile(
    r"(?:^|(?<=[.!?])\s+)(?P<w>(?:a |one )?(?:teeny|tiny|quick|small|little|wee|cheeky|itty[- "
    r"]bitty|teensy|minor|big|huge|massive)(?: (?:little|tiny|teeny|wee|weeny))? favou?r(?: to "
    r"ask)?(?: (?:for|of) you)?(?: please)?\s*(?:[,:;]|\s[-\u2013\u2014])\s*)",
    _F,
)


def _favour55(text: str, lexicon: Lexicon) -> str:
    """Session 55: a leading 'Teeny favour,' taken off (above)."""
    low = text.lower()
    if "favour" not in low and "favor" not in low:
        return text
    m = _FAVOUR55.search(text)
    if m is None:
        return text
    return _cut52(text, m.start("w"), m.end("w"), "", lexicon)


# -- a kind word in a closing 'if': "…, if you'd be an absolute gem", "…, if you would be a star"
# (the courtesy frames take off ', if you'd be so kind'; 'be a gem' made the 'if' a condition)
_GEM55 = re.compile(
    r",\s*\bif you(?:'d| would| could| will)? be (?:a|an|my|such a|such an) (?:(?:absolute|real|"
    r"total|proper|utter|little|lovely|complete|right) )?(?:gem|star|angel|love|dear|darling|"
    r"treasure|sweetheart|doll|diamond|legend|hero|saint|lifesaver|life saver|pet|lamb|duck|"
    r"sweetie|superstar|babe|peach|godsend)\b(?=\s*[.!]*\s*$)",
    _F,
)
_GEM_WORDS55 = ("if you'd be", "if you would be", "if you could be", "if you will be", "if you be")


def _gem55(text: str, lexicon: Lexicon) -> str:
    """Session 55: a closing ', if you'd be a gem' taken off (above)."""
    low = text.lower()
    if not any(w in low for w in _GEM_WORDS55):
        return text
    m = _GEM55.search(text)
    if m is None:
        return text
    return _cut52(text, m.start(), m.end(), "", lexicon)


# -- an apology for interrupting at the start ("Hate to interrupt, only, would you kindly bring …",
# "Sorry to butt in, only, could you …", "I hate to bother you, only …"): taken off ('Sorry to
# interrupt, would you …' was read; 'hate to interrupt' and 'only' as 'but' were not)
_BOTHER55 = (
    r"(?:interrupt|butt in|barge in|cut in|bother you|trouble you|disturb you|pester you|intrude)"
    r"(?: again)?"
)
_INTERRUPT55 = re.compile(
    rf"^(?P<w>(?:(?:i )?hate to {_BOTHER55}(?:,? (?:only|but|just))?|(?:(?:so |really |very )?"
    rf"sorry|apologies|i'm sorry) to {_BOTHER55},\s*only)\s*,\s*)",
    _F,
)
_INTERRUPT_WORDS55 = tuple(
    f"to {w}"
    for w in (
        *("interrupt", "butt in", "barge in", "cut in", "bother you", "trouble you"),
        *("disturb you", "pester you", "intrude"),
    )
)


def _interrupt55(text: str, lexicon: Lexicon) -> str:
    """Session 55: a leading 'Hate to interrupt, only,' taken off (above)."""
    low = text.lower()
    if not any(w in low for w in _INTERRUPT_WORDS55):
        return text
    m = _INTERRUPT55.search(text)
    if m is None:
        return text
    return _cut52(text, m.start("w"), m.end("w"), "", lexicon)


# -- a thanks for waiting opening the text ("Sorry, bless you for waiting, Lena wants …", "Thanks
# for your patience, give Bob the apple", "Oh bless you for being so patient, …"): asks nothing,
# taken off (read as a verb 'bless' or a person 'waiting')
_BLESS55 = re.compile(
    r"(?:^|(?<=[,.!?])\s*)(?P<w>(?:(?:oh|aw|aww|ah),? )?(?:bless (?:you|ya|ye|your heart)|thanks|"
    r"thank you|cheers|ta)(?: (?:so|ever so|very) much)? for (?:waiting|your patience|being (?:so "
    r"|very )?patient|holding on|hanging on|bearing with (?:me|us))\s*[,.!]\s*)(?=\S)",
    _F,
)
_BLESS_WORDS55 = (
    *("for waiting", "for your patience", "for being patient", "for being so patient"),
    *("for being very patient", "for holding on", "for hanging on", "for bearing with"),
)


def _bless55(text: str, lexicon: Lexicon) -> str:
    """Session 55: an opening 'bless you for waiting,' taken off (above)."""
    low = text.lower()
    if not any(w in low for w in _BLESS_WORDS55):
        return text
    m = _BLESS55.search(text)
    if m is None:
        return text
    return _cut52(text, m.start("w"), m.end("w"), "", lexicon)


# -- thanks in Irish ("Go raibh maith agat, Jess would love the torch", "go raibh míle maith
# agaibh"): said 'thanks' (the unknown words were read as a name)
_IRISH55 = re.compile(
    r"\b(?P<w>go raibh (?:(?:m[i\u00ed]le )?maith) (?:agat|agaibh))\b",
    _F,
)


def _irish55(text: str, lexicon: Lexicon) -> str:
    """Session 55: Irish thanks ('go raibh maith agat') said 'thanks' (above)."""
    if "raibh" not in text.lower():
        return text
    m = _IRISH55.search(text)
    if m is None:
        return text
    return _cut52(text, m.start("w"), m.end("w"), "thanks", lexicon)


# -- Spanish 'please' said short ("Porfa, could the chips find their way to Person A?", "porfis",
# "porfavor"): said 'por favor', as the courtesy list has it
_PORFA55 = re.compile(r"\b(?P<w>porfa|porfis|porfi|porfavor)\b", _F)


def _porfa55(text: str, lexicon: Lexicon) -> str:
    """Session 55: 'porfa' said 'por favor' (above)."""
    low = text.lower()
    if "porf" not in low:
        return text
    m = _PORFA55.search(text)
    if m is None:
        return text
    return _cut52(text, m.start("w"), m.end("w"), "por favor", lexicon)


# -- why a thing is placed where it is, then a closing courtesy ("Stow the crisps on the shelf, away
# from little hands, ta very much", "…, out of reach of the kids, cheers"): session 43s's
# _placed_aside43s takes the reason off when it closes the text (and not 'away from' bare words);
# taken off before a comma too, when its words name nothing of the scene and every task left is a
# placing
_AWAY55 = re.compile(
    r",\s*(?:well |safely |right )?(?:away from|out of (?:the )?reach of|out of (?:the )?sight of|"
    r"clear of) (?P<x>[a-z][a-z' ]{0,40}?)(?=\s*,)",
    _F,
)
_AWAY_WORDS55 = ("away from", "reach of", "sight of", "clear of")


def _away55(text: str, lexicon: Lexicon) -> str:
    """Session 55: ', away from little hands,' after a placing taken off (above)."""
    low = text.lower()
    if not any(w in low for w in _AWAY_WORDS55):
        return text
    m = _AWAY55.search(text)
    if m is None or _ids(m["x"], lexicon):
        return text
    out = _cut52(text, m.start(), m.end(), "", lexicon)
    if out == text:
        return text
    node = _reading(out, lexicon)
    if node is None or any(t.kind != "place" for t in tasks(node)):
        return text
    return out


# -- 'whenever you're passing' before a remark ("Jess would love the torch whenever you're passing,
# she's under the van."): when the hearer passes, not a time the task waits for (read when it
# closes the sentence), taken off before a comma too
_PASSING55 = re.compile(
    r"\s*,?\s*\b(?:whenever|when|as|if) you(?:'re| are) (?:passing|going past|walking "
    r"past|going by)(?: by)?(?=\s*,)",
    _F,
)


_PASSING_WORDS55 = tuple(
    f"{y} {w}"
    for y in ("you're", "you are")
    for w in ("passing", "going past", "walking past", "going by")
)


def _passing55(text: str, lexicon: Lexicon) -> str:
    """Session 55: 'whenever you're passing' before a comma taken off (above)."""
    low = text.lower()
    if not any(w in low for w in _PASSING_WORDS55):
        return text
    m = _PASSING55.search(text)
    if m is None:
        return text
    return _cut52(text, m.start(), m.end(), "", lexicon)


# -- wants and needs -------------------------------------------------------------------------------

# -- 'specifically' / 'in particular' closing the name of the thing ("Bob's after a mug, the blue
# one specifically.", "Alice wants the red mug in particular."): says which, taken off
_SPECIFIC55 = re.compile(
    r"(?P<x>\b(?:the|a|an|that|this) [a-z]+(?: [a-z]+){0,2}?)(?P<w>,? (?:specifically|in "
    r"particular|particularly|precisely|especially|exactly|mind you))(?=\s*(?:[.,;!]|$))",
    _F,
)
_SPECIFIC_WORDS55 = ("specifically", "particular", "precisely", "especially", "exactly", "mind you")


def _specific55(text: str, lexicon: Lexicon) -> str:
    """Session 55: 'specifically' after the thing's name taken off (above)."""
    low = text.lower()
    if not any(w in low for w in _SPECIFIC_WORDS55):
        return text
    m = _SPECIFIC55.search(text)
    if m is None:
        return text
    x = m["x"].lower()
    if not (x.endswith(" one") or _objects_only(m["x"], lexicon)):
        return text
    return _cut52(text, m.start("w"), m.end("w"), "", lexicon)


# -- 'then the Y straight after that' ("What Person A is after is the bottle, and then the apple
# straight after that."): the 'then' says the order; the closing 'straight after that' taken off
_THEN_AFTER55 = re.compile(
    r"\bthen\b[^.;!?,]*?(?P<w>,? (?:straight|right|directly|immediately|just)? ?after (?:that|"
    r"it|this|those))(?=\s*(?:[.;!?]|$))",
    _F,
)


def _then_after55(text: str, lexicon: Lexicon) -> str:
    """Session 55: 'then the Y straight after that': 'straight after that' taken off (above)."""
    low = text.lower()
    if "then" not in low or not any(w in low for w in ("after that", "after it", "after this")):
        return text
    m = _THEN_AFTER55.search(text)
    if m is None:
        return text
    return _cut52(text, m.start("w"), m.end("w"), "", lexicon)


# -- 'P has his heart set on X' and a remark after it ("Person B has his heart set on the apple,
# bless him."): said 'P wants X' (session 54's _craving54 says the "'s got his heart set on" form;
# the older rules read it alone or before a request: left to them)
_HEART55 = re.compile(
    r"(?:^|(?<=[.;!?])\s+)(?P<p>[^.;!?,]+?)(?P<w>(?:'s|\u2019s| has| is) (?:(?:his|her|their) "
    r"heart (?:set|fixed|dead set) on|(?:dead )?set on having)) [^.;!?,]+,\s*(?P<rest>[^.;!?]+)",
    _F,
)
# a verb of handing in the remark after it: the older rules read those ('…, hand him the cup')
_HANDS55 = re.compile(
    r"\b(?:give|hand|pass|bring|take|fetch|send|put|let|pop|stick|move|place)\b", _F
)


def _heart55(text: str, lexicon: Lexicon) -> str:
    """Session 55: 'P has his heart set on X, <remark>' said 'P wants X, …' (above)."""
    if "set on" not in text.lower():
        return text
    m = _HEART55.search(text)
    if m is None or _HANDS55.search(m["rest"]) or not _only_person(m["p"], lexicon):
        return text
    return _cut52(text, m.start("w"), m.end("w"), " wants", lexicon)


# -- 'at the moment' closing a present want ("Person A wants her bottle and nothing else at the
# moment.", "Bob needs the apple at the moment."): now, taken off
_MOMENT55 = re.compile(
    r"\b(?:wants|needs|would like|'d like|could use|is after|'s after|fancies)\b[^.;!?]*?"
    r"(?P<w>,? (?:right |just )?(?:at the moment|at present|at this moment|for the moment))"
    r"(?=\s*(?:[.,;!]|$))",
    _F,
)


def _moment55(text: str, lexicon: Lexicon) -> str:
    """Session 55: 'at the moment' closing a present want taken off (above)."""
    low = text.lower()
    if not any(w in low for w in ("the moment", "at present", "this moment")):
        return text
    m = _MOMENT55.search(text)
    if m is None:
        return text
    return _cut52(text, m.start("w"), m.end("w"), "", lexicon)


# -- an emphatic 'did' before a verb of saying in a forgetting remark ("Sam needs a pen and did
# tell me the colour, but it's gone clean out of my head."): session 42's which_lost42r refuses
# the remark with 'told me' naming the readings ('did say' too); 'did tell me' / 'did mention' /
# 'did show me' said so and asked of it
_DID_TELL55 = re.compile(r"\b(?P<w>did (?P<v>tell|mention|show))\b", _F)
_SAID55 = {"tell": "told", "mention": "mentioned", "show": "showed"}


def _did_tell55(text: str, lexicon: Lexicon) -> None:
    """Session 55: 'did tell me …, but I've forgotten' refused as 'told me …' is (above)."""
    low = text.lower()
    if "did tell" not in low and "did mention" not in low and "did show" not in low:
        return
    m = _DID_TELL55.search(text)
    if m is None:
        return
    which_lost42r(f"{text[: m.start('w')]}{_SAID55[m['v'].lower()]}{text[m.end('w') :]}", lexicon)


# -- a drink from a vessel of the scene ("Mr Lee's asking for his tablets and a drink from the water
# jug."): the vessel is what is handed, said 'the water jug'
_DRINK_FROM55 = re.compile(
    r"\b(?P<w>(?:a|some|another) (?:drink|glass|sip|swig|splash|top-up|refill)(?: of "
    r"(?:water|juice|milk|squash))? (?:from|out of) )(?P<x>the [a-z]+"
    r"(?: [a-z]+)?)(?=\s*(?:[.,;!?]|$|\s(?:and|please|too)\b))",
    _F,
)


_DRINK_WORDS55 = ("drink", "glass", "sip", "swig", "splash", "top-up", "refill")
# what a drink is poured from
_VESSELS55 = frozenset(
    ("jug", "bottle", "flask", "carton", "jar", "kettle", "pitcher", "beaker", "cup", "mug")
) | frozenset(("glass", "thermos", "urn", "decanter", "teapot", "cafetiere", "canteen"))


def _drink_from55(text: str, lexicon: Lexicon) -> str:
    """Session 55: 'a drink from the water jug' said 'the water jug' (above)."""
    low = text.lower()
    if not any(w in low for w in _DRINK_WORDS55):
        return text
    m = _DRINK_FROM55.search(text)
    if m is None or not _objects_only(m["x"], lexicon):
        return text
    if m["x"].lower().split()[-1] not in _VESSELS55:
        return text
    return _cut52(text, m.start("w"), m.end("w"), "", lexicon)


# -- what the wanted thing is for, inside a longer text ("Omar requires the sponge for scrubbing
# out the sink, and Emma would quite like a banana.", "Kofi's needing the drill to put up the
# brackets; Jess would like the small spanner."): the older purpose rules take it off when it
# closes the text and names nothing of the scene; taken off before a comma or a stop too, and
# when it names a surface (what is scrubbed or wiped is not where the thing goes), when its verb is
# none the grounder reads (or 'put up' / 'hang up' of things the scene does not have), it names no
# person, no object and no place it goes to, and holds no word that counts, points back or
# negates (_KEEP_WORDS)
_PURPOSE55 = re.compile(
    r"\b(?:needs|need|needed|needing|requires|required|wants|wanting|would (?:quite |really )?"
    r"like|'d (?:quite |really )?like|could (?:really )?use|could do with|(?:is|'s) after) "
    r"(?:the|a|an|his|her|their|some) [a-z]+(?: (?!(?:to|for)\b)[a-z]+){0,2}? (?P<p>(?:to "
    r"(?P<v>[a-z]+)|for (?P<g>[a-z]{3,}ing))(?P<w>(?: (?!(?:and|but|so|then|please)\b)[a-z']+)"
    r"{1,5}?))(?=\s*[,;.]\s*\S)",
    _F,
)
# where a thing goes ('to the shelf', 'on the bench'): then the purpose may be a placing
_TO_PLACE55 = re.compile(r"\b(?:to|on|onto|into|in|at|over|by|near|beside|under|inside)\b", _F)
_NOT_VERBS55 = frozenset(("the", "a", "an", "my", "your", "our", "its", "be", "have", "go"))
_PHRASAL55 = frozenset(("put up", "hang up", "set up", "put together", "take down", "take apart"))


def _purpose55(text: str, lexicon: Lexicon) -> str:
    """Session 55: what the wanted thing is for, before a comma or a stop, taken off (above)."""
    low = text.lower()
    if " to " not in low and " for " not in low:
        return text
    for m in _PURPOSE55.finditer(text):
        words = m["w"].strip()
        if m["v"]:
            verb = m["v"].lower()
            if _KEEP_WORDS.search(verb) or verb in _NOT_VERBS55:
                continue
            phrasal = f"{verb} {words.split()[0].lower()}" in _PHRASAL55
            if (verb in VERBS and not phrasal) or verb not in _COMMON:
                continue
            if phrasal and _names_any55(words, lexicon):
                continue
        else:
            g = m["g"].lower()
            if {g, g[:-3], g[:-3] + "e", g[:-4]} & VERBS.keys():
                continue
            if not _ids(words, lexicon, "surface"):
                continue  # naming nothing: session 33's _purpose_ing33t reads it
        if _KEEP_WORDS.search(words) or _TO_PLACE55.search(words):
            continue
        if _ids(words, lexicon, "human") or _ids(words, lexicon, "object"):
            continue
        out = _cut52(text, m.start("p") - 1, m.end("p"), "", lexicon)
        if out != text:
            return out
    return text


def _names_any55(words: str, lexicon: Lexicon) -> bool:
    return bool(_ids(words, lexicon))


# -- pronouns and ellipsis -------------------------------------------------------------------------

# -- how long a want has gone on, closing it ("Person A's been hanging on for that bottle a good
# while now, off it goes to her.", "Bob's been waiting for the apple all day, …"): taken off (the
# want holds now: 'been … for')
_WHILE55 = re.compile(
    r"\bbeen (?:[a-z]+ing)(?: on| out)? for (?:the|that|this|his|her|their) [a-z]+(?: [a-z]+)?"
    r"(?P<w> (?:for )?(?:a (?:good |long |fair )?while|quite a while|ages|a long time)(?: now)?)"
    r"(?=\s*[,.;!])",
    _F,
)
_WHILE_WORDS55 = ("while", "ages", "long time")


def _while55(text: str, lexicon: Lexicon) -> str:
    """Session 55: 'been hanging on for X a good while now' without the while (above)."""
    low = text.lower()
    if "been " not in low or not any(w in low for w in _WHILE_WORDS55):
        return text
    m = _WHILE55.search(text)
    if m is None:
        return text
    return _cut52(text, m.start("w"), m.end("w"), "", lexicon)


# -- 'on at me about' ("The crisps? Bob's been on at me about them all day, so let him have them."):
# nagging the speaker, said 'on about' (read; 'me' names no one of the scene)
_ON_AT55 = re.compile(r"\bon (?P<w>at (?:me|us) )about (?:it|them)\b", _F)


def _on_at55(text: str, lexicon: Lexicon) -> str:
    """Session 55: 'on at me about' said 'on about' (above)."""
    low = text.lower()
    if "on at me" not in low and "on at us" not in low:
        return text
    m = _ON_AT55.search(text)
    if m is None:
        return text
    return _cut52(text, m.start("w"), m.end("w"), "", lexicon)


# -- a pronoun named after the clause ("…, and give him the apple too, Person B that is."): the name
# said in the pronoun's place (the last him / her before it), the tag taken off
_THAT_IS55 = re.compile(
    r",\s*(?P<p>[A-Za-z][\w]*(?: [A-Za-z][\w]*)?) (?:that is|that's who)\s*[.!]?\s*$", _F
)


def _that_is55(text: str, lexicon: Lexicon) -> str:
    """Session 55: '…him…, Person B that is' said with the name (above)."""
    low = text.lower()
    if "that is" not in low and "that's who" not in low:
        return text
    m = _THAT_IS55.search(text)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    before = text[: m.start()]
    prons = list(re.finditer(r"\b(?:him|her)\b", before, _F))
    if not prons:
        return text
    k = prons[-1]
    out = f"{before[: k.start()]}{m['p']}{before[k.end() :]}."
    if _UNSAFE52.search(out) or _reading(out, lexicon) is None:
        return text
    return out


# -- where the one who needs it is, after the need ("Jess needs a light under there, so pass her the
# flashlight"): 'under there' says where she is working, taken off
_THERE55 = re.compile(
    r"\b(?:needs|wants|could use|could do with|would like) (?:a|an|some) [a-z]+(?P<w> "
    r"(?:under|down|in|up|inside|behind) there)(?=\s*,)",
    _F,
)
_THERE_WORDS55 = tuple(f"{w} there" for w in ("under", "down", "in", "up", "inside", "behind"))


def _there55(text: str, lexicon: Lexicon) -> str:
    """Session 55: 'needs a light under there,' without 'under there' (above)."""
    low = text.lower()
    if not any(w in low for w in _THERE_WORDS55):
        return text
    m = _THERE55.search(text)
    if m is None:
        return text
    return _cut52(text, m.start("w"), m.end("w"), "", lexicon)


# -- lower case ------------------------------------------------------------------------------------

# -- a request pointing back run on after a want without a comma ("person b is gagging for the
# bottle pass it him"): the comma said
_RUNON55 = re.compile(
    r"\b(?:wants|needs|would like|could use|is after|'s after|(?:is|'s) [a-z]+ing for) "
    r"(?:the|a|an|his|her|their|that|this) [a-z]+(?: (?!(?:so|and|then|but|now|please|just)\b)"
    r"[a-z]+)?(?P<w>) (?:pass|give|hand|bring|take|fetch|send) (?:it|them)(?=\s+(?:him|her|to|"
    r"over|across|round|back)\b|\s*[.!]?\s*$)",
    _F,
)
_RUNON_WORDS55 = tuple(
    f" {v} {p}"
    for v in ("pass", "give", "hand", "bring", "take", "fetch", "send")
    for p in ("it", "them")
)


def _runon55(text: str, lexicon: Lexicon) -> str:
    """Session 55: 'P wants the X pass it him' said with a comma before the request (above)."""
    low = text.lower()
    if not any(w in low for w in _RUNON_WORDS55):
        return text
    m = _RUNON55.search(text)
    if m is None:
        return text
    return _cut52(text, m.start("w"), m.end("w"), ",", lexicon)


# -- a remark about the person run on after the want ("person b could use the bottle hes a
# captioner and talks all day"): the comma said
_RUNON_REMARK55 = re.compile(
    r"\b(?:wants|needs|would like|could use|could do with|is after|'s after) (?:the|a|an|his|her|"
    r"their) [a-z]+(?: [a-z]+)?(?P<w>) (?:hes|shes|he's|she's|he is|she is|theyre|they're) "
    r"(?:a|an) ",
    _F,
)
_REMARK_WORDS55 = (
    *(" hes ", " shes ", " he's ", " she's ", " he is ", " she is ", " theyre "),
    " they're ",
)


def _runon_remark55(text: str, lexicon: Lexicon) -> str:
    """Session 55: 'P could use the X hes a …' said with a comma before the remark (above)."""
    low = text.lower()
    if not any(w in low for w in _REMARK_WORDS55):
        return text
    m = _RUNON_REMARK55.search(text)
    if m is None:
        return text
    return _cut52(text, m.start("w"), m.end("w"), ",", lexicon)


# -- a forgetting remark run on without a comma ("lena or marco wanted the tongs not sure which"):
# refused as the same words with the comma are (naming the readings), not for its 'not'
_NOT_SURE55 = re.compile(
    r"(?<=[a-z])(?P<w>) (?:not sure|no idea|dunno|cant remember|can't remember|cannot remember|"
    r"i forget|forgot) (?:which|who)\b",
    _F,
)
_NOT_SURE_WORDS55 = tuple(
    f"{w} {x}"
    for w in ("not sure", "no idea", "dunno", "remember", "forget", "forgot")
    for x in ("which", "who")
)


def _not_sure55(text: str, lexicon: Lexicon) -> None:
    """Session 55: '… the tongs not sure which' refused as '…, not sure which' is (above)."""
    low = text.lower()
    if not any(w in low for w in _NOT_SURE_WORDS55):
        return
    m = _NOT_SURE55.search(text)
    if m is None or re.search(r"[,;:.!?]", text[: m.start()]):
        return
    if re.search(r"\b(?:i|i'm|im|i've|ive|and|but|we|so)\s*$", text[: m.start()], _F):
        return
    # why: offline.py imports this module, so the grammar is imported where it is used
    from hltl.grounding.offline import parse_instruction

    # the same words with the comma: its refusal (naming the readings) is this text's; a reading
    # of it leaves this text to the rules after this one
    parse_instruction(f"{text[: m.start('w')]},{text[m.end('w') :]}", lexicon.scene, lexicon)


# -- why a thing is placed, closing the placing without a comma ("green block into the high chair so
# lily can reach it"): taken off when every task is a placing
_REACH55 = re.compile(
    r"\s*,?\s*\bso (?:that )?(?P<who>[a-z][a-z' ]{0,30}?) can (?:reach|get|grab|see|find|get at|"
    r"get to) (?:it|them)\s*[.!]?\s*$",
    _F,
)
_REACH_WORDS55 = tuple(f"can {v}" for v in ("reach", "get", "grab", "see", "find"))


def _reach55(text: str, lexicon: Lexicon) -> str:
    """Session 55: '… so lily can reach it' after a placing taken off (above)."""
    low = text.lower()
    if text != low or not any(w in low for w in _REACH_WORDS55):
        return text  # said in lower case (cased, session 38r's rules read it)
    m = _REACH55.search(text)
    if m is None or _ids(m["who"], lexicon, "object") or _ids(m["who"], lexicon, "surface"):
        return text
    out = _cut52(text, m.start(), m.end(), "", lexicon)
    if out == text:
        return text
    node = _reading(out, lexicon)
    if node is None or any(t.kind != "place" for t in tasks(node)):
        return text
    return out


# -- a closing 'don't mix them up' after two or more handovers ("apple goes to person a n the cup to
# person b, dont mix em up"): a care, not a negated task, taken off
_MIX55 = re.compile(
    r",?\s*\b(?:and )?(?:don't|dont|do not) (?:mix (?:them|em|'em|those|these) up|get (?:them|em|"
    r"'em) mixed up)\s*[.!]?\s*$",
    _F,
)


def _mix55(text: str, lexicon: Lexicon) -> str:
    """Session 55: a closing "don't mix them up" after two handovers taken off (above)."""
    if "mix" not in text.lower():
        return text
    m = _MIX55.search(text)
    if m is None:
        return text
    out = _cut52(text, m.start(), m.end(), "", lexicon)
    if out == text:
        return text
    node = _reading(out, lexicon)
    if node is None or len(list(tasks(node))) < 2:
        return text
    return out


# the normaliser's first rewrites (wired into normalise._STEPS19, before the session-54 ones)
_STEPS55_FIRST: tuple[Callable[[str, Lexicon], str], ...] = (
    _sec55,
    _pretty55,
    _favour55,
    _gem55,
    _interrupt55,
    _bless55,
    _irish55,
    _porfa55,
    _away55,
    _passing55,
    _specific55,
    _then_after55,
    _heart55,
    _moment55,
    _drink_from55,
    _purpose55,
    _while55,
    _on_at55,
    _that_is55,
    _there55,
    _runon55,
    _runon_remark55,
    _reach55,
    _mix55,
)
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-54 ones)
_STEPS55: tuple[Callable[[str, Lexicon], str], ...] = ()
# refusals asked of the text before it is read (offline._parse, after the session-54 ones)
REFUSE55: tuple[Callable[[str, Lexicon], None], ...] = (_owned_want55, _did_tell55, _not_sure55)
# checks of the whole instruction's reading (offline.parse_instruction, after the session-54 ones)
CHECK55: tuple[Callable[[str, Node, Lexicon], None], ...] = (_placed_wanted55,)
