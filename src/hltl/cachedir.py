"""Where hltl keeps what it computes once for every later process (DFA tables, parser tables)."""

from __future__ import annotations

import os
from pathlib import Path


def cache_dir(kind: str) -> Path | None:
    """``$HLTL_CACHE_DIR/<kind>``, else ``$XDG_CACHE_HOME/hltl/<kind>`` or
    ``~/.cache/hltl/<kind>``; ``None`` when ``HLTL_CACHE_DIR`` is ``off`` (or empty or 0)."""
    root = os.environ.get("HLTL_CACHE_DIR")
    if root is not None:
        return None if root in ("", "off", "0") else Path(root) / kind
    xdg = os.environ.get("XDG_CACHE_HOME")
    base = Path(xdg) if xdg else Path.home() / ".cache"
    return base / "hltl" / kind
