"""The grounder's rules of session 52, engineer 12s (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _ids
from hltl.grounding._rewrites51s import _not_x_rest51s, _plain51s
from hltl.grounding.lexicon import Lexicon, first_name_sex36s, person_name, said_sex35s
from hltl.grounding.tree import Node, tasks

# what a person holds, held, was handed or wanted once ("…, so he had the blue one", "he had the
# pills", "Bob has …", "Lily's got …"): a report, which a rewrite would leave to be read as a
# handover (12c 13:43). One list for session 52's rules here (12s) and session 53's `_held53r` (12r)
_HELD52S = re.compile(
    r"\b(?:has|had|'s got|'ve got|have got|got|gotten|took|taken|received|wanted|needed|was "
    r"after|were after|went|given|was handed|already|ended up|finished up|wound up|kept|keeps|"
    r"holds|holding|held)\b",
    _F,
)


def _plain52s(out: str, text: str, lexicon: Lexicon) -> str:
    """Session 51's `_plain51s`, unless ``text`` says a past holding (above): then ``text``."""
    if out != text and _HELD52S.search(text):
        return text
    return _plain51s(out, text, lexicon)


# -- session 52 (12s): a he / she who wants a thing the reading gives to the other sex ----------
#
# "Give Alice the cup, not Bob, he wants the apple." read `cup>A & apple>A` (12c's fuzz, session
# 51): the grammar gave the apple to the one person the request hands to, and session 34's
# `_named_other_sex34s` let it be, Bob (named in 'not Bob') being one a 'he' may be. A clause whose
# subject is a he / she and whose verb wants, needs or gets a thing of the scene says who is to
# have it; a reading handing that thing to a person the scene says is of the other sex (a first
# name, a title, a word of kin; not the generic 'Person A' / 'Person B', which older parts call
# 'she' and 'he' either way) is refused. The clause names no other person ('she wants the apple
# for Tom' hands it to Tom) and no him / her / them.
_SHE_WANTS52S = re.compile(
    r"\b(?P<pro>he|she)(?:'s| is| has| was)?(?: (?:just|really|still|also|too|been|got|even))*"
    r" (?:wants|needs|gets|getting|get|would like|'d like|after|fancies|fancying|asked for|"
    r"asking for|can have|should get|should have|'ll have|will have|'ll take|will take|takes|"
    r"is having|'s having|craving|dying for|gasping for|desperate for)\b"
    r"(?P<rest>[^,.;:!?]*)",
    _F,
)


def _other_sex52s(pid: str, sex: str, lexicon: Lexicon) -> bool:
    """Whether the scene says person ``pid`` is not of ``sex`` (a first name of one sex, a title,
    a word of kin; none of them saying ``sex``)."""
    said = {first_name_sex36s(pid, lexicon), said_sex35s(pid, lexicon)} - {None}
    return bool(said) and sex not in said


def _she_wants_other52s(text: str, node: Node, lexicon: Lexicon) -> None:
    """Session 52 (12s): a thing a he / she wants given to the other sex is refused (above)."""
    low = text.lower()
    if "he" not in low:  # 'he' and 'she' both hold it
        return
    given = [t for t in tasks(node) if t.kind == "deliver"]
    if not given:
        return
    for m in _SHE_WANTS52S.finditer(text):
        rest = m["rest"]
        if re.search(r"\b(?:him|her|them|for|to)\b", rest, flags=_F):
            continue
        if _ids(rest, lexicon, "human"):
            continue
        wanted = _ids(rest, lexicon, "object")
        if not wanted:
            continue
        sex = "m" if m["pro"].lower() == "he" else "f"
        for task in given:
            if task.obj in wanted and _other_sex52s(task.target, sex, lexicon):
                raise GroundingError(
                    f"{m['pro']!r} wants {rest.strip()!r}, but the reading gives it to "
                    f"{person_name(task.target, lexicon)}, whom {m['pro']!r} cannot mean: "
                    "name the person"
                )


# -- session 52 (12s): blind50's negation by kind -------------------------------------------------
#
# "Carol doesn't drink from the red mug, she says it's chipped, so give her the blue." (blind50
# #120): not using a thing said of its use ('doesn't drink from / eat off / use the X', 'won't
# drink out of the X'): said "doesn't want the X", which the older rules read with what is wanted
# instead (a not-wanting alone stays refused).
_NOT_USE52S = re.compile(
    r"\b(?:doesn't|does not|won't|will not|wouldn't|would not|never) (?:(?:drink|eat|drinks|eats)"
    r" (?:from|out of|off)|use|uses) (?=(?:the|that|this|her|his|their) [a-z])",
    _F,
)


def _not_use52s(text: str, lexicon: Lexicon) -> str:
    """Session 52 (12s): 'P doesn't drink from the X' said 'P doesn't want the X' (above)."""
    low = text.lower()
    if "drink" not in low and "eat" not in low and "use" not in low:
        return text
    out = _NOT_USE52S.sub("doesn't want ", text)
    return _plain52s(out, text, lexicon)


# "Jess doesn't need the drill after all, she's only after the torch for the crawl space." (#139):
# 'after all' closing a not-wanting clause says the want is over, which the clause says already:
# taken off (a not-wanting alone stays refused, as a want that is over).
_AFTER_ALL52S = re.compile(
    r"(?P<neg>\b(?:doesn't|does not|don't|do not|won't|no longer|isn't|is not) (?:need|want|"
    r"after|needs|wants|fancy|have) (?:the|that|this|her|his|their|any) [a-z]+(?: [a-z]+)?)"
    r" after all(?=\s*[,;])",
    _F,
)


def _after_all52s(text: str, lexicon: Lexicon) -> str:
    """Session 52 (12s): 'P doesn't need the X after all, …' said without 'after all' (above)."""
    if "after all" not in text.lower():
        return text
    return _plain52s(_AFTER_ALL52S.sub(lambda m: m["neg"], text), text, lexicon)


# "Don't put the knife out, just the tongs for Lena." (#136): a negated command whose thing the
# request after 'just / only' replaces: said "Not the X, just …" (session 42's), when the thing
# is one of the scene and the request then reads without it.
_PARTICLE52S = r"(?:out|over|down|up|across|round|back)"
_DONT_JUST52S = re.compile(
    r"^(?:please\s+)?(?:don't|do not) (?:put|get|bring|take|fetch|grab|pass|hand|give|set|lay)"
    rf"(?: {_PARTICLE52S})? (?P<x>the [a-z]+(?: (?!{_PARTICLE52S}\b)[a-z]+)?)"
    rf"(?: {_PARTICLE52S})?\s*[,;]\s*(?P<rest>(?:just|only) \S.*)$",
    _F,
)


def _dont_just52s(text: str, lexicon: Lexicon) -> str:
    """Session 52 (12s): "Don't put the X out, just the Y for P" said "Not the X, just …"."""
    low = text.lower()
    if "just" not in low and "only" not in low:
        return text
    out = _not_x_rest51s(_DONT_JUST52S.match(text.strip()), text, lexicon)
    return text if out is None else _plain52s(out, text, lexicon)


# -- session 52 (12s): an opening perfect participle (12c's probe) ------------------------------
#
# "Having given Bob the apple, give Alice the crisps." read `apple>B & chips>A`, and "Having given
# Bob the apple." `apple>B`: the grammar took the participle for a request. 'Having given …' says
# the task is done (a report), or at most that it comes first: refused before the read, as a
# told-as-done task is ("Once you've given Bob the apple, give Alice the crisps." orders them).
# Only opening a sentence; after a person's sentence ('Bob has earned the crisps, having given
# Carol the apple.') session 34's `_doer_said34s` refuses it as said of them.
_HAVING52S = re.compile(
    r"(?:^|[.;!?]\s+)(?P<h>having (?:given|handed|passed|put|placed|set|taken|brought|fetched|"
    r"dropped|delivered|popped|stuck|laid|sent|moved|left)\b[^,;.!?]*)",
    _F,
)


def _having_done52s(text: str, lexicon: Lexicon) -> None:
    """Session 52 (12s): a sentence opening "Having given P the X" is refused (above)."""
    if "having" not in text.lower():
        return
    m = _HAVING52S.search(text.strip())
    if m is not None:
        raise GroundingError(
            f"{m['h'].strip()!r} tells what is done already: to have it done first, say "
            "'first …, then …'"
        )


# the normaliser's first rewrites (wired into normalise._STEPS19, before the session-51 ones)
_STEPS52S_FIRST: tuple[Callable[[str, Lexicon], str], ...] = (
    _not_use52s,
    _after_all52s,
    _dont_just52s,
)
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-51 ones)
_STEPS52S: tuple[Callable[[str, Lexicon], str], ...] = ()
# refusals asked of the text before it is read (offline._parse, after the session-51 ones)
REFUSE52S: tuple[Callable[[str, Lexicon], None], ...] = (_having_done52s,)
# checks of the whole instruction's reading (offline.parse_instruction, after the session-51 ones)
CHECK52S: tuple[Callable[[str, Node, Lexicon], None], ...] = (_she_wants_other52s,)
