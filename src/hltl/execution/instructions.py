"""Spec updates as the executor receives them: instructions grounded outside it (GOAL events)."""

from __future__ import annotations

from dataclasses import dataclass

from hltl.execution.log import Grounding
from hltl.spec.hierarchy import HSpec, spec_to_dict


@dataclass(frozen=True, slots=True)
class SpecChange:
    """How an update changed the running spec (names of formulas kept, changed, added, removed)."""

    kind: str
    kept: tuple[str, ...] = ()
    changed: tuple[str, ...] = ()
    added: tuple[str, ...] = ()
    removed: tuple[str, ...] = ()


@dataclass(frozen=True, slots=True)
class SpecUpdate:
    """One instruction after grounding: the new running spec, or why there is none.

    Attributes:
        text: what was said.
        spec: the running spec with the instruction merged in; ``None`` when grounding failed.
        error: why grounding failed.
        prompt_tokens, completion_tokens: LLM tokens grounding cost.
        latency_ms: wall-clock time grounding took.
        change: how the running spec changed (for an update of a running spec).
    """

    text: str
    spec: HSpec | None
    error: str = ""
    prompt_tokens: int = 0
    completion_tokens: int = 0
    latency_ms: float = 0.0
    change: SpecChange | None = None

    @property
    def tokens(self) -> int:
        return self.prompt_tokens + self.completion_tokens

    def record(self, t: float, done: frozenset[str], charged_s: float | None = None) -> Grounding:
        """The ``grounding`` log record (``done``: formulas done after it; ``charged_s``: the
        simulated seconds grounding was charged, under a latency model)."""
        if self.spec is None:  # tokens are paid for whether or not the answer is used
            return Grounding(
                t=t,
                text=self.text,
                error=self.error,
                tokens=self.tokens,
                prompt_tokens=self.prompt_tokens,
                completion_tokens=self.completion_tokens,
                charged_s=charged_s,
            )
        c = self.change
        return Grounding(
            t=t,
            text=self.text,
            tokens=self.tokens,
            prompt_tokens=self.prompt_tokens,
            completion_tokens=self.completion_tokens,
            latency_ms=round(self.latency_ms, 3),
            spec=spec_to_dict(self.spec),
            done=sorted(done),
            update=None
            if c is None
            else {
                "kind": c.kind,
                "kept": list(c.kept),
                "changed": list(c.changed),
                "added": list(c.added),
                "removed": list(c.removed),
            },
            charged_s=charged_s,
        )
