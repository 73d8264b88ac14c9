"""Local llama.cpp grounder: missing backend, the shared loop with a fake model, opt-in real run."""

from __future__ import annotations

import importlib.util

import pytest

from hltl.errors import BackendUnavailableError
from hltl.grounding import make_grounder
from hltl.grounding.base import TokenUsage
from hltl.grounding.local import LocalGrounder
from hltl.grounding.prompt import answer_schema
from hltl.spec.equivalence import equivalent
from hltl.spec.hierarchy import spec_from_dict
from hltl.world.scene import Scene

from .conftest import recorded

HAS_LLAMA = importlib.util.find_spec("llama_cpp") is not None
TWO = "Give Person A the bottle and Person B the chips"


class FakeLlama:
    """``create_chat_completion`` as llama_cpp.Llama has it, replaying recorded responses."""

    def __init__(self, *names: str) -> None:
        self.responses = [recorded(n) for n in names]
        self.calls: list[dict[str, object]] = []

    def create_chat_completion(self, **kwargs: object) -> dict[str, object]:
        self.calls.append(kwargs)
        return self.responses.pop(0)


@pytest.mark.skipif(HAS_LLAMA, reason="llama-cpp-python is installed")
def test_missing_llama_cpp_names_the_extra(two_arms: Scene) -> None:
    g = make_grounder("local")
    with pytest.raises(BackendUnavailableError, match=r"pip install 'hltl\[local\]'"):
        g.ground(TWO, two_arms)


def test_constraining_schema_and_repair_loop(two_arms: Scene) -> None:
    llm = FakeLlama("unknown_cup.json", "repaired_bottle.json")
    g = LocalGrounder(llm=llm).ground("give A the cup", two_arms)
    assert g.tokens == TokenUsage(447 + 560, 49 + 50) and g.rounds == 2
    fmt = llm.calls[0]["response_format"]
    assert fmt == {"type": "json_object", "schema": answer_schema(two_arms)}
    assert llm.calls[0]["temperature"] == 0.0
    messages = llm.calls[1]["messages"]
    assert isinstance(messages, list)
    assert "'cup' is not an object of the scene" in messages[-1]["content"]


@pytest.mark.live
@pytest.mark.skipif(not HAS_LLAMA, reason="needs the 'local' extra (llama-cpp-python)")
def test_gemma_grounds_a_single_delivery(two_arms: Scene) -> None:
    # Gemma 3 270M is small: judge it on the easiest instruction, with repairs allowed.
    g = LocalGrounder(max_repairs=2).ground("Give Person A the bottle", two_arms)
    expected = spec_from_dict(
        {"root": "p0", "formulas": {"p0": "F p100", "p100": "F delivered(bottle, A)"}}
    )
    assert equivalent(g.spec, expected)
    assert g.tokens.prompt > 0
