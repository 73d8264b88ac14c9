"""The normaliser's rules of sessions 10-37, part 1 of 5 (docs/grounding.md: where they live)."""

from __future__ import annotations

import bisect
import functools
from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding.lexicon import (
    PRONOUN_SEX,
    TITLES,
    VERB_CLASS,
    VERBS,
    WORDS,
    Item,
    Lexicon,
    common_words,
    first_names,
    lex,
    person_name,
    title_sex,
)
from hltl.grounding.phrasing import starting_on
from hltl.grounding.repairs import (
    REPAIR_WORDS,
    _first_name,
    _last_name,
)
from hltl.grounding.stepguard import Guard, guards
from hltl.grounding.tree import (
    Group,
    Node,
    tasks,
)
from hltl.world.scene import Scene

_F = re.IGNORECASE
_TASK_WORDS = r"\b(?:needs?|wants?|gets?|give|hand|bring|take|put|place)\b"


def _rewritten(
    name: str, steps: tuple[Callable[[str, Lexicon], str], ...], text: str, lexicon: Lexicon
) -> str:
    """``text`` through ``steps`` in turn, once per instruction: the grounder tries
    ``rewritten19``, ``canonical`` and ``canonical19`` in turn, and the last runs both of the
    others again on the same text (``lexicon.rewrites`` keeps each result, or its refusal,
    until the next instruction)."""
    out = " ".join(text.split())
    key = (name, out)
    known = lexicon.rewrites.get(key)
    if isinstance(known, GroundingError):
        raise GroundingError(str(known))
    if isinstance(known, str):
        return known
    rules = _guards_of(steps)
    index = _index_of(rules)
    try:
        if index is None or not out.isascii():
            out = _run(steps, rules, out, lexicon, 0)
        else:
            out = _run_indexed(steps, rules, index, out, lexicon)
    except GroundingError as refused:
        lexicon.rewrites[key] = refused
        raise
    lexicon.rewrites[key] = out
    return out


def _run(
    steps: tuple[Callable[[str, Lexicon], str], ...],
    rules: tuple[Guard | None, ...],
    out: str,
    lexicon: Lexicon,
    start: int,
) -> str:
    """``out`` through ``steps`` from ``start`` on, each step's guard asked before it is called."""
    low, plain = out.lower(), out.isascii()
    for k in range(start, len(steps)):
        rule = rules[k]
        if rule is not None and (plain or not rule[2]):
            # the step's guard (stepguard.py): it does nothing to a text holding none of
            # its words, so it is not called (a loop: any() over a generator costs more)
            for word in rule[1]:
                if word in low:
                    break
            else:
                for word in rule[0]:
                    if word in out:
                        break
                else:
                    continue
        new = steps[k](out, lexicon)
        if new is not out:
            if new != out:  # (a new string equal to it: what is asked of it is the same)
                low, plain = new.lower(), new.isascii()
            out = new
    return out


# Session 49 (12p): the guards indexed by their words' first three letters (lower-cased; a
# shorter word whole). A guarded step can act on an ASCII text only where one of its words is
# in it, so only where that word's first letters are among the text's (lower-cased) pieces of
# one to three letters; the text's pieces pick out the steps that may act. Only for a long tuple
# of steps (_STEPS19's ~1,300: the loop over every guard was most of a pass's own time) and an
# ASCII text (lower() of other letters may depend on the letters beside them).
# Session 50 (12p): the index holds the words, each once with every step it guards: a piece of
# the text asks each of its words once (a word shared by many steps, 'the ', ' for ', 'needs',
# was asked once for each), and the steps picked are exactly those whose guard holds (a word of
# theirs in the text: the folded ones in its lower case, the others in it as it is), so the
# pass asks no guard again.
_INDEXED_FROM = 300
# Session 51 (12p): each word is indexed by the three letters of it (lower-cased) that the guard
# words hold least often (any three letters of a word in the text are among the text's: the
# rarest of them picks fewest words to ask), words under three letters by themselves; the text's
# pieces of three letters are met with the index's in one set intersection, and the steps
# picked for a text are kept (a pure function of the text: ~1 in 5 texts of a part is met again).
# The index: words by their three letters (each with whether it is asked of the lower-cased
# text and the steps it guards), those letters as a set, the words under three letters, the
# steps without a guard (always picked), and the steps picked by text
_Words = tuple[tuple[str, bool, tuple[int, ...]], ...]
_Index = tuple[
    dict[str, _Words],
    frozenset[str],
    tuple[tuple[str, _Words], ...],
    tuple[int, ...],
    dict[str, list[int]],
]
_INDEXES: dict[int, tuple[tuple[Guard | None, ...], _Index]] = {}
_PICKS_KEPT = 4096


def _index_of(rules: tuple[Guard | None, ...]) -> _Index | None:
    """The steps' guard words by three of their letters, with the steps each guards, and the
    steps without a guard (None for a short tuple)."""
    if len(rules) < _INDEXED_FROM:
        return None
    kept = _INDEXES.get(id(rules))
    if kept is None or kept[0] is not rules:
        words: dict[tuple[str, bool], set[int]] = {}
        always: list[int] = []
        for k, rule in enumerate(rules):
            if rule is None or "" in rule[0] or "" in rule[1]:
                always.append(k)  # ('' is in every text: stepguard never writes one)
                continue
            for word in rule[0]:
                words.setdefault((word, False), set()).add(k)
            for word in rule[1]:
                words.setdefault((word, True), set()).add(k)
        held: dict[str, int] = {}  # how many words hold each three letters
        for word, _ in words:
            low = word.lower()
            for piece in {low[i : i + 3] for i in range(len(low) - 2)}:
                held[piece] = held.get(piece, 0) + 1
        three: dict[str, list[tuple[str, bool, tuple[int, ...]]]] = {}
        short: dict[str, list[tuple[str, bool, tuple[int, ...]]]] = {}
        for (word, folded), ks in sorted(words.items()):
            low = word.lower()
            said = (word, folded, tuple(sorted(ks)))
            if len(low) < 3:
                short.setdefault(low, []).append(said)
                continue
            piece = min((low[i : i + 3] for i in range(len(low) - 2)), key=lambda p: (held[p], p))
            three.setdefault(piece, []).append(said)
        if len(_INDEXES) > 64:
            _INDEXES.clear()
        kept = _INDEXES[id(rules)] = (
            rules,
            (
                {piece: tuple(ws) for piece, ws in three.items()},
                frozenset(three),
                tuple((piece, tuple(ws)) for piece, ws in short.items()),
                tuple(always),
                {},
            ),
        )
    return kept[1]


def _may_act(index: _Index, out: str, low: str, start: int) -> list[int]:
    """The steps from ``start`` on that may act on the ASCII text ``out`` (``low``: its lower
    case), in order: those without a guard, and those whose guard holds (a word of theirs in
    it). A word in the text holds the three letters it is indexed by (lower-cased: ``out`` is
    ASCII) among the text's, so each word that may be in it is asked once."""
    three, pieces, short, always, picks = index
    picked = picks.get(out)
    if picked is None:
        found = set(always)
        for piece, said in short:
            if piece in low:
                for word, folded, ks in said:
                    if word in (low if folded else out):
                        found.update(ks)
        for piece in pieces.intersection({low[i : i + 3] for i in range(len(low) - 2)}):
            for word, folded, ks in three[piece]:
                if word in (low if folded else out):
                    found.update(ks)
        if len(picks) > _PICKS_KEPT:
            picks.clear()
        picked = picks[out] = sorted(found)
    return picked[bisect.bisect_left(picked, start) :]


def _run_indexed(
    steps: tuple[Callable[[str, Lexicon], str], ...],
    rules: tuple[Guard | None, ...],
    index: _Index,
    out: str,
    lexicon: Lexicon,
) -> str:
    """``out`` (ASCII) through the steps that may act on it (_may_act: each one picked is
    called); the steps after one that changes the text picked again."""
    todo = _may_act(index, out, out.lower(), 0)
    n = 0
    while n < len(todo):
        k = todo[n]
        n += 1
        new = steps[k](out, lexicon)
        if new is not out:
            changed = new != out  # (a new string equal to it picks the same steps)
            out = new
            if changed:
                if not out.isascii():
                    return _run(steps, rules, out, lexicon, k + 1)
                todo, n = _may_act(index, out, out.lower(), k + 1), 0
    return out


# each steps tuple's guards (stepguard.py), kept with the tuple (a test may run another one)
_GUARDED: dict[int, tuple[tuple[Callable[[str, Lexicon], str], ...], tuple[Guard | None, ...]]] = {}


def _guards_of(steps: tuple[Callable[[str, Lexicon], str], ...]) -> tuple[Guard | None, ...]:
    """Each of ``steps``' guard (None: the step always runs), read once per tuple."""
    kept = _GUARDED.get(id(steps))
    if kept is None or kept[0] is not steps:
        # why: the list (~40 ms to load) only where a text is rewritten, not where one reads
        from hltl.grounding._step_guards import GUARDS

        if len(_GUARDED) > 64:
            _GUARDED.clear()
        kept = _GUARDED[id(steps)] = (steps, guards(steps, GUARDS))
    return kept[1]


def _names(text: str, lexicon: Lexicon) -> list[Item]:
    """The scene's objects, people and surfaces ``text`` names, in order (also inside words the
    lexer joins to an unknown word: 'the plates out'); kept per text in the lexicon (lexing is a
    function of the text and the lexicon's names, and the items are frozen)."""
    kept = lexicon.named.get(text)
    if kept is None:
        kept = lexicon.named[text] = tuple(_names_now(text, lexicon))
    return list(kept)


def _names_now(text: str, lexicon: Lexicon) -> list[Item]:
    try:
        items = lex(text, lexicon)
    except GroundingError:
        return []
    out: list[Item] = []
    for it in items:
        if it.kind == "ent":
            out.append(it)
        elif it.kind == "unknown" and " " in it.text:
            head, rest = it.text.split(" ", 1)  # "important Mrs Khan", "plates out"
            found = [*_names(head, lexicon), *_names(rest, lexicon)]
            if not found and " " in rest:
                # "Mr Novak about": the name, then a word the lexer joined to it
                head, last = it.text.rsplit(" ", 1)
                found = [*_names(head, lexicon), *_names(last, lexicon)]
            out += found
    return out


def _ids(text: str, lexicon: Lexicon, kind: str | None = None) -> set[str]:
    return {r.id for it in _names(text, lexicon) for r in it.refs if kind in (None, r.kind)}


@functools.lru_cache(maxsize=8192)
def _rx(pattern: str) -> re.Pattern[str]:
    """``pattern`` compiled (case-insensitive) once: re's own cache keeps 512 patterns, fewer than
    the rewrites build over a scene's names, and recompiling them was a third of a rewrite's
    time (the pattern the gate compiled when it gated it, where it did: gate.compiled)."""
    return re.compiled(pattern, _F)


def _sub(pattern: str, repl: str | Callable[[re.Match[str]], str], text: str) -> str:
    if not re.may_match(pattern, _F, text):
        return text  # no match is possible: what sub returns for none
    return _rx(pattern).sub(repl, text)


# -- wrappers ----------------------------------------------------------------------------------

_OPEN = r"(^|(?<=[.;!?:])\s*|(?<=,)\s*(?:and\s+)?)"
_WRAPPERS: tuple[tuple[str, str | Callable[[re.Match[str]], str]], ...] = (
    # session 11: "is to be given", "ought to" (an obligation is a request, as "should")
    (r"\b(?:is|are|was|were|am) to be\b", "should be"),
    (r"\bought to\b", "should"),
    (
        r"\bwould it be (?:at all |even )?(?:possible|ok|okay|alright) for (.+?) to be "
        r"(taken|brought|given|handed|put|placed|moved|delivered|sent|passed)\b",
        r"\1 should be \2",
    ),
    (_OPEN + r"(?:so,?\s+)?is there any (?:chance|way|possibility) (?:that )?", r"\1"),
    (
        _OPEN + r"would it be (?:possible|ok|okay|alright) for (.+?) to (?:borrow|have|get|take) ",
        r"\1\2 could have ",
    ),
    (_OPEN + r"(?:i|we) (?:was|were|am|are) (?:just )?wondering (?:if|whether) ", r"\1"),
    (
        _OPEN + r"(?:i|we) (?:would|'d|should) be (?:most |very |really |so |extremely )?"
        r"(?:grateful|thankful|obliged) if ",
        r"\1",
    ),
    (_OPEN + r"(?:please |kindly )?(?:ensure|make sure|see to it) that ", r"\1"),
    (r",\s*and that ", ", and "),
    (_OPEN + r"(?:please |kindly )?arrange for (.+?) to be ", r"\1\2 is "),
    (r"\bupon\b", "on"),
    (
        r"\b(would|'d|will) be (?:(?:most|very|really|so|extremely|ever|awfully|terribly) )*(?:gra"
        r"teful|thankful) "
        r"for\b",
        r"\1 like",
    ),
    (r"\b(?:could|can|should|might|will) be (?:provided|supplied|furnished) with\b", "could get"),
    (
        r"\b(?:could|can|should|might|will|must) (?:please )?be (?:given|handed|passed|brought|"
        r"sent)\b(?!\s+(?:to|over|across|back|on|onto)\b)",  # "the cup should be handed to Carol"
        "could get",
    ),
    (
        r"^(could|can|would|will|might|must|should) ((?:the )?[\w ]+?) (?:please )?be (?:given|"
        r"handed|passed|brought|sent)\b(?!\s+(?:to|over|across|back|on|onto)\b)",
        r"\1 \2 get",
    ),
    # "after Bob has been given the chips": once Bob has them
    (
        r"\b(?:has|have|had|'s|'ve) been (?:given|handed|passed|brought|sent)\b"
        r"(?!\s+(?:to|over|across|back|on|onto)\b)",
        "has",
    ),
    (r"\b(could|can|may|might) borrow\b", r"\1 have"),
    (
        r"\basked (?:whether|if) (?:she|he|they) (?:could|might|can|may) (?:have|get)\b",
        "wants",
    ),
    (r"\b(could|can|would|will) (?:someone|somebody|anyone|anybody)\b", r"\1 you"),
    (_OPEN + r"(?:i|we)(?:'d| would) (?:love|like|prefer) it if ", r"\1"),
    (_OPEN + r"(?:please )?see (?:to it )?that ", r"\1"),
    # session 27 (12r): "Would it be a problem to let Person A have the cup?"
    (
        _OPEN + r"(?:would|will|is) it be (?:a problem|an issue|a bother|a hassle|any trouble|too "
        r"much (?:trouble|bother|hassle)) (?:for you )?to (?:(let) )?",
        lambda m: f"{m.group(1)}could " if m.group(2) else f"{m.group(1)}could you ",
    ),
)


def _wrappers(text: str, _lexicon: Lexicon) -> str:
    for pattern, repl in _WRAPPERS:
        text = _sub(pattern, repl, text)
    return text


# -- words -------------------------------------------------------------------------------------

_WORDS: tuple[tuple[str, str], ...] = (
    # "Bob has asked for the chips twice now": how often he asked, not how often to hand over
    (
        r"\b(ask(?:ed|ing) for [^.;!?,]*?) (?:twice|three times|several times|a few times|again|"
        r"already|ages ago|a while ago|a bit ago|earlier|this morning|this afternoon|yesterday|"
        r"last night|(?:an|one|two|ten|twenty|half an) (?:minutes?|hours?) ago|just now|all day|"
        r"all morning|all afternoon|all evening|all week|all lesson|all class|all shift|all "
        r"session|all practice|all rehearsal|all meeting|all match)(?: long)?"
        r"(?: now| today| already)?"
        r"(?=\s*(?:[.,;!?]|$))",
        r"\1",
    ),
    (r",?\s*\b(?:sharpish|pronto|asap|chop chop|on the double)\b", ""),
    (
        r"\s*(?:\bis|'s|\bare|'re|\bwas|\bhas been|'s been|\bhave been|'ve been) (?:still )?"
        r"waiting(?: ages| forever| a while| so long)? for\b",
        " wants",
    ),
    (r"\s*(?:\bwas|\bwere|\bis|\bare|'s|\bhas been|'s been) asking for\b", " wants"),
    (r"\s*(?:\bhas|\bhave|\bhad|'s|'ve) asked for\b", " wants"),
    (r"(?<=\w) asked for\b(?= (?:the|a|an|some)\b)", " wants"),
    # "Mr Novak's plate is the blue one": the blue plate is his
    (r"^(.+?)'s (\w+) is the (\w+) one\b", r"the \3 \2 is for \1."),
    # "Give all three of them an item: Alice the cup, …": the list says it
    (
        r"^(give|hand|pass|bring) (?:all (?:two|three|four|five) of them|each of them|them all|"
        r"everyone|everybody|all of them) (?:an? (?:item|thing|object)|something)(?: each)?:\s*",
        r"\1 ",
    ),
    # "Sorry, I mean the lemon. No, actually the salt was right.": the correction taken back
    (
        r"(?:^|(?<=[.!?;])\s*)(?:sorry,? )?i mean(?:t)? [^.!?;]*[.!?;]\s*no,? (?:actually,? )?"
        r"(?:the )?\w+(?: \w+)? (?:was|is) (?:right|correct|fine|ok)[.!?]?",
        "",
    ),
    # "Carol wants the apple; Bob, for the bottle": the want said again without its verb
    (r"([;,]\s*(?:and )?[A-Z][\w ]*?),\s*for (?=the |a |an )", r"\1 "),
    # "give lena the knife no the tongs": a correction said without its commas
    (r"(?<=\w) no,? (?=the |a |an )", ", no, "),
    # "…, chips last": an object named alone before an ordering word
    (r",\s*(?!the |a |an )(\w+) (last|first)\b", r", the \1 \2"),
    # "whichever box is on the pallet": the box that is on it
    (r"\bwhichever (\w+) (?:is|'s) (on|in) ", r"the \1 that is \2 "),
    (
        r"\b(?:that|which)(?:'s| is| are|'re)? (?:sitting|lying|standing|resting|kept) (on|in)\b",
        r"\1",
    ),
    (r"\blast of all\b", "finally"),
    (r"(^|(?<=[.;!?])\s*)(?:to finish|to end with|at the end|to close|to wrap up),", r"\1finally,"),
    (r"\s*(?:\bhas|'s) been after\b", " wants"),
    (r"\s*(?:\bis|\bare|'s|'re) needing\b", " needs"),
    (r"\s*(?:\bis|\bare|'s|'re) wanting\b", " wants"),
    (r"\s*(?:\bis|\bare|'s|'re) (?:supposed|meant|due) to (?:get|have|receive)\b", " should get"),
    # "Person B has to get the bottle": should get it
    (r"\b(?:has|have|had)(?: got)? to (?:get|have|receive)\b", "should get"),
    # "Bob gets whatever Alice doesn't: Alice gets the bottle": Bob gets the rest
    (
        r"^(.+?) (gets|can have|should get|takes) whatever (.+?) (?:doesn't|does not|don't|"
        r"won't|isn't)(?: get| take| have| want)?\s*[:;,-]\s*(.+?)[.!]?$",
        r"\4. \1 \2 the rest",
    ),
    (
        r",?\s*(?:and )?after (?:both|all|those|these|them|both of them|all of them) "
        r"(?:are|have been|were) (?:done|finished|complete|completed),?",
        ", then",
    ),
    # session 11
    (r"(^|(?<=[.;!?])\s*)(?:is there )?any chance (?:of|for) ", r"\1"),
    (r",?\s*\b(?:as soon as (?:possible|you can)|when(?:ever)? possible)\b", ""),
    (r",?\s*\bby the end(?: of (?:the |this |today's |your )?\w+)?\b", ""),
    (r",\s*like,", ","),
    (r",?\s*\bright now\b,?", ""),
    (r",?\s*\bif (?:that's|that is|it's|it is) (?:easier|simpler|better|quicker)\b", ""),
    # "be quick and give Bob the chips": said first, it asks nothing; later, "…, so be nice: give
    # her the cup" keeps the request apart from the remark before it
    (
        r"(^|(?<=[.;!?])\s*)(?:so |and )?be (?:nice|quick|careful|gentle|polite|kind|quiet)\b"
        r"(?:\s*[:,]|\s+and\b)?\s*",
        r"\1",
    ),
    (
        r",?\s*\b(?:so |and )?be (?:nice|quick|careful|gentle|polite|kind|quiet)\b(?:\s*[:,])?",
        ", so",
    ),
    (
        r",\s*(?:very |so |quite |really |rather |most |extremely )?(?:politely|nicely|kindly|"
        r"sweetly)\s*,",
        "",
    ),
    (
        r"\s*(?:\bhas |\bhave |\bhad |'s |'ve )?asked,? (?:whether|if) (?:she|he|they) "
        r"(?:could|might|may|can) (?:have|get)\b",
        " wants",
    ),
)
# "the foreman himself", "Bob herself": a person said with emphasis (after anything else, "Ava
# can get it herself", the person does it themself: see _words)
_REFLEXIVE = r"(?<=\w) (?:himself|herself)\b"
# "Noah is wanting the ruler for his maths": what it is for, taken off unless it is a thing of
# the scene said right after a verb (_wanted_thing; session 55: "Lily's been whining for her
# teddy, and …" lost the teddy, 12b's review); not what a person cries or asks for ("Lily's been
# crying for her teddy": a want)
_FOR_THEIRS = (
    r"(?<!\bits)(?<!it's)(?<!\bis)(?<!\bare)(?<!\bcrying)(?<!\basking)(?<!\basked)(?<!\bcalling)"
    r"(?<!\bbegging)\s+for (?:his|her|their|my|our) (?!(?:own)\b)"
    r"([a-z]+(?: [a-z]+)?)(?=\s*(?:[.,;!?]|$))"
)
_WORDS_LATE: tuple[tuple[str, str], ...] = (
    # "Give Bob the chips and then when he's got them give Alice the cup": the condition ends
    # at the command
    (
        r"\b((?:once|when|after) (?:he|she|they)(?:'s| has| have|'ve)? (?:got|had|taken|"
        r"received|gotten) (?:them|it|those|that))\s+(?=(?:give|hand|pass|bring|put|place)\b)",
        r"\1, ",
    ),
    (r"\b(?:back )?(?:in|into|onto) (?=the )", "on "),
    (r"\bback on (?=the )", "on "),
    (r"\s*(?:\bis|'s|\bare|'re) due (?:his|her|their|the)?\b", " should get the"),
    (
        r"(?<=\w) also (?=(?:wants|needs|would like|'d like|gets|should get|could have|can "
        r"have)\b)",
        " ",
    ),
    # "Leave the mugs alone and give Bob everything else"
    (
        r"^(?:please )?(?:leave|don't touch|do not touch) (the [\w ]+?)(?: alone| where they are| "
        r"be)?,? (?:and|but) (give|hand|bring) ([\w ]+?) everything else\b",
        r"\2 \3 everything except \1",
    ),
    # "Omar said he needs the sponge": the one who said it
    (
        r"^([A-Z][\w ]*?) (?:said|says|mentioned|told me|tells me)(?: that)? (?:he|she|they) "
        r"(?=(?:needs|wants|would like|'d like|could use|'s after)\b)",
        r"\1 ",
    ),
    # "Lily and Ava both want a block, so one each"
    (r"\bboth (want|need|would like)s? (a|an|one) ([\w ]+?),? so one each\b", r"\1 \2 \3 each"),
    # "What I need is for the blue mug to be on the table …"
    # "… all I need is for Marco to get the knife": Marco should get it
    (
        r"^(?:(?:ok|okay|so|well|right|literally|basically|honestly|just),?\s+)*(?:what|all) "
        r"(?:i|we) (?:need|want|would like|'d like) is for ([A-Z][\w ]*?) to (get|have|receive)\b"
        r"(?= (?:the|a|an|both|all|one)\b)",
        r"\1 should \2",
    ),
    (
        r"^(?:(?:ok|okay|so|well|right|literally|basically|honestly|just),?\s+)*(?:what|all) "
        r"(?:i|we) (?:need|want|would like|'d like) is for ",
        "",
    ),
    # "Lena can take whichever she likes, …": may have (not carry it anywhere: no 'to'/'on')
    (
        r"^([A-Z][\w ]*?) (can|may|could) take\b(?=(?:(?!\b(?:to|on|onto|in|into|over)\b)"
        r"[^.;!?])*[.!?]?$)",
        r"\1 \2 have",
    ),
    (r"(?<!needs )(?<!need )(?<!has )(?<!have )\bto be (on|in|onto)\b", "on"),
    (r"\b(?:has to|have to|should|must|needs? to) end up (on|in|onto)\b", "should go on"),
    # session 12
    # "Alice can have whichever she likes, the bottle or the crisps": the choice said after it
    (
        r"\bwhichever ((?:she|he|they|you) (?:likes?|wants?|prefers?|fancies|fancy)),\s+"
        r"((?:the |a |an |either )?[^,.;!?]+?\bor\b[^,.;!?]+)",
        r"\2, whichever \1",
    ),
    # "Every object here is for Person B": 'here' is the scene
    (
        r"\b(everything|(?:all the|every|each) (?:objects?|things?|items?)) (?:here|in here)\b",
        r"\1",
    ),
    # "…, oh hang on, she's got water already, take it to Mr Lee": the reason for a correction,
    # between its marker and the new request, asks nothing
    (
        r"\b((?:hang on|hold on|no wait|wait|actually|sorry|oops)(?:,? (?:no|wait))?),\s+(?:since |"
        r"because |as )?(?:she|he|they)(?:'s| is| has|'ve| have| are|'re| already)\b[^,;.!?]*?,\s*"
        r"(?=(?:take|give|hand|bring|put|place|pass|send)\b)",
        r"\1, ",
    ),
    # "Can Sam borrow the blue pen?": may he have it
    (r"\b(can|could|may|might) (?!(?:you|we|i|u)\b)(\w+(?: \w+)?) borrow\b", r"\1 \2 have"),
    # "Miss, Zoe needs the glue": the one spoken to by a title alone (when no scene name)
    (r"^(?:miss|sir|madam|ma'am|mister|missus)\s*[,:]\s*", ""),
    # "Mind passing Carol the bottle?": would you mind
    (r"(^|(?<=[.;!?])\s*)mind (?=\w+ing\b)", r"\1would you mind "),
    # "Alice would like to have the cup": would like the cup (no place or person after it)
    (
        r"\b(would like|'d like|would love|'d love|wants|want|needs|need) to (?:have|get|receive) "
        r"(?=(?:the|a|an|some|both|one|all|either|any)\b(?:(?!\b(?:to|on|onto|in|into|for)\b)"
        r"[^.;!?])*(?:[.;!?]|$))",
        r"\1 ",
    ),
    # "Noah is wanting the ruler for his maths": what it is for: _FOR_THEIRS, a step after _words'
    # "The magazine, Mrs Khan asked it, please bring to her": 'asked it' is asked for it
    (r"\basked (it|them|that)(?=\s*[,;.])", r"asked for \1"),
    # "the white plate, then the blue one, both to Lena"
    (
        r"^(the [\w ]+?), then (the [\w ]+?),? both (to|on|onto) ([\w ]+?)[.!]?$",
        r"\1 \3 \4, then \2 \3 \4",
    ),
)


def _person_before(m: re.Match[str], lexicon: Lexicon) -> bool:
    """Whether the words right before match ``m`` name a person of the scene ('the foreman',
    'Person A')."""
    tail = " ".join(m.string[: m.start()].split()[-3:])
    said = _names(tail, lexicon)
    return (
        bool(said)
        and all(r.kind == "human" for r in said[-1].refs)
        and tail.lower().endswith(said[-1].text.lower())
    )


def _person_ends_up36s(after: str, lexicon: Lexicon) -> bool:
    """Session 36 (12s): whether what follows 'end up with' names an object first: then the
    person ends up with it ("I'd quite like Person B to end up with the bottle", left to the
    grammar), not the object with a person ('go to' had made 'Person B to go to the bottle')."""
    names = _names(after, lexicon)
    return bool(names) and names[0].refs[0].kind == "object"


# -- people ------------------------------------------------------------------------------------

_TITLES = {"mrs": "f", "ms": "f", "miss": "f", "mr": "m"}


def _one_thing(words: str, lexicon: Lexicon) -> bool:
    """Whether what 'each <role>' gets is one thing said plainly: no list, task or person."""
    return not re.search(_TASK_WORDS + r"|\band\b|,", words, _F) and not _ids(
        words, lexicon, "human"
    )


def _name(pid: str, lexicon: Lexicon) -> str:
    h = next(x for x in lexicon.scene.humans if x.id == pid)
    unique = [a for a in h.aliases if sum(a in g.aliases for g in lexicon.scene.humans) == 1]
    return unique[0] if unique else h.name


# -- remarks -----------------------------------------------------------------------------------

_MAY_HAVE = r"|\b(?:can|could|may|might|should) (?:have|get)\b"
_CLAUSE = re.compile(
    r"\s*(?:[.;!?]+|,\s*so\b:?|\bso\b:|\s-\s|,(?=\s*(?:could|can|would|will)\b)|"
    r",(?=\s*(?:it'?s|its)\b)|\s(?=its\b)|"
    r",(?=\s*(?:he|she|they|it)(?:'s|'re|'ll|'d| is| are| was| were| will)\b))\s*",
    _F,
)
_PRONOUNS = {"he": "h", "him": "h", "she": "h", "her": "h", "his": "p", "it": "o", "them": "os"}


def _object_before_pronoun31l(body: str, lexicon: Lexicon) -> bool:
    """Whether ``body`` names an object before its first 'it' / 'them': the pronoun's antecedent,
    which a remark said later does not replace (``_remarks``; session 31, lead: "Person B asked
    for the apple, so hand it over, and the cup to Person A. It's the bottle that Person B is
    hoping for." had handed the bottle)."""
    m = re.search(r"\b(?:it|them)\b", body, _F)
    return m is not None and any(
        n.refs[0].kind == "object" for n in _names(body[: m.start()], lexicon)
    )


def _pronoun_among(said: list[str], body: str, person: set[str], lexicon: Lexicon) -> None:
    """'Mrs Ortiz was talking to Zoe about the ruler, let her have it': a remark about several
    people that wants nothing, before a request whose one person is a pronoun and which names
    no one: the pronoun could mean any of them (a title may rule some out), so it is refused
    listing them (not read as no one)."""
    pronouns = {w.lower() for w in re.findall(r"\b(?:he|him|she|her)\b", body, _F)}
    if len(pronouns) != 1 or _ids(body, lexicon, "human"):
        return
    if any(re.search(_TASK_WORDS + _MAY_HAVE, c, _F) for c in said):
        return  # a want in the remark may say whose it is
    sex = PRONOUN_SEX.get(next(iter(pronouns)))
    fits = [h.id for h in lexicon.scene.humans if h.id in person]
    fits = [p for p in fits if title_sex(p, lexicon) in (None, sex)]
    if len(fits) < 2:
        return
    names = [person_name(p, lexicon) for p in fits]
    raise GroundingError(
        f"{next(iter(pronouns))!r} is not resolved: it could mean {', '.join(names[:-1])} or "
        f"{names[-1]} (each named before it); name the person"
    )


# a person at work on a surface ("she's packing the last pallet", "Mia's checking the pallets")
_AT_WORK35S = re.compile(
    r"(?:'s|\bis|\bare|'re|\bwas|\bwere)(?: still| just| busy)? (?:packing|loading|unloading|"
    r"checking|stacking|sorting|clearing|wiping|cleaning|tidying|laying|setting) (?:up )?"
    r"(?:the|her|his|their) (?P<s>[a-z]+(?: [a-z]+)?)(?=\s*[,.;!?]|\s*$)",
    _F,
)


def _agrees(remarks: list[str], body: str, lexicon: Lexicon) -> bool:
    """Whether every object a remark with a want names goes, in the request, to a person that
    remark names ('Mr Novak wants his lemon earlier, so …': the lemon is Mr Novak's)."""
    # why: offline.py imports this module, so the grammar is imported where it is used
    from hltl.grounding.offline import parse_instruction

    try:
        node = parse_instruction(body, lexicon.scene, lexicon, normalise=False)
    except GroundingError:
        return False
    given = {t.obj: t.target for t in tasks(node)}
    for remark in remarks:
        people = _ids(remark, lexicon, "human")
        for obj in _ids(remark, lexicon, "object"):
            if given.get(obj) not in people:
                return False
    return True


_NEGATIONS = re.compile(
    r"\b(?:no|not|never|nobody|no one|nothing|none|forget|cancel|instead|swap|skip|drop|"
    r"except|without|but|rather|only|neither|nor)\b|n't\b",
    _F,
)


_COMMON = common_words() | frozenset(WORDS) | frozenset(VERBS)


@functools.lru_cache(maxsize=64)
def _known_words(lexicon: Lexicon) -> frozenset[str]:
    """The words ``_plain_words`` knows in ``lexicon``'s scene: a union with the 20,000 common
    words, built once per lexicon (session 42, 12p: it had been built again at every call, some
    0.4 ms each; a lexicon's names do not change, and lexicons are kept, 64 at most)."""
    scene = lexicon.scene
    names = [
        *(n for o in scene.objects for n in (o.id, o.category, *o.aliases)),
        *(n for h in scene.humans for n in (h.id, h.name, *h.aliases)),
        *(n for s in scene.surfaces for n in (s.id, *s.aliases)),
    ]
    own = {w for n in names for w in re.findall(r"[a-z]+", n.lower())}
    # session 36 (12s): a word of a name said in the plural is that word ("Mia's checking the
    # pallets": the scene's pallet)
    own |= {w + "s" for w in own} | {w + "es" for w in own if w.endswith(("s", "x", "ch", "sh"))}
    return _COMMON | own


def _plain_words(clause: str, lexicon: Lexicon) -> bool:
    """Whether every word of ``clause`` is a common English word, a word the grammar knows or a
    word of a name in the scene."""
    known = _known_words(lexicon)
    words = re.findall(r"[a-z]+", re.sub(r"'(?:s|ll|re|d|ve|m)\b|n't\b", " ", clause.lower()))
    return all(w in known for w in words)


def _opens_request(clause: str) -> bool:
    return bool(
        re.match(
            r"\s*(?:please |so |and |then )*(?:could|can|would|will|give|hand|pass|bring|take|"
            r"put|place|fetch|get)\b",
            clause,
            _F,
        )
    )


# -- order said apart --------------------------------------------------------------------------


def _order(text: str, lexicon: Lexicon) -> str:
    """'Last, X. Before that, Y.' / 'Last, X. First, though, Y.' → 'Y. Finally, X.';
    'the bottle and the chips to Bob, the chips last' → 'the bottle to Bob, then the chips to
    Bob' (one of the two objects of a clause said last or first)."""
    m = re.match(
        r"^(?P<head>(?:please )?(?:(?:give|hand|pass|bring|take|put|place) [\w ]*?)?)"
        r"(?P<a>the [\w ]+?) and (?P<b>the [\w ]+?)(?P<tail> (?:to|on|onto) [^,]+)?, "
        r"(?P<one>the [\w ]+?) (?P<w>last|first)[.!]?$",
        text,
        _F,
    )
    if m is not None:
        a, b, one = (_ids(m.group(g), lexicon) for g in ("a", "b", "one"))
        if one and one in (a, b) and a != b and len(a) == len(b) == 1:
            late = (one == b) == (m.group("w").lower() == "last")
            x, y = (m.group("a"), m.group("b")) if late else (m.group("b"), m.group("a"))
            head, tail = m.group("head"), m.group("tail") or ""
            return f"{head}{x}{tail}, then {head}{y}{tail}"
    sentences = [s for s in re.split(r"(?<=[.;!?])\s+", text.strip()) if s]
    if len(sentences) != 2:
        return text
    last = re.match(r"(?:last|lastly|finally|last of all),?\s+(.*)$", sentences[0], _F)
    first = re.match(
        r"(?:before that|first|first of all|but first)(?:,?\s*though)?,?\s+(.*)$",
        sentences[1],
        _F,
    )
    if last is None or first is None:
        return text
    before = first.group(1).rstrip(" .;!?")
    return f"{before}. Finally, {last.group(1)}"


def _only(words: str, lexicon: Lexicon, kind: str) -> bool:
    """Whether ``words`` is one name of one thing of ``kind`` in the scene."""
    names = _names(words, lexicon)
    return (
        len(names) == 1
        and len({r.id for r in names[0].refs}) == 1
        and names[0].refs[0].kind == kind
        and words.lower().removeprefix("the ").strip() == names[0].text.lower()
    )


def _a_thing(words: str, lexicon: Lexicon) -> bool:
    """Whether ``words`` are a scene object's name, or end in a word that names one ('teddy',
    'teddy bear'; not 'water polo', whose 'water' is only a bottle's alias word)."""
    said = words.lower()
    names = {n.lower() for o in lexicon.scene.objects for n in (o.id, o.category, *o.aliases)}
    return said in names or bool(_ids(said.split()[-1], lexicon, "object"))


def _wanted_thing(m: re.Match[str], lexicon: Lexicon) -> bool:
    """Whether _FOR_THEIRS' "for her X" is what a person whines / looks / asks for: X a thing of
    the scene right after a verb ("Lily's been whining for her teddy"); after an object it says
    what the object is for ("Mr Lee wants the jug for his tablets"), taken off as before."""
    before = m.string[: m.start()].split()
    return bool(before) and before[-1].lower().endswith(("ing", "ed")) and _a_thing(m[1], lexicon)


def _words(text: str, lexicon: Lexicon) -> str:
    for pattern, repl in _WORDS:
        text = _sub(pattern, repl, text)
    # "the foreman himself": said of a person, taken off; after anything else ("Ava can get it
    # herself") the person does it themself, which asks the robot for nothing: kept, so the
    # clause is refused (session 25)
    text = _sub(_REFLEXIVE, lambda m: "" if _person_before(m, lexicon) else m[0], text)
    for pattern, repl in _WORDS_LATE:
        text = _sub(pattern, repl, text)
    return text


def _for_theirs55l(text: str, lexicon: Lexicon) -> str:
    """_FOR_THEIRS taken off (after _words' steps, a step of its own so stepguard guards each)."""
    if "for " not in text and "For " not in text:
        return text
    return _sub(_FOR_THEIRS, lambda m: m[0] if _wanted_thing(m, lexicon) else "", text)


# Session 55 (12p): _words was one step ending with two rewrites and a spacing of its sentences,
# run on every text; each is a step of its own after it (the same text out of the four), the
# rewrites asked only where their words are (so stepguard guards _words and them).
def _words_spaced55p(text: str, _lexicon: Lexicon) -> str:
    """_words' sentences joined by one space."""
    return " ".join(re.split(r"(?<=[.;!?])\s+", text))


def _ends_up_with55p(text: str, lexicon: Lexicon) -> str:
    """_words' "X should end up with Carol, and Y with Bob": goes to (each 'with' of the
    sentence). A sentence of the text matches only where the text does; the text comes spaced by
    _words_spaced55p, so its sentences joined again are the text."""
    if not re.search(r"\bends? up with\b", text, _F):
        return text
    sentences = re.split(r"(?<=[.;!?])\s+", text)
    for n, s in enumerate(sentences):
        m = re.search(r"\bends? up with\b", s, _F)
        if m is not None and not _person_ends_up36s(s[m.end() :], lexicon):
            s = _sub(r"\bends? up with\b", "go to", s)
            sentences[n] = _sub(r"\bwith\b", "to", s)
    return " ".join(sentences)


def _left_with55p(text: str, lexicon: Lexicon) -> str:
    """_words' "…, and the apple with Carol": an object left with a person goes to that person
    (in a list of what goes where; after 'give P' it could be a second recipient or company).
    Each pattern holds ' with '."""
    if not re.search(r"\bwith\b", text, _F):
        return text
    given = re.search(r"\b(?:give|hand|pass|bring|take|fetch|get)\b", text, _F)
    for h in [] if given else lexicon.scene.humans:
        for alias in (*h.aliases, h.name):
            text = _sub(
                rf"\b(the \w+(?: \w+)?) with ({re.escape(alias)})(?=\s*(?:[.,;!?]|\band\b|$))",
                lambda m: (
                    f"{m.group(1)} to {m.group(2)}"
                    if _only(m.group(1), lexicon, "object")
                    else m.group(0)
                ),
                text,
            )
    return text


def _gendered_header(text: str, lexicon: Lexicon) -> str:
    """'Mrs Khan, then Mr Lee: the magazine for her, the grey blanket for him': the people said
    first, each pronoun after the colon the one whose title fits it, in the order said."""
    m = re.match(r"^([^,:]+?),? (then|and) ([^,:]+?)\s*:\s*([^,]+), ([^,]+?)[.!]?$", text)
    if m is None:
        return text
    sexes = []
    for who in (m.group(1), m.group(3)):
        title = who.split()[0].lower().rstrip(".")
        if title not in _TITLES or not _only(who, lexicon, "human"):
            return text
        sexes.append(_TITLES[title])
    if sexes[0] == sexes[1]:
        return text
    parts = []
    for n, part in enumerate((m.group(4), m.group(5))):
        pron = re.findall(r"\b(?:him|her)\b", part, _F)
        if len(pron) != 1:
            return text
        sex = {"her": "f", "him": "m"}[pron[0].lower()]
        if m.group(2).lower() == "then" and sex != sexes[n]:
            return text  # after 'then' each pronoun must be the person said at its place
        parts.append(_sub(r"\b(?:him|her)\b", m.group(1 if sex == sexes[0] else 3), part))
    return f"{parts[0]}, {m.group(2)} {parts[1]}"


def _worked_on35s(text: str, lexicon: Lexicon) -> str:
    """Session 35 (12s): which of a surface a person is at work on ("she's packing the last
    pallet"), a scene that has one, says nothing of any task: 'the last / next / first' taken
    off before it (a remark can then be taken off: _at_work35s)."""

    def plain(m: re.Match[str]) -> str:
        if not _only(m["s"], lexicon, "surface") or m.group(0).lower().count(" the ") != 1:
            return m.group(0)
        return m.group(0).replace(f" {m['which']} ", " ", 1)

    return _rx(
        r"(?:'s|\bis|\bare|'re)(?: still| just| busy)? (?:packing|loading|unloading|checking|"
        r"stacking|sorting|clearing) the (?P<which>last|next|first) (?P<s>[a-z]+)"
        r"(?=\s*[,.;!?]|\s*$)"
    ).sub(plain, text)


def _at_work35s(said: list[str], body: str, lexicon: Lexicon) -> set[str]:
    """Session 35 (12s): the surfaces remarks name only as where a person is at work ("The
    tape's for Mia, and the gloves as well, she's packing the last pallet."), on the conditions
    of _where_they_are (the remarks name no object; the request points at no place): what a
    person works on changes nobody's task. The surface said in the plural ('the pallets') counts
    as its name."""
    if any(_ids(c, lexicon, "object") for c in said) or re.search(r"\b(?:there|here)\b", body, _F):
        return set()
    out: set[str] = set()
    for c in said:
        for m in _AT_WORK35S.finditer(c):
            for n in (m["s"], m["s"].removesuffix("s")):
                if _only(n, lexicon, "surface"):
                    out |= _ids(n, lexicon, "surface")
                    break
    return out


def _where_they_are(said: list[str], body: str, lexicon: Lexicon) -> set[str]:
    """The surfaces remarks name only as where a person is ("Lily's in her high chair now"),
    when the remarks name no object and the request points at no place ('there', 'here'): a
    person's whereabouts change nobody's task."""
    if any(_ids(c, lexicon, "object") for c in said) or re.search(r"\b(?:there|here)\b", body, _F):
        return set()
    out: set[str] = set()
    for c in said:
        for m in re.finditer(
            # session 34 (12s): "Omar's the one at the sink" says where Omar is, too
            r"(?:'s|\bis|\bare|\bwas|\bsits?|\bsitting|\bstands?|\bstanding|\bwaiting) (?:the one "
            r"(?:(?:standing|sitting|waiting) )?)?(?:now |"
            r"still |already |just )?(?:in|at|on|by|near|next to|beside) (?:her|his|their|the|its)"
            r" ([a-z]+(?: [a-z]+)?)",
            c,
            _F,
        ):
            words = m.group(1)
            for n in (words, words.split()[0]):
                if _only(n, lexicon, "surface"):
                    out |= _ids(n, lexicon, "surface")
                    break
    return out


def _said(oid: str, lexicon: Lexicon) -> str:
    """A name of object ``oid`` that names it alone."""
    o = next(x for x in lexicon.scene.objects if x.id == oid)
    for name in (*o.aliases, o.id.replace("_", " "), o.category):
        if _only(name, lexicon, "object") and _ids(name, lexicon) == {oid}:
            return name
    return o.id


# -- notes -------------------------------------------------------------------------------------


def _notes(text: str, lexicon: Lexicon) -> str:
    kinds: dict[str, list[list[str]]] = {}
    for o in lexicon.scene.objects:
        names = [o.id.replace("_", " "), *o.aliases]
        kinds.setdefault(o.category.lower(), []).append(
            [w for n in names for w in n.lower().split() if w != o.category.lower()]
        )
    # "Plates: white one to the counter, blue one to Lena" / "Boxes: small and medium on …"
    m = re.match(r"^(\w+)\s*:\s*(.*)$", text)
    if m is not None:
        head = m.group(1).lower()
        cat = next((c for c in kinds if head in (c + "s", c + "es")), None)
        if cat is not None:
            adjs = {w for ws in kinds[cat] for w in ws}
            rest = _sub(
                rf"\b({'|'.join(map(re.escape, sorted(adjs)))}) ones?\b", rf"\1 {cat}", m.group(2)
            )
            rest = _sub(
                rf"\b(?<!the )({'|'.join(map(re.escape, sorted(adjs)))})\b(?! {cat})",
                rf"the \1 {cat}",
                rest,
            )
            text = rest
    # "Both items to Bob" in a scene of two objects
    if len(lexicon.scene.objects) == 2:
        both = " and ".join(f"the {_said(o.id, lexicon)}" for o in lexicon.scene.objects)
        text = _sub(r"\bboth (?:items|things|objects)\b", both, text)
    # "Mug, red one, to Carol"
    for cat, lists in kinds.items():
        adjs = {w for ws in lists for w in ws}
        if adjs:
            alt = "|".join(map(re.escape, sorted(adjs)))
            # (not before a list: "one pen, the red one and the blue one" is two, not one)
            text = _sub(
                rf"\b{cat},\s*(?:the )?({alt}) one(?!\s+(?:and|or)\b),?", rf"the \1 {cat}", text
            )
    # "Carol: nothing." / "nothing for Carol" / "the large box stays": no task
    clauses = re.split(r"(?<=[.;,])\s+", text)
    kept = []
    for c in clauses:
        bare = c.strip(" .;,")
        nothing = re.match(r"^(?:and )?(.+?):?\s+(?:gets |wants |needs )?nothing$", bare, _F)
        stays = re.match(r"^(?:and )?(?:the )?(.+?) stays(?: put| where it is| there)?$", bare, _F)
        # (only if nobody else's clause names them: "Alice gets nothing, Alice gets the cup"
        # contradicts itself)
        others = " ".join(x for x in clauses if x is not c)
        if (
            nothing is not None
            and _only(nothing.group(1), lexicon, "human")
            and not _ids(nothing.group(1), lexicon) & _ids(others, lexicon)
        ):
            continue
        if (
            stays is not None
            and _only(stays.group(1), lexicon, "object")
            and not _ids(stays.group(1), lexicon) & _ids(others, lexicon)
            # nor when another clause counts every object: "Everything except the cup goes to
            # Bob, the apple stays" hands over the apple with the rest (session 26, 12s)
            and not _rx(r"\b(?:everything|anything|all|the lot|the rest|every)\b").search(others)
        ):
            continue
        kept.append(c)
    if len(kept) < len(clauses) and kept:
        text = " ".join(kept).rstrip(" ,;")
    return text


# -- session 11: labels, descriptions, contrasts, counts, answered questions ---------------------

_ORDER_WORDS = re.compile(
    r"\b(?:first|last|then|next|finally|before|after|once|when|only|each|both|all|either|or|"
    r"every|except|instead|if|unless|until)\b",
    _F,
)


def _statement(clause: str, lexicon: Lexicon) -> bool:
    """Whether ``clause`` says something about someone or something ('Tom is about to leave',
    "it's urgent", 'Bob wants the chips earlier') with no word that could cancel, negate or
    restrict a task: only such a clause can be a remark."""
    words = clause.strip(" ,:").lower()
    if _NEGATIONS.search(words) or _ORDER_WORDS.search(words):
        return False  # "Bob first, please" orders: no remark
    if "," in words:
        return False  # "he's hungry, just kidding": a remark is one clause
    words = re.sub(r"^(?:(?:and|so|because|since|as|anyway|well|ok|okay|right),?\s+)+", "", words)
    m = re.match(r"^(?:it'?s|its|it|he|she|they|that|this|there)\b", words)
    if m is None:
        names = _names(words, lexicon)
        if not names or names[0].refs[0].kind != "human":
            return False
        at = words.find(names[0].text.lower())
        if at < 0 or words[:at].strip() not in ("", "the", "our", "my"):
            return False
        rest = words[at + len(names[0].text) :]
    else:
        rest = words[m.end() :]
    if re.match(r"^\s*(?:does|did|do|is|was|will|has|had|can|could|would|should)\s*[.!?]*$", rest):
        return False  # "Bob does, give him the chips": an answer to a question not asked
    return bool(re.match(r"^(?:'s|'re|'ll|'d)?\s*\w+", rest))


# session 30 (12s): a label naming a later time than now ("Tomorrow's list: Alice, cup.") puts
# what follows off; it is not dropped, and the instruction is refused for the time
_LATER30S = re.compile(r"\b(?:tomorrow|later|next (?:week|month|shift|time)|weekend)\b", _F)

# words that head a note and are in no list of common words
_NOTE_WORDS = re.compile(r"\b(?:handover|hand-over|fyi|memo|todo|to-do|reminder|ps|nb|re)\b", _F)


def _labels(text: str, lexicon: Lexicon) -> str:
    """'Tidy-up time: …', 'Night shift note - …', 'Handover, bay 3: …': a label before a colon
    or a dash that names nothing of the scene, negates, orders or chooses nothing is dropped."""
    m = re.match(r"^([\w' ,-]{1,40}?)\s*(?::|\s-\s)\s*(\S.*)$", text)
    if m is None:
        return text
    label = m.group(1)
    if (
        len(label.split()) > 5
        or _names(label, lexicon)
        # "Not urgent:" / "No rush -" are labels; "Cancel this:" is not
        or (_NEGATIONS.search(label) and not re.match(r"^(?:not|no) [a-z]+$", label, _F))
        or _ORDER_WORDS.search(label)
        or _LATER30S.search(label)
        or re.search(_TASK_WORDS, label, _F)
        or not _plain_words(_NOTE_WORDS.sub(" ", label), lexicon)
    ):
        return text
    return m.group(2)


def _heads(text: str, lexicon: Lexicon) -> str:
    """'the bear' for the object called 'teddy bear': the last word of an object's or a
    surface's name of two or more words, when no other name of the scene has that word, no name
    is that word alone, and it is no word the grammar knows."""
    for pattern, name in _heads_of(lexicon.scene):
        text = _sub(pattern, name, text)
    return text


# each scene's heads (_heads_now), kept by the scene itself as _scene_words (session 53, 12p:
# they are the scene's alone, and were worked out again for every text)
_HEADS_KEPT: dict[int, tuple[Scene, tuple[tuple[str, str], ...]]] = {}


def _heads_of(scene: Scene) -> tuple[tuple[str, str], ...]:
    kept = _HEADS_KEPT.get(id(scene))
    if kept is not None and kept[0] is scene:
        return kept[1]
    out = _heads_now(scene)
    if len(_HEADS_KEPT) > 64:
        _HEADS_KEPT.clear()
    _HEADS_KEPT[id(scene)] = (scene, out)
    return out


def _heads_now(scene: Scene) -> tuple[tuple[str, str], ...]:
    """The (pattern, name) pairs _heads asks in turn: each head said alone, and the name it is
    the head of."""
    names = [
        *((o.id, n) for o in scene.objects for n in (o.id, o.category, *o.aliases)),
        *((h.id, n) for h in scene.humans for n in (h.id, h.name, *h.aliases)),
        *((x.id, n) for x in scene.surfaces for n in (x.id, *x.aliases)),
    ]
    said = [(i, n.lower().replace("_", " ").split()) for i, n in names]
    people = {h.id for h in scene.humans}  # a surname is a person's (see _people)
    out: list[tuple[str, str]] = []
    for oid, name in names:
        words = name.lower().split()
        if len(words) < 2 or name == oid or oid in people:
            continue
        head = words[-1]
        owners = {i for i, ws in said if head in ws}
        alone = any(ws == [head] for _, ws in said)  # a name of its own already
        if owners != {oid} or alone or head in WORDS or head in VERBS:
            continue
        out.append((rf"(?<!{re.escape(words[-2])} )\b{re.escape(head)}\b", name))
    return tuple(out)


def _only_kind(words: str, lexicon: Lexicon, kind: str) -> bool:
    """Whether ``words`` is one name, of things of ``kind`` only (one or several)."""
    names = _names(words, lexicon)
    return (
        len(names) == 1
        and all(r.kind == kind for r in names[0].refs)
        and words.lower().removeprefix("the ").strip() == names[0].text.lower()
    )


def _described(text: str, lexicon: Lexicon) -> str:
    """'The plate on the rack goes to the guest': the object of that name that stands on that
    surface (one, else left alone); 'The block on the mat, that one's for Grandad' / 'the mug
    closest to Alice, give her that one': the object said first is what 'that one' is."""
    text = _sub(r"^(the [^,]+?),\s*that one(?:'s| is)\b", r"\1 is", text)
    m = re.match(r"^(the [^,]+?),\s*(.*)\bthat one\b(.*)$", text, _F)
    if (
        m is not None
        and _ids(m.group(1), lexicon, "object")
        and not re.search(r"\b(?:it|them|that)\b", m.group(2), _F)
    ):
        text = f"{m.group(2)}{m.group(1)}{m.group(3)}"

    def on(m: re.Match[str]) -> str:
        things, place = m.group(2), m.group(3)
        ids = _ids(things, lexicon, "object")
        if not _only_kind(things, lexicon, "object") or not _only(place, lexicon, "surface"):
            return m.group(0)
        (surface,) = _ids(place, lexicon, "surface")
        there = starting_on(ids, surface, lexicon)
        if len(there) != 1:
            return m.group(0)
        return f"{m.group(1)}the {_said(there[0], lexicon)}"

    return _sub(
        r"(^|(?<=[.;!?])\s*|(?<=,)\s*(?:and )?)(the [\w ]+?) (?:that's |that is |which is )?"
        r"(?:on|in) (the [\w ]+?)(?= (?:goes|go|is for|are for|should go|needs to go|has to go)\b)",
        on,
        text,
    )


def _fronted(text: str, lexicon: Lexicon) -> str:
    """'Except for the small one, all the boxes go on the pallet' and 'Not the bottle, Bob wants
    the crisps': what is left out, said before the request, goes after it ('… except for the
    small one'; '…, not the bottle'), where the grammar reads it against what the request names.
    Only before a clause with its own verb ('Not the hammer, the drill, to Kofi' is a contrast)."""
    m = re.match(
        r"^(except(?: for)?|apart from|other than|not|but not)\s+((?:the |a |an )?[^,;:.!?]+?),"
        r"\s*(.+?)\s*([.!?]?)$",
        text.strip(),
        _F,
    )
    if m is None or not re.search(_TASK_WORDS + r"|\b(?:goes?|go|should)\b", m.group(3), _F):
        return text
    left = m.group(2)
    if not _only_kind(left, lexicon, "object") and not re.match(r"^the \w+ one$", left, _F):
        return text
    rest = m.group(3)
    if not _ids(rest, lexicon, "object") and not re.search(r"\b(?:everything|all)\b", rest, _F):
        return text
    word = m.group(1).lower()
    contrast = word in ("not", "but not")
    said = f"{rest}, not {left}{m.group(4)}" if contrast else f"{rest} {word} {left}{m.group(4)}"
    # the words put after the request must be read as leaving out of it, and nothing else ('…
    # Jess after all except for the small spanner' would leave it out of 'all')
    # why: offline.py imports this module, so the grammar is imported where it is used
    from hltl.grounding.offline import parse_instruction

    try:
        whole = set(tasks(parse_instruction(rest, lexicon.scene, lexicon)))
        kept = set(tasks(parse_instruction(said, lexicon.scene, lexicon)))
    except GroundingError:
        return text
    dropped = {t.obj for t in whole - kept}
    named = _ids(left, lexicon, "object")
    if not kept <= whole or (contrast and dropped):
        return text
    if not contrast and (not dropped or (dropped - named if named else len(dropped) != 1)):
        return text
    return said


def _keeps_out(text: str, ids: set[str], lexicon: Lexicon) -> bool:
    """Whether the grammar reads ``text`` with none of the objects ``ids`` in any task ('Give
    Carol everything except the mugs. Not the crisps.': the crisps are in 'everything')."""
    # why: offline.py imports this module, so the grammar is imported where it is used
    from hltl.grounding.offline import parse_instruction

    try:
        node = parse_instruction(text, lexicon.scene, lexicon)
    except GroundingError:
        return False  # not read: the negation is left to be refused with it
    return not any(t.obj in ids for t in tasks(node))


def _kinds(ids: set[str], lexicon: Lexicon) -> set[str]:
    return {o.category for o in lexicon.scene.objects if o.id in ids}


def _one(said: str, other: str, lexicon: Lexicon) -> str:
    """'the green one' after 'the red block': 'the green block'."""
    if not said.lower().endswith(" one"):
        return said
    kinds = _kinds(_ids(other, lexicon, "object"), lexicon)
    return said[: -len("one")] + next(iter(kinds)) if len(kinds) == 1 else said


def _contrast(text: str, lexicon: Lexicon) -> str:
    """'Not the red block, the green one, for Lily' / 'not the green book the red one for
    noah': the second object, of the same kind as the first and another one of it;
    'Give the waitress the blue plate. Not the white one.': the last sentence only stresses."""
    m = re.match(
        r"^not (the [\w ]+?),? (the [\w ]+?)(,\s*.*|\s+(?:for|to|and)\b.*|[.!]?)$", text, _F
    )
    if m is not None:
        no, yes = m.group(1), m.group(2)
        yes_ids = _ids(_one(yes, no, lexicon), lexicon, "object")
        no_ids = _ids(no, lexicon, "object")
        if (
            len(yes_ids) == 1
            and no_ids
            and not yes_ids & no_ids
            and _only_kind(no, lexicon, "object")
        ):
            said = f"{_one(yes, no, lexicon)}{m.group(3)}"
            if _keeps_out(said, no_ids, lexicon):
                return said
    sentences = [x for x in re.split(r"(?<=[.;!?])\s+", text.strip()) if x]
    if len(sentences) >= 2:
        last = re.match(r"^not (the \w+ one|the [\w ]+?)[.!]?$", sentences[-1], _F)
        before = " ".join(sentences[:-1])
        named = _ids(before, lexicon, "object")
        if last is not None and len(named) >= 1:
            said = last.group(1)
            if said.lower().endswith(" one"):
                kinds = _kinds(named, lexicon)
                if len(kinds) != 1:
                    return text
                said = said[: -len("one")] + next(iter(kinds))
            no_ids = _ids(said, lexicon, "object")
            if no_ids and not no_ids & named and _keeps_out(before, no_ids, lexicon):
                return before  # leaving out what is not asked for adds nothing
    return text


def _same_kind(ids: set[str], lexicon: Lexicon) -> bool:
    return len(_kinds(ids, lexicon)) == 1


_COUNTS = {"one": 1, "two": 2, "three": 3, "four": 4, "five": 5, "six": 6}


def _each_of_one29r(header: str, who: set[str], lexicon: Lexicon) -> None:
    """Session 29 (12r): 'One thing each: the tape for Mia.' — 'each' shares out among more
    than one, and the list names one person where the scene has others: refused, saying who
    else 'each' could take in (read before as the one hand-over)."""
    if len(who) != 1 or len(lexicon.scene.humans) < 2:
        return
    (pid,) = who
    others = [_name(h.id, lexicon) for h in lexicon.scene.humans if h.id != pid]
    raise GroundingError(
        f"{header!r} names something for {_name(pid, lexicon)} only: say what "
        + " and what ".join(others)
        + (" gets" if len(others) == 1 else " get")
        + f" as well, or leave out {'apiece' if 'apiece' in header.lower() else 'each'!r}"
    )


def _counted(text: str, lexicon: Lexicon) -> str:
    """'Two things for Ava: the beaker and the wipes' and 'Person A takes two things: the cup
    and the apple' → 'Ava: the beaker and the wipes' when the list names that many objects; 'One
    thing each: bottle for A, chips for B', 'All three of them want something to drink: Alice
    the bottle, …' and 'The three people each get one thing: knife for Marco, …' → the list,
    when it names one object for each of that many people."""
    m = re.match(
        r"^(one|two|three|four|five|six) (?:things?|items?|objects?) for ([^:]+?)\s*:\s*(.+)$",
        text,
        _F,
    )
    said = None if m is None else (m.group(1), m.group(2), m.group(3))
    m = re.match(  # "Person A takes two things: the cup and the apple"
        r"^([^:]+?) (?:takes|gets|wants|needs|should get|is getting|can have|receives) "
        r"(one|two|three|four|five|six) (?:things?|items?|objects?)\s*:\s*(.+)$",
        text,
        _F,
    )
    said = said or (None if m is None else (m.group(2), m.group(1), m.group(3)))
    if said is not None and _only(said[1], lexicon, "human"):
        count, who, listed = said
        named = [it for it in _names(listed, lexicon) if it.refs[0].kind == "object"]
        if len(named) == _COUNTS[count.lower()] == len(_ids(listed, lexicon)):
            return f"{who}: {listed}"
        return text
    m = re.match(
        r"^(?:(one) (?:thing|item) each|(?:all (two|three|four|five|six) of them|the "
        r"(two|three|four|five|six) (?:people|of them)(?: each)?) (?:want|need|would like|get|"
        r"should get|each get|each want|each need) (?:something|one thing|an item|one item|a "
        r"thing)(?: each)?(?: to (?:drink|eat|read|use))?)\s*:\s*(.+)$",
        text,
        _F,
    )
    if m is None:
        return text
    listed = m.group(4)
    count = m.group(2) or m.group(3)
    parts = [x for x in re.split(r",\s*(?:and\s+)?|\s+and\s+", listed.rstrip(".!")) if x]
    people = [_ids(x, lexicon, "human") for x in parts]
    things = [_ids(x, lexicon, "object") for x in parts]
    if not all(len(p) == 1 and len(t) == 1 for p, t in zip(people, things, strict=True)):
        return text
    who = {next(iter(p)) for p in people}
    if len(who) != len(parts) or (count and len(who) != _COUNTS[count.lower()]):
        return text
    if m.group(1):
        _each_of_one29r(text[: text.index(":")].strip(), who, lexicon)
    return listed


def _answered(text: str, lexicon: Lexicon) -> str:
    """'Which block? The green one. It's for Ava.' / 'You asked which book: the green one, and
    it's for Zoe': the question answered is the object; 'it' after it is that object."""
    m = re.match(
        r"^(?:you asked |you wanted to know )?which (\w+)\s*[?:]\s*(the \w+ one)\s*(.*)$",
        text,
        _F,
    )
    if m is None:
        return text
    noun, rest = m.group(1).lower(), m.group(3)
    kinds = {o.category.lower() for o in lexicon.scene.objects}
    if noun not in kinds and noun.rstrip("s") not in kinds:
        return text
    thing = m.group(2)[: -len("one")] + (noun if noun in kinds else noun.rstrip("s"))
    if len(_ids(thing, lexicon, "object")) != 1:
        return text
    tail = re.match(
        r"^[.,]?\s*(?:and )?(?:it'?s|it is|that'?s|that is)?\s*(for|to) (.+)$", rest, _F
    )
    if tail is not None:
        return f"{thing} {tail.group(1)} {tail.group(2)}"
    tail = re.match(r"^[.,]\s*(.*)\b(it)\b(.*)$", rest, _F)
    if tail is not None and not re.search(r"\b(?:it|them)\b", tail.group(1) + tail.group(3), _F):
        return f"{tail.group(1)}{thing}{tail.group(3)}"
    return text


_PARTICIPLES = {
    "delivered": "deliver",
    "handed": "hand",
    "given": "give",
    "brought": "bring",
    "taken": "take",
    "put": "put",
    "placed": "place",
    "moved": "move",
    "passed": "pass",
    "sent": "send",
}


def _passive(text: str, lexicon: Lexicon) -> str:
    """'The apple and the chips should be delivered to Person B': deliver them to Person B (a
    passive whose subject names objects only, before 'to'/'on' and its target)."""

    def active(m: re.Match[str]) -> str:
        things = m.group(2)
        names = _names(things, lexicon)
        if not names or any(r.kind != "object" for it in names for r in it.refs):
            return m.group(0)
        return f"{m.group(1)}{_PARTICIPLES[m.group(3).lower()]} {things}"

    return _sub(
        r"(^|(?<=[.;!?])\s*|(?<=,)\s*(?:and )?)((?:the |a |an )[\w ]+?) (?:should|must|has to|"
        r"have to|needs to|need to) be (" + "|".join(_PARTICIPLES) + r")\b(?=\s+(?:over |across "
        r"|back )?(?:to|on|onto)\b)",
        active,
        text,
    )


def _fits(pid: str, text: str, lexicon: Lexicon) -> bool:
    """Whether every he/she/him/her in ``text`` may be person ``pid`` (a title says which; a
    name alone does not)."""
    sex = title_sex(pid, lexicon)
    said = {
        PRONOUN_SEX[w.lower()] for w in re.findall(r"\b(?:he|him|his|she|her|hers)\b", text, _F)
    }
    return sex is None or said <= {sex}


def _said_again30s(pid: str, lexicon: Lexicon) -> Callable[[re.Match[str]], str]:
    """Session 30 (12s): 'P, he …' says P again, unless P's title rules the pronoun out ("Mr
    Lee, she gets the jug" speaks to Mr Lee of someone else)."""

    def again(m: re.Match[str]) -> str:
        return m.group(1) + " " if _fits(pid, m.group(0), lexicon) else m.group(0)

    return again


def _absent(name: str, text: str) -> bool:
    """True only where ``name`` cannot stand in ``text`` in any letter case, so that a pattern
    holding it (escaped) cannot match (session 44, 12b: a rule skips a name the text lacks;
    False, and the rule runs, for a text or name that is not ASCII, whose case folding re may do
    otherwise)."""
    return text.isascii() and name.isascii() and name.lower() not in text.lower()


# A titled alias's rewrites ("Mister Lee", "Lee", "Miss Ortiz"): (the name after the title, the
# alias, the pattern for 'mister'/'missus', the pattern for the name alone (or ''), the patterns
# for the same-sex titles no other person has)
_Titled = tuple[str, str, str, str, tuple[str, ...]]


@functools.lru_cache(maxsize=64)
def _people_plan(lexicon: Lexicon) -> tuple[tuple[_Titled, ...], tuple[tuple[str, str], ...]]:
    """What _people builds from the scene's names alone, once per lexicon (session 44, 12b: it
    was built again for every text): the titled aliases' patterns and the roles two or more
    people share, with the names each role's sentence lists and its two patterns."""
    humans = lexicon.scene.humans
    titled: list[_Titled] = []
    everyone = [
        *(a for g in humans for a in (*g.aliases, g.name)),
        *(n for o in lexicon.scene.objects for n in (o.id, o.category, *o.aliases)),
        *(n for x in lexicon.scene.surfaces for n in (x.id, *x.aliases)),
    ]
    for h in humans:
        for alias in h.aliases:
            words = alias.split()
            if len(words) < 2 or words[0].lower().rstrip(".") not in _TITLES:
                continue
            sex, rest = _TITLES[words[0].lower().rstrip(".")], " ".join(words[1:])
            others = [t for t, s in _TITLES.items() if s == sex and t != words[0].lower()]
            said = {"m": "mister", "f": "missus"}[sex]  # "Mister Lee" for "Mr Lee"
            alone = ""
            # "Lee" alone for "Mr Lee", when no other name of the scene has that word
            if len(words) == 2 and sum(rest.lower() in n.lower().split() for n in everyone) == 1:
                after_title = "".join(  # "mr Khan" is no "Mrs Khan" either
                    rf"(?<!{t} )(?<!{t}\. )"
                    for title in ("Mr", "Mrs", "Ms", "Miss", "Dr")
                    for t in (title, title.lower(), title.upper())
                )
                alone = rf"{after_title}\b{re.escape(rest)}\b"
            same = tuple(  # "Miss Ortiz" for "Mrs Ortiz": the same woman, if no other
                rf"\b{t}\.? {re.escape(rest)}\b"
                for t in others
                if not any(a.lower() == f"{t} {rest}".lower() for g in humans for a in g.aliases)
            )
            titled.append((rest, alias, rf"\b{said} {re.escape(rest)}\b", alone, same))
    # "each student": every person of a role two or more share
    roles: dict[str, list[str]] = {}
    for h in humans:
        for alias in h.aliases:
            roles.setdefault(alias.lower(), []).append(_name(h.id, lexicon))
    shared = tuple((role, " and ".join(names)) for role, names in roles.items() if len(names) >= 2)
    return tuple(titled), shared


def _people(text: str, lexicon: Lexicon) -> str:
    humans = lexicon.scene.humans
    titled, shared = _people_plan(lexicon)
    for rest, alias, mister, alone, same in titled:
        if _absent(rest, text):
            continue  # every pattern below holds the name
        text = _sub(mister, alias, text)
        if alone:
            text = re.sub(alone, alias, text)
        for pattern in same:
            text = _sub(pattern, alias, text)
    for role, names in shared:
        if _absent(role, text):
            continue
        # only as the one request of the text: "(please) give each student <objects>"
        m = re.match(
            rf"^((?:please |could you |can you )?(?:give|hand|bring|pass|get)) each (?:of the )?"
            rf"{re.escape(role)}s? ((?:a|an|one of the|one|the) [\w ]+?)(?: please)?[.!?]?$",
            text,
            _F,
        )
        if m is not None and _one_thing(m.group(2), lexicon):
            text = f"{m.group(1)} {names} {m.group(2)} each"
        # "Each patient should receive one blanket", "Every student gets a book"
        m = re.match(
            rf"^(?:each|every) (?:of the )?{re.escape(role)}s? (?:(?:should|could|can|must|will|"
            rf"is to|are to) (?:receive|get|have|be given)|gets|receives|wants|needs|is getting|"
            rf"is given|has to get) ((?:a|an|one) [\w ]+?)[.!]?$",
            text,
            _F,
        )
        if m is not None and _one_thing(m.group(1), lexicon):
            text = f"{names} should get {m.group(1)} each"
    text = _gendered_header(text, lexicon)
    for h in humans:
        for alias in (*h.aliases, h.name):
            if _absent(alias, text):
                continue  # each pattern below holds the name
            p = re.escape(alias)
            # clefts: "It's Carol who needs …", "Carol's the one who wants …", "What Carol
            # needs is the apple"
            text = _sub(rf"^it(?:'s| is) ({p}) (?:who|that) ", r"\1 ", text)
            text = _sub(rf"^({p})(?:'s| is) the one (?:who|that) ", r"\1 ", text)
            text = _sub(rf"^what ({p}) (needs|wants|would like|'d like) is ", r"\1 \2 ", text)
            # a note headed "For Bob:" / "To Bob:"
            text = _sub(rf"(^|(?<=[.;])\s*)(?:for|to) ({p})\s*:", r"\1\2:", text)
            # "once Bob has had his chips": his is Bob's
            text = _sub(
                rf"\b({p}) (has|had|has had|'s had|gets|got|has got) (?:his|her|their) ",
                r"\1 \2 the ",
                text,
            )
    # "Person B wants the chips, and after that Person A for the bottle": the want again
    if re.search(r"\b(?:wants?|needs?|would like|'d like)\b", text, _F):
        for h in humans:
            for alias in (*h.aliases, h.name):
                if _absent(alias, text):
                    continue
                text = _sub(
                    r"(,\s*(?:and )?(?:then |after that |afterwards |next )?)"
                    rf"({re.escape(alias)}),?\s+for (?=the |a |an )",
                    r"\1\2 ",
                    text,
                )
    # "Bed 2, Mr Lee: …": a place said before the person
    text = _sub(r"^(?:bed|room|table|seat|desk|bay|cubicle) \d+\s*[,:-]\s*", "", text)
    # "Mr Novak he want lemon": a pronoun repeating the subject
    for h in humans:
        for alias in (*h.aliases, h.name):
            if _absent(alias, text):
                continue
            text = _sub(
                rf"^({re.escape(alias)}),? (?:he|she|they) ", _said_again30s(h.id, lexicon), text
            )
    # "You bring for the doctor the bowl"
    text = _sub(r"^you (?=give|bring|hand|pass|take|put|place|fetch)", "", text)
    return _sub(
        r"\b(give|bring|hand|pass|take|fetch) for ((?:the |our |my )?[\w' ]+?) (?=the |a |an )",
        lambda m: (
            f"{m.group(1)} {m.group(2)} "
            if _ids(m.group(2), lexicon, "human") and len(_ids(m.group(2), lexicon)) == 1
            else m.group(0)
        ),
        text,
    )


def _possessed(text: str, lexicon: Lexicon) -> str:
    """ "Carol's chips, Bob's apple, Alice's cup. Go.": a list of what is whose is who gets
    what; "Mr Lee's medication is to be handed to him": the object, and the one pronoun that
    fits his title is him."""
    body = _sub(r"(?:[.!]\s*(?:go|thanks|thank you|cheers|ta|please)[.!]*)+$", "", text.strip())
    parts = [x.strip() for x in re.split(r",\s*(?:and\s+)?|\s+and\s+", body.rstrip(" .!"))]
    pairs = [re.match(r"^(.+?)'s (.+)$", x) for x in parts]
    if len(parts) > 1 and all(
        m is not None
        and _only(m.group(1), lexicon, "human")
        and _only_kind(m.group(2), lexicon, "object")
        for m in pairs
    ):
        return ", ".join(f"the {m.group(2)} for {m.group(1)}" for m in pairs if m is not None)
    for h in lexicon.scene.humans:
        for alias in h.aliases:
            m = re.search(  # gated (session 53, 12p)
                _rx(rf"\b({re.escape(alias)})'s ([\w ]+?)\b(?= (?:is|are|should|must|has|have)\b)"),
                text,
            )
            if m is None or not _only(m.group(2), lexicon, "object"):
                continue  # "Mr Novak's plate is the blue one" says which (_words)
            pron = re.findall(r"\b(?:him|her)\b", text, _F)
            if title_sex(h.id, lexicon) is None or len(pron) != 1 or not _fits(h.id, text, lexicon):
                continue
            text = text[: m.start()] + f"the {m.group(2)}" + text[m.end() :]
            return _sub(r"\b(?:him|her)\b", alias, text)
    return text


def _there(text: str, lexicon: Lexicon) -> str:
    """'Put the notebook on the desk. Actually no, put the stapler there instead.': 'there' after
    a placement is the one surface named before it (none, or two, and it is left to be refused)."""
    m = re.search(
        r"\b((?:put|place|set|leave|stack|store|move)s? (?:the |a |an |it\b|them\b)[\w ]*?)"
        r"(?<! over)(?<! right)(?<! out)(?<! up)(?<! down)(?<! back)(?<! in) there\b",
        text,
        _F,
    )
    if m is None:
        return text
    said = text[: m.end() - len("there")]
    before = [it for it in _names(said, lexicon) if it.refs[0].kind == "surface"]
    if len({r.id for it in before for r in it.refs}) != 1:
        return text
    return f"{text[: m.start()]}{m.group(1)} on the {before[-1].text}{text[m.end() :]}"


def _topic(text: str, lexicon: Lexicon) -> str:
    """'The magazine, (…,) please bring to her': an object said first as the topic, and a verb
    later with no object of its own before 'to'/'on': the verb's object is the topic ('it')."""
    m = re.match(r"^(?:the |a |an )?([\w ]+?),", text, _F)
    if m is None or not _only_kind(m.group(1), lexicon, "object"):
        return text
    rest = text[m.end() :]
    gap = re.search(
        r"\b(bring|give|hand|take|pass|send|carry|deliver|put|place|get)\s+((?:over|back|across|"
        r"round) )?(to|on|onto|in|into)\b",
        rest,
        _F,
    )
    if gap is None or _ids(rest[: gap.start()], lexicon, "object"):
        return text
    verb = f"{gap.group(1)} it {gap.group(2) or ''}{gap.group(3)}"
    return f"{text[: m.end()]}{rest[: gap.start()]}{verb}{rest[gap.end() :]}"


def _reordered(text: str, lexicon: Lexicon) -> str:
    """'Tongs to Marco then the knife to Lena, wait, no, knife first then tongs': a correction
    of only names and an order, after two steps said in order, says them the other way round.
    Each name must pick out one of the two steps (by its object or its person)."""
    m = re.match(
        r"^(.+?)\s*,?\s+then\s+(.+?)(?:,|[.;!])\s*(?:(?:wait|hang on|hold on),?\s+)?"
        r"(?:no|sorry|actually|oops)(?:,? (?:wait|sorry))?,?\s+(?:the )?([\w ]+?) first"
        r"(?:,?\s*(?:and )?then (?:the )?([\w ]+?))?[.!]?$",
        text.strip(),
        _F,
    )
    if m is None:
        return text
    early, late = m.group(1), m.group(2)
    first = _ids(m.group(3), lexicon)
    if not first or not first <= _ids(late, lexicon) or first & _ids(early, lexicon):
        return text
    if m.group(4) is not None:
        second = _ids(m.group(4), lexicon)
        if not second or not second <= _ids(early, lexicon) or second & _ids(late, lexicon):
            return text
    if not (_ids(late, lexicon, "human") | _ids(late, lexicon, "surface")):
        # "Give Bob the apple, then the cup. Actually, cup first.": the second step shares the
        # first one's verb and person, so the two objects change places
        objs = [it for it in _names(early, lexicon) if it.refs[0].kind == "object"]
        said = [it for it in _names(late, lexicon) if it.refs[0].kind == "object"]
        if (
            len(objs) != 1
            or len(said) != 1
            or not re.fullmatch(rf"(?:the )?{re.escape(said[0].text)}", late.strip(), _F)
        ):
            return text
        at = early.lower().rfind(objs[0].text.lower())
        swapped = early[:at] + said[0].text + early[at + len(objs[0].text) :]
        return f"{swapped}, then the {objs[0].text}"
    return f"{late}, then {early}"


def _leave_it(text: str, _lexicon: Lexicon) -> str:
    """'Actually no, leave it, put the stapler there (instead)': 'leave it' in a correction takes
    back the request before, so the new one stands instead of it."""
    m = re.search(
        r"\b((?:actually|no|wait|sorry|oops)(?:,? (?:no|wait))?),?\s+(?:leave it|leave that|forget "
        r"(?:it|that)|scrap that|never mind(?: that)?)\s*,\s*((?:put|place|give|hand|bring|take|"
        r"pass|set)\b[^.;!?]*?)(\s+instead)?([.;!?]?)\s*$",
        text,
        _F,
    )
    if m is None:
        return text
    return f"{text[: m.start()]}{m.group(1)}, {m.group(2)} instead{m.group(4)}"


_JOINS = frozenset(
    {
        *("if", "when", "because", "and", "so", "as", "since", "that", "once", "before"),
        *("after", "until", "but", "or", "whether", "unless", "then", "while", "though"),
    }
)


def _run_on(text: str, _lexicon: Lexicon) -> str:
    """'Marco is on grill tonight he needs the tongs': a statement run into a want with no stop
    between them; the stop is put back ('… tonight. he needs …') when the word before the
    pronoun joins nothing, so that the statement can be read as a remark."""
    m = re.search(
        r"(?<=[a-z])( (?:now|today|tonight|again|already))? (he|she|they) (?="
        r"(?:needs|wants|would like|'d like|could use|will need|is "
        r"going to need|'s going to need|'ll need)\b)",
        text,
        _F,
    )
    if m is None:
        return text
    before = text[: m.start()]
    last = before.split()[-1].lower() if before.split() else ""
    if last in _JOINS or not re.search(r"\b(?:is|are|was|were)\b|'s\b|'re\b", before, _F):
        return text
    return f"{before}{m.group(1) or ''}. {m.group(2)} {text[m.end() :]}"


def _texting(text: str, lexicon: Lexicon) -> str:
    """'give the chips 2 bob', 'cup 4 alice': '2' and '4' typed for 'to' and 'for', only right
    before the name of a person (a number before an object counts it)."""
    if not re.search(r"\b[24] ", text):
        return text
    for h in lexicon.scene.humans:
        for alias in (*h.aliases, h.name):
            text = _sub(rf"\b2 (?={re.escape(alias)}\b)", "to ", text)
            text = _sub(rf"\b4 (?={re.escape(alias)}\b)", "for ", text)
    return text


def _vocative(text: str, lexicon: Lexicon) -> str:
    """'Lena, the tongs are for you': the person spoken to first is the 'you' of the request
    ('for you', 'you can have'), when the words before the comma name that person only."""
    m = re.match(r"^([^,;:.!?]+?),\s*(.+)$", text.strip())
    if m is None or not _only(m.group(1), lexicon, "human"):
        return text
    rest = m.group(2)
    if not re.search(r"\bfor you\b|\byou (?:can|could|may) have\b", rest, _F):
        return text
    who = m.group(1)
    rest = _sub(r"\bfor you\b", f"for {who}", rest)
    return _sub(r"\byou (can|could|may) have\b", rf"{who} \1 have", rest)


def _lacks(text: str, lexicon: Lexicon) -> str:
    """'Zoe hasn't got a ruler, can she have one', "Noah can't find his book, give him the red
    one": what a person lacks, then a request whose 'one' / 'it' / 'the red one' is that kind
    of object and whose pronoun is that person: the request with them said."""
    m = re.match(
        r"^([^,;.!?]+?)(?: (?=[a-z])|(?='s ))(?:hasn't got|has not got|hasn't|has no|doesn't have|"
        r"does not have|can't find|cannot find|can not find|has lost|lost|forgot|has forgotten|has"
        r" run out of|'s run out of|ran out of|is out of|'s out of) (?:his |her |their |a |an |any"
        r" |the )?([\w ]+?),\s*(?:so\s+)?(.+)$",
        text.strip(),
        _F,
    )
    if m is None or not _only(m.group(1), lexicon, "human"):
        return text
    who, kind, rest = m.group(1), m.group(2), m.group(3)
    if not _only_kind(kind, lexicon, "object") or not re.search(r"\b(?:one|it)\b", rest, _F):
        return text
    if _ids(rest, lexicon, "human") - _ids(who, lexicon, "human"):
        return text  # "Bob hasn't got the cup, give it to Carol": the lack is not why
    if kind.endswith("s") and _only_kind(kind[:-1], lexicon, "object"):
        kind = kind[:-1]  # "Sam's run out of pens, give him the black one": the black pen
    rest = _sub(r"\bthe (\w+) one\b", rf"the \1 {kind}", rest)
    rest = _sub(r"(?<!\bthe )\bone\b", f"a {kind}", rest)
    rest = _sub(r"\bit\b", f"the {kind}", rest)
    return _sub(r"\b(?:he|she|him|her|they|them)\b", who, rest)


def _thanks(text: str, _lexicon: Lexicon) -> str:
    """'Ruler. Zoe. Thanks.': a last sentence of thanks asks nothing (taken off first, so that
    what stands before it is read as said)."""
    return _sub(
        r"(?<=[.!?])\s+(?:thanks|thank you|cheers|ta|thx|many thanks)(?: (?:so|very) much| a lot|"
        r" again)?\s*[.!]*\s*$",
        "",
        text,
    )


def _bare_pair(text: str, lexicon: Lexicon) -> str:
    """'Wipes. Grandad.': an object said alone, then a person said alone: the object for them."""
    m = re.match(r"^(?:the )?([\w ]+?)[.,]\s*(?:for )?([\w ]+?)[.!]?$", text.strip(), _F)
    if m is None or not _only_kind(m.group(1), lexicon, "object"):
        return text
    if not _only(m.group(2), lexicon, "human"):
        return text
    return f"the {m.group(1)} for {m.group(2)}"


def hearer_named(text: str, lexicon: Lexicon) -> str | None:
    """ "You're Carol, Bob wants a mug": the one spoken to said to be a person of the scene (the
    robots are spoken to, so who 'you', 'I' and the vocative are is unclear): that person's
    words, else None."""
    for m in re.finditer(r"\byou(?:'re| are| r)\s+((?:the |our |my )?[\w ]{1,30})", text, _F):
        names = _names(m.group(1), lexicon)
        if names and names[0].refs[0].kind == "human":
            head = m.group(1).lower().removeprefix("the ").removeprefix("our ").removeprefix("my ")
            if head.startswith(names[0].text.lower()):
                return names[0].text
    return None


def people_named(text: str, lexicon: Lexicon) -> set[str]:
    """The ids of the people ``text`` names (by name, title or role)."""
    return _ids(text, lexicon, "human")


def one_person(text: str, lexicon: Lexicon) -> str | None:
    """The name of the one person ``text`` names (several names of one person count once),
    when every he/she/him/her of ``text`` may be them."""
    people = [it for it in _names(text, lexicon) if all(r.kind == "human" for r in it.refs)]
    ids = {r.id for it in people for r in it.refs}
    if len(ids) != 1 or not _fits(next(iter(ids)), text, lexicon):
        return None
    return people[0].text


def _told_apart(text: str, lexicon: Lexicon) -> str:
    """'The red mug, which Bob has been asking about all morning, should go to him.', 'the mug
    closest to Alice, give her that one': the one person the text names is the pronoun (the
    aside naming only them is then dropped); 'Bob's on his break and asked for …', 'Ava wants
    to build a tower, can she have …': a state or a plan before the request is a remark."""
    who = one_person(text, lexicon)
    pron = re.findall(r"\b(?:him|her|he|she)\b", text, _F)
    m = re.search(r",\s*(?:which|who)\b([^,]+),", text, _F)
    if m is not None and who is not None and len(pron) == 1 and one_person(m.group(1), lexicon):
        aside = m.group(1)
        if not _NEGATIONS.search(aside) and not _ids(aside, lexicon, "object"):
            rest = text[: m.start()] + text[m.end() - 1 :]
            if one_person(rest, lexicon) is None:
                rest = rest.replace(",,", ",")
                return _sub(r"\b(?:him|her)\b", who, rest.replace(", should", " should"))
    m = re.match(r"^(the [^,]+?),\s*(give|hand|pass|bring) (him|her) that one\b(.*)$", text, _F)
    if m is not None and who is not None and _ids(m.group(1), lexicon, "object"):
        return f"{m.group(2)} {who} {m.group(1)}{m.group(4)}"
    m = re.match(
        r"^(.+?)(?:'s| is| was) ([a-z' ]+?),? and "
        r"(?=(?:wants|needs|asked for|would like|'d like)\b)",
        text,
    )
    if m is not None and _only(m.group(1), lexicon, "human"):
        state = m.group(2)
        if (
            not _names(state, lexicon)
            and not _NEGATIONS.search(state)
            and not _ORDER_WORDS.search(state)
            and _plain_words(state, lexicon)
        ):
            return f"{m.group(1)} {text[m.end() :]}"
    m = re.match(
        r"^(.+?) (?:wants|would like|'d like|needs|is going|'s going|is trying|'s trying|has) "
        r"to (?!have\b|get\b|receive\b|keep\b|borrow\b|use\b)([a-z]+(?: [a-z]+){0,4}),\s*"
        r"(?:so )?(can|could|would|will|please)\b(.*)$",
        text,
    )
    if m is not None and _only(m.group(1), lexicon, "human") and one_person(text, lexicon):
        plan, rest = m.group(2), f"{m.group(3)}{m.group(4)}"
        things = [it for it in _names(plan, lexicon) if it.refs[0].kind == "object"]
        if len(things) == 1:
            # "…, can he have it?": the 'it' of the request's own sentence, an object; not the
            # subject of a later remark (session 35, lead: 12r's fuzz read "…, can he have the
            # gloves? Also, give Tom the tape or the scanner, it's up to you which." as the
            # large box of the plan joining the choice)
            end = re.search(r"[.!?](?:\s|$)", rest)
            head, tail = (rest[: end.end()], rest[end.end() :]) if end else (rest, "")
            it = r"\bit\b(?!'s|\s+(?:is|was|does|doesn't|makes)\b)"
            rest = _sub(it, f"the {things[0].text}", head) + tail
        if (
            len(things) == len(_names(plan, lexicon))
            and _ids(plan, lexicon) <= _ids(rest, lexicon)  # else the plan may ask for them
            and not _NEGATIONS.search(plan)
            and _plain_words(plan, lexicon)
        ):
            return _sub(r"\b(?:he|she)\b", m.group(1), rest)
    return text


# a verb after the subject of a clause ('both mugs need …', '… go on the shelf')
_CLAUSE_VERB35L = re.compile(
    r"\s+(?:need|go|should|must|are|have|want|can|could|will|would|belong|get)\b", _F
)


def _both_kind(text: str, lexicon: Lexicon) -> str:
    """'Both books on the desk, green first': 'both <kind>s' when the scene has two of that kind
    names them; '<word> first/last' after them names the one of that kind the word picks."""
    kinds: dict[str, list[str]] = {}
    for o in lexicon.scene.objects:
        kinds.setdefault(o.category.lower(), []).append(o.id)
    for cat, ids in kinds.items():
        if len(ids) != 2:
            continue
        m = _rx(rf"\bboth (?:the )?{re.escape(cat)}s\b").search(text)
        if m is None:
            continue
        a, b = (_said(i, lexicon) for i in ids)
        comma = _rx(r",\s*$").search(text, 0, m.start())
        if comma is not None and _CLAUSE_VERB35L.match(text, m.end()):
            # Session 35 (lead): "We need the apple, both mugs need shifting up to the shelf"
            # (12's frames fuzz) read the apple onto the shelf: 'both mugs' opening a clause of
            # its own after a comma would join the list before it once named; it opens a
            # sentence instead
            text = text[: comma.start()] + f". The {a} and the {b}" + text[m.end() :]
        else:
            text = text[: m.start()] + f"the {a} and the {b}" + text[m.end() :]
        words = {w for i in ids for w in _said(i, lexicon).lower().split() if w != cat}
        alt = "|".join(map(re.escape, sorted(words)))
        if alt:
            text = _sub(
                rf",\s*(?:the )?({alt})(?: one)? (first|last)\b", rf", the \1 {cat} \2", text
            )
    return text


_RANKS = (
    (r"first(?: of all)?|firstly|to start(?: with)?|start with", 0),
    (r"in between|in the middle|second|secondly", 1),
    (r"last(?: of all)?|lastly|finally|at the end", 2),
)


def _ranked(text: str, _lexicon: Lexicon) -> str:
    """'Last, the apple to Alice. First the chips to Bob. In between, the cup to Carol.': three
    sentences each opening with its place in the order, said in another order."""
    sentences = [x for x in re.split(r"(?<=[.;!?])\s+", text.strip()) if x]
    if len(sentences) != 3:
        return text
    placed: dict[int, str] = {}
    for x in sentences:
        for words, rank in _RANKS:
            m = re.match(rf"^(?:{words}),?\s+(.+?)[.;!]?$", x, _F)
            if m is not None:
                if rank in placed or _ORDER_WORDS.search(m.group(1)):
                    return text
                placed[rank] = m.group(1)
                break
        else:
            return text
    return f"{placed[0]}. Then {placed[1]}. Finally, {placed[2]}."


# -- session 13: what a request carries that cannot change who gets what ------------------------
#
# Each rewrite below takes off a listed class of words or clauses, and only where the words taken
# off name nothing in the scene (no object, person or surface, also not by a typo) and hold no
# negation, quantifier, number, 'or', 'then' or 'before' of the request: courtesy and closings,
# the speaker talking about themselves, what a thing is for, when (a time clause about no task),
# a negated command about objects the request leaves alone, a confirmation of a correction.


def _names_nothing(words: str, lexicon: Lexicon) -> bool:
    """Whether ``words`` names no object, person or surface of the scene (nor a typo of one)."""
    return not _names(words, lexicon)


def _drop(pattern: str, text: str, lexicon: Lexicon, repl: str = "") -> str:
    """``text`` without each match of ``pattern`` that names nothing in the scene ('thing', as in
    'poor thing', is not a name)."""
    return _sub(
        pattern,
        lambda m: (
            m.expand(repl)
            if _names_nothing(re.sub(r"\bthings?\b", "", m.group(0), flags=_F), lexicon)
            else m.group(0)
        ),
        text,
    )


# The opener rule: greetings, 'yes' and a call for attention ('excuse me', 'pardon me', 'sorry
# to bother you', with or without 'sorry') opening the request, each before a comma (a call for
# attention also before a full stop): the 'me' of 'excuse me' is no recipient and its 'sorry'
# corrects nothing. Later in the instruction a call for attention is left (_corrections19 does not
# read it as a correction).
_GREETING = (
    r"(?:hi|hello|hey|hiya|yes|yeah|yep|ok|okay|right|morning|evening|afternoon|"
    r"good (?:morning|afternoon|evening|day)|ah|oh)(?: there)?"  # session 24: 'Ah, good afternoon'
)
_BOTHERING = r"(?:to|for) (?:bother|interrupt|trouble|disturb|rush)(?:ing)?(?: you)?"
_ATTENTION = (
    r"(?:(?:(?:excuse|pardon) me(?:,? (?:so )?sorry)?|(?:so )?sorry,? (?:excuse|pardon) me)"
    rf"(?:,? (?:(?:so )?sorry )?{_BOTHERING})?|(?:so )?sorry {_BOTHERING}|"
    # session 25: a call to listen, and an opening 'so' / 'lovely' ("Right, listen. Person B:
    # bottle.", "Come on then, love, chips to …", "So. Chips, …", "Lovely, ta, the lemon …")
    r"listen(?: up)?|look|come on(?: then| now)?|lovely|so)"
)
_OPENERS = rf"^(?:{_GREETING}\s*[,!]\s*|{_ATTENTION}\s*[,.!]\s*(?=[a-z]))+"


_COURTESY: tuple[tuple[str, str], ...] = (
    # "No rush at all, but at some point could Priya get …": when, not what
    (
        r"(^|(?<=[.;!?])\s*)(?:there'?s )?no (?:rush|hurry)(?: at all)?(?:\s*[,.!;]\s*|\s+)"
        r"(?:but\s+)?",
        r"\1",
    ),
    # "Hi, yes, hello, could you …", "Excuse me, sorry to bother you, …": the opener rule
    (_OPENERS, ""),
    (r",?\s*\bat some (?:point|stage)(?: today| later)?\b", ""),
    (r"(^|(?<=[.;!?])\s*)(?:whenever|when) (?:you'?re|you are) (?:ready|free)\s*[,.]?\s*", r"\1"),
    # "Be an angel and hand …": a request for a favour, not a name
    (
        r"(^|(?<=[.;!?,])\s*)(?:(?:could|would|can|will) you |so |and |please |now )*be (?:an? )?("
        r"?:angel|dear|star|love|darling|gem|sweetheart|sweetie|pal|treasure|doll|lamb|good (?:rob"
        r"ot|lad|girl|boy))(?:\s+and\b|\s*[,:])\s*",
        r"\1",
    ),
    # "would you be ever so kind and pass …", "if you'd be so good, …"
    (
        r"\b(?:(?:would|could|will) you )?(?:please )?be (?:ever |so |very )*(?:so )?(?:kind|good|"
        r"nice|sweet)(?: as to| and| enough to)\b,?\s*",
        "",
    ),
    (r",?\s*\bif you(?:'d| would| could)? (?:be )?(?:ever )?so (?:kind|good)\b\s*,?", ""),
    # "if you wouldn't mind", "if you would not mind": a courtesy, not a negated task
    (r",?\s*\bif you (?:wouldn't|would not|don't|do not|didn't|did not) mind\b\s*,?", ""),
    # thanks said every way: "thank you ever so much", "thanks a million", "ta very much"
    (
        r"\b(?:thank you|thanks|ta|thx)(?:\s+(?:ever|so|very|really|most|kindly))*\s+"
        r"(?:much|kindly)\b",
        "thanks",
    ),
    (r"\bthanks (?:a (?:million|bunch|lot|ton|heap)|loads|heaps|again|in advance)\b", "thanks"),
    (r"\b(?:many|big|huge) thanks\b", "thanks"),
    (
        r",?\s*\b(?:much appreciated|(?:i |really )*appreciate it|you'?re (?:a star|an angel|a gem|"
        r"a lifesaver|the best))\b",
        "",
    ),
    # "Just so you know, Ava wants …", "Heads up, …", "By the way, …": a note on the request
    (
        r"(^|(?<=[.;!?])\s*)(?:just so (?:you know|ya know)|heads up|by the way|for the record|"
        r"for your information|as (?:i said|mentioned|discussed)|like i said)\s*[,:!-]?\s*",
        r"\1",
    ),
    # "…, bless him", "…, poor thing": sympathy said after the request
    (
        r",\s*(?:bless (?:him|her|them|'?em)|(?:the )?poor (?:thing|dear|love|lamb|soul|mite|"
        r"guy|man|woman|kid|pet|sausage)s?)(?=\s*(?:[.,;!?]|$))",
        "",
    ),
    # "…, would be great", "…, if that's alright with you", "Much obliged."
    (
        r",?\s*\b(?:that |it )?(?:would|'d|will) be (?:great|lovely|brilliant|perfect|wonderful|"
        r"amazing|fab|fantastic|ideal|helpful|super|awesome|appreciated|much appreciated)\b",
        "",
    ),
    (
        r",?\s*\bif (?:that's|that is|it's|it is|that'd be|that would be) (?:ok|okay|alright|all "
        r"right|fine)(?: with you| by you)?\b",
        "",
    ),
    (r"(^|(?<=[.;!?])\s*)much obliged\b[.!]*", r"\1"),
    # "Could I get the robot to give Bob the chips?": the speaker asks through the robot
    (
        r"\b(?:could|can|may|might) (?:i|we) (?:get|ask|have) (?:you|the robots?|the arms?|it) "
        r"(?:to )?(?=(?:give|hand|pass|bring|take|put|place|move|fetch|send)\b)",
        "please ",
    ),
    # "…, where it belongs": where a placement puts it back, said again
    (r",?\s+where (?:it|they) (?:belongs?|lives?|goes|go|should be)\b", ""),
    # "… for later", "… for a sec": for how long or for when
    (
        r"\s+for (?:later|now|a (?:sec|second|minute|moment|bit|while)|the (?:moment|time being|"
        r"day|night|week|weekend)|tonight|tomorrow|today)\b(?=\s*(?:[.,;!?]|$|please|thanks))",
        "",
    ),
    # "…, you know", "…, over and out": said to close, not to ask
    (
        r",\s*(?:you know|you see|over and out|and that's (?:it|that)|that's it)(?=\s*(?:[.!?]|$))",
        "",
    ),
    (r",?\s*\b(?:whenever|when) (?:you're|you are) (?:ready|free|able)\b", ""),
    # "I'd say Dana needs the spoon", "If I'm not mistaken, …": how sure the speaker is
    (
        r"(^|(?<=[.;!?])\s*)(?:i'd say|i would say|if i'm not mistaken|if i remember (?:right|"
        r"rightly|correctly)|as far as i know|i suppose|i imagine|i'm (?:pretty |fairly )?sure|i "
        r"am (?:pretty |fairly )?sure|i think|i believe|i reckon|i guess)(?: that)?\s*,?\s*",
        r"\1",
    ),
    # "… so that he has something to eat", "… to soak": what it is for, naming nothing
    (
        r",?\s+so (?:that )?(?:he|she|they|it) (?:can|could|has|have|will|'ll|won't|doesn't|"
        r"don't|isn't|is|are|gets?) [a-z' ]{2,40}?(?=\s*(?:[.;!?]|,\s*(?:please|thanks)\b|$))",
        "",
    ),
    (
        r"(?<!thing)(?<!stuff)\s+(?:so as )?to (?:soak|dry|cool|cool down|warm up|eat|drink|use|re"
        r"ad|charge|share|keep|wash|clean|play with|play|sign|fix|cut|write|write with|work|work w"
        r"ith|snack on|look at|finish|study|sort|pack|label|scan)\b(?: [a-z]+){0,3}?(?=\s*(?:[.;!?"
        r"]|,\s*(?:please|thanks)\b|$|\s+please\b))",
        "",
    ),
    # "give the, uh, banana": a hesitation between commas
    (r",\s*(?:um+|uh+|erm*|er|hmm+|ah+)\s*,", ""),
    # "I was hoping Emma could have …", "Don't forget to give …": asking, reminding
    (
        r"(^|(?<=[.;!?])\s*)(?:i was|i'm|i am|we were|we're|we are) (?:just |really )?hoping"
        r"(?: that)? ",
        r"\1",
    ),
    (r"(^|(?<=[.;!?,])\s*)(?:please )?(?:don't|do not) forget to ", r"\1"),
    (r"\bmake sure (?:that )?(?:you )?(don't|do not|never)\b", r"\1"),
    (r"\bmake sure not to\b", "don't"),
)
# "… on the tray for us": the speaker's benefit, as "for me" (not after a part naming only an
# object: "…, and the apple for us" may make the speaker its recipient)
_FOR_US = r"\s+for us\b(?=\s*(?:[,.;!?]|please|thanks|$))"
_VERB_WORDS = re.compile(
    r"\b(?:give|hand|pass|bring|take|put|place|pop|stick|set|move|send|fetch|get|gets|leave|"
    r"drop|deliver|wants?|needs?|like|have|has|goes|go|going)\b",
    _F,
)


def _for_us(text: str, lexicon: Lexicon) -> str:
    def drop(m: re.Match[str]) -> str:
        part = re.split(r",|\band\b|[.;!?]", text[: m.start()])[-1]
        if (
            _ids(part, lexicon, "object")
            and not _ids(part, lexicon, "human")
            and not _ids(part, lexicon, "surface")
        ):
            words = part
            for it in _names(part, lexicon):  # "the glue stick": no verb
                words = words.replace(it.text, " ")
            if not _VERB_WORDS.search(words):
                return m.group(0)
        return "" if _names_nothing(m.group(0), lexicon) else m.group(0)

    return _sub(_FOR_US, drop, text)


# requests asked as a possibility or a choice, rewritten with their names kept
_ASKED: tuple[tuple[str, str], ...] = (
    # "I request you to give …", "I'd ask you to …"
    (
        r"(^|(?<=[.;!?])\s*)(?:i|we)(?:'d| would)? (?:request|ask|beg) (?:you |that you )?(?:to )?"
        r"(?=(?:give|hand|pass|bring|take|put|place|move|fetch|send|get)\b)",
        r"\1",
    ),
    # "Mrs Khan is requesting the magazine"
    (r"\s*(?:\bis|'s|\bare|'re) (?:requesting|asking for)\b", " wants"),
    # "The thermometer needs to get to Ruth": goes to her
    (r"\b(?:needs?|has|have) to get (?:over )?to\b", "should go to"),
    # "The guest hasn't had his salt yet": he wants it (the whole sentence)
    (
        r"^((?:the )?[\w ]+?) (?:still )?(?:hasn't|has not|hasn't yet|has not yet|still hasn't) "
        r"(?:had|got|gotten|received) (?![^.!]*\b(?:or|nor|and|any|either|neither|all|both)\b)"
        r"((?:his|her|their|the|a|an) [\w ]+?)(?: yet)?\s*[.!]?$",
        r"\1 wants \2",
    ),
    # "Hand the glue to Zoe or Noah, whoever wants it": the choice the 'or' already gives
    (
        r"(\bor\b[^.;!?]*?),\s*whoever (?:wants|needs|likes|would like|prefers) (?:it|them|one)\b",
        r"\1",
    ),
    # "Is it possible for Emma to have …", "Would it be ok if Emma had …": may she have it
    (
        r"(^|(?<=[.;!?])\s*)(?:is it|would it be|will it be) (?:at all )?(?:possible|ok|okay|"
        r"alright|all right|fine) (?:for|if) ((?:the )?[\w ]+?) (?:to have|to get|had|got|could "
        r"have|could get|has|gets) ",
        r"\1could \2 have ",
    ),
    # "Priya and Sam both need a pen": each of them one
    (
        r"\bboth (need|want|would like|get|should get|could use)s? (a|an|one) ([a-z]+(?: [a-z]+)?)"
        r"(?=\s*(?:[.,;!?]|$|please))(?!,?\s*so one each)",
        r"\1 \2 \3 each",
    ),
)


def _courtesy(text: str, lexicon: Lexicon) -> str:
    """Courtesy said around a request: favours asked ('be an angel and'), 'if you wouldn't
    mind', 'no rush, but', thanks said every way, 'for us'. Taken off only where it names
    nothing in the scene. Then requests asked as a possibility ('Is it possible for Emma to have
    …'), a choice left to them ('…, whoever wants it') or shared ('both need a pen')."""
    for pattern, repl in _COURTESY:
        text = _drop(pattern, text, lexicon, repl)
    text = _for_us(text, lexicon)
    for pattern, repl in _ASKED:
        text = _sub(pattern, repl, text)
    # "Mia's on the phone but she needs the tape": a remark naming no object, then the want
    text = _sub(
        r"^([^,;.!?]+?) but (he|she|they) (needs|wants|would like|'d like|could use)\b",
        lambda m: (
            f"{m.group(1)}. {m.group(2)} {m.group(3)}"
            if not _ids(m.group(1), lexicon, "object")
            else m.group(0)
        ),
        text,
    )
    return text


# Session 55 (12p): the single spacing that closed _courtesy, _courtesy14 and _courtesy_frames,
# a step of its own after each (the same text out): what is left of each is read by its words,
# so stepguard guards it.
def _spaced55p(text: str, _lexicon: Lexicon) -> str:
    return " ".join(text.split())


# The words of a closing or greeting said as a sentence of its own ("Lovely, thanks.", "That
# would be lovely.", "Thank you, dear."): none can name, count, negate or order a task.
_CLOSING_WORDS = frozenset(
    {
        *("lovely", "brilliant", "perfect", "great", "super", "superb", "wonderful"),
        *("fantastic", "excellent", "marvellous", "marvelous", "splendid", "awesome", "amazing"),
        *("fab", "fabulous", "cool", "nice", "grand", "ace", "sweet", "smashing", "cheers"),
        *("thanks", "thank", "you", "ta", "thx", "dear", "love", "darling", "mate", "pal"),
        *("hun", "hon", "buddy", "so", "much", "very", "really", "a", "lot", "that", "would"),
        *("be", "that'd", "that's", "it", "it'd", "i'd", "appreciate", "appreciated", "many"),
        *("ever", "kindly", "bye", "goodbye", "good", "stuff", "job", "helpful", "kind"),
        *("oh", "ah", "well", "ok", "okay", "hello", "hi", "hey", "hiya", "morning"),
        *("afternoon", "evening", "there", "robot", "robots", "everyone", "folks", "all"),
        *("again", "too", "and", "just", "again", "bunch", "million", "loads", "yes", "yeah"),
        *("right", "sure", "great", "top", "legend", "star", "sir", "madam", "please"),
    }
)


def _closing(text: str, lexicon: Lexicon) -> str:
    """'… to the waitress. Lovely, thanks.' / 'Good evening. …': a sentence only of greeting,
    praise and thanks asks nothing (the first and the last ones are taken off)."""
    sentences = [x for x in re.split(r"(?<=[.;!?])\s+", text.strip()) if x]
    if len(sentences) < 2:
        return text

    def closing(sentence: str) -> bool:
        words = re.findall(r"[a-z']+", sentence.lower())
        return (
            bool(words)
            and all(w in _CLOSING_WORDS for w in words)
            and _names_nothing(sentence, lexicon)
        )

    while len(sentences) > 1 and closing(sentences[-1]):
        sentences.pop()
    while len(sentences) > 1 and closing(sentences[0]):
        sentences.pop(0)
    return " ".join(sentences)


_SELF = re.compile(
    r"(^|(?<=[.;!?])\s*|(?<=,)\s*)(?:(?:(?:hi|hello|hey|hiya)(?: there)?|sorry|excuse me|good "
    r"(?:morning|afternoon|evening)|morning|evening)\s*[,!.]?\s*)*"
    r"(?:i'm|i am|im|we're|we are)\s+(?P<said>[^.;!?,]*?)"
    r"(?:\s*[.;!?]+\s*|\s*,\s*(?:(?:so|but|and)\b,?\s*)?|\s+(?:so|but)\s+)",
    _F,
)
# what the speaker says of themselves must be a state, not an act on a task: no verb of giving,
# placing or wanting, no negation of a task and no order
_SELF_ACTS = re.compile(
    r"\b(?:giv\w*|hand\w*|pass\w*|bring\w*|brought|tak\w*|took|put\w*|plac\w*|send\w*|sent|"
    r"deliver\w*|mov\w*|fetch\w*|want\w*|need\w*|ask\w*|after|before|then|first|last|only "
    r"(?:getting|having)|getting|having|going to|about to)\b",
    _F,
)

_SELF_CHANGES = re.compile(
    r"\b(?:except|instead|rather|cancel|forget|skip|drop|swap|without|or|either|neither|nor|"
    r"each|every|all|both|any|not sure|unsure|not certain|maybe|perhaps|probably|torn|"
    r"mistaken|confused)\b|n't sure\b",
    _F,
)


def _speaker(text: str, lexicon: Lexicon) -> str:
    """ "I'm only visiting, but …", "Sorry, I'm just here for the cooking class. …", "I'm
    covering for the day nurse, so …": the speaker saying who they are is not a request, and
    not a recipient. Taken off when it names no object or surface of the scene, does nothing to
    a task, and (if it names a person) the request has no he/she/him/her that could be them."""
    for m in _SELF.finditer(text):
        said = m.group("said")
        if _SELF_ACTS.search(said) or _SELF_CHANGES.search(said):
            continue
        named = _names(said, lexicon)
        if any(r.kind != "human" for it in named for r in it.refs):
            continue
        rest = text[: m.start()] + m.group(1) + text[m.end() :]
        if named and re.search(r"\b(?:he|she|him|her|his|they|them)\b", rest, _F):
            continue
        if not rest.strip() or not _names(rest, lexicon):
            continue
        return _speaker(" ".join(rest.split()), lexicon)
    return text


# Words that count, choose, order or point back: a phrase holding one is never taken off as what
# a thing is for or when it is wanted ('before the rest', 'for the other one', 'after that').
_KEEP_WORDS = re.compile(
    r"\b(?:all|everything|everyone|everybody|each|every|both|either|neither|any|anything|anyone|"
    r"rest|other|others|another|one|ones|first|last|second|third|next|previous|same|that|this|"
    r"those|these|it|them|then|him|her|me|us|you|his|hers|theirs|mine|yours|ours|its|none|"
    r"nothing|nobody|no|not|or|and|nor|only|"
    r"instead|except|without|twice|again|once|[0-9]+|two|three|four|five|six|ten|dozen|half)\b|"
    r"n't\b",
    _F,
)


def _purpose(text: str, lexicon: Lexicon) -> str:
    """'The technician needs a sponge for the spill', 'Put the cup on the table for the
    meeting': what it is for, a phrase after 'for' that names nothing in the scene and holds no
    word that counts, chooses or points back, said at the end of a clause.

    Session 24: '…, the green one's for the communion wine' says what an object is kept for: the
    clause is a remark, taken off whole (it never asks for the object); a 'for' phrase right
    after 'is' / ''s' is what the clause says, so it is never taken off alone (that left "the
    green one's", read as 'the green one too')."""
    text = _sub(
        r",\s+(?:and\s+)?(?:the|that|this|those|these) (?P<subj>[a-z]+(?: [a-z]+){0,2})"
        r"(?:'s|'re| is| are) (?:only |just |all )?for (?:the|a|an|this|that|some|my|our) "
        r"(?P<use>[a-z]+(?:[ -][a-z]+)?)(?=\s*(?:[.;!?]|$))",
        lambda m: (
            ""
            if _names_nothing(m.group("use"), lexicon)
            and not _KEEP_WORDS.search(m.group("use"))
            and all(r.kind == "object" for n in _names(m.group("subj"), lexicon) for r in n.refs)
            else m.group(0)
        ),
        text,
    )
    return _sub(
        r"(?<!'s)(?<! is)(?<! are)(?<!'re)(?<! was)(?<! were)"
        r"\s+for (?:the|a|an|this|that|some) ([a-z]+(?:[ -][a-z]+)?)(?=\s*(?:[.,;!?]|$|\bplease\b|"
        r"\bthanks\b))",
        lambda m: (
            ""
            if _names_nothing(m.group(0), lexicon) and not _KEEP_WORDS.search(m.group(1))
            else m.group(0)
        ),
        text,
    )


# a time later than now, said in a deadline ('before I go tomorrow', 'before she leaves tonight')
_LATER24 = re.compile(
    r"\b(?:tomorrow|tonight|later|next|week|weekend|month|evening|afternoon|morning|lunch|"
    r"dinner|breakfast|tea|hours?|minutes?|mins?|days?|o'clock|\d)\b",
    _F,
)


def _when(text: str, lexicon: Lexicon) -> str:
    """'… before he heads off', '… before the lesson starts': a deadline about no task (it names
    nothing in the scene, and no word in it counts, chooses or points back to a task) is met by
    doing the task now; 'before he gets the apple' names an object and orders the tasks, so it
    stays. A delay ('after he finishes his lunch', 'when she gets back', 'tomorrow') is not met
    by doing it now: left to be refused."""

    def timed(m: re.Match[str]) -> str:
        said = m.group("said")
        # session 34 (12s): "… before the kids find them": the object said again after a verb
        # of no task of the robots' (not giving, bringing or putting) is what the deadline is
        # about, not another task ("… before Bob gets them" stays)
        last = re.match(r"^(?P<rest>.*) (?P<verb>[a-z]+) (?:it|them)$", said, _F)
        if last is not None and VERB_CLASS.get(VERBS.get(last["verb"].lower(), "")) not in (
            "give",
            "bring",
            "put",
            "possess",
        ):
            said = f"{last['rest']} {last['verb']}"
        if (
            _names_nothing(said, lexicon)
            and not _KEEP_WORDS.search(said)
            and not re.search(r"\b(?:done|finished|complete|completed)\b", said, _F)
            # session 24: "before I go tomorrow" names a later time: the task is put off
            and not _LATER24.search(said)
        ):
            return ""
        return m.group(0)

    return _sub(
        r",?\s+(?:before|by the time) (?:he|she|they|the|his|"
        r"her|their|my|our|i|we)\b(?P<said>(?:'s|'re| [a-z']+){1,5})(?=\s*(?:[.;!?]|,\s*(?:please|"
        r"thanks|thank you|cheers|ta)\b|$))",
        timed,
        text,
    )


def _wants(text: str, lexicon: Lexicon) -> str:
    """'Mrs Khan would quite like the grey blanket', 'What Mia really needs is the gloves', 'For
    the foreman the hammer': wants said with a degree, as a cleft, or with the person first."""
    text = _sub(
        r"\b(would|'d) (?:quite|really|rather|very much|so much|dearly|much|so|truly|actually|"
        r"just|also) (like|love)\b",
        r"\1 \2",
        text,
    )

    def cleft(m: re.Match[str]) -> str:
        return (
            f"{m.group(1)}{m.group(2)} {m.group(3)} "
            if _only(m.group(2), lexicon, "human")
            else m.group(0)
        )

    # "Bob is desperate for the chips": wants them
    text = _sub(
        r"\s*(?:\bis|'s|\bare|'re|\bhas been|'s been) (?:really |so |just )?(?:desperate|dying|"
        r"gasping|longing|itching|crying out|keen|gagging) (?:for|to have|to get)\b",
        " wants",
        text,
    )
    text = _sub(
        r"(^|(?<=[.;!?])\s*)(?:all (?:i'm|i am|we're|we are) asking(?: for)? is for|all (?:i|we) "
        r"ask is for|what (?:i'm|i am|we're|we are) asking(?: for)? is for) (.+?) to (get|have)\b",
        r"\1\2 should \3",
        text,
    )
    text = _sub(
        r"(^|(?<=[.;!?])\s*)(?:what|all|the only thing) ((?:the )?[\w ]+?) (?:really |actually |mo"
        r"st |honestly |truly |definitely |absolutely )?(needs|wants|would like|'d like|could use|"
        r"is after|asked for) (?:most |really )?is (?=(?:the|a|an|some|both|one|either)\b)",
        cleft,
        text,
    )

    def fronted(m: re.Match[str]) -> str:
        if _only(m.group(2), lexicon, "human") and _only_kind(m.group(3), lexicon, "object"):
            return f"{m.group(1)}the {m.group(3)} for {m.group(2)}"
        return m.group(0)

    return _sub(
        r"(^|(?<=[.;!?,])\s*)for ((?:the )?[\w ]+?),? (?:the |a |an )([\w ]+?)(?=\s*(?:[,.;!?]|$|p"
        r"lease\b))",
        fronted,
        text,
    )


# Session 51 (12p): _scene_adjectives and _scene_words kept by the scene itself (its id, with the
# scene kept beside: an id is its own only while it lives). lru_cache hashed the scene at every
# call, and a frozen dataclass's hash is made anew each time from every object, person and
# surface of it (~10 µs, some seven times an instruction); what is kept for a scene is what
# was made from it, as before.
_ADJECTIVES_KEPT: dict[int, tuple[Scene, dict[str, frozenset[str]]]] = {}


def _scene_adjectives(scene: Scene) -> dict[str, frozenset[str]]:
    kept = _ADJECTIVES_KEPT.get(id(scene))
    if kept is not None and kept[0] is scene:
        return kept[1]
    out = _scene_adjectives_now(scene)
    if len(_ADJECTIVES_KEPT) > 64:
        _ADJECTIVES_KEPT.clear()
    _ADJECTIVES_KEPT[id(scene)] = (scene, out)
    return out


def _scene_adjectives_now(scene: Scene) -> dict[str, frozenset[str]]:
    single = {
        w.lower()
        for n in (
            *(n for o in scene.objects for n in (o.id, o.category, *o.aliases)),
            *(n for h in scene.humans for n in (h.id, h.name, *h.aliases)),
            *(n for x in scene.surfaces for n in (x.id, *x.aliases)),
        )
        for w in ([n] if " " not in n else n.split()[1:])
    }
    out: dict[str, set[str]] = {}
    for o in scene.objects:
        for name in o.aliases:
            words = name.lower().split()
            if len(words) == 2 and words[0] not in single and words[0] not in WORDS:
                out.setdefault(words[0], set()).add(o.category)
    return {k: frozenset(v) for k, v in out.items()}


def _adjectives(lexicon: Lexicon) -> dict[str, frozenset[str]]:
    """Each first word of a two-word object name that is no name alone ('red' of 'red pen', 'big'
    of 'big box'), with the kinds of objects it tells apart."""
    return _scene_adjectives(lexicon.scene)


# -- asides ------------------------------------------------------------------------------------


def _picks_object(words: str, lexicon: Lexicon) -> bool:
    """Whether ``words`` is 'the <colour or size of an object> one' ('the green one'), which
    picks out an object, unlike 'the one at the end'."""
    m = re.search(r"\bthe (\w+) ones?\b", words, _F)
    return m is not None and m.group(1).lower() in _adjectives(lexicon)


def _people_only(words: str, lexicon: Lexicon) -> bool:
    """Whether ``words`` are only names of people of the scene ('Mia', 'the driver', 'Mia and
    Tom'), each naming one person."""
    named = _names(words, lexicon)
    if not named or any(
        len({r.id for r in it.refs}) != 1 or it.refs[0].kind != "human" for it in named
    ):
        return False
    left = words.lower()
    for it in named:
        left = left.replace(it.text.lower(), " ", 1)
    return not re.sub(r"\b(?:the|and|our|my)\b|,", " ", left).strip()


def _elided(text: str, lexicon: Lexicon) -> str:
    """'Priya wants the blue pen; Sam, the red' / 'Zoe the green': a colour or size said alone
    after 'the', at the end of a clause, is 'the red one' (the grammar then finds which one by
    the object said before it, or refuses); 'Mia takes the small box; …' (no place or person
    after it) is 'Mia gets the small box'."""
    adjectives = _adjectives(lexicon)
    if adjectives:
        text = _sub(
            r"\bthe (" + "|".join(sorted(map(re.escape, adjectives))) + r")(?=\s*(?:[.,;!?]|$|"
            r"\band\b|\bplease\b))",
            r"the \1 one",
            text,
        )

    def takes(m: re.Match[str]) -> str:
        if not _people_only(m.group(1), lexicon):
            return m.group(0)
        return f"{m.group(1)} {m.group(2) or ''}{'get' if m.group(2) else 'gets'}"

    return _sub(
        r"(?<![\w,] )(?:^|(?<=[.;!?]\s)|(?<=[;]))\s*([A-Z][\w ]*?) ((?:can |will |should |may |"
        r"could )?(?:each )?)takes?\b(?=(?:(?!\b(?:to|on|onto|in|into|over|for|from|out|off|"
        r"away|back|it|them|him|her)\b)[^.;!?])*(?:[.;!?]|$))",
        takes,
        text,
    )


def _choice(text: str, lexicon: Lexicon) -> str:
    """'Put any box you like on the belt' (any box), 'Both the knife and the tongs go to Marco'
    (the knife and the tongs), 'a plate, any except the blue one' (a plate except the blue
    one), 'Give P two things, the bottle and the apple, and …' (the bottle and the apple, when
    the list names that many objects), 'the only bottle' (the bottle, when it is one)."""
    # (one chosen object, so only in a clause of one task: no 'and' after it)
    text = _sub(
        r"\b((?:any|either|whichever) [a-z]+) (?:that |which )?(?:you|she|he|they|we) (?:like|"
        r"likes|want|wants|prefer|prefers|fancy|fancies|choose|chooses|pick|picks)\b"
        r"(?![^.;!?]*\band\b)",
        r"\1",
        text,
    )

    def both(m: re.Match[str]) -> str:
        # 'both' before two objects joined ("both the knife and the tongs"), not before one
        # kind and a closing ("both boxes and that's it": 'both' counts them)
        second = " ".join(m.group(1).split()[:3])
        return "" if _ids(second, lexicon, "object") else m.group(0)

    text = _sub(
        r"\bboth (?=(?:the |a |an )?[a-z][\w ]*? and ((?:the |a |an )?[a-z][\w ]*))"
        r"(?![^.;!?,]*\bboth\b)",
        both,
        text,
    )
    # "a mug for Bob and one for Carol": 'one' is another of that kind
    text = _sub(
        r"\b(a|an) ([a-z]+) (for|to) ([\w ]+?),? and one (for|to) ",
        lambda m: (
            f"{m.group(1)} {m.group(2)} {m.group(3)} {m.group(4)} and a {m.group(2)} {m.group(5)} "
            if _only_kind(m.group(2), lexicon, "object")
            else m.group(0)
        ),
        text,
    )
    text = _sub(
        r",\s*any (?:one )?(?:except|but|apart from|other than|besides|bar) (?=the )",
        " except ",
        text,
    )

    def listed(m: re.Match[str]) -> str:
        items = [x for x in re.split(r",\s*(?:and\s+)?|\s+and\s+", m.group(2)) if x]
        ids = [_ids(x, lexicon, "object") for x in items]
        count = int(m.group(1)) if m.group(1).isdigit() else _COUNTS[m.group(1).lower()]
        if (
            len(items) == count
            and all(
                len(x) == 1 and _only_kind(y.removeprefix("the "), lexicon, "object")
                for x, y in zip(ids, items, strict=True)
            )
            and len(set().union(*ids)) == len(items)
        ):
            return m.group(2)
        return m.group(0)

    text = _sub(r"\ba couple of (?=(?:things|items|objects)\b)", "two ", text)
    text = _sub(
        r"\b(one|two|three|four|five|six|[1-6]) (?:things?|items?|objects?)\s*[,:]\s*((?:the |a |a"
        r"n )[a-z][\w ]*?(?:(?:,\s*|\s+and\s+)(?:the |a |an )[a-z][\w ]*?)*)(?=,|\s*[.;!?]|$)",
        listed,
        text,
    )

    def only(m: re.Match[str]) -> str:
        words = m.group(1).split()
        for n in (2, 1):
            said = " ".join(words[:n])
            if len(words) >= n and _only(said, lexicon, "object"):
                return f"the {said}{m.group(1)[len(said) :]}"
        return m.group(0)

    return _sub(r"\bthe only ([a-z]+(?: [a-z]+)?)\b", only, text)


def _reading(text: str, lexicon: Lexicon, *, normalise: bool = True) -> Node | None:
    """What the grounder reads ``text`` as, or None where it refuses (``normalise=False``: the
    grammar alone, without the rewrites)."""
    # why: offline.py imports this module, so the grammar is imported where it is used
    from hltl.grounding.offline import parse_instruction

    try:
        return parse_instruction(text, lexicon.scene, lexicon, normalise=normalise)
    except GroundingError:
        return None


def _tasks_of(
    text: str, lexicon: Lexicon, *, normalise: bool = True
) -> set[tuple[str, str, str]] | None:
    """The (kind, object, target) of every task the grammar reads in ``text``; None if refused
    (``normalise=False``: the grammar alone, without the rewrites)."""
    node = _reading(text, lexicon, normalise=normalise)
    return None if node is None else {(t.kind, t.obj, t.target) for t in tasks(node)}


_DONT = r"(?:please |just |and |but |so |also )*(?:don't|do not|dont|never)\s+"
_DO_VERBS = r"(?:give|hand|pass|bring|take|send|put|place|move|leave|set|drop|deliver)\b"


def _first_sentence_it31l(rest: str, words: str, lexicon: Lexicon) -> str:
    """'it' / 'them' in the first sentence of ``rest`` (after a negated command naming
    ``words``), when that sentence names no object of its own: the negated command's object,
    whatever later sentences name (session 31, lead: "Don't put the lemon on the rack, give it
    to Marco. It's the knife that Marco is hoping for." had handed the knife alone)."""
    m = re.match(r"[^.;!?]*", rest)
    first = m.group(0) if m is not None else ""
    later = rest[len(first) :]
    if any(it.refs[0].kind == "object" for it in _names(first, lexicon)):
        return rest
    if not re.search(r"\b(?:it|them)\b", first, _F):
        return rest
    return _sub(r"\b(?:it|them)\b", f"the {words}", first) + later


def _unless_asked(said: str, request: str, result: str, lexicon: Lexicon) -> str | None:
    """``result`` when the grammar reads both ``said`` (a negated command, read as if asked) and
    ``request``, and no task of the first is one of the second's; else None."""
    if _KEEP_WORDS.search(re.sub(r"\b(?:the|and|them|it|him|her)\b", " ", said)) and re.search(
        r"\b(?:all|everything|any|anything|each|every|either|or|rest|other|others)\b", said, _F
    ):
        return None  # "don't give him anything else": not a task that can be left out
    if re.search(r"\b(?:rather|instead|than|except|but|unless|if)\b", said, _F):
        return None  # "don't give her the apple rather than the crisps": which is negated?
    negated = _tasks_of(said, lexicon)
    asked = _tasks_of(request, lexicon)
    if not negated or not asked or negated & asked:
        return None
    return result


def _negated(text: str, lexicon: Lexicon) -> str:
    """A negated command beside a request: 'Give Bob the chips. Don't give him the apple.' and
    "Don't put the crisps on the shelf, give them to Alice". The negated command is read as if
    it were asked (its he/she being the one person of the request), and dropped only when none
    of its tasks is among the request's (with 'it'/'them' in the request being its object, when
    it comes first); else the negation stays, and is refused."""
    # "Don't put the lemon on the rack, give it to Marco"
    m = re.match(
        rf"^{_DONT}({_DO_VERBS}[^,;.!?]*?)\s*[,;.]\s*(?:(?:but|instead|and|rather|just|please),?"
        r"\s+)*(.+?)$",
        text.strip(),
        _F,
    )
    if m is not None:
        said, rest = m.group(1), m.group(2)
        objects = [it for it in _names(said, lexicon) if it.refs[0].kind == "object"]
        own = [it for it in _names(rest, lexicon) if it.refs[0].kind == "object"]
        if len(objects) == 1 and not own and re.search(r"\b(?:it|them)\b", rest, _F):
            rest = _sub(r"\b(?:it|them)\b", f"the {objects[0].text}", rest)
        elif len(objects) == 1 and own:
            rest = _first_sentence_it31l(rest, objects[0].text, lexicon)
        return _unless_asked(said, rest, rest, lexicon) or text
    # "Give Bob the chips. Don't give him the apple." / "…, but don't hand her the bib"
    m = re.match(
        rf"^(.+?)\s*(?:[.;!]|,)\s*{_DONT}({_DO_VERBS}[^.;!?]*?)\s*[.!]?$", text.strip(), _F
    )
    if m is not None:
        rest, said = m.group(1), m.group(2)
        who = one_person(rest, lexicon)
        if who is not None:
            said = _sub(r"\b(?:he|she|him|her)\b", who, said)
        return _unless_asked(said, rest, rest, lexicon) or text
    # "Not to Mrs Khan, the magazine goes to Mr Lee": a place or person left out, said first
    m = re.match(r"^not (?:to|for|on|onto|in|into) ([^,;.!?]+?)\s*,\s*(.+)$", text.strip(), _F)
    if m is not None:
        named = _names(m.group(1), lexicon)
        if not named or any(r.kind == "object" for it in named for r in it.refs):
            return text
        if m.group(1).lower().removeprefix("the ") != named[0].text.lower() or len(named) > 1:
            return text
        kept = _tasks_of(m.group(2), lexicon)
        if kept is None:
            return m.group(2)  # refused either way; its refusal may list readings
        if not kept or any(t[2] in {r.id for r in named[0].refs} for t in kept):
            return text
        return m.group(2)
    return text


def _confirmed(text: str, lexicon: Lexicon) -> str:
    """'Give the bottle to Person B, wait, Person A, yes Person A': the correction said again
    after 'yes' confirms it; 'Knife to Lena, oops, I meant tongs to Lena': a correction that is
    a whole task (an object and where it goes) after a request of one task replaces it."""
    text = _sub(
        r"(\b(?:wait|no|sorry|oops|actually|i mean|i meant|hang on|hold on),?\s+([\w ]+?)),?\s+"
        r"(?:yes|yeah|yep|yup)\b,?\s+\2(?=\s*[.!]?\s*$)",
        r"\1",
        text,
    )
    m = re.match(
        r"^(.+?),?\s+(?:(?:oops|whoops|sorry|no|wait),?\s+)+i (?:meant|mean)\s+(.+?)"
        r"\s*[.!]?$",
        text.strip(),
        _F,
    )
    if m is None:
        return text
    before, after = m.group(1), m.group(2)
    old = _tasks_of(before, lexicon)
    new = _tasks_of(after, lexicon)
    said = _names(after, lexicon)
    if (
        old is None
        or new is None
        or len(old) != 1
        or len(new) != 1
        or not any(r.kind == "object" for it in said for r in it.refs)
        or not any(r.kind != "object" for it in said for r in it.refs)
    ):
        return text
    return after


def _chance(text: str, _lexicon: Lexicon) -> str:
    """'Any chance Lena could get the knife?': a request asked as a chance, when a modal follows
    the person ('Any chance Lena has the knife?' asks whether she has it: left alone)."""
    return _sub(
        r"(^|(?<=[.;!?])\s*)(?:(?:so|and|hey|hi),?\s+)*(?:is there )?any (?:chance|way|possibility)"
        r"(?: at all)?,? (?:that )?(?=(?:[\w ]+? )?(?:could|can|might|may|would|will)\b)",
        r"\1",
        text,
    )


# -- session 14: more of what a request carries, and frames read as their plain forms ------------
#
# As in session 13, each rewrite below takes off a listed class of words (only where they name
# nothing in the scene and hold no negation, quantifier, number, 'or' or order word), or rewrites a
# frame into the plain form the grammar reads, which then decides (a count, a name or a place the
# scene lacks is refused there).

# words no inert stretch may hold: they could name, count, choose, negate, order, delay, correct
# or point back at a task, or make the speaker a recipient
_HELD = re.compile(
    r"\b(?:no|not|never|nobody|none|nothing|nor|neither|without|except|but|rather|instead|only|"
    r"just|all|every|each|both|any|some|either|or|whichever|whatever|whoever|one|ones|two|three|"
    r"four|five|six|first|last|then|next|finally|before|after|once|when|until|till|if|unless|"
    r"later|tomorrow|wait|hang|hold|actually|sorry|oops|mean|meant|mistake|scratch|forget|cancel|"
    r"stop|swap|switch|other|another|else|rest|it|them|they|this|that|these|those|there|here|me|"
    r"my|mine|i|we|us|our|to|for|on|in|into|onto|at|with|from|by|near|next|under|off|out|"
    r"give|hand|pass|bring|take|put|place|get|have|want|need|keep|leave|move|send)\b|n't\b|\d",
    _F,
)


def _inert(words: str, lexicon: Lexicon) -> bool:
    """Whether ``words`` can change nothing of who gets what: it names nothing in the scene (nor
    by a typo) and holds no word of ``_HELD``."""
    return not _HELD.search(words) and _names_nothing(words, lexicon)


# the hearer addressed as a group ("y'all", "you guys", "yous", "ye"): 'you'
_HEARERS = (
    # (before a verb of the request, 'mind', a modal or a stop: "You guys is the bottle …?" is
    # not rewritten)
    (
        r"\b(?:y'?all|ya'?ll|you-all|youse|yous|you guys|you lot|you two)\b(?=\s*(?:[,.!:;]|$|"
        r"(?:mind|hand|pass|give|bring|put|take|pop|grab|get|fetch|be|please|could|can|would|w"
        r"ill|need|have|should|must|go|just)\b))",
        "you",
    ),
    (r"\bye\b(?=\s+(?:mind|hand|pass|give|bring|put|take|pop|grab|get|fetch|be|please)\b)", "you"),
    (r"\b(could|would|can|will|do|did|have|are|were) ye\b", r"\1 you"),
    (
        r"\byou all\b(?=\s*(?:[,.!:;]|$|(?:mind|hand|pass|give|bring|put|take|pop|grab|get|fetch|"
        r"please|could|can|would|will|need|have|should|must|just)\b))",
        "you",
    ),
)
# apostrophes left out ("thats it", "isnt"): the contraction ('its' and 'were' are words)
_UNAPOSTROPHED = {
    "thats": "that's",
    "whats": "what's",
    "theres": "there's",
    "isnt": "isn't",
    "doesnt": "doesn't",
    "didnt": "didn't",
    "wouldnt": "wouldn't",
    "couldnt": "couldn't",
    "shouldnt": "shouldn't",
    "youre": "you're",
    "theyre": "they're",
    "hasnt": "hasn't",
    "havent": "haven't",
    "arent": "aren't",
    "wasnt": "wasn't",
    "shes": "she's",
    "hes": "he's",
    # session 28 (blind26's lower case: 'im on the perfume stall till five', 'im off to the
    # hatters'): none of these is an English word without its apostrophe
    "im": "I'm",
    "ive": "I've",
    "dont": "don't",
    "werent": "weren't",
    "youve": "you've",
    "weve": "we've",
    "theyve": "they've",
    "youll": "you'll",
    "theyll": "they'll",
    # session 55 (12c's fuzz: 'i cant remember which', 'he wont mind'): an English 'cant' / 'wont'
    # is not said to a robot
    "cant": "can't",
    "wont": "won't",
    "mustnt": "mustn't",
    "neednt": "needn't",
    "hadnt": "hadn't",
}


def apostrophes(text: str) -> str:
    """'thats' typed for "that's", 'isnt' for "isn't" …: the contraction (read so from the
    start: 'after thats it' is not 'after that')."""
    return _sub(
        rf"\b({'|'.join(_UNAPOSTROPHED)})\b", lambda m: _UNAPOSTROPHED[m.group(1).lower()], text
    )


_ORDER_COLON = re.compile(
    r"(^|(?<=[.!?;])\s*)(then|next|after that|afterwards|finally|last|lastly|first|second|third|"
    r"first things first)\s*:\s*",
    _F,
)


def order_colons(text: str) -> str:
    """'First: X. Then: Y. Last: Z.': an order word before a colon orders (as 'Then, Y'), it is
    no header of a list (read so from the start: 'Then: Y' was read as 'and Y')."""
    return _ORDER_COLON.sub(r"\1\2, ", text) if ":" in text else text


def _base(stem: str) -> str:
    """'hand' from 'handing', 'put' from 'putt(ing)', 'pass' from 'pass(ing)', 'giv' → 'give'."""
    low = stem.lower()
    if len(low) > 2 and low[-1] == low[-2] and low[-1] not in "ls":
        return stem[:-1]  # putting, popping, dropping
    if low in ("giv", "tak", "plac", "mov", "leav", "serv", "us", "shar", "mak"):
        return stem + "e"
    return stem


def _spoken(text: str, lexicon: Lexicon) -> str:
    """How people speak to the robots: the hearer said as a group ("Y'all mind …", "Could ye
    hand …", "you guys"), which is 'you'; "(do) you mind handing"."""
    for pattern, repl in _HEARERS:
        text = _sub(pattern, repl, text)
    # "(do) you mind handing …", "you mind putting …": asked as a favour
    return _sub(
        r"(^|(?<=[.;!?,])\s*)(?:(?:hey|hi|so|oh|ok|okay),?\s+)*(?:(?:do|would) )?you mind ("
        r"\w+)ing\b",
        lambda m: f"{m.group(1)}{_base(m.group(2))}",
        text,
    )


_COURTESY14: tuple[tuple[str, str], ...] = (
    # "If it's not a bother, …", "if it isn't too much trouble", "if it's no problem": asked
    # kindly, not a condition on the task
    (
        r"(^|(?<=[.;!?,])\s*|\s+)if (?:it's|it is|that's|that is|it isn't|it is not|it wouldn't be|"
        r"it would not be|it's not|that's not|that isn't) (?:not )?(?:too much |much |a |any |no |"
        r"of )*(?:bother|trouble|problem|hassle|inconvenience|imposition|fuss|pain)(?: for you| to"
        r" you| at all)?\b\s*[,.]?\s*",
        r"\1",
    ),
    (r"(^|(?<=[.;!?,])\s*|\s+)if (?:it's|it is) not too much to ask\b\s*[,.]?\s*", r"\1"),
    # "… if it's going / free / spare": if it can be had, which the task needs anyway
    (
        r",?\s+if (?:it's|it is|they're|they are|there's one|there is one) (?:still )?(?:going|fre"
        r"e|spare|available|about|around|handy|to hand|not (?:being )?used|not in use)\b",
        "",
    ),
    # "So sorry to interrupt, …", "Sorry to be a pain, but …": an apology for asking
    (
        r"(^|(?<=[.;!?])\s*)(?:(?:hi|hello|hey|oh),?\s+)?(?:(?:i'm|i am) )?(?:so |really |very |ter"
        r"ribly |awfully |ever so |truly )*sorry (?:to (?:bother|interrupt|trouble|disturb|pester|"
        r"hassle|ask|nag|be (?:a |such a )?(?:pain|nuisance|bother|pest))(?: you)?(?: again)?(?: "
        r"all)?|for (?:the )?(?:bother|interrupting|interruption|bothering you|troubling you|askin"
        r"g))\b\s*(?:[,.!]+\s*(?:but\b)?|\s+but\b)?\s*",
        r"\1",
    ),
    # "…, there's a good robot"
    (
        r",\s*there's a (?:good |clever |lovely |smashing )?(?:robot|lad|girl|boy|chap|fella|one)"
        r"(?=\s*(?:[.!]|$))",
        "",
    ),
    # "…, that'd be grand", "it'd be a great help": praise of the deed, said after it
    (
        r",?\s*\b(?:that|it|this)(?:\s+would|'d|\s+will|'ll) be (?:just |really |so |absolutely |a"
        r" )?(?:grand|ace|magic|class|champion|smashing|sound|deadly|cracking|tops|terrific|tremen"
        r"dous|marvellous|marvelous|splendid|sweet|nice|good|cool|fab|fabulous|excellent|superb|"
        r"stellar|kind|very kind|so kind|(?:a |such a )?(?:great |big |huge |real )?(?:help|life"
        r"saver|godsend))\b",
        "",
    ),
    # "Bless you.", "…, bless you", "God bless."
    (r",?\s*\b(?:god )?bless (?:you|ya|ye|your (?:heart|cotton socks))\b", ""),
    (r"(^|(?<=[.;!?])\s*)god bless\b[.!]*", r"\1"),
    # "Appreciate you.", "Appreciate ya"
    (r"(^|(?<=[.;!?])\s*|,\s*)(?:i |really )*appreciate (?:you|ya|ye|it|that)\b[.!]*", r"\1"),
    # "Listen, …", "ok listen the tape goes …", "Right, listen up: …": said to be heard
    (
        r"(^|(?<=[.;!?])\s*)(?:(?:ok|okay|right|so|now|alright|hey|oh)[,]?\s+)*(?:listen|look)(?: "
        r"up| here| now)?(?:\s*[,:!.-]+\s*|\s+(?=(?:the|a|an|could|can|would|will|please|give|hand"
        r"|pass|bring|put|take|pop|grab|fetch|ok|so|just)\b))",
        r"\1",
    ),
)
# "Oh you're a lifesaver, …", "…, you're a star": what the speaker says of the hearer, before or
# after the request (inert only: naming nothing, holding no word of _HELD)
_PRAISE = (
    r"(^|(?<=[.;!?])\s*)(?:(?:oh|aw|ah|ooh),?\s+)?(?:you're|you are|ur|you really are|what) (?:"
    r"such |an? |the |my |absolute |total |real |proper |complete |little |true |utter )*[a-z-]+"
    r"(?:\s+[a-z-]+)?\s*[,.!]+\s*",
    r"(),\s*(?:you're|you are|ur|you really are|what) (?:such |an? |the |my |absolute |total |re"
    r"al |proper |complete |little |true |utter )*[a-z-]+(?:\s+[a-z-]+)?(?=\s*(?:[.!]|$))",
)
# a trailing stretch of address, praise or thanks ("…, nice one", "…, good man", "…, cheers
# mate", "…, ta love", "…, thanks pet"): every word from these lists, naming nothing
_ADDRESS = frozenset(
    {
        *("pet", "love", "luv", "hen", "duck", "ducky", "chuck", "petal", "flower", "sweetie"),
        *("sweetheart", "honey", "hun", "hon", "babe", "boss", "chief", "guv", "mate", "pal"),
        *("buddy", "bud", "dude", "man", "lad", "lass", "girl", "boy", "son", "sir", "madam"),
        *("ma'am", "folks", "guys", "everyone", "team", "fella", "bro", "mister", "sunshine"),
        *("dear", "dearie", "darling", "chap", "champ", "friend", "my", "old", "young", "robot"),
        *("nice", "good", "great", "top", "cracking", "champion", "magic", "wicked", "sound"),
        *("class", "beaut", "legend", "star", "gem", "hero", "ace", "brill", "brilliant", "one"),
        *("job", "work", "well", "done", "lovely", "cheers", "ta", "thanks", "thank", "you"),
        *("thx", "ty", "much", "so", "very", "a", "lot", "again", "sweet", "awesome", "perfect"),
        *("grand", "super", "fab", "smashing", "amazing", "cool", "that's", "it", "the", "best"),
        *("bless", "ya", "always", "as", "mate's", "yeah", "right", "ok", "okay"),
        # session 39 (12): "…, bonny lad", "…, bonny lass"
        "bonny",
    }
)


# words of _ADDRESS that said first may begin the request itself ("Right, …" is a filler anyway)
_NOT_ADDRESS = frozenset({"one", "it", "the", "a", "that's", "so", "very", "much", "lot", "as"})
_NICE_ONE = r"(?:(?:oh|cheers|thanks|ta),?\s+)?(?:nice|good|great) one"


def _courtesy14(text: str, lexicon: Lexicon) -> str:
    """Courtesy of the kinds blind12 showed, each a class: 'if it's no bother' and 'if it's
    going' (asked kindly), 'sorry to interrupt' (an apology, not a correction), praise of the
    hearer ('you're a lifesaver'), 'bless you', 'appreciate you', 'listen', and a last stretch
    of address or praise after a comma ('nice one', 'good man', 'thanks pet'). Taken off only
    where it names nothing in the scene."""
    for pattern, repl in _COURTESY14:
        text = _drop(pattern, text, lexicon, repl)
    for pattern in _PRAISE:
        text = _sub(
            pattern, lambda m: m.group(1) if _inert(m.group(0), lexicon) else m.group(0), text
        )
    # "Love, the water jug for Mrs Khan": a word of address said first
    m = re.match(
        r"^(?:(?:oh|hi|hey|hello|ok|okay|right),?\s+)?([a-z']+(?: [a-z']+)?)\s*,\s*", text, _F
    )
    if m is not None and m.end() < len(text):
        words = m.group(1).lower().split()
        if all(w in _ADDRESS and w not in _NOT_ADDRESS for w in words) and _names_nothing(
            m.group(1), lexicon
        ):
            text = text[m.end() :]
    m = re.search(r",\s*([a-z' ]+?)\s*([.!]*)\s*$", text, _F)
    if m is not None and text[: m.start()].strip():
        words = m.group(1).lower().split()
        # 'one' only in 'nice one' / 'good one'; 'it' only in "that's it" (closings)
        plain = [w for w in words if w not in ("one", "it")]
        if (
            0 < len(words) <= 4
            and all(w in _ADDRESS for w in words)
            and ("one" not in words or re.fullmatch(_NICE_ONE, m.group(1), _F) is not None)
            and ("it" not in words or re.search(r"\bthat's it$", m.group(1), _F))
            and plain
            # "…, sorry, the.": a determiner last is a word cut off, not address
            and words[-1] not in ("the", "a", "my")
            and _names_nothing(m.group(1), lexicon)
        ):
            text = text[: m.start()] + m.group(2)
    return text


# a sentence only of the speaker saying it is them again ("Sorry, me again.", "It's me again!",
# "Only me!"): it asks nothing
_ME_AGAIN = re.compile(
    r"^(?:(?:sorry|hi|hello|hey|oh|ok|okay|yes|right|so),?\s+)*(?:it's |it is |its )?(?:only |jus"
    r"t )?me(?: again)?(?:,?\s+(?:sorry|again|hi|hello))*\s*[.!]+$",
    _F,
)


def _me_again(text: str, _lexicon: Lexicon) -> str:
    """'Sorry, me again. Could Person A get …': a first sentence of the speaker saying it is
    them asks nothing (its 'me' is not a recipient)."""
    sentences = re.split(r"(?<=[.!])\s+", text.strip(), maxsplit=1)
    if len(sentences) == 2 and _ME_AGAIN.match(sentences[0]):
        return sentences[1]
    return text


def _after(text: str, lexicon: Lexicon) -> str:
    """ "Mr Lee's after his tablets", 'Jess is after the torch': a person 'after' an object
    wants it (only a person said before it, and an object phrase after it)."""
    m = re.match(
        r"^(.+?)(?:'s| is) (?:still |really |just |only )?after ((?:his|her|their|the|a|an|some|"
        r"both|any) .+)$",
        text.strip(),
        _F,
    )
    if m is None or not _only(m.group(1), lexicon, "human"):
        return text
    return f"{m.group(1)} wants {m.group(2)}"


_PLACED = (
    r"put|placed|loaded|moved|set|stacked|popped|dropped|stored|stood|laid|kept|parked|shifted|"
    r"carried|taken|brought"
)


def _wanted_placed(text: str, lexicon: Lexicon) -> str:
    """'Tom needs the medium box loaded onto the pallet', 'Dana wants the bowl put in the sink':
    a person wanting an object placed wants the placement (the grammar then reads 'put … on
    …', refusing a person or a name the scene lacks there)."""
    m = re.match(
        r"^(.+?) (?:needs|wants|would like|'d like|would love|'d love|could use|asked for|has asked"
        rf" for) ((?:the|a|an|both|all|his|her|their) .+?) (?:{_PLACED})(?: back| down| up| over|"
        r" away)? (on|onto|in|into|on top of|inside|at) (.+)$",
        text.strip(),
        _F,
    )
    if m is None or not _only(m.group(1), lexicon, "human"):
        return text
    # one list of objects, then one surface and nothing more (a comma or 'then' in the list may
    # end the want before the participle's object: left to the grammar, which refuses it)
    if _ids(m.group(2), lexicon, "human") or re.search(r",|\bthen\b", m.group(2), _F):
        return text
    where = m.group(4).rstrip(" .!")
    if not _only(where, lexicon, "surface"):
        return text
    return f"put {m.group(2)} {m.group(3)} {where}"


def placed_list32l(text: str, lexicon: Lexicon) -> str:
    """Session 32 (lead): 'Tom needs the packing tape and the medium box loaded onto the pallet'
    rewritten as _wanted_placed does, before the instruction is first read, when the wanted
    objects are a list: the grammar alone had read it as 'needs the tape' and 'the box loaded
    onto the pallet' (tape>B & box_medium@pallet), one reading of two, where the participle is
    said of the whole list (12c's repairs fuzz, 'and, um, the medium box')."""
    if not re.search(r"\band\b", text, _F):
        return text
    repaired = _rx(
        r"^(?P<want>.+? (?:needs|wants|would like|'d like|would love|'d love|could use)) "
        r"(?P<said>(?:the|a|an) [^,]+?),\s*(?:(?:er|um|uh),\s*)?(?:i mean|sorry|no,? sorry|no)"
        r"\s*,?\s*(?P<meant>(?:the|a|an) [^,]+?(?:, (?:the|a|an) [^,]+?)* and (?:the|a|an) [^,]+? "
        rf"(?:{_PLACED})\b[^,]*)$"
    ).match(text.strip())
    if repaired is not None and _only_kind(repaired["said"], lexicon, "object"):
        # "Mrs Khan wants the medication, I mean the magazine and the jug placed on the bedside
        # table": the repair names what is wanted placed; the first name is taken back
        return _wanted_placed(f"{repaired['want']} {repaired['meant']}", lexicon)
    out = _wanted_placed(text, lexicon)
    return out if out != text and re.search(r"\band\b", out, _F) else text


def _they_one(text: str, lexicon: Lexicon) -> str:
    """'Person B gets the chips, and when they've got them, Person A gets the bottle': 'they'
    for the one person named before the condition."""
    m = re.search(
        r"\b(when|once|after|as soon as) they(?:'ve| have)?(?: (?:got|received|had|gotten)| have|"
        r" get| has)\b",
        text,
        _F,
    )
    if m is None:
        return text
    who = one_person(text[: m.start()], lexicon)
    if who is None:
        return text
    said = re.sub(r"\bthey(?:'ve| have)?", f"{who} has", m.group(0), count=1, flags=_F)
    said = re.sub(r"\bhas (?:have|get|has)\b", "has", said, flags=_F)
    return text[: m.start()] + said + text[m.end() :]


def _kind_of(word: str, lexicon: Lexicon) -> str | None:
    """The category a plural or singular kind word names ('books' → 'book'), else None."""
    low = word.lower()
    cats = {o.category.lower() for o in lexicon.scene.objects}
    for cat in cats:
        if low in (cat, cat + "s", cat + "es"):
            return cat
    return None


def _header_stop(text: str, lexicon: Lexicon) -> str:
    """'Books. Red one to Noah. Green one to Zoe.': a kind said alone as a first sentence heads
    the notes after it, as 'Books: red one to Noah, green one to Zoe' (each note must begin with
    '(the) <word> one')."""
    m = re.match(r"^(\w+)\s*[.!]\s+(.+?)[.!]?$", text.strip())
    if m is None or _kind_of(m.group(1), lexicon) is None:
        return text
    notes = [x.strip() for x in re.split(r"(?<=[.;!])\s+|,\s*(?:and\s+)?", m.group(2)) if x.strip()]
    if len(notes) < 2 or not all(re.match(r"^(?:the )?\w+ one\b", x, _F) for x in notes):
        return text
    return f"{m.group(1)}: " + ", ".join(x.rstrip(".;!") for x in notes)


def _given_nothing(text: str, lexicon: Lexicon) -> str:
    """'Mrs Khan, the magazine. Mr Lee, nothing.': 'P, nothing' as the note 'P: nothing' (the
    notes mechanism drops it when nothing else names P)."""
    return _sub(
        r"(^|(?<=[.;!?])\s*)([^,.;!?:]+?),\s*(?:gets |wants |needs )?nothing\b(?=\s*(?:[.;!?]|$))",
        lambda m: (
            f"{m.group(1)}{m.group(2)}: nothing"
            if _only(m.group(2), lexicon, "human")
            else m.group(0)
        ),
        text,
    )


_HANDY = (
    r"nearer|closer|nearest|closest|handiest|handier|easiest|easier|quickest|quicker|easiest to "
    r"reach|easier to reach|nearest to hand|closest to hand|within reach|to hand"
)


def _handy(text: str, lexicon: Lexicon) -> str:
    """'Give Dana whichever cup is nearer', 'Whatever pen's closest, give it to Priya': near to
    nothing said, it is the robots' pick of any of that kind ('a cup'); 'nearer to her' is left
    to the grammar (the one nearest her)."""
    m = re.match(
        rf"^(?:whichever|whatever) ([a-z]+(?: [a-z]+)?)(?: is|'s) (?:the )?(?:{_HANDY})(?: one)?\s*"
        r",\s*(?:(?:please|just|can you|could you)\s+)?(give|hand|pass|bring|put|place|take|send|"
        r"pop|chuck|get) (?:it|that(?: one)?)\b(?!\s+(?:to|than|from)\s+(?:it|that)\b)(.*)$",
        text.strip(),
        _F,
    )
    if m is not None:
        return f"{m.group(2)} a {m.group(1)}{m.group(3)}"
    return _sub(
        rf"\b(?:whichever|whatever) ([a-z]+(?: [a-z]+)?)(?: is|'s) (?:the )?(?:{_HANDY})(?: one)?"
        r"\b(?!\s+(?:to|than|from|for|of)\b)",
        r"a \1",
        text,
    )


def _one_each(text: str, _lexicon: Lexicon) -> str:
    """'Both patients need a blanket, one each': 'need a blanket each' (the grammar then gives
    each of them a different one, or refuses)."""
    return _sub(
        r"\b(need|want|get|would like|should get|could use|can have|can take)(s?) (a|an) ([a-z]+"
        r"(?: [a-z]+)?),\s*(?:so\s+)?one each\b",
        r"\1\2 \3 \4 each",
        text,
    )


def _either_one(text: str, lexicon: Lexicon) -> str:
    """'Noah or Zoe, either one can have the globe': 'Noah or Zoe can have the globe'."""
    m = re.match(
        r"^(.+?) or (.+?),\s*(?:either|any|whichever|whoever)(?: one| of them| of the two| of "
        r"you)?,?\s+(can|could|may|should|gets?|wants?)\b(.*)$",
        text.strip(),
        _F,
    )
    if m is None or not (
        _only(m.group(1), lexicon, "human") and _only(m.group(2), lexicon, "human")
    ):
        return text
    return f"{m.group(1)} or {m.group(2)} {m.group(3)}{m.group(4)}"


def _listed(text: str, lexicon: Lexicon) -> str:
    """'Bob should get both of them, the bottle and the crisps': the list said after 'both of
    them' (or 'all N of them', 'these') is what they are, when it names that many objects and
    only objects; '…, both of them' after a plural that names that many restates it."""
    m = re.search(
        r"\b(both|all (?:two|three|four|five|six)|all|these|those)(?: of (?:them|these|those))?"
        r"\s*[,:]\s*((?:the |a |an )?[^,.;!?]+?(?:,\s*(?:and\s+)?|\s+and\s+)(?:the |a |an )?[^"
        r".;!?]+?)\s*([.!]?)$",
        text,
        _F,
    )
    if m is not None and re.search(
        r"\bof (?:them|these|those)\b|\b(?:these|those)\b", m.group(0), _F
    ):
        listed = m.group(2)
        parts = [x for x in re.split(r",\s*(?:and\s+)?|\s+and\s+", listed) if x.strip()]
        count = _COUNTS.get(
            m.group(1).lower().split()[-1], 2 if m.group(1).lower() == "both" else 0
        )
        ok = all(_only(x.strip(), lexicon, "object") for x in parts)
        ids = _ids(listed, lexicon, "object")
        if ok and len(ids) == len(parts) and (not count or count == len(parts)):
            before = text[: m.start()].rstrip(" ,")
            return f"{before} {' and '.join(x.strip() for x in parts)}{m.group(3)}"
        return text
    # "Put both of them in the sink, the bowl and the spoon": the list at the end is 'them'
    m = re.search(
        r"\b(?:both|all (?:two|three|four|five|six)) of (?:them|these|those)\b([^,.;!?]*),\s*((?:"
        r"the |a |an )?[^,.;!?]+?(?:,\s*(?:and\s+)?|\s+and\s+)(?:the |a |an )?[^.;!?]+?)\s*([.!]"
        r"?)$",
        text,
        _F,
    )
    if m is not None:
        parts = [x.strip() for x in re.split(r",\s*(?:and\s+)?|\s+and\s+", m.group(2)) if x.strip()]
        word = m.group(0).lower().split()
        count = 2 if word[0] == "both" else _COUNTS[word[1]]
        ids = _ids(m.group(2), lexicon, "object")
        if all(_only(x, lexicon, "object") for x in parts) and len(ids) == len(parts) == count:
            return f"{text[: m.start()]}{' and '.join(parts)}{m.group(1)}{m.group(3)}"
        return text
    # "Put the pens in the box, all three of them", "The spanners go on the bench, both of them":
    # a count said after the one plural of the sentence, which must be right
    m = re.search(
        r",\s*(?:all (two|three|four|five|six)|(both)|(all)) of (?:them|these|those)\s*([.!]?)$",
        text,
        _F,
    )
    if m is None:
        return text
    plurals = [
        w
        for w in re.findall(r"[a-z]+", text[: m.start()].lower())
        if (cat := _kind_of(w, lexicon)) is not None and w != cat
    ]
    if len(plurals) != 1:
        return text
    cat = _kind_of(plurals[0], lexicon) or ""
    n = sum(1 for o in lexicon.scene.objects if o.category.lower() == cat)
    said = _COUNTS[m.group(1).lower()] if m.group(1) else 2 if m.group(2) else n
    if said != n:
        return text
    return text[: m.start()] + m.group(4)


_NUMBER = {"1": "one", "2": "two", "3": "three", "4": "four", "5": "five", "6": "six"}


def _all_counted(text: str, lexicon: Lexicon) -> str:
    """ "Priya's taking all 3 pens": 'Priya takes the three pens' (the grammar checks the count
    against the scene); 'P is taking X' is P's, unless it goes 'to' someone or somewhere."""
    text = _sub(
        r"\ball (?:of )?(?:the )?([1-6]|two|three|four|five|six) (?=[a-z]+s\b)",
        lambda m: f"the {_NUMBER.get(m.group(1), m.group(1))} ",
        text,
    )
    m = re.match(
        r"^(.+?)(?:'s| is) taking ((?:the|a|an|both|all) [^,.;!?]+?)\s*([.!]?)$", text.strip(), _F
    )
    if (
        m is not None
        and _only(m.group(1), lexicon, "human")
        and not re.search(r"\b(?:to|on|in|into|onto|over|across|for)\b", m.group(2), _F)
    ):
        return f"{m.group(1)} takes {m.group(2)}{m.group(3)}"
    return text


def _just_one(text: str, lexicon: Lexicon) -> str:
    """'Just the one cup for Omar, the green one': the green cup for Omar; 'Only the one plate for
    Lena' alone is one plate for her (any)."""
    m = re.match(
        r"^(?:just|only) (?:the )?one ([a-z]+) ([^,.;!?]+?),\s*the ([a-z]+)(?: one)?\b(.*)$",
        text.strip(),
        _F,
    )
    if m is not None:
        cat = _kind_of(m.group(1), lexicon)
        if cat is None or cat != m.group(1).lower():
            return text
        return f"the {m.group(3)} {m.group(1)} {m.group(2)}{m.group(4)}"
    m = re.match(r"^(?:just|only) (?:the )?one ([a-z]+)\b(?!,)(.*)$", text.strip(), _F)
    if m is not None and _kind_of(m.group(1), lexicon) == m.group(1).lower():
        return f"a {m.group(1)}{m.group(2)}"
    return text


def _counted_list(text: str, lexicon: Lexicon) -> str:
    """'Two boxes for Mia, the small and the medium': the boxes named by the adjectives after,
    when there are as many as counted ('the small box and the medium box for Mia'); 'Give each
    of the three people one thing: …' is the list, as 'The three people each get one thing'."""
    m = re.match(
        r"^(?:give )?each of (?:the |them |these |those )?(?:(two|three|four|five|six) )?(?:people"
        r"|persons|of them|of you)?,?\s*(?:gets? |wants? |needs? |should get |can have )?(?:one "
        r"thing|something|an item|one item|a thing)(?: each)?\s*:\s*(.+)$",
        text.strip(),
        _F,
    )
    if m is not None:
        count = m.group(1) or ""
        said = f"the {count} people each get one thing: {m.group(2)}" if count else m.group(2)
        return _counted(said, lexicon) if count else text
    m = re.match(
        r"^(two|three|four|five|six|[2-6]) ([a-z]+) ((?:for|to|in|on|into|onto) [^,]+?),\s*(.+?)"
        r"\s*([.!]?)$",
        text.strip(),
        _F,
    )
    if m is None:
        return text
    cat = _kind_of(m.group(2), lexicon)
    if cat is None or m.group(2).lower() == cat:
        return text
    adjs = [
        re.sub(r"^(?:the|both the)\s+|\s+ones?$", "", x.strip(), flags=_F)
        for x in re.split(r",\s*(?:and\s+)?|\s+and\s+", m.group(4))
        if x.strip()
    ]
    n = _COUNTS[_NUMBER.get(m.group(1), m.group(1)).lower()]
    if len(adjs) != n or not all(re.fullmatch(r"[a-z]+", a, _F) for a in adjs):
        return text
    named = [f"the {a} {cat}" for a in adjs]
    if not all(_only(x, lexicon, "object") for x in named):
        return text
    if len({next(iter(_ids(x, lexicon))) for x in named}) != n:
        return text
    return f"{' and '.join(named)} {m.group(3)}{m.group(5)}"


def _excluded_count(text: str, lexicon: Lexicon) -> str:
    """'Apart from the two plates, everything goes on the counter': a count in what is left out
    says how many of that kind there are; said rightly it is taken off ('the plates'), else
    the text is left (and refused)."""
    m = re.match(
        r"^(except(?: for)?|apart from|other than|besides|aside from)\s+(?:the |all )?(two|three|"
        r"four|five|six|both) ([a-z]+)\b",
        text.strip(),
        _F,
    )
    if m is None:
        return text
    cat = _kind_of(m.group(3), lexicon)
    if cat is None or m.group(3).lower() == cat:
        return text
    n = sum(1 for o in lexicon.scene.objects if o.category.lower() == cat)
    said = 2 if m.group(2).lower() == "both" else _COUNTS[m.group(2).lower()]
    if said != n:
        return text
    word = "except" if m.group(1).lower() in ("besides", "aside from") else m.group(1)
    return f"{word} the {m.group(3)}" + text.strip()[m.end() :]


def _rather(text: str, lexicon: Lexicon) -> str:
    """'Give Carol the cup rather than the bottle', 'Hand Jess the torch instead of the drill',
    'Put the bowl in the sink rather than on the tray': what is not wanted, said after the
    request. The request is read alone: an object or surface it does not use is taken off;
    one it chooses among is left out of the choice (as '…, not the bottle'); one it uses
    otherwise is a contradiction (left, so refused)."""
    m = re.search(r",?\s+(?:rather than|instead of)\s+(.+?)\s*([.!]?)$", text, _F)
    if m is None:
        return text
    head, said = text[: m.start()], m.group(1)
    place = re.match(r"^(?:on|onto|in|into|at) ((?:the )?[a-z ]+)$", said, _F)
    kind = "surface" if place is not None else "object"
    words = place.group(1) if place is not None else said
    if not _only_kind(words, lexicon, kind):
        return text
    # why: offline.py imports this module, so the grammar is imported where it is used
    from hltl.grounding.offline import parse_instruction

    try:
        node = parse_instruction(head, lexicon.scene, lexicon)
    except GroundingError:
        return text
    found = list(tasks(node))
    named = _ids(words, lexicon, kind)
    used = {t.target if kind == "surface" else t.obj for t in found}
    if not found or (kind == "surface" and any(t.kind != "place" for t in found)):
        return text
    if not used & named:
        return head + m.group(2)
    if kind == "object" and isinstance(node, Group) and node.op == "or" and used - named:
        return f"{head}, not {said}{m.group(2)}"
    return text


_BETTER = (
    r"(?:'s|\s+is|\s+would be|\s+'d be|\s+will be|\s+might be|\s+may be|\s+seems|\s+looks|"
    r"\s+sounds)(?: even| much| a lot| probably| definitely)? (?:better|best|nicer|safer|a better "
    r"(?:place|spot|bet|idea|choice|option)|the better (?:place|spot|bet|choice|option))\b"
)


def _better(text: str, lexicon: Lexicon) -> str:
    """'Spoon on the tray — hang on, the sink's better', 'Put the knife on the rack, actually the
    counter would be better': a correction that names the new place or person and says it is
    better is the correction '…, the sink'."""
    m = re.search(
        r"(\s*(?:—|–|-|,|\.|;)\s*(?:(?:no|hang on|hold on|wait|actually|hmm+|oh|on second thought|"
        r"sorry|scratch that|no wait)[,.!]?\s+)+)((?:the )?[a-z ]+?)" + _BETTER + r"\s*([.!]?)$",
        text,
        _F,
    )
    if m is None:
        return text
    name = m.group(2)
    if not (_only(name, lexicon, "surface") or _only(name, lexicon, "human")):
        return text
    return text[: m.start()] + m.group(1) + name + m.group(3)


def _my_mistake(text: str, lexicon: Lexicon) -> str:
    """ "Lemon's for Marco. Oh no, my mistake, it's for the guest.", "Give Zoe the glue stick. My
    bad, it's for Noah.": an admitted mistake followed by where it goes instead is the
    correction '…, no, the guest' (left alone when nothing follows: refused)."""
    m = re.search(
        r"\s*[.;,!]\s*(?:(?:oh|no|sorry|wait|oops|whoops|ah)[,!.]?\s+)*(?:my (?:mistake|bad|error|"
        r"fault)|i got (?:it|that) wrong|i made a mistake|wrong (?:person|one))[,.!]?\s+(?:it's|it "
        r"is|it should be|it should go|that's|that should be|it goes|they're|they are) (?:for|to|on"
        r"|in) (.+?)\s*([.!]?)$",
        text,
        _F,
    )
    if m is None:
        return text
    said = m.group(1)
    if not (_only(said, lexicon, "human") or _only(said, lexicon, "surface")):
        return text
    return f"{text[: m.start()]}, no, {said}{m.group(2)}"


def _i_mean_it(text: str, lexicon: Lexicon) -> str:
    """'The stapler goes to Sam, I mean it goes in the box', "The teddy's for Lily, I mean it's
    for Ava", 'Give Tom the gloves, I mean give them to Mia': a correction of where the one
    object said before it goes, as the grammar's '…, no, in the box' / '…, no, Ava'."""
    m = re.search(
        r",?\s*\b(?:i mean|i meant)\s*,?\s*(?:it's|it is|it goes|it should go|they go|they're|the"
        r"y are|(?:give|hand|pass|bring|take|send) (?:it|them)|(?:put|place|pop|leave) (?:it|them))"
        r" (to|for|on|in|into|onto) ((?:the )?[a-z ]+?)\s*([.!]?)$",
        text,
        _F,
    )
    if m is None:
        return text
    before = text[: m.start()]
    things = {r.id for it in _names(before, lexicon) for r in it.refs if r.kind == "object"}
    if len(things) != 1:
        return text
    said, to = m.group(2), m.group(1).lower()
    person = _only(said, lexicon, "human") and to in ("to", "for")
    surface = _only(said, lexicon, "surface") and to not in ("to", "for")
    if not person and not surface:
        return text
    before_kind = "human" if _ids(before, lexicon, "human") else "surface"
    if _ids(before, lexicon, "human") and _ids(before, lexicon, "surface"):
        return text
    if (person and before_kind == "human") or (surface and before_kind == "surface"):
        return f"{before}, no, {said}{m.group(3)}" if person else f"{before}, no, {to} {said}"
    obj = next(it.text for it in _names(before, lexicon) if it.refs[0].kind == "object")
    goes = f"to {said}" if person else f"{to} {said}"
    return f"{before}, I meant the {obj} goes {goes}{m.group(3)}"


# -- session 14, generalised: classes a new writer brings, probed across scenes --------------------

_SAID14: tuple[tuple[str, str], ...] = (
    # "Could you do me a favour and …": the favour is the request ('me' is not a recipient)
    (
        r"(^|(?<=[.;!?,])\s*)(?:(?:could|would|can|will) you |please )?do (?:me|us) a (?:(?:big|"
        r"quick|small|huge) )?(?:favou?r|kindness|solid)(?:\s+and\b|\s*[,:!.]|\s+please\b,?)\s*",
        r"\1",
    ),
    # "…, eh", "…, there you go", "… and Bob's your uncle", "…, that's the lot", "job done"
    (
        r",?\s*(?:\band\s+)?\b(?:there you go|there we go|there you are|bob's your uncle|that's th"
        r"e lot|that's your lot|that's the lot of them|job done|job's a good 'un|sorted|innit|eh|"
        r"right\?|ok\?|okay\?|alright\?|yeah\?|got it\?|understood\?|if i remember (?:right|"
        r"rightly|correctly)|(?:just )?like i said(?: before| earlier)?|as i said(?: before| earl"
        r"ier)?|as i mentioned)(?=\s*(?:[.!]|$))",
        "",
    ),
    (
        r"(^|(?<=[.;!?])\s*)(?:(?:just )?like i said(?: before| earlier)?|as i said(?: before| "
        r"earlier)?|as i mentioned(?: before| earlier)?)\s*,\s*",
        r"\1",
    ),
    # "…, bless her" at the end, with or without a comma
    (
        r",?\s+bless (?:him|her|them|'?em)(?:,? the (?:poor )?(?:thing|dear|love|lamb))?"
        r"(?=\s*(?:[.!]|$))",
        "",
    ),
    # "The plan is to give …", "What I need you to do is …": the task said as a plan
    (
        r"(^|(?<=[.;!?])\s*)(?:the (?:plan|idea|task|job|thing)|your (?:job|task)|what (?:i|we) "
        r"(?:need|want|'d like) you to do) (?:is|will be|for now is) (?:to |that you |just )?",
        r"\1",
    ),
    # "Alexa, …", "OK Google, …", "Hey Siri, …", "Computer, …": the device addressed
    (
        r"^(?:(?:ok|okay|hey|hi)\s+)?(?:alexa|google|siri|computer|robots?|cortana|assistant)"
        r"\s*[,!.:]\s*",
        "",
    ),
    # "Would you mind awfully passing …": how much the hearer might mind
    (r"\b(you mind) (?:awfully|terribly|very much|at all|too much)\b", r"\1"),
    # "Mrs Khan (bed 3) wants …", "Mrs Khan, bed 3, wants …": where a person is, in brackets
    # or after a comma (a bed, a room, a bay: a number of a place, not a count)
    (
        r"\s*\((?:in )?(?:bed|room|bay|seat|desk|table|station|row|cubicle|ward|chair) ?\w{1,4}\)",
        "",
    ),
    (
        r",\s*(?:in )?(?:bed|room|bay|seat|station|row|cubicle|chair) (?:\d{1,3}|one|two|three|"
        r"four|five|six)\s*,",
        " ",
    ),
    # "No worries, knife to Marco", "…, no dramas": set phrases of ease, not a negation
    (
        r"(^|(?<=[.;!?])\s*|,\s*)(?:no (?:worries|dramas|problem|probs|bother|biggie|sweat|stress"
        r")(?: at all)?(?: mate| love)?)(?:\s*[,.!]+\s*|\s*$)",
        r"\1",
    ),
    # "G'day", "Howay", "Ey up", "Wotcha": greetings
    (
        r"^(?:g'?day|howay|ey up|eh up|hey up|wotcha|watcha|oi|cooee|yo|aye|ahoy|howdy|hiya|sup|wa"
        r"ssup|now then|well then|right then|morning all|evening all|hello all|hi all)(?: (?:mate"
        r"|love|pet|folks|guys|all|there|dear))?\s*[,!.:]+\s*",
        "",
    ),
    # "Now, where was I? Oh yes, …", "What was it... ah, …": the speaker thinking aloud
    (
        r"^(?:(?:now|so|right|ok|okay|um+|er+m?|hmm+),?\s+)?(?:where was i|what was it|what else|w"
        r"hat was i saying|what did i want|let me think|let me see|let's see|what's next|now then)"
        r"\s*[?.!,…]+\s*(?:(?:oh|ah|ahh|yes|yeah|right|that's it|that's right)[,!.]*\s+)*",
        "",
    ),
    # session 34 (12s): "…, hang on, let me check my list, no, Person B …": thinking aloud before
    # a correction's cue (kept where no cue follows: 'let me check' alone is not taken off)
    (
        r",\s*let me (?:think|see|check|look)(?: (?:at )?(?:my|the) (?:list|notes|sheet|order))?"
        r"\s*,\s*(?=(?:no|sorry|actually)\b)",
        ", ",
    ),
    # "Reckon Lena wants the lemon", "I am asking you to put …"
    (r"^(?:i )?reckon,?\s+", ""),
    # (session 28: "I am requesting you to give …", "I'm kindly asking you to …")
    (
        r"(^|(?<=[.;!?])\s*)(?:i'm|i am|we're|we are) (?:kindly )?(?:asking|requesting) "
        r"(?:you )?(?:to )?(?=[a-z])",
        r"\1",
    ),
    # "Is possible to give …", "please to put", "must to have": said by someone learning English
    (r"^(?:is|would be|will be) (?:it )?possible (?:for you )?to (?=[a-z])", ""),
    (r"\bplease to\b", "please"),
    (r"\b(must|should|can|could) to (?=have|get|give|put|bring|take)\b", r"\1 "),
    # "Would you see Mrs Khan gets the jug", "see to it that …"
    (
        r"(?:\b(?:would|could|can|will) you )?(?:kindly |please )*\bsee (?:to it )?(?:that )?(?=(?:"
        r"the )?[a-z][\w ]*? (?:gets?|receives?|has)\b)",
        "make sure ",
    ),
    # "Give Priya the lot", "All of it to Priya bar the pens": everything (but)
    # (session 27: 'of' a word, so 'the lot off you' is everything too)
    (r"\bthe (?:whole )?lot\b(?! of\b)", "everything"),
    (r"^all of it\b", "everything"),
    (r"\b(everything|everything else)\s+bar\s+(?=the\b)", r"\1 except "),
    # "Any old pen for Sam": any pen
    (r"\bany old\b", "any"),
    # "Stapler in the box when you're done": when, with nothing after it
    (
        r",?\s+when (?:you're|you are|you've|you have) (?:done|finished|free|ready|got a (?:sec|m"
        r"inute|moment|mo))\s*([.!]?)\s*$",
        r"\1",
    ),
    # "right about now"
    (r"\s+(?:right )?about now\b(?=\s*(?:[.,;!?]|$))", ""),
    # dictated: "new line give Omar the spoon", "… new paragraph …"
    (r"(^|\s+)(?:new line|next line|new paragraph)\b\s*", r"\1. "),
)
_WANTS14: tuple[tuple[str, str], ...] = (
    # "Mrs Khan was wondering if she might have the water jug"
    (
        r"^((?:the )?[\w ]+?) (?:was|is|'s|were|are|has been) (?:just )?wondering (?:if|whether) "
        r"(?:he|she|they) (?:could|might|can|may) (?:have|get|borrow)\b",
        r"\1 would like",
    ),
    # "Mia could really do with the scanner": she would like it
    (r"\b(?:could|can) (?:really |certainly |definitely |probably |just )?do with\b", "would like"),
    # "Ruth will be wanting the thermometer", "Zoe would be wanting the green book"; session 36
    # (12s): with the space kept ("she'll be wanting" had become 'shewants')
    (r"(?:\s+(?:will|would)|'ll|'d) be wanting\b", " wants"),
    (r"(?:\s+(?:will|would)|'ll|'d) be needing\b", " needs"),
    # "Can I get the salt for Lena", "I'll have the salt for Lena": asked for someone else
    (
        r"^(?:(?:can|could|may) (?:i|we) (?:get|have|grab|please have|please get)|(?:i|we)'ll have"
        r"|(?:i|we)'d like|(?:i|we) would like)((?: the| a| an| some) [\w ]+?) for ((?:the )?[\w "
        r"]+?)(\s*,?\s*please)?\s*([.!?]?)$",
        r"give\1 to \2\3\4",
    ),
    # "Bob mentioned he'd like the cup", "Bob told me she wants …"
    (
        r"^((?:the )?[\w ]+?) (?:mentioned|was saying|has said|has mentioned|says|told (?:me|us)|"
        r"let (?:me|us) know|was telling (?:me|us)|reckons|thinks)(?: that)? (he|she|they)(?:'d| wo"
        r"uld) like\b",
        r"\1 would like",
    ),
    (
        r"^((?:the )?[\w ]+?) (?:mentioned|was saying|has said|has mentioned|says|told (?:me|us)|"
        r"let (?:me|us) know|was telling (?:me|us)|reckons|thinks)(?: that)? (?:he|she|they) (wants"
        r"|needs)\b",
        r"\1 \2",
    ),
    # "Bob ordered the cup", "Bob's order is the cup", "Bob's request: the cup", "Request from
    # Bob: the cup", "Order for Bob: one cup"
    (r"^((?:the )?[\w ]+?) (?:has )?(?:ordered|requested)\b", r"\1 wants"),
    (r"^((?:the )?[\w ]+?)'s (?:order|request)(?: is|:)\s*", r"\1 wants "),
    (r"^(?:request|order) (?:from|for) ((?:the )?[\w ]+?)\s*:\s*(?:one )?", r"\1 wants the "),
)


def _wanting_that(text: str, lexicon: Lexicon) -> str:
    """'Emma is wanting that you give her the white cup': the request she wants, her pronoun
    her (when the title fits)."""
    m = re.match(
        r"^((?:the )?[\w ]+?) (?:is wanting|wants|would like|would want|is asking|asks|asked) (?:t"
        r"hat )?you (?:to )?((?:give|hand|pass|bring|take|put|place|fetch)\b.*)$",
        text.strip(),
        _F,
    )
    if m is None or not _only(m.group(1), lexicon, "human"):
        return text
    who = next(iter(_ids(m.group(1), lexicon, "human")))
    if not _fits(who, m.group(2), lexicon):
        return text
    return _sub(r"\b(?:him|her)\b", m.group(1), m.group(2))


def _pronoun_said(text: str, lexicon: Lexicon) -> str:
    """'Give the jug to her, Mrs Khan I mean', 'Give her the jug - Mrs Khan': a person said after
    the request says who its one 'him'/'her' is (when the title fits and nobody else is named)."""
    m = re.match(
        r"^(.+?)(?:,\s*|\s+[-—–]+\s*|\s*\(\s*)((?:i mean |i meant |that's |that is |meaning )?"
        r"(?:the )?[\w ]+?)(?: i mean| i meant)?\s*\)?\s*([.!]?)$",
        text.strip(),
        _F,
    )
    if m is None:
        return text
    said = re.sub(r"^(?:i mean|i meant|that's|that is|meaning)\s+", "", m.group(2), flags=_F)
    if not _only(said, lexicon, "human"):
        return text
    head = m.group(1)
    pronouns = re.findall(r"\b(?:him|her|he|she)\b", head, _F)
    if len(pronouns) != 1 or _ids(head, lexicon, "human"):
        return text
    if not _fits(next(iter(_ids(said, lexicon, "human"))), head, lexicon):
        return text
    return _sub(r"\b(?:him|her|he|she)\b", said, head) + m.group(3)


def _a_kind_for(text: str, lexicon: Lexicon) -> str:
    """'A pen for Sam, any colour', 'One cup for Omar': a note giving one of a kind to a person,
    as 'give Sam a pen' (whatever is said after it is read with it)."""
    m = re.match(
        r"^(?:just |only )?(?:a|an|any|one) ([a-z]+) (?:for|to) ([^,.;!?]+?)(?=\s*(?:[,.;!]|$))"
        r"(.*)$",
        text.strip(),
        _F,
    )
    if m is None or not _only(m.group(2), lexicon, "human"):
        return text
    if _kind_of(m.group(1), lexicon) != m.group(1).lower():
        return text
    return f"give {m.group(2)} a {m.group(1)}{m.group(3)}"


def _possessed14(text: str, lexicon: Lexicon) -> str:
    """ "The cup is Bob's", "Carol, the apple is yours", "Per Bob's request, give him the cup":
    whose an object is said to be, as 'the cup is for Bob'."""
    m = re.match(r"^((?:the|that|this) [\w ]+?) (?:is|'s) ([\w ]+?)'s\s*([.!]?)$", text.strip(), _F)
    if (
        m is not None
        and _only(m.group(2), lexicon, "human")
        and _ids(m.group(1), lexicon, "object")
    ):
        return f"{m.group(1)} is for {m.group(2)}{m.group(3)}"
    m = re.match(
        r"^([\w ]+?),\s*((?:the|that|this) [\w ]+?) (?:is|are) yours\s*([.!]?)$", text.strip(), _F
    )
    if (
        m is not None
        and _only(m.group(1), lexicon, "human")
        and _ids(m.group(2), lexicon, "object")
    ):
        return f"{m.group(2)} is for {m.group(1)}{m.group(3)}"
    m = re.match(r"^(?:per|at|by|on) ([\w ]+?)'s request,?\s*(.+)$", text.strip(), _F)
    if (
        m is not None
        and _only(m.group(1), lexicon, "human")
        and _fits(next(iter(_ids(m.group(1), lexicon))), m.group(2), lexicon)
    ):
        return _sub(r"\b(?:him|her)\b", m.group(1), m.group(2))
    return text


def _said14(text: str, lexicon: Lexicon) -> str:
    """Ways people close, favour, hedge and dictate that session 14's probes showed ('do me a
    favour and', '…, eh', '… and Bob's your uncle', 'like I said', 'new line'), taken off where
    they name nothing. Session 56 (12p): the rest of what the step did is the steps after it in
    the normaliser (_said14_spaced56p, _wants14_56p, _a_kind_for, _wanting_that, _possessed14,
    _pronoun_said), in the same order, so that the step guard reads the word-gated ones."""
    for pattern, repl in _SAID14:
        text = _drop(pattern, text, lexicon, repl)
    return text


def _said14_spaced56p(text: str, _lexicon: Lexicon) -> str:
    """Session 56 (12p): _said14's text single-spaced, a full stop opening it taken off (as the
    step did after its rewrites)."""
    text = " ".join(text.split()).strip()
    return re.sub(r"^[.\s]+", "", text)


def _wants14_56p(text: str, lexicon: Lexicon) -> str:
    """Wants said another way ('could do with', 'will be wanting', 'Bob mentioned he'd like',
    'ordered', "Bob's request: …"), rewritten when their subject is one person of the scene
    (session 14's _said14; a step of its own since session 56)."""
    for pattern, repl in _WANTS14:
        m = re.search(pattern, text, _F)
        if m is None:
            continue
        if pattern.startswith("^((?:the )") and not _only(m.group(1), lexicon, "human"):
            continue
        if pattern.startswith("^(?:(?:can|could|may)") and not (
            _only(m.group(2), lexicon, "human")
            and _only_kind(m.group(1).strip(), lexicon, "object")
        ):
            continue
        text = text[: m.start()] + m.expand(repl) + text[m.end() :]
    return re.sub(r"\bwants the the\b", "wants the", text, flags=_F)


# -- remarks read by kind: a clause that is provably inert ----------------------------------------
#
# One rule, not a list per frame: a clause between punctuation that says something about the
# speaker, the hearer or the moment ("I know it's hectic", "I've been waiting here ten minutes",
# "hope you're having a great day", "force of habit", "Have a great day") is taken off when it
# opens with the speaker or the hearer (I, we, you, 'hope', 'have a'), names nothing in the scene
# (nor by a typo), and no word of it could name, count, choose, negate, order, delay, condition,
# correct, point back at a task or a person, describe, or make the speaker a recipient
# (_REMARK_HELD, the grammar's verbs of giving, placing and wanting, the scene's adjectives).
# Light verbs ('have', 'got', 'going'), words the word list lacks ('hectic') and the speaker's
# own possessions ('my break') are allowed: a clause about the speaker or the hearer with no name,
# no pointing word and no verb of giving or wanting cannot pick out anything in the scene. The
# request must be left: a text that is all remark is not rewritten.

_REMARK_HELD = re.compile(
    r"\b(?:no|not|never|nobody|none|nothing|nor|neither|without|except|but|rather|instead|only|"
    r"all|every|each|both|any|some|either|or|whichever|whatever|whoever|one|ones|two|three|"
    r"four|five|six|first|last|then|next|finally|before|after|once|when|until|till|if|unless|"
    r"later|tonight|tomorrow|soon|wait|hang|hold|actually|sorry|oops|mean|meant|mistake|scratch|"
    r"forget|cancel|stop|swap|switch|reverse|other|another|else|rest|it|them|they|their|theirs|"
    r"change|changed|ignore|scrap|"  # session 24: "…, I changed my mind" takes the request back
    r"he|him|his|she|her|hers|this|that|these|those|me|us|mine|ours|myself|to|for|into|onto|"
    r"from|under|off|out|near|nearest|closest|give|hand|pass|bring|take|put|place|keep|leave|"
    r"move|send|want|need|like|love|fancy|prefer|after|same|too|also|again|instead|what|which|"
    r"who|whom|whose|where|why|more|less|most|least|same|both|pair|couple|thing|things|item|"
    r"items|object|objects|stuff|everything|anything|something|yes|yeah|okay|ok|done|n't)\b"
    r"|n't\b|\d",
    _F,
)
# the words that open a clause about the speaker, the hearer or the moment
_REMARK_SUBJECT = re.compile(
    r"^(?:(?:oh|ah|well|so|and|just|really)\s+)*(?:i|i'm|i've|i'd|im|ive|we|we're|we've|you|"
    r"you're|you've|your|hope|hoping|have a|force of|old|chef|kitchen|workshop)\b",
    _F,
)
# light verbs: without a name or a pointing word they cannot pick out anything in the scene
_LIGHT_VERBS = frozenset(
    {"have", "has", "had", "having", "got", "gotten", "go", "goes", "going", "gone", "went"}
)


def _remark_clause(chunk: str, lexicon: Lexicon) -> bool:
    """Whether ``chunk`` is a clause about the speaker, the hearer or the moment that can change
    nothing of who gets what (see above)."""
    said = chunk.strip().lower()
    if not said or not _REMARK_SUBJECT.match(said):
        return False
    said = re.sub(r"\b(?:good|great|nice|lovely) one\b", "", said)
    # "I know it's hectic": a dummy 'it' before the last word or two; "for ages": how long
    said = re.sub(r"\bit(?:'s| is) (?=(?:so |really |very |a bit |bit )?[a-z]+$)", "", said)
    said = re.sub(r"\bfor (?:ages|a while|a bit|hours|(?:[a-z]+ )?minutes)$", "", said)
    if _REMARK_HELD.search(said):
        return False
    words = re.findall(r"[a-z']+", said)
    plain = [re.sub(r"'(?:s|ll|re|d|ve|m)$", "", w) for w in words]
    adjectives = {w for ws in _adjectives(lexicon).values() for w in ws}
    for n, w in enumerate(plain):
        noun = n > 0 and plain[n - 1] in ("your", "my", "our")  # "hope your shift's going well"
        if w in adjectives or (w in VERBS and w not in _LIGHT_VERBS and not noun):
            return False
    return _names_nothing(chunk, lexicon)


def _call(chunk: str, lexicon: Lexicon) -> bool:
    """Whether ``chunk`` is a call of one to three common words that names nothing and holds
    no word of _REMARK_HELD ("Behind", "Hot behind", "Mind your backs")."""
    words = re.findall(r"[a-z']+", chunk.lower())
    return (
        0 < len(words) <= 3
        and not _REMARK_HELD.search(chunk)
        and all(w in _COMMON and w not in VERBS for w in words)
        and not any(w in ws for ws in _adjectives(lexicon).values() for w in words)
        and _names_nothing(chunk, lexicon)
    )


# -- the speaker, not a recipient: leaving, finishing, signing off ---------------------------------
#
# Said of the speaker, none of these asks anything for them: 'before I go' is now, 'from me' and
# 'that's us done' close the request.
_SPEAKER_SIGN_OFFS = (
    (
        r"\s*,?\s*\bbefore (?:i|we) (?:go|leave|head off|head home|clock off|finish)"
        r"(?=\s*(?:[.,;!?]|$))",
        "",
    ),
    (r"\b(that's|that is) (everything|all|it) from (?:me|us)(?=\s*(?:[.!]|$))", r"\1 \2"),
    # "… and that's me done for the shift": the speaker finishing, not a recipient
    (
        r"\b(and )?that's (?:us|me) (?:done|finished|sorted)(?: for (?:the (?:day|shift|week|"
        r"morning)|today|now))?(?=\s*(?:[.!]|$))",
        r"\1that's it",
    ),
)


def _said_any(text: str, words: tuple[str, ...]) -> bool:
    """Whether ``text`` holds any of ``words`` (lower case): a cheap test before a rewrite's
    patterns are tried."""
    low = text.lower()
    return any(w in low for w in words)


def _sign_offs(text: str, lexicon: Lexicon) -> str:
    if not _said_any(
        text, ("before i", "before we", "from me", "from us", "that's us", "that's me")
    ):
        return text
    for pattern, repl in _SPEAKER_SIGN_OFFS:
        text = _drop(pattern, text, lexicon, repl)
    return " ".join(text.split())


# -- corrections said in other words: each is 'no,' -----------------------------------------------
#
# A marker that takes back what was just said, in the words people use: what follows it is the
# correction, read by the grammar's own 'no, …' (which refuses a correction it cannot place).
_TAKE_BACKS = (
    r",?\s*(?:\b(?:wait|hang on|hold on|um|er|hmm|oh),?\s*)*what am i (?:saying|on about|thinking)"
    r"\s*[,!?]\s*",
    r",?\s*(?:\b(?:um|er|hmm|oh|wait),?\s*)*(?:\bno,?\s*)?\bi tell a lie\s*,\s*",
    r",?\s*(?:\b(?:um|er|hmm|oh|wait),?\s*)*\bscratch that\s*,\s*",
    r",\s*or,\s*no\s*,\s*",
)
_SILLY = (
    r"(?<=[.!])\s*(?:wait|hang on|hold on|oh|no)\s*,?\s*that's (?:silly|daft|wrong|not right|"
    r"stupid|no good|mad)\s*,\s*"
)


def _repeated_destination(text: str, lexicon: Lexicon) -> str:
    """'Salt to Marco, no, lemon to Marco': the correction names the same person or place again;
    the grammar's 'no, <object>' keeps them."""
    m = _rx(
        r"\b(to|on|in|onto|into) ([^,.;!?]+?),\s*no,\s*((?:the )?[a-z ]+?) (to|on|in|onto|into) "
        r"([^,.;!?]+?)\s*([.!]?)$"
    ).search(text)
    if m is None:
        return text
    there, again = _ids(m.group(2), lexicon), _ids(m.group(5), lexicon)
    if not there or there != again or not _ids(m.group(3), lexicon, "object"):
        return text
    return f"{text[: m.start(3)]}{m.group(3)}{m.group(6)}"


def _only_person(words: str, lexicon: Lexicon) -> bool:
    return len(_ids(words, lexicon)) == 1 and _only(words, lexicon, "human")


def _take_backs(text: str, lexicon: Lexicon) -> str:
    if not _said_any(
        text,
        (
            "what am i",
            "tell a lie",
            "scratch that",
            "or, no",
            "that's",
            "let me",
            "or was it",
            "no,",
        ),
    ):
        return text
    for pattern in _TAKE_BACKS:
        text = _sub(pattern, ", no, ", text)
    text = _sub(_SILLY, " No, ", text)
    # "…, no, she wants the wipes": the want of the one named before
    text = _sub(
        r"(,\s*no,\s*)(?:he|she|they) (?:wants?|needs?|would like|'d like|'s after) (?=the )",
        r"\1",
        text,
    )
    text = _repeated_destination(text, lexicon)
    # "Let me think... the bowl to Omar": the speaker thinking aloud first
    text = _sub(r"^(?:hmm,?\s*|um,?\s*)?let me (?:think|see)\s*(?:\.\.\.|…|,|\.)\s*", "", text)
    # "or was it Zoe... yes, Zoe": the one said last stands
    text = _sub(
        r",?\s*or was it ([^.,;!?]+?)\s*(?:\.\.\.|…)\s*(?:yes|yeah|yep|no|nope),?\s+([^.,;!?]+)$",
        lambda m: f", no, {m.group(2)}" if _only_person(m.group(2), lexicon) else m.group(0),
        text,
    )
    return " ".join(text.split())


def _the_person(words: str, text: str, lexicon: Lexicon) -> bool:
    """Whether ``words`` name exactly one person and every he/she/him/her in ``text`` may be
    that person."""
    return _only_person(words, lexicon) and _fits(next(iter(_ids(words, lexicon))), text, lexicon)


def _said_why(text: str, lexicon: Lexicon) -> str:
    """After a correction, the reason for it restated: "…, no, on the trolley, that's nearer",
    "…, no, Marco, it's Marco who wanted it", "…, sorry, red mug, she always has the red one",
    "Hmm, actually, no, Sam needs it more." (the person the object goes to, said as a need). The
    reason is taken off only when it names what the correction names (else it is left, and
    refused)."""
    if not _said_any(text, ("no,", "sorry,", "actually,")):
        return text
    m = _rx(r"^.*\b(?:no|sorry|actually),\s+(.+)$").search(text)
    if m is None:
        return text
    tail = m.group(1)
    parts = re.split(r",\s*", tail)
    if len(parts) < 2:
        # "…. Hmm, actually, no, Sam needs it more.": the object goes to Sam after all
        n = _rx(r"([^,]+?) (?:needs|wants) it more\s*([.!]?)").fullmatch(tail.strip())
        if n is not None and _only_person(n.group(1), lexicon):
            return text[: m.start(1)] + f"to {n.group(1)}{n.group(2)}"
        return text
    said, why = parts[0], ", ".join(parts[1:])
    why_plain = why.strip().rstrip(".!")
    if _rx(
        r"(?:that's|that is|it's|it is|that one's) (?:nearer|closer|better|handier|easier|"
        r"bigger|cleaner)(?: to (?:her|him|them))?"
    ).fullmatch(why_plain):
        return text[: m.start(1)] + said + why[len(why.rstrip(".!")) :]
    n = _rx(r"it's ([^,]+?) who (?:wanted|wants|asked for|needs|needed) it").fullmatch(why_plain)
    if (
        n is not None
        and _ids(n.group(1), lexicon) == _ids(said, lexicon)
        and _only_person(said, lexicon)
    ):
        return text[: m.start(1)] + said
    n = _rx(
        r"(?:he|she|they) (?:always |usually )?(?:has|have|wants|likes|prefers|uses) the (\w+)"
        r"(?: one)?"
    ).fullmatch(why_plain)
    if n is not None:
        ids = _ids(said, lexicon, "object")
        if len(ids) == 1 and _rx(rf"\b{re.escape(n.group(1))}\b").search(said):
            return text[: m.start(1)] + said
    return text


def _redone(text: str, lexicon: Lexicon) -> str:
    """'…, and... no, leave the plate, put the tongs on the rack instead': the object left is the
    one just said, and what follows replaces it; "…, oh, not the green, the white cup": the one
    said after 'not the <word>' replaces the one that word named."""
    if not _said_any(text, ("leave the", "not the")):
        return text
    m = _rx(
        r"(?:,?\s*and)?\s*(?:\.\.\.|…)?\s*,?\s*\bno,\s*leave the ([a-z ]+?),\s*(.+?)\s+instead"
        r"\s*([.!]?)$"
    ).search(text)
    if m is not None:
        before = text[: m.start()]
        left = _ids(m.group(1), lexicon, "object")
        said_before = _names(before, lexicon)
        objs = [it for it in said_before if all(r.kind == "object" for r in it.refs)]
        if left and objs and {r.id for r in objs[-1].refs} <= left:
            new = m.group(2)
            n = _rx(r"^(?:put|place|give|hand|pass|take|bring) (?:(him|her|them) )?(.+)$").match(
                new
            )
            if n is not None:
                if n.group(1) and one_person(before, lexicon) is None:
                    return text
                new = n.group(2)
            return _repeated_destination(f"{before.rstrip(' ,.')}, no, {new}{m.group(3)}", lexicon)
    m = _rx(r",\s*(?:oh,?\s*)?not the (\w+),\s*(?=the )").search(text)
    if m is not None:
        before = text[: m.start()]
        if _rx(rf"\bthe {re.escape(m.group(1))} \w+").search(before):
            return f"{before}, no, {text[m.end() :]}"
    return text


def _order_again(text: str, _lexicon: Lexicon) -> str:
    """'Actually reverse that, apple first.', 'swap that round, bowl first': the order said again
    is the one said after."""
    if not _said_any(text, ("first",)):
        return text
    return _sub(
        r"\b((?:actually|no|sorry|wait),?\s*)(?:reverse that|swap that(?: round| around)?|the other"
        r" way (?:round|around)|flip that)\s*,\s*(?=(?:the )?[a-z ]+ first\b)",
        r"\1",
        text,
    )


# -- counts said beside their list -----------------------------------------------------------------
#
# "Two things in the sink: the bowl and the spoon", "Lena's getting two things today, the lemon and
# the knife", "Each of them gets two things: Mia the scanner and the tape, Tom …": a count of
# things said before the list that names them is dropped when the list names exactly that many
# (per person after 'each'); otherwise the text is left, and refused.

_NUMBERS15 = {"one": 1, "two": 2, "three": 3, "four": 4, "five": 5, "six": 6, "both": 2}
_THINGS = r"(?:things?|items?|bits?|objects?)"


def _shares(listed: str, lexicon: Lexicon) -> dict[str, list[str]]:
    """The objects each person gets in 'Alice the cup, Bob the apple and the chips': person id →
    object ids, in order; empty when the list is not of that shape."""
    out: dict[str, list[str]] = {}
    who: str | None = None
    for it in _names(listed, lexicon):
        kinds = {r.kind for r in it.refs}
        ids = {r.id for r in it.refs}
        if kinds == {"human"} and len(ids) == 1:
            who = next(iter(ids))
            if who in out:
                return {}
            out[who] = []
        elif kinds == {"object"} and len(ids) == 1 and who is not None:
            out[who].append(next(iter(ids)))
        else:
            return {}
    return out


def _plain_list28s(listed: str, lexicon: Lexicon) -> bool:
    """Whether ``listed`` is only names of the scene's objects, joined by commas, 'and' and
    articles (session 28, 12s: "Two things for Alice: the cup, and we need the water bottle" had
    counted the speaker's want as the second thing, and read both for Alice)."""
    rest = listed.lower()
    for it in _names(listed, lexicon):
        rest = rest.replace(it.text.lower(), " ", 1)
    return set(re.findall(r"[a-z']+", rest)) <= {"the", "a", "an", "and", "both", "also"}


def _objects_listed(listed: str, lexicon: Lexicon) -> list[str]:
    out = []
    for it in _names(listed, lexicon):
        if all(r.kind != "object" for r in it.refs):
            continue
        ids = {r.id for r in it.refs if r.kind == "object"}
        if len(ids) != 1 or len(ids) != len({r.id for r in it.refs}):
            return []
        out.append(next(iter(ids)))
    return out


def _categories(listed: str, lexicon: Lexicon) -> list[str]:
    cats = {o.id: o.category for o in lexicon.scene.objects}
    return [cats[i] for i in _objects_listed(listed, lexicon)]


def _counted_things(text: str, lexicon: Lexicon) -> str:
    s = text.strip()
    # "Each person gets two things: Alice the cup, Bob the apple, Carol the chips"
    m = _rx(
        rf"^each (?:person|of them|one|of you)(?: gets?| will get| should get| needs?)? "
        rf"(one|two|three|four|five|six) {_THINGS}\s*:\s*(.+)$"
    ).match(s)
    if m is not None:
        n = _NUMBERS15[m.group(1).lower()]
        shares = _shares(m.group(2), lexicon)
        if shares and all(len(objs) == n for objs in shares.values()):
            return m.group(2)
        return text
    # "Two things in the sink: the bowl and the spoon"
    m = _rx(
        rf"^(one|two|three|four|five|six) {_THINGS} ((?:in|on|onto|into|for|to) [^,:]+?)\s*[:,]\s*"
        r"(.+?)\s*([.!]?)$"
    ).match(s)
    if m is not None:
        if len(_objects_listed(m.group(3), lexicon)) == _NUMBERS15[m.group(1).lower()] and (
            _plain_list28s(m.group(3), lexicon)
        ):
            return f"{m.group(3)} {m.group(2)}{m.group(4)}"
        return text
    # "Lena's getting two things today, the lemon and the knife", "Sam wants two pens, the blue
    # and the black", "Carol's taking the pair of them, the cup and the apple"
    m = _rx(
        r"^(.+?)(?:'s| is)? (getting|gets|wants|needs|taking|takes|would like|is having|'s having)"
        r" (?:(one|two|three|four|five|six) ([a-z]+)|the pair of them|both of them)"
        r"(?: (?:today|tonight|this week|now|here))?\s*[:,]\s*(.+?)\s*([.!]?)$"
    ).match(s)
    if m is not None and _only_person(m.group(1), lexicon):
        n = _NUMBERS15[(m.group(3) or "two").lower()]
        listed = m.group(5)
        kind = m.group(4)
        if kind and not _rx(_THINGS).fullmatch(kind):
            cat = _kind_of(kind, lexicon)
            if cat is None:
                return text
            # "the blue and the black": each adjective names one of that kind
            listed = re.sub(
                r"\bthe (\w+)(?= and\b|,|$)", lambda x: f"the {x.group(1)} {cat}", listed
            )
            if not all(r == cat for r in _categories(listed, lexicon)):
                return text
        if len(_objects_listed(listed, lexicon)) == n:
            verb = "wants" if m.group(2).lower() in ("wants", "needs", "would like") else "gets"
            return f"{m.group(1)} {verb} {listed}{m.group(6)}"
        return text
    # "Both of the patients need a blanket: the blue one for Mr Lee and the grey one for …"
    m = _rx(
        r"^both (?:of )?(?:the )?([a-z]+)(?: here)? (?:need|want|get|should get) (?:a|an|one) "
        r"([a-z]+)\s*:\s*(.+)$"
    ).match(s)
    if m is not None:
        cat = _kind_of(m.group(2), lexicon)
        listed = m.group(3)
        if cat is not None:
            listed = re.sub(r"\b(\w+) one\b", lambda x: f"{x.group(1)} {cat}", listed)
            if (
                len(_objects_listed(listed, lexicon)) == 2
                and len(_ids(listed, lexicon, "human")) == 2
            ):
                return listed
        return text
    # "Person A gets all four things, every single one": the count said again
    return _sub(r",\s*every (?:single |last )?one\b", "", text)


# -- choices said again in other words ------------------------------------------------------------
#
# Each of these says again that any one will do, after a request that already leaves the choice
# (an 'a <kind>', 'one of the …', 'X or Y'); the rewrite keeps the request and the grammar reads
# the choice.
_ANY_WILL_DO = (
    r"(?:(?:any|either) (?:one|of them|of those)(?: (?:will do|is fine|'s fine|is ok))?|"
    r"(?:(?:i'm|i am|we're|we are) )?not (?:fussed|bothered) which(?: one)?|"
    r"(?:i )?don't mind which|doesn't matter which|(?:he|she|they) (?:doesn't|"
    r"don't|does not|do not) mind|(?:he|she|they)(?:'s|'re| is| are) not fussy|(?:he|she|they) "
    r"(?:isn't|aren't) fussy|whichever you reach first|whichever's (?:easier|handier|nearer|"
    r"closer)(?: to (?:grab|reach|get))?)"
)


def _any_again(text: str, lexicon: Lexicon) -> str:
    """'Can Priya have a pen? Any one, she doesn't mind', 'One of the pens in the box, not fussed
    which', 'Person A, either the bottle or the chips, whichever you reach first': the choice said
    again is taken off when a choice is already said before it."""
    pattern = rf"(\s*[,.?!]\s*)(?:{_ANY_WILL_DO}(?:\s*,\s*)?)+\s*([.!]?)\s*$"
    m = _rx(pattern).search(text)
    if m is None:
        return text
    before = text[: m.start()]
    if not _rx(r"\b(?:a|an|one of|any|either)\b|\bor\b").search(before):
        return text
    if _rx(r"\b(?:the other|the rest)\b").search(before):
        return text
    if m.group(1).strip() == "?":
        return f"{before}?"
    return f"{before}{m.group(2)}"


def _either_of(text: str, lexicon: Lexicon) -> str:
    """'Either of the students can have the globe, Noah or Zoe', 'Either of them can have the
    lemon, Marco or Lena': the two named after (each must be one of the group named, if one is)
    can have it; 'Either Alice or Carol, whoever's nearer, gets the apple': the choice is theirs."""
    m = _rx(
        r"^either of (?:the ([a-z]+)|them|the two|you two)( can have| could have| gets?| can get"
        r"| should get| may have)( [^,]+?),\s*([^,]+?) or ([^,]+?)\s*([.!]?)$"
    ).match(text.strip())
    # (what they can have ends at the first comma: "…, Mrs Ortiz, sorry, Noah or Zoe" had
    # dropped the repair with the name it takes back, then given her a share; session 32)
    if m is not None:
        a, b = m.group(4), m.group(5)
        if not (_only_person(a, lexicon) and _only_person(b, lexicon)):
            return text
        if m.group(1):
            group = _ids(m.group(1), lexicon, "human") or _ids(
                re.sub(r"s$", "", m.group(1)), lexicon, "human"
            )
            if not (_ids(a, lexicon) | _ids(b, lexicon)) <= group:
                return text
        return f"{a} or {b}{m.group(2)}{m.group(3)}{m.group(6)}"
    text = _sub(
        r"^(either )?([^,]+?) or ([^,]+?),\s*whoever(?:'s| is) (?:nearer|closer|nearest|closest|"
        r"free|handier|quicker),\s*",
        lambda n: (
            f"{n.group(2)} or {n.group(3)} "
            if _only_person(n.group(2), lexicon) and _only_person(n.group(3), lexicon)
            else n.group(0)
        ),
        text,
    )
    # "Each of the students gets a book": each one of that group
    return _sub(
        r"^each of the ([a-z]+)s (gets?|needs?|wants?|should get|can have) (a|an|one) ",
        lambda n: (
            f"each {n.group(1)} {n.group(2)} {n.group(3)} "
            if len(_ids(n.group(1), lexicon, "human")) >= 2
            else n.group(0)
        ),
        text,
    )


def _either_fine(text: str, lexicon: Lexicon) -> str:
    """ "…, either's fine" is "either is fine"; "Person B, either the apple or the cup" is "Person
    B, the apple or the cup"."""
    text = _sub(
        r"^([^,]+?),\s*either (?=the )",
        lambda m: f"{m.group(1)}, " if _only_person(m.group(1), lexicon) else m.group(0),
        text,
    )
    return _sub(r",\s*either's (fine|ok|okay|good)\b", r", either is \1", text)


# -- exclusions said first -------------------------------------------------------------------------


def _not_first(text: str, lexicon: Lexicon) -> str:
    """'No, not Lena, the knife's for Marco': the person left out first is not the one the request
    names; 'Not the ruler, he wants the glue, give Noah the glue stick': the object left out is
    not one the request names, and a want said before the request for the same object is the
    request said twice; 'Not the pens, just the other bits, into the box': everything but them;
    'Leave the blue pen, put the other two in the box': the others of its kind, as many as said."""
    # (what is left out ends at a comma, and never runs across a colon or a full stop: "Not
    # urgent: the apple and, um, the cup to Bob" left out nothing; session 32, 12c's repairs fuzz)
    m = _rx(r"^(no,\s*)?not ([^,:;.!?]+?),\s*(.+)$").match(text.strip())
    if m is not None:
        left, rest = m.group(2), m.group(3)
        n = _rx(r"^just the other (?:bits|things|stuff|items|ones),?\s*(.+)$").match(rest)
        if n is not None and _ids(left, lexicon, "object"):
            return f"everything except {left} {n.group(1)}"
        said = _ids(left, lexicon)
        if not said or said & _ids(rest, lexicon):
            return text
        # a person left out is read only after 'No,' ("No, not Lena, the knife's for Marco":
        # the speaker answering who it is for); "Not Bob, give Alice the cup" is not read
        if not (
            (m.group(1) and _only_person(left, lexicon)) or _ids(left, lexicon, "object") == said
        ):
            return text
        rest = _sub(
            r"^(?:he|she|they) (?:wants?|needs?) (?:the|his|her|their) ([a-z ]+?),\s*(?=(?:give|"
            r"hand|pass|bring) )",
            lambda x: (
                ""
                if _ids(x.group(1), lexicon) <= _ids(x.string[x.end() :], lexicon)
                else x.group(0)
            ),
            rest,
        )
        return rest
    m = _rx(
        r"^leave the ([a-z ]+?),\s*(put|give|hand|pass) (.*?)the other (one|two|three|four)\b(.*)$"
    ).match(text.strip())
    if m is not None:
        left = _ids(m.group(1), lexicon, "object")
        if len(left) != 1:
            return text
        cats = {o.id: o.category for o in lexicon.scene.objects}
        cat = cats[next(iter(left))]
        others = [o.id for o in lexicon.scene.objects if o.category == cat and o.id not in left]
        if len(others) != _NUMBERS15[m.group(4).lower()]:
            return text
        named = " and ".join(f"the {_said(i, lexicon)}" for i in others)
        return f"{m.group(2)} {m.group(3)}{named}{m.group(5)}"
    return text


# -- what a want is for, and wants said in other words -------------------------------------------
_FOR_WHAT = (
    # "a bit of salt with his dinner", "the jug with his lunch": what it goes with (naming nothing)
    (r"\s+with (?:his|her|their|my|your) [a-z]+(?= *(?:[.,;!?]|$))", ""),
    # "for these reports", "for his project", "for the next sample"
    (
        r"(?<!\bits)(?<!\bit's)(?<!\bis)\s+for (?:these|this|those|his|her|their|the next|the new|"
        r"my|our) [a-z]+(?: [a-z]+)?"
        r"(?= *(?:[.,;!?]|$))",
        "",
    ),
    # "Omar says he needs", "Dana said she wants"
    (r"\b(?:says|said|reckons|tells me) (?:he|she|they) (needs|wants|would like)\b", r"\1"),
    # "… been wanting the drill for ages / all morning"
    (r"(?:'s| has| have) been wanting\b", " wants"),
    (
        r"\s+(?:for ages|all (?:morning|day|afternoon|evening|week|lesson|class|shift|session)"
        r"(?: long)?|for a while|since this morning)\b",
        "",
    ),
    # "a bit of salt": the salt
    (r"\b(?:a bit|a drop|a little|a spot) of (?:the )?", "the "),
)


def _wanted_for(text: str, lexicon: Lexicon) -> str:
    if not _rx(r"\b(?:wants?|needs?|would like|wanting|says|said|after)\b").search(text):
        return text
    for pattern, repl in _FOR_WHAT:
        text = _drop(pattern, text, lexicon, repl)
    # "Mrs Khan's after something to read, the magazine": the thing said after
    text = _sub(
        r"^([^,]+?)(?:'s| is) after something (?:to [a-z]+(?: with)?|for [a-z ]+?),\s*(?=the )",
        lambda m: f"{m.group(1)} wants " if _only_person(m.group(1), lexicon) else m.group(0),
        text,
    )
    # "Sam needs a pen, he hasn't got one": why, said after
    text = _sub(
        r"\b(a|an) ([a-z]+),\s*(?:he|she|they) (?:hasn't got|haven't got|doesn't have|don't "
        r"have|has no|have no|hasn't any|needs|wants) (?:one|any)\b",
        r"\1 \2",
        text,
    )
    return " ".join(text.split())


# -- remarks that carry the reason, about the one the request is for ------------------------------
_STATE = (
    r"(?:(?:'s|is|has|'s got|has got) (?:finishing|starting|ending|off on|going on|on) (?:her|his"
    r"|their) (?:shift|break|lunch|rounds|round)|(?:'s|is) (?:off home|leaving|going home|off)|"
    r"(?:'s|has) got (?:his|her|their) hands full|has (?:his|her|their) hands full|(?:'s|is) "
    r"busy|(?:'s|is) back)"
)


def _why_said_first(text: str, lexicon: Lexicon) -> str:
    """'Lena's finishing her shift, take the knife and hand it to her', 'Kofi's got his hands full,
    put the drill on the bench for him': a remark about the state of the one person the request
    is for, naming nothing else, is taken off (its he/she is theirs); 'Zoe dropped her book, the
    green one, pick it up and give it back to her' / 'Marco hasn't had his knife, take it over':
    the object the remark names is what 'it' is, and the person is who gets it."""
    # "Mr Lee and Mrs Khan are both awake now, pass him the jug": a remark about two people,
    # as a sentence of its own (its he/she is read among them, or refused with both)
    text = _sub(
        r"^([^,]+?) and ([^,]+?) are both ([a-z]+)((?: now| here| in| up)?),\s*",
        lambda x: (
            f"{x.group(1)} and {x.group(2)} are {x.group(3)}{x.group(4)}. "
            if _only_person(x.group(1), lexicon) and _only_person(x.group(2), lexicon)
            else x.group(0)
        ),
        text,
    )
    m = _rx(rf"^([^,]+?)\s*{_STATE}\s*,\s*(.+)$").match(text.strip())
    if m is not None and _only_person(m.group(1), lexicon):
        who, rest = m.group(1), m.group(2)
        rest = _rx(r"\s+for (?:him|her|them)\b").sub("", rest)
        rest = _rx(r"\b(give|hand|pass|bring|take) it (?:back )?to (?:him|her|them)\b").sub(
            lambda x: f"{x.group(1)} it to {who}", rest
        )
        rest = _rx(r"\b(give|hand|pass|bring|take) (?:him|her|them)\b").sub(
            lambda x: f"{x.group(1)} {who}", rest
        )
        return rest
    m = _rx(
        r"^([^,]+?)(?:'s| is) [a-z]+ing (?:with )?(both|the|all) ([a-z ]+?)(?: today| this week| "
        r"now| again)?,\s*(?:give|hand|pass|bring) them to (?:him|her|them)\s*([.!]?)$"
    ).match(text.strip())
    if m is not None and _only_person(m.group(1), lexicon):
        # "Zoe's reading both books today, give them to her": what the remark names is 'them'
        said = f"{m.group(2)} {m.group(3)}"
        if len(_ids(said, lexicon, "object")) >= 2 and _fits(
            next(iter(_ids(m.group(1), lexicon))), text, lexicon
        ):
            return f"give {m.group(1)} {said}{m.group(4)}"
        return text
    m = _rx(
        r"^([^,]+?)(?:'s| has) lost (?:his|her|their) ([a-z ]+?)(?: again)?,\s*(?:can you |could "
        r"you |please )?(give|hand|pass|bring) (him|her|them) (.+?)(?:,? while you're (?:there|at "
        r"it))?\s*([.!?]?)$"
    ).match(text.strip())
    if m is not None and _only_person(m.group(1), lexicon):
        # "Zoe's lost her ruler again, can you give her the ruler, and the glue while you're
        # there": the remark names what the request gives her
        lost = _ids(m.group(2), lexicon, "object")
        if (
            lost
            and lost <= _ids(m.group(5), lexicon)
            and _fits(next(iter(_ids(m.group(1), lexicon))), text, lexicon)
        ):
            return f"{m.group(3)} {m.group(1)} {m.group(5)}{m.group(6)}"
        return text
    m = _rx(
        r"^([^,]+?) (?:dropped|lost|has lost|'s lost|hasn't had|has not had|hasn't got|forgot|"
        # session 40 (12): where it was left ("Sam left his notepad here, take it back to him")
        r"left|misplaced) (?:his|her|their) ([a-z ]+?)(?: again| yet| here| behind| over here| "
        r"(?:on|in|at|by) the [a-z]+(?: [a-z]+)?)?(?:,\s*the ([a-z]+) one)?,\s*"
        r"(?:(?:pick|grab|get) it(?: up)? and )?(?:give|hand|pass|bring|take) it (?:back )?(?:over"
        r"|to (?:him|her|them))\s*(.*)$"
    ).match(text.strip())
    if m is not None and _only_person(m.group(1), lexicon):
        thing = f"the {m.group(3)} {m.group(2)}" if m.group(3) else f"the {m.group(2)}"
        ids = _ids(thing, lexicon, "object")
        if len(ids) != 1 or not _ids(m.group(2), lexicon):
            return text
        rest = _rx(r"^(,?\s*then .+?) after$").sub(r"\1", m.group(4) or "")
        sep = "" if not rest or rest.startswith(",") else " "
        return f"give {m.group(1)} {thing}{sep}{rest}"
    return text


def _them_one(text: str, lexicon: Lexicon) -> str:
    """'Alice wants the apple. When they've got it, give them the chips too.': 'them' handed
    something, after 'they' said of the one person named, is that person."""
    if not _said_any(text, ("they",)) or one_person(text, lexicon) is None:
        return text
    if not _rx(r"\b(?:when|once|after|as soon as) they(?:'ve| have)?\b").search(text):
        return text
    who = one_person(text, lexicon)
    return _sub(r"\b(give|hand|pass|bring) them (?=the |a |an )", rf"\1 {who} ", text)


def _them_over(text: str, lexicon: Lexicon) -> str:
    """'Priya wants the stapler and the notepad; hand them over': to the one person who wants
    them."""
    m = _rx(r"[;.,]\s*(hand|pass|bring|take) (them|it) over\s*(,\s*please)?\s*([.!]?)$").search(
        text
    )
    if m is None:
        return text
    before = text[: m.start()]
    who = one_person(before, lexicon)
    if who is None or not _rx(r"\b(?:wants?|needs?|would like)\b").search(before):
        return text
    return f"{before}; give {m.group(2)} to {who}{m.group(4)}"


def _likewise(text: str, lexicon: Lexicon) -> str:
    """'Grey blanket on the locker, magazine likewise', '…, and the notepad, same thing': the
    object said is done the same way ('too')."""
    text = _sub(
        r"(,\s*(?:and )?(?:the )?[a-z ]+?)\s*,?\s*(?:likewise|same thing|same again|the same)\s*"
        r"([.!]?)$",
        lambda m: (
            f"{m.group(1)} too{m.group(2)}"
            if _only(re.sub(r"^,\s*(?:and )?", "", m.group(1)), lexicon, "object")
            else m.group(0)
        ),
        text,
    )
    return text


# -- run-ons and dictation ------------------------------------------------------------------------
_LEADS = (
    # "Order's up so …", "Truck's here so …": a remark naming nothing, then 'so'
    r"^[a-z]+(?:'s| is) (?:up|in|here|ready|done|out|back|on)\s*,?\s*so\b\s*",
    # "Right lads listen up …", "Ok team, listen up, …"
    r"^(?:(?:right|ok|okay|oi|now)\s*,?\s*)?(?:(?:lads|team|everyone|folks|guys|all|people)\s*,?\s*)?"
    r"listen up\s*[,!.]?\s*",
)


# courtesy said as a condition, in other words: "if you'd be good enough to", "if ye could",
# "Kindly do the needful and": each is "could you"; a clause of 'while' about people the scene
# does not name ("while everyone settles down") is when, not a condition on a task
_COURTESY_IFS = (
    (
        r"\bif (?:you|ye|yous|u)(?:'d| would)? be (?:so )?(?:kind|good) enough(?: as)? to\s+",
        "if you could ",
    ),
    (
        r"\bif (?:you|ye|yous|u)(?:'d| would)\s+(?=(?:give|hand|pass|bring|take|put|pop)\b)",
        "if you could ",
    ),
    (r"\bif (?:ye|yous|u) (could|would|can)\b", r"if you \1"),
    # session 27: "…, if you can manage." / "if you can manage it" / "if you're able": asking
    # whether the hearer can, closing a sentence (said before the rest of a clause it is left)
    (
        r"\s*,?\s*\bif (?:you|ye|u)(?: can| could| think you can| are able to|'re able to) manage"
        r"(?: it| that| this)?(?=\s*(?:[.!?]|$))|\s*,\s*\bif (?:you|ye|u) ?(?:'re|are) able"
        r"(?=\s*(?:[.!?]|$))",
        "",
    ),
    (r"\b(?:kindly |please )?do the needful,?\s+and\s+", ""),
    (
        r"^(?:right,?\s*|ok,?\s*|okay,?\s*)?while (?:everyone|everybody|the [a-z]+|we|they) "
        r"[^,.;!?]+,\s*",
        "",
    ),
    (
        r"^(?:right,?\s*|ok,?\s*|okay,?\s*)?(?:handover|hand-over|notes for today|notes)\s*[.:]\s*",
        "",
    ),
)


def _courtesy_ifs(text: str, lexicon: Lexicon) -> str:
    if not _said_any(text, ("if ", "needful", "while ", "handover", "hand-over", "notes")):
        return text
    for pattern, repl in _COURTESY_IFS:
        text = _drop(pattern, text, lexicon, repl)
    return " ".join(text.split())


def _run_on_leads(text: str, lexicon: Lexicon) -> str:
    if not _said_any(text, ("listen up", " so ")):
        return text
    for pattern in _LEADS:
        text = _drop(pattern, text, lexicon)
    return text


def _dictated(text: str, lexicon: Lexicon) -> str:
    """'apple on the table cup to alice done': a list dictated without stops; a stop goes after
    each place or recipient that another object follows, and the closing 'done' goes. Each part
    must then name one object and one place or recipient ('apple on the table cup done' is
    left, and refused)."""
    m = _rx(r"\s+done\s*[.!]?$").search(text)
    if m is None or re.search(r"[,.;:!?]", text[: m.start()]):
        return text
    words = text[: m.start()].split()
    parts: list[list[str]] = [[]]
    for k, w in enumerate(words):
        head = " ".join(parts[-1])
        named = _names(head, lexicon) if head else []
        if (
            named
            and any(r.kind in ("human", "surface") for r in named[-1].refs)
            and _names(" ".join(words[k : k + 2]), lexicon)
            and all(r.kind == "object" for r in _names(" ".join(words[k : k + 2]), lexicon)[0].refs)
            and head.lower().endswith(named[-1].text.lower())
        ):
            parts.append([])
        parts[-1].append(w)
    if len(parts) < 2:
        return text
    for part in parts:
        kinds = [{r.kind for r in it.refs} for it in _names(" ".join(part), lexicon)]
        if kinds[:1] != [{"object"}] or len(kinds) != 2 or kinds[1] == {"object"}:
            return text
    return ", ".join(" ".join(p) for p in parts)


def _after_those(text: str, lexicon: Lexicon) -> str:
    """'… And the cup to Carol, after those two.': after every task said before, when there are
    that many."""
    m = _rx(
        r"\.\s*(?:and |then )?([^.]+?),\s*after (?:those|these|the) (two|three|four)\s*([.!]?)$"
    ).search(text)
    if m is None:
        return text
    before = text[: m.start() + 1]
    objs = [it for it in _names(before, lexicon) if all(r.kind == "object" for r in it.refs)]
    if len(objs) != _NUMBERS15[m.group(2).lower()]:
        return text
    return f"{before} Then {m.group(1)}{m.group(3)}"


def _can_wait(text: str, lexicon: Lexicon) -> str:
    """'Priya wants the stapler and Sam wants the notepad but he can wait so do that last': the
    want of the one who can wait comes after the other."""
    m = _rx(
        r"^(.+) and ([^,]+?) (wants|needs|gets) (.+?),? but (?:he|she|they) can wait,?\s*so do "
        r"(?:that|his|hers|theirs|it|them) last\s*([.!]?)$"
    ).match(text.strip())
    if m is None or not _only_person(m.group(2), lexicon):
        return text
    if not _fits(next(iter(_ids(m.group(2), lexicon))), m.group(0), lexicon):
        return text
    # session 36 (12t): the one who can wait is the subject of the last want ("… and the
    # visitor wants the white cup and Omar wants the bowl but he can wait …" had put the cup
    # last with the bowl): the want said of them names no other person
    if _ids(m.group(4), lexicon, "human"):
        return text
    return f"{m.group(1)}, then {m.group(2)} {m.group(3)} {m.group(4)}{m.group(5)}"


# -- questions that end in a request -------------------------------------------------------------
def _asked_then_told(text: str, lexicon: Lexicon) -> str:
    """'How long would it take to get the bowl to Omar? Just do it, please.': the task asked
    about, then 'do it', is the request; 'Is there a book for Zoe? Either one will do.': any one;
    "Won't you pass Lena the knife?": a request."""
    if not _said_any(text, ("how long", "is there", "won't you")):
        return text
    text = _sub(
        r"^how long (?:does|would|will|might) it take to (.+?)\?\s*(?:just |please )?do it"
        r"(?:,? please)?\s*[.!]?$",
        r"\1.",
        text,
    )
    text = _sub(
        r"^is there (a|an|any) ([a-z ]+?) for ([^?]+?)\?\s*(?:either|any) (?:one|of them)"
        r" (?:will do|is fine|'s fine|is ok)\s*[.!]?$",
        lambda m: (
            f"{m.group(1)} {m.group(2)} for {m.group(3)}."
            if _only_person(m.group(3), lexicon)
            else m.group(0)
        ),
        text,
    )
    return _sub(r"^won't you\b", "will you", text)


# -- the last step: stretches that are provably inert ----------------------------------------------
#
# A stretch between punctuation is taken off only when every word of it is a common English word
# and none could name, count, choose, negate, order, delay, correct, point back, describe, make
# the speaker a recipient or be a task ('_HELD', the grammar's verbs, articles and possessives, the
# scene's adjectives and colours, sizes and states, words that cancel or hedge), and it names
# nothing in the scene (nor by a typo); and only when what is left is read by the grammar and the
# text holds no question. What is left is the request: nothing taken off could change who gets
# what.

_HELD_MORE = frozenset(
    {
        *("the", "a", "an", "some", "his", "her", "hers", "their", "its", "your", "yours", "our"),
        *("and", "also", "plus", "too", "again", "twice", "thrice", "everything", "anything"),
        *("something", "everyone", "anyone", "someone", "everybody", "anybody", "somebody"),
        *("maybe", "perhaps", "possibly", "probably", "kidding", "joking", "jk", "lol"),
        *("disregard", "ignore", "undo", "belay", "abort", "nevermind", "nvm", "skip", "drop"),
        *("remove", "revert", "reverse", "return", "tonight", "today", "tomorrow", "soon"),
        *("eventually", "afterwards", "afterward", "morning", "evening", "afternoon", "noon"),
        *("midnight", "o'clock", "pm", "am", "minute", "minutes", "hour", "hours", "week"),
        *("lunch", "dinner", "breakfast", "tea", "red", "blue", "green", "white", "black"),
        *("grey", "gray", "yellow", "orange", "pink", "purple", "brown", "big", "small", "large"),
        *("little", "tall", "short", "left", "right", "top", "bottom", "middle", "full", "empty"),
        *("clean", "dirty", "new", "old", "hot", "cold", "warm", "upright", "open", "closed"),
        *("sealed", "filled", "washed", "dry", "wet", "same", "different", "more", "less"),
        *("most", "least", "half", "both", "either", "neither", "whole", "yes", "no", "nope"),
        *("only", "single", "pair", "couple", "few", "several", "many", "much", "each"),
        *("person", "people", "thing", "things", "item", "items", "object", "objects"),
        *("somewhere", "anywhere", "everywhere", "nowhere", "where", "who", "what", "which"),
        *("how", "why", "whose", "whom", "back", "away", "over", "down", "up", "inside"),
        *("outside", "above", "below", "behind", "beside", "between", "near", "far", "closer"),
        *("nearer", "nearest", "closest", "further", "furthest", "farthest", "order", "instead"),
    }
)


# the words an inert stretch is made of: interjections, praise, thanks, address, hurry and care,
# sign-offs (with _CLOSING_WORDS and _ADDRESS, and adverbs in -ly); a noun that could be an object
# ("…, spoon") is none of them
_INERT_WORDS = frozenset(
    {
        *("ah", "aha", "oh", "ooh", "wow", "whoa", "yay", "yippee", "hooray", "phew", "gosh"),
        *("golly", "blimey", "crikey", "cor", "jeez", "geez", "gee", "hmm", "um", "uh", "er"),
        *("erm", "huh", "well", "now", "righto", "alright", "okey", "dokey", "sure", "fine"),
        *("brill", "excellent", "splendid", "marvellous", "marvelous", "terrific", "cracking"),
        *("bonza", "bonzer", "stellar", "superb", "tremendous", "outstanding", "incredible"),
        *("glorious", "jolly", "lush", "mint", "sorted", "cheerio", "tara", "ttfn", "ciao"),
        *("pls", "plz", "quick", "fast", "asap", "pronto", "sharpish", "snappy", "hurry", "chop"),
        *("rush", "careful", "gentle", "steady", "easy", "mind", "go", "work", "stuff", "effort"),
        *("yourself", "bless", "heavens", "lord", "indeed", "ever", "usual", "lots", "regards"),
        *("best", "wishes", "kind", "warm", "roger", "wilco", "copy", "affirmative", "understood"),
        *("noted", "got", "gotcha", "yah", "yup", "aye", "done", "lovely", "jubbly", "smashing"),
    }
)


# adverbs of manner, hurry and stance only ('lastly', 'respectively', 'preferably', 'separately'
# order, pair, choose or split, so an adverb is inert only when it is one of these)
_MANNER = frozenset(
    {
        *("quickly", "carefully", "gently", "slowly", "swiftly", "promptly", "urgently"),
        *("immediately", "kindly", "nicely", "safely", "softly", "quietly", "calmly", "smoothly"),
        *("speedily", "hastily", "rapidly", "steadily", "politely", "gladly", "happily"),
        *("really", "truly", "honestly", "seriously", "genuinely", "absolutely", "totally"),
        *("literally", "basically", "certainly", "definitely", "obviously", "clearly", "simply"),
        *("surely", "cheerfully", "warmly", "delicately", "neatly", "tidily", "properly"),
    }
)


def _held_word(word: str, lexicon: Lexicon) -> bool:
    low = word.lower()
    if low in _HELD_MORE or low in VERBS or _HELD.search(low):
        return True
    return any(low in words for words in _adjectives(lexicon).values())


# -- session 16: blind14's kinds, each a general rewrite (courtesy and calls, wants, remarks,
#    run-ons, choices, counts, exclusions, corrections) ----------------------------------------
#
# A sentence naming nothing in the scene and holding no word that could name, count, choose,
# negate, order, delay, condition, correct, point back or hand over ('Good robot.', 'Regards.',
# 'Right, eyes on me everyone.', "Okay darling, let's get you sorted.", 'Done.', 'Go.') is taken
# off: the speaker and the hearer ('me', 'you', 'I') can be no recipient in it, as it has no verb
# that gives.
_SENTENCE_HELD = re.compile(
    r"\b(?:no|not|never|nobody|none|nothing|nor|neither|without|except|but|rather|instead|only|"
    r"all|every|each|both|any|some|either|or|whichever|whatever|whoever|one|ones|two|three|"
    r"four|five|six|first|last|then|next|finally|before|after|once|when|until|till|if|unless|"
    r"later|tomorrow|tonight|wait|hang|hold|actually|sorry|oops|mean|meant|mistake|scratch|"
    r"forget|cancel|stop|swap|switch|other|another|else|rest|same|too|also|and|plus|it|them|"
    r"they|these|those|there|here|him|her|his|he|she|hers|theirs|mine|yours|something|anything|"
    r"everything|give|hand|pass|bring|take|put|place|want|need|keep|leave|move|send|drop|fetch|"
    r"grab|deliver|have|has|had|more|again|well|as|correction|correct|wrong|change|changed|"
    r"mind|like|prefer|fancy|rather|"
    # session 27: 'in between', 'meanwhile' order the steps around them
    r"between|meanwhile|meantime|afterwards|beforehand)\b|n't\b|\d",
    _F,
)
# 'this' / 'that' only as a statement's subject ("I hope this is okay"), or thanked for
_POINTING = re.compile(r"\b(?:this|that)\b(?!\s*(?:'s|is|was|would|'d|will)\b)", _F)
_THANKED = re.compile(r"\b(?:cheers|thanks|thank you|ta) for that\b", _F)


# Session 30 (12s): a sentence shaped as a request is no remark, whatever it names: a thing said
# alone ('The spanner.', 'A cloth, please.'), someone wanting or getting a thing ('The chef
# wants the jug.'), a thing with its recipient or place ('The jug to the chef.', 'For the chef,
# the jug.'). Naming nothing of the scene, it had been taken off as inert, and the request
# beside it read as if it were all that was asked; kept, it is refused for the unknown name.
_ASKS30S = re.compile(
    r"^\s*(?:the|a|an|some|that|this|these|those)\s+[a-z][a-z'-]*(?:\s+[a-z][a-z'-]*){0,2}"
    r"\s*(?:,?\s*please)?\s*[.!]*\s*$|"
    r"\b(?:wants|needs|would like|'d like|is after|asked for|asks for|is asking for|gets|is "
    r"getting|is to get|should get|should have|can have|could have|will have|is due)\s+(?:the|a|"
    r"an|some|his|her|their|my|your|our|this|that|these|those)\b|"
    # "The jug to the chef.", "A towel for the guest.", "For the chef, the jug."
    r"^\s*(?:the|a|an|some|that|this|these|those)\s+[a-z][a-z'-]*(?:\s+[a-z][a-z'-]*)?\s+(?:to|"
    r"for|on|onto|into|over to|across to)\s+(?:the|a|an|my|our|your|his|her)\s+[a-z]|"
    r"^\s*for\s+(?:the|a|an|my|our|your|his|her)\s+[a-z]+(?:\s+[a-z]+)?\s*[,:]\s*(?:the|a|an|"
    r"some)\s+[a-z]",
    _F,
)


def _asks30s(sentence: str) -> bool:
    return _ASKS30S.search(sentence) is not None


# courtesy in frames a held word is part of: each asks nothing of its own
_COURTESY_FRAMES: tuple[tuple[str, str], ...] = (
    # "would you be a dear / a love / an angel and give …": could you give (session 33, 12s:
    # "would you be a good sort and hand …", "be a real star and …": a kind word before it)
    (
        r"\b(would|could|will|can) you be (?:a|an|my) (?:(?:good|real|proper|absolute|kind|"
        r"lovely|little|total) )?[a-z]+ and\s+",
        r"\1 you ",
    ),
    (r"^(?:be (?:a|an) [a-z]+ and|be a love,?)\s+", ""),
    # "Pretty please (with sugar / a cherry on top)": please
    (r"\bpretty please(?: with (?:sugar|a cherry|cherries|bells) on(?: top)?)?\b", "please"),
    # "When convenient, …", "At your convenience, …", "When you get a chance, …"
    (
        r"(^|(?<=[.!?])\s*)(?:when (?:convenient|it's convenient|you can)|at your "
        # session 33 (12s): 'a second', 'a tick' (blind22)
        r"(?:earliest )?convenience|when you get a (?:chance|minute|moment|sec|second|tick))"
        r"\s*,\s*",
        r"\1",
    ),
    # "I hope this is okay, …", "I hope that's alright, …"
    (
        r"(^|(?<=[.!?,])\s*)(?:um,?\s*|er,?\s*)?i hope (?:this|that|it)(?:'s| is) (?:okay|ok|"
        r"alright|all right|fine)\s*,\s*",
        r"\1",
    ),
    # "thank you so much for earlier, you were brilliant. Now, …"
    (
        r"(^|(?<=[.!?,])\s*)(?:oh,?\s*)?(?:thank you|thanks|cheers)(?: so much| very much| again)?"
        r" for (?:earlier|before|this morning|yesterday|last time)\s*[,.!]\s*(?:you(?:'re| are| "
        r"were) (?:very |so |really )?[a-z]+\s*[.!,]\s*)?(?:now,?\s*)?",
        r"\1",
    ),
    # "One more favour, …", "Just one more thing, …"
    (
        r"(^|(?<=[.!?])\s*)(?:and |just )?one (?:more|last) (?:favour|favor|thing|job)(?: for me)?"
        r"\s*[,:]\s*",
        r"\1",
    ),
    # "…, if that's alright (with you)", "…, if that's okay": asked kindly
    (
        r",?\s*if that's (?:alright|all right|okay|ok|fine)(?: with (?:you|you all|everyone|"
        r"everybody|all of you))?(?=\s*(?:[.!:]|$))",
        "",
    ),
    (r",?\s*if you don't mind\s*(?=[,:])", ""),
    # "Sorry, I know it's manic in here, but …"
    (
        r"(^|(?<=[.!?])\s*)(?:sorry,?\s*)?i know (?:it's|it is|you're|you are|things are|we're) "
        r"(?:a bit |very |so |really )?[a-z]+(?: (?:in here|out there|today|right now|at the moment"
        r"|this morning|tonight))?\s*,?\s*(?:but|so)\s+",
        r"\1",
    ),
    # "Next order.", "New order:", "Two plates up!" said before the list (a kitchen call)
    (r"^(?:next|new|another) (?:order|ticket|table)\s*[.!:]\s*", ""),
    # "…, go go go", "…, go!": hurry
    (r",?\s*(?:go,?\s*){2,}go[.!]*$|,?\s*go go[.!]*$", ""),
)


def _courtesy_frames(text: str, lexicon: Lexicon) -> str:
    for pattern, repl in _COURTESY_FRAMES:
        text = _drop(pattern, text, lexicon, repl)
    # "Next one on my list: …", "Next item on the list: …" ('item' and 'one' name no object here)
    text = _sub(
        r"(^|(?<=[.!?])\s*)(?:(?:morning|right|ok|okay)\s*[!,.]?\s*)?next (?:one|item|job|thing|"
        r"task) (?:on|from|off) (?:my|the) list\s*[:,]\s*(?=\S)",
        r"\1",
        text,
    )
    # "Yes chef!", "Yes boss!": an answer to a call (naming the one called is no request)
    text = _sub(r"^yes,? (?:chef|boss|sir|madam|ma'am|captain|mate|love)\s*!\s*(?=\S)", "", text)
    # "Two plates up! White plate to Marco, …": a call naming only objects the rest hands out
    m = _rx(r"^(?:two|three|four|2|3|4) ([a-z]+) (?:up|coming up|ready)\s*!\s*").match(text)
    if (
        m is not None
        and _ids(m.group(1), lexicon, "object")
        and (_ids(m.group(1), lexicon) <= _ids(text[m.end() :], lexicon))
    ):
        text = text[m.end() :]
    return text


# -- wants and purposes --------------------------------------------------------------------------
_WANT_FRAMES: tuple[tuple[str, str], ...] = (
    # "Jess is gonna need", "Lena's going to want": needs, wants
    (r"(?:'s| is) (?:gonna|going to|about to) (need|want)\b", r" \1s"),
    # "Tom's happy with the tape or the gloves": wants (either)
    (r"(?:'s| is) (?:happy|fine|okay|ok|good) with\b(?= the\b)", " wants"),
    # "for cleaning up", "for washing up", "for cooking": what it is for, naming nothing
    (r"\s+for [a-z]+ing(?: up| out| with)?(?= *(?:[.,;!?]|$))", ""),
    # "for lunch", "for homework", "for her game", "for the repair", "for revision"
    (
        r"\s+for (?:(?:his|her|their|the|my|our) )?(?:lunch|dinner|breakfast|tea|supper|homework|"
        r"revision|game|repair|meeting|class|lesson|trip|journey|shift|rounds|project|work)(?= *(?:"
        r"[.,;!?]|$))",
        "",
    ),
)


def _want_frames(text: str, lexicon: Lexicon) -> str:
    if not _rx(
        r"\b(?:wants?|needs?|would like|'d like|gonna|going to|about to|happy with|fine with)\b"
    ).search(text):
        return text
    for pattern, repl in _WANT_FRAMES:
        text = _drop(pattern, text, lexicon, repl)
    # "The gentleman there, Mr Lee I think it is, he'd like …": the name said again, then 'he'
    m = _rx(
        r"^(?:i'?m only visiting\.\s*)?the (?:lady|gentleman|man|woman|chap|guy|fella|girl|boy|"
        r"kid|patient|child)(?: (?:there|over there|here|in the corner|by the window))?,\s*([^,]+?)"
        r"(?: i think(?: it is| that is)?| i believe| i reckon| is it)?,\s*(?:he|she)(?:'d| would)"
        r" like\b"
    ).match(text)
    if m is not None and _the_person(m.group(1), text, lexicon):
        text = f"{m.group(1)} would like{text[m.end() :]}"
    return " ".join(text.split())


# -- remarks and pronouns ------------------------------------------------------------------------


def _remark_owner(text: str, lexicon: Lexicon) -> str:
    """'Lily's hungry, put her bib on the high chair', "Omar's doing the washing up. Put the bowl in
    the sink for him": a remark about the one person named, naming nothing else, before a
    placement: 'her <object>' is that object, 'for him' is said of a placement (no one gets it),
    and the remark is taken off."""
    m = _rx(r"^([^,.!?]+?)(?:'s| is| was)( [a-z]+(?: [a-z]+){0,3})\s*[,.!]\s*(.+)$").match(text)
    if m is None or not _only_person(m.group(1), lexicon):
        return text
    remark, rest = m.group(2), m.group(3)
    if _SENTENCE_HELD.search(remark) or not _names_nothing(remark, lexicon):
        return text
    who = next(iter(_ids(m.group(1), lexicon)))
    if not _fits(who, rest, lexicon) or _ids(rest, lexicon, "human"):
        return text
    if not _rx(r"^(?:please\s+)?(?:put|place|set|pop|stick|leave)\b").match(rest):
        return text  # a placement only: 'for him' hands nothing over
    rest = _rx(r",?\s*for (?:him|her)\b").sub("", rest)
    rest = _sub(
        r"\b(?:his|her) ([a-z]+(?: [a-z]+)?)\b",
        lambda x: (
            f"the {x.group(1)}" if len(_ids(x.group(1), lexicon, "object")) == 1 else x.group(0)
        ),
        rest,
    )
    if re.search(r"\b(?:he|him|she|her|his)\b", rest, _F):
        return text
    return rest


def _same_person(text: str, lexicon: Lexicon) -> str:
    """'… After that, the cup goes to the same person.': the one person named before."""
    m = _rx(r"\b(to|for) the same (?:person|one|guy|lady|man|woman)\b").search(text)
    if m is None:
        return text
    before = _ids(text[: m.start()], lexicon, "human")
    if len(before) != 1:
        return text
    name = one_person(text[: m.start()], lexicon)
    if name is None:
        return text
    return text[: m.start()] + f"{m.group(1)} {name}" + text[m.end() :]


# -- run-ons -------------------------------------------------------------------------------------


def _both_got_theirs(text: str, lexicon: Lexicon) -> str:
    """'Kofi wants the big spanner and Jess wants the torch and the drill goes in the locker when
    they've both got theirs': the last clause after the two before it."""
    m = _rx(
        r"^(.+)\s+and\s+([^,]+?)\s+(?:when|once|after) they(?:'ve| have) both (?:got|had|"
        r"received) theirs\s*([.!]?)$"
    ).match(text)
    if m is None or len(_ids(m.group(1), lexicon, "human")) != 2:
        return text
    return f"{m.group(1)}, then {m.group(2)}{m.group(3)}"


def _run_on_remarks(text: str, lexicon: Lexicon) -> str:
    """ "Ruth needs the thermometer she's doing rounds and Mrs Khan needs the jug she's thirsty": a
    remark run on after 'P needs X' about P, naming nothing, is taken off."""

    def drop(m: re.Match[str]) -> str:
        clause, pronoun, remark = m.group(1), m.group(2), m.group(3)
        if _SENTENCE_HELD.search(remark) or not _names_nothing(remark, lexicon):
            return m.group(0)
        subject = _ids(clause, lexicon, "human")
        if len(subject) != 1:
            return m.group(0)
        if title_sex(next(iter(subject)), lexicon) not in (None, PRONOUN_SEX[pronoun.lower()]):
            return m.group(0)
        return clause

    return _sub(
        r"([^,]*?\b(?:needs?|wants?) the [a-z ]+?) (he|she)(?:'s| is) ([a-z]+(?: [a-z]+)?)"
        r"(?=\s+and\b|\s*[.!]?$)",
        drop,
        text,
    )


# -- which / any / each / either -----------------------------------------------------------------
_NOT_FUSSY = (
    r"(?:'s|is|was) (?:not|n't|never) (?:fussy|bothered|picky|choosy|particular)|(?:isn't|wasn't)"
    r" (?:fussy|bothered|picky|choosy|particular)|(?:'s|is) (?:easy|easygoing|easy-going|not "
    r"fussed)"
)


def _choice_frames(text: str, lexicon: Lexicon) -> str:
    """Choices said in other frames, each rewritten to the grammar's own choice."""
    # "Marco's not fussy, any plate will do for him": give Marco any plate
    m = _rx(
        rf"^([^,]+?)\s*(?:{_NOT_FUSSY})\s*,\s*(?:any|either) ([a-z]+) (?:will do|is fine|'ll do|"
        r"will be fine)(?: for (?:him|her))?\s*([.!]?)$"
    ).match(text)
    if m is not None and _the_person(m.group(1), text, lexicon):
        return f"give {m.group(1)} any {m.group(2)}{m.group(3)}"
    # "Whichever of Dana or Omar is free, give them the spoon": the spoon to Dana or Omar (session
    # 28: the objects one phrase, with no comma: "…, hand them the scanner, and we need the work
    # gloves" had been read as the gloves to either, and the scanner only with them to Mia)
    m = _rx(
        r"^whichever of ([^,]+?) or ([^,]+?) (?:is|'s) [a-z]+(?: [a-z]+)?\s*,\s*(give|hand|pass|"
        r"bring|take) (?:them|him or her) ([^,;:]+?)\s*([.!]?)$"
    ).match(text)
    if (
        m is not None
        and _only_person(m.group(1), lexicon)
        and _only_person(m.group(2), lexicon)
        and _ids(m.group(1), lexicon) != _ids(m.group(2), lexicon)
        and _ids(m.group(4), lexicon, "object")
        and not _ids(m.group(4), lexicon, "human")
    ):
        if len(_ids(m.group(4), lexicon, "object")) > 1:
            # "…, hand them the scanner and the gloves": both to the one who is around
            v, o = m.group(3), m.group(4)
            return f"either {v} {o} to {m.group(1)} or {v} {o} to {m.group(2)}{m.group(5)}"
        return f"{m.group(3)} {m.group(4)} to {m.group(1)} or {m.group(2)}{m.group(5)}"
    # "One of the two people should get the apple", "The cup should go to one of the two people"
    people = [h for h in lexicon.scene.humans]
    if len(people) == 2:
        both = f"{people[0].name} or {people[1].name}"
        text = _sub(
            r"\b(?:one of the two people|one of the two of them|one of them two|either of the two "
            r"people|one of you two)\b",
            both,
            text,
        )
        text = _sub(r"\b(or Person [A-Z]) should (?:get|have|receive)\b", r"\1 gets", text)
        text = _sub(r"\bshould go to\b", "goes to", text)
    # "…, either is fine", "…, either one is fine", "…, one or the other", "…, I don't mind which"
    if _rx(r"\bor\b").search(text):
        text = _drop(
            r",\s*(?:either(?: one)? (?:is|'s) (?:fine|ok|okay|good)|one or the other|i don't mind "
            r"which(?: one)?|not fussed which|whichever)(?=\s*(?:[.!,]|$))",
            text,
            lexicon,
        )
        # "…, whichever stops her crying", "…, whichever's nearest": the robots choose
        text = _sub(
            r",\s*whichever(?:'s| is)? ([a-z' ]+?)\s*([.!]?)$",
            lambda x: (
                x.group(2)
                if _names_nothing(x.group(1), lexicon)
                and not _rx(r"\b(?:to|from|than|of|by|on|in|next)\b").search(x.group(1))
                and not _rx(r"\b(?:not|n't|no|never|only|first|last|before|after)\b").search(
                    x.group(1)
                )
                else x.group(0)
            ),
            text,
        )
    # "… for Person A, and the chips and the apple both for Person B": both the chips and …
    text = _sub(r"\b(the [a-z ]+? and the [a-z ]+?) both (for|to)\b", r"both \1 \2", text)
    # "Each of them gets a spanner, Kofi and Jess": Kofi and Jess each get a spanner
    m = _rx(
        r"^each of (?:them|you|the two) (?:gets?|has|can have|should get) (an? [a-z]+),\s*([^,]+?) "
        r"and ([^,]+?)\s*([.!]?)$"
    ).match(text)
    if m is not None and _only_person(m.group(2), lexicon) and _only_person(m.group(3), lexicon):
        return f"{m.group(2)} and {m.group(3)} each get {m.group(1)}{m.group(4)}"
    return " ".join(text.replace(",,", ",").split())


# -- counts --------------------------------------------------------------------------------------


def _singular(plural: str) -> str:
    return plural[:-2] if plural.endswith(("xes", "ches", "shes")) else plural[:-1]


def _count_frames(text: str, lexicon: Lexicon) -> str:
    """Counts said with the ones they count: each rewritten to the objects themselves, when the
    count is what the scene has (else left to be refused)."""
    objects = len(lexicon.scene.objects)
    # "two boxes, the medium and the big one": the medium box and the big box
    m = _rx(
        r"\b(?:two|2) ([a-z]+s)((?: (?:on|in|onto|into|to|for) [^,]+?)?),\s*the ([a-z]+)(?: one)? "
        r"and the ([a-z]+) one\b"
    ).search(text)
    if m is not None:
        one = _singular(m.group(1))
        first, second = f"the {m.group(3)} {one}", f"the {m.group(4)} {one}"
        a, b = _ids(first, lexicon, "object"), _ids(second, lexicon, "object")
        if len(a) == 1 and len(b) == 1 and a != b and a | b <= _ids(m.group(1), lexicon):
            text = f"{text[: m.start()]}{first} and {second}{m.group(2)}{text[m.end() :]}"
    # "a single pen, the blue one", "just the one spanner, the big one": the blue pen
    m = _rx(
        r"\b(?:a single|just the one|just one|only one|the one) ([a-z]+),\s*the ([a-z]+) one\b"
        r"(?!\s*(?:,|and\b|or\b|&))"
    ).search(text)
    if m is not None:
        said = f"the {m.group(2)} {m.group(1)}"
        if len(_ids(said, lexicon, "object")) == 1:
            text = f"{text[: m.start()]}{said}{text[m.end() :]}"
    # "the one and only bottle": the bottle (when there is one)
    m = _rx(r"\bthe one and only ([a-z]+)\b").search(text)
    if m is not None and len(_ids(m.group(1), lexicon, "object")) == 1:
        text = f"{text[: m.start()]}the {m.group(1)}{text[m.end() :]}"
    # "all four of the items": everything, when the scene has four
    m = _rx(r"\ball (two|three|four|five|six) of the (?:items|things|objects)\b").search(text)
    if m is not None and _COUNTS[m.group(1).lower()] == objects:
        text = f"{text[: m.start()]}everything{text[m.end() :]}"
    # "…, there's only the two things": a remark the scene bears out
    m = _rx(
        r",\s*there(?:'s| is| are) only (?:the )?(two|three|four|five|six) (?:things|items|objects)"
        r"\s*([.!]?)$"
    ).search(text)
    if m is not None and _COUNTS[m.group(1).lower()] == objects:
        text = text[: m.start()] + m.group(2)
    # "Both cups need washing, into the sink with them": put both cups in the sink
    m = _rx(
        r"^both ([a-z]+) (?:need|needs|are|could do with|want) [a-z ]+?,\s*(into|in|onto|on) "
        r"(the [a-z ]+?) with (?:them|'em)\s*([.!]?)$"
    ).match(text)
    if m is not None and len(_ids(m.group(1), lexicon, "object")) == 2:
        text = f"put both {m.group(1)} {m.group(2)} {m.group(3)}{m.group(4)}"
    # "Mrs Khan's getting the two blankets tonight, she's freezing": Mrs Khan gets them
    m = _rx(
        r"^([^,]+?)(?:'s| is) getting (the [a-z ]+?)(?: tonight| now| today| later)?(?:,\s*(?:she|"
        r"he)(?:'s| is) [a-z]+)?\s*([.!]?)$"
    ).match(text)
    if m is not None and _the_person(m.group(1), text, lexicon):
        text = f"{m.group(1)} gets {m.group(2)}{m.group(3)}"
    return text


# -- negation and exclusion ----------------------------------------------------------------------


def _exclusion_frames(text: str, lexicon: Lexicon) -> str:
    """Exclusions and negations said in other frames, each rewritten to the grammar's own."""
    # "Not Alice, Bob is the one who wants the bottle": Bob wants the bottle
    m = _rx(
        r"^not ([^,]+?),\s*([^,]+?) is the one (?:who|that) (wants|needs|gets|should get) (.+)$"
    ).match(text)
    if (
        m is not None
        and _only_person(m.group(1), lexicon)
        and _only_person(m.group(2), lexicon)
        and _ids(m.group(1), lexicon) != _ids(m.group(2), lexicon)
        and not _ids(m.group(4), lexicon, "human")
    ):
        return f"{m.group(2)} {m.group(3)} {m.group(4)}"
    # "the lot, minus the bottle", "everything, minus the cup": everything except
    text = _sub(r"\bthe lot\b(?=,?\s*(?:minus|except|but|apart from|bar)\b)", "everything", text)
    text = _sub(
        r"\beverything,?\s*(?:minus|bar|apart from)\s+(?=the\b)", "everything except ", text
    )
    # "Only the cup for Person A, nothing else": the cup for Person A
    m = _rx(r"^only (.+?),\s*nothing else\s*([.!]?)$").match(text)
    if m is not None and not _rx(r"\b(?:and|or|,)\b").search(m.group(1)):
        text = f"{m.group(1)}{m.group(2)}"
    # "Leave the apple, give Person B the rest": everything except the apple
    m = _rx(r"^leave (the [a-z ]+?),\s*(give|hand|pass) ([^,]+?) the rest\s*([.!]?)$").match(text)
    if m is not None and _ids(m.group(1), lexicon, "object") and _only_person(m.group(3), lexicon):
        text = f"{m.group(2)} {m.group(3)} everything except {m.group(1)}{m.group(4)}"
    # "Don't bother with the magazine, just take Mrs Khan her tablets": the second
    m = _rx(
        r"^(?:don't|do not) (?:bother|worry)(?: with| about) (the [a-z ]+?),\s*just (.+)$"
    ).match(text)
    if m is not None:
        left = _ids(m.group(1), lexicon, "object")
        if left and not left & _ids(m.group(2), lexicon):
            text = m.group(2)
    # "No banana for Emma, she wants the white cup": Emma wants the white cup
    m = _rx(
        r"^no ([a-z ]+?) for ([^,]+?),\s*(?:she|he)(?:'d| would)? (?:wants?|needs?|like|prefers?|"
        r"'d rather have) (the [a-z ]+?)\s*([.!]?)$"
    ).match(text)
    if (
        m is not None
        and _the_person(m.group(2), text, lexicon)
        and _ids(m.group(1), lexicon, "object")
        and _ids(m.group(3), lexicon, "object")
        and not _ids(m.group(1), lexicon) & _ids(m.group(3), lexicon)
    ):
        text = f"{m.group(2)} wants {m.group(3)}{m.group(4)}"
    return text


# -- corrections ---------------------------------------------------------------------------------


def _correction_frames(text: str, lexicon: Lexicon) -> str:
    """Corrections said in other frames, each rewritten to 'X, no, Y'."""
    # ", no wait," ", correction," ", no, silly me," ", sorry, silly me,": no
    text = _sub(
        r",\s*(?:no,?\s*wait|correction|no,?\s*silly me|sorry,?\s*silly me|no,?\s*my mistake)"
        r"\s*,\s*(?=[a-z])",
        ", no, ",
        text,
    )
    # "Spoon to Dana, no, spoon to Emma": the same object to another person
    m = _rx(
        r"^((?:the )?[a-z ]+?) (to|for) ([^,]+?),\s*no,\s*(?:the )?([a-z ]+?) (to|for) ([^,.!]+?)"
        r"\s*([.!]?)$"
    ).match(text)
    if m is not None:
        said, again = _ids(m.group(1), lexicon, "object"), _ids(m.group(4), lexicon, "object")
        if said and said == again and _only_person(m.group(6), lexicon):
            text = f"{m.group(1)} {m.group(2)} {m.group(3)}, no, to {m.group(6)}{m.group(7)}"
    # "…, sorry, blue plate, the white one's chipped": the reason for the correction
    text = _sub(
        r"(,\s*(?:no|sorry),\s*[^,]+?),\s*the [a-z]+ one(?:'s| is) (?:chipped|cracked|dirty|broken|"
        r"empty|wrong|used|wet|full|too [a-z]+)\s*([.!]?)$",
        r"\1\2",
        text,
    )
    # "…, or hang on, was it the crisps she wanted? Yes, the crisps.": no, the crisps
    m = _rx(
        r",?\s*or (?:hang on|hold on|wait),?\s*was it (the [a-z ]+?) (?:she|he|they) wanted\?\s*"
        r"(?:yes|yeah|yep),?\s*(the [a-z ]+?)\s*([.!]?)$"
    ).search(text)
    if (
        m is not None
        and _ids(m.group(1), lexicon) == _ids(m.group(2), lexicon)
        and _ids(m.group(1), lexicon, "object")
    ):
        text = f"{text[: m.start()]}, no, {m.group(2)}{m.group(3)}"
    # "No, not bowl, I said spoon.": no, the spoon
    text = _sub(
        r"\bno,?\s*not (?:the )?([a-z ]+?),\s*i (?:said|meant|mean) (?:the )?([a-z ]+?)\s*([.!]?)$",
        lambda x: (
            f"No, the {x.group(2)}{x.group(3)}"
            if _ids(x.group(1), lexicon, "object")
            and _ids(x.group(2), lexicon, "object")
            and _rx(rf"\b{re.escape(x.group(1))}\b").search(text[: x.start()])
            else x.group(0)
        ),
        text,
    )
    # "… the red book on the desk. Wait, not the red book, the scissors.": said in its place
    m = _rx(
        r"(?<=[.!])\s*(?:wait|no|sorry|oh),?\s*not (the [a-z ]+?),\s*(the [a-z ]+?)\s*([.!]?)$"
    ).search(text)
    if m is not None:
        before = text[: m.start()]
        found = list(_rx(rf"\b{re.escape(m.group(1))}\b").finditer(before))
        if len(found) == 1 and _ids(m.group(2), lexicon, "object") and _ids(m.group(1), lexicon):
            at = found[0]
            text = f"{before[: at.start()]}{m.group(2)}{before[at.end() :]}"
    return text


# -- session 17: blind15's kinds, each a general rewrite (courtesy and address, wants, remarks,
# run-ons and dictation, choices, counts, exclusions, corrections, questions) ----------------

_ENDEARING = r"(?:love|dear|darling|pet|sweetheart|star|good (?:robot|lad|girl|boy|helper))"


def _courtesy17(text: str, lexicon: Lexicon) -> str:
    """Courtesy that asks nothing: 'sorry to interrupt', 'could I trouble you to' (the hearer
    does it), 'Now then, dear,', 'be a good helper and', '…, won't you?', '…, there's a love',
    'Oh dear,' opening a remark, and a person thanked by role after the request ('Thanks chef.':
    said to the one who spoke, not asking anything for them)."""
    out = _sub(r"\b(?:so |very )?sorry to (?:interrupt|butt in|bother you)\s*,\s*", "", text)
    out = _sub(r"\bcould I (?:trouble|bother) you to\b", "could you", out)
    out = _sub(r"^(?:now then|oh dear)\s*,\s*(?:dear\s*,\s*)?", "", out)
    out = _sub(rf"\bbe an? (?:{_ENDEARING}|angel) and (?=[a-z])", "", out)
    out = _sub(r",\s*won't you\s*([?.!]*)\s*$", r"\1", out)
    out = _sub(rf",\s*there's an? {_ENDEARING}\s*([.!]*)\s*$", r"\1", out)

    def thanked(m: re.Match[str]) -> str:
        return m.group(1) if _only(m.group(2), lexicon, "human") else m.group(0)

    # "Salt to Lena. Thanks chef.": the chef is thanked; "Thanks chef, and the knife to you" stays
    return _sub(r"([.!])\s*(?:thanks|thank you|cheers|ta)\s+([a-z]+)\s*[.!]*\s*$", thanked, out)


def _wants17(text: str, lexicon: Lexicon) -> str:
    """'P is hoping to get X', 'P could do with X', 'P is to have X', 'P (in bed two) is due
    (his) X': P wants X (the speaker's 'I could do with' stays refused: 'I' is no one here)."""

    def wants(m: re.Match[str]) -> str:
        return f"{m.group(1)} wants" if _only_person(m.group(1), lexicon) else m.group(0)

    out = _sub(
        r"^([a-z][\w ]*?)(?: in bed (?:one|two|three|four|five|six|\d+))?(?: is|'s) (?:hoping to "
        r"get|to have|due|borrowing)\b",
        wants,
        text,
    )
    out = _sub(r"^([a-z][\w ]*?) could do with\b", wants, out)

    def asked(m: re.Match[str]) -> str:
        if not _the_person(m.group(1), text, lexicon):
            return m.group(0)
        return f"{m.group(1)} wants the "

    # "Bob asked for his apple", "Lily's crying for her teddy": what they asked for is theirs
    return _sub(
        r"^([a-z][\w ]*?)(?:'s| is| has)? (?:asked|asking|crying|calling|begging) for (?:his|her) ",
        asked,
        out,
    )


def _see_it17(text: str, lexicon: Lexicon) -> str:
    """'See the torch? Take it over to Kofi.', 'The red book's overdue. Put it back …': an object
    pointed at or remarked on in a first sentence, then 'it' in the request: that object."""

    def it_is(m: re.Match[str]) -> str:
        # group 2 is the remark ("overdue"), or the space after a question: it names nothing
        if not _only(m.group(1), lexicon, "object") or not _names_nothing(m.group(2), lexicon):
            return m.group(0)
        return f"{m.group(3)} {m.group(1)}"

    out = _sub(r"^(?:see|you see) (the [a-z ]+?)\?(\s*)([a-z]+) it\b", it_is, text)
    return _sub(
        r"^(the [a-z ]+?)(?:'s| is) ([a-z]+)[.!]\s*((?:put|pop|take|bring|pass|hand|give) ?)it\b",
        it_is,
        out,
    )


def _same_but17(text: str, lexicon: Lexicon) -> str:
    """'Give Bob the cup, and do the same for Carol but with the apple': the apple to Carol."""

    def same(m: re.Match[str]) -> str:
        if not _only_person(m.group(3), lexicon) or not _only(m.group(4), lexicon, "object"):
            return m.group(0)
        return f"{m.group(1)}, {m.group(2)} {m.group(4)} to {m.group(3)}{m.group(5)}"

    return _sub(
        r"^(.+?),?\s*(and|then) do the same for ([a-z][\w ]*?),? but with (the [a-z ]+?)"
        r"\s*([.!]?)$",
        same,
        text,
    )


def _both_them17(text: str, lexicon: Lexicon) -> str:
    """'The small box and the medium box: put them both on the pallet': those two there."""

    def both(m: re.Match[str]) -> str:
        if len(_ids(m.group(1), lexicon, "object")) != 2 or _ids(m.group(1), lexicon, "human"):
            return m.group(0)
        return f"{m.group(2)} {m.group(1)} {m.group(3)} "

    return _sub(
        r"^(the [a-z ]+? and the [a-z ]+?)\s*:\s*(put|pop|place|stick|move) them(?: both)? "
        r"(on|onto|in|into) ",
        both,
        text,
    )


def _run_ons17(text: str, lexicon: Lexicon) -> str:
    """Dictation and run-ons: 'Scene change.'/'New job.' opening, 'Pens first:' heading the
    first step, 'After,' for 'Then', 'Finish.' closing, '…, and that's your lot', 'and, hang on,
    yeah, and …, that's it', and a list dictated as 'Black pen: Sam. Red pen: box.'"""
    out = _sub(r"^(?:scene change|new job|next job|new task)\s*[.!:]\s*", "", text)
    out = _sub(r"^[a-z]+ first\s*:\s*(?=.+[.!;]\s*then\b)", "", out)
    out = _sub(r"(?<=[.!])\s*after\s*,\s*", " Then ", out)
    out = _sub(r"(?<=[.!])\s*(?:finish|finished|end)\s*[.!]*\s*$", "", out)
    out = _sub(r",?\s*and that's your lot\s*([.!]?)\s*$", r"\1", out)

    def counted(m: re.Match[str]) -> str:
        # a step names something: "and that's your lot. Have a great day." is none
        pieces = re.split(r",\s*(?:and\s+)?|\s+and\s+|(?<=[.!?])\s+", m.group(2))
        steps = [x for x in pieces if x.strip() and not _names_nothing(x, lexicon)]
        return m.group(2) if len(steps) == _NUMBERS15[m.group(1).lower()] else m.group(0)

    # "Okay two things, salt to Marco, lemon to Lena": the count is the steps that follow
    out = _sub(
        r"^(?:(?:okay|right|so)\s*,?\s*)?(two|three|four) (?:things|jobs)\s*,\s*(.+)$", counted, out
    )
    out = _sub(r"\band\s*,\s*hang on\s*,\s*(?:yeah|yes|yep)\s*,\s*and\b", "and", out)
    out = _sub(r"(?<=\S),\s*that's it\s*([.!]?)\s*$", r"\1", out)
    parts = [p.strip() for p in re.split(r"(?<=[.!])\s+", out.strip()) if p.strip()]
    lines = [re.match(r"^([a-z][a-z ]*?)\s*:\s*([a-z][\w ]*?)\s*[.!]?$", p, _F) for p in parts]
    if len(parts) < 2 or any(m is None for m in lines):
        return out
    said = []
    for m in lines:
        assert m is not None
        if not _only(m.group(1), lexicon, "object"):
            return out
        if _only_person(m.group(2), lexicon):
            said.append(f"the {m.group(1)} to {m.group(2)}")
        elif _only(m.group(2), lexicon, "surface"):
            said.append(f"the {m.group(1)} on the {m.group(2)}")
        else:
            return out
    return ". ".join(said) + "."


def _choices17(text: str, lexicon: Lexicon) -> str:
    """'whichever X you like' (the robots choose), 'Either X is fine for P', '…, whoever's
    nearer' after 'to P or (to) Q', 'One of the X for P: the A or the B'."""
    out = _sub(r"\bwhichever ([a-z]+) you (?:like|want|fancy|prefer)\b", r"whichever \1", text)

    def either(m: re.Match[str]) -> str:
        if not _only_person(m.group(2), lexicon):
            return m.group(0)
        return f"give {m.group(2)} either {m.group(1)}{m.group(3)}"

    out = _sub(
        r"^either ([a-z]+) is (?:fine|okay|ok|good) for ([a-z][\w ]*?)\s*([.!]?)$", either, out
    )

    def whoever(m: re.Match[str]) -> str:
        if not _only_person(m.group(2), lexicon) or not _only_person(m.group(3), lexicon):
            return m.group(0)
        return f"{m.group(1)} to {m.group(2)} or to {m.group(3)}{m.group(4)}"

    out = _sub(
        r"^(.+?) to ([a-z][\w ]*?) or (?:to )?([a-z][\w ]*?)\s*,\s*whoever(?:'s| is) (?:nearer|"
        r"closer|nearest|closest|free)\s*([.!]?)$",
        whoever,
        out,
    )

    def one_of(m: re.Match[str]) -> str:
        kind = m.group(1).removesuffix("s")
        if not _only_person(m.group(2), lexicon):
            return m.group(0)
        picks = []
        for said in (m.group(3), m.group(4)):
            name = said if said.endswith(f" {kind}") else f"{said} {kind}"
            ids = _ids(name, lexicon, "object")
            cats = {o.category for o in lexicon.scene.objects if o.id in ids}
            if len(ids) != 1 or cats != {kind}:
                return m.group(0)  # "One of the drinks …: the bottle or the chips": not read
            picks.append(name)
        return f"give {m.group(2)} {picks[0]} or {picks[1]}{m.group(5)}"

    return _sub(
        r"^one of the ([a-z]+) for ([a-z][\w ]*?)\s*:\s*(the [a-z ]+?) or (the [a-z ]+?)"
        r"\s*([.!]?)$",
        one_of,
        out,
    )


def _counts17(text: str, lexicon: Lexicon) -> str:
    """'the pair of X' (the two X), '…, there's just the one', 'the only/single X there is',
    'every one of the four X' (all four of the X), 'a couple of things, namely A and B' (when
    two are named)."""
    out = _sub(r"\bthe pair of ([a-z]+s)(?=\s*,\s*the\b)", r"two \1", text)
    out = _sub(r"\bthe pair of ([a-z]+s)\b", r"the two \1", out)
    out = _sub(r",\s*there(?:'s| is) (?:just |only )?the one\s*([.!]?)\s*$", r"\1", out)
    out = _sub(r"\bthe (?:only|single|one) ([a-z ]+?) there is\b", r"the \1", out)
    out = _sub(r"\bevery one of the (two|three|four|five|six) ", r"all \1 of the ", out)

    def namely(m: re.Match[str]) -> str:
        if (
            len(_ids(m.group(1), lexicon, "object")) != 2
            or len(re.findall(r"\bthe\b", m.group(1), _F)) != 2
        ):
            return m.group(0)
        return m.group(1)

    return _sub(r"\ba couple of things\s*,?\s*namely\s+(.+?)(?=\s*[.!]?$)", namely, out)


def _exclusions17(text: str, lexicon: Lexicon) -> str:
    """'whichever X isn't the Y one' (any X but that one), 'everything besides', 'P's having',
    'P, but not Q, gets', 'Leave X where it is and …' (X not asked for after)."""
    out = _sub(
        r"\bwhichever ([a-z]+) (?:isn't|is not) the ([a-z]+) one\b",
        r"any \1 except the \2 one",
        text,
    )
    out = _sub(r"\bbesides\b", "except", out)
    out = _sub(r"^([a-z][\w ]*?)(?:'s| is) having\b", r"\1 gets", out)

    def but_not(m: re.Match[str]) -> str:
        a, b = _ids(m.group(1), lexicon, "human"), _ids(m.group(2), lexicon, "human")
        if not _only_person(m.group(1), lexicon) or not _only_person(m.group(2), lexicon) or a == b:
            return m.group(0)
        return f"{m.group(1)} "

    out = _sub(r"^([a-z][\w ]*?),\s*but not ([a-z][\w ]*?),\s*", but_not, out)

    def left(m: re.Match[str]) -> str:
        ids = _ids(m.group(1), lexicon, "object")
        if not ids or ids & _ids(m.group(2), lexicon, "object"):
            return m.group(0)
        if re.search(r"\b(?:else|rest|other|others|everything|all)\b", m.group(2), _F):
            return m.group(0)  # "Leave the mugs alone and give Bob everything else": said apart
        return m.group(2)

    out = _sub(r"\b(put|give|hand|pass) only (the|a|an)\b", r"\1 \2", out)
    return _sub(
        r"^leave (the [a-z ]+?) (?:where (?:it is|they are)|alone)\s*,?\s*(?:and\s+)?(.+)$",
        left,
        out,
    )


def _corrections17(text: str, lexicon: Lexicon) -> str:
    """'…, no not the X, the Y!' (no, the Y), 'X to P. No no, not P. X to Q.' (no, X to Q),
    'X to P. Actually no, Y to P.', '…, whoops, I meant …', '…, correction, X in S' (no)."""
    out = _sub(r",\s*no,? not (the [a-z ]+?),\s*(the [a-z ]+?)\s*([!.]?)$", r", no, \2\3", text)
    out = _sub(r"([.!])\s*no,?(?: no,?)? not ([a-z][\w ]*?)[.!]\s*(?=\S)", ", no, ", out)
    out = _sub(r"([.!])\s*actually,? no,?\s*(?=\S)", ", no, ", out)
    out = _sub(r",\s*(?:whoops|oops|oh)\s*,\s*i meant\b", ", no, I meant", out)

    def placed(m: re.Match[str]) -> str:
        # "Drill to Jess, correction, drill in the locker": the same object put somewhere instead
        if not _only(m.group(1), lexicon, "object") or not _only_person(m.group(2), lexicon):
            return m.group(0)
        if _ids(m.group(3), lexicon, "object") != _ids(m.group(1), lexicon, "object"):
            return m.group(0)
        if not _only(m.group(5), lexicon, "surface"):
            return m.group(0)
        return f"put the {m.group(3)} {m.group(4)} {m.group(5)}{m.group(6)}"

    out = _sub(
        r"^(?:the )?([a-z ]+?) to ([a-z][\w ]*?),\s*(?:correction|no|sorry),\s*(?:the )?([a-z ]+?) "
        r"(in|on|into|onto) (the [a-z ]+?)\s*([.!]?)$",
        placed,
        out,
    )

    def swapped(m: re.Match[str]) -> str:
        # "Lemon to Marco then knife to Lena, sorry, swap the people": lemon to Lena, knife to Marco
        p, q = m.group(2), m.group(5)
        if not _only_person(p, lexicon) or not _only_person(q, lexicon):
            return m.group(0)
        if _ids(p, lexicon, "human") == _ids(q, lexicon, "human"):
            return m.group(0)
        return f"{m.group(1)} to {q} {m.group(3)} {m.group(4)} to {p}{m.group(6)}"

    return _sub(
        r"^((?:the )?[a-z ]+?) to ([a-z][\w ]*?) (then|and) ((?:the )?[a-z ]+?) to ([a-z][\w ]*?)"
        r",\s*(?:sorry|no|wait|oops)\s*,\s*swap the (?:people|names|two of them)\s*([.!]?)$",
        swapped,
        out,
    )


def _questions17(text: str, lexicon: Lexicon) -> str:
    """'You can give X to P, yes?', 'passing X along to P', 'Any chance of X going to P?', 'the
    X can sit on S'."""
    out = _sub(r"^you can (.+?),\s*(?:yes|right|yeah|okay|ok)\s*\?$", r"\1", text)
    # "Drop the bowl in the sink for washing": why it goes there asks nothing more
    out = _sub(
        r"(\b(?:in|on|into|onto) the [a-z ]+?) for (?:washing|washing up|drying|cleaning|charging)"
        r"\s*([.!]?)\s*$",
        r"\1\2",
        out,
    )
    out = _sub(
        r"\b(pass(?:ing)?|hand(?:ing)?|take|taking|bring(?:ing)?) (the [a-z ]+?) along to\b",
        r"\1 \2 to",
        out,
    )
    out = _sub(
        r"^any chance of (the [a-z ]+?) going (to|on|onto|in|into) (.+?)\?$", r"\1 \2 \3", out
    )

    def theirs(m: re.Match[str]) -> str:
        # "take Mrs Khan's tablets over to her": hers, to her
        if not _only_person(m.group(2), lexicon) or not _only(m.group(3), lexicon, "object"):
            return m.group(0)
        pid = next(iter(_ids(m.group(2), lexicon, "human")))
        if title_sex(pid, lexicon) != PRONOUN_SEX[m.group(4).lower()]:
            return m.group(0)  # a name alone does not say who 'her' is
        return f"{m.group(1)} the {m.group(3)} over to {m.group(2)}"

    out = _sub(
        r"\b(take|bring|pass|carry) ([a-z][\w ]*?)'s ([a-z ]+?) over to (him|her)\b", theirs, out
    )
    return _sub(r"^(the [a-z ]+?) can (?:sit|go|live|stay) (on|onto|in|into) ", r"put \1 \2 ", out)


# -- session 18: blind16's kinds, by mechanism: a speaker's own words around the request --------
#
# New speakers bring their own openers, closers, calls and tics ("Kia ora", "gg", "my bad",
# "going once, going twice", "C-could", "the, the blue mug"). Rather than one frame per sentence,
# three mechanisms: a stammer or a restart is read as the word said in full; an idiom of address,
# sign-off, hurry or praise (a lexicon by kind, below) is said to no one about nothing; and a
# stretch at either edge of the request made only of such words (or of short chat tokens that
# are no English word, no first name and name nothing in the scene, not even by a typo) is
# taken off. A stretch that could name a scene person or object, or holds a held word (a verb,
# a number, a negation, 'or', 'then', a pronoun, a preposition), is never taken off.

# "C-could", "g-give", "Th-thanks": the word said in full
_STAMMER = re.compile(r"\b([a-z]{1,3})-(?=\1[a-z])", _F)
# "the b-, the bottle", "the sc-, the scanner", "the h- the hammer": a word cut off and said again
_RESTART = re.compile(
    r"\b(?:(the|a|an|my|his|her|their) )?([a-z]{1,4})-\s*,?\s*(?=(?:(?:the|a|an|my|his|her|their) )"
    r"?\2[a-z])",
    _F,
)
# "the, the blue mug", "on the, on the high chair", "the, um, the the apple": a restart
_FILLER = r"(?:\s*,?\s*\b(?:um+|uh+|er+|erm+|ah+)\b\s*,?\s*|\s*,\s*|\s+)"
_REPEATED = re.compile(
    rf"\b((?:(?:to|on|onto|in|into|for|at|of|with) )?(?:the|a|an|my|his|her|to|on|in|for)){_FILLER}"
    r"\1\b",
    _F,
)


def _stammers18(text: str, _lexicon: Lexicon) -> str:
    """A stammered word ('C-could'), a word cut off and said again ('the b-, the bottle') and a
    function word said twice ('the, the blue mug') read as said once. A word cut off and not said
    again ('Give Jess the sp-') is left, and refused."""
    out = _sub(r"\bmy bad\b", "my mistake", text)
    if "-" not in out and not re.search(r"\b(\w+(?: \w+)?)\W+\1\b", out, _F):
        return out
    out = _STAMMER.sub("", out)
    out = _RESTART.sub("", out)
    for _ in range(3):
        again = _REPEATED.sub(r"\1", out)
        if again == out:
            break
        out = again
    return out


# Idioms said to no one about nothing, by kind; each is taken off wherever it stands as a stretch
# of its own (between punctuation or at an edge), and only when it names nothing in the scene.
_IDIOMS18: dict[str, tuple[str, ...]] = {
    "address": (
        "ladies and gentlemen",
        "boys and girls",
        "my friends?",
        "my good (?:man|woman|sir)",
        "big (?:man|guy|fella)",
        "chat",
        "y'all",
        "you lot",
        "you guys",
        "everybody",
        "people",
        "lads",
        "guys",
        "team",
        "bestie",
        "bruv",
        "matey?",
        "shipmate",
        "partner",
        "tower",
        "good robot",
        "captain",
        *("hon", "hun", "love", "dear", "mate", "pal", "sweetie", "darling", "folks", "everyone"),
    ),
    "greeting": (
        *("and now", "roger(?: that)?", "copy(?: that)?(?:,? copy)?", "mmm+", "eh", "right then"),
        "kia ora(?: mate)?",
        "g'day(?: mate)?",
        "howdy(?: partner)?",
        "ahoy(?: there)?",
        "ey up(?: love)?",
        "namaste",
        "hey there",
        "good evening and welcome",
        "yo",
        "arr(?:,? matey)?",
        "prithee(?:,? good robot)?",
    ),
    "sign-off": (
        *("y'hear", "then we're (?:done|finished)", "let's hear it(?:,? everybody)?", "play on"),
        "over and out",
        "over",
        "out",
        "sweet as",
        "no worries",
        "no cap",
        "fr",
        "gg",
        "ez",
        "ez clap",
        "gg ez",
        "lol",
        "lmao",
        "tysm",
        "ty",
        "tbh",
        "innit",
        "safe",
        "slay",
        "respect",
        "legend",
        "much obliged",
        "thank ya kindly",
        "thanks in advance",
        "best regards",
        "kind regards",
        "cheerio",
        "anon",
        "encore",
        "bravo(?:,? bravo)?",
        "checkmate",
        "yo ho ho",
        "and bob's your uncle",
        "bob's your uncle",
        "ta-da",
        "appreciate it",
        "all done",
        "there we go",
        "job done",
        "great (?:show|energy|work|job)(?: (?:tonight|today|everyone|team))?",
        "good (?:hustle|work|job|show)(?:,? (?:team|everyone|folks))?",
        "(?:nice|good) work",
        "totally stoked",
        "stoked",
        "gnarly",
        "dude",
        "zzz+",
        "yawn",
        "good grief",
        "omg",
        "argh+",
        "ugh+",
        "ooh",
        "wow",
    ),
    "hurry": (
        "let's (?:hustle|roll|go|move)",
        "(?:off|away|on) you (?:go|pop)",
        "come on(?:,? come on)*(?:,? (?:let's )?move(?: it)?)?",
        "move(?: it)?",
        "chop chop",
        "hop to it",
        "on the double",
        "pronto",
        "rn",
        "asap",
        "listen up(?:,? (?:people|everyone|team))?",
        "heads up(?:,? team)?",
        "when (?:u|you) get a (?:chance|sec|minute|moment)",
        "when (?:ur|you're) free",
        "no hurry",
        "no rush",
        "crack on",
        "right-o",
        "righty ho",
    ),
    # the speaker's own aside about the request or the day, asking nothing
    "aside": (
        *("mark my words", "per my last email", "(?:just )?circling back", "quick one"),
        *(
            "(?:just )?a (?:gentle|quick|friendly) reminder",
            "(?:sorry,? )?long (?:night|day|shift)",
        ),
        *("this is your captain speaking", "attention(?:,? please| please)?", "watch this"),
        "at your (?:earliest )?convenience",
        *("thank you for (?:flying with us|your patience)", "(?:ok )?chat,? watch this"),
        *("for tonight's star prize", "(?:i'm|i am) half asleep(?: anyway)?", "whenever"),
        *(
            "whenever you're (?:fixin'?|fixing|ready)(?: to)?",
            "crack on",
            "let's (?:hustle|roll|go|move)(?: it)?",
        ),
    ),
    "filler": ("well", "you know", "um+", "uh+", "er+", "erm+", "hmm+"),
    "auction": ("going once", "going twice", "going once,? going twice", "sold"),
}
_IDIOM18 = re.compile(
    r"^(?:"
    + "|".join(sorted((i for kind in _IDIOMS18.values() for i in kind), key=len, reverse=True))
    + r")$",
    _F,
)
# said without punctuation at the very start or end: greetings, sign-offs and chat (not address,
# which may be a subject, 'Everybody gets a cup', nor a call that may ask, 'move it')
_WORD_IDIOM18 = re.compile(
    r"^(?:"
    + "|".join(
        sorted(
            (
                i
                for kind in ("greeting", "sign-off")
                for i in _IDIOMS18[kind]
                if i not in ("over", "out", "safe", "respect", "legend", "wow")
            ),
            key=len,
            reverse=True,
        )
    )
    + r"|when (?:u|you) get a (?:chance|sec|minute|moment)|when (?:ur|you're) free|asap|rn"
    + r")$",
    _F,
)
_HESITATION = re.compile(r"^(?:um+|uh+|er+|erm+|hmm+)$", _F)
# a stretch of the text: between commas, sentence ends, colons, dashes and ellipses
_STRETCH = re.compile(r"(\s*(?:[,;:!?—–]|\.{2,}|…|\.(?=\s|$)|\s-\s)\s*)")


def _idiom_stretch(chunk: str, lexicon: Lexicon) -> bool:
    plain = chunk.strip(" .!?,'\"").lower()
    plain = re.sub(r"\s+", " ", plain)
    bare = re.sub(r"^(?:and|so) ", "", plain)  # "…, and bob's your uncle", "…, so crack on"
    return (
        bool(plain)
        and bool(_IDIOM18.match(plain) or _IDIOM18.match(bare))
        and _names_nothing(chunk, lexicon)
    )


_WORDS_KEPT: dict[int, tuple[Scene, frozenset[str]]] = {}


def _scene_words(scene: Scene) -> frozenset[str]:
    """Every word of every name in the scene ('b' of 'Person B', 'mr' of 'Mr Lee'; kept by the
    scene itself, as _scene_adjectives)."""
    kept = _WORDS_KEPT.get(id(scene))
    if kept is not None and kept[0] is scene:
        return kept[1]
    out = _scene_words_now(scene)
    if len(_WORDS_KEPT) > 64:
        _WORDS_KEPT.clear()
    _WORDS_KEPT[id(scene)] = (scene, out)
    return out


def _scene_words_now(scene: Scene) -> frozenset[str]:
    names = [o.id for o in scene.objects] + [h.id for h in scene.humans]
    names += [s.id for s in scene.surfaces] + [h.name for h in scene.humans]
    for x in (*scene.objects, *scene.humans, *scene.surfaces):
        names += list(getattr(x, "aliases", ()))
    return frozenset(w for n in names for w in re.split(r"[\s_]+", n.lower()) if w)


@functools.cache
def _verbs_of_length(n: int) -> tuple[str, ...]:
    """The verbs of one word whose length is ``n - 1`` to ``n + 1``: those _near_verb compares a
    word of ``n`` letters with (session 46, 12p: it had compared every verb)."""
    return tuple(v for v in VERBS if abs(len(v) - n) <= 1 and " " not in v)


@functools.lru_cache(maxsize=4096)
def _near_verb(word: str) -> bool:
    """Whether ``word`` is one edit from a verb the grammar reads ('hnad' for 'hand')."""
    for verb in _verbs_of_length(len(word)):
        if len(verb) == len(word):
            diff = [k for k in range(len(word)) if verb[k] != word[k]]
            if len(diff) == 1 or (
                len(diff) == 2
                and diff[1] == diff[0] + 1
                and verb[diff[0]] == word[diff[1]]
                and verb[diff[1]] == word[diff[0]]
            ):
                return True
        else:
            short, long_ = sorted((verb, word), key=len)
            if any(long_[:k] + long_[k + 1 :] == short for k in range(len(long_))):
                return True
    return False


def _word_idiom(words: str, lexicon: Lexicon) -> bool:
    plain = re.sub(r"\s+", " ", words.strip(" .!?,'\"").lower())
    return bool(plain) and bool(_WORD_IDIOM18.match(plain)) and _names_nothing(words, lexicon)


def _word_idiom_may(said: str) -> bool:
    """Session 55 (12p): False only where _word_idiom is false of every stretch of ``said`` (words
    joined by single spaces): the gate finds none of _WORD_IDIOM18's words in it lower-cased, and
    a stretch's plain form is a piece of that."""
    return re.may_match(_WORD_IDIOM18.pattern, int(_WORD_IDIOM18.flags), said.lower())


_P = r"([A-Za-z][\w ]*?)"  # a person's name (checked by the rewrite)
_X = r"([A-Za-z][\w ,'-]*?)"  # what is asked for (checked by the rewrite)
# what a thing is wanted for: an occasion, which names no one and nothing in the scene
_OCCASION = (
    r"(?:meeting|stand-up|standup|one-to-one|round|rounds|job|jobs|inspection|tour|trip|film|"
    r"movie|show|party|class|lesson|lecture|presentation|demo|shift|service|match|game|test|exam|"
    r"session|call|interview|break|picnic|journey|drive|ride|weekend|trick|rehearsal|practice|"
    r"training|workout|walk|nap|bath|bedtime|story|project|review|audit|visit|week|day|night|"
    r"part)"
)
_DEADLINE = (
    r"(?:end of (?:the )?day|eod|close of play|lunch|lunchtime|noon|midday|tonight|this "
    r"(?:evening|afternoon)|the end of the (?:day|shift))"
)


def _frames18(text: str, lexicon: Lexicon) -> str:
    """blind16's frames of courtesy, wants, purposes and choices, each a general rewrite whose
    people and objects are checked against the scene:

    - asked of a person: 'Would P be so kind as to accept X (from you)?', 'Would P be able to
      have X?', 'Is P able to get X, do you reckon?' (can P have X), 'What P really needs right
      now is X' (P needs X), 'Might P be furnished with X?', 'might X be conveyed to P';
    - conditions of courtesy: 'If it would not be too much trouble,', 'If it's no bother,', 'if
      my lovely assistant would kindly …';
    - wants: 'is keen on', 'would care for', 'has expressed a wish for / an interest in',
      'requires', 'is going home with', 'takes home', 'should be furnished with';
    - purposes and deadlines that name nothing in the scene: 'for the stand-up', 'for the next
      part of the tour', 'by end of day', '… so he can clean up';
    - choices: 'apiece' (each), 'dont' (don't), 'not a big deal / blocker', 'colours don't
      matter', 'any colour will do' after a choice."""
    low = text.lower()
    out = text

    def asked(m: re.Match[str]) -> str:
        if not _only_person(m.group(1), lexicon) or _ids(m.group(2), lexicon, "human"):
            return m.group(0)
        if not _ids(m.group(2), lexicon, "object"):
            return m.group(0)
        return f"give {m.group(1)} {m.group(2)}"

    out = _sub(
        rf"^(?:would|could|will) {_P} be (?:so kind|so good|good enough|kind enough) as to "
        rf"(?:accept|take|receive|have) {_X}(?: from you)?\s*\?$",
        asked,
        out,
    )
    out = _sub(
        rf"^(?:would|could|will|is|are) {_P} (?:be )?able to (?:have|get|take|receive|borrow) "
        rf"{_X}"
        r"(?: from you)?(?:,? do you (?:think|reckon))?\s*\?$",
        asked,
        out,
    )
    out = _sub(
        rf"^might {_P} be (?:brought|given|handed|passed|furnished with|provided with) {_X}\s*\?$",
        asked,
        out,
    )

    def conveyed(m: re.Match[str]) -> str:
        if not _only_person(m.group(2), lexicon) or _ids(m.group(1), lexicon, "human"):
            return m.group(0)
        return f"take {m.group(1)} to {m.group(2)}{m.group(3)}"

    out = _sub(
        rf"\b(?:might|could|may|can) {_X} be (?:conveyed|taken|brought|carried|delivered) to "
        rf"{_P}(\s*[.!?]|$)",
        conveyed,
        out,
    )

    def what_needs(m: re.Match[str]) -> str:
        if not _only_person(m.group(2), lexicon) or not _ids(m.group(3), lexicon, "object"):
            return m.group(0)
        if _ids(m.group(3), lexicon, "human") or re.match(r"(?:not|never|no)\b", m.group(3), _F):
            return m.group(0)  # "what Bob needs is not the cup" says what he does not need
        return f"{m.group(1)}{m.group(2)} needs {m.group(3)}{m.group(4)}"

    # session 27 (12r): also after a comma or 'and' ("…, and what P wants is X"), and 'the one
    # thing' / 'the only thing' / 'all' for 'what' (never 'the last thing': he does not want it)
    out = _sub(
        rf"{_OPEN}(?:what|the (?:one|only) thing|all) {_P} (?:really |actually |most )?(?:needs|"
        rf"wants|could (?:really )?use|could do with|would like)(?: right now| now| most)? is "
        rf"{_X}(\s*[,.!]|$)",
        what_needs,
        out,
    )

    def the_one_who(m: re.Match[str]) -> str:
        # "Person A's the one who wants it": Person A wants it; "the one who needs the cup is
        # Bob": Bob needs it (the person checked to be one, the object an object or it/them)
        who, what = (m.group(2), m.group(3)) if m.group(2) else (m.group(5), m.group(4))
        if not _only_person(who, lexicon) or _ids(what, lexicon, "human"):
            return m.group(0)
        if not (_ids(what, lexicon, "object") or re.fullmatch(r"it|them", what.strip(), _F)):
            return m.group(0)
        return f"{m.group(1)}{who} wants {what}{m.group(6)}"

    out = _sub(
        rf"{_OPEN}(?:{_P}(?:'s| is) the (?:one|person) (?:who|that) (?:wants|needs|asked for) "
        rf"{_X}|the (?:one|person) (?:who|that) (?:wants|needs|asked for) {_X} is {_P})"
        r"(\s*[,.!?]|$)",
        the_one_who,
        out,
    )

    def wanted_by(m: re.Match[str]) -> str:
        # "The bottle's wanted by Person A": Person A wants it (a passive of wanting)
        things, who = m.group(2), m.group(3)
        if not _only_person(who, lexicon) or not _only_kind(things, lexicon, "object"):
            return m.group(0)
        gap = r"^\s*,?\s*(?:and |or |but |plus |then )?(?:the |a |an )(?:(?!is |are |was )[\w ])+?"
        gap += r" by\b"
        if re.search(gap, m.string[m.end() :], _F):
            return m.group(0)  # "…, and the crisps by Bob": the gap would read 'by' as a place
        return f"{m.group(1)}{who} wants {things}"

    out = _sub(
        rf"{_OPEN}((?:the |a |an |that |this |these |those )[\w '-]+?)(?:'s| is| are) (?:wanted|"
        rf"needed|asked for|requested) by {_P}(?=\s*(?:[,.!?]|$))",
        wanted_by,
        out,
    )
    if low.startswith("if "):
        out = _sub(
            r"^if (?:it(?:'s| is| would(?: not|n't) be| isn't| wouldn't be) (?:not )?(?:no|too "
            r"much|any) (?:bother|trouble)|it (?:isn't|is not) too much (?:bother|trouble))\s*,\s*",
            "",
            out,
        )
        out = _sub(
            r"^if my (?:[a-z]+ )?(?:assistant|helper|friend|robot) would (?:kindly |please )?",
            "",
            out,
        )
    for frame, repl in (
        (r"(?:\s+is|'s) keen on\b", " wants"),
        (r"\bwould care for\b", "would like"),
        (r"\bhas expressed (?:a wish|an interest|a desire) (?:for|in)\b", "wants"),
        (r"\brequires\b", "needs"),
        (r"\bwill want\b", "wants"),
        (r"\b(?:has |have )?been (?:wanting|asking for|after)\b", "wants"),
        (r"\b(?:should|must|is to) be (?:furnished|provided|supplied) with\b", "gets"),
        (r"\bapiece\b", "each"),
        (r"\bdont\b", "don't"),
    ):
        out = _sub(frame, repl, out)

    def home(m: re.Match[str]) -> str:
        # "Zoe is going home with the book" (she gets it); "Everything … is going home with P"
        said = _names(m.group(1), lexicon)
        if said and all(r.kind == "human" for r in said[-1].refs):
            return f"{m.group(1)} gets"
        return f"{m.group(1)} goes to"

    out = _sub(r"([\w']+)(?:\s+is|'s) going home with\b", home, out)
    out = _sub(r"([\w']+) takes home\b", home, out)

    def inert(m: re.Match[str]) -> str:
        return "" if _names_nothing(m.group(0), lexicon) else m.group(0)

    end = r"(?=\s*(?:[,.;!?]|\band\b|$))"
    out = _sub(
        rf",?\s+for (?:the|my|our|his|her|their|a|an|this|tonight's|today's) (?:next )?"
        rf"(?:[a-z-]+ )?{_OCCASION}(?: of the [a-z]+)?(?:\s*,(?=\s*(?:wants|needs|gets)\b))?{end}",
        inert,
        out,
    )
    out = _sub(rf"\s+by {_DEADLINE}{end}", inert, out)
    out = _sub(
        r",?\s+so (?:that )?(?:he|she|they|we|i) can [a-z]+(?: up| on| off| down)?"
        r"(?=\s*(?:[.!]|$))",
        inert,
        out,
    )

    def after_choice(m: re.Match[str]) -> str:
        # only after a choice said before it ("Give Noah the red book, either colour" stays)
        chose = re.search(r"\b(?:one of|either|any|each|apiece)\b", m.string[: m.start()], _F)
        return "" if chose else m.group(0)

    for _ in range(2):
        out = _sub(
            r",\s*(?:(?:it's |that's )?not a (?:big deal|blocker|problem|biggie|big thing)|"
            r"(?:colours|colors|sizes) don't matter|any (?:colour|color|size|one) will do|"
            r"whichever(?: one)?(?: is fine)?|just (?:the )?one|(?:i )?don't (?:mind|care) which|"
            r"either (?:colour|color|size|one|way)|(?:any|whatever) (?:colour|color|size))"
            r"(?=\s*(?:[,.!]|$))",
            after_choice,
            out,
        )
    return out


_NUMBER18 = {"two": 2, "three": 3, "four": 4, "five": 5, "six": 6}


def _objects_only(words: str, lexicon: Lexicon) -> bool:
    named = _names(words, lexicon)
    return bool(named) and all(r.kind == "object" for it in named for r in it.refs)


def _surface_only(words: str, lexicon: Lexicon) -> bool:
    return _only(words, lexicon, "surface")


_REPAIR_WORD33L = re.compile(
    rf"(?:,?\s*\b(?:{REPAIR_WORDS}|rather|i should say)\b)+"
    r"\s*,?\s*",
    _F,
)


def _taken_back33l(text: str, lexicon: Lexicon) -> set[str]:
    """Session 33 (lead): the people ``text`` names and takes back at once by a repair ('for
    Bob, I mean Alice': Bob), so that 'the other one' after it is not read as the one person
    neither said (12c's repairs fuzz: "The cup is for Bob, I mean Alice, and the apple goes to
    the other one." read apple>C, where Bob is as likely)."""
    taken: set[str] = set()
    for m in _REPAIR_WORD33L.finditer(text):
        before = _last_name(text[: m.start()], lexicon)
        after = _first_name(text[m.end() :], lexicon)
        if before is None or after is None:
            continue
        if all(r.kind == "human" for r in before[0].refs + after[0].refs):
            taken |= {r.id for r in before[0].refs} - {r.id for r in after[0].refs}
    return taken


def _resumes30s(m: re.Match[str], lexicon: Lexicon) -> bool:
    """Session 30 (12s): whether the pronoun of 'P, she gets …' may say P again: not when P's
    title says otherwise ("Mr Lee, she gets the jug" speaks to Mr Lee of someone else, and had
    been read as the jug for Mr Lee)."""
    return all(
        _fits(pid, m.group(0)[len(m.group(1)) :], lexicon)
        for pid in _ids(m.group(1), lexicon, "human")
    )


def _pronouns18(text: str, lexicon: Lexicon) -> str:
    """Pronouns and ellipsis said of one person: 'P wants X. Give it to them.' ('them' for the one
    person the text names, who asked), '…, sort that out (for them)' after a want, 'Then the Y,
    same person.', 'P the X, and the Y … the other one' (the other of two people), 'and P, she
    needs Y' (the pronoun says P again), 'Find X and put it …'."""
    out = text
    people = _ids(out, lexicon, "human")
    asked = re.match(
        r"^(.+?) (?:wants|needs|has wanted|asked for|is after|has been asking for|would like|"
        r"is due)\b",
        out,
        _F,
    )
    if len(people) == 1 and asked and _only_person(asked.group(1), lexicon):
        who = asked.group(1)
        out = _sub(r"\b(to|for) them\b(?!\s+(?:both|all|each))", rf"\1 {who}", out)
        out = _sub(
            r",\s*(?:so\s+)?sort (?:it|that|this)(?: out)?(?: for [A-Za-z ]+?)?(?:,? please| pls)?"
            r"\s*([.!]?)$",
            r"\1",
            out,
        )
    out = _sub(r",\s*same (?:person|one|guy|lady)\s*([.!]?)$", r" to the same person\1", out)
    other = re.search(r"\b(to|for) the other (?:one|person)\b", out, _F)
    if other and people:
        # "… and the chips are for the other one": the one person not named (one taken back
        # by a repair is not named: "for Bob, I mean Alice, …" names Alice alone)
        kept = [h for h in people if h not in _taken_back33l(out[: other.start()], lexicon)]
        left = [h for h in lexicon.scene.humans if h.id not in kept]
        if len(left) == 1:
            out = _sub(
                r"\b(to|for) the other (?:one|person)\b", rf"\1 {_name(left[0].id, lexicon)}", out
            )
        elif len(left) > 1:
            who = " or ".join(
                f"{h.name} ({', '.join(h.aliases)})" if h.aliases else h.name for h in left
            )
            raise GroundingError(f"'the other one' could mean {who}: name the person")

    def fronted(m: re.Match[str]) -> str:
        return f"{m.group(1)} {m.group(2)}" if _objects_only(m.group(1), lexicon) else m.group(0)

    # "and the chips, those go to P": the pronoun says the fronted objects again
    out = _sub(r"\b(the [a-z ]+?),\s*(?:those|these|they|it|that) (go|goes|are|is)\b", fronted, out)

    def resumed(m: re.Match[str]) -> str:
        if not _only_person(m.group(1), lexicon) or not _resumes30s(m, lexicon):
            return m.group(0)
        return f"{m.group(1)} {m.group(2)}"

    out = _sub(r"\b([A-Z][\w ]*?),\s*(?:she|he|they) (needs|wants|gets|would like)\b", resumed, out)

    def found(m: re.Match[str]) -> str:
        if not _objects_only(m.group(1), lexicon):
            return m.group(0)
        return f"{m.group(2)} {m.group(1)}"

    return _sub(
        r"^(?:find|grab|fetch|get) (the [a-z ]+?) and (put|place|give|hand|take|bring) "
        r"(?:it|them)\b",
        found,
        out,
    )


def _run_ons18(text: str, lexicon: Lexicon) -> str:
    """Run-ons and dictation: 'Last:' (finally), 'Thereafter,' (then), 'X is to go on S' (goes on),
    'S first, the X.' (the X on S), 'X. P. Done.' (X to P), 'P is waiting on X and Q on Y' (Q
    wants Y), 'Those are the action items.' (a sentence that only names the list), 'Give each of
    them one thing: P the X, Q the Y' and 'Give both people a snack: X for P and Y for Q' (the
    list is the request)."""
    out = _sub(r"(^|[.!]\s*)(?:last|lastly)\s*[:,]\s*", r"\1Finally, ", text)
    out = _sub(r"\s+and then we're (?:done|finished|good)\s*([.!]?)$", r"\1", out)
    # "Books. Red one to Zoe.": a heading said as a sentence of its own
    out = _sub(r"^([a-z]+s)\.\s+(?=[a-z]+ ones? (?:to|for|on|in)\b)", r"\1: ", out)
    out = _sub(r"(^|[.!]\s*)thereafter\s*,\s*", r"\1Then, ", out)
    out = _sub(r"\b(?:is|are) to go (on|onto|in|into|to)\b", r"goes \1", out)
    out = _sub(
        r"(?:^|(?<=[.!]))\s*(?:those|these) are (?:the|today's|my|your|our) (?:action items|jobs|"
        r"tasks|orders|instructions)\s*[.!]?\s*$",
        "",
        out,
    ).strip()

    def first(m: re.Match[str]) -> str:
        if not _surface_only(m.group(2), lexicon) or not _objects_only(m.group(3), lexicon):
            return m.group(0)
        return f"{m.group(1)}Put {m.group(3)} on the {m.group(2)}{m.group(4)}"

    out = _sub(r"(^|[.!]\s+)(?:the )?([a-z ]+?) first,\s*(the [a-z ]+?)([.!])", first, out)

    def dictated(m: re.Match[str]) -> str:
        if not _objects_only(m.group(2), lexicon) or not _only_person(m.group(3), lexicon):
            return m.group(0)
        return f"{m.group(1)}{m.group(2)} to {m.group(3)}."

    out = _sub(
        r"((?:^|(?<=[.!?])\s+)(?:then,? )?)(the [a-z ]+?)\.\s+([A-Za-z][\w ]*?)\."
        r"(?:\s+(?:done|sold|next)\.)?",
        dictated,
        out,
    )
    out = _sub(r"\b(?:is|'s|are) waiting (?:on|for)\b", " wants", out).replace("  ", " ")

    def gapped(m: re.Match[str]) -> str:
        if not _only_person(m.group(2), lexicon) or not _objects_only(m.group(3), lexicon):
            return m.group(0)
        return f"{m.group(1)} and {m.group(2)} wants {m.group(3)}"

    out = _sub(
        r"(\bwants [^,.;]*?) and ([A-Za-z][\w ]*?) on (the [a-z ]+?)\b(?=\s*(?:[,.;!]|so\b|$))",
        gapped,
        out,
    )

    def listed(m: re.Match[str]) -> str:
        if len(_ids(m.group(1), lexicon, "human")) < 2:
            return m.group(0)
        return f"give {m.group(1)}" if m.group(1)[:1].isupper() else m.group(1)

    return _sub(
        r"^give (?:each of them|both of them|both people|them both|everyone|each person) "
        r"(?:a|an|one) [a-z]+(?: each)?\s*:\s*(.+)$",
        listed,
        out,
    )


def _as_many29r(said: str, ids: set[str], lexicon: Lexicon) -> None:
    """Session 29 (12r): 'for each of the three patients' where the scene has two read as the
    two (the count unheard): a count of people that does not match the scene is refused."""
    n = re.search(r"\beach of the (two|three|four) ([a-z]+)", said, _F)
    if n is not None and _COUNTS[n.group(1).lower()] != len(ids):
        names = ", ".join(_name(pid, lexicon) for pid in sorted(ids))
        raise GroundingError(
            f"'the {n.group(1)} {n.group(2)}': the scene has {len(ids)} ({names}), not "
            f"{_COUNTS[n.group(1).lower()]}"
        )


def _counts18(text: str, lexicon: Lexicon) -> str:
    """Counts: 'a (fine) pair of Xs' / 'that pair of Xs' (the two Xs), ', the two of them,' said
    again, 'All three of the Xs, a, b and c,' (the three Xs), "S's for the two Xs, a and b" (the
    two Xs on S), "There's only a single X, and it's for P" (the X to P), 'N of the Xs: the A one
    and the B one' (the A X and the B X, when N are named), 'One X per <role>' / 'An X for each
    of the two <role>s' / 'An X each for P and Q' (each gets one)."""

    def pair(m: re.Match[str]) -> str:
        if len(_ids(m.group(1), lexicon, "object")) != 2:
            return m.group(0)
        return f"the two {m.group(1)}"

    out = _sub(r"\b(?:a|an|that|this) (?:[a-z]+ )?pair of ([a-z]+s)\b", pair, text)
    out = _sub(r"\b(?:that|this) trio of ([a-z]+s)\b", r"the three \1", out)
    out = _sub(r"(\bthe two [a-z]+s),\s*the two of them,", r"\1", out)

    def all_of(m: re.Match[str]) -> str:
        said = re.findall(r"[a-z]+", (m.group(3) or "").lower())
        adjectives = {w for words in _adjectives(lexicon).values() for w in words}
        adjectives |= set(_adjectives(lexicon))
        if said and not all(w in adjectives or w == "and" for w in said):
            return m.group(0)
        if said and len([w for w in said if w != "and"]) != _COUNTS[m.group(1).lower()]:
            return m.group(0)  # "all three of the boxes, small and large": which three? (s26)
        return f"the {m.group(1)} {m.group(2)}"

    out = _sub(
        r"\ball (two|three|four|five|six) of the ([a-z]+s)((?:,\s*[a-z]+)+,? and [a-z]+)?(?=,)",
        all_of,
        out,
    )

    def for_s(m: re.Match[str]) -> str:
        if not _surface_only(m.group(1), lexicon):
            return m.group(0)
        return f"Put the {m.group(2)} {m.group(3)} on the {m.group(1)}{m.group(4)}"

    out = _sub(
        r"^the ([a-z ]+?)'s for the (two|three|four) ([a-z]+s)(?:,\s*[a-z]+,? and [a-z]+)?"
        r"(\s*[.!]?)$",
        for_s,
        out,
    )

    def single(m: re.Match[str]) -> str:
        ids = _ids(m.group(1), lexicon, "object")
        kind = _names(m.group(1), lexicon)
        if len(ids) != 1 or not kind or not _only_person(m.group(2), lexicon):
            return m.group(0)
        return f"the {m.group(1)} to {m.group(2)}{m.group(3)}"

    out = _sub(
        r"^there's (?:only |just )?(?:a single|the one|one|just the one) ([a-z ]+?),\s*and it"
        r"(?:'s| is| goes) (?:for|to) ([A-Za-z][\w ]*?)(\s*[.!]?)$",
        single,
        out,
    )

    def named_n(m: re.Match[str]) -> str:
        n = _NUMBER18[m.group(1).lower()]
        kind = _singular(m.group(2).lower())
        listed = _sub(r"\b([a-z]+) ones?\b", rf"\1 {kind}", m.group(3))
        objs = _ids(listed, lexicon, "object")
        if len(objs) != n or _ids(listed, lexicon, "human"):
            return m.group(0)
        return listed

    out = _sub(
        r"\b(two|three|four) of the ([a-z]+s)\s*(?::|,\s*namely)\s*((?:the [a-z ]+?)(?:,\s*| and "
        r")(?:the [a-z ]+?))(?=\s*[.!]?$)",
        named_n,
        out,
    )

    def each_for(m: re.Match[str]) -> str:
        if not (m.group(3) or m.group(6)):
            return m.group(0)  # "a mug for bob and one for carol": no 'each'
        if not (_only_person(m.group(4), lexicon) and _only_person(m.group(5), lexicon)):
            return m.group(0)
        if _ids(m.group(4), lexicon) == _ids(m.group(5), lexicon):
            return m.group(0)
        return (
            f"{m.group(4)} and {m.group(5)} each get {m.group(1).lower()} {m.group(2)}{m.group(7)}"
        )

    out = _sub(
        r"^(a|an|one) ([a-z]+) (each )?for ([A-Za-z][\w ]*?) and ([A-Za-z][\w ]*?)( each)?"
        r"(\s*[.!]?)$",
        each_for,
        out,
    )

    def role_each(m: re.Match[str]) -> str:
        role = m.group(3)
        ids = _ids(role, lexicon, "human")
        if len(ids) < 2:
            return m.group(0)
        _as_many29r(m.group(0), ids, lexicon)
        names = [_name(pid, lexicon) for pid in sorted(ids)]
        return f"{' and '.join(names)} each get {m.group(1).lower()} {m.group(2)}{m.group(4)}"

    return _sub(
        r"^(a|an|one) ([a-z]+) (?:per |for each of the (?:two|three) |for each )([a-z]+?)s?"
        r"(?:,? please)?(\s*[.!]?)$",
        role_each,
        out,
    )


def _negation18(text: str, lexicon: Lexicon) -> str:
    """Negation: 'bar the X' (except), 'Give P the Y. Not the X, just the Y.' (the Y said again),
    'P wants Y, no X for him' (X not asked), "Don't give P the X, give it to Q instead" (the X to
    Q), 'the X that isn't on S' (the Xs not on S: one is that one; several are the X, whose
    refusal names them)."""
    out = _sub(r"\bbar the\b", "except the", text)

    def not_just(m: re.Match[str]) -> str:
        before = out[: m.start()]
        if not _ids(m.group(2), lexicon) <= _ids(before, lexicon) or _ids(
            m.group(1), lexicon
        ) & _ids(before, lexicon):
            return m.group(0)
        return ""

    out = _sub(r"(?<=[.!])\s*not the ([a-z ]+?),\s*just the ([a-z ]+?)\s*[.!]?$", not_just, out)

    def none_for(m: re.Match[str]) -> str:
        rest = out[: m.start()]
        ids = _ids(m.group(1), lexicon, "object")
        if not ids or ids & _ids(rest, lexicon) or len(_ids(rest, lexicon, "human")) != 1:
            return m.group(0)
        return ""

    out = _sub(
        r",\s*(?:but )?no ([a-z ]+?) for (?:him|her|them)(?: (?:tho|though))?(?=\s*[.!]?$)",
        none_for,
        out,
    )

    def instead(m: re.Match[str]) -> str:
        if not _only_person(m.group(1), lexicon) or not _only_person(m.group(3), lexicon):
            return m.group(0)
        if not _objects_only(m.group(2), lexicon) or _ids(m.group(1), lexicon) == _ids(
            m.group(3), lexicon
        ):
            return m.group(0)
        return f"give {m.group(2)} to {m.group(3)}{m.group(4)}"

    out = _sub(
        r"^don't give ([A-Za-z][\w ]*?) (the [a-z ]+?),\s*give (?:it|them) to ([A-Za-z][\w ]*?)"
        r" instead(\s*[.!]?)$",
        instead,
        out,
    )

    def not_on(m: re.Match[str]) -> str:
        ids = _ids(m.group(1), lexicon, "object")
        where = _ids(m.group(2), lexicon, "surface")
        if len(ids) < 2 or len(where) != 1 or _ids(m.group(2), lexicon, "object"):
            return m.group(0)
        # session 34 (12s): the surface's words may run on past its name ("… the rack goes to
        # Mr Novak", "… the plate rack before I go tomorrow"): what follows the name is kept (it
        # had been dropped with the time in it)
        words = m.group(2).split()
        n = next(
            (n for n in range(len(words), 0, -1) if _only(" ".join(words[:n]), lexicon, "surface")),
            0,
        )
        if n == 0:
            return m.group(0)
        rest = " ".join(words[n:])
        if re.fullmatch(r"(?:give|hand|pass|take|bring|send) (?:it|them)", rest, _F):
            rest = ""  # "… on the bookshelf give it to Zoe": the object said again, then where
        rest = f" {rest}" if rest else ""
        off = ids - set(starting_on(ids, next(iter(where)), lexicon))
        if len(off) == 1:
            return _said(next(iter(off)), lexicon) + rest
        if off == ids:
            return m.group(1) + rest  # every one of them: the refusal names the readings
        if off:
            raise GroundingError(
                f"{m.group(0)!r} could mean {' or '.join(sorted(off))}: name the one meant"
            )
        return m.group(0)

    return _sub(
        r"\b(the [a-z ]+?) that (?:isn't|is not|'s not) (?:on|in) (the [a-z ]+?)\b"
        r"(?=\s*(?:[.,!]|to\b|$))",
        not_on,
        out,
    )


def _corrections18(text: str, lexicon: Lexicon) -> str:
    """Corrections: 'P, no, Q needs X' (Q), 'X to P. Correction: to Q.' (no, to Q), 'X to P,
    sorry, Y to P' (the Y), 'Give P X. Wait, not P, Q.' (no, to Q), 'No, make that Q, the <who>'
    (no, to Q), '…, I mean the Y one, my mistake' (said of the correction), 'No, hang on, the Y to
    P, leave the X where it is' (no, the Y to P)."""
    out = text

    def person_no(m: re.Match[str]) -> str:
        if not _only_person(m.group(1), lexicon) or not _only_person(m.group(2), lexicon):
            return m.group(0)
        return f"{m.group(2)} {m.group(3)}"

    out = _sub(
        r"^([A-Za-z][\w ]*?),\s*no,\s*([A-Za-z][\w ]*?) (needs|wants|gets)\b", person_no, out
    )

    def to_q(m: re.Match[str]) -> str:
        if not _only_person(m.group(2), lexicon):
            return m.group(0)
        if m.group(1) and (_ids(m.group(1), lexicon) - _ids(out[: m.start()], lexicon)):
            return m.group(0)  # 'not P' names one the request did not
        return f". No, to {m.group(2)}{m.group(3) or '.'}"

    out = _sub(
        r"\.\s*(?:correction\s*:\s*to|wait,\s*not ([A-Za-z][\w ]*?),|no,\s*make that)\s*"
        r"([A-Za-z][\w ]*?)(?:,\s*the [a-z ]+?)?(\s*[.!])?$",
        to_q,
        out,
    )

    def swapped(m: re.Match[str]) -> str:
        if not _objects_only(m.group(1), lexicon) or not _objects_only(m.group(3), lexicon):
            return m.group(0)
        if not _only_person(m.group(2), lexicon) or _ids(m.group(2), lexicon) != _ids(
            m.group(4), lexicon
        ):
            return m.group(0)
        return f"{m.group(3)} to {m.group(4)}{m.group(5)}"

    out = _sub(
        r"^([a-z ]+?) to ([A-Za-z][\w ]*?),\s*sorry,\s*([a-z ]+?) to ([A-Za-z][\w ]*?)(\s*[.!]?)$",
        swapped,
        out,
    )
    out = _sub(r"(\bi mean the [a-z ]+?),\s*my (?:mistake|bad)\s*([.!]?)$", r"\1\2", out)

    def hang_on(m: re.Match[str]) -> str:
        before = _ids(out[: m.start()], lexicon, "object")
        left = _ids(m.group(3), lexicon, "object")
        if not left or not left <= before or _ids(m.group(1), lexicon, "object") & left:
            return m.group(0)
        return f". No, {m.group(1)} to {m.group(2)}."

    return _sub(
        r"\.\s*no,\s*(?:hang on|hold on|wait),\s*(the [a-z ]+?) to ([A-Za-z][\w ]*?),\s*leave "
        r"(the [a-z ]+?) (?:where it is|alone|be)\s*[.!]?$",
        hang_on,
        out,
    )


def _sold18(text: str, lexicon: Lexicon) -> str:
    """An auctioneer's 'Sold to P, one X!' (the X to P)."""

    def sold(m: re.Match[str]) -> str:
        if not _only_person(m.group(1), lexicon) or not _objects_only(m.group(2), lexicon):
            return m.group(0)
        return f"the {m.group(2)} to {m.group(1)}{m.group(3)}"

    return _sub(r"^sold to ([A-Za-z][\w ]*?),\s*(?:one|a|an|the) ([a-z ]+?)(\s*[.!]?)$", sold, text)


# -- session 19: blind17's kinds, as general mechanisms -----------------------------------------
#
# A word is taken as the speaker's own (a filler) by what KIND of word it is and WHERE it stands,
# not by a list of sentences: a manner adverb (an -ly word whose stem is an English word:
# 'smartly', 'gently'), a sentence particle ('lah', 'innit', 'ja'), a word of immediacy ('tonight',
# 'right now'), a word of address or an interjection (by kind, _ADDRESS19 / _INTERJECTION19), or a
# word that is no English word at all ('cariad', 'eish', 'lgtm': not among the 20,000 most
# frequent words, no first name, no title, not one edit from a verb, a scene name or any word of
# one). None of them is ever taken off where it could name a scene thing (nor by a typo), and an
# unknown word is taken off only as a stretch of its own that does not follow an object (where
# it could be one more object: "the knife, whisk" stays refused).

_ADDRESS19 = frozenset(
    {
        *("sister", "sis", "brother", "bro", "sailor", "shipmate", "matey", "hearty", "hearties"),
        *("captain", "cap'n", "skipper", "cobber", "hinny", "cher", "dawg", "doll", "cariad"),
        *("bach", "boyo", "lads", "laddie", "lassie", "mucker", "marra", "kidda", "chum"),
        *("amigo", "amiga", "compadre", "partner", "pardner", "sport", "fam", "bruv", "cuz"),
        *("bredren", "boet", "bru", "bestie", "babes", "sweetness", "treasure", "angel"),
        *("y'all", "yall", "everybody", "people", "gang", "crew", "troops", "kiddo", "buddy"),
        *("boy", "boys", "girls", "gents", "ladies", "gentlemen", "colleagues", "friends"),
        *("old", "me", "my", "our", "dear", "good", "young", "big", "little"),
    }
)
_INTERJECTION19 = frozenset(
    {
        *("abeg", "o", "oya", "jor", "sha", "chur", "wahey", "woohoo", "whoopee", "arr", "ahoy"),
        *("avast", "yarr", "oi", "oy", "howzit", "eish", "ja", "shot", "lekker", "tidy", "lush"),
        *("ace", "sweet", "cool", "nice", "awesome", "wicked", "sound", "dope", "slay", "bet"),
        *("innit", "lah", "la", "leh", "lor", "hor", "ah", "eh", "hey", "yo", "ey", "ayy"),
        *("yeah", "yep", "yup", "aye", "ok", "okay", "alright", "right", "well", "so", "now"),
        *("capisce", "capiche", "pronto", "presto", "voila", "bravo", "encore", "cheers", "ta"),
        *("muchly", "diolch", "merci", "gracias", "grazie", "danke", "namaste", "aloha", "bless"),
        *("please", "thanks", "thank", "you", "kindly", "steady", "easy", "careful", "quick"),
        *("smart", "sharpish", "chop", "lickety-split", "asap", "and", "just", "there"),
        *("whoa", "wow", "gosh", "golly", "blimey", "crikey", "cor", "heck", "hmm", "um", "uh"),
        *("er", "erm", "mighty", "fine", "proper", "like", "hands", "slow", "slowly", "magic"),
        *("magnificent", "marvellous", "marvelous", "wonderful", "brilliant", "fantastic"),
        *("superb", "excellent", "perfect", "great", "lovely", "splendid", "terrific", "amazing"),
    }
)
# words that order, count, choose, negate or time what is asked: an -ly word among them is no
# filler ('lastly', 'separately', 'equally', 'only')
_LY_HELD19 = frozenset(
    {
        *("only", "early", "firstly", "secondly", "thirdly", "lastly", "finally", "respectively"),
        *("separately", "individually", "equally", "evenly", "alternately", "exclusively"),
        *("solely", "merely", "previously", "subsequently", "initially", "eventually", "mostly"),
        *("partly", "nearly", "mainly", "likely", "unlikely", "simultaneously", "jointly"),
        *("collectively", "accordingly", "similarly", "additionally", "lately", "shortly"),
        *("daily", "weekly", "monthly", "hourly", "nightly", "elderly", "family", "supply"),
        *("apply", "reply", "rely", "ally", "rally", "belly", "jelly", "italy", "july", "ugly"),
        *("holy", "silly", "jolly", "bully", "curly", "woolly", "friendly", "lonely", "costly"),
        *("instead", "together", "partially", "fully", "wholly", "entirely", "completely"),
        *("randomly", "personally", "directly", "straight", "later", "afterwards", "next"),
        *("actually", "alternatively", "ideally", "preferably", "optionally", "possibly"),
        *("probably", "presumably", "conditionally", "hopefully", "otherwise", "really"),
    }
)
# Sentence and polite particles, one list for both places they are said (session 25: sessions
# 19 and 24 had one list each): glued to the word before ("… to Person B please krap", "Give
# Bob the cup lah": _fillers19) or as a stretch of their own between punctuation marks ("…,
# lah.", "Sawasdee krap.": _courtesy24). Malaysian and Singaporean English lah, la, leh, lor,
# meh, hor, ah; London innit; Afrikaans ja; Nigerian o, sha; Thai krap, khrap, krub, khrub, kha;
# Tagalog po, opo; Ghanaian paa.
_PARTICLES = frozenset(
    {"lah", "la", "leh", "lor", "meh", "hor", "ah", "innit", "ja", "o", "sha"}
    | {"krap", "khrap", "krub", "khrub", "kha", "po", "opo"}
    | {"paa"}  # Ghanaian English: 'thank you paa' (very much), session 26
)
_NOW19 = re.compile(
    r"\s*\b(?:right now|just now|now in a minute|in a minute|straight ?away|at once|"
    r"forthwith|quick smart)\b",
    _F,
)
_TIMED19 = re.compile(
    r"\b(?:later|after|afterwards|before|then|first|next|tomorrow|soon|until|till|once|when|"
    r"while|wait|yesterday|last)\b",
    _F,
)
_DETERMINER19 = frozenset(
    {"the", "a", "an", "this", "that", "his", "her", "their", "my", "your", "our", "its", "some"}
)


def _manner(word: str, lexicon: Lexicon) -> bool:
    """An -ly adverb of manner or stance ('smartly', 'gently', 'nicely', 'happily'): its stem is
    an English word, and it orders, counts, times or names nothing."""
    low = word.lower()
    if len(low) < 5 or not low.endswith("ly") or not low.isalpha() or low in _LY_HELD19:
        return False
    if low in _scene_words(lexicon.scene) or low in first_names() or low in VERBS:
        return False
    stems = {low[:-2], low[:-3] + "y", low[:-1] + "e", low[:-2] + "le", low[:-4] + "le"}
    return bool(stems & _COMMON) or low in _MANNER


def _unknown_word(word: str, lexicon: Lexicon) -> bool:
    """A word that is no English word the grounder knows of ('cariad', 'eish', 'lgtm')."""
    low = word.lower().strip("'")
    return (
        low.replace("-", "").replace("'", "").isalpha()
        and low not in _COMMON
        and low not in first_names()
        and low not in TITLES
        and low not in _scene_words(lexicon.scene)
        and not _held_word(low, lexicon)
        and not _near_verb(low)
    )


def _filler_word(word: str, lexicon: Lexicon) -> bool:
    low = word.lower()
    if low in _scene_words(lexicon.scene):
        return False
    if low in _ADDRESS19 or low in _INTERJECTION19 or low in _ADDRESS or low in _INERT_WORDS:
        return True
    return _manner(low, lexicon) or _unknown_word(low, lexicon)


_SET_FILLERS19 = re.compile(
    r"^(?:and |so )?(?:(?:no|nae|nay) (?:bother|worries|problem|problems|fuss|rush|hurry|sweat|"
    r"stress|pressure|drama)|good (?:night|morning|evening|afternoon|day)|in your own time|"
    # session 33 (12s): 'ready when you are', 'you help me' (blind21), 'quick as you like'
    r"when(?: you're| you are) ready|ready when you are|(?:please )?(?:you )?help me(?: out)?|"
    r"(?:as )?(?:quick|fast|soon) as you (?:like|can)|"
    r"there's a good (?:lad|girl|boy|robot|chap)|nice and (?:slow|"
    r"easy|gentle|steady|careful)|steady hands(?: everyone)?|for the record|with respect|"
    r"merging now|over and out|back after the break|see you (?:soon|later|all))$",
    _F,
)


def _filler_stretch(chunk: str, after_object: bool, lexicon: Lexicon) -> bool:
    """A stretch that is the speaker's own words: every word a filler by kind, at least one not
    a word of address alone, nothing named in the scene (nor by a typo), no digit; an unknown
    word only where it cannot be one more object ('…, whisk' after an object stays)."""
    words = re.findall(r"[a-z][a-z'-]*", chunk.lower())
    if not words or len(words) > 5 or re.search(r"\d", chunk):
        return False
    if _SET_FILLERS19.match(chunk.strip(" .!?")) and _names_nothing(chunk, lexicon):
        return True
    if not all(_filler_word(w, lexicon) for w in words):
        return False
    if words[0] in ("and", "so", "then", "just") and len(words) == 1:
        return False
    if "then" in words or ("there" in words and words != ["there"]):
        return False
    held = [w for w in words if _held_word(w, lexicon)]
    allowed = ("me", "my", "our", "old", "little", "big", "good", "so", "just", "and")
    if words == ["like"]:
        return True  # "…, straightaway like": said after the request
    if any(w not in allowed for w in held):
        return False
    if after_object and any(
        _unknown_word(w, lexicon) and w not in _INERT_WORDS and w not in _INTERJECTION19
        for w in words
    ):
        return False
    return _names_nothing(chunk, lexicon)


_VERB_NEXT19 = re.compile(
    r"^(?:wants|needs|gets|receives|has|would|should|could|will|can|is|are|goes|go|takes|"
    r"asked|likes|shall|must)\b",
    _F,
)


# Session 53 (12p): a text _tidy19 leaves as it is, said at once: each of its rewrites changes the
# text exactly where its pattern matches (a mark doubled, a space before a mark, marks together,
# marks or spaces opening it, two spaces, a mark closing it), so a text none of them matches
# (at any step: none changes it) and that has no space at either end is its own tidy form
_UNTIDY19 = re.compile(r"[.!?][.!?,;:]|\s[,;:.!?]|[,;:]\s*[,;:.!?]|^[\s,;:.!]|\s\s|[,;:]$")


def _tidy19(text: str) -> str:
    if text == text.strip() and _UNTIDY19.search(text) is None:
        return text
    out = re.sub(r"([.!?])[.!?,;:]+", r"\1", text)
    out = re.sub(r"\s+([,;:.!?])", r"\1", out)
    out = re.sub(r"([,;:])\s*([,;:.!?])", r"\2", out)
    out = re.sub(r"^[\s,;:.!]+", "", out)
    out = re.sub(r"\s{2,}", " ", out).strip()
    out = re.sub(r"[,;:]$", "", out).strip()
    return out


def _joined19(chunks: list[str], seps: list[str], drop: list[bool]) -> str:
    """The stretches kept, joined as they were said: a sentence end of a stretch taken off
    stays, and an aside taken off between a subject and its verb ('Each patient, gently,
    receives …') leaves no comma."""
    res = ""
    pending = ""
    for k, c in enumerate(chunks):
        sep = seps[k] if k < len(seps) else ""
        end = sep.strip()[:1] if sep.strip()[:1] in (".", "!", "?") else ""
        if drop[k] or not c.strip():
            if end and res:
                pending = end
            elif res and not pending:
                pending = ","
            continue
        if res:
            if pending in (".", "!", "?"):
                res = res.rstrip(" ,;:.!?") + pending + " "
            elif pending == "," and _VERB_NEXT19.match(c.strip()):
                res = res.rstrip(" ,;:") + " "
            elif not res.endswith(" "):
                res += " "
        pending = ""
        res += c
        res += sep if sep.strip() else " "
    return _tidy19(res)


def _ends_object(chunk: str, lexicon: Lexicon) -> bool:
    named = _names(chunk, lexicon)
    if not named:
        return False
    last = named[-1]
    tail = chunk.lower().rstrip(" .!?")
    return any(r.kind == "object" for r in last.refs) and tail.endswith(last.text.lower())


# the words after which _fillers19 asks whether a word is 'loose' between a thing and where it goes
_LOOSE_BEFORE19 = ("on", "onto", "to", "in", "into", "over")
# the interjections that are not address (session 55, 12p: the difference had been made at every
# call)
_INTERJECTION_ONLY19 = _INTERJECTION19 - _ADDRESS


def _fillers19(text: str, lexicon: Lexicon) -> str:
    """The speaker's own words taken off by kind (above): manner adverbs, particles and words of
    immediacy wherever they stand (not between a determiner and its noun: 'the woolly hat'), and
    whole stretches between punctuation that are fillers only."""
    out = text
    if not _TIMED19.search(out):
        out = _NOW19.sub("", out)
    words = out.split(" ")
    # interjections said first without a comma ('aye aye the bottle's going …')
    lead = 0
    while lead < len(words) - 2 and words[lead].lower() in _INTERJECTION_ONLY19:
        if _held_word(words[lead], lexicon) or words[lead].lower() in ("please", "and", "so"):
            break
        lead += 1
    if lead and (words[lead].lower() in _DETERMINER19 or words[lead].lower() in VERBS):
        words = words[lead:]
    kept: list[str] = []
    for k, w in enumerate(words):
        core = w.strip('.,;:!?"')
        low = core.lower()
        if (
            low not in _PARTICLES
            and (len(low) < 5 or not low.endswith("ly"))
            and not (0 < k < len(words) - 1 and words[k + 1].lower() in _LOOSE_BEFORE19)
        ):
            # session 55 (12p): a word none of the three tests below can take off (not a
            # particle, not an -ly word, as _manner asks first, nor before a word 'loose' asks
            # for), kept at once: most words are
            kept.append(w)
            continue
        prev = words[k - 1].lower().strip(",;:") if k else ""
        last = k + 1 == len(words) or w[-1:] in ",;:.!?"
        glued = low in _PARTICLES and k > 0 and prev[-1:] not in (",", ";", ":")
        loose = (  # the cheap tests first (session 44, 12b): the same value, not asked of most
            0 < k < len(words) - 1
            and words[k + 1].lower() in _LOOSE_BEFORE19
            and _unknown_word(core, lexicon)
            and _ends_object(" ".join(words[:k]), lexicon)
        )  # 'the sippy cup aloft on the high chair': a word between a thing and where it goes
        if (
            core
            and (glued or loose or _manner(core, lexicon))
            and (prev not in _DETERMINER19 or last)
        ):
            tail = w[len(w.rstrip('.,;:!?"')) :]
            if tail and kept:
                kept[-1] = kept[-1].rstrip(",;:") + tail
            continue
        kept.append(w)
    out = " ".join(kept)
    parts = _STRETCH.split(out.strip())
    chunks, seps = parts[0::2], parts[1::2]
    asks = "?" in out and not re.match(r"^(?:could|can|would|will|may|might|is it)\b", out, _F)
    if (
        len(chunks) < 2
        or asks
        or _rx(
            r"\b(?:no|sorry|actually|wait|i mean|hang on|hold on|scratch|strike|correction|rather|"
            r"oops|whoops|i tell a lie|my mistake|my bad)\b"
        ).search(out)
    ):
        # a stretch taken off next to a correction would change what the correction takes back
        return _tidy19(out)
    drop = []
    for k, c in enumerate(chunks):
        prev = chunks[k - 1] if k else ""
        prev_sep = seps[k - 1] if k else "."
        after_object = (
            k > 0 and prev_sep.strip()[:1] not in (".", "!", "?") and _ends_object(prev, lexicon)
        )
        drop.append(bool(c.strip()) and _filler_stretch(c, after_object, lexicon))
    if not any(drop) or all(d or not c.strip() for d, c in zip(drop, chunks, strict=True)):
        return _tidy19(out)
    return _joined19(chunks, seps, drop)


# The speaker's own stance said with 'I' or 'me' (not a recipient): a stretch whose verb is one of
# thinking, hoping, begging, thanking, apologising or asking leave ('I reckon', 'I'm afraid', 'If I
# may', 'I beg you', 'I thank thee', 'I hate to be a pain, but', 'Let me think', 'Mind you, I'm
# no expert'), and 'help me' before a verb (Singapore English 'please'). Every word of the
# stretch is of that closed set, and it names nothing; 'I need the cup' and 'Bring me the chips'
# stay refused (a want and a recipient are not in the set).
_STANCE19 = frozenset(
    {
        *("i", "i'm", "i'd", "i'll", "i've", "me", "my", "myself", "we", "we'd", "let", "if"),
        *("think", "reckon", "suppose", "guess", "believe", "daresay", "dare", "say", "expect"),
        *("imagine", "bet", "trust", "gather", "hope", "fear", "feel", "afraid", "sure", "must"),
        *("may", "might", "beg", "begging", "thank", "thee", "thou", "you", "ye", "hate", "to"),
        *("be", "a", "pain", "bother", "nuisance", "ask", "asking", "so", "very", "most"),
        *("heartily", "kindly", "truly", "really", "just", "rest", "case", "the", "mind", "am"),
        *("no", "expert", "leave", "it", "up", "honest", "honestly", "promise", "swear", "but"),
        *("suspect", "see", "hear", "told", "understand", "grateful", "oh", "well", "bless"),
        *("apologise", "apologize", "sorry", "confess", "admit", "again", "this", "once"),
    }
)
_STANCE_VERB19 = re.compile(
    r"\b(?:think|reckon|suppose|guess|believe|daresay|dare say|expect|imagine|bet|trust|gather|"
    r"hope|fear|afraid|sure|must say|may|beg|begging|thank|hate to|rest my case|mind you|"
    r"no expert|leave it (?:up )?to you|promise|swear|suspect|understand|am told|i'm told|"
    r"grateful|bless)\b",
    _F,
)


def _stance_stretch(chunk: str, lexicon: Lexicon) -> bool:
    words = re.findall(r"[a-z][a-z']*", chunk.lower())
    return (
        bool(words)
        and len(words) <= 8
        and all(w in _STANCE19 for w in words)
        and bool(_STANCE_VERB19.search(chunk))
        and not re.search(r"\b(?:no|not|n't)\b(?! expert| bother)", chunk, _F)
        and _names_nothing(chunk, lexicon)
    )


def _speaker19(text: str, lexicon: Lexicon) -> str:
    """The speaker's stance taken off (above); 'me hearty', 'me lad', 'me old mucker' (address);
    'help me <verb>' (please); 'I reckon P wants X' (P wants X); 'May I ask that X be placed …'
    (X should be placed …); 'May I request X for P?' (X for P)."""
    out = _sub(
        r"\bme (?:old |dear |fine |young )?(?:hearty|hearties|lad|lads|lass|mucker|matey|"
        r"darling|duck|beauty|beauties|friend|boy|boys|girl|son)\b",
        "",
        out := text,
    )
    out = _sub(r"\bbless (?:her|him|them|'em|you|me)(?: (?:little )?(?:heart|socks))?\b", "", out)
    out = _sub(
        r"(?:^|(?<=[,.!?] ))(?:(?:i'm|i am) )?(?:so |very |really |terribly )?sorry to (?:bother|"
        r"trouble|ask|interrupt|disturb|be a pain)(?: you)?(?: again)?,?(?: but,?)?\s*",
        "",
        out,
    )
    out = _sub(
        r"\b(?:can |could |please )?help me (?:to )?(?=([a-z]+)\b)",
        lambda m: "" if m.group(1).lower() in VERBS else m.group(0),
        out,
    )
    out = _sub(r"^(?:(?:and|so|oh|well),? )?let me (?:think|see)\s*[.,:;!]+\s*", "", out)
    out = _sub(
        r"^(?:may|might|can|could) (?:i|we) (?:ask|request) (?:that )?(.+?) be ",
        r"\1 should be ",
        out,
    )
    out = _sub(r"^(?:may|might|can|could) (?:i|we) (?:ask for|request) ", "", out)
    m = _rx(
        r"^((?:oh,? |well,? |and |so )?(?:(?:i|we) (?:do |really |honestly )?(?:think|reckon|"
        r"suppose|guess|believe|daresay|dare say|expect|imagine|bet|trust|gather|hope|suspect|"
        r"understand|must say|fear|feel)|(?:i'm|i am|we're|we are) (?:afraid|sure|told))"
        r"(?: that)?,?) "
    ).match(out)
    if m is not None and _names_nothing(m.group(1), lexicon):
        out = out[m.end() :]
    parts = _STRETCH.split(out.strip())
    chunks, seps = parts[0::2], parts[1::2]
    negated = re.search(r"\b(?:not|never|no)\b|n't\b", out.replace("don't mind", ""), _F)
    if len(chunks) >= 2 and not negated:  # 'Not yet, I'll leave it to you: …' stays refused
        drop = [bool(c.strip()) and _stance_stretch(c, lexicon) for c in chunks]
        if any(drop) and not all(d or not c.strip() for d, c in zip(drop, chunks, strict=True)):
            res = ""
            for k, c in enumerate(chunks):
                if drop[k] or not c.strip():
                    continue
                if res:
                    res += seps[k - 1] if k - 1 < len(seps) and seps[k - 1].strip() else ", "
                res += c
            tail = seps[-1].strip() if len(seps) >= len(chunks) else ""
            out = res + (tail[:1] if tail[:1] in (".", "!", "?") else "")
    return _tidy19(out) if out != text else text


# A hedge or a condition of courtesy around one request leaves nothing open: 'maybe' /
# 'perhaps' / 'possibly' (not with 'or' or 'not': "maybe give Bob the cup, or maybe not" stays
# refused), 'if you could (just) VP', 'is it okay if you VP', 'is it alright if P has X' (P gets
# X), 'would it be alright to VP', "if you'd be so good", 'if ye please', 'only if it's no
# bother'; and a tag after a request ('…, yeah?', '…, right?', '…, isn't it?', '…, won't you?',
# '…, can or not?', '…, innit?'), but not a tag about a person ("Tom has the gloves, doesn't
# he?": a question of fact).
_TAG19 = (
    r"(?:isn't it|doesn't it|won't you|will you|would you|could you|can you|right|yeah|yes|yah|"
    r"ya|okay|ok|eh|innit|can or not|can|alright|all right|aye|yeah\?? no|agreed|got it|"
    r"understood|see)"
)


# session 20: requests asked as whether they can be done
_ASKED20: tuple[tuple[str, str], ...] = (
    # "Could the banana go across to Emma, do you think?": after a polite question that asks
    # for something the tag asks nothing more ('Emma has it, do you think?' stays)
    (
        r"((?:^|[,.!]\s*)(?:could|can|would|will|might|shall)\b.+?),\s*(?:do|d'|don't) ?you "
        r"(?:think|reckon|suppose)\s*\?$",
        r"\1?",
    ),
    # "Is it possible that P gets X?", as 'is it okay if P gets X' is
    (
        r"^(?:sorry,? )?is it (?:possible|okay|ok|alright|all right|fine) (?:that|for) "
        r"([A-Za-z][\w ]*?) (?:gets|has|could have|can have|to get|to have) ",
        r"\1 gets ",
    ),
    # session 21: "Would it be possible for P to have X, and for Q to get Y?": P gets X, …
    (
        r"^(?:would|could|will) it be (?:possible|okay|ok|alright|all right) for ([A-Za-z][\w ]*?)"
        r" to (?:have|get|receive) (.+?),? and for ([A-Za-z][\w ]*?) to (?:have|get|receive)"
        r" (.+?)\s*\?$",
        r"\1 gets \2 and \3 gets \4",
    ),
    # "You couldn't give P the X, could you?": could you give P the X?
    (
        r"^you (?:couldn't|could not|can't|cannot|wouldn't|would not) (.+?),\s*(could|can|would)"
        r" you\s*\?$",
        r"\2 you \1?",
    ),
    # "Is possible you give the gloves to Tom?"
    (r"^is (?:it )?possible (?:you|to|for you to) (?:just |please )*", ""),
)


def _hedges19(text: str, lexicon: Lexicon) -> str:
    out = _sub(
        r"(?:^|,\s*|\bbut\s+)(?:and )?if (?:it's|it is|it isn't|it's not|that's|that is) (?:not )?"
        r"(?:too much |any |no )?(?:trouble|bother|okay|ok|alright|all right|fine|possible)"
        r"\s*(?:,|(?=[.!?]|$))",
        ", ",
        text,
    ).strip(" ,")
    out = _sub(r"(?:^|(?<=[.!?] ))(?:be (?:a|an|my) (?:[a-z']+ ){1,3}and) (?=[a-z]+ )", "", out)
    out = _sub(r"\b(would|could|will) be so (?:good|kind) as to\b", r"\1", out)
    out = _sub(r"\b(?:is|are) to (?:receive|get|have)\b", "gets", out)
    out = _sub(r"(?<=[a-z]) only\s*([.!]?)$", r"\1", out)
    out = _sub(r"(\bthen\b[^.!?]*?) (?:after|afterwards)\s*([.!?]|$)", r"\1\2", out)
    out = _sub(r"^(can|could|will|would)\b(.+?)\s+or not\s*\?$", r"\1\2?", out)
    asked = out.rstrip().endswith("?") or re.match(r"^(?:could|can|would|will|might)\b", out, _F)
    if asked and not re.search(r"\b(?:or|not|n't|unless)\b", out, _F):
        # a softener inside a polite question ('could the apple maybe go to Carol?'); a bare
        # '…, maybe' after a request leaves it open and stays refused
        out = _sub(r"(?:,\s*)?\b(?:maybe|perhaps|possibly)\b(?:\s*,)?\s*", " ", out)
        out = _sub(r"\bif at all possible\b\s*,?\s*", "", out)
    out = _sub(
        r"^(?:so,? |oh,? |and )?if (?:you|the robot|we|someone)(?:'d| would| could| can) "
        r"(?:just |please |kindly )*(?=([a-z]+) )",
        lambda m: "" if m.group(1).lower() in VERBS else m.group(0),
        out,
    )
    out = _sub(
        r"^is it (?:okay|ok|alright|all right|fine) if (?:you|the robot|we) (?:just )?", "", out
    )
    out = _sub(
        r"^(?:sorry,? )?is it (?:okay|ok|alright|all right|fine) if ([A-Za-z][\w ]*?) "
        r"(?:has|gets|takes|could have|can have) ",
        r"\1 gets ",
        out,
    )
    # session 24: "Would it be at all possible to set the lemon on the worktop?"
    out = _sub(
        r"^(?:would|could) it be (?:at all |even )?(?:okay|ok|alright|all right|fine|possible) to ",
        "",
        out,
    )
    for pattern, repl in _ASKED20:
        out = _sub(pattern, repl, out)
    out = _sub(
        r"^(?:,\s*)?if (?:you|ye|thou)(?:'d| would| wouldst)? (?:be so (?:good|kind)|"
        r"please)\s*,\s*",
        "",
        out,
    )
    out = _sub(r",?\s*if (?:you|ye|thou) (?:please|will)\b", "", out)
    out = _sub(r"(?:^|(?<=[.!?])\s*)only if it's no (?:bother|trouble)\s*[.!]?", "", out)
    m = _rx(rf",\s*{_TAG19}\s*[?.!]*\s*$").search(out)
    if m is None:
        # session 27: "Kindly give the chips to Person A, no?" (the tag of Sinhala and Indian
        # English, asking 'isn't it?'): only with its question mark, at the end ("…, no!" or
        # "…, no, Bob" could take the request back or correct it)
        m = _rx(r",\s*no\s*\?+\s*$").search(out)
    if m is not None and m.start() > 0:
        out = out[: m.start()] + "."
    out = _tidy19(out)
    if out != text and out.endswith("?") and text.rstrip().endswith("?"):
        # "Maybe pass Alice the bottle?", "Is it alright if P has X?": the hedge was the
        # question, and what is left is a request
        head = out.rstrip("?").strip()
        first = head.split(" ", 1)[0].lower()
        stated = first in VERBS or re.match(
            r"^[A-Z][\w ]*? gets\b|^the [a-z ]+ goes to\b", head, _F
        )
        if stated and first not in ("could", "can", "would", "will", "is", "are", "do", "does"):
            out = head + "."
    return out if out.strip() else text


# Closers after the request that ask nothing more ("That's all from me.", "End of list.", "Make
# it so.", "Over to you.", "That concludes the briefing.", "them's the orders", "Nothing
# further.", "and that's that", "Those are the headlines.", "I rest my case.", "… then we can
# close the ticket"): a last stretch or sentence that opens as a closer does, names nothing in
# the scene, and holds no word that adds, excepts, negates what was asked or points at a thing.
_CLOSER19 = re.compile(
    r"^(?:and |so )?(?:that's|that is|thats|that'll be|those are|these are|them's|this is|"
    r"we're|we are|that concludes|that completes|end of|nothing (?:further|else|more)|no further|"
    r"so let it be|let it be|make it so|over to you|over and out|class dismissed|story over|"
    r"job done|job's|jobs a|all done|all hands|what a|and scene|that be all|that would be|"
    r"that'd be|there's|there you go|there we go|so be it|"
    r"(?:and )?(?:then|after that|afterwards) (?:we|you|i) (?:can|could|'ll|will|are|'re)|"
    r"we're|we are)\b",
    _F,
)
_CLOSER_HELD19 = re.compile(
    r"\b(?:not|n't|except|but|too|also|another|more(?! questions)|other|else(?=\s+(?:to|for|on)"
    r")|and the|give|hand|pass|bring|take|put|place|send|them|him|her|he|she|they)\b",
    _F,
)


def _closers19(text: str, lexicon: Lexicon) -> str:
    if "?" in text:
        return text  # "ava gets the teddy?. That's everything.": a question stays one
    parts = _STRETCH.split(text.strip())
    chunks, seps = parts[0::2], [*parts[1::2], ""]
    keep = len(chunks)
    for k in range(len(chunks) - 1, 0, -1):
        c = chunks[k].strip()
        opener = _CLOSER19.match(c)
        go = re.match(r"^(?:go(?: go)*|let's go|off you go)$", c, _F)
        if go and k > 0 and _CLOSER19.match(chunks[k - 1].strip()):
            continue  # '… All hands, go.': said with the closer
        if not c or _filler_stretch(c, False, lexicon):
            continue
        rest = c[opener.end() :] if opener is not None else ""
        if opener is not None and re.match(r"nothing (?:else|more)\b", c, _F):
            # session 34 (12s): "…, nothing else will do for her": whom it is for, said again
            rest = re.sub(r"\s+for (?:him|her|them)\s*[.!]*$", "", rest, flags=_F)
        if opener is not None and not _CLOSER_HELD19.search(rest) and _names_nothing(c, lexicon):
            keep = k
            continue
        break
    if keep < len(chunks) and all(
        not c.strip() or _filler_stretch(c.strip(), False, lexicon) for c in chunks[keep:]
    ):
        keep = len(chunks)  # fillers only: _fillers19's to take off
    chunks, seps = chunks[:keep], seps[:keep]
    # a closer said on in the last stretch kept: '… and then we're lekker', '… then we can
    # close the ticket', '… and that's your lot', '… and then you can rest.' (the last stretch
    # holding words: a full stop leaves an empty one after it)
    at = max((k for k, c in enumerate(chunks) if c.strip()), default=len(chunks) - 1)
    last = chunks[at]
    m = _rx(
        r"\s+(?:and then |then |and )(?:we're|we are|that's|that is|you're|we can|we'll|that'll be)"
        r" [^,.;!?]*$|\s+(?:and )?(?:then|after that|afterwards) you (?:can|could|may) "
        r"(?:rest|relax|have a (?:rest|break|sit down|breather))\s*$"
    ).search(last)
    if (
        m is not None
        and not _CLOSER_HELD19.search(m.group(0))
        and _names_nothing(m.group(0), lexicon)
        and _names(last[: m.start()], lexicon)
    ):
        chunks[at] = last[: m.start()]
    head = "".join(
        p for k, c in enumerate(chunks) for p in (c, seps[k] if k < len(chunks) - 1 else "")
    )
    if head.strip() == text.strip() or not head.strip():
        return text
    head = _sub(r"(?:[,.!]\s*)(?:sorry|so sorry)\s*[.!,]*\s*$", "", head)
    return _tidy19(head) + ("." if not head.rstrip().endswith(("?", "!", ".")) else "")


# Corrections by cue, as one rule: a cue that takes back what was just said ('sorry', 'no sorry',
# 'whoops', 'oops', 'my mistake', 'my bad', 'pardon me', 'I mean', 'I misspeak', 'let me
# rephrase', 'or rather', 'strike that', 'scratch that', 'belay that (order)', 'revert that',
# 'correction:', 'no wait', 'no, hold on', 'eh no', 'nay') is said as the grammar's one form of
# correction (', no, '), which replaces what the words after it name in the request before it,
# or the whole request when they are one. A cue that ends the text, or one that begins it, is no
# correction ('Sorry, give Bob the cup' apologises; 'Give Bob the cup. Scratch that.' stays
# refused: nothing is left to do). A sentence that only apologises ('Sorry.', 'Sorry!') is taken
# off.
_CUE19 = (
    # session 25: 'ah no', 'eh sorry', 'sorry, wrong'
    r"(?:(?:no,? |(?:eh|ah),? no,? |(?:oh|eh|ah),? )?(?:sorry|so sorry)(?:,? (?:no|wrong))?"
    r"(?:,? i meant?)?|whoops|oops|"  # session 29 (12s): 'I meant' whole, not 'I mean' + 't'
    r"(?:no,? )?my (?:mistake|bad)|pardon me|i meant?|i misspeak|i misspoke|let me rephrase|"
    r"(?:or )?rather|(?:no,? )?(?:strike|scratch|belay|revert|cancel) that(?: order)?|"
    r"(?:wait|no wait|no),? (?:revert|scratch|strike|cancel) that|correction|"
    r"no,? (?:wait|hold on|hang on)|(?:eh|ah),? no|nay(?:,? i misspeak)?|no,? sorry|no,? no)"
)


def _asides_between_commas(text: str, lexicon: Lexicon) -> str:
    """The asides between the commas of one sentence (``_asides``; its stop is kept)."""
    stop = re.search(r"[.!?;]*\s*$", text)
    end = text[stop.start() :] if stop is not None else ""
    parts = text[: len(text) - len(end)].split(",")
    out = [parts[0]]
    k = 1
    while k < len(parts):
        seg = parts[k]
        words = seg.strip()
        last = k == len(parts) - 1
        before = _names(out[-1], lexicon)
        here = _names(words, lexicon)
        rel = re.match(r"(?:who|which)\b", words, _F)
        if rel and not here and not re.search(r"\b(?:it|them|him|her|he|she)\b", words, _F):
            # a relative clause ending at the next comma (which goes with it), or at the end
            if not last:
                out[-1] += parts[k + 1]
            k += 2
            continue
        if (
            not last
            and before
            and all(r.kind == "human" for r in before[-1].refs)
            and out[-1].rstrip().endswith(before[-1].text)
        ):
            same = (
                len(here) == 1
                and {r.id for r in here[0].refs} == {r.id for r in before[-1].refs}
                and words.lower().removeprefix("the ").strip() == here[0].text.lower()
            )
            # "Mrs Ortiz, the class teacher,": a description naming nobody else
            himself = all({r.id for r in x.refs} == {r.id for r in before[-1].refs} for x in here)
            # "… for Omar, the green one, …": 'one' picks out an object, not the person
            described = (
                himself
                and re.match(r"(?:the|a|an|our|my|your)\b", words, _F) is not None
                and not _picks_object(words, lexicon)
                # "Person A, my mistake, the apple": a correction's cue, not who Person A is
                and re.fullmatch(_CUE19, words, _F) is None
            )
            if same or described:  # "our manager, Priya," / "Mr Novak, the gentleman …,"
                out[-1] += parts[k + 1]
                k += 2
                continue
        out.append(seg)
        k += 1
    return ",".join(out) + end


def _asides(text: str, lexicon: Lexicon) -> str:
    """', who is at the front,' and ', the gentleman at the end,' said about someone or
    something: dropped when they name nothing of the scene; two names of one person keep one.
    A sentence at a time (session 29): in 'Thermometer to Ruth, the juggler. After that, …' the
    words between the commas are not one aside (the next sentence's order went with them)."""
    text = "".join(
        _asides_between_commas(part, lexicon) for part in re.split(r"(?<=[.!?;])(?=\s)", text)
    )
    # a restrictive 'who …' after a person the scene names once: "The guest who ordered the
    # fish wants a lemon"
    m = re.search(
        r"\bwho (?P<rel>(?:\w+'?\w* ){1,8}?)(?=(?:wants|needs|would like|'d like|should|gets|"
        r"could|can|is after)\b)",
        text,
        _F,
    )
    if m is not None:
        head = _names(text[: m.start()], lexicon)
        if (
            head
            and len(head[-1].refs) == 1
            and head[-1].refs[0].kind == "human"
            and text[: m.start()].rstrip().endswith(head[-1].text)
            and not _names(m.group("rel"), lexicon)
            and not re.search(r"\b(?:it|them|him|her|he|she)\b", m.group("rel"), _F)
        ):
            text = text[: m.start()] + text[m.end() :]
    return text


_RESTATE20 = re.compile(
    r"(?:(?<=[.!?])\s+|\s*,\s*)(?:(?:oh,? )?(?:no|sorry|correction|hang on|hold on|wait)"
    # session 34 (12s): 'no, (my) mistake' admits the slip ("…, no, mistake, it is for Person A")
    r"(?:,? (?:actually|sorry|no|wait|(?:my )?mistake))?"
    r"(?:,? i said that wrong| i got that wrong| that's wrong)?"
    r"|sorry,? i (?:said|got) that wrong|actually,? no)\s*[,.:;!]\s*(?:actually\s*,\s*)?",
    _F,
)


# session 34 (lead): 'it' that stands for the object, not the empty subject of a remark on the
# choice ('…, Alice or Bob, it doesn't matter' / 'it makes no odds' / 'it's all the same' / 'it's
# up to you'): read as the object, that 'it' made a correction of the object look like the whole
# request said again (12r's repairs fuzz: "Either of them can have the bottle, uh, no, the
# chips, Alice or Bob, makes no odds." read chips>A | bottle>A | bottle>B)
_REFERRING_IT34L = re.compile(
    r"\bit\b(?!\s*(?:doesn't|does not|don't|won't|will not) matter\b|\s+makes? no (?:odds|"
    r"difference)\b|(?:'s| is) (?:all )?(?:the same|one|fine|up to)\b)",
    _F,
)


def _restated20(text: str, lexicon: Lexicon) -> str:
    """Session 20: a correction said as the whole request again ('Chips to A. Correction, chips
    to B, and the apple to A.', 'Chips to A, sorry, I said that wrong, chips to B.', 'Teddy on the
    high chair, no, actually, give it to Lily.'): the clause before the cue is replaced when what
    follows reads by itself and names every object that clause did ('it' standing for its one
    object); one that adds ('too', 'also', 'as well') or leaves an object out stays refused."""
    for m in reversed(list(_RESTATE20.finditer(text))):
        head, after = text[: m.start()], text[m.end() :]
        # "…, no, scratch that, the crisps to Alice": the second cue is the same correction; left
        # at the head of the restated words it would take back the sentence before (session 24)
        after = _sub(
            r"^(?:scratch|strike|forget|ignore|cancel) that\s*[,.:;!]\s*|^i mean\s*,?\s*", "", after
        )
        cut = max(head.rfind(". "), head.rfind("! "), head.rfind("? "), head.rfind("; "))
        kept, before = (head[: cut + 1], head[cut + 2 :]) if cut >= 0 else ("", head)
        if not before.strip() or re.search(r"\b(?:too|also|as well|instead of)\b", after, _F):
            continue
        if not _names(before, lexicon) or not _names(after, lexicon):
            continue  # each side must name what it is about (cheap: no reading)
        said = _tasks_of(before, lexicon, normalise=False) or _tasks_of(before, lexicon)
        objects = {obj for _, obj, _ in said or ()}
        if not said or any(o.startswith("?") for o in objects):
            continue
        if _REFERRING_IT34L.search(after):
            if len(objects) != 1:
                continue
            after = _REFERRING_IT34L.sub(f"the {_said(next(iter(objects)), lexicon)}", after)
        # the grammar alone first; the rewrites only where that is refused ('Bob. Chips to Bob.')
        again = _tasks_of(after, lexicon, normalise=False) or _tasks_of(after, lexicon)
        if again is None or not objects <= {obj for _, obj, _ in again} or again == said:
            continue
        return f"{kept} {after}".strip()
    return text


_APOLOGY19 = re.compile(r"\b(?:excuse|pardon) me\s*$", _F)
_BOTHER19 = (
    r"(?:to|for) (?:bother|interrupt|trouble|disturb|rush|butt in|barge in)|for (?:the|any) "
)
_BOTHER19 += r"(?:bother|trouble|interruption|intrusion)|for (?:bothering|interrupting|troubling)"


# a call said as a sentence of its own before the request: 'Porter coming through, sorry!',
# 'Oh, aren't you clever.'
_CALLS21 = re.compile(
    r"^(?:(?:oh|ooh|well),? )?(?:(?:[a-z]+ )?coming through|mind your backs?|(?:aren't|isn't) "
    r"(?:you|he|she) (?:clever|good|lovely|kind|a star|a treasure|a love|a gem|helpful|"
    r"wonderful|brilliant|marvellous|a good (?:robot|boy|girl|helper)))(?:,? sorry)?\s*[.!]+\s*"
    r"(?=[a-z])",
    _F,
)


def _in_that_order21(text: str) -> str:
    """'Crisps on the shelf. Bottle to Alice. In that order.': a closing sentence of 'in that
    order' orders the sentences before it (each after the one before)."""
    m = _rx(r"\s*(?:sorry,? |oh,? |and )?in (?:that|this) order\s*[.!]*$").search(text)
    if m is None or m.start() == 0 or text[m.start() - 1] not in ".!":
        return text
    parts = re.split(r"(?<=[.!])\s+", text[: m.start()].strip())
    if len(parts) < 2 or any(re.match(r"(?:then|after|before|first|next)\b", p, _F) for p in parts):
        return text
    return " Then ".join(p.rstrip(".! ") + "." for p in parts).replace(". Then ", ". Then ")


def _attention21(text: str, lexicon: Lexicon) -> str:
    """Session 21: the opener rule (greetings, 'yes', 'Excuse me, sorry, …': _OPENERS) said
    first, before any other session-19 rewrite reads 'sorry' as a correction or 'me' as the
    speaker. A call of its own ('Porter coming through!', 'Oh, aren't you clever.') likewise; a
    closing 'In that order.' orders the sentences before it."""
    return _in_that_order21(_CALLS21.sub("", _drop(_OPENERS, text, lexicon)))


_SPEAKER21: tuple[tuple[str, str], ...] = (
    # "don't mind me", "never mind me", "ignore me": the speaker excusing themself
    (r"(?:^|\s*,\s*)(?:(?:oh,? )?(?:don't|do not|never) mind me|ignore me)\s*(?=[,.!?]|$)", ""),
    # "I would like to ask you, …", "Can I ask you for something? …": a request announced
    (
        r"(?:^|(?<=[.!?] ))(?:(?:i would|i'd) like to|can i|could i|may i|let me) ask(?: you)?"
        r"(?: for)?(?: (?:something|a favou?r|a (?:quick|small) (?:thing|favou?r)|one thing))?"
        r"\s*[,.?!:]\s*(?=[a-z])",
        "",
    ),
    # "very kindly", "ever so gently": the manner word with its intensifier
    (r"\b(?:very|so|ever so|most|really) (kindly|gently|quickly|carefully)\b", r"\1"),
    # "Either cup will do for Dana.": either cup for Dana
    (
        r"^(either|any) ([a-z]+) (?:will do|would do|is fine|is okay|works) for "
        r"([A-Z]\w*(?: [A-Z]\w*)?)(\s*[.!]?)$",  # one person
        r"\1 \2 for \3\4",
    ),
    # "…, before I start on this socket": the speaker's own next step, after the request
    (
        r"\s*,?\s+before (?:i|we) (?:start|begin|get going|get started|crack on|head off|go|"
        r"leave)(?: on| with)?(?: (?:this|the|my|our|that) [a-z]+)?(?=\s*[.!]?$)",
        "",
    ),
)


def _speaker21(text: str, _lexicon: Lexicon) -> str:
    """Session 21: the speaker's remarks that ask nothing ('don't mind me', 'I would like to ask
    you,', 'Can I ask you for something?', '…, before I start on this socket'); 'Either X will
    do for P' (either X for P)."""
    out = text
    for pattern, repl in _SPEAKER21:
        out = _sub(pattern, repl, out)
    return out.strip(" ,") or text


# a clause giving a reason after the request: its subject, then a verb
_REASON21 = re.compile(
    r"(?:\s*[,;]\s*|\s+[—–-]\s+|\s+(?=its [a-z]+ing\b))"
    r"((?:(?:oh|and|cos|coz|cause|because|as|since)\s+)?"
    r"(?:(?:she|he|it|they|we|i)(?:'s|'re|'ve|'ll|'d|'m| is| are| was| were| has| have| had| "
    r"keeps?| will| can| just)|its [a-z]+ing|(?:her|his|their|my|our|the) [a-z]+(?:'s| is| are| "
    r"was| were| has| keeps?)|table (?:one|two|three|four|five|six|seven|eight|nine|ten|\d+)"
    r"(?:'s| is| are))\b[^,.;!?—–]*?)\s*(?=[.!?]|$)",
    _F,
)
# words a reason must not hold: what would change who gets what, or which one
_REASON_HELD21 = re.compile(
    r"\b(?:no|not|never|nothing|none|only|just the|too|also|as well|instead|rather|first|then|"
    r"before|once|when|until|unless|if|one|ones|both|each|either|every|another|other|rest|same|"
    r"give|hand|pass|bring|take|put|place|want|wants|wanted|need|needs|needed|like|likes|love|"
    r"loves|fancy|fancies|prefer|prefers|keep it|leave|send|move|them|those|these|that|this|"
    r"wrong|mean|meant|sorry|actually|mistake|change|swap|cancel|instead|him|for him|for her|"
    r"mine|yours|hers|his own|her own)\b|n't\b",
    _F,
)


def _reasons21(text: str, lexicon: Lexicon) -> str:
    """Session 21: a reason said after the request, closing its sentence (', she's getting
    chilly after her exercises', ', her bench is a mess', ', table six is waiting on their
    mains', ' its cluttering my desk'): a clause of a subject (a pronoun, 'her X', 'table six')
    and a verb that names nothing in the scene, no other name, and no word that could change who
    gets what or which one: taken off, when the request before it names something."""
    for m in reversed(list(_REASON21.finditer(text))):
        clause = m.group(1)
        before = text[: m.start()]
        words = re.findall(r"[A-Za-z']+", clause)
        if (
            _REASON_HELD21.search(clause)
            or any(w[0].isupper() and w != "I" and not w.startswith("I'") for w in words[1:])
            or not _names_nothing(clause, lexicon)
            or not _names(re.split(r"[.!?]\s", before)[-1], lexicon)
        ):
            continue
        text = before + text[m.end() :]
    return text


# -- session 31 (engineer 12s): blind17-23's known misses, by kind -------------------------------

# 'will do' / 'is fine' said of a choice with its one recipient ("Any of the pens will do for
# Sam.", "Either mug's fine for Carol.", "Either of the two things to Person B is fine."): the
# choice for that person. Session 21 read "Either cup will do for Dana" alone (one word after
# 'either', a whole text); this reads a sentence of that shape wherever it stands.
_FINE31S = r"(?: will do| would do|'ll do| is fine|'s fine| is okay| is ok| works)"
_CHOICE31S = (
    r"(?:either|any)(?: one)?(?: of (?:the|those|these)(?: two| three| four)?)? [a-z]+(?: [a-z]+)?"
)
_WILL_DO31S = re.compile(
    rf"(?:^|(?<=[.!?] ))(?P<choice>{_CHOICE31S}){_FINE31S} (?P<to>for|to) "
    r"(?P<who>[^,.;!?]+?)(?=\s*(?:[,.;!?]|$))",
    _F,
)
_FINE_AFTER31S = re.compile(
    rf"(?:^|(?<=[.!?] ))(?P<choice>{_CHOICE31S}) (?P<to>for|to) (?P<who>[^,.;!?]+?)"
    rf"{_FINE31S}(?=\s*(?:[,.;!?]|$))",
    _F,
)
# after a choice said before it: 'either colour's fine', 'any size is ok' (said of the kind)
_KIND_FINE31S = re.compile(
    r",\s*(?:either|any) (?:colour|color|size|one|kind|sort)(?:'s| is) (?:fine|ok|okay)"
    r"(?=\s*(?:[,.!]|$))",
    _F,
)


def _will_do31s(text: str, lexicon: Lexicon) -> str:
    """Session 31 (12s): a choice said to be fine for one person is that choice for them (above):
    read when the choice names only objects and the words after 'for' / 'to' exactly one person
    ("Any of the pens will do for Sam and Priya" stays)."""

    def chosen(m: re.Match[str]) -> str:
        if not _objects_only(m.group("choice"), lexicon) or not _only_person(
            m.group("who"), lexicon
        ):
            return m.group(0)
        return f"{m.group('choice')} {m.group('to')} {m.group('who')}"

    out = _WILL_DO31S.sub(chosen, text)
    out = _FINE_AFTER31S.sub(chosen, out)

    def after_choice(m: re.Match[str]) -> str:
        chose = re.search(r"\b(?:one of|either|any)\b", m.string[: m.start()], _F)
        return "" if chose else m.group(0)

    return _KIND_FINE31S.sub(after_choice, out)


# 'Both of those' / 'both of them' opening a sentence, then where they go ("Black pen to Sam.
# Also the notepad. Both of those to him."): the grammar's 'both' (the two objects named before,
# or a refusal saying it cannot tell which); with the list said after it ("Both of them, bottle
# and chips, go to Person A"): the list. ('Give both of them a cup' names people: left.)
_BOTH_OF31S = re.compile(
    r"(?:^|(?<=[.!?] ))(?:(?P<both>both|the two|all three|the three) of (?:them|those|these)"
    r"(?P<list>,\s*[^,.;!?]+?,)?|(?P<alone>both|all three),\s*(?P<listed>[^,.;!?]+?),)"
    r"(?= (?:to|for|on|onto|in|into|go|goes|over|up|across)\b)",
    _F,
)
_HOW_MANY31S = {"both": 2, "the two": 2, "all three": 3, "the three": 3}


def _both_of31s(text: str, lexicon: Lexicon) -> str:
    """Session 31 (12s): 'both of those' before where they go is 'both'; with a list in
    apposition, the list, when it names only objects, as many as the count says (above)."""

    def said(m: re.Match[str]) -> str:
        listed, both = m.group("list") or m.group("listed"), m.group("both") or m.group("alone")
        if listed is None:
            return both
        names = _names(listed, lexicon)
        if not _objects_only(listed, lexicon) or len(names) != _HOW_MANY31S[both.lower()]:
            return m.group(0)
        words = listed.strip(" ,")
        return words[0].upper() + words[1:] if both[0].isupper() else words

    return _BOTH_OF31S.sub(said, text)


# Where an object is, said where the object opens a sentence ("You see the red mug by the
# window? Take it across to Alice", "That bottle by the door, up on the shelf", "You see that
# bottle next to you? Person A needs it"): a place the scene does not know, after a name that is
# one object of the scene, tells which object is meant no more than the name does; taken off.
# (After a name of several objects it would have to choose — 'the mug by the window' with two
# mugs — and is left, and refused; after a verb it may say where to put it — "Put the cup by the
# window" — and is left.) The question pointing at the object ("You see that bottle? …") is the
# object said as a topic ("That bottle. …"), as session 17's _see_it17 reads it before 'it'.
_WHERE_IT_IS31S = re.compile(
    r"(?:^|(?<=[.!?] ))(?P<see>(?:(?:so |and )?(?:do |can )?you see |see ))?"
    r"(?P<det>the|that|this) (?P<obj>[a-z]+(?: [a-z]+)?)(?P<loc> (?:by|next to|near|beside|"
    r"behind|in front of|right by|just by|over by) (?:you|(?:the|your|my|that|this) [a-z]+"
    r"(?: [a-z]+)?))?(?P<end>\s*[?,])",
    _F,
)


def _where_it_is31s(text: str, lexicon: Lexicon) -> str:
    """Session 31 (12s): a place the scene does not know after a sentence-opening name of one
    object is taken off, and the question pointing at it is the object as a topic (above)."""

    def one(m: re.Match[str]) -> str:
        obj, loc, see = m.group("obj"), m.group("loc"), m.group("see")
        asks = see is not None and m.group("end").strip() == "?"
        if loc is None and not asks:
            return m.group(0)
        named = _names(obj, lexicon)
        if len(named) != 1 or named[0].quant or len(_ids(obj, lexicon)) != 1:
            return m.group(0)
        if not _objects_only(obj, lexicon) or not _names_nothing(loc or "", lexicon):
            return m.group(0)
        if asks:
            return f"{m.group('det').capitalize()} {obj}."
        return f"{see or ''}{m.group('det')} {obj}{m.group('end')}"

    return _WHERE_IT_IS31S.sub(one, text)


# A reason after the request that says what is not so of its subject ("…, she won't settle for
# the hymn practice without it", "…, she hasn't eaten since six this morning", "…, the race
# isn't for an hour"): session 21's reasons (_reasons21) hold no negation, as 'she's not having
# the X' changes what is asked; a negated verb whose clause names nothing in the scene, no
# other name, and no word that could change who gets what, which one or when (_NOT_HELD31S:
# session 21's words but the negation, and choices, time words) is a reason all the same, taken
# off on session 21's terms (closing its sentence, after a request that names something), when
# it holds no word of a scene name either ("…, he can't stand blue" may say which mug).
_NOT_REASON31S = re.compile(
    r"\s*,\s*(?P<said>(?:(?:and|cos|because|as|since)\s+)?(?:she|he|it|they|(?:the|her|his|their) "
    r"[a-z]+)(?:'s| is| has)? ?(?:won't|wont|isn't|hasn't|can't|doesn't|didn't|haven't|aren't|"
    r"wasn't|not|'s not|'re not| is not| has not)\b[^,.;!?—–]*?)\s*(?=[.!?]|$)",
    _F,
)
_NOT_HELD31S = re.compile(
    r"\b(?:nothing|none|only|just the|too|also|as well|instead|rather|first|then|before|once|"
    r"when|until|unless|if|one|ones|both|each|either|every|another|other|rest|same|give|hand|"
    r"pass|bring|take|put|place|want|wants|wanted|need|needs|needed|like|likes|love|loves|fancy|"
    r"fancies|prefer|prefers|keep|leave|send|move|them|those|these|that|this|wrong|mean|meant|"
    r"sorry|actually|mistake|change|swap|cancel|him|for him|for her|mine|yours|hers|his own|"
    r"her own|which|what|whatever|any|anything|all|else|matter|mind|fussed|bothered|care|sure|"
    r"know|yet|now|today|tomorrow|tonight|later|soon|here|have|get|got|having|getting|theirs|"
    r"ours)\b|\b(?:his|her|their)\s*$",
    _F,
)


# Words the grammar reads said another way: 'do likewise' is 'do the same' ("Haul the medium box
# onto the belt, then do likewise with the small one"); 'straight / right / directly /
# immediately after' closing a clause is 'after' ("…, and the medium one straight after"); 'the
# X and the Y both' is 'both the X and the Y' when X and Y name objects ("Person B wants the
# bottle and the chips both, …").
_BOTH_AFTER31S = re.compile(
    r"\b(?P<list>(?:the )?[a-z]+(?: [a-z]+)? and (?:the )?[a-z]+(?: [a-z]+)?) both"
    r"(?=\s*(?:[,.;!?]|$))",
    _F,
)


def _said_otherwise31s(text: str, lexicon: Lexicon) -> str:
    """Session 31 (12s): 'do likewise', 'straight after', '… both', 'please love', 'this
    morning' said as the grammar says them (above)."""
    out = _sub(r"\bdo likewise\b", "do the same", text)
    # a term of address after a courtesy word, without its comma ('please love')
    out = _sub(
        r"\b(please|thanks|ta|cheers) (love|dear|mate|pet|hun|darling)(?=\s*(?:[,.;!?]|$))",
        r"\1, \2",
        out,
    )
    # 'this morning' closing a request: today ('this afternoon / evening' put it off: session 20);
    # not after a past tense ("Marco had the knife this morning" says what was)
    if not re.search(
        r"\b(?:had|got|was|were|gave|took|brought|handed|passed|did|went|came)\b", out, _F
    ):
        out = _sub(r"(?<=[a-z]) this morning(?=\s*[.!]*\s*$)", "", out)
    out = _sub(
        r"\b(?:straight|right|directly|immediately) (after|afterwards)(?=\s*(?:[,.;!?]|$))",
        r"\1",
        out,
    )

    def both(m: re.Match[str]) -> str:
        listed = m.group("list")
        if len(_ids(listed, lexicon, "object")) != 2 or not _objects_only(listed, lexicon):
            return m.group(0)
        return f"both {listed}"

    return _BOTH_AFTER31S.sub(both, out)


# -- session 28 (engineer 12): blind26's reasons said after the request ---------------------------

# A reason closing the request's sentence that session 21's (_reasons21) did not take: a subject
# of two or three words ('the bell ringers are starving', 'the foley session ran long'), a past
# tense of a few verbs ('ran', 'finished': _PAST28; not any '-ed', 'the red' is none), 'both'
# after a plural pronoun and its 'be' ("they're both glazing pots": says they are two, asks
# nothing), and 'seeing as' / 'seeing that' / 'given that' / 'now that' opening it. The same
# conditions as session 21's: the clause names nothing in the scene, holds no word that could
# change who gets what or which one, no capitalised word but 'I', and the request before it
# names something.
_PAST28 = (
    r"(?:ran|went|got|came|took|fell|broke|began|overran|finished|started|ended|arrived|left|"
    r"stopped|closed|opened|dragged|ran over)"
)
# a noun phrase's words after its determiner (no 'and' / 'or' / article: one phrase)
_NOUNS28 = r"(?!(?:and|or|the|a|an)\b)[a-z-]+"
_REASON28 = re.compile(
    r"(?:\s*[,;]\s*|\s+[—–-]\s+)"
    r"((?:(?:oh|and|cos|coz|cause|because|as|since|seeing as|seeing that|given that|now that)"
    rf"\s+)?(?:(?:they|we)(?:'re| are| were) (both)\b|(?:her|his|their|my|our|the) {_NOUNS28}"
    rf"(?: {_NOUNS28}){{1,2}}(?:'s| is| are| was| were| has| have| had| keeps?)|"
    rf"(?:her|his|their|my|our|the) {_NOUNS28}(?: {_NOUNS28}){{0,2}} {_PAST28}|"
    r"(?:she|he|it|they|we|i)(?:'s|'re|'ve|'d|'m| is| are| was| were| has| have| had) |"
    rf"(?:she|he|it|they|we|i) {_PAST28})\b[^,.;!?—–]*?)\s*(?=[.!?]|$)",
    _F,
)
