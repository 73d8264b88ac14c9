"""Robot-to-robot handover pose optimisation (paper §IV-B) and robot-to-human targets (§IV-C)."""

from __future__ import annotations

import math
import time
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from hltl.motion.collision import min_distance
from hltl.motion.grasps import Cylinder, Grasp, co_grasp_pairs, grasp_candidates
from hltl.motion.human import Posture, body_capsules, comfort_zone
from hltl.motion.kinematics import Arm, Capsule, FloatArray, Joints, rotation_z_to
from hltl.motion.workspace import Rendezvous

PRE_HANDOVER = 0.10  # the receiver stops this far back along its approach, then moves in
RETREAT = 0.06  # the giver backs off this far after the transfer
ARM_MARGIN = 0.01  # minimum clearance between the two arms at the handover (m)
PERSON_MARGIN = 0.05  # minimum clearance between an arm and a person's body (m)
BOTTLE = Cylinder(0.035, 0.22)
W_FEASIBILITY = 0.5  # weight of closeness to the centre against time efficiency


@dataclass(frozen=True, slots=True)
class Candidate:
    """A sampled handover position with its two criteria and combined score (higher is better)."""

    position: tuple[float, float, float]
    feasibility: float  # 1 at the centre of the inscribed sphere, 0 on its surface
    travel: float  # max distance of the two hands from it (m), the time proxy
    score: float


@dataclass(frozen=True, slots=True)
class ArmGoal:
    """One arm's part of a handover: its tool pose and the configurations that reach it."""

    robot: str
    grasp: Grasp
    tool_position: tuple[float, float, float]
    tool_rotation: tuple[tuple[float, float, float], ...]
    q: tuple[float, ...]
    q_approach: tuple[float, ...]  # receiver: pre-handover pose; giver: retreat pose


@dataclass(frozen=True, slots=True)
class HandoverPose:
    """The chosen robot-to-robot handover: where the object is exchanged and how."""

    position: tuple[float, float, float]
    candidate: Candidate
    giver: ArmGoal
    receiver: ArmGoal
    clearance: float  # between the two arms (m)


@dataclass(frozen=True, slots=True)
class HandoverResult:
    """What the optimisation found: the pose or why none, all candidates and the time spent."""

    pose: HandoverPose | None
    reason: str | None
    sphere: Rendezvous
    candidates: tuple[Candidate, ...]
    tried: int
    seconds: float


def sample_ball(centre: Sequence[float], radius: float, n: int, seed: int = 0) -> FloatArray:
    """``n`` points uniformly distributed inside a ball (the centre itself first)."""
    rng = np.random.default_rng(seed)
    d = rng.normal(size=(n, 3))
    d /= np.linalg.norm(d, axis=1, keepdims=True)
    r = radius * rng.uniform(size=(n, 1)) ** (1.0 / 3.0)
    pts = np.asarray(centre, dtype=float) + d * r
    pts[0] = centre
    return pts


def score_candidates(
    points: FloatArray, sphere: Rendezvous, hands: Sequence[FloatArray]
) -> list[Candidate]:
    """Feasibility (closeness to the centre) and time efficiency (max hand distance), combined.

    Travel is normalised by the largest travel among the candidates, so both criteria lie in
    [0, 1]; the best candidates come first.
    """
    c = np.asarray(sphere.centre)
    feas = 1.0 - np.linalg.norm(points - c, axis=1) / max(sphere.radius, 1e-9)
    travel = np.max([np.linalg.norm(points - h, axis=1) for h in hands], axis=0)
    t_norm = travel / max(float(travel.max()), 1e-9)
    score = W_FEASIBILITY * feas - (1.0 - W_FEASIBILITY) * t_norm
    out = [
        Candidate(_v(p), float(f), float(t), float(s))
        for p, f, t, s in zip(points, feas, travel, score, strict=True)
    ]
    out.sort(key=lambda cand: -cand.score)
    return out


def _orient_pairs(
    pairs: Sequence[tuple[Grasp, Grasp, float]],
    giver_base: FloatArray,
    receiver_base: FloatArray,
    giver_rot: FloatArray,
    receiver_rot: FloatArray,
    point: FloatArray,
) -> list[tuple[Grasp, Grasp]]:
    """Grasp pairs ordered by how little the two hands must turn from where they point now.

    A hand approaches best along the line from its base to the object (the arm extends); the
    hand's current approach direction breaks ties, so the wrist turns least.
    """

    def cost(g: Grasp, base: FloatArray, rot: FloatArray) -> float:
        a = np.asarray(g.approach)
        reach_dir = point - base
        reach_dir[2] = 0.0
        n = float(np.linalg.norm(reach_dir))
        natural = reach_dir / n if n > 1e-9 else a
        return float(2.0 - np.dot(a, natural) - 0.25 * np.dot(a, rot[:, 2]))

    ranked = sorted(
        pairs,
        key=lambda p: cost(p[0], giver_base, giver_rot) + cost(p[1], receiver_base, receiver_rot),
    )
    return [(g, r) for g, r, _ in ranked]


def optimise_r2r(
    giver: Arm,
    receiver: Arm,
    sphere: Rendezvous,
    *,
    giver_q: Joints | None = None,
    receiver_q: Joints | None = None,
    obj: Cylinder = BOTTLE,
    people: Sequence[Capsule] = (),
    n_samples: int = 24,
    max_tries: int = 8,
    grasp_pairs: int = 3,
    seed: int = 0,
) -> HandoverResult:
    """The robot-to-robot handover pose of §IV-B.

    Candidate object positions are sampled uniformly in the inscribed sphere of the two
    reachable regions and ranked by feasibility and time efficiency. For each, in rank order,
    grasp pairs that pass the co-grasp filter are oriented from the arms' current states; both
    arms get IK (the receiver also at its pre-handover pose, the giver at its retreat pose);
    the arms must clear each other and every person. The first candidate that passes wins.
    """
    t0 = time.perf_counter()
    qg = giver.home if giver_q is None else np.asarray(giver_q, dtype=float)
    qr = receiver.home if receiver_q is None else np.asarray(receiver_q, dtype=float)
    pg, rg = giver.fk(qg)
    pr, rr = receiver.fk(qr)
    pts = sample_ball(sphere.centre, sphere.radius, n_samples, seed)
    cands = score_candidates(pts, sphere, (pg, pr))
    pairs = co_grasp_pairs(obj, grasp_candidates(obj, top=False), partner="robot")
    tried = 0
    reason = "no candidate passed"
    for cand in cands[:max_tries]:
        tried += 1
        p = np.asarray(cand.position)
        ordered = _orient_pairs(pairs, giver.base, receiver.base, rg, rr, p)
        for g_grasp, r_grasp in ordered[:grasp_pairs]:
            goal_g, why = _arm_goal(giver, g_grasp, p, qg, -RETREAT)
            if goal_g is None:
                reason = f"{giver.robot}: {why}"
                continue
            goal_r, why = _arm_goal(receiver, r_grasp, p, qr, -PRE_HANDOVER)
            if goal_r is None:
                reason = f"{receiver.robot}: {why}"
                continue
            caps_g = giver.capsules(goal_g.q)
            caps_r = receiver.capsules(goal_r.q)
            clear, a, b = min_distance(caps_g, caps_r)
            if clear < ARM_MARGIN:
                reason = f"arms collide ({giver.robot} {a} / {receiver.robot} {b})"
                continue
            if people:
                pre_r = receiver.capsules(goal_r.q_approach)
                dp, _, part = min_distance([*caps_g, *caps_r, *pre_r], list(people))
                if dp < PERSON_MARGIN:
                    reason = f"an arm passes {dp:.2f} m from a person's {part}"
                    continue
            pose = HandoverPose(cand.position, cand, goal_g, goal_r, clear)
            return HandoverResult(pose, None, sphere, tuple(cands), tried, time.perf_counter() - t0)
    return HandoverResult(None, reason, sphere, tuple(cands), tried, time.perf_counter() - t0)


def ik_with_line(
    arm: Arm, tool: FloatArray, rot: FloatArray, q_now: Joints, offset: FloatArray
) -> tuple[tuple[float, ...], list[tuple[float, ...]]] | str:
    """IK for a tool pose whose straight line by ``offset`` (approach or retreat) the tool can
    follow on the same branch, clear of the table: the configuration and the line, or the IK's
    reason for failing."""
    lines: dict[tuple[float, ...], list[tuple[float, ...]]] = {}

    def usable(q: FloatArray) -> bool:
        line = arm.ik_line(q, offset)
        if line is None or not all(arm.pose_clear(x) for x in line[1:]):
            return False
        lines[tuple(float(v) for v in q)] = line
        return True

    res = arm.ik(tool, rot, q_now, starts=10, prefer=q_now, solutions=4, accept=usable)
    if res.q is None:
        return str(res.reason)
    return res.q, lines[res.q]


def _arm_goal(
    arm: Arm, grasp: Grasp, centre: FloatArray, q_now: FloatArray, approach_offset: float
) -> tuple[ArmGoal | None, str]:
    """IK for the grasp pose, and the straight line ``approach_offset`` along the approach vector.

    The grasp configuration must be clear of the table (and of the arm itself), and the tool
    must be able to move along the approach line from it on the same IK branch: a pre-grasp or
    retreat pose on another branch would make the short approach a wide swing.
    """
    tool = centre + np.asarray(grasp.offset)
    rot = rotation_z_to(grasp.approach, (0.0, 0.0, -1.0))
    found = ik_with_line(arm, tool, rot, q_now, np.asarray(grasp.approach) * approach_offset)
    if isinstance(found, str):
        return None, f"no IK at the handover pose ({found})"
    q, line = found
    rows = tuple((float(r[0]), float(r[1]), float(r[2])) for r in rot)
    return ArmGoal(arm.robot, grasp, _v(tool), rows, q, line[-1]), ""


@dataclass(frozen=True, slots=True)
class R2HTarget:
    """Where the hand offers an object to a person, and from where it approaches."""

    position: tuple[float, float, float]
    approach: tuple[float, float, float]
    q: tuple[float, ...]
    q_pre: tuple[float, ...]
    clearance: float  # arm to body (m)


def plan_r2h(
    arm: Arm,
    posture: Posture,
    *,
    q_now: Joints | None = None,
    reachable: Sequence[bool] | None = None,
) -> tuple[R2HTarget | None, str]:
    """A robot-to-human handover target in the comfort zone, approached from the front.

    Comfort-zone points are tried nearest the robot first; the hand comes in horizontally
    along the line from the robot towards the person, and neither the pre-handover pose nor the
    handover pose may bring the arm within PERSON_MARGIN of the person's body capsules.
    """
    q0 = arm.home if q_now is None else np.asarray(q_now, dtype=float)
    zone = np.array(comfort_zone(posture))
    order = np.argsort(np.linalg.norm(zone - arm.base, axis=1))
    body = body_capsules(posture)
    facing = np.asarray(posture.facing)
    reason = "no comfort-zone point is reachable"
    for i in order:
        if reachable is not None and not reachable[i]:
            continue
        p = zone[i]
        approach = -facing  # the hand comes towards the person's front
        rot = rotation_z_to(approach, (0.0, 0.0, -1.0))
        found = ik_with_line(arm, p, rot, q0, -approach * PRE_HANDOVER)
        if isinstance(found, str):
            reason = f"no IK in the comfort zone with a clear approach ({found})"
            continue
        q, line = found
        q_pre = line[-1]
        d = min(
            min_distance(arm.capsules(q), body)[0],
            min_distance(arm.capsules(q_pre), body)[0],
        )
        if d < PERSON_MARGIN:
            reason = f"the arm would pass {d:.2f} m from the person's body"
            continue
        return R2HTarget(_v(p), _v(approach), q, q_pre, d), ""
    return None, reason


def _v(a: FloatArray | Sequence[float]) -> tuple[float, float, float]:
    return (float(a[0]), float(a[1]), float(a[2]))


def angle_between(a: Sequence[float], b: Sequence[float]) -> float:
    """Angle in radians between two vectors."""
    u, v = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    c = float(np.dot(u, v) / (np.linalg.norm(u) * np.linalg.norm(v)))
    return math.acos(max(-1.0, min(1.0, c)))
