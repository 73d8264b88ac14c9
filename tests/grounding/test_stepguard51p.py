"""Session 51 (12p): stepguard reads five more shapes of a step's statements — a match bound
only where a test holds ('m = P.search(text) if "w" in text.lower() else None'), a return that
is the text on one side of a test ('return X if T else text', 'return text if T else X'),
startswith / endswith of a tuple of words, and stretches of the text ('text[:40].lower()',
'text.rstrip(" .!")') in 'in', '==' and '!=' tests. A step read so is turned away only where it
leaves the text as it is (hand-made steps of each shape, and every corpus step so read, asked of
corpus sentences); a shape it cannot be sure of has no guard. And the step index (keyed by each
word's rarest three letters, its picks kept per text) picks what the loop over every guard picks,
from a text met before too."""

from __future__ import annotations

import contextlib
from collections.abc import Callable
from functools import cache

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.bench.grounding import CORPUS_DIR, load_corpus
from hltl.errors import GroundingError
from hltl.grounding import _normalise1, gate, normalise, stepguard
from hltl.grounding._normalise1 import _F, _sub
from hltl.grounding._step_guards import GUARDS
from hltl.grounding.lexicon import Lexicon
from hltl.world.scene import Scene
from tests.grounding.helpers import ROOT, SCENES

_Step = Callable[[str, Lexicon], str]

_CUE51P = gate.compile(r"\bno wait\b", _F)

# -- the shapes read -----------------------------------------------------------------------------


def _match_if_word(text: str, lexicon: Lexicon) -> str:
    m = _CUE51P.search(text) if "wait" in text.lower() else None
    if m is None:
        return text
    return text.upper()


def _match_if_either(text: str, lexicon: Lexicon) -> str:
    m = _CUE51P.search(text) if "hang" in text.lower() or "hold" in text.lower() else None
    if m is None or len(lexicon.scene.objects) > 99:
        return text
    return text.upper()


def _match_after_match(text: str, lexicon: Lexicon) -> str:
    m = _CUE51P.search(text)
    k = _CUE51P.search(text[: m.start()]) if m is not None else None
    if k is None:
        return text
    return text.upper()


def _returned_if_word(text: str, lexicon: Lexicon) -> str:
    return _sub(r"\bta\b", "thanks", text) if "ta" in text.lower() else text


def _text_if_none(text: str, lexicon: Lexicon) -> str:
    m = _CUE51P.search(text)
    return text if m is None else text.upper()


def _opens_with_any(text: str, lexicon: Lexicon) -> str:
    if not text.startswith(("Midway ", "Halfway ")):
        return text
    return text.upper()


def _ends_stripped(text: str, lexicon: Lexicon) -> str:
    if not text.rstrip(" .!").endswith((" his", " hers")):
        return text
    return text.upper()


def _opening_lowered(text: str, lexicon: Lexicon) -> str:
    if text[:5].lower() != "never":
        return text
    return text.upper()


def _word_in_opening(text: str, lexicon: Lexicon) -> str:
    if "sorry" not in text[:40].lower():
        return text
    return text.upper()


def _opening_is(text: str, lexicon: Lexicon) -> str:
    if text[-3:].lower() == "eh?":
        return text.upper()
    return text


# -- shapes that must not be read ----------------------------------------------------------------


def _else_not_none(text: str, lexicon: Lexicon) -> str:
    m = _CUE51P.search(text) if "wait" in text.lower() else text
    if m is None:
        return text
    return text.upper()


def _bool_bound(text: str, lexicon: Lexicon) -> str:
    # a bool, not a match: False (not None) where the word is absent
    m = ("wait" in text) if text else None
    if m is None:
        return text
    return text.upper()


def _unsafe_test(text: str, lexicon: Lexicon) -> str:
    m = _CUE51P.search(text) if lexicon.scene.objects[0].id else None
    if m is None:
        return text
    return text.upper()


def _neither_side_text(text: str, lexicon: Lexicon) -> str:
    return text.upper() if "wait" in text else text.lower()


def _sliced_by_a_sum(text: str, lexicon: Lexicon) -> str:
    if "sorry" not in text[: len(text) // 2].lower():
        return text
    return text.upper()


def _stripped_by_a_name(text: str, lexicon: Lexicon) -> str:
    if not text.strip(lexicon.scene.objects[0].id).endswith("his"):
        return text
    return text.upper()


def _upper_cased(text: str, lexicon: Lexicon) -> str:
    if text[:5].upper() != "NEVER":
        return text
    return text.lower()


def _indexed_not_sliced(text: str, lexicon: Lexicon) -> str:
    if text[0] != "N":
        return text
    return text.upper()


def _opens_with_a_name(text: str, lexicon: Lexicon) -> str:
    if not text.startswith(lexicon.scene.objects[0].id):
        return text
    return text.upper()


@pytest.mark.parametrize(
    ("step", "want"),
    [
        (_match_if_word, ((), ("wait",), False)),
        (_match_if_either, ((), ("no wait",), True)),
        (_match_after_match, ((), ("no wait",), True)),
        (_returned_if_word, ((), ("ta",), False)),
        (_text_if_none, ((), ("no wait",), True)),
        (_opens_with_any, (("Halfway ", "Midway "), (), False)),
        (_ends_stripped, ((" hers", " his"), (), False)),
        (_opening_lowered, ((), ("never",), False)),
        (_word_in_opening, ((), ("sorry",), False)),
        (_opening_is, ((), ("eh?",), False)),
        (_else_not_none, None),
        (_bool_bound, None),
        (_unsafe_test, None),
        (_neither_side_text, None),
        (_sliced_by_a_sum, None),
        (_stripped_by_a_name, None),
        (_upper_cased, None),
        (_indexed_not_sliced, None),
        (_opens_with_a_name, None),
    ],
)
def test_a_guard_is_read_only_where_the_step_leaves_the_text_without_its_words(
    step: _Step, want: stepguard.Guard | None
) -> None:
    entry = stepguard.read_guard(step)
    assert (entry and entry[1]) == want
    if entry is not None:
        assert stepguard.guard(step, entry) == want
        lexicon = Lexicon.of(SCENES[0])
        for text in (
            "Give Alice the cup",
            "no wait, the mug",
            "Wait, hold on, no wait the mug",
            "Midway through, give it to his",
            "never mind, ta",
            "sorry, the cup, eh?",
            "Halfway there. Is it his!",
        ):
            if not stepguard.may_act(entry[1], text, text.lower(), text.isascii()):
                assert step(text, lexicon) == text


# -- the corpus steps read so --------------------------------------------------------------------

# steps of each shape that session 51's reading guards (none had a guard before it)
_READ51 = (
    "hltl.grounding._normalise4:_meant_for35r",  # m = P.search(text) if 'meant' in … else None
    "hltl.grounding._normalise4:_leave_that34r",  # k = re.search(…) if m is not None else None
    "hltl.grounding._normalise2:_tag28",  # return P.sub('?', text) if ',' in … else text
    "hltl.grounding._normalise4:_we_have34r",  # return text if m is None else …
    "hltl.grounding._rewrites49:_midway49",  # text.startswith(('Midway ', 'Halfway ', …))
    "hltl.grounding._rewrites49:_theirs49",  # text.rstrip(' .!').endswith((' his', ' hers'))
    "hltl.grounding._rewrites38r:_never_mind38r",  # text[:5].lower() != 'never'
    "hltl.grounding._rewrites44s:_opening_sorry44s",  # 'sorry' not in text[:40].lower()
)


@cache
def _steps() -> dict[str, _Step]:
    return {stepguard.key(s): s for s in stepguard.all_steps()}


def test_the_steps_of_each_shape_have_a_guard_in_use() -> None:
    steps = _steps()
    for name in _READ51:
        entry = GUARDS.get(name)
        assert isinstance(entry, tuple), name
        assert stepguard.guard(steps[name], entry) is not None, name
        assert stepguard.read_guard(steps[name]) == entry, name


@cache
def _sentences() -> tuple[tuple[str, Scene], ...]:
    out: list[tuple[str, Scene]] = []
    for part in ("tuning", "blind48", "blind49"):
        corpus = load_corpus(ROOT / CORPUS_DIR / f"{part}.yaml", ROOT)
        out += [(e.text, corpus.scenes[e.scene]) for e in corpus.entries]
    return tuple(out)


@settings(max_examples=60, deadline=None)
@given(st.sampled_from(_sentences()))
def test_a_step_read_so_turned_away_in_a_pass_leaves_its_text_as_it_is(
    said: tuple[str, Scene],
) -> None:
    """Every step of _READ51 in a whole pass (nested reads too) is run; where its guard would
    turn the text it is handed away, what it returns is that text."""
    text, scene = said
    steps = _steps()
    rules: dict[str, stepguard.Guard | None] = {}
    for name in _READ51:
        entry = GUARDS.get(name)
        rules[name] = stepguard.guard(steps[name], entry if isinstance(entry, tuple) else None)
    wrong: list[tuple[str, str, str]] = []

    def checked(step: _Step) -> _Step:
        rule = rules.get(stepguard.key(step))
        if rule is None:
            return step

        def run(text: str, lexicon: Lexicon) -> str:
            out = step(text, lexicon)
            if not stepguard.may_act(rule, text, text.lower(), text.isascii()) and out != text:
                wrong.append((stepguard.key(step), text, out))
            return out

        return run

    lexicon = Lexicon.of(scene)
    lexicon.forget()
    lexicon.rewrites.clear()
    with pytest.MonkeyPatch.context() as mp:
        for name in ("_STEPS19", "_STEPS"):
            mp.setattr(normalise, name, tuple(checked(s) for s in getattr(normalise, name)))
        mp.setattr(_normalise1, "_guards_of", lambda steps: (None,) * len(steps))
        with contextlib.suppress(GroundingError):
            normalise.canonical19(text, lexicon)
    assert not wrong, wrong[:3]


# -- the step index --------------------------------------------------------------------------------


def _holding(rules: tuple[stepguard.Guard | None, ...], out: str, start: int) -> list[int]:
    low = out.lower()
    return [
        k
        for k, rule in enumerate(rules)
        if k >= start and (rule is None or stepguard.may_act(rule, out, low, out.isascii()))
    ]


@settings(max_examples=60, deadline=None)
@given(st.sampled_from(_sentences()), st.integers(min_value=0, max_value=1500))
def test_the_index_picks_what_every_guard_holds_twice_over(
    said: tuple[str, Scene], start: int
) -> None:
    """A text met again is answered from what was picked for it: the same steps from any
    start."""
    out = " ".join(said[0].split())
    if not out.isascii():
        return
    rules = _normalise1._guards_of(normalise._STEPS19)
    index = _normalise1._index_of(rules)
    assert index is not None
    for at in (start, 0, start // 2, start):
        assert _normalise1._may_act(index, out, out.lower(), at) == _holding(rules, out, at)


def test_a_word_is_found_by_any_three_of_its_letters() -> None:
    # 'zqab' and 'xzqa' share 'zqa' (the rarer letters index them elsewhere); 'ab' is short
    rules: tuple[stepguard.Guard | None, ...] = (
        (("zqab",), (), False),
        ((), ("xzqa",), False),
        ((), ("ab",), False),
        None,
        *(((f"w{k:03d}q",), (), False) for k in range(300)),
    )
    index = _normalise1._index_of(rules)
    assert index is not None
    assert _normalise1._may_act(index, "a zqab b", "a zqab b", 0) == [0, 2, 3]
    assert _normalise1._may_act(index, "a XZQA", "a xzqa", 0) == [1, 3]
    assert _normalise1._may_act(index, "a XZQA", "a xzqa", 2) == [3]
    assert _normalise1._may_act(index, "w007q w123q", "w007q w123q", 0) == [3, 11, 127]
