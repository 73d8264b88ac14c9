"""Fast Downward on the same instances, compiled to classical planning with unified-planning."""

from __future__ import annotations

import importlib
import importlib.util
import os
import tempfile
import time
from dataclasses import asdict, dataclass
from typing import Any

from hltl.bench.baselines.flat import flatten
from hltl.errors import BackendUnavailableError, HltlError
from hltl.spec.hierarchy import HSpec
from hltl.spec.syntax import And, Atom, Eventually, Formula, Or
from hltl.world.geometry import can_meet, context_label, human_in_workspace, reaches
from hltl.world.scene import Scene
from hltl.world.state import WorldState, initial_world

INSTALL_HINT = "pip install 'hltl[baselines]'"
NONE_ITEM = "none_"


class NotEncodable(HltlError):
    """The spec has temporal structure the classical encoding does not express."""


def fd_unavailable() -> str | None:
    """Why Fast Downward cannot run here, or None."""
    if any(importlib.util.find_spec(m) is None for m in ("unified_planning", "up_fast_downward")):
        return f"unified-planning and up-fast-downward are not installed: {INSTALL_HINT}"
    return None


def _is_state(f: Formula) -> bool:
    """No temporal operator: true or false at a single step."""
    if isinstance(f, Atom):
        return True
    if isinstance(f, And | Or):
        return _is_state(f.left) and _is_state(f.right)
    return False


def goal_of(f: Formula) -> tuple[Any, list[tuple[str, str]]]:
    """The goal as nested ``("and"|"or", parts)`` / ``("atom", Atom)`` and the (before, after)
    object orderings.

    Raises:
        NotEncodable: anything but eventualities of delivery/placement events under ``&``,
            ``|`` and non-strict ordering ``F (a & F b)``.
    """
    order: list[tuple[str, str]] = []

    def events(g: Any) -> list[str]:
        if g[0] == "atom":
            return [g[1].args[0]]
        return [o for part in g[1] for o in events(part)]

    def conv(x: Formula, under_f: bool) -> Any:
        if isinstance(x, Atom) and x.name in ("delivered", "placed") and len(x.args) == 2:
            if not under_f:
                raise NotEncodable(f"{x} outside an eventuality")
            return ("atom", x)
        if isinstance(x, Eventually):
            inner = x.operand
            if (
                isinstance(inner, And)
                and isinstance(inner.right, Eventually)
                and _is_state(inner.left)
            ):
                first = conv(inner.left, True)
                then = conv(inner.right, True)
                order.extend((a, b) for a in events(first) for b in events(then))
                return ("and", [first, then])
            return conv(inner, True)
        if isinstance(x, And):
            return ("and", [conv(x.left, under_f), conv(x.right, under_f)])
        if isinstance(x, Or):
            return ("or", [conv(x.left, under_f), conv(x.right, under_f)])
        raise NotEncodable(f"cannot express {x!r} as a classical goal")

    return conv(f, False), order


@dataclass(frozen=True, slots=True)
class FDResult:
    """Fast Downward's answer for one instance."""

    status: str  # "solved", "unsolvable", "timeout", "not_encodable", "error: ..."
    seconds: float | None = None
    cost: float | None = None  # sum of action durations (s)
    length: int | None = None
    plan: tuple[str, ...] = ()

    def to_dict(self) -> dict[str, Any]:
        return asdict(self)


def build_problem(scene: Scene, spec: HSpec, world: WorldState | None = None) -> Any:
    """The unified-planning ``Problem`` of the instance (see the module docstring)."""

    ups = importlib.import_module("unified_planning.shortcuts")
    BoolType, Fluent, InstantaneousAction = ups.BoolType, ups.Fluent, ups.InstantaneousAction
    Int, MinimizeActionCosts, Object = ups.Int, ups.MinimizeActionCosts, ups.Object
    Problem, UserType, UAnd, UOr = ups.Problem, ups.UserType, ups.And, ups.Or

    w = initial_world(scene) if world is None else world
    flat, _ = flatten(spec)
    goal, order = goal_of(flat)
    preds: dict[str, str] = {}
    for a, b in order:
        if b in preds and preds[b] != a:
            raise NotEncodable(f"{b} has two predecessors ({preds[b]}, {a})")
        preds[b] = a

    Robot, Item, Person, Surface = (UserType(n) for n in ("Robot", "Item", "Person", "Surface"))
    free = Fluent("free", BoolType(), r=Robot)
    holding = Fluent("holding", BoolType(), r=Robot, o=Item)
    rest = Fluent("rest", BoolType(), o=Item)
    on = Fluent("on", BoolType(), o=Item, s=Surface)
    delivered = Fluent("delivered", BoolType(), o=Item, u=Person)
    placed = Fluent("placed", BoolType(), o=Item, s=Surface)
    gone = Fluent("gone", BoolType(), o=Item)
    reach = Fluent("reach", BoolType(), r=Robot, o=Item)
    reach_s = Fluent("reach_surface", BoolType(), r=Robot, s=Surface)
    meet = Fluent("meet", BoolType(), g=Robot, r=Robot)
    serves = Fluent("serves", BoolType(), r=Robot, u=Person)
    before = Fluent("before", BoolType(), a=Item, b=Item)
    fluents = (
        free,
        holding,
        rest,
        on,
        delivered,
        placed,
        gone,
        reach,
        reach_s,
        meet,
        serves,
        before,
    )

    pick = InstantaneousAction("pick", r=Robot, o=Item)
    r, o = pick.parameters
    pick.add_precondition(free(r))
    pick.add_precondition(rest(o))
    pick.add_precondition(reach(r, o))
    pick.add_effect(holding(r, o), True)
    pick.add_effect(free(r), False)
    pick.add_effect(rest(o), False)

    pick_s = InstantaneousAction("pick_from", r=Robot, o=Item, s=Surface)
    r, o, s = pick_s.parameters
    pick_s.add_precondition(free(r))
    pick_s.add_precondition(on(o, s))
    pick_s.add_precondition(reach_s(r, s))
    pick_s.add_effect(holding(r, o), True)
    pick_s.add_effect(free(r), False)
    pick_s.add_effect(on(o, s), False)

    place = InstantaneousAction("place", r=Robot, o=Item, s=Surface, p=Item)
    r, o, s, p = place.parameters
    place.add_precondition(holding(r, o))
    place.add_precondition(reach_s(r, s))
    place.add_precondition(before(p, o))
    place.add_precondition(gone(p))
    place.add_effect(holding(r, o), False)
    place.add_effect(free(r), True)
    place.add_effect(on(o, s), True)
    place.add_effect(placed(o, s), True)
    place.add_effect(gone(o), True)

    r2r = InstantaneousAction("handover_r2r", g=Robot, r=Robot, o=Item)
    g, r, o = r2r.parameters
    r2r.add_precondition(holding(g, o))
    r2r.add_precondition(free(r))
    r2r.add_precondition(meet(g, r))
    r2r.add_effect(holding(g, o), False)
    r2r.add_effect(free(g), True)
    r2r.add_effect(holding(r, o), True)
    r2r.add_effect(free(r), False)

    r2h = InstantaneousAction("handover_r2h", r=Robot, o=Item, u=Person, p=Item)
    r, o, u, p = r2h.parameters
    r2h.add_precondition(holding(r, o))
    r2h.add_precondition(serves(r, u))
    r2h.add_precondition(before(p, o))
    r2h.add_precondition(gone(p))
    r2h.add_effect(holding(r, o), False)
    r2h.add_effect(free(r), True)
    r2h.add_effect(delivered(o, u), True)
    r2h.add_effect(gone(o), True)

    problem = Problem("hltl")
    for fl in fluents:
        problem.add_fluent(fl, default_initial_value=False)
    actions = (pick, pick_s, place, r2r, r2h)
    problem.add_actions(actions)
    R = {x.id: Object(x.id, Robot) for x in scene.robots}
    items = {x.id: Object(x.id, Item) for x in scene.objects}
    items[NONE_ITEM] = Object(NONE_ITEM, Item)
    U = {x.id: Object(x.id, Person) for x in scene.humans}
    S = {x.id: Object(x.id, Surface) for x in scene.surfaces}
    for group in (R, items, U, S):
        problem.add_objects(list(group.values()))

    ctx = context_label(scene, w.humans)
    avail = [x for x in scene.robots if x.id not in w.unavailable]
    init = [gone(items[NONE_ITEM])]
    for oid, st in w.objects:
        if st.loc.kind == "rest":
            init.append(rest(items[oid]))
            init += [reach(R[x.id], items[oid]) for x in avail if reaches(x, st.position)]
        elif st.loc.kind == "held":
            init.append(holding(R[st.loc.ref], items[oid]))
        elif st.loc.kind == "on":
            init.append(on(items[oid], S[st.loc.ref]))
        else:
            init += [gone(items[oid]), delivered(items[oid], U[st.loc.ref])]
        init.append(before(items[preds[oid]] if oid in preds else items[NONE_ITEM], items[oid]))
    holders = {st.loc.ref for _, st in w.objects if st.loc.kind == "held"}
    init += [free(R[x.id]) for x in avail if x.id not in holders]
    for x in avail:
        init += [reach_s(R[x.id], S[sf.id]) for sf in scene.surfaces if reaches(x, sf.object_point)]
        init += [
            meet(R[x.id], R[y.id]) for y in avail if can_meet(x, y) and not ctx.blocked(x.id, y.id)
        ]
        for hid, pos in w.humans:
            if human_in_workspace(x, pos, scene.human_reach):
                init.append(serves(R[x.id], U[hid]))
    for fact in init:
        problem.set_initial_value(fact, True)

    def expr(gl: Any) -> Any:
        if gl[0] == "atom":
            a: Atom = gl[1]
            if a.name == "delivered":
                return delivered(items[a.args[0]], U[a.args[1]])
            return placed(items[a.args[0]], S[a.args[1]])
        parts = [expr(x) for x in gl[1]]
        return UAnd(*parts) if gl[0] == "and" else UOr(*parts)

    problem.add_goal(expr(goal))
    d = dict(scene.durations or ())
    costs = {
        pick: d.get("pick", 0.5),
        pick_s: d.get("pick", 0.5),
        place: d.get("place", 0.5),
        r2r: d.get("handover_r2r", 0.6),
        r2h: d.get("handover_r2h", 0.5),
    }
    problem.add_quality_metric(
        MinimizeActionCosts({a: Int(round(10 * c)) for a, c in costs.items()})
    )
    return problem


def solve(
    scene: Scene,
    spec: HSpec,
    world: WorldState | None = None,
    *,
    optimal: bool = True,
    timeout: float = 60.0,
) -> FDResult:
    """Plan with Fast Downward (``seq-opt`` with ``optimal``, else its satisficing default).

    The call runs in a fresh temporary working directory (the process's, so not from several
    threads at once).

    Raises:
        BackendUnavailableError: the ``baselines`` extra is not installed.
    """
    missing = fd_unavailable()
    if missing is not None:
        raise BackendUnavailableError(missing)
    ups = importlib.import_module("unified_planning.shortcuts")
    St = importlib.import_module("unified_planning.engines").PlanGenerationResultStatus

    try:
        problem = build_problem(scene, spec, world)
    except NotEncodable as exc:
        return FDResult(f"not_encodable: {exc}")
    ups.get_environment().credits_stream = None
    name = "fast-downward-opt" if optimal else "fast-downward"
    # Fast Downward's driver writes output.sas into the working directory: two planners in one
    # directory (parallel workers) would read each other's tasks, so each call gets its own.
    here = os.getcwd()
    with tempfile.TemporaryDirectory(prefix="hltl-fd-") as work:
        os.chdir(work)
        try:
            t0 = time.perf_counter()
            with ups.OneshotPlanner(name=name) as planner:
                res = planner.solve(problem, timeout=timeout)
            seconds = time.perf_counter() - t0
        finally:
            os.chdir(here)
    if res.status in (St.SOLVED_OPTIMALLY, St.SOLVED_SATISFICING) and res.plan is not None:
        names = tuple(str(a) for a in res.plan.actions)
        d = {"pick": 0.5, "place": 0.5, "handover_r2r": 0.6, "handover_r2h": 0.5}
        d.update(dict(scene.durations or ()))
        cost = sum(
            d[{"pick_from": "pick"}.get(a.action.name, a.action.name)] for a in res.plan.actions
        )
        return FDResult("solved", seconds, round(cost, 6), len(names), names)
    if res.status in (St.UNSOLVABLE_PROVEN, St.UNSOLVABLE_INCOMPLETELY):
        return FDResult("unsolvable", seconds)
    if res.status is St.TIMEOUT:
        return FDResult("timeout", seconds)
    return FDResult(f"error: {res.status.name}", seconds)
