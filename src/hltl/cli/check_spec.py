"""``hltl check-spec``: validate H-LTLf spec files and show their trees and automaton sizes."""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path
from typing import Any

from hltl.errors import HltlError, error_line
from hltl.spec.automata import default_cache
from hltl.spec.hierarchy import load_spec
from hltl.spec.printer import to_string


def register(subparsers: Any) -> None:
    parser = subparsers.add_parser(
        "check-spec",
        help="validate H-LTLf specification files",
        description="Validate H-LTLf specs (YAML or JSON, DESIGN.md or Luo & Liu layout) and "
        "print each as a tree with the size of every formula's DFA.",
    )
    parser.add_argument("files", nargs="+", type=Path, metavar="FILE", help="spec files")
    parser.add_argument("--json", action="store_true", help="print machine-readable JSON")
    parser.set_defaults(func=run)


def _report(path: Path) -> dict[str, Any]:
    cache = default_cache()
    spec = load_spec(path, cache=cache)
    formulas = []
    for name, f in spec.formulas:
        dfa = cache.to_dfa(f)
        formulas.append(
            {
                "name": name,
                "formula": to_string(f),
                "level": spec.level_of(name),
                "parent": spec.parent.get(name),
                "children": list(spec.children[name]),
                "leaf": spec.is_leaf(name),
                "states": dfa.n_states,
                "edges": dfa.n_edges,
            }
        )
    return {
        "file": str(path),
        "valid": True,
        "root": spec.root,
        "depth": spec.depth,
        "formulas": formulas,
    }


def _print_tree(report: dict[str, Any]) -> None:
    from rich.console import Console
    from rich.text import Text
    from rich.tree import Tree

    by_name = {f["name"]: f for f in report["formulas"]}

    def label(name: str) -> Text:
        f = by_name[name]
        text = Text()
        text.append(name, style="bold")
        text.append(f": {f['formula']}  ")
        text.append(f"[{f['states']} states, {f['edges']} edges]", style="dim")
        return text

    head = Text()
    head.append(report["file"], style="bold")
    n = len(report["formulas"])
    head.append(f": valid ({n} formula{'s' if n != 1 else ''}, depth {report['depth']})")
    tree = Tree(head)

    def add(branch: Tree, name: str) -> None:
        node = branch.add(label(name))
        for child in by_name[name]["children"]:
            add(node, child)

    add(tree, report["root"])
    # wide enough never to crop a formula; the terminal wraps long lines itself
    Console(file=sys.stdout, width=10_000).print(tree)


def run(args: argparse.Namespace) -> int:
    """Check every file; print each valid one, an ``error: <file>: ...`` line for the others."""
    reports: list[dict[str, Any]] = []
    failed = False
    for path in args.files:
        try:
            report = _report(path)
        except HltlError as exc:
            failed = True
            message = str(exc)
            if not message.startswith(f"{path}:"):
                message = f"{path}: {message}"
            print(f"error: {error_line(message)}", file=sys.stderr)
            reports.append({"file": str(path), "valid": False, "error": message})
            continue
        reports.append(report)
        if not args.json:
            _print_tree(report)
    if args.json:
        print(json.dumps(reports, indent=2))
    return 1 if failed else 0
