"""``hltl motion``: handover poses, comfort-zone targets, skill motions and reachability maps."""

from __future__ import annotations

import argparse
import json
from pathlib import Path
from typing import Any

from hltl.errors import HltlError
from hltl.motion.grasps import Cylinder
from hltl.motion.handover import optimise_r2r, plan_r2h
from hltl.motion.human import standing_posture
from hltl.motion.planning import CandidatePlanner, Cell, plan_action
from hltl.motion.reach import _cache_file, default_resolution, load_or_build
from hltl.motion.robots import MODEL_NAMES
from hltl.skills.library import Action
from hltl.world.scene import load_scene


def register(sub: Any) -> None:
    p: argparse.ArgumentParser = sub.add_parser(
        "motion",
        help="arm kinematics: handover poses, comfort zones, skill motions, reachability maps",
        description="Motion planning on the scene's arm models (paper §IV). Robots whose model "
        "is elfin3, xarm6, ur5 or panda get real kinematics; others keep their reach sphere.",
    )
    msub = p.add_subparsers(dest="motion_command", metavar="WHAT", required=True)

    h = msub.add_parser("handover", help="optimise a robot-to-robot handover pose (§IV-B)")
    h.add_argument("--scene", required=True, type=Path, help="scene file (YAML or JSON)")
    h.add_argument("--giver", required=True, help="robot id of the giver")
    h.add_argument("--receiver", required=True, help="robot id of the receiver")
    h.add_argument("--object", help="object handed over (sets the grasped cylinder)")
    h.add_argument("--samples", type=int, default=24, help="candidate poses (default 24)")
    h.add_argument("--seed", type=int, default=0, help="sampling seed")
    h.add_argument("--json", action="store_true", help="print the result as JSON")
    h.set_defaults(func=run_handover)

    r = msub.add_parser("r2h", help="a robot-to-human handover target in the comfort zone (§IV-C)")
    r.add_argument("--scene", required=True, type=Path, help="scene file (YAML or JSON)")
    r.add_argument("--robot", required=True, help="robot id")
    r.add_argument("--human", required=True, help="human id")
    r.add_argument("--height", type=float, default=1.70, help="the person's height in m")
    r.add_argument("--json", action="store_true", help="print the result as JSON")
    r.set_defaults(func=run_r2h)

    s = msub.add_parser("skill", help="plan one skill instance's motion (trajectories, events)")
    s.add_argument("--scene", required=True, type=Path, help="scene file (YAML or JSON)")
    s.add_argument(
        "--skill", required=True, choices=("pick", "place", "handover_r2r", "handover_r2h")
    )
    s.add_argument("--robots", required=True, help="robot ids in role order, comma-separated")
    s.add_argument("--object", required=True, help="object id")
    s.add_argument("--human", help="human id (handover_r2h)")
    s.add_argument("--surface", help="surface id (place)")
    s.add_argument(
        "--workers", type=int, default=0, help="processes for candidate planning (0: serial)"
    )
    s.add_argument("--json", action="store_true", help="print the motion plan as JSON")
    s.set_defaults(func=run_skill)

    m = msub.add_parser("maps", help="build (or load) the reachability maps of the arm models")
    m.add_argument("--model", action="append", help="model name (repeat; default: all)")
    m.add_argument("--resolution", type=float, help="grid spacing in m (default per model)")
    m.set_defaults(func=run_maps)


def _cell(scene_path: Path) -> Any:
    return Cell(load_scene(scene_path))


def _round(x: Any, n: int = 4) -> Any:
    if isinstance(x, float):
        return round(x, n)
    if isinstance(x, list | tuple):
        return [_round(v, n) for v in x]
    return x


def run_handover(args: argparse.Namespace) -> int:
    from rich.console import Console
    from rich.table import Table

    if args.samples < 1:
        raise HltlError(f"--samples must be at least 1, got {args.samples}")
    cell = _cell(args.scene)
    scene = cell.scene
    g, r = scene.robot(args.giver), scene.robot(args.receiver)
    if g.id == r.id:
        raise HltlError(f"--giver and --receiver are both {g.id!r}; expected two robots")
    cyl = Cylinder.for_category(scene.object(args.object).category) if args.object else None
    sphere = cell.kinematics.rendezvous(g, r)
    if sphere is None:
        raise HltlError(f"{g.id} and {r.id} share no reachable region large enough to meet in")
    kwargs: dict[str, Any] = {} if cyl is None else {"obj": cyl}
    res = optimise_r2r(
        cell.arm(g.id),
        cell.arm(r.id),
        sphere,
        people=cell.people(),
        n_samples=args.samples,
        seed=args.seed,
        **kwargs,
    )
    data: dict[str, Any] = {
        "giver": g.id,
        "receiver": r.id,
        "sphere": {"centre": _round(sphere.centre), "radius": round(sphere.radius, 4)},
        "candidates": [
            {
                "position": _round(c.position),
                "feasibility": round(c.feasibility, 4),
                "travel": round(c.travel, 4),
                "score": round(c.score, 4),
            }
            for c in res.candidates
        ],
        "tried": res.tried,
        "seconds": round(res.seconds, 4),
        "status": "found" if res.pose is not None else "none",
    }
    if res.pose is None:
        data["reason"] = res.reason
    else:
        pose = res.pose
        data["pose"] = {
            "position": _round(pose.position),
            "clearance": round(pose.clearance, 4),
            **{
                role: {
                    "robot": goal.robot,
                    "grasp": {
                        "kind": goal.grasp.kind,
                        "azimuth": round(goal.grasp.azimuth, 4),
                        "height": round(goal.grasp.height, 4),
                    },
                    "tool_position": _round(goal.tool_position),
                    "tool_rotation": _round(goal.tool_rotation),
                    "approach": _round(goal.grasp.approach),
                    "q": _round(goal.q),
                    ("q_retreat" if role == "giver" else "q_pre_handover"): _round(goal.q_approach),
                }
                for role, goal in (("giver", pose.giver), ("receiver", pose.receiver))
            },
        }
    if args.json:
        print(json.dumps(data, indent=2))
        return 0 if res.pose is not None else 1
    con = Console()
    con.print(
        f"inscribed sphere of {g.id}∩{r.id}: centre {_fmt(sphere.centre)}, "
        f"radius {sphere.radius:.3f} m"
    )
    t = Table(title="best candidates", title_justify="left")
    for col in ("position (m)", "feasibility", "travel (m)", "score"):
        t.add_column(col, justify="right")
    for c in res.candidates[:8]:
        t.add_row(_fmt(c.position), f"{c.feasibility:.2f}", f"{c.travel:.3f}", f"{c.score:.3f}")
    con.print(t)
    if res.pose is None:
        con.print(f"[bold red]no feasible handover pose[/]: {res.reason}")
        return 1
    pose = res.pose
    con.print(
        f"[bold green]handover pose[/] {_fmt(pose.position)} (tried {res.tried}, "
        f"{res.seconds * 1000:.1f} ms), arm clearance {pose.clearance:.3f} m"
    )
    for role, goal in (("giver", pose.giver), ("receiver", pose.receiver)):
        con.print(
            f"  {role} {goal.robot}: {goal.grasp.kind} grasp, "
            f"approach {_fmt(goal.grasp.approach)}, tool {_fmt(goal.tool_position)}\n"
            f"    q = {_fmt(goal.q)}"
        )
    return 0


def run_r2h(args: argparse.Namespace) -> int:
    from rich.console import Console

    cell = _cell(args.scene)
    robot = cell.scene.robot(args.robot)
    human = cell.scene.human(args.human)
    try:
        posture = standing_posture(human.position, robot.base, args.height)
    except ValueError as exc:
        raise HltlError(f"--height: {exc}") from None
    target, why = plan_r2h(cell.arm(robot.id), posture)
    data: dict[str, Any] = {"robot": robot.id, "human": human.id, "height": args.height}
    if target is None:
        data["status"] = "none"
        data["reason"] = why
    else:
        data.update(
            status="found",
            position=_round(target.position),
            approach=_round(target.approach),
            q=_round(target.q),
            q_pre_handover=_round(target.q_pre),
            clearance=round(target.clearance, 4),
        )
    if args.json:
        print(json.dumps(data, indent=2))
    elif target is None:
        Console().print(f"[bold red]no comfort-zone target[/] for {human.name}: {why}")
    else:
        Console().print(
            f"{robot.id} offers at {_fmt(target.position)} in {human.name}'s comfort zone, "
            f"approaching along {_fmt(target.approach)}; body clearance {target.clearance:.3f} m"
            f"\n  q = {_fmt(target.q)}"
        )
    return 0 if target is not None else 1


def run_skill(args: argparse.Namespace) -> int:
    from rich.console import Console

    cell = _cell(args.scene)
    robots = tuple(x.strip() for x in args.robots.split(",") if x.strip())
    for rid in robots:
        cell.scene.robot(rid)
    cell.scene.object(args.object)
    if args.human:
        cell.scene.human(args.human)
    if args.surface:
        cell.scene.surface(args.surface)
    want = 2 if args.skill == "handover_r2r" else 1
    if len(robots) != want:
        raise HltlError(f"--robots {args.robots!r}: {args.skill} needs {want} robot(s)")
    if args.skill == "handover_r2h" and not args.human:
        raise HltlError("--human is required for handover_r2h")
    if args.skill == "place" and not args.surface:
        raise HltlError("--surface is required for place")
    if args.workers < 0:
        raise HltlError(f"--workers must be >= 0, got {args.workers}")
    action = Action(args.skill, robots, args.object, human=args.human, surface=args.surface)
    with CandidatePlanner(cell, workers=args.workers) as planner:
        motion = plan_action(cell, action, planner=planner)
    if motion.plan is None:
        if args.json:
            print(
                json.dumps({"action": action.to_dict(), "status": "none", "reason": motion.reason})
            )
        else:
            Console().print(f"[bold red]no motion[/] for {action}: {motion.reason}")
        return 1
    plan = motion.plan
    if args.json:
        print(
            json.dumps(
                {
                    "action": action.to_dict(),
                    "status": "found",
                    "duration": round(plan.duration, 4),
                    "events": [[round(t, 4), k, r] for t, k, r in plan.events],
                    "trajectories": [
                        {
                            "robot": tr.robot,
                            "joint_names": list(tr.joint_names),
                            "times": _round(list(tr.times)),
                            "positions": _round([list(p) for p in tr.positions]),
                        }
                        for tr in plan.trajectories
                    ],
                }
            )
        )
        return 0
    con = Console()
    con.print(f"{action}: {plan.duration:.2f} s (planned in {motion.seconds * 1000:.0f} ms)")
    for tr in plan.trajectories:
        con.print(f"  {tr.robot}: {len(tr.times)} samples over {tr.duration:.2f} s")
    for t, kind, rid in plan.events:
        con.print(f"  t={t:.2f} s  {kind} ({rid})")
    return 0


def run_maps(args: argparse.Namespace) -> int:
    import time

    from rich.console import Console

    models = args.model or list(MODEL_NAMES)
    for name in models:
        if name not in MODEL_NAMES:
            raise HltlError(f"--model {name!r}: expected one of {', '.join(MODEL_NAMES)}")
    if args.resolution is not None and not 0.005 <= args.resolution <= 0.5:
        raise HltlError(f"--resolution {args.resolution!r}: expected 0.005 … 0.5 m")
    con = Console()
    for name in models:
        res = args.resolution or default_resolution(name)
        cached = _cache_file(name, res).exists()
        t0 = time.perf_counter()
        m = load_or_build(name, res)
        dt = time.perf_counter() - t0
        con.print(
            f"{name}: {m.reachable.shape} grid at {res * 100:.1f} cm, "
            f"{int(m.reachable.sum())} reachable points "
            f"({'read from cache' if cached else 'built'} in {dt:.1f} s) → {_cache_file(name, res)}"
        )
    return 0


def _fmt(v: Any) -> str:
    return "(" + ", ".join(f"{float(x):.3f}" for x in v) + ")"
