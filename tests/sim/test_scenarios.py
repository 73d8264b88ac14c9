"""The scenario catalogue: determinism, sizes, feasibility, example files, specs and optima."""

from __future__ import annotations

import math
import re
from pathlib import Path

import pytest
import yaml

from hltl.errors import SceneError, UnknownEntityError
from hltl.sim import Scenario, catalogue, generate, get, write_examples
from hltl.sim.scenarios import (
    DURATIONS,
    PAPER_CONFIGS,
    delivery_chain,
    example_files,
    names,
    render_scene_yaml,
)
from hltl.spec.hierarchy import load_spec, spec_from_dict
from hltl.world.scene import Scene, load_scene, scene_from_dict

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
SCENARIOS = catalogue()
DELIVERED = re.compile(r"^F delivered\((\w+), (\w+)\)$")
ORDERING = re.compile(r"F \(p\d+ & F p\d+\)")


def deliveries(s: Scenario) -> list[tuple[str, str]]:
    """(object, human) of every leaf, read back from the spec text."""
    out = []
    for name, text in s.spec_dict["formulas"].items():
        if name.startswith("p") and int(name[1:]) >= 100:
            match = DELIVERED.match(text)
            assert match, text
            out.append((match.group(1), match.group(2)))
    return out


def independent_chain(scene: Scene, oid: str, hid: str) -> int | None:
    """Robots in the shortest relay for a delivery, by the oracle's own geometry (not the
    generator's), so that a bug in hltl.world.geometry cannot hide here."""
    from oracles.model import can_hand_over, human_inside, reaches

    obj, human = scene.object(oid), scene.human(hid)
    frontier = [r for r in scene.robots if reaches(r, obj.position)]
    seen = {r.id for r in frontier}
    length = 1
    while frontier:
        if any(human_inside(r, human, scene.human_reach) for r in frontier):
            return length
        nxt = [
            b
            for a in frontier
            for b in scene.robots
            if b.id not in seen and can_hand_over(scene, a, b)
        ]
        seen |= {b.id for b in nxt}
        frontier = list({b.id: b for b in nxt}.values())
        length += 1
    return None


def test_catalogue_names_and_lookup() -> None:
    expected = {
        "fig1",
        "1-1", "2-1", "4-1", "1-2", "2-2", "4-2",
        "1-4-line", "2-4-line", "4-4-line", "1-4-square", "2-4-square", "4-4-square",
    }  # fmt: skip
    assert {s.name for s in SCENARIOS} == expected == set(names())
    assert get("2-4-line") == next(s for s in SCENARIOS if s.name == "2-4-line")
    assert get("fig1").instruction == "Give Person A the bottle and Person B the chips."
    with pytest.raises(UnknownEntityError, match="unknown scenario '3-3'; catalogue has: fig1"):
        get("3-3")
    assert {s.name for s in catalogue(tags={"paper", "line"})} == {
        "1-4-line",
        "2-4-line",
        "4-4-line",
    }
    assert len(catalogue(tags={"paper"})) == 12
    assert catalogue(tags={"no-such-tag"}) == ()


@pytest.mark.parametrize("s", SCENARIOS, ids=lambda s: s.name)
def test_every_scenario_is_well_formed(s: Scenario) -> None:
    # the scene round-trips through its file format and validates
    assert scene_from_dict(s.scene.to_dict()) == s.scene
    assert s.scene.duration_map() == DURATIONS
    # sizes match the configuration: one object and one leaf per delivery
    assert len(s.scene.robots) == s.n_robot
    assert len(s.scene.objects) == s.n_task == len(deliveries(s))
    assert s.layout in s.tags
    assert s.name == "fig1" or s.name.startswith(f"{s.n_task}-{s.n_robot}")
    # people are named "Person X" and each delivery has a chain of robots, by two geometries
    assert all(h.name == f"Person {h.id}" for h in s.scene.humans)
    for oid, hid in deliveries(s):
        chain = delivery_chain(s.scene, oid, hid)
        assert chain is not None, (oid, hid)
        assert independent_chain(s.scene, oid, hid) == len(chain)
    # the spec follows the grounding conventions and validates
    spec = s.spec
    assert spec.root == "p0"
    assert set(spec.leaves) == {n for n in s.spec_dict["formulas"] if int(n[1:]) >= 100}
    composites = [t for n, t in s.spec_dict["formulas"].items() if n in spec.composites]
    assert ("ordering" in s.tags) == any(ORDERING.search(t) for t in composites)
    if "ordering" in s.tags:
        assert s.instruction.startswith("First give")
    for oid, hid in deliveries(s):
        assert s.scene.human(hid).name in s.instruction
        assert s.scene.object(oid).category in s.instruction


def test_paper_configurations_sizes_and_layouts() -> None:
    for n_task, n_robot, layout in PAPER_CONFIGS:
        s = next(
            x for x in SCENARIOS if x.name.startswith(f"{n_task}-{n_robot}") and x.layout == layout
        )
        assert (s.n_task, s.n_robot, s.layout) == (n_task, n_robot, layout)
        bases = [r.base for r in s.scene.robots]
        if layout == "line":
            assert len({b[1] for b in bases}) == 1 and len({b[0] for b in bases}) == 4
        if layout == "square":
            assert len({b[0] for b in bases}) == 2 and len({b[1] for b in bases}) == 2
    assert {s.name for s in SCENARIOS if "ordering" in s.tags}, "some scenarios have an ordering"


def test_line_needs_relay_chains() -> None:
    line = get("4-4-line")
    lengths = [len(delivery_chain(line.scene, o, u) or ()) for o, u in deliveries(line)]
    assert max(lengths) == 4 and sum(n >= 3 for n in lengths) >= 2
    assert "relay" in line.tags
    assert len(delivery_chain(get("1-4-line").scene, "bottle", "A") or ()) == 4
    assert "handover" in get("1-2").tags and "handover" not in get("1-1").tags


def test_people_never_block_a_rendezvous() -> None:
    from oracles.model import can_meet, rendezvous_blocked

    for s in [*SCENARIOS, generate(8, 8, "grid", 3), generate(16, 16, "square", 1)]:
        for a in s.scene.robots:
            for b in s.scene.robots:
                if can_meet(a, b):
                    assert not rendezvous_blocked(s.scene, a, b), (s.name, a.id, b.id)


def test_generation_is_deterministic_per_seed() -> None:
    for args in [(1, 1, "single"), (2, 4, "line"), (4, 4, "square"), (3, 6, "grid")]:
        assert generate(*args, seed=7) == generate(*args, seed=7)
        assert render_scene_yaml(generate(*args, seed=7)) == render_scene_yaml(
            generate(*args, seed=7)
        )
    assert generate(4, 4, "line", seed=1).scene != generate(4, 4, "line", seed=2).scene
    assert generate(2, 2, seed=5, ordered=True).spec_dict["formulas"]["p0"] == "F (p100 & F p200)"
    assert generate(2, 2, seed=5, ordered=False).spec_dict["formulas"]["p0"] == "F p100 & F p200"


@pytest.mark.parametrize(
    ("n_task", "n_robot", "layout"),
    [(8, 8, "line"), (8, 8, "grid"), (16, 16, "grid"), (16, 16, "square")],
)
def test_large_scenarios_for_scaling(n_task: int, n_robot: int, layout: str) -> None:
    s = generate(n_task, n_robot, layout, seed=0)
    assert len(s.scene.robots) == n_robot and len(s.scene.objects) == n_task
    assert len({o.id for o in s.scene.objects}) == n_task
    assert len(s.scene.humans) == n_task // 2
    for oid, hid in deliveries(s):
        assert independent_chain(s.scene, oid, hid) is not None
    if layout in ("grid", "square"):
        cols = math.ceil(math.sqrt(n_robot))
        assert len({r.base for r in s.scene.robots}) == n_robot
        assert {r.base[0] for r in s.scene.robots} == {float(c) for c in range(cols)}
    spec = spec_from_dict(s.spec_dict)  # compiles every DFA: no composite may be too wide
    assert all(len(spec.children[n]) <= 4 for n in spec.composites)
    assert spec.depth == 3 and len(spec.leaves) == n_task


def test_impossible_configurations_are_rejected() -> None:
    with pytest.raises(SceneError, match="layout 'pair' needs exactly 2 robots, got 3"):
        generate(1, 3, "pair")
    with pytest.raises(SceneError, match="layout 'square' needs k\\*k robots"):
        generate(1, 6, "square")
    with pytest.raises(SceneError, match="unknown layout 'ring'"):
        generate(1, 4, "ring")
    with pytest.raises(SceneError, match="at least one task"):
        generate(0, 2)
    with pytest.raises(SceneError, match="ordering needs at least two"):
        generate(1, 2, ordered=True)


def test_fig1_is_the_two_arms_scene() -> None:
    assert get("fig1").scene == load_scene(EXAMPLES / "scenes" / "two_arms.yaml")


def test_example_files_match_the_generator(tmp_path: Path) -> None:
    files = example_files()
    assert len(files) == 2 * len(SCENARIOS)
    for rel, text in files.items():
        path = EXAMPLES / rel
        assert path.is_file(), (
            f"{path} is missing: run hltl.sim.scenarios.write_examples('examples')"
        )
        assert path.read_text(encoding="utf-8") == text, f"{path} is stale"
    for s in SCENARIOS:
        assert load_scene(EXAMPLES / "scenes" / f"{s.name}.yaml") == s.scene
        spec_file = EXAMPLES / "specs" / "suite" / f"{s.name}.yaml"
        assert yaml.safe_load(spec_file.read_text()) == s.spec_dict
        assert load_spec(spec_file) == s.spec
    written = write_examples(tmp_path)
    assert sorted(p.relative_to(tmp_path).as_posix() for p in written) == sorted(files)


# Optimal makespans of the catalogue with the fixed durations (pick 0.5, r2r 0.6, r2h 0.5), by
# the CP-SAT oracle and by brute force, which agree. They pin the
# generator: a change to it shows up here and in the example files.
OPTIMA = {
    "fig1": 1.0,
    "1-1": 1.0,
    "2-1": 2.0,
    "4-1": 4.0,
    "1-2": 1.6,
    "2-2": 2.1,
    "4-2": 4.8,
    "1-4-line": 2.8,
    "2-4-line": 4.5,
    "4-4-line": 5.7,
    "1-4-square": 2.2,
    "2-4-square": 2.2,
    "4-4-square": 3.8,
}


@pytest.mark.parametrize("name", sorted(OPTIMA))
def test_catalogue_optima(name: str) -> None:
    from oracles.brute_force import optimal_plan
    from oracles.cpsat import cpsat_solve
    from oracles.validator import check_plan

    s = get(name)
    spec = s.spec
    result = cpsat_solve(s.scene, spec, time_limit=120)
    assert result.makespan == pytest.approx(OPTIMA[name])
    assert result.plan is not None
    check_plan(s.scene, spec, result.plan)
    plan = optimal_plan(s.scene, spec)
    assert plan is not None and plan["makespan"] == pytest.approx(OPTIMA[name])
    check_plan(s.scene, spec, plan)
