"""The grounder's rules of session 50, the lead (docs/grounding.md): blind48's wrong reading."""

from __future__ import annotations

from collections.abc import Callable

from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _reading
from hltl.grounding._rewrites49l import choice_forgotten49l
from hltl.grounding.lexicon import TITLE_SEX, Lexicon, _kin_sex35s
from hltl.grounding.tree import Node

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


def _forgot_choice50l(text: str, node: Node, lexicon: Lexicon) -> None:
    """Session 50 (lead): session 49's check with the remark recognised by its meaning
    (`forgets50l`): a reading with a choice, of a text in which the speaker says they have
    forgotten, is refused naming the options."""
    if forgets50l(text) is not None:
        choice_forgotten49l(node, lexicon)


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
    r"\b(?P<w>she|he)(?:'d| would| will|'ll|'s| has| is| was)?(?: just| really| now)? (?:like|love|"
    r"wants?|needs?|wanted|needed|asked for|after|fancies|fancied|could use|could do with|"
    r"wants? it|is after|was after)\b"
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
    return [m["w"] or m["o"] or m["f"] for m in _WANTING50L.finditer(text)]


# refusals asked of the text before it is read (offline._parse, after the session-49 ones)
REFUSE50L: tuple[Callable[[str, Lexicon], None], ...] = (forgot_which50l,)
# checks of the whole instruction's reading (offline.parse_instruction, after the session-49 ones)
CHECK50L: tuple[Callable[[str, Node, Lexicon], None], ...] = (_forgot_choice50l,)
