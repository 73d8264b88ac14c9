"""Measured serial vs parallel latency of the motion layer's candidate planning (P.M.P.)."""

from __future__ import annotations

import json
import math
from dataclasses import asdict, dataclass
from pathlib import Path

from hltl.execution.latency import load_record

DEFAULT_PMP = Path(__file__).parent / "data" / "pmp_latency.json"


@dataclass(frozen=True, slots=True)
class PmpLatency:
    """One measurement of ``CandidatePlanner`` on the Fig. 1 robot-to-robot handover.

    Attributes:
        candidates: candidate goal sets (handover positions × grasp pairs) planned per call.
        workers: processes of the parallel planner.
        serial_s: median wall-clock seconds of one call of the serial planner.
        parallel_s: median wall-clock seconds of one call of the process pool.
        serial_cpu_s: median CPU seconds of the serial call (what it costs on an idle core).
        runs: calls each median is taken over.
        load: the machine's 1-minute load average when measured (two cores, shared).
        source: command, date and machine.
    """

    candidates: int
    workers: int
    serial_s: float
    parallel_s: float
    serial_cpu_s: float
    runs: int
    load: float
    source: str

    def __post_init__(self) -> None:
        for name in ("serial_s", "parallel_s", "serial_cpu_s", "load"):
            v = getattr(self, name)
            if not (isinstance(v, (int, float)) and math.isfinite(v) and v >= 0):
                raise ValueError(f"{name} must be a finite number >= 0, got {v!r}")
        if self.candidates < 1 or self.workers < 2 or self.runs < 1:
            raise ValueError("candidates and runs must be >= 1 and workers >= 2")

    @property
    def speedup(self) -> float:
        return self.serial_s / self.parallel_s if self.parallel_s > 0 else math.inf

    def describe(self) -> str:
        return (
            f"{self.candidates} candidates: serial {self.serial_s * 1e3:.0f} ms, "
            f"{self.workers} processes {self.parallel_s * 1e3:.0f} ms (×{self.speedup:.2f}, "
            f"load {self.load:.1f}; {self.source})"
        )


def write_pmp_latency(path: Path, rec: PmpLatency) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(asdict(rec), indent=1) + "\n", encoding="utf-8")


def load_pmp_latency(path: str | Path) -> PmpLatency:
    """A measurement written by ``hltl bench pmp --write-model``.

    Raises:
        HltlError: the file is missing, not JSON or not such a measurement.
    """
    return load_record(path, "P.M.P. latency", PmpLatency)
