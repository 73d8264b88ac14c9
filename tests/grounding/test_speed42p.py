"""Session 42 (12p): work a refusal no longer repeats gives what the work it replaces gave."""

from __future__ import annotations

import re

from hltl.bench.grounding import CORPUS_DIR, PARTS, load_corpus
from hltl.grounding import _normalise1
from hltl.grounding.lexicon import Lexicon
from tests.grounding.helpers import ROOT
from tests.grounding.test_paraphrase import MEASURED_ONLY


def _scenes() -> list[Lexicon]:
    lexicons: dict[int, Lexicon] = {}
    for part in PARTS:
        if part in MEASURED_ONLY:
            continue  # the held-back part is opened by its one measurement only
        corpus = load_corpus(ROOT / CORPUS_DIR / f"{part}.yaml", ROOT)
        for scene in corpus.scenes.values():
            lexicon = Lexicon.of(scene)
            lexicons[id(lexicon)] = lexicon
    return list(lexicons.values())


def test_the_known_words_are_built_once_per_lexicon_as_they_were_at_every_call() -> None:
    lexicons = _scenes()
    assert len(lexicons) > 20
    for lexicon in lexicons:
        kept = _normalise1._known_words(lexicon)
        assert kept is _normalise1._known_words(lexicon)  # built once
        assert kept == _normalise1._known_words.__wrapped__(lexicon)  # what a call built
    # what _plain_words answers with the kept words is what it answered
    lexicon = lexicons[0]
    names = " ".join(o.id for o in lexicon.scene.objects)
    for clause in ("the weather is lovely", f"he likes {names}", "zyzzyva qwertyuiop", ""):
        known = _normalise1._known_words.__wrapped__(lexicon)
        words = re.findall(r"[a-z]+", re.sub(r"'(?:s|ll|re|d|ve|m)\b|n't\b", " ", clause.lower()))
        assert _normalise1._plain_words(clause, lexicon) == all(w in known for w in words)
