"""Session 49 (12p): stepguard reads more of a step's statements — names bound to the text
('out = text', 'out = _sub(P, R, out)', a helper read through: 'out = helper(out, lexicon)'),
blocks run only on a match (skipped), blocks that keep the text as it is (read through),
'if m is not None and …', a compiled pattern's '.sub(R, text)', '_rx(P).search(text)' (``_rx``
is cached: never read before), searches of the lower-cased text, a name bound again, nested
functions, imports and 'del'. A step read so is turned away only where it leaves the text as it
is: asked of every text a pass hands each step (corpus sentences and mixes of the guards' words),
and of hand-made steps of each shape; a shape it cannot be sure of has no guard; a helper
changed since the list was made drops the guard of the step that calls it."""

from __future__ import annotations

import contextlib
import re as std_re
from collections.abc import Callable
from functools import cache

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.bench.grounding import CORPUS_DIR, load_corpus
from hltl.errors import GroundingError
from hltl.grounding import _normalise1, gate, normalise, stepguard
from hltl.grounding._normalise1 import _F, _rx, _sub
from hltl.grounding._step_guards import GUARDS
from hltl.grounding.lexicon import Lexicon
from hltl.world.scene import Scene
from tests.grounding.helpers import ROOT, SCENES

_Step = Callable[[str, Lexicon], str]


@cache
def _guarded() -> dict[str, stepguard.Guard]:
    """Every step's guard in use, by the step's name."""
    steps = stepguard.all_steps()
    rules = stepguard.guards(steps, GUARDS)
    return {stepguard.key(s): r for s, r in zip(steps, rules, strict=True) if r is not None}


@cache
def _sentences() -> tuple[tuple[str, Scene], ...]:
    out: list[tuple[str, Scene]] = []
    for part in ("tuning", "blind45", "blind46", "blind47"):
        corpus = load_corpus(ROOT / CORPUS_DIR / f"{part}.yaml", ROOT)
        out += [(e.text, corpus.scenes[e.scene]) for e in corpus.entries]
    return tuple(out)


@cache
def _pieces() -> tuple[str, ...]:
    words = sorted({w for plain, folded, _ in _guarded().values() for w in (*plain, *folded)})
    pieces = words[::2] + [w[: len(w) // 2] for w in words[::5]] + [w.upper() for w in words[::7]]
    pieces += ["the", "cup", "to", "Alice", "Bob", "give", ",", ".", "please", "no,", "sorry"]
    pieces += ["actually", "it", "she's", "he", "—", "’", "café", "wait", "Give", "?"]
    return tuple(pieces)


def _texts() -> st.SearchStrategy[tuple[str, Scene]]:
    mixed = st.tuples(
        st.lists(st.sampled_from(_pieces()), min_size=1, max_size=14).map(" ".join),
        st.sampled_from(SCENES),
    )
    return st.one_of(st.sampled_from(_sentences()), mixed)


def test_most_steps_have_a_guard_in_use() -> None:
    assert len(_guarded()) > 1100  # of some 1,370 (926 before session 49)


@settings(max_examples=60, deadline=None)
@given(_texts())
def test_every_step_turned_away_in_a_pass_leaves_its_text_as_it_is(
    said: tuple[str, Scene],
) -> None:
    """Every step of a whole pass (nested reads too) is run; where its guard would turn the
    text it is handed away, what it returns is that text."""
    text, scene = said
    rules = _guarded()
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


# -- reading a guard: the shapes of session 49 ---------------------------------------------------

_CUE49P = gate.compile(r"\bno wait\b", _F)
_ASIDE49P = gate.compile(r"\bby the way\b", _F)


def _helper49p(text: str, lexicon: Lexicon) -> str:
    if "kindly" not in text:
        return text
    return text.replace("kindly", "")


def _unread_helper49p(text: str, lexicon: Lexicon) -> str:
    return text.strip()


def _aliased(text: str, lexicon: Lexicon) -> str:
    out = text
    out = _sub(r"\bplease\b", "", out)
    return _sub(r"\bcheers\b", "", out)


def _through_helper(text: str, lexicon: Lexicon) -> str:
    out = _helper49p(text, lexicon)
    return _sub(r"\bta\b", "", out)


def _helper_returned(text: str, lexicon: Lexicon) -> str:
    return _helper49p(text, lexicon)


def _nested_first(text: str, lexicon: Lexicon) -> str:
    def drop(m: std_re.Match[str]) -> str:
        return ""

    from hltl.grounding.lexicon import Lexicon as _Lex  # noqa: F401

    del lexicon
    return _sub(r"\bmate\b", drop, text)


def _block_skipped(text: str, lexicon: Lexicon) -> str:
    m = _CUE49P.search(text)
    if m is not None:
        text = text[: m.start()] + "no," + text[m.end() :]
        return text.upper()
    return text


def _and_first_side(text: str, lexicon: Lexicon) -> str:
    m = _CUE49P.search(text)
    if m is not None and len(lexicon.scene.objects) > 0:
        return text.upper()
    return text


def _block_kept(text: str, lexicon: Lexicon) -> str:
    out = text
    if not _ASIDE49P.search(out):
        out = _sub(r"\bmate\b", "", out)
    return out


def _compiled_sub(text: str, lexicon: Lexicon) -> str:
    out = _CUE49P.sub("no,", text)
    return out


def _rx_search(text: str, lexicon: Lexicon) -> str:
    if not _rx(r"\bcheers\b").search(text):
        return text
    return text.upper()


def _low_search(text: str, lexicon: Lexicon) -> str:
    low = text.lower()
    if std_re.search(r"\bget\b", low):
        return text.upper()
    return text


def _bound_again(text: str, lexicon: Lexicon) -> str:
    m = _CUE49P.search(text)
    if m is not None:
        return text.upper()
    m = _ASIDE49P.search(text)
    if m is not None:
        return text.lower()
    return text


def _while_found(text: str, lexicon: Lexicon) -> str:
    out = text
    while (m := _CUE49P.search(out)) is not None:
        out = out[: m.start()] + out[m.end() :]
    return out


def _compared_helper(text: str, lexicon: Lexicon) -> str:
    if _helper49p(text, lexicon) != text:
        return text.upper()
    return text


# shapes that must not be read
def _rebound(text: str, lexicon: Lexicon) -> str:
    out = text
    out = out.strip()
    return _sub(r"\bplease\b", "", out)


def _unsafe_first_side(text: str, lexicon: Lexicon) -> str:
    m = _CUE49P.search(text)
    if len(lexicon.scene.objects) > 99 and m is not None:
        return text.upper()
    return text


def _unsafe_block_test(text: str, lexicon: Lexicon) -> str:
    if len(lexicon.scene.objects) > 99:
        return text.upper()
    return _sub(r"\bplease\b", "", text)


def _through_unread_helper(text: str, lexicon: Lexicon) -> str:
    out = _unread_helper49p(text, lexicon)
    return _sub(r"\bplease\b", "", out)


def _impure_argument(text: str, lexicon: Lexicon) -> str:
    out = _helper49p(text, lexicon.scene.objects[0])  # type: ignore[arg-type]
    return _sub(r"\bplease\b", "", out)


def _no_atoms(text: str, lexicon: Lexicon) -> str:
    out = text
    return out


def _falls_off(text: str, lexicon: Lexicon) -> str:  # type: ignore[return]
    out = _sub(r"\bplease\b", "", text)
    if out:
        return out


def _if_else(text: str, lexicon: Lexicon) -> str:
    if _CUE49P.search(text):
        pass
    else:
        text = text.strip()
    return _sub(r"\bplease\b", "", text)


def _shadowed(text: str, lexicon: Lexicon) -> str:
    _CUE49P = std_re.compile(r".")
    m = _CUE49P.search(text)
    if m is None:
        return text
    return text.upper()


@pytest.mark.parametrize(
    ("step", "want"),
    [
        (_aliased, ((), ("cheers", "please"), True)),
        (_through_helper, (("kindly",), ("ta",), True)),
        (_helper_returned, (("kindly",), (), False)),
        (_nested_first, ((), ("mate",), True)),
        (_block_skipped, ((), ("no wait",), True)),
        (_and_first_side, ((), ("no wait",), True)),
        (_block_kept, ((), ("mate",), True)),
        (_compiled_sub, ((), ("no wait",), True)),
        (_rx_search, ((), ("cheers",), True)),
        (_low_search, ((), ("get",), True)),
        (_bound_again, ((), ("by the way", "no wait"), True)),
        (_while_found, ((), ("no wait",), True)),
        (_compared_helper, (("kindly",), (), False)),
        (_rebound, None),
        (_unsafe_first_side, None),
        (_unsafe_block_test, None),
        (_through_unread_helper, None),
        (_impure_argument, None),
        (_no_atoms, None),
        (_falls_off, None),
        (_if_else, None),
        (_shadowed, None),
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
        for text in ("Give Alice the cup", "no wait, the mug", "kindly pass it", "GET it, mate"):
            if not stepguard.may_act(entry[1], text, text.lower(), text.isascii()):
                assert step(text, lexicon) == text


def test_a_helper_changed_since_the_list_was_made_drops_the_guard(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    entry = stepguard.read_guard(_through_helper)
    assert entry is not None and stepguard.guard(_through_helper, entry) is not None
    monkeypatch.setitem(_through_helper.__globals__, "_helper49p", _unread_helper49p)
    assert stepguard.guard(_through_helper, entry) is None


def test_a_name_a_helper_reads_changed_drops_the_guard(monkeypatch: pytest.MonkeyPatch) -> None:
    entry = stepguard.read_guard(_block_kept)
    assert entry is not None and stepguard.guard(_block_kept, entry) is not None
    monkeypatch.setitem(_block_kept.__globals__, "_ASIDE49P", gate.compile(r"\bbtw\b", _F))
    assert stepguard.guard(_block_kept, entry) is None


# -- the guards indexed by their words' first letters (_normalise1._run_indexed) ----------------


def _calls(text: str, scene: Scene, indexed: bool) -> tuple[list[tuple[str, str]], str]:
    """The steps a whole pass calls, each with the text it is handed, and what the pass gives."""
    called: list[tuple[str, str]] = []

    def spied(step: _Step) -> _Step:
        def run(text: str, lexicon: Lexicon) -> str:
            called.append((stepguard.key(step), text))
            return step(text, lexicon)

        return run

    lexicon = Lexicon.of(scene)
    lexicon.forget()
    lexicon.rewrites.clear()
    with pytest.MonkeyPatch.context() as mp:
        for name in ("_STEPS19", "_STEPS"):
            steps = getattr(normalise, name)
            mp.setattr(normalise, name, tuple(spied(s) for s in steps))
            rules = stepguard.guards(steps, GUARDS)
            mp.setitem(
                _normalise1._GUARDED,
                id(getattr(normalise, name)),
                (getattr(normalise, name), rules),
            )
        if not indexed:
            mp.setattr(_normalise1, "_INDEXED_FROM", 10**9)
        try:
            out = normalise.canonical19(text, lexicon)
        except GroundingError as refused:
            out = f"refused: {refused}"
    return called, out


@settings(max_examples=60, deadline=None)
@given(_texts())
def test_a_pass_through_the_index_calls_what_the_loop_over_every_guard_calls(
    said: tuple[str, Scene],
) -> None:
    text, scene = said
    assert _calls(text, scene, indexed=True) == _calls(text, scene, indexed=False)


def test_the_index_leaves_out_only_steps_whose_words_are_absent() -> None:
    steps = normalise._STEPS19
    rules = _normalise1._guards_of(steps)
    index = _normalise1._index_of(rules)
    assert index is not None and _normalise1._index_of(rules[:5]) is None
    for text, _ in _sentences()[::7]:
        low = " ".join(text.split()).lower()
        if not low.isascii():
            continue
        picked = set(_normalise1._may_act(index, " ".join(text.split()), low, 0))
        for k, rule in enumerate(rules):
            if k not in picked:
                assert rule is not None
                assert not stepguard.may_act(rule, " ".join(text.split()), low, True)
