"""Paired A/B of bus variants: the discrete suite in-process and over the bus, trial by trial.

Each variant is ``NODE/EXECUTOR``: a patch of the node's code (applied in a node process of
its own, one per node variant, each serving the suite's 20 trials as ``hltl bench bus`` does)
and one of the executor's (applied around its episodes). Every trial is run in-process and in
every variant before the next, the order rotated and reversed from trial to trial; repeat 0 is
a warm-up. Prints each variant's suite ratio per repeat and, for every two variants, the
median and mean of their per-episode wall difference (the sensitive statistic). Also prints
the executor process's garbage collections by side (in-process or bus) and generation.

    PYTHONPATH=src .venv/bin/python docs/tools/bus_ab.py REPEATS VARIANT ...

e.g. ``main/main main2/main nolg/main`` (``main2``, ``main3``: the unpatched node in another
process: the harness's own noise floor). Node variants: ``main``, ``main2``, ``main3``,
``nolg`` (no let-go anywhere), ``replynolg`` (none after an answer), ``fsnolg`` (none before
the node plans a step), ``fs1nolg`` (none before it plans the first step), ``nopause`` (no
pause after an answer that guessed steps follow, ``GUESS_PAUSE`` 0), ``resetnext`` (after a
reset's answer, the next query looked for before the idle work). Executor variants: ``main``,
``nolg`` (no let-go after the requests it does not wait for), ``first`` (the node asked
to foresee the first step, ``bus_cell(first=True)``: the default until the end of session 28;
as deployed since, ``main``, the first commands go in a query). Besides the suite ratios and
paired wall differences it prints the loop's waits for the node (``DriverStats.waited``),
paired. Sessions 27 and 28 (docs/bus.md, "Where the time
goes") ran it under ``bash /work/notes/bench.sh``.
"""

from __future__ import annotations

import gc
import multiprocessing
import statistics
import sys
import time
from collections.abc import Callable
from typing import Any


def _noop(*_: Any, **__: Any) -> None:
    return None


def _without_let_go(method: Callable[..., Any], first_only: bool = False) -> Callable[..., Any]:
    """``CellNode._foreseen`` with the node's let-go off while it runs (only for the first
    step's plan, nothing in its batch yet, with ``first_only``)."""
    from hltl.bus import node as N

    def wrapped(self: Any, s: Any, world: Any) -> Any:
        if first_only and s.batch.ticks:
            return method(self, s, world)
        kept = N.CellNode.__dict__["_let_go"]
        N.CellNode._let_go = staticmethod(_noop)  # type: ignore[method-assign]
        try:
            return method(self, s, world)
        finally:
            N.CellNode._let_go = kept  # type: ignore[method-assign]

    return wrapped


def _patch_node(variant: str) -> None:
    from hltl.bus import node as N

    if variant == "nolg":
        N.CellNode._let_go = staticmethod(_noop)  # type: ignore[method-assign]
    elif variant == "replynolg":

        def _reply_bytes(self: Any, query: Any, payload: bytes, key: str | None = None) -> bool:
            if self.link.reply_lost():
                return False
            query.reply(key or str(query.key_expr), payload)
            return True

        N.CellNode._reply_bytes = _reply_bytes  # type: ignore[method-assign]
    elif variant in ("fsnolg", "fs1nolg"):
        N.CellNode._foreseen = _without_let_go(  # type: ignore[method-assign]
            N.CellNode._foreseen, first_only=variant == "fs1nolg"
        )
    elif variant == "nopause":
        N.GUESS_PAUSE = 0.0
    elif variant == "resetnext":
        on_reset = N.CellNode._on_reset

        def _on_reset(self: Any, query: Any) -> None:
            on_reset(self, query)
            self._ahead_sent = True  # (the briefing comes next: looked for before idle work)

        N.CellNode._on_reset = _on_reset  # type: ignore[method-assign]
    elif variant not in ("main", "main2", "main3"):
        raise SystemExit(f"unknown node variant {variant!r}")


def _serve(endpoint: str, ready: Any, stop: Any, prefix: str, variant: str) -> None:
    from hltl.bus import bench as B
    from hltl.bus import node as N
    from hltl.bus.session import BusConfig, open_session

    _patch_node(variant)
    with open_session(BusConfig(listen=(endpoint,))) as session:
        nodes = [
            N.CellNode(session, tr.scene, cell=f"{prefix}{i}") for i, tr in enumerate(B._trials(20))
        ]
        ready.set()
        stop.wait()
        for n in nodes:
            n.close()


_side = ["none"]
_gc: dict[tuple[str, int], list[float]] = {}
_gc_start = [0.0]


def _on_gc(phase: str, info: dict[str, Any]) -> None:
    if phase == "start":
        _gc_start[0] = time.perf_counter()
    else:
        _gc.setdefault((_side[0], info["generation"]), []).append(
            time.perf_counter() - _gc_start[0]
        )


def main(repeats: int, names: list[str]) -> None:
    from hltl.bus import bench as B
    from hltl.bus import driver as D
    from hltl.bus.session import BusConfig, free_endpoint, open_session
    from hltl.sim.episode import run_episode
    from hltl.sim.simulator import Simulator

    for name in names:
        if name.count("/") != 1 or name.split("/")[1] not in ("main", "nolg", "first"):
            raise SystemExit(f"bad variant {name!r}: expected NODE/EXECUTOR")
    trials = B._trials(20)
    ctx = multiprocessing.get_context("spawn")
    stop = ctx.Event()
    nodes: dict[str, tuple[str, str]] = {}
    procs = []
    for k, variant in enumerate(sorted({n.split("/")[0] for n in names})):
        ready, endpoint = ctx.Event(), free_endpoint()
        nodes[variant] = (endpoint, f"ab{k}-")
        p = ctx.Process(
            target=_serve, args=(endpoint, ready, stop, f"ab{k}-", variant), daemon=True
        )
        p.start()
        procs.append(p)
        if not ready.wait(120):
            raise SystemExit("a node process did not start")
    let_go = D.let_go
    sides = ["inproc", *names]
    wall = {s: [[0.0] * len(trials) for _ in range(repeats)] for s in sides}
    waited = {s: [[0.0] * len(trials) for _ in range(repeats)] for s in names}
    same = 0
    gc.callbacks.append(_on_gc)
    with open_session(BusConfig(connect=tuple(e for e, _ in nodes.values()))) as session:
        time.sleep(0.5)  # (the connections settle)
        for r in range(repeats + 1):
            if r == 1:
                _gc.clear()
            for i, tr in enumerate(trials):
                k = (r + i) % len(sides)
                order = sides[k:] + sides[:k]
                order = order[::-1] if (r + i) % 2 else order
                logs = {}
                for s in order:
                    kw: dict[str, Any] = {
                        "instruction": tr.instruction,
                        "events": tr.events,
                        "seed": tr.seed,
                    }
                    opened: list[Any] = []
                    make: Any = Simulator
                    if s != "inproc":
                        node, executor = s.split("/")
                        D.let_go = _noop if executor == "nolg" else let_go  # type: ignore[assignment]
                        make = D.bus_cell(
                            session,
                            cell=f"{nodes[node][1]}{i}",
                            opened=opened,
                            first=executor == "first",
                        )
                    _side[0] = "inproc" if s == "inproc" else "bus"
                    t0 = time.perf_counter()
                    ep = run_episode(tr.scene, simulator=make, **kw)
                    w = time.perf_counter() - t0
                    _side[0] = "none"
                    if opened:
                        if r:
                            waited[s][r - 1][i] = opened[0].stats.waited
                        opened[0].end()
                        opened[0].close()
                    D.let_go = let_go  # type: ignore[assignment]
                    logs[s] = B._strip(list(ep.records))
                    if r:
                        wall[s][r - 1][i] = w
                same += all(v == logs["inproc"] for v in logs.values())
    stop.set()
    for p in procs:
        p.join(10)
    n = repeats * len(trials)
    print(f"logs equal to the in-process one (every variant): {same}/{(repeats + 1) * len(trials)}")
    base = wall["inproc"]
    for s in names:
        ratios = [100 * (sum(wall[s][r]) / sum(base[r]) - 1) for r in range(repeats)]
        excess = [(wall[s][r][i] - base[r][i]) * 1e3 for r in range(repeats) for i in range(20)]
        print(
            f"{s}: suite ratio median {statistics.median(ratios):+.1f} % "
            f"({', '.join(f'{x:+.1f}' for x in ratios)}); per-episode excess median "
            f"{statistics.median(excess):+.2f} ms, mean {statistics.mean(excess):+.2f} ms; the "
            f"loop waited for the node {1e3 * statistics.mean(sum(x) for x in waited[s]) / 20:.2f}"
            " ms an episode"
        )
    for a in names:
        for b in names:
            if a < b:
                d = [
                    (wall[b][r][i] - wall[a][r][i]) * 1e3 for r in range(repeats) for i in range(20)
                ]
                w = [
                    (waited[b][r][i] - waited[a][r][i]) * 1e3
                    for r in range(repeats)
                    for i in range(20)
                ]
                print(
                    f"{b} - {a}: per episode median {statistics.median(d):+.2f} ms, "
                    f"mean {statistics.mean(d):+.2f} ms; {b} faster in {sum(x < 0 for x in d)}"
                    f"/{len(d)}; the loop's waits for the node median {statistics.median(w):+.2f} "
                    f"ms, mean {statistics.mean(w):+.2f} ms"
                )
    per_side = {"inproc": n, "bus": n * len(names)}
    for (side, gen), times in sorted(_gc.items()):
        if side in per_side:
            print(
                f"gc {side} generation {gen}: {len(times) / per_side[side]:.3f} an episode, "
                f"{sum(times) / per_side[side] * 1e3:.3f} ms an episode, "
                f"{statistics.median(times) * 1e3:.3f} ms each (median)"
            )


if __name__ == "__main__":
    if len(sys.argv) < 3:
        raise SystemExit(__doc__)
    main(int(sys.argv[1]), sys.argv[2:])
