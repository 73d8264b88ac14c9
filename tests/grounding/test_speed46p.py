"""Session 46 (12p): cheaper ways to the same answers in helpers the always-run steps ask of every
text — _person_alt35t and _scene_words29 built once per lexicon, _remark29's cheap test asked
first, _near_verb and _near_keywords comparing only words of a near length. Each is checked
against the way it was computed before (kept here), over the corpus's scenes and sentences and
random words."""

from __future__ import annotations

import re
import string
from functools import cache

from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.bench.grounding import CORPUS_DIR, load_corpus
from hltl.grounding import _normalise1, _normalise2, _normalise4, lexicon
from hltl.grounding.lexicon import VERBS, Lexicon
from hltl.world.scene import Scene
from tests.grounding.helpers import ROOT, SCENES


@cache
def _corpus() -> tuple[tuple[str, Scene], ...]:
    out: list[tuple[str, Scene]] = []
    for part in ("tuning", "blind42", "blind44"):
        corpus = load_corpus(ROOT / CORPUS_DIR / f"{part}.yaml", ROOT)
        out += [(e.text, corpus.scenes[e.scene]) for e in corpus.entries]
    return tuple(out)


@cache
def _scenes() -> tuple[Scene, ...]:
    seen: dict[int, Scene] = {}
    for _, scene in _corpus():
        seen.setdefault(id(scene), scene)
    return (*SCENES, *seen.values())


def test_the_scene_helpers_kept_per_lexicon_are_what_they_build() -> None:
    for scene in _scenes():
        lex = Lexicon.of(scene)
        assert _normalise4._person_alt35t(lex) == _normalise4._person_alt35t.__wrapped__(lex)
        assert _normalise2._scene_words29(lex) == _normalise2._scene_words29.__wrapped__(lex)
        assert _normalise4._person_alt35t(lex) is _normalise4._person_alt35t(lex)


def _remark29_before(words: str, lex: Lexicon, opener: str) -> bool:
    """_remark29 as it was before session 46."""
    low = words.strip().lower()
    opens = bool(opener) and low.startswith(opener)
    rest = low[len(opener) :] if opens else low
    if (
        re.match(r"(?:and|or|plus|with|also|then)\b", low)
        or re.search(r"\bfor\b", rest)
        or not _normalise2._asks_nothing29(words, lex)
    ):
        return False
    return opens or bool(_normalise2._STATEMENT29.search(words))


@cache
def _pieces() -> tuple[tuple[str, Scene], ...]:
    """Sentences and comma parts of the corpus, as _remarks29 asks _remark29 of them."""
    out: list[tuple[str, Scene]] = []
    for text, scene in _corpus():
        for sent in re.split(r"\s*[.!?;:]+\s*", text):
            out += [(sent, scene), *((p, scene) for p in re.split(r"\s*,\s*", sent))]
    return tuple(out)


@settings(max_examples=200, deadline=None)
@given(
    st.sampled_from(_pieces()),
    st.sampled_from(["", "for ", "back to "]),
    st.sampled_from(["", "for ", "back to ", "it's ", "and "]),
)
def test_remark29_asks_its_cheap_test_first_and_answers_as_before(
    said: tuple[str, Scene], opener: str, lead: str
) -> None:
    words, scene = said
    words = lead + words
    lex = Lexicon.of(scene)
    assert _normalise2._remark29(words, lex, opener) == _remark29_before(words, lex, opener)


def test_remark29_on_every_piece_of_the_corpus() -> None:
    for words, scene in _pieces()[::7]:
        lex = Lexicon.of(scene)
        for opener in ("", "for ", "back to "):
            assert _normalise2._remark29(words, lex, opener) == _remark29_before(words, lex, opener)


def _near_verb_before(word: str) -> bool:
    for verb in VERBS:
        if abs(len(verb) - len(word)) > 1 or " " in verb:
            continue
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


def _near_keywords_before(word: str) -> tuple[str, ...]:
    if len(word) < 3 or not word.isalpha():
        return ()
    near = [k for k in lexicon._keywords() if lexicon._one_edit(word, k)]
    if len(word) == 3:
        near = [k for k in near if (len(k) == 3 and sorted(k) == sorted(word)) or len(k) == 4]
    return tuple(near)


@cache
def _known() -> tuple[str, ...]:
    return tuple(sorted({*lexicon._keywords(), *(v for v in VERBS if " " not in v)}))


@st.composite
def _words(draw: st.DrawFn) -> str:
    """A keyword or verb with up to two edits, or letters at random."""
    word = draw(st.sampled_from(_known()))
    for _ in range(draw(st.integers(0, 2))):
        k = draw(st.integers(0, len(word)))
        letter = draw(st.sampled_from(string.ascii_lowercase + "'"))
        edit = draw(st.integers(0, 3))
        if edit == 0:
            word = word[:k] + letter + word[k:]
        elif edit == 1:
            word = word[:k] + word[k + 1 :]
        elif edit == 2:
            word = word[:k] + letter + word[k + 1 :]
        elif k + 1 < len(word):
            word = word[:k] + word[k + 1] + word[k] + word[k + 2 :]
    random = st.text(alphabet=string.ascii_lowercase + "' ", min_size=0, max_size=9)
    return draw(st.one_of(st.just(word), random))


@settings(max_examples=200, deadline=None)
@given(_words())
def test_the_near_words_are_those_found_comparing_every_word(word: str) -> None:
    assert _normalise1._near_verb.__wrapped__(word) == _near_verb_before(word)
    assert lexicon._near_keywords.__wrapped__(word) == _near_keywords_before(word)


def test_the_near_words_of_every_keyword_and_verb() -> None:
    for word in {*lexicon._keywords(), *VERBS}:
        for said in (word[1:],):
            assert _normalise1._near_verb.__wrapped__(said) == _near_verb_before(said)
            assert lexicon._near_keywords.__wrapped__(said) == _near_keywords_before(said)
