"""Session 55 (12p): steps split so that stepguard guards them, steps guarded by their tuples of
words, and _fillers19's word test, each answering as the code it replaced, on every text."""

from __future__ import annotations

from collections.abc import Callable
from functools import cache

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.bench.grounding import CORPUS_DIR, load_corpus
from hltl.errors import GroundingError
from hltl.grounding import _normalise1 as n1
from hltl.grounding import _normalise3 as n3
from hltl.grounding import (
    _rewrites53s,
    _rewrites54,
    _rewrites54r,
    _step_guards,
    normalise,
    stepguard,
)
from hltl.grounding._rewrites54r import _says54r
from hltl.grounding.lexicon import Lexicon
from hltl.world.scene import Scene
from tests.grounding.helpers import CELL, OFFICE, ROOT, WARD, WORKSHOP

_Step = Callable[[str, Lexicon], str]

# the steps whose single spacing is now the step after them (_spaced55p)
_SPLIT: tuple[_Step, ...] = (n1._courtesy, n1._courtesy14, n1._courtesy_frames)

# sentences the three steps rewrite (their sessions' tests), some spaced oddly
_REWRITTEN = (
    "Be an angel and give Bob the apple, thanks so much.",
    "If you wouldn't mind, the cup to Alice.",
    "No rush, but  the crisps to Bob.",
    "Is it possible for Alice to have the apple?",
    "Alice is on the phone but she needs the cup",
    "If it's no bother, the bottle to Alice, nice one.",
    "Sorry to interrupt, you're a lifesaver, the apple to Bob.",
    "Love, the cup for Alice",
    "The chips to Bob , good man .",
    "Next one on my list: the apple to Alice.",
    "Yes chef! The cup to Bob.",
    "Two apples up! Apple to Alice, apple to Bob.",
    "  thanks a million,   the   cup to Alice  ",
    "Cheers, pal.",
)


@cache
def _sentences() -> tuple[tuple[str, Scene], ...]:
    out: list[tuple[str, Scene]] = []
    for part in ("tuning", "blind22", "blind52", "blind53", "causes15"):
        corpus = load_corpus(ROOT / CORPUS_DIR / f"{part}.yaml", ROOT)
        out += [(e.text, corpus.scenes[e.scene]) for e in corpus.entries[::2]]
    for scene in (CELL, WORKSHOP, OFFICE):
        out += [(t, scene) for t in _REWRITTEN]
    return tuple(out)


def _answer(step: _Step, text: str, scene: Scene) -> str:
    try:
        return step(text, Lexicon.of(scene))
    except GroundingError as refused:
        return f"refused: {refused}"


def _canonical(text: str, lexicon: Lexicon) -> str:
    """normalise.canonical of ``text``, nothing kept from a text before (as a new instruction)."""
    lexicon.forget()
    return normalise.canonical(text, lexicon)


def _spaced_as_it_was(step: _Step) -> _Step:
    """``step`` as it was before session 55: its text single-spaced at the end."""

    def joined(text: str, lexicon: Lexicon) -> str:
        return " ".join(step(text, lexicon).split())

    return joined


def test_each_split_step_has_its_spacing_after_it() -> None:
    steps = normalise._STEPS
    for step in _SPLIT:
        assert steps[steps.index(step) + 1] is n1._spaced55p
    assert steps.count(n1._spaced55p) == len(_SPLIT)


@pytest.mark.parametrize("step", _SPLIT, ids=lambda s: s.__name__)
def test_the_split_step_is_guarded(step: _Step) -> None:
    entry = stepguard.read_guard(step)
    assert entry is not None
    assert stepguard.guards((step,), _step_guards.GUARDS) == (entry[1],)


@pytest.mark.parametrize("step", _SPLIT, ids=lambda s: s.__name__)
def test_the_split_step_changes_nothing_its_guard_turns_away(step: _Step) -> None:
    entry = stepguard.read_guard(step)
    assert entry is not None
    away = 0
    for text, scene in _sentences():
        if not stepguard.may_act(entry[1], text, text.lower(), text.isascii()):
            away += 1
            assert _answer(step, text, scene) == text
    assert away > 50  # not vacuous


def test_the_canonical_rewrite_answers_as_before(monkeypatch: pytest.MonkeyPatch) -> None:
    """The rewrites of _STEPS (their guards asked) with each split step and its spacing as one
    step again (unguarded, as before)."""
    new = [_answer(_canonical, t, s) for t, s in _sentences()]
    old: list[_Step] = []
    for step in normalise._STEPS:
        if step is n1._spaced55p:
            continue
        old.append(_spaced_as_it_was(step) if step in _SPLIT else step)
    monkeypatch.setattr(normalise, "_STEPS", tuple(old))
    assert [_answer(_canonical, t, s) for t, s in _sentences()] == new
    assert sum(a != t for a, (t, _) in zip(new, _sentences(), strict=True)) > 50  # not vacuous


def test_the_split_steps_rewrite_some_sentences() -> None:
    """Not vacuous: each split step rewrites some of the sentences above."""
    for step in _SPLIT:
        assert any(_answer(step, t, s) != t for t, s in _sentences()), step.__name__


# -- _fillers19: a word none of its tests can take off, kept at once (session 55) ---------------


def _fillers19_as_it_was(text: str, lexicon: Lexicon) -> str:
    """_fillers19 of session 54."""
    re = n1.re
    out = text
    if not n1._TIMED19.search(out):
        out = n1._NOW19.sub("", out)
    words = out.split(" ")
    lead = 0
    while lead < len(words) - 2 and words[lead].lower() in n1._INTERJECTION19 - n1._ADDRESS:
        if n1._held_word(words[lead], lexicon) or words[lead].lower() in ("please", "and", "so"):
            break
        lead += 1
    if lead and (words[lead].lower() in n1._DETERMINER19 or words[lead].lower() in n1.VERBS):
        words = words[lead:]
    kept: list[str] = []
    for k, w in enumerate(words):
        core = w.strip('.,;:!?"')
        low = core.lower()
        prev = words[k - 1].lower().strip(",;:") if k else ""
        last = k + 1 == len(words) or w[-1:] in ",;:.!?"
        glued = low in n1._PARTICLES and k > 0 and prev[-1:] not in (",", ";", ":")
        loose = (
            0 < k < len(words) - 1
            and words[k + 1].lower() in ("on", "onto", "to", "in", "into", "over")
            and n1._unknown_word(core, lexicon)
            and n1._ends_object(" ".join(words[:k]), lexicon)
        )
        if (
            core
            and (glued or loose or n1._manner(core, lexicon))
            and (prev not in n1._DETERMINER19 or last)
        ):
            tail = w[len(w.rstrip('.,;:!?"')) :]
            if tail and kept:
                kept[-1] = kept[-1].rstrip(",;:") + tail
            continue
        kept.append(w)
    out = " ".join(kept)
    parts = n1._STRETCH.split(out.strip())
    chunks, seps = parts[0::2], parts[1::2]
    asks = "?" in out and not re.match(r"^(?:could|can|would|will|may|might|is it)\b", out, n1._F)
    if (
        len(chunks) < 2
        or asks
        or n1._rx(
            r"\b(?:no|sorry|actually|wait|i mean|hang on|hold on|scratch|strike|correction|rather|"
            r"oops|whoops|i tell a lie|my mistake|my bad)\b"
        ).search(out)
    ):
        return n1._tidy19(out)
    drop = []
    for k, c in enumerate(chunks):
        prev = chunks[k - 1] if k else ""
        prev_sep = seps[k - 1] if k else "."
        after_object = (
            k > 0 and prev_sep.strip()[:1] not in (".", "!", "?") and n1._ends_object(prev, lexicon)
        )
        drop.append(bool(c.strip()) and n1._filler_stretch(c, after_object, lexicon))
    if not any(drop) or all(d or not c.strip() for d, c in zip(drop, chunks, strict=True)):
        return n1._tidy19(out)
    return n1._joined19(chunks, seps, drop)


def test_fillers19_answers_as_it_did() -> None:
    for text, scene in _sentences():
        want = _answer(_fillers19_as_it_was, text, scene)
        assert _answer(n1._fillers19, text, scene) == want, text


def test_fillers19_rewrites_some_sentences() -> None:
    """Not vacuous."""
    assert sum(_answer(n1._fillers19, t, s) != t for t, s in _sentences()) > 20


_WORDS = st.sampled_from(
    [
        *("the", "a", "my", "cup", "apple", "Bob", "Alice", "Person", "B", "give", "pass", "to"),
        *("on", "onto", "in", "into", "over", "shelf", "table", "gently", "quickly", "Kindly"),
        *("only", "ugly", "early", "holly", "lah", "la", "innit", "ah", "po", "aye", "oi", "yo"),
        *("right", "now", "asap", "cheers", "blorp", "aloft", "please", "and", "so", "sorry"),
        *("Ly", "ly", "LAH", "bed", "ward", "nurse", "Ruth", "Mr", "Lee"),
    ]
)
_MARKS = st.sampled_from(["", "", "", ",", ".", "!", "?", ";", ":", '"', "'s"])


@settings(max_examples=1500, deadline=None)
@given(
    st.lists(st.tuples(_WORDS, _MARKS).map("".join), min_size=1, max_size=9),
    st.sampled_from([CELL, WARD, WORKSHOP]),
)
def test_fillers19_answers_as_it_did_on_any_words(words: list[str], scene: Scene) -> None:
    text = " ".join(words)
    assert _answer(n1._fillers19, text, scene) == _answer(_fillers19_as_it_was, text, scene)


# -- stepguard reads a module's tuple of words and _says54r (session 55) ------------------------

_TOY_WORDS = ("kindly", "gently")
_TOY_MIXED = ("kindly", 3)


def _toy_any(text: str, lexicon: Lexicon) -> str:
    low = text.lower()
    if not any(w in low for w in _TOY_WORDS):
        return text
    return text + "!"


def _toy_any_local(text: str, lexicon: Lexicon) -> str:
    words = ("kindly", "gently")
    low = text.lower()
    if not any(w in low for w in words):  # a tuple of the step's own: not read
        return text
    return text + "!"


def _toy_any_mixed(text: str, lexicon: Lexicon) -> str:
    low = text.lower()
    if not any(w in low for w in _TOY_MIXED):  # not only strings: not read
        return text
    return text + "!"


def _toy_says(text: str, lexicon: Lexicon) -> str:
    if not _rewrites54r._says54r(text, "kindly", " gently "):  # a module's attribute: not read
        return text
    return text + "!"


def _toy_says_named(text: str, lexicon: Lexicon) -> str:
    if not _says54r(text, "kindly", " gently "):
        return text
    return text + "!"


def _toy_says_starred(text: str, lexicon: Lexicon) -> str:
    if not _says54r(text, *_TOY_WORDS):  # starred: not read
        return text
    return text + "!"


@pytest.mark.parametrize(
    ("step", "want"),
    [
        (_toy_any, ((), ("gently", "kindly"), False)),
        (_toy_any_local, None),
        (_toy_any_mixed, None),
        (_toy_says, None),
        (_toy_says_named, ((), (" gently ", "kindly"), False)),
        (_toy_says_starred, None),
    ],
    ids=lambda x: getattr(x, "__name__", "want"),
)
def test_a_tuple_of_words_and_says54r_are_read(step: _Step, want: stepguard.Guard | None) -> None:
    entry = stepguard.read_guard(step)
    assert (entry and entry[1]) == want
    if entry is not None:
        assert stepguard.guard(step, entry) == want
        for text in ("Kindly give Alice the cup", "give Bob the cup", "go gently now", "KINDLY"):
            if not stepguard.may_act(entry[1], text, text.lower(), text.isascii()):
                assert step(text, Lexicon.of(CELL)) == text
            else:
                assert step(text, Lexicon.of(CELL)) != text


def test_a_changed_tuple_of_words_drops_the_guard(monkeypatch: pytest.MonkeyPatch) -> None:
    entry = stepguard.read_guard(_toy_any)
    assert entry is not None
    monkeypatch.setitem(globals(), "_TOY_WORDS", ("kindly",))
    assert stepguard.guard(_toy_any, entry) is None


# the steps guarded since the reader reads their words (session 53 and 54 rules)
_NOW_GUARDED = (
    _rewrites54._grand54,
    _rewrites54._craving54,
    _rewrites54._over_goes54,
    _rewrites53s._all_for53s,
    _rewrites53s._claimed53s,
    _rewrites54r._stacked54r,
    _rewrites54r._at_her54r,
    _rewrites54r._likes_to54r,
    _rewrites54r._having_lot54r,
    _rewrites54r._only_one54r,
)


@pytest.mark.parametrize("step", _NOW_GUARDED, ids=lambda s: s.__name__)
def test_the_step_is_guarded_and_changes_nothing_its_guard_turns_away(step: _Step) -> None:
    entry = stepguard.read_guard(step)
    assert entry is not None
    assert stepguard.guards((step,), _step_guards.GUARDS) == (entry[1],)
    for text, scene in _sentences():
        if not stepguard.may_act(entry[1], text, text.lower(), text.isascii()):
            assert _answer(step, text, scene) == text


# -- _words split in four steps; _word_edges18 asks idioms only where one may be (session 55) ----


def _words_as_it_was(text: str, lexicon: Lexicon) -> str:
    """_words as one step (session 54's, with the lead's session-55 branch for 'for his X')."""
    re = n1.re
    for pattern, repl in n1._WORDS:
        text = n1._sub(pattern, repl, text)
    text = n1._sub(n1._REFLEXIVE, lambda m: "" if n1._person_before(m, lexicon) else m[0], text)
    for pattern, repl in n1._WORDS_LATE:
        if pattern is n1._FOR_THEIRS:  # the lead's session-55 branch
            text = n1._sub(pattern, lambda m: m[0] if n1._a_thing(m[1], lexicon) else "", text)
        else:
            text = n1._sub(pattern, repl, text)
    sentences = re.split(r"(?<=[.;!?])\s+", text)
    for n, s in enumerate(sentences):
        m = re.search(r"\bends? up with\b", s, n1._F)
        if m is not None and not n1._person_ends_up36s(s[m.end() :], lexicon):
            s = n1._sub(r"\bends? up with\b", "go to", s)
            sentences[n] = n1._sub(r"\bwith\b", "to", s)
    text = " ".join(sentences)
    given = re.search(r"\b(?:give|hand|pass|bring|take|fetch|get)\b", text, n1._F)
    for h in [] if given else lexicon.scene.humans:
        for alias in (*h.aliases, h.name):
            text = n1._sub(
                rf"\b(the \w+(?: \w+)?) with ({re.escape(alias)})(?=\s*(?:[.,;!?]|\band\b|$))",
                lambda m: (
                    f"{m.group(1)} to {m.group(2)}"
                    if n1._only(m.group(1), lexicon, "object")
                    else m.group(0)
                ),
                text,
            )
    return text


_WORDS_STEPS: tuple[_Step, ...] = (
    n1._words,
    n1._words_spaced55p,
    n1._ends_up_with55p,
    n1._left_with55p,
)


def _words_now(text: str, lexicon: Lexicon) -> str:
    for step in _WORDS_STEPS:
        text = step(text, lexicon)
    return text


# sentences _words rewrites (its sessions' tests), some spaced oddly
_WORDS_SAID = (
    "The apple should end up with Alice, and the cup with Bob.",
    "The cup ends up with Bob.   The apple to Alice.",
    "The apple with Alice and the cup with Bob.",
    "the crisps with Person B, the cup with Person A",
    "The cup for Bob himself.",
    "Alice can get it herself.",
    "Give Bob the cup with Alice.",
    "The chips end up with Bob!  Then  the apple to Alice;   thanks",
    "The APPLE WITH ALICE.",
)


def test_the_words_steps_follow_one_another() -> None:
    steps = normalise._STEPS
    k = steps.index(n1._words)
    assert steps[k : k + 4] == _WORDS_STEPS


def test_words_in_four_steps_answers_as_it_did() -> None:
    said = [*_sentences(), *((t, s) for t in _WORDS_SAID for s in (CELL, WORKSHOP, WARD))]
    changed = 0
    for text, scene in said:
        want = _answer(_words_as_it_was, text, scene)
        assert _answer(_words_now, text, scene) == want, text
        changed += want != text
    assert changed > 20  # not vacuous


# (_words itself is not read since the lead's branch in its loop: it runs on every text, as before)
@pytest.mark.parametrize("step", [n1._ends_up_with55p, n1._left_with55p], ids=lambda s: s.__name__)
def test_the_words_steps_with_a_guard_change_nothing_it_turns_away(step: _Step) -> None:
    entry = stepguard.read_guard(step)
    assert entry is not None
    assert stepguard.guards((step,), _step_guards.GUARDS) == (entry[1],)
    away = 0
    for text, scene in (*_sentences(), *((t, CELL) for t in _WORDS_SAID)):
        if not stepguard.may_act(entry[1], text, text.lower(), text.isascii()):
            away += 1
            assert _answer(step, text, scene) == text
    assert away > 20  # not vacuous


def _word_edges18_as_it_was(text: str, lexicon: Lexicon) -> str:
    """_word_edges18 of session 54."""
    chat, idiom = n3._chat_token, n1._word_idiom
    words = text.split()
    if len(words) < 3:
        return text
    start, stop = 0, len(words)
    for _ in range(4):
        moved = False
        for n in (5, 4, 3, 2, 1):
            if stop - start - n < 2:
                continue
            tail = " ".join(words[stop - n : stop])
            bare = tail.strip(" .!?,").lower()
            if (n == 1 and chat(bare, lexicon)) or idiom(tail, lexicon):
                stop -= n
                moved = True
                break
        for n in (5, 4, 3, 2, 1):
            if stop - start - n < 2:
                continue
            head = " ".join(words[start : start + n])
            bare = head.strip(" .!?,").lower()
            if (n == 1 and chat(bare, lexicon)) or idiom(head, lexicon):
                start += n
                moved = True
                break
        if not moved:
            break
    if (start, stop) == (0, len(words)):
        return text
    while stop - start > 2 and words[stop - 1].lower() in ("and", "so"):
        stop -= 1
    end = words[-1][-1] if words[-1][-1] in ".!?" else ""
    return " ".join(words[start:stop]).rstrip(",;:") + end


_EDGES_SAID = (
    "lmao ok give person b the bottle lol tysm",
    "hiya give Bob the cup rn",
    "the apple to Alice when u get a chance",
    "good morning the cup to Bob cheers",
    "the cup to Alice when you're free thanks",
    "Howdy partner, the apple to Bob",
    "the crisps to Bob asap and so",
    "Give Bob the cup, thanks so much, much appreciated",
)


def test_word_edges18_answers_as_it_did() -> None:
    said = [*_sentences(), *((t, s) for t in _EDGES_SAID for s in (CELL, WORKSHOP))]
    changed = 0
    for text, scene in said:
        want = _answer(_word_edges18_as_it_was, text, scene)
        assert _answer(n3._word_edges18, text, scene) == want, text
        changed += want != text
    assert changed >= 5  # not vacuous


_EDGE_WORDS = st.sampled_from(
    [
        *("give", "Bob", "the", "cup", "to", "Alice", "apple", "lol", "ok", "tysm", "rn", "asap"),
        *("hiya", "cheers", "thanks", "when", "u", "you", "get", "a", "chance", "free", "ur"),
        *("good", "morning", "howdy", "partner", "and", "so", "pls", "thx", "ta", "xx", "mate"),
        *("Roger", "that", "copy", "g'day", "ahoy", "there", "kia", "ora", "bye", "é", "K"),
    ]
)


@settings(max_examples=1500, deadline=None)
@given(
    st.lists(st.tuples(_EDGE_WORDS, _MARKS).map("".join), min_size=1, max_size=9),
    st.sampled_from([CELL, WORKSHOP]),
)
def test_word_edges18_answers_as_it_did_on_any_words(words: list[str], scene: Scene) -> None:
    text = " ".join(words)
    assert _answer(n3._word_edges18, text, scene) == _answer(_word_edges18_as_it_was, text, scene)


def test_most_texts_can_hold_no_idiom_of_words() -> None:
    """Not vacuous: _word_edges18 asks only for chat tokens on most texts, and for idioms where
    one may be."""
    texts = [" ".join(t.split()) for t, _ in _sentences()]
    assert sum(not n1._word_idiom_may(t) for t in texts) > len(texts) // 2
    assert all(n1._word_idiom_may(t) for t in _EDGES_SAID[:4])
