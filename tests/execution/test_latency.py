"""Computation charged where it occurs (hltl.execution.latency) and anticipatory execution."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.bench.latency import DEFAULT_MODEL, Samples, fit
from hltl.errors import HltlError
from hltl.execution.executor import ExecutorConfig
from hltl.execution.latency import (
    LatencyModel,
    load_latency_model,
    planner_charge,
    takeover_charge,
)
from hltl.grounding.offline import OfflineGrounder
from hltl.perception.predict import make_predictor
from hltl.sim.dynamic import make_trial
from hltl.sim.episode import Episode, EpisodeConfig, run_episode
from hltl.sim.invariants import check_invariants

MODEL = LatencyModel(planner_fixed_s=0.3, planner_per_node_s=0.01, grounding_s=0.25)


def test_disruption_replans_pay_in_full_routine_ones_only_beyond_the_step() -> None:
    assert planner_charge(MODEL, "goal", 10, 9.0, since_step=2.0) == (
        pytest.approx(0.4),
        "critical",
    )
    assert planner_charge(MODEL, "context+progress", 0, 0.0, 5.0)[1] == "critical"
    # the step ran 0.1 s: the suffix computed alongside it still needs 0.3 s more
    assert planner_charge(MODEL, "progress", 10, 0.0, since_step=0.1) == (
        pytest.approx(0.3),
        "pipelined",
    )
    assert planner_charge(MODEL, "progress", 10, 0.0, since_step=2.0) == (0.0, "pipelined")
    # no step ran before: nothing to overlap with
    assert planner_charge(MODEL, "progress", 0, 0.0, since_step=None)[1] == "critical"
    assert takeover_charge(MODEL, 0, 0.0, since=0.1) == pytest.approx(0.2)
    assert takeover_charge(MODEL, 0, 0.0, since=1.0) == 0.0


def test_measured_mode_charges_the_wall_clock_time() -> None:
    m = LatencyModel(measured=True, planner_fixed_s=5.0, scale=2.0)
    assert m.planner(1000, 0.004) == pytest.approx(0.008)
    assert m.grounding(0.5) == pytest.approx(1.0)
    assert "measured" in m.describe()


@settings(max_examples=60, deadline=None)
@given(
    a=st.floats(0, 1),
    b=st.floats(0, 0.01),
    expanded=st.integers(0, 10_000),
    since=st.one_of(st.none(), st.floats(0, 10)),
    trigger=st.sampled_from(["initial", "progress", "goal", "context", "halt:intrusion"]),
)
def test_a_charge_is_never_more_than_the_call_and_pipelining_only_saves(
    a: float, b: float, expanded: int, since: float | None, trigger: str
) -> None:
    m = LatencyModel(planner_fixed_s=a, planner_per_node_s=b)
    full = a + b * expanded
    charge, basis = planner_charge(m, trigger, expanded, 0.0, since)
    assert 0.0 <= charge <= full + 1e-12
    if basis == "pipelined":
        assert trigger == "progress" and since is not None
        assert charge == pytest.approx(max(0.0, full - since))
    else:
        assert charge == pytest.approx(full)


def test_bad_models_are_refused(tmp_path: Path) -> None:
    with pytest.raises(ValueError, match="grounding_s"):
        LatencyModel(grounding_s=-1.0)
    with pytest.raises(ValueError, match="scale"):
        LatencyModel(scale=float("nan"))
    bad = tmp_path / "m.json"
    for text, match in (
        ("{", "cannot read"),
        ("[]", "'model'"),
        ('{"model": {"planner_fixed_s": 1, "warp": 2}}', "unknown keys"),
        ('{"model": {"planner_fixed_s": -1}}', "planner_fixed_s"),
    ):
        bad.write_text(text)
        with pytest.raises(HltlError, match=match):
            load_latency_model(bad)
    with pytest.raises(HltlError, match="cannot read"):
        load_latency_model(tmp_path / "missing.json")


def test_the_fit_recovers_a_line_and_drops_stalled_calls() -> None:
    pts = tuple((n, 0.002 + 0.0005 * n) for n in range(0, 40, 3))
    stalled = ((5, 0.9), (7, 1.3))  # calls another process held up
    f = fit([Samples(pts + stalled, (0.01, 0.03, 0.02))], "test")
    assert f.model.planner_fixed_s == pytest.approx(0.002, abs=1e-9)
    assert f.model.planner_per_node_s == pytest.approx(0.0005, abs=1e-9)
    assert f.outliers == 2 and f.r2 == pytest.approx(1.0)
    assert f.model.grounding_s == pytest.approx(0.02)
    assert f.planner_calls == len(pts) + 2
    with pytest.raises(ValueError, match="no planner call"):
        fit([Samples((), ())], "test")


def test_the_shipped_model_names_its_measurement() -> None:
    data = json.loads(DEFAULT_MODEL.read_text())
    m = load_latency_model(DEFAULT_MODEL)
    assert m.source.startswith("`hltl bench latency")
    assert data["measurement"]["planner_calls"] > 100
    assert m.planner_fixed_s + m.planner_per_node_s > 0 and not m.measured


def _episode(config: str, index: int, **executor: Any) -> Episode:
    trial = make_trial(config, index)
    ep = run_episode(
        trial.scene,
        instruction=trial.instruction,
        events=trial.events,
        seed=trial.seed,
        config=EpisodeConfig(executor=ExecutorConfig(**executor)),
        grounder=OfflineGrounder(),
        predictor=make_predictor("goal", trial.scene),
    )
    assert check_invariants(ep.records) == []
    return ep


def test_charges_are_logged_and_delay_the_next_dispatch() -> None:
    ep = _episode("2-2", 2, latency=MODEL)
    assert ep.success
    replans = [r for r in ep.records if r.type == "replan"]
    groundings = [r for r in ep.records if r.type == "grounding"]
    assert {r.charge for r in replans} >= {"critical", "pipelined"}
    assert all(g.charged_s == pytest.approx(0.25) for g in groundings)
    # the routine replans overlapped a step of at least 0.5 s: nothing left to pay
    assert all(r.charged_s == 0.0 for r in replans if r.charge == "pipelined")
    dispatches = [r.t for r in ep.records if r.type == "dispatch"]
    for r in replans:
        if r.charge == "critical" and r.status == "solved":
            later = [t for t in dispatches if t >= r.t]
            assert later and later[0] >= r.t + r.charged_s - 1e-9
    # the same trial charged nothing is faster by at least the first (initial) charge
    free = _episode("2-2", 2)
    assert free.metrics.time_cost is not None and ep.metrics.time_cost is not None
    assert ep.metrics.time_cost >= free.metrics.time_cost + 0.25 + 0.3 - 1e-9


def test_anticipation_relays_toward_the_forecast_and_saves_time() -> None:
    # 2-4-line#2: a recipient walks along the line; the relay toward the arm that will serve
    # them starts before they get there
    plain = _episode("2-4-line", 2)
    ahead = _episode("2-4-line", 2, anticipate=True)
    assert plain.success and ahead.success
    antic = [r for r in ahead.records if r.type == "anticipate"]
    assert antic and not [r for r in plain.records if r.type == "anticipate"]
    for r in antic:
        dispatch = next(d for d in ahead.records if d.type == "dispatch" and d.t == r.t)
        assert dispatch.actions == r.actions
    assert ahead.metrics.time_cost is not None and plain.metrics.time_cost is not None
    assert ahead.metrics.time_cost < plain.metrics.time_cost - 0.5


@pytest.mark.parametrize("votes", [0.6, 1.0])
def test_anticipation_waits_for_a_confident_forecast(votes: float) -> None:
    """The gate: an anticipatory dispatch happens only when at least ``anticipate_votes`` of
    every moving person's forecast samples agree on the label; a stricter gate dispatches no
    earlier (and on 2-4-line#2 later: the relay waits until the whole horizon agrees)."""
    ep = _episode("2-4-line", 2, anticipate=True, anticipate_votes=votes)
    antic = [r for r in ep.records if r.type == "anticipate"]
    assert antic
    for r in antic:
        for forecast in r.humans.values():
            assert forecast["votes"] >= votes * forecast["samples"]
    loose = _episode("2-4-line", 2, anticipate=True, anticipate_votes=0.6)
    first = min(r.t for r in loose.records if r.type == "anticipate")
    assert antic[0].t >= first
    if votes == 1.0:
        assert antic[0].t > first


def test_anticipation_needs_prediction_and_valid_votes() -> None:
    with pytest.raises(ValueError, match="anticipate_votes"):
        ExecutorConfig(anticipate_votes=1.5)
    ep = _episode("2-4-line", 2, anticipate=True, predict=False)
    assert not [r for r in ep.records if r.type == "anticipate"]


def test_motion_planning_is_added_to_the_call_and_pipelined_with_it() -> None:
    # 0.3 + 0.01·10 for the planner, 0.5 for the first step's robot-to-robot hand-over
    assert planner_charge(MODEL, "goal", 10, 0.0, 2.0, motion_s=0.5) == (
        pytest.approx(0.9),
        "critical",
    )
    assert planner_charge(MODEL, "progress", 10, 0.0, 0.7, motion_s=0.5) == (
        pytest.approx(0.2),
        "pipelined",
    )
    assert takeover_charge(MODEL, 0, 0.0, since=0.5, motion_s=0.5) == pytest.approx(0.3)
    with pytest.raises(ValueError, match="r2r_motion_s"):
        ExecutorConfig(r2r_motion_s=-1.0)


def test_first_step_robot_handovers_pay_their_motion_planning() -> None:
    plain = _episode("2-2", 2, latency=MODEL)
    motion = _episode("2-2", 2, latency=MODEL, r2r_motion_s=0.5)
    charged = 0
    for r in motion.records:
        if r.type != "replan" or r.source != "planner":
            continue
        first = r.steps[0]["actions"] if r.steps else []
        n = sum(a["skill"] == "handover_r2r" for a in first)
        if r.charge == "critical":
            assert r.charged_s == pytest.approx(0.3 + 0.01 * r.expanded + 0.5 * n, abs=1e-6)
        charged += n * (r.charged_s > 0)
    assert charged >= 1  # this trial hands over between robots after a short step
    assert motion.metrics.time_cost is not None and plain.metrics.time_cost is not None
    assert motion.metrics.time_cost > plain.metrics.time_cost
