"""A lower bound on the makespan from a relaxed schedule: routes as paths, hands as sessions."""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from functools import reduce
from typing import Any

from hltl.planner.lns import solve_until
from hltl.planner.problem import Instance, Node, Problem
from hltl.planner.relaxed import RelaxedGraph
from hltl.spec.hierarchy import HSpec
from hltl.spec.syntax import And, Atom, Eventually, Formula

# event atoms: they happen in the step of an instance (the relaxation schedules that instance)
_EVENTS = frozenset({"delivered", "placed", "picked"})


@dataclass(frozen=True, slots=True)
class Target:
    """An event atom every accepting run must make happen, as the relaxation needs it: its
    object, the instances that make it happen, and the targets that must not happen later."""

    atom: Atom
    obj: int
    fires: frozenset[int]  # instance indices
    after: tuple[int, ...]  # indices into the target list


@dataclass(frozen=True, slots=True)
class ScheduleBound:
    """What the relaxation proved: ``ticks`` is a lower bound on the optimal makespan from
    the node; ``solved`` says the relaxation itself was solved to optimality (no more time
    spent on it can raise the bound)."""

    ticks: int
    solved: bool
    targets: int


def applicable(problem: Problem) -> bool:
    """The relaxation's proof holds: durations are fixed, and every instance is done by exactly
    the robots that hold its object before or after it (picks, places, handovers, deliveries),
    so a robot's instances are the ends of the sessions in which it holds an object."""
    if not problem.cost.fixed:
        return False
    for inst in problem.instances:
        holders = 0
        for code in (inst.pre, inst.post):
            r = problem.code_holder.get(code)
            if r is not None:
                holders |= 1 << r
        if holders != inst.executors:
            return False
    return True


def targets(
    problem: Problem, graph: RelaxedGraph, node: Node, required: frozenset[Atom]
) -> list[Target]:
    """The event atoms of ``required`` (atoms every accepting run from ``node`` must make
    true), one per object (any subset of them gives a valid bound), with "first A, then B"
    orders when the spec has no "or" (then every such order is needed too)."""
    by_obj: dict[int, Atom] = {}
    for a in sorted(required):
        if a.name not in _EVENTS:
            continue
        g = graph.goal(a)
        if g is None or g[0] in by_obj:
            continue
        by_obj[g[0]] = a
    out: list[Target] = []
    index: dict[Atom, int] = {}
    for o, a in sorted(by_obj.items()):
        fires = frozenset(i.index for row in problem.by_obj_pre[o] for i in row if a in i.events)
        if not fires:
            continue
        index[a] = len(out)
        out.append(Target(a, o, fires, ()))
    orders = _orders(problem.spec)
    return [
        Target(
            t.atom,
            t.obj,
            t.fires,
            tuple(sorted(index[b] for b, c in orders if c == t.atom and b in index)),
        )
        for t in out
    ]


def _orders(spec: HSpec) -> list[tuple[Atom, Atom]]:
    """(a, b) for every "F (x & F y)" whose children x, y are leaves "F a" and "F b": the step a
    first happens in is no later than b's. Only when every formula is built of "and" and "F"
    alone (no "or", no negation): then every such part must hold in every accepting run;
    otherwise no orders (fewer constraints: the bound stays valid)."""
    parts: list[Formula] = []
    for _, f in spec.formulas:
        stack: list[Formula] = [f]
        while stack:
            g = stack.pop()
            if isinstance(g, And):
                stack += [g.left, g.right]
            elif isinstance(g, Eventually):
                parts.append(g)
                stack.append(g.operand)
            elif not isinstance(g, Atom):
                return []

    def leaf_atom(f: Formula) -> Atom | None:
        if isinstance(f, Atom) and not f.args and f.name in spec.leaves:
            leaf = spec.formula(f.name)
            if isinstance(leaf, Eventually) and isinstance(leaf.operand, Atom):
                return leaf.operand
        return None

    out = []
    for g in parts:
        assert isinstance(g, Eventually)
        if isinstance(g.operand, And) and isinstance(g.operand.right, Eventually):
            a = leaf_atom(g.operand.left)
            b = leaf_atom(g.operand.right.operand)
            if a is not None and b is not None:
                out.append((a, b))
    return out


def schedule_bound(
    problem: Problem,
    graph: RelaxedGraph,
    node: Node,
    tgts: Sequence[Target],
    *,
    floor: int,
    upper: int | None,
    deadline: float,
    seed: int = 0,
) -> ScheduleBound:
    """A lower bound (ticks) on the makespan of every plan from ``node`` that makes every
    target happen, from a relaxed schedule (docs/planner.md, "Scheduling bound").

    ``floor`` is a lower bound known already and ``upper`` the makespan of a known plan
    (None: none). The bound is raised one time unit (the durations' common divisor) at a time:
    CP-SAT proves that no relaxed schedule ends by the current value, until it finds one
    (then the value is the relaxation's optimum), the value reaches ``upper``, or ``deadline``
    (``time.perf_counter()`` time; building counts) passes. Never below ``floor``.
    """
    durations = [i.lower for i in problem.instances if i.lower > 0]
    unit = reduce(math.gcd, durations, 0) or 1
    level = -(-floor // unit)  # the least makespan (in units) not yet ruled out
    while upper is None or level * unit < upper:
        found = _feasible(problem, graph, node, tgts, level, unit, deadline, seed)
        if found is None:  # out of time
            return ScheduleBound(max(floor, level * unit), False, len(tgts))
        if found:
            return ScheduleBound(max(floor, level * unit), True, len(tgts))
        level += 1
    return ScheduleBound(max(floor, upper), True, len(tgts))


def _feasible(
    problem: Problem,
    graph: RelaxedGraph,
    node: Node,
    tgts: Sequence[Target],
    level: int,
    unit: int,
    deadline: float,
    seed: int,
) -> bool | None:
    """Whether some relaxed schedule makes every target happen by ``level`` units (None: CP-SAT
    could not tell before ``deadline``).

    The relaxation: each target's object follows a path of instances from where it is to an
    instance that makes the atom happen, each instance an interval of its duration starting
    after the previous one ends; a robot's *sessions* (from the instance that gives it an
    object to the one that takes it away) never overlap, because a robot holds one object at
    a time and acts only on what it holds or, with an empty hand, picks or receives. Where the
    object leaves a robot and comes back (a loop, cut out of the path) the session may be
    split into its two ends. Places the object cannot pass through and still make its atom
    happen by ``level`` are left out.
    """
    from ortools.sat.python import cp_model  # why: an optional extra, loaded on first use

    p = problem
    locs = node[0]
    H = level
    cap = level * unit
    m = cp_model.CpModel()
    per_robot: list[list[Any]] = [[] for _ in p.robots]
    fire_start: list[Any] = []
    for t in tgts:
        o, s0 = t.obj, locs[t.obj]
        reach = graph.place_time[o][s0]
        togo = graph.event_time[o]
        if togo[s0].get(t.atom, math.inf) > cap:
            return False
        cand: list[Instance] = [
            i
            for row in p.by_obj_pre[o]
            for i in row
            if reach[i.pre] + i.lower <= cap
            and (
                i.index in t.fires
                or (
                    i.post != s0
                    and reach[i.pre] + i.lower + togo[i.post].get(t.atom, math.inf) <= cap
                )
            )
        ]
        places = {s0} | {i.pre for i in cand} | {i.post for i in cand if i.index not in t.fires}
        arrive = {c: m.new_int_var(0, H, "") for c in places}
        m.add(arrive[s0] == 0)
        outs: dict[int, list[Any]] = {c: [] for c in places}
        ins: dict[int, list[Any]] = {c: [] for c in places}
        fired: list[tuple[Any, Any]] = []
        opens: dict[int, list[tuple[Any, Any, int]]] = {}  # robot -> (used, start, duration)
        closes: dict[int, list[tuple[Any, Any, int, bool]]] = {}  # ... and whether it fires
        for i in cand:
            u = m.new_bool_var("")
            d = i.lower // unit
            st = m.new_int_var(0, H - d, "")
            m.add(st >= arrive[i.pre]).only_enforce_if(u)
            outs[i.pre].append(u)
            fires = i.index in t.fires
            if fires:
                fired.append((u, st))
            else:
                ins[i.post].append(u)
                m.add(arrive[i.post] == st + d).only_enforce_if(u)
                r_in = p.code_holder.get(i.post)
                if r_in is not None:
                    opens.setdefault(r_in, []).append((u, st, d))
            r_out = p.code_holder.get(i.pre)
            if r_out is not None:
                closes.setdefault(r_out, []).append((u, st, d, fires))
        if not fired:
            return False
        # a path from s0: leaves s0 once, enters and leaves every other place at most once;
        # cycles apart from it are impossible (each instance starts after the last ended)
        m.add(sum(outs[s0]) == 1)
        for c in places:
            if c != s0:
                m.add(sum(ins[c]) <= 1)
                m.add(sum(outs[c]) == sum(ins[c]))
        m.add_exactly_one(u for u, _ in fired)
        fs = m.new_int_var(0, H, "")
        for u, st in fired:
            m.add(fs == st).only_enforce_if(u)
        fire_start.append(fs)
        for r, ends in closes.items():
            starts = opens.get(r)
            if not starts:
                # the object is in r's hand at the start: its leaving is plain work of r
                for u, st, d, _ in ends:
                    per_robot[r].append(m.new_optional_fixed_size_interval_var(st, d, u, ""))
                continue
            # the quickest ways out of r's hand (not firing: a loop goes on) and back in, over
            # every instance, so that no way a plan may take is missed
            hand = p.held_code[r]
            leave = [i.lower for i in p.by_obj_pre[o][hand] if i.index not in t.fires]
            back = [i.lower for row in p.by_obj_pre[o] for i in row if i.post == hand]
            quickest = (min(leave) // unit, min(back) // unit) if leave and back else None
            per_robot[r].extend(_session(m, H, starts, ends, quickest))
    for k, t in enumerate(tgts):
        for j in t.after:
            m.add(fire_start[k] >= fire_start[j])
    for ivs in per_robot:
        if len(ivs) > 1:
            m.add_no_overlap(ivs)
    solved = solve_until(m, deadline, seed)
    if solved is None:
        return None
    status = solved[1]
    if status == cp_model.INFEASIBLE:
        return False
    if status in (cp_model.OPTIMAL, cp_model.FEASIBLE):
        return True
    return None


def _session(
    m: Any,
    H: int,
    starts: list[tuple[Any, Any, int]],
    ends: list[tuple[Any, Any, int, bool]],
    quickest: tuple[int, int] | None,
) -> list[Any]:
    """Robot r's time with the object in hand, as intervals for r's no-overlap: whole, from the
    instance that brings it to the one that takes it away; or, when the object leaves r and
    comes back (a loop the path does not show), split into the arrival plus the quickest way
    out, and the quickest way back in plus the departure (``quickest``: those two durations;
    None when the object cannot leave r without its atom happening, or never come back)."""
    present = m.new_bool_var("")
    m.add(present == sum(u for u, _, _ in starts))
    begin, end = m.new_int_var(0, H, ""), m.new_int_var(0, H, "")
    end_in, start_out = m.new_int_var(0, H, ""), m.new_int_var(0, H, "")
    for u, st, d in starts:
        m.add(begin == st).only_enforce_if(u)
        m.add(end_in == st + d).only_enforce_if(u)
    for u, st, d, _ in ends:
        m.add(end == st + d).only_enforce_if(u)
        m.add(start_out == st).only_enforce_if(u)
    whole = m.new_bool_var("")
    out: list[Any] = [m.new_optional_interval_var(begin, m.new_int_var(0, H, ""), end, whole, "")]
    if quickest is None:
        m.add(whole == present)
        return out
    leave, back = quickest
    split = m.new_bool_var("")
    m.add(whole + split == present)
    e1, s2 = m.new_int_var(0, H, ""), m.new_int_var(-H, H, "")
    m.add(e1 == end_in + leave).only_enforce_if(split)
    m.add(s2 == start_out - back).only_enforce_if(split)
    m.add(e1 <= s2).only_enforce_if(split)
    out.append(m.new_optional_interval_var(begin, m.new_int_var(0, H, ""), e1, split, ""))
    out.append(m.new_optional_interval_var(s2, m.new_int_var(0, 2 * H, ""), end, split, ""))
    return out
