"""Where an episode's time goes over the bus: both processes timed, query by query.

Runs the discrete suite trial by trial in-process and over the bus in several variants (the
node in a process of its own, as ``hltl bench bus`` does, with nodes of its own for each
variant; all in turn, each first in turn): with the node's foresight, the same with each
part of a stretch whole (the node's ``split`` 0), and with the executor's hints only. Timers
are wrapped around the bus's functions on both sides and the executor's foresight seams (the
loop's thread CPU by part, for each variant); ``time.perf_counter`` is one clock for both
processes (CLOCK_MONOTONIC), so a query is followed from the executor's ``session.get`` to
the node's step thread taking it, the node's answer, and the executor reading it. Prints the
tables docs/bus.md ("Where the time goes") shows, and each variant paired trial by trial with
the foresight one.

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


# the variants run trial by trial, in turn: in-process, and over the bus with the node's
# foresight (the executor's basis and briefing sent), the same with the node's parts whole
# (split 0), and with hints only; over the bus, each variant's executor options and its
# nodes' settings (cells <variant index>-<trial>)
VARIANTS = ("in-process", "foresight", "foresight, parts whole", "hints only")
_EXECUTOR: dict[str, dict[str, Any]] = {
    "foresight": {},
    "foresight, parts whole": {},
    "hints only": {"foresee": False},
}
_NODE: dict[str, dict[str, Any]] = {"foresight, parts whole": {"split": 0}}
# the variant whose episode runs now (the executor's side); on the node's side each variant has
# nodes of its own, told apart by their step threads' names
_now = ["in-process"]


def _cell(variant: str, i: int) -> str:
    return f"v{VARIANTS.index(variant)}-{i}"


def _exclusive(
    acct: dict[tuple[str, str], float], local: threading.local, f: Any, name: str, variant: Any
) -> Any:
    """``f`` timed in thread CPU seconds, exclusive of the timed functions it calls, counted
    under (``variant()``, ``name``)."""

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
            key = (variant(), name)
            acct[key] = acct.get(key, 0.0) + d - inner
            if stack:
                stack[-1] += d

    return timed


_node_local = threading.local()  # the variant of the node whose reset a Zenoh thread handles


def _node_variant() -> str:
    name = threading.current_thread().name
    if name.startswith("steps:"):
        return name.split(":", 1)[1]
    return str(getattr(_node_local, "variant", "other threads"))


def _serve(endpoint: str, episodes: int, ready: Any, stop: Any, out: str) -> None:
    from hltl.bus import bench as B
    from hltl.bus import node as N
    from hltl.bus.session import BusConfig, open_session

    ev: list[Event] = []
    acct: dict[tuple[str, str], float] = {}
    local = threading.local()
    loads = N.loads

    def timed_loads(b: bytes, what: str) -> Any:
        if what in ("step request", "reset request"):
            ev.append(("recv", time.perf_counter(), what, _node_variant()))
        return loads(b, what)

    N.loads = timed_loads  # type: ignore[assignment]
    reply = N.CellNode._reply_bytes

    def timed_reply(self: Any, q: Any, payload: bytes, key: str | None = None) -> bool:
        ev.append(("reply", time.perf_counter(), len(payload), _node_variant()))
        return reply(self, q, payload, key)

    N.CellNode._reply_bytes = timed_reply  # type: ignore[method-assign]
    on_reset = N.CellNode._on_reset

    def tagged_reset(self: Any, query: Any) -> None:
        _node_local.variant = VARIANTS[int(self.keys.cell[1:].split("-")[0])]
        try:
            on_reset(self, query)
        finally:
            _node_local.variant = "other threads"

    N.CellNode._on_reset = tagged_reset  # type: ignore[method-assign]
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
        setattr(
            N.CellNode,
            name,
            _exclusive(acct, local, getattr(N.CellNode, name), name, _node_variant),
        )
    for name in ("_saver", "world_to_wire", "encode_answer", "dumps", "loads"):
        setattr(N, name, _exclusive(acct, local, getattr(N, name), name, _node_variant))
    with open_session(BusConfig(listen=(endpoint,))) as session:
        nodes = []
        for variant in VARIANTS[1:]:
            for i, tr in enumerate(B._trials(episodes)):
                n = N.CellNode(
                    session,
                    tr.scene,
                    cell=_cell(variant, i),
                    factory=B.suite_factory("discrete", tr.scene),
                )
                for k, v in _NODE.get(variant, {}).items():
                    setattr(n, k, v)
                n._server.name = f"steps:{variant}"
                nodes.append((variant, n))
        clocks = [(v, time.pthread_getcpuclockid(n._server.ident or 0)) for v, n in nodes]
        c0 = time.process_time()
        s0 = [time.clock_gettime(c) for _, c in clocks]
        ready.set()
        stop.wait()
        cpu = time.process_time() - c0
        steps: dict[str, float] = collections.defaultdict(float)
        for (v, c), s in zip(clocks, s0, strict=True):
            steps[v] += time.clock_gettime(c) - s
        for _, n in nodes:
            n.close()
    Path(out).write_bytes(pickle.dumps((ev, acct, cpu, dict(steps))))


# the executor's side: the bus driver's parts, and the executor's own foresight seams, each
# timed on the loop's thread (exclusive of the others)
_DRIVER_METHODS = (
    "advance",
    "observe",
    "next_event_time",
    "pending_instructions",
    "take_instructions",
    "unavailable",
    "start",
    "poll",
    "halt",
    "expect",
    "foresee",
    "brief",
    "_ready",
    "_follow",
    "_request",
    "_ask",
    "_query",
    "_pull",
    "_take",
    "_absorb",
    "_absorb_tick",
    "_guessed_right",
    "_flush",
    "_sync",
    "_basis_out",
    "_foresee_spec",
    "_foresee_first",
)
_DRIVER_FUNCTIONS = ("wire_basis", "wire_briefing", "dumps", "decode_answer")
_TICK_METHODS = ("take", "peek_starts")
_EXECUTOR_METHODS = ("_tell_basis", "_after_running", "_check_forecaster", "brief", "_hint")


def main(episodes: int, repeats: int) -> None:
    from hltl.bus import bench as B
    from hltl.bus import driver as D
    from hltl.bus import ticks as T
    from hltl.bus.session import BusConfig, free_endpoint, open_session
    from hltl.execution import executor as X
    from hltl.sim.episode import run_episode

    ctx = multiprocessing.get_context("spawn")
    ready, stop = ctx.Event(), ctx.Event()
    endpoint = free_endpoint()
    out = str(Path(tempfile.mkdtemp()) / "node.pkl")
    child = ctx.Process(target=_serve, args=(endpoint, episodes, ready, stop, out))
    child.start()
    ready.wait(120)
    ev: list[Event] = []
    acct: dict[tuple[str, str], float] = {}
    local = threading.local()

    def variant() -> str:
        return _now[0]

    class Timed:
        def __init__(self, session: Any) -> None:
            self._s = session

        def __getattr__(self, k: str) -> Any:
            return getattr(self._s, k)

        def get(self, key: Any, **kw: Any) -> Any:
            p = bytes(kw.get("payload") or b"")
            kind = (
                "reset"  # (on sim/reset, or first in a request on sim/step: session 20)
                if "reset" in str(key) or p.startswith(b'{"reset":true')
                else ("foresee: the first step" if b'"t"' in p else "foresee: a new spec's basis")
                if b'"foresee"' in p
                else "end"
                if b'"end"' in p
                else ("after commands" if b'"commands"' in p else "peek")
                if b'"peek"' in p
                else "step"
            )
            ev.append(("send", time.perf_counter(), kind, _now[0]))
            r = self._s.get(key, **kw)
            ev.append(("sent", time.perf_counter(), kind, _now[0]))
            return r

    decode = D.decode_answer

    def timed_decode(b: bytes, what: str, episode: str = "") -> Any:
        ev.append(("arrive", time.perf_counter(), what, _now[0]))
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
        ev.append(("pull", t0, time.perf_counter(), kind, _now[0]))

    D.BusCell._pull = timed_pull  # type: ignore[method-assign]
    init = D.BusCell.__init__

    def timed_init(self: Any, *a: Any, **k: Any) -> None:
        t0 = time.perf_counter()
        c0 = time.thread_time()
        init(self, *a, **k)
        key = (_now[0], "BusCell()")
        acct[key] = acct.get(key, 0.0) + time.thread_time() - c0
        ev.append(("ctor", t0, time.perf_counter(), _now[0]))

    D.BusCell.__init__ = timed_init  # type: ignore[method-assign]
    for name in _DRIVER_METHODS:
        setattr(D.BusCell, name, _exclusive(acct, local, getattr(D.BusCell, name), name, variant))
    for name in _DRIVER_FUNCTIONS:
        setattr(D, name, _exclusive(acct, local, getattr(D, name), name, variant))
    for name in _TICK_METHODS:
        setattr(
            T.TickReader,
            name,
            _exclusive(acct, local, getattr(T.TickReader, name), f"ticks.{name}", variant),
        )
    for name in _EXECUTOR_METHODS:
        setattr(
            X.Executor,
            name,
            _exclusive(acct, local, getattr(X.Executor, name), f"Executor.{name}", variant),
        )
    ask = D.BusCell._ask

    def waited_ask(self: Any, key: str, data: dict[str, Any], *a: Any, **k: Any) -> Any:
        kind = (
            "end"
            if data.get("end")
            else "reset"
            if "reset" in key or data.get("reset") is True
            else "a step's commands"
            if data.get("commands")
            else "a step"
            if "step" in data
            else "other"
        )
        w0 = self.stats.waited
        try:
            return ask(self, key, data, *a, **k)
        finally:
            waits[(_now[0], kind)] = waits.get((_now[0], kind), 0.0) + self.stats.waited - w0

    waits: dict[tuple[str, str], float] = {}
    D.BusCell._ask = waited_ask  # type: ignore[method-assign]
    trials = B._trials(episodes)
    rows: dict[str, list[tuple[Any, ...]]] = {v: [] for v in VARIANTS}
    awaited = {v: [0, 0] for v in VARIANTS[1:]}  # guessed steps waited for: foreseen, hinted
    with open_session(BusConfig(connect=(endpoint,))) as session:
        timed = Timed(session)
        for r in range(repeats):
            for i, tr in enumerate(trials):
                kw: dict[str, Any] = dict(
                    instruction=tr.instruction, events=tr.events, seed=tr.seed
                )
                _now[0] = "in-process"
                a = run_episode(tr.scene, **kw)  # (the log the bus runs must equal)
                k = (r * len(trials) + i) % len(VARIANTS)  # each variant first in turn
                for v in VARIANTS[k:] + VARIANTS[:k]:
                    _now[0] = v
                    opened: list[Any] = []
                    sim = (
                        {}
                        if v == "in-process"
                        else {
                            "simulator": D.bus_cell(
                                timed, cell=_cell(v, i), opened=opened, **_EXECUTOR[v]
                            )
                        }
                    )
                    t0, c0, p0 = time.perf_counter(), time.thread_time(), time.process_time()
                    b = run_episode(tr.scene, **sim, **kw)
                    wb, cb = time.perf_counter() - t0, time.thread_time() - c0
                    pb = time.process_time() - p0
                    waited = queries = 0.0
                    if opened:
                        st = opened[0].stats
                        waited, queries = st.waited, st.queries
                        awaited[v][0] += st.awaited_foreseen
                        awaited[v][1] += st.awaited_hinted
                        opened[0].end()
                        opened[0].close()
                    same = B._strip(list(a.records)) == B._strip(list(b.records))
                    rows[v].append((wb, cb, pb, waited, queries, same))
    _now[0] = "in-process"
    stop.set()
    child.join(60)
    nev, nacct, node_cpu, node_steps = pickle.loads(Path(out).read_bytes())
    _report(rows, ev, nev, acct, nacct, node_cpu, node_steps, awaited)
    n = len(rows[VARIANTS[0]])
    print("\nthe loop's waits by what it waited for, ms an episode (the episode's end not in it):")
    print("| waited for | " + " | ".join(VARIANTS[1:]) + " |")
    print("|---|" + "---|" * (len(VARIANTS) - 1))
    pulls: dict[tuple[str, str], float] = collections.defaultdict(float)
    for e in ev:
        if e[0] == "pull":
            pulls[(e[4], f"further replies: {e[3]}")] += e[2] - e[1]
    every = {**waits, **pulls}
    for kind in sorted({k for _, k in every}):
        if kind == "end":
            continue
        print(
            f"| {kind} | "
            + " | ".join(f"{every.get((v, kind), 0.0) / n * 1e3:.2f}" for v in VARIANTS[1:])
            + " |"
        )


def _report(
    rows: dict[str, list[Any]],
    ev: list[Event],
    nev: list[Event],
    acct: dict[tuple[str, str], float],
    nacct: dict[tuple[str, str], float],
    node_cpu: float,
    node_steps: dict[str, float],
    awaited: dict[str, list[int]],
) -> None:
    n = len(rows[VARIANTS[0]])

    def per_ep(x: float) -> str:
        return f"{x / n * 1e3:.2f}"

    def col(v: str, k: int) -> float:
        return float(sum(r[k] for r in rows[v]))

    print(
        f"episodes {n} per variant, logs equal: "
        + ", ".join(f"{v} {sum(r[5] for r in rows[v])}/{n}" for v in VARIANTS[1:])
    )
    print("| per episode (ms) | " + " | ".join(VARIANTS) + " |")
    print("|---|" + "---|" * len(VARIANTS))
    base = col("in-process", 0)

    def pct(v: str) -> str:
        return "" if v == "in-process" else f" ({(col(v, 0) / base - 1) * 100:+.1f} %)"

    print("| wall | " + " | ".join(f"{per_ep(col(v, 0))}{pct(v)}" for v in VARIANTS) + " |")
    print("| the loop's thread CPU | " + " | ".join(per_ep(col(v, 1)) for v in VARIANTS) + " |")
    print(
        "| the executor process's other threads (Zenoh) | "
        + " | ".join("—" if v == "in-process" else per_ep(col(v, 2) - col(v, 1)) for v in VARIANTS)
        + " |"
    )
    print(
        "| the loop waited for the node (its own count) | "
        + " | ".join("—" if v == "in-process" else per_ep(col(v, 3)) for v in VARIANTS)
        + " |"
    )
    print(
        "| queries | "
        + " | ".join("—" if v == "in-process" else f"{col(v, 4) / n:.2f}" for v in VARIANTS)
        + " |"
    )
    print(
        "| the node's step thread CPU | "
        + " | ".join("—" if v == "in-process" else per_ep(node_steps.get(v, 0.0)) for v in VARIANTS)
        + f" |\n(the node process's CPU, both variants and its Zenoh threads: {per_ep(node_cpu)})"
    )
    for other in VARIANTS[2:]:
        fw = [f[0] - h[0] for f, h in zip(rows["foresight"], rows[other], strict=True)]
        fc = [f[1] - h[1] for f, h in zip(rows["foresight"], rows[other], strict=True)]
        print(
            f"\npaired by trial, foresight − {other}: wall median "
            f"{statistics.median(fw) * 1e3:+.2f} ms, mean {statistics.fmean(fw) * 1e3:+.2f} ms "
            f"(± {_sem(fw) * 1e3:.2f}), foresight faster in {sum(d < 0 for d in fw)} of {n}; "
            f"the loop's CPU median {statistics.median(fc) * 1e3:+.2f} ms, mean "
            f"{statistics.fmean(fc) * 1e3:+.2f} ms (± {_sem(fc) * 1e3:.2f})"
        )
    print(
        "\nguessed steps the loop waited for, an episode (foreseen by the node / matching the "
        "hint): " + ", ".join(f"{v} {a[0] / n:.2f} / {a[1] / n:.2f}" for v, a in awaited.items())
    )
    print(
        "\nthe loop's thread CPU by part, ms an episode (each without the parts it calls; "
        "'the rest' is the loop's own work: planning, the monitor, the check, the log):"
    )
    names = sorted({k for _, k in acct}, key=lambda k: -acct.get(("foresight", k), 0.0))
    print("| part | " + " | ".join(VARIANTS) + " | foresight − hints only |")
    print("|---|" + "---|" * (len(VARIANTS) + 1))
    hints = VARIANTS.index("hints only")
    for name in names:
        vals = [acct.get((v, name), 0.0) for v in VARIANTS]
        if max(vals) * 1e3 / n < 0.005:
            continue
        print(
            f"| {name} | "
            + " | ".join(per_ep(x) for x in vals)
            + f" | {(vals[1] - vals[hints]) / n * 1e3:+.2f} |"
        )
    rest = [col(v, 1) - sum(x for (w, _), x in acct.items() if w == v) for v in VARIANTS]
    print(
        "| the rest | "
        + " | ".join(per_ep(x) for x in rest)
        + f" | {(rest[1] - rest[hints]) / n * 1e3:+.2f} |"
    )
    for v in VARIANTS[1:]:
        _queries(v, n, [e for e in ev if e[-1] == v], [e for e in nev if e[-1] == v])
    print(
        "\nthe node's step thread, CPU ms per episode (each part without the parts it calls): "
        + " / ".join(VARIANTS[1:])
    )
    parts = sorted({k for _, k in nacct}, key=lambda k: -nacct.get(("foresight", k), 0.0))
    for k in parts:
        print(f"  {k} " + " / ".join(per_ep(nacct.get((v, k), 0.0)) for v in VARIANTS[1:]))
    print(
        "  total "
        + " / ".join(per_ep(sum(x for (w, _), x in nacct.items() if w == v)) for v in VARIANTS[1:])
    )


def _sem(xs: list[float]) -> float:
    """The standard error of the mean of ``xs``."""
    return statistics.stdev(xs) / len(xs) ** 0.5 if len(xs) > 1 else 0.0


def _queries(variant: str, n: int, ev: list[Event], nev: list[Event]) -> None:
    """The variant's queries, from the executor's ``get`` to its answer read, and the further
    replies the loop waited for."""

    def per_ep(x: float) -> str:
        return f"{x / n * 1e3:.2f}"

    sends = [e for e in ev if e[0] == "send"]
    sent = [e for e in ev if e[0] == "sent"]
    recvs = [e for e in nev if e[0] == "recv"]
    replies = [e for e in nev if e[0] == "reply"]
    arrive = [e for e in ev if e[0] == "arrive"]
    rt, at = [e[1] for e in replies], [e[1] for e in arrive]
    by: dict[str, list[tuple[float, ...]]] = collections.defaultdict(list)
    for s, s2, r in zip(sends, sent, recvs, strict=False):
        i, j = bisect.bisect_left(rt, r[1]), bisect.bisect_left(at, s[1])
        if i == len(rt) or j == len(at):
            continue
        rep, arr = replies[i], arrive[j]
        by[s[2]].append((s2[1] - s[1], r[1] - s[1], rep[1] - r[1], arr[1] - rep[1], arr[1] - s[1]))
    print(f"\n{variant}: queries, ms (median)")
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
    if ctor:
        print(
            f"BusCell() (its subscriptions and the reset): {per_ep(sum(ctor))} ms an episode, "
            f"median {statistics.median(ctor) * 1e3:.3f} ms"
        )
    pulls = [e for e in ev if e[0] == "pull"]
    if pulls:
        ds = [e[2] - e[1] for e in pulls]
        print(
            f"further replies waited for: {len(ds) / n:.1f} an episode, "
            f"{per_ep(sum(ds))} ms, median {statistics.median(ds) * 1e3:.3f} ms"
        )
        for k in sorted({e[3] for e in pulls}):
            ks = [e[2] - e[1] for e in pulls if e[3] == k]
            print(
                f"  {k}: {len(ks) / n:.2f} an episode, {per_ep(sum(ks))} ms, "
                f"median {statistics.median(ks) * 1e3:.3f} ms"
            )


if __name__ == "__main__":
    main(
        int(sys.argv[1]) if len(sys.argv) > 1 else 20, int(sys.argv[2]) if len(sys.argv) > 2 else 1
    )
