"""Episode metrics computed from an execution log alone (definitions: docs/metrics.md)."""

from __future__ import annotations

import re
import statistics
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import asdict, dataclass
from typing import Any

from hltl.errors import PlanFormatError
from hltl.execution.log import (
    REPLANS,
    ActionDone,
    ActionFailed,
    ActionHalted,
    ActionStart,
    EpisodeEnd,
    EpisodeStart,
    Grounding,
    Halt,
    HumanMove,
    LogRecord,
    Takeover,
    Violation,
    check_records,
)

Interval = tuple[float, float]
_DELIVERED = re.compile(r"delivered\(\s*([A-Za-z_][\w-]*)\s*,\s*([A-Za-z_][\w-]*)\s*\)")
_ENDS = (ActionDone, ActionFailed, ActionHalted)


@dataclass(frozen=True, slots=True)
class Metrics:
    """What one episode scored. Percentages are in [0, 100] except ``f_del`` (may be negative);
    fluency metrics are ``None`` when the task time is zero or nobody took part."""

    success: bool
    reason: str
    time_cost: float
    replans: int
    planner_calls: int
    takeovers: int
    halts: int
    failures: int
    replan_latency_median_ms: float | None
    replan_latency_p95_ms: float | None
    tokens: int
    violations: int
    deliveries: int
    h_idle: float | None
    r_idle: float | None
    c_act: float | None
    f_del: float | None
    # added fields (docs/metrics.md): the paper's F-DEL as a time union (``f_del`` is the sum
    # over hand-offs), Hoffman's human-robot concurrency, and H-IDLE with walking counted
    f_del_union: float | None = None
    c_act_hr: float | None = None
    h_idle_walk_active: float | None = None

    def to_dict(self) -> dict[str, Any]:
        return asdict(self)


def _union(intervals: Iterable[Interval]) -> list[Interval]:
    out: list[Interval] = []
    for a, b in sorted(intervals):
        if b <= a:
            continue
        if out and a <= out[-1][1]:
            out[-1] = (out[-1][0], max(out[-1][1], b))
        else:
            out.append((a, b))
    return out


def _length(intervals: Iterable[Interval]) -> float:
    return sum(b - a for a, b in _union(intervals))


def _clip(iv: Interval, horizon: float) -> Interval:
    return (min(max(iv[0], 0.0), horizon), min(max(iv[1], 0.0), horizon))


def concurrent_time(agents: Mapping[str, Sequence[Interval]], at_least: int = 2) -> float:
    """Total time during which at least ``at_least`` agents are active at once."""
    edges: list[tuple[float, int]] = []
    for ivs in agents.values():
        for a, b in _union(ivs):
            edges += [(a, 1), (b, -1)]
    edges.sort(key=lambda e: (e[0], e[1]))  # ends before starts at the same instant
    total, active, last = 0.0, 0, 0.0
    for t, d in edges:
        if active >= at_least:
            total += t - last
        active += d
        last = t
    return total


def percentile(values: Sequence[float], q: float) -> float:
    """Linear-interpolation percentile (``q`` in [0, 100]) of a non-empty sample."""
    xs = sorted(values)
    if len(xs) == 1:
        return xs[0]
    pos = (len(xs) - 1) * q / 100.0
    lo = int(pos)
    hi = min(lo + 1, len(xs) - 1)
    return xs[lo] + (xs[hi] - xs[lo]) * (pos - lo)


@dataclass(frozen=True, slots=True)
class Activity:
    """Activity intervals recovered from a log."""

    robots: dict[str, list[Interval]]
    humans: dict[str, list[Interval]]
    # completed actions, in start order: (start, end, robots, object)
    completed: list[tuple[float, float, tuple[str, ...], str]]
    # each person's walks: from ``human_move`` to its ``eta``, cut short by the next walk
    walks: dict[str, list[Interval]]


def activity(records: Sequence[LogRecord], end_time: float) -> Activity:
    """Who was active when: a robot while it executes an action (start to done, failure or
    halt); a person while a robot hands them an object (the ``handover_r2h`` action)."""
    first = records[0]
    scene = (first.scene if isinstance(first, EpisodeStart) else None) or {}
    robots: dict[str, list[Interval]] = {str(r["id"]): [] for r in scene.get("robots", [])}
    humans: dict[str, list[Interval]] = {}
    open_: dict[int, ActionStart] = {}
    completed: list[tuple[float, float, tuple[str, ...], str]] = []
    for rec in records:
        if isinstance(rec, ActionStart):
            open_[int(rec.handle)] = rec
        elif isinstance(rec, _ENDS):
            start = open_.pop(int(rec.handle), None)
            if start is None:
                continue
            end = rec.ended
            _add(robots, humans, start, end)
            if isinstance(rec, ActionDone):
                a = start.action
                completed.append(
                    (float(start.t), end, tuple(str(r) for r in a["robots"]), str(a["object"]))
                )
    for start in open_.values():  # still running when the log ends
        _add(robots, humans, start, end_time)
    completed.sort(key=lambda c: c[0])
    return Activity(robots, humans, completed, walks(records, end_time))


def walks(records: Sequence[LogRecord], end_time: float) -> dict[str, list[Interval]]:
    """When each person walks: a ``human_move`` at t with arrival ``eta`` walks over
    [t, eta]; a later ``human_move`` of the same person replaces the rest of the walk, and a
    walk still under way when the log ends counts until ``end_time``."""
    out: dict[str, list[Interval]] = {}
    for rec in records:
        if not isinstance(rec, HumanMove):
            continue
        who, t = str(rec.human), float(rec.t)
        ivs = out.setdefault(who, [])
        if ivs and ivs[-1][1] > t:  # the new walk replaces the rest of the previous one
            ivs[-1] = (ivs[-1][0], t)
        eta = rec.eta
        ivs.append((t, min(float(eta), end_time) if eta is not None else end_time))
    return out


def _add(
    robots: dict[str, list[Interval]],
    humans: dict[str, list[Interval]],
    start: ActionStart,
    end: float,
) -> None:
    a = start.action
    iv = (float(start.t), end)
    for r in a["robots"]:
        robots.setdefault(str(r), []).append(iv)
    if a.get("skill") == "handover_r2h" and a.get("human") is not None:
        humans.setdefault(str(a["human"]), []).append(iv)


def participants(records: Sequence[LogRecord]) -> set[str]:
    """People the task is for: recipients in any spec of the log, or of any handover."""
    people: set[str] = set()
    for rec in records:
        spec = rec.spec if isinstance(rec, EpisodeStart | Grounding) else None
        if isinstance(spec, Mapping):
            for text in (spec.get("formulas") or {}).values():
                people |= {m.group(2) for m in _DELIVERED.finditer(str(text))}
        if isinstance(rec, ActionStart) and rec.action.get("skill") == "handover_r2h":
            people.add(str(rec.action.get("human")))
    return people


def functional_delay(completed: Sequence[tuple[float, float, tuple[str, ...], str]]) -> float:
    """Summed hand-off delays: for each object, consecutive completed actions on it done by
    different sets of robots, the next start minus the previous end (negative if it began
    before the previous one ended)."""
    last: dict[str, tuple[float, float, tuple[str, ...], str]] = {}
    total = 0.0
    for act in completed:
        prev = last.get(act[3])
        if prev is not None and set(prev[2]) != set(act[2]):
            total += act[0] - prev[1]
        last[act[3]] = act
    return total


def functional_delay_union(
    completed: Sequence[tuple[float, float, tuple[str, ...], str]],
) -> float:
    """Signed functional delay as a time union: the time during which at least one object
    waits for its next agent (the union over all hand-offs, as in :func:`functional_delay`,
    of [previous end, next start]) minus the time during which at least one hand-off is
    anticipated (the union of [next start, previous end] where the next agent began first).
    Parallel objects waiting at once count once; it equals the sum when no two waits and no
    two anticipations overlap in time."""
    last: dict[str, tuple[float, float, tuple[str, ...], str]] = {}
    waits: list[Interval] = []
    early: list[Interval] = []
    for act in completed:
        prev = last.get(act[3])
        if prev is not None and set(prev[2]) != set(act[2]):
            if act[0] >= prev[1]:
                waits.append((prev[1], act[0]))
            else:
                early.append((act[0], prev[1]))
        last[act[3]] = act
    return _length(waits) - _length(early)


def overlap_time(a: Sequence[Interval], b: Sequence[Interval]) -> float:
    """Length of (union of ``a``) ∩ (union of ``b``)."""
    return concurrent_time({"a": a, "b": b}, at_least=2)


def _idle(people: Mapping[str, Sequence[Interval]], horizon: float) -> float | None:
    if not people:
        return None
    return 100.0 * statistics.fmean(1.0 - _length(ivs) / horizon for ivs in people.values())


def compute_metrics(records: Sequence[LogRecord]) -> Metrics:
    """All metrics of one episode from its log records.

    Raises:
        PlanFormatError: the log is malformed or has no ``episode_end`` (truncated).
    """
    check_records(records)
    ends = [r for r in records if isinstance(r, EpisodeEnd)]
    if not ends:
        raise PlanFormatError("the log has no episode_end record (truncated or still running)")
    end = ends[-1]
    violations = sum(1 for r in records if isinstance(r, Violation))
    success = bool(end.success) and violations == 0
    time_cost = float(end.t if end.time_cost is None else end.time_cost)
    replans = [r for r in records if isinstance(r, REPLANS)]
    latencies = [float(r.latency_ms) for r in replans if r.trigger != "initial"]
    disruptive = [r for r in replans if set(str(r.trigger).split("+")) - {"initial", "progress"}]
    horizon = time_cost
    act = activity(records, float(end.t))
    h_idle = r_idle = c_act = f_del = None
    f_del_union = c_act_hr = h_idle_walk = None
    if horizon > 0:
        robot_iv = {r: [_clip(i, horizon) for i in ivs] for r, ivs in act.robots.items()}
        people = participants(records)
        human_iv = {h: [_clip(i, horizon) for i in act.humans.get(h, [])] for h in sorted(people)}
        if robot_iv:
            r_idle = 100.0 * statistics.fmean(
                1.0 - _length(ivs) / horizon for ivs in robot_iv.values()
            )
        h_idle = _idle(human_iv, horizon)
        h_idle_walk = _idle(
            {
                h: [*ivs, *(_clip(i, horizon) for i in act.walks.get(h, []))]
                for h, ivs in human_iv.items()
            },
            horizon,
        )
        c_act = (
            100.0
            * concurrent_time({**robot_iv, **{f"human:{h}": v for h, v in human_iv.items()}})
            / horizon
        )
        c_act_hr = (
            100.0
            * overlap_time(
                [i for ivs in robot_iv.values() for i in ivs],
                [i for ivs in human_iv.values() for i in ivs],
            )
            / horizon
        )
        f_del = 100.0 * functional_delay(act.completed) / horizon
        f_del_union = 100.0 * functional_delay_union(act.completed) / horizon
    reason = str(end.reason)
    if violations and end.success:
        # the goals were met, but unsafely: say so instead of "failed: all goals met"
        first = next(r for r in records if isinstance(r, Violation))
        reason = f"{violations} safety violation(s) ({first.reason}) although {reason}"
    return Metrics(
        success=success,
        reason=reason,
        time_cost=time_cost,
        replans=len(disruptive),
        planner_calls=sum(1 for r in replans if r.source == "planner"),
        takeovers=sum(1 for r in records if isinstance(r, Takeover)),
        halts=sum(1 for r in records if isinstance(r, Halt)),
        failures=sum(1 for r in records if isinstance(r, ActionFailed)),
        replan_latency_median_ms=statistics.median(latencies) if latencies else None,
        replan_latency_p95_ms=percentile(latencies, 95.0) if latencies else None,
        tokens=sum(int(r.tokens) for r in records if isinstance(r, Grounding)),
        violations=violations,
        deliveries=sum(
            1
            for r in records
            if isinstance(r, ActionDone) and r.action.get("skill") == "handover_r2h"
        ),
        h_idle=h_idle,
        r_idle=r_idle,
        c_act=c_act,
        f_del=f_del,
        f_del_union=f_del_union,
        c_act_hr=c_act_hr,
        h_idle_walk_active=h_idle_walk,
    )
