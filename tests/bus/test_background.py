"""The node makes the executor's background plans: the same problems, the same log, fewer plans."""

from __future__ import annotations

from collections.abc import Iterator
from typing import Any

import pytest

from hltl.bus.codec import WirePlan
from hltl.bus.driver import BusCell
from hltl.errors import BusError
from hltl.execution.background import Given, Problem, problem_digest
from hltl.execution.log import Predict
from hltl.planner import Binding, PlanResult, PlanStatus, PlanStep, SearchStats
from hltl.sim.dynamic import make_trial
from hltl.sim.episode import run_episode
from hltl.skills.library import Action
from tests.bus.helpers import Loopback, patient_foresight, without_wall_clock

# suite trials whose walks change the forecast's context (background plans)
TRIALS = (("4-2", 0), ("2-4-line", 0))


@pytest.fixture
def node_saw(monkeypatch: pytest.MonkeyPatch) -> set[str]:
    """Every background problem the node computed (its digest), planned or not."""
    seen: set[str] = set()

    def kept(spec_id: str, problem: Problem) -> str:
        d = problem_digest(spec_id, problem)
        seen.add(d)
        return d

    monkeypatch.setattr("hltl.bus.node.problem_digest", kept)
    return seen


@pytest.fixture
def planned(monkeypatch: pytest.MonkeyPatch) -> Iterator[list[tuple[str, bool]]]:
    """Every background problem the executor asked its driver for: its digest (under the
    spec the driver names it by) and whether the node's plan was given."""
    seen: list[tuple[str, bool]] = []
    orig = BusCell.planned

    def asked(self: BusCell, spec_version: int, problem: Problem) -> Given | None:
        got = orig(self, spec_version, problem)
        sid = self._spec_ids.get(spec_version)
        assert sid is not None  # (the executor's basis went before it planned)
        seen.append((problem_digest(sid, problem), got is not None))
        return got

    monkeypatch.setattr(BusCell, "planned", asked)
    yield seen


def test_the_node_makes_the_executors_background_plans(
    loopback: Loopback,
    monkeypatch: pytest.MonkeyPatch,
    planned: list[tuple[str, bool]],
    node_saw: set[str],
) -> None:
    patient_foresight(monkeypatch)
    own = given = predicts = 0
    for config, index in TRIALS:
        tr = make_trial(config, index)
        kw: dict[str, Any] = {"instruction": tr.instruction, "events": tr.events, "seed": tr.seed}
        a = run_episode(tr.scene, **kw)
        planned.clear()
        r = loopback.run(tr.scene, background=True, **kw)
        assert without_wall_clock(list(r.episode.records)) == without_wall_clock(list(a.records))
        n = sum(isinstance(x, Predict) for x in a.records)
        st = r.cell.stats
        # the executor asked before each of its background plans; the node had computed the
        # same problem (its digest: the spec, the monitor state, the whole forecast world)
        assert st.background_asked == len(planned) == n > 0
        assert {d for d, _ in planned} <= node_saw
        assert st.background_given == sum(g for _, g in planned)
        assert st.bad_plans == 0
        assert r.node.stats.background >= st.background_given
        given += st.background_given
        own += st.background_asked - st.background_given
        predicts += n
    # most are made by the node (those in an answer the executor waits for are its own)
    assert given > 0 and own + given == predicts


def test_without_the_executors_forecast_the_node_plans_nothing(
    loopback: Loopback, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A basis without the forecast's horizon (the default, or an executor from before
    session 23) gets no plans, and the log is the same."""
    patient_foresight(monkeypatch)
    tr = make_trial(*TRIALS[0])
    kw: dict[str, Any] = {"instruction": tr.instruction, "events": tr.events, "seed": tr.seed}
    a = run_episode(tr.scene, **kw)
    r = loopback.run(tr.scene, **kw)
    assert without_wall_clock(list(r.episode.records)) == without_wall_clock(list(a.records))
    assert r.node.stats.background == 0 and r.cell.stats.background_given == 0
    assert r.cell.stats.background_asked == sum(isinstance(x, Predict) for x in a.records) > 0


def _result() -> PlanResult:
    a = Action("pick", ("r1",), "cup")
    b = Action("handover_r2h", ("r1",), "cup", human="A")
    steps = (
        PlanStep(0.0, 1 / 3, (a,), (Binding("r1", "x", "solo"),)),
        PlanStep(1 / 3, 2.1 + 1e-12, (b,)),
    )
    return PlanResult(
        PlanStatus.SOLVED, steps, 1 / 3 + 2.1 + 1e-12, SearchStats(expanded=17, generated=40)
    )


def test_a_plan_travels_exactly() -> None:
    w = WirePlan("ab" * 16, 0.0021, _result())
    back = WirePlan.from_dict(w.to_dict())
    assert back.digest == w.digest and back.wall_s == w.wall_s
    r, b = w.result, back.result
    assert b.steps == r.steps and b.status is r.status and b.reason == r.reason
    assert b.makespan is not None and b.makespan.hex() == (r.makespan or 0.0).hex()
    assert [(s.start.hex(), s.duration.hex()) for s in b.steps] == [
        (s.start.hex(), s.duration.hex()) for s in r.steps
    ]
    assert (b.stats.expanded, b.stats.generated) == (17, 40)
    none = WirePlan("cd" * 16, 0.001, PlanResult(PlanStatus.INFEASIBLE, reason="no"))
    assert WirePlan.from_dict(none.to_dict()).result == none.result


@pytest.mark.parametrize(
    ("change", "says"),
    [
        ({"status": "maybe"}, "'maybe' is not a valid PlanStatus"),
        ({"expanded": -1}, "expanded must be an integer >= 0"),
        ({"wall": "x"}, "wall must be"),
        ({"steps": [{"start": 0}]}, "'duration' missing"),
        ({"id": 3}, "id and reason must be strings"),
    ],
)
def test_a_malformed_plan_is_one_error_line(change: dict[str, Any], says: str) -> None:
    d = {**WirePlan("ab" * 16, 0.002, _result()).to_dict(), **change}
    with pytest.raises(BusError, match="malformed background plan on the bus") as got:
        WirePlan.from_dict(d)
    assert says in str(got.value) and "\n" not in str(got.value)
