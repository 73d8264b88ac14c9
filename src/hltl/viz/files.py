"""What a file to draw holds: a plan (JSON), an execution log (JSON Lines) or an H-LTLf spec."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any, Literal

from hltl.errors import PlanFormatError
from hltl.execution.log import LogRecord, parse_log
from hltl.fileio import MAX_LOG_BYTES, load_data, read_text, try_json
from hltl.spec.hierarchy import HSpec, spec_from_dict
from hltl.world.scene import Scene, load_scene

SourceKind = Literal["plan", "log", "spec"]

EXPECTED = (
    "expected a plan (JSON with status and steps, from 'hltl plan --json'), an execution log "
    "(JSON Lines starting with episode_start, from 'hltl run --log') or an H-LTLf spec "
    "(YAML or JSON with root and formulas)"
)


@dataclass(frozen=True, slots=True)
class Source:
    """A loaded file: exactly one of ``plan``, ``records``, ``spec`` is set, as ``kind`` says."""

    kind: SourceKind
    path: Path
    plan: dict[str, Any] | None = None
    records: tuple[LogRecord, ...] = ()
    spec: HSpec | None = None


def load_source(path: str | Path) -> Source:
    """Read ``path`` and tell what it is by its content (the suffix only breaks ties).

    Raises:
        PlanFormatError: unreadable, or none of the three formats (the message names the file
            and what was expected); also a malformed plan or log.
        SpecValidationError, SpecSyntaxError: a spec that does not validate.
    """
    p = Path(path)
    text = read_text(p, "file", PlanFormatError, MAX_LOG_BYTES)
    if not text.strip():
        raise PlanFormatError(f"{p}: the file is empty; {EXPECTED}")
    whole_json, data = try_json(text, str(p), PlanFormatError)
    if whole_json and isinstance(data, dict) and data.get("type") == "episode_start":
        return _log(p, text)  # a log of one line is valid JSON too
    if not whole_json and _looks_like_jsonl(text):
        return _log(p, text)
    if not whole_json:
        if p.suffix.lower() == ".json":
            raise PlanFormatError(f"{p}: not valid JSON; {EXPECTED}")
        data = load_data(text, str(p), PlanFormatError, as_json=False)
    if isinstance(data, dict) and "steps" in data and "status" in data:
        return Source("plan", p, plan=data)
    if (isinstance(data, dict) and "formulas" in data) or (
        isinstance(data, list) and data and all(isinstance(level, dict) for level in data)
    ):
        return Source("spec", p, spec=spec_from_dict(data, str(p)))
    found = type(data).__name__ if not isinstance(data, dict) else f"keys {sorted(data)[:6]}"
    raise PlanFormatError(f"{p}: found {found}; {EXPECTED}")


def _looks_like_jsonl(text: str) -> bool:
    first = text.lstrip().splitlines()[0]
    try:
        ok, rec = try_json(first, "", PlanFormatError)
    except PlanFormatError:
        return False
    if not ok:
        return False
    return isinstance(rec, dict) and "type" in rec and "t" in rec


def _log(p: Path, text: str) -> Source:
    return Source("log", p, records=tuple(parse_log(text, str(p))))


def plan_scene(source: Source, scene: str | Path | None) -> Scene:
    """The scene a plan was made for: ``scene`` if given, else the file its ``scene`` field
    names (as given, or next to the plan file).

    Raises:
        PlanFormatError: no scene given and the plan's cannot be found.
    """
    if scene is not None:
        return load_scene(scene)
    named = (source.plan or {}).get("scene")
    if isinstance(named, str) and named:
        for candidate in (Path(named), source.path.parent / named):
            if candidate.is_file():
                return load_scene(candidate)
        raise PlanFormatError(
            f"{source.path}: the plan's scene {named!r} was not found (from here or next to the "
            "plan); give it with --scene"
        )
    raise PlanFormatError(f"{source.path}: the plan names no scene; give it with --scene")
