"""Plan validator: replays a DESIGN.md §3 plan from the initial state by docs/model.md."""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import Any

from hltl.spec.syntax import Atom
from hltl.world.scene import Scene

from .model import (
    REST,
    ROBOTS_PER_SKILL,
    ROLES,
    SKILLS,
    Hierarchy,
    Location,
    can_meet,
    effect,
    event_atom,
    fire_steps,
    hierarchy,
    human_inside,
    mentions,
    point_of,
    reaches,
    rendezvous_blocked,
    state_atoms,
    surface_point,
)

TOL = 1e-6


def _close(a: float, b: float) -> bool:
    return math.isclose(a, b, rel_tol=TOL, abs_tol=TOL)


def _number(value: Any) -> float | None:
    if isinstance(value, bool) or not isinstance(value, int | float) or not math.isfinite(value):
        return None
    return float(value)


def validate_plan(scene: Scene, spec: Any, plan: Mapping[str, Any]) -> list[str]:
    """Every way ``plan`` breaks the planning model; an empty list means the plan is valid.

    Checks: ids exist; each step's robots are disjoint and its objects distinct; every action's
    precondition holds on the state before its step; start times are the running sum of
    durations; each duration is the step's largest fixed skill duration (scenes with
    ``durations``) or positive (analytic costs), and 0 for an empty step; the makespan is the sum
    of durations; the root fires exactly at the last step (direct LTLf semantics, not the DFA
    monitor); bindings, where given, bind every acting robot to a not-yet-done leaf that
    mentions its object, with a valid role, and both robots of a handover to the same leaf.
    """
    if not isinstance(plan, Mapping):
        return [f"a plan must be a mapping, got {type(plan).__name__}"]
    errors: list[str] = []
    if plan.get("status") != "solved":
        errors.append(f"status is {plan.get('status')!r}; only a 'solved' plan can be replayed")
    steps = plan.get("steps")
    if not isinstance(steps, list):
        return [*errors, f"'steps' must be a list, got {steps!r}"]

    h = hierarchy(spec)
    fixed = scene.duration_map()
    locs: dict[str, Location] = {o.id: REST for o in scene.objects}
    symbols: list[frozenset[Atom]] = []
    step_actions: list[list[Mapping[str, Any]]] = []
    clock = 0.0
    for k, step in enumerate(steps):
        where = f"step {k}"
        if not isinstance(step, Mapping):
            errors.append(f"{where}: a step must be a mapping, got {step!r}")
            return errors
        start, duration = _number(step.get("start")), _number(step.get("duration"))
        if start is None or duration is None:
            errors.append(f"{where}: 'start' and 'duration' must be finite numbers, got {step!r}")
            return errors
        if not _close(start, clock):
            errors.append(f"{where}: starts at {start}, expected {clock} (sum of durations)")
        raw_actions = step.get("actions", [])
        if not isinstance(raw_actions, list):
            errors.append(f"{where}: 'actions' must be a list, got {raw_actions!r}")
            raw_actions = []
        actions = []
        for j, a in enumerate(raw_actions):
            shape = _shape_errors(scene, a, f"{where} action {j}")
            errors.extend(shape)
            if not shape:
                actions.append(a)
        errors.extend(_step_errors(scene, locs, actions, where))
        errors.extend(_duration_errors(fixed, actions, len(raw_actions), duration, where))
        events = set()
        for a in actions:
            locs[a["object"]] = effect(a)
            ev = event_atom(a)
            if ev is not None:
                events.add(ev)
        symbols.append(frozenset(events) | state_atoms(scene, [locs[o.id] for o in scene.objects]))
        step_actions.append(actions)
        clock += duration

    makespan = _number(plan.get("makespan"))
    if makespan is None:
        errors.append(f"'makespan' must be a finite number, got {plan.get('makespan')!r}")
    elif not _close(makespan, clock):
        errors.append(f"makespan is {makespan}, but the durations sum to {clock}")

    fired = fire_steps(h, symbols)
    root = fired[h.root]
    if root is None:
        errors.append(f"the root {h.root!r} never accepts: the plan does not satisfy the spec")
    elif root != len(steps) - 1:
        errors.append(
            f"the root {h.root!r} fires at step {root}, but the plan goes on to step "
            f"{len(steps) - 1}: a plan ends when the root fires"
        )
    for k, step in enumerate(steps):
        if "bindings" in step:
            errors.extend(_binding_errors(scene, h, fired, k, step["bindings"], step_actions[k]))
    return errors


def check_plan(scene: Scene, spec: Any, plan: Mapping[str, Any]) -> None:
    """Raise AssertionError listing every violation of :func:`validate_plan`."""
    errors = validate_plan(scene, spec, plan)
    if errors:
        raise AssertionError("invalid plan:\n  " + "\n  ".join(errors))


def check_against_optimum(
    scene: Scene,
    spec: Any,
    result: Any,
    expected: float | None,
    *,
    abs_tol: float = 1e-6,
    validate: bool = True,
) -> None:
    """A planner result against an oracle's optimum (``None``: no plan exists): the status,
    the makespan, and (``validate``) the plan replayed by :func:`check_plan`."""
    status = result.status.value
    if expected is None:
        assert status == "infeasible", result
        assert result.reason
        return
    assert status == "solved", result.reason
    assert result.makespan is not None
    assert math.isclose(result.makespan, expected, abs_tol=abs_tol), (result.makespan, expected)
    if validate:
        check_plan(scene, spec, result.to_dict())


def _shape_errors(scene: Scene, a: Any, where: str) -> list[str]:
    if not isinstance(a, Mapping):
        return [f"{where}: an action must be a mapping, got {a!r}"]
    skill = a.get("skill")
    if skill not in SKILLS:
        return [f"{where}: unknown skill {skill!r}; expected one of {', '.join(SKILLS)}"]
    errors = []
    robots = a.get("robots")
    if not isinstance(robots, list | tuple) or len(robots) != ROBOTS_PER_SKILL[skill]:
        errors.append(f"{where}: {skill} takes {ROBOTS_PER_SKILL[skill]} robot(s), got {robots!r}")
    else:
        errors += [f"{where}: unknown robot {r!r}" for r in robots if r not in scene.robot_ids]
        if len(set(robots)) != len(robots):
            errors.append(f"{where}: {skill} names the same robot twice: {robots!r}")
    if a.get("object") not in scene.object_ids:
        errors.append(f"{where}: unknown object {a.get('object')!r}")
    for key, kind, ids, needed in (
        ("human", "human", scene.human_ids, skill == "handover_r2h"),
        ("surface", "surface", scene.surface_ids, skill == "place"),
    ):
        if needed and a.get(key) not in ids:
            errors.append(f"{where}: {skill} needs a known {kind}, got {a.get(key)!r}")
        if not needed and key in a:
            errors.append(f"{where}: {skill} takes no {kind}, got {a[key]!r}")
    return errors


def _step_errors(
    scene: Scene, locs: Mapping[str, Location], actions: Sequence[Mapping[str, Any]], where: str
) -> list[str]:
    errors: list[str] = []
    seen_robots: set[str] = set()
    seen_objects: set[str] = set()
    for a in actions:
        for r in a["robots"]:
            if r in seen_robots:
                errors.append(f"{where}: robot {r!r} runs two actions in one step")
            seen_robots.add(r)
        if a["object"] in seen_objects:
            errors.append(f"{where}: object {a['object']!r} is used by two actions in one step")
        seen_objects.add(a["object"])
    held_by = {loc[1]: oid for oid, loc in locs.items() if loc[0] == "held"}
    for a in actions:
        problems = _precondition_errors(scene, locs, held_by, a)
        errors += [f"{where}: {_describe(a)}: {e}" for e in problems]
    return errors


def _precondition_errors(
    scene: Scene, locs: Mapping[str, Location], held_by: Mapping[str, str], a: Mapping[str, Any]
) -> list[str]:
    skill, oid, robots = a["skill"], a["object"], list(a["robots"])
    loc = locs[oid]
    errors = []
    if skill == "pick":
        r = scene.robot(robots[0])
        if r.id in held_by:
            errors.append(f"{r.id} is not free (holds {held_by[r.id]})")
        point = point_of(scene, oid, loc)
        if point is None:
            errors.append(f"{oid} is not resting or on a surface (it is {_where(loc)})")
        elif not reaches(r, point):
            errors.append(f"{oid} at {list(point)} is out of {r.id}'s reach")
    elif skill == "place":
        r, s = scene.robot(robots[0]), scene.surface(a["surface"])
        if loc != ("held", r.id):
            errors.append(f"{r.id} does not hold {oid} (it is {_where(loc)})")
        if not reaches(r, surface_point(scene, s.id)):
            errors.append(f"surface {s.id} is out of {r.id}'s reach")
    elif skill == "handover_r2r":
        g, r = scene.robot(robots[0]), scene.robot(robots[1])
        if loc != ("held", g.id):
            errors.append(f"giver {g.id} does not hold {oid} (it is {_where(loc)})")
        if r.id in held_by:
            errors.append(f"receiver {r.id} is not free (holds {held_by[r.id]})")
        if not can_meet(g, r):
            errors.append(f"{g.id} and {r.id} cannot meet (reach spheres do not overlap)")
        elif rendezvous_blocked(scene, g, r):
            errors.append(f"the rendezvous of {g.id} and {r.id} is blocked by a person")
    else:
        r, u = scene.robot(robots[0]), scene.human(a["human"])
        if loc != ("held", r.id):
            errors.append(f"{r.id} does not hold {oid} (it is {_where(loc)})")
        if not human_inside(r, u, scene.human_reach):
            errors.append(f"human {u.id} is not inside {r.id}'s workspace")
    return errors


def _duration_errors(
    fixed: Mapping[str, float] | None,
    actions: Sequence[Mapping[str, Any]],
    n_raw: int,
    duration: float,
    where: str,
) -> list[str]:
    if n_raw == 0:
        return [] if duration == 0 else [f"{where}: an empty step lasts 0, not {duration}"]
    if fixed is not None and actions and all(a["skill"] in fixed for a in actions):
        expected = max(fixed[a["skill"]] for a in actions)
        if not _close(duration, expected):
            return [f"{where}: lasts {duration}, expected {expected} (longest fixed duration)"]
        return []
    return [] if duration > 0 else [f"{where}: a step with actions must last > 0, not {duration}"]


def _binding_errors(
    scene: Scene,
    h: Hierarchy,
    fired: Mapping[str, int | None],
    k: int,
    bindings: Any,
    actions: Sequence[Mapping[str, Any]],
) -> list[str]:
    where = f"step {k} bindings"
    if not isinstance(bindings, Mapping):
        return [f"{where}: must map robots to [leaf, role], got {bindings!r}"]
    errors: list[str] = []
    bound: dict[str, tuple[str, str]] = {}
    for rid, value in bindings.items():
        if rid not in scene.robot_ids:
            errors.append(f"{where}: unknown robot {rid!r}")
            continue
        if not isinstance(value, list | tuple) or len(value) != 2:
            errors.append(f"{where}: {rid} must be bound to [leaf, role], got {value!r}")
            continue
        leaf, role = value
        if leaf not in h.leaves:
            errors.append(f"{where}: {rid} is bound to {leaf!r}, which is not a leaf")
            continue
        if role not in ROLES:
            errors.append(f"{where}: {rid} has role {role!r}; expected one of {sorted(ROLES)}")
        bound[rid] = (leaf, role)
    for a in actions:
        for rid in a["robots"]:
            if rid not in bound:
                if rid not in bindings:
                    errors.append(f"{where}: {rid} acts ({_describe(a)}) but is not bound")
                continue
            leaf, role = bound[rid]
            done_at = fired[leaf]
            if done_at is not None and done_at < k:
                errors.append(f"{where}: {rid} is bound to {leaf}, already done at step {done_at}")
            if not mentions(h.formulas[leaf], a["object"]):
                errors.append(
                    f"{where}: {rid} moves {a['object']} but its leaf {leaf} does not mention it"
                )
            if a["skill"] == "handover_r2r" and role == "solo":
                errors.append(f"{where}: {rid} takes part in a handover with role 'solo'")
        if a["skill"] == "handover_r2r":
            g, r = a["robots"]
            if g in bound and r in bound and bound[g][0] != bound[r][0]:
                errors.append(
                    f"{where}: handover of {a['object']}: giver {g} is bound to {bound[g][0]} "
                    f"but receiver {r} to {bound[r][0]}"
                )
    return errors


def _describe(a: Mapping[str, Any]) -> str:
    target = a.get("human") or a.get("surface")
    args = ", ".join([str(a["object"]), *([str(target)] if target else [])])
    return f"{a['skill']}({args}) by {'→'.join(a['robots'])}"


def _where(loc: Location) -> str:
    kind, place = loc
    return {"rest": "resting", "held": f"held by {place}", "on": f"on {place}"}.get(
        kind, f"delivered to {place}"
    )
