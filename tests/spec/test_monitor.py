"""Hierarchy monitors: one-shot firing, bottom-up propagation in one step, against a reference."""

from __future__ import annotations

import random
from pathlib import Path

import pytest

from hltl.spec.automata import AutomatonCache
from hltl.spec.hierarchy import HSpec, load_spec, spec_from_dict
from hltl.spec.monitor import DONE, HierarchyMonitor
from hltl.spec.semantics import evaluate
from hltl.spec.syntax import Atom

SPECS = Path(__file__).parents[2] / "examples" / "specs"
BOTTLE_A = Atom("delivered", ("bottle", "A"))
CHIPS_B = Atom("delivered", ("chips", "B"))
BOTTLE_SHELF = Atom("placed", ("bottle", "shelf"))
CUP_SHELF = Atom("at", ("cup", "shelf"))
NOTHING = frozenset[Atom]()


def _spec(**formulas: str) -> HSpec:
    return spec_from_dict({"root": "p0", "formulas": formulas})


def _monitor(p0: str) -> HierarchyMonitor:
    spec = _spec(p0=p0, p100="F delivered(bottle, A)", p200="F delivered(chips, B)")
    return HierarchyMonitor(spec)


def test_fig1_one_delivery_at_a_time() -> None:
    mon = _monitor("F p100 & F p200")
    q0 = mon.initial
    assert mon.nodes == ("p0", "p100", "p200") and q0 == (0, 0, 0)
    q1 = mon.step(q0, {BOTTLE_A})
    assert mon.fired(q0, q1) == {"p100"} and mon.done(q1) == {"p100"}
    assert not mon.accepted(q1)
    q2 = mon.step(q1, {CHIPS_B})
    assert mon.fired(q1, q2) == {"p200", "p0"}
    assert mon.accepted(q2) and mon.done(q2) == {"p0", "p100", "p200"}
    assert q2 == (DONE, DONE, DONE)


def test_children_may_complete_in_the_same_step() -> None:
    mon = _monitor("F p100 & F p200")
    q = mon.step(mon.initial, {BOTTLE_A, CHIPS_B})
    assert mon.fired(mon.initial, q) == {"p0", "p100", "p200"} and mon.accepted(q)


def test_leaves_fire_once() -> None:
    mon = _monitor("F p100 & F p200")
    q1 = mon.step(mon.initial, {BOTTLE_A})
    q2 = mon.step(q1, {BOTTLE_A})
    assert mon.fired(q1, q2) == frozenset() and q2 == q1


@pytest.mark.parametrize(
    ("trace", "accepted"),
    [
        ([{BOTTLE_A}, {CHIPS_B}], True),
        ([{BOTTLE_A, CHIPS_B}], True),  # same step: non-strict order
        ([{CHIPS_B}, {BOTTLE_A}], False),
        ([{CHIPS_B}, {BOTTLE_A}, {CHIPS_B}, {BOTTLE_A}], False),  # one-shot: no second chance
        ([{BOTTLE_A}, NOTHING, NOTHING, {CHIPS_B}], True),
    ],
)
def test_ordered(trace: list[set[Atom]], accepted: bool) -> None:
    mon = _monitor("F (p100 & F p200)")
    assert mon.accepted(mon.run(trace)) is accepted


def test_a_node_accepting_initially_fires_after_the_first_step() -> None:
    mon = HierarchyMonitor(_spec(p0="F p100", p100="G !picked(cup)"))
    picked = Atom("picked", ("cup",))
    assert mon.done(mon.initial) == frozenset()
    q = mon.step(mon.initial, set())
    assert mon.accepted(q)
    # once done it stays done, whatever comes later
    assert mon.accepted(mon.step(q, {picked}))
    # picked in the first step: the leaf can never fire
    dead = mon.step(mon.initial, {picked})
    assert not mon.accepted(mon.run([set()] * 3, dead))


def test_events_propagate_bottom_up_within_one_step() -> None:
    mon = HierarchyMonitor(load_spec(SPECS / "three_level.yaml"))
    q1 = mon.step(mon.initial, {BOTTLE_SHELF})
    assert mon.fired(mon.initial, q1) == {"p110"}
    q2 = mon.step(q1, {BOTTLE_A, CHIPS_B})
    assert mon.fired(q1, q2) == {"p120", "p100", "p200", "p0"}
    assert mon.accepted(q2)


def test_atoms_in_a_composite() -> None:
    mon = HierarchyMonitor(_spec(p0="F p100 & G !at(cup, shelf)", p100="F delivered(bottle, A)"))
    assert mon.accepted(mon.run([set(), {BOTTLE_A}]))
    assert not mon.accepted(mon.run([{CUP_SHELF}, {BOTTLE_A}]))
    assert mon.atoms == {BOTTLE_A, CUP_SHELF}


def test_unrelated_atoms_are_ignored() -> None:
    mon = _monitor("F p100 & F p200")
    assert mon.step(mon.initial, {Atom("picked", ("cup",)), Atom("p100")}) == mon.initial


def test_api_details() -> None:
    cache = AutomatonCache()
    mon = HierarchyMonitor(load_spec(SPECS / "fig1.yaml", cache=cache), cache)
    assert cache.hits >= 3  # the monitor reused the validation's DFAs
    assert mon.leaf_atoms == {"p100": {BOTTLE_A}, "p200": {CHIPS_B}}
    assert set(mon.dfas) == {"p0", "p100", "p200"}
    masks = mon.masks({BOTTLE_A})
    assert masks == [0, 1, 0]
    q = mon.step_masks(mon.initial, masks)
    assert q == mon.step(mon.initial, {BOTTLE_A}) and masks == [0, 1, 0]
    assert mon.state_of(q, "p100") is None and mon.state_of(q, "p0") == 1
    assert hash(q) == hash(tuple(q)) and isinstance(q, tuple)


def _reference_firing(spec: HSpec, trace: list[frozenset[Atom]]) -> dict[str, int | None]:
    """When each node fires, straight from the definition (docs/model.md), via ``evaluate``."""
    fired: dict[str, int | None] = {}
    for name in reversed(spec.names):  # children before parents
        kids = spec.children[name]
        symbols = [
            frozenset(Atom(c) for c in kids if fired[c] == t)
            | frozenset(a for a in trace[t] if a.is_predicate)
            for t in range(len(trace))
        ]
        fired[name] = next(
            (t for t in range(len(trace)) if evaluate(spec.formula(name), symbols[: t + 1])), None
        )
    return fired


@pytest.mark.parametrize(
    "name", ["fig1", "ordered", "either", "three_level", "office_1", "office_3"]
)
def test_monitor_matches_the_definition_on_random_traces(name: str) -> None:
    spec = load_spec(SPECS / f"{name}.yaml")
    mon = HierarchyMonitor(spec)
    atoms = sorted(mon.atoms)
    rng = random.Random(name)
    seen_accept = 0
    for _ in range(150):
        # sparse symbols, like a plan's: most atoms false in most steps
        trace = [
            frozenset(a for a in atoms if rng.random() < 0.25) for _ in range(rng.randint(1, 6))
        ]
        reference = _reference_firing(spec, trace)
        q = mon.initial
        for t, symbol in enumerate(trace):
            q_next = mon.step(q, symbol)
            assert mon.fired(q, q_next) == {n for n, s in reference.items() if s == t}
            q = q_next
        seen_accept += mon.accepted(q)
        assert mon.accepted(q) == (reference[spec.root] is not None)
    assert 0 < seen_accept < 150
