"""The normaliser's steps indexed by their words: a step runs only where the text holds one."""

from __future__ import annotations

import ast
import contextlib
import functools
import hashlib
import inspect
import re
import sys
import textwrap
import types
from collections.abc import Callable, Iterable, Mapping, Sequence
from pathlib import Path
from typing import Any

from hltl.grounding import gate

# an atom of a guard: ("in", word, 1 if asked of the lower-cased text else 0), ("re", pattern,
# flags), or ("re-low", pattern, flags) for a search of the lower-cased text (session 49): the
# step does something only where one of its atoms is present in the text
Atom = tuple[str, str, int]
# a module name the guard was read with, and what it held: ("value", repr) for a string or an
# int, ("pattern", pattern, flags) for a compiled pattern, ("function", name, fingerprint),
# ("module", name)
Dep = tuple[str, tuple[Any, ...]]
# a step's guard as _rewritten asks it: the words asked of the text as it is, those asked of it
# lower-cased, and whether any came from a pattern (asked only of an ASCII text, as the gate asks)
Guard = tuple[tuple[str, ...], tuple[str, ...], bool]
# a step's entry in the list: its fingerprint, its guard, the module names it was read with
Entry = tuple[str, Guard, tuple[Dep, ...]]


def _feed(digest: Any, code: types.CodeType) -> None:
    """Feed ``code``'s bytecode, names and constants (nested code too) to ``digest``, in a form
    that is the same in every process (a frozenset's members sorted)."""
    digest.update(code.co_code)
    digest.update(
        "\x00".join((*code.co_names, "", *code.co_varnames, str(code.co_argcount))).encode()
    )
    for const in code.co_consts:
        if type(const) is str:
            digest.update(b"\x00s")
            digest.update(const.encode("utf-8", "surrogatepass"))
        elif isinstance(const, types.CodeType):
            digest.update(b"\x00c")
            _feed(digest, const)
        elif isinstance(const, frozenset):
            digest.update(repr(("frozenset", sorted(map(repr, const)))).encode())
        else:
            digest.update(b"\x00r")
            digest.update(repr(const).encode("utf-8", "surrogatepass"))


# fingerprints by the code's id (the code and defaults kept beside: an id is theirs only while
# they live): a tuple of steps made again (a test taking one out) costs no digest again
_PRINTS: dict[int, tuple[types.CodeType, object, str]] = {}


def fingerprint(fn: Callable[..., Any]) -> str:
    """A digest of ``fn``'s bytecode, names and constants (its docstring too) and its defaults,
    the same in every process of one Python version ('' for what has no code)."""
    code = getattr(fn, "__code__", None)
    if not isinstance(code, types.CodeType):
        return ""
    defaults = getattr(fn, "__defaults__", None)
    kept = _PRINTS.get(id(code))
    if kept is not None and kept[0] is code and kept[1] is defaults:
        return kept[2]
    digest = hashlib.sha1(repr(sys.version_info[:2]).encode())
    _feed(digest, code)
    digest.update(repr(defaults).encode("utf-8", "surrogatepass"))
    out = digest.hexdigest()[:16]
    _PRINTS[id(code)] = (code, defaults, out)
    return out


def key(fn: Callable[..., Any]) -> str:
    """A step's name in the list: its module and qualified name."""
    return f"{getattr(fn, '__module__', '?')}:{getattr(fn, '__qualname__', '?')}"


# -- reading a guard from a step's source (only when the list is remade) ------------------------

# the helpers a guard may name, by module and name: what each asks of the text
_NORMALISE1 = "hltl.grounding._normalise1"
_SUB = (_NORMALISE1, "_sub")
_RX = (_NORMALISE1, "_rx")
_SAID_ANY = (_NORMALISE1, "_said_any")
_SAYS54R = ("hltl.grounding._rewrites54r", "_says54r")  # any of its words in the text, lower
_DROP = (_NORMALISE1, "_drop")  # _sub of the pattern with a replacement of each match
_SEARCHES = ("search", "match", "fullmatch")
_ITERATIONS = ("finditer", "findall")  # an empty iteration where the pattern finds nothing
_BUILTIN_WRAPS = ("reversed", "list", "tuple")  # the same items, or none where there are none


# how deep helpers are read through (a step calling a helper calling a helper, …)
_HELPER_DEPTH = 3


def _plain(value: Any) -> Any:
    """A function cached by functools (``_rx``) as the function it wraps (session 49: the
    ``_rx(P).search(text)`` form was never read, ``_rx`` being cached)."""
    if isinstance(value, functools._lru_cache_wrapper):
        return value.__wrapped__
    return value


def _whole(node: ast.expr | None) -> bool:
    """Whether ``node`` is absent or a whole number written out (a slice's bound)."""
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.USub):
        node = node.operand
    return node is None or (isinstance(node, ast.Constant) and type(node.value) is int)


class _Unread(Exception):
    """The step's first statements are not of the kinds a guard is read from."""


class _Reader:
    """Reads one step's guard from its source."""

    def __init__(self, fn: types.FunctionType, depth: int = 0) -> None:
        self.fn = fn
        self.glob = fn.__globals__
        self.deps: dict[str, tuple[Any, ...]] = {}
        self.text = ""
        # session 49: names equal to the text wherever none of the atoms read so far is present
        # ('out = text', 'out = _sub(P, R, out)', 'out = helper(out, lexicon)'), the function's
        # own names (never read as the module's), the loop's pattern name, how deep a helper is
        self.same: set[str] = set()
        code = fn.__code__
        self.locals = frozenset((*code.co_varnames, *code.co_cellvars))
        self.loop_name = ""
        self.depth = depth
        self.at: ast.stmt | None = None
        self.lowers: set[str] = set()  # names bound to text.lower()
        self.matches: dict[str, frozenset[Atom]] = {}  # names bound to a search of the text

    def _global(self, name: str) -> object:
        """A name of the step's module (kept, with what it holds, to be checked at run time)."""
        if name not in self.glob or (name in self.locals and name != self.loop_name):
            raise _Unread(name)  # a name of the function's own is not the module's
        value = _plain(self.glob[name])
        if isinstance(value, str | int) and not isinstance(value, bool):
            self.deps[name] = ("value", repr(value))
        elif isinstance(value, re.Pattern):
            self.deps[name] = ("pattern", value.pattern, int(value.flags))
        elif isinstance(value, types.FunctionType):
            self.deps[name] = ("function", key(value), fingerprint(value))
        elif isinstance(value, types.ModuleType):
            self.deps[name] = ("module", value.__name__)
        else:
            raise _Unread(name)
        return value

    def _helper(self, node: ast.expr, want: tuple[str, str]) -> bool:
        """Whether ``node`` names the helper ``want`` (module, name)."""
        if not isinstance(node, ast.Name) or node.id not in self.glob:
            return False
        value = _plain(self.glob[node.id])
        if not isinstance(value, types.FunctionType) or (value.__module__, value.__name__) != want:
            return False
        self._global(node.id)
        return True

    def _re_module(self, node: ast.expr) -> bool:
        """Whether ``node`` names re or the gate (the module a step calls re's functions of)."""
        if not isinstance(node, ast.Name) or node.id not in self.glob:
            return False
        value = self.glob[node.id]
        if value is not re and value is not gate:
            return False
        self._global(node.id)
        return True

    def _str(self, node: ast.expr) -> str:
        """A string the expression always is (constants and module strings, joined)."""
        if isinstance(node, ast.Constant) and isinstance(node.value, str):
            return node.value
        if isinstance(node, ast.Name):
            value = self._global(node.id)
            if isinstance(value, str):
                return value
        if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Add):
            return self._str(node.left) + self._str(node.right)
        if isinstance(node, ast.JoinedStr):
            out = []
            for part in node.values:
                if isinstance(part, ast.FormattedValue):
                    if part.conversion != -1 or part.format_spec is not None:
                        raise _Unread("format")
                    out.append(self._str(part.value))
                else:
                    out.append(self._str(part))
            return "".join(out)
        raise _Unread("not a string")

    def _pattern_of(self, node: ast.expr, flags: ast.expr | None) -> tuple[str, int]:
        """The pattern and flags of re's function (or the gate's) called with ``node`` and
        ``flags``: a string, or a module's compiled pattern without flags (session 54, 12p:
        ``re.search(_P, text)`` with ``re`` the gate, as session 53 made raw calls gated)."""
        if isinstance(node, ast.Name) and flags is None and node.id not in self.locals:
            value = self.glob.get(node.id)
            if isinstance(value, re.Pattern):
                self._global(node.id)  # kept with what it holds, checked at run time
                return value.pattern, int(value.flags)
        return self._str(node), self._flags(flags)

    def _flags(self, node: ast.expr | None) -> int:
        if node is None:
            return 0
        if isinstance(node, ast.Constant) and isinstance(node.value, int):
            return node.value
        if isinstance(node, ast.Name):
            value = self._global(node.id)
            if isinstance(value, int):
                return int(value)
        if (
            isinstance(node, ast.Attribute)
            and self._re_module(node.value)
            and node.attr in ("I", "IGNORECASE")
        ):
            return int(re.IGNORECASE)
        raise _Unread("flags")

    def _is_text(self, node: ast.expr, *, stripped: bool = False) -> bool:
        """Whether ``node`` is the step's text (``stripped``: or ``text.strip()``)."""
        if isinstance(node, ast.Name) and node.id in self.same:
            return True
        return (
            stripped
            and isinstance(node, ast.Call)
            and isinstance(node.func, ast.Attribute)
            and node.func.attr == "strip"
            and not node.args
            and not node.keywords
            and self._is_text(node.func.value)
        )

    def _hay(self, node: ast.expr) -> int:
        """0 where ``node`` is the text, 1 where it is the text lower-cased."""
        if self._is_text(node):
            return 0
        if isinstance(node, ast.Name) and node.id in self.lowers:
            return 1
        if (
            isinstance(node, ast.Call)
            and isinstance(node.func, ast.Attribute)
            and node.func.attr == "lower"
            and not node.args
            and not node.keywords
            and self._is_text(node.func.value)
        ):
            return 1
        raise _Unread("hay")

    def _part(self, node: ast.expr) -> int:
        """Session 51: as ``_hay``, or a stretch of the text or of it lower-cased: sliced by
        whole numbers (``text[:40]``), stripped of given characters (``text.rstrip(" .!")``),
        lower-cased (``text[:8].lower()``; 1 from there on). A word in such a stretch is in the
        text (lower-cased where the stretch is), and none of these can raise."""
        with contextlib.suppress(_Unread):
            return self._hay(node)
        if (
            isinstance(node, ast.Subscript)
            and isinstance(node.slice, ast.Slice)
            and node.slice.step is None
            and all(_whole(b) for b in (node.slice.lower, node.slice.upper))
        ):
            return self._part(node.value)
        if (
            isinstance(node, ast.Call)
            and isinstance(node.func, ast.Attribute)
            and not node.keywords
        ):
            if (
                node.func.attr in ("strip", "lstrip", "rstrip")
                and len(node.args) <= 1
                and all(isinstance(a, ast.Constant) and type(a.value) is str for a in node.args)
            ):
                return self._part(node.func.value)
            if node.func.attr == "lower" and not node.args:
                self._part(node.func.value)
                return 1
        raise _Unread("hay")

    def _said_words(self, node: ast.expr) -> tuple[str, ...]:
        """Session 51: a string, or a tuple of strings written out (``startswith``'s argument)."""
        if isinstance(node, ast.Tuple):
            return tuple(self._str(e) for e in node.elts)
        return (self._str(node),)

    def _words(self, node: ast.expr) -> tuple[str, ...]:
        """The strings of a tuple, list or set written out, or of a module's tuple of strings
        (session 55, 12p: 'any(w in low for w in _GRAND_WORDS54)'; kept with the guard as a
        tuple of patterns is)."""
        if isinstance(node, ast.Name) and node.id not in self.locals:
            value = self.glob.get(node.id)
            if isinstance(value, tuple) and value and all(type(v) is str for v in value):
                return self._patterns(node.id)
            raise _Unread("words")
        if isinstance(node, ast.Tuple | ast.List | ast.Set):
            out: list[str] = []
            for e in node.elts:  # session 49: '*("a", "b"), *("c",)' too
                if isinstance(e, ast.Starred):
                    out += self._words(e.value)
                else:
                    out.append(self._str(e))
            return tuple(out)
        raise _Unread("words")

    def _search(self, node: ast.expr, kinds: tuple[str, ...] = _SEARCHES) -> frozenset[Atom]:
        """The atom of a search of the text (``re.search(P, text, F)``, ``re.match``,
        ``_rx(P).search(text)``, a module's compiled pattern's ``.search(text)``; ``kinds``: the
        methods taken), whose every match holds a word of its pattern."""
        if not isinstance(node, ast.Call) or not isinstance(node.func, ast.Attribute):
            raise _Unread("not a search")
        func, args, kw = node.func, node.args, {k.arg: k.value for k in node.keywords}
        if func.attr not in kinds:
            raise _Unread("not a search")
        if self._re_module(func.value):  # re.search(P, text[, flags])
            if len(args) < 2 or set(kw) - {"flags"}:
                raise _Unread("search args")
            kind = self._searched(args[1])
            flags = args[2] if len(args) > 2 else kw.get("flags")
            return frozenset({(kind, *self._pattern_of(args[0], flags))})
        if len(args) != 1 or kw:
            raise _Unread("search args")
        kind = self._searched(args[0])
        target = func.value
        if (
            isinstance(target, ast.Call)
            and len(target.args) == 1
            and not target.keywords
            and self._helper(target.func, _RX)
        ):  # _rx(P).search(text): case-blind
            return frozenset({(kind, self._str(target.args[0]), int(re.IGNORECASE))})
        if isinstance(target, ast.Name):  # a module's compiled pattern
            value = self._global(target.id)
            if isinstance(value, re.Pattern):
                return frozenset({(kind, value.pattern, int(value.flags))})
        raise _Unread("search target")

    def _searches(self, node: ast.expr) -> frozenset[Atom]:
        """A search, or searches joined by 'or' (session 49: 'A.match(text) or B.match(text)'
        is None where neither finds anything)."""
        if isinstance(node, ast.BoolOp) and isinstance(node.op, ast.Or):
            return frozenset().union(*(self._search(v) for v in node.values))
        return self._search(node)

    def _searched(self, node: ast.expr) -> str:
        """The atom kind of a search of ``node``: "re" of the text (or it stripped), "re-low" of
        it lower-cased (session 49: its words are asked of the lower-cased text)."""
        if self._is_text(node, stripped=True):
            return "re"
        if isinstance(node, ast.Name) and node.id in self.lowers:
            return "re-low"
        raise _Unread("search args")

    def present(self, node: ast.expr) -> frozenset[Atom]:
        """Atoms one of which is present in the text wherever ``node`` is true."""
        if isinstance(node, ast.Name) and node.id in self.matches:
            return self.matches[node.id]
        if isinstance(node, ast.NamedExpr):  # (m := search) in a test: what the search needs
            return self.present(node.value)
        if (
            isinstance(node, ast.Call)
            and isinstance(node.func, ast.Attribute)
            and node.func.attr in ("startswith", "endswith")
            and len(node.args) == 1
            and not node.keywords
            and isinstance(node.args[0], ast.Constant | ast.Tuple)
        ):  # session 49: text.startswith(W) only where W is in the text (session 51: a
            # tuple of words, any of them; a stretch of the text, 'text[:8].lower()')
            fold = self._part(node.func.value)
            return frozenset(("in", w, fold) for w in self._said_words(node.args[0]))
        helper = self._compared_helper(node, ast.NotEq)
        if helper is not None:
            return helper  # 'helper(text, …) != text': a helper that leaves it as it is
        if self._both_same(node, ast.NotEq):
            return frozenset()  # 'out != text': never true while both are the text
        if (
            isinstance(node, ast.Compare)
            and len(node.ops) == 1
            and isinstance(node.ops[0], ast.IsNot)
            and isinstance(node.comparators[0], ast.Constant)
            and node.comparators[0].value is None
        ):  # a search's match is not None only where it found something
            left = node.left
            if isinstance(left, ast.Name) and left.id in self.matches:
                return self.matches[left.id]
            if isinstance(left, ast.NamedExpr):
                return self.present(left.value)
            return self._search(left)
        if isinstance(node, ast.BoolOp) and isinstance(node.op, ast.Or):
            return frozenset().union(*(self.present(v) for v in node.values))
        if isinstance(node, ast.BoolOp):  # and: true only where its first side is (any side)
            return self._best(node.values, self.present)
        if (
            isinstance(node, ast.Compare)
            and len(node.ops) == 1
            and isinstance(node.ops[0], ast.In)
            and isinstance(node.left, ast.Constant)
        ):
            return frozenset({("in", self._str(node.left), self._part(node.comparators[0]))})
        if (
            isinstance(node, ast.Compare)
            and len(node.ops) == 1
            and isinstance(node.ops[0], ast.Eq)
            and isinstance(node.comparators[0], ast.Constant)
            and type(node.comparators[0].value) is str
        ):  # session 51: 'text[:5].lower() == "never"' only where the word is in the text
            return frozenset({("in", node.comparators[0].value, self._part(node.left))})
        if isinstance(node, ast.Call) and self._helper(node.func, _SAID_ANY):
            if len(node.args) != 2 or node.keywords or not self._is_text(node.args[0]):
                raise _Unread("_said_any")
            return frozenset(("in", w, 1) for w in self._words(node.args[1]))
        if isinstance(node, ast.Call) and self._helper(node.func, _SAYS54R):
            # session 55 (12p): '_says54r(text, "w1", "w2")', any word in the text lower-cased
            words = node.args[1:]
            if (
                not words
                or node.keywords
                or not self._is_text(node.args[0])
                or any(isinstance(w, ast.Starred) for w in words)
            ):
                raise _Unread("_says54r")
            return frozenset(("in", self._str(w), 1) for w in words)
        if (
            isinstance(node, ast.Call)
            and isinstance(node.func, ast.Name)
            and node.func.id == "any"
            and "any" not in self.glob
            and len(node.args) == 1
            and not node.keywords
            and isinstance(node.args[0], ast.GeneratorExp)
        ):
            gen = node.args[0]
            comp = gen.generators[0] if len(gen.generators) == 1 else None
            elt = gen.elt
            if (
                comp is None
                or comp.ifs
                or comp.is_async
                or not isinstance(comp.target, ast.Name)
                or not isinstance(elt, ast.Compare)
                or len(elt.ops) != 1
                or not isinstance(elt.ops[0], ast.In)
            ):
                raise _Unread("any")
            fold = self._hay(elt.comparators[0])
            listed = self._words(comp.iter)
            if isinstance(elt.left, ast.Name) and elt.left.id == comp.target.id:
                return frozenset(("in", w, fold) for w in listed)
            # session 56 (12p): 'any(f"{w} of the " in text for w in ("last", …))': each
            # word in the f-string (no conversion or format), the rest written out
            return frozenset(("in", said, fold) for said in self._filled(elt.left, comp, listed))
        return self._search(node)

    def absent(self, node: ast.expr) -> frozenset[Atom]:
        """Atoms such that ``node`` is true wherever none of them is present in the text."""
        if isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.Not):
            return self.present(node.operand)
        counted = self._few(node)
        if counted is not None:
            return counted
        if self._both_same(node, ast.Eq):
            return frozenset()  # 'out == text': true while both are the text
        helper = self._compared_helper(node, ast.Eq)
        if helper is not None:
            return helper
        if isinstance(node, ast.BoolOp) and isinstance(node.op, ast.And):
            return frozenset().union(*(self.absent(v) for v in node.values))
        if isinstance(node, ast.BoolOp):  # or: true wherever any one side is
            return self._best(node.values, self.absent)
        if isinstance(node, ast.Compare) and len(node.ops) == 1:
            op, right = node.ops[0], node.comparators[0]
            if isinstance(op, ast.NotIn) and isinstance(node.left, ast.Constant):
                return frozenset({("in", self._str(node.left), self._part(right))})
            if (
                isinstance(op, ast.NotEq)
                and isinstance(right, ast.Constant)
                and type(right.value) is str
            ):
                # session 51: 'text[:5].lower() != "never"' wherever the word is not in the text
                return frozenset({("in", right.value, self._part(node.left))})
            if isinstance(op, ast.Is) and isinstance(right, ast.Constant) and right.value is None:
                # None only where a search finds nothing ('in', any() and _said_any are bools)
                left = node.left
                if isinstance(left, ast.Name) and left.id in self.matches:
                    return self.matches[left.id]
                return self._search(left)
        raise _Unread("test")

    def _filled(
        self, node: ast.expr, comp: ast.comprehension, words: tuple[str, ...]
    ) -> tuple[str, ...]:
        """Session 56 (12p): the strings of the f-string ``node`` with each of ``words`` for the
        comprehension's name (its other parts strings the reader reads)."""
        if not isinstance(node, ast.JoinedStr) or not isinstance(comp.target, ast.Name):
            raise _Unread("any")
        name = comp.target.id
        parts: list[str | None] = []  # None: the word
        for part in node.values:
            if isinstance(part, ast.FormattedValue):
                if part.conversion != -1 or part.format_spec is not None:
                    raise _Unread("format")
                if isinstance(part.value, ast.Name) and part.value.id == name:
                    parts.append(None)
                    continue
                parts.append(self._str(part.value))
            else:
                parts.append(self._str(part))
        if None not in parts:
            raise _Unread("any")
        return tuple("".join(w if p is None else p for p in parts) for w in words)

    def _counts(self, node: ast.expr) -> frozenset[Atom]:
        """Session 56 (12p): the atoms of a count that is 0 wherever none of them is present:
        ``text.count(W)`` (of the text, lower-cased or a stretch of it), such counts added,
        or ``sum(low.count(w) for w in WORDS)``."""
        if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Add):
            return self._counts(node.left) | self._counts(node.right)
        if (
            isinstance(node, ast.Call)
            and isinstance(node.func, ast.Attribute)
            and node.func.attr == "count"
            and len(node.args) == 1
            and not node.keywords
        ):
            fold = self._part(node.func.value)
            return frozenset({("in", self._str(node.args[0]), fold)})
        if (
            isinstance(node, ast.Call)
            and isinstance(node.func, ast.Name)
            and node.func.id == "sum"
            and "sum" not in self.glob
            and "sum" not in self.locals
            and len(node.args) == 1
            and not node.keywords
            and isinstance(node.args[0], ast.GeneratorExp)
            and len(node.args[0].generators) == 1
        ):
            gen = node.args[0]
            comp = gen.generators[0]
            elt = gen.elt
            if (
                comp.ifs
                or comp.is_async
                or not isinstance(comp.target, ast.Name)
                or not isinstance(elt, ast.Call)
                or not isinstance(elt.func, ast.Attribute)
                or elt.func.attr != "count"
                or len(elt.args) != 1
                or elt.keywords
                or not isinstance(elt.args[0], ast.Name)
                or elt.args[0].id != comp.target.id
            ):
                raise _Unread("sum")
            fold = self._part(elt.func.value)
            return frozenset(("in", w, fold) for w in self._words(comp.iter))
        raise _Unread("count")

    def _few(self, node: ast.expr) -> frozenset[Atom] | None:
        """Session 56 (12p): the atoms of a test of a count (``_counts``) true where the count is
        0 — ``< N`` or ``!= N`` (N ≥ 1), ``<= N`` (N ≥ 0), ``== 0`` — so true wherever none of
        them is present; None where ``node`` is no such test."""
        if (
            not isinstance(node, ast.Compare)
            or len(node.ops) != 1
            or not isinstance(node.comparators[0], ast.Constant)
            or type(node.comparators[0].value) is not int
        ):
            return None
        op, n = node.ops[0], node.comparators[0].value
        if not (
            (isinstance(op, ast.Lt | ast.NotEq) and n >= 1)
            or (isinstance(op, ast.LtE) and n >= 0)
            or (isinstance(op, ast.Eq) and n == 0)
        ):
            return None
        try:
            return self._counts(node.left)
        except _Unread:
            return None

    def _both_same(self, node: ast.expr, op: type[ast.cmpop]) -> bool:
        """Whether ``node`` compares two names that are the text with ``op`` (session 49)."""
        return (
            isinstance(node, ast.Compare)
            and len(node.ops) == 1
            and isinstance(node.ops[0], op)
            and self._is_text(node.left)
            and self._is_text(node.comparators[0])
        )

    def _compared_helper(self, node: ast.expr, op: type[ast.cmpop]) -> frozenset[Atom] | None:
        """The atoms of ``helper(text, …) <op> text`` (session 49), None where it is not so."""
        if (
            not isinstance(node, ast.Compare)
            or len(node.ops) != 1
            or not isinstance(node.ops[0], op)
            or not self._is_text(node.comparators[0])
        ):
            return None
        try:
            return self._call(node.left)
        except _Unread:
            return None

    @staticmethod
    def _best(
        nodes: list[ast.expr], read: Callable[[ast.expr], frozenset[Atom]]
    ) -> frozenset[Atom]:
        """Of the sides ``read`` reads, the one with the fewest atoms."""
        found = []
        for node in nodes:
            try:
                found.append(read(node))
            except _Unread:
                continue
        if not found:
            raise _Unread("no side")
        return min(found, key=len)

    def _sub(self, node: ast.expr) -> Atom:
        """The atom of ``_sub(P, R, text)`` or ``re.sub(P, R, text[, flags=F])`` (the text
        unchanged where it lacks the pattern's words)."""
        if not isinstance(node, ast.Call):
            raise _Unread("not a sub")
        args, kw = node.args, {k.arg: k.value for k in node.keywords}
        if self._helper(node.func, _SUB):
            if len(args) != 3 or kw or not self._is_text(args[2]):
                raise _Unread("_sub args")
            return ("re", self._str(args[0]), int(re.IGNORECASE))
        if self._helper(node.func, _DROP):  # _drop(P, text, lexicon[, R]): _sub(P, …, text)
            if not 3 <= len(args) <= 4 or kw or not self._is_text(args[1]):
                raise _Unread("_drop args")
            if not all(isinstance(a, ast.Name | ast.Constant) for a in args[2:]):
                raise _Unread("_drop args")
            return ("re", self._str(args[0]), int(re.IGNORECASE))
        func = node.func
        if (
            isinstance(func, ast.Attribute)
            and func.attr == "sub"
            and self._re_module(func.value)
            and len(args) == 3
            and self._is_text(args[2])
            and not set(kw) - {"flags", "count"}
        ):
            return ("re", *self._pattern_of(args[0], kw.get("flags")))
        if (
            isinstance(func, ast.Attribute)
            and func.attr == "sub"
            and isinstance(func.value, ast.Name)
            and func.value.id not in self.locals
            and len(args) == 2
            and self._is_text(args[1])
            and not set(kw) - {"count"}
            and self._pure(args[0])
        ):  # session 49: a module's compiled pattern's .sub(R, text)
            value = self._global(func.value.id)
            if isinstance(value, re.Pattern):
                return ("re", value.pattern, int(value.flags))
        raise _Unread("not a sub")

    def _iteration(self, node: ast.expr) -> frozenset[Atom]:
        """The atoms of ``finditer``/``findall`` of the text, in ``reversed(…)``, ``list(…)``,
        ``tuple(…)`` or ``…[::-1]`` or not: items only where the pattern finds something."""
        while True:
            if (
                isinstance(node, ast.Call)
                and isinstance(node.func, ast.Name)
                and node.func.id in _BUILTIN_WRAPS
                and node.func.id not in self.glob
                and len(node.args) == 1
                and not node.keywords
            ):
                node = node.args[0]
                continue
            if (
                isinstance(node, ast.Subscript)
                and isinstance(node.slice, ast.Slice)
                and node.slice.lower is None
                and node.slice.upper is None
                and isinstance(node.slice.step, ast.UnaryOp)
                and isinstance(node.slice.step.op, ast.USub)
                and isinstance(node.slice.step.operand, ast.Constant)
                and node.slice.step.operand.value == 1
            ):
                node = node.value
                continue
            return self._search(node, _ITERATIONS)

    def _patterns(self, name: str) -> tuple[str, ...]:
        """The patterns of a module's tuple of patterns or of (pattern, replacement) pairs (kept
        with the guard: the patterns only, a replacement may be a function)."""
        value = self.glob.get(name)
        if not isinstance(value, tuple) or not value:
            raise _Unread(name)
        heads = [v[0] if isinstance(v, tuple) and len(v) == 2 else v for v in value]
        if not all(type(h) is str for h in heads):
            raise _Unread(name)
        shape = "pairs" if isinstance(value[0], tuple) else "strings"
        if any(isinstance(v, tuple) != (shape == "pairs") for v in value):
            raise _Unread(name)
        out = tuple(str(h) for h in heads)
        self.deps[name] = ("patterns", shape, out)
        return out

    def _loop(self, stmt: ast.For) -> frozenset[Atom]:
        """The atoms of a loop: over a search's matches, or ``for P, R in <module pairs>: text =
        _sub(P, R, text)`` (``_drop``; a tuple of patterns: ``for P in …``)."""
        try:
            return self._iteration(stmt.iter)
        except _Unread:
            pass
        with contextlib.suppress(_Unread):
            return self._searched_loop(stmt)
        if not isinstance(stmt.iter, ast.Name) or len(stmt.body) != 1:
            raise _Unread("loop")
        target, body = stmt.target, stmt.body[0]
        names = [target] if isinstance(target, ast.Name) else getattr(target, "elts", [])
        if not names or not all(isinstance(n, ast.Name) for n in names):
            raise _Unread("loop target")
        pattern = names[0].id
        if len(names) > 2 or pattern in (*self.same, *self.lowers, *self.matches):
            raise _Unread("loop target")
        if (
            not isinstance(body, ast.Assign)
            or len(body.targets) != 1
            or not self._is_text(body.targets[0])
            or not isinstance(body.value, ast.Call)
        ):
            raise _Unread("loop body")
        patterns = self._patterns(stmt.iter.id)
        shape = self.deps[stmt.iter.id][1]
        if (shape == "pairs") != (len(names) == 2) or not isinstance(target, ast.Tuple | ast.Name):
            raise _Unread("loop shape")
        first = body.value.args[0] if body.value.args else None
        if not isinstance(first, ast.Name) or first.id != pattern:
            raise _Unread("loop body")
        # the body read as a substitution of one pattern (its first argument the loop's name,
        # kept out of the module names), then said of each pattern of the tuple
        marker = "\x00loop pattern\x00"
        saved = self.glob
        self.glob = {**saved, pattern: marker}
        self.loop_name = pattern
        try:
            kind, said, flags = self._sub(body.value)
        finally:
            self.glob = saved
            self.loop_name = ""
        self.deps.pop(pattern, None)
        if kind != "re" or said != marker:
            raise _Unread("loop body")
        return frozenset(("re", p, flags) for p in patterns)

    def _searched_loop(self, stmt: ast.For) -> frozenset[Atom]:
        """Session 56 (12p): the atoms of a loop over a module's tuple of patterns (strings or
        compiled; or (pattern, replacement) pairs) whose body opens with a search of the text by
        the loop's pattern and goes on to the next pattern where it finds nothing::

            for P, R in _MODULE_PAIRS:
                m = re.search(P, text[, F])   # re.match, _rx(P).search(text), P.search(text),
                if m is None[ or …]:          # re.search(_rx(P), text)
                    continue
                …                             # anything: run only on a match

        or whose body is that search and ``if m is not None[ and …]: …``, or whose one statement
        is a loop over the pattern's matches in the text (``for m in
        list(re.finditer(P, text))[::-1]: …``). Without any pattern's words the first search
        finds nothing, so the text is as it was at the next one, and so on: the loop leaves the
        text as it is (its match name is None after it, read as nothing known)."""
        if not isinstance(stmt.iter, ast.Name) or stmt.iter.id in self.locals:
            raise _Unread("loop")
        target = stmt.target
        names = [target] if isinstance(target, ast.Name) else getattr(target, "elts", [])
        if not names or len(names) > 2 or not all(isinstance(n, ast.Name) for n in names):
            raise _Unread("loop target")
        bound = [n.id for n in names if isinstance(n, ast.Name)]
        if any(n in (*self.same, *self.lowers, *self.matches) for n in bound):
            raise _Unread("loop target")
        value = self.glob.get(stmt.iter.id)
        if not isinstance(value, tuple) or not value:
            raise _Unread(stmt.iter.id)
        pairs = all(isinstance(v, tuple) and len(v) == 2 for v in value)
        heads = [v[0] for v in value] if pairs else list(value)
        if (len(names) == 2) != pairs or (not pairs and not isinstance(target, ast.Name)):
            raise _Unread("loop shape")
        if all(type(h) is str for h in heads):
            strings = True
        elif all(isinstance(h, re.Pattern) for h in heads):
            strings = False
        else:
            raise _Unread(stmt.iter.id)
        first = stmt.body[0]
        if isinstance(first, ast.For):
            # for m in list(re.finditer(P, text))[::-1]: … (the loop's one statement)
            if len(stmt.body) != 1 or first.orelse:
                raise _Unread("loop body")
            bound_inner = [n.id for n in ast.walk(first.target) if isinstance(n, ast.Name)]
            if any(n in (*self.same, *self.lowers, *self.matches) for n in bound_inner):
                raise _Unread("loop target")
            node = first.iter
            while True:
                if (
                    isinstance(node, ast.Call)
                    and isinstance(node.func, ast.Name)
                    and node.func.id in _BUILTIN_WRAPS
                    and node.func.id not in self.glob
                    and len(node.args) == 1
                    and not node.keywords
                ):
                    node = node.args[0]
                    continue
                if (
                    isinstance(node, ast.Subscript)
                    and isinstance(node.slice, ast.Slice)
                    and node.slice.lower is None
                    and node.slice.upper is None
                    and isinstance(node.slice.step, ast.UnaryOp)
                    and isinstance(node.slice.step.op, ast.USub)
                    and isinstance(node.slice.step.operand, ast.Constant)
                    and node.slice.step.operand.value == 1
                ):
                    node = node.value
                    continue
                break
            kind, flags = self._loop_search(node, bound[0], strings, _ITERATIONS)
        else:
            if len(stmt.body) < 2:
                raise _Unread("loop body")
            test = stmt.body[1]
            if (
                not isinstance(first, ast.Assign)
                or len(first.targets) != 1
                or not isinstance(first.targets[0], ast.Name)
            ):
                raise _Unread("loop body")
            match = first.targets[0].id
            if match in bound or match in self.same or match in self.lowers:
                raise _Unread("loop body")
            if not isinstance(test, ast.If) or test.orelse:
                raise _Unread("loop body")
            cond = test.test
            if len(test.body) == 1 and isinstance(test.body[0], ast.Continue):
                # 'if m is None[ or …]: continue' (true where m is None, the rest not asked)
                op: type[ast.cmpop] = ast.Is
                if isinstance(cond, ast.BoolOp) and isinstance(cond.op, ast.Or):
                    cond = cond.values[0]
            elif len(stmt.body) == 2:
                # the body's last statement 'if m is not None[ and …]: …' (false where m is None)
                op = ast.IsNot
                if isinstance(cond, ast.BoolOp) and isinstance(cond.op, ast.And):
                    cond = cond.values[0]
            else:
                raise _Unread("loop body")
            if not (
                isinstance(cond, ast.Compare)
                and len(cond.ops) == 1
                and isinstance(cond.ops[0], op)
                and isinstance(cond.left, ast.Name)
                and cond.left.id == match
                and isinstance(cond.comparators[0], ast.Constant)
                and cond.comparators[0].value is None
            ):
                raise _Unread("loop body")
            kind, flags = self._loop_search(first.value, bound[0], strings, _SEARCHES)
            self.matches.pop(match, None)  # None after the loop without the atoms
        if strings:
            said = tuple(str(h) for h in heads)
            self.deps[stmt.iter.id] = ("patterns", "pairs" if pairs else "strings", said)
            return frozenset((kind, h, flags) for h in said)
        compiled = tuple((h.pattern, int(h.flags)) for h in heads)
        self.deps[stmt.iter.id] = ("compiled", "pairs" if pairs else "single", compiled)
        return frozenset((kind, p, f) for p, f in compiled)

    def _loop_search(
        self, node: ast.expr, pattern: str, strings: bool, kinds: tuple[str, ...]
    ) -> tuple[str, int]:
        """The atom kind and flags of a search (one of ``kinds``) of the text by the loop's
        pattern name ``pattern`` (the flags of the tuple's strings; the compiled patterns' own
        are taken where ``strings`` is false: -1)."""
        if not isinstance(node, ast.Call) or not isinstance(node.func, ast.Attribute):
            raise _Unread("loop search")
        func, args = node.func, node.args
        kw = {k.arg: k.value for k in node.keywords}
        if func.attr not in kinds:
            raise _Unread("loop search")

        def named(arg: ast.expr) -> bool:
            return isinstance(arg, ast.Name) and arg.id == pattern

        def rx(arg: ast.expr) -> bool:  # _rx(P): P compiled case-blind
            return (
                isinstance(arg, ast.Call)
                and len(arg.args) == 1
                and not arg.keywords
                and named(arg.args[0])
                and self._helper(arg.func, _RX)
            )

        if self._re_module(func.value) and len(args) >= 2:
            if strings and named(args[0]):  # re.search(P, text[, F])
                if set(kw) - {"flags"} or len(args) > 3 or (len(args) == 3 and kw):
                    raise _Unread("loop search")
                kind = self._searched(args[1])
                return kind, self._flags(args[2] if len(args) > 2 else kw.get("flags"))
            if len(args) == 2 and not kw and strings and rx(args[0]):
                return self._searched(args[1]), int(re.IGNORECASE)  # re.search(_rx(P), text)
            if len(args) == 2 and not kw and not strings and named(args[0]):
                return self._searched(args[1]), -1  # re.search(P, text): P's own flags
            raise _Unread("loop search")
        if len(args) != 1 or kw:
            raise _Unread("loop search")
        if strings and rx(func.value):
            return self._searched(args[0]), int(re.IGNORECASE)  # _rx(P).search(text)
        if not strings and named(func.value):
            return self._searched(args[0]), -1  # P.search(text)
        raise _Unread("loop search")

    def _inert(self, stmt: ast.stmt) -> bool:
        """Whether ``stmt`` only binds names of the step's own that no atom is read of (a
        nested function without decorators or defaults, an import, ``del`` of a name)."""
        bound: list[str] = []
        if isinstance(stmt, ast.FunctionDef):
            args = stmt.args
            if stmt.decorator_list or args.defaults or any(d is not None for d in args.kw_defaults):
                return False
            bound = [stmt.name]
        elif isinstance(stmt, ast.ImportFrom) and stmt.module and not stmt.level:
            if not stmt.module.startswith("hltl.") or any(a.name == "*" for a in stmt.names):
                return False  # hltl's modules are loaded already: importing runs nothing
            bound = [a.asname or a.name for a in stmt.names]
        elif isinstance(stmt, ast.Delete) and all(isinstance(t, ast.Name) for t in stmt.targets):
            bound = [t.id for t in stmt.targets if isinstance(t, ast.Name)]
        else:
            return False
        return not any(n in self.same or n in self.lowers or n in self.matches for n in bound)

    def _fresh(self, node: ast.expr) -> bool:
        """Whether ``node`` is a constant or a new empty container ('set()', '{}', '[]')."""
        if isinstance(node, ast.Constant):
            return True
        if isinstance(node, ast.List | ast.Tuple | ast.Set) and not node.elts:
            return True
        if isinstance(node, ast.Dict) and not node.keys:
            return True
        return (
            isinstance(node, ast.Call)
            and isinstance(node.func, ast.Name)
            and node.func.id in ("set", "dict", "list")
            and node.func.id not in self.glob
            and node.func.id not in self.locals
            and not node.args
            and not node.keywords
        )

    def _same(self, node: ast.expr) -> frozenset[Atom] | None:
        """Atoms such that ``node`` equals the text wherever none of them is present (the empty
        set for the text itself), or None where it is not read so."""
        if self._is_text(node):
            return frozenset()
        try:
            return frozenset({self._sub(node)})
        except _Unread:
            pass
        try:
            return self._call(node)
        except _Unread:
            return None

    def _pure(self, node: ast.expr) -> bool:
        """Whether evaluating ``node`` as an argument can do nothing (a name, a constant, a
        name's attribute, a lambda)."""
        while isinstance(node, ast.Attribute):
            node = node.value
        return isinstance(node, ast.Name | ast.Constant | ast.Lambda)

    def _call(self, node: ast.expr) -> frozenset[Atom]:
        """Session 49: the atoms of ``helper(text, …)``, a plain function of a module whose own
        guard is read from its source (it returns its first argument as it is without them)."""
        if (
            not isinstance(node, ast.Call)
            or not isinstance(node.func, ast.Name)
            or not node.args
            or not self._is_text(node.args[0])
            or any(isinstance(a, ast.Starred) for a in node.args)
            or any(k.arg is None for k in node.keywords)
            or not all(self._pure(a) for a in (*node.args[1:], *(k.value for k in node.keywords)))
            or self.depth >= _HELPER_DEPTH
        ):
            raise _Unread("not a helper")
        helper = self._global(node.func.id)
        if (
            not isinstance(helper, types.FunctionType)
            or helper.__closure__
            or "<" in helper.__qualname__
            or helper is self.fn
        ):
            raise _Unread("not a helper")
        reader = _Reader(helper, self.depth + 1)
        try:
            atoms = reader.read()
        except (OSError, TypeError, SyntaxError) as e:
            raise _Unread("helper source") from e
        # its guard holds while its code and the module names it was read with are the same
        self.deps[node.func.id] = (
            "guarded",
            key(helper),
            fingerprint(helper),
            tuple(sorted(reader.deps.items())),
        )
        return atoms

    def read(self) -> frozenset[Atom]:
        """The guard's atoms, read from the step's first statements."""
        source = textwrap.dedent(inspect.getsource(self.fn))
        tree = ast.parse(source)
        fdef = tree.body[0]
        if not isinstance(fdef, ast.FunctionDef) or fdef.decorator_list or not fdef.args.args:
            raise _Unread("not a plain function")
        self.text = fdef.args.args[0].arg
        self.same = {self.text}
        body = list(fdef.body)
        if body and isinstance(body[0], ast.Expr) and isinstance(body[0].value, ast.Constant):
            body = body[1:]  # the docstring
        atoms: set[Atom] = set()
        if not self._block(body, atoms):
            raise _Unread("no guard")  # it ends without a return: None
        if not atoms:
            raise _Unread("no atoms")  # never a guard that turns every text away
        return frozenset(atoms)

    def _block(self, body: list[ast.stmt], atoms: set[Atom]) -> bool:
        """Read ``body``'s statements into ``atoms`` up to one returning the text: True where
        one does, False where the block ends first; _Unread at a statement it cannot read."""
        for stmt in body:
            self.at = stmt  # where the reading stopped, if it does (for a report)
            if self._inert(stmt):
                continue  # session 49: binds a name of its own and does nothing else
            if isinstance(stmt, ast.Assign | ast.AnnAssign):
                target = stmt.targets[0] if isinstance(stmt, ast.Assign) else stmt.target
                if (
                    (isinstance(stmt, ast.Assign) and len(stmt.targets) != 1)
                    or not isinstance(target, ast.Name)
                    or stmt.value is None
                ):
                    raise _Unread("assignment")
                said = self._same(stmt.value)
                if said is not None:
                    # 'out = _sub(P, R, out)', 'out = text', 'out = helper(out, lexicon)':
                    # the text still, wherever none of the atoms is present
                    if target.id in self.lowers or target.id in self.matches:
                        raise _Unread("assignment")
                    atoms |= said
                    self.same.add(target.id)
                    continue
                if target.id in self.same:
                    raise _Unread("assignment")
                # session 49: 'm = A.search(out)' … 'm = B.search(out)': bound again, what it
                # holds now is read
                self.lowers.discard(target.id)
                self.matches.pop(target.id, None)
                if isinstance(stmt.value, ast.IfExp):
                    # session 51: 'm = P.search(text) if "w" in text.lower() else None'
                    self.matches[target.id] = self._chosen(stmt.value)
                    continue
                try:
                    self._hay(stmt.value)
                except _Unread:
                    try:
                        self.matches[target.id] = self._searches(stmt.value)
                    except _Unread:
                        if not self._fresh(stmt.value):
                            raise
                        continue  # 'about = set()': a new empty value of the step's own
                else:
                    self.lowers.add(target.id)  # low = text.lower()
                continue
            if isinstance(stmt, ast.If):
                if self._if(stmt, atoms):
                    return True
                continue
            if isinstance(stmt, ast.While) and not stmt.orelse and self._safe(stmt.test):
                # session 49: a loop run only where its test finds one of its atoms
                atoms |= self.present(stmt.test)
                continue
            if isinstance(stmt, ast.For) and not stmt.orelse:
                # a loop that runs only on a match (its body may do anything), or one over a
                # module's patterns each substituted in the text: nothing without their words
                atoms |= self._loop(stmt)
                continue
            if isinstance(stmt, ast.Return) and isinstance(stmt.value, ast.IfExp):
                atoms |= self._returned(stmt.value)
                return True
            if isinstance(stmt, ast.Return) and stmt.value is not None:
                if self._is_text(stmt.value) and atoms:
                    return True
                said = self._same(stmt.value)
                if said is None or self._is_text(stmt.value):
                    raise _Unread("not a sub")
                atoms |= said
                return True
            raise _Unread("statement")
        return False

    def _chosen(self, node: ast.IfExp) -> frozenset[Atom]:
        """Session 51: the atoms of ``X if T else None`` bound to a name (a search's match, or
        None): not None only where its test is true and, where X is a search of the text, X
        finds something; the fewer atoms of the two. Its test must raise nothing."""
        if (
            not isinstance(node.orelse, ast.Constant)
            or node.orelse.value is not None
            or not self._safe(node.test)
        ):
            raise _Unread("if expression")
        found = []
        with contextlib.suppress(_Unread):
            found.append(self.present(node.test))  # not None only where T is true
        with contextlib.suppress(_Unread):
            found.append(self._searches(node.body))  # a match only where X finds something
        if not found:
            raise _Unread("if expression")
        return min(found, key=len)

    def _returned(self, node: ast.IfExp) -> frozenset[Atom]:
        """Session 51: the atoms of ``return X if T else text`` (the text wherever T is false:
        T's atoms) or ``return text if T else X`` (wherever T is true: the atoms without which
        it is). Its test must raise nothing."""
        if not self._safe(node.test):
            raise _Unread("if expression")
        if self._is_text(node.orelse):
            return self.present(node.test)
        if self._is_text(node.body):
            return self.absent(node.test)
        raise _Unread("if expression")

    def _if(self, stmt: ast.If, atoms: set[Atom]) -> bool:
        """Read an ``if`` into ``atoms``: True where it returns the text wherever none of them
        is present; False where the statements after it are read on (_Unread: not read)."""
        if (
            not stmt.orelse
            and len(stmt.body) == 1
            and isinstance(stmt.body[0], ast.Return)
            and stmt.body[0].value is not None
            and self._is_text(stmt.body[0].value)
        ):
            with contextlib.suppress(_Unread):
                atoms |= self.absent(stmt.test)
                return True
        if stmt.orelse:
            raise _Unread("if")
        if not self._safe(stmt.test):
            # 'if m is not None and <anything>:': its first sides are asked safely, and one of
            # them is false without its atoms, so the rest is not asked and the block not run
            atoms |= self._skips(stmt.test)
            return False
        with contextlib.suppress(_Unread):
            # session 49: a block run only where its test is true, and the test true only where
            # one of its atoms is present: without them the block does not run
            atoms |= self.present(stmt.test)
            return False
        # session 49: a block that leaves the text as it is without its atoms, run or not (the
        # names it binds are not read after it)
        same, lowers, matches = set(self.same), set(self.lowers), dict(self.matches)
        inner: set[Atom] = set()
        self._block(stmt.body, inner)  # returns the text, or ends with it as it was
        self.same &= same
        self.lowers, self.matches = lowers, matches
        atoms |= inner
        return False

    def _skips(self, node: ast.expr) -> frozenset[Atom]:
        """The atoms of an 'and' false without them: a side read by ``present`` after sides
        that are all safe (the sides after it are not evaluated)."""
        if isinstance(node, ast.BoolOp) and isinstance(node.op, ast.And):
            for side in node.values:
                if not self._safe(side):
                    break
                with contextlib.suppress(_Unread):
                    return self.present(side)
        raise _Unread("if test")

    def _safe(self, node: ast.expr) -> bool:
        """Whether evaluating the test ``node`` raises nothing and changes nothing: names,
        constants, comparisons, 'not', 'and', 'or', searches of the text, 'in' tests, len()."""
        if isinstance(node, ast.Name | ast.Constant):
            return True
        if isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.Not):
            return self._safe(node.operand)
        if isinstance(node, ast.BoolOp):
            return all(self._safe(v) for v in node.values)
        if isinstance(node, ast.Compare):
            return all(
                isinstance(op, ast.In | ast.NotIn | ast.Is | ast.IsNot | ast.Eq | ast.NotEq)
                for op in node.ops
            ) and all(self._safe(v) for v in (node.left, *node.comparators))
        if isinstance(node, ast.NamedExpr):
            return self._safe(node.value)
        if isinstance(node, ast.Tuple) and all(isinstance(e, ast.Constant) for e in node.elts):
            return True
        with contextlib.suppress(_Unread):
            self._part(node)
            return True  # session 51: a stretch of the text (slicing, strip, lower)
        if isinstance(node, ast.Call):
            func = node.func
            if (
                isinstance(func, ast.Attribute)
                and func.attr in ("startswith", "endswith")
                and len(node.args) == 1
                and not node.keywords
                and isinstance(node.args[0], ast.Constant | ast.Tuple)
            ):
                with contextlib.suppress(_Unread):
                    self._part(func.value)
                    self._said_words(node.args[0])
                    return True  # session 51: of a stretch of the text, with words written out
            if (
                isinstance(func, ast.Attribute)
                and isinstance(func.value, ast.Name)
                and (func.value.id in self.same or func.value.id in self.lowers)
                and not node.keywords
                and (
                    (
                        func.attr in ("lower", "strip", "rstrip", "lstrip", "isascii")
                        and not node.args
                    )
                    or (
                        func.attr in ("startswith", "endswith")
                        and len(node.args) == 1
                        and isinstance(node.args[0], ast.Constant)
                        and isinstance(node.args[0].value, str)
                    )
                )
            ):
                return True  # a string method of the text that raises nothing
            if (
                isinstance(func, ast.Name)
                and func.id == "len"
                and "len" not in self.glob
                and "len" not in self.locals
                and len(node.args) == 1
                and not node.keywords
                and isinstance(node.args[0], ast.Name)
                and node.args[0].id in self.same | self.lowers
            ):
                return True
            for read in (self.present, self._call):
                with contextlib.suppress(_Unread):
                    read(node)  # a search; a helper that returns the text without its atoms
                    return True
            return False
        return False


def read_guard(fn: Callable[..., Any]) -> Entry | None:
    """``fn``'s entry: the words one of which the text must hold for it to do anything, read from
    its source; None where its first statements are not of the kinds a guard is read from."""
    if (
        not isinstance(fn, types.FunctionType)
        or fn.__closure__
        or "<" in fn.__qualname__
        or fn.__code__.co_argcount < 1
    ):
        return None
    reader = _Reader(fn)
    try:
        atoms = reader.read()
    except (_Unread, OSError, TypeError, SyntaxError):
        return None
    plain: set[str] = set()
    folded: set[str] = set()
    patterned = False
    for kind, said, flags in atoms:
        if kind == "in":
            (folded if flags else plain).add(said)
            continue
        found = _words(said, flags)
        if found is None:
            return None  # a pattern that may match without any word: the step always runs
        words, fold = found
        if kind == "re-low":  # a match in the lower-cased text holds a word lower-cased
            folded.update(w.lower() for w in words)
        else:
            (folded if fold else plain).update(words)
        patterned = True
    if "" in plain or "" in folded:
        return None  # '' is in every text
    deps = tuple(sorted(reader.deps.items()))
    return fingerprint(fn), (tuple(sorted(plain)), tuple(sorted(folded)), patterned), deps


# -- using the list ------------------------------------------------------------------------------

# the list's entry saying how the gate derived the words it keeps (``derivation``)
_DERIVATION = "derivation"


def _words(pattern: str, flags: int) -> tuple[tuple[str, ...], bool] | None:
    """The gate's words of ``pattern`` and whether they are lower-cased (gate.py), None where it
    has none (the pattern may match without any)."""
    try:
        return gate._GATES[flags][pattern]
    except KeyError:
        return gate._gate(pattern, flags, build=False)


def derivation() -> str:
    """A digest of how the gate derives a pattern's words (the list keeps the words it derived:
    where this differs, no guard is used). Session 51: a digest of all five fingerprints (the
    first 32 letters of them joined had been the first two only)."""
    said = "".join(
        fingerprint(f) for f in (gate._needed, gate._fewest, gate._best, gate._gate, _words)
    )
    return hashlib.sha1(said.encode()).hexdigest()[:32]


def _holds(fn: Callable[..., Any], deps: tuple[Dep, ...]) -> bool:
    """Whether every module name the guard was read with still holds what it held."""
    glob = getattr(fn, "__globals__", {})
    for name, was in deps:
        if name not in glob:
            return False
        value = glob[name]
        kind = was[0]
        if kind == "value":
            if not isinstance(value, str | int) or repr(value) != was[1]:
                return False
        elif kind == "pattern":
            if not isinstance(value, re.Pattern) or (value.pattern, int(value.flags)) != was[1:]:
                return False
        elif kind == "function":
            value = _plain(value)
            if key(value) != was[1] or fingerprint(value) != was[2]:
                return False
        elif kind == "module":
            if getattr(value, "__name__", None) != was[1]:
                return False
        elif kind == "guarded":  # a helper read through (session 49): its own names too
            if (
                not isinstance(value, types.FunctionType)
                or key(value) != was[1]
                or fingerprint(value) != was[2]
                or not _holds(value, was[3])
            ):
                return False
        elif kind == "compiled":  # session 56 (12p): a tuple of compiled patterns (or pairs)
            if not isinstance(value, tuple) or not value:
                return False
            pairs = was[1] == "pairs"
            if any(isinstance(v, tuple) != pairs for v in value):
                return False
            heads = [v[0] if pairs and len(v) == 2 else None if pairs else v for v in value]
            if not all(isinstance(h, re.Pattern) for h in heads):
                return False
            if tuple((h.pattern, int(h.flags)) for h in heads if h is not None) != was[2]:
                return False
        elif kind == "patterns":
            if not isinstance(value, tuple) or not value:
                return False
            pairs = was[1] == "pairs"
            if (
                any(not isinstance(v, tuple) or len(v) != 2 for v in value)
                if pairs
                else any(not isinstance(v, str) for v in value)
            ):
                return False
            if tuple(v[0] if pairs else v for v in value) != was[2]:
                return False
        else:
            return False
    return True


def guard(fn: Callable[..., Any], entry: Entry | None) -> Guard | None:
    """``fn``'s guard from its entry, or None (the step always runs) where it has none, its code
    is not what the entry was read from, or a name it was read with holds something else."""
    if entry is None or fingerprint(fn) != entry[0] or not _holds(fn, entry[2]):
        return None
    if "" in entry[1][0] or "" in entry[1][1]:
        return None  # session 50: '' is in every text (read_guard never writes one)
    return entry[1]


def guards(
    steps: Sequence[Callable[..., Any]], known: Mapping[str, Entry | str]
) -> tuple[Guard | None, ...]:
    """Each step's guard (None: it always runs; every step, where the gate's way of deriving a
    pattern's words is not the one the list was made with)."""
    if known.get(_DERIVATION) != derivation():
        return (None,) * len(steps)
    out = []
    for step in steps:
        entry = known.get(key(step))
        out.append(guard(step, entry if isinstance(entry, tuple) else None))
    return tuple(out)


def may_act(rule: Guard, text: str, low: str, ascii_: bool) -> bool:
    """Whether a step with guard ``rule`` may do anything to ``text`` (``low``: its lower case;
    ``ascii_``: whether it is ASCII)."""
    plain, folded, patterned = rule
    if patterned and not ascii_:
        return True
    for word in plain:  # a loop: any() over a generator costs more
        if word in text:
            return True
    for word in folded:  # noqa: SIM110
        if word in low:
            return True
    return False


# -- remaking the list ---------------------------------------------------------------------------


# Session 52 (12b): the list writer shared by this module and refusalguard.py (which kept a copy):
# ``read_all`` with the reader of the list's kind, ``list_text`` the module written, ``write_list``
# both and the file; each module's ``main`` says what it wrote.


def read_all(
    fns: Iterable[Callable[..., Any]],
    read: Callable[[Callable[..., Any]], Entry | None] = read_guard,
) -> dict[str, Entry]:
    """The entries (by ``key``) of every function ``read`` reads a guard of (a step's, here)."""
    out: dict[str, Entry] = {}
    for fn in fns:
        entry = read(fn)
        if entry is not None:
            out[key(fn)] = entry
    return out


def list_text(what: str, maker: str, made: str, entries: Mapping[str, Entry]) -> str:
    """A generated list's source: its docstring (``what`` it guards, made by module ``maker``),
    the entry saying how its guards were read (``made``) and the entries, sorted by name."""
    lines = [
        "# ruff: noqa: E501",
        f'"""{what} (made by python -m {maker} --write)."""',
        "",
        "from hltl.grounding.stepguard import Entry",
        "",
        "GUARDS: dict[str, Entry | str] = {",
        f"    {_DERIVATION!r}: {made!r},",
        *(f"    {name!r}: {entry!r}," for name, entry in sorted(entries.items())),
        "}",
        "",
    ]
    return "\n".join(lines)


def write_list(
    out: Path,
    fns: Sequence[Callable[..., Any]],
    read: Callable[[Callable[..., Any]], Entry | None],
    what: str,
    maker: str,
    made: str,
) -> int:
    """Writes the list of ``fns``' guards to ``out`` (``ruff format`` it after); how many."""
    entries = read_all(fns, read)
    out.write_text(list_text(what, maker, made, entries), encoding="utf-8")
    return len(entries)


def all_steps() -> tuple[Callable[..., Any], ...]:
    """Every step the normaliser runs, once each."""
    # why: normalise imports _normalise1, which imports this module
    from hltl.grounding import normalise

    return tuple(dict.fromkeys((*normalise._STEPS19, *normalise._STEPS)))


def main(argv: Sequence[str]) -> int:
    """``--write``: remake _step_guards.py from the steps' source."""
    if list(argv) != ["--write"]:
        print("usage: python -m hltl.grounding.stepguard --write", file=sys.stderr)
        return 2
    steps = all_steps()
    out = Path(__file__).with_name("_step_guards.py")
    what = "The normaliser's step guards"
    n = write_list(out, steps, read_guard, what, "hltl.grounding.stepguard", derivation())
    print(f"{n} of {len(steps)} steps guarded, written to {out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
