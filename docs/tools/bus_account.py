"""Where an episode's time goes over the bus: both processes timed, query by query.

Runs the discrete suite trial by trial in-process and over the bus (the node in a process of
its own, as ``hltl bench bus`` does) with timers wrapped around the bus's functions on both
sides; ``time.perf_counter`` is one clock for both processes (CLOCK_MONOTONIC), so a query is
followed from the executor's ``session.get`` to the node's step thread taking it, the node's
answer, and the executor reading it. Prints the table docs/bus.md ("Where the time goes") shows.

    PYTHONPATH=src .venv/bin/python docs/tools/bus_account.py [EPISODES] [REPEATS]

The wrappers cost a little CPU on both sides (a few percent): the wall times are the suite's
under instrumentation, not the benchmark's.
"""

from __future__ import annotations

import bisect
import collections
import multiprocessing
import pickle
import statistics
import sys
import tempfile
import threading
import time
from pathlib import Path
from typing import Any

Event = tuple[Any, ...]


def _exclusive(acct: dict[str, float], local: threading.local, f: Any, name: str) -> Any:
    """``f`` timed in thread CPU seconds, exclusive of the timed functions it calls."""

    def timed(*a: Any, **k: Any) -> Any:
        stack = getattr(local, "stack", None)
        if stack is None:
            stack = local.stack = []
        c0 = time.thread_time()
        stack.append(0.0)
        try:
            return f(*a, **k)
        finally:
            d = time.thread_time() - c0
            inner = stack.pop()
            acct[name] = acct.get(name, 0.0) + d - inner
            if stack:
                stack[-1] += d

    return timed


def _serve(endpoint: str, episodes: int, ready: Any, stop: Any, out: str) -> None:
    from hltl.bus import bench as B
    from hltl.bus import node as N
    from hltl.bus.session import BusConfig, open_session

    ev: list[Event] = []
    acct: dict[str, float] = {}
    local = threading.local()
    loads = N.loads

    def timed_loads(b: bytes, what: str) -> Any:
        if what in ("step request", "reset request"):
            ev.append(("recv", time.perf_counter(), what))
        return loads(b, what)

    N.loads = timed_loads  # type: ignore[assignment]
    reply = N.CellNode._reply_bytes

    def timed_reply(self: Any, q: Any, payload: bytes, key: str | None = None) -> bool:
        ev.append(("reply", time.perf_counter(), len(payload)))
        return reply(self, q, payload, key)

    N.CellNode._reply_bytes = timed_reply  # type: ignore[method-assign]
    for name in (
        "_tick",
        "_on_step",
        "_stream",
        "_save_idle",
        "_publish_later",
        "_ahead_tick",
        "_settle",
        "_look_ahead",
        "_execute",
        "_clock",
        "_flush",
        "_feedback",
        "_reply_bytes",
        "_serve_steps",
        "_foreseen",
        "_next_query",
        "_check",
        "_ground_ahead",
        "_take_brief",
        "_step_cell",
    ):
        setattr(N.CellNode, name, _exclusive(acct, local, getattr(N.CellNode, name), name))
    for name in ("_saver", "world_to_wire", "encode_answer", "dumps", "loads"):
        setattr(N, name, _exclusive(acct, local, getattr(N, name), name))
    with open_session(BusConfig(listen=(endpoint,))) as session:
        nodes = [
            N.CellNode(
                session, tr.scene, cell=f"acct{i}", factory=B.suite_factory("discrete", tr.scene)
            )
            for i, tr in enumerate(B._trials(episodes))
        ]
        c0 = time.process_time()
        ready.set()
        stop.wait()
        cpu = time.process_time() - c0
        for n in nodes:
            n.close()
    Path(out).write_bytes(pickle.dumps((ev, acct, cpu)))


def main(episodes: int, repeats: int) -> None:
    from hltl.bus import bench as B
    from hltl.bus import driver as D
    from hltl.bus.session import BusConfig, free_endpoint, open_session
    from hltl.sim.episode import run_episode

    ctx = multiprocessing.get_context("spawn")
    ready, stop = ctx.Event(), ctx.Event()
    endpoint = free_endpoint()
    out = str(Path(tempfile.mkdtemp()) / "node.pkl")
    child = ctx.Process(target=_serve, args=(endpoint, episodes, ready, stop, out))
    child.start()
    ready.wait(120)
    ev: list[Event] = []

    class Timed:
        def __init__(self, session: Any) -> None:
            self._s = session

        def __getattr__(self, k: str) -> Any:
            return getattr(self._s, k)

        def get(self, key: Any, **kw: Any) -> Any:
            p = bytes(kw.get("payload") or b"")
            kind = (
                ("foresee: the first step" if b'"t"' in p else "foresee: a new spec's basis")
                if b'"foresee"' in p
                else "end"
                if b'"end"' in p
                else "reset"
                if "reset" in str(key)
                else ("after commands" if b'"commands"' in p else "peek")
                if b'"peek"' in p
                else "step"
            )
            ev.append(("send", time.perf_counter(), kind))
            r = self._s.get(key, **kw)
            ev.append(("sent", time.perf_counter(), kind))
            return r

    decode = D.decode_answer

    def timed_decode(b: bytes, what: str, episode: str = "") -> Any:
        ev.append(("arrive", time.perf_counter(), what))
        return decode(b, what, episode)

    D.decode_answer = timed_decode  # type: ignore[assignment]
    pull = D.BusCell._pull

    def timed_pull(self: Any) -> None:
        kind = (
            "the first step, foreseen"
            if not self._step and not self._streamed
            else "a step foreseen"
            if self._foresee_next and self._dirty
            else "a hinted step"
            if self._dirty
            else "ticks"
        )
        t0 = time.perf_counter()
        pull(self)
        ev.append(("pull", t0, time.perf_counter(), kind))

    D.BusCell._pull = timed_pull  # type: ignore[method-assign]
    init = D.BusCell.__init__

    def timed_init(self: Any, *a: Any, **k: Any) -> None:
        t0 = time.perf_counter()
        init(self, *a, **k)
        ev.append(("ctor", t0, time.perf_counter()))

    D.BusCell.__init__ = timed_init  # type: ignore[method-assign]
    trials = B._trials(episodes)
    rows = []
    awaited = [0, 0]  # guessed steps waited for: foreseen by the node, hinted
    with open_session(BusConfig(connect=(endpoint,))) as session:
        timed = Timed(session)
        for _ in range(repeats):
            for i, tr in enumerate(trials):
                kw: dict[str, Any] = dict(
                    instruction=tr.instruction, events=tr.events, seed=tr.seed
                )
                t0, c0 = time.perf_counter(), time.thread_time()
                a = run_episode(tr.scene, **kw)
                wi, ci = time.perf_counter() - t0, time.thread_time() - c0
                opened: list[Any] = []
                make = D.bus_cell(timed, cell=f"acct{i}", opened=opened)
                t0, c0, p0 = time.perf_counter(), time.thread_time(), time.process_time()
                b = run_episode(tr.scene, simulator=make, **kw)
                wb, cb = time.perf_counter() - t0, time.thread_time() - c0
                pb = time.process_time() - p0
                st = opened[0].stats
                opened[0].end()
                opened[0].close()
                same = B._strip(list(a.records)) == B._strip(list(b.records))
                rows.append((wi, ci, wb, cb, pb, st.waited, same))
                awaited[0] += st.awaited_foreseen
                awaited[1] += st.awaited_hinted
    stop.set()
    child.join(60)
    nev, acct, node_cpu = pickle.loads(Path(out).read_bytes())
    _report(rows, ev, nev, acct, node_cpu)
    n = len(rows)
    print(
        f"\nguessed steps the loop waited for, an episode: foreseen by the node "
        f"{awaited[0] / n:.2f}, matching the hint {awaited[1] / n:.2f}"
    )


def _report(
    rows: list[Any], ev: list[Event], nev: list[Event], acct: dict[str, float], node_cpu: float
) -> None:
    n = len(rows)

    def per_ep(x: float) -> str:
        return f"{x / n * 1e3:.2f}"

    wi, ci, wb, cb, pb, waited = (sum(r[k] for r in rows) for k in range(6))
    print(f"episodes {n}, logs equal {sum(r[6] for r in rows)}/{n}")
    print("| per episode (ms) | in-process | over the bus |")
    print("|---|---|---|")
    print(f"| wall | {per_ep(wi)} | {per_ep(wb)} ({(wb / wi - 1) * 100:+.1f} %) |")
    print(f"| the loop's thread CPU | {per_ep(ci)} | {per_ep(cb)} |")
    print(f"| the executor process's other threads (Zenoh) | — | {per_ep(pb - cb)} |")
    print(f"| the loop waited for the node (its own count) | — | {per_ep(waited)} |")
    print(f"| the node process's CPU | — | {per_ep(node_cpu)} |")
    sends = [e for e in ev if e[0] == "send"]
    sent = [e for e in ev if e[0] == "sent"]
    recvs = [e for e in nev if e[0] == "recv"]
    replies = [e for e in nev if e[0] == "reply"]
    arrive = [e for e in ev if e[0] == "arrive"]
    rt, at = [e[1] for e in replies], [e[1] for e in arrive]
    by: dict[str, list[tuple[float, ...]]] = collections.defaultdict(list)
    for s, s2, r in zip(sends, sent, recvs, strict=False):
        rep = replies[bisect.bisect_left(rt, r[1])]
        arr = arrive[bisect.bisect_left(at, s[1])]
        by[s[2]].append((s2[1] - s[1], r[1] - s[1], rep[1] - r[1], arr[1] - rep[1], arr[1] - s[1]))
    print()
    print(
        "| query | per episode | `get()` returns | the node has it | the node answers | "
        "the answer is read | total | total per episode |"
    )
    print("|---|---|---|---|---|---|---|---|")
    for kind, v in sorted(by.items(), key=lambda kv: -len(kv[1])):
        cols = list(zip(*v, strict=True))
        med = " | ".join(f"{statistics.median(c) * 1e3:.3f}" for c in cols)
        print(f"| {kind} | {len(v) / n:.2f} | {med} | {per_ep(sum(cols[4]))} |")
    ctor = [e[2] - e[1] for e in ev if e[0] == "ctor"]
    print(
        f"\nBusCell() (its subscriptions and the reset): {per_ep(sum(ctor))} ms an episode, "
        f"median {statistics.median(ctor) * 1e3:.3f} ms"
    )
    pulls = [e[2] - e[1] for e in ev if e[0] == "pull"]
    if pulls:
        print(
            f"\nfurther replies waited for: {len(pulls) / n:.1f} an episode, "
            f"{per_ep(sum(pulls))} ms, median {statistics.median(pulls) * 1e3:.3f} ms"
        )
        kinds = sorted({e[3] for e in ev if e[0] == "pull"})
        for k in kinds:
            ds = [e[2] - e[1] for e in ev if e[0] == "pull" and e[3] == k]
            print(
                f"  {k}: {len(ds) / n:.2f} an episode, {per_ep(sum(ds))} ms, "
                f"median {statistics.median(ds) * 1e3:.3f} ms"
            )
    print("\nthe node's step thread, CPU ms per episode (each part without the parts it calls):")
    for k, v in sorted(acct.items(), key=lambda kv: -kv[1]):
        print(f"  {k} {per_ep(v)}")
    print(f"  total {per_ep(sum(acct.values()))}")


if __name__ == "__main__":
    main(
        int(sys.argv[1]) if len(sys.argv) > 1 else 20, int(sys.argv[2]) if len(sys.argv) > 2 else 1
    )
