"""The grounder protocol, its result type and the compact scene graph used in prompts."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Protocol, runtime_checkable

from hltl.errors import GroundingError
from hltl.fileio import quote
from hltl.spec.hierarchy import HSpec
from hltl.world.scene import Scene

# A spoken or typed task is a sentence or a few; beyond this it is pasted text, and every
# grounder's cost (prompt tokens, parsing, messages quoting it) grows with it.
MAX_INSTRUCTION_CHARS = 2_000


def check_instruction(text: str, where: str = "instruction") -> str:
    """``text`` if it is at most :data:`MAX_INSTRUCTION_CHARS` long.

    Raises:
        GroundingError: naming ``where``, the start of the text and its length.
    """
    if len(text) > MAX_INSTRUCTION_CHARS:
        raise GroundingError(
            f"{where}: an instruction has at most {MAX_INSTRUCTION_CHARS:,} characters, got "
            f"{quote(text)}"
        )
    return text


@dataclass(frozen=True, slots=True)
class TokenUsage:
    """Tokens an LLM counted for one grounding (summed over repair rounds)."""

    prompt: int = 0
    completion: int = 0

    @property
    def total(self) -> int:
        return self.prompt + self.completion

    def __add__(self, other: TokenUsage) -> TokenUsage:
        return TokenUsage(self.prompt + other.prompt, self.completion + other.completion)

    def to_dict(self) -> dict[str, int]:
        return {"prompt": self.prompt, "completion": self.completion}


@dataclass(frozen=True, slots=True)
class UpdateInfo:
    """How an update instruction changed a running spec (see :mod:`hltl.grounding.update`).

    ``kept`` formulas have the same name and text as before, so their monitor state carries over
    unchanged; ``changed`` formulas kept their name but got a new text (their state must be
    recomputed, :func:`hltl.spec.monitor.carry_over` does it); ``added`` and ``removed`` are
    new and dropped names.
    """

    kind: str  # "add", "then", "cancel", "instead", "priority"
    kept: tuple[str, ...] = ()
    changed: tuple[str, ...] = ()
    added: tuple[str, ...] = ()
    removed: tuple[str, ...] = ()
    completed_kept: tuple[str, ...] = ()  # formulas done before the update that are still done


@dataclass(frozen=True, slots=True)
class Grounding:
    """A grounded instruction.

    Attributes:
        spec: the H-LTLf specification (for an update: the merged running spec).
        entities: scene ids the instruction refers to, in order of first mention.
        tokens: LLM tokens spent (0/0 for the offline grounder).
        update: for an instruction grounded against a running spec, how the spec changed.
        rounds: LLM queries made (1 + repair rounds); 0 offline.
    """

    spec: HSpec
    entities: tuple[str, ...]
    tokens: TokenUsage = field(default_factory=TokenUsage)
    update: UpdateInfo | None = None
    rounds: int = 0


@runtime_checkable
class Grounder(Protocol):
    """Turns an instruction into an H-LTLf spec over a scene's ids."""

    def ground(self, instruction: str, scene: Scene, running: HSpec | None = None) -> Grounding:
        """Ground ``instruction`` in ``scene``.

        Args:
            instruction: English text.
            scene: the scene whose ids the spec may use.
            running: the spec being executed, for an instruction given during execution (a paper
                GOAL event); the result is then the merged spec (:mod:`hltl.grounding.update`).

        Raises:
            GroundingError: the instruction cannot be grounded; the message says why.
        """
        ...


def scene_graph(scene: Scene) -> str:
    """The scene in a few short lines for a prompt: ids with categories, names and aliases.

    Positions and robots are left out on purpose: grounding needs the names of what can be
    handed over, to whom and where; the planner handles robots and geometry.
    """
    lines = []
    if scene.objects:
        parts = []
        for o in scene.objects:
            words = [w for w in (o.category, *o.aliases) if w != o.id]
            parts.append(f"{o.id} ({', '.join(words)})" if words else o.id)
        lines.append("objects: " + "; ".join(parts))
    if scene.humans:
        parts = []
        for h in scene.humans:
            words = [w for w in (h.name, *h.aliases) if w != h.id]
            parts.append(f"{h.id} ({', '.join(words)})" if words else h.id)
        lines.append("people: " + "; ".join(parts))
    if scene.surfaces:
        parts = []
        for s in scene.surfaces:
            parts.append(f"{s.id} ({', '.join(s.aliases)})" if s.aliases else s.id)
        lines.append("surfaces: " + "; ".join(parts))
    return "\n".join(lines)
