"""R2R handover poses, the R2H comfort zone, grasps and the co-grasp filter (paper §IV)."""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import pytest

from hltl.motion.collision import min_distance
from hltl.motion.grasps import (
    CO_GRASP_GAP,
    Cylinder,
    co_grasp_pairs,
    complement,
    grasp_candidates,
    placements,
)
from hltl.motion.handover import PERSON_MARGIN, optimise_r2r, plan_r2h
from hltl.motion.human import (
    FLEXION_DEG,
    TABLE_HEIGHT,
    body_capsules,
    comfort_zone,
    standing_posture,
)
from hltl.motion.kinematics import Arm
from hltl.world.scene import Scene


def test_r2r_pose_is_inside_both_maps_and_collision_free(fig1: Scene, fig1_cell: Any) -> None:
    kin = fig1_cell.kinematics
    r1, r2 = fig1.robots
    a1, a2 = fig1_cell.arms["r1"], fig1_cell.arms["r2"]
    sphere = kin.rendezvous(r1, r2)
    people = fig1_cell.people()
    for seed in range(2):
        res = optimise_r2r(a1, a2, sphere, people=people, seed=seed)
        assert res.pose is not None, res.reason
        pose = res.pose
        p = pose.position
        assert kin.reaches(r1, p) and kin.reaches(r2, p)
        assert math.dist(p, sphere.centre) <= sphere.radius + 1e-9
        # IK solutions put each tool where the grasp says, with the grasp's approach axis
        for arm, goal in ((a1, pose.giver), (a2, pose.receiver)):
            pos, rot = arm.fk(goal.q)
            assert np.linalg.norm(pos - np.asarray(goal.tool_position)) < 1e-3
            assert np.dot(rot[:, 2], goal.grasp.approach) > 0.999
        # complementary grasps: opposite sides of the object
        assert np.dot(pose.giver.grasp.approach, pose.receiver.grasp.approach) < -0.999
        # collision-free: recomputed independently with coal
        d, _, _ = min_distance(a1.capsules(pose.giver.q), a2.capsules(pose.receiver.q))
        assert d >= 0.01
        assert min_distance(a2.capsules(pose.receiver.q_approach), people)[0] >= PERSON_MARGIN
        # the pre-handover pose is PRE_HANDOVER back along the receiver's approach
        pre, _ = a2.fk(pose.receiver.q_approach)
        back = np.asarray(pose.receiver.tool_position) - pre
        assert np.linalg.norm(back) == pytest.approx(0.10, abs=2e-3)
        assert np.dot(back / np.linalg.norm(back), pose.receiver.grasp.approach) > 0.99
        # candidates are ranked best first
        scores = [c.score for c in res.candidates]
        assert scores == sorted(scores, reverse=True)


@pytest.mark.parametrize("height", [1.5, 1.7, 1.9])
def test_comfort_zone_geometry(height: float) -> None:
    person = (1.0, 0.5, 0.0)
    posture = standing_posture(person, (0.0, 0.0, 0.0), height)
    shoulder = np.asarray(posture.shoulder)
    floor = person[2] - TABLE_HEIGHT
    assert shoulder[2] - floor == pytest.approx(0.818 * height)
    fwd = np.asarray(posture.facing)
    zone = comfort_zone(posture)
    assert len(zone) >= 4
    for p in zone:
        v = np.asarray(p) - shoulder
        assert np.dot(v, fwd) > 0.0  # in front of the person
        assert np.linalg.norm(v) <= (0.186 + 0.146 + 0.108) * height  # within the arm
        assert floor + 0.55 * height < p[2] < shoulder[2]  # between hip and shoulder
        # the forearm makes 90°-120° with the upper arm: recover the elbow from the zone's
        # construction (upper arm 0.186 H below the shoulder, swung forward at most 20°)
        best = min(
            abs(_flexion(shoulder, fwd, p, height, swing) - f)
            for swing in np.linspace(0, 20, 4)
            for f in np.linspace(*FLEXION_DEG, 4)
        )
        assert best < 1.0
    # taller people get higher targets
    assert min(z for *_, z in zone) > floor + 0.6 * height


def _flexion(shoulder: np.ndarray, fwd: np.ndarray, p: Any, h: float, swing: float) -> float:
    s = math.radians(swing)
    arm = -math.cos(s) * np.array([0, 0, 1.0]) + math.sin(s) * fwd
    elbow = shoulder + 0.186 * h * arm
    fore = np.asarray(p) - elbow
    if abs(np.linalg.norm(fore) - (0.146 + 0.054) * h) > 1e-6:
        return 1e9
    return math.degrees(math.acos(np.dot(arm, fore) / np.linalg.norm(fore)))


@pytest.mark.parametrize("height", [1.55, 1.85])
def test_r2h_target_is_reached_from_the_front(height: float) -> None:
    arm = Arm("r1", "elfin3")
    posture = standing_posture((0.75, 0.1, 0.0), arm.base, height)
    target, why = plan_r2h(arm, posture)
    assert target is not None, why
    assert target.position in comfort_zone(posture)
    assert np.dot(target.approach, posture.facing) < -0.999  # towards the person's front
    for q in (target.q, target.q_pre):
        assert min_distance(arm.capsules(q), body_capsules(posture))[0] >= PERSON_MARGIN
    pos, _ = arm.fk(target.q)
    assert np.linalg.norm(pos - np.asarray(target.position)) < 1e-3


def test_co_grasp_filter_keeps_room_for_both_hands() -> None:
    cyl = Cylinder(0.035, 0.22)
    grasps = grasp_candidates(cyl)
    for partner in ("robot", "human"):
        pairs = co_grasp_pairs(cyl, grasps, partner=partner)
        assert pairs, partner
        assert all(d >= CO_GRASP_GAP for *_, d in pairs)
        assert [d for *_, d in pairs] == sorted((d for *_, d in pairs), reverse=True)
        for g, c, _ in pairs:
            assert c == complement(g, cyl)
            if g.kind == "side":
                assert np.dot(g.approach, c.approach) == pytest.approx(-1.0)
    # a hand at the object's middle leaves no room for a complementary hand there
    middle = [g for g in grasps if g.kind == "side" and abs(g.height) < 1e-9]
    assert middle
    assert not co_grasp_pairs(cyl, middle, partner="robot")
    with pytest.raises(ValueError, match="co-grasp partner"):
        co_grasp_pairs(cyl, grasps, partner="dog")


def test_cylinder_fit_from_points() -> None:
    rng = np.random.default_rng(0)
    ang = rng.uniform(0, 2 * math.pi, 400)
    z = rng.uniform(0.0, 0.2, 400)
    pts = np.stack([0.3 + 0.04 * np.cos(ang), -0.1 + 0.04 * np.sin(ang), z], axis=1)
    cyl, centre = Cylinder.from_points(pts)
    assert cyl.radius == pytest.approx(0.04, abs=2e-3)
    assert cyl.height == pytest.approx(0.2, abs=5e-3)
    assert centre[:2] == pytest.approx((0.3, -0.1), abs=5e-3)
    with pytest.raises(ValueError, match="at least 10 rows"):
        Cylinder.from_points(pts[:3])


def test_placements_on_surface_inside_reach_and_clear_of_objects() -> None:
    cyl = Cylinder(0.035, 0.2)
    occupied = [((0.6, 0.3, 0.0), 0.04)]

    def inside(p: np.ndarray) -> bool:
        return float(np.linalg.norm(p[:2])) <= 0.68

    got = placements((0.6, 0.3, 0.0), (0.3, 0.3), cyl, occupied, inside)
    assert got
    for pl in got:
        x, y, z = pl.position
        assert abs(x - 0.6) <= 0.15 - cyl.radius + 1e-9 and abs(y - 0.3) <= 0.15 - cyl.radius + 1e-9
        assert z == pytest.approx(cyl.height / 2)
        assert math.dist((x, y), (0.6, 0.3)) >= 0.04 + cyl.radius
        assert inside(np.asarray(pl.position))
