"""Checking an LLM's answer: JSON, H-LTLf validity, scene ids of the right kind, satisfiability."""

from __future__ import annotations

import json
from collections.abc import Mapping
from typing import Any

from hltl.errors import GroundingError, HltlError
from hltl.grounding.tree import check_deliveries, decode
from hltl.spec.hierarchy import HSpec, spec_from_dict
from hltl.spec.monitor import HierarchyMonitor
from hltl.spec.printer import atoms_in_order
from hltl.world.scene import Scene

# Argument kinds of each predicate (DESIGN.md §3).
ARG_KINDS: dict[str, tuple[str, ...]] = {
    "delivered": ("object", "human"),
    "placed": ("object", "surface"),
    "picked": ("object",),
    "holding": ("robot", "object"),
    "at": ("object", "surface"),
}

# Above this many leaf atoms the explicit search for an accepting run is skipped; every
# formula is still checked satisfiable (with one-shot children) by the spec module.
MAX_ATOMS_SEARCHED = 10


class AnswerError(GroundingError):
    """An answer was rejected for a reason the model can repair; the message says what."""


class ModelDeclined(GroundingError):
    """The model answered that the instruction cannot be grounded (its ``error`` field)."""


def check_answer(text: str | None, scene: Scene) -> tuple[HSpec, tuple[str, ...]]:
    """Validate a model's answer; return the spec and the scene ids it uses.

    Raises:
        AnswerError: not JSON, wrong shape, invalid H-LTLf, unknown or wrong-kind ids,
            unsatisfiable, or an object handed over twice.
        ModelDeclined: the answer's ``error`` field is set.
    """
    if not text or not text.strip():
        raise AnswerError("the answer is empty; expected a JSON object")
    try:
        data = json.loads(_strip_fences(text))
    except json.JSONDecodeError as exc:
        raise AnswerError(
            f"the answer is not valid JSON: {exc.msg} at character {exc.pos}"
        ) from None
    if not isinstance(data, Mapping):
        raise AnswerError(f"the answer must be a JSON object, got {type(data).__name__}")
    error = data.get("error")
    if error:
        raise ModelDeclined(f"the model could not ground the instruction: {error}")
    formulas = _formulas(data.get("formulas"))
    root = data.get("root", "p0")
    if not isinstance(root, str):
        raise AnswerError(f"'root' must be a formula name, got {root!r}")
    try:
        spec = spec_from_dict({"root": root, "formulas": formulas}, source="answer")
    except HltlError as exc:
        raise AnswerError(str(exc)) from None
    ids = check_entities(spec, scene)
    node = decode(spec)
    if node is not None:
        try:
            check_deliveries(node, {h.id: h.name for h in scene.humans})
        except GroundingError as exc:
            raise AnswerError(str(exc)) from None
    if not root_can_accept(spec):
        raise AnswerError(f"no sequence of events completes the root {spec.root}: unsatisfiable")
    return spec, ids


def _strip_fences(text: str) -> str:
    """Models without JSON mode like to wrap JSON in a Markdown code fence."""
    t = text.strip()
    if t.startswith("```"):
        t = t.split("\n", 1)[1] if "\n" in t else ""
        if t.rstrip().endswith("```"):
            t = t.rstrip()[:-3]
    return t


def _formulas(raw: Any) -> dict[str, Any]:
    if isinstance(raw, Mapping):
        return dict(raw)
    if isinstance(raw, list):
        out: dict[str, Any] = {}
        for k, entry in enumerate(raw):
            if not isinstance(entry, Mapping) or "name" not in entry or "formula" not in entry:
                raise AnswerError(
                    f"formulas[{k}] must be an object with 'name' and 'formula', got {entry!r}"
                )
            name = entry["name"]
            if not isinstance(name, str):
                raise AnswerError(f"formulas[{k}].name must be a string, got {name!r}")
            if name in out:
                raise AnswerError(f"formula {name} is given twice")
            out[name] = entry["formula"]
        return out
    raise AnswerError("'formulas' is missing; expected a list of {name, formula}")


def check_entities(spec: HSpec, scene: Scene) -> tuple[str, ...]:
    """Every predicate argument is a scene id of the right kind; returns the ids in order.

    Raises:
        AnswerError: naming the atom, the argument and what the scene has.
    """
    kinds = {
        "object": scene.object_ids,
        "human": scene.human_ids,
        "surface": scene.surface_ids,
        "robot": scene.robot_ids,
    }
    words = {"object": "objects", "human": "people", "surface": "surfaces", "robot": "robots"}
    seen: dict[str, None] = {}
    for _, f in spec.formulas:
        for atom in atoms_in_order(f):
            if not atom.is_predicate:
                continue
            expected = ARG_KINDS.get(atom.name)
            if expected is None:  # pragma: no cover - the spec parser knows the same predicates
                raise AnswerError(f"unknown predicate {atom.name!r}")
            for arg, kind in zip(atom.args, expected, strict=True):
                if arg not in kinds[kind]:
                    what = "person" if kind == "human" else kind
                    raise AnswerError(
                        f"{atom}: {arg!r} is not a{'n' if what == 'object' else ''} {what} of the "
                        f"scene; {words[kind]}: {', '.join(kinds[kind]) or 'none'}"
                    )
                seen.setdefault(arg)
    return tuple(seen)


def root_can_accept(spec: HSpec) -> bool:
    """Whether some trace of leaf events completes the root (breadth-first over monitor states).

    With more than ``MAX_ATOMS_SEARCHED`` atoms this returns True: the spec module's per-formula
    checks (satisfiable with one-shot children) are then what stands.
    """
    monitor = HierarchyMonitor(spec)
    props = sorted(monitor.atoms)
    if len(props) > MAX_ATOMS_SEARCHED:
        return True
    symbols: list[list[Any]] = [[]]
    for a in props:
        symbols += [[*s, a] for s in symbols]
    masks = [monitor.masks(s) for s in symbols]
    seen = {monitor.initial}
    frontier = [monitor.initial]
    while frontier:
        nxt = []
        for q in frontier:
            for m in masks:
                r = monitor.step_masks(q, m)
                if monitor.accepted(r):
                    return True
                if r not in seen:
                    seen.add(r)
                    nxt.append(r)
        frontier = nxt
    return False
