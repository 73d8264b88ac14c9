"""``hltl plan``: plan a spec (or an instruction) in a scene; print a timeline or the plan JSON."""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path
from typing import Any

from hltl.cli.common import check_option, load_spec_or_ground, print_plan_timeline
from hltl.fileio import write_output


def register(sub: Any) -> None:
    p: argparse.ArgumentParser = sub.add_parser(
        "plan",
        help="find a makespan-optimal plan",
        description="Find a minimum-makespan plan for a spec or an instruction in a scene. "
        "Exit 0 when solved, 1 when infeasible or timed out, 2 on bad usage.",
    )
    p.add_argument("--scene", required=True, type=Path, help="scene file (YAML or JSON)")
    src = p.add_mutually_exclusive_group(required=True)
    src.add_argument("--spec", type=Path, help="H-LTLf spec file (YAML or JSON)")
    src.add_argument("--instruction", help="an instruction in English, grounded offline")
    p.add_argument(
        "--grounder",
        choices=("offline", "llm", "local"),
        default="offline",
        help="grounder for --instruction (default: the embedded offline parser)",
    )
    p.add_argument(
        "--algorithm", choices=("astar", "dijkstra"), default="astar", help="search algorithm"
    )
    p.add_argument("--timeout", type=float, default=60.0, help="seconds before giving up")
    p.add_argument("--json", action="store_true", help="print the plan JSON")
    p.add_argument(
        "--motion",
        action="store_true",
        help="reach from the arms' reachability maps and durations from motion plans "
        "(robots with model elfin3, ur5 or panda; needs the motion extra)",
    )
    p.add_argument("-o", "--output", type=Path, help="also write the plan JSON to this file")
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    from hltl.planner import plan
    from hltl.spec.hierarchy import spec_to_dict
    from hltl.world.scene import load_scene

    check_option("--timeout", args.timeout, positive=True)
    scene = load_scene(args.scene)
    spec = load_spec_or_ground(scene, args.spec, args.instruction, args.grounder)
    extra: dict[str, Any] = {}
    if args.motion:
        from hltl.motion.cost import motion_models

        kinematics, cost = motion_models(scene)
        extra = {"kinematics": kinematics, "cost": cost}
    result = plan(scene, spec, algorithm=args.algorithm, timeout=args.timeout, **extra)
    data = result.to_dict(spec=spec_to_dict(spec), scene=str(args.scene))
    if args.output is not None:
        write_output(args.output, "the plan", json.dumps(data, indent=2) + "\n")
    if args.json:
        print(json.dumps(data, indent=2))
    else:
        print_plan_timeline(result, scene)
    if not result.solved:
        print(f"error: {result.status.value}: {result.reason}", file=sys.stderr)
        return 1
    return 0
