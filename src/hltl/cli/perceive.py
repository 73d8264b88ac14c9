"""``hltl perceive``: run the perception stage on a frame folder and print what it sees."""

from __future__ import annotations

import argparse
import json
import os
import sys
from pathlib import Path
from typing import Any

from hltl.errors import HltlError
from hltl.perception.clipselect import CLIP_ENV, clip_embedder, crop_box, select_visual
from hltl.perception.frames import FrameFolder
from hltl.perception.language import Candidate, select
from hltl.perception.objects import BACKENDS
from hltl.perception.observe import Perceiver
from hltl.perception.overlay import draw_overlay
from hltl.perception.predict import make_predictor
from hltl.world.scene import load_scene


def frame_options(p: argparse.ArgumentParser, *, people_help: str) -> None:
    """Frame folder and backend options shared by ``perceive`` and ``node perception``."""
    p.add_argument("frames", type=Path, metavar="FRAMES_DIR", help="frame folder")
    p.add_argument("--scene", type=Path, help="scene file: match objects and people to its ids")
    p.add_argument(
        "--backend",
        choices=tuple(BACKENDS),
        help="object backend (default: segmentation when the folder has seg/, else depth-clusters)",
    )
    p.add_argument(
        "--people", choices=("segmentation", "depth", "fused", "yolo", "none"), help=people_help
    )


def register(sub: Any) -> None:
    p: argparse.ArgumentParser = sub.add_parser(
        "perceive",
        help="objects in 3D and tracked people from an RGB-D frame folder",
        description="Read a frame folder (camera.json, rgb/, depth/, optional seg/), detect and "
        "localise objects, track people and tie them to the scene's people. Prints the last "
        "frame's objects and people and what could not be decided.",
    )
    frame_options(
        p,
        people_help="person detector for the tracker: depth = body columns on the floor plan, "
        "fused = "
        "depth confirmed by YOLO every 10th frame (default: segmentation when the folder has "
        "seg/, else depth)",
    )
    p.add_argument(
        "--select",
        metavar="WORDS",
        help="pick the object these words name: by its label and the scene's words (MiniLM), "
        "or by what it looks like in the last frame with --clip",
    )
    p.add_argument(
        "--clip",
        type=Path,
        metavar="DIR",
        help=f"local CLIP weights (transformers format; default ${CLIP_ENV}): --select compares "
        "the words with each object's image crop",
    )
    p.add_argument("--predictor", choices=("cv", "goal", "gru"), default="gru",
                   help="forecast drawn by --viz (default: gru)")  # fmt: skip
    p.add_argument("--json", action="store_true", help="print every frame's observation as JSON")
    p.add_argument("--viz", type=Path, metavar="DIR", help="write overlay PNGs here")
    p.add_argument(
        "--skeleton",
        action="store_true",
        help="3D shoulders, elbows, wrists of tracked people (MediaPipe in the .venv-pose "
        "environment, its own process)",
    )
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    folder = FrameFolder(args.frames)
    scene = load_scene(args.scene) if args.scene is not None else None
    has_seg = folder.frame(0).seg is not None
    backend = args.backend or ("segmentation" if has_seg else "depth-clusters")
    people = args.people or ("segmentation" if has_seg else "depth")
    if args.skeleton and people == "none":
        raise HltlError("--skeleton: needs a person detector, got --people none")
    try:
        perceiver = Perceiver(scene, folder.camera, backend, people, skeleton=args.skeleton)
    except ValueError as exc:
        raise HltlError(str(exc)) from None
    try:
        return _run(args, folder, scene, backend, people, perceiver)
    finally:
        perceiver.close()


def _run(args: argparse.Namespace, folder: Any, scene: Any, backend: str, people: str,
         perceiver: Any) -> int:  # fmt: skip
    predictor = None
    if args.viz is not None and scene is not None:
        predictor = make_predictor(args.predictor, scene)
    observations = []
    frame = None
    for frame in folder:
        obs = perceiver.process(frame)
        observations.append(obs)
        if predictor is not None:
            predictor.observe(obs.t, [(p.person, p.position) for p in obs.people if p.person])
        if args.viz is not None:
            args.viz.mkdir(parents=True, exist_ok=True)
            draw_overlay(frame, folder.camera, obs, predictor, perceiver).save(
                args.viz / f"{frame.index:06d}.png"
            )
    selection = None
    clip = args.clip or os.environ.get(CLIP_ENV)
    by = "clip" if clip else "minilm"
    if args.select and clip and frame is not None:
        crops = []
        for k, o in enumerate(observations[-1].objects):
            box = crop_box(o.cylinder, folder.camera)
            if box is not None:
                u0, v0, u1, v1 = box
                crops.append((o.id or f"{o.label}#{k}", frame.rgb[v0:v1, u0:u1]))
        selection = select_visual(args.select, crops, clip_embedder(clip))
    elif args.select:
        selection = _select(args.select, observations[-1], scene)
    if args.json:
        out: dict[str, Any] = {"frames": [o.to_dict() for o in observations]}
        if selection is not None:
            out["select"] = {
                "query": selection.query,
                "id": selection.key,
                "similarity": round(selection.similarity, 3),
                "ambiguous": selection.ambiguous,
                "by": by,
                "message": selection.describe(),
            }
        print(json.dumps(out))
    else:
        _print(observations, backend, people, perceiver)
        if selection is not None:
            how = " (CLIP, by appearance)" if by == "clip" else ""
            print(f"select{how}: {selection.describe()}")
        if args.viz is not None:
            print(f"overlays: {args.viz}/")
    return 0


def _select(words: str, obs: Any, scene: Any) -> Any:
    cands = []
    for k, o in enumerate(obs.objects):
        ws = [o.label]
        key = o.id or f"{o.label}#{k}"
        if scene is not None and o.id is not None:
            so = scene.object(o.id)
            ws += [so.id, so.category, *so.aliases]
        cands.append(Candidate(key, tuple(dict.fromkeys(w.replace("_", " ") for w in ws))))
    return select(words, cands)


def _print(observations: list[Any], backend: str, people: str, perceiver: Any) -> None:
    from rich.console import Console
    from rich.table import Table

    console = Console(file=sys.stdout, highlight=False)
    last = observations[-1]
    ms = sorted(o.latency * 1000.0 for o in observations)
    console.print(
        f"{len(observations)} frame(s), backend {backend}, people by {people}; "
        f"latency median {ms[len(ms) // 2]:.0f} ms, max {ms[-1]:.0f} ms; last frame t={last.t:g}"
    )
    t = Table(title="objects")
    for c in ("id", "label", "position (m)", "radius", "height", "score", "pixels"):
        t.add_column(c)
    for o in last.objects:
        t.add_row(
            o.id or "-",
            o.label,
            ", ".join(f"{v:.3f}" for v in o.position),
            f"{o.cylinder.radius:.3f}",
            f"{o.cylinder.height:.3f}",
            f"{o.score:.2f}",
            str(o.pixels),
        )
    console.print(t)
    t = Table(title="people")
    for c in ("track", "id", "position (m)", "score", "skeleton (joints seen of 6)"):
        t.add_column(c)
    for p in last.people:
        sk = "-" if p.skeleton is None else str(p.skeleton.seen)
        t.add_row(
            p.track,
            p.person or "-",
            ", ".join(f"{v:.3f}" for v in p.position),
            f"{p.score:.2f}",
            sk,
        )
    console.print(t)
    for label, items in (
        ("not seen", last.missing),
        ("matches no scene object", last.unmatched),
        ("ambiguous", last.ambiguous),
        ("no live track", last.lost),
    ):
        if items:
            console.print(f"{label}: {', '.join(items)}")
    tracker = perceiver.tracker
    if tracker is not None and tracker.detector_name in ("yolo", "fused"):
        console.print(
            f"person detector: {tracker.detections} detections in {tracker.frames} frame(s), "
            f"{tracker.rejected} YOLO boxes rejected as too short for a person"
            + (
                f", {tracker.confirmed} depth bodies confirmed by YOLO, {tracker.added} added"
                if tracker.detector_name == "fused"
                else ""
            )
        )
