"""What ``hltl run --sim mujoco`` adds to an episode: the 3D simulator and its camera frames."""

from __future__ import annotations

import argparse
import functools
from pathlib import Path
from typing import Any

from hltl.sim3d.driver import MujocoSimulator
from hltl.sim3d.model import compile_scene
from hltl.sim3d.perceived import CameraSimulator
from hltl.sim3d.record import FrameRecorder
from hltl.world.scene import Scene


def add_simulator_arguments(p: argparse.ArgumentParser, sim_help: str) -> None:
    """``--sim`` (discrete or mujoco) and ``--timing`` (the 3D simulator's action durations)."""
    p.add_argument("--sim", choices=("discrete", "mujoco"), default="discrete", help=sim_help)
    p.add_argument(
        "--timing",
        choices=("motion", "cost"),
        default="motion",
        help="--sim mujoco: actions last as long as their arm motions, or the cost model says",
    )


def simulator_options(
    scene: Scene,
    timing: str,
    frames: Path | None,
    perception: str = "truth",
    objects: str = "segmentation",
) -> tuple[dict[str, Any], FrameRecorder | None]:
    """``run_episode`` keywords for the 3D simulator (model compiled or loaded from the cache
    before the episode starts) and the frame recorder, if frames are wanted. ``perception``
    ``camera`` observes through the rendered camera (:mod:`hltl.sim3d.perceived`) with the
    ``objects`` backend."""
    model = compile_scene(scene)
    extra: dict[str, Any] = {
        "simulator": functools.partial(MujocoSimulator, timing=timing, model=model)
    }
    if perception == "camera":
        extra["simulator"] = functools.partial(
            CameraSimulator, timing=timing, model=model, backend=objects
        )
    recorder = None
    if frames is not None:
        recorder = FrameRecorder(frames)
        extra["hooks"] = (recorder,)
    return extra, recorder
