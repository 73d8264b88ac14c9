"""Animations: frames, what a frame shows, GIF / HTML / MP4 output."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest
from PIL import Image

from hltl.errors import BackendUnavailableError
from hltl.execution.log import LogRecord
from hltl.planner import PlanResult
from hltl.viz.animate import (
    animate,
    animate_episode,
    animate_plan,
    draw_frame,
    frame_times,
    save_animation,
)
from hltl.viz.track import track_from_log, track_from_plan
from hltl.world.scene import Scene


def artist(fig: Any, gid: str) -> Any:
    found = [a for a in fig.findobj() if a.get_gid() == gid]
    assert len(found) == 1, gid
    return found[0]


def xy(line: Any) -> tuple[float, float] | None:
    xs, ys = line.get_data()
    return None if len(xs) == 0 else (float(xs[-1]), float(ys[-1]))


def test_frame_times(paper_plan: PlanResult, scene: Scene) -> None:
    track = track_from_plan(paper_plan, scene)
    ts = frame_times(track, fps=10, max_frames=200)
    assert ts[0] == 0.0 and ts[-1] == pytest.approx(track.end + 0.5)
    assert len(ts) == 16  # 1.5 s at 10 frames per second, both ends included
    assert len(frame_times(track, fps=100, max_frames=20)) == 20
    with pytest.raises(ValueError, match="fps"):
        frame_times(track, fps=0)


def test_a_frame_shows_hands_objects_people_and_the_halt(
    demo_records: tuple[LogRecord, ...], scene: Scene
) -> None:
    track = track_from_log(demo_records)
    halt = next(r for r in demo_records if r.type == "halt")
    t = halt.t + 0.02
    fig = draw_frame(track, t)
    for rid in scene.robot_ids:
        assert xy(artist(fig, f"hand:{rid}")) == pytest.approx(track.hand_position(rid, t)[:2])
    # r1 still holds the bottle (the handover was halted): it is drawn in r1's hand
    assert xy(artist(fig, "object:bottle")) == pytest.approx(track.hand_position("r1", t)[:2])
    assert xy(artist(fig, "person:A")) == pytest.approx(track.human_position("A", t)[:2])
    # the forecast of the background plan made at the halt is drawn from A to where it puts A
    pred = next(r for r in demo_records if r.type == "predict" and r.t == halt.t)
    assert xy(artist(fig, "forecast:A")) == pytest.approx(pred.humans["A"]["position"][:2])
    assert xy(artist(fig, "forecast:B")) is None
    assert artist(fig, "status").get_text().startswith("HALT (INTRUSION)")
    assert "(halted)" in artist(fig, "step").get_text()
    assert artist(fig, "clock").get_text() == f"t = {t:5.2f} s"
    # later, A has the bottle
    end = draw_frame(track, track.end + 0.1)
    ax_, ay_ = track.human_position("A", track.end)[:2]
    bx, by = xy(artist(end, "object:bottle")) or (0.0, 0.0)
    assert abs(bx - ax_) < 0.15 and abs(by - ay_) < 0.15
    assert "all goals met" in artist(end, "step").get_text()


def test_gif_has_the_frames(demo_records: tuple[LogRecord, ...], tmp_path: Path) -> None:
    anim = animate_episode(demo_records, fps=5, max_frames=8, dpi=40)
    path = save_animation(anim, tmp_path / "a.gif")
    with Image.open(path) as im:
        assert im.format == "GIF" and im.n_frames == 8


def test_plan_replay_and_html(chips_plan: PlanResult, scene: Scene, tmp_path: Path) -> None:
    anim = animate_plan(chips_plan, scene, fps=4, max_frames=5, dpi=40)
    path = save_animation(anim, tmp_path / "a.html")
    text = path.read_text(encoding="utf-8")
    assert "<script" in text and "anim" in text.lower() and len(text) > 10_000


def test_mp4_needs_ffmpeg(
    paper_plan: PlanResult, scene: Scene, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr("hltl.viz.animate.shutil.which", lambda name: None)
    anim = animate(track_from_plan(paper_plan, scene), fps=2, max_frames=2, dpi=30)
    with pytest.raises(BackendUnavailableError, match=r"ffmpeg.*gif or html"):
        save_animation(anim, tmp_path / "a.mp4")
    assert not (tmp_path / "a.mp4").exists()
    # the fallback the message suggests works on the same animation
    assert save_animation(anim, tmp_path / "a.gif").stat().st_size > 0
