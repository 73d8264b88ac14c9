"""Running the CLI in-process on bad input and checking the promise: one bounded error line."""

from __future__ import annotations

import contextlib
import io
import tracemalloc
from collections.abc import Iterator, Sequence
from dataclasses import dataclass
from pathlib import Path

import pytest

from hltl.bench.soak import alarm
from hltl.cli.main import main

ROOT = Path(__file__).resolve().parents[2]
SCENE = ROOT / "examples" / "scenes" / "two_arms.yaml"
SPEC = ROOT / "examples" / "specs" / "fig1.yaml"

# What "bounded" means here: an error line a person can read, memory a laptop has, and a time
# after which the case is a hang (not a timing assertion: it only stops a runaway case).
MAX_ERROR_LINE = 2_200
MAX_PEAK_BYTES = 200 << 20
HANG_SECONDS = 120


@dataclass(frozen=True, slots=True)
class Outcome:
    code: int
    out: str
    err: str
    peak: int  # bytes allocated at the peak (tracemalloc)


class Hang(Exception):
    """The case ran longer than HANG_SECONDS."""


def run_cli(argv: Sequence[str], *, measure: bool = True) -> Outcome:
    """``hltl ARGV`` in this process, with its output captured and its peak memory measured."""
    out, err = io.StringIO(), io.StringIO()
    if measure:
        tracemalloc.start()
    try:
        with (
            alarm(HANG_SECONDS, lambda: Hang(f"still running after {HANG_SECONDS} s")),
            contextlib.redirect_stdout(out),
            contextlib.redirect_stderr(err),
        ):
            code = main(list(argv))
        peak = tracemalloc.get_traced_memory()[1] if measure else 0
    finally:
        if measure:
            tracemalloc.stop()
    return Outcome(code, out.getvalue(), err.getvalue(), peak)


def assert_one_error(result: Outcome, *needles: str) -> str:
    """Exit 1, exactly one ``error:`` line (bounded, no traceback, not the catch-all), needles
    in it; returns the line."""
    lines = [ln for ln in result.err.splitlines() if ln.strip()]
    errors = [ln for ln in lines if ln.startswith("error: ")]
    assert result.code == 1, (result.code, result.err[-2000:])
    assert len(errors) == 1, result.err[-2000:]
    assert "Traceback" not in result.err
    line = errors[0]
    assert len(line) <= MAX_ERROR_LINE, line[:300]
    # the catch-all in main() reports defects; none of this corpus may reach it
    assert "unexpected; rerun with --debug" not in line, line
    assert result.peak <= MAX_PEAK_BYTES, f"{result.peak / 1e6:.0f} MB"
    for needle in needles:
        assert needle in line, (needle, line)
    return line


@pytest.fixture
def write(tmp_path: Path) -> Iterator[object]:
    """write(name, text_or_bytes) -> path in a fresh folder."""

    def _write(name: str, content: str | bytes) -> Path:
        p = tmp_path / name
        if isinstance(content, bytes):
            p.write_bytes(content)
        else:
            p.write_text(content, encoding="utf-8")
        return p

    yield _write
