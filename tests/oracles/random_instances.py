"""Seeded random small planning instances (scene and spec as plain dicts) for optimality tests.

Robots stand on a line or a two-column grid with varied spacing and reach, so some deliveries
need robot-to-robot relays; people sometimes stand where they block a rendezvous or out of every
workspace, and objects sometimes lie out of every robot's reach, so some instances are
infeasible. Specs mix ``&``, ``|``, non-strict ordering, placements and one nested level; every
leaf moves a different object (the class for which the CP-SAT oracle's relaxation is exact).
"""

from __future__ import annotations

import math
import random
from typing import Any

DURATION_CHOICES = (0.3, 0.5, 0.6, 0.8)
CATEGORIES = ("bottle", "chips", "cup", "apple", "can", "box", "banana")
MARGIN = 1e-3  # keep every distance this far from the threshold it is compared with


def random_instance(
    seed: int, max_robots: int = 3, max_objects: int = 3, robots: int | None = None
) -> tuple[dict[str, Any], dict[str, Any]]:
    """A deterministic random ``(scene_dict, spec_dict)`` pair; both load with the hltl loaders.

    ``robots`` fixes the number of robots (else at most ``max_robots``, mostly 2 or 3).
    """
    rng = random.Random(seed)
    # Several robots more often than one: relays are what the oracles are for.
    n_robots = min(max_robots, rng.choice((1, 2, 2, 3, 3, 3)))
    if robots is not None:
        n_robots = robots
    n_objects = rng.randint(1, max_objects)
    n_humans = rng.randint(1, 2)
    with_surface = rng.random() < 0.5
    for _ in range(1000):
        scene = _scene(rng, n_robots, n_objects, n_humans, with_surface)
        if _clear_of_thresholds(scene):
            break
    else:  # pragma: no cover - the jitter makes a near-tie vanishingly rare
        raise RuntimeError(f"seed {seed}: could not place entities away from reach thresholds")
    scene["durations"] = {
        s: rng.choice(DURATION_CHOICES) for s in ("pick", "place", "handover_r2r", "handover_r2h")
    }
    return scene, _spec(rng, scene)


def _scene(
    rng: random.Random, n_robots: int, n_objects: int, n_humans: int, with_surface: bool
) -> dict[str, Any]:
    spacing = rng.choice((0.8, 1.0, 1.0, 1.2, 1.2, 1.5))
    grid = n_robots >= 3 and rng.random() < 0.4

    def jitter() -> float:
        return rng.uniform(-0.05, 0.05)

    robots = []
    for i in range(n_robots):
        x, y = ((i % 2) * spacing, (i // 2) * spacing) if grid else (i * spacing, 0.0)
        robots.append(
            {
                "id": f"r{i + 1}",
                "base": [_r(x + jitter()), _r(y + jitter()), 0.0],
                "reach": rng.choice((0.5, 0.6, 0.7, 0.8, 0.9)),
            }
        )
    xs = [r["base"][0] for r in robots]
    ys = [r["base"][1] for r in robots]
    far = (_r(max(xs) + 3.0 + jitter()), _r(max(ys) + 3.0 + jitter()))

    def near(robot: dict[str, Any], lo: float, hi: float) -> tuple[float, float]:
        angle = rng.uniform(0, 2 * math.pi)
        d = rng.uniform(lo, hi)
        return (
            _r(robot["base"][0] + d * math.cos(angle)),
            _r(robot["base"][1] + d * math.sin(angle)),
        )

    objects = []
    for k in range(n_objects):
        if rng.random() < 0.08:
            x, y = far
        else:
            robot = rng.choice(robots)
            x, y = near(robot, 0.1, robot["reach"] - 0.05)
        objects.append({"id": CATEGORIES[k], "category": CATEGORIES[k], "position": [x, y, 0.05]})

    humans = []
    for k in range(n_humans):
        roll = rng.random()
        if roll < 0.06:
            x, y = far[0] + 1.0, far[1]
        elif roll < 0.25 and n_robots >= 2:  # between two robots: may block their rendezvous
            a, b = rng.sample(robots, 2)
            x = _r((a["base"][0] + b["base"][0]) / 2 + jitter())
            y = _r((a["base"][1] + b["base"][1]) / 2 + 0.3 + jitter())
        else:
            robot = rng.choice(robots)
            x, y = near(robot, robot["reach"] + 0.05, robot["reach"] + 0.25)
        letter = "ABCDEFGH"[k]
        humans.append({"id": letter, "name": f"Person {letter}", "position": [x, y, 0.0]})

    surfaces = []
    if with_surface:
        if n_robots >= 2 and rng.random() < 0.6:
            a, b = rng.sample(robots, 2)
            cx = (a["base"][0] + b["base"][0]) / 2 + jitter()
            cy = (a["base"][1] + b["base"][1]) / 2 + 0.2 + jitter()
        else:
            cx, cy = near(rng.choice(robots), 0.2, 0.45)
        surfaces.append({"id": "shelf", "center": [_r(cx), _r(cy), 0.0], "size": [0.3, 0.3]})
    return {
        "units": "m",
        "robots": robots,
        "objects": objects,
        "humans": humans,
        "surfaces": surfaces,
    }


def _spec(rng: random.Random, scene: dict[str, Any]) -> dict[str, Any]:
    objects = [o["id"] for o in scene["objects"]]
    n_leaves = rng.randint(1, len(objects))
    leaves: dict[str, str] = {}
    for k, obj in enumerate(rng.sample(objects, n_leaves)):
        if scene["surfaces"] and rng.random() < 0.3:
            atom = f"placed({obj}, {rng.choice(scene['surfaces'])['id']})"
        else:
            atom = f"delivered({obj}, {rng.choice(scene['humans'])['id']})"
        leaves[f"p{100 * (k + 1)}"] = f"F {atom}"
    names = list(leaves)
    formulas: dict[str, str] = {}
    if len(names) == 1:
        formulas["p0"] = f"F {names[0]}"
    elif len(names) == 2:
        formulas["p0"] = _combine(rng, names[0], names[1])
    else:
        shape = rng.choice(("flat", "nested", "ordered"))
        a, b, c = names[:3]
        if shape == "flat":
            op = rng.choice(("&", "|"))
            formulas["p0"] = f"F {a} {op} F {b} {op} F {c}"
        elif shape == "ordered":
            formulas["p0"] = f"F ({a} & F {b}) {rng.choice(('&', '|'))} F {c}"
        else:
            formulas["p0"] = f"F p1 {rng.choice(('&', '|'))} F {c}"
            formulas["p1"] = _combine(rng, a, b)
    formulas.update(leaves)
    return {"root": "p0", "formulas": formulas}


def _combine(rng: random.Random, a: str, b: str) -> str:
    return rng.choice((f"F {a} & F {b}", f"F {a} | F {b}", f"F ({a} & F {b})"))


def _r(v: float) -> float:
    return round(v, 3)


def _clear_of_thresholds(scene: dict[str, Any]) -> bool:
    hr = 0.3
    robots = scene["robots"]
    for i, a in enumerate(robots):
        for b in robots[i + 1 :]:
            if abs(math.dist(a["base"], b["base"]) - a["reach"] - b["reach"]) < MARGIN:
                return False
        points = [o["position"] for o in scene["objects"]] + [
            s["center"] for s in scene["surfaces"]
        ]
        if any(abs(math.dist(a["base"], p) - a["reach"]) < MARGIN for p in points):
            return False
        for h in scene["humans"]:
            dh = math.hypot(a["base"][0] - h["position"][0], a["base"][1] - h["position"][1])
            if abs(dh - a["reach"] - hr) < MARGIN:
                return False
    return True
