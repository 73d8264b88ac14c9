"""The LLM prompt: instructions, two few-shot examples, the scene graph and the answer schema."""

from __future__ import annotations

import json
import re
from typing import TYPE_CHECKING, Any

from hltl.grounding.base import scene_graph

if TYPE_CHECKING:
    from hltl.world.scene import Scene

SYSTEM = "\n".join(
    (
        "Translate a robot instruction into a hierarchical LTLf specification. Answer with JSON "
        "only:",
        '{"root": "p0", "formulas": [{"name": "p0", "formula": "..."}, ...], '
        '"entities": [ids], "error": null}',
        "Rules:",
        '- One leaf per delivery or placement: "F delivered(<object>, <person>)" or '
        '"F placed(<object>, <surface>)", named p100, p200, ...',
        '- Other formulas use only their children\'s names: "and"/lists -> "F p100 & F p200"; '
        '"first A then B", "B after A" -> "F (p100 & F p200)"; "A or B" -> "F p100 | F p200". '
        "A nested group is its own formula (p1, p2, ...). The root is p0; a single task is "
        '"F p100".',
        "- Use only the scene's ids. If something is not in the scene or is ambiguous, give "
        '"error" saying why, with no formulas.',
    )
)

# Few-shot examples over their own small scene, so that the model copies the format, not the ids.
EXAMPLE_SCENE = """\
objects: mug; book (novel)
people: X (Person X, Xia); Y (Person Y)
surfaces: desk
robots: r1, r2 (assigned by the planner)"""

EXAMPLES: tuple[tuple[str, dict[str, Any]], ...] = (
    (
        "Give Xia the mug and Person Y the novel",
        {
            "root": "p0",
            "formulas": [
                {"name": "p0", "formula": "F p100 & F p200"},
                {"name": "p100", "formula": "F delivered(mug, X)"},
                {"name": "p200", "formula": "F delivered(book, Y)"},
            ],
            "entities": ["mug", "X", "book", "Y"],
            "error": None,
        },
    ),
    (
        "First put the book on the desk, then give X either the mug or the book",
        {
            "root": "p0",
            "formulas": [
                {"name": "p0", "formula": "F (p100 & F p1)"},
                {"name": "p100", "formula": "F placed(book, desk)"},
                {"name": "p1", "formula": "F p200 | F p300"},
                {"name": "p200", "formula": "F delivered(mug, X)"},
                {"name": "p300", "formula": "F delivered(book, X)"},
            ],
            "entities": ["book", "desk", "mug", "X"],
            "error": None,
        },
    ),
)


def user_message(instruction: str, scene_text: str) -> str:
    return f"Scene:\n{scene_text}\nInstruction: {instruction.strip()}"


def build_messages(
    instruction: str, scene: Scene, *, examples: bool = True
) -> list[dict[str, str]]:
    """The chat messages for one grounding query (system, few-shot pairs, the instruction)."""
    messages = [{"role": "system", "content": SYSTEM}]
    if examples:
        for text, answer in EXAMPLES:
            messages.append({"role": "user", "content": user_message(text, EXAMPLE_SCENE)})
            messages.append({"role": "assistant", "content": json.dumps(answer)})
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
