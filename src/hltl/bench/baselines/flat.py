"""Flat LTLf: the whole task as one formula and one automaton, no hierarchy."""

from __future__ import annotations

import multiprocessing as mp
import time
from dataclasses import asdict, dataclass
from typing import Any

from hltl.planner import plan
from hltl.sim.scenarios import generate
from hltl.spec.automata import AutomatonCache, substitute_atoms, to_dfa
from hltl.spec.hierarchy import HSpec, spec_from_formulas
from hltl.spec.monitor import HierarchyMonitor
from hltl.spec.parser import parse_formula
from hltl.spec.syntax import Atom, Eventually, Formula
from hltl.world.scene import Scene


def _event_of_leaf(f: Formula) -> Formula | None:
    """The atom whose occurrence is the leaf's first acceptance, for ``F delivered/placed``."""
    if (
        isinstance(f, Eventually)
        and isinstance(f.operand, Atom)
        and f.operand.name in ("delivered", "placed")
    ):
        return f.operand
    return None


def flatten(spec: HSpec) -> tuple[Formula, bool]:
    """The root formula with every child substituted; and whether that is exact (above)."""
    exact = True

    def sub(f: Formula) -> Formula:
        return substitute_atoms(f, child)

    def child(a: Atom) -> Formula:
        if not a.is_predicate and a.name in spec.children:
            return expand(a.name)
        return a

    def expand(name: str) -> Formula:
        nonlocal exact
        f = spec.formula(name)
        if not spec.children[name]:
            event = _event_of_leaf(f)
            if event is not None:
                return event
            exact = False
            return f
        return sub(f)

    return expand(spec.root), exact


def flat_spec(spec: HSpec) -> HSpec:
    """A one-node spec whose root is the flattened formula (a leaf: atoms only)."""
    f, _ = flatten(spec)
    return spec_from_formulas("p0", {"p0": f})


@dataclass(frozen=True, slots=True)
class SideResult:
    """Automata and planning for one side (hierarchical or flat)."""

    status: str  # "ok", "timeout", or "error: ..."
    nodes: int = 0
    props: int = 0  # most propositions of one automaton
    states: int = 0  # summed over the automata
    edges: int = 0
    compile_s: float | None = None
    plan_s: float | None = None
    plan_status: str = ""
    expanded: int | None = None
    makespan: float | None = None


def measure(scene: Scene, spec: HSpec, plan_timeout: float) -> SideResult:
    """Compile ``spec``'s monitors with a fresh cache (timed) and plan with them."""
    to_dfa(
        parse_formula("F delivered(warm, up)")
    )  # load ltlf2dfa and MONA once, outside the timing
    cache = AutomatonCache(timeout=max(plan_timeout, 1.0))
    t0 = time.perf_counter()
    monitor = HierarchyMonitor(spec, cache=cache)
    compile_s = time.perf_counter() - t0
    dfas = list(monitor.dfas.values())
    t1 = time.perf_counter()
    res = plan(scene, spec, monitor=monitor, timeout=plan_timeout)
    plan_s = time.perf_counter() - t1
    return SideResult(
        status="ok",
        nodes=len(dfas),
        props=max(len(d.props) for d in dfas),
        states=sum(d.n_states for d in dfas),
        edges=sum(d.n_edges for d in dfas),
        compile_s=compile_s,
        plan_s=plan_s,
        plan_status=res.status.value,
        expanded=res.stats.expanded,
        makespan=res.makespan,
    )


def _child(scene: Scene, spec: HSpec, timeout: float, out: Any) -> None:
    try:
        out.send(asdict(measure(scene, spec, timeout)))
    except Exception as exc:  # reported to the parent as this side's status
        out.send({"status": f"error: {type(exc).__name__}: {exc}"[:300]})


def measure_isolated(scene: Scene, spec: HSpec, limit: float) -> SideResult:
    """:func:`measure` in a child process that is killed after ``limit`` seconds."""
    ctx = mp.get_context("spawn")
    recv, send = ctx.Pipe(duplex=False)
    proc = ctx.Process(target=_child, args=(scene, spec, limit, send), daemon=True)
    t0 = time.perf_counter()
    proc.start()
    try:
        if recv.poll(limit + 10.0):  # the child's own import and start-up are not the limit
            data = recv.recv()
        else:
            data = {"status": f"timeout: nothing after {time.perf_counter() - t0:.0f} s"}
    finally:
        if proc.is_alive():
            proc.kill()
        proc.join()
    return SideResult(**data)


@dataclass(frozen=True, slots=True)
class FlatComparison:
    """Hierarchical monitors beside one flat automaton for the same task."""

    tasks: int
    robots: int
    layout: str
    seed: int
    exact: bool
    hier: SideResult
    flat: SideResult

    def to_dict(self) -> dict[str, Any]:
        return asdict(self)


def compare(
    scene: Scene,
    spec: HSpec,
    *,
    limit: float = 60.0,
    tasks: int = 0,
    robots: int = 0,
    layout: str = "",
    seed: int = 0,
) -> FlatComparison:
    """Both sides on one task; the flat side gets ``limit`` seconds to compile and plan."""
    hier = measure(scene, spec, limit)
    _, exact = flatten(spec)
    flat = measure_isolated(scene, flat_spec(spec), limit)
    return FlatComparison(tasks, robots, layout, seed, exact, hier, flat)


def sweep(
    tasks: list[int],
    *,
    robots: int = 4,
    layout: str = "square",
    seed: int = 0,
    limit: float = 60.0,
) -> list[FlatComparison]:
    """Growing task counts on one layout (unordered deliveries, so only the size grows)."""
    out = []
    for n in tasks:
        sc = generate(n, robots, layout, seed, ordered=False)
        out.append(
            compare(
                sc.scene, sc.spec, limit=limit, tasks=n, robots=robots, layout=layout, seed=seed
            )
        )
    return out


def side_from_dict(data: dict[str, Any]) -> SideResult:
    return SideResult(**data)


def comparison_from_dict(data: dict[str, Any]) -> FlatComparison:
    d = dict(data)
    d["hier"] = side_from_dict(d["hier"])
    d["flat"] = side_from_dict(d["flat"])
    return FlatComparison(**d)
