"""The grounder's rules of session 51, engineer 12 (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable
from typing import NoReturn

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import (
    _F,
    _ids,
    _names,
    _only_person,
    _reading,
    _unknown_word,
)
from hltl.grounding._rewrites45 import _read_for, _read_for_said
from hltl.grounding._rewrites48 import _GLOSS48
from hltl.grounding._rewrites50 import _cut50
from hltl.grounding.lexicon import Lexicon
from hltl.grounding.tree import Group, Node, tasks

# -- session 51 (engineer 12): blind49's refusals of politeness and fillers, wants and needs,
# pronouns and ellipsis and questions, each read as a family. Every rule rewrites to words the
# grammar (or an older rule) already reads, and keeps the rewrite only when it reads.

# a person's name as the corpus says them ('Bob', 'Person A', 'Mrs Khan')
_P51 = r"[A-Z]\w*(?: [A-Z]\w*)?"


# -- politeness and fillers ------------------------------------------------------------------------

# -- a word of thanks in another language (glossed by who says it and where, or not) opening a
# request asked as a question ("Jërëjëf, as we say back in Dakar, and could you bring Carol the
# blue mug?"): the word and its gloss taken off (session 50's _gloss50 reads it before a request
# said as an order; session 19's fillers leave a stretch before a question)
_GLOSS51 = re.compile(
    r"^(?P<w>[^\W\d_]+(?:[ -][^\W\d_]+)?)(?:,\s*as (?:we|they|folk|people|you|my [a-z]+|our "
    r"[a-z]+)(?:'d| would)? (?:say|says|put it|puts it|always say|always says)(?: (?:back|out|"
    r"over|up|down))?(?: home)? (?:in|on) (?P<place>[A-Z][a-z]+(?: [A-Z][a-z]+)?))?\s*,\s*"
    r"(?:and )?(?=(?:could|can|would|will|might) you\b)"
)


def _gloss51(text: str, lexicon: Lexicon) -> str:
    """Session 51: a foreign word of thanks opening a question taken off."""
    if " you" not in text:
        return text
    m = _GLOSS51.match(text)
    if m is None or (m["place"] and _names(m["place"], lexicon)) or _GLOSS48.match(text):
        return text
    if not all(_unknown_word(w, lexicon) for w in re.split(r"[ -]", m["w"])):
        return text
    return _cut50(text, 0, m.end(), "", lexicon)


# -- a foreign word of thanks glossed as such ("Ko rab'a, that's thanks in Gilbertese, and now the
# chips across to Person B please.", "Mèrcie, that's Jèrriais for thanks, and would you kindly
# drop the sponge into the sink?"): the word and its gloss taken off
_THANKS_IN51 = re.compile(
    r"^(?P<w>[^\W\d_]+(?:['’ -][^\W\d_]+){0,2}),\s*(?:that's|that is|which is|it's|it is|"
    r"meaning) (?:(?:thanks|thank you|cheers|ta)(?: (?:in|in the|from)(?: [^\W\d_]+){1,2})|"
    r"(?P<lang>[^\W\d_]+(?: [^\W\d_]+)?) for (?:thanks|thank you|cheers|ta))\s*[,;:]\s*"
    r"(?:and )?"
)


def _thanks_in51(text: str, lexicon: Lexicon) -> str:
    """Session 51: "Ko rab'a, that's thanks in Gilbertese," taken off."""
    if "thank" not in text and "cheers" not in text and " ta" not in text:
        return text
    m = _THANKS_IN51.match(text)
    if m is None or _names(m["w"], lexicon) or (m["lang"] and m["lang"].isascii()):
        return text
    return _cut50(text, 0, m.end(), "", lexicon)


# -- 'a spare moment' in 'when you've a spare moment' ("… when you've a spare moment?"): said 'a
# moment' (read: session 20's courtesies)
_SPARE51 = re.compile(
    r"\bwhen(?:ever)? you(?:'ve| have|'ve got| have got| get| find) a (?P<a>(?:spare|free|quiet|"
    r"spare few|free few) )(?=(?:moment|minute|min|sec|second|mo|jiffy)s?\b)",
    _F,
)


def _spare51(text: str, lexicon: Lexicon) -> str:
    """Session 51: 'when you've a spare moment' read as 'when you've a moment'."""
    if "spare" not in text and "free" not in text and "quiet" not in text:
        return text
    m = _SPARE51.search(text)
    if m is None:
        return text
    return _cut50(text, m.start("a"), m.end("a"), "", lexicon)


# -- 'would be lovely over with P' ("the crisps would be lovely over with Bob"): the object going
# over to P, said 'the crisps over to Bob would be lovely' (read)
_OVER_WITH51 = re.compile(
    r"\b(?P<x>(?:[Tt]he|[Tt]hat|[Tt]hose|[Tt]hese|[Ss]ome|a|an) [a-z]+(?: [a-z]+)?) would be "
    r"(?P<adj>lovely|"
    r"nice|great|grand|perfect|ideal|brilliant|wonderful|best|good|smashing|champion|fab|"
    r"fabulous|super) over with (?P<p>" + _P51 + r")\b"
)


def _over_with51(text: str, lexicon: Lexicon) -> str:
    """Session 51: 'the X would be lovely over with P' read as 'the X over to P would be
    lovely'."""
    if " over with " not in text:
        return text
    m = _OVER_WITH51.search(text)
    if m is None or not _only_person(m["p"], lexicon) or _names(m["adj"], lexicon):
        return text
    put = f"{m['x']} over to {m['p']} would be {m['adj']}"
    out = f"{text[: m.start()]}{put}{text[m.end() :]}"
    return _read_for(out, text, None, lexicon)


# -- 'With (my) apologies for …,' opening a request ("With my apologies for the muddle earlier,
# could Person B be given the bottle now?"): said 'Apologies for …,' (read)
_WITH_APOLOGIES51 = re.compile(
    r"^With (?:my |our |all my |many |sincere |my sincere |humble |my humble |profuse |my "
    r"profuse )?apologies(?= for\b|\s*,)"
)


def _with_apologies51(text: str, lexicon: Lexicon) -> str:
    """Session 51: an opening 'With my apologies for …' read as 'Apologies for …'."""
    if not text.startswith("With "):
        return text
    m = _WITH_APOLOGIES51.match(text)
    if m is None:
        return text
    return _cut50(text, 0, m.end(), "Apologies", lexicon)


# -- 'if you'd be a star' ("Right then, if you'd be a star, the packing tape goes over to Tom"):
# a courtesy, no condition: said 'be a star' (read)
_STAR51 = re.compile(
    r"\b(?P<if>[Ii]f you(?:'d| would) )be (?:a |an |such a |such an )?(?:star|angel|dear|love|"
    r"darling|treasure|gem|sweetheart|poppet|pet|diamond|sweetie|doll|lamb|duck)\b(?=\s*,)"
)


def _star51(text: str, lexicon: Lexicon) -> str:
    """Session 51: 'if you'd be a star' read as 'be a star'."""
    if "f you" not in text:
        return text
    m = _STAR51.search(text)
    if m is None:
        return text
    out = f"{text[: m.start('if')]}{text[m.end('if') :]}"
    return _read_for(out[:1].upper() + out[1:], text, None, lexicon)


# -- wants and needs -------------------------------------------------------------------------------

# -- 'a proper craving for' ("Bob's got a proper craving for an apple"): the want's intensity, said
# 'a craving for' (read)
_PROPER51 = re.compile(
    r"\ba (?P<a>(?:proper|real|right|serious|terrible|massive|huge|desperate|fierce|sudden|big|"
    r"awful|dreadful|mighty|powerful|raging|strong|wicked|major|definite|bit of a) )(?=(?:craving|"
    r"hankering|longing|yen|hunger|thirst|fancy|urge|need|appetite|yearning|itch|hankering) for\b)"
)


def _proper51(text: str, lexicon: Lexicon) -> str:
    """Session 51: 'a proper craving for' read as 'a craving for'."""
    if " for " not in text:
        return text
    m = _PROPER51.search(text)
    if m is None:
        return text
    return _cut50(text, m.start("a"), m.end("a"), "", lexicon)


# -- ', nothing fancier' closing a want ("What Person A needs … is the cup, nothing fancier."):
# that it is just that, taken off
_NOTHING_FANCIER51 = re.compile(
    r",\s*(?:and |just )?nothing (?:fancier|fancy|posher|posh|grander|grand|special|elaborate|"
    r"flash|flashier|more|else|extra|bigger|clever|cleverer)(?: than that)?(?=\s*[.!]?$)"
)


def _nothing_fancier51(text: str, lexicon: Lexicon) -> str:
    """Session 51: a closing ', nothing fancier' taken off."""
    if "nothing " not in text:
        return text
    m = _NOTHING_FANCIER51.search(text)
    if m is None:
        return text
    return _cut50(text, m.start(), m.end(), "", lexicon)


# -- ', being a collier with a dry throat,' after a want ("Person B is after the bottle, being a
# collier with a dry throat, and …", "Person A fancies the chips, being a woodcutter with an
# appetite."): who the person is, why they want it; taken off when it names nothing of the scene
_BEING_A51 = re.compile(
    r",\s*(?:what with |)(?:him |her )?being (?:a|an) (?P<w>[a-z]+(?:[ -][a-z]+){0,3}"
    r"(?: with (?:a|an|no|his|her) [a-z]+(?: [a-z]+)?)?)(?=\s*(?:,|[.!]?$))"
)


def _being_a51(text: str, lexicon: Lexicon) -> str:
    """Session 51: a remark ', being a collier with a dry throat' taken off."""
    if "being a" not in text:
        return text
    m = _BEING_A51.search(text)
    if m is None or _names(m["w"], lexicon):
        return text
    return _cut50(text, m.start(), m.end(), "", lexicon)


# -- 'Ever since the shrimping trip,' opening a want ("Ever since the shrimping trip, the bottle's
# what Person B has been hoping for."): since when, taken off when it names nothing of the scene
_EVER_SINCE51 = re.compile(
    r"^(?:Ever )?[Ss]ince (?:the|his|her|their|that|this|our|my) (?P<w>[a-z]+(?:[ -][a-z]+){0,3})"
    r"\s*,\s*"
)


def _ever_since51(text: str, lexicon: Lexicon) -> str:
    """Session 51: an opening 'Ever since the shrimping trip,' taken off."""
    if not text.startswith(("Ever ", "Since ", "since ")):
        return text
    m = _EVER_SINCE51.match(text)
    if m is None or _names(m["w"], lexicon):
        return text
    return _cut50(text, 0, m.end(), "", lexicon)


# -- 'After an afternoon on the climbing wall,' opening 'P is gasping, so the X' ("After an
# afternoon on the rock climbing wall, Person A is gasping, so the bottle, please."): why, taken
# off when it names nothing of the scene (session 50's _long_day50 reads 'After a long day …,')
_AFTER_STATE51 = re.compile(
    r"^After (?P<w>[^,;.!?]{3,60}),\s*(?=(?P<p>" + _P51 + r")(?:'s| is) (?:gasping|parched|"
    r"starving|famished|thirsty|hungry|peckish|exhausted|shattered|knackered|done in|worn out|"
    r"frozen|freezing|flagging|wilting|dying of thirst|spent)\s*,\s*so\b)"
)


def _after_state51(text: str, lexicon: Lexicon) -> str:
    """Session 51: an opening 'After an afternoon on the climbing wall,' before a state taken
    off."""
    if not text.startswith("After "):
        return text
    m = _AFTER_STATE51.match(text)
    if m is None or _names(m["w"], lexicon) or not _only_person(m["p"], lexicon):
        return text
    return _cut50(text, 0, m.end(), "", lexicon)


# -- '; that's all he's after' closing a want ("Person B wants the chips; that's all he's
# after."): said ', that's all' (read), when the pronoun may be the one person who gets it
_ALL_AFTER51 = re.compile(
    r"\s*;\s*(?:and )?that(?:'s| is) all (?P<pro>he|she|they)(?:(?:'s| is|'re| are) "
    r"(?:after|wanting|asking for|hoping for|angling for)| (?:wants|needs))(?=\s*[.!]?$)"
)


def _all_after51(text: str, lexicon: Lexicon) -> str:
    """Session 51: a closing "; that's all he's after" read as ", that's all"."""
    if "all " not in text or ";" not in text:
        return text
    m = _ALL_AFTER51.search(text)
    if m is None:
        return text
    out = f"{text[: m.start()]}, that's all{text[m.end() :]}"
    return _read_for_said(out, text, m["pro"], lexicon)


# -- ', the site manager wants a count' closing a want ("Mia's crying out for the barcode scanner,
# the site manager wants a count."): why, someone outside the scene's want of something outside
# it; taken off when the clause names nothing of the scene
_OUTSIDER51 = re.compile(
    r",\s*(?:and |as |because |cos |since )?(?:the|our|my|his|her|their) [a-z]+(?: [a-z]+)? "
    r"(?:wants|needs|is after|is waiting on|is waiting for|has asked for|asked for|is expecting) "
    r"(?:a|an|some|the|his|her|their) [a-z]+(?: [a-z]+)?(?: (?:done|doing|by [a-z]+|today|"
    r"soon))?(?=\s*[.!]?$)"
)


def _outsider51(text: str, lexicon: Lexicon) -> str:
    """Session 51: a closing ', the site manager wants a count' taken off."""
    if (
        " wants " not in text
        and " needs " not in text
        and " is " not in text
        and " asked " not in text
    ):
        return text
    m = _OUTSIDER51.search(text)
    if m is None or _names(m.group(0), lexicon):
        return text
    return _cut50(text, m.start(), m.end(), "", lexicon)


# -- "P's been asking / needing …" ("Bob's been asking about the red mug all morning; …", "Noah's
# been needing the ruler"): said 'P has been …' (read where the "'s" is not)
_BEEN51 = re.compile(r"\b(?P<p>" + _P51 + r")(?P<s>'s) been (?=[a-z]+ing\b)")


def _been51(text: str, lexicon: Lexicon) -> str:
    """Session 51: "P's been V-ing" read as 'P has been V-ing'."""
    if "'s been " not in text:
        return text
    m = _BEEN51.search(text)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    return _cut50(text, m.start("s"), m.end("s"), " has", lexicon)


# -- 'a bottle of water' for the scene's 'water bottle' ("Bob's desperate for a bottle of water
# after his cajón session.", "Mrs Khan wants a jug of water."): said by the scene's name of it,
# when that is a name of one object of the scene and the words as said are none
_BOTTLE_OF51 = re.compile(r"\b(?P<d>[Aa]|[Aa]n|[Oo]ne|[Tt]he) (?P<c>[a-z]+) of (?P<w>[a-z]+)\b")


def _bottle_of51(text: str, lexicon: Lexicon) -> str:
    """Session 51: 'a bottle of water' read as 'the water bottle' (above)."""
    if " of " not in text:
        return text
    for m in _BOTTLE_OF51.finditer(text):
        said = f"the {m['w']} {m['c']}"
        if len(_ids(said, lexicon, "object")) != 1:
            continue
        aliases = {a for o in lexicon.scene.objects for a in o.aliases}
        if said[4:] not in aliases or m.group(0)[len(m["d"]) + 1 :] in aliases:
            continue
        return _cut50(text, m.start(), m.end(), said, lexicon)
    return text


# -- a closing 'since the laundress took her paper away' after a want ("Mrs Khan has been pining
# for that magazine since the laundress took her paper away."): since when, a clause of its own;
# taken off when it names nothing of the scene
_SINCE_CLAUSE51 = re.compile(
    r"\s+(?:ever )?since (?P<w>(?:the|her|his|their|a|an|my|our) [a-z]+(?: [a-z]+)? (?:took|"
    r"took away|borrowed|nicked|pinched|broke|lost|moved|hid|tidied|cleared|ran off with|went "
    r"off with|made off with|had|got|left|came|went|finished|started|said|told)\b[^,;.!?]*)"
    r"(?=\s*[.!]?$)"
)


def _since_clause51(text: str, lexicon: Lexicon) -> str:
    """Session 51: a closing 'since the laundress took her paper away' taken off."""
    if " since " not in text:
        return text
    m = _SINCE_CLAUSE51.search(text)
    if m is None or _names(m["w"], lexicon):
        return text
    return _cut50(text, m.start(), m.end(), "", lexicon)


# -- 'P's forgotten his X; lend him ours' ("Noah's forgotten his ruler; lend him ours, would
# you."): 'ours' is the scene's X, the one the person forgot theirs of; said 'the X'
_LEND_OURS51 = re.compile(
    r"^(?P<p>[A-Z]\w*(?: [A-Z]\w*)?)(?:'s| has) (?:forgotten|lost|left behind|mislaid|left) "
    r"(?P<pro>his|her|their) (?P<x>[a-z]+(?: [a-z]+)?)(?: at home)?\s*[;,.]\s*(?:so )?"
    r"(?P<v>lend|give|pass|hand) (?P<to>him|her|them) (?P<ours>ours|one of ours|ours instead)"
)


def _lend_ours51(text: str, lexicon: Lexicon) -> str:
    """Session 51: "P's forgotten his X; lend him ours" read as 'lend him the X'."""
    if "ours" not in text:
        return text
    m = _LEND_OURS51.match(text)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    if len(_ids(f"the {m['x']}", lexicon, "object")) != 1:
        return text
    out = f"{text[: m.start('ours')]}the {m['x']}{text[m.end('ours') :]}"
    return _read_for_said(out, text, f"{m['pro']} {m['to']}", lexicon)


# -- 'she's flagging after the face painting' ("Ta, pet, and could Lily have her teddy now? She's
# flagging after the face painting."): a state of tiredness said in other words before 'after',
# said 'tired' (read: the state and the pastime after it are why)
_FLAGGING51 = re.compile(
    r"\b(?:she|he|they|[A-Z]\w*(?: [A-Z]\w*)?)(?:'s| is|'re| are) (?:a bit |rather |really |"
    r"totally |completely )?(?P<s>flagging|wilting|drooping|whacked|pooped|frazzled|worn to a "
    r"frazzle|dead on (?:her|his|their) feet|running on empty|fit to drop|dog-tired|bushed|"
    r"jiggered|wiped out|washed out)(?= after )",
    _F,
)


def _flagging51(text: str, lexicon: Lexicon) -> str:
    """Session 51: "she's flagging after …" read as "she's tired after …"."""
    if " after " not in text:
        return text
    m = _FLAGGING51.search(text)
    if m is None:
        return text
    return _cut50(text, m.start("s"), m.end("s"), "tired", lexicon)


# -- "P's short a glue stick" ("Noah's short a glue stick. Zoe's short a ruler. Sort them both
# out, cheers."): what the person lacks, said 'P needs a glue stick' (read)
_SHORT_A51 = re.compile(
    r"\b(?P<p>[A-Z]\w*(?: [A-Z]\w*)?)(?:'s| is) (?:a bit |rather |still |one )?short (?:of )?"
    r"(?=(?:a|an|the|one) [a-z])"
)


def _short_a51(text: str, lexicon: Lexicon) -> str:
    """Session 51: "P's short a glue stick" read as 'P needs a glue stick' (each such clause)."""
    if " short " not in text:
        return text
    out, pos = text, 0
    while (m := _SHORT_A51.search(out, pos)) is not None:
        pos = m.end()
        if _only_person(m["p"], lexicon):
            out = f"{out[: m.start()]}{m['p']} needs {out[m.end() :]}"
            pos = m.start() + len(m["p"]) + 7
    if out == text:
        return text
    return _read_for(out, text, None, lexicon)


# -- 'P has been needing the X' ("Noah has been needing the ruler since the start of the
# lesson."): said 'P has needed the X' (read)
_BEEN_NEEDING51 = re.compile(r"\b(?P<h>has|have) been needing\b")


def _been_needing51(text: str, lexicon: Lexicon) -> str:
    """Session 51: 'has been needing' read as 'has needed'."""
    if "been needing" not in text:
        return text
    m = _BEEN_NEEDING51.search(text)
    if m is None:
        return text
    return _cut50(text, m.start(), m.end(), f"{m['h']} needed", lexicon)


# -- pronouns and ellipsis ------------------------------------------------------------------------

# -- 'hers, P's I mean' closing an owner ("The chips are hers, Person A's I mean."): the name said
# after the pronoun to say whose, 'I mean' taken off when the pronoun may be that person
_I_MEAN51 = re.compile(
    r"\b(?P<pro>hers|his|theirs),\s*(?P<p>" + _P51 + r")'s,?\s*I mean(?=\s*[.!]?$)"
)


def _i_mean51(text: str, lexicon: Lexicon) -> str:
    """Session 51: "hers, P's I mean" read as "hers, P's"."""
    if "I mean" not in text:
        return text
    m = _I_MEAN51.search(text)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    out = f"{text[: m.start()]}{m['pro']}, {m['p']}'s{text[m.end() :]}"
    return _read_for_said(out, text, m["pro"], lexicon)


# -- 'At the narrowboat club' opening what people asked for ("At the narrowboat club Person A
# asked for the bottle and …"): where they asked, taken off when it names nothing of the scene
_AT_THE51 = re.compile(
    r"^At (?:the|our|my|his|her|their) (?P<w>[a-z]+(?:[ -][a-z]+){0,3}?),? (?=(?P<p>"
    + _P51
    + r") (?:asked|asked for|wanted|said|put in for|requested|ordered|was after)\b)"
)


def _at_the51(text: str, lexicon: Lexicon) -> str:
    """Session 51: an opening 'At the narrowboat club' before what someone asked taken off."""
    if not text.startswith("At "):
        return text
    m = _AT_THE51.match(text)
    if m is None or _names(m["w"], lexicon) or not _only_person(m["p"], lexicon):
        return text
    return _cut50(text, 0, m.end(), "", lexicon)


# -- 'see to the pair of them' after two requests ("…, so could you see to the pair of them."):
# said 'see to them both' (read)
_PAIR51 = re.compile(
    r"\b(?P<v>see to|sort out|deal with|look after|take care of|attend to|sort) (?P<n>the pair of "
    r"them|the two of them|both of them|the both of them|the pair|the two|the lot of them)"
    r"(?=\s*[.!?]?$)"
)


def _pair51(text: str, lexicon: Lexicon) -> str:
    """Session 51: 'see to the pair of them' read as 'see to them both'."""
    if " of them" not in text and "the pair" not in text and "the two" not in text:
        return text
    m = _PAIR51.search(text)
    if m is None:
        return text
    return _cut50(text, m.start("n"), m.end("n"), "them both", lexicon)


# -- "It's P's X, she wants it." ("It's Person A's bottle, she wants it."): said 'P wants the X'
# (read), when the pronoun may be P
_ITS_ONES51 = re.compile(
    r"^It(?:'s| is) (?P<p>" + _P51 + r")'s (?P<x>[a-z]+(?: [a-z]+)?)\s*[,;]\s*(?:and )?"
    r"(?P<pro>she|he|they) (?P<v>wants|needs|'d like|would like|asked for|is after|'s after|"
    r"'re after|are after|want|need) (?:it|that one|them)(?=\s*[.!]?$)"
)


def _its_ones51(text: str, lexicon: Lexicon) -> str:
    """Session 51: "It's P's X, she wants it." read as 'P wants the X'."""
    if not text.startswith("It"):
        return text
    m = _ITS_ONES51.match(text)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    v = {"'d like": "would like", "'s after": "is after", "'re after": "is after"}.get(
        m["v"], m["v"]
    )
    out = f"{m['p']} {v} the {m['x']}{text[m.end() :]}"
    return _read_for_said(out, text, m["pro"], lexicon)


# -- ', same as last time,' ("Person A again, same as last time, the bottle."): that it is asked
# again, taken off (what is asked is said beside it)
_SAME_AS51 = re.compile(
    r",\s*(?:the |just )?same as (?:last time|before|yesterday|usual|always|ever|last week|the "
    r"other day|this morning)\s*(?=,)"
)


def _same_as51(text: str, lexicon: Lexicon) -> str:
    """Session 51: ', same as last time,' taken off."""
    if "same as " not in text:
        return text
    m = _SAME_AS51.search(text)
    if m is None:
        return text
    return _cut50(text, m.start(), m.end(), "", lexicon)


# -- ', the lass who does aerial silks' closing a name ("…, that's hers, Person A's, the lass who
# does aerial silks."): who the person is, taken off when it names nothing of the scene
_THE_LASS51 = re.compile(
    r"(?<=\w),\s*the (?:lass|lad|girl|boy|woman|man|chap|fella|"
    r"fellow|bloke|guy|lady|gent|gentleman|one|person|kid|young [a-z]+|old [a-z]+) (?:who|that)"
    r"(?:'s| is| does| plays| runs| teaches| works| [a-z]+s)\b(?P<w>[^,;.!?]*)(?=\s*[.!]?$)"
)


def _the_lass51(text: str, lexicon: Lexicon) -> str:
    """Session 51: a closing ', the lass who does aerial silks' taken off."""
    if " who" not in text and " that" not in text:
        return text
    m = _THE_LASS51.search(text)
    if m is None or _names(m.group(0), lexicon):
        return text
    return _cut50(text, m.start(), m.end(), "", lexicon)


# -- 'P and Q were both on about the X' ("Ruth and Mrs Khan were both on about the jug; she says
# it's hers."): said 'P and Q both wanted the X' (whose refusal names who it could be)
_BOTH_ON51 = re.compile(
    r"\b(?P<p>" + _P51 + r") and (?P<q>" + _P51 + r") (?:were|are|have been|'ve been|'re) both "
    r"(?:on about|after|going on about|asking (?:about|for|after)|wanting|keen on|set on|eyeing|"
    r"angling for|hankering after|banging on about) (?=(?:the|that|this) )"
)


def _both_on51(text: str, lexicon: Lexicon) -> str:
    """Session 51: 'P and Q were both on about the X' said 'P and Q both wanted the X'."""
    if " both " not in text:
        return text
    m = _BOTH_ON51.search(text)
    if m is None or not (_only_person(m["p"], lexicon) and _only_person(m["q"], lexicon)):
        return text
    return f"{text[: m.start()]}{m['p']} and {m['q']} both wanted {text[m.end() :]}"


# -- questions -------------------------------------------------------------------------------------

# -- 'Do you think P (, who …,) could have the X?' ("Do you think Person A, who's been grafting
# roses all morning, could have the cup?"): asked as 'Could P (, who …,) have the X?' (read)
_DO_YOU_THINK51 = re.compile(
    r"^(?:Do you think|D'you think|Do you reckon|D'you reckon|Would you say|Do you suppose) "
    r"(?P<p>" + _P51 + r")(?P<rel>,[^,?]{3,80},)? (?P<m>could|can|might|may|would) "
    r"(?=(?:have|get|be given|borrow|take)\b)"
)


def _do_you_think51(text: str, lexicon: Lexicon) -> str:
    """Session 51: 'Do you think P could have the X?' asked as 'Could P have the X?'."""
    if not text.startswith(("Do ", "D'you ", "Would ")):
        return text
    m = _DO_YOU_THINK51.match(text)
    if m is None or not m["rel"] or not _only_person(m["p"], lexicon):
        return text
    put = f"{m['m'].capitalize()} {m['p']}{m['rel'] or ''} "
    return _read_for(f"{put}{text[m.end() :]}", text, None, lexicon)


# -- ', as a favour (to a weary mahout)' closing a request ("Can you give Person B the chips, as a
# favour to a weary mahout?"): why, taken off when it names nothing of the scene
_FAVOUR51 = re.compile(
    r",\s*as a (?:(?:little|small|big|special|personal) )?(?:favour|favor|kindness|treat|good "
    r"turn)(?: to (?P<to>[^,;.!?]+))?(?=\s*[.!?]?$)"
)


def _favour51(text: str, lexicon: Lexicon) -> str:
    """Session 51: a closing ', as a favour (to …)' taken off."""
    if " as a " not in text:
        return text
    m = _FAVOUR51.search(text)
    if m is None or (m["to"] and _names(m["to"], lexicon)):
        return text
    return _cut50(text, m.start(), m.end(), "", lexicon)


# -- 'so P can grab it on his way out' closing a placing ("Can you put the packing tape on the
# pallet so Tom can grab it on his way out?"): why it is put there, taken off when what is left
# only places things
_GRAB_IT51 = re.compile(
    r",?\s+so (?:that )?(?P<p>" + _P51 + r"|he|she|they) (?:can|could|will|'ll|may|might) "
    r"(?:grab|collect|get|take|pick up|fetch|pick|nab|find) (?:it|them)(?: up)?(?: (?:on "
    r"(?:his|her|their) way (?:out|in|past|home|through)|later(?: on)?|when (?:he|she|they) "
    r"(?:goes|leaves|passes|comes|gets)[^,.;!?]*|after [^,.;!?]+|first thing))?(?=\s*[.!?]?$)"
)


def _grab_it51(text: str, lexicon: Lexicon) -> str:
    """Session 51: a closing 'so P can grab it on his way out' taken off a placing."""
    if " so " not in text:
        return text
    m = _GRAB_IT51.search(text)
    if m is None or (m["p"][0].isupper() and not _only_person(m["p"], lexicon)):
        return text
    out = f"{text[: m.start()]}{text[m.end() :]}"
    read = _reading(out, lexicon)
    if read is None or any(t.kind != "place" for t in tasks(read)):
        return text
    return out


# -- a sentence saying someone needs a surface clear ("Would you put the globe on the bookshelf?
# Mrs Ortiz needs the desk clear for the crystal radio demo."): why, taken off when what is left
# only places things, none on that surface
_CLEAR51 = re.compile(
    r"(?<=[.?!])\s+(?P<p>" + _P51 + r"|[Ss]he|[Hh]e|[Tt]hey|We) (?:needs|need|wants|want|would "
    r"like|'d like|has asked for|asked for|likes) the (?P<s>[a-z]+(?: [a-z]+)?) (?:clear|cleared|"
    r"free|empty|emptied|tidy|tidied|clean|clear of clutter)(?: (?:for|before|by) [^.!?]+)?"
    r"[.!]?$"
)


def _clear51(text: str, lexicon: Lexicon) -> str:
    """Session 51: a closing 'P needs the desk clear (for …).' taken off a placing."""
    if (
        " clear" not in text
        and " free" not in text
        and " empty" not in text
        and " tidy" not in text
        and " clean" not in text
    ):
        return text
    m = _CLEAR51.search(text)
    if m is None:
        return text
    if m["p"] not in ("She", "he", "He", "she", "They", "they", "We") and not _only_person(
        m["p"], lexicon
    ):
        return text
    surfaces = _ids(f"the {m['s']}", lexicon, "surface")
    if not surfaces:
        return text
    out = text[: m.start()]
    read = _reading(out, lexicon)
    if read is None or any(t.kind != "place" or t.target in surfaces for t in tasks(read)):
        return text
    return out


# -- ', a mate's bike has a loose nut' closing a request ("Could Kofi borrow the big spanner for a
# bit, a mate's bike has a loose nut?"): why; said ', the mate's bike …' (read as a remark)
_A_MATES51 = re.compile(
    r",\s*(?P<a>a) (?=(?:mate|friend|neighbour|pal|cousin|brother|sister|colleague|buddy|chum|"
    r"workmate|flatmate|housemate|neighbour)'s [a-z]+ (?:has|is|needs|'s|wants|keeps)\b)"
)


def _a_mates51(text: str, lexicon: Lexicon) -> str:
    """Session 51: ", a mate's bike has …" read as ", the mate's bike has …"."""
    if "'s " not in text or ", a " not in text:
        return text
    m = _A_MATES51.search(text)
    if m is None:
        return text
    return _cut50(text, m.start("a"), m.end("a"), "the", lexicon)


# -- refusals -------------------------------------------------------------------------------------

# -- what would or should have been ("Alice would have wanted the apple.", "Mr Lee should have got
# the magazine."): a want or a handover that did not happen, no request; refused (session 44's
# refusal takes 'should have had')
_WOULD_HAVE51 = re.compile(
    r"\b(?P<said>(?:would|should|could|might|must|'d)(?: have|'ve| of) (?:wanted|liked|loved|"
    r"needed|got|gotten|preferred|enjoyed|fancied|been given|received|asked for))\b",
    _F,
)


_WOULD_P_HAVE51 = re.compile(
    r"\b(?P<said>(?:could|would|should|might|must) (?:[A-Z]\w*(?: [A-Z]\w*)?|he|she|they) "
    r"(?:have|'ve) (?:been given|got|had|received|wanted|been handed))\b",
    _F,
)


def _would_have51(text: str, lexicon: Lexicon) -> None:
    """Session 51: refuse a want or a handover said as what would or should have been."""
    low = text.lower()
    if " have " not in low and "'ve " not in low and " of " not in low:
        return
    m = _WOULD_HAVE51.search(text) or _WOULD_P_HAVE51.search(text)
    if m is None:
        return
    raise GroundingError(
        f"{m['said']!r} says what would have been, not what to do now: it asks for nothing; say "
        "'give <person> <object>' to have it handed over"
    )


# -- a verb of handing over said in the past opening the text ("Gave Bob the apple.", "Took the jug
# to Mrs Khan.", "you gave bob the apple"): what was done, no request (the lexicon reads the past
# form as the order's verb); refused (12c's fuzz)
_DONE_VERB51 = re.compile(
    r"^(?P<said>(?:(?:just|already|you|u|you've|you have|you just|we|we've)\s+)*(?:gave|given|"
    r"brought|took|taken|handed|passed|delivered|placed|moved|dropped|fetched|carried|returned|"
    r"sent|laid))\b",
    _F,
)
# the words such a text opens with (a cheap test before the pattern)
_DONE_FIRST51 = (
    "just",
    "already",
    "you",
    "u ",
    "we",
    *[
        "gave",
        "given",
        "brought",
        "took",
        "taken",
        "handed",
        "passed",
        "delivered",
        "placed",
        "moved",
        "dropped",
        "fetched",
        "carried",
        "returned",
        "sent",
        "laid",
    ],
)


# 'you' + the past verb after a clause's start ("Thanks, you brought Carol the blue mug.",
# "Jërëjëf, as we say back in Dakar, and you brought Carol the blue mug."): what the robot did
_YOU_DID51 = re.compile(
    r"[,;.!?:]\s*(?:(?:and|so|but|oh|well|now)\s+)?(?P<said>(?:you|u|you've|you have|we|we've)"
    r"\s+(?:just\s+|already\s+)?(?:gave|brought|took|handed|passed|delivered|placed|moved|"
    r"dropped|fetched|carried|returned|sent))\b",
    _F,
)


def _done_verb51(text: str, lexicon: Lexicon) -> None:
    """Session 51: refuse a verb of handing over in the past opening the text or, after 'you',
    a clause (above)."""
    m = None
    if text[:12].lower().startswith(_DONE_FIRST51):
        m = _DONE_VERB51.match(text.lstrip())
    if m is None and ("you" in text or "You" in text or "we" in text or " u " in text):
        m = _YOU_DID51.search(text)
    if m is None:
        return
    raise GroundingError(
        f"{m['said']!r} says what was done: it asks for nothing; say 'give …' or 'put …' to have "
        "it done"
    )


# -- 'P has received the X' ("Person A has received the chips."): what was done, no request;
# refused ("Bob's been given the apple." is refused already)
_RECEIVED51 = re.compile(
    r"^(?P<said>(?P<p>[A-Z]\w*(?: [A-Z]\w*)?) (?:has|have|'s) (?:already |just |now )?"
    r"(?:received|been handed|got hold of|collected|picked up|been sent))\b"
)


def _received51(text: str, lexicon: Lexicon) -> None:
    """Session 51: refuse 'P has received the X' (above)."""
    if (
        " received " not in text
        and " been " not in text
        and " got hold " not in text
        and " collected " not in text
        and " picked up " not in text
    ):
        return
    m = _RECEIVED51.match(text)
    if m is None or not _only_person(m["p"], lexicon):
        return
    raise GroundingError(
        f"{m['said']!r} says what was done: it asks for nothing; say 'give …' to have it done"
    )


# -- a want said over by another ("Bob wanted the apple, now he wants the crisps.", "Bob asked for
# the apple earlier, now he's after the crisps."): the new want may replace the old or add to it;
# refused (12c's fuzz: both were read; "…, but now he'd rather have the jug" replaces it, read)
_WANT_NOW51 = re.compile(
    r"\b(?:wanted|asked for|was after|had asked for|asked after|was wanting|requested|fancied|"
    r"was hoping for|needed)\b[^.;!?]*?[,;.]\s*(?:but |and |though |only )?(?:now|these days|"
    r"today|this time)\s*,?\s*(?P<pro>he|she|they)(?:'s| is|'re| are)? (?:wants|needs|'d like|"
    r"would like|fancies|prefers|after|asking for|asks for|keen on|set on|hoping for|want|need)\b",
    _F,
)


_WANT_NOW_NAMED51 = re.compile(
    r"\b(?P<p>[A-Z]\w*(?: [A-Z]\w*)?) (?:wanted|asked for|was after|had asked for|asked after|"
    r"was wanting|requested|fancied|was hoping for|needed)\b[^.;!?]*?[,;.]\s*(?:but |and |though |"
    r"only )?(?:now|these days|today|this time)\s*,?\s*(?P<q>[A-Z]\w*(?: [A-Z]\w*)?)(?:'s| is)? "
    r"(?:wants|needs|'d like|would like|fancies|prefers|after|asking for|asks for|keen on|set on|"
    r"hoping for)\b"
)


def _want_now51(text: str, lexicon: Lexicon) -> None:
    """Session 51: refuse a past want followed by 'now he wants …' (above)."""
    if "now" not in text.lower() and "today" not in text.lower() and "this time" not in text:
        return
    m = _WANT_NOW51.search(text)
    if m is None:
        m = _WANT_NOW_NAMED51.search(text)
        if m is None or m["p"] != m["q"] or not _only_person(m["p"], lexicon):
            return
    earlier_and_new51(m.group(0))


def earlier_and_new51(said: str) -> NoReturn:
    """Refuse ``said``, an earlier want and a new one (also session 53's ``_want_over53l``)."""
    raise GroundingError(
        f"{said!r} says an earlier want and a new one: the new one may replace it or add to it; "
        "say 'instead' or 'too'"
    )


# -- a request, then that its person is away ("Give Bob the apple, hmm, he's gone.", "…, oh, he's
# not here."): it cannot be done now; refused (", but he's gone home." is refused already)
_GONE51 = re.compile(
    r"[,;.!?]\s*(?:(?:oh|hmm|ah|wait|actually|oops|ugh|um|er|erm|oh no|drat|damn)\s*[,.!]?\s+)?"
    r"(?P<said>(?:he|she|they)(?:'s| is|'ve| has| have|'re| are) (?:just |already )?(?:gone|left|"
    r"not here|not around|not in|away|been discharged|gone home|gone out|popped out|nipped out|"
    r"off home|clocked off|gone off home|gone for the day|not here any ?more)(?: (?:now|already|"
    r"for the day|for the night|any ?more|again))?)\s*[.!]*$",
    _F,
)


def _gone51(text: str, lexicon: Lexicon) -> None:
    """Session 51: refuse a request closed by 'he's gone' (above)."""
    low = text.lower()
    if (
        "gone" not in low
        and "left" not in low
        and "not " not in low
        and "away" not in low
        and "discharged" not in low
        and " out" not in low
        and " off" not in low
    ):
        return
    m = _GONE51.search(text)
    if m is None:
        return
    raise GroundingError(
        f"{m['said']!r} says the person is not there: the request cannot be done now; say it "
        "again when they are back"
    )


# -- a report closed by saying it is not true ("Ava says Grandad wants the bib, she's fibbing.",
# "Alice says Bob wants the apple, she's pulling your leg."): nothing is asked; refused (", but
# she's joking." is refused already)
_FIBBING51 = re.compile(
    r"[,;.!]\s*(?:(?:and|though|mind|mind you|only)\s+)?(?P<said>(?:she|he|they)(?:'s| is|'re| "
    r"are|'s only| is only|'re only| are only|'s just| is just) (?:fibbing|lying|pulling your "
    r"leg|pulling my leg|having you on|having us on|winding you up|winding us up|kidding|joking|"
    r"teasing|making it up|telling porkies|telling fibs|telling tales|having a laugh|messing "
    r"about|messing around|not serious))\s*[.!]*$",
    _F,
)


def _fibbing51(text: str, lexicon: Lexicon) -> None:
    """Session 51: refuse a request or report closed by "she's fibbing" (above)."""
    if (
        "ing" not in text
        and " leg" not in text
        and " on" not in text
        and " up" not in text
        and "porkies" not in text
        and "fibs" not in text
        and "tales" not in text
        and "serious" not in text
    ):
        return
    m = _FIBBING51.search(text)
    if m is None:
        return
    raise GroundingError(
        f"{m['said']!r} says what was said is not meant: it asks for nothing; say the request "
        "itself"
    )


# -- what a person usually has ("Alice usually gets the crisps.", "Alice normally has the red
# mug."): a habit, not a request; refused when the text is that sentence alone
_HABIT51 = re.compile(
    r"^(?P<said>(?P<p>[A-Z]\w*(?: [A-Z]\w*)?) (?:usually|normally|generally|typically|always|"
    r"often|mostly|tends to|likes to) (?:gets?|has|have|takes?|receives?|is given|gets given))"
    r" [^,;.!?]+[.!]?$"
)


def _habit51(text: str, lexicon: Lexicon) -> None:
    """Session 51: refuse a sentence saying what a person usually gets (above)."""
    m = _HABIT51.match(text)
    if m is None or not _only_person(m["p"], lexicon):
        return
    raise GroundingError(
        f"{m['said']!r} says what usually happens: it asks for nothing; say 'give {m['p']} …' to "
        "have it handed over"
    )


# -- a want, then that the person has it ("Bob's been asking about the red mug all morning; he's
# got it now.", "Bob needs the apple, but he's had it."): nothing is left to do; refused (", but
# he's got it." was refused already)
_HAS_IT51 = re.compile(
    r"[,;.!?]\s*(?:(?:but|and|though|oh|well)\s*,?\s+)?(?P<said>(?:he|she|they)(?:'s|'ve| has| "
    r"have) (?:already |just )?(?:got|had|received|been given|gotten) (?:it|them|that|those|"
    r"that one)(?: (?:now|already|by now|since|though|anyway))?|(?:he|she) has (?:it|them) "
    r"(?:now|already)|they have (?:it|them) (?:now|already))\s*[.!]*$",
    _F,
)


def _has_it51(text: str, lexicon: Lexicon) -> None:
    """Session 51: refuse a want closed by "he's got it now" (above)."""
    if (
        " got " not in text
        and " had " not in text
        and " has " not in text
        and " have " not in text
        and "'s had" not in text
        and " received " not in text
        and " given " not in text
        and " gotten " not in text
    ):
        return
    m = _HAS_IT51.search(text)
    if m is None:
        return
    raise GroundingError(
        f"{m['said']!r} says the person has it already: nothing is left to do; say the request "
        "again if it still stands"
    )


# -- a request, then the speaker saying it is done or that they will do it ("Alice asked for the
# apple, it's sorted.", "Alice wants the apple, I've done it.", "The apple for Bob, I'll do it
# myself.", "…, and I've seen to the pair of them."): nothing is asked of the robot; refused
_DONE_SAID51 = re.compile(
    r"[,;.!?]\s*(?:(?:and|but|so|oh|well|though)\s*,?\s+)?(?P<said>(?:(?:it's|that's|it is|that is|"
    r"it has|it's all|that's all|it's been|that's been|they're|they've been|it was|all) "
    r"(?:all |already |been |now )*(?:sorted|handled|taken care of|dealt with|seen to|sorted out)"
    r"|(?:it's|that's|it has|that has|it is|that is|it was|that was|they've|they have) (?:all )?"
    r"(?:been |already )+done"
    r"|(?:I've|I have|I|we've|we have|we|I'll|I will|we'll|I'm going to|I can|let me|leave it, "
    r"I'll) (?:already |just |quickly |now )*(?:done|did|do|sorted|sort|sort out|sorted out|"
    r"handled|handle|seen to|see to|dealt with|deal with|taken care of|take care of|get|got|fetch|"
    r"grab|grabbed) (?:it|that|them|this|those|that one|this one|the pair of them|both of them|"
    r"the lot|both|it all|them both|it out|that out)(?: (?:myself|ourselves|out|already|now|"
    r"for (?:him|her|them)))?))\s*[.!]*$",
    _F,
)


def _done_said51(text: str, lexicon: Lexicon) -> None:
    """Session 51: refuse a request closed by the speaker saying it is done or theirs to do."""
    m = _DONE_SAID51.search(text)
    if m is None:
        return
    raise GroundingError(
        f"{m['said']!r} says it is done or the speaker's to do: nothing is asked of the robot; "
        "say the request alone"
    )


# -- praise for what is done ("Great job putting the apple on the shelf.", "Well done getting the
# jug to Mrs Khan."): thanks for what is done; refused ("Thanks for giving Bob the apple." is)
_PRAISE51 = re.compile(
    r"\b(?P<said>(?:(?:great|good|nice|excellent|brilliant|fantastic|lovely|super|top|fine|"
    r"smashing|cracking|terrific|splendid|awesome) (?:job|work|stuff|effort|going)|well done|"
    r"nicely done|kudos|bravo|nice one)(?: (?:on|with|for|in))? (?:putting|giving|getting|"
    r"bringing|handing|taking|passing|moving|delivering|fetching|dropping|placing|sending|"
    r"carrying|popping|setting|sorting))\b",
    _F,
)


def _praise51(text: str, lexicon: Lexicon) -> None:
    """Session 51: refuse praise for a handover or a placing done (above)."""
    low = text.lower()
    if "ing" not in low or (
        " job" not in low
        and " work" not in low
        and "done" not in low
        and "stuff" not in low
        and "effort" not in low
        and "going" not in low
        and "kudos" not in low
        and "bravo" not in low
        and "nice one" not in low
    ):
        return
    m = _PRAISE51.search(text)
    if m is None:
        return
    raise GroundingError(
        f"{m['said']!r} praises what is done: it asks for nothing; say 'give …' or 'put …' to "
        "have it done"
    )


# -- 'possibly' before an object added to a request ("Give Bob the apple and possibly the
# crisps."): leaves open whether to do it, as 'perhaps' does; refused ("Could you possibly …"
# asks politely and is read)
_POSSIBLY51 = re.compile(
    r"(?:\b(?:and|or)|,)\s+(?P<said>(?:possibly|potentially|conceivably)) (?:also )?(?=(?:the|a|"
    r"an|some|that|those|these|this) )|\b(?:the|a|an) [a-z]+(?: [a-z]+)? (?P<said2>possibly|"
    r"potentially)(?=\s*(?:too|as well)?\s*[.!]?$)",
    _F,
)


def _possibly51(text: str, lexicon: Lexicon) -> None:
    """Session 51: refuse 'possibly' before an added object (above)."""
    low = text.lower()
    if "possibly" not in low and "potentially" not in low and "conceivably" not in low:
        return
    m = _POSSIBLY51.search(text)
    if m is None:
        return
    raise GroundingError(
        f"{m['said'] or m['said2']!r} leaves open whether to do it: say what to do"
    )


# -- 'Will P get the X?' ("Will Bob get the apple?", "Will the apple go on the shelf?"): a
# question that only asks what will happen ("Does Bob get …?", "Should Bob get …?" are refused;
# "Will you give Bob the apple?" asks the robot and is read)
_WILL51 = re.compile(
    r"^(?P<said>Will (?!you\b|u\b|ya\b|one of you\b|someone\b|somebody\b|anyone\b|the robot)"
    r"[^?]{1,60}? (?:get|be getting|have|be having|be given|receive|go|be going|end up))\b[^?]*\?"
    r"\s*$",
    _F,
)


def _will51(text: str, lexicon: Lexicon) -> None:
    """Session 51: refuse 'Will P get the X?' (above)."""
    if not text[:5].lower().startswith("will "):
        return
    m = _WILL51.match(text)
    if m is None:
        return
    raise GroundingError(
        f"{m['said']!r} asks what will happen: it asks for nothing; say 'give …' or 'put …'"
    )


# -- a task said to be done, before another ("The apple to Bob is done, now the crisps to
# Alice.", "Apple to Bob: done. Crisps to Alice: please.", "Bob: apple done. …"): a checklist
# whose done item is no request; refused
_CHECKLIST51 = re.compile(
    r"(?P<said>\b(?:to|for|on|onto|in|into|with) (?:the )?[A-Za-z]+(?: [A-Za-z]+)?(?: is|'s|"
    r" has been|'s been)?\s*[:\-–—]?\s*(?:done|sorted|ticked off|complete|finished|delivered)"
    r"|^[A-Z]\w*(?: [A-Z]\w*)?: [a-z]+(?: [a-z]+)? (?:done|sorted|ticked off))(?: already)?"
    r"\s*[,.;:!—–-]\s*(?=\S)",
    _F,
)


def _checklist51(text: str, lexicon: Lexicon) -> None:
    """Session 51: refuse a task said to be done before another (above)."""
    low = text.lower()
    if (
        "done" not in low
        and "sorted" not in low
        and "ticked" not in low
        and "complete" not in low
        and "finished" not in low
        and "delivered" not in low
    ):
        return
    m = _CHECKLIST51.search(text)
    if m is None:
        return
    raise GroundingError(f"{m['said']!r} says a task is done: say only what is still to do")


# -- 'they' after two people ("Give Alice the apple and Bob the crisps; they also want the
# bottle."): both of them, or either; refused (it had been read as the last one; 'he' / 'she' in
# that place are refused naming who it could be)
_THEY51 = re.compile(
    r"(?<=[.;,!?])\s*(?:and |but |oh, |oh )?(?P<said>they) (?:also |too |as well |both |each )?"
    r"(?:want|need|'d like|would like|asked for|fancy|are after|'re after|wanted|needed)\b",
    _F,
)


def _they51(text: str, lexicon: Lexicon) -> None:
    """Session 51: refuse a 'they' said after two or more people were named (above)."""
    if "they" not in text.lower():
        return
    m = _THEY51.search(text)
    if m is None or len(_ids(text[: m.start()], lexicon, "human")) < 2:
        return
    after = text[m.end() :]
    if _ids(after, lexicon, "human") or not _ids(after, lexicon, "object"):
        return  # (someone named after it, or no new object: 'they both want them')
    raise GroundingError(
        f"{m['said']!r} after {text[: m.start()].strip()!r} could mean both people or one of "
        "them: name the person"
    )


# -- one object both placed and handed over at once ("Put the mugs on the shelf, Bob's got the red
# one." read mug_red@shelf & mug_red>B): a reading that does two things with one object at the
# same time contradicts itself; refused (12c's fuzz)
_HOLDS51 = re.compile(r"(?:'s got|'s had| has got| has had| has| had| got)\b")


def _one_object_twice51(text: str, node: Node, lexicon: Lexicon) -> None:
    """Session 51: refuse a reading whose 'and' does two things with one object, when the text
    says someone has or had a thing ('give it to Bob' after a placing reads as before)."""
    if _HOLDS51.search(text) is None:
        return
    stack = [node]
    while stack:
        n = stack.pop()
        if isinstance(n, Group):
            if n.op == "and":
                seen: dict[str, int] = {}
                for k, child in enumerate(n.children):
                    for t in tasks(child):
                        if seen.setdefault(t.obj, k) != k:
                            raise GroundingError(
                                f"the reading does two things with the {t.obj} at once: say "
                                "which, or in which order"
                            )
            stack.extend(n.children)


# the normaliser's first rewrites (wired into normalise._STEPS19, before the session-50 ones)
_STEPS51_FIRST: tuple[Callable[[str, Lexicon], str], ...] = (
    _gloss51,
    _thanks_in51,
    _spare51,
    _over_with51,
    _with_apologies51,
    _star51,
    _proper51,
    _nothing_fancier51,
    _being_a51,
    _ever_since51,
    _after_state51,
    _all_after51,
    _outsider51,
    _bottle_of51,
    _short_a51,
    _since_clause51,
    _lend_ours51,
    _flagging51,
    _been51,
    _been_needing51,
    _i_mean51,
    _at_the51,
    _pair51,
    _its_ones51,
    _same_as51,
    _the_lass51,
    _both_on51,
    _do_you_think51,
    _favour51,
    _grab_it51,
    _clear51,
    _a_mates51,
)
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-50 ones)
_STEPS51: tuple[Callable[[str, Lexicon], str], ...] = ()
# refusals asked of the text before it is read (offline._parse, after the session-50 ones)
REFUSE51: tuple[Callable[[str, Lexicon], None], ...] = (
    _would_have51,
    _done_verb51,
    _received51,
    _want_now51,
    _gone51,
    _fibbing51,
    _habit51,
    _has_it51,
    _done_said51,
    _praise51,
    _possibly51,
    _will51,
    _checklist51,
    _they51,
)
# checks of the whole instruction's reading (offline.parse_instruction, after the session-50 ones)
CHECK51: tuple[Callable[[str, Node, Lexicon], None], ...] = (_one_object_twice51,)
