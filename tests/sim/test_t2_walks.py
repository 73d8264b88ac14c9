"""T2-style H-MOVEs in the suite's trials and the ablation's per-cell reporting."""

from __future__ import annotations

import pytest

from hltl.bench.report import format_ablation_groups
from hltl.bench.suite import AblationOptions, TrialResult, Variant
from hltl.errors import HltlError
from hltl.planner import PlanStatus, plan
from hltl.sim.dynamic import full_spec, make_trial, walk_kind
from hltl.sim.events import HumanMove
from hltl.world.geometry import human_in_workspace


def test_walk_kinds() -> None:
    assert [walk_kind("mixed", i) for i in range(4)] == ["random", "t2", "random", "t2"]
    assert walk_kind("t2", 0) == "t2" and walk_kind("random", 1) == "random"
    with pytest.raises(HltlError, match="unknown walks"):
        walk_kind("zigzag", 0)


@pytest.mark.parametrize(("config", "index"), [("2-2", 0), ("1-2", 1), ("4-4-line", 2)])
def test_a_t2_walk_leaves_mid_delivery_for_other_robots(config: str, index: int) -> None:
    t = make_trial(config, index, walks="t2")
    assert t.walk == "t2"
    mover, dest = t.move
    (walk,) = [e for e in t.events.timed if isinstance(e, HumanMove)]
    assert (walk.human, walk.to) == (mover, dest)
    base = plan(t.scene, t.scenario.spec)
    assert base.status is PlanStatus.SOLVED
    serving = {r.id for r in t.scene.robots if human_in_workspace(r, dest, t.scene.human_reach)}
    # some delivery to the mover is under way at the walk's start and its giver cannot serve
    # the destination
    ok = False
    for step in base.steps:
        for a in step.actions:
            if a.skill == "handover_r2h" and a.human == mover:
                first = min(s.start for s in base.steps for b in s.actions if b.object == a.object)
                if first <= walk.t <= step.start and a.robots[0] not in serving:
                    ok = True
    assert ok
    moved = [h for h in t.scene.humans if h.id == mover]
    assert moved and moved[0].position != dest
    assert plan(t.scene, full_spec(t)).status is PlanStatus.SOLVED


def test_one_robot_cells_keep_the_random_walk_and_random_trials_do_not_change() -> None:
    t = make_trial("2-1", 1, walks="t2")
    assert t.walk == "random"
    assert t.events.to_list() == make_trial("2-1", 1).events.to_list()
    assert make_trial("2-2", 2, walks="mixed").events == make_trial("2-2", 2).events
    assert make_trial("2-2", 3, walks="mixed").walk == "t2"


def _r(config: str, index: int, variant: str, time: float, walk: str) -> TrialResult:
    return TrialResult(
        "hltl",
        config,
        index,
        index,
        "ok",
        success=True,
        time_cost=time,
        h_idle=50.0,
        r_idle=40.0,
        variant=variant,
        extra={"walk": walk, "anticipations": 1 if variant == "antic-goal" else 0},
    )


def test_groups_split_one_robot_from_multi_robot_and_walk_kinds() -> None:
    rs = [
        _r("2-1", 0, "full", 5.0, "random"),
        _r("2-1", 0, "antic-goal", 5.0, "random"),
        _r("2-2", 1, "full", 6.0, "t2"),
        _r("2-2", 1, "antic-goal", 4.0, "t2"),
        _r("2-2", 0, "full", 7.0, "random"),
    ]
    text = format_ablation_groups(rs, [Variant("full"), Variant("antic-goal")])
    lines = text.splitlines()
    assert "| 1 robot | full | 1 | 100 | 5.00 | 50.0 | 40.0 | 0.00 |" in lines
    assert "| multi-robot, T2 walk | + anticipation (goal-directed) | 1 | 100 | 4.00 |" in text
    # 2-2#0 has no antic-goal result: not paired, so no time for its cell
    assert "| multi-robot, random walk | full | 1 | 100 | – |" in text
    assert "| 2-2 | full | 2 | 100 | 6.00 |" in text


def test_ablation_walk_option() -> None:
    opts = AblationOptions(trials=1, walks="mixed", variants_text="full")
    assert "--walks mixed" in opts.command()
    assert all(j.walks == "mixed" for j in opts.trial_jobs())
    with pytest.raises(HltlError, match="--walks"):
        AblationOptions(walks="t3")
