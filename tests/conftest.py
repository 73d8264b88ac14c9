"""Shared fixtures: paths to the example scenes and specs."""

from __future__ import annotations

import os
import sys
from pathlib import Path

# This checkout's own code, first: the shared .venv installs hltl in editable mode from
# /work/main/src, so without this a worktree's (or the landing train's) tests import main's code,
# and so do the interpreters the tests start (they inherit PYTHONPATH).
_SRC = str(Path(__file__).resolve().parents[1] / "src")
if sys.path[:1] != [_SRC]:
    sys.path.insert(0, _SRC)
os.environ["PYTHONPATH"] = os.pathsep.join(
    [_SRC, *(p for p in os.environ.get("PYTHONPATH", "").split(os.pathsep) if p)]
)

import pytest  # noqa: E402
from hypothesis import settings  # noqa: E402

from hltl.sim3d.gl import choose_backend  # noqa: E402

# MuJoCo picks its OpenGL backend once, when first imported (possibly by another test's import of
# mink): choose the offscreen one for the whole session before anything imports it.
os.environ.setdefault("MUJOCO_GL", choose_backend() or "disable")

# No property test has a deadline: Hypothesis's default (200 ms an example) is an assertion
# on wall-clock time, which a loaded machine breaks (tests/bus/test_bench.py's verdict tests
# took 300-430 ms an example under the landing train's load, session 30). What a test may
# assume about time: docs/bus.md, "Tests and time".
settings.register_profile("hltl", deadline=None)
settings.load_profile("hltl")

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "examples"


@pytest.fixture
def examples_dir() -> Path:
    return EXAMPLES


@pytest.fixture
def two_arms_path() -> Path:
    return EXAMPLES / "scenes" / "two_arms.yaml"
