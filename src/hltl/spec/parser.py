"""Parse LTLf formulas (our syntax and ltl2ba's) into the syntax tree of ``hltl.spec.syntax``."""

from __future__ import annotations

import re
from collections.abc import Callable

from hltl.errors import SpecSyntaxError
from hltl.fileio import quote
from hltl.spec.syntax import (
    PREDICATES,
    Always,
    And,
    Atom,
    Equiv,
    Eventually,
    FalseF,
    Formula,
    Implies,
    Next,
    Not,
    Or,
    Release,
    TrueF,
    Until,
    WeakNext,
)

# Words that are operators or constants, hence never atom or formula names.
KEYWORDS = frozenset({"X", "WX", "F", "G", "U", "R", "V", "true", "false"})

# Far beyond any task a person states; the bounds keep parsing, printing and compiling (all
# recursive over the tree) inside Python's recursion limit and error messages short.
MAX_FORMULA_CHARS = 10_000
MAX_FORMULA_DEPTH = 100

# The grammar (hltl.spec.grammar, lark's LALR parser) is the reference. The hand-written parser
# below reads what the grammar accepts the way lark's contextual lexer and parser read it, and
# gives up on anything else (every error, and formulas nested too deep): lark then parses the
# text again and words the error. A valid spec is read without importing lark at all (~30 ms
# of `hltl plan`'s start-up, docs/benchmarks.md "Start-up").
_SPACE = re.compile(r"\s*")
_WORD = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
_Prefix = Callable[[Formula], Formula]
_Infix = Callable[[Formula, Formula], Formula]
_PREFIX_WORDS: dict[str, _Prefix] = {
    "X": Next,
    "WX": WeakNext,
    "F": Eventually,
    "G": Always,
}
_PREFIX_SIGNS: tuple[tuple[str, _Prefix], ...] = (
    ("!", Not),
    ("<>", Eventually),
    ("[]", Always),
)
# binary operators, loosest first: (sign, level, class); a longer sign before its prefix
_BINARY: tuple[tuple[str, int, _Infix], ...] = (
    ("<->", 0, Equiv),
    ("->", 1, Implies),
    ("||", 2, Or),
    ("|", 2, Or),
    ("&&", 3, And),
    ("&", 3, And),
    ("U", 4, Until),
    ("R", 4, Release),
    ("V", 4, Release),
)
_RIGHT_LEVELS = frozenset({1, 4})  # -> and U R are right-associative, the others left


class _LeftToLark(Exception):
    """The hand-written parser does not decide this text: the grammar does (or refuses it)."""


class _Reader:
    """Precedence climbing over ``text``; each result comes with the depth of lark's parse tree
    for it (a group in parentheses is a level there), which ``MAX_FORMULA_DEPTH`` bounds."""

    __slots__ = ("nest", "pos", "text")

    def __init__(self, text: str) -> None:
        self.text = text
        self.pos = 0
        self.nest = 0  # formulas being read inside each other: at most the tree's depth

    def parse(self) -> tuple[Formula, int]:
        formula, depth = self._formula(0)
        if self._skip() != len(self.text) or depth > MAX_FORMULA_DEPTH:
            raise _LeftToLark
        return formula, depth

    def _skip(self) -> int:
        match = _SPACE.match(self.text, self.pos)
        assert match is not None  # (\s* matches everywhere)
        self.pos = match.end()
        return self.pos

    def _formula(self, least: int) -> tuple[Formula, int]:
        # operands joined by binary operators of level ``least`` or tighter
        self.nest += 1
        if self.nest > MAX_FORMULA_DEPTH:
            raise _LeftToLark  # (lark refuses it as too deep; this keeps off the recursion limit)
        left, depth = self._unary()
        while True:
            op = self._operator()
            if op is None or op[1] < least:
                break
            sign, level, cls = op
            self.pos += len(sign)
            right, right_depth = self._formula(level if level in _RIGHT_LEVELS else level + 1)
            left, depth = cls(left, right), 1 + max(depth, right_depth)
        self.nest -= 1
        return left, depth

    def _operator(self) -> tuple[str, int, _Infix] | None:
        pos = self._skip()
        text = self.text
        for op in _BINARY:
            if text.startswith(op[0], pos):
                return op
        return None

    def _unary(self) -> tuple[Formula, int]:
        ops: list[_Prefix] = []
        text = self.text
        while True:
            pos = self._skip()
            for sign, cls in _PREFIX_SIGNS:
                if text.startswith(sign, pos):
                    ops.append(cls)
                    self.pos += len(sign)
                    break
            else:
                match = _WORD.match(text, pos)
                if match is None or match.group() not in _PREFIX_WORDS:
                    break
                ops.append(_PREFIX_WORDS[match.group()])
                self.pos = match.end()
        formula, depth = self._primary()
        for cls in reversed(ops):
            formula = cls(formula)
        return formula, depth + len(ops)

    def _primary(self) -> tuple[Formula, int]:
        text, pos = self.text, self.pos
        if text.startswith("(", pos):
            self.pos += 1
            inner, depth = self._formula(0)
            if not text.startswith(")", self._skip()):
                raise _LeftToLark
            self.pos += 1
            return inner, depth + 1
        match = _WORD.match(text, pos)
        if match is None:
            raise _LeftToLark
        name = match.group()
        self.pos = match.end()
        if name == "true":
            return TrueF(), 1
        if name == "false":
            return FalseF(), 1
        if name in KEYWORDS:
            raise _LeftToLark
        if not text.startswith("(", self._skip()):
            return Atom(name), 1
        args: list[str] = []
        while True:
            self.pos += 1  # the "(" or a ","
            match = _WORD.match(text, self._skip())
            if match is None:
                raise _LeftToLark
            args.append(match.group())
            self.pos = match.end()
            pos = self._skip()
            if text.startswith(")", pos):
                self.pos += 1
                break
            if not text.startswith(",", pos):
                raise _LeftToLark
        if PREDICATES.get(name) != len(args):
            raise _LeftToLark  # (an unknown predicate, or the wrong number of arguments)
        return Atom(name, tuple(args)), 1


def read_valid(text: str) -> tuple[Formula, int] | None:
    """``text``'s formula and parse-tree depth when the hand-written parser reads it (a valid
    formula of bounded depth), else ``None`` (``parse_formula`` asks the grammar then)."""
    try:
        return _Reader(text).parse()
    except _LeftToLark:
        return None


def parse_formula(text: str) -> Formula:
    """Parse one LTLf formula.

    Accepts ``X WX F G U R ! & | -> <->``, ``true``/``false``, parentheses, bare atoms (``p100``)
    and predicate atoms (``delivered(bottle, A)``), plus ltl2ba's ``<> [] && || V``.

    Args:
        text: the formula.

    Returns:
        The formula's syntax tree.

    Raises:
        SpecSyntaxError: the text does not parse, or a predicate is unknown or has the wrong
            number of arguments; the message names line and column and quotes the text.
    """
    if not isinstance(text, str):
        raise SpecSyntaxError(
            f"a formula must be a string, got {type(text).__name__}: {quote(text)}"
        )
    if not text.strip():
        raise SpecSyntaxError(f"empty formula {quote(text)}", text=text, line=1, column=1)
    if len(text) > MAX_FORMULA_CHARS:
        raise SpecSyntaxError(
            f"formula of {len(text):,} characters is too long (at most {MAX_FORMULA_CHARS:,}): "
            f"{quote(text, 40)}; split the task into named sub-formulas",
            text=text,
            line=1,
            column=1,
        )
    read = read_valid(text)
    if read is not None:
        return read[0]
    # why: lark (30 ms to import) only for what the hand-written parser leaves: errors, deep nests
    from hltl.spec import grammar

    return grammar.parse(text)
