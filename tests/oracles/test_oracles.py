"""The oracles themselves, on hand-checked cases, and against each other on random instances."""

from __future__ import annotations

import copy
from pathlib import Path
from typing import Any

import pytest
import yaml

from hltl.spec.hierarchy import spec_from_dict
from hltl.world.scene import Robot, scene_from_dict

from .brute_force import SearchBudgetExceeded, optimal_makespan, optimal_plan
from .cpsat import UnsupportedSpec, cpsat_makespan, cpsat_solve
from .model import can_meet, human_inside, reaches, rendezvous_blocked
from .random_instances import random_instance
from .validator import check_plan, validate_plan

TWO_ARMS = Path(__file__).resolve().parents[2] / "examples" / "scenes" / "two_arms.yaml"
FIG1 = {
    "root": "p0",
    "formulas": {
        "p0": "F p100 & F p200",
        "p100": "F delivered(bottle, A)",
        "p200": "F delivered(chips, B)",
    },
}


def two_arms(**changes: Any) -> dict[str, Any]:
    """The Fig. 1 scene as a dict; ``humans={"A": [x, y, z]}`` moves people, other keys replace."""
    data: dict[str, Any] = yaml.safe_load(TWO_ARMS.read_text())
    for hid, pos in changes.pop("humans", {}).items():
        next(h for h in data["humans"] if h["id"] == hid)["position"] = pos
    for oid, pos in changes.pop("objects", {}).items():
        next(o for o in data["objects"] if o["id"] == oid)["position"] = pos
    data.update(changes)
    return data


def spec(root: str, **leaves: str) -> Any:
    return spec_from_dict({"root": "p0", "formulas": {"p0": root, **leaves}})


def both_oracles(scene_data: dict[str, Any], spec_obj: Any) -> float | None:
    """Brute force and CP-SAT agree, and the validator accepts both their plans."""
    scene = scene_from_dict(scene_data)
    plan = optimal_plan(scene, spec_obj)
    result = cpsat_solve(scene, spec_obj)
    if plan is None or result.makespan is None:
        assert plan is None and result.makespan is None, (plan, result.makespan)
        return None
    assert result.makespan == pytest.approx(plan["makespan"], abs=1e-9)
    check_plan(scene, spec_obj, plan)
    assert result.plan is not None
    check_plan(scene, spec_obj, result.plan)
    return float(plan["makespan"])


# -- geometry of docs/model.md --------------------------------------------------------------------


def test_geometry_thresholds() -> None:
    a = Robot("a", (0.0, 0.0, 0.0), 0.5)
    b = Robot("b", (1.0, 0.0, 0.0), 0.5)
    assert reaches(a, (0.5, 0.0, 0.0)) and not reaches(a, (0.5, 0.0, 0.01))  # inclusive, 3-D
    assert not can_meet(a, b)  # touching spheres do not overlap: strict
    assert can_meet(a, Robot("c", (0.99, 0.0, 0.0), 0.5)) and not can_meet(a, a)
    scene = scene_from_dict(two_arms())
    r1, r2 = scene.robots
    assert human_inside(r1, scene.human("A"), 0.3) and not human_inside(r2, scene.human("A"), 0.3)
    assert not rendezvous_blocked(scene, r1, r2)
    middle = scene_from_dict(two_arms(humans={"A": [0.6, 0.2, 0.0]}))
    assert rendezvous_blocked(middle, *middle.robots)
    # the person's height is ignored: only the horizontal distance counts
    tall = scene_from_dict(two_arms(humans={"A": [-0.5, 0.6, 5.0]}))
    assert human_inside(r1, tall.human("A"), 0.3)


# -- hand-computed optima on the Fig. 1 cell ------------------------------------------------------
# two_arms.yaml: r1 (reach 0.7) at x=0, r2 (reach 0.9) at x=1.2; they can meet (1.2 < 1.6). The
# bottle (0.45 m from r1) only r1 reaches, the chips (0.43 m from r2) only r2; Person A is in
# r1's workspace only (0.78 <= 1.0), Person B in r2's only (0.86 <= 1.2); the shelf (0.67 m from
# both) both reach. Durations: pick 0.5, place 0.5, r2r 0.6, r2h 0.5.


def test_fig1_straight_deliveries_run_in_parallel() -> None:
    # Each arm picks its object and hands it over, both at once: 0.5 + 0.5 = 1.0.
    assert both_oracles(two_arms(), spec_from_dict(FIG1)) == pytest.approx(1.0)


def test_non_strict_ordering_allows_the_same_step() -> None:
    # "First A the bottle, then B the chips": B may complete in the same step as A, so 1.0 still.
    ordered = spec("F (p100 & F p200)", **FIG1["formulas"] | {"p0": "F (p100 & F p200)"})
    assert both_oracles(two_arms(), ordered) == pytest.approx(1.0)


def test_relay_across_the_cell() -> None:
    # Bottle to B: r1 picks (0.5), hands to r2 (0.6), r2 hands to B (0.5) = 1.6.
    assert both_oracles(two_arms(), spec("F p100", p100="F delivered(bottle, B)")) == pytest.approx(
        1.6
    )


def test_person_between_the_arms_forces_the_shelf() -> None:
    # Person A stands at (0.6, 0.2), inside both workspaces: no r1→r2 handover. The bottle goes
    # over the shelf instead: pick 0.5, place 0.5, pick 0.5, hand to B 0.5 = 2.0.
    scene = two_arms(humans={"A": [0.6, 0.2, 0.0]})
    assert both_oracles(scene, spec("F p100", p100="F delivered(bottle, B)")) == pytest.approx(2.0)


def test_crossed_deliveries_swap_over_the_shelf() -> None:
    # A gets the chips, B the bottle: both objects must cross. Each needs pick, a transfer and a
    # hand-over, so >= 3 steps; a 3-step plan would need both transfers in step 2, impossible
    # (an r2r takes both arms). With the shelf, 4 steps of 0.5: both pick, both place on the
    # shelf, each picks the other's object, both hand over = 2.0. Any r2r instead needs a free
    # receiver, which with both arms busy costs more.
    crossed = spec("F p100 & F p200", p100="F delivered(chips, A)", p200="F delivered(bottle, B)")
    assert both_oracles(two_arms(), crossed) == pytest.approx(2.0)
    # Without the shelf, r1 is on both paths (receives the chips, picks and gives the bottle) and
    # never holds two things: pick chips, r2r, hand to A, pick bottle, r2r, hand to B, all in
    # sequence = 0.5 + 0.6 + 0.5 + 0.5 + 0.6 + 0.5 = 3.2.
    assert both_oracles(two_arms(surfaces=[]), crossed) == pytest.approx(3.2)


def test_either_or_takes_the_cheaper_branch() -> None:
    # Bottle to B needs a relay (1.6), chips to B does not (1.0): "either" costs 1.0.
    either = spec("F p100 | F p200", p100="F delivered(bottle, B)", p200="F delivered(chips, B)")
    assert both_oracles(two_arms(), either) == pytest.approx(1.0)


def test_placement_leaf() -> None:
    # Put the bottle on the shelf: pick 0.5 + place 0.5.
    assert both_oracles(two_arms(), spec("F p100", p100="F placed(bottle, shelf)")) == 1.0


def test_object_out_of_every_reach_is_infeasible() -> None:
    scene = two_arms(objects={"chips": [5.0, 5.0, 0.05]})
    assert both_oracles(scene, spec_from_dict(FIG1)) is None


def test_person_out_of_every_workspace_is_infeasible() -> None:
    scene = two_arms(humans={"B": [4.0, 4.0, 0.0]})
    assert both_oracles(scene, spec_from_dict(FIG1)) is None


def test_one_object_cannot_be_delivered_twice() -> None:
    twice = spec("F p100 & F p200", p100="F delivered(bottle, A)", p200="F delivered(bottle, B)")
    assert both_oracles(two_arms(), twice) is None


def test_brute_force_bounds() -> None:
    scene = scene_from_dict(two_arms())
    fig1 = spec_from_dict(FIG1)
    assert optimal_makespan(scene, fig1, max_cost=0.9) is None  # no plan costs <= 0.9
    assert optimal_makespan(scene, fig1, max_cost=1.0) == pytest.approx(1.0)
    with pytest.raises(SearchBudgetExceeded):
        optimal_makespan(scene, fig1, max_nodes=1)
    with pytest.raises(ValueError, match="fixed durations"):
        optimal_makespan(scene_from_dict({**two_arms(), "durations": None}), fig1)


def test_brute_force_handles_state_leaves_cpsat_does_not() -> None:
    # "r2 ends up holding the bottle": pick 0.5 + r2r 0.6; outside the CP-SAT class.
    holding = spec("F p100", p100="F holding(r2, bottle)")
    scene = scene_from_dict(two_arms())
    plan = optimal_plan(scene, holding)
    assert plan is not None and plan["makespan"] == pytest.approx(1.1)
    check_plan(scene, holding, plan)
    with pytest.raises(UnsupportedSpec):
        cpsat_makespan(scene, holding)
    with pytest.raises(UnsupportedSpec):
        cpsat_makespan(
            scene, spec("F p100 & p200", p100="F picked(bottle)", p200="F picked(chips)")
        )


def test_cpsat_fixed_horizon_is_the_best_plan_within_it() -> None:
    scene = scene_from_dict(two_arms())
    relay = spec("F p100", p100="F delivered(bottle, B)")
    assert cpsat_makespan(scene, relay, horizon_steps=2) is None  # needs 3 steps
    assert cpsat_makespan(scene, relay, horizon_steps=3) == pytest.approx(1.6)


# -- the validator rejects bad plans --------------------------------------------------------------


def act(skill: str, robots: list[str], obj: str, **target: str) -> dict[str, Any]:
    return {"skill": skill, "robots": robots, "object": obj, **target}


def plan_of(*steps: tuple[float, list[dict[str, Any]]], **extra: Any) -> dict[str, Any]:
    out, clock = [], 0.0
    for duration, actions in steps:
        out.append({"start": clock, "duration": duration, "actions": actions})
        clock += duration
    return {"status": "solved", "makespan": clock, "steps": out, **extra}


FIG1_PLAN = plan_of(
    (0.5, [act("pick", ["r1"], "bottle"), act("pick", ["r2"], "chips")]),
    (
        0.5,
        [
            act("handover_r2h", ["r1"], "bottle", human="A"),
            act("handover_r2h", ["r2"], "chips", human="B"),
        ],
    ),
)


def violations(
    plan: dict[str, Any], scene_data: dict[str, Any] | None = None, sp: Any = None
) -> str:
    scene = scene_from_dict(scene_data or two_arms())
    return "\n".join(validate_plan(scene, sp or spec_from_dict(FIG1), plan))


def test_validator_accepts_the_hand_made_fig1_plan() -> None:
    assert violations(FIG1_PLAN) == ""
    with_bindings = copy.deepcopy(FIG1_PLAN)
    for step in with_bindings["steps"]:
        step["bindings"] = {"r1": ["p100", "solo"], "r2": ["p200", "solo"]}
    assert violations(with_bindings) == ""


def test_validator_rejects_out_of_reach_pick() -> None:
    plan = copy.deepcopy(FIG1_PLAN)
    plan["steps"][0]["actions"][0]["robots"] = ["r2"]  # r2 picks the bottle, 1.62 m away
    plan["steps"][0]["actions"][1]["robots"] = ["r1"]
    text = violations(plan)
    assert "bottle at [-0.4, 0.2, 0.05] is out of r2's reach" in text
    assert "out of r1's reach" in text


def test_validator_rejects_two_robots_on_one_object() -> None:
    data = two_arms(objects={"chips": [0.6, -0.1, 0.05]})  # both arms reach the chips now
    plan = plan_of((0.5, [act("pick", ["r1"], "chips"), act("pick", ["r2"], "chips")]))
    assert "object 'chips' is used by two actions in one step" in violations(plan, data)


def test_validator_rejects_a_robot_doing_two_things() -> None:
    plan = plan_of((0.5, [act("pick", ["r1"], "bottle"), act("pick", ["r1"], "chips")]))
    assert "robot 'r1' runs two actions in one step" in violations(plan)


def test_validator_rejects_handover_next_to_a_person() -> None:
    data = two_arms(humans={"A": [0.6, 0.2, 0.0]})
    plan = plan_of(
        (0.5, [act("pick", ["r1"], "bottle")]),
        (0.6, [act("handover_r2r", ["r1", "r2"], "bottle")]),
        (0.5, [act("handover_r2h", ["r2"], "bottle", human="B")]),
    )
    relay = spec("F p100", p100="F delivered(bottle, B)")
    assert "rendezvous of r1 and r2 is blocked by a person" in violations(plan, data, relay)
    assert violations(plan, two_arms(), relay) == ""  # with A back in place it is fine


def test_validator_rejects_wrong_times() -> None:
    plan = copy.deepcopy(FIG1_PLAN)
    plan["makespan"] = 0.9
    assert "makespan is 0.9, but the durations sum to 1.0" in violations(plan)
    plan = copy.deepcopy(FIG1_PLAN)
    plan["steps"][1]["start"] = 0.6
    assert "step 1: starts at 0.6, expected 0.5" in violations(plan)
    plan = copy.deepcopy(FIG1_PLAN)
    plan["steps"][1]["duration"] = 0.4
    plan["makespan"] = 0.9
    assert "step 1: lasts 0.4, expected 0.5" in violations(plan)
    plan = plan_of((0.0, []), *[(s["duration"], s["actions"]) for s in FIG1_PLAN["steps"]])
    assert violations(plan) == ""  # an empty step of length 0 is allowed
    plan["steps"][0]["duration"] = 0.1
    assert "an empty step lasts 0" in violations(plan)


def test_validator_rejects_plans_that_do_not_accept() -> None:
    only_bottle = plan_of(
        (0.5, [act("pick", ["r1"], "bottle")]),
        (0.5, [act("handover_r2h", ["r1"], "bottle", human="A")]),
    )
    assert "root 'p0' never accepts" in violations(only_bottle)
    too_long = plan_of(
        *[(s["duration"], s["actions"]) for s in FIG1_PLAN["steps"]],
        (0.0, []),
    )
    assert "fires at step 1, but the plan goes on to step 2" in violations(too_long)
    assert "status is 'infeasible'" in violations({**FIG1_PLAN, "status": "infeasible"})


def test_validator_rejects_broken_preconditions() -> None:
    # r1 picks twice without a free hand; r2 hands chips it does not hold; A is out of r2's reach
    plan = plan_of(
        (0.5, [act("pick", ["r1"], "bottle")]),
        (0.5, [act("pick", ["r1"], "bottle"), act("handover_r2h", ["r2"], "chips", human="A")]),
    )
    text = violations(plan)
    assert "r1 is not free (holds bottle)" in text
    assert "bottle is not resting or on a surface (it is held by r1)" in text
    assert "r2 does not hold chips (it is resting)" in text
    assert "human A is not inside r2's workspace" in text
    place = plan_of(
        (0.5, [act("pick", ["r2"], "chips")]),
        (0.5, [act("place", ["r2"], "chips", surface="shelf")]),
    )
    far_shelf = two_arms(surfaces=[{"id": "shelf", "center": [3.0, 0.0, 0.0], "size": [0.3, 0.3]}])
    assert "surface shelf is out of r2's reach" in violations(place, far_shelf)


def test_validator_rejects_unknown_names_and_malformed_actions() -> None:
    plan = plan_of(
        (
            0.5,
            [
                act("fly", ["r1"], "bottle"),
                act("pick", ["r9"], "bottle"),
                act("pick", ["r1"], "teapot"),
                act("handover_r2h", ["r1"], "bottle", human="Z"),
                act("handover_r2r", ["r1", "r1"], "bottle"),
                act("pick", ["r1"], "bottle", human="A"),
            ],
        )
    )
    text = violations(plan)
    for needle in (
        "unknown skill 'fly'",
        "unknown robot 'r9'",
        "unknown object 'teapot'",
        "handover_r2h needs a known human, got 'Z'",
        "names the same robot twice",
        "pick takes no human",
    ):
        assert needle in text


def test_validator_checks_bindings() -> None:
    data = two_arms()
    relay = spec("F p100 & F p200", p100="F delivered(bottle, B)", p200="F delivered(chips, B)")
    good = plan_of(
        (0.5, [act("pick", ["r1"], "bottle")]),
        (0.6, [act("handover_r2r", ["r1", "r2"], "bottle")]),
        (0.5, [act("handover_r2h", ["r2"], "bottle", human="B")]),
        (0.5, [act("pick", ["r2"], "chips")]),
        (0.5, [act("handover_r2h", ["r2"], "chips", human="B")]),
    )
    roles = [
        {"r1": ["p100", "giver"]},
        {"r1": ["p100", "giver"], "r2": ["p100", "receiver"]},
        {"r2": ["p100", "receiver"]},
        {"r2": ["p200", "solo"]},
        {"r2": ["p200", "solo"]},
    ]
    for step, b in zip(good["steps"], roles, strict=True):
        step["bindings"] = b
    assert violations(good, data, relay) == ""
    bad = copy.deepcopy(good)
    bad["steps"][0]["bindings"] = {}
    bad["steps"][1]["bindings"] = {"r1": ["p100", "giver"], "r2": ["p200", "boss"]}
    bad["steps"][3]["bindings"] = {"r2": ["p100", "solo"]}
    bad["steps"][4]["bindings"] = {"r2": ["p0", "solo"]}
    text = violations(bad, data, relay)
    assert "step 0 bindings: r1 acts (pick(bottle) by r1) but is not bound" in text
    assert "r2 has role 'boss'" in text
    assert "giver r1 is bound to p100 but receiver r2 to p200" in text
    assert "r2 is bound to p100, already done at step 2" in text
    assert "r2 moves chips but its leaf p100 does not mention it" in text
    assert "bound to 'p0', which is not a leaf" in text
    solo = copy.deepcopy(good)
    solo["steps"][1]["bindings"] = {"r1": ["p100", "solo"], "r2": ["p100", "solo"]}
    assert "takes part in a handover with role 'solo'" in violations(solo, data, relay)


def test_check_plan_raises_with_every_violation() -> None:
    plan = copy.deepcopy(FIG1_PLAN)
    plan["makespan"] = 2.0
    plan["steps"][0]["actions"][0]["robots"] = ["r2"]
    with pytest.raises(AssertionError, match=r"(?s)out of r2's reach.*makespan is 2.0"):
        check_plan(scene_from_dict(two_arms()), spec_from_dict(FIG1), plan)


# -- random instances: brute force == CP-SAT, plans valid -----------------------------------------


def test_random_instances_are_deterministic_and_load() -> None:
    for seed in range(20):
        scene_data, spec_data = random_instance(seed)
        assert (scene_data, spec_data) == random_instance(seed)
        scene = scene_from_dict(scene_data)
        spec_from_dict(spec_data)
        assert 1 <= len(scene.robots) <= 3 and 1 <= len(scene.objects) <= 3
    assert random_instance(0) != random_instance(1)
    small = [random_instance(s, max_robots=1, max_objects=1)[0] for s in range(10)]
    assert all(len(d["robots"]) == 1 and len(d["objects"]) == 1 for d in small)


SEEDS = range(60)


def test_brute_force_equals_cpsat_on_random_instances() -> None:
    outcomes = {"infeasible": 0, "relay": 0, "ordering": 0, "solved": 0}
    for seed in SEEDS:
        scene_data, spec_data = random_instance(seed)
        sp = spec_from_dict(spec_data)
        try:
            best = both_oracles(scene_data, sp)
        except AssertionError as exc:
            raise AssertionError(f"seed {seed}: {exc}") from None
        if best is None:
            outcomes["infeasible"] += 1
            continue
        outcomes["solved"] += 1
        plan = optimal_plan(scene_from_dict(scene_data), sp)
        assert plan is not None
        if any(a["skill"] == "handover_r2r" for s in plan["steps"] for a in s["actions"]):
            outcomes["relay"] += 1
        if any("& F" in f for f in spec_data["formulas"].values()):
            outcomes["ordering"] += 1
    # the batch exercises every kind of instance, not just the easy ones
    assert all(n >= 3 for n in outcomes.values()), outcomes
