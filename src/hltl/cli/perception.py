"""``hltl perception``: train and evaluate the trajectory predictors."""

from __future__ import annotations

import argparse
import json
import shlex
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any, TypeVar

from hltl.bench.perception import evaluate_predictors
from hltl.errors import HltlError
from hltl.perception.evaluate import HORIZONS
from hltl.perception.gru import SHIPPED, load_model, train
from hltl.perception.learned import SHIPPED as DETECTOR_WEIGHTS
from hltl.sim3d.dataset import train_detector
from hltl.sim3d.gl import require_renderer

R = TypeVar("R")


def register(sub: Any) -> None:
    p: argparse.ArgumentParser = sub.add_parser(
        "perception",
        help="train and evaluate the trajectory predictors",
        description="Train the GRU trajectory predictor on seeded walks of the human model and "
        "compare it with constant velocity and the goal-directed predictor.",
    )
    psub = p.add_subparsers(dest="perception", metavar="ACTION", required=True)
    tr = psub.add_parser("train-predictor", help="train the GRU on seeded walks")
    tr.add_argument("--out", type=Path, help="weights file (default: the shipped one)")
    tr.add_argument("--seed", type=int, default=0, help="seed of walks and initialisation")
    tr.add_argument("--walks", type=int, default=600, help="20 s walks to train on")
    tr.add_argument("--epochs", type=int, default=12, help="passes over the windows")
    tr.set_defaults(func=run_train)
    td = psub.add_parser(
        "train-detector",
        help="train the learned object segmenter on labelled renders of randomised cells",
    )
    td.add_argument("--out", type=Path, help="weights file (default: the shipped one)")
    td.add_argument("--seed", type=int, default=0, help="seed of layouts, views and weights")
    td.add_argument("--layouts", type=int, default=6, help="cluttered layouts per training cell")
    td.add_argument("--views", type=int, default=8, help="random views per layout")
    td.add_argument("--epochs", type=int, default=30, help="passes over the renders")
    td.set_defaults(func=run_train_detector)
    ev = psub.add_parser(
        "eval-predictor", help="ADE/FDE at 1 s and 2 s of cv, goal and gru on held-out walks"
    )
    ev.add_argument("--weights", type=Path, help="GRU weights (default: the shipped ones)")
    ev.add_argument("--seed", type=int, default=1000, help="seed of the held-out walks")
    ev.add_argument("--walks", type=int, default=30, help="20 s walks per test set")
    ev.add_argument("--json", action="store_true", help="print the scores as JSON")
    ev.set_defaults(func=run_eval)


def _positive(name: str, value: int) -> None:
    if value < 1:
        raise HltlError(f"--{name}: expected a positive integer, got {value!r}")


def _phases(bar: Any) -> Callable[[str, float], None]:
    """A progress callback (phase name, fraction done) drawing one rich bar per phase."""
    tasks: dict[str, Any] = {}

    def progress(phase: str, frac: float) -> None:
        if phase not in tasks:
            tasks[phase] = bar.add_task(phase, total=1.0)
        bar.update(tasks[phase], completed=frac)

    return progress


def _trained(
    args: argparse.Namespace,
    action: str,
    options: tuple[str, ...],
    shipped: Path,
    fit: Callable[..., R],
) -> R:
    """Check ``options`` are positive, then train with ``fit(out, seed=…, <options>…,
    command=…, progress=…)`` under one rich bar per phase; ``command`` records how to
    reproduce the weights (the file's ``meta``)."""
    from rich.console import Console
    from rich.progress import Progress

    for name in options:
        _positive(name, getattr(args, name))
    out = shipped if args.out is None else args.out
    values = {name: getattr(args, name) for name in ("seed", *options)}
    command = f"hltl perception {action} " + shlex.join(
        f"--{name}={value}" for name, value in values.items()
    )
    with Progress(console=Console(stderr=True), transient=True) as bar:
        try:
            return fit(out, **values, command=command, progress=_phases(bar))
        except OSError as exc:
            raise HltlError(f"{out}: cannot write weights ({exc.strerror})") from None


def run_train(args: argparse.Namespace) -> int:
    res = _trained(args, "train-predictor", ("walks", "epochs"), SHIPPED, train)
    print(
        f"trained on {res.samples} windows of {args.walks} walks in {res.seconds:.0f} s: "
        f"validation ADE@2s {res.val_ade:.3f} m (goal-directed {res.val_prior_ade:.3f} m)"
    )
    print(f"wrote {res.path}")
    return 0


def run_train_detector(args: argparse.Namespace) -> int:
    require_renderer()
    res = _trained(
        args, "train-detector", ("layouts", "views", "epochs"), DETECTOR_WEIGHTS, train_detector
    )
    iou = ", ".join(f"{k} {v:.2f}" for k, v in res.val_iou.items())
    print(
        f"trained on {res.images} renders in {res.seconds:.0f} s: validation IoU {iou}; "
        f"wrote {res.path}"
    )
    return 0


def run_eval(args: argparse.Namespace) -> int:
    _positive("walks", args.walks)
    try:
        model = load_model(args.weights)
    except (FileNotFoundError, ValueError) as exc:
        raise HltlError(str(exc)) from None
    results = evaluate_predictors(args.seed, args.walks, model)
    if args.json:
        print(json.dumps({name: [s.to_dict() for s in scores] for name, scores in results}))
        return 0
    from rich.console import Console
    from rich.table import Table

    table = Table(title=f"trajectory prediction, held-out walks (seed {args.seed})")
    table.add_column("test set")
    table.add_column("predictor")
    table.add_column("samples", justify="right")
    for h in HORIZONS:
        table.add_column(f"ADE@{h:g}s", justify="right")
        table.add_column(f"FDE@{h:g}s", justify="right")
    for name, scores in results:
        for s in scores:
            cells = [f"{v:.3f}" for pair in zip(s.ade, s.fde, strict=True) for v in pair]
            table.add_row(name, s.predictor, str(s.samples), *cells)
    Console(file=sys.stdout).print(table)
    return 0
