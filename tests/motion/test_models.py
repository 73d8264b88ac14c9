"""Robot models: hltl's Elfin-3 and xArm6 against their published kinematics, the registry,
tool frames."""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET
from pathlib import Path
from typing import Any

import numpy as np
import pytest

pytest.importorskip("pinocchio")

from hltl.errors import SceneError
from hltl.motion.kinematics import Arm
from hltl.motion.robots import (
    ELFIN3_URDF,
    MODEL_NAMES,
    XARM6_URDF,
    arm_spec,
    has_model,
    model_hash,
)

# The published chain (/work/shared/robots/elfin3.md), typed in again here as the oracle:
# (origin xyz, origin rpy, lower, upper, max velocity).
PUBLISHED = [
    ((0, 0, 0.1925), (0, 0, 0), -3.14, 3.14, 1.57),
    ((0, 0, 0), (1.5708, 0, 0), -2.35, 2.35, 1.57),
    ((0, 0.266, 0), (3.1416, 0, 1.5708), -2.61, 2.61, 1.57),
    ((0, 0, 0), (1.5708, 0, 1.5708), -3.14, 3.14, 1.57),
    ((0, 0, 0.324), (-1.5708, 0, 0), -2.56, 2.56, 1.57),
    ((0, 0, 0), (1.5708, 0, 0), -3.14, 3.14, 1.57),
]
FLANGE = 0.1565
HAND = 0.10
# UFACTORY's published xArm6 (xArm-Developer/xarm_ros, xarm_description: xarm6.urdf.xacro with
# its default, unlimited joint ranges, and xarm6_default_kinematics.yaml), typed in again here
# as the oracle; its flange is link6's origin.
TAU = 2 * math.pi
XARM6 = [
    ((0, 0, 0.267), (0, 0, 0), -TAU, TAU, 3.14),
    ((0, 0, 0), (-1.5708, 0, 0), -2.059, 2.0944, 3.14),
    ((0.0535, -0.2845, 0), (0, 0, 0), -3.927, 0.19198, 3.14),
    ((0.0775, 0.3425, 0), (-1.5708, 0, 0), -TAU, TAU, 3.14),
    ((0, 0, 0), (1.5708, 0, 0), -1.69297, math.pi, 3.14),
    ((0.076, 0.097, 0), (-1.5708, 0, 0), -TAU, TAU, 3.14),
]


def _rpy(r: float, p: float, y: float) -> np.ndarray:
    cr, sr, cp, sp, cy, sy = (
        math.cos(r),
        math.sin(r),
        math.cos(p),
        math.sin(p),
        math.cos(y),
        math.sin(y),
    )
    rx = np.array([[1, 0, 0], [0, cr, -sr], [0, sr, cr]])
    ry = np.array([[cp, 0, sp], [0, 1, 0], [-sp, 0, cp]])
    rz = np.array([[cy, -sy, 0], [sy, cy, 0], [0, 0, 1]])
    return rz @ ry @ rx


def _h(rot: np.ndarray, xyz: tuple[float, ...]) -> np.ndarray:
    m = np.eye(4)
    m[:3, :3] = rot
    m[:3, 3] = xyz
    return m


def _published_fk(
    q: np.ndarray, tool: float, chain: list[Any] = PUBLISHED, flange: float = FLANGE
) -> np.ndarray:
    m = np.eye(4)
    for (xyz, rpy, *_), qi in zip(chain, q, strict=True):
        m = m @ _h(_rpy(*rpy), xyz) @ _h(_rpy(0, 0, qi), (0, 0, 0))
    return m @ _h(np.eye(3), (0, 0, flange + tool))


def test_elfin3_zero_pose_is_upright_at_published_height() -> None:
    arm = Arm("r1", "elfin3")
    pos, _ = arm.fk(np.zeros(6))
    # shoulder 0.1925 + upper arm 0.266 + forearm 0.324 + wrist-to-flange 0.1565 + hand 0.10
    assert pos == pytest.approx((0.0, 0.0, 0.1925 + 0.266 + 0.324 + 0.1565 + HAND), abs=1e-4)


@pytest.mark.parametrize("seed", range(6))
@pytest.mark.parametrize(
    ("name", "chain", "flange"), [("elfin3", PUBLISHED, FLANGE), ("xarm6", XARM6, 0.0)]
)
def test_fk_matches_published_chain(name: str, chain: list[Any], flange: float, seed: int) -> None:
    rng = np.random.default_rng(seed)
    arm = Arm("r1", name, (0.5, -0.2, 0.1))
    lo = np.array([p[2] for p in chain])
    hi = np.array([p[3] for p in chain])
    q = rng.uniform(lo, hi)
    expect = _published_fk(q, HAND, chain, flange)
    pos, rot = arm.fk(q)
    assert pos == pytest.approx(expect[:3, 3] + np.array([0.5, -0.2, 0.1]), abs=1e-6)
    assert rot == pytest.approx(expect[:3, :3], abs=1e-6)


@pytest.mark.parametrize(("path", "chain"), [(ELFIN3_URDF, PUBLISHED), (XARM6_URDF, XARM6)])
def test_urdf_chains_and_limits_are_the_published_ones(path: Path, chain: list[Any]) -> None:
    root = ET.parse(path).getroot()
    joints = [j for j in root.iter("joint") if j.get("type") == "revolute"]
    assert [j.get("name") for j in joints] == [f"joint{i}" for i in range(1, 7)]
    for j, (xyz, rpy, lo, hi, vel) in zip(joints, chain, strict=True):
        origin = j.find("origin")
        limit = j.find("limit")
        assert origin is not None and limit is not None
        assert [float(v) for v in origin.get("xyz", "").split()] == pytest.approx(xyz)
        assert [float(v) for v in origin.get("rpy", "").split()] == pytest.approx(rpy)
        assert float(limit.get("lower", "nan")) == pytest.approx(lo, abs=1e-6)
        assert float(limit.get("upper", "nan")) == pytest.approx(hi, abs=1e-6)
        assert float(limit.get("velocity", "nan")) == vel
    # every link that moves carries primitive collision geometry, no meshes
    for link in root.iter("link"):
        for geom in link.iter("geometry"):
            assert geom.find("mesh") is None
    assert any(link.get("name") == "tool0" for link in root.iter("link"))


def test_xarm6_zero_pose_is_ufactorys() -> None:
    # UFACTORY documents the xArm6's zero pose as the flange at (207, 0, 112) mm pointing down
    arm = Arm("r1", "xarm6")
    pos, rot = arm.fk(np.zeros(6))
    assert pos == pytest.approx((0.207, 0.0, 0.112 - HAND), abs=1e-4)
    assert rot[:, 2] == pytest.approx((0.0, 0.0, -1.0), abs=1e-4)


@pytest.mark.parametrize("name", MODEL_NAMES)
def test_registry_models_load_with_tool_frames(name: str) -> None:
    arm = Arm("r", name)
    spec = arm_spec(name)
    assert arm.model.existFrame(spec.tool_frame)
    assert len(arm.joint_names) == arm.nq
    # the home pose puts the hand at handover height above the base
    pos, _ = arm.fk(arm.home)
    assert pos[2] > 0.1
    assert len(model_hash(name)) == 16


def test_unknown_models_keep_the_sphere() -> None:
    assert has_model("elfin3") and has_model("xarm6")
    assert not has_model("kr6")
    with pytest.raises(SceneError, match="unknown robot model 'kr6'"):
        arm_spec("kr6")


def test_elfin3_mjcf_is_the_urdf_model() -> None:
    """hltl's Elfin-3 MJCF (for MuJoCo) has the URDF's joints, limits and masses, and its tool0
    site moves exactly as the URDF's tool frame (Pinocchio) at random configurations."""
    mujoco = pytest.importorskip("mujoco")
    from hltl.motion.robots import MODELS_DIR

    m = mujoco.MjModel.from_xml_path(str(MODELS_DIR / "elfin3.xml"))
    d = mujoco.MjData(m)
    arm = Arm("r", "elfin3")
    names = [m.joint(i).name for i in range(m.njnt)]
    assert names == [f"joint{i}" for i in range(1, 7)]
    assert np.allclose(m.jnt_range[:, 0], arm.lower) and np.allclose(m.jnt_range[:, 1], arm.upper)
    urdf = ET.parse(ELFIN3_URDF).getroot()
    masses = [float(e.get("value", "nan")) for e in urdf.iter("mass")]
    assert m.body_mass.sum() == pytest.approx(sum(masses), abs=1e-9)
    tool = m.site("tool0").id
    rng = np.random.default_rng(0)
    for _ in range(50):
        q = rng.uniform(arm.lower, arm.upper)
        d.qpos[:] = q
        mujoco.mj_kinematics(m, d)
        p, r = arm.fk(q)
        assert np.allclose(d.site_xpos[tool], p, atol=1e-9)
        assert np.allclose(d.site_xmat[tool].reshape(3, 3), r, atol=1e-9)
