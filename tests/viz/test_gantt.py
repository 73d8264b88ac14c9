"""Gantt charts: bar geometry against the plan or log, links, markers, files, missing backend."""

from __future__ import annotations

import sys
from collections import defaultdict
from pathlib import Path
from typing import Any

import pytest

from hltl.errors import BackendUnavailableError, HltlError
from hltl.execution.log import LogRecord
from hltl.planner import PlanResult
from hltl.viz._mpl import save_figure
from hltl.viz.gantt import episode_gantt, plan_gantt
from hltl.world.scene import Scene
from tests.viz.conftest import PNG, magic


def bars(fig: Any) -> dict[str, list[tuple[float, float]]]:
    """gid -> sorted (x, width) of the chart's bars."""
    out: dict[str, list[tuple[float, float]]] = defaultdict(list)
    for p in fig.axes[0].patches:
        gid = p.get_gid() or ""
        if gid.split(":")[0] in ("action", "receives", "walk"):
            out[gid].append((round(p.get_x(), 9), round(p.get_width(), 9)))
    return {k: sorted(v) for k, v in out.items()}


def rounded(items: list[tuple[float, float]]) -> list[tuple[float, float]]:
    return sorted((round(x, 9), round(w, 9)) for x, w in items)


def vlines(fig: Any) -> list[float]:
    return sorted(
        float(line.get_xdata()[0])
        for line in fig.axes[0].lines
        if len(line.get_xdata()) == 2 and line.get_xdata()[0] == line.get_xdata()[1]
    )


def test_plan_bars_are_the_plan_steps(paper_plan: PlanResult, scene: Scene) -> None:
    fig = plan_gantt(paper_plan, scene)
    expected: dict[str, list[tuple[float, float]]] = defaultdict(list)
    for step in paper_plan.steps:
        for a in step.actions:
            for r in a.robots:
                expected[f"action:{r}"].append((step.start, step.duration))
            if a.skill == "handover_r2h":
                expected[f"receives:{a.human}"].append((step.start, step.duration))
    got = bars(fig)
    assert got == {k: rounded(v) for k, v in expected.items()}
    assert len(got["action:r1"]) == 2 and len(got["action:r2"]) == 2
    assert paper_plan.makespan in vlines(fig)
    rows = [t.get_text() for t in fig.axes[0].get_yticklabels()]
    assert rows == ["r1 (elfin3)", "r2 (ur5)", "Person A", "Person B"]


def test_a_robot_handover_is_a_linked_pair(chips_plan: PlanResult, scene: Scene) -> None:
    fig = plan_gantt(chips_plan.to_dict(), scene)
    step = next(s for s in chips_plan.steps if s.actions[0].skill == "handover_r2r")
    giver, receiver = step.actions[0].robots
    got = bars(fig)
    pair = (round(step.start, 9), round(step.duration, 9))
    assert pair in got[f"action:{giver}"] and pair in got[f"action:{receiver}"]
    links = [p for p in fig.axes[0].patches if (p.get_gid() or "").startswith("link:")]
    assert [p.get_gid() for p in links] == [f"link:{giver}:{receiver}"]
    # the arrow runs, at the middle of the step, from the giver's row to the receiver's
    shaft = links[0].get_path().vertices[:3]  # in data coordinates; the head follows
    assert shaft[:, 0] == pytest.approx(step.start + step.duration / 2)
    y0, y1 = shaft[0, 1], shaft[-1, 1]
    ticks = {t.get_text().split(" ")[0]: t.get_position()[1] for t in fig.axes[0].get_yticklabels()}
    assert (y1 - y0) * (ticks[receiver] - ticks[giver]) > 0
    # the bars carry the object and the direction
    texts = {t.get_text() for t in fig.axes[0].texts}
    assert {"chips → r1", "chips ← r2", "receives chips"} <= texts


def test_episode_bars_walks_and_markers_match_the_log(
    demo_records: tuple[LogRecord, ...],
) -> None:
    fig = episode_gantt(demo_records)
    starts = {r.handle: r for r in demo_records if r.type == "action_start"}
    expected: dict[str, list[tuple[float, float]]] = defaultdict(list)
    for r in demo_records:
        if r.type in ("action_done", "action_halted", "action_failed"):
            s = starts[r.handle]
            x, w = s.t, r.ended - s.t
            for rid in s.action["robots"]:
                expected[f"action:{rid}"].append((x, w))
            if s.action["skill"] == "handover_r2h":
                expected[f"receives:{s.action['human']}"].append((x, w))
    got = bars(fig)
    for gid, items in expected.items():
        assert got[gid] == rounded(items), gid
    # A walked twice: two bars in A's walking lane, none for B
    assert len(got["walk:A"]) == 2 and "walk:B" not in got
    # the halted handover is hatched; the completed ones are not
    hatches = {
        (p.get_gid(), round(p.get_x(), 6)): p.get_hatch()
        for p in fig.axes[0].patches
        if (p.get_gid() or "").startswith("action:")
    }
    halted = next(r for r in demo_records if r.type == "action_halted")
    x = starts[halted.handle].t
    assert hatches[("action:r1", x)] == "///"
    assert sum(1 for h in hatches.values() if h) == 1
    lines = vlines(fig)
    for kind in ("halt", "takeover"):
        t = next(r.t for r in demo_records if r.type == kind)
        assert t in lines
    labels = " ".join(t.get_text() for t in fig.axes[0].texts)
    assert "halt (intrusion)" in labels and "takeover" in labels
    notes = " ".join(t.get_text() for t in fig.texts)
    assert "is not inside r1's workspace" in notes


def test_failed_actions_are_hatched_and_robot_events_marked(
    down_records: tuple[LogRecord, ...],
) -> None:
    fig = episode_gantt(down_records)
    failed = [
        p for p in fig.axes[0].patches if p.get_gid() == "action:r1" and p.get_hatch() == "xxx"
    ]
    assert len(failed) == 1 and failed[0].get_x() == 0.0
    labels = " ".join(t.get_text() for t in fig.axes[0].texts)
    assert "r1 down" in labels and "r1 up" in labels and "failed" in labels


def test_png_and_svg_files(paper_plan: PlanResult, scene: Scene, tmp_path: Path) -> None:
    png = save_figure(plan_gantt(paper_plan, scene), tmp_path / "g.png")
    assert magic(png) == PNG and png.stat().st_size > 5000
    svg = save_figure(plan_gantt(paper_plan, scene), tmp_path / "g.out", format="svg")
    assert svg.read_text(encoding="utf-8").lstrip().startswith("<?xml") and "<svg" in svg.read_text(
        encoding="utf-8"
    )
    with pytest.raises(HltlError, match="expected one of png, svg"):
        save_figure(plan_gantt(paper_plan, scene), tmp_path / "g.gif")


def test_without_matplotlib_the_error_names_the_extra(
    paper_plan: PlanResult, scene: Scene, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setitem(sys.modules, "matplotlib", None)
    with pytest.raises(BackendUnavailableError, match=r"pip install 'hltl\[viz\]'"):
        plan_gantt(paper_plan, scene)


def test_a_plan_that_is_not_solved_says_why(scene: Scene) -> None:
    plan = {"status": "infeasible", "makespan": None, "reason": "no robot reaches the cup"}
    fig = plan_gantt({**plan, "steps": []}, scene)
    assert bars(fig) == {} and vlines(fig) == []
    texts = [t.get_text() for t in fig.axes[0].texts]
    assert texts == ["no plan (infeasible): no robot reaches the cup"]
