"""``hltl perception``: train and evaluate the trajectory predictors."""

from __future__ import annotations

import argparse
import json
import shlex
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any, TypeVar

from hltl.bench.perception import TEST_SETS, _three, evaluate_predictors
from hltl.errors import HltlError
from hltl.perception.evaluate import HORIZONS, score
from hltl.perception.forecast import F64
from hltl.perception.gru import SHIPPED, load_model, train
from hltl.perception.learned import SHIPPED as DETECTOR_WEIGHTS
from hltl.perception.oracle import LIBRARY_SEED, LibraryForecaster, OraclePredictor, build_library
from hltl.perception.walks import KINDS, MIX, generate_walks
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
    tr.add_argument(
        "--mix",
        default=",".join(f"{m:g}" for m in MIX),
        help=f"weights of the walks' leg kinds {','.join(KINDS)} (default %(default)s)",
    )
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
    orc = psub.add_parser(
        "oracle-predictor",
        help="how good a forecaster can be on a held-out set: one that knows the walk generator",
        description="Score cv, goal, gru and a forecaster that knows the walk generator "
        "(hltl.perception.oracle: nearest windows of a library of generated walks of the same "
        "leg mix) on one held-out test set of eval-predictor.",
    )
    orc.add_argument(
        "--set", default="wandering", choices=[name for name, _ in TEST_SETS], help="test set"
    )
    orc.add_argument("--seed", type=int, default=1000, help="seed of the held-out walks")
    orc.add_argument("--walks", type=int, default=40, help="20 s walks in the test set")
    orc.add_argument("--library", type=int, default=1000, help="20 s walks in the library")
    orc.add_argument("--k", type=int, default=100, help="nearest windows per forecast")
    orc.add_argument("--json", action="store_true", help="print the scores as JSON")
    orc.set_defaults(func=run_oracle)


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
    recorded: tuple[str, ...] = (),
) -> R:
    """Check ``options`` are positive, then train with ``fit(out, seed=…, <options>…,
    command=…, progress=…)`` under one rich bar per phase; ``command`` records how to
    reproduce the weights (the file's ``meta``), with the ``recorded`` options too (``fit``
    has those bound already)."""
    from rich.console import Console
    from rich.progress import Progress

    for name in options:
        _positive(name, getattr(args, name))
    out = shipped if args.out is None else args.out
    values = {name: getattr(args, name) for name in ("seed", *options)}
    shown = {**values, **{name: getattr(args, name) for name in recorded}}
    command = f"hltl perception {action} " + shlex.join(
        f"--{name}={value}" for name, value in shown.items()
    )
    with Progress(console=Console(stderr=True), transient=True) as bar:
        try:
            return fit(out, **values, command=command, progress=_phases(bar))
        except OSError as exc:
            raise HltlError(f"{out}: cannot write weights ({exc.strerror})") from None


def _mix(text: str) -> tuple[float, ...]:
    """``--mix``: one non-negative weight per leg kind, not all zero."""
    try:
        mix = tuple(float(v) for v in text.split(","))
    except ValueError:
        mix = ()
    if len(mix) != len(KINDS) or min(mix) < 0 or sum(mix) <= 0 or not all(m < 1e9 for m in mix):
        raise HltlError(
            f"--mix: expected {len(KINDS)} comma-separated non-negative weights "
            f"({','.join(KINDS)}), not all zero; got {text[:80]!r}"
        )
    return mix


def run_train(args: argparse.Namespace) -> int:
    mix = _mix(args.mix)

    def fit(out: Path, **kw: Any) -> Any:
        return train(out, mix=mix, **kw)

    res = _trained(args, "train-predictor", ("walks", "epochs"), SHIPPED, fit, ("mix",))
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


def run_oracle(args: argparse.Namespace) -> int:
    for name in ("walks", "library", "k"):
        _positive(name, getattr(args, name))
    k, mix = next((i, m) for i, (n, m) in enumerate(TEST_SETS) if n == args.set)
    walks = generate_walks(args.seed + k, args.walks, mix=mix)
    data = [(w.observed, w.true, w.stops) for w in walks]
    scores = _three(load_model(), data, 2)
    library = build_library(LIBRARY_SEED, args.library, mix)
    if args.k > len(library.obs):
        raise HltlError(f"--k: at most the library's {len(library.obs)} windows, got {args.k}")
    forecaster = LibraryForecaster(library, args.k)

    def oracle(stops: F64) -> OraclePredictor:
        return OraclePredictor(stops, forecaster)

    scores.append(score("oracle", oracle, data, 2))
    cv = scores[0]
    if args.json:
        out = [dict(s.to_dict(), vs_cv=_margins(s, cv)) for s in scores]
        print(json.dumps({"set": args.set, "library_windows": len(library.obs), "scores": out}))
        return 0
    from rich.console import Console
    from rich.table import Table

    table = Table(
        title=f"{args.set} (seed {args.seed + k}, {args.walks} walks); oracle: "
        f"{len(library.obs)} library windows, k {args.k}"
    )
    for col in ("predictor", "samples", "ADE@1s", "FDE@1s", "ADE@2s", "FDE@2s", "below CV"):
        table.add_column(col, justify="left" if col == "predictor" else "right")
    for s in scores:
        cells = [f"{v:.3f}" for pair in zip(s.ade, s.fde, strict=True) for v in pair]
        margins = " / ".join(f"{m:+.0%}" for m in _margins(s, cv))
        table.add_row(s.predictor, str(s.samples), *cells, margins)
    Console(file=sys.stdout).print(table)
    return 0


def _margins(s: Any, cv: Any) -> list[float]:
    """How far below constant velocity: ADE@1s, FDE@1s, ADE@2s, FDE@2s."""
    pairs = zip(s.ade, s.fde, cv.ade, cv.fde, strict=True)
    return [round(1.0 - v / c, 4) for a, f, ca, cf in pairs for v, c in ((a, ca), (f, cf))]
