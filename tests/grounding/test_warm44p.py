"""Session 44 (12p): the warm-up gates and compiles the listed patterns as their first use would,
and a pattern the list lacks still works (gated and compiled when first met)."""

from __future__ import annotations

import argparse
import re

import pytest

from hltl.grounding import _normalise1, gate, warm
from hltl.grounding._warm_patterns import PATTERNS


def test_the_listed_patterns_are_each_listed_once_and_compile() -> None:
    assert len(PATTERNS) > 500
    assert len({(p, f) for p, f, _ in PATTERNS}) == len(PATTERNS)
    for pattern, flags, _build in PATTERNS:
        re.compile(pattern, flags)


def test_the_warm_up_gates_and_compiles_as_a_first_use_does() -> None:
    warm.warm_up()
    assert warm.warm_up() == 0  # once per process
    for pattern, flags, build in PATTERNS[::7]:
        assert pattern in gate._GATES[flags]
        assert gate._GATES[flags][pattern] == gate._gate(pattern, flags, build=False)
        if build:
            assert gate.compiled(pattern, flags) == re.compile(pattern, flags)


def test_a_pattern_the_list_lacks_is_gated_when_first_met(monkeypatch: pytest.MonkeyPatch) -> None:
    warm.warm_up()
    pattern = r"\bnever listed (\w+)\b"
    assert all(p != pattern for p, _, _ in PATTERNS)
    for text in ("the cup to Alice", "NEVER LISTED Bob", "never listed"):
        want = re.sub(pattern, r"<\1>", text, flags=re.I)
        assert _normalise1._sub(pattern, r"<\1>", text) == want
        assert gate.sub(pattern, r"<\1>", text, flags=re.I) == want


def test_an_instruction_does_not_warm_up(monkeypatch: pytest.MonkeyPatch) -> None:
    """One ``hltl ground`` compiles only what its instruction meets: parse_instruction never
    calls the warm-up (the bench does, before its parts)."""
    from hltl.grounding.offline import parse_instruction
    from tests.grounding.helpers import CELL

    monkeypatch.setattr(warm, "_DONE", False)
    parse_instruction("Give Alice the cup", CELL)
    assert not warm._DONE


def test_the_bench_warms_up_unless_told_cold(
    monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    from hltl.bench.grounding import Corpus, Score
    from hltl.cli import bench

    calls: list[int] = []
    monkeypatch.setattr(bench, "warm_up", lambda: len(calls.append(1) or ()))
    monkeypatch.setattr(bench, "score", lambda corpus, ground: Score(corpus.name, ()))
    monkeypatch.setattr(bench, "load_corpus", lambda path, root: Corpus("tuning", {}, ()))
    for cold in (False, True):
        args = argparse.Namespace(parts="tuning", write=None, show=False, cold=cold)
        assert bench.run_grounding(args) == 0
    assert calls == [1]
    assert capsys.readouterr().err.count("warm-up:") == 1
