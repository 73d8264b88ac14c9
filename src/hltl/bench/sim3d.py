"""Speed of the 3D simulator: model compile vs cache, playback real-time factor, render times."""

from __future__ import annotations

import os
import statistics
import tempfile
import time
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from hltl.sim.episode import run_episode
from hltl.sim.scenarios import fig1
from hltl.sim3d.camera import CameraRenderer
from hltl.sim3d.driver import MujocoSimulator
from hltl.sim3d.model import compile_scene, scene_cameras
from hltl.sim3d.stage import Stage
from hltl.spec.hierarchy import spec_from_dict


@dataclass(frozen=True, slots=True)
class Sim3dBench:
    compile_s: float  # build + compile, no cache
    reload_s: float  # load of the cached compiled model
    sim_time: float  # simulated seconds of the two-arm episode
    wall_s: float  # wall seconds it took (model given, no rendering)
    steps: int  # posings (contact checks) in it
    render_ms: dict[tuple[str, str], tuple[float, float]]  # (geometry, channels) → wall, CPU ms
    demo_s: float | None  # the whole `hltl demo --3d` (episode + render + encode), if run
    load: float  # the machine's 1-minute load average when the renders ran

    @property
    def real_time_factor(self) -> float:
        return self.sim_time / self.wall_s if self.wall_s > 0 else float("inf")


def _median_ms(f: Callable[[], object], n: int) -> tuple[float, float]:
    """Median wall and CPU milliseconds of ``f`` (CPU: all of this process's threads, the
    renderer's included; on a shared machine it is the figure that does not depend on load)."""
    f()  # warm-up (first-frame GL set-up)
    wall, cpu = [], []
    for _ in range(n):
        t0, c0 = time.perf_counter(), time.process_time()
        f()
        wall.append((time.perf_counter() - t0) * 1000)
        cpu.append((time.process_time() - c0) * 1000)
    return statistics.median(wall), statistics.median(cpu)


def bench_sim3d(*, frames: int = 15, demo: Callable[[str], object] | None = None) -> Sim3dBench:
    """Measure the 3D simulator on the Fig. 1 two-arm cell (its delivery task, no events).

    ``demo``, when given, renders the 3D demo into a folder and is timed (the CLI passes
    ``hltl.viz.demo3d.run_demo3d``: bench sits below viz in the layer order).
    """
    cell = fig1()
    scene = cell.scene
    with tempfile.TemporaryDirectory() as tmp:
        t0 = time.perf_counter()
        compile_scene(scene, cache=Path(tmp))
        compile_s = time.perf_counter() - t0
        t0 = time.perf_counter()
        sm = compile_scene(scene, cache=Path(tmp))
        reload_s = time.perf_counter() - t0

    spec = spec_from_dict(cell.spec_dict, source="fig1")
    poses: list[float] = []

    def make(*a: Any, **kw: Any) -> MujocoSimulator:
        sim = MujocoSimulator(*a, model=sm, **kw)
        sim.on_pose.append(poses.append)
        return sim

    t0 = time.perf_counter()
    ep = run_episode(scene, spec=spec, seed=0, simulator=make)
    wall = time.perf_counter() - t0
    steps = len(poses)

    stage = Stage(sm)
    cam = scene_cameras(scene)[0]
    render_ms: dict[tuple[str, str], tuple[float, float]] = {}
    for geometry in ("collision", "visual"):
        with CameraRenderer(sm, cam, geometry=geometry) as r:

            def rgb(r: CameraRenderer = r) -> object:
                return r.render(stage.data, depth=False, seg=False)

            def full(r: CameraRenderer = r) -> object:
                return r.render(stage.data)

            render_ms[(geometry, "rgb")] = _median_ms(rgb, frames)
            render_ms[(geometry, "rgb+depth+seg")] = _median_ms(full, frames)
    load = os.getloadavg()[0]
    demo_s = None
    if demo is not None:
        with tempfile.TemporaryDirectory() as tmp:
            t0 = time.perf_counter()
            demo(tmp)
            demo_s = time.perf_counter() - t0
    return Sim3dBench(
        compile_s, reload_s, ep.metrics.time_cost, wall, steps, render_ms, demo_s, load
    )


def format_sim3d(b: Sim3dBench, command: str, when: str) -> str:
    """The benchmarks.md section body."""
    lines = [
        f"Command: `{command}` ({when}; this machine: 2 cores shared with other jobs, "
        "offscreen EGL on the CPU (Mesa llvmpipe)).",
        "",
        "| measure | value |",
        "|---|---|",
        f"| model build + compile (no cache) | {b.compile_s:.2f} s |",
        f"| compiled-model cache reload | {b.reload_s:.3f} s |",
        f"| two-arm Fig. 1 episode, arm playback + contact checks every 20 ms, no rendering | "
        f"{b.sim_time:.2f} s simulated ({b.steps} posings) in {b.wall_s:.2f} s wall: "
        f"real-time factor **{b.real_time_factor:.1f}** |",
    ]
    for (geometry, channel), (wall, cpu) in sorted(b.render_ms.items()):
        lines.append(
            f"| 640×480 {channel}, {geometry} geometry | {cpu:.0f} ms CPU, {wall:.0f} ms wall "
            "per frame |"
        )
    if b.demo_s is not None:
        lines.append(
            f"| `hltl demo --3d` (episode, 2 views × frames, MP4 + GIF) | {b.demo_s:.0f} s |"
        )
    lines += [
        "",
        f"Load average during the renders: {b.load:.1f} on 2 cores. CPU time is summed over the "
        "renderer's threads (Mesa llvmpipe uses both cores), so on an idle machine the wall time "
        "is below it and under load above it. Frames for perception are drawn without shadows "
        "(one lit "
        "colour pass, one segmentation pass that also yields the depth); the demo video with "
        "shadows. The real-time factor includes the executor and planner calls of the "
        "episode (the same loop as the discrete simulator); the arms are played back "
        "kinematically, so there is no physics step to pay for. Render times are medians "
        "after one warm-up frame.",
    ]
    return "\n".join(lines) + "\n"
