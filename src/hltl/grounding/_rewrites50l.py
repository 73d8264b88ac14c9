"""The grounder's rules of session 50, the lead (docs/grounding.md): blind48's wrong reading."""

from __future__ import annotations

from collections.abc import Callable

from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _ids, _reading
from hltl.grounding._rewrites49l import choice_forgotten49l, forgot49l
from hltl.grounding.lexicon import TITLE_SEX, Lexicon, _kin_sex35s
from hltl.grounding.tree import Group, Node

# -- the speaker has forgotten which: said by what it means, not by a list of wordings --------
#
# blind48: "Mrs Khan wanted one of the blankets, blue or grey, and I've gone blank on which."
# read `blanket_blue>C | blanket_grey>C`: session 49's list of forgetting remarks (`_FORGOT49L`)
# lacked "I've gone blank", as session 48's list had lacked "it's gone clean out of my head".
# Each session found a new wording, so the remark is recognised here by its parts: the speaker
# (I, my mind / memory / head, or no subject at all after a break: "Can't remember which."), an
# adverb or none ("clean", "completely", "gone and", "for the life of me"), and a predicate of
# one of five meanings — forgetting (forget, forgot, forgotten: not "forgot to …"), going blank
# (gone / went / drawn a blank, blanking), losing track (lost track, lost the thread), memory
# denied (can't / don't / didn't / never + remember, recall, recollect, know, catch, hear, say,
# write it down, note), and doubt (not sure, no idea, not a clue, dunno, haven't the foggiest);
# or the thing gone from the speaker ("it's gone from me", "it's slipped my mind", "it escapes
# me"). A reading with a choice in it is refused, naming the options (session 49's
# `choice_forgotten49l`). And since 'I' names no person of the scene, a text with the remark in it
# was often refused for 'I' without its options ("…, and I've gone and forgotten which, sorry."):
# the remark's clause is taken off and the rest read; when that reads as a choice, it is refused
# naming the options (`forgot_which50l`, asked of the text before it is read, after the older
# refusals).
_ADV50L = (
    r"(?:(?:clean|completely|totally|quite|just|simply|honestly|really|clear|entirely|right|"
    r"gone and|went and|have|'ve|for the life of me|now|already|stupidly|somehow)\s+)*"
)
_CLOSE50L = (
    r"(?=\s*(?:[,.;:!?]|$|\b(?:which|whether|what|who|on which|about which|exactly|sorry|now|"
    r"offhand|again|though|i'm afraid|to be honest|mind)\b))"
)
_DENIED50L = (
    r"(?:can't|cannot|can not|couldn't|could not|don't|do not|didn't|did not|never|can no longer|"
    r"no longer|honestly can't|just can't)\s+" + _ADV50L + r"(?:quite\s+)?"
    r"(?:remember|recall|recollect|know|catch|hear|say|think which|tell which|tell you which|"
    r"write(?: it)? down|wrote(?: it)? down|note(?: it)? down|take(?: it)? in)"
)
_PREDICATE50L = (
    r"(?:"
    rf"forg(?:e|o)t(?:ten)?(?!\s+to\b){_CLOSE50L}"
    r"|(?:gone|went|go|going|drawn|drew|draw)\s+(?:a\s+|completely\s+|totally\s+)?blank"
    r"|blank(?:ed|ing)"
    r"|lost (?:track|the thread|the plot)"
    rf"|{_DENIED50L}"
    rf"|(?:(?:'m|am)\s+)?(?:not (?:sure|certain)|unsure|clueless|stumped){_CLOSE50L}"
    r"|(?:have|'ve got|'ve|have got)\s+no (?:idea|clue)"
    r"|(?:haven't|have not)\s+(?:got\s+)?(?:a|the (?:faintest|foggiest|slightest))(?: idea| clue)?"
    r")"
)
_MIND50L = r"(?:mind|memory|head|brain|noggin)"
_FORGOT50L = re.compiled(
    r"(?:"
    # the speaker: I / I've / I'm / I'd + adverbs + the predicate
    rf"\bI(?:'ve|'m|'d|'ll| have| am| had| was| just)?\s+{_ADV50L}{_PREDICATE50L}"
    # no subject, after a break: "Can't remember which." / "Forgotten which, sorry."
    rf"|(?:^|(?<=[,.;:!?]\s)|(?<=[,.;:!?])|\b(?:and|but|though)\s+){_ADV50L}(?:{_DENIED50L}|"
    rf"forg(?:o|e)t(?:ten)?(?!\s+to\b){_CLOSE50L}|(?:gone|went|drawn|drew) (?:a )?blank|"
    r"lost track|no idea|not a clue|no clue|not sure|dunno|search me|beats me)"
    # the speaker's mind: "my mind's gone blank", "my memory is shot", "my head's like a sieve"
    rf"|\bmy {_MIND50L}(?:'s| is| has| went| just went| was)?\s+(?:gone\s+|just\s+|completely\s+)?"
    r"(?:a\s+)?(?:blank|gone|shot|empty|fuzzy|foggy|mush|a blur|a sieve|like a sieve|failing)"
    # the thing gone from the speaker: "it's gone from me", "it's slipped my mind"
    rf"|\bit(?:'s|s| has| is| just)?\s+{_ADV50L}(?:gone|went|slipped|escaped|escapes|vanished|"
    rf"fled|left)\s+(?:clean\s+|right\s+|completely\s+)?(?:from me|me|out of my {_MIND50L}|from "
    rf"my {_MIND50L}|my {_MIND50L}|out my {_MIND50L})"
    r"|\bdunno\b|\bsearch me\b|\bbeats me\b"
    r")",
    _F,
)
_FORGOT_WORDS50L = (
    "forg",
    "blank",
    "lost",
    "remember",
    "recall",
    "recollect",
    "know",
    "catch",
    "hear",
    "say",
    "think",
    "tell",
    "write",
    "wrote",
    "note",
    "take",
    "sure",
    "certain",
    "clue",
    "idea",
    "foggiest",
    "faintest",
    "slightest",
    "stumped",
    "my ",
    "gone",
    "went",
    "slipped",
    "escape",
    "vanished",
    "fled",
    "left",
    "dunno",
    "search me",
    "beats me",
)


def forgets50l(text: str) -> re.Match[str] | None:
    """The speaker's remark that they have forgotten (or never knew) something, or None."""
    low = text.lower()
    if not any(w in low for w in _FORGOT_WORDS50L):
        return None
    return _FORGOT50L.search(text)


def _has_choice50l(node: Node) -> bool:
    """Session 52 (12b): whether the reading holds an 'or' group, the only thing
    `choice_forgotten49l` refuses (walked as it walks it)."""
    groups = [node]
    while groups:
        g = groups.pop()
        if isinstance(g, Group):
            if g.op == "or":
                return True
            groups.extend(g.children)
    return False


def _forgot_choice50l(text: str, node: Node, lexicon: Lexicon) -> None:
    """Session 50 (lead): session 49's check with the remark recognised by its meaning
    (`forgets50l`): a reading with a choice, of a text in which the speaker says they have
    forgotten, is refused naming the options; and so is one beside any remark of the speaker's
    about what they know or heard (`unknowing50l`: "I'm hazy on which", "I wasn't paying
    attention", "it's on the tip of my tongue"). Session 49's listed wordings (`forgot49l`, not
    all of which `forgets50l` reads: "it's completely gone", "I'd have to ask him") are asked
    here too, so the reading is walked for a choice once (session 51)."""
    if not _has_choice50l(node):
        return  # session 52 (12b): no choice to refuse; the remarks need not be looked for
    if forgets50l(text) is not None or forgot49l(text):
        choice_forgotten49l(node, lexicon)
    said = unknowing50l(text, lexicon)
    if said is not None:
        choice_forgotten49l(
            node, lexicon, f"{said!r} could say the speaker does not know which was asked for"
        )


# 12c's probes (session 50) found thirty more ways to say it ("I'm drawing a blank", "I'm a bit
# foggy on which", "my brain's fried", "your guess is as good as mine", "I'd have to check", "it
# didn't stick"): no list of wordings closes. So beside a choice, any clause of the speaker's that
# names nothing of the scene and speaks of knowing, memory, hearing or attention (a word of that
# class) is taken as a doubt about which was asked for, unless it leaves the choice free ("I don't
# mind which", "either will do", "you choose").
_CLAUSES50L = re.compiled(r"[,;:.!?()]+|\s[-–—]\s|\s(?:and|but|though|so)\s", _F)
_SPEAKER50L = re.compiled(
    r"^(?:(?:oh|ah|um|er|erm|hmm|sorry|honestly|to be honest|mind you|well|and|but|so|though|"
    r"if i'm honest|truth be told)\s+)*"
    r"(?:i\b|i'm|i've|i'd|i'll|me\b|my\b|mine\b|it's on|it'll|it didn't|it hasn't|it won't|"
    r"it's all|it was all|it's a|it's just a|"
    r"it's gone|it slipped|it escapes|it's slipped|who knows|your guess|which one|which it was|"
    r"can't|couldn't|cannot|don't|didn't|dunno|not\b|no idea|no clue|brain|memory|mind's|head's|"
    r"haven't|never)",
    _F,
)
_KNOWING50L = re.compiled(
    # (forgetting to do something, or one's own things, is no doubt about which)
    r"\b(?:forg[eo]t\w*(?!\s+(?:to|my|his|her|our|their|your)\b)|remember\w*|recall\w*|recollect\w*|know|knew|knows|known|sure|certain|"
    r"idea|clue|blank\w*|memory|mind|head|brain|tongue|hazy|foggy|fuzzy|vague|muddled|confused|"
    r"mixed|listening|listen|attention|heard|hear|misheard|caught|catch|note|notes|noted|wrote|"
    r"written|write|check|guess|stick|stuck|escapes?|slipped|come back|ago|hundred|percent|"
    r"per cent|lost|went in|go in|asleep|half|think|tell|ask|asked|blur|blurry)\b",
    _F,
)
_FREE50L = re.compiled(
    r"\b(?:(?:don't|do not|wouldn't|won't|doesn't|does not|never) (?:mind|care)|"
    r"not (?:fussy|fussed|bothered)(?! about remember)|either|whichever|any (?:one|of them|will)|"
    r"you (?:choose|pick|decide)|your (?:choice|call|pick)|up to you|"
    r"(?:doesn't|does not|won't|wouldn't) matter|no matter|i'm easy|"
    r"(?:both|either) (?:are|is|will be) fine|"
    r"(?:he|she|they|it|anyone|anybody) (?:minds?|cares?|matters?))\b",
    _F,
)


def unknowing50l(text: str, lexicon: Lexicon) -> str | None:
    """Session 50 (lead): the first clause of ``text`` in which the speaker speaks of what they
    know, remember, heard or noted ("I'm hazy on which", "my brain's fried", "I'd have to check"),
    naming nothing of the scene, in a text that does not leave the choice free; else None."""
    if _FREE50L.search(text) is not None:
        return None
    for clause in _CLAUSES50L.split(text):
        said = clause.strip()
        if not said or _SPEAKER50L.match(said) is None:
            continue
        words = {w.lower() for w in _KNOWING50L.findall(said)}
        # "I'm sure", "I know", "I think" said without a negation are confidence, not doubt
        if words <= _SURE50L and _NEGATED50L.search(said) is None:
            continue
        if words and not _ids(said, lexicon):
            return said
    return None


_SURE50L = frozenset({"sure", "certain", "know", "known", "think", "tell"})
_NEGATED50L = re.compiled(
    r"(?:\b(?:not|no|never|nor)|n't)\s+(?:[a-z]+\s+){0,5}(?:sure|certain|know|known|think|tell)\b",
    _F,
)


# the clause a remark stands in: from the break before it to the end of its sentence
_BREAK50L = re.compiled(
    r"(?:[.!?]\s+|[,;:]\s*(?:(?:and|but|so|though)\s+)?|\s+(?:and|but|though)\s+)", _F
)


def forgot_which50l(text: str, lexicon: Lexicon) -> None:
    """Session 50 (lead): a text with the speaker's forgetting remark in it ("Priya asked for a
    pen, the black or the red, and I've gone and forgotten which, sorry."): the remark's clause
    is taken off and the rest read; a reading with a choice in it is refused naming the options
    (else the text is read as it is: "Give Bob the cup, I forget why he wanted it")."""
    m = forgets50l(text)
    if m is None:
        return
    start = 0
    for b in _BREAK50L.finditer(text[: m.start()]):
        start = b.start()
    sentence = re.search(r"[.;!?](?:\s|$)", text[m.end() :])
    end = len(text) if sentence is None else m.end() + sentence.start()
    rest = f"{text[:start].rstrip()}{text[end:]}".strip()
    if not rest or start == 0:
        return
    node = _reading(rest if rest[-1] in ".!?" else f"{rest}.", lexicon)
    if node is not None:
        choice_forgotten49l(node, lexicon)


def named_sex50l(name: str) -> str | None:
    """Session 50 (lead): 'm' / 'f' when a name the scene gives says the sex as a first name
    does: a word of kin ('Grandad', 'big sister') or a title ('Mr Lee'); else None."""
    words = name.split()
    if len(words) > 1 and words[0].lower().rstrip(".") in TITLE_SEX:
        return TITLE_SEX[words[0].lower().rstrip(".")]
    return _kin_sex35s(name)


# a he / she who wants something, a him / her who is given it
_WANTING50L = re.compiled(
    # the pronoun, its auxiliaries and adverbs ("she's been", "he keeps", "she's going to")
    r"\b(?P<w>she|he)(?:(?:'s|'d|'ll| is| was| has| had| will| would| can| could| keeps| kept| "
    r"been| just| really| now| still| going to| gonna| got| so| ever so| really| dead| proper)"
    r"(?=[\s,]))*\s+"
    # a want, a need, a state that asks for something, or having it
    r"(?:like|love|wants?|needs?|wanted|needed|asked for|asks for|asking for|after|fancies|"
    r"fancied|fancying|could use|could do with|craving|craves|desperate for|dying for|crying for|"
    r"gagging for|begging for|pining for|longing for|hankering for|on about|going on about|eyeing|"
    r"eyed|got (?:her|his) eye on|has (?:her|his) eye on|(?:her|his) eye on|have it|have them|"
    r"get it|get them|take it|take them)\b"
    # a state said of her / him by the person named ("Grandad says she's thirsty"): not "Could
    # Grandad have the beaker? She's thirsty.", where Grandad is named to get it
    r"|\b(?:says|said|reckons|tells me|told me|mentioned)\s+(?:that\s+)?(?P<s>she|he)"
    r"(?:'s| is| was|'s been| has been)\s+(?:(?:so|really|very|ever so|dead|proper|a bit)\s+)?"
    r"(?:thirsty|hungry|peckish|starving|starved|parched|famished|cold|freezing|chilly)\b"
    # given: "give it to her", "for him"
    r"|\b(?:give|hand|pass|bring|take|send)\s+(?:(?:it|them|this|that|these|those|the [a-z]+|"
    r"both)\s+)?(?:(?:over|across|back|along)\s+)?(?:to\s+)?(?P<o>her|him)\b"
    r"|\bfor (?P<f>her|him)\b",
    _F,
)


def wanting50l(text: str) -> list[str]:
    """Session 50 (lead): each he / she said as wanting ("said she wants the teddy") and each
    him / her said as given ("give it to her", "for him")."""
    low = text.lower()
    if "he" not in low and "him" not in low:
        return []
    return [m["w"] or m["o"] or m["f"] or m["s"] for m in _WANTING50L.finditer(text)]


# refusals asked of the text before it is read (offline._parse, after the session-49 ones)
REFUSE50L: tuple[Callable[[str, Lexicon], None], ...] = (forgot_which50l,)
# checks of the whole instruction's reading (offline.parse_instruction, after the session-49 ones)
CHECK50L: tuple[Callable[[str, Node, Lexicon], None], ...] = (_forgot_choice50l,)
