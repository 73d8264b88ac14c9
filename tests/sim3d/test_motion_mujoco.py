"""``--motion`` in the 3D simulator: the MuJoCo arms start at the motion layer's rest pose and
play the trajectories the executor's motion cost model planned, without a jump."""

from __future__ import annotations

import functools
import json
import math
import os
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import numpy as np
import pytest

pytest.importorskip("mujoco")
pytest.importorskip("pinocchio")

from hltl.cli.main import main
from hltl.cli.run import _motion_options
from hltl.grounding.offline import OfflineGrounder
from hltl.motion.kinematics import Arm
from hltl.motion.planning import Cell, plan_action
from hltl.sim.episode import EpisodeConfig, run_episode
from hltl.sim3d.driver import MujocoSimulator
from hltl.sim3d.model import compile_scene
from hltl.skills.library import Action
from hltl.world.scene import Scene, load_scene

INSTRUCTION = "Give Person A the bottle and Person B the chips"


@pytest.fixture(scope="module")
def coarse_maps(tmp_path_factory: pytest.TempPathFactory) -> Iterator[None]:
    # reachability maps at 10 cm in a temporary cache (cheap; the motions are what is tested)
    with pytest.MonkeyPatch.context() as mp:
        mp.setenv("HLTL_CACHE", str(tmp_path_factory.mktemp("hltl-cache")))
        mp.setenv("HLTL_REACH_RESOLUTION", "0.1")
        yield


FIG1 = Path(__file__).resolve().parents[2] / "examples" / "scenes" / "fig1.yaml"


@pytest.fixture(scope="module")
def fig1() -> Scene:
    return load_scene(FIG1)


class _Poses:
    """Every posing of the MuJoCo arms, and how far each is from the plan it plays."""

    def __init__(self, sim: MujocoSimulator) -> None:
        self.sim = sim
        self.rows: list[tuple[float, dict[str, np.ndarray]]] = []
        self.worst = 0.0
        self.played = 0
        sim.on_pose.append(self)

    def __call__(self, t: float) -> None:
        sim = self.sim
        q = {rid: np.asarray(sim.stage.robot_q(rid)) for rid in sim.stage.sm.robots}
        self.rows.append((t, q))
        for rid in q:
            run = sim._running_plan(rid)
            if run is None:
                continue
            tr = run[0].plan.trajectory(rid)
            if tr is not None:
                want = np.asarray(tr.sample(run[1]))
                self.worst = max(self.worst, float(np.max(np.abs(want - q[rid]))))
                self.played += 1


def test_arms_start_at_the_motion_layers_rest_pose(fig1: Scene) -> None:
    sim = MujocoSimulator(fig1)
    for robot in fig1.robots:
        arm = Arm(robot.id, robot.model, robot.base)
        assert np.allclose(sim.stage.home[robot.id], arm.home)
        assert np.allclose(sim.stage.robot_q(robot.id), arm.home)
        assert math.dist(sim.stage.hand(robot.id), tuple(arm.fk(arm.home)[0])) < 1e-6


def test_mujoco_arms_play_the_executors_trajectories(fig1: Scene, coarse_maps: None) -> None:
    sims: list[MujocoSimulator] = []
    poses: list[_Poses] = []

    def factory(*args: Any, **kwargs: Any) -> MujocoSimulator:
        sim = MujocoSimulator(*args, **kwargs)
        sims.append(sim)
        poses.append(_Poses(sim))
        return sim

    cfg = EpisodeConfig()
    base = functools.partial(factory, timing="motion", model=compile_scene(fig1))
    extra = _motion_options(fig1, None, cfg, None, base)
    ep = run_episode(fig1, instruction=INSTRUCTION, config=cfg, grounder=OfflineGrounder(), **extra)
    assert ep.success
    (sim,), (watch,) = sims, poses
    # every action plays the trajectories the executor's motion layer planned: the first step
    # from the rest pose, later ones from where the episode's earlier plans left the arms, so
    # the driver plans none of them again
    infos = list(sim._plans.values())
    assert len(infos) == 4 and [i.source for i in infos] == ["given"] * 4
    assert watch.played > 100
    assert watch.worst <= 1e-9  # kinematic playback: the joints are the plan's samples
    # and the arms never jump: between posings no joint moves faster than its limit
    arms = {r.id: Arm(r.id, r.model, r.base) for r in fig1.robots}
    for (t0, q0), (t1, q1) in zip(watch.rows, watch.rows[1:], strict=False):
        for rid, arm in arms.items():
            step = np.abs(q1[rid] - q0[rid])
            # (1e-4 rad: where one plan ends and the next starts, within the time law's tolerance)
            assert np.all(step <= arm.max_velocity * (t1 - t0) * 1.05 + 1e-4), (rid, t0, t1)
    # the motions decide how long the actions last
    done = [r for r in ep.records if r.type == "action_done"]
    assert len(done) == 4


def test_a_plan_that_starts_elsewhere_is_planned_again(fig1: Scene) -> None:
    sim = MujocoSimulator(fig1)
    arm = sim._arms["r2"]
    # a pick planned from another configuration than the arm's rest pose
    away = {"r2": tuple(float(v) for v in arm.home + 0.3)}
    stale = plan_action(Cell(fig1), Action("pick", ("r2",), "chips"), away).plan
    assert stale is not None
    handle = sim.start(Action("pick", ("r2",), "chips"), 0.0, motion=stale)
    info = sim.motion_of(handle)
    assert info is not None and info.source == "hltl.motion"
    assert "starts away from the arms" in info.note
    tr = info.plan.trajectory("r2")
    assert tr is not None and np.allclose(tr.positions[0], arm.home)


def test_run_motion_with_the_3d_simulator(
    coarse_maps: None, capsys: pytest.CaptureFixture[str]
) -> None:
    assert os.environ["HLTL_REACH_RESOLUTION"] == "0.1"
    argv = ["run", "--scene", str(FIG1), "--instruction", INSTRUCTION, "--motion"]
    assert main([*argv, "--sim", "mujoco", "--json"]) == 0
    metrics = json.loads(capsys.readouterr().out.strip().splitlines()[-1])
    assert metrics["success"] and metrics["deliveries"] == 2
