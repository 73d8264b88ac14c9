"""The grounder's rules of session 49, engineer 12 (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _names, _only_person, _unknown_word
from hltl.grounding._rewrites45 import _read_for, _read_for_said
from hltl.grounding._rewrites48 import _placing48
from hltl.grounding.lexicon import Lexicon
from hltl.grounding.tree import Node

# -- session 49 (engineer 12): blind47's refusals of politeness and fillers, wants and needs,
# pronouns and ellipsis and questions, each read as a family. Every rule rewrites to words the
# grammar (or an older rule) already reads, and keeps the rewrite only when it reads.


def _capital49(out: str) -> str:
    """``out`` with its first letter upper-cased."""
    return out[:1].upper() + out[1:]


# -- sympathy said after the request with a word the grounder does not know ("Lily's grizzling
# for her teddy bear again, poor mite.", "…, the poor little poppet."): the courtesy list's
# ', poor thing' took such words for a name before it ran; taken off when the words name nothing
_POOR49 = re.compile(r",\s*(?:the )?poor (?:little |wee |old )?(?P<w>[a-z]+)(?=\s*(?:[.!]|$))", _F)


def _poor49(text: str, lexicon: Lexicon) -> str:
    """Session 49: the sympathy above taken off."""
    if "poor " not in text.lower():
        return text
    m = _POOR49.search(text)
    if m is None or _names(m.group(0).strip(", ").removeprefix("the "), lexicon):
        return text
    if " poor " + m["w"] in m.group(0) and not _unknown_word(m["w"], lexicon):
        return text  # ('…, poor man' and the courtesy list's other words are read already)
    return _read_for(f"{text[: m.start()]}{text[m.end() :]}", text, None, lexicon)


# -- 'seeing' alone opening a reason that the person asked or waited ("Could the bottle go over
# to Person A, seeing she's asked twice?"): read as 'seeing as' (session 28's reasons read that;
# other reasons after a bare 'seeing' are older rules')
_SEEING49 = re.compile(
    r",\s*seeing (?=(?:she|he|they)(?:'s|'ve| has| have) (?:asked|been asking|waited|been waiting|"
    r"requested|put in for|been after)\b)"
)


def _seeing49(text: str, lexicon: Lexicon) -> str:
    """Session 49: 'seeing' before a pronoun and its verb read as 'seeing as'."""
    if ", seeing " not in text:
        return text
    out = _SEEING49.sub(", seeing as ", text, count=1)
    return text if out == text else _read_for(out, text, None, lexicon)


# -- 'sorting P out with the X' ("would you mind sorting him out with the bottle?"): giving P
# the X (an older rule reads 'sort P out with the X')
_SORT49 = re.compile(
    r"\bsorting (?P<p>him|her|them|[A-Z]\w*(?: [A-Z]\w*)?) out with "
    r"(?P<x>(?:the|a|an|some|his|her|their) )",
)


def _sort_out49(text: str, lexicon: Lexicon) -> str:
    """Session 49: 'sorting P out with the X' read as 'giving P the X'."""
    if "sorting " not in text:
        return text
    m = _SORT49.search(text)
    if m is None:
        return text
    out = f"{text[: m.start()]}giving {m['p']} {m['x']}{text[m.end() :]}"
    return _read_for(out, text, None, lexicon)


# -- a reason that something is in someone's way ("Would you set the bowl down on the tray, it's
# in Dana's way?"): read as 'it's in the way' (an older rule reads that), the person named
_IN_WAY49 = re.compile(
    r",\s*it(?:'s| is) (?:getting )?in (?P<p>[A-Z]\w*(?: [A-Z]\w*)?'s|his|her|their) way"
    r"(?=\s*[.!?]?$)"
)


def _in_way49(text: str, lexicon: Lexicon) -> str:
    """Session 49: '… in P's way' closing a placing read as '… in the way'."""
    if " way" not in text:
        return text
    m = _IN_WAY49.search(text)
    if m is None:
        return text
    out = f"{text[: m.start()]}, it's in the way{text[m.end() :]}"
    return _read_for(out, text, None, lexicon)


# -- 'for that' closing a request after what someone is doing ("Jess is putting up brackets,
# could you fetch Jess the power drill for that?"): the purpose said again, taken off
_FOR_THAT49 = re.compile(r" for (?:that|this|the job)(?=\s*[.!?]?$)")


def _for_that49(text: str, lexicon: Lexicon) -> str:
    """Session 49: a closing 'for that' taken off a request after a remark."""
    if not text.rstrip(" .!?").endswith(("for that", "for this", "for the job")):
        return text
    m = _FOR_THAT49.search(text)
    if m is None or "," not in text[: m.start()]:
        return text
    return _read_for(f"{text[: m.start()]}{text[m.end() :]}", text, None, lexicon)


# -- 'any objection to' before what to do ("Person B's hungry, any objection to giving him the
# chips?"): asked as 'would you mind' ('any chance of' is session 44's _ask_chance44)
_OBJECTION49 = re.compile(
    r"(?P<lead>^|,\s*)(?:(?:is there|would there be|have you got|got) )?any objection to "
    r"(?=(?:giving|handing|passing|bringing|taking|putting|setting|getting) )",
    _F,
)


def _objection49(text: str, lexicon: Lexicon) -> str:
    """Session 49: 'any objection to V-ing' read as 'would you mind V-ing'."""
    low = text.lower()
    if "any objection to " not in low:
        return text
    m = _OBJECTION49.search(text)
    if m is None:
        return text
    ask = "would you mind " if m["lead"] else "Would you mind "
    out = f"{text[: m.start()]}{m['lead']}{ask}{text[m.end() :]}"
    return _read_for(out, text, None, lexicon)


# -- 'just one thing' opening the request ("Sorry, sorry, just one thing: Lena needs the tongs,
# …", "One more thing, could Bob have the apple?"): a call for attention, taken off
_ONE_THING49 = re.compile(
    r"(?P<lead>^|,\s*)(?:just |and )?one (?:more |last |small |quick |little |other )?thing"
    r"\s*(?::|,|—|-)\s*",
    _F,
)


def _one_thing49(text: str, lexicon: Lexicon) -> str:
    """Session 49: 'just one thing:' opening the request taken off."""
    if "thing" not in text.lower():
        return text
    m = _ONE_THING49.search(text)
    if m is None or (m["lead"] and not _opened49(text[: m.start()], lexicon)):
        return text
    out = f"{text[: m.start()]}{', ' if m['lead'] else ''}{text[m.end() :]}"
    return _read_for(_capital49(out), text, None, lexicon)


def _opened49(before: str, lexicon: Lexicon) -> bool:
    """Whether ``before`` (what opens the text before a comma) names nothing of the scene and
    asks nothing: an opener ('Sorry, sorry', 'Right')."""
    return len(before.split()) <= 4 and not _names(before, lexicon)


# -- thanks from someone opening the request ("With many thanks from the teacher, the globe over
# to Zoe, please."): who sends thanks says nothing of the request; read as 'With thanks,'
_THANKS_FROM49 = re.compile(
    r"^With (?:(?:many|grateful|warm|kind|warmest|kindest|best) )?thanks from (?:the [a-z]+|"
    r"[A-Z]\w*(?: [A-Z]\w*)?)\s*,\s*"
)


def _thanks_from49(text: str, lexicon: Lexicon) -> str:
    """Session 49: 'With thanks from X,' opening the request read as 'With thanks,'."""
    if not text.startswith("With "):
        return text
    m = _THANKS_FROM49.match(text)
    if m is None:
        return text
    return _read_for(f"With thanks, {text[m.end() :]}", text, None, lexicon)


# -- 'could (really) use / do with' and 'after his shift' ("Person B could really use the chips
# after his shift as a kilnman."): a want, read as 'wants' (the grammar reads 'wants … after his
# shift'; with 'could use' it took 'shift' for the verb; other 'after …' are older rules')
_COULD_USE49 = re.compile(
    r"\b(?:could|can) (?:really |honestly |seriously |certainly |definitely )?(?:use|do with) "
    r"(?=(?:the|a|an|some|her|his|their) [^,;.!?]*? after (?:his|her|their) (?:shift|stint|turn|"
    r"set|move)(?: as an? [a-z]+)?\s*(?:[.!?]|$))"
)


def _could_use49(text: str, lexicon: Lexicon) -> str:
    """Session 49: 'could use the X after …' read as 'wants the X after …'."""
    if " after " not in text or ("use " not in text and "do with " not in text):
        return text
    m = _COULD_USE49.search(text)
    if m is None or " after " not in text[m.end() :]:
        return text
    return _read_for(f"{text[: m.start()]}wants {text[m.end() :]}", text, None, lexicon)


# -- 'I'd be (ever so) grateful if P got the X' ("If it's no trouble at all, I'd be ever so
# grateful if Person A got the bottle."): read as 'I'd be grateful if you gave P the X'
_GRATEFUL49 = re.compile(
    r"\bgrateful if (?P<p>[A-Z]\w*(?: [A-Z]\w*)?) (?:got|were given|was given|were to get) "
    r"(?=(?:the|a|an|some|her|his|their) )"
)
_SO_GRATEFUL49 = re.compile(
    r"\b(?:ever so|so|very|really|most|awfully|terribly|eternally|truly|hugely) grateful\b"
)


def _grateful49(text: str, lexicon: Lexicon) -> str:
    """Session 49: 'grateful if P got the X' read as 'grateful if you gave P the X'."""
    if "grateful" not in text:
        return text
    out = _SO_GRATEFUL49.sub("grateful", text)
    m = _GRATEFUL49.search(out)
    if m is None or not _only_person(m["p"], lexicon):
        return text  # ('ever so grateful' alone, 'if P could have' are older rules')
    out = f"{out[: m.start()]}grateful if you gave {m['p']} {out[m.end() :]}"
    return _read_for(out, text, None, lexicon)


# -- 'to pass the time' after a want ("Mrs Khan is keen to have the magazine to pass the time."):
# why the person wants it ('pass' is no handing here), taken off
_PASS_TIME49 = re.compile(
    r",? (?:just )?to (?:help )?(?:pass|while away|kill|fill) (?:the )?(?:time|hours|afternoon|"
    r"morning|evening|day|wait)(?=\s*(?:[.!?,;]|$))"
)


def _pass_time49(text: str, lexicon: Lexicon) -> str:
    """Session 49: 'to pass the time' taken off a request."""
    if not any(w in text for w in ("pass the", "while away", "kill ", "fill the")):
        return text
    m = _PASS_TIME49.search(text)
    if m is None:
        return text
    return _read_for(f"{text[: m.start()]}{text[m.end() :]}", text, None, lexicon)


# -- 'for the last / rest of the Ns' after a want ("Mia requires the packing tape for the last of
# the parcels."): read as 'for the Ns' when the Ns are nothing of the scene
_LAST_OF49 = re.compile(
    r"\bfor the (?:last|rest|remainder|final few|last few|other half) of the (?P<n>[a-z]+s)\b"
)


def _last_of49(text: str, lexicon: Lexicon) -> str:
    """Session 49: 'for the last of the Ns' read as 'for the Ns'."""
    if not any(f"{w} of the " in text for w in ("last", "rest", "remainder", "few", "half")):
        return text
    m = _LAST_OF49.search(text)
    if m is None or _names(m["n"], lexicon):
        return text
    return _read_for(f"{text[: m.start()]}for the {m['n']}{text[m.end() :]}", text, None, lexicon)


# -- 'now she's up from her nap' ("Is it all right for Lily to have her sippy cup now she's up
# from her nap?"): read as 'back from' (session 48 reads 'now she's back from …')
_UP_FROM49 = re.compile(
    r"\bnow (?P<s>she|he|they)(?P<v>'s| is|'re| are) up from (?=(?:her|his|their|the) )"
)


def _up_from49(text: str, lexicon: Lexicon) -> str:
    """Session 49: 'now she's up from' read as 'now she's back from'."""
    if " up from " not in text:
        return text
    out = _UP_FROM49.sub(lambda m: f"now {m['s']}{m['v']} back from ", text, count=1)
    return text if out == text else _read_for(out, text, None, lexicon)


# -- 'she's had nothing since …' saying why ("Alice is after the crisps, she's had nothing since
# the cluedo tournament."): read as 'she hasn't eaten since …' (an older reason rule reads that)
_HAD_NOTHING49 = re.compile(
    r",\s*(?P<s>she|he|they)(?:'s|'ve| has| have) had nothing(?: to eat)?(?= since | all )"
)


def _had_nothing49(text: str, lexicon: Lexicon) -> str:
    """Session 49: 'she's had nothing since' read as 'she hasn't eaten since'."""
    if "had nothing" not in text:
        return text
    m = _HAD_NOTHING49.search(text)
    if m is None:
        return text
    neg = "haven't" if m["s"] == "they" else "hasn't"
    out = f"{text[: m.start()]}, {m['s']} {neg} eaten{text[m.end() :]}"
    return _read_for(out, text, None, lexicon)


# -- 'the X is his / hers' closing after a semicolon ("Person B hasn't eaten since breakfast; the
# chips are his."): read as 'the X is for him / her' (after a comma it is session 44's)
_THEIRS49 = re.compile(
    r"(?P<sep>;\s*)the (?P<x>[a-z]+(?: [a-z]+)?) (?P<v>is|are) (?P<p>his|hers)(?=\s*[.!]?$)"
)


def _theirs49(text: str, lexicon: Lexicon) -> str:
    """Session 49: a closing 'the X are his' read as 'the X are for him'."""
    if not text.rstrip(" .!").endswith((" his", " hers")):
        return text
    m = _THEIRS49.search(text)
    if m is None or not _names(m["x"], lexicon):
        return text
    who = "him" if m["p"] == "his" else "her"
    out = f"{text[: m.start()]}{m['sep']}the {m['x']} {m['v']} for {who}{text[m.end() :]}"
    return _read_for(out, text, None, lexicon)


# -- a count of minutes in a 'while' aside ("… to Person A while she's having five minutes off
# from the devil sticks?"): the count is no count of the scene's things; read as 'a few'
_MINUTES49 = re.compile(
    r"\bwhile (?P<s>(?:she|he|they)(?:'s| is|'re| are) (?:having|taking|on)) (?:two|three|four|"
    r"five|ten|fifteen|twenty|thirty|a couple of|\d+) (?=minutes?\b)"
)


def _minutes49(text: str, lexicon: Lexicon) -> str:
    """Session 49: 'while she's having five minutes off' read with 'a few minutes'."""
    if "minute" not in text or "while " not in text:
        return text
    out = _MINUTES49.sub(lambda m: f"while {m['s']} a few ", text, count=1)
    return text if out == text else _read_for(out, text, None, lexicon)


# -- a second want joined by ', while' ("Person A's got her eye on the apple, while Person B is
# after the cup, …"): read as 'and'
_WHILE_WANT49 = re.compile(
    r",\s*while (?P<p>[A-Z]\w*(?: [A-Z]\w*)?)(?P<v> is after| wants| would like| fancies| needs|"
    r"'s after| is keen on| has (?:his|her|their) eye on) "
)


def _while_want49(text: str, lexicon: Lexicon) -> str:
    """Session 49: ', while P is after the X' read as ' and P is after the X'."""
    if "while " not in text:
        return text
    m = _WHILE_WANT49.search(text)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    out = f"{text[: m.start()]} and {m['p']}{m['v']} {text[m.end() :]}"
    return _read_for(out, text, None, lexicon)


# -- a participle saying why, closing ("…, having lost at kerplunk."): taken off when the request
# before it names who gets what
_HAVING49 = re.compile(
    r",\s*having (?:lost|won|played|finished|been|had|done|spent|come|got) [^,;.!?]*(?=[.!?]?$)"
)


def _having49(text: str, lexicon: Lexicon) -> str:
    """Session 49: a closing 'having lost at …' taken off."""
    if "having " not in text:
        return text
    m = _HAVING49.search(text)
    if m is None or _names(m.group(0), lexicon):
        return text
    return _read_for(f"{text[: m.start()]}{text[m.end() :]}", text, None, lexicon)


# -- 'Midway / halfway through X,' opening the request ("Midway through pass the parcel, Person B
# put in a request for the bottle; …"): when it was asked, taken off
_MIDWAY49 = re.compile(r"^(?:Midway|Halfway|Partway|Part way|Half way) through [^,;]+,\s*")


def _midway49(text: str, lexicon: Lexicon) -> str:
    """Session 49: 'Midway through X,' opening the request taken off."""
    if not text.startswith(("Midway ", "Halfway ", "Partway ", "Part way ", "Half way ")):
        return text
    m = _MIDWAY49.match(text)
    if m is None or _names(m.group(0), lexicon):
        return text
    return _read_for(_capital49(text[m.end() :]), text, None, lexicon)


# -- what has left someone wanting ("An hour on the bongos has left Person A gasping for the
# bottle."): read as 'P is gasping for the X'
_LEFT49 = re.compile(
    r"^(?P<c>[A-Z][^,;.!?]*?) (?:has|have|had) left (?P<p>[A-Z]\w*(?: [A-Z]\w*)?) (?P<a>gasping|"
    r"desperate|dying|parched|longing|crying out|starving|aching|itching|thirsting) for "
)


def _left49(text: str, lexicon: Lexicon) -> str:
    """Session 49: 'X has left P gasping for the Y' read as 'P is gasping for the Y'."""
    if " left " not in text:
        return text
    m = _LEFT49.match(text)
    if m is None or _names(m["c"], lexicon) or not _only_person(m["p"], lexicon):
        return text
    return _read_for(f"{m['p']} is {m['a']} for {text[m.end() :]}", text, None, lexicon)


# -- a missed meal before the want ("Emma skipped lunch for the stonecarver's talk and would
# appreciate the banana."): why, taken off
_SKIPPED49 = re.compile(
    r"^(?P<p>[A-Z]\w*(?: [A-Z]\w*)?) (?:skipped|missed|went without|gave up) (?:her |his |their )?"
    r"(?:lunch|breakfast|dinner|tea|supper|elevenses)(?: for [^,;]+?)? and (?=(?:would|wants|"
    r"needs|could|'d|fancies|is after)\b)"
)


def _skipped49(text: str, lexicon: Lexicon) -> str:
    """Session 49: 'P skipped lunch … and would like the X' read as 'P would like the X'."""
    if not any(w in text for w in (" skipped ", " missed ", " went without ", " gave up ")):
        return text
    m = _SKIPPED49.match(text)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    return _read_for(f"{m['p']} {text[m.end() :]}", text, None, lexicon)


# -- 'the X is what P would like' ("…, and the bottle is what Person B would like."): read as
# 'P would like the X' ('is what P wants / is after / asked for' are older rules')
_WHAT_WANTS49 = re.compile(
    r"(?P<lead>^|,\s*(?:and |while |but )?|;\s*)(?P<x>[Tt]he [a-z]+(?: [a-z]+)?) (?:is|'s|are) "
    r"what "
    r"(?P<p>[A-Z]\w*(?: [A-Z]\w*)?) (?P<v>would like|'d like|would love|'d love|fancies)"
    r"(?=\s*(?:[.!?,;]|$))"
)


def _what_wants49(text: str, lexicon: Lexicon) -> str:
    """Session 49: 'the X is what P would like' read as 'P would like the X'."""
    if " what " not in text:
        return text
    m = _WHAT_WANTS49.search(text)
    if m is None or not _only_person(m["p"], lexicon):
        return text
    x = m["x"][0].lower() + m["x"][1:] if m["lead"] else m["x"]
    said = f"{m['p']} {m['v']} {x}"
    out = f"{text[: m.start()]}{m['lead']}{said}{text[m.end() :]}"
    return _read_for(out, text, None, lexicon)


# -- a pastime after 'after' in a want said as a state now ("Person A is craving the chips after
# leapfrog with the kids, …", "After three rounds of twister Person B is in real need of the
# bottle."): why the person wants it now, not when to do it; taken off when it names nothing of
# the scene ('Bob wants the apple after lunch' may say when: refused as before); a bare pastime
# ('after leapfrog', not 'after the long hike') and an opener with no comma (with one, or with a
# determiner, older rules read it)
_STATE49 = (
    r"(?:'s|is)(?: been)? (?:craving|gasping for|desperate for|dying for|longing for|crying out "
    r"for|in (?:real |dire |desperate |urgent )?need of)"
)
_AFTER_PASTIME49 = re.compile(
    rf"(?P<want>\b{_STATE49}(?: the| a| an| some| her| his| their) [a-z]+(?: [a-z]+)?)"
    r" after (?P<c>(?!(?:the|a|an|his|her|their|my|our|all|that|this|some|one|two|three)\b)"
    r"[a-z][^,;.!?]*?)(?=\s*(?:[,;.!?]|$))"
)
_AFTER_OPENER49 = re.compile(
    r"^After (?P<c>(?:a|an|one|two|three|four|five|six|several|a few|a couple of|all that|hours "
    r"of|all those) [^,;]+?)\s+(?=(?P<p>[A-Z]\w*(?: [A-Z]\w*)?) ?"
    rf"{_STATE49} )"
)


def _after_pastime49(text: str, lexicon: Lexicon) -> str:
    """Session 49: 'after leapfrog' in a want, or opening it, taken off."""
    if "fter " not in text or not any(
        w in text
        for w in ("need of", "craving", "gasping", "desperate", "dying", "longing", "crying")
    ):
        return text
    m = _AFTER_OPENER49.match(text)
    if m is not None:
        if _names(m["c"], lexicon) or not _only_person(m["p"], lexicon):
            return text
        return _read_for(text[m.end() :], text, None, lexicon)
    m = _AFTER_PASTIME49.search(text)
    if m is None or _names(m["c"], lexicon):
        return text
    return _read_for(f"{text[: m.end('want')]}{text[m.end() :]}", text, None, lexicon)


# -- 'P's been hinting about the X' ("Bob's been hinting about the crisps all morning, any chance
# he could have them?"): a want, read as 'P's been angling for the X' (an older rule reads that);
# 'any chance he could have them' asked as 'could he have them'
_HINTING49 = re.compile(
    r"\b(?P<p>[A-Z]\w*(?: [A-Z]\w*)?)(?P<b>'s been| has been| was) (?:hinting (?:about|at)|"
    r"dropping hints about|going on about|banging on about) "
    r"(?=(?:the|a|an|some|her|his|their) )"
)
_ANY_CHANCE49 = re.compile(
    r",\s*any chance (?P<p>he|she|they|[A-Z]\w*(?: [A-Z]\w*)?) (?P<v>could|can|might) "
    r"(?=(?:have|get|borrow) )"
)


def _hinting49(text: str, lexicon: Lexicon) -> str:
    """Session 49: 'hinting about the X' read as 'angling for the X'; ', any chance he could
    have them' as ', could he have them'."""
    if not any(w in text for w in ("hinting ", "hints about", "going on about", "banging on")):
        return text
    out = text
    m = _HINTING49.search(out)
    if m is not None and _only_person(m["p"], lexicon):
        out = f"{out[: m.start()]}{m['p']}{m['b']} angling for {out[m.end() :]}"
    c = _ANY_CHANCE49.search(out)
    if c is not None and out != text:
        out = f"{out[: c.start()]}, {c['v']} {c['p']} {out[c.end() :]}"
    return text if out == text else _read_for(out, text, None, lexicon)


# -- a request reported with 'asks whether' ("Priya asks, very politely, whether the stapler could
# find its way into the box."): asked as the question ('Could the stapler find its way into the
# box?'); only a thing as its subject (who asks is no one the question hands anything to)
_ASKS_WHETHER49 = re.compile(
    r"^(?P<p>[A-Z]\w*(?: [A-Z]\w*)?) (?:asks|asked|is asking|wonders|wondered)(?:,\s*(?:very "
    r"|ever so |quite |most )?(?:politely|nicely|kindly|sweetly|meekly|quietly|shyly),)?\s+"
    r"(?:whether|if) "
    r"(?P<x>the [a-z]+(?: [a-z]+)?) (?P<v>could|might|can|would) (?P<rest>[^.?!]+)[.?!]?$"
)


def _asks_whether49(text: str, lexicon: Lexicon) -> str:
    """Session 49: 'P asks whether the X could go …' read as 'Could the X go …?'."""
    if " ask" not in text and " wonder" not in text:
        return text
    m = _ASKS_WHETHER49.match(text)
    if m is None or not _only_person(m["p"], lexicon) or not _names(m["x"], lexicon):
        return text
    if any(i.kind != "ent" for i in _names(m["x"], lexicon)):
        return text
    out = f"{m['v'].capitalize()} {m['x']} {m['rest']}?"
    return _placing48(out, text, lexicon)


# -- 'has had her heart set on' ("…, Person A has had her heart set on the bottle."): read as
# 'has her heart set on'; a 'Since she came in …,' before it (when, not what) taken off with it
_HEART49 = re.compile(r"(?:'s| has) had (?P<w>her|his|their) heart set on ")
_SINCE49 = re.compile(r"^Since (?P<c>(?:she|he|they) [^,;]+),\s*")


def _heart_set49(text: str, lexicon: Lexicon) -> str:
    """Session 49: 'has had her heart set on' read as 'has her heart set on'."""
    if "heart set on" not in text:
        return text
    out = _HEART49.sub(lambda m: f" has {m['w']} heart set on ", text, count=1)
    if out == text:
        return text
    m = _SINCE49.match(out)
    if m is not None and not _names(m["c"], lexicon):
        return _read_for_said(_capital49(out[m.end() :]), text, m["c"], lexicon)
    return _read_for(out, text, None, lexicon)


# -- 'asking after it' ("That bottle over there, Person A's been asking after it since fly tying
# finished."): read as 'asking for it'; 'over there' after the thing said first taken off
_ASKING_AFTER49 = re.compile(r"\basking after (?=(?:it|them)\b)")
_OVER_THERE49 = re.compile(
    r"^(?P<x>(?:That|This|The|Those|These) [a-z]+(?: [a-z]+)?) over (?:there|here),"
)


def _asking_after49(text: str, lexicon: Lexicon) -> str:
    """Session 49: 'asking after it' read as 'asking for it'."""
    if "asking after " not in text:
        return text
    out = _ASKING_AFTER49.sub("asking for ", text, count=1)
    out = _OVER_THERE49.sub(lambda m: f"{m['x']},", out, count=1)
    return text if out == text else _read_for(out, text, None, lexicon)


# -- the thing an 'it' of the request is, named after it with 'I mean' ("Hand it over to Person A,
# the bottle, I mean."): says what 'it' is (as session 42's "…; Person A, I mean" says who a
# pronoun is), no correction cut off (offline._cut_off asks `thing_named49`); older rules then
# read it as "Hand it over to Person A, the bottle."
_IT_I_MEAN49 = re.compile(
    r"^(?P<head>[^,;]+?)\s*,\s*(?P<x>the [a-z]+(?: [a-z]+)?),? I mean(?P<end>\s*[.!]?)$", _F
)


def thing_named49(text: str) -> bool:
    """Session 49: whether ``text`` ends "…, the X, I mean" after a request with one 'it' or
    'them' and no other 'the' (what older rules read once it is not refused as cut off)."""
    m = _IT_I_MEAN49.match(text.strip())
    if m is None:
        return False
    head = m["head"].lower()
    return len(re.findall(r"\b(?:it|them)\b", head)) == 1 and " the " not in f" {head} "


# the normaliser's first rewrites (wired into normalise._STEPS19, before the session-48 ones)
_STEPS49_FIRST: tuple[Callable[[str, Lexicon], str], ...] = (
    _poor49,
    _seeing49,
    _sort_out49,
    _in_way49,
    _for_that49,
    _objection49,
    _one_thing49,
    _thanks_from49,
    _could_use49,
    _grateful49,
    _pass_time49,
    _last_of49,
    _up_from49,
    _had_nothing49,
    _theirs49,
    _minutes49,
    _while_want49,
    _having49,
    _midway49,
    _left49,
    _skipped49,
    _what_wants49,
    _after_pastime49,
    _hinting49,
    _asks_whether49,
    _heart_set49,
    _asking_after49,
)
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-48 ones)
_STEPS49: tuple[Callable[[str, Lexicon], str], ...] = ()
# refusals asked of the text before it is read (offline._parse, after the session-48 ones)
REFUSE49: tuple[Callable[[str, Lexicon], None], ...] = ()
# checks of the whole instruction's reading (offline.parse_instruction, after the session-48 ones)
CHECK49: tuple[Callable[[str, Node, Lexicon], None], ...] = ()
