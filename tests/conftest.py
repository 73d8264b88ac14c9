"""Shared fixtures: paths to the example scenes and specs."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from hltl.sim3d.gl import choose_backend

# MuJoCo picks its OpenGL backend once, when first imported (possibly by another test's import of
# mink): choose the offscreen one for the whole session before anything imports it.
os.environ.setdefault("MUJOCO_GL", choose_backend() or "disable")

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "examples"


@pytest.fixture
def examples_dir() -> Path:
    return EXAMPLES


@pytest.fixture
def two_arms_path() -> Path:
    return EXAMPLES / "scenes" / "two_arms.yaml"
