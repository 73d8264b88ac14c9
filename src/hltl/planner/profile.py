"""A lower bound that sees step synchrony cheaply: routes as flows, steps counted by length."""

from __future__ import annotations

import importlib.util
import itertools
import math
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

from hltl.planner.lns import solve_until
from hltl.planner.problem import Instance, Node, Problem
from hltl.planner.relaxed import RelaxedGraph, _dijkstra
from hltl.planner.schedule import Target, time_unit

_FAR = 1 << 30  # "no route" in instance counts
# CP-SAT's presolve on the profile model's questions: off (docs/planner.md, "Profile bound",
# session 16: the hard "no"s near the bound took 2-7 times less CPU without it)
PRESOLVE = False
# the climb (``profile_bound``): a level above the next one gets FAR_SHARE times what the last "no"
# took, and the levels skipped grow to at most MAX_STRIDE - 1 (session 16: without presolve a
# relaxed solution far up is dear, and a stride of 8 or 16 levels landed there and lost the
# rest of the budget on random 32 x 32 seeds 1 and 3; grid seed 0's level 8.1 s needs the time)
FAR_SHARE = 2.0
MAX_STRIDE = 4
# the LP bound (``lp_bound``) rounds its optimum up to a whole time unit after taking this many
# units off (the solver's tolerances: its optimum may be a little above the exact one)
LP_SLACK = 0.01
# the MIP after the LP (``profile_bound``'s ``mip``) stops this many seconds before the deadline:
# HiGHS may overrun its time limit a little, and the bound's process is stopped soon after it
MIP_MARGIN = 0.25
# ... and first, where the robots that hand over to each other form a bipartite graph
# (``_bipartite``: grids), HiGHS looks for a relaxed solution at the bound for at most
# FITS_SECONDS (``_Linear.fits``), up to FITS_QUESTIONS times: one there makes that bound
# final, and "none" proves one time unit more. 32 x 32 grids 0 and 2: a solution at the LP's
# bound in 1.1 and 3.3 s; grids 3 and 4: "no" in 2.0 and 1.8 s, then grid 3 a solution in
# 1.1 s; the MIP found them only after 6-8 s. Not on random layouts: their handovers close odd
# cycles, which the LP misses and the MIP's cut rounds find (docs/planner.md, "Session 20"),
# so there the MIP raises the bound sooner than questions (each "no" 0.6-3.0 s), and a
# question first cost random seed 2 its last rise (10.5 -> 10.2 s)
FITS_SECONDS = 3.5
FITS_QUESTIONS = 2
_HUGE = 1 << 60  # a row's bound beyond this is none


@dataclass(frozen=True, slots=True)
class ProfileBound:
    """What the relaxation proved: ``ticks`` is a lower bound on the optimal makespan from the
    node (never below the ``floor`` it was given); ``solved`` says the relaxation has a solution
    at ``ticks`` (more time cannot raise it); ``questions`` is how many levels were asked."""

    ticks: int
    solved: bool
    questions: int


def applicable(problem: Problem) -> bool:
    """The proof holds: durations are fixed (a step lasts exactly its longest instance) and
    every instance takes time (a plan ending by M has at most M / shortest non-empty steps)."""
    return problem.cost.fixed and all(i.lower > 0 for i in problem.instances)


def feasible(
    problem: Problem,
    graph: RelaxedGraph,
    node: Node,
    tgts: Sequence[Target],
    level: int,
    deadline: float,
    *,
    seed: int = 0,
    presolve: bool = PRESOLVE,
) -> bool | None:
    """Whether the profile relaxation has a solution ending by ``level`` ticks: False when
    CP-SAT proved it has none (then every plan from ``node`` that makes every target happen is
    longer than ``level``), True when it found one, None when it could not tell before
    ``deadline`` (``time.perf_counter()``; building the model counts).

    The relaxation: each target's object follows a route of instances from where it is to an
    instance that makes its atom happen (a unit flow; places too far for ``level`` left out);
    for each duration level d, c_d is the number of steps lasting at least d, and the makespan
    is sum_j (d_j - d_(j-1)) c_(d_j) <= level; every robot's route instances lasting at least d
    fit into the c_d steps (one instance per robot and step), as do every route's own; and
    before a robot's first route instance and after its last there are as many such steps as
    the objects it handles need at least (counted in instances lasting at least d, guarded by
    "the robot handles one of these objects").
    """
    from ortools.sat.python import cp_model  # why: an optional extra, loaded on first use

    built = _build(problem, graph, node, tgts, level, deadline)
    if not isinstance(built, tuple):
        return built  # (None, or False: a target without a route by ``level``)
    m, _ = built
    solved = solve_until(m, deadline, seed, presolve=presolve)
    if solved is None:
        return None
    _, status = solved
    if status == cp_model.INFEASIBLE:
        return False
    if status in (cp_model.OPTIMAL, cp_model.FEASIBLE):
        return True
    return None


def lp_available() -> bool:
    """The LP bound's solver (scipy's HiGHS) is installed, found without importing it."""
    return importlib.util.find_spec("scipy") is not None


def lp_bound(
    problem: Problem,
    graph: RelaxedGraph,
    node: Node,
    tgts: Sequence[Target],
    level: int,
    deadline: float,
) -> int | None:
    """A lower bound (ticks) on the makespan of every plan from ``node`` that makes every
    target happen and ends by ``level`` (with ``level`` a known plan's makespan: on the
    optimum): the least makespan of the linear relaxation of ``feasible``'s model at ``level``,
    every variable in [0, 1] or its integer range, each implication ``x => y`` as ``x <= y``,
    rounded up to a whole time unit (less ``LP_SLACK`` units for the solver's tolerances).
    One LP (scipy's HiGHS) instead of a climb of CP-SAT questions: on the 32-goal grid and
    random cells it gives what the climb reaches in 10 s, in about 1 s of CPU (docs/planner.md,
    "Session 17"). None: no scipy, not solved before ``deadline`` (``time.perf_counter()``),
    or a model with a constraint of another kind."""
    linear = _linear(problem, graph, node, tgts, level, deadline)
    if linear is None:
        return None
    got = linear.solve(deadline, integral=False)
    return None if got is None else got[0]


@dataclass(frozen=True, slots=True)
class _Linear:
    """``feasible``'s model at a level as scipy's ``milp`` takes it: the makespan (in time
    units) to minimise over the rows, each variable in its domain."""

    cost: Any  # numpy arrays and a sparse matrix (numpy and scipy are optional: loaded late)
    rows: Any
    low: Any
    high: Any
    lo: Any
    hi: Any
    unit: int

    def solve(
        self,
        deadline: float,
        *,
        integral: bool,
        on_bound: Callable[[int], None] | None = None,
    ) -> tuple[int, bool] | None:
        """(a lower bound in ticks on the model's least makespan, whether it is that least
        makespan), solved by HiGHS until ``deadline`` (``time.perf_counter()``). Not
        ``integral``: the LP relaxation's optimum (never said to be the least). ``integral``:
        every variable kept integral (the model itself) and the bound HiGHS proved by the
        deadline (its dual bound: its root LP, then its cuts and branching), the least makespan
        itself when it closed the gap. Rounded up to a whole time unit (the model's makespan is
        one) after ``LP_SLACK`` units are taken off. None: no bound by the deadline.

        With ``on_bound`` (``integral`` only) each rise of that rounded dual bound is told as
        HiGHS proves it, while it still runs (``_mip_told``): its cut rounds raise it over
        seconds on 32-goal cells, and scipy's ``milp`` gives it only when HiGHS stops."""
        import numpy as np  # why: the LP's solver is optional (scipy), loaded on first use
        from scipy.optimize import Bounds, LinearConstraint, milp

        left = deadline - time.perf_counter()
        if left <= 0:
            return None
        if integral and on_bound is not None:
            told = self._mip_told(left, on_bound)
            if told is not None:
                return told[0]
        res = milp(
            self.cost,
            integrality=np.ones(len(self.cost)) if integral else None,
            constraints=LinearConstraint(self.rows, self.low, self.high),
            bounds=Bounds(self.lo, self.hi),
            options={"time_limit": left},
        )
        if not integral:
            if res.status != 0 or res.fun is None:
                return None
            return math.ceil(res.fun - LP_SLACK) * self.unit, False
        dual = getattr(res, "mip_dual_bound", None)
        if dual is None or not math.isfinite(dual):
            return None
        units = math.ceil(dual - LP_SLACK)
        return units * self.unit, res.fun is not None and units >= round(res.fun)

    def fits(self, units: int, deadline: float) -> bool | None:
        """Whether the model (every variable integral) has a solution of makespan at most
        ``units`` time units: True when HiGHS found one, False when it proved there is none
        (then every plan the model covers is longer), None when it could not tell before
        ``deadline`` (``time.perf_counter()``). A question without an objective: HiGHS's
        heuristics look for a solution, and no cut rounds raise a bound first."""
        import numpy as np  # why: the LP's solver is optional (scipy), loaded on first use
        from scipy.optimize import Bounds, LinearConstraint, milp

        left = deadline - time.perf_counter()
        if left <= 0:
            return None
        res = milp(
            np.zeros(len(self.cost)),
            integrality=np.ones(len(self.cost)),
            constraints=[
                LinearConstraint(self.rows, self.low, self.high),
                LinearConstraint(np.asarray(self.cost)[None, :], -np.inf, units),
            ],
            bounds=Bounds(self.lo, self.hi),
            options={"time_limit": left},
        )
        if res.status == 0:
            return True
        if res.status == 2:
            return False
        return None

    def _mip_told(
        self, left: float, on_bound: Callable[[int], None]
    ) -> tuple[tuple[int, bool] | None] | None:
        """``solve``'s MIP (its answer, in a 1-tuple) through HiGHS's own interface in scipy
        (``scipy.optimize._highspy``, private: None when it is not there, and then ``milp``
        is used instead), with a
        callback on HiGHS's MIP interrupt points that tells ``on_bound`` each rise of the
        rounded dual bound. The same model, options and rounding as ``milp``'s, so the same
        answer; only when it is known changes."""
        try:
            import numpy as np  # why: the LP's solver is optional (scipy), loaded on first use
            from scipy.optimize._highspy import _core as highs
            from scipy.sparse import csc_matrix

            interrupt = highs.cb.HighsCallbackType.kCallbackMipInterrupt
            solver = highs._Highs()
            model = highs.HighsLp()
        except (ImportError, AttributeError):
            return None
        cols = csc_matrix(self.rows)
        n_row, n_col = cols.shape
        model.num_col_ = n_col
        model.num_row_ = n_row
        model.a_matrix_.num_col_ = n_col
        model.a_matrix_.num_row_ = n_row
        model.a_matrix_.format_ = highs.MatrixFormat.kColwise
        model.a_matrix_.start_ = cols.indptr
        model.a_matrix_.index_ = cols.indices
        model.a_matrix_.value_ = cols.data.astype(np.float64)
        model.col_cost_ = np.asarray(self.cost, dtype=np.float64)
        model.col_lower_ = np.asarray(self.lo, dtype=np.float64)
        model.col_upper_ = np.asarray(self.hi, dtype=np.float64)
        model.row_lower_ = np.asarray(self.low, dtype=np.float64)
        model.row_upper_ = np.asarray(self.high, dtype=np.float64)
        model.integrality_ = [highs.HighsVarType.kInteger] * n_col
        solver.setOptionValue("output_flag", False)
        solver.setOptionValue("time_limit", left)
        solver.passModel(model)
        best = [-_HUGE]  # the last units told

        def rose(_kind: Any, _message: Any, out: Any, _into: Any, _user: Any) -> None:
            dual = out.mip_dual_bound
            if math.isfinite(dual) and (units := math.ceil(dual - LP_SLACK)) > best[0]:
                best[0] = units
                on_bound(units * self.unit)

        solver.setCallback(rose, None)
        solver.startCallback(interrupt)
        solver.run()
        info = solver.getInfo()
        dual = info.mip_dual_bound
        if not math.isfinite(dual):
            return (None,)
        units = math.ceil(dual - LP_SLACK)
        found = info.primal_solution_status == highs.SolutionStatus.kSolutionStatusFeasible
        return ((units * self.unit, found and units >= round(info.objective_function_value)),)


def _streams() -> bool:
    """HiGHS's own interface in scipy, with the MIP callback ``_Linear._mip_told`` uses, is
    there (it is private to scipy: else ``milp``, which tells the bound only at its end)."""
    try:
        from scipy.optimize._highspy import _core as highs

        return highs.cb.HighsCallbackType.kCallbackMipInterrupt is not None
    except (ImportError, AttributeError):
        return False


def _bipartite(problem: Problem) -> bool:
    """Whether the robots, joined where an instance has two executors (a handover), form a
    bipartite graph (no odd cycle of handovers)."""
    side: dict[int, int] = {}
    near: dict[int, set[int]] = {}
    for inst in problem.instances:
        if inst.executors.bit_count() == 2:
            low = inst.executors & -inst.executors
            a, b = low.bit_length() - 1, (inst.executors ^ low).bit_length() - 1
            near.setdefault(a, set()).add(b)
            near.setdefault(b, set()).add(a)
    for root in near:
        if root in side:
            continue
        side[root] = 0
        todo = [root]
        while todo:
            r = todo.pop()
            for q in near[r]:
                if q not in side:
                    side[q] = 1 - side[r]
                    todo.append(q)
                elif side[q] == side[r]:
                    return False
    return True


def _linear(
    problem: Problem,
    graph: RelaxedGraph,
    node: Node,
    tgts: Sequence[Target],
    level: int,
    deadline: float,
) -> _Linear | None:
    """``feasible``'s model at ``level`` as rows for scipy's ``milp`` (``_Linear``); None: no
    scipy, no time left, a target without a route by ``level``, or a constraint of a kind
    not turned into rows."""
    import numpy as np  # why: the LP's solver is optional (scipy), loaded on first use
    from scipy.sparse import csr_matrix

    built = _build(problem, graph, node, tgts, level, deadline)
    if not isinstance(built, tuple):
        return None
    m, objective = built
    proto = m.Proto()
    n = len(proto.variables)
    # (``list``: the proto's repeated fields do not take negative indices)
    domains = [list(v.domain) for v in proto.variables]
    lo = [dom[0] for dom in domains]
    hi = [dom[-1] for dom in domains]
    cost = np.zeros(n)
    rows: list[int] = []
    cols: list[int] = []
    vals: list[int] = []
    low: list[float] = []
    high: list[float] = []
    for k, ct in enumerate(proto.constraints):
        if list(ct.enforcement_literal) and not ct.has_bool_and():
            return None
        if ct.has_linear():
            if k == objective:
                for v, a in zip(ct.linear.vars, ct.linear.coeffs, strict=True):
                    cost[v] = a
            domain = list(ct.linear.domain)
            if len(domain) != 2:
                return None
            r = len(low)
            for v, a in zip(ct.linear.vars, ct.linear.coeffs, strict=True):
                rows.append(r)
                cols.append(v)
                vals.append(a)
            low.append(domain[0] if domain[0] > -_HUGE else -np.inf)
            high.append(domain[1] if domain[1] < _HUGE else np.inf)
        elif ct.has_bool_and():
            for e in ct.enforcement_literal:
                for lit in ct.bool_and.literals:
                    if e < 0 or lit < 0:
                        return None  # (the model has no negated literals)
                    r = len(low)
                    rows += [r, r]
                    cols += [lit, e]
                    vals += [1, -1]
                    low.append(0.0)
                    high.append(np.inf)
        else:
            return None
    if time.perf_counter() > deadline:
        return None
    matrix = csr_matrix((vals, (rows, cols)), shape=(len(low), n))
    return _Linear(cost, matrix, low, high, lo, hi, time_unit(problem))


def _build(
    problem: Problem,
    graph: RelaxedGraph,
    node: Node,
    tgts: Sequence[Target],
    level: int,
    deadline: float,
) -> tuple[Any, int] | bool | None:
    """``feasible``'s CP-SAT model at ``level`` and the index of its makespan row (the sum
    over duration levels, in time units, at most ``level``); False when some target has no
    route by ``level``; None when ``deadline`` passed while it was being built."""
    from ortools.sat.python import cp_model  # why: an optional extra, loaded on first use

    durations = sorted({i.lower for i in problem.instances})
    unit = time_unit(problem)
    most_steps = level // durations[0]
    locs = node[0]
    m = cp_model.CpModel()
    count = {d: m.new_int_var(0, most_steps, "") for d in durations}
    for shorter, longer in itertools.pairwise(durations):
        m.add(count[longer] <= count[shorter])
    prev = 0
    makespan = []
    for d in durations:
        makespan.append(((d - prev) // unit) * count[d])
        prev = d
    objective = len(m.Proto().constraints)  # (the makespan's row: the LP's objective)
    m.add(sum(makespan) <= level // unit)
    # per robot: its candidate route instances, by object
    by_robot: list[dict[int, list[tuple[Instance, Any]]]] = [{} for _ in problem.robots]
    fires_of: dict[int, frozenset[int]] = {}
    for t in tgts:
        if time.perf_counter() > deadline:
            return None  # (building a 32-goal model takes 0.3-0.5 s of CPU)
        o = t.obj
        here = locs[o]
        reach = graph.place_time[o][here]
        togo = graph.event_time[o]
        fires_of[o] = t.fires
        out: dict[int, list[Any]] = {}
        into: dict[int, list[Any]] = {}
        fired: list[Any] = []
        mine: list[tuple[Instance, Any]] = []
        for inst in (i for row in problem.by_obj_pre[o] for i in row):
            fires = inst.index in t.fires
            rest = 0.0 if fires else togo[inst.post].get(t.atom, math.inf)
            # a loop-erased route never comes back to where it starts, and a plan ending by
            # ``level`` uses no instance it cannot reach, do and finish after by then
            if (not fires and inst.post == here) or reach[inst.pre] + inst.lower + rest > level:
                continue
            x = m.new_bool_var("")
            out.setdefault(inst.pre, []).append(x)
            if fires:
                fired.append(x)
            else:
                into.setdefault(inst.post, []).append(x)
            mine.append((inst, x))
            for r in range(len(problem.robots)):
                if inst.executors >> r & 1:
                    by_robot[r].setdefault(o, []).append((inst, x))
        if not fired:
            return False
        for place in set(out) | set(into):
            supply = 1 if place == here else 0
            m.add(sum(out.get(place, [])) - sum(into.get(place, [])) == supply)
        m.add(sum(fired) == 1)
        for d in durations:
            rows = [x for inst, x in mine if inst.lower >= d]
            if rows:
                m.add(sum(rows) <= count[d])
    counts = {
        (t.obj, d): _counts(problem, locs[t.obj], t.obj, t.fires, d)
        for t in tgts
        for d in durations
    }
    for jobs in by_robot:
        if time.perf_counter() > deadline:
            return None
        handles: dict[tuple[int, ...], Any] = {}  # shared by the duration levels
        for d in durations:
            _robot_rows(m, jobs, d, counts, fires_of, count[d], handles)
    return m, objective


def _robot_rows(
    m: Any,
    jobs: dict[int, list[tuple[Instance, Any]]],
    d: int,
    counts: dict[tuple[int, int], tuple[list[int], list[int]]],
    fires_of: dict[int, frozenset[int]],
    steps: Any,
    handles: dict[tuple[int, ...], Any],
) -> None:
    """One robot's rows at duration level ``d``: for a set J of the objects it may handle, its
    route instances on J lasting at least d, plus (when it handles one of J at all) the fewest
    such instances any object of J needs before the robot can act on it and after, fit into the
    ``steps`` lasting at least d. J: all its objects, and those whose head (tail) is at least
    each value, as the one-machine bound takes them.

    "It handles one of J" is an indicator per set (kept in ``handles``, shared by the duration
    levels), implied by one indicator per object ("it handles o", ``handles[(o,)]``), each
    implied by the robot's route instances on o. The same solutions as one implication per set
    and instance (session 16's model: 48k implications on a 32-goal cell where this has about
    6k; its model is built in about half the CPU, and solved in less), so the same answers."""
    if not jobs:
        return
    head: dict[int, int] = {}
    tail: dict[int, int] = {}
    for o, lst in jobs.items():
        before, after = counts[(o, d)]
        head[o] = min(before[inst.pre] for inst, _ in lst)
        tail[o] = min(0 if inst.index in fires_of[o] else after[inst.post] for inst, _ in lst)
    objs = sorted(jobs)
    subsets = [objs]
    subsets += [[o for o in objs if head[o] >= h] for h in sorted(set(head.values()))]
    subsets += [[o for o in objs if tail[o] >= h] for h in sorted(set(tail.values()))]
    seen: set[tuple[int, ...]] = set()
    for subset in subsets:
        key = tuple(subset)
        if not subset or key in seen:
            continue
        seen.add(key)
        xs = [x for o in subset for inst, x in jobs[o] if inst.lower >= d]
        extra = min(head[o] for o in subset) + min(tail[o] for o in subset)
        if extra >= _FAR:
            continue  # (cannot happen for candidate instances; kept safe)
        if extra == 0:
            if xs:
                m.add(sum(xs) <= steps)
            continue
        some = handles.get(key)
        if some is None:
            some = m.new_bool_var("")
            for o in subset:
                one = handles.get((o,))
                if one is None:
                    one = handles[(o,)] = m.new_bool_var("")
                    for _, x in jobs[o]:
                        m.add_implication(x, one)
                if one is not some:
                    m.add_implication(one, some)
            handles.setdefault(key, some)
        m.add(sum(xs) + extra * some <= steps)


def _counts(
    problem: Problem, here: int, o: int, fires: frozenset[int], d: int
) -> tuple[list[int], list[int]]:
    """For object ``o`` at ``here``: per place, the fewest instances lasting at least ``d`` on
    any route from ``here`` to it, and on any route from it to an instance of ``fires``
    (that instance included); ``_FAR`` where there is none."""
    n = len(problem.locs)
    forward: list[list[tuple[int, float]]] = [[] for _ in range(n)]
    back: list[list[tuple[int, float]]] = [[] for _ in range(n + 1)]  # n: "the atom happened"
    for v in range(n):
        for inst in problem.by_obj_pre[o][v]:
            w = float(inst.lower >= d)
            forward[v].append((inst.post, w))
            back[n if inst.index in fires else inst.post].append((v, w))
    before = _dijkstra(forward, here)
    after = _dijkstra(back, n)[:n]
    return _whole(before), _whole(after)


def _whole(dist: list[float]) -> list[int]:
    return [_FAR if math.isinf(k) else int(k) for k in dist]


def profile_bound(
    problem: Problem,
    graph: RelaxedGraph,
    node: Node,
    tgts: Sequence[Target],
    *,
    floor: int,
    upper: int | None,
    deadline: float,
    seed: int = 0,
    on_proven: Callable[[int], None] | None = None,
    lp: bool = False,
    mip: bool = False,
) -> ProfileBound:
    """A lower bound (ticks) on the makespan of every plan from ``node`` that makes every
    target happen (docs/planner.md, "Profile bound"); ``floor`` is a bound known already,
    ``upper`` a known plan's makespan (None: none). Levels are asked from ``floor`` up in
    doubling strides of at most ``MAX_STRIDE`` levels while CP-SAT proves "no" (each "no"
    proves every level below it); a level above the next one gets ``FAR_SHARE`` times what the
    last "no" took (at least 0.5 s), and where it has a relaxed
    solution or no answer the climb goes on one time unit at a time below it. The next level's
    solution ends the climb, as do ``upper`` and ``deadline`` (``time.perf_counter()``; the
    next level gets all the time left). ``on_proven`` is told each bound (ticks) as it is
    proved. Never below ``floor``. With ``lp`` (and ``upper`` and scipy), the climb starts
    from the LP bound at ``upper`` (``lp_bound``: every plan no longer than ``upper``, the
    optimum among them, is at least that long). With ``mip`` too, where handovers close no odd
    cycle (``_bipartite``), HiGHS is asked for a solution of the model (every variable
    integral) at that bound, for at most ``FITS_SECONDS`` (``_Linear.fits``): one ends the run
    there, the bound final (``solved``); "none" proves a time unit more, and the next unit is
    asked (at most ``FITS_QUESTIONS`` questions). Then (no solution found) the model is given
    to HiGHS to minimise until ``MIP_MARGIN`` before ``deadline``, each rise of its dual bound
    told to ``on_proven`` as HiGHS proves it (``_Linear.solve``'s ``on_bound``); solved to
    optimality, that ends the run too (``solved``); else the climb goes on from the bound it
    proved."""
    if not tgts:
        return ProfileBound(floor, False, 0)
    unit = time_unit(problem)
    proven = -(-floor // unit)  # the least level (units) not ruled out
    if lp and upper is not None and lp_available():

        def told(ticks: int) -> None:  # (the MIP's dual bound, as HiGHS raises it, too)
            nonlocal proven
            if ticks // unit > proven:
                proven = ticks // unit
                if on_proven is not None:
                    on_proven(max(floor, proven * unit))

        linear = _linear(problem, graph, node, tgts, upper, deadline)
        asks = FITS_QUESTIONS if mip and _bipartite(problem) else 0
        # (the MIP's first dual bound is the LP's, or above it: where the MIP comes next and
        # tells its bound as it rises, the LP alone is not solved first)
        lp_first = not mip or asks > 0 or not _streams()
        got = None if linear is None or not lp_first else linear.solve(deadline, integral=False)
        if got is not None:
            told(got[0])
        if mip and linear is not None:
            until = deadline - MIP_MARGIN
            fits: bool | None = False
            for _ in range(asks):
                fits = linear.fits(proven, min(until, time.perf_counter() + FITS_SECONDS))
                if fits is not False:
                    break
                told((proven + 1) * unit)
            got = None if fits else linear.solve(until, integral=True, on_bound=told)
            if got is not None:
                told(got[0])
            if fits or (got is not None and got[1]):
                # (a relaxed solution at the bound: no level above it can be ruled out)
                return ProfileBound(max(floor, proven * unit), True, 0)
    # the least level known (or feared) to have a relaxed solution: a plan's makespan has one
    cap = math.inf if upper is None else upper // unit
    cap_solved = upper is not None
    stride = 1
    questions = 0
    last = 0.0  # seconds the last "no" took
    while proven < cap and (now := time.perf_counter()) < deadline:
        ask = int(min(proven + stride - 1, cap - 1))
        # a level far up may be much harder than the ones below it: it gets a few times what the
        # last "no" took, the next level up all the time left
        until = deadline if ask == proven else min(deadline, now + max(FAR_SHARE * last, 0.5))
        questions += 1
        answer = feasible(problem, graph, node, tgts, ask * unit, until, seed=seed)
        if answer is False:
            proven = ask + 1
            if on_proven is not None:
                on_proven(max(floor, proven * unit))
            stride = min(2 * stride, MAX_STRIDE)
            last = time.perf_counter() - now
        elif answer is None and ask > proven:
            stride = 1  # no answer far up: climb one level at a time again
        else:  # a solution there (or no answer at the next level): nothing below it is known
            cap = ask
            cap_solved = answer is True
            stride = 1
    return ProfileBound(max(floor, proven * unit), proven == cap and cap_solved, questions)
