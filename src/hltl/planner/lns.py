"""Anytime improvement by CP-SAT: every goal's route re-planned jointly, step by step."""

from __future__ import annotations

import importlib.util
import sys
import threading
import time
import types
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

from hltl.planner.problem import Instance, Problem

# a plan as the model sees it: per step its instances
Steps = list[list[Instance]]


@dataclass(frozen=True, slots=True)
class GoalSpec:
    """A goal as the model needs it: its object, the instances that make its atom happen, the
    places its object may pass through, and the goals whose atom must not happen later."""

    obj: int
    fires: frozenset[int]  # instance indices
    places: frozenset[int]
    after: tuple[int, ...]


def available() -> bool:
    """CP-SAT (the ``ortools`` package) can be imported (and is, once this says so: without
    pandas where it can be, ``_import_cp_sat``)."""
    try:
        _import_cp_sat()
    except ImportError:  # pragma: no cover - ortools is part of the dev and anytime extras
        return False
    return True


class _NotPandas(types.ModuleType):
    """What CP-SAT's module sees as ``pandas`` while it is imported (``_import_cp_sat``):
    every name it asks for is a class of its own, of which nothing the planner passes to
    CP-SAT is an instance."""

    def __getattr__(self, name: str) -> type:
        if name.startswith("__"):
            raise AttributeError(name)
        made = type(name, (), {})
        setattr(self, name, made)
        return made


def _import_cp_sat() -> None:
    """Import ``ortools.sat.python.cp_model`` without importing pandas. CP-SAT's module
    imports pandas only for its pandas-series helpers (``pd.Index``, ``pd.Series`` in type
    hints and ``isinstance`` checks), which the planner never calls; pandas is about two
    thirds of that import's time (0.5-1.2 s of 0.8-1.8 s under load; docs/planner.md,
    "CP-SAT without pandas"), paid by every cell whose first phase asks CP-SAT. While the
    module is imported, ``sys.modules["pandas"]`` is a ``_NotPandas``, taken out again right
    after, so a later ``import pandas`` anywhere gets the real one (CP-SAT's series helpers
    then do not recognise its objects: nothing here uses them). Where pandas is imported
    already, or the import fails this way (another ortools), CP-SAT is imported as usual."""
    if "ortools.sat.python.cp_model" in sys.modules or "pandas" in sys.modules:
        import ortools.sat.python.cp_model

        return
    sys.modules["pandas"] = _NotPandas("pandas")
    try:
        import ortools.sat.python.cp_model
    except Exception:
        # (a partly imported module would keep the stand-in: import it again, as usual)
        for name in [m for m in sys.modules if m.startswith("ortools.sat.python.cp_model")]:
            del sys.modules[name]
        sys.modules.pop("pandas", None)
        import ortools.sat.python.cp_model  # noqa: F401
    finally:
        if isinstance(sys.modules.get("pandas"), _NotPandas):
            del sys.modules["pandas"]


def installed() -> bool:
    """CP-SAT (the ``ortools`` package) is installed, found without importing it (the import
    takes 0.5-1.5 s of CPU, and much more wall time under load)."""
    return importlib.util.find_spec("ortools") is not None


class Stop:
    """A way to stop, from another thread, the CP-SAT solves of one question
    (``solve_until``'s ``stop``): once ``stop`` is called, a solve not yet started returns
    None and a running one ends soon with an unknown status."""

    def __init__(self) -> None:
        self._lock = threading.Lock()
        self._solver: Any = None
        self.stopped = False

    def attach(self, solver: Any) -> bool:
        """``solver`` is about to solve; False when the question is stopped already."""
        with self._lock:
            self._solver = solver
            return not self.stopped

    def stop(self) -> None:
        """Stop the question. A solve that had not yet begun when this was called may miss it:
        call it again until the question has ended."""
        with self._lock:
            self.stopped = True
            solver = self._solver
        if solver is not None:
            solver.stop_search()


def stop_until(stop: Stop, ended: Callable[[float], bool]) -> None:
    """Stop ``stop``'s question, again and again until ``ended`` (called with how long it may
    wait, in seconds) says it has ended: a solve may begin after a call."""
    stop.stop()
    while not ended(0.01):
        stop.stop()


# told how many questions this process asks CP-SAT at once (``share_busy``)
_busy: Callable[[int], None] | None = None


def share_busy(busy: Callable[[int], None] | None) -> None:
    """From now on, ``schedule``'s climb calls ``busy`` with how many questions it asks
    CP-SAT in a round, at once (0 between its rounds; None: nobody is told). Exact mode's A*
    process (``phase._Apart``) is paused through the rounds that ask one on every core."""
    global _busy
    _busy = busy


def note_busy(n: int) -> None:
    """A round of ``n`` questions at once begins (0: it has ended); told to the
    ``share_busy`` callback, if any."""
    busy = _busy
    if busy is not None:
        busy(n)


def solve_until(
    model: Any,
    deadline: float,
    seed: int,
    stop: Stop | None = None,
    *,
    presolve: bool = True,
    work: float | None = None,
    linearization: int | None = None,
) -> tuple[Any, Any] | None:
    """Solve a CP-SAT ``model`` on one worker with ``seed`` until ``deadline``
    (``time.perf_counter()``); the solver and its status, or None when no time is left (or
    ``stop`` stopped the question before the solve began). ``presolve=False`` skips CP-SAT's
    presolve (the profile bound's questions: docs/planner.md, "Profile bound"); ``work``
    caps CP-SAT's deterministic time (a measure of its work that does not depend on the
    machine's load); ``linearization`` sets CP-SAT's ``linearization_level`` (the step
    model's questions: ``schedule.STEP_LINEARIZATION``)."""
    from ortools.sat.python import cp_model  # why: an optional extra, loaded on first use

    left = deadline - time.perf_counter()
    if left <= 0:
        return None
    solver = cp_model.CpSolver()
    solver.parameters.max_time_in_seconds = left
    solver.parameters.num_workers = 1
    solver.parameters.random_seed = seed
    if not presolve:
        solver.parameters.cp_model_presolve = False
    if work is not None:
        solver.parameters.max_deterministic_time = work
    if linearization is not None:
        solver.parameters.linearization_level = linearization
    if stop is not None and not stop.attach(solver):
        return None
    return solver, solver.solve(model)


def replan_jointly(
    problem: Problem,
    goals: Sequence[GoalSpec],
    start: Sequence[int],
    steps: Steps,
    *,
    slack: int = 0,
    deadline: float,
    seed: int = 0,
    floor: int = 0,
    stop: Stop | None = None,
    work: float | None = None,
) -> Steps | None:
    """A plan for ``goals`` in at most ``len(steps) + slack`` steps, as short as CP-SAT finds
    before ``deadline`` (``time.perf_counter()``; building the model counts), starting from
    ``steps`` (its hint); None when it found none (or ``stop`` stopped it first).

    ``floor`` is a lower bound on every plan's makespan (ticks): the objective is kept at or
    above it, so a plan that meets it ends the solve at once (CP-SAT has its optimum then)
    instead of the search for a proof it cannot find (random 10 x 10 seed 4: 0.7 s instead of
    5.0 s, docs/planner.md "Cells left to A*"). ``work`` caps CP-SAT's deterministic time.

    The model is time-indexed: where each goal's object is before each step (one of its
    ``places``), and which instance it undergoes in each step. Under the step semantics of
    docs/model.md: an instance needs its object where it starts and leaves it where it ends;
    a robot does at most one instance per step and holds at most one object; it must hold
    nothing to pick or receive; an object nothing acts on stays put. Each goal's atom happens
    in exactly one step, no earlier than the atoms of the goals it must follow. Objects no goal
    is about do not move (a robot holding one at the start holds it throughout). A step lasts
    its longest instance, an empty one nothing, and the objective is their sum: the makespan.
    The plan returned is not checked here: replay it through the monitors before using it.
    """
    from ortools.sat.python import cp_model  # why: an optional extra, loaded on first use

    p = problem
    n_robots = len(p.robots)
    T = len(steps) + slack
    goal_objs = {g.obj for g in goals}
    taken = 0  # robots holding an object no goal is about: out of play
    for o, code in enumerate(start):
        r = p.code_holder.get(code)
        if r is not None and o not in goal_objs:
            taken |= 1 << r
    # the hint, complete: each instance's step, each object's place before each step, each
    # step's longest duration
    hint = {(inst.index, t) for t, step in enumerate(steps) for inst in step}
    where = [list(start)]
    for step in steps:
        now = list(where[-1])
        for inst in step:
            now[inst.obj] = inst.post
        where.append(now)
    where += [where[-1]] * slack
    longest = [max((i.lower for i in step), default=0) for step in steps] + [0] * slack

    m = cp_model.CpModel()
    x: dict[tuple[int, int], Any] = {}  # (instance, step) -> it runs in that step
    loc: dict[tuple[int, int, int], Any] = {}  # (goal, step, place) -> the object is there
    by_robot: list[list[list[Any]]] = [[[] for _ in range(n_robots)] for _ in range(T)]
    by_length: list[dict[int, list[Any]]] = [{} for _ in range(T)]
    held: list[list[list[Any]]] = [[[] for _ in range(n_robots)] for _ in range(T + 1)]
    fire_step: list[Any] = []
    chosen: list[list[tuple[int, Instance, Any]]] = []
    for gi, g in enumerate(goals):
        places = sorted(g.places)
        for t in range(T + 1):
            for code in places:
                lit = m.new_bool_var("")
                loc[(gi, t, code)] = lit
                m.add_hint(lit, where[t][g.obj] == code)
                r = p.code_holder.get(code)
                if r is not None:
                    held[t][r].append(lit)
            m.add_exactly_one(loc[(gi, t, code)] for code in places)
        for code in places:
            m.add(loc[(gi, 0, code)] == int(code == start[g.obj]))
        candidates = [
            i
            for row in p.by_obj_pre[g.obj]
            for i in row
            if i.pre in g.places
            and (i.post in g.places or i.index in g.fires)
            and not i.executors & taken
        ]
        fires = []
        mine = []
        for t in range(T):
            acted = []
            for inst in candidates:
                lit = m.new_bool_var("")
                x[(inst.index, t)] = lit
                m.add_hint(lit, (inst.index, t) in hint)
                m.add_implication(lit, loc[(gi, t, inst.pre)])
                m.add_implication(lit, loc[(gi, t + 1, inst.post)])
                for r in range(n_robots):
                    if inst.executors >> r & 1:
                        by_robot[t][r].append(lit)
                by_length[t].setdefault(inst.lower, []).append(lit)
                acted.append(lit)
                mine.append((t, inst, lit))
                if inst.index in g.fires:
                    fires.append((t, lit))
            for code in places:  # nothing done to the object: it stays
                m.add(loc[(gi, t + 1, code)] >= loc[(gi, t, code)] - sum(acted))
        chosen.append(mine)
        m.add_exactly_one(lit for _, lit in fires)
        fire_step.append(sum(t * lit for t, lit in fires))
    # the free-robot preconditions: nothing held by a robot that picks or receives
    for mine in chosen:
        for t, inst, lit in mine:
            for r in inst.free:
                for h in held[t][r]:
                    m.add_implication(lit, ~h)
    for t in range(T + 1):
        for r in range(n_robots):
            if len(held[t][r]) > 1:
                m.add_at_most_one(held[t][r])
            if t < T and len(by_robot[t][r]) > 1:
                m.add_at_most_one(by_robot[t][r])
    for gi, g in enumerate(goals):
        for j in g.after:
            m.add(fire_step[gi] >= fire_step[j])
    # each step lasts its longest instance: one indicator per duration level
    objective = []
    for t in range(T):
        prev = 0
        for d in sorted(by_length[t]):
            y = m.new_bool_var("")
            m.add_hint(y, longest[t] >= d)
            for dd, lits in by_length[t].items():
                if dd >= d:
                    for lit in lits:
                        m.add_implication(lit, y)
            objective.append((d - prev) * y)
            prev = d
    if floor > 0:
        m.add(sum(objective) >= floor)
    m.minimize(sum(objective))

    solved = solve_until(m, deadline, seed, stop, work=work)
    if solved is None:
        return None
    solver, status = solved
    if status not in (cp_model.OPTIMAL, cp_model.FEASIBLE):
        return None
    out: Steps = [[] for _ in range(T)]
    for mine in chosen:
        for t, inst, lit in mine:
            if solver.value(lit):
                out[t].append(inst)
    return [step for step in out if step]
