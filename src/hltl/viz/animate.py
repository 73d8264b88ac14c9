"""Top-down animations of an executed episode (from its log) or of a plan replayed on its scene."""

from __future__ import annotations

import math
import shutil
import textwrap
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

from hltl.errors import BackendUnavailableError
from hltl.execution.log import LogRecord
from hltl.planner.result import PlanResult
from hltl.viz._mpl import MARKER_STYLES, MOVING_FORMATS, format_of, pyplot
from hltl.viz.track import (
    ActionSpan,
    Marker,
    Track,
    describe_action,
    track_from_log,
    track_from_plan,
)
from hltl.world.geometry import context_label
from hltl.world.scene import Scene

if TYPE_CHECKING:
    from matplotlib.animation import FuncAnimation
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

DEFAULT_FPS = 10
MAX_FRAMES = 200
ROBOT_COLORS = ("#0072B2", "#E69F00", "#009E73", "#CC79A7", "#56B4E9", "#D55E00")
HUMAN_COLORS = ("#AA3377", "#66CCEE", "#228833", "#CCBB44", "#4477AA", "#EE6677")
OBJECT_COLOR = "#D55E00"
# How long (s) an event stays in the status line, and a forecast arrow on screen.
STATUS_HOLD = 0.6
PREDICTION_HOLD = 0.5


def animate_episode(records: Sequence[LogRecord], **kwargs: Any) -> FuncAnimation:
    """Animate an executed episode from its log records; see :func:`animate`."""
    return animate(track_from_log(records), **kwargs)


def animate_plan(
    plan: PlanResult | Mapping[str, Any], scene: Scene, **kwargs: Any
) -> FuncAnimation:
    """Animate a plan replayed on its scene (people stand still); see :func:`animate`."""
    return animate(track_from_plan(plan, scene), **kwargs)


def frame_times(
    track: Track, *, fps: int = DEFAULT_FPS, max_frames: int = MAX_FRAMES, tail: float = 0.5
) -> list[float]:
    """The times shown: ``fps`` frames per simulated second up to ``max_frames`` (the clock then
    runs faster than real time), from 0 to the end plus ``tail`` seconds of the final state."""
    if fps <= 0 or max_frames < 2:
        raise ValueError(f"need fps > 0 and max_frames >= 2, got {fps!r} and {max_frames!r}")
    duration = max(track.end, 0.0) + tail
    n = min(max_frames, max(2, math.floor(duration * fps) + 1))
    return [duration * k / (n - 1) for k in range(n)]


def animate(
    track: Track,
    *,
    fps: int = DEFAULT_FPS,
    max_frames: int = MAX_FRAMES,
    dpi: float = 80.0,
) -> FuncAnimation:
    """A top-down animation of a :class:`Track` (matplotlib ``FuncAnimation``, not yet saved).

    Args:
        track: the plan or episode.
        fps: frames per simulated second (and the playback rate).
        max_frames: at most this many frames; longer episodes play faster than real time.
        dpi: resolution of the frames.
    """
    plt = pyplot()
    from matplotlib.animation import FuncAnimation

    times = frame_times(track, fps=fps, max_frames=max_frames)
    fig, update = _scene_figure(track, dpi=dpi)
    anim = FuncAnimation(
        fig,
        lambda i: update(times[i]),
        frames=len(times),
        interval=1000.0 / fps,
        blit=False,
        repeat=False,
    )
    anim._hltl_fps = fps  # type: ignore[attr-defined]  # read back by save_animation
    plt.close(fig)  # the animation keeps the figure; nothing should show it
    return anim


def draw_frame(track: Track, t: float, *, dpi: float = 110.0) -> Figure:
    """The animation's still frame at time ``t`` (for documents, and to look at)."""
    fig, update = _scene_figure(track, dpi=dpi)
    update(t)
    return fig


def save_animation(
    anim: FuncAnimation, path: str | Path, *, format: str | None = None, fps: int | None = None
) -> Path:
    """Write an animation as GIF (pillow), HTML (``to_jshtml``) or MP4 (needs ffmpeg).

    Raises:
        BackendUnavailableError: MP4 asked for but ffmpeg is not on PATH.
        HltlError: an unknown format.
    """
    p = Path(path)
    fmt = format_of(p, format, MOVING_FORMATS)
    rate = fps if fps is not None else int(getattr(anim, "_hltl_fps", DEFAULT_FPS))
    p.parent.mkdir(parents=True, exist_ok=True)
    if fmt == "gif":
        from matplotlib.animation import PillowWriter

        anim.save(str(p), writer=PillowWriter(fps=rate))
    elif fmt == "html":
        p.write_text(anim.to_jshtml(fps=rate, default_mode="once"), encoding="utf-8")
    else:
        from matplotlib.animation import FFMpegWriter

        require_ffmpeg()
        anim.save(str(p), writer=FFMpegWriter(fps=rate))
    return p


def require_ffmpeg() -> None:
    """Raise unless ffmpeg (for MP4) is on PATH.

    Raises:
        BackendUnavailableError: naming what to install and the formats that work without it.
    """
    if shutil.which("ffmpeg") is None:
        raise BackendUnavailableError(
            "MP4 needs ffmpeg, which is not on PATH (apt-get install ffmpeg); "
            "write --format gif or html instead"
        )


# -- the drawing ----------------------------------------------------------------------------------


def _bounds(track: Track) -> tuple[float, float, float, float]:
    scene = track.scene
    xs: list[float] = []
    ys: list[float] = []
    for r in scene.robots:
        m = r.reach + scene.human_reach
        xs += [r.base[0] - m, r.base[0] + m]
        ys += [r.base[1] - m, r.base[1] + m]
    for h in scene.humans:
        xs.append(h.position[0])
        ys.append(h.position[1])
    for _, segs in track.walks:
        for s in segs:
            xs += [s.p0[0], s.p1[0]]
            ys += [s.p0[1], s.p1[1]]
    for o in scene.objects:
        xs.append(o.position[0])
        ys.append(o.position[1])
    pad = 0.2
    return min(xs) - pad, max(xs) + pad, min(ys) - pad, max(ys) + pad


def _scene_figure(track: Track, *, dpi: float) -> tuple[Figure, Any]:
    """The figure with the static scene drawn, and ``update(t)`` that moves everything to ``t``."""
    plt = pyplot()
    from matplotlib.patches import Circle, Rectangle

    scene = track.scene
    x0, x1, y0, y1 = _bounds(track)
    width = 7.2
    header, footer = 1.0, 0.5  # inches for the clock, step and status lines; the x label
    height = min(8.0, max(4.0, 0.9 * width * (y1 - y0) / (x1 - x0) + header + footer))
    fig: Figure = plt.figure(figsize=(width, height), dpi=dpi)
    ax: Axes = fig.add_axes((0.08, footer / height, 0.9, (height - header - footer) / height))
    ax.set_xlim(x0, x1)
    ax.set_ylim(y0, y1)
    ax.set_aspect("equal", adjustable="box")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.tick_params(labelsize=8)
    ax.grid(color="#eeeeee", linewidth=0.6)
    ax.set_axisbelow(True)

    for s in scene.surfaces:
        ax.add_patch(
            Rectangle(
                (s.center[0] - s.size[0] / 2, s.center[1] - s.size[1] / 2),
                s.size[0],
                s.size[1],
                facecolor="#e8dcc8",
                edgecolor="#a08c6c",
                zorder=1,
            )
        )
        ax.text(*s.center[:2], s.id, ha="center", va="center", fontsize=7.5, color="#6b5a3e")

    robot_color = {r.id: ROBOT_COLORS[i % len(ROBOT_COLORS)] for i, r in enumerate(scene.robots)}
    reach_circles = {}
    for r in scene.robots:
        c = robot_color[r.id]
        reach_circles[r.id] = ax.add_patch(
            Circle(r.base[:2], r.reach, fill=False, edgecolor=c, linewidth=1.2, zorder=2)
        )
        ax.add_patch(
            Circle(
                r.base[:2],
                r.reach + scene.human_reach,
                facecolor=c,
                alpha=0.05,
                edgecolor="none",
                zorder=1,
            )
        )
        ax.add_patch(
            Circle(
                r.base[:2],
                r.reach + scene.human_reach,
                fill=False,
                edgecolor=c,
                linewidth=0.9,
                linestyle=":",
                zorder=2,
            )
        )
        ax.plot(*r.base[:2], marker="s", markersize=11, color="#333333", zorder=6)
        label = r.id if r.model == "generic" else f"{r.id} ({r.model})"
        ax.text(
            r.base[0],
            r.base[1] - 0.09,
            label,
            ha="center",
            va="top",
            fontsize=8,
            fontweight="bold",
            color=c,
            zorder=12,
            bbox={"boxstyle": "round,pad=0.15", "fc": "white", "ec": "none", "alpha": 0.75},
        )
    for _, _, p in track.rendezvous():
        ax.plot(*p[:2], marker="D", markersize=6, color="#8a5a00", alpha=0.8, zorder=3)

    arms = {
        r.id: ax.plot([], [], color=robot_color[r.id], linewidth=3.0, alpha=0.8, zorder=5)[0]
        for r in scene.robots
    }
    hands = {
        r.id: ax.plot(
            [],
            [],
            marker="o",
            markersize=8,
            color=robot_color[r.id],
            markeredgecolor="black",
            zorder=8,
        )[0]
        for r in scene.robots
    }
    human_color = {h.id: HUMAN_COLORS[i % len(HUMAN_COLORS)] for i, h in enumerate(scene.humans)}
    paths = {
        h.id: ax.plot([], [], color=human_color[h.id], linewidth=1.4, alpha=0.7, zorder=4)[0]
        for h in scene.humans
    }
    people = {
        h.id: ax.plot(
            [],
            [],
            marker="o",
            markersize=14,
            color=human_color[h.id],
            markeredgecolor="white",
            zorder=9,
        )[0]
        for h in scene.humans
    }
    people_text = {
        h.id: ax.text(0, 0, "", ha="center", va="bottom", fontsize=8, zorder=10)
        for h in scene.humans
    }
    forecasts = {
        h.id: ax.plot(
            [], [], color=human_color[h.id], linestyle="--", linewidth=1.2, alpha=0.9, zorder=4
        )[0]
        for h in scene.humans
    }
    forecast_ends = {
        h.id: ax.plot(
            [],
            [],
            marker="o",
            markersize=12,
            markerfacecolor="none",
            markeredgecolor=human_color[h.id],
            linestyle="none",
            zorder=4,
        )[0]
        for h in scene.humans
    }
    forecast_text = {
        h.id: ax.text(0, 0, "", fontsize=7, color=human_color[h.id], zorder=10)
        for h in scene.humans
    }
    objects = {
        o.id: ax.plot(
            [], [], marker="h", markersize=9, color=OBJECT_COLOR, markeredgecolor="black", zorder=11
        )[0]
        for o in scene.objects
    }
    object_text = {
        o.id: ax.text(0, 0, o.id, fontsize=7.5, ha="left", va="bottom", zorder=12)
        for o in scene.objects
    }

    def at(inches: float) -> float:
        return 1.0 - inches / height

    clock = fig.text(0.02, at(0.1), "", fontsize=10.5, fontweight="bold", va="top")
    step_text = fig.text(0.02, at(0.38), "", fontsize=8.5, va="top")
    status = fig.text(0.02, at(0.6), "", fontsize=8.5, va="top", linespacing=1.1)
    # gids name the moving artists, for whoever inspects a frame (tests, documents)
    for kind, group in (
        ("arm", arms),
        ("hand", hands),
        ("path", paths),
        ("person", people),
        ("forecast", forecasts),
        ("object", objects),
    ):
        for key, artist in group.items():
            artist.set_gid(f"{kind}:{key}")
    clock.set_gid("clock")
    step_text.set_gid("step")
    status.set_gid("status")
    fig.text(0.98, at(0.1), _clip(track.title, 80), fontsize=8, va="top", ha="right", color="#555")
    ax.legend(
        handles=_legend_handles(),
        loc="lower left",
        fontsize=6.5,
        framealpha=0.85,
        ncols=2,
    )

    def update(t: float) -> None:
        humans_now = {h.id: track.human_position(h.id, t) for h in scene.humans}
        served = context_label(scene, humans_now)
        for r in scene.robots:
            hx, hy, _ = track.hand_position(r.id, t)
            arms[r.id].set_data([r.base[0], hx], [r.base[1], hy])
            hands[r.id].set_data([hx], [hy])
            last = _last_span(track, r.id, t)
            busy = last is not None and last.start <= t < last.end
            stopped = last is not None and t >= last.end and last.outcome in ("halted", "failed")
            reach_circles[r.id].set_linewidth(2.2 if busy else 1.0)
            arms[r.id].set_linestyle("--" if stopped else "-")
            hands[r.id].set_markeredgecolor("#D55E00" if stopped else "black")
        for h in scene.humans:
            x, y, _ = humans_now[h.id]
            people[h.id].set_data([x], [y])
            path = track.human_path(h.id, t)
            paths[h.id].set_data([p[0] for p in path], [p[1] for p in path])
            robots = ",".join(sorted(served.robots_serving(h.id))) or "nobody"
            people_text[h.id].set_position((x, y + 0.07))
            people_text[h.id].set_text(f"{h.name}\nserved by {robots}")
            pred = _latest_prediction(track, h.id, t)
            if pred is None:
                forecasts[h.id].set_data([], [])
                forecast_ends[h.id].set_data([], [])
                forecast_text[h.id].set_text("")
            else:
                px, py, _ = pred.position
                forecasts[h.id].set_data([x, px], [y, py])
                forecast_ends[h.id].set_data([px], [py])
                forecast_text[h.id].set_position((px + 0.05, py - 0.02))
                label = ",".join(pred.robots) or "nobody"
                forecast_text[h.id].set_text(f"forecast: {label}")
        for o in scene.objects:
            kind, _, _ = track.object_place(o.id, t)
            ox, oy, _ = track.object_position(o.id, t)
            objects[o.id].set_data([ox], [oy])
            objects[o.id].set_alpha(0.6 if kind == "delivered" else 1.0)
            object_text[o.id].set_position((ox + 0.035, oy + 0.02))
            object_text[o.id].set_text(o.id + (" ✓" if kind == "delivered" else ""))
        clock.set_text(f"t = {t:5.2f} s")
        step = track.step_at(t)
        done = t >= track.end - 1e-9
        if step is None:
            step_text.set_text("")
        elif done and track.kind == "episode":
            verdict = "all goals met" if track.success else "gave up"
            step_text.set_text(f"{verdict} at {track.end:.2f} s")
        else:
            words = _step_words(track, step.index, t)
            step_text.set_text(_clip(f"step {step.index}: {words}", 110))
        m = _latest_marker(track.markers, t)
        if m is None:
            status.set_text("")
        else:
            color = MARKER_STYLES.get(m.kind, ("#333333", "-"))[0]
            status.set_color(color)
            detail = f": {m.detail}" if m.detail else ""
            lines = textwrap.wrap(f"{m.text.upper()} @{m.t:.2f}{detail}", 105)
            status.set_text("\n".join(lines[:2]) + (" …" if len(lines) > 2 else ""))

    return fig, update


def _legend_handles() -> list[Any]:
    from matplotlib.lines import Line2D

    return [
        Line2D([], [], marker="s", color="#333333", linestyle="none", label="robot base"),
        Line2D([], [], color="#555555", linewidth=1.2, label="reach"),
        Line2D([], [], color="#555555", linestyle=":", label="serves a person"),
        Line2D([], [], marker="o", color="#555555", markeredgecolor="black", label="hand"),
        Line2D([], [], marker="D", color="#8a5a00", linestyle="none", label="rendezvous"),
        Line2D([], [], marker="h", color=OBJECT_COLOR, linestyle="none", label="object"),
        Line2D([], [], marker="o", color="#AA3377", linestyle="none", label="person"),
        Line2D([], [], color="#AA3377", linestyle="--", label="forecast"),
    ]


def _last_span(track: Track, rid: str, t: float) -> ActionSpan | None:
    """The robot's latest action started at or before ``t``."""
    last = None
    for s in track.spans:
        if rid in s.action.robots and s.start <= t + 1e-9:
            last = s
    return last


def _step_words(track: Track, index: int, t: float) -> str:
    """A step's actions in words, each marked done, halted or failed once it is."""
    parts = []
    for s in track.spans:
        if s.step != index:
            continue
        text = describe_action(track.scene, s.action)
        if t >= s.end - 1e-9 and s.outcome != "running":
            text += {"halted": " (halted)", "failed": " (failed)"}.get(s.outcome, " ✓")
        parts.append(text)
    return "; ".join(parts) or "(wait)"


def _latest_prediction(track: Track, hid: str, t: float) -> Any:
    best = None
    for p in track.predictions:
        if p.human == hid and p.t <= t + 1e-9:
            best = p
    if best is None or t - best.t > PREDICTION_HOLD:
        return None
    return best


def _latest_marker(markers: Sequence[Marker], t: float) -> Marker | None:
    best = None
    for m in markers:
        if m.t <= t + 1e-9 and t - m.t <= STATUS_HOLD:
            best = m
    return best


def _clip(text: str, n: int) -> str:
    return text if len(text) <= n else text[: n - 1] + "…"
