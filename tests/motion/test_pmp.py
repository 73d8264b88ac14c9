"""P.M.P. in the closed loop: the executor charges the motion layer's measured hand-overs."""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import pytest

from hltl.bench.suite import TrialJob, Variant, run_trial
from hltl.execution.executor import Executor, ExecutorConfig
from hltl.execution.latency import LatencyModel
from hltl.execution.log import ActionStart, EventLog, Replan
from hltl.grounding.offline import OfflineGrounder
from hltl.motion.pmp import HandoverMotionTimer
from hltl.sim.dynamic import Trial, make_trial
from hltl.sim.episode import Cell, EpisodeConfig, run_episode
from hltl.skills.library import Action
from hltl.world.state import WorldState

# 1-2#2: two Elfin-3s (the test maps have them), the bottle on r1's side, Person A on r2's: the
# delivery needs a robot-to-robot hand-over
CONFIG, INDEX = "1-2", 2


class _Recording:
    """A motion timer that notes what each call returned."""

    def __init__(self, inner: HandoverMotionTimer) -> None:
        self.inner = inner
        self.calls: list[float] = []

    def __call__(self, world: WorldState, actions: Sequence[Action]) -> float:
        s = self.inner(world, actions)
        self.calls.append(s)
        return s


def _trial() -> Trial:
    trial = make_trial(CONFIG, INDEX, 0, "mixed")
    assert [r.model for r in trial.scene.robots] == ["elfin3", "elfin3"]
    return trial


def _episode(trial: Trial, timer: _Recording, latency: LatencyModel | None) -> list[Any]:
    config = ExecutorConfig(latency=latency, plan_latency=0.0)

    def agent(sim: Cell, log: EventLog) -> Executor:
        return Executor(trial.scene, None, sim, log=log, config=config, motion=timer)

    ep = run_episode(
        trial.scene,
        instruction=trial.instruction,
        events=trial.events,
        seed=trial.seed,
        config=EpisodeConfig(executor=config),
        grounder=OfflineGrounder(),
        agent=agent,
    )
    assert ep.success
    return list(ep.records)


MODEL = LatencyModel(planner_fixed_s=0.002, planner_per_node_s=1e-5, source="test")


@pytest.mark.parametrize(("workers", "latency"), [(0, None), (2, MODEL)])
def test_the_charge_is_the_motion_layers_measured_seconds(
    coarse_maps: dict[str, Any], workers: int, latency: LatencyModel | None
) -> None:
    trial = _trial()
    with HandoverMotionTimer(trial.scene, workers=workers) as inner:
        timer = _Recording(inner)
        records = _episode(trial, timer, latency)
    replans = [r for r in records if isinstance(r, Replan)]
    logged = [r.motion_s for r in replans if r.motion_s is not None]
    # one timer call per plan with a first step, its answer logged and charged as measured
    assert logged == [round(s, 6) for s in timer.calls]
    paid = [r for r in replans if r.source == "planner" and r.motion_s]
    assert paid
    for r in paid:
        assert r.charged_s is not None and r.motion_s is not None
        if latency is None:
            assert r.charged_s == r.motion_s  # a constant 0 s planner: only the motion
            continue
        cost = latency.planner(r.expanded, r.latency_ms / 1000.0) + r.motion_s
        if r.charge == "critical":
            assert r.charged_s == pytest.approx(cost, abs=2e-6)
        else:  # pipelined: paid beyond the step it overlaps
            assert r.charge == "pipelined" and -1e-6 <= r.charged_s <= cost + 2e-6
    # what the timer answered is what the motion layer measured, hand-over by hand-over
    planned = [m for m in inner.motions if m.plan is not None]
    assert planned and all(m.action.skill == "handover_r2r" for m in inner.motions)
    assert math.fsum(timer.calls) == pytest.approx(math.fsum(m.seconds for m in inner.motions))
    assert all(m.seconds > 0 for m in inner.motions)
    # and the charge delays the plan it was paid for: nothing starts before it is paid
    first = replans[0]
    starts = [r.t for r in records if isinstance(r, ActionStart)]
    assert first.charged_s is not None and min(starts) >= first.t + first.charged_s - 1e-6


def test_serial_and_pooled_timers_plan_the_same_handover(coarse_maps: dict[str, Any]) -> None:
    trial = _trial()
    world = WorldState(0.0, (), ())
    action = Action("handover_r2r", ("r1", "r2"), trial.scene.objects[0].id)
    pick = Action("pick", ("r1",), trial.scene.objects[0].id)
    with (
        HandoverMotionTimer(trial.scene) as serial,
        HandoverMotionTimer(trial.scene, workers=2) as pooled,
    ):
        s = serial(world, [pick, action])
        p = pooled(world, [action])
        assert serial.parallel is False and pooled.parallel is True
        (ms,), (mp,) = serial.motions, pooled.motions
        assert s == ms.seconds > 0 and p == mp.seconds > 0
        # the same candidate goal sets, planned on one process or two: the same motion
        assert ms.plan is not None and mp.plan is not None
        assert ms.duration == pytest.approx(mp.duration)
        assert [r for r, _ in ms.final] == [r for r, _ in mp.final] == ["r1", "r2"]
        # the same request from the same arms again is the plan in hand: no new planning
        assert serial(world, [action]) == 0.0 and len(serial.motions) == 1


def test_the_ablations_variants_run_the_motion_layer(coarse_maps: dict[str, Any]) -> None:
    v = Variant("no-pmp", motion="serial")
    res = run_trial(TrialJob("hltl", CONFIG, INDEX, 0, v, walks="mixed"))
    assert res.status == "ok" and res.success, res.reason
    assert res.extra["motion_calls"] >= 1 and res.extra["motion_s"] > 0
    bad = run_trial(TrialJob("hltl", CONFIG, INDEX, 0, Variant("x", motion="fast")))
    assert bad.status == "error" and "unknown motion mode 'fast'" in bad.reason
