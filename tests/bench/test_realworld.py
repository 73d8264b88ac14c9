"""T1–T6 of the paper's real-world study (§V-B) in the 3D simulator."""

from __future__ import annotations

import importlib.util
import math
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Any

import pytest

from hltl.bench import realworld
from hltl.bench.realworld import (
    TASKS,
    WORDING,
    Result3D,
    World3D,
    _bars,
    _replans,
    _world,
    contacts,
    format_t16,
    make_task,
    run_task,
    summarise3d,
    unplanned_motions,
)
from hltl.cli.main import main
from hltl.errors import HltlError
from hltl.execution.drivers import Handle
from hltl.execution.log import (
    ActionDone,
    ActionStart,
    Contact,
    Dispatch,
    LogRecord,
    PolicyReplan,
    Replan,
)
from hltl.grounding.offline import OfflineGrounder
from hltl.motion.trajectory import MotionPlan
from hltl.sim.episode import run_episode
from hltl.sim.events import HumanMove, Instruction
from hltl.sim3d.driver import MotionInfo
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
    assert "| T1 | hltl | 2 | 50 | 10.00 ± 0.00 | 2.00 ± 2.83 | 0 | 0 |" in table
    assert "| T1 | Greedy-R | 1 | 0 | – |" in table
    assert "| T1–T6 | SMART-LLM-R | – | not run: no LLM configured | – | – | – | – |" in table
    # a trial that ran an action without a motion plan is failed and counted in its column
    rows = summarise3d([Result3D("T2", 0, "hltl", True, False, 9.0, 1, "no motion plan", 1.0, 1)])
    assert rows[0].unplanned == 1 and rows[0].time is None
    assert format_t16(rows).splitlines()[-1].endswith("| 1 | 0 |")


def test_contacts_are_counted_per_trial_and_reported_without_failing_it() -> None:
    touch = [
        Contact(t=1.0, robot="r2", human="A", position=[0.7, 0.3, 0.3], depth=0.01),
        Contact(t=1.5, robot="r1", human="A", position=[0.2, 0.3, 0.3], depth=0.02),
    ]
    assert contacts([Dispatch(t=0.0, step=0, actions=[]), *touch]) == 2
    assert contacts([Dispatch(t=0.0, step=0, actions=[])]) == 0
    rs = [
        Result3D("T2", 0, "hltl", True, True, 9.0, 1, "", 1.0, contacts=2),
        Result3D("T2", 1, "hltl", True, True, 11.0, 1, "", 1.0),
    ]
    (row,) = summarise3d(rs)
    assert row.contacts == 1 and row.success == 100.0 and row.time == (10.0, 1.4142135623730951)
    assert format_t16([row]).splitlines()[-1].endswith("| 0 | 1 |")


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


def _timing_errors(records: Sequence[LogRecord]) -> list[float]:
    """Per finished action: how far its real duration is from what the executor expected."""
    started = {r.handle: r for r in records if isinstance(r, ActionStart)}
    return [
        abs((r.ended - started[r.handle].t) - float(started[r.handle].expected or 0.0))
        for r in records
        if isinstance(r, ActionDone) and r.handle in started
    ]


@needs_mujoco
@pytest.mark.skipif(importlib.util.find_spec("pinocchio") is None, reason="needs the motion extra")
def test_motion_mode_plans_with_the_durations_the_arms_take() -> None:
    """With --motion hltl's executor expects an action to last as long as the arms' motion
    (the first pick starts where the arm rests, so the 3D simulator plays the executor's own
    trajectory: equal to the microsecond); without, it expects the scene's fixed 0.5 s."""
    for motion in (True, False):
        t = make_task("T1", 0, motion=motion)
        world = _world(t.scene, "motion", motion)
        ep = run_episode(
            t.scene,
            instruction=t.instruction,
            events=t.events,
            seed=t.seed,
            grounder=OfflineGrounder(),
            simulator=world.simulator,
            agent=world.agent,
        )
        assert ep.success, ep.metrics.reason
        assert len(world.made) == 1
        first = _timing_errors(ep.records)[0]
        assert (first < 1e-5) if motion else (first > 1.0)


class _FakeSim:
    """Answers motion_of like the 3D simulator: one handle's motion came from its IK fallback."""

    def __init__(self, fallback: int) -> None:
        self.fallback = fallback

    def motion_of(self, handle: Handle) -> MotionInfo | None:
        plan = MotionPlan((), (), 1.0)
        if handle.id == self.fallback:
            return MotionInfo(plan, 0.0, "ik", "IK found no pose")
        return MotionInfo(plan, 0.0, "hltl.motion")


def test_actions_without_a_motion_plan_are_found_from_both_sides() -> None:
    def start(handle: int, skill: str, expected: float) -> ActionStart:
        act = {"skill": skill, "robots": ["r2", "r1"], "object": "chips"}
        return ActionStart(t=float(handle), handle=handle, action=act, expected=expected)

    recs: list[LogRecord] = [
        start(1, "pick", 4.0),
        start(2, "handover_r2r", math.inf),  # hltl's motion model had no plan (INFEASIBLE)
        start(3, "handover_r2h", 3.0),  # the simulator's planner failed: IK waypoints
    ]
    world = World3D(lambda: None, None, None, [_FakeSim(3)])  # type: ignore[arg-type]
    found = unplanned_motions(recs, world)
    assert len(found) == 2
    assert found[0].startswith("handover_r2r(chips) by r2→r1 at 2.00 s: hltl's motion model")
    assert "simulator has no motion plan, ran IK waypoints (IK found no pose)" in found[1]
    # a finite expectation is a planned motion, whatever its length
    assert unplanned_motions([start(4, "handover_r2r", 1000.0)], world) == []


@needs_mujoco
def test_a_trial_with_an_unplanned_motion_fails(monkeypatch: pytest.MonkeyPatch) -> None:
    """The time of such a trial is not a checked motion's: failed, with why, never timed."""
    t = make_task("T1", 0, timing="cost")
    ok = run_task(t, "hltl", timing="cost")
    assert ok.success and ok.unplanned == 0
    monkeypatch.setattr(realworld, "unplanned_motions", lambda records, world: ["pick(x) …"])
    bad = run_task(t, "hltl", timing="cost")
    assert not bad.success and bad.unplanned == 1
    assert bad.reason == "no motion plan: pick(x) …"
    assert summarise3d([bad])[0].time is None


def test_error_bars_stay_on_the_axis() -> None:
    """A std larger than the mean is not drawn below 0, and a mean off the replanning axis
    (T4's Greedy-R trial with 923 replans) gets no bar at all."""
    lo, hi = _bars([(1.0, 3.0), (47.1, 206.2), (math.nan, 0.0), (2.0, 0.5)], top=6.0)
    assert lo == [1.0, 0.0, 0.0, 0.5]
    assert hi == [3.0, 0.0, 0.0, 0.5]
