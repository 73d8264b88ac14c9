"""Grounding what people say during an episode into spec updates for the agent."""

from __future__ import annotations

import time
from collections.abc import Collection, Iterable

from hltl.errors import GroundingError
from hltl.execution.instructions import SpecChange, SpecUpdate
from hltl.grounding.base import Grounder
from hltl.grounding.update import apply_update
from hltl.spec.hierarchy import HSpec
from hltl.world.scene import Scene


def ground_instruction(
    grounder: Grounder,
    text: str,
    scene: Scene,
    running: HSpec | None,
    done: Collection[str] = (),
) -> SpecUpdate:
    """Ground ``text`` against the running spec (merging it in, paper GOAL event); ``done``
    names the running spec's formulas already done (finished work stays finished)."""
    t0 = time.perf_counter()
    try:
        if running is None:
            g = grounder.ground(text, scene)
        else:
            g = apply_update(text, scene, running, grounder, done)
    except GroundingError as exc:
        return SpecUpdate(
            text,
            None,
            error=str(exc),
            prompt_tokens=exc.prompt_tokens,
            completion_tokens=exc.completion_tokens,
        )
    ms = (time.perf_counter() - t0) * 1000.0
    change = None
    if g.update is not None:
        u = g.update
        change = SpecChange(u.kind, u.kept, u.changed, u.added, u.removed)
    return SpecUpdate(
        text,
        g.spec,
        prompt_tokens=g.tokens.prompt,
        completion_tokens=g.tokens.completion,
        latency_ms=ms,
        change=change,
    )


def ground_all(
    grounder: Grounder,
    texts: Iterable[str],
    scene: Scene,
    running: HSpec | None,
    done: Collection[str] = (),
) -> list[SpecUpdate]:
    """Ground several instructions in order, each against the spec the previous ones left."""
    out: list[SpecUpdate] = []
    for text in texts:
        upd = ground_instruction(grounder, text, scene, running, done)
        out.append(upd)
        if upd.spec is not None:
            running = upd.spec
    return out
