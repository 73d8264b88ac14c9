"""The offline grounder on the corpus: each spec must have the expected language (equivalence)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest
import yaml

from hltl.errors import GroundingError
from hltl.grounding.offline import OfflineGrounder
from hltl.spec.equivalence import counterexample
from hltl.spec.hierarchy import spec_from_dict, spec_to_dict
from hltl.world.scene import Scene, load_scene

ROOT = Path(__file__).resolve().parents[2]
CORPUS = yaml.safe_load((Path(__file__).parent / "corpus.yaml").read_text(encoding="utf-8"))
SCENES: dict[str, Scene] = {k: load_scene(ROOT / v) for k, v in CORPUS["scenes"].items()}


def _id(entry: dict[str, Any]) -> str:
    return f"{entry['scene']}: {entry['text'][:60]}"


def test_corpus_size() -> None:
    assert len(CORPUS["accept"]) + len(CORPUS["reject"]) >= 80
    assert len(CORPUS["reject"]) >= 15


@pytest.mark.parametrize("entry", CORPUS["accept"], ids=_id)
def test_accepted_instruction_has_the_expected_language(entry: dict[str, Any]) -> None:
    scene = SCENES[entry["scene"]]
    expected = spec_from_dict(entry["spec"], source="corpus")
    got = OfflineGrounder().ground(entry["text"], scene)
    trace = counterexample(got.spec, expected)
    assert trace is None, (
        f"{entry['text']!r} grounded as {spec_to_dict(got.spec)}, which differs from the "
        f"expected spec on trace {[sorted(map(str, s)) for s in trace]}"
    )
    # the entities are exactly the ids the expected spec mentions
    mentioned = {arg for _, f in expected.formulas for a in _atoms(f) for arg in a.args}
    assert set(got.entities) == mentioned
    assert got.tokens.prompt == 0 and got.tokens.completion == 0


@pytest.mark.parametrize("entry", CORPUS["reject"], ids=_id)
def test_rejected_instruction_says_why(entry: dict[str, Any]) -> None:
    scene = SCENES[entry["scene"]]
    with pytest.raises(GroundingError) as info:
        OfflineGrounder().ground(entry["text"], scene)
    assert entry["error"] in str(info.value)


def _atoms(f: Any) -> Any:
    from hltl.spec.printer import atoms

    return atoms(f)
