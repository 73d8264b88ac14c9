"""Shared fixtures: paths to the example scenes and specs."""

from __future__ import annotations

from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "examples"


@pytest.fixture
def examples_dir() -> Path:
    return EXAMPLES


@pytest.fixture
def two_arms_path() -> Path:
    return EXAMPLES / "scenes" / "two_arms.yaml"
