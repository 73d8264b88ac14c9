"""``hltl ground``: turn an instruction into an H-LTLf spec; print its tree or JSON."""

from __future__ import annotations

import argparse
import json
from pathlib import Path
from typing import Any

from hltl import grounding
from hltl.errors import GroundingError
from hltl.fileio import write_output
from hltl.grounding.base import Grounding, check_instruction
from hltl.spec.hierarchy import load_spec, spec_to_dict
from hltl.spec.printer import to_string
from hltl.world.scene import Scene, load_scene


def register(sub: Any) -> None:
    p: argparse.ArgumentParser = sub.add_parser(
        "ground",
        help="turn an instruction into an H-LTLf spec",
        description="Ground an English instruction in a scene as an H-LTLf spec. With --running, "
        "the instruction updates that spec (add, then, first, cancel, instead, priority; see "
        "docs/grounding.md). Exit 0 on success, 1 if the instruction is rejected.",
    )
    p.add_argument("--scene", required=True, type=Path, help="scene file (YAML or JSON)")
    p.add_argument("--instruction", required=True, help="the instruction, in English")
    p.add_argument(
        "--grounder",
        choices=("offline", "llm", "local"),
        default="offline",
        help="offline parser (default), an OpenAI-compatible LLM, or a local GGUF model",
    )
    p.add_argument("--running", type=Path, help="spec being executed, to update")
    p.add_argument(
        "--llm-config", type=Path, help="TOML config for --grounder llm (default: env, ~/.config)"
    )
    p.add_argument("--model", type=Path, help="GGUF file for --grounder local")
    p.add_argument("--json", action="store_true", help="print one JSON object")
    p.add_argument("-o", "--output", type=Path, help="also write the spec to this file (YAML)")
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    check_instruction(args.instruction, "--instruction")
    scene = load_scene(args.scene)
    running = load_spec(args.running) if args.running is not None else None
    options: dict[str, Any] = {}
    if args.grounder == "llm" and args.llm_config is not None:
        options["config_path"] = args.llm_config
    if args.grounder == "local" and args.model is not None:
        options["model_path"] = args.model
    grounder = grounding.make_grounder(args.grounder, **options)
    try:
        result = grounder.ground(args.instruction, scene, running)
    except GroundingError as exc:
        if not exc.tokens_spent:
            raise
        # tokens are paid for whether the answer was used or not: report them on failure too
        tokens = {"prompt": exc.prompt_tokens, "completion": exc.completion_tokens}
        if args.json:
            print(json.dumps({"error": str(exc), "tokens": tokens}))
        raise GroundingError(
            f"{exc} ({exc.prompt_tokens} prompt + {exc.completion_tokens} completion tokens spent)",
            prompt_tokens=exc.prompt_tokens,
            completion_tokens=exc.completion_tokens,
        ) from None
    spec = spec_to_dict(result.spec)
    if args.output is not None:
        import yaml

        write_output(args.output, "the spec", yaml.safe_dump(spec, sort_keys=False))
    if args.json:
        out: dict[str, Any] = {
            "spec": spec,
            "entities": list(result.entities),
            "tokens": result.tokens.to_dict(),
        }
        if result.update is not None:
            u = result.update
            out["update"] = {
                "kind": u.kind,
                "kept": list(u.kept),
                "changed": list(u.changed),
                "added": list(u.added),
                "removed": list(u.removed),
            }
        print(json.dumps(out))
    else:
        _print_tree(result, scene)
    return 0


def _print_tree(result: Grounding, scene: Scene) -> None:
    from rich.console import Console
    from rich.markup import escape
    from rich.tree import Tree

    spec = result.spec

    def label(name: str) -> str:
        return f"[bold]{name}[/]  {escape(to_string(spec.formula(name)))}"

    def build(name: str, node: Tree) -> None:
        for child in spec.children[name]:
            build(child, node.add(label(child)))

    tree = Tree(label(spec.root))
    build(spec.root, tree)
    console = Console()
    console.print(tree)
    names = {h.id: h.name for h in scene.humans}
    ents = ", ".join(f"{e} ({names[e]})" if e in names else e for e in result.entities)
    console.print(f"entities: {escape(ents) or 'none'}")
    t = result.tokens
    console.print(f"tokens: {t.prompt} prompt + {t.completion} completion")
    if result.update is not None:
        u = result.update
        console.print(
            f"update ({u.kind}): kept {', '.join(u.kept) or '-'}; changed "
            f"{', '.join(u.changed) or '-'}; added {', '.join(u.added) or '-'}; removed "
            f"{', '.join(u.removed) or '-'}"
        )
