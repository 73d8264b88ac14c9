"""``hltl demo --3d``: the Fig. 1 story in the 3D simulator, as a video with a timeline."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

pytest.importorskip("mujoco")
pytest.importorskip("imageio")


def test_demo3d_short(tmp_path: Path) -> None:
    import imageio.v3 as iio

    from hltl.viz.demo3d import STRIP_H, TITLE_H, VIEW_H, VIEW_W, run_demo3d

    result = run_demo3d(out=tmp_path, short=True, speed=2.0)
    assert result.episode.success
    assert all(result.story.values()), result.story
    paths = dict(result.pictures)
    video = iio.imread(paths["3D video"])
    n_snaps = round(result.episode.metrics.time_cost / 0.2)
    assert video.shape[1:] == (TITLE_H + VIEW_H + STRIP_H, 2 * VIEW_W, 3)
    assert video.shape[0] >= n_snaps
    # the two views differ (fixed camera vs orbit), and the timeline grows
    first, last = video[0], video[-1]
    left = last[TITLE_H : TITLE_H + VIEW_H, :VIEW_W].astype(int)
    right = last[TITLE_H : TITLE_H + VIEW_H, VIEW_W:].astype(int)
    assert np.abs(left - right).mean() > 10
    strip0 = first[TITLE_H + VIEW_H :].astype(int)
    strip1 = last[TITLE_H + VIEW_H :].astype(int)
    assert np.abs(strip1 - strip0).mean() > 1
    assert paths["3D frame at the halt"].exists() and paths["3D animation"].exists()
