"""Issue 18's LLM repros: huge answers, ignored token limits, deep answers, hanging endpoints,
and tokens spent on failed groundings."""

from __future__ import annotations

import json
from types import SimpleNamespace
from typing import Any

import pytest

from hltl.errors import GroundingError
from hltl.grounding.llm import (
    ECHO_CHARS,
    LLMConfig,
    LLMGrounder,
    LLMGroundingError,
    load_config,
)
from hltl.world.scene import Scene

GOOD = json.dumps(
    {
        "root": "p0",
        "formulas": [
            {"name": "p0", "formula": "F p100"},
            {"name": "p100", "formula": "F delivered(bottle, A)"},
        ],
        "entities": ["bottle", "A"],
        "error": None,
    }
)


def reply(content: str, prompt: int = 400, completion: int = 40) -> Any:
    return SimpleNamespace(
        choices=[SimpleNamespace(message=SimpleNamespace(content=content))],
        usage=SimpleNamespace(prompt_tokens=prompt, completion_tokens=completion),
    )


class Scripted:
    """A fake OpenAI client answering from a list (an exception in the list is raised)."""

    def __init__(self, *answers: Any) -> None:
        self.answers = list(answers)
        self.calls: list[dict[str, Any]] = []
        self.chat = SimpleNamespace(completions=SimpleNamespace(create=self._create))

    def _create(self, **kwargs: Any) -> Any:
        self.calls.append(kwargs)
        answer = self.answers.pop(0)
        if isinstance(answer, Exception):
            raise answer
        return answer


def grounder(client: Scripted, **config: Any) -> LLMGrounder:
    cfg = LLMConfig(base_url="http://fake/v1", structured=False, **config)
    return LLMGrounder(cfg, client=client)


def test_a_huge_answer_is_refused_and_not_echoed(two_arms: Scene) -> None:
    client = Scripted(reply("x" * 10_000_000), reply(GOOD))
    g = grounder(client).ground("Give Person A the bottle", two_arms)
    assert g.tokens.prompt == 800
    repair_prompt = client.calls[1]["messages"]
    assert sum(len(m["content"]) for m in repair_prompt) < 10_000
    assert repair_prompt[-2]["content"] == "x" * ECHO_CHARS
    assert "10,000,000 characters" in repair_prompt[-1]["content"]


def test_an_endpoint_ignoring_max_tokens_is_refused(two_arms: Scene) -> None:
    client = Scripted(reply(GOOD, completion=2_500_000))
    with pytest.raises(LLMGroundingError, match=r"2,500,000 completion tokens .* 600"):
        grounder(client).ground("Give Person A the bottle", two_arms)


@pytest.mark.parametrize(
    ("children", "chain", "why"),
    [(5000, False, "characters"), (300, False, "nests 301 levels"), (200, True, "201 levels")],
)
def test_an_answer_with_thousands_of_children_is_a_repairable_error(
    two_arms: Scene, children: int, chain: bool, why: str
) -> None:
    names = [f"p{i}" for i in range(1, children + 1)]
    if chain:  # p0 -> p1 -> ... -> p200 -> the delivery
        formulas = [
            {"name": a, "formula": f"F {b}"} for a, b in zip(["p0", *names], names, strict=False)
        ] + [{"name": names[-1], "formula": "F delivered(bottle, A)"}]
    else:  # p0 with every child side by side
        formulas = [{"name": "p0", "formula": " & ".join(f"F {n}" for n in names)}] + [
            {"name": n, "formula": "F delivered(bottle, A)"} for n in names
        ]
    deep = {"root": "p0", "formulas": formulas, "entities": ["bottle", "A"], "error": None}
    client = Scripted(reply(json.dumps(deep)), reply(GOOD))
    g = grounder(client).ground("Give Person A the bottle", two_arms)
    assert g.rounds == 2  # the first answer was refused with a message, not a RecursionError
    assert why in client.calls[1]["messages"][-1]["content"]


class APITimeoutError(Exception):
    """Stands in for openai.APITimeoutError."""


def test_a_hanging_endpoint_names_the_limit_and_how_to_change_it(two_arms: Scene) -> None:
    client = Scripted(reply("{}"), APITimeoutError("Request timed out."))
    with pytest.raises(LLMGroundingError) as info:
        grounder(client, timeout=7.0).ground("Give Person A the bottle", two_arms)
    assert "within 7 s" in str(info.value) and "HLTL_LLM_TIMEOUT" in str(info.value)
    # the first (refused) answer was paid for
    assert info.value.tokens_spent == 440


def test_the_timeout_comes_from_the_environment() -> None:
    assert load_config(env={"HLTL_LLM_TIMEOUT": "2.5"}).timeout == 2.5
    with pytest.raises(GroundingError, match=r"HLTL_LLM_TIMEOUT: expected seconds.*'soon'"):
        load_config(env={"HLTL_LLM_TIMEOUT": "soon"})
    with pytest.raises(GroundingError, match="HLTL_LLM_TIMEOUT"):
        load_config(env={"HLTL_LLM_TIMEOUT": "nan"})


def test_tokens_of_a_failed_grounding_are_kept(two_arms: Scene) -> None:
    declined = json.dumps({"root": "p0", "formulas": [], "entities": [], "error": "no cup"})
    client = Scripted(reply("not json", 450, 20), reply(declined, 460, 30))
    with pytest.raises(GroundingError) as info:
        grounder(client).ground("Give Person A the cup", two_arms)
    assert (info.value.prompt_tokens, info.value.completion_tokens) == (910, 50)


def test_usage_that_is_not_a_count_counts_as_zero(two_arms: Scene) -> None:
    bad = reply(GOOD)
    bad.usage = SimpleNamespace(prompt_tokens="many", completion_tokens=-3)
    g = grounder(Scripted(bad)).ground("Give Person A the bottle", two_arms)
    assert g.tokens.total == 0


class Spends:
    """A grounder that spends tokens and fails, as an LLM whose answers are all refused."""

    name = "spends"

    def ground(self, instruction: str, scene: Scene, running: Any = None) -> Any:
        raise GroundingError("every answer was refused", prompt_tokens=900, completion_tokens=70)


def test_hltl_ground_reports_tokens_spent_on_failure(
    monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str], two_arms_path: Any
) -> None:
    import hltl.grounding
    from hltl.cli.main import main

    monkeypatch.setattr(hltl.grounding, "make_grounder", lambda name, **kw: Spends())
    argv = ["ground", "--scene", str(two_arms_path), "--instruction", "give A the cup", "--json"]
    assert main(argv) == 1
    out, err = capsys.readouterr()
    assert json.loads(out)["tokens"] == {"prompt": 900, "completion": 70}
    assert err.strip().endswith("(900 prompt + 70 completion tokens spent)")


def test_a_failed_grounding_in_an_episode_counts_its_tokens(two_arms: Scene) -> None:
    from hltl.sim.episode import run_episode

    episode = run_episode(two_arms, instruction="give A the cup", grounder=Spends())
    record = next(r for r in episode.records if r.type == "grounding")
    assert (record.tokens, record.prompt_tokens, record.completion_tokens) == (
        970,
        900,
        70,
    )
    assert episode.metrics.tokens == 970 and not episode.success
