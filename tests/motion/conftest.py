"""Motion fixtures: coarse reachability maps (cheap to build) in a temporary cache."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

pytest.importorskip("pinocchio")

from hltl.world.scene import Scene, load_scene

ROOT = Path(__file__).resolve().parents[2]
TEST_RESOLUTION = 0.1  # coarse: the tests check properties, the benchmark measures accuracy


@pytest.fixture(scope="session")
def fig1() -> Scene:
    return load_scene(ROOT / "examples" / "scenes" / "fig1.yaml")


@pytest.fixture(scope="session")
def coarse_maps(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Any]:
    import os

    from hltl.motion.reach import load_or_build

    os.environ["HLTL_CACHE"] = str(tmp_path_factory.mktemp("hltl-cache"))
    # the CLI and the cost model build maps at the default spacing: make that coarse too
    os.environ["HLTL_REACH_RESOLUTION"] = str(TEST_RESOLUTION)
    return {m: load_or_build(m, TEST_RESOLUTION) for m in ("elfin3", "ur5")}


@pytest.fixture(scope="session")
def fig1_cell(fig1: Scene, coarse_maps: dict[str, Any]) -> Any:
    from hltl.motion.planning import Cell
    from hltl.motion.workspace import MapKinematics

    return Cell(fig1, MapKinematics(fig1, coarse_maps))
