"""``hltl plan``: plan a spec (or an instruction) in a scene; print a timeline or the plan JSON."""

from __future__ import annotations

import argparse
import json
import math
import sys
from pathlib import Path
from typing import Any

from hltl.cli.common import check_option, load_spec_or_ground, print_plan_timeline
from hltl.errors import HltlError
from hltl.fileio import write_output
from hltl.planner import plan
from hltl.spec.hierarchy import spec_to_dict
from hltl.world.scene import load_scene


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
    p.add_argument(
        "--timeout",
        type=float,
        default=None,
        help="seconds before giving up (default 60); with --anytime, the time to improve the "
        "plan and its bound (default 10)",
    )
    p.add_argument(
        "--anytime",
        action="store_true",
        help="return a plan fast, improve it until --timeout, and prove how far from optimal it "
        "can be (lower_bound and gap in the plan JSON)",
    )
    p.add_argument(
        "--suboptimality",
        type=float,
        metavar="W",
        help="anytime mode that stops once makespan <= W x lower bound (W >= 1, e.g. 1.1)",
    )
    p.add_argument("--json", action="store_true", help="print the plan JSON")
    p.add_argument(
        "--motion",
        action="store_true",
        help="reach from the arms' reachability maps and durations from motion plans "
        "(robots with model elfin3, xarm6, ur5 or panda; needs the motion extra)",
    )
    p.add_argument("-o", "--output", type=Path, help="also write the plan JSON to this file")
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    if args.timeout is not None:
        check_option("--timeout", args.timeout, positive=True)
    if args.suboptimality is not None and not (
        math.isfinite(args.suboptimality) and args.suboptimality >= 1.0
    ):
        raise HltlError(
            f"--suboptimality: expected a factor of at least 1 (e.g. 1.1), got {args.suboptimality}"
        )
    anytime = args.anytime or args.suboptimality is not None
    timeout = args.timeout if args.timeout is not None else (10.0 if anytime else 60.0)
    scene = load_scene(args.scene)
    spec = load_spec_or_ground(scene, args.spec, args.instruction, args.grounder)
    extra: dict[str, Any] = {}
    if args.motion:
        # why: the motion layer loads numpy and a process pool; `hltl plan` without --motion
        # starts in 0.2 s CPU (docs/benchmarks.md, Start-up)
        from hltl.motion.cost import motion_models

        kinematics, cost = motion_models(scene)
        extra = {"kinematics": kinematics, "cost": cost}
    result = plan(
        scene,
        spec,
        algorithm=args.algorithm,
        timeout=timeout,
        anytime=anytime,
        suboptimality=args.suboptimality,
        **extra,
    )
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
    if anytime and not args.json and result.gap is not None and result.lower_bound is not None:
        print(
            f"makespan {result.makespan:.2f} s, lower bound {result.lower_bound:.2f} s: "
            f"optimal within {100 * result.gap:.1f} %"
        )
    return 0
