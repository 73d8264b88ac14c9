"""Skeletons (shoulders, elbows, wrists in 3D) from MediaPipe pose run in its own process."""

from __future__ import annotations

import json
import math
import os
import subprocess
from dataclasses import dataclass, field
from pathlib import Path
from typing import IO, Any

import numpy as np
import numpy.typing as npt

from hltl.errors import BackendUnavailableError, PerceptionError
from hltl.perception.frames import Camera

Vec3 = tuple[float, float, float]
Box = tuple[float, float, float, float]
# MediaPipe pose landmark indices of the joints the comfort zone uses
JOINTS: dict[str, int] = {
    "l_shoulder": 11,
    "r_shoulder": 12,
    "l_elbow": 13,
    "r_elbow": 14,
    "l_wrist": 15,
    "r_wrist": 16,
}
MIN_VISIBILITY = 0.5
LIMB_RADIUS = 0.045  # m: a joint's visible surface lies this far in front of the joint
PAD = 0.15  # crops grow by this share of the box on each side (arms reach out of the box)


@dataclass(frozen=True, slots=True)
class Skeleton:
    """3D joints of one person (scene frame); a joint is None when not seen well enough."""

    joints: tuple[tuple[str, Vec3 | None], ...]
    pixels: tuple[tuple[str, tuple[float, float] | None], ...]

    def joint(self, name: str) -> Vec3 | None:
        return dict(self.joints)[name]

    @property
    def seen(self) -> int:
        return sum(p is not None for _, p in self.joints)

    def to_dict(self) -> dict[str, list[float] | None]:
        return {k: (None if p is None else [round(v, 4) for v in p]) for k, p in self.joints}


def pose_python() -> Path:
    """The pose environment's Python: ``HLTL_POSE_PYTHON`` or ``.venv-pose`` at the checkout's
    root (beside ``src/``)."""
    env = os.environ.get("HLTL_POSE_PYTHON")
    if env:
        return Path(env)
    return Path(__file__).resolve().parents[3] / ".venv-pose" / "bin" / "python"


def lift(
    depth: npt.NDArray[np.float32],
    camera: Camera,
    uv: tuple[float, float],
    mask: npt.NDArray[np.bool_] | None = None,
    radius: int = 3,
) -> Vec3 | None:
    """The 3D point of pixel ``uv``: the nearest half of the valid depths around it (inside
    ``mask`` when given), pushed back along the view ray by LIMB_RADIUS."""
    h, w = depth.shape
    u, v = round(uv[0]), round(uv[1])
    if not (0 <= u < w and 0 <= v < h):
        return None
    v0, v1, u0, u1 = (
        max(v - radius, 0),
        min(v + radius + 1, h),
        max(u - radius, 0),
        min(u + radius + 1, w),
    )
    win = depth[v0:v1, u0:u1]
    ok = win > 0
    if mask is not None:
        ok &= mask[v0:v1, u0:u1]
    if not ok.any():
        return None
    z = np.sort(win[ok].astype(float))
    d = float(np.median(z[: max(1, (len(z) + 1) // 2)])) + LIMB_RADIUS
    ray = np.array([(uv[0] - camera.cx) / camera.fx, (uv[1] - camera.cy) / camera.fy, 1.0])
    p = camera.pose[:3, :3] @ (ray * d) + camera.pose[:3, 3]
    return (float(p[0]), float(p[1]), float(p[2]))


MIN_SHOULDER_SPAN = 0.25  # m: shoulders lifted closer than this are one shoulder seen twice


def _hide_far_side(sk: Skeleton, camera: Camera) -> Skeleton:
    """Seen from the side, the pose model still places the far arm (behind the body), and its
    pixels' depth is the near side's: when the two shoulders land closer than a body is wide,
    the side farther from the camera is dropped (shoulder, elbow, wrist)."""
    ls, rs = sk.joint("l_shoulder"), sk.joint("r_shoulder")
    if ls is None or rs is None:
        return sk
    if float(np.linalg.norm(np.subtract(ls, rs))) >= MIN_SHOULDER_SPAN:
        return sk
    cam = camera.pose[:3, 3]
    far = (
        "l" if np.linalg.norm(np.subtract(ls, cam)) > np.linalg.norm(np.subtract(rs, cam)) else "r"
    )
    return Skeleton(
        tuple((k, None if k.startswith(far) else p) for k, p in sk.joints),
        tuple((k, None if k.startswith(far) else p) for k, p in sk.pixels),
    )


# m/s: walking at least this fast, the heading tells left from right (a standing track's
# filtered speed stays below it: 0.31 m/s p95 with 3 cm noise)
SIDE_SPEED = 0.5
SIDE_MARGIN = 0.05  # m: a lone joint this far on the wrong side of the body axis is relabelled


# m: how far from the body's vertical axis a joint can be (shoulder half-width; upper arm and
# forearm held out); a lifted joint beyond it took its depth from something else
REACH = {"shoulder": 0.35, "elbow": 0.6, "wrist": 0.85}


def drop_implausible(sk: Skeleton, centre: tuple[float, float]) -> Skeleton:
    """The skeleton without joints farther from the body axis through ``centre`` (the
    tracked floor position) than a body reaches: their pixel's depth was the background's or
    another person's."""
    keep = {
        k: p is not None and math.hypot(p[0] - centre[0], p[1] - centre[1]) <= REACH[k[2:]]
        for k, p in sk.joints
    }
    return Skeleton(
        tuple((k, p if keep[k] else None) for k, p in sk.joints),
        tuple((k, p if keep[k] else None) for k, p in sk.pixels),
    )


def orient_sides(
    sk: Skeleton,
    centre: tuple[float, float],
    velocity: tuple[float, float] | None = None,
    previous: Skeleton | None = None,
) -> Skeleton:
    """Left and right as the body is oriented: MediaPipe confuses them on side and back views.

    Walking (speed ≥ SIDE_SPEED), a person faces where they go, so a left joint lies left of
    the line through ``centre`` along ``velocity``: a pair whose left joint lies right of its
    right joint is swapped, and a lone joint more than SIDE_MARGIN on the wrong side moves to
    the other side's name. Standing, each pair keeps the labelling nearer to ``previous`` (the
    same track's last skeleton). Pairs are shoulders, elbows, wrists, each decided alone."""
    joints = dict(sk.joints)
    pixels = dict(sk.pixels)
    speed = 0.0 if velocity is None else math.hypot(*velocity)
    # unit vector to the walker's left (their heading turned 90° anticlockwise)
    left = (
        (0.0, 0.0)
        if velocity is None or speed == 0.0
        else (-velocity[1] / speed, velocity[0] / speed)
    )

    def side(p: Vec3) -> float:
        return (p[0] - centre[0]) * left[0] + (p[1] - centre[1]) * left[1]

    for part in ("shoulder", "elbow", "wrist"):
        ln, rn = f"l_{part}", f"r_{part}"
        lp, rp = joints.get(ln), joints.get(rn)
        swap = False
        if speed >= SIDE_SPEED:
            if lp is not None and rp is not None:
                swap = side(lp) < side(rp)
            elif lp is not None:
                swap = side(lp) < -SIDE_MARGIN
            elif rp is not None:
                swap = side(rp) > SIDE_MARGIN
        elif previous is not None and lp is not None and rp is not None:
            pl, pr = previous.joint(ln), previous.joint(rn)
            if pl is not None and pr is not None:
                same = math.dist(lp, pl) + math.dist(rp, pr)
                swapped = math.dist(lp, pr) + math.dist(rp, pl)
                swap = swapped < same
        if swap:
            joints[ln], joints[rn] = rp, lp
            pixels[ln], pixels[rn] = pixels.get(rn), pixels.get(ln)
    return Skeleton(
        tuple((k, joints[k]) for k, _ in sk.joints), tuple((k, pixels[k]) for k, _ in sk.pixels)
    )


# m: longest upper arm (shoulder to elbow) and forearm (elbow to wrist) a lifted skeleton may
# have, with room for lifting error (the simulator's: 0.29 and 0.23 m; people: ~0.25-0.33)
BONES = (("shoulder", "elbow", 0.40), ("elbow", "wrist", 0.36))
MAX_SHOULDER_SPAN = 0.55  # m: shoulders farther apart than this are not one body's
# m/s: how fast a joint can move relative to the body's axis (arm swing and reach), and the
# slack (m) a frame's lifting error adds; a faster jump is held back until a second agrees
JOINT_SPEED = {"shoulder": 0.8, "elbow": 2.0, "wrist": 3.0}
JUMP_SLACK = 0.08


def drop_broken_bones(sk: Skeleton, centre: tuple[float, float]) -> Skeleton:
    """The skeleton without joints that would stretch a bone past a human's length: a wrist
    farther than a forearm from its elbow, an elbow farther than an upper arm from its
    shoulder (the outer joint goes: its pixel's depth was the background's or the other
    arm's), and of two shoulders wider apart than a body, the one farther from the body axis
    through ``centre``."""
    joints = dict(sk.joints)
    ls, rs = joints.get("l_shoulder"), joints.get("r_shoulder")
    if ls is not None and rs is not None and math.dist(ls, rs) > MAX_SHOULDER_SPAN:
        far = max(
            ("l", "r"),
            key=lambda k: math.hypot(
                joints[f"{k}_shoulder"][0] - centre[0],  # type: ignore[index]
                joints[f"{k}_shoulder"][1] - centre[1],  # type: ignore[index]
            ),
        )
        joints[f"{far}_shoulder"] = None
    for side in ("l", "r"):
        for inner, outer, length in BONES:
            a, b = joints.get(f"{side}_{inner}"), joints.get(f"{side}_{outer}")
            if a is not None and b is not None and math.dist(a, b) > length:
                joints[f"{side}_{outer}"] = None
    return Skeleton(
        tuple((k, joints[k]) for k, _ in sk.joints),
        tuple((k, p if joints[k] is not None else None) for k, p in sk.pixels),
    )


@dataclass(slots=True)
class JointGate:
    """One track's joints over time: a joint that jumps, relative to the body axis, farther
    than it can move since it was last accepted (:data:`JOINT_SPEED` × the time +
    :data:`JUMP_SLACK`) is reported unseen for that frame — a left/right mix-up or a depth
    sample off the arm — unless the next frame confirms it (the arm really moved there)."""

    last: dict[str, tuple[float, Vec3]] = field(default_factory=dict)  # joint -> (t, offset)
    pending: dict[str, tuple[float, Vec3]] = field(default_factory=dict)
    held: int = 0  # joints held back so far

    def update(self, sk: Skeleton, centre: tuple[float, float], t: float) -> Skeleton:
        out = dict(sk.joints)
        for k, p in sk.joints:
            if p is None:
                continue
            rel = (p[0] - centre[0], p[1] - centre[1], p[2])
            allowed = JOINT_SPEED[k[2:]]
            prev = self.last.get(k)
            if prev is None or t - prev[0] > 1.0 or _within(rel, prev[1], allowed, t - prev[0]):
                self.last[k] = (t, rel)
                self.pending.pop(k, None)
                continue
            seen = self.pending.get(k)
            if seen is not None and _within(rel, seen[1], allowed, t - seen[0]):
                self.last[k] = (t, rel)  # two frames agree: the joint moved
                self.pending.pop(k, None)
                continue
            self.pending[k] = (t, rel)
            out[k] = None
            self.held += 1
        return Skeleton(
            tuple((k, out[k]) for k, _ in sk.joints),
            tuple((k, p if out[k] is not None else None) for k, p in sk.pixels),
        )


def _within(a: Vec3, b: Vec3, speed: float, dt: float) -> bool:
    return math.dist(a, b) <= speed * max(dt, 0.0) + JUMP_SLACK


class PoseWorker:
    """A MediaPipe pose process; :meth:`skeleton` asks it about one person.

    Raises:
        BackendUnavailableError: no pose environment, or its worker did not start.
    """

    def __init__(self, python: Path | None = None) -> None:
        exe = python if python is not None else pose_python()
        if not exe.is_file():
            raise BackendUnavailableError(
                f"skeletons need the pose environment: {exe} not found (bash setup.sh makes "
                ".venv-pose with mediapipe 0.10.21 and numpy<2; or set HLTL_POSE_PYTHON)"
            )
        worker = Path(__file__).with_name("pose_worker.py")
        self._proc = subprocess.Popen(
            [str(exe), str(worker)],
            stdin=subprocess.PIPE,
            stdout=subprocess.PIPE,
            stderr=subprocess.DEVNULL,  # TensorFlow Lite's start-up chatter
        )
        hello = self._read()
        if not hello.get("ready"):
            self.close()
            raise BackendUnavailableError(f"pose worker {exe}: did not start ({hello})")
        self.version = str(hello.get("mediapipe"))

    def _pipes(self) -> tuple[IO[bytes], IO[bytes]]:
        assert self._proc.stdin is not None and self._proc.stdout is not None
        return self._proc.stdin, self._proc.stdout

    def _read(self) -> dict[str, Any]:
        _, out = self._pipes()
        line = out.readline()
        if not line:
            code = self._proc.poll()
            raise BackendUnavailableError(f"pose worker ended (exit code {code})")
        reply = json.loads(line)
        if not isinstance(reply, dict):
            raise PerceptionError(f"pose worker: unexpected reply {line[:80]!r}")
        return reply

    def landmarks(self, crop: npt.NDArray[np.uint8]) -> list[tuple[float, float, float]] | None:
        """MediaPipe's 33 landmarks (u, v, visibility) in the crop's pixels, or None."""
        inp, _ = self._pipes()
        h, w = crop.shape[:2]
        inp.write((json.dumps({"w": w, "h": h}) + "\n").encode())
        inp.write(np.ascontiguousarray(crop, dtype=np.uint8).tobytes())
        inp.flush()
        reply = self._read()
        if "error" in reply:
            raise PerceptionError(f"pose worker: {reply['error']}")
        marks = reply.get("landmarks")
        if marks is None:
            return None
        return [(float(a), float(b), float(c)) for a, b, c in marks]

    def skeleton(
        self,
        rgb: npt.NDArray[np.uint8],
        depth: npt.NDArray[np.float32],
        camera: Camera,
        box: Box,
        mask: npt.NDArray[np.bool_] | None = None,
    ) -> Skeleton | None:
        """The skeleton of the person in ``box`` (None: the pose model found nobody)."""
        h, w = depth.shape
        u0, v0, u1, v1 = box
        pu, pv = PAD * (u1 - u0), PAD * (v1 - v0)
        cu0, cv0 = max(int(u0 - pu), 0), max(int(v0 - pv), 0)
        cu1, cv1 = min(int(u1 + pu) + 1, w), min(int(v1 + pv) + 1, h)
        if cu1 - cu0 < 8 or cv1 - cv0 < 8:
            return None
        marks = self.landmarks(rgb[cv0:cv1, cu0:cu1])
        if marks is None:
            return None
        joints: list[tuple[str, Vec3 | None]] = []
        pixels: list[tuple[str, tuple[float, float] | None]] = []
        for name, k in JOINTS.items():
            mu, mv, vis = marks[k]
            if vis < MIN_VISIBILITY:
                joints.append((name, None))
                pixels.append((name, None))
                continue
            uv = (mu + cu0, mv + cv0)
            pixels.append((name, uv))
            # an arm held out may leave the detector's mask: then the window alone decides
            joints.append((name, lift(depth, camera, uv, mask) or lift(depth, camera, uv)))
        return _hide_far_side(Skeleton(tuple(joints), tuple(pixels)), camera)

    def close(self) -> None:
        if self._proc.poll() is None:
            inp, _ = self._pipes()
            inp.close()
            try:
                self._proc.wait(timeout=10)
            except subprocess.TimeoutExpired:
                self._proc.kill()
                self._proc.wait()

    def __enter__(self) -> PoseWorker:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()
