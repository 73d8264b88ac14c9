"""The list of patterns the grounder's warm-up compiles, made from the tuning parts."""

from __future__ import annotations

import contextlib
import sys
from collections.abc import Sequence
from pathlib import Path

from hltl.bench import grounding as bench
from hltl.bench.grounding import CORPUS_DIR, load_corpus
from hltl.errors import GroundingError
from hltl.grounding import gate, warm
from hltl.grounding.offline import parse_instruction

# parts only measured, never tuned on: never run to make the list
MEASURED_ONLY = frozenset(getattr(bench, "MEASURED_ONLY", ())) | {"blind55"}


def met_on(parts: Sequence[str], root: Path) -> list[tuple[str, int, bool]]:
    """The patterns the grounder gates on every entry of ``parts`` (corpus part names) in more
    than one scene: their text, flags and whether the gate compiles them (False: compiled
    already, a module's constant)."""
    scenes: dict[tuple[str, int], set[str]] = {}
    built: dict[tuple[str, int], bool] = {}
    where = [""]
    real_may_match, real_gate = gate.may_match, gate._gate

    def may_match(pattern: str, flags: int, text: str) -> bool:
        scenes.setdefault((pattern, int(flags)), set()).add(where[0])
        return real_may_match(pattern, flags, text)

    def gated(pattern: str, flags: int, *, build: bool = True) -> gate._Gate:
        built[pattern, int(flags)] = build
        return real_gate(pattern, flags, build=build)

    gate.may_match, gate._gate = may_match, gated
    try:
        for part in parts:
            corpus = load_corpus(root / CORPUS_DIR / f"{part}.yaml", root)
            for entry in corpus.entries:
                where[0] = entry.scene
                with contextlib.suppress(GroundingError):
                    parse_instruction(entry.text, corpus.scenes[entry.scene])
    finally:
        gate.may_match, gate._gate = real_may_match, real_gate
    return sorted(
        (pattern, flags, built.get((pattern, flags), True))
        for (pattern, flags), seen in scenes.items()
        if len(seen) > 1
    )


def _write(patterns: list[tuple[str, int, bool]], parts: Sequence[str]) -> str:
    lines = [
        "# ruff: noqa: E501",
        '"""The patterns warm.warm_up compiles (made by python -m hltl.bench.warm_list)."""',
        f"# from the tuning parts {', '.join(parts)}, then ruff format",
        "",
        "PATTERNS: tuple[tuple[str, int, bool], ...] = (",
        *(f"    ({pattern!r}, {flags}, {build})," for pattern, flags, build in patterns),
        ")",
        "",
    ]
    return "\n".join(lines)


def main(argv: Sequence[str]) -> int:
    """``--write [part …]``: remake _warm_patterns.py from the given tuning parts (run from the
    repository root)."""
    if not argv or argv[0] != "--write":
        print("usage: python -m hltl.bench.warm_list --write [part ...]", file=sys.stderr)
        return 2
    parts = list(argv[1:]) or ["tuning", "blind22", "blind42"]
    if set(parts) & set(MEASURED_ONLY):
        print("the held-back part is never run", file=sys.stderr)
        return 2
    patterns = met_on(parts, Path.cwd())
    out = Path(warm.__file__).with_name("_warm_patterns.py")
    out.write_text(_write(patterns, parts), encoding="utf-8")
    print(f"{len(patterns)} patterns written to {out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
