"""Plans, logs and specs to draw: made here, from the planner and short simulated episodes."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

from hltl.execution.log import LogRecord
from hltl.planner import PlanResult, plan
from hltl.sim.episode import run_episode
from hltl.sim.events import events_from_dict
from hltl.spec.hierarchy import HSpec, spec_from_dict
from hltl.viz.demo import DEMO_INSTRUCTION, demo_events
from hltl.world.scene import Scene, load_scene

ROOT = Path(__file__).resolve().parents[2]
TWO_ARMS = ROOT / "examples" / "scenes" / "two_arms.yaml"

# The paper's task: r1 picks and hands the bottle to A, r2 the chips to B (two steps, 1.0 s).
PAPER_SPEC = {
    "root": "p0",
    "formulas": {
        "p0": "F p100 & F p200",
        "p100": "F delivered(bottle, A)",
        "p200": "F delivered(chips, B)",
    },
}
# The chips lie on r2's side and A stands on r1's: r2 picks them, hands them to r1 (a
# robot-to-robot handover), r1 hands them to A.
CHIPS_TO_A = {"root": "p0", "formulas": {"p0": "F delivered(chips, A)"}}


@pytest.fixture(autouse=True)
def _close_figures() -> Iterator[None]:
    yield
    import matplotlib.pyplot as plt

    plt.close("all")


@pytest.fixture(scope="session")
def scene() -> Scene:
    return load_scene(TWO_ARMS)


def _plan(scene: Scene, spec: dict[str, Any]) -> PlanResult:
    result = plan(scene, spec_from_dict(spec))
    assert result.solved
    return result


@pytest.fixture(scope="session")
def paper_plan(scene: Scene) -> PlanResult:
    return _plan(scene, PAPER_SPEC)


@pytest.fixture(scope="session")
def chips_plan(scene: Scene) -> PlanResult:
    result = _plan(scene, CHIPS_TO_A)
    assert any(a.skill == "handover_r2r" for a in result.actions)
    return result


@pytest.fixture(scope="session")
def paper_spec() -> HSpec:
    return spec_from_dict(PAPER_SPEC)


@pytest.fixture(scope="session")
def demo_records(scene: Scene) -> tuple[LogRecord, ...]:
    """The demo episode: a person walks over, a halt, a predicted takeover, success."""
    ep = run_episode(scene, instruction=DEMO_INSTRUCTION, events=demo_events(scene), seed=0)
    assert ep.success
    return ep.records


@pytest.fixture(scope="session")
def down_records(scene: Scene) -> tuple[LogRecord, ...]:
    """r1 goes down mid-pick: a failed action, no plan while it is down, a replan when back."""
    events = events_from_dict(
        {"events": [{"t": 0.2, "type": "robot_down", "robot": "r1", "duration": 1.0}]}, scene
    )
    ep = run_episode(scene, spec=spec_from_dict(PAPER_SPEC), events=events, seed=0)
    assert ep.success
    return ep.records


def magic(path: Path) -> bytes:
    return path.read_bytes()[:8]


PNG = b"\x89PNG\r\n\x1a\n"
