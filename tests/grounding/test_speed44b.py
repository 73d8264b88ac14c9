"""Session 44 (12b): _people's patterns built once per lexicon and skipped where the text lacks
the name, _fillers19's cheap tests first, _names kept per text, and phrasing passes run only
where their word is said, give what the work they replace gave."""

from __future__ import annotations

import re
import string

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.bench.grounding import CORPUS_DIR, load_corpus
from hltl.errors import GroundingError
from hltl.grounding import _normalise1, phrasing
from hltl.grounding.lexicon import Lexicon, lex
from tests.grounding.helpers import ROOT

# tuning parts only (a held-back part is never read by a test)
_PARTS = ("tuning", "blind22", "blind37", "blind42")


def _entries() -> list[tuple[str, Lexicon]]:
    out = []
    for part in _PARTS:
        corpus = load_corpus(ROOT / CORPUS_DIR / f"{part}.yaml", ROOT)
        out += [(e.text, Lexicon.of(corpus.scenes[e.scene])) for e in corpus.entries]
    return out


_ENTRIES = _entries()


def _people_every_name(text: str, lexicon: Lexicon, monkeypatch: pytest.MonkeyPatch) -> str:
    """_people with no name skipped: every pattern tried, as before session 44."""
    with monkeypatch.context() as m:
        m.setattr(_normalise1, "_absent", lambda name, text: False)
        return _normalise1._people(text, lexicon)


def test_people_skips_only_what_could_not_match_on_the_corpus(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # the corpus's sentences, and the same lower-cased, with a title said in full
    for text, lexicon in _ENTRIES:
        for said in (text, text.lower(), re.sub(r"\bMr\b", "Mister", text)):
            got = _normalise1._people(said, lexicon)
            assert got == _people_every_name(said, lexicon, monkeypatch), said


def test_people_plan_is_built_once_per_lexicon() -> None:
    lexicons = {id(lx): lx for _, lx in _ENTRIES}.values()
    for lexicon in lexicons:
        plan = _normalise1._people_plan(lexicon)
        assert plan is _normalise1._people_plan(lexicon)
    ward = next(lx for lx in lexicons if any("Mr Lee" in h.aliases for h in lx.scene.humans))
    assert _normalise1._people_plan.__wrapped__(ward) == _normalise1._people_plan(ward)


_ASCII = string.ascii_letters + " .,'-"


@settings(max_examples=300, deadline=None)
@given(st.text(alphabet=_ASCII, max_size=30), st.text(alphabet=_ASCII, min_size=1, max_size=6))
def test_absent_only_where_the_name_cannot_match(text: str, name: str) -> None:
    if _normalise1._absent(name, text):
        assert re.search(re.escape(name), text, re.IGNORECASE) is None


@settings(max_examples=200, deadline=None)
@given(st.text(max_size=20), st.text(min_size=1, max_size=4))
def test_absent_is_false_for_text_that_is_not_ascii(text: str, name: str) -> None:
    if not (text.isascii() and name.isascii()):
        assert not _normalise1._absent(name, text)
    # the long s and the Kelvin sign match 's' and 'k' with re.IGNORECASE: never skipped
    assert re.search("sk", "\u017f\u212a", re.IGNORECASE) is not None
    assert not _normalise1._absent("sk", "\u017f\u212a")


def test_people_skips_a_name_the_text_lacks(monkeypatch: pytest.MonkeyPatch) -> None:
    text, lexicon = next((t, lx) for t, lx in _ENTRIES if "Mr Lee" in t)
    tried: list[str] = []
    real = _normalise1._sub

    def spy(pattern: str, repl: object, said: str) -> str:
        tried.append(pattern)
        return real(pattern, repl, said)  # type: ignore[arg-type]

    monkeypatch.setattr(_normalise1, "_sub", spy)
    _normalise1._people("give the jug to the nurse", lexicon)
    assert not any("Lee" in p for p in tried)  # no 'Mr Lee' pattern for a text without 'Lee'
    tried.clear()
    _normalise1._people(text, lexicon)
    assert any("Lee" in p for p in tried)


def test_fillers_ask_the_unknown_word_test_only_before_a_place_word(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    asked: list[str] = []
    real = _normalise1._unknown_word

    def spy(word: str, lexicon: Lexicon) -> bool:
        asked.append(word)
        return real(word, lexicon)

    lexicon = _ENTRIES[0][1]
    monkeypatch.setattr(_normalise1, "_unknown_word", spy)
    _normalise1._fillers19("give zorp the blarg cup please", lexicon)
    assert "zorp" not in asked and "blarg" not in asked
    asked.clear()
    _normalise1._fillers19("put the cup aloft on the shelf", lexicon)
    assert "aloft" in asked


def test_names_kept_per_text_are_what_lexing_names() -> None:
    for text, lexicon in _ENTRIES[::7]:
        for said in (text, text.split(",")[0], "the " + text.split(" ")[-1]):
            first = _normalise1._names(said, lexicon)
            assert first == _normalise1._names_now(said, lexicon)
            again = _normalise1._names(said, lexicon)
            assert again == first and again is not first  # a list of its own each time
            again.clear()
            assert _normalise1._names(said, lexicon) == first


def test_gated_passes_give_what_the_passes_give_at_every_step() -> None:
    gated = [step for step in phrasing._PASSES if hasattr(step, "__wrapped__")]
    assert len(gated) >= 8
    skipped = 0
    for text, lexicon in _ENTRIES:
        try:
            items = lex(text, lexicon)
        except GroundingError:
            continue
        for step in phrasing._PASSES:
            plain = getattr(step, "__wrapped__", step)
            outcomes: list[object] = []
            for run in (plain, step):
                try:
                    outcomes.append(run(list(items), lexicon))
                except GroundingError as exc:
                    outcomes.append(f"refused: {exc}")
            assert outcomes[0] == outcomes[1], (text, plain)
            refused = isinstance(outcomes[0], str)  # (a gated pass may refuse: session 45)
            if plain is not step and not refused and step(items, lexicon) is items:
                skipped += 1
            if isinstance(outcomes[0], str):
                break
            items = outcomes[0]  # type: ignore[assignment]
    assert skipped > 1000  # the gates do skip
