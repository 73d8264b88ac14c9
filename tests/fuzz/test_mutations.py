"""Generated bad input: valid scenes, specs, events and logs with one part broken (hypothesis).

Whatever the mutation, a command either succeeds or ends with exactly one bounded ``error:``
line and exit 1: never a traceback, never the catch-all for unexpected errors.
"""

from __future__ import annotations

import json
import math
import tempfile
from pathlib import Path
from typing import Any

import yaml
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from .conftest import SCENE, SPEC, Outcome, assert_one_error, run_cli

BASE_SCENE: dict[str, Any] = yaml.safe_load(SCENE.read_text(encoding="utf-8"))
BASE_SPEC: dict[str, Any] = yaml.safe_load(SPEC.read_text(encoding="utf-8"))
BASE_EVENTS: dict[str, Any] = {
    "events": [
        {"t": 0.2, "type": "human_move", "human": "A", "to": [0.3, 0.5, 0.0], "speed": 1.5},
        {"t": 0.3, "type": "object_move", "object": "chips", "to": [1.4, -0.2, 0.05]},
        {"t": 0.5, "type": "instruction", "text": "also give Person B the chips"},
        {"t": 0.4, "type": "robot_down", "robot": "r2", "duration": 0.5},
        {"t": 0.1, "type": "human_wander", "human": "B", "duration": 2.0, "leg": 0.5},
        {"type": "skill_failure", "skill": "pick", "probability": 0.2},
    ]
}

NASTY = st.one_of(
    st.booleans(),
    st.none(),
    st.floats(allow_nan=True, allow_infinity=True),
    st.integers(min_value=-(10**30), max_value=10**30),
    st.text(max_size=20),
    st.sampled_from(["🍾", "дай", "p0", "F p0", "x" * 3000, "", " ", "1.0e300", "r1", "A"]),
    st.lists(st.one_of(st.floats(), st.booleans(), st.text(max_size=3)), max_size=5),
    st.dictionaries(st.text(max_size=5), st.integers(), max_size=3),
)


def _paths(doc: Any, prefix: tuple[Any, ...] = ()) -> list[tuple[Any, ...]]:
    """Every place in a document: keys of mappings and indices of lists."""
    out = [prefix] if prefix else []
    if isinstance(doc, dict):
        for k, v in doc.items():
            out += _paths(v, (*prefix, k))
    elif isinstance(doc, list):
        for i, v in enumerate(doc):
            out += _paths(v, (*prefix, i))
    return out


@st.composite
def mutated(draw: st.DrawFn, base: dict[str, Any]) -> dict[str, Any]:
    doc = json.loads(json.dumps(base))
    path = draw(st.sampled_from(_paths(doc)))
    parent = doc
    for part in path[:-1]:
        parent = parent[part]
    op = draw(st.sampled_from(["replace", "delete", "extra"]))
    if op == "delete":
        del parent[path[-1]]
    elif op == "extra" and isinstance(parent, dict):
        parent[draw(st.text(min_size=1, max_size=8))] = draw(NASTY)
    else:
        parent[path[-1]] = draw(NASTY)
    return doc


def _dump(doc: Any) -> str:
    # floats YAML cannot spell are written the way YAML 1.2 reads them
    return yaml.safe_dump(doc, allow_unicode=True, sort_keys=False)


def _check(result: Outcome) -> None:
    if result.code != 0:
        assert_one_error(result)


FUZZ = settings(
    max_examples=25,
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture],
    derandomize=True,
)


@FUZZ
@given(mutated(BASE_SCENE))
def test_mutated_scene(doc: dict[str, Any]) -> None:
    with tempfile.TemporaryDirectory() as d:
        p = Path(d) / "scene.yaml"
        p.write_text(_dump(doc), encoding="utf-8")
        _check(run_cli(["plan", "--scene", str(p), "--spec", str(SPEC)], measure=False))


@FUZZ
@given(mutated(BASE_SPEC))
def test_mutated_spec(doc: dict[str, Any]) -> None:
    with tempfile.TemporaryDirectory() as d:
        p = Path(d) / "spec.json"
        p.write_text(json.dumps(doc), encoding="utf-8")
        _check(run_cli(["check-spec", str(p)], measure=False))


@settings(FUZZ, max_examples=15)
@given(mutated(BASE_EVENTS))
def test_mutated_events(doc: dict[str, Any]) -> None:
    with tempfile.TemporaryDirectory() as d:
        p = Path(d) / "events.yaml"
        p.write_text(_dump(doc), encoding="utf-8")
        argv = ["run", "--scene", str(SCENE), "--spec", str(SPEC), "--events", str(p)]
        _check(run_cli([*argv, "--max-time", "10", "--no-predict", "--json"], measure=False))


@FUZZ
@given(st.binary(max_size=300), st.sampled_from(["spec.yaml", "spec.json", "log.jsonl"]))
def test_random_bytes(data: bytes, name: str) -> None:
    with tempfile.TemporaryDirectory() as d:
        p = Path(d) / name
        p.write_bytes(data)
        argv = ["score", str(p)] if name.endswith("jsonl") else ["check-spec", str(p)]
        result = run_cli(argv, measure=False)
        assert result.code == 1
        assert_one_error(result)


@FUZZ
@given(st.text(max_size=200))
def test_any_instruction_text(text: str) -> None:
    result = run_cli(["ground", "--scene", str(SCENE), f"--instruction={text}"], measure=False)
    _check(result)


def test_yaml_dump_of_nan_reads_back() -> None:
    """The mutations write NaN as YAML's .nan, which the strict loader reads as a float."""
    from hltl.errors import SceneError
    from hltl.fileio import load_data

    got = load_data(_dump({"x": math.nan}), "x", SceneError, as_json=False)
    assert math.isnan(got["x"])
