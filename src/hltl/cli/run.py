"""``hltl run``: one closed-loop episode in the simulator, with a live timeline and metrics."""

from __future__ import annotations

import argparse
import gc
import json
import sys
from pathlib import Path
from typing import Any

from hltl.bench.latency import DEFAULT_MODEL
from hltl.cli.bus_options import BusSimulator, add_bus_arguments
from hltl.cli.common import check_option, describe_action
from hltl.cli.sim3d import add_simulator_arguments, simulator_options
from hltl.errors import HltlError
from hltl.execution import log as elog
from hltl.execution.executor import Executor, ExecutorConfig
from hltl.execution.latency import LatencyModel, load_latency_model
from hltl.execution.log import LogRecord
from hltl.grounding import make_grounder
from hltl.grounding.base import check_instruction
from hltl.motion.cost import motion_models
from hltl.perception.objects import BACKENDS
from hltl.perception.predict import make_predictor
from hltl.sim.episode import EpisodeConfig, run_episode
from hltl.sim.events import load_events
from hltl.sim.simulator import PerceptionModel, Simulator
from hltl.skills.library import Action
from hltl.spec.hierarchy import load_spec
from hltl.world.scene import load_scene


def register(sub: Any) -> None:
    p: argparse.ArgumentParser = sub.add_parser(
        "run",
        help="run one closed-loop episode in the simulator",
        description="Execute an instruction or spec in a scene with the receding-horizon "
        "executor against the simulator, injecting dynamic events. Prints a live timeline and "
        "the episode's metrics. Exit 0 when every goal is met without violations, 1 otherwise.",
    )
    p.add_argument("--scene", required=True, type=Path, help="scene file (YAML or JSON)")
    src = p.add_mutually_exclusive_group(required=True)
    src.add_argument("--instruction", help="the task in English")
    src.add_argument("--spec", type=Path, help="H-LTLf spec file (YAML or JSON)")
    p.add_argument(
        "--events", type=Path, help="events file (YAML): H-MOVE, O-MOVE, GOAL, RES, FAIL"
    )
    p.add_argument("--seed", type=int, default=0, help="seed of noise, failures and random walks")
    p.add_argument("--log", type=Path, help="write the JSON Lines execution log here")
    p.add_argument("--json", action="store_true", help="print the metrics as one JSON object")
    p.add_argument(
        "--no-predict", action="store_true", help="no predictive planning or intrusion forecasts"
    )
    p.add_argument(
        "--predictor",
        choices=("cv", "goal", "gru"),
        default="cv",
        help="human trajectory predictor for workspace prediction and intrusion forecasts: "
        "constant velocity, goal-directed or the learned GRU (default: cv)",
    )
    p.add_argument("--grounder", default="offline", help="grounder for instructions")
    p.add_argument("--noise", type=float, default=0.0, help="perception noise (m, std. dev.)")
    p.add_argument("--latency", type=float, default=0.0, help="perception latency (s)")
    p.add_argument(
        "--plan-latency",
        type=float,
        default=0.0,
        help="simulated seconds each critical-path planner call costs",
    )
    p.add_argument(
        "--compute-latency",
        choices=("none", "measured", "model"),
        default="none",
        help="charge planner and grounding time where it occurs: each call's measured wall "
        "time, or the shipped latency model (replaces --plan-latency; docs/execution.md)",
    )
    p.add_argument(
        "--anticipate",
        action="store_true",
        help="anticipatory execution: start what the forecast world's plan allows now",
    )
    p.add_argument("--max-time", type=float, default=120.0, help="simulated time limit (s)")
    add_simulator_arguments(
        p, "discrete-event simulator, or the 3D one (MuJoCo; the sim3d extra): same log"
    )
    p.add_argument(
        "--frames", type=Path, metavar="DIR", help="--sim mujoco: write camera frames to DIR"
    )
    p.add_argument(
        "--motion",
        action="store_true",
        help="reach, workspaces and ℓ from the arms' reachability maps, durations from motion "
        "plans, trajectories handed to the driver (either simulator; the motion extra)",
    )
    p.add_argument(
        "--perception",
        choices=("truth", "camera"),
        default="truth",
        help="--sim mujoco: observe the simulator's state (with --noise/--latency) or run the "
        "perception stage on its rendered RGB-D frames",
    )
    p.add_argument(
        "--objects",
        choices=tuple(BACKENDS),
        help="--perception camera: the object backend (default segmentation)",
    )
    add_bus_arguments(p)
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    check_option("--max-time", args.max_time, positive=True)
    if args.instruction is not None:
        check_instruction(args.instruction, "--instruction")
    for name in ("noise", "latency", "plan_latency"):
        check_option("--" + name.replace("_", "-"), getattr(args, name))
    compute = None
    if args.compute_latency == "measured":
        compute = LatencyModel(measured=True, source="measured per call")
    elif args.compute_latency == "model":
        compute = load_latency_model(DEFAULT_MODEL)
    try:
        config = EpisodeConfig(
            max_time=args.max_time,
            perception=PerceptionModel(noise=args.noise, latency=args.latency),
            executor=ExecutorConfig(
                predict=not args.no_predict,
                intrusion=not args.no_predict,
                plan_latency=args.plan_latency,
                latency=compute,
                anticipate=args.anticipate,
            ),
        )
    except ValueError as exc:
        raise HltlError(str(exc)) from None
    scene = load_scene(args.scene)
    spec = None
    if args.spec is not None:
        spec = load_spec(args.spec)
    events = load_events(args.events, scene) if args.events is not None else None

    predictor = make_predictor(args.predictor, scene)
    timeline = None if args.json else Timeline(scene)
    if args.sim != "mujoco" and args.frames is not None:
        raise HltlError("--frames needs the 3D simulator: add --sim mujoco")
    if args.sim != "mujoco" and args.perception == "camera":
        raise HltlError("--perception camera needs the 3D simulator: add --sim mujoco")
    if args.objects is not None and args.perception != "camera":
        raise HltlError("--objects chooses the camera's object backend: add --perception camera")
    extra: dict[str, Any] = {}
    recorder = None
    if args.sim == "mujoco":
        extra, recorder = simulator_options(
            scene, args.timing, args.frames, args.perception, args.objects or "segmentation"
        )
    grounder = make_grounder(args.grounder)
    if args.motion:
        extra.update(_motion_options(scene, spec, config, predictor, extra.get("simulator")))
    bus = None
    if args.bus is None and args.realtime is not None:
        raise HltlError("--realtime runs the cell on a node's clock: add --bus zenoh")
    if args.bus is not None:
        bus = BusSimulator(args)
        extra["simulator"] = bus.factory
    if getattr(args, "program", False):
        # set up: the process's heap (modules, the scene, the grounder's tables, the bus
        # session) lives as long as the episode, so the collector's full collections no longer
        # walk it (docs/bus.md, "Where the time goes (session 27)"); not when called in a
        # process that goes on (tests)
        gc.freeze()
    try:
        episode = run_episode(
            scene,
            spec=spec,
            instruction=args.instruction,
            events=events,
            seed=args.seed,
            config=config,
            grounder=grounder,
            predictor=predictor,
            log_path=args.log,
            on_record=None if timeline is None else timeline,
            **extra,
        )
    finally:
        # also when the episode failed (no node answers): an open session's subscriptions run
        # their callbacks on threads that keep the process from exiting
        if bus is not None:
            bus.close()
    if recorder is not None:
        recorder.close()
        if not args.json:
            print(f"frames: {recorder.frames} in {args.frames}", file=sys.stderr)
    if args.json:
        print(json.dumps(episode.metrics.to_dict()))
    else:
        print_metrics(episode.metrics.to_dict())
    if not episode.success:
        print(f"error: episode failed: {episode.metrics.reason}", file=sys.stderr)
        return 1
    return 0


def _motion_options(
    scene: Any, spec: Any, config: Any, predictor: Any, simulator: Any = None
) -> dict[str, Any]:
    """``run_episode`` keywords that put the motion layer under the simulator (``simulator``, a
    factory taking ``cost`` and ``kinematics``, default the discrete one) and the executor."""
    import functools

    kinematics, cost = motion_models(scene)

    def agent(sim: Any, log: Any) -> Executor:
        return Executor(
            scene,
            spec,
            sim,
            log=log,
            predictor=predictor,
            config=config.executor,
            cost=cost,
            kinematics=kinematics,
        )

    base = Simulator if simulator is None else simulator
    return {
        "simulator": functools.partial(base, cost=cost, kinematics=kinematics),
        "agent": agent,
    }


class Timeline:
    """Prints the interesting log records as they happen."""

    def __init__(self, scene: Any) -> None:
        from rich.console import Console

        self.scene = scene
        self.console = Console(highlight=False)

    def __call__(self, rec: LogRecord) -> None:
        line = describe_record(self.scene, rec)
        if line is not None:
            style, text = line
            self.console.print(f"[dim]{rec.t:7.2f}[/] [{style}]{rec.type:<13}[/] {text}")


def describe_record(scene: Any, rec: LogRecord) -> tuple[str, str] | None:
    """(style, text) for a log record worth showing, or None."""

    def act(d: dict[str, Any] | None) -> str:
        return "?" if d is None else describe_action(scene, Action.from_dict(d))

    match rec:
        case elog.Grounding(error=str() as error):
            return "red", f"{rec.text!r}: {error}"
        case elog.Grounding():
            n = len((rec.spec or {}).get("formulas", ()))
            return "cyan", f"{rec.text!r} → {rec.tokens} tokens, {n} formulas"
        case elog.Replan() | elog.PolicyReplan() if rec.status != "solved":
            return "yellow", f"{rec.trigger}: {rec.status} ({rec.reason or ''})"
        case elog.Replan():
            return (
                "blue",
                f"{rec.trigger} ({rec.source}): makespan {rec.makespan or 0.0:.2f} s, "
                f"{_steps(len(rec.steps))}, {rec.latency_ms:.1f} ms"
                + (
                    f", {rec.charged_s * 1000:.1f} ms charged ({rec.charge})"
                    if rec.charged_s
                    else ""
                ),
            )
        case elog.PolicyReplan():
            return "blue", f"{rec.trigger} ({rec.source}): {_steps(len(rec.steps))}"
        case elog.Dispatch():
            return "bold", " | ".join(act(a) for a in rec.actions) or "(empty step)"
        case elog.ActionDone():
            return "green", act(rec.action)
        case elog.ActionFailed() | elog.ActionHalted():
            return "red", f"{act(rec.action)}: {rec.reason}"
        case elog.Halt():
            return "bold red", f"{rec.kind}: {rec.reason}"
        case elog.Takeover():
            return (
                "magenta",
                f"predicted plan from t={rec.predicted_at or 0.0:.2f} takes over ({rec.context})",
            )
        case elog.Anticipate():
            return (
                "magenta",
                f"anticipating {rec.context}: "
                + ", ".join(act(a) for a in rec.actions)
                + " (valid now and in the forecast world)",
            )
        case elog.Predict():
            people = ", ".join(f"{h} → {{{','.join(p['robots'])}}}" for h, p in rec.humans.items())
            # two background plans per forecast: one from the current world, one from the world
            # after the running step; say which, or the lines look like duplicates
            basis = _BASIS.get(str(rec.basis), "")
            result = str(rec.status)
            if rec.makespan is not None and result == "solved":
                result += f", makespan {float(rec.makespan):.2f} s"
            return "magenta", f"background plan for {people}{basis}: {result}"
        case elog.Monitor() if rec.fired:
            return "green", f"fired {', '.join(rec.fired)}" + (
                " — task complete" if rec.accepted else ""
            )
        case elog.HumanMove():
            return "yellow", f"{rec.human} walks to {rec.to} at {rec.speed} m/s"
        case elog.ObjectMove():
            return "yellow", f"{rec.object} moved to {rec.to}" + (
                "" if rec.applied else f" (ignored: {rec.reason})"
            )
        case elog.ObjectDrop():
            return "yellow", f"{rec.object} dropped at {rec.position}"
        case elog.RobotDown(until=None):  # lost on the bus: no known return
            return "yellow", f"{rec.robot}: {rec.reason or 'down'}"
        case elog.RobotDown(until=float() | int() as until):
            return "yellow", f"{rec.robot} until t={until:.2f}"
        case elog.RobotUp():
            return "yellow", rec.robot
        case elog.InstructionGiven():
            return "cyan", repr(rec.text)
        case elog.Wait():
            return "yellow", rec.reason
        case elog.GiveUp():
            return "bold red", rec.reason
        case elog.Contact():
            return "bold red", f"{rec.robot} touches {rec.human} ({rec.part})"
        case elog.Violation():
            return "bold red", f"{act(rec.action)}: {rec.reason}"
        case elog.EpisodeEnd():
            return ("bold green" if rec.success else "bold red"), rec.reason
    return None


_BASIS = {"now": " (from now)", "after_step": " (after the running step)"}


def _steps(n: int) -> str:
    return f"{n} step" if n == 1 else f"{n} steps"


def print_metrics(metrics: dict[str, Any]) -> None:
    """The metrics as a two-column table."""
    from rich.console import Console
    from rich.table import Table

    table = Table(title="metrics", title_justify="left")
    table.add_column("metric")
    table.add_column("value", justify="right")
    for k, v in metrics.items():
        if isinstance(v, float):
            text = f"{v:.2f}"
        elif v is None:
            text = "—"
        else:
            text = str(v)
        table.add_row(k, text)
    Console().print(table)
