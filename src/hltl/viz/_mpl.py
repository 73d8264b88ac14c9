"""Loading matplotlib on demand (Agg, no display), the shared palette and saving figures."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Any, Literal

from hltl.errors import BackendUnavailableError, HltlError

if TYPE_CHECKING:
    from matplotlib.figure import Figure

INSTALL_HINT = "pip install 'hltl[viz]'"

# One colour per skill, the same in every picture (colour-blind safe, Okabe-Ito).
SKILL_COLORS: dict[str, str] = {
    "pick": "#0072B2",
    "place": "#CC79A7",
    "handover_r2r": "#E69F00",
    "handover_r2h": "#009E73",
}
RECEIVES_COLOR = "#8fd9c0"
WALK_COLOR = "#bbbbbb"
OTHER_COLOR = "#999999"
# Vertical event lines: halts, replans, takeovers, background (predictive) plans, goals, robots.
LineStyle = Literal["-", "--", ":", "-."]
MARKER_STYLES: dict[str, tuple[str, LineStyle]] = {
    "halt": ("#D55E00", "-"),
    "replan": ("#0072B2", "--"),
    "takeover": ("#AA3377", "-"),
    "predict": ("#AA3377", ":"),
    "failure": ("#D55E00", ":"),
    "goal": ("#56B4E9", "-."),
    "robot": ("#666666", "-."),
    "no_plan": ("#D55E00", "--"),
}
DEFAULT_STYLE: tuple[str, LineStyle] = ("#666666", "-")
SKILL_NAMES = {
    "pick": "pick",
    "place": "place",
    "handover_r2r": "handover robot→robot",
    "handover_r2h": "handover robot→person",
}

STILL_FORMATS = ("png", "svg")
MOVING_FORMATS = ("gif", "html", "mp4")


def pyplot() -> Any:
    """``matplotlib.pyplot`` on the Agg backend.

    Raises:
        BackendUnavailableError: matplotlib is not installed.
    """
    try:
        import matplotlib
    except ImportError:
        raise BackendUnavailableError(
            f"pictures need matplotlib, which is not installed; {INSTALL_HINT}"
        ) from None
    matplotlib.use("Agg", force=True)
    import matplotlib.pyplot as plt

    return plt


def skill_color(skill: str) -> str:
    return SKILL_COLORS.get(skill, OTHER_COLOR)


def format_of(path: Path, fmt: str | None, allowed: tuple[str, ...]) -> str:
    """The picture format: ``fmt`` if given, else the file's suffix; checked against ``allowed``."""
    chosen = (fmt or path.suffix.lstrip(".")).lower()
    if chosen not in allowed:
        raise HltlError(
            f"{path}: cannot write format {chosen or '(none)'!r} here; "
            f"expected one of {', '.join(allowed)}"
        )
    return chosen


def save_figure(fig: Figure, path: str | Path, *, format: str | None = None) -> Path:
    """Write a still picture (PNG or SVG, from ``format`` or the file's suffix) and close it.

    Returns:
        The path written.
    """
    p = Path(path)
    fmt = format_of(p, format, STILL_FORMATS)
    p.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(p, format=fmt, dpi=110 if fmt == "png" else None)
    pyplot().close(fig)
    return p
