"""The 3D simulator against the discrete-event one: same episodes, same skills, arms that arrive."""

from __future__ import annotations

import functools
import math
from pathlib import Path
from typing import Any

import pytest

from hltl.execution.log import HumanMove as HumanMoveRecord
from hltl.execution.log import LogRecord
from hltl.sim import scenarios
from hltl.sim.episode import Episode, EpisodeConfig, run_episode
from hltl.sim.events import EventSchedule, HumanMove, events_from_dict, load_events
from hltl.spec.hierarchy import HSpec, load_spec, spec_from_dict
from hltl.world.scene import Scene, Vec3, load_scene, scene_from_dict

pytest.importorskip("mujoco")

from hltl.sim3d.driver import WALK_CLEARANCE, MujocoSimulator
from hltl.sim3d.model import compile_scene

SMALL_CELLS = ("1-1", "1-2", "2-1", "2-2")


def _skills(ep: Episode) -> list[tuple[str, tuple[str, ...], str, str | None]]:
    out = []
    for r in ep.records:
        if r.type == "action_done":
            a = r.action
            out.append((a["skill"], tuple(a["robots"]), a["object"], a.get("human")))
    return out


def _per_object(ep: Episode) -> dict[str, list[tuple[str, tuple[str, ...], str | None]]]:
    """Each object's skills in order: what 'the same sequence' means when steps run in parallel
    and motion durations decide which of two concurrent actions ends first."""
    out: dict[str, list[tuple[str, tuple[str, ...], str | None]]] = {}
    for skill, robots, obj, human in _skills(ep):
        out.setdefault(obj, []).append((skill, robots, human))
    return out


def _timed(ep: Episode) -> list[tuple[float, str]]:
    return [(round(r.t, 6), str(r.action)) for r in ep.records if r.type == "action_done"]


def _both(
    scene: Scene, spec: HSpec, events: EventSchedule | None, timing: str, **kw: Any
) -> tuple[Episode, Episode]:
    flat = run_episode(scene, spec=spec, events=events, seed=0)
    model = compile_scene(scene)
    sim = functools.partial(MujocoSimulator, timing=timing, model=model, **kw)
    return flat, run_episode(scene, spec=spec, events=events, seed=0, simulator=sim)


@pytest.mark.parametrize("name", SMALL_CELLS)
def test_small_cells_same_skills_motion_timing(name: str) -> None:
    cell = scenarios.get(name)
    spec = spec_from_dict(cell.spec_dict, source=name)
    flat, deep = _both(cell.scene, spec, None, "motion")
    assert flat.success and deep.success
    assert _per_object(deep) == _per_object(flat)
    # timing differs only through the motions: every action lasts its motion plan
    for rec in deep.records:
        if rec.type == "action_start":
            assert rec.expected > 0


@pytest.mark.parametrize("name", SMALL_CELLS)
def test_small_cells_identical_with_cost_timing(name: str) -> None:
    cell = scenarios.get(name)
    spec = spec_from_dict(cell.spec_dict, source=name)
    flat, deep = _both(cell.scene, spec, None, "cost")
    assert _timed(deep) == _timed(flat)
    assert deep.metrics.time_cost == pytest.approx(flat.metrics.time_cost)


def test_fig1_episode(examples_dir: Path) -> None:
    scene = load_scene(examples_dir / "scenes" / "fig1.yaml")
    spec = load_spec(examples_dir / "specs" / "fig1.yaml")
    events = load_events(examples_dir / "events" / "fig1.yaml", scene)
    # people walking straight (as in the discrete simulator): the same episode, exactly
    flat, deep = _both(scene, spec, events, "cost", walk_round_table=False)
    assert flat.success and deep.success
    assert _timed(deep) == _timed(flat)
    # with arm motions timing the actions, the person's walk meets a different stage of the
    # plan; the task is still done
    _, moving = _both(scene, spec, events, "motion")
    assert moving.success
    delivered = {(s[2], s[3]) for s in _skills(moving) if s[0] == "handover_r2h"}
    assert delivered == {("bottle", "A"), ("chips", "B")}


class _Watch:
    """Checks the embodiment at every tick: a held object rides rigidly on its hand, close to
    where the fingers are; a delivered one is in the person's hand; a resting one is where the
    log says, or being lifted or set down there."""

    def __init__(self) -> None:
        self.carried = 0
        self.delivered = 0
        self.offsets: dict[tuple[str, str], tuple[float, ...]] = {}

    def on_tick(self, t: float, sim: Any, executor: Any) -> None:
        st = sim.stage
        for oid in sim.scene.object_ids:
            status = sim.object_status(oid)
            at = tuple(float(v) for v in st.data.mocap_pos[st.sm.object_mocap[oid]])
            carry = sim._carry.get(oid)
            if status.loc.kind == "held":
                # the hands may be ahead of the log while an action on the object runs
                assert carry is not None
                assert carry[1] == status.loc.ref or sim._running_on(oid)
                self.carried += 1
            if carry is not None and carry[0] == "robot":
                # from the grasp event on (a pick's log entry comes when it ends) the object
                # rides rigidly on the hand, near the fingers
                hand = st.hand(carry[1])
                off = tuple(a - h for a, h in zip(at, hand, strict=True))
                assert math.hypot(*off) < 0.15, (oid, off)
                key = (oid, carry[1])
                if key in self.offsets:
                    assert math.dist(off, self.offsets[key]) < 1e-9
                self.offsets[key] = off
            elif carry is not None:
                # a released handover: in the person's hand (the log says so when it ends)
                assert math.dist(at, st.human_hand(carry[1])) < 1e-9
                self.delivered += status.loc.kind == "delivered"
            else:
                assert math.dist(at, status.position) < 0.3, (oid, at, status)


def test_objects_follow_hands_and_grasps_are_reached(examples_dir: Path) -> None:
    scene = load_scene(examples_dir / "scenes" / "fig1.yaml")
    spec = load_spec(examples_dir / "specs" / "fig1.yaml")
    watch = _Watch()
    sims: list[MujocoSimulator] = []

    def make(*a: Any, **kw: Any) -> MujocoSimulator:
        sims.append(MujocoSimulator(*a, model=compile_scene(scene), **kw))
        return sims[0]

    ep = run_episode(scene, spec=spec, seed=0, simulator=make, hooks=(watch,))
    assert ep.success and watch.carried > 0 and watch.delivered > 0
    sim = sims[0]
    for act in sim._actions.values():
        info = sim.motion_of(act.handle)
        assert info is not None
        # both arms have models: every motion comes from hltl.motion's planner
        assert info.source == "hltl.motion", (act.handle.action, info.note)
        # the plan's trajectories use the model's joint names and end where IK put them
        for tr in info.plan.trajectories:
            assert tr.joint_names == sim.stage.sm.robots[tr.robot].joint_names
            assert tr.times[0] == 0.0 and tr.duration <= info.plan.duration + 1e-9


def _contact_scene() -> tuple[Scene, EventSchedule]:
    scene = scene_from_dict(
        {
            "robots": [{"id": "r1", "base": [0, 0, 0], "reach": 0.7, "model": "elfin3"}],
            "objects": [{"id": "cup", "category": "cup", "position": [0.3, -0.3, 0.05]}],
            "humans": [{"id": "A", "position": [1.5, 0.0, 0.0]}],
        }
    )
    events = events_from_dict(
        {
            "events": [
                {"t": 0.0, "type": "human_move", "human": "A", "to": [0.1, 0, 0], "speed": 1.0}
            ]
        },
        scene,
        "walk-in",
    )
    return scene, events


def test_person_walking_into_an_arm_is_a_logged_contact() -> None:
    scene, events = _contact_scene()
    spec = spec_from_dict({"root": "p0", "formulas": {"p0": "F picked(cup)"}}, source="t")
    records: list[LogRecord] = []
    sim = functools.partial(MujocoSimulator, model=compile_scene(scene))
    run_episode(scene, spec=spec, events=events, seed=0, simulator=sim, on_record=records.append)
    contacts = [r for r in records if r.type == "contact"]
    assert contacts and contacts[0].robot == "r1" and contacts[0].human == "A"
    # the person's torso or legs reach the arm's base after walking ~1.2 m at 1 m/s
    assert 0.9 < contacts[0].t < 1.6
    flat: list[LogRecord] = []
    run_episode(scene, spec=spec, events=events, seed=0, on_record=flat.append)
    assert not [r for r in flat if r.type == "contact"]


def test_dropped_object_rests_where_the_log_says(examples_dir: Path) -> None:
    scene = load_scene(examples_dir / "scenes" / "two_arms.yaml")
    spec = load_spec(examples_dir / "specs" / "fig1.yaml")
    events = events_from_dict(
        {
            "events": [
                {
                    "type": "skill_failure",
                    "skill": "handover_r2h",
                    "probability": 1.0,
                    "outcome": "drop",
                }
            ]
        },
        scene,
        "drops",
    )
    sims: list[MujocoSimulator] = []

    def make(*a: Any, **kw: Any) -> MujocoSimulator:
        sims.append(MujocoSimulator(*a, model=compile_scene(scene), use_motion_layer=False, **kw))
        return sims[0]

    records: list[LogRecord] = []
    run_episode(
        scene,
        spec=spec,
        events=events,
        seed=0,
        simulator=make,
        on_record=records.append,
        config=EpisodeConfig(max_time=12.0),
    )
    drops = [r for r in records if r.type == "object_drop"]
    assert drops
    st = sims[0].stage
    last = drops[-1]
    at = st.data.mocap_pos[st.sm.object_mocap[last.object]]
    status = sims[0].object_status(last.object)
    assert status.loc.kind in ("rest", "held")
    if status.loc.kind == "rest":
        assert math.dist(tuple(at), status.position) < 1e-9
    else:  # picked up again: on the hand, where the fingers closed (the driver's IK: at it)
        assert math.dist(tuple(at), st.hand(status.loc.ref)) < 0.01


def test_fk_matches_the_motion_layer(examples_dir: Path) -> None:
    pytest.importorskip("pinocchio")
    import numpy as np

    from hltl.motion.kinematics import Arm
    from hltl.sim3d.stage import Stage

    scene = load_scene(examples_dir / "scenes" / "fig1.yaml")
    stage = Stage(compile_scene(scene))
    rng = np.random.default_rng(7)
    for robot in scene.robots:
        arm = Arm(robot.id, robot.model, robot.base)
        rig = stage.sm.robots[robot.id]
        assert arm.joint_names == rig.joint_names
        for _ in range(5):
            q = rng.uniform(arm._seed_lo, arm._seed_hi)
            stage.set_robot(robot.id, q)
            stage.forward()
            p, rot = arm.fk(q)
            assert math.dist(tuple(p), stage.hand(robot.id)) < 1e-6
            z = stage.data.site_xmat[rig.hand_site].reshape(3, 3)[:, 2]
            assert np.allclose(rot[:, 2], z, atol=1e-6)


class _StraightWalks(MujocoSimulator):
    """The 3D simulator as it was until session 8: people walk straight, over the table."""

    def _route(self, start: Vec3, to: Vec3) -> list[Vec3]:
        return [to]


def _walk_past_the_ur5(simulator: type[MujocoSimulator]) -> tuple[MujocoSimulator, list[Vec3]]:
    """T6#0's cell with nobody else moving and no task: A walks from beside the Elfin-3 to
    where the old T6 sent them, 0.25 m in front of B's spot, straight past the UR5's base."""
    from hltl.bench.realworld import make_task

    scene = make_task("T6", 0).scene
    a, b = scene.human("A").position, scene.human("B").position
    to = (b[0], b[1] - 0.25, 0.0)
    sim = simulator(scene, EventSchedule(timed=(HumanMove(0.0, "A", to),)), seed=0)
    path = []
    for k in range(1, 81):
        sim.advance(k * 0.05)
        path.append(sim.human_position("A"))
    assert path[-1] == pytest.approx(to) and a != to
    return sim, path


def test_people_walk_round_the_table_and_do_not_walk_into_the_arms() -> None:
    straight, _ = _walk_past_the_ur5(_StraightWalks)
    assert [(r, h) for _, r, h in straight.contacts] == [("r2", "A")]  # the old walk's contact
    sim, path = _walk_past_the_ur5(MujocoSimulator)
    assert sim.contacts == []
    table = sim.stage.table_rect()
    start, to = sim.scene.human("A").position, path[-1]
    room = min(WALK_CLEARANCE, *(table.margin(p) for p in (start, to)))
    assert room > 0.2
    # every sampled position is outside the table grown by the clearance the two ends allow
    assert min(table.margin(p) for p in path) >= room - 1e-6
    (move,) = [r for r in sim.log.records if isinstance(r, HumanMoveRecord)]
    assert move.wander is not None and len(move.wander) >= 2
    assert move.wander[-1] == pytest.approx(list(to), abs=1e-6)
