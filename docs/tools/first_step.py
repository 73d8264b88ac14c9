"""The first step of an episode over the bus, both processes on one clock.

Runs the discrete suite's trials over the bus (the nodes in a process of their own, as ``hltl
bench bus`` runs them), REPEATS times, with timers on the executor's side (its bus cell's
construction and reset, the executor's construction, the briefing, its grounding, the reset's
answer taken in, its first start, the wait for the node's first step) and the node's (the
reset, the idle work, the briefing's request taken up, its grounding, its plan of the first
step and the check, the start, the answer encoded and sent). ``time.perf_counter`` is one
clock for both processes (CLOCK_MONOTONIC). Prints, for each point, the median over the
episodes of its offset from the bus cell's construction (the first and second time it is
reached in an episode), and the loop's wait for the first step.

    PYTHONPATH=src .venv/bin/python docs/tools/first_step.py [REPEATS]

The medians are of each point alone, not one episode's timeline; the timers cost a little.
Session 26 (docs/bus.md, "Where the time goes (session 26)") used it to place the first
step's wait on the node's chain.
"""

from __future__ import annotations

import functools
import multiprocessing
import pickle
import statistics
import sys
import tempfile
import time
from collections import defaultdict
from pathlib import Path
from typing import Any

Event = tuple[str, str, float]  # (episode or cell, point, time)

# the node's points: its methods, timed in and out
_NODE = {
    "_on_step": "node: a query",
    "_on_reset": "node: the reset",
    "_reply_bytes": "node: an answer sent",
    "_publish_later": "node: idle, publish",
    "_save_idle": "node: idle, save",
    "_foresee_first": "node: the first step foreseen",
    "_take_brief": "node: the briefing grounded",
    "_foreseen": "node: its plan",
    "_check": "node: the check",
    "_start_guessed": "node: the guessed start",
    "_look_ahead": "node: the ticks ahead",
}
# the executor's: the bus cell's methods, and the executor's construction and grounding
_EXECUTOR = {
    "__init__": "executor: the bus cell",
    "_query": "executor: a query sent",
    "brief": "executor: the briefing",
    "_ready": "executor: the reset's answer",
    "start": "executor: a start",
    "_pull": "executor: waits for the node",
}


def _timed(owner: Any, name: str, point: str, out: list[Event], who: Any) -> None:
    f = getattr(owner, name)

    @functools.wraps(f)
    def timed(*a: Any, **k: Any) -> Any:
        w = who(a)
        out.append((w, point + " <", time.perf_counter()))
        try:
            return f(*a, **k)
        finally:
            out.append((w, point + " >", time.perf_counter()))

    setattr(owner, name, timed)


def _serve(endpoint: str, episodes: int, ready: Any, stop: Any, path: str) -> None:
    from hltl.bus import bench as B
    from hltl.bus import node as N
    from hltl.bus.session import BusConfig, open_session

    out: list[Event] = []

    def cell(a: Any) -> str:
        return str(a[0].keys.cell)

    for name, point in _NODE.items():
        _timed(N.CellNode, name, point, out, cell)
    with open_session(BusConfig(listen=(endpoint,))) as session:
        nodes = [
            N.CellNode(session, tr.scene, cell=f"suite{i}")
            for i, tr in enumerate(B._trials(episodes))
        ]
        ready.set()
        stop.wait()
        for n in nodes:
            n.close()
    Path(path).write_bytes(pickle.dumps(out))


def main(repeats: int) -> None:
    from hltl.bus import bench as B
    from hltl.bus import driver as D
    from hltl.bus.session import BusConfig, free_endpoint, open_session
    from hltl.execution import executor as X
    from hltl.sim import episode as E

    out: list[Event] = []
    now = ["?"]

    def episode(_: Any) -> str:
        return now[0]

    for name, point in _EXECUTOR.items():
        _timed(D.BusCell, name, point, out, episode)
    _timed(X.Executor, "__init__", "executor: the executor built", out, episode)
    _timed(E, "ground_all", "executor: grounds", out, episode)
    trials = B._trials(20)
    ctx = multiprocessing.get_context("spawn")
    ready, stop = ctx.Event(), ctx.Event()
    endpoint = free_endpoint()
    with tempfile.TemporaryDirectory() as tmp:
        path = str(Path(tmp) / "node.pickle")
        child = ctx.Process(target=_serve, args=(endpoint, len(trials), ready, stop, path))
        child.start()
        if not ready.wait(120):
            raise SystemExit("the node process did not start")
        ends: dict[str, float] = {}
        with open_session(BusConfig(connect=(endpoint,))) as session:
            for r in range(repeats):
                for i, tr in enumerate(trials):
                    now[0] = f"suite{i}#{r}"
                    opened: list[D.BusCell] = []
                    E.run_episode(
                        tr.scene,
                        simulator=D.bus_cell(session, cell=f"suite{i}", opened=opened),
                        instruction=tr.instruction,
                        events=tr.events,
                        seed=tr.seed,
                    )
                    ends[now[0]] = time.perf_counter()
                    opened[0].end()
                    opened[0].close()
            stop.set()
            child.join(30)
        node: list[Event] = pickle.loads(Path(path).read_bytes())
    _report(out, node, ends)


def _report(out: list[Event], node: list[Event], ends: dict[str, float]) -> None:
    by_episode: dict[str, list[tuple[str, float]]] = defaultdict(list)
    for w, point, t in out:
        by_episode[w].append((point, t))
    by_cell: dict[str, list[tuple[str, float]]] = defaultdict(list)
    for w, point, t in node:
        by_cell[w].append((point, t))
    offsets: dict[str, list[float]] = defaultdict(list)
    waits: list[float] = []
    for key, events in by_episode.items():
        t0, end = events[0][1], ends[key]
        cell = key.split("#")[0]
        seen: dict[str, int] = defaultdict(int)
        mine = events + [(p, t) for p, t in by_cell[cell] if t0 - 0.001 <= t <= end]
        for point, t in sorted(mine, key=lambda e: e[1]):
            k = seen[point]
            seen[point] += 1
            if k < 2:
                offsets[point + ("" if k == 0 else " (2nd)")].append((t - t0) * 1000)
        pulls = [t for p, t in events if p.startswith("executor: waits for the node")]
        if len(pulls) >= 2:
            waits.append((pulls[1] - pulls[0]) * 1000)
    n = len(by_episode)
    print(f"{n} episodes; median offset from the bus cell's construction, ms (how many reached it)")
    for point, values in sorted(offsets.items(), key=lambda kv: statistics.median(kv[1])):
        if len(values) >= n // 2 and statistics.median(values) < 12:
            print(f"  {statistics.median(values):7.3f}  {point}  ({len(values)})")
    if waits:
        wait = statistics.median(waits)
        print(f"the loop's first wait for the node's first step: median {wait:.3f} ms")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 3)
