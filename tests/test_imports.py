"""``import hltl`` (and the CLI parser) must stay light: no heavy optional dependency."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

HEAVY = ("torch", "openai", "mujoco", "matplotlib", "ortools", "llama_cpp", "sympy")


def test_import_hltl_is_light() -> None:
    code = (
        "import sys, hltl, hltl.cli.main\n"
        "hltl.cli.main.build_parser()\n"
        f"print(','.join(m for m in {HEAVY!r} if m in sys.modules))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == ""


def test_each_subcommand_module_is_light_and_only_the_chosen_one_is_imported() -> None:
    # every `hltl <command>` module can be imported without a heavy dependency, and building
    # the parser for one command imports no other command's module
    code = (
        "import sys, importlib, hltl.cli.main as m\n"
        "heavy = " + repr(HEAVY) + "\n"
        "for name, (module, _) in m.COMMANDS.items():\n"
        "    before = {k for k in sys.modules if k.split('.')[0] in heavy}\n"
        "    importlib.import_module('hltl.cli.' + module)\n"
        "    new = {k.split('.')[0] for k in sys.modules if k.split('.')[0] in heavy} - before\n"
        "    print(name + ':' + ','.join(sorted(new)))\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    lines = [line.split(":", 1) for line in out.stdout.strip().splitlines()]
    assert lines and all(heavy.strip() == "" for _, heavy in lines), out.stdout
    code = (
        "import sys, hltl.cli.main as m\n"
        "m.build_parser('plan')\n"
        "print(sorted(k for k in sys.modules if k.startswith('hltl.cli.')))\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "['hltl.cli.common', 'hltl.cli.main', 'hltl.cli.plan']"


def test_command_table_help_matches_each_module() -> None:
    # the one-line help `hltl --help` shows without importing a module is the module's own
    import hltl.cli.main as m

    for name, (_, help_) in m.COMMANDS.items():
        parser = m.build_parser(name)
        sub = next(a for a in parser._actions if a.dest == "command")
        shown = {c.dest: c.help for c in sub._choices_actions}  # type: ignore[attr-defined]
        assert shown[name] == help_, name


def test_planning_a_small_cell_imports_no_heavy_module() -> None:
    # exact mode's first phase is for 9-16-goal cells: a small plan (the paper's Fig. 1) must
    # not pay for importing CP-SAT (and pandas with it) at start-up
    code = (
        "import sys\n"
        "from hltl.planner import plan\n"
        "from hltl.spec.hierarchy import load_spec\n"
        "from hltl.world.scene import load_scene\n"
        "scene = load_scene('examples/scenes/two_arms.yaml')\n"
        "r = plan(scene, load_spec('examples/specs/fig1.yaml'), timeout=30)\n"
        "assert r.solved\n"
        f"print(','.join(m for m in {HEAVY!r} + ('pandas',) if m in sys.modules))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == ""


def test_hltl_plan_with_a_spec_file_imports_only_what_it_uses(tmp_path: Path) -> None:
    # `hltl plan --spec FILE` on a small scene (docs/benchmarks.md, "Start-up"): no grounder,
    # no lark (a valid formula is read by the hand-written parser), no MONA helpers (the DFA
    # comes from the disk cache), no thread pool (concurrent.futures, logging: no task is
    # given to one on a small cell), no planner module only exact mode's first phase or
    # anytime mode uses (CP-SAT's, the bounds', conflict repair), and, once the files were
    # read before, no PyYAML
    code = (
        "import contextlib, io, sys\n"
        "from hltl.cli.main import main\n"
        "with contextlib.redirect_stdout(io.StringIO()):\n"
        "    code = main(['plan', '--scene', 'examples/scenes/two_arms.yaml',\n"
        "                 '--spec', 'examples/specs/fig1.yaml'])\n"
        "unwanted = ('lark', 'yaml', 'hltl.grounding', 'subprocess', 'tempfile', 'concurrent',\n"
        "            'logging', 'shutil', 'hashlib', 'numpy',\n"
        "            'scipy', 'pandas') + " + repr(HEAVY) + "\n"
        "phase = ('hltl.planner.lns', 'hltl.planner.schedule', 'hltl.planner.profile',\n"
        "         'hltl.planner.repair')\n"
        "print(code, sorted(m for m in sys.modules if m.split('.')[0] in unwanted\n"
        "                   or m.startswith('hltl.grounding') or m in phase))\n"
    )
    env = {**os.environ, "HLTL_CACHE_DIR": str(tmp_path)}
    runs = [
        subprocess.run(
            [sys.executable, "-c", code], capture_output=True, text=True, check=True, env=env
        ).stdout.strip()
        for _ in range(2)
    ]
    assert runs[1] == "0 []", runs


def test_the_dfa_cache_imports_concurrent_futures_only_when_mona_runs(tmp_path: Path) -> None:
    # a DFA read back from the disk folder needs no Future (docs/planner.md, "Start-up"); one
    # MONA compiles does (the same process code, run twice: cold folder, then warm)
    code = (
        "import sys\n"
        "from pathlib import Path\n"
        "from hltl.spec.automata import AutomatonCache\n"
        "from hltl.spec.parser import parse_formula\n"
        "before = 'concurrent.futures' in sys.modules\n"
        f"cache = AutomatonCache(disk=Path({str(tmp_path)!r}))\n"
        "cache.to_dfa(parse_formula('F (a & X (b U picked(cup)))'))\n"
        "print(before, 'concurrent.futures' in sys.modules)\n"
    )
    runs = [
        subprocess.run(
            [sys.executable, "-c", code], capture_output=True, text=True, check=True
        ).stdout.strip()
        for _ in range(2)
    ]
    assert runs == ["False True", "False False"]


@pytest.mark.parametrize("columns", [None, "40", "132", "0", "-3", "wide"])
def test_the_help_width_is_the_one_shutil_gives(
    columns: str | None, monkeypatch: pytest.MonkeyPatch
) -> None:
    # argparse sizes help with shutil.get_terminal_size(); hltl's parsers ask the same without
    # importing shutil (tests/test_imports.py: `hltl plan` imports no shutil)
    import shutil

    import hltl.cli.main as m

    if columns is None:
        monkeypatch.delenv("COLUMNS", raising=False)
    else:
        monkeypatch.setenv("COLUMNS", columns)
    assert m._columns() == shutil.get_terminal_size().columns
    parser = m.build_parser()
    assert parser._get_formatter()._width == shutil.get_terminal_size().columns - 2
