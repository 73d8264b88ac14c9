"""The hand-written parser against the grammar (lark): same formula and depth, or lark decides."""

from __future__ import annotations

import random
import subprocess
import sys

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from ltlf_strategies import formulas

from hltl.errors import SpecSyntaxError
from hltl.spec import grammar
from hltl.spec.parser import MAX_FORMULA_DEPTH, parse_formula, read_valid
from hltl.spec.printer import to_string
from hltl.spec.syntax import (
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

SPELLINGS: dict[type, tuple[str, ...]] = {
    Not: ("!",),
    Next: ("X",),
    WeakNext: ("WX",),
    Eventually: ("F", "<>"),
    Always: ("G", "[]"),
    And: ("&", "&&"),
    Or: ("|", "||"),
    Implies: ("->",),
    Equiv: ("<->",),
    Until: ("U",),
    Release: ("R", "V"),
}
SPACES = ("", " ", "  ", "\n", "\t", "\u00a0")
# what an edit may put in: pieces of the syntax, keywords glued to names, strays
PIECES = (
    "(", ")", ",", "!", "<>", "[]", "&", "&&", "|", "||", "->", "<->", "<", "-", "[", "$",
    "U", "R", "V", "X", "WX", "F", "G", "W", "true", "false", "Fa", "Ub", "Xa", "WXa", "trueish",
    "a", "p100", "picked", "delivered", "at", "_", "9", " ", "\n",
)  # fmt: skip


def _render(rng: random.Random, f: Formula) -> str:
    """``f`` with random spellings, spaces and extra parentheses."""

    def space() -> str:
        return rng.choice(SPACES)

    def go(g: Formula) -> str:
        if isinstance(g, Atom):
            if not g.args:
                text = g.name
            else:
                args = ("," + space()).join(g.args)
                text = f"{g.name}{space()}({space()}{args}{space()})"
        elif isinstance(g, TrueF | FalseF):
            text = "true" if isinstance(g, TrueF) else "false"
        elif isinstance(g, Not | Next | WeakNext | Eventually | Always):
            text = rng.choice(SPELLINGS[type(g)]) + space() + go(g.operand)
        else:
            op = rng.choice(SPELLINGS[type(g)])
            text = f"({go(g.left)}){space()}{op}{space()}({go(g.right)})"
        if rng.random() < 0.15:
            text = f"({space()}{text}{space()})"
        return text

    return go(f)


def _edited(rng: random.Random, f: Formula) -> str:
    """``f`` rendered, then up to two random edits (most texts are then no formula)."""
    text = _render(rng, f)
    for _ in range(rng.randint(0, 2)):
        at = rng.randint(0, len(text))
        text = text[:at] + rng.choice(PIECES) + text[at + rng.randint(0, 2) :]
    return text


texts = st.builds(_edited, st.randoms(use_true_random=False), formulas(depth=4))


def _grammar_says(text: str) -> tuple[Formula, int] | None:
    try:
        formula = grammar.parse(text)
    except SpecSyntaxError:
        return None
    return formula, grammar.tree_depth(grammar.parse_tree(text))


@settings(max_examples=1000, deadline=None)
@given(texts)
def test_the_reader_reads_exactly_what_the_grammar_accepts(text: str) -> None:
    if not text.strip():
        return
    assert read_valid(text) == _grammar_says(text), text


@pytest.mark.parametrize(
    "text",
    [
        "a Ub",  # after an operand the lexer takes U as until, whatever follows
        "a Vb",
        "a Rtrue",
        "Fa U Xb",
        "WX WXa",
        "F(a)",
        "G[]<>F a",
        "holding(X, F) & at ( x , true )",
        "a&&b||c<->d->e",
        "true&false",
        "truex & _false",
        "delivered\n(\tb,\u00a0A\n)",
    ],
)
def test_the_reader_on_what_lark_lexes_by_context(text: str) -> None:
    read = read_valid(text)
    assert read is not None and read == _grammar_says(text)


@pytest.mark.parametrize(
    ("text", "reads"),
    [
        ("(" * 49 + "a" + ")" * 49, True),  # depth 50: 49 groups around the atom
        ("(" * 99 + "a" + ")" * 99, True),  # depth 100
        ("(" * 100 + "a" + ")" * 100, False),  # depth 101: lark refuses it
        ("!" * 99 + "a", True),
        ("!" * 100 + "a", False),
        (" & ".join(["a"] * 100), True),  # a left-leaning chain: 99 Ands over an atom
        (" & ".join(["a"] * 101), False),
        (" U ".join(["a"] * 100), True),
        (" U ".join(["a"] * 101), False),
        ("(" * 3000 + "a" + ")" * 3000, False),  # far past the recursion limit
    ],
)
def test_depth_at_the_bound_is_lark_s(text: str, reads: bool) -> None:
    read = read_valid(text)
    assert (read is not None) is reads
    if reads:
        assert read is not None and read[1] <= MAX_FORMULA_DEPTH
        assert read == _grammar_says(text)
    else:
        with pytest.raises(SpecSyntaxError, match="levels deep"):
            parse_formula(text)


@settings(max_examples=300, deadline=None)
@given(formulas(depth=5))
def test_every_printed_formula_is_read_without_lark(f: Formula) -> None:
    read = read_valid(to_string(f))
    assert read is not None and read[0] == f


def test_a_valid_formula_does_not_import_lark_and_an_error_does() -> None:
    code = (
        "import sys\n"
        "from hltl.errors import SpecSyntaxError\n"
        "from hltl.spec.parser import parse_formula\n"
        "parse_formula('F delivered(bottle, A) & (G !picked(cup) U X p100)')\n"
        "print('lark' in sys.modules)\n"
        "try:\n"
        "    parse_formula('F (a & )')\n"
        "except SpecSyntaxError as exc:\n"
        "    print('lark' in sys.modules, exc)\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.splitlines() == [
        "False",
        "True unexpected ')' at line 1, column 8 in \"F (a & )\"; expected an atom, 'true', "
        "'false', '(' or a unary operator (! X WX F G)",
    ]
