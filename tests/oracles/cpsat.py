"""Time-indexed CP-SAT model of the planning problem: an optimality oracle independent of search.

Supported specs: leaves ``F delivered(o, u)`` / ``F placed(o, s)``; composites built with ``&``
and ``|`` from ``F child`` and non-strict ordering chains ``F (c1 & F (c2 & … F ck))`` (each
child completes no earlier than the one before it). Anything else raises :class:`UnsupportedSpec`.

Why the horizon is exact
------------------------
Write OPT for the optimal makespan and d_min > 0 for the smallest fixed skill duration.

1. In the supported class an empty step fires nothing: leaves read event atoms only, and a
   composite's value depends only on the order (ties included) of its children's firing steps.
   Deleting the empty steps of a plan keeps it valid and its cost, so some optimal plan has no
   empty step, and each of its steps lasts at least d_min: it has at most floor(OPT / d_min)
   steps.
2. A model with T steps (trailing steps may be empty, cost 0) therefore contains an optimal plan
   as soon as T >= floor(OPT / d_min). Any feasible solution of value V bounds OPT <= V, so
   solving with T and getting the optimum V at T proves V == OPT when floor(V / d_min) <= T;
   otherwise one more solve with T = floor(V / d_min) is exact.
3. Infeasibility is proved without a horizon: project any plan onto one object o. Other objects
   only take robots away, so o's projection is a valid single-object plan; after a delivery o is
   gone, so o is delivered at most once. Hence the set of leaves that can ever fire is contained
   in the events reachable in o's single-object graph (rest, held by r, on s, delivered to u),
   with at most one delivery per object, and the root's firing implies its Boolean value (all
   orderings dropped) under that set. If no choice of at most one reachable delivery per object
   makes the root true, no plan exists and the result is None.
4. If the relaxation says "maybe" but T0 (the sum of the leaves' single-object distances) and
   its doublings up to 8 * T0 give no solution, we cannot tell and raise
   :class:`HorizonUndetermined` rather than guess. For specs whose leaves move distinct objects
   and whose orderings are acyclic the relaxation is exact (objects can be served one after the
   other, each along its shortest single-object path, with every robot free in between), so T0
   suffices and this never happens; ``random_instances`` generates such specs.
"""

from __future__ import annotations

import itertools
import math
from collections import deque
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any

from hltl.spec.syntax import And, Atom, Eventually, Formula, Or
from hltl.world.scene import Scene

from .brute_force import Instance, fixed_durations
from .model import (
    REST,
    Hierarchy,
    Location,
    can_hand_over,
    hierarchy,
    human_inside,
    reaches,
    surface_point,
)

SCALE = 1000  # durations in integer milliseconds


class UnsupportedSpec(NotImplementedError):
    """The spec is outside the class the CP-SAT model encodes; skip the cross-check."""


class HorizonUndetermined(RuntimeError):
    """Neither a plan within the tried horizons nor a proof of infeasibility was found."""


@dataclass(frozen=True)
class CpSatResult:
    makespan: float | None
    plan: dict[str, Any] | None
    horizon: int  # steps in the last model solved (0 when infeasibility was proved without one)


# A composite's value as a tree: ("D", child) | ("and", l, r) | ("or", l, r) | ("chain", names)
Term = tuple[Any, ...]


def cpsat_makespan(
    scene: Scene, spec: Any, horizon_steps: int | None = None, time_limit: float = 60.0
) -> float | None:
    """The optimal makespan by CP-SAT; None when no plan exists.

    Args:
        horizon_steps: None picks a provably sufficient horizon (module docstring); a number
            fixes T, and the answer is then the best plan of at most T steps (exact only when
            T is large enough).
        time_limit: work per CP-SAT solve, in its deterministic time units (about seconds of one
            core; the same on a loaded machine), with 30 times that in wall seconds as a backstop.

    Raises:
        UnsupportedSpec: the spec or durations are outside the encoded class.
        HorizonUndetermined: see the module docstring, point 4.
        TimeoutError: CP-SAT did not prove optimality or infeasibility within ``time_limit``
            (its work limit).
    """
    return cpsat_solve(scene, spec, horizon_steps, time_limit).makespan


def cpsat_solve(
    scene: Scene, spec: Any, horizon_steps: int | None = None, time_limit: float = 60.0
) -> CpSatResult:
    """Like :func:`cpsat_makespan`, also returning the plan (DESIGN.md JSON, no bindings)."""
    h = hierarchy(spec)
    terms = {name: _term(h, name) for name in h.bottom_up() if h.children[name]}
    leaf_events = {leaf: _leaf_event(h.formulas[leaf]) for leaf in h.leaves}
    fixed = fixed_durations(scene)
    grounding = _ground(scene)
    if horizon_steps is not None:
        return _solve(scene, h, terms, leaf_events, fixed, grounding, horizon_steps, time_limit)

    d_min = min((fixed[a.skill] for a, _, _ in grounding), default=math.inf)
    if d_min == 0:
        raise UnsupportedSpec("a skill with a grounded instance has duration 0: no step bound")
    dist = _single_object_distances(scene, grounding)
    if not _relaxation_feasible(scene, h, terms, leaf_events, dist):
        return CpSatResult(None, None, 0)
    t0 = max(1, sum(_leaf_distance(leaf_events[leaf], dist) for leaf in h.leaves))
    horizon = t0
    while True:
        result = _solve(scene, h, terms, leaf_events, fixed, grounding, horizon, time_limit)
        if result.makespan is not None:
            break
        if horizon >= 8 * t0:
            raise HorizonUndetermined(
                f"no plan within {horizon} steps, and the relaxation does not prove infeasibility"
            )
        horizon *= 2
    bound = math.floor(result.makespan / d_min + 1e-9)
    if bound <= horizon:
        return result
    return _solve(scene, h, terms, leaf_events, fixed, grounding, bound, time_limit)


# -- the supported spec class ---------------------------------------------------------------------


def _leaf_event(f: Formula) -> Atom:
    if (
        isinstance(f, Eventually)
        and isinstance(f.operand, Atom)
        and f.operand.name in ("delivered", "placed")
        and len(f.operand.args) == 2
    ):
        return f.operand
    raise UnsupportedSpec(f"leaf {f!r} is not F delivered(o, u) or F placed(o, s)")


def _term(h: Hierarchy, name: str) -> Term:
    kids = set(h.children[name])

    def child(f: Formula) -> str | None:
        return f.name if isinstance(f, Atom) and not f.args and f.name in kids else None

    def chain(f: Formula) -> list[str]:  # the operand of an F: "c" or "c & F(...)"
        if child(f) is not None:
            return [f.name]  # type: ignore[union-attr]
        if isinstance(f, And):
            for first, rest in ((f.left, f.right), (f.right, f.left)):
                c = child(first)
                if c is not None and isinstance(rest, Eventually):
                    return [c, *chain(rest.operand)]
        raise UnsupportedSpec(f"{name}: {f!r} is not a child or an ordering 'c & F …'")

    def walk(f: Formula) -> Term:
        if isinstance(f, And):
            return ("and", walk(f.left), walk(f.right))
        if isinstance(f, Or):
            return ("or", walk(f.left), walk(f.right))
        if isinstance(f, Eventually):
            names = chain(f.operand)
            return ("D", names[0]) if len(names) == 1 else ("chain", tuple(names))
        raise UnsupportedSpec(f"{name}: {f!r} is outside &, |, F child and F (c & F …)")

    return walk(h.formulas[name])


# -- grounding and the single-object relaxation ---------------------------------------------------


def _ground(scene: Scene) -> list[tuple[Instance, Location, Location]]:
    """Every skill instance that is geometrically possible, with the object's location before
    and after it (a pick is grounded once per place it can pick from)."""
    out: list[tuple[Instance, Location, Location]] = []
    for o in scene.objects:
        sources: list[tuple[Location, tuple[float, float, float]]] = [(REST, o.position)]
        sources += [(("on", s.id), surface_point(scene, s.id)) for s in scene.surfaces]
        for r in scene.robots:
            held: Location = ("held", r.id)
            for loc, point in sources:
                if reaches(r, point):
                    out.append((Instance("pick", (r.id,), o.id), loc, held))
            for s in scene.surfaces:
                if reaches(r, surface_point(scene, s.id)):
                    out.append((Instance("place", (r.id,), o.id, s.id), held, ("on", s.id)))
            for r2 in scene.robots:
                if can_hand_over(scene, r, r2):
                    out.append(
                        (Instance("handover_r2r", (r.id, r2.id), o.id), held, ("held", r2.id))
                    )
            for u in scene.humans:
                if human_inside(r, u, scene.human_reach):
                    out.append(
                        (Instance("handover_r2h", (r.id,), o.id, u.id), held, ("delivered", u.id))
                    )
    return out


def _single_object_distances(
    scene: Scene, grounding: Sequence[tuple[Instance, Location, Location]]
) -> dict[str, dict[Location, int]]:
    """Per object, the fewest actions from its start to each location, moving it alone."""
    out: dict[str, dict[Location, int]] = {}
    for o in scene.objects:
        edges: dict[Location, list[Location]] = {}
        for a, pre, post in grounding:
            if a.object == o.id:
                edges.setdefault(pre, []).append(post)
        dist = {REST: 0}
        queue = deque([REST])
        while queue:
            loc = queue.popleft()
            for nxt in edges.get(loc, ()):
                if nxt not in dist:
                    dist[nxt] = dist[loc] + 1
                    queue.append(nxt)
        out[o.id] = dist
    return out


def _event_location(event: Atom) -> tuple[str, Location]:
    obj, target = event.args
    return obj, (("delivered", target) if event.name == "delivered" else ("on", target))


def _leaf_distance(event: Atom, dist: Mapping[str, Mapping[Location, int]]) -> int:
    obj, loc = _event_location(event)
    return dist.get(obj, {}).get(loc, 0)


def _relaxation_feasible(
    scene: Scene,
    h: Hierarchy,
    terms: Mapping[str, Term],
    leaf_events: Mapping[str, Atom],
    dist: Mapping[str, Mapping[Location, int]],
) -> bool:
    options = []
    for o in scene.objects:
        deliveries = [loc for loc in dist[o.id] if loc[0] == "delivered"]
        options.append([None, *deliveries])
    for choice in itertools.product(*options):
        chosen = dict(zip(scene.object_ids, choice, strict=True))
        value: dict[str, bool] = {}
        for name in h.bottom_up():
            if h.children[name]:
                value[name] = _bool_term(terms[name], value)
            else:
                value[name] = _possible(leaf_events[name], dist, chosen)
        if value[h.root]:
            return True
    return False


def _possible(
    event: Atom, dist: Mapping[str, Mapping[Location, int]], chosen: Mapping[str, Location | None]
) -> bool:
    """Whether one object-alone run can make ``event`` true, given the delivery it ends with."""
    obj, loc = _event_location(event)
    if obj not in dist or loc not in dist[obj]:
        return False
    return loc[0] == "on" or chosen[obj] == loc


def _bool_term(t: Term, value: Mapping[str, bool]) -> bool:
    if t[0] == "D":
        return value[t[1]]
    if t[0] == "chain":
        return all(value[c] for c in t[1])
    left, right = _bool_term(t[1], value), _bool_term(t[2], value)
    return left and right if t[0] == "and" else left or right


# -- the CP-SAT model -----------------------------------------------------------------------------


def _solve(
    scene: Scene,
    h: Hierarchy,
    terms: Mapping[str, Term],
    leaf_events: Mapping[str, Atom],
    fixed: Mapping[str, float],
    grounding: Sequence[tuple[Instance, Location, Location]],
    horizon: int,
    time_limit: float,
) -> CpSatResult:
    from ortools.sat.python import cp_model

    m = cp_model.CpModel()
    T = horizon
    locations: list[Location] = [REST]
    locations += [("held", r.id) for r in scene.robots]
    locations += [("on", s.id) for s in scene.surfaces]
    locations += [("delivered", u.id) for u in scene.humans]
    loc = {
        (o.id, t, L): m.NewBoolVar(f"loc[{o.id},{t},{L}]")
        for o in scene.objects
        for t in range(T + 1)
        for L in locations
    }
    x = {(i, t): m.NewBoolVar(f"x[{i},{t}]") for i in range(len(grounding)) for t in range(T)}
    durations = {s: round(d * SCALE) for s, d in fixed.items()}
    for s, d in fixed.items():
        if abs(d * SCALE - durations[s]) > 1e-6:
            raise UnsupportedSpec(f"duration {d} of {s} is not a multiple of 1/{SCALE} s")
    step_cost = [m.NewIntVar(0, max(durations.values()), f"dur[{t}]") for t in range(T)]

    for o in scene.objects:
        for L in locations:
            m.Add(loc[(o.id, 0, L)] == (1 if L == REST else 0))
        for t in range(T + 1):
            m.AddExactlyOne(loc[(o.id, t, L)] for L in locations)
    holding = {
        (r.id, t): sum(loc[(o.id, t, ("held", r.id))] for o in scene.objects)
        for r in scene.robots
        for t in range(T + 1)
    }
    for t in range(T):
        by_robot: dict[str, list[Any]] = {r.id: [] for r in scene.robots}
        by_object: dict[str, list[Any]] = {o.id: [] for o in scene.objects}
        for i, (a, pre, post) in enumerate(grounding):
            xi = x[(i, t)]
            for r in a.robots:
                by_robot[r].append(xi)
            by_object[a.object].append(xi)
            m.AddImplication(xi, loc[(a.object, t, pre)])
            if a.skill == "pick":
                m.Add(holding[(a.robots[0], t)] == 0).OnlyEnforceIf(xi)
            elif a.skill == "handover_r2r":
                m.Add(holding[(a.robots[1], t)] == 0).OnlyEnforceIf(xi)
            m.AddImplication(xi, loc[(a.object, t + 1, post)])
            m.Add(step_cost[t] >= durations[a.skill]).OnlyEnforceIf(xi)
        for xs in by_robot.values():
            m.AddAtMostOne(xs)
        for o in scene.objects:
            m.AddAtMostOne(by_object[o.id])
            acted = sum(by_object[o.id])
            for L in locations:  # nothing acted on o: it stays where it is
                m.Add(loc[(o.id, t + 1, L)] >= loc[(o.id, t, L)] - acted)

    done = _monitors(m, h, terms, leaf_events, grounding, x, T)
    m.Add(done[h.root][T - 1] == 1)
    m.Minimize(sum(step_cost))

    solver = cp_model.CpSolver()
    # the limit is on work, not on the wall clock: one worker's search is the same on every run,
    # and its deterministic time does not grow with the machine's load (a wall-clock limit of
    # 120 s ran out on the 4-4-line scenario at load 10-19, which one worker proves in 9 units);
    # the wall clock is only a backstop against a hang
    solver.parameters.num_workers = 1
    solver.parameters.max_deterministic_time = time_limit
    solver.parameters.max_time_in_seconds = 30 * time_limit
    status = solver.Solve(m)
    if status == cp_model.INFEASIBLE:
        return CpSatResult(None, None, horizon)
    if status != cp_model.OPTIMAL:
        raise TimeoutError(f"CP-SAT ended with {solver.StatusName(status)} at horizon {horizon}")

    root_step = next(t for t in range(T) if solver.Value(done[h.root][t]))
    steps = []
    clock = 0.0
    for t in range(root_step + 1):
        chosen = [grounding[i][0] for i in range(len(grounding)) if solver.Value(x[(i, t)])]
        if not chosen:
            continue
        d = max(fixed[a.skill] for a in chosen)
        steps.append(
            {"start": clock, "duration": d, "actions": [a.to_json() for a in sorted(chosen)]}
        )
        clock += d
    makespan = solver.ObjectiveValue() / SCALE
    plan = {"status": "solved", "makespan": clock, "planner": {"name": "cp-sat"}, "steps": steps}
    return CpSatResult(makespan, plan, horizon)


def _monitors(
    m: Any,
    h: Hierarchy,
    terms: Mapping[str, Term],
    leaf_events: Mapping[str, Atom],
    grounding: Sequence[tuple[Instance, Location, Location]],
    x: Mapping[tuple[int, int], Any],
    T: int,
) -> dict[str, list[Any]]:
    """done[node][t]: the node has fired at or before step t (monotone in t)."""

    def new_and(a: Any, b: Any) -> Any:
        y = m.NewBoolVar("")
        m.AddBoolAnd([a, b]).OnlyEnforceIf(y)
        m.AddBoolOr([a.Not(), b.Not(), y])
        return y

    def new_or(a: Any, b: Any) -> Any:
        y = m.NewBoolVar("")
        m.AddBoolOr([a, b]).OnlyEnforceIf(y)
        m.AddImplication(a, y)
        m.AddImplication(b, y)
        return y

    def cumulative(now: Callable[[int, Any], Any]) -> list[Any]:
        """c[t] = c[t-1] or now(t, c[t-1]) with c[-1] = false."""
        out: list[Any] = []
        for t in range(T):
            cur = now(t, out[t - 1] if t else None)
            out.append(cur if t == 0 else new_or(out[t - 1], cur))
        return out

    done: dict[str, list[Any]] = {}

    def fires(name: str, t: int) -> Any:
        return done[name][t] if t == 0 else new_and(done[name][t], done[name][t - 1].Not())

    def value(term: Term) -> list[Any]:
        if term[0] == "D":
            return done[term[1]]
        if term[0] == "chain":
            prefix = done[term[1][0]]
            for c in term[1][1:]:
                prev = prefix
                prefix = cumulative(lambda t, _, c=c, prev=prev: new_and(fires(c, t), prev[t]))
            return prefix
        left, right = value(term[1]), value(term[2])
        combine = new_and if term[0] == "and" else new_or
        return [combine(left[t], right[t]) for t in range(T)]

    for name in h.bottom_up():
        if h.children[name]:
            done[name] = value(terms[name])
            continue
        event = leaf_events[name]
        obj, target = event.args
        skill = "handover_r2h" if event.name == "delivered" else "place"
        idx = [
            i
            for i, (a, _, _) in enumerate(grounding)
            if a.skill == skill and a.object == obj and a.target == target
        ]

        def happened(t: int, _: Any, idx: list[int] = idx) -> Any:
            e = m.NewBoolVar("")
            m.Add(e == sum(x[(i, t)] for i in idx))
            return e

        done[name] = cumulative(happened)
    return done
