"""Session 50 (12p): the index of the steps' guards holds each guard word once, with every step
it guards; a text's pieces ask each word that may be in it once, and the steps picked are exactly
those whose guard holds (no guard is asked again in the pass). A guard with an empty word ('' is
in every text) is never used: stepguard drops it, and the index picks its step always. Session
46's rules that leave a sentence an older rule reads to it ask their own tests of the text first
(each returns the text, as the older rules' reading does): what they give is what they gave."""

from __future__ import annotations

from collections.abc import Callable

from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.grounding import _normalise1, _rewrites46, normalise, stepguard
from hltl.grounding._step_guards import GUARDS
from hltl.grounding.lexicon import Lexicon
from hltl.world.scene import Scene
from tests.grounding import test_phrasing_s46
from tests.grounding.helpers import PhrasingCases
from tests.grounding.test_stepguard49p import _calls, _sentences, _texts

_Step = Callable[[str, Lexicon], str]


def _holding(rules: tuple[stepguard.Guard | None, ...], out: str, start: int) -> list[int]:
    """The steps from ``start`` on that may act on ``out`` by the guards asked one by one."""
    low = out.lower()
    return [
        k
        for k, rule in enumerate(rules)
        if k >= start and (rule is None or stepguard.may_act(rule, out, low, out.isascii()))
    ]


@settings(max_examples=80, deadline=None)
@given(_texts(), st.integers(min_value=0, max_value=1400))
def test_the_index_picks_exactly_the_steps_whose_guard_holds(
    said: tuple[str, Scene], start: int
) -> None:
    text, _ = said
    out = " ".join(text.split())
    if not out.isascii():
        return  # the index is asked of ASCII texts only (_rewritten)
    rules = _normalise1._guards_of(normalise._STEPS19)
    index = _normalise1._index_of(rules)
    assert index is not None
    assert _normalise1._may_act(index, out, out.lower(), start) == _holding(rules, out, start)


def test_the_index_asks_plain_words_of_the_text_as_it_is() -> None:
    rules: tuple[stepguard.Guard | None, ...] = (
        (("Bob",), (), False),
        ((), ("bob",), False),
        None,
        *(((f"zq{k}x",), (), False) for k in range(300)),
    )
    index = _normalise1._index_of(rules)
    assert index is not None
    assert _normalise1._may_act(index, "give BOB it", "give bob it", 0) == [1, 2]
    assert _normalise1._may_act(index, "give Bob it", "give bob it", 0) == [0, 1, 2]
    assert _normalise1._may_act(index, "give Bob it", "give bob it", 1) == [1, 2]


def test_a_guard_with_an_empty_word_is_never_used() -> None:
    rules: tuple[stepguard.Guard | None, ...] = (
        (("",), (), False),
        ((), ("",), False),
        ((), ("zqx",), False),
        *(((), (f"zq{k}y",), False) for k in range(300)),
    )
    index = _normalise1._index_of(rules)
    assert index is not None
    assert _normalise1._may_act(index, "give it", "give it", 0) == [0, 1]
    step = normalise._STEPS19[0]
    made: stepguard.Entry = (stepguard.fingerprint(step), (("",), ("please",), False), ())
    assert stepguard.guard(step, made) is None
    assert stepguard.guard(step, (made[0], ((), ("please",), False), ())) is not None


def test_no_guard_in_the_list_has_an_empty_word() -> None:
    for name, entry in GUARDS.items():
        if isinstance(entry, tuple):
            plain, folded, _ = entry[1]
            assert "" not in plain and "" not in folded, name


@settings(max_examples=40, deadline=None)
@given(_texts())
def test_a_pass_through_the_index_still_calls_what_the_loop_calls(
    said: tuple[str, Scene],
) -> None:
    text, scene = said
    assert _calls(text, scene, indexed=True) == _calls(text, scene, indexed=False)


def test_corpus_sentences_pass_the_same_through_the_index_and_the_loop() -> None:
    for text, scene in _sentences()[::41]:
        assert _calls(text, scene, indexed=True) == _calls(text, scene, indexed=False), text


# -- session 46's rules ask their own tests of the text before the older rules' reading ---------

_OLDER46: tuple[tuple[str, tuple[_Step, ...], PhrasingCases], ...] = (
    (
        "_remark_it46",
        (_rewrites46._owner_then37s, _rewrites46._pronouns38, _rewrites46._lone_going44r),
        test_phrasing_s46.REMARK_IT,
    ),
    ("_not_for_cleft46", (_rewrites46._who_asked38r,), test_phrasing_s46.NOT_FOR),
    ("_so_reason46", (_rewrites46._remark_first39s,), test_phrasing_s46.SO_REASON),
    ("_placed_so46", (_rewrites46._questions38,), test_phrasing_s46.PLACED_SO),
    (
        "_bare_doing46",
        (_rewrites46._occasion41s, _rewrites46._the_one45r),
        test_phrasing_s46.BARE_DOING,
    ),
)


def _older_first(name: str, older: tuple[_Step, ...]) -> _Step:
    """The rule as it was before session 50: the older rules' reading asked first."""
    step: _Step = getattr(_rewrites46, name)

    def run(text: str, lexicon: Lexicon) -> str:
        if _rewrites46._older_reads46(text, lexicon, *older):
            return text
        return step(text, lexicon)

    return run


def _same46(text: str, scene: Scene) -> None:
    for name, older, _ in _OLDER46:
        step: _Step = getattr(_rewrites46, name)
        lexicon = Lexicon.of(scene)
        assert step(text, lexicon) == _older_first(name, older)(text, lexicon), (name, text)


def test_the_rules_read_their_own_sentences_as_before() -> None:
    for _, _, cases in _OLDER46:
        assert cases.read
        for text, _, scene in cases.read:
            _same46(text, scene)


@settings(max_examples=60, deadline=None)
@given(_texts())
def test_the_rules_leave_what_the_older_rules_read_as_before(said: tuple[str, Scene]) -> None:
    _same46(*said)


def test_corpus_sentences_meet_the_rules_as_before() -> None:
    for text, scene in _sentences()[::23]:
        _same46(" ".join(text.split()), scene)
