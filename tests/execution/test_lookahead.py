"""The executor tells a driver that takes hints its plan's next steps, and nothing else changes."""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import Any, ClassVar

import pytest

from hltl.execution.drivers import (
    Basis,
    Briefed,
    Briefing,
    Expected,
    Foresight,
    Lookahead,
    RobotDriver,
)
from hltl.grounding import make_grounder
from hltl.sim import scenarios
from hltl.sim.dynamic import make_trial
from hltl.sim.episode import run_episode
from hltl.sim.events import load_events
from hltl.sim.simulator import Simulator
from hltl.spec.hierarchy import spec_from_dict
from hltl.spec.monitor import HierarchyMonitor

EVENTS = Path(__file__).resolve().parents[2] / "examples" / "events"


class _Hinted(Simulator):
    """The discrete simulator, also taking the executor's hints (and ignoring them)."""

    made: ClassVar[list[_Hinted]] = []

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        self.hints: list[tuple[float, tuple[Expected, ...]]] = []
        _Hinted.made.append(self)

    def expect(self, steps: Sequence[Expected]) -> None:
        self.hints.append((self.now, tuple(steps)))


def _no_wall_clock(records: Sequence[Any]) -> list[dict[str, Any]]:
    return [{k: v for k, v in r.to_json().items() if not k.endswith("_ms")} for r in records]


def test_the_in_process_simulator_takes_no_hints() -> None:
    sim, hinted = Simulator.__new__(Simulator), _Hinted.__new__(_Hinted)
    assert isinstance(sim, RobotDriver) and not isinstance(sim, Lookahead)
    assert isinstance(hinted, Lookahead)


def _episodes() -> list[tuple[str, Any, dict[str, Any]]]:
    sc = scenarios.get("fig1")
    fig1 = {
        "instruction": sc.instruction,
        "events": load_events(EVENTS / "fig1.yaml", sc.scene),
        "seed": 3,
    }
    out = [("fig1", sc.scene, fig1)]
    for config, index in (("4-1", 0), ("4-4-square", 0), ("2-1", 1)):
        tr = make_trial(config, index)
        kw = {"instruction": tr.instruction, "events": tr.events, "seed": tr.seed}
        out.append((f"{config}#{index}", tr.scene, kw))
    return out


@pytest.mark.parametrize(("name", "scene", "kw"), _episodes(), ids=[e[0] for e in _episodes()])
def test_hints_are_the_plans_next_steps_and_change_nothing(
    name: str, scene: Any, kw: dict[str, Any]
) -> None:
    """A driver that takes hints gets, at each dispatch, the rest of the plan the step came
    from (with when the plan expects each step to start); the episode is the one a driver
    without hints gives, record for record."""
    plain = run_episode(scene, **kw)
    _Hinted.made.clear()
    hinted = run_episode(scene, simulator=_Hinted, **kw)
    assert _no_wall_clock(hinted.records) == _no_wall_clock(plain.records)
    (sim,) = _Hinted.made
    dispatches = [r for r in plain.records if r.type == "dispatch"]
    assert [t for t, _ in sim.hints] == pytest.approx([r.t for r in dispatches], abs=1e-6)
    # each hint is the plan's steps after the one dispatched, as the last plan logged says
    for (t, hint), d in zip(sim.hints, dispatches, strict=True):
        plans = [
            r
            for r in plain.records
            if r.type == "replan" and r.t <= d.t and r.status == "solved" and r.steps
        ]
        steps = plans[-1].steps
        assert steps[0]["actions"] == d.planned
        assert [[a.to_dict() for a in e.actions] for e in hint] == [s["actions"] for s in steps[1:]]
        at = t + steps[0]["duration"]
        for e, s in zip(hint, steps[1:], strict=True):
            assert e.at == pytest.approx(at, abs=1e-5)
            at += s["duration"]


class _Foreseeing(Simulator):
    """The discrete simulator, also taking the executor's basis (and ignoring it)."""

    made: ClassVar[list[_Foreseeing]] = []

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        self.bases: list[tuple[float, Basis]] = []
        _Foreseeing.made.append(self)

    def foresee(self, basis: Basis) -> None:
        self.bases.append((self.now, basis))


@pytest.mark.parametrize(("name", "scene", "kw"), _episodes(), ids=[e[0] for e in _episodes()])
def test_the_basis_is_the_state_after_the_step_and_changes_nothing(
    name: str, scene: Any, kw: dict[str, Any]
) -> None:
    """A driver that foresees gets the executor's basis when its spec is set and at each
    dispatch: the monitor state it names is the one the step's end reaches when the step ends
    as planned (the next monitor record's formulas done and acceptance), its spec's version
    counts the groundings, and the episode is the one a driver without it gives."""
    plain = run_episode(scene, **kw)
    _Foreseeing.made.clear()
    run = run_episode(scene, simulator=_Foreseeing, **kw)
    assert _no_wall_clock(run.records) == _no_wall_clock(plain.records)
    (sim,) = _Foreseeing.made
    assert isinstance(sim, Foresight)
    groundings = [r for r in plain.records if r.type == "grounding" and r.spec is not None]
    assert sorted({b.version for _, b in sim.bases}) == list(range(1, len(groundings) + 1))
    dispatches = [r for r in plain.records if r.type == "dispatch"]
    assert len(sim.bases) == len(dispatches) + len(groundings)
    records = list(plain.records)
    checked = 0
    for t, basis in sim.bases:
        i = next(
            (k for k, r in enumerate(records) if r.type == "dispatch" and abs(r.t - t) < 1e-9),
            None,
        )
        if i is None:
            continue  # (a grounding's basis)
        after = records[i + 1 :]
        mon = next(r for r in after if r.type == "monitor")
        between = {r.type for r in after[: after.index(mon)]}
        if between & {"action_failed", "action_halted", "grounding"}:
            continue  # (not ended as planned, or under another spec)
        monitor = HierarchyMonitor(basis.spec)
        assert sorted(monitor.done(basis.q)) == sorted(mon.done)
        assert monitor.accepted(basis.q) == mon.accepted
        checked += 1
    assert checked > 0


class _Briefed(_Foreseeing):
    """The discrete simulator, also taking the executor's briefing (and ignoring it)."""

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        self.briefings: list[tuple[int, Briefing]] = []

    def brief(self, briefing: Briefing) -> None:
        self.briefings.append((len(self.bases), briefing))


@pytest.mark.parametrize(
    ("name", "scene", "kw"), _episodes()[:2], ids=[e[0] for e in _episodes()[:2]]
)
def test_the_briefing_is_the_instruction_before_any_basis_and_changes_nothing(
    name: str, scene: Any, kw: dict[str, Any]
) -> None:
    """A driver that takes briefings is told the first instruction once, before the first
    basis, with the planner and checks the executor plans and checks with; the episode is the
    one a driver without it gives. Given a spec, or a grounder of its own, none is sent."""
    plain = run_episode(scene, **kw)
    _Foreseeing.made.clear()
    run = run_episode(scene, simulator=_Briefed, **kw)
    assert _no_wall_clock(run.records) == _no_wall_clock(plain.records)
    (sim,) = _Foreseeing.made
    assert isinstance(sim, _Briefed) and isinstance(sim, Briefed)
    ((before, b),) = sim.briefings
    assert before == 0 and b.instruction == kw["instruction"]
    (_, first) = sim.bases[0]
    assert (b.planner, b.config, b.predictor) == (first.planner, first.config, first.predictor)
    _Foreseeing.made.clear()
    run_episode(scene, simulator=_Briefed, grounder=make_grounder("offline"), **kw)
    spec = next(r for r in plain.records if r.type == "grounding").spec
    given = {k: v for k, v in kw.items() if k != "instruction"}
    run_episode(scene, simulator=_Briefed, spec=spec_from_dict(spec), **given)
    assert [s.briefings for s in _Foreseeing.made] == [[], []]  # type: ignore[attr-defined]
