"""``hltl node``: run a part of the cell as a node on the Zenoh bus (simulator, perception)."""

from __future__ import annotations

import argparse
import functools
import math
import sys
import threading
from pathlib import Path
from typing import Any

from hltl.bus.node import CellNode, serve
from hltl.bus.perception import serve_frames
from hltl.bus.session import DEFAULT_ENDPOINT, PERCEPTION_ENDPOINT, BusConfig, open_session
from hltl.cli.bus_options import add_node_arguments
from hltl.cli.perceive import frame_options
from hltl.cli.sim3d import add_simulator_arguments, simulator_options
from hltl.errors import HltlError
from hltl.motion.cost import motion_models
from hltl.perception.frames import FrameFolder
from hltl.perception.observe import Perceiver
from hltl.sim.simulator import Simulator
from hltl.world.scene import load_scene


def register(sub: Any) -> None:
    p: argparse.ArgumentParser = sub.add_parser(
        "node",
        help="run the simulator or the perception stage as a node on the Zenoh bus",
        description="Serve a part of the cell on the Zenoh bus (docs/bus.md): its robots, its "
        "camera and its simulated clock. An executor started with 'hltl run --bus zenoh' "
        "drives it. Loopback by default, multicast scouting off.",
    )
    nsub = p.add_subparsers(dest="node", metavar="NODE", required=True)
    s = nsub.add_parser(
        "sim",
        help="the simulator as robot and camera nodes",
        description="Serve the simulated cell: robots take actions over the bus, report "
        "progress and outcomes, and the executor steps simulated time.",
    )
    s.add_argument("--scene", required=True, type=Path, help="scene file (YAML or JSON)")
    add_simulator_arguments(
        s, "which simulator serves the cell (mujoco: the 3D simulator, the sim3d extra)"
    )
    s.add_argument(
        "--motion",
        action="store_true",
        help="--sim discrete: time actions with the motion layer (as 'hltl run --motion', the "
        "motion extra); serve executors started with 'hltl run --motion --bus'",
    )
    add_node_arguments(s, DEFAULT_ENDPOINT)
    s.add_argument(
        "--episodes", type=int, help="exit after serving this many episodes (default: run on)"
    )
    s.add_argument(
        "--rate",
        type=float,
        metavar="HZ",
        help="in real-time episodes ('hltl run --bus --realtime'), tick and publish this many "
        "times per cell second (default: as often as the executor ticks)",
    )
    s.set_defaults(func=run_sim)
    c = nsub.add_parser(
        "perception",
        help="the perception stage as a node: camera frames in, observations out",
        description="Run the perception stage on a frame folder (camera.json, rgb/, depth/, "
        "optional seg/: what 'hltl render' and the 3D simulator write, or a recorded RealSense "
        "sequence) and publish each frame's objects and tracked people on "
        "hltl/<cell>/perception, people as PoseStamped on hltl/<cell>/humans/<h>/pose. "
        "'hltl run --bus zenoh --bus-perception zenoh' fuses them into the executor's world.",
    )
    frame_options(
        c,
        people_help="person detector (default: segmentation when the folder has seg/, else depth)",
    )
    add_node_arguments(c, PERCEPTION_ENDPOINT, "; the executor connects here")
    c.add_argument("--realtime", action="store_true", help="pace frames by their time stamps")
    c.add_argument(
        "--wait",
        type=float,
        default=30.0,
        help="seconds to wait for a subscriber before the first frame (default 30)",
    )
    c.set_defaults(func=run_perception)


def run_sim(args: argparse.Namespace) -> int:
    from rich.console import Console

    if args.episodes is not None and args.episodes < 1:
        raise HltlError(f"--episodes must be at least 1, got {args.episodes}")
    if args.rate is not None and not (math.isfinite(args.rate) and args.rate > 0):
        raise HltlError(f"--rate must be a positive number of ticks per second, got {args.rate!r}")
    scene = load_scene(args.scene)
    factory = _factory(args, scene)
    console = Console(stderr=True, highlight=False)
    config = BusConfig(listen=(args.listen,), connect=tuple(args.connect))

    def ready(node: CellNode) -> None:
        robots = ", ".join(scene.robot_ids)
        console.print(
            f"[bold]hltl node sim[/] ({args.sim}) serving cell [cyan]{args.cell}[/] "
            f"(robots {robots}) on {args.listen}; Ctrl-C to stop"
        )

    stop = threading.Event()
    with open_session(config) as session:
        try:
            stats = serve(
                session,
                scene,
                cell=args.cell,
                episodes=args.episodes,
                stop=stop,
                factory=factory,
                on_ready=ready,
                period=None if args.rate is None else 1.0 / args.rate,
                freeze=getattr(args, "program", False),
            )
        except KeyboardInterrupt:
            console.print("stopped")
            return 0
    console.print(
        f"served {stats.finished} episode(s): {stats.steps} steps, "
        f"{len(stats.starts)} actions started, {stats.duplicates} duplicate commands ignored"
    )
    sys.stdout.flush()
    return 0


def run_perception(args: argparse.Namespace) -> int:
    from rich.console import Console

    if not (args.wait >= 0):
        raise HltlError(f"--wait must be a number of seconds >= 0, got {args.wait!r}")
    folder = FrameFolder(args.frames)
    scene = load_scene(args.scene) if args.scene is not None else None
    has_seg = folder.frame(0).seg is not None
    backend = args.backend or ("segmentation" if has_seg else "depth-clusters")
    people = args.people or ("segmentation" if has_seg else "depth")
    try:
        perceiver = Perceiver(scene, folder.camera, backend, people)
    except ValueError as exc:
        raise HltlError(str(exc)) from None
    console = Console(stderr=True, highlight=False)
    config = BusConfig(listen=(args.listen,), connect=tuple(args.connect))
    with open_session(config) as session:
        console.print(
            f"[bold]hltl node perception[/] {args.frames} ({backend}, people by {people}) on "
            f"cell [cyan]{args.cell}[/], {args.listen}; waiting for a subscriber"
        )
        try:
            stats = serve_frames(
                session,
                perceiver,
                folder,
                cell=args.cell,
                realtime=args.realtime,
                wait=args.wait,
            )
        except KeyboardInterrupt:
            console.print("stopped")
            return 0
    console.print(f"published {stats.frames} frame(s), {stats.poses} person pose(s)")
    return 0


def _factory(args: argparse.Namespace, scene: Any) -> Any:
    """What makes each episode's world: the discrete-event simulator, or the 3D one."""
    if args.sim == "discrete":
        if args.motion:
            kinematics, cost = motion_models(scene)
            return functools.partial(Simulator, cost=cost, kinematics=kinematics)
        return Simulator
    if args.motion:
        raise HltlError(
            "--motion times the discrete simulator; the 3D simulator (--sim mujoco) always "
            "follows the joint trajectories it receives"
        )

    extra, _ = simulator_options(scene, args.timing, None)  # compiles the model once, up front
    return extra["simulator"]
