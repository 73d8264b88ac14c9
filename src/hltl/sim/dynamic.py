"""Dynamic scenarios of the catalogue: the suite's trials (H-MOVE and GOAL) and Fig. 1's walk."""

from __future__ import annotations

import math
import random
from dataclasses import dataclass, replace
from typing import Any

from hltl.errors import HltlError
from hltl.grounding.offline import OfflineGrounder
from hltl.planner import PlanStatus, PlanStep, plan
from hltl.sim.events import EventSchedule, HumanMove, Instruction, events_from_dict
from hltl.sim.scenarios import (
    CATEGORIES,
    OBJECT_HEIGHT,
    OBJECT_RADIUS,
    PAPER_CONFIGS,
    PERSON_OFFSET,
    Scenario,
    delivery_chain,
    generate,
    scenario_name,
)
from hltl.spec.hierarchy import HSpec
from hltl.spec.printer import atoms
from hltl.world.geometry import human_in_workspace
from hltl.world.scene import Scene, Vec3, scene_from_dict

WALK_SPEED = 1.0  # m/s
# H-MOVE kinds: random walks, T2-style walks (paper §V-B T2: the recipient of the delivery under
# way walks to a place served by other robots, mid-delivery), or both (odd trials T2-style)
WALKS = ("random", "t2", "mixed")
MIN_SPACING = 0.4  # metres between two people's spots

# Fig. 1's walk: Person A steps up to the table, then walks on to r2's side during the handovers.
# Also in examples/events/demo.yaml (a test keeps the two equal).
FIG1_EVENTS: tuple[dict[str, Any], ...] = (
    {"t": 0.0, "type": "human_move", "human": "A", "to": [0.45, 0.75, 0.0], "speed": 1.0},
    {"t": 0.7, "type": "human_move", "human": "A", "to": [1.1, 1.05, 0.0], "speed": 1.5},
)


def fig1_events(scene: Scene) -> EventSchedule:
    """The Fig. 1 demo's events on ``scene`` (the Fig. 1 cell)."""
    return events_from_dict({"events": [dict(e) for e in FIG1_EVENTS]}, scene, "demo events")


@dataclass(frozen=True, slots=True)
class Trial:
    """One task of the suite with its dynamics.

    Attributes:
        config: the Table II configuration name, e.g. ``"2-4-line"``.
        index: trial number within the configuration.
        seed: the trial's seed (scenario, events and the episode's randomness).
        scenario: the base task; its ``scene`` already holds the extra object of the GOAL.
        goal: the GOAL delivery (object, human) and ``goal_text`` what is said.
        move: the H-MOVE (human, destination).
        events: the schedule injected into the episode (H-MOVE and GOAL).
        base_makespan: the exact planner's optimum for the base task from the start (s).
        walk: the H-MOVE's kind: ``random`` (10–70 % of the base makespan, any recipient) or
            ``t2`` (the recipient of a delivery under way leaves for other robots' side).
    """

    config: str
    index: int
    seed: int
    scenario: Scenario
    goal: tuple[str, str]
    goal_text: str
    move: tuple[str, Vec3]
    events: EventSchedule
    base_makespan: float
    walk: str = "random"

    @property
    def scene(self) -> Scene:
        return self.scenario.scene

    @property
    def instruction(self) -> str:
        return self.scenario.instruction


def trial_seed(suite_seed: int, index: int) -> int:
    """The seed of trial ``index`` (the configuration is mixed in by the generator itself)."""
    return suite_seed * 100_000 + index


def config_of(name: str) -> tuple[int, int, str]:
    """``(tasks, robots, layout)`` of a Table II configuration name.

    Raises:
        HltlError: not one of the twelve names.
    """
    for cfg in PAPER_CONFIGS:
        if scenario_name(*cfg) == name:
            return cfg
    known = ", ".join(scenario_name(*c) for c in PAPER_CONFIGS)
    raise HltlError(f"unknown configuration {name!r}; expected one of {known}")


def config_names() -> tuple[str, ...]:
    return tuple(scenario_name(*c) for c in PAPER_CONFIGS)


def walk_kind(walks: str, index: int) -> str:
    """The H-MOVE kind of trial ``index`` under ``walks`` (``mixed``: odd trials T2-style).

    Raises:
        HltlError: ``walks`` is not one of WALKS.
    """
    if walks not in WALKS:
        raise HltlError(f"unknown walks {walks[:40]!r}; expected one of {', '.join(WALKS)}")
    if walks == "mixed":
        return "t2" if index % 2 else "random"
    return walks


def make_trial(config: str, index: int, suite_seed: int = 0, walks: str = "random") -> Trial:
    """Generate trial ``index`` of ``config`` (pure function of its arguments).

    ``walks`` picks the H-MOVE (see :data:`WALKS`); a T2-style walk needs another robot to
    serve the person, so one-robot cells fall back to the random walk (``Trial.walk`` says
    which one a trial got). ``random`` trials are the same whatever ``walks`` says.

    Raises:
        HltlError: no solvable variant was found in 50 draws (never seen for the paper's
            configurations; the message names the configuration and seed); unknown ``walks``.
    """
    kind = walk_kind(walks, index)
    n_task, n_robot, layout = config_of(config)
    seed = trial_seed(suite_seed, index)
    rng = random.Random(f"hltl-suite/{config}/{seed}")
    if kind == "t2" and n_robot == 1:
        kind = "random"
    for attempt in range(50):
        sc = generate(n_task, n_robot, layout, seed * 50 + attempt)
        trial = _dress(config, index, seed, sc, rng, kind)
        if trial is not None:
            return trial
    raise HltlError(f"no solvable trial for {config} with seed {seed} after 50 draws")


def _t2_walk(
    scene: Scene,
    base_steps: tuple[PlanStep, ...],
    deliveries: list[tuple[str, str]],
    spots: list[Vec3],
    rng: random.Random,
) -> tuple[str, Vec3, float, Scene] | None:
    """A T2-style walk (paper §V-B): the recipient of a delivery of the base plan walks, while
    that delivery is under way (after its object's first action starts, before the hand-over
    starts), to a spot served only by robots other than the one planned to hand it over.
    (mover, destination, start time, moved scene), or None when no such walk exists."""
    options = []
    for o, u in deliveries:
        acts = [(s, a) for s in base_steps for a in s.actions if a.object == o]
        r2h = [(s, a) for s, a in acts if a.skill == "handover_r2h" and a.human == u]
        if not acts or not r2h or r2h[0][0].start <= acts[0][0].start:
            continue
        options.append((o, u, acts[0][0].start, r2h[0][0].start, r2h[0][1].robots[0]))
    rng.shuffle(options)
    for _, u, t0, t1, giver in options:
        for p in spots:
            serving = {r.id for r in scene.robots if human_in_workspace(r, p, scene.human_reach)}
            if giver in serving:
                continue
            cand = _moved(scene, u, p)
            if all(delivery_chain(cand, o2, u2) is not None for o2, u2 in deliveries):
                return u, p, round(rng.uniform(t0, t1), 3), cand
    return None


def _dress(
    config: str, index: int, seed: int, sc: Scenario, rng: random.Random, kind: str = "random"
) -> Trial | None:
    """Add the GOAL object and draw the events; None when the result is not solvable."""
    scene = sc.scene
    deliveries = _deliveries(sc)
    # the GOAL object: next category, next to a seeded robot, for a seeded person
    category = CATEGORIES[len(scene.objects) % len(CATEGORIES)]
    oid = category if category not in scene.object_ids else f"{category}_goal"
    human = rng.choice(scene.humans)
    holder = rng.choice(scene.robots)
    angle = rng.uniform(0.0, 2.0 * math.pi)
    radius = rng.uniform(0.5, 1.0) * OBJECT_RADIUS
    pos = [
        round(holder.base[0] + radius * math.cos(angle), 3) + 0.0,
        round(holder.base[1] + radius * math.sin(angle), 3) + 0.0,
        OBJECT_HEIGHT,
    ]
    data = scene.to_dict()
    data["objects"] = [*data["objects"], {"id": oid, "category": category, "position": pos}]
    scene = scene_from_dict(data, source=scene.source)
    goal = (oid, human.id)
    all_deliveries = [*deliveries, goal]

    # the H-MOVE: a recipient walks to a free spot that keeps every delivery possible
    recipients = sorted({u for _, u in all_deliveries})
    mover = rng.choice(recipients)
    spots = [
        p
        for p in _spots(scene)
        if all(math.dist(p[:2], h.position[:2]) >= MIN_SPACING for h in scene.humans)
    ]
    rng.shuffle(spots)
    dest: Vec3 | None = None
    moved_scene = scene
    for p in spots:
        cand = _moved(scene, mover, p)
        if all(delivery_chain(cand, o, u) is not None for o, u in all_deliveries):
            dest, moved_scene = p, cand
            break
    if dest is None or any(delivery_chain(scene, o, u) is None for o, u in all_deliveries):
        return None

    base = plan(scene, sc.spec, timeout=30.0)
    if base.status is not PlanStatus.SOLVED or base.makespan is None:
        return None
    m = base.makespan
    t_move = round(rng.uniform(0.1, 0.7) * m, 3)
    t_goal = round(rng.uniform(0.2, 0.8) * m, 3)
    if kind == "t2":
        walk = _t2_walk(scene, base.steps, all_deliveries, spots, rng)
        if walk is None:
            return None
        mover, dest, t_move, moved_scene = walk
    full = _with_goal(sc, scene, goal)
    after = plan(moved_scene, full, timeout=30.0)
    if after.status is not PlanStatus.SOLVED:
        return None

    name = scene.human(goal[1]).name
    text = f"Also give {name} the {category}."
    events = EventSchedule(
        timed=tuple(
            sorted(
                (
                    HumanMove(t_move, mover, dest, WALK_SPEED),
                    Instruction(t_goal, text),
                ),
                key=lambda e: e.t,
            )
        ),
        source=f"suite {config} seed {seed}",
    )
    return Trial(
        config=config,
        index=index,
        seed=seed,
        scenario=replace(sc, scene=scene),
        goal=goal,
        goal_text=text,
        move=(mover, dest),
        events=events,
        base_makespan=m,
        walk=kind,
    )


def _deliveries(sc: Scenario) -> list[tuple[str, str]]:
    out = []
    spec = sc.spec
    for leaf in spec.leaves:
        for a in atoms(spec.formula(leaf)):
            if a.name == "delivered" and len(a.args) == 2:
                out.append((a.args[0], a.args[1]))
    return out


def _spots(scene: Scene) -> list[Vec3]:
    """Places a person may walk to: PERSON_OFFSET from a base in one of eight directions,
    inside exactly that robot's workspace (so nobody blocks a rendezvous)."""
    out: list[Vec3] = []
    for r in scene.robots:
        for k in range(8):
            a = k * math.pi / 4.0
            p = (
                round(r.base[0] + PERSON_OFFSET * math.cos(a), 3) + 0.0,
                round(r.base[1] + PERSON_OFFSET * math.sin(a), 3) + 0.0,
                0.0,
            )
            serving = [s for s in scene.robots if human_in_workspace(s, p, scene.human_reach)]
            if len(serving) == 1:
                out.append(p)
    return sorted(set(out))


def _moved(scene: Scene, hid: str, to: Vec3) -> Scene:
    humans = tuple(replace(h, position=to) if h.id == hid else h for h in scene.humans)
    return replace(scene, humans=humans)


def _with_goal(sc: Scenario, scene: Scene, goal: tuple[str, str]) -> HSpec:
    """The base spec with the GOAL delivery added as the offline grounder would merge it."""
    text = f"Also give {scene.human(goal[1]).name} the {scene.object(goal[0]).category}."
    return OfflineGrounder().ground(text, scene, running=sc.spec).spec


def full_spec(trial: Trial) -> HSpec:
    """The whole task of a trial: the base task and the GOAL delivery, merged as grounded."""
    return _with_goal(trial.scenario, trial.scene, trial.goal)
