"""A seeded human walk model for training and testing trajectory predictors."""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from hltl.perception.forecast import DT, F64, stop_places
from hltl.world.scene import Human, Robot, Scene

LAYOUTS = ((1, 1), (1, 2), (1, 3), (1, 4), (2, 2))  # (rows, cols) of robots


@dataclass(frozen=True, slots=True)
class Walk:
    """One person's walk in one cell.

    Attributes:
        true: (n, 2) true floor positions every DT seconds.
        observed: ``true`` plus perception noise.
        stops: (m, 2) the cell's stopping places (what a predictor is told).
        kinds: per leg, what it was (``sim``, ``smooth``, ``turn``, ``hesitate``, ``wander``).
    """

    true: F64
    observed: F64
    stops: F64
    kinds: tuple[str, ...]


def random_cell(rng: np.random.Generator) -> Scene:
    """A cell like the catalogue's: 1–4 arms on a 1 m grid (jittered), people 0.6–1.0 m out."""
    rows, cols = LAYOUTS[int(rng.integers(len(LAYOUTS)))]
    spacing = float(rng.uniform(0.9, 1.3))
    robots: list[Robot] = []
    for r in range(rows):
        for c in range(cols):
            if len(robots) == 4:
                break
            base = (c * spacing + rng.normal(0, 0.03), r * spacing + rng.normal(0, 0.03), 0.0)
            robots.append(Robot(f"r{len(robots) + 1}", base, float(rng.uniform(0.55, 0.75))))
    offset = float(rng.uniform(0.6, 1.0))
    humans: list[Human] = []
    for k in range(2):
        rb = robots[int(rng.integers(len(robots)))]
        a = float(rng.uniform(0, 2 * math.pi))
        humans.append(
            Human(
                f"h{k}",
                f"Person {k}",
                (rb.base[0] + offset * math.cos(a), rb.base[1] + offset * math.sin(a), 0.0),
            )
        )
    return Scene(robots=tuple(robots), humans=tuple(humans))


def _leg(
    rng: np.random.Generator,
    p: F64,
    goal: F64,
    speed: float,
    kind: str,
    stops: F64,
) -> list[F64]:
    """Positions every DT from ``p`` (exclusive) to the end of one leg of kind ``kind``."""
    out: list[F64] = []
    smooth = kind != "sim"
    accel = float(rng.uniform(0.8, 2.0))
    v = 0.0 if smooth else speed
    # a curved path: head first for a waypoint beside the straight line
    d = goal - p
    dist = float(np.hypot(*d))
    targets = [goal]
    if smooth and dist > 1.0 and rng.random() < 0.4:
        normal = np.array([-d[1], d[0]]) / dist
        targets = [p + d * 0.5 + normal * float(rng.uniform(-0.25, 0.25)), goal]
    turn_at = float(rng.uniform(0.25, 0.7)) * dist if kind == "turn" else math.inf
    hes_at = float(rng.uniform(0.2, 0.7)) * dist if kind == "hesitate" else math.inf
    hes_left = float(rng.uniform(0.3, 1.2))
    hes_speed = float(rng.uniform(0.0, 0.3))
    travelled = 0.0
    for _ in range(int(60 / DT)):
        if travelled >= turn_at:
            # change of mind: another stopping place, not the current goal
            others = stops[np.hypot(*(stops - goal).T) > 0.3]
            if len(others):
                goal = others[int(rng.integers(len(others)))]
                targets = [goal]
            turn_at = math.inf
        tgt = targets[0]
        rem_vec = tgt - p
        rem = float(np.hypot(*rem_vec))
        if len(targets) > 1 and rem < 0.15:
            targets.pop(0)
            continue
        to_goal = float(np.hypot(*(goal - p))) if len(targets) == 1 else rem + 1.0
        want = speed
        if travelled >= hes_at and hes_left > 0:
            want = hes_speed
            hes_left -= DT
        if smooth:
            want = min(want, math.sqrt(2.0 * accel * max(to_goal, 0.0)))
            v = min(v + accel * DT, want) if v < want else max(v - 2 * accel * DT, want)
        else:
            v = want
        step = v * DT
        if step >= rem and len(targets) == 1:
            p = tgt.copy()
            out.append(p)
            break
        if rem > 0:
            p = p + rem_vec / rem * min(step, rem)
        travelled += step
        out.append(p)
        if smooth and v < 0.02 and to_goal < 0.05:
            break
    return out


KINDS = ("sim", "smooth", "turn", "hesitate", "wander")
MIX = (0.3, 0.3, 0.15, 0.15, 0.1)  # how often each kind of leg is drawn (training and tests)


def generate_walk(
    rng: np.random.Generator, duration: float = 20.0, mix: Sequence[float] = MIX
) -> Walk:
    """One seeded walk of about ``duration`` seconds in a random cell; ``mix`` gives the
    probability of each leg kind in KINDS."""
    scene = random_cell(rng)
    stops = stop_places(scene)
    p = stops[int(rng.integers(len(stops)))].copy()
    pts: list[F64] = [p]
    kinds: list[str] = []
    n = int(duration / DT)
    while len(pts) < n:
        # stand a while
        pts += [p] * int(rng.uniform(0.5, 3.0) / DT)
        kind = str(rng.choice(KINDS, p=np.asarray(mix) / sum(mix)))
        dists = np.hypot(*(stops - p).T)
        if kind == "wander":
            a = float(rng.uniform(0, 2 * math.pi))
            goal = p + float(rng.uniform(0.5, 2.0)) * np.array([math.cos(a), math.sin(a)])
        else:
            cand = np.flatnonzero(dists > 0.3)
            w = np.exp(-dists[cand] / 1.5)
            goal = stops[int(rng.choice(cand, p=w / w.sum()))]
        speed = 1.0 if kind == "sim" and rng.random() < 0.5 else float(rng.uniform(0.6, 1.4))
        leg = _leg(rng, p, goal, speed, kind, stops)
        pts += leg
        if leg:
            p = leg[-1]
        kinds.append(kind)
    true = np.array(pts[:n], dtype=float)
    sigma = float(rng.choice([0.0, 0.005, 0.01, 0.02]))
    observed = true + rng.normal(0.0, sigma, size=true.shape) if sigma else true.copy()
    return Walk(true, observed, stops, tuple(kinds))


def generate_walks(
    seed: int, count: int, duration: float = 20.0, mix: Sequence[float] = MIX
) -> list[Walk]:
    """``count`` walks from ``seed`` (the same seed gives the same walks)."""
    rng = np.random.default_rng(seed)
    return [generate_walk(rng, duration, mix) for _ in range(count)]
