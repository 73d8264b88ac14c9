"""Robot model registry: which arm a scene's ``model`` names, its URDF, tool frame and limits."""

from __future__ import annotations

import functools
import hashlib
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

from hltl.errors import BackendUnavailableError, SceneError

if TYPE_CHECKING:  # pragma: no cover - typing only
    import pinocchio

MODELS_DIR = Path(__file__).resolve().parent / "models"
ELFIN3_URDF = MODELS_DIR / "elfin3.urdf"
XARM6_URDF = MODELS_DIR / "xarm6.urdf"
# the arms whose URDF hltl writes itself from published kinematics (the rest: example-robot-data)
OWN_URDFS = {"elfin3": ELFIN3_URDF, "xarm6": XARM6_URDF}

# Bumped whenever what a model means changes (tool offsets, capsule sizes): it feeds the model
# hash that keys the reachability maps cached on disk.
MODEL_FORMAT_VERSION = 3  # 2: the table test uses link capsules; 3: self-collision


@dataclass(frozen=True, slots=True)
class ArmSpec:
    """One arm of the registry.

    Attributes:
        name: the scene's ``model`` value.
        source: where the kinematics come from.
        tool_frame: the hand's tool frame (the point that grasps), ``tool0`` for hltl's Elfin-3.
        hand_length: metres from the flange to the tool frame (the hand the paper's arms carry).
        link_radius: radius of the collision capsules hltl puts around the links (metres).
        hand_radius: radius of the capsule around the hand.
        max_acceleration: joint acceleration limit (rad/s²) for time parametrisation; URDFs
            carry velocity limits only.
        nominal_reach: the reach (m, from the base) the vendor quotes with a hand.
        hand_bodies: the collision bodies of the hand (hltl.motion.selfcollision names); the
            rest pose keeps them clear of the other links.
    """

    name: str
    source: str
    tool_frame: str
    hand_length: float
    link_radius: float
    hand_radius: float
    max_acceleration: float
    nominal_reach: float
    hand_bodies: tuple[str, ...] = ()


ARMS: tuple[ArmSpec, ...] = (
    ArmSpec(
        name="elfin3",
        source="hltl's URDF from the published Elfin-3 kinematics (hans-robot/elfin_robot)",
        tool_frame="tool0",
        hand_length=0.10,
        link_radius=0.05,
        hand_radius=0.045,
        max_acceleration=3.0,
        nominal_reach=0.7,
        hand_bodies=("hand_0",),
    ),
    ArmSpec(
        name="xarm6",
        source="hltl's URDF from UFACTORY's published xArm6 kinematics (xArm-Developer/xarm_ros)",
        tool_frame="tool0",
        hand_length=0.10,
        link_radius=0.045,
        hand_radius=0.045,
        max_acceleration=3.0,
        nominal_reach=0.7,
        hand_bodies=("hand_0",),
    ),
    ArmSpec(
        name="ur5",
        source="example-robot-data ur5_robot.urdf; hltl adds a 0.15 m hand beyond tool0",
        tool_frame="hand_tcp",
        hand_length=0.15,
        link_radius=0.055,
        hand_radius=0.045,
        max_acceleration=3.0,
        nominal_reach=0.9,
        hand_bodies=("hltl_hand_0",),
    ),
    ArmSpec(
        name="panda",
        source="example-robot-data panda.urdf, fingers locked open; Franka hand, panda_hand_tcp",
        tool_frame="panda_hand_tcp",
        hand_length=0.1034,
        link_radius=0.055,
        hand_radius=0.05,
        max_acceleration=3.0,
        nominal_reach=0.855,
        hand_bodies=(
            "panda_hand_0",
            *(f"panda_{side}finger_{k}" for side in ("left", "right") for k in range(4)),
        ),
    ),
)

MODEL_NAMES: tuple[str, ...] = tuple(a.name for a in ARMS)


def has_model(name: str) -> bool:
    """True when ``name`` is an arm hltl has kinematics for (otherwise the robot is a sphere)."""
    return name in MODEL_NAMES


def arm_spec(name: str) -> ArmSpec:
    """The registry entry of ``name``.

    Raises:
        SceneError: for a name the registry does not know.
    """
    for a in ARMS:
        if a.name == name:
            return a
    raise SceneError(f"unknown robot model {name!r}; expected one of {', '.join(MODEL_NAMES)}")


def _require_pinocchio() -> Any:
    try:
        import pinocchio
    except ImportError:
        raise BackendUnavailableError(
            "robot kinematics need Pinocchio: install the 'motion' extra "
            "(pip install 'hltl[motion]')"
        ) from None
    return pinocchio


def urdf_path(name: str) -> Path:
    """The URDF file of a registered arm (hltl's own for the Elfin-3 and the xArm6,
    example-robot-data's else)."""
    arm_spec(name)
    if name in OWN_URDFS:
        return OWN_URDFS[name]
    try:
        import example_robot_data as erd
    except ImportError:
        raise BackendUnavailableError(
            f"model {name!r} comes from example-robot-data: install the 'motion' extra"
        ) from None
    return Path(erd.load(name).urdf)


def model_hash(name: str) -> str:
    """A digest of everything the model's kinematics depend on (URDF text and hltl's additions)."""
    spec = arm_spec(name)
    h = hashlib.sha256()
    h.update(urdf_path(name).read_bytes())
    h.update(repr((spec, MODEL_FORMAT_VERSION)).encode())
    return h.hexdigest()[:16]


@functools.cache
def load_model(name: str) -> pinocchio.Model:
    """The Pinocchio model of a registered arm, base at the origin, with its tool frame.

    Loaded once per process (models are immutable once built; each caller makes its own data).
    """
    pin = _require_pinocchio()
    spec = arm_spec(name)
    if name in OWN_URDFS:
        return pin.buildModelFromUrdf(str(OWN_URDFS[name]))
    import example_robot_data as erd

    model = erd.load(name).model
    if name == "panda":
        # The two finger joints are not part of the arm's kinematics: lock them open.
        locked = [model.getJointId(n) for n in ("panda_finger_joint1", "panda_finger_joint2")]
        q_ref = pin.neutral(model)
        q_ref[-2:] = 0.04
        model = pin.buildReducedModel(model, locked, q_ref)
    if name == "ur5":
        flange = model.getFrameId("tool0")
        f = model.frames[flange]
        tcp = pin.SE3(f.placement.rotation, f.placement.translation)
        tcp = tcp * pin.SE3(pin.SE3.Identity().rotation, _z(spec.hand_length))
        model.addFrame(
            pin.Frame(spec.tool_frame, f.parentJoint, flange, tcp, pin.FrameType.OP_FRAME)
        )
    return model


def _z(length: float) -> Any:
    import numpy as np

    return np.array([0.0, 0.0, length])
