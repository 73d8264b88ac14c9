"""Self-collision: the checked link pairs, coal distances against a sampled-surface oracle."""

from __future__ import annotations

import functools
import itertools
import math
from typing import Any

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.motion.kinematics import COLLISION, Arm
from hltl.motion.paths import config_valid
from hltl.motion.robots import load_model
from hltl.motion.selfcollision import SELF_MARGIN, LinkPair, collision_geometry, raw_geometry

MODELS = ("elfin3", "ur5", "panda", "xarm6")
SPACING = 0.005  # m between oracle surface samples
# The oracle's points lie on the surfaces, at most ~0.6 SPACING from any surface point, so the
# sampled distance overestimates the true one by at most about 1.2 SPACING.
SLACK = 2 * SPACING


@functools.cache
def _arm(name: str) -> Arm:
    return Arm("r", name)


def _mesh_points(geometry: Any) -> np.ndarray:
    """Points on a coal BVH mesh: its triangles split at the midpoint of their longest edge until
    no edge is longer than SPACING, and the corners of the pieces (every point of a triangle
    with edges ≤ SPACING lies within SPACING/√3 of one of its corners)."""
    verts = np.asarray(geometry.vertices(), dtype=float)
    tri = [geometry.tri_indices(t) for t in range(geometry.num_tris)]
    idx = np.array([[t[0], t[1], t[2]] for t in tri], dtype=int)
    tris = verts[idx]  # (n, 3 corners, 3)
    out = [verts]
    while len(tris):
        edges = np.stack(
            [np.linalg.norm(tris[:, (k + 1) % 3] - tris[:, k], axis=1) for k in (0, 1, 2)]
        )
        longest = edges.argmax(axis=0)
        big = edges.max(axis=0) > SPACING
        tris = tris[big]
        longest = longest[big]
        if not len(tris):
            break
        # rotate each triangle so its longest edge runs from corner 0 to corner 1
        order = np.stack([longest, (longest + 1) % 3, (longest + 2) % 3], axis=1)
        tris = np.take_along_axis(tris, order[:, :, None], axis=1)
        mid = (tris[:, 0] + tris[:, 1]) / 2
        out.append(mid)
        tris = np.concatenate(
            [
                np.stack([tris[:, 0], mid, tris[:, 2]], axis=1),
                np.stack([mid, tris[:, 1], tris[:, 2]], axis=1),
            ]
        )
    return np.unique(np.concatenate(out).round(7), axis=0)


def _cylinder_points(radius: float, length: float) -> np.ndarray:
    k = max(8, math.ceil(2 * math.pi * radius / SPACING))
    ang = np.linspace(0.0, 2 * math.pi, k, endpoint=False)
    zs = np.linspace(-length / 2, length / 2, max(2, math.ceil(length / SPACING) + 1))
    side = np.array([(radius * math.cos(a), radius * math.sin(a), z) for a in ang for z in zs])
    rs = np.linspace(0.0, radius, max(2, math.ceil(radius / SPACING) + 1))
    disc = np.array([(r * math.cos(a), r * math.sin(a)) for a in ang for r in rs])
    caps = [np.column_stack([disc, np.full(len(disc), s * length / 2)]) for s in (-1, 1)]
    return np.concatenate([side, *caps])


def _box_points(half: np.ndarray) -> np.ndarray:
    axes = [np.linspace(-h, h, max(2, math.ceil(2 * h / SPACING) + 1)) for h in half]
    out = []
    for d in range(3):
        u, v = (axes[e] for e in range(3) if e != d)
        uu, vv = np.meshgrid(u, v, indexing="ij")
        for s in (-1, 1):
            p = np.zeros((uu.size, 3))
            p[:, [e for e in range(3) if e != d]] = np.column_stack([uu.ravel(), vv.ravel()])
            p[:, d] = s * half[d]
            out.append(p)
    return np.concatenate(out)


@functools.cache
def _oracle_model(name: str) -> tuple[Any, dict[str, tuple[int, np.ndarray]]]:
    """Every collision body's surface samples (its own frame) and parent joint, from the
    description's raw geometry (meshes, not the hulls the checker's broad phase uses)."""
    import coal

    geom = raw_geometry(name)
    bodies: dict[str, tuple[int, np.ndarray]] = {}
    for o in geom.geometryObjects:
        g = o.geometry
        if isinstance(g, coal.BVHModelBase):
            pts = _mesh_points(g)
        elif isinstance(g, coal.Cylinder):
            pts = _cylinder_points(g.radius, 2 * g.halfLength)
        elif isinstance(g, coal.Box):
            pts = _box_points(np.asarray(g.halfSide, dtype=float))
        else:  # pragma: no cover - the three descriptions use only these shapes
            raise AssertionError(f"no oracle for {type(g).__name__}")
        placed = o.placement
        world = (np.asarray(placed.rotation) @ pts.T).T + np.asarray(placed.translation)
        bodies[str(o.name)] = (int(o.parentJoint), world)  # in the parent joint's frame
    return geom, bodies


@functools.cache
def _tree(name: str, body: str) -> Any:
    from scipy.spatial import cKDTree

    return cKDTree(_oracle_model(name)[1][body][1])


def _oracle_distance(name: str, q: np.ndarray, pair: LinkPair, bound: float = math.inf) -> float:
    """Smallest distance between the two bodies' surface samples at ``q`` (Pinocchio FK of the
    joint frames only, then a scipy k-d tree of the larger body's samples); inf when no two
    samples are closer than ``bound`` (the tree search then skips most of both bodies)."""
    import pinocchio as pin

    model = load_model(name)
    data = model.createData()
    pin.forwardKinematics(model, data, q)
    _, bodies = _oracle_model(name)
    (ja, pa), (jb, pb) = bodies[pair.first], bodies[pair.second]
    a, b = pair.first, pair.second
    if len(pa) < len(pb):
        (ja, pa, a), (jb, pb, b) = (jb, pb, b), (ja, pa, a)
    rel = data.oMi[ja].inverse() * data.oMi[jb]  # b's joint frame in a's
    moved = (np.asarray(rel.rotation) @ pb.T).T + np.asarray(rel.translation)
    d, _ = _tree(name, a).query(moved, k=1, distance_upper_bound=bound)
    return float(np.min(d))


@pytest.mark.parametrize("name", MODELS)
def test_checked_pairs_are_all_pairs_but_adjacent_and_always_touching(name: str) -> None:
    cg = collision_geometry(name)
    model = load_model(name)
    geom, bodies = _oracle_model(name)
    names = [str(o.name) for o in geom.geometryObjects]
    parents = list(model.parents)
    adjacent, rest = set(), set()
    for a, b in itertools.combinations(names, 2):
        ja, jb = bodies[a][0], bodies[b][0]
        (adjacent if ja == jb or parents[ja] == jb or parents[jb] == ja else rest).add((a, b))
    assert {(p.first, p.second) for p in cg.adjacent} == adjacent
    checked = {(p.first, p.second) for p in cg.checked}
    always = {(p.first, p.second) for p in cg.always}
    assert checked | always == rest and not checked & always
    assert len(checked) >= 20
    # the left-out pairs do touch in (nearly) every configuration: check with the oracle
    rng = np.random.default_rng(5)
    lo = np.maximum(model.lowerPositionLimit, -np.pi)
    hi = np.minimum(model.upperPositionLimit, np.pi)
    for pair in cg.always:
        qs = [rng.uniform(lo, hi) for _ in range(12)]
        close = [_oracle_distance(name, q, pair) < SELF_MARGIN + SLACK for q in qs]
        assert np.mean(close) >= 0.9, pair


def test_elfin3_upper_arm_and_forearm_share_the_elbow() -> None:
    # The two cylinders meet at the elbow (and the forearm and the wrist cylinder at joint 5):
    # they overlap whenever the joint between them bends, so they are not checked pairs.
    always = {(p.first, p.second) for p in collision_geometry("elfin3").always}
    assert always == {("link2_0", "link4_0"), ("link4_0", "link6_0")}


@settings(max_examples=12, deadline=None, derandomize=True)
@given(st.sampled_from(MODELS), st.lists(st.floats(0.0, 1.0), min_size=7, max_size=7))
def test_coal_distances_match_the_sampled_surface_oracle(name: str, u: list[float]) -> None:
    arm = _arm(name)
    q = arm._seed_lo + np.asarray(u[: arm.nq]) * (arm._seed_hi - arm._seed_lo)
    checker = arm.self_collision
    exact = checker.pair_distances(q, margin=math.inf)  # every mesh pair measured on the mesh
    for pair, d in zip(checker.geometry.checked, exact, strict=True):
        oracle = _oracle_distance(name, q, pair, bound=max(d, 0.0) + SLACK)
        assert oracle >= d - 1e-4, (pair, d, oracle)  # samples never beat the true distance
        assert oracle <= max(d, 0.0) + SLACK, (pair, d, oracle)
    # the fast test (hull broad phase, mesh collision with a margin) decides as the distances do
    assert arm.self_clear(q) == bool(np.all(exact >= SELF_MARGIN))
    best, pair = arm.self_distance(q)
    assert best == pytest.approx(float(np.min(exact)), abs=1e-5)  # EPA depth: warm starts
    assert pair == checker.geometry.checked[int(np.argmin(exact))]


# Folded configurations found by sampling, in which a checked pair intersects (the oracle says so).
# All above the table: only the arm itself is in the way.
FOLDED = {
    "elfin3": (-2.0, 2.0, 1.8, 1.8, -0.1, -1.5),  # upper arm down against the base
    "ur5": (-1.1, -0.4, -2.7, -2.1, 1.0, 0.8),  # hand folded back onto the upper arm
    "panda": (-0.3, 0.9, -1.4, -2.6, -0.5, 0.5, -2.1),  # hand against link 1
    "xarm6": (-1.8, 0.6, -0.5, 2.9, -1.0, -0.1),  # hand folded back onto the base
}


@pytest.mark.parametrize("name", MODELS)
def test_folded_arm_collides_with_itself(name: str) -> None:
    arm = _arm(name)
    q = np.asarray(FOLDED[name])
    d, pair = arm.self_distance(q)
    assert pair is not None and d < SELF_MARGIN
    assert _oracle_distance(name, q, pair) < SELF_MARGIN + SLACK
    assert arm.above_table(q)
    assert not arm.self_clear(q) and not arm.pose_clear(q)
    assert not config_valid(arm, q, (np.zeros((0, 3)), np.zeros((0, 3)), np.zeros(0)))
    # IK for the folded tool pose never returns a self-colliding configuration
    pos, rot = arm.fk(q)
    res = arm.ik(pos, rot, q, starts=6)
    assert res.q is not None or res.reason is not None
    if res.q is not None:
        assert arm.self_clear(res.q) and not np.allclose(res.q, q)
    # and the configuration itself, as the only start, is refused as a collision
    stuck = arm.ik(pos, rot, q, starts=1)
    assert stuck.q is None and stuck.reason == COLLISION
