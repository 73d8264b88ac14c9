"""``hltl bench perception``: run the perception benchmarks and record them."""

from __future__ import annotations

import argparse
import datetime
import shlex
import sys
import time

from hltl.bench.markdown import machine, write_section
from hltl.bench.perception import (
    _three,
    clutter_bench,
    evaluate_predictors,
    format_categories,
    format_loop,
    format_objects,
    format_outliers,
    format_people,
    format_prediction,
    format_skeleton,
    loop_bench,
    object_bench,
    people_bench,
    skeleton_bench,
    suite_walks,
)
from hltl.errors import HltlError
from hltl.perception.gru import load_model
from hltl.perception.skeleton import pose_python
from hltl.sim.dynamic import config_names
from hltl.sim.scenarios import get
from hltl.sim3d.gl import require_renderer
from hltl.world.scene import Scene


def _scenes(quick: bool) -> list[Scene]:
    """The benchmark's held-out cells (the learned segmenter never saw them)."""
    names = ("fig1",) if quick else ("fig1", "2-2", "4-2", "4-4-line", "4-4-square")
    return [get(n).scene for n in names]


def _layouts(quick: bool) -> int:
    return 1 if quick else 4


def run(args: argparse.Namespace) -> int:
    if args.walks < 1:
        raise HltlError(f"--walks: expected a positive integer, got {args.walks!r}")
    quick = args.quick
    if args.outliers:
        if args.write is not None:
            raise HltlError("--outliers writes nothing: drop --write")
        require_renderer()
        rows = clutter_bench(_scenes(quick), layouts=_layouts(quick), views=3)
        print(format_outliers(rows))
        return 0
    model = load_model()

    wall0, cpu0 = time.perf_counter(), time.process_time()

    def say(text: str) -> None:  # with the time so far: where a long run spends it
        wall, cpu = time.perf_counter() - wall0, time.process_time() - cpu0
        print(f"  [{wall:6.0f} s wall, {cpu:6.0f} s CPU] {text}", file=sys.stderr)

    say("prediction: held-out walks")
    pred = evaluate_predictors(1000, 2 if quick else args.walks, model)
    say("prediction: the simulator's walks in the catalogue cells")
    pred.append(("suite H-MOVE walks", _three(model, suite_walks(legs=1 if quick else 3), 2)))
    tables = ["### Trajectory prediction\n\n" + format_prediction(pred)]

    try:
        require_renderer()
    except HltlError as exc:  # no offscreen GL here: the prediction part only
        say(f"renders skipped: {exc}")
    else:
        scenes = _scenes(quick)
        say(f"objects: {len(scenes)} scene(s) x 3 camera poses")
        objs = object_bench(scenes, say)
        tables.append("### Objects on renders\n\n" + format_objects(objs))
        say("objects: cluttered layouts of the same cells")
        clutter = clutter_bench(scenes, layouts=_layouts(quick), views=3, progress=say)
        tables.append(
            "### Objects in clutter (held-out cells, random cameras and lights)\n\n"
            + format_objects(clutter)
            + "\n\nThe learned backend per category (found: localised and matched to the right "
            "scene id; named as another: the detection covering most of the object has another "
            "category):\n\n"
            + format_categories(clutter[-1])
            + "\n\nEvery found object over its backend's centroid target (frame: render order; "
            "share: its shown pixels over its whole unhidden silhouette):\n\n"
            + format_outliers(clutter)
        )
        say("people: two people crossing")
        people = people_bench(scenes[0], frames=10 if quick else 40, progress=say)
        tables.append("### People crossing on renders\n\n" + format_people(people))
        if pose_python().is_file():
            say("skeletons: MediaPipe pose worker")
            sk = skeleton_bench(scenes[0], frames=10 if quick else 40)
            tables.append("### Skeletons of the crossing people\n\n" + format_skeleton(sk))
        else:
            say(f"skeletons skipped: no pose environment at {pose_python()}")
        if args.loop_trials > 0 and not quick:
            say("closed loop: ground truth vs camera")
            loop = loop_bench(
                config_names(), args.loop_trials, say, unfiltered=args.loop_unfiltered
            )
            tables.append(
                "### Closed loop in the 3D simulator: ground truth vs camera\n\n"
                + format_loop(loop)
            )
    text = "\n\n".join(tables)
    print(text)
    if args.write is not None:
        cmd = "hltl bench perception" + (" --quick" if quick else "")
        cmd += " --loop-unfiltered" if args.loop_unfiltered and not quick else ""
        body = (
            f"## Perception\n\nCommand: `{cmd} --write {shlex.quote(str(args.write))}`  \n"
            f"Date: {datetime.date.today().isoformat()}. Machine: {machine()} (shared with other "
            "jobs). How to read it: docs/perception.md.\n\n" + text
        )
        write_section(args.write, "perception", body)
        print(f"wrote {args.write}", file=sys.stderr)
    return 0
