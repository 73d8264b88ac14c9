"""Where hands go and what they reach: the Reachability/Kinematics seam of the skill library."""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from typing import Protocol, runtime_checkable

from hltl.world import geometry
from hltl.world.geometry import Context
from hltl.world.scene import Robot, Scene, Vec3


@runtime_checkable
class Reachability(Protocol):
    """Which points a robot's hand reaches and which robots can hand over to each other."""

    def reaches(self, robot: Robot, point: Vec3) -> bool:
        """True when the robot's hand can grasp or release at ``point``."""
        ...

    def can_meet(self, giver: Robot, receiver: Robot) -> bool:
        """True when the two robots can exchange an object hand to hand."""
        ...


@runtime_checkable
class Kinematics(Reachability, Protocol):
    """Reachability plus the poses an instance uses (metres, scene frame)."""

    @property
    def name(self) -> str:
        """What a log calls these kinematics (``episode_start.kinematics``, so that the log
        checker judges with the same reach): ``spheres`` or ``maps``."""
        ...

    def rendezvous_point(self, giver: Robot, receiver: Robot) -> Vec3:
        """Where the two hands meet for a robot-to-robot handover."""
        ...

    def human_handover_point(self, robot: Robot, human_position: Vec3) -> Vec3:
        """Where the hand offers an object to a person standing at ``human_position``."""
        ...

    def home_point(self, robot: Robot) -> Vec3:
        """The hand's rest pose."""
        ...

    def context_label(
        self, scene: Scene, humans: Mapping[str, Vec3] | Iterable[tuple[str, Vec3]]
    ) -> Context:
        """ℓ(w): which robots' workspaces hold each person standing where ``humans`` says."""
        ...


@dataclass(frozen=True, slots=True)
class ReachSpheres:
    """The paper's geometry: each arm reaches a sphere around its base (world/geometry.py)."""

    @property
    def name(self) -> str:
        return "spheres"

    def reaches(self, robot: Robot, point: Vec3) -> bool:
        return geometry.reaches(robot, point)

    def can_meet(self, giver: Robot, receiver: Robot) -> bool:
        return geometry.can_meet(giver, receiver)

    def rendezvous_point(self, giver: Robot, receiver: Robot) -> Vec3:
        return geometry.rendezvous_point(giver, receiver)

    def human_handover_point(self, robot: Robot, human_position: Vec3) -> Vec3:
        return geometry.human_handover_point(robot, human_position)

    def home_point(self, robot: Robot) -> Vec3:
        return geometry.home_point(robot)

    def context_label(
        self, scene: Scene, humans: Mapping[str, Vec3] | Iterable[tuple[str, Vec3]]
    ) -> Context:
        return geometry.context_label(scene, humans)


REACH_SPHERES: Kinematics = ReachSpheres()
