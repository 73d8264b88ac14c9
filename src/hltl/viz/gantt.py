"""Gantt charts of a plan or an executed episode: one row per robot and per person."""

from __future__ import annotations

import textwrap
from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING, Any

from hltl.execution.log import LogRecord
from hltl.planner.result import PlanResult
from hltl.viz._mpl import (
    DEFAULT_STYLE,
    MARKER_STYLES,
    RECEIVES_COLOR,
    SKILL_NAMES,
    WALK_COLOR,
    pyplot,
    skill_color,
)
from hltl.viz.track import ActionSpan, Marker, Track, track_from_log, track_from_plan
from hltl.world.scene import Scene

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

BAR_HEIGHT = 0.6
# A person's row has two lanes: receiving (upper) and walking (lower, thin).
RECEIVE_Y, RECEIVE_HEIGHT = 0.1, 0.5
WALK_Y, WALK_HEIGHT = -0.3, 0.16
FIG_WIDTH = 10.0  # inches
AX_LEFT, AX_RIGHT = 1.25, 2.35  # inches of margin for row labels and the legend
CHAR_WIDTH = 0.58  # width of a character in font sizes (points), roughly, for fitting labels
NOTE_KINDS = ("halt", "no_plan", "takeover", "failure", "replan", "goal", "robot")
MAX_NOTES = 6


def plan_gantt(
    plan: PlanResult | Mapping[str, Any], scene: Scene, *, title: str | None = None
) -> Figure:
    """The Gantt chart of a plan (each action spans its step; a line marks the makespan).

    Args:
        plan: a :class:`PlanResult` or the plan JSON as a dict.
        scene: the plan's scene (rows, people's names).
        title: replaces the default title.
    """
    return gantt(track_from_plan(plan, scene, title=title))


def episode_gantt(records: Sequence[LogRecord], *, title: str | None = None) -> Figure:
    """The Gantt chart of an executed episode from its log records."""
    return gantt(track_from_log(records, title=title))


def gantt(track: Track) -> Figure:
    """Draw a :class:`Track` as a Gantt chart and return the figure (not yet saved).

    Every bar is a ``Rectangle`` in ``fig.axes[0].patches`` whose gid says what it is:
    ``action:<row>`` (an action on a robot's row), ``receives:<row>`` (a person receiving),
    ``walk:<row>`` (a person walking); a robot-to-robot handover adds a ``link:<giver>:<receiver>``
    arrow patch.
    """
    plt = pyplot()
    from matplotlib.lines import Line2D
    from matplotlib.patches import FancyArrowPatch, Patch

    rows = track.rows()
    y_of = {r: len(rows) - 1 - i for i, r in enumerate(rows)}
    end = max(track.end, max((s.end for s in track.spans), default=0.0))
    x_max = max(end * 1.04, end + 0.1, 0.5)

    markers = [m for m in track.markers if m.t <= x_max]
    levels = _label_levels(markers, x_max)
    n_levels = max(levels, default=-1) + 1
    notes = _notes(markers)
    note_lines = sum(len(n) for n in notes)

    ax_h = 0.62 * len(rows) + 0.3
    top = 0.42 + 0.2 * n_levels
    bottom = 0.75 + 0.16 * note_lines + (0.15 if notes else 0.0)
    fig_h = ax_h + top + bottom
    fig: Figure = plt.figure(figsize=(FIG_WIDTH, fig_h))
    ax: Axes = fig.add_axes(
        (
            AX_LEFT / FIG_WIDTH,
            bottom / fig_h,
            (FIG_WIDTH - AX_LEFT - AX_RIGHT) / FIG_WIDTH,
            ax_h / fig_h,
        )
    )
    ax.set_xlim(0.0, x_max)
    ax.set_ylim(-0.6, len(rows) - 0.4)
    ax.set_yticks([y_of[r] for r in rows])
    ax.set_yticklabels([_row_label(track, r) for r in rows])
    for r in track.humans:  # people's rows on a grey band
        ax.axhspan(y_of[r] - 0.5, y_of[r] + 0.5, color="#f4f4f4", zorder=0)
    ax.set_xlabel("time (s)")
    ax.grid(axis="x", color="#dddddd", linewidth=0.6, zorder=0)
    ax.set_axisbelow(True)
    inches_per_s = (FIG_WIDTH - AX_LEFT - AX_RIGHT) / x_max

    skills_seen: list[str] = []
    outcomes_seen: set[str] = set()
    for span in track.spans:
        a = span.action
        if a.skill not in skills_seen:
            skills_seen.append(a.skill)
        outcomes_seen.add(span.outcome)
        for k, rid in enumerate(a.robots):
            if rid not in y_of:
                continue
            label = _bar_label(span, k)
            _bar(ax, span, y_of[rid], BAR_HEIGHT, skill_color(a.skill), f"action:{rid}")
            _bar_text(ax, span, y_of[rid], label, inches_per_s)
        if a.skill == "handover_r2r" and len(a.robots) == 2 and set(a.robots) <= set(y_of):
            g, r = a.robots
            x = span.start + 0.5 * (span.end - span.start)
            sign = 1 if y_of[r] > y_of[g] else -1
            arrow = FancyArrowPatch(
                (x, y_of[g] + sign * BAR_HEIGHT / 2),
                (x, y_of[r] - sign * BAR_HEIGHT / 2),
                arrowstyle="-|>",
                mutation_scale=12,
                color="#8a5a00",
                linewidth=1.6,
                zorder=4,
            )
            arrow.set_gid(f"link:{g}:{r}")
            ax.add_patch(arrow)
        if a.skill == "handover_r2h" and a.human in y_of:
            hid = str(a.human)
            y = y_of[hid] + RECEIVE_Y
            _bar(ax, span, y, RECEIVE_HEIGHT, RECEIVES_COLOR, f"receives:{hid}")
            _bar_text(ax, span, y, (f"receives {a.object}", a.object), inches_per_s)

    walked = False
    for hid, segs in track.walks:
        if hid not in y_of:
            continue
        first = True
        for seg in segs:
            if seg.t1 - seg.t0 <= 1e-9:
                continue
            walked = True
            y = y_of[hid] + WALK_Y
            rect = ax.barh(
                y,
                seg.t1 - seg.t0,
                left=seg.t0,
                height=WALK_HEIGHT,
                color=WALK_COLOR,
                edgecolor="#888888",
                linewidth=0.5,
                zorder=2,
            )[0]
            rect.set_gid(f"walk:{hid}")
            if first and (seg.t1 - seg.t0) * inches_per_s > 0.55:
                first = False
                ax.text(
                    seg.t0 + 0.02 * (seg.t1 - seg.t0) + 0.01,
                    y,
                    "walking",
                    va="center",
                    ha="left",
                    fontsize=6.5,
                    color="#333333",
                    zorder=3,
                    clip_on=True,
                )

    # the end line: the plan's makespan or when the episode ended
    end_label = (
        f"makespan {track.end:.2f} s"
        if track.kind == "plan"
        else (f"done {track.end:.2f} s" if track.success else f"ended {track.end:.2f} s")
    )
    if track.note:  # nothing to draw: say why instead of a zero makespan
        ax.text(
            0.5, 0.5, textwrap.fill(track.note, 90), transform=ax.transAxes, ha="center",
            va="center", fontsize=9, color="#a33", zorder=6,
        )  # fmt: skip
    else:
        ax.axvline(track.end, color="black", linewidth=1.6, zorder=5)
        ax.annotate(
            end_label,
            xy=(track.end, 0.0),
            xycoords=("data", "axes fraction"),
            xytext=(3, 3),
            textcoords="offset points",
            fontsize=8,
            fontweight="bold",
            ha="left",
            va="bottom",
        )

    # event lines, labels staggered above the chart, reasons as numbered notes below it
    numbers = {id(m): i + 1 for i, m in enumerate(_noted(markers))}
    for m, level in zip(markers, levels, strict=True):
        color, style = MARKER_STYLES.get(m.kind, DEFAULT_STYLE)
        ax.axvline(m.t, color=color, linestyle=style, linewidth=1.3, zorder=5)
        num = numbers.get(id(m))
        text = f"[{num}] {m.text}" if num is not None and num <= MAX_NOTES else m.text
        ax.annotate(
            f"{text} @{m.t:.2f}",
            xy=(m.t, 1.0),
            xycoords=("data", "axes fraction"),
            xytext=(0, 4 + 14 * level),
            textcoords="offset points",
            fontsize=7.5,
            color=color,
            ha="left",
            va="bottom",
            # lower labels (white boxes) hide the leader lines of higher ones
            zorder=20 - level,
            bbox={"boxstyle": "square,pad=0.05", "fc": "white", "ec": "none"},
            arrowprops={"arrowstyle": "-", "color": color, "linewidth": 0.6, "shrinkA": 0},
            annotation_clip=False,
        )
    if notes:
        y = bottom - 0.62
        for para in notes:
            for line in para:
                fig.text(0.012, y / fig_h, line, fontsize=7.2, va="top", family="DejaVu Sans")
                y -= 0.16

    fig.suptitle(track.title, x=0.012, y=1 - 0.1 / fig_h, ha="left", va="top", fontsize=10.5)

    handles: list[Any] = [
        Patch(facecolor=skill_color(s), label=SKILL_NAMES.get(s, s)) for s in skills_seen
    ]
    if any(s.action.skill == "handover_r2h" for s in track.spans):
        handles.append(Patch(facecolor=RECEIVES_COLOR, label="person receives"))
    if walked:
        handles.append(Patch(facecolor=WALK_COLOR, edgecolor="#888888", label="person walking"))
    if "halted" in outcomes_seen:
        handles.append(Patch(facecolor="white", edgecolor="#a33", hatch="///", label="halted"))
    if "failed" in outcomes_seen:
        handles.append(Patch(facecolor="white", edgecolor="#a33", hatch="xxx", label="failed"))
    if "running" in outcomes_seen:
        handles.append(Patch(facecolor="#dddddd", alpha=0.5, label="unfinished"))
    names = {
        "halt": "halt",
        "replan": "replan",
        "no_plan": "no plan",
        "takeover": "takeover",
        "predict": "background plan",
        "failure": "failure",
        "goal": "new instruction",
        "robot": "robot down/up",
    }
    for kind in dict.fromkeys(m.kind for m in markers):
        color, style = MARKER_STYLES.get(kind, DEFAULT_STYLE)
        handles.append(Line2D([], [], color=color, linestyle=style, label=names.get(kind, kind)))
    if not track.note:
        handles.append(Line2D([], [], color="black", linewidth=1.6, label=end_label.split(" ")[0]))
    ax.legend(
        handles=handles,
        loc="upper left",
        bbox_to_anchor=(1.01, 1.0),
        fontsize=7.5,
        frameon=False,
        borderaxespad=0.0,
    )
    return fig


# -- pieces -------------------------------------------------------------------------------------


def _row_label(track: Track, row: str) -> str:
    if row in track.robots:
        model = track.scene.robot(row).model
        return row if model == "generic" else f"{row} ({model})"
    return track.human_name(row)


def _bar_label(span: ActionSpan, k: int) -> tuple[str, str]:
    """(long, short) text for the bar of executor ``k`` of ``span``."""
    a = span.action
    obj = a.object
    suffix = {"halted": " (halted)", "failed": " (failed)"}.get(span.outcome, "")
    if a.skill == "handover_r2r" and len(a.robots) == 2:
        long = f"{obj} → {a.robots[1]}" if k == 0 else f"{obj} ← {a.robots[0]}"
    elif a.skill == "handover_r2h" and a.human is not None:
        long = f"{obj} → {a.human}"
    elif a.skill == "place" and a.surface is not None:
        long = f"{obj} → {a.surface}"
    else:
        long = obj
    return long + suffix, obj


def _bar(ax: Axes, span: ActionSpan, y: float, height: float, color: str, gid: str) -> None:
    kw: dict[str, Any] = {"color": color, "edgecolor": "#333333", "linewidth": 0.6, "zorder": 3}
    if span.outcome == "halted":
        kw.update(alpha=0.55, hatch="///", edgecolor="#aa3333", linewidth=1.0)
    elif span.outcome == "failed":
        kw.update(alpha=0.55, hatch="xxx", edgecolor="#aa3333", linewidth=1.0)
    elif span.outcome == "running":
        kw.update(alpha=0.4)
    rect = ax.barh(y, span.end - span.start, left=span.start, height=height, **kw)[0]
    rect.set_gid(gid)


def _bar_text(
    ax: Axes, span: ActionSpan, y: float, labels: tuple[str, str], inches_per_s: float
) -> None:
    """The longest label that fits inside the bar, else none (colour and legend still tell)."""
    width_in = (span.end - span.start) * inches_per_s
    hatched = span.outcome in ("halted", "failed")
    for text in labels:
        for size in (8.0, 6.8):
            if len(text) * size * CHAR_WIDTH / 72.0 + 0.06 <= width_in:
                box = {"boxstyle": "square,pad=0.1", "fc": "white", "ec": "none", "alpha": 0.85}
                ax.text(
                    span.start + (span.end - span.start) / 2,
                    y,
                    text,
                    ha="center",
                    va="center",
                    fontsize=size,
                    color="black",
                    zorder=4,
                    clip_on=True,
                    bbox=box if hatched else None,
                )
                return


def _label_levels(markers: Sequence[Marker], x_max: float) -> list[int]:
    """A stacking level per marker so that labels above the chart do not overlap."""
    width_in = FIG_WIDTH - AX_LEFT - AX_RIGHT
    ends: list[float] = []  # per level, where (in inches) its last label ends
    out = []
    for m in markers:
        x = m.t / x_max * width_in
        w = (len(m.text) + 10) * 7.5 * CHAR_WIDTH / 72.0
        for level, last in enumerate(ends):
            if x >= last + 0.08:
                ends[level] = x + w
                out.append(level)
                break
        else:
            ends.append(x + w)
            out.append(len(ends) - 1)
    return out


def _noted(markers: Sequence[Marker]) -> list[Marker]:
    return [m for m in markers if m.kind in NOTE_KINDS and m.detail]


def _notes(markers: Sequence[Marker]) -> list[list[str]]:
    """Numbered reasons of the markers that have one, wrapped to the figure's width."""
    out: list[list[str]] = []
    noted = _noted(markers)
    for i, m in enumerate(noted[:MAX_NOTES], 1):
        text = f"[{i}] {m.text} at {m.t:.2f} s: {m.detail}"
        out.append(textwrap.wrap(text, 150, subsequent_indent="      "))
    if len(noted) > MAX_NOTES:
        out.append([f"… and {len(noted) - MAX_NOTES} more events (see the log)"])
    return out
