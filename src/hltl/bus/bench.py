"""``hltl bench bus``: round trips over loopback, a suite over the bus vs in-process, faults."""

from __future__ import annotations

import statistics
import time
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, replace
from typing import Any

from hltl.bus.driver import BusCell, BusTiming, bus_cell
from hltl.bus.faults import FaultModel
from hltl.bus.node import CellNode
from hltl.bus.realtime import realtime_bus_cell
from hltl.bus.session import BusConfig, open_session
from hltl.execution.drivers import ActionState, ActionStatus, Handle
from hltl.execution.log import ActionDone, ActionStart, EpisodeEnd, EventLog, LogRecord
from hltl.sim.dynamic import make_trial
from hltl.sim.episode import run_episode
from hltl.sim.events import EventSchedule
from hltl.sim.scenarios import get
from hltl.sim.simulator import PerceptionModel
from hltl.skills.library import Action
from hltl.world.scene import Scene
from hltl.world.state import WorldState

# the twelve Table II configurations
CONFIGS: tuple[str, ...] = ("1-1", "2-1", "4-1", "1-2", "2-2", "4-2", "1-4-line", "2-4-line")
CONFIGS += ("4-4-line", "1-4-square", "2-4-square", "4-4-square")


class _InstantCell:
    """A cell whose actions end the moment they start: what remains is the bus itself."""

    def __init__(self, scene: Scene, events: EventSchedule, **_: Any) -> None:
        self.scene = scene
        self._n = 0

    def start(self, action: Action, t: float, **_: Any) -> Handle:
        self._n += 1
        return Handle(self._n, action, t)

    def poll(self, handle: Handle, t: float) -> ActionStatus:
        return ActionStatus(ActionState.DONE, 1.0, t)

    def halt(self, handle: Handle, t: float, reason: str) -> None:
        return None

    def unavailable(self, t: float) -> frozenset[str]:
        return frozenset()

    def advance(self, t: float) -> None:
        return None

    def observe(self, t: float | None = None) -> WorldState:
        return WorldState(t=0.0 if t is None else t, humans=(), objects=())

    def next_event_time(self) -> float:
        return float("inf")

    def pending_instructions(self) -> bool:
        return False

    def take_instructions(self) -> list[str]:
        return []


@dataclass(frozen=True, slots=True)
class BusBench:
    round_trip_ms: tuple[float, float, float]  # median, p95, max of action → completion
    step_ms: float  # median sim/step round trip during the suite
    episodes: int
    inproc_s: float
    bus_s: float
    inproc_cpu_s: float  # process CPU time (the node shares the process: both sides counted)
    bus_cpu_s: float
    ticks: int  # simulated ticks the executor consumed over the bus
    queries: int  # reset/step/peek queries (round trips) for those ticks
    undone: int  # ticks simulated ahead and undone because a command came first
    same_logs: int
    fault_episodes: int
    fault_same_logs: int
    dispatched: int
    lost: int
    duplicated: int
    realtime: RealtimeBench


@dataclass(frozen=True, slots=True)
class RealtimeBench:
    """The same trials run in real time (the node's clock ``factor`` times faster)."""

    factor: float
    episodes: int
    goals_met: int  # every goal met (safety violations aside)
    same_done: int  # the same formulas done as in-process
    violations: int  # episodes with a safety violation (a late reaction)
    dispatched: int
    lost: int
    duplicated: int
    lag_ms: tuple[float, float, float]  # action end (node) → the executor logs it: wall ms
    late_ticks: int  # executor ticks reached after their time (it was busy)
    ticks: int
    missed: int  # node ticks that never arrived (none without faults)
    wall_s: float
    cell_s: float  # cell seconds the episodes lasted
    stepped_s: float  # cell seconds they lasted in-process (the executor stepping time)


def _dispatch_counts(
    records: Sequence[LogRecord], starts: Mapping[int, int]
) -> tuple[int, int, int]:
    """(dispatches the executor logged, those the node never started, handles started twice)."""
    handles = [r.handle for r in records if isinstance(r, ActionStart)]
    lost = sum(1 for h in handles if starts.get(h, 0) == 0)
    return len(handles), lost, sum(1 for n in starts.values() if n > 1)


def _strip(x: Any) -> Any:
    if isinstance(x, LogRecord):
        return _strip(x.to_json())
    if isinstance(x, dict):
        return {k: _strip(v) for k, v in x.items() if not str(k).endswith("_ms")}
    if isinstance(x, list | tuple):
        return [_strip(v) for v in x]
    return x


def bench_bus(
    endpoint: str,
    *,
    round_trips: int = 1000,
    episodes: int = 20,
    on_progress: Callable[[str], None] | None = None,
) -> BusBench:
    """Measure the bus on ``endpoint`` (loopback): see docs/benchmarks.md, section "bus"."""
    say = on_progress or (lambda _: None)
    with (
        open_session(BusConfig(listen=(endpoint,))) as ns,
        open_session(BusConfig(connect=(endpoint,))) as cs,
    ):
        scene = get("fig1").scene
        # 1. action → completion round trip (command out, DONE report back)
        with CellNode(ns, scene, factory=_InstantCell, publish_poses=False):
            cell = BusCell(cs, scene, EventSchedule(), 0, PerceptionModel(), EventLog())
            action = Action("pick", ("r1",), "bottle")
            times = []
            for _ in range(round_trips):
                t0 = time.perf_counter()
                h = cell.start(action, 0.0)
                if cell.poll(h, 0.0).state is not ActionState.DONE:
                    raise RuntimeError("the instant cell did not complete")
                times.append((time.perf_counter() - t0) * 1000)
            cell.end()
            cell.close()
        times.sort()
        rt = (
            statistics.median(times),
            times[int(0.95 * (len(times) - 1))],
            times[-1],
        )
        say(f"round trip median {rt[0]:.3f} ms")
        # 2. the suite, in-process and over the bus, alternating
        trials = [make_trial(CONFIGS[i % len(CONFIGS)], i // len(CONFIGS)) for i in range(episodes)]
        inproc = bus = inproc_cpu = bus_cpu = 0.0
        same = ticks = queries = undone = 0
        steps: list[float] = []
        for tr in trials:
            kw: dict[str, Any] = {
                "instruction": tr.instruction,
                "events": tr.events,
                "seed": tr.seed,
            }
            t0, c0 = time.perf_counter(), time.process_time()
            a = run_episode(tr.scene, **kw)
            inproc += time.perf_counter() - t0
            inproc_cpu += time.process_time() - c0
            opened: list[BusCell] = []
            with CellNode(ns, tr.scene) as node:
                t0, c0 = time.perf_counter(), time.process_time()
                b = run_episode(tr.scene, simulator=bus_cell(cs, opened=opened), **kw)
                bus += time.perf_counter() - t0
                bus_cpu += time.process_time() - c0
                opened[0].end()
                opened[0].close()
            steps += opened[0].stats.round_trips
            ticks += opened[0].stats.ticks
            queries += opened[0].stats.queries - 1  # not counting the end-of-episode query
            undone += node.stats.undone
            same += _strip(list(a.records)) == _strip(list(b.records))
            say(f"{tr.config}#{tr.index}: same log {same}")
        # 3. faults: every fault at once on both sides; count lost and duplicated dispatches
        faults = FaultModel(
            loss=0.1, duplicate=0.2, reorder=0.2, delay=0.001, reply_loss=0.1, slow=0.001, seed=1
        )
        fsame = dispatched = lost = dup = 0
        for i, tr in enumerate(trials):
            kw = {"instruction": tr.instruction, "events": tr.events, "seed": tr.seed}
            a = run_episode(tr.scene, **kw)
            opened = []
            with CellNode(ns, tr.scene, faults=replace(faults, seed=i)) as node:
                b = run_episode(
                    tr.scene,
                    simulator=bus_cell(
                        cs,
                        opened=opened,
                        faults=replace(faults, seed=1000 + i),
                        timing=BusTiming(timeout=0.1, retries=6),
                    ),
                    **kw,
                )
                opened[0].end()
                opened[0].close()
                counts = _dispatch_counts(b.records, node.stats.starts)
                dispatched, lost, dup = dispatched + counts[0], lost + counts[1], dup + counts[2]
            fsame += _strip(list(a.records)) == _strip(list(b.records))
            say(f"faults {tr.config}#{tr.index}: same log {fsame}")
        rt_bench = _realtime(ns, cs, trials, say)
    return BusBench(
        rt,
        statistics.median(steps) * 1000 if steps else 0.0,
        episodes,
        inproc,
        bus,
        inproc_cpu,
        bus_cpu,
        ticks,
        queries,
        undone,
        same,
        episodes,
        fsame,
        dispatched,
        lost,
        dup,
        rt_bench,
    )


def _realtime(
    ns: Any, cs: Any, trials: list[Any], say: Callable[[str], None], factor: float = 10.0
) -> RealtimeBench:
    """Run ``trials`` in real time, ``factor`` times faster: what the guarantees and the
    executor's reaction time are when the cell does not wait for it."""
    goals = same = violations = dispatched = lost = dup = late = ticks = missed = 0
    lags: list[float] = []
    wall = cell_s = stepped_s = 0.0
    for tr in trials:
        kw: dict[str, Any] = {"instruction": tr.instruction, "events": tr.events, "seed": tr.seed}
        a = run_episode(tr.scene, **kw)
        opened: list[BusCell] = []
        with CellNode(ns, tr.scene) as node:
            t0 = time.perf_counter()
            b = run_episode(
                tr.scene, simulator=realtime_bus_cell(cs, factor=factor, opened=opened), **kw
            )
            wall += time.perf_counter() - t0
            opened[0].end()
            opened[0].close()
        counts = _dispatch_counts(b.records, node.stats.starts)
        dispatched, lost, dup = dispatched + counts[0], lost + counts[1], dup + counts[2]
        end_a, end_b = a.records[-1], b.records[-1]
        assert isinstance(end_a, EpisodeEnd) and isinstance(end_b, EpisodeEnd)
        goals += end_b.reason == "all goals met"
        same += end_a.done == end_b.done
        violations += b.metrics.violations > 0
        lags += [(r.t - r.ended) / factor * 1000 for r in b.records if isinstance(r, ActionDone)]
        stats = opened[0].stats
        late, ticks, missed = late + stats.late_ticks, ticks + stats.ticks, missed + stats.missed
        cell_s += end_b.t
        stepped_s += end_a.t
        say(f"real time {tr.config}#{tr.index}: {end_b.reason}")
    lags.sort()
    lag = (
        (statistics.median(lags), lags[int(0.95 * (len(lags) - 1))], lags[-1])
        if lags
        else (0.0, 0.0, 0.0)
    )
    return RealtimeBench(
        factor, len(trials), goals, same, violations, dispatched, lost, dup, lag, late, ticks,
        missed, wall, cell_s, stepped_s,
    )  # fmt: skip


def format_bus(b: BusBench, command: str, date: str, machine: str) -> str:
    over = (b.bus_s / b.inproc_s - 1) * 100 if b.inproc_s else 0.0
    cpu_over = (b.bus_cpu_s / b.inproc_cpu_s - 1) * 100 if b.inproc_cpu_s else 0.0
    return "\n".join(
        [
            "## Bus (Zenoh, loopback)",
            "",
            f"Command: `{command}`  ",
            f"Date: {date}. Machine: {machine} (shared with other jobs: wall times are noisy).",
            "",
            "| measure | value | target |",
            "|---|---|---|",
            f"| action → completion round trip, median / p95 / max | "
            f"{b.round_trip_ms[0]:.3f} / {b.round_trip_ms[1]:.3f} / {b.round_trip_ms[2]:.3f} ms"
            " | ≤ 5 ms median |",
            f"| `sim/step` (and start/halt) round trip during the suite, median | "
            f"{b.step_ms:.3f} ms | — |",
            f"| {b.episodes}-episode suite, in-process wall time | {b.inproc_s:.2f} s | — |",
            f"| same suite over the bus (node in this process, its own session) | "
            f"{b.bus_s:.2f} s ({over:+.1f} %) | within 10 % |",
            f"| CPU time of the process, in-process / over the bus (both sides) | "
            f"{b.inproc_cpu_s:.2f} s / {b.bus_cpu_s:.2f} s ({cpu_over:+.1f} %) | — |",
            f"| simulated ticks / queries over the bus / ticks undone | "
            f"{b.ticks} / {b.queries} / {b.undone} | — |",
            f"| episodes whose log equals the in-process one | {b.same_logs}/{b.episodes} | all |",
            f"| under faults (10 % loss, 20 % duplicates, 20 % reordered, 1 ms delay, 10 % lost "
            f"replies, slow subscriber): logs equal | {b.fault_same_logs}/{b.fault_episodes} | — |",
            f"| under those faults: dispatches / lost / started twice | "
            f"{b.dispatched} / {b.lost} / {b.duplicated} | 0 lost, 0 twice |",
            "",
            "The round trip is a start to a node whose actions end at once, until the DONE "
            "report is back (in lockstep the start rides the query that follows it: one Zenoh "
            "query and its answer, JSON payloads). The suite cycles "
            "through the twelve Table II configurations with their dynamic events "
            "(`hltl.sim.dynamic.make_trial`).",
            "",
            f"The wall-time target is {'met' if over <= 10 else '**not met**'} on this run: the "
            f"bus adds {(b.bus_s - b.inproc_s) / b.episodes * 1000:.0f} ms wall and "
            f"{(b.bus_cpu_s - b.inproc_cpu_s) / b.episodes * 1000:.0f} ms CPU per episode. The "
            "node simulates the ticks the executor will ask for next (until an action ends, an "
            "instruction arrives or a robot's availability changes, doubling the stretch while "
            "the executor uses all of it) and sends them, with the actions' reports, in one "
            "answer; the executor consumes them without a round trip, and a command in the "
            "middle makes the node undo the rest (the simulator's state saved before the "
            "stretch) and replay the ticks used, so the log is unchanged. A step's starts and "
            "halts ride the query that follows them (no exchange per action). Hence "
            f"{b.queries / b.episodes:.0f} queries per episode for "
            f"{b.ticks / b.episodes:.0f} ticks (lockstep: one per tick, +108 % wall). What "
            "remains is the node's work on the bus (JSON of every tick, saving and restoring "
            "the simulator, the replies) and Zenoh's own threads; the node here shares the "
            "Python interpreter with the executor, so its CPU time adds to the wall time.",
            "",
            *_format_realtime(b.realtime),
        ]
    )


def _format_realtime(r: RealtimeBench) -> list[str]:
    f = f"{r.factor:g}"
    return [
        f"### Real time (`hltl run --bus zenoh --realtime {f}`)",
        "",
        f"The same {r.episodes} trials with the node running the cell on its own clock, {f} "
        "times faster than real time, and the executor following the wall clock "
        '(docs/bus.md, "Real time"). Planning and the bus now take cell time: at '
        f"{f}× every wall millisecond is {r.factor:g} cell milliseconds, so this is harsher "
        "than real arms at 1×.",
        "",
        "| measure | value |",
        "|---|---|",
        f"| episodes with every goal met / the in-process run's formulas done | "
        f"{r.goals_met}/{r.episodes} / {r.same_done}/{r.episodes} |",
        f"| episodes with a safety violation (a reaction too late) | {r.violations} |",
        f"| dispatches / lost / started twice | {r.dispatched} / {r.lost} / {r.duplicated} |",
        f"| action end on the node → the executor logs it (wall), median / p95 / max | "
        f"{r.lag_ms[0]:.1f} / {r.lag_ms[1]:.1f} / {r.lag_ms[2]:.1f} ms |",
        f"| executor ticks / reached late (busy past their time) / node ticks never received | "
        f"{r.ticks} / {r.late_ticks} / {r.missed} |",
        f"| wall time / cell time of the episodes (in-process, stepped: {r.stepped_s:.1f} s) | "
        f"{r.wall_s:.2f} s / {r.cell_s:.1f} s |",
    ]
