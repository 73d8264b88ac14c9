"""The grounder's rules of session 44, engineer 12r (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _ids, _reading
from hltl.grounding._rewrites42r import _WHO42R, _fits42r, _person42r
from hltl.grounding.lexicon import PRONOUN_SEX, Lexicon, unnamed_sex44l
from hltl.grounding.tree import Node, tasks

# -- corrections -----------------------------------------------------------------------------------

# a cue that the request before is being taken back ("ooh wait", "no hang on", "correction",
# "oh hang about", "hang on, my mistake"), each word of it one of these
_CUE44R = (
    r"(?:ooh|oh|ah|er|erm|um|hmm|no|nope|wait|hang on|hold on|hang about|correction|my mistake|"
    r"sorry|whoops|oops|actually)"
)
# the words of a cue that take the request back (a bare 'oh' or 'hmm' may add to it)
_BACK44R = r"\b(?:wait|hang on|hold on|hang about|correction|my mistake|no|sorry)\b"
_REASON_FIX44R = (
    rf"^(?P<head>.+?)\s*(?P<sep>\.\.\.|…|[,;.!—])\s*(?P<cue>{_CUE44R}(?:\s*,?\s*{_CUE44R})*)\s*"
    r"[,;:—]\s*(?P<why>(?:[^,;.]+[,;]\s*){0,2}?)(?P<fix>[^,;.]+?)(?:\s*,\s*(?P<pro>hers|his) "
    r"then)?(?P<end>\s*[.!]?)$"
)
# the corrected request, said as what takes the place of the request's person, place or thing
_FIXES44R: tuple[str, ...] = (
    # "make it Person B"
    r"^make (?:it|that|them) (?:to |for )?(?P<r>.+)$",
    # "they're for Person B", "it's meant for Tom", "they're Tom's"
    rf"^(?:they're|they are|it's|it is|those are) (?:(?:meant |going )?(?:for|to) (?P<r>{_WHO42R})"
    rf"|(?P<r2>{_WHO42R})'s)$",
    # "Tom should have them", "Tom's having it"
    rf"^(?P<r>{_WHO42R}) (?:should (?:have|get)|gets|can have|(?:'s|is) (?:having|to have|getting)|"
    r"wants) (?:it|them|those|that|one)$",
    # "Ruth's doing the rounds so it's hers"
    rf"^(?P<r>{_WHO42R})(?:'s| is| has) [a-z ]+? so (?:it's|it is|they're|they are) "
    r"(?P<pro>hers|his)$",
    # "the sink's better"
    r"^(?P<r>(?:the )?[a-z]+)(?:'s| is| would be|'d be| will be) (?:better|best|a better (?:bet|"
    r"place|spot|idea))$",
    # "I must have meant the bottle"
    r"^i (?:must have |must've |should have |)meant (?P<r>.+)$",
)
_FIX_PRO44R = {"hers": "she", "his": "he"}


def _agrees44r(pid: str, pronoun: str, lexicon: Lexicon) -> bool:
    """Whether ``pronoun`` may be person ``pid``: as ``_fits42r`` has it, and not against the sex
    the scene's names or the corpus's Person A / B convention give (``unnamed_sex44l``)."""
    pro = _FIX_PRO44R.get(pronoun.lower(), pronoun.lower())
    sex = unnamed_sex44l(pid, lexicon)
    return _fits42r(pid, pro, lexicon) and (sex is None or sex == PRONOUN_SEX.get(pro, sex))


def _fix44r(fix: str, lexicon: Lexicon) -> str | None:
    """What the corrected request ``fix`` puts in the place of the request's person, place or
    thing, or None when it is said some other way."""
    for pat in _FIXES44R:
        m = re.match(pat, fix.strip(), _F)
        if m is None:
            continue
        said = next(w for w in (m.group("r"), m.groupdict().get("r2")) if w)
        pro = m.groupdict().get("pro")
        if pro is not None:
            pid = _person42r(said, lexicon)
            if pid is None or not _agrees44r(pid, pro, lexicon):
                return None
        return said
    return None


def _reason_fix44r(text: str, lexicon: Lexicon) -> str:
    """Session 44 (12r): one request, a cue that takes it back ("ooh wait", "no hang on",
    "correction", "oh hang about", "hang on, my mistake"), maybe a reason that names nothing the
    request does not ("she's got one", "she's out on the pilot boat", "it's mucky", "no chips
    here"), then what takes the place of its person, place or thing ("make it P", "they're for P",
    "Q should have them", "Q's doing the rounds so it's hers", "the sink's better", "I must have
    meant the bottle, hers then"): "<request>, no, <that>" (the grammar's correction). Taken only
    when the request is one task (or names what the scene lacks) and that reads."""
    low = text.lower()
    if not any(
        w in low for w in ("wait", "hang ", "hold on", "correction", "mistake", "no", "sorry")
    ):
        return text
    m = re.match(_REASON_FIX44R, text.strip(), _F)
    if m is None or not re.search(_BACK44R, m["cue"], _F):
        return text
    head, why = m["head"], m["why"]
    said = _fix44r(m["fix"], lexicon)
    if said is None or re.search(r"\b(?:and|also|too|as well|plus|then|instead)\b", why, _F):
        return text
    if not _ids(said, lexicon) or _ids(why, lexicon) - _ids(head, lexicon):
        return text  # the reason names something the request does not: more than a reason
    first = _reading(head, lexicon)
    if first is not None and len(list(tasks(first))) != 1:
        return text  # several requests: which does it correct?
    if m["pro"] is not None:
        pids = _ids(f"{head} {said}", lexicon, "human")
        if len(pids) != 1 or not _agrees44r(next(iter(pids)), m["pro"], lexicon):
            return text  # "…, hers then": the request's one person
    out = f"{head}, no, {said}{m['end'] or '.'}"
    return out if _reading(out, lexicon) is not None else text


# the normaliser's rewrites run before the session-43 ones (wired into normalise._STEPS19)
_STEPS44R_FIRST: tuple[Callable[[str, Lexicon], str], ...] = ()
# the normaliser's rewrites (wired into normalise._STEPS19, before the session-43 ones)
_STEPS44R: tuple[Callable[[str, Lexicon], str], ...] = (_reason_fix44r,)
# refusals asked of the text before it is read (offline._parse, after the session-43 ones)
REFUSE44R: tuple[Callable[[str, Lexicon], None], ...] = ()
# checks of the whole instruction's reading (offline.parse_instruction, after the session-43 ones)
CHECK44R: tuple[Callable[[str, Node, Lexicon], None], ...] = ()
