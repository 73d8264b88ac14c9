"""The LTLf grammar as a lark LALR parser: the reference behind parse_formula, and its errors."""

from __future__ import annotations

import threading
from typing import Any

from lark import Lark, Token, Transformer, v_args
from lark.exceptions import UnexpectedCharacters, UnexpectedEOF, UnexpectedToken, VisitError

from hltl.errors import SpecSyntaxError
from hltl.fileio import cache_dir, quote
from hltl.spec.parser import MAX_FORMULA_DEPTH
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

# Precedence, loosest first (each level is one rule below):
#   <->  left-associative
#   ->   right-associative
#   |    left-associative       (also ||)
#   &    left-associative       (also &&)
#   U R  right-associative, same level (ltl2ba's V is R)
#   ! X WX F G  prefix, tightest (ltl2ba's <> is F, [] is G)
# NAME refuses a keyword standing alone, so "F a" is eventually-a while "Fa" is an atom.
GRAMMAR = r"""
?start: equiv

?equiv: implies
      | equiv EQUIV implies          -> equiv

?implies: or_
        | or_ IMPLIES implies        -> implies

?or_: and_
    | or_ OR and_                    -> or_

?and_: temporal
     | and_ AND temporal             -> and_

?temporal: unary
         | unary UNTIL temporal      -> until
         | unary RELEASE temporal    -> release

?unary: primary
      | NOT unary                    -> not_
      | NEXT unary                   -> next_
      | WEAK_NEXT unary              -> weak_next
      | EVENTUALLY unary             -> eventually
      | ALWAYS unary                 -> always

?primary: TRUE                       -> true
        | FALSE                      -> false
        | NAME                       -> bare_atom
        | NAME LPAR ARG (COMMA ARG)* RPAR -> predicate
        | LPAR equiv RPAR            -> group

EQUIV: "<->"
IMPLIES: "->"
OR: "||" | "|"
AND: "&&" | "&"
UNTIL: "U"
RELEASE: "R" | "V"
NOT: "!"
NEXT: "X"
WEAK_NEXT: "WX"
EVENTUALLY: "F" | "<>"
ALWAYS: "G" | "[]"
TRUE: "true"
FALSE: "false"
LPAR: "("
RPAR: ")"
COMMA: ","
NAME: /(?!(?:X|WX|F|G|U|R|V|true|false)(?![A-Za-z0-9_]))[A-Za-z_][A-Za-z0-9_]*/
ARG: /[A-Za-z_][A-Za-z0-9_]*/

%ignore /\s+/
"""

_OPERAND_START = frozenset({"NAME", "LPAR", "TRUE", "FALSE", "NOT", "EVENTUALLY"})

_parser_lock = threading.Lock()
_parser: Lark | None = None


def _lark() -> Lark:
    # Built on first use: a module-level parser would cost every import of this module.
    global _parser
    with _parser_lock:
        if _parser is None:
            _parser = Lark(
                GRAMMAR,
                parser="lalr",
                lexer="contextual",
                propagate_positions=False,
                cache=_cache_file(),
            )
        return _parser


def _cache_file() -> str | bool:
    """Lark keeps the analysed grammar here (keyed by the grammar's hash, so an edited grammar is
    analysed again): a new process loads the parser in ~5 ms instead of building it in ~25 ms."""
    folder = cache_dir("lark")
    if folder is None:
        return False
    try:
        folder.mkdir(parents=True, exist_ok=True)
    except OSError:
        return False  # a read-only cache folder only costs the next process the build
    return str(folder / "spec-grammar.lark")


class _PredicateError(Exception):
    """Raised inside the transformer; turned into a SpecSyntaxError with the token's position."""

    def __init__(self, head: str, tail: str, token: Token) -> None:
        super().__init__(head)
        self.head, self.tail, self.token = head, tail, token


@v_args(inline=True)
class _ToFormula(Transformer[Token, Formula]):
    def equiv(self, left: Formula, _op: Token, right: Formula) -> Formula:
        return Equiv(left, right)

    def implies(self, left: Formula, _op: Token, right: Formula) -> Formula:
        return Implies(left, right)

    def or_(self, left: Formula, _op: Token, right: Formula) -> Formula:
        return Or(left, right)

    def and_(self, left: Formula, _op: Token, right: Formula) -> Formula:
        return And(left, right)

    def until(self, left: Formula, _op: Token, right: Formula) -> Formula:
        return Until(left, right)

    def release(self, left: Formula, _op: Token, right: Formula) -> Formula:
        return Release(left, right)

    def not_(self, _op: Token, operand: Formula) -> Formula:
        return Not(operand)

    def next_(self, _op: Token, operand: Formula) -> Formula:
        return Next(operand)

    def weak_next(self, _op: Token, operand: Formula) -> Formula:
        return WeakNext(operand)

    def eventually(self, _op: Token, operand: Formula) -> Formula:
        return Eventually(operand)

    def always(self, _op: Token, operand: Formula) -> Formula:
        return Always(operand)

    def true(self, _tok: Token) -> Formula:
        return TrueF()

    def false(self, _tok: Token) -> Formula:
        return FalseF()

    def group(self, _lpar: Token, inner: Formula, _rpar: Token) -> Formula:
        return inner

    def bare_atom(self, name: Token) -> Formula:
        return Atom(str(name))

    def predicate(self, name: Token, *rest: Token) -> Formula:
        args = tuple(str(t) for t in rest if t.type == "ARG")
        arity = PREDICATES.get(str(name))
        if arity is None:
            known = ", ".join(sorted(PREDICATES))
            head = f"unknown predicate {str(name)!r}"
            raise _PredicateError(head, f"; predicates are: {known}", name)
        if len(args) != arity:
            noun = "argument" if arity == 1 else "arguments"
            head = f"{name}() takes {arity} {noun}, got {len(args)} ({', '.join(args)})"
            raise _PredicateError(head, "", name)
        return Atom(str(name), args)


_EXCERPT = 60


def _where(text: str, line: int, column: int) -> str:
    if len(text) <= 2 * _EXCERPT:
        return f'at line {line}, column {column} in "{text}"'
    # a long formula is shown around the problem only
    lines = text.split("\n")
    row = lines[line - 1] if 0 < line <= len(lines) else text
    lo = max(0, column - 1 - _EXCERPT // 2)
    piece = row[lo : lo + _EXCERPT]
    left = "…" if lo > 0 else ""
    right = "…" if lo + _EXCERPT < len(row) else ""
    return f'at line {line}, column {column} in "{left}{piece}{right}" ({len(text):,} characters)'


def tree_depth(tree: Any) -> int:
    """The depth of lark's parse tree (tokens not counted): what MAX_FORMULA_DEPTH bounds."""
    # iterative: the tree may be far deeper than the recursion limit
    best = 0
    stack: list[tuple[Any, int]] = [(tree, 1)]
    while stack:
        node, d = stack.pop()
        best = max(best, d)
        stack.extend((c, d + 1) for c in getattr(node, "children", ()) if not isinstance(c, Token))
    return best


def _end_position(text: str) -> tuple[int, int]:
    lines = text.split("\n")
    return len(lines), len(lines[-1]) + 1


def _hint(text: str, got: str, expected: Any) -> str:
    # LALR's expected sets are merged across contexts, so they are only trusted where they are
    # unambiguous: an operand is missing, an identifier is missing, or a '(' is left open.
    names = set(expected or ())
    if "NAME" in names:
        return "; expected an atom, 'true', 'false', '(' or a unary operator (! X WX F G)"
    if names == {"ARG"}:
        return "; expected an identifier"
    if got == "$END" and text.count("(") > text.count(")"):
        return "; missing ')'"
    if got == "RPAR" and text.count(")") > text.count("("):
        return "; this ')' has no matching '('"
    # ARG: a keyword where no operand may stand is lexed by the fallback lexer as an identifier
    if got in _OPERAND_START or got in {"NEXT", "WEAK_NEXT", "ALWAYS", "ARG"}:
        return "; expected a binary operator (& | -> <-> U R) between two formulas"
    return ""


def parse_tree(text: str) -> Any:
    """Lark's parse tree of ``text`` (a non-empty string of bounded length).

    Raises:
        SpecSyntaxError: the text does not parse; the message names line and column.
    """
    try:
        return _lark().parse(text)
    except UnexpectedCharacters as exc:
        msg = f"unexpected character {exc.char!r} {_where(text, exc.line, exc.column)}"
        raise SpecSyntaxError(msg, text=text, line=exc.line, column=exc.column) from None
    except UnexpectedToken as exc:
        if exc.token.type == "$END":
            line, column = _end_position(text)
            what = "end of formula"
        else:
            line, column = exc.token.line or 0, exc.token.column or 0
            what = repr(str(exc.token))
        hint = _hint(text, exc.token.type, exc.expected)
        msg = f"unexpected {what} {_where(text, line, column)}{hint}"
        raise SpecSyntaxError(msg, text=text, line=line, column=column) from None
    except UnexpectedEOF:  # pragma: no cover - LALR reports end of input as UnexpectedToken
        line, column = _end_position(text)
        msg = f"unexpected end of formula {_where(text, line, column)}"
        raise SpecSyntaxError(msg, text=text, line=line, column=column) from None


def parse(text: str) -> Formula:
    """``parse_formula``'s work through lark, from the parse on (see there).

    Raises:
        SpecSyntaxError: the text does not parse, nests too deep, or a predicate is unknown or
            has the wrong number of arguments.
    """
    tree = parse_tree(text)
    depth = tree_depth(tree)
    if depth > MAX_FORMULA_DEPTH:
        raise SpecSyntaxError(
            f"formula nests {depth} levels deep (operators, parentheses or a long chain of "
            f"binary operators; at most {MAX_FORMULA_DEPTH}): {quote(text, 40)}; split it into "
            "named sub-formulas",
            text=text,
            line=1,
            column=1,
        )
    try:
        result: Formula = _ToFormula().transform(tree)
    except VisitError as exc:
        orig = exc.orig_exc
        if isinstance(orig, _PredicateError):
            line, column = orig.token.line or 0, orig.token.column or 0
            msg = f"{orig.head} {_where(text, line, column)}{orig.tail}"
            raise SpecSyntaxError(msg, text=text, line=line, column=column) from None
        raise
    return result
