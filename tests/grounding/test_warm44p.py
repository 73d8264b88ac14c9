"""Session 44 (12p): the warm-up gates and compiles the listed patterns as their first use would,
and a pattern the list lacks still works (gated and compiled when first met)."""

from __future__ import annotations

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


def test_the_first_instruction_of_a_process_warms_up(monkeypatch: pytest.MonkeyPatch) -> None:
    from hltl.grounding.offline import parse_instruction
    from tests.grounding.helpers import CELL

    monkeypatch.setattr(warm, "_DONE", False)
    for pattern, flags, _ in PATTERNS[:3]:
        gate.forget(pattern, flags)
    parse_instruction("Give Alice the cup", CELL)
    assert warm._DONE
    assert all(p in gate._GATES[f] for p, f, _ in PATTERNS[:3])
