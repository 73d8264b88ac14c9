"""``hltl viz``: draw a plan (Gantt), an execution log (Gantt and animation) or a spec (tree)."""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import Any

from hltl.errors import HltlError
from hltl.motion.handover import optimise_r2r
from hltl.motion.planning import Cell
from hltl.viz.arms3d import render_arms
from hltl.viz.render import RenderOptions, render_file
from hltl.world.scene import load_scene


def register(sub: Any) -> None:
    p: argparse.ArgumentParser = sub.add_parser(
        "viz",
        help="draw a plan, an execution log or a spec",
        description="Draw FILE, told apart by its content: a plan JSON ('hltl plan --json') "
        "becomes a Gantt chart (--animate: also a top-down replay on its scene); an execution "
        "log ('hltl run --log') a Gantt chart and an animation; an H-LTLf spec its tree with "
        "each node's formula and automaton size (--node: also that node's DFA). --frame T draws "
        "one moment of a plan or log instead. Prints the paths written. Needs the viz extra: "
        "pip install 'hltl[viz]'.",
    )
    p.add_argument("file", type=Path, metavar="FILE", help="plan JSON, log JSONL or spec YAML/JSON")
    p.add_argument(
        "-o",
        "--output",
        type=Path,
        metavar="OUT",
        help="the picture's file (its suffix sets the format) or, for several pictures, a folder "
        "(default: the current folder)",
    )
    p.add_argument(
        "--format",
        choices=("png", "svg", "gif", "html", "mp4"),
        help="png/svg: still pictures only; gif/html/mp4: the animation only (mp4 needs ffmpeg)",
    )
    p.add_argument("--scene", type=Path, help="a plan's scene file (default: the one it names)")
    p.add_argument("--animate", action="store_true", help="also animate a plan on its scene")
    p.add_argument("--node", help="also draw the DFA of this formula of a spec (e.g. p0)")
    p.add_argument(
        "--frame",
        type=float,
        metavar="T",
        help="instead, draw the animation's frame at T seconds as a still picture",
    )
    p.add_argument(
        "--arms",
        metavar="POSE",
        help="FILE is a scene: draw its arms in 3D at POSE, 'home' or 'handover:GIVER,RECEIVER' "
        "(the optimised robot-to-robot handover pose; needs the motion extra)",
    )
    p.add_argument("--fps", type=int, default=10, help="animation frames per second (default 10)")
    p.add_argument(
        "--max-frames", type=int, default=200, help="most animation frames (default 200)"
    )
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    if args.arms is not None:
        print(_arms(args))
        return 0
    if args.fps < 1 or args.max_frames < 2:
        raise HltlError(f"need --fps >= 1 and --max-frames >= 2, got {args.fps}, {args.max_frames}")
    opts = RenderOptions(
        format=args.format,
        scene=args.scene,
        animate=args.animate,
        node=args.node,
        frame=args.frame,
        fps=args.fps,
        max_frames=args.max_frames,
    )
    for path in render_file(args.file, args.output, opts):
        print(path)
    return 0


def _arms(args: argparse.Namespace) -> Path:
    cell = Cell(load_scene(args.file))
    out = args.output or Path(f"{args.file.stem}-arms.png")
    if out.suffix not in (".png", ".svg"):
        out = out / f"{args.file.stem}-arms.png"
    if args.arms == "home":
        return render_arms(cell, {}, out, title=f"{args.file.name}: arms at home")
    kind, _, who = args.arms.partition(":")
    ids = [x.strip() for x in who.split(",") if x.strip()]
    if kind != "handover" or len(ids) != 2:
        raise HltlError(f"--arms {args.arms!r}: expected 'home' or 'handover:GIVER,RECEIVER'")
    g, r = (cell.scene.robot(i) for i in ids)
    sphere = cell.kinematics.rendezvous(g, r)
    if sphere is None:
        raise HltlError(f"{g.id} and {r.id} share no reachable region to meet in")
    res = optimise_r2r(cell.arm(g.id), cell.arm(r.id), sphere, people=cell.people())
    if res.pose is None:
        raise HltlError(f"no handover pose for {g.id}→{r.id}: {res.reason}")
    pose = res.pose
    x, y, z = pose.position
    return render_arms(
        cell,
        {g.id: pose.giver.q, r.id: pose.receiver.q},
        out,
        title=f"{g.id}→{r.id} handover at ({x:.2f}, {y:.2f}, {z:.2f}) m",
        marks=[(pose.position, "handover")],
    )
