"""Interchangeable objects: the search keeps one node per swap of twins, and the optimum stays.

Twins are objects with the same instances (same robots reach them, same durations) whose leaves
ask the same of each (``delivered(·, A)``). The instances here clone objects of the random
oracle instances, so every class the planner finds is checked against the exhaustive search.
"""

from __future__ import annotations

import random
from typing import Any

import pytest

from hltl.planner import plan
from hltl.planner.problem import Problem
from hltl.planner.search import _Search
from hltl.sim.scenarios import generate
from hltl.spec.hierarchy import spec_from_dict
from hltl.world.scene import scene_from_dict
from tests.oracles.brute_force import optimal_makespan
from tests.oracles.random_instances import _clear_of_thresholds, random_instance
from tests.oracles.validator import check_against_optimum

NAMES = ("bottle", "chips", "cup", "apple", "can", "box", "banana")


def twins_instance(seed: int) -> tuple[dict[str, Any], dict[str, Any]]:
    """A random oracle scene whose objects get clones next to them, and a conjunction of one
    leaf per object: a clone mostly asks for the same as its original (a twin), sometimes for
    another person (not a twin)."""
    rng = random.Random(f"twins/{seed}")
    scene, _ = random_instance(seed, max_robots=3, max_objects=2)
    objects = list(scene["objects"])
    goals: dict[str, str] = {}
    for o in objects:
        if scene["surfaces"] and rng.random() < 0.2:
            goals[o["id"]] = f"placed({{}}, {scene['surfaces'][0]['id']})"
        else:
            goals[o["id"]] = f"delivered({{}}, {rng.choice(scene['humans'])['id']})"
    clones: list[dict[str, Any]] = []
    for o in objects:
        for _ in range(rng.choice((0, 1, 1, 2))):
            if len(objects) + len(clones) >= 4:
                break
            oid = NAMES[len(objects) + len(clones)]
            x, y, z = o["position"]
            clone = {"id": oid, "category": oid, "position": [x + 0.002, y - 0.001, z]}
            if not _clear_of_thresholds({**scene, "objects": [clone]}):
                clone["position"] = [x, y, z]
            clones.append(clone)
            goal = goals[o["id"]]
            if rng.random() < 0.2:
                goal = f"delivered({{}}, {rng.choice(scene['humans'])['id']})"
            goals[oid] = goal
    scene = {**scene, "objects": objects + clones}
    leaves = {f"p{100 * (k + 1)}": "F " + g.format(o) for k, (o, g) in enumerate(goals.items())}
    root = " & ".join(f"F {name}" for name in leaves)
    return scene, {"root": "p0", "formulas": {"p0": root, **leaves}}


SEEDS = range(150)


@pytest.mark.parametrize("seed", SEEDS)
def test_twins_keep_the_optimum(seed: int) -> None:
    scene_d, spec_d = twins_instance(seed)
    scene = scene_from_dict(scene_d, source=f"twins-{seed}")
    spec = spec_from_dict(spec_d)
    expected = optimal_makespan(scene, spec, max_nodes=1_000_000)
    check_against_optimum(scene, spec, plan(scene, spec, timeout=120), expected)


def test_the_twin_instances_have_twins() -> None:
    # the sweep above is only worth something if most of its instances have classes
    with_twins = 0
    for seed in SEEDS:
        scene_d, spec_d = twins_instance(seed)
        problem = Problem(scene_from_dict(scene_d), spec_from_dict(spec_d))
        with_twins += bool(problem.symmetry.classes)
    assert with_twins >= len(SEEDS) // 2, with_twins


def test_swapped_twins_are_one_node() -> None:
    sc = generate(8, 8, "grid", 4, ordered=False)
    problem = Problem(sc.scene, sc.spec)
    # apple and box wait next to r8 for Person D; chips and banana next to r8 for Person B
    named = {
        frozenset(problem.objects[o] for o, _ in members) for members in problem.symmetry.classes
    }
    assert frozenset({"apple", "box"}) in named
    assert frozenset({"chips", "banana"}) in named
    s = _Search(problem)
    start = problem.start()
    apple, box = problem.obj_index["apple"], problem.obj_index["box"]
    held = problem.held_code[problem.robot_index["r8"]]
    a = list(start[0])
    a[apple] = held
    b = list(start[0])
    b[box] = held
    ca, pa = s.canonical((tuple(a), None, start[2]))
    cb, pb = s.canonical((tuple(b), None, start[2]))
    assert ca == cb
    assert (pa is None) != (pb is None)  # exactly one of them was relabelled


def test_no_twins_without_fixed_durations_or_with_ordering() -> None:
    ordered = generate(8, 8, "grid", 4, ordered=True)
    assert not Problem(ordered.scene, ordered.spec).symmetry.classes
    data = generate(8, 8, "grid", 4, ordered=False)
    scene = scene_from_dict({k: v for k, v in data.scene.to_dict().items() if k != "durations"})
    assert not Problem(scene, data.spec).symmetry.classes
