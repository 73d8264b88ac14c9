"""Skill motion plans, candidate planning serial and parallel, the motion cost model, the CLI."""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from hltl.cli.main import main
from hltl.motion.cost import MotionCostModel
from hltl.motion.planning import (
    EXCHANGE_DWELL,
    CandidatePlanner,
    plan_action,
    r2r_candidates,
)
from hltl.planner import plan
from hltl.skills.cost import executed_duration
from hltl.skills.library import Action, Transition
from hltl.skills.semantics import ActionSemantics, apply, apply_all
from hltl.spec.hierarchy import load_spec
from hltl.world.scene import Scene
from hltl.world.state import initial_world

ROOT = Path(__file__).resolve().parents[2]


def _within_velocity_limits(arm: Any, tr: Any) -> bool:
    t = np.asarray(tr.times)
    q = np.asarray(tr.positions)
    v = np.abs(np.diff(q, axis=0)) / np.diff(t)[:, None]
    return bool(np.all(v <= arm.max_velocity * 1.05 + 1e-6))


def test_r2r_motion_meets_at_the_handover_pose(fig1_cell: Any) -> None:
    action = Action("handover_r2r", ("r1", "r2"), "bottle")
    motion = plan_action(fig1_cell, action, k=2)
    assert motion.plan is not None, motion.reason
    plan_ = motion.plan
    kinds = {(k, r) for _, k, r in plan_.events}
    assert kinds == {("grasp", "r2"), ("transfer", "r2"), ("release", "r1")}
    t_transfer = next(t for t, k, _ in plan_.events if k == "transfer")
    t_grasp = next(t for t, k, _ in plan_.events if k == "grasp")
    assert t_transfer == pytest.approx(t_grasp + EXCHANGE_DWELL)
    g = fig1_cell.arms["r1"]
    r = fig1_cell.arms["r2"]
    tg, tr = plan_.trajectory("r1"), plan_.trajectory("r2")
    assert tg is not None and tr is not None
    # while the object changes hands, the two tools hold it from opposite sides, a hand apart
    pg, rg = g.fk(tg.sample(t_transfer))
    pr, rr = r.fk(tr.sample(t_transfer))
    assert np.dot(rg[:, 2], rr[:, 2]) < -0.99
    assert 0.05 < np.linalg.norm(pg - pr) < 0.3
    for arm, traj in ((g, tg), (r, tr)):
        assert traj.positions[0] == pytest.approx(tuple(arm.home))
        assert _within_velocity_limits(arm, traj)
        assert traj.duration <= plan_.duration + 1e-9


def test_parallel_and_serial_candidate_planning_agree(fig1_cell: Any) -> None:
    action = Action("handover_r2r", ("r1", "r2"), "bottle")
    cands = r2r_candidates(fig1_cell, action, {}, k=4)
    assert len(cands) == 4
    best_s, all_s = CandidatePlanner(fig1_cell).plan(action, {}, cands)
    with CandidatePlanner(fig1_cell, workers=2) as pool:
        best_p, all_p = pool.plan(action, {}, cands)
    assert best_s is not None and best_p is not None
    assert sorted(m.duration for m in all_s) == pytest.approx(sorted(m.duration for m in all_p))
    assert best_s.duration == pytest.approx(best_p.duration)
    first, tried = CandidatePlanner(fig1_cell).plan(action, {}, cands, mode="first")
    assert first is not None and len(tried) <= len(cands)


def test_fig1_planned_with_motion_durations(fig1: Scene, fig1_cell: Any) -> None:
    spec = load_spec(ROOT / "examples" / "specs" / "fig1.yaml")
    cost = MotionCostModel(fig1_cell)
    result = plan(fig1, spec, kinematics=fig1_cell.kinematics, cost=cost, timeout=120)
    assert result.solved, result.reason
    steps = result.steps
    assert result.makespan == pytest.approx(sum(s.duration for s in steps))
    done = {(a.skill, a.object, a.human) for s in steps for a in s.actions}
    assert ("handover_r2h", "bottle", "A") in done and ("handover_r2h", "chips", "B") in done
    # every step lasts as long as its slowest motion plan, and each has one
    for s in steps:
        durations = [
            m.duration for (a, _), m in cost.plans.items() if a in s.actions and m.plan is not None
        ]
        assert durations
        # the step is as long as one of its instances' motions from where its hands were
        assert any(abs(s.duration - d) < 1e-3 for d in durations)
        assert s.duration >= min(durations) - 1e-3
    # motion durations differ from the scene's fixed ones: real trajectories were timed
    assert all(s.duration > 1.0 for s in steps)


def test_planned_durations_are_the_dispatched_ones(fig1: Scene, fig1_cell: Any) -> None:
    """The planner searches from where the arms are and through the joints each motion leaves
    them in, as the executor dispatches: replaying the plan, every motion from where the
    previous one left the arm, gives each step the duration the plan gave it."""
    spec = load_spec(ROOT / "examples" / "specs" / "fig1.yaml")
    cost = MotionCostModel(fig1_cell)
    result = plan(fig1, spec, kinematics=fig1_cell.kinematics, cost=cost, timeout=120)
    assert result.solved, result.reason
    ep = cost.for_episode()
    sem = ActionSemantics.of(fig1, kinematics=fig1_cell.kinematics, cost=ep)
    world = initial_world(fig1)
    acted: dict[str, int] = {}
    for step in result.steps:
        hands = dict(world.hands)
        transitions = []
        longest = 0.0
        for a in step.actions:
            tr = sem.transition(a, world)
            assert isinstance(tr, Transition)
            motion = ep.motion_plan(a, tr, hands)
            assert motion is not None
            longest = max(longest, executed_duration(ep, a, tr, motion.duration))
            transitions.append(tr)
            for r in a.robots:
                acted[r] = acted.get(r, 0) + 1
        assert step.duration == pytest.approx(longest, abs=1e-6), step
        world = apply_all(world, transitions)
    # some arm moved again from where its previous motion left it (a chained start)
    assert max(acted.values()) >= 2


def test_motion_cli_handover_json(fig1_cell: Any, capsys: pytest.CaptureFixture[str]) -> None:
    scene = str(ROOT / "examples" / "scenes" / "fig1.yaml")
    code = main(
        ["motion", "handover", "--scene", scene, "--giver", "r1", "--receiver", "r2", "--json"]
    )
    out = json.loads(capsys.readouterr().out)
    assert code == 0 and out["status"] == "found"
    assert len(out["pose"]["position"]) == 3
    assert len(out["pose"]["giver"]["q"]) == 6 and len(out["pose"]["receiver"]["q"]) == 6
    assert out["candidates"][0]["score"] >= out["candidates"][-1]["score"]


@pytest.mark.parametrize(
    ("argv", "needle"),
    [
        (["handover", "--giver", "r1", "--receiver", "r1"], "both 'r1'"),
        (["handover", "--giver", "r1", "--receiver", "zz"], "unknown robot 'zz'"),
        (["r2h", "--robot", "r1", "--human", "A", "--height", "4"], "implausible"),
        (["skill", "--skill", "pick", "--robots", "r1,r2", "--object", "bottle"], "needs 1"),
    ],
)
def test_motion_cli_rejects_bad_input(
    fig1_cell: Any, argv: list[str], needle: str, capsys: pytest.CaptureFixture[str]
) -> None:
    scene = str(ROOT / "examples" / "scenes" / "fig1.yaml")
    code = main(["motion", argv[0], "--scene", scene, *argv[1:]])
    err = capsys.readouterr().err
    assert code == 1
    assert err.startswith("error: ") and needle in err and err.count("\n") == 1


def test_place_puts_the_object_on_the_surface_within_reach(fig1: Scene, fig1_cell: Any) -> None:
    from hltl.motion.planning import placement_point

    action = Action("place", ("r1",), "bottle", surface="shelf")
    p = placement_point(fig1_cell, action)
    shelf = fig1.surface("shelf")
    assert abs(p[0] - shelf.center[0]) <= shelf.size[0] / 2
    assert abs(p[1] - shelf.center[1]) <= shelf.size[1] / 2
    assert p[2] == shelf.center[2]
    assert fig1_cell.kinematics.reaches(fig1.robot("r1"), (p[0], p[1], p[2] + 0.11))
    motion = plan_action(fig1_cell, action)
    assert motion.plan is not None, motion.reason
    assert [k for _, k, _ in motion.plan.events] == ["release"]


def test_run_with_motion_completes_fig1(fig1_cell: Any, capsys: pytest.CaptureFixture[str]) -> None:
    scene = str(ROOT / "examples" / "scenes" / "fig1.yaml")
    spec = str(ROOT / "examples" / "specs" / "fig1.yaml")
    code = main(["run", "--scene", scene, "--spec", spec, "--motion", "--json", "--no-predict"])
    metrics = json.loads(capsys.readouterr().out)
    assert code == 0 and metrics["success"] and metrics["deliveries"] == 2
    # durations come from motion plans, not the scene's fixed 0.5 s per skill
    assert metrics["time_cost"] > 2.0
    # with --sim mujoco as well: tests/sim3d/test_motion_mujoco.py


def test_dispatched_motions_chain_through_the_arms_joints_within_an_episode(
    fig1: Scene, fig1_cell: Any
) -> None:
    """The executor's motions start where the episode's previous dispatched plan left the arm
    (so the 3D simulator plays them as given), and so do the durations asked of the model then;
    a new episode starts from scratch."""
    sem = ActionSemantics.of(fig1, kinematics=fig1_cell.kinematics)
    w0 = initial_world(fig1)
    pick = Action("pick", ("r1",), "bottle")
    give = Action("handover_r2h", ("r1",), "bottle", human="A")
    tr0 = sem.transition(pick, w0)
    assert isinstance(tr0, Transition)
    w1 = apply(w0, tr0)
    tr1 = sem.transition(give, w1)
    assert isinstance(tr1, Transition)
    h0, h1 = dict(w0.hands), dict(w1.hands)
    cost = MotionCostModel(fig1_cell)
    ep = cost.for_episode()
    assert ep.plans is cost.plans  # the plan cache is shared, the dispatch state is not
    planned = ep.duration(give, tr1, h1)
    first = ep.motion_plan(pick, tr0, h0)
    assert first is not None
    end = first.trajectory("r1")
    assert end is not None
    now = ep.duration(give, tr1, h1)  # from where the pick left the arm
    second = ep.motion_plan(give, tr1, h1)
    assert second is not None and (t := second.trajectory("r1")) is not None
    assert np.allclose(t.positions[0], end.positions[-1], atol=1e-9)
    # the duration from where the arm is is the dispatched motion's; a fresh model, whose arm
    # is at rest, times it from an IK nearest the rest pose, as the episode did before the pick
    assert now == executed_duration(ep, give, tr1, second.duration) != planned
    assert MotionCostModel(fig1_cell).duration(give, tr1, h1) == planned
    # the arm reporting its real tool position (not the transition's point) is recognised too
    ep2 = cost.for_episode()
    assert ep2.motion_plan(pick, tr0, h0) is not None
    tool = tuple(float(v) for v in fig1_cell.arm("r1").fk(end.positions[-1])[0])
    assert math.dist(tool, h1["r1"]) > 0.02
    again = ep2.motion_plan(give, tr1, {**h1, "r1": tool})
    assert again is not None and (a := again.trajectory("r1")) is not None
    assert np.allclose(a.positions[0], end.positions[-1], atol=1e-9)
    # another episode has no memory of this one's arms
    other = cost.for_episode().motion_plan(give, tr1, h1)
    assert other is not None and (o := other.trajectory("r1")) is not None
    assert not np.allclose(o.positions[0], end.positions[-1], atol=1e-3)
