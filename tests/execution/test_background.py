"""The executor's background plans: a driver that made them is asked first, nothing else changes."""

from __future__ import annotations

from typing import Any, ClassVar

import pytest

from hltl.execution.background import Given, PlansAhead, Problem, problem_digest
from hltl.execution.executor import ExecutorConfig
from hltl.execution.log import LogRecord, Predict
from hltl.planner import PlanResult, plan
from hltl.sim.dynamic import make_trial
from hltl.sim.episode import EpisodeConfig, run_episode
from hltl.sim.simulator import Simulator
from hltl.spec.monitor import MonitorState
from hltl.world.state import WorldState
from tests.execution import mocks
from tests.execution.mocks import RecordingPlanner

# suite trials with walks whose forecasts change the context (background plans made)
TRIALS = (("4-2", 0), ("2-4-line", 0))


class _Counting(RecordingPlanner):
    """The exact planner, counting its calls and keeping each result by its start."""

    def __init__(self, monkeypatch: pytest.MonkeyPatch) -> None:
        super().__init__()
        self.made: dict[tuple[MonitorState, WorldState], PlanResult] = {}

        def plan_kept(*args: Any, **kw: Any) -> PlanResult:
            result = plan(*args, **kw)
            self.made[(kw["q0"], kw["world"])] = result
            return result

        monkeypatch.setattr(mocks, "plan", plan_kept)

    @property
    def count(self) -> int:
        return len(self.calls)


class _Planning(Simulator):
    """The discrete simulator, also giving the executor's background plans from ``table``
    (plans made by an earlier run of the same episode, by start)."""

    table: ClassVar[dict[tuple[MonitorState, WorldState], PlanResult]] = {}
    asked: ClassVar[list[tuple[int, Problem]]] = []

    def planned(self, spec_version: int, problem: Problem) -> Given | None:
        _Planning.asked.append((spec_version, problem))
        got = _Planning.table.get((problem.q, problem.world))
        return None if got is None else Given(got, 0.002)


def _strip(records: list[LogRecord]) -> list[Any]:
    out = []
    for r in records:
        d = r.to_json()
        out.append({k: v for k, v in d.items() if not k.endswith("_ms")})
    return out


@pytest.mark.parametrize(("config", "index"), TRIALS)
def test_given_background_plans_replace_the_executors_own(
    config: str, index: int, monkeypatch: pytest.MonkeyPatch
) -> None:
    assert isinstance(_Planning.__new__(_Planning), PlansAhead)
    tr = make_trial(config, index)
    kw: dict[str, Any] = {"instruction": tr.instruction, "events": tr.events, "seed": tr.seed}
    first = _Counting(monkeypatch)
    a = run_episode(tr.scene, planner=first, **kw)
    predicts = sum(isinstance(r, Predict) for r in a.records)
    assert predicts > 0
    _Planning.table, _Planning.asked = dict(first.made), []
    second = _Counting(monkeypatch)
    b = run_episode(tr.scene, planner=second, simulator=_Planning, **kw)
    assert _strip(list(b.records)) == _strip(list(a.records))
    # every background plan came from the driver: the executor planned only its replans
    assert len(_Planning.asked) == predicts
    assert second.count == first.count - predicts
    latencies = [r.latency_ms for r in b.records if isinstance(r, Predict)]
    assert latencies == [2.0] * predicts  # (the driver's wall time, logged)


@pytest.mark.parametrize(("config", "index"), TRIALS[:1])
def test_no_plan_given_the_executor_plans_itself(
    config: str, index: int, monkeypatch: pytest.MonkeyPatch
) -> None:
    tr = make_trial(config, index)
    kw: dict[str, Any] = {"instruction": tr.instruction, "events": tr.events, "seed": tr.seed}
    first = _Counting(monkeypatch)
    a = run_episode(tr.scene, planner=first, **kw)
    _Planning.table, _Planning.asked = {}, []
    second = _Counting(monkeypatch)
    b = run_episode(tr.scene, planner=second, simulator=_Planning, **kw)
    assert _strip(list(b.records)) == _strip(list(a.records))
    assert second.count == first.count > 0
    assert len(_Planning.asked) == sum(isinstance(r, Predict) for r in a.records) > 0


def test_no_forecast_without_prediction() -> None:
    tr = make_trial(*TRIALS[0])
    _Planning.table, _Planning.asked = {}, []
    kw: dict[str, Any] = {"instruction": tr.instruction, "events": tr.events, "seed": tr.seed}
    cfg = EpisodeConfig(executor=ExecutorConfig(predict=False))
    ep = run_episode(tr.scene, config=cfg, simulator=_Planning, **kw)
    assert not any(isinstance(r, Predict) for r in ep.records)
    assert _Planning.asked == []


def test_the_digest_is_the_whole_problem() -> None:
    tr = make_trial(*TRIALS[0])
    table: dict[str, Problem] = {}
    _Planning.table, _Planning.asked = {}, []
    run_episode(
        tr.scene, instruction=tr.instruction, events=tr.events, seed=tr.seed, simulator=_Planning
    )
    assert _Planning.asked
    for version, p in _Planning.asked:
        d = problem_digest(f"spec {version}", p)
        assert table.setdefault(d, p) == p  # one digest, one problem
        moved = p.world.with_time(p.world.t + 1e-9)
        assert problem_digest(f"spec {version}", Problem(p.basis, moved, p.q, p.key)) != d
        assert problem_digest(f"spec {version + 1}", p) != d
