"""``hltl demo``: the Fig. 1 story end to end, its pictures and summary."""

from __future__ import annotations

from pathlib import Path

import pytest
import yaml
from PIL import Image

from hltl.cli.main import main
from hltl.execution.log import read_log
from hltl.sim.dynamic import FIG1_EVENTS
from hltl.viz.demo import story

ROOT = Path(__file__).resolve().parents[2]
PNG = b"\x89PNG\r\n\x1a\n"


def test_demo_short_tells_the_story_and_draws_it(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    out = tmp_path / "demo"
    assert main(["demo", "--short", "--out", str(out)]) == 0
    text = capsys.readouterr().out
    # the live timeline, then the summary
    assert text.index("halt") < text.index("takeover") < text.index("summary")
    for row in ("time cost", "replans", "replan latency median", "tokens", "H-IDLE", "F-DEL"):
        assert row in text
    assert "✗" not in text and "warning" not in text
    for name in ("gantt.png", "frame.png", "spec_tree.png"):
        assert (out / name).read_bytes()[:8] == PNG
        assert str(out / name) in text
    with Image.open(out / "animation.gif") as im:
        assert im.format == "GIF" and 2 <= im.n_frames <= 12
    # the log tells the story: halt with a reason, replan, takeover, success
    records = read_log(out / "episode.jsonl")
    assert all(story(records).values())
    halt = next(r for r in records if r.type == "halt")
    assert "not inside r1's workspace" in halt.reason
    end = records[-1]
    assert end.type == "episode_end" and end.success is True


def test_demo_without_pictures(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["demo", "--no-pictures", "--out", str(tmp_path)]) == 0
    assert [p.name for p in tmp_path.iterdir()] == ["episode.jsonl"]
    assert "summary" in capsys.readouterr().out


def test_demo_with_other_events_reports_a_missing_beat(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    calm = tmp_path / "calm.yaml"
    calm.write_text("events: []\n", encoding="utf-8")
    code = main(["demo", "--no-pictures", "--events", str(calm), "--out", str(tmp_path)])
    text = capsys.readouterr().out
    assert code == 0  # nobody moves: both deliveries as planned, no halt to tell
    assert "✗ halt with a reason" in text and "warning" not in text


def test_the_example_events_file_is_the_demo_default() -> None:
    data = yaml.safe_load((ROOT / "examples" / "events" / "demo.yaml").read_text("utf-8"))
    assert data["events"] == [dict(e) for e in FIG1_EVENTS]
