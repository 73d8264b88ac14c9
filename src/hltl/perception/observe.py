"""Frames → observations → the executor's WorldState."""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np

from hltl.perception.filtering import RestingFilter
from hltl.perception.frames import Camera, Frame
from hltl.perception.geometry import Cylinder
from hltl.perception.objects import MAX_SPREAD, Located, ObjectBackend, localize, make_backend
from hltl.perception.people import DETECTORS, PeopleTracker, PersonObservation
from hltl.world.scene import Scene, Vec3
from hltl.world.state import ObjectStatus, WorldState

# m: a detection named by category matches a registered object of it at most this far away
CATEGORY_GATE = 1.0
AMBIGUOUS = 0.05  # m: two registered objects this close in distance to a detection are ambiguous


@dataclass(frozen=True, slots=True)
class ObjectObservation:
    """One object seen in 3D.

    Attributes:
        id: the scene object it is (None when nothing in the scene matches).
        label: the backend's label.
        position: the fitted cylinder's axis point at mid-height (scene frame).
    """

    id: str | None
    label: str
    position: Vec3
    cylinder: Cylinder
    score: float
    pixels: int

    def to_dict(self) -> dict[str, Any]:
        return {
            "id": self.id,
            "label": self.label,
            "position": [round(v, 4) for v in self.position],
            "size": {
                "radius": round(self.cylinder.radius, 4),
                "height": round(self.cylinder.height, 4),
            },
            "score": round(self.score, 3),
            "pixels": self.pixels,
        }


@dataclass(frozen=True, slots=True)
class Observation:
    """What one frame says about the world, with what it could not decide."""

    t: float
    frame: int
    objects: tuple[ObjectObservation, ...]
    people: tuple[PersonObservation, ...]
    latency: float  # seconds spent on this frame
    missing: tuple[str, ...] = ()  # scene objects not seen
    unmatched: tuple[str, ...] = ()  # labels of detections no scene object matches
    # "label: a or b" descriptions, regions the backend could not decide, objects seen too little
    ambiguous: tuple[str, ...] = ()
    lost: tuple[str, ...] = ()  # scene people without a live track
    notes: tuple[str, ...] = field(default=())

    def to_dict(self) -> dict[str, Any]:
        return {
            "t": self.t,
            "frame": self.frame,
            "latency_ms": round(self.latency * 1000.0, 1),
            "objects": [o.to_dict() for o in self.objects],
            "people": [p.to_dict() for p in self.people],
            "missing": list(self.missing),
            "unmatched": list(self.unmatched),
            "ambiguous": list(self.ambiguous),
            "lost": list(self.lost),
        }


def match_objects(
    scene: Scene | None, located: list[Located]
) -> tuple[list[ObjectObservation], list[str], list[str]]:
    """Scene ids for located detections: an exact label (a segment's scene id) is that object;
    otherwise the scene objects whose category or alias is the label within CATEGORY_GATE,
    nearest registered position first (ambiguous when two are about as near). Returns
    (observations, unmatched, ambiguous)."""
    out: list[ObjectObservation] = []
    unmatched: list[str] = []
    ambiguous: list[str] = []
    taken: set[str] = set()
    for loc in sorted(located, key=lambda x: -x.detection.score):
        det, cyl = loc.detection, loc.cylinder
        oid: str | None = None
        if scene is not None:
            if det.exact and det.label in scene.object_ids:
                oid = det.label
            else:
                cands = [
                    o
                    for o in scene.objects
                    if o.id not in taken and (det.label == o.category or det.label in o.aliases)
                ]
                cands.sort(key=lambda o: math.dist(o.position[:2], cyl.center[:2]))
                # farther than CATEGORY_GATE from every candidate: some other thing, not guessed
                cands = [
                    o for o in cands if math.dist(o.position[:2], cyl.center[:2]) <= CATEGORY_GATE
                ]
                if cands:
                    oid = cands[0].id
                    if len(cands) > 1:
                        d0 = math.dist(cands[0].position[:2], cyl.center[:2])
                        d1 = math.dist(cands[1].position[:2], cyl.center[:2])
                        if d1 - d0 < AMBIGUOUS:
                            ambiguous.append(f"{det.label}: {cands[0].id} or {cands[1].id}")
                            oid = None
        if oid is None:
            unmatched.append(det.label)
        else:
            taken.add(oid)
        out.append(ObjectObservation(oid, det.label, cyl.center, cyl, det.score, loc.pixels))
    return out, unmatched, ambiguous


class Perceiver:
    """The perception stage for one camera.

    Args:
        scene: the scene whose ids observations are matched to (None: labels only).
        camera: the camera the frames come from.
        backend: object backend name (see :data:`hltl.perception.objects.BACKENDS`).
        people: a person detector of :data:`hltl.perception.people.DETECTORS` or ``none``.
        skeleton: 3D shoulders, elbows and wrists of tracked people (MediaPipe in its own
            process; see :mod:`hltl.perception.skeleton`).
        smooth: filter positions over frames (:mod:`hltl.perception.filtering`): people by
            track (constant velocity, gated), matched objects by id (at rest, gated).
        yolo_async: ``fused`` runs YOLO on a worker thread (see :class:`PeopleTracker`).
    """

    def __init__(
        self,
        scene: Scene | None,
        camera: Camera,
        backend: str = "segmentation",
        people: str = "segmentation",
        skeleton: bool = False,
        smooth: bool = True,
        yolo_async: bool = True,
    ) -> None:
        self.scene = scene
        self.camera = camera
        self.smooth = smooth
        self.resting: dict[str, RestingFilter] = {}
        self.backend: ObjectBackend = make_backend(backend, scene)
        if people != "none" and people not in DETECTORS:
            raise ValueError(
                f"unknown people detector {people!r}; expected {', '.join(DETECTORS)} or none"
            )
        self.tracker = (
            None
            if people == "none"
            else PeopleTracker(
                scene if scene is not None else Scene(robots=()),
                people,
                skeleton=skeleton,
                smooth=smooth,
                yolo_async=yolo_async,
            )
        )

    def close(self) -> None:
        """End helper processes (the pose worker)."""
        if self.tracker is not None:
            self.tracker.close()

    def process(self, frame: Frame) -> Observation:
        t0 = time.perf_counter()
        dets = self.backend.detect(frame, self.camera)
        located = localize(
            frame, self.camera, dets, self.backend.planes, self.scene, max_spread=None
        )
        # a partly hidden object the frame cannot place within MAX_SPREAD is reported, not placed:
        # it stays where the world last had it
        unsure = [loc for loc in located if loc.spread > MAX_SPREAD]
        located = [loc for loc in located if loc.spread <= MAX_SPREAD]
        objects, unmatched, ambiguous = match_objects(self.scene, located)
        ambiguous += self.backend.doubts  # regions the backend could not call person or object
        ambiguous += [
            f"{loc.detection.label}: seen too little to place ({loc.pixels} px, axis uncertain "
            + ("beyond its size)" if math.isinf(loc.spread) else f"by {100 * loc.spread:.1f} cm)")
            for loc in unsure
        ]
        if self.smooth:  # a matched object's position over frames, gated (filtering.py)
            objects = [
                o
                if o.id is None
                else replace(
                    o, position=self.resting.setdefault(o.id, RestingFilter()).update(o.position)
                )
                for o in objects
            ]
        people = self.tracker.update(frame, self.camera) if self.tracker is not None else []
        seen = {o.id for o in objects}
        missing = tuple(o for o in self.scene.object_ids if o not in seen) if self.scene else ()
        held = {p.person for p in people}
        lost = (
            tuple(h for h in self.scene.human_ids if h not in held)
            if self.scene is not None and self.tracker is not None
            else ()
        )
        return Observation(
            frame.t,
            frame.index,
            tuple(objects),
            tuple(people),
            time.perf_counter() - t0,
            missing,
            tuple(unmatched),
            tuple(ambiguous),
            lost,
        )


def fuse(world: WorldState, obs: Observation) -> WorldState:
    """``world`` updated by an observation: people tied to a scene person move to their
    observed floor position, resting objects matched by id move to the observed axis (their
    grasp height stays the world's: the height convention is the scene's, not the camera's).
    Objects in a hand, people without a track and unmatched detections change nothing; the
    observation lists them."""
    w = world.with_time(obs.t)
    humans = dict(world.humans)
    for p in obs.people:
        if p.person is not None and p.person in humans:
            z = humans[p.person][2]
            w = w.with_human(p.person, (p.position[0], p.position[1], z))
    objects = dict(world.objects)
    for o in obs.objects:
        st = objects.get(o.id) if o.id is not None else None
        if st is None or st.loc.kind not in ("rest", "on"):
            continue
        pos = (o.position[0], o.position[1], st.position[2])
        w = w.with_object(o.id, ObjectStatus(pos, st.loc))  # type: ignore[arg-type]
    return w


def position_errors(
    observed: dict[str, Vec3], truth: dict[str, Vec3], horizontal: bool = False
) -> dict[str, float]:
    """Euclidean error per id present in both (metres)."""
    n = 2 if horizontal else 3
    return {
        k: float(np.linalg.norm(np.array(observed[k][:n]) - np.array(truth[k][:n])))
        for k in observed
        if k in truth
    }
