"""The log checker judges preconditions with the reach the run used (issue 17): a pick that the
Elfin-3's reachability map allows beyond its 0.7 m reach sphere (T4#9's cup at 0.716 m) is
sound in a log run with the maps, and a pick outside the map is not."""

from __future__ import annotations

import dataclasses
import functools
import math
from typing import Any

import pytest

from hltl.execution.executor import Executor
from hltl.execution.log import Dispatch, EpisodeStart, EventLog, LogRecord, world_to_dict
from hltl.motion.kinematics import Arm
from hltl.motion.workspace import MapKinematics
from hltl.sim.episode import Cell, run_episode
from hltl.sim.invariants import check_invariants
from hltl.sim.simulator import Simulator
from hltl.skills.library import Action
from hltl.world.scene import Scene, scene_from_dict
from hltl.world.state import initial_world

INSIDE_MAP = 0.75  # m from the Elfin-3's base: beyond its 0.7 m sphere, inside its map
OUTSIDE_MAP = 0.95  # beyond both


def _scene(cup_at: float) -> Scene:
    return scene_from_dict(
        {
            "units": "m",
            "robots": [{"id": "r1", "base": [0.0, 0.0, 0.0], "reach": 0.7, "model": "elfin3"}],
            "objects": [{"id": "cup", "category": "cup", "position": [cup_at, 0.0, 0.05]}],
            "humans": [{"id": "A", "name": "Person A", "position": [-0.5, 0.6, 0.0]}],
        },
        source=f"cup at {cup_at} m",
    )


def _pick_log(scene: Scene, kinematics: str | None) -> list[LogRecord]:
    """episode_start and one dispatch of r1's pick of the cup in the scene's first world."""
    return [
        EpisodeStart(t=0.0, scene=scene.to_dict(), kinematics=kinematics),
        Dispatch(
            t=0.0,
            step=0,
            actions=[Action("pick", ("r1",), "cup").to_dict()],
            world=world_to_dict(initial_world(scene)),
        ),
    ]


def assert_arm_reaches(cup_at: float, reaches: bool) -> None:
    """The premise, by an oracle the checker does not use: the arm's position-only IK."""
    arm = Arm("r1", "elfin3", (0.0, 0.0, 0.0))
    res = arm.ik((cup_at, 0.0, 0.05), None, arm.home, prefer=arm.home)
    assert (res.q is not None) is reaches
    assert math.dist((cup_at, 0.0, 0.05), (0.0, 0.0, 0.0)) > 0.7


@pytest.mark.parametrize(
    ("cup_at", "kinematics", "sound"),
    [
        (INSIDE_MAP, "maps", True),  # the T4#9 case: the map allows it
        (INSIDE_MAP, None, False),  # the same log judged by the 0.7 m sphere
        (OUTSIDE_MAP, "maps", False),  # the map does not allow it
    ],
)
def test_a_pick_is_judged_by_the_kinematics_the_log_names(
    coarse_maps: dict[str, Any], cup_at: float, kinematics: str | None, sound: bool
) -> None:
    assert_arm_reaches(cup_at, reaches=cup_at == INSIDE_MAP)
    problems = check_invariants(_pick_log(_scene(cup_at), kinematics))
    if sound:
        assert problems == []
    else:
        assert problems == [
            "t=0.0: dispatched pick(cup) by r1 with a false precondition: "
            "pick(cup) by r1: out of reach or not a skill of the library"
        ]


def test_given_kinematics_override_the_log(coarse_maps: dict[str, Any]) -> None:
    scene = _scene(INSIDE_MAP)
    assert check_invariants(_pick_log(scene, None), MapKinematics(scene)) == []


def test_an_unknown_kinematics_name_is_one_problem() -> None:
    problems = check_invariants(_pick_log(_scene(INSIDE_MAP), "lidar"))
    assert problems == ["episode_start names unknown kinematics 'lidar'; expected spheres or maps"]


def test_an_episode_run_with_the_maps_names_them_and_passes(coarse_maps: dict[str, Any]) -> None:
    """The executor and the simulator reach the cup by the map; the log says so, and the
    checker, reading it, finds the run sound. Judged by the sphere, its pick is not."""
    scene = _scene(INSIDE_MAP)
    kin = MapKinematics(scene)

    def agent(cell: Cell, log: EventLog) -> Executor:
        return Executor(scene, None, cell, log=log, kinematics=kin)

    ep = run_episode(
        scene,
        instruction="Give Person A the cup.",
        simulator=functools.partial(Simulator, kinematics=kin),
        agent=agent,
    )
    assert ep.success, ep.metrics.reason
    start = ep.records[0]
    assert isinstance(start, EpisodeStart) and start.kinematics == "maps"
    assert check_invariants(ep.records) == []
    as_spheres = [dataclasses.replace(start, kinematics=None), *ep.records[1:]]
    problems = check_invariants(as_spheres)
    assert problems and all("dispatched pick(cup) by r1" in p for p in problems)
