"""Scenario catalogue: the paper's simulation suite (§V-A, Fig. 7) and the Fig. 1 cell, seeded."""

from __future__ import annotations

import copy
import json
import math
import random
from collections import deque
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import yaml

from hltl.errors import SceneError, UnknownEntityError
from hltl.spec.hierarchy import HSpec, spec_from_dict
from hltl.world.geometry import can_meet, context_label, human_in_workspace, reaches
from hltl.world.scene import Scene, scene_from_dict

LAYOUTS = ("single", "pair", "line", "square", "grid")

# Fixed skill times (seconds) so that every generated scenario has a reproducible optimum.
DURATIONS: dict[str, float] = {"pick": 0.5, "place": 0.5, "handover_r2r": 0.6, "handover_r2h": 0.5}

CATEGORIES = (
    "bottle",
    "chips",
    "cup",
    "apple",
    "can",
    "box",
    "banana",
    "orange",
    "mug",
    "book",
    "sponge",
    "pear",
    "lemon",
    "spoon",
    "bowl",
    "cookie",
)

# Geometry of generated cells (metres). Neighbouring bases are SPACING apart and every reach is
# at most 0.7, so neighbours can meet (reach sum >= 1.2 > 1.0) and diagonal neighbours in a grid
# cannot (1.4 < 1.414). An object lies within OBJECT_RADIUS of one base: only that robot reaches
# it (a neighbour is >= 0.75 away). A person stands PERSON_OFFSET outside one robot: inside that
# workspace (0.8 <= reach + 0.3) and no other, so nobody blocks a rendezvous.
SPACING = 1.0
ARMS = (("elfin3", 0.6), ("xarm6", 0.7))
OBJECT_RADIUS = 0.25
OBJECT_HEIGHT = 0.05
PERSON_OFFSET = 0.8

# The paper's Table II configurations: (tasks, robots, layout).
PAPER_CONFIGS: tuple[tuple[int, int, str], ...] = (
    (1, 1, "single"),
    (2, 1, "single"),
    (4, 1, "single"),
    (1, 2, "pair"),
    (2, 2, "pair"),
    (4, 2, "pair"),
    (1, 4, "line"),
    (2, 4, "line"),
    (4, 4, "line"),
    (1, 4, "square"),
    (2, 4, "square"),
    (4, 4, "square"),
)
CATALOGUE_SEED = 0
GROUP = 4  # most children per composite formula: a flat "F p100 & … & F p1600" DFA is huge


@dataclass(frozen=True, slots=True)
class Scenario:
    """A named, tagged planning problem.

    Attributes:
        name: catalogue name, ``"<tasks>-<robots>"`` for one or two robots, else
            ``"<tasks>-<robots>-<layout>"``; ``"fig1"`` for the paper's Fig. 1 cell.
        scene: the validated scene (fixed ``durations``).
        spec_dict: the H-LTLf spec in DESIGN.md's layout, one leaf per delivery.
        instruction: the English sentence a person would say for the spec.
        tags: e.g. ``paper``, the layout, ``handover`` (some delivery needs a robot-to-robot
            handover), ``relay`` (some delivery needs a chain of three or more robots),
            ``ordering``.
        n_task, n_robot, layout, seed: how it was generated.
    """

    name: str
    scene: Scene
    spec_dict: dict[str, Any] = field(hash=False)
    instruction: str
    tags: frozenset[str]
    n_task: int
    n_robot: int
    layout: str
    seed: int

    @property
    def spec(self) -> HSpec:
        """The spec, parsed and validated (``hltl.spec.hierarchy.spec_from_dict``)."""
        return spec_from_dict(copy.deepcopy(self.spec_dict), source=f"scenario {self.name}")


# -- geometry helpers -----------------------------------------------------------------------------


def delivery_chain(scene: Scene, object_id: str, human_id: str) -> tuple[str, ...] | None:
    """The shortest chain of robots that can carry ``object_id`` from its spot to ``human_id``.

    The first robot reaches the object, each next one meets the previous one at a rendezvous no
    person blocks, and the last one has the person inside its workspace. None when no chain
    exists (the delivery is infeasible in the initial context).
    """
    obj, human = scene.object(object_id), scene.human(human_id)
    context = context_label(scene, {h.id: h.position for h in scene.humans})
    start = [r.id for r in scene.robots if reaches(r, obj.position)]
    goal = {r.id for r in scene.robots if human_in_workspace(r, human.position, scene.human_reach)}
    previous: dict[str, str | None] = {rid: None for rid in start}
    queue = deque(start)
    while queue:
        rid = queue.popleft()
        if rid in goal:
            chain = [rid]
            while (prev := previous[chain[-1]]) is not None:
                chain.append(prev)
            return tuple(reversed(chain))
        here = scene.robot(rid)
        for other in scene.robots:
            if (
                other.id not in previous
                and can_meet(here, other)
                and not context.blocked(here.id, other.id)
            ):
                previous[other.id] = rid
                queue.append(other.id)
    return None


def _grid_shape(layout: str, n_robot: int) -> tuple[int, int]:
    """(rows, columns) of the robot arrangement."""
    if layout in ("single", "pair", "line"):
        return 1, n_robot
    if layout == "square":
        k = math.isqrt(n_robot)
        return k, k
    cols = math.ceil(math.sqrt(n_robot))
    return math.ceil(n_robot / cols), cols


def _check_config(n_task: int, n_robot: int, layout: str) -> None:
    if n_task < 1 or n_robot < 1:
        raise SceneError(
            f"a scenario needs at least one task and one robot, got {n_task}, {n_robot}"
        )
    if n_task > 26 * len(CATEGORIES):
        raise SceneError(f"at most {26 * len(CATEGORIES)} tasks, got {n_task}")
    if layout not in LAYOUTS:
        raise SceneError(f"unknown layout {layout!r}; expected one of {', '.join(LAYOUTS)}")
    need = {
        "single": (n_robot == 1, "exactly 1 robot"),
        "pair": (n_robot == 2, "exactly 2 robots"),
        "line": (n_robot >= 2, "at least 2 robots"),
        "grid": (n_robot >= 2, "at least 2 robots"),
        "square": (n_robot >= 4 and math.isqrt(n_robot) ** 2 == n_robot, "k*k robots, k >= 2"),
    }
    ok, what = need[layout]
    if not ok:
        raise SceneError(f"layout {layout!r} needs {what}, got {n_robot}")


def default_layout(n_robot: int) -> str:
    """``single`` for one robot, ``pair`` for two, ``line`` otherwise."""
    return {1: "single", 2: "pair"}.get(n_robot, "line")


def scenario_name(n_task: int, n_robot: int, layout: str) -> str:
    """The catalogue name: the layout is left out where the robot count implies it."""
    if layout == default_layout(n_robot) and layout != "line":
        return f"{n_task}-{n_robot}"
    return f"{n_task}-{n_robot}-{layout}"


def _r(v: float) -> float:
    return round(v, 3) + 0.0  # + 0.0 turns -0.0 into 0.0


# -- the generator --------------------------------------------------------------------------------


def generate(
    n_task: int,
    n_robot: int,
    layout: str | None = None,
    seed: int = 0,
    *,
    ordered: bool | None = None,
) -> Scenario:
    """A delivery scenario with ``n_task`` deliveries and ``n_robot`` fixed-base arms.

    Robots stand ``SPACING`` apart in a line or a grid, so neighbours can hand over; people
    stand at the ends or outer edges, each inside one workspace; each object lies within one
    robot's reach. In line, square and grid layouts the first delivery starts at the robot
    farthest (in handovers) from its recipient, so it needs a relay chain across the layout.
    Every delivery is checked to have a chain of robots from the object to the person.

    Args:
        n_task: number of deliveries (one object and one leaf each).
        n_robot: number of robots.
        layout: one of ``LAYOUTS``; default ``single``/``pair``/``line`` by robot count.
        seed: the same arguments and seed always give the same scenario.
        ordered: whether the first delivery must complete no later than the second
            (``F (p100 & F p200)``); None lets the seed decide (when there are two or more).

    Raises:
        SceneError: an impossible configuration (``pair`` with 3 robots, ``square`` with 6...).
    """
    layout = default_layout(n_robot) if layout is None else layout
    _check_config(n_task, n_robot, layout)
    rng = random.Random(f"hltl-scenario/{n_task}/{n_robot}/{layout}/{seed}")
    rows, cols = _grid_shape(layout, n_robot)

    robots: list[dict[str, Any]] = []
    for i in range(n_robot):
        model, reach = rng.choice(ARMS)
        row, col = divmod(i, cols)
        base = [_r(col * SPACING), _r(row * SPACING), 0.0]
        robots.append({"id": f"r{i + 1}", "base": base, "reach": reach, "model": model})
    cells = {(i // cols, i % cols): robots[i]["id"] for i in range(n_robot)}

    spots = _person_spots(cells, rows, cols)
    n_humans = min(len(spots), n_task if n_task <= 2 else max(2, n_task // 2))
    chosen_spots = _spread(spots, n_humans, rng)
    humans: list[dict[str, Any]] = []
    for k, (x, y) in enumerate(chosen_spots):
        letter = _letters(k)
        humans.append({"id": letter, "name": f"Person {letter}", "position": [_r(x), _r(y), 0.0]})

    objects: list[dict[str, Any]] = []
    deliveries: list[tuple[str, str]] = []  # (object id, human id)
    draft = {"units": "m", "robots": robots, "humans": humans, "durations": dict(DURATIONS)}
    empty = scene_from_dict(draft)
    hops = _hops(empty)
    for t in range(n_task):
        human = humans[t % len(humans)]["id"] if t < len(humans) else rng.choice(humans)["id"]
        oid, category = _object_name(t)
        for _attempt in range(100):
            if t == 0 and n_robot >= 2:  # start the first delivery as far as possible
                person = empty.human(human)
                serving = [
                    r.id
                    for r in empty.robots
                    if human_in_workspace(r, person.position, empty.human_reach)
                ]
                holder = max(
                    robots,
                    key=lambda r: (
                        min((hops[r["id"]][s] for s in serving), default=0),
                        -int(r["id"][1:]),
                    ),
                )
            else:
                holder = rng.choice(robots)
            angle = rng.uniform(0.0, 2.0 * math.pi)
            radius = rng.uniform(0.5, 1.0) * OBJECT_RADIUS
            position = [
                _r(holder["base"][0] + radius * math.cos(angle)),
                _r(holder["base"][1] + radius * math.sin(angle)),
                OBJECT_HEIGHT,
            ]
            candidate = {"id": oid, "category": category, "position": position}
            scene = scene_from_dict({**draft, "objects": [*objects, candidate]})
            if delivery_chain(scene, oid, human) is not None:
                break
        else:  # pragma: no cover - the layouts above are connected by construction
            raise SceneError(f"could not place {oid!r} so that it reaches {human!r}")
        objects.append(candidate)
        deliveries.append((oid, human))

    if ordered is None:
        ordered = n_task >= 2 and rng.random() < 0.5
    if ordered and n_task < 2:
        raise SceneError("an ordering needs at least two deliveries")
    data = {**draft, "objects": objects}
    name = scenario_name(n_task, n_robot, layout)
    scene = scene_from_dict(data, source=f"scenario {name}")
    names = {h["id"]: h["name"] for h in humans}
    categories = {o["id"]: o["category"] for o in objects}
    return Scenario(
        name=name,
        scene=scene,
        spec_dict=_delivery_spec(deliveries, ordered),
        instruction=_instruction(deliveries, ordered, names, categories),
        tags=_tags(scene, deliveries, layout, ordered),
        n_task=n_task,
        n_robot=n_robot,
        layout=layout,
        seed=seed,
    )


def _letters(k: int) -> str:
    return "ABCDEFGHIJKLMNOPQRSTUVWXYZ"[k] if k < 26 else f"P{k + 1}"


def _object_name(t: int) -> tuple[str, str]:
    category = CATEGORIES[t % len(CATEGORIES)]
    rank = t // len(CATEGORIES)
    return (category if rank == 0 else f"{category}_{rank + 1}"), category


def _person_spots(
    cells: Mapping[tuple[int, int], str], rows: int, cols: int
) -> list[tuple[float, float]]:
    """Where people may stand: beside a robot where no robot stands next in that direction.

    A single robot gets the four sides; a line gets its two ends first, then its sides; a grid
    its outer edges, corners diagonally.
    """
    out: list[tuple[float, float]] = []
    diagonal = PERSON_OFFSET / math.sqrt(2.0)
    directions: list[tuple[int, int]] = [(0, -1), (0, 1), (-1, 0), (1, 0)]  # (drow, dcol)
    for (row, col), _rid in sorted(cells.items()):
        x, y = col * SPACING, row * SPACING
        for dr, dc in directions:
            if (row + dr, col + dc) not in cells:
                out.append((x + dc * PERSON_OFFSET, y + dr * PERSON_OFFSET))
        if rows > 1 and cols > 1:
            for dr, dc in ((-1, -1), (-1, 1), (1, -1), (1, 1)):
                if all((row + a, col + b) not in cells for a, b in ((dr, 0), (0, dc), (dr, dc))):
                    out.append((x + dc * diagonal, y + dr * diagonal))
    return out


def _spread(
    spots: Sequence[tuple[float, float]], n: int, rng: random.Random
) -> list[tuple[float, float]]:
    """``n`` spots: the two farthest apart first (the ends of a line, opposite corners), then
    seeded picks among the rest."""
    if len(spots) < 2:
        return list(spots[:n])
    pairs = [
        (round(math.dist(a, b), 6), i, j)
        for i, a in enumerate(spots)
        for j, b in enumerate(spots)
        if i < j
    ]
    _, i, j = max(pairs, key=lambda p: (p[0], -p[1], -p[2]))
    rest = [spot for k, spot in enumerate(spots) if k not in (i, j)]
    rng.shuffle(rest)
    return [spots[i], spots[j], *rest][:n]


def _hops(scene: Scene) -> dict[str, dict[str, int]]:
    """Handovers needed between each pair of robots (breadth-first over meeting pairs)."""
    context = context_label(scene, {h.id: h.position for h in scene.humans})
    out: dict[str, dict[str, int]] = {}
    for src in scene.robots:
        dist = {src.id: 0}
        queue = deque([src])
        while queue:
            here = queue.popleft()
            for other in scene.robots:
                if (
                    other.id not in dist
                    and can_meet(here, other)
                    and not context.blocked(here.id, other.id)
                ):
                    dist[other.id] = dist[here.id] + 1
                    queue.append(other)
        out[src.id] = {r.id: dist.get(r.id, len(scene.robots) + 1) for r in scene.robots}
    return out


def _delivery_spec(deliveries: Sequence[tuple[str, str]], ordered: bool) -> dict[str, Any]:
    """One leaf per delivery; at most ``GROUP`` children per composite, so that no DFA is huge.

    Up to ``GROUP`` deliveries the root is ``F p100 & F p200 …`` (``F (p100 & F p200) & …``
    when ordered); more are grouped into intermediate nodes ``p1``, ``p2`` … (a deeper level of
    the tree, as for nested groups in an instruction). The ordered pair stays in the first group.
    """
    leaves = {f"p{100 * (k + 1)}": f"F delivered({o}, {u})" for k, (o, u) in enumerate(deliveries)}
    composites: dict[str, str] = {}

    def combine(children: Sequence[str], with_order: bool) -> str:
        if with_order and len(children) >= 2:
            parts = [f"F ({children[0]} & F {children[1]})", *[f"F {c}" for c in children[2:]]]
        else:
            parts = [f"F {c}" for c in children]
        return " & ".join(parts)

    level, first_level = list(leaves), True
    while len(level) > GROUP:
        groups = [level[i : i + GROUP] for i in range(0, len(level), GROUP)]
        level = []
        for k, group in enumerate(groups):
            name = f"p{len(composites) + 1}"
            composites[name] = combine(group, ordered and first_level and k == 0)
            level.append(name)
        first_level = False
    root = combine(level, ordered and first_level)
    return {"root": "p0", "formulas": {"p0": root, **composites, **leaves}}


def _and_list(items: Sequence[str], oxford: bool = False) -> str:
    """ "a", "a and b", "a, b and c"; with ``oxford`` a comma before "and" (for nested lists)."""
    if len(items) == 1:
        return items[0]
    return ", ".join(items[:-1]) + ("," if oxford else "") + " and " + items[-1]


def _instruction(
    deliveries: Sequence[tuple[str, str]],
    ordered: bool,
    names: Mapping[str, str],
    categories: Mapping[str, str],
) -> str:
    def the(oid: str) -> str:
        category = categories[oid]
        suffix = oid[len(category) :].lstrip("_")
        return f"the {category}" + (f" {suffix}" if suffix else "")

    def grouped(items: Sequence[tuple[str, str]]) -> str:
        # "Person A the bottle and the cup, and Person B the chips": one phrase per person
        by_person: dict[str, list[str]] = {}
        for o, u in items:
            by_person.setdefault(u, []).append(the(o))
        phrases = [f"{names[u]} {_and_list(objs)}" for u, objs in by_person.items()]
        several = any(len(objs) > 1 for objs in by_person.values())
        return _and_list(phrases, oxford=several)

    if not ordered:
        return f"Give {grouped(deliveries)}."
    (o1, u1), (o2, u2), rest = deliveries[0], deliveries[1], deliveries[2:]
    text = f"First give {names[u1]} {the(o1)}, then give {names[u2]} {the(o2)}"
    return text + (f"; also give {grouped(rest)}." if rest else ".")


def _tags(
    scene: Scene, deliveries: Sequence[tuple[str, str]], layout: str, ordered: bool
) -> frozenset[str]:
    tags = {layout, "multi-robot" if len(scene.robots) > 1 else "single-robot"}
    longest = max(len(delivery_chain(scene, o, u) or ()) for o, u in deliveries)
    if longest >= 2:
        tags.add("handover")
    if longest >= 3:
        tags.add("relay")
    if ordered:
        tags.add("ordering")
    return frozenset(tags)


# -- the Fig. 1 cell ------------------------------------------------------------------------------

_FIG1_SCENE: dict[str, Any] = {
    "units": "m",
    "robots": [
        {"id": "r1", "base": [0.0, 0.0, 0.0], "reach": 0.7, "model": "elfin3"},
        {"id": "r2", "base": [1.2, 0.0, 0.0], "reach": 0.9, "model": "ur5"},
    ],
    "objects": [
        {"id": "bottle", "category": "bottle", "position": [-0.4, 0.2, 0.05]},
        {"id": "chips", "category": "chips", "position": [1.5, -0.3, 0.05], "aliases": ["crisps"]},
    ],
    "humans": [
        {"id": "A", "name": "Person A", "position": [-0.5, 0.6, 0.0], "aliases": ["Alice"]},
        {"id": "B", "name": "Person B", "position": [1.9, 0.5, 0.0], "aliases": ["Bob"]},
    ],
    "surfaces": [{"id": "shelf", "center": [0.6, 0.3, 0.0], "size": [0.3, 0.3]}],
    "durations": dict(DURATIONS),
}


def fig1() -> Scenario:
    """The paper's Fig. 1 cell (an Elfin-3 and a UR5), the scene of ``two_arms.yaml``."""
    scene = scene_from_dict(copy.deepcopy(_FIG1_SCENE), source="scenario fig1")
    deliveries = [("bottle", "A"), ("chips", "B")]
    return Scenario(
        name="fig1",
        scene=scene,
        spec_dict=_delivery_spec(deliveries, ordered=False),
        instruction="Give Person A the bottle and Person B the chips.",
        tags=frozenset({"fig1", "pair", "multi-robot"}),
        n_task=2,
        n_robot=2,
        layout="pair",
        seed=0,
    )


# -- the catalogue --------------------------------------------------------------------------------


def catalogue(tags: Iterable[str] | None = None) -> tuple[Scenario, ...]:
    """The named scenarios (Table II's twelve configurations and ``fig1``).

    Args:
        tags: keep only scenarios carrying all of these tags (e.g. ``{"paper", "line"}``).
    """
    entries = [fig1()]
    for n_task, n_robot, layout in PAPER_CONFIGS:
        s = generate(n_task, n_robot, layout, CATALOGUE_SEED)
        entries.append(
            Scenario(
                name=s.name,
                scene=s.scene,
                spec_dict=s.spec_dict,
                instruction=s.instruction,
                tags=s.tags | {"paper"},
                n_task=s.n_task,
                n_robot=s.n_robot,
                layout=s.layout,
                seed=s.seed,
            )
        )
    wanted = frozenset(tags or ())
    return tuple(s for s in entries if wanted <= s.tags)


def names() -> tuple[str, ...]:
    """Names of the catalogue entries, in catalogue order."""
    return ("fig1", *(scenario_name(t, r, layout) for t, r, layout in PAPER_CONFIGS))


def get(name: str) -> Scenario:
    """The catalogue entry called ``name`` (e.g. ``"2-4-line"`` or ``"fig1"``).

    Raises:
        UnknownEntityError: no such entry; the message lists the names.
    """
    if name == "fig1":
        return fig1()
    for s in catalogue():
        if s.name == name:
            return s
    raise UnknownEntityError(f"unknown scenario {name!r}; catalogue has: {', '.join(names())}")


# -- example files --------------------------------------------------------------------------------


def _flow(item: Mapping[str, Any]) -> str:
    return str(
        yaml.safe_dump(dict(item), default_flow_style=True, sort_keys=False, width=10_000)
    ).strip()


def render_scene_yaml(s: Scenario) -> str:
    """The scene file of ``s`` (one flow mapping per entity, like ``two_arms.yaml``)."""
    data = s.scene.to_dict()
    lines = [
        f"# Scenario {s.name} (hltl.sim.scenarios, seed {s.seed}): {s.instruction}",
        "# Generated by hltl.sim.scenarios.write_examples; edit the generator, not this file.",
        f"units: {data['units']}",
    ]
    for key in ("robots", "objects", "humans", "surfaces"):
        if data[key]:
            lines.append(f"{key}:")
            lines += [f"  - {_flow(item)}" for item in data[key]]
    for key in ("durations", "human_reach"):
        if key in data:
            value = data[key]
            lines.append(f"{key}: {_flow(value) if isinstance(value, dict) else value}")
    return "\n".join(lines) + "\n"


def render_spec_yaml(s: Scenario) -> str:
    """The spec file of ``s`` in DESIGN.md's layout, with the instruction as a comment."""
    lines = [
        f"# Scenario {s.name}: {s.instruction}",
        "# Generated by hltl.sim.scenarios.write_examples; edit the generator, not this file.",
        f"root: {s.spec_dict['root']}",
        "formulas:",
    ]
    lines += [f"  {name}: {json.dumps(text)}" for name, text in s.spec_dict["formulas"].items()]
    return "\n".join(lines) + "\n"


def example_files(scenarios: Iterable[Scenario] | None = None) -> dict[str, str]:
    """Relative path (under ``examples/``) to text, for every catalogue entry."""
    out: dict[str, str] = {}
    for s in catalogue() if scenarios is None else scenarios:
        out[f"scenes/{s.name}.yaml"] = render_scene_yaml(s)
        out[f"specs/suite/{s.name}.yaml"] = render_spec_yaml(s)
    return out


def write_examples(directory: str | Path) -> list[Path]:
    """Write every catalogue entry as ``scenes/<name>.yaml`` and ``specs/suite/<name>.yaml``.

    Args:
        directory: the examples folder (``examples`` in the repository).

    Returns:
        The paths written.
    """
    root = Path(directory)
    written = []
    for rel, text in example_files().items():
        path = root / rel
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text, encoding="utf-8")
        written.append(path)
    return written
