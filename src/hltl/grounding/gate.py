"""re's functions behind a word gate: no pattern runs on a text lacking every word it needs."""

# The normaliser runs some 1,500 regular expressions over each refused instruction, most of
# which cannot match it: a rewrite for 'be grateful for' on a text without 'grateful'. Each
# pattern's literal words, one of which every match contains, are derived once from the pattern
# itself (re's own parser), so a new rule is gated without anything said about it; where no such
# words can be derived (a pattern that can match without any fixed word) it always runs. The text
# is checked lower-cased for a case-blind pattern, and only when it is ASCII (re folds a few
# other letters onto ASCII ones: 'ſ', the long s, is an 's'), else the pattern runs.
#
# Compiled patterns are also kept in a cache larger than re's own (512): the normaliser's
# patterns overflowed it, and every overflow recompiled a pattern on its next use.
#
# A pattern's words are derived the first time it is met (session 39, 12p), from re's parse of
# it, and the pattern is compiled from that same parse (re's own code generator on it: the
# pattern re.compile returns). Until then a pattern had been compiled (parsed) the first time it
# was met and parsed again for its words the second: two parses where one does.
#
# The functions take re's arguments and return what re returns; where the gate says no match is
# possible they return what re returns for no match (the text unchanged, None, [], [text]).

from __future__ import annotations

import contextlib
import functools
import itertools
import re
import sys
from collections.abc import Callable, Iterator
from re import IGNORECASE as IGNORECASE
from re import Match as Match
from re import Pattern as Pattern
from re import compile as compile  # re's name, for the module-level patterns
from re import escape as escape
from typing import Any, TypeVar

__all__ = [
    "IGNORECASE",
    "Match",
    "Pattern",
    "compile",
    "compiled",
    "escape",
    "findall",
    "finditer",
    "first_words",
    "fullmatch",
    "match",
    "may_match",
    "required",
    "search",
    "spelt",
    "split",
    "sub",
]

_Words = frozenset[str] | None

# re's own pattern parser and code generator (imported by re itself; taken from sys.modules, as
# typeshed's re has no _parser: mypy 2.4 refuses ``from re import _parser``)
_parser = sys.modules["re._parser"]
_compiler = sys.modules["re._compiler"]
_sre = sys.modules["_sre"]

_LITERAL = _parser.LITERAL
_BRANCH = _parser.BRANCH
_SUBPATTERN = _parser.SUBPATTERN
_ATOMIC = getattr(_parser, "ATOMIC_GROUP", None)
_REPEATS = {
    op
    for op in (_parser.MAX_REPEAT, _parser.MIN_REPEAT, getattr(_parser, "POSSESSIVE_REPEAT", None))
    if op is not None
}


def _best(a: _Words, b: _Words) -> _Words:
    """Of two sets of words each of which a match must contain one of, the more selective."""
    if a is None:
        return b
    if b is None:
        return a
    return a if (min(map(len, a)), -len(a)) >= (min(map(len, b)), -len(b)) else b


def _needed(items: object, fold: bool) -> _Words:
    """Words one of which every match of the parsed sequence ``items`` contains, or None."""
    best: _Words = None
    run: list[str] = []

    def close() -> None:
        nonlocal best
        if run:
            best = _best(best, frozenset({"".join(run)}))
            run.clear()

    for op, av in items:  # type: ignore[attr-defined]
        if op is _LITERAL and av < 128:
            run.append(chr(av).lower() if fold else chr(av))
            continue
        close()
        if op is _BRANCH:
            alts = [_needed(alt, fold) for alt in av[1]]
            if all(alt is not None for alt in alts):
                best = _best(best, frozenset().union(*alts))  # type: ignore[arg-type]
        elif op is _SUBPATTERN:
            _group, add, remove, sub = av
            if not add and not remove:
                best = _best(best, _needed(sub, fold))
        elif op is _ATOMIC:
            best = _best(best, _needed(av, fold))
        elif op in _REPEATS:
            low, _high, sub = av
            if low >= 1:
                best = _best(best, _needed(sub, fold))
        # anything else (a class, a back reference, a look-around, an anchor) needs no word
    close()
    if best is not None and "" in best:
        return None
    return best


def _all_needed(items: object, fold: bool) -> list[frozenset[str]]:
    """Session 51 (12p): every set of words one of which every match of the parsed sequence
    ``items`` contains (each found as _needed finds its one best: a run of literals, a branch
    whose every alternative needs a word, a plain group, an atomic group, a repeat at least
    once), all of them: a match holds a word of each."""
    sets: list[frozenset[str]] = []
    run: list[str] = []

    def close() -> None:
        if run:
            sets.append(frozenset({"".join(run)}))
            run.clear()

    for op, av in items:  # type: ignore[attr-defined]
        if op is _LITERAL and av < 128:
            run.append(chr(av).lower() if fold else chr(av))
            continue
        close()
        if op is _BRANCH:
            alts = [_needed(alt, fold) for alt in av[1]]
            if all(alt is not None for alt in alts):
                sets.append(frozenset().union(*alts))  # type: ignore[arg-type]
        elif op is _SUBPATTERN:
            _group, add, remove, sub = av
            if not add and not remove:
                sets += _all_needed(sub, fold)
        elif op is _ATOMIC:
            sets += _all_needed(av, fold)
        elif op in _REPEATS:
            low, _high, sub = av
            if low >= 1:
                sets += _all_needed(sub, fold)
    close()
    return [words for words in sets if "" not in words]


def _also(parsed: object, fold: bool, first: tuple[str, ...]) -> tuple[tuple[str, ...], ...]:
    """The sets of words a match needs besides ``first`` (the gate's own), the most selective
    first, at most four (none that every word of ``first`` holds a word of: asked already;
    none with a word of one letter)."""
    out: list[tuple[str, ...]] = []
    for words in sorted(
        {_fewest(w) for w in _all_needed(parsed, fold)},
        key=lambda w: (-min(map(len, w)), len(w), w),
    ):
        implied = all(any(w in f for w in words) for f in first)  # first's words hold one
        if not implied and min(map(len, words)) > 1 and len(out) < 4:
            out.append(words)  # (a single letter or space is in nearly every text)
    return tuple(out)


def _fewest(words: frozenset[str]) -> tuple[str, ...]:
    """``words`` without those holding another of them ('okay' beside 'ok'): a text holds one
    of what is left where it holds one of ``words``."""
    return tuple(sorted(w for w in words if not any(v != w and v in w for v in words)))


def first_words(pattern: str, flags: int = 0, limit: int = 4096) -> dict[str, set[str]] | None:
    """Session 52 (12p): every text ``pattern`` matches by its first word, lower-cased (a text's
    first word: its letters up to the first that is not a word letter, ``\\w``), where the
    pattern matches at most ``limit`` texts, each spelt out by literals (alternatives, groups,
    repeats of at most two) and beginning with a word letter, and no letter of it folds onto an
    ASCII letter it is not ('ſ', 'K', 'ı', 'İ'); None where not. ``\\b(?:P)\\b`` then matches
    an ASCII text only where a word of the text (a run of word letters between others) is the
    first word of a text P matches, and one of those texts is there: the match begins at a
    word's start and ends at a word's end or at a letter that is not a word letter."""
    try:
        parsed = _parser.parse(pattern, flags)
    except re.error:
        return None
    texts = _spelt(list(parsed), limit)
    if not texts:
        return None
    out: dict[str, set[str]] = {}
    for text in sorted(texts):
        if not text or not (text[0].isalnum() or text[0] == "_"):
            return None
        for c in text:
            if not c.isascii() and (
                any(f.isascii() for f in (c.lower(), c.upper(), c.casefold()))
                or c in "\u0131\u0130\u017f\u212a"
            ):
                return None
        low = text.lower()
        end = 0
        while end < len(low) and (low[end].isalnum() or low[end] == "_"):
            end += 1
        out.setdefault(low[:end], set()).add(text)
    return out


def spelt(pattern: str, flags: int = 0, limit: int = 4096) -> frozenset[str] | None:
    """Session 52 (12p): every text ``pattern`` matches, where it is spelt out by literals,
    alternatives, plain groups and repeats of at most two, and they are at most ``limit``;
    None where not."""
    try:
        parsed = _parser.parse(pattern, flags)
    except re.error:
        return None
    texts = _spelt(list(parsed), limit)
    return None if texts is None else frozenset(texts)


def _spelt(items: list[Any], limit: int) -> set[str] | None:
    """Every text the parsed sequence ``items`` matches, where it is spelt out by literals,
    alternatives, plain groups and repeats of at most two, and they are at most ``limit``."""
    texts = {""}
    for op, av in items:
        if op is _LITERAL:
            more: set[str] | None = {chr(av)}
        elif op is _BRANCH:
            more = set()
            for alt in av[1]:
                got = _spelt(list(alt), limit)
                if got is None:
                    return None
                more |= got
        elif op is _SUBPATTERN and not av[1] and not av[2]:
            more = _spelt(list(av[3]), limit)
        elif op in _REPEATS and av[1] <= 2:
            once = _spelt(list(av[2]), limit)
            if once is None:
                return None
            more = set()
            for n in range(av[0], av[1] + 1):
                more |= {"".join(t) for t in itertools.product(once, repeat=n)}
        else:
            return None
        if more is None or len(texts) * len(more) > limit:
            return None
        texts = {a + b for a in texts for b in more}
    return texts


@functools.lru_cache(maxsize=16384)
def required(pattern: str, flags: int = 0) -> tuple[_Words, bool]:
    """The words one of which every match of ``pattern`` contains (None where none can be
    derived), and whether the pattern is case-blind (the words are then lower-cased)."""
    try:
        parsed = _parser.parse(pattern, flags)
    except re.error:
        return None, True
    fold = bool(parsed.state.flags & re.IGNORECASE)  # its flags or an inline '(?i)'
    return _needed(parsed, fold), fold


# a pattern's gate: the words one of which every match contains, and whether they are
# lower-cased; None: always run
_Gate = tuple[tuple[str, ...], bool] | None
# gates by flags, then by pattern (no key tuple built per check: ~600 checks an instruction)
_GATES: dict[int, dict[str, _Gate]] = {}
# a compiled pattern's text and flags by the pattern's id (the pattern kept beside them: an id is
# the pattern's only while it lives; re's hash of a pattern hashes its whole code at each call)
_SOURCES: dict[int, tuple[re.Pattern[str], str, int]] = {}
# Session 51 (12p): the other sets of words a pattern's every match needs (a word of each), asked
# only where the text holds a word of its gate; by flags, then by pattern, only for patterns
# that have any (a pure function of the pattern: kept while the gate is dropped and made again)
_ALSO: dict[int, dict[str, tuple[tuple[str, ...], ...]]] = {}
# each pattern gated, compiled from the parse its words were derived from, until it is first run
# (then kept by the caller: ``compiled`` hands it over)
_BUILT: dict[tuple[str, int], re.Pattern[str]] = {}
# flags whose patterns re.compile alone builds (it prints a pattern, or warns of it)
_RE_ONLY = int(re.DEBUG) | int(getattr(re, "TEMPLATE", 0))


def _gate(pattern: str, flags: int, *, build: bool = True) -> _Gate:
    """The words ``pattern`` needs and whether they are lower-cased, or None (always run),
    derived from re's parse of it, from which the pattern is compiled too (``compiled``; not
    where ``build`` is false: the caller has it compiled)."""
    key = (pattern, flags)
    try:
        parsed = _parser.parse(pattern, int(flags))  # as re.compile parses it
    except re.error:
        gate: _Gate = None  # run: re raises its error
    else:
        fold = bool(parsed.state.flags & re.IGNORECASE)  # its flags or an inline '(?i)'
        words = _needed(parsed, fold)
        gate = None if words is None else (_fewest(words), fold)
        also = () if gate is None else _also(parsed, fold, gate[0])
        if also:
            kept = _ALSO.setdefault(flags, {})
            if len(kept) > 16384:
                kept.clear()
            kept[pattern] = also
        if build and not flags & _RE_ONLY:
            if len(_BUILT) > 16384:
                _BUILT.clear()
            # an error re raises where it compiles the pattern: raised there, as it was; and
            # where re's private code generator is not what this Python's re has (_from_parse
            # follows the re._compiler.compile of CPython 3.11, the version used here), re.compile
            # builds the pattern as before
            with contextlib.suppress(re.error, AttributeError, TypeError, ValueError):
                _BUILT[key] = _from_parse(pattern, int(flags), parsed)
    gates = _GATES.setdefault(flags, {})
    if len(gates) > 16384:
        gates.clear()
    gates[pattern] = gate
    return gate


def forget(pattern: str, flags: int = 0) -> None:
    """Drop ``pattern``'s gate (it is derived again when next met)."""
    _GATES.get(flags, {}).pop(pattern, None)


def prepare(pattern: str, flags: int = 0, *, build: bool = True) -> bool:
    """Gate ``pattern`` now rather than when first met (``build``: and compile it, kept until it
    is first run); whether it was not gated yet."""
    if pattern in _GATES.get(flags, {}):
        return False
    _gate(pattern, flags, build=build)
    return True


def _from_parse(pattern: str, flags: int, parsed: Any) -> re.Pattern[str]:
    """re._compiler.compile, given re's parse of ``pattern`` instead of its text."""
    code = _compiler._code(parsed, flags)
    groupindex = parsed.state.groupdict
    indexgroup: list[str | None] = [None] * parsed.state.groups
    for name, index in groupindex.items():
        indexgroup[index] = name
    out: re.Pattern[str] = _sre.compile(
        pattern,
        int(flags | parsed.state.flags),
        code,
        parsed.state.groups - 1,
        groupindex,
        tuple(indexgroup),
    )
    return out


def compiled(pattern: str, flags: int = 0) -> re.Pattern[str]:
    """What ``re.compile(pattern, flags)`` returns (an equal pattern): the one compiled when
    the pattern was gated, where it was (not kept here: the callers keep what they compile)."""
    built = _BUILT.pop((pattern, flags), None)
    return re.compile(pattern, flags) if built is None else built


# the last text checked and its lower case (None where it is not ASCII), replaced as one tuple
# (threads may ground at once): the normaliser checks one text against some 600 patterns in turn
_LAST: tuple[str, str | None] = ("", "")


def may_match(pattern: str, flags: int, text: str) -> bool:
    """False only where ``pattern`` cannot match anywhere in ``text``."""
    global _LAST
    try:
        gate = _GATES[flags][pattern]
    except KeyError:
        gate = _gate(pattern, flags)
    if gate is None:
        return True
    last = _LAST
    if last[0] is not text:
        last = _LAST = (text, text.lower() if text.isascii() else None)
    low = last[1]
    if low is None:
        return True
    words, fold = gate
    if fold:
        text = low
    for word in words:  # a loop: any() over a generator costs more
        if word in text:
            break
    else:
        return False
    # session 51: the other words it needs (a word of each), where it has any
    also = _ALSO.get(flags)
    if also is not None:
        more = also.get(pattern)
        if more is not None:
            for need in more:
                for word in need:
                    if word in text:
                        break
                else:
                    return False
    return True


@functools.lru_cache(maxsize=16384)
def _compiled(pattern: str, flags: int) -> re.Pattern[str]:
    return compiled(pattern, flags)


_T = TypeVar("_T")


def _gated(
    pattern: str | re.Pattern[str],
    flags: int,
    string: str,
    on_no_match: _T,
    method: Callable[..., _T],
    *args: Any,
) -> _T:
    """``method`` of the compiled ``pattern`` called with ``args``, or ``on_no_match`` (what re
    returns for no match) where the gate says ``pattern`` cannot match ``string``."""
    if isinstance(pattern, re.Pattern):
        kept = _SOURCES.get(id(pattern))
        if kept is None or kept[0] is not pattern:
            if len(_SOURCES) > 16384:
                _SOURCES.clear()
            kept = _SOURCES[id(pattern)] = (pattern, pattern.pattern, pattern.flags)
            _gate(kept[1], kept[2], build=False)  # compiled already: never again
        if not may_match(kept[1], kept[2], string):
            return on_no_match
        return method(pattern, *args)
    if not may_match(pattern, flags, string):
        return on_no_match
    return method(_compiled(pattern, flags), *args)


def sub(
    pattern: str | re.Pattern[str],
    repl: str | Callable[[re.Match[str]], str],
    string: str,
    count: int = 0,
    flags: int = 0,
) -> str:
    """re.sub, gated."""
    return _gated(pattern, flags, string, string, re.Pattern.sub, repl, string, count)


def search(pattern: str | re.Pattern[str], string: str, flags: int = 0) -> re.Match[str] | None:
    """re.search, gated."""
    return _gated(pattern, flags, string, None, re.Pattern.search, string)


def match(pattern: str | re.Pattern[str], string: str, flags: int = 0) -> re.Match[str] | None:
    """re.match, gated."""
    return _gated(pattern, flags, string, None, re.Pattern.match, string)


def fullmatch(pattern: str | re.Pattern[str], string: str, flags: int = 0) -> re.Match[str] | None:
    """re.fullmatch, gated."""
    return _gated(pattern, flags, string, None, re.Pattern.fullmatch, string)


def findall(pattern: str | re.Pattern[str], string: str, flags: int = 0) -> list[Any]:
    """re.findall, gated."""
    return _gated(pattern, flags, string, [], re.Pattern.findall, string)


def finditer(
    pattern: str | re.Pattern[str], string: str, flags: int = 0
) -> Iterator[re.Match[str]]:
    """re.finditer, gated."""
    return _gated(pattern, flags, string, iter(()), re.Pattern.finditer, string)


def split(
    pattern: str | re.Pattern[str], string: str, maxsplit: int = 0, flags: int = 0
) -> list[str | Any]:
    """re.split, gated."""
    return _gated(pattern, flags, string, [string], re.Pattern.split, string, maxsplit)
