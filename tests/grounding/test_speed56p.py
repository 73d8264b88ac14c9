"""Session 56 (12p): loops over a module's patterns read by the step guard, and _said14 split in
its place so that its word-gated parts are guarded: each answering as before, on every text."""

from __future__ import annotations

import re
from collections.abc import Callable
from functools import cache

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.bench.grounding import CORPUS_DIR, load_corpus
from hltl.errors import GroundingError
from hltl.grounding import _normalise1 as n1
from hltl.grounding import _normalise2 as n2
from hltl.grounding import _normalise3 as n3
from hltl.grounding import (
    _rewrites41,
    _rewrites42,
    _rewrites43s,
    _rewrites44,
    _rewrites48r,
    _rewrites49,
    _rewrites54,
    _step_guards,
    normalise,
    stepguard,
)
from hltl.grounding._normalise1 import _rx
from hltl.grounding.lexicon import Lexicon
from hltl.world.scene import Scene
from tests.grounding.helpers import CELL, OFFICE, ROOT, WARD, WORKSHOP

_Step = Callable[[str, Lexicon], str]

# sentences the steps below rewrite (their sessions' tests), some spaced oddly
_REWRITTEN = (
    "Do me a favour and give Bob the cup.",
    "Bob could do with the crisps.",
    "Alice will be wanting the bottle, bless her.",
    "Person A is wanting that you give her the water bottle",
    "Give the chips to her, Alice I mean",
    "A mug for Carol, any colour.",
    "The bottle is Bob's.",
    "Carol, the crisps are yours.",
    "Per Alice's request, give her the bottle",
    ". . give Bob the   crisps , like I said",
    "Bob ordered the bottle.",
    "Bob's request: the crisps",
    "Request from Alice: one bottle",
    "Prithee, wouldst thou bear the bottle unto Alice?",
    "Could you see that the crisps reach Bob?",
    "Bob has his heart set on the crisps.",
    "Alice keeps asking for the bottle, give her the chips.",
    "Carol could murder the crisps.",
    "The bottle is meant for Bob.",
    "The crisps to Bob, the poor thing's starving.",
    "Excuse me, could I trouble you to give Alice the bottle?",
    "Sorry about the wait: the crisps to Bob.",
    "The manager sends her regards. Give Alice the bottle.",
    "Merci, which is thanks in French. The bottle to Carol.",
    "Could you spare a minute to give Carol the bottle?",
    "With all due respect, the bottle to Alice, thanking you.",
    "Excuse the mess, the chips to Bob",
    "Put the crisps on the table before it gets knocked over.",
    "Alice requires the bottle for the last of the parcels.",
    "The chips for Person B, oh no hang on, the bottle for Person B.",
    "Give Carol the chips, the bottle on the table for Bob.",
    "The fizzy stuff, the bottle, should go to Bob.",
)


@cache
def _sentences() -> tuple[tuple[str, Scene], ...]:
    out: list[tuple[str, Scene]] = []
    for part in ("tuning", "blind22", "blind52", "blind54", "causes15"):
        corpus = load_corpus(ROOT / CORPUS_DIR / f"{part}.yaml", ROOT)
        out += [(e.text, corpus.scenes[e.scene]) for e in corpus.entries[::2]]
    for scene in (CELL, WORKSHOP, OFFICE, WARD):
        out += [(t, scene) for t in _REWRITTEN]
    return tuple(out)


def _answer(step: _Step, text: str, scene: Scene) -> str:
    try:
        return step(text, Lexicon.of(scene))
    except GroundingError as refused:
        return f"refused: {refused}"


# -- the steps guarded since the reader reads their loops, or their tuple is the module's --------

_NOW_GUARDED: tuple[_Step, ...] = (
    _rewrites41._courtesy41,
    _rewrites42._courtesy42,
    _rewrites42._ask_forms42,
    _rewrites44._courtesy44,
    _rewrites44._ask_forms44,
    n2._idioms32,
    n2._idioms33,
    n2._idioms34,
    n3._remarks28r,
    n2._archaic19,
    n1._said14,
    n1._wants14_56p,
    n1._a_kind_for,
    n1._wanting_that,
    n1._possessed14,
    # an f-string in any(), a count test (below)
    _rewrites54._before_gets54,
    _rewrites49._last_of49,
    _rewrites48r._said_again_for48r,
    _rewrites43s._placed_for43s,
    n2._described29,
)


@pytest.mark.parametrize("step", _NOW_GUARDED, ids=lambda s: s.__name__)
def test_the_step_is_guarded_and_changes_nothing_its_guard_turns_away(step: _Step) -> None:
    entry = stepguard.read_guard(step)
    assert entry is not None
    assert stepguard.guards((step,), _step_guards.GUARDS) == (entry[1],)
    for text, scene in _sentences():
        if not stepguard.may_act(entry[1], text, text.lower(), text.isascii()):
            assert _answer(step, text, scene) == text, text


def test_the_guarded_steps_rewrite_some_sentences() -> None:
    """Not vacuous: each step above rewrites some of the sentences."""
    for step in _NOW_GUARDED:
        if step is n1._said14:
            continue  # its drops leave spacing to the step after it: asked below
        assert any(_answer(step, t, s) != t for t, s in _sentences()), step.__name__


# -- _said14 in seven steps ----------------------------------------------------------------------


def _said14_as_it_was(text: str, lexicon: Lexicon) -> str:
    """_said14 as one step (session 55's)."""
    re = n1.re
    for pattern, repl in n1._SAID14:
        text = n1._drop(pattern, text, lexicon, repl)
    text = " ".join(text.split()).strip()
    text = re.sub(r"^[.\s]+", "", text)
    for pattern, repl in n1._WANTS14:
        m = re.search(pattern, text, n1._F)
        if m is None:
            continue
        if pattern.startswith("^((?:the )") and not n1._only(m.group(1), lexicon, "human"):
            continue
        if pattern.startswith("^(?:(?:can|could|may)") and not (
            n1._only(m.group(2), lexicon, "human")
            and n1._only_kind(m.group(1).strip(), lexicon, "object")
        ):
            continue
        text = text[: m.start()] + m.expand(repl) + text[m.end() :]
    text = re.sub(r"\bwants the the\b", "wants the", text, flags=n1._F)
    text = n1._a_kind_for(text, lexicon)
    return n1._pronoun_said(n1._possessed14(n1._wanting_that(text, lexicon), lexicon), lexicon)


_SAID14_STEPS: tuple[_Step, ...] = (
    n1._said14,
    n1._said14_spaced56p,
    n1._wants14_56p,
    n1._a_kind_for,
    n1._wanting_that,
    n1._possessed14,
    n1._pronoun_said,
)


def _said14_now(text: str, lexicon: Lexicon) -> str:
    for step in _SAID14_STEPS:
        text = step(text, lexicon)
    return text


def test_the_said14_steps_follow_one_another() -> None:
    steps = normalise._STEPS
    k = steps.index(n1._said14)
    assert steps[k : k + len(_SAID14_STEPS)] == _SAID14_STEPS
    for step in _SAID14_STEPS:
        assert steps.count(step) == 1
        assert step not in normalise._STEPS19


def test_said14_in_seven_steps_answers_as_it_did() -> None:
    changed = 0
    for text, scene in _sentences():
        want = _answer(_said14_as_it_was, text, scene)
        assert _answer(_said14_now, text, scene) == want, text
        changed += want != text
    assert changed > 40  # not vacuous


_WORDS = st.sampled_from(
    [
        *("give", "Bob", "Alice", "Carol", "the", "cup", "crisps", "bottle", "a", "mug", "for"),
        *("to", "her", "him", "you", "that", "is", "wanting", "could", "do", "with", "will"),
        *("be", "ordered", "request", "'s", "yours", "per", ",", ".", "I", "mean", "-", "one"),
        *("like", "said", "bless", "favour", "me", "and", "any", "colour", "  ", "request:"),
    ]
)


@settings(max_examples=300, deadline=None)
@given(words=st.lists(_WORDS, min_size=1, max_size=12), scene=st.sampled_from([CELL, WARD]))
def test_said14_in_seven_steps_answers_as_it_did_on_any_words(
    words: list[str], scene: Scene
) -> None:
    text = " ".join(words)
    assert _answer(_said14_now, text, scene) == _answer(_said14_as_it_was, text, scene)


def test_the_canonical_rewrite_answers_as_before(monkeypatch: pytest.MonkeyPatch) -> None:
    """The rewrites of _STEPS (their guards asked) with _said14 one step again (unguarded)."""

    def canonical(text: str, lexicon: Lexicon) -> str:
        lexicon.forget()
        return normalise.canonical(text, lexicon)

    said = _sentences()[::3]
    new = [_answer(canonical, t, s) for t, s in said]
    old: list[_Step] = []
    for step in normalise._STEPS:
        if step in _SAID14_STEPS[1:]:
            continue
        old.append(_said14_as_it_was if step is n1._said14 else step)
    monkeypatch.setattr(normalise, "_STEPS", tuple(old))
    assert [_answer(canonical, t, s) for t, s in said] == new


# -- the reader: loops over a module's patterns ---------------------------------------------------

_TOY_PAIRS = ((r"\bkindly\b", "please"), (r"\bgently\b", "softly"))
_TOY_COMPILED = (re.compile(r"\bkindly\b", re.I), re.compile(r"\bgently\b", re.I))
_TOY_COMPILED_PAIRS = ((re.compile(r"\bkindly\b", re.I), "please"), (re.compile("gently"), "x"))
_TOY_OTHER = re.compile(r"\bslowly\b")


def _toy_continue(text: str, lexicon: Lexicon) -> str:
    for pattern, said in _TOY_PAIRS:
        m = re.search(pattern, text, re.I)
        if m is None:
            continue
        text = text[: m.start()] + said + text[m.end() :]
    return text


def _toy_compiled(text: str, lexicon: Lexicon) -> str:
    for rx in _TOY_COMPILED:
        m = rx.search(text)
        if m is None or m.start() == 0:
            continue
        text += "!"
    return text


def _toy_not_none(text: str, lexicon: Lexicon) -> str:
    for pattern, said in _TOY_PAIRS:
        m = re.search(_rx(pattern), text)
        if m is not None and not text.endswith("?"):
            text = text[: m.start()] + said + text[m.end() :]
    return text


def _toy_finditer(text: str, lexicon: Lexicon) -> str:
    for rx, said in _TOY_COMPILED_PAIRS:
        for m in list(re.finditer(rx, text))[::-1]:
            text = text[: m.start()] + said + text[m.end() :]
    return text


def _toy_before(text: str, lexicon: Lexicon) -> str:
    for pattern, said in _TOY_PAIRS:
        text = text.strip() + " "  # something before the search: not read
        m = re.search(pattern, text, re.I)
        if m is None:
            continue
        text = said
    return text


def _toy_other(text: str, lexicon: Lexicon) -> str:
    for _pattern, said in _TOY_PAIRS:
        m = _TOY_OTHER.search(text)  # not the loop's pattern: not read
        if m is None:
            continue
        text = said
    return text


def _toy_break(text: str, lexicon: Lexicon) -> str:
    for pattern, _said in _TOY_PAIRS:
        m = re.search(pattern, text, re.I)
        if m is None:
            break  # not 'continue': not read
        text += "!"
    return text


def _toy_local(text: str, lexicon: Lexicon) -> str:
    pairs = _TOY_PAIRS
    for pattern, said in pairs:  # a tuple of the step's own: not read
        m = re.search(pattern, text, re.I)
        if m is None:
            continue
        text = said
    return text


def _toy_not_none_more(text: str, lexicon: Lexicon) -> str:
    for pattern, _said in _TOY_PAIRS:
        m = re.search(pattern, text, re.I)
        if m is not None:
            text += "?"
        text += "!"  # run on every text: not read
    return text


def _toy_inner_more(text: str, lexicon: Lexicon) -> str:
    for rx, _said in _TOY_COMPILED_PAIRS:
        for _m in re.finditer(rx, text):
            text += "?"
        text += "!"  # after the matches' loop, run on every text: not read
    return text


_FOLDED = ((), ("gently", "kindly"), True)


@pytest.mark.parametrize(
    ("step", "want"),
    [
        (_toy_continue, _FOLDED),
        (_toy_compiled, _FOLDED),
        (_toy_not_none, _FOLDED),
        (_toy_finditer, (("gently",), ("kindly",), True)),  # 'gently' (no flags) as it is
        (_toy_before, None),
        (_toy_other, None),
        (_toy_break, None),
        (_toy_local, None),
        (_toy_not_none_more, None),
        (_toy_inner_more, None),
    ],
    ids=lambda x: getattr(x, "__name__", "want"),
)
def test_a_loop_over_a_modules_patterns_is_read(step: _Step, want: stepguard.Guard | None) -> None:
    entry = stepguard.read_guard(step)
    assert (entry and entry[1]) == want
    if entry is None:
        return
    assert stepguard.guard(step, entry) == want
    said = ("Kindly give Alice the cup", "give Bob the cup", "go gently now", "x KINDLY", "gent")
    for text in said:
        if not stepguard.may_act(entry[1], text, text.lower(), text.isascii()):
            assert step(text, Lexicon.of(CELL)) == text
        else:
            assert step(text, Lexicon.of(CELL)) != text or text.startswith("Kindly")


@pytest.mark.parametrize(
    ("name", "value"),
    [
        ("_TOY_COMPILED", (re.compile(r"\bkindly\b", re.I),)),
        ("_TOY_COMPILED", (re.compile(r"\bkindly\b"), re.compile(r"\bgently\b", re.I))),
        ("_TOY_COMPILED", (r"\bkindly\b", r"\bgently\b")),
        ("_TOY_COMPILED", ()),
        ("_TOY_COMPILED_PAIRS", ((re.compile(r"\bkindly\b", re.I), "please"),)),
        ("_TOY_COMPILED_PAIRS", _TOY_COMPILED),
        ("_TOY_PAIRS", ((r"\bkindly\b", "please"),)),
    ],
)
def test_a_changed_tuple_of_patterns_drops_the_guard(
    monkeypatch: pytest.MonkeyPatch, name: str, value: tuple[object, ...]
) -> None:
    step = {
        "_TOY_COMPILED": _toy_compiled,
        "_TOY_COMPILED_PAIRS": _toy_finditer,
        "_TOY_PAIRS": _toy_continue,
    }[name]
    entry = stepguard.read_guard(step)
    assert entry is not None
    monkeypatch.setitem(globals(), name, value)
    assert stepguard.guard(step, entry) is None


# -- the reader: an f-string in any(), a test of a count ------------------------------------------

_TOY_WORDS = ("last", "rest")


def _toy_fstring(text: str, lexicon: Lexicon) -> str:
    if not any(f"{w} of the " in text.lower() for w in ("last", "rest")):
        return text
    return text + "!"


def _toy_fstring_module(text: str, lexicon: Lexicon) -> str:
    if not any(f"the {w} " in text for w in _TOY_WORDS):
        return text
    return text + "!"


def _toy_fstring_format(text: str, lexicon: Lexicon) -> str:
    if not any(f"{w!r} of" in text for w in ("last", "rest")):  # a conversion: not read
        return text
    return text + "!"


def _toy_fstring_other(text: str, lexicon: Lexicon) -> str:
    said = "x"
    if not any(f"{said} of" in text for _w in ("last", "rest")):  # not the loop's name
        return text
    return text + "!"


def _toy_count(text: str, lexicon: Lexicon) -> str:
    if text.count(",") < 2:
        return text
    return text + "!"


def _toy_counts(text: str, lexicon: Lexicon) -> str:
    low = text.lower()
    if low.count(" for ") + low.count(" to ") <= 1:
        return text
    return text + "!"


def _toy_count_once(text: str, lexicon: Lexicon) -> str:
    if text.lower().count(" for ") != 1:
        return text
    return text + "!"


def _toy_count_sum(text: str, lexicon: Lexicon) -> str:
    low = text.lower()
    if sum(low.count(w) for w in ("no", "sorry")) < 2:
        return text
    return text + "!"


def _toy_count_more(text: str, lexicon: Lexicon) -> str:
    if text.count(",") > 1:  # true only where a comma is: 'return text' where it is not read
        return text
    return text + "!"


def _toy_count_zero(text: str, lexicon: Lexicon) -> str:
    if text.count(",") < 0:  # never true: not read
        return text
    return text + "!"


def _toy_count_plus(text: str, lexicon: Lexicon) -> str:
    if text.count(",") + 1 < 2:  # not only counts: not read
        return text
    return text + "!"


@pytest.mark.parametrize(
    ("step", "want"),
    [
        (_toy_fstring, ((), ("last of the ", "rest of the "), False)),
        (_toy_fstring_module, (("the last ", "the rest "), (), False)),
        (_toy_fstring_format, None),
        (_toy_fstring_other, None),
        (_toy_count, ((",",), (), False)),
        (_toy_counts, ((), (" for ", " to "), False)),
        (_toy_count_once, ((), (" for ",), False)),
        (_toy_count_sum, ((), ("no", "sorry"), False)),
        (_toy_count_more, None),
        (_toy_count_zero, None),
        (_toy_count_plus, None),
    ],
    ids=lambda x: getattr(x, "__name__", "want"),
)
def test_an_fstring_in_any_and_a_count_are_read(step: _Step, want: stepguard.Guard | None) -> None:
    entry = stepguard.read_guard(step)
    assert (entry and entry[1]) == want
    if entry is None:
        return
    assert stepguard.guard(step, entry) == want
    said = (
        "Give the last of the crisps to Bob, the rest of the apples to Alice, thanks",
        "the rest for Bob, for Alice, to Carol",
        "No, sorry, no",
        "give Bob the cup",
        "for Bob",
        "the cup for Bob",
    )
    for text in said:
        if not stepguard.may_act(entry[1], text, text.lower(), text.isascii()):
            assert step(text, Lexicon.of(CELL)) == text
    assert any(step(t, Lexicon.of(CELL)) != t for t in said)  # not vacuous


def test_a_changed_tuple_of_fstring_words_drops_the_guard(monkeypatch: pytest.MonkeyPatch) -> None:
    entry = stepguard.read_guard(_toy_fstring_module)
    assert entry is not None
    monkeypatch.setitem(globals(), "_TOY_WORDS", ("last",))
    assert stepguard.guard(_toy_fstring_module, entry) is None
