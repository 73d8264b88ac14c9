"""Session 54 (12p): the people's pattern of _person_alt35t is the same text in every run (the
warm list's), and each speed change answers as the code it replaced, on every text."""

from __future__ import annotations

import os
import subprocess
import sys
from collections.abc import Callable
from functools import cache

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.bench.grounding import CORPUS_DIR, load_corpus
from hltl.errors import GroundingError
from hltl.grounding import _normalise2, _normalise4, gate, offline, stepguard
from hltl.grounding.lexicon import Lexicon
from hltl.world.scene import Scene
from tests.grounding.helpers import CELL, OFFICE, ROOT, SCENES, WORKSHOP, assert_refused

_PRINT_ALTS = (
    "from hltl.grounding._normalise4 import _person_alt35t\n"
    "from hltl.grounding.lexicon import Lexicon\n"
    "from tests.grounding.helpers import SCENES\n"
    "for scene in SCENES:\n"
    "    print(_person_alt35t(Lexicon.of(scene)))\n"
)


def _alts_in_a_run(seed: str) -> str:
    env = {**os.environ, "PYTHONHASHSEED": seed, "PYTHONPATH": str(ROOT / "src")}
    done = subprocess.run(
        [sys.executable, "-c", _PRINT_ALTS], cwd=ROOT, env=env, capture_output=True, text=True
    )
    assert done.returncode == 0, done.stderr
    return done.stdout


def test_the_people_pattern_is_the_same_text_in_every_run() -> None:
    """Two runs with other string hashes (a set's order) build the same patterns."""
    runs = {_alts_in_a_run(seed) for seed in ("1", "2")}
    assert len(runs) == 1
    assert "Person\\ A|Person\\ B" in runs.pop()  # not vacuous: names of one length


def _scene_id(scene: Scene) -> str:
    return scene.source.rsplit("/", 1)[-1]


def _plain(alt: str) -> str:
    return alt.replace("\\", "")


@pytest.mark.parametrize("scene", SCENES, ids=_scene_id)
def test_names_of_one_length_in_alphabetical_order(scene: Scene) -> None:
    names = [_plain(a) for a in _normalise4._person_alt35t(Lexicon.of(scene)).split("|")]
    assert names == sorted(names, key=lambda n: (-len(n), n))


@pytest.mark.parametrize("scene", SCENES, ids=_scene_id)
def test_the_order_of_names_of_one_length_changes_no_match(scene: Scene) -> None:
    """Names of one length in another order (a set's, as before) match as the sorted ones do."""
    alts = _normalise4._person_alt35t(Lexicon.of(scene)).split("|")
    other = sorted(alts[::-1], key=lambda a: -len(_plain(a)))  # ties reversed
    texts = [
        f"{_plain(a)}{tail} can keep the cup, and {_plain(b)} too."
        for a in alts
        for b in alts
        for tail in ("", "s", " B", "a")
    ]
    for text in (*texts, *(t.lower() for t in texts)):
        one = gate.search(rf"\b(?P<p>{'|'.join(alts)}) can keep", text, gate.IGNORECASE)
        two = gate.search(rf"\b(?P<p>{'|'.join(other)}) can keep", text, gate.IGNORECASE)
        assert (one and (one.span(), one["p"])) == (two and (two.span(), two["p"]))


def test_some_scene_has_names_of_one_length() -> None:
    """Not vacuous: the reversed order differs from the sorted one somewhere."""
    assert any(
        sorted(a[::-1], key=lambda n: -len(_plain(n))) != a
        for a in (_normalise4._person_alt35t(Lexicon.of(s)).split("|") for s in SCENES)
    )


# -- the raw pattern calls made cheaper (session 54, 12p) ------------------------------------

_COURTESIES = sorted(gate.spelt(_normalise2._COURTESY24, _normalise2._F) or ())


def test_the_courtesies_are_spelt_out() -> None:
    """Not vacuous: the list the stretch test is checked over."""
    assert len(_COURTESIES) > 200


def _stretch_as_it_was(said: str) -> bool:
    return _normalise2._COURTESY_STRETCH24.fullmatch(said) is not None


@pytest.mark.parametrize("courtesy", _COURTESIES)
def test_a_courtesy_stretch_is_found_as_before(courtesy: str) -> None:
    for said in (
        courtesy,
        courtesy.upper(),
        courtesy.title(),
        f"and {courtesy}",
        f"And  {courtesy} my friend",
        f"{courtesy} in advance",
        f"{courtesy} {courtesy}",
        f"{courtesy}s",
        f"{courtesy} the cup",
        f"x{courtesy}",
        f"{courtesy[:-1]}",
        f" {courtesy}",
        f"{courtesy}, friend",
    ):
        assert _normalise2._courtesy_stretch24(said) == _stretch_as_it_was(said), said


_PIECES = st.sampled_from(
    [*_COURTESIES[::7], "and", "And", "the", "cup", "Bob", "friend", "sir", "in advance", "a"]
) | st.sampled_from([" ", "  ", ",", ".", "!", "'", "-", "\t", "é", "ß", "ſ", "K", "1", "_"])


@settings(max_examples=1500, deadline=None)
@given(st.lists(_PIECES, max_size=6).map("".join))
def test_the_stretch_test_answers_as_the_pattern(said: str) -> None:
    assert _normalise2._courtesy_stretch24(said) == _stretch_as_it_was(said)


def _translated_as_it_was(text: str, lexicon: Lexicon) -> str:
    """_translated25 of session 53 (every pattern asked raw)."""
    n2 = _normalise2
    if n2._PLEASE25.search(text):
        text = n2._PLEASE25.sub(lambda m: m[0] if n2._names(m[0], lexicon) else "please", text)
    if n2._SORRY25.search(text):
        text = n2._SORRY25.sub("sorry", text)
    if n2._PATOIS_WORD25.search(text):
        text = n2._PATOIS_WORD25.sub(lambda m: n2._PATOIS25.get(m[0].lower(), ""), text)
    if not n2._HONORIFIC25.search(text):
        return text
    return n2._HONORIFIC25.sub(
        lambda m: "" if n2._opens_with_person(m.string[m.end() :], lexicon) else m[0], text
    )


# sentences _translated25 or _courtesy24 rewrite (their sessions' tests)
_REWRITTEN = (
    "Permisi, tolong the bottle for Person A",
    "Bitte, the apple to Bob.",
    "The cup to Alice, por favor.",
    "…, ah no, bebakhshid, the apple",
    "Not di bottle, jus di crisps fi Bob",
    "Stapler to Bu Priya, then the notepad to Mas Sam",
    "S'il vous plaît, the crisps to Alice.",
    "Maaf, the chips to Person B.",
    "Sawasdee krap. The apple to Bob.",
    "The cup to Alice, asante.",
    "Habari, the crisps to Bob.",
    "Diakuiu, thank you very much. The apple to Alice.",
    "Eskerrik asko in advance: the cup to Bob.",
    "Give Bob the apple, as we say, asante sana.",
)


@cache
def _sentences() -> tuple[tuple[str, Scene], ...]:
    out: list[tuple[str, Scene]] = []
    for part in ("tuning", "blind22", "blind52", "causes15"):
        corpus = load_corpus(ROOT / CORPUS_DIR / f"{part}.yaml", ROOT)
        out += [(e.text, corpus.scenes[e.scene]) for e in corpus.entries[::2]]
    for scene in (CELL, WORKSHOP, OFFICE):
        out += [(t, scene) for t in _REWRITTEN]
    return tuple(out)


def _answer(step: Callable[[str, Lexicon], str], text: str, scene: Scene) -> str:
    try:
        return step(text, Lexicon.of(scene))
    except GroundingError as refused:
        return f"refused: {refused}"


@pytest.mark.parametrize(
    "step",
    [_normalise2._translated25, _normalise2._courtesy24, _normalise2._as_used_to34],
    ids=lambda s: s.__name__,
)
def test_the_step_answers_as_without_the_gate(
    step: Callable[[str, Lexicon], str], monkeypatch: pytest.MonkeyPatch
) -> None:
    gated = [_answer(step, t, s) for t, s in _sentences()]
    monkeypatch.setattr(gate, "may_match", lambda pattern, flags, text: True)  # every call raw
    monkeypatch.setattr(_normalise2, "_BY_FIRST24", None)  # the stretch asked at once
    raw = [_answer(step, t, s) for t, s in _sentences()]
    assert gated == raw


def test_translated25_answers_as_it_did() -> None:
    for text, scene in _sentences():
        want = _answer(_translated_as_it_was, text, scene)
        assert _answer(_normalise2._translated25, text, scene) == want, text


def test_the_steps_rewrite_some_sentences() -> None:
    """Not vacuous: the sentences above are rewritten by the steps asked."""
    changed = {
        step.__name__
        for step in (_normalise2._translated25, _normalise2._courtesy24)
        for text, scene in _sentences()
        if _answer(step, text, scene) != text
    }
    assert changed == {"_translated25", "_courtesy24"}


def test_the_doubts_are_counted_as_before() -> None:
    """offline._parse counts the speaker's doubts through the gate."""
    texts = [t for t, _ in _sentences()] + [
        "I'm not sure, morning! Would you mind passing Bob the crisps?",
        "The cup to Alice, no, Bob. Ugh, I don't know. Good robot.",
        "I DUNNO, the apple to Bob, no idea why, I forgot, lost track.",
        "Before I forget, the apple to Bob; I can't recall his name, I can't decide.",
    ]
    counts = [len(offline._DOUBT.findall(t)) for t in texts]
    assert [len(gate.findall(offline._DOUBT, t)) for t in texts] == counts
    assert sum(counts) >= 8  # not vacuous


def test_a_rewrite_that_drops_a_doubt_is_still_not_read() -> None:
    assert_refused("I'm not sure, morning! Would you mind passing Bob the crisps?")


# -- stepguard reads re's functions called with a module's compiled pattern (session 54) -----

_TOY = gate.compile(r"\bkindly\b", gate.IGNORECASE)


def _toy_search(text: str, lexicon: Lexicon) -> str:
    if gate.search(_TOY, text):
        return text + "!"
    return text


def _toy_sub(text: str, lexicon: Lexicon) -> str:
    return gate.sub(_TOY, "please", text)


def _toy_flags(text: str, lexicon: Lexicon) -> str:
    if gate.search(_TOY, text, gate.IGNORECASE):  # flags beside a compiled pattern: not read
        return text + "!"
    return text


@pytest.mark.parametrize(
    ("step", "want"),
    [
        (_toy_search, ((), ("kindly",), True)),
        (_toy_sub, ((), ("kindly",), True)),
        (_toy_flags, None),
    ],
)
def test_a_compiled_pattern_asked_through_re_is_read(
    step: Callable[[str, Lexicon], str], want: stepguard.Guard | None
) -> None:
    entry = stepguard.read_guard(step)
    assert (entry and entry[1]) == want
    if entry is not None:
        assert stepguard.guard(step, entry) == want
        for text in ("Kindly give Alice the cup", "give Bob the cup", "unkindly"):
            if not stepguard.may_act(entry[1], text, text.lower(), text.isascii()):
                assert step(text, Lexicon.of(CELL)) == text


def test_translated25_keeps_a_guard_of_its_four_lists() -> None:
    entry = stepguard.read_guard(_normalise2._translated25)
    assert entry is not None
    said, low, _ = entry[1]
    assert {"tolong", "bitte", "maaf", "tafadhali"} <= set(low) and "u" in said
