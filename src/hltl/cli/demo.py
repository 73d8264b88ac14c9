"""``hltl demo``: the paper's Fig. 1 episode end to end, with a live timeline, metrics, pictures."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path
from typing import Any

from hltl.cli.run import Timeline
from hltl.sim.events import load_events
from hltl.viz.demo import DEFAULT_OUT, DEMO_INSTRUCTION, DemoResult, demo_scene, run_demo
from hltl.viz.demo3d import run_demo3d
from hltl.world.scene import Scene, load_scene


def register(sub: Any) -> None:
    p: argparse.ArgumentParser = sub.add_parser(
        "demo",
        help="run the paper's Fig. 1 episode and draw it",
        description="Two arms of different reach are told to give Person A the bottle and "
        "Person B the chips. Person A walks over to the other arm's side: predictive planning "
        "starts in the background, the handover to A is halted before its precondition breaks, "
        "the predicted suffix takes over and both deliveries succeed. Prints a live timeline, a "
        "summary and the pictures written (Gantt chart, animation, a frame, the spec tree). "
        "Exit 0 when every goal is met.",
    )
    p.add_argument(
        "--instruction", default=DEMO_INSTRUCTION, help=f"the task (default: {DEMO_INSTRUCTION!r})"
    )
    p.add_argument("--scene", type=Path, help="scene file (default: the embedded Fig. 1 cell)")
    p.add_argument("--seed", type=int, default=0, help="seed of noise and failures (default 0)")
    p.add_argument(
        "--events", type=Path, help="events file (default: the demo's, examples/events/demo.yaml)"
    )
    p.add_argument(
        "--out", type=Path, default=DEFAULT_OUT, help=f"folder for log and pictures ({DEFAULT_OUT})"
    )
    p.add_argument("--short", action="store_true", help="few, small animation frames (quick)")
    p.add_argument("--no-pictures", action="store_true", help="run and summarise only")
    p.add_argument(
        "--3d",
        dest="three_d",
        action="store_true",
        help="run in the 3D simulator (MuJoCo) and render a video from the fixed camera and an "
        "orbit view with the timeline (demo3d.mp4, demo3d.gif, a PNG frame); sim3d extra",
    )
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    from rich.console import Console

    console = Console(highlight=False)
    scene = load_scene(args.scene) if args.scene is not None else demo_scene()
    events = None
    if args.events is not None:
        events = load_events(args.events, scene)
    _header(console, scene, args.instruction, args.events)
    common: dict[str, Any] = {
        "scene": scene,
        "instruction": args.instruction,
        "events": events,
        "seed": args.seed,
        "out": args.out,
        "short": args.short,
        "on_record": Timeline(scene),
    }
    result = _run_3d(common) if args.three_d else run_demo(pictures=not args.no_pictures, **common)
    _summary(console, result)
    default_story = (
        args.events is None and args.scene is None and args.instruction == DEMO_INSTRUCTION
    )
    _story(console, result, warn=default_story)
    # paths on one line each, never wrapped, so that they can be copied
    console.print(f"[bold]log[/]      {result.log_path}", soft_wrap=True)
    for what, path in result.pictures:
        console.print(f"[bold]picture[/]  {path}  [dim]({what})[/]", soft_wrap=True)
    if not result.episode.success:
        print(f"error: demo episode failed: {result.episode.metrics.reason}", file=sys.stderr)
        return 1
    return 0


def _run_3d(common: dict[str, Any]) -> DemoResult:
    from rich.progress import Progress

    with Progress(transient=True) as bar:
        task = bar.add_task("rendering 3D frames", total=None)

        def progress(done: int, total: int) -> None:
            bar.update(task, completed=done, total=total)

        return run_demo3d(progress=progress, **common)


def _header(console: Any, scene: Scene, instruction: str, events: Path | None) -> None:
    arms = ", ".join(f"{r.id} ({r.model}, reach {r.reach:.1f} m)" for r in scene.robots)
    console.rule("[bold]hltl demo[/] — the paper's Fig. 1 episode")
    console.print(f"[bold]instruction[/] {instruction!r}")
    console.print(f"[bold]cell[/]        {arms}; people {', '.join(scene.human_ids)}")
    console.print(
        f"[bold]events[/]      {events if events is not None else 'the demo default'}; "
        "offline grounder, exact A* planner, simulator"
    )
    console.rule()


def _summary(console: Any, result: DemoResult) -> None:
    from rich.table import Table

    m = result.episode.metrics

    def pct(v: float | None) -> str:
        return "—" if v is None else f"{v:.1f} %"

    def ms(v: float | None) -> str:
        return "—" if v is None else f"{v:.2f} ms"

    planned = "—" if result.planned_makespan is None else f"{result.planned_makespan:.2f} s"
    table = Table(title="summary", title_justify="left")
    table.add_column("")
    table.add_column("value", justify="right")
    table.add_column("what it is", style="dim")
    rows = [
        ("outcome", "success" if m.success else "failed", m.reason),
        ("time cost", f"{m.time_cost:.2f} s", "until the root monitor accepted"),
        ("planned makespan", planned, "of the first plan, before anybody moved"),
        ("halts", str(m.halts), "actions stopped by reactive safety"),
        ("replans", str(m.replans), "caused by disruptions (not routine steps)"),
        ("takeovers", str(m.takeovers), "predicted suffix switched in"),
        ("planner calls", str(m.planner_calls), "on the critical path"),
        ("replan latency median", ms(m.replan_latency_median_ms), "wall clock"),
        ("replan latency p95", ms(m.replan_latency_p95_ms), "wall clock"),
        ("tokens", str(m.tokens), "grounding (0 offline)"),
        ("deliveries", str(m.deliveries), "objects handed to people"),
        ("H-IDLE", pct(m.h_idle), "people idle, not being handed anything"),
        ("H-IDLE walk=active", pct(m.h_idle_walk_active), "the same, walking counted as active"),
        ("R-IDLE", pct(m.r_idle), "robots idle, no action running"),
        ("C-ACT", pct(m.c_act), "time with two or more agents active"),
        ("C-ACT H–R", pct(m.c_act_hr), "time a person and a robot are active at once"),
        ("F-DEL Σ", pct(m.f_del), "hand-off delays summed over objects"),
        ("F-DEL ∪", pct(m.f_del_union), "time some object waits (a union over objects)"),
    ]
    for row in rows:
        table.add_row(*row)
    console.print(table)


def _story(console: Any, result: DemoResult, *, warn: bool) -> None:
    console.print("[bold]story[/]")
    for beat, ok in result.story.items():
        console.print(f"  [green]✓[/] {beat}" if ok else f"  [red]✗[/] {beat}")
    if warn and not all(result.story.values()):
        console.print(
            "[bold yellow]warning:[/] the default demo no longer shows the Fig. 1 story "
            "(see the ✗ above); the executor or simulator changed — adjust "
            "FIG1_EVENTS in hltl.sim.dynamic"
        )
