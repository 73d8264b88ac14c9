"""Reasons a person can act on when no plan exists."""

from __future__ import annotations

from hltl.planner.problem import Problem
from hltl.planner.relaxed import INF, RelaxedGraph
from hltl.spec.syntax import Atom
from hltl.world.geometry import distance, horizontal_distance


def explain_infeasible(problem: Problem, graph: RelaxedGraph | None = None) -> str:
    """Say why no plan exists: name the events that can never happen and what blocks them."""
    g = RelaxedGraph(problem) if graph is None else graph
    locs = problem.start()[0]
    # only what is still open matters: a finished delivery's atom can never happen again
    done = problem.monitor.done(problem.q0)
    open_atoms = frozenset().union(
        *(atoms_ for name, atoms_ in problem.formula_atoms.items() if name not in done)
    )
    impossible = sorted(a for a in open_atoms if g.atom_time(a, locs) == INF)
    # state atoms that can never become true matter only when positive; we cannot tell polarity
    # here cheaply, so report event atoms and state atoms alike, events first
    reasons = [_why(problem, g, a, locs) for a in impossible if a.name in _EVENTS]
    reasons += [_why(problem, g, a, locs) for a in impossible if a.name not in _EVENTS]
    root = problem.spec.root
    if reasons:
        return f"no plan satisfies {root}: " + "; ".join(reasons)
    return (
        f"no plan satisfies {root} from here: every open event is reachable on its own, but no "
        "sequence of steps completes it (an ordering that cannot be met, hands that block each "
        "other, an object that would be needed twice, or a constraint the events violate); "
        f"now: {_situation(problem, locs)}"
    )


def _situation(problem: Problem, locs: tuple[int, ...]) -> str:
    """Who holds what, and which robots serve each person: what a person can change."""
    held = [
        f"{problem.robots[problem.code_holder[c]]} holds {problem.objects[o]}"
        for o, c in enumerate(locs)
        if c in problem.code_holder
    ]
    served = [
        f"{hid} served by {', '.join(sorted(rs)) or 'no robot'}"
        for hid, rs in problem.context.served_by
    ]
    return "; ".join(held + served) or "all hands free"


_EVENTS = ("delivered", "placed", "picked")


def _why(problem: Problem, g: RelaxedGraph, atom: Atom, locs: tuple[int, ...]) -> str:
    scene = problem.scene
    obj = atom.args[1] if atom.name == "holding" else atom.args[0]
    o = problem.obj_index[obj]
    here = problem.locs[locs[o]]
    if here.kind == "delivered":
        return f"{atom} can never happen: {obj} was already handed to {here.ref}"
    pickers = sorted(
        {
            problem.instances[i.index].action.robots[0]
            for i in problem.by_obj_pre[o][locs[o]]
            if i.action.skill == "pick"
        }
    )
    avail = ", ".join(r.id for r in problem.situation.available) or "none"
    if here.kind == "rest" and not pickers:
        pos = problem.situation.rest_position(obj)
        near = min(
            problem.situation.available, key=lambda r: distance(r.base, pos) - r.reach, default=None
        )
        detail = ""
        if near is not None:
            detail = (
                f" (nearest: {near.id}, {distance(near.base, pos):.2f} m away, "
                f"reach {near.reach:.2f} m)"
            )
        return (
            f"{atom} can never happen: {obj} at {_fmt(pos)} is out of reach of every "
            f"available robot ({avail}){detail}"
        )
    if atom.name == "delivered":
        hid = atom.args[1]
        serving = sorted(
            problem.context.robots_serving(hid) & {r.id for r in problem.situation.available}
        )
        if not serving:
            pos = problem.situation.human_position(hid)
            near = min(scene.robots, key=lambda r: horizontal_distance(r.base, pos) - r.reach)
            return (
                f"{atom} can never happen: {scene.human(hid).name} ({hid}) at {_fmt(pos)} "
                f"is outside every available robot's workspace (nearest: {near.id}, "
                f"{horizontal_distance(near.base, pos):.2f} m away, reach {near.reach:.2f} m "
                f"+ {scene.human_reach:.2f} m arm)"
            )
        return (
            f"{atom} can never happen: {obj} is out of reach of every robot chain that can "
            f"reach {scene.human(hid).name} (robots that can pick {obj}: "
            f"{', '.join(pickers) or 'none'}; robots serving {hid}: {', '.join(serving)}; "
            "no chain of handovers joins them, or a person blocks the rendezvous)"
        )
    if atom.name in ("placed", "at"):
        sid = atom.args[1]
        placers = sorted(
            {
                r.id
                for r in problem.situation.available
                if problem.situation.kinematics.reaches(r, scene.surface(sid).object_point)
            }
        )
        if not placers:
            return f"{atom} can never happen: surface {sid} is out of reach of every robot"
        return (
            f"{atom} can never happen: no robot chain carries {obj} from where it is to a "
            f"robot that reaches {sid} ({', '.join(placers)})"
        )
    return f"{atom} can never happen from the current state"


def _fmt(p: tuple[float, float, float]) -> str:
    return "(" + ", ".join(f"{v:.2f}" for v in p) + ")"
