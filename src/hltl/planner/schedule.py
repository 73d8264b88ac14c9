"""A lower bound on the makespan from a relaxed schedule: routes as paths, hands as sessions."""

from __future__ import annotations

import math
import os
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from functools import reduce
from itertools import pairwise
from typing import TYPE_CHECKING, Any

from hltl.planner.lns import Stop, note_busy, solve_until, stop_until
from hltl.planner.problem import Instance, Node, Problem
from hltl.planner.relaxed import RelaxedGraph
from hltl.spec.hierarchy import HSpec
from hltl.spec.syntax import And, Atom, Eventually, Formula

if TYPE_CHECKING:
    from concurrent.futures import Future, ThreadPoolExecutor

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
    # the step relaxation's schedule at ``ticks`` when it was solved there: per non-empty step
    # its instances (a plan of makespan ``ticks`` once a replay accepts it: then it is optimal)
    steps: tuple[tuple[Instance, ...], ...] | None = None


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


# the step model's climb skips levels while CP-SAT proves their "no"s in less than this many
# deterministic seconds (a load-independent measure: 0.25 is about 0.4 s of CPU on an idle
# core), at most MAX_SKIP at a time (``_shave``)
CHEAP_NO = 0.25
MAX_SKIP = 4
# CP-SAT's ``linearization_level`` on the step model's questions (its default is 1): without
# its LP the dear "no"s just below the optimum took 30-40 % less CPU (docs/planner.md, "The
# step model's roof")
STEP_LINEARIZATION = 0
# ``schedule_bound``'s ``roof``: the first round asks the levels just below a known plan's
# makespan when it is at most this many levels above the first level not ruled out (where
# they are "yes"es far above the optimum, a round is lost)
ROOF_SPAN = 10
# levels the climbs ask at once (``_shave``), one thread each: two cores, when there are two
WORKERS = min(2, len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else 1)


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
    steps: bool = False,
    accept: Callable[[tuple[tuple[Instance, ...], ...]], bool] | None = None,
    before_full: Callable[[], None] | None = None,
    roof: int | None = None,
) -> ScheduleBound:
    """A lower bound (ticks) on the makespan of every plan from ``node`` that makes every
    target happen, from a relaxed schedule (docs/planner.md, "Scheduling bound").

    ``floor`` is a lower bound known already and ``upper`` the makespan of a known plan
    (None: none). The bound is raised one time unit (the durations' common divisor) at a time:
    CP-SAT proves that no relaxed schedule ends by the current value, until it finds one
    (then the value is the relaxation's optimum), the value reaches ``upper``, or ``deadline``
    (``time.perf_counter()`` time; building counts) passes. Never below ``floor``.

    With ``steps`` (only where ``steps_applicable``) the relaxation is the step-indexed one
    (``relaxed_steps``), which also sees that a step lasts its longest instance; with an
    ``upper`` too, the levels gallop up from ``floor`` and are then bisected below the first
    feasible one (``_bisect``; a plan ends by ``upper``, so the relaxation is feasible there).

    With ``accept`` too (it says whether a relaxed schedule at the level found is a plan) the
    levels are first asked with loops as session 8 modelled them (``relaxed_steps`` without
    ``holders``: weaker, and cheaper); where that finds a schedule that is no plan, the levels
    from there on are asked of the full model, each first with every session whole
    (``_shave`` with ``whole_first``; a plan from it is optimal: the schedule returned).
    Every "no" of the weaker model is one of the full model's (it is a relaxation of it).
    ``before_full`` is called before the full model's levels are asked, and they are then
    asked one at a time (the caller has other work for the second core).

    ``roof`` (without ``upper``: the step model shaved) is the makespan of a known plan: no
    level at or above it is asked (the relaxation is feasible there), and where it is at most
    ``ROOF_SPAN`` units above the first level, the climb's first round asks the two levels
    just below it (``_shave``'s ``descend``): where the plan is optimal, the "no" just below
    it is the one question that proves it, and the levels between need no asking. Where the
    climb proves every level below it "no", the bound is ``roof`` with no schedule.
    """
    unit = time_unit(problem)
    level = -(-floor // unit)  # the least makespan (in units) not yet ruled out
    weak = accept is not None
    # (the climb without ``upper`` asks the full model's first questions ahead: ``_Whole``)
    whole = (
        None
        if upper is not None or accept is None or not steps
        else _Whole(problem, graph, node, tgts, deadline, seed, accept)
    )

    def shave(
        at: int,
        steps: bool,
        weak: bool,
        whole_first: bool = False,
        workers: int | None = None,
        descend: bool = False,
    ) -> ScheduleBound:
        return _shave(
            problem,
            graph,
            node,
            tgts,
            at,
            upper if roof is None else roof,
            deadline,
            seed,
            floor,
            steps,
            weak,
            whole_first,
            workers,
            whole,
            descend,
        )

    try:
        if steps and upper is not None:
            res = _bisect(
                problem, graph, node, tgts, level, upper // unit, deadline, seed, floor, not weak
            )
        else:
            descend = roof is not None and upper is None and roof // unit - level <= ROOF_SPAN
            res = shave(level, steps, weak, descend=descend)
        if accept is None or res.steps is None or accept(res.steps):
            return res
        workers = None
        if before_full is not None:
            before_full()
            workers = 1
        return shave(res.ticks // unit, True, False, True, workers)
    finally:
        if whole is not None:
            whole.close()


class _Whole:
    """Questions "is there a schedule with every session whole at this level" asked ahead
    (``schedule_bound`` with ``accept``, the full model's first question at a level): when the
    cheaper model's climb finds a schedule that is no plan at a level while the levels between
    the last "no" and it are still being asked, a core is free until they end, and if they all
    say "no" the level is the bound and the full model's climb asks exactly this question
    first. Asked on that core instead, its answer (one worker, the fixed seed: the same as
    asked later) is taken when the full model's climb gets there; an answer not needed is
    stopped. So the bound, the schedule and the plan are the same as without it."""

    def __init__(
        self,
        problem: Problem,
        graph: RelaxedGraph,
        node: Node,
        tgts: Sequence[Target],
        deadline: float,
        seed: int,
        accept: Callable[[tuple[tuple[Instance, ...], ...]], bool],
    ) -> None:
        self.problem, self.graph, self.node, self.tgts = problem, graph, node, tgts
        self.deadline, self.seed, self.accept = deadline, seed, accept
        self.pool: ThreadPoolExecutor | None = None
        self.asked: dict[
            int, tuple[Future[tuple[tuple[Instance, ...], ...] | bool | None], Stop]
        ] = {}

    def ahead(self, at: int, found: tuple[tuple[Instance, ...], ...]) -> None:
        """The cheaper model found ``found`` at level ``at``: ask the level with sessions
        whole now, unless ``found`` is a plan (then the climb needs no full model)."""
        if at in self.asked or self.accept(found):
            return
        if self.pool is None:
            from concurrent.futures import ThreadPoolExecutor  # (start-up: planner/__init__.py)

            self.pool = ThreadPoolExecutor(max_workers=1)
        stop = Stop()
        future = self.pool.submit(
            relaxed_steps,
            self.problem,
            self.graph,
            self.node,
            self.tgts,
            at,
            self.deadline,
            seed=self.seed,
            whole=True,
            stop=stop,
        )
        self.asked[at] = (future, stop)

    def has(self, at: int) -> bool:
        """Whether the level ``at`` was asked ahead (and its answer not yet taken)."""
        return at in self.asked

    def take(self, at: int) -> tuple[tuple[Instance, ...], ...] | bool | None:
        """The answer at ``at``, asked ahead (``has``), waited for."""
        future, _ = self.asked.pop(at)
        return future.result()

    def close(self) -> None:
        """Stop the answers not taken."""
        for future, stop in self.asked.values():
            stop_until(stop, _ended(future))
        if self.pool is not None:
            self.pool.shutdown(wait=True)


def _ended(future: Future[Any]) -> Callable[[float], bool]:
    """Whether ``future`` has ended, waiting at most the seconds given (``stop_until``)."""
    from concurrent.futures import wait  # (start-up: planner/__init__.py)

    return lambda seconds: bool(wait([future], timeout=seconds).done)


def _shave(
    problem: Problem,
    graph: RelaxedGraph,
    node: Node,
    tgts: Sequence[Target],
    level: int,
    upper: int | None,
    deadline: float,
    seed: int,
    floor: int,
    steps: bool,
    weak: bool,
    whole_first: bool = False,
    workers: int | None = None,
    whole: _Whole | None = None,
    descend: bool = False,
) -> ScheduleBound:
    """The relaxation's optimum from ``level`` units up (``steps``: the step model, ``weak``:
    without ``holders``; else the interval model).

    With ``whole_first`` (the full step model) each level is asked first with every session
    whole: a restriction of the full model (its "no" proves nothing) that finds a schedule far
    more cheaply where there is one. Where it finds one the full model has it too, so the level
    is the full model's optimum without asking it (and where that schedule replays as a plan,
    the plan is optimal); only where it finds none is the full model asked.

    Without it, the step model skips levels while its "no"s are cheap: after a "no" that took
    CP-SAT less than ``CHEAP_NO`` deterministic seconds the next level asked is twice as far
    up as the last step (at most ``MAX_SKIP`` levels), after a dearer one the next level.
    A "no" at a level is a "no" at every level below it, so the skipped ones need no asking
    unless a schedule turns up above them: then they are asked from the lowest, and the first
    schedule found is the optimum (docs/planner.md, "Which levels are asked").

    ``workers`` (default ``WORKERS``) levels are asked at once, each on a thread of its own
    (CP-SAT leaves Python's lock while it solves): the level the climb would ask next and the
    ones above it, as far apart as that level is from the last "no" while levels are skipped
    (two "no"s then rule out twice as many levels: docs/planner.md, "Rounds as far apart as
    the skip"), else the ones just above it. A
    "no" answers every level below it and a schedule every level above it, so a question whose
    answer another one implies is stopped, and its answer is never used: the optimum found,
    its schedule (one CP-SAT worker with a fixed seed at a fixed level) and the levels asked
    are the same whichever question ends first.

    With ``descend`` (and ``upper``) the first round asks the ``workers`` levels just below
    ``upper`` instead (``schedule_bound``'s ``roof``); the climb then goes on from ``level``
    below whatever they leave open."""
    unit = time_unit(problem)
    top = None if upper is None else -(-upper // unit)  # the least level ``upper`` reaches
    proved = level - 1  # no schedule ends by this level (nor, then, by any below it)
    skip = 1 if steps and not whole_first else 0  # 0: one level at a time
    workers = WORKERS if workers is None else workers
    lowest: tuple[int, ScheduleBound] | None = None  # the lowest level with a schedule found

    def ask(at: int, stop: Stop) -> tuple[tuple[tuple[Instance, ...], ...] | bool | None, float]:
        """One level's answer (a schedule, True: one exists, False, None: unknown) and the
        deterministic seconds CP-SAT took to find it."""
        if whole_first:
            if whole is not None and whole.has(at):
                whole_steps = whole.take(at)  # (asked ahead: ``_Whole``)
            else:
                whole_steps = relaxed_steps(
                    problem, graph, node, tgts, at, deadline, seed=seed, whole=True, stop=stop
                )
            if whole_steps is None or isinstance(whole_steps, tuple):
                return whole_steps, 0.0
        if not steps:
            return _feasible(problem, graph, node, tgts, at, unit, deadline, seed, stop), 0.0
        spent: list[float] = []
        found = relaxed_steps(
            problem,
            graph,
            node,
            tgts,
            at,
            deadline,
            seed=seed,
            holders=not weak,
            spent=spent,
            stop=stop,
        )
        return found, sum(spent)

    # (imported here: start-up, planner/__init__.py)
    from concurrent.futures import FIRST_COMPLETED, ThreadPoolExecutor, wait

    with ThreadPoolExecutor(max_workers=workers) as pool:
        while True:
            if lowest is not None and lowest[0] == proved + 1:
                return lowest[1]
            if top is not None and proved + 1 >= top:
                return ScheduleBound(max(floor, upper or 0), True, len(tgts))
            apart = 1  # how far apart the levels of a round are
            if descend and top is not None:  # (the first round: the levels below ``upper``)
                first = max(proved + 1, top - workers)
                descend = False
            elif lowest is not None:  # levels were skipped below it: ask them from the lowest
                first = proved + 1
            else:
                apart = max(1, skip)
                first = proved + apart
                if top is not None and first >= top:
                    first, apart = max(proved + 1, top - 1), 1
            levels = [
                at
                for at in range(first, first + workers * apart, apart)
                if (top is None or at < top) and (lowest is None or at < lowest[0])
            ]
            # (phase._Apart pauses A* through a round that asks a level on every core)
            note_busy(told := len(levels))
            asked = {at: Stop() for at in levels}
            try:
                running = {pool.submit(ask, at, asked[at]): at for at in levels}
                out_of_time = False
                dear = 0.0  # CP-SAT's time for the highest "no" of this round
                while running:
                    stopping = [stop for stop in asked.values() if stop.stopped]
                    done, _ = wait(
                        running, timeout=0.01 if stopping else None, return_when=FIRST_COMPLETED
                    )
                    for stop in stopping:
                        stop.stop()  # again: a solve may have begun after the first call
                    for future in sorted(done, key=running.__getitem__):
                        at = running.pop(future)
                        if asked[at].stopped:
                            continue  # another answer implies this one
                        found, dt = future.result()
                        if found is None:
                            out_of_time = True
                        elif found is False:
                            if at > proved:
                                proved, dear = at, dt
                        else:
                            got = None if found is True else found
                            res = ScheduleBound(max(floor, at * unit), True, len(tgts), got)
                            if lowest is None or at < lowest[0]:
                                lowest = (at, res)
                                if (
                                    whole is not None
                                    and not whole_first
                                    and isinstance(found, tuple)
                                    and (at - 1 <= proved or at - 1 in running.values())
                                ):
                                    # the level below is being asked: if it says "no" (and
                                    # with it every level below) this is the bound, and a
                                    # core is free till then
                                    whole.ahead(at, found)
                        for other in running.values():
                            if out_of_time or other <= proved or (lowest and other >= lowest[0]):
                                asked[other].stop()
                    if running and len(running) < told:
                        # (a question left alone leaves a core to a paused A*: a round below a
                        # roof waits for its dear "no" long after the other level's answer)
                        told = len(running)
                        note_busy(told)
            finally:
                # (also when a question raised: the others are stopped, so that the pool need
                # not wait for them, and a paused A* is never left paused)
                for stop in asked.values():
                    stop.stop()
                note_busy(0)
            if out_of_time:
                return ScheduleBound(max(floor, (proved + 1) * unit), False, len(tgts))
            if skip and lowest is None:
                skip = min(2 * skip, MAX_SKIP) if dear < CHEAP_NO else 1
            elif lowest is not None:
                skip = 0


def _bisect(
    problem: Problem,
    graph: RelaxedGraph,
    node: Node,
    tgts: Sequence[Target],
    lo: int,
    hi: int,
    deadline: float,
    seed: int,
    floor: int,
    holders: bool,
) -> ScheduleBound:
    """The step relaxation's optimum in [lo, hi] units (feasible at ``hi``): a "no" at a level
    raises ``lo`` above it, a schedule lowers ``hi`` to it. The levels asked gallop up from
    ``lo`` (lo, lo+1, lo+3, lo+7, ...: the optimum is often at or just above the known bound)
    until one is feasible, then bisect. Most levels far below the optimum are never asked."""
    unit = time_unit(problem)
    at_hi: tuple[tuple[Instance, ...], ...] | None = None
    gallop: int | None = 0
    while lo < hi:
        mid = (lo + hi) // 2 if gallop is None else min(lo + gallop, hi - 1)
        found = relaxed_steps(problem, graph, node, tgts, mid, deadline, seed=seed, holders=holders)
        if found is None:
            return ScheduleBound(max(floor, lo * unit), False, len(tgts))
        if found is False:
            lo = mid + 1
            gallop = None if gallop is None else 2 * gallop + 1
        else:
            hi, at_hi, gallop = mid, None if found is True else found, None
    return ScheduleBound(max(floor, lo * unit), True, len(tgts), at_hi)


def time_unit(problem: Problem) -> int:
    """The durations' common divisor in ticks: every makespan is a multiple of it."""
    durations = [i.lower for i in problem.instances if i.lower > 0]
    return reduce(math.gcd, durations, 0) or 1


def _feasible(
    problem: Problem,
    graph: RelaxedGraph,
    node: Node,
    tgts: Sequence[Target],
    level: int,
    unit: int,
    deadline: float,
    seed: int,
    stop: Stop | None = None,
) -> bool | None:
    """Whether some relaxed schedule makes every target happen by ``level`` units (None: CP-SAT
    could not tell before ``deadline``, or ``stop`` stopped it).

    The relaxation (``_relaxation`` on a time line, ``_Times``): each target's object follows a
    path of instances from where it is to an instance that makes the atom happen, each
    instance an interval of its duration starting after the previous one ends; a robot's
    *sessions* (from the instance that gives it an object to the one that takes it away) never
    overlap, because a robot holds one object at a time and acts only on what it holds or, with
    an empty hand, picks or receives. Where the object leaves a robot and comes back (a loop,
    cut out of the path) the session may be split into its two ends. Places the object cannot
    pass through and still make its atom happen by ``level`` are left out.
    """
    from ortools.sat.python import cp_model  # why: an optional extra, loaded on first use

    axis = _Times(cp_model.CpModel(), level, unit)
    if not _relaxation(problem, graph, node, tgts, axis):
        return False
    solver = _solve(axis, deadline, seed, stop=stop)
    return solver if solver is None or solver is False else True


def steps_applicable(problem: Problem) -> bool:
    """The step-indexed relaxation's proof holds: that of ``applicable``, and every instance
    takes time, so a plan ending by M has at most M / (shortest duration) non-empty steps."""
    return applicable(problem) and all(i.lower > 0 for i in problem.instances)


def relaxed_steps(
    problem: Problem,
    graph: RelaxedGraph,
    node: Node,
    tgts: Sequence[Target],
    level: int,
    deadline: float,
    *,
    seed: int = 0,
    whole: bool = False,
    holders: bool = True,
    spent: list[float] | None = None,
    stop: Stop | None = None,
) -> tuple[tuple[Instance, ...], ...] | bool | None:
    """A step-indexed relaxed schedule that makes every target happen by ``level`` time units
    (``time_unit``), as its non-empty steps; False when CP-SAT proved there is none, None when
    it could not tell before ``deadline`` (or ``stop`` stopped it). docs/planner.md, "Step
    bound".

    With ``whole`` no session is split (a restriction, not a relaxation: its "no" proves
    nothing, but its schedules are more often plans). CP-SAT's deterministic time is appended
    to ``spent``. Without ``holders`` a split session
    keeps of its loop only the fixed runs and the time (session 8's model: a relaxation of this
    one, docs/planner.md "Loops").

    The paths and sessions of ``_feasible`` (``_relaxation`` on a sequence of steps,
    ``_Steps``): every instance on a path is in one step, the next instance on its path in a
    later one; a robot's sessions cover runs of steps that never share a step; a step lasts at
    least its longest instance (0 when empty; the empty steps come last), and the steps last at
    most ``level`` units in all. K = ``level`` // (shortest duration): no plan ending by
    ``level`` has more non-empty steps. Where a plan runs a 0.5 s pick beside a 0.6 s
    handover, the pick's step costs 0.6 s here too, which intervals of their own durations do
    not see.
    """
    from ortools.sat.python import cp_model  # why: an optional extra, loaded on first use

    p = problem
    unit = time_unit(p)
    shortest = min(i.lower for i in p.instances)
    if level * unit // shortest == 0:
        return False
    axis = _Steps(cp_model.CpModel(), p, level, unit, whole, holders)
    if not _relaxation(p, graph, node, tgts, axis):
        return False
    solver = _solve(axis, deadline, seed, spent, stop)
    if solver is None or solver is False:
        return solver
    out: list[list[Instance]] = [[] for _ in range(axis.horizon)]
    for i, xs in axis.chosen:
        for k, x in xs:
            if solver.value(x):
                out[k].append(i)
    return tuple(tuple(step) for step in out if step)


def _solve(
    axis: _Axis,
    deadline: float,
    seed: int,
    spent: list[float] | None = None,
    stop: Stop | None = None,
) -> Any:
    """CP-SAT on the model built on ``axis``: its solver when it found a schedule, False when
    it proved there is none, None when it could not tell before ``deadline`` (or ``stop``
    stopped it). CP-SAT's deterministic time is appended to ``spent``."""
    from ortools.sat.python import cp_model  # why: an optional extra, loaded on first use

    steps = isinstance(axis, _Steps)
    solved = solve_until(
        axis.model, deadline, seed, stop, linearization=STEP_LINEARIZATION if steps else None
    )
    if solved is None:
        return None
    solver, status = solved
    if spent is not None:
        spent.append(solver.deterministic_time)
    if status == cp_model.INFEASIBLE:
        return False
    if status not in (cp_model.OPTIMAL, cp_model.FEASIBLE):
        return None
    return solver


# per instance that makes the atom happen or not, and the least ticks from its end until the
# atom can: the positions it may sit in on the axis (None: not on the path)
_Window = Callable[[Instance, bool, float], tuple[int, int] | None]
# (used, time in units) per instance that brings an object into a hand or takes it out
_Stamps = list[tuple[Any, Any]]


@dataclass(frozen=True, slots=True)
class _Job:
    """Instances of one robot (or on one object's path) that the model counts together: their
    least summed duration (ticks, in time units), a lower bound on each one's, and the literal
    "they happen"."""

    total: int
    each: tuple[int, ...]
    used: Any


@dataclass(frozen=True, slots=True)
class _Slot:
    """An instance as the model places it on an object's path: whether the path uses it,
    where it sits on the axis (a time in units, or a step), how far along the axis it reaches
    (its duration, or one step), and the time (units) it starts."""

    used: Any
    at: Any
    span: int
    begins: Any


class _Axis:
    """What the two relaxations differ in: the axis instances are placed on (``horizon``
    points), the window each instance may sit in, how a split session's loop is timed, and the
    constraints over the whole axis. ``_relaxation`` builds the rest (paths and sessions)."""

    def __init__(self, model: Any, level: int, unit: int, horizon: int) -> None:
        self.model = model
        self.level = level
        self.unit = unit
        self.horizon = horizon
        self.whole = False  # no session is split

    def windows(self, problem: Problem, t: Target, s0: int) -> _Window:
        """For ``t``'s object at ``s0``: the positions an instance (that makes the atom happen
        or not; the least time, ticks, from its end until the atom can) may sit in; None when
        it cannot be on the path."""
        raise NotImplementedError

    def place(self, i: Instance, window: tuple[int, int], early: float, rest: float) -> _Slot:
        """Variables for ``i`` on the path, in ``window``, starting no earlier than ``early``
        ticks, and leaving ``rest`` ticks after its end."""
        raise NotImplementedError

    def split(
        self,
        r: int,
        t: Target,
        loop: tuple[int, int],
        hold: _Hold,
        arrivals: _Stamps,
        departures: _Stamps,
    ) -> list[tuple[int, Any]]:
        """Robot ``r``'s session with ``t``'s object split around a loop out of its hand and
        back (at least ``loop``: ticks out, ticks back), present when ``hold.split``: its
        pieces, and what the loop takes of other robots, as (robot, interval); ``arrivals``
        and ``departures``: the times the session's first instance ends and its last starts
        (each with its instance's "used")."""
        raise NotImplementedError

    def finish(self) -> None:
        """Constraints over the whole axis, once every path is built."""


class _Times(_Axis):
    """The time line of ``_feasible``: a position is a time in units, an instance spans its
    duration."""

    def __init__(self, model: Any, level: int, unit: int) -> None:
        super().__init__(model, level, unit, level)

    def windows(self, problem: Problem, t: Target, s0: int) -> _Window:
        return lambda i, fires, rest: (0, self.level - i.lower // self.unit)

    def place(self, i: Instance, window: tuple[int, int], early: float, rest: float) -> _Slot:
        m = self.model
        u = m.new_bool_var("")
        st = m.new_int_var(*window, "")
        return _Slot(u, st, i.lower // self.unit, st)

    def split(
        self,
        r: int,
        t: Target,
        loop: tuple[int, int],
        hold: _Hold,
        arrivals: _Stamps,
        departures: _Stamps,
    ) -> list[tuple[int, Any]]:
        # the arrival plus the quickest way out, the quickest way back in plus the departure
        m, H, split = self.model, self.horizon, hold.split
        leave, back = loop[0] // self.unit, loop[1] // self.unit
        e1, s2 = m.new_int_var(0, H, ""), m.new_int_var(-H, H, "")
        m.add(e1 == hold.end_in + leave).only_enforce_if(split)
        m.add(s2 == hold.start_out - back).only_enforce_if(split)
        m.add(e1 <= s2).only_enforce_if(split)
        return [
            (r, m.new_optional_interval_var(hold.begin, m.new_int_var(0, H, ""), e1, split, "")),
            (r, m.new_optional_interval_var(s2, m.new_int_var(0, 2 * H, ""), hold.end, split, "")),
        ]


class _Steps(_Axis):
    """The step sequence of ``relaxed_steps``: a position is a step; step k starts at
    ``start[k]`` units, is non-empty (``busy``, at least the shortest duration) or empty and
    then last, and lasts at least each longer duration its instances have (``at_least``)."""

    def __init__(
        self, model: Any, problem: Problem, level: int, unit: int, whole: bool, holders: bool
    ) -> None:
        shortest = min(i.lower for i in problem.instances)
        super().__init__(model, level, unit, level * unit // shortest)
        self.problem = problem
        self.whole = whole
        self.holders = holders
        self.d_min = shortest // unit
        K, m = self.horizon, model
        lengths = sorted({i.lower // unit for i in problem.instances if i.lower > shortest})
        self.busy = [m.new_bool_var("") for _ in range(K)]
        for k in range(K - 1):
            m.add_implication(self.busy[k + 1], self.busy[k])
        self.at_least: list[dict[int, Any]] = []
        for k in range(K):
            row = {d: m.new_bool_var("") for d in lengths}
            for a, b in pairwise(lengths):
                m.add_implication(row[b], row[a])
            if lengths:
                m.add_implication(row[lengths[0]], self.busy[k])
            self.at_least.append(row)
        self.start = [m.new_int_var(0, level, "") for _ in range(K + 1)]  # when step k starts
        m.add(self.start[0] == 0)
        for k in range(K):
            prev = self.d_min
            length = self.d_min * self.busy[k]
            for d in lengths:
                length += (d - prev) * self.at_least[k][d]
                prev = d
            m.add(self.start[k + 1] == self.start[k] + length)
        self.per_robot_step: dict[tuple[int, int], list[Any]] = {}
        self.lengths = lengths
        # each robot's instances, and each target object's path (``finish``)
        self.work: list[list[_Job]] = [[] for _ in problem.robots]
        self.paths: dict[int, list[_Job]] = {}
        # every instance placed, with its step literals: the schedule is read from them
        self.chosen: list[tuple[Instance, list[tuple[int, Any]]]] = []

    def windows(self, problem: Problem, t: Target, s0: int) -> _Window:
        o, K = t.obj, self.horizon
        hops_in = _hops(problem, o, [s0], forward=True)
        hops_out = _hops(
            problem,
            o,
            [i.pre for row in problem.by_obj_pre[o] for i in row if i.index in t.fires],
            False,
        )

        def window(i: Instance, fires: bool, rest: float) -> tuple[int, int] | None:
            # after the hops that bring the object to it, early enough for the hops after it,
            # and (each step lasting at least d_min) for the time after it
            first = hops_in.get(i.pre)
            after = 0 if fires else hops_out.get(i.post, K) + 1
            if first is None:
                return None
            slack = self.level - i.lower // self.unit - math.ceil(rest / self.unit)
            last = min(K - 1 - after, slack // self.d_min)
            return (first, last) if first <= last else None

        return window

    def place(self, i: Instance, window: tuple[int, int], early: float, rest: float) -> _Slot:
        m, unit = self.model, self.unit
        d = i.lower // unit
        lo = math.ceil(early / unit)
        late = self.level - d - math.ceil(rest / unit)
        first, last = window
        xs = []
        for k in range(first, last + 1):
            x = m.new_bool_var("")
            xs.append((k, x))
            m.add(self.start[k] >= lo).only_enforce_if(x)
            m.add(self.start[k] <= late).only_enforce_if(x)
            m.add_implication(x, self.at_least[k][d] if d > self.d_min else self.busy[k])
            for r in range(len(self.problem.robots)):
                if i.executors >> r & 1:
                    self.per_robot_step.setdefault((r, k), []).append(x)
        self.chosen.append((i, xs))
        u = m.new_bool_var("")
        m.add(u == sum(x for _, x in xs))
        for r in range(len(self.problem.robots)):
            if i.executors >> r & 1:
                self.work[r].append(_Job(d, (d,), u))
        self.paths.setdefault(i.obj, []).append(_Job(d, (d,), u))
        st = m.new_int_var(first, last, "")
        tm = m.new_int_var(0, self.level, "")  # when its step starts
        for k, x in xs:
            m.add(st == k).only_enforce_if(x)
            m.add(tm == self.start[k]).only_enforce_if(x)
        return _Slot(u, st, 1, tm)

    def split(
        self,
        r: int,
        t: Target,
        loop: tuple[int, int],
        hold: _Hold,
        arrivals: _Stamps,
        departures: _Stamps,
    ) -> list[tuple[int, Any]]:
        # the object first leaves r's hand in step e (after the arrival's step a) and last
        # comes back in step f (e < f, before the departure's step b): r holds it in [a, e]
        # and in [f, b] (docs/planner.md, "Step bound")
        p, m, K, unit, split = self.problem, self.model, self.horizon, self.unit, hold.split
        if self.holders:
            e, f = m.new_int_var(0, K, ""), m.new_int_var(0, K, "")
            m.add(e >= hold.end_in).only_enforce_if(split)
            m.add(f + 1 <= hold.start_out).only_enforce_if(split)
        else:  # session 8's runs, [a, a+2) and [b-1, b+1)
            e, f = hold.end_in, hold.start_out - 1
        m.add(f >= e + 1).only_enforce_if(split)
        out = [
            (r, m.new_optional_interval_var(hold.begin, m.new_int_var(0, K, ""), e + 1, split, "")),
            (r, m.new_optional_interval_var(f, m.new_int_var(0, K, ""), hold.end, split, "")),
        ]
        # the loop takes time, from the arrival's end to the departure's start
        arrived, leaves = m.new_int_var(0, self.level, ""), m.new_int_var(0, self.level, "")
        for u, when in arrivals:
            m.add(arrived == when).only_enforce_if(u)
        for u, when in departures:
            m.add(leaves == when).only_enforce_if(u)
        m.add(arrived + (loop[0] + loop[1]) // unit <= leaves).only_enforce_if(split)
        # the way out and the way back are two more instances of r's, each in a step of its
        # own: r's load, and its steps (``finish``)
        self.work[r].append(
            _Job((loop[0] + loop[1]) // unit, (loop[0] // unit, loop[1] // unit), split)
        )
        if not self.holders:
            return out
        # and the steps e and f last at least the quickest way out and the quickest way back
        for at, d in ((e, loop[0] // unit), (f, loop[1] // unit)):
            which = [m.new_bool_var("") for _ in range(K)]
            m.add(sum(which) == split)
            for k, b in enumerate(which):
                m.add(at == k).only_enforce_if(b)
                m.add_implication(b, self.at_least[k][d] if d > self.d_min else self.busy[k])
        # where the way out takes it (a robot's hand, or a place no robot holds), from where it
        # can go on without its atom happening: a robot there holds it in step e and acts on
        # it again in a later one, so it holds it in [e, e + 1], and does two instances on it
        o = t.obj
        on: dict[int, int] = {}  # place -> quickest way on from there
        for i in p.by_obj_pre[o][p.held_code[r]]:
            if i.index in t.fires or i.post in on:
                continue
            nxt = [j.lower for j in p.by_obj_pre[o][i.post] if j.index not in t.fires]
            if nxt:
                on[i.post] = min(nxt)
        taken: dict[int | None, tuple[int, Any]] = {}  # robot (None: none) -> (work, literal)
        for i in p.by_obj_pre[o][p.held_code[r]]:
            if i.index in t.fires or i.post not in on:
                continue
            who = p.code_holder.get(i.post)
            work = (i.lower + on[i.post]) // unit
            if who in taken:
                taken[who] = (min(work, taken[who][0]), taken[who][1])
            else:
                taken[who] = (work, m.new_bool_var(""))
        m.add(sum(z for _, z in taken.values()) == split)
        for who, (work, z) in taken.items():
            if who is not None:
                out.append((who, m.new_optional_fixed_size_interval_var(e, 2, z, "")))
                self.work[who].append(_Job(work, (self.d_min, self.d_min), z))
        return out

    def finish(self) -> None:
        m = self.model
        for lits in self.per_robot_step.values():
            if len(lits) > 1:
                m.add_at_most_one(lits)
        # Counting rows (docs/planner.md, "Counting rows"): a robot's instances, and the
        # instances of one object's path, each fill a non-empty step of their own that lasts at
        # least the instance, and every other non-empty step lasts at least d_min. So, with B
        # the non-empty steps and A_d the steps of at least d: they are at most B, those of at
        # least d at most A_d, and their durations plus d_min per other non-empty step at most
        # the level. Mostly implied by the step literals, but CP-SAT's linear relaxation sees
        # them only when stated (and a loop's two instances have no step literals of their own)
        dm = self.d_min
        steps = sum(self.busy)
        longer = {d: sum(row[d] for row in self.at_least) for d in self.lengths}
        for jobs in [*self.work, *self.paths.values()]:
            if not jobs:
                continue
            m.add(sum(j.total * j.used for j in jobs) <= self.level)
            m.add(sum(len(j.each) * j.used for j in jobs) <= steps)
            m.add(
                sum((j.total - len(j.each) * dm) * j.used for j in jobs) + dm * steps <= self.level
            )
            for d in self.lengths:
                at_least_d = [(sum(e >= d for e in j.each), j.used) for j in jobs]
                if any(n for n, _ in at_least_d):
                    m.add(sum(n * u for n, u in at_least_d if n) <= longer[d])


def _relaxation(
    problem: Problem, graph: RelaxedGraph, node: Node, tgts: Sequence[Target], axis: _Axis
) -> bool:
    """Build the relaxation's paths and hand sessions into ``axis.model`` on ``axis``: per
    target, its object's path from where it is to an instance that makes the atom happen, and
    per robot the sessions in which it holds that object (whole, or split around a loop), none
    of a robot's overlapping; every "first A, then B" order. False (the model unfinished) when
    some target cannot happen by ``axis.level``."""
    p, m = problem, axis.model
    locs = node[0]
    cap = axis.level * axis.unit
    H = axis.horizon
    per_robot: list[list[Any]] = [[] for _ in p.robots]
    fire_at: list[Any] = []
    for t in tgts:
        o, s0 = t.obj, locs[t.obj]
        reach = graph.place_time[o][s0]
        togo = graph.event_time[o]
        if togo[s0].get(t.atom, math.inf) > cap:
            return False
        window = axis.windows(p, t, s0)
        cand: list[tuple[Instance, tuple[int, int], float]] = []
        for i in (i for row in p.by_obj_pre[o] for i in row):
            fires = i.index in t.fires
            rest = 0 if fires else togo[i.post].get(t.atom, math.inf)
            if reach[i.pre] + i.lower + rest > cap or (not fires and i.post == s0):
                continue
            w = window(i, fires, rest)
            if w is not None:
                cand.append((i, w, rest))
        places = {s0} | {i.pre for i, _, _ in cand}
        places |= {i.post for i, _, _ in cand if i.index not in t.fires}
        arrive = {c: m.new_int_var(0, H, "") for c in places}
        m.add(arrive[s0] == 0)
        outs: dict[int, list[Any]] = {c: [] for c in places}
        ins: dict[int, list[Any]] = {c: [] for c in places}
        fired: list[tuple[Any, Any]] = []
        opens: dict[int, list[tuple[Any, Any, int]]] = {}  # robot -> (used, at, span)
        closes: dict[int, list[tuple[Any, Any, int, bool]]] = {}  # ... and whether it fires
        arrivals: dict[int, list[tuple[Any, Any]]] = {}  # robot -> (used, time the arrival ends)
        departures: dict[int, list[tuple[Any, Any]]] = {}  # ... (used, time it starts)
        for i, w, rest in cand:
            slot = axis.place(i, w, reach[i.pre], rest)
            u, st, span = slot.used, slot.at, slot.span
            m.add(st >= arrive[i.pre]).only_enforce_if(u)
            outs[i.pre].append(u)
            fires = i.index in t.fires
            if fires:
                fired.append((u, st))
            else:
                ins[i.post].append(u)
                m.add(arrive[i.post] == st + span).only_enforce_if(u)
                r_in = p.code_holder.get(i.post)
                if r_in is not None:
                    opens.setdefault(r_in, []).append((u, st, span))
                    arrivals.setdefault(r_in, []).append((u, slot.begins + i.lower // axis.unit))
            r_out = p.code_holder.get(i.pre)
            if r_out is not None:
                closes.setdefault(r_out, []).append((u, st, span, fires))
                departures.setdefault(r_out, []).append((u, slot.begins))
        if not fired:
            return False
        fire_at.append(_path(m, s0, places, outs, ins, fired, H))
        for r, ends in closes.items():
            starts = opens.get(r)
            if not starts:
                # the object is in r's hand at the start: its leaving is plain work of r
                for u, st, span, _ in ends:
                    per_robot[r].append(m.new_optional_fixed_size_interval_var(st, span, u, ""))
                continue
            loop = _quickest_loop(p, t, r)
            ivs, hold = _session(m, H, starts, ends, loop is not None and not axis.whole)
            per_robot[r].extend(ivs)
            if loop is not None and hold is not None:
                for who, iv in axis.split(r, t, loop, hold, arrivals[r], departures[r]):
                    per_robot[who].append(iv)
    for k, t in enumerate(tgts):
        for j in t.after:
            m.add(fire_at[k] >= fire_at[j])
    for k, j in twin_pairs(p, tgts, locs):
        m.add(fire_at[k] <= fire_at[j])
    for ivs in per_robot:
        if len(ivs) > 1:
            m.add_no_overlap(ivs)
    axis.finish()
    return True


def twin_pairs(
    problem: Problem, tgts: Sequence[Target], locs: Sequence[int]
) -> list[tuple[int, int]]:
    """Pairs (k, j) of targets whose atoms may be made to happen in this order (k's step no
    later than j's) without changing whether a relaxed schedule exists: the objects of each
    class of ``Problem.symmetry`` (interchangeable objects) that rest at the same place, in
    class order, when no target has an order (docs/planner.md, "Twins in the relaxation")."""
    if any(t.after for t in tgts):
        return []
    index = {t.obj: k for k, t in enumerate(tgts)}
    out: list[tuple[int, int]] = []
    for cls in problem.symmetry.classes:
        by_place: dict[int, list[int]] = {}
        for o, _ in cls:
            if o in index:
                by_place.setdefault(locs[o], []).append(index[o])
        for ks in by_place.values():
            out += pairwise(ks)
    return out


def _quickest_loop(problem: Problem, t: Target, r: int) -> tuple[int, int] | None:
    """The quickest way (ticks) for ``t``'s object out of robot ``r``'s hand without its atom
    happening (a loop goes on) and the quickest way back in, over every instance, so that no
    way a plan may take is missed; None when either does not exist."""
    hand = problem.held_code[r]
    o = t.obj
    leave = [i.lower for i in problem.by_obj_pre[o][hand] if i.index not in t.fires]
    back = [i.lower for row in problem.by_obj_pre[o] for i in row if i.post == hand]
    return (min(leave), min(back)) if leave and back else None


def _path(
    m: Any,
    s0: int,
    places: set[int],
    outs: dict[int, list[Any]],
    ins: dict[int, list[Any]],
    fired: list[tuple[Any, Any]],
    H: int,
) -> Any:
    """One object's path from ``s0`` to exactly one instance of ``fired`` (used, start): it
    leaves s0 once, enters and leaves every other place at most once (cycles apart from it are
    impossible: each instance starts after the last one ended). The firing instance's start."""
    m.add(sum(outs[s0]) == 1)
    for c in places:
        if c != s0:
            m.add(sum(ins[c]) <= 1)
            m.add(sum(outs[c]) == sum(ins[c]))
    m.add_exactly_one(u for u, _ in fired)
    fs = m.new_int_var(0, H, "")
    for u, st in fired:
        m.add(fs == st).only_enforce_if(u)
    return fs


def _hops(problem: Problem, obj: int, sources: Sequence[int], forward: bool) -> dict[int, int]:
    """The fewest instances that take ``obj`` from one of ``sources`` to each place (forward)
    or from each place to one of ``sources`` (backward)."""
    edges: dict[int, list[int]] = {}
    for row in problem.by_obj_pre[obj]:
        for i in row:
            a, b = (i.pre, i.post) if forward else (i.post, i.pre)
            edges.setdefault(a, []).append(b)
    dist = {s: 0 for s in sources}
    frontier = list(dict.fromkeys(sources))
    while frontier:
        nxt = []
        for a in frontier:
            for b in edges.get(a, ()):
                if b not in dist:
                    dist[b] = dist[a] + 1
                    nxt.append(b)
        frontier = nxt
    return dist


@dataclass(frozen=True, slots=True)
class _Hold:
    """A robot's session with an object as the model sees it: where the instance that brings
    the object starts and ends, where the one that takes it away starts and ends, and (when it
    may be split around a loop) the literal "it is split"."""

    begin: Any
    end_in: Any
    start_out: Any
    end: Any
    split: Any


def _session(
    m: Any,
    H: int,
    starts: list[tuple[Any, Any, int]],
    ends: list[tuple[Any, Any, int, bool]],
    may_split: bool,
) -> tuple[list[Any], _Hold | None]:
    """Robot r's time with the object in hand, as intervals for r's no-overlap: whole, from the
    instance that brings it to the one that takes it away; or, when ``may_split`` (the object
    may leave r and come back: a loop the path does not show), split, which the axis models
    (``_Axis.split``) from the session returned."""
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
    if not may_split:
        m.add(whole == present)
        return out, None
    split = m.new_bool_var("")
    m.add(whole + split == present)
    return out, _Hold(begin, end_in, start_out, end, split)
