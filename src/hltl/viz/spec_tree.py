"""The H-LTLf tree (each node's formula and automaton size) and single-node DFA diagrams."""

from __future__ import annotations

import math
import textwrap
from collections.abc import Iterable, Sequence
from typing import TYPE_CHECKING, Any

from hltl.spec.automata import DFA, AutomatonCache, default_cache
from hltl.spec.hierarchy import HSpec
from hltl.spec.printer import to_string
from hltl.viz._mpl import pyplot

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

LEAF_COLOR = "#e3f4ea"
COMPOSITE_COLOR = "#e2ecf8"
BOX_WIDTH = 2.6  # layout units (one unit per leaf slot is 3.0)
SLOT = 3.0
LEVEL = 1.9
WRAP = 30
LINE = 0.27  # height of a text line in layout units
INCH = 0.85  # inches per layout unit
MAX_GUARD_PROPS = 6
MAX_GUARD_CHARS = 42
DENSE_EDGES = 12
INLINE_GUARD = 24  # longer guards go to a table beside the diagram


def node_dfas(spec: HSpec, cache: AutomatonCache | None = None) -> dict[str, DFA]:
    """Each node's DFA (compiled with MONA through the cache)."""
    c = default_cache() if cache is None else cache
    return {name: c.to_dfa(f) for name, f in spec.formulas}


def spec_tree(
    spec: HSpec,
    *,
    automata: bool = True,
    cache: AutomatonCache | None = None,
    title: str | None = None,
) -> Figure:
    """Draw the specification's tree: per node its name, formula and DFA size.

    Args:
        spec: the H-LTLf specification.
        automata: compile each node's DFA and show its states and edges (needs MONA).
        cache: the DFA cache (default: the process-wide one).
        title: replaces the default title.

    Raises:
        BackendUnavailableError: matplotlib is missing, or MONA when ``automata`` is set.
    """
    plt = pyplot()
    from matplotlib.patches import FancyArrowPatch, FancyBboxPatch

    dfas = node_dfas(spec, cache) if automata else {}
    pos = _layout(spec)
    texts = {name: _node_text(spec, name, dfas.get(name)) for name in spec.names}
    heights = {name: LINE * (t.count("\n") + 2) + 0.25 for name, t in texts.items()}
    box_h = max(heights.values())
    level_gap = max(LEVEL, box_h + 0.7)
    n_slots = max(len(spec.leaves), 1)
    width_units = n_slots * SLOT
    height_units = spec.depth * level_gap
    fig_w = max(5.0, INCH * width_units + 0.4)
    fig_h = max(2.5, INCH * height_units + 0.7)
    fig: Figure = plt.figure(figsize=(fig_w, fig_h))
    ax: Axes = fig.add_axes((0.01, 0.01, 0.98, 1 - 0.55 / fig_h))
    ax.set_xlim(-SLOT / 2, width_units - SLOT / 2)
    ax.set_ylim(-(spec.depth - 1) * level_gap - box_h / 2 - 0.2, box_h / 2 + 0.2)
    ax.axis("off")

    def xy(name: str) -> tuple[float, float]:
        x, level = pos[name]
        return x, -level * level_gap

    for name in spec.names:
        x, y = xy(name)
        for child in spec.children[name]:
            cx, cy = xy(child)
            arrow = FancyArrowPatch(
                (x, y - heights[name] / 2),
                (cx, cy + heights[child] / 2),
                arrowstyle="-|>",
                mutation_scale=11,
                color="#555555",
                linewidth=1.0,
                zorder=1,
            )
            arrow.set_gid(f"edge:{name}:{child}")
            ax.add_patch(arrow)
    for name in spec.names:
        x, y = xy(name)
        leaf = spec.is_leaf(name)
        h = heights[name]
        box = FancyBboxPatch(
            (x - BOX_WIDTH / 2, y - h / 2),
            BOX_WIDTH,
            h,
            boxstyle="round,pad=0.02,rounding_size=0.12",
            facecolor=LEAF_COLOR if leaf else COMPOSITE_COLOR,
            edgecolor="#2a6a45" if leaf else "#2a4a7a",
            linewidth=1.6 if name == spec.root else 1.0,
            zorder=2,
        )
        box.set_gid(f"node:{name}")
        ax.add_patch(box)
        kind = "leaf" if leaf else "composite"
        top = y + h / 2 - 0.14
        ax.text(x, top, name, ha="center", va="top", fontsize=10, fontweight="bold", zorder=3)
        ax.text(x, top - LINE * 1.25, texts[name], ha="center", va="top", fontsize=9, zorder=3)
        ax.text(x + BOX_WIDTH / 2 - 0.08, top, kind, ha="right", va="top", fontsize=7, color="#555")

    total = ""
    if dfas:
        states = sum(d.n_states for d in dfas.values())
        total = f" — {len(dfas)} automata, {states} states in all"
    head = title if title is not None else f"H-LTLf specification, root {spec.root}{total}"
    fig.suptitle(head, x=0.01, ha="left", fontsize=10)
    return fig


def dfa_diagram(dfa: DFA, *, title: str = "") -> Figure:
    """A small state diagram of one DFA.

    States sit in columns by the longest path that reaches them from the initial state (so an
    "F a & F b" monitor reads left to right as its children fire); accepting states are
    double-ringed, the initial state has a start arrow, and every edge is labelled with its
    guard (or, when there are many or long guards, with a number that a table beside the
    diagram explains). Self-loops are drawn on the outer side of their state.
    """
    plt = pyplot()
    from matplotlib.patches import Circle, FancyArrowPatch

    pos = _dfa_layout(dfa)
    n_cols = max(c for c, _ in pos.values()) + 1
    n_rows = max(r for _, r in pos.values()) + 1
    gx, gy = 3.2, 2.0
    xy = {s: (c * gx, (r - (n_rows - 1) / 2) * gy) for s, (c, r) in pos.items()}
    col_sizes = {c: sum(1 for cc, _ in pos.values() if cc == c) for c in range(n_cols)}
    for s, (c, _) in pos.items():  # centre short columns
        offset = (n_rows - col_sizes[c]) / 2 * gy
        xy[s] = (xy[s][0], xy[s][1] + offset)
    edges = _edges(dfa)
    # Many edges: tag them with numbers and list the guards beside the diagram.
    guards = {e: guard_text(dfa.props, m) for e, m in edges.items()}
    dense = len(edges) > DENSE_EDGES or max(len(g) for g in guards.values()) > INLINE_GUARD
    r = 0.38
    rads = {
        (a, b): 0.18 if (b, a) in edges else _bend(xy[a], xy[b], xy, (a, b), r + 0.25)
        for (a, b) in edges
        if a != b
    }
    # how far the arcs bulge beyond the rows of states
    bulge = max(
        (abs(rad) / 2 * math.dist(xy[a], xy[b]) for (a, b), rad in rads.items()), default=0.0
    )
    x_lo, x_hi = -1.6, (n_cols - 1) * gx + 1.0
    margin = max(1.6, bulge + 0.4)
    y_lo, y_hi = -(n_rows - 1) / 2 * gy - margin, (n_rows - 1) / 2 * gy + margin
    scale = 0.75
    longest = max(len(g) for g in guards.values()) + 10
    table_w = longest * 7 * 0.62 / 72 + 0.3 if dense else 0.0
    diagram_w = max(4.5, scale * (x_hi - x_lo))
    fig_w = diagram_w + table_w
    fig_h = max(2.8, scale * (y_hi - y_lo) + 0.5, 0.16 * len(edges) + 0.8 if dense else 0.0)
    fig: Figure = plt.figure(figsize=(fig_w, fig_h))
    ax: Axes = fig.add_axes((0.01, 0.01, diagram_w / fig_w - 0.02, 1 - 0.45 / fig_h))
    ax.set_xlim(x_lo, x_hi)
    ax.set_ylim(y_lo, y_hi)
    ax.set_aspect("equal")
    ax.axis("off")
    for s, (x, y) in xy.items():
        circle = Circle((x, y), r, facecolor="white", edgecolor="black", linewidth=1.2, zorder=3)
        circle.set_gid(f"state:{s}")
        ax.add_patch(circle)
        if s in dfa.accepting:
            ax.add_patch(Circle((x, y), r - 0.07, fill=False, edgecolor="black", zorder=3))
        ax.text(x, y, str(s), ha="center", va="center", fontsize=10, zorder=4)
    x0, y0 = xy[dfa.initial]
    ax.add_patch(
        FancyArrowPatch(
            (x0 - r - 0.9, y0), (x0 - r, y0), arrowstyle="-|>", mutation_scale=12, color="black"
        )
    )
    ax.text(x0 - r - 0.95, y0 + 0.1, "start", fontsize=8, ha="left", va="bottom")
    shrink = r * 72 * scale + 1
    table: list[str] = []
    for k, (src, dst) in enumerate(sorted(edges), 1):
        guard = guards[(src, dst)]
        if dense:
            table.append(f"{k:>2}  {src}→{dst}  {guard.replace(chr(10), ' ')}")
        label = str(k) if dense else guard
        (xa, ya), (xb, yb) = xy[src], xy[dst]
        if src == dst:  # a loop on the outer side of the state
            up = 1 if ya >= -1e-9 else -1
            arrow = FancyArrowPatch(
                (xa - 0.2 * up, ya + up * (r - 0.05)),
                (xa + 0.2 * up, ya + up * (r - 0.05)),
                connectionstyle="arc3,rad=-2.2",
                arrowstyle="-|>",
                mutation_scale=10,
                color="#333333",
                zorder=2,
            )
            lx, ly, va = xa, ya + up * (r + 0.62), "bottom" if up > 0 else "top"
        else:
            rad = rads[(src, dst)]
            arrow = FancyArrowPatch(
                (xa, ya),
                (xb, yb),
                connectionstyle=f"arc3,rad={rad}",
                arrowstyle="-|>",
                mutation_scale=10,
                color="#333333",
                shrinkA=shrink,
                shrinkB=shrink,
                zorder=2,
            )
            f = 0.5 if not dense else 0.3 + 0.4 * ((src * 7 + dst * 3) % 5) / 4
            lx, ly, va = xa + f * (xb - xa), ya + f * (yb - ya), "center"
            if rad:  # the arc bulges to the right of the direction of travel
                dx, dy = xb - xa, yb - ya
                bulge = rad * 2 * f * (1 - f)  # quadratic Bezier through arc3's control point
                lx, ly = lx + bulge * dy, ly - bulge * dx
        arrow.set_gid(f"edge:{src}:{dst}")
        ax.add_patch(arrow)
        ax.text(
            lx,
            ly,
            label,
            ha="center",
            va=va,
            fontsize=7 if dense else 7.5,
            family="monospace",
            zorder=4,
            bbox={"boxstyle": "square,pad=0.1", "fc": "white", "ec": "none", "alpha": 0.85},
        )
    if table:
        fig.text(
            diagram_w / fig_w,
            1 - 0.5 / fig_h,
            "edge  guard\n" + "\n".join(table),
            va="top",
            ha="left",
            fontsize=7,
            family="monospace",
        )
    head = title or "DFA"
    fig.suptitle(
        f"{head} — {dfa.n_states} states, {dfa.n_edges} edges, accepting {sorted(dfa.accepting)}",
        x=0.01,
        ha="left",
        fontsize=9.5,
    )
    return fig


def _bend(
    a: tuple[float, float],
    b: tuple[float, float],
    xy: dict[int, tuple[float, float]],
    ends: tuple[int, int],
    clearance: float,
) -> float:
    """``arc3`` rad for an edge a→b: 0 if the straight line passes clear of every other state,
    else the bend (either way) whose arc keeps farthest from them."""
    others = [p for s, p in xy.items() if s not in ends]

    def dist_to_curve(rad: float) -> float:
        dx, dy = b[0] - a[0], b[1] - a[1]
        best = float("inf")
        for k in range(1, 20):
            f = k / 20
            off = 2 * f * (1 - f) * rad
            x, y = a[0] + f * dx + off * dy, a[1] + f * dy - off * dx
            best = min([best, *(math.hypot(x - p[0], y - p[1]) for p in others)])
        return best

    if not others or dist_to_curve(0.0) >= clearance:
        return 0.0
    return max((0.3, -0.3, 0.5, -0.5), key=dist_to_curve)


def _dfa_layout(dfa: DFA) -> dict[int, tuple[int, int]]:
    """(column, row) per state: column = longest path from the initial state ignoring
    self-loops (breadth-first distance if the DFA has other cycles); rows in state order."""
    succ = {s: {t for (a, t) in _edges(dfa) if a == s and t != s} for s in range(dfa.n_states)}
    depth: dict[int, int] = {}
    state: dict[int, int] = {}  # 1 visiting, 2 done
    # longest path from the initial state over a DAG: relax in topological order
    order: list[int] = []
    cyclic = False

    def visit(s: int) -> None:
        nonlocal cyclic
        state[s] = 1
        for t in sorted(succ[s]):
            if state.get(t) == 1:
                cyclic = True
            elif t not in state:
                visit(t)
        state[s] = 2
        order.append(s)

    visit(dfa.initial)
    for s in range(dfa.n_states):
        if s not in state:
            visit(s)
    if not cyclic:
        for s in reversed(order):
            depth.setdefault(s, 0)
            for t in succ[s]:
                depth[t] = max(depth.get(t, 0), depth[s] + 1)
    else:
        frontier = [dfa.initial]
        depth = {dfa.initial: 0}
        while frontier:
            nxt = []
            for s in frontier:
                for t in sorted(succ[s]):
                    if t not in depth:
                        depth[t] = depth[s] + 1
                        nxt.append(t)
            frontier = nxt
        last = max(depth.values()) + 1
        for s in range(dfa.n_states):
            depth.setdefault(s, last)
    rows: dict[int, int] = {}
    out = {}
    for s in range(dfa.n_states):
        c = depth[s]
        out[s] = (c, rows.get(c, 0))
        rows[c] = rows.get(c, 0) + 1
    return out


# -- pieces ---------------------------------------------------------------------------------------


def _layout(spec: HSpec) -> dict[str, tuple[float, int]]:
    """(x, level) per node: leaves one slot apart in depth-first order, parents centred."""
    pos: dict[str, tuple[float, int]] = {}
    next_slot = [0]

    def place(name: str, level: int) -> float:
        kids = spec.children[name]
        if not kids:
            x = next_slot[0] * SLOT
            next_slot[0] += 1
        else:
            xs = [place(k, level + 1) for k in kids]
            x = (min(xs) + max(xs)) / 2
        pos[name] = (x, level)
        return x

    place(spec.root, 0)
    return pos


def _node_text(spec: HSpec, name: str, dfa: DFA | None) -> str:
    formula = to_string(spec.formula(name))
    wrapped = textwrap.wrap(formula, WRAP, break_long_words=False) or [formula]
    parts = list(wrapped)
    if dfa is not None:
        parts.append(f"DFA: {dfa.n_states} states, {dfa.n_edges} edges")
    return "\n".join(parts)


def _edges(dfa: DFA) -> dict[tuple[int, int], list[int]]:
    width = 1 << len(dfa.props)
    out: dict[tuple[int, int], list[int]] = {}
    for s in range(dfa.n_states):
        for mask in range(width):
            out.setdefault((s, dfa.table[s * width + mask]), []).append(mask)
    return out


def guard_text(props: Sequence[Any], masks: Iterable[int]) -> str:
    """The symbols ``masks`` as a short boolean formula over ``props`` (sum of prime
    implicants, e.g. ``p100 & !p200 | p300``); ``true`` for every symbol."""
    ms = sorted(set(masks))
    k = len(props)
    if len(ms) == 1 << k:
        return "true"
    if k > MAX_GUARD_PROPS:
        return f"{len(ms)} of {1 << k} symbols"
    names = [str(p) for p in props]
    terms = []
    for value, care in _cover(ms, k):
        lits = [(names[i] if value >> i & 1 else f"!{names[i]}") for i in range(k) if care >> i & 1]
        terms.append(" & ".join(lits) or "true")
    text = " | ".join(terms)
    if len(text) > MAX_GUARD_CHARS:
        text = "\n| ".join(terms)
    return text


def _cover(minterms: list[int], k: int) -> list[tuple[int, int]]:
    """Prime implicants (value, care mask) of a function given by its minterms (Quine-McCluskey)
    and a greedy cover of the minterms by them."""
    full = (1 << k) - 1
    current = {(m, full) for m in minterms}
    primes: set[tuple[int, int]] = set()
    while current:
        merged: set[tuple[int, int]] = set()
        used: set[tuple[int, int]] = set()
        items = sorted(current)
        for i, (v1, c1) in enumerate(items):
            for v2, c2 in items[i + 1 :]:
                if c1 != c2:
                    continue
                diff = (v1 ^ v2) & c1
                if diff and diff & (diff - 1) == 0:
                    merged.add((v1 & ~diff & c1, c1 & ~diff))
                    used.update({(v1, c1), (v2, c2)})
        primes |= current - used
        current = merged
    left = set(minterms)
    chosen: list[tuple[int, int]] = []

    def covers(p: tuple[int, int], m: int) -> bool:
        return (m & p[1]) == p[0]

    while left:
        best = max(
            sorted(primes), key=lambda p: (sum(covers(p, m) for m in left), -bin(p[1]).count("1"))
        )
        chosen.append(best)
        left = {m for m in left if not covers(best, m)}
    return sorted(chosen, key=lambda p: (-bin(p[1]).count("1"), p))
