"""The learned backend's geometric checks on exact synthetic frames: a table-top sized
"person" standing on a table is re-tested as an object (or reported), and an object region
that is a piece of a bigger surface (an arm's base) is recognised by the ring around it."""

from __future__ import annotations

import numpy as np
import pytest

from hltl.perception.detection import support_planes, world_points
from hltl.perception.learned import CLASSES, CONTINUED, LearnedBackend, PixelProbabilities
from hltl.perception.synthetic import Solid, make_camera, render

pytest.importorskip("torch")

TABLE = Solid("surface", "table", (0.0, 0.0, 0.0), 0.8, 0.75, (120, 90, 60))
CUP = Solid("object", "cup", (0.1, -0.2, 0.75), 0.04, 0.10, (230, 230, 230))
BASE = Solid("robot", "base", (-0.3, 0.1, 0.75), 0.07, 0.25, (90, 90, 100))
PERSON = Solid("human", "A", (0.2, 1.3, 0.0), 0.15, 1.7, (200, 50, 50))
FLOOR_CUP = Solid("object", "floorcup", (1.1, -0.5, 0.0), 0.04, 0.10, (230, 230, 230))
BOX = Solid("object", "box", (0.45, -0.3, 0.75), 0.06, 0.12, (40, 90, 200))
SOLIDS = (TABLE, CUP, BASE, PERSON, FLOOR_CUP, BOX)
EYE, TARGET = (0.0, -2.0, 1.6), (0.1, 0.0, 0.7)


def setup():  # type: ignore[no-untyped-def]
    cam = make_camera(EYE, TARGET, SOLIDS, width=320, height=240)
    frame = render(cam, SOLIDS)
    backend = LearnedBackend()
    pts = world_points(frame.depth, cam)
    backend.planes = support_planes(pts[frame.depth > 0][:, 2], share=0.01)
    backend._depth = frame.depth
    assert backend.planes[0] == pytest.approx(0.0, abs=0.01)
    assert any(abs(p - 0.75) < 0.01 for p in backend.planes)
    return cam, frame, backend, pts


def probabilities(frame, **classes: float) -> PixelProbabilities:  # type: ignore[no-untyped-def]
    """The same class probabilities at every pixel (the rest spread over background)."""
    h2, w2 = frame.depth.shape[0] // 2, frame.depth.shape[1] // 2
    p = np.zeros((len(CLASSES), h2, w2), np.float32)
    for name, v in classes.items():
        p[CLASSES.index(name)] = v
    p[0] = 1.0 - p.sum(axis=0)
    return PixelProbabilities(p)


def mask_of(frame, solid: Solid) -> np.ndarray:  # type: ignore[no-untyped-def,type-arg]
    return frame.seg == SOLIDS.index(solid) + 1


def test_a_person_sized_or_floor_standing_region_stays_a_person() -> None:
    _, frame, backend, pts = setup()
    prob = probabilities(frame, person=0.6, cup=0.3)
    assert backend._retest_person(mask_of(frame, PERSON), pts, prob) == "person"
    # object-sized but on the floor: feet, not something on a table
    assert backend._retest_person(mask_of(frame, FLOOR_CUP), pts, prob) == "person"
    assert backend.doubts == []


def test_a_small_person_on_the_table_is_the_object_class_the_network_favours_next() -> None:
    _, frame, backend, pts = setup()
    cup = mask_of(frame, CUP)
    assert backend._retest_person(cup, pts, probabilities(frame, person=0.6, cup=0.3)) == "cup"
    # the network's favourite object class is tried first; one the region is too wide for
    # (a cup is at most 11 cm across, the box 12 cm) falls through to the next
    box = mask_of(frame, BOX)
    label = backend._retest_person(box, pts, probabilities(frame, person=0.5, cup=0.3, box=0.15))
    assert label == "box"
    assert backend.doubts == []


def test_no_object_class_fits_so_the_region_is_reported_not_guessed() -> None:
    _, frame, backend, pts = setup()
    cup = mask_of(frame, CUP)
    assert backend._retest_person(cup, pts, probabilities(frame, person=0.95, cup=0.02)) is None
    (doubt,) = backend.doubts
    assert doubt.startswith("person or object:") and "closest cup" in doubt


def backend_points(frame):  # type: ignore[no-untyped-def]
    cam = make_camera(EYE, TARGET, SOLIDS, width=320, height=240)
    return world_points(frame.depth, cam)


def test_a_piece_of_an_arm_base_is_continued_by_its_surface_and_an_object_is_not() -> None:
    _, frame, backend, _ = setup()
    full = np.zeros(frame.depth.shape, dtype=np.int64)
    z = backend_points(frame)[..., 2]
    cup = mask_of(frame, CUP)
    assert backend._continued(cup, frame.depth, z, full) < CONTINUED
    base = mask_of(frame, BASE)
    v = np.nonzero(base)[0]
    lo, hi = np.percentile(v, [42, 58])
    rows = np.arange(base.shape[0])[:, None]
    piece = base & (rows >= lo) & (rows <= hi)  # a band of it: the base goes on above and below
    assert backend._continued(piece, frame.depth, z, full) >= CONTINUED
    # the whole base stands free as well (it is the network's label, not the geometry, that
    # makes it no object): only a piece of it is continued
    assert backend._continued(base, frame.depth, z, full) < CONTINUED


def test_the_observation_reports_what_the_backend_could_not_decide() -> None:
    from hltl.perception.observe import Perceiver

    cam, frame, _, _ = setup()

    class Undecided:
        name = "undecided"

        def __init__(self) -> None:
            self.planes: list[float] = []
            self.doubts = ["person or object: 40 px at (0.10, -0.20, 0.80)"]

        def detect(self, frame, camera):  # type: ignore[no-untyped-def]
            return []

    p = Perceiver(None, cam, "segmentation", "none")
    p.backend = Undecided()
    assert p.process(frame).ambiguous == ("person or object: 40 px at (0.10, -0.20, 0.80)",)


def test_only_regions_by_a_registered_arm_base_are_checked_for_being_a_piece_of_it() -> None:
    from hltl.world.scene import Robot, Scene

    _, frame, _, pts = setup()
    backend = LearnedBackend(Scene(robots=(Robot("r1", BASE.base, 0.7),)))
    assert backend._near_base(pts[mask_of(frame, BASE)])
    assert not backend._near_base(pts[mask_of(frame, BOX)])  # 0.8 m away
    assert not LearnedBackend()._near_base(pts[mask_of(frame, BASE)])  # no scene: no arms known
