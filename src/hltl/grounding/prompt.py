"""The LLM prompt: rules, few-shot examples chosen for the instruction, the scene, the schema."""

from __future__ import annotations

import json
import re
from dataclasses import dataclass
from typing import Any

from hltl.grounding.base import scene_graph
from hltl.world.scene import Scene

SYSTEM = "\n".join(
    (
        'Instruction to hierarchical LTLf, as JSON only: {"root": "p0", "formulas": [{"name": ..., '
        '"formula": ...}], "entities": [ids], "error": null}',
        '- Leaves p100, p200, ...: "F delivered(<object>, <person>)" or "F placed(<object>, '
        '<surface>)", one per task.',
        '- Others (p0, p1, ...) combine children by name: A and B "F p100 & F p200"; A then B '
        '"F (p100 & F p200)"; A or B "F p100 | F p200"; one task "F p100".',
        '- Scene ids only (aliases in parentheses). Unknown or ambiguous: "error" says why, no '
        "formulas.",
    )
)

# Few-shot examples over their own small scene, so that the model copies the format, not the ids.
# Each shows one structure the rules state in words; a query carries only the examples whose
# structure its instruction has (a plain list needs none), which keeps a query's tokens close to
# what its task needs (the paper's point: few tokens per query).
EXAMPLE_SCENE = """\
objects: mug; book (novel)
people: X (Person X, Xia); Y (Person Y)
surfaces: desk"""


@dataclass(frozen=True, slots=True)
class Example:
    """A few-shot pair and the structures it demonstrates."""

    text: str
    answer: dict[str, Any]
    shows: frozenset[str]  # "order", "choice"


def _answer(formulas: dict[str, str], entities: list[str]) -> dict[str, Any]:
    return {
        "root": "p0",
        "formulas": [{"name": n, "formula": f} for n, f in formulas.items()],
        "entities": entities,
        "error": None,
    }


EXAMPLES: tuple[Example, ...] = (
    Example(
        "Put the novel on the desk, then give Xia the mug",
        _answer(
            {
                "p0": "F (p100 & F p200)",
                "p100": "F placed(book, desk)",
                "p200": "F delivered(mug, X)",
            },
            ["book", "desk", "mug", "X"],
        ),
        frozenset({"order"}),
    ),
    Example(
        "Give Person Y the mug or the book",
        _answer(
            {
                "p0": "F p100 | F p200",
                "p100": "F delivered(mug, Y)",
                "p200": "F delivered(book, Y)",
            },
            ["mug", "Y", "book"],
        ),
        frozenset({"choice"}),
    ),
    Example(
        "First put the book on the desk, then give X either the mug or the book",
        _answer(
            {
                "p0": "F (p100 & F p1)",
                "p100": "F placed(book, desk)",
                "p1": "F p200 | F p300",
                "p200": "F delivered(mug, X)",
                "p300": "F delivered(book, X)",
            },
            ["book", "desk", "mug", "X"],
        ),
        frozenset({"order", "choice"}),
    ),
)

_CUES = {
    "order": re.compile(r"\b(then|after|afterwards|before|first|once|next|later|followed)\b", re.I),
    "choice": re.compile(r"\b(or|either|whichever|one of|any of)\b", re.I),
}


def structures(instruction: str) -> frozenset[str]:
    """The structures (ordering, choice) an instruction's wording hints at."""
    return frozenset(name for name, cue in _CUES.items() if cue.search(instruction))


def select_examples(instruction: str) -> tuple[Example, ...]:
    """The few-shot examples for ``instruction``: one that shows exactly its structures, if any.

    A plain instruction ("give A the bottle and B the chips") gets none: the rules say it all.
    """
    wanted = structures(instruction)
    return tuple(e for e in EXAMPLES if wanted and e.shows == wanted)


def user_message(instruction: str, scene_text: str) -> str:
    return f"Scene:\n{scene_text}\nInstruction: {instruction.strip()}"


def build_messages(
    instruction: str, scene: Scene, *, examples: bool = True
) -> list[dict[str, str]]:
    """The chat messages for one grounding query (system, selected few-shot pairs, the query)."""
    messages = [{"role": "system", "content": SYSTEM}]
    if examples:
        for ex in select_examples(instruction):
            messages.append({"role": "user", "content": user_message(ex.text, EXAMPLE_SCENE)})
            messages.append({"role": "assistant", "content": json.dumps(ex.answer)})
    messages.append({"role": "user", "content": user_message(instruction, scene_graph(scene))})
    return messages


def repair_message(error: str) -> str:
    """What is sent back after a rejected answer."""
    return (
        f"Your answer was rejected: {error}\n"
        "Answer again with the corrected JSON only, following the rules and the scene's ids."
    )


def answer_schema(scene: Scene, *, grammar: bool = False) -> dict[str, Any]:
    """JSON schema of an answer; entity ids are restricted to the scene's.

    Written for OpenAI's strict structured outputs (every property required, no extra keys,
    formulas as a list since free-form keys are not allowed). With ``grammar`` (for llama.cpp,
    which compiles the schema into a grammar) the arrays are bounded and formula names and texts
    must match patterns over the scene's ids, so a small model can only write well-formed,
    finite answers that name scene entities.
    """
    ids = [*scene.object_ids, *scene.human_ids, *scene.surface_ids]
    schema = _schema(ids)
    if grammar:
        props = schema["properties"]
        item = props["formulas"]["items"]["properties"]
        item["name"]["pattern"] = "^p[0-9]{1,4}$"
        item["formula"]["pattern"] = _formula_pattern(scene)
        props["formulas"]["maxItems"] = min(24, 2 * len(scene.object_ids) + 4)
        props["entities"]["maxItems"] = max(1, len(ids))
    return schema


def _formula_pattern(scene: Scene) -> str:
    def alt(names: tuple[str, ...]) -> str:
        return "(" + "|".join(re.escape(n) for n in names) + ")" if names else "(?!)"

    objs, people, places = alt(scene.object_ids), alt(scene.human_ids), alt(scene.surface_ids)
    leaf = rf"F (delivered\({objs}, {people}\)|placed\({objs}, {places}\))"
    return rf"^({leaf}|[Fp0-9 ()&|]{{1,80}})$"


def _schema(ids: list[str]) -> dict[str, Any]:
    return {
        "type": "object",
        "properties": {
            "root": {"type": "string"},
            "formulas": {
                "type": "array",
                "items": {
                    "type": "object",
                    "properties": {
                        "name": {"type": "string"},
                        "formula": {"type": "string"},
                    },
                    "required": ["name", "formula"],
                    "additionalProperties": False,
                },
            },
            "entities": {"type": "array", "items": {"type": "string", "enum": ids or [""]}},
            "error": {"type": ["string", "null"]},
        },
        "required": ["root", "formulas", "entities", "error"],
        "additionalProperties": False,
    }


def response_format(scene: Scene) -> dict[str, Any]:
    """The ``response_format`` for OpenAI-compatible structured output."""
    return {
        "type": "json_schema",
        "json_schema": {"name": "hltl_spec", "strict": True, "schema": answer_schema(scene)},
    }
