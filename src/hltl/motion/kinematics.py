"""One arm placed in the scene: forward kinematics, Jacobians, DLS inverse kinematics, capsules."""

from __future__ import annotations

import itertools
import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
import numpy.typing as npt

from hltl.motion.robots import ArmSpec, arm_spec, load_model
from hltl.motion.selfcollision import LinkPair, SelfCollision, collision_geometry
from hltl.world.geometry import HANDOVER_HEIGHT

FloatArray = npt.NDArray[np.float64]
Joints = Sequence[float] | FloatArray  # a configuration, as a tuple or an array

# Reasons an IK query fails (IkResult.reason).
OUT_OF_REACH = "out_of_reach"
JOINT_LIMIT = "joint_limit"
COLLISION = "collision"

# How far (m) a link's collision capsule may dip into the table top: the capsules are rounded
# stand-ins for boxy links and hands, so a grasp at table level may graze the plane a little.
TABLE_TOLERANCE = 0.01
# Extra travel time (s) an elbow-down IK solution must save to be preferred over an elbow-up one:
# elbow-down poses sweep the forearm low over the table and the objects on it.
ELBOW_DOWN_PENALTY = 1.0
# Clearance (m) between the arm's own links in its rest pose (Arm.home).
HOME_CLEARANCE = 0.03


@dataclass(frozen=True, slots=True)
class IkResult:
    """What an IK query found: a configuration, or the reason there is none.

    The residuals are always those of the returned configuration (or of the best attempt when
    there is none), measured by forward kinematics after the solve, never assumed.
    """

    q: tuple[float, ...] | None
    reason: str | None
    position_error: float
    rotation_error: float
    iterations: int
    starts: int

    @property
    def ok(self) -> bool:
        return self.q is not None


@dataclass(frozen=True, slots=True)
class Capsule:
    """A segment with a radius, in the scene frame: one link, the hand, or a body part."""

    a: tuple[float, float, float]
    b: tuple[float, float, float]
    radius: float
    name: str = ""


def rotation_z_to(
    direction: Sequence[float] | FloatArray, roll_hint: Sequence[float] | FloatArray | None = None
) -> FloatArray:
    """A rotation whose z axis is ``direction``, x as close to ``roll_hint`` as it gets."""
    z = np.asarray(direction, dtype=float)
    z = z / np.linalg.norm(z)
    hint = np.array([0.0, 0.0, -1.0]) if roll_hint is None else np.asarray(roll_hint, dtype=float)
    x = hint - np.dot(hint, z) * z
    if np.linalg.norm(x) < 1e-6:
        alt = np.array([1.0, 0.0, 0.0]) if abs(z[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
        x = alt - np.dot(alt, z) * z
    x = x / np.linalg.norm(x)
    # z × x written out: np.cross is slow on single vectors, and this runs per collision check
    y = np.array([z[1] * x[2] - z[2] * x[1], z[2] * x[0] - z[0] * x[2], z[0] * x[1] - z[1] * x[0]])
    out = np.empty((3, 3))
    out[:, 0], out[:, 1], out[:, 2] = x, y, z
    return out


class Arm:
    """A registered arm model whose base sits at ``base`` in the scene frame (no base rotation).

    Holds its own Pinocchio data, so one Arm must not be shared between threads.
    """

    def __init__(self, robot: str, model: str, base: Sequence[float] = (0.0, 0.0, 0.0)) -> None:
        import pinocchio as pin

        self._pin = pin
        self.robot = robot
        self.spec: ArmSpec = arm_spec(model)
        self.model = load_model(model)
        self.data = self.model.createData()
        self.base = np.asarray(base, dtype=float)
        self.tool = self.model.getFrameId(self.spec.tool_frame)
        self.nq = int(self.model.nq)
        self.joint_names: tuple[str, ...] = tuple(str(n) for n in self.model.names[1:])
        self.lower = np.asarray(self.model.lowerPositionLimit, dtype=float).copy()
        self.upper = np.asarray(self.model.upperPositionLimit, dtype=float).copy()
        self.max_velocity = np.asarray(self.model.velocityLimit, dtype=float).copy()
        # Seeds are drawn from the limits folded into one turn: beyond ±π a revolute joint only
        # repeats itself.
        self._seed_lo = np.maximum(self.lower, -math.pi)
        self._seed_hi = np.minimum(self.upper, math.pi)
        q0 = self.neutral()
        self._fk_all(q0)
        joints = [np.asarray(self.data.oMi[j].translation) for j in range(1, self.model.njoints)]
        # The shoulder is the first point the arm pivots about away from the base axis; every
        # reachable point lies within the summed link lengths of it.
        self.shoulder_offset = joints[1]
        chain = [*joints[1:], np.asarray(self.data.oMf[self.tool].translation)]
        self.max_extent = float(sum(np.linalg.norm(b - a) for a, b in itertools.pairwise(chain)))
        self._library: tuple[FloatArray, FloatArray, FloatArray] | None = None
        self.self_collision = SelfCollision(collision_geometry(model), self.model)
        self.home = self._home()

    # -- forward kinematics ----------------------------------------------------------------------
    def neutral(self) -> FloatArray:
        return np.clip(np.zeros(self.nq), self.lower, self.upper)

    def _fk_all(self, q: FloatArray) -> None:
        pin = self._pin
        local = _local(q)
        pin.forwardKinematics(self.model, self.data, local)
        pin.updateFramePlacements(self.model, self.data)
        # shift into the scene frame lazily: callers add self.base

    def fk(self, q: Joints) -> tuple[FloatArray, FloatArray]:
        """Tool frame position (scene frame) and rotation matrix at joint positions ``q``."""
        pin = self._pin
        qa = _local(q)
        pin.forwardKinematics(self.model, self.data, qa)
        m = pin.updateFramePlacement(self.model, self.data, self.tool)
        return np.asarray(m.translation) + self.base, np.asarray(m.rotation).copy()

    def jacobian(self, q: Joints) -> FloatArray:
        """6×n tool Jacobian (linear; angular), expressed in the scene-aligned tool frame."""
        pin = self._pin
        qa = _local(q)
        j = pin.computeFrameJacobian(
            self.model, self.data, qa, self.tool, pin.ReferenceFrame.LOCAL_WORLD_ALIGNED
        )
        return np.asarray(j).copy()

    def joint_positions(self, q: Joints) -> list[FloatArray]:
        """Scene-frame origins of every joint, then the flange-side wrist and the tool point."""
        self._fk_all(_local(q))
        return _joint_points(self.model, self.data, self.tool, self.base)

    def capsules(self, q: Joints) -> list[Capsule]:
        """Collision capsules of the links and the hand at ``q`` (scene frame)."""
        pts = self.joint_positions(q)
        return link_capsules(
            self.spec, self.base, pts, np.asarray(self.data.oMf[self.tool].rotation)
        )

    def table_clearance(self, q: Joints) -> float:
        """Signed distance (m) from the table top to the lowest link surface (capsules beyond the
        base); negative when a link passes into the table."""
        caps = self.capsules(q)[1:]
        return min(min(c.a[2], c.b[2]) - c.radius for c in caps) - float(self.base[2])

    def pose_clear(self, q: Joints) -> bool:
        """The arm alone is in a valid pose: clear of the table top (:meth:`above_table`) and of
        itself (:meth:`self_clear`)."""
        return self.above_table(q) and self.self_clear(q)

    def self_clear(self, q: Joints) -> bool:
        """No two links of the arm that can touch come closer than SELF_MARGIN (coal distances
        on the URDF's collision geometry; see :mod:`hltl.motion.selfcollision`)."""
        return self.self_collision.clear(_local(q))

    def self_distance(self, q: Joints) -> tuple[float, LinkPair | None]:
        """The closest pair of the arm's own links that can touch, and their distance (m)."""
        return self.self_collision.distance(_local(q))

    def elbow_up(self, q: Joints) -> bool:
        """True when the elbow sits above the line from the shoulder to the wrist.

        The elbow is the joint farthest from that line (Elfin-3 joint 3, UR5 elbow, Panda joint 4);
        the wrist is the last joint origin.
        """
        pts = self.joint_positions(q)
        shoulder, wrist = pts[1], pts[-2]
        axis = wrist - shoulder
        n = float(np.dot(axis, axis))
        best, above = -1.0, True
        for p in pts[2:-2]:
            s = float(np.dot(p - shoulder, axis)) / n if n > 1e-12 else 0.0
            foot = shoulder + axis * min(max(s, 0.0), 1.0)
            d = float(np.linalg.norm(p - foot))
            if d > best:
                best, above = d, bool(p[2] >= foot[2] - 1e-6)
        return above

    def travel_time(self, q_from: Joints, q_to: Joints) -> float:
        """Lower bound (s) on moving between two configurations: the slowest joint at its
        velocity limit."""
        dq = np.abs(np.asarray(q_to, dtype=float) - np.asarray(q_from, dtype=float))
        return float(np.max(dq / self.max_velocity))

    def ik_line(
        self,
        q_start: Joints,
        offset: Sequence[float] | FloatArray,
        *,
        step: float = 0.01,
        max_joint_step: float = 0.15,
    ) -> list[tuple[float, ...]] | None:
        """Configurations moving the tool in a straight line by ``offset`` at a fixed orientation.

        Each step (``step`` m) is solved from the previous configuration, and a step that moves
        any joint by more than ``max_joint_step`` rad (another IK branch) or does not converge
        ends the line: approach and retreat stay on the grasp's own branch.
        """
        q = np.asarray(q_start, dtype=float)
        p0, rot = self.fk(q)
        off = np.asarray(offset, dtype=float)
        n = max(1, math.ceil(float(np.linalg.norm(off)) / step))
        out = [_q(q)]
        for k in range(1, n + 1):
            target = p0 + off * (k / n)
            q1, ep, er, _ = self._dls(target, rot, q, 1e-3, 1e-2, 60, True)
            if ep > 1e-3 or er > 1e-2 or float(np.max(np.abs(q1 - q))) > max_joint_step:
                return None
            q = q1
            out.append(_q(q))
        return out

    def above_table(self, q: Joints) -> bool:
        """True when every link capsule beyond the base stays above the table top (within
        TABLE_TOLERANCE): the table the arm is mounted on, which objects stand on."""
        return self.table_clearance(q) >= -TABLE_TOLERANCE

    # -- inverse kinematics ----------------------------------------------------------------------
    def ik(
        self,
        position: Sequence[float] | FloatArray,
        rotation: FloatArray | None = None,
        q0: Joints | None = None,
        *,
        starts: int = 8,
        seed: int = 0,
        tol_pos: float = 1e-3,
        tol_rot: float = 1e-2,
        max_iter: int = 150,
        accept: Callable[[FloatArray], bool] | None = None,
        prefer: Joints | None = None,
        solutions: int = 3,
    ) -> IkResult:
        """Damped least squares IK with joint limits and random restarts.

        Args:
            position: the tool point's target (scene frame).
            rotation: the tool frame's target rotation, or ``None`` for position only.
            q0: the first start (the arm's current configuration); else :attr:`home`.
            starts: number of starts (q0 plus random configurations within the limits).
            accept: an extra test a solution must pass (e.g. collision-free); a converged
                solution it rejects makes the reason ``collision``.
            prefer: when given, up to ``solutions`` solutions are collected and the one quickest
                to reach from ``prefer`` (slowest joint at its velocity limit) is returned, an
                elbow-down one only when it saves more than ELBOW_DOWN_PENALTY seconds: the
                branch continuous with the current configuration, elbow up.

        Returns:
            An :class:`IkResult`; ``reason`` is ``out_of_reach``, ``joint_limit`` or ``collision``
            when no configuration was found.
        """
        target = np.asarray(position, dtype=float)
        if np.linalg.norm(target - (self.base + self.shoulder_offset)) > self.max_extent + tol_pos:
            return IkResult(None, OUT_OF_REACH, math.inf, math.inf, 0, 0)
        rng = np.random.default_rng(seed)
        near = self._nearest_seeds(target, rotation, max(starts // 2, 1))
        # The current configuration is the natural first start (short motions); without one the
        # stored configuration nearest the target is.
        first = near.pop(0) if q0 is None else np.asarray(q0, dtype=float)
        rejected = False
        best: tuple[float, float, FloatArray] | None = None
        found: list[tuple[float, FloatArray, float, float, int]] = []
        total_iter = 0
        for k in range(starts):
            if k == 0:
                start = first
            elif k <= len(near):
                start = near[k - 1]
            else:
                start = rng.uniform(self._seed_lo, self._seed_hi)
            q, ep, er, it = self._dls(target, rotation, start, tol_pos, tol_rot, max_iter, True)
            total_iter += it
            if ep <= tol_pos and er <= tol_rot:
                if self.pose_clear(q) and (accept is None or accept(q)):
                    if prefer is None:
                        return IkResult(_q(q), None, ep, er, total_iter, k + 1)
                    gap = self.travel_time(prefer, q)
                    if not self.elbow_up(q):
                        gap += ELBOW_DOWN_PENALTY
                    found.append((gap, q, ep, er, k + 1))
                    if len(found) >= solutions:
                        break
                    continue
                rejected = True
                continue
            if best is None or ep + 0.1 * er < best[0] + 0.1 * best[1]:
                best = (ep, er, q)
        if found:
            _, q, ep, er, k = min(found, key=lambda f: f[0])
            return IkResult(_q(q), None, ep, er, total_iter, k)
        if rejected:
            return IkResult(None, COLLISION, 0.0, 0.0, total_iter, starts)
        assert best is not None
        # Without joint limits, does the same start converge? Then the limits are what block it.
        _, ep, er, it = self._dls(target, rotation, best[2], tol_pos, tol_rot, max_iter, False)
        total_iter += it
        reason = JOINT_LIMIT if ep <= tol_pos and er <= tol_rot else OUT_OF_REACH
        return IkResult(None, reason, best[0], best[1], total_iter, starts)

    def _nearest_seeds(
        self, target: FloatArray, rotation: FloatArray | None, k: int
    ) -> list[FloatArray]:
        """Stored configurations whose tool pose is nearest the target: IK starts that converge."""
        if self._library is None:
            self._library = self._build_library(2048)
        qs, pos, rot = self._library
        cost = np.linalg.norm(pos - (target - self.base), axis=1)
        if rotation is not None:
            # 3 - trace(R_a^T R_b) grows with the angle between the two orientations
            cost = cost + 0.1 * (3.0 - np.einsum("nij,ij->n", rot, rotation))
        idx = np.argsort(cost)[:k]
        return [qs[i] for i in idx]

    def _build_library(self, n: int) -> tuple[FloatArray, FloatArray, FloatArray]:
        rng = np.random.default_rng(12345)
        qs: list[FloatArray] = []
        pos: list[FloatArray] = []
        rot: list[FloatArray] = []
        while len(qs) < n:
            q = rng.uniform(self._seed_lo, self._seed_hi)
            if not self.pose_clear(q):
                continue
            p, r = self.fk(q)
            qs.append(q)
            pos.append(p - self.base)
            rot.append(r)
        return np.array(qs), np.array(pos), np.array(rot)

    def _dls(
        self,
        target: FloatArray,
        rotation: FloatArray | None,
        start: FloatArray,
        tol_pos: float,
        tol_rot: float,
        max_iter: int,
        limits: bool,
    ) -> tuple[FloatArray, float, float, int]:
        pin = self._pin
        model, data, fid = self.model, self.data, self.tool
        lwa = pin.ReferenceFrame.LOCAL_WORLD_ALIGNED
        q = np.array(start, dtype=float)
        local_target = target - self.base
        six = rotation is not None
        damping = 1e-4
        ep = er = math.inf
        stall_ref, stall_it = math.inf, 0
        for it in range(max_iter):
            pin.computeJointJacobians(model, data, q)  # also runs forward kinematics
            m = pin.updateFramePlacement(model, data, fid)
            e_pos = local_target - m.translation
            ep = float(np.linalg.norm(e_pos))
            if six:
                e_rot = pin.log3(rotation @ m.rotation.T)
                er = float(np.linalg.norm(e_rot))
                err = np.concatenate([e_pos, e_rot])
            else:
                er = 0.0
                err = e_pos
            if ep <= tol_pos and er <= tol_rot:
                return q, ep, er, it
            # A start that stops improving (a joint pinned at its limit, a singularity) is
            # abandoned early: another start is cheaper than waiting out max_iter.
            total = ep + 0.1 * er
            if total < 0.98 * stall_ref:
                stall_ref, stall_it = total, it
            elif it - stall_it > 25:
                return q, ep, er, it
            jac = pin.getFrameJacobian(model, data, fid, lwa)
            if not six:
                jac = jac[:3]
            dq = jac.T @ np.linalg.solve(jac @ jac.T + damping * np.eye(jac.shape[0]), err)
            step = float(np.max(np.abs(dq)))
            if step > 0.4:
                dq *= 0.4 / step
            q = q + dq
            if limits:
                q = np.clip(q, self.lower, self.upper)
        return q, ep, er, max_iter

    def _roomy(self, q: FloatArray) -> bool:
        """The hand's collision bodies are HOME_CLEARANCE from every other link they could
        touch."""
        return self.self_collision.clearance_of(q, self.spec.hand_bodies) >= HOME_CLEARANCE

    def _home(self) -> FloatArray:
        """A rest pose: the hand above the base at handover height, pointing down."""
        target = self.base + np.array([0.0, 0.0, HANDOVER_HEIGHT])
        down = rotation_z_to((0.0, 0.0, -1.0), (1.0, 0.0, 0.0))
        seed_q = self.neutral()
        self.home = seed_q
        # among several solutions, the one nearest the upright zero pose: elbow up, wrist level,
        # and the links well apart, so that motions out of the rest pose start free
        roomy = self._roomy
        res = self.ik(
            target, down, seed_q, starts=24, seed=7, prefer=seed_q, solutions=8, accept=roomy
        )
        if res.q is None:
            lifted = target + np.array([0.2, 0.0, 0.1])
            res = self.ik(
                lifted, None, seed_q, starts=24, seed=7, prefer=seed_q, solutions=8, accept=roomy
            )
        return seed_q if res.q is None else np.asarray(res.q)


class LinkGeometry:
    """An arm's link capsules by forward kinematics alone — the same capsules as
    :meth:`Arm.capsules` — without what makes an :class:`Arm` slow to build (its rest pose is an
    IK search, its self-collision model loads meshes): what perception needs to tell the arm's
    own pixels from objects.

    Raises:
        SceneError: an unknown model. BackendUnavailableError: no Pinocchio.
    """

    def __init__(self, model: str, base: Sequence[float] = (0.0, 0.0, 0.0)) -> None:
        import pinocchio as pin

        self._pin = pin
        self.spec: ArmSpec = arm_spec(model)
        self.model = load_model(model)
        self.data = self.model.createData()
        self.tool = self.model.getFrameId(self.spec.tool_frame)
        self.base = np.asarray(base, dtype=float)
        self.nq = int(self.model.nq)

    def capsules(self, q: Joints) -> list[Capsule]:
        """The links' and the hand's capsules at ``q`` (scene frame)."""
        pin = self._pin
        pin.forwardKinematics(self.model, self.data, _local(q))
        pin.updateFramePlacements(self.model, self.data)
        pts = _joint_points(self.model, self.data, self.tool, self.base)
        return link_capsules(
            self.spec, self.base, pts, np.asarray(self.data.oMf[self.tool].rotation)
        )


def _joint_points(model: Any, data: Any, tool: int, base: FloatArray) -> list[FloatArray]:
    """Scene-frame joint origins and the tool point of ``data`` after forward kinematics."""
    pts = [np.asarray(data.oMi[j].translation) + base for j in range(1, model.njoints)]
    pts.append(np.asarray(data.oMf[tool].translation) + base)
    return pts


def link_capsules(
    spec: ArmSpec, base: FloatArray, pts: Sequence[FloatArray], tool_rot: FloatArray
) -> list[Capsule]:
    """The base, link and hand capsules through joint points ``pts`` (tool point last)."""
    out = [Capsule(_t(base), _t(pts[0]), spec.link_radius, "base")]
    r = spec.link_radius
    for i in range(len(pts) - 2):
        out.append(Capsule(_t(pts[i]), _t(pts[i + 1]), r, f"link{i + 1}"))
    # The hand ends short of the tool point: the fingers close around the object there.
    palm = pts[-1] - tool_rot[:, 2] * (spec.hand_radius * 0.9)
    out.append(Capsule(_t(pts[-2]), _t(palm), spec.hand_radius, "hand"))
    return out


def _q(q: FloatArray) -> tuple[float, ...]:
    return tuple(float(v) for v in q)


def _local(q: Joints | FloatArray) -> FloatArray:
    return np.asarray(q, dtype=float)


def _t(p: Any) -> tuple[float, float, float]:
    return (float(p[0]), float(p[1]), float(p[2]))
