"""Partly hidden objects: placed within a centimetre from what the camera sees, or not at all.

Oracles: the exact ray-cast frames of :mod:`hltl.perception.synthetic` (their own ray-cylinder
code, not :func:`hltl.perception.carve.ray_depths`) and the 3D simulator's renders with its
true object centres."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

from hltl.perception.carve import hidden_share, ray_depths
from hltl.perception.geometry import cylinder_outline, cylinder_silhouette, polygon_area
from hltl.perception.learned import SIZES
from hltl.perception.objects import MAX_SPREAD, SegmentationBackend, localize, size_prior
from hltl.perception.observe import Perceiver
from hltl.perception.synthetic import Solid, make_camera, render
from hltl.world.scene import Robot, Scene, SceneObject

CATEGORIES = sorted(SIZES)


def _frame(  # type: ignore[no-untyped-def]
    category: str,
    offset: float,
    azimuth: float,
    elevation: float,
    gap: float,
    distance: float = 1.3,
    width: int = 320,
):
    """An object of ``category`` at the origin and a tall occluder ``gap`` m in front of it
    (towards the camera), shifted sideways by ``offset`` m; the camera ``distance`` m away."""
    r, h = SIZES[category]
    target = Solid("object", category, (0.0, 0.0, 0.0), r, h, (200, 60, 40))
    toward = np.array([math.cos(azimuth), math.sin(azimuth)])
    side = np.array([-toward[1], toward[0]])
    oc = toward * (r + gap + 0.06) + side * offset
    occluder = Solid("other", "wall", (oc[0], oc[1], 0.0), 0.06, 0.4, (90, 90, 90))
    eye = distance * math.cos(elevation) * toward
    cam = make_camera(
        (eye[0], eye[1], distance * math.sin(elevation)),
        (0.0, 0.0, h / 2),
        (target, occluder),
        width=width,
        height=width * 3 // 4,
        fov_deg=50.0,
    )
    return target, cam, render(cam, (target, occluder))


@settings(max_examples=40, deadline=None)
@given(
    st.sampled_from(CATEGORIES),
    st.floats(-0.16, 0.16),  # the occluder's sideways shift: from hiding all to hiding none
    st.floats(-math.pi, math.pi),  # direction the camera looks from
    st.floats(0.15, 0.9),  # camera elevation (rad)
    st.floats(0.0, 0.1),  # gap between the object and the occluder (m)
)
# found before the region was refined on the 1 mm lattice (session 12): a grazing view whose
# only free 4 mm grid axis was 9 mm off (spread 1.13 cm, 62 % shown), and a random sweep's
# bottle (1.07 cm, 74 % shown)
@example("apple", 0.0703125, 0.1875, 0.15625, 0.0)
@example("bottle", -0.075293774591477, 1.2262243281213854, 0.3689770145604052, 0.04949412602503114)
def test_a_partly_hidden_object_is_placed_within_a_centimetre_or_not_reported(
    category: str, offset: float, azimuth: float, elevation: float, gap: float
) -> None:
    target, cam, frame = _frame(category, offset, azimuth, elevation, gap)
    assert frame.seg is not None
    shown = int((frame.seg == 1).sum())
    backend = SegmentationBackend()
    dets = backend.detect(frame, cam)
    located = [
        loc
        for loc in localize(frame, cam, dets, backend.planes, max_spread=None)
        if loc.detection.label == category
    ]
    confident = [loc for loc in located if loc.spread <= MAX_SPREAD]
    for loc in confident:
        assert math.dist(loc.cylinder.center, target.center) <= 0.01
    # recall is not given away: an object showing half of itself or more is placed
    hull = cylinder_outline(target.center, target.radius, target.height, cam)
    assert hull is not None
    if shown >= 0.5 * polygon_area(hull):
        assert confident, f"{category}: {shown} px shown, spread {[x.spread for x in located]}"


def test_an_unsure_object_is_reported_not_placed(monkeypatch: pytest.MonkeyPatch) -> None:
    """The Perceiver names an object it cannot place; it is missing, so fusion keeps it where
    it was. (Exact frames place even slivers well, so the accepted spread is lowered below this
    sliver's.)"""
    _, cam, frame = _frame("chips", 0.05, 0.3, 0.05, 0.0, 2.5, 160)  # 39 px of its side
    located = localize(
        frame, cam, SegmentationBackend().detect(frame, cam), [0.0], None, True, None
    )
    sliver = [loc for loc in located if loc.detection.label == "chips"]
    assert sliver and 0.0 < sliver[0].spread < MAX_SPREAD
    scene = Scene(
        robots=(Robot("r1", (2.0, 2.0, 0.0), 0.7),),
        objects=(SceneObject("chips", "chips", (0.0, 0.0, 0.05)),),
    )
    placed = Perceiver(scene, cam, backend="segmentation", people="none").process(frame)
    assert [o.id for o in placed.objects] == ["chips"] and not placed.missing
    monkeypatch.setattr("hltl.perception.observe.MAX_SPREAD", sliver[0].spread / 2)
    obs = Perceiver(scene, cam, backend="segmentation", people="none").process(frame)
    assert obs.missing == ("chips",) and not obs.objects
    assert any(a.startswith("chips: seen too little to place (39 px") for a in obs.ambiguous)


@settings(max_examples=30, deadline=None)
@given(
    st.floats(0.02, 0.08),
    st.floats(0.03, 0.25),
    st.floats(-math.pi, math.pi),
    st.floats(0.1, 1.0),
)
def test_ray_depths_and_silhouette_match_the_synthetic_renderer(
    radius: float, height: float, azimuth: float, elevation: float
) -> None:
    solid = Solid("object", "x", (0.1, -0.05, 0.0), radius, height, (255, 0, 0))
    eye = (
        1.2 * math.cos(elevation) * math.cos(azimuth),
        1.2 * math.cos(elevation) * math.sin(azimuth),
    )
    cam = make_camera((eye[0], eye[1], 1.2 * math.sin(elevation)), (0.1, -0.05, 0.05), (solid,))
    frame = render(cam, (solid,))
    assert frame.seg is not None
    mask = frame.seg == 1
    sil = cylinder_silhouette(solid.center, radius, height, cam)
    # pixels whose centre is on the rim may go either way
    assert int((mask ^ sil).sum()) <= 0.1 * max(int(mask.sum()), 1) + 4
    v, u = np.nonzero(mask)
    pose = cam.pose
    rays = np.stack([(u - cam.cx) / cam.fx, (v - cam.cy) / cam.fy, np.ones(len(u))])
    t = ray_depths(
        pose[:3, 3], (pose[:3, :3] @ rays).T, np.array([[0.1, -0.05]]), radius, 0.0, height
    )
    hit = np.isfinite(t[0])
    assert hit.mean() >= 0.95
    assert np.abs(t[0][hit] - frame.depth[v, u][hit]).max() <= 1e-4
    assert hidden_share(frame.depth, cam, solid.center, radius, height) <= 0.05


def test_every_rendered_category_has_its_size() -> None:
    from hltl.sim3d.model import object_look

    for category in CATEGORIES:
        r, h, _ = object_look(SceneObject("x", category, (0.0, 0.0, 0.05)))
        assert size_prior(None, category) == (r, h)


def test_the_simulator_renders_clutter_objects_within_the_targets() -> None:
    """The 3D simulator's own renders (random clutter, cameras, people, arms): every object
    the segmentation backend places is within 1 cm of the simulator's centre."""
    pytest.importorskip("mujoco")
    from hltl.errors import HltlError
    from hltl.sim.scenarios import get
    from hltl.sim3d.dataset import render_samples
    from hltl.sim3d.gl import require_renderer
    from hltl.sim3d.model import object_look

    try:
        require_renderer()
    except HltlError as exc:
        pytest.skip(str(exc))
    samples = render_samples([get("fig1").scene], seed=1000, layouts=2, views=3)
    placed = 0
    for s in samples:
        assert s.frame.seg is not None
        backend = SegmentationBackend(s.scene)
        dets = backend.detect(s.frame, s.camera)
        for loc in localize(s.frame, s.camera, dets, backend.planes, s.scene):
            oid = loc.detection.label
            assert math.dist(loc.cylinder.center, s.centres[oid]) <= 0.01, (s.frame.index, oid)
            placed += 1
        # the silhouette of every object covers its rendered pixels
        for sid, seg in s.camera.segments.items():
            if seg.kind != "object":
                continue
            r, h, _ = object_look(s.scene.object(seg.id))
            sil = cylinder_silhouette(s.centres[seg.id], r, h, s.camera)
            assert int(((s.frame.seg == sid) & ~sil).sum()) <= 3
    assert placed >= 20


@settings(max_examples=30, deadline=None)
@given(st.floats(-0.6, 0.6), st.floats(-0.45, 0.45))
def test_hidden_share_counts_what_the_image_border_cuts_off(du: float, dv: float) -> None:
    """Nothing in front: the hidden share is the part of the silhouette outside the image."""
    solid = Solid("object", "x", (0.0, 0.0, 0.0), 0.05, 0.18, (255, 0, 0))
    # the camera looks past the object, so that it sits anywhere from the centre to off-image
    eye = np.array([0.0, -1.0, 0.5])
    aim = np.array([du, 0.0, 0.09 + dv])
    cam = make_camera(tuple(eye), tuple(aim), (solid,), width=640, height=480)
    frame = render(cam, (solid,))
    assert frame.seg is not None
    hull = cylinder_outline(solid.center, solid.radius, solid.height, cam)
    assert hull is not None
    shown = int((frame.seg == 1).sum())
    expected = 1.0 - shown / polygon_area(hull)
    got = hidden_share(frame.depth, cam, solid.center, solid.radius, solid.height)
    assert got == pytest.approx(max(expected, 0.0), abs=0.05)


@settings(max_examples=50, deadline=None)
@given(st.lists(st.tuples(st.floats(-10, 10), st.floats(-10, 10)), min_size=3, max_size=60))
def test_convex_hull_holds_every_point_and_has_scipys_area(pts: list[tuple[float, float]]) -> None:
    from scipy.spatial import ConvexHull, QhullError

    from hltl.perception.geometry import convex_hull

    p = np.asarray(pts, dtype=float)
    try:
        expected = float(ConvexHull(p).volume)
    except QhullError:  # collinear or repeated points: no area
        expected = 0.0
    hull = convex_hull(p)
    assert polygon_area(hull) == pytest.approx(expected, rel=1e-9, abs=1e-9)
    for a, b in zip(hull, np.roll(hull, -1, axis=0), strict=True):  # every point on the left
        cross = (b[0] - a[0]) * (p[:, 1] - a[1]) - (b[1] - a[1]) * (p[:, 0] - a[0])
        assert cross.min() >= -1e-9
