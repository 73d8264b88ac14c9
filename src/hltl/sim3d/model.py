"""Scene → MuJoCo model (built in code with MjSpec), with a cache of compiled models."""

from __future__ import annotations

import hashlib
import json
import math
import os
import zlib
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from hltl.errors import BackendUnavailableError, SceneError
from hltl.motion.grasps import CATEGORY_CYLINDERS
from hltl.motion.robots import ELFIN3_URDF, arm_spec
from hltl.sim3d.gl import mujoco
from hltl.world.scene import Camera, Robot, Scene, SceneObject

# Height of the scene's z = 0 plane (the work table) above the floor people stand on.
TABLE_HEIGHT = 0.75
# Bumped whenever the builder changes what it builds, so cached models are rebuilt.
BUILDER_VERSION = "sim3d-1"

# Segment kinds of camera.json, by root-body prefix.
_KINDS = ("robot", "object", "human", "surface")

# Joints a person's figure has; each rotates about the person's lateral axis (positive: forward).
HUMAN_JOINTS = (
    "r_shoulder",
    "r_elbow",
    "l_shoulder",
    "l_elbow",
    "r_hip",
    "r_knee",
    "l_hip",
    "l_knee",
)

# category → (radius, height, rgba)
_OBJECT_LOOKS: dict[str, tuple[float, float, tuple[float, float, float, float]]] = {
    "bottle": (0.033, 0.22, (0.10, 0.55, 0.30, 1.0)),
    "chips": (0.055, 0.16, (0.95, 0.75, 0.10, 1.0)),
    "cup": (0.040, 0.10, (0.92, 0.92, 0.88, 1.0)),
    "mug": (0.040, 0.10, (0.85, 0.25, 0.20, 1.0)),
    "can": (0.033, 0.12, (0.80, 0.10, 0.10, 1.0)),
    "apple": (0.040, 0.08, (0.75, 0.10, 0.10, 1.0)),
    "box": (0.060, 0.12, (0.60, 0.45, 0.30, 1.0)),
    "book": (0.070, 0.04, (0.20, 0.30, 0.70, 1.0)),
}
_SKIN = (
    (0.93, 0.78, 0.65, 1.0),
    (0.65, 0.46, 0.33, 1.0),
    (0.85, 0.66, 0.50, 1.0),
    (0.45, 0.30, 0.22, 1.0),
)
_SHIRTS = (
    (0.80, 0.20, 0.20, 1.0),
    (0.20, 0.35, 0.75, 1.0),
    (0.95, 0.60, 0.10, 1.0),
    (0.45, 0.25, 0.60, 1.0),
)
_TROUSERS = ((0.15, 0.18, 0.28, 1.0), (0.25, 0.25, 0.25, 1.0))

# UR5 joint origins (example-robot-data's ur5_robot.urdf) on robosuite's UR5e body tree.
_UR5_CHAIN = (
    ("shoulder_link", (0.0, 0.0, 0.089159)),
    ("upper_arm_link", (0.0, 0.13585, 0.0)),
    ("forearm_link", (0.0, -0.1197, 0.425)),
    ("wrist_1_link", (0.0, 0.0, 0.39225)),
    ("wrist_2_link", (0.0, 0.093, 0.0)),
    ("wrist_3_link", (0.0, 0.0, 0.09465)),
    ("right_hand", (0.0, 0.0823, 0.0)),
)


def _hand_length(kind: str) -> float:
    """Flange to grasp point, as the motion layer's registry says (its extra is not needed)."""
    return arm_spec(kind).hand_length if kind in ("ur5", "elfin3") else 0.1034


# Per robot model: joint speed limit (rad/s) and a comfortable seed posture for IK.
_ROBOT_KINEMATICS: dict[str, tuple[float, tuple[float, ...]]] = {
    "ur5": (math.pi, (0.0, -1.9, 1.9, -1.57, -1.57, 0.0)),
    "panda": (2.1, (0.0, -0.3, 0.0, -2.2, 0.0, 2.0, 0.78)),
    "elfin3": (1.57, (0.0, 0.6, 1.6, 0.0, 0.9, 0.0)),
    "primitive": (1.5, (0.0, 0.5, 1.4, 1.2)),
}
_ROBOT_MODEL_ALIASES = {"ur5": "ur5", "ur5e": "ur5", "panda": "panda", "elfin3": "elfin3"}


@dataclass(frozen=True, slots=True)
class Segment:
    """An entity of the scene as the segmentation image names it."""

    kind: str  # object | human | robot | surface | floor | other
    id: str


@dataclass(frozen=True, slots=True)
class RobotRig:
    """One robot's joints in the compiled model."""

    id: str
    model: str  # ur5 | panda | elfin3 | primitive
    joint_names: tuple[str, ...]  # without the ``robot:<id>/`` prefix
    qpos_adr: tuple[int, ...]
    dof_adr: tuple[int, ...]
    lower: tuple[float, ...]
    upper: tuple[float, ...]
    vmax: float
    seed: tuple[float, ...]
    hand_site: int


@dataclass(frozen=True, slots=True)
class HumanRig:
    id: str
    mocap: int
    qpos: tuple[tuple[str, int], ...]  # joint → qpos address
    hand_site: int

    def adr(self, joint: str) -> int:
        for name, a in self.qpos:
            if name == joint:
                return a
        raise KeyError(joint)


class SceneModel:
    """A compiled scene: the MuJoCo model plus the map from its parts to scene entities."""

    def __init__(self, scene: Scene, model: Any) -> None:
        mj = mujoco()
        self.scene = scene
        self.model = model
        m = model
        self.segments: dict[int, Segment] = {
            1: Segment("floor", "floor"),
            2: Segment("other", "table"),
        }
        ids: dict[tuple[str, str], int] = {}
        for kind, items in (
            ("surface", scene.surface_ids),
            ("robot", scene.robot_ids),
            ("object", scene.object_ids),
            ("human", scene.human_ids),
        ):
            for eid in items:
                sid = len(self.segments) + 1
                self.segments[sid] = Segment(kind, eid)
                ids[(kind, eid)] = sid
        # geom → segment id, through each geom's root body
        body_seg = np.zeros(m.nbody, dtype=np.int32)
        for b in range(1, m.nbody):
            root = int(m.body_rootid[b])
            name = mj.mj_id2name(m, mj.mjtObj.mjOBJ_BODY, root) or ""
            kind, _, eid = name.partition(":")
            if name == "table":
                body_seg[b] = 2
            elif kind in _KINDS:
                body_seg[b] = ids.get((kind, eid.split("/")[0]), 0)
        self.geom_segment = np.zeros(m.ngeom, dtype=np.int32)
        for g in range(m.ngeom):
            body = int(m.geom_bodyid[g])
            if body == 0:
                gname = mj.mj_id2name(m, mj.mjtObj.mjOBJ_GEOM, g) or ""
                self.geom_segment[g] = 1 if gname == "floor" else 0
            else:
                self.geom_segment[g] = body_seg[body]
        self.robots = {r.id: self._robot_rig(r) for r in scene.robots}
        self.humans = {h.id: self._human_rig(h.id) for h in scene.humans}
        self.object_mocap = {
            o.id: int(m.body_mocapid[self._body(f"object:{o.id}")]) for o in scene.objects
        }

    def _body(self, name: str) -> int:
        mj = mujoco()
        i = int(mj.mj_name2id(self.model, mj.mjtObj.mjOBJ_BODY, name))
        if i < 0:
            raise SceneError(f"3D model has no body {name!r} (stale model cache?)")
        return i

    def _site(self, name: str) -> int:
        mj = mujoco()
        i = int(mj.mj_name2id(self.model, mj.mjtObj.mjOBJ_SITE, name))
        if i < 0:
            raise SceneError(f"3D model has no site {name!r} (stale model cache?)")
        return i

    def _robot_rig(self, robot: Robot) -> RobotRig:
        mj = mujoco()
        m = self.model
        root = self._body(f"robot:{robot.id}")
        prefix = f"robot:{robot.id}/"
        names, qadr, dadr, lo, hi = [], [], [], [], []
        for j in range(m.njnt):
            if int(m.body_rootid[m.jnt_bodyid[j]]) != root:
                continue
            if m.jnt_type[j] != mj.mjtJoint.mjJNT_HINGE:
                continue
            name = mj.mj_id2name(m, mj.mjtObj.mjOBJ_JOINT, j) or ""
            if "finger" in name:
                continue
            names.append(name.removeprefix(prefix))
            qadr.append(int(m.jnt_qposadr[j]))
            dadr.append(int(m.jnt_dofadr[j]))
            limited = bool(m.jnt_limited[j])
            lo.append(float(m.jnt_range[j][0]) if limited else -math.pi)
            hi.append(float(m.jnt_range[j][1]) if limited else math.pi)
        kind = robot_kind(robot)
        vmax, seed = _ROBOT_KINEMATICS[kind]
        return RobotRig(
            robot.id,
            kind,
            tuple(names),
            tuple(qadr),
            tuple(dadr),
            tuple(lo),
            tuple(hi),
            vmax,
            seed[: len(names)],
            self._site(f"robot:{robot.id}/hand"),
        )

    def _human_rig(self, hid: str) -> HumanRig:
        mj = mujoco()
        m = self.model
        qpos = []
        for j in HUMAN_JOINTS:
            jid = int(mj.mj_name2id(m, mj.mjtObj.mjOBJ_JOINT, f"human:{hid}/{j}"))
            qpos.append((j, int(m.jnt_qposadr[jid])))
        return HumanRig(
            hid,
            int(m.body_mocapid[self._body(f"human:{hid}")]),
            tuple(qpos),
            self._site(f"human:{hid}/hand"),
        )

    def segment_table(self) -> dict[str, dict[str, str]]:
        """camera.json's ``segments``."""
        return {str(k): {"kind": s.kind, "id": s.id} for k, s in sorted(self.segments.items())}


def robot_kind(robot: Robot) -> str:
    return _ROBOT_MODEL_ALIASES.get(robot.model.lower(), "primitive")


def object_look(obj: SceneObject) -> tuple[float, float, tuple[float, float, float, float]]:
    """(radius, height, rgba) of an object's cylinder, by category (unknown ones: hashed colour)."""
    look = _OBJECT_LOOKS.get(obj.category.lower())
    size = CATEGORY_CYLINDERS.get(obj.category.lower())  # the motion layer's grasp model
    if look is not None:
        return look if size is None else (size[0], size[1], look[2])
    h = zlib.crc32(obj.category.encode())
    rgb = tuple(0.25 + 0.6 * ((h >> s) & 0xFF) / 255.0 for s in (0, 8, 16))
    return (0.04, 0.14, (rgb[0], rgb[1], rgb[2], 1.0))


# -- cameras -------------------------------------------------------------------------------------


def default_camera(scene: Scene) -> Camera:
    """A RealSense-D435-like camera (640×480 colour, 42° vertical field of view) on the side of
    the cell, 25° above the table, as close as it can be with every robot, object and person
    (feet to head) in the picture."""
    pts = [r.base for r in scene.robots] + [o.position for o in scene.objects]
    pts += [s.center for s in scene.surfaces]
    for h in scene.humans:
        pts += [
            (h.position[0], h.position[1], -TABLE_HEIGHT),
            (h.position[0], h.position[1], 1.8 - TABLE_HEIGHT),
        ]
    pts += [(r.base[0], r.base[1], r.base[2] + 0.8) for r in scene.robots]
    xs = [p[0] for p in pts]
    ys = [p[1] for p in pts]
    target = ((min(xs) + max(xs)) / 2, (min(ys) + max(ys)) / 2, 0.0)
    elev = math.radians(25)
    fovy = 42.0
    f = 240 / math.tan(math.radians(fovy / 2))
    dist = 1.0
    while dist < 30.0:
        position = (target[0], target[1] - dist * math.cos(elev), target[2] + dist * math.sin(elev))
        cam = Camera("front", position, target, 640, 480, fovy, 10.0)
        axes = camera_axes(cam)
        ok = True
        for p in pts:
            rel = axes.T @ np.subtract(p, position)  # MuJoCo camera frame: -z forward
            if rel[2] > -0.3 or abs(f * rel[0] / -rel[2]) > 300 or abs(f * rel[1] / -rel[2]) > 225:
                ok = False
                break
        if ok:
            return cam
        dist += 0.1
    return cam


def scene_cameras(scene: Scene) -> tuple[Camera, ...]:
    return scene.cameras or (default_camera(scene),)


def camera_axes(cam: Camera) -> np.ndarray:
    """3×3 rotation whose columns are MuJoCo's camera axes (x right, y up, z backwards)."""
    fwd = np.subtract(cam.look_at, cam.position).astype(float)
    fwd /= np.linalg.norm(fwd)
    up = np.array([0.0, 0.0, 1.0])
    if abs(float(fwd @ up)) > 0.999:  # looking straight up or down: pick +y as "up"
        up = np.array([0.0, 1.0, 0.0])
    x = np.cross(fwd, up)
    x /= np.linalg.norm(x)
    y = np.cross(x, fwd)
    return np.column_stack([x, y, -fwd])


# -- building ------------------------------------------------------------------------------------


def _robosuite_assets() -> Path:
    import importlib.util

    spec = importlib.util.find_spec("robosuite")
    if spec is None or not spec.submodule_search_locations:
        raise BackendUnavailableError(
            "the UR5e and Panda models come from robosuite's asset files; install it with "
            "'pip install --no-deps robosuite==1.5.2' (setup.sh does)"
        )
    return Path(next(iter(spec.submodule_search_locations))) / "models" / "assets"


def _quat_from_axes(axes: np.ndarray) -> list[float]:
    mj = mujoco()
    q = np.zeros(4)
    mj.mju_mat2Quat(q, np.ascontiguousarray(axes).reshape(-1))
    return [float(v) for v in q]


def _yaw_quat(yaw: float) -> list[float]:
    return [math.cos(yaw / 2), 0.0, 0.0, math.sin(yaw / 2)]


def _rpy_quat(r: float, p: float, y: float) -> list[float]:
    """URDF roll-pitch-yaw (fixed axes x, y, z) as a MuJoCo quaternion (w, x, y, z)."""
    cr, sr = math.cos(r / 2), math.sin(r / 2)
    cp, sp = math.cos(p / 2), math.sin(p / 2)
    cy, sy = math.cos(y / 2), math.sin(y / 2)
    return [
        cr * cp * cy + sr * sp * sy,
        sr * cp * cy - cr * sp * sy,
        cr * sp * cy + sr * cp * sy,
        cr * cp * sy - sr * sp * cy,
    ]


class _Builder:
    def __init__(self, scene: Scene) -> None:
        self.mj = mujoco()
        self.scene = scene
        self.spec = self.mj.MjSpec()
        s = self.spec
        s.modelname = "hltl_scene"
        s.compiler.degree = False
        s.option.timestep = 0.01
        s.visual.global_.offwidth = 1920
        s.visual.global_.offheight = 1080
        s.visual.quality.shadowsize = 2048
        s.visual.headlight.ambient = [0.35, 0.35, 0.35]
        s.visual.headlight.diffuse = [0.45, 0.45, 0.45]
        s.stat.center = [0.0, 0.0, 0.0]
        s.stat.extent = 4.0

    def geom(self, body: Any, *, group: int = 2, collide: int = 0, **kw: Any) -> Any:
        """A geom; ``collide``: 0 none, 1 robot (collides with people), 2 person."""
        g = body.add_geom(**kw)
        g.group = group
        g.contype = 1 if collide == 1 else 0
        g.conaffinity = 1 if collide == 2 else 0
        return g

    def hinge(self, body: Any, name: str, axis: list[float], rng: Any, mass: float) -> None:
        """A limited revolute joint on ``body`` (and a nominal mass: the playback is kinematic)."""
        mj = self.mj
        body.add_joint(
            name=name,
            type=mj.mjtJoint.mjJNT_HINGE,
            axis=axis,
            range=list(rng),
            limited=mj.mjtLimited.mjLIMITED_TRUE,
        )
        body.mass = mass

    def build(self) -> Any:
        mj = self.mj
        s = self.spec
        tex = s.add_texture(
            name="floor_tex",
            type=mj.mjtTexture.mjTEXTURE_2D,
            builtin=mj.mjtBuiltin.mjBUILTIN_CHECKER,
            rgb1=[0.62, 0.62, 0.60],
            rgb2=[0.55, 0.55, 0.53],
            width=256,
            height=256,
        )
        mat = s.add_material(name="floor_mat", texrepeat=[8, 8])
        mat.textures[mj.mjtTextureRole.mjTEXROLE_RGB] = tex.name
        s.add_texture(
            name="sky",
            type=mj.mjtTexture.mjTEXTURE_SKYBOX,
            builtin=mj.mjtBuiltin.mjBUILTIN_GRADIENT,
            rgb1=[0.80, 0.86, 0.92],
            rgb2=[0.35, 0.40, 0.48],
            width=256,
            height=256,
        )
        w = s.worldbody
        floor = self.geom(
            w,
            name="floor",
            type=mj.mjtGeom.mjGEOM_PLANE,
            size=[6.0, 6.0, 0.1],
            pos=[0.0, 0.0, -TABLE_HEIGHT],
        )
        floor.material = "floor_mat"
        light = w.add_light(pos=[0.0, -1.0, 3.0], dir=[0.0, 0.3, -1.0])
        light.castshadow = True
        light.diffuse = [0.6, 0.6, 0.6]
        self.table()
        for surf in self.scene.surfaces:
            self.surface(surf.id, surf.center, surf.size)
        for robot in self.scene.robots:
            self.robot(robot)
        for obj in self.scene.objects:
            self.object(obj)
        for i, human in enumerate(self.scene.humans):
            self.human(human.id, i)
        for cam in scene_cameras(self.scene):
            c = w.add_camera(name=f"camera:{cam.id}", pos=list(cam.position))
            c.quat = _quat_from_axes(camera_axes(cam))
            c.fovy = cam.fovy
        return s

    # -- the room ---------------------------------------------------------------------------

    def _support_z(self, x: float, y: float) -> float:
        """Height of what an object at (x, y) stands on: a surface under it, else the table."""
        z = 0.0
        for s in self.scene.surfaces:
            if abs(x - s.center[0]) <= s.size[0] / 2 and abs(y - s.center[1]) <= s.size[1] / 2:
                z = max(z, s.center[2])
        return z

    def table(self) -> None:
        mj = self.mj
        sc = self.scene
        xs, ys = [], []
        for r in sc.robots:
            xs += [r.base[0] - 0.25, r.base[0] + 0.25]
            ys += [r.base[1] - 0.25, r.base[1] + 0.25]
        for p in [o.position for o in sc.objects] + [s.center for s in sc.surfaces]:
            xs += [p[0] - 0.15, p[0] + 0.15]
            ys += [p[1] - 0.15, p[1] + 0.15]
        for s in sc.surfaces:
            xs += [s.center[0] - s.size[0] / 2 - 0.05, s.center[0] + s.size[0] / 2 + 0.05]
            ys += [s.center[1] - s.size[1] / 2 - 0.05, s.center[1] + s.size[1] / 2 + 0.05]
        x0, x1, y0, y1 = min(xs), max(xs), min(ys), max(ys)
        # people stand beside the table, not in it: pull the nearest edge back where the robots
        # allow it
        bx = [r.base[0] for r in sc.robots]
        by = [r.base[1] for r in sc.robots]
        for h in sc.humans:
            hx, hy = h.position[0], h.position[1]
            if not (x0 - 0.25 < hx < x1 + 0.25 and y0 - 0.25 < hy < y1 + 0.25):
                continue
            cuts = [
                (hy - 0.25 - y0 if hy > max(by) + 0.15 else -1.0, "y1", hy - 0.25),
                (y1 - hy - 0.25 if hy < min(by) - 0.15 else -1.0, "y0", hy + 0.25),
                (hx - 0.25 - x0 if hx > max(bx) + 0.15 else -1.0, "x1", hx - 0.25),
                (x1 - hx - 0.25 if hx < min(bx) - 0.15 else -1.0, "x0", hx + 0.25),
            ]
            cuts = [c for c in cuts if c[0] > 0.1]
            if not cuts:
                continue
            _, side, v = max(cuts)
            if side == "y1":
                y1 = min(y1, max(v, max(by) + 0.15))
            elif side == "y0":
                y0 = max(y0, min(v, min(by) - 0.15))
            elif side == "x1":
                x1 = min(x1, max(v, max(bx) + 0.15))
            else:
                x0 = max(x0, min(v, min(bx) - 0.15))
        body = self.spec.worldbody.add_body(name="table", pos=[(x0 + x1) / 2, (y0 + y1) / 2, 0.0])
        hx, hy = (x1 - x0) / 2, (y1 - y0) / 2
        wood = [0.72, 0.58, 0.42, 1.0]
        self.geom(
            body, type=mj.mjtGeom.mjGEOM_BOX, size=[hx, hy, 0.02], pos=[0, 0, -0.02], rgba=wood
        )
        leg = TABLE_HEIGHT - 0.04
        for sx in (-1, 1):
            for sy in (-1, 1):
                self.geom(
                    body,
                    type=mj.mjtGeom.mjGEOM_BOX,
                    size=[0.03, 0.03, leg / 2],
                    pos=[sx * (hx - 0.05), sy * (hy - 0.05), -0.04 - leg / 2],
                    rgba=[0.45, 0.35, 0.25, 1.0],
                )

    def surface(self, sid: str, center: Sequence[float], size: Sequence[float]) -> None:
        mj = self.mj
        body = self.spec.worldbody.add_body(name=f"surface:{sid}", pos=list(center))
        top = float(center[2])
        thick = max(top, 0.0) + 0.01  # a mat on the table, or a block up to a raised top
        self.geom(
            body,
            type=mj.mjtGeom.mjGEOM_BOX,
            size=[size[0] / 2, size[1] / 2, thick / 2],
            pos=[0, 0, 0.002 - thick / 2],
            rgba=[0.35, 0.55, 0.70, 1.0],
        )

    def object(self, obj: SceneObject) -> None:
        mj = self.mj
        radius, height, rgba = object_look(obj)
        body = self.spec.worldbody.add_body(name=f"object:{obj.id}", pos=list(obj.position))
        body.mocap = True
        # the body is the grasp point; the cylinder stands on whatever is under it at the start,
        # even when the point is above its top (a 4 cm book held at 5 cm used to float 1 cm up)
        below = max(obj.position[2] - self._support_z(obj.position[0], obj.position[1]), 0.0)
        self.geom(
            body,
            type=mj.mjtGeom.mjGEOM_CYLINDER,
            size=[radius, height / 2, 0],
            pos=[0, 0, height / 2 - below],
            rgba=list(rgba),
        )

    # -- robots -----------------------------------------------------------------------------

    def robot(self, robot: Robot) -> None:
        kind = robot_kind(robot)
        root = self.spec.worldbody.add_body(name=f"robot:{robot.id}", pos=list(robot.base))
        if kind in ("ur5", "panda"):
            self._robosuite_arm(root, robot, kind)
        elif kind == "elfin3":
            self._elfin3(root, robot)
        else:
            self._primitive(root, robot)
        if robot.base[2] > 0.01:  # a riser from the table up to a raised base
            self.geom(
                root,
                type=self.mj.mjtGeom.mjGEOM_CYLINDER,
                size=[0.09, robot.base[2] / 2, 0],
                pos=[0, 0, -robot.base[2] / 2],
                rgba=[0.3, 0.3, 0.32, 1.0],
            )

    def _robosuite_arm(self, root: Any, robot: Robot, kind: str) -> None:
        mj = self.mj
        assets = _robosuite_assets()
        folder = "ur5e" if kind == "ur5" else "panda"
        arm = mj.MjSpec.from_file(str(assets / "robots" / folder / "robot.xml"))
        gripper = mj.MjSpec.from_file(str(assets / "grippers" / "panda_gripper.xml"))
        for sp in (arm, gripper):
            for a in list(sp.actuators):
                sp.delete(a)
            for sn in list(sp.sensors):
                sp.delete(sn)
        hand = arm.body("right_hand")
        if kind == "ur5":
            # the motion layer plans for the UR5 (example-robot-data's URDF): same joint frames
            # as robosuite's UR5e, other lengths; the UR5e meshes are drawn on the UR5's chain
            for body, pos in _UR5_CHAIN:
                arm.body(body).pos = list(pos)
        tcp = _hand_length(kind)
        # the Panda gripper's fingertips end ~0.11 m from its mount: a coupling fills the rest
        mount = max(0.0, tcp - 0.11)
        if mount > 0:
            cg = hand.add_geom(
                type=mj.mjtGeom.mjGEOM_CYLINDER,
                size=[0.032, mount / 2, 0],
                pos=[0, 0, mount / 2],
                rgba=[0.2, 0.2, 0.22, 1.0],
            )
            cg.group = 2
        hand.add_frame(pos=[0, 0, mount]).attach_body(gripper.body("right_gripper"), "g/", "")
        hand.add_site(name="tcp", pos=[0, 0, tcp], size=[0.005, 0, 0], group=5)
        base = arm.body("base")
        root.add_frame().attach_body(base, f"robot:{robot.id}/", "")
        self.spec.site(f"robot:{robot.id}/tcp").name = f"robot:{robot.id}/hand"
        # tidy what robosuite's files bring: cameras, sites drawn as long lines
        for cam in list(self.spec.cameras):
            if cam.name.startswith(f"robot:{robot.id}/"):
                self.spec.delete(cam)
        for site in list(self.spec.sites):
            if site.name.startswith(f"robot:{robot.id}/") and site.name != f"robot:{robot.id}/hand":
                site.group = 5
        for b in self._bodies_under(root):
            for g in b.geoms:
                if g.group == 1 or (g.contype == 0 and g.conaffinity == 0):
                    g.contype, g.conaffinity = 0, 0
                    g.group = 1
                else:
                    g.contype, g.conaffinity = 1, 0
                    g.group = 0

    def _bodies_under(self, body: Any) -> list[Any]:
        out = [body]
        for child in body.bodies:
            out += self._bodies_under(child)
        return out

    def _link(
        self, body: Any, a: Sequence[float], b: Sequence[float], r: float, rgba: Sequence[float]
    ) -> None:
        """A capsule link between two points of ``body`` (robot collision geometry)."""
        mj = self.mj
        if math.dist(a, b) < 1e-6:
            self.geom(
                body,
                type=mj.mjtGeom.mjGEOM_SPHERE,
                size=[r, 0, 0],
                pos=list(a),
                rgba=list(rgba),
                collide=1,
            )
            return
        self.geom(
            body,
            type=mj.mjtGeom.mjGEOM_CAPSULE,
            fromto=[*a, *b],
            size=[r, 0, 0],
            rgba=list(rgba),
            collide=1,
        )

    def _simple_gripper(self, body: Any, robot_id: str, length: float) -> None:
        """Two fingers along the body's z axis; the hand site is between the fingertips."""
        mj = self.mj
        dark = [0.15, 0.15, 0.17, 1.0]
        self.geom(
            body,
            type=mj.mjtGeom.mjGEOM_BOX,
            size=[0.025, 0.045, 0.015],
            pos=[0, 0, 0.015],
            rgba=dark,
            collide=1,
        )
        for side in (-1, 1):
            self.geom(
                body,
                type=mj.mjtGeom.mjGEOM_BOX,
                size=[0.012, 0.006, (length - 0.03) / 2],
                pos=[0, side * 0.035, 0.03 + (length - 0.03) / 2],
                rgba=dark,
                collide=1,
            )
        body.add_site(
            name=f"robot:{robot_id}/hand", pos=[0, 0, length - 0.015], size=[0.005, 0, 0], group=5
        )

    def _elfin3(self, root: Any, robot: Robot) -> None:
        """hltl's Elfin-3: the motion layer's URDF itself (one kinematic model), its collision
        cylinders coloured, the tool frame ``tool0`` as the hand site, fingers on the hand."""
        mj = self.mj
        arm = mj.MjSpec.from_file(str(ELFIN3_URDF))
        white = [0.92, 0.92, 0.90, 1.0]
        blue = [0.15, 0.35, 0.65, 1.0]
        for i, b in enumerate(self._bodies_under(arm.worldbody)):
            for g in b.geoms:
                g.rgba = blue if i % 2 else white
                g.group = 2
                g.contype, g.conaffinity = 1, 0
        link6 = arm.body("link6")
        tool = _urdf_fixed_offset(ELFIN3_URDF, "link6", "tool0")
        for side in (-1, 1):
            finger = link6.add_geom(
                type=mj.mjtGeom.mjGEOM_BOX,
                size=[0.012, 0.006, 0.03],
                pos=[0, side * 0.03, tool - 0.02],
                rgba=[0.15, 0.15, 0.17, 1.0],
            )
            finger.group = 2
            finger.contype, finger.conaffinity = 1, 0
        link6.add_site(name="tool0", pos=[0, 0, tool], size=[0.005, 0, 0], group=5)
        frame = root.add_frame()
        for child in list(arm.worldbody.bodies):
            frame.attach_body(child, f"robot:{robot.id}/", "")
        self.spec.site(f"robot:{robot.id}/tool0").name = f"robot:{robot.id}/hand"
        for g in arm.worldbody.geoms:  # the base link's own geoms (fused into the world)
            ng = root.add_geom(type=g.type, size=list(g.size), pos=list(g.pos), quat=list(g.quat))
            ng.rgba, ng.group, ng.contype, ng.conaffinity = white, 2, 1, 0

    def _primitive(self, root: Any, robot: Robot) -> None:
        """A four-joint arm (yaw, three pitches) sized so that its hand reaches ``reach``."""
        p = f"robot:{robot.id}/"
        shoulder = 0.15
        hand = 0.1
        link = max(0.1, (robot.reach - hand) / 2)
        grey = [0.55, 0.57, 0.60, 1.0]
        orange = [0.90, 0.45, 0.10, 1.0]
        self._link(root, [0, 0, 0], [0, 0, shoulder - 0.05], 0.06, grey)
        yaw = root.add_body(name=f"{p}link1", pos=[0, 0, shoulder])
        self.hinge(yaw, f"{p}joint1", [0, 0, 1], [-3.14, 3.14], 1.0)
        self._link(yaw, [0, 0, -0.05], [0, 0, 0], 0.055, orange)
        body = yaw
        for i, (length, r) in enumerate(((link, 0.045), (link, 0.04)), start=2):
            body = body.add_body(name=f"{p}link{i}", pos=[0, 0, 0] if i == 2 else [0, 0, link])
            self.hinge(body, f"{p}joint{i}", [0, 1, 0], [-2.6, 2.6], 1.0)
            self._link(body, [0, 0, 0], [0, 0, length], r, grey if i == 2 else orange)
        wrist = body.add_body(name=f"{p}link4", pos=[0, 0, link])
        self.hinge(wrist, f"{p}joint4", [0, 1, 0], [-2.6, 2.6], 0.5)
        self._simple_gripper(wrist, robot.id, hand)

    # -- people -----------------------------------------------------------------------------

    def human(self, hid: str, index: int) -> None:
        """A capsule figure 1.75 m tall facing its local +x, feet on the floor."""
        mj = self.mj
        skin = list(_SKIN[index % len(_SKIN)])
        shirt = list(_SHIRTS[index % len(_SHIRTS)])
        trousers = list(_TROUSERS[index % len(_TROUSERS)])
        hair = [0.12, 0.08, 0.05, 1.0]
        shoe = [0.10, 0.10, 0.10, 1.0]
        h = self.scene.human(hid)
        p = f"human:{hid}/"
        root = self.spec.worldbody.add_body(
            name=f"human:{hid}", pos=[h.position[0], h.position[1], -TABLE_HEIGHT]
        )
        root.mocap = True

        def g(body: Any, **kw: Any) -> None:
            self.geom(body, collide=2, **kw)

        cap = mj.mjtGeom.mjGEOM_CAPSULE
        sph = mj.mjtGeom.mjGEOM_SPHERE
        box = mj.mjtGeom.mjGEOM_BOX
        g(root, type=cap, fromto=[0, -0.09, 0.93, 0, 0.09, 0.93], size=[0.10, 0, 0], rgba=trousers)
        g(root, type=cap, fromto=[0, 0, 1.02, 0, 0, 1.33], size=[0.15, 0, 0], rgba=shirt)
        g(root, type=cap, fromto=[0, -0.15, 1.40, 0, 0.15, 1.40], size=[0.07, 0, 0], rgba=shirt)
        g(root, type=cap, fromto=[0, 0, 1.45, 0, 0, 1.53], size=[0.05, 0, 0], rgba=skin)
        g(root, type=sph, size=[0.105, 0, 0], pos=[0, 0, 1.63], rgba=skin)
        g(root, type=sph, size=[0.1, 0, 0], pos=[-0.03, 0, 1.665], rgba=hair)
        g(root, type=sph, size=[0.02, 0, 0], pos=[0.10, 0, 1.62], rgba=skin)  # nose
        for side, sy in (("r", -1.0), ("l", 1.0)):
            upper = root.add_body(name=f"{p}{side}_upper_arm", pos=[0, sy * 0.21, 1.41])
            self.hinge(upper, f"{p}{side}_shoulder", [0, -1, 0], [-1.0, 2.8], 2.0)
            g(upper, type=cap, fromto=[0, 0, 0, 0, 0, -0.27], size=[0.05, 0, 0], rgba=shirt)
            lower = upper.add_body(name=f"{p}{side}_forearm", pos=[0, 0, -0.29])
            self.hinge(lower, f"{p}{side}_elbow", [0, -1, 0], [0.0, 2.6], 1.0)
            g(lower, type=cap, fromto=[0, 0, 0, 0, 0, -0.23], size=[0.04, 0, 0], rgba=skin)
            g(lower, type=sph, size=[0.05, 0, 0], pos=[0, 0, -0.29], rgba=skin)
            if side == "r":
                lower.add_site(name=f"{p}hand", pos=[0, 0, -0.29], size=[0.01, 0, 0], group=5)
            thigh = root.add_body(name=f"{p}{side}_thigh", pos=[0, sy * 0.095, 0.90])
            self.hinge(thigh, f"{p}{side}_hip", [0, -1, 0], [-1.0, 1.5], 5.0)
            g(thigh, type=cap, fromto=[0, 0, 0, 0, 0, -0.42], size=[0.07, 0, 0], rgba=trousers)
            shin = thigh.add_body(name=f"{p}{side}_shin", pos=[0, 0, -0.43])
            self.hinge(shin, f"{p}{side}_knee", [0, 1, 0], [0.0, 2.4], 3.0)
            g(shin, type=cap, fromto=[0, 0, 0, 0, 0, -0.38], size=[0.055, 0, 0], rgba=trousers)
            g(shin, type=box, size=[0.12, 0.05, 0.035], pos=[0.05, 0, -0.435], rgba=shoe)


def _urdf_fixed_offset(urdf: Path, parent: str, child: str) -> float:
    """Distance along z from ``parent`` to ``child`` through fixed joints with no rotation."""
    import xml.etree.ElementTree as ET

    joints: dict[str, tuple[str, Any]] = {}
    for j in ET.parse(urdf).getroot().iter("joint"):
        pj, cj, org = j.find("parent"), j.find("child"), j.find("origin")
        if pj is not None and cj is not None:
            joints[cj.get("link", "")] = (pj.get("link", ""), org)
    z, link = 0.0, child
    while link != parent:
        if link not in joints:
            raise SceneError(f"{urdf}: no fixed chain from {parent!r} to {child!r}")
        link, org = joints[link]
        xyz = [float(v) for v in (org.get("xyz", "0 0 0") if org is not None else "0 0 0").split()]
        rpy = [float(v) for v in (org.get("rpy", "0 0 0") if org is not None else "0 0 0").split()]
        if any(abs(v) > 1e-9 for v in xyz[:2] + rpy):
            raise SceneError(f"{urdf}: the hand chain {parent!r}→{child!r} is not straight along z")
        z += xyz[2]
    return z


# -- compiling, caching --------------------------------------------------------------------------


def build_spec(scene: Scene) -> Any:
    """The scene as an (uncompiled) ``MjSpec``."""
    return _Builder(scene).build()


def cache_key(scene: Scene) -> str:
    mj = mujoco()
    payload = json.dumps(
        {
            "v": BUILDER_VERSION,
            # the builder's own source: editing it invalidates cached models
            "code": hashlib.sha256(Path(__file__).read_bytes()).hexdigest(),
            "mujoco": mj.__version__,
            "scene": scene.to_dict(),
        },
        sort_keys=True,
    )
    return hashlib.sha256(payload.encode()).hexdigest()[:24]


def default_cache_dir() -> Path:
    env = os.environ.get("HLTL_CACHE_DIR")
    base = (
        Path(env)
        if env
        else Path(os.environ.get("XDG_CACHE_HOME", Path.home() / ".cache")) / "hltl"
    )
    return base / "sim3d"


def compile_scene(scene: Scene, *, cache: bool | Path = True) -> SceneModel:
    """Build and compile the scene's model, or load it from the compiled-model cache.

    Args:
        cache: True for the default folder (``$HLTL_CACHE_DIR/sim3d`` or ``~/.cache/hltl/sim3d``),
            a folder, or False to always compile.
    """
    mj = mujoco()
    path: Path | None = None
    if cache is not False:
        folder = default_cache_dir() if cache is True else Path(cache)
        path = folder / f"{cache_key(scene)}.mjb"
        if path.exists():
            try:
                return SceneModel(scene, mj.MjModel.from_binary_path(str(path)))
            except (ValueError, SceneError):
                pass  # unreadable or stale: rebuild below
    try:
        model = build_spec(scene).compile()
    except ValueError as exc:
        raise SceneError(f"{scene.source}: cannot build the 3D model: {exc}") from None
    if path is not None:
        try:
            path.parent.mkdir(parents=True, exist_ok=True)
            tmp = path.with_suffix(f".{os.getpid()}.tmp")
            mj.mj_saveModel(model, str(tmp), None)
            tmp.replace(path)
        except OSError:
            pass  # a read-only cache only costs the compile time
    return SceneModel(scene, model)
