"""CP-SAT is imported without pandas (``lns._import_cp_sat``, docs/planner.md "CP-SAT without
pandas"): the planner's models still solve, and pandas, when something imports it later, is the
real one."""

from __future__ import annotations

import subprocess
import sys

import pytest

pytest.importorskip("ortools")

# a tiny model solved through the planner's own helper, in a fresh interpreter
_SOLVE = (
    "from ortools.sat.python import cp_model\n"
    "m = cp_model.CpModel()\n"
    "x = m.new_int_var(0, 10, 'x')\n"
    "b = m.new_bool_var('b')\n"
    "m.add(x >= 3).only_enforce_if(b)\n"
    "m.add_bool_or([b])\n"
    "m.add_no_overlap([m.new_fixed_size_interval_var(x, 2, 'i')])\n"
    "got = lns.solve_until(m, time.perf_counter() + 30, 0)\n"
    "assert got is not None and got[1] == cp_model.OPTIMAL, got\n"
    "assert got[0].value(x) >= 3\n"
)


def _run(code: str) -> str:
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=False)
    assert out.returncode == 0, out.stderr
    return out.stdout.strip()


def test_cp_sat_is_imported_without_pandas_and_solves() -> None:
    code = (
        "import sys, time\n"
        "from hltl.planner import lns\n"
        "assert lns.available()\n"
        "print('pandas' in sys.modules)\n" + _SOLVE
    )
    assert _run(code) == "False"


def test_pandas_imported_after_cp_sat_is_the_real_one() -> None:
    pytest.importorskip("pandas")
    code = (
        "import sys, time\n"
        "from hltl.planner import lns\n"
        "assert lns.available()\n"
        "import pandas\n"
        "print(hasattr(pandas, 'DataFrame'), pandas.Series([1, 2]).sum())\n" + _SOLVE
    )
    assert _run(code) == "True 3"


def test_where_the_stand_in_fails_cp_sat_is_imported_as_usual() -> None:
    # (another ortools that needs more of pandas at import: the stand-in is dropped, the
    # partly imported module forgotten, and CP-SAT imported with pandas)
    code = (
        "import sys, time\n"
        "from hltl.planner import lns\n"
        "def refuse(self, name):\n"
        "    raise AttributeError(name)\n"
        "lns._NotPandas.__getattr__ = refuse\n"
        "assert lns.available()\n"
        "import ortools.sat.python.cp_model as cp\n"
        "print(type(sys.modules.get('pandas')).__name__, hasattr(cp.pd, 'DataFrame'))\n" + _SOLVE
    )
    pytest.importorskip("pandas")
    assert _run(code) == "module True"
