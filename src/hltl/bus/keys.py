"""Key expressions of a cell on the bus (docs/bus.md lists them with their payloads)."""

from __future__ import annotations

import re
from dataclasses import dataclass

from hltl.errors import BusError

PREFIX = "hltl"
_NAME = re.compile(r"[A-Za-z0-9_\-]+")


def check_name(kind: str, name: str) -> str:
    """``name`` if it can be one chunk of a key expression (no ``/``, ``*``, ``$``, spaces)."""
    if not _NAME.fullmatch(name):
        raise BusError(
            f"{kind} name {name[:60]!r} cannot be used in a key expression; "
            "expected letters, digits, '_' or '-'"
        )
    return name


@dataclass(frozen=True, slots=True)
class Keys:
    """Every key expression of one cell: ``hltl/<cell>/…``."""

    cell: str

    def __post_init__(self) -> None:
        check_name("cell", self.cell)

    @property
    def root(self) -> str:
        return f"{PREFIX}/{self.cell}"

    def robot(self, robot: str) -> str:
        return f"{self.root}/robots/{check_name('robot', robot)}"

    # executor → robot
    def action(self, robot: str) -> str:
        """Start/halt commands (JSON :class:`~hltl.bus.codec.Command`)."""
        return f"{self.robot(robot)}/action"

    def trajectory(self, robot: str) -> str:
        """A started action's joint trajectory (CDR ``trajectory_msgs/msg/JointTrajectory``)."""
        return f"{self.robot(robot)}/trajectory"

    # robot → executor
    def status(self, robot: str) -> str:
        """Action reports: acknowledgements, progress, completions, failures (JSON)."""
        return f"{self.robot(robot)}/status"

    def state(self, robot: str) -> str:
        """Queryable: the robot's latest report for each action it is in (JSON)."""
        return f"{self.robot(robot)}/state"

    def alive(self, robot: str) -> str:
        """Liveliness token held while the robot's node runs."""
        return f"{self.robot(robot)}/alive"

    def joint_states(self, robot: str) -> str:
        """CDR ``sensor_msgs/msg/JointState`` (published by cells that have joints)."""
        return f"{self.robot(robot)}/joint_states"

    def tool_pose(self, robot: str) -> str:
        """CDR ``geometry_msgs/msg/PoseStamped`` of the hand, scene frame."""
        return f"{self.robot(robot)}/tool_pose"

    @property
    def all_status(self) -> str:
        return f"{self.root}/robots/*/status"

    @property
    def all_actions(self) -> str:
        return f"{self.root}/robots/*/action"

    @property
    def all_trajectories(self) -> str:
        return f"{self.root}/robots/*/trajectory"

    @property
    def all_states(self) -> str:
        return f"{self.root}/robots/*/state"

    @property
    def all_alive(self) -> str:
        return f"{self.root}/robots/*/alive"

    # perception and people
    @property
    def observation(self) -> str:
        """The perceived world state (JSON)."""
        return f"{self.root}/observation"

    @property
    def perception(self) -> str:
        """What a perception node sees in each camera frame (JSON, ``hltl.bus.perception``)."""
        return f"{self.root}/perception"

    def human_pose(self, human: str) -> str:
        """CDR ``geometry_msgs/msg/PoseStamped`` of a person, scene frame."""
        return f"{self.root}/humans/{check_name('human', human)}/pose"

    # executor's own records
    @property
    def plan(self) -> str:
        """Each replan's result (JSON, the ``replan`` log record)."""
        return f"{self.root}/plan"

    @property
    def log(self) -> str:
        """Every execution log record (JSON)."""
        return f"{self.root}/log"

    # simulated clock (simulator nodes only)
    @property
    def sim_reset(self) -> str:
        """Queryable: start an episode (scene check, events, seed, perception model)."""
        return f"{self.root}/sim/reset"

    @property
    def sim_step(self) -> str:
        """Queryable: advance simulated time to ``t`` and return what happened."""
        return f"{self.root}/sim/step"

    @property
    def sim_tick(self) -> str:
        """A real-time cell's clock, published every tick of its own: time, world, what
        happened (JSON, numbered; see :mod:`hltl.bus.realtime`)."""
        return f"{self.root}/sim/tick"

    @property
    def sim_clock(self) -> str:
        """Queryable on a real-time cell: its latest tick and what was missed since given
        counts of log records and instructions (JSON)."""
        return f"{self.root}/sim/clock"


def robot_of(key: str) -> str:
    """The robot id in ``hltl/<cell>/robots/<robot>/…``."""
    parts = key.split("/")
    if len(parts) < 4 or parts[2] != "robots":
        raise BusError(f"key expression {key[:80]!r} names no robot")
    return parts[3]
