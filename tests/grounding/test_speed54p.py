"""Session 54 (12p): the people's pattern of _person_alt35t is the same text in every run (the
warm list's), and each speed change answers as the code it replaced, on every text."""

from __future__ import annotations

import os
import subprocess
import sys

import pytest

from hltl.grounding import _normalise4, gate
from hltl.grounding.lexicon import Lexicon
from hltl.world.scene import Scene
from tests.grounding.helpers import ROOT, SCENES

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
