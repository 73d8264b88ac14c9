"""The unified search graph, compiled: integer-coded states, ground skill instances, atom tables."""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

from hltl.errors import UnknownEntityError
from hltl.skills.cost import AnalyticCostModel, ChainedCostModel, CostModel, Joints
from hltl.skills.kinematics import Kinematics
from hltl.skills.library import DEFAULT_SKILLS, Action, Skill, Transition, state_atoms
from hltl.skills.semantics import ActionSemantics
from hltl.spec.hierarchy import HSpec
from hltl.spec.monitor import HierarchyMonitor, MonitorState
from hltl.spec.printer import atoms as formula_atoms
from hltl.spec.syntax import PREDICATES, And, Atom, Eventually, Formula
from hltl.world.geometry import distance
from hltl.world.scene import Scene, Vec3
from hltl.world.state import REST, Loc, WorldState, initial_world

# A search node x = (s, q): object places (codes), hand poses (hand-state ids, or None when
# durations are fixed and poses cannot change a cost), and the monitor state. η is derived
# (docs/model.md). A hand state is a point, and with a ChainedCostModel the arm's joints there.
Node = tuple[tuple[int, ...], tuple[int, ...] | None, MonitorState]

# Search costs are integers in these units (microseconds): sums of integers do not depend on the
# order they are added in, so the search (its ties, its expansions) is the same in every run,
# whatever PYTHONHASHSEED says. A plan's makespan is the sum of its steps' rounded durations.
TICKS_PER_SECOND = 1_000_000


def to_ticks(seconds: float) -> int:
    """Seconds as integer search-cost units (rounded to the nearest microsecond)."""
    return round(seconds * TICKS_PER_SECOND)


def to_seconds(ticks: float) -> float:
    """Integer search-cost units back to seconds (``inf`` stays ``inf``)."""
    return ticks / TICKS_PER_SECOND


@dataclass(frozen=True, slots=True)
class Instance:
    """A ground skill instance in integer codes (hot loop of the search)."""

    index: int
    obj: int
    pre: int
    post: int
    executors: int  # bit mask over robots
    free: tuple[int, ...]
    events: frozenset[Atom]
    event_bits: int  # ``events`` as a bit mask over ``Problem.spec_atom_list``
    hands: tuple[tuple[int, int], ...]  # (robot index, point index)
    lower: int  # duration lower bound in ticks (exact when durations are fixed)
    const: float  # analytic model: grasp/release/exchange time in seconds
    action: Action


class Problem:
    """A planning problem: scene, world w_t, spec with its monitor and q_t, skills, cost model."""

    def __init__(
        self,
        scene: Scene,
        spec: HSpec,
        *,
        world: WorldState | None = None,
        monitor: HierarchyMonitor | None = None,
        q0: MonitorState | None = None,
        skills: Sequence[Skill] = DEFAULT_SKILLS,
        cost: CostModel | None = None,
        kinematics: Kinematics | None = None,
    ) -> None:
        self.scene = scene
        self.spec = spec
        self.world = initial_world(scene) if world is None else world
        self.monitor = HierarchyMonitor(spec) if monitor is None else monitor
        self.q0 = self.monitor.initial if q0 is None else q0
        self.semantics = ActionSemantics.of(scene, cost=cost, skills=skills, kinematics=kinematics)
        self.cost = self.semantics.cost
        self.situation = self.semantics.situation(self.world)
        self.context = self.situation.context

        # every predicate atom of the spec, and which formulas mention which objects
        self.formula_atoms: dict[str, frozenset[Atom]] = {
            name: frozenset(a for a in formula_atoms(f) if a.is_predicate)
            for name, f in spec.formulas
        }
        self.spec_atoms: frozenset[Atom] = frozenset().union(*self.formula_atoms.values())
        check_atoms_against_scene(self.spec_atoms, scene)
        # the hot loop unions a step's events as bit masks over these (no Atom hashing)
        self.spec_atom_list: tuple[Atom, ...] = tuple(sorted(self.spec_atoms))
        self.atom_bit: dict[Atom, int] = {a: 1 << i for i, a in enumerate(self.spec_atom_list)}

        self.objects: tuple[str, ...] = tuple(oid for oid, _ in self.world.objects)
        self.robots: tuple[str, ...] = scene.robot_ids
        self.obj_index = {o: i for i, o in enumerate(self.objects)}
        self.robot_index = {r: i for i, r in enumerate(self.robots)}

        self.locs: list[Loc] = [REST]
        self.locs += [Loc("held", r) for r in self.robots]
        self.locs += [Loc("on", s) for s in scene.surface_ids]
        self.locs += [Loc("delivered", h) for h in scene.human_ids]
        self.loc_code = {loc: i for i, loc in enumerate(self.locs)}
        self.held_code = {i: self.loc_code[Loc("held", r)] for i, r in enumerate(self.robots)}
        self.code_holder = {c: i for i, c in self.held_code.items()}

        # hand states when durations depend on hand poses: a point and, when they depend on the
        # arms' joints (ChainedCostModel), the joints the arm has there (None: no arm model)
        self.points: list[Vec3] = []
        self.joints: list[Joints | None] = []
        self._point_index: dict[tuple[Vec3, Joints | None], int] = {}
        self.track_hands = not self.cost.fixed
        self.chained: ChainedCostModel | None = (
            self.cost if isinstance(self.cost, ChainedCostModel) else None
        )
        # (instance, its executors' start states) -> (ticks or None, executors' end states)
        self._timed: dict[tuple[int, ...], tuple[int | None, tuple[tuple[int, int], ...]]] = {}
        # Objects no open formula mentions are never picked up only under fixed durations: when
        # durations depend on hand poses, moving such an object can bring a hand closer to where
        # it is needed next (docs/planner.md, "Exactness"), so every object stays in play.
        self.prune_irrelevant = self.cost.fixed
        self.speeds: tuple[float, ...] = ()
        if isinstance(self.cost, AnalyticCostModel):
            self.speeds = tuple(self.cost._speed(r) for r in self.robots)

        self.instances: list[Instance] = []
        n_locs = len(self.locs)
        self.by_obj_pre: list[list[list[Instance]]] = [
            [[] for _ in range(n_locs)] for _ in self.objects
        ]
        # per instance its own transition: one action can have several (a pick from where the
        # object rests and one from a surface), and a duration depends on which
        self.transitions: list[Transition] = []
        for action, trans in self.semantics.instances(self.world):
            self.transitions.append(trans)
            oi = self.obj_index[trans.obj]
            inst = Instance(
                index=len(self.instances),
                obj=oi,
                pre=self.loc_code[trans.pre],
                post=self.loc_code[trans.post],
                executors=sum(1 << self.robot_index[r] for r in action.robots),
                free=tuple(self.robot_index[r] for r in trans.free),
                events=trans.events & self.spec_atoms,
                event_bits=self.atom_bits(trans.events & self.spec_atoms),
                hands=tuple((self.robot_index[r], self._point(p)) for r, p in trans.hands),
                lower=to_ticks(self.cost.lower_bound(action, trans)),
                const=self.cost.lower_bound(action, trans),
                action=action,
            )
            self.instances.append(inst)
            self.by_obj_pre[oi][inst.pre].append(inst)

        # state atoms per (object, place), restricted to the spec's atoms
        self.state_atoms: list[list[frozenset[Atom]]] = [
            [state_atoms(o, loc) & self.spec_atoms for loc in self.locs] for o in self.objects
        ]
        self.state_bits: list[list[int]] = [
            [self.atom_bits(a) for a in row] for row in self.state_atoms
        ]
        # instances no monitor can see: no spec event, and the object has no spec state atom
        # where it starts or ends (picks and robot-to-robot handovers in delivery tasks)
        self.invisible: tuple[bool, ...] = tuple(
            not inst.events
            and not self.state_atoms[inst.obj][inst.pre]
            and not self.state_atoms[inst.obj][inst.post]
            for inst in self.instances
        )
        self.state_atom_objects: tuple[int, ...] = tuple(
            i for i in range(len(self.objects)) if any(self.state_atoms[i])
        )
        # instances the left-shift rule may move one step earlier (docs/planner.md): the
        # invisible ones, and every instance when the spec is a conjunction of events
        self.events_commute = _events_commute(spec, self.state_atom_objects)
        self.shiftable: tuple[bool, ...] = (
            tuple(True for _ in self.instances) if self.events_commute else self.invisible
        )
        # objects each formula is about
        self.formula_objects: dict[str, frozenset[int]] = {
            name: frozenset(
                self.obj_index[o] for a in atoms_ for o in _object_args(a) if o in self.obj_index
            )
            for name, atoms_ in self.formula_atoms.items()
        }
        self._relevant_cache: dict[frozenset[str], frozenset[int]] = {}
        self._dist: dict[tuple[int, int], float] = {}
        self.symmetry = Symmetry.of(self, spec)

    # -- encoding --------------------------------------------------------------------------------
    def atom_bits(self, atoms_: frozenset[Atom]) -> int:
        """Spec atoms as a bit mask (see ``spec_atom_list``)."""
        bits = 0
        for a in atoms_:
            bits |= self.atom_bit[a]
        return bits

    def bits_atoms(self, bits: int) -> frozenset[Atom]:
        """The inverse of :meth:`atom_bits`."""
        out = []
        i = 0
        while bits:
            if bits & 1:
                out.append(self.spec_atom_list[i])
            bits >>= 1
            i += 1
        return frozenset(out)

    def _point(self, p: Vec3, joints: Joints | None = None) -> int:
        key = (p, joints)
        idx = self._point_index.get(key)
        if idx is None:
            idx = len(self.points)
            self.points.append(p)
            self.joints.append(joints)
            self._point_index[key] = idx
        return idx

    def start(self) -> Node:
        status = dict(self.world.objects)
        locs = tuple(self.loc_code[status[o].loc] for o in self.objects)
        hands: tuple[int, ...] | None = None
        if self.track_hands:
            home = self.semantics.kinematics.home_point
            hands = tuple(
                self._start_state(r, self.world.hand_position(r) or home(self.scene.robot(r)))
                for r in self.robots
            )
        return (locs, hands, self.q0)

    def relevant(self, done: frozenset[str]) -> frozenset[int]:
        """Objects that some formula not yet done is about: only they are worth touching."""
        rel = self._relevant_cache.get(done)
        if rel is None:
            rel = frozenset().union(
                *(objs for name, objs in self.formula_objects.items() if name not in done)
            )
            self._relevant_cache[done] = rel
        return rel

    def travel(self, a: int, b: int) -> float:
        key = (a, b) if a <= b else (b, a)
        d = self._dist.get(key)
        if d is None:
            d = distance(self.points[a], self.points[b])
            self._dist[key] = d
        return d

    def duration(self, inst: Instance, hands: tuple[int, ...] | None) -> int | None:
        """The instance's duration in ticks when the hands start at ``hands``; ``None`` when the
        cost model says it cannot be done from there (``math.inf``: no motion plan)."""
        if hands is None:
            return inst.lower
        if self.speeds:
            t = 0.0
            for r, p in inst.hands:
                t = max(t, self.travel(hands[r], p) / self.speeds[r])
            return to_ticks(t + inst.const)
        if self.chained is not None:
            return self._chain(inst, hands)[0]
        start = {self.robots[r]: self.points[hands[r]] for r, _ in inst.hands}
        d = self.cost.duration(inst.action, self.transitions[inst.index], start)
        return to_ticks(d) if math.isfinite(d) else None

    def ends(self, inst: Instance, hands: tuple[int, ...]) -> tuple[tuple[int, int], ...]:
        """Where the instance leaves its executors' hands from ``hands``: (robot index, hand
        state); with a ChainedCostModel the state carries the joints its motion ends in."""
        return inst.hands if self.chained is None else self._chain(inst, hands)[1]

    def _start_state(self, robot: str, point: Vec3) -> int:
        """The hand state of ``robot`` in the start node: its hand point, and its arm's joints
        now when durations depend on them."""
        joints = None if self.chained is None else self.chained.arm_state(robot, point)
        return self._point(point, joints)

    def _chain(
        self, inst: Instance, hands: tuple[int, ...]
    ) -> tuple[int | None, tuple[tuple[int, int], ...]]:
        """Duration (ticks, None: no motion) and end states of ``inst`` from ``hands`` under
        the ChainedCostModel, computed once per instance and start states."""
        key = (inst.index, *(hands[r] for r, _ in inst.hands))
        hit = self._timed.get(key)
        if hit is None:
            assert self.chained is not None
            start = {self.robots[r]: self.points[hands[r]] for r, _ in inst.hands}
            joints = {
                self.robots[r]: q for r, _ in inst.hands if (q := self.joints[hands[r]]) is not None
            }
            d, after = self.chained.timed(inst.action, self.transitions[inst.index], start, joints)
            ends = tuple(
                (r, self._point(self.points[p], after.get(self.robots[r]))) for r, p in inst.hands
            )
            hit = self._timed[key] = (to_ticks(d) if math.isfinite(d) else None, ends)
        return hit


# An instance up to its object: what it needs, what it does, who does it and how long it takes.
_InstanceShape = tuple[int, int, int, tuple[int, ...], int, bool]


def _shape(inst: Instance) -> _InstanceShape:
    return (inst.pre, inst.post, inst.executors, inst.free, inst.lower, inst.event_bits != 0)


@dataclass(frozen=True, slots=True)
class Symmetry:
    """Interchangeable objects (docs/planner.md, "Interchangeable objects"): with fixed
    durations and a conjunction of events, two objects whose instances have the same shapes
    (places, robots, durations, whether they fire the object's leaf) and whose leaves ask for
    the same thing of each (``delivered(·, A)``) can swap places without changing what any plan
    costs from there, as long as neither leaf has fired. The search keeps one node per such
    swap: it sorts the places of the unfired members of each class.

    ``classes``: per class, its members and each member's leaf (``None``: no leaf mentions it).
    ``twin``: ``twin[o][k]`` is object ``o``'s instance at position ``k`` of the shape order, so
    an instance of one member maps to the same position of another (``counterpart``).
    """

    classes: tuple[tuple[tuple[int, str | None], ...], ...]
    position: dict[int, int]  # instance index -> its position among its object's instances
    twin: dict[int, tuple[Instance, ...]]

    @staticmethod
    def of(problem: Problem, spec: HSpec) -> Symmetry:
        if problem.track_hands or not problem.events_commute or not problem.prune_irrelevant:
            return Symmetry((), {}, {})
        # per object its leaf and what the leaf asks of it (the atom without the object)
        leaf_of: dict[int, tuple[str, tuple[str, tuple[str, ...]]]] = {}
        for name in spec.leaves:
            f = spec.formula(name)
            assert isinstance(f, Eventually) and isinstance(f.operand, Atom)
            a = f.operand
            for oid in _object_args(a):
                if oid in problem.obj_index:
                    leaf_of[problem.obj_index[oid]] = (name, (a.name, a.args[1:]))
        groups: dict[object, list[tuple[int, str | None]]] = {}
        ordered: dict[int, tuple[Instance, ...]] = {}
        for o in range(len(problem.objects)):
            insts = [i for row in problem.by_obj_pre[o] for i in row]
            ordered[o] = tuple(sorted(insts, key=lambda i: (_shape(i), i.index)))
            leaf = leaf_of.get(o)
            key = (None if leaf is None else leaf[1], tuple(_shape(i) for i in ordered[o]))
            groups.setdefault(key, []).append((o, None if leaf is None else leaf[0]))
        classes = tuple(tuple(g) for g in groups.values() if len(g) > 1)
        members = {o for c in classes for o, _ in c}
        twin = {o: ordered[o] for o in members}
        position = {inst.index: k for o in members for k, inst in enumerate(ordered[o])}
        return Symmetry(classes, position, twin)

    def counterpart(self, inst: Instance, obj: int) -> Instance:
        """``inst`` done to ``obj`` instead (``obj`` in the same class as ``inst.obj``)."""
        if obj == inst.obj:
            return inst
        return self.twin[obj][self.position[inst.index]]


def _events_commute(spec: HSpec, state_atom_objects: tuple[int, ...]) -> bool:
    """True when making an event happen one step earlier can never hurt: every leaf is ``F a``
    for an event atom ``a`` (no state atom anywhere), no two leaves are about the same object,
    and every composite is a conjunction of ``F child``. Then a formula is done exactly when all
    the leaves under it have fired, in any order, so firing one earlier leaves the monitor
    state after the later step unchanged, only frees robots, and keeps every later instance
    relevant and alive (docs/planner.md, "Left-shift rule")."""
    if state_atom_objects:
        return False
    names = {name for name, _ in spec.formulas}
    seen: set[str] = set()
    for name in spec.leaves:
        f = spec.formula(name)
        if not (isinstance(f, Eventually) and isinstance(f.operand, Atom)):
            return False
        if not f.operand.is_predicate or f.operand.name not in _EVENT_PREDICATES:
            return False
        for o in _object_args(f.operand):
            if o in seen:
                return False
            seen.add(o)
    return all(_conjunction_of_children(spec.formula(n), names) for n in spec.composites)


_EVENT_PREDICATES = frozenset({"delivered", "placed", "picked"})


def _conjunction_of_children(f: Formula, names: set[str]) -> bool:
    if isinstance(f, And):
        return _conjunction_of_children(f.left, names) and _conjunction_of_children(f.right, names)
    return (
        isinstance(f, Eventually)
        and isinstance(f.operand, Atom)
        and not f.operand.args
        and f.operand.name in names
    )


def _object_args(atom: Atom) -> tuple[str, ...]:
    if atom.name == "holding":
        return atom.args[1:]
    if atom.name in ("delivered", "placed", "picked", "at"):
        return atom.args[:1]
    return ()


_ARG_KINDS: dict[str, tuple[str, ...]] = {
    "delivered": ("object", "human"),
    "placed": ("object", "surface"),
    "picked": ("object",),
    "holding": ("robot", "object"),
    "at": ("object", "surface"),
}


def check_atoms_against_scene(atoms_: frozenset[Atom], scene: Scene) -> None:
    """Every predicate atom must name entities of the right kind that the scene has."""
    ids = {
        "object": scene.object_ids,
        "human": scene.human_ids,
        "surface": scene.surface_ids,
        "robot": scene.robot_ids,
    }
    for atom in sorted(atoms_):
        kinds = _ARG_KINDS.get(atom.name)
        if kinds is None or len(kinds) != PREDICATES.get(atom.name, -1):
            continue
        for value, kind in zip(atom.args, kinds, strict=False):
            if value not in ids[kind]:
                have = ", ".join(ids[kind]) or "none"
                raise UnknownEntityError(
                    f"{atom}: unknown {kind} {value!r}; the scene ({scene.source}) has: {have}"
                )
