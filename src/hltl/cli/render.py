"""``hltl render``: a still of a scene from its fixed RGB-D camera, as a camera frame folder."""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import Any

from hltl.errors import HltlError
from hltl.sim3d.camera import CameraRenderer, FrameWriter, intrinsics
from hltl.sim3d.model import compile_scene, scene_cameras
from hltl.sim3d.stage import Stage
from hltl.world.scene import load_scene


def register(sub: Any) -> None:
    p: argparse.ArgumentParser = sub.add_parser(
        "render",
        help="render a scene's RGB-D camera (RGB, depth, segmentation) to a frame folder",
        description="Build the scene's 3D model (MuJoCo; cached) in its initial state and render "
        "its fixed camera (the scene's 'cameras:' block, default a RealSense-D435-like 640×480 "
        "side view) to DIR as camera.json, rgb/000000.png, depth/000000.npz (metres) and "
        "seg/000000.png (16-bit segment ids named in camera.json). Needs the sim3d extra.",
    )
    p.add_argument("--scene", required=True, type=Path, help="scene file (YAML or JSON)")
    p.add_argument("-o", "--output", required=True, type=Path, metavar="DIR", help="frame folder")
    p.add_argument("--camera", help="camera id from the scene's 'cameras:' (default: the first)")
    p.add_argument(
        "--geometry",
        choices=("collision", "visual"),
        default="visual",
        help="draw robots' visual meshes or their (faster) collision shapes",
    )
    p.add_argument("--no-cache", action="store_true", help="compile the model even if cached")
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    from rich.console import Console

    scene = load_scene(args.scene)
    cams = scene_cameras(scene)
    if args.camera is None:
        cam = cams[0]
    else:
        found = [c for c in cams if c.id == args.camera]
        if not found:
            have = ", ".join(c.id for c in cams)
            raise HltlError(
                f"--camera: no camera {args.camera!r} in {scene.source}; it has: {have}"
            )
        cam = found[0]
    sm = compile_scene(scene, cache=not args.no_cache)
    stage = Stage(sm)
    with CameraRenderer(sm, cam, geometry=args.geometry) as renderer:
        frame = renderer.render(stage.data)
    writer = FrameWriter(args.output, sm, cam)
    writer.write(frame, 0.0, stage.joints())
    writer.close()
    k = intrinsics(cam)
    seen = sorted({int(v) for v in frame.seg.reshape(-1)} - {0})
    names = ", ".join(f"{sm.segments[i].kind} {sm.segments[i].id}" for i in seen)
    console = Console(highlight=False)
    console.print(
        f"[bold]{args.output}[/]: camera {cam.id!r} {cam.width}×{cam.height}, "
        f"fx={k.fx:.1f} px, at {tuple(round(v, 2) for v in cam.position)} looking at "
        f"{tuple(round(v, 2) for v in cam.look_at)}"
    )
    valid = frame.depth[frame.depth > 0]
    if valid.size:
        console.print(f"depth {valid.min():.2f}–{valid.max():.2f} m; in view: {names}")
    return 0
