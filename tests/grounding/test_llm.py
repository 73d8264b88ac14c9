"""LLM grounder: prompt, schema, answer validation, repair loop, tokens, config, live opt-in.

The responses replayed here are hand-recorded shapes (see fixtures/README.md), not live calls.
"""

from __future__ import annotations

import json
import os
from pathlib import Path
from typing import Any

import pytest

from hltl.errors import BackendUnavailableError, GroundingError
from hltl.grounding import make_grounder
from hltl.grounding.base import TokenUsage, scene_graph
from hltl.grounding.llm import (
    LLMConfig,
    LLMGrounder,
    LLMGroundingError,
    load_config,
    make_openai_client,
)
from hltl.grounding.prompt import EXAMPLES, SYSTEM, answer_schema, build_messages, structures
from hltl.grounding.tokens import estimate_grounding_tokens
from hltl.grounding.validate import AnswerError, ModelDeclined, check_answer, root_can_accept
from hltl.spec.hierarchy import spec_from_dict, spec_to_dict
from hltl.world.scene import Scene, load_scene

from .conftest import FIXTURES, FakeClient, recorded

TWO = "Give Person A the bottle and Person B the chips"
EXAMPLES_DIR = Path(__file__).resolve().parents[2] / "examples"


def grounder(client: FakeClient, max_repairs: int = 2) -> LLMGrounder:
    return LLMGrounder(LLMConfig(base_url="http://fake/v1", max_repairs=max_repairs), client=client)


# -- prompt ------------------------------------------------------------------------------------


def test_scene_graph_is_compact_and_complete(two_arms: Scene) -> None:
    text = scene_graph(two_arms)
    assert text.splitlines() == [
        "objects: bottle; chips (crisps)",
        "people: A (Person A, Alice); B (Person B, Bob)",
        "surfaces: shelf",
    ]


def test_a_plain_instruction_is_sent_without_examples(two_arms: Scene) -> None:
    msgs = build_messages(TWO, two_arms)
    assert [m["role"] for m in msgs] == ["system", "user"]
    assert msgs[0]["content"] == SYSTEM
    assert msgs[-1]["content"] == f"Scene:\n{scene_graph(two_arms)}\nInstruction: {TWO}"


@pytest.mark.parametrize(
    ("instruction", "shows"),
    [
        ("Give Person A the bottle, then Person B the chips", {"order"}),
        ("Bring Bob the chips after Alice has the bottle", {"order"}),
        ("Give Person A either the bottle or the chips", {"choice"}),
        (
            "First put the bottle on the shelf, then give Bob the chips or the bottle",
            {"order", "choice"},
        ),
    ],
)
def test_examples_are_chosen_by_the_instructions_structure(
    two_arms: Scene, instruction: str, shows: set[str]
) -> None:
    msgs = build_messages(instruction, two_arms)
    assert [m["role"] for m in msgs] == ["system", "user", "assistant", "user"]
    (ex,) = [e for e in EXAMPLES if e.shows == shows]
    assert json.loads(msgs[2]["content"]) == ex.answer
    assert ex.text in msgs[1]["content"]


@pytest.mark.parametrize("ex", EXAMPLES, ids=lambda e: e.text)
def test_every_example_answer_is_a_valid_spec_that_shows_what_it_claims(ex: Any) -> None:
    data = {
        "root": ex.answer["root"],
        "formulas": {e["name"]: e["formula"] for e in ex.answer["formulas"]},
    }
    spec = spec_from_dict(data)
    text = " ".join(e["formula"] for e in ex.answer["formulas"])
    assert ("F (" in text) == ("order" in ex.shows)
    assert ("|" in text) == ("choice" in ex.shows)
    assert structures(ex.text) == ex.shows
    assert spec.root == "p0"


def test_a_one_task_query_costs_no_more_tokens_than_the_papers() -> None:
    pytest.importorskip("bpe_openai")
    scene = load_scene(EXAMPLES_DIR / "scenes" / "1-1.yaml")
    # Table II of the paper: 261 tokens per query for one task with one robot
    assert 0 < estimate_grounding_tokens("Give Person A the bottle.", scene) <= 261


def test_schema_restricts_entities_to_scene_ids(two_arms: Scene) -> None:
    schema = answer_schema(two_arms)
    assert schema["properties"]["entities"]["items"]["enum"] == [
        "bottle",
        "chips",
        "A",
        "B",
        "shelf",
    ]
    assert schema["additionalProperties"] is False
    assert set(schema["required"]) == set(schema["properties"])


# -- answer validation -----------------------------------------------------------------------


def content(name: str) -> str:
    text = recorded(name)["choices"][0]["message"]["content"]
    assert isinstance(text, str)
    return text


def test_valid_answer_gives_spec_and_entities(two_arms: Scene) -> None:
    spec, ids = check_answer(content("two_deliveries.json"), two_arms)
    assert spec_to_dict(spec)["formulas"]["p200"] == "F delivered(chips, B)"
    assert ids == ("bottle", "A", "chips", "B")


@pytest.mark.parametrize(
    ("name", "message"),
    [
        (
            "unknown_cup.json",
            "delivered(cup, A): 'cup' is not an object of the scene; objects: bottle, chips",
        ),
        ("wrong_kind.json", "'shelf' is not a person of the scene; people: A, B"),
        ("prose.json", "the answer is not valid JSON"),
        ("same_step.json", "rule 3"),
    ],
)
def test_invalid_answers_are_rejected_precisely(two_arms: Scene, name: str, message: str) -> None:
    with pytest.raises(AnswerError) as info:
        check_answer(content(name), two_arms)
    assert message in str(info.value)


def test_declined_answer_is_final(two_arms: Scene) -> None:
    with pytest.raises(ModelDeclined, match="there is no cup in the scene"):
        check_answer(content("declined.json"), two_arms)


def test_fenced_json_with_mapping_formulas_is_accepted(two_arms: Scene) -> None:
    spec, _ = check_answer(content("fenced_sequence.json"), two_arms)
    assert spec_to_dict(spec)["formulas"]["p0"] == "F (p100 & F p200)"


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("", "the answer is empty"),
        ("[1, 2]", "must be a JSON object"),
        ('{"root": "p0"}', "'formulas' is missing"),
        ('{"root": "p0", "formulas": [{"name": "p0"}]}', "formulas[0] must be an object"),
        ('{"root": "p0", "formulas": {"p0": "F p100", "p100": "F delivered(bottle A)"}}', "p100"),
        (
            '{"root": "p0", "formulas": {"p0": "F p100 & F p200", '
            '"p100": "F delivered(bottle, A)", "p200": "F delivered(bottle, B)"}}',
            "handed over only once",
        ),
        (
            '{"root": "p0", "formulas": {"p0": "F p100", '
            '"p100": "F delivered(bottle, A) & G !delivered(bottle, A)"}}',
            "unsatisfiable",
        ),
    ],
)
def test_malformed_answers(two_arms: Scene, text: str, message: str) -> None:
    with pytest.raises(AnswerError) as info:
        check_answer(text, two_arms)
    assert message in str(info.value)


def test_root_can_accept_finds_a_run(two_arms: Scene) -> None:
    spec, _ = check_answer(content("two_deliveries.json"), two_arms)
    assert root_can_accept(spec)


# -- the repair loop and tokens --------------------------------------------------------------


def test_first_answer_accepted_counts_its_tokens(two_arms: Scene) -> None:
    client = FakeClient("two_deliveries.json")
    g = grounder(client).ground(TWO, two_arms)
    assert g.tokens == TokenUsage(452, 71)
    assert g.rounds == 1 and g.entities == ("bottle", "A", "chips", "B")
    call = client.calls[0]
    assert call["model"] == "gpt-4o-mini" and call["temperature"] == 0.0
    assert call["response_format"]["type"] == "json_schema"
    assert call["response_format"]["json_schema"]["schema"] == answer_schema(two_arms)


def test_repair_round_sends_the_precise_error_back(two_arms: Scene) -> None:
    client = FakeClient("unknown_cup.json", "repaired_bottle.json")
    g = grounder(client).ground("give A the cup", two_arms)
    assert spec_to_dict(g.spec)["formulas"]["p100"] == "F delivered(bottle, A)"
    assert g.tokens == TokenUsage(447 + 560, 49 + 50)  # summed over both queries
    assert g.rounds == 2
    second = client.calls[1]["messages"]
    assert second[-2] == {"role": "assistant", "content": content("unknown_cup.json")}
    assert "'cup' is not an object of the scene; objects: bottle, chips" in second[-1]["content"]
    assert second[: len(client.calls[0]["messages"])] == client.calls[0]["messages"]


def test_repairs_are_bounded_and_the_error_carries_the_history(two_arms: Scene) -> None:
    client = FakeClient("prose.json", "same_step.json", "unknown_cup.json", "two_deliveries.json")
    with pytest.raises(LLMGroundingError) as info:
        grounder(client, max_repairs=2).ground(TWO, two_arms)
    err = info.value
    assert len(client.calls) == 3  # one query + two repairs; the fourth answer is never asked for
    assert err.history[0][1].startswith("the answer is not valid JSON")
    assert "rule 3" in err.history[1][1] and "'cup'" in err.history[2][1]
    assert "rejected 3 time(s)" in str(err) and "last error" in str(err)
    assert err.tokens == TokenUsage(441 + 452 + 447, 24 + 70 + 49)


def test_no_repair_when_max_repairs_is_zero(two_arms: Scene) -> None:
    client = FakeClient("prose.json")
    with pytest.raises(LLMGroundingError):
        grounder(client, max_repairs=0).ground(TWO, two_arms)
    assert len(client.calls) == 1


def test_declined_instruction_is_not_repaired(two_arms: Scene) -> None:
    client = FakeClient("declined.json", "two_deliveries.json")
    with pytest.raises(GroundingError, match="no cup in the scene"):
        grounder(client).ground("give A the cup", two_arms)
    assert len(client.calls) == 1


def test_falls_back_to_json_mode_then_remembers(two_arms: Scene) -> None:
    client = FakeClient(
        "fenced_sequence.json", "two_deliveries.json", reject_formats=("json_schema",)
    )
    llm = grounder(client)
    g = llm.ground("give A the bottle, then put the chips on the shelf", two_arms)
    assert spec_to_dict(g.spec)["formulas"]["p200"] == "F placed(chips, shelf)"
    kinds = [c.get("response_format", {}).get("type") for c in client.calls]
    assert kinds == ["json_schema", "json_object"]
    llm.ground(TWO, two_arms)
    assert client.calls[-1]["response_format"]["type"] == "json_object"  # not json_schema again


def test_falls_back_on_a_server_error_naming_the_format(two_arms: Scene) -> None:
    # llama-cpp-python's server answers an unknown response_format type with HTTP 500
    class ServerError(Exception):
        status_code = 500

    client = FakeClient("two_deliveries.json")
    create = client.chat.completions.create

    def picky(**kwargs: object) -> object:
        fmt = kwargs.get("response_format")
        if isinstance(fmt, dict) and fmt["type"] == "json_schema":
            raise ServerError(
                "Error code: 500 - {'loc': ('body', 'response_format', 'type'), "
                "'msg': \"Input should be 'text' or 'json_object'\"}"
            )
        return create(**kwargs)

    client.chat.completions.create = picky
    llm = grounder(client)
    llm.ground(TWO, two_arms)
    assert llm.modes == ["json_object", "text"]


def test_falls_back_to_plain_text(two_arms: Scene) -> None:
    client = FakeClient("two_deliveries.json", reject_formats=("json_schema", "json_object"))
    grounder(client).ground(TWO, two_arms)
    assert "response_format" not in client.calls[-1]


def test_endpoint_failure_is_a_grounding_error(two_arms: Scene) -> None:
    class Down:
        class chat:
            class completions:
                @staticmethod
                def create(**_: object) -> object:
                    raise ConnectionError("connection refused")

    with pytest.raises(GroundingError, match="connection refused"):
        LLMGrounder(LLMConfig(base_url="http://localhost:9/v1"), client=Down()).ground(
            TWO, two_arms
        )


def test_update_through_llm_grounder(two_arms: Scene) -> None:
    running = spec_from_dict(
        {"root": "p0", "formulas": {"p0": "F p100", "p100": "F delivered(chips, B)"}}
    )
    client = FakeClient("repaired_bottle.json")
    g = grounder(client).ground("Also give Person A the bottle", two_arms, running)
    assert g.update is not None and g.update.kind == "add"
    assert g.tokens == TokenUsage(560, 50)
    assert "Instruction: give Person A the bottle" in client.calls[0]["messages"][-1]["content"]
    assert set(g.spec.names) == {"p0_1", "p0", "p100", "p200"}


# -- recorded shapes and the real client -----------------------------------------------------


@pytest.mark.parametrize("path", sorted(FIXTURES.glob("*.json")), ids=lambda p: p.name)
def test_fixtures_are_openai_chat_completions(path: Path) -> None:
    types = pytest.importorskip("openai.types.chat")
    completion = types.ChatCompletion.model_validate(json.loads(path.read_text(encoding="utf-8")))
    assert completion.usage is not None and completion.usage.total_tokens > 0


def test_real_client_is_built_for_the_endpoint() -> None:
    pytest.importorskip("openai")
    client = make_openai_client(LLMConfig(base_url="http://localhost:11434/v1", model="llama3.2"))
    assert str(client.base_url).rstrip("/") == "http://localhost:11434/v1"


def test_missing_openai_names_the_extra(monkeypatch: pytest.MonkeyPatch) -> None:
    import builtins

    real = builtins.__import__

    def fake_import(name: str, *args: object, **kwargs: object) -> object:
        if name == "openai":
            raise ImportError("No module named 'openai'")
        return real(name, *args, **kwargs)  # type: ignore[arg-type]

    monkeypatch.setattr(builtins, "__import__", fake_import)
    with pytest.raises(BackendUnavailableError, match=r"pip install 'hltl\[llm\]'"):
        make_openai_client(LLMConfig(base_url="http://localhost:11434/v1"))


# -- configuration ---------------------------------------------------------------------------


def test_config_from_file_then_env(tmp_path: Path) -> None:
    file = tmp_path / "llm.toml"
    file.write_text(
        '[llm]\nbase_url = "http://localhost:8000/v1"\nmodel = "qwen2.5"\nmax_repairs = 1\n'
        'api_key_env = "MY_KEY"\n',
        encoding="utf-8",
    )
    cfg = load_config(file, env={"MY_KEY": "sk-file"})
    assert (cfg.base_url, cfg.model, cfg.max_repairs, cfg.api_key) == (
        "http://localhost:8000/v1",
        "qwen2.5",
        1,
        "sk-file",
    )
    cfg = load_config(file, env={"HLTL_LLM_MODEL": "llama3.2", "HLTL_LLM_API_KEY": "sk-env"})
    assert (cfg.model, cfg.api_key) == ("llama3.2", "sk-env")
    assert "sk-env" not in repr(cfg)


def test_config_defaults_without_file(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("HOME", str(tmp_path))
    cfg = load_config(env={"HLTL_LLM_BASE_URL": "http://localhost:11434/v1"})
    assert cfg.base_url == "http://localhost:11434/v1" and cfg.model == "gpt-4o-mini"


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("model = 3\n", "model must be str"),
        ("colour = 'red'\n", "unknown key 'colour'"),
        ("x = \n", "not valid TOML"),
    ],
)
def test_bad_config_files(tmp_path: Path, text: str, message: str) -> None:
    file = tmp_path / "llm.toml"
    file.write_text(text, encoding="utf-8")
    with pytest.raises(GroundingError, match=message):
        load_config(file, env={})


def test_make_grounder_names() -> None:
    assert type(make_grounder("offline")).__name__ == "OfflineGrounder"
    with pytest.raises(GroundingError, match="unknown grounder 'gpt'"):
        make_grounder("gpt")


# -- live (opt-in) -----------------------------------------------------------------------------


@pytest.mark.live
@pytest.mark.skipif(not os.environ.get("HLTL_LLM_BASE_URL"), reason="set HLTL_LLM_BASE_URL")
def test_live_endpoint_grounds_two_deliveries(two_arms: Scene) -> None:
    from hltl.spec.equivalence import equivalent

    g = LLMGrounder().ground(TWO, two_arms)
    expected = spec_from_dict(
        {
            "root": "p0",
            "formulas": {
                "p0": "F p100 & F p200",
                "p100": "F delivered(bottle, A)",
                "p200": "F delivered(chips, B)",
            },
        }
    )
    assert equivalent(g.spec, expected)
    assert g.tokens.prompt > 0 and g.tokens.completion > 0


def test_root_can_accept_rejects_an_unreachable_root() -> None:
    spec = spec_from_dict(
        {"root": "p0", "formulas": {"p0": "F p100 & G !p100", "p100": "F delivered(bottle, A)"}},
        check_automata=False,
    )
    assert not root_can_accept(spec)
