"""Helpers shared by CLI commands: loading specs or grounding instructions, printing plans."""

from __future__ import annotations

import math
from pathlib import Path
from typing import TYPE_CHECKING

from hltl.errors import HltlError
from hltl.spec.hierarchy import HSpec, load_spec
from hltl.world.scene import Scene

if TYPE_CHECKING:
    # why: the annotation only; importing the planner is the plan command's to pay
    from hltl.planner.result import PlanResult


def check_option(name: str, value: float, *, positive: bool = False) -> float:
    """A numeric option's value if it is finite and >= 0 (> 0 with ``positive``).

    argparse's ``float`` reads "nan" and "inf"; no time, noise or latency is either.

    Raises:
        HltlError: naming the option, the value and what was expected.
    """
    if not math.isfinite(value) or value < 0 or (positive and value == 0):
        want = "a finite number > 0" if positive else "a finite number >= 0"
        raise HltlError(f"{name}: expected {want}, got {value!r}")
    return value


def load_spec_or_ground(
    scene: Scene, spec_path: Path | None, instruction: str | None, grounder: str = "offline"
) -> HSpec:
    """The spec from a file, or the instruction grounded in the scene."""
    if spec_path is not None:
        return load_spec(spec_path)
    if instruction is None:
        raise HltlError("give --spec FILE or --instruction TEXT")
    # why: a spec file needs no grounder (the grounding package is ~10 ms of start-up)
    from hltl.grounding import make_grounder
    from hltl.grounding.base import check_instruction  # why: as above

    check_instruction(instruction, "--instruction")
    spec: HSpec = make_grounder(grounder).ground(instruction, scene).spec
    return spec


def describe_action(scene: Scene, action: object) -> str:
    """One action in words: 'r1 hands bottle to Person A'."""
    # why: the commands that print no plan need no skill library
    from hltl.skills.library import Action

    assert isinstance(action, Action)
    rs = action.robots
    if action.skill == "pick":
        return f"{rs[0]} picks {action.object}"
    if action.skill == "place":
        return f"{rs[0]} places {action.object} on {action.surface}"
    if action.skill == "handover_r2r":
        return f"{rs[0]} hands {action.object} to {rs[1]}"
    if action.skill == "handover_r2h" and action.human is not None:
        name = scene.human(action.human).name
        return f"{rs[0]} hands {action.object} to {name}"
    return str(action)


def print_plan_timeline(result: PlanResult, scene: Scene) -> None:
    """A readable timeline: one row per step with who does what, when, and for which leaf."""
    from rich.console import Console
    from rich.table import Table

    console = Console()
    if not result.solved:
        console.print(f"[bold red]{result.status.value}[/]: {result.reason}")
        if not result.steps:
            return
    table = Table(title=f"plan — makespan {result.makespan:.2f} s", title_justify="left")
    table.add_column("step", justify="right")
    table.add_column("start", justify="right")
    table.add_column("dur", justify="right")
    table.add_column("actions")
    table.add_column("bindings (leaf/role)")
    for i, step in enumerate(result.steps):
        actions = "\n".join(describe_action(scene, a) for a in step.actions) or "(wait)"
        binds = "  ".join(f"{b.robot}:{b.leaf}/{b.role}" for b in step.bindings)
        table.add_row(str(i), f"{step.start:.2f}", f"{step.duration:.2f}", actions, binds)
    console.print(table)
    s = result.stats
    console.print(
        f"[dim]{s.algorithm}: {s.expanded} nodes expanded, {s.generated} generated, "
        f"{s.seconds * 1000:.1f} ms[/]"
    )
