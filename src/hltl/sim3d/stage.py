"""The posable 3D cell: set arms' joints, people's walk and reach, objects' places; IK for arms."""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from hltl.sim.route import Rect
from hltl.sim3d.gl import mujoco
from hltl.sim3d.model import TABLE_HEIGHT, RobotRig, SceneModel
from hltl.world.geometry import home_point
from hltl.world.scene import Scene, Vec3

DOWN = (0.0, 0.0, -1.0)


@dataclass(frozen=True, slots=True)
class Contact:
    """A robot's collision geometry touching a person's body."""

    robot: str
    human: str
    position: Vec3
    depth: float  # penetration in metres (MuJoCo's contact distance, negated)
    part: str = ""  # the person's body part touched (``r_forearm``, ``torso`` …)


@dataclass(frozen=True, slots=True)
class IKResult:
    q: tuple[float, ...]
    error: float  # remaining distance from the hand to the target, metres


class Stage:
    """One scene model with a posable state (``data``) and a scratch state for IK."""

    def __init__(self, sm: SceneModel) -> None:
        mj = mujoco()
        self.mj = mj
        self.sm = sm
        self.scene: Scene = sm.scene
        self.model = sm.model
        self.data = mj.MjData(self.model)
        self._ik = mj.MjData(self.model)
        self._object_body = {
            o.id: int(mj.mj_name2id(self.model, mj.mjtObj.mjOBJ_BODY, f"object:{o.id}"))
            for o in self.scene.objects
        }
        self.home = {
            rid: self.solve(rid, home_point(self.scene.robot(rid)), rig.seed).q
            for rid, rig in sm.robots.items()
        }
        for rid, q in self.home.items():
            self.set_robot(rid, q)
        for h in self.scene.humans:
            self.set_human(h.id, h.position, self.facing(h.position))
        for o in self.scene.objects:
            self.set_object(o.id, o.position)
        self.forward()

    def rehome(self, rid: str, q: Sequence[float]) -> None:
        """Make ``q`` the arm's rest pose (e.g. the motion layer's ``Arm.home``) and pose it."""
        self.home[rid] = tuple(float(v) for v in q)
        self.set_robot(rid, self.home[rid])
        self.forward()

    # -- posing -----------------------------------------------------------------------------

    def set_robot(self, rid: str, q: Sequence[float]) -> None:
        rig = self.sm.robots[rid]
        self.data.qpos[list(rig.qpos_adr)] = q

    def robot_q(self, rid: str) -> tuple[float, ...]:
        rig = self.sm.robots[rid]
        return tuple(float(v) for v in self.data.qpos[list(rig.qpos_adr)])

    def joints(self) -> dict[str, tuple[float, ...]]:
        """The joint positions of every arm drawn as its motion model (what a frame of this pose
        carries as ``joints``). A primitive arm is left out: its joints (e.g. an xArm6 drawn
        with four) are not its motion model's, so they would place nothing."""
        return {
            rid: self.robot_q(rid)
            for rid, rig in self.sm.robots.items()
            if rig.model != "primitive"
        }

    def table_rect(self) -> Rect:
        """The work table's top on the floor plan (its box geom in the compiled model)."""
        m = self.model
        body = int(self.mj.mj_name2id(m, self.mj.mjtObj.mjOBJ_BODY, "table"))
        g = int(m.body_geomadr[body])
        (cx, cy, _), (hx, hy) = m.body_pos[body], m.geom_size[g][:2]
        return Rect(float(cx - hx), float(cx + hx), float(cy - hy), float(cy + hy))

    def object_lift(self, oid: str) -> float:
        """Height of an object's grasp point above its bottom (to stand it on a surface)."""
        m = self.model
        body = self._object_body[oid]
        g = int(m.body_geomadr[body])
        return float(m.geom_size[g][1] - m.geom_pos[g][2])

    def set_object(self, oid: str, position: Sequence[float]) -> None:
        self.data.mocap_pos[self.sm.object_mocap[oid]] = position

    def facing(self, position: Sequence[float]) -> float:
        """Yaw of a person at ``position`` who faces the nearest robot."""
        base = min(self.scene.robots, key=lambda r: math.dist(r.base[:2], position[:2])).base
        return math.atan2(base[1] - position[1], base[0] - position[0])

    def set_human(
        self,
        hid: str,
        position: Sequence[float],
        yaw: float,
        *,
        reach: float = 0.0,
        hold: bool = False,
        stride: float | None = None,
    ) -> None:
        """Pose a person: standing at ``position`` facing ``yaw``; ``reach`` in [0, 1] raises the
        right forearm to receive; ``hold`` carries something in the right hand; ``stride`` is the
        distance walked so far (legs and arms swing with it), None when standing."""
        rig = self.sm.humans[hid]
        d = self.data
        d.mocap_pos[rig.mocap] = (position[0], position[1], -TABLE_HEIGHT)
        d.mocap_quat[rig.mocap] = (math.cos(yaw / 2), 0.0, 0.0, math.sin(yaw / 2))
        swing = 0.0 if stride is None else math.sin(2 * math.pi * stride / 1.3)
        lift = 0.0 if stride is None else abs(math.sin(2 * math.pi * stride / 1.3))
        angles = {
            "r_hip": 0.4 * swing,
            "l_hip": -0.4 * swing,
            "r_knee": 0.5 * lift * (swing < 0),
            "l_knee": 0.5 * lift * (swing > 0),
            "l_shoulder": 0.3 * swing,
            "l_elbow": 0.15 + 0.1 * lift,
            "r_shoulder": -0.3 * swing,
            "r_elbow": 0.15 + 0.1 * lift,
        }
        if hold:
            angles["r_shoulder"], angles["r_elbow"] = 0.0, 1.0
        a = min(max(reach, 0.0), 1.0)
        if a > 0.0:
            angles["r_shoulder"] = (1 - a) * angles["r_shoulder"] + a * 0.45
            angles["r_elbow"] = (1 - a) * angles["r_elbow"] + a * 1.15
        for joint, value in angles.items():
            d.qpos[rig.adr(joint)] = value

    def forward(self) -> None:
        """Recompute positions (and contacts) after posing."""
        self.mj.mj_fwdPosition(self.model, self.data)

    # -- reading ----------------------------------------------------------------------------

    def hand(self, rid: str) -> Vec3:
        p = self.data.site_xpos[self.sm.robots[rid].hand_site]
        return (float(p[0]), float(p[1]), float(p[2]))

    def human_hand(self, hid: str) -> Vec3:
        p = self.data.site_xpos[self.sm.humans[hid].hand_site]
        return (float(p[0]), float(p[1]), float(p[2]))

    def contacts(self) -> list[Contact]:
        """Robot–person contacts in the current pose (after :meth:`forward`)."""
        out = []
        seg = self.sm.geom_segment
        segs = self.sm.segments
        d = self.data
        for i in range(d.ncon):
            c = d.contact[i]
            a, b = segs.get(int(seg[c.geom1])), segs.get(int(seg[c.geom2]))
            if a is None or b is None:
                continue
            hg = int(c.geom2)
            if a.kind == "human" and b.kind == "robot":
                a, b = b, a
                hg = int(c.geom1)
            if a.kind == "robot" and b.kind == "human":
                p = c.pos
                body = self.mj.mj_id2name(
                    self.model, self.mj.mjtObj.mjOBJ_BODY, int(self.model.geom_bodyid[hg])
                )
                part = (body or "").partition("/")[2] or "torso"
                out.append(
                    Contact(
                        a.id,
                        b.id,
                        (float(p[0]), float(p[1]), float(p[2])),
                        float(-c.dist),
                        part,
                    )
                )
        return out

    # -- inverse kinematics -----------------------------------------------------------------

    def solve(
        self,
        rid: str,
        target: Sequence[float],
        q0: Sequence[float],
        approach: Sequence[float] | None = DOWN,
        iters: int = 200,
    ) -> IKResult:
        """Joint angles that put the hand at ``target`` (damped least squares), with the hand's
        approach axis along ``approach`` where the arm allows it."""
        r = self._dls(self.sm.robots[rid], np.asarray(target, float), q0, approach, iters)
        if approach is not None and r.error > 0.005:
            # the orientation cannot be had here: position alone, from where that got to
            alt = self._dls(self.sm.robots[rid], np.asarray(target, float), r.q, None, iters)
            if alt.error < r.error:
                return alt
        return r

    def _dls(
        self,
        rig: RobotRig,
        target: np.ndarray,
        q0: Sequence[float],
        approach: Sequence[float] | None,
        iters: int,
    ) -> IKResult:
        mj = self.mj
        m, d = self.model, self._ik
        adr = list(rig.qpos_adr)
        dof = list(rig.dof_adr)
        lo, hi = np.array(rig.lower), np.array(rig.upper)
        q = np.clip(np.array(q0, float), lo, hi)
        jacp = np.zeros((3, m.nv))
        jacr = np.zeros((3, m.nv))
        want = None if approach is None else np.asarray(approach, float) / np.linalg.norm(approach)
        err = math.inf
        lam2 = 0.03**2
        for _ in range(iters):
            d.qpos[adr] = q
            mj.mj_kinematics(m, d)
            mj.mj_comPos(m, d)
            pos = d.site_xpos[rig.hand_site]
            e_p = target - pos
            err = float(np.linalg.norm(e_p))
            mj.mj_jacSite(m, d, jacp, jacr, rig.hand_site)
            if want is None:
                jac = jacp[:, dof]
                e = e_p
            else:
                z = d.site_xmat[rig.hand_site].reshape(3, 3)[:, 2]
                e_r = np.cross(z, want)
                if err < 1e-4 and float(np.linalg.norm(e_r)) < 1e-3 and float(z @ want) > 0:
                    break
                if float(z @ want) < 0:  # pointing away: any perpendicular turn axis works
                    e_r = np.cross(
                        z,
                        np.array([1.0, 0.0, 0.0]) if abs(z[0]) < 0.9 else np.array([0.0, 1.0, 0.0]),
                    )
                w = 0.3
                jac = np.vstack([jacp[:, dof], w * jacr[:, dof]])
                e = np.concatenate([e_p, w * e_r])
            if want is None and err < 1e-4:
                break
            dq = jac.T @ np.linalg.solve(jac @ jac.T + lam2 * np.eye(jac.shape[0]), e)
            n = float(np.linalg.norm(dq))
            if n > 0.3:
                dq *= 0.3 / n
            q = np.clip(q + dq, lo, hi)
        d.qpos[adr] = q
        mj.mj_kinematics(m, d)
        err = float(np.linalg.norm(target - d.site_xpos[rig.hand_site]))
        return IKResult(tuple(float(v) for v in q), err)
