"""``import hltl`` (and the CLI parser) must stay light: no heavy optional dependency."""

from __future__ import annotations

import subprocess
import sys

HEAVY = ("torch", "openai", "mujoco", "matplotlib", "ortools", "llama_cpp", "sympy")


def test_import_hltl_is_light() -> None:
    code = (
        "import sys, hltl, hltl.cli.main\n"
        "hltl.cli.main.build_parser()\n"
        f"print(','.join(m for m in {HEAVY!r} if m in sys.modules))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == ""
