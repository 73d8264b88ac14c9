"""Does code on one vCPU run slower while the other vCPU is busy (two hardware threads of one
core)? The question behind the bus's quiet runs (docs/bus.md, "Where the time goes (session
22)"): in-process on an idle machine the executor's loop has a core to itself; over the bus the
node works beside it.

A fixed Python loop pinned to vCPU 0 is timed (thread CPU) alone and with a spinner pinned to
vCPU 1, in turn; for each "alone" run the other vCPU's busy share (``/proc/stat``) says whether
it really was alone. Run it on an idle machine, under the heavy lock:

    bash /work/notes/bench.sh python3 docs/tools/cores_probe.py [PAIRS]

A ratio near 1.0 with vCPU 1 idle in the "alone" runs: the vCPUs do not slow each other; well
above 1 (1.3 and more): they share a core, and the node's CPU beside the loop slows it.
"""

from __future__ import annotations

import os
import statistics
import subprocess
import sys
import time

SPIN = "import os\nos.sched_setaffinity(0, {1})\nwhile True:\n    pass\n"


def _busy(cpu: int) -> tuple[int, int]:
    """(busy, total) clock ticks of ``cpu`` so far."""
    with open("/proc/stat") as f:
        for line in f:
            if line.startswith(f"cpu{cpu} "):
                v = [int(x) for x in line.split()[1:]]
                return sum(v[:8]) - v[3] - v[4], sum(v[:8])
    raise RuntimeError(f"no cpu{cpu} in /proc/stat")


def _work() -> float:
    """Thread CPU seconds of a fixed loop."""
    c0 = time.thread_time()
    x = 0
    for i in range(3_000_000):
        x += i * i % 7
    return time.thread_time() - c0


def main() -> None:
    pairs = int(sys.argv[1]) if len(sys.argv) > 1 else 6
    if os.cpu_count() != 2:
        print(f"(this machine has {os.cpu_count()} CPUs: vCPUs 0 and 1 are compared)")
    os.sched_setaffinity(0, {0})
    _work()  # warm
    alone, beside, idle = [], [], []
    for _ in range(pairs):
        b0, t0 = _busy(1)
        alone.append(_work())
        b1, t1 = _busy(1)
        idle.append(1 - (b1 - b0) / max(1, t1 - t0))
        spinner = subprocess.Popen([sys.executable, "-c", SPIN])
        time.sleep(0.2)
        beside.append(_work())
        spinner.kill()
        spinner.wait()
        time.sleep(0.2)
    for a, b, i in zip(alone, beside, idle, strict=True):
        print(
            f"alone {a * 1000:6.1f} ms CPU (vCPU 1 idle {i:4.0%}), "
            f"beside a spinner {b * 1000:6.1f} ms: x{b / a:.2f}"
        )
    ratios = [b / a for a, b in zip(alone, beside, strict=True)]
    quiet = [r for r, i in zip(ratios, idle, strict=True) if i >= 0.9]
    line = f"median x{statistics.median(ratios):.2f} over {pairs} pairs; "
    if quiet:
        line += f"x{statistics.median(quiet):.2f} over the {len(quiet)} with vCPU 1 idle >= 90 %"
    else:
        line += "no 'alone' run had vCPU 1 idle: not settled (run it on an idle machine)"
    print(line)
    with open("/proc/loadavg") as f:
        print(f"load {f.read().split()[0]}")


if __name__ == "__main__":
    main()
