"""The grounder's warm-up: its fixed patterns gated and compiled once per process."""

from __future__ import annotations

import threading

from hltl.grounding import gate
from hltl.grounding._warm_patterns import PATTERNS

_LOCK = threading.Lock()
_DONE = False


def warm_up() -> int:
    """Gate and compile every listed pattern not met yet (once per process); how many were."""
    global _DONE
    if _DONE:
        return 0
    with _LOCK:
        if _DONE:
            return 0
        done = sum(gate.prepare(pattern, flags, build=build) for pattern, flags, build in PATTERNS)
        _DONE = True
    return done
