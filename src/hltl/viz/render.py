"""Which pictures a file makes and where they go (what ``hltl viz`` does)."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from hltl.errors import HltlError
from hltl.spec.printer import to_string
from hltl.viz._mpl import MOVING_FORMATS, STILL_FORMATS, save_figure
from hltl.viz.animate import animate, draw_frame, require_ffmpeg, save_animation
from hltl.viz.files import Source, load_source, plan_scene
from hltl.viz.gantt import gantt
from hltl.viz.spec_tree import dfa_diagram, node_dfas, spec_tree
from hltl.viz.track import track_from_log, track_from_plan

KNOWN_FORMATS = STILL_FORMATS + MOVING_FORMATS


@dataclass(frozen=True, slots=True)
class RenderOptions:
    """What to draw beyond the defaults.

    Attributes:
        format: ``png``/``svg`` (still pictures only) or ``gif``/``html``/``mp4`` (the animation
            only); ``None``: the defaults of the file's kind, or the suffix of ``out``.
        scene: the scene file of a plan (default: the one the plan names).
        animate: also animate a plan (replayed on its scene).
        node: also draw the DFA of this node of a spec.
        frame: instead, draw the animation's still frame at this time (seconds).
        fps: animation frames per simulated second.
        max_frames: most animation frames.
    """

    format: str | None = None
    scene: Path | None = None
    animate: bool = False
    node: str | None = None
    frame: float | None = None
    fps: int = 10
    max_frames: int = 200


def render_file(path: str | Path, out: str | Path | None, opts: RenderOptions) -> list[Path]:
    """Draw a plan (Gantt; replay animation with ``animate``), a log (Gantt and animation) or a
    spec (tree; a node's DFA with ``node``), dispatching on the file's content.

    ``out`` is a file when one picture is made and it has a suffix; otherwise a folder (made if
    needed) that gets ``<stem>_gantt.png``, ``<stem>_anim.gif``, ``<stem>_tree.png``,
    ``<stem>_<node>_dfa.png``, ``<stem>_frame.png``. Default: the current folder.

    Returns:
        The paths written.

    Raises:
        PlanFormatError: the file is none of the three formats (naming it and what was expected).
        HltlError: a format that does not suit the file, or ``out`` names one file for several
            pictures.
        BackendUnavailableError: matplotlib (or ffmpeg for MP4) is missing.
    """
    src = load_source(path)
    out_path = None if out is None else Path(out)
    fmt = opts.format
    if fmt is None and out_path is not None and out_path.suffix:
        fmt = out_path.suffix.lstrip(".").lower()
    if fmt is not None and fmt not in KNOWN_FORMATS:
        known = ", ".join(KNOWN_FORMATS)
        raise HltlError(
            f"{out_path}: unknown picture format {fmt!r} (from the suffix); expected one of "
            f"{known}, or a folder"
        )
    still = fmt is None or fmt in STILL_FORMATS
    moving = fmt in MOVING_FORMATS or (
        fmt is None and (src.kind == "log" or (src.kind == "plan" and opts.animate))
    )
    if src.kind == "spec" and moving:
        raise HltlError(f"{src.path}: a spec tree is a still picture; use --format png or svg")
    if src.kind == "plan" and opts.animate and fmt in STILL_FORMATS:
        raise HltlError(f"--animate writes an animation; use --format {'/'.join(MOVING_FORMATS)}")
    if opts.node is not None and src.kind != "spec":
        raise HltlError(f"--node draws a node's DFA of a spec; {src.path} is a {src.kind}")
    if opts.scene is not None and src.kind != "plan":
        raise HltlError(f"--scene is for plans; a {src.kind} carries everything it needs")
    if opts.frame is not None:
        if src.kind == "spec":
            raise HltlError(f"--frame draws a moment of a plan or log; {src.path} is a spec")
        if fmt in MOVING_FORMATS:
            raise HltlError("--frame draws a still picture; use --format png or svg")
        if opts.frame < 0:
            raise HltlError(f"--frame must be a time >= 0 (seconds), got {opts.frame}")
        still, moving = False, False

    jobs: list[tuple[str, str]] = []  # (picture, format)
    if still:
        jobs.append(("tree" if src.kind == "spec" else "gantt", fmt or "png"))
        if opts.node is not None:
            jobs.append(("dfa", fmt or "png"))
    if moving:
        jobs.append(("anim", fmt if fmt in MOVING_FORMATS else "gif"))
    if opts.frame is not None:
        jobs.append(("frame", fmt or "png"))

    if ("anim", "mp4") in jobs:
        require_ffmpeg()  # before drawing anything
    if out_path is not None and out_path.suffix and len(jobs) > 1:
        hint = " (or pick one with --format)" if any(j == "anim" for j, _ in jobs) else ""
        raise HltlError(
            f"{out_path} names one file but {src.path} makes {len(jobs)} pictures "
            f"({', '.join(j for j, _ in jobs)}); give a folder{hint}"
        )
    single = out_path is not None and bool(out_path.suffix)
    folder = Path(".") if out_path is None else (out_path.parent if single else out_path)

    def target(job: str, ext: str) -> Path:
        if single:
            assert out_path is not None
            return out_path
        suffix = f"{opts.node}_dfa" if job == "dfa" else job
        return folder / f"{src.path.stem}_{suffix}.{ext}"

    written: list[Path] = []
    for job, ext in jobs:
        written.append(_draw(src, job, ext, target(job, ext), opts))
    return written


def _draw(src: Source, job: str, ext: str, dest: Path, opts: RenderOptions) -> Path:
    if job == "tree":
        assert src.spec is not None
        return save_figure(spec_tree(src.spec), dest, format=ext)
    if job == "dfa":
        assert src.spec is not None
        if opts.node is None or opts.node not in src.spec.names:
            raise HltlError(
                f"{src.path}: no formula {opts.node!r}; the spec has {', '.join(src.spec.names)}"
            )

        dfa = node_dfas(src.spec)[opts.node]
        title = f"{opts.node}: {to_string(src.spec.formula(opts.node))}"
        return save_figure(dfa_diagram(dfa, title=title), dest, format=ext)

    if src.kind == "log":
        track = track_from_log(src.records)
    else:
        track = track_from_plan(src.plan or {}, plan_scene(src, opts.scene))
    if job == "gantt":
        return save_figure(gantt(track), dest, format=ext)
    if job == "frame":
        assert opts.frame is not None
        return save_figure(draw_frame(track, opts.frame), dest, format=ext)

    anim = animate(track, fps=opts.fps, max_frames=opts.max_frames)
    return save_animation(anim, dest, format=ext)
