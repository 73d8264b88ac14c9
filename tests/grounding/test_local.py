"""Local llama.cpp grounder: missing backend, the shared loop with a fake model, opt-in real run."""

from __future__ import annotations

import importlib.util
import json
import re

import pytest

from hltl.errors import BackendUnavailableError
from hltl.grounding import make_grounder
from hltl.grounding.base import TokenUsage
from hltl.grounding.llm import LLMGroundingError
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
    assert fmt == {"type": "json_object", "schema": answer_schema(two_arms, grammar=True)}
    assert llm.calls[0]["temperature"] == 0.0
    messages = llm.calls[1]["messages"]
    assert isinstance(messages, list)
    assert "'cup' is not an object of the scene" in messages[-1]["content"]


def test_grammar_schema_bounds_answers_to_scene_ids(two_arms: Scene) -> None:
    schema = answer_schema(two_arms, grammar=True)
    props = schema["properties"]
    pattern = props["formulas"]["items"]["properties"]["formula"]["pattern"]
    for text in ("F delivered(bottle, A)", "F placed(chips, shelf)", "F (p100 & F p200)"):
        assert re.fullmatch(pattern, text)
    for text in ("F delivered(cup, A)", "F delivered(bottle, shelf)", "F placed(bottle, A)"):
        assert not re.fullmatch(pattern, text)
    assert props["formulas"]["maxItems"] == 8 and props["entities"]["maxItems"] == 5
    assert "pattern" not in json.dumps(answer_schema(two_arms))  # OpenAI gets the plain schema


@pytest.mark.live
@pytest.mark.skipif(not HAS_LLAMA, reason="needs the 'local' extra (llama-cpp-python)")
def test_gemma_end_to_end(two_arms: Scene) -> None:
    """A real llama.cpp run: grammar-bound JSON, validation, repairs and tokens all work.

    Whether Gemma 3 270M gets the meaning right is not asserted: on this prompt it mostly
    does not (docs/grounding.md). ``n_batch=1`` avoids a crash of some llama.cpp CPU builds in
    batched prompt evaluation.
    """
    grounder = LocalGrounder(max_repairs=1, llama_options={"n_batch": 1})
    try:
        g = grounder.ground("Give Person A the bottle", two_arms)
    except LLMGroundingError as exc:
        assert len(exc.history) == 2 and exc.tokens.prompt > 0 and exc.tokens.completion > 0
        for answer, _ in exc.history:
            json.loads(answer)  # the grammar only lets the model write valid JSON
    else:
        expected = spec_from_dict(
            {"root": "p0", "formulas": {"p0": "F p100", "p100": "F delivered(bottle, A)"}}
        )
        assert equivalent(g.spec, expected)
        assert g.tokens.prompt > 0
