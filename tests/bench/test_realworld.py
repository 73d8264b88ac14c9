"""T1–T6 of the paper's real-world study (§V-B) in the 3D simulator."""

from __future__ import annotations

import importlib.util
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from hltl.bench.realworld import (
    TASKS,
    WORDING,
    Result3D,
    _replans,
    format_t16,
    make_task,
    run_task,
    summarise3d,
)
from hltl.cli.main import main
from hltl.errors import HltlError
from hltl.execution.log import Dispatch, LogRecord, PolicyReplan, Replan
from hltl.sim.events import HumanMove, Instruction
from hltl.world.geometry import human_in_workspace, reaches

needs_mujoco = pytest.mark.skipif(
    importlib.util.find_spec("mujoco") is None, reason="needs the sim3d extra (mujoco)"
)


def _serving(task: object, p: tuple[float, float, float]) -> list[str]:
    scene = task.scene  # type: ignore[attr-defined]
    return [r.id for r in scene.robots if human_in_workspace(r, p, scene.human_reach)]


@pytest.mark.parametrize("name", [t for t in TASKS if t != "T2"])
def test_each_scenario_is_as_the_paper_words_it(name: str) -> None:
    t = make_task(name, 3)
    assert t == make_task(name, 3) and t != make_task(name, 4)
    assert {r.id: (r.reach, r.model) for r in t.scene.robots} == {
        "r1": (0.7, "elfin3"),
        "r2": (0.9, "ur5"),
    }
    people = {h.id: _serving(t, h.position) for h in t.scene.humans}
    assert len(people) == (2 if name in ("T4", "T5", "T6") else 1)
    assert people["A"] == ["r1"] and people.get("B", ["r2"]) == ["r2"]
    reach = {
        o.id: [r.id for r in t.scene.robots if reaches(r, o.position)] for o in t.scene.objects
    }
    if name in ("T1", "T3"):
        assert reach["chips"] == ["r2"]  # distant for A
    if name == "T3":
        assert reach["bottle"] == ["r1"]  # nearby for A
    if name == "T4":
        assert reach["cup"] == ["r1", "r2"]  # in the shared workspace
    if name == "T5":  # both distant: A's bottle on r2's side, B's chips on r1's
        assert reach["bottle"] == ["r2"] and reach["chips"] == ["r1"]
    if name == "T6":
        moves = [e for e in t.events.timed if isinstance(e, HumanMove)]
        assert {m.human for m in moves} == {"A", "B"}
        for m in moves:  # each ends on the other robot's side
            assert _serving(t, m.to) == (["r2"] if m.human == "A" else ["r1"])
    said = [e for e in t.events.timed if isinstance(e, Instruction)]
    assert len(said) == (1 if name in ("T3", "T4") else 0)


def test_unknown_task() -> None:
    with pytest.raises(HltlError, match="T9"):
        make_task("T9", 0)


def test_replans_count_regenerations_not_routine_steps() -> None:
    recs: list[LogRecord] = [
        Replan(t=0.0, trigger=t)
        for t in ("initial", "progress", "goal", "context+progress", "halt:intrusion")
    ]
    recs.append(PolicyReplan(t=0.0, source="greedy", trigger="script_end"))
    assert _replans([*recs, Dispatch(t=0.0, step=0, actions=[])]) == 3


def test_summary_and_table() -> None:
    rs = [
        Result3D("T1", 0, "hltl", True, True, 10.0, 0, "", 1.0),
        Result3D("T1", 1, "hltl", True, False, 12.0, 4, "4 replans", 1.0),
        Result3D("T1", 0, "greedy", False, False, None, 1, "gave up", 1.0),
    ]
    rows = summarise3d(rs)
    assert [(s.method, s.n, s.success, s.time) for s in rows] == [
        ("hltl", 2, 50.0, (10.0, 0.0)),
        ("greedy", 1, 0.0, None),
    ]
    assert "not run" not in format_t16(rows)
    table = format_t16(rows, {"smart-llm": "no LLM configured"})
    assert "| T1 | hltl | 2 | 50 | 10.00 ± 0.00 | 2.00 ± 2.83 |" in table
    assert "| T1 | Greedy-R | 1 | 0 | – |" in table
    assert "| T1–T6 | SMART-LLM-R | – | not run: no LLM configured | – | – |" in table


@needs_mujoco
def test_t2_walk_starts_during_the_hand_over_and_both_methods_run() -> None:
    t = make_task("T2", 0, timing="cost")
    (walk,) = t.events.timed
    assert isinstance(walk, HumanMove) and _serving(t, walk.to) == ["r2"]
    # with cost timing the hand-over runs 0.5-1.1 s (pick 0.5 s, then 0.6 s)
    assert 0.5 <= walk.t <= 1.1
    for method in ("hltl", "greedy"):
        r = run_task(t, method, timing="cost")
        assert r.goals_met and r.time_cost is not None, r


def _answer(script: str) -> Callable[[list[dict[str, str]]], dict[str, Any]]:
    """A chat function answering every query with ``script`` (an OpenAI-shaped response)."""

    def chat(messages: list[dict[str, str]]) -> dict[str, Any]:
        return {
            "choices": [{"message": {"content": f"```python\n{script}\n```"}}],
            "usage": {"prompt_tokens": 800, "completion_tokens": 60},
        }

    return chat


@needs_mujoco
def test_smart_llm_runs_on_a_scenario_when_an_llm_answers() -> None:
    """T1 with a recorded answer: the distant chips go r2 → r1 → A; a script that does not
    parse fails the trial (the code path an endpoint would take)."""
    t = make_task("T1", 0, timing="cost")
    relay = (
        'pick("r2", "chips")\nhandover_r2r("r2", "r1", "chips")\nhandover_r2h("r1", "chips", "A")'
    )
    good = run_task(t, "smart-llm", timing="cost", chat=_answer(relay))
    assert good.success and good.time_cost is not None and good.method == "smart-llm", good
    broken = run_task(t, "smart-llm", timing="cost", chat=_answer("for o in x\n    pick(o)"))
    assert not broken.success and "not executable" in broken.reason


@needs_mujoco
def test_cli_writes_section_and_figure(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    for var in ("HLTL_LLM_BASE_URL", "HLTL_LLM_CONFIG", "HLTL_LOCAL_MODEL"):
        monkeypatch.delenv(var, raising=False)
    monkeypatch.setattr("hltl.bench.baselines.smart_llm.DEFAULT_CONFIG_PATH", tmp_path / "none")
    out, fig = tmp_path / "b.md", tmp_path / "figures" / "t16.png"
    argv = ["bench", "realworld", "--trials", "1", "--tasks", "T1", "--jobs", "1"]
    assert main([*argv, "--timing", "cost", "--write", str(out), "--figure", str(fig)]) == 0
    text = out.read_text()
    assert "<!-- realworld:begin -->" in text and WORDING["T1"] in text
    assert "| T1–T6 | SMART-LLM-R | – | not run: no LLM configured" in text
    assert fig.stat().st_size > 1000


@pytest.mark.parametrize(
    ("argv", "bad"), [(["--tasks", "T1,T7"], "T7"), (["--methods", "hltl,gpt"], "'gpt'")]
)
def test_cli_rejects_unknown_tasks_and_methods(
    capsys: pytest.CaptureFixture[str], argv: list[str], bad: str
) -> None:
    assert main(["bench", "realworld", *argv]) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("error: ") and bad in err[0]
