"""A 3D still of the cell: arms as their collision capsules at given joint configurations."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

import numpy as np

from hltl.motion.grasps import Cylinder
from hltl.motion.human import body_capsules, standing_posture
from hltl.motion.kinematics import Capsule
from hltl.motion.planning import Cell
from hltl.viz._mpl import pyplot, save_figure

ARM_COLORS = ("#0072B2", "#E69F00", "#009E73", "#CC79A7", "#56B4E9", "#D55E00")


def _capsule(ax: Any, c: Capsule, color: str, alpha: float = 0.9) -> None:
    """A capsule drawn as a tube (surface of revolution) with round ends."""
    a, b = np.asarray(c.a), np.asarray(c.b)
    axis = b - a
    length = float(np.linalg.norm(axis))
    u = np.linspace(0, 2 * np.pi, 16)
    if length < 1e-9:
        v = np.linspace(0, np.pi, 8)
        x = a[0] + c.radius * np.outer(np.cos(u), np.sin(v))
        y = a[1] + c.radius * np.outer(np.sin(u), np.sin(v))
        z = a[2] + c.radius * np.outer(np.ones_like(u), np.cos(v))
        ax.plot_surface(x, y, z, color=color, alpha=alpha, linewidth=0, shade=True)
        return
    w = axis / length
    n1 = np.cross(w, [0.0, 0.0, 1.0])
    if np.linalg.norm(n1) < 1e-6:
        n1 = np.cross(w, [1.0, 0.0, 0.0])
    n1 /= np.linalg.norm(n1)
    n2 = np.cross(w, n1)
    # the tube plus a hemisphere at each end, as one parametrised surface
    t = np.concatenate(
        [np.linspace(-np.pi / 2, 0, 5), np.linspace(0, 0, 2), np.linspace(0, np.pi / 2, 5)]
    )
    along = np.concatenate([np.zeros(5), np.array([0.0, length]), np.full(5, length)])
    ring = c.radius * np.cos(t)
    ax_off = along + c.radius * np.sin(t)
    pts = (
        a[None, None, :]
        + ax_off[None, :, None] * w
        + ring[None, :, None] * (np.cos(u)[:, None, None] * n1 + np.sin(u)[:, None, None] * n2)
    )
    ax.plot_surface(
        pts[..., 0], pts[..., 1], pts[..., 2], color=color, alpha=alpha, linewidth=0, shade=True
    )


def render_arms(
    cell: Cell,
    configs: Mapping[str, Sequence[float]],
    path: Path,
    *,
    title: str = "",
    marks: Sequence[tuple[Sequence[float], str]] = (),
) -> Path:
    """Draw every modelled arm at ``configs[robot]`` (default: home), the objects, the people
    (body capsules), surfaces and the table; ``marks`` are labelled points (e.g. a handover pose).
    """
    plt = pyplot()
    fig = plt.figure(figsize=(9, 6))
    ax = fig.add_subplot(projection="3d")
    scene = cell.scene
    pts: list[np.ndarray] = []
    for i, r in enumerate(scene.robots):
        color = ARM_COLORS[i % len(ARM_COLORS)]
        arm = cell.arms.get(r.id)
        if arm is None:
            ax.scatter(*r.base, color=color, s=60, marker="s")
            ax.text(*r.base, f" {r.id} (sphere)", fontsize=8)
            continue
        q = configs.get(r.id, arm.home)
        for cap in arm.capsules(q):
            _capsule(ax, cap, color)
            pts += [np.asarray(cap.a), np.asarray(cap.b)]
        tip, _ = arm.fk(q)
        ax.text(*arm.base, f"  {r.id} ({r.model})", fontsize=8, color=color)
        ax.scatter(*tip, color="k", s=8)
    centre = np.mean([r.base for r in scene.robots], axis=0)
    for h in scene.humans:
        posture = standing_posture(h.position, centre)
        for cap in body_capsules(posture):
            _capsule(ax, cap, "#bbbbbb", alpha=0.35)
            pts += [np.asarray(cap.a), np.asarray(cap.b)]
        top = body_capsules(posture)[-1].a
        ax.text(top[0], top[1], top[2] + 0.15, h.name, fontsize=8, ha="center")
    for o in scene.objects:
        cyl = Cylinder.for_category(o.category)
        x, y, z = o.position
        _capsule(ax, Capsule((x, y, z), (x, y, z + cyl.height), cyl.radius, o.id), "#D55E00", 0.8)
        ax.text(x, y, z + cyl.height + 0.03, o.id, fontsize=7, ha="center")
    for s in scene.surfaces:
        cx, cy, cz = s.center
        hx, hy = s.size[0] / 2, s.size[1] / 2
        xs = [cx - hx, cx + hx, cx + hx, cx - hx, cx - hx]
        ys = [cy - hy, cy - hy, cy + hy, cy + hy, cy - hy]
        ax.plot(xs, ys, [cz] * 5, color="#CC79A7")
        ax.text(cx, cy, cz, s.id, fontsize=7, color="#CC79A7")
    for p, label in marks:
        ax.scatter(*p, color="#AA3377", s=40, marker="*")
        ax.text(*p, f" {label}", fontsize=8, color="#AA3377")
    all_pts = np.array(pts) if pts else np.zeros((1, 3))
    lo, hi = all_pts.min(axis=0) - 0.15, all_pts.max(axis=0) + 0.15
    # the table top (z = 0 of the scene) under the arms
    tx, ty = np.meshgrid([lo[0], hi[0]], [lo[1], hi[1]])
    ax.plot_surface(tx, ty, np.zeros_like(tx), color="#dddddd", alpha=0.25)
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(lo[1], hi[1])
    ax.set_zlim(lo[2], hi[2])
    ax.set_box_aspect(tuple(hi - lo))  # metres look the same along every axis
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.set_zlabel("z (m)")
    ax.view_init(elev=24, azim=-62)
    fig.subplots_adjust(left=0.0, right=1.0, bottom=0.02, top=0.95)
    ax.set_title(title or "arms at their home configuration", fontsize=10)
    return save_figure(fig, path)
