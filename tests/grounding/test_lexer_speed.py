"""The lexer's speed paths (session 24, issue 12s) give what the plain computation gives:
tokenize's rewrites run only on a text holding one of their words, Lexicon.match is kept per
window of words, _match_phrase looks only at a word that starts a keyword phrase."""

from __future__ import annotations

import re

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.bench.grounding import CORPUS_DIR, load_corpus
from hltl.grounding import lexicon
from hltl.grounding.lexicon import PHRASES, Lexicon, Token, tokenize
from tests.grounding.helpers import ROOT


def _tokenize_unguarded(text: str) -> list[Token]:
    """tokenize with every rewrite run on every text (what it did before the words were tested)."""
    text = text.replace("\u2019", "'").replace("\u2018", "'").replace("\u2026", "...")
    for pattern, repl, _words, _fold in lexicon._TOKEN_REWRITES:
        text = pattern.sub(repl, text)
    out = []
    for m in lexicon._TOKEN.finditer(text):
        word = m.group(0)
        if word in ("\u2013", "\u2014"):
            word = "-"
        out.append(Token(word, word.lower()))
    return out


# the words tokenize's rewrites look for, their near misses, and letters re folds onto ASCII
_PIECES = (
    "..",
    ".",
    "...",
    "&",
    "+",
    "->",
    "=>",
    "\u2192",
    "comma",
    "Comma",
    "full stop",
    "period",
    "question mark",
    "exclamation mark",
    "exclamation point",
    "all of the stuff",
    "all but",
    "ALL EXCEPT",
    "1st",
    "2nd",
    "3rd",
    "won't",
    "can't",
    "shan't",
    "don't",
    "Won't",
    "isn't",
    "\u017fhan't",
    "\u212aomma",
    "Dr.",
    "mr.",
    "give",
    "Bob",
    "the cup",
    " ",
    " ",
    ",",
    "!",
    "?",
    "\u2019",
    "\u2026",
    "\u2013",
    "actually",
    "sorry",
)


def _matches_hold_their_words(text: str) -> None:
    """Every match of each rewrite on an ASCII text holds one of the words tokenize tests for it
    (lower-cased for a case-blind pattern); a text that is not ASCII is always rewritten."""
    if not text.isascii():
        return
    for pattern, _repl, words, fold in lexicon._TOKEN_REWRITES:
        assert fold == bool(pattern.flags & re.IGNORECASE)
        for m in pattern.finditer(text):
            said = m.group(0).lower() if fold else m.group(0)
            assert any(w in said for w in words), (pattern.pattern, m.group(0), words)


@given(st.lists(st.sampled_from(_PIECES), max_size=12))
@settings(max_examples=400, deadline=None)
def test_tokenize_gives_what_every_rewrite_run_gives(pieces: list[str]) -> None:
    text = "".join(pieces)
    _matches_hold_their_words(text)
    assert tokenize(text) == _tokenize_unguarded(text)


@pytest.mark.parametrize("part", ["tuning", "causes18", "blind21"])
def test_tokenize_and_match_on_the_corpus(part: str) -> None:
    corpus = load_corpus(ROOT / CORPUS_DIR / f"{part}.yaml", ROOT)
    for entry in corpus.entries:
        _matches_hold_their_words(entry.text)
        tokens = tokenize(entry.text)
        assert tokens == _tokenize_unguarded(entry.text)
        lex = Lexicon.of(corpus.scenes[entry.scene])
        for i in range(len(tokens)):
            first = lex.match(tokens, i)
            assert lex.match(tokens, i) == first == lex._match(tokens, i)
            assert lexicon._match_phrase(tokens, i) == _match_phrase_plain(tokens, i)


def _match_phrase_plain(tokens: list[Token], i: int) -> tuple[int, str] | None:
    for n in range(min(lexicon.MAX_PHRASE, len(tokens) - i), 1, -1):
        lemma = PHRASES.get(tuple(t.low for t in tokens[i : i + n]))
        if lemma is not None and not lexicon._pronoun_subject(tokens, i + n):
            words = tuple(t.low for t in tokens[i : i + n])
            if words in lexicon._GREETING_ALONE and not lexicon._sentence_starts(tokens, i):
                continue  # (a greeting is one only where a sentence starts)
            return n, lemma
    return None


def test_match_is_kept_per_window_and_dropped_when_many(monkeypatch: pytest.MonkeyPatch) -> None:
    corpus = load_corpus(ROOT / CORPUS_DIR / "tuning.yaml", ROOT)
    lex = Lexicon(next(iter(corpus.scenes.values())))
    tokens = tokenize("Give bob the cpu, and Bob the cup")
    # the same words typed in another case are another window ('Bob' / 'bob': ids match by case)
    assert lex.match(tokens, 1) == lex._match(tokens, 1)
    assert lex.match(tokens, 6) == lex._match(tokens, 6)
    assert len(lex._matches) == 2
    monkeypatch.setattr(lexicon, "_LEXED_KEPT", 1)
    lex.forget()
    assert lex._matches == {}
