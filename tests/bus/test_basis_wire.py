"""The executor's basis on the wire: a typed record, round-tripped exactly, checked field by
field (a bad payload is one clear error), and the node's copy plans what the executor's does."""

from __future__ import annotations

import json
from typing import Any

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.bus.codec import WireBasis, WireCheck
from hltl.bus.driver import wire_basis
from hltl.bus.node import FORESEE_TIMEOUT, _Basis
from hltl.errors import BusError
from hltl.execution.drivers import Basis
from hltl.execution.executor import ExactPlanner, ExecutorConfig
from hltl.grounding import make_grounder
from hltl.perception.predict import ConstantVelocityPredictor
from hltl.sim.dynamic import make_trial
from hltl.sim.instruct import ground_all
from hltl.spec.hierarchy import HSpec, spec_to_dict
from hltl.spec.monitor import HierarchyMonitor

positive = st.floats(min_value=1e-6, max_value=1e6, allow_nan=False)
non_negative = st.floats(min_value=0.0, max_value=1e6, allow_nan=False)
checks = st.none() | st.builds(
    WireCheck, non_negative, positive, st.none() | st.tuples(positive, non_negative)
)


@settings(max_examples=60, deadline=None)
@given(
    st.integers(1, 10**6),
    st.lists(st.integers(-1, 10**6), min_size=1, max_size=8),
    st.text(min_size=1, max_size=12),
    positive,
    checks,
    st.booleans(),
)
def test_the_basis_round_trips_exactly(
    version: int, q: list[int], algorithm: str, timeout: float, check: Any, with_spec: bool
) -> None:
    spec = {"formulas": [{"name": "f", "ltl": "F a"}]}
    w = WireBasis(version, tuple(q), algorithm, timeout, check, spec)
    back = WireBasis.from_dict(json.loads(json.dumps(w.to_dict(with_spec))))
    assert back == (w if with_spec else WireBasis(version, tuple(q), algorithm, timeout, check))


def _grounded(config: str = "4-2", index: int = 1) -> tuple[Any, HSpec]:
    trial = make_trial(config, index)
    (u,) = ground_all(make_grounder("offline"), [trial.instruction], trial.scene, None)
    assert u.spec is not None
    return trial.scene, u.spec


def test_the_node_holds_the_executors_basis() -> None:
    """What the executor sends (its spec, monitor state, planner and check) is what the node
    plans and checks with; the spec goes once, later bases name its version."""
    _, spec = _grounded()
    monitor = HierarchyMonitor(spec)
    q = monitor.initial
    cfg, pred = ExecutorConfig(intrusion_speed=0.3), ConstantVelocityPredictor(window=0.7)
    planner = ExactPlanner(timeout=0.02)
    w = wire_basis(Basis(spec, 1, q, planner, cfg, pred))
    assert w is not None
    held = _Basis.parse(json.loads(json.dumps(w.to_dict())), None)
    assert spec_to_dict(held.basis.spec) == spec_to_dict(spec)
    assert held.basis.version == 1 and held.basis.q == tuple(q)
    assert isinstance(held.basis.planner, ExactPlanner)
    assert held.basis.planner.algorithm == planner.algorithm
    assert held.basis.planner.timeout == min(planner.timeout, FORESEE_TIMEOUT)
    assert held.check is not None
    assert (held.check.intrusion_speed, held.check.predict_dt) == (0.3, cfg.predict_dt)
    assert held.forecast == (0.7, pred.min_speed)
    assert held.horizon is None  # (no background plans asked for)
    wb = wire_basis(Basis(spec, 1, q, planner, cfg, pred), background=True)
    assert wb is not None and wb.check is not None and wb.check.horizon == cfg.horizon
    assert _Basis.parse(json.loads(json.dumps(wb.to_dict())), None).horizon == cfg.horizon
    # a later basis of the same spec names it only; the node keeps the one it has
    later = _Basis.parse(json.loads(json.dumps(w.to_dict(with_spec=False))), held)
    assert later.basis.spec is held.basis.spec and later.monitor is held.monitor
    # without intrusion checks (no forecaster), the node does not forecast either
    w2 = wire_basis(Basis(spec, 1, q, planner, cfg, None))
    assert w2 is not None and w2.check == WireCheck(0.3, cfg.predict_dt, None)


def test_a_planner_the_node_cannot_run_sends_no_basis() -> None:
    _, spec = _grounded()
    q = HierarchyMonitor(spec).initial
    assert wire_basis(Basis(spec, 1, q, object())) is None
    assert wire_basis(Basis(spec, 1, q, lambda *a, **k: None)) is None


def _good() -> dict[str, Any]:
    return {
        "version": 2,
        "q": [0, 1],
        "planner": {"algorithm": "astar", "timeout": 1.0},
        "check": {
            "intrusion_speed": 0.0,
            "predict_dt": 0.1,
            "forecast": {"window": 1.0, "min_speed": 0.05},
        },
    }


def _without(key: str) -> dict[str, Any]:
    d = _good()
    del d[key]
    return d


def _with(path: tuple[str, ...], value: Any) -> dict[str, Any]:
    d = _good()
    at = d
    for k in path[:-1]:
        at = at[k]
    at[path[-1]] = value
    return d


@pytest.mark.parametrize(
    ("payload", "says"),
    [
        ([1, 2], "expected a JSON object"),
        (_without("version"), "'version' missing"),
        (_without("planner"), "'planner' missing"),
        (_with(("version",), 0), "version must be an integer >= 1"),
        (_with(("version",), True), "version must be an integer"),
        (_with(("version",), "2"), "version must be an integer"),
        (_with(("q",), []), "q must be a non-empty list"),
        (_with(("q",), [0, -2]), "a monitor state must be an integer >= -1"),
        (_with(("q",), [0, 1.5]), "a monitor state must be an integer"),
        (_with(("planner",), "astar"), "planner must be an object"),
        (_with(("planner", "algorithm"), ""), "planner algorithm must be a name"),
        (_with(("planner", "timeout"), 0), "planner timeout must be a finite positive"),
        (_with(("planner", "timeout"), float("inf")), "planner timeout must be a finite"),
        (_with(("check",), 3), "check must be an object"),
        (_with(("check", "predict_dt"), -0.1), "predict_dt must be a finite positive"),
        (_with(("check", "intrusion_speed"), None), "intrusion_speed must be a number"),
        (_with(("check", "forecast"), [1, 2]), "forecast must be an object"),
        (_with(("check", "forecast", "window"), 0), "forecast window must be a finite positive"),
        (_with(("spec",), "F a"), "spec must be an object"),
    ],
)
def test_a_malformed_basis_is_one_clear_error(payload: Any, says: str) -> None:
    with pytest.raises(BusError) as err:
        WireBasis.from_dict(payload)
    msg = str(err.value)
    assert msg.startswith("malformed basis on the bus: ") and says in msg
    assert "\n" not in msg


def test_the_node_refuses_a_basis_it_cannot_hold() -> None:
    """A basis naming a spec the node never got, a spec that does not parse, or monitor states
    that do not fit the spec: each a BusError (the node then drops the basis and uses the
    executor's hints only)."""
    _, spec = _grounded()
    q = list(HierarchyMonitor(spec).initial)
    with pytest.raises(BusError, match="spec version 2 never sent"):
        _Basis.parse(_good(), None)
    with pytest.raises(BusError, match="its spec"):
        _Basis.parse({**_good(), "spec": {"nonsense": 1}}, None)
    with pytest.raises(BusError, match="monitor states for"):
        _Basis.parse({**_good(), "q": [*q, 0], "spec": spec_to_dict(spec)}, None)
