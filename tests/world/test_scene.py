"""Scene loading and validation."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from hltl.errors import SceneError, UnknownEntityError
from hltl.world.scene import load_scene, scene_from_dict

BASE = {"robots": [{"id": "r1", "base": [0, 0, 0], "reach": 0.7}]}


def test_two_arms_loads_and_round_trips(two_arms_path: Path) -> None:
    scene = load_scene(two_arms_path)
    assert scene.robot_ids == ("r1", "r2")
    assert scene.object("chips").aliases == ("crisps",)
    assert scene.duration_map() == {
        "pick": 0.5,
        "place": 0.5,
        "handover_r2r": 0.6,
        "handover_r2h": 0.5,
    }
    assert scene_from_dict(scene.to_dict()) == scene


@pytest.mark.parametrize(
    ("patch", "needle"),
    [
        ({"robots": [{"id": "r1", "base": [0, 0, 0], "reach": -1}]}, "robots[0].reach"),
        ({"robots": [{"id": "r1", "base": [0, 0, math.nan], "reach": 1}]}, "nan"),
        (
            {"robots": [{"id": "r1", "base": [0, 0, 0], "reach": 1, "speeed": 2}]},
            "robots[0].speeed",
        ),
        ({"objects": [{"id": "r1", "position": [0, 0, 0]}]}, "duplicate id 'r1'"),
        ({"objects": [{"id": "cup"}]}, "objects[0].position"),
        ({"units": "ft"}, "unknown unit 'ft'"),
        ({"durations": {"pick": -1.0}}, "pick"),
        ({"humans": [{"id": "A B", "position": [0, 0, 0]}]}, "'A B' is not valid"),
        ({"robots": []}, "robots"),
    ],
)
def test_bad_scenes_name_field_and_value(patch: dict[str, object], needle: str) -> None:
    with pytest.raises(SceneError) as err:
        scene_from_dict({**BASE, **patch}, source="bad.yaml")
    assert "bad.yaml" in str(err.value)
    assert needle in str(err.value)


def test_units_are_converted_to_metres() -> None:
    robots = [{"id": "r", "base": [100, 0, 0], "reach": 70}]
    scene = scene_from_dict({"units": "cm", "robots": robots})
    assert scene.robot("r").base == (1.0, 0.0, 0.0)
    assert scene.robot("r").reach == pytest.approx(0.7)


def test_unknown_lookup_lists_what_exists(two_arms_path: Path) -> None:
    scene = load_scene(two_arms_path)
    with pytest.raises(UnknownEntityError, match="unknown object 'cup'; scene has: bottle, chips"):
        scene.object("cup")


def test_unreadable_and_malformed_files(tmp_path: Path) -> None:
    with pytest.raises(SceneError, match="cannot read"):
        load_scene(tmp_path / "missing.yaml")
    bad = tmp_path / "bad.yaml"
    bad.write_text("robots: [\n")
    with pytest.raises(SceneError, match="not valid YAML"):
        load_scene(bad)
