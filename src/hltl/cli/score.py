"""``hltl score``: recompute an episode's metrics from its execution log alone."""

from __future__ import annotations

import argparse
import json
from pathlib import Path
from typing import Any

from hltl.cli.run import print_metrics
from hltl.execution.log import read_log
from hltl.sim.invariants import check_invariants
from hltl.sim.metrics import compute_metrics


def register(sub: Any) -> None:
    p: argparse.ArgumentParser = sub.add_parser(
        "score",
        help="recompute metrics from an execution log",
        description="Read a JSON Lines execution log (from `hltl run --log`), recompute its "
        "metrics and re-check its invariants. Exit 0 when the episode succeeded and the log is "
        "sound, 1 otherwise.",
    )
    p.add_argument("log", type=Path, help="execution log (JSON Lines)")
    p.add_argument("--json", action="store_true", help="print the metrics as one JSON object")
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    records = read_log(args.log)
    metrics = compute_metrics(records).to_dict()
    problems = check_invariants(records)
    if args.json:
        print(json.dumps({**metrics, "invariant_problems": problems}))
    else:
        print_metrics(metrics)
        for p in problems:
            print(f"invariant: {p}")
    return 0 if metrics["success"] and not problems else 1
