"""Motion plans for skill instances, and parallel candidate planning (the paper's P.M.P.)."""

from __future__ import annotations

import math
import time
from collections.abc import Mapping, Sequence
from concurrent.futures import FIRST_COMPLETED, Future, ProcessPoolExecutor, wait
from dataclasses import dataclass, replace

import numpy as np

from hltl.errors import SceneError
from hltl.motion.collision import capsule_arrays, min_distance
from hltl.motion.grasps import (
    Cylinder,
    Grasp,
    co_grasp_pairs,
    grasp_candidates,
    placements,
    side_grasp,
)
from hltl.motion.handover import (
    PERSON_MARGIN,
    PRE_HANDOVER,
    RETREAT,
    _arm_goal,
    plan_r2h,
    sample_ball,
    score_candidates,
)
from hltl.motion.human import body_capsules, standing_posture
from hltl.motion.kinematics import Arm, Capsule, FloatArray, Joints
from hltl.motion.paths import plan_path, segment_clear, time_parametrise
from hltl.motion.robots import has_model
from hltl.motion.trajectory import JointTrajectory, MotionPlan
from hltl.motion.workspace import MapKinematics
from hltl.skills.library import Action
from hltl.world.scene import Scene, Vec3

# Dwell times (s): closing or opening the hand, and the exchange when both hands hold the object.
GRASP_DWELL = 0.3
RELEASE_DWELL = 0.3
EXCHANGE_DWELL = 0.4
PRE_GRASP = 0.10  # m back along the approach before closing on an object
# goal sets (hand-over position x grasp pair) a robot-to-robot hand-over tries before it is
# called infeasible: the best k first, then the rest of a sample of this many
R2R_MAX_CANDIDATES = 32


@dataclass(frozen=True, slots=True)
class SkillMotion:
    """A skill instance's motion: the plan (or why there is none) and where each hand ends."""

    action: Action
    plan: MotionPlan | None
    reason: str | None
    final: tuple[tuple[str, tuple[float, ...]], ...]  # robot → configuration at the end
    seconds: float  # planning time: wall-clock seconds of the whole call that produced it

    @property
    def duration(self) -> float:
        return math.inf if self.plan is None else self.plan.duration


class Cell:
    """The arms of a scene (robots with a registered model) and their reachability.

    ``arms`` may give some of them already built (an :class:`Arm` for the robot's id, model and
    base), e.g. shared by the cells of several scenes with the same robots.
    """

    def __init__(
        self,
        scene: Scene,
        kinematics: MapKinematics | None = None,
        arms: Mapping[str, Arm] | None = None,
    ) -> None:
        self.scene = scene
        self.kinematics = MapKinematics(scene) if kinematics is None else kinematics
        given = arms or {}
        self.arms: dict[str, Arm] = {
            r.id: given[r.id] if r.id in given else Arm(r.id, r.model, r.base)
            for r in scene.robots
            if has_model(r.model)
        }

    def arm(self, rid: str) -> Arm:
        if rid not in self.arms:
            model = self.scene.robot(rid).model
            raise SceneError(
                f"robot {rid!r} has model {model!r}, which hltl has no kinematics for; "
                "motion planning needs elfin3, xarm6, ur5 or panda"
            )
        return self.arms[rid]

    def people(self, humans: Mapping[str, Vec3] | None = None) -> list[Capsule]:
        """Body capsules of everyone in the cell (standing, facing the cell's centre)."""
        centre = np.mean([r.base for r in self.scene.robots], axis=0)
        pos = humans if humans is not None else {h.id: h.position for h in self.scene.humans}
        out: list[Capsule] = []
        for p in pos.values():
            out.extend(body_capsules(standing_posture(p, centre)))
        return out


def _object_cylinder(scene: Scene, oid: str) -> Cylinder:
    return Cylinder.for_category(scene.object(oid).category)


def _traj_to(
    arm: Arm, q0: Joints, goals: Sequence[Joints], obstacles: Sequence[Capsule]
) -> JointTrajectory | None:
    """A timed trajectory through ``goals`` in order (each leg direct or RRTConnect)."""
    pts: list[tuple[float, ...]] = [tuple(float(v) for v in q0)]
    for g in goals:
        path = plan_path(arm, pts[-1], g, obstacles)
        if path is None:
            return None
        pts.extend(path.waypoints[1:])
    return time_parametrise(arm, pts, obstacles)


def _segment_ok(arm: Arm, a: Joints, b: Joints, obstacles: Sequence[Capsule]) -> bool:
    """The straight joint segment a→b is valid: limits, table, obstacles (paths.config_valid)."""
    packed = capsule_arrays(obstacles)
    return segment_clear(arm, np.asarray(a, dtype=float), np.asarray(b, dtype=float), packed)


def _side_grasps_towards(base: FloatArray, point: FloatArray, cyl: Cylinder) -> list[Grasp]:
    """Side grasps whose approach points from the arm towards the object, nearest first; a top
    grasp last."""
    d = point - base
    az = math.atan2(-d[1], -d[0])  # the hand sits on the arm's side of the object
    out = [side_grasp(az + k * math.radians(20.0), 0.0) for k in (0, -1, 1, -2, 2)]
    out.extend(g for g in grasp_candidates(cyl, n_angles=1, n_heights=1) if g.kind == "top")
    return out


def plan_pick(
    cell: Cell,
    action: Action,
    q: Mapping[str, Joints],
    where: Vec3,
    *,
    place: bool = False,
) -> SkillMotion:
    """pick (or place): approach the object's grasp pose from PRE_GRASP back, close, lift."""
    t0 = time.perf_counter()
    rid = action.robots[0]
    arm = cell.arm(rid)
    q0 = np.asarray(q.get(rid, arm.home), dtype=float)
    cyl = _object_cylinder(cell.scene, action.object)
    centre = np.asarray(where, dtype=float)
    if place:
        centre = centre + np.array([0.0, 0.0, cyl.height / 2.0])
    else:
        centre = centre + np.array([0.0, 0.0, max(cyl.height / 2.0 - 0.05, 0.0)])
    reason = "no grasp reachable"
    obstacles = cell.people()
    for g in _side_grasps_towards(arm.base, centre, cyl):
        goal, why = _arm_goal(arm, g, centre, q0, -PRE_GRASP)
        if goal is None:
            reason = why
            continue
        traj = _traj_to(arm, q0, [goal.q_approach, goal.q], obstacles)
        if traj is None:
            reason = "no collision-free path to the grasp"
            continue
        # the approach in and the retreat out retrace one short segment: check it (the legs
        # before it were checked by plan_path)
        if not _segment_ok(arm, goal.q_approach, goal.q, obstacles):
            reason = "the approach or retreat collides"
            continue
        back = time_parametrise(arm, [goal.q, goal.q_approach])
        kind = "release" if place else "grasp"
        dwell = RELEASE_DWELL if place else GRASP_DWELL
        t_event = traj.duration + dwell / 2
        full = traj.then(back.shifted(dwell))
        plan = MotionPlan((full,), ((t_event, kind, rid),), full.duration)
        return SkillMotion(
            action, plan, None, ((rid, full.positions[-1]),), time.perf_counter() - t0
        )
    return SkillMotion(action, None, reason, (), time.perf_counter() - t0)


def plan_r2h_action(
    cell: Cell, action: Action, q: Mapping[str, Joints], human_at: Vec3
) -> SkillMotion:
    """handover_r2h: to the pre-handover pose, in along the approach, release, back."""
    t0 = time.perf_counter()
    rid = action.robots[0]
    arm = cell.arm(rid)
    q0 = np.asarray(q.get(rid, arm.home), dtype=float)
    posture = standing_posture(human_at, arm.base)
    target, why = plan_r2h(arm, posture, q_now=q0)
    if target is None:
        return SkillMotion(action, None, why, (), time.perf_counter() - t0)
    body = body_capsules(posture)
    traj = _traj_to(arm, q0, [target.q_pre], body)
    if traj is None:
        return SkillMotion(action, None, "no path around the person", (), time.perf_counter() - t0)
    if not _segment_ok(arm, target.q_pre, target.q, body):
        return SkillMotion(
            action, None, "the approach or retreat collides", (), time.perf_counter() - t0
        )
    approach = time_parametrise(arm, [target.q_pre, target.q])
    traj = traj.then(approach)
    t_event = traj.duration + RELEASE_DWELL / 2
    back = time_parametrise(arm, [target.q, target.q_pre]).shifted(RELEASE_DWELL)
    full = traj.then(back)
    plan = MotionPlan((full,), ((t_event, "release", rid),), full.duration)
    return SkillMotion(action, plan, None, ((rid, full.positions[-1]),), time.perf_counter() - t0)


@dataclass(frozen=True, slots=True)
class R2RCandidate:
    """One goal set of a robot-to-robot handover: an object position and a grasp pair."""

    position: tuple[float, float, float]
    giver_grasp: Grasp
    receiver_grasp: Grasp
    score: float


def r2r_candidates(
    cell: Cell, action: Action, q: Mapping[str, Joints], *, k: int = 8, seed: int = 0
) -> list[R2RCandidate]:
    """The best ``k`` (position × grasp pair) goal sets of §IV-B, best first."""
    g_id, r_id = action.robots
    giver, receiver = cell.arm(g_id), cell.arm(r_id)
    sphere = cell.kinematics.rendezvous(cell.scene.robot(g_id), cell.scene.robot(r_id))
    if sphere is None:
        return []
    hands = [
        giver.fk(q.get(g_id, giver.home))[0],
        receiver.fk(q.get(r_id, receiver.home))[0],
    ]
    pts = sample_ball(sphere.centre, sphere.radius * 0.8, max(2 * k, 8), seed)
    cands = score_candidates(pts, sphere, hands)
    cyl = _object_cylinder(cell.scene, action.object)
    pairs = co_grasp_pairs(cyl, grasp_candidates(cyl, n_angles=8, top=False))
    axis = receiver.base - giver.base
    az = math.atan2(-axis[1], -axis[0])
    # the two pairs whose giver approach is closest to the line between the bases (the same
    # for every position)
    ranked = sorted(pairs, key=lambda t: abs(math.remainder(t[0].azimuth - az, 2 * math.pi)))
    out: list[R2RCandidate] = []
    for c in cands:
        for g, r, _ in ranked[:2]:
            out.append(R2RCandidate(c.position, g, r, c.score))
        if len(out) >= k:
            break
    return out[:k]


def evaluate_r2r(
    cell: Cell, action: Action, q: Mapping[str, Joints], cand: R2RCandidate
) -> SkillMotion:
    """Plan one goal set completely: IK, clearance checks, both arms' timed trajectories."""
    t0 = time.perf_counter()
    g_id, r_id = action.robots
    giver, receiver = cell.arm(g_id), cell.arm(r_id)
    qg = np.asarray(q.get(g_id, giver.home), dtype=float)
    qr = np.asarray(q.get(r_id, receiver.home), dtype=float)
    p = np.asarray(cand.position)
    goal_g, why = _arm_goal(giver, cand.giver_grasp, p, qg, -RETREAT)
    if goal_g is None:
        return SkillMotion(action, None, f"{g_id}: {why}", (), time.perf_counter() - t0)
    goal_r, why = _arm_goal(receiver, cand.receiver_grasp, p, qr, -PRE_HANDOVER)
    if goal_r is None:
        return SkillMotion(action, None, f"{r_id}: {why}", (), time.perf_counter() - t0)
    clear, a, b = min_distance(giver.capsules(goal_g.q), receiver.capsules(goal_r.q))
    if clear < 0.01:
        return SkillMotion(action, None, f"arms collide ({a}/{b})", (), time.perf_counter() - t0)
    people = cell.people()
    if people:
        d, _, part = min_distance(
            [*giver.capsules(goal_g.q), *receiver.capsules(goal_r.q_approach)], people
        )
        if d < PERSON_MARGIN:
            return SkillMotion(
                action, None, f"too close to a person's {part}", (), time.perf_counter() - t0
            )
    # giver: to the handover pose (the other arm at its pre-handover pose is an obstacle)
    tg = _traj_to(giver, qg, [goal_g.q], [*people, *receiver.capsules(goal_r.q_approach)])
    tr = _traj_to(receiver, qr, [goal_r.q_approach], [*people, *giver.capsules(goal_g.q)])
    if tg is None or tr is None:
        return SkillMotion(
            action, None, "no collision-free path to the handover", (), time.perf_counter() - t0
        )
    if not (
        _segment_ok(giver, goal_g.q, goal_g.q_approach, people)
        and _segment_ok(receiver, goal_r.q_approach, goal_r.q, people)
    ):
        return SkillMotion(
            action, None, "the approach or retreat collides", (), time.perf_counter() - t0
        )
    meet = max(tg.duration, tr.duration)
    approach = time_parametrise(receiver, [goal_r.q_approach, goal_r.q])
    t_grasp = meet + approach.duration
    t_transfer = t_grasp + EXCHANGE_DWELL
    tr_full = (
        tr.then(approach.shifted(meet - tr.duration)) if meet > tr.duration else tr.then(approach)
    )
    retreat = time_parametrise(giver, [goal_g.q, goal_g.q_approach])
    hold = t_transfer - tg.duration
    tg_full = tg.then(retreat.shifted(hold))
    duration = max(tg_full.duration, tr_full.duration)
    events = (
        (t_grasp, "grasp", r_id),
        (t_transfer, "transfer", r_id),
        (t_transfer, "release", g_id),
    )
    plan = MotionPlan((tg_full, tr_full), events, duration)
    final = ((g_id, tg_full.positions[-1]), (r_id, tr_full.positions[-1]))
    return SkillMotion(action, plan, None, final, time.perf_counter() - t0)


# -- parallel candidate planning -------------------------------------------------------------------

_WORKER_CELL: Cell | None = None


def _init_worker(scene: Scene, cell: Cell | None = None) -> None:
    """A worker's cell: the parent's own (inherited by fork, its models, maps and rest poses
    already built) or, without one, built from the scene."""
    global _WORKER_CELL
    _WORKER_CELL = cell if cell is not None else Cell(scene)


def _work(action: Action, q: dict[str, tuple[float, ...]], cand: R2RCandidate) -> SkillMotion:
    assert _WORKER_CELL is not None
    return evaluate_r2r(_WORKER_CELL, action, q, cand)


class CandidatePlanner:
    """Plans a multi-robot skill's candidate goal sets serially or on a process pool.

    ``mode="best"`` plans every candidate and keeps the shortest motion; ``mode="first"``
    returns the first feasible one (in completion order when parallel, rank order when serial).
    A time budget stops waiting for more candidates once one is feasible.
    """

    def __init__(self, cell: Cell, *, workers: int = 0) -> None:
        self.cell = cell
        self.workers = workers
        self._pool: ProcessPoolExecutor | None = None
        if workers > 1:
            import multiprocessing

            ctx = multiprocessing.get_context("fork")
            # forked workers inherit the cell (fork passes the initializer's arguments without
            # pickling them), so starting the pool costs no model loading or IK
            self._pool = ProcessPoolExecutor(
                workers, mp_context=ctx, initializer=_init_worker, initargs=(cell.scene, cell)
            )

    def close(self) -> None:
        if self._pool is not None:
            self._pool.shutdown(cancel_futures=True)
            self._pool = None

    def __enter__(self) -> CandidatePlanner:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def warm_up(self) -> None:
        """Start every worker (model loading, maps) before timing anything."""
        if self._pool is not None:
            list(self._pool.map(_noop, range(self.workers * 2)))

    def plan(
        self,
        action: Action,
        q: Mapping[str, Joints],
        candidates: Sequence[R2RCandidate],
        *,
        mode: str = "best",
        budget: float = math.inf,
    ) -> tuple[SkillMotion | None, list[SkillMotion]]:
        qq = {k: tuple(float(x) for x in v) for k, v in q.items()}
        results: list[SkillMotion] = []
        t0 = time.perf_counter()
        if self._pool is None:
            for cand in candidates:
                res = evaluate_r2r(self.cell, action, qq, cand)
                results.append(res)
                if res.plan is not None and (mode == "first" or time.perf_counter() - t0 > budget):
                    break
        else:
            futures: list[Future[SkillMotion]] = [
                self._pool.submit(_work, action, qq, c) for c in candidates
            ]
            pending = set(futures)
            while pending:
                done, pending = wait(pending, return_when=FIRST_COMPLETED)
                for f in done:
                    results.append(f.result())
                feasible = any(r.plan is not None for r in results)
                if feasible and (mode == "first" or time.perf_counter() - t0 > budget):
                    for f in pending:
                        f.cancel()
                    break
        ok = [r for r in results if r.plan is not None]
        return (min(ok, key=lambda r: r.duration) if ok else None), results


def _noop(_: int) -> int:
    return 0


def plan_r2r(
    cell: Cell,
    action: Action,
    q: Mapping[str, Joints],
    *,
    planner: CandidatePlanner | None = None,
    k: int = 8,
) -> SkillMotion:
    """The best of the ``k`` best goal sets; when none of them has a motion plan, the further
    goal sets of a larger sample (up to R2R_MAX_CANDIDATES), ``k`` at a time, until one does.
    Its ``seconds`` are the whole call's wall-clock time (what P.M.P. shortens).

    The top-ranked goal sets sit near the centre of the shared region, where a hand orientation
    can put a wrist into a singularity on the approach line (the realworld T1 cell: the
    Elfin-3's joint 5 passes through 0 backing off from the centre); that is no reason to call
    the hand-over infeasible while other goal sets remain.
    """
    t0 = time.perf_counter()
    cands = r2r_candidates(cell, action, q, k=k)
    if not cands:
        return SkillMotion(
            action, None, "the two arms share no reachable region", (), time.perf_counter() - t0
        )
    cp = planner or CandidatePlanner(cell)
    tried = {(c.position, c.giver_grasp, c.receiver_grasp) for c in cands}
    best, results = cp.plan(action, q, cands)
    if best is None and k < R2R_MAX_CANDIDATES:
        more = [
            c
            for c in r2r_candidates(cell, action, q, k=R2R_MAX_CANDIDATES)
            if (c.position, c.giver_grasp, c.receiver_grasp) not in tried
        ]
        for i in range(0, len(more), k):
            best, batch = cp.plan(action, q, more[i : i + k])
            results.extend(batch)
            if best is not None:
                break
    if best is None:
        reasons = sorted({r.reason for r in results if r.reason})
        why = "; ".join(reasons) if reasons else "no candidate"
        return SkillMotion(
            action,
            None,
            f"no goal set of {len(results)} has a motion plan ({why})",
            (),
            time.perf_counter() - t0,
        )
    # the whole call's time (candidates, every goal set tried, the pool's round trips), not the
    # winning goal set's own
    return replace(best, seconds=time.perf_counter() - t0)


# -- one action -----------------------------------------------------------------------------------


def placement_point(cell: Cell, action: Action) -> Vec3:
    """Where on the surface to put the object down: the placement with the most room among those
    inside the placing robot's reach and clear of the scene's other objects (paper §IV-A);
    the surface's centre when none is."""
    assert action.surface is not None
    scene = cell.scene
    surface = scene.surface(action.surface)
    robot = scene.robot(action.robots[0])
    cyl = _object_cylinder(scene, action.object)
    occupied = [
        (o.position, Cylinder.for_category(o.category).radius)
        for o in scene.objects
        if o.id != action.object
    ]
    kin = cell.kinematics

    def reachable(p: FloatArray) -> bool:
        return kin.reaches(robot, (float(p[0]), float(p[1]), float(p[2])))

    found = placements(surface.center, surface.size, cyl, occupied, reachable)
    if not found:
        return surface.center
    x, y, _ = found[0].position
    return (x, y, surface.center[2])


def plan_action(
    cell: Cell,
    action: Action,
    q: Mapping[str, Joints] | None = None,
    *,
    where: Vec3 | None = None,
    human_at: Vec3 | None = None,
    planner: CandidatePlanner | None = None,
    k: int = 8,
) -> SkillMotion:
    """The motion of one skill instance from the arms' configurations ``q`` (default: home).

    ``where`` is the object's position for pick, the surface point for place; ``human_at`` the
    person's position for handover_r2h (defaults come from the scene).
    """
    qq: Mapping[str, Joints] = q or {}
    scene = cell.scene
    if action.skill == "pick":
        at = scene.object(action.object).position if where is None else where
        return plan_pick(cell, action, qq, at)
    if action.skill == "place":
        if where is None:
            assert action.surface is not None
            where = placement_point(cell, action)
        return plan_pick(cell, action, qq, where, place=True)
    if action.skill == "handover_r2h":
        assert action.human is not None
        at = scene.human(action.human).position if human_at is None else human_at
        return plan_r2h_action(cell, action, qq, at)
    if action.skill == "handover_r2r":
        return plan_r2r(cell, action, qq, planner=planner, k=k)
    raise ValueError(f"no motion planner for skill {action.skill!r}")
