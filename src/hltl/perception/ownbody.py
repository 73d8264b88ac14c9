"""The robots' own bodies in a frame: their link capsules placed by the frame's joint state."""

# A learned segmenter takes a gripper's fingers or a link's end for a box now and then. The arm's
# joint positions are known to the robot itself (the 3D simulator's frames carry them; a recording
# may carry them per frame in camera.json), so forward kinematics of the motion model's link
# geometry (hltl.motion.kinematics.LinkGeometry, the capsules motion planning checks) says where
# the arm is, and a region lying mostly inside those capsules is the arm, not an object.

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np
import numpy.typing as npt

from hltl.errors import PerceptionError
from hltl.world.scene import Scene

F64 = npt.NDArray[np.float64]

# m beyond a capsule's radius that still counts as the arm: the capsules are rounded stand-ins
# for the meshes, and the hand's capsule ends at the palm, short of the fingers
OWN_MARGIN = 0.03
# a region with at least this share of its points on the arm is the arm
OWN_SHARE = 0.5


class OwnBodies:
    """The scene's arms with a motion model (UR5, Panda, Elfin-3); arms drawn without one (the
    simulator's primitive arm) have no link geometry here and are never masked.

    Args:
        scene: the robots (id, model, base).
        margin: metres beyond each capsule's radius counted as the arm.
    """

    def __init__(self, scene: Scene | None, margin: float = OWN_MARGIN) -> None:
        self.scene = scene
        self.margin = margin
        self._geometry: dict[str, Any] = {}

    def _link_geometry(self, rid: str) -> Any:
        # why: the motion layer needs Pinocchio (extra motion); frames without joints never do
        from hltl.motion.kinematics import LinkGeometry
        from hltl.motion.robots import has_model  # why: as above

        if rid not in self._geometry:
            assert self.scene is not None
            robot = next((r for r in self.scene.robots if r.id == rid), None)
            ok = robot is not None and has_model(robot.model)
            self._geometry[rid] = LinkGeometry(robot.model, robot.base) if ok and robot else None
        return self._geometry[rid]

    def capsules(
        self, joints: Mapping[str, Sequence[float]] | None
    ) -> list[tuple[F64, F64, float]]:
        """(a, b, radius + margin) of every link of every arm ``joints`` poses (robot id →
        joint positions); robots the scene does not have, or without a motion model, are left
        out.

        Raises:
            PerceptionError: a robot's joint count is not its model's.
        """
        if not joints or self.scene is None:
            return []
        out: list[tuple[F64, F64, float]] = []
        for rid, q in sorted(joints.items()):
            geo = self._link_geometry(rid)
            if geo is None:
                continue
            if len(q) != geo.nq:
                raise PerceptionError(
                    f"frame joints: robot {rid} ({geo.spec.name}) has {geo.nq} joints, "
                    f"got {len(q)} values"
                )
            for c in geo.capsules(q):
                out.append((np.asarray(c.a), np.asarray(c.b), c.radius + self.margin))
        return out

    @staticmethod
    def share(points: F64, capsules: Sequence[tuple[F64, F64, float]]) -> float:
        """The share of ``points`` (n, 3) inside any of ``capsules`` (0 when there are none)."""
        if len(points) == 0 or not capsules:
            return 0.0
        from hltl.motion.collision import segment_distances  # why: motion loads only to mask arms

        a = np.array([c[0] for c in capsules], dtype=float)
        b = np.array([c[1] for c in capsules], dtype=float)
        r = np.array([c[2] for c in capsules], dtype=float)
        # each point a zero-length segment: its distance to every capsule's axis at once
        inside = (segment_distances(points, points, a, b) <= r[None, :]).any(axis=1)
        return float(inside.mean())
