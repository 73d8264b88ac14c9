"""Closed-loop episodes in the simulator, one per dynamic event type and more.

Every episode run here goes through :func:`run_checked`, which re-checks the log's invariants
(:func:`hltl.sim.invariants.check_invariants`): no action dispatched with a false precondition
in the executor's recorded world, no robot in two actions at once, no object delivered twice.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

from hltl.execution.executor import Executor, ExecutorConfig
from hltl.sim.episode import Episode, EpisodeConfig, run_episode
from hltl.sim.events import EventSchedule, events_from_dict, load_events
from hltl.sim.invariants import check_invariants
from hltl.sim.scenarios import catalogue
from hltl.sim.simulator import PerceptionModel, Simulator
from hltl.spec.monitor import MonitorState
from hltl.world.scene import Scene, load_scene

EVENTS = Path(__file__).resolve().parents[2] / "examples" / "events"
# each example events file with the instruction its header names
EXAMPLES = {
    "h_move_midhandover": "Give Person A the chips",
    "o_move": "Give Person A the bottle",
    "goal": "Give Person A the bottle",
    "res": "Give Person A the chips",
    "fail": "Give Person A the bottle and Person B the chips",
    "fig1": "Give Person A the chips and Person B the bottle",
    "demo": "Give Person A the bottle and Person B the chips",
}


@pytest.fixture
def cell(two_arms_path: Path) -> Scene:
    return load_scene(two_arms_path)


def run_checked(scene: Scene, **kw: Any) -> Episode:
    """run_episode, then the log's invariants (every episode in the tests goes through here)."""
    ep = run_episode(scene, **kw)
    assert check_invariants(ep.records) == []
    return ep


def _config(predict: bool = True, **perception: float) -> EpisodeConfig:
    return EpisodeConfig(
        perception=PerceptionModel(**perception),
        executor=ExecutorConfig(predict=predict, intrusion=predict),
    )


def _of(ep: Episode, kind: str) -> list[dict[str, Any]]:
    return [r for r in ep.records if r.type == kind]


def test_every_example_has_an_instruction() -> None:
    assert set(EXAMPLES) == {p.stem for p in EVENTS.glob("*.yaml")}


@pytest.mark.parametrize("predict", [True, False], ids=["predict", "reactive"])
@pytest.mark.parametrize("name", sorted(EXAMPLES))
def test_each_event_type_ends_in_success(cell: Scene, name: str, predict: bool) -> None:
    events = load_events(EVENTS / f"{name}.yaml", cell)
    ep = run_checked(
        cell, instruction=EXAMPLES[name], events=events, seed=1, config=_config(predict)
    )
    assert ep.success, ep.metrics.reason
    assert ep.metrics.violations == 0
    end = _of(ep, "episode_end")[-1]
    assert end.success and end.reason == "all goals met"


class QRecorder:
    """Records the monitor state and the number of monitor steps at every tick."""

    def __init__(self) -> None:
        self.seen: list[tuple[float, MonitorState, int]] = []

    def on_tick(self, t: float, sim: Simulator, executor: Executor) -> None:
        self.seen.append((t, executor.q, len(executor.trace)))


@pytest.mark.parametrize("predict", [True, False], ids=["predict", "reactive"])
def test_person_walking_into_the_rendezvous_mid_handover(cell: Scene, predict: bool) -> None:
    hook = QRecorder()
    ep = run_checked(
        cell,
        instruction="Give Person A the chips",
        events=load_events(EVENTS / "h_move_midhandover.yaml", cell),
        config=_config(predict),
        hooks=[hook],
    )
    assert ep.success
    (halt,) = _of(ep, "halt")
    assert halt.actions == [{"skill": "handover_r2r", "robots": ["r2", "r1"], "object": "chips"}]
    assert halt.kind == ("intrusion" if predict else "precondition")
    assert "inside both" in halt.reason
    # the replan after the halt keeps q: same finished formulas, and q only ever changes when
    # a step's symbol is read (never at a halt)
    after = next(r for r in _of(ep, "replan") if r.t >= halt.t)
    assert after.trigger.startswith("halt") and after.done == halt.done
    for (_, q0, n0), (_, q1, n1) in zip(hook.seen, hook.seen[1:], strict=False):
        assert q0 == q1 or n1 > n0
    # served directly by r2 once A stands in its workspace
    last = _of(ep, "action_done")[-1].action
    assert last == {"skill": "handover_r2h", "robots": ["r2"], "object": "chips", "human": "A"}


def test_fig1_predicted_plan_takes_over_after_the_halt(cell: Scene) -> None:
    ep = run_checked(
        cell,
        instruction=EXAMPLES["fig1"],
        events=load_events(EVENTS / "fig1.yaml", cell),
    )
    assert ep.success and ep.metrics.deliveries == 2
    (halt,) = _of(ep, "halt")
    (takeover,) = _of(ep, "takeover")
    predicts = [r for r in _of(ep, "predict") if r.t <= takeover.t]
    assert any(p.context == takeover.context and p.status == "solved" for p in predicts)
    assert halt.t < takeover.t
    # Person B's delivery went on during the halt
    b = next(r for r in _of(ep, "action_done") if r.action.get("human") == "B")
    assert halt.t < b.t <= takeover.t


def test_new_instruction_mid_episode_keeps_finished_deliveries(cell: Scene) -> None:
    ep = run_checked(
        cell,
        instruction="Give Person A the bottle",
        events=events_from_dict(
            {"events": [{"t": 1.5, "type": "instruction", "text": "Also give Person B the chips"}]},
            cell,
        ),
    )
    assert ep.success
    delivered = [
        r.action["object"] for r in _of(ep, "action_done") if r.action["skill"] == "handover_r2h"
    ]
    assert delivered == ["bottle", "chips"]
    (update,) = [g for g in _of(ep, "grounding") if g.update is not None]
    assert update.t == 1.5 and "p100" in update.done  # finished before, still finished
    assert "p100" in _of(ep, "episode_end")[0].done
    assert any(r.trigger == "goal" for r in _of(ep, "replan"))


def test_grasp_failures_end_in_success_or_a_logged_give_up(cell: Scene) -> None:
    events = events_from_dict(
        {"events": [{"type": "skill_failure", "skill": "pick", "probability": 0.2}]}, cell
    )
    outcomes = []
    for seed in range(20):
        ep = run_checked(
            cell,
            instruction="Give Person A the chips and Person B the bottle",
            events=events,
            seed=seed,
        )
        if ep.success:
            outcomes.append("success")
        else:
            (give_up,) = _of(ep, "give_up")
            assert "consecutive failed actions" in give_up["reason"]
            assert _of(ep, "episode_end")[0]["reason"] == give_up["reason"]
            outcomes.append("give-up")
    assert sum(1 for r in outcomes if r == "success") >= 15
    assert len(outcomes) == 20


def test_episodes_are_reproducible_from_their_seed(cell: Scene) -> None:
    events = load_events(EVENTS / "fail.yaml", cell)
    wander = events_from_dict(
        {"events": [{"t": 0.0, "type": "human_wander", "human": "B", "duration": 3.0}]}, cell
    )
    both = EventSchedule(wander.timed, events.failures)
    cfg = _config(noise=0.01, latency=0.05)

    def strip(ep: Episode) -> list[dict[str, Any]]:
        # wall-clock latencies are the only non-simulated numbers in a log
        return [{k: v for k, v in r.to_json().items() if k != "latency_ms"} for r in ep.records]

    kw: dict[str, Any] = {"instruction": EXAMPLES["fail"], "events": both, "config": cfg}
    a, b, c = (run_checked(cell, seed=s, **kw) for s in (4, 4, 5))
    assert strip(a) == strip(b)
    assert strip(a) != strip(c)


@pytest.mark.parametrize("scenario", catalogue(), ids=lambda s: s.name)
def test_catalogue_scenarios_with_a_wandering_person(scenario: Any) -> None:
    person = scenario.scene.human_ids[0]
    events = events_from_dict(
        {
            "events": [
                {"t": 0.2, "type": "human_wander", "human": person, "duration": 2.0, "speed": 0.8}
            ]
        },
        scenario.scene,
    )
    for seed in range(2):
        ep = run_checked(
            scenario.scene,
            spec=scenario.spec,
            events=events,
            seed=seed,
            config=EpisodeConfig(max_time=30.0),
        )
        if not ep.success:
            # a person wandering out of every workspace can make a delivery impossible for a
            # while; the executor must then say so
            assert _of(ep, "give_up") or _of(ep, "wait"), ep.metrics.reason


def test_replan_bench_rows() -> None:
    from hltl.bench.replan import bench_replan, format_rows

    rows = bench_replan([(2, 2, None)], [0])
    assert [(r.config, r.predict, r.episodes) for r in rows] == [
        ("2-2", True, 1),
        ("2-2", False, 1),
    ]
    assert all(r.successes == 1 and r.median_ms is not None for r in rows)
    assert rows[1].takeovers == 0  # no prediction, no takeover
    assert format_rows(rows).count("\n") == 3


def test_planning_latency_is_charged_and_takeovers_save_it(cell: Scene) -> None:
    events = load_events(EVENTS / "fig1.yaml", cell)
    costs = {}
    for predict in (True, False):
        cfg = EpisodeConfig(
            executor=ExecutorConfig(predict=predict, intrusion=predict, plan_latency=0.2)
        )
        ep = run_checked(cell, instruction=EXAMPLES["fig1"], events=events, config=cfg)
        assert ep.success
        costs[predict] = ep.metrics.time_cost
        # every critical-path planner call delays the next dispatch by 0.2 simulated seconds
        assert ep.metrics.time_cost >= 2.0 + 0.2 * (ep.metrics.planner_calls - 1)
    assert costs[True] < costs[False]
