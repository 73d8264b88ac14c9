"""The paper's Fig. 1 episode end to end: ground, plan, execute with a person walking, draw it."""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path

from hltl.execution import log
from hltl.execution.log import EpisodeStart, Grounding, LogRecord, Replan
from hltl.grounding import make_grounder
from hltl.sim.dynamic import fig1_events
from hltl.sim.episode import Episode, run_episode
from hltl.sim.events import EventSchedule
from hltl.sim.scenarios import fig1
from hltl.spec.hierarchy import HSpec, spec_from_dict
from hltl.viz._mpl import pyplot, save_figure
from hltl.viz.animate import animate, draw_frame, save_animation
from hltl.viz.gantt import gantt
from hltl.viz.spec_tree import spec_tree
from hltl.viz.track import track_from_log
from hltl.world.scene import Scene

DEMO_INSTRUCTION = "Give Person A the bottle and Person B the chips"
DEFAULT_OUT = Path("out/demo")


def demo_scene() -> Scene:
    """The Fig. 1 cell (the scene of examples/scenes/two_arms.yaml), embedded in hltl."""
    return fig1().scene


def demo_events(scene: Scene) -> EventSchedule:
    """The demo's events (Person A walks over to r2's side during the handovers)."""
    return fig1_events(scene)


def story(records: Sequence[LogRecord]) -> dict[str, bool]:
    """Which beats of the Fig. 1 story the log shows (each should be ``True``)."""
    halts = [r for r in records if isinstance(r, log.Halt) and r.reason.strip()]
    first_halt = halts[0].t if halts else float("inf")
    replans = [
        r
        for r in records
        if isinstance(r, log.REPLANS) and set(r.trigger.split("+")) - {"initial", "progress"}
    ]
    switched = any(isinstance(r, log.Takeover) for r in records) or any(
        "halt" in r.trigger and r.status == "solved" for r in replans
    )
    ends = [r for r in records if isinstance(r, log.EpisodeEnd)]
    return {
        "background plan while a person walks": any(
            isinstance(r, log.Predict) and r.status == "solved" and r.t <= first_halt
            for r in records
        ),
        "halt with a reason": bool(halts),
        "replan after the halt": any(r.t >= first_halt for r in replans),
        "takeover or suffix switch": switched,
        "both deliveries, success": bool(ends) and bool(ends[-1].success),
    }


@dataclass(frozen=True, slots=True)
class DemoResult:
    """What the demo did.

    Attributes:
        episode: the episode's log and metrics.
        log_path: the JSON Lines log written.
        pictures: (what, path) of each picture written.
        spec: the H-LTLf spec the instruction was grounded into.
        story: the beats of the Fig. 1 story and whether the log shows them.
        planned_makespan: the makespan of the first plan (before anybody moved).
    """

    episode: Episode
    log_path: Path
    pictures: tuple[tuple[str, Path], ...]
    spec: HSpec | None
    story: dict[str, bool]
    planned_makespan: float | None


def run_demo(
    *,
    scene: Scene | None = None,
    instruction: str = DEMO_INSTRUCTION,
    events: EventSchedule | None = None,
    seed: int = 0,
    out: str | Path = DEFAULT_OUT,
    short: bool = False,
    pictures: bool = True,
    on_record: Callable[[LogRecord], None] | None = None,
) -> DemoResult:
    """Run the demo episode in the simulator and draw it.

    Args:
        scene: the cell (default: the embedded Fig. 1 cell).
        instruction: the task in English (grounded offline).
        events: dynamic events (default: :data:`hltl.sim.dynamic.FIG1_EVENTS` on ``scene``).
        seed: the episode's seed.
        out: folder for the log and the pictures.
        short: fewer, smaller animation frames (quick, for tests).
        pictures: draw the pictures (Gantt PNG, animation GIF, a frame PNG, spec tree PNG).
        on_record: called with each log record as it is written (a live timeline).

    Raises:
        BackendUnavailableError: ``pictures`` and matplotlib is missing (checked before the run).
    """
    if pictures:
        pyplot()  # fail before the episode, not after it
    cell = demo_scene() if scene is None else scene
    schedule = demo_events(cell) if events is None else events
    folder = Path(out)
    folder.mkdir(parents=True, exist_ok=True)
    log_path = folder / "episode.jsonl"
    episode = run_episode(
        cell,
        instruction=instruction,
        events=schedule,
        seed=seed,
        grounder=make_grounder("offline"),
        log_path=log_path,
        on_record=on_record,
    )
    records = episode.records
    spec = _grounded_spec(records)
    drawn = draw_episode(records, spec, folder, short=short) if pictures else ()
    return DemoResult(episode, log_path, drawn, spec, story(records), first_makespan(records))


def first_makespan(records: Sequence[LogRecord]) -> float | None:
    """The makespan of the episode's first solved plan (what was planned before anything
    happened), or None."""
    for r in records:
        if isinstance(r, Replan) and r.status == "solved" and r.makespan is not None:
            return float(r.makespan)
    return None


def draw_episode(
    records: Sequence[LogRecord], spec: HSpec | None, folder: Path, *, short: bool = False
) -> tuple[tuple[str, Path], ...]:
    """The demo's pictures of an episode: Gantt chart, animation, the frame at the first halt
    (or mid-episode), the spec tree."""
    track = track_from_log(records)
    out: list[tuple[str, Path]] = [("Gantt chart", save_figure(gantt(track), folder / "gantt.png"))]
    fps, frames, dpi = (5, 12, 55.0) if short else (10, 200, 80.0)
    anim = animate(track, fps=fps, max_frames=frames, dpi=dpi)
    out.append(("animation", save_animation(anim, folder / "animation.gif")))
    halts = [m.t for m in track.markers if m.kind == "halt"]
    t_frame = halts[0] + 0.02 if halts else track.end / 2
    frame = draw_frame(track, t_frame)
    out.append((f"frame at t={t_frame:.2f} s", save_figure(frame, folder / "frame.png")))
    if spec is not None:
        out.append(("spec tree", save_figure(spec_tree(spec), folder / "spec_tree.png")))
    return tuple(out)


def _grounded_spec(records: Sequence[LogRecord]) -> HSpec | None:
    """The last spec the episode ran (grounded, or given up front)."""
    data = None
    for r in records:
        if isinstance(r, EpisodeStart | Grounding) and r.spec:
            data = r.spec
    return None if data is None else spec_from_dict(data, "the episode's spec")
