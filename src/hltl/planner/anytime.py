"""Anytime planning with a certificate: prioritized plans fast, then proof of how good they are."""

from __future__ import annotations

import math
import multiprocessing
import random
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from hltl.planner import lns, profile, repair, schedule
from hltl.planner.clock import WALL, Clock
from hltl.planner.pairs import PairBound, pair_value
from hltl.planner.problem import TICKS_PER_SECOND, Instance, Node, Problem, to_seconds
from hltl.planner.result import PlanResult, PlanStatus, SearchStats
from hltl.planner.search import _infeasible, _Search, plan_steps, search
from hltl.spec.monitor import DONE
from hltl.spec.syntax import And, Atom, Eventually, Formula, Or

if TYPE_CHECKING:
    from multiprocessing.connection import Connection


# the share of the time budget by which more priority orders stop being tried
RESTART_SHARE = 0.5
# the share spent first on the exact search (small cells are proved optimal right away)
EXACT_FIRST_SHARE = 0.2
# big cells: pair bounds until this share of the budget, more orders until the next
PAIRS_SHARE = 0.45
BIG_RESTART_SHARE = 0.9
# neighbourhood moves per new priority order (a move reroutes a few goals, an order all of them)
LNS_STEPS = 2
# big cells: pairs tried at the start node before giving up when none beats the start bound
PAIRS_TRIAL = 8
# pair tables cost about a millisecond each; beyond this many goal atoms they wait for A*
PAIRS_UP_TO = 8
# CP-SAT re-plans every goal jointly (``_jointly``) when the plan phase has this many seconds,
# after the walk over priority orders has had this share of them
CP_MIN_SECONDS = 2.0
CP_WALK_SHARE = 0.2
# ... and has at most this many goals: with 32, CP-SAT's presolve alone takes about 3 s of the
# budget, and the 10 s benchmark runs lost more on 32-robot lines (the walk's time) than they
# gained on grids (docs/planner.md, "Anytime mode")
CP_UP_TO = 16
# ... keeping each object to places on routes at most this much slower than its quickest (s)
CP_DETOUR = 0.6
# cells of more goals (no joint re-plan) where the profile bound runs (grids, random layouts,
# 10 s budgets): after this share of the time the walk's best plan is squeezed into fewer steps
# by conflict repair (``_squeezed``, ``repair.Repair``) until the end. 0: the repair
# squeezes the walk's first plan (the critical-first order's) at once. The walk's 1.5 s took
# 32 x 32 grid 3 from 27 to 25 steps, which the repair squeezes to 18 in about 1.2 s from
# either; its last level (17 steps) is the one that needs the time (docs/planner.md, "Session
# 23"; 0.15 against 0.3 in session 20: random 4 13.0 -> 12.4 s)
REPAIR_WALK_SHARE = 0.0
# big cells of at most this many goals: the relaxed-schedule bound (``schedule``) runs first,
# until this share of the budget
SCHEDULE_UP_TO = 16
SCHEDULE_SHARE = 0.25
# the step bound (``step_bound``) only where the start bound is at most this many of the
# shortest steps: its model has a variable per instance and step, and on 10-robot lines (start
# bound 11.7 s, 23 steps) it proved nothing in 7.6 s of CPU where A* alone finishes in about 5 s
STEPS_UP_TO = 16
# cells of more goals than SCHEDULE_UP_TO where no pair beats the start bound (grids and random
# layouts: docs/planner.md, "Profile bound"): the last share of the budget goes to the profile
# bound, when that share is at least PROFILE_MIN_SECONDS long (``_profile_fits``: 10 s budgets
# give it 1 s). The A* slice's share: on 32-goal
# cells that slice raised no bound, while a share taken from the walk cost more plan than it
# gave bound (0.3 of 10 s under load: random 32 x 32 median gap 35.6 -> 38.7 %)
PROFILE_SHARE = 1.0 - BIG_RESTART_SHARE
PROFILE_MIN_SECONDS = 1.0
# on two cores the profile bound runs beside the walk (``_ProfileBeside``); at the deadline it
# is waited for this much longer (its last CP-SAT solve ends at the deadline), then stopped
BESIDE_GRACE = 0.2
# ... and once its bound is final it squeezes plans too (``_plans_beside``): the walk's best
# plan, handed over in shared memory (``_Slot``: at most SLOT_INSTANCES instances), with this
# seed for its conflict repair (the walk's process uses ``repair.Repair``'s default); each
# process looks for a shorter plan from the other every NEWS_EVERY repair moves
BESIDE_SEED = 11
SLOT_INSTANCES = 4096
NEWS_EVERY = 64


@dataclass(frozen=True, slots=True)
class Goal:
    """An atom to make true, its object, and the goals that must not happen after it."""

    atom: Atom
    obj: int
    after: tuple[int, ...]


# a plan found: its cost in ticks and its (node before, step, duration) chain
_Found = tuple[int, list[tuple[Node, tuple[Instance, ...], int]]]


# one goal's route: (step, instance) actions, (robot, step) holds, final step, and the robot that
# keeps the object afterwards (None: nobody)
_Route = tuple[list[tuple[int, Instance]], list[tuple[int, int]], int, int | None]


class _Unsupported(Exception):
    """The spec has a shape prioritized routing does not serve (the exact search still does)."""


def goals(s: _Search, node: Node) -> list[Goal] | None:
    """The goal atoms that satisfy the spec from ``node`` (one branch per "or", the one with the
    earlier relaxed finish), or None when the spec is not made of such goals."""
    p = s.p
    spec = p.spec
    names = {name for name, _ in spec.formulas}
    index = {n: i for i, n in enumerate(s.monitor.nodes)}
    locs, _, q = node
    graph = s.heuristic.graph

    def estimate(atoms_: Sequence[Atom]) -> float:
        return max((graph.atom_time(a, locs) for a in atoms_), default=0.0)

    order: list[tuple[Atom, Atom]] = []  # (before, after)

    def walk(name: str) -> list[Atom]:
        if q[index[name]] == DONE:
            return []
        f = spec.formula(name)
        if name in spec.leaves:
            if isinstance(f, Eventually) and isinstance(f.operand, Atom) and f.operand.args:
                return [f.operand]
            raise _Unsupported(name)
        return tree(f)

    def tree(f: Formula) -> list[Atom]:
        if isinstance(f, Eventually) and isinstance(f.operand, Atom) and f.operand.name in names:
            return walk(f.operand.name)
        if (
            isinstance(f, Eventually)
            and isinstance(f.operand, And)
            and isinstance(f.operand.left, Atom)
            and isinstance(f.operand.right, Eventually)
            and isinstance(f.operand.right.operand, Atom)
        ):
            # F (a & F b): a no later than b
            first = walk(f.operand.left.name)
            second = walk(f.operand.right.operand.name)
            order.extend((x, y) for x in first for y in second)
            return first + second
        if isinstance(f, And):
            return tree(f.left) + tree(f.right)
        if isinstance(f, Or):
            a, b = tree(f.left), tree(f.right)
            return a if estimate(a) <= estimate(b) else b
        raise _Unsupported(str(f))

    try:
        atoms_ = list(dict.fromkeys(walk(spec.root)))
    except _Unsupported:
        return None
    out: list[Goal] = []
    position = {a: i for i, a in enumerate(atoms_)}
    seen_objects: set[int] = set()
    for a in atoms_:
        g = graph.goal(a)
        if g is None or g[0] in seen_objects:
            return None  # two goals on one object: routing serves one goal per object
        seen_objects.add(g[0])
        after = tuple(sorted(position[x] for x, y in order if y == a and x in position))
        out.append(Goal(a, g[0], after))
    return out


class _Router:
    """Prioritized routing over steps with per-robot reservations."""

    def __init__(self, s: _Search, node: Node, gls: Sequence[Goal]) -> None:
        self.s = s
        self.p = s.p
        self.node = node
        self.goals = gls
        p = self.p
        self.targets = {g.obj for g in gls}
        self.last_goal: int | None = None  # the goal the last routed plan served last
        self.routes: dict[int, _Route] = {}  # per goal its route in the last routed plan
        graph = s.heuristic.graph
        # per goal and place: can the atom still happen from there? (prune hopeless routes)
        self.alive: list[list[bool]] = [
            [
                graph.atom_time(g.atom, _with(node[0], g.obj, loc)) < math.inf
                for loc in range(len(p.locs))
            ]
            for g in gls
        ]
        # per goal: the instances that make its atom happen (event atoms), or per place whether
        # the atom holds there (state atoms): integer look-ups in the routing loop
        self.fires: list[frozenset[int]] = [
            frozenset(i.index for row in p.by_obj_pre[g.obj] for i in row if g.atom in i.events)
            for g in gls
        ]
        self.holds_at: list[list[bool] | None] = [
            None
            if g.atom.name in ("delivered", "placed", "picked")
            else [g.atom in atoms_ for atoms_ in p.state_atoms[g.obj]]
            for g in gls
        ]

    def route_all(
        self, order: Sequence[int], fixed: dict[int, _Route] | None = None
    ) -> list[list[Instance]] | None:
        """The plan's steps when the goals of ``fixed`` keep their routes and the goals of
        ``order`` are routed one after the other around them (None: some goal cannot be
        served). The routes of every goal are kept in ``routes``."""
        p = self.p
        locs = self.node[0]
        n_robots = len(p.robots)
        # per step, the robots busy in it as a bit mask; per robot, the step from which it keeps
        # an object for good
        busy: dict[int, int] = {}
        forever = [math.inf] * n_robots
        for o, code in enumerate(locs):
            r = p.code_holder.get(code)
            if r is not None and o not in self.targets:
                forever[r] = 0  # holds an object nobody asked for: out of play
        steps: dict[int, list[Instance]] = {}
        finish: dict[int, int] = {}
        routes: dict[int, _Route] = {}

        def reserve(gi: int, found: _Route) -> None:
            route, holds, end, keep = found
            for t, inst in route:
                steps.setdefault(t, []).append(inst)
                busy[t] = busy.get(t, 0) | inst.executors
            for r, t in holds:
                busy[t] = busy.get(t, 0) | 1 << r
            if keep is not None:
                forever[keep] = min(forever[keep], end + 1)
            finish[gi] = end
            routes[gi] = found

        for gi, kept in (fixed or {}).items():
            reserve(gi, kept)
        for gi in order:
            g = self.goals[gi]
            earliest = max((finish[j] for j in g.after if j in finish), default=0)
            found = self._route(g, gi, locs[g.obj], earliest, busy, forever)
            if found is None:
                return None
            reserve(gi, found)
        self.routes = routes
        self.last_goal = max(finish, key=lambda gi: (finish[gi], -gi))
        return [steps[t] for t in sorted(steps)]

    def _route(
        self,
        g: Goal,
        gi: int,
        start: int,
        earliest: int,
        busy: dict[int, int],
        forever: list[float],
    ) -> _Route | None:
        """Earliest step at which the goal's atom happens, routing its object around the
        reservations (``busy``: per step the robots reserved in it, a bit mask; ``forever``: per
        robot the step from which it is taken): (actions by step, (robot, step) holds, final
        step, robot that keeps the object afterwards or None).

        Of the routes that make the atom happen at that step, the one that takes the fewest
        robot-steps: an instance counts each of its robots, a step the object waits in a hand
        counts its holder. Without that, a route would as soon move its object through idle
        robots as let it wait, and those robots are then busy for the goals routed after it
        (docs/planner.md, "Anytime mode")."""
        p = self.p
        holder = p.code_holder
        alive = self.alive[gi]
        fires = self.fires[gi]
        holds_at = self.holds_at[gi]
        by_pre = p.by_obj_pre[g.obj]
        # robots taken for good, as (from step, bit), earliest first
        taken = sorted((f, 1 << r) for r, f in enumerate(forever) if f < math.inf)
        gone = 0  # robots taken for good by the current step
        k = 0
        horizon = max(busy, default=0) + 4 * len(p.locs) + earliest
        horizon += 8
        back: dict[tuple[int, int], tuple[int, Instance | None]] = {}
        # per place the object can be in at step t: the fewest robot-steps that bring it there
        frontier = {start: 0}
        for t in range(horizon):
            while k < len(taken) and taken[k][0] <= t:
                gone |= taken[k][1]
                k += 1
            blocked = busy.get(t, 0) | gone
            nxt: dict[int, int] = {}
            done: tuple[int, int, Instance] | None = None  # (robot-steps, place, last instance)
            for loc, cost in frontier.items():
                r_hold = holder.get(loc)
                if r_hold is not None and blocked >> r_hold & 1:
                    continue  # the holder is needed elsewhere in this step: impossible state
                for inst in by_pre[loc]:
                    fired = inst.index in fires
                    if not alive[inst.post] and not fired:
                        continue
                    if inst.executors & blocked:
                        continue
                    c = cost + inst.executors.bit_count()
                    reached = fired if holds_at is None else holds_at[inst.post]
                    if reached and t >= earliest:
                        if done is None or c < done[0]:
                            done = (c, loc, inst)
                        continue
                    if c < nxt.get(inst.post, math.inf):
                        nxt[inst.post] = c
                        back[(inst.post, t + 1)] = (loc, inst)
                c = cost + (r_hold is not None)  # wait (in a hand: its holder's step)
                if c < nxt.get(loc, math.inf):
                    nxt[loc] = c
                    back[(loc, t + 1)] = (loc, None)
            if done is not None:
                return self._unwind(back, start, done[1], t, done[2])
            frontier = nxt
        return None

    def _unwind(
        self,
        back: dict[tuple[int, int], tuple[int, Instance | None]],
        start: int,
        loc: int,
        t: int,
        last: Instance,
    ) -> _Route:
        holder = self.p.code_holder
        route: list[tuple[int, Instance]] = [(t, last)]
        holds: list[tuple[int, int]] = []
        r = holder.get(loc)
        if r is not None:
            holds.append((r, t))
        cur, ct = loc, t
        while ct > 0:
            prev, inst = back[(cur, ct)]
            ct -= 1
            if inst is not None:
                route.append((ct, inst))
            r = holder.get(prev)
            if r is not None:
                holds.append((r, ct))
            cur = prev
        assert cur == start
        keep = holder.get(last.post)
        return route[::-1], holds, t, keep

    def replay(self, steps: Sequence[Sequence[Instance]]) -> _Found | None:
        """Check the plan step by step (preconditions, monitors); its cost and chain, cut at the
        step in which the root fires; None if it is not a plan."""
        return replay(self.s, self.node, steps)


def replay(s: _Search, node: Node, steps: Sequence[Sequence[Instance]]) -> _Found | None:
    """Check ``steps`` from ``node`` step by step (robots disjoint within a step, objects where
    the instances need them, receiving robots free, monitors); the plan's cost and chain, cut at
    the step in which the root fires; None if it is not a plan."""
    p = s.p
    total = 0
    chain: list[tuple[Node, tuple[Instance, ...], int]] = []
    for U in steps:
        locs = node[0]
        held = {p.code_holder[c] for c in locs if c in p.code_holder}
        busy = 0
        for inst in U:
            if locs[inst.obj] != inst.pre or any(r in held for r in inst.free):
                return None
            if busy & inst.executors:
                return None
            busy |= inst.executors
        if len({i.obj for i in U}) != len(U):
            return None
        step = tuple(sorted(U, key=lambda i: i.index))
        applied = s.apply(node, step)
        if applied is None:  # an instance has no motion from these hands
            return None
        cost, child = applied
        chain.append((node, step, cost))
        total += cost
        node = child
        if p.monitor.accepted(node[2]):
            return total, chain
    return None


def _with(locs: tuple[int, ...], o: int, loc: int) -> tuple[int, ...]:
    out = list(locs)
    out[o] = loc
    return tuple(out)


def _orders(s: _Search, node: Node, gls: Sequence[Goal], seed: int) -> Callable[[], list[int]]:
    """Priority orders: most critical goal first, then random ones; "after" goals keep order."""

    graph = s.heuristic.graph
    crit = [graph.atom_time(g.atom, node[0]) for g in gls]
    rng = random.Random(seed)
    calls = [0]

    def next_order() -> list[int]:
        calls[0] += 1
        noise = [0.0 if calls[0] == 1 else rng.random() * (1.0 + c) for c in crit]
        key = [-(c + n) for c, n in zip(crit, noise, strict=True)]
        placed: list[int] = []
        left = set(range(len(gls)))
        while left:
            ready = [i for i in left if all(j not in left for j in gls[i].after)]
            if not ready:  # a cycle in "after": no order serves it
                return []
            i = min(ready, key=lambda k: (key[k], k))
            placed.append(i)
            left.discard(i)
        return placed

    return next_order


def construct(
    problem: Problem,
    s: _Search | None = None,
    *,
    tries: int = 1,
    deadline: float = math.inf,
    clock: Clock = WALL,
) -> _Found | None:
    """The best prioritized plan over ``tries`` priority orders (cost in ticks, step chain),
    no more tried once ``clock`` has passed ``deadline``."""
    s = _Search(problem) if s is None else s
    node = problem.start()
    gls = goals(s, node)
    if not gls:
        return None
    router = _Router(s, node, gls)
    next_order = _orders(s, node, gls, seed=0)
    best: _Found | None = None
    for k in range(tries):
        if k and clock.now() > deadline:
            break
        order = next_order()
        steps = router.route_all(order) if order else None
        found = None if steps is None else router.replay(steps)
        if found is not None and (best is None or found[0] < best[0]):
            best = found
    return best


def plan_anytime(
    problem: Problem,
    *,
    timeout: float = 10.0,
    suboptimality: float | None = None,
    on_improve: Callable[[float, float, float], None] | None = None,
    clock: Clock = WALL,
) -> PlanResult:
    """A plan within ``timeout`` seconds and a proven lower bound on the optimum.

    Args:
        problem: the compiled problem.
        timeout: seconds for the whole run (first plan, improvements, bound).
        suboptimality: stop as soon as makespan <= suboptimality x lower bound (e.g. 1.1).
        on_improve: called with (seconds since start, makespan, lower bound) on every change.
        clock: where the deadline, the phases' shares and the seconds reported are read
            (``clock.WALL``; tests: a ``clock.WorkClock``, docs/planner.md "The clock").

    Returns:
        ``solved`` with ``lower_bound`` and ``gap`` (0: proved optimal); ``infeasible`` when no
        plan exists; ``timeout`` when no plan was found in time (the bound is still reported).
    """

    t0 = clock.now()
    deadline = t0 + timeout
    s = _Search(problem)
    heur = s.heuristic
    start = problem.start()
    if problem.monitor.accepted(start[2]):
        return PlanResult(PlanStatus.SOLVED, (), 0.0, SearchStats(0, 1, 0.0, "anytime"), "", 0.0)
    lb: float = heur(start)
    if math.isinf(lb):
        return _infeasible(problem, s, "anytime", t0, 0, 1, clock=clock)

    best = construct(problem, s, tries=1, deadline=deadline, clock=clock)
    first = None if best is None else clock.now() - t0

    def note() -> None:
        if on_improve is not None and best is not None:
            on_improve(clock.now() - t0, to_seconds(best[0]), to_seconds(lb))

    def good_enough() -> bool:
        if best is None:
            return False
        if best[0] <= lb:
            return True
        return suboptimality is not None and best[0] <= suboptimality * lb

    note()
    n_goals = len(heur.required_atoms(start[2]))
    if not good_enough() and n_goals <= PAIRS_UP_TO:
        heur.enable_pairs()
        lb = max(lb, heur(start))
        note()
    # small cells: a short exact search first (they finish here, proved optimal), then more
    # priority orders, then the exact search again with whatever time is left. Big cells: pair
    # bounds at the start node (most promising pairs first) instead of the first exact slice,
    # whose very first expansion would enumerate more step sets than there is time for
    big = n_goals > PAIRS_UP_TO
    if big and not good_enough() and best is not None:
        until = t0 + SCHEDULE_SHARE * timeout
        if schedule.steps_applicable(problem):
            ticks, found = step_bound(problem, s, start, round(lb), best[0], clock.wall(until))
            if found is not None and found[0] < best[0]:
                best = found
        else:
            ticks = _schedule_at_start(problem, s, start, round(lb), best[0], clock.wall(until))
        lb = max(lb, ticks)
        note()
    phases = (
        (PAIRS_SHARE, BIG_RESTART_SHARE, 1.0) if big else (EXACT_FIRST_SHARE, RESTART_SHARE, 1.0)
    )
    expanded = 0
    profiled = False  # the last share goes to the profile bound instead of A*
    beside: _ProfileBeside | None = None  # ... or, on two cores, a thread beside the walk
    try:
        for k, until in enumerate(phases):
            if good_enough():
                break
            end = min(deadline, t0 + until * timeout)
            if big and k == 0:
                profiled = (
                    best is not None
                    and n_goals > SCHEDULE_UP_TO
                    and _profile_fits(timeout)
                    and profile.applicable(problem)
                    and lns.installed()
                )
                if profiled and beside_possible():
                    # on two cores the profile bound starts now, beside the pairs (0.8-0.9 s
                    # on 32-goal grid and random cells), and is stopped if a pair beats the
                    # start bound (lines: there the pairs are the bound)
                    assert best is not None
                    beside = _ProfileBeside(
                        problem, s, start, round(lb), best[0], deadline, clock=clock
                    )
                # (the first pair even when the first plan came after this phase's end)
                walk_end = min(deadline, t0 + phases[1] * timeout)
                paired = _pairs_at_start(
                    problem, s, start, end, lb, first_until=walk_end, clock=clock
                )
                if paired > lb:
                    profiled = False
                    if beside is not None:
                        beside.close()
                        lb = max(lb, beside.bound)
                        beside = None
                lb = max(lb, paired)
                note()
                continue
            if profiled and k == 1:
                end = deadline if beside else min(deadline, t0 + (1 - PROFILE_SHARE) * timeout)
            # more goals than the step bound takes and no profile bound (a pair beat the start
            # bound: lines; or a budget too short for it): the A* slice raised no bound there
            # (32 x 32 line seed 0: 36.3 s from 4.5 s to the end of a 10 s run; grid seed 0 in
            # session 10), so the walk keeps its time (at 1 s the walk's last 0.1 s found
            # 32 x 32 line seed 1's 35.8 s plan in some runs and not in others)
            if big and n_goals > SCHEDULE_UP_TO and not profiled:
                if k == 1:
                    end = deadline
                elif k == 2:
                    continue
            if profiled and k == 2:
                if beside is None:
                    assert best is not None
                    tgts = schedule.targets(
                        problem, heur.graph, start, heur.required_atoms(start[2])
                    )
                    bound = profile.profile_bound(
                        problem,
                        heur.graph,
                        start,
                        tgts,
                        floor=round(lb),
                        upper=best[0],
                        deadline=clock.wall(end),
                    )
                    lb = max(lb, bound.ticks)
                    note()
                continue
            if k == 1:
                if best is not None:
                    # (repair where the profile bound runs: grid and random layouts; on
                    # 32-goal lines the walk's plans meet the pairs' bound within 0.5 %,
                    # and at 1 s its whole phase is needed: 1 s gaps 0.5 -> 6.2 % with it)
                    cand = _more(
                        problem,
                        s,
                        end,
                        enough=lb,
                        squeeze=profiled,
                        exchange=None if beside is None else beside.exchange,
                        clock=clock,
                    )
                    if cand is not None and cand[0] < best[0]:
                        best = cand
                        note()
                continue
            remaining = end - clock.now()
            if remaining <= 0:
                continue
            res = search(
                problem,
                timeout=remaining,
                clock=clock,
                upper=None if best is None else best[0],
                state=s,
                pairs_after=0 if n_goals <= PAIRS_UP_TO else 10**9,
            )
            expanded += res.stats.expanded
            if res.status is PlanStatus.SOLVED and res.makespan is not None:
                stats = SearchStats(
                    expanded, res.stats.generated, clock.now() - t0, "anytime", first
                )
                return PlanResult(
                    PlanStatus.SOLVED, res.steps, res.makespan, stats, "", res.makespan
                )
            if res.status is PlanStatus.INFEASIBLE and best is None:
                return res
            if res.status is PlanStatus.INFEASIBLE:
                assert best is not None
                lb = best[0]  # nothing shorter exists: the incumbent is optimal
            elif res.lower_bound is not None:
                lb = max(lb, round(res.lower_bound * TICKS_PER_SECOND))
            note()
        if beside is not None:
            # (not wanted when the plan already meets the bound: stopped at once)
            lb = max(lb, beside.finish(wanted=not good_enough()))
            # (the plan it squeezed last, if the walk did not take it yet: replayed here)
            theirs = beside.exchange.news()
            found = None if theirs is None else replay(s, start, _steps_of(theirs))
            if found is not None and best is not None and found[0] < best[0]:
                best = found
            note()
    finally:
        if beside is not None:
            beside.close()
    stats = SearchStats(expanded, 0, clock.now() - t0, "anytime", first)
    if best is None:
        return PlanResult(
            PlanStatus.TIMEOUT,
            stats=stats,
            reason=f"no plan found in {timeout:g} s (lower bound {to_seconds(lb):.3f} s)",
            lower_bound=to_seconds(lb),
        )
    steps = plan_steps(problem, best[1])
    return PlanResult(
        PlanStatus.SOLVED, steps, to_seconds(best[0]), stats, "", to_seconds(min(lb, best[0]))
    )


def beside_possible() -> bool:
    """The profile bound can run in a process of its own beside the walk: two cores
    (``schedule.WORKERS``) and processes started by ``fork`` (which copies the compiled
    problem instead of pickling it)."""

    return schedule.WORKERS >= 2 and "fork" in multiprocessing.get_all_start_methods()


class _ProfileBeside:
    """The profile bound in a process of its own beside the walk (``beside_possible``), from
    the end of the pair bounds to the deadline, instead of the walk's last ``PROFILE_SHARE``:
    the walk keeps its core and Python's lock (a thread would take turns with it on both, for
    CP-SAT's import and each question's model: 0.5-1.5 s and 0.3-0.5 s of CPU on 32 goals),
    and the bound gets the other core. The process sends each level it proves as it goes, so
    stopping it, at the deadline or when the plan meets the bound, loses nothing proved."""

    def __init__(
        self,
        problem: Problem,
        s: _Search,
        start: Node,
        floor: int,
        upper: int,
        deadline: float,
        *,
        clock: Clock = WALL,
    ) -> None:

        heur = s.heuristic
        tgts = schedule.targets(problem, heur.graph, start, heur.required_atoms(start[2]))
        self.bound = floor
        self.deadline = deadline
        self.clock = clock  # (the process takes a copy as it stands: ``clock.WorkClock``)

        ctx = multiprocessing.get_context("fork")
        self.conn, send = ctx.Pipe(duplex=False)
        walks, squeezes = _Slot(ctx), _Slot(ctx)
        # (the walk's plans out, the process's in, taken only at the end; the process's
        # exchange the other way round, taken as they come)
        self.exchange = _Exchange(problem, walks, squeezes, listen=False)
        self.proc = ctx.Process(
            target=_profile_child,
            args=(send, problem, s, start, tgts, floor, upper, deadline),
            kwargs={"exchange": _Exchange(problem, squeezes, walks), "clock": clock},
            daemon=True,
        )
        self.proc.start()
        send.close()  # (the child's copy stays open: its end is the end of the pipe)

    def finish(self, *, wanted: bool) -> int:
        """The bound it proved (ticks, never below its floor). When ``wanted`` it is waited
        for until it ends or until its deadline and ``BESIDE_GRACE`` have passed; when not
        (the plan meets the bound already) it is stopped at once."""
        if wanted:
            self._read(self.deadline + BESIDE_GRACE)
        self.close()
        return self.bound

    def close(self) -> None:
        """Stop the process (if it still runs) and keep what it sent."""
        if self.proc.is_alive():
            self.proc.terminate()
        self.proc.join()
        self._read(-math.inf)
        self.conn.close()

    def _read(self, until: float) -> None:
        # the levels proved, until the process ends (the pipe's end) or ``until`` (on the
        # run's clock; a wait keeps wall time)
        while not self.conn.closed and self.conn.poll(
            max(0.0, self.clock.wall(until) - time.perf_counter())
        ):
            try:
                self.bound = max(self.bound, self.conn.recv())
            except EOFError:
                return


def _profile_child(
    send: Connection,
    problem: Problem,
    s: _Search,
    start: Node,
    tgts: list[schedule.Target],
    floor: int,
    upper: int,
    deadline: float,
    *,
    exchange: _Exchange | None = None,
    clock: Clock = WALL,
) -> None:
    """The profile bound's process (``_ProfileBeside``): every level it proves is sent; once
    the bound is final (the relaxation solved at it), it squeezes the walk's plans handed
    over by ``exchange`` until ``deadline`` on ``clock`` (``_plans_beside``)."""

    try:
        if lns.available():
            got = profile.profile_bound(
                problem,
                s.heuristic.graph,
                start,
                tgts,
                floor=floor,
                upper=upper,
                deadline=clock.wall(deadline),
                on_proven=send.send,
                lp=True,
                mip=True,
            )
            if got.solved and exchange is not None:
                _plans_beside(s, start, exchange, got.ticks, deadline, clock=clock)
    finally:
        send.close()


def _plans_beside(
    s: _Search,
    start: Node,
    exchange: _Exchange,
    bound: int,
    deadline: float,
    *,
    clock: Clock = WALL,
) -> None:
    """The bound's process, its bound final: the walk's best plan (``exchange.news``; waited
    for) squeezed by conflict repair with its own seed (``BESIDE_SEED``) until ``deadline``
    on ``clock``, each shorter plan handed back; again from the walk's next plan when it is
    shorter than any found here. Stops at a plan that meets ``bound``."""

    gls = goals(s, start)
    if not gls:
        return
    router = _Router(s, start, gls)
    while clock.now() < deadline:
        theirs = exchange.news()
        if theirs is None:
            time.sleep(0.02)
            continue
        found = _squeeze_paths(
            router,
            repair.ranked(theirs),
            deadline,
            bound,
            seed=BESIDE_SEED,
            exchange=exchange,
            clock=clock,
        )
        if found is not None and found[0] <= bound:
            return


class _Slot:
    """The last plan one process hands the other (``_Exchange``), in shared memory, so that
    the writer never waits for the reader: a version (0: none yet), its cost (ticks), and per
    goal its path, as (goal, step, instance index) triples."""

    def __init__(self, ctx: Any) -> None:
        # (a ``multiprocessing`` context; the array has a lock of its own)
        self.arr: Any = ctx.Array("q", 3 + 3 * SLOT_INSTANCES)

    def put(self, cost: int, paths: dict[int, repair.Path]) -> None:
        """Hand over a plan (not when it has more than ``SLOT_INSTANCES`` instances)."""
        flat = [v for gi, path in paths.items() for t, inst in path for v in (gi, t, inst.index)]
        if len(flat) > 3 * SLOT_INSTANCES:
            return
        with self.arr.get_lock():
            self.arr[1] = cost
            self.arr[2] = len(flat) // 3
            self.arr[3 : 3 + len(flat)] = flat
            self.arr[0] += 1

    def head(self) -> tuple[int, int]:
        """(version, cost) of the plan handed over last."""
        with self.arr.get_lock():
            return self.arr[0], self.arr[1]

    def get(self, problem: Problem) -> tuple[int, int, dict[int, repair.Path]]:
        """(version, cost, paths) of the plan handed over last (version 0: none)."""
        with self.arr.get_lock():
            version, cost, n = self.arr[0], self.arr[1], self.arr[2]
            flat = self.arr[3 : 3 + 3 * n]
        paths: dict[int, repair.Path] = {}
        for k in range(0, len(flat), 3):
            paths.setdefault(flat[k], []).append((flat[k + 1], problem.instances[flat[k + 2]]))
        return version, cost, paths


class _Exchange:
    """Plans handed between the walk's process and the bound's (``_ProfileBeside``): each
    offers its shorter plans into one ``_Slot`` and takes the other's from another when they
    are shorter than any it has. Whoever takes a plan replays it through the monitors before
    it counts. ``listen``: the squeeze (``_squeeze_paths``) takes the other side's plans as
    they come; the walk's side does not (it takes the last one at the end): squeezing the
    bound process's plans instead of its own made grid 32 x 32 seed 0 end at 9.4 s in three
    10 s runs of five, where the walk alone ends at 8.8 s (docs/planner.md, "Session 21")."""

    def __init__(self, problem: Problem, out: _Slot, into: _Slot, *, listen: bool = True) -> None:
        self.problem = problem
        self.out = out
        self.into = into
        self.listen = listen
        self.best = math.inf  # the shortest plan (ticks) this side has offered or taken

    def offer(self, cost: int, paths: dict[int, repair.Path]) -> None:
        """A plan this side found, handed over when shorter than any it had."""
        if cost < self.best:
            self.best = cost
            self.out.put(cost, paths)

    def news(self) -> dict[int, repair.Path] | None:
        """The other side's last plan when it is shorter than any this side has (taken:
        this side has it from now on); None otherwise."""
        version, cost = self.into.head()
        if version == 0 or cost >= self.best:
            return None
        _, cost, paths = self.into.get(self.problem)
        self.best = min(self.best, cost)
        return paths


def _paths_of(routes: dict[int, _Route]) -> dict[int, repair.Path]:
    """Per goal its route's path, with the steps no route acts in taken out."""

    return repair.ranked({gi: rt[0] for gi, rt in routes.items()})


def _steps_of(paths: dict[int, repair.Path]) -> list[list[Instance]]:
    """The steps of a plan given as per-goal paths (steps counted from 0, none empty)."""
    acts = sorted((t, inst.index, inst) for path in paths.values() for t, inst in path)
    out: list[list[Instance]] = []
    last = -1
    for t, _, inst in acts:
        if t != last:
            out.append([])
            last = t
        out[-1].append(inst)
    return out


def _schedule_at_start(
    problem: Problem, s: _Search, start: Node, floor: int, upper: int, until: float
) -> int:
    """The relaxed-schedule bound at the start node (``schedule.schedule_bound``) when it
    applies (fixed durations, CP-SAT installed, at most ``SCHEDULE_UP_TO`` event goals);
    ``floor`` otherwise or when it proves nothing more before ``until``."""

    if not schedule.applicable(problem):
        return floor
    heur = s.heuristic
    tgts = schedule.targets(problem, heur.graph, start, heur.required_atoms(start[2]))
    if not tgts or len(tgts) > SCHEDULE_UP_TO or not lns.available():
        return floor
    res = schedule.schedule_bound(
        problem, heur.graph, start, tgts, floor=floor, upper=upper, deadline=until
    )
    return res.ticks


def step_bound(
    problem: Problem,
    s: _Search,
    start: Node,
    floor: int,
    upper: int | None,
    until: float,
    before_full: Callable[[], None] | None = None,
    roof: int | None = None,
) -> tuple[int, _Found | None]:
    """The step bound at ``start`` (``schedule.schedule_bound`` with ``steps``) when it applies
    (fixed positive durations, CP-SAT installed, at most ``SCHEDULE_UP_TO`` event goals, a
    ``floor`` of at most ``STEPS_UP_TO`` shortest steps), and a plan of exactly that makespan
    when the relaxation's schedule at the bound is one (or the schedule with sessions whole
    is): then that plan is optimal. With ``upper`` (a plan's makespan) the levels gallop and
    bisect, without it they are shaved one by one (``schedule.schedule_bound``, which calls
    ``before_full`` before it asks the full model, and asks first just below ``roof``, a
    known plan's makespan). (``floor``, None) when the bound does not apply; it is never below
    ``floor``."""

    if not schedule.steps_applicable(problem):
        return floor, None
    heur = s.heuristic
    graph = heur.graph
    tgts = schedule.targets(problem, graph, start, heur.required_atoms(start[2]))
    if floor > STEPS_UP_TO * min(i.lower for i in problem.instances):
        return floor, None
    if not tgts or len(tgts) > SCHEDULE_UP_TO:
        return floor, None
    # last: importing CP-SAT takes 0.5-1.5 s, which a cell the bound does not apply to (32
    # goals: a 32-robot line never needs CP-SAT) would take from its plans
    if not lns.available():
        return floor, None

    def is_plan(steps: tuple[tuple[Instance, ...], ...]) -> bool:
        # a relaxed schedule at level L that replays is a plan of makespan at most L: the
        # cheaper model's bound L is then proved optimal, and the full model need not be asked
        return replay(s, start, steps) is not None

    res = schedule.schedule_bound(
        problem,
        graph,
        start,
        tgts,
        floor=floor,
        upper=upper,
        deadline=until,
        steps=True,
        accept=is_plan,
        before_full=before_full,
        roof=roof,
    )
    if res.steps is None:
        return res.ticks, None
    # (where it is no plan, the level was asked with every session whole already)
    found = replay(s, start, res.steps)
    if found is None or found[0] > res.ticks:
        return res.ticks, None
    return found[0], found


def _pairs_at_start(
    problem: Problem,
    s: _Search,
    start: Node,
    until: float,
    floor: float = 0.0,
    *,
    first_until: float | None = None,
    clock: Clock = WALL,
) -> float:
    """The best pairwise bound at the start node from the pairs solved before ``until``, the
    pairs of the longest routes first (any subset of pairs gives a valid bound). When the first
    ``PAIRS_TRIAL`` pairs do not beat ``floor`` (the bound already known), the rest are skipped
    and their time goes to the plans: on grid and random cells, where two routes seldom meet,
    no pair beats the start bound (on lines, where every route crosses the middle, the first
    ones do). The first pair is tried until ``first_until`` (default ``until``) even when
    ``until`` has passed: on 32-robot lines a 1 s budget's first plan came at 0.51-0.62 s in
    some runs, after the pairs' 0.45 s, and no pair at all left the gap at 26-61 % where one
    pair (about 0.1 s) gives 0.3-5 % (docs/planner.md, "Session 17"). The times are on
    ``clock``."""
    heur = s.heuristic
    graph = heur.graph
    locs = start[0]
    atoms_ = sorted(heur.required_atoms(start[2]))
    crit = {a: graph.atom_time(a, locs) for a in atoms_}
    pairs = [(a, b) for i, a in enumerate(atoms_) for b in atoms_[i + 1 :]]
    pairs.sort(key=lambda ab: (-min(crit[ab[0]], crit[ab[1]]), -max(crit[ab[0]], crit[ab[1]])))
    bound = PairBound(problem, graph)
    best = 0.0
    for k, (a, b) in enumerate(pairs):
        if clock.now() > (until if k or first_until is None else first_until) or (
            k >= PAIRS_TRIAL and best <= floor
        ):
            break
        for lk in bound.lookups([a, b]):
            best = max(best, pair_value(lk, locs))
    return best


def _more(
    problem: Problem,
    s: _Search,
    until: float,
    *,
    enough: float = -math.inf,
    rounds: int | None = None,
    squeeze: bool = False,
    exchange: _Exchange | None = None,
    clock: Clock = WALL,
) -> _Found | None:
    """More plans until ``until`` (on ``clock``): a walk over priority orders, each new order
    followed by large-neighbourhood moves from the best plan (see ``_OrderWalk``,
    ``_Neighbourhood``); when there are at least ``CP_MIN_SECONDS``, at most ``CP_UP_TO`` goals
    and CP-SAT is installed, the walk stops after ``CP_WALK_SHARE`` of the time and CP-SAT
    re-plans every goal jointly from the best plan (``_jointly``), then the walk goes on if time
    is left. The best plan found; the walk stops early once it is no longer than ``enough`` (a
    lower bound: it is optimal). With ``rounds``: at most that many rounds (an order and its
    moves) and no joint re-plan, so the plan does not depend on the machine's speed (``until``
    only as a safety net). With ``squeeze``, on cells of more than ``CP_UP_TO`` goals the walk
    stops after ``REPAIR_WALK_SHARE`` of the time and conflict repair squeezes its best plan
    into fewer steps until ``until`` (``_squeezed``). With ``exchange``, each shorter plan is
    offered to the bound's process."""

    node = problem.start()
    gls = goals(s, node)
    if not gls:
        return None
    walk = _OrderWalk(s, node, gls)
    lns: _Neighbourhood | None = None
    best = walk.best
    best_routes = walk.best_routes
    joint = (
        rounds is None
        and 3 <= len(gls) <= CP_UP_TO
        and until - clock.now() >= CP_MIN_SECONDS
        and _joint_possible(problem, gls)
    )
    # (after CP-SAT's import in ``_joint_possible``, 0.5-1.5 s: the walk's share is measured
    # from here, or a 16-goal line, where the joint re-plan finds nothing, would get no walk)
    squeeze = (
        squeeze
        and rounds is None
        and not joint
        and len(gls) > CP_UP_TO
        and repair.applicable(problem, [g.atom.name for g in gls], [g.after for g in gls])
    )
    now = clock.now()
    if joint:
        walk_until = now + CP_WALK_SHARE * (until - now)
    elif squeeze:
        walk_until = now + REPAIR_WALK_SHARE * (until - now)
    else:
        walk_until = until

    def better(found: _Found | None, routes: dict[int, _Route] | None = None) -> None:
        nonlocal best, best_routes
        if found is not None and (best is None or found[0] < best[0]):
            best = found
            if routes is not None:
                best_routes = routes
                if exchange is not None:
                    exchange.offer(found[0], _paths_of(routes))

    if best is not None and exchange is not None:
        exchange.offer(best[0], _paths_of(best_routes))

    took = 0.0  # how long the last round (an order and its moves) took
    while True:
        if best is not None and best[0] <= enough:
            break
        if rounds is not None:
            if rounds <= 0:
                break
            rounds -= 1
        now = clock.now()
        # a round is not cut short: none starts that would end past ``walk_until`` if it took
        # as long as the last one (32-goal rounds take 0.05-0.3 s of CPU, more under load)
        if now + took >= walk_until:
            if squeeze and best is not None:
                squeeze = False
                better(
                    _squeezed(
                        walk.router, best_routes, until, enough, exchange=exchange, clock=clock
                    )
                )
                walk_until = until
                continue
            if not joint or best is None:
                break
            joint = False
            better(_jointly(problem, s, walk.router, best, clock.wall(until)))
            walk_until = until
            continue
        walk.step()
        better(walk.best, walk.best_routes)
        if walk.best is not None and len(gls) >= 3:
            if lns is None or walk.best[0] < lns.cost:
                lns = _Neighbourhood(walk.router, walk.best, walk.best_routes)
            for _ in range(LNS_STEPS):
                lns.step()
            # (the neighbourhood's current routes: a plan as long as its best)
            better(lns.best, lns.routes)
        took = clock.now() - now
    return best


def _squeezed(
    router: _Router,
    routes: dict[int, _Route],
    until: float,
    enough: float = -math.inf,
    *,
    exchange: _Exchange | None = None,
    moves: int | None = None,
    clock: Clock = WALL,
) -> _Found | None:
    """The plan of ``routes`` in fewer steps, by conflict repair (``repair.Repair``) until
    ``until`` (on ``clock``): squeezed into one step fewer, repaired, and again from each
    plan found, every one replayed through the monitors. The shortest plan found (None:
    none); stops once it is no longer than ``enough`` (a lower bound: it is optimal).
    ``exchange`` and ``moves``: see ``_squeeze_paths``."""
    return _squeeze_paths(
        router, _paths_of(routes), until, enough, exchange=exchange, moves=moves, clock=clock
    )


def _squeeze_paths(
    router: _Router,
    paths: dict[int, repair.Path],
    until: float,
    enough: float = -math.inf,
    *,
    seed: int = 5,
    exchange: _Exchange | None = None,
    moves: int | None = None,
    clock: Clock = WALL,
) -> _Found | None:
    """``_squeezed`` from per-goal paths (steps counted from 0, none empty), its repair with
    ``seed``. With ``exchange`` each shorter plan is offered to the other process, and (when
    it listens) every ``NEWS_EVERY`` moves a shorter plan from it is taken when it has fewer
    steps than the plan being squeezed: replayed through the monitors, then squeezed instead.
    (One with as many steps, shorter only by its steps' lengths, would restart the search for
    the level this one has been repairing: engineer 11's diagnosis in session 21.) With
    ``moves``: at most that many moves (repair steps, plans replayed and taken), so that the
    plan does not depend on the machine's speed (as ``_more``'s ``rounds``; ``until`` then
    only a safety net, ``math.inf`` for none)."""

    p = router.p
    node = router.node
    gone = 0
    for o, code in enumerate(node[0]):
        r = p.code_holder.get(code)
        if r is not None and o not in router.targets:
            gone |= 1 << r  # holds an object nobody asked for: out of play
    rep = repair.Repair(
        p, node[0], [g.obj for g in router.goals], router.fires, router.alive, gone, seed=seed
    )
    best: _Found | None = None
    if not rep.squeeze(paths, repair.length(paths) - 1):
        return None
    done = 0  # moves made
    while clock.now() < until and (moves is None or done < moves):
        done += 1
        listen = exchange is not None and exchange.listen and not done % NEWS_EVERY
        theirs = exchange.news() if listen and exchange is not None else None
        if theirs is not None and repair.length(theirs) <= rep.T:
            found = router.replay(_steps_of(theirs))
            if found is not None and (best is None or found[0] < best[0]):
                best = found
                if found[0] <= enough:
                    break
                if not rep.squeeze(theirs, repair.length(theirs) - 1):
                    break
            continue
        if rep.clashes:
            rep.step()
            continue
        found = router.replay(rep.steps())
        if found is None:  # (routes without clashes are a plan: not expected)
            break
        if best is None or found[0] < best[0]:
            best = found
        paths = rep.paths()
        if exchange is not None:
            exchange.offer(found[0], paths)
        if found[0] <= enough:
            break
        if not rep.squeeze(paths, repair.length(paths) - 1):
            break
    return best


def _profile_fits(timeout: float) -> bool:
    """Whether the profile bound's share of a ``timeout`` budget is at least
    ``PROFILE_MIN_SECONDS`` long. Compared in milliseconds: ``1.0 - 0.9`` is
    0.09999999999999998, so a plain comparison said no at 10 s, and from session 12 to 14 the
    profile bound never ran in the 10 s benchmark runs (the A* slice had the time)."""
    return round(PROFILE_SHARE * timeout * 1000) >= round(PROFILE_MIN_SECONDS * 1000)


def _joint_possible(problem: Problem, gls: Sequence[Goal]) -> bool:
    """The joint model applies: fixed durations, goals that are events, CP-SAT installed."""

    return (
        problem.cost.fixed
        and not problem.state_atom_objects
        and all(g.atom.name in ("delivered", "placed", "picked") for g in gls)
        and lns.available()
    )


def _jointly(
    problem: Problem,
    s: _Search,
    router: _Router,
    best: _Found,
    until: float,
    *,
    detour: float = CP_DETOUR,
    slack: int = 0,
    floor: int = 0,
    stop: lns.Stop | None = None,
    work: float | None = None,
) -> _Found | None:
    """``best`` re-planned by CP-SAT with every goal free (``lns.replan_jointly``), in at
    most ``slack`` more steps, each object kept to places on routes at most ``detour`` seconds
    slower than its quickest (and to those ``best`` uses); the plan is replayed through the
    monitors before it counts. None: nothing found by ``until`` (``time.perf_counter()``), or
    ``stop`` stopped it. ``floor``: a lower bound on every plan (ticks), where the solve may
    end; ``work``: at most this much of CP-SAT's deterministic time (``lns.replan_jointly``)."""

    node = router.node
    graph = s.heuristic.graph
    steps = [list(U) for _, U, _ in best[1]]
    used: dict[int, set[int]] = {}
    for U in steps:
        for inst in U:
            used.setdefault(inst.obj, set()).update((inst.pre, inst.post))
    specs = []
    for gi, g in enumerate(router.goals):
        o = g.obj
        here = node[0][o]
        fires = frozenset(
            i.index for row in problem.by_obj_pre[o] for i in row if g.atom in i.events
        )
        quickest = graph.event_time[o][here].get(g.atom, math.inf)
        places = {
            loc
            for loc in range(len(problem.locs))
            if router.alive[gi][loc]
            and graph.place_time[o][here][loc] + graph.event_time[o][loc].get(g.atom, math.inf)
            <= quickest + detour * TICKS_PER_SECOND
        }
        places |= {here, *used.get(o, ()), *(problem.instances[i].post for i in fires)}
        specs.append(lns.GoalSpec(o, fires, frozenset(places), g.after))
    new = lns.replan_jointly(
        problem,
        specs,
        node[0],
        steps,
        slack=slack,
        deadline=until,
        floor=floor,
        stop=stop,
        work=work,
    )
    return None if new is None else router.replay(new)


class _Neighbourhood:
    """Large-neighbourhood search over a routed plan: take out the routes of a few goals (the
    one that finishes last and others that share its robots, or random ones) and route them
    again, in a random order, around the routes that stay. A result no longer than the current
    plan becomes the current plan (plateaus are crossed); the best is kept. Unlike a new
    priority order, the routes that stay keep their steps, so a goal routed early in a bad
    order can move into the room the others leave."""

    def __init__(self, router: _Router, best: _Found, routes: dict[int, _Route]) -> None:

        self.router = router
        self.best = best
        self.cost = best[0]
        self.routes = dict(routes)
        self.rng = random.Random(3)
        self.n = len(router.goals)

    def step(self) -> None:
        rng = self.rng
        routes = self.routes
        last = max(routes, key=lambda gi: (routes[gi][2], -gi))
        k = min(self.n - 1, rng.choice((2, 2, 3, 3, 4)))
        if rng.random() < 0.7:
            robots = 0  # the robots of the last goal's route, as a bit mask
            for _, inst in routes[last][0]:
                robots |= inst.executors
            near = [
                gi
                for gi, rt in routes.items()
                if gi != last and any(i.executors & robots for _, i in rt[0])
            ]
            pool = near if len(near) >= k - 1 else [gi for gi in routes if gi != last]
            out = [last, *rng.sample(pool, k - 1)]
        else:
            out = rng.sample(list(routes), k)
        order = list(out)
        rng.shuffle(order)
        fixed = {gi: rt for gi, rt in routes.items() if gi not in out}
        steps = self.router.route_all(order, fixed)
        found = None if steps is None else self.router.replay(steps)
        if found is None or found[0] > self.cost:
            return
        self.cost = found[0]
        self.routes = dict(self.router.routes)
        if found[0] < self.best[0]:
            self.best = found


class _OrderWalk:
    """A local search over priority orders. Most candidates change the current order: the goal
    that finished last moves to an earlier position, or a random goal moves (or two swap); a
    candidate is kept when its plan is no longer, so the walk crosses plateaus. Every fourth
    candidate is a fresh random order, kept only when it is better. On 16- and 32-robot cells
    this finds shorter plans than random restarts alone (docs/planner.md, "Anytime mode")."""

    def __init__(self, s: _Search, node: Node, gls: Sequence[Goal]) -> None:

        self.gls = gls
        self.router = _Router(s, node, gls)
        self.next_order = _orders(s, node, gls, seed=1)
        # the walk starts at the critical-first order
        self.current = self.next_order()
        self.cost: float = math.inf
        self.last: int | None = None  # the goal that finished last in the current plan
        self.rng = random.Random(2)
        self.best: _Found | None = None
        self.tried = 0
        self.best_routes: dict[int, _Route] = {}
        if self.current:
            steps = self.router.route_all(self.current)
            self.best = None if steps is None else self.router.replay(steps)
            if self.best is not None:
                self.cost = self.best[0]
                self.last = self.router.last_goal
                self.best_routes = dict(self.router.routes)

    def step(self) -> None:
        self.tried += 1
        fresh = self.tried % 4 == 0 or not self.current
        order = self.next_order() if fresh else self._perturb()
        if not order:
            return
        steps = self.router.route_all(order)
        found = None if steps is None else self.router.replay(steps)
        if found is None:
            return
        if found[0] < self.cost or (not fresh and found[0] == self.cost):
            self.current, self.cost = order, found[0]
            self.last = self.router.last_goal
        if self.best is None or found[0] < self.best[0]:
            self.best = found
            self.best_routes = dict(self.router.routes)

    def _perturb(self) -> list[int]:
        """The current order changed a little; [] when that breaks an "after" order."""
        out = list(self.current)
        rng = self.rng
        j = rng.randrange(len(out))
        if self.last is not None and rng.random() < 0.5:
            i = out.index(self.last)
            out.insert(min(j, i), out.pop(i))
        elif rng.random() < 0.5:
            out.insert(j, out.pop(rng.randrange(len(out))))
        else:
            i = rng.randrange(len(out))
            out[i], out[j] = out[j], out[i]
        placed: set[int] = set()
        for gi in out:
            if any(a not in placed for a in self.gls[gi].after):
                return []
            placed.add(gi)
        return out


def with_fallback_plan(
    problem: Problem,
    result: PlanResult,
    until: float | None = None,
    known: _Found | None = None,
    *,
    clock: Clock = WALL,
) -> PlanResult:
    """A timed-out exact result with a prioritized plan attached (status unchanged): the first
    one, improved by more orders and neighbourhoods until ``until`` (on ``clock``), or
    ``known`` (a plan found before) where that is shorter."""
    s = _Search(problem)
    found = construct(problem, s)
    if found is None or (known is not None and known[0] < found[0]):
        found = known
    if found is None:
        return result
    if until is not None and clock.now() < until:
        better = _more(problem, s, until, clock=clock)
        if better is not None and better[0] < found[0]:
            found = better
    lb = result.lower_bound
    makespan = to_seconds(found[0])
    return PlanResult(
        result.status,
        plan_steps(problem, found[1]),
        makespan,
        result.stats,
        result.reason + f"; best plan found: {makespan:.3f} s",
        None if lb is None else min(lb, makespan),
    )
